/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_mat4.c - float 4x4 homogeneous transforms: constructors, accessors,
 * products and application to points, directions and planes (Paul 1981,
 * chapter 1).
 *
 * Storage is column-major (m[col][row]); see dh_common.h. Every sum is
 * evaluated left to right (k = 0, 1, 2, 3), so the fast paths and the
 * general loops give the same bits (NaN payloads aside) on every target.
 * "x + 0.0f" maps -0 to +0 and changes nothing else.
 */
#include <float.h>
#include <math.h>

#include "dhmath/mat4.h"
#include "dhmath/trig.h"
#include "../internal/dh_floatops.h"
#include "../internal/dh_mathf.h"

static void mat4_set_identity(dh_mat4_f32 *T)
{
    int c, r;
    for (c = 0; c < 4; c++) {
        for (r = 0; r < 4; r++) T->m[c][r] = 0.0f;
        T->m[c][c] = 1.0f;
    }
}

/* ---------------------------------------------------------------------- */
/* constructors                                                           */
/* ---------------------------------------------------------------------- */

void dh_mat4_identity_f32(dh_mat4_f32 *T)
{
    DH_ASSERT(T != NULL);
    mat4_set_identity(T);
}

/* o = (a, b, c, d): a 4-float struct as an array */
DH_INLINE void mat4_load4(float *o, float a, float b, float c, float d)
{
    o[0] = a;
    o[1] = b;
    o[2] = c;
    o[3] = d;
}

/* The identity with (x, y, z) in column 3 (col 3) or on the diagonal (col -1). */
static void mat4_identity_xyz(dh_mat4_f32 *T, float x, float y, float z, int col)
{
    DH_ASSERT(T != NULL);
    mat4_set_identity(T);
    T->m[(col < 0) ? 0 : col][0] = x;
    T->m[(col < 0) ? 1 : col][1] = y;
    T->m[(col < 0) ? 2 : col][2] = z;
}

void dh_mat4_trans_f32(float x, float y, float z, dh_mat4_f32 *T)
{
    mat4_identity_xyz(T, x, y, z, 3);
}

/*
 * Rot(x|y|z, deg) is Rot(k, deg) about the coordinate axis k: the
 * normalisation of a unit axis is exact and every product with its zero
 * components is +-0, which the "+ 0.0f" of dh_mat4_rot_axis_f32 maps to +0.
 * Twin bodies: the default build writes the matrix of a finite deg
 * directly (the rotation in the plane (i, j) = (axis + 1, axis + 2) mod 3;
 * 0 - s is never -0), the size-first build always goes through
 * dh_mat4_rot_axis_f32.
 */
#if DH_FAST_PATHS
static dh_status mat4_rotk(dh_mat4_f32 *T, float deg, int axis)
{
    float k[3] = {0.0f, 0.0f, 0.0f};
    if (dh_isfinite_f32(deg)) {
        const int i = (axis == 2) ? 0 : axis + 1, j = (i == 2) ? 0 : i + 1;
        float s, c;
        DH_ASSERT(T != NULL);
        (void)dh_sincos_f32(deg, &s, &c);
        s += 0.0f;
        c += 0.0f;
        mat4_set_identity(T);
        T->m[i][i] = c;
        T->m[i][j] = s;
        T->m[j][i] = 0.0f - s;
        T->m[j][j] = c;
        return DH_OK;
    }
    k[axis] = 1.0f;
    return dh_mat4_rot_axis_f32(k[0], k[1], k[2], deg, T);
}
#else
static dh_status mat4_rotk(dh_mat4_f32 *T, float deg, int axis)
{
    float k[3] = {0.0f, 0.0f, 0.0f};
    k[axis] = 1.0f;
    return dh_mat4_rot_axis_f32(k[0], k[1], k[2], deg, T);
}
#endif

dh_status dh_mat4_rotx_f32(float deg, dh_mat4_f32 *T)
{
    return mat4_rotk(T, deg, 0);
}

dh_status dh_mat4_roty_f32(float deg, dh_mat4_f32 *T)
{
    return mat4_rotk(T, deg, 1);
}

dh_status dh_mat4_rotz_f32(float deg, dh_mat4_f32 *T)
{
    return mat4_rotk(T, deg, 2);
}

/*
 * Diagonal entry k_i^2 vers + cos of Paul 1981 eq. 1.70 for a unit axis.
 * When k_i^2 is large the equivalent 1 - (k_j^2 + k_l^2) vers is used: more
 * accurate there and exactly 1 on a coordinate axis.
 */
static float mat4_rot_diag(float ki2, float others2, float v, float c)
{
    return (ki2 >= 0.5f) ? 1.0f - others2 * v : ki2 * v + c;
}

/* eq. 1.70 for any input: the classification (DH_ERR_NAN,
 * DH_ERR_ZERO_AXIS) and the general loop over the three axes */
static dh_status mat4_rot_axis_general(float kx, float ky, float kz, float deg, dh_mat4_f32 *T)
{
    float k[4], m = 0.0f, len = 0.0f, s, c, v, z = 0.0f, x, y, w, p0;
    int i, j, a, b, t;
    k[0] = kx;
    k[1] = ky;
    k[2] = kz;
    k[3] = deg;
    /* z is NaN iff one of them is NaN or Inf; m the largest |k_i| */
    for (i = 0; i < 4; i++) {
        z += k[i] * 0.0f;
        if (i < 3 && fabsf(k[i]) > m) m = fabsf(k[i]);
    }
    if (!dh_feq_f32(z, z)) return DH_ERR_NAN;
    if (m < FLT_MIN) return DH_ERR_ZERO_AXIS;
    /* scaled by the largest component: no overflow, len in [1, sqrt 3] */
    for (i = 0; i < 3; i++) {
        k[i] /= m;
        len += k[i] * k[i];
    }
    len = dh_sqrtf_(len);
    (void)dh_sincos_f32(deg, &s, &c); /* DH_OK: deg is finite */
    s += 0.0f;
    c += 0.0f;
    v = 1.0f - c; /* vers */
    mat4_set_identity(T);
    /* eq. 1.70 by the axis j and the two others a, b in cyclic order: the
     * diagonal entry j, (column a, row b) = k_a k_b vers + k_j sin and
     * (column b, row a) = k_a k_b vers - k_j sin */
    x = k[0];
    y = k[1];
    w = k[2];
    for (i = 0, j = 0, a = 1, b = 2; i < 3; i++) {
        const float uj = x / len, ua = y / len, ub = w / len; /* unit axis */
        const float p = ua * ub * v, q = uj * s;
        T->m[j][j] = mat4_rot_diag(uj * uj, ua * ua + ub * ub, v, c);
        T->m[a][b] = (p + q) + 0.0f;
        T->m[b][a] = (p - q) + 0.0f;
        t = j; /* (j, a, b) -> (a, b, j) */
        j = a;
        a = b;
        b = t;
        p0 = x;
        x = y;
        y = w;
        w = p0;
    }
    return DH_OK;
}


/* The default build writes eq. 1.70 out for a finite input with a non-zero
 * axis (the same operations) and leaves the rest to the general path; the
 * size-first build has the general path only. */
#if DH_FAST_PATHS
dh_status dh_mat4_rot_axis_f32(float kx, float ky, float kz, float deg, dh_mat4_f32 *T)
{
    float m, len, s, c, v, x, y, w;
    DH_ASSERT(T != NULL);
    m = fabsf(kx);
    if (fabsf(ky) > m) m = fabsf(ky);
    if (fabsf(kz) > m) m = fabsf(kz);
    if (dh_isfinite_f32(kx) && dh_isfinite_f32(ky) && dh_isfinite_f32(kz) &&
        dh_isfinite_f32(deg) && m >= FLT_MIN) {
        float x2, y2, z2, xyv, xzv, yzv;
        x = kx / m;
        y = ky / m;
        w = kz / m;
        len = dh_sqrtf_(x * x + y * y + w * w);
        x /= len;
        y /= len;
        w /= len;
        (void)dh_sincos_f32(deg, &s, &c);
        s += 0.0f;
        c += 0.0f;
        v = 1.0f - c;
        x2 = x * x;
        y2 = y * y;
        z2 = w * w;
        xyv = x * y * v;
        xzv = x * w * v;
        yzv = y * w * v;
        T->m[0][0] = mat4_rot_diag(x2, y2 + z2, v, c);
        T->m[0][1] = (xyv + w * s) + 0.0f;
        T->m[0][2] = (xzv - y * s) + 0.0f;
        T->m[0][3] = 0.0f;
        T->m[1][0] = (xyv - w * s) + 0.0f;
        T->m[1][1] = mat4_rot_diag(y2, x2 + z2, v, c);
        T->m[1][2] = (yzv + x * s) + 0.0f;
        T->m[1][3] = 0.0f;
        T->m[2][0] = (xzv + y * s) + 0.0f;
        T->m[2][1] = (yzv - x * s) + 0.0f;
        T->m[2][2] = mat4_rot_diag(z2, x2 + y2, v, c);
        T->m[2][3] = 0.0f;
        T->m[3][0] = 0.0f;
        T->m[3][1] = 0.0f;
        T->m[3][2] = 0.0f;
        T->m[3][3] = 1.0f;
        return DH_OK;
    }
    return mat4_rot_axis_general(kx, ky, kz, deg, T);
}
#else
dh_status dh_mat4_rot_axis_f32(float kx, float ky, float kz, float deg, dh_mat4_f32 *T)
{
    DH_ASSERT(T != NULL);
    return mat4_rot_axis_general(kx, ky, kz, deg, T);
}
#endif

void dh_mat4_scale_f32(float sx, float sy, float sz, dh_mat4_f32 *T)
{
    mat4_identity_xyz(T, sx, sy, sz, -1);
}

/* f = +-0 gives r = -+Inf, so the finiteness test of r is also f == 0 */
dh_status dh_mat4_persp_f32(int axis, float f, dh_mat4_f32 *T)
{
    float r;
    DH_ASSERT(T != NULL);
    if (axis < 0 || axis > 2) return DH_ERR_ARG;
    if (!dh_isfinite_f32(f)) return DH_ERR_NAN;
    r = -1.0f / f;
    if (!dh_isfinite_f32(r)) return DH_ERR_DOMAIN;
    mat4_set_identity(T);
    T->m[axis][3] = r; /* bottom row, column of the axis (eq. 1.127) */
    return DH_OK;
}

void dh_mat4_from_noap_f32(const dh_vec3_f32 *n, const dh_vec3_f32 *o, const dh_vec3_f32 *a,
                           const dh_vec3_f32 *p, dh_mat4_f32 *T)
{
    DH_ASSERT(T != NULL && n != NULL && o != NULL && a != NULL && p != NULL);
    {
        /* read everything first: the vectors may live inside T */
        const dh_vec3_f32 nn = *n, oo = *o, aa = *a, pp = *p;
        T->m[0][0] = nn.x; T->m[0][1] = nn.y; T->m[0][2] = nn.z; T->m[0][3] = 0.0f;
        T->m[1][0] = oo.x; T->m[1][1] = oo.y; T->m[1][2] = oo.z; T->m[1][3] = 0.0f;
        T->m[2][0] = aa.x; T->m[2][1] = aa.y; T->m[2][2] = aa.z; T->m[2][3] = 0.0f;
        T->m[3][0] = pp.x; T->m[3][1] = pp.y; T->m[3][2] = pp.z; T->m[3][3] = 1.0f;
    }
}

/* ---------------------------------------------------------------------- */
/* accessors                                                              */
/* ---------------------------------------------------------------------- */

static dh_vec3_f32 mat4_col3(const dh_mat4_f32 *T, int c)
{
    dh_vec3_f32 v;
    DH_ASSERT(T != NULL);
    v.x = T->m[c][0];
    v.y = T->m[c][1];
    v.z = T->m[c][2];
    return v;
}

dh_vec3_f32 dh_mat4_n_f32(const dh_mat4_f32 *T) { return mat4_col3(T, 0); }
dh_vec3_f32 dh_mat4_o_f32(const dh_mat4_f32 *T) { return mat4_col3(T, 1); }
dh_vec3_f32 dh_mat4_a_f32(const dh_mat4_f32 *T) { return mat4_col3(T, 2); }
dh_vec3_f32 dh_mat4_p_f32(const dh_mat4_f32 *T) { return mat4_col3(T, 3); }

void dh_mat4_get_rot_f32(const dh_mat4_f32 *T, dh_mat3_f32 *R)
{
    int c, r;
    DH_ASSERT(T != NULL && R != NULL);
    for (c = 0; c < 3; c++) {
        for (r = 0; r < 3; r++) R->m[c][r] = T->m[c][r];
    }
}

void dh_mat4_set_rot_f32(dh_mat4_f32 *T, const dh_mat3_f32 *R)
{
    int c, r;
    DH_ASSERT(T != NULL && R != NULL);
    for (c = 0; c < 3; c++) {
        for (r = 0; r < 3; r++) T->m[c][r] = R->m[c][r];
    }
}

/* ---------------------------------------------------------------------- */
/* composition                                                            */
/* ---------------------------------------------------------------------- */

/*
 * o[r] = A_r0 in[0] + ... + A_r(n-1) in[n-1] for the rows r < 4: column c
 * of a product (in = column c of B), a point (in = u, 1: the + p is p * 1,
 * exact), a direction (n = 3), a homogeneous point; n is 3 or 4. The four
 * sums are kept in registers, one column of A per step; each still runs
 * k = 0, 1, ... .
 */
static void mat4_lin(const dh_mat4_f32 *A, const float *in, float *o, int n)
{
    float x = in[0];
    float o0 = A->m[0][0] * x, o1 = A->m[0][1] * x, o2 = A->m[0][2] * x, o3 = A->m[0][3] * x;
    const int nk = (n < 4) ? n : 4; /* in[] has at most 4 entries */
    int k = 1;
    do { /* nk >= 2: a bottom-tested loop */
        const float *c = A->m[k];
        x = in[k];
        o0 += c[0] * x;
        o1 += c[1] * x;
        o2 += c[2] * x;
        o3 += c[3] * x;
    } while (++k < nk);
    o[0] = o0;
    o[1] = o1;
    o[2] = o2;
    o[3] = o3;
}

#if !DH_FAST_PATHS
/* mat4_lin() of in = (x, y, z, 1): a point (n = 4; its p * 1 is p, exact) or
 * a direction (n = 3) */
static void mat4_lin3(const dh_mat4_f32 *A, float x, float y, float z, float *o, int n)
{
    float in[4];
    in[0] = x;
    in[1] = y;
    in[2] = z;
    in[3] = 1.0f;
    mat4_lin(A, in, o, n);
}
#endif

/*
 * out = A B (aff == 0), or the affine product (aff == 1, a constant of each
 * caller): columns 0..2 of R_A R_B, column 3 R_A p_B + p_A (the fourth term
 * of a point), bottom row 0 0 0 1; the bottom rows of A and B are not used.
 * out may alias A and/or B. Three whole bodies, chosen by the build:
 *  - size-first build: the general loops (mat4_lin) into a temporary;
 *  - default build, 4-wide SIMD hosts and soft float: the copy form,
 *    unrolled products from a local copy of A (vectorised; with soft float
 *    the register form saves 2 % of the instructions for about 1 KiB of
 *    flash on Cortex-M0+);
 *  - default build, scalar FPUs (Cortex-M4F/M7): the register form.
 * Every form computes the same sums in the same order.
 */
#if !DH_FAST_PATHS
DH_SPEED_INLINE void mat4_mul(const dh_mat4_f32 *A, const dh_mat4_f32 *B, dh_mat4_f32 *out, int aff)
{
    dh_mat4_f32 t;
    int i;
    DH_ASSERT(out != NULL && A != NULL && B != NULL);
    /* the columns of R_A R_B (aff) or of A B: B's columns read before out
     * is written */
    for (i = 0; i < 4 - aff; i++) mat4_lin(A, B->m[i], &t.m[i][0], 4 - aff);
    if (aff) {
        /* column 3: R_A p_B + p_A, A applied to the point p_B */
        mat4_lin3(A, B->m[3][0], B->m[3][1], B->m[3][2], t.m[3], 4);
        t.m[0][3] = 0.0f;
        t.m[1][3] = 0.0f;
        t.m[2][3] = 0.0f;
        t.m[3][3] = 1.0f;
    }
    *out = t;
}
#elif defined(__SSE__) || defined(__ARM_NEON) || defined(__ARM_NEON__) || defined(__ALTIVEC__) || DH_SOFT_FLOAT
/* Rows the affine product computes before its bottom row is set to 0 0 0 1:
 * four where 4-wide SIMD makes a column one vector operation, the three
 * needed ones with soft float. */
#if defined(__SSE__) || defined(__ARM_NEON) || defined(__ARM_NEON__) || defined(__ALTIVEC__)
#define DH_AFFINE_ROWS 4
#else
#define DH_AFFINE_ROWS 3
#endif

/* o = rows 0..3 (full) of the combination of the columns of a with the
 * weights b[0..3] (b read before o is written); one vector multiply-add
 * chain on 4-wide float SIMD (SSE2, NEON), scalar code with soft float */
DH_INLINE void mat4_col4_copy(const dh_mat4_f32 *a, const float *b, float *o)
{
    const float x = b[0], y = b[1], z = b[2], w = b[3];
    int r;
    for (r = 0; r < 4; r++) o[r] = a->m[0][r] * x + a->m[1][r] * y + a->m[2][r] * z + a->m[3][r] * w;
}

/* the same with the three weights b[0..2] on the first DH_AFFINE_ROWS rows,
 * plus column 3 of a (pt 1: a point) or not (pt 0) */
DH_INLINE void mat4_col3_copy(const dh_mat4_f32 *a, const float *b, float *o, int pt)
{
    const float x = b[0], y = b[1], z = b[2];
    int r;
    if (pt) {
        for (r = 0; r < DH_AFFINE_ROWS; r++) o[r] = a->m[0][r] * x + a->m[1][r] * y + a->m[2][r] * z + a->m[3][r];
    } else {
        for (r = 0; r < DH_AFFINE_ROWS; r++) o[r] = a->m[0][r] * x + a->m[1][r] * y + a->m[2][r] * z;
    }
}

/* The copy form: column c of A*B is the combination of the columns of A
 * (copied to a local first) with the weights of column c of B, read before
 * column c of out is written. */
DH_SPEED_INLINE void mat4_mul(const dh_mat4_f32 *A, const dh_mat4_f32 *B, dh_mat4_f32 *out, int aff)
{
    dh_mat4_f32 a;
    DH_ASSERT(out != NULL && A != NULL && B != NULL);
    a = *A;
    if (!aff) {
        mat4_col4_copy(&a, B->m[0], out->m[0]);
        mat4_col4_copy(&a, B->m[1], out->m[1]);
        mat4_col4_copy(&a, B->m[2], out->m[2]);
        mat4_col4_copy(&a, B->m[3], out->m[3]);
        return;
    }
    mat4_col3_copy(&a, B->m[0], out->m[0], 0);
    mat4_col3_copy(&a, B->m[1], out->m[1], 0);
    mat4_col3_copy(&a, B->m[2], out->m[2], 0);
    mat4_col3_copy(&a, B->m[3], out->m[3], 1);
    out->m[0][3] = 0.0f;
    out->m[1][3] = 0.0f;
    out->m[2][3] = 0.0f;
    out->m[3][3] = 1.0f;
}
#else
/* o = rows 0..3 of a_r0 x + a_r1 y + a_r2 z + a_r3 w for the weights
 * b[0..3] (read before o is written) and the 16 elements a_rk of A held by
 * the caller */
DH_INLINE void mat4_col4_regs(const float *b, float *o, float a00, float a01, float a02, float a03,
                              float a10, float a11, float a12, float a13, float a20, float a21,
                              float a22, float a23, float a30, float a31, float a32, float a33)
{
    const float x = b[0], y = b[1], z = b[2], w = b[3];
    o[0] = a00 * x + a01 * y + a02 * z + a03 * w;
    o[1] = a10 * x + a11 * y + a12 * z + a13 * w;
    o[2] = a20 * x + a21 * y + a22 * z + a23 * w;
    o[3] = a30 * x + a31 * y + a32 * z + a33 * w;
}

/* rows 0..2 of a_r0 x + a_r1 y + a_r2 z (+ a_r3 when pt, a point) for the
 * weights b[0..2] */
DH_INLINE void mat4_col3_regs(const float *b, float *o, int pt, float a00, float a01, float a02,
                              float a03, float a10, float a11, float a12, float a13, float a20,
                              float a21, float a22, float a23)
{
    const float x = b[0], y = b[1], z = b[2];
    if (pt) {
        o[0] = a00 * x + a01 * y + a02 * z + a03;
        o[1] = a10 * x + a11 * y + a12 * z + a13;
        o[2] = a20 * x + a21 * y + a22 * z + a23;
    } else {
        o[0] = a00 * x + a01 * y + a02 * z;
        o[1] = a10 * x + a11 * y + a12 * z;
        o[2] = a20 * x + a21 * y + a22 * z;
    }
}

/* The register form: every element of A that the product uses is read
 * into a local first (out may alias A), then column c of out is computed
 * from column c of B, read before column c of out is written (out may
 * alias B). Straight-line code with no copy through memory: the locals are
 * registers (the 16 of the full product, the weights and the sums fit the
 * 32 single registers of FPv4/FPv5). */
DH_SPEED_INLINE void mat4_mul(const dh_mat4_f32 *A, const dh_mat4_f32 *B, dh_mat4_f32 *out, int aff)
{
    const float a00 = A->m[0][0], a10 = A->m[0][1], a20 = A->m[0][2];
    const float a01 = A->m[1][0], a11 = A->m[1][1], a21 = A->m[1][2];
    const float a02 = A->m[2][0], a12 = A->m[2][1], a22 = A->m[2][2];
    const float a03 = A->m[3][0], a13 = A->m[3][1], a23 = A->m[3][2];
    DH_ASSERT(out != NULL && A != NULL && B != NULL);
    if (!aff) {
        const float a30 = A->m[0][3], a31 = A->m[1][3], a32 = A->m[2][3], a33 = A->m[3][3];
        mat4_col4_regs(B->m[0], out->m[0], a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, a30, a31, a32, a33);
        mat4_col4_regs(B->m[1], out->m[1], a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, a30, a31, a32, a33);
        mat4_col4_regs(B->m[2], out->m[2], a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, a30, a31, a32, a33);
        mat4_col4_regs(B->m[3], out->m[3], a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, a30, a31, a32, a33);
        return;
    }
    mat4_col3_regs(B->m[0], out->m[0], 0, a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23);
    mat4_col3_regs(B->m[1], out->m[1], 0, a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23);
    mat4_col3_regs(B->m[2], out->m[2], 0, a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23);
    mat4_col3_regs(B->m[3], out->m[3], 1, a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23);
    out->m[0][3] = 0.0f;
    out->m[1][3] = 0.0f;
    out->m[2][3] = 0.0f;
    out->m[3][3] = 1.0f;
}
#endif

void dh_mat4_mul_f32(const dh_mat4_f32 *A, const dh_mat4_f32 *B, dh_mat4_f32 *out)
{
    mat4_mul(A, B, out, 0);
}

void dh_mat4_mul_affine_f32(const dh_mat4_f32 *A, const dh_mat4_f32 *B, dh_mat4_f32 *out)
{
    mat4_mul(A, B, out, 1);
}

void dh_mat4_premul_f32(dh_mat4_f32 *T, const dh_mat4_f32 *X)
{
    dh_mat4_mul_f32(X, T, T);
}

void dh_mat4_postmul_f32(dh_mat4_f32 *T, const dh_mat4_f32 *X)
{
    dh_mat4_mul_f32(T, X, T);
}

/* ---------------------------------------------------------------------- */
/* application                                                            */
/* ---------------------------------------------------------------------- */

/* v = rows 0..2 of the n-term combination of the columns of T with u, 1
 * (n = 4: a point, n = 3: a direction; u, v may be the same object: u is
 * read first). Twin bodies: R u (+ p) written out in the default build,
 * ((a + b) + c) + d being the general path's order, and mat4_lin3 in the
 * size-first build. */
#if DH_FAST_PATHS
DH_SPEED_INLINE void mat4_apply3(const dh_mat4_f32 *T, const dh_vec3_f32 *u, dh_vec3_f32 *v, int n)
{
    float x, y, z, rx, ry, rz;
    DH_ASSERT(T != NULL && u != NULL && v != NULL);
    x = u->x;
    y = u->y;
    z = u->z;
    rx = T->m[0][0] * x + T->m[1][0] * y + T->m[2][0] * z;
    ry = T->m[0][1] * x + T->m[1][1] * y + T->m[2][1] * z;
    rz = T->m[0][2] * x + T->m[1][2] * y + T->m[2][2] * z;
    if (n == 4) {
        rx += T->m[3][0];
        ry += T->m[3][1];
        rz += T->m[3][2];
    }
    v->x = rx;
    v->y = ry;
    v->z = rz;
}
#else
DH_SPEED_INLINE void mat4_apply3(const dh_mat4_f32 *T, const dh_vec3_f32 *u, dh_vec3_f32 *v, int n)
{
    float o[4];
    DH_ASSERT(T != NULL && u != NULL && v != NULL);
    mat4_lin3(T, u->x, u->y, u->z, o, n);
    v->x = o[0];
    v->y = o[1];
    v->z = o[2];
}
#endif

void dh_mat4_apply_point_f32(const dh_mat4_f32 *T, const dh_vec3_f32 *u, dh_vec3_f32 *v)
{
    mat4_apply3(T, u, v, 4);
}

void dh_mat4_apply_dir_f32(const dh_mat4_f32 *T, const dh_vec3_f32 *u, dh_vec3_f32 *v)
{
    mat4_apply3(T, u, v, 3);
}

#if DH_FAST_PATHS
/* row r of T (x y z w)^T written out (the general path's order) */
DH_INLINE float mat4_row4(const dh_mat4_f32 *T, int r, float x, float y, float z, float w)
{
    return T->m[0][r] * x + T->m[1][r] * y + T->m[2][r] * z + T->m[3][r] * w;
}

/* Twin bodies: the rows written out (default build) or mat4_lin (size-first
 * build); u is read first, so u and v may be the same object. */
void dh_mat4_apply_vec4_f32(const dh_mat4_f32 *T, const dh_vec4_f32 *u, dh_vec4_f32 *v)
{
    float in[4];
    DH_ASSERT(T != NULL && u != NULL && v != NULL);
    in[0] = u->x;
    in[1] = u->y;
    in[2] = u->z;
    in[3] = u->w;
    v->x = mat4_row4(T, 0, in[0], in[1], in[2], in[3]);
    v->y = mat4_row4(T, 1, in[0], in[1], in[2], in[3]);
    v->z = mat4_row4(T, 2, in[0], in[1], in[2], in[3]);
    v->w = mat4_row4(T, 3, in[0], in[1], in[2], in[3]);
}
#else
void dh_mat4_apply_vec4_f32(const dh_mat4_f32 *T, const dh_vec4_f32 *u, dh_vec4_f32 *v)
{
    float in[4], o[4];
    DH_ASSERT(T != NULL && u != NULL && v != NULL);
    in[0] = u->x;
    in[1] = u->y;
    in[2] = u->z;
    in[3] = u->w;
    mat4_lin(T, in, o, 4);
    v->x = o[0];
    v->y = o[1];
    v->z = o[2];
    v->w = o[3];
}
#endif

/* 1 when every entry of T is finite, else 0: x * 0 is +-0 for finite x
 * and NaN for NaN and +-Inf; a sum of +-0 is never NaN. The general path
 * of dh_mat4_apply_point_h_f32 tests this directly, so a firmware that
 * does not call dh_mat4_check_finite_f32 does not link its status form. */
static DH_NOINLINE int mat4_all_finite(const dh_mat4_f32 *T)
{
    float z = 0.0f;
    int c, r;
    for (c = 0; c < 4; c++) {
        for (r = 0; r < 4; r++) z += T->m[c][r] * 0.0f;
    }
    return dh_feq_f32(z, z);
}

dh_status dh_mat4_check_finite_f32(const dh_mat4_f32 *T)
{
    DH_ASSERT(T != NULL);
    return mat4_all_finite(T) ? DH_OK : DH_ERR_NAN;
}

/* The general path for in = u: h = T in (h: the caller's scratch),
 * classified (DH_ERR_OVERFLOW, DH_ERR_NAN, DH_ERR_DOMAIN) and divided.
 * The default build answers a finite h with w != 0 and finite quotients
 * before it; the size-first build is this path alone (inlined: a separate
 * call there costs flash). */
DH_INLINE dh_status mat4_point_h_general(const dh_mat4_f32 *T, const float *in, float *h, dh_vec3_f32 *v)
{
    float z = 0.0f, zi = 0.0f, w;
    int i;
    mat4_lin(T, in, h, 4);
    for (i = 0; i < 4; i++) {
        z += h[i] * 0.0f;
        zi += in[i] * 0.0f;
    }
    if (!dh_feq_f32(z, z)) return (mat4_all_finite(T) && dh_feq_f32(zi, zi)) ? DH_ERR_OVERFLOW : DH_ERR_NAN;
    if (dh_feq_f32(h[3], 0.0f)) return DH_ERR_DOMAIN;
    w = h[3]; /* in a local: through the pointer h, each store h[i] would reload it */
    for (i = 0; i < 3; i++) {
        h[i] = h[i] / w + 0.0f;
        z += h[i] * 0.0f;
    }
    if (!dh_feq_f32(z, z)) return DH_ERR_OVERFLOW;
    v->x = h[0];
    v->y = h[1];
    v->z = h[2];
    return DH_OK;
}

#if DH_FAST_PATHS
dh_status dh_mat4_apply_point_h_f32(const dh_mat4_f32 *T, const dh_vec4_f32 *u, dh_vec3_f32 *v)
{
    float in[4], h[4];
    DH_ASSERT(T != NULL && u != NULL && v != NULL);
    mat4_load4(in, u->x, u->y, u->z, u->w);
    h[0] = mat4_row4(T, 0, in[0], in[1], in[2], in[3]);
    h[1] = mat4_row4(T, 1, in[0], in[1], in[2], in[3]);
    h[2] = mat4_row4(T, 2, in[0], in[1], in[2], in[3]);
    h[3] = mat4_row4(T, 3, in[0], in[1], in[2], in[3]);
    if (dh_isfinite_f32(h[0]) && dh_isfinite_f32(h[1]) && dh_isfinite_f32(h[2]) &&
        dh_isfinite_f32(h[3]) && !dh_feq_f32(h[3], 0.0f)) {
        const float x = h[0] / h[3], y = h[1] / h[3], w = h[2] / h[3];
        if (dh_isfinite_f32(x) && dh_isfinite_f32(y) && dh_isfinite_f32(w)) {
            v->x = x + 0.0f;
            v->y = y + 0.0f;
            v->z = w + 0.0f;
            return DH_OK;
        }
    }
    return mat4_point_h_general(T, in, h, v);
}
#else
dh_status dh_mat4_apply_point_h_f32(const dh_mat4_f32 *T, const dh_vec4_f32 *u, dh_vec3_f32 *v)
{
    float in[4], h[4];
    DH_ASSERT(T != NULL && u != NULL && v != NULL);
    mat4_load4(in, u->x, u->y, u->z, u->w);
    return mat4_point_h_general(T, in, h, v);
}
#endif

/* Q_j = P . (column j of Tinv). Twin bodies: written out (default build)
 * or loops (size-first build), the same sums in the same order. */
#if DH_FAST_PATHS
void dh_plane_mul_f32(const dh_plane_f32 *P, const dh_mat4_f32 *Tinv, dh_plane_f32 *Q)
{
    float p[4];
    DH_ASSERT(P != NULL && Tinv != NULL && Q != NULL);
    mat4_load4(p, P->a, P->b, P->c, P->d);
    Q->a = p[0] * Tinv->m[0][0] + p[1] * Tinv->m[0][1] + p[2] * Tinv->m[0][2] + p[3] * Tinv->m[0][3];
    Q->b = p[0] * Tinv->m[1][0] + p[1] * Tinv->m[1][1] + p[2] * Tinv->m[1][2] + p[3] * Tinv->m[1][3];
    Q->c = p[0] * Tinv->m[2][0] + p[1] * Tinv->m[2][1] + p[2] * Tinv->m[2][2] + p[3] * Tinv->m[2][3];
    Q->d = p[0] * Tinv->m[3][0] + p[1] * Tinv->m[3][1] + p[2] * Tinv->m[3][2] + p[3] * Tinv->m[3][3];
}
#else
void dh_plane_mul_f32(const dh_plane_f32 *P, const dh_mat4_f32 *Tinv, dh_plane_f32 *Q)
{
    float p[4], q[4];
    int j, k;
    DH_ASSERT(P != NULL && Tinv != NULL && Q != NULL);
    mat4_load4(p, P->a, P->b, P->c, P->d);
    for (j = 0; j < 4; j++) {
        float acc = p[0] * Tinv->m[j][0];
        for (k = 1; k < 4; k++) acc += p[k] * Tinv->m[j][k];
        q[j] = acc;
    }
    Q->a = q[0];
    Q->b = q[1];
    Q->c = q[2];
    Q->d = q[3];
}
#endif

void dh_mat4_apply_points_f32(const dh_mat4_f32 *T, const dh_vec3_f32 *u, dh_vec3_f32 *v, size_t count)
{
    size_t i;
    float r00, r10, r20, r01, r11, r21, r02, r12, r22, p0, p1, p2;
    DH_ASSERT(T != NULL);
    if (count == 0) return;
    DH_ASSERT(u != NULL && v != NULL);
    /* hoist T: element i of v is written after element i of u is read, so
     * in-place use (u == v) is safe */
    r00 = T->m[0][0]; r10 = T->m[0][1]; r20 = T->m[0][2];
    r01 = T->m[1][0]; r11 = T->m[1][1]; r21 = T->m[1][2];
    r02 = T->m[2][0]; r12 = T->m[2][1]; r22 = T->m[2][2];
    p0 = T->m[3][0]; p1 = T->m[3][1]; p2 = T->m[3][2];
    for (i = 0; i < count; i++) {
        const float x = u[i].x, y = u[i].y, z = u[i].z;
        v[i].x = r00 * x + r01 * y + r02 * z + p0;
        v[i].y = r10 * x + r11 * y + r12 * z + p1;
        v[i].z = r20 * x + r21 * y + r22 * z + p2;
    }
}
