/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_ik.c - numerical inverse kinematics (dh_ik_f32).
 *
 * Every result is judged in double, independently of the library: the
 * returned float joint values go through the double reference FK of
 * support_robots.c (with the robot's stored float parameters) and are
 * compared with the float target by a double log map. Targets are the
 * reference FK of random in-limit configurations, so they are reachable.
 */
#include "dht.h"
#include "support_robots.h"
#include "dhmath/kin.h"
#include "dhmath/mat4.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define PI 3.14159265358979323846
#define D2R (PI / 180.0)
#define NJ DH_MAX_JOINTS

static float g_work[DH_IK_WORK_FLOATS(NJ)];

/* ---------------------------------------------------------------------- */

static int within_limits(const dh_robot *r, const float *q)
{
    uint32_t i;
    for (i = 0; i < r->n; i++) {
        const dh_joint *j = &r->joint[i];
        if (!(q[i] == q[i])) return 0;
        if (j->qmin <= j->qmax && (q[i] < j->qmin || q[i] > j->qmax)) return 0;
    }
    return 1;
}

/* ---------------------------------------------------------------------- */
/* success rate on random reachable targets                                 */

typedef struct {
    int runs, ok, ok_status;
    double iter_sum;
    uint32_t iter_max;
    double ep_max, er_max;       /* worst true errors among successes */
} ik_stats;

/* count targets: the double FK of random in-limit configurations (dht
 * generator, seeded by the caller) rounded to float, solved from home */
static void run_rate(const char *name, const dhs_robot *desc, const float *home, double tol_p, double tol_r,
                     const dh_ik_params_f32 *prm, int count, ik_stats *s)
{
    dh_robot r;
    int it;
    memset(s, 0, sizeof *s);
    DHT_EQ_INT(dhs_build(desc, &r), DH_OK);
    for (it = 0; it < count; it++) {
        double q[NJ], ep, er;
        float qo[NJ];
        dh_mat4_f32 T;
        dh_ik_result_f32 res;
        dh_status st;
        dhs_random_q(desc, q);
        dhs_target_f32(&r, q, &T);
        st = dh_ik_f32(&r, &T, home, prm, g_work, DH_IK_WORK_FLOATS(r.n), qo, &res);
        /* whatever the status: a finite configuration within the limits,
         * and res describes it */
        DHT_TRUE_MSG(st == DH_OK || st == DH_ERR_NO_CONVERGENCE || st == DH_ERR_UNREACHABLE,
                     "%s target %d: status %d (%s), expected OK, NO_CONVERGENCE or UNREACHABLE; w_rot %g, "
                     "tol %g / %g, %lu iterations; target q %s", name, it, (int)st, dh_status_str(st),
                     (double)prm->w_rot, (double)prm->tol_pos, (double)prm->tol_rot, (unsigned long)res.iterations,
                     dhs_q_str(q, r.n, 0));
        DHT_TRUE_MSG(within_limits(&r, qo), "%s target %d: result outside the limits: q %s; target q %s", name, it,
                     dhs_qf_str(qo, r.n, 1), dhs_q_str(q, r.n, 0));
        dhs_true_error_f32(&r, qo, &T, &ep, &er);
        DHT_TRUE_MSG(res.iterations <= prm->max_iter, "%s target %d: %lu iterations > max_iter %lu", name, it,
                     (unsigned long)res.iterations, (unsigned long)prm->max_iter);
        s->runs++;
        s->iter_sum += res.iterations;
        if (res.iterations > s->iter_max) s->iter_max = res.iterations;
        if (st == DH_OK) {
            s->ok_status++;
            /* the reported errors are the library's float estimate */
            DHT_TRUE_MSG(res.err_pos <= prm->tol_pos && res.err_rot <= prm->tol_rot,
                         "%s target %d: OK with reported errors %g / %g above tol %g / %g; target q %s", name, it,
                         (double)res.err_pos, (double)res.err_rot, (double)prm->tol_pos, (double)prm->tol_rot,
                         dhs_q_str(q, r.n, 0));
        }
        if (prm->mask == DH_IK_POSITION) er = 0;
        if (st == DH_OK && ep <= tol_p && er <= tol_r) {
            s->ok++;
            if (ep > s->ep_max) s->ep_max = ep;
            if (er > s->er_max) s->er_max = er;
        }
    }
}

/* The success rate is asserted for the run's seed (DHT_SEED or the default)
 * and for these fixed seeds, so that one lucky random target set cannot hide
 * a shortfall (the Puma 560 used to pass the default seed at 99.4% and fail
 * seeds 1 and 12345 at 98.2%). */
static const uint64_t extra_seeds[] = { 1u, 12345u, 2u, 3u, 5u, 6u };

/* Success rate >= need over DHT_ITER(1000) targets for the run's seed and
 * nseeds fixed ones; parameters: the robot's defaults, the given
 * tolerances (also the bounds on the true errors) and, if w_rot > 0, that
 * weight. */
static void rate_case(const char *name, const dhs_robot *desc, const float *home, uint32_t mask,
                      double tol_p, double tol_r, double w_rot, double need, unsigned nseeds)
{
    dh_robot r;
    dh_ik_params_f32 prm;
    ik_stats s;
    const uint64_t s0 = dht_seed();
    uint64_t worst_seed = s0;
    int worst_ok = -1, worst_runs = 1;
    unsigned k;
    DHT_EQ_INT(dhs_build(desc, &r), DH_OK);
    dh_ik_params_default_f32(&r, &prm);
    prm.mask = mask;
    prm.tol_pos = (float)tol_p;
    prm.tol_rot = (float)tol_r;
    if (w_rot > 0) prm.w_rot = (float)w_rot;
    if (nseeds > sizeof extra_seeds / sizeof extra_seeds[0]) nseeds = sizeof extra_seeds / sizeof extra_seeds[0];
    /* Scaled-down runs (slow targets: a few targets per seed) check the run's
     * seed only: with 5..50 targets, 99% means no miss at all, and every
     * extra seed would add another chance of one legitimate miss. */
    if (DHT_ITER(1000) < 1000) nseeds = 0u;
    for (k = 0; k <= nseeds; k++) {
        const uint64_t seed = (k == 0u) ? s0 : extra_seeds[k - 1u];
        if (k > 0u && seed == s0) continue;
        dht_reseed(seed);
        run_rate(name, desc, home, tol_p, tol_r, &prm, DHT_ITER(1000), &s);
        dht_printf("ik %-22s %s w_rot %-7.3g seed 0x%llx: %d/%d converged with true error <= %.0e / %.0e "
                   "(status OK %d), iterations mean %.2f max %llu, worst true error %.3g / %.3g\n",
                   name, mask == DH_IK_POSITION ? "position" : "full", (double)prm.w_rot, (unsigned long long)seed,
                   s.ok, s.runs, tol_p, tol_r, s.ok_status, s.iter_sum / s.runs, (unsigned long long)s.iter_max,
                   s.ep_max, s.er_max);
        if (worst_ok < 0 || (double)s.ok * worst_runs < (double)worst_ok * s.runs) {
            worst_ok = s.ok;
            worst_runs = s.runs;
            worst_seed = seed;
        }
    }
    dht_reseed(s0);     /* the following cases start from the run's seed again */
    DHT_TRUE_MSG((double)worst_ok >= need * worst_runs,
                 "%s %s: success %d/%d = %.4f below %.3f for seed 0x%llx (w_rot %g, tol %g / %g)", name,
                 mask == DH_IK_POSITION ? "position" : "full", worst_ok, worst_runs, (double)worst_ok / worst_runs,
                 need, (unsigned long long)worst_seed, (double)prm.w_rot, tol_p, tol_r);
}

/* Home poses away from singularities (deg). Puma: elbow bent, wrist q5 != 0;
 * UR5: its usual "up" pose with q5 = -90; Panda: the manufacturer's ready
 * pose (the zero pose violates its joint-4 limit). */
static const float puma_home[6] = { 0, 30, -60, 0, 45, 0 };
static const float ur5_home[6] = { 0, -90, 90, -90, -90, 0 };
static const float panda_home[7] = { 0, -45, 0, -135, 0, 90, 45 };

static void ik_rate_puma(void) { rate_case("puma560 (m)", &dhs_puma560_m, puma_home, DH_IK_FULL, 1e-6, 1e-5, 0, 0.99, 6u); }
static void ik_rate_ur5(void) { rate_case("ur5 (m)", &dhs_ur5_m, ur5_home, DH_IK_FULL, 1e-6, 1e-5, 0, 0.99, 6u); }
static void ik_rate_panda(void) { rate_case("panda (m)", &dhs_panda_m, panda_home, DH_IK_FULL, 1e-6, 1e-5, 0, 0.99, 6u); }
static void ik_rate_position(void)
{
    rate_case("puma560 (m)", &dhs_puma560_m, puma_home, DH_IK_POSITION, 1e-6, 1e-5, 0, 0.99, 2u);
    rate_case("ur5 (m)", &dhs_ur5_m, ur5_home, DH_IK_POSITION, 1e-6, 1e-5, 0, 0.99, 2u);
    rate_case("panda (m)", &dhs_panda_m, panda_home, DH_IK_POSITION, 1e-6, 1e-5, 0, 0.99, 2u);
}
/* Millimetre models: 1e-3 mm = 1e-6 m, float resolution of 1000 mm is 6e-5 mm. */
static void ik_rate_mm(void)
{
    rate_case("puma560 (mm)", &dhs_puma560_mm, puma_home, DH_IK_FULL, 1e-3, 1e-5, 0, 0.99, 4u);
    rate_case("ur5 (mm)", &dhs_ur5_mm, ur5_home, DH_IK_FULL, 1e-3, 1e-5, 0, 0.99, 2u);
    rate_case("panda (mm)", &dhs_panda_mm, panda_home, DH_IK_FULL, 1e-3, 1e-5, 0, 0.99, 2u);
}

/* ---------------------------------------------------------------------- */
/* deterministic cases                                                     */

static void ik_bad_arguments(void)
{
    dh_robot r;
    dh_ik_params_f32 p;
    dh_ik_result_f32 res;
    dh_mat4_f32 T;
    float q[6], q0[6] = { 0, 30, -60, 0, 45, 0 };
    double qd[6] = { 10, 20, -30, 40, 50, 60 };
    int k;
    DHT_EQ_INT(dhs_build(&dhs_puma560_m, &r), DH_OK);
    dhs_target_f32(&r, qd, &T);
    dh_ik_params_default_f32(&r, &p);
    for (k = 0; k < 6; k++) q[k] = 99.0f;
    res.iterations = 77u;

    /* workspace too small / missing */
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, DH_IK_WORK_FLOATS(6u) - 1u, q, &res), DH_ERR_ARG);
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, NULL, 0, q, &res), DH_ERR_ARG);
    /* bad parameters */
    p.max_iter = 0;
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_ERR_ARG);
    dh_ik_params_default_f32(&r, &p);
    p.mask = 0;
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_ERR_ARG);
    p.mask = 0x40u;
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_ERR_ARG);
    dh_ik_params_default_f32(&r, &p);
    p.tol_pos = -1.0f;
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_ERR_ARG);
    dh_ik_params_default_f32(&r, &p);
    p.tol_rot = NAN;
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_ERR_ARG);
    dh_ik_params_default_f32(&r, &p);
    p.w_rot = 0.0f;
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_ERR_ARG);
    dh_ik_params_default_f32(&r, &p);
    /* NaN target / NaN start */
    T.m[3][1] = NAN;
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_ERR_NAN);
    dhs_target_f32(&r, qd, &T);
    T.m[0][0] = INFINITY;
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_ERR_NAN);
    dhs_target_f32(&r, qd, &T);
    q0[2] = NAN;
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_ERR_NAN);
    q0[2] = -60.0f;
    /* target rotation not a rotation */
    T.m[0][0] *= 2.0f;
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_ERR_NOT_RIGID);
    /* ... which does not matter for position-only IK */
    p.mask = DH_IK_POSITION;
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_OK);
    dh_ik_params_default_f32(&r, &p);
    for (k = 0; k < 6; k++) q[k] = 99.0f;
    res.iterations = 77u;
    /* no joints */
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_ERR_ARG);
    /* outputs untouched on argument errors */
    for (k = 0; k < 6; k++) DHT_TRUE_MSG(q[k] == 99.0f, "q[%d] = %.9g written on an argument error (was 99)", k, (double)q[k]);
    DHT_EQ_INT(res.iterations, 77);
}

/* A target twice as far as the arm reaches: no convergence, but a finite
 * best effort within limits whose reported residual is the true one, with
 * the arm stretched towards the target. */
static void ik_unreachable(void)
{
    dh_robot r;
    dh_ik_params_f32 p;
    dh_ik_result_f32 res;
    dh_mat4_f32 T;
    float q[6];
    double ep, er;
    dh_status st;
    DHT_EQ_INT(dhs_build(&dhs_puma560_m, &r), DH_OK);
    dh_ik_params_default_f32(&r, &p);
    dh_mat4_identity_f32(&T);
    T.m[3][0] = 2.0f;
    T.m[3][1] = 0.5f;
    T.m[3][2] = 1.0f;
    st = dh_ik_f32(&r, &T, puma_home, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res);
    dht_printf("unreachable target: status %d after %lu iterations, residual %.4g m / %.4g rad\n", (int)st,
               (unsigned long)res.iterations, (double)res.err_pos, (double)res.err_rot);
    /* beyond the reach bound: UNREACHABLE after a few attempts, not the
     * whole step budget */
    DHT_EQ_INT(st, DH_ERR_UNREACHABLE);
    DHT_TRUE_MSG(res.iterations < 400u, "%lu iterations, bound < 400", (unsigned long)res.iterations);
    DHT_TRUE_MSG(within_limits(&r, q), "result outside the limits: q %s", dhs_qf_str(q, r.n, 0));
    dhs_true_error_f32(&r, q, &T, &ep, &er);
    DHT_NEAR(res.err_pos, ep, 1e-5);
    /* reach of the Puma is < 1.1 m from the shoulder at z = 0.672: the
     * distance to (2, 0.5, 1) can't be below 2.06 - 1.1 */
    DHT_TRUE_MSG(ep > 0.9 && ep < 1.3, "true residual %.6g m, expected in (0.9, 1.3)", ep);
    /* position only: the closest point is the stretched arm, distance
     * |target - shoulder| - reach, found to 1e-3 */
    p.mask = DH_IK_POSITION;
    st = dh_ik_f32(&r, &T, puma_home, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res);
    DHT_EQ_INT(st, DH_ERR_UNREACHABLE);
    DHT_TRUE_MSG(res.iterations < 400u, "%lu iterations, bound < 400", (unsigned long)res.iterations);
    DHT_TRUE_MSG(within_limits(&r, q), "result outside the limits: q %s", dhs_qf_str(q, r.n, 0));
    dhs_true_error_f32(&r, q, &T, &ep, &er);
    DHT_NEAR(res.err_pos, ep, 1e-5);
    dht_printf("unreachable target, position only: status %d after %lu iterations, residual %.6g m\n", (int)st,
               (unsigned long)res.iterations, ep);
    /* without restarts the stall is reported as such, quickly */
    p.restarts = 0;
    st = dh_ik_f32(&r, &T, puma_home, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res);
    dht_printf("unreachable target, no restarts: status %d after %lu iterations, residual %.6g m\n", (int)st,
               (unsigned long)res.iterations, (double)res.err_pos);
    DHT_EQ_INT(st, DH_ERR_UNREACHABLE);
    DHT_TRUE_MSG(res.iterations < 100u, "%lu iterations, bound < 100", (unsigned long)res.iterations);
    DHT_TRUE_MSG(within_limits(&r, q), "result outside the limits: q %s", dhs_qf_str(q, r.n, 0));
    dhs_true_error_f32(&r, q, &T, &ep, &er);
    DHT_NEAR(res.err_pos, ep, 1e-5);
    DHT_TRUE_MSG(ep > 0.9 && ep < 1.3, "true residual %.6g m, expected in (0.9, 1.3)", ep);
}

/* Planar 2R arm (l1 = 0.6, l2 = 0.4), position x/y only. The target has two
 * solutions, elbow q2 = -70 (reached without limits from q0 = (0, -10)) and
 * q2 = +70. With q2 limited to [0, 150] the solver must not pass through
 * the forbidden side: it returns the elbow-up solution, within limits. */
static void ik_limits_respected(void)
{
    dh_robot r;
    dh_ik_params_f32 p;
    dh_ik_result_f32 res;
    dh_mat4_f32 T;
    double qt[2] = { 35, -70 }, ep, er;
    float q0[2] = { 0, -10 }, q[2];
    const float l1 = 0.6f, l2 = 0.4f;
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0, 0, l1, 0), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0, 0, l2, 0), DH_OK);
    dhs_target_f32(&r, qt, &T);
    dh_ik_params_default_f32(&r, &p);
    p.mask = DH_IK_PX | DH_IK_PY;
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_OK);
    DHT_NEAR(q[1], -70.0, 1e-3);            /* unconstrained: elbow down */
    DHT_EQ_INT(dh_robot_set_limits_f32(&r, 1, 0.0f, 150.0f), DH_OK);
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_OK);
    DHT_TRUE_MSG(within_limits(&r, q), "result outside the limits: q %s", dhs_qf_str(q, r.n, 0));
    DHT_NEAR(q[1], 70.0, 1e-3);             /* elbow up */
    dhs_true_error_f32(&r, q, &T, &ep, &er);
    DHT_TRUE_MSG(ep <= 1e-6, "true position error %.3g m > 1e-6", ep);
    /* q1 limited too, to [50, 90]: the elbow-up solution needs q1 = 35 - 70
     * ... = -35 (outside), the elbow-down one q1 = 35 with q2 = -70 (outside):
     * no admissible solution. Best effort within limits, UNREACHABLE. */
    DHT_EQ_INT(dh_robot_set_limits_f32(&r, 0, 50.0f, 90.0f), DH_OK);
    {
        dh_status st = dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res);
        DHT_EQ_INT(st, DH_ERR_UNREACHABLE);     /* every attempt stalls at the limits */
        DHT_TRUE_MSG(within_limits(&r, q), "result outside the limits: q %s", dhs_qf_str(q, r.n, 0));
        dhs_true_error_f32(&r, q, &T, &ep, &er);
        DHT_TRUE_MSG(ep > 1e-3, "true position error %.3g m, expected > 1e-3 (no admissible solution)", ep);
        DHT_NEAR(res.err_pos, ep, 1e-6);
    }
}

/* Joint with more than 360 degrees of travel: the solution is found next to
 * the start, not wrapped into +-180. */
static void ik_multiturn(void)
{
    dh_robot r;
    dh_ik_params_f32 p;
    dh_ik_result_f32 res;
    dh_mat4_f32 T;
    double qt[6] = { 400, -80, 95, -100, -85, 700 }, ep, er;
    float q0[6] = { 395, -85, 90, -95, -90, 705 }, q[6];
    uint32_t i;
    DHT_EQ_INT(dhs_build(&dhs_ur5_m, &r), DH_OK);
    for (i = 0; i < 6; i++) DHT_EQ_INT(dh_robot_set_limits_f32(&r, i, -720.0f, 720.0f), DH_OK);
    dhs_target_f32(&r, qt, &T);
    dh_ik_params_default_f32(&r, &p);
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_OK);
    for (i = 0; i < 6; i++) DHT_NEAR(q[i], qt[i], 1e-2);
    dhs_true_error_f32(&r, q, &T, &ep, &er);
    DHT_TRUE_MSG(ep <= 1e-6 && er <= 1e-5, "true errors %.3g m / %.3g rad, bounds 1e-6 / 1e-5", ep, er);
}

/* Prismatic joints: a cartesian XYZ robot and a SCARA (R R P R), with
 * masks for the DOF they have. Also q may alias q0. */
static void ik_prismatic(void)
{
    dh_robot cart, scara;
    dh_ik_params_f32 p;
    int it, ok_c = 0, ok_s = 0, n = DHT_ITER(200);
    DHT_EQ_INT(dh_robot_init(&cart, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&cart, DH_JOINT_PRISMATIC, 0, 0, 0, -90), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&cart, DH_JOINT_PRISMATIC, -90, 0, 0, -90), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&cart, DH_JOINT_PRISMATIC, 0, 0.1f, 0, 0), DH_OK);
    DHT_EQ_INT(dh_robot_set_limits_f32(&cart, 0, 0.0f, 1.0f), DH_OK);
    DHT_EQ_INT(dh_robot_set_limits_f32(&cart, 1, -0.5f, 0.5f), DH_OK);
    DHT_EQ_INT(dh_robot_set_limits_f32(&cart, 2, -0.5f, 0.5f), DH_OK);
    /* SCARA: a1 = 0.35, a2 = 0.25, vertical prismatic, tool roll; alpha 180
     * on joint 2 points z down as on real SCARAs. */
    DHT_EQ_INT(dh_robot_init(&scara, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&scara, DH_JOINT_REVOLUTE, 0, 0.4f, 0.35f, 0), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&scara, DH_JOINT_REVOLUTE, 0, 0, 0.25f, 180), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&scara, DH_JOINT_PRISMATIC, 0, 0, 0, 0), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&scara, DH_JOINT_REVOLUTE, 0, 0.05f, 0, 0), DH_OK);
    DHT_EQ_INT(dh_robot_set_limits_f32(&scara, 0, -130.0f, 130.0f), DH_OK);
    DHT_EQ_INT(dh_robot_set_limits_f32(&scara, 1, 5.0f, 145.0f), DH_OK);
    DHT_EQ_INT(dh_robot_set_limits_f32(&scara, 2, 0.0f, 0.3f), DH_OK);
    DHT_EQ_INT(dh_robot_set_limits_f32(&scara, 3, -360.0f, 360.0f), DH_OK);
    dh_ik_params_default_f32(&cart, &p);
    p.tol_pos = 1e-6f;     /* the bound checked below, for both robots */
    for (it = 0; it < n; it++) {
        double qc[3], qs[4], ep, er;
        float q[4];
        dh_mat4_f32 T;
        dh_ik_result_f32 res;
        dh_status st;
        uint32_t i;
        dhs_random_q_robot(&cart, qc);
        dhs_target_f32(&cart, qc, &T);
        q[0] = 0.5f; q[1] = 0.0f; q[2] = 0.0f;
        p.mask = DH_IK_FULL;
        st = dh_ik_f32(&cart, &T, q, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res);
        dhs_true_error_f32(&cart, q, &T, &ep, &er);
        DHT_TRUE_MSG(within_limits(&cart, q), "cartesian: result outside the limits: q %s", dhs_qf_str(q, 3u, 0));
        if (st == DH_OK && ep <= 1e-6 && er <= 1e-5) ok_c++;
        for (i = 0; i < 3; i++) DHT_NEAR(q[i], qc[i], 2e-6);

        dhs_random_q_robot(&scara, qs);
        dhs_target_f32(&scara, qs, &T);
        q[0] = 0.0f; q[1] = 90.0f; q[2] = 0.15f; q[3] = 0.0f;
        p.mask = DH_IK_POSITION | DH_IK_RZ;
        st = dh_ik_f32(&scara, &T, q, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res);
        dhs_true_error_f32(&scara, q, &T, &ep, &er);
        DHT_TRUE_MSG(within_limits(&scara, q), "SCARA: result outside the limits: q %s", dhs_qf_str(q, 4u, 0));
        /* the SCARA keeps its tool vertical, so the full rotation matches too */
        if (st == DH_OK && ep <= 1e-6 && er <= 1e-5) ok_s++;
    }
    dht_printf("ik cartesian XYZ (P P P): %d/%d; SCARA (R R P R, mask xyz+rz): %d/%d\n", ok_c, n, ok_s, n);
    DHT_EQ_INT(ok_c, n);
    DHT_TRUE_MSG(ok_s >= (99 * n) / 100, "SCARA: %d/%d converged, need %d", ok_s, n, (99 * n) / 100);
}

/* Masked: only x and z of the Puma; the other components are free, so the
 * result matches the masked components only. Deterministic: same inputs,
 * bitwise same outputs. */
static void ik_masked_deterministic(void)
{
    dh_robot r;
    dh_ik_params_f32 p;
    dh_ik_result_f32 r1, r2;
    dh_mat4_f32 T;
    double qd[6] = { 20, 40, -50, 30, 60, -20 };
    float q1[6], q2[6];
    dhr_mat4 D;
    double qq[6];
    int k;
    DHT_EQ_INT(dhs_build(&dhs_puma560_m, &r), DH_OK);
    dhs_target_f32(&r, qd, &T);
    T.m[3][1] += 0.3f;     /* y is not asked for */
    dh_ik_params_default_f32(&r, &p);
    p.mask = DH_IK_PX | DH_IK_PZ;
    DHT_EQ_INT(dh_ik_f32(&r, &T, puma_home, &p, g_work, sizeof g_work / sizeof g_work[0], q1, &r1), DH_OK);
    DHT_EQ_INT(dh_ik_f32(&r, &T, puma_home, &p, g_work, sizeof g_work / sizeof g_work[0], q2, &r2), DH_OK);
    for (k = 0; k < 6; k++) DHT_EQ_F32_BITS(q1[k], q2[k]);
    DHT_EQ_INT(r1.iterations, r2.iterations);
    for (k = 0; k < 6; k++) qq[k] = (double)q1[k];
    dhs_fk_ref_f32(&r, qq, NULL, &D);
    DHT_NEAR(D.m[3][0], (double)T.m[3][0], 1e-6);
    DHT_NEAR(D.m[3][2], (double)T.m[3][2], 1e-6);
}

/* Start already at the solution: DH_OK, q stays within a few ulp. */
static void ik_start_at_solution(void)
{
    dh_robot r;
    dh_ik_params_f32 p;
    dh_ik_result_f32 res;
    dh_mat4_f32 T;
    double qd[7] = { 10, -30, 20, -100, 15, 80, 30 };
    float q0[7], q[7];
    int k;
    DHT_EQ_INT(dhs_build(&dhs_panda_m, &r), DH_OK);
    for (k = 0; k < 7; k++) q0[k] = (float)qd[k];
    dhs_target_f32(&r, qd, &T);
    dh_ik_params_default_f32(&r, &p);
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_OK);
    for (k = 0; k < 7; k++) DHT_NEAR(q[k], qd[k], 1e-3);
    DHT_TRUE_MSG(res.iterations <= 3u, "%lu iterations, bound <= 3", (unsigned long)res.iterations);    /* only the refinement steps */
}

/* Robot size as the tests define it (independently of the library): sum of
 * |a| and |d| of the joints (all revolute on the shipped robots) plus the
 * tool offset's length. */
static double robot_size(const dhs_robot *d)
{
    const double *t = d->tool.m[3];
    double L = sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
    unsigned i;
    for (i = 0; i < d->n; i++) L += fabs(d->j[i].a) + fabs(d->j[i].d);
    return L;
}

/* The defaults scale with the robot's size L (the tests' own sum of |a|
 * and |d|): tol_pos 1e-6 L, w_rot L / 4, the rest fixed; the mm model gets
 * 1000 times the metre model's lengths; a robot without lengths (n = 0, or
 * every a and d zero) L = 1. */
static void ik_params_default_scaled(void)
{
    static const dhs_robot *const robots[] = { &dhs_puma560_m, &dhs_puma560_mm, &dhs_ur5_m, &dhs_ur5_mm,
                                                &dhs_panda_m, &dhs_panda_mm };
    dh_robot r;
    dh_ik_params_f32 p;
    unsigned k;
    for (k = 0; k < 6u; k++) {
        const double L = robot_size(robots[k]);
        DHT_EQ_INT(dhs_build(robots[k], &r), DH_OK);
        dh_ik_params_default_f32(&r, &p);
        DHT_NEAR(p.tol_pos, 1e-6 * L, 1e-12 * L);
        DHT_NEAR(p.w_rot, 0.25 * L, 1e-6 * L);
        DHT_EQ_INT(p.max_iter, 2000);
        DHT_EQ_INT(p.restarts, 200);
        DHT_EQ_INT(p.mask, DH_IK_FULL);
        DHT_NEAR(p.tol_rot, 1e-5, 1e-12);
    }
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    dh_ik_params_default_f32(&r, &p);
    DHT_NEAR(p.tol_pos, 1e-6, 1e-12);
    DHT_NEAR(p.w_rot, 0.25, 1e-7);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0, 0, 0, 90), DH_OK);
    dh_ik_params_default_f32(&r, &p);
    DHT_NEAR(p.w_rot, 0.25, 1e-7);
}

/* The rotation weight does not decide success: on a fixed list of 200
 * reachable Puma targets (m and mm), every w_rot from 0.1 to 30 times the
 * robot's size and the heavy 100 and 1000 m/rad (x unit) converges for
 * >= 99% of them, and no status is SINGULAR (finite input). Heavy weights
 * make J^T W^2 J indefinite in float (pivots <= 0) near singular targets. */
static void ik_weight_insensitive(void)
{
    static const double factor[] = { 0.1, 0.3, 1.0, 3.0, 10.0, 30.0 };
    static const double absolute[] = { 3.0, 100.0, 1000.0 };     /* m/rad, times unit_per_m */
    static const dhs_robot *const robots[] = { &dhs_puma560_m, &dhs_puma560_mm };
    const uint64_t s0 = dht_seed();
    const int count = DHT_ITER(200);
    unsigned ri, k;
    for (ri = 0; ri < 2u; ri++) {
        const dhs_robot *d = robots[ri];
        const double size = robot_size(d), u = d->unit_per_m;
        for (k = 0; k < 9u; k++) {
            const double w = (k < 6u) ? factor[k] * size : absolute[k - 6u] * u;
            dh_robot r;
            dh_ik_params_f32 prm;
            ik_stats s;
            char name[48];
            DHT_EQ_INT(dhs_build(d, &r), DH_OK);
            dh_ik_params_default_f32(&r, &prm);
            prm.tol_pos = (float)(1e-6 * u);
            prm.w_rot = (float)w;
            (void)snprintf(name, sizeof name, "%s w_rot %g", u > 1 ? "puma560 (mm)" : "puma560 (m)", w);
            dht_reseed(0x1d2c3b4au);        /* the same target list whatever the run's seed */
            run_rate(name, d, puma_home, 1e-6 * u, 1e-5, &prm, count, &s);
            dht_printf("ik %s: %d/%d converged (w_rot = %.3g x size %.4g), iterations mean %.2f max %lu\n", name,
                       s.ok, s.runs, w / size, size, s.iter_sum / s.runs, (unsigned long)s.iter_max);
            DHT_TRUE_MSG(s.ok * 100 >= 99 * s.runs, "%s: %d/%d converged, need 99%% (tol %g / 1e-5)", name, s.ok,
                         s.runs, 1e-6 * u);
        }
    }
    dht_reseed(s0);
}

/* A UR5 target whose normal matrix has a finite pivot <= 0 in float on the
 * way (SINGULAR after 2000 steps at 2.4e-6 m without the pivot rule):
 * tol 1e-6 m / 1e-5 rad, w_rot 1 m/rad, home start, limits +-360 (the
 * shipped model). */
static void ik_ur5_hard_target(void)
{
    static const double qt[6] = { 299.51278838944893, 54.07958061836041, 60.844163601340369,
                                  -52.798711358032733, -186.32417516489036, -192.67032377374386 };
    dh_robot r;
    dh_ik_params_f32 p;
    dh_ik_result_f32 res;
    dh_mat4_f32 T;
    float q[6];
    double ep, er;
    dh_status st;
    DHT_EQ_INT(dhs_build(&dhs_ur5_m, &r), DH_OK);
    dhs_target_f32(&r, qt, &T);
    dh_ik_params_default_f32(&r, &p);
    p.tol_pos = 1e-6f;
    p.w_rot = 1.0f;
    st = dh_ik_f32(&r, &T, ur5_home, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res);
    dhs_true_error_f32(&r, q, &T, &ep, &er);
    dht_printf("ur5 hard target: status %d after %lu iterations, true error %.3g m / %.3g rad\n", (int)st,
               (unsigned long)res.iterations, ep, er);
    DHT_TRUE_MSG(st == DH_OK && ep <= 1e-6 && er <= 1e-5,
                 "ur5 target q %s: status %d (%s), %lu iterations, true error %.3g m / %.3g rad (bounds 1e-6 / 1e-5)",
                 dhs_q_str(qt, 6u, 0), (int)st, dh_status_str(st), (unsigned long)res.iterations, ep, er);
}

/* Prismatic joints without limits reach distant targets: a lone P joint
 * to z = 100 (an uncapped damping mu E, E = 5000 against a column of 1,
 * allows steps of 1/5000 of the error), and an R R P arm with 0.5 m links
 * to targets 5 .. 500 m away, position only, tol_pos 1e-6 x the distance
 * (the float resolution of 500 is 3e-5). */
static void ik_prismatic_unlimited(void)
{
    dh_robot r;
    dh_ik_params_f32 p;
    dh_ik_result_f32 res;
    dh_mat4_f32 T;
    float q0[3] = { 0, 0, 0 }, q[3];
    double ep, er;
    dh_status st;
    unsigned k;
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_PRISMATIC, 0, 0, 0, 0), DH_OK);
    dh_mat4_identity_f32(&T);
    T.m[3][2] = 100.0f;
    dh_ik_params_default_f32(&r, &p);
    st = dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res);
    dht_printf("P to z = 100: status %d after %lu iterations, q %.9g\n", (int)st, (unsigned long)res.iterations,
               (double)q[0]);
    DHT_TRUE_MSG(st == DH_OK && res.iterations <= 20u,
                 "P to z = 100: status %d (%s) after %lu iterations (bound 20), q = %.9g", (int)st,
                 dh_status_str(st), (unsigned long)res.iterations, (double)q[0]);
    DHT_NEAR(q[0], 100.0, 1e-4);

    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0, 0.5f, 0, 90), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0, 0, 0.5f, 90), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_PRISMATIC, 0, 0, 0, 0), DH_OK);
    for (k = 0; k < 4u; k++) {
        static const float tgt[4][3] = { { 0, 0, 500 }, { 0, 0, 5 }, { 30, -40, 50 }, { -300, 200, -250 } };
        double dist = 0;
        unsigned i;
        dh_mat4_identity_f32(&T);
        for (i = 0; i < 3u; i++) {
            T.m[3][i] = tgt[k][i];
            dist += (double)tgt[k][i] * tgt[k][i];
        }
        dist = sqrt(dist);
        dh_ik_params_default_f32(&r, &p);
        p.mask = DH_IK_POSITION;
        p.tol_pos = (float)(1e-6 * dist);
        st = dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res);
        dhs_true_error_f32(&r, q, &T, &ep, &er);
        dht_printf("R R P to (%g, %g, %g): status %d after %lu iterations, q %s, true error %.3g\n",
                   (double)tgt[k][0], (double)tgt[k][1], (double)tgt[k][2], (int)st, (unsigned long)res.iterations,
                   dhs_qf_str(q, 3u, 0), ep);
        DHT_TRUE_MSG(st == DH_OK && ep <= 1e-6 * dist,
                     "R R P to (%g, %g, %g): status %d (%s) after %lu iterations, q %s, true error %.3g > %.3g",
                     (double)tgt[k][0], (double)tgt[k][1], (double)tgt[k][2], (int)st, dh_status_str(st),
                     (unsigned long)res.iterations, dhs_qf_str(q, 3u, 0), ep, 1e-6 * dist);
    }
}

/* Finite input whose normal matrix overflows: a revolute joint with a
 * lever of 1e20 (unlimited prismatic joint), target 0.001 deg away.
 * (J^T J)_11 = 1e40 is not a float; the solver retries with more damping
 * and ends as a stall (UNREACHABLE), never SINGULAR, with a finite q in
 * the limits that res describes. */
static void ik_normal_overflow(void)
{
    dh_robot r;
    dh_ik_params_f32 p;
    dh_ik_result_f32 res;
    dh_mat4_f32 T;
    const float q0[2] = { 0.0f, 1e20f }, qt[2] = { 1e-3f, 1e20f };
    float q[2];
    dh_status st;
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0, 0, 0, 90), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_PRISMATIC, 0, 0, 0, 0), DH_OK);
    DHT_EQ_INT(dh_fk_f32(&r, qt, &T), DH_OK);
    dh_ik_params_default_f32(&r, &p);
    p.mask = DH_IK_POSITION;
    st = dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res);
    dht_printf("normal matrix overflow: status %d after %lu iterations, q %s, err_pos %.4g\n", (int)st,
               (unsigned long)res.iterations, dhs_qf_str(q, 2u, 0), (double)res.err_pos);
    DHT_TRUE_MSG(st == DH_ERR_UNREACHABLE || st == DH_ERR_NO_CONVERGENCE || st == DH_OK,
                 "status %d (%s) after %lu iterations, expected UNREACHABLE, NO_CONVERGENCE or OK", (int)st,
                 dh_status_str(st), (unsigned long)res.iterations);
    DHT_TRUE_MSG(within_limits(&r, q) && q[0] == q[0] && q[1] == q[1] && res.err_pos == res.err_pos &&
                 res.err_pos <= FLT_MAX, "q %s, err_pos %g: not finite", dhs_qf_str(q, 2u, 0), (double)res.err_pos);
}

/* A robot in millimetres converges with its defaults (no parameter set by
 * hand): >= 99 of 100 reachable targets per shipped mm model, fixed list,
 * with true errors within the defaults' tolerances. */
static void ik_mm_defaults(void)
{
    static const dhs_robot *const robots[] = { &dhs_puma560_mm, &dhs_ur5_mm, &dhs_panda_mm };
    static const float *const homes[] = { puma_home, ur5_home, panda_home };
    const uint64_t s0 = dht_seed();
    const int count = DHT_ITER(100);
    unsigned k;
    for (k = 0; k < 3u; k++) {
        dh_robot r;
        dh_ik_params_f32 prm;
        ik_stats s;
        DHT_EQ_INT(dhs_build(robots[k], &r), DH_OK);
        dh_ik_params_default_f32(&r, &prm);
        dht_reseed(0x5a17e0u + k);
        run_rate("mm defaults", robots[k], homes[k], (double)prm.tol_pos, (double)prm.tol_rot, &prm, count, &s);
        dht_printf("ik mm robot %u with its defaults (tol_pos %g mm, w_rot %g mm/rad): %d/%d, iterations mean %.2f\n",
                   k, (double)prm.tol_pos, (double)prm.w_rot, s.ok, s.runs, s.iter_sum / s.runs);
        DHT_TRUE_MSG(s.ok * 100 >= 99 * s.runs, "mm robot %u with its defaults (tol_pos %g, w_rot %g): %d/%d, need 99%%",
                     k, (double)prm.tol_pos, (double)prm.w_rot, s.ok, s.runs);
    }
    dht_reseed(s0);
}

static const dht_case cases[] = {
    DHT_CASE(ik_bad_arguments),
    DHT_CASE(ik_unreachable),
    DHT_CASE(ik_limits_respected),
    DHT_CASE(ik_multiturn),
    DHT_CASE(ik_prismatic),
    DHT_CASE(ik_masked_deterministic),
    DHT_CASE(ik_start_at_solution),
    DHT_CASE(ik_params_default_scaled),
    DHT_CASE(ik_weight_insensitive),
    DHT_CASE(ik_ur5_hard_target),
    DHT_CASE(ik_prismatic_unlimited),
    DHT_CASE(ik_normal_overflow),
    DHT_CASE(ik_mm_defaults),
    DHT_CASE(ik_rate_puma),
    DHT_CASE(ik_rate_ur5),
    DHT_CASE(ik_rate_panda),
    DHT_CASE(ik_rate_position),
    DHT_CASE(ik_rate_mm),
};
DHT_MAIN(cases)
