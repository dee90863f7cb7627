/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_path_q.c - the fixed-point paths and path moves (motion.h:
 * dh_path_line_q, dh_path_arc_q, dh_path_eval_q, dh_path_move_q,
 * dh_path_move_eval_q) in mm (Q16.16), seeded random lines and arcs
 * against double-precision references computed here from the integer
 * inputs: the line p_A + s (p_B - p_A); the circle through p_A, via, p_B
 * (centre from the textbook circumcentre formula, radius, normal, sweep
 * with atan2); the rotation angles from R_A and to R_B (s and 1 - s times
 * the angle between them, dh_pose_interp_q's 1.5e-6 per entry).
 * Bounds of the contracts: a line point within 0.5 LSB of the exact one;
 * an arc point within 4 LSB + 2^-26 R of the circle and at the angle
 * s sweep (the sweep to 2^-23 degrees, dh_atan2_q's 1 LSB refined) along
 * it; every bound below the 5e-3 mm. Moves: the duration at
 * least the double trapezoid of the same rates of s and at most that
 * plus the rounding of the rates (1 LSB of each) and 2 us; speed, total
 * acceleration and angular speed by finite differences of the evaluated
 * frames at 1 kHz within the limits times 1 + 1e-3, over windows of w
 * periods long enough that the position noise N (the path's bound, the
 * profile's position bound 4 + 2^-27 2^e LSB of 2^e, 1 LSB) is at most
 * 2.5e-4 of the limit: 2 N / (w dt) for a speed, 4 N / (w dt)^2 for an
 * acceleration (the rotation's noise 3e-6 rad likewise).
 */
#include <math.h>
#include <string.h>

#include "dht.h"
#include "dhmath/motion.h"

#define PI_D 3.14159265358979323846
#define Q30 1073741824.0
#define QPOS ((double)((int32_t)1 << DH_QPOS_FRAC))
#define REL_FD 1e-3
#define NOISE_FRAC 2.5e-4
#define ROT_NOISE 3e-6 /* rad: two rotations of dh_pose_interp_q's 1.5e-6 */
/* length unit per mm of the random geometry: 1, or 2^(16 - DH_QPOS_FRAC)
 * in a finer format, whose range (2^(31 - DH_QPOS_FRAC) units) is smaller:
 * the same magnitudes in LSB as at DH_QPOS_FRAC 16 */
#define LS (DH_QPOS_FRAC > 16 ? ldexp(1.0, 16 - DH_QPOS_FRAC) : 1.0)

/* a uniformly random unit quaternion (two planar angles) */
static void rot_rand(double *q)
{
    const double u = dht_rand_uniform(0.0, 1.0);
    const double a = dht_rand_uniform(-PI_D, PI_D), b = dht_rand_uniform(-PI_D, PI_D);
    q[0] = sqrt(u) * cos(a);
    q[1] = sqrt(u) * sin(a);
    q[2] = sqrt(1.0 - u) * cos(b);
    q[3] = sqrt(1.0 - u) * sin(b);
}

static void rot_set(dh_frame_q *F, const double *q)
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

/* q turned by deg about a uniformly random axis (polar angle from a
 * uniform cosine, azimuth uniform): b = a r */
static void rot_turn(const double *a, double deg, double *b)
{
    const double ct = dht_rand_uniform(-1.0, 1.0), ph = dht_rand_uniform(-PI_D, PI_D);
    const double h = deg * PI_D / 360.0, st = sqrt(1.0 - ct * ct) * sin(h);
    const double r[4] = { cos(h), st * cos(ph), st * sin(ph), ct * sin(h) };
    b[0] = a[0] * r[0] - a[1] * r[1] - a[2] * r[2] - a[3] * r[3];
    b[1] = a[0] * r[1] + a[1] * r[0] + a[2] * r[3] - a[3] * r[2];
    b[2] = a[0] * r[2] - a[1] * r[3] + a[2] * r[0] + a[3] * r[1];
    b[3] = a[0] * r[3] + a[1] * r[2] - a[2] * r[1] + a[3] * r[0];
}

/* rotation angle (rad) between the Q2.30 rotations of F and G */
static double rot_angle(const dh_frame_q *F, const dh_frame_q *G)
{
    double tr = 0.0, v[3], M[3][3];
    int i, j, k;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            M[i][j] = 0.0;
            for (k = 0; k < 3; k++) M[i][j] += (F->r[i][k] / Q30) * (G->r[j][k] / Q30);
        }
    for (i = 0; i < 3; i++) tr += M[i][i];
    v[0] = M[2][1] - M[1][2];
    v[1] = M[0][2] - M[2][0];
    v[2] = M[1][0] - M[0][1];
    return atan2(sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), tr - 1.0);
}

/* mm of a dh_qpos */
static double mm(int32_t x)
{
    return (double)x / QPOS;
}

static void pos_mm(const dh_frame_q *F, double *p)
{
    int k;
    for (k = 0; k < 3; k++) p[k] = mm(F->p[k]);
}

/* the double circle through three points: centre c, unit normal n (the
 * arc p_a -> via -> p_b turns counterclockwise about it), radius, sweep (rad) */
typedef struct {
    double c[3], n[3], u0[3], R, sweep;
} ref_arc;

static void cross3(const double *a, const double *b, double *o)
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void ref_arc_make(ref_arc *ra, const double *pa, const double *v, const double *pb)
{
    double a[3], b[3], x[3], w[3], cr[3], u1[3], a2, b2, x2, ang;
    int k;
    for (k = 0; k < 3; k++) {
        a[k] = v[k] - pa[k];
        b[k] = pb[k] - pa[k];
    }
    cross3(a, b, x);
    a2 = dot3(a, a);
    b2 = dot3(b, b);
    x2 = dot3(x, x);
    for (k = 0; k < 3; k++) w[k] = a2 * b[k] - b2 * a[k];
    cross3(w, x, cr);
    for (k = 0; k < 3; k++) {
        ra->c[k] = pa[k] + cr[k] / (2.0 * x2);
        ra->n[k] = x[k] / sqrt(x2);
        ra->u0[k] = pa[k] - ra->c[k];
        u1[k] = pb[k] - ra->c[k];
    }
    ra->R = sqrt(dot3(ra->u0, ra->u0));
    cross3(ra->u0, u1, w);
    ang = atan2(dot3(w, ra->n), dot3(ra->u0, u1));
    ra->sweep = (ang <= 0.0) ? ang + 2.0 * PI_D : ang;
}

/* distance of p from the circle, and the angle of p about n from u0 in [0, 2 pi) */
static double ref_arc_dist(const ref_arc *ra, const double *p, double *phi)
{
    double d[3], h, r[3], rho, t[3], ang;
    int k;
    for (k = 0; k < 3; k++) d[k] = p[k] - ra->c[k];
    h = dot3(d, ra->n);
    for (k = 0; k < 3; k++) r[k] = d[k] - h * ra->n[k];
    rho = sqrt(dot3(r, r));
    cross3(ra->u0, r, t);
    ang = atan2(dot3(t, ra->n), dot3(ra->u0, r));
    if (ang < 0.0) ang += 2.0 * PI_D;
    if (ang > 2.0 * PI_D - 1e-6) ang -= 2.0 * PI_D;   /* at p_A from below */
    *phi = ang;
    return sqrt(h * h + (rho - ra->R) * (rho - ra->R));
}

/* random end frames: positions within +-600 mm, B turned by up to 170 degrees */
static void frames_rand(dh_frame_q *A, dh_frame_q *B, double *angle_deg)
{
    double qa[4], qb[4];
    int k;
    rot_rand(qa);
    *angle_deg = dht_rand_uniform(0.0, 170.0);
    if (dht_rand_uniform(0.0, 1.0) < 0.1) *angle_deg = 0.0;
    rot_turn(qa, *angle_deg, qb);
    rot_set(A, qa);
    rot_set(B, qb);
    for (k = 0; k < 3; k++) {
        A->p[k] = (int32_t)llround(dht_rand_uniform(-600.0, 600.0) * LS * QPOS);
        B->p[k] = (int32_t)llround(dht_rand_uniform(-600.0, 600.0) * LS * QPOS);
    }
}

/* a random arc: centre within +-400 mm, radius 0.5..600 mm, p_A at 0, via
 * and p_B at random angles about a random normal; p_A, p_B into A, B */
static void arc_rand(dh_frame_q *A, dh_frame_q *B, dh_qpos via[3])
{
    double c[3], n[3], e1[3], e2[3], R, tb, tv, nn, ang;
    int k;
    do {
        for (k = 0; k < 3; k++) n[k] = dht_rand_uniform(-1.0, 1.0);
        nn = sqrt(dot3(n, n));
    } while (nn < 0.1 || nn > 1.0);
    for (k = 0; k < 3; k++) n[k] /= nn;
    e1[0] = -n[1];
    e1[1] = n[0];
    e1[2] = 0.0;
    if (fabs(n[2]) > 0.9) {
        e1[0] = 0.0;
        e1[1] = -n[2];
        e1[2] = n[1];
    }
    nn = sqrt(dot3(e1, e1));
    for (k = 0; k < 3; k++) e1[k] /= nn;
    cross3(n, e1, e2);
    R = exp(dht_rand_uniform(log(0.5), log(600.0))) * LS;
    tb = dht_rand_uniform(15.0, 345.0) * PI_D / 180.0;
    tv = tb * dht_rand_uniform(0.15, 0.85);
    for (k = 0; k < 3; k++) c[k] = dht_rand_uniform(-400.0, 400.0) * LS;
    for (k = 0; k < 3; k++) {
        A->p[k] = (int32_t)llround((c[k] + R * e1[k]) * QPOS);
        via[k] = (int32_t)llround((c[k] + R * (cos(tv) * e1[k] + sin(tv) * e2[k])) * QPOS);
        B->p[k] = (int32_t)llround((c[k] + R * (cos(tb) * e1[k] + sin(tb) * e2[k])) * QPOS);
    }
    (void)ang;
}

/* the rotation of T at s: s angle from R_A and (1 - s) angle to R_B */
static void check_rot(const dh_path_q *p, const dh_frame_q *T, double s, const char *what, long i)
{
    const double th = rot_angle(&p->A, &p->B);
    const double e0 = fabs(rot_angle(&p->A, T) - s * th), e1 = fabs(rot_angle(T, &p->B) - (1.0 - s) * th);
    DHT_TRUE_MSG(e0 <= ROT_NOISE + 1e-6 && e1 <= ROT_NOISE + 1e-6, "%s %ld: rotation at s %.9g off by %.3g / %.3g rad",
                 what, i, s, e0, e1);
}

static void lines_q_vs_double(void)
{
    long i, n = DHT_ITER(300);
    double worst = 0.0;
    for (i = 0; i < n; i++) {
        dh_frame_q A, B, T;
        dh_path_q p;
        double ang, L = 0.0, d;
        int k, j;
        frames_rand(&A, &B, &ang);
        DHT_EQ_INT(dh_path_line_q(&p, &A, &B), DH_OK);
        for (k = 0; k < 3; k++) L += ((double)B.p[k] - A.p[k]) * ((double)B.p[k] - A.p[k]);
        L = sqrt(L);
        DHT_TRUE_MSG(p.length <= L + 1e-9 && p.length >= L - 1.0, "line %ld: length %ld vs %.3f", i, (long)p.length, L);
        DHT_TRUE_MSG(fabs(p.angle / 65536.0 - rot_angle(&A, &B) * 180.0 / PI_D) <= 2e-5, "line %ld: angle", i);
        for (j = 0; j <= 16; j++) {
            const int32_t s = (j == 16) ? DH_Q30_ONE : (int32_t)(dht_rand_uniform(0.0, 1.0) * Q30);
            DHT_EQ_INT(dh_path_eval_q(&p, s, &T), DH_OK);
            for (k = 0; k < 3; k++) {
                const double ref = A.p[k] + (s / Q30) * ((double)B.p[k] - A.p[k]);
                d = fabs(T.p[k] - ref);
                if (d > worst) worst = d;
                DHT_TRUE_MSG(d <= 0.5 + 1e-6, "line %ld: s %ld component %d off by %.3f LSB", i, (long)s, k, d);
            }
            check_rot(&p, &T, s / Q30, "line", i);
        }
        DHT_EQ_INT(dh_path_eval_q(&p, 0, &T), DH_OK);
        DHT_TRUE(memcmp(&T, &A, sizeof T) == 0);
        DHT_EQ_INT(dh_path_eval_q(&p, DH_Q30_ONE, &T), DH_OK);
        DHT_TRUE(memcmp(&T, &B, sizeof T) == 0);
        DHT_EQ_INT(dh_path_eval_q(&p, -5, &T), DH_OK);
        DHT_TRUE(memcmp(&T, &A, sizeof T) == 0);
        DHT_EQ_INT(dh_path_eval_q(&p, INT32_MAX, &T), DH_OK);
        DHT_TRUE(memcmp(&T, &B, sizeof T) == 0);
    }
    dht_reach_max("path_q.line_lsb", worst);
    dht_printf("%ld lines: largest position error %.3f LSB\n", n, worst);
}

static void arcs_q_vs_double(void)
{
    long i, n = DHT_ITER(300), sing = 0;
    double worst = 0.0, worst_along = 0.0;
    for (i = 0; i < n; i++) {
        dh_frame_q A, B, T;
        dh_qpos via[3];
        dh_path_q p;
        ref_arc ra;
        double ang, pa[3], pv[3], pb[3], pt[3], bound, phi, lref;
        int k, j;
        dh_status st;
        frames_rand(&A, &B, &ang);
        arc_rand(&A, &B, via);
        st = dh_path_arc_q(&p, &A, via, &B);
        if (st == DH_ERR_SINGULAR) {
            sing++;
            continue;
        }
        DHT_EQ_INT(st, DH_OK);
        pos_mm(&A, pa);
        pos_mm(&B, pb);
        for (k = 0; k < 3; k++) pv[k] = mm(via[k]);
        ref_arc_make(&ra, pa, pv, pb);
        bound = (4.0 + ldexp(ra.R * QPOS, -26)) / QPOS;   /* mm */
        {
            /* the radius from the plane's coordinates x, y (rounded to
             * eps <= max(M, R) 2^-29 LSB at the scale of dh_path_q.c):
             * yc moves by at most eps (M + 2 R) / y per unit of them */
            double ab[3], bb[3], cr[3], M, y, eps;
            for (k = 0; k < 3; k++) {
                ab[k] = pv[k] - pa[k];
                bb[k] = pb[k] - pa[k];
            }
            cross3(ab, bb, cr);
            y = sqrt(dot3(cr, cr)) / sqrt(dot3(bb, bb));
            M = fmax(sqrt(dot3(ab, ab)), sqrt(dot3(bb, bb)));
            for (k = 0; k < 3; k++) ab[k] = pb[k] - pv[k];
            M = fmax(M, sqrt(dot3(ab, ab)));
            eps = fmax(M, ra.R) * ldexp(1.0, -29);
            DHT_TRUE_MSG(fabs(mm(p.radius) - ra.R) <= 2.0 / QPOS + 4.0 * eps * (M + 2.0 * ra.R) / y,
                         "arc %ld: radius %.9f vs %.9f", i, mm(p.radius), ra.R);
        }
        DHT_TRUE_MSG(fabs(p.sw / 8388608.0 - ra.sweep * 180.0 / PI_D) <= 2.5e-7 + 4.0 / (QPOS * ra.R) * 180.0 / PI_D,
                     "arc %ld: sweep %.9f vs %.9f deg", i, p.sw / 8388608.0, ra.sweep * 180.0 / PI_D);
        lref = ra.R * ra.sweep;
        DHT_TRUE_MSG(fabs(mm(p.length) - lref) <= 4.0 / QPOS + 1e-8 * lref, "arc %ld: length %.9f vs %.9f", i,
                     mm(p.length), lref);
        /* the via point is on the arc (the evaluation passes it) */
        (void)ref_arc_dist(&ra, pv, &phi);
        DHT_TRUE(phi > 0.0 && phi < ra.sweep);
        for (j = 0; j <= 24; j++) {
            const int32_t s = (j == 24) ? DH_Q30_ONE / 2 : (int32_t)(dht_rand_uniform(0.0, 1.0) * Q30);
            double d, along;
            DHT_EQ_INT(dh_path_eval_q(&p, s, &T), DH_OK);
            pos_mm(&T, pt);
            d = ref_arc_dist(&ra, pt, &phi);
            along = fabs(phi - (s / Q30) * ra.sweep) * ra.R;
            if (d / bound > worst) worst = d / bound;
            if (along > worst_along) worst_along = along;
            DHT_TRUE_MSG(d <= bound && d <= 5e-3, "arc %ld (R %.3f mm, sweep %.3f deg): s %.9f off the circle by %.3g mm",
                         i, ra.R, ra.sweep * 180.0 / PI_D, s / Q30, d);
            DHT_TRUE_MSG(along <= bound + 2.0 * ra.R * (2.5e-7 * PI_D / 180.0) + 4.0 / QPOS,
                         "arc %ld (R %.3f mm): s %.9f along the arc off by %.3g mm", i, ra.R, s / Q30, along);
            check_rot(&p, &T, s / Q30, "arc", i);
        }
        DHT_EQ_INT(dh_path_eval_q(&p, 0, &T), DH_OK);
        DHT_TRUE(memcmp(&T, &A, sizeof T) == 0);
        DHT_EQ_INT(dh_path_eval_q(&p, DH_Q30_ONE, &T), DH_OK);
        DHT_TRUE(memcmp(&T, &B, sizeof T) == 0);
    }
    DHT_TRUE(sing * 10 < n + 10);
    dht_reach_max("path_q.arc_rel", worst);
    dht_printf("%ld arcs (%ld thin): largest distance from the circle %.3f of its bound, along it %.3g mm\n", n, sing,
               worst, worst_along);
}

/* The trapezoid of the rates vs, as (units of s per s^k), duration (s) */
static double trap_T(double vs, double as)
{
    return (vs * vs <= as) ? 1.0 / vs + vs / as : 2.0 * sqrt(1.0 / as);
}

/* finite differences of a move at 1 kHz against lim; noise N (mm) */
static long fd_windows; /* windows checked by check_move_fd */

static void check_move_fd(const dh_profile_q *pr, uint32_t e, const dh_path_q *p, const dh_cart_limits_q *lim,
                          double N, long i)
{
    const double dt = 1e-3, V = lim->vmax / QPOS, Ac = lim->amax / QPOS, W = lim->wmax / 65536.0 * PI_D / 180.0;
    long wv = (long)ceil(2.0 * N / (NOISE_FRAC * V * dt)), wa = (long)ceil(sqrt(4.0 * N / (NOISE_FRAC * Ac)) / dt);
    long ww = (long)ceil(2.0 * ROT_NOISE / (NOISE_FRAC * W * dt));
    long k, nk = (long)(pr->T / 1000u) + 2;
    long w = wv > wa ? wv : wa;
    dh_frame_q F0, F1, F2;
    if (ww > w) w = ww;
    if (w < 1) w = 1;
    if (2 * w > nk) return;   /* too short a move for windows this long */
    for (k = 0; k + 2 * w <= nk; k += (w > 4 ? w / 4 : 1)) {
        double p0[3], p1[3], p2[3], d1[3], d2[3], sp, ac, wr;
        int c;
        fd_windows++;
        DHT_EQ_INT(dh_path_move_eval_q(pr, e, p, (uint32_t)(k * 1000), &F0), DH_OK);
        DHT_EQ_INT(dh_path_move_eval_q(pr, e, p, (uint32_t)((k + w) * 1000), &F1), DH_OK);
        DHT_EQ_INT(dh_path_move_eval_q(pr, e, p, (uint32_t)((k + 2 * w) * 1000), &F2), DH_OK);
        pos_mm(&F0, p0);
        pos_mm(&F1, p1);
        pos_mm(&F2, p2);
        for (c = 0; c < 3; c++) {
            d1[c] = p1[c] - p0[c];
            d2[c] = p2[c] - 2.0 * p1[c] + p0[c];
        }
        sp = sqrt(dot3(d1, d1)) / (w * dt);
        ac = sqrt(dot3(d2, d2)) / ((w * dt) * (w * dt));
        wr = rot_angle(&F0, &F1) / (w * dt);
        DHT_TRUE_MSG(sp <= V * (1 + REL_FD) + 2.0 * N / (w * dt), "move %ld: speed %.6f > %.6f mm/s (w %ld)", i, sp, V, w);
        DHT_TRUE_MSG(ac <= Ac * (1 + REL_FD) + 4.0 * N / ((w * dt) * (w * dt)), "move %ld: acceleration %.6f > %.6f (w %ld)",
                     i, ac, Ac, w);
        DHT_TRUE_MSG(wr <= W * (1 + REL_FD) + 2.0 * ROT_NOISE / (w * dt), "move %ld: angular speed %.6g > %.6g", i, wr, W);
    }
}

static void moves_q_within_limits(void)
{
    long i, n = DHT_ITER(60);
    fd_windows = 0;
    for (i = 0; i < n; i++) {
        dh_frame_q A, B, T;
        dh_qpos via[3];
        dh_path_q p;
        dh_profile_q pr;
        dh_cart_limits_q lim;
        uint32_t e = 99u;
        double ang, V, At, vs, as, Tref, N, R;
        const int arc = (i & 1) != 0;
        frames_rand(&A, &B, &ang);
        if (arc) {
            arc_rand(&A, &B, via);
            if (dh_path_arc_q(&p, &A, via, &B) != DH_OK) continue;
        } else {
            DHT_EQ_INT(dh_path_line_q(&p, &A, &B), DH_OK);
        }
        lim.vmax = (int32_t)(dht_rand_uniform(20.0, 1000.0) * LS * QPOS);
        lim.amax = (int32_t)(dht_rand_uniform(100.0, 5000.0) * LS * QPOS);
        lim.wmax = (int32_t)(dht_rand_uniform(20.0, 180.0) * 65536.0);
        lim.wdmax = (int32_t)(dht_rand_uniform(100.0, 1000.0) * 65536.0);
        DHT_EQ_INT(dh_path_move_q(&pr, &e, &p, &lim), DH_OK);
        DHT_TRUE(e <= 30u);
        DHT_EQ_INT(pr.d, (int32_t)1 << e);
        /* the double reference of the rates of s */
        V = lim.vmax / QPOS;
        At = lim.amax / QPOS;
        R = mm(p.radius);
        if (arc) {
            const double r = sqrt(At * R / sqrt(2.0));
            if (r < V) V = r;
            At = At * sqrt(1.0 - pow(V * V / (R * lim.amax / QPOS), 2.0));
        }
        vs = V / mm(p.length);
        as = At / mm(p.length);
        if (p.angle > 0) {
            vs = fmin(vs, lim.wmax / (double)p.angle);
            as = fmin(as, lim.wdmax / (double)p.angle);
        }
        Tref = trap_T(vs, as);
        DHT_TRUE_MSG(pr.T * 1e-6 >= Tref * (1 - 1e-7) - 1e-6, "move %ld: T %.9f below the minimum %.9f", i, pr.T * 1e-6, Tref);
        DHT_TRUE_MSG(pr.T * 1e-6 <= Tref * (1 + 1e-6 + 2.0 / pr.v + 2.0 / pr.a) + 2e-6, "move %ld: T %.9f vs %.9f", i,
                     pr.T * 1e-6, Tref);
        DHT_EQ_INT(dh_path_move_eval_q(&pr, e, &p, 0u, &T), DH_OK);
        DHT_TRUE(memcmp(&T, &A, sizeof T) == 0);
        DHT_EQ_INT(dh_path_move_eval_q(&pr, e, &p, pr.T, &T), DH_OK);
        DHT_TRUE(memcmp(&T, &B, sizeof T) == 0);
        N = (arc ? 4.0 + ldexp(p.radius, -26) : 0.5) / QPOS + mm(p.length) * (5.0 * ldexp(1.0, -(int)e) + ldexp(1.0, -27)) +
            1.0 / QPOS;
        check_move_fd(&pr, e, &p, &lim, N, i);
    }
    DHT_TRUE(fd_windows > 20 * n);
    dht_printf("%ld moves, %ld windows of finite differences\n", n, fd_windows);
}

static void paths_q_errors(void)
{
    dh_frame_q A, B, bad;
    dh_qpos via[3];
    dh_path_q p, keep;
    dh_profile_q pr;
    dh_cart_limits_q lim = { 100 << 16, 1000 << 16, 90 << 16, 900 << 16 };
    uint32_t e = 7u;
    double ang;
    int k;
    frames_rand(&A, &B, &ang);
    bad = A;
    bad.r[1][2] += 200000;
    memset(&keep, 0x5a, sizeof keep);
    p = keep;
    DHT_EQ_INT(dh_path_line_q(&p, &bad, &B), DH_ERR_NOT_RIGID);
    DHT_EQ_INT(dh_path_line_q(&p, &A, &bad), DH_ERR_NOT_RIGID);
    DHT_TRUE(memcmp(&p, &keep, sizeof p) == 0);
    for (k = 0; k < 3; k++) via[k] = (A.p[k] / 2) + (B.p[k] / 2);   /* on the chord: collinear */
    DHT_EQ_INT(dh_path_arc_q(&p, &A, via, &B), DH_ERR_SINGULAR);
    DHT_EQ_INT(dh_path_arc_q(&p, &A, A.p, &B), DH_ERR_SINGULAR);
    DHT_EQ_INT(dh_path_arc_q(&p, &bad, via, &B), DH_ERR_NOT_RIGID);
    p = keep;
    bad = B;
    bad.p[0] = INT32_MAX;
    A.p[0] = INT32_MIN;
    DHT_EQ_INT(dh_path_line_q(&p, &A, &bad), DH_ERR_OVERFLOW);
    DHT_TRUE(memcmp(&p, &keep, sizeof p) == 0);   /* a line: untouched */
    via[1] += 1 << 20;
    DHT_EQ_INT(dh_path_arc_q(&p, &A, via, &bad), DH_ERR_OVERFLOW);
    memset(&keep, 0, sizeof keep);   /* an arc: all zero, no path */
    DHT_TRUE(memcmp(&p, &keep, sizeof p) == 0);
    DHT_EQ_INT(dh_path_eval_q(&p, 5, &B), DH_ERR_ARG);
    /* a path that holds none */
    memset(&p, 0, sizeof p);
    DHT_EQ_INT(dh_path_eval_q(&p, 5, &A), DH_ERR_ARG);
    DHT_EQ_INT(dh_path_move_q(&pr, &e, &p, &lim), DH_ERR_ARG);
    DHT_EQ_INT(pr.T, 0u);
    DHT_EQ_INT(pr.d, 0);
    DHT_EQ_INT(e, 30u);
    frames_rand(&A, &B, &ang);
    DHT_EQ_INT(dh_path_line_q(&p, &A, &B), DH_OK);
    lim.wmax = 0;
    DHT_EQ_INT(dh_path_move_q(&pr, &e, &p, &lim), DH_ERR_ARG);
    lim.wmax = 90 << 16;
    DHT_EQ_INT(dh_path_move_q(&pr, &e, &p, &lim), DH_OK);
    DHT_EQ_INT(dh_path_move_eval_q(&pr, 31u, &p, 0u, &A), DH_ERR_ARG);
    DHT_EQ_INT(dh_path_move_eval_q(&pr, e == 0u ? 1u : e - 1u, &p, 0u, &A), DH_ERR_ARG);
    /* no motion: length and angle 0 */
    DHT_EQ_INT(dh_path_line_q(&p, &A, &A), DH_OK);
    DHT_EQ_INT(dh_path_move_q(&pr, &e, &p, &lim), DH_OK);
    DHT_EQ_INT(pr.T, 0u);
    DHT_EQ_INT(dh_path_move_eval_q(&pr, e, &p, 5000u, &B), DH_OK);
    DHT_TRUE(memcmp(&B, &A, sizeof B) == 0);
}

static const dht_case cases[] = {
    DHT_CASE(lines_q_vs_double),
    DHT_CASE(arcs_q_vs_double),
    DHT_CASE(moves_q_within_limits),
    DHT_CASE(paths_q_errors),
};
DHT_MAIN(cases)
