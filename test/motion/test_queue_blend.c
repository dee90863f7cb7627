/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_queue_blend.c - blended corners in the move queue
 * (dh_queue_add_path_blend_f32), run through the tracker as `dhmath move
 * --blend` runs them, at 1 kHz, seeded random queues.
 *
 * Queues of 2 to 6 segments on the Puma 560, UR5 and Panda, each a line
 * or (in half of them) an arc through a via point off its chord by 0.1
 * to 0.4 of it (the segments join the FK frames of configurations a few
 * degrees apart, so the tool also turns), each with a random radius (0 in
 * a fifth of them; up to 5 cm),
 * random Cartesian limits, in a queue of three items: up to three lines
 * queued at the start (in a third of the queues fewer), the others
 * appended as moves complete (a corner whose successor is not queued when
 * the line starts runs at rest). Every period's target (the queue's
 * command) is checked:
 * - outside an overlap (the queue's bmode is not 2) on its segment within
 *   1e-6 m (an arc: the circle of the path dh_path_arc_f32 made, centre
 *   p_A - u0, and within its sweep; test_path.c bounds that circle
 *   against the double one through the three points), inside one within
 *   the corner's radius of the corner (plus 8 FLT_EPSILON of the
 *   positions' scale);
 * - speed, TOTAL acceleration, angular speed and angular acceleration by
 *   finite differences within the limits times 1 + 1e-3, over windows of
 *   WS = 10 periods every period (plus 8 ulp of the positions' scale, at
 *   most a few percent of the bound: a short stretch beyond the limits
 *   shows there) and of W = 50 periods every 10 (the rounding at most
 *   2.5e-4 of the bound), from the start of the queue to its end, stops
 *   and tracker lags included; the angular ones from rotation vectors
 *   log(R(t +- w) R(t)^T) about the middle sample (test_blend.c);
 * - each period's step within one period at the speed limits (plus the
 *   rounding), so no jump hides in a window.
 * In half the queues the tracker's state is replaced by LAGGING for a
 * random stretch starting inside an overlap, and in half for one at a
 * random period (the feed override falls and rises; it holds inside an
 * overlap). In a third, a stop comes inside an overlap: both lines brake
 * within the limits and rest comes within the overlap's duration of OK
 * periods, inside the ball; the resume (at once, or some periods later)
 * reaches the end; in a third a stop comes at a random period (it brakes
 * within the limits as well). A first corner planned with its next line
 * queued at the start runs blended when nothing stops the queue. Moves
 * complete in order, the last target is the last line's B bit for bit.
 *
 * Statuses of dh_queue_add_path_blend_f32: a NaN radius, a negative one,
 * the queue untouched; an arc with a radius > 0 is accepted.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "dht.h"
#include "support_motion.h"
#include "support_robots.h"
#include "dhmath/motion.h"
#include "dhmath/track.h"

#define DT 1e-3f
#define NMAX 6           /* lines of a queue */
#define CAP 3            /* the queue's items: a line, the next, and the one after */
#define WS 10            /* the short window (periods), every period */
#define WD 10            /* the long window's sampling (periods) */
#define W (5 * WD)       /* the long window (periods) */
#define NS (2 * WS + 1)  /* samples kept, every period */
#define NL (2 * W / WD + 1) /* samples kept, every WD periods */
#define MAXCALL 200000L

/* static: the micro:bit's RAM holds them beside the rig on the stack */
static dh_queue_f32 qu;
static dh_queue_item_f32 items[CAP];
static float cp[NMAX + 1][3];         /* the corners' positions (line k: cp[k] to cp[k + 1]) */
static float radius[NMAX];
static unsigned char isarc[NMAX];      /* segment k is an arc (drawn when appended) */
static float sp[NS][7], lp[NL][7];    /* position and unit quaternion of the target m periods (m WD periods) ago */
static long arc_ov;                   /* periods in overlaps at a corner with an arc */
static long arc_stops;                /* stops inside such an overlap */

/* the path of segment k in the queue's ring: the item from corner k to
 * corner k + 1 (NULL when none) */
static const dh_path_f32 *seg_path(uint32_t k)
{
    uint32_t i;
    for (i = 0; i < CAP; i++) {
        const dh_path_f32 *p = &items[i].path;
        if (items[i].kind == (uint32_t)DH_MOVE_PATH && memcmp(&p->A.m[3][0], cp[k], sizeof cp[k]) == 0 &&
            memcmp(&p->B.m[3][0], cp[k + 1u], sizeof cp[k]) == 0)
            return p;
    }
    return NULL;
}

/* distance of x from the arc of segment k (its path in the queue's ring) */
static double arc_dist(uint32_t k, const double x[3])
{
    const dh_path_f32 *p = seg_path(k);
    DHT_TRUE(p != NULL);
    return (p != NULL) ? dhm_arc_dist(p, x) : INFINITY;
}

/* every target's finite differences within lim (the file's comment):
 * each period's step, windows of WS periods every period and of W
 * periods every WD periods */
static void check_fd(dhm_fd *fd, const dh_mat4_f32 *T, const dh_cart_limits_f32 *lim, double S, long call)
{
    (void)dhm_fd_push(fd, T, lim, S * FLT_EPSILON, call);
}

/* the target on its line outside an overlap, within the corner's radius
 * inside one; 1 when inside */
static int check_path(const dh_mat4_f32 *T, uint32_t n, double S, long call)
{
    uint32_t k;
    double x[3], d;
    if (dhm_check_corner(&qu, T, n, (const float (*)[3])cp, radius, S, call, &k, x)) {
        if (isarc[k] || (k + 1u < n && isarc[k + 1u])) arc_ov++;
        return 1;
    }
    d = isarc[k] ? arc_dist(k, x) : dhm_seg_dist(cp[k], cp[k + 1u], x);
    DHT_TRUE_MSG(d <= 1e-6, "call %ld: %.9g off %s %u", call, d, isarc[k] ? "arc" : "line", (unsigned)k);
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

/* segment k appended with its radius: a line, or an arc (dhm_draw_via) */
static void append(const dhm_rig *g, const float (*qc)[DH_MAX_JOINTS], uint32_t k, const dh_cart_limits_f32 *lim)
{
    dh_path_f32 line;
    dh_mat4_f32 A, B;
    float via[3];
    corner(g, qc, k, &A);
    corner(g, qc, k + 1u, &B);
    isarc[k] = (unsigned char)dhm_draw_via(cp[k], cp[k + 1u], via);
    if (isarc[k])
        DHT_EQ_INT(dh_path_arc_f32(&line, &A, via, &B), DH_OK);
    else
        DHT_EQ_INT(dh_path_line_f32(&line, &A, &B), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_blend_f32(&qu, &line, lim, radius[k]), DH_OK);
}

/* a random queue of n lines from the configuration qa: the corners'
 * configurations a few degrees apart, their positions, the radii */
static void draw_lines(const dhm_rig *g, const double *qa, uint32_t n, double step, float (*qc)[DH_MAX_JOINTS])
{
    dh_mat4_f32 T;
    uint32_t k, i;
    for (i = 0; i < g->r.n; i++) qc[0][i] = (float)qa[i];
    for (k = 0; k <= n; k++) {
        if (k > 0) dhm_draw_q(&g->r, qc[k - 1u], step, qc[k]);
        corner(g, (const float (*)[DH_MAX_JOINTS])qc, k, &T);
        for (i = 0; i < 3u; i++) cp[k][i] = T.m[3][i];
        if (k < n) radius[k] = (dht_rand_u32() % 5u == 0u) ? 0.0f : (float)dht_rand_uniform(1e-3, 0.05);
    }
}

/* one random queue on the rig's robot from about q_nom (the file's comment) */
static void blend_queue(dhm_rig *g, const double *q_nom, long *overlap_periods)
{
    dh_cart_limits_f32 lim;
    dhm_fd fd = { sp, lp, NS, NL, WS, WD, W, (double)DT, 0 };
    double qa[DH_MAX_JOINTS], S = 1.0;
    float q0[DH_MAX_JOINTS];
    dh_queue_cmd_f32 cmd;
    dh_queue_report_f32 rep;
    dh_track_report_f32 trep;
    const uint32_t n = 2u + dht_rand_u32() % (NMAX - 1u);
    const uint32_t n0 = (dht_rand_u32() % 3u == 0u) ? 1u + dht_rand_u32() % n : n;
    /* the stop: none, inside an overlap, or at a random period */
    const int stop_mode = (int)(dht_rand_u32() % 3u), lag_in = (int)(dht_rand_u32() % 2u);
    const long stop_at = (long)(dht_rand_u32() % 3000u), ov0 = *overlap_periods;
    const long lag_len = 1 + (long)(dht_rand_u32() % 300u), lag_at = (long)(dht_rand_u32() % 3000u);
    const long resume_wait = (long)(dht_rand_u32() % 3u) * (long)(dht_rand_u32() % 200u);
    long call, lag_from = -1, stop_call = -1, rest_ok = 0, stopped_at = -1;
    double tb_stop = 0.0;
    uint32_t i, added, done = 0;
    int stopped = 0, in_ov, planned;
    float qc[NMAX + 1][DH_MAX_JOINTS]; /* the corners' configurations (on the stack: the micro:bit's RAM) */
    const float (*qcc)[DH_MAX_JOINTS] = (const float (*)[DH_MAX_JOINTS])qc;
    for (i = 0; i < g->r.n; i++) qa[i] = q_nom[i] + dht_rand_uniform(-5.0, 5.0);
    draw_lines(g, qa, n, 8.0, qc);
    for (i = 0; i <= n; i++) {
        int k;
        for (k = 0; k < 3; k++) S = fmax(S, fabs((double)cp[i][k]));
    }
    dhm_draw_limits(&lim, NULL);
    for (i = 0; i < g->r.n; i++) q0[i] = qc[0][i];
    DHT_EQ_INT(dh_track_init_f32(&g->t, &g->r, g->closed ? &g->m : NULL, q0, DT), DH_OK);
    DHT_EQ_INT(dh_queue_init_f32(&qu, items, CAP), DH_OK);
    for (added = 0; added < n0 && added < CAP; added++) append(g, qcc, added, &lim);
    planned = added >= 2u && items[0].ctb > 0.0f;
    for (call = 0; call < MAXCALL && done < n; call++) {
        dh_track_state st;
        DHT_EQ_INT(dh_queue_target_f32(&qu, &g->t, DT, &cmd), DH_OK);
        DHT_EQ_INT(cmd.kind, DH_MOVE_PATH);
        in_ov = check_path(&cmd.T, n, S, call);
        *overlap_periods += in_ov;
        check_fd(&fd, &cmd.T, &lim, S, call);
        DHT_EQ_INT(dh_track_step_f32(&g->t, &cmd.T, g->t.q, &trep), DH_OK);
        st = trep.state;
        /* the lag stretch: inside the first overlap, or at a random period */
        if (lag_from < 0 && !stopped && ((lag_in && in_ov) || (!lag_in && call == lag_at))) lag_from = call;
        if (lag_from >= 0 && call - lag_from < lag_len && qu.phase == (uint32_t)DH_QUEUE_RUN) st = DH_TRACK_LAGGING;
        DHT_EQ_INT(dh_queue_advance_f32(&qu, st, &rep), DH_OK);
        if (stop_call >= 0 && stopped_at < 0 && st == DH_TRACK_OK) rest_ok++;
        if (rep.stopped && stopped_at < 0) {
            stopped_at = call;
            if (stop_mode == 1)
                DHT_TRUE_MSG((double)(rest_ok - 1) * DT <= tb_stop + 2.0 * DT,
                             "rest after %ld OK periods, overlap %.9g s", rest_ok, tb_stop);
        }
        if (stopped_at >= 0 && !stopped && call - stopped_at >= resume_wait) {
            stopped = 1;
            DHT_EQ_INT(dh_queue_resume_f32(&qu), DH_OK);
        }
        if (rep.done) {
            done++;
            DHT_EQ_INT(rep.last, done == added);
            if (added < n) append(g, qcc, added++, &lim);
        }
        /* the stop inside an overlap (the head line's tail and the next's) */
        if (stop_call < 0 && qu.phase == (uint32_t)DH_QUEUE_RUN && done < n &&
            ((stop_mode == 1 && qu.bmode == 2u && qu.bl[1].T > 0.0f && dht_rand_u32() % 8u == 0u) ||
             (stop_mode == 2 && call == stop_at))) {
            stop_call = call;
            tb_stop = qu.bl[0].tb1;
            if (stop_mode == 1 && (isarc[qu.seq] || isarc[qu.seq + 1u])) arc_stops++;
            DHT_EQ_INT(dh_queue_stop_f32(&qu), DH_OK);
            if (stop_mode == 1) DHT_EQ_INT(qu.phase, DH_QUEUE_BRAKE);
        }
    }
    DHT_TRUE_MSG(done == n, "%u of %u moves done in %ld periods", (unsigned)done, (unsigned)n, call);
    {
        dh_mat4_f32 B;
        corner(g, qcc, n, &B);
        DHT_TRUE(memcmp(&cmd.T, &B, sizeof cmd.T) == 0);
    }
    if (stop_call >= 0) DHT_TRUE(stopped);
    /* a corner planned with the line after it queued at the start is run
     * blended when nothing stops the queue */
    if (stop_mode == 0 && planned) DHT_TRUE(*overlap_periods > ov0);
}

static void run_robot(const dhm_robot_case *c)
{
    long it, nq = DHT_ITER(8), ov = 0;
    dhm_rig g;
    dhm_rig_make(&g, c);
    arc_ov = 0;
    arc_stops = 0;
    for (it = 0; it < nq; it++) blend_queue(&g, c->q, &ov);
    printf("%s: %ld queues, %ld periods in overlaps, %ld at corners with an arc (%ld stops there)\n", c->d->name, nq,
           ov, arc_ov, arc_stops);
}

static void queues_puma(void) { run_robot(&dhm_puma560); }
static void queues_ur5(void) { run_robot(&dhm_ur5); }
static void queues_panda(void) { run_robot(&dhm_panda); }

/* the queue's hash (and its items') */
static uint64_t queue_hash(void)
{
    return dhm_hash(&qu, sizeof qu, NULL, 0);
}

/* the radius's statuses; the queue untouched */
static void blend_bad(void)
{
    static const dh_cart_limits_f32 lim = { 0.1f, 1.0f, 30.0f, 300.0f };
    dh_path_f32 line, arc;
    uint64_t keep;
    dhm_line_arc(&line, &arc);
    DHT_EQ_INT(dh_queue_init_f32(&qu, items, 1), DH_OK);
    keep = queue_hash();
    DHT_EQ_INT(dh_queue_add_path_blend_f32(&qu, &line, &lim, NAN), DH_ERR_NAN);
    DHT_EQ_INT(dh_queue_add_path_blend_f32(&qu, &line, &lim, INFINITY), DH_ERR_NAN);
    DHT_EQ_INT(dh_queue_add_path_blend_f32(&qu, &line, &lim, -1e-3f), DH_ERR_ARG);
    DHT_TRUE(queue_hash() == keep);
    DHT_EQ_INT(dh_queue_add_path_blend_f32(&qu, &arc, &lim, 1e-3f), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_blend_f32(&qu, &line, &lim, 1e-3f), DH_ERR_LIMIT);
    DHT_EQ_INT(qu.count, 1);
    DHT_TRUE(items[0].radius == 1e-3f && items[0].path.kind == (uint32_t)DH_PATH_ARC);
}

static const dht_case cases[] = {
    DHT_CASE(blend_bad),
    DHT_CASE(queues_ur5),
    DHT_CASE(queues_puma),
    DHT_CASE(queues_panda),
};

DHT_MAIN(cases)
