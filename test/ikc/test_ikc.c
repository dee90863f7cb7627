/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_ikc.c - closed-form inverse kinematics, float (dh_ikc_analyse_f32,
 * dh_ikc_f32, dh_ikc_nearest_f32): the spherical-wrist families.
 *
 * Every solution is judged in double, independently of the library: its
 * float joint values go through the double reference FK of
 * support_robots.c (the robot's stored float parameters) and are compared
 * with the float target (the double FK of a random in-limit configuration,
 * rounded). Completeness: the generating configuration is among the
 * solutions, and the numerical solver dh_ik_f32 from random starts finds no
 * solution that the closed form misses. Singular, limit, unreachable,
 * MDH, base/tool, no-closed-form and bad-argument cases.
 */
#include "dht.h"
#include "support_robots.h"
#include "dhmath/ikc.h"
#include "dhmath/kin.h"
#include "dhmath/mat4.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define PI 3.14159265358979323846
#define D2R (PI / 180.0)
#define NJ 6

#define TOL_POS 2e-6 /* m */
#define TOL_ROT 2e-6 /* rad */
#define TOL_GEN 1e-3 /* deg (revolute) / 1e-5 m (prismatic): generating configuration found */

static float g_work[DH_IK_WORK_FLOATS(NJ)];

/* ---------------------------------------------------------------------- */

/* Largest joint difference between float solution s and q (revolute
 * joints modulo 360 deg). */
static double q_dist(const dh_robot *r, const float *s, const double *q)
{
    double w = 0.0;
    uint32_t i;
    for (i = 0; i < r->n; i++) w = fmax(w, dhs_joint_dist(r, i, s[i], q[i]));
    return w;
}

static int within_limits(const dh_robot *r, const float *q)
{
    uint32_t i;
    for (i = 0; i < r->n; i++) {
        const dh_joint *j = &r->joint[i];
        if (j->qmin <= j->qmax && ((double)q[i] < (double)j->qmin || (double)q[i] > (double)j->qmax)) return 0;
    }
    return 1;
}

/* Every solution: FK matches, the flags agree with the limits, revolute
 * values in limits where the robot has them. Returns the worst errors. */
static void check_solutions(const dh_robot *r, const dh_mat4_f32 *T, const dh_ikc_sol_f32 *sol, uint32_t n_sol,
                            const char *what, double *wp, double *wr)
{
    uint32_t s;
    for (s = 0; s < n_sol; s++) {
        double ep, er;
        dhs_true_error_f32(r, sol[s].q, T, &ep, &er);
        DHT_TRUE_MSG(ep <= TOL_POS && er <= TOL_ROT, "%s: solution %u (%s, flags 0x%x): position error %.3g m, rotation %.3g rad",
                     what, (unsigned)s, dhs_qf_str(sol[s].q, r->n, 0), (unsigned)sol[s].flags, ep, er);
        DHT_TRUE_MSG(((sol[s].flags & DH_IKC_OUT_OF_LIMITS) != 0u) == !within_limits(r, sol[s].q),
                     "%s: solution %u (%s) flags 0x%x disagree with the limits", what, (unsigned)s, dhs_qf_str(sol[s].q, r->n, 0),
                     (unsigned)sol[s].flags);
        if (ep > *wp) *wp = ep;
        if (er > *wr) *wr = er;
    }
}

/* The configuration is at least lim away from the singularities that the
 * solver treats specially, each distance normalised and squared as the
 * solver's radicand: sin^2 theta5 (wrist), sin^2(theta3 - atan2(sin alpha3
 * d4, a3)) (elbow, RRR: (D^2 - K'^2) / D^2) and (u / reach)^2 with u the
 * shoulder's square root (wrist centre rotated back by theta1), all from
 * the double description. Near these the joint values of the exact
 * solution of the float-rounded target move by the rounding over the
 * distance (e.g. 6e-8 m / (2 a2 rho sin psi) rad at the elbow), so
 * 1e-3 deg needs the normalised radicands, not the plain angles, >= 2e-2
 * (near two of them at once the amplifications multiply). */
static int away_from(const dhs_robot *d, const double *q, double lim)
{
    dhr_mat4 F[DHS_MAX_JOINTS];
    double t5 = (q[4] + d->j[4].theta_deg) * D2R, x, y, reach = 0.0;
    unsigned i;
    if (sin(t5) * sin(t5) < lim) return 0;
    for (i = 0; i < d->n; i++) reach += fabs(d->j[i].a) + fabs(d->j[i].d);
    if (d->j[2].type == DH_JOINT_REVOLUTE) {
        const double phi = atan2(sin(d->j[2].alpha_deg * D2R) * d->j[3].d, d->j[2].a);
        const double se = sin((q[2] + d->j[2].theta_deg) * D2R - phi);
        if (se * se < lim) return 0;
    }
    dhs_fk_desc(d, q, F, NULL);
    /* wrist centre: origin of frame 5 (a5 = d5 = 0) in the base frame; the
     * shipped robots have an identity base */
    x = F[4].m[3][0];
    y = F[4].m[3][1];
    /* rotated back by theta1 the wrist centre is (u, -h tau): the two
     * shoulder branches meet at u = 0 */
    {
        const double c = cos((q[0] + d->j[0].theta_deg) * D2R), s = sin((q[0] + d->j[0].theta_deg) * D2R);
        const double u = (c * x + s * y) / reach;
        if (u * u < lim) return 0;
    }
    return 1;
}

static int away_from_singular(const dhs_robot *d, const double *q) { return away_from(d, q, 2e-2); }

typedef struct {
    const char *name;
    const dhs_robot *desc;
    dh_ikc_kind kind;
} robot_case;

static const robot_case g_robots[] = {
    { "puma560", &dhs_puma560_m, DH_IKC_WRIST_RRR },
    { "kuka_kr5", &dhs_kuka_kr5_m, DH_IKC_WRIST_RRR },
    { "abb_irb140", &dhs_abb_irb140_m, DH_IKC_WRIST_RRR },
    { "stanford", &dhs_stanford_m, DH_IKC_WRIST_RRP },
};
#define N_ROBOTS (sizeof g_robots / sizeof g_robots[0])

/* 1 when a joint of q lies within TOL_GEN of one of its limits */
static int near_limit_f32(const dh_robot *r, const double *q)
{
    uint32_t i;
    for (i = 0; i < r->n; i++) {
        const dh_joint *j = &r->joint[i];
        if (j->qmin <= j->qmax && (fabs(q[i] - j->qmin) <= TOL_GEN || fabs(q[i] - j->qmax) <= TOL_GEN)) return 1;
    }
    return 0;
}

/* dh_ikc_f32 on the target T of the in-limit configuration q. A joint of
 * q within TOL_GEN of its limit, or q within the singular bands of
 * ikc.h (the elbow's 5e-7 L holds the Puma's configurations within
 * 0.13 deg of stretched; sin^2 < 1e-5 covers them), where the solution's
 * joints differ from q's by more than a rounding: the solution may lie
 * beyond a limit; DH_ERR_LIMIT then solves again keeping out-of-limit
 * solutions (counted in *nedge). */
static dh_status solve_target(const dh_ikc_model_f32 *m, const dh_robot *r, const dhs_robot *desc, const double *q,
                              const dh_mat4_f32 *T, dh_ikc_sol_f32 *sol, uint32_t *n_sol, long *nedge)
{
    dh_status st = dh_ikc_f32(m, T, NULL, 0u, sol, n_sol);
    if (st == DH_ERR_LIMIT && (near_limit_f32(r, q) || !away_from(desc, q, 1e-5))) {
        st = dh_ikc_f32(m, T, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, sol, n_sol);
        (*nedge)++;
    }
    return st;
}

/* count random in-limit configurations of r: every solution checked; the
 * generating one found when away from the singularities. Reach probes:
 * "<name>.elbow_deg", the nearest a configuration came to the stretched or
 * folded elbow (deg), and "edge.<name>", the targets solved beyond a limit. */
static void run_completeness(const char *name, const dhs_robot *desc, const dh_robot *r, const dh_ikc_model_f32 *m,
                             long count)
{
    long t, checked = 0, nsum = 0, nedge = 0;
    double wp = 0.0, wr = 0.0, wq = 0.0;
    char probe[40];
    snprintf(probe, sizeof probe, "%s.elbow_deg", name);
    for (t = 0; t < count; t++) {
        double q[NJ], best = 1e30;
        dh_mat4_f32 T;
        dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
        uint32_t n_sol = 99u, s;
        dh_status st;
        dhs_random_q_robot(r, q);
        if (desc->j[2].type == DH_JOINT_REVOLUTE) /* from stretched or folded */
            dht_reach_min(probe, fabs(remainder(q[2] + desc->j[2].theta_deg -
                                                atan2(sin(desc->j[2].alpha_deg * D2R) * desc->j[3].d, desc->j[2].a) / D2R,
                                                180.0)));
        dhs_target_f32(r, q, &T);
        st = solve_target(m, r, desc, q, &T, sol, &n_sol, &nedge);
        DHT_TRUE_MSG(n_sol <= DH_IKC_MAX_SOL, "%s: %u solutions", name, (unsigned)n_sol);
        DHT_TRUE_MSG(st == DH_OK && n_sol >= 1u, "%s: q = %s: status %d, %u solutions", name, dhs_q_str(q, r->n, 0),
                     (int)st, (unsigned)n_sol);
        check_solutions(r, &T, sol, n_sol, name, &wp, &wr);
        nsum += (long)n_sol;
        (void)desc;
        if (!away_from_singular(desc, q)) continue;
        checked++;
        for (s = 0; s < n_sol; s++) {
            double dq = q_dist(r, sol[s].q, q);
            if (dq < best) best = dq;
        }
        DHT_TRUE_MSG(best <= TOL_GEN, "%s: q = %s not among the %u solutions (nearest %.3g deg away; first %s)", name,
                     dhs_q_str(q, r->n, 0), (unsigned)n_sol, best, dhs_qf_str(sol[0].q, r->n, 1));
        if (best > wq) wq = best;
    }
    snprintf(probe, sizeof probe, "edge.%s", name);
    dht_reach_max(probe, (double)nedge);
    dht_printf("ikc %s: %ld targets (%ld checked for the generating configuration), mean %.2f solutions, worst "
               "position %.3g m, rotation %.3g rad, generating configuration within %.3g; %ld within it of a "
               "limit or a singularity, solved beyond a limit\n",
               name, count, checked, (double)nsum / (double)count, wp, wr, wq, nedge);
}

static void ikc_completeness(void)
{
    unsigned k;
    for (k = 0; k < N_ROBOTS; k++) {
        dh_robot r;
        dh_ikc_model_f32 m;
        DHT_EQ_INT(dhs_build(g_robots[k].desc, &r), DH_OK);
        DHT_EQ_INT(dh_ikc_analyse_f32(&r, &m), DH_OK);
        DHT_EQ_INT(m.kind, g_robots[k].kind);
        DHT_EQ_INT(m.why, DH_IKC_WHY_NONE);
        run_completeness(g_robots[k].name, g_robots[k].desc, &r, &m, DHT_ITER(10000));
    }
}

/* How far the float results of the two solvers for one solution lie
 * apart: the closed form's float rounding (within TOL_GEN of the exact
 * solution, asserted above) plus dh_ik_f32's stop anywhere within its
 * tolerances (1e-5 rad, 1e-6 L), which the wrist's conditioning at the
 * test's distance from the singularities magnifies in a joint. Measured:
 * at most 5.5e-3 deg and 3e-7 m over 1.3 M converged results (the four
 * robots, seeds 0x90b0f7f3, 1, 2, 3). Within this distance a limit can
 * fall between them: dh_ik_f32 stops on the inner side (or exactly on the
 * limit, where it clamps) and the closed form's twin lies beyond it. */
#define LIMIT_SLACK_DEG 1e-2
#define LIMIT_SLACK_M 1e-5


/* Distance (deg) within which a dh_ik_f32 result matches a closed-form
 * solution */
#define MATCH_DEG 0.05

/* q_dist of a dh_ik_f32 result y from a closed-form solution c, where
 * joints 4 and 6 count only beyond what the solver's orientation tolerance
 * leaves open near the wrist singularity: stopped within tol_rot, y's
 * joints 4 and 6 may each be off by up to tol_rot / |sin t5| (only their
 * sum or difference is fixed at t5 = 0). Where that is not below
 * MATCH_DEG, the tolerance does not fix joints 4 and 6 one by one to the
 * match distance at all (the other joints take up part of a move along
 * the singular direction, so the open part may exceed tol_rot / |sin t5|):
 * there the combination the orientation fixes, q4 + sigma q6 (sigma =
 * cos(alpha4 + alpha5): z6 = sigma z4 at t5 = 0), counts instead. */
static double wrist_dist(const dh_robot *r, const dh_ik_params_f32 *p, const float *c, const double *y)
{
    const double s5 = fabs(sin((y[4] + (double)r->joint[4].theta_deg) * D2R));
    const double open = (double)p->tol_rot / D2R / fmax(s5, 1e-9);
    const double sigma = (cos(((double)r->joint[3].alpha_deg + (double)r->joint[4].alpha_deg) * D2R) > 0.0) ? 1.0 : -1.0;
    double w = 0.0, comb;
    uint32_t i;
    for (i = 0; i < r->n; i++) {
        const double d = dhs_joint_dist(r, i, c[i], y[i]);
        if (i == 3u || i == 5u)
            w = fmax(w, (open < MATCH_DEG) ? fmax(d - open, 0.0) : 0.0);
        else
            w = fmax(w, d);
    }
    if (open >= MATCH_DEG) {
        comb = fmod(((double)c[3] + sigma * (double)c[5]) - (y[3] + sigma * y[5]), 360.0);
        if (comb > 180.0) comb -= 360.0;
        if (comb < -180.0) comb += 360.0;
        w = fmax(w, fabs(comb));
    }
    return w;
}

/* dh_ik_f32 from random starts (no restarts) on random targets: every
 * converged in-limit result is one of the closed-form solutions. Reach
 * probes: "numerical.<name>.s5", the smallest |sin theta5| of a converged
 * result, and "twins.<name>", the results matched to a twin beyond a limit. */
static void ikc_numerical_completeness(void)
{
    unsigned k;
    /* host: 1000 targets x 200 starts; targets (DHT_ITER divisor > 1):
     * fewer targets and 20 starts each */
    const long targets = DHT_ITER(1000), starts = (dht_iter_div() == 1) ? 200 : 20;
    for (k = 0; k < N_ROBOTS; k++) {
        dh_robot r;
        dh_ikc_model_f32 m;
        dh_ik_params_f32 p;
        long t, st_i, found = 0, conv = 0, twins = 0;
        char probe[40], probe_s5[40];
        snprintf(probe_s5, sizeof probe_s5, "numerical.%s.s5", g_robots[k].name);
        DHT_EQ_INT(dhs_build(g_robots[k].desc, &r), DH_OK);
        DHT_EQ_INT(dh_ikc_analyse_f32(&r, &m), DH_OK);
        dh_ik_params_default_f32(&r, &p);
        p.restarts = 0u;
        p.max_iter = 100u;
        for (t = 0; t < targets; t++) {
            double q[NJ];
            dh_mat4_f32 T;
            dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
            uint32_t n_sol = 0, s, hit = 0;
            dhs_random_q_robot(&r, q);
            if (!away_from_singular(g_robots[k].desc, q)) {
                t--;
                continue;
            }
            dhs_target_f32(&r, q, &T);
            /* out-of-limit solutions kept: dh_ik_f32 stops within its
             * tolerance on or just inside a limit, where the closed form's
             * solution may lie a rounding beyond it (matched only then, see
             * dhs_limit_twin_f32) */
            DHT_EQ_INT(dh_ikc_f32(&m, &T, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &n_sol), DH_OK);
            for (st_i = 0; st_i < starts; st_i++) {
                double q0d[NJ];
                float q0[NJ], qs[NJ];
                dh_ik_result_f32 res;
                uint32_t i;
                double best = 1e30;
                int twin = 0;
                dhs_random_q_robot(&r, q0d);
                for (i = 0; i < r.n; i++) q0[i] = (float)q0d[i];
                if (dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], qs, &res) != DH_OK) continue;
                conv++;
                dht_reach_min(probe_s5, fabs(sin(((double)qs[4] + (double)r.joint[4].theta_deg) * D2R)));
                for (s = 0; s < n_sol; s++) {
                    double dd[NJ], dq;
                    for (i = 0; i < r.n; i++) dd[i] = (double)qs[i];
                    dq = wrist_dist(&r, &p, sol[s].q, dd);
                    if ((sol[s].flags & DH_IKC_OUT_OF_LIMITS) != 0u &&
                        !dhs_limit_twin_f32(&r, sol[s].q, qs, LIMIT_SLACK_DEG, LIMIT_SLACK_M))
                        continue;
                    if (dq < best) {
                        best = dq;
                        twin = (sol[s].flags & DH_IKC_OUT_OF_LIMITS) != 0u;
                    }
                    if (dq <= MATCH_DEG) hit |= 1u << s;
                }
                DHT_TRUE_MSG(best <= MATCH_DEG, "%s: target of q = %s: dh_ik_f32 found %s, not among the %u closed-form "
                             "solutions (nearest %.3g away)", g_robots[k].name, dhs_q_str(q, r.n, 0),
                             dhs_qf_str(qs, r.n, 1), (unsigned)n_sol, best);
                if (twin) twins++;
            }
            for (s = 0; s < n_sol; s++)
                if ((hit >> s) & 1u) found++;
        }
        snprintf(probe, sizeof probe, "twins.%s", g_robots[k].name);
        dht_reach_max(probe, (double)twins);
        dht_printf("ikc %s: dh_ik_f32 from %ld starts on %ld targets: %ld converged, all among the closed-form "
                   "solutions (%ld distinct solutions met; %ld results on or just inside a limit matched a twin beyond it)\n",
                   g_robots[k].name, starts, targets, conv, found, twins);
    }
}

/* ---------------------------------------------------------------------- */
/* singular cases                                                          */

/* q5 = 0 on the Puma: one solution per arm branch, flagged, joint 4 kept
 * at q_ref's value, FK matching. */
static void ikc_wrist_singular(void)
{
    dh_robot r;
    dh_ikc_model_f32 m;
    long t;
    DHT_EQ_INT(dhs_build(&dhs_puma560_m, &r), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_f32(&r, &m), DH_OK);
    for (t = 0; t < DHT_ITER(200); t++) {
        double q[NJ], qr[NJ], wp = 0, wr = 0;
        float qref[NJ];
        dh_mat4_f32 T;
        dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
        uint32_t n_sol = 0, s, i, nsing = 0;
        dhs_random_q_robot(&r, q);
        q[4] = 30.0;
        if (!away_from(&dhs_puma560_m, q, 0.1)) {
            /* a well-conditioned arm: the float rounding of its angles
             * keeps axis 6 within 1e-6 rad of axis 4 */
            t--;
            continue;
        }
        q[4] = 0.0;
        dhs_random_q_robot(&r, qr);
        for (i = 0; i < 6u; i++) qref[i] = (float)qr[i];
        dhs_target_f32(&r, q, &T);
        DHT_EQ_INT(dh_ikc_f32(&m, &T, qref, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &n_sol), DH_OK);
        check_solutions(&r, &T, sol, n_sol, "puma wrist singular", &wp, &wr);
        for (s = 0; s < n_sol; s++) {
            if ((sol[s].flags & DH_IKC_SING_WRIST) == 0u) continue;
            nsing++;
            DHT_TRUE_MSG(sol[s].q[3] == qref[3], "wrist singular: q4 = %.9g, q_ref4 = %.9g", (double)sol[s].q[3],
                         (double)qref[3]);
        }
        /* the generating arm branch is singular (theta5 = 0 exactly) */
        DHT_TRUE_MSG(nsing >= 1u, "q = %s: no solution flagged wrist singular", dhs_q_str(q, 6u, 0));
        DHT_TRUE_MSG(n_sol <= 8u - nsing, "q = %s: %u solutions with %u singular ones", dhs_q_str(q, 6u, 0), (unsigned)n_sol, (unsigned)nsing);
    }
}

/* KUKA KR5 and ABB IRB140 (h = 0): the wrist centre on axis 1 (q2 found
 * by bisection on the double FK): joint 1 from q_ref, flagged. */
static void ikc_shoulder_singular(void)
{
    const dhs_robot *descs[2] = { &dhs_kuka_kr5_m, &dhs_abb_irb140_m };
    unsigned k;
    for (k = 0; k < 2u; k++) {
        dh_robot r;
        dh_ikc_model_f32 m;
        long t;
        DHT_EQ_INT(dhs_build(descs[k], &r), DH_OK);
        DHT_EQ_INT(dh_ikc_analyse_f32(&r, &m), DH_OK);
        for (t = 0; t < DHT_ITER(50); t++) {
            double q[NJ], lo, hi, flo, wp = 0, wr = 0;
            float qref[NJ] = { 0 };
            dhr_mat4 F[NJ];
            dh_mat4_f32 T;
            dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
            uint32_t n_sol = 0, s, it;
            int found = 0;
            dhs_random_q_robot(&r, q);
            q[0] = 0.0;
            /* x of the wrist centre (y is -h = 0) as a function of q2: a sign
             * change on a grid of the joint range, then bisection */
            for (lo = r.joint[1].qmin; lo < r.joint[1].qmax - 1.0 && !found; lo += 1.0) {
                q[1] = lo;
                dhs_fk_desc(descs[k], q, F, NULL);
                flo = F[4].m[3][0];
                q[1] = lo + 1.0;
                dhs_fk_desc(descs[k], q, F, NULL);
                if ((flo < 0.0) != (F[4].m[3][0] < 0.0)) found = 1;
            }
            if (!found) {
                t--;
                continue;
            }
            lo -= 1.0;
            hi = lo + 1.0;
            for (it = 0; it < 60u; it++) {
                double mid = 0.5 * (lo + hi);
                q[1] = mid;
                dhs_fk_desc(descs[k], q, F, NULL);
                if ((F[4].m[3][0] < 0.0) == (flo < 0.0)) lo = mid;
                else hi = mid;
            }
            q[1] = 0.5 * (lo + hi);
            qref[0] = (float)dht_rand_uniform(-100.0, 100.0);
            dhs_target_f32(&r, q, &T);
            DHT_EQ_INT(dh_ikc_f32(&m, &T, qref, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &n_sol), DH_OK);
            check_solutions(&r, &T, sol, n_sol, descs[k]->name, &wp, &wr);
            DHT_TRUE_MSG(n_sol >= 1u && n_sol <= 4u, "%s shoulder singular: %u solutions", descs[k]->name, (unsigned)n_sol);
            for (s = 0; s < n_sol; s++) {
                DHT_TRUE_MSG((sol[s].flags & DH_IKC_SING_SHOULDER) != 0u, "%s: solution %u not flagged shoulder singular",
                             descs[k]->name, (unsigned)s);
                DHT_TRUE_MSG(sol[s].q[0] == qref[0], "%s shoulder singular: q1 = %.9g, q_ref1 = %.9g", descs[k]->name,
                             (double)sol[s].q[0], (double)qref[0]);
            }
        }
    }
}

/* Puma near its elbow boundaries. The folded elbow with the wrist centre
 * on the shoulder cylinder (u = 0), where a rounding of the target moves u
 * by far more than a rounding: every target of a sweep over +-4e-6 deg of
 * joint 3 around the fold and +-0.03 deg of joint 2 around u = 0 is solved.
 * A target moved radially beyond the stretched elbow: by 0.9 of 2.5e-7 L
 * it is solved on the boundary (flagged), by 1.1 of 1.5e-6 L it is
 * unreachable (the bounds of ikc.h; L = 1.1 m). */
static void ikc_elbow_boundary(void)
{
    const dhs_robot *d = &dhs_puma560_m;
    const double a2 = d->j[1].a, a3 = d->j[2].a, e = sin(d->j[2].alpha_deg * D2R) * d->j[3].d;
    const double phi = atan2(e, a3), t3 = phi + PI;
    const double A = a2 + a3 * cos(t3) + e * sin(t3), B = a3 * sin(t3) - e * cos(t3);
    const double t2 = 90.0 - atan2(B, A) / D2R;
    dh_robot r;
    dh_ikc_model_f32 m;
    dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
    dh_mat4_f32 T;
    double wp = 0.0, wr = 0.0, L = 0.0;
    uint32_t n_sol, s;
    int i, j, k, far;
    for (i = 0; i < (int)d->n; i++) L += fabs(d->j[i].a) + fabs(d->j[i].d);
    DHT_EQ_INT(dhs_build(d, &r), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_f32(&r, &m), DH_OK);
    for (j = -3; j <= 3; j++)
        for (k = -4; k <= 4; k++) {
            double q[6] = {-130.0, 0.0, 0.0, 40.0, 50.0, -60.0};
            q[1] = t2 - d->j[1].theta_deg + 0.01 * j;
            q[2] = t3 / D2R - d->j[2].theta_deg + 1e-6 * k;
            dhs_target_f32(&r, q, &T);
            DHT_TRUE_MSG(dh_ikc_f32(&m, &T, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &n_sol) == DH_OK && n_sol >= 1u,
                         "folded elbow on the shoulder cylinder: q = %s not solved", dhs_q_str(q, 6u, 0));
            check_solutions(&r, &T, sol, n_sol, "folded elbow on the shoulder cylinder", &wp, &wr);
        }
    for (far = 0; far < 2; far++) {
        double q[6] = {20.0, -30.0, 0.0, 40.0, 50.0, -60.0}, w[3], nw = 0.0, wz = 0.0;
        dhr_mat4 F[DHS_MAX_JOINTS];
        q[2] = phi / D2R - d->j[2].theta_deg;
        dhs_fk_desc(d, q, F, NULL);
        /* from the joint 2 axis (frame 1) to the wrist centre (frame 4), normal to that axis */
        for (i = 0; i < 3; i++) w[i] = F[3].m[3][i] - F[0].m[3][i];
        for (i = 0; i < 3; i++) wz += w[i] * F[0].m[2][i];
        for (i = 0; i < 3; i++) {
            w[i] -= wz * F[0].m[2][i];
            nw += w[i] * w[i];
        }
        nw = sqrt(nw);
        DHT_TRUE(fabs(nw - (fabs(a2) + sqrt(a3 * a3 + e * e))) < 1e-9); /* stretched */
        dhs_target_f32(&r, q, &T);
        for (i = 0; i < 3; i++) T.m[3][i] = (float)((double)T.m[3][i] + (far ? 1.1 * 1.5e-6 : 0.9 * 2.5e-7) * L * w[i] / nw);
        if (far) {
            DHT_EQ_INT(dh_ikc_f32(&m, &T, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &n_sol), DH_ERR_UNREACHABLE);
            DHT_EQ_INT(n_sol, 0);
        } else {
            DHT_EQ_INT(dh_ikc_f32(&m, &T, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &n_sol), DH_OK);
            DHT_TRUE(n_sol >= 1u);
            for (s = 0; s < n_sol; s++) DHT_TRUE((sol[s].flags & DH_IKC_SING_ELBOW) != 0u);
            check_solutions(&r, &T, sol, n_sol, "just beyond the stretched elbow", &wp, &wr);
        }
    }
    dht_printf("ikc puma elbow boundary: worst position %.3g m, rotation %.3g rad\n", wp, wr);
}

/* Puma with the elbow stretched (theta3 = atan2(sin alpha3 d4, a3)): the
 * elbow branches coincide, each shoulder's returned once, flagged. */
static void ikc_elbow_stretched(void)
{
    dh_robot r;
    dh_ikc_model_f32 m;
    const dhs_robot *d = &dhs_puma560_m;
    const double phi = atan2(sin(d->j[2].alpha_deg * D2R) * d->j[3].d, d->j[2].a) / D2R;
    long t;
    DHT_EQ_INT(dhs_build(d, &r), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_f32(&r, &m), DH_OK);
    for (t = 0; t < DHT_ITER(200); t++) {
        double q[NJ], wp = 0, wr = 0;
        dh_mat4_f32 T;
        dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
        uint32_t n_sol = 0, s, nel = 0;
        dhs_random_q_robot(&r, q);
        q[2] = phi - d->j[2].theta_deg;
        if (fabs(sin(q[4] * D2R)) < 1e-2) q[4] = 30.0;
        dhs_target_f32(&r, q, &T);
        DHT_EQ_INT(dh_ikc_f32(&m, &T, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &n_sol), DH_OK);
        check_solutions(&r, &T, sol, n_sol, "puma elbow stretched", &wp, &wr);
        for (s = 0; s < n_sol; s++)
            if ((sol[s].flags & DH_IKC_SING_ELBOW) != 0u) nel++;
        DHT_TRUE_MSG(nel >= 2u && (sol[0].flags & DH_IKC_SING_ELBOW) != 0u && n_sol <= 6u,
                     "q = %s: %u solutions, %u flagged stretched", dhs_q_str(q, 6u, 0), (unsigned)n_sol, (unsigned)nel);
        for (s = 0; s < n_sol; s++)
            DHT_TRUE_MSG((sol[s].flags & DH_IKC_ELBOW_ALT) == 0u || (sol[s].flags & DH_IKC_SING_ELBOW) == 0u,
                         "stretched elbow returned twice");
    }
}

/* ---------------------------------------------------------------------- */
/* limits                                                                   */

static void ikc_limits(void)
{
    dh_robot r;
    dh_ikc_model_f32 m;
    dh_mat4_f32 T;
    dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL], solk[DH_IKC_MAX_SOL];
    uint32_t n_sol = 0, n_keep = 0, s, nflag;
    double q[NJ] = { 20, -40, 60, 200, 50, -190 }, wp = 0, wr = 0;
    float qref[NJ] = { 0, 0, 0, 180, 0, -180 };
    long t;
    int seen = 0;
    /* KUKA KR5, joints 4 and 6 over +-350: the value nearest q_ref */
    DHT_EQ_INT(dhs_build(&dhs_kuka_kr5_m, &r), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_f32(&r, &m), DH_OK);
    dhs_target_f32(&r, q, &T);
    DHT_EQ_INT(dh_ikc_f32(&m, &T, qref, 0u, sol, &n_sol), DH_OK);
    for (s = 0; s < n_sol; s++) {
        double dd = 0;
        uint32_t i;
        for (i = 0; i < 6u; i++) dd = fmax(dd, fabs((double)sol[s].q[i] - q[i]));
        if (dd <= TOL_GEN) seen = 1;
        DHT_TRUE_MSG(fabs((double)sol[s].q[3] - 180.0) <= 180.0 && fabs((double)sol[s].q[5] + 180.0) <= 180.0,
                     "kr5 solution %u: q4 %.9g, q6 %.9g not the shifts nearest q_ref", (unsigned)s, (double)sol[s].q[3],
                     (double)sol[s].q[5]);
    }
    DHT_TRUE_MSG(seen, "kr5: q = %s (q4, q6 beyond +-180) not returned as such for q_ref near it", dhs_q_str(q, 6u, 0));
    /* same target, q_ref 0: q4 = 200 - 360 and q6 = -190 + 360 */
    DHT_EQ_INT(dh_ikc_f32(&m, &T, NULL, 0u, sol, &n_sol), DH_OK);
    seen = 0;
    for (s = 0; s < n_sol; s++)
        if (fabs((double)sol[s].q[3] + 160.0) <= TOL_GEN && fabs((double)sol[s].q[5] - 170.0) <= TOL_GEN &&
            fabs((double)sol[s].q[1] + 40.0) <= TOL_GEN)
            seen = 1;
    DHT_TRUE_MSG(seen, "kr5: q_ref 0 did not give q4 = -160, q6 = 170");

    /* Puma: solutions outside the limits left out, or kept and flagged */
    DHT_EQ_INT(dhs_build(&dhs_puma560_m, &r), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_f32(&r, &m), DH_OK);
    nflag = 0;
    for (t = 0; t < DHT_ITER(500); t++) {
        uint32_t a, b, i;
        dh_status st;
        dhs_random_q_robot(&r, q);
        if (!away_from(&dhs_puma560_m, q, 1e-6)) continue;
        dhs_target_f32(&r, q, &T);
        st = dh_ikc_f32(&m, &T, NULL, 0u, sol, &n_sol);
        DHT_EQ_INT(st, DH_OK);
        DHT_EQ_INT(dh_ikc_f32(&m, &T, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, solk, &n_keep), DH_OK);
        check_solutions(&r, &T, solk, n_keep, "puma keep", &wp, &wr);
        DHT_TRUE_MSG(n_keep >= n_sol, "kept %u < %u", (unsigned)n_keep, (unsigned)n_sol);
        for (s = 0; s < n_sol; s++) DHT_TRUE_MSG(within_limits(&r, sol[s].q), "solution %u outside the limits", (unsigned)s);
        /* the in-limit ones of the kept set are the plain set, same order */
        for (a = 0, b = 0; a < n_keep; a++) {
            if ((solk[a].flags & DH_IKC_OUT_OF_LIMITS) != 0u) {
                nflag++;
                continue;
            }
            DHT_TRUE_MSG(b < n_sol, "more in-limit kept solutions than plain ones");
            for (i = 0; i < 6u; i++) DHT_EQ_F32_BITS(solk[a].q[i], sol[b].q[i]);
            DHT_EQ_INT(solk[a].flags, sol[b].flags);
            b++;
        }
        DHT_EQ_INT(b, n_sol);
    }
    DHT_TRUE_MSG(nflag > 0u, "no Puma target had a solution outside the limits");

    /* every solution outside: DH_ERR_LIMIT, n_sol 0; kept: all flagged */
    DHT_EQ_INT(dh_robot_set_limits_f32(&r, 0, 10.0f, 20.0f), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_f32(&r, &m), DH_OK);
    {
        double qo[NJ] = { 60, -30, 40, 10, 30, 20 };
        dhs_target_f32(&r, qo, &T);
        n_sol = 5u;
        DHT_EQ_INT(dh_ikc_f32(&m, &T, NULL, 0u, sol, &n_sol), DH_ERR_LIMIT);
        DHT_EQ_INT(n_sol, 0);
        DHT_EQ_INT(dh_ikc_f32(&m, &T, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &n_sol), DH_OK);
        DHT_TRUE_MSG(n_sol >= 1u, "kept nothing");
        for (s = 0; s < n_sol; s++) DHT_TRUE_MSG((sol[s].flags & DH_IKC_OUT_OF_LIMITS) != 0u, "solution %u not flagged", (unsigned)s);
        check_solutions(&r, &T, sol, n_sol, "puma narrow joint 1", &wp, &wr);
    }
    /* Stanford: the prismatic extension's negative branch is outside its
     * limits (0.3048 .. 1.27 m) */
    DHT_EQ_INT(dhs_build(&dhs_stanford_m, &r), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_f32(&r, &m), DH_OK);
    {
        double qs[NJ] = { 30, -50, 0.8, 20, 40, -60 };
        dhs_target_f32(&r, qs, &T);
        DHT_EQ_INT(dh_ikc_f32(&m, &T, NULL, 0u, sol, &n_sol), DH_OK);
        DHT_EQ_INT(dh_ikc_f32(&m, &T, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, solk, &n_keep), DH_OK);
        DHT_EQ_INT(n_keep, 8);
        DHT_TRUE(n_sol >= 1u && n_sol <= 4u);
        for (s = 0; s < n_sol; s++) DHT_TRUE_MSG(sol[s].q[2] > 0.0f, "stanford solution %u: d3 %.9g", (unsigned)s, (double)sol[s].q[2]);
        for (s = 0, nflag = 0; s < n_keep; s++) nflag += (solk[s].q[2] < 0.0f) ? 1u : 0u;
        DHT_EQ_INT(nflag, 4); /* the negative extensions, kept and flagged */
        check_solutions(&r, &T, solk, n_keep, "stanford kept", &wp, &wr);
    }
}

/* Beyond the reach, and (Stanford) inside the cylinder of radius h around
 * axis 1 that the wrist centre cannot enter: DH_ERR_UNREACHABLE, 0 solutions. */
static void ikc_unreachable(void)
{
    unsigned k;
    for (k = 0; k < N_ROBOTS; k++) {
        dh_robot r;
        dh_ikc_model_f32 m;
        dh_mat4_f32 T;
        dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
        uint32_t n_sol = 7u;
        DHT_EQ_INT(dhs_build(g_robots[k].desc, &r), DH_OK);
        DHT_EQ_INT(dh_ikc_analyse_f32(&r, &m), DH_OK);
        dh_mat4_trans_f32(3.0f, 1.0f, 2.0f, &T);
        if (m.kind == DH_IKC_WRIST_RRP) dh_mat4_trans_f32(0.01f, 0.0f, 0.5f, &T);
        DHT_EQ_INT(dh_ikc_f32(&m, &T, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &n_sol), DH_ERR_UNREACHABLE);
        DHT_EQ_INT(n_sol, 0);
    }
}

/* Regression: a finite target far beyond the reach (1e6 .. 3e38) overflows
 * the squares of the position solution; every revolute family answers
 * UNREACHABLE with no solution (once it returned DH_OK with NaN joint
 * values); a robot whose prismatic joint reaches it, kept outside its limits,
 * returns finite solutions only. */
static void ikc_far_target(void)
{
    static const dhs_robot *const robots[] = { &dhs_puma560_m, &dhs_kuka_kr5_m, &dhs_stanford_m, &dhs_ur5_m,
                                               &dhs_ur10_m, &dhs_cobra600_m };
    static const float far[] = { 1e6f, 1e15f, 1e19f, 1e20f, 1e30f, 3e38f };
    unsigned k, f, c;
    for (k = 0; k < sizeof robots / sizeof robots[0]; k++) {
        dh_robot r;
        dh_ikc_model_f32 m;
        DHT_EQ_INT(dhs_build(robots[k], &r), DH_OK);
        DHT_EQ_INT(dh_ikc_analyse_f32(&r, &m), DH_OK);
        for (f = 0; f < sizeof far / sizeof far[0]; f++)
            for (c = 0; c < 4u; c++) {
                dh_mat4_f32 T;
                dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
                uint32_t n_sol = 7u;
                dh_status st;
                const float x = (c & 1u) ? -far[f] : far[f], y = (c & 2u) ? 0.5f * far[f] : 0.0f;
                dh_mat4_trans_f32(x, y, -0.7f * far[f], &T);
                st = dh_ikc_f32(&m, &T, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &n_sol);
                if (m.prismatic != 0u && st == DH_OK) {
                    /* an unlimited prismatic joint reaches it: real solutions only */
                    uint32_t i, j;
                    for (i = 0; i < n_sol; i++)
                        for (j = 0; j < m.n; j++) DHT_TRUE_MSG(isfinite(sol[i].q[j]), "%s: solution %u", robots[k]->name, (unsigned)i);
                    continue;
                }
                DHT_TRUE_MSG(st == DH_ERR_UNREACHABLE && n_sol == 0u, "%s, target (%g, %g, %g): status %d, %u solutions",
                             robots[k]->name, (double)x, (double)y, -0.7 * (double)far[f], (int)st, (unsigned)n_sol);
            }
    }
}

/* ---------------------------------------------------------------------- */
/* conventions and frames                                                   */

/* The Puma's table converted to modified DH in double (joint i takes a,
 * alpha of standard joint i-1; the last a, alpha go into the tool, here 0):
 * the same solutions in the same order. */
static void ikc_mdh_puma(void)
{
    const dhs_robot *d = &dhs_puma560_m;
    dh_robot rs, rm;
    dh_ikc_model_f32 ms, mm;
    unsigned i;
    long t;
    DHT_EQ_INT(dhs_build(d, &rs), DH_OK);
    DHT_EQ_INT(dh_robot_init(&rm, DH_CONV_MODIFIED), DH_OK);
    for (i = 0; i < d->n; i++) {
        const double a = (i == 0u) ? 0.0 : d->j[i - 1u].a, al = (i == 0u) ? 0.0 : d->j[i - 1u].alpha_deg;
        DHT_EQ_INT(dh_robot_add_joint_f32(&rm, d->j[i].type, (float)d->j[i].theta_deg, (float)d->j[i].d, (float)a,
                                          (float)al), DH_OK);
        DHT_EQ_INT(dh_robot_set_limits_f32(&rm, i, (float)d->j[i].qmin, (float)d->j[i].qmax), DH_OK);
    }
    DHT_TRUE_MSG(d->j[5].a == 0.0 && d->j[5].alpha_deg == 0.0, "the Puma's last a, alpha are 0 (no tool needed)");
    DHT_EQ_INT(dh_ikc_analyse_f32(&rs, &ms), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_f32(&rm, &mm), DH_OK);
    DHT_EQ_INT(mm.kind, DH_IKC_WRIST_RRR);
    for (t = 0; t < DHT_ITER(1000); t++) {
        double q[NJ], wp = 0, wr = 0;
        dh_mat4_f32 T;
        dh_ikc_sol_f32 s1[DH_IKC_MAX_SOL], s2[DH_IKC_MAX_SOL];
        uint32_t n1 = 0, n2 = 0, s;
        dhs_random_q_robot(&rm, q);
        if (!away_from(d, q, 1e-6)) continue;
        dhs_target_f32(&rm, q, &T);
        DHT_EQ_INT(dh_ikc_f32(&mm, &T, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, s2, &n2), DH_OK);
        check_solutions(&rm, &T, s2, n2, "puma MDH", &wp, &wr);
        DHT_EQ_INT(dh_ikc_f32(&ms, &T, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, s1, &n1), DH_OK);
        DHT_EQ_INT(n1, n2);
        for (s = 0; s < n1 && s < n2; s++) {
            double dd[NJ], dq;
            unsigned j;
            for (j = 0; j < 6u; j++) dd[j] = (double)s1[s].q[j];
            dq = q_dist(&rs, s2[s].q, dd);
            DHT_TRUE_MSG(dq <= 1e-3 && s1[s].flags == s2[s].flags, "MDH solution %u (%s) differs from SDH (%s) by %.3g",
                         (unsigned)s, dhs_qf_str(s2[s].q, 6u, 0), dhs_qf_str(s1[s].q, 6u, 1), dq);
        }
    }
}

/* Base and tool not the identity (rotation and translation): every
 * solution matches, the generating configuration is found. */
static void ikc_base_tool(void)
{
    unsigned k;
    for (k = 0; k < N_ROBOTS; k++) {
        dh_robot r;
        dh_ikc_model_f32 m;
        dh_mat4_f32 B, Tl, X;
        DHT_EQ_INT(dhs_build(g_robots[k].desc, &r), DH_OK);
        DHT_EQ_INT(dh_mat4_rot_axis_f32(1.0f, -2.0f, 0.5f, 37.0f, &B), DH_OK);
        B.m[3][0] = 0.3f;
        B.m[3][1] = -0.2f;
        B.m[3][2] = 0.1f;
        DHT_EQ_INT(dh_mat4_rot_axis_f32(0.2f, 1.0f, -0.7f, -61.0f, &Tl), DH_OK);
        dh_mat4_trans_f32(0.01f, -0.02f, 0.12f, &X);
        dh_mat4_premul_f32(&Tl, &X);
        DHT_EQ_INT(dh_robot_set_base_f32(&r, &B), DH_OK);
        DHT_EQ_INT(dh_robot_set_tool_f32(&r, &Tl), DH_OK);
        DHT_EQ_INT(dh_ikc_analyse_f32(&r, &m), DH_OK);
        DHT_EQ_INT(m.kind, g_robots[k].kind);
        {
            long t, nedge = 0;
            double wp = 0, wr = 0;
            for (t = 0; t < DHT_ITER(1000); t++) {
                double q[NJ], best = 1e30;
                dh_mat4_f32 T;
                dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
                uint32_t n_sol = 0, s;
                dhs_random_q_robot(&r, q);
                dhs_target_f32(&r, q, &T);
                DHT_EQ_INT(solve_target(&m, &r, g_robots[k].desc, q, &T, sol, &n_sol, &nedge), DH_OK);
                check_solutions(&r, &T, sol, n_sol, "base and tool", &wp, &wr);
                if (!away_from_singular(g_robots[k].desc, q)) continue;
                for (s = 0; s < n_sol; s++) best = fmin(best, q_dist(&r, sol[s].q, q));
                DHT_TRUE_MSG(best <= TOL_GEN, "%s with base and tool: q = %s not found (%.3g)", g_robots[k].name,
                             dhs_q_str(q, r.n, 0), best);
            }
            dht_printf("ikc %s with base and tool: worst position %.3g m, rotation %.3g rad; %ld solved beyond a limit\n",
                       g_robots[k].name, wp, wr, nedge);
        }
    }
}

/* ---------------------------------------------------------------------- */
/* robots without a closed form, and bad arguments                          */

static void expect_none(const dh_robot *r, dh_status st, dh_ikc_why why, const char *what)
{
    dh_ikc_model_f32 m;
    memset(&m, 0x5A, sizeof m);
    DHT_TRUE_MSG(dh_ikc_analyse_f32(r, &m) == st, "%s: status %d, expected %d", what, (int)dh_ikc_analyse_f32(r, &m),
                 (int)st);
    DHT_TRUE_MSG(m.kind == DH_IKC_NONE && m.why == why, "%s: kind %d why %d, expected NONE and %d", what, (int)m.kind,
                 (int)m.why, (int)why);
}

static void ikc_no_closed_form(void)
{
    dh_robot r;
    dh_mat4_f32 S;
    unsigned i;
    /* Panda: 7 joints */
    DHT_EQ_INT(dhs_build(&dhs_panda_m, &r), DH_OK);
    expect_none(&r, DH_ERR_UNAVAILABLE, DH_IKC_WHY_JOINTS, "panda");
    /* Puma with a5 != 0: the wrist axes do not meet */
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    for (i = 0; i < 6u; i++) {
        const dhs_joint_desc *j = &dhs_puma560_m.j[i];
        DHT_EQ_INT(dh_robot_add_joint_f32(&r, j->type, (float)j->theta_deg, (float)j->d, (i == 4u) ? 0.05f : (float)j->a,
                                          (float)j->alpha_deg), DH_OK);
    }
    expect_none(&r, DH_ERR_UNAVAILABLE, DH_IKC_WHY_WRIST, "puma with a5 = 0.05");
    /* Puma with alpha2 = 10: spherical wrist, axes 2 and 3 not parallel */
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    for (i = 0; i < 6u; i++) {
        const dhs_joint_desc *j = &dhs_puma560_m.j[i];
        DHT_EQ_INT(dh_robot_add_joint_f32(&r, j->type, (float)j->theta_deg, (float)j->d, (float)j->a,
                                          (i == 1u) ? 10.0f : (float)j->alpha_deg), DH_OK);
    }
    expect_none(&r, DH_ERR_UNAVAILABLE, DH_IKC_WHY_AXES, "puma with alpha2 = 10");
    /* Puma with alpha4 = 60: the wrist axes meet, but not at right angles */
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    for (i = 0; i < 6u; i++) {
        const dhs_joint_desc *j = &dhs_puma560_m.j[i];
        DHT_EQ_INT(dh_robot_add_joint_f32(&r, j->type, (float)j->theta_deg, (float)j->d, (float)j->a,
                                          (i == 3u) ? 60.0f : (float)j->alpha_deg), DH_OK);
    }
    expect_none(&r, DH_ERR_UNAVAILABLE, DH_IKC_WHY_AXES, "puma with alpha4 = 60");
    /* Stanford with alpha2 = 60: not a Stanford arm */
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    for (i = 0; i < 6u; i++) {
        const dhs_joint_desc *j = &dhs_stanford_m.j[i];
        DHT_EQ_INT(dh_robot_add_joint_f32(&r, j->type, (float)j->theta_deg, (float)j->d, (float)j->a,
                                          (i == 1u) ? 60.0f : (float)j->alpha_deg), DH_OK);
    }
    expect_none(&r, DH_ERR_UNAVAILABLE, DH_IKC_WHY_AXES, "stanford with alpha2 = 60");
    /* R-R-P-R with twisted axes: no SCARA */
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0.0f, 0.3f, 0.3f, 20.0f), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0.0f, 0.0f, 0.3f, 30.0f), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_PRISMATIC, 0.0f, 0.0f, 0.0f, 0.0f), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0.0f, 0.0f, 0.0f, 0.0f), DH_OK);
    expect_none(&r, DH_ERR_UNAVAILABLE, DH_IKC_WHY_AXES, "twisted RRPR");
    /* two joints: no family */
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0.0f, 0.0f, 1.0f, 0.0f), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0.0f, 0.0f, 1.0f, 0.0f), DH_OK);
    expect_none(&r, DH_ERR_UNAVAILABLE, DH_IKC_WHY_JOINTS, "2R");
    /* no joints */
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    expect_none(&r, DH_ERR_UNAVAILABLE, DH_IKC_WHY_JOINTS, "no joints");
    /* fixed-point-only robot: no float path */
    DHT_EQ_INT(dhs_build_q(&dhs_puma560_mm, &r), DH_OK);
    expect_none(&r, DH_ERR_UNAVAILABLE, DH_IKC_WHY_PATH, "fixed-only puma");
    /* base or tool not rigid (scaled) */
    DHT_EQ_INT(dhs_build(&dhs_puma560_m, &r), DH_OK);
    dh_mat4_scale_f32(1.0f, 2.0f, 1.0f, &S);
    DHT_EQ_INT(dh_robot_set_base_f32(&r, &S), DH_OK);
    expect_none(&r, DH_ERR_NOT_RIGID, DH_IKC_WHY_PATH, "scaled base");
    DHT_EQ_INT(dhs_build(&dhs_puma560_m, &r), DH_OK);
    DHT_EQ_INT(dh_robot_set_tool_f32(&r, &S), DH_OK);
    expect_none(&r, DH_ERR_NOT_RIGID, DH_IKC_WHY_PATH, "scaled tool");
    /* description out of range */
    DHT_EQ_INT(dhs_build(&dhs_puma560_m, &r), DH_OK);
    r.n = DH_MAX_JOINTS + 1u;
    expect_none(&r, DH_ERR_ARG, DH_IKC_WHY_JOINTS, "n > DH_MAX_JOINTS");
    DHT_EQ_INT(dhs_build(&dhs_puma560_m, &r), DH_OK);
    r.conv = (dh_convention)7;
    expect_none(&r, DH_ERR_ARG, DH_IKC_WHY_JOINTS, "unknown convention");
    DHT_EQ_INT(dhs_build(&dhs_puma560_m, &r), DH_OK);
    r.joint[2].type = (dh_joint_type)5;
    expect_none(&r, DH_ERR_ARG, DH_IKC_WHY_JOINTS, "unknown joint type");
}

static void ikc_why_strings(void)
{
    int w, v;
    for (w = 0; w <= 4; w++) {
        const char *s = dh_ikc_why_str((dh_ikc_why)w);
        DHT_TRUE(s != NULL && strlen(s) > 10u);
        for (v = 0; v < w; v++) DHT_TRUE(strcmp(s, dh_ikc_why_str((dh_ikc_why)v)) != 0);
    }
    DHT_TRUE(strcmp(dh_ikc_why_str((dh_ikc_why)5), "unknown reason") == 0);
    DHT_TRUE(strcmp(dh_ikc_why_str((dh_ikc_why)-1), "unknown reason") == 0);
}

/* Every error status of dh_ikc_f32: n_sol 0 and sol untouched. */
static void expect_err(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *qref, uint32_t opts, dh_status st,
                       const char *what)
{
    dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL], ref[DH_IKC_MAX_SOL];
    uint32_t n_sol = 42u;
    dh_status got;
    memset(sol, 0xA5, sizeof sol);
    memcpy(ref, sol, sizeof sol);
    got = dh_ikc_f32(m, T, qref, opts, sol, &n_sol);
    DHT_TRUE_MSG(got == st, "%s: status %d, expected %d", what, (int)got, (int)st);
    DHT_EQ_INT(n_sol, 0);
    DHT_TRUE_MSG(memcmp(sol, ref, sizeof sol) == 0, "%s: sol written", what);
}

static void ikc_bad_arguments(void)
{
    dh_robot r;
    dh_ikc_model_f32 m, bad;
    dh_mat4_f32 T, U;
    float qref[NJ] = { 1, 2, 3, 4, 5, 6 };
    double q[NJ] = { 10, 20, -30, 40, 50, 60 };
    DHT_EQ_INT(dhs_build(&dhs_puma560_m, &r), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_f32(&r, &m), DH_OK);
    dhs_target_f32(&r, q, &T);
    expect_err(&m, &T, qref, 0x2u, DH_ERR_ARG, "unknown option bit");
    expect_err(&m, &T, qref, 0x80000001u, DH_ERR_ARG, "unknown option bit with KEEP");
    bad = m;
    bad.kind = DH_IKC_NONE;
    expect_err(&bad, &T, qref, 0u, DH_ERR_UNAVAILABLE, "kind NONE");
    bad = m;
    bad.kind = (dh_ikc_kind)9;
    expect_err(&bad, &T, qref, 0u, DH_ERR_ARG, "kind out of range");
    bad = m;
    bad.n = 5u;
    expect_err(&bad, &T, qref, 0u, DH_ERR_ARG, "n not the family's");
    bad.kind = DH_IKC_SCARA;
    bad.n = 6u;
    expect_err(&bad, &T, qref, 0u, DH_ERR_ARG, "SCARA with 6 joints");
    U = T;
    U.m[3][1] = NAN;
    expect_err(&m, &U, qref, 0u, DH_ERR_NAN, "NaN target");
    U = T;
    U.m[1][0] = INFINITY;
    expect_err(&m, &U, qref, 0u, DH_ERR_NAN, "Inf target");
    qref[4] = NAN;
    expect_err(&m, &T, qref, 0u, DH_ERR_NAN, "NaN q_ref");
    qref[4] = -INFINITY;
    expect_err(&m, &T, qref, 0u, DH_ERR_NAN, "Inf q_ref");
    qref[4] = 5.0f;
    U = T;
    U.m[2][3] = 1e-3f;
    expect_err(&m, &U, qref, 0u, DH_ERR_NOT_RIGID, "bottom row");
    U = T;
    U.m[0][3] = -1e-3f;
    expect_err(&m, &U, qref, 0u, DH_ERR_NOT_RIGID, "bottom row, column 0");
    U = T;
    U.m[1][3] = 1e-3f;
    expect_err(&m, &U, qref, 0u, DH_ERR_NOT_RIGID, "bottom row, column 1");
    U = T;
    U.m[3][3] = 2.0f;
    expect_err(&m, &U, qref, 0u, DH_ERR_NOT_RIGID, "bottom row w");
    U = T;
    U.m[0][0] *= 1.01f;
    expect_err(&m, &U, qref, 0u, DH_ERR_NOT_RIGID, "rotation not orthonormal");
    U = T;
    U.m[2][0] = -U.m[2][0];
    U.m[2][1] = -U.m[2][1];
    U.m[2][2] = -U.m[2][2];
    expect_err(&m, &U, qref, 0u, DH_ERR_NOT_RIGID, "reflection");
    /* the checks pass for the original target */
    {
        dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
        uint32_t n_sol = 0;
        DHT_EQ_INT(dh_ikc_f32(&m, &T, qref, 0u, sol, &n_sol), DH_OK);
        DHT_TRUE(n_sol >= 1u);
    }
}

static void ikc_nearest(void)
{
    dh_ikc_sol_f32 sol[3];
    float qref[NJ] = { 0, 0, 0, 0, 0, 0 };
    uint32_t idx = 77u, i;
    for (i = 0; i < 6u; i++) {
        sol[0].q[i] = 10.0f;
        sol[1].q[i] = -2.0f;
        sol[2].q[i] = 2.0f;
    }
    DHT_EQ_INT(dh_ikc_nearest_f32(sol, 3u, qref, 6u, &idx), DH_OK);
    DHT_EQ_INT(idx, 1); /* first of equals */
    qref[0] = 3.0f;
    DHT_EQ_INT(dh_ikc_nearest_f32(sol, 3u, qref, 6u, &idx), DH_OK);
    DHT_EQ_INT(idx, 2);
    DHT_EQ_INT(dh_ikc_nearest_f32(sol, 3u, NULL, 6u, &idx), DH_OK);
    DHT_EQ_INT(idx, 1);
    DHT_EQ_INT(dh_ikc_nearest_f32(sol, 1u, qref, 6u, &idx), DH_OK);
    DHT_EQ_INT(idx, 0);
    idx = 77u;
    DHT_EQ_INT(dh_ikc_nearest_f32(sol, 0u, qref, 6u, &idx), DH_ERR_ARG);
    DHT_EQ_INT(dh_ikc_nearest_f32(sol, 3u, qref, 7u, &idx), DH_ERR_ARG);
    qref[3] = NAN;
    DHT_EQ_INT(dh_ikc_nearest_f32(sol, 3u, qref, 6u, &idx), DH_ERR_NAN);
    DHT_EQ_INT(idx, 77);
}

static const dht_case cases[] = {
    DHT_CASE(ikc_bad_arguments),
    DHT_CASE(ikc_why_strings),
    DHT_CASE(ikc_nearest),
    DHT_CASE(ikc_no_closed_form),
    DHT_CASE(ikc_unreachable),
    DHT_CASE(ikc_far_target),
    DHT_CASE(ikc_limits),
    DHT_CASE(ikc_wrist_singular),
    DHT_CASE(ikc_shoulder_singular),
    DHT_CASE(ikc_elbow_stretched),
    DHT_CASE(ikc_elbow_boundary),
    DHT_CASE(ikc_mdh_puma),
    DHT_CASE(ikc_base_tool),
    DHT_CASE(ikc_completeness),
    DHT_CASE(ikc_numerical_completeness),
};
DHT_MAIN(cases)
