/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_ikc_calib.c - closed-form IK of calibrated robots, float: a UR5
 * whose a, d deviate by up to 2 mm and whose twists and theta offsets by
 * up to 0.5 deg, drawn at random for each seed (every other one with a
 * random base and tool frame); and robots beyond the calibration
 * tolerance, which have no closed form.
 *
 * Every solution is judged in double, independently of the library: its
 * joint values go through the double reference FK of the exact robot's
 * stored float parameters (dhs_true_error_f32). The generating
 * configuration (at least GEN_MIN from every singularity, sing_of) must be
 * among the solutions. The number of solutions must equal the idealised
 * robot's (the twists snapped, a5 0; an exact family) for the same target
 * only where every solution of the idealised robot is SING_MIN (3e-2) from
 * its singularities: nearer one, the deviations make branches appear or
 * disappear (a branch of the idealised robot 1.07e-2 L inside the elbow's
 * boundary has no twin on the calibrated one), and only where the wrist
 * flip of every idealised solution that the idealised robot lacks lies
 * beyond the elbow's reach by more than FLIP_BAND / |s5| (flip_margin):
 * the calibrated robot's joint 1 differs from the idealised one's by up to
 * degrees, which the wrist turns into a planar point moved by up to
 * 4.4e-3 L / |s5| (3.4e-2 L at q5 = 7.5 deg), so such a branch may exist
 * on the calibrated robot and is then found.
 */
#include "dht.h"
#include "support_ikc.h"
#include "dhmath/ikc.h"

#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846
#define D2R (PI / 180.0)
#define TOL_POS 2e-6
#define TOL_ROT 2e-6
#define NJ DH_IKC_JOINTS
/* Normalised distances from the singularities (sing_of): the generating
 * configuration at least GEN_MIN from the wrist and shoulder singularities
 * (the 1e-2: s5 >= 0.1) and its joint 5 point GEN_ELBOW L from the
 * elbow's boundary (stretched or folded): the UR5's deviations move that
 * boundary by up to about 1.3e-2 L, and a branch whose idealised twin lies
 * beyond the idealised robot's reach is not found (the closed form gives
 * no start for it; ikc.h); the counts compared where every idealised
 * solution is at least SING_MIN from all three. */
#define GEN_MIN 1e-2
#define GEN_ELBOW 3e-2
#define SING_MIN 3e-2
/* twice the largest planar shift of a wrist-flipped branch measured, times |s5| (L) */
#define FLIP_BAND 1e-2
/* deg: a solution this near the generating configuration on every joint is
 * it; the nearest other branch lies degrees away at GEN_MIN (joint 5
 * flipped at |s5| = 0.1: 11 deg). */
#define GEN_DEG 0.05
/* configurations per drawn robot (at DHT_ITER_DIV 1: 10 robots) */
#define PER_ROBOT 1000L

/* ---- the robots -------------------------------------------------------------- */

/* d widened to +-360 deg on every joint (the limits drop no branch) */
static void open_limits(dhs_robot *d)
{
    unsigned i;
    for (i = 0; i < d->n; i++) {
        d->j[i].qmin = -360.0;
        d->j[i].qmax = 360.0;
    }
}

/* twist snapped to the nearest multiple of 90 deg */
static double snap90(double a)
{
    return 90.0 * floor(a / 90.0 + 0.5);
}

/* A rigid frame: Rz Rx Rz of random angles, translation within +-t (m),
 * its entries rounded to float (the description and the float robot hold
 * the same frame). */
static void draw_frame(dhr_mat4 *F, double t)
{
    dhr_mat4 A, B;
    int c, k;
    dhr_rotz(dht_rand_uniform(-180, 180), &A);
    dhr_rotx(dht_rand_uniform(-180, 180), &B);
    dhr_mul(&A, &B, F);
    dhr_rotz(dht_rand_uniform(-180, 180), &A);
    dhr_mul(F, &A, F);
    for (k = 0; k < 3; k++) F->m[3][k] = dht_rand_uniform(-t, t);
    for (c = 0; c < 4; c++)
        for (k = 0; k < 4; k++) F->m[c][k] = (double)(float)F->m[c][k];
}

/* A UR5 with every a and d off by up to dl (m) and every twist and theta
 * offset by up to da (deg) into cal, with a random base and tool frame
 * when frames is set; its idealised twin (twists snapped, a5 = 0) into
 * ideal. */
static void draw_ur5(double dl, double da, int frames, dhs_robot *cal, dhs_robot *ideal)
{
    unsigned i;
    *cal = dhs_ur5_m;
    open_limits(cal);
    if (frames) {
        draw_frame(&cal->base, 0.5);
        draw_frame(&cal->tool, 0.15);
    }
    for (i = 0; i < 6u; i++) {
        cal->j[i].a += dht_rand_uniform(-dl, dl);
        cal->j[i].d += dht_rand_uniform(-dl, dl);
        cal->j[i].alpha_deg += dht_rand_uniform(-da, da);
        cal->j[i].theta_deg += dht_rand_uniform(-da, da);
    }
    *ideal = *cal;
    for (i = 0; i < 6u; i++) ideal->j[i].alpha_deg = snap90(cal->j[i].alpha_deg);
    ideal->j[4].a = 0.0;
}

/* Normalised distances from the singularities, the smallest returned:
 * wrist s5^2; shoulder (u / L)^2 with u the joint 5 point's coordinate
 * along x1 (dhk_sing_parts) and L the sum of |a| and |d|; elbow: the joint
 * 5 point's distance from the boundary of the elbow's annulus (stretched or
 * folded) over L, divided by elbow_scale. */
static double sing_of(const dhs_robot *d, const double *q, double elbow_scale)
{
    double part[3], best, l1, l2, th, reach = 0.0, v;
    unsigned i;
    for (i = 0; i < d->n; i++) reach += fabs(d->j[i].a) + fabs(d->j[i].d);
    l1 = fabs(d->j[1].a);
    l2 = fabs(d->j[2].a);
    th = (q[2] + d->j[2].theta_deg) * D2R;
    (void)dhk_sing_parts(d, q, part);
    if (d->j[1].a * d->j[2].a < 0.0) th += PI;
    v = sqrt(l1 * l1 + l2 * l2 + 2.0 * l1 * l2 * cos(th));
    part[1] = ((l1 + l2 - v < v - fabs(l1 - l2)) ? l1 + l2 - v : v - fabs(l1 - l2)) / reach;
    best = part[0] * part[0];
    if (part[2] * part[2] < best) best = part[2] * part[2];
    if (part[1] / elbow_scale < best) best = part[1] / elbow_scale;
    return best;
}

/* The wrist flip of the idealised robot's solution q (the same joint 1, 5
 * point and orientation; joint 4 turned by 180 deg, joint 5 negated): its
 * elbow's planar point (from axis 2 to axis 4 across axis 2) is 2 g - v,
 * with v that of q and g the joint 5 point's, both across axis 2 from
 * frame 1's origin. Returns that point's signed distance inside the
 * elbow's annulus over L (negative: the flip does not exist) divided by
 * FLIP_BAND / |s5|: in (-1, 0) the flip may exist on the calibrated robot. */
static double flip_margin(const dhs_robot *d, const double *q)
{
    dhr_mat4 F[NJ];
    double v[3], g[3], vz = 0.0, gz = 0.0, n = 0.0, reach = 0.0, l1, l2, e, s5;
    unsigned i;
    dhs_fk_desc(d, q, F, NULL);
    for (i = 0; i < d->n; i++) reach += fabs(d->j[i].a) + fabs(d->j[i].d);
    for (i = 0; i < 3u; i++) {
        v[i] = F[2].m[3][i] - F[0].m[3][i];
        g[i] = F[4].m[3][i] - F[0].m[3][i];
        vz += v[i] * F[0].m[2][i];
        gz += g[i] * F[0].m[2][i];
    }
    for (i = 0; i < 3u; i++) {
        const double c = 2.0 * (g[i] - gz * F[0].m[2][i]) - (v[i] - vz * F[0].m[2][i]);
        n += c * c;
    }
    n = sqrt(n);
    l1 = fabs(d->j[1].a);
    l2 = fabs(d->j[2].a);
    e = ((l1 + l2 - n < n - fabs(l1 - l2)) ? l1 + l2 - n : n - fabs(l1 - l2)) / reach;
    s5 = fabs(sin((q[4] + d->j[4].theta_deg) * D2R));
    return e * s5 / FLIP_BAND;
}

/* ---- the check ---------------------------------------------------------------- */

typedef struct {
    long targets, compared;
    double pos, rot;
} run_stats;

/* Analyse cal (calibrated, kind) and ideal (exact, kind). */
static void build_pair(const dhs_robot *cal, const dhs_robot *ideal, dh_ikc_kind kind, dh_robot *rc,
                       dh_ikc_model_f32 *mc, dh_robot *ri, dh_ikc_model_f32 *mi)
{
    DHT_EQ_INT(dhs_build(cal, rc), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_f32(rc, mc), DH_OK);
    DHT_EQ_INT(mc->kind, kind);
    DHT_EQ_INT(mc->why, DH_IKC_WHY_NONE);
    DHT_EQ_INT(mc->calibrated, 1);
    DHT_EQ_INT(dhs_build(ideal, ri), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_f32(ri, mi), DH_OK);
    DHT_EQ_INT(mi->kind, kind);
    DHT_EQ_INT(mi->calibrated, 0);
}

/* The target of q on the calibrated robot: every solution refined and
 * within the bounds, q among them, and the count the idealised robot's
 * when its solutions are away from its singularities. */
static void check_target(const dhs_robot *cal, const dhs_robot *ideal, const dh_robot *rc,
                         const dh_ikc_model_f32 *mc, const dh_ikc_model_f32 *mi, const double *q, run_stats *st)
{
    dh_mat4_f32 T;
    dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL], isol[DH_IKC_MAX_SOL];
    uint32_t n = 99u, ni = 99u, s, i;
    double best = 1e9;
    int ideal_far = 1;
    dhs_target_f32(rc, q, &T);
    DHT_EQ_INT(dh_ikc_f32(mc, &T, NULL, 0u, sol, &n), DH_OK);
    for (s = 0; s < n; s++) {
        double ep, er, dmax = 0.0;
        DHT_TRUE((sol[s].flags & DH_IKC_REFINED) != 0u);
        dhs_true_error_f32(rc, sol[s].q, &T, &ep, &er);
        DHT_TRUE_MSG(ep <= TOL_POS && er <= TOL_ROT, "%s: solution %u (flags 0x%x) %s: %.3g m, %.3g rad; q %s",
                     cal->name, (unsigned)s, (unsigned)sol[s].flags, dhs_qf_str(sol[s].q, 6u, 0), ep, er,
                     dhs_q_str(q, 6u, 1));
        if (ep > st->pos) st->pos = ep;
        if (er > st->rot) st->rot = er;
        for (i = 0; i < 6u; i++) {
            const double dd = dhs_joint_dist(rc, i, (double)sol[s].q[i], q[i]);
            if (dd > dmax) dmax = dd;
        }
        if (dmax < best) best = dmax;
    }
    DHT_TRUE_MSG(best <= GEN_DEG, "%s: q %s not among the %u solutions (nearest %.3g deg)", cal->name,
                 dhs_q_str(q, 6u, 0), (unsigned)n, best);
    (void)dh_ikc_f32(mi, &T, NULL, 0u, isol, &ni);
    best = 360.0;
    for (s = 0; s < ni; s++) {
        double qi[NJ], dmax = 0.0;
        for (i = 0; i < 6u; i++) {
            const double dd = dhs_joint_dist(rc, i, (double)isol[s].q[i], q[i]);
            if (dd > dmax) dmax = dd;
            qi[i] = (double)isol[s].q[i];
        }
        if (dmax < best) best = dmax;
        if (sing_of(ideal, qi, 1.0) < SING_MIN) ideal_far = 0;
        if (flip_margin(ideal, qi) > -1.0 && flip_margin(ideal, qi) < 0.0) ideal_far = 0;
    }
    /* the generating configuration this far (deg) from every idealised
     * solution: its branch is not the idealised robot's nearest one */
    dht_reach_max("calib.ur5.ideal_deg", best);
    if (ideal_far) {
        DHT_TRUE_MSG(n == ni, "%s: %u solutions, the idealised robot %u; q %s", cal->name, (unsigned)n,
                     (unsigned)ni, dhs_q_str(q, 6u, 0));
        st->compared++;
    }
    st->targets++;
}

/* PER_ROBOT configurations per drawn robot (every other one with a base
 * and tool frame), DHT_ITER(10^4) in all. */
static void ikc_calib_ur5(void)
{
    dhs_robot cal, ideal;
    dh_robot rc, ri;
    dh_ikc_model_f32 mc, mi;
    run_stats st;
    const long total = DHT_ITER(10000L);
    long k;
    memset(&st, 0, sizeof st);
    for (k = 0; k < total; k++) {
        double q[NJ];
        uint32_t i;
        if (k % PER_ROBOT == 0L) {
            draw_ur5(0.002, 0.5, (int)((k / PER_ROBOT) & 1L), &cal, &ideal);
            build_pair(&cal, &ideal, DH_IKC_PARALLEL_234, &rc, &mc, &ri, &mi);
        }
        do {
            for (i = 0; i < 6u; i++) q[i] = dht_rand_uniform(-180.0, 180.0);
        } while (sing_of(&cal, q, GEN_ELBOW / GEN_MIN) < GEN_MIN);
        dht_reach_min("calib.ur5.gen_sing", sing_of(&cal, q, GEN_ELBOW / GEN_MIN));
        check_target(&cal, &ideal, &rc, &mc, &mi, q, &st);
    }
    dht_printf("ur5 calibrated: %ld targets (%ld counts compared), worst %.3g m, %.3g rad\n", st.targets,
               st.compared, st.pos, st.rot);
    dht_reach_max("calib.ur5.pos", st.pos);
    DHT_TRUE(st.compared * 2L >= st.targets);
}

/* ---- the tolerance ------------------------------------------------------------- */

static void expect_none(const dhs_robot *d, dh_ikc_why why, const char *what)
{
    dh_robot r;
    dh_ikc_model_f32 m;
    DHT_EQ_INT(dhs_build(d, &r), DH_OK);
    DHT_TRUE_MSG(dh_ikc_analyse_f32(&r, &m) == DH_ERR_UNAVAILABLE, "%s: a closed form", what);
    DHT_EQ_INT(m.kind, DH_IKC_NONE);
    DHT_EQ_INT(m.why, why);
    DHT_EQ_INT(m.calibrated, 0);
}

static void expect_cal(const dhs_robot *d, dh_ikc_kind kind, const char *what)
{
    dh_robot r;
    dh_ikc_model_f32 m;
    DHT_EQ_INT(dhs_build(d, &r), DH_OK);
    DHT_TRUE_MSG(dh_ikc_analyse_f32(&r, &m) == DH_OK, "%s: no closed form", what);
    DHT_EQ_INT(m.kind, kind);
    DHT_EQ_INT(m.calibrated, 1);
}

/* Within the tolerance (0.9 deg, 0.9 % of the reach): calibrated; beyond
 * it (1.1 deg, 1.1 %): no closed form, with the exact chain's reason; on
 * the family: exact (calibrated 0). */
static void ikc_calib_tolerance(void)
{
    dhs_robot d;
    dh_robot r;
    dh_ikc_model_f32 m;
    double reach = 0.0;
    unsigned i;
    for (i = 0; i < 6u; i++) reach += fabs(dhs_ur5_m.j[i].a) + fabs(dhs_ur5_m.j[i].d);
    DHT_EQ_INT(dhs_build(&dhs_ur5_m, &r), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_f32(&r, &m), DH_OK);
    DHT_EQ_INT(m.calibrated, 0);
    d = dhs_ur5_m;
    d.j[1].alpha_deg = 0.9;
    expect_cal(&d, DH_IKC_PARALLEL_234, "ur5 alpha2 0.9");
    d.j[1].alpha_deg = -1.1;
    expect_none(&d, DH_IKC_WHY_WRIST, "ur5 alpha2 -1.1");
    d = dhs_ur5_m;
    d.j[3].alpha_deg = 90.9;
    expect_cal(&d, DH_IKC_PARALLEL_234, "ur5 alpha4 90.9");
    d.j[3].alpha_deg = 88.9;
    expect_none(&d, DH_IKC_WHY_WRIST, "ur5 alpha4 88.9");
    d = dhs_ur5_m;
    d.j[4].a = 0.009 * reach;
    expect_cal(&d, DH_IKC_PARALLEL_234, "ur5 a5 0.9 %");
    d.j[4].a = -0.011 * reach;
    expect_none(&d, DH_IKC_WHY_WRIST, "ur5 a5 1.1 %");
    reach = 0.0;
    for (i = 0; i < 6u; i++) reach += fabs(dhs_puma560_m.j[i].a) + fabs(dhs_puma560_m.j[i].d);
    /* the spherical-wrist family (test_ikc_calib_wrist.c) */
    d = dhs_puma560_m;
    d.j[4].d = 0.005 * reach;
    expect_cal(&d, DH_IKC_WRIST_RRR, "puma d5 0.5 %");
    d = dhs_puma560_m;
    d.j[1].alpha_deg = 1.1;
    expect_none(&d, DH_IKC_WHY_AXES, "puma alpha2 1.1");
}

/* ---- singular configurations ------------------------------------------------ */

/* A calibrated UR5 (fixed deviations; the last twist 179.6 deg, taken as
 * 180) at configurations on the idealised chain's singularities, where the
 * refinement's Jacobian is singular: wrist (q5 0 or 180), elbow stretched
 * (q3 0) and both, and near them. The contract (ikc.h, calibration
 * tolerance): a branch there may be missing, but every branch returned is
 * refined and within the bounds on the exact chain; none left is
 * DH_ERR_UNREACHABLE. */
static void ikc_calib_singular(void)
{
    static const double qs[][6] = {
        { 30.0, -60.0, 80.0, -40.0, 0.0, 20.0 },    { -120.0, -100.0, 45.0, 10.0, 180.0, -70.0 },
        { 60.0, -45.0, 0.0, 30.0, 50.0, 10.0 },     { 10.0, -90.0, 0.0, -90.0, 0.0, 0.0 },
        { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 },           { 45.0, -30.0, 60.0, 15.0, 1e-4, -15.0 },
        { -45.0, -150.0, 1e-4, 100.0, -90.0, 5.0 }, { 90.0, -90.0, 90.0, -90.0, -90.0, 0.0 },
    };
    dhs_robot d = dhs_ur5_m;
    dh_robot r;
    dh_ikc_model_f32 m;
    dh_mat4_f32 T;
    dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
    uint32_t k, n, s, found = 0;
    open_limits(&d);
    d.j[1].a += 0.0015;
    d.j[3].d -= 0.001;
    d.j[1].alpha_deg += 0.4;
    d.j[3].alpha_deg += 0.3;
    d.j[2].theta_deg += 0.3;
    d.j[5].alpha_deg = 179.6;
    DHT_EQ_INT(dhs_build(&d, &r), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_f32(&r, &m), DH_OK);
    DHT_EQ_INT(m.kind, DH_IKC_PARALLEL_234);
    DHT_EQ_INT(m.calibrated, 1);
    for (k = 0; k < sizeof qs / sizeof qs[0]; k++) {
        dh_status st;
        dhs_target_f32(&r, qs[k], &T);
        n = 99u;
        st = dh_ikc_f32(&m, &T, NULL, 0u, sol, &n);
        DHT_TRUE_MSG(st == DH_OK || st == DH_ERR_UNREACHABLE, "q %s: status %d", dhs_q_str(qs[k], 6u, 0), (int)st);
        if (st != DH_OK) DHT_EQ_INT(n, 0);
        for (s = 0; s < n; s++) {
            double ep, er;
            DHT_TRUE((sol[s].flags & DH_IKC_REFINED) != 0u);
            dhs_true_error_f32(&r, sol[s].q, &T, &ep, &er);
            DHT_TRUE_MSG(ep <= TOL_POS && er <= TOL_ROT, "q %s: solution %u (flags 0x%x) %s: %.3g m, %.3g rad",
                         dhs_q_str(qs[k], 6u, 0), (unsigned)s, (unsigned)sol[s].flags, dhs_qf_str(sol[s].q, 6u, 1),
                         ep, er);
        }
        found += n;
    }
    /* the singular targets are not all lost */
    DHT_TRUE(found > 0u);
}

static const dht_case cases[] = {
    DHT_CASE(ikc_calib_tolerance),
    DHT_CASE(ikc_calib_singular),
    DHT_CASE(ikc_calib_ur5),
};
DHT_MAIN(cases)
