/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_errors_mat4.c - bad input to the float 4x4 transforms
 * (docs/errors.md, section mat4.h).
 *
 * Every error case pre-fills the outputs with a canary byte pattern and
 * checks that they are untouched afterwards (the contract of mat4.h:
 * "on a non-OK status every output is left untouched"). Accepted inputs at
 * the edges are checked against double references computed here or in
 * test/support_ref.c (never against the code under test).
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_canary.h"
#include "support_ref.h"
#include "dhmath/mat4.h"
#include "dhmath/rot.h"

#define U24 5.9604644775390625e-8




static void set_identity(dh_mat4_f32 *T)
{
    int c, r;
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) T->m[c][r] = (c == r) ? 1.0f : 0.0f;
}

/* Rot(x|y|z) with NaN/Inf angle: DH_ERR_NAN, T untouched; huge finite
 * angles are accepted and exact-reduced */
static void mat4_rot_nan_inf_huge(void)
{
    unsigned k, ax;
    for (ax = 0; ax < 3; ax++) {
        for (k = 0; k < 4; k++) {
            dh_mat4_f32 T;
            dh_status st;
            CANARY(T);
            st = (ax == 0) ? dh_mat4_rotx_f32(bad_value(k), &T)
               : (ax == 1) ? dh_mat4_roty_f32(bad_value(k), &T) : dh_mat4_rotz_f32(bad_value(k), &T);
            DHT_EQ_INT(st, DH_ERR_NAN);
            UNTOUCHED(T);
        }
    }
    {
        static const float huge[] = { 1e6f, -1e6f, 1e7f + 0.5f, 1e20f, -3.4028235e38f, 3.4028235e38f };
        for (k = 0; k < sizeof huge / sizeof huge[0]; k++) {
            dh_mat4_f32 T;
            dhr_mat4 R;
            DHT_EQ_INT(dh_mat4_rotz_f32(huge[k], &T), DH_OK);
            dhr_rotz(fmod((double)huge[k], 360.0), &R);
            DHT_TRUE(dhr_max_abs_diff(&T, &R) <= 6.2e-8);
            DHT_EQ_INT(dh_mat4_rotx_f32(huge[k], &T), DH_OK);
            dhr_rotx(fmod((double)huge[k], 360.0), &R);
            DHT_TRUE(dhr_max_abs_diff(&T, &R) <= 6.2e-8);
            DHT_EQ_INT(dh_mat4_roty_f32(huge[k], &T), DH_OK);
            dhr_roty(fmod((double)huge[k], 360.0), &R);
            DHT_TRUE(dhr_max_abs_diff(&T, &R) <= 6.2e-8);
        }
    }
}

/* Rot(k, deg): NaN/Inf anywhere -> DH_ERR_NAN; zero or denormal axis ->
 * DH_ERR_ZERO_AXIS; T untouched. Smallest normal and largest axes work. */
static void mat4_rot_axis_bad(void)
{
    unsigned pos, k;
    for (pos = 0; pos < 4; pos++) {
        for (k = 0; k < 4; k++) {
            float a[4] = { 0.3f, -0.4f, 0.5f, 33.0f };
            dh_mat4_f32 T;
            a[pos] = bad_value(k);
            CANARY(T);
            DHT_EQ_INT(dh_mat4_rot_axis_f32(a[0], a[1], a[2], a[3], &T), DH_ERR_NAN);
            UNTOUCHED(T);
        }
    }
    {
        static const uint32_t zero_axes[][3] = {
            { 0u, 0u, 0u }, { 0x80000000u, 0x80000000u, 0x80000000u },
            { 0x00000001u, 0u, 0u }, { 0u, 0x807FFFFFu, 0x007FFFFFu },
            { 0x00400000u, 0x00400000u, 0x00400000u }
        };
        for (k = 0; k < sizeof zero_axes / sizeof zero_axes[0]; k++) {
            dh_mat4_f32 T;
            CANARY(T);
            DHT_EQ_INT(dh_mat4_rot_axis_f32(f32_bits(zero_axes[k][0]), f32_bits(zero_axes[k][1]), f32_bits(zero_axes[k][2]),
                                            30.0f, &T),
                       DH_ERR_ZERO_AXIS);
            UNTOUCHED(T);
            /* the zero axis is reported even with a NaN-free but huge angle */
            DHT_EQ_INT(dh_mat4_rot_axis_f32(f32_bits(zero_axes[k][0]), f32_bits(zero_axes[k][1]), f32_bits(zero_axes[k][2]),
                                            1e30f, &T),
                       DH_ERR_ZERO_AXIS);
            UNTOUCHED(T);
        }
    }
    /* FLT_MIN (smallest normal) and FLT_MAX axes are accepted */
    {
        static const float mags[] = { FLT_MIN, -FLT_MIN, FLT_MAX, -FLT_MAX };
        for (k = 0; k < 4; k++) {
            dh_mat4_f32 T;
            dhr_mat4 R;
            DHT_EQ_INT(dh_mat4_rot_axis_f32(mags[k], mags[k], mags[k], 70.0f, &T), DH_OK);
            dhr_rot_axis((mags[k] > 0) ? 1.0 : -1.0, (mags[k] > 0) ? 1.0 : -1.0,
                         (mags[k] > 0) ? 1.0 : -1.0, 70.0, &R);
            DHT_TRUE(dhr_max_abs_diff(&T, &R) <= 5 * U24);
        }
    }
}

/* Perspective: bad axis -> ARG, NaN/Inf f -> NAN, f == 0 or |1/f|
 * overflowing -> DOMAIN; T untouched. Boundary 2^-127 accepted. */
static void mat4_persp_bad(void)
{
    static const int bad_axes[] = { -1, 3, 4, -2147483647 - 1, 2147483647 };
    dh_mat4_f32 T;
    unsigned k;
    for (k = 0; k < sizeof bad_axes / sizeof bad_axes[0]; k++) {
        CANARY(T);
        DHT_EQ_INT(dh_mat4_persp_f32(bad_axes[k], 10.0f, &T), DH_ERR_ARG);
        UNTOUCHED(T);
    }
    for (k = 0; k < 4; k++) {
        CANARY(T);
        DHT_EQ_INT(dh_mat4_persp_f32(1, bad_value(k), &T), DH_ERR_NAN);
        UNTOUCHED(T);
    }
    {
        /* 0, -0, denormals, 2^-128 (1/f = 2^128 overflows) */
        static const uint32_t dom[] = { 0u, 0x80000000u, 0x00000001u, 0x80200000u, 0x00200000u };
        for (k = 0; k < sizeof dom / sizeof dom[0]; k++) {
            CANARY(T);
            DHT_EQ_INT(dh_mat4_persp_f32(2, f32_bits(dom[k]), &T), DH_ERR_DOMAIN);
            UNTOUCHED(T);
        }
    }
    /* 2^-127 (denormal, but 1/f = 2^127 is finite): accepted */
    DHT_EQ_INT(dh_mat4_persp_f32(0, f32_bits(0x00400000u), &T), DH_OK);
    DHT_EQ_F32_BITS(DH_M4(&T, 3, 0), -1.7014118e38f);
    DHT_EQ_F32_BITS(DH_M4(&T, 3, 3), 1.0f);
}

/* Homogeneous point: w == 0 -> DOMAIN; NaN/Inf inputs -> NAN; finite input
 * with a non-finite product or quotient -> OVERFLOW; v untouched. */
static void mat4_apply_point_h_bad(void)
{
    dh_mat4_f32 T;
    dh_vec4_f32 u;
    dh_vec3_f32 v;
    unsigned k, e;
    set_identity(&T);
    u.x = 1.0f; u.y = 2.0f; u.z = 3.0f; u.w = 0.0f;
    CANARY(v);
    DHT_EQ_INT(dh_mat4_apply_point_h_f32(&T, &u, &v), DH_ERR_DOMAIN);
    UNTOUCHED(v);
    u.w = -0.0f;
    DHT_EQ_INT(dh_mat4_apply_point_h_f32(&T, &u, &v), DH_ERR_DOMAIN);
    UNTOUCHED(v);
    /* perspective point on the focal plane: w = 1 - y/f = 0 */
    DHT_EQ_INT(dh_mat4_persp_f32(1, 4.0f, &T), DH_OK);
    u.x = 1.0f; u.y = 4.0f; u.z = 3.0f; u.w = 1.0f;
    DHT_EQ_INT(dh_mat4_apply_point_h_f32(&T, &u, &v), DH_ERR_DOMAIN);
    UNTOUCHED(v);
    /* NaN/Inf in each element of T and of u */
    for (e = 0; e < 20; e++) {
        for (k = 0; k < 4; k++) {
            set_identity(&T);
            u.x = 1.0f; u.y = 2.0f; u.z = 3.0f; u.w = 1.0f;
            if (e < 16) T.m[e / 4][e % 4] = bad_value(k);
            else if (e == 16) u.x = bad_value(k);
            else if (e == 17) u.y = bad_value(k);
            else if (e == 18) u.z = bad_value(k);
            else u.w = bad_value(k);
            DHT_EQ_INT(dh_mat4_apply_point_h_f32(&T, &u, &v), DH_ERR_NAN);
            UNTOUCHED(v);
        }
    }
    /* finite, product overflows */
    set_identity(&T);
    DH_M4(&T, 0, 0) = FLT_MAX;
    u.x = 4.0f; u.y = 0.0f; u.z = 0.0f; u.w = 1.0f;
    DHT_EQ_INT(dh_mat4_apply_point_h_f32(&T, &u, &v), DH_ERR_OVERFLOW);
    UNTOUCHED(v);
    /* finite, the division overflows (tiny w) */
    set_identity(&T);
    u.x = 1e30f; u.y = 0.0f; u.z = 0.0f; u.w = 1e-30f;
    DHT_EQ_INT(dh_mat4_apply_point_h_f32(&T, &u, &v), DH_ERR_OVERFLOW);
    UNTOUCHED(v);
    /* accepted: v may alias nothing of the input (different types), value exact */
    u.x = 6.0f; u.y = -3.0f; u.z = 1.5f; u.w = -1.5f;
    DHT_EQ_INT(dh_mat4_apply_point_h_f32(&T, &u, &v), DH_OK);
    DHT_EQ_F32_BITS(v.x, -4.0f);
    DHT_EQ_F32_BITS(v.y, 2.0f);
    DHT_EQ_F32_BITS(v.z, -1.0f);
}

/* double 1-norm condition number (max column sum), T^-1 by dhr_inv */
static double cond1(const dhr_mat4 *T, dhr_mat4 *Ti)
{
    double n1 = 0.0, n2 = 0.0;
    int c, r;
    if (!dhr_inv(T, Ti)) return HUGE_VAL;
    for (c = 0; c < 4; c++) {
        double s1 = 0.0, s2 = 0.0;
        for (r = 0; r < 4; r++) {
            s1 += fabs(T->m[c][r]);
            s2 += fabs(Ti->m[c][r]);
        }
        n1 = (s1 > n1) ? s1 : n1;
        n2 = (s2 > n2) ? s2 : n2;
    }
    return n1 * n2;
}

/* T = R1 diag(1, s1, s2, s3) R2 in double, rounded to float, scaled by 2^e */
static void make_conditioned(dh_mat4_f32 *T, double s1, double s2, double s3, int e)
{
    dhr_mat4 R1, R2, D, M;
    double k[3];
    dhr_rand_unit3(k);
    dhr_rot_axis(k[0], k[1], k[2], dht_rand_uniform(-180.0, 180.0), &R1);
    dhr_rand_unit3(k);
    dhr_rot_axis(k[0], k[1], k[2], dht_rand_uniform(-180.0, 180.0), &R2);
    dhr_identity(&D);
    D.m[1][1] = s1;
    D.m[2][2] = s2;
    D.m[3][3] = s3;
    dhr_mul(&R1, &D, &M);
    dhr_mul(&M, &R2, &M);
    {
        int c, r;
        for (c = 0; c < 4; c++)
            for (r = 0; r < 4; r++) M.m[c][r] = ldexp(M.m[c][r], e);
    }
    dhr_to_f32(&M, T);
}

/* General inverse: NaN/Inf -> NAN; zero, denormal, exactly singular and
 * near-singular (cond >= 2^19) -> SINGULAR; inverse beyond FLT_MAX ->
 * OVERFLOW; out untouched, also when out aliases T. */
static void mat4_inv_bad(void)
{
    dh_mat4_f32 T, X;
    unsigned e, k, it;
    /* NaN/Inf in every position */
    for (e = 0; e < 16; e++) {
        for (k = 0; k < 4; k++) {
            set_identity(&T);
            T.m[e / 4][e % 4] = bad_value(k);
            CANARY(X);
            DHT_EQ_INT(dh_mat4_inv_f32(&T, &X), DH_ERR_NAN);
            UNTOUCHED(X);
            DHT_EQ_INT(dh_mat4_inv_auto_f32(&T, &X), DH_ERR_NAN);
            UNTOUCHED(X);
            {
                dh_mat4_f32 A = T;
                DHT_EQ_INT(dh_mat4_inv_f32(&A, &A), DH_ERR_NAN);
                DHT_TRUE(memcmp(&A, &T, sizeof A) == 0);
            }
        }
    }
    /* zero and denormal matrices */
    memset(&T, 0, sizeof T);
    CANARY(X);
    DHT_EQ_INT(dh_mat4_inv_f32(&T, &X), DH_ERR_SINGULAR);
    UNTOUCHED(X);
    for (e = 0; e < 16; e++) T.m[e / 4][e % 4] = (e % 5 == 0) ? f32_bits(0x007FFFFFu) : 0.0f;
    DHT_EQ_INT(dh_mat4_inv_f32(&T, &X), DH_ERR_SINGULAR);
    UNTOUCHED(X);
    DHT_EQ_INT(dh_mat4_inv_auto_f32(&T, &X), DH_ERR_SINGULAR);
    UNTOUCHED(X);
    /* exactly singular: rank 3, 2, 1 at scales 2^-100 .. 2^100 */
    for (it = 0; it < DHT_ITER(3000u); it++) {
        const int sc = (int)(dht_rand_u32() % 201u) - 100;
        const unsigned rank = 1u + it % 3u;
        int c, r;
        dhr_mat4 M;
        /* the first `rank` columns are random small integers, the others
         * integer combinations of them: exact in float, exactly singular */
        for (c = 0; c < (int)rank; c++)
            for (r = 0; r < 4; r++) M.m[c][r] = (double)(int)(dht_rand_u32() % 17u) - 8.0;
        for (c = (int)rank; c < 4; c++) {
            const double w0 = (double)(int)(dht_rand_u32() % 7u) - 3.0;
            const double w1 = (double)(int)(dht_rand_u32() % 5u) - 2.0;
            const double w2 = (double)(int)(dht_rand_u32() % 3u) - 1.0;
            for (r = 0; r < 4; r++)
                M.m[c][r] = w0 * M.m[0][r] + ((rank > 1) ? w1 * M.m[1][r] : 0.0)
                          + ((rank > 2) ? w2 * M.m[2][r] : 0.0);
        }
        for (c = 0; c < 4; c++)
            for (r = 0; r < 4; r++) M.m[c][r] = ldexp(M.m[c][r], sc);
        dhr_to_f32(&M, &T);
        CANARY(X);
        DHT_EQ_INT(dh_mat4_inv_f32(&T, &X), DH_ERR_SINGULAR);
        UNTOUCHED(X);
        {
            dh_plane_f32 P, Q;
            P.a = 1.0f; P.b = -2.0f; P.c = 0.5f; P.d = 3.0f;
            CANARY(Q);
            DHT_EQ_INT(dh_mat4_apply_plane_f32(&T, &P, &Q), DH_ERR_SINGULAR);
            UNTOUCHED(Q);
        }
    }
    /* near-singular: smallest singular value 1e-7 .. 1e-6 (cond >= 1e6 > 2^19) */
    for (it = 0; it < DHT_ITER(2000u); it++) {
        const int sc = (int)(dht_rand_u32() % 121u) - 60;
        make_conditioned(&T, 1.0, dht_rand_uniform(1e-7, 1e-6), 1.0, sc);
        CANARY(X);
        DHT_EQ_INT(dh_mat4_inv_f32(&T, &X), DH_ERR_SINGULAR);
        UNTOUCHED(X);
    }
    /* well conditioned (cond <= ~1e3) at any scale: accepted and accurate,
     * |X - T^-1| <= 5.5 cond 2^-24 max|T^-1| (mat4.h) */
    for (it = 0; it < DHT_ITER(2000u); it++) {
        const int sc = (int)(dht_rand_u32() % 121u) - 60;
        dhr_mat4 D, Di;
        double cd;
        make_conditioned(&T, dht_rand_uniform(0.5, 2.0), dht_rand_uniform(1e-3, 1.0),
                         dht_rand_uniform(0.5, 2.0), sc);
        dhr_from_f32(&T, &D);
        cd = cond1(&D, &Di);
        DHT_EQ_INT(dh_mat4_inv_f32(&T, &X), DH_OK);
        DHT_TRUE_MSG(dhr_max_abs_diff(&X, &Di) <= 5.5 * cd * U24 * dhr_max_abs(&Di),
                     "cond %.3g scale 2^%d err %.3g", cd, sc, dhr_max_abs_diff(&X, &Di));
    }
    /* the inverse overflows: diag(2^-120, 2^-120, 2^-120, 2^-130) is well
     * conditioned (2^10) but its inverse holds 2^130 > FLT_MAX */
    set_identity(&T);
    T.m[0][0] = ldexpf(1.0f, -120);
    T.m[1][1] = ldexpf(1.0f, -120);
    T.m[2][2] = ldexpf(1.0f, -120);
    T.m[3][3] = f32_bits(0x00100000u); /* 2^-130, denormal */
    CANARY(X);
    DHT_EQ_INT(dh_mat4_inv_f32(&T, &X), DH_ERR_OVERFLOW);
    UNTOUCHED(X);
    DHT_EQ_INT(dh_mat4_inv_auto_f32(&T, &X), DH_ERR_OVERFLOW);
    UNTOUCHED(X);
    /* aliasing out == T on the error path leaves T as it was */
    {
        dh_mat4_f32 A = T;
        DHT_EQ_INT(dh_mat4_inv_f32(&A, &A), DH_ERR_OVERFLOW);
        DHT_TRUE(memcmp(&A, &T, sizeof A) == 0);
    }
}

/* Non-rigid input to the rigid inverse is NOT checked: the result is the
 * documented formula [R^T, -R^T p]; dh_mat4_inv_auto_f32 detects it and
 * falls back to the general inverse. */
static void mat4_inv_rigid_nonrigid(void)
{
    dh_mat4_f32 T, X, Y;
    dhr_mat4 D, Di;
    unsigned it;
    for (it = 0; it < DHT_ITER(2000u); it++) {
        int c, r;
        make_conditioned(&T, dht_rand_uniform(0.5, 2.0), dht_rand_uniform(0.5, 2.0), 1.0, 0);
        for (r = 0; r < 3; r++) T.m[3][r] = (float)dht_rand_uniform(-10.0, 10.0);
        for (c = 0; c < 3; c++) T.m[c][3] = 0.0f;
        T.m[3][3] = 1.0f;
        if (it % 2u) {
            /* bottom row not 0 0 0 1: not read by the rigid inverse. The
             * matrix stays well conditioned for the general inverse only
             * if 1 - b R^-1 p stays away from 0 (b = (0.25, 0, 0)): with
             * |p| <= 0.87 and sigma_min(R) >= 0.5, |b R^-1 p| <= 0.44
             * (with |p| up to 17, some draws are singular to float) */
            T.m[0][3] = 0.25f;
            for (r = 0; r < 3; r++) T.m[3][r] *= 0.05f;
        }
        dh_mat4_inv_rigid_f32(&T, &X);
        /* documented formula, evaluated in double */
        for (c = 0; c < 3; c++)
            for (r = 0; r < 3; r++) DHT_EQ_F32_BITS(X.m[c][r], T.m[r][c]);
        for (r = 0; r < 3; r++) {
            const double ref = -((double)T.m[3][0] * T.m[r][0] + (double)T.m[3][1] * T.m[r][1] +
                                 (double)T.m[3][2] * T.m[r][2]);
            DHT_NEAR(X.m[3][r], ref, 4 * U24 * 40.0);
            DHT_EQ_F32_BITS(X.m[r][3], 0.0f);
        }
        DHT_EQ_F32_BITS(X.m[3][3], 1.0f);
        /* check_rigid rejects it; inv_auto gives the true inverse */
        DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, DH_MAT4_RIGID_TOL), DH_ERR_NOT_RIGID);
        DHT_EQ_INT(dh_mat4_inv_auto_f32(&T, &Y), DH_OK);
        dhr_from_f32(&T, &D);
        DHT_TRUE(dhr_inv(&D, &Di));
        DHT_TRUE(dhr_max_abs_diff(&Y, &Di) <= 5.5 * cond1(&D, &Di) * U24 * dhr_max_abs(&Di));
    }
}

/* checks: tol negative/NaN -> ARG; NaN/Inf -> NAN; scaled, sheared,
 * reflected, bottom row -> NOT_RIGID. They have no outputs. */
static void mat4_check_rigid_bad(void)
{
    dh_mat4_f32 T;
    unsigned k, e;
    set_identity(&T);
    DHT_EQ_INT(dh_mat4_check_rot_f32(&T, -1e-6f), DH_ERR_ARG);
    DHT_EQ_INT(dh_mat4_check_rot_f32(&T, bad_value(0)), DH_ERR_ARG);
    DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, -0.5f), DH_ERR_ARG);
    DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, bad_value(0)), DH_ERR_ARG);
    DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, -0.0f), DH_OK); /* -0 >= 0 */
    for (e = 0; e < 16; e++) {
        for (k = 0; k < 4; k++) {
            set_identity(&T);
            T.m[e / 4][e % 4] = bad_value(k);
            DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, 1e-5f), DH_ERR_NAN);
            /* check_rot only reads the rotation part */
            DHT_EQ_INT(dh_mat4_check_rot_f32(&T, 1e-5f), (e % 4 < 3 && e / 4 < 3) ? DH_ERR_NAN : DH_OK);
        }
    }
    /* scaled, sheared, reflected */
    set_identity(&T);
    T.m[0][0] = 1.001f;
    DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, 1e-5f), DH_ERR_NOT_RIGID);
    set_identity(&T);
    T.m[1][0] = 0.01f;
    DHT_EQ_INT(dh_mat4_check_rot_f32(&T, 1e-5f), DH_ERR_NOT_RIGID);
    set_identity(&T);
    T.m[2][2] = -1.0f;
    DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, 1e-5f), DH_ERR_NOT_RIGID);
    DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, 10.0f), DH_ERR_NOT_RIGID); /* det < 0 whatever tol */
    /* entries whose squares overflow */
    set_identity(&T);
    T.m[0][0] = 1e30f;
    DHT_EQ_INT(dh_mat4_check_rot_f32(&T, 1e-5f), DH_ERR_NOT_RIGID);
    /* bottom row */
    for (e = 0; e < 4; e++) {
        set_identity(&T);
        T.m[e][3] = (e == 3) ? 0.999f : 1e-30f;
        DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, 1e-5f), DH_ERR_NOT_RIGID);
        DHT_EQ_INT(dh_mat4_check_rot_f32(&T, 1e-5f), DH_OK);
    }
}

/* to_axis_angle: NaN/Inf -> NAN; not a rotation within DH_MAT4_AXIS_TOL
 * (scaled, sheared, reflected) -> NOT_RIGID; k and theta untouched. Within
 * the tolerance the matrix is used as it is. */
static void mat4_axis_angle_bad(void)
{
    dh_mat4_f32 T;
    dh_vec3_f32 k;
    float th;
    unsigned e, b;
    for (e = 0; e < 9; e++) {
        for (b = 0; b < 4; b++) {
            set_identity(&T);
            T.m[e / 3][e % 3] = bad_value(b);
            CANARY(k);
            CANARY(th);
            DHT_EQ_INT(dh_mat4_to_axis_angle_f32(&T, &k, &th), DH_ERR_NAN);
            UNTOUCHED(k);
            UNTOUCHED(th);
        }
    }
    {
        static const float scale[] = { 2.0f, 0.5f, 1.001f, 0.0f, -1.0f };
        for (e = 0; e < sizeof scale / sizeof scale[0]; e++) {
            DHT_EQ_INT(dh_mat4_rot_axis_f32(1.0f, 2.0f, 3.0f, 50.0f, &T), DH_OK);
            for (b = 0; b < 9; b++) T.m[b / 3][b % 3] *= scale[e];
            CANARY(k);
            CANARY(th);
            DHT_EQ_INT(dh_mat4_to_axis_angle_f32(&T, &k, &th), DH_ERR_NOT_RIGID);
            UNTOUCHED(k);
            UNTOUCHED(th);
        }
    }
    /* reflection (det -1) and shear */
    set_identity(&T);
    T.m[0][0] = -1.0f;
    DHT_EQ_INT(dh_mat4_to_axis_angle_f32(&T, &k, &th), DH_ERR_NOT_RIGID);
    UNTOUCHED(k);
    UNTOUCHED(th);
    set_identity(&T);
    T.m[1][0] = 1e-3f;
    DHT_EQ_INT(dh_mat4_to_axis_angle_f32(&T, &k, &th), DH_ERR_NOT_RIGID);
    UNTOUCHED(k);
    UNTOUCHED(th);
    /* non-rigid p and bottom row are not examined */
    DHT_EQ_INT(dh_mat4_rotz_f32(90.0f, &T), DH_OK);
    T.m[3][0] = bad_value(0);
    T.m[0][3] = 7.0f;
    DHT_EQ_INT(dh_mat4_to_axis_angle_f32(&T, &k, &th), DH_OK);
    DHT_EQ_F32_BITS(th, 90.0f);
    DHT_EQ_F32_BITS(k.z, 1.0f);
    /* within the tolerance (deviation 5e-5): accepted as is, the axis is
     * still a unit vector and the angle within the perturbation */
    DHT_EQ_INT(dh_mat4_rotz_f32(40.0f, &T), DH_OK);
    T.m[0][0] *= 1.00005f;
    DHT_EQ_INT(dh_mat4_to_axis_angle_f32(&T, &k, &th), DH_OK);
    DHT_NEAR(th, 40.0, 0.01);
    DHT_NEAR(sqrt((double)k.x * k.x + (double)k.y * k.y + (double)k.z * k.z), 1.0, 2.4e-7);
}

/* apply_plane: NaN/Inf P or T -> NAN; singular T -> SINGULAR; Q untouched;
 * Q may alias P. */
static void mat4_apply_plane_bad(void)
{
    dh_mat4_f32 T;
    dh_plane_f32 P, Q;
    unsigned k, e;
    set_identity(&T);
    for (e = 0; e < 4; e++) {
        for (k = 0; k < 4; k++) {
            P.a = 1.0f; P.b = 2.0f; P.c = 3.0f; P.d = 4.0f;
            if (e == 0) P.a = bad_value(k);
            else if (e == 1) P.b = bad_value(k);
            else if (e == 2) P.c = bad_value(k);
            else P.d = bad_value(k);
            CANARY(Q);
            DHT_EQ_INT(dh_mat4_apply_plane_f32(&T, &P, &Q), DH_ERR_NAN);
            UNTOUCHED(Q);
        }
    }
    P.a = 0.0f; P.b = 0.0f; P.c = 1.0f; P.d = -2.0f;
    for (e = 0; e < 16; e++) {
        set_identity(&T);
        T.m[e / 4][e % 4] = bad_value(e);
        CANARY(Q);
        DHT_EQ_INT(dh_mat4_apply_plane_f32(&T, &P, &Q), DH_ERR_NAN);
        UNTOUCHED(Q);
    }
    dh_mat4_scale_f32(1.0f, 0.0f, 1.0f, &T);
    CANARY(Q);
    DHT_EQ_INT(dh_mat4_apply_plane_f32(&T, &P, &Q), DH_ERR_SINGULAR);
    UNTOUCHED(Q);
    /* alias: Q == P, translation by (0, 0, 3): z = 2 -> z = 5 */
    dh_mat4_trans_f32(0.0f, 0.0f, 3.0f, &T);
    DHT_EQ_INT(dh_mat4_apply_plane_f32(&T, &P, &P), DH_OK);
    DHT_EQ_F32_BITS(P.c, 1.0f);
    DHT_EQ_F32_BITS(P.d, -5.0f);
    /* error path with Q == P: P unchanged */
    dh_mat4_scale_f32(0.0f, 1.0f, 1.0f, &T);
    Q = P;
    DHT_EQ_INT(dh_mat4_apply_plane_f32(&T, &P, &P), DH_ERR_SINGULAR);
    DHT_TRUE(memcmp(&P, &Q, sizeof P) == 0);
}

/* Functions without a status follow IEEE semantics: NaN/Inf propagate to
 * the outputs that depend on them (documented), nothing else is affected;
 * outputs may alias inputs. */
static void mat4_no_status_ieee_and_alias(void)
{
    dh_mat4_f32 A, B, C, D, E;
    dh_vec3_f32 u, v;
    unsigned it;
    int c, r;
    /* NaN in A(1, 2) reaches exactly row 1 of A*B (full product) */
    set_identity(&A);
    DH_M4(&A, 1, 2) = bad_value(0);
    DHT_EQ_INT(dh_mat4_rotz_f32(30.0f, &B), DH_OK);
    dh_mat4_mul_f32(&A, &B, &C);
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) {
            const int nan_expected = (r == 1); /* NaN * 0 is NaN too */
            DHT_EQ_INT(DH_M4(&C, r, c) != DH_M4(&C, r, c), nan_expected);
        }
    /* the affine product ignores the bottom rows, even NaN */
    DHT_EQ_INT(dh_mat4_rotx_f32(20.0f, &A), DH_OK);
    A.m[3][0] = 1.0f;
    D = A;
    D.m[0][3] = bad_value(0);
    D.m[3][3] = bad_value(1);
    E = B;
    E.m[1][3] = bad_value(2);
    dh_mat4_mul_affine_f32(&D, &E, &C);
    dh_mat4_mul_f32(&A, &B, &D);
    DHT_EQ_INT(dh_mat4_check_finite_f32(&C), DH_OK);
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) DHT_NEAR(C.m[c][r], D.m[c][r], 0.0);
    /* isfinite sees every element */
    for (c = 0; c < 16; c++) {
        set_identity(&C);
        C.m[c / 4][c % 4] = bad_value((unsigned)c);
        DHT_EQ_INT(dh_mat4_check_finite_f32(&C), DH_ERR_NAN);
    }
    /* aliasing: out == A, out == B, out == A == B give the non-aliased result */
    for (it = 0; it < DHT_ITER(500u); it++) {
        dhr_mat4 RA, RB;
        dhr_rand_general(&RA);
        dhr_rand_general(&RB);
        dhr_to_f32(&RA, &A);
        dhr_to_f32(&RB, &B);
        dh_mat4_mul_f32(&A, &B, &C);
        D = A;
        dh_mat4_mul_f32(&D, &B, &D);
        DHT_TRUE(memcmp(&C, &D, sizeof C) == 0);
        D = B;
        dh_mat4_mul_f32(&A, &D, &D);
        DHT_TRUE(memcmp(&C, &D, sizeof C) == 0);
        D = A;
        dh_mat4_postmul_f32(&D, &B);
        DHT_TRUE(memcmp(&C, &D, sizeof C) == 0);
        D = B;
        dh_mat4_premul_f32(&D, &A);
        DHT_TRUE(memcmp(&C, &D, sizeof C) == 0);
        dh_mat4_mul_f32(&A, &A, &C);
        D = A;
        dh_mat4_mul_f32(&D, &D, &D);
        DHT_TRUE(memcmp(&C, &D, sizeof C) == 0);
        dh_mat4_mul_affine_f32(&A, &B, &C);
        D = A;
        dh_mat4_mul_affine_f32(&D, &B, &D);
        DHT_TRUE(memcmp(&C, &D, sizeof C) == 0);
        D = B;
        dh_mat4_mul_affine_f32(&A, &D, &D);
        DHT_TRUE(memcmp(&C, &D, sizeof C) == 0);
        dh_mat4_inv_rigid_f32(&A, &C);
        D = A;
        dh_mat4_inv_rigid_f32(&D, &D);
        DHT_TRUE(memcmp(&C, &D, sizeof C) == 0);
        u.x = (float)dht_rand_uniform(-5, 5); u.y = (float)dht_rand_uniform(-5, 5); u.z = 1.5f;
        dh_mat4_apply_point_f32(&A, &u, &v);
        dh_mat4_apply_point_f32(&A, &u, &u);
        DHT_TRUE(memcmp(&u, &v, sizeof u) == 0);
        dh_mat4_apply_dir_f32(&A, &u, &v);
        dh_mat4_apply_dir_f32(&A, &u, &u);
        DHT_TRUE(memcmp(&u, &v, sizeof u) == 0);
    }
    /* noap may read its vectors from inside T itself */
    DHT_EQ_INT(dh_mat4_rotz_f32(90.0f, &A), DH_OK);
    A.m[3][0] = 4.0f;
    C = A;
    dh_mat4_from_noap_f32((const dh_vec3_f32 *)&A.m[1][0], (const dh_vec3_f32 *)&A.m[0][0], (const dh_vec3_f32 *)&A.m[2][0],
                          (const dh_vec3_f32 *)&A.m[3][0], &A);
    for (r = 0; r < 3; r++) {
        DHT_EQ_F32_BITS(A.m[0][r], C.m[1][r]);
        DHT_EQ_F32_BITS(A.m[1][r], C.m[0][r]);
        DHT_EQ_F32_BITS(A.m[3][r], C.m[3][r]);
    }
    /* count == 0: nothing is read or written, pointers may be NULL */
    dh_mat4_apply_points_f32(&A, NULL, NULL, 0u);
    /* accessors copy any bits, NaN included, and nothing else */
    for (c = 0; c < 16; c++) {
        dh_mat3_f32 R;
        dh_vec3_f32 col[4];
        set_identity(&A);
        A.m[c / 4][c % 4] = bad_value((unsigned)c);
        col[0] = dh_mat4_n_f32(&A);
        col[1] = dh_mat4_o_f32(&A);
        col[2] = dh_mat4_a_f32(&A);
        col[3] = dh_mat4_p_f32(&A);
        dh_mat4_get_rot_f32(&A, &R);
        for (r = 0; r < 3; r++) {
            int k;
            for (k = 0; k < 4; k++) {
                const float *cv = &col[k].x;
                DHT_TRUE(memcmp(&cv[r], &A.m[k][r], sizeof(float)) == 0);
                if (k < 3) DHT_TRUE(memcmp(&R.m[k][r], &A.m[k][r], sizeof(float)) == 0);
            }
        }
        set_identity(&B);
        dh_mat4_set_rot_f32(&B, &R);
        for (r = 0; r < 16; r++) {
            if (r / 4 < 3 && r % 4 < 3) DHT_TRUE(memcmp(&B.m[r / 4][r % 4], &A.m[r / 4][r % 4], 4) == 0);
            else DHT_EQ_F32_BITS(B.m[r / 4][r % 4], (r / 4 == r % 4) ? 1.0f : 0.0f);
        }
    }
}

/*
 * Edges where the loop-based code of the DH_SMALL build is organised
 * differently from the unrolled default code; both builds must give these
 * results: the NaN/Inf test of check_rot/check_rigid takes precedence over
 * the orthonormality and determinant tests; the affine test accepts -0 in
 * the bottom row (== 0); Rot(x|y|z, deg) is bitwise Rot(k, deg) about the
 * coordinate axis k of any positive length (mat4.h); apply_point and
 * apply_dir never let entries they do not read (the bottom row, and p for
 * a direction) into the result.
 */
static void mat4_shared_path_edges(void)
{
    dh_mat4_f32 T, U, X, Y;
    dh_vec3_f32 u, v, w;
    unsigned it;
    int c, r;
    /* NaN/Inf in every entry of R, with R also huge or a reflection */
    for (it = 0; it < 9u * 4u * 2u; it++) {
        set_identity(&T);
        T.m[0][0] = (it & 1u) ? 1e30f : -1.0f;
        T.m[(it / 2u) % 3u][(it / 6u) % 3u] = bad_value(it / 18u);
        DHT_EQ_INT(dh_mat4_check_rot_f32(&T, 1e-3f), DH_ERR_NAN);
        DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, 1e-3f), DH_ERR_NAN);
    }
    /* -0 in the bottom row is affine: same status and bits as +0 */
    for (it = 0; it < DHT_ITER(200u); it++) {
        DHT_EQ_INT(dh_mat4_rot_axis_f32((float)dht_rand_uniform(-1.0, 1.0), (float)dht_rand_uniform(-1.0, 1.0), 1.0f,
                                        (float)dht_rand_uniform(-180.0, 180.0), &T), DH_OK);
        for (r = 0; r < 3; r++) T.m[3][r] = (float)dht_rand_uniform(-100.0, 100.0);
        U = T;
        for (c = 0; c < 3; c++) U.m[c][3] = -0.0f;
        DHT_EQ_INT(dh_mat4_check_rigid_f32(&U, DH_MAT4_RIGID_TOL), DH_OK);
        DHT_EQ_INT(dh_mat4_inv_auto_f32(&T, &X), DH_OK);
        DHT_EQ_INT(dh_mat4_inv_auto_f32(&U, &Y), DH_OK);
        DHT_TRUE(memcmp(&X, &Y, sizeof X) == 0);
        /* scaled (not rigid): the general inverse */
        for (c = 0; c < 3; c++)
            for (r = 0; r < 3; r++) {
                T.m[c][r] *= 1.5f;
                U.m[c][r] *= 1.5f;
            }
        DHT_EQ_INT(dh_mat4_inv_f32(&T, &X), DH_OK);
        DHT_EQ_INT(dh_mat4_inv_f32(&U, &Y), DH_OK);
        DHT_TRUE(memcmp(&X, &Y, sizeof X) == 0);
        for (r = 0; r < 3; r++) DHT_EQ_F32_BITS(Y.m[r][3], 0.0f);
        DHT_EQ_F32_BITS(Y.m[3][3], 1.0f);
    }
    /* coordinate rotations == Rot(k, deg) about a coordinate axis */
    for (it = 0; it < DHT_ITER(3000u); it++) {
        const double d = dht_rand_uniform(-720.0, 720.0);
        const float deg = (it & 1u) ? (float)d : (float)(long)d;   /* whole degrees too */
        const float len = (float)ldexp(dht_rand_uniform(1.0, 2.0), (int)(dht_rand_u32() % 201u) - 100);
        int ax;
        for (ax = 0; ax < 3; ax++) {
            const dh_status st = (ax == 0) ? dh_mat4_rotx_f32(deg, &X)
                               : (ax == 1) ? dh_mat4_roty_f32(deg, &X) : dh_mat4_rotz_f32(deg, &X);
            DHT_EQ_INT(st, DH_OK);
            DHT_EQ_INT(dh_mat4_rot_axis_f32((ax == 0) ? len : 0.0f, (ax == 1) ? len : 0.0f, (ax == 2) ? len : 0.0f,
                                            deg, &Y), DH_OK);
            DHT_TRUE_MSG(memcmp(&X, &Y, sizeof X) == 0, "axis %d deg %.9g len %g", ax, (double)deg, (double)len);
        }
    }
    /* entries not read: bottom row (point, direction), p (direction) */
    DHT_EQ_INT(dh_mat4_rot_axis_f32(0.3f, -0.5f, 0.8f, 33.3f, &T), DH_OK);
    T.m[3][0] = 1.5f;
    T.m[3][1] = -2.25f;
    T.m[3][2] = 7.0f;
    u.x = 0.7f;
    u.y = -1.3f;
    u.z = 2.9f;
    for (it = 0; it < 4u; it++) {
        U = T;
        for (c = 0; c < 4; c++) U.m[c][3] = bad_value(it);
        dh_mat4_apply_point_f32(&T, &u, &v);
        dh_mat4_apply_point_f32(&U, &u, &w);
        DHT_TRUE(memcmp(&v, &w, sizeof v) == 0);
        for (r = 0; r < 3; r++) U.m[3][r] = bad_value(it + 1u);
        dh_mat4_apply_dir_f32(&T, &u, &v);
        dh_mat4_apply_dir_f32(&U, &u, &w);
        DHT_TRUE(memcmp(&v, &w, sizeof v) == 0);
        DHT_EQ_INT(dh_mat4_check_finite_f32(&U), DH_ERR_NAN);
    }
}

/*
 * Zero results are +0 (DH_SMALL forms them as x + 0 instead of the
 * default's x == 0 ? 0 : x, which must give the same bits): a homogeneous
 * point whose quotient is -0 (-0 / 1 and +0 / -1), and rotations at
 * angles whose sine or cosine is a signed zero.
 */
static void mat4_signed_zeros(void)
{
    static const float degs[] = {0.0f, -0.0f, 90.0f, -90.0f, 180.0f, -180.0f, 270.0f, -270.0f, 360.0f, -360.0f, 720.0f};
    dh_mat4_f32 T;
    dh_vec4_f32 u;
    dh_vec3_f32 v;
    int i, c, r, ax;
    dh_mat4_trans_f32(-0.0f, -0.0f, -0.0f, &T);
    u.x = -0.0f; u.y = -0.0f; u.z = -0.0f; u.w = 1.0f;
    DHT_EQ_INT(dh_mat4_apply_point_h_f32(&T, &u, &v), DH_OK);
    DHT_EQ_F32_BITS(v.x, 0.0f);
    DHT_EQ_F32_BITS(v.y, 0.0f);
    DHT_EQ_F32_BITS(v.z, 0.0f);
    dh_mat4_identity_f32(&T);
    u.x = 0.0f; u.y = 0.0f; u.z = 0.0f; u.w = -1.0f;
    DHT_EQ_INT(dh_mat4_apply_point_h_f32(&T, &u, &v), DH_OK);
    DHT_EQ_F32_BITS(v.x, 0.0f);
    DHT_EQ_F32_BITS(v.y, 0.0f);
    DHT_EQ_F32_BITS(v.z, 0.0f);
    u.x = -2.0f; u.y = 0.0f; u.z = 4.0f; u.w = -2.0f;
    DHT_EQ_INT(dh_mat4_apply_point_h_f32(&T, &u, &v), DH_OK);
    DHT_EQ_F32_BITS(v.x, 1.0f);
    DHT_EQ_F32_BITS(v.y, 0.0f);
    DHT_EQ_F32_BITS(v.z, -2.0f);
    for (i = 0; i < (int)(sizeof degs / sizeof degs[0]); i++) {
        for (ax = 0; ax < 4; ax++) {
            dh_status st;
            if (ax == 0) st = dh_mat4_rotx_f32(degs[i], &T);
            else if (ax == 1) st = dh_mat4_roty_f32(degs[i], &T);
            else if (ax == 2) st = dh_mat4_rotz_f32(degs[i], &T);
            else st = dh_mat4_rot_axis_f32(-1.0f, 0.0f, -0.0f, degs[i], &T);
            DHT_EQ_INT(st, DH_OK);
            for (c = 0; c < 4; c++)
                for (r = 0; r < 4; r++) {
                    DHT_TRUE_MSG(!(T.m[c][r] == 0.0f && signbit(T.m[c][r])), "-0 at %d %d (axis %d, %g deg)", c, r, ax,
                                 (double)degs[i]);
                    DHT_TRUE(T.m[c][r] == 0.0f || fabsf(T.m[c][r]) == 1.0f);
                }
        }
    }
}

/*
 * The affine product never reads the bottom rows of A and B: NaN, +-Inf or
 * FLT_MAX in any one of those eight entries (DH_SMALL adds p_A into a
 * column whose row 3 it then overwrites) leaves every bit of the result,
 * also with out aliasing A or B. Small integers, so the reference (double,
 * here) is exact.
 */
static void mat4_affine_bottom_rows(void)
{
    const float poison[] = {NAN, INFINITY, -INFINITY, FLT_MAX};
    dh_mat4_f32 A, B, C, R;
    int c, r, k, e, p, alias;
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) {
            A.m[c][r] = (float)((c * 5 + r * 3) % 7 - 3);
            B.m[c][r] = (float)((c * 2 + r * 5) % 9 - 4);
        }
    for (c = 0; c < 4; c++) {
        for (r = 0; r < 3; r++) {
            double acc = (c == 3) ? (double)A.m[3][r] : 0.0;
            for (k = 0; k < 3; k++) acc += (double)A.m[k][r] * (double)B.m[c][k];
            R.m[c][r] = (float)acc;
        }
        R.m[c][3] = (c == 3) ? 1.0f : 0.0f;
    }
    for (e = 0; e < 8; e++) {
        for (p = 0; p < 4; p++) {
            for (alias = 0; alias < 3; alias++) {
                dh_mat4_f32 A2 = A, B2 = B;
                if (e < 4) A2.m[e][3] = poison[p];
                else B2.m[e - 4][3] = poison[p];
                if (alias == 0) {
                    dh_mat4_mul_affine_f32(&A2, &B2, &C);
                } else if (alias == 1) {
                    dh_mat4_mul_affine_f32(&A2, &B2, &A2);
                    C = A2;
                } else {
                    dh_mat4_mul_affine_f32(&A2, &B2, &B2);
                    C = B2;
                }
                DHT_TRUE_MSG(memcmp(&C, &R, sizeof C) == 0, "entry %d poison %d alias %d", e, p, alias);
            }
        }
    }
}

static const dht_case cases[] = {
    DHT_CASE(mat4_rot_nan_inf_huge),
    DHT_CASE(mat4_rot_axis_bad),
    DHT_CASE(mat4_persp_bad),
    DHT_CASE(mat4_apply_point_h_bad),
    DHT_CASE(mat4_inv_bad),
    DHT_CASE(mat4_inv_rigid_nonrigid),
    DHT_CASE(mat4_check_rigid_bad),
    DHT_CASE(mat4_axis_angle_bad),
    DHT_CASE(mat4_apply_plane_bad),
    DHT_CASE(mat4_no_status_ieee_and_alias),
    DHT_CASE(mat4_shared_path_edges),
    DHT_CASE(mat4_signed_zeros),
    DHT_CASE(mat4_affine_bottom_rows),
};
DHT_MAIN(cases)
