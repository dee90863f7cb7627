/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_blend.c - two line moves blended at their corner
 * (dh_blend_plan_f32, dh_blend_eval_f32) against references computed here
 * in double from the float inputs: the distance of the tool point from
 * each segment and from the corner, the rotation vector between two
 * sampled rotations, the rest-to-rest trapezoids' minimum durations.
 *
 * Random corners on UR5-scale distances (segments 0.05 to 0.6 m, the
 * corner within 0.5 m of the base, angles between the directions 1 to 179
 * degrees), each line turning the tool by up to 60 degrees about its own
 * axis, sampled at 1 kHz:
 * - outside the overlap the position is on its segment within 1e-6 m,
 *   inside it within the radius (and bl.dev) of the corner, plus 1e-6 m;
 * - speed, TOTAL acceleration, angular speed and angular acceleration by
 *   finite differences within their limits times 1 + 1e-3, over the least
 *   window for which the rounding of the samples (8 ulp of the largest
 *   position, 6e-4 degrees of rotation) is at most 2.5e-4 of the limit;
 *   the angular ones from rotation vectors log(R(t +- w) R(t)^T) about the
 *   middle sample (their sum over w^2 is the angular acceleration, with no
 *   cubic term of the composed rotations);
 * - the pose steps by at most one period of the speed limits (plus the
 *   samples' rounding) everywhere;
 * - the pair is shorter than the two rest-to-rest trapezoids, whose
 *   minimum durations are computed here from the lines' lengths and
 *   angles.
 * The same for corners where either or both moves are arcs (through a via
 * point off the chord's middle by 0.1 to 0.4 of the chord, across it in a
 * random direction): on the arc within 1e-6 m means on the circle of the
 * path dh_path_arc_f32 made (centre p_A - u0, normal n) and within its
 * sweep (test_path.c bounds that circle against the double one through
 * the three points); the durations are compared with the two moves'
 * dh_path_move_f32 trapezoids (an arc's own rest-to-rest minimum under
 * its centripetal acceleration, test_path.c); the finite differences
 * include the arcs' centripetal accelerations.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_ref.h"
#include "support_robots.h"
#include "dhmath/motion.h"
#include "dhmath/mat4.h"

#define HZ 1000.0
#define REL_FD 1e-3
#define NOISE_FRAC 2.5e-4
#define POS_TOL 1e-6   /* m */
#define ANG_NOISE 6e-4 /* degrees */

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* distance of x from the path p: from its segment (a line), from the
 * circle of centre p_A - u0 and radius |u0| in the plane of normal n
 * within the sweep, else from the nearer end (an arc) */
static double seg_dist(const double a[3], const double b[3], const double x[3]);
static double path_dist(const dh_path_f32 *p, const double x[3])
{
    double a[3], b[3], r[3], n[3], u[3], w[3], z, nn = 0.0, rho, ph, sw = (double)p->sweep / 57.29577951308232;
    int i;
    for (i = 0; i < 3; i++) {
        a[i] = DH_M4(&p->A, i, 3);
        b[i] = DH_M4(&p->B, i, 3);
    }
    if (p->kind != (uint32_t)DH_PATH_ARC) return seg_dist(a, b, x);
    for (i = 0; i < 3; i++) nn += (double)p->n[i] * p->n[i];
    for (i = 0; i < 3; i++) {
        n[i] = p->n[i] / sqrt(nn);
        u[i] = p->u0[i];
        r[i] = x[i] - (a[i] - u[i]);
    }
    z = dot3(r, n);
    rho = sqrt(dot3(u, u));
    for (i = 0; i < 3; i++) r[i] -= z * n[i];
    w[0] = n[1] * u[2] - n[2] * u[1];
    w[1] = n[2] * u[0] - n[0] * u[2];
    w[2] = n[0] * u[1] - n[1] * u[0];
    ph = atan2(dot3(r, w), dot3(r, u));
    if (ph < -0.5 * (2.0 * 3.14159265358979323846 - sw)) ph += 2.0 * 3.14159265358979323846;
    if (ph >= 0.0 && ph <= sw) return sqrt(z * z + (sqrt(dot3(r, r)) - rho) * (sqrt(dot3(r, r)) - rho));
    for (i = 0; i < 3; i++) r[i] = x[i] - ((ph < 0.0) ? a[i] : b[i]);
    return sqrt(dot3(r, r));
}

/* p (a line) replaced by the arc between its frames through a via point
 * off the chord's middle by 0.1 to 0.4 of the chord, across it */
static void arc_of(dh_path_f32 *p)
{
    const dh_mat4_f32 A = p->A, B = p->B;
    double d[3], e[3], c, x, h;
    float via[3];
    int i;
    for (i = 0; i < 3; i++) d[i] = (double)DH_M4(&B, i, 3) - DH_M4(&A, i, 3);
    c = dot3(d, d);
    do {
        dhr_rand_unit3(e);
        x = dot3(e, d) / c;
        for (i = 0; i < 3; i++) e[i] -= x * d[i];
        h = dot3(e, e);
    } while (h < 0.01);
    x = dht_rand_uniform(0.1, 0.4) * sqrt(c / h);
    for (i = 0; i < 3; i++) via[i] = (float)(0.5 * ((double)DH_M4(&A, i, 3) + DH_M4(&B, i, 3)) + x * e[i]);
    DHT_EQ_INT(dh_path_arc_f32(p, &A, via, &B), DH_OK);
}

/* the duration of p's rest-to-rest trapezoid within lim (dh_path_move_f32) */
static double path_trr(const dh_path_f32 *p, const dh_cart_limits_f32 *lim)
{
    dh_profile_f32 prof;
    DHT_EQ_INT(dh_path_move_f32(&prof, p, lim), DH_OK);
    return (double)prof.T;
}

/* distance of x from the segment [a, b] */
static double seg_dist(const double a[3], const double b[3], const double x[3])
{
    double d[3], r[3], dd, s, e[3];
    int i;
    for (i = 0; i < 3; i++) {
        d[i] = b[i] - a[i];
        r[i] = x[i] - a[i];
    }
    dd = dot3(d, d);
    s = (dd > 0.0) ? dot3(r, d) / dd : 0.0;
    if (s < 0.0) s = 0.0;
    if (s > 1.0) s = 1.0;
    for (i = 0; i < 3; i++) e[i] = r[i] - s * d[i];
    return sqrt(dot3(e, e));
}

/* the rotation vector (degrees, world frame) of R_Y R_X^T */
static void rot_vec(const dh_mat4_f32 *X, const dh_mat4_f32 *Y, double rv[3])
{
    double M[3][3], v[3], sn, cs, th, f;
    int i, j, k;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            M[i][j] = 0.0;
            for (k = 0; k < 3; k++) M[i][j] += (double)DH_M4(Y, i, k) * DH_M4(X, j, k);
        }
    v[0] = M[2][1] - M[1][2];
    v[1] = M[0][2] - M[2][0];
    v[2] = M[1][0] - M[0][1];
    sn = 0.5 * sqrt(dot3(v, v));
    cs = 0.5 * (M[0][0] + M[1][1] + M[2][2] - 1.0);
    th = atan2(sn, cs);
    f = (sn > 1e-12) ? th / (2.0 * sn) : 0.5;
    for (i = 0; i < 3; i++) rv[i] = dhr_rad2deg(f * v[i]);
}

static double trap_tmin(double v, double a)
{
    return (1.0 >= v * v / a) ? 1.0 / v + v / a : 2.0 * sqrt(1.0 / a);
}

/* the rest-to-rest trapezoid's minimum duration of a line of length L and
 * angle th (degrees) within lim */
static double line_tmin(double L, double th, const dh_cart_limits_f32 *lim)
{
    double v = 1e300, a = 1e300;
    if (L > 0.0) {
        v = fmin(v, lim->vmax / L);
        a = fmin(a, lim->amax / L);
    }
    if (th > 0.0) {
        v = fmin(v, lim->wmax / th);
        a = fmin(a, lim->wdmax / th);
    }
    return (L > 0.0 || th > 0.0) ? trap_tmin(v, a) : 0.0;
}

typedef struct {
    dh_path_f32 p1, p2;
    double a[3], c[3], b[3];  /* the float positions */
    double S;                 /* the largest position magnitude */
    double th1, th2;          /* the lines' rotation angles (degrees) from the float rotations */
} corner;

static void pos_of(const dh_mat4_f32 *T, double p[3])
{
    int i;
    for (i = 0; i < 3; i++) p[i] = DH_M4(T, i, 3);
}

/* a corner of angle deg between the directions, segments L1, L2, the
 * tool turning by up to rmax degrees along each */
static void make_corner(corner *k, double deg, double L1, double L2, double rmax)
{
    dhr_mat4 RA, RC, RB, X;
    dh_mat4_f32 A, C, B;
    double d1[3], n[3], d2[3], c[3], ax[3], t, cs, sn;
    int i;
    dhr_rand_unit3(d1);
    do {
        dhr_rand_unit3(n);
        t = dot3(n, d1);
        for (i = 0; i < 3; i++) n[i] -= t * d1[i];
    } while (dot3(n, n) < 0.01);
    t = sqrt(dot3(n, n));
    dhr_sincos_deg(deg, &sn, &cs);
    for (i = 0; i < 3; i++) {
        n[i] /= t;
        d2[i] = cs * d1[i] + sn * n[i];
        c[i] = dht_rand_uniform(-0.3, 0.3);
    }
    dhr_rand_rigid(0.0, &RA);
    dhr_rand_unit3(ax);
    dhr_rot_axis(ax[0], ax[1], ax[2], dht_rand_uniform(0.0, rmax), &X);
    dhr_mul(&X, &RA, &RC);
    dhr_rand_unit3(ax);
    dhr_rot_axis(ax[0], ax[1], ax[2], dht_rand_uniform(0.0, rmax), &X);
    dhr_mul(&X, &RC, &RB);
    for (i = 0; i < 3; i++) {
        DHR_M4(&RA, i, 3) = c[i] - L1 * d1[i];
        DHR_M4(&RC, i, 3) = c[i];
        DHR_M4(&RB, i, 3) = c[i] + L2 * d2[i];
    }
    dhr_to_f32(&RA, &A);
    dhr_to_f32(&RC, &C);
    dhr_to_f32(&RB, &B);
    DHT_EQ_INT(dh_path_line_f32(&k->p1, &A, &C), DH_OK);
    DHT_EQ_INT(dh_path_line_f32(&k->p2, &C, &B), DH_OK);
    pos_of(&A, k->a);
    pos_of(&C, k->c);
    pos_of(&B, k->b);
    k->S = 0.0;
    for (i = 0; i < 3; i++) k->S = fmax(k->S, fmax(fabs(k->a[i]), fmax(fabs(k->b[i]), fabs(k->c[i]))));
    rot_vec(&A, &C, ax);
    k->th1 = sqrt(dot3(ax, ax));
    rot_vec(&C, &B, ax);
    k->th2 = sqrt(dot3(ax, ax));
}

static void eval_at(const dh_blend_f32 *bl, double t, dh_mat4_f32 *T)
{
    DHT_EQ_INT(dh_blend_eval_f32(bl, (float)t, T), DH_OK);
}

/* what the finite differences sample: a pair (bl) or a sequence (sq) */
typedef struct {
    const dh_blend_f32 *bl;
    const dh_blend_seq_f32 *sq;
} source;

static void src_at(const source *src, double t, dh_mat4_f32 *T)
{
    if (src->sq != NULL)
        DHT_EQ_INT(dh_blend_seq_eval_f32(src->sq, (float)t, T), DH_OK);
    else
        eval_at(src->bl, t, T);
}

static double src_T(const source *src)
{
    return (src->sq != NULL) ? (double)src->sq->T : (double)src->bl->T;
}

/* the least window (periods) over which a per-sample noise perturbs the
 * finite difference of the given order by at most NOISE_FRAC of lim */
static long fd_window(double noise, int order, double lim)
{
    double wh = pow(ldexp(noise, order) / (NOISE_FRAC * lim), 1.0 / order);
    long w = (long)ceil(wh * HZ);
    return (w < 2) ? 2 : w;
}

/* the largest ratio to lim of the finite difference of the given order
 * (1 speed, 2 acceleration, 3 jerk) of the position (ang 0) or of the
 * rotation (ang 1; order 3 only for rotations about one world axis, whose
 * rotation vectors add) over windows of w periods */
static double fd_ratio(const source *src, int order, int ang, long w, double lim)
{
    double worst = 0.0, h = 1.0 / HZ, x[3][4], ra[3], rb[3], f, d;
    long k, kend = (long)ceil(src_T(src) * HZ) + 2;
    int i, j;
    dh_mat4_f32 T[4];
    for (k = -2 * w; k <= kend; k++) {
        for (j = 0; j <= order; j++) {
            src_at(src, (double)(k + j * w) * h, &T[j]);
            for (i = 0; i < 3; i++) x[i][j] = DH_M4(&T[j], i, 3);
        }
        f = 0.0;
        if (ang && order == 3) {
            /* about one world axis only: the rotation vectors from T[0] add */
            for (i = 0; i < 3; i++) rb[i] = 0.0;
            for (j = 1; j <= 3; j++) {
                rot_vec(&T[0], &T[j], ra);
                for (i = 0; i < 3; i++) rb[i] += ((j == 3) ? 1.0 : ((j == 2) ? -3.0 : 3.0)) * ra[i];
            }
            f = sqrt(dot3(rb, rb));
        } else if (ang && order == 1) {
            rot_vec(&T[0], &T[1], ra);
            f = sqrt(dot3(ra, ra));
        } else if (ang) {
            rot_vec(&T[1], &T[0], ra);
            rot_vec(&T[1], &T[2], rb);
            for (i = 0; i < 3; i++) rb[i] += ra[i];
            f = sqrt(dot3(rb, rb));
        } else {
            for (i = 0; i < 3; i++) {
                if (order == 3)
                    d = x[i][3] - 3.0 * x[i][2] + 3.0 * x[i][1] - x[i][0];
                else
                    d = (order == 1) ? x[i][1] - x[i][0] : x[i][2] - 2.0 * x[i][1] + x[i][0];
                f += d * d;
            }
            f = sqrt(f);
        }
        f /= pow((double)w * h, order);
        if (f / lim > worst) worst = f / lim;
    }
    return worst;
}

/* the step from P to T (T's position p) within one period of the linear
 * and angular speed limits, up to the finite differences' allowance and
 * the samples' rounding (posn in position, ANG_NOISE in angle) */
static void step_check(const dh_mat4_f32 *P, const dh_mat4_f32 *T, const double p[3], const dh_cart_limits_f32 *lim,
                       double posn, double t)
{
    const double h = 1.0 / HZ;
    double q[3], rv[3], dp;
    int j;
    pos_of(P, q);
    for (j = 0; j < 3; j++) q[j] -= p[j];
    dp = sqrt(dot3(q, q));
    DHT_TRUE_MSG(dp <= lim->vmax * h * (1.0 + REL_FD) + 2.0 * posn, "t %.9g: step %.3g m", t, dp);
    rot_vec(P, T, rv);
    dp = sqrt(dot3(rv, rv));
    DHT_TRUE_MSG(dp <= lim->wmax * h * (1.0 + REL_FD) + 2.0 * ANG_NOISE, "t %.9g: step %.3g deg", t, dp);
}

/* every sample on its segment outside the overlap and near the corner
 * inside; every step within one period of the speed limits */
static void path_check(const dh_blend_f32 *bl, const corner *k, const dh_cart_limits_f32 *lim, double radius)
{
    double h = 1.0 / HZ, t, p[3], q[3], e, posn = 8.0 * dhr_ulp_f32(k->S);
    long i, n = (long)ceil((double)bl->T * HZ) + 1;
    int j;
    dh_mat4_f32 T, P;
    eval_at(bl, 0.0, &P);
    for (i = 1; i <= n; i++) {
        t = (double)i * h;
        eval_at(bl, t, &T);
        pos_of(&T, p);
        if ((float)t <= bl->t0) {
            e = path_dist(&k->p1, p);
            DHT_TRUE_MSG(e <= POS_TOL, "t %.9g (t0 %.9g): %.3g m off the first line", t, (double)bl->t0, e);
        } else if ((float)t >= bl->t0 + bl->tb) {
            e = path_dist(&k->p2, p);
            DHT_TRUE_MSG(e <= POS_TOL, "t %.9g: %.3g m off the second line", t, e);
        } else {
            for (j = 0; j < 3; j++) q[j] = p[j] - k->c[j];
            e = sqrt(dot3(q, q));
            DHT_TRUE_MSG(e <= radius + POS_TOL && e <= (double)bl->dev + POS_TOL,
                         "t %.9g: %.9g m from the corner (radius %.9g, dev %.9g)", t, e, radius, (double)bl->dev);
            dht_reach_max("overlap.dev_frac", e / radius);
        }
        step_check(&P, &T, p, lim, posn, t);
        P = T;
    }
    DHT_TRUE(memcmp(&T, &k->p2.B, sizeof T) == 0);
}

/* speed and acceleration, linear and (ang 1) angular, of src within lim by
 * finite differences; S the largest position magnitude */
static void src_limits(const source *src, double S, int ang, const dh_cart_limits_f32 *lim)
{
    double plim[2], alim[2], wr, posn = 8.0 * dhr_ulp_f32(S);
    long w;
    int o;
    plim[0] = lim->vmax;
    plim[1] = lim->amax;
    alim[0] = lim->wmax;
    alim[1] = lim->wdmax;
    for (o = 1; o <= 2; o++) {
        w = fd_window(posn, o, plim[o - 1]);
        wr = fd_ratio(src, o, 0, w, plim[o - 1]);
        DHT_TRUE_MSG(wr <= 1.0 + REL_FD, "linear derivative %d: %.9g x its limit (window %ld ms)", o, wr, w);
        dht_reach_max(o == 1 ? "lin.v" : "lin.a", wr);
        if (ang) {
            w = fd_window(ANG_NOISE, o, alim[o - 1]);
            wr = fd_ratio(src, o, 1, w, alim[o - 1]);
            DHT_TRUE_MSG(wr <= 1.0 + REL_FD, "angular derivative %d: %.9g x its limit (window %ld ms)", o, wr, w);
            dht_reach_max(o == 1 ? "ang.v" : "ang.a", wr);
        }
    }
}

static void limits_check(const dh_blend_f32 *bl, const corner *k, const dh_cart_limits_f32 *lim)
{
    source src;
    src.bl = bl;
    src.sq = NULL;
    src_limits(&src, k->S, k->th1 > 0.0 || k->th2 > 0.0, lim);
}

/* one random corner (the file's comment); arcs: 0 two lines, else bit 0
 * the first move and bit 1 the second an arc */
static void corner_case(int it, int arcs)
{
    corner k;
    dh_blend_f32 bl;
    dh_cart_limits_f32 lim;
    dh_mat4_f32 T;
    double deg = (it == 0) ? 1.0 : (it == 1) ? 179.0 : dht_rand_uniform(1.0, 179.0);
    double radius = pow(10.0, dht_rand_uniform(-3.0, -1.0)), Trr;
    make_corner(&k, deg, dht_rand_uniform(0.05, 0.6), dht_rand_uniform(0.05, 0.6), 60.0);
    lim.vmax = (float)dht_rand_uniform(0.1, 1.0);
    lim.amax = (float)dht_rand_uniform(1.0, 10.0);
    lim.wmax = (float)dht_rand_uniform(30.0, 90.0);
    lim.wdmax = (float)dht_rand_uniform(300.0, 2000.0);
    if (arcs & 1) arc_of(&k.p1);
    if (arcs & 2) arc_of(&k.p2);
    DHT_EQ_INT(dh_blend_plan_f32(&bl, &k.p1, &k.p2, &lim, (float)radius), DH_OK);
    DHT_TRUE(bl.t0 >= 0.0f && (double)bl.dev <= radius);
    dht_reach_min(arcs ? "arc.tb" : "tb", (double)bl.tb);
    /* exact ends */
    eval_at(&bl, 0.0, &T);
    DHT_TRUE(memcmp(&T, &k.p1.A, sizeof T) == 0);
    eval_at(&bl, -1.0, &T);
    DHT_TRUE(memcmp(&T, &k.p1.A, sizeof T) == 0);
    eval_at(&bl, (double)bl.T, &T);
    DHT_TRUE(memcmp(&T, &k.p2.B, sizeof T) == 0);
    eval_at(&bl, (double)bl.T + 1.0, &T);
    DHT_TRUE(memcmp(&T, &k.p2.B, sizeof T) == 0);
    /* shorter than the two rest-to-rest moves */
    if (arcs) {
        Trr = path_trr(&k.p1, &lim) + path_trr(&k.p2, &lim);
    } else {
        Trr = line_tmin(sqrt((k.c[0] - k.a[0]) * (k.c[0] - k.a[0]) + (k.c[1] - k.a[1]) * (k.c[1] - k.a[1]) +
                             (k.c[2] - k.a[2]) * (k.c[2] - k.a[2])), k.th1, &lim) +
              line_tmin(sqrt((k.b[0] - k.c[0]) * (k.b[0] - k.c[0]) + (k.b[1] - k.c[1]) * (k.b[1] - k.c[1]) +
                             (k.b[2] - k.c[2]) * (k.b[2] - k.c[2])), k.th2, &lim);
    }
    /* a blend that would not be shorter is not made (tb 0: back to back) */
    DHT_TRUE_MSG((bl.tb > 0.0f) ? (double)bl.T < Trr : (double)bl.T <= Trr * (1.0 + 1e-6),
                 "blended %.9g s (tb %.9g), rest to rest %.9g s", (double)bl.T, (double)bl.tb, Trr);
    dht_reach_max(arcs ? "arc.saving_frac" : "saving_frac", (Trr - (double)bl.T) / Trr);
    path_check(&bl, &k, &lim, radius);
    limits_check(&bl, &k, &lim);
}

static void random_corners(void)
{
    int it, n = DHT_ITER(40);
    for (it = 0; it < n; it++) corner_case(it, 0);
}

/* corners with an arc: the first move, the second or both */
static void random_arc_corners(void)
{
    int it, n = DHT_ITER(40);
    for (it = 0; it < n; it++) corner_case(it, 1 + (int)(dht_rand_u32() % 3u));
}

/* a straight continuation stays on the line; radius 0 runs the moves back
 * to back, each at rest at the corner */
static void straight_and_zero_radius(void)
{
    corner k;
    dh_blend_f32 bl;
    dh_cart_limits_f32 lim = { 0.5f, 2.0f, 60.0f, 500.0f };
    dh_mat4_f32 T;
    double p[3], e, t, Trr;
    long i, n;
    make_corner(&k, 0.0, 0.3, 0.2, 0.0);
    DHT_EQ_INT(dh_blend_plan_f32(&bl, &k.p1, &k.p2, &lim, 0.05f), DH_OK);
    DHT_TRUE(bl.tb > 0.0f);
    n = (long)ceil((double)bl.T * HZ) + 1;
    for (i = 0; i <= n; i++) {
        eval_at(&bl, (double)i / HZ, &T);
        pos_of(&T, p);
        e = seg_dist(k.a, k.b, p);
        DHT_TRUE_MSG(e <= POS_TOL, "straight: %.3g m off the line", e);
    }
    limits_check(&bl, &k, &lim);
    make_corner(&k, 90.0, 0.3, 0.2, 30.0);
    DHT_EQ_INT(dh_blend_plan_f32(&bl, &k.p1, &k.p2, &lim, 0.0f), DH_OK);
    DHT_TRUE(bl.tb == 0.0f && bl.dev == 0.0f && bl.t0 == bl.m1.T);
    Trr = line_tmin(0.3, k.th1, &lim) + line_tmin(0.2, k.th2, &lim);
    DHT_TRUE_MSG(fabs((double)bl.T - Trr) <= 1e-5 * Trr, "back to back %.9g s vs %.9g s", (double)bl.T, Trr);
    for (i = 0; i <= 100; i++) {
        t = (double)i * (double)bl.T / 100.0;
        eval_at(&bl, t, &T);
        pos_of(&T, p);
        e = fmin(seg_dist(k.a, k.c, p), seg_dist(k.c, k.b, p));
        DHT_TRUE(e <= POS_TOL);
    }
    eval_at(&bl, (double)bl.t0, &T);
    DHT_TRUE(memcmp(&T, &k.p1.B, sizeof T) == 0);
    limits_check(&bl, &k, &lim);
}

/* every status, and nothing written on error */
static void blend_errors(void)
{
    corner k;
    dh_blend_f32 bl, zero, copy;
    dh_cart_limits_f32 lim = { 0.5f, 2.0f, 60.0f, 500.0f };
    dh_path_f32 arc, moved;
    dh_mat4_f32 T;
    const float via[3] = { 0.1f, 0.2f, 0.3f };
    memset(&zero, 0, sizeof zero);
    make_corner(&k, 60.0, 0.3, 0.2, 30.0);
    bl = zero;
    DHT_EQ_INT(dh_blend_plan_f32(&bl, &k.p1, &k.p2, &lim, NAN), DH_ERR_NAN);
    DHT_EQ_INT(dh_blend_plan_f32(&bl, &k.p1, &k.p2, &lim, INFINITY), DH_ERR_NAN);
    DHT_EQ_INT(dh_blend_plan_f32(&bl, &k.p1, &k.p2, &lim, -1e-3f), DH_ERR_ARG);
    lim.amax = NAN;
    DHT_EQ_INT(dh_blend_plan_f32(&bl, &k.p1, &k.p2, &lim, 0.01f), DH_ERR_NAN);
    lim.amax = 0.0f;
    DHT_EQ_INT(dh_blend_plan_f32(&bl, &k.p1, &k.p2, &lim, 0.01f), DH_ERR_ARG);
    lim.amax = 2.0f;
    lim.wdmax = -1.0f;
    DHT_EQ_INT(dh_blend_plan_f32(&bl, &k.p1, &k.p2, &lim, 0.01f), DH_ERR_ARG);
    lim.wdmax = 500.0f;
    /* a second arc or line that does not start at the first's end, no path */
    T = k.p2.A;
    DH_M4(&T, 0, 3) += 1e-3f;
    DHT_EQ_INT(dh_path_arc_f32(&arc, &T, via, &k.p2.B), DH_OK);
    DHT_EQ_INT(dh_blend_plan_f32(&bl, &k.p1, &arc, &lim, 0.01f), DH_ERR_ARG);
    DHT_EQ_INT(dh_path_line_f32(&moved, &T, &k.p2.B), DH_OK);
    DHT_EQ_INT(dh_blend_plan_f32(&bl, &k.p1, &moved, &lim, 0.01f), DH_ERR_ARG);
    memset(&moved, 0, sizeof moved);
    DHT_EQ_INT(dh_blend_plan_f32(&bl, &k.p1, &moved, &lim, 0.01f), DH_ERR_ARG);
    /* limits too small for float: s' underflows */
    lim.vmax = 1e-45f;
    DHT_EQ_INT(dh_blend_plan_f32(&bl, &k.p1, &k.p2, &lim, 0.01f), DH_ERR_OVERFLOW);
    lim.vmax = 0.5f;
    DHT_TRUE(memcmp(&bl, &zero, sizeof bl) == 0);
    /* evaluation: no blend, NaN time */
    T = k.p1.A;
    DHT_EQ_INT(dh_blend_eval_f32(&zero, 0.5f, &T), DH_ERR_ARG);
    DHT_TRUE(memcmp(&T, &k.p1.A, sizeof T) == 0);
    DHT_EQ_INT(dh_blend_plan_f32(&bl, &k.p1, &k.p2, &lim, 0.01f), DH_OK);
    copy = bl;
    DHT_EQ_INT(dh_blend_eval_f32(&bl, NAN, &T), DH_ERR_NAN);
    DHT_TRUE(memcmp(&T, &k.p1.A, sizeof T) == 0 && memcmp(&bl, &copy, sizeof bl) == 0);
    /* a move without motion: no overlap */
    DHT_EQ_INT(dh_path_line_f32(&moved, &k.p1.B, &k.p1.B), DH_OK);
    DHT_EQ_INT(dh_blend_plan_f32(&bl, &k.p1, &moved, &lim, 0.01f), DH_OK);
    DHT_TRUE(bl.tb == 0.0f && bl.m2.T == 0.0f && bl.T == bl.m1.T);
    eval_at(&bl, (double)bl.T, &T);
    DHT_TRUE(memcmp(&T, &k.p1.B, sizeof T) == 0);
}


/* ---- blended sequences (dh_blend_seq_plan_f32, dh_blend_seq_eval_f32) -- */

#define NSEQ 5

typedef struct {
    dh_path_f32 p[NSEQ];
    double x[NSEQ + 1][3]; /* the float positions of the corners, x[0] the start, x[n] the end */
    double L[NSEQ], th[NSEQ];
    double S;
    int n;
} chain;

/* n lines of 0.05 to 0.4 m in random directions (the second straight on
 * when straight, the third reversed when reverse), each turning the tool
 * by up to rmax degrees about a random axis (about the world axis ax when
 * not NULL) */
/* line k of the chain from F0 to F1: its path, end point, rotation angle
 * and length */
static void chain_line(chain *c, int k, const dh_mat4_f32 *F0, const dh_mat4_f32 *F1)
{
    double ax[3], d[3];
    int i;
    DHT_EQ_INT(dh_path_line_f32(&c->p[k], F0, F1), DH_OK);
    pos_of(F1, c->x[k + 1]);
    rot_vec(F0, F1, ax);
    c->th[k] = sqrt(dot3(ax, ax));
    for (i = 0; i < 3; i++) d[i] = c->x[k + 1][i] - c->x[k][i];
    c->L[k] = sqrt(dot3(d, d));
}

/* c->S: the largest coordinate of the chain's points */
static void chain_scale(chain *c)
{
    int k, i;
    for (k = 0; k <= c->n; k++)
        for (i = 0; i < 3; i++) c->S = fmax(c->S, fabs(c->x[k][i]));
}

static void make_chain_ax(chain *c, int n, double rmax, int straight, int reverse, const double *ax1)
{
    dhr_mat4 R0, R1, X;
    dh_mat4_f32 F0, F1;
    double d[3], pd[3] = { 0.0, 0.0, 0.0 }, ax[3], pos[3];
    int k, i;
    dhr_rand_rigid(0.0, &R0);
    for (i = 0; i < 3; i++) {
        pos[i] = dht_rand_uniform(-0.3, 0.3);
        DHR_M4(&R0, i, 3) = pos[i];
    }
    dhr_to_f32(&R0, &F0);
    pos_of(&F0, c->x[0]);
    c->S = 0.0;
    c->n = n;
    for (k = 0; k < n; k++) {
        dhr_rand_unit3(d);
        for (i = 0; i < 3; i++) {
            if (k == 1 && straight) d[i] = pd[i];
            if (k == 2 && reverse) d[i] = -pd[i];
        }
        c->L[k] = dht_rand_uniform(0.05, 0.4);
        dhr_rand_unit3(ax);
        if (ax1 != NULL)
            for (i = 0; i < 3; i++) ax[i] = ax1[i];
        dhr_rot_axis(ax[0], ax[1], ax[2], dht_rand_uniform((ax1 != NULL) ? -rmax : 0.0, rmax), &X);
        dhr_mul(&X, &R0, &R1);
        for (i = 0; i < 3; i++) {
            pos[i] += c->L[k] * d[i];
            DHR_M4(&R1, i, 3) = pos[i];
            pd[i] = d[i];
        }
        dhr_to_f32(&R1, &F1);
        chain_line(c, k, &F0, &F1);
        R0 = R1;
        F0 = F1;
    }
    chain_scale(c);
}

static void make_chain(chain *c, int n, double rmax, int straight, int reverse)
{
    make_chain_ax(c, n, rmax, straight, reverse, NULL);
}

/* every sample on its line outside the overlaps, within the radius and
 * dev of its corner inside; every step within one period of the speed
 * limits; the end exact */
static void seq_path_check(const dh_blend_seq_f32 *sq, const chain *c, const float *radius,
                           const dh_cart_limits_f32 *lim)
{
    const dh_blend_seg_f32 *g = sq->seg;
    double h = 1.0 / HZ, t, p[3], q[3], e, posn = 8.0 * dhr_ulp_f32(c->S);
    long i, ns = (long)ceil((double)sq->T * HZ) + 1;
    int j, k;
    float tau;
    dh_mat4_f32 T, P;
    DHT_EQ_INT(dh_blend_seq_eval_f32(sq, 0.0f, &P), DH_OK);
    DHT_TRUE(memcmp(&P, &c->p[0].A, sizeof P) == 0);
    for (i = 1; i <= ns; i++) {
        t = (double)i * h;
        DHT_EQ_INT(dh_blend_seq_eval_f32(sq, (float)t, &T), DH_OK);
        pos_of(&T, p);
        k = 0;
        while (k + 1 < c->n && !((float)t < g[k + 1].t0)) k++;
        tau = (float)t - g[k].t0;
        if (k > 0 && tau < g[k].tb0) {
            for (j = 0; j < 3; j++) q[j] = p[j] - c->x[k][j];
            e = sqrt(dot3(q, q));
            DHT_TRUE_MSG(e <= (double)radius[k - 1] + POS_TOL && e <= (double)g[k - 1].dev + POS_TOL,
                         "t %.9g: %.9g m from corner %d (radius %.9g, dev %.9g)", t, e, k - 1,
                         (double)radius[k - 1], (double)g[k - 1].dev);
            dht_reach_max("seq.dev_frac", e / (double)radius[k - 1]);
        } else {
            e = path_dist(&c->p[k], p);
            DHT_TRUE_MSG(e <= POS_TOL, "t %.9g: %.3g m off segment %d", t, e, k);
            dht_reach_max("seq.line_err", e);
        }
        step_check(&P, &T, p, lim, posn, t);
        P = T;
    }
    DHT_TRUE(memcmp(&T, &c->p[c->n - 1].B, sizeof T) == 0);
    DHT_EQ_INT(dh_blend_seq_eval_f32(sq, sq->T + 1.0f, &T), DH_OK);
    DHT_TRUE(memcmp(&T, &c->p[c->n - 1].B, sizeof T) == 0);
    DHT_EQ_INT(dh_blend_seq_eval_f32(sq, -1.0f, &T), DH_OK);
    DHT_TRUE(memcmp(&T, &c->p[0].A, sizeof T) == 0);
}

/* the sum of the segments' rest-to-rest minimum durations (an arc's:
 * dh_path_move_f32's) */
static double chain_trr(const chain *c, const dh_cart_limits_f32 *lim)
{
    double T = 0.0;
    int k;
    for (k = 0; k < c->n; k++)
        T += (c->p[k].kind == (uint32_t)DH_PATH_ARC) ? path_trr(&c->p[k], lim) : line_tmin(c->L[k], c->th[k], lim);
    return T;
}

static void seq_check_all(const chain *c, const float *radius, const dh_cart_limits_f32 *lim,
                          const dh_blend_seq_f32 *sq)
{
    source src;
    double Trr = chain_trr(c, lim), ang = 0.0;
    int k, blended = 0;
    for (k = 0; k < c->n; k++) {
        ang += c->th[k];
        if (k + 1 < c->n) {
            DHT_TRUE(sq->seg[k].tb1 == sq->seg[k + 1].tb0 && sq->seg[k].dev <= radius[k]);
            if (sq->seg[k].tb1 > 0.0f) blended = 1;
        }
    }
    DHT_TRUE(sq->seg[0].tb0 == 0.0f && sq->seg[c->n - 1].tb1 == 0.0f);
    DHT_TRUE_MSG(blended ? (double)sq->T < Trr : (double)sq->T <= Trr * (1.0 + 1e-5),
                 "sequence %.9g s (blended %d), rest to rest %.9g s", (double)sq->T, blended, Trr);
    if (blended) dht_reach_max("seq.saving_frac", (Trr - (double)sq->T) / Trr);
    seq_path_check(sq, c, radius, lim);
    src.bl = NULL;
    src.sq = sq;
    src_limits(&src, c->S, ang > 0.0, lim);
}

/* random chains of lines (arcs 0) or of lines and arcs (arcs 1: each
 * segment an arc with probability 1/2) */
static void sequences(int arcs)
{
    int it, k, n = DHT_ITER(20);
    for (it = 0; it < n; it++) {
        chain c;
        dh_blend_seg_f32 seg[NSEQ];
        dh_blend_seq_f32 sq;
        dh_cart_limits_f32 lim;
        float radius[NSEQ - 1];
        int nl = 2 + (int)(dht_rand_u32() % (NSEQ - 1));
        make_chain(&c, nl, 60.0, it % 4 == 1, it % 4 == 2);
        for (k = 0; k + 1 < nl; k++)
            radius[k] = (dht_rand_u32() % 5u == 0u) ? 0.0f : (float)pow(10.0, dht_rand_uniform(-3.0, -1.0));
        lim.vmax = (float)dht_rand_uniform(0.1, 1.0);
        lim.amax = (float)dht_rand_uniform(1.0, 10.0);
        lim.wmax = (float)dht_rand_uniform(30.0, 90.0);
        lim.wdmax = (float)dht_rand_uniform(300.0, 2000.0);
        for (k = 0; arcs && k < nl; k++) {
            if (dht_rand_u32() % 2u == 0u) arc_of(&c.p[k]);
        }
        DHT_EQ_INT(dh_blend_seq_plan_f32(&sq, seg, c.p, (uint32_t)nl, radius, &lim), DH_OK);
        DHT_TRUE(sq.n == (uint32_t)nl && sq.seg == seg && sq.p == c.p);
        seq_check_all(&c, radius, &lim, &sq);
    }
}

static void random_sequences(void)
{
    sequences(0);
}

static void random_arc_sequences(void)
{
    sequences(1);
}

/* one line is its rest-to-rest trapezoid; radius 0 everywhere runs the
 * lines back to back, exactly at each corner between them */
static void seq_single_and_rest(void)
{
    chain c;
    dh_blend_seg_f32 seg[NSEQ];
    dh_blend_seq_f32 sq;
    dh_cart_limits_f32 lim = { 0.5f, 2.0f, 60.0f, 500.0f };
    const float zero[NSEQ - 1] = { 0.0f, 0.0f, 0.0f, 0.0f };
    dh_mat4_f32 T;
    double Trr;
    int k;
    make_chain(&c, 1, 30.0, 0, 0);
    DHT_EQ_INT(dh_blend_seq_plan_f32(&sq, seg, c.p, 1u, NULL, &lim), DH_OK);
    Trr = chain_trr(&c, &lim);
    DHT_TRUE_MSG(fabs((double)sq.T - Trr) <= 1e-5 * Trr, "one line %.9g s vs %.9g s", (double)sq.T, Trr);
    seq_check_all(&c, zero, &lim, &sq);
    make_chain(&c, NSEQ, 30.0, 1, 1);
    DHT_EQ_INT(dh_blend_seq_plan_f32(&sq, seg, c.p, NSEQ, zero, &lim), DH_OK);
    Trr = chain_trr(&c, &lim);
    DHT_TRUE_MSG(fabs((double)sq.T - Trr) <= 1e-5 * Trr, "back to back %.9g s vs %.9g s", (double)sq.T, Trr);
    for (k = 1; k < NSEQ; k++) {
        DHT_TRUE(seg[k].tb0 == 0.0f && seg[k - 1].dev == 0.0f);
        DHT_EQ_INT(dh_blend_seq_eval_f32(&sq, seg[k].t0, &T), DH_OK);
        DHT_TRUE(memcmp(&T, &c.p[k].A, sizeof T) == 0);
    }
    seq_check_all(&c, zero, &lim, &sq);
}

/* every status, and nothing written on error */
static void seq_errors(void)
{
    chain c;
    dh_blend_seg_f32 seg[3], segz[3];
    dh_blend_seq_f32 sq, sqz;
    dh_cart_limits_f32 lim = { 0.5f, 2.0f, 60.0f, 500.0f };
    float radius[2] = { 0.01f, 0.01f };
    dh_path_f32 keep;
    dh_mat4_f32 T, T0;
    const float via[3] = { 0.1f, 0.2f, 0.3f };
    memset(segz, 0, sizeof segz);
    memset(&sqz, 0, sizeof sqz);
    memcpy(seg, segz, sizeof seg);
    sq = sqz;
    make_chain(&c, 3, 30.0, 0, 0);
    DHT_EQ_INT(dh_blend_seq_plan_f32(&sq, seg, c.p, 0u, radius, &lim), DH_ERR_ARG);
    radius[1] = NAN;
    DHT_EQ_INT(dh_blend_seq_plan_f32(&sq, seg, c.p, 3u, radius, &lim), DH_ERR_NAN);
    radius[1] = -1e-3f;
    DHT_EQ_INT(dh_blend_seq_plan_f32(&sq, seg, c.p, 3u, radius, &lim), DH_ERR_ARG);
    radius[1] = 0.01f;
    lim.wmax = INFINITY;
    DHT_EQ_INT(dh_blend_seq_plan_f32(&sq, seg, c.p, 3u, radius, &lim), DH_ERR_NAN);
    lim.wmax = 0.0f;
    DHT_EQ_INT(dh_blend_seq_plan_f32(&sq, seg, c.p, 3u, radius, &lim), DH_ERR_ARG);
    lim.wmax = 60.0f;
    /* a gap (an arc's, a line's), no path */
    keep = c.p[1];
    T = keep.A;
    DH_M4(&T, 1, 3) += 1e-3f;
    DHT_EQ_INT(dh_path_arc_f32(&c.p[1], &T, via, &keep.B), DH_OK);
    DHT_EQ_INT(dh_blend_seq_plan_f32(&sq, seg, c.p, 3u, radius, &lim), DH_ERR_ARG);
    DHT_EQ_INT(dh_path_line_f32(&c.p[1], &T, &keep.B), DH_OK);
    DHT_EQ_INT(dh_blend_seq_plan_f32(&sq, seg, c.p, 3u, radius, &lim), DH_ERR_ARG);
    memset(&c.p[1], 0, sizeof c.p[1]);
    DHT_EQ_INT(dh_blend_seq_plan_f32(&sq, seg, c.p, 3u, radius, &lim), DH_ERR_ARG);
    c.p[1] = keep;
    /* limits too small for float */
    lim.vmax = 1e-45f;
    DHT_EQ_INT(dh_blend_seq_plan_f32(&sq, seg, c.p, 3u, radius, &lim), DH_ERR_OVERFLOW);
    lim.vmax = 0.5f;
    DHT_TRUE(memcmp(seg, segz, sizeof seg) == 0 && memcmp(&sq, &sqz, sizeof sq) == 0);
    /* evaluation: no sequence, NaN time */
    T0 = c.p[0].A;
    T = T0;
    DHT_EQ_INT(dh_blend_seq_eval_f32(&sqz, 0.5f, &T), DH_ERR_ARG);
    DHT_EQ_INT(dh_blend_seq_plan_f32(&sq, seg, c.p, 3u, radius, &lim), DH_OK);
    DHT_EQ_INT(dh_blend_seq_eval_f32(&sq, NAN, &T), DH_ERR_NAN);
    DHT_TRUE(memcmp(&T, &T0, sizeof T) == 0);
    /* a line without motion in the middle: both its corners at rest */
    DHT_EQ_INT(dh_path_line_f32(&c.p[1], &c.p[0].B, &c.p[0].B), DH_OK);
    DHT_EQ_INT(dh_path_line_f32(&c.p[2], &c.p[0].B, &keep.B), DH_OK);
    DHT_EQ_INT(dh_blend_seq_plan_f32(&sq, seg, c.p, 3u, radius, &lim), DH_OK);
    DHT_TRUE(seg[1].T == 0.0f && seg[0].tb1 == 0.0f && seg[2].tb0 == 0.0f);
    DHT_EQ_INT(dh_blend_seq_eval_f32(&sq, sq.T, &T), DH_OK);
    DHT_TRUE(memcmp(&T, &keep.B, sizeof T) == 0);
}

/* ---- jerk-limited blended sequences (dh_blend_seq_plan_jerk_f32) ----- */

/* the rest-to-rest minimum duration of s from 0 to 1 within s' <= V,
 * |s''| <= A, |s'''| <= J (Biagiotti & Melchiorri 2008, 3.4), in double:
 * V reached (then T = 1 / V + ta), else A reached (1 >= 2 A^3 / J^2:
 * T = 2 ta, ta = tj / 2 + sqrt(tj^2 / 4 + 1 / A), tj = A / J), else
 * T = 4 cbrt(1 / (2 J)) */
static double scurve_tmin(double V, double A, double J)
{
    double tj, ta;
    ta = (V * J >= A * A) ? V / A + A / J : 2.0 * sqrt(V / J);
    if (V * ta <= 1.0) return 1.0 / V + ta;
    if (1.0 >= 2.0 * A * A * A / (J * J)) {
        tj = A / J;
        return 2.0 * (0.5 * tj + sqrt(0.25 * tj * tj + 1.0 / A));
    }
    return 4.0 * cbrt(1.0 / (2.0 * J));
}

/* the rest-to-rest jerk-limited minimum duration of a line of length L
 * and angle th (degrees) within lim and jk */
static double line_jmin(double L, double th, const dh_cart_limits_f32 *lim, const dh_cart_jerk_f32 *jk)
{
    double v = 1e300, a = 1e300, j = 1e300;
    if (L > 0.0) {
        v = fmin(v, lim->vmax / L);
        a = fmin(a, lim->amax / L);
        j = fmin(j, jk->jmax / L);
    }
    if (th > 0.0) {
        v = fmin(v, lim->wmax / th);
        a = fmin(a, lim->wdmax / th);
        j = fmin(j, jk->wjmax / th);
    }
    return (L > 0.0 || th > 0.0) ? scurve_tmin(v, a, j) : 0.0;
}

/* n lines between the tool frames of the robot d at n + 1
 * configurations: a random one, then each joint moved by up to 20
 * degrees from the one before */
static void robot_chain(chain *c, const dhs_robot *d, int n)
{
    dh_robot r;
    double q[DHS_MAX_JOINTS];
    dh_mat4_f32 F0, F1;
    int k, i;
    DHT_EQ_INT(dhs_build(d, &r), DH_OK);
    dhs_random_q(d, q);
    dhs_target_f32(&r, q, &F0);
    pos_of(&F0, c->x[0]);
    c->n = n;
    c->S = 0.0;
    for (k = 0; k < n; k++) {
        for (i = 0; i < (int)r.n; i++) q[i] += dht_rand_uniform(-20.0, 20.0);
        dhs_target_f32(&r, q, &F1);
        chain_line(c, k, &F0, &F1);
        F0 = F1;
    }
    chain_scale(c);
}

/* the sequence against its lines' jerk-limited rest-to-rest minima (in
 * double), on its lines outside the overlaps and within the radii inside
 * (seq_path_check), speed, acceleration (linear and angular) and the
 * linear jerk within their limits by finite differences over windows */
static void jseq_check_all(const chain *c, const float *radius, const dh_cart_limits_f32 *lim,
                           const dh_cart_jerk_f32 *jk, const dh_blend_seq_f32 *sq)
{
    source src;
    double Trr = 0.0, ang = 0.0, wr;
    long w;
    int k, blended = 0;
    for (k = 0; k < c->n; k++) {
        Trr += line_jmin(c->L[k], c->th[k], lim, jk);
        ang += c->th[k];
        DHT_TRUE(sq->seg[k].j > 0.0f || sq->seg[k].T == 0.0f);
        if (k + 1 < c->n) {
            DHT_TRUE(sq->seg[k].tb1 == sq->seg[k + 1].tb0 && sq->seg[k].dev <= radius[k]);
            if (sq->seg[k].tb1 > 0.0f) blended = 1;
        }
    }
    DHT_TRUE(sq->seg[0].tb0 == 0.0f && sq->seg[c->n - 1].tb1 == 0.0f);
    DHT_TRUE_MSG(blended ? (double)sq->T < Trr : fabs((double)sq->T - Trr) <= Trr * 1e-5,
                 "jerk-limited sequence %.9g s (blended %d), rest to rest %.9g s", (double)sq->T, blended, Trr);
    if (blended) dht_reach_max("jseq.saving_frac", (Trr - (double)sq->T) / Trr);
    seq_path_check(sq, c, radius, lim);
    src.bl = NULL;
    src.sq = sq;
    src_limits(&src, c->S, ang > 0.0, lim);
    w = fd_window(8.0 * dhr_ulp_f32(c->S), 3, jk->jmax);
    wr = fd_ratio(&src, 3, 0, w, jk->jmax);
    DHT_TRUE_MSG(wr <= 1.0 + REL_FD, "linear jerk: %.9g x its limit (window %ld ms)", wr, w);
    dht_reach_max("jseq.lin.j", wr);
}

/* random jerk-limited sequences of 2 to NSEQ lines on the robot d */
static void jerk_sequences(const dhs_robot *d)
{
    int it, k, n = DHT_ITER(8);
    for (it = 0; it < n; it++) {
        chain c;
        dh_blend_seg_f32 seg[NSEQ];
        dh_blend_seq_f32 sq;
        dh_cart_limits_f32 lim;
        dh_cart_jerk_f32 jk;
        float radius[NSEQ - 1];
        int nl = 2 + (int)(dht_rand_u32() % (NSEQ - 1));
        robot_chain(&c, d, nl);
        for (k = 0; k + 1 < nl; k++)
            radius[k] = (dht_rand_u32() % 5u == 0u) ? 0.0f : (float)pow(10.0, dht_rand_uniform(-3.0, -1.0));
        lim.vmax = (float)dht_rand_uniform(0.25, 1.0);
        lim.amax = (float)dht_rand_uniform(1.0, 10.0);
        lim.wmax = (float)dht_rand_uniform(30.0, 90.0);
        lim.wdmax = (float)dht_rand_uniform(300.0, 2000.0);
        jk.jmax = (float)dht_rand_uniform(5.0, 100.0);
        jk.wjmax = (float)dht_rand_uniform(3000.0, 30000.0);
        DHT_EQ_INT(dh_blend_seq_plan_jerk_f32(&sq, seg, c.p, (uint32_t)nl, radius, &lim, &jk), DH_OK);
        DHT_TRUE(sq.n == (uint32_t)nl && sq.seg == seg && sq.p == c.p);
        jseq_check_all(&c, radius, &lim, &jk, &sq);
    }
}

static void jerk_sequences_puma560(void)
{
    jerk_sequences(&dhs_puma560_m);
}

static void jerk_sequences_ur5(void)
{
    jerk_sequences(&dhs_ur5_m);
}

static void jerk_sequences_panda(void)
{
    jerk_sequences(&dhs_panda_m);
}

/* random jerk-limited sequences whose lines turn the tool about the world
 * z axis only (by up to +-60 degrees each): the angular jerk by third
 * differences of the rotation angle within wjmax as well (the composed
 * rotation's cross terms vanish there; they are bounded by the proof) */
static void jerk_sequences_one_axis(void)
{
    const double z[3] = { 0.0, 0.0, 1.0 };
    int it, k, n = DHT_ITER(8);
    for (it = 0; it < n; it++) {
        chain c;
        dh_blend_seg_f32 seg[NSEQ];
        dh_blend_seq_f32 sq;
        dh_cart_limits_f32 lim;
        dh_cart_jerk_f32 jk;
        source src;
        float radius[NSEQ - 1];
        double wr;
        long w;
        int nl = 2 + (int)(dht_rand_u32() % (NSEQ - 1));
        make_chain_ax(&c, nl, 60.0, it % 4 == 1, it % 4 == 2, z);
        for (k = 0; k + 1 < nl; k++) radius[k] = (float)pow(10.0, dht_rand_uniform(-3.0, -1.0));
        lim.vmax = (float)dht_rand_uniform(0.25, 1.0);
        lim.amax = (float)dht_rand_uniform(1.0, 10.0);
        lim.wmax = (float)dht_rand_uniform(30.0, 90.0);
        lim.wdmax = (float)dht_rand_uniform(100.0, 1000.0);
        jk.jmax = (float)dht_rand_uniform(5.0, 100.0);
        jk.wjmax = (float)dht_rand_uniform(500.0, 10000.0);
        DHT_EQ_INT(dh_blend_seq_plan_jerk_f32(&sq, seg, c.p, (uint32_t)nl, radius, &lim, &jk), DH_OK);
        jseq_check_all(&c, radius, &lim, &jk, &sq);
        src.bl = NULL;
        src.sq = &sq;
        w = fd_window(ANG_NOISE, 3, jk.wjmax);
        wr = fd_ratio(&src, 3, 1, w, jk.wjmax);
        DHT_TRUE_MSG(wr <= 1.0 + REL_FD, "angular jerk: %.9g x its limit (window %ld ms)", wr, w);
        dht_reach_max("jseq.ang.j", wr);
    }
}

/* radius 0 and one line are the double minima; every status, nothing
 * written on error */
static void jerk_seq_single_and_errors(void)
{
    chain c;
    dh_blend_seg_f32 seg[3], segz[3];
    dh_blend_seq_f32 sq, sqz;
    dh_cart_limits_f32 lim = { 0.5f, 2.0f, 60.0f, 500.0f };
    dh_cart_jerk_f32 jk = { 20.0f, 5000.0f };
    float radius[2] = { 0.01f, 0.01f };
    const float zero[2] = { 0.0f, 0.0f };
    dh_path_f32 keep;
    double Trr;
    make_chain(&c, 3, 30.0, 0, 0);
    DHT_EQ_INT(dh_blend_seq_plan_jerk_f32(&sq, seg, c.p, 3u, zero, &lim, &jk), DH_OK);
    jseq_check_all(&c, zero, &lim, &jk, &sq);
    DHT_EQ_INT(dh_blend_seq_plan_jerk_f32(&sq, seg, c.p, 3u, radius, &lim, &jk), DH_OK);
    jseq_check_all(&c, radius, &lim, &jk, &sq);
    make_chain(&c, 1, 30.0, 0, 0);
    DHT_EQ_INT(dh_blend_seq_plan_jerk_f32(&sq, seg, c.p, 1u, NULL, &lim, &jk), DH_OK);
    DHT_TRUE(sq.n == 1u && sq.seg == seg && seg[0].j > 0.0f);
    Trr = line_jmin(c.L[0], c.th[0], &lim, &jk);
    DHT_TRUE_MSG(fabs((double)sq.T - Trr) <= 1e-5 * Trr, "one line %.9g s vs %.9g s", (double)sq.T, Trr);
    jseq_check_all(&c, zero, &lim, &jk, &sq);
    /* errors: the trapezoid's statuses first, then the jerk's */
    make_chain(&c, 3, 30.0, 0, 0);
    memset(segz, 0, sizeof segz);
    memset(&sqz, 0, sizeof sqz);
    memcpy(seg, segz, sizeof seg);
    sq = sqz;
    DHT_EQ_INT(dh_blend_seq_plan_jerk_f32(&sq, seg, c.p, 0u, radius, &lim, &jk), DH_ERR_ARG);
    radius[0] = NAN;
    jk.jmax = 0.0f;
    DHT_EQ_INT(dh_blend_seq_plan_jerk_f32(&sq, seg, c.p, 3u, radius, &lim, &jk), DH_ERR_NAN);
    radius[0] = 0.01f;
    DHT_EQ_INT(dh_blend_seq_plan_jerk_f32(&sq, seg, c.p, 3u, radius, &lim, &jk), DH_ERR_ARG);
    jk.jmax = NAN;
    DHT_EQ_INT(dh_blend_seq_plan_jerk_f32(&sq, seg, c.p, 3u, radius, &lim, &jk), DH_ERR_NAN);
    jk.jmax = 20.0f;
    jk.wjmax = INFINITY;
    DHT_EQ_INT(dh_blend_seq_plan_jerk_f32(&sq, seg, c.p, 3u, radius, &lim, &jk), DH_ERR_NAN);
    jk.wjmax = -1.0f;
    DHT_EQ_INT(dh_blend_seq_plan_jerk_f32(&sq, seg, c.p, 3u, radius, &lim, &jk), DH_ERR_ARG);
    jk.wjmax = 5000.0f;
    /* an arc: its centripetal jerk in a tail is not bounded */
    keep = c.p[1];
    arc_of(&c.p[1]);
    DHT_EQ_INT(dh_blend_seq_plan_jerk_f32(&sq, seg, c.p, 3u, radius, &lim, &jk), DH_ERR_ARG);
    c.p[1] = keep;
    /* a bound of s too small for float */
    lim.vmax = 1e-45f;
    DHT_EQ_INT(dh_blend_seq_plan_jerk_f32(&sq, seg, c.p, 3u, radius, &lim, &jk), DH_ERR_OVERFLOW);
    lim.vmax = 0.5f;
    DHT_TRUE(memcmp(seg, segz, sizeof seg) == 0 && memcmp(&sq, &sqz, sizeof sq) == 0);
    /* a line without motion in the middle: both its corners at rest */
    DHT_EQ_INT(dh_path_line_f32(&c.p[1], &c.p[0].B, &c.p[0].B), DH_OK);
    DHT_EQ_INT(dh_path_line_f32(&c.p[2], &c.p[0].B, &keep.B), DH_OK);
    DHT_EQ_INT(dh_blend_seq_plan_jerk_f32(&sq, seg, c.p, 3u, radius, &lim, &jk), DH_OK);
    DHT_TRUE(seg[1].T == 0.0f && seg[0].tb1 == 0.0f && seg[2].tb0 == 0.0f);
}

static const dht_case cases[] = {
    DHT_CASE(random_corners),
    DHT_CASE(straight_and_zero_radius),
    DHT_CASE(blend_errors),
    DHT_CASE(random_sequences),
    DHT_CASE(seq_single_and_rest),
    DHT_CASE(seq_errors),
    DHT_CASE(random_arc_corners),
    DHT_CASE(random_arc_sequences),
    DHT_CASE(jerk_sequences_puma560),
    DHT_CASE(jerk_sequences_ur5),
    DHT_CASE(jerk_sequences_panda),
    DHT_CASE(jerk_seq_single_and_errors),
    DHT_CASE(jerk_sequences_one_axis),
};
DHT_MAIN(cases)
