/**
 * @file dh_mat4.h
 * @brief Float 4x4 homogeneous transforms (seed 000): constructors,
 *        composition, application to points/directions/planes, inverses,
 *        equivalent angle and axis.
 *
 * Angles are in degrees. Unless stated otherwise outputs may alias inputs.
 * On a non-OK status the output is left untouched unless the function's
 * contract says otherwise.
 */
#ifndef DHMATH_DH_MAT4_H
#define DHMATH_DH_MAT4_H

#include "dhmath/dh_common.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- constructors ---- */
void dh_mat4_identity_f32(dh_mat4_f32 *T);
void dh_mat4_trans_f32(dh_mat4_f32 *T, float x, float y, float z);          /* eq. 1.24 */
dh_status dh_mat4_rotx_f32(dh_mat4_f32 *T, float deg);                     /* eq. 1.32 */
dh_status dh_mat4_roty_f32(dh_mat4_f32 *T, float deg);                     /* eq. 1.33 */
dh_status dh_mat4_rotz_f32(dh_mat4_f32 *T, float deg);                     /* eq. 1.34 */
dh_status dh_mat4_rot_axis_f32(dh_mat4_f32 *T, float kx, float ky, float kz, float deg); /* eq. 1.70 */
void dh_mat4_scale_f32(dh_mat4_f32 *T, float sx, float sy, float sz);      /* eq. 1.113 */
/** Perspective along axis 0=x, 1=y, 2=z with focal length f (eq. 1.127). */
dh_status dh_mat4_persp_f32(dh_mat4_f32 *T, int axis, float f);
void dh_mat4_from_noap_f32(dh_mat4_f32 *T, const dh_vec3_f32 *n, const dh_vec3_f32 *o,
                           const dh_vec3_f32 *a, const dh_vec3_f32 *p);

/* ---- accessors ---- */
dh_vec3_f32 dh_mat4_n_f32(const dh_mat4_f32 *T);
dh_vec3_f32 dh_mat4_o_f32(const dh_mat4_f32 *T);
dh_vec3_f32 dh_mat4_a_f32(const dh_mat4_f32 *T);
dh_vec3_f32 dh_mat4_p_f32(const dh_mat4_f32 *T);
void dh_mat4_get_rot_f32(const dh_mat4_f32 *T, dh_mat3_f32 *R);
void dh_mat4_set_rot_f32(dh_mat4_f32 *T, const dh_mat3_f32 *R);

/* ---- composition (out may alias A and/or B) ---- */
void dh_mat4_mul_f32(dh_mat4_f32 *out, const dh_mat4_f32 *A, const dh_mat4_f32 *B);
/** Affine product: assumes bottom rows 0 0 0 1 (not read) and writes 0 0 0 1. */
void dh_mat4_mul_affine_f32(dh_mat4_f32 *out, const dh_mat4_f32 *A, const dh_mat4_f32 *B);
/** T = X * T (pre-multiplication: X is expressed in the base frame, seed sec. 9). */
void dh_mat4_premul_f32(dh_mat4_f32 *T, const dh_mat4_f32 *X);
/** T = T * X (post-multiplication: X is expressed in T's own frame). */
void dh_mat4_postmul_f32(dh_mat4_f32 *T, const dh_mat4_f32 *X);

/* ---- application ---- */
void dh_mat4_apply_point_f32(const dh_mat4_f32 *T, const dh_vec3_f32 *u, dh_vec3_f32 *v); /* w = 1, affine T */
void dh_mat4_apply_dir_f32(const dh_mat4_f32 *T, const dh_vec3_f32 *u, dh_vec3_f32 *v);   /* w = 0 */
void dh_mat4_apply_vec4_f32(const dh_mat4_f32 *T, const dh_vec4_f32 *u, dh_vec4_f32 *v);  /* full product */
/** v = T*u then divide by w; w == 0 -> DH_ERR_DOMAIN (point at infinity). */
dh_status dh_mat4_apply_point_h_f32(const dh_mat4_f32 *T, const dh_vec4_f32 *u, dh_vec3_f32 *v);
/** Q = P * T^-1 (eq. 1.21); singular T -> DH_ERR_SINGULAR. */
dh_status dh_mat4_apply_plane_f32(const dh_mat4_f32 *T, const dh_plane_f32 *P, dh_plane_f32 *Q);
/** Q = P * Tinv where the caller already holds the inverse. */
void dh_plane_mul_f32(const dh_plane_f32 *P, const dh_mat4_f32 *Tinv, dh_plane_f32 *Q);
void dh_mat4_apply_points_f32(const dh_mat4_f32 *T, const dh_vec3_f32 *u, dh_vec3_f32 *v, size_t count);

/* ---- inverses ---- */
/** Closed-form rigid inverse (eq. 1.57); does not check rigidity. */
void dh_mat4_inv_rigid_f32(dh_mat4_f32 *out, const dh_mat4_f32 *T);
/** General inverse; DH_ERR_SINGULAR with a relative tolerance; DH_ERR_NAN on non-finite input. */
dh_status dh_mat4_inv_f32(dh_mat4_f32 *out, const dh_mat4_f32 *T);
/** Rigid within tol (orthonormal rotation with det +1, bottom row 0 0 0 1): DH_OK or DH_ERR_NOT_RIGID / DH_ERR_NAN. */
dh_status dh_mat4_check_rigid_f32(const dh_mat4_f32 *T, float tol);
/** Rigid inverse when rigid (tol 1e-5), else general inverse. */
dh_status dh_mat4_inv_auto_f32(dh_mat4_f32 *out, const dh_mat4_f32 *T);

/* ---- equivalent angle and axis (seed sec. 13) ---- */
/** Rotation part of T -> unit axis k and angle theta in [0, 180] degrees. */
dh_status dh_mat4_to_axis_angle_f32(const dh_mat4_f32 *T, dh_vec3_f32 *k, float *theta_deg);

/* ---- misc ---- */
/** 1 if every element is finite, else 0. */
int dh_mat4_isfinite_f32(const dh_mat4_f32 *T);

#ifdef __cplusplus
}
#endif

#endif /* DHMATH_DH_MAT4_H */
