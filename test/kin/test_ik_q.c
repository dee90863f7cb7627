/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_ik_q.c - numerical inverse kinematics in fixed point (dh_ik_q).
 *
 * Every result is judged in double, independently of the library: the
 * returned Q joint values go through the double reference FK of the
 * robot's stored fixed parameters (dhs_fk_ref_q) and are compared with the
 * double target by a double log map. Targets are that reference FK of
 * random in-limit Q configurations (reachable), rounded to dh_frame_q.
 */
#include "dht.h"
#include "support_robots.h"
#include "dhmath/kin.h"
#include "dhmath/frame.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define NJ DH_MAX_JOINTS
#define WORDS DH_IK_WORK_Q(NJ)

static int32_t g_work[WORDS];

/* Position tolerance (mm) verified: 1e-3 mm, or the same number of LSB
 * (65.5) with a coarser position format (DH_QPOS_FRAC < 16, a build
 * variant), where dh_qpos cannot resolve 1e-3 mm and the fixed FK's own
 * error is about half an LSB per joint. x is scaled the same way. */
static double pos_tol(double x)
{
    return (DH_QPOS_FRAC >= 16) ? x : ldexp(x, 16 - DH_QPOS_FRAC);
}

/* ---------------------------------------------------------------------- */

static void to_frame_q(const dhr_mat4 *D, dh_frame_q *F)
{
    int c, k;
    for (c = 0; c < 3; c++)
        for (k = 0; k < 3; k++) F->r[c][k] = dhs_to_q(D->m[c][k], 30);
    for (k = 0; k < 3; k++) F->p[k] = dhs_to_q(D->m[3][k], DH_QPOS_FRAC);
}

/* True errors of q for the double target D: position norm (length unit)
 * and rotation angle of R_D R(q)^T, from the double reference FK. */
static void true_error(const dh_robot *r, const int32_t *q, const dhr_mat4 *D, double *ep, double *er)
{
    dhr_mat4 T;
    double M[3][3], ux, uy, uz;
    int a, b, k;
    dhs_fk_ref_q(r, q, NULL, &T);
    *ep = 0;
    for (k = 0; k < 3; k++) {
        double d = D->m[3][k] - T.m[3][k];
        *ep += d * d;
    }
    *ep = sqrt(*ep);
    for (a = 0; a < 3; a++)         /* M[col][row] = (R_D R^T)(row, col) */
        for (b = 0; b < 3; b++) {
            double s = 0;
            for (k = 0; k < 3; k++) s += D->m[k][b] * T.m[k][a];
            M[a][b] = s;
        }
    ux = M[1][2] - M[2][1];
    uy = M[2][0] - M[0][2];
    uz = M[0][1] - M[1][0];
    *er = atan2(sqrt(ux * ux + uy * uy + uz * uz), M[0][0] + M[1][1] + M[2][2] - 1.0);
}

static int within_limits(const dh_robot *r, const int32_t *q)
{
    uint32_t i;
    for (i = 0; i < r->n; i++) {
        const dh_joint *j = &r->joint[i];
        if (j->qmin_q <= j->qmax_q && (q[i] < j->qmin_q || q[i] > j->qmax_q)) return 0;
    }
    return 1;
}

static int32_t clamp_q(const dh_joint *j, double v)
{
    if (j->qmin_q <= j->qmax_q) {
        if (v < j->qmin_q) return j->qmin_q;
        if (v > j->qmax_q) return j->qmax_q;
    }
    return (int32_t)v;
}

/* A random in-limit Q configuration qt, its double FK D and target T, and a
 * start q0 10..20 degrees away on every joint (clamped into the limits). */
static void random_case(const dhs_robot *desc, const dh_robot *r, int32_t *qt, int32_t *q0, dhr_mat4 *D,
                        dh_frame_q *T)
{
    double q[NJ];
    uint32_t i;
    dhs_random_q(desc, q);
    dhs_q_from_double(r, q, qt);
    for (i = 0; i < r->n; i++) qt[i] = clamp_q(&r->joint[i], qt[i]);
    dhs_fk_ref_q(r, qt, NULL, D);
    to_frame_q(D, T);
    for (i = 0; i < r->n; i++) {
        double off = dht_rand_uniform(10.0, 20.0) * ((dht_rand_u32() & 1u) ? 1.0 : -1.0);
        q0[i] = clamp_q(&r->joint[i], (double)qt[i] + off * 65536.0);
    }
}

static const char *q_str(const int32_t *q, uint32_t n)
{
    static char buf[NJ * 16];
    size_t k = 0;
    uint32_t i;
    for (i = 0; i < n && i < NJ; i++)
        k += (size_t)snprintf(buf + k, sizeof buf - k, "%s%ld", i ? " " : "", (long)q[i]);
    return buf;
}

/* ---------------------------------------------------------------------- */
/* success rate                                                            */

/* Targets of a success-rate check. The Puma 560 misses about 0.35 % of its
 * targets (706 of 200,000 over 200 seeds), near-singular ones: mostly q3
 * near 92.7 deg (the folded elbow) or q5 near 0; for 686 of the 706 the
 * smallest singular value of the weighted Jacobian at the target is below
 * the solver's damping floor sqrt(wbar) = L 2^-11.5 = 0.59 mm/rad (most
 * 0.01 .. 0.1 mm/rad): attempts crawl along that direction (about 1 % of
 * E per step) or stall, and the restarts use up max_iter (UNREACHABLE,
 * some NO_CONVERGENCE). Against need = 99 %, the number of misses is
 * Binomial(n, 0.0035): over 100 targets it exceeds 1 % for 4.8 % of the
 * seeds, over 1000 for 0.1 %, over 10,000 for 7e-20 (1.4e-10 at a miss
 * rate of 0.5 %). So the host runs 10,000 targets whatever DHT_ITER_DIV
 * says (the whole suite about 0.7 s); a target build (its DHT_ITER_DIV
 * compiled in, one fixed seed) divides 1000 as every loop count. */
#if defined(DHT_ITER_DIV)
#define RATE_TARGETS ((int)DHT_ITER(1000))
#else
#define RATE_TARGETS 10000
#endif

static void rate_case(const char *name, const dhs_robot *desc, double tol_p, double tol_r, double need)
{
    dh_robot r;
    dh_ik_params_q p;
    const int count = RATE_TARGETS;
    int it, ok = 0, ok_status = 0, miss100 = 0, miss1000 = 0;
    double iter_sum = 0, ep_max = 0, er_max = 0;
    uint32_t iter_max = 0;
    char probe[48];
    DHT_EQ_INT(dhs_build(desc, &r), DH_OK);
    dh_ik_params_default_q(&r, &p);
    /* the solver's tolerances 0.9 of the verified ones: room for the
     * error of the fixed FK it iterates on (dh_fk_q, 4e-5 mm) */
    p.tol_pos = (int32_t)(0.9 * tol_p * (double)DH_QPOS_ONE);
    p.tol_rot = (int32_t)(0.9 * tol_r * 1073741824.0);
    for (it = 0; it < count; it++) {
        int32_t qt[NJ], q0[NJ], q[NJ];
        dhr_mat4 D;
        dh_frame_q T;
        dh_ik_result_q res;
        double ep, er;
        dh_status st;
        random_case(desc, &r, qt, q0, &D, &T);
        st = dh_ik_q(&r, &T, q0, &p, g_work, WORDS, q, &res);
        DHT_TRUE_MSG(st == DH_OK || st == DH_ERR_NO_CONVERGENCE || st == DH_ERR_UNREACHABLE,
                     "%s target %d: status %d (%s); target q %s", name, it, (int)st, dh_status_str(st),
                     q_str(qt, r.n));
        DHT_TRUE_MSG(within_limits(&r, q), "%s target %d: result outside the limits", name, it);
        DHT_TRUE_MSG(res.iterations <= p.max_iter, "%s target %d: %lu iterations", name, it,
                     (unsigned long)res.iterations);
        true_error(&r, q, &D, &ep, &er);
        iter_sum += res.iterations;
        if (res.iterations > iter_max) iter_max = res.iterations;
        if (st == DH_OK) {
            ok_status++;
            DHT_TRUE_MSG(res.err_pos <= p.tol_pos && res.err_rot <= p.tol_rot,
                         "%s target %d: OK with reported errors %ld / %ld above tol", name, it, (long)res.err_pos,
                         (long)res.err_rot);
            /* the reported errors are the fixed FK's: within its error of the true ones */
            DHT_NEAR(res.err_pos / (double)DH_QPOS_ONE, ep, pos_tol(2e-4));
            DHT_NEAR(res.err_rot / 1073741824.0, er, 2e-7);
        }
        if (!(st == DH_OK && ep <= tol_p && er <= tol_r)) {
            dht_printf("  miss %d: st %d it %lu err %ld %ld true %.3g %.3g q %s\n", it, (int)st,
                       (unsigned long)res.iterations, (long)res.err_pos, (long)res.err_rot, ep, er, q_str(qt, r.n));
            if (it < 100) miss100++;
            if (it < 1000) miss1000++;
        }
        if (st == DH_OK && ep <= tol_p && er <= tol_r) {
            ok++;
            if (ep > ep_max) ep_max = ep;
            if (er > er_max) er_max = er;
        }
    }
    dht_printf("ik_q %-14s seed 0x%llx: %d/%d within %.0e / %.0e (status OK %d), iterations mean %.2f max %lu, "
               "worst true error %.3g / %.3g\n",
               name, (unsigned long long)dht_seed(), ok, count, tol_p, tol_r, ok_status, iter_sum / count,
               (unsigned long)iter_max, ep_max, er_max);
    dht_printf("ik_q %-14s misses among the first 100 / 1000 targets: %d / %d\n", name, miss100, miss1000);
    /* reach probes "<desc name>.miss100" and ".miss1000" */
    snprintf(probe, sizeof probe, "%s.miss100", desc->name);
    dht_reach_max(probe, (double)miss100);
    snprintf(probe, sizeof probe, "%s.miss1000", desc->name);
    dht_reach_max(probe, (double)miss1000);
    DHT_TRUE_MSG((double)ok >= need * count, "%s: success %d/%d below %.3f", name, ok, count, need);
}

static void ikq_rate_puma(void) { rate_case("puma560 (mm)", &dhs_puma560_mm, pos_tol(1e-3), 1e-5, 0.99); }
static void ikq_rate_ur5(void) { rate_case("ur5 (mm)", &dhs_ur5_mm, pos_tol(1e-3), 1e-5, 0.99); }
static void ikq_rate_panda(void) { rate_case("panda (mm)", &dhs_panda_mm, pos_tol(1e-3), 1e-5, 0.99); }

/* ---------------------------------------------------------------------- */
/* bad input                                                               */

static void puma_case(dh_robot *r, dh_frame_q *T, dhr_mat4 *D, int32_t *q0)
{
    int32_t qt[6] = { DH_Q16(10), DH_Q16(20), DH_Q16(-30), DH_Q16(40), DH_Q16(50), DH_Q16(60) };
    int i;
    DHT_EQ_INT(dhs_build(&dhs_puma560_mm, r), DH_OK);
    dhs_fk_ref_q(r, qt, NULL, D);
    to_frame_q(D, T);
    for (i = 0; i < 6; i++) q0[i] = qt[i] + (15 << 16);
}

static void ikq_bad_arguments(void)
{
    dh_robot r;
    dh_ik_params_q p;
    dh_ik_result_q res;
    dh_frame_q T;
    dhr_mat4 D;
    int32_t q[6], q0[6];
    int k;
    puma_case(&r, &T, &D, q0);
    dh_ik_params_default_q(&r, &p);
    for (k = 0; k < 6; k++) q[k] = 99;
    res.iterations = 77u;
    /* workspace too small / missing */
    DHT_EQ_INT(dh_ik_q(&r, &T, q0, &p, g_work, DH_IK_WORK_Q(6u) - 1u, q, &res), DH_ERR_ARG);
    DHT_EQ_INT(dh_ik_q(&r, &T, q0, &p, NULL, WORDS, q, &res), DH_ERR_ARG);
    /* bad parameters */
    p.max_iter = 0;
    DHT_EQ_INT(dh_ik_q(&r, &T, q0, &p, g_work, WORDS, q, &res), DH_ERR_ARG);
    dh_ik_params_default_q(&r, &p);
    p.mask = 0;
    DHT_EQ_INT(dh_ik_q(&r, &T, q0, &p, g_work, WORDS, q, &res), DH_ERR_ARG);
    p.mask = 0x40u;
    DHT_EQ_INT(dh_ik_q(&r, &T, q0, &p, g_work, WORDS, q, &res), DH_ERR_ARG);
    dh_ik_params_default_q(&r, &p);
    p.tol_pos = -1;
    DHT_EQ_INT(dh_ik_q(&r, &T, q0, &p, g_work, WORDS, q, &res), DH_ERR_ARG);
    dh_ik_params_default_q(&r, &p);
    p.tol_rot = INT32_MIN;
    DHT_EQ_INT(dh_ik_q(&r, &T, q0, &p, g_work, WORDS, q, &res), DH_ERR_ARG);
    dh_ik_params_default_q(&r, &p);
    p.w_rot = 0;
    DHT_EQ_INT(dh_ik_q(&r, &T, q0, &p, g_work, WORDS, q, &res), DH_ERR_ARG);
    p.w_rot = -5;
    DHT_EQ_INT(dh_ik_q(&r, &T, q0, &p, g_work, WORDS, q, &res), DH_ERR_ARG);
    dh_ik_params_default_q(&r, &p);
    /* target rotation not a rotation: scaled, reflected */
    T.r[0][0] *= 2;
    DHT_EQ_INT(dh_ik_q(&r, &T, q0, &p, g_work, WORDS, q, &res), DH_ERR_NOT_RIGID);
    to_frame_q(&D, &T);
    for (k = 0; k < 3; k++) T.r[2][k] = (T.r[2][k] == INT32_MIN) ? INT32_MAX : -T.r[2][k];
    DHT_EQ_INT(dh_ik_q(&r, &T, q0, &p, g_work, WORDS, q, &res), DH_ERR_NOT_RIGID);
    /* unknown convention and joint type */
    to_frame_q(&D, &T);
    r.conv = (dh_convention)7;
    DHT_EQ_INT(dh_ik_q(&r, &T, q0, &p, g_work, WORDS, q, &res), DH_ERR_ARG);
    r.conv = DH_CONV_STANDARD;
    r.joint[3].type = (dh_joint_type)9;
    DHT_EQ_INT(dh_ik_q(&r, &T, q0, &p, g_work, WORDS, q, &res), DH_ERR_ARG);
    r.joint[3].type = DH_JOINT_REVOLUTE;
    /* fixed path unavailable */
    r.flags &= ~DH_ROBOT_HAS_Q;
    DHT_EQ_INT(dh_ik_q(&r, &T, q0, &p, g_work, WORDS, q, &res), DH_ERR_UNAVAILABLE);
    r.flags |= DH_ROBOT_HAS_Q;
    /* no joints, too many */
    r.n = 0;
    DHT_EQ_INT(dh_ik_q(&r, &T, q0, &p, g_work, WORDS, q, &res), DH_ERR_ARG);
    r.n = DH_MAX_JOINTS + 1u;
    DHT_EQ_INT(dh_ik_q(&r, &T, q0, &p, g_work, WORDS, q, &res), DH_ERR_ARG);
    r.n = 6;
    /* outputs untouched on every error above */
    for (k = 0; k < 6; k++) DHT_EQ_INT(q[k], 99);
    DHT_EQ_INT(res.iterations, 77);
    /* the scaled target rotation does not matter for position-only IK */
    T.r[0][0] *= 2;
    p.mask = DH_IK_POSITION;
    DHT_EQ_INT(dh_ik_q(&r, &T, q0, &p, g_work, WORDS, q, &res), DH_OK);
}

/* dh_ik_q refuses the call with status want: q and the result untouched */
static void ikq_refused(const dh_robot *r, const dh_frame_q *T, const int32_t *q0, const dh_ik_params_q *p,
                        dh_status want)
{
    dh_ik_result_q res;
    int32_t q[NJ];
    uint32_t k;
    for (k = 0; k < NJ; k++) q[k] = 99;
    res.iterations = 77u;
    DHT_EQ_INT(dh_ik_q(r, T, q0, p, g_work, WORDS, q, &res), want);
    for (k = 0; k < NJ; k++) DHT_EQ_INT(q[k], 99);
    DHT_EQ_INT(res.iterations, 77);
}

/* Non-rigid end rotation (scaled fixed base): NOT_RIGID at the start. */
static void ikq_end_not_rigid(void)
{
    dh_robot r;
    dh_ik_params_q p;
    dh_frame_q T, B;
    dhr_mat4 D;
    int32_t q0[6];
    puma_case(&r, &T, &D, q0);
    dh_ik_params_default_q(&r, &p);
    dh_frame_identity_q(&B);
    B.r[0][0] = DH_Q30(1.5);
    DHT_EQ_INT(dh_robot_set_base_q(&r, &B), DH_OK);
    ikq_refused(&r, &T, q0, &p, DH_ERR_NOT_RIGID);
}

/* FK of the start saturates (prismatic joint far beyond the dh_qpos range
 * with no limits): OVERFLOW, outputs untouched. */
static void ikq_start_overflow(void)
{
    dh_robot r;
    dh_ik_params_q p;
    dh_frame_q T;
    const int32_t q0[2] = { 0, INT32_MAX };
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_q(&r, DH_JOINT_REVOLUTE, 0, 0, DH_QPOS_ONE, 0), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_q(&r, DH_JOINT_PRISMATIC, 0, INT32_MAX / 2, 0, 0), DH_OK);
    dh_frame_identity_q(&T);
    dh_ik_params_default_q(&r, &p);
    p.mask = DH_IK_POSITION;
    ikq_refused(&r, &T, q0, &p, DH_ERR_OVERFLOW);
}

/* Beyond the reach bound: UNREACHABLE after a few attempts, q within the
 * limits, reported error the true one. */
static void ikq_unreachable(void)
{
    dh_robot r;
    dh_ik_params_q p;
    dh_ik_result_q res;
    dh_frame_q T;
    dhr_mat4 D;
    int32_t q[6], q0[6];
    double ep, er;
    dh_status st;
    int k;
    puma_case(&r, &T, &D, q0);
    dh_ik_params_default_q(&r, &p);
    D.m[3][0] = 1500.0;     /* 2.2 m from a Puma reaching < 1 m; fits dh_qpos up to 20 bits */
    D.m[3][1] = 1000.0;
    D.m[3][2] = 1200.0;
    to_frame_q(&D, &T);
    st = dh_ik_q(&r, &T, q0, &p, g_work, WORDS, q, &res);
    dht_printf("unreachable: status %d after %lu iterations, residual %ld / %ld\n", (int)st,
               (unsigned long)res.iterations, (long)res.err_pos, (long)res.err_rot);
    DHT_EQ_INT(st, DH_ERR_UNREACHABLE);
    DHT_TRUE_MSG(res.iterations < 400u, "%lu iterations", (unsigned long)res.iterations);
    DHT_TRUE(within_limits(&r, q));
    true_error(&r, q, &D, &ep, &er);
    DHT_NEAR(res.err_pos / (double)DH_QPOS_ONE, ep, 1e-3);
    DHT_TRUE_MSG(ep > 1000.0, "residual %.6g mm", ep);
    /* inside the reach bound but outside the limits: joint 2 locked near
     * the start, target from a configuration far from it */
    puma_case(&r, &T, &D, q0);
    DHT_EQ_INT(dh_robot_set_limits_q(&r, 1, 30 << 16, 31 << 16), DH_OK);
    p.restarts = 2u;
    st = dh_ik_q(&r, &T, q0, &p, g_work, WORDS, q, &res);
    DHT_TRUE_MSG(st == DH_ERR_UNREACHABLE, "status %d", (int)st);
    DHT_TRUE(within_limits(&r, q));
    true_error(&r, q, &D, &ep, &er);
    DHT_TRUE_MSG(ep > 1.0, "residual %.6g mm", ep);
    /* max_iter too small: NO_CONVERGENCE with the best point so far */
    puma_case(&r, &T, &D, q0);
    p.max_iter = 1u;
    st = dh_ik_q(&r, &T, q0, &p, g_work, WORDS, q, &res);
    DHT_EQ_INT(st, DH_ERR_NO_CONVERGENCE);
    DHT_EQ_INT(res.iterations, 1);
    /* q0 far outside the limits is clamped first; q may alias q0 */
    dh_ik_params_default_q(&r, &p);
    p.tol_pos = (int32_t)(0.9 * pos_tol(1e-3) * DH_QPOS_ONE);
    for (k = 0; k < 6; k++) q0[k] = (k & 1) ? INT32_MIN : INT32_MAX;
    st = dh_ik_q(&r, &T, q0, &p, g_work, WORDS, q0, &res);
    DHT_TRUE_MSG(st == DH_OK, "status %d", (int)st);
    DHT_TRUE(within_limits(&r, q0));
    true_error(&r, q0, &D, &ep, &er);
    DHT_TRUE_MSG(ep <= pos_tol(1e-3) && er <= 1e-5, "true errors %.3g / %.3g", ep, er);
}

/* Same inputs, same outputs; q aliasing q0 gives the same result. */
static void ikq_deterministic(void)
{
    dh_robot r;
    dh_ik_params_q p;
    dh_ik_result_q a, b;
    dh_frame_q T;
    dhr_mat4 D;
    int32_t q0[6], q1[6], q2[6];
    int k;
    puma_case(&r, &T, &D, q0);
    dh_ik_params_default_q(&r, &p);
    DHT_EQ_INT(dh_ik_q(&r, &T, q0, &p, g_work, WORDS, q1, &a), DH_OK);
    memcpy(q2, q0, sizeof q2);
    DHT_EQ_INT(dh_ik_q(&r, &T, q2, &p, g_work, WORDS, q2, &b), DH_OK);
    for (k = 0; k < 6; k++) DHT_EQ_INT(q1[k], q2[k]);
    DHT_EQ_INT(a.iterations, b.iterations);
    DHT_EQ_INT(a.err_pos, b.err_pos);
    DHT_EQ_INT(a.err_rot, b.err_rot);
}

/* Orientation errors near 180 degrees and exactly 0 (the start rotated by
 * 170 deg about the tool z axis; the solver must still converge). */
static void ikq_large_rotation(void)
{
    dh_robot r;
    dh_ik_params_q p;
    dh_ik_result_q res;
    dh_frame_q T;
    dhr_mat4 D;
    int32_t q[6], q0[6];
    double ep, er;
    puma_case(&r, &T, &D, q0);
    dh_ik_params_default_q(&r, &p);
    p.tol_pos = (int32_t)(0.9 * pos_tol(1e-3) * DH_QPOS_ONE);
    q0[5] += DH_Q16(150);
    DHT_EQ_INT(dh_ik_q(&r, &T, q0, &p, g_work, WORDS, q, &res), DH_OK);
    true_error(&r, q, &D, &ep, &er);
    DHT_TRUE_MSG(ep <= pos_tol(1e-3) && er <= 1e-5, "true errors %.3g / %.3g", ep, er);
}

static void ikq_defaults(void)
{
    dh_robot r;
    dh_ik_params_q p;
    DHT_EQ_INT(dhs_build(&dhs_puma560_mm, &r), DH_OK);
    dh_ik_params_default_q(&r, &p);
    DHT_EQ_INT(p.mask, DH_IK_FULL);
    DHT_EQ_INT(p.tol_rot, 10737);
    DHT_TRUE(p.tol_pos >= 1 && p.w_rot >= 1 && p.max_iter >= 1u);
    /* an empty robot: L = one length unit */
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    dh_ik_params_default_q(&r, &p);
    DHT_EQ_INT(p.w_rot, DH_QPOS_ONE / 4);
}

static const dht_case cases[] = {
    DHT_CASE(ikq_rate_puma),       DHT_CASE(ikq_rate_ur5),       DHT_CASE(ikq_rate_panda),
    DHT_CASE(ikq_bad_arguments),   DHT_CASE(ikq_end_not_rigid),  DHT_CASE(ikq_start_overflow),
    DHT_CASE(ikq_unreachable),     DHT_CASE(ikq_deterministic),  DHT_CASE(ikq_large_rotation),
    DHT_CASE(ikq_defaults),
};
DHT_MAIN(cases)
