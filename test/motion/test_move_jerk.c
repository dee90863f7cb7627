/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_move_jerk.c - a jerk-limited path move (dh_move_path_jerk_f32) that
 * the tracker cannot follow: it brakes, holds and resumes on its own
 * (motion.h, dh_move_advance_f32), run by the firmware loop of motion.h at
 * 1 kHz, seeded.
 *
 * Two sources of lag:
 * - the Puma 560 (metres) with joint rates 150 deg/s and 600 deg/s^2 on
 *   the line of docs/motion.md that asks its wrist for more than its
 *   rates (from near q = (10, -30, 45, 20, 35, -60) to near
 *   (0.5, -0.03, 1.0) with the base's orientation; the first draw exactly
 *   that), at 0.3 m/s, 1.5 m/s^2, 90 deg/s, 360 deg/s^2 and a random jerk
 *   limit: the tracker's own LAGGING;
 * - random lines and arcs on the UR5 and the Panda (random Cartesian and
 *   jerk limits), the tracker's state replaced by LAGGING for a random
 *   stretch at a random period.
 * Every period's target is checked against double references written
 * here: speed, TOTAL acceleration, angular speed and acceleration by
 * finite differences within the limits times 1 + 1e-3 over windows of
 * WS = 10 periods every period and of W = 50 periods every WD = 25, and
 * TOTAL jerk and angular jerk by third differences over W periods within
 * the jerk limits times 1 + 1e-3 (plus the rounding: support_motion.h),
 * over EVERY window, those of the lags, brakes, holds and resumes
 * included. Held is reported exactly on the not-OK periods; the reported
 * r (the cap of s') never rises, is 1 before the first brake and at most
 * 7/8 after it; every period after a resume the target moves by at most
 * the cap times the first plan's peak of s' (its length times that, plus
 * 4 ulp of the scale); the move is done with the target at B bit for bit,
 * within 20 times the duration plus 5 s. The forced lags come while the
 * path moves: each brakes (mv.bst), holds and resumes.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_motion.h"
#include "support_robots.h"
#include "dhmath/motion.h"
#include "dhmath/track.h"

#define DT 1e-3f
#define WS 10               /* the short window (periods), every period */
#define WD 25               /* the long window's sampling (periods) */
#define W (2 * WD)          /* the long window (periods) */
#define NS (2 * WS + 1)     /* samples kept, every period */
#define NL (3 * W / WD + 1) /* samples kept, every WD periods */

static float sp[NS][7], lp[NL][7]; /* position and unit quaternion of the target m periods (m WD periods) ago */

/* what a run saw */
typedef struct {
    long notok, brakes, resumes, periods;
    double jerk[2]; /* the largest third-difference ratios (linear, angular) */
} run_stats;

/* One move along p within lim and jk by the rig's tracker from q0; the
 * tracker's state replaced by LAGGING for lag_len periods (0: none) from
 * the first period at lag_frac of the move's duration or later while the
 * path moves. The checks of the file's comment; S the scale of the
 * positions (at least 1), L the path's length. */
static void run_move(dhm_rig *g, const float *q0, const dh_path_f32 *p, const dh_cart_limits_f32 *lim,
                     const dh_cart_jerk_f32 *jk, double S, double lag_frac, long lag_len, run_stats *rs)
{
    static dh_move_f32 mv;
    dhm_fd fd = { sp, lp, NS, NL, WS, WD, W, (double)DT, 0 };
    const double ulp = S * FLT_EPSILON;
    dh_track_report_f32 trep;
    dh_move_report_f32 rep;
    dh_mat4_f32 T, Tp;
    float q[DH_MAX_JOINTS], feed = 1.0f, cap = 1.0f;
    long call, max_calls, lag_at, lag_from = -1;
    int done = 0, have = 0;
    uint32_t bst = 0u;
    memset(rs, 0, sizeof *rs);
    DHT_EQ_INT(dh_track_init_f32(&g->t, &g->r, g->closed ? &g->m : NULL, q0, DT), DH_OK);
    DHT_EQ_INT(dh_move_path_jerk_f32(&mv, p, lim, jk), DH_OK);
    max_calls = (long)ceil((20.0 * mv.dur + 5.0) / DT);
    lag_at = (long)(lag_frac * mv.dur / DT);
    for (call = 0; call < max_calls && !done; call++) {
        dh_track_state st;
        DHT_EQ_INT(dh_move_target_f32(&mv, &T), DH_OK);
        if (dhm_fd_push(&fd, &T, lim, ulp, call) && fd.nh >= (long)(NL - 1) * WD + 1)
            dhm_check_jerk((const float (*)[7])lp, W / WD, (double)W * DT, jk, ulp, call, rs->jerk);
        if (have && mv.bst == 0u && rs->resumes > 0) {
            /* after a resume: within the cap of s' */
            double d = 0.0;
            int k;
            for (k = 0; k < 3; k++) d += ((double)T.m[3][k] - Tp.m[3][k]) * ((double)T.m[3][k] - Tp.m[3][k]);
            DHT_TRUE_MSG(sqrt(d) <= (double)cap * mv.vs * p->length * DT * (1.0 + DHM_REL) + 4.0 * ulp,
                         "call %ld: step %.9g, cap %.9g of %.9g", call, sqrt(d), (double)cap, (double)mv.vs);
        }
        Tp = T;
        have = 1;
        DHT_EQ_INT(dh_track_step_f32(&g->t, &T, q, &trep), DH_OK);
        st = trep.state;
        if (lag_len > 0 && lag_from < 0 && call >= lag_at && mv.clock > 0.0f && mv.clock < mv.dur && mv.bst == 0u)
            lag_from = call;
        if (lag_from >= 0 && call - lag_from < lag_len) st = DH_TRACK_LAGGING;
        DHT_EQ_INT(dh_move_advance_f32(&mv, DT, st, &rep), DH_OK);
        DHT_EQ_INT(rep.held, st != DH_TRACK_OK);
        DHT_TRUE(rep.feed <= feed && rep.feed > 0.0f);
        if (st != DH_TRACK_OK) rs->notok++;
        if (bst == 0u && mv.bst != 0u) {
            rs->brakes++;
            DHT_TRUE(rep.feed <= 0.875f);
        }
        if (rs->brakes == 0) DHT_TRUE(rep.feed == 1.0f);
        feed = rep.feed;
        if (bst == 2u && mv.bst == 0u) {
            rs->resumes++;
            cap = rep.feed;
        }
        bst = mv.bst;
        done = rep.done;
    }
    rs->periods = call;
    DHT_TRUE_MSG(done, "not done in %ld periods (%.9g s planned)", call, (double)mv.dur);
    DHT_TRUE(memcmp(&T, &p->B, sizeof T) == 0);
    if (lag_len > 0) DHT_TRUE(lag_from >= 0 && rs->brakes > 0 && rs->resumes > 0);
}

/* The Puma line of the file's comment: the tracker's own lags brake the
 * move, which resumes and completes */
static void puma_lag(void)
{
    static const dh_cart_limits_f32 PLIM = { 0.3f, 1.5f, 90.0f, 360.0f };
    dhm_rig g;
    run_stats rs;
    double worst = 0.0;
    uint32_t i;
    int it, n = (int)DHT_ITER(4);
    long notok = 0, brakes = 0;
    DHT_EQ_INT(dhs_build(&dhs_puma560_m, &g.r), DH_OK);
    for (i = 0; i < g.r.n; i++) DHT_EQ_INT(dh_robot_set_rates_f32(&g.r, i, 150.0f, 600.0f), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_f32(&g.r, &g.m), DH_OK);
    g.closed = 1;
    for (it = 0; it < n; it++) {
        double qa[DH_MAX_JOINTS];
        float q0[DH_MAX_JOINTS];
        dh_cart_jerk_f32 jk;
        dh_mat4_f32 A, B;
        dh_path_f32 p;
        dhm_puma_line(&g.r, it == 0, qa, &A, &B);
        for (i = 0; i < 6u; i++) q0[i] = (float)qa[i];
        jk.jmax = (it == 0) ? 8.0f : (float)dht_rand_uniform(4.0, 20.0);
        jk.wjmax = (it == 0) ? 3600.0f : (float)dht_rand_uniform(1000.0, 6000.0);
        DHT_EQ_INT(dh_path_line_f32(&p, &A, &B), DH_OK);
        run_move(&g, q0, &p, &PLIM, &jk, 1.0, 0.0, 0, &rs);
        notok += rs.notok;
        brakes += rs.brakes;
        worst = fmax(worst, fmax(rs.jerk[0], rs.jerk[1]));
        if (it == 0)
            dht_printf("puma line: %ld periods, %ld not OK, %ld brakes, %ld resumes, worst jerk %ld ppm of the limits\n",
                       rs.periods, rs.notok, rs.brakes, rs.resumes, (long)(fmax(rs.jerk[0], rs.jerk[1]) * 1e6));
    }
    DHT_TRUE(notok > 0 && brakes > 0);
    dht_reach_max("move_jerk.puma_worst_jerk", worst);
}

/* random lines and arcs on c's robot, with a forced lag each */
static void forced(const dhm_robot_case *c)
{
    dhm_rig g;
    run_stats rs;
    long it, n = DHT_ITER(6), brakes = 0;
    double worst = 0.0;
    dhm_rig_make(&g, c);
    for (it = 0; it < n; it++) {
        float qc[2][DH_MAX_JOINTS], via[3];
        double q[DH_MAX_JOINTS], S = 1.0;
        dh_cart_limits_f32 lim;
        dh_cart_jerk_f32 jk;
        dh_mat4_f32 A, B;
        dh_path_f32 p;
        uint32_t i;
        for (i = 0; i < g.r.n; i++) qc[0][i] = (float)(c->q[i] + dht_rand_uniform(-5.0, 5.0));
        dhm_draw_q(&g.r, qc[0], 10.0, qc[1]);
        for (i = 0; i < g.r.n; i++) q[i] = qc[0][i];
        dhs_target_f32(&g.r, q, &A);
        for (i = 0; i < g.r.n; i++) q[i] = qc[1][i];
        dhs_target_f32(&g.r, q, &B);
        for (i = 0; i < 3u; i++) S = fmax(S, fmax(fabs((double)A.m[3][i]), fabs((double)B.m[3][i])));
        if (dhm_draw_via(&A.m[3][0], &B.m[3][0], via))
            DHT_EQ_INT(dh_path_arc_f32(&p, &A, via, &B), DH_OK);
        else
            DHT_EQ_INT(dh_path_line_f32(&p, &A, &B), DH_OK);
        dhm_draw_limits(&lim, &jk);
        run_move(&g, qc[0], &p, &lim, &jk, S, dht_rand_uniform(0.05, 0.9), 1 + (long)(dht_rand_u32() % 300u), &rs);
        brakes += rs.brakes;
        worst = fmax(worst, fmax(rs.jerk[0], rs.jerk[1]));
    }
    DHT_TRUE(brakes >= n);
    dht_printf("%s: %ld moves, %ld brakes, worst jerk %ld ppm of the limits\n", c->d->name, n, brakes,
               (long)(worst * 1e6));
}

static void forced_ur5(void) { forced(&dhm_ur5); }
static void forced_panda(void) { forced(&dhm_panda); }

static const dht_case cases[] = {
    DHT_CASE(puma_lag),
    DHT_CASE(forced_ur5),
    DHT_CASE(forced_panda),
};

DHT_MAIN(cases)
