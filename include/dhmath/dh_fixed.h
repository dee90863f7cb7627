/**
 * @file dh_fixed.h
 * @brief Fixed-point rigid frames: rotation Q2.30, position dh_qpos
 *        (DH_QPOS_FRAC fraction bits), angles in degrees Q16.16.
 *
 * Integer only (no float, no libm, no 64-bit division). 64-bit accumulation
 * with one rounding per output; saturation is reported as DH_ERR_OVERFLOW
 * (the saturated value is written). Outputs may alias inputs.
 */
#ifndef DHMATH_DH_FIXED_H
#define DHMATH_DH_FIXED_H

#include "dhmath/dh_common.h"

#ifdef __cplusplus
extern "C" {
#endif

void dh_frame_identity_q(dh_frame_q *F);
void dh_frame_trans_q(dh_frame_q *F, dh_qpos x, dh_qpos y, dh_qpos z);
void dh_frame_rotx_q(dh_frame_q *F, dh_q16 deg);
void dh_frame_roty_q(dh_frame_q *F, dh_q16 deg);
void dh_frame_rotz_q(dh_frame_q *F, dh_q16 deg);
/** Axis (any scale, Q2.30 or any common scale) normalised internally; zero axis -> DH_ERR_ZERO_AXIS. */
dh_status dh_frame_rot_axis_q(dh_frame_q *F, dh_q30 kx, dh_q30 ky, dh_q30 kz, dh_q16 deg);

/** out = A * B. */
dh_status dh_frame_mul_q(dh_frame_q *out, const dh_frame_q *A, const dh_frame_q *B);
/** out = F^-1 (transpose rotation, -R^T p). */
dh_status dh_frame_inv_q(dh_frame_q *out, const dh_frame_q *F);
/** v = F * u (point). */
dh_status dh_frame_apply_point_q(const dh_frame_q *F, const dh_vec3_q *u, dh_vec3_q *v);
/** v = R * u (direction, positions scale). */
dh_status dh_frame_apply_dir_q(const dh_frame_q *F, const dh_vec3_q *u, dh_vec3_q *v);
/** Re-orthonormalise the rotation part in place. */
void dh_frame_orthonormalize_q(dh_frame_q *F);
/** Largest |R^T R - I| entry in Q2.30 LSB (drift measure). */
int32_t dh_frame_ortho_error_q(const dh_frame_q *F);

/* conversions (live in their own source file: they use float) */
dh_status dh_frame_from_mat4_q(dh_frame_q *F, const dh_mat4_f32 *T);
void dh_frame_to_mat4_q(dh_mat4_f32 *T, const dh_frame_q *F);

#ifdef __cplusplus
}
#endif

#endif /* DHMATH_DH_FIXED_H */
