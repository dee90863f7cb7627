/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_rotvec.c - angle-axis <-> rotation matrix, rotation vector (log / exp
 * maps), skew-symmetric matrices and vee, angular velocity from R and
 * Rdot, the rotation check and re-orthonormalisation of a 3x3 rotation.
 *
 * Math: Rodrigues' formula (Paul 1981 eq. 1.70; FloCal, "Angle Axis"),
 * S(w) = Rdot R^T (FloCal, "Angular Velocity"), polar decomposition by the
 * Newton-Schulz iteration.
 */
#include <float.h>
#include <math.h>

#include "dhmath/rot.h"
#include "dhmath/mat4.h"
#include "dhmath/trig.h"
#include "../internal/dh_mathf.h"
#include "../internal/dh_floatops.h"
#include "rot_impl.h"

static int dh_mat3_finite(const dh_mat3_f32 *R)
{
    int c, r;
    for (c = 0; c < 3; c++) {
        for (r = 0; r < 3; r++) {
            if (!dh_isfinite_f32(R->m[c][r])) return 0;
        }
    }
    return 1;
}

dh_status dh_mat3_check_rot_f32(const dh_mat3_f32 *R, float tol)
{
    DH_ASSERT(R != NULL);
    if (!dh_isfinite_f32(tol) || !(tol >= 0.0f)) return DH_ERR_ARG;
    if (!dh_mat3_finite(R)) return DH_ERR_NAN;
    return dh_rot_cols_ok_f32(R->m[0], R->m[1], R->m[2], tol) ? DH_OK : DH_ERR_NOT_RIGID;
}

/* R = c I + s [k]x + v k k^T, unit k, v = 1 - c: the diagonal avoids
 * cancellation (exact for a coordinate axis); + 0.0f: no -0 off it. */
static void dh_rodrigues(dh_mat3_f32 *R, const float k[3], float s, float c, float v)
{
    float kx = k[0], ky = k[1], kz = k[2];
    float xx = kx * kx, yy = ky * ky, zz = kz * kz;
    float vxy = v * kx * ky, vxz = v * kx * kz, vyz = v * ky * kz;
    float sx = s * kx, sy = s * ky, sz = s * kz;

    DH_M3(R, 0, 0) = (xx < 0.5f) ? c + v * xx : 1.0f - v * (yy + zz);
    DH_M3(R, 1, 1) = (yy < 0.5f) ? c + v * yy : 1.0f - v * (xx + zz);
    DH_M3(R, 2, 2) = (zz < 0.5f) ? c + v * zz : 1.0f - v * (xx + yy);
    dh_rot_offdiag_f32(R, vxy, vxz, vyz, sx, sy, sz);
}

dh_status dh_axis_angle_to_mat3_f32(const dh_vec3_f32 *axis, float deg, dh_mat3_f32 *R)
{
    float k[3], len, s, c;
    dh_status st;
    DH_ASSERT(R != NULL && axis != NULL);
    if (!dh_isfinite_f32(deg)) return DH_ERR_NAN;
    k[0] = axis->x;
    k[1] = axis->y;
    k[2] = axis->z;
    st = dh_axis_prescale_f32(k, &len);
    if (st != DH_OK) return st;
    st = dh_sincos_f32(deg, &s, &c);
    if (st != DH_OK) return st;
    k[0] /= len;
    k[1] /= len;
    k[2] /= len;
    dh_rodrigues(R, k, s, c, 1.0f - c);
    return DH_OK;
}

/* Checks R and copies it into T with zero translation (T untouched on
 * error); out of line: only the 4x4 stays in the caller's frame. */
static DH_NOINLINE dh_status dh_mat3_to_mat4_checked(dh_mat4_f32 *T, const dh_mat3_f32 *R)
{
    int c, r;
    if (!dh_mat3_finite(R)) return DH_ERR_NAN;
    if (dh_mat3_check_rot_f32(R, DH_ROT_TOL) != DH_OK) return DH_ERR_NOT_RIGID;
    for (c = 0; c < 3; c++) {
        for (r = 0; r < 3; r++) T->m[c][r] = R->m[c][r];
        T->m[c][3] = 0.0f;
        T->m[3][c] = 0.0f;
    }
    T->m[3][3] = 1.0f;
    return DH_OK;
}

dh_status dh_mat3_to_axis_angle_f32(const dh_mat3_f32 *R, dh_vec3_f32 *axis, float *deg)
{
    /* the 4x4 version's algorithm: bitwise the same answer */
    dh_mat4_f32 T;
    dh_status st;
    DH_ASSERT(R != NULL && axis != NULL && deg != NULL);
    st = dh_mat3_to_mat4_checked(&T, R);
    if (st != DH_OK) return st;
    return dh_mat4_to_axis_angle_f32(&T, axis, deg);
}

/* a * a = *h + *l exactly (Dekker's product; Veltkamp's split done on the
 * bits: the high part keeps 12 significant bits, so each partial product
 * has at most 24 and is exact, fused or not). Needs a * a normal: the low
 * part of a square below 2^-102 is lost to underflow. */
static void dh_square2(float a, float *h, float *l)
{
    const float ah = dh_f32_from_bits(dh_f32_bits(a) & 0xFFFFF000u);
    const float al = a - ah; /* exact: the 12 low bits */
    *h = a * a;
    *l = ((ah * ah - *h) + 2.0f * ah * al) + al * al;
}

/* a + b = *s + *e exactly (Knuth's TwoSum, any order of magnitudes) */
static void dh_sum2(float a, float b, float *s, float *e)
{
    const float t = a + b;
    const float bb = t - a;
    *s = t;
    *e = (a - (t - bb)) + (b - bb);
}

/* |(x, y, z)| as th + tl to about 2^-44 relative: the sum of squares as an
 * unevaluated float pair, the float square root th, and the correction
 * tl = (x^2 + y^2 + z^2 - th^2) / (2 th) from the exact residual (th^2 is
 * within 2 ulp of the sum, so s - ph is exact by Sterbenz's lemma). */
static DH_NOINLINE float dh_norm3_2(float x, float y, float z, float *tl)
{
    float h1, l1, h2, l2, h3, l3, s1, e1, s2, e2, th, ph, pl;
    dh_square2(x, &h1, &l1);
    dh_square2(y, &h2, &l2);
    dh_square2(z, &h3, &l3);
    dh_sum2(h1, h2, &s1, &e1);
    dh_sum2(s1, h3, &s2, &e2);
    th = dh_sqrt_f32(s2);
    dh_square2(th, &ph, &pl);
    *tl = (((s2 - ph) - pl) + ((l1 + l2 + l3) + (e1 + e2))) / (2.0f * th);
    return th;
}

dh_status dh_rotvec_to_mat3_f32(const dh_vec3_f32 *phi, dh_mat3_f32 *R)
{
    float x, y, z, m, t, tl, d, u, su, cu, k[3], sh, ch;
    int scaled;
    DH_ASSERT(R != NULL && phi != NULL);
    x = phi->x;
    y = phi->y;
    z = phi->z;
    if (!dh_isfinite_f32(x) || !dh_isfinite_f32(y) || !dh_isfinite_f32(z)) return DH_ERR_NAN;
    m = fabsf(x);
    if (fabsf(y) > m) m = fabsf(y);
    if (fabsf(z) > m) m = fabsf(z);
    if (dh_feq_f32(m, 0.0f)) {
        k[0] = 0.0f;
        k[1] = 0.0f;
        k[2] = 1.0f;
        dh_rodrigues(R, k, 0.0f, 1.0f, 0.0f); /* exactly I */
        return DH_OK;
    }
    /* within 2^-63 .. 2^63 the squares neither overflow nor underflow:
     * |phi| directly, else scaled by 1 / m */
    scaled = !(m >= 1.0842022e-19f && m <= 9.2233720e18f);
    if (scaled) {
        x /= m;
        y /= m;
        z /= m;
    }
    /* The angle t + tl is |phi| to about 2^-44 relative: the float |phi|
     * alone is off by up to 1.5 ulp (3.6e-7 rad just below pi), an error
     * that R inherits in full. k = phi / (t + tl), to first order. */
    t = dh_norm3_2(x, y, z, &tl);
    d = tl / t;
    k[0] = x / t;
    k[1] = y / t;
    k[2] = z / t;
    k[0] -= k[0] * d;
    k[1] -= k[1] * d;
    k[2] -= k[2] * d;
    if (scaled) {
        t *= m;
        tl *= m;
        if (!dh_isfinite_f32(t)) return DH_ERR_NAN;   /* |phi| > FLT_MAX */
    }
    dh_sincosf_(0.5f * t, &sh, &ch);     /* libm-free, exact reduction */
    /* (sh, ch) rotated on by u = tl / 2: to first order while u^2 / 2 is
     * below 2^-27 (|phi| up to about 2^11), else exactly (huge lengths,
     * where tl itself can be large) */
    u = 0.5f * tl;
    if (fabsf(u) <= 1.220703125e-4f) { /* 2^-13 */
        su = u;
        cu = 1.0f;
    } else {
        dh_sincosf_(u, &su, &cu);
    }
    d = sh;
    sh = sh * cu + ch * su;
    ch = ch * cu - d * su;
    dh_rodrigues(R, k, 2.0f * sh * ch, 1.0f - 2.0f * sh * sh, 2.0f * sh * sh);
    return DH_OK;
}

dh_status dh_mat3_to_rotvec_f32(const dh_mat3_f32 *R, dh_vec3_f32 *phi)
{
    dh_quat_f32 q;
    float n, f;
    dh_status st;
    DH_ASSERT(R != NULL && phi != NULL);
    st = dh_mat3_to_quat_f32(R, &q); /* checks R; w >= 0 */
    if (st != DH_OK) return st;
    n = dh_sqrt_f32(q.x * q.x + q.y * q.y + q.z * q.z);
    if (dh_feq_f32(n, 0.0f)) {
        phi->x = 0.0f;
        phi->y = 0.0f;
        phi->z = 0.0f;
        return DH_OK;
    }
    f = 2.0f * dh_atan2f_(n, q.w) / n; /* t / |v| = t / sin(t/2), in [2, pi] */
    phi->x = f * q.x;
    phi->y = f * q.y;
    phi->z = f * q.z;
    return DH_OK;
}

void dh_skew_f32(const dh_vec3_f32 *v, dh_mat3_f32 *S)
{
    float x, y, z;
    DH_ASSERT(S != NULL && v != NULL);
    x = v->x;
    y = v->y;
    z = v->z;
    DH_M3(S, 0, 0) = 0.0f;
    DH_M3(S, 1, 1) = 0.0f;
    DH_M3(S, 2, 2) = 0.0f;
    DH_M3(S, 0, 1) = -z;
    DH_M3(S, 1, 0) = z;
    DH_M3(S, 0, 2) = y;
    DH_M3(S, 2, 0) = -y;
    DH_M3(S, 1, 2) = -x;
    DH_M3(S, 2, 1) = x;
}

void dh_vee_f32(const dh_mat3_f32 *S, dh_vec3_f32 *v)
{
    DH_ASSERT(v != NULL && S != NULL);
    v->x = 0.5f * DH_M3(S, 2, 1) - 0.5f * DH_M3(S, 1, 2);
    v->y = 0.5f * DH_M3(S, 0, 2) - 0.5f * DH_M3(S, 2, 0);
    v->z = 0.5f * DH_M3(S, 1, 0) - 0.5f * DH_M3(S, 0, 1);
}

/* w = vee(Rdot R^T) (body == 0) or vee(R^T Rdot) (body == 1). */
static dh_status dh_angvel_common(dh_vec3_f32 *w, const dh_mat3_f32 *R, const dh_mat3_f32 *Rdot, int body)
{
    float W[3][3]; /* W[r][c], only off-diagonal entries used */
    int r, c;
    dh_status st;
    DH_ASSERT(w != NULL && R != NULL && Rdot != NULL);
    if (!dh_mat3_finite(R) || !dh_mat3_finite(Rdot)) return DH_ERR_NAN;
    st = dh_mat3_check_rot_f32(R, DH_ROT_TOL);
    if (st != DH_OK) return st;
    for (r = 0; r < 3; r++) {
        for (c = 0; c < 3; c++) {
            if (r == c) {
                W[r][c] = 0.0f;
            } else if (!body) {
                /* (Rdot R^T)_rc = sum_k Rdot_rk R_ck */
                W[r][c] = DH_M3(Rdot, r, 0) * DH_M3(R, c, 0) + DH_M3(Rdot, r, 1) * DH_M3(R, c, 1)
                        + DH_M3(Rdot, r, 2) * DH_M3(R, c, 2);
            } else {
                /* (R^T Rdot)_rc = sum_k R_kr Rdot_kc */
                W[r][c] = DH_M3(R, 0, r) * DH_M3(Rdot, 0, c) + DH_M3(R, 1, r) * DH_M3(Rdot, 1, c)
                        + DH_M3(R, 2, r) * DH_M3(Rdot, 2, c);
            }
        }
    }
    {
        /* a finite Rdot near FLT_MAX can overflow: w untouched */
        const float wx = 0.5f * W[2][1] - 0.5f * W[1][2];
        const float wy = 0.5f * W[0][2] - 0.5f * W[2][0];
        const float wz = 0.5f * W[1][0] - 0.5f * W[0][1];
        if (!dh_isfinite_f32(wx) || !dh_isfinite_f32(wy) || !dh_isfinite_f32(wz)) return DH_ERR_OVERFLOW;
        w->x = wx;
        w->y = wy;
        w->z = wz;
    }
    return DH_OK;
}

dh_status dh_angvel_f32(const dh_mat3_f32 *R, const dh_mat3_f32 *Rdot, dh_vec3_f32 *w)
{
    return dh_angvel_common(w, R, Rdot, 0);
}

dh_status dh_angvel_body_f32(const dh_mat3_f32 *R, const dh_mat3_f32 *Rdot, dh_vec3_f32 *w)
{
    return dh_angvel_common(w, R, Rdot, 1);
}

#define DH_ORTHO_STOP 2.384185791015625e-7f /* 2^-22 */
#define DH_ORTHO_MAX_STEPS 8

dh_status dh_mat3_orthonormalize_f32(const dh_mat3_f32 *R, dh_mat3_f32 *out)
{
    dh_mat3_f32 X;
    float G[3][3]; /* G = X^T X, symmetric; G[i][j] = c_i . c_j */
    float dev;
    int step, i, j, r;
    DH_ASSERT(out != NULL && R != NULL);
    if (!dh_mat3_finite(R)) return DH_ERR_NAN;
    if (!dh_rot_cols_ok_f32(R->m[0], R->m[1], R->m[2], DH_ROT_ORTHO_MAX_DEV)) return DH_ERR_NOT_RIGID;
    X = *R;
    for (step = 0; step <= DH_ORTHO_MAX_STEPS; step++) {
        for (i = 0; i < 3; i++) {
            for (j = i; j < 3; j++) {
                G[i][j] = X.m[i][0] * X.m[j][0] + X.m[i][1] * X.m[j][1] + X.m[i][2] * X.m[j][2];
                G[j][i] = G[i][j];
            }
        }
        dev = 0.0f;
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++) {
                float d = fabsf(G[i][j] - (i == j ? 1.0f : 0.0f));
                if (d > dev) dev = d;
            }
        }
        if (dev <= DH_ORTHO_STOP) {
            *out = X;
            return DH_OK;
        }
        if (step == DH_ORTHO_MAX_STEPS) break;
        /* Y = X (3I - G) / 2 = X + X E, E = (I - G) / 2; the correction
         * sum_i x_i E_ij is summed before x_j is added */
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++) {
                G[i][j] = 0.5f * ((i == j ? 1.0f : 0.0f) - G[i][j]);
            }
        }
        /* row r of Y needs only row r of X: in place, row by row */
        for (r = 0; r < 3; r++) {
            const float x0 = X.m[0][r], x1 = X.m[1][r], x2 = X.m[2][r];
            for (j = 0; j < 3; j++) {
                X.m[j][r] = X.m[j][r] + (x0 * G[0][j] + x1 * G[1][j] + x2 * G[2][j]);
            }
        }
    }
    return DH_ERR_NO_CONVERGENCE;
}
