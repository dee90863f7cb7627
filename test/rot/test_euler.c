/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_euler.c - Euler angles <-> rotation matrix (rot.h), all 24
 * sequences, against double-precision references built here from the
 * scipy definitions with libm (never from the code under test).
 */
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_ref.h"
#include "dhmath/rot.h"

#define PI_D 3.14159265358979323846

/*
 * Measured bounds (21 seeds, see docs/accuracy_rot.md). The reproduction
 * error compares the exact rotation of the returned float angles with the
 * float input; it is dominated by the rounding of three angles to float
 * degrees (half an ulp at 180 deg is 1.3e-7 rad each).
 */
#define REPRO_TOL 6e-7     /* measured 5.1e-7 */

/* ---- double reference (dhr_mat3 of support_ref.h) ------------------- */

/* the 24 names in dh_euler_seq order: the reference reads the axes from
 * the letters itself */
static const char *const seq_names[24] = {
    "XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX", "XYX", "XZX", "YXY", "YZY", "ZXZ", "ZYZ",
    "xyz", "xzy", "yxz", "yzx", "zxy", "zyx", "xyx", "xzx", "yxy", "yzy", "zxz", "zyz"
};

static void d_elem(int axis, double deg, dhr_mat3 *M)
{
    double t = deg * PI_D / 180.0, c = cos(t), s = sin(t);
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) M->d[i][j] = (i == j) ? 1.0 : 0.0;
    if (axis == 0) { M->d[1][1] = c; M->d[1][2] = -s; M->d[2][1] = s; M->d[2][2] = c; }
    if (axis == 1) { M->d[0][0] = c; M->d[0][2] = s; M->d[2][0] = -s; M->d[2][2] = c; }
    if (axis == 2) { M->d[0][0] = c; M->d[0][1] = -s; M->d[1][0] = s; M->d[1][1] = c; }
}

/* scipy: upper case R = R_l0(a) R_l1(b) R_l2(c); lower case R = R_l2(c) R_l1(b) R_l0(a) */
static void d_euler(int seq, double a, double b, double c, dhr_mat3 *R)
{
    const char *nm = seq_names[seq];
    int ax[3], k, upper = (nm[0] >= 'X' && nm[0] <= 'Z');
    dhr_mat3 A, B, C;
    for (k = 0; k < 3; k++) ax[k] = upper ? nm[k] - 'X' : nm[k] - 'x';
    d_elem(ax[0], a, &A);
    d_elem(ax[1], b, &B);
    d_elem(ax[2], c, &C);
    if (upper) {
        dhr_mat3_mul(&A, &B, R);
        dhr_mat3_mul(R, &C, R);
    } else {
        dhr_mat3_mul(&C, &B, R);
        dhr_mat3_mul(R, &A, R);
    }
}

static int is_proper(int seq)
{
    return seq_names[seq][0] == seq_names[seq][2];
}

/* |a - b| modulo 360, in [0, 180] */
static double ang_diff(double a, double b)
{
    double d = fmod(fabs(a - b), 360.0);
    return d > 180.0 ? 360.0 - d : d;
}

/* exact rotation of the float angles returned, compared with the float input */
static double reproduce_err(const dh_mat3_f32 *R, int seq, const float ang[3])
{
    dhr_mat3 D;
    d_euler(seq, (double)ang[0], (double)ang[1], (double)ang[2], &D);
    return dhr_mat3_max_diff(R, &D);
}

static void check_ranges(int seq, const float ang[3])
{
    DHT_TRUE(ang[0] > -180.0f && ang[0] <= 180.0f);
    DHT_TRUE(ang[2] > -180.0f && ang[2] <= 180.0f);
    if (is_proper(seq)) DHT_TRUE(ang[1] >= 0.0f && ang[1] <= 180.0f);
    else DHT_TRUE(ang[1] >= -90.0f && ang[1] <= 90.0f);
}

/* ---- parser ---------------------------------------------------------- */

static void parse_names(void)
{
    static const char *const bad[] = {
        "", "X", "XY", "XYZW", "XXY", "XYY", "xxz", "XyZ", "xYz", "XYz", "ABC", "xyw",
        "XYZ ", " XYZ", "W", "XY\0Z", "zz", "xy0", "XZZ", "YYY"
    };
    int i;
    dh_euler_seq seq;
    for (i = 0; i < 24; i++) {
        seq = (dh_euler_seq)99;
        DHT_EQ_INT(dh_euler_parse(seq_names[i], &seq), DH_OK);
        DHT_EQ_INT(seq, i);
        DHT_TRUE(strcmp(dh_euler_name((dh_euler_seq)i), seq_names[i]) == 0);
    }
    for (i = 0; i < (int)(sizeof bad / sizeof bad[0]); i++) {
        seq = (dh_euler_seq)77;
        DHT_TRUE_MSG(dh_euler_parse(bad[i], &seq) == DH_ERR_ARG, "accepted \"%s\"", bad[i]);
        DHT_EQ_INT(seq, 77); /* untouched */
    }
    DHT_TRUE(strcmp(dh_euler_name((dh_euler_seq)24), "???") == 0);
    DHT_TRUE(strcmp(dh_euler_name((dh_euler_seq)-1), "???") == 0);
    DHT_EQ_INT(dh_euler_parse(dh_euler_name((dh_euler_seq)24), &seq), DH_ERR_ARG);
    DHT_EQ_INT(DH_EULER_zyz, 23);
    DHT_EQ_INT(DH_EULER_COUNT, 24);
}

/* ---- angles -> matrix ------------------------------------------------ */

static void to_mat_random_vs_double(void)
{
    int seq, it, n = DHT_ITER(20000);
    double worst = 0.0;
    for (seq = 0; seq < 24; seq++) {
        for (it = 0; it < n; it++) {
            float ang[3];
            dh_mat3_f32 R;
            dhr_mat3 D;
            double e;
            ang[0] = (float)dht_rand_uniform(-360.0, 360.0);
            ang[1] = (float)dht_rand_uniform(-360.0, 360.0);
            ang[2] = (float)dht_rand_uniform(-360.0, 360.0);
            DHT_EQ_INT(dh_euler_to_mat3_f32((dh_euler_seq)seq, ang, &R), DH_OK);
            d_euler(seq, ang[0], ang[1], ang[2], &D);
            e = dhr_mat3_max_diff(&R, &D);
            if (e > worst) worst = e;
            DHT_TRUE_MSG(e <= 3e-7, "%s (%.9g %.9g %.9g): entry error %.3g",
                         seq_names[seq], (double)ang[0], (double)ang[1], (double)ang[2], e);
        }
    }
    dht_printf("euler->mat3: max entry error %.3g over %d x 24 random angle sets\n", worst, n);
}

static void to_mat_multiples_of_90_exact(void)
{
    int seq, i, j, k, r, c;
    for (seq = 0; seq < 24; seq++)
        for (i = -4; i <= 4; i++)
            for (j = -4; j <= 4; j++)
                for (k = -4; k <= 4; k++) {
                    float ang[3];
                    dh_mat3_f32 R;
                    dhr_mat3 D;
                    ang[0] = 90.0f * (float)i;
                    ang[1] = 90.0f * (float)j;
                    ang[2] = 90.0f * (float)k;
                    DHT_EQ_INT(dh_euler_to_mat3_f32((dh_euler_seq)seq, ang, &R), DH_OK);
                    d_euler(seq, ang[0], ang[1], ang[2], &D);
                    for (r = 0; r < 3; r++)
                        for (c = 0; c < 3; c++) {
                            /* exact 0 / +-1, and +0 rather than -0 */
                            DHT_EQ_F32_BITS(DH_M3(&R, r, c), (float)floor(D.d[r][c] + 0.5) + 0.0f);
                        }
                }
}

static void extrinsic_is_reversed_intrinsic(void)
{
    int seq, it, r, c;
    for (seq = 0; seq < 12; seq++) {
        /* "xyz" (a, b, c) == "ZYX" (c, b, a): find the reversed upper-case name */
        char rev[4];
        dh_euler_seq up;
        rev[0] = (char)(seq_names[seq][2]);
        rev[1] = (char)(seq_names[seq][1]);
        rev[2] = (char)(seq_names[seq][0]);
        rev[3] = '\0';
        DHT_EQ_INT(dh_euler_parse(rev, &up), DH_OK);
        for (it = 0; it < DHT_ITER(200); it++) {
            float a[3], b[3];
            dh_mat3_f32 R1, R2;
            a[0] = (float)dht_rand_uniform(-400.0, 400.0);
            a[1] = (float)dht_rand_uniform(-400.0, 400.0);
            a[2] = (float)dht_rand_uniform(-400.0, 400.0);
            b[0] = a[2]; b[1] = a[1]; b[2] = a[0];
            DHT_EQ_INT(dh_euler_to_mat3_f32((dh_euler_seq)(seq + 12), a, &R1), DH_OK);
            DHT_EQ_INT(dh_euler_to_mat3_f32(up, b, &R2), DH_OK);
            for (r = 0; r < 3; r++)
                for (c = 0; c < 3; c++) DHT_EQ_F32_BITS(DH_M3(&R1, r, c), DH_M3(&R2, r, c));
        }
    }
}

/* The explicit XYZ matrix of the FloCal notes ("Euler angles to rotation matrix"). */
static void seed_xyz_formula(void)
{
    int it, r, c;
    for (it = 0; it < DHT_ITER(2000); it++) {
        float ang[3];
        dh_mat3_f32 R;
        double al, be, ga, ca, sa, cb, sb, cg, sg, M[3][3];
        ang[0] = (float)dht_rand_uniform(-180.0, 180.0);
        ang[1] = (float)dht_rand_uniform(-180.0, 180.0);
        ang[2] = (float)dht_rand_uniform(-180.0, 180.0);
        al = ang[0] * PI_D / 180.0; be = ang[1] * PI_D / 180.0; ga = ang[2] * PI_D / 180.0;
        ca = cos(al); sa = sin(al); cb = cos(be); sb = sin(be); cg = cos(ga); sg = sin(ga);
        M[0][0] = cb * cg;                 M[0][1] = -cb * sg;                M[0][2] = sb;
        M[1][0] = ca * sg + cg * sa * sb;  M[1][1] = ca * cg - sa * sb * sg;  M[1][2] = -cb * sa;
        M[2][0] = sa * sg - ca * cg * sb;  M[2][1] = cg * sa + ca * sb * sg;  M[2][2] = ca * cb;
        DHT_EQ_INT(dh_euler_to_mat3_f32(DH_EULER_XYZ, ang, &R), DH_OK);
        for (r = 0; r < 3; r++)
            for (c = 0; c < 3; c++) DHT_NEAR(DH_M3(&R, r, c), M[r][c], 4e-7);
        /* and the seed's inverse solution away from gimbal lock */
        if (cb > 0.05) {
            float out[3];
            DHT_EQ_INT(dh_mat3_to_euler_f32(&R, DH_EULER_XYZ, out), DH_OK);
            DHT_NEAR(ang_diff(out[0], atan2(-M[1][2], M[2][2]) * 180.0 / PI_D), 0.0, 1e-4);
            DHT_NEAR(out[1], atan2(M[0][2], sqrt(M[0][0] * M[0][0] + M[0][1] * M[0][1])) * 180.0 / PI_D, 1e-4);
            DHT_NEAR(ang_diff(out[2], atan2(-M[0][1], M[0][0]) * 180.0 / PI_D), 0.0, 1e-4);
        }
    }
}

/* ---- matrix -> angles ------------------------------------------------ */

/* random angles inside the output ranges, middle at least 1 degree from the poles */
static void rand_angles(int seq, double a[3])
{
    a[0] = dht_rand_uniform(-179.999, 180.0);
    a[2] = dht_rand_uniform(-179.999, 180.0);
    if (is_proper(seq)) a[1] = dht_rand_uniform(1.0, 179.0);
    else a[1] = dht_rand_uniform(-89.0, 89.0);
}

static void from_mat_random_roundtrip(void)
{
    int seq, it, k, n = DHT_ITER(20000);
    double worst_rep = 0.0, worst_ang = 0.0;
    for (seq = 0; seq < 24; seq++) {
        for (it = 0; it < n; it++) {
            double a[3], e;
            float out[3];
            dh_mat3_f32 R;
            dhr_mat3 D;
            rand_angles(seq, a);
            d_euler(seq, a[0], a[1], a[2], &D);
            dhr_mat3_to_f32(&D, &R);
            DHT_EQ_INT(dh_mat3_to_euler_f32(&R, (dh_euler_seq)seq, out), DH_OK);
            check_ranges(seq, out);
            for (k = 0; k < 3; k++) {
                e = ang_diff(out[k], a[k]);
                if (e > worst_ang) worst_ang = e;
                DHT_TRUE_MSG(e <= 2.5e-5, "%s angle %d: %.9g vs %.9g", seq_names[seq], k, (double)out[k], a[k]);
            }
            e = reproduce_err(&R, seq, out);
            if (e > worst_rep) worst_rep = e;
            DHT_TRUE_MSG(e <= REPRO_TOL, "%s reproduction %.3g", seq_names[seq], e);
        }
    }
    dht_printf("mat3->euler (middle >= 1 deg from poles): max angle error %.3g deg, "
               "max reproduction error %.3g over %d x 24\n", worst_ang, worst_rep, n);
}

/* Haar-random rotations (random unit quaternion, double) through every sequence. */
static void from_mat_haar_random(void)
{
    int seq, it, n = DHT_ITER(10000);
    double worst = 0.0;
    for (it = 0; it < n; it++) {
        double q[4], nq = 0.0, w, x, y, z;
        dhr_mat3 D;
        dh_mat3_f32 R;
        int k;
        for (k = 0; k < 4; k++) { q[k] = dht_rand_uniform(-1.0, 1.0); nq += q[k] * q[k]; }
        if (nq < 1e-3 || nq > 1.0) { it--; continue; }
        nq = sqrt(nq);
        w = q[0] / nq; x = q[1] / nq; y = q[2] / nq; z = q[3] / nq;
        dhr_mat3_from_quat(w, x, y, z, &D);
        dhr_mat3_to_f32(&D, &R);
        for (seq = 0; seq < 24; seq++) {
            float out[3];
            double e;
            DHT_EQ_INT(dh_mat3_to_euler_f32(&R, (dh_euler_seq)seq, out), DH_OK);
            check_ranges(seq, out);
            e = reproduce_err(&R, seq, out);
            if (e > worst) worst = e;
            DHT_TRUE_MSG(e <= REPRO_TOL, "%s reproduction %.3g", seq_names[seq], e);
        }
    }
    dht_printf("mat3->euler Haar-random rotations: max reproduction error %.3g (%d x 24)\n", worst, n);
}

/* middle angle of the pole: +-90 (Tait-Bryan) or 0 / 180 (proper) */
static double pole_mid(int seq, int which)
{
    if (is_proper(seq)) return which ? 180.0 : 0.0;
    return which ? 90.0 : -90.0;
}

static void at_the_poles(void)
{
    int seq, which, it, n = DHT_ITER(2000);
    double worst = 0.0;
    for (seq = 0; seq < 24; seq++)
        for (which = 0; which < 2; which++)
            for (it = 0; it < n; it++) {
                float ang[3], out[3];
                dh_mat3_f32 R;
                dhr_mat3 D;
                double e, mid = pole_mid(seq, which);
                ang[0] = (float)dht_rand_uniform(-180.0, 180.0);
                ang[1] = (float)mid;
                ang[2] = (float)dht_rand_uniform(-180.0, 180.0);
                /* (1) built by the library: exact sin/cos of the pole */
                DHT_EQ_INT(dh_euler_to_mat3_f32((dh_euler_seq)seq, ang, &R), DH_OK);
                DHT_EQ_INT(dh_mat3_to_euler_f32(&R, (dh_euler_seq)seq, out), DH_OK);
                check_ranges(seq, out);
                DHT_EQ_F32_BITS(out[2], 0.0f);              /* policy: third angle exactly 0 */
                DHT_NEAR(out[1], mid, 1e-5);
                e = reproduce_err(&R, seq, out);
                if (e > worst) worst = e;
                DHT_TRUE_MSG(e <= REPRO_TOL, "%s pole %g: reproduction %.3g", seq_names[seq], mid, e);
                /* (2) the exact matrix rounded to float */
                d_euler(seq, ang[0], mid, ang[2], &D);
                dhr_mat3_to_f32(&D, &R);
                DHT_EQ_INT(dh_mat3_to_euler_f32(&R, (dh_euler_seq)seq, out), DH_OK);
                check_ranges(seq, out);
                DHT_NEAR(out[1], mid, 1e-5);
                e = reproduce_err(&R, seq, out);
                if (e > worst) worst = e;
                DHT_TRUE_MSG(e <= REPRO_TOL, "%s pole %g (rounded): reproduction %.3g", seq_names[seq], mid, e);
            }
    dht_printf("mat3->euler at the poles: max reproduction error %.3g\n", worst);
}

/* Dense sweep within 1e-4 degree of each pole (log-uniform distance 1e-9 .. 1e-4 deg
 * and uniform 0 .. 1e-4 deg), approached from inside the range. */
static void near_the_poles(void)
{
    int seq, which, it, n = DHT_ITER(3000);
    double worst = 0.0, worst_mid = 0.0;
    for (seq = 0; seq < 24; seq++)
        for (which = 0; which < 2; which++)
            for (it = 0; it < n; it++) {
                double mid = pole_mid(seq, which), delta, b, a0, a2, e;
                float out[3];
                dh_mat3_f32 R;
                dhr_mat3 D;
                if (it & 1) delta = pow(10.0, dht_rand_uniform(-9.0, -4.0));
                else delta = dht_rand_uniform(0.0, 1e-4);
                /* towards the inside of the range */
                b = (mid > 0.0) ? mid - delta : mid + delta;
                a0 = dht_rand_uniform(-180.0, 180.0);
                a2 = dht_rand_uniform(-180.0, 180.0);
                d_euler(seq, a0, b, a2, &D);
                dhr_mat3_to_f32(&D, &R);
                DHT_EQ_INT(dh_mat3_to_euler_f32(&R, (dh_euler_seq)seq, out), DH_OK);
                check_ranges(seq, out);
                e = fabs(out[1] - b);
                if (e > worst_mid) worst_mid = e;
                DHT_TRUE_MSG(e <= 1e-5, "%s middle %.9g vs %.12g", seq_names[seq], (double)out[1], b);
                e = reproduce_err(&R, seq, out);
                if (e > worst) worst = e;
                DHT_TRUE_MSG(e <= REPRO_TOL, "%s middle %.12g: reproduction %.3g", seq_names[seq], b, e);
            }
    dht_printf("mat3->euler within 1e-4 deg of the poles: max reproduction error %.3g, "
               "middle angle error %.3g deg\n", worst, worst_mid);
}

/* ---- errors ---------------------------------------------------------- */

static void bad_input(void)
{
    float ang[3] = { 10.0f, 20.0f, 30.0f }, out[3] = { 7.0f, 7.0f, 7.0f };
    dh_mat3_f32 R, Rb, Rsave;
    int r, c, seq;
    DHT_EQ_INT(dh_euler_to_mat3_f32(DH_EULER_ZYX, ang, &R), DH_OK);
    Rsave = R;

    /* bad sequence */
    DHT_EQ_INT(dh_euler_to_mat3_f32((dh_euler_seq)24, ang, &R), DH_ERR_ARG);
    DHT_EQ_INT(dh_euler_to_mat3_f32((dh_euler_seq)-1, ang, &R), DH_ERR_ARG);
    DHT_EQ_INT(dh_mat3_to_euler_f32(&R, (dh_euler_seq)24, out), DH_ERR_ARG);
    DHT_TRUE(memcmp(&R, &Rsave, sizeof R) == 0);
    DHT_TRUE(out[0] == 7.0f && out[1] == 7.0f && out[2] == 7.0f);

    /* non-finite angles */
    for (r = 0; r < 3; r++) {
        float bad[3] = { 1.0f, 2.0f, 3.0f };
        bad[r] = NAN;
        DHT_EQ_INT(dh_euler_to_mat3_f32(DH_EULER_xyz, bad, &R), DH_ERR_NAN);
        bad[r] = INFINITY;
        DHT_EQ_INT(dh_euler_to_mat3_f32(DH_EULER_ZXZ, bad, &R), DH_ERR_NAN);
        bad[r] = -INFINITY;
        DHT_EQ_INT(dh_euler_to_mat3_f32(DH_EULER_XYZ, bad, &R), DH_ERR_NAN);
    }
    DHT_TRUE(memcmp(&R, &Rsave, sizeof R) == 0);

    for (seq = 0; seq < 24; seq++) {
        /* NaN / Inf entries */
        for (c = 0; c < 3; c++)
            for (r = 0; r < 3; r++) {
                Rb = Rsave;
                Rb.m[c][r] = NAN;
                DHT_EQ_INT(dh_mat3_to_euler_f32(&Rb, (dh_euler_seq)seq, out), DH_ERR_NAN);
                Rb.m[c][r] = -INFINITY;
                DHT_EQ_INT(dh_mat3_to_euler_f32(&Rb, (dh_euler_seq)seq, out), DH_ERR_NAN);
            }
        /* scaled, sheared, reflected, zero */
        Rb = Rsave;
        for (c = 0; c < 3; c++) for (r = 0; r < 3; r++) Rb.m[c][r] *= 1.001f;
        DHT_EQ_INT(dh_mat3_to_euler_f32(&Rb, (dh_euler_seq)seq, out), DH_ERR_NOT_RIGID);
        Rb = Rsave;
        Rb.m[1][0] += 0.01f;
        DHT_EQ_INT(dh_mat3_to_euler_f32(&Rb, (dh_euler_seq)seq, out), DH_ERR_NOT_RIGID);
        Rb = Rsave;
        for (r = 0; r < 3; r++) Rb.m[2][r] = -Rb.m[2][r]; /* det -1, orthonormal */
        DHT_EQ_INT(dh_mat3_to_euler_f32(&Rb, (dh_euler_seq)seq, out), DH_ERR_NOT_RIGID);
        memset(&Rb, 0, sizeof Rb);
        DHT_EQ_INT(dh_mat3_to_euler_f32(&Rb, (dh_euler_seq)seq, out), DH_ERR_NOT_RIGID);
        DHT_TRUE(out[0] == 7.0f && out[1] == 7.0f && out[2] == 7.0f);
        /* within the tolerance: accepted, and reproduces the rotation closely */
        Rb = Rsave;
        Rb.m[0][1] += 4e-5f;
        DHT_EQ_INT(dh_mat3_to_euler_f32(&Rb, (dh_euler_seq)seq, out), DH_OK);
        {
            dhr_mat3 D;
            d_euler(seq, out[0], out[1], out[2], &D);
            DHT_TRUE(dhr_mat3_max_diff(&Rsave, &D) <= 1e-4);
        }
        out[0] = out[1] = out[2] = 7.0f;
    }
}

static const dht_case cases[] = {
    DHT_CASE(parse_names),
    DHT_CASE(to_mat_random_vs_double),
    DHT_CASE(to_mat_multiples_of_90_exact),
    DHT_CASE(extrinsic_is_reversed_intrinsic),
    DHT_CASE(seed_xyz_formula),
    DHT_CASE(from_mat_random_roundtrip),
    DHT_CASE(from_mat_haar_random),
    DHT_CASE(at_the_poles),
    DHT_CASE(near_the_poles),
    DHT_CASE(bad_input),
};
DHT_MAIN(cases)
