/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_mat3.c - 3x3 rotation helpers: the rotation check, skew-symmetric
 * matrices and vee, angular velocity from R and Rdot, re-orthonormalisation.
 *
 * Math: S(w) = Rdot R^T (FloCal, "Angular Velocity"), polar decomposition
 * by the Newton-Schulz iteration.
 */
#include <math.h>

#include "dhmath/rot.h"
#include "../internal/dh_floatops.h"

static int mat3_finite(const dh_mat3_f32 *R)
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
    if (!mat3_finite(R)) return DH_ERR_NAN;
    return dh_rot_cols_ok_f32(R->m[0], R->m[1], R->m[2], tol) ? DH_OK : DH_ERR_NOT_RIGID;
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
static dh_status mat3_angvel(dh_vec3_f32 *w, const dh_mat3_f32 *R, const dh_mat3_f32 *Rdot, int body)
{
    float W[3][3]; /* W[r][c], only off-diagonal entries used */
    int r, c;
    dh_status st;
    DH_ASSERT(w != NULL && R != NULL && Rdot != NULL);
    if (!mat3_finite(R) || !mat3_finite(Rdot)) return DH_ERR_NAN;
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
    return mat3_angvel(w, R, Rdot, 0);
}

dh_status dh_angvel_body_f32(const dh_mat3_f32 *R, const dh_mat3_f32 *Rdot, dh_vec3_f32 *w)
{
    return mat3_angvel(w, R, Rdot, 1);
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
    if (!mat3_finite(R)) return DH_ERR_NAN;
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
