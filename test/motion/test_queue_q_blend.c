/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_queue_q_blend.c - blended lines and arcs in the fixed-point move queue
 * (motion.h: dh_queue_add_path_blend_q, run by dh_queue_target_q and
 * dh_queue_advance_q, with dh_queue_stop_q and dh_queue_resume_q) with
 * the fixed tracker (dh_track_step_q) on the UR5 and the Puma 560 in mm,
 * 1 kHz (the Panda's seven joints have no fixed closed-form model for
 * the fixed tracker).
 *
 * Random chains (seeded) of 2 to 3 lines and arcs (through a point off
 * the chord by 0.1 to 0.3 of its length) between tool frames of
 * configurations of the robot's region (support_motion_q.c), each
 * appended with a random radius (0 to 24 mm, in units of 2^(16 - F) mm
 * as the robots are), all before the first period, run by the firmware
 * loop (dh_track_init_q when cmd.sync, dh_track_step_q, advance). In
 * some chains a stop at the first period inside an overlap, resumed
 * after a random rest or at once (during the brake). Checked every period
 * against references computed here in double: outside the overlaps the
 * target within PATH_TOL = 5e-3 mm of its line or arc (the bound
 * at DH_QPOS_FRAC 16), inside an overlap within the corner's dev (<= its
 * radius) plus the held scalings' and the arcs' rounding of the corner;
 * the tool at every OK period within the tracker's pos_tol (plus the
 * fixed FK's 4 n LSB) of the target; over windows of w periods (a position every DEC
 * periods) the target's speed within vmax and its total acceleration
 * within amax times 1 + 1e-3 plus the noise terms 2 N / (w dt) and
 * 4 N / (w dt)^2 (N: 1 LSB of the path, an arc's 4 LSB + 2^-26 R, 64
 * 2^-30 of the two paths' length of the held scalings, the clock's 1 us
 * at vmax), w the least window with the noise within 2.5e-4 of the limit; every joint's tracked
 * position over such windows within the robot's vmax and amax. Every
 * line completes in order (seq), the last with the target at its B bit
 * for bit and the tool there within the tracker's tolerance; a stop
 * reaches rest and the commands hold still until the resume.
 *
 * The Puma's line faster than its wrist can follow (test_move_q.c's)
 * blended into a second line: lagging periods are reported held, the
 * feed override falls below 1, the limits and the blend's radius hold and
 * the queue completes.
 *
 * Every status of dh_queue_add_path_blend_q, and the corners it runs at
 * rest.
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
#define NL 3u      /* lines of a chain at most (the queue's items: the micro:bit's RAM) */
#define DEC 4      /* one position kept every DEC periods */
#define RING 42    /* positions kept, in DEC periods: the longest window (2 w) plus one */
#define NJ 6u

/* one tracker, one queue (the M0 target has 16 KB of RAM: the queue's
 * items live on the cases' stacks) */
static dh_track_q the_trk;
static dh_queue_q the_qu;
static int32_t pring[RING][3];   /* targets, one every DEC periods */
static int32_t jring[RING][NJ];  /* tracked joints, one every DEC periods */

static const dh_cart_limits_q LIM = { 250 << 16, 2000 << 16, 45 << 16, 360 << 16 };
/* the Puma's lagging line's limits (test_move_q.c's) */
static const dh_cart_limits_q PLIM = { 300 << 16, 1500 << 16, 90 << 16, 360 << 16 };

/* a chain of lines: the paths, their double references and radii */
typedef struct {
    dh_path_q p[NL];
    dhsm_ref ref[NL];
    dh_qpos R[NL];
    uint32_t n;
    const dh_cart_limits_q *lim;
} chain;

/* the least window (periods, a multiple of DEC) with the noise 2 N / w
 * (k 1: speed) or 4 N / w^2 (k 2) within NOISE_FRAC of the limit L */
static long window_of(double N, double L, int k)
{
    const double w = (k == 1) ? 2.0 * N / (NOISE_FRAC * L * DT) : sqrt(4.0 * N / (NOISE_FRAC * L)) / DT;
    const long p = DEC * ((long)ceil(w / DEC) + 1);
    DHT_TRUE_MSG(2 * p < DEC * RING, "window %ld periods for noise %.3g", p, N);
    return p;
}

/* the difference of order k (1 or 2) over w periods of coordinate c of
 * m-wide ring positions, ending at period i (a multiple of DEC) */
static double ring_diff(const int32_t *rg, int m, int c, long i, long w, int k)
{
    const double x0 = rg[((i / DEC) % RING) * m + c], x1 = rg[(((i - w) / DEC) % RING) * m + c];
    if (k == 1) return x0 - x1;
    return x0 - 2.0 * x1 + rg[(((i - 2 * w) / DEC) % RING) * m + c];
}

/* The rates of the ring rg (m coordinates, scale to mm or degrees) at
 * period i, n positions recorded since it was fresh: the norm (m 3) or
 * each coordinate's speed over wv and acceleration over wa within V and
 * A up to the noise N */
static void check_rates(const int32_t *rg, int m, double scale, long i, long n, double N, double V, double A, long wv,
                        long wa, const char *what)
{
    int k;
    for (k = 1; k <= 2; k++) {
        const long w = (k == 1) ? wv : wa;
        const double tw = pow(w * DT, (double)k), L = (k == 1) ? V : A;
        const double bound = L * (1 + REL_FD) + 2.0 * k * N / tw;
        double sq = 0.0;
        int c;
        if (n < k * w) continue;
        for (c = 0; c < m; c++) {
            const double x = ring_diff(rg, m, c, i, w, k) * scale / tw;
            if (m == 3) sq += x * x;
            else DHT_TRUE_MSG(fabs(x) <= bound, "%s period %ld: joint %d rate %d %.6g > %.6g", what, i, c, k, fabs(x), L);
        }
        if (m == 3) DHT_TRUE_MSG(sqrt(sq) <= bound, "%s period %ld: rate %d %.6g > %.6g", what, i, k, sqrt(sq), L);
    }
}

/* via = the point of the arc from F to B bulging out of the chord by
 * f of its length (f in [0.1, 0.3]) in a random direction across it */
static void arc_via(const dh_frame_q *F, const dh_frame_q *B, dh_qpos *via)
{
    double d[3], r[3], x[3], n = 0.0, L = 0.0, f = dht_rand_uniform(0.1, 0.3);
    int i;
    for (i = 0; i < 3; i++) {
        d[i] = (double)B->p[i] - F->p[i];
        r[i] = dht_rand_uniform(-1.0, 1.0);
        L += d[i] * d[i];
    }
    x[0] = d[1] * r[2] - d[2] * r[1];
    x[1] = d[2] * r[0] - d[0] * r[2];
    x[2] = d[0] * r[1] - d[1] * r[0];
    for (i = 0; i < 3; i++) n += x[i] * x[i];
    L = sqrt(L);
    n = sqrt(n);
    for (i = 0; i < 3; i++)
        via[i] = (dh_qpos)llround(0.5 * ((double)F->p[i] + B->p[i]) + ((n > 0.0) ? f * L * x[i] / n : 0.0));
}

/* the chain's lines and arcs from the configuration q through n - 1 more
 * of the region (each joint 4 to 12 degrees on), each reachable, an arc
 * with probability 1/2 (through arc_via's point); radii in [0, 24] mm
 * (some 0), in [5, 24] mm in the first chain of a robot (so that every
 * run passes blended corners), whose paths alternate: line, arc, line */
static void chain_make(const dhsm_rig *g, const int32_t *q0, uint32_t n, int first, chain *ch)
{
    int32_t q[NJ], qb[NJ];
    dh_frame_q F, B;
    uint32_t k, i;
    memcpy(q, q0, sizeof q);
    dhsm_target_of(g, q, &F);
    ch->n = n;
    ch->lim = &LIM;
    for (k = 0; k < n; k++) {
        int tries = 0, ok = 0;
        const int arc = first ? (int)(k % 2u) : (int)(dht_rand_u32() % 2u);
        dh_qpos via[3];
        while (!ok && tries++ < 50) {
            double qa[DH_MAX_JOINTS], qn[DH_MAX_JOINTS];
            dhsm_region_q(g, qa);
            for (i = 0; i < NJ; i++)
                qn[i] = q[i] / Q16 + dht_rand_uniform(4.0, 12.0) * (qa[i] < q[i] / Q16 ? -1.0 : 1.0);
            dhs_q_from_double(&g->r, qn, qb);
            dhsm_target_of(g, qb, &B);
            if (arc) {
                arc_via(&F, &B, via);
                if (dh_path_arc_q(&ch->p[k], &F, via, &B) != DH_OK) continue;
            } else {
                DHT_EQ_INT(dh_path_line_q(&ch->p[k], &F, &B), DH_OK);
            }
            ok = dhsm_path_reachable(g, &ch->p[k], q);
        }
        DHT_TRUE(ok);
        dhsm_ref_make(&ch->ref[k], &ch->p[k], arc ? via : NULL);
        ch->R[k] = (dh_qpos)(dht_rand_uniform(first ? 5.0 : 0.0, 24.0) * LS * QPOS);
        if (!first && dht_rand_u32() % 5u == 0u) ch->R[k] = 0;
        memcpy(q, qb, sizeof q);
        F = B;
    }
}

typedef struct {
    long periods, notok, blended, arcs, inside, stopped;
    dh_q30 minfeed;
} run_stats;

/* the current line's overlap with the next: 1 when the running blended
 * line's clock is in its end tail */
static int in_overlap(const dh_queue_q *qu)
{
    const dh_blend_seg_q *g = &qu->bg;
    return qu->started && qu->bl && g->dur[4] > 0u && qu->mv.clock > g->T - g->dur[4];
}

/* The chain ch run from the tracker's configuration to its end (the
 * file's comment): stopped at the first period inside an overlap when
 * stop (resumed after rest periods; at once during the brake when rest
 * < 0) */
static void run_chain(const dhsm_rig *g, const chain *ch, int stop, long rest, run_stats *rs, const char *what)
{
    dh_queue_q *const qu = &the_qu;
    dh_track_q *const t = &the_trk;
    const double V = ch->lim->vmax / QPOS, A = ch->lim->amax / QPOS;
    const double VJ = g->r.joint[0].vmax_q, AJ = g->r.joint[0].amax_q;
    double Lmax = 0.0, Rmax = 0.0, NA, NP, NJN;
    long i, n = 0, wv, wa, wvj, waj, still = -1, braking = -1;
    uint32_t k, done = 0;
    int32_t q[NJ];
    dh_frame_q Thold;
    int stop_done = !stop;
    for (k = 0; k < ch->n; k++) {
        Lmax = fmax(Lmax, ch->p[k].length);
        Rmax = fmax(Rmax, ch->p[k].radius);
    }
    /* an arc's point within 4 LSB + 2^-26 of its radius (dh_path_eval_q) */
    NA = 4.0 + Rmax / 67108864.0;
    NP = (1.0 + NA + 2.0 * Lmax * 64.0 / DHSM_Q30) / QPOS + V * 1e-6;
    NJN = 4.0 + VJ * 1e-6;
    wv = window_of(NP, V, 1);
    wa = window_of(NP, A, 2);
    wvj = window_of(NJN, VJ, 1);
    waj = window_of(NJN, AJ, 2);
    memcpy(q, t->q, sizeof q);
    memset(rs, 0, sizeof *rs);
    rs->minfeed = DH_Q30_ONE;
    for (i = 0; i < 400000 && qu->count > 0u; i++) {
        dh_queue_cmd_q cmd;
        dh_queue_report_q rep;
        dh_track_report_q tr;
        const uint32_t line = qu->seq;
        double pt[3];
        int c, ov;
        DHT_EQ_INT(dh_queue_target_q(qu, t, &cmd), DH_OK);
        DHT_EQ_INT(cmd.kind, DH_MOVE_PATH);
        if (cmd.sync) DHT_EQ_INT(dh_track_init_q(t, &g->r, &g->m, cmd.q, DT_US), DH_OK);
        DHT_EQ_INT(dh_track_step_q(t, &cmd.T, q, &tr), DH_OK);
        for (c = 0; c < 3; c++) pt[c] = cmd.T.p[c] / QPOS;
        ov = in_overlap(qu);
        if (ov) {
            /* within the corner's dev (<= its radius) of the corner */
            const dh_qpos dev = qu->bg.dev;
            const double d = dhsm_dist3(pt, ch->ref[line].pb);
            const double tol = (3.0 + 2.0 * NA + 64.0 * (ch->p[line].length + ch->p[line + 1u].length) / DHSM_Q30) / QPOS;
            DHT_TRUE_MSG(dev <= ch->R[line], "%s: corner %u dev %ld > radius %ld", what, (unsigned)line, (long)dev,
                         (long)ch->R[line]);
            DHT_TRUE_MSG(d <= dev / QPOS + tol, "%s period %ld: %.4g mm from corner %u (dev %.4g)", what, i, d,
                         (unsigned)line, dev / QPOS);
            dht_reach_max("queue_q_blend.corner_frac", d / (dev / QPOS + tol));
            rs->inside++;
        } else {
            const double d = dhsm_ref_dist(&ch->ref[line], pt);
            DHT_TRUE_MSG(d <= PATH_TOL, "%s period %ld: target %.3g mm off line %u", what, i, d, (unsigned)line);
        }
        if (tr.state == DH_TRACK_OK) {
            const double tol = t->pos_tol / QPOS + 4.0 * NJ / QPOS + 1e-6;
            dhr_mat4 F;
            double pq[3];
            dhsm_tool_mm(g, q, pq, &F);
            DHT_TRUE_MSG(dhsm_dist3(pq, pt) <= tol, "%s period %ld: tool %.3g mm from the target", what, i,
                         dhsm_dist3(pq, pt));
        } else {
            rs->notok++;
        }
        if (qu->phase == DH_QUEUE_STOPPED && still >= 0) DHT_TRUE(memcmp(&cmd.T, &Thold, sizeof Thold) == 0);
        Thold = cmd.T;
        if (i % DEC == 0) {
            memcpy(pring[(i / DEC) % RING], cmd.T.p, sizeof pring[0]);
            memcpy(jring[(i / DEC) % RING], q, sizeof jring[0]);
            check_rates(&pring[0][0], 3, 1.0 / QPOS, i, n, NP, V, A, wv, wa, what);
            check_rates(&jring[0][0], NJ, 1.0 / Q16, i, n, NJN / Q16, VJ / Q16, AJ / Q16, wvj, waj, what);
        }
        n++;
        DHT_EQ_INT(dh_queue_advance_q(qu, tr.state, &rep), DH_OK);
        DHT_EQ_INT(rep.seq, line);
        DHT_EQ_INT(rep.held, tr.state != DH_TRACK_OK || (qu->phase == DH_QUEUE_STOPPED && !rep.done && still >= 0));
        if (rep.feed < rs->minfeed) rs->minfeed = rep.feed;
        if (rep.done) {
            DHT_EQ_INT(qu->seq, line + 1u);
            done++;
            if (ov) rs->blended++;
            if (ov && (ch->p[line].kind == DH_PATH_ARC || ch->p[line + 1u].kind == DH_PATH_ARC)) rs->arcs++;
            if (rep.last) {
                DHT_TRUE(memcmp(&cmd.T, &ch->p[ch->n - 1u].B, sizeof cmd.T) == 0);
                DHT_TRUE(tr.state == DH_TRACK_OK);
            }
        }
        /* the stop at the first period inside an overlap */
        if (!stop_done && braking < 0 && in_overlap(qu) && qu->mv.feed > 0) {
            DHT_EQ_INT(dh_queue_stop_q(qu), DH_OK);
            DHT_EQ_INT(qu->phase, DH_QUEUE_BRAKE);
            braking = 0;
            rs->stopped++;
        } else if (braking >= 0 && still < 0) {
            DHT_TRUE_MSG(braking++ < 20000, "%s: the brake does not reach rest", what);
            if (rest < 0 && braking == 3) {
                DHT_EQ_INT(dh_queue_resume_q(qu), DH_OK);
                braking = -1;
                stop_done = 1;
            } else if (rep.stopped) {
                still = 0;
            }
        } else if (still >= 0) {
            DHT_TRUE(rep.stopped);
            if (still++ >= rest) {
                DHT_EQ_INT(dh_queue_resume_q(qu), DH_OK);
                still = -1;
                braking = -1;
                stop_done = 1;
            }
        }
    }
    rs->periods = i;
    DHT_TRUE_MSG(qu->count == 0u && done == ch->n, "%s: %u of %u lines done in %ld periods", what, (unsigned)done,
                 (unsigned)ch->n, i);
}

static const dhs_robot *const robots[] = { &dhs_ur5_mm, &dhs_puma560_mm };

static void blend_queues_q(void)
{
    long total = 0, total_arcs = 0;
    size_t ri;
    for (ri = 0; ri < sizeof robots / sizeof robots[0]; ri++) {
        dhsm_rig rig;
        chain ch;
        dh_queue_item_q items[NL];
        dhsm_rig *const g = &rig;
        long it, n = DHT_ITER(6), periods = 0, blended = 0, arcs = 0, inside = 0, stops = 0;
        dhsm_rig_make(g, robots[ri], 180.0, 720.0);
        for (it = 0; it < n; it++) {
            double qa[DH_MAX_JOINTS];
            int32_t ia[NJ];
            run_stats rs;
            uint32_t k;
            const int stop = (int)(dht_rand_u32() % 2u);
            const long rest = (dht_rand_u32() % 3u == 0u) ? -1 : (long)(dht_rand_u32() % 200u);
            dhsm_region_q(g, qa);
            dhs_q_from_double(&g->r, qa, ia);
            chain_make(g, ia, 2u + dht_rand_u32() % (NL - 1u), it == 0, &ch);
            DHT_EQ_INT(dh_track_init_q(&the_trk, &g->r, &g->m, ia, DT_US), DH_OK);
            DHT_EQ_INT(dh_queue_init_q(&the_qu, items, NL), DH_OK);
            for (k = 0; k < ch.n; k++) DHT_EQ_INT(dh_queue_add_path_blend_q(&the_qu, &ch.p[k], ch.lim, ch.R[k]), DH_OK);
            run_chain(g, &ch, stop, rest, &rs, g->d->name);
            periods += rs.periods;
            blended += rs.blended;
            arcs += rs.arcs;
            inside += rs.inside;
            stops += rs.stopped;
        }
        total += blended;
        total_arcs += arcs;
        dht_reach_min("queue_q_blend.robot_blended", (double)blended);
        dht_reach_min("queue_q_blend.robot_arc_corners", (double)arcs);
        dht_printf("%s: %ld chains, %ld periods, %ld corners passed blended (%ld with an arc; %ld periods inside), "
                   "%ld stops inside\n",
                   g->d->name, n, periods, blended, arcs, inside, stops);
    }
    DHT_TRUE(total > 0 && total_arcs > 0);
}

/* The Puma's line its wrist cannot follow, blended into a line back
 * towards its start (the file's comment) */
static void lagging_blend_q(void)
{
    static const double QP[6] = { 10.0, -30.0, 45.0, 20.0, 35.0, -60.0 };
    dhsm_rig rig;
    chain ch;
    dh_queue_item_q items[2];
    dhsm_rig *const g = &rig;
    double qa[DH_MAX_JOINTS];
    int32_t ia[NJ];
    dh_frame_q A, B, C;
    run_stats rs;
    int k;
    dhsm_rig_make(g, &dhs_puma560_mm, 150.0, 600.0);
    for (k = 0; k < 6; k++) qa[k] = QP[k];
    dhs_q_from_double(&g->r, qa, ia);
    dhsm_target_of(g, ia, &A);
    dh_frame_identity_q(&B);
    B.p[0] = (int32_t)(500.0 * LS * QPOS);
    B.p[1] = (int32_t)(-30.0 * LS * QPOS);
    B.p[2] = (int32_t)(1000.0 * LS * QPOS);
    C = B;
    C.p[2] -= (int32_t)(150.0 * LS * QPOS);
    ch.n = 2u;
    ch.lim = &PLIM;
    DHT_EQ_INT(dh_path_line_q(&ch.p[0], &A, &B), DH_OK);
    DHT_EQ_INT(dh_path_line_q(&ch.p[1], &B, &C), DH_OK);
    dhsm_ref_make(&ch.ref[0], &ch.p[0], NULL);
    dhsm_ref_make(&ch.ref[1], &ch.p[1], NULL);
    ch.R[0] = (dh_qpos)(20.0 * LS * QPOS);
    ch.R[1] = 0;
    DHT_EQ_INT(dh_track_init_q(&the_trk, &g->r, &g->m, ia, DT_US), DH_OK);
    DHT_EQ_INT(dh_queue_init_q(&the_qu, items, 2u), DH_OK);
    for (k = 0; k < 2; k++) DHT_EQ_INT(dh_queue_add_path_blend_q(&the_qu, &ch.p[k], ch.lim, ch.R[k]), DH_OK);
    DHT_TRUE(items[0].seg.dur[4] > 0u);
    run_chain(g, &ch, 0, 0, &rs, "Puma lagging blend");
    DHT_TRUE_MSG(rs.notok > 0, "the Puma blend: no lagging period");
    DHT_TRUE(rs.minfeed < DH_Q30_ONE && rs.blended == 1);
    dht_reach_max("queue_q_blend.puma_notok", (double)rs.notok);
    dht_printf("Puma lagging blend: %ld periods, %ld not OK, least feed %.3f\n", rs.periods, rs.notok,
               rs.minfeed / DHSM_Q30);
}

static void blend_q_errors(void)
{
    dh_queue_q *const qu = &the_qu;
    dh_queue_item_q the_items[4];
    dh_frame_q A, B, C;
    dh_path_q p[3], arc;
    dh_cart_limits_q lim = LIM;
    const dh_qpos R = (dh_qpos)(10.0 * LS * QPOS);
    dh_qpos via[3];
    dh_frame_identity_q(&A);
    A.p[0] = (int32_t)(300.0 * LS * QPOS);
    A.p[2] = (int32_t)(400.0 * LS * QPOS);
    B = A;
    B.p[0] += (int32_t)(100.0 * LS * QPOS);
    C = B;
    C.p[1] += (int32_t)(100.0 * LS * QPOS);
    DHT_EQ_INT(dh_path_line_q(&p[0], &A, &B), DH_OK);
    DHT_EQ_INT(dh_path_line_q(&p[1], &B, &C), DH_OK);
    DHT_EQ_INT(dh_path_line_q(&p[2], &C, &A), DH_OK);
    memcpy(via, B.p, sizeof via);
    via[2] += (int32_t)(30.0 * LS * QPOS);
    DHT_EQ_INT(dh_path_arc_q(&arc, &A, via, &C), DH_OK);
    /* bad arguments, checked after a full queue; nothing appended */
    DHT_EQ_INT(dh_queue_init_q(qu, the_items, 1u), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_blend_q(qu, &p[0], &LIM, -1), DH_ERR_ARG);
    lim.wmax = 0;
    DHT_EQ_INT(dh_queue_add_path_blend_q(qu, &p[0], &lim, R), DH_ERR_ARG);
    lim = LIM;
    {
        dh_path_q bad;
        memset(&bad, 0, sizeof bad);
        DHT_EQ_INT(dh_queue_add_path_blend_q(qu, &bad, &LIM, R), DH_ERR_ARG);
        bad = p[0];
        bad.length = -1;
        DHT_EQ_INT(dh_queue_add_path_blend_q(qu, &bad, &LIM, R), DH_ERR_ARG);
    }
    DHT_EQ_INT(qu->count, 0u);
    DHT_EQ_INT(dh_queue_add_path_blend_q(qu, &p[0], &LIM, R), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_blend_q(qu, &p[1], &LIM, R), DH_ERR_LIMIT);
    DHT_EQ_INT(dh_queue_add_path_blend_q(qu, &p[1], &LIM, -1), DH_ERR_LIMIT);
    /* a phase of 2^28 us or more (a line of 100 mm at 1 LSB/s) */
    DHT_EQ_INT(dh_queue_init_q(qu, the_items, 4u), DH_OK);
    lim.vmax = 1;
    DHT_EQ_INT(dh_queue_add_path_blend_q(qu, &p[0], &lim, R), DH_ERR_OVERFLOW);
    DHT_EQ_INT(qu->count, 0u);
    lim = LIM;
    /* blended corners: two lines with a radius */
    DHT_EQ_INT(dh_queue_add_path_blend_q(qu, &p[0], &LIM, R), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_blend_q(qu, &p[1], &LIM, R), DH_OK);
    DHT_TRUE(the_items[0].seg.dur[4] > 0u && the_items[0].seg.dur[4] == the_items[1].seg.dur[0]);
    DHT_TRUE(the_items[0].seg.dev > 0 && the_items[0].seg.dev <= R);
    /* at rest: other limits, radius 0, after an arc appended by
     * dh_queue_add_path_q */
    lim.vmax = LIM.vmax / 2;
    DHT_EQ_INT(dh_queue_add_path_blend_q(qu, &p[2], &lim, R), DH_OK);
    DHT_EQ_INT(the_items[1].seg.dur[4], 0u);
    DHT_EQ_INT(dh_queue_init_q(qu, the_items, 4u), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_blend_q(qu, &p[0], &LIM, 0), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_blend_q(qu, &p[1], &LIM, R), DH_OK);
    DHT_EQ_INT(the_items[0].seg.dur[4], 0u);
    DHT_EQ_INT(dh_queue_add_path_q(qu, &arc, &LIM), DH_OK);
    DHT_TRUE(the_items[2].blend == 0u && the_items[1].seg.dur[4] == 0u);
    DHT_EQ_INT(dh_queue_add_path_blend_q(qu, &p[1], &LIM, R), DH_OK);
    DHT_EQ_INT(the_items[3].seg.dur[0], 0u);
    /* an arc into a line and a line into an arc, blended; an arc whose
     * radius is not positive holds no arc */
    DHT_EQ_INT(dh_queue_init_q(qu, the_items, 4u), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_blend_q(qu, &arc, &LIM, R), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_blend_q(qu, &p[2], &LIM, R), DH_OK);
    DHT_TRUE(the_items[0].seg.dur[4] > 0u && the_items[0].seg.dur[4] == the_items[1].seg.dur[0]);
    DHT_TRUE(the_items[0].seg.dev > 0 && the_items[0].seg.dev <= R);
    {
        dh_path_q back, bad = arc;
        dh_qpos v2[3];
        memcpy(v2, via, sizeof v2);
        v2[1] = via[1] + (int32_t)(50.0 * LS * QPOS);
        DHT_EQ_INT(dh_path_arc_q(&back, &A, v2, &C), DH_OK);
        bad.radius = 0;
        DHT_EQ_INT(dh_queue_add_path_blend_q(qu, &bad, &LIM, R), DH_ERR_ARG);
        DHT_EQ_INT(dh_queue_init_q(qu, the_items, 4u), DH_OK);
        DHT_EQ_INT(dh_queue_add_path_blend_q(qu, &p[2], &LIM, R), DH_OK);
        DHT_EQ_INT(dh_queue_add_path_blend_q(qu, &back, &LIM, R), DH_OK);
        DHT_TRUE(the_items[0].seg.dur[4] > 0u && the_items[0].seg.dev <= R);
    }
    /* not starting at the last one's end: at rest */
    DHT_EQ_INT(dh_queue_init_q(qu, the_items, 4u), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_blend_q(qu, &p[0], &LIM, R), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_blend_q(qu, &p[2], &LIM, R), DH_OK);
    DHT_EQ_INT(the_items[0].seg.dur[4], 0u);
}

static const dht_case cases[] = {
    DHT_CASE(blend_queues_q),
    DHT_CASE(lagging_blend_q),
    DHT_CASE(blend_q_errors),
};
DHT_MAIN(cases)
