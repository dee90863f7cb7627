/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_queue_blend_jerk.c - jerk-limited blended corners in the move
 * queue (dh_queue_add_path_blend_jerk_f32), run through the tracker as
 * `dhmath move --blend --jerk` runs them, at 1 kHz, seeded random queues
 * on the Puma 560, UR5 (closed forms) and Panda (numerical tracker).
 *
 * Queues of 2 to 6 lines joining the FK frames of configurations a few
 * degrees apart (so the tool also turns), each with a random radius (0
 * in a fifth of them; up to 5 cm), random Cartesian and jerk limits, in
 * a queue of three items: up to three lines queued at the start (in a
 * third of the queues fewer), the others appended as moves complete.
 * Every period's target is checked against double references written
 * here:
 * - outside an overlap (the queue's bmode is not 2) on its line within
 *   1e-6 m, inside one within the corner's radius of the corner (plus 8
 *   FLT_EPSILON of the positions' scale);
 * - speed, TOTAL acceleration, angular speed and acceleration by finite
 *   differences within the limits times 1 + 1e-3 over windows of WS = 10
 *   periods every period and of W = 125 periods every WD = 25 (plus the
 *   rounding), from the start to the end, feed override changes, stops
 *   and resumes included;
 * - TOTAL jerk and angular jerk by third differences over W periods
 *   within jmax and wjmax times 1 + 1e-3 (plus the rounding: 8 samples)
 *   over every window whose periods had the tracker OK and the feed
 *   override unchanged (the contract's condition), stops included;
 * - each period's step within one period at the speed limits.
 * In half the queues the tracker's state is replaced by LAGGING for a
 * random stretch starting inside an overlap, in the other half at a
 * random period (the feed override falls and rises; it holds inside an
 * overlap). In a third, a stop comes inside an overlap: it waits, the
 * overlap runs to its end, then the next line alone brakes (qu.stopq,
 * the phase); in a third a stop comes at a random period; resumed some
 * periods after rest. A first corner planned blended with its next
 * line queued at the start runs blended when nothing stops the queue.
 * Moves complete in order, the last target is the last line's B bit for
 * bit.
 *
 * Statuses of dh_queue_add_path_blend_jerk_f32: a full queue, a NaN and a
 * negative radius, an arc, a NaN and a zero jerk limit, each with the
 * queue untouched.
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
#define NMAX 6              /* lines of a queue */
#define CAP 3               /* the queue's items */
#define WS 10               /* the short window (periods), every period */
#define WD 25               /* the long window's sampling (periods) */
#define W (5 * WD)          /* the long window (periods) */
#define NS (2 * WS + 1)     /* samples kept, every period */
#define NL (3 * W / WD + 1) /* samples kept, every WD periods */
#define MAXCALL 400000L

/* static: the micro:bit's RAM holds them beside the rig on the stack */
static dh_queue_f32 qu;
static dh_queue_item_f32 items[CAP];
static float cp[NMAX + 1][3];             /* the corners' positions (line k: cp[k] to cp[k + 1]) */
static float radius[NMAX];
static float sp[NS][7], lp[NL][7]; /* position and unit quaternion of the target m periods (m WD periods) ago */
static long last_bad;              /* the last period with a lag or a change of r */
static double jerk_worst[2];       /* largest third-difference ratios seen (linear, angular) */
static long jerk_windows;

/* every target's finite differences within lim and jk (the file's
 * comment) */
static void check_fd(dhm_fd *fd, const dh_mat4_f32 *T, const dh_cart_limits_f32 *lim, const dh_cart_jerk_f32 *jk,
                     double S, long call)
{
    const double ulp = S * FLT_EPSILON;
    if (!dhm_fd_push(fd, T, lim, ulp, call)) return;
    if (fd->nh >= (long)(NL - 1) * WD + 1 && last_bad < call - 3L * W - 1L) {
        dhm_check_jerk((const float (*)[7])lp, W / WD, (double)W * DT, jk, ulp, call, jerk_worst);
        jerk_windows++;
    }
}

/* the target on its line outside an overlap, within the corner's radius
 * inside one; 1 when inside */
static int check_path(const dh_mat4_f32 *T, uint32_t n, double S, long call)
{
    uint32_t k;
    double x[3], d;
    if (dhm_check_corner(&qu, T, n, (const float (*)[3])cp, radius, S, call, &k, x)) return 1;
    d = dhm_seg_dist(cp[k], cp[k + 1u], x);
    DHT_TRUE_MSG(d <= 1e-6, "call %ld: %.9g off line %u", call, d, (unsigned)k);
    return 0;
}

/* the frame of corner k (FK of its configuration) */
static void corner(const dhm_rig *g, const float (*qc)[DH_MAX_JOINTS], uint32_t k, dh_mat4_f32 *T)
{
    double q[DH_MAX_JOINTS];
    uint32_t i;
    for (i = 0; i < g->r.n; i++) q[i] = qc[k][i];
    dhs_target_f32(&g->r, q, T);
}

/* line k appended with its radius (qc: the corners' configurations) */
static void append(const dhm_rig *g, const float (*qc)[DH_MAX_JOINTS], uint32_t k, const dh_cart_limits_f32 *lim,
                   const dh_cart_jerk_f32 *jk)
{
    dh_path_f32 line;
    dh_mat4_f32 A, B;
    corner(g, qc, k, &A);
    corner(g, qc, k + 1u, &B);
    DHT_EQ_INT(dh_path_line_f32(&line, &A, &B), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_blend_jerk_f32(&qu, &line, lim, jk, radius[k]), DH_OK);
    DHT_EQ_INT(items[(qu.head + qu.count - 1u) % CAP].jerk, 2);
}

/* the corners' configurations qc a few degrees apart from qa, their
 * positions, the radii; S the largest |coordinate| (at least 1) */
static void draw_lines(const dhm_rig *g, const double *qa, uint32_t n, double step, float (*qc)[DH_MAX_JOINTS],
                       double *S)
{
    dh_mat4_f32 T;
    uint32_t k, i;
    *S = 1.0;
    for (i = 0; i < g->r.n; i++) qc[0][i] = (float)qa[i];
    for (k = 0; k <= n; k++) {
        if (k > 0) dhm_draw_q(&g->r, qc[k - 1u], step, qc[k]);
        corner(g, (const float (*)[DH_MAX_JOINTS])qc, k, &T);
        for (i = 0; i < 3u; i++) {
            cp[k][i] = T.m[3][i];
            *S = fmax(*S, fabs((double)cp[k][i]));
        }
        if (k < n) radius[k] = (dht_rand_u32() % 5u == 0u) ? 0.0f : (float)dht_rand_uniform(1e-3, 0.05);
    }
}

/* one random queue on the rig's robot from about q_nom (the file's
 * comment); ov[0] counts the periods in overlaps, ov[1] the stops there */
static void blend_jerk_queue(dhm_rig *g, const double *q_nom, long ov[2])
{
    dh_cart_limits_f32 lim;
    dh_cart_jerk_f32 jk;
    dhm_fd fd = { sp, lp, NS, NL, WS, WD, W, (double)DT, 0 };
    double qa[DH_MAX_JOINTS], S;
    float q0[DH_MAX_JOINTS], feed = 1.0f;
    dh_queue_cmd_f32 cmd;
    dh_queue_report_f32 rep;
    dh_track_report_f32 trep;
    const uint32_t n = 2u + dht_rand_u32() % (NMAX - 1u);
    const uint32_t n0 = (dht_rand_u32() % 3u == 0u) ? 1u + dht_rand_u32() % n : n;
    const int stop_mode = (int)(dht_rand_u32() % 3u), lag_in = (int)(dht_rand_u32() % 2u);
    const long stop_at = (long)(dht_rand_u32() % 3000u), ov0 = ov[0];
    const long lag_len = 1 + (long)(dht_rand_u32() % 300u), lag_at = (long)(dht_rand_u32() % 3000u);
    const long resume_wait = (long)(dht_rand_u32() % 3u) * (long)(dht_rand_u32() % 200u);
    long call, lag_from = -1, stop_call = -1, stopped_at = -1;
    uint32_t i, added, done = 0, ov_stop = 0xffffffffu;
    int resumed = 0, in_ov, planned;
    float qc[NMAX + 1][DH_MAX_JOINTS]; /* the corners' configurations (on the stack: the micro:bit's RAM) */
    const float (*qcc)[DH_MAX_JOINTS] = (const float (*)[DH_MAX_JOINTS])qc;
    for (i = 0; i < g->r.n; i++) qa[i] = q_nom[i] + dht_rand_uniform(-5.0, 5.0);
    draw_lines(g, qa, n, 8.0, qc, &S);
    dhm_draw_limits(&lim, &jk);
    for (i = 0; i < g->r.n; i++) q0[i] = qc[0][i];
    DHT_EQ_INT(dh_track_init_f32(&g->t, &g->r, g->closed ? &g->m : NULL, q0, DT), DH_OK);
    DHT_EQ_INT(dh_queue_init_f32(&qu, items, CAP), DH_OK);
    for (added = 0; added < n0 && added < CAP; added++) append(g, qcc, added, &lim, &jk);
    planned = added >= 2u && items[0].ctb > 0.0f;
    last_bad = -1;
    for (call = 0; call < MAXCALL && done < n; call++) {
        dh_track_state st;
        DHT_EQ_INT(dh_queue_target_f32(&qu, &g->t, DT, &cmd), DH_OK);
        DHT_EQ_INT(cmd.kind, DH_MOVE_PATH);
        in_ov = check_path(&cmd.T, n, S, call);
        ov[0] += in_ov;
        check_fd(&fd, &cmd.T, &lim, &jk, S, call);
        DHT_EQ_INT(dh_track_step_f32(&g->t, &cmd.T, g->t.q, &trep), DH_OK);
        st = trep.state;
        if (lag_from < 0 && stop_call < 0 && ((lag_in && in_ov) || (!lag_in && call == lag_at))) lag_from = call;
        if (lag_from >= 0 && call - lag_from < lag_len && qu.phase == (uint32_t)DH_QUEUE_RUN) st = DH_TRACK_LAGGING;
        DHT_EQ_INT(dh_queue_advance_f32(&qu, st, &rep), DH_OK);
        DHT_TRUE(rep.feed >= 0.0f && rep.feed <= 1.0f);
        if (st != DH_TRACK_OK || rep.feed != feed) last_bad = call;
        feed = rep.feed;
        if (rep.stopped && stopped_at < 0 && stop_call >= 0) stopped_at = call;
        if (stop_call >= 0 && !resumed && stopped_at >= 0 && call - stopped_at >= resume_wait) {
            resumed = 1;
            DHT_EQ_INT(dh_queue_resume_f32(&qu), DH_OK);
        }
        if (rep.done) {
            done++;
            DHT_EQ_INT(rep.last, done == added);
            if (added < n) append(g, qcc, added++, &lim, &jk);
        }
        /* the stop inside an overlap (the head line's tail and the next's), or at stop_at */
        if (stop_call < 0 && qu.phase == (uint32_t)DH_QUEUE_RUN && done < n &&
            ((stop_mode == 1 && qu.bmode == 2u && qu.bl[1].T > 0.0f && dht_rand_u32() % 8u == 0u) ||
             (stop_mode == 2 && call == stop_at))) {
            stop_call = call;
            if (stop_mode == 1) ov[1]++;
            DHT_EQ_INT(dh_queue_stop_f32(&qu), DH_OK);
            /* inside an overlap it waits for the overlap's end */
            if (stop_mode == 1) {
                DHT_EQ_INT(qu.phase, DH_QUEUE_RUN);
                DHT_EQ_INT(qu.stopq, 1);
                ov_stop = qu.seq;
            }
        }
        /* the deferred stop brakes the next line alone, from the overlap's end on */
        if (ov_stop != 0xffffffffu && qu.stopq == 0u) {
            DHT_TRUE(qu.seq == ov_stop + 1u && qu.bmode != 2u && qu.phase != (uint32_t)DH_QUEUE_RUN);
            ov_stop = 0xffffffffu;
        }
        if (ov_stop != 0xffffffffu) DHT_TRUE(qu.bmode == 2u && qu.phase == (uint32_t)DH_QUEUE_RUN);
    }
    DHT_TRUE_MSG(done == n, "%u of %u moves done in %ld periods", (unsigned)done, (unsigned)n, call);
    {
        dh_mat4_f32 B;
        corner(g, qcc, n, &B);
        DHT_TRUE(memcmp(&cmd.T, &B, sizeof cmd.T) == 0);
    }
    if (stop_call >= 0) DHT_TRUE(resumed);
    if (stop_mode == 0 && planned) DHT_TRUE(ov[0] > ov0);
}

static void run_robot(const dhm_robot_case *c)
{
    long it, nq = DHT_ITER(8), ov[2] = { 0, 0 };
    dhm_rig g;
    dhm_rig_make(&g, c);
    jerk_worst[0] = 0.0;
    jerk_worst[1] = 0.0;
    jerk_windows = 0;
    for (it = 0; it < nq; it++) blend_jerk_queue(&g, c->q, ov);
    DHT_TRUE(jerk_windows > 0);
    dht_printf("%s: %ld queues, %ld periods in overlaps, %ld stops there, %ld jerk windows, worst jerk %ld, angular "
               "%ld ppm of the limits\n",
               c->d->name, nq, ov[0], ov[1], jerk_windows, (long)(jerk_worst[0] * 1e6), (long)(jerk_worst[1] * 1e6));
}

static void queues_puma(void) { run_robot(&dhm_puma560); }
static void queues_ur5(void) { run_robot(&dhm_ur5); }
static void queues_panda(void) { run_robot(&dhm_panda); }

/* the queue's hash and its items' */
static uint64_t queue_hash(void)
{
    return dhm_hash(&qu, sizeof qu, items, sizeof items[0]);
}

/* the statuses; the queue untouched */
static void blend_jerk_bad(void)
{
    static const dh_cart_limits_f32 lim = { 0.1f, 1.0f, 30.0f, 300.0f };
    dh_cart_jerk_f32 jk = { 10.0f, 3000.0f };
    dh_path_f32 line, arc;
    uint64_t keep;
    dhm_line_arc(&line, &arc);
    DHT_EQ_INT(dh_queue_init_f32(&qu, items, 1), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_blend_jerk_f32(&qu, &line, &lim, &jk, NAN), DH_ERR_NAN);
    DHT_EQ_INT(dh_queue_add_path_blend_jerk_f32(&qu, &line, &lim, &jk, -1e-3f), DH_ERR_ARG);
    DHT_EQ_INT(dh_queue_add_path_blend_jerk_f32(&qu, &arc, &lim, &jk, 1e-3f), DH_ERR_ARG);
    jk.jmax = NAN;
    DHT_EQ_INT(dh_queue_add_path_blend_jerk_f32(&qu, &line, &lim, &jk, 1e-3f), DH_ERR_NAN);
    jk.jmax = 0.0f;
    DHT_EQ_INT(dh_queue_add_path_blend_jerk_f32(&qu, &line, &lim, &jk, 1e-3f), DH_ERR_ARG);
    DHT_EQ_INT(qu.count, 0);
    jk.jmax = 10.0f;
    DHT_EQ_INT(dh_queue_add_path_blend_jerk_f32(&qu, &line, &lim, &jk, 1e-3f), DH_OK);
    DHT_TRUE(items[0].radius == 1e-3f && items[0].jerk == 2u && items[0].seg.T > 0.0f);
    keep = queue_hash();
    DHT_EQ_INT(dh_queue_add_path_blend_jerk_f32(&qu, &line, &lim, &jk, 1e-3f), DH_ERR_LIMIT);
    DHT_TRUE(queue_hash() == keep);
}

static const dht_case cases[] = {
    DHT_CASE(blend_jerk_bad),
    DHT_CASE(queues_ur5),
    DHT_CASE(queues_puma),
    DHT_CASE(queues_panda),
};

DHT_MAIN(cases)
