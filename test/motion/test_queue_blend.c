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
static dh_queue_item_f32 items[CAP];
static dh_path_f32 line;              /* the line being appended */
static float qc[NMAX + 1][DH_MAX_JOINTS]; /* the corners' configurations */
static float cp[NMAX + 1][3];         /* the corners' positions (line k: cp[k] to cp[k + 1]) */
static float radius[NMAX];
static unsigned char isarc[NMAX];      /* segment k is an arc (drawn when appended) */
static float sp[NS][7], lp[NL][7];    /* position and unit quaternion of the target m periods (m WD periods) ago */
static long nh;
static long arc_ov;                   /* periods in overlaps at a corner with an arc */
static long arc_stops;                /* stops inside such an overlap */

static double dist3(const double a[3], const double b[3])
{
    const double d[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
    return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

/* distance of x from the segment of line k */
static double seg_dist(uint32_t k, const double x[3])
{
    double a[3], d[3], r[3], dd = 0.0, s = 0.0, e[3];
    int i;
    for (i = 0; i < 3; i++) {
        a[i] = cp[k][i];
        d[i] = (double)cp[k + 1u][i] - a[i];
        r[i] = x[i] - a[i];
        dd += d[i] * d[i];
        s += r[i] * d[i];
    }
    s = (dd > 0.0) ? s / dd : 0.0;
    s = fmin(fmax(s, 0.0), 1.0);
    for (i = 0; i < 3; i++) e[i] = r[i] - s * d[i];
    return sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
}

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

/* distance of x from the arc of segment k (its path in the queue's ring):
 * from the circle of centre p_A - u0, radius |u0| in the plane of normal
 * n, and beyond the sweep the distance from the nearer end */
static double arc_dist(uint32_t k, const double x[3])
{
    const dh_path_f32 *p = seg_path(k);
    double r[3], n[3], u[3], w[3], z = 0.0, nn = 0.0, rho = 0.0, rr = 0.0, ph, e[2], sw;
    int i;
    DHT_TRUE(p != NULL && p->kind == (uint32_t)DH_PATH_ARC);
    if (p == NULL) return INFINITY;
    sw = (double)p->sweep / RAD2DEG;
    for (i = 0; i < 3; i++) nn += (double)p->n[i] * p->n[i];
    for (i = 0; i < 3; i++) {
        n[i] = p->n[i] / sqrt(nn);
        u[i] = p->u0[i];
        r[i] = x[i] - ((double)cp[k][i] - u[i]);
        z += r[i] * n[i];
        rho += u[i] * u[i];
    }
    rho = sqrt(rho);
    for (i = 0; i < 3; i++) {
        r[i] -= z * n[i];
        rr += r[i] * r[i];
    }
    w[0] = n[1] * u[2] - n[2] * u[1];
    w[1] = n[2] * u[0] - n[0] * u[2];
    w[2] = n[0] * u[1] - n[1] * u[0];
    ph = atan2(r[0] * w[0] + r[1] * w[1] + r[2] * w[2], r[0] * u[0] + r[1] * u[1] + r[2] * u[2]);
    if (ph < -0.5 * (2.0 * 3.14159265358979323846 - sw)) ph += 2.0 * 3.14159265358979323846;
    if (ph >= 0.0 && ph <= sw) {
        e[0] = z;
        e[1] = sqrt(rr) - rho;
        return sqrt(e[0] * e[0] + e[1] * e[1]);
    }
    for (i = 0; i < 3; i++) r[i] = x[i] - cp[(ph < 0.0) ? k : k + 1u][i];
    return sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
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
static void rotvec(const float *qa, const float *qb, double v[3])
{
    /* qb * conj(qa) */
    const double w = (double)qb[0] * qa[0] + (double)qb[1] * qa[1] + (double)qb[2] * qa[2] + (double)qb[3] * qa[3];
    double x[3], n, th;
    int i;
    x[0] = -(double)qb[0] * qa[1] + (double)qb[1] * qa[0] - (double)qb[2] * qa[3] + (double)qb[3] * qa[2];
    x[1] = -(double)qb[0] * qa[2] + (double)qb[1] * qa[3] + (double)qb[2] * qa[0] - (double)qb[3] * qa[1];
    x[2] = -(double)qb[0] * qa[3] - (double)qb[1] * qa[2] + (double)qb[2] * qa[1] + (double)qb[3] * qa[0];
    n = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    th = 2.0 * atan2(n, fabs(w));
    for (i = 0; i < 3; i++) v[i] = (n > 0.0) ? ((w < 0.0) ? -1.0 : 1.0) * th * x[i] / n * RAD2DEG : 0.0;
}

/* the acceleration (linear, angular) of the samples h[0], h[w], h[2 w]
 * times (w dt)^2 within lim (h: NS or NL rows of 7) */
static void check_acc(const float (*h)[7], int w, double hdt, const dh_cart_limits_f32 *lim, double ulp, long call)
{
    double a[3], b[3], x;
    int k;
    for (k = 0; k < 3; k++) a[k] = (double)h[0][k] - 2.0 * h[w][k] + h[2 * w][k];
    x = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    DHT_TRUE_MSG(x <= (double)lim->amax * hdt * hdt * (1.0 + REL) + 8.0 * ulp,
                 "call %ld: acceleration %.9g over %.9g (%.3g s)", call, x / (hdt * hdt), (double)lim->amax, hdt);
    rotvec(&h[w][3], &h[0][3], a);
    rotvec(&h[w][3], &h[2 * w][3], b);
    for (k = 0; k < 3; k++) a[k] += b[k];
    x = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    DHT_TRUE_MSG(x <= (double)lim->wdmax * hdt * hdt * (1.0 + REL) + 2.0 * ANG_NOISE,
                 "call %ld: angular acceleration %.9g over %.9g (%.3g s)", call, x / (hdt * hdt), (double)lim->wdmax,
                 hdt);
}

/* the speed (linear, angular) between the samples h0 and h1, hdt apart */
static void check_speed(const float *h0, const float *h1, double hdt, const dh_cart_limits_f32 *lim, double ulp,
                        long call)
{
    double p0[3], p1[3], a[3], x;
    int k;
    for (k = 0; k < 3; k++) {
        p0[k] = h0[k];
        p1[k] = h1[k];
    }
    x = dist3(p0, p1);
    DHT_TRUE_MSG(x <= (double)lim->vmax * hdt * (1.0 + REL) + 4.0 * ulp, "call %ld: speed %.9g over %.9g (%.3g s)",
                 call, x / hdt, (double)lim->vmax, hdt);
    rotvec(&h1[3], &h0[3], a);
    x = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    DHT_TRUE_MSG(x <= (double)lim->wmax * hdt * (1.0 + REL) + ANG_NOISE, "call %ld: angular speed %.9g over %.9g",
                 call, x / hdt, (double)lim->wmax);
}

/* every target's finite differences within lim (the file's comment):
 * each period's step, windows of WS periods every period and of W
 * periods every WD periods */
static void check_fd(const dh_mat4_f32 *T, const dh_cart_limits_f32 *lim, double S, long call)
{
    const double ulp = S * FLT_EPSILON;
    double q[4];
    int m, k;
    for (m = NS - 1; m > 0; m--) memcpy(sp[m], sp[m - 1], sizeof sp[0]);
    quat_of(T, q);
    for (k = 0; k < 3; k++) sp[0][k] = T->m[3][k];
    for (k = 0; k < 4; k++) sp[0][3 + k] = (float)q[k];
    nh++;
    if (nh >= 2) check_speed(sp[0], sp[1], DT, lim, ulp, call);
    if (nh >= NS) check_acc((const float (*)[7])sp, WS, (double)WS * DT, lim, ulp, call);
    if ((nh - 1) % WD != 0) return;
    for (m = NL - 1; m > 0; m--) memcpy(lp[m], lp[m - 1], sizeof lp[0]);
    memcpy(lp[0], sp[0], sizeof lp[0]);
    if (nh < (long)(NL - 1) * WD + 1) return;
    check_speed(lp[0], lp[W / WD], (double)W * DT, lim, ulp, call);
    check_acc((const float (*)[7])lp, W / WD, (double)W * DT, lim, ulp, call);
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
        c[i] = cp[k + 1u][i];
    }
    if (qu.bmode == 2u) {
        d = dist3(x, c);
        DHT_TRUE_MSG(k + 1u < n && d <= (double)radius[k] + tol, "call %ld: %.9g from corner %u, radius %.9g", call, d,
                     (unsigned)k, (double)radius[k]);
        if (isarc[k] || (k + 1u < n && isarc[k + 1u])) arc_ov++;
        return 1;
    }
    d = isarc[k] ? arc_dist(k, x) : seg_dist(k, x);
    DHT_TRUE_MSG(d <= 1e-6, "call %ld: %.9g off %s %u", call, d, isarc[k] ? "arc" : "line", (unsigned)k);
    return 0;
}

/* the frame of corner k (FK of its configuration) */
static void corner(const rig *g, uint32_t k, dh_mat4_f32 *T)
{
    double q[DH_MAX_JOINTS];
    uint32_t i;
    for (i = 0; i < g->r.n; i++) q[i] = qc[k][i];
    dhs_target_f32(&g->r, q, T);
}

/* segment k an arc (in half the segments, of a chord of 1 cm at least;
 * 0 when not): its via point off the chord's middle by 0.1 to 0.4 of the
 * chord, in a random direction across it */
static int draw_arc(uint32_t k, float via[3])
{
    double d[3], e[3], h = 0.0, c = 0.0, x;
    int i;
    for (i = 0; i < 3; i++) {
        d[i] = (double)cp[k + 1u][i] - cp[k][i];
        c += d[i] * d[i];
    }
    if (dht_rand_u32() % 2u == 0u || c < 1e-4) return 0;
    do {
        for (i = 0; i < 3; i++) e[i] = dht_rand_uniform(-1.0, 1.0);
        x = (e[0] * d[0] + e[1] * d[1] + e[2] * d[2]) / c;
        h = 0.0;
        for (i = 0; i < 3; i++) {
            e[i] -= x * d[i];
            h += e[i] * e[i];
        }
    } while (h < 0.01);
    x = dht_rand_uniform(0.1, 0.4) * sqrt(c / h);
    for (i = 0; i < 3; i++) via[i] = (float)(0.5 * ((double)cp[k][i] + cp[k + 1u][i]) + x * e[i]);
    return 1;
}

/* segment k appended with its radius: a line, or an arc (draw_arc) */
static void append(const rig *g, uint32_t k, const dh_cart_limits_f32 *lim)
{
    dh_mat4_f32 A, B;
    float via[3];
    corner(g, k, &A);
    corner(g, k + 1u, &B);
    isarc[k] = (unsigned char)draw_arc(k, via);
    if (isarc[k])
        DHT_EQ_INT(dh_path_arc_f32(&line, &A, via, &B), DH_OK);
    else
        DHT_EQ_INT(dh_path_line_f32(&line, &A, &B), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_blend_f32(&qu, &line, lim, radius[k]), DH_OK);
}

/* a random queue of n lines from the configuration qa: the corners'
 * configurations a few degrees apart, their positions, the radii */
static void draw_lines(const rig *g, const double *qa, uint32_t n, double step)
{
    dh_mat4_f32 T;
    uint32_t k, i;
    for (i = 0; i < g->r.n; i++) qc[0][i] = (float)qa[i];
    for (k = 0; k <= n; k++) {
        for (i = 0; k > 0 && i < g->r.n; i++) {
            const dh_joint *j = &g->r.joint[i];
            double v = qc[k - 1u][i] + dht_rand_uniform(-step, step);
            if (j->qmin <= j->qmax) v = fmin(fmax(v, j->qmin + 5.0), j->qmax - 5.0);
            qc[k][i] = (float)v;
        }
        corner(g, k, &T);
        for (i = 0; i < 3u; i++) cp[k][i] = T.m[3][i];
        if (k < n) radius[k] = (dht_rand_u32() % 5u == 0u) ? 0.0f : (float)dht_rand_uniform(1e-3, 0.05);
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
    /* the stop: none, inside an overlap, or at a random period */
    const int stop_mode = (int)(dht_rand_u32() % 3u), lag_in = (int)(dht_rand_u32() % 2u);
    const long stop_at = (long)(dht_rand_u32() % 3000u), ov0 = *overlap_periods;
    const long lag_len = 1 + (long)(dht_rand_u32() % 300u), lag_at = (long)(dht_rand_u32() % 3000u);
    const long resume_wait = (long)(dht_rand_u32() % 3u) * (long)(dht_rand_u32() % 200u);
    long call, lag_from = -1, stop_call = -1, rest_ok = 0, stopped_at = -1;
    double tb_stop = 0.0;
    uint32_t i, added, done = 0;
    int stopped = 0, in_ov, planned;
    for (i = 0; i < g->r.n; i++) qa[i] = q_nom[i] + dht_rand_uniform(-5.0, 5.0);
    draw_lines(g, qa, n, 8.0);
    for (i = 0; i <= n; i++) {
        int k;
        for (k = 0; k < 3; k++) S = fmax(S, fabs((double)cp[i][k]));
    }
    lim.vmax = (float)dht_rand_uniform(0.05, 0.2);
    lim.amax = (float)dht_rand_uniform(0.3, 2.0);
    lim.wmax = (float)dht_rand_uniform(15.0, 60.0);
    lim.wdmax = (float)dht_rand_uniform(60.0, 600.0);
    for (i = 0; i < g->r.n; i++) q0[i] = qc[0][i];
    DHT_EQ_INT(dh_track_init_f32(&g->t, &g->r, g->closed ? &g->m : NULL, q0, DT), DH_OK);
    DHT_EQ_INT(dh_queue_init_f32(&qu, items, CAP), DH_OK);
    for (added = 0; added < n0 && added < CAP; added++) append(g, added, &lim);
    planned = added >= 2u && items[0].ctb > 0.0f;
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
            if (added < n) append(g, added++, &lim);
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
        corner(g, n, &B);
        DHT_TRUE(memcmp(&cmd.T, &B, sizeof cmd.T) == 0);
    }
    if (stop_call >= 0) DHT_TRUE(stopped);
    /* a corner planned with the line after it queued at the start is run
     * blended when nothing stops the queue */
    if (stop_mode == 0 && planned) DHT_TRUE(*overlap_periods > ov0);
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
    arc_ov = 0;
    arc_stops = 0;
    for (it = 0; it < nq; it++) blend_queue(&g, q_nom, &ov);
    printf("%s: %ld queues, %ld periods in overlaps, %ld at corners with an arc (%ld stops there)\n", d->name, nq,
           ov, arc_ov, arc_stops);
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
    dh_path_f32 arc;
    dh_mat4_f32 A, B;
    const float v[3] = { 0.3f, 0.1f, 0.2f };
    uint64_t keep;
    memset(&A, 0, sizeof A);
    A.m[0][0] = A.m[1][1] = A.m[2][2] = A.m[3][3] = 1.0f;
    B = A;
    A.m[3][0] = 0.2f;
    B.m[3][0] = 0.4f;
    B.m[3][1] = 0.2f;
    DHT_EQ_INT(dh_path_line_f32(&line, &A, &B), DH_OK);
    DHT_EQ_INT(dh_path_arc_f32(&arc, &A, v, &B), DH_OK);
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
