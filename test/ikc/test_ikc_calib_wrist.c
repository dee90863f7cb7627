/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_ikc_calib_wrist.c - closed-form IK of calibrated spherical-wrist
 * robots, float: a Puma 560 or a KUKA KR5 (in turn) whose wrist axes miss
 * their common point by a random wrist offset (a4, a5, d5 each up to
 * 0.5 mm) and whose twists and theta offsets deviate by up to 0.2 deg,
 * drawn at random for each seed (every other pair with a random base and
 * tool frame); the calibration tolerance of the family; configurations on
 * the idealised chain's singularities.
 *
 * Every solution is judged in double, independently of the library: its
 * joint values go through the double reference FK of the exact robot's
 * stored float parameters (dhs_true_error_f32). The generating
 * configuration (at least GEN_MIN from the wrist and shoulder
 * singularities and GEN_ELBOW L from the elbow's boundary, wrist_sing)
 * must be among the solutions. The number of solutions must equal the
 * idealised robot's (twists snapped, a4 = a5 = d5 = 0: an exact
 * DH_IKC_WRIST_RRR robot) for the same target where every idealised
 * solution is that far from its singularities: nearer one, a branch can
 * appear or disappear (the deviations move the wrist centre by up to a few
 * mm, which moves the elbow's boundary; the refinement starts only from
 * the idealised branches, ikc.h).
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
/* Normalised distances (wrist_sing): s5^2 and the shoulder's (u / L)^2 at
 * least GEN_MIN (the 1e-2), the wrist centre's distance from the
 * elbow's boundary (stretched or folded) at least GEN_ELBOW L: the
 * deviations (0.2 deg of twist over arms of up to 0.9 m, 0.9 mm of wrist
 * offset) move the wrist centre by up to about 5e-3 L. */
#define GEN_MIN 1e-2
#define GEN_ELBOW 1.5e-2
/* deg: a solution this near the generating configuration on every joint is
 * it (the nearest other branch lies degrees away at GEN_MIN) */
#define GEN_DEG 0.05
/* drawn robots per run (every DHT_ITER_DIV) */
#define ROBOTS 10L

/* ---- the robots -------------------------------------------------------------- */

/* Rz Rx Rz of random angles and a translation within +-t (m), rounded to
 * float entries (the description and the float robot hold the same frame) */
static void rand_rigid(double t, dhr_mat4 *F)
{
    dhr_mat4 A;
    int k, c;
    dhr_rotz(dht_rand_uniform(-180, 180), F);
    dhr_rotx(dht_rand_uniform(-180, 180), &A);
    dhr_mul(F, &A, F);
    dhr_rotz(dht_rand_uniform(-180, 180), &A);
    dhr_mul(F, &A, F);
    for (k = 0; k < 3; k++) F->m[3][k] = dht_rand_uniform(-t, t);
    for (k = 0; k < 16; k++) {
        c = k >> 2;
        F->m[c][k & 3] = (double)(float)F->m[c][k & 3];
    }
}

/* Robot number k (Puma 560 for k even, KR5 for k odd; base and tool frames
 * for k / 2 odd): its twists and theta offsets off by up to da (deg), a4,
 * a5, d5 by up to dw (m), limits +-360 deg, into cal; its idealised twin
 * into ideal. */
static void draw_wrist(long k, double dw, double da, dhs_robot *cal, dhs_robot *ideal)
{
    unsigned i;
    *cal = ((k & 1L) == 0L) ? dhs_puma560_m : dhs_kuka_kr5_m;
    if (((k >> 1) & 1L) != 0L) {
        rand_rigid(0.5, &cal->base);
        rand_rigid(0.15, &cal->tool);
    }
    for (i = 0; i < 6u; i++) {
        cal->j[i].qmin = -360.0;
        cal->j[i].qmax = 360.0;
        cal->j[i].alpha_deg += dht_rand_uniform(-da, da);
        cal->j[i].theta_deg += dht_rand_uniform(-da, da);
    }
    cal->j[3].a += dht_rand_uniform(-dw, dw);
    cal->j[4].a += dht_rand_uniform(-dw, dw);
    cal->j[4].d += dht_rand_uniform(-dw, dw);
    *ideal = *cal;
    for (i = 0; i < 6u; i++) ideal->j[i].alpha_deg = 90.0 * floor(cal->j[i].alpha_deg / 90.0 + 0.5);
    ideal->j[3].a = 0.0;
    ideal->j[4].a = 0.0;
    ideal->j[4].d = 0.0;
}

/* Normalised distances of q from the family's singularities, the smallest
 * returned: wrist s5^2; shoulder (u / L)^2 (dhk_sing_parts: u the joint 5
 * point along x1, L the sum of |a| and |d|); elbow: the wrist centre's
 * distance from the boundary of the elbow's annulus (radii |a2| + rho and
 * ||a2| - rho|, rho^2 = a3^2 + (sin alpha3 d4)^2, the distance from axis 2
 * sqrt(a2^2 + rho^2 + 2 a2 rho cos(theta3 - phi)), phi = atan2(sin alpha3
 * d4, a3)) over L, divided by elbow_scale. */
static double wrist_sing(const dhs_robot *d, const double *q, double elbow_scale)
{
    double part[3], best, L = 0.0, a2 = d->j[1].a, e, rho, phi, v, el;
    unsigned i;
    for (i = 0; i < d->n; i++) L += fabs(d->j[i].a) + fabs(d->j[i].d);
    (void)dhk_sing_parts(d, q, part);
    e = sin(d->j[2].alpha_deg * D2R) * d->j[3].d;
    rho = sqrt(d->j[2].a * d->j[2].a + e * e);
    phi = atan2(e, d->j[2].a);
    v = sqrt(fmax(0.0, a2 * a2 + rho * rho + 2.0 * a2 * rho * cos((q[2] + d->j[2].theta_deg) * D2R - phi)));
    el = fmin(fabs(a2) + rho - v, v - fabs(fabs(a2) - rho)) / L;
    best = fmin(part[0] * part[0], part[2] * part[2]);
    return fmin(best, el / elbow_scale);
}

/* ---- the check ---------------------------------------------------------------- */

typedef struct {
    long targets, compared;
    double pos, rot;
} wrist_stats;

/* d built and analysed into r, m: kind, calibrated as given */
static void analyse_as(const dhs_robot *d, uint32_t calibrated, dh_robot *r, dh_ikc_model_f32 *m)
{
    DHT_EQ_INT(dhs_build(d, r), DH_OK);
    DHT_TRUE_MSG(dh_ikc_analyse_f32(r, m) == DH_OK, "%s: no closed form", d->name);
    DHT_EQ_INT(m->kind, DH_IKC_WRIST_RRR);
    DHT_EQ_INT(m->why, DH_IKC_WHY_NONE);
    DHT_EQ_INT(m->calibrated, calibrated);
}

/* Every returned solution of the calibrated robot (rc, mc) for T flagged
 * refined and within the bounds on the exact chain; returns the largest
 * joint distance (deg) of the nearest one from q (NULL: 0). */
static double check_refined(const dh_robot *rc, const dh_mat4_f32 *T, const dh_ikc_sol_f32 *sol, uint32_t n,
                            const double *q, wrist_stats *st)
{
    double best = 360.0;
    uint32_t s, i;
    for (s = 0; s < n; s++) {
        double ep, er, dmax = 0.0;
        DHT_TRUE_MSG((sol[s].flags & DH_IKC_REFINED) != 0u, "solution %u flags 0x%x", (unsigned)s,
                     (unsigned)sol[s].flags);
        dhs_true_error_f32(rc, sol[s].q, T, &ep, &er);
        DHT_TRUE_MSG(ep <= TOL_POS && er <= TOL_ROT, "solution %u (flags 0x%x) %s: %.3g m, %.3g rad", (unsigned)s,
                     (unsigned)sol[s].flags, dhs_qf_str(sol[s].q, 6u, 1), ep, er);
        st->pos = fmax(st->pos, ep);
        st->rot = fmax(st->rot, er);
        for (i = 0; q != NULL && i < 6u; i++) dmax = fmax(dmax, dhs_joint_dist(rc, i, (double)sol[s].q[i], q[i]));
        best = fmin(best, dmax);
    }
    return (q != NULL) ? best : 0.0;
}

/* The target of q on the calibrated robot: every solution refined and
 * within the bounds, q among them, and the count the idealised robot's
 * when its solutions are away from its singularities. */
static void wrist_target(const dhs_robot *cal, const dhs_robot *ideal, const dh_robot *rc,
                         const dh_ikc_model_f32 *mc, const dh_ikc_model_f32 *mi, const double *q, wrist_stats *st)
{
    dh_mat4_f32 T;
    dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
    uint32_t n = 99u, s, i;
    double best;
    int far = 1;
    dhs_target_f32(rc, q, &T);
    DHT_EQ_INT(dh_ikc_f32(mc, &T, NULL, 0u, sol, &n), DH_OK);
    best = check_refined(rc, &T, sol, n, q, st);
    DHT_TRUE_MSG(best <= GEN_DEG, "%s: q %s not among the %u solutions (nearest %.3g deg)", cal->name,
                 dhs_q_str(q, 6u, 0), (unsigned)n, best);
    dht_reach_max("calib.wrist.gen_deg", best);
    s = n;
    (void)dh_ikc_f32(mi, &T, NULL, 0u, sol, &n);
    for (i = 0; i < n; i++) {
        double qi[NJ];
        uint32_t j;
        for (j = 0; j < 6u; j++) qi[j] = (double)sol[i].q[j];
        if (wrist_sing(ideal, qi, GEN_ELBOW / GEN_MIN) < GEN_MIN) far = 0;
    }
    if (far) {
        DHT_TRUE_MSG(s == n, "%s: %u solutions, the idealised robot %u; q %s", cal->name, (unsigned)s, (unsigned)n,
                     dhs_q_str(q, 6u, 0));
        st->compared++;
    }
    st->targets++;
}

/* A configuration of d uniform in +-180 deg on every joint, redrawn until
 * it is GEN_MIN from the singularities (wrist_sing) */
static void draw_q(const dhs_robot *d, double *q)
{
    unsigned i;
    do
        for (i = 0; i < 6u; i++) q[i] = dht_rand_uniform(-180.0, 180.0);
    while (wrist_sing(d, q, GEN_ELBOW / GEN_MIN) < GEN_MIN);
    dht_reach_min("calib.wrist.gen_sing", wrist_sing(d, q, GEN_ELBOW / GEN_MIN));
}

/* A drawn robot (draw_wrist) and its idealised twin, built and analysed */
typedef struct {
    dhs_robot cal, ideal;
    dh_robot rc, ri;
    dh_ikc_model_f32 mc, mi;
} wrist_pair;

static void draw_pair(long k, wrist_pair *p)
{
    draw_wrist(k, 0.0005, 0.2, &p->cal, &p->ideal);
    analyse_as(&p->cal, 1u, &p->rc, &p->mc);
    analyse_as(&p->ideal, 0u, &p->ri, &p->mi);
}

/* DHT_ITER(10^4) configurations in all, on ROBOTS drawn robots in turn. */
static void ikc_calib_wrist(void)
{
    wrist_pair p;
    wrist_stats st = { 0L, 0L, 0.0, 0.0 };
    const long total = DHT_ITER(10000L);
    const long per = (total >= ROBOTS) ? total / ROBOTS : 1L;
    long k;
    for (k = 0; k < total; k++) {
        double q[NJ];
        if (k % per == 0L) draw_pair(k / per, &p);
        draw_q(&p.cal, q);
        wrist_target(&p.cal, &p.ideal, &p.rc, &p.mc, &p.mi, q, &st);
    }
    dht_printf("spherical wrist calibrated: %ld targets (%ld counts compared), worst %.3g m, %.3g rad\n", st.targets,
               st.compared, st.pos, st.rot);
    dht_reach_max("calib.wrist.pos", st.pos);
    dht_reach_max("calib.wrist.rot", st.rot);
    DHT_TRUE(st.compared * 2L >= st.targets);
}

/* ---- the tolerance ------------------------------------------------------------- */

/* d analysed: calibrated spherical wrist (cal 1) or no closed form with why */
static void expect_wrist(const dhs_robot *d, int cal, dh_ikc_why why, const char *what)
{
    dh_robot r;
    dh_ikc_model_f32 m;
    DHT_EQ_INT(dhs_build(d, &r), DH_OK);
    DHT_TRUE_MSG(dh_ikc_analyse_f32(&r, &m) == (cal ? DH_OK : DH_ERR_UNAVAILABLE), "%s: status", what);
    DHT_EQ_INT(m.kind, cal ? DH_IKC_WRIST_RRR : DH_IKC_NONE);
    DHT_EQ_INT(m.why, cal ? DH_IKC_WHY_NONE : why);
    DHT_EQ_INT(m.calibrated, (uint32_t)cal);
}

/* Within the tolerance (0.9 deg, 0.9 % of the reach): calibrated; beyond
 * it (1.1 deg, 1.1 %): no closed form, the exact chain's reason. */
static void ikc_calib_wrist_tolerance(void)
{
    dhs_robot d;
    double reach = 0.0;
    unsigned i;
    for (i = 0; i < 6u; i++) reach += fabs(dhs_puma560_m.j[i].a) + fabs(dhs_puma560_m.j[i].d);
    d = dhs_puma560_m;
    d.j[4].d = 0.009 * reach;
    expect_wrist(&d, 1, DH_IKC_WHY_NONE, "puma d5 0.9 %");
    d.j[4].d = -0.011 * reach;
    expect_wrist(&d, 0, DH_IKC_WHY_WRIST, "puma d5 1.1 %");
    d = dhs_puma560_m;
    d.j[3].a = -0.009 * reach;
    d.j[4].a = 0.009 * reach;
    expect_wrist(&d, 1, DH_IKC_WHY_NONE, "puma a4, a5 0.9 %");
    d.j[3].a = 0.011 * reach;
    expect_wrist(&d, 0, DH_IKC_WHY_WRIST, "puma a4 1.1 %");
    d = dhs_puma560_m;
    d.j[3].alpha_deg = 90.9;
    d.j[1].alpha_deg = -0.9;
    expect_wrist(&d, 1, DH_IKC_WHY_NONE, "puma alpha4 90.9, alpha2 -0.9");
    d.j[3].alpha_deg = 91.1;
    expect_wrist(&d, 0, DH_IKC_WHY_AXES, "puma alpha4 91.1");
    d = dhs_puma560_m;
    d.j[1].alpha_deg = 1.1;
    expect_wrist(&d, 0, DH_IKC_WHY_AXES, "puma alpha2 1.1");
}

/* ---- singular configurations ------------------------------------------------ */

/* A calibrated Puma 560 (fixed deviations) at configurations on the
 * idealised chain's singularities, where a block of the refinement is
 * singular: wrist (q5 0), elbow stretched or folded, shoulder (the wrist
 * centre on the shoulder's cylinder: q2 30, q3 32.58; 1 cm across it: q3
 * 30.04), and near them. The contract (ikc.h): a branch
 * there may be missing, but every branch returned is refined and within
 * the bounds on the exact chain; none left is DH_ERR_UNREACHABLE. */
static void ikc_calib_wrist_singular(void)
{
    static const double qs[][6] = {
        { 30.0, -60.0, 80.0, -40.0, 0.0, 20.0 },    { -120.0, 40.0, 45.0, 10.0, 1e-3, -70.0 },
        { 60.0, -45.0, 90.0, 30.0, 50.0, 10.0 },    { 10.0, 30.0, 87.3, -90.0, 0.0, 0.0 },
        { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 },           { 45.0, -30.0, 60.0, 15.0, 0.3, -15.0 },
        { 90.0, -90.0, -90.0, -90.0, -90.0, 0.0 },  { -45.0, 100.0, -92.7, 100.0, -90.0, 5.0 },
        { 20.0, 30.0, 32.58, 40.0, 60.0, 10.0 },    { 20.0, 30.0, 30.04, 40.0, 60.0, 10.0 },
    };
    dhs_robot d = dhs_puma560_m;
    dh_robot r;
    dh_ikc_model_f32 m;
    dh_mat4_f32 T;
    dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
    wrist_stats st;
    uint32_t k, n, found = 0;
    memset(&st, 0, sizeof st);
    for (k = 0; k < 6u; k++) {
        d.j[k].qmin = -360.0;
        d.j[k].qmax = 360.0;
    }
    d.j[3].a = 0.0004;
    d.j[4].d = -0.0003;
    d.j[4].a = 0.0002;
    d.j[1].alpha_deg += 0.15;
    d.j[3].alpha_deg -= 0.2;
    d.j[5].alpha_deg = 0.1;
    analyse_as(&d, 1u, &r, &m);
    for (k = 0; k < sizeof qs / sizeof qs[0]; k++) {
        dh_status s;
        dhs_target_f32(&r, qs[k], &T);
        n = 99u;
        s = dh_ikc_f32(&m, &T, NULL, 0u, sol, &n);
        DHT_TRUE_MSG(s == DH_OK || s == DH_ERR_UNREACHABLE, "q %s: status %d", dhs_q_str(qs[k], 6u, 0), (int)s);
        if (s != DH_OK) DHT_EQ_INT(n, 0);
        (void)check_refined(&r, &T, sol, n, NULL, &st);
        found += n;
    }
    /* the singular targets are not all lost */
    DHT_TRUE(found > 0u);
}

static const dht_case cases[] = {
    DHT_CASE(ikc_calib_wrist_tolerance),
    DHT_CASE(ikc_calib_wrist_singular),
    DHT_CASE(ikc_calib_wrist),
};
DHT_MAIN(cases)
