/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_ikc_ur.c - closed-form IK, float: axes 2-3-4 parallel (UR3, UR5,
 * UR10) and SCARA (Adept Cobra 600), robots in metres.
 *
 * Every solution is judged in double, independently of the library: its
 * joint values go through the double reference FK of support_robots.c
 * (the robot's stored float parameters) and are compared with the float
 * target (position norm, rotation angle of R_target R^T). Targets are the
 * reference FK of random in-limit configurations, rounded to float.
 */
#include "dht.h"
#include "support_robots.h"
#include "dhmath/dh_ikc.h"
#include "dhmath/dh_kin.h"
#include "dhmath/dh_mat4.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define PI 3.14159265358979323846
#define D2R (PI / 180.0)
#define TOL_POS 2e-6
#define TOL_ROT 2e-6
#define NJ DH_IKC_JOINTS
/* Normalised distance from every singularity (shoulder |u| / L, elbow
 * |a2 a3 s3| / (|a2| + |a3|)^2, wrist |s5|; SCARA |a1 a2 s2| / (|a1| +
 * |a2|)^2). ikc_complete and ikc_vs_numerical accept a joint distance
 * within MATCH_FLOOR, or else within the bound derived from the local
 * conditioning (pair_bound), which is only evaluated for the pairs that
 * need it; the description variants (complete_desc) and the singular cases
 * keep configurations at least SING_FAR away, where the generating
 * configuration is among the solutions within 1e-3 deg. */
#define SING_FAR 1e-1

/* ---- the robots ---------------------------------------------------------- */

static const dhs_robot *const g_robots[] = { &dhs_ur3_m, &dhs_ur5_m, &dhs_ur10_m, &dhs_cobra600_m };
#define N_ROBOTS (sizeof g_robots / sizeof g_robots[0])

/* ---- double helpers --------------------------------------------------------- */

static void to_f32(const dhr_mat4 *D, dh_mat4_f32 *T)
{
    int c, r;
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) T->m[c][r] = (float)D->m[c][r];
}

static void target_of(const dh_robot *r, const double *q, dh_mat4_f32 *T)
{
    dhr_mat4 F;
    dhs_fk_ref_f32(r, q, NULL, &F);
    to_f32(&F, T);
}

/* |a - b| modulo 360 for revolute joints, plain for prismatic ones */
static double joint_dist(const dh_robot *r, uint32_t i, double a, double b)
{
    double d = a - b;
    if (r->joint[i].type == DH_JOINT_REVOLUTE) {
        d = fmod(d, 360.0);
        if (d > 180.0) d -= 360.0;
        if (d < -180.0) d += 360.0;
    }
    return fabs(d);
}

static double sol_dist(const dh_robot *r, const float *qs, const double *q)
{
    double m = 0.0;
    uint32_t i;
    for (i = 0; i < r->n; i++) {
        double d = joint_dist(r, i, (double)qs[i], q[i]);
        if (r->joint[i].type == DH_JOINT_PRISMATIC) d *= 1000.0; /* mm as "degrees" */
        if (d > m) m = d;
    }
    return m;
}

static const char *q_str(const double *q, uint32_t n, int slot)
{
    static char buf[2][160];
    uint32_t i;
    size_t o = 0;
    buf[slot][0] = 0;
    for (i = 0; i < n && o < sizeof buf[slot]; i++)
        o += (size_t)snprintf(buf[slot] + o, sizeof buf[slot] - o, "%s%.9g", i ? " " : "", q[i]);
    return buf[slot];
}

/* ---- analysis and solving through the public API -------------------------- */

static void build(const dhs_robot *d, dh_robot *r, dh_ikc_model_f32 *m)
{
    DHT_EQ_INT(dhs_build(d, r), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_f32(r, m), DH_OK);
    DHT_EQ_INT(m->kind, r->n == 6u ? DH_IKC_PARALLEL_234 : DH_IKC_SCARA);
    DHT_EQ_INT(m->why, DH_IKC_WHY_NONE);
}

/* every solution within the limits; DH_ERR_UNREACHABLE / DH_ERR_LIMIT: 0 */
static uint32_t solve(const dh_robot *r, const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *q_ref,
                      dh_ikc_sol_f32 *sol)
{
    uint32_t n = 99u, s, i;
    const dh_status st = dh_ikc_f32(m, T, q_ref, 0u, sol, &n);
    DHT_TRUE_MSG(st == DH_OK || st == DH_ERR_UNREACHABLE || st == DH_ERR_LIMIT, "dh_ikc_f32: status %d", (int)st);
    DHT_TRUE(n <= DH_IKC_MAX_SOL);
    DHT_TRUE((st == DH_OK) == (n >= 1u));
    for (s = 0; s < n; s++) {
        DHT_EQ_INT(sol[s].flags & DH_IKC_OUT_OF_LIMITS, 0);
        for (i = 0; i < r->n; i++) {
            const dh_joint *j = &r->joint[i];
            DHT_TRUE_MSG(j->qmin > j->qmax || (sol[s].q[i] >= j->qmin && sol[s].q[i] <= j->qmax),
                         "solution %u joint %u = %.9g outside [%g, %g]", (unsigned)s, (unsigned)i,
                         (double)sol[s].q[i], (double)j->qmin, (double)j->qmax);
        }
    }
    return n;
}

/* normalised distances of configuration q from the family's singularities:
 * part[0] shoulder |u| / L (u: the joint 5 point's coordinate along x1),
 * part[1] elbow |a2 a3 s3| / (|a2| + |a3|)^2, part[2] wrist |s5|; SCARA:
 * part[1] = |a1 a2 s2| / (|a1| + |a2|)^2, the others 1. Returns the smallest. */
static double sing_parts(const dhs_robot *d, const double *q, double part[3])
{
    dhr_mat4 F[DHS_MAX_JOINTS];
    double m;
    int i;
    part[0] = part[2] = 1.0;
    if (d->n == 4u) {
        const double a1 = fabs(d->j[0].a), a2 = fabs(d->j[1].a);
        part[1] = a1 * a2 * fabs(sin((q[1] + d->j[1].theta_deg) * D2R)) / ((a1 + a2) * (a1 + a2));
    } else {
        const double a2 = fabs(d->j[1].a), a3 = fabs(d->j[2].a);
        double L = 0, u;
        unsigned j;
        for (j = 0; j < d->n; j++) L += fabs(d->j[j].a) + fabs(d->j[j].d);
        dhs_fk_desc(d, q, F, NULL);
        /* along x1 from the origin of the frame before joint 1 (the base) */
        u = (F[4].m[3][0] - d->base.m[3][0]) * F[0].m[0][0] + (F[4].m[3][1] - d->base.m[3][1]) * F[0].m[0][1] +
            (F[4].m[3][2] - d->base.m[3][2]) * F[0].m[0][2];
        part[0] = fabs(u) / L;
        part[1] = a2 * a3 * fabs(sin((q[2] + d->j[2].theta_deg) * D2R)) / ((a2 + a3) * (a2 + a3));
        part[2] = fabs(sin((q[4] + d->j[4].theta_deg) * D2R));
    }
    m = part[0];
    for (i = 1; i < 3; i++)
        if (part[i] < m) m = part[i];
    return m;
}

static double sing_dist(const dhs_robot *d, const double *q)
{
    double part[3];
    return sing_parts(d, q, part);
}

/* every solution FK-correct; returns the smallest distance to q */
static double check_all(const dh_robot *r, const dh_mat4_f32 *T, const dh_ikc_sol_f32 *sol, uint32_t n,
                        const double *q, const char *name, double *ep_max, double *er_max)
{
    double best = 1e9;
    uint32_t s;
    for (s = 0; s < n; s++) {
        double ep, er, dd;
        double qs[NJ];
        uint32_t i;
        for (i = 0; i < r->n; i++) qs[i] = (double)sol[s].q[i];
        dhs_true_error_f32(r, sol[s].q, T, &ep, &er);
        DHT_TRUE_MSG(ep <= TOL_POS && er <= TOL_ROT,
                     "%s: solution %u (flags 0x%x) q %s: error %.3g m, %.3g rad; generated by %s", name,
                     (unsigned)s, (unsigned)sol[s].flags, q_str(qs, r->n, 0), ep, er, q_str(q, r->n, 1));
        if (ep > *ep_max) *ep_max = ep;
        if (er > *er_max) *er_max = er;
        dd = sol_dist(r, sol[s].q, q);
        if (dd < best) best = dd;
    }
    return best;
}

/* ---- joint-space match bound from the local conditioning ------------------- */

/* Two configurations qa and qb whose end frames differ by at most ep (m,
 * position) and er (rad, rotation angle) satisfy, by the mean value
 * theorem, FK(qb) - FK(qa) = Jm (qb - qa) with Jm the Jacobian averaged
 * over the segment, so |qb_i - qa_i| <= ||Jm^-1_i,pos|| ep +
 * ||Jm^-1_i,rot|| er, with Jm^-1_i,pos / _i,rot the position / rotation
 * blocks of row i of Jm^-1 (Cauchy-Schwarz on each block). J is square:
 * 6x6 for the UR, 4x4 over x y z and the rotation about z for the SCARA;
 * match_bound evaluates that first-order bound with J at one configuration
 * (in double, central differences of the reference FK). Near a singularity
 * J^-1 grows as 1 / (singular distance): this is the amplification of the
 * wrist (1 / |s5|), the elbow and the shoulder. The conditioning along the
 * segment is set by the singular distance, which the ill-conditioned
 * direction itself barely moves (the wrist's: q4 and q6 turning against
 * each other about nearly parallel axes leave s5 unchanged), so pair_bound
 * takes the larger first-order bound of the two ends (the end nearer a
 * singularity, the worse conditioned along a short segment between them)
 * and MATCH_SAFETY for the rest of the second-order term.
 * Units follow sol_dist: deg for revolute joints, mm for prismatic ones. */
#define MATCH_SAFETY 2.0
/* deg: the joint distance accepted without the derived bound, the
 * resolution the completeness checks ask for */
#define MATCH_FLOOR 1e-3
#define F32_EPS (1.0 / 16777216.0) /* 2^-24: float rounding, relative */

static double match_bound(const dh_robot *r, const double *qa, double ep, double er)
{
    const uint32_t n = r->n, nr = (n == 6u) ? 6u : 4u;
    double J[6][6], A[6][12], b = 0.0;
    uint32_t i, k, c;
    for (i = 0; i < n; i++) {
        const int pri = r->joint[i].type == DH_JOINT_PRISMATIC;
        const double h = pri ? 1e-7 : 1e-4; /* m / deg */
        double qp[DHS_MAX_JOINTS], qm[DHS_MAX_JOINTS], w[3];
        dhr_mat4 Fp, Fm, F0;
        int a, bb, kk;
        memcpy(qp, qa, n * sizeof qa[0]);
        memcpy(qm, qa, n * sizeof qa[0]);
        qp[i] += h;
        qm[i] -= h;
        dhs_fk_ref_f32(r, qp, NULL, &Fp);
        dhs_fk_ref_f32(r, qm, NULL, &Fm);
        dhs_fk_ref_f32(r, qa, NULL, &F0);
        /* per deg (revolute) or per mm (prismatic) */
        for (k = 0; k < 3; k++) J[k][i] = (Fp.m[3][k] - Fm.m[3][k]) / (2.0 * h) / (pri ? 1000.0 : 1.0);
        { /* omega: the axial vector of dR R^T (R[row][col] = m[col][row]) */
            double W[3][3];
            for (a = 0; a < 3; a++)
                for (bb = 0; bb < 3; bb++) {
                    double s = 0;
                    for (kk = 0; kk < 3; kk++) s += (Fp.m[kk][a] - Fm.m[kk][a]) * F0.m[kk][bb];
                    W[a][bb] = s / (2.0 * h) / (pri ? 1000.0 : 1.0);
                }
            w[0] = 0.5 * (W[2][1] - W[1][2]);
            w[1] = 0.5 * (W[0][2] - W[2][0]);
            w[2] = 0.5 * (W[1][0] - W[0][1]);
        }
        if (nr == 6u)
            for (k = 0; k < 3; k++) J[3 + k][i] = w[k];
        else
            J[3][i] = w[2];
    }
    /* J^-1 by Gauss-Jordan with partial pivoting */
    for (i = 0; i < nr; i++)
        for (c = 0; c < 2 * nr; c++) A[i][c] = (c < nr) ? J[i][c] : (c - nr == i ? 1.0 : 0.0);
    for (c = 0; c < nr; c++) {
        uint32_t p = c;
        double t;
        for (i = c + 1; i < nr; i++)
            if (fabs(A[i][c]) > fabs(A[p][c])) p = i;
        if (A[p][c] == 0.0) return 1e9;
        for (k = 0; k < 2 * nr; k++) {
            t = A[c][k];
            A[c][k] = A[p][k];
            A[p][k] = t;
        }
        t = A[c][c];
        for (k = 0; k < 2 * nr; k++) A[c][k] /= t;
        for (i = 0; i < nr; i++)
            if (i != c) {
                t = A[i][c];
                for (k = 0; k < 2 * nr; k++) A[i][k] -= t * A[c][k];
            }
    }
    for (i = 0; i < nr; i++) { /* row i of J^-1: A[i][nr..2nr) */
        double sp = 0, sr = 0, bi;
        for (k = 0; k < 3; k++) sp += A[i][nr + k] * A[i][nr + k];
        for (k = 3; k < nr; k++) sr += A[i][nr + k] * A[i][nr + k];
        bi = sqrt(sp) * ep + sqrt(sr) * er;
        if (bi > b) b = bi;
    }
    return b;
}

/* the match bound of a float solution qs against qa (see match_bound) */
static double pair_bound(const dh_robot *r, const double *qa, const float *qs, double ep, double er)
{
    double qb[DHS_MAX_JOINTS], ba, bb;
    uint32_t i;
    for (i = 0; i < r->n; i++) qb[i] = (double)qs[i];
    ba = match_bound(r, qa, ep, er);
    bb = match_bound(r, qb, ep, er);
    return MATCH_SAFETY * (ba > bb ? ba : bb);
}

/* the rounding of the float target T of the exact frame with position p:
 * 2^-24 relative per coordinate, 2^-24 per rotation entry (|entry| <= 1,
 * so the rotation moves by at most its Frobenius norm, 3 x 2^-24 rad) */
static void target_rounding(const dh_mat4_f32 *T, double *rp, double *rr)
{
    double s = 0;
    int k;
    for (k = 0; k < 3; k++) s += (double)T->m[3][k] * (double)T->m[3][k];
    *rp = F32_EPS * sqrt(s);
    *rr = 3.0 * F32_EPS;
}

/* ---- completeness ----------------------------------------------------------- */

/* the smallest ratio, over the solutions, of the joint distance to q and
 * the pair's match bound: the end frame of solution s lies within
 * ep_s + rp, er_s + rr of FK(q) (its measured error to the float target
 * plus the target's rounding). *dist, *bound: those of the solution
 * attaining it */
static double nearest_ratio(const dh_robot *r, const dh_mat4_f32 *T, const dh_ikc_sol_f32 *sol,
                            uint32_t n, const double *q, double *dist, double *bound)
{
    double rp, rr, best = 1e30;
    uint32_t s;
    target_rounding(T, &rp, &rr);
    *dist = *bound = 1e9;
    for (s = 0; s < n; s++) {
        double ep, er, b, dd;
        dhs_true_error_f32(r, sol[s].q, T, &ep, &er);
        b = pair_bound(r, q, sol[s].q, ep + rp, er + rr);
        dd = sol_dist(r, sol[s].q, q);
        if (dd / b < best) {
            best = dd / b;
            *dist = dd;
            *bound = b;
        }
    }
    return best;
}

static void ikc_complete(void)
{
    unsigned ri;
    for (ri = 0; ri < N_ROBOTS; ri++) {
        const dhs_robot *d = g_robots[ri];
        dh_robot r;
        dh_ikc_model_f32 m;
        dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
        const float qref[NJ] = { 0 };
        double ep_max = 0, er_max = 0, worst = 0, worst_near = 0, ratio_max = 0;
        long it, n_it = DHT_ITER(10000), used = 0, derived = 0;
        build(d, &r, &m);
        for (it = 0; it < n_it; it++) {
            double q[DHS_MAX_JOINTS], best, sd;
            dh_mat4_f32 T;
            uint32_t n;
            dhs_random_q(d, q);
            sd = sing_dist(d, q);
            if (sd < 1e-2) continue;
            used++;
            target_of(&r, q, &T);
            n = solve(&r, &m, &T, qref, sol);
            DHT_TRUE_MSG(n >= 1u, "%s: no solution for q %s", d->name, q_str(q, r.n, 0));
            best = check_all(&r, &T, sol, n, q, d->name, &ep_max, &er_max);
            if (best > MATCH_FLOOR) {
                double dist, bound;
                const double ratio = nearest_ratio(&r, &T, sol, n, q, &dist, &bound);
                DHT_TRUE_MSG(ratio <= 1.0, "%s: generating q %s (singular distance %.3g) not among the %u "
                             "solutions (nearest %.3g deg, %.3g deg from the one within its derived bound %.3g deg)",
                             d->name, q_str(q, r.n, 0), sd, (unsigned)n, best, dist, bound);
                derived++;
                if (ratio > ratio_max) ratio_max = ratio;
            }
            if (sd < SING_FAR) {
                if (best > worst_near) worst_near = best;
            } else if (best > worst) {
                worst = best;
            }
        }
        dht_printf("%s: %ld targets, max error %.3g m %.3g rad, generating q within %.3g deg "
                   "(%.3g deg at singular distance 1e-2..%g); %ld beyond %g deg, distance / derived bound <= %.3g\n",
                   d->name, used, ep_max, er_max, worst, worst_near, SING_FAR, derived, MATCH_FLOOR, ratio_max);
    }
}

/* ---- singular cases ------------------------------------------------------- */

/* solve, check every solution's FK; returns n and ORs the flags */
static uint32_t solve_check(const dh_robot *r, const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *qref,
                            const double *q, const char *what, uint32_t *flags_or, double *best)
{
    dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
    double ep = 0, er = 0;
    uint32_t n = solve(r, m, T, qref, sol), s;
    *flags_or = 0;
    DHT_TRUE_MSG(n >= 1u, "%s: no solution for q %s", what, q_str(q, r->n, 0));
    for (s = 0; s < n; s++) *flags_or |= sol[s].flags;
    *best = check_all(r, T, sol, n, q, what, &ep, &er);
    return n;
}

/* UR with q5 = 0 or 180: wrist singular, joint 6 taken from q_ref; with
 * qref6 = the generating q6 the generating configuration is found. */
static void ikc_ur_wrist_singular(void)
{
    unsigned ri;
    for (ri = 0; ri < 3u; ri++) {
        const dhs_robot *d = g_robots[ri];
        dh_robot r;
        dh_ikc_model_f32 m;
        long it;
        build(d, &r, &m);
        for (it = 0; it < DHT_ITER(500); it++) {
            double q[DHS_MAX_JOINTS], best;
            float qref[NJ] = { 0 };
            dh_mat4_f32 T;
            uint32_t n, fl;
            double part[3];
            dhs_random_q(d, q);
            q[4] = (it & 1) ? 180.0 : 0.0;
            (void)sing_parts(d, q, part);
            if (part[0] < SING_FAR || part[1] < SING_FAR) continue; /* only the wrist singular */
            qref[5] = (float)(q[5] - 360.0 * floor((q[5] + 180.0) / 360.0));
            target_of(&r, q, &T);
            n = solve_check(&r, &m, &T, qref, q, d->name, &fl, &best);
            DHT_TRUE_MSG((fl & DH_IKC_SING_WRIST) != 0u, "%s: q5 = %g not flagged wrist singular", d->name, q[4]);
            /* the singular shoulder branch gives 2 (one per elbow), the other at most 4 */
            DHT_TRUE_MSG(n <= 6u, "%s: %u solutions at a wrist singularity", d->name, (unsigned)n);
            DHT_TRUE_MSG(best <= 1e-2, "%s: q %s not found with qref6 = q6 (nearest %.3g deg)", d->name,
                         q_str(q, r.n, 0), best);
        }
    }
}

/* q[1] and q[3] of a UR configuration moved, keeping q[2] and
 * phi = q2 + q3 + q4, so that the planar x of the joint 5 point,
 * a2 c2 + a3 c23 + e5 sin(phi), is u0 (the elbow solution of sign sgn);
 * 0 when no such q[1] exists */
static int put_u(const dhs_robot *d, double *q, double u0, int sgn)
{
    const double a2 = d->j[1].a, a3 = d->j[2].a, e5 = d->j[4].d; /* sb = +1 for UR */
    const double phi = (q[1] + q[2] + q[3]) * D2R;
    const double X = a2 + a3 * cos(q[2] * D2R), Y = a3 * sin(q[2] * D2R), R = sqrt(X * X + Y * Y);
    const double c = u0 - e5 * sin(phi);
    if (fabs(c) >= R) return 0;
    q[1] = (-atan2(Y, X) + sgn * acos(c / R)) / D2R;
    q[3] = phi / D2R - q[1] - q[2];
    return 1;
}

/* UR with the joint 5 point on the cylinder |u| = 0 (the two shoulder
 * branches meet): flagged, FK-correct, returned once */
static void ikc_ur_shoulder_singular(void)
{
    unsigned ri;
    for (ri = 0; ri < 3u; ri++) {
        const dhs_robot *d = g_robots[ri];
        dh_robot r;
        dh_ikc_model_f32 m;
        long it;
        int found = 0;
        build(d, &r, &m);
        for (it = 0; it < DHT_ITER(500); it++) {
            double q[DHS_MAX_JOINTS], best;
            const float qref[NJ] = { 0 };
            dh_mat4_f32 T;
            uint32_t n, fl;
            dhs_random_q(d, q);
            if (!put_u(d, q, 0.0, (it & 1) ? 1 : -1)) continue;
            DHT_TRUE(sing_dist(d, q) < 1e-12);
            target_of(&r, q, &T);
            n = solve_check(&r, &m, &T, qref, q, d->name, &fl, &best);
            DHT_TRUE_MSG((fl & DH_IKC_SING_SHOULDER) != 0u, "%s: u = 0 not flagged shoulder singular (q %s)",
                         d->name, q_str(q, r.n, 0));
            DHT_TRUE_MSG(n <= 4u, "%s: %u solutions with the shoulder branches merged", d->name, (unsigned)n);
            found++;
        }
        DHT_TRUE(found > 0);
    }
}

/* The joint 5 point on the shoulder cylinder and the elbow within 0.05 deg
 * of stretched or folded: the rounding of the target turns the exact
 * joint 1 by up to sqrt(2 |h| e) / |h| (e the rounding), which the wrist
 * amplifies into the elbow's planar point; every such target is solved,
 * FK-correct. */
static void ikc_ur_corner(void)
{
    unsigned ri;
    for (ri = 0; ri < 3u; ri++) {
        const dhs_robot *d = g_robots[ri];
        dh_robot r;
        dh_ikc_model_f32 m;
        long it;
        int found = 0;
        build(d, &r, &m);
        for (it = 0; it < 20L * DHT_ITER(500) && found < DHT_ITER(500); it++) {
            double q[DHS_MAX_JOINTS], part[3], best;
            const float qref[NJ] = { 0 };
            dh_mat4_f32 T;
            uint32_t fl;
            dhs_random_q(d, q);
            q[2] = ((it & 2) ? 180.0 : 0.0) + dht_rand_uniform(-0.05, 0.05);
            if (!put_u(d, q, 0.0, (it & 1) ? 1 : -1)) continue;
            (void)sing_parts(d, q, part);
            if (part[2] < 0.05) continue;
            target_of(&r, q, &T);
            (void)solve_check(&r, &m, &T, qref, q, d->name, &fl, &best);
            found++;
        }
        DHT_TRUE(found > 0);
    }
}

/* As ikc_ur_corner with the joint 5 point 0.3 mm along +-x1 off the
 * shoulder cylinder (u = +-3e-4 m, set exactly in the double reference):
 * inside the float shoulder band of UR3 and UR5 (one branch) or just
 * outside it (UR10, two branches). The rounding of the float target
 * leaves joint 1 free by up to about 1e-3 rad there, which the wrist turns
 * into tenths of mm of the elbow's planar point; every such target is
 * solved, FK-correct. */
static void ikc_ur_corner_off(void)
{
    unsigned ri;
    for (ri = 0; ri < 3u; ri++) {
        const dhs_robot *d = g_robots[ri];
        dh_robot r;
        dh_ikc_model_f32 m;
        long it;
        int found = 0;
        build(d, &r, &m);
        for (it = 0; it < 20L * DHT_ITER(500) && found < DHT_ITER(500); it++) {
            double q[DHS_MAX_JOINTS], part[3], best, L = 0.0;
            const double u0 = (it & 4) ? 3e-4 : -3e-4;
            const float qref[NJ] = { 0 };
            dh_mat4_f32 T;
            uint32_t fl;
            unsigned j;
            for (j = 0; j < d->n; j++) L += fabs(d->j[j].a) + fabs(d->j[j].d);
            dhs_random_q(d, q);
            q[2] = ((it & 2) ? 180.0 : 0.0) + dht_rand_uniform(-0.05, 0.05);
            if (!put_u(d, q, u0, (it & 1) ? 1 : -1)) continue;
            (void)sing_parts(d, q, part);
            DHT_TRUE_MSG(fabs(part[0] * L - 3e-4) <= 1e-9, "%s: u = %.9g m, not 3e-4", d->name, part[0] * L);
            if (part[2] < 0.05) continue;
            target_of(&r, q, &T);
            (void)solve_check(&r, &m, &T, qref, q, d->name, &fl, &best);
            found++;
        }
        DHT_TRUE(found > 0);
    }
}

/* The float boundary bound of src/dh_ikc_ur.c: tol = 4e-7 L (L the sum of
 * the robot's |a| and |d|); solved within tol / 4 beyond the boundary (the
 * solver's own rounding takes up to about half of tol: UR10), refused
 * beyond 3 tol. The double parameters of the description
 * differ from the robot's stored float ones by up to 1e-8 m: the
 * reference points below are checked within 2e-8 m. */
#define UR_TOL_REL 4e-7

/* Stretched elbow with the wrist offset d5 in line with the arm (q3 = 0,
 * q4 = +-90, whichever puts the joint 5 point farther from the frame 1
 * origin): the joint 5 point on the sphere of the largest reach, beyond
 * which no configuration puts it. The target moved outward by tol / 4:
 * solved, elbow flagged, FK-correct; by 4 tol: DH_ERR_UNREACHABLE. The
 * joint 5 point on the shoulder cylinder (u = 0) moved into it by tol / 4:
 * solved, shoulder flagged; by 4 tol: DH_ERR_UNREACHABLE. */
static void ikc_ur_beyond(void)
{
    unsigned ri;
    for (ri = 0; ri < 3u; ri++) {
        const dhs_robot *d = g_robots[ri];
        const double a2 = d->j[1].a, a3 = d->j[2].a, e5 = d->j[4].d; /* sb = +1 for UR */
        const double h = d->j[1].d + d->j[2].d + d->j[3].d;
        dh_robot r;
        dh_ikc_model_f32 m;
        dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
        double L = 0.0;
        long it, n[2] = { 0, 0 };
        unsigned j;
        for (j = 0; j < d->n; j++) L += fabs(d->j[j].a) + fabs(d->j[j].d);
        build(d, &r, &m);
        for (it = 0; it < 20L * DHT_ITER(200) && (n[0] < DHT_ITER(200) || n[1] < DHT_ITER(200)); it++) {
            const int cyl = (int)(it & 1);
            const float qref[NJ] = { 0 };
            double q[DHS_MAX_JOINTS], part[3], e[3], Rr, best = -1.0, ez = 0.0, sh;
            dhr_mat4 F[DHS_MAX_JOINTS], Td, Ts;
            dh_mat4_f32 T;
            uint32_t fl, ns, k;
            int i;
            if (n[cyl] >= DHT_ITER(200)) continue;
            dhs_random_q(d, q);
            if (!cyl) {
                q[2] = 0.0;
                for (k = 0; k < 2u; k++) {
                    double qt[DHS_MAX_JOINTS];
                    memcpy(qt, q, sizeof qt);
                    qt[3] = k ? -90.0 : 90.0;
                    dhs_fk_ref_f32(&r, qt, F, NULL);
                    for (i = 0; i < 3; i++) e[i] = F[4].m[3][i] - F[0].m[3][i];
                    Rr = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
                    if (Rr > best) {
                        best = Rr;
                        q[3] = qt[3];
                    }
                }
            } else {
                double X, Y, c, phi;
                phi = (q[1] + q[2] + q[3]) * D2R;
                X = a2 + a3 * cos(q[2] * D2R);
                Y = a3 * sin(q[2] * D2R);
                Rr = sqrt(X * X + Y * Y);
                c = -e5 * sin(phi);
                if (fabs(c) >= Rr) continue;
                q[1] = (-atan2(Y, X) + ((it & 2) ? 1 : -1) * acos(c / Rr)) / D2R;
                q[3] = phi / D2R - q[1] - q[2];
            }
            (void)sing_parts(d, q, part);
            if (part[2] < 0.1 || (cyl ? part[1] < 0.1 : part[0] < 0.05)) continue;
            dhs_fk_ref_f32(&r, q, F, &Td);
            if (!cyl) {
                /* outward from the frame 1 origin */
                for (i = 0; i < 3; i++) e[i] = F[4].m[3][i] - F[0].m[3][i];
                Rr = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
                DHT_TRUE_MSG(fabs(Rr - sqrt((fabs(a2) + fabs(a3) + fabs(e5)) * (fabs(a2) + fabs(a3) + fabs(e5)) + h * h)) <=
                                 2e-8,
                             "%s: joint 5 point at %.9g from the frame 1 origin", d->name, Rr);
                sh = 1.0;
            } else {
                /* from axis 1 (base z through the base origin) to the joint 5 point, inward */
                for (i = 0; i < 3; i++) {
                    e[i] = F[4].m[3][i] - d->base.m[3][i];
                    ez += e[i] * d->base.m[2][i];
                }
                for (i = 0; i < 3; i++) e[i] -= ez * d->base.m[2][i];
                Rr = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
                DHT_TRUE_MSG(fabs(Rr - fabs(h)) <= 2e-8, "%s: joint 5 point at %.9g from axis 1, |h| = %.9g",
                             d->name, Rr, fabs(h));
                sh = -1.0;
            }
            for (i = 0; i < 3; i++) e[i] /= Rr;
            Ts = Td;
            for (i = 0; i < 3; i++) Ts.m[3][i] += sh * 0.25 * UR_TOL_REL * L * e[i];
            to_f32(&Ts, &T);
            (void)solve_check(&r, &m, &T, qref, q, d->name, &fl, &best);
            DHT_TRUE_MSG((fl & (cyl ? DH_IKC_SING_SHOULDER : DH_IKC_SING_ELBOW)) != 0u,
                         "%s: tol / 4 beyond the %s not flagged (q %s)", d->name, cyl ? "shoulder cylinder" : "reach",
                         q_str(q, r.n, 0));
            Ts = Td;
            for (i = 0; i < 3; i++) Ts.m[3][i] += sh * 4.0 * UR_TOL_REL * L * e[i];
            to_f32(&Ts, &T);
            ns = 99u;
            DHT_TRUE_MSG(dh_ikc_f32(&m, &T, qref, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &ns) == DH_ERR_UNREACHABLE &&
                             ns == 0u,
                         "%s: 4 tol beyond the %s: %u solutions (q %s)", d->name,
                         cyl ? "shoulder cylinder" : "reach", (unsigned)ns, q_str(q, r.n, 0));
            n[cyl]++;
        }
        DHT_TRUE(n[0] > 0 && n[1] > 0);
    }
}

/* stretched or folded elbow: UR q3 = 0 / 180, SCARA q2 = 0 */
static void ikc_elbow_singular(void)
{
    unsigned ri;
    for (ri = 0; ri < N_ROBOTS; ri++) {
        const dhs_robot *d = g_robots[ri];
        dh_robot r;
        dh_ikc_model_f32 m;
        long it;
        build(d, &r, &m);
        for (it = 0; it < DHT_ITER(500); it++) {
            double q[DHS_MAX_JOINTS], best;
            const float qref[NJ] = { 0 };
            dh_mat4_f32 T;
            uint32_t n, fl, j = (d->n == 4u) ? 1u : 2u;
            double part[3];
            dhs_random_q(d, q);
            q[j] = (d->n == 6u && (it & 1)) ? 180.0 : 0.0;
            (void)sing_parts(d, q, part);
            if (part[0] < SING_FAR || part[2] < SING_FAR) continue; /* only the elbow singular */
            target_of(&r, q, &T);
            n = solve_check(&r, &m, &T, qref, q, d->name, &fl, &best);
            DHT_TRUE_MSG((fl & DH_IKC_SING_ELBOW) != 0u, "%s: q%u = %g not flagged elbow singular (q %s)", d->name,
                         (unsigned)j + 1u, q[j], q_str(q, r.n, 0));
            /* UR: the stretched branch once, its wrist flip and the other shoulder up to 2 + 4 */
            DHT_TRUE_MSG(n <= (d->n == 4u ? 1u : 7u), "%s: %u solutions with the elbow stretched", d->name,
                         (unsigned)n);
        }
    }
}

/* ---- unreachable ------------------------------------------------------------- */

static void ikc_unreachable(void)
{
    unsigned ri;
    for (ri = 0; ri < N_ROBOTS; ri++) {
        const dhs_robot *d = g_robots[ri];
        dh_robot r;
        dh_ikc_model_f32 m;
        dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
        const float qref[NJ] = { 0 };
        double q[DHS_MAX_JOINTS];
        dh_mat4_f32 T;
        long it;
        uint32_t n;
        build(d, &r, &m);
        for (it = 0; it < DHT_ITER(200); it++) {
            double L = 0, sc, rxy;
            unsigned i;
            for (i = 0; i < d->n; i++) L += fabs(d->j[i].a) + fabs(d->j[i].d);
            dhs_random_q(d, q);
            target_of(&r, q, &T);
            /* beyond the reach: the horizontal position moved out to 1.2 .. 5 L */
            rxy = sqrt((double)T.m[3][0] * T.m[3][0] + (double)T.m[3][1] * T.m[3][1]);
            sc = dht_rand_uniform(1.2, 5.0) * L / (rxy > 1e-3 ? rxy : 1e-3);
            T.m[3][0] = (float)(T.m[3][0] * sc);
            T.m[3][1] = (float)(T.m[3][1] * sc);
            n = solve(&r, &m, &T, qref, sol);
            DHT_TRUE_MSG(n == 0u, "%s: %u solutions for the unreachable p = (%g, %g, %g)", d->name, (unsigned)n,
                         (double)T.m[3][0], (double)T.m[3][1], (double)T.m[3][2]);
        }
        if (d->n == 4u) {
            /* SCARA: a tool axis not parallel to the joint axes */
            dh_mat4_f32 Rx, T2;
            dhs_random_q(d, q);
            target_of(&r, q, &T);
            DHT_EQ_INT(dh_mat4_rotx_f32(0.01f, &Rx), DH_OK);
            dh_mat4_mul_f32(&T, &Rx, &T2);
            T = T2;
            DHT_EQ_INT(solve(&r, &m, &T, qref, sol), 0);
        }
    }
}

/* ---- numerical IK finds nothing the closed form misses ------------------- */

/* A dh_ik_f32 result qn (error ep, er to the float target, measured in
 * double) counts as closed-form solution s (error ep_s, er_s) when their
 * joint distance is within MATCH_FLOOR or else within pair_bound(qn, s,
 * ep + ep_s, er + er_s): both end frames lie within their errors of the
 * target. The solver stops at tol_pos 1e-6 L and tol_rot 1e-5 rad (the
 * test keeps ep <= 1e-5 m, er <= 1e-4 rad); near the wrist singularity
 * J^-1 maps its error of about 1e-6 m to tenths of a degree. */

/* the smallest distance / derived bound over the closed-form solutions
 * (out-of-limit ones only as limit twins of qo) */
static double numerical_ratio(const dh_robot *r, const dh_mat4_f32 *T, const dh_ikc_sol_f32 *sol, uint32_t n,
                              const float *qo, double ep, double er, double *bound)
{
    double qn[DHS_MAX_JOINTS], ratio = 1e30;
    uint32_t i, s;
    for (i = 0; i < r->n; i++) qn[i] = (double)qo[i];
    *bound = 1e9;
    for (s = 0; s < n; s++) {
        double eps, ers, bd, dd = sol_dist(r, sol[s].q, qn);
        dhs_true_error_f32(r, sol[s].q, T, &eps, &ers);
        bd = pair_bound(r, qn, sol[s].q, ep + eps, er + ers);
        if ((sol[s].flags & DH_IKC_OUT_OF_LIMITS) != 0u && !dhs_limit_twin_f32(r, sol[s].q, qo, bd, bd * 1e-3))
            continue;
        if (dd / bd < ratio) {
            ratio = dd / bd;
            *bound = bd;
        }
    }
    return ratio;
}

static void ikc_vs_numerical(void)
{
    static float work[DH_IK_WORK_FLOATS(DH_MAX_JOINTS)];
    unsigned ri;
    for (ri = 0; ri < N_ROBOTS; ri++) {
        const dhs_robot *d = g_robots[ri];
        dh_robot r;
        dh_ikc_model_f32 m;
        dh_ik_params p;
        long it, st_n, conv = 0, near = 0, derived = 0;
        double worst = 0, ratio_max = 0;
        build(d, &r, &m);
        dh_ik_params_default(&r, &p);
        p.restarts = 0;
        p.max_iter = 60;
        if (d->n == 4u) p.mask = DH_IK_POSITION | DH_IK_RZ;
        for (it = 0; it < DHT_ITER(1000); it++) {
            double q[DHS_MAX_JOINTS];
            dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
            const float qref[NJ] = { 0 };
            dh_mat4_f32 T;
            uint32_t n;
            dhs_random_q(d, q);
            target_of(&r, q, &T);
            n = solve(&r, &m, &T, qref, sol);
            DHT_TRUE(n >= 1u);
            /* out-of-limit solutions kept: dh_ik_f32 stops on or just inside
             * a limit, where the closed form's solution may lie beyond it
             * (matched only then, as the limit twin of the numerical result) */
            DHT_EQ_INT(dh_ikc_f32(&m, &T, qref, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &n), DH_OK);
            for (st_n = 0; st_n < DHT_ITER(200); st_n++) {
                double q0d[DHS_MAX_JOINTS], qn[DHS_MAX_JOINTS], best = 1e9, ep, er;
                float q0[DHS_MAX_JOINTS], qo[DHS_MAX_JOINTS];
                dh_ik_result res;
                uint32_t i, s;
                dhs_random_q(d, q0d);
                for (i = 0; i < r.n; i++) q0[i] = (float)q0d[i];
                if (dh_ik_f32(&r, &T, q0, &p, work, sizeof work / sizeof work[0], qo, &res) != DH_OK) continue;
                dhs_true_error_f32(&r, qo, &T, &ep, &er);
                if (ep > 1e-5 || er > 1e-4) continue;
                for (i = 0; i < r.n; i++) qn[i] = (double)qo[i];
                if (sing_dist(d, qn) < 1e-2) { /* the solution set is flat there: joint distance says little */
                    near++;
                    continue;
                }
                for (s = 0; s < n; s++) {
                    double dd = sol_dist(&r, sol[s].q, qn);
                    if ((sol[s].flags & DH_IKC_OUT_OF_LIMITS) != 0u &&
                        !dhs_limit_twin_f32(&r, sol[s].q, qo, MATCH_FLOOR, MATCH_FLOOR * 1e-3))
                        continue;
                    if (dd < best) best = dd;
                }
                if (best > MATCH_FLOOR) {
                    double bound;
                    const double ratio = numerical_ratio(&r, &T, sol, n, qo, ep, er, &bound);
                    derived++;
                    if (ratio > ratio_max) ratio_max = ratio;
                    DHT_TRUE_MSG(ratio <= 1.0, "%s: numerical solution %s (error %.3g m %.3g rad) not among the %u "
                                 "closed-form ones (nearest %.3g deg, distance / derived bound %.3g, bound %.3g deg); "
                                 "target q %s", d->name, q_str(qn, r.n, 0), ep, er, (unsigned)n, best, ratio, bound,
                                 q_str(q, r.n, 1));
                }
                conv++;
                if (best > worst) worst = best;
            }
        }
        dht_printf("%s: %ld converged numerical solutions, all among the closed-form ones (nearest within %.3g "
                   "deg; %ld beyond %g deg, distance / derived bound <= %.3g; not compared: %ld within 1e-2 of a "
                   "singularity)\n", d->name, conv, worst, derived, MATCH_FLOOR, ratio_max, near);
    }
}

/* ---- frames, conventions, limits, statuses ------------------------------- */

/* completeness and FK of one description (any base, tool, convention);
 * sdh: a standard-DH description of the same chain, for the singular distance */
static void complete_desc(const dhs_robot *d, const dhs_robot *sdh, long count)
{
    dh_robot r;
    dh_ikc_model_f32 m;
    dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
    double ep_max = 0, er_max = 0, worst = 0;
    long it, used = 0;
    build(d, &r, &m);
    for (it = 0; it < count; it++) {
        double q[DHS_MAX_JOINTS], best;
        dh_mat4_f32 T;
        uint32_t n;
        dhs_random_q(d, q);
        if (sing_dist(sdh, q) < SING_FAR) continue;
        used++;
        target_of(&r, q, &T);
        n = solve(&r, &m, &T, NULL, sol);
        DHT_TRUE_MSG(n >= 1u, "%s: no solution for q %s", d->name, q_str(q, r.n, 0));
        best = check_all(&r, &T, sol, n, q, d->name, &ep_max, &er_max);
        DHT_TRUE_MSG(best <= 1e-3, "%s: generating q %s not among the %u solutions (nearest %.3g deg)", d->name,
                     q_str(q, r.n, 0), (unsigned)n, best);
        if (best > worst) worst = best;
    }
    dht_printf("%s: %ld targets, max error %.3g m %.3g rad, generating q within %.3g deg\n", d->name, used, ep_max,
               er_max, worst);
}

/* a rigid frame from a random rotation vector and translation (double) */
static void random_frame(dhr_mat4 *F, double tmax)
{
    dhr_mat4 A, B;
    dhr_rotz(dht_rand_uniform(-180, 180), &A);
    dhr_rotx(dht_rand_uniform(-180, 180), &B);
    dhr_mul(&A, &B, F);
    dhr_rotz(dht_rand_uniform(-180, 180), &A);
    dhr_mul(F, &A, F);
    F->m[3][0] = dht_rand_uniform(-tmax, tmax);
    F->m[3][1] = dht_rand_uniform(-tmax, tmax);
    F->m[3][2] = dht_rand_uniform(-tmax, tmax);
}

/* frames rounded to float and back, so that the description and the
 * float robot hold the same rigid frame */
static void frame_f32(dhr_mat4 *F)
{
    int c, k;
    for (c = 0; c < 4; c++)
        for (k = 0; k < 4; k++) F->m[c][k] = (double)(float)F->m[c][k];
}

static void ikc_ur_base_tool(void)
{
    unsigned ri;
    for (ri = 0; ri < N_ROBOTS; ri++) {
        dhs_robot d = *g_robots[ri];
        random_frame(&d.base, 0.5);
        random_frame(&d.tool, 0.15);
        frame_f32(&d.base);
        frame_f32(&d.tool);
        if (d.n == 4u) {
            /* SCARA: a base and tool about the joint axes keep the tool axis reachable */
            dhr_rotz(dht_rand_uniform(-180, 180), &d.tool);
            d.tool.m[3][0] = 0.05;
            d.tool.m[3][2] = -0.1;
            frame_f32(&d.tool);
        }
        complete_desc(&d, &d, DHT_ITER(2000));
    }
}

/* UR5 in modified DH: joint i takes the twist and length of SDH joint
 * i - 1 (Tx(a) Rx(alpha) = Rx(alpha) Tx(a)); SDH joint 6's (0, 0) drops out */
static void ikc_ur5_mdh(void)
{
    dhs_robot d = dhs_ur5_m;
    unsigned i;
    d.name = "ur5 (modified DH)";
    d.conv = DH_CONV_MODIFIED;
    for (i = d.n - 1u; i >= 1u; i--) {
        d.j[i].a = d.j[i - 1u].a;
        d.j[i].alpha_deg = d.j[i - 1u].alpha_deg;
    }
    d.j[0].a = 0.0;
    d.j[0].alpha_deg = 0.0;
    /* the conversion is exact: same FK as the SDH table */
    {
        double q[DHS_MAX_JOINTS];
        dhr_mat4 A, B;
        int c, k;
        dhs_random_q(&d, q);
        dhs_fk_desc(&d, q, NULL, &A);
        dhs_fk_desc(&dhs_ur5_m, q, NULL, &B);
        for (c = 0; c < 4; c++)
            for (k = 0; k < 4; k++) DHT_NEAR(A.m[c][k], B.m[c][k], 1e-12);
    }
    complete_desc(&d, &dhs_ur5_m, DHT_ITER(2000));
    /* and with a base and a tool */
    random_frame(&d.base, 0.5);
    random_frame(&d.tool, 0.15);
    frame_f32(&d.base);
    frame_f32(&d.tool);
    {
        dhs_robot sdh = dhs_ur5_m;
        sdh.base = d.base;
        complete_desc(&d, &sdh, DHT_ITER(2000));
    }
}

/* limits: the Cobra's joints 1 and 2 (+-50, +-88) leave out the other elbow
 * for many targets; kept and flagged with DH_IKC_KEEP_OUT_OF_LIMITS */
static void ikc_limits(void)
{
    dh_robot r;
    dh_ikc_model_f32 m;
    long it, cut = 0;
    build(&dhs_cobra600_m, &r, &m);
    for (it = 0; it < DHT_ITER(2000); it++) {
        double q[DHS_MAX_JOINTS], ep = 0, er = 0;
        dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL], all[DH_IKC_MAX_SOL];
        dh_mat4_f32 T;
        uint32_t n = 0, na = 0, s, flagged = 0;
        dhs_random_q(&dhs_cobra600_m, q);
        target_of(&r, q, &T);
        n = solve(&r, &m, &T, NULL, sol);
        DHT_EQ_INT(dh_ikc_f32(&m, &T, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, all, &na), DH_OK);
        (void)check_all(&r, &T, all, na, q, "cobra600 kept", &ep, &er);
        for (s = 0; s < na; s++) flagged += (all[s].flags & DH_IKC_OUT_OF_LIMITS) ? 1u : 0u;
        DHT_EQ_INT(na - flagged, n);
        if (flagged) cut++;
    }
    DHT_TRUE(cut > 0);
    /* every solution out of the limits: DH_ERR_LIMIT */
    {
        double q[DHS_MAX_JOINTS] = { 40.0, 80.0, 0.1, 10.0 };
        dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
        dh_mat4_f32 T;
        uint32_t n = 7u;
        target_of(&r, q, &T);
        T.m[3][2] += 0.5f; /* joint 3 would have to go to 0.6 m (limit 0.21) */
        DHT_EQ_INT(dh_ikc_f32(&m, &T, NULL, 0u, sol, &n), DH_ERR_LIMIT);
        DHT_EQ_INT(n, 0);
        DHT_EQ_INT(dh_ikc_f32(&m, &T, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &n), DH_OK);
        DHT_TRUE(n >= 1u);
    }
}

/* statuses of unreachable targets */
static void ikc_unreachable_status(void)
{
    unsigned ri;
    for (ri = 0; ri < N_ROBOTS; ri++) {
        dh_robot r;
        dh_ikc_model_f32 m;
        dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
        dh_mat4_f32 T;
        double q[DHS_MAX_JOINTS];
        uint32_t n = 5u;
        build(g_robots[ri], &r, &m);
        dhs_random_q(g_robots[ri], q);
        target_of(&r, q, &T);
        T.m[3][0] += 10.0f;
        DHT_EQ_INT(dh_ikc_f32(&m, &T, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &n), DH_ERR_UNREACHABLE);
        DHT_EQ_INT(n, 0);
        if (r.n == 4u) {
            dh_mat4_f32 Rx, T2;
            target_of(&r, q, &T);
            DHT_EQ_INT(dh_mat4_rotx_f32(0.01f, &Rx), DH_OK);
            dh_mat4_mul_f32(&T, &Rx, &T2);
            n = 5u;
            DHT_EQ_INT(dh_ikc_f32(&m, &T2, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &n), DH_ERR_UNREACHABLE);
            DHT_EQ_INT(n, 0);
        }
    }
}

/* what is recognised: a twist off by 1 degree or a joint 5 length breaks
 * the family; signs and offsets keep it */
static void ikc_detect(void)
{
    dh_robot r;
    dh_ikc_model_f32 m;
    dhs_robot d = dhs_ur5_m;
    d.j[1].alpha_deg = 1.0;
    DHT_EQ_INT(dhs_build(&d, &r), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_f32(&r, &m), DH_ERR_UNAVAILABLE);
    DHT_EQ_INT(m.kind, DH_IKC_NONE);
    d = dhs_ur5_m;
    d.j[4].a = 0.01;
    DHT_EQ_INT(dhs_build(&d, &r), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_f32(&r, &m), DH_ERR_UNAVAILABLE);
    d = dhs_cobra600_m;
    d.j[1].alpha_deg = 179.0;
    DHT_EQ_INT(dhs_build(&d, &r), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_f32(&r, &m), DH_ERR_UNAVAILABLE);
    /* other signs, offsets and shoulder / wrist offsets: still the family, still complete */
    d = dhs_ur10_m;
    d.name = "ur10 (signs, offsets)";
    d.j[0].alpha_deg = -90.0;
    d.j[0].a = 0.05;
    d.j[1].alpha_deg = 180.0;
    d.j[2].d = 0.03;
    d.j[3].alpha_deg = -90.0;
    d.j[3].a = 0.02;
    d.j[4].alpha_deg = 90.0;
    d.j[1].theta_deg = 20.0;
    d.j[4].theta_deg = -90.0;
    d.j[5].a = 0.01;
    d.j[5].alpha_deg = 30.0;
    complete_desc(&d, &d, DHT_ITER(2000));
    d = dhs_cobra600_m;
    d.name = "cobra600 (signs, offsets)";
    d.j[0].alpha_deg = 180.0;
    d.j[1].alpha_deg = 0.0;
    d.j[2].a = 0.02;
    d.j[2].theta_deg = 30.0;
    d.j[2].qmin = -0.3;
    d.j[2].qmax = 0.3;
    d.j[3].d = 0.05;
    d.j[0].theta_deg = 15.0;
    complete_desc(&d, &d, DHT_ITER(2000));
}

/* not the family: each structural condition of the detectors broken on its
 * own (a twist 1 degree off, a length that must be zero made non-zero, a
 * length that must be non-zero made zero) */
static void not_family(const dhs_robot *d, dh_ikc_kind kind)
{
    dh_robot r;
    dh_ikc_model_f32 m;
    dh_status st;
    DHT_EQ_INT(dhs_build(d, &r), DH_OK);
    st = dh_ikc_analyse_f32(&r, &m);
    DHT_TRUE_MSG(st == DH_OK || st == DH_ERR_UNAVAILABLE, "%s: status %d", d->name, (int)st);
    DHT_TRUE_MSG(m.kind != kind, "%s: still recognised as kind %d", d->name, (int)kind);
}

static void ikc_detect_each(void)
{
    dhs_robot d;
    unsigned i;
    for (i = 0; i < 5u; i++) {
        d = dhs_ur5_m;
        d.name = "ur5, one twist 1 deg off";
        d.j[i].alpha_deg += 1.0;
        not_family(&d, DH_IKC_PARALLEL_234);
    }
    d = dhs_ur5_m;
    d.j[4].a = 0.01;
    not_family(&d, DH_IKC_PARALLEL_234);
    for (i = 1; i < 3u; i++) {
        d = dhs_ur5_m;
        d.name = "ur5, a2 or a3 zero";
        d.j[i].a = 0.0;
        not_family(&d, DH_IKC_PARALLEL_234);
    }
    for (i = 0; i < 3u; i++) {
        d = dhs_cobra600_m;
        d.name = "cobra600, one twist 1 deg off";
        d.j[i].alpha_deg += 1.0;
        not_family(&d, DH_IKC_SCARA);
    }
    d = dhs_cobra600_m;
    d.j[0].a = 0.0;
    not_family(&d, DH_IKC_SCARA);
    d = dhs_cobra600_m; /* the second link folded onto itself: a2 + a3 cos 180 = 0 */
    d.j[2].a = d.j[1].a;
    d.j[2].theta_deg = 180.0;
    not_family(&d, DH_IKC_SCARA);
    /* each twist sign on its own: still the family, still complete */
    for (i = 0; i < 5u; i++) {
        d = dhs_ur5_m;
        d.name = "ur5, one twist mirrored";
        d.j[i].alpha_deg = dhs_mirror_twist(d.j[i].alpha_deg);
        complete_desc(&d, &d, DHT_ITER(300));
    }
    for (i = 0; i < 3u; i++) {
        d = dhs_cobra600_m;
        d.name = "cobra600, one twist mirrored";
        d.j[i].alpha_deg = dhs_mirror_twist(d.j[i].alpha_deg);
        complete_desc(&d, &d, DHT_ITER(300));
    }
}

static const dht_case cases[] = {
    DHT_CASE(ikc_complete),
    DHT_CASE(ikc_ur_wrist_singular),
    DHT_CASE(ikc_ur_shoulder_singular),
    DHT_CASE(ikc_ur_corner),
    DHT_CASE(ikc_ur_corner_off),
    DHT_CASE(ikc_ur_beyond),
    DHT_CASE(ikc_elbow_singular),
    DHT_CASE(ikc_unreachable),
    DHT_CASE(ikc_vs_numerical),
    DHT_CASE(ikc_ur_base_tool),
    DHT_CASE(ikc_ur5_mdh),
    DHT_CASE(ikc_limits),
    DHT_CASE(ikc_unreachable_status),
    DHT_CASE(ikc_detect),
    DHT_CASE(ikc_detect_each),
};
DHT_MAIN(cases)
