/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_pose_error.c - the orientation error a(dR) = w, dR = Rt R^T (the
 * rotation vector of dR, accurate at 0 and 180 degrees alike) and the pose
 * error (position difference and w) of two float frames; the blocks that
 * the float IK calls on its workspace (kin_impl.h). Method: docs/design.md,
 * "Kinematics".
 */
#include "dhmath/kin.h"
#include "kin_impl.h"
#include "../internal/dh_mathf.h"
#include "../internal/dh_floatops.h"

#include <math.h>

/* det of the 3x3 whose columns are c0, c1, c2: c0 . (c1 x c2) */
int dh_kin_rot_ok_f32_(const float *c0, const float *c1, const float *c2)
{
    return dh_rot_cols_ok_f32(c0, c1, c2, DH_ROT_ERROR_TOL);
}

/* theta > 90 deg: the axis from the symmetric part (dR + dR^T)/2 =
 * c I + (1 - c) k k^T, largest diagonal entry first, signed like u (held in
 * w on entry; at exactly 180 deg k_m > 0 is kept). */
static void pose_rotvec_big(const float *d, float *w, float tr, float theta)
{
    float c = 0.5f * tr, omc = 1.0f - c;   /* omc in (1, 2] */
    float kv[3], km, kn, s;
    uint32_t m = 0u, a;
    if (d[4] > d[4u * m]) m = 1u;
    if (d[8] > d[4u * m]) m = 2u;
    km = (d[4u * m] - c) / omc;
    km = dh_sqrtf_(km > 0.0f ? km : 0.0f);
    if (!(km > 0.0f)) km = 1.0f;   /* unreachable for a rotation (km^2 >= 1/3) */
    for (a = 0; a < 3u; a++)
        kv[a] = (a == m) ? km : 0.5f * (d[3u * a + m] + d[3u * m + a]) / (omc * km);
    kn = dh_sqrtf_(kv[0] * kv[0] + kv[1] * kv[1] + kv[2] * kv[2]);
    s = (kv[0] * w[0] + kv[1] * w[1] + kv[2] * w[2] < 0.0f) ? -theta / kn : theta / kn;
    w[0] = s * kv[0];
    w[1] = s * kv[1];
    w[2] = s * kv[2];
}

/* a(dR). The identity is NOT tested on the diagonal (it rounds to 1 for
 * small angles while u still carries the rotation): u = 0 -> w = 0. */
void dh_kin_rotvec_f32_(const float *d, float *w)
{
    float un, tr, theta;
    w[0] = d[7] - d[5];                       /* u = (r32 - r23, r13 - r31, r21 - r12) */
    w[1] = d[2] - d[6];
    w[2] = d[3] - d[1];
    un = dh_sqrtf_(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);   /* = 2 sin(theta) */
    tr = d[0] + d[4] + d[8] - 1.0f;                         /* = 2 cos(theta) */
    theta = dh_atan2f_(un, tr);               /* in [0, pi]: no acos domain error */
    if (tr >= 0.0f) {
        /* theta <= 90 deg: u is accurate; theta / un -> 1/2 as un -> 0 */
        float f = (un > 0.0f) ? theta / un : 0.5f;
        w[0] *= f;
        w[1] *= f;
        w[2] *= f;
        return;
    }
    pose_rotvec_big(d, w, tr, theta);
}

/* d = Rt R^T row-major; column c of Rt, R starts at ct[s c], cr[s c]
 * (s: 3 for a dh_mat3_f32, 4 for a dh_mat4_f32). */
static void pose_delta(const float *ct, const float *cr, uint32_t s, float *d)
{
    uint32_t i, j, k;
    for (i = 0; i < 3u; i++)
        for (j = 0; j < 3u; j++) {
            float x = 0.0f;
            for (k = 0; k < 3u; k++) x += ct[s * k + i] * cr[s * k + j];
            d[3u * i + j] = x;
        }
}

/* 1 when the entries (i, j), i < nrow, j < 3, at a[s i + j] are finite */
DH_INLINE int pose_finite(const float *a, uint32_t s, uint32_t nrow)
{
    uint32_t i, j;
    for (i = 0; i < nrow; i++)
        for (j = 0; j < 3u; j++)
            if (!dh_isfinite_f32(a[s * i + j])) return 0;
    return 1;
}

/* Checks of two frames whose entries (i, j) sit at a[s i + j], b[s i + j]:
 * rows 0..2 the rotation's columns, rows 3..nrow-1 (nrow 3 or 4) the
 * translation. DH_ERR_NAN when an entry is not finite, DH_ERR_NOT_RIGID
 * when a rotation is not one (within DH_ROT_ERROR_TOL), else DH_OK. */
DH_INLINE dh_status pose_check(const float *a, const float *b, uint32_t s, uint32_t nrow)
{
    if (!pose_finite(a, s, nrow) || !pose_finite(b, s, nrow)) return DH_ERR_NAN;
    if (!dh_kin_rot_ok_f32_(a, a + s, a + 2u * s) || !dh_kin_rot_ok_f32_(b, b + s, b + 2u * s))
        return DH_ERR_NOT_RIGID;
    return DH_OK;
}

dh_status dh_rot_error_f32(const dh_mat3_f32 *R_target, const dh_mat3_f32 *R, dh_vec3_f32 *w)
{
    float d[9], v[3];
    dh_status st;

    DH_ASSERT(R_target != NULL);
    DH_ASSERT(R != NULL);
    DH_ASSERT(w != NULL);

    st = pose_check(&R_target->m[0][0], &R->m[0][0], 3u, 3u);
    if (st != DH_OK) return st;
    pose_delta(&R_target->m[0][0], &R->m[0][0], 3u, d);
    dh_kin_rotvec_f32_(d, v);
    w->x = v[0];
    w->y = v[1];
    w->z = v[2];
    return DH_OK;
}

/* e from two checked frames, dR in d (inlined: no frame of its own below
 * the callers') */
DH_INLINE void pose_error_body(const dh_mat4_f32 *T_target, const dh_mat4_f32 *T, float *e, float *d)
{
    uint32_t i;
    pose_delta(&T_target->m[0][0], &T->m[0][0], 4u, d);
    dh_kin_rotvec_f32_(d, e + 3);
    for (i = 0; i < 3u; i++) e[i] = T_target->m[3][i] - T->m[3][i];
}

/* The body of dh_pose_error_f32 with dR's scratch d[9] in the caller's
 * memory (the tracker keeps it off the stack). */
dh_status dh_kin_pose_error_f32_(const dh_mat4_f32 *T_target, const dh_mat4_f32 *T, float *e, float *d)
{
    const dh_status st = pose_check(&T_target->m[0][0], &T->m[0][0], 4u, 4u);

    if (st != DH_OK) return st;
    pose_error_body(T_target, T, e, d);
    return DH_OK;
}

dh_status dh_kin_pose_error_to_f32_(const dh_mat4_f32 *T_target, const dh_mat4_f32 *T, float *e, float *d)
{
    const float *const b = &T->m[0][0];

    if (!pose_finite(b, 4u, 4u)) return DH_ERR_NAN;
    if (!dh_kin_rot_ok_f32_(b, b + 4u, b + 8u)) return DH_ERR_NOT_RIGID;
    pose_error_body(T_target, T, e, d);
    return DH_OK;
}

dh_status dh_pose_error_f32(const dh_mat4_f32 *T_target, const dh_mat4_f32 *T, float e[6])
{
    float d[9];
    DH_ASSERT(T_target != NULL);
    DH_ASSERT(T != NULL);
    DH_ASSERT(e != NULL);
    return dh_kin_pose_error_f32_(T_target, T, e, d);
}
