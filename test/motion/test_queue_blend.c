/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_queue_blend.c - blended corners in the move queue
 * (dh_queue_add_path_blend_f32), run through the tracker as `dhmath move
 * --blend` runs them, at 1 kHz, seeded random queues.
 *
 * Queues of 2 to 6 lines on the Puma 560, UR5 and Panda (the lines join
 * the FK frames of configurations a few degrees apart, so the tool also
 * turns), each with a random radius (0 in a fifth of them; up to 5 cm),
 * random Cartesian limits, most lines queued at the start and the rest
 * appended as moves complete (a corner whose successor is not queued when
 * the line starts runs at rest). Every period's target (the queue's
 * command) is checked:
 * - outside an overlap (the queue's bmode is not 2) on its line within
 *   1e-6 m, inside one within the corner's radius of the corner (plus
 *   8 FLT_EPSILON of the positions' scale);
 * - speed, TOTAL acceleration, angular speed and angular acceleration by
 *   finite differences over windows of W periods within the limits times
 *   1 + 1e-3 (plus the samples' rounding, at most 2.5e-4 of the bound
 *   with W = 50), from the start of the queue to its end, stops and
 *   tracker lags included; the angular ones from rotation vectors
 *   log(R(t +- w) R(t)^T) about the middle sample (test_blend.c);
 * - each period's step within one period at the speed limits (plus the
 *   rounding), so no jump hides in a window.
 * In half the queues the tracker's state is replaced by LAGGING for a
 * random stretch starting inside an overlap, and in half for one at a
 * random period (the feed override falls and rises; it holds inside an
 * overlap). In half, a stop comes inside an overlap: both lines brake
 * within the limits and rest comes within the overlap's duration of OK
 * periods, inside the ball; the resume (at once, or some periods later)
 * reaches the end. Moves complete in order, the last target is the last
 * line's B bit for bit.
 *
 * Statuses of dh_queue_add_path_blend_f32: a NaN radius, a negative one,
 * an arc with a radius > 0 (a radius 0 is accepted), the queue untouched.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "dht.h"
#include "support_robots.h"
#include "dhmath/motion.h"
#include "dhmath/track.h"

#define DT 1e-3f
#define NMAX 6
#define W 50             /* window of the finite differences (periods) */
#define NH (2 * W + 1)   /* samples kept */
#define WS 10            /* the short window (periods) */
#define REL 1e-3
#define ANG_NOISE 1e-4   /* degrees: rounding of a sampled rotation */
#define MAXCALL 200000L
#define RAD2DEG 57.29577951308232

typedef struct {
    dh_robot r;
    dh_ikc_model_f32 m;
    dh_track_f32 t;
    int closed;
} rig;

/* static: the micro:bit's RAM holds them beside the rig on the stack */
static dh_queue_f32 qu;
static dh_queue_item_f32 items[NMAX];
static dh_path_f32 lines[NMAX];
static float radius[NMAX];
static float hp[NH][3]; /* hp[m], hq[m]: the target m periods ago */
static double hq[NH][4];
static long nh;

static double dist3(const double a[3], const double b[3])
{
    const double d[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
    return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

/* distance of x from the segment of the line p */
static double seg_dist(const dh_path_f32 *p, const double x[3])
{
    double a[3], d[3], r[3], dd = 0.0, s = 0.0, e[3];
    int i;
    for (i = 0; i < 3; i++) {
        a[i] = p->A.m[3][i];
        d[i] = (double)p->B.m[3][i] - a[i];
        r[i] = x[i] - a[i];
        dd += d[i] * d[i];
        s += r[i] * d[i];
    }
    s = (dd > 0.0) ? s / dd : 0.0;
    s = fmin(fmax(s, 0.0), 1.0);
    for (i = 0; i < 3; i++) e[i] = r[i] - s * d[i];
    return sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
}

/* unit quaternion (w, x, y, z) of T's rotation, in double (Shepperd) */
static void quat_of(const dh_mat4_f32 *T, double q[4])
{
    double R[3][3], tr, s, n;
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) R[i][j] = T->m[j][i];
    tr = R[0][0] + R[1][1] + R[2][2];
    if (tr > 0.0) {
        s = 2.0 * sqrt(1.0 + tr);
        q[0] = 0.25 * s;
        q[1] = (R[2][1] - R[1][2]) / s;
        q[2] = (R[0][2] - R[2][0]) / s;
        q[3] = (R[1][0] - R[0][1]) / s;
    } else if (R[0][0] > R[1][1] && R[0][0] > R[2][2]) {
        s = 2.0 * sqrt(1.0 + R[0][0] - R[1][1] - R[2][2]);
        q[0] = (R[2][1] - R[1][2]) / s;
        q[1] = 0.25 * s;
        q[2] = (R[0][1] + R[1][0]) / s;
        q[3] = (R[0][2] + R[2][0]) / s;
    } else if (R[1][1] > R[2][2]) {
        s = 2.0 * sqrt(1.0 + R[1][1] - R[0][0] - R[2][2]);
        q[0] = (R[0][2] - R[2][0]) / s;
        q[1] = (R[0][1] + R[1][0]) / s;
        q[2] = 0.25 * s;
        q[3] = (R[1][2] + R[2][1]) / s;
    } else {
        s = 2.0 * sqrt(1.0 + R[2][2] - R[0][0] - R[1][1]);
        q[0] = (R[1][0] - R[0][1]) / s;
        q[1] = (R[0][2] + R[2][0]) / s;
        q[2] = (R[1][2] + R[2][1]) / s;
        q[3] = 0.25 * s;
    }
    n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (i = 0; i < 4; i++) q[i] /= n;
}

/* v = the rotation vector (degrees) of Rb Ra^T, from quaternions */
static void rotvec(const double qa[4], const double qb[4], double v[3])
{
    /* qb * conj(qa) */
    const double w = qb[0] * qa[0] + qb[1] * qa[1] + qb[2] * qa[2] + qb[3] * qa[3];
    double x[3], n, th;
    int i;
    x[0] = -qb[0] * qa[1] + qb[1] * qa[0] - qb[2] * qa[3] + qb[3] * qa[2];
    x[1] = -qb[0] * qa[2] + qb[1] * qa[3] + qb[2] * qa[0] - qb[3] * qa[1];
    x[2] = -qb[0] * qa[3] - qb[1] * qa[2] + qb[2] * qa[1] + qb[3] * qa[0];
    n = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    th = 2.0 * atan2(n, fabs(w));
    for (i = 0; i < 3; i++) v[i] = (n > 0.0) ? ((w < 0.0) ? -1.0 : 1.0) * th * x[i] / n * RAD2DEG : 0.0;
}

/* every target's finite differences within lim (the file's comment) */
static void check_fd(const dh_mat4_f32 *T, const dh_cart_limits_f32 *lim, double S, long call)
{
    const double h = (double)W * DT, ulp = S * FLT_EPSILON;
    double p0[3], p1[3], pw[3], p2w[3], a[3], b[3], x;
    int m, k;
    for (m = NH - 1; m > 0; m--) {
        memcpy(hp[m], hp[m - 1], sizeof hp[0]);
        memcpy(hq[m], hq[m - 1], sizeof hq[0]);
    }
    for (k = 0; k < 3; k++) hp[0][k] = T->m[3][k];
    quat_of(T, hq[0]);
    nh++;
    for (k = 0; k < 3; k++) {
        p0[k] = hp[0][k];
        p1[k] = hp[1][k];
        pw[k] = hp[W][k];
        p2w[k] = hp[2 * W][k];
    }
    if (nh >= 2) {
        x = dist3(p0, p1);
        DHT_TRUE_MSG(x <= (double)lim->vmax * DT * (1.0 + REL) + 4.0 * ulp, "call %ld: step %.9g over %.9g", call, x,
                     (double)lim->vmax * DT);
        rotvec(hq[1], hq[0], a);
        x = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        DHT_TRUE_MSG(x <= (double)lim->wmax * DT * (1.0 + REL) + ANG_NOISE, "call %ld: turn %.9g over %.9g", call, x,
                     (double)lim->wmax * DT);
    }
    if (nh >= 2 * WS + 1) {
        /* a short window (the rounding a larger share of its bound) */
        const double hs = (double)WS * DT;
        for (k = 0; k < 3; k++) a[k] = p0[k] - 2.0 * hp[WS][k] + hp[2 * WS][k];
        x = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        DHT_TRUE_MSG(x <= (double)lim->amax * hs * hs * (1.0 + REL) + 8.0 * ulp,
                     "call %ld: acceleration %.9g over %.9g (%d periods)", call, x / (hs * hs), (double)lim->amax, WS);
        rotvec(hq[WS], hq[0], a);
        rotvec(hq[WS], hq[2 * WS], b);
        for (k = 0; k < 3; k++) a[k] += b[k];
        x = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        DHT_TRUE_MSG(x <= (double)lim->wdmax * hs * hs * (1.0 + REL) + 2.0 * ANG_NOISE,
                     "call %ld: angular acceleration %.9g over %.9g (%d periods)", call, x / (hs * hs),
                     (double)lim->wdmax, WS);
    }
    if (nh < NH) return;
    x = dist3(p0, pw);
    DHT_TRUE_MSG(x <= (double)lim->vmax * h * (1.0 + REL) + 4.0 * ulp, "call %ld: speed %.9g over %.9g", call, x / h,
                 (double)lim->vmax);
    for (k = 0; k < 3; k++) a[k] = p0[k] - 2.0 * pw[k] + p2w[k];
    x = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    DHT_TRUE_MSG(x <= (double)lim->amax * h * h * (1.0 + REL) + 8.0 * ulp, "call %ld: acceleration %.9g over %.9g",
                 call, x / (h * h), (double)lim->amax);
    rotvec(hq[W], hq[0], a);
    x = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    DHT_TRUE_MSG(x <= (double)lim->wmax * h * (1.0 + REL) + ANG_NOISE, "call %ld: angular speed %.9g over %.9g", call,
                 x / h, (double)lim->wmax);
    rotvec(hq[W], hq[2 * W], b);
    for (k = 0; k < 3; k++) a[k] += b[k];
    x = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    DHT_TRUE_MSG(x <= (double)lim->wdmax * h * h * (1.0 + REL) + 2.0 * ANG_NOISE,
                 "call %ld: angular acceleration %.9g over %.9g", call, x / (h * h), (double)lim->wdmax);
}

/* the target on its line outside an overlap, within the corner's radius
 * inside one; 1 when inside */
static int check_path(const dh_mat4_f32 *T, uint32_t n, double S, long call)
{
    const uint32_t k = (qu.seq < n) ? qu.seq : n - 1u;
    const double tol = 1e-6 + 8.0 * FLT_EPSILON * S;
    double x[3], c[3], d;
    int i;
    for (i = 0; i < 3; i++) {
        x[i] = T->m[3][i];
        c[i] = lines[k].B.m[3][i];
    }
    if (qu.bmode == 2u) {
        d = dist3(x, c);
        DHT_TRUE_MSG(k + 1u < n && d <= (double)radius[k] + tol, "call %ld: %.9g from corner %u, radius %.9g", call, d,
                     (unsigned)k, (double)radius[k]);
        return 1;
    }
    d = seg_dist(&lines[k], x);
    DHT_TRUE_MSG(d <= 1e-6, "call %ld: %.9g off line %u", call, d, (unsigned)k);
    return 0;
}

/* a random queue of n lines from the configuration qa (float) */
static void draw_lines(rig *g, const double *qa, uint32_t n, double step)
{
    double q[DH_MAX_JOINTS], qn[DH_MAX_JOINTS];
    dh_mat4_f32 A, B;
    uint32_t k, i;
    memcpy(q, qa, sizeof q);
    dhs_target_f32(&g->r, q, &A);
    for (k = 0; k < n; k++) {
        for (i = 0; i < g->r.n; i++) {
            const dh_joint *j = &g->r.joint[i];
            double v = q[i] + dht_rand_uniform(-step, step);
            if (j->qmin <= j->qmax) v = fmin(fmax(v, j->qmin + 5.0), j->qmax - 5.0);
            qn[i] = v;
        }
        dhs_target_f32(&g->r, qn, &B);
        DHT_EQ_INT(dh_path_line_f32(&lines[k], &A, &B), DH_OK);
        radius[k] = (dht_rand_u32() % 5u == 0u) ? 0.0f : (float)dht_rand_uniform(1e-3, 0.05);
        A = B;
        memcpy(q, qn, sizeof q);
    }
}

/* one random queue on the rig's robot from about q_nom (the file's comment) */
static void blend_queue(rig *g, const double *q_nom, long *overlap_periods)
{
    dh_cart_limits_f32 lim;
    double qa[DH_MAX_JOINTS], S = 1.0;
    float q0[DH_MAX_JOINTS];
    dh_queue_cmd_f32 cmd;
    dh_queue_report_f32 rep;
    dh_track_report_f32 trep;
    const uint32_t n = 2u + dht_rand_u32() % (NMAX - 1u);
    const uint32_t n0 = (dht_rand_u32() % 3u == 0u) ? 1u + dht_rand_u32() % n : n;
    const int stop_in = (int)(dht_rand_u32() % 2u), lag_in = (int)(dht_rand_u32() % 2u);
    const long lag_len = 1 + (long)(dht_rand_u32() % 300u), lag_at = (long)(dht_rand_u32() % 3000u);
    const long resume_wait = (long)(dht_rand_u32() % 3u) * (long)(dht_rand_u32() % 200u);
    long call, lag_from = -1, stop_call = -1, rest_ok = 0, stopped_at = -1;
    double tb_stop = 0.0;
    uint32_t i, added, done = 0;
    int stopped = 0, in_ov;
    for (i = 0; i < g->r.n; i++) qa[i] = q_nom[i] + dht_rand_uniform(-5.0, 5.0);
    draw_lines(g, qa, n, 8.0);
    for (i = 0; i < n; i++) {
        int k;
        for (k = 0; k < 3; k++) S = fmax(S, fabs((double)lines[i].B.m[3][k]));
    }
    lim.vmax = (float)dht_rand_uniform(0.05, 0.2);
    lim.amax = (float)dht_rand_uniform(0.3, 2.0);
    lim.wmax = (float)dht_rand_uniform(15.0, 60.0);
    lim.wdmax = (float)dht_rand_uniform(60.0, 600.0);
    for (i = 0; i < g->r.n; i++) q0[i] = (float)qa[i];
    DHT_EQ_INT(dh_track_init_f32(&g->t, &g->r, g->closed ? &g->m : NULL, q0, DT), DH_OK);
    DHT_EQ_INT(dh_queue_init_f32(&qu, items, NMAX), DH_OK);
    for (added = 0; added < n0; added++)
        DHT_EQ_INT(dh_queue_add_path_blend_f32(&qu, &lines[added], &lim, radius[added]), DH_OK);
    nh = 0;
    for (call = 0; call < MAXCALL && done < n; call++) {
        dh_track_state st;
        DHT_EQ_INT(dh_queue_target_f32(&qu, &g->t, DT, &cmd), DH_OK);
        DHT_EQ_INT(cmd.kind, DH_MOVE_PATH);
        in_ov = check_path(&cmd.T, n, S, call);
        *overlap_periods += in_ov;
        check_fd(&cmd.T, &lim, S, call);
        DHT_EQ_INT(dh_track_step_f32(&g->t, &cmd.T, g->t.q, &trep), DH_OK);
        st = trep.state;
        /* the lag stretch: inside the first overlap, or at a random period */
        if (lag_from < 0 && !stopped && ((lag_in && in_ov) || (!lag_in && call == lag_at))) lag_from = call;
        if (lag_from >= 0 && call - lag_from < lag_len && qu.phase == (uint32_t)DH_QUEUE_RUN) st = DH_TRACK_LAGGING;
        DHT_EQ_INT(dh_queue_advance_f32(&qu, st, &rep), DH_OK);
        if (stop_call >= 0 && stopped_at < 0 && st == DH_TRACK_OK) rest_ok++;
        if (rep.stopped && stopped_at < 0) {
            stopped_at = call;
            DHT_TRUE_MSG((double)(rest_ok - 1) * DT <= tb_stop + 2.0 * DT, "rest after %ld OK periods, overlap %.9g s",
                         rest_ok, tb_stop);
        }
        if (stopped_at >= 0 && !stopped && call - stopped_at >= resume_wait) {
            stopped = 1;
            DHT_EQ_INT(dh_queue_resume_f32(&qu), DH_OK);
        }
        if (rep.done) {
            done++;
            DHT_EQ_INT(rep.last, done == added);
            if (added < n) {
                DHT_EQ_INT(dh_queue_add_path_blend_f32(&qu, &lines[added], &lim, radius[added]), DH_OK);
                added++;
            }
        }
        /* the stop inside an overlap (the head line's tail and the next's) */
        if (stop_in && stop_call < 0 && qu.bmode == 2u && qu.bl[1].T > 0.0f && qu.phase == (uint32_t)DH_QUEUE_RUN &&
            dht_rand_u32() % 8u == 0u) {
            stop_call = call;
            tb_stop = qu.bl[0].tb1;
            DHT_EQ_INT(dh_queue_stop_f32(&qu), DH_OK);
            DHT_EQ_INT(qu.phase, DH_QUEUE_BRAKE);
        }
    }
    DHT_TRUE_MSG(done == n, "%u of %u moves done in %ld periods", (unsigned)done, (unsigned)n, call);
    DHT_TRUE(memcmp(&cmd.T, &lines[n - 1u].B, sizeof cmd.T) == 0);
    if (stop_call >= 0) DHT_TRUE(stopped);
}

static void run_robot(const dhs_robot *d, const double *q_nom, int closed)
{
    long it, nq = DHT_ITER(8), ov = 0;
    uint32_t i;
    rig g;
    DHT_EQ_INT(dhs_build(d, &g.r), DH_OK);
    for (i = 0; i < g.r.n; i++) DHT_EQ_INT(dh_robot_set_rates_f32(&g.r, i, 180.0f, 3000.0f), DH_OK);
    g.closed = closed;
    if (closed) DHT_EQ_INT(dh_ikc_analyse_f32(&g.r, &g.m), DH_OK);
    for (it = 0; it < nq; it++) blend_queue(&g, q_nom, &ov);
    printf("%s: %ld queues, %ld periods in overlaps\n", d->name, nq, ov);
    DHT_TRUE(ov > 0);
}

static void queues_puma(void)
{
    static const double Q[6] = { 10.0, -30.0, 45.0, 20.0, 35.0, -60.0 };
    run_robot(&dhs_puma560_m, Q, 1);
}

static void queues_ur5(void)
{
    static const double Q[6] = { 30.0, -80.0, 90.0, -100.0, -90.0, 20.0 };
    run_robot(&dhs_ur5_m, Q, 1);
}

static void queues_panda(void)
{
    static const double Q[7] = { 0.0, -30.0, 0.0, -120.0, 0.0, 90.0, 45.0 };
    run_robot(&dhs_panda_m, Q, 0);
}

/* FNV-1a hash of the queue (a copy does not fit the micro:bit's RAM) */
static uint64_t queue_hash(void)
{
    const unsigned char *b = (const unsigned char *)&qu;
    uint64_t h = 14695981039346656037ull;
    size_t i;
    for (i = 0; i < sizeof qu; i++) h = (h ^ b[i]) * 1099511628211ull;
    return h;
}

/* the radius's statuses; the queue untouched */
static void blend_bad(void)
{
    static const dh_cart_limits_f32 lim = { 0.1f, 1.0f, 30.0f, 300.0f };
    static dh_path_f32 arc;
    dh_mat4_f32 A, B;
    const float via[3] = { 0.3f, 0.1f, 0.2f };
    uint64_t keep;
    memset(&A, 0, sizeof A);
    A.m[0][0] = A.m[1][1] = A.m[2][2] = A.m[3][3] = 1.0f;
    B = A;
    A.m[3][0] = 0.2f;
    B.m[3][0] = 0.4f;
    B.m[3][1] = 0.2f;
    DHT_EQ_INT(dh_path_line_f32(&lines[0], &A, &B), DH_OK);
    DHT_EQ_INT(dh_path_arc_f32(&arc, &A, via, &B), DH_OK);
    DHT_EQ_INT(dh_queue_init_f32(&qu, items, 1), DH_OK);
    keep = queue_hash();
    DHT_EQ_INT(dh_queue_add_path_blend_f32(&qu, &lines[0], &lim, NAN), DH_ERR_NAN);
    DHT_EQ_INT(dh_queue_add_path_blend_f32(&qu, &lines[0], &lim, INFINITY), DH_ERR_NAN);
    DHT_EQ_INT(dh_queue_add_path_blend_f32(&qu, &lines[0], &lim, -1e-3f), DH_ERR_ARG);
    DHT_EQ_INT(dh_queue_add_path_blend_f32(&qu, &arc, &lim, 1e-3f), DH_ERR_ARG);
    DHT_TRUE(queue_hash() == keep);
    DHT_EQ_INT(dh_queue_add_path_blend_f32(&qu, &arc, &lim, 0.0f), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_blend_f32(&qu, &lines[0], &lim, 1e-3f), DH_ERR_LIMIT);
    DHT_EQ_INT(qu.count, 1);
    DHT_TRUE(items[0].radius == 0.0f && items[0].path.kind == (uint32_t)DH_PATH_ARC);
}

static const dht_case cases[] = {
    DHT_CASE(blend_bad),
    DHT_CASE(queues_ur5),
    DHT_CASE(queues_puma),
    DHT_CASE(queues_panda),
};

DHT_MAIN(cases)
