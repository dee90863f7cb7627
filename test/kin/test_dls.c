/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_dls.c - singularity measures (dh_manipulability_f32) and the damped
 * least-squares step (dh_dls_step_f32) against double precision.
 *
 * The Jacobians are dh_jacobian_f32's on the shipped robots at random
 * configurations, half of them pushed near a singularity (one joint within
 * a small angle of 0, which is the wrist singularity of the spherical
 * wrists and the elbow singularity of the UR family, or the elbow
 * stretched). The references use the float J's entries in double: the
 * eigenvalues of J J^T by cyclic Jacobi rotations, the DLS solution by
 * Gaussian elimination with partial pivoting. Every tolerance is derived
 * per input from float's unit roundoff u = 2^-24 and the conditioning of
 * the input (below), never a fixed number fitted to a run. The entry
 * points the tracker calls (kin_impl.h: the same bodies with their matrix
 * in the caller's workspace) must give the public functions' statuses
 * and bits on every input.
 */
#include "dht.h"
#include "support_robots.h"
#include "dhmath/kin.h"
#include "../../src/kin/kin_impl.h" /* the tracker's entry points: private, not on the include path */

#include <math.h>
#include <stdio.h>
#include <string.h>

#define U 5.9604644775390625e-8
#define R2D 57.295779513082320876798

static const dhs_robot *const robots[] = { &dhs_puma560_m, &dhs_puma560_mm, &dhs_ur5_m, &dhs_ur5_mm,
                                           &dhs_kuka_kr5_m, &dhs_stanford_m, &dhs_stanford_mm, &dhs_panda_m,
                                           &dhs_panda_mm };
#define N_ROBOTS (sizeof robots / sizeof robots[0])

/* J J^T (n >= 6) or J^T J in double from the float entries (each product
 * exact in double); returns m and its trace */
static int normal_ref(const float *J, unsigned n, double *A, double *tr)
{
    const int m = (n >= 6u) ? 6 : (int)n;
    int i, j;
    unsigned k;
    *tr = 0.0;
    for (i = 0; i < m; i++)
        for (j = 0; j < m; j++) {
            double s = 0.0;
            if (n >= 6u) for (k = 0; k < n; k++) s += (double)J[i * n + k] * (double)J[j * n + k];
            else for (k = 0; k < 6u; k++) s += (double)J[k * n + (unsigned)i] * (double)J[k * n + (unsigned)j];
            A[i * m + j] = s;
            if (i == j) *tr += s;
        }
    return m;
}

/* a random configuration of d, half the time with one joint (or the elbow
 * offset) pushed to within 10^-U(0..6) deg of 0 */
static void config(const dhs_robot *d, const dh_robot *r, float *qf)
{
    double q[DHS_MAX_JOINTS];
    unsigned i;
    dhs_random_q(d, q);
    if (dht_rand_u32() & 1u) {
        const unsigned j = dht_rand_u32() % r->n;
        if (r->joint[j].type == DH_JOINT_REVOLUTE) {
            double v = pow(10.0, -dht_rand_uniform(0.0, 6.0)) * ((dht_rand_u32() & 1u) ? 1 : -1);
            if (dht_rand_u32() % 8u == 0u) v = 0.0;
            if (!(r->joint[j].qmin <= r->joint[j].qmax) || (v >= r->joint[j].qmin && v <= r->joint[j].qmax)) q[j] = v;
        }
    }
    for (i = 0; i < r->n; i++) qf[i] = (float)q[i];
}

/* w against sqrt(prod lambda_i): with the float rounding of J J^T and of
 * its Cholesky factor bounded by eps = 16 u trace (||E||_2, see dh_dls.c),
 * every eigenvalue moves by at most eps, so w^2 lies between prod(lambda_i
 * - eps)+ and prod(lambda_i + eps) (times 1 +- 64 u for the product and the
 * square roots). sigma_min: at most sqrt(lambda_min), at least
 * sqrt(lambda_min / m (1 - 2^-7) - 33 u trace). */
static void manipulability_against_double(void)
{
    long it, n_it = DHT_ITER(20000);
    double worst_rel = 0.0, worst_ratio = 1.0;
    for (it = 0; it < n_it; it++) {
        const dhs_robot *d = robots[dht_rand_u32() % N_ROBOTS];
        dh_robot r;
        float qf[DH_MAX_JOINTS], J[6 * DH_MAX_JOINTS], w = -1.0f, sg = -1.0f;
        double A[36], ev[6] = { 0, 0, 0, 0, 0, 0 }, tr, eps, lo = 1.0, hi = 1.0, lmin;
        int m, i;
        DHT_EQ_INT(dhs_build(d, &r), DH_OK);
        config(d, &r, qf);
        DHT_EQ_INT(dh_jacobian_f32(&r, qf, J, NULL), DH_OK);
        DHT_EQ_INT(dh_manipulability_f32(J, r.n, &w, &sg), DH_OK);
        m = normal_ref(J, r.n, A, &tr);
        dhr_sym_eig(A, m, ev);
        eps = 16.0 * U * tr;
        lmin = ev[0];
        for (i = 0; i < m; i++) {
            lo *= (ev[i] - eps > 0.0) ? ev[i] - eps : 0.0;
            hi *= ev[i] + eps;
            if (ev[i] < lmin) lmin = ev[i];
        }
        if (lmin < 0.0) lmin = 0.0;
        DHT_TRUE_MSG((double)w * w >= lo * (1 - 64 * U) && (double)w * w <= hi * (1 + 64 * U),
                     "%s q %s: w %.9g outside [%.9g, %.9g]", d->name, dhs_qf_str(qf, r.n, 0), (double)w, sqrt(lo),
                     sqrt(hi));
        DHT_TRUE_MSG((double)sg <= sqrt(lmin) * (1 + 1e-12), "%s q %s: sigma_min %.9g above the true %.9g", d->name,
                     dhs_qf_str(qf, r.n, 0), (double)sg, sqrt(lmin));
        DHT_TRUE_MSG((double)sg * sg >= lmin / m * (1 - 1.0 / 128) - 33 * U * tr,
                     "%s q %s: sigma_min %.9g too far below %.9g", d->name, dhs_qf_str(qf, r.n, 0), (double)sg,
                     sqrt(lmin));
        if (lmin > 1e4 * eps) { /* away from singularities: the relative error */
            double p = 1.0, rel;
            for (i = 0; i < m; i++) p *= ev[i];
            rel = fabs(w - sqrt(p)) / sqrt(p);
            if (rel > worst_rel) worst_rel = rel;
        }
        if (lmin > 0.0 && sg > 0.0f && sg / sqrt(lmin) < worst_ratio) worst_ratio = sg / sqrt(lmin);
        dht_reach_min("manip sigma_true", sqrt(lmin) / sqrt(tr));
    }
    printf("manipulability: %ld Jacobians, w within %.3g relative of the reference where lambda_min > 1e4 eps; sigma_min >= %.3g of the true\n",
           n_it, worst_rel, worst_ratio);
}

/* (J J^T + l^2 I) y = e in double, Gaussian elimination with partial
 * pivoting; returns lambda_min of the matrix through dhr_sym_eig */
static double dls_ref(const float *J, unsigned n, const float *e, double l2, double *y)
{
    double A[36], B[36], b[6], lmin, ev[6];
    int i, j, k;
    for (i = 0; i < 6; i++) {
        for (j = 0; j < 6; j++) {
            double s = (i == j) ? l2 : 0.0;
            unsigned c;
            for (c = 0; c < n; c++) s += (double)J[i * n + c] * (double)J[j * n + c];
            A[i * 6 + j] = B[i * 6 + j] = s;
        }
        b[i] = e[i];
    }
    for (k = 0; k < 6; k++) {
        int p = k;
        for (i = k + 1; i < 6; i++)
            if (fabs(A[i * 6 + k]) > fabs(A[p * 6 + k])) p = i;
        for (j = 0; j < 6; j++) { double t = A[k * 6 + j]; A[k * 6 + j] = A[p * 6 + j]; A[p * 6 + j] = t; }
        { double t = b[k]; b[k] = b[p]; b[p] = t; }
        for (i = k + 1; i < 6; i++) {
            const double f = A[i * 6 + k] / A[k * 6 + k];
            for (j = k; j < 6; j++) A[i * 6 + j] -= f * A[k * 6 + j];
            b[i] -= f * b[k];
        }
    }
    for (i = 5; i >= 0; i--) {
        double s = b[i];
        for (j = i + 1; j < 6; j++) s -= A[i * 6 + j] * y[j];
        y[i] = s / A[i * 6 + i];
    }
    dhr_sym_eig(B, 6, ev);
    lmin = ev[0];
    for (i = 1; i < 6; i++) if (ev[i] < lmin) lmin = ev[i];
    return lmin;
}

/* dq against J^T y in double (degrees for revolute joints). Perturbation
 * bound: A = J J^T + l^2 I formed and factored in float is A + E, ||E|| <=
 * 16 u tr(A), so |dy| <= |y| 16 u tr / (lambda_min - 16 u tr) (first
 * order, doubled), plus u-level errors of the two substitutions and of J^T
 * y (8 u |J|_F |y|): |dq_k - ref_k| <= R2D |J|_F |y| u (32 tr / lambda_min
 * + 8). Scaled steps: within dq_max, a common factor of the unscaled step. */
static void dls_against_double(void)
{
    long it, n_it = DHT_ITER(20000);
    double worst = 0.0;
    for (it = 0; it < n_it; it++) {
        const dhs_robot *d = robots[dht_rand_u32() % N_ROBOTS];
        dh_robot r;
        float qf[DH_MAX_JOINTS], J[6 * DH_MAX_JOINTS], e[6], dq[DH_MAX_JOINTS], dqs[DH_MAX_JOINTS],
            dqm[DH_MAX_JOINTS];
        double y[6], tr = 0.0, jf = 0.0, yn = 0.0, lmin, l2, bound, scale = d->unit_per_m;
        float lambda;
        unsigned i, k, at_bound = 0u;
        DHT_EQ_INT(dhs_build(d, &r), DH_OK);
        config(d, &r, qf);
        DHT_EQ_INT(dh_jacobian_f32(&r, qf, J, NULL), DH_OK);
        for (i = 0; i < 3u; i++) e[i] = (float)(dht_rand_uniform(-1e-2, 1e-2) * scale);
        for (i = 3; i < 6u; i++) e[i] = (float)dht_rand_uniform(-2e-2, 2e-2);
        lambda = (float)(pow(10.0, -dht_rand_uniform(0.5, 3.0)) * scale);
        DHT_EQ_INT(dh_dls_step_f32(&r, J, e, lambda, NULL, dq), DH_OK);
        l2 = (double)lambda * lambda;
        lmin = dls_ref(J, r.n, e, l2, y);
        for (i = 0; i < 6u * r.n; i++) jf += (double)J[i] * J[i];
        for (i = 0; i < 6u; i++) {
            unsigned c;
            for (c = 0; c < r.n; c++) tr += (double)J[i * r.n + c] * J[i * r.n + c];
            tr += l2;
            yn += y[i] * y[i];
        }
        bound = R2D * sqrt(jf) * sqrt(yn) * U * (32.0 * tr / lmin + 8.0);
        for (k = 0; k < r.n; k++) {
            double ref = 0.0, err;
            for (i = 0; i < 6u; i++) ref += (double)J[i * r.n + k] * y[i];
            if (r.joint[k].type == DH_JOINT_REVOLUTE) ref *= R2D;
            err = fabs(dq[k] - ref);
            DHT_TRUE_MSG(err <= bound, "%s q %s lambda %.3g: dq[%u] %.9g vs %.9g (bound %.3g)", d->name,
                         dhs_qf_str(qf, r.n, 0), (double)lambda, k, (double)dq[k], ref, bound);
            if (err / bound > worst) worst = err / bound;
        }
        /* scaled to random bounds: within them, parallel to dq */
        for (k = 0; k < r.n; k++) dqm[k] = (float)(fabs(dq[k]) * dht_rand_uniform(0.0, 2.0));
        DHT_EQ_INT(dh_dls_step_f32(&r, J, e, lambda, dqm, dqs), DH_OK);
        {
            double s = 1.0;
            for (k = 0; k < r.n; k++)
                if (fabs(dq[k]) > dqm[k]) s = fmin(s, dqm[k] / fabs(dq[k]));
            for (k = 0; k < r.n; k++) {
                DHT_TRUE_MSG(fabs(dqs[k]) <= dqm[k], "joint %u: |%.9g| > %.9g", k, (double)dqs[k], (double)dqm[k]);
                DHT_TRUE_MSG(fabs(dqs[k] - s * dq[k]) <= 4 * U * fabs(dq[k]) + 1e-30,
                             "joint %u: %.9g is not %.9g x %.9g", k, (double)dqs[k], s, (double)dq[k]);
                if (fabs(dq[k]) > 0.0 && fabs(dqs[k]) >= dqm[k] * (1 - 4 * U)) at_bound++;
            }
            if (s < 1.0) DHT_TRUE(at_bound >= 1u);
        }
    }
    printf("dls step: %ld steps, largest error %.3g of its bound\n", n_it, worst);
}

/* lambda 0: the pseudo-inverse step; singular J J^T (exact wrist
 * singularity, fewer than 6 joints) -> DH_ERR_SINGULAR with dq zeros; the
 * same with damping -> OK */
static void dls_singular(void)
{
    dh_robot r, r3;
    float q[6] = { 10.0f, -30.0f, 40.0f, 20.0f, 0.0f, 15.0f }, J[6 * DH_MAX_JOINTS], dq[DH_MAX_JOINTS];
    const float e[6] = { 1e-3f, -2e-3f, 0.0f, 0.01f, 0.0f, -0.01f };
    unsigned k;
    DHT_EQ_INT(dhs_build(&dhs_puma560_m, &r), DH_OK);
    DHT_EQ_INT(dh_jacobian_f32(&r, q, J, NULL), DH_OK);
    for (k = 0; k < 6u; k++) dq[k] = 7.0f;
    DHT_EQ_INT(dh_dls_step_f32(&r, J, e, 0.0f, NULL, dq), DH_ERR_SINGULAR);
    for (k = 0; k < 6u; k++) DHT_TRUE(dq[k] == 0.0f);
    DHT_EQ_INT(dh_dls_step_f32(&r, J, e, 1e-2f, NULL, dq), DH_OK);
    q[4] = 30.0f;
    DHT_EQ_INT(dh_jacobian_f32(&r, q, J, NULL), DH_OK);
    DHT_EQ_INT(dh_dls_step_f32(&r, J, e, 0.0f, NULL, dq), DH_OK);
    /* 3 joints: J J^T has rank 3 */
    r3 = r;
    r3.n = 3u;
    DHT_EQ_INT(dh_jacobian_f32(&r3, q, J, NULL), DH_OK);
    DHT_EQ_INT(dh_dls_step_f32(&r3, J, e, 0.0f, NULL, dq), DH_ERR_SINGULAR);
    DHT_EQ_INT(dh_dls_step_f32(&r3, J, e, 1e-3f, NULL, dq), DH_OK);
    {
        float w = -1.0f, s = -1.0f;
        DHT_EQ_INT(dh_manipulability_f32(J, 3u, &w, &s), DH_OK); /* J^T J, 3 x 3 */
        DHT_TRUE(w > 0.0f && s > 0.0f);
    }
}

/* bad input: status, outputs untouched */
static void dls_bad_input(void)
{
    dh_robot r;
    float q[6] = { 10.0f, -30.0f, 40.0f, 20.0f, 30.0f, 15.0f }, J[6 * DH_MAX_JOINTS], dq[6], dqm[6];
    float e[6] = { 1e-3f, -2e-3f, 0.0f, 0.01f, 0.0f, -0.01f };
    float w = 5.0f, s = 5.0f;
    const float nan = dht_f32_from_bits(0x7FC00000u), inf = dht_f32_from_bits(0x7F800000u);
    unsigned k;
    DHT_EQ_INT(dhs_build(&dhs_ur5_m, &r), DH_OK);
    DHT_EQ_INT(dh_jacobian_f32(&r, q, J, NULL), DH_OK);
    for (k = 0; k < 6u; k++) { dq[k] = 7.0f; dqm[k] = 1.0f; }
    DHT_EQ_INT(dh_manipulability_f32(J, 0u, &w, &s), DH_ERR_ARG);
    DHT_EQ_INT(dh_manipulability_f32(J, DH_MAX_JOINTS + 1u, &w, &s), DH_ERR_ARG);
    DHT_EQ_INT(dh_dls_step_f32(&r, J, e, -1.0f, NULL, dq), DH_ERR_ARG);
    DHT_EQ_INT(dh_dls_step_f32(&r, J, e, inf, NULL, dq), DH_ERR_ARG);
    DHT_EQ_INT(dh_dls_step_f32(&r, J, e, nan, NULL, dq), DH_ERR_NAN);
    dqm[3] = -1.0f;
    DHT_EQ_INT(dh_dls_step_f32(&r, J, e, 0.1f, dqm, dq), DH_ERR_ARG);
    dqm[3] = nan;
    DHT_EQ_INT(dh_dls_step_f32(&r, J, e, 0.1f, dqm, dq), DH_ERR_ARG);
    e[4] = inf;
    DHT_EQ_INT(dh_dls_step_f32(&r, J, e, 0.1f, NULL, dq), DH_ERR_NAN);
    e[4] = 0.0f;
    J[17] = nan;
    DHT_EQ_INT(dh_dls_step_f32(&r, J, e, 0.1f, NULL, dq), DH_ERR_NAN);
    DHT_EQ_INT(dh_manipulability_f32(J, 6u, &w, &s), DH_ERR_NAN);
    J[17] = 1e30f;
    DHT_EQ_INT(dh_manipulability_f32(J, 6u, &w, &s), DH_ERR_OVERFLOW);
    DHT_EQ_INT(dh_dls_step_f32(&r, J, e, 0.1f, NULL, dq), DH_ERR_OVERFLOW);
    r.n = 0u;
    DHT_EQ_INT(dh_dls_step_f32(&r, J, e, 0.1f, NULL, dq), DH_ERR_ARG);
    DHT_TRUE(w == 5.0f && s == 5.0f);
    for (k = 0; k < 6u; k++) DHT_TRUE(dq[k] == 7.0f);
    /* NULL outputs are allowed */
    r.n = 6u;
    DHT_EQ_INT(dh_jacobian_f32(&r, q, J, NULL), DH_OK);
    DHT_EQ_INT(dh_manipulability_f32(J, 6u, NULL, NULL), DH_OK);
    /* a zero bound stops the step */
    for (k = 0; k < 6u; k++) dqm[k] = (k == 2u) ? 0.0f : inf;
    DHT_EQ_INT(dh_dls_step_f32(&r, J, e, 0.1f, dqm, dq), DH_OK);
    for (k = 0; k < 6u; k++) DHT_TRUE(dq[k] == 0.0f);
}

/* the public step and the tracker's entry point: same status, same bits */
static void dls_both(const dh_robot *r, const float *J, const float *e, float lambda, const float *dqm)
{
    float a[DH_MAX_JOINTS], b[DH_MAX_JOINTS], ws[DH_DLS_WS_FLOATS];
    unsigned k;
    for (k = 0; k < DH_MAX_JOINTS; k++) a[k] = b[k] = 7.0f;
    DHT_EQ_INT(dh_dls_step_ws_f32_(r, J, e, lambda, dqm, b, ws), dh_dls_step_f32(r, J, e, lambda, dqm, a));
    DHT_TRUE(memcmp(a, b, sizeof a) == 0);
}

/* the public measures and the tracker's entry point: same status, same bits */
static void manip_both(const float *J, uint32_t n)
{
    float wa = 5.0f, sa = 5.0f, wb = 5.0f, sb = 5.0f, ws[DH_DLS_WS_FLOATS];
    DHT_EQ_INT(dh_manipulability_ws_f32_(J, n, &wb, &sb, ws), dh_manipulability_f32(J, n, &wa, &sa));
    DHT_TRUE(memcmp(&wa, &wb, sizeof wa) == 0 && memcmp(&sa, &sb, sizeof sa) == 0);
}

/* the entry points agree on the inputs of dls_singular and dls_bad_input */
static void ws_entry_points_agree(void)
{
    dh_robot r, r3;
    float q[6] = { 10.0f, -30.0f, 40.0f, 20.0f, 0.0f, 15.0f }, J[6 * DH_MAX_JOINTS], dqm[6];
    float e[6] = { 1e-3f, -2e-3f, 0.0f, 0.01f, 0.0f, -0.01f };
    const float nan = dht_f32_from_bits(0x7FC00000u), inf = dht_f32_from_bits(0x7F800000u);
    unsigned k;
    DHT_EQ_INT(dhs_build(&dhs_puma560_m, &r), DH_OK);
    DHT_EQ_INT(dh_jacobian_f32(&r, q, J, NULL), DH_OK); /* wrist singular */
    dls_both(&r, J, e, 0.0f, NULL);
    dls_both(&r, J, e, 1e-2f, NULL);
    manip_both(J, 6u);
    q[4] = 30.0f;
    DHT_EQ_INT(dh_jacobian_f32(&r, q, J, NULL), DH_OK);
    dls_both(&r, J, e, 0.0f, NULL);
    manip_both(J, 6u);
    manip_both(J, 0u);
    manip_both(J, DH_MAX_JOINTS + 1u);
    for (k = 0; k < 6u; k++) dqm[k] = (k == 2u) ? 0.0f : 1e-3f;
    dls_both(&r, J, e, 0.1f, dqm);
    dls_both(&r, J, e, -1.0f, NULL);
    dls_both(&r, J, e, inf, NULL);
    dls_both(&r, J, e, nan, NULL);
    dqm[3] = -1.0f;
    dls_both(&r, J, e, 0.1f, dqm);
    e[4] = inf;
    dls_both(&r, J, e, 0.1f, NULL);
    e[4] = 0.0f;
    J[17] = nan;
    dls_both(&r, J, e, 0.1f, NULL);
    manip_both(J, 6u);
    J[17] = 1e30f;
    dls_both(&r, J, e, 0.1f, NULL);
    manip_both(J, 6u);
    r3 = r;
    r3.n = 3u;
    DHT_EQ_INT(dh_jacobian_f32(&r3, q, J, NULL), DH_OK);
    dls_both(&r3, J, e, 0.0f, NULL);
    dls_both(&r3, J, e, 1e-3f, NULL);
    manip_both(J, 3u);
    r3.n = 0u;
    dls_both(&r3, J, e, 0.1f, NULL);
}

static const dht_case cases[] = {
    DHT_CASE(manipulability_against_double),
    DHT_CASE(dls_against_double),
    DHT_CASE(dls_singular),
    DHT_CASE(dls_bad_input),
    DHT_CASE(ws_entry_points_agree),
};

DHT_MAIN(cases)
