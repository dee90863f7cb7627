/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_rotvec.c - angle-axis, rotation vector (log / exp), skew / vee,
 * angular velocity, rotation check and re-orthonormalisation (rot.h),
 * against double-precision references computed here with libm.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_ref.h"
#include "dhmath/rot.h"
#include "dhmath/mat4.h"
#include "dhmath/trig.h"

#define PI_D 3.14159265358979323846

/* Measured bounds (docs/accuracy_rot.md): maximum over 12 seeds, or over
 * the 201 seeds of tools/seeds.sh (full counts) where marked "201". */
#define A2M_TOL 4e-7     /* axis-angle -> matrix (3.35e-7, 201) */
/* exp for |phi| <= 4 pi (and huge axis-aligned |phi|): 3.5e-7 (201), and
 * 3.4e-7 over 2.4e7 more random vectors */
#define EXP_TOL 4e-7
#define AXREP_TOL 3e-7   /* matrix -> axis-angle, exact rotation of the result vs input (2.5e-7) */
#define AXANG_TOL 2e-5   /* matrix -> axis-angle, angle error in degrees (1.6e-5) */
#define LOG_TOL 7.5e-7   /* |phi - phi_exact| (rad) for t <= pi - 1e-3 (6.06e-7, 201) */
#define LOGREP_TOL 5.5e-7 /* log within 1e-3 rad of pi: reproduction (4.97e-7, 201) */
#define ANGVEL_TOL 3e-7  /* angular velocity error / max(1, |w|) (2.4e-7) */
#define ORTHO_TOL 4e-7   /* max |(X^T X - I)_ij| after re-orthonormalisation (3.6e-7) */
#define POLAR_TOL 3e-7   /* entry distance to the double polar factor (2.4e-7) */


/* Rodrigues in double for axis k (normalised here) and angle t in radians */
static void d_rot(double kx, double ky, double kz, double t, dhr_mat3 *R)
{
    double n = sqrt(kx * kx + ky * ky + kz * kz), c = cos(t), s = sin(t), v = 1.0 - c;
    kx /= n; ky /= n; kz /= n;
    R->d[0][0] = c + v * kx * kx;      R->d[0][1] = v * kx * ky - s * kz; R->d[0][2] = v * kx * kz + s * ky;
    R->d[1][0] = v * kx * ky + s * kz; R->d[1][1] = c + v * ky * ky;      R->d[1][2] = v * ky * kz - s * kx;
    R->d[2][0] = v * kx * kz - s * ky; R->d[2][1] = v * ky * kz + s * kx; R->d[2][2] = c + v * kz * kz;
}

static void rand_axis(double k[3])
{
    double n;
    do {
        k[0] = dht_rand_uniform(-1, 1); k[1] = dht_rand_uniform(-1, 1); k[2] = dht_rand_uniform(-1, 1);
        n = k[0] * k[0] + k[1] * k[1] + k[2] * k[2];
    } while (n > 1.0 || n < 1e-4);
    n = sqrt(n);
    k[0] /= n; k[1] /= n; k[2] /= n;
}

/* max |(X^T X - I)_ij| in double of a float matrix */
static double ortho_dev(const dh_mat3_f32 *X)
{
    double m = 0.0;
    int i, j, r;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            double s = 0.0;
            for (r = 0; r < 3; r++) s += (double)X->m[i][r] * X->m[j][r];
            s -= (i == j) ? 1.0 : 0.0;
            if (fabs(s) > m) m = fabs(s);
        }
    return m;
}

/* ---- angle-axis -> matrix -------------------------------------------- */

static void axis_angle_to_mat(void)
{
    int it, n = DHT_ITER(100000);
    double worst = 0.0;
    for (it = 0; it < n; it++) {
        double k[3], deg, e;
        dh_vec3_f32 a;
        dh_mat3_f32 R;
        dhr_mat3 D;
        rand_axis(k);
        a.x = (float)(k[0] * dht_rand_uniform(0.01, 100.0)); /* any length */
        a.y = (float)(k[1] * fabs(a.x / k[0]));
        a.z = (float)(k[2] * fabs(a.x / k[0]));
        if (!(fabs(a.x) + fabs(a.y) + fabs(a.z) > 1e-6) || !isfinite(a.y) || !isfinite(a.z)) continue;
        deg = (float)dht_rand_uniform(-720.0, 720.0);
        if (it % 10 == 0) deg = (float)dht_rand_uniform(-1e-3, 1e-3);
        DHT_EQ_INT(dh_axis_angle_to_mat3_f32(&a, (float)deg, &R), DH_OK);
        d_rot(a.x, a.y, a.z, deg * PI_D / 180.0, &D);
        e = dhr_mat3_max_diff(&R, &D);
        if (e > worst) worst = e;
        DHT_TRUE_MSG(e <= A2M_TOL, "axis (%a, %a, %a), deg %.9g: entry error %.3g > bound %.3g",
                     (double)a.x, (double)a.y, (double)a.z, deg, e, A2M_TOL);
    }
    dht_printf("axis-angle -> mat3: max entry error %.3g, n = %d\n", worst, n);
}

/* a coordinate axis gives bitwise Rx/Ry/Rz built from dh_sincos_f32 */
static void axis_angle_coordinate_axes(void)
{
    int it, ax, r, c;
    for (it = 0; it < DHT_ITER(20000); it++) {
        float deg = (it < 33) ? 90.0f * (float)(it - 16) : (float)dht_rand_uniform(-400.0, 400.0);
        float s, co, E[3][3];
        dh_vec3_f32 a;
        dh_mat3_f32 R;
        DHT_EQ_INT(dh_sincos_f32(deg, &s, &co), DH_OK);
        for (ax = 0; ax < 3; ax++) {
            int u = (ax + 1) % 3, w = (ax + 2) % 3;
            float len = (float)dht_rand_uniform(0.5, 50.0);
            a.x = ax == 0 ? len : 0.0f; a.y = ax == 1 ? len : 0.0f; a.z = ax == 2 ? len : 0.0f;
            for (r = 0; r < 3; r++) for (c = 0; c < 3; c++) E[r][c] = (r == c) ? 1.0f : 0.0f;
            E[u][u] = co; E[w][w] = co; E[w][u] = s + 0.0f; E[u][w] = 0.0f - s; /* no -0 */
            DHT_EQ_INT(dh_axis_angle_to_mat3_f32(&a, deg, &R), DH_OK);
            for (r = 0; r < 3; r++)
                for (c = 0; c < 3; c++) DHT_EQ_F32_BITS(DH_M3(&R, r, c), E[r][c]);
        }
    }
}

static void axis_angle_bad_input(void)
{
    dh_vec3_f32 a = { 0.0f, 0.0f, 0.0f };
    dh_mat3_f32 R, Rs;
    memset(&R, 0x5a, sizeof R);
    Rs = R;
    DHT_EQ_INT(dh_axis_angle_to_mat3_f32(&a, 10.0f, &R), DH_ERR_ZERO_AXIS);
    a.y = 1e-39f;
    DHT_EQ_INT(dh_axis_angle_to_mat3_f32(&a, 10.0f, &R), DH_ERR_ZERO_AXIS);
    a.y = 1.0f;
    DHT_EQ_INT(dh_axis_angle_to_mat3_f32(&a, NAN, &R), DH_ERR_NAN);
    DHT_EQ_INT(dh_axis_angle_to_mat3_f32(&a, -INFINITY, &R), DH_ERR_NAN);
    a.z = NAN;
    DHT_EQ_INT(dh_axis_angle_to_mat3_f32(&a, 10.0f, &R), DH_ERR_NAN);
    DHT_TRUE(memcmp(&R, &Rs, sizeof R) == 0);
    /* huge finite axis: normalised without overflow */
    a.x = FLT_MAX; a.y = FLT_MAX; a.z = 0.0f;
    DHT_EQ_INT(dh_axis_angle_to_mat3_f32(&a, 180.0f, &R), DH_OK);
    DHT_NEAR(DH_M3(&R, 0, 1), 1.0, 2.4e-7);
    DHT_NEAR(DH_M3(&R, 2, 2), -1.0, 2.4e-7);
}

/* ---- matrix -> angle-axis -------------------------------------------- */

static void check_axis_angle_of(const dh_mat3_f32 *R, double *rep_err, double *ang_err, double t_ref_deg)
{
    dh_vec3_f32 k;
    float deg;
    dhr_mat3 D;
    double n, e;
    DHT_EQ_INT(dh_mat3_to_axis_angle_f32(R, &k, &deg), DH_OK);
    DHT_TRUE(deg >= 0.0f && deg <= 180.0f);
    n = sqrt((double)k.x * k.x + (double)k.y * k.y + (double)k.z * k.z);
    DHT_NEAR(n, 1.0, 2.4e-7);
    d_rot(k.x, k.y, k.z, deg * PI_D / 180.0, &D);
    e = dhr_mat3_max_diff(R, &D);
    if (e > *rep_err) *rep_err = e;
    DHT_TRUE_MSG(e <= AXREP_TOL, "angle %.9g: reproduction %.3g", t_ref_deg, e);
    e = fabs(deg - t_ref_deg);
    if (e > *ang_err) *ang_err = e;
    DHT_TRUE_MSG(e <= AXANG_TOL, "angle %.9g vs %.12g", (double)deg, t_ref_deg);
}

static void mat_to_axis_angle(void)
{
    int it, n = DHT_ITER(30000);
    double rep = 0.0, ang = 0.0, rep0 = 0.0, ang0 = 0.0, rep180 = 0.0, ang180 = 0.0;
    for (it = 0; it < n; it++) {
        double k[3], t;
        dhr_mat3 D;
        dh_mat3_f32 R;
        rand_axis(k);
        /* anywhere */
        t = dht_rand_uniform(0.0, 180.0);
        d_rot(k[0], k[1], k[2], t * PI_D / 180.0, &D);
        dhr_mat3_to_f32(&D, &R);
        check_axis_angle_of(&R, &rep, &ang, t);
        /* near 0: 1e-9 .. 1e-3 deg */
        t = pow(10.0, dht_rand_uniform(-9.0, -3.0));
        d_rot(k[0], k[1], k[2], t * PI_D / 180.0, &D);
        dhr_mat3_to_f32(&D, &R);
        check_axis_angle_of(&R, &rep0, &ang0, t);
        /* near and at 180 */
        t = (it % 4 == 0) ? 180.0 : 180.0 - pow(10.0, dht_rand_uniform(-9.0, -3.0));
        d_rot(k[0], k[1], k[2], t * PI_D / 180.0, &D);
        dhr_mat3_to_f32(&D, &R);
        check_axis_angle_of(&R, &rep180, &ang180, t);
    }
    dht_printf("mat3 -> axis-angle: reproduction / angle error (deg): random %.3g / %.3g, "
               "near 0 %.3g / %.3g, near and at 180 %.3g / %.3g, n = %d\n",
               rep, ang, rep0, ang0, rep180, ang180, n);
    /* near 0 the extraction must keep the small angle's precision: the
     * band-wide tolerances above are sized for large angles (measured over
     * 12 seeds: reproduction 1.5e-10, angle 1.8e-10 deg; bound 2x) */
    DHT_TRUE_MSG(rep0 <= 3e-10, "near 0: reproduction %.3g > 3e-10", rep0);
    DHT_TRUE_MSG(ang0 <= 4e-10, "near 0: angle error %.3g deg > 4e-10", ang0);
}

static void mat_to_axis_angle_special(void)
{
    dh_mat3_f32 R, Rb;
    dh_mat4_f32 T;
    dh_vec3_f32 k, k4;
    float deg, deg4;
    int r, c, it;
    for (r = 0; r < 3; r++) for (c = 0; c < 3; c++) DH_M3(&R, r, c) = (r == c) ? 1.0f : 0.0f;
    DHT_EQ_INT(dh_mat3_to_axis_angle_f32(&R, &k, &deg), DH_OK);
    DHT_EQ_F32_BITS(deg, 0.0f);
    DHT_TRUE(k.x == 0.0f && k.y == 0.0f && k.z == 1.0f);
    /* the same answer as the 4x4 function (shared algorithm) */
    for (it = 0; it < DHT_ITER(2000); it++) {
        double ax[3];
        dhr_mat3 D;
        rand_axis(ax);
        d_rot(ax[0], ax[1], ax[2], dht_rand_uniform(0.0, PI_D), &D);
        dhr_mat3_to_f32(&D, &R);
        dh_mat4_identity_f32(&T);
        dh_mat4_set_rot_f32(&T, &R);
        DHT_EQ_INT(dh_mat3_to_axis_angle_f32(&R, &k, &deg), DH_OK);
        DHT_EQ_INT(dh_mat4_to_axis_angle_f32(&T, &k4, &deg4), DH_OK);
        DHT_EQ_F32_BITS(deg, deg4);
        DHT_EQ_F32_BITS(k.x, k4.x); DHT_EQ_F32_BITS(k.y, k4.y); DHT_EQ_F32_BITS(k.z, k4.z);
    }
    /* errors */
    k.x = 7.0f; deg = 7.0f;
    for (c = 0; c < 3; c++)
        for (r = 0; r < 3; r++) {
            Rb = R;
            Rb.m[c][r] = NAN;
            DHT_EQ_INT(dh_mat3_to_axis_angle_f32(&Rb, &k, &deg), DH_ERR_NAN);
            Rb.m[c][r] = INFINITY;
            DHT_EQ_INT(dh_mat3_to_axis_angle_f32(&Rb, &k, &deg), DH_ERR_NAN);
        }
    Rb = R;
    for (r = 0; r < 3; r++) Rb.m[0][r] *= 1.001f;
    DHT_EQ_INT(dh_mat3_to_axis_angle_f32(&Rb, &k, &deg), DH_ERR_NOT_RIGID);
    Rb = R;
    for (r = 0; r < 3; r++) Rb.m[0][r] = -Rb.m[0][r];
    DHT_EQ_INT(dh_mat3_to_axis_angle_f32(&Rb, &k, &deg), DH_ERR_NOT_RIGID);
    DHT_TRUE(k.x == 7.0f && deg == 7.0f);
}

/* ---- exp / log -------------------------------------------------------- */

static void exp_map(void)
{
    int it, n = DHT_ITER(100000);
    double worst = 0.0, worst_big = 0.0;
    for (it = 0; it < n; it++) {
        double k[3], t, e;
        dh_vec3_f32 p;
        dh_mat3_f32 R;
        dhr_mat3 D;
        rand_axis(k);
        if (it % 4 == 0) t = pow(10.0, dht_rand_uniform(-30.0, -2.0));
        else t = dht_rand_uniform(0.0, 4.0 * PI_D);
        p.x = (float)(k[0] * t); p.y = (float)(k[1] * t); p.z = (float)(k[2] * t);
        DHT_EQ_INT(dh_rotvec_to_mat3_f32(&p, &R), DH_OK);
        /* reference: the float vector actually passed */
        t = sqrt((double)p.x * p.x + (double)p.y * p.y + (double)p.z * p.z);
        if (t == 0.0) continue;
        d_rot(p.x, p.y, p.z, t, &D);
        e = dhr_mat3_max_diff(&R, &D);
        if (t <= PI_D) {
            if (e > worst) worst = e;
        } else if (e > worst_big) {
            worst_big = e;
        }
        DHT_TRUE_MSG(e <= EXP_TOL, "exp(%a, %a, %a), |phi| %.9g: entry error %.3g > bound %.3g",
                     (double)p.x, (double)p.y, (double)p.z, t, e, EXP_TOL);
    }
    dht_printf("exp (rotvec -> mat3): max entry error %.3g for |phi| <= pi (incl. 1e-30..1e-2), "
               "%.3g for pi < |phi| <= 4 pi\n", worst, worst_big);
}

/* The float |phi| is off by up to 1.5 ulp; this vector's 1.2 ulp (2.9e-7
 * rad) put the entries 4.2e-7 away when |phi| was used as the angle: the
 * length is carried to about 2^-44 relative (src/rot/dh_rotvec.c). */
static void exp_length_rounding(void)
{
    static const float v[][3] = {
        { 0x1.0dc806p+1f, 0x1.be5022p-1f, 0x1.df8018p+0f },
    };
    size_t i;
    for (i = 0; i < sizeof v / sizeof v[0]; i++) {
        dh_vec3_f32 p;
        dh_mat3_f32 R;
        dhr_mat3 D;
        double t, e;
        p.x = v[i][0]; p.y = v[i][1]; p.z = v[i][2];
        DHT_EQ_INT(dh_rotvec_to_mat3_f32(&p, &R), DH_OK);
        t = sqrt((double)p.x * p.x + (double)p.y * p.y + (double)p.z * p.z);
        d_rot(p.x, p.y, p.z, t, &D);
        e = dhr_mat3_max_diff(&R, &D);
        DHT_TRUE_MSG(e <= EXP_TOL, "exp(%a, %a, %a), |phi| %.9g: entry error %.3g > bound %.3g",
                     (double)p.x, (double)p.y, (double)p.z, t, e, EXP_TOL);
    }
}

static void exp_special(void)
{
    dh_vec3_f32 p = { 0.0f, 0.0f, 0.0f };
    dh_mat3_f32 R, Rs;
    int r, c;
    DHT_EQ_INT(dh_rotvec_to_mat3_f32(&p, &R), DH_OK);
    for (r = 0; r < 3; r++)
        for (c = 0; c < 3; c++) DHT_EQ_F32_BITS(DH_M3(&R, r, c), r == c ? 1.0f : 0.0f);
    p.x = 1e-45f; /* smallest denormal: still (a tiny rotation about) x */
    DHT_EQ_INT(dh_rotvec_to_mat3_f32(&p, &R), DH_OK);
    DHT_TRUE(ortho_dev(&R) <= ORTHO_TOL);
    p.x = 1e30f; p.y = -3e30f; p.z = 2e29f; /* huge: finite and a rotation */
    DHT_EQ_INT(dh_rotvec_to_mat3_f32(&p, &R), DH_OK);
    DHT_TRUE(ortho_dev(&R) <= 1e-6);
    /* huge lengths are reduced exactly (dh_sincosf_): an axis-aligned phi
     * has an exact float length, and the result is the rotation by that
     * exact number of radians, as accurate as for small angles */
    {
        int k;
        for (k = 2; k <= 127; k += 5) {
            float t = ldexpf(1.0f + (float)k / 128.0f, k);
            dhr_mat3 D;
            dh_vec3_f32 ph = { 0.0f, 0.0f, 0.0f };
            if (k % 3 == 0) ph.x = -t; else if (k % 3 == 1) ph.y = t; else ph.z = t;
            DHT_EQ_INT(dh_rotvec_to_mat3_f32(&ph, &R), DH_OK);
            d_rot(ph.x, ph.y, ph.z, (double)t, &D);
            DHT_TRUE_MSG(dhr_mat3_max_diff(&R, &D) <= EXP_TOL, "exp(%a, %a, %a): entry error %.3g > bound %.3g",
                         (double)ph.x, (double)ph.y, (double)ph.z, dhr_mat3_max_diff(&R, &D), EXP_TOL);
        }
    }
    p.x = 1e30f; p.y = -3e30f; p.z = 2e29f;
    DHT_EQ_INT(dh_rotvec_to_mat3_f32(&p, &R), DH_OK);
    Rs = R;
    p.y = NAN;
    DHT_EQ_INT(dh_rotvec_to_mat3_f32(&p, &R), DH_ERR_NAN);
    p.y = INFINITY;
    DHT_EQ_INT(dh_rotvec_to_mat3_f32(&p, &R), DH_ERR_NAN);
    p.x = FLT_MAX; p.y = FLT_MAX; /* |phi| overflows float */
    DHT_EQ_INT(dh_rotvec_to_mat3_f32(&p, &R), DH_ERR_NAN);
    DHT_TRUE(memcmp(&R, &Rs, sizeof R) == 0);
}

static void log_map(void)
{
    int it, n = DHT_ITER(50000);
    double worst = 0.0, worst_small = 0.0, worst_pi = 0.0;
    for (it = 0; it < n; it++) {
        double k[3], t, e;
        dh_vec3_f32 p;
        dh_mat3_f32 R;
        dhr_mat3 D;
        rand_axis(k);
        /* away from pi: |phi - phi_exact| */
        t = (it % 3 == 0) ? pow(10.0, dht_rand_uniform(-12.0, -1.0)) : dht_rand_uniform(0.0, PI_D - 1e-3);
        d_rot(k[0], k[1], k[2], t, &D);
        dhr_mat3_to_f32(&D, &R);
        DHT_EQ_INT(dh_mat3_to_rotvec_f32(&R, &p), DH_OK);
        e = fabs(p.x - k[0] * t);
        if (fabs(p.y - k[1] * t) > e) e = fabs(p.y - k[1] * t);
        if (fabs(p.z - k[2] * t) > e) e = fabs(p.z - k[2] * t);
        if (t < 1e-1) { if (e > worst_small) worst_small = e; }
        else if (e > worst) worst = e;
        DHT_TRUE_MSG(e <= LOG_TOL, "log of R = float(Rot((%.17g, %.17g, %.17g), t %.17g)): |phi - phi_exact| "
                     "%.3g > bound %.3g", k[0], k[1], k[2], t, e, LOG_TOL);
        /* within 1e-3 rad of pi, and at pi: only the rotation is meaningful */
        t = (it % 5 == 0) ? PI_D : PI_D - pow(10.0, dht_rand_uniform(-9.0, -3.0));
        d_rot(k[0], k[1], k[2], t, &D);
        dhr_mat3_to_f32(&D, &R);
        DHT_EQ_INT(dh_mat3_to_rotvec_f32(&R, &p), DH_OK);
        e = sqrt((double)p.x * p.x + (double)p.y * p.y + (double)p.z * p.z);
        DHT_TRUE(e <= PI_D + 1e-6);
        d_rot(p.x, p.y, p.z, e, &D);
        e = dhr_mat3_max_diff(&R, &D);
        if (e > worst_pi) worst_pi = e;
        DHT_TRUE_MSG(e <= LOGREP_TOL, "log of R = float(Rot((%.17g, %.17g, %.17g), t %.17g)): reproduction "
                     "%.3g > bound %.3g", k[0], k[1], k[2], t, e, LOGREP_TOL);
    }
    dht_reach_max("log.err", worst); /* rad: |phi - phi_exact| for t in [0.1, pi - 1e-3], bound LOG_TOL */
    dht_printf("log (mat3 -> rotvec): |phi - phi_exact| %.3g (t in [0.1, pi - 1e-3]), %.3g (t < 0.1); "
               "reproduction near pi %.3g\n", worst, worst_small, worst_pi);
}

static void log_special(void)
{
    dh_mat3_f32 R;
    dh_vec3_f32 p = { 9.0f, 9.0f, 9.0f };
    int r, c;
    for (r = 0; r < 3; r++) for (c = 0; c < 3; c++) DH_M3(&R, r, c) = (r == c) ? 1.0f : 0.0f;
    DHT_EQ_INT(dh_mat3_to_rotvec_f32(&R, &p), DH_OK);
    DHT_EQ_F32_BITS(p.x, 0.0f); DHT_EQ_F32_BITS(p.y, 0.0f); DHT_EQ_F32_BITS(p.z, 0.0f);
    /* Ry(180) -> (0, pi, 0) */
    DH_M3(&R, 0, 0) = -1.0f; DH_M3(&R, 2, 2) = -1.0f;
    DHT_EQ_INT(dh_mat3_to_rotvec_f32(&R, &p), DH_OK);
    DHT_EQ_F32_BITS(p.x, 0.0f); DHT_NEAR(p.y, PI_D, 2.4e-7); DHT_EQ_F32_BITS(p.z, 0.0f);
    p.x = 9.0f;
    DH_M3(&R, 1, 2) = NAN;
    DHT_EQ_INT(dh_mat3_to_rotvec_f32(&R, &p), DH_ERR_NAN);
    DH_M3(&R, 1, 2) = 0.5f;
    DHT_EQ_INT(dh_mat3_to_rotvec_f32(&R, &p), DH_ERR_NOT_RIGID);
    DHT_TRUE(p.x == 9.0f);
}

/* ---- skew / vee / angular velocity ----------------------------------- */

static void skew_vee(void)
{
    int it, r, c;
    for (it = 0; it < DHT_ITER(20000); it++) {
        dh_vec3_f32 v, u, w;
        dh_mat3_f32 S, G;
        double cr[3], Su[3];
        volatile float fu;
        double sc = pow(10.0, dht_rand_uniform(-30.0, 30.0));
        v.x = (float)(dht_rand_uniform(-1, 1) * sc); v.y = (float)(dht_rand_uniform(-1, 1) * sc);
        v.z = (float)(dht_rand_uniform(-1, 1) * sc);
        /* through a volatile float: GCC 12 -O2 was seen to keep the unrounded
         * double of a (float) cast in a non-escaping struct member */
        fu = (float)dht_rand_uniform(-1, 1); u.x = fu;
        fu = (float)dht_rand_uniform(-1, 1); u.y = fu;
        fu = (float)dht_rand_uniform(-1, 1); u.z = fu;
        dh_skew_f32(&v, &S);
        /* S u == v x u (double) */
        cr[0] = (double)v.y * u.z - (double)v.z * u.y;
        cr[1] = (double)v.z * u.x - (double)v.x * u.z;
        cr[2] = (double)v.x * u.y - (double)v.y * u.x;
        for (r = 0; r < 3; r++) {
            Su[r] = (double)DH_M3(&S, r, 0) * u.x + (double)DH_M3(&S, r, 1) * u.y + (double)DH_M3(&S, r, 2) * u.z;
            DHT_NEAR(Su[r], cr[r], 1e-15 * sc); /* exact up to double rounding */
        }
        for (r = 0; r < 3; r++) DHT_EQ_F32_BITS(DH_M3(&S, r, r), 0.0f);
        dh_vee_f32(&S, &w);
        DHT_EQ_F32_BITS(w.x, v.x); DHT_EQ_F32_BITS(w.y, v.y); DHT_EQ_F32_BITS(w.z, v.z);
        /* vee of a general matrix: the skew part */
        for (r = 0; r < 3; r++) for (c = 0; c < 3; c++) DH_M3(&G, r, c) = (float)dht_rand_uniform(-1, 1);
        dh_vee_f32(&G, &w);
        DHT_NEAR(w.x, 0.5 * ((double)DH_M3(&G, 2, 1) - DH_M3(&G, 1, 2)), 6e-8);
        DHT_NEAR(w.y, 0.5 * ((double)DH_M3(&G, 0, 2) - DH_M3(&G, 2, 0)), 6e-8);
        DHT_NEAR(w.z, 0.5 * ((double)DH_M3(&G, 1, 0) - DH_M3(&G, 0, 1)), 6e-8);
    }
    {   /* huge entries do not overflow */
        dh_vec3_f32 v = { FLT_MAX, -FLT_MAX, 1.0f }, w;
        dh_mat3_f32 S;
        dh_skew_f32(&v, &S);
        dh_vee_f32(&S, &w);
        DHT_EQ_F32_BITS(w.x, FLT_MAX); DHT_EQ_F32_BITS(w.y, -FLT_MAX); DHT_EQ_F32_BITS(w.z, 1.0f);
    }
}

static void angular_velocity(void)
{
    int it, n = DHT_ITER(50000), r, c, k;
    double worst = 0.0, worst_b = 0.0;
    for (it = 0; it < n; it++) {
        double ax[3], om[3], S[3][3], Rd[3][3], Rdb[3][3], omb[3], e, mag;
        dhr_mat3 D;
        dh_mat3_f32 R, Rdot, Rdotb;
        dh_vec3_f32 w, wb;
        rand_axis(ax);
        d_rot(ax[0], ax[1], ax[2], dht_rand_uniform(0.0, PI_D), &D);
        dhr_mat3_to_f32(&D, &R);
        for (r = 0; r < 3; r++) for (c = 0; c < 3; c++) D.d[r][c] = DH_M3(&R, r, c); /* the float R exactly */
        mag = (it % 2) ? dht_rand_uniform(0.0, 10.0) : dht_rand_uniform(0.0, 1.0);
        om[0] = dht_rand_uniform(-1, 1) * mag; om[1] = dht_rand_uniform(-1, 1) * mag; om[2] = dht_rand_uniform(-1, 1) * mag;
        /* space frame: Rdot = [w] R; body frame: Rdot = R [w_b] with w_b = R^T w */
        S[0][0] = 0; S[0][1] = -om[2]; S[0][2] = om[1];
        S[1][0] = om[2]; S[1][1] = 0; S[1][2] = -om[0];
        S[2][0] = -om[1]; S[2][1] = om[0]; S[2][2] = 0;
        for (r = 0; r < 3; r++)
            for (c = 0; c < 3; c++) {
                Rd[r][c] = 0.0;
                for (k = 0; k < 3; k++) Rd[r][c] += S[r][k] * D.d[k][c];
                DH_M3(&Rdot, r, c) = (float)Rd[r][c];
            }
        for (r = 0; r < 3; r++) {
            omb[r] = 0.0;
            for (k = 0; k < 3; k++) omb[r] += D.d[k][r] * om[k];
        }
        S[0][0] = 0; S[0][1] = -omb[2]; S[0][2] = omb[1];
        S[1][0] = omb[2]; S[1][1] = 0; S[1][2] = -omb[0];
        S[2][0] = -omb[1]; S[2][1] = omb[0]; S[2][2] = 0;
        for (r = 0; r < 3; r++)
            for (c = 0; c < 3; c++) {
                Rdb[r][c] = 0.0;
                for (k = 0; k < 3; k++) Rdb[r][c] += D.d[r][k] * S[k][c];
                DH_M3(&Rdotb, r, c) = (float)Rdb[r][c];
            }
        DHT_EQ_INT(dh_angvel_f32(&R, &Rdot, &w), DH_OK);
        DHT_EQ_INT(dh_angvel_body_f32(&R, &Rdotb, &wb), DH_OK);
        /* the float R is orthonormal only within ~1e-7, so the reference is
         * the exact formula vee(Rdot R^T) on the float data, plus its distance
         * to the true w, which is bounded by the test (scale max(1, |w|)) */
        mag = sqrt(om[0] * om[0] + om[1] * om[1] + om[2] * om[2]);
        e = fabs(w.x - om[0]);
        if (fabs(w.y - om[1]) > e) e = fabs(w.y - om[1]);
        if (fabs(w.z - om[2]) > e) e = fabs(w.z - om[2]);
        e /= (mag > 1.0 ? mag : 1.0);
        if (e > worst) worst = e;
        DHT_TRUE_MSG(e <= ANGVEL_TOL, "space w error %.3g (|w| %.3g)", e, mag);
        e = fabs(wb.x - omb[0]);
        if (fabs(wb.y - omb[1]) > e) e = fabs(wb.y - omb[1]);
        if (fabs(wb.z - omb[2]) > e) e = fabs(wb.z - omb[2]);
        e /= (mag > 1.0 ? mag : 1.0);
        if (e > worst_b) worst_b = e;
        DHT_TRUE_MSG(e <= ANGVEL_TOL, "body w error %.3g (|w| %.3g)", e, mag);
    }
    dht_printf("angular velocity: max error / max(1, |w|): space %.3g, body %.3g\n", worst, worst_b);
}

static void angular_velocity_bad_input(void)
{
    dh_mat3_f32 R, Rdot;
    dh_vec3_f32 w = { 4.0f, 4.0f, 4.0f };
    int r, c;
    for (r = 0; r < 3; r++) for (c = 0; c < 3; c++) { DH_M3(&R, r, c) = (r == c) ? 1.0f : 0.0f; DH_M3(&Rdot, r, c) = 0.0f; }
    DH_M3(&Rdot, 0, 1) = NAN;
    DHT_EQ_INT(dh_angvel_f32(&R, &Rdot, &w), DH_ERR_NAN);
    DHT_EQ_INT(dh_angvel_body_f32(&R, &Rdot, &w), DH_ERR_NAN);
    DH_M3(&Rdot, 0, 1) = 1.0f;
    DH_M3(&R, 2, 2) = INFINITY;
    DHT_EQ_INT(dh_angvel_f32(&R, &Rdot, &w), DH_ERR_NAN);
    DH_M3(&R, 2, 2) = 2.0f;
    DHT_EQ_INT(dh_angvel_f32(&R, &Rdot, &w), DH_ERR_NOT_RIGID);
    DHT_EQ_INT(dh_angvel_body_f32(&R, &Rdot, &w), DH_ERR_NOT_RIGID);
    DHT_TRUE(w.x == 4.0f && w.y == 4.0f && w.z == 4.0f);
}

/* ---- check / orthonormalise ------------------------------------------ */

static void check_rot(void)
{
    dh_mat3_f32 R;
    int r, c;
    for (r = 0; r < 3; r++) for (c = 0; c < 3; c++) DH_M3(&R, r, c) = (r == c) ? 1.0f : 0.0f;
    DHT_EQ_INT(dh_mat3_check_rot_f32(&R, 0.0f), DH_OK);
    DHT_EQ_INT(dh_mat3_check_rot_f32(&R, -1e-6f), DH_ERR_ARG);
    DHT_EQ_INT(dh_mat3_check_rot_f32(&R, NAN), DH_ERR_ARG);
    DHT_EQ_INT(dh_mat3_check_rot_f32(&R, INFINITY), DH_ERR_ARG);
    DH_M3(&R, 0, 1) = 1e-4f;  /* column dot products 1e-4 */
    DHT_EQ_INT(dh_mat3_check_rot_f32(&R, 1.01e-4f), DH_OK);
    DHT_EQ_INT(dh_mat3_check_rot_f32(&R, 0.99e-4f), DH_ERR_NOT_RIGID);
    DH_M3(&R, 0, 1) = 0.0f;
    DH_M3(&R, 1, 1) = -1.0f;  /* orthonormal, det -1 */
    DHT_EQ_INT(dh_mat3_check_rot_f32(&R, 0.1f), DH_ERR_NOT_RIGID);
    DH_M3(&R, 1, 1) = NAN;
    DHT_EQ_INT(dh_mat3_check_rot_f32(&R, 0.1f), DH_ERR_NAN);
}

/* double polar factor by Newton's iteration X <- (X + X^-T) / 2 */
static void d_polar(dhr_mat3 *X)
{
    int it, r, c;
    for (it = 0; it < 60; it++) {
        double (*a)[3] = X->d, det, cof[3][3];
        for (r = 0; r < 3; r++)
            for (c = 0; c < 3; c++) {
                int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
                cof[r][c] = a[r1][c1] * a[r2][c2] - a[r1][c2] * a[r2][c1];
            }
        det = a[0][0] * cof[0][0] + a[0][1] * cof[0][1] + a[0][2] * cof[0][2];
        /* X^-T = cof / det */
        for (r = 0; r < 3; r++)
            for (c = 0; c < 3; c++) a[r][c] = 0.5 * (a[r][c] + cof[r][c] / det);
    }
}

static void orthonormalize(void)
{
    static const double eps[] = { 0.0, 1e-7, 1e-5, 1e-3, 1e-2, 0.05 };
    int it, e_i, r, c, n = DHT_ITER(20000);
    double worst_o = 0.0, worst_p = 0.0, worst_orig[6] = { 0, 0, 0, 0, 0, 0 };
    for (e_i = 0; e_i < 6; e_i++)
        for (it = 0; it < n; it++) {
            double ax[3], e;
            dhr_mat3 D, P;
            dh_mat3_f32 R, O, A;
            rand_axis(ax);
            d_rot(ax[0], ax[1], ax[2], dht_rand_uniform(0.0, PI_D), &D);
            for (r = 0; r < 3; r++)
                for (c = 0; c < 3; c++) DH_M3(&R, r, c) = (float)(D.d[r][c] + dht_rand_uniform(-eps[e_i], eps[e_i]));
            for (r = 0; r < 3; r++) for (c = 0; c < 3; c++) P.d[r][c] = DH_M3(&R, r, c);
            d_polar(&P);
            DHT_EQ_INT(dh_mat3_orthonormalize_f32(&R, &O), DH_OK);
            e = ortho_dev(&O);
            if (e > worst_o) worst_o = e;
            DHT_TRUE_MSG(e <= ORTHO_TOL, "eps %g: orthonormality %.3g", eps[e_i], e);
            e = dhr_mat3_max_diff(&O, &P);
            if (e > worst_p) worst_p = e;
            DHT_TRUE_MSG(e <= POLAR_TOL, "eps %g: distance to polar factor %.3g", eps[e_i], e);
            e = dhr_mat3_max_diff(&O, &D);
            if (e > worst_orig[e_i]) worst_orig[e_i] = e;
            DHT_TRUE(e <= 3.0 * eps[e_i] + 3e-7); /* close to the rotation that was perturbed */
            /* in place */
            A = R;
            DHT_EQ_INT(dh_mat3_orthonormalize_f32(&A, &A), DH_OK);
            DHT_TRUE(memcmp(&A, &O, sizeof A) == 0);
        }
    dht_printf("orthonormalize: max |X^T X - I| %.3g, max distance to double polar factor %.3g; "
               "distance to the unperturbed rotation for eps 0/1e-7/1e-5/1e-3/1e-2/0.05: "
               "%.3g %.3g %.3g %.3g %.3g %.3g\n", worst_o, worst_p, worst_orig[0], worst_orig[1],
               worst_orig[2], worst_orig[3], worst_orig[4], worst_orig[5]);
}

static void orthonormalize_edges(void)
{
    dh_mat3_f32 R, O, Os;
    dhr_mat3 P;
    int r, c;
    /* uniformly scaled by 0.9 (deviation 0.19 < 0.25): converges to the rotation */
    for (r = 0; r < 3; r++) for (c = 0; c < 3; c++) DH_M3(&R, r, c) = 0.0f;
    DH_M3(&R, 0, 1) = -0.9f; DH_M3(&R, 1, 0) = 0.9f; DH_M3(&R, 2, 2) = 0.9f;
    DHT_EQ_INT(dh_mat3_orthonormalize_f32(&R, &O), DH_OK);
    DHT_NEAR(DH_M3(&O, 0, 1), -1.0, 1.2e-7);
    DHT_NEAR(DH_M3(&O, 1, 0), 1.0, 1.2e-7);
    DHT_NEAR(DH_M3(&O, 2, 2), 1.0, 1.2e-7);
    /* 1.1 scale: deviation 0.21 */
    for (r = 0; r < 3; r++) for (c = 0; c < 3; c++) DH_M3(&R, r, c) = (r == c) ? 1.1f : 0.0f;
    DH_M3(&R, 0, 1) = 0.05f;
    for (r = 0; r < 3; r++) for (c = 0; c < 3; c++) P.d[r][c] = DH_M3(&R, r, c);
    d_polar(&P);
    DHT_EQ_INT(dh_mat3_orthonormalize_f32(&R, &O), DH_OK);
    DHT_TRUE(dhr_mat3_max_diff(&O, &P) <= POLAR_TOL);
    Os = O;
    /* too far (deviation 0.44), reflection, NaN: errors, O untouched */
    for (r = 0; r < 3; r++) for (c = 0; c < 3; c++) DH_M3(&R, r, c) = (r == c) ? 1.2f : 0.0f;
    DHT_EQ_INT(dh_mat3_orthonormalize_f32(&R, &O), DH_ERR_NOT_RIGID);
    for (r = 0; r < 3; r++) for (c = 0; c < 3; c++) DH_M3(&R, r, c) = (r == c) ? 1.0f : 0.0f;
    DH_M3(&R, 2, 2) = -1.0f;
    DHT_EQ_INT(dh_mat3_orthonormalize_f32(&R, &O), DH_ERR_NOT_RIGID);
    DH_M3(&R, 2, 2) = NAN;
    DHT_EQ_INT(dh_mat3_orthonormalize_f32(&R, &O), DH_ERR_NAN);
    memset(&R, 0, sizeof R);
    DHT_EQ_INT(dh_mat3_orthonormalize_f32(&R, &O), DH_ERR_NOT_RIGID);
    DHT_TRUE(memcmp(&O, &Os, sizeof O) == 0);
}

static const dht_case cases[] = {
    DHT_CASE(axis_angle_to_mat),
    DHT_CASE(axis_angle_coordinate_axes),
    DHT_CASE(axis_angle_bad_input),
    DHT_CASE(mat_to_axis_angle),
    DHT_CASE(mat_to_axis_angle_special),
    DHT_CASE(exp_map),
    DHT_CASE(exp_special),
    DHT_CASE(exp_length_rounding),
    DHT_CASE(log_map),
    DHT_CASE(log_special),
    DHT_CASE(skew_vee),
    DHT_CASE(angular_velocity),
    DHT_CASE(angular_velocity_bad_input),
    DHT_CASE(check_rot),
    DHT_CASE(orthonormalize),
    DHT_CASE(orthonormalize_edges),
};
DHT_MAIN(cases)
