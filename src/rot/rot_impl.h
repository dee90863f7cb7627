/* SPDX-License-Identifier: Apache-2.0 */
/*
 * rot_impl.h - PRIVATE to the rotation family (src/rot/, not installed):
 * float helpers shared by the quaternion, axis-angle and rotation-vector
 * modules, and the fixed rotation blocks of dh_rot_q.c that the fixed
 * orientation error (src/kin/dh_pose_error_q.c) calls.
 */
#ifndef DHMATH_SRC_ROT_IMPL_H
#define DHMATH_SRC_ROT_IMPL_H

#include "dhmath/rot.h"
#include "../internal/dh_floatops.h"

/** An axis (v[0], v[1], v[2]) divided by its largest magnitude, so that its
 *  squares neither overflow nor underflow, and *len = its length then (in
 *  [1, sqrt 3]). DH_ERR_NAN for a NaN/Inf component, DH_ERR_ZERO_AXIS when
 *  the largest magnitude is below FLT_MIN; v and *len untouched then. */
DH_INLINE dh_status dh_axis_prescale_f32(float v[3], float *len)
{
    float m;
    if (!dh_isfinite_f32(v[0]) || !dh_isfinite_f32(v[1]) || !dh_isfinite_f32(v[2])) return DH_ERR_NAN;
    m = fabsf(v[0]);
    if (fabsf(v[1]) > m) m = fabsf(v[1]);
    if (fabsf(v[2]) > m) m = fabsf(v[2]);
    if (m < FLT_MIN) return DH_ERR_ZERO_AXIS;
    v[0] /= m;
    v[1] /= m;
    v[2] /= m;
    *len = dh_sqrt_f32(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return DH_OK;
}

/** The off-diagonal of R = S + [w]x, S symmetric with S01 = xy, S02 = xz,
 *  S12 = yz (+ 0.0f: no -0). */
DH_INLINE void dh_rot_offdiag_f32(dh_mat3_f32 *R, float xy, float xz, float yz, float wx, float wy,
                                  float wz)
{
    DH_M3(R, 0, 1) = (xy - wz) + 0.0f;
    DH_M3(R, 1, 0) = (xy + wz) + 0.0f;
    DH_M3(R, 0, 2) = (xz + wy) + 0.0f;
    DH_M3(R, 2, 0) = (xz - wy) + 0.0f;
    DH_M3(R, 1, 2) = (yz - wx) + 0.0f;
    DH_M3(R, 2, 1) = (yz + wx) + 0.0f;
}

/* R = c I + s [k]x + v k k^T, unit k, v = 1 - c: the diagonal avoids
 * cancellation (exact for a coordinate axis); + 0.0f: no -0 off it. */
static inline void dh_rot_rodrigues_f32_(dh_mat3_f32 *R, const float k[3], float s, float c, float v)
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

/* ---- fixed blocks (dh_rot_q.c) ------------------------------------------ */

/* 1 when F's rotation is orthonormal within tol LSB (every entry of
 * R^T R - I, exact, within tol 2^-30) and det > 0; an entry of magnitude
 * above 1.25 fails at once. */
int dh_rot_ok_q_(const dh_frame_q *F, int32_t tol);

/* Rotation vector (Q3.29 rad) of the checked-or-near rotation D (q: 4
 * words of scratch, the caller's: the frame stays small). */
void dh_rot_vec_q_(const dh_frame_q *D, dh_dir3_q *w, int32_t *q);

#endif /* DHMATH_SRC_ROT_IMPL_H */
