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
#include "dhmath/dh_kin.h"
#include "dhmath/dh_mat4.h"

#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846
#define D2R (PI / 180.0)
#define NJ DH_MAX_JOINTS

static float g_work[DH_IK_WORK_FLOATS(NJ)];

/* ---------------------------------------------------------------------- */

/* Rotation vector angle of R (column-major 3x3, double), robust. */
static double rot_angle(double R[3][3])
{
    double ux = R[1][2] - R[2][1], uy = R[2][0] - R[0][2], uz = R[0][1] - R[1][0];
    double s = sqrt(ux * ux + uy * uy + uz * uz), c = R[0][0] + R[1][1] + R[2][2] - 1.0;
    return atan2(s, c);
}

/* True errors of float q for the float target: position norm and rotation
 * angle of R_target R(q)^T, both from the double reference FK. */
static void true_error(const dh_robot *r, const float *q, const dh_mat4_f32 *target, double *ep, double *er)
{
    dhs_mat4_d T;
    double qd[NJ], D[3][3];
    uint32_t i;
    int a, b, k;
    for (i = 0; i < r->n; i++) qd[i] = (double)q[i];
    dhs_fk_ref_f32(r, qd, NULL, &T);
    *ep = 0;
    for (k = 0; k < 3; k++) {
        double d = (double)target->m[3][k] - T.m[3][k];
        *ep += d * d;
    }
    *ep = sqrt(*ep);
    for (a = 0; a < 3; a++)
        for (b = 0; b < 3; b++) {
            double s = 0;
            for (k = 0; k < 3; k++) s += (double)target->m[k][a] * T.m[k][b];
            D[b][a] = s;
        }
    *er = rot_angle(D);
}

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

static void target_of(const dh_robot *r, const double *q, dh_mat4_f32 *T)
{
    dhs_mat4_d D;
    int c, k;
    dhs_fk_ref_f32(r, q, NULL, &D);
    for (c = 0; c < 4; c++)
        for (k = 0; k < 4; k++) T->m[c][k] = (float)D.m[c][k];
}

/* ---------------------------------------------------------------------- */
/* success rate on random reachable targets                                 */

typedef struct {
    int runs, ok, ok_status;
    double iter_sum;
    uint32_t iter_max;
    double ep_max, er_max;       /* worst true errors among successes */
} ik_stats;

static void run_rate(const dhs_robot *desc, const float *home, uint32_t mask, double tol_p, double tol_r,
                     const dh_ik_params *prm, int count, ik_stats *s)
{
    dh_robot r;
    int it;
    memset(s, 0, sizeof *s);
    DHT_EQ_INT(dhs_build(desc, &r), DH_OK);
    for (it = 0; it < count; it++) {
        double q[NJ], ep, er;
        float qo[NJ];
        dh_mat4_f32 T;
        dh_ik_result res;
        dh_status st;
        dhs_random_q(desc, q);
        target_of(&r, q, &T);
        st = dh_ik_f32(&r, &T, home, prm, g_work, DH_IK_WORK_FLOATS(r.n), qo, &res);
        /* whatever the status: a finite configuration within the limits,
         * and res describes it */
        DHT_TRUE(st == DH_OK || st == DH_ERR_NO_CONVERGENCE || st == DH_ERR_UNREACHABLE);
        DHT_TRUE(within_limits(&r, qo));
        true_error(&r, qo, &T, &ep, &er);
        DHT_TRUE(res.iterations <= prm->max_iter);
        s->runs++;
        s->iter_sum += res.iterations;
        if (res.iterations > s->iter_max) s->iter_max = res.iterations;
        if (st == DH_OK) {
            s->ok_status++;
            /* the reported errors are the library's float estimate */
            DHT_TRUE(res.err_pos <= prm->tol_pos && res.err_rot <= prm->tol_rot);
        }
        if (mask == DH_IK_POSITION) er = 0;
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

static void rate_case(const char *name, const dhs_robot *desc, const float *home, uint32_t mask,
                      double tol_p, double tol_r, double need, unsigned nseeds)
{
    dh_ik_params prm;
    ik_stats s;
    const uint64_t s0 = dht_seed();
    uint64_t worst_seed = s0;
    int worst_ok = -1, worst_runs = 1;
    unsigned k;
    dh_ik_params_default(&prm);
    prm.mask = mask;
    prm.tol_pos = (float)tol_p;
    prm.tol_rot = (float)tol_r;
    prm.w_rot = (float)desc->unit_per_m;
    if (nseeds > sizeof extra_seeds / sizeof extra_seeds[0]) nseeds = sizeof extra_seeds / sizeof extra_seeds[0];
    /* Scaled-down runs (slow targets: a few targets per seed) check the run's
     * seed only: with 5..50 targets, 99% means no miss at all, and every
     * extra seed would add another chance of one legitimate miss. */
    if (DHT_ITER(1000) < 1000) nseeds = 0u;
    for (k = 0; k <= nseeds; k++) {
        const uint64_t seed = (k == 0u) ? s0 : extra_seeds[k - 1u];
        if (k > 0u && seed == s0) continue;
        dht_reseed(seed);
        run_rate(desc, home, mask, tol_p, tol_r, &prm, DHT_ITER(1000), &s);
        dht_printf("ik %-22s %s seed 0x%llx: %d/%d converged with true error <= %.0e / %.0e (status OK %d), "
                   "iterations mean %.2f max %llu, worst true error %.3g / %.3g\n",
                   name, mask == DH_IK_POSITION ? "position" : "full", (unsigned long long)seed, s.ok, s.runs,
                   tol_p, tol_r, s.ok_status, s.iter_sum / s.runs, (unsigned long long)s.iter_max, s.ep_max,
                   s.er_max);
        if (worst_ok < 0 || (double)s.ok * worst_runs < (double)worst_ok * s.runs) {
            worst_ok = s.ok;
            worst_runs = s.runs;
            worst_seed = seed;
        }
    }
    dht_reseed(s0);     /* the following cases start from the run's seed again */
    DHT_TRUE_MSG((double)worst_ok >= need * worst_runs, "%s: success %d/%d below %.3f for seed 0x%llx", name,
                 worst_ok, worst_runs, need, (unsigned long long)worst_seed);
}

/* Home poses away from singularities (deg). Puma: elbow bent, wrist q5 != 0;
 * UR5: its usual "up" pose with q5 = -90; Panda: the manufacturer's ready
 * pose (the zero pose violates its joint-4 limit). */
static const float puma_home[6] = { 0, 30, -60, 0, 45, 0 };
static const float ur5_home[6] = { 0, -90, 90, -90, -90, 0 };
static const float panda_home[7] = { 0, -45, 0, -135, 0, 90, 45 };

static void ik_rate_puma(void) { rate_case("puma560 (m)", &dhs_puma560_m, puma_home, DH_IK_FULL, 1e-6, 1e-5, 0.99, 6u); }
static void ik_rate_ur5(void) { rate_case("ur5 (m)", &dhs_ur5_m, ur5_home, DH_IK_FULL, 1e-6, 1e-5, 0.99, 6u); }
static void ik_rate_panda(void) { rate_case("panda (m)", &dhs_panda_m, panda_home, DH_IK_FULL, 1e-6, 1e-5, 0.99, 6u); }
static void ik_rate_position(void)
{
    rate_case("puma560 (m)", &dhs_puma560_m, puma_home, DH_IK_POSITION, 1e-6, 1e-5, 0.99, 2u);
    rate_case("ur5 (m)", &dhs_ur5_m, ur5_home, DH_IK_POSITION, 1e-6, 1e-5, 0.99, 2u);
    rate_case("panda (m)", &dhs_panda_m, panda_home, DH_IK_POSITION, 1e-6, 1e-5, 0.99, 2u);
}
/* Millimetre models: 1e-3 mm = 1e-6 m, float resolution of 1000 mm is 6e-5 mm. */
static void ik_rate_mm(void)
{
    rate_case("puma560 (mm)", &dhs_puma560_mm, puma_home, DH_IK_FULL, 1e-3, 1e-5, 0.99, 4u);
    rate_case("ur5 (mm)", &dhs_ur5_mm, ur5_home, DH_IK_FULL, 1e-3, 1e-5, 0.99, 2u);
    rate_case("panda (mm)", &dhs_panda_mm, panda_home, DH_IK_FULL, 1e-3, 1e-5, 0.99, 2u);
}

/* ---------------------------------------------------------------------- */
/* deterministic cases                                                     */

static void ik_bad_arguments(void)
{
    dh_robot r;
    dh_ik_params p;
    dh_ik_result res;
    dh_mat4_f32 T;
    float q[6], q0[6] = { 0, 30, -60, 0, 45, 0 };
    double qd[6] = { 10, 20, -30, 40, 50, 60 };
    int k;
    DHT_EQ_INT(dhs_build(&dhs_puma560_m, &r), DH_OK);
    target_of(&r, qd, &T);
    dh_ik_params_default(&p);
    for (k = 0; k < 6; k++) q[k] = 99.0f;
    res.iterations = 77u;

    /* workspace too small / missing */
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, DH_IK_WORK_FLOATS(6u) - 1u, q, &res), DH_ERR_ARG);
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, NULL, 0, q, &res), DH_ERR_ARG);
    /* bad parameters */
    p.max_iter = 0;
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_ERR_ARG);
    dh_ik_params_default(&p);
    p.mask = 0;
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_ERR_ARG);
    p.mask = 0x40u;
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_ERR_ARG);
    dh_ik_params_default(&p);
    p.tol_pos = -1.0f;
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_ERR_ARG);
    dh_ik_params_default(&p);
    p.tol_rot = NAN;
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_ERR_ARG);
    dh_ik_params_default(&p);
    p.w_rot = 0.0f;
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_ERR_ARG);
    dh_ik_params_default(&p);
    /* NaN target / NaN start */
    T.m[3][1] = NAN;
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_ERR_NAN);
    target_of(&r, qd, &T);
    T.m[0][0] = INFINITY;
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_ERR_NAN);
    target_of(&r, qd, &T);
    q0[2] = NAN;
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_ERR_NAN);
    q0[2] = -60.0f;
    /* target rotation not a rotation */
    T.m[0][0] *= 2.0f;
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_ERR_NOT_RIGID);
    /* ... which does not matter for position-only IK */
    p.mask = DH_IK_POSITION;
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_OK);
    dh_ik_params_default(&p);
    for (k = 0; k < 6; k++) q[k] = 99.0f;
    res.iterations = 77u;
    /* no joints */
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_ERR_ARG);
    /* outputs untouched on argument errors */
    for (k = 0; k < 6; k++) DHT_TRUE(q[k] == 99.0f);
    DHT_EQ_INT(res.iterations, 77);
}

/* A target twice as far as the arm reaches: no convergence, but a finite
 * best effort within limits whose reported residual is the true one, with
 * the arm stretched towards the target. */
static void ik_unreachable(void)
{
    dh_robot r;
    dh_ik_params p;
    dh_ik_result res;
    dh_mat4_f32 T;
    float q[6];
    double ep, er;
    dh_status st;
    DHT_EQ_INT(dhs_build(&dhs_puma560_m, &r), DH_OK);
    dh_ik_params_default(&p);
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
    DHT_TRUE(res.iterations < 400u);
    DHT_TRUE(within_limits(&r, q));
    true_error(&r, q, &T, &ep, &er);
    DHT_NEAR(res.err_pos, ep, 1e-5);
    /* reach of the Puma is < 1.1 m from the shoulder at z = 0.672: the
     * distance to (2, 0.5, 1) can't be below 2.06 - 1.1 */
    DHT_TRUE(ep > 0.9 && ep < 1.3);
    /* position only: the closest point is the stretched arm, distance
     * |target - shoulder| - reach, found to 1e-3 */
    p.mask = DH_IK_POSITION;
    st = dh_ik_f32(&r, &T, puma_home, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res);
    DHT_EQ_INT(st, DH_ERR_UNREACHABLE);
    DHT_TRUE(res.iterations < 400u);
    DHT_TRUE(within_limits(&r, q));
    true_error(&r, q, &T, &ep, &er);
    DHT_NEAR(res.err_pos, ep, 1e-5);
    dht_printf("unreachable target, position only: status %d after %lu iterations, residual %.6g m\n", (int)st,
               (unsigned long)res.iterations, ep);
    /* without restarts the stall is reported as such, quickly */
    p.restarts = 0;
    st = dh_ik_f32(&r, &T, puma_home, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res);
    dht_printf("unreachable target, no restarts: status %d after %lu iterations, residual %.6g m\n", (int)st,
               (unsigned long)res.iterations, (double)res.err_pos);
    DHT_EQ_INT(st, DH_ERR_UNREACHABLE);
    DHT_TRUE(res.iterations < 100u);
    DHT_TRUE(within_limits(&r, q));
    true_error(&r, q, &T, &ep, &er);
    DHT_NEAR(res.err_pos, ep, 1e-5);
    DHT_TRUE(ep > 0.9 && ep < 1.3);
}

/* Planar 2R arm (l1 = 0.6, l2 = 0.4), position x/y only. The target has two
 * solutions, elbow q2 = -70 (reached without limits from q0 = (0, -10)) and
 * q2 = +70. With q2 limited to [0, 150] the solver must not pass through
 * the forbidden side: it returns the elbow-up solution, within limits. */
static void ik_limits_respected(void)
{
    dh_robot r;
    dh_ik_params p;
    dh_ik_result res;
    dh_mat4_f32 T;
    double qt[2] = { 35, -70 }, ep, er;
    float q0[2] = { 0, -10 }, q[2];
    const float l1 = 0.6f, l2 = 0.4f;
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0, 0, l1, 0), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0, 0, l2, 0), DH_OK);
    target_of(&r, qt, &T);
    dh_ik_params_default(&p);
    p.mask = DH_IK_PX | DH_IK_PY;
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_OK);
    DHT_NEAR(q[1], -70.0, 1e-3);            /* unconstrained: elbow down */
    DHT_EQ_INT(dh_robot_set_limits_f32(&r, 1, 0.0f, 150.0f), DH_OK);
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_OK);
    DHT_TRUE(within_limits(&r, q));
    DHT_NEAR(q[1], 70.0, 1e-3);             /* elbow up */
    true_error(&r, q, &T, &ep, &er);
    DHT_TRUE(ep <= 1e-6);
    /* q1 limited too, to [50, 90]: the elbow-up solution needs q1 = 35 - 70
     * ... = -35 (outside), the elbow-down one q1 = 35 with q2 = -70 (outside):
     * no admissible solution. Best effort within limits, UNREACHABLE. */
    DHT_EQ_INT(dh_robot_set_limits_f32(&r, 0, 50.0f, 90.0f), DH_OK);
    {
        dh_status st = dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res);
        DHT_EQ_INT(st, DH_ERR_UNREACHABLE);     /* every attempt stalls at the limits */
        DHT_TRUE(within_limits(&r, q));
        true_error(&r, q, &T, &ep, &er);
        DHT_TRUE(ep > 1e-3);
        DHT_NEAR(res.err_pos, ep, 1e-6);
    }
}

/* Joint with more than 360 degrees of travel: the solution is found next to
 * the start, not wrapped into +-180. */
static void ik_multiturn(void)
{
    dh_robot r;
    dh_ik_params p;
    dh_ik_result res;
    dh_mat4_f32 T;
    double qt[6] = { 400, -80, 95, -100, -85, 700 }, ep, er;
    float q0[6] = { 395, -85, 90, -95, -90, 705 }, q[6];
    uint32_t i;
    DHT_EQ_INT(dhs_build(&dhs_ur5_m, &r), DH_OK);
    for (i = 0; i < 6; i++) DHT_EQ_INT(dh_robot_set_limits_f32(&r, i, -720.0f, 720.0f), DH_OK);
    target_of(&r, qt, &T);
    dh_ik_params_default(&p);
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_OK);
    for (i = 0; i < 6; i++) DHT_NEAR(q[i], qt[i], 1e-2);
    true_error(&r, q, &T, &ep, &er);
    DHT_TRUE(ep <= 1e-6 && er <= 1e-5);
}

/* Prismatic joints: a cartesian XYZ robot and a SCARA (R R P R), with
 * masks for the DOF they have. Also q may alias q0. */
static void ik_prismatic(void)
{
    dh_robot cart, scara;
    dh_ik_params p;
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
    dh_ik_params_default(&p);
    for (it = 0; it < n; it++) {
        double qc[3], qs[4], ep, er;
        float q[4];
        dh_mat4_f32 T;
        dh_ik_result res;
        dh_status st;
        uint32_t i;
        dhs_random_q_robot(&cart, qc);
        target_of(&cart, qc, &T);
        q[0] = 0.5f; q[1] = 0.0f; q[2] = 0.0f;
        p.mask = DH_IK_FULL;
        st = dh_ik_f32(&cart, &T, q, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res);
        true_error(&cart, q, &T, &ep, &er);
        DHT_TRUE(within_limits(&cart, q));
        if (st == DH_OK && ep <= 1e-6 && er <= 1e-5) ok_c++;
        for (i = 0; i < 3; i++) DHT_NEAR(q[i], qc[i], 2e-6);

        dhs_random_q_robot(&scara, qs);
        target_of(&scara, qs, &T);
        q[0] = 0.0f; q[1] = 90.0f; q[2] = 0.15f; q[3] = 0.0f;
        p.mask = DH_IK_POSITION | DH_IK_RZ;
        st = dh_ik_f32(&scara, &T, q, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res);
        true_error(&scara, q, &T, &ep, &er);
        DHT_TRUE(within_limits(&scara, q));
        /* the SCARA keeps its tool vertical, so the full rotation matches too */
        if (st == DH_OK && ep <= 1e-6 && er <= 1e-5) ok_s++;
    }
    dht_printf("ik cartesian XYZ (P P P): %d/%d; SCARA (R R P R, mask xyz+rz): %d/%d\n", ok_c, n, ok_s, n);
    DHT_EQ_INT(ok_c, n);
    DHT_TRUE(ok_s >= (99 * n) / 100);
}

/* Masked: only x and z of the Puma; the other components are free, so the
 * result matches the masked components only. Deterministic: same inputs,
 * bitwise same outputs. */
static void ik_masked_deterministic(void)
{
    dh_robot r;
    dh_ik_params p;
    dh_ik_result r1, r2;
    dh_mat4_f32 T;
    double qd[6] = { 20, 40, -50, 30, 60, -20 };
    float q1[6], q2[6];
    dhs_mat4_d D;
    double qq[6];
    int k;
    DHT_EQ_INT(dhs_build(&dhs_puma560_m, &r), DH_OK);
    target_of(&r, qd, &T);
    T.m[3][1] += 0.3f;     /* y is not asked for */
    dh_ik_params_default(&p);
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
    dh_ik_params p;
    dh_ik_result res;
    dh_mat4_f32 T;
    double qd[7] = { 10, -30, 20, -100, 15, 80, 30 };
    float q0[7], q[7];
    int k;
    DHT_EQ_INT(dhs_build(&dhs_panda_m, &r), DH_OK);
    for (k = 0; k < 7; k++) q0[k] = (float)qd[k];
    target_of(&r, qd, &T);
    dh_ik_params_default(&p);
    DHT_EQ_INT(dh_ik_f32(&r, &T, q0, &p, g_work, sizeof g_work / sizeof g_work[0], q, &res), DH_OK);
    for (k = 0; k < 7; k++) DHT_NEAR(q[k], qd[k], 1e-3);
    DHT_TRUE(res.iterations <= 3u);    /* only the refinement steps */
}

static const dht_case cases[] = {
    DHT_CASE(ik_bad_arguments),
    DHT_CASE(ik_unreachable),
    DHT_CASE(ik_limits_respected),
    DHT_CASE(ik_multiturn),
    DHT_CASE(ik_prismatic),
    DHT_CASE(ik_masked_deterministic),
    DHT_CASE(ik_start_at_solution),
    DHT_CASE(ik_rate_puma),
    DHT_CASE(ik_rate_ur5),
    DHT_CASE(ik_rate_panda),
    DHT_CASE(ik_rate_position),
    DHT_CASE(ik_rate_mm),
};
DHT_MAIN(cases)
