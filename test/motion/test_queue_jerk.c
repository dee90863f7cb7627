/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_queue_jerk.c - jerk-limited path moves in the move queue
 * (dh_queue_add_path_jerk_f32), run through the tracker at 1 kHz, seeded
 * random queues on the Puma 560, UR5 (closed forms) and Panda (numerical
 * tracker).
 *
 * Queues of 2 to 5 segments, each a line or (in half of them) an arc
 * through a via point off its chord by 0.1 to 0.4 of it, joining the FK
 * frames of configurations a few degrees apart (so the tool also turns),
 * random Cartesian and jerk limits, in a queue of three items (the rest
 * appended as moves complete; every corner at rest). Every period's
 * target is checked against double references written here:
 * - on its segment within 1e-6 m (the distance from the segment, or from
 *   the arc's circle within its sweep), braking included;
 * - speed, TOTAL acceleration, angular speed and acceleration by finite
 *   differences within the limits times 1 + 1e-3 over windows of WS = 10
 *   periods every period and of W = 50 periods every WD = 25 (plus the
 *   rounding of 8 ulp of the positions' scale and 1e-4 degrees per
 *   sample), from the start to the end, feed override changes, stops and
 *   resumes included;
 * - TOTAL jerk and angular jerk by third differences over W = 50 periods
 *   within jmax and wjmax times 1 + 1e-3 (plus the rounding: 8 samples),
 *   over every window whose periods had the tracker OK and the feed
 *   override unchanged (the contract's condition);
 * - each period's step within one period at the speed limits.
 * In half the queues the tracker's state is replaced by LAGGING for a
 * random stretch at a random period while running (the feed override
 * falls and rises); in two thirds a stop comes at a random period (twice,
 * the second changing nothing), resumed at once, while braking or some
 * periods after rest: rest comes within v / A + 3 A / j of OK periods
 * (motion.h, dh_queue_stop_f32; v, A, j the plan's peaks of s). Moves
 * complete in order, the last target is the last segment's B bit for bit.
 *
 * Statuses of dh_queue_add_path_jerk_f32: NaN/Inf and <= 0 jerk limits, a
 * full queue (before a bad limit), each with the queue and its queued moves
 * untouched; NULL jerk queues the item of
 * dh_queue_add_path_f32 bit for bit; a blended move before a jerk-limited
 * one keeps its corner at rest.
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
#define NMAX 5              /* segments of a queue */
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
static float sp[NS][7], lp[NL][7];        /* position and unit quaternion of the target m periods (m WD periods) ago */
static long last_bad;                     /* the last period with a lag or a change of r */
static double jerk_worst[2];              /* largest third-difference ratios seen (linear, angular) */
static long jerk_windows;

/* every target's finite differences within lim and jk (the file's
 * comment) */
static void check_fd(dhm_fd *fd, const dh_mat4_f32 *T, const dh_cart_limits_f32 *lim, const dh_cart_jerk_f32 *jk, double S,
                     long call)
{
    const double ulp = S * FLT_EPSILON;
    if (!dhm_fd_push(fd, T, lim, ulp, call)) return;
    /* the jerk over windows of OK periods at a constant r */
    if (fd->nh >= (long)(NL - 1) * WD + 1 && last_bad < call - 3L * W - 1L) {
        dhm_check_jerk((const float (*)[7])lp, W / WD, (double)W * DT, jk, ulp, call, jerk_worst);
        jerk_windows++;
    }
}

/* the target on the running move's segment (the queue's head item)
 * within 1e-6 m */
static void check_path(const dh_mat4_f32 *T, long call)
{
    const dh_path_f32 *p = &items[qu.head].path;
    double x[3], d;
    int i;
    DHT_TRUE(qu.count > 0u);
    for (i = 0; i < 3; i++) x[i] = T->m[3][i];
    if (p->kind == (uint32_t)DH_PATH_ARC)
        d = dhm_arc_dist(p, x);
    else
        d = dhm_seg_dist(&p->A.m[3][0], &p->B.m[3][0], x);
    DHT_TRUE_MSG(d <= 1e-6, "call %ld: %.9g off segment %u", call, d, (unsigned)qu.seq);
}

/* the frame of corner k (FK of its configuration) */
static void corner(const dhm_rig *g, const float (*qc)[DH_MAX_JOINTS], uint32_t k, dh_mat4_f32 *T)
{
    double q[DH_MAX_JOINTS];
    uint32_t i;
    for (i = 0; i < g->r.n; i++) q[i] = qc[k][i];
    dhs_target_f32(&g->r, q, T);
}

/* segment k (a line, or an arc: dhm_draw_via) appended */
static void append(const dhm_rig *g, const float (*qc)[DH_MAX_JOINTS], uint32_t k, const dh_cart_limits_f32 *lim, const dh_cart_jerk_f32 *jk)
{
    dh_path_f32 seg;
    dh_mat4_f32 A, B;
    float via[3];
    corner(g, qc, k, &A);
    corner(g, qc, k + 1u, &B);
    if (dhm_draw_via(&A.m[3][0], &B.m[3][0], via))
        DHT_EQ_INT(dh_path_arc_f32(&seg, &A, via, &B), DH_OK);
    else
        DHT_EQ_INT(dh_path_line_f32(&seg, &A, &B), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_jerk_f32(&qu, &seg, lim, jk), DH_OK);
}

/* the corners' configurations a few degrees apart from qa; S the
 * largest |coordinate| of their positions (at least 1) */
static void draw_corners(const dhm_rig *g, const double *qa, uint32_t n, double step, float (*qc)[DH_MAX_JOINTS], double *S)
{
    dh_mat4_f32 T;
    uint32_t k, i;
    for (i = 0; i < g->r.n; i++) qc[0][i] = (float)qa[i];
    for (k = 1; k <= n; k++) dhm_draw_q(&g->r, qc[k - 1u], step, qc[k]);
    *S = 1.0;
    for (k = 0; k <= n; k++) {
        corner(g, (const float (*)[DH_MAX_JOINTS])qc, k, &T);
        for (i = 0; i < 3u; i++) *S = fmax(*S, fabs((double)T.m[3][i]));
    }
}

/* the stop at call: braking, a second stop changes nothing; the bound of
 * its duration (v / A + 3 A / j of the head's plan of s) into *tmax */
static void stop_now(double *tmax)
{
    const dh_profile_f32 *pr = &items[qu.head].prof;
    const uint32_t ph0 = qu.phase;
    DHT_EQ_INT(dh_queue_stop_f32(&qu), DH_OK);
    DHT_TRUE(ph0 == (uint32_t)DH_QUEUE_RUN);
    *tmax = (pr->a > 0.0f && pr->j > 0.0f) ? (double)pr->v / pr->a + 3.0 * (double)pr->a / pr->j : 0.0;
    if (qu.phase == (uint32_t)DH_QUEUE_BRAKE) {
        DHT_EQ_INT(dh_queue_stop_f32(&qu), DH_OK);
        DHT_EQ_INT(qu.phase, DH_QUEUE_BRAKE);
    } else {
        DHT_EQ_INT(qu.phase, DH_QUEUE_STOPPED);
    }
}

/* one random queue on the rig's robot from about q_nom (the file's
 * comment); *nstop counts the stops that braked */
static void jerk_queue(dhm_rig *g, const double *q_nom, long *nstop)
{
    dh_cart_limits_f32 lim;
    dh_cart_jerk_f32 jk;
    double qa[DH_MAX_JOINTS], S = 1.0, tmax = 0.0;
    dhm_fd fd = { sp, lp, NS, NL, WS, WD, W, (double)DT, 0 };
    float q0[DH_MAX_JOINTS];
    dh_queue_cmd_f32 cmd;
    dh_queue_report_f32 rep;
    dh_track_report_f32 trep;
    const uint32_t n = 2u + dht_rand_u32() % (NMAX - 1u);
    const int stop_mode = (int)(dht_rand_u32() % 3u), lag_on = (int)(dht_rand_u32() % 2u);
    const long stop_at = (long)(dht_rand_u32() % 3000u), lag_at = (long)(dht_rand_u32() % 3000u);
    const long lag_len = 1 + (long)(dht_rand_u32() % 300u);
    const long resume_wait = (long)(dht_rand_u32() % 3u) * (long)(dht_rand_u32() % 200u);
    long call, stop_call = -1, rest_ok = 0, stopped_at = -1;
    uint32_t i, added, done = 0;
    float feed = 1.0f;
    int resumed = 0;
    float qc[NMAX + 1][DH_MAX_JOINTS]; /* the corners' configurations (on the stack: the micro:bit's RAM) */
    const float (*qcc)[DH_MAX_JOINTS] = (const float (*)[DH_MAX_JOINTS])qc;
    for (i = 0; i < g->r.n; i++) qa[i] = q_nom[i] + dht_rand_uniform(-5.0, 5.0);
    draw_corners(g, qa, n, 8.0, qc, &S);
    dhm_draw_limits(&lim, &jk);
    for (i = 0; i < g->r.n; i++) q0[i] = qc[0][i];
    DHT_EQ_INT(dh_track_init_f32(&g->t, &g->r, g->closed ? &g->m : NULL, q0, DT), DH_OK);
    DHT_EQ_INT(dh_queue_init_f32(&qu, items, CAP), DH_OK);
    for (added = 0; added < n && added < CAP; added++)
        append(g, qcc, added, &lim, &jk);
    last_bad = -1;
    for (call = 0; call < MAXCALL && done < n; call++) {
        dh_track_state st;
        DHT_EQ_INT(dh_queue_target_f32(&qu, &g->t, DT, &cmd), DH_OK);
        DHT_EQ_INT(cmd.kind, DH_MOVE_PATH);
        check_path(&cmd.T, call);
        check_fd(&fd, &cmd.T, &lim, &jk, S, call);
        DHT_EQ_INT(dh_track_step_f32(&g->t, &cmd.T, g->t.q, &trep), DH_OK);
        st = trep.state;
        if (lag_on && call >= lag_at && call - lag_at < lag_len && qu.phase == (uint32_t)DH_QUEUE_RUN)
            st = DH_TRACK_LAGGING;
        DHT_EQ_INT(dh_queue_advance_f32(&qu, st, &rep), DH_OK);
        DHT_TRUE(rep.feed >= 0.0f && rep.feed <= 1.0f);
        if (st != DH_TRACK_OK || rep.feed != feed) last_bad = call;
        feed = rep.feed;
        if (stop_call >= 0 && stopped_at < 0 && st == DH_TRACK_OK) rest_ok++;
        if (rep.stopped && stopped_at < 0 && stop_call >= 0) {
            stopped_at = call;
            DHT_TRUE_MSG((double)(rest_ok - 1) * DT <= tmax + 2.0 * DT, "rest after %ld OK periods, bound %.9g s",
                         rest_ok, tmax);
        }
        if (stop_call >= 0 && !resumed && (stop_mode == 1 || (stopped_at >= 0 && call - stopped_at >= resume_wait))) {
            resumed = 1;
            DHT_EQ_INT(dh_queue_resume_f32(&qu), DH_OK);
        }
        if (rep.done) {
            done++;
            DHT_EQ_INT(rep.last, done == added);
            if (added < n) append(g, qcc, added++, &lim, &jk);
        }
        if (stop_call < 0 && stop_mode != 0 && call == stop_at && done < n) {
            stop_call = call;
            stop_now(&tmax);
            if (qu.phase == (uint32_t)DH_QUEUE_BRAKE) (*nstop)++;
        }
    }
    DHT_TRUE_MSG(done == n, "%u of %u moves done in %ld periods", (unsigned)done, (unsigned)n, call);
    {
        dh_mat4_f32 B;
        corner(g, qcc, n, &B);
        DHT_TRUE(memcmp(&cmd.T, &B, sizeof cmd.T) == 0);
    }
    if (stop_call >= 0) DHT_TRUE(resumed);
}

static void run_robot(const dhm_robot_case *c)
{
    long it, nq = DHT_ITER(8), nstop = 0;
    dhm_rig g;
    dhm_rig_make(&g, c);
    jerk_worst[0] = 0.0;
    jerk_worst[1] = 0.0;
    jerk_windows = 0;
    for (it = 0; it < nq; it++) jerk_queue(&g, c->q, &nstop);
    DHT_TRUE(jerk_windows > 0);
    /* integers: a double's printf needs more heap than the micro:bit's */
    dht_printf("%s: %ld queues, %ld stops braked, %ld jerk windows, worst jerk %ld, angular %ld ppm of the limits\n",
               c->d->name, nq, nstop, jerk_windows, (long)(jerk_worst[0] * 1e6), (long)(jerk_worst[1] * 1e6));
}

static void queues_puma(void) { run_robot(&dhm_puma560); }
static void queues_ur5(void) { run_robot(&dhm_ur5); }
static void queues_panda(void) { run_robot(&dhm_panda); }

/* the queue's hash and its queued items' (the first count: jerk_bad
 * queues from items[0]) */
static uint64_t queue_hash(void)
{
    return dhm_hash(&qu, sizeof qu, items, qu.count * sizeof items[0]);
}

/* the statuses (the file's comment) */
static void jerk_bad(void)
{
    static const dh_cart_limits_f32 lim = { 0.1f, 1.0f, 30.0f, 300.0f };
    static const float bad[5] = { NAN, INFINITY, -INFINITY, 0.0f, -1.0f };
    dh_cart_jerk_f32 jk;
    dh_path_f32 seg;
    dh_mat4_f32 A, B;
    dh_queue_item_f32 it0;
    uint64_t keep;
    int i, w;
    memset(&A, 0, sizeof A);
    A.m[0][0] = A.m[1][1] = A.m[2][2] = A.m[3][3] = 1.0f;
    B = A;
    A.m[3][0] = 0.2f;
    B.m[3][0] = 0.4f;
    B.m[3][1] = 0.2f;
    DHT_EQ_INT(dh_path_line_f32(&seg, &A, &B), DH_OK);
    memset(items, 0, sizeof items);
    DHT_EQ_INT(dh_queue_init_f32(&qu, items, 2), DH_OK);
    keep = queue_hash();
    for (w = 0; w < 2; w++)
        for (i = 0; i < 5; i++) {
            jk.jmax = 10.0f;
            jk.wjmax = 1000.0f;
            if (w == 0)
                jk.jmax = bad[i];
            else
                jk.wjmax = bad[i];
            DHT_EQ_INT(dh_queue_add_path_jerk_f32(&qu, &seg, &lim, &jk), (i < 3) ? DH_ERR_NAN : DH_ERR_ARG);
            DHT_TRUE(queue_hash() == keep);
        }
    /* NULL: dh_queue_add_path_f32's item bit for bit */
    DHT_EQ_INT(dh_queue_add_path_f32(&qu, &seg, &lim), DH_OK);
    it0 = items[0];
    DHT_EQ_INT(dh_queue_init_f32(&qu, items, 2), DH_OK);
    memset(items, 0, sizeof items);
    DHT_EQ_INT(dh_queue_add_path_jerk_f32(&qu, &seg, &lim, NULL), DH_OK);
    DHT_TRUE(memcmp(&it0, &items[0], sizeof it0) == 0);
    DHT_EQ_INT(items[0].jerk, 0);
    /* a blended move, then a jerk-limited one from its end: at rest */
    DHT_EQ_INT(dh_queue_init_f32(&qu, items, 2), DH_OK);
    DHT_EQ_INT(dh_path_line_f32(&seg, &A, &B), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_blend_f32(&qu, &seg, &lim, 0.05f), DH_OK);
    A.m[3][2] = 0.2f;
    DHT_EQ_INT(dh_path_line_f32(&seg, &B, &A), DH_OK);
    jk.jmax = 10.0f;
    jk.wjmax = 1000.0f;
    DHT_EQ_INT(dh_queue_add_path_jerk_f32(&qu, &seg, &lim, &jk), DH_OK);
    DHT_EQ_INT(items[1].jerk, 1);
    DHT_EQ_INT(items[1].prof.kind, DH_PROFILE_SCURVE);
    DHT_TRUE(items[0].ctb == 0.0f);
    /* full */
    keep = queue_hash();
    DHT_EQ_INT(dh_queue_add_path_jerk_f32(&qu, &seg, &lim, &jk), DH_ERR_LIMIT);
    jk.jmax = NAN;
    DHT_EQ_INT(dh_queue_add_path_jerk_f32(&qu, &seg, &lim, &jk), DH_ERR_LIMIT);
    DHT_TRUE(queue_hash() == keep);
    DHT_EQ_INT(qu.count, 2);
}

static const dht_case cases[] = {
    DHT_CASE(jerk_bad),
    DHT_CASE(queues_ur5),
    DHT_CASE(queues_puma),
    DHT_CASE(queues_panda),
};

DHT_MAIN(cases)
