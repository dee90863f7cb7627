/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_blend_q.c - the fixed-point blended sequence of line moves
 * (dh_blend_seq_plan_q, dh_blend_seq_eval_q) in mm, seeded random
 * sequences of 2 to 6 lines against double-precision references computed
 * here from the integer inputs.
 *
 * Lines join random corners in a box of +-500 mm (a tenth of them of
 * length 0, a tenth straight on), the tool turning by up to 20 degrees per
 * line about a random axis (a fifth without rotation); radii 0 in a fifth
 * of the corners, else up to 50 mm; random limits. The sequence is
 * sampled every 1 ms (1 kHz) from 0 to its end:
 * - t = 0 gives the first line's A and t = T the last one's B exactly;
 * - outside the overlaps the point is within 1 LSB of its line, inside
 *   the overlap of corner k within seg[k].dev + 2 LSB + 32 2^-30 of the
 *   two lines' lengths of the corner (the contract's bounds, far below
 *   the 5e-3 mm), and seg[k].dev <= radius[k];
 * - speed, TOTAL acceleration, angular speed and angular acceleration by
 *   finite differences within the limits times 1 + 1e-3, over windows of
 *   WS = 10 periods every period and W = 50 periods every 10, plus the
 *   noise of the samples: N the contract's position bound (2 LSB and
 *   16 2^-30 of the two lines' lengths) in 2 N / h and 4 N / h^2, and
 *   ANG_NOISE per rotation (1.5e-6 per entry, 3e-6 rad) likewise; the
 *   angular ones from rotation vectors log(R(t +- h) R(t)^T) about the
 *   middle sample (angle and axis of the relative rotation matrix);
 * - each line's rest-to-rest scaling lasts at least the time-optimal
 *   trapezoid of the double rates of s and at most that times 1 + 2^-9
 *   plus 4 us (the plan's 2^-10 margin, whole microseconds), and the
 *   blended sequence is shorter than its lines at rest whenever a corner
 *   is blended (and never longer).
 * Statuses of dh_blend_seq_plan_q.
 */
#include <math.h>
#include <string.h>

#include "dht.h"
#include "dhmath/motion.h"
#include "dhmath/frame.h"

#define PI_D 3.14159265358979323846
#define RAD2DEG (180.0 / PI_D)
#define Q30 1073741824.0
#define QPOS ((double)((int32_t)1 << DH_QPOS_FRAC))
#define NMAX 6
#define WS 10
#define WD 10
#define W (5 * WD)
#define REL 1e-3
#define POS_TOL 5e-3
#define ANG_NOISE (3e-6 * RAD2DEG)
#define DT_US 1000u

static dh_frame_q fr[NMAX + 1];
static dh_path_q line[NMAX];
static dh_blend_seg_q seg[NMAX];
static dh_qpos radius[NMAX];
static double sp[3][12], cur[12];

static void rot_of_quat(dh_frame_q *F, const double *q)
{
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    const double R[3][3] = {
        { 1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y) },
        { 2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x) },
        { 2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y) },
    };
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) F->r[j][i] = (dh_q30)llround(R[i][j] * Q30);
}

/* q = q * (a small rotation of deg degrees about a random axis) */
static void quat_turn(double *q, double deg)
{
    double ax[3], n = 0.0, h = deg / RAD2DEG / 2.0, r[4], o[4];
    int i;
    for (i = 0; i < 3; i++) {
        ax[i] = dht_rand_uniform(-1.0, 1.0);
        n += ax[i] * ax[i];
    }
    n = sqrt(n);
    if (n < 1e-3) return;
    r[0] = cos(h);
    for (i = 0; i < 3; i++) r[1 + i] = sin(h) * ax[i] / n;
    o[0] = q[0] * r[0] - q[1] * r[1] - q[2] * r[2] - q[3] * r[3];
    o[1] = q[0] * r[1] + q[1] * r[0] + q[2] * r[3] - q[3] * r[2];
    o[2] = q[0] * r[2] - q[1] * r[3] + q[2] * r[0] + q[3] * r[1];
    o[3] = q[0] * r[3] + q[1] * r[2] - q[2] * r[1] + q[3] * r[0];
    for (i = 0; i < 4; i++) q[i] = o[i];
}

/* n + 1 random corner frames (file comment) and the n lines */
static void draw_lines(uint32_t n)
{
    double q[4] = { 1.0, 0.0, 0.0, 0.0 }, p[3], d[3] = { 100.0, 0.0, 0.0 };
    uint32_t k;
    int i;
    quat_turn(q, dht_rand_uniform(0.0, 180.0));
    for (i = 0; i < 3; i++) p[i] = dht_rand_uniform(-300.0, 300.0);
    for (k = 0; k <= n; k++) {
        if (k > 0u) {
            const double u = dht_rand_uniform(0.0, 1.0);
            if (u < 0.1) {
                /* length 0 */
            } else if (u < 0.2) {
                for (i = 0; i < 3; i++) p[i] += d[i] * dht_rand_uniform(0.1, 1.0);
            } else {
                for (i = 0; i < 3; i++) {
                    d[i] = dht_rand_uniform(-400.0, 400.0);
                    p[i] += d[i];
                }
            }
            for (i = 0; i < 3; i++) p[i] = fmin(fmax(p[i], -500.0), 500.0);
            if (dht_rand_uniform(0.0, 1.0) > 0.2) quat_turn(q, dht_rand_uniform(0.0, 20.0));
        }
        rot_of_quat(&fr[k], q);
        for (i = 0; i < 3; i++) fr[k].p[i] = (dh_qpos)llround(p[i] * QPOS);
    }
    for (k = 0; k < n; k++) DHT_EQ_INT(dh_path_line_q(&line[k], &fr[k], &fr[k + 1u]), DH_OK);
}

static void rand_lim(dh_cart_limits_q *lim)
{
    lim->vmax = (int32_t)(dht_rand_uniform(50.0, 1000.0) * QPOS);
    lim->amax = (int32_t)(dht_rand_uniform(200.0, 1500.0) * QPOS);
    lim->wmax = (int32_t)(dht_rand_uniform(20.0, 180.0) * 65536.0);
    lim->wdmax = (int32_t)(dht_rand_uniform(50.0, 1000.0) * 65536.0);
}

/* position (mm) and rotation (row-major) of a fixed frame, in double */
static void sample_of(const dh_frame_q *T, double h[12])
{
    int i, j;
    for (i = 0; i < 3; i++) {
        h[i] = T->p[i] / QPOS;
        for (j = 0; j < 3; j++) h[3 + 3 * i + j] = T->r[j][i] / Q30;
    }
}

/* v = the rotation vector (degrees) of Rb Ra^T (R row-major) */
static void rotvec(const double *Ra, const double *Rb, double v[3])
{
    double M[3][3], s[3], n, c, th;
    int i, j, k;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            M[i][j] = 0.0;
            for (k = 0; k < 3; k++) M[i][j] += Rb[3 * i + k] * Ra[3 * j + k];
        }
    s[0] = 0.5 * (M[2][1] - M[1][2]);
    s[1] = 0.5 * (M[0][2] - M[2][0]);
    s[2] = 0.5 * (M[1][0] - M[0][1]);
    n = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    c = 0.5 * (M[0][0] + M[1][1] + M[2][2] - 1.0);
    th = atan2(n, c) * RAD2DEG;
    for (i = 0; i < 3; i++) v[i] = (n > 0.0) ? th * s[i] / n : 0.0;
}

static double norm3(const double a[3])
{
    return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

static double limd(int32_t x, double unit)
{
    return (double)x / unit;
}

/* the acceleration (linear, angular) of h[0], h[w], h[2 w], hdt apart */
static void check_acc(const double (*h)[12], int w, double hdt, const dh_cart_limits_q *lim, double N)
{
    double a[3], b[3], x;
    int k;
    for (k = 0; k < 3; k++) a[k] = h[0][k] - 2.0 * h[w][k] + h[2 * w][k];
    x = norm3(a);
    dht_reach_max("blendq.acc_ratio", x / (hdt * hdt) / limd(lim->amax, QPOS));
    DHT_TRUE_MSG(x <= limd(lim->amax, QPOS) * hdt * hdt * (1.0 + REL) + 4.0 * N,
                 "acceleration %.9g over %.9g (%.3g s)", x / (hdt * hdt), limd(lim->amax, QPOS), hdt);
    rotvec(&h[w][3], &h[0][3], a);
    rotvec(&h[w][3], &h[2 * w][3], b);
    for (k = 0; k < 3; k++) a[k] += b[k];
    x = norm3(a);
    DHT_TRUE_MSG(x <= limd(lim->wdmax, 65536.0) * hdt * hdt * (1.0 + REL) + 4.0 * ANG_NOISE,
                 "angular acceleration %.9g over %.9g (%.3g s)", x / (hdt * hdt), limd(lim->wdmax, 65536.0), hdt);
}

/* the speed (linear, angular) between h0 and h1, hdt apart */
static void check_speed(const double *h0, const double *h1, double hdt, const dh_cart_limits_q *lim, double N)
{
    double a[3], x;
    int k;
    for (k = 0; k < 3; k++) a[k] = h1[k] - h0[k];
    x = norm3(a);
    dht_reach_max("blendq.speed_ratio", x / hdt / limd(lim->vmax, QPOS));
    DHT_TRUE_MSG(x <= limd(lim->vmax, QPOS) * hdt * (1.0 + REL) + 2.0 * N, "speed %.9g over %.9g (%.3g s)", x / hdt,
                 limd(lim->vmax, QPOS), hdt);
    rotvec(&h1[3], &h0[3], a);
    x = norm3(a);
    DHT_TRUE_MSG(x <= limd(lim->wmax, 65536.0) * hdt * (1.0 + REL) + 2.0 * ANG_NOISE,
                 "angular speed %.9g over %.9g", x / hdt, limd(lim->wmax, 65536.0));
}

/* the finite differences about the sample h at t (windows of WS periods
 * every period and of W periods every WD, the samples t +- w evaluated
 * here: no ring of samples, so the micro:bit's RAM holds the test) */
static void check_fd(const dh_blend_seq_q *sq, uint32_t t, const double *h, const dh_cart_limits_q *lim, double N)
{
    static const int win[2] = { WS, W };
    dh_frame_q T;
    int i;
    DHT_EQ_INT(dh_blend_seq_eval_q(sq, t + DT_US, &T), DH_OK);
    sample_of(&T, sp[2]);
    check_speed(h, sp[2], 1e-3, lim, N);
    for (i = 0; i < 2; i++) {
        const uint32_t w = (uint32_t)win[i] * DT_US;
        if (t < w || (i == 1 && (t / DT_US) % WD != 0)) continue;
        DHT_EQ_INT(dh_blend_seq_eval_q(sq, t - w, &T), DH_OK);
        sample_of(&T, sp[0]);
        memcpy(sp[1], h, sizeof sp[1]);
        DHT_EQ_INT(dh_blend_seq_eval_q(sq, t + w, &T), DH_OK);
        sample_of(&T, sp[2]);
        check_speed(sp[0], sp[1], win[i] * 1e-3, lim, N);
        check_acc((const double (*)[12])sp, 1, win[i] * 1e-3, lim, N);
    }
}

/* distance of x (mm) from line k's segment */
static double seg_dist(uint32_t k, const double x[3])
{
    double a[3], d[3], r[3], e[3], dd = 0.0, s = 0.0;
    int i;
    for (i = 0; i < 3; i++) {
        a[i] = fr[k].p[i] / QPOS;
        d[i] = fr[k + 1u].p[i] / QPOS - a[i];
        r[i] = x[i] - a[i];
        dd += d[i] * d[i];
        s += r[i] * d[i];
    }
    s = (dd > 0.0) ? fmin(fmax(s / dd, 0.0), 1.0) : 0.0;
    for (i = 0; i < 3; i++) e[i] = r[i] - s * d[i];
    return norm3(e);
}

/* the point at t on its line, or within the radius in an overlap */
static void check_path(const dh_blend_seq_q *sq, uint32_t t, const double x[3])
{
    uint32_t k = 0u;
    double c[3], d;
    int i;
    while (k + 1u < sq->n && seg[k + 1u].t0 <= t) k++;
    if (k > 0u && seg[k].dur[0] > 0u && t - seg[k].t0 < seg[k].dur[0]) {
        for (i = 0; i < 3; i++) c[i] = x[i] - fr[k].p[i] / QPOS;
        d = norm3(c);
        dht_reach_max("blendq.corner_ratio", d / (radius[k - 1u] / QPOS));
        DHT_TRUE_MSG(d <= seg[k - 1u].dev / QPOS + 2.0 / QPOS + 32.0 / Q30 * (line[k - 1u].length + line[k].length) / QPOS &&
                         d <= radius[k - 1u] / QPOS + POS_TOL,
                     "t %lu: %.9g from corner %u, dev %.9g radius %.9g",
                     (unsigned long)t, d, (unsigned)k, seg[k - 1u].dev / QPOS, radius[k - 1u] / QPOS);
        return;
    }
    d = seg_dist(k, x);
    dht_reach_max("blendq.line_dist_lsb", d * QPOS);
    DHT_TRUE_MSG(d <= 1.0 / QPOS, "t %lu: %.9g off line %u", (unsigned long)t, d, (unsigned)k);
}

/* the time-optimal trapezoid of s within the double rates of line k */
static double rest_T(uint32_t k, const dh_cart_limits_q *lim)
{
    const double L = line[k].length / QPOS, th = line[k].angle / 65536.0;
    double V = 1e300, A = 1e300;
    if (L > 0.0) {
        V = fmin(V, limd(lim->vmax, QPOS) / L);
        A = fmin(A, limd(lim->amax, QPOS) / L);
    }
    if (th > 0.0) {
        V = fmin(V, limd(lim->wmax, 65536.0) / th);
        A = fmin(A, limd(lim->wdmax, 65536.0) / th);
    }
    if (!(L > 0.0) && !(th > 0.0)) return 0.0;
    return (V * V <= A) ? 1.0 / V + V / A : 2.0 * sqrt(1.0 / A);
}

static void one_sequence(void)
{
    const uint32_t n = 2u + dht_rand_u32() % (NMAX - 1u);
    dh_cart_limits_q lim;
    dh_blend_seq_q sq;
    dh_frame_q T;
    double N = 0.0, x[3], Lmax = 0.0;
    uint32_t k, t, rest = 0u, blended = 0u;
    int i;
    draw_lines(n);
    rand_lim(&lim);
    for (k = 0; k < n; k++) {
        radius[k] = 0;
        if (dht_rand_uniform(0.0, 1.0) > 0.2) radius[k] = (dh_qpos)(dht_rand_uniform(0.1, 50.0) * QPOS);
        if (line[k].length / QPOS > Lmax) Lmax = line[k].length / QPOS;
    }
    /* at rest: each line's scaling against the double trapezoid */
    {
        dh_qpos zero[NMAX] = { 0 };
        DHT_EQ_INT(dh_blend_seq_plan_q(&sq, seg, line, n, zero, &lim), DH_OK);
        for (k = 0; k < n; k++) {
            const double Td = rest_T(k, &lim) * 1e6;
            DHT_EQ_INT(seg[k].dur[0], 0);
            DHT_EQ_INT(seg[k].dur[4], 0);
            DHT_TRUE_MSG(seg[k].T >= Td - 1e-6 * Td && seg[k].T <= Td * (1.0 + 1.0 / 512.0) + 4.0,
                         "line %u: rest %lu us, optimal %.3f us", (unsigned)k, (unsigned long)seg[k].T, Td);
            rest += seg[k].T;
        }
        DHT_EQ_INT(sq.T, rest);
    }
    DHT_EQ_INT(dh_blend_seq_plan_q(&sq, seg, line, n, radius, &lim), DH_OK);
    for (k = 0; k + 1u < n; k++) {
        DHT_EQ_INT(seg[k].dur[4], seg[k + 1u].dur[0]);
        DHT_TRUE(seg[k].dev <= radius[k]);
        if (seg[k].dur[4] > 0u) blended++;
    }
    DHT_TRUE_MSG(sq.T <= rest && (blended == 0u || sq.T < rest), "T %lu, at rest %lu, %u blended",
                 (unsigned long)sq.T, (unsigned long)rest, (unsigned)blended);
    dht_reach_max("blendq.blended", (double)blended);
    /* noise of a sample: 2 LSB and 16 2^-30 of two lines (the contract) */
    N = 2.0 / QPOS + 16.0 / Q30 * 2.0 * Lmax;
    DHT_EQ_INT(dh_blend_seq_eval_q(&sq, 0u, &T), DH_OK);
    DHT_TRUE(memcmp(&T, &fr[0], sizeof T) == 0);
    DHT_EQ_INT(dh_blend_seq_eval_q(&sq, sq.T, &T), DH_OK);
    DHT_TRUE(memcmp(&T, &fr[n], sizeof T) == 0);
    for (t = 0u;; t += DT_US) {
        const uint32_t tt = (t < sq.T) ? t : sq.T;
        DHT_EQ_INT(dh_blend_seq_eval_q(&sq, tt, &T), DH_OK);
        for (i = 0; i < 3; i++) x[i] = T.p[i] / QPOS;
        check_path(&sq, tt, x);
        sample_of(&T, cur);
        check_fd(&sq, t, cur, &lim, N);
        if (t >= sq.T + (uint32_t)(W * DT_US)) break; /* at rest at the end for a window */
    }
}

static void sequences(void)
{
    int i;
    for (i = 0; i < DHT_ITER(40); i++) one_sequence();
}

static void statuses(void)
{
    dh_cart_limits_q lim = { 100 << 16, 1000 << 16, 90 << 16, 500 << 16 };
    dh_blend_seq_q sq;
    dh_path_q arc;
    dh_qpos via[3];
    dh_qpos r[NMAX] = { 0 };
    draw_lines(3u);
    memset(&sq, 0x5A, sizeof sq);
    DHT_EQ_INT(dh_blend_seq_plan_q(&sq, seg, line, 0u, r, &lim), DH_ERR_ARG);
    r[0] = -1;
    DHT_EQ_INT(dh_blend_seq_plan_q(&sq, seg, line, 3u, r, &lim), DH_ERR_ARG);
    r[0] = 0;
    lim.wdmax = 0;
    DHT_EQ_INT(dh_blend_seq_plan_q(&sq, seg, line, 3u, r, &lim), DH_ERR_ARG);
    lim.wdmax = 500 << 16;
    /* a line that does not start at the end of the one before */
    line[1].A.p[0] += 1;
    DHT_EQ_INT(dh_blend_seq_plan_q(&sq, seg, line, 3u, r, &lim), DH_ERR_ARG);
    line[1].A.p[0] -= 1;
    /* an arc into a line: blended (its corner's dev within the radius);
     * an arc whose radius is not positive holds no arc */
    {
        dh_frame_q F[3];
        dh_path_q pa[2];
        dh_qpos ra[2] = { 10 << 16, 0 };
        int k;
        for (k = 0; k < 3; k++) dh_frame_identity_q(&F[k]);
        F[1].p[0] = 100 << 16;
        F[2].p[0] = 100 << 16;
        F[2].p[1] = 100 << 16;
        via[0] = 50 << 16;
        via[1] = 0;
        via[2] = 30 << 16;
        DHT_EQ_INT(dh_path_arc_q(&arc, &F[0], via, &F[1]), DH_OK);
        pa[0] = arc;
        DHT_EQ_INT(dh_path_line_q(&pa[1], &F[1], &F[2]), DH_OK);
        DHT_EQ_INT(dh_blend_seq_plan_q(&sq, seg, pa, 2u, ra, &lim), DH_OK);
        DHT_TRUE(seg[0].dur[4] > 0u && seg[0].dev > 0 && seg[0].dev <= ra[0]);
        pa[0].radius = 0;
        DHT_EQ_INT(dh_blend_seq_plan_q(&sq, seg, pa, 2u, ra, &lim), DH_ERR_ARG);
        memset(&sq, 0x5A, sizeof sq);
    }
    /* no path */
    memset(&line[2], 0, sizeof line[2]);
    DHT_EQ_INT(dh_blend_seq_plan_q(&sq, seg, line, 3u, r, &lim), DH_ERR_ARG);
    {
        dh_blend_seq_q probe;
        memset(&probe, 0x5A, sizeof probe);
        DHT_TRUE(memcmp(&sq, &probe, sizeof sq) == 0);
    }
    /* a sequence of no lines evaluates to DH_ERR_ARG */
    sq.n = 0u;
    {
        dh_frame_q T;
        DHT_EQ_INT(dh_blend_seq_eval_q(&sq, 0u, &T), DH_ERR_ARG);
    }
}

static const dht_case cases[] = {
    DHT_CASE(sequences),
    DHT_CASE(statuses),
};
DHT_MAIN(cases)
