/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_errors_rot.c - bad input to the rotation conversions of rot.h
 * (docs/errors.md, section rot.h): Euler angles, quaternions,
 * angle-axis, rotation vector, angular velocity, checks and
 * re-orthonormalisation.
 *
 * Extraction functions (matrix -> parameters) check their input and do not
 * re-orthonormalise it: NaN/Inf -> DH_ERR_NAN, beyond DH_ROT_TOL or a
 * reflection -> DH_ERR_NOT_RIGID, within the tolerance it is used as it is.
 * Every error leaves the outputs untouched (canary), also when the output
 * aliases the input.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_canary.h"
#include "dhmath/rot.h"

#define PI_D 3.14159265358979323846


/* NaN, +Inf, -Inf and a negative NaN payload variant */
static float bad_value_nan(unsigned k)
{
    static const uint32_t b[4] = { 0x7FC00000u, 0x7F800000u, 0xFF800000u, 0xFF800001u };
    return f32_bits(b[k & 3u]);
}

/* R = Rot(k, deg) in double (Rodrigues), rounded to float */
static void rot_ref(dh_mat3_f32 *R, double kx, double ky, double kz, double deg)
{
    const double n = sqrt(kx * kx + ky * ky + kz * kz);
    const double x = kx / n, y = ky / n, z = kz / n, t = deg * PI_D / 180.0;
    const double c = cos(t), s = sin(t), v = 1.0 - c;
    DH_M3(R, 0, 0) = (float)(x * x * v + c);
    DH_M3(R, 0, 1) = (float)(x * y * v - z * s);
    DH_M3(R, 0, 2) = (float)(x * z * v + y * s);
    DH_M3(R, 1, 0) = (float)(x * y * v + z * s);
    DH_M3(R, 1, 1) = (float)(y * y * v + c);
    DH_M3(R, 1, 2) = (float)(y * z * v - x * s);
    DH_M3(R, 2, 0) = (float)(x * z * v - y * s);
    DH_M3(R, 2, 1) = (float)(y * z * v + x * s);
    DH_M3(R, 2, 2) = (float)(z * z * v + c);
}

/* the non-rotations every extraction must reject: scaled by 1.001, 0.5 and
 * 0, sheared, one column negated (det -1), -I, the transpose of a reflection */
static void non_rotation(dh_mat3_f32 *R, unsigned k)
{
    unsigned i;
    rot_ref(R, 1.0, -2.0, 0.5, 37.0);
    switch (k) {
    case 0: for (i = 0; i < 9; i++) R->m[i / 3][i % 3] *= 1.001f; break;
    case 1: for (i = 0; i < 9; i++) R->m[i / 3][i % 3] *= 0.5f; break;
    case 2: memset(R, 0, sizeof *R); break;
    case 3: R->m[1][0] += 1e-3f; break;
    case 4: for (i = 0; i < 3; i++) R->m[2][i] = -R->m[2][i]; break;
    default:
        memset(R, 0, sizeof *R);
        R->m[0][0] = -1.0f; R->m[1][1] = -1.0f; R->m[2][2] = -1.0f;
        break;
    }
}
#define N_NONROT 6u

/* every extraction on one input; returns only if all gave `want`, with
 * the outputs untouched when `want` is an error */
#undef UNTOUCHED
#define UNTOUCHED(x) DHT_TRUE_MSG(want == DH_OK || is_canary(&(x), sizeof(x)), "%s written on error", #x)
static dh_status want = DH_ERR_ARG; /* DH_OK only inside extract_all */
static void extract_all(const dh_mat3_f32 *R, dh_status want_)
{
    dh_vec3_f32 v;
    float f, ang[3];
    dh_quat_f32 q;
    dh_mat3_f32 out, Rd;
    unsigned s;
    want = want_;
    CANARY(v); CANARY(f); CANARY(ang); CANARY(q); CANARY(out);
    DHT_EQ_INT(dh_mat3_to_axis_angle_f32(R, &v, &f), want);
    UNTOUCHED(v);
    UNTOUCHED(f);
    DHT_EQ_INT(dh_mat3_to_rotvec_f32(R, &v), want);
    UNTOUCHED(v);
    DHT_EQ_INT(dh_mat3_to_quat_f32(R, &q), want);
    UNTOUCHED(q);
    for (s = 0; s < DH_EULER_COUNT; s++) {
        DHT_EQ_INT(dh_mat3_to_euler_f32(R, (dh_euler_seq)s, ang), want);
        UNTOUCHED(ang);
    }
    DHT_EQ_INT(dh_mat3_check_rot_f32(R, DH_ROT_TOL), want);
    memset(&Rd, 0, sizeof Rd);
    DHT_EQ_INT(dh_angvel_f32(R, &Rd, &v), want);
    UNTOUCHED(v);
    DHT_EQ_INT(dh_angvel_body_f32(R, &Rd, &v), want);
    UNTOUCHED(v);
    if (want == DH_ERR_NAN) {
        DHT_EQ_INT(dh_mat3_orthonormalize_f32(R, &out), DH_ERR_NAN);
        UNTOUCHED(out);
    }
    want = DH_ERR_ARG; /* every later UNTOUCHED checks */
}

/* NaN/Inf in any entry -> DH_ERR_NAN everywhere */
static void rot_extract_nan(void)
{
    unsigned e, k;
    for (e = 0; e < 9; e++) {
        for (k = 0; k < 4; k++) {
            dh_mat3_f32 R;
            rot_ref(&R, 0.3, 0.4, -0.5, 100.0);
            R.m[e / 3][e % 3] = bad_value_nan(k);
            extract_all(&R, DH_ERR_NAN);
        }
    }
}

/* non-rotations -> DH_ERR_NOT_RIGID everywhere; the re-orthonormaliser
 * refuses those too far away or reflected, repairs the small ones */
static void rot_extract_not_rigid(void)
{
    unsigned k;
    for (k = 0; k < N_NONROT; k++) {
        dh_mat3_f32 R, out;
        dh_status st;
        non_rotation(&R, k);
        extract_all(&R, DH_ERR_NOT_RIGID);
        CANARY(out);
        st = dh_mat3_orthonormalize_f32(&R, &out);
        if (k == 0 || k == 3) {
            /* drifted by 1e-3: repaired into a rotation */
            DHT_EQ_INT(st, DH_OK);
            extract_all(&out, DH_OK);
        } else {
            DHT_EQ_INT(st, DH_ERR_NOT_RIGID);
            UNTOUCHED(out);
        }
    }
    /* within the tolerance (deviation 4e-5): accepted and used as is, not
     * re-orthonormalised -- the results still describe it closely */
    {
        dh_mat3_f32 R;
        dh_vec3_f32 ax;
        float deg;
        rot_ref(&R, 0.0, 0.0, 1.0, 30.0);
        DH_M3(&R, 0, 0) *= 1.00002f;
        DHT_EQ_INT(dh_mat3_check_rot_f32(&R, DH_ROT_TOL), DH_OK);
        DHT_EQ_INT(dh_mat3_to_axis_angle_f32(&R, &ax, &deg), DH_OK);
        DHT_NEAR(deg, 30.0, 5e-3);
        DHT_NEAR(ax.z, 1.0, 1e-6);
    }
}

/* orthonormalise: error leaves out untouched also when out == R; the
 * deviation limit DH_ROT_ORTHO_MAX_DEV */
static void rot_orthonormalize_bad(void)
{
    dh_mat3_f32 R, S;
    rot_ref(&R, 1.0, 1.0, 0.0, 50.0);
    R.m[0][0] += 0.3f; /* deviation ~0.6 > 0.25 */
    S = R;
    DHT_EQ_INT(dh_mat3_orthonormalize_f32(&R, &R), DH_ERR_NOT_RIGID);
    DHT_TRUE(memcmp(&R, &S, sizeof R) == 0);
    R.m[0][0] = bad_value_nan(0);
    S = R;
    DHT_EQ_INT(dh_mat3_orthonormalize_f32(&R, &R), DH_ERR_NAN);
    DHT_TRUE(memcmp(&R, &S, sizeof R) == 0);
    /* entries whose squares overflow */
    rot_ref(&R, 1.0, 1.0, 0.0, 50.0);
    R.m[1][1] = 1e30f;
    DHT_EQ_INT(dh_mat3_orthonormalize_f32(&R, &S), DH_ERR_NOT_RIGID);
}

/* check: tol negative, NaN or infinite -> ARG */
static void rot_check_bad_tol(void)
{
    dh_mat3_f32 R;
    rot_ref(&R, 0.0, 1.0, 0.0, 10.0);
    DHT_EQ_INT(dh_mat3_check_rot_f32(&R, -1e-9f), DH_ERR_ARG);
    DHT_EQ_INT(dh_mat3_check_rot_f32(&R, bad_value_nan(0)), DH_ERR_ARG);
    DHT_EQ_INT(dh_mat3_check_rot_f32(&R, bad_value_nan(1)), DH_ERR_ARG);
    DHT_EQ_INT(dh_mat3_check_rot_f32(&R, bad_value_nan(2)), DH_ERR_ARG);
    DHT_EQ_INT(dh_mat3_check_rot_f32(&R, -0.0f), dh_mat3_check_rot_f32(&R, 0.0f)); /* -0 is 0 */
    DHT_EQ_INT(dh_mat3_check_rot_f32(&R, FLT_MAX), DH_OK);
}

/* Euler: sequence names, out-of-range sequences, NaN/Inf angles */
static void rot_euler_bad(void)
{
    static const char *bad_names[] = { "", "X", "XY", "XYZW", "XXY", "XYY", "XyZ", "xYz", "ABC",
                                       "xyzz", "XY\0Z", "ZZZ", "x y" };
    dh_euler_seq seq;
    dh_mat3_f32 R;
    float ang[3];
    unsigned i, k, s;
    for (i = 0; i < sizeof bad_names / sizeof bad_names[0]; i++) {
        CANARY(seq);
        DHT_EQ_INT(dh_euler_parse(bad_names[i], &seq), DH_ERR_ARG);
        UNTOUCHED(seq);
    }
    DHT_TRUE(strcmp(dh_euler_name((dh_euler_seq)DH_EULER_COUNT), "???") == 0);
    DHT_TRUE(strcmp(dh_euler_name((dh_euler_seq)-1), "???") == 0);
    DHT_EQ_INT(dh_euler_parse(dh_euler_name((dh_euler_seq)99), &seq), DH_ERR_ARG);
    ang[0] = 10.0f; ang[1] = 20.0f; ang[2] = 30.0f;
    rot_ref(&R, 1.0, 0.0, 0.0, 10.0);
    {
        static const int bad_seq[] = { DH_EULER_COUNT, DH_EULER_COUNT + 1, -1, 1000 };
        for (i = 0; i < 4; i++) {
            dh_mat3_f32 out;
            float a[3];
            CANARY(out);
            DHT_EQ_INT(dh_euler_to_mat3_f32((dh_euler_seq)bad_seq[i], ang, &out), DH_ERR_ARG);
            UNTOUCHED(out);
            CANARY(a);
            DHT_EQ_INT(dh_mat3_to_euler_f32(&R, (dh_euler_seq)bad_seq[i], a), DH_ERR_ARG);
            UNTOUCHED(a);
        }
    }
    for (s = 0; s < DH_EULER_COUNT; s++) {
        for (k = 0; k < 12; k++) {
            dh_mat3_f32 out;
            float a[3] = { 10.0f, 20.0f, 30.0f };
            a[k / 4] = bad_value_nan(k);
            CANARY(out);
            DHT_EQ_INT(dh_euler_to_mat3_f32((dh_euler_seq)s, a, &out), DH_ERR_NAN);
            UNTOUCHED(out);
        }
        /* huge finite angles: accepted, reduced exactly (checked against
         * the same sequence at the reduced angles) */
        {
            float a[3] = { 1e30f, -3.4028235e38f, 1e7f + 0.5f };
            float ar[3];
            dh_mat3_f32 A, B;
            for (k = 0; k < 3; k++) ar[k] = (float)fmod((double)a[k], 360.0);
            DHT_EQ_INT(dh_euler_to_mat3_f32((dh_euler_seq)s, a, &A), DH_OK);
            DHT_EQ_INT(dh_euler_to_mat3_f32((dh_euler_seq)s, ar, &B), DH_OK);
            for (k = 0; k < 9; k++) DHT_NEAR(A.m[k / 3][k % 3], B.m[k / 3][k % 3], 4e-7);
        }
    }
}

/* quaternions: NaN/Inf, zero and denormal -> error, untouched (also when
 * out aliases q); huge and tiny normal ones work */
static void rot_quat_bad(void)
{
    dh_quat_f32 q, o;
    dh_mat3_f32 R;
    unsigned k;
    for (k = 0; k < 16; k++) {
        q.w = 0.5f; q.x = 0.5f; q.y = -0.5f; q.z = 0.5f;
        if (k / 4 == 0) q.w = bad_value_nan(k);
        else if (k / 4 == 1) q.x = bad_value_nan(k);
        else if (k / 4 == 2) q.y = bad_value_nan(k);
        else q.z = bad_value_nan(k);
        CANARY(R);
        DHT_EQ_INT(dh_quat_to_mat3_f32(&q, &R), DH_ERR_NAN);
        UNTOUCHED(R);
        CANARY(o);
        DHT_EQ_INT(dh_quat_normalize_f32(&q, &o), DH_ERR_NAN);
        UNTOUCHED(o);
        o = q;
        DHT_EQ_INT(dh_quat_normalize_f32(&o, &o), DH_ERR_NAN);
        DHT_TRUE(memcmp(&o, &q, sizeof o) == 0);
    }
    {
        static const uint32_t z[][4] = { { 0u, 0u, 0u, 0u }, { 0x80000000u, 0u, 0x80000000u, 0u },
                                         { 1u, 0x807FFFFFu, 0u, 0x00400000u } };
        for (k = 0; k < 3; k++) {
            q.w = f32_bits(z[k][0]); q.x = f32_bits(z[k][1]); q.y = f32_bits(z[k][2]); q.z = f32_bits(z[k][3]);
            CANARY(R);
            DHT_EQ_INT(dh_quat_to_mat3_f32(&q, &R), DH_ERR_ZERO_AXIS);
            UNTOUCHED(R);
            CANARY(o);
            DHT_EQ_INT(dh_quat_normalize_f32(&q, &o), DH_ERR_ZERO_AXIS);
            UNTOUCHED(o);
        }
    }
    /* any normal scale works: same rotation as the unit quaternion */
    {
        static const float sc[] = { 2.0f * FLT_MIN, 1e-30f, 1e30f, FLT_MAX / 2.0f };
        dh_mat3_f32 U;
        q.w = 0.5f; q.x = 0.5f; q.y = -0.5f; q.z = 0.5f;
        DHT_EQ_INT(dh_quat_to_mat3_f32(&q, &U), DH_OK);
        for (k = 0; k < 4; k++) {
            dh_quat_f32 s;
            s.w = 0.5f * sc[k]; s.x = 0.5f * sc[k]; s.y = -0.5f * sc[k]; s.z = 0.5f * sc[k];
            DHT_EQ_INT(dh_quat_to_mat3_f32(&s, &R), DH_OK);
            {
                unsigned e;
                for (e = 0; e < 9; e++) DHT_NEAR(R.m[e / 3][e % 3], U.m[e / 3][e % 3], 6e-7);
            }
            DHT_EQ_INT(dh_quat_normalize_f32(&s, &o), DH_OK);
            DHT_NEAR(o.w, 0.5, 2e-7);
            DHT_NEAR(o.y, -0.5, 2e-7);
        }
    }
}

/* angle-axis constructors: NaN/Inf, zero or denormal axis -> error, untouched */
static void rot_axis_angle_bad(void)
{
    dh_vec3_f32 ax;
    dh_mat3_f32 R;
    dh_quat_f32 q;
    unsigned k;
    for (k = 0; k < 16; k++) {
        float deg = 30.0f;
        ax.x = 1.0f; ax.y = 2.0f; ax.z = 3.0f;
        if (k / 4 == 0) ax.x = bad_value_nan(k);
        else if (k / 4 == 1) ax.y = bad_value_nan(k);
        else if (k / 4 == 2) ax.z = bad_value_nan(k);
        else deg = bad_value_nan(k);
        CANARY(R);
        DHT_EQ_INT(dh_axis_angle_to_mat3_f32(&ax, deg, &R), DH_ERR_NAN);
        UNTOUCHED(R);
        CANARY(q);
        DHT_EQ_INT(dh_quat_from_axis_angle_f32(&ax, deg, &q), DH_ERR_NAN);
        UNTOUCHED(q);
    }
    {
        static const uint32_t z[][3] = { { 0u, 0u, 0u }, { 0x80000000u, 0u, 0u },
                                         { 0x00000001u, 0x807FFFFFu, 0x00000100u } };
        for (k = 0; k < 3; k++) {
            ax.x = f32_bits(z[k][0]); ax.y = f32_bits(z[k][1]); ax.z = f32_bits(z[k][2]);
            CANARY(R);
            DHT_EQ_INT(dh_axis_angle_to_mat3_f32(&ax, 45.0f, &R), DH_ERR_ZERO_AXIS);
            UNTOUCHED(R);
            CANARY(q);
            DHT_EQ_INT(dh_quat_from_axis_angle_f32(&ax, 45.0f, &q), DH_ERR_ZERO_AXIS);
            UNTOUCHED(q);
        }
    }
    /* FLT_MAX axis and FLT_MIN axis: accepted, same as the unit axis */
    {
        dh_mat3_f32 U, B;
        dh_vec3_f32 u;
        u.x = 1.0f; u.y = 1.0f; u.z = 0.0f;
        DHT_EQ_INT(dh_axis_angle_to_mat3_f32(&u, 77.0f, &U), DH_OK);
        ax.x = FLT_MAX; ax.y = FLT_MAX; ax.z = 0.0f;
        DHT_EQ_INT(dh_axis_angle_to_mat3_f32(&ax, 77.0f, &B), DH_OK);
        for (k = 0; k < 9; k++) DHT_EQ_F32_BITS(B.m[k / 3][k % 3], U.m[k / 3][k % 3]);
        ax.x = FLT_MIN; ax.y = FLT_MIN;
        DHT_EQ_INT(dh_axis_angle_to_mat3_f32(&ax, 77.0f, &B), DH_OK);
        for (k = 0; k < 9; k++) DHT_EQ_F32_BITS(B.m[k / 3][k % 3], U.m[k / 3][k % 3]);
    }
}

/* rotation vector -> matrix: NaN/Inf -> NAN (untouched); finite phi whose
 * length |phi| exceeds FLT_MAX -> NAN as well (documented: no float angle),
 * untouched; every other finite phi is a rotation about phi */
static void rot_rotvec_bad_and_huge(void)
{
    dh_vec3_f32 phi;
    dh_mat3_f32 R;
    unsigned k;
    for (k = 0; k < 12; k++) {
        phi.x = 0.1f; phi.y = 0.2f; phi.z = 0.3f;
        if (k / 4 == 0) phi.x = bad_value_nan(k);
        else if (k / 4 == 1) phi.y = bad_value_nan(k);
        else phi.z = bad_value_nan(k);
        CANARY(R);
        DHT_EQ_INT(dh_rotvec_to_mat3_f32(&phi, &R), DH_ERR_NAN);
        UNTOUCHED(R);
    }
    {
        static const float over[][3] = { { FLT_MAX, FLT_MAX, FLT_MAX }, { -FLT_MAX, FLT_MAX, 0.0f },
                                         { 3e38f, 3e38f, 0.0f }, { 1e38f, -2e38f, 3e38f } };
        static const float big[][3] = { { FLT_MAX, 0.0f, 0.0f }, { 2e38f, -2e38f, 0.0f },
                                        { 1e20f, 0.0f, 0.0f }, { 1e-40f, 0.0f, 0.0f },
                                        { 1e30f, 3e30f, -2e29f } };
        for (k = 0; k < sizeof over / sizeof over[0]; k++) {
            phi.x = over[k][0]; phi.y = over[k][1]; phi.z = over[k][2];
            CANARY(R);
            DHT_EQ_INT(dh_rotvec_to_mat3_f32(&phi, &R), DH_ERR_NAN);
            UNTOUCHED(R);
        }
        for (k = 0; k < sizeof big / sizeof big[0]; k++) {
            const double hx = big[k][0], hy = big[k][1], hz = big[k][2];
            const double n = sqrt(hx * hx + hy * hy + hz * hz);
            double rk[3];
            unsigned r;
            phi.x = big[k][0]; phi.y = big[k][1]; phi.z = big[k][2];
            CANARY(R);
            DHT_EQ_INT(dh_rotvec_to_mat3_f32(&phi, &R), DH_OK);
            /* a rotation ... */
            DHT_EQ_INT(dh_mat3_check_rot_f32(&R, 1e-6f), DH_OK);
            /* ... about phi: R k == k for k = phi / |phi| (the angle itself,
             * about 1e38 rad, is arbitrary: one float ulp of it is 1e31 rad) */
            for (r = 0; r < 3; r++)
                rk[r] = DH_M3(&R, r, 0) * hx / n + DH_M3(&R, r, 1) * hy / n + DH_M3(&R, r, 2) * hz / n;
            DHT_NEAR(rk[0], hx / n, 1e-6);
            DHT_NEAR(rk[1], hy / n, 1e-6);
            DHT_NEAR(rk[2], hz / n, 1e-6);
        }
    }
}

/* angular velocity: finite but overflowing products -> OVERFLOW (regression:
 * used to return a NaN/Inf w with DH_OK), w untouched */
static void rot_angvel_overflow(void)
{
    dh_mat3_f32 R, Rd;
    dh_vec3_f32 w;
    unsigned k;
    rot_ref(&R, 1.0, 1.0, 1.0, 60.0);
    for (k = 0; k < 9; k++) Rd.m[k / 3][k % 3] = (k % 2) ? FLT_MAX : -FLT_MAX;
    CANARY(w);
    DHT_EQ_INT(dh_angvel_f32(&R, &Rd, &w), DH_ERR_OVERFLOW);
    UNTOUCHED(w);
    DHT_EQ_INT(dh_angvel_body_f32(&R, &Rd, &w), DH_ERR_OVERFLOW);
    UNTOUCHED(w);
    /* NaN in Rdot */
    for (k = 0; k < 9; k++) {
        memset(&Rd, 0, sizeof Rd);
        Rd.m[k / 3][k % 3] = bad_value_nan(k);
        DHT_EQ_INT(dh_angvel_f32(&R, &Rd, &w), DH_ERR_NAN);
        UNTOUCHED(w);
        DHT_EQ_INT(dh_angvel_body_f32(&R, &Rd, &w), DH_ERR_NAN);
        UNTOUCHED(w);
    }
    /* large but representable: accepted and exact enough (Rdot = 1e30 [z]x R) */
    {
        dh_mat3_f32 I;
        memset(&I, 0, sizeof I);
        I.m[0][0] = 1.0f; I.m[1][1] = 1.0f; I.m[2][2] = 1.0f;
        memset(&Rd, 0, sizeof Rd);
        DH_M3(&Rd, 0, 1) = -1e30f;
        DH_M3(&Rd, 1, 0) = 1e30f;
        DHT_EQ_INT(dh_angvel_f32(&I, &Rd, &w), DH_OK);
        DHT_NEAR(w.z, 1e30, 1e30 * 1e-7);
        DHT_NEAR(w.x, 0.0, 0.0);
    }
}

/* functions without a status (skew, vee, quaternion product/conjugate):
 * IEEE semantics, NaN propagates to the dependent outputs; aliasing */
static void rot_no_status_ieee(void)
{
    dh_vec3_f32 v, u;
    dh_mat3_f32 S;
    dh_quat_f32 a, b, c, d;
    v.x = bad_value_nan(0); v.y = 2.0f; v.z = -3.0f;
    dh_skew_f32(&v, &S);
    DHT_TRUE(DH_M3(&S, 2, 1) != DH_M3(&S, 2, 1));   /* vx appears at (2,1), (1,2) */
    DHT_TRUE(DH_M3(&S, 1, 2) != DH_M3(&S, 1, 2));
    DHT_EQ_F32_BITS(DH_M3(&S, 0, 2), 2.0f);
    DHT_EQ_F32_BITS(DH_M3(&S, 0, 0), 0.0f);
    dh_vee_f32(&S, &u);
    DHT_TRUE(u.x != u.x);
    DHT_EQ_F32_BITS(u.y, 2.0f);
    DHT_EQ_F32_BITS(u.z, -3.0f);
    a.w = 1.0f; a.x = 2.0f; a.y = 3.0f; a.z = 4.0f;
    b.w = -0.5f; b.x = 0.25f; b.y = 1.5f; b.z = -2.0f;
    dh_quat_mul_f32(&a, &b, &c);
    d = a;
    dh_quat_mul_f32(&d, &b, &d);
    DHT_TRUE(memcmp(&c, &d, sizeof c) == 0);
    d = b;
    dh_quat_mul_f32(&a, &d, &d);
    DHT_TRUE(memcmp(&c, &d, sizeof c) == 0);
    dh_quat_mul_f32(&a, &a, &c);
    d = a;
    dh_quat_mul_f32(&d, &d, &d);
    DHT_TRUE(memcmp(&c, &d, sizeof c) == 0);
    d = a;
    dh_quat_conj_f32(&d, &d);
    DHT_EQ_F32_BITS(d.x, -2.0f);
    a.y = bad_value_nan(1);
    dh_quat_mul_f32(&a, &b, &c);
    DHT_TRUE(!(fabsf(c.w) <= FLT_MAX)); /* - Inf * 1.5 */
    DHT_TRUE(!(fabsf(c.x) <= FLT_MAX));
}

static const dht_case cases[] = {
    DHT_CASE(rot_extract_nan),
    DHT_CASE(rot_extract_not_rigid),
    DHT_CASE(rot_orthonormalize_bad),
    DHT_CASE(rot_check_bad_tol),
    DHT_CASE(rot_euler_bad),
    DHT_CASE(rot_quat_bad),
    DHT_CASE(rot_axis_angle_bad),
    DHT_CASE(rot_rotvec_bad_and_huge),
    DHT_CASE(rot_angvel_overflow),
    DHT_CASE(rot_no_status_ieee),
};
DHT_MAIN(cases)
