/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_interp.c - pose interpolation: slerp of unit quaternions along the
 * shortest arc, the pose between two frames, the angle between two frames.
 *
 * Slerp (Shoemake 1985) is written as a rotation relative to the nearer
 * end: with r = a* b = (cos h, sin h k), the path is a (cos sh, sin sh k)
 * for s <= 1/2 and b (cos (1-s)h, -sin (1-s)h k) after, h = atan2(|v|, w)
 * from the vector part v of r (no acos near 1, no division by sin h: the
 * axis k = v / |v| multiplies sin(sh) directly). Each end is reached with
 * no rounding of the other, so s == 0 and s == 1 give a and b as
 * normalised, and the two halves meet at s = 1/2 within rounding.
 *
 * The angle between two frames is atan2(2 sin t, 2 cos t) read off
 * M = R_A^T R_B (the vee of M - M^T and tr M - 1): well conditioned at
 * every angle, 0 and 180 degrees included.
 */
#include <float.h>
#include <math.h>

#include "dhmath/motion.h"
#include "dhmath/mat4.h"
#include "../internal/dh_floatops.h"
#include "motion_impl.h"

void dh_motion_shorter_f32_(const dh_quat_f32 *qa, dh_quat_f32 *qb)
{
    if (qa->w * qb->w + qa->x * qb->x + qa->y * qb->y + qa->z * qb->z < 0.0f) {
        qb->w = -qb->w;
        qb->x = -qb->x;
        qb->y = -qb->y;
        qb->z = -qb->z;
    }
}

/* dh_motion_slerp_f32_ (motion_impl.h).
 * The argument s h or (1 - s) h is at most pi/4 (h <= pi/2 since r.w >= 0,
 * up to rounding), so the sine and cosine need no argument reduction. */
DH_NOINLINE void dh_motion_slerp_f32_(const dh_quat_f32 *qa, const dh_quat_f32 *qb, float s, dh_quat_f32 *out)
{
    dh_quat_f32 r;
    float n, h, sn, cs;
    int back = s > 0.5f;
    dh_quat_conj_f32(qa, &r);
    dh_quat_mul_f32(&r, qb, &r);
    n = dh_sqrt_f32(r.x * r.x + r.y * r.y + r.z * r.z);
    if (!(s > 0.0f) || !(s < 1.0f) || !(n > 0.0f)) {
        *out = back ? *qb : *qa;
        return;
    }
    h = dh_atan2f_(n, r.w);
    dh_sincosf_pio4_((back ? 1.0f - s : s) * h, &sn, &cs);
    sn /= n;
    if (back) sn = -sn;
    r.w = cs;
    r.x *= sn;
    r.y *= sn;
    r.z *= sn;
    dh_quat_mul_f32(back ? qb : qa, &r, &r);
    /* a product of unit quaternions: its norm is 1 within rounding, so the
     * division needs no rescaling against overflow */
    n = dh_sqrt_f32(r.w * r.w + r.x * r.x + r.y * r.y + r.z * r.z);
    out->w = r.w / n;
    out->x = r.x / n;
    out->y = r.y / n;
    out->z = r.z / n;
}

dh_status dh_slerp_f32(const dh_quat_f32 *a, const dh_quat_f32 *b, float s, dh_quat_f32 *out)
{
    dh_quat_f32 qa, qb;
    dh_status st;
    DH_ASSERT(a != NULL && b != NULL && out != NULL);
    if (!dh_isfinite_f32(s)) return DH_ERR_NAN;
    st = dh_quat_normalize_f32(a, &qa);
    if (st == DH_OK) st = dh_quat_normalize_f32(b, &qb);
    if (st != DH_OK) return st;
    if (s < 0.0f || s > 1.0f) return DH_ERR_ARG;
    dh_motion_shorter_f32_(&qa, &qb);
    dh_motion_slerp_f32_(&qa, &qb, s, out);
    return DH_OK;
}

/* DH_OK when A and B are rigid frames (dh_mat4_check_rigid_f32) */
static dh_status interp_check(const dh_mat4_f32 *A, const dh_mat4_f32 *B)
{
    dh_status st = dh_mat4_check_rigid_f32(A, DH_ROT_TOL);
    return (st == DH_OK) ? dh_mat4_check_rigid_f32(B, DH_ROT_TOL) : st;
}

dh_status dh_pose_interp_f32(const dh_mat4_f32 *A, const dh_mat4_f32 *B, float s, dh_mat4_f32 *T)
{
    dh_quat_f32 qa, qb;
    dh_mat3_f32 R;
    float dp;
    int i, back;
    dh_status st;
    DH_ASSERT(A != NULL && B != NULL && T != NULL);
    st = interp_check(A, B);
    if (st != DH_OK) return st;
    if (!dh_isfinite_f32(s)) return DH_ERR_NAN;
    if (s < 0.0f || s > 1.0f) return DH_ERR_ARG;
    for (i = 0; i < 3; i++) {
        if (!dh_isfinite_f32(DH_M4(B, i, 3) - DH_M4(A, i, 3))) return DH_ERR_OVERFLOW;
    }
    back = s > 0.5f;
    if (!(s > 0.0f) || !(s < 1.0f)) {
        *T = back ? *B : *A;
        return DH_OK;
    }
    dh_mat4_get_rot_f32(A, &R);
    st = dh_mat3_to_quat_f32(&R, &qa);
    if (st != DH_OK) return st;
    dh_mat4_get_rot_f32(B, &R);
    st = dh_mat3_to_quat_f32(&R, &qb);
    if (st != DH_OK) return st;
    dh_motion_shorter_f32_(&qa, &qb);
    dh_motion_slerp_f32_(&qa, &qb, s, &qa);
    (void)dh_quat_to_mat3_f32(&qa, &R);
    /* element i of the position reads only element i of A's and B's, so
     * T may alias either */
    for (i = 0; i < 3; i++) {
        dp = DH_M4(B, i, 3) - DH_M4(A, i, 3);
        DH_M4(T, i, 3) = back ? DH_M4(B, i, 3) - (1.0f - s) * dp : DH_M4(A, i, 3) + s * dp;
    }
    dh_mat4_set_rot_f32(T, &R);
    for (i = 0; i < 3; i++) DH_M4(T, 3, i) = 0.0f;
    DH_M4(T, 3, 3) = 1.0f;
    return DH_OK;
}

/* column i of A's rotation . column j of B's: entry (i, j) of R_A^T R_B */
static DH_NOINLINE float interp_dot(const dh_mat4_f32 *A, const dh_mat4_f32 *B, int i, int j)
{
    return A->m[i][0] * B->m[j][0] + A->m[i][1] * B->m[j][1] + A->m[i][2] * B->m[j][2];
}

dh_status dh_pose_angle_f32(const dh_mat4_f32 *A, const dh_mat4_f32 *B, float *deg)
{
    float vx, vy, vz, c;
    dh_status st;
    DH_ASSERT(A != NULL && B != NULL && deg != NULL);
    st = interp_check(A, B);
    if (st != DH_OK) return st;
    /* M = R_A^T R_B: M - M^T = 2 sin(t) [k]x, tr M - 1 = 2 cos(t) */
    vx = interp_dot(A, B, 2, 1) - interp_dot(A, B, 1, 2);
    vy = interp_dot(A, B, 0, 2) - interp_dot(A, B, 2, 0);
    vz = interp_dot(A, B, 1, 0) - interp_dot(A, B, 0, 1);
    c = (interp_dot(A, B, 0, 0) + interp_dot(A, B, 1, 1) + interp_dot(A, B, 2, 2)) - 1.0f;
    *deg = dh_atan2f_deg_(dh_sqrt_f32(vx * vx + vy * vy + vz * vz), c, 0.0f);
    return DH_OK;
}
