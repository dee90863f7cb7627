/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_quat.c - quaternions (rot.h) against double-precision references
 * computed here from the textbook formulas with libm.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_ref.h"
#include "dhmath/rot.h"

#define PI_D 3.14159265358979323846

/* Measured bounds (docs/accuracy_rot.md). */
#define Q2M_TOL 6e-7   /* quaternion -> matrix entries, measured 4.9e-7 */
#define M2Q_TOL 2e-7   /* matrix -> quaternion components, measured 1.65e-7 */
#define UNIT_TOL 2.4e-7 /* | |q| - 1 |, measured 1.3e-7 */

typedef struct { double w, x, y, z; } dq;

static void d_normalize(dq *q)
{
    double n = sqrt(q->w * q->w + q->x * q->x + q->y * q->y + q->z * q->z);
    q->w /= n; q->x /= n; q->y /= n; q->z /= n;
}

/* uniformly distributed random unit quaternion (rejection in the 4-ball), w >= 0 */
static void d_rand_q(dq *q)
{
    double n;
    do {
        q->w = dht_rand_uniform(-1.0, 1.0);
        q->x = dht_rand_uniform(-1.0, 1.0);
        q->y = dht_rand_uniform(-1.0, 1.0);
        q->z = dht_rand_uniform(-1.0, 1.0);
        n = q->w * q->w + q->x * q->x + q->y * q->y + q->z * q->z;
    } while (n > 1.0 || n < 1e-4);
    d_normalize(q);
    if (q->w < 0) { q->w = -q->w; q->x = -q->x; q->y = -q->y; q->z = -q->z; }
}

static double q_diff(const dh_quat_f32 *q, const dq *r)
{
    double m = fabs(q->w - r->w), e;
    e = fabs(q->x - r->x); if (!(e <= m)) m = e;
    e = fabs(q->y - r->y); if (!(e <= m)) m = e;
    e = fabs(q->z - r->z); if (!(e <= m)) m = e;
    return m;
}

/* distance up to the sign ambiguity q ~ -q */
static double q_diff_pm(const dh_quat_f32 *q, const dq *r)
{
    dq n;
    double a = q_diff(q, r), b;
    n.w = -r->w; n.x = -r->x; n.y = -r->y; n.z = -r->z;
    b = q_diff(q, &n);
    return a < b ? a : b;
}

static double q_norm_err(const dh_quat_f32 *q)
{
    double w = q->w, x = q->x, y = q->y, z = q->z;
    return fabs(sqrt(w * w + x * x + y * y + z * z) - 1.0);
}

/* ---- quaternion -> matrix ------------------------------------------- */

static void to_mat_vs_double(void)
{
    int it, n = DHT_ITER(100000);
    double worst = 0.0, worst_scaled = 0.0;
    for (it = 0; it < n; it++) {
        dq r, rf;
        dh_quat_f32 q, qs;
        dh_mat3_f32 R;
        dhr_mat3 D;
        double e, sc;
        d_rand_q(&r);
        if (it & 1) { r.w = -r.w; r.x = -r.x; r.y = -r.y; r.z = -r.z; } /* both signs */
        q.w = (float)r.w; q.x = (float)r.x; q.y = (float)r.y; q.z = (float)r.z;
        /* reference: the rotation of the float quaternion actually passed */
        rf.w = q.w; rf.x = q.x; rf.y = q.y; rf.z = q.z;
        d_normalize(&rf);
        dhr_mat3_from_quat(rf.w, rf.x, rf.y, rf.z, &D);
        DHT_EQ_INT(dh_quat_to_mat3_f32(&q, &R), DH_OK);
        e = dhr_mat3_max_diff(&R, &D);
        if (e > worst) worst = e;
        DHT_TRUE_MSG(e <= Q2M_TOL, "entry error %.3g", e);
        /* a non-unit quaternion gives the rotation of q / |q| */
        sc = pow(2.0, dht_rand_uniform(-120.0, 120.0));
        qs.w = (float)(q.w * sc); qs.x = (float)(q.x * sc); qs.y = (float)(q.y * sc); qs.z = (float)(q.z * sc);
        rf.w = qs.w; rf.x = qs.x; rf.y = qs.y; rf.z = qs.z;
        d_normalize(&rf);
        dhr_mat3_from_quat(rf.w, rf.x, rf.y, rf.z, &D);
        DHT_EQ_INT(dh_quat_to_mat3_f32(&qs, &R), DH_OK);
        e = dhr_mat3_max_diff(&R, &D);
        if (e > worst_scaled) worst_scaled = e;
        DHT_TRUE_MSG(e <= Q2M_TOL, "scale %g: entry error %.3g", sc, e);
    }
    dht_printf("quat->mat3: max entry error %.3g (unit), %.3g (scaled by 2^-120..2^120), n = %d\n",
               worst, worst_scaled, n);
}

static void to_mat_special(void)
{
    dh_quat_f32 q;
    dh_mat3_f32 R, Rs;
    int r, c;
    /* identity, and 180 degrees about each axis: exact */
    q.w = 1.0f; q.x = q.y = q.z = 0.0f;
    DHT_EQ_INT(dh_quat_to_mat3_f32(&q, &R), DH_OK);
    for (r = 0; r < 3; r++)
        for (c = 0; c < 3; c++) DHT_EQ_F32_BITS(DH_M3(&R, r, c), r == c ? 1.0f : 0.0f);
    q.w = 0.0f; q.x = 0.0f; q.y = 0.0f; q.z = -3.0f; /* Rz(180), non-unit */
    DHT_EQ_INT(dh_quat_to_mat3_f32(&q, &R), DH_OK);
    for (r = 0; r < 3; r++)
        for (c = 0; c < 3; c++) DHT_EQ_F32_BITS(DH_M3(&R, r, c), r != c ? 0.0f : (r == 2 ? 1.0f : -1.0f));
    /* errors leave R untouched */
    Rs = R;
    q.w = 0.0f; q.x = 0.0f; q.y = 0.0f; q.z = 0.0f;
    DHT_EQ_INT(dh_quat_to_mat3_f32(&q, &R), DH_ERR_ZERO_AXIS);
    q.y = 1e-39f; /* denormal */
    DHT_EQ_INT(dh_quat_to_mat3_f32(&q, &R), DH_ERR_ZERO_AXIS);
    q.y = FLT_MIN; /* smallest normal: fine */
    DHT_EQ_INT(dh_quat_to_mat3_f32(&q, &Rs), DH_OK);
    DHT_NEAR(DH_M3(&Rs, 1, 1), 1.0, 0.0);
    DHT_NEAR(DH_M3(&Rs, 0, 0), -1.0, 0.0);
    Rs = R;
    q.w = NAN;
    DHT_EQ_INT(dh_quat_to_mat3_f32(&q, &R), DH_ERR_NAN);
    q.w = 1.0f; q.z = INFINITY;
    DHT_EQ_INT(dh_quat_to_mat3_f32(&q, &R), DH_ERR_NAN);
    q.z = 0.0f; q.x = NAN; /* each component on its own */
    DHT_EQ_INT(dh_quat_to_mat3_f32(&q, &R), DH_ERR_NAN);
    q.x = 0.0f; q.y = -INFINITY;
    DHT_EQ_INT(dh_quat_to_mat3_f32(&q, &R), DH_ERR_NAN);
    q.y = FLT_MIN;
    q.z = FLT_MAX; q.x = -FLT_MAX; /* huge but finite: 90 deg about (-1, 0, 1) within rounding */
    DHT_EQ_INT(dh_quat_to_mat3_f32(&q, &Rs), DH_OK);
    DHT_NEAR(DH_M3(&Rs, 1, 1), -1.0, Q2M_TOL);
    DHT_TRUE(memcmp(&R, &Rs, sizeof R) != 0);
}

/* ---- matrix -> quaternion -------------------------------------------- */

static void check_canonical(const dh_quat_f32 *q)
{
    uint32_t bits;
    float w = q->w;
    DHT_TRUE(w >= 0.0f);
    memcpy(&bits, &w, 4);
    DHT_TRUE(bits != 0x80000000u); /* never -0 */
}

static void from_mat_random(void)
{
    int it, n = DHT_ITER(100000);
    double worst = 0.0, worst_n = 0.0;
    for (it = 0; it < n; it++) {
        dq r;
        dhr_mat3 D;
        dh_mat3_f32 R;
        dh_quat_f32 q;
        double e;
        d_rand_q(&r);
        dhr_mat3_from_quat(r.w, r.x, r.y, r.z, &D);
        dhr_mat3_to_f32(&D, &R);
        DHT_EQ_INT(dh_mat3_to_quat_f32(&R, &q), DH_OK);
        check_canonical(&q);
        e = (r.w < 1e-6) ? q_diff_pm(&q, &r) : q_diff(&q, &r);
        if (e > worst) worst = e;
        DHT_TRUE_MSG(e <= M2Q_TOL, "component error %.3g (w %.3g)", e, r.w);
        e = q_norm_err(&q);
        if (e > worst_n) worst_n = e;
        DHT_TRUE(e <= UNIT_TOL);
    }
    dht_printf("mat3->quat Haar-random: max component error %.3g, max | |q| - 1 | %.3g, n = %d\n",
               worst, worst_n, n);
}

/*
 * Dense sweeps of the Shepperd branch boundaries: two of |w|, |x|, |y|, |z|
 * equal within 1e-6 relative (every pair), and rotations within 1e-3 deg
 * of 180 (w ~ 0) including exactly 180.
 */
static void from_mat_branch_boundaries(void)
{
    int it, n = DHT_ITER(30000);
    double worst = 0.0;
    for (it = 0; it < n; it++) {
        double c[4], nn;
        dq r;
        dhr_mat3 D;
        dh_mat3_f32 R;
        dh_quat_f32 q;
        double e;
        int a = (int)(dht_rand_u32() % 4u), b = (int)(dht_rand_u32() % 3u), k;
        if (b >= a) b++;
        do {
            nn = 0.0;
            for (k = 0; k < 4; k++) { c[k] = dht_rand_uniform(-1.0, 1.0); nn += c[k] * c[k]; }
        } while (nn > 1.0 || nn < 1e-4);
        if (it % 3 == 0) {
            /* |c_a| == |c_b| (1 + tiny) */
            c[b] = (c[b] < 0 ? -1.0 : 1.0) * fabs(c[a]) * (1.0 + dht_rand_uniform(-1e-6, 1e-6));
        } else if (it % 3 == 1) {
            /* near 180 degrees: w tiny (including 0) */
            c[0] = (it % 2) ? 0.0 : dht_rand_uniform(-1e-5, 1e-5);
        } else {
            /* near 180 and two vector components equal */
            c[0] = dht_rand_uniform(-1e-5, 1e-5);
            if (a == 0) a = 1;
            if (b == 0 || b == a) b = (a % 3) + 1;
            c[b] = (c[b] < 0 ? -1.0 : 1.0) * fabs(c[a]) * (1.0 + dht_rand_uniform(-1e-6, 1e-6));
        }
        r.w = c[0]; r.x = c[1]; r.y = c[2]; r.z = c[3];
        d_normalize(&r);
        if (r.w < 0) { r.w = -r.w; r.x = -r.x; r.y = -r.y; r.z = -r.z; }
        dhr_mat3_from_quat(r.w, r.x, r.y, r.z, &D);
        dhr_mat3_to_f32(&D, &R);
        DHT_EQ_INT(dh_mat3_to_quat_f32(&R, &q), DH_OK);
        check_canonical(&q);
        e = (r.w < 1e-6) ? q_diff_pm(&q, &r) : q_diff(&q, &r);
        if (e > worst) worst = e;
        DHT_TRUE_MSG(e <= M2Q_TOL, "component error %.3g (q %.9g %.9g %.9g %.9g)", e, r.w, r.x, r.y, r.z);
        DHT_TRUE(q_norm_err(&q) <= UNIT_TOL);
    }
    dht_printf("mat3->quat branch boundaries and 180 deg: max component error %.3g, n = %d\n", worst, n);
}

/* At exactly 180 degrees the component of the largest diagonal entry is positive
 * (the axis sign documented for dh_mat3_to_axis_angle_f32 too). */
static void from_mat_180_sign(void)
{
    int it, k;
    for (it = 0; it < DHT_ITER(5000); it++) {
        dq r;
        dhr_mat3 D;
        dh_mat3_f32 R;
        dh_quat_f32 q;
        float diag[3], comp[3];
        int big = 0;
        r.w = 0.0;
        r.x = dht_rand_uniform(-1, 1); r.y = dht_rand_uniform(-1, 1); r.z = dht_rand_uniform(-1, 1);
        d_normalize(&r);
        dhr_mat3_from_quat(r.w, r.x, r.y, r.z, &D);
        dhr_mat3_to_f32(&D, &R);
        /* make it exactly symmetric, as an exact 180-degree rotation is */
        DH_M3(&R, 0, 1) = DH_M3(&R, 1, 0);
        DH_M3(&R, 0, 2) = DH_M3(&R, 2, 0);
        DH_M3(&R, 1, 2) = DH_M3(&R, 2, 1);
        DHT_EQ_INT(dh_mat3_to_quat_f32(&R, &q), DH_OK);
        DHT_EQ_F32_BITS(q.w, 0.0f);
        diag[0] = DH_M3(&R, 0, 0); diag[1] = DH_M3(&R, 1, 1); diag[2] = DH_M3(&R, 2, 2);
        comp[0] = q.x; comp[1] = q.y; comp[2] = q.z;
        for (k = 1; k < 3; k++) if (diag[k] > diag[big]) big = k;
        DHT_TRUE(comp[big] > 0.0f);
        DHT_TRUE(q_diff_pm(&q, &r) <= M2Q_TOL);
    }
}

static void from_mat_exact_cases(void)
{
    /* Rx(180) -> (0, 1, 0, 0) exactly; I -> (1, 0, 0, 0) exactly */
    dh_mat3_f32 R;
    dh_quat_f32 q;
    int r, c;
    for (r = 0; r < 3; r++)
        for (c = 0; c < 3; c++) DH_M3(&R, r, c) = (r == c) ? (r == 0 ? 1.0f : -1.0f) : 0.0f;
    DHT_EQ_INT(dh_mat3_to_quat_f32(&R, &q), DH_OK);
    DHT_EQ_F32_BITS(q.w, 0.0f); DHT_EQ_F32_BITS(q.x, 1.0f);
    DHT_EQ_F32_BITS(q.y, 0.0f); DHT_EQ_F32_BITS(q.z, 0.0f);
    for (r = 0; r < 3; r++)
        for (c = 0; c < 3; c++) DH_M3(&R, r, c) = (r == c) ? 1.0f : 0.0f;
    DHT_EQ_INT(dh_mat3_to_quat_f32(&R, &q), DH_OK);
    DHT_EQ_F32_BITS(q.w, 1.0f); DHT_EQ_F32_BITS(q.x, 0.0f);
    DHT_EQ_F32_BITS(q.y, 0.0f); DHT_EQ_F32_BITS(q.z, 0.0f);
}

static void from_mat_bad_input(void)
{
    dh_mat3_f32 R, Rb;
    dh_quat_f32 q = { 5.0f, 6.0f, 7.0f, 8.0f };
    int r, c;
    for (r = 0; r < 3; r++)
        for (c = 0; c < 3; c++) DH_M3(&R, r, c) = (r == c) ? 1.0f : 0.0f;
    for (c = 0; c < 3; c++)
        for (r = 0; r < 3; r++) {
            Rb = R;
            Rb.m[c][r] = NAN;
            DHT_EQ_INT(dh_mat3_to_quat_f32(&Rb, &q), DH_ERR_NAN);
            Rb.m[c][r] = INFINITY;
            DHT_EQ_INT(dh_mat3_to_quat_f32(&Rb, &q), DH_ERR_NAN);
        }
    Rb = R;
    Rb.m[0][0] = 1.01f;
    DHT_EQ_INT(dh_mat3_to_quat_f32(&Rb, &q), DH_ERR_NOT_RIGID);
    Rb = R;
    Rb.m[2][2] = -1.0f; /* reflection */
    DHT_EQ_INT(dh_mat3_to_quat_f32(&Rb, &q), DH_ERR_NOT_RIGID);
    Rb = R;
    Rb.m[1][0] = 2e-4f; /* shear beyond DH_ROT_TOL */
    DHT_EQ_INT(dh_mat3_to_quat_f32(&Rb, &q), DH_ERR_NOT_RIGID);
    DHT_TRUE(q.w == 5.0f && q.x == 6.0f && q.y == 7.0f && q.z == 8.0f);
    Rb.m[1][0] = 5e-5f; /* within the tolerance: accepted and normalised */
    DHT_EQ_INT(dh_mat3_to_quat_f32(&Rb, &q), DH_OK);
    DHT_TRUE(q_norm_err(&q) <= UNIT_TOL);
}

/* ---- normalisation, product, conjugate, angle-axis ------------------- */

static void normalize_cases(void)
{
    int it;
    double worst = 0.0;
    dh_quat_f32 q, o;
    for (it = 0; it < DHT_ITER(50000); it++) {
        double sc = pow(2.0, dht_rand_uniform(-125.0, 127.0)), e, n;
        dq r;
        r.w = dht_rand_uniform(-1, 1); r.x = dht_rand_uniform(-1, 1);
        r.y = dht_rand_uniform(-1, 1); r.z = dht_rand_uniform(-1, 1);
        q.w = (float)(r.w * sc); q.x = (float)(r.x * sc); q.y = (float)(r.y * sc); q.z = (float)(r.z * sc);
        if (fabs(q.w) < FLT_MIN && fabs(q.x) < FLT_MIN && fabs(q.y) < FLT_MIN && fabs(q.z) < FLT_MIN) continue;
        /* reference: the float input normalised in double */
        r.w = q.w; r.x = q.x; r.y = q.y; r.z = q.z;
        n = sqrt(r.w * r.w + r.x * r.x + r.y * r.y + r.z * r.z);
        r.w /= n; r.x /= n; r.y /= n; r.z /= n;
        DHT_EQ_INT(dh_quat_normalize_f32(&q, &o), DH_OK);
        e = q_diff(&o, &r); /* sign kept */
        if (e > worst) worst = e;
        DHT_TRUE_MSG(e <= 2e-7, "scale %g: error %.3g", sc, e);
        DHT_TRUE(q_norm_err(&o) <= UNIT_TOL);
        /* aliasing */
        DHT_EQ_INT(dh_quat_normalize_f32(&q, &q), DH_OK);
        DHT_TRUE(memcmp(&q, &o, sizeof q) == 0);
    }
    dht_printf("quat normalize over 2^-125..2^127: max component error %.3g\n", worst);
    o.w = 9.0f; o.x = o.y = o.z = 0.0f;
    q.w = q.x = q.y = q.z = 0.0f;
    DHT_EQ_INT(dh_quat_normalize_f32(&q, &o), DH_ERR_ZERO_AXIS);
    q.z = -1e-40f;
    DHT_EQ_INT(dh_quat_normalize_f32(&q, &o), DH_ERR_ZERO_AXIS);
    q.z = NAN;
    DHT_EQ_INT(dh_quat_normalize_f32(&q, &o), DH_ERR_NAN);
    q.z = -INFINITY;
    DHT_EQ_INT(dh_quat_normalize_f32(&q, &o), DH_ERR_NAN);
    DHT_TRUE(o.w == 9.0f);
    q.w = -FLT_MAX; q.x = FLT_MAX; q.y = 0.0f; q.z = 0.0f;
    DHT_EQ_INT(dh_quat_normalize_f32(&q, &o), DH_OK);
    DHT_NEAR(o.w, -sqrt(0.5), 1e-7);
    DHT_NEAR(o.x, sqrt(0.5), 1e-7);
}

static void mul_conj(void)
{
    int it;
    double worst = 0.0;
    for (it = 0; it < DHT_ITER(50000); it++) {
        dq a, b, p;
        dh_quat_f32 fa, fb, fp, fc;
        dh_mat3_f32 Ra, Rb, Rp;
        double e, M[3][3];
        int r, c, k;
        d_rand_q(&a);
        d_rand_q(&b);
        fa.w = (float)a.w; fa.x = (float)a.x; fa.y = (float)a.y; fa.z = (float)a.z;
        fb.w = (float)b.w; fb.x = (float)b.x; fb.y = (float)b.y; fb.z = (float)b.z;
        a.w = fa.w; a.x = fa.x; a.y = fa.y; a.z = fa.z;
        b.w = fb.w; b.x = fb.x; b.y = fb.y; b.z = fb.z;
        p.w = a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z;
        p.x = a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y;
        p.y = a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x;
        p.z = a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w;
        dh_quat_mul_f32(&fa, &fb, &fp);
        e = q_diff(&fp, &p);
        if (e > worst) worst = e;
        DHT_TRUE(e <= 2.4e-7);
        /* R(a b) = R(a) R(b) */
        DHT_EQ_INT(dh_quat_to_mat3_f32(&fa, &Ra), DH_OK);
        DHT_EQ_INT(dh_quat_to_mat3_f32(&fb, &Rb), DH_OK);
        DHT_EQ_INT(dh_quat_to_mat3_f32(&fp, &Rp), DH_OK);
        for (r = 0; r < 3; r++)
            for (c = 0; c < 3; c++) {
                M[r][c] = 0.0;
                for (k = 0; k < 3; k++) M[r][c] += (double)DH_M3(&Ra, r, k) * DH_M3(&Rb, k, c);
                DHT_NEAR(DH_M3(&Rp, r, c), M[r][c], 1e-6);
            }
        /* aliasing: out = a */
        fc = fa;
        dh_quat_mul_f32(&fc, &fb, &fc);
        DHT_TRUE(memcmp(&fc, &fp, sizeof fc) == 0);
        /* q q* = 1 */
        dh_quat_conj_f32(&fa, &fc);
        DHT_TRUE(fc.w == fa.w && fc.x == -fa.x && fc.y == -fa.y && fc.z == -fa.z);
        dh_quat_mul_f32(&fa, &fc, &fc);
        DHT_NEAR(fc.w, 1.0, 3e-7);
        DHT_NEAR(fc.x, 0.0, 1e-7);
        DHT_NEAR(fc.y, 0.0, 1e-7);
        DHT_NEAR(fc.z, 0.0, 1e-7);
    }
    dht_printf("quat mul: max component error %.3g\n", worst);
}

static void from_axis_angle(void)
{
    int it;
    double worst = 0.0;
    dh_quat_f32 q, qs;
    dh_vec3_f32 k;
    for (it = 0; it < DHT_ITER(50000); it++) {
        double kx = dht_rand_uniform(-1, 1), ky = dht_rand_uniform(-1, 1), kz = dht_rand_uniform(-1, 1);
        double deg = dht_rand_uniform(-720.0, 720.0), n, h, e;
        dq r;
        k.x = (float)kx; k.y = (float)ky; k.z = (float)kz;
        if (fabs(k.x) + fabs(k.y) + fabs(k.z) < 1e-3) continue;
        deg = (float)deg;
        n = sqrt((double)k.x * k.x + (double)k.y * k.y + (double)k.z * k.z);
        h = deg * PI_D / 360.0;
        r.w = cos(h); r.x = sin(h) * k.x / n; r.y = sin(h) * k.y / n; r.z = sin(h) * k.z / n;
        DHT_EQ_INT(dh_quat_from_axis_angle_f32(&k, (float)deg, &q), DH_OK);
        e = q_diff(&q, &r);
        if (e > worst) worst = e;
        DHT_TRUE_MSG(e <= 2e-7, "axis-angle -> quat error %.3g", e);
    }
    dht_printf("quat from axis-angle (|deg| <= 720): max component error %.3g\n", worst);
    qs.w = 3.0f; qs.x = qs.y = qs.z = 0.0f;
    q = qs;
    k.x = k.y = k.z = 0.0f;
    DHT_EQ_INT(dh_quat_from_axis_angle_f32(&k, 30.0f, &q), DH_ERR_ZERO_AXIS);
    k.x = 1.0f;
    DHT_EQ_INT(dh_quat_from_axis_angle_f32(&k, NAN, &q), DH_ERR_NAN);
    k.y = INFINITY;
    DHT_EQ_INT(dh_quat_from_axis_angle_f32(&k, 30.0f, &q), DH_ERR_NAN);
    DHT_TRUE(memcmp(&q, &qs, sizeof q) == 0);
    /* 180 about z exactly */
    k.x = 0.0f; k.y = 0.0f; k.z = 2.0f;
    DHT_EQ_INT(dh_quat_from_axis_angle_f32(&k, 180.0f, &q), DH_OK);
    DHT_EQ_F32_BITS(q.w, 0.0f);
    DHT_EQ_F32_BITS(q.z, 1.0f);
}

/* q -> R -> q round trip (float only path), against the double input */
static void round_trip(void)
{
    int it;
    double worst = 0.0;
    for (it = 0; it < DHT_ITER(50000); it++) {
        dq r;
        dh_quat_f32 q, q2;
        dh_mat3_f32 R;
        double e;
        d_rand_q(&r);
        q.w = (float)r.w; q.x = (float)r.x; q.y = (float)r.y; q.z = (float)r.z;
        DHT_EQ_INT(dh_quat_to_mat3_f32(&q, &R), DH_OK);
        DHT_EQ_INT(dh_mat3_to_quat_f32(&R, &q2), DH_OK);
        e = (r.w < 1e-6) ? q_diff_pm(&q2, &r) : q_diff(&q2, &r);
        if (e > worst) worst = e;
        DHT_TRUE_MSG(e <= 3e-7, "round trip error %.3g", e);
    }
    dht_printf("quat -> mat3 -> quat: max component error %.3g\n", worst);
}

static const dht_case cases[] = {
    DHT_CASE(to_mat_vs_double),
    DHT_CASE(to_mat_special),
    DHT_CASE(from_mat_random),
    DHT_CASE(from_mat_branch_boundaries),
    DHT_CASE(from_mat_180_sign),
    DHT_CASE(from_mat_exact_cases),
    DHT_CASE(from_mat_bad_input),
    DHT_CASE(normalize_cases),
    DHT_CASE(mul_conj),
    DHT_CASE(from_axis_angle),
    DHT_CASE(round_trip),
};
DHT_MAIN(cases)
