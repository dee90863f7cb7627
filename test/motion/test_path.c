/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_path.c - Cartesian paths and moves (motion.h) against references
 * computed here in double from the float inputs: the line p_A + s (p_B -
 * p_A); the circle through p_A, via, p_B in a plane basis (Gram-Schmidt
 * of via - p_A and p_B - p_A, the centre from the perpendicular
 * bisectors, angles by atan2); the rotation angle of R_X^T R_Y from its
 * trace and vee; the trapezoid's minimum duration.
 *
 * Bounds (EPS = FLT_EPSILON, S = the largest |position| of p_A, via, p_B):
 * - a point of a line: dh_pose_interp_f32's 2 ulp of S (4 EPS S here);
 * - the circle: about 8 roundings of the scaled sides in the centre, each
 *   amplified by the circumcentre's condition 1 / ln (ln = |a x b| / L^2,
 *   L the longest side, > 2^-10), and 6 in the evaluation, relative to
 *   S + R + L: E = 16 EPS (S + R + L) / ln; the radius is within E, the
 *   sweep within 2 E / R, so a point at s within 3 E (E for the circle,
 *   2 E for the parameter) and the length within (2 + 2 pi) E < 9 E;
 * - the rotation angle from R_A at s against s times the angle from R_A to
 *   R_B: rotation entries within 2e-6 (dh_pose_interp_f32), so the angle
 *   within 3 * 2e-6 rad = 3.4e-4 deg, plus 1e-4 deg for each angle of
 *   float rotations (dh_pose_angle_f32): ANG_TOL 6e-4 deg.
 * Moves, sampled at 1 kHz: finite differences of float positions carry
 * their rounding, about 4 ulp of max(S, 2 R) per sample (the last
 * additions of the evaluation; the errors of the centre and sweep are
 * smooth in s), and of the angle 3.4e-4 deg; each check's window is the
 * least number of periods for which that rounding is at most 2.5e-4 of
 * the limit, and the difference must stay within the limit times
 * 1 + 1e-3.
 * Jerk-limited moves (dh_path_move_jerk_f32): the bounds of s written
 * here in double from motion.h's formulas (an arc's V, At, Jt from amax,
 * jmax and R), the seven-phase profile's minimum duration for them
 * (Biagiotti & Melchiorri 2008, 3.4), and the same finite differences
 * plus the third ones (8 samples' noise) of the position vector (the
 * TOTAL jerk) and of the rotation angle against jmax and wjmax. Without
 * jerk limits the functions are the trapezoid's bit for bit; the executor
 * (dh_move_path_jerk_f32) targets the move's frame at its clock (its feed
 * override 1 until a lagging stretch, falling in it); every
 * status of a bad jerk limit empties the profile and the move.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_ref.h"
#include "dhmath/motion.h"
#include "dhmath/mat4.h"

#define EPS ((double)FLT_EPSILON)
#define ANG_TOL 6e-4      /* degrees */
#define REL_FD 1e-3
#define NOISE_FRAC 2.5e-4
#define HZ 1000.0
#define THIN 9.765625e-4  /* 2^-10 */

typedef struct {
    double pa[3], pb[3], via[3];
    double c[3], e1[3], e2[3];
    double R, th0, sweep, svia, L, ln, S, theta, len, E;
    int arc;
} ref_path;

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static double norm3(const double a[3]) { return sqrt(dot3(a, a)); }

static double mod2pi(double x)
{
    x = fmod(x, 2.0 * DHR_PI);
    return (x < 0.0) ? x + 2.0 * DHR_PI : x;
}

/* the angle in degrees of R_X^T R_Y, from the float entries */
static double rot_angle(const dh_mat4_f32 *X, const dh_mat4_f32 *Y)
{
    double M[3][3], vx, vy, vz;
    int i, j, k;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            M[i][j] = 0.0;
            for (k = 0; k < 3; k++) M[i][j] += (double)DH_M4(X, k, i) * DH_M4(Y, k, j);
        }
    vx = M[2][1] - M[1][2];
    vy = M[0][2] - M[2][0];
    vz = M[1][0] - M[0][1];
    return atan2(sqrt(vx * vx + vy * vy + vz * vz), M[0][0] + M[1][1] + M[2][2] - 1.0) * 180.0 / DHR_PI;
}

/* the reference of the path from A to B (through via when arc) */
static void ref_make(ref_path *r, const dh_mat4_f32 *A, const float *via, const dh_mat4_f32 *B, int arc)
{
    double a[3], b[3], e[3], la, bx, by, cx, cy, m;
    int i;
    memset(r, 0, sizeof *r);
    r->arc = arc;
    for (i = 0; i < 3; i++) {
        r->pa[i] = DH_M4(A, i, 3);
        r->pb[i] = DH_M4(B, i, 3);
        r->via[i] = arc ? via[i] : r->pa[i];
        b[i] = r->pb[i] - r->pa[i];
        a[i] = r->via[i] - r->pa[i];
        e[i] = r->pb[i] - r->via[i];
    }
    r->S = norm3(r->pa);
    if (norm3(r->pb) > r->S) r->S = norm3(r->pb);
    if (norm3(r->via) > r->S) r->S = norm3(r->via);
    r->theta = rot_angle(A, B);
    if (!arc) {
        r->len = norm3(b);
        r->E = 4.0 * EPS * r->S;
        return;
    }
    r->L = norm3(a);
    if (norm3(b) > r->L) r->L = norm3(b);
    if (norm3(e) > r->L) r->L = norm3(e);
    la = norm3(a);
    for (i = 0; i < 3; i++) r->e1[i] = a[i] / la;
    bx = dot3(b, r->e1);
    for (i = 0; i < 3; i++) r->e2[i] = b[i] - bx * r->e1[i];
    by = norm3(r->e2);
    for (i = 0; i < 3; i++) r->e2[i] /= by;
    r->ln = la * by / (r->L * r->L);
    /* the centre on the bisector x = la / 2, at equal distance from p_A and p_B */
    cx = 0.5 * la;
    cy = (bx * bx + by * by - la * bx) / (2.0 * by);
    for (i = 0; i < 3; i++) r->c[i] = r->pa[i] + cx * r->e1[i] + cy * r->e2[i];
    r->R = sqrt(cx * cx + cy * cy);
    r->th0 = atan2(-cy, -cx);
    r->sweep = mod2pi(atan2(by - cy, bx - cx) - r->th0);
    r->svia = mod2pi(atan2(-cy, la - cx) - r->th0) / r->sweep;
    r->len = r->R * r->sweep;
    m = r->S + r->R + r->L;
    r->E = 16.0 * EPS * m / r->ln;
}

/* the reference position at s */
static void ref_point(const ref_path *r, double s, double p[3])
{
    int i;
    double th = r->th0 + s * r->sweep;
    for (i = 0; i < 3; i++) {
        p[i] = r->arc ? r->c[i] + r->R * (cos(th) * r->e1[i] + sin(th) * r->e2[i])
                      : r->pa[i] + s * (r->pb[i] - r->pa[i]);
    }
}

static double pos_err(const dh_mat4_f32 *T, const double p[3])
{
    double m = 0.0, e;
    int i;
    for (i = 0; i < 3; i++) {
        e = fabs((double)DH_M4(T, i, 3) - p[i]);
        if (!(e <= m)) m = e;
    }
    return m;
}

/* a float frame with the rotation R (double) and position p */
static void frame_set(const dhr_mat4 *R, const double p[3], dh_mat4_f32 *T)
{
    dhr_mat4 D = *R;
    DHR_M4(&D, 0, 3) = p[0];
    DHR_M4(&D, 1, 3) = p[1];
    DHR_M4(&D, 2, 3) = p[2];
    dhr_to_f32(&D, T);
}

/* A and B with positions pa, pb: A's rotation random, B's turned from it
 * by deg about a random axis (deg < 0: a random rotation of its own) */
static void frames(const double pa[3], const double pb[3], double deg, dh_mat4_f32 *A, dh_mat4_f32 *B)
{
    dhr_mat4 Ra, Rr, Rb;
    double k[3];
    dhr_rand_rigid(0.0, &Ra);
    if (deg < 0.0) {
        dhr_rand_rigid(0.0, &Rb);
    } else {
        dhr_rand_unit3(k);
        (void)dhr_rot_axis(k[0], k[1], k[2], deg, &Rr);
        dhr_mul(&Ra, &Rr, &Rb);
    }
    frame_set(&Ra, pa, A);
    frame_set(&Rb, pb, B);
}

/* an arc of radius R about a centre within off of the origin: sweep
 * (radians) and the via point's fraction of it; positions into pa, via, pb */
static void arc_points(double R, double off, double sweep, double fv, double pa[3], float via[3], double pb[3])
{
    double c[3], u[3], w[3], n[3], t;
    int i;
    for (i = 0; i < 3; i++) c[i] = dht_rand_uniform(-off, off);
    dhr_rand_unit3(n);
    do {
        dhr_rand_unit3(u);
        t = dot3(u, n);
        for (i = 0; i < 3; i++) u[i] -= t * n[i];
    } while (norm3(u) < 0.1);
    t = norm3(u);
    for (i = 0; i < 3; i++) u[i] /= t;
    w[0] = n[1] * u[2] - n[2] * u[1];
    w[1] = n[2] * u[0] - n[0] * u[2];
    w[2] = n[0] * u[1] - n[1] * u[0];
    for (i = 0; i < 3; i++) {
        pa[i] = c[i] + R * u[i];
        via[i] = (float)(c[i] + R * (cos(fv * sweep) * u[i] + sin(fv * sweep) * w[i]));
        pb[i] = c[i] + R * (cos(sweep) * u[i] + sin(sweep) * w[i]);
    }
}

/* a random path into p (and its reference): an arc when arc, else a line;
 * rotation deg between the ends */
static void rand_path(dh_path_f32 *p, ref_path *r, int arc, double size, double deg)
{
    dh_mat4_f32 A, B;
    double pa[3], pb[3];
    float via[3];
    int i;
    dh_status st;
    do {
        if (arc) {
            arc_points(size, size * dht_rand_uniform(0.0, 3.0), dht_rand_uniform(0.2, 2.0 * DHR_PI - 0.2),
                       dht_rand_uniform(0.1, 0.9), pa, via, pb);
        } else {
            for (i = 0; i < 3; i++) {
                pa[i] = dht_rand_uniform(-size, size);
                pb[i] = dht_rand_uniform(-size, size);
                via[i] = 0.0f;
            }
        }
        frames(pa, pb, deg, &A, &B);
        ref_make(r, &A, via, &B, arc);
    } while (arc && r->ln < 1.01 * THIN);
    st = arc ? dh_path_arc_f32(p, &A, via, &B) : dh_path_line_f32(p, &A, &B);
    DHT_EQ_INT(st, DH_OK);
}

static double draw_deg(int it)
{
    switch (it % 5) {
    case 0: return 0.0;
    case 1: return -1.0;                     /* two random rotations */
    case 2: return 180.0 - pow(10.0, dht_rand_uniform(-3.0, 0.0));
    default: return dht_rand_uniform(0.0, 180.0);
    }
}

/* ends, clamping, position along the line or arc, via point, rotation */
static void paths_vs_double(int arc)
{
    int it, k, n = DHT_ITER(3000);
    double worst = 0.0;
    for (it = 0; it < n; it++) {
        dh_path_f32 p;
        dh_mat4_f32 T;
        ref_path r;
        double q[3], s, e, tol;
        rand_path(&p, &r, arc, pow(10.0, dht_rand_uniform(-2.0, 3.0)), draw_deg(it));
        DHT_EQ_INT((int)p.kind, arc ? DH_PATH_ARC : DH_PATH_LINE);
        /* ends bit for bit, clamped parameters */
        DHT_EQ_INT(dh_path_eval_f32(&p, 0.0f, &T), DH_OK);
        DHT_TRUE(memcmp(&T, &p.A, sizeof T) == 0);
        DHT_EQ_INT(dh_path_eval_f32(&p, -0.25f, &T), DH_OK);
        DHT_TRUE(memcmp(&T, &p.A, sizeof T) == 0);
        DHT_EQ_INT(dh_path_eval_f32(&p, -INFINITY, &T), DH_OK);
        DHT_TRUE(memcmp(&T, &p.A, sizeof T) == 0);
        DHT_EQ_INT(dh_path_eval_f32(&p, 1.0f, &T), DH_OK);
        DHT_TRUE(memcmp(&T, &p.B, sizeof T) == 0);
        DHT_EQ_INT(dh_path_eval_f32(&p, 3.0f, &T), DH_OK);
        DHT_TRUE(memcmp(&T, &p.B, sizeof T) == 0);
        DHT_EQ_INT(dh_path_eval_f32(&p, INFINITY, &T), DH_OK);
        DHT_TRUE(memcmp(&T, &p.B, sizeof T) == 0);
        /* the fields */
        DHT_TRUE_MSG(fabs(p.angle - r.theta) <= 1e-4, "angle %.9g vs %.9g", (double)p.angle, r.theta);
        if (arc) {
            DHT_TRUE_MSG(fabs(p.radius - r.R) <= r.E, "radius %.9g vs %.9g (E %.3g)", (double)p.radius, r.R, r.E);
            DHT_TRUE_MSG(fabs(p.sweep * DHR_PI / 180.0 - r.sweep) <= 2.0 * r.E / r.R + 2.0 * EPS * r.sweep,
                         "sweep %.9g vs %.9g rad", p.sweep * DHR_PI / 180.0, r.sweep);
            DHT_TRUE_MSG(fabs(p.length - r.len) <= 9.0 * r.E, "length %.9g vs %.9g", (double)p.length, r.len);
            /* the via point at its parameter, found here */
            DHT_EQ_INT(dh_path_eval_f32(&p, (float)r.svia, &T), DH_OK);
            e = pos_err(&T, r.via);
            tol = 3.0 * r.E + EPS * r.len;   /* plus the rounding of s to float */
            DHT_TRUE_MSG(e <= tol, "via missed by %.3g (bound %.3g)", e, tol);
        } else {
            DHT_TRUE_MSG(fabs(p.length - r.len) <= 4.0 * EPS * r.len, "length %.9g vs %.9g", (double)p.length, r.len);
            DHT_TRUE(p.radius == 0.0f && p.sweep == 0.0f);
        }
        for (k = 0; k < 8; k++) {
            s = (k == 0) ? 0.5 : dht_rand_uniform(0.0, 1.0);
            if (k == 1) s = pow(10.0, dht_rand_uniform(-7.0, -1.0));
            if (k == 2) s = 1.0 - pow(10.0, dht_rand_uniform(-7.0, -1.0));
            s = (double)(float)s;
            DHT_EQ_INT(dh_path_eval_f32(&p, (float)s, &T), DH_OK);
            ref_point(&r, s, q);
            e = pos_err(&T, q);
            tol = arc ? 3.0 * r.E : r.E;
            if (e / tol > worst) worst = e / tol;
            DHT_TRUE_MSG(e <= tol, "s %.9g: position off by %.3g (bound %.3g)", s, e, tol);
            e = fabs(rot_angle(&p.A, &T) - s * r.theta);
            DHT_TRUE_MSG(e <= ANG_TOL, "s %.9g: angle from A off by %.3g deg", s, e);
        }
    }
    dht_printf("%s: worst position error %.3g of its bound\n", arc ? "arc" : "line", worst);
}

static void lines_vs_double(void) { paths_vs_double(0); }
static void arcs_vs_double(void) { paths_vs_double(1); }

/* a known arc: the quarter circle of radius 2 about (1, 0, 0) in z = 3 */
static void quarter_circle(void)
{
    dh_mat4_f32 A, B, T;
    dh_path_f32 p;
    const float via[3] = { 1.0f + 1.4142135f, 1.4142135f, 3.0f };
    dh_mat4_trans_f32(3.0f, 0.0f, 3.0f, &A);
    dh_mat4_trans_f32(1.0f, 2.0f, 3.0f, &B);
    DHT_EQ_INT(dh_path_arc_f32(&p, &A, via, &B), DH_OK);
    DHT_NEAR(p.radius, 2.0f, 1e-6f);
    DHT_NEAR(p.sweep, 90.0f, 1e-4f);
    DHT_NEAR(p.length, 3.14159265f, 1e-6f);
    DHT_TRUE(p.angle == 0.0f);
    DHT_EQ_INT(dh_path_eval_f32(&p, 0.5f, &T), DH_OK);
    DHT_NEAR(DH_M4(&T, 0, 3), via[0], 1e-6f);
    DHT_NEAR(DH_M4(&T, 1, 3), via[1], 1e-6f);
    DHT_NEAR(DH_M4(&T, 2, 3), 3.0f, 1e-6f);
    /* the other way round: through (1 - sqrt 2, -sqrt 2), three quarters */
    {
        const float v2[3] = { 1.0f - 1.4142135f, -1.4142135f, 3.0f };
        DHT_EQ_INT(dh_path_arc_f32(&p, &A, v2, &B), DH_OK);
        DHT_NEAR(p.sweep, 270.0f, 1e-4f);
        DHT_EQ_INT(dh_path_eval_f32(&p, 0.5f, &T), DH_OK);
        DHT_NEAR(DH_M4(&T, 0, 3), v2[0], 1e-6f);
        DHT_NEAR(DH_M4(&T, 1, 3), v2[1], 1e-6f);
    }
}

/* ---- moves ---------------------------------------------------------------- */

/* the trapezoid's minimum duration for distance d within v, a */
static double trap_tmin(double d, double v, double a)
{
    return (d >= v * v / a) ? d / v + v / a : 2.0 * sqrt(d / a);
}

/* the seven-phase profile's minimum duration for distance d within v, a, j */
static double scurve_tmin(double d, double v, double a, double j)
{
    double tj, ta, tv;
    if (v * j >= a * a) {            /* amax reached on the way to vmax */
        tj = a / j;
        ta = tj + v / a;
    } else {
        tj = sqrt(v / j);
        ta = 2.0 * tj;
    }
    tv = d / v - ta;
    if (tv < 0.0) {                  /* vmax not reached */
        tv = 0.0;
        if (d >= 2.0 * a * a * a / (j * j)) {
            tj = a / j;
            ta = 0.5 * tj + sqrt(0.25 * tj * tj + d / a);
        } else {
            tj = cbrt(d / (2.0 * j));
            ta = 2.0 * tj;
        }
    }
    return 2.0 * ta + tv;
}

/* the documented bounds of s (b[0] speed, b[1] acceleration, b[2] jerk,
 * HUGE_VAL without jk) for the reference path r within lim and jk (NULL:
 * no jerk limit), in double; *rel the relative error of the float path's
 * length, radius and angle they inherit */
static void ref_rates(const ref_path *r, const dh_cart_limits_f32 *lim, const dh_cart_jerk_f32 *jk, double b[3],
                      double *rel)
{
    double V = lim->vmax, At = lim->amax, Jt = jk ? jk->jmax : HUGE_VAL, q;
    int i;
    for (i = 0; i < 3; i++) b[i] = HUGE_VAL;
    *rel = 16.0 * EPS;
    if (r->arc) {
        q = sqrt(lim->amax * r->R / sqrt(2.0));
        if (q < V) V = q;
        if (jk) {
            q = cbrt(jk->jmax * r->R * r->R / 4.0);
            if (q < V) V = q;
        }
        q = V * V / r->R / lim->amax;
        At = lim->amax * sqrt(1.0 - q * q);
        if (jk) {
            q = jk->jmax * r->R / (12.0 * V);
            if (q < At) At = q;
            Jt = 0.5 * jk->jmax;
        }
        *rel += r->E / r->R;
    }
    if (r->len > 0.0) {
        b[0] = V / r->len;
        b[1] = At / r->len;
        b[2] = Jt / r->len;
        *rel += 9.0 * r->E / r->len;
    }
    if (r->theta > 0.0) {
        if (lim->wmax / r->theta < b[0]) b[0] = lim->wmax / r->theta;
        if (lim->wdmax / r->theta < b[1]) b[1] = lim->wdmax / r->theta;
        if (jk && jk->wjmax / r->theta < b[2]) b[2] = jk->wjmax / r->theta;
        *rel += 1e-4 / r->theta;
    }
}

/* the finite difference of the given order (1 to 3) of the samples y[0..order] */
static double fd_of(const double *y, int order)
{
    switch (order) {
    case 1: return y[1] - y[0];
    case 2: return y[2] - 2.0 * y[1] + y[0];
    default: return y[3] - 3.0 * y[2] + 3.0 * y[1] - y[0];
    }
}

/* the largest ratio of a finite difference to its limit over windows of w
 * periods: order 1 (speed), 2 (acceleration) or 3 (jerk) of the position
 * (ang 0) or of the rotation angle from A (ang 1) */
static double fd_ratio(const dh_profile_f32 *prof, const dh_path_f32 *p, int order, int ang, long w, double lim)
{
    double worst = 0.0, h = 1.0 / HZ, x[3][4], th[4], f, d;
    long k, kend = (long)ceil((double)prof->T * HZ) + 2;
    int j, i;
    for (k = -w; k <= kend; k++) {
        for (j = 0; j <= order; j++) {
            dh_mat4_f32 T;
            float v;
            DHT_EQ_INT(dh_path_move_eval_f32(prof, p, (float)((double)(k + j * w) * h), &T, &v), DH_OK);
            for (i = 0; i < 3; i++) x[i][j] = DH_M4(&T, i, 3);
            th[j] = ang ? rot_angle(&p->A, &T) : 0.0;
        }
        f = 0.0;
        if (ang) {
            f = fabs(fd_of(th, order));
        } else {
            for (i = 0; i < 3; i++) {
                d = fd_of(x[i], order);
                f += d * d;
            }
            f = sqrt(f);
        }
        f /= pow((double)w * h, order);
        if (f / lim > worst) worst = f / lim;
    }
    return worst;
}

/* the least window (periods) over which a per-sample rounding noise
 * perturbs the finite difference of the given order by at most
 * NOISE_FRAC of lim */
static long fd_window(double noise, int order, double lim)
{
    /* the difference of order k sums 2^k samples' noise */
    double wh = pow(ldexp(noise, order) / (NOISE_FRAC * lim), 1.0 / order);
    long w = (long)ceil(wh * HZ);
    return (w < 2) ? 2 : w;
}

/* the largest finite-difference ratios seen: speed, acceleration, jerk,
 * angular speed, angular acceleration, angular jerk */
static double fd_worst[6];

static void fd_note(int i, double wr)
{
    if (wr > fd_worst[i]) fd_worst[i] = wr;
}

/* a move (jerk-limited when jk != NULL) of p against its reference r:
 * the minimum duration, exact ends, the limits by finite differences */
static void move_check(const dh_path_f32 *p, const ref_path *r, const dh_cart_limits_f32 *lim,
                       const dh_cart_jerk_f32 *jk)
{
    dh_profile_f32 prof;
    dh_mat4_f32 T;
    double b[3], rel, Tref, noise, wr, plim[3], alim[3];
    float v;
    long w;
    int k, top = jk ? 3 : 2;
    DHT_EQ_INT(dh_path_move_jerk_f32(&prof, p, lim, jk), DH_OK);
    DHT_EQ_INT((int)prof.kind, jk ? DH_PROFILE_SCURVE : DH_PROFILE_TRAP);
    ref_rates(r, lim, jk, b, &rel);
    /* the seven-phase profile adds 8 roundings of its own (motion.h) */
    if (jk) rel += 8.0 * EPS;
    Tref = jk ? scurve_tmin(1.0, b[0], b[1], b[2]) : trap_tmin(1.0, b[0], b[1]);
    DHT_TRUE_MSG(fabs(prof.T - Tref) <= rel * Tref, "T %.9g vs the minimum %.9g (rel %.3g)", (double)prof.T, Tref, rel);
    /* exact ends, at rest */
    DHT_EQ_INT(dh_path_move_eval_f32(&prof, p, 0.0f, &T, &v), DH_OK);
    DHT_TRUE(memcmp(&T, &p->A, sizeof T) == 0 && v == 0.0f);
    DHT_EQ_INT(dh_path_move_eval_f32(&prof, p, prof.T, &T, &v), DH_OK);
    DHT_TRUE(memcmp(&T, &p->B, sizeof T) == 0 && v == 0.0f);
    DHT_EQ_INT(dh_path_move_eval_f32(&prof, p, 0.5f * prof.T, &T, &v), DH_OK);
    DHT_TRUE(v > 0.0f || r->len == 0.0);
    DHT_TRUE(v <= lim->vmax * (1.0f + 1e-6f));
    /* limits by finite differences: speed, TOTAL acceleration, TOTAL jerk */
    plim[0] = lim->vmax;
    plim[1] = lim->amax;
    plim[2] = jk ? jk->jmax : 0.0;
    alim[0] = lim->wmax;
    alim[1] = lim->wdmax;
    alim[2] = jk ? jk->wjmax : 0.0;
    noise = 4.0 * dhr_ulp_f32(fmax(r->S, 2.0 * r->R));
    for (k = 1; k <= top && r->len > 0.0; k++) {
        w = fd_window(noise, k, plim[k - 1]);
        wr = fd_ratio(&prof, p, k, 0, w, plim[k - 1]);
        fd_note(k - 1, wr);
        DHT_TRUE_MSG(wr <= 1.0 + REL_FD, "linear derivative %d: %.9g x its limit (window %ld ms)", k, wr, w);
    }
    for (k = 1; k <= top && r->theta > 0.0; k++) {
        w = fd_window(3.4e-4, k, alim[k - 1]);
        wr = fd_ratio(&prof, p, k, 1, w, alim[k - 1]);
        fd_note(k + 2, wr);
        DHT_TRUE_MSG(wr <= 1.0 + REL_FD, "angular derivative %d: %.9g x its limit (window %ld ms)", k, wr, w);
    }
}

/* the executor on the move (prof, p): dh_move_path_jerk_f32 holds prof;
 * each period's target is the move's frame at the clock bit for bit; up
 * to a stretch of 5 LAGGING periods at a third of the move the feed
 * override stays 1 and the clock advances by dt bit for bit; in the
 * stretch r falls (held 1, the clock advancing by r dt); done only at the
 * end, with the target at B, within the duration plus 1 s */
static void move_run(const dh_profile_f32 *prof, const dh_path_f32 *p, const dh_cart_limits_f32 *lim,
                     const dh_cart_jerk_f32 *jk)
{
    dh_move_f32 mv;
    dh_move_report_f32 rep;
    dh_mat4_f32 T, E;
    float v, c, r = 1.0f;
    const float dt = (float)(1.0 / HZ);
    long k, nmax = (long)ceil((double)prof->T * HZ) + 1, lag0 = nmax / 3;
    DHT_EQ_INT(dh_move_path_jerk_f32(&mv, p, lim, jk), DH_OK);
    DHT_TRUE(memcmp(&mv.prof[0], prof, sizeof *prof) == 0 && mv.dur == prof->T && mv.clock == 0.0f);
    DHT_TRUE(mv.feed == 1.0f);
    rep.done = 0;
    for (k = 0; k < 2 * nmax + (long)HZ; k++) {
        const int lag = (k >= lag0 && k < lag0 + 5);
        DHT_EQ_INT(dh_move_target_f32(&mv, &T), DH_OK);
        DHT_EQ_INT(dh_path_move_eval_f32(prof, p, mv.clock, &E, &v), DH_OK);
        DHT_TRUE(memcmp(&T, &E, sizeof T) == 0);
        c = mv.clock;
        DHT_EQ_INT(dh_move_advance_f32(&mv, dt, lag ? DH_TRACK_LAGGING : DH_TRACK_OK, &rep), DH_OK);
        DHT_TRUE(rep.held == lag && rep.clock == mv.clock && rep.feed == mv.feed);
        DHT_TRUE(rep.feed >= 0.0f && rep.feed <= 1.0f);
        if (lag) DHT_TRUE(rep.feed <= r && !rep.done);
        if (k < lag0) DHT_TRUE(rep.feed == 1.0f && (rep.done || rep.clock == ((c + dt < mv.dur) ? c + dt : mv.dur)));
        if (!rep.done)
            DHT_TRUE(fabs((double)rep.clock - fmin((double)c + (double)rep.feed * dt, (double)mv.dur)) <=
                     2.0 * (double)FLT_EPSILON * (double)mv.dur);
        r = rep.feed;
        if (rep.done) break;
    }
    DHT_TRUE_MSG(rep.done == 1, "no done within %ld periods for T %.9g", k, (double)prof->T);
    DHT_TRUE(memcmp(&T, &p->B, sizeof T) == 0 && mv.clock == mv.dur);
}

static double rlog(double lo, double hi) { return pow(10.0, dht_rand_uniform(lo, hi)); }

/* n random lines and arcs moved within limits spread so that each of the
 * speed, acceleration, centripetal and (jerk) jerk bounds binds in some */
static void random_moves(int n, int jerk)
{
    int it;
    for (it = 0; it < n; it++) {
        dh_path_f32 p;
        ref_path r;
        dh_cart_limits_f32 lim;
        dh_cart_jerk_f32 jk;
        double t0 = dht_rand_uniform(0.3, 1.5), deg = (it % 4 == 0) ? 0.0 : dht_rand_uniform(5.0, 175.0);
        rand_path(&p, &r, it % 2, rlog(-1.0, 3.0), deg);
        lim.vmax = (float)(r.len / t0 * rlog(-0.5, 0.5));
        lim.amax = (float)(lim.vmax / t0 * rlog(0.0, 1.0));
        lim.wmax = (float)((deg > 0.0 ? deg : 90.0) / t0 * rlog(-0.5, 0.5));
        lim.wdmax = (float)(lim.wmax / t0 * rlog(0.0, 1.0));
        if (jerk) {
            jk.jmax = (float)(lim.amax / t0 * rlog(-0.5, 1.5));
            jk.wjmax = (float)(lim.wdmax / t0 * rlog(-0.5, 1.5));
        }
        move_check(&p, &r, &lim, jerk ? &jk : NULL);
    }
    dht_printf("%s: worst speed %.6f, acceleration %.6f, jerk %.6f, angular %.6f %.6f %.6f of the limits\n",
               jerk ? "jerk-limited moves" : "moves", fd_worst[0], fd_worst[1], fd_worst[2], fd_worst[3],
               fd_worst[4], fd_worst[5]);
}

static void moves_within_limits(void) { random_moves(DHT_ITER(60), 0); }
static void jerk_moves_within_limits(void) { random_moves(DHT_ITER(40), 1); }

/* an arc of radius 5 mm, sweep 5 rad, turning 30 degrees, into p and its
 * reference r; limits 500 mm/s, 1000 mm/s^2, 1000 deg/s, 10000 deg/s^2 */
static void small_arc(dh_path_f32 *p, ref_path *r, dh_cart_limits_f32 *lim)
{
    dh_mat4_f32 A, B;
    double pa[3], pb[3];
    float via[3];
    arc_points(5.0, 100.0, 5.0, 0.5, pa, via, pb);
    frames(pa, pb, 30.0, &A, &B);
    DHT_EQ_INT(dh_path_arc_f32(p, &A, via, &B), DH_OK);
    ref_make(r, &A, via, &B, 1);
    lim->vmax = 500.0f;
    lim->amax = 1000.0f;
    lim->wmax = 1000.0f;
    lim->wdmax = 10000.0f;
}

/* the small arc: the centripetal term binds (V = sqrt(1000 * 5 / sqrt 2)
 * = 59.5 mm/s) */
static void small_radius_binds(void)
{
    dh_path_f32 p;
    ref_path r;
    dh_profile_f32 prof;
    dh_cart_limits_f32 lim;
    small_arc(&p, &r, &lim);
    DHT_EQ_INT(dh_path_move_f32(&prof, &p, &lim), DH_OK);
    DHT_TRUE(prof.v * p.length < 60.0f && prof.v * p.length > 59.0f);
    move_check(&p, &r, &lim, NULL);
}

/* the small arc with jmax = 2000 mm/s^3: the jerk's centripetal terms
 * bind (V = cbrt(2000 * 25 / 4) = 23.2 mm/s, At = 2000 * 5 / (12 V) =
 * 35.9 mm/s^2); the executor runs the move through its targets */
static void small_radius_jerk_binds(void)
{
    dh_path_f32 p;
    ref_path r;
    dh_profile_f32 prof;
    dh_cart_limits_f32 lim;
    const dh_cart_jerk_f32 jk = { 2000.0f, 1e6f };
    const double V = cbrt(12500.0), At = 10000.0 / (12.0 * V);
    small_arc(&p, &r, &lim);
    DHT_EQ_INT(dh_path_move_jerk_f32(&prof, &p, &lim, &jk), DH_OK);
    DHT_EQ_INT((int)prof.kind, DH_PROFILE_SCURVE);
    DHT_TRUE_MSG(fabs(prof.v * p.length - V) <= 1e-4 * V, "speed %.9g vs %.9g", (double)(prof.v * p.length), V);
    DHT_TRUE_MSG(fabs(prof.a * p.length - At) <= 1e-4 * At, "acceleration %.9g vs %.9g", (double)(prof.a * p.length),
                 At);
    DHT_TRUE_MSG(fabs(prof.j * p.length - 1000.0) <= 1e-4 * 1000.0, "jerk %.9g", (double)(prof.j * p.length));
    move_check(&p, &r, &lim, &jk);
    move_run(&prof, &p, &lim, &jk);
}

/* without jerk limits dh_path_move_jerk_f32 is dh_path_move_f32 bit for
 * bit, and dh_move_path_jerk_f32 dh_move_path_f32 */
static void jerk_null_is_trapezoid(void)
{
    int it, n = DHT_ITER(50);
    for (it = 0; it < n; it++) {
        dh_path_f32 p;
        ref_path r;
        dh_profile_f32 a, b;
        dh_move_f32 ma, mb;
        dh_cart_limits_f32 lim;
        rand_path(&p, &r, it % 2, rlog(-1.0, 3.0), draw_deg(it));
        lim.vmax = (float)rlog(-1.0, 2.0);
        lim.amax = (float)rlog(-1.0, 2.0);
        lim.wmax = (float)rlog(0.0, 3.0);
        lim.wdmax = (float)rlog(0.0, 3.0);
        DHT_EQ_INT(dh_path_move_f32(&a, &p, &lim), DH_OK);
        memset(&b, 0x55, sizeof b);
        DHT_EQ_INT(dh_path_move_jerk_f32(&b, &p, &lim, NULL), DH_OK);
        DHT_TRUE(memcmp(&a, &b, sizeof a) == 0);
        DHT_EQ_INT((int)a.kind, DH_PROFILE_TRAP);
        DHT_EQ_INT(dh_move_path_f32(&ma, &p, &lim), DH_OK);
        DHT_EQ_INT(dh_move_path_jerk_f32(&mb, &p, &lim, NULL), DH_OK);
        DHT_TRUE(memcmp(&ma.prof[0], &a, sizeof a) == 0 && memcmp(&mb.prof[0], &a, sizeof a) == 0);
        DHT_TRUE(ma.dur == mb.dur && ma.kind == mb.kind && mb.kind == (uint32_t)DH_MOVE_PATH);
    }
}

/* the statuses of the jerk limits: NaN/Inf, <= 0; prof all zero and the
 * move emptied on error */
static void jerk_bad_limits(void)
{
    static const dh_profile_f32 zero = { 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0u };
    const float bad[5] = { NAN, INFINITY, 0.0f, -1.0f, -INFINITY };
    const int want[5] = { DH_ERR_NAN, DH_ERR_NAN, DH_ERR_ARG, DH_ERR_ARG, DH_ERR_NAN };
    dh_cart_limits_f32 lim = { 1.0f, 2.0f, 30.0f, 60.0f };
    dh_mat4_f32 A, B;
    dh_path_f32 p;
    dh_profile_f32 prof;
    dh_move_f32 mv;
    int i, k;
    dh_mat4_trans_f32(0.1f, 0.2f, 0.3f, &A);
    dh_mat4_rotz_f32(40.0f, &B);
    DH_M4(&B, 0, 3) = 10.0f;
    DHT_EQ_INT(dh_path_line_f32(&p, &A, &B), DH_OK);
    for (i = 0; i < 5; i++) {
        for (k = 0; k < 2; k++) {
            const dh_cart_jerk_f32 good = { 5.0f, 100.0f };
            dh_cart_jerk_f32 jk = good;
            if (k == 0) jk.jmax = bad[i];
            else jk.wjmax = bad[i];
            memset(&prof, 0x55, sizeof prof);
            DHT_EQ_INT(dh_path_move_jerk_f32(&prof, &p, &lim, &jk), want[i]);
            DHT_TRUE(memcmp(&prof, &zero, sizeof prof) == 0);
            /* a failed start empties a running move */
            DHT_EQ_INT(dh_move_path_jerk_f32(&mv, &p, &lim, &good), DH_OK);
            DHT_EQ_INT(dh_move_path_jerk_f32(&mv, &p, &lim, &jk), want[i]);
            DHT_EQ_INT((int)mv.kind, DH_MOVE_NONE);
            DHT_EQ_INT(dh_move_target_f32(&mv, &A), DH_ERR_ARG);
        }
    }
    /* a bad Cartesian limit with good jerk limits */
    {
        dh_cart_jerk_f32 jk = { 5.0f, 100.0f };
        lim.amax = 0.0f;
        DHT_EQ_INT(dh_path_move_jerk_f32(&prof, &p, &lim, &jk), DH_ERR_ARG);
        DHT_TRUE(memcmp(&prof, &zero, sizeof prof) == 0);
        lim.amax = NAN;
        DHT_EQ_INT(dh_path_move_jerk_f32(&prof, &p, &lim, &jk), DH_ERR_NAN);
        /* a jerk limit too small for float: s''' or the profile underflows */
        lim.amax = 2.0f;
        jk.jmax = 1e-45f;   /* the least denormal, over a length of 10 */
        DHT_EQ_INT(dh_path_move_jerk_f32(&prof, &p, &lim, &jk), DH_ERR_OVERFLOW);
        DHT_TRUE(memcmp(&prof, &zero, sizeof prof) == 0);
    }
}

/* no length and no angle: duration 0, the frame stays at A */
static void zero_move(void)
{
    dh_mat4_f32 A, T;
    dh_path_f32 p;
    dh_profile_f32 prof;
    dh_cart_limits_f32 lim = { 1.0f, 1.0f, 1.0f, 1.0f };
    float v = -1.0f;
    dh_mat4_rotz_f32(30.0f, &A);
    DH_M4(&A, 0, 3) = 5.0f;
    DHT_EQ_INT(dh_path_line_f32(&p, &A, &A), DH_OK);
    DHT_TRUE(p.length == 0.0f && p.angle == 0.0f);
    DHT_EQ_INT(dh_path_move_f32(&prof, &p, &lim), DH_OK);
    DHT_TRUE(prof.T == 0.0f);
    DHT_EQ_INT(dh_path_move_eval_f32(&prof, &p, 1.0f, &T, &v), DH_OK);
    DHT_TRUE(memcmp(&T, &A, sizeof T) == 0 && v == 0.0f);
    /* a pure rotation: the angular limits alone */
    dh_mat4_rotz_f32(120.0f, &T);
    DH_M4(&T, 0, 3) = 5.0f;
    DHT_EQ_INT(dh_path_line_f32(&p, &A, &T), DH_OK);
    DHT_TRUE(p.length == 0.0f);
    DHT_EQ_INT(dh_path_move_f32(&prof, &p, &lim), DH_OK);
    DHT_NEAR(prof.T, (float)trap_tmin(90.0, 1.0, 1.0), 1e-4f);
}

static const dht_case cases[] = {
    DHT_CASE(lines_vs_double),
    DHT_CASE(arcs_vs_double),
    DHT_CASE(quarter_circle),
    DHT_CASE(moves_within_limits),
    DHT_CASE(small_radius_binds),
    DHT_CASE(zero_move),
    DHT_CASE(jerk_moves_within_limits),
    DHT_CASE(small_radius_jerk_binds),
    DHT_CASE(jerk_null_is_trapezoid),
    DHT_CASE(jerk_bad_limits),
};
DHT_MAIN(cases)
