/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_queue_q.c - the fixed-point move queue (motion.h: dh_queue_init_q,
 * dh_queue_add_joint_q, dh_queue_add_path_q, dh_queue_target_q,
 * dh_queue_advance_q, dh_queue_stop_q, dh_queue_resume_q) with the fixed
 * tracker (dh_track_step_q) on the UR5 and the Puma 560 in mm, 1 kHz.
 *
 * Random queues (seeded): joint moves to configurations of the robot's
 * region (support_motion_q.c) and line and arc moves between such
 * configurations' tool frames, appended to a queue of CAP items as it
 * drains (every end near a configuration of the region), run by the
 * firmware loop (target, dh_track_init_q when
 * cmd.sync, dh_track_step_q for path commands, advance), one stop in each
 * queue inside a move, at a random period or else in its last move (some
 * resumed while braking, the others after a random rest). Checked every period against references
 * computed here in double: a path move's target on its path within
 * PATH_TOL = 5e-3 mm (the bound at DH_QPOS_FRAC 16) and the tool
 * at every OK period within the tracker's pos_tol (plus the fixed FK's
 * 4 n LSB) of the target; over windows of w periods (a
 * ring of positions, one every DEC periods) the target's speed within
 * vmax and its total acceleration within amax times 1 + 1e-3 plus the
 * noise terms 2 N / (w dt) and 4 N / (w dt)^2 (N the target's position
 * noise: the path's bound, the profile's 4 + 2^-27 2^e LSB of its
 * distance 2^e, the clock's 1 us at vmax, 1 LSB), w the least window with
 * the noise within 2.5e-4 of the limit; every joint's commanded or
 * tracked position over such windows within the robot's vmax and amax
 * (the joint moves' limits) likewise, N = 4 LSB + 2^-27 of the move +
 * 1 us at vmax (dh_move_joint_step_q's rounding and the warped clock's
 * whole microseconds). A joint move ends at q1 exactly, a path move with
 * the tool at B within the tracker's tolerances; the stop reaches rest
 * (stopped) and the commands then hold still; every queued move
 * completes, in order.
 *
 * The Puma's line faster than its wrist can follow (test_move_q.c's) in a
 * queue with a joint move back and the line again, stopped while it lags:
 * lagging periods are reported held, the feed override falls below 1, the
 * checks above hold and the queue completes.
 *
 * Every status of the queue's functions for bad inputs, with the outputs
 * untouched.
 */
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_robots.h"
#include "support_motion_q.h"
#include "dhmath/motion.h"
#include "dhmath/track.h"
#include "dhmath/frame.h"

#define DT_US 1000u
#define DT 1e-3
#define QPOS DHSM_QPOS
#define Q16 DHSM_Q16
#define LS DHSM_LS
#define PATH_TOL (5e-3 * ldexp(1.0, 16 - DH_QPOS_FRAC))
#define REL_FD 1e-3
#define NOISE_FRAC 2.5e-4
#define CAP 3u     /* queue items (the micro:bit's RAM) */
#define DEC 4      /* one position kept every DEC periods */
#define RING 40    /* positions kept: the longest window (2 w) plus one, in DEC periods */
#define NJ 6u

/* one tracker, one queue (the M0 target has 16 KB of RAM: the robot, the
 * queue's items and the paths' references live on the cases' stacks) */
static dh_track_q the_trk;
static dh_queue_q the_qu;
static int32_t jring[RING][NJ];            /* joint positions, one every DEC periods */
static int32_t cring[RING][3];             /* targets of the running path move, one every DEC periods */

/* the generator of a queue's moves: the end of the last one appended */
typedef struct {
    int32_t q[NJ];      /* configuration there */
    dh_frame_q F;       /* its tool frame (a path's B, or the FK of a joint move's q1) */
    long left;          /* moves still to append */
    int lag;            /* 1: the Puma's lagging line, joint back, line again */
    dhsm_ref *refs;     /* each queued path move's reference, by item (CAP) */
    int32_t q0[NJ];     /* lag: the configuration the line starts from */
} gen_state;

/* the Puma's line (test_move_q.c's) and its limits */
static const dh_cart_limits_q PLIM = { 300 << 16, 1500 << 16, 90 << 16, 360 << 16 };
static const dh_cart_limits_q LIM = { 250 << 16, 2000 << 16, 45 << 16, 360 << 16 };

static void joint_rates(const dhsm_rig *g, int32_t *v, int32_t *a)
{
    uint32_t i;
    for (i = 0; i < NJ; i++) {
        v[i] = g->r.joint[i].vmax_q;
        a[i] = g->r.joint[i].amax_q;
    }
}

/* appends the generator's next move to the queue (one item is free) */
static void gen_next(const dhsm_rig *g, gen_state *gs)
{
    dh_queue_q *const qu = &the_qu;
    const uint32_t slot = (qu->head + qu->count) % qu->cap;
    int32_t v[NJ], a[NJ], ib[NJ], im[NJ];
    double qa[DH_MAX_JOINTS], qb[DH_MAX_JOINTS], qm[DH_MAX_JOINTS];
    dh_frame_q B, Mf;
    dh_path_q p;
    uint32_t i;
    int kind = (int)(dht_rand_u32() % 3u), tries = 0, ok = 0;
    joint_rates(g, v, a);
    if (gs->lag) kind = (gs->left == 2) ? 0 : 1;
    if (kind == 0) {
        if (gs->lag) {
            memcpy(ib, gs->q0, sizeof ib);
        } else {
            dhsm_region_q(g, qa);
            dhs_q_from_double(&g->r, qa, ib);
        }
        DHT_EQ_INT(dh_queue_add_joint_q(qu, NJ, ib, v, a, NULL), DH_OK);
        memcpy(gs->q, ib, sizeof ib);
        dhsm_target_of(g, ib, &gs->F);
        gs->left--;
        return;
    }
    if (gs->lag) {
        dh_frame_identity_q(&B);
        B.p[0] = (int32_t)(500.0 * LS * QPOS);
        B.p[1] = (int32_t)(-30.0 * LS * QPOS);
        B.p[2] = (int32_t)(1000.0 * LS * QPOS);
        DHT_EQ_INT(dh_path_line_q(&p, &gs->F, &B), DH_OK);
        dhsm_ref_make(&gs->refs[slot], &p, NULL);
        DHT_EQ_INT(dh_queue_add_path_q(qu, &p, &PLIM), DH_OK);
        gs->F = B;
        gs->left--;
        return;
    }
    while (!ok && tries++ < 50) {
        /* B 4 to 12 degrees per joint from the last end, each towards a
         * fresh configuration of the region (a free walk would drift
         * towards the singularities) */
        dhsm_region_q(g, qa);
        for (i = 0; i < NJ; i++) {
            const double dlt = dht_rand_uniform(4.0, 12.0) * (qa[i] < gs->q[i] / Q16 ? -1.0 : 1.0);
            qb[i] = gs->q[i] / Q16 + dlt;
            qm[i] = 0.5 * (gs->q[i] / Q16 + qb[i]) + dht_rand_uniform(-4.0, 4.0);
        }
        dhs_q_from_double(&g->r, qb, ib);
        dhs_q_from_double(&g->r, qm, im);
        dhsm_target_of(g, ib, &B);
        dhsm_target_of(g, im, &Mf);
        if (kind == 2) {
            if (dh_path_arc_q(&p, &gs->F, Mf.p, &B) != DH_OK) continue;
        } else {
            DHT_EQ_INT(dh_path_line_q(&p, &gs->F, &B), DH_OK);
        }
        ok = dhsm_path_reachable(g, &p, gs->q);
    }
    DHT_TRUE(ok);
    dhsm_ref_make(&gs->refs[slot], &p, kind == 2 ? Mf.p : NULL);
    DHT_EQ_INT(dh_queue_add_path_q(qu, &p, &LIM), DH_OK);
    memcpy(gs->q, ib, sizeof ib);
    gs->F = B;
    gs->left--;
}

/* windows (periods, multiples of DEC) for the noise N at the limits V, A */
static void windows(double N, double V, double A, long *wv, long *wa)
{
    long v = (long)ceil(2.0 * N / (NOISE_FRAC * V * DT)), a = (long)ceil(sqrt(4.0 * N / (NOISE_FRAC * A)) / DT);
    *wv = DEC * ((v + DEC - 1) / DEC + (v < 1));
    *wa = DEC * ((a + DEC - 1) / DEC + (a < 1));
    DHT_TRUE_MSG(2 * *wa < DEC * RING && *wv < DEC * RING, "windows %ld %ld periods", *wv, *wa);
}

/* speed and acceleration of ring positions (m coordinates, scale to the
 * unit) over the windows ending at period k, n the periods the ring holds */
static void ring_rates(int32_t *rg, int m, double scale, long k, long n, double N, double V, double A, long wv,
                       long wa, const char *what)
{
    int c;
    if (k % DEC != 0) return;
    if (n >= wv) {
        double sp = 0.0;
        for (c = 0; c < m; c++) {
            const double x = ((double)rg[((k / DEC) % RING) * m + c] - rg[(((k - wv) / DEC) % RING) * m + c]) * scale;
            if (m == 3) sp += x * x;
            else DHT_TRUE_MSG(fabs(x) / (wv * DT) <= V * (1 + REL_FD) + 2.0 * N / (wv * DT),
                              "%s period %ld: joint %d speed %.6g > %.6g", what, k, c, fabs(x) / (wv * DT), V);
        }
        if (m == 3)
            DHT_TRUE_MSG(sqrt(sp) / (wv * DT) <= V * (1 + REL_FD) + 2.0 * N / (wv * DT), "%s period %ld: speed %.6g > %.6g",
                         what, k, sqrt(sp) / (wv * DT), V);
    }
    if (n >= 2 * wa) {
        double ac = 0.0;
        const double w2 = (wa * DT) * (wa * DT);
        for (c = 0; c < m; c++) {
            const double x = ((double)rg[((k / DEC) % RING) * m + c] - 2.0 * rg[(((k - wa) / DEC) % RING) * m + c] +
                              rg[(((k - 2 * wa) / DEC) % RING) * m + c]) * scale;
            if (m == 3) ac += x * x;
            else DHT_TRUE_MSG(fabs(x) / w2 <= A * (1 + REL_FD) + 4.0 * N / w2, "%s period %ld: joint %d acceleration %.6g > %.6g",
                              what, k, c, fabs(x) / w2, A);
        }
        if (m == 3)
            DHT_TRUE_MSG(sqrt(ac) / w2 <= A * (1 + REL_FD) + 4.0 * N / w2, "%s period %ld: acceleration %.6g > %.6g", what, k,
                         sqrt(ac) / w2, A);
    }
}

typedef struct {
    long periods, notok, stops, minfeed_hits;
    dh_q30 minfeed;
} run_stats;

/* A queue of nm moves run to its end (the file's comment), stopped once
 * at the first period from stop_at inside a move; resumed at once
 * (early) or after rest periods of rest */
static void run_queue(const dhsm_rig *g, gen_state *gs, long stop_at, int early, long rest, run_stats *rs,
                      const char *what)
{
    dh_queue_q *const qu = &the_qu;
    dh_track_q *const t = &the_trk;
    const double VJ = g->r.joint[0].vmax_q, AJ = g->r.joint[0].amax_q;   /* LSB/s, /s^2: every joint's */
    double NP = 0.0, V = 0.0, A = 0.0;
    long k, wvj, waj, wv = 0, wa = 0, jn = 0, cn = 0, stopped_for = -1, braking = -1;
    const long limit = 400000;
    uint32_t seq = 0, runkind = 0;
    int32_t q[NJ], qhold[NJ];
    dh_frame_q Thold;
    const double NJN = 4.0 + ldexp(90.0 * Q16, -27) + VJ * 1e-6;   /* joint moves of up to 90 degrees */
    int stop_done = 0, was_stopped;
    windows(NJN, VJ, AJ, &wvj, &waj);
    memcpy(q, t->q, sizeof q);
    memset(rs, 0, sizeof *rs);
    rs->minfeed = DH_Q30_ONE;
    for (k = 0; k < limit; k++) {
        dh_queue_cmd_q cmd;
        dh_queue_report_q rep;
        dh_track_report_q tr;
        dh_track_state state = DH_TRACK_OK;
        const uint32_t head = qu->head;
        while (gs->left > 0 && qu->count < qu->cap) gen_next(g, gs);
        if (qu->count == 0u && gs->left == 0) break;
        DHT_EQ_INT(dh_queue_target_q(qu, t, &cmd), DH_OK);
        /* a new path move: its windows and a fresh ring */
        if (qu->started && qu->mv.kind == DH_MOVE_PATH && (qu->seq != seq || runkind != DH_MOVE_PATH || qu->mv.clock == 0u)) {
            const dh_move_q *mv = &qu->mv;
            const dhsm_ref *rp = &gs->refs[head];
            const dh_cart_limits_q *lim = &qu->items[head].lim;
            const double pb = (rp->arc ? 4.0 + ldexp(rp->R * QPOS, -26) : 0.87) / QPOS;
            V = lim->vmax / QPOS;
            A = lim->amax / QPOS;
            NP = pb + mv->path.length / QPOS * (5.0 * ldexp(1.0, -(int)mv->e) + ldexp(1.0, -27)) + V * 1e-6 + 1.0 / QPOS;
            windows(NP, V, A, &wv, &wa);
            if (mv->clock == 0u) cn = 0;
        }
        seq = qu->seq;
        runkind = qu->started ? qu->mv.kind : 0u;
        if (cmd.kind == DH_MOVE_PATH) {
            double pt[3];
            int c;
            if (cmd.sync) DHT_EQ_INT(dh_track_init_q(t, &g->r, &g->m, cmd.q, DT_US), DH_OK);
            DHT_EQ_INT(dh_track_step_q(t, &cmd.T, q, &tr), DH_OK);
            state = tr.state;
            if (qu->started) {
                const dhsm_ref *rp = &gs->refs[head];
                double d;
                for (c = 0; c < 3; c++) pt[c] = cmd.T.p[c] / QPOS;
                d = dhsm_ref_dist(rp, pt);
                DHT_TRUE_MSG(d <= PATH_TOL, "%s period %ld: target %.3g mm off the path", what, k, d);
                if (state == DH_TRACK_OK) {
                    /* the tool within the tracker's tolerance of the target */
                    const double tol = t->pos_tol / QPOS + 4.0 * NJ / QPOS + 1e-6;
                    dhr_mat4 F;
                    double pq[3], dt;
                    dhsm_tool_mm(g, q, pq, &F);
                    dt = dhsm_dist3(pq, pt);
                    DHT_TRUE_MSG(dt <= tol, "%s period %ld: tool %.3g mm from the target", what, k, dt);
                    DHT_TRUE_MSG(dhsm_ref_dist(rp, pq) <= d + tol, "%s period %ld: tool off the path", what, k);
                    dht_reach_max("queue_q.tool_path_mm", dhsm_ref_dist(rp, pq) / ldexp(1.0, 16 - DH_QPOS_FRAC));
                }
                if (cn % DEC == 0) memcpy(cring[(cn / DEC) % RING], cmd.T.p, sizeof cring[0]);
                if (cn % DEC == 0) ring_rates(&cring[0][0], 3, 1.0 / QPOS, cn, cn, NP, V, A, wv, wa, what);
                cn++;
            }
            if (state != DH_TRACK_OK) rs->notok++;
        } else if (cmd.kind == DH_MOVE_JOINT) {
            memcpy(q, cmd.q, sizeof q);
        }
        if (qu->phase == DH_QUEUE_STOPPED && stopped_for >= 0) {
            /* at rest: the commands hold still */
            if (cmd.kind == DH_MOVE_JOINT) DHT_TRUE(memcmp(cmd.q, qhold, sizeof qhold) == 0);
            if (cmd.kind == DH_MOVE_PATH) DHT_TRUE(memcmp(&cmd.T, &Thold, sizeof Thold) == 0);
        }
        memcpy(qhold, cmd.q, sizeof qhold);
        Thold = cmd.T;
        if (k % DEC == 0) memcpy(jring[(k / DEC) % RING], q, sizeof jring[0]);
        jn++;
        ring_rates(&jring[0][0], NJ, 1.0, k, jn, NJN, VJ, AJ, wvj, waj, what);
        was_stopped = qu->phase == DH_QUEUE_STOPPED;
        DHT_EQ_INT(dh_queue_advance_q(qu, state, &rep), DH_OK);
        DHT_TRUE(rep.feed >= 0 && rep.feed <= DH_Q30_ONE);
        if (rep.feed < rs->minfeed) rs->minfeed = rep.feed;
        if (cmd.kind == DH_MOVE_PATH && runkind == DH_MOVE_PATH) DHT_EQ_INT(rep.held, state != DH_TRACK_OK || was_stopped);
        if (rep.done) {
            if (qu->mv.kind == DH_MOVE_JOINT) DHT_TRUE_MSG(memcmp(q, qu->mv.q1, NJ * sizeof q[0]) == 0, "%s: joint move not at q1", what);
            if (qu->mv.kind == DH_MOVE_PATH) {
                dhr_mat4 F;
                double pq[3], pb[3];
                int c;
                DHT_TRUE(state == DH_TRACK_OK);
                dhsm_tool_mm(g, q, pq, &F);
                for (c = 0; c < 3; c++) pb[c] = qu->mv.path.B.p[c] / QPOS;
                DHT_TRUE_MSG(dhsm_dist3(pq, pb) <= t->pos_tol / QPOS + 4.0 * NJ / QPOS + 1e-6, "%s: end %.3g mm from B", what,
                             dhsm_dist3(pq, pb));
            }
            DHT_EQ_INT(rep.seq + 1u, qu->seq);
        }
        /* the stop: inside a move (started, clock strictly inside) */
        if (!stop_done && braking < 0 && (k >= stop_at || (gs->left == 0 && qu->count == 1u)) && qu->started && qu->mv.clock > 0u && qu->mv.clock < qu->mv.dur &&
            (qu->mv.kind == DH_MOVE_JOINT ? qu->r > 0 : qu->mv.feed > 0)) {
            DHT_EQ_INT(dh_queue_stop_q(qu), DH_OK);
            DHT_EQ_INT(qu->phase, DH_QUEUE_BRAKE);
            braking = 0;
            rs->stops++;
        } else if (braking >= 0 && stopped_for < 0) {
            braking++;
            DHT_TRUE_MSG(braking < (long)(qu->mv.dur / DT_US) + 1000, "%s: the brake does not reach rest", what);
            if (early && braking == 5) {
                DHT_EQ_INT(dh_queue_resume_q(qu), DH_OK);
                stop_done = 1;
                braking = -1;
            } else if (rep.stopped) {
                stopped_for = 0;
            }
        } else if (stopped_for >= 0) {
            DHT_TRUE(rep.stopped);
            if (stopped_for++ >= rest) {
                DHT_EQ_INT(dh_queue_resume_q(qu), DH_OK);
                DHT_EQ_INT(qu->phase, DH_QUEUE_RUN);
                stopped_for = -1;
                braking = -1;
                stop_done = 1;
            }
        }
    }
    rs->periods = k;
    DHT_TRUE_MSG(k < limit && qu->count == 0u, "%s: the queue did not complete (%ld periods)", what, k);
}

static const dhs_robot *const robots[] = { &dhs_ur5_mm, &dhs_puma560_mm };

static void random_queues_q(void)
{
    size_t ri;
    for (ri = 0; ri < sizeof robots / sizeof robots[0]; ri++) {
        dhsm_rig rig;
        dh_queue_item_q items[CAP];
        dhsm_ref refs[CAP];
        dhsm_rig *const g = &rig;
        long it, n = DHT_ITER(4), periods = 0, notok = 0, stops = 0;
        dhsm_rig_make(g, robots[ri], 180.0, 720.0);
        for (it = 0; it < n; it++) {
            double qa[DH_MAX_JOINTS];
            int32_t ia[NJ];
            gen_state gs;
            run_stats rs;
            memset(&gs, 0, sizeof gs);
            gs.refs = refs;
            dhsm_region_q(g, qa);
            dhs_q_from_double(&g->r, qa, ia);
            memcpy(gs.q, ia, sizeof ia);
            dhsm_target_of(g, ia, &gs.F);
            gs.left = 3 + (long)(dht_rand_u32() % 4u);
            DHT_EQ_INT(dh_track_init_q(&the_trk, &g->r, &g->m, ia, DT_US), DH_OK);
            DHT_EQ_INT(dh_queue_init_q(&the_qu, items, CAP), DH_OK);
            run_queue(g, &gs, (long)(dht_rand_u32() % 1500u), (dht_rand_u32() % 3u) == 0u, (long)(dht_rand_u32() % 200u),
                      &rs, g->d->name);
            periods += rs.periods;
            notok += rs.notok;
            stops += rs.stops;
        }
        dht_printf("%s: %ld queues, %ld periods, %ld not OK, %ld stops inside a move\n", g->d->name, n, periods, notok,
                   stops);
        DHT_TRUE(stops > 0);
    }
}

/* The Puma's line its wrist cannot follow, in a queue (the file's comment) */
static void lagging_queue_q(void)
{
    static const double QP[6] = { 10.0, -30.0, 45.0, 20.0, 35.0, -60.0 };
    dhsm_rig rig;
    dh_queue_item_q items[CAP];
    dhsm_ref refs[CAP];
    dhsm_rig *const g = &rig;
    double qa[DH_MAX_JOINTS];
    int32_t ia[NJ];
    gen_state gs;
    run_stats rs;
    int k;
    dhsm_rig_make(g, &dhs_puma560_mm, 150.0, 600.0);
    for (k = 0; k < 6; k++) qa[k] = QP[k];
    dhs_q_from_double(&g->r, qa, ia);
    memset(&gs, 0, sizeof gs);
    gs.refs = refs;
    memcpy(gs.q, ia, sizeof ia);
    memcpy(gs.q0, ia, sizeof ia);
    dhsm_target_of(g, ia, &gs.F);
    gs.left = 3;
    gs.lag = 1;
    DHT_EQ_INT(dh_track_init_q(&the_trk, &g->r, &g->m, ia, DT_US), DH_OK);
    DHT_EQ_INT(dh_queue_init_q(&the_qu, items, CAP), DH_OK);
    run_queue(g, &gs, 150 + (long)(dht_rand_u32() % 300u), 0, 50, &rs, "Puma lagging queue");
    DHT_TRUE_MSG(rs.notok > 0, "the Puma queue: no lagging period");
    DHT_TRUE(rs.minfeed < DH_Q30_ONE);
    dht_reach_max("queue_q.puma_notok", (double)rs.notok);
    dht_printf("Puma lagging queue: %ld periods, %ld not OK, least feed %.3f\n", rs.periods, rs.notok,
               rs.minfeed / 1073741824.0);
}

static void queue_q_errors(void)
{
    dh_queue_q *const qu = &the_qu;
    dhsm_rig rig;
    dh_queue_item_q items[CAP];
    dhsm_rig *const g = &rig;
    dh_queue_cmd_q cmd, keep_cmd;
    dh_queue_report_q rep, keep_rep;
    dh_frame_q A, B;
    dh_path_q p;
    dh_cart_limits_q lim = LIM;
    int32_t q1[NJ] = { 0 }, v[NJ], a[NJ];
    double qa[DH_MAX_JOINTS];
    int32_t ia[NJ];
    dhsm_rig_make(g, &dhs_ur5_mm, 180.0, 720.0);
    dhs_ur5_safe_q(15.0, qa);
    dhs_q_from_double(&g->r, qa, ia);
    DHT_EQ_INT(dh_track_init_q(&the_trk, &g->r, &g->m, ia, DT_US), DH_OK);
    joint_rates(g, v, a);
    memset(&keep_cmd, 0x5a, sizeof keep_cmd);
    memset(&keep_rep, 0x5a, sizeof keep_rep);
    cmd = keep_cmd;
    rep = keep_rep;
    DHT_EQ_INT(dh_queue_init_q(qu, items, 0u), DH_ERR_ARG);
    DHT_EQ_INT(dh_queue_init_q(qu, items, 1u), DH_OK);
    /* nothing queued: no command, and a stop is immediate */
    DHT_EQ_INT(dh_queue_advance_q(qu, DH_TRACK_OK, &rep), DH_ERR_ARG);
    DHT_TRUE(memcmp(&rep, &keep_rep, sizeof rep) == 0);
    DHT_EQ_INT(dh_queue_target_q(qu, &the_trk, &cmd), DH_OK);
    DHT_EQ_INT(cmd.kind, DH_MOVE_NONE);
    cmd = keep_cmd;
    DHT_EQ_INT(dh_queue_target_q(qu, &the_trk, &cmd), DH_ERR_ARG);   /* pending */
    DHT_TRUE(memcmp(&cmd, &keep_cmd, sizeof cmd) == 0);
    DHT_EQ_INT(dh_queue_stop_q(qu), DH_ERR_ARG);
    DHT_EQ_INT(dh_queue_resume_q(qu), DH_ERR_ARG);
    DHT_EQ_INT(dh_queue_advance_q(qu, (dh_track_state)77, &rep), DH_ERR_ARG);
    DHT_TRUE(memcmp(&rep, &keep_rep, sizeof rep) == 0);
    DHT_EQ_INT(dh_queue_advance_q(qu, DH_TRACK_OK, &rep), DH_OK);
    DHT_TRUE(rep.last == 1 && rep.done == 0 && rep.held == 1);
    DHT_EQ_INT(dh_queue_stop_q(qu), DH_OK);
    DHT_EQ_INT(qu->phase, DH_QUEUE_STOPPED);
    DHT_EQ_INT(dh_queue_resume_q(qu), DH_OK);
    DHT_EQ_INT(qu->phase, DH_QUEUE_RUN);
    /* joint moves: bad arguments, a full queue */
    DHT_EQ_INT(dh_queue_add_joint_q(qu, 0u, q1, v, a, NULL), DH_ERR_ARG);
    DHT_EQ_INT(dh_queue_add_joint_q(qu, DH_MAX_JOINTS + 1u, q1, v, a, NULL), DH_ERR_ARG);
    v[3] = 0;
    DHT_EQ_INT(dh_queue_add_joint_q(qu, NJ, q1, v, a, NULL), DH_ERR_ARG);
    v[3] = v[2];
    DHT_EQ_INT(qu->count, 0u);
    DHT_EQ_INT(dh_queue_add_joint_q(qu, NJ, ia, v, a, NULL), DH_OK);
    DHT_EQ_INT(dh_queue_add_joint_q(qu, NJ, ia, v, a, NULL), DH_ERR_LIMIT);
    dhsm_target_of(g, ia, &A);
    B = A;
    B.p[0] += 10 << 16;
    DHT_EQ_INT(dh_path_line_q(&p, &A, &B), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_q(qu, &p, &LIM), DH_ERR_LIMIT);
    DHT_EQ_INT(qu->count, 1u);
    /* a joint move for another number of joints than the robot's */
    DHT_EQ_INT(dh_queue_init_q(qu, items, CAP), DH_OK);
    DHT_EQ_INT(dh_queue_add_joint_q(qu, 5u, ia, v, a, NULL), DH_OK);
    cmd = keep_cmd;
    DHT_EQ_INT(dh_queue_target_q(qu, &the_trk, &cmd), DH_ERR_ARG);
    DHT_TRUE(memcmp(&cmd, &keep_cmd, sizeof cmd) == 0);
    /* path moves: bad limits, no path */
    DHT_EQ_INT(dh_queue_init_q(qu, items, CAP), DH_OK);
    lim.wdmax = 0;
    DHT_EQ_INT(dh_queue_add_path_q(qu, &p, &lim), DH_ERR_ARG);
    memset(&p, 0, sizeof p);
    DHT_EQ_INT(dh_queue_add_path_q(qu, &p, &LIM), DH_ERR_ARG);
    DHT_EQ_INT(qu->count, 0u);
    /* a joint move to where the robot is: done at once, at q1 */
    DHT_EQ_INT(dh_queue_add_joint_q(qu, NJ, ia, v, a, NULL), DH_OK);
    DHT_EQ_INT(dh_queue_target_q(qu, &the_trk, &cmd), DH_OK);
    DHT_EQ_INT(cmd.kind, DH_MOVE_JOINT);
    DHT_TRUE(memcmp(cmd.q, ia, sizeof ia) == 0);
    DHT_EQ_INT(dh_queue_stop_q(qu), DH_ERR_ARG);
    DHT_EQ_INT(dh_queue_advance_q(qu, DH_TRACK_OK, &rep), DH_OK);
    DHT_TRUE(rep.done == 1 && rep.last == 1 && rep.seq == 0u && qu->seq == 1u);
    /* then the hold command is that configuration */
    DHT_EQ_INT(dh_queue_target_q(qu, &the_trk, &cmd), DH_OK);
    DHT_TRUE(cmd.kind == DH_MOVE_JOINT && memcmp(cmd.q, ia, sizeof ia) == 0);
    DHT_EQ_INT(dh_queue_advance_q(qu, DH_TRACK_OK, &rep), DH_OK);
    /* a path after it: sync once, a stop held at its start is immediate */
    dhsm_target_of(g, ia, &A);
    B = A;
    B.p[0] += 10 << 16;
    DHT_EQ_INT(dh_path_line_q(&p, &A, &B), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_q(qu, &p, &LIM), DH_OK);
    DHT_EQ_INT(dh_queue_target_q(qu, &the_trk, &cmd), DH_OK);
    DHT_TRUE(cmd.kind == DH_MOVE_PATH && cmd.sync == 1u && memcmp(cmd.q, ia, sizeof ia) == 0);
    DHT_TRUE(memcmp(&cmd.T, &A, sizeof A) == 0);
    DHT_EQ_INT(dh_queue_advance_q(qu, DH_TRACK_LAGGING, &rep), DH_OK);
    DHT_TRUE(rep.held == 1 && rep.clock == 0u && rep.feed == 0);
    DHT_EQ_INT(dh_queue_stop_q(qu), DH_OK);
    DHT_EQ_INT(qu->phase, DH_QUEUE_STOPPED);
    DHT_EQ_INT(dh_queue_target_q(qu, &the_trk, &cmd), DH_OK);
    DHT_TRUE(cmd.kind == DH_MOVE_PATH && cmd.sync == 0u && memcmp(&cmd.T, &A, sizeof A) == 0);
    DHT_EQ_INT(dh_queue_advance_q(qu, DH_TRACK_OK, &rep), DH_OK);
    DHT_TRUE(rep.stopped == 1 && rep.held == 1 && rep.clock == 0u);
    /* a corrupted running path is refused */
    qu->mv.e = 31u;
    cmd = keep_cmd;
    DHT_EQ_INT(dh_queue_target_q(qu, &the_trk, &cmd), DH_ERR_ARG);
    DHT_TRUE(memcmp(&cmd, &keep_cmd, sizeof cmd) == 0);
}

static const dht_case cases[] = {
    DHT_CASE(random_queues_q),
    DHT_CASE(lagging_queue_q),
    DHT_CASE(queue_q_errors),
};
DHT_MAIN(cases)
