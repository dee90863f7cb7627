/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_mat4_seed.c - every worked example of Paul 1981 chapter 1 (in the
 * transcription of Paul & Daly, "dhmatrix.spad") reproduced EXACTLY: all the numbers in those examples
 * are small integers, 0 and +-1, so the float results must be bitwise equal
 * to the book's values (zeros as +0). The expected values below are typed
 * in from the book, not computed by the code under test.
 *
 * Also: the contracts' special cases (status codes, untouched outputs,
 * aliasing) of the constructors, products, application functions,
 * inverses and the equivalent angle and axis.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "dht.h"
#include "dhmath/mat4.h"
#include "dhmath/rot.h"

/* ---- helpers ----------------------------------------------------------- */

/* Matrix typed row by row as in the book (rows top to bottom). */
static dh_mat4_f32 rows(const float r[4][4])
{
    dh_mat4_f32 T;
    int i, j;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) DH_M4(&T, i, j) = r[i][j];
    return T;
}

#define CHECK_MAT_BITS(T, R)                                                  \
    do {                                                                      \
        int i_, j_;                                                           \
        for (i_ = 0; i_ < 4; i_++)                                            \
            for (j_ = 0; j_ < 4; j_++) DHT_EQ_F32_BITS(DH_M4((T), i_, j_), (R)[i_][j_]); \
    } while (0)

#define CHECK_V3_BITS(v, X, Y, Z)        \
    do {                                 \
        DHT_EQ_F32_BITS((v).x, (X));     \
        DHT_EQ_F32_BITS((v).y, (Y));     \
        DHT_EQ_F32_BITS((v).z, (Z));     \
    } while (0)

static dh_vec3_f32 v3(float x, float y, float z)
{
    dh_vec3_f32 v;
    v.x = x; v.y = y; v.z = z;
    return v;
}

static dh_vec4_f32 v4(float x, float y, float z, float w)
{
    dh_vec4_f32 v;
    v.x = x; v.y = y; v.z = z; v.w = w;
    return v;
}

static int mat_bits_equal(const dh_mat4_f32 *A, const dh_mat4_f32 *B)
{
    return memcmp(A, B, sizeof *A) == 0;
}

/* Seed matrices (row by row) */
static const float ROTZ90[4][4] = { { 0, -1, 0, 0 }, { 1, 0, 0, 0 }, { 0, 0, 1, 0 }, { 0, 0, 0, 1 } };
static const float ROTY90[4][4] = { { 0, 0, 1, 0 }, { 0, 1, 0, 0 }, { -1, 0, 0, 0 }, { 0, 0, 0, 1 } };
static const float EQ141[4][4] = { { 0, 0, 1, 0 }, { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 0, 1 } };
static const float EQ143[4][4] = { { 0, -1, 0, 0 }, { 0, 0, 1, 0 }, { -1, 0, 0, 0 }, { 0, 0, 0, 1 } };
static const float EQ146[4][4] = { { 0, 0, 1, 4 }, { 1, 0, 0, -3 }, { 0, 1, 0, 7 }, { 0, 0, 0, 1 } };
static const float EQ152[4][4] = { { 0, 0, 1, 4 }, { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 0, 1 } };
static const float EQ154[4][4] = { { 0, 1, 0, 0 }, { 0, 0, 1, 0 }, { 1, 0, 0, -4 }, { 0, 0, 0, 1 } };
static const float IDENT[4][4] = { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 }, { 0, 0, 0, 1 } };

/* ---- eq. 1.24-1.31: translation, points and planes -------------------- */

static void seed_eq_1_27_translation(void)
{
    static const float TR[4][4] = { { 1, 0, 0, 4 }, { 0, 1, 0, -3 }, { 0, 0, 1, 7 }, { 0, 0, 0, 1 } };
    dh_mat4_f32 T;
    dh_vec3_f32 u = v3(2, 3, 2), v;
    dh_vec4_f32 h = v4(2, 3, 2, 1), hv;
    dh_mat4_trans_f32(4, -3, 7, &T);
    CHECK_MAT_BITS(&T, TR);
    dh_mat4_apply_point_f32(&T, &u, &v);
    CHECK_V3_BITS(v, 6.0f, 0.0f, 9.0f);
    dh_mat4_apply_vec4_f32(&T, &h, &hv);
    CHECK_V3_BITS(hv, 6.0f, 0.0f, 9.0f);
    DHT_EQ_F32_BITS(hv.w, 1.0f);
    /* in place (u and v the same object) */
    dh_mat4_apply_point_f32(&T, &u, &u);
    CHECK_V3_BITS(u, 6.0f, 0.0f, 9.0f);
}

static void seed_eq_1_28_scaled_homogeneous(void)
{
    /* the transform times -5 and the point times 2 describe the same point */
    static const float TR5[4][4] = { { -5, 0, 0, -20 }, { 0, -5, 0, 15 }, { 0, 0, -5, -35 }, { 0, 0, 0, -5 } };
    dh_mat4_f32 T = rows(TR5);
    dh_vec4_f32 u = v4(4, 6, 4, 2), hv;
    dh_vec3_f32 v;
    dh_mat4_apply_vec4_f32(&T, &u, &hv);
    DHT_EQ_F32_BITS(hv.x, -60.0f);
    DHT_EQ_F32_BITS(hv.y, 0.0f);
    DHT_EQ_F32_BITS(hv.z, -90.0f);
    DHT_EQ_F32_BITS(hv.w, -10.0f);
    DHT_EQ_INT(dh_mat4_apply_point_h_f32(&T, &u, &v), DH_OK);
    CHECK_V3_BITS(v, 6.0f, 0.0f, 9.0f); /* [6, 0, 9, 1] as before; zero is +0 */
}

static void seed_eq_1_29_1_31_plane(void)
{
    static const float INV[4][4] = { { 1, 0, 0, -4 }, { 0, 1, 0, 3 }, { 0, 0, 1, -7 }, { 0, 0, 0, 1 } };
    dh_mat4_f32 T, Ti, Tg;
    dh_plane_f32 P = { 1, 0, 0, -2 }, Q;
    dh_vec3_f32 u = v3(2, 3, 2), v;
    dh_mat4_trans_f32(4, -3, 7, &T);
    /* eq. 1.29: the point lies in the plane */
    DHT_EQ_F32_BITS(P.a * u.x + P.b * u.y + P.c * u.z + P.d, 0.0f);
    /* the inverse given in the book, by both inverses */
    dh_mat4_inv_rigid_f32(&T, &Ti);
    CHECK_MAT_BITS(&Ti, INV);
    DHT_EQ_INT(dh_mat4_inv_f32(&T, &Tg), DH_OK);
    CHECK_MAT_BITS(&Tg, INV);
    /* eq. 1.30 */
    DHT_EQ_INT(dh_mat4_apply_plane_f32(&T, &P, &Q), DH_OK);
    DHT_EQ_F32_BITS(Q.a, 1.0f);
    DHT_EQ_F32_BITS(Q.b, 0.0f);
    DHT_EQ_F32_BITS(Q.c, 0.0f);
    DHT_EQ_F32_BITS(Q.d, -6.0f);
    dh_plane_mul_f32(&P, &Ti, &P); /* aliasing P == Q */
    DHT_EQ_F32_BITS(P.a, 1.0f);
    DHT_EQ_F32_BITS(P.d, -6.0f);
    /* eq. 1.31: the transformed point lies in the transformed plane */
    dh_mat4_apply_point_f32(&T, &u, &v);
    DHT_EQ_F32_BITS(Q.a * v.x + Q.b * v.y + Q.c * v.z + Q.d, 0.0f);
}

/* ---- eq. 1.32-1.47: rotations and their products ---------------------- */

static void seed_eq_1_35_1_36_rotations(void)
{
    dh_mat4_f32 Rz, Ry;
    dh_vec3_f32 u = v3(7, 3, 2), v, w;
    DHT_EQ_INT(dh_mat4_rotz_f32(90.0f, &Rz), DH_OK);
    CHECK_MAT_BITS(&Rz, ROTZ90);
    DHT_EQ_INT(dh_mat4_roty_f32(90.0f, &Ry), DH_OK);
    CHECK_MAT_BITS(&Ry, ROTY90);
    dh_mat4_apply_point_f32(&Rz, &u, &v);     /* eq. 1.35 */
    CHECK_V3_BITS(v, -3.0f, 7.0f, 2.0f);
    dh_mat4_apply_point_f32(&Ry, &v, &w);     /* eq. 1.36 */
    CHECK_V3_BITS(w, 2.0f, 7.0f, 3.0f);
}

static void seed_eq_1_40_1_42_composition(void)
{
    dh_mat4_f32 Rz, Ry, P, Pa;
    dh_vec3_f32 u = v3(7, 3, 2), w;
    dh_mat4_rotz_f32(90.0f, &Rz);
    dh_mat4_roty_f32(90.0f, &Ry);
    dh_mat4_mul_f32(&Ry, &Rz, &P);            /* eq. 1.40 / 1.41 */
    CHECK_MAT_BITS(&P, EQ141);
    dh_mat4_mul_affine_f32(&Ry, &Rz, &Pa);
    CHECK_MAT_BITS(&Pa, EQ141);
    dh_mat4_apply_point_f32(&P, &u, &w);      /* eq. 1.42 */
    CHECK_V3_BITS(w, 2.0f, 7.0f, 3.0f);
}

static void seed_eq_1_43_1_45_noncommutative(void)
{
    dh_mat4_f32 Rz, Ry, P, Q;
    dh_vec3_f32 u = v3(7, 3, 2), w;
    dh_mat4_rotz_f32(90.0f, &Rz);
    dh_mat4_roty_f32(90.0f, &Ry);
    dh_mat4_mul_f32(&Rz, &Ry, &P);            /* eq. 1.43 */
    CHECK_MAT_BITS(&P, EQ143);
    dh_mat4_apply_point_f32(&P, &u, &w);      /* eq. 1.44 */
    CHECK_V3_BITS(w, -3.0f, 2.0f, -7.0f);
    dh_mat4_mul_f32(&Ry, &Rz, &Q);            /* eq. 1.45: AB != BA */
    DHT_TRUE(!mat_bits_equal(&P, &Q));
}

static void seed_eq_1_46_1_48_translation_and_frame(void)
{
    dh_mat4_f32 Tr, Rz, Ry, P;
    dh_vec3_f32 u = v3(7, 3, 2), x, o = v3(0, 0, 0), d;
    dh_vec4_f32 h;
    dh_mat4_trans_f32(4, -3, 7, &Tr);
    dh_mat4_rotz_f32(90.0f, &Rz);
    dh_mat4_roty_f32(90.0f, &Ry);
    /* Trans Rot(y) Rot(z): built both ways round (grouping) and affine */
    dh_mat4_mul_f32(&Ry, &Rz, &P);
    dh_mat4_mul_f32(&Tr, &P, &P);             /* out aliases B */
    CHECK_MAT_BITS(&P, EQ146);
    dh_mat4_mul_affine_f32(&Tr, &Ry, &P);
    dh_mat4_mul_affine_f32(&P, &Rz, &P);      /* out aliases A */
    CHECK_MAT_BITS(&P, EQ146);
    dh_mat4_apply_point_f32(&P, &u, &x);      /* eq. 1.47 */
    CHECK_V3_BITS(x, 6.0f, 4.0f, 10.0f);
    /* eq. 1.48: the null vector maps to the p column; unit vectors */
    dh_mat4_apply_point_f32(&P, &o, &x);
    CHECK_V3_BITS(x, 4.0f, -3.0f, 7.0f);
    d = v3(1, 0, 0); dh_mat4_apply_point_f32(&P, &d, &x); CHECK_V3_BITS(x, 4.0f, -2.0f, 7.0f);
    d = v3(0, 1, 0); dh_mat4_apply_point_f32(&P, &d, &x); CHECK_V3_BITS(x, 4.0f, -3.0f, 8.0f);
    d = v3(0, 0, 1); dh_mat4_apply_point_f32(&P, &d, &x); CHECK_V3_BITS(x, 5.0f, -3.0f, 7.0f);
    /* directions of the frame axes: the n, o, a columns */
    d = v3(1, 0, 0); dh_mat4_apply_dir_f32(&P, &d, &x); CHECK_V3_BITS(x, 0.0f, 1.0f, 0.0f);
    d = v3(0, 1, 0); dh_mat4_apply_dir_f32(&P, &d, &x); CHECK_V3_BITS(x, 0.0f, 0.0f, 1.0f);
    d = v3(0, 0, 1); dh_mat4_apply_dir_f32(&P, &d, &x); CHECK_V3_BITS(x, 1.0f, 0.0f, 0.0f);
    x = dh_mat4_n_f32(&P); CHECK_V3_BITS(x, 0.0f, 1.0f, 0.0f);
    x = dh_mat4_o_f32(&P); CHECK_V3_BITS(x, 0.0f, 0.0f, 1.0f);
    x = dh_mat4_a_f32(&P); CHECK_V3_BITS(x, 1.0f, 0.0f, 0.0f);
    x = dh_mat4_p_f32(&P); CHECK_V3_BITS(x, 4.0f, -3.0f, 7.0f);
    /* homogeneous direction (w = 0) through the full product */
    h = v4(1, 0, 0, 0);
    dh_mat4_apply_vec4_f32(&P, &h, &h);
    CHECK_V3_BITS(h, 0.0f, 1.0f, 0.0f);
    DHT_EQ_F32_BITS(h.w, 0.0f);
}

/* ---- eq. 1.49-1.51: relative transformations -------------------------- */

static void seed_eq_1_50_1_51_pre_post(void)
{
    static const float C_[4][4] = { { 1, 0, 0, 20 }, { 0, 0, -1, 10 }, { 0, 1, 0, 0 }, { 0, 0, 0, 1 } };
    static const float T_[4][4] = { { 0, -1, 0, 10 }, { 1, 0, 0, 0 }, { 0, 0, 1, 0 }, { 0, 0, 0, 1 } };
    static const float X_[4][4] = { { 0, 0, 1, 0 }, { 1, 0, 0, 20 }, { 0, 1, 0, 0 }, { 0, 0, 0, 1 } };
    static const float Y_[4][4] = { { 0, -1, 0, 30 }, { 0, 0, -1, 10 }, { 1, 0, 0, 0 }, { 0, 0, 0, 1 } };
    dh_mat4_f32 C = rows(C_), T, Tz, Tx, X, Y;
    /* T = Trans(10, 0, 0) Rot(z, 90), built with the constructors */
    dh_mat4_trans_f32(10, 0, 0, &Tx);
    dh_mat4_rotz_f32(90.0f, &Tz);
    dh_mat4_mul_f32(&Tx, &Tz, &T);
    CHECK_MAT_BITS(&T, T_);
    X = C;
    dh_mat4_premul_f32(&X, &T);   /* X = T C, motion in base coordinates (eq. 1.50) */
    CHECK_MAT_BITS(&X, X_);
    Y = C;
    dh_mat4_postmul_f32(&Y, &T);  /* Y = C T, motion in the frame's axes (eq. 1.51) */
    CHECK_MAT_BITS(&Y, Y_);
    /* the same with the affine product */
    dh_mat4_mul_affine_f32(&T, &C, &X);
    CHECK_MAT_BITS(&X, X_);
    dh_mat4_mul_affine_f32(&C, &T, &Y);
    CHECK_MAT_BITS(&Y, Y_);
}

/* ---- eq. 1.52-1.55: objects and the inverse --------------------------- */

static void seed_eq_1_52_1_53_object(void)
{
    /* six points of the wedge, columns of eq. 1.53 */
    static const float U[6][3] = { { 1, 0, 0 }, { -1, 0, 0 }, { -1, 0, 2 }, { 1, 0, 2 }, { 1, 4, 0 }, { -1, 4, 0 } };
    static const float V[6][3] = { { 4, 1, 0 }, { 4, -1, 0 }, { 6, -1, 0 }, { 6, 1, 0 }, { 4, 1, 4 }, { 4, -1, 4 } };
    dh_mat4_f32 Tr, Ry, Rz, T;
    dh_vec3_f32 u[6], v[6];
    int i;
    dh_mat4_trans_f32(4, 0, 0, &Tr);
    dh_mat4_roty_f32(90.0f, &Ry);
    dh_mat4_rotz_f32(90.0f, &Rz);
    dh_mat4_mul_f32(&Tr, &Ry, &T);
    dh_mat4_postmul_f32(&T, &Rz);
    CHECK_MAT_BITS(&T, EQ152);
    for (i = 0; i < 6; i++) u[i] = v3(U[i][0], U[i][1], U[i][2]);
    dh_mat4_apply_points_f32(&T, u, v, 6);
    for (i = 0; i < 6; i++) CHECK_V3_BITS(v[i], V[i][0], V[i][1], V[i][2]);
    dh_mat4_apply_points_f32(&T, u, u, 6); /* in place */
    for (i = 0; i < 6; i++) CHECK_V3_BITS(u[i], V[i][0], V[i][1], V[i][2]);
    dh_mat4_apply_points_f32(&T, NULL, NULL, 0); /* count 0: nothing */
}

static void seed_eq_1_54_1_55_inverse(void)
{
    dh_mat4_f32 T = rows(EQ152), Ti, Tg, Ta, P;
    dh_mat4_inv_rigid_f32(&T, &Ti);               /* eq. 1.54 via eq. 1.57 */
    CHECK_MAT_BITS(&Ti, EQ154);
    DHT_EQ_INT(dh_mat4_inv_f32(&T, &Tg), DH_OK);  /* general inverse */
    CHECK_MAT_BITS(&Tg, EQ154);
    DHT_EQ_INT(dh_mat4_inv_auto_f32(&T, &Ta), DH_OK);
    CHECK_MAT_BITS(&Ta, EQ154);
    dh_mat4_mul_f32(&Ti, &T, &P);                 /* eq. 1.55 */
    CHECK_MAT_BITS(&P, IDENT);
    dh_mat4_mul_f32(&T, &Ti, &P);
    CHECK_MAT_BITS(&P, IDENT);
    /* in place */
    Ta = T;
    dh_mat4_inv_rigid_f32(&Ta, &Ta);
    CHECK_MAT_BITS(&Ta, EQ154);
    Ta = T;
    DHT_EQ_INT(dh_mat4_inv_f32(&Ta, &Ta), DH_OK);
    CHECK_MAT_BITS(&Ta, EQ154);
}

/* ---- eq. 1.104-1.112: Example 1.1 ------------------------------------- */

static void seed_example_1_1_axis_angle(void)
{
    dh_mat4_f32 Ry, Rz, R, Rk;
    dh_vec3_f32 k;
    float th = -1.0f;
    const double inv_sqrt3 = 0.57735026918962576451; /* 1/sqrt(3) */
    dh_mat4_roty_f32(90.0f, &Ry);
    dh_mat4_rotz_f32(90.0f, &Rz);
    dh_mat4_mul_f32(&Ry, &Rz, &R);
    CHECK_MAT_BITS(&R, EQ141);                    /* eq. 1.104 */
    DHT_EQ_INT(dh_mat4_to_axis_angle_f32(&R, &k, &th), DH_OK);
    DHT_EQ_F32_BITS(th, 120.0f);                  /* eq. 1.107: exactly 120 */
    /* eq. 1.108-1.110, 1.112: k = (1,1,1)/sqrt(3) within 1 ulp (6e-8) */
    DHT_NEAR(k.x, inv_sqrt3, 6e-8);
    DHT_NEAR(k.y, inv_sqrt3, 6e-8);
    DHT_NEAR(k.z, inv_sqrt3, 6e-8);
    dht_printf("Example 1.1: theta = %.9g, k = (%.9g, %.9g, %.9g), 1/sqrt3 = %.9g\n", (double)th,
               (double)k.x, (double)k.y, (double)k.z, inv_sqrt3);
    /* eq. 1.111: Rot(k, 120) reproduces the matrix (0/1 entries within
     * rounding of the irrational k) */
    DHT_EQ_INT(dh_mat4_rot_axis_f32(1, 1, 1, 120.0f, &Rk), DH_OK);
    {
        int i, j;
        for (i = 0; i < 4; i++)
            for (j = 0; j < 4; j++) DHT_NEAR(DH_M4(&Rk, i, j), EQ141[i][j], 2.4e-7);
    }
}

/* ---- eq. 1.113-1.129: scaling and perspective ------------------------- */

static void seed_eq_1_113_scale(void)
{
    static const float S[4][4] = { { 2, 0, 0, 0 }, { 0, 3, 0, 0 }, { 0, 0, 0.5f, 0 }, { 0, 0, 0, 1 } };
    dh_mat4_f32 T;
    dh_vec3_f32 u = v3(5, -7, 9), v;
    dh_mat4_scale_f32(2, 3, 0.5f, &T);
    CHECK_MAT_BITS(&T, S);
    dh_mat4_apply_point_f32(&T, &u, &v);  /* eq. 1.114 */
    CHECK_V3_BITS(v, 10.0f, -21.0f, 4.5f);
}

static void seed_eq_1_127_perspective(void)
{
    /* eq. 1.127 with f = 4: -1/f = -0.25 in the bottom row, y column */
    static const float PY[4][4] = { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 }, { 0, -0.25f, 0, 1 } };
    static const float PX[4][4] = { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 }, { -0.25f, 0, 0, 1 } };
    static const float PZ[4][4] = { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 }, { 0, 0, -0.25f, 1 } };
    dh_mat4_f32 T, U;
    dh_vec4_f32 u = v4(3, 2, -6, 1), h;
    dh_vec3_f32 v;
    DHT_EQ_INT(dh_mat4_persp_f32(1, 4.0f, &T), DH_OK);
    CHECK_MAT_BITS(&T, PY);
    /* eq. 1.128: w = 1 - y/f = 0.5 */
    dh_mat4_apply_vec4_f32(&T, &u, &h);
    DHT_EQ_F32_BITS(h.w, 0.5f);
    /* eq. 1.129: image point (x, y, z) / (1 - y/f) */
    DHT_EQ_INT(dh_mat4_apply_point_h_f32(&T, &u, &v), DH_OK);
    CHECK_V3_BITS(v, 6.0f, 4.0f, -12.0f);
    DHT_EQ_INT(dh_mat4_persp_f32(0, 4.0f, &T), DH_OK);
    CHECK_MAT_BITS(&T, PX);
    DHT_EQ_INT(dh_mat4_persp_f32(2, 4.0f, &T), DH_OK);
    CHECK_MAT_BITS(&T, PZ);
    /* along z: w = 1 - z/f = 2.5 */
    DHT_EQ_INT(dh_mat4_apply_point_h_f32(&T, &u, &v), DH_OK);
    CHECK_V3_BITS(v, 1.2f, 0.8f, -2.4f);
    /* errors: bad axis, f == 0, NaN; T untouched */
    U = T;
    DHT_EQ_INT(dh_mat4_persp_f32(3, 4.0f, &T), DH_ERR_ARG);
    DHT_EQ_INT(dh_mat4_persp_f32(-1, 4.0f, &T), DH_ERR_ARG);
    DHT_EQ_INT(dh_mat4_persp_f32(1, 0.0f, &T), DH_ERR_DOMAIN);
    DHT_EQ_INT(dh_mat4_persp_f32(1, -0.0f, &T), DH_ERR_DOMAIN);
    DHT_EQ_INT(dh_mat4_persp_f32(1, 1e-45f, &T), DH_ERR_DOMAIN); /* 1/f overflows */
    DHT_EQ_INT(dh_mat4_persp_f32(1, NAN, &T), DH_ERR_NAN);
    DHT_EQ_INT(dh_mat4_persp_f32(1, INFINITY, &T), DH_ERR_NAN);
    DHT_TRUE(mat_bits_equal(&T, &U));
}

/* ---- constructor contracts ------------------------------------------- */

static void rotations_whole_quadrants_exact(void)
{
    /* multiples of 90 are exact and carry no -0; Rot(.., 0) == I bitwise */
    static const float RX90[4][4] = { { 1, 0, 0, 0 }, { 0, 0, -1, 0 }, { 0, 1, 0, 0 }, { 0, 0, 0, 1 } };
    static const float RZ180[4][4] = { { -1, 0, 0, 0 }, { 0, -1, 0, 0 }, { 0, 0, 1, 0 }, { 0, 0, 0, 1 } };
    static const float RYM90[4][4] = { { 0, 0, -1, 0 }, { 0, 1, 0, 0 }, { 1, 0, 0, 0 }, { 0, 0, 0, 1 } };
    dh_mat4_f32 T, I;
    dh_mat4_identity_f32(&I);
    CHECK_MAT_BITS(&I, IDENT);
    DHT_EQ_INT(dh_mat4_rotx_f32(0.0f, &T), DH_OK);  CHECK_MAT_BITS(&T, IDENT);
    DHT_EQ_INT(dh_mat4_roty_f32(-0.0f, &T), DH_OK); CHECK_MAT_BITS(&T, IDENT);
    DHT_EQ_INT(dh_mat4_rotz_f32(360.0f, &T), DH_OK); CHECK_MAT_BITS(&T, IDENT);
    DHT_EQ_INT(dh_mat4_rotx_f32(90.0f, &T), DH_OK); CHECK_MAT_BITS(&T, RX90);
    DHT_EQ_INT(dh_mat4_rotx_f32(-270.0f, &T), DH_OK); CHECK_MAT_BITS(&T, RX90);
    DHT_EQ_INT(dh_mat4_rotz_f32(180.0f, &T), DH_OK); CHECK_MAT_BITS(&T, RZ180);
    DHT_EQ_INT(dh_mat4_rotz_f32(-180.0f, &T), DH_OK); CHECK_MAT_BITS(&T, RZ180);
    DHT_EQ_INT(dh_mat4_roty_f32(-90.0f, &T), DH_OK); CHECK_MAT_BITS(&T, RYM90);
    /* general axis along the coordinate axes: bitwise the same */
    DHT_EQ_INT(dh_mat4_rot_axis_f32(1, 0, 0, 90.0f, &T), DH_OK); CHECK_MAT_BITS(&T, RX90);
    DHT_EQ_INT(dh_mat4_rot_axis_f32(0, 0, 5, 90.0f, &T), DH_OK); CHECK_MAT_BITS(&T, ROTZ90);
    DHT_EQ_INT(dh_mat4_rot_axis_f32(0, 1e-30f, 0, 90.0f, &T), DH_OK); CHECK_MAT_BITS(&T, ROTY90);
    DHT_EQ_INT(dh_mat4_rot_axis_f32(0, -3e30f, 0, -90.0f, &T), DH_OK); CHECK_MAT_BITS(&T, ROTY90);
    DHT_EQ_INT(dh_mat4_rot_axis_f32(0, 0, 1, 180.0f, &T), DH_OK); CHECK_MAT_BITS(&T, RZ180);
    DHT_EQ_INT(dh_mat4_rot_axis_f32(0.3f, -0.2f, 0.9f, 0.0f, &T), DH_OK); CHECK_MAT_BITS(&T, IDENT);
}

static void constructor_errors(void)
{
    dh_mat4_f32 T, U;
    dh_mat4_trans_f32(1, 2, 3, &T);
    U = T;
    DHT_EQ_INT(dh_mat4_rotx_f32(NAN, &T), DH_ERR_NAN);
    DHT_EQ_INT(dh_mat4_roty_f32(INFINITY, &T), DH_ERR_NAN);
    DHT_EQ_INT(dh_mat4_rotz_f32(-INFINITY, &T), DH_ERR_NAN);
    DHT_EQ_INT(dh_mat4_rot_axis_f32(0, 0, 0, 10.0f, &T), DH_ERR_ZERO_AXIS);
    DHT_EQ_INT(dh_mat4_rot_axis_f32(1e-40f, -1e-41f, 0, 10.0f, &T), DH_ERR_ZERO_AXIS); /* denormal */
    DHT_EQ_INT(dh_mat4_rot_axis_f32(NAN, 0, 1, 10.0f, &T), DH_ERR_NAN);
    DHT_EQ_INT(dh_mat4_rot_axis_f32(0, INFINITY, 1, 10.0f, &T), DH_ERR_NAN);
    DHT_EQ_INT(dh_mat4_rot_axis_f32(0, 0, 1, NAN, &T), DH_ERR_NAN);
    DHT_EQ_INT(dh_mat4_rot_axis_f32(0, 0, 0, NAN, &T), DH_ERR_NAN);
    DHT_TRUE(mat_bits_equal(&T, &U));
    /* FLT_MIN itself is a valid (normal) axis */
    DHT_EQ_INT(dh_mat4_rot_axis_f32(FLT_MIN, 0, 0, 90.0f, &T), DH_OK);
    DHT_EQ_F32_BITS(DH_M4(&T, 2, 1), 1.0f);
    /* huge components: normalisation does not overflow */
    DHT_EQ_INT(dh_mat4_rot_axis_f32(FLT_MAX, FLT_MAX, FLT_MAX, 120.0f, &T), DH_OK);
    DHT_NEAR(DH_M4(&T, 1, 0), 1.0, 2.4e-7);
    DHT_NEAR(DH_M4(&T, 0, 0), 0.0, 2.4e-7);
}

static void frame_from_noap_and_rot_access(void)
{
    static const float F[4][4] = { { 0, 0, 1, 4 }, { 1, 0, 0, -3 }, { 0, 1, 0, 7 }, { 0, 0, 0, 1 } };
    dh_vec3_f32 n = v3(0, 1, 0), o = v3(0, 0, 1), a = v3(1, 0, 0), p = v3(4, -3, 7);
    dh_mat4_f32 T, U;
    dh_mat3_f32 R;
    int i, j;
    /* garbage first: every element must be written */
    memset(&T, 0x7f, sizeof T);
    dh_mat4_from_noap_f32(&n, &o, &a, &p, &T);
    CHECK_MAT_BITS(&T, F);
    dh_mat4_get_rot_f32(&T, &R);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) DHT_EQ_F32_BITS(DH_M3(&R, i, j), F[i][j]);
    dh_mat4_trans_f32(4, -3, 7, &U);
    dh_mat4_set_rot_f32(&U, &R);
    CHECK_MAT_BITS(&U, F);
}

/* ---- application contracts ------------------------------------------- */

static void point_h_errors(void)
{
    dh_mat4_f32 T;
    dh_vec4_f32 u;
    dh_vec3_f32 v = v3(11, 12, 13);
    dh_mat4_persp_f32(1, 4.0f, &T);
    u = v4(1, 4, 1, 1);                      /* w = 1 - 4/4 = 0: at infinity */
    DHT_EQ_INT(dh_mat4_apply_point_h_f32(&T, &u, &v), DH_ERR_DOMAIN);
    u = v4(1, 2, 3, 0);                      /* a direction through identity-ish T */
    dh_mat4_identity_f32(&T);
    DHT_EQ_INT(dh_mat4_apply_point_h_f32(&T, &u, &v), DH_ERR_DOMAIN);
    u = v4(NAN, 2, 3, 1);
    DHT_EQ_INT(dh_mat4_apply_point_h_f32(&T, &u, &v), DH_ERR_NAN);
    u = v4(1, 2, 3, 1);
    DH_M4(&T, 3, 3) = INFINITY;
    DHT_EQ_INT(dh_mat4_apply_point_h_f32(&T, &u, &v), DH_ERR_NAN);
    dh_mat4_identity_f32(&T);
    u = v4(3e38f, 3e38f, 0, 1);
    DH_M4(&T, 0, 1) = 2.0f;                  /* x = 9e38: overflow */
    DHT_EQ_INT(dh_mat4_apply_point_h_f32(&T, &u, &v), DH_ERR_OVERFLOW);
    dh_mat4_identity_f32(&T);
    u = v4(1e30f, 0, 0, 1e-30f);             /* x / w overflows */
    DHT_EQ_INT(dh_mat4_apply_point_h_f32(&T, &u, &v), DH_ERR_OVERFLOW);
    CHECK_V3_BITS(v, 11.0f, 12.0f, 13.0f);   /* untouched */
    /* negative w: signs and zeros */
    u = v4(-2, 0, 4, -2);
    DHT_EQ_INT(dh_mat4_apply_point_h_f32(&T, &u, &v), DH_OK);
    CHECK_V3_BITS(v, 1.0f, 0.0f, -2.0f);
}

static void plane_errors(void)
{
    dh_mat4_f32 T;
    dh_plane_f32 P = { 0, 0, 1, -1 }, Q = { 5, 6, 7, 8 };
    dh_mat4_scale_f32(1, 0, 1, &T);          /* singular */
    DHT_EQ_INT(dh_mat4_apply_plane_f32(&T, &P, &Q), DH_ERR_SINGULAR);
    dh_mat4_identity_f32(&T);
    P.b = NAN;
    DHT_EQ_INT(dh_mat4_apply_plane_f32(&T, &P, &Q), DH_ERR_NAN);
    P.b = 0;
    DH_M4(&T, 0, 2) = NAN;
    DHT_EQ_INT(dh_mat4_apply_plane_f32(&T, &P, &Q), DH_ERR_NAN);
    DHT_EQ_F32_BITS(Q.a, 5.0f);
    DHT_EQ_F32_BITS(Q.d, 8.0f);
    /* a scaling (not rigid) goes through the general inverse:
     * plane z = 1 under scale z by 2 becomes z = 2 */
    dh_mat4_scale_f32(1, 1, 2, &T);
    DHT_EQ_INT(dh_mat4_apply_plane_f32(&T, &P, &Q), DH_OK);
    DHT_EQ_F32_BITS(Q.a, 0.0f);
    DHT_EQ_F32_BITS(Q.b, 0.0f);
    DHT_EQ_F32_BITS(Q.c, 0.5f);
    DHT_EQ_F32_BITS(Q.d, -1.0f);
}

/* ---- inverse contracts ------------------------------------------------ */

static void inverse_errors_and_rigidity(void)
{
    static const float SING[4][4] = { { 1, 2, 3, 4 }, { 2, 4, 6, 8 }, { 0, 1, 0, 0 }, { 0, 0, 0, 1 } };
    dh_mat4_f32 T, O, O0;
    memset(&O, 0x55, sizeof O);
    O0 = O;
    /* exactly singular, zero, denormal, NaN, Inf: output untouched */
    T = rows(SING);
    DHT_EQ_INT(dh_mat4_inv_f32(&T, &O), DH_ERR_SINGULAR);
    memset(&T, 0, sizeof T);
    DHT_EQ_INT(dh_mat4_inv_f32(&T, &O), DH_ERR_SINGULAR);
    dh_mat4_scale_f32(1e-39f, 1e-39f, 1e-39f, &T);
    DH_M4(&T, 3, 3) = 1e-39f;
    DHT_EQ_INT(dh_mat4_inv_f32(&T, &O), DH_ERR_SINGULAR);
    dh_mat4_identity_f32(&T);
    DH_M4(&T, 2, 3) = NAN;
    DHT_EQ_INT(dh_mat4_inv_f32(&T, &O), DH_ERR_NAN);
    DHT_EQ_INT(dh_mat4_inv_auto_f32(&T, &O), DH_ERR_NAN);
    DH_M4(&T, 2, 3) = -INFINITY;
    DHT_EQ_INT(dh_mat4_inv_f32(&T, &O), DH_ERR_NAN);
    DHT_TRUE(mat_bits_equal(&O, &O0));
    /* uniform scale: diag(2^-120) has an inverse 2^120 (fine), diag(1e-38)
     * needs 1e38 (fine), diag(FLT_MIN) would need 2^126 (fine) */
    dh_mat4_scale_f32(FLT_MIN, FLT_MIN, FLT_MIN, &T);
    DH_M4(&T, 3, 3) = FLT_MIN;
    DHT_EQ_INT(dh_mat4_inv_f32(&T, &O), DH_OK);
    DHT_EQ_F32_BITS(DH_M4(&O, 0, 0), 1.0f / FLT_MIN);
    DHT_EQ_F32_BITS(DH_M4(&O, 0, 1), 0.0f);

    /* rigidity checks */
    dh_mat4_trans_f32(1, 2, 3, &T);
    DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, 1e-6f), DH_OK);
    DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, 0.0f), DH_OK);
    DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, -1.0f), DH_ERR_ARG);
    DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, NAN), DH_ERR_ARG);
    DHT_EQ_INT(dh_mat4_check_rot_f32(&T, -1.0f), DH_ERR_ARG);
    DH_M4(&T, 3, 0) = 1e-3f;                              /* bottom row */
    DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, 1e-2f), DH_ERR_NOT_RIGID);
    DHT_EQ_INT(dh_mat4_check_rot_f32(&T, 1e-2f), DH_OK);  /* rotation part only */
    dh_mat4_scale_f32(1, 1, -1, &T);                      /* reflection: det -1 */
    DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, 1e-2f), DH_ERR_NOT_RIGID);
    dh_mat4_scale_f32(1, 1, 1.001f, &T);                  /* stretched */
    DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, 1e-3f), DH_ERR_NOT_RIGID);
    DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, 3e-3f), DH_OK);
    dh_mat4_identity_f32(&T);
    DH_M4(&T, 0, 1) = 1e-3f;                              /* sheared */
    DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, 1e-4f), DH_ERR_NOT_RIGID);
    DH_M4(&T, 0, 1) = NAN;
    DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, 1e-4f), DH_ERR_NAN);
    DHT_EQ_INT(dh_mat4_check_rot_f32(&T, 1e-4f), DH_ERR_NAN);
    dh_mat4_identity_f32(&T);
    DH_M4(&T, 0, 3) = INFINITY;                           /* p not finite */
    DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, 1e-4f), DH_ERR_NAN);
    DHT_EQ_INT(dh_mat4_check_rot_f32(&T, 1e-4f), DH_OK);
    /* huge entries: squares overflow to Inf, must be "not rigid" */
    dh_mat4_scale_f32(1e30f, 1, 1, &T);
    DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, 1e-4f), DH_ERR_NOT_RIGID);
    /* inv_auto on a non-rigid matrix uses the general inverse */
    dh_mat4_scale_f32(2, 4, 8, &T);
    DHT_EQ_INT(dh_mat4_inv_auto_f32(&T, &O), DH_OK);
    DHT_EQ_F32_BITS(DH_M4(&O, 0, 0), 0.5f);
    DHT_EQ_F32_BITS(DH_M4(&O, 1, 1), 0.25f);
    DHT_EQ_F32_BITS(DH_M4(&O, 2, 2), 0.125f);
    DHT_EQ_F32_BITS(DH_M4(&O, 3, 3), 1.0f);
    /* and on a singular one reports it */
    dh_mat4_scale_f32(2, 0, 8, &T);
    O = O0;
    DHT_EQ_INT(dh_mat4_inv_auto_f32(&T, &O), DH_ERR_SINGULAR);
    DHT_TRUE(mat_bits_equal(&O, &O0));
}

/* ---- axis-angle special cases ---------------------------------------- */

static void axis_angle_special_cases(void)
{
    dh_mat4_f32 T;
    dh_vec3_f32 k = v3(9, 9, 9);
    float th = 99.0f;
    /* identity: theta 0, k = +z by contract */
    dh_mat4_trans_f32(5, 6, 7, &T);
    DHT_EQ_INT(dh_mat4_to_axis_angle_f32(&T, &k, &th), DH_OK);
    DHT_EQ_F32_BITS(th, 0.0f);
    CHECK_V3_BITS(k, 0.0f, 0.0f, 1.0f);
    /* exact quadrants */
    dh_mat4_rotx_f32(90.0f, &T);
    DHT_EQ_INT(dh_mat4_to_axis_angle_f32(&T, &k, &th), DH_OK);
    DHT_EQ_F32_BITS(th, 90.0f);
    CHECK_V3_BITS(k, 1.0f, 0.0f, 0.0f);
    dh_mat4_roty_f32(-90.0f, &T);
    DHT_EQ_INT(dh_mat4_to_axis_angle_f32(&T, &k, &th), DH_OK);
    DHT_EQ_F32_BITS(th, 90.0f);
    CHECK_V3_BITS(k, 0.0f, -1.0f, 0.0f);
    /* 180 exactly: axis up to sign, largest-diagonal component positive */
    dh_mat4_rotz_f32(180.0f, &T);
    DHT_EQ_INT(dh_mat4_to_axis_angle_f32(&T, &k, &th), DH_OK);
    DHT_EQ_F32_BITS(th, 180.0f);
    CHECK_V3_BITS(k, 0.0f, 0.0f, 1.0f);
    dh_mat4_rotx_f32(-180.0f, &T);
    DHT_EQ_INT(dh_mat4_to_axis_angle_f32(&T, &k, &th), DH_OK);
    DHT_EQ_F32_BITS(th, 180.0f);
    CHECK_V3_BITS(k, 1.0f, 0.0f, 0.0f);
    /* errors: k and theta untouched */
    k = v3(9, 9, 9);
    th = 99.0f;
    dh_mat4_scale_f32(1, 1, 1.01f, &T);
    DHT_EQ_INT(dh_mat4_to_axis_angle_f32(&T, &k, &th), DH_ERR_NOT_RIGID);
    dh_mat4_scale_f32(-1, 1, 1, &T);         /* reflection */
    DHT_EQ_INT(dh_mat4_to_axis_angle_f32(&T, &k, &th), DH_ERR_NOT_RIGID);
    dh_mat4_identity_f32(&T);
    DH_M4(&T, 1, 2) = NAN;
    DHT_EQ_INT(dh_mat4_to_axis_angle_f32(&T, &k, &th), DH_ERR_NAN);
    DH_M4(&T, 1, 2) = INFINITY;
    DHT_EQ_INT(dh_mat4_to_axis_angle_f32(&T, &k, &th), DH_ERR_NAN);
    CHECK_V3_BITS(k, 9.0f, 9.0f, 9.0f);
    DHT_EQ_F32_BITS(th, 99.0f);
    /* only the rotation part is read: p and the bottom row are ignored */
    dh_mat4_rotz_f32(90.0f, &T);
    DH_M4(&T, 3, 0) = NAN;
    DH_M4(&T, 0, 3) = 1e30f;
    DHT_EQ_INT(dh_mat4_to_axis_angle_f32(&T, &k, &th), DH_OK);
    DHT_EQ_F32_BITS(th, 90.0f);
    CHECK_V3_BITS(k, 0.0f, 0.0f, 1.0f);
}

static void isfinite_all_positions(void)
{
    dh_mat4_f32 T;
    int i, j;
    dh_mat4_identity_f32(&T);
    DHT_EQ_INT(dh_mat4_check_finite_f32(&T), DH_OK);
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            dh_mat4_identity_f32(&T);
            DH_M4(&T, i, j) = ((i + j) & 1) ? NAN : -INFINITY;
            DHT_EQ_INT(dh_mat4_check_finite_f32(&T), DH_ERR_NAN);
            DHT_TRUE(dh_mat4_inv_f32(&T, &T) == DH_ERR_NAN);
        }
}

static const dht_case cases[] = {
    DHT_CASE(seed_eq_1_27_translation),
    DHT_CASE(seed_eq_1_28_scaled_homogeneous),
    DHT_CASE(seed_eq_1_29_1_31_plane),
    DHT_CASE(seed_eq_1_35_1_36_rotations),
    DHT_CASE(seed_eq_1_40_1_42_composition),
    DHT_CASE(seed_eq_1_43_1_45_noncommutative),
    DHT_CASE(seed_eq_1_46_1_48_translation_and_frame),
    DHT_CASE(seed_eq_1_50_1_51_pre_post),
    DHT_CASE(seed_eq_1_52_1_53_object),
    DHT_CASE(seed_eq_1_54_1_55_inverse),
    DHT_CASE(seed_example_1_1_axis_angle),
    DHT_CASE(seed_eq_1_113_scale),
    DHT_CASE(seed_eq_1_127_perspective),
    DHT_CASE(rotations_whole_quadrants_exact),
    DHT_CASE(constructor_errors),
    DHT_CASE(frame_from_noap_and_rot_access),
    DHT_CASE(point_h_errors),
    DHT_CASE(plane_errors),
    DHT_CASE(inverse_errors_and_rigidity),
    DHT_CASE(axis_angle_special_cases),
    DHT_CASE(isfinite_all_positions),
};
DHT_MAIN(cases)
