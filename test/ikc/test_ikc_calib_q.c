/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_ikc_calib_q.c - closed-form IK of calibrated robots, fixed point:
 * a UR5 in mm whose a, d deviate by up to 2 mm and whose twists and theta
 * offsets by up to 0.5 deg, drawn at random for each seed (every other one
 * with a random base and tool frame); robots beyond the calibration
 * tolerance, which have no closed form; and the calls that refuse a
 * calibrated model. The fixed twin of test_ikc_calib.c.
 *
 * Every solution is judged in double, independently of the library: its
 * Q joint values go through the double reference FK of the robot's Q
 * parameters (dhk_check_sols_q: within DHK_POS_TOL and DHK_ROT_TOL). The
 * generating configuration (at least GEN_MIN from every singularity,
 * dhk_cal_sing) must be among the solutions, and the number of solutions equal
 * the idealised robot's where test_ikc_calib.c compares them (ideal_far).
 */
#include "dht.h"
#include "support_ikc.h"
#include "dhmath/ikc.h"

#include <math.h>
#include <string.h>

#define NJ DH_IKC_JOINTS
/* as test_ikc_calib.c */
#define GEN_MIN 1e-2
#define GEN_ELBOW 3e-2
#define SING_MIN 3e-2
#define FLIP_BAND 1e-2
#define GEN_DEG 0.05
/* configurations per drawn robot (at DHT_ITER_DIV 1: 10 robots) */
#define PER_ROBOT 1000L

/* ---- the check ---------------------------------------------------------------- */

/* Analyse cal (calibrated, kind) and ideal (exact, kind). */
static void build_pair(const dhs_robot *cal, const dhs_robot *ideal, dh_ikc_kind kind, dh_robot *rc,
                       dh_ikc_model_q *mc, dh_robot *ri, dh_ikc_model_q *mi)
{
    DHT_EQ_INT(dhs_build(cal, rc), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_q(rc, mc), DH_OK);
    DHT_EQ_INT(mc->kind, kind);
    DHT_EQ_INT(mc->why, DH_IKC_WHY_NONE);
    DHT_EQ_INT(mc->calibrated, 1);
    DHT_EQ_INT(dhs_build(ideal, ri), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_q(ri, mi), DH_OK);
    DHT_EQ_INT(mi->kind, kind);
    DHT_EQ_INT(mi->calibrated, 0);
}

/* The target of q on the calibrated robot: every solution refined and
 * within the bounds, q among them, and the count the idealised robot's
 * when the solutions of both are away from their singularities. */
static void check_target(const dhs_robot *cal, const dhs_robot *ideal, const dh_robot *rc,
                         const dh_ikc_model_q *mc, const dh_ikc_model_q *mi, const double *q, dhk_stats *st,
                         long *compared)
{
    dhr_mat4 Td;
    dh_frame_q T;
    int32_t qq[NJ];
    dh_ikc_sol_q sol[DH_IKC_MAX_SOL], isol[DH_IKC_MAX_SOL];
    uint32_t n = 99u, ni = 99u, s, i;
    double best = 1e9;
    int ideal_far = 1;
    dh_status rs;
    dhs_q_from_double(rc, q, qq);
    dhs_fk_ref_q(rc, qq, NULL, &Td);
    dhs_to_frame_q(&Td, &T);
    rs = dh_ikc_q(mc, &T, NULL, 0u, sol, &n);
    DHT_TRUE_MSG(rs == DH_OK, "%s: status %d for q %s", cal->name, (int)rs, dhs_q_str(q, 6u, 0));
    (void)dhk_check_sols_q(rc, &Td, sol, n, NULL, st);
    for (s = 0; s < n; s++) {
        double dmax = 0.0, qs[NJ];
        DHT_TRUE((sol[s].flags & DH_IKC_REFINED) != 0u);
        for (i = 0; i < 6u; i++) {
            const double dd = dhk_jdiff_q(rc, i, sol[s].q[i], qq[i]);
            if (dd > dmax) dmax = dd;
            qs[i] = ldexp((double)sol[s].q[i], -16);
        }
        if (dhk_cal_sing(cal, qs, 1.0) < SING_MIN) ideal_far = 0;
        if (dmax < best) best = dmax;
    }
    DHT_TRUE_MSG(best <= GEN_DEG, "%s: q %s not among the %u solutions (nearest %.3g deg)", cal->name,
                 dhs_q_str(q, 6u, 0), (unsigned)n, best);
    (void)dh_ikc_q(mi, &T, NULL, 0u, isol, &ni);
    best = 1e9;
    for (s = 0; s < ni; s++) {
        double qi[NJ], fm, dmax = 0.0;
        for (i = 0; i < 6u; i++) {
            const double dd = dhk_jdiff_q(rc, i, isol[s].q[i], qq[i]);
            if (dd > dmax) dmax = dd;
            qi[i] = ldexp((double)isol[s].q[i], -16);
        }
        if (dmax < best) best = dmax;
        if (dhk_cal_sing(ideal, qi, 1.0) < SING_MIN) ideal_far = 0;
        fm = dhk_flip_margin(ideal, qi, FLIP_BAND);
        if (fm > -1.0 && fm < 0.0) ideal_far = 0;
    }
    /* the idealised solution nearest q: far when the restart found q */
    dht_reach_max("calibq.ur5.ideal_deg", best);
    if (ideal_far) {
        DHT_TRUE_MSG(n == ni, "%s: %u solutions, the idealised robot %u; q %s", cal->name, (unsigned)n,
                     (unsigned)ni, dhs_q_str(q, 6u, 0));
        (*compared)++;
    }
    st->targets++;
}

/* PER_ROBOT configurations per drawn robot (every other one with a base
 * and tool frame), DHT_ITER(10^4) in all. */
static void ikc_calib_ur5_q(void)
{
    dhs_robot cal, ideal;
    dh_robot rc, ri;
    dh_ikc_model_q mc, mi;
    dhk_stats st;
    const long total = DHT_ITER(10000L);
    long k, compared = 0;
    memset(&st, 0, sizeof st);
    for (k = 0; k < total; k++) {
        double q[NJ];
        uint32_t i;
        if (k % PER_ROBOT == 0L) {
            dhk_draw_ur5(&dhs_ur5_mm, 2.0, 0.5, (int)((k / PER_ROBOT) & 1L), &cal, &ideal);
            dhk_scale_desc(&cal);
            dhk_scale_desc(&ideal);
            build_pair(&cal, &ideal, DH_IKC_PARALLEL_234, &rc, &mc, &ri, &mi);
        }
        do {
            for (i = 0; i < 6u; i++) q[i] = dht_rand_uniform(-180.0, 180.0);
        } while (dhk_cal_sing(&cal, q, GEN_ELBOW / GEN_MIN) < GEN_MIN);
        check_target(&cal, &ideal, &rc, &mc, &mi, q, &st, &compared);
    }
    dht_printf("ur5 calibrated, fixed: %ld targets (%ld counts compared), worst %.3g mm, %.3g rad\n", st.targets,
               compared, st.pos, st.rot);
    dht_reach_max("calibq.ur5.pos", st.pos);
    DHT_TRUE(compared * 2L >= st.targets);
}

/* ---- the tolerance ------------------------------------------------------------- */

static void expect_q(const dhs_robot *d, dh_status want, dh_ikc_kind kind, uint32_t calibrated, const char *what)
{
    dhs_robot s = *d;
    dh_robot r;
    dh_ikc_model_q m;
    dhk_scale_desc(&s);
    DHT_EQ_INT(dhs_build(&s, &r), DH_OK);
    DHT_TRUE_MSG(dh_ikc_analyse_q(&r, &m) == want, "%s: status", what);
    DHT_EQ_INT(m.kind, kind);
    DHT_EQ_INT(m.calibrated, calibrated);
}

/* Within the tolerance (0.9 deg, 0.9 % of the reach): calibrated; beyond
 * it (1.1 deg, 1.1 %): no closed form; on the family: exact. */
static void ikc_calib_tolerance_q(void)
{
    dhs_robot d = dhs_ur5_mm;
    double reach = 0.0;
    unsigned i;
    for (i = 0; i < 6u; i++) reach += fabs(dhs_ur5_mm.j[i].a) + fabs(dhs_ur5_mm.j[i].d);
    expect_q(&d, DH_OK, DH_IKC_PARALLEL_234, 0u, "ur5");
    d.j[1].alpha_deg = 0.9;
    expect_q(&d, DH_OK, DH_IKC_PARALLEL_234, 1u, "ur5 alpha2 0.9");
    d.j[1].alpha_deg = -1.1;
    expect_q(&d, DH_ERR_UNAVAILABLE, DH_IKC_NONE, 0u, "ur5 alpha2 -1.1");
    d = dhs_ur5_mm;
    d.j[3].alpha_deg = 90.9;
    expect_q(&d, DH_OK, DH_IKC_PARALLEL_234, 1u, "ur5 alpha4 90.9");
    d.j[3].alpha_deg = 88.9;
    expect_q(&d, DH_ERR_UNAVAILABLE, DH_IKC_NONE, 0u, "ur5 alpha4 88.9");
    d = dhs_ur5_mm;
    d.j[4].a = 0.009 * reach;
    expect_q(&d, DH_OK, DH_IKC_PARALLEL_234, 1u, "ur5 a5 0.9 %");
    d.j[4].a = -0.011 * reach;
    expect_q(&d, DH_ERR_UNAVAILABLE, DH_IKC_NONE, 0u, "ur5 a5 1.1 %");
}

/* A calibrated model: dh_ikc_q refines; a hand-built model with
 * calibrated out of range is DH_ERR_ARG. */
static void ikc_calib_model_q(void)
{
    dhs_robot d = dhs_ur5_mm;
    dh_robot r;
    dh_ikc_model_q m;
    dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
    dhr_mat4 Td;
    dh_frame_q T;
    int32_t qq[NJ];
    static const double q[NJ] = {30.0, -60.0, 80.0, -40.0, 50.0, 20.0};
    uint32_t n = 99u;
    d.j[1].a += 1.5;
    d.j[3].alpha_deg += 0.3;
    dhk_scale_desc(&d);
    DHT_EQ_INT(dhs_build(&d, &r), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_q(&r, &m), DH_OK);
    DHT_EQ_INT(m.calibrated, 1);
    dhs_q_from_double(&r, q, qq);
    dhs_fk_ref_q(&r, qq, NULL, &Td);
    dhs_to_frame_q(&Td, &T);
    DHT_EQ_INT(dh_ikc_q(&m, &T, NULL, 0u, sol, &n), DH_OK);
    DHT_TRUE(n >= 1u);
    DHT_TRUE(dhk_check_sols_q(&r, &Td, sol, n, qq, NULL) >= 0);
    m.calibrated = 2u;
    DHT_EQ_INT(dh_ikc_q(&m, &T, NULL, 0u, sol, &n), DH_ERR_ARG);
    DHT_EQ_INT(n, 0);
}

static const dht_case cases[] = {
    DHT_CASE(ikc_calib_tolerance_q),
    DHT_CASE(ikc_calib_model_q),
    DHT_CASE(ikc_calib_ur5_q),
};
DHT_MAIN(cases)
