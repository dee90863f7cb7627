/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Index: the functions of mat4.h by source file (src/mat4/).
 *   dh_mat4.c      dh_mat4_identity_f32, dh_mat4_trans_f32, dh_mat4_rotx_f32,
 *                  dh_mat4_roty_f32, dh_mat4_rotz_f32, dh_mat4_rot_axis_f32,
 *                  dh_mat4_scale_f32, dh_mat4_persp_f32,
 *                  dh_mat4_from_noap_f32, dh_mat4_n_f32, dh_mat4_o_f32,
 *                  dh_mat4_a_f32, dh_mat4_p_f32, dh_mat4_get_rot_f32,
 *                  dh_mat4_set_rot_f32, dh_mat4_mul_f32,
 *                  dh_mat4_mul_affine_f32, dh_mat4_premul_f32,
 *                  dh_mat4_postmul_f32, dh_mat4_apply_point_f32,
 *                  dh_mat4_apply_dir_f32, dh_mat4_apply_vec4_f32,
 *                  dh_mat4_apply_point_h_f32, dh_plane_mul_f32,
 *                  dh_mat4_apply_points_f32, dh_mat4_check_finite_f32
 *   dh_mat4_inv.c  dh_mat4_apply_plane_f32, dh_mat4_inv_rigid_f32,
 *                  dh_mat4_inv_f32, dh_mat4_check_rot_f32,
 *                  dh_mat4_check_rigid_f32, dh_mat4_inv_auto_f32
 */
/**
 * @file mat4.h
 * @brief Float 4x4 homogeneous transforms (Paul 1981, ch. 1): constructors,
 *        composition, application to points/directions/planes, inverses,
 *        equivalent angle and axis.
 *
 * Conventions (Paul 1981 eq. 1.20, 1.56):
 * - a transform T has the columns n, o, a, p; points are columns and are
 *   mapped as v = T*u; planes are rows and are mapped as Q = P*T^-1;
 * - storage is column-major, element (row r, column c) is T->m[c][r]
 *   (DH_M4(T, r, c)), so n, o, a, p are each four contiguous floats;
 * - angles are in DEGREES (any finite value; the rotation constructors use
 *   dh_sincos_f32, so whole multiples of 90 give exact 0 and +-1);
 * - lengths are in the caller's unit, unchanged;
 * - equation numbers below are those of Paul 1981 (docs/references.md).
 *
 * Pointers must not be NULL (checked with DH_ASSERT). Unless a contract
 * says otherwise, outputs may alias inputs (the same object; partial
 * overlap of different objects is not allowed), and on a non-OK status
 * every output is left untouched.
 *
 * Error bounds are against the exact result for the given float inputs;
 * measured accuracy: docs/accuracy_mat4.md; cost and stack:
 * docs/generated/performance_target.md, docs/generated/footprint.md; methods and proofs:
 * docs/design.md ("Float transforms and inverses"). All functions are
 * float-only, reentrant, use no heap and at most 256 bytes of stack.
 */
#ifndef DHMATH_MAT4_H
#define DHMATH_MAT4_H

#include "dhmath/common.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * Condition-number limit of dh_mat4_inv_f32 (2^19 = 524288: above it a
 * float inverse keeps fewer than about two correct decimal digits).
 * "cond" of dh_mat4_inv_f32 is the balanced condition number
 * ||B||_1 ||B^-1||_1 of B = E M E^-1, E = diag(1, 1, 1, g), where:
 *  - T with bottom row 0 0 0 w, w a power of two (w = 1: affine; 2^k times
 *    an affine T): M = blockdiag(c R, 1), c the power of two that brings
 *    max|c R_ij| into [1, 2) ([2, 4) for the top binade); g = 1;
 *  - any other T: M = T, g = sqrt(|p|_1 / |q|_1), p = column 3 and q =
 *    bottom row of T without the corner, as they are in T scaled by a
 *    power of two to max|T_ij| in [1, 2) ([2, 4) for the top binade);
 *    g = 2^-24 ||R||_1 / |q|_1 for p = 0, g = 2^24 |p|_1 / ||R||_1 for
 *    q = 0; g clamped to [2^-60, 2^60].
 * cond is the same for T and every exact 2^k T (and affine T: any c R).
 */
#define DH_MAT4_COND_MAX 524288.0f

/** Tolerance used by dh_mat4_inv_auto_f32 to take the rigid fast path. */
#define DH_MAT4_RIGID_TOL 1e-5f

/**
 * Orthonormality tolerance of dh_mat4_to_axis_angle_f32: every entry of
 * R^T R - I must be within this bound (and det R > 0).
 */
#define DH_MAT4_AXIS_TOL 1e-4f

/* ======================================================================
 * Constructors
 * ==================================================================== */

/** @brief T = I. Cannot fail. */
void dh_mat4_identity_f32(dh_mat4_f32 *T);

/**
 * @brief T = Trans(x, y, z) (eq. 1.24): identity with p = (x, y, z).
 * Any float values are stored as given (no check). Cannot fail.
 */
void dh_mat4_trans_f32(float x, float y, float z, dh_mat4_f32 *T);

/**
 * @brief T = Rot(x, deg) (eq. 1.32): rows (1 0 0), (0 c -s), (0 s c).
 * @param T output (untouched on error)
 * @param deg angle in degrees, any finite value.
 * @return DH_OK; DH_ERR_NAN if deg is NaN or infinite (T untouched).
 * The entries are exactly dh_sincos_f32(deg) and 0 - s (so no -0 appears:
 * Rot(x, 0) is bitwise the identity; multiples of 90 are exact).
 */
dh_status dh_mat4_rotx_f32(float deg, dh_mat4_f32 *T);

/** @brief T = Rot(y, deg) (eq. 1.33): rows (c 0 s), (0 1 0), (-s 0 c). Same contract as rotx. */
dh_status dh_mat4_roty_f32(float deg, dh_mat4_f32 *T);

/** @brief T = Rot(z, deg) (eq. 1.34): rows (c -s 0), (s c 0), (0 0 1). Same contract as rotx. */
dh_status dh_mat4_rotz_f32(float deg, dh_mat4_f32 *T);

/**
 * @brief T = Rot(k, deg), rotation by deg degrees about the axis k through
 *        the origin (eq. 1.70, right-hand rule); p = 0.
 * @param T output (untouched on error)
 * @param kx,ky,kz axis, any finite non-zero length (it is normalised; the
 *        normalisation is overflow-free for any finite components).
 * @param deg angle in degrees, any finite value.
 * @return DH_OK; DH_ERR_NAN if any argument is NaN/Inf; DH_ERR_ZERO_AXIS if
 *         max(|kx|,|ky|,|kz|) < FLT_MIN (zero or denormal axis). T untouched
 *         on error.
 * For a coordinate axis (any positive length) the result is bitwise
 * Rot(x|y|z, deg). No -0 entries. Entry error: test_mat4_props asserts
 * <= 10 * 2^-24 against double.
 */
dh_status dh_mat4_rot_axis_f32(float kx, float ky, float kz, float deg, dh_mat4_f32 *T);

/**
 * @brief T = diag(sx, sy, sz, 1) (eq. 1.113). Values stored as given. Cannot fail.
 */
void dh_mat4_scale_f32(float sx, float sy, float sz, dh_mat4_f32 *T);

/**
 * @brief Perspective transform along an axis (eq. 1.127 for the y axis):
 *        identity with -1/f in the bottom row, in the column of the axis,
 *        so a point u maps to w = 1 - u_axis / f.
 * @param T output (untouched on error)
 * @param axis 0 = x, 1 = y, 2 = z.
 * @param f focal length (any finite non-zero value; Paul 1981 uses f > 0).
 * @return DH_OK; DH_ERR_ARG if axis is not 0..2; DH_ERR_NAN if f is NaN/Inf;
 *         DH_ERR_DOMAIN if f == 0 or |1/f| overflows (|f| < 2^-128).
 *         T untouched on error.
 */
dh_status dh_mat4_persp_f32(int axis, float f, dh_mat4_f32 *T);

/**
 * @brief T = [n o a p; 0 0 0 1] (eq. 1.56). The vectors are copied as given
 * (no orthonormality check; see dh_mat4_check_rigid_f32). Cannot fail.
 */
void dh_mat4_from_noap_f32(const dh_vec3_f32 *n, const dh_vec3_f32 *o, const dh_vec3_f32 *a,
                           const dh_vec3_f32 *p, dh_mat4_f32 *T);

/* ======================================================================
 * Accessors (plain loads; cannot fail)
 * ==================================================================== */

/** @brief Column n (x axis of the frame): rows 0..2 of column 0. */
dh_vec3_f32 dh_mat4_n_f32(const dh_mat4_f32 *T);
/** @brief Column o (y axis of the frame): rows 0..2 of column 1. */
dh_vec3_f32 dh_mat4_o_f32(const dh_mat4_f32 *T);
/** @brief Column a (z axis of the frame): rows 0..2 of column 2. */
dh_vec3_f32 dh_mat4_a_f32(const dh_mat4_f32 *T);
/** @brief Column p (origin of the frame): rows 0..2 of column 3. */
dh_vec3_f32 dh_mat4_p_f32(const dh_mat4_f32 *T);
/** @brief R = upper-left 3x3 block of T (columns n, o, a). */
void dh_mat4_get_rot_f32(const dh_mat4_f32 *T, dh_mat3_f32 *R);
/** @brief Upper-left 3x3 block of T = R; p and the bottom row are not touched. */
void dh_mat4_set_rot_f32(dh_mat4_f32 *T, const dh_mat3_f32 *R);

/* ======================================================================
 * Composition. out may alias A and/or B. No status: IEEE semantics
 * (NaN/Inf propagate; overflow gives Inf). Cannot fail.
 * ==================================================================== */

/**
 * @brief out = A * B, full 4x4 product (64 multiplies, 48 adds).
 * Each element is the sum of 4 products evaluated left to right, so integer
 * and 0/+-1 inputs give exact results. Error vs the exact product:
 * |err_rc| <= 4 * 2^-24 * sum_k |A_rk||B_kc|.
 */
void dh_mat4_mul_f32(const dh_mat4_f32 *A, const dh_mat4_f32 *B, dh_mat4_f32 *out);

/**
 * @brief out = A * B for affine transforms: the bottom rows of A and B are
 * IGNORED (taken as 0 0 0 1; their values, even NaN, do not affect the
 * result) and the bottom row of out is written 0 0 0 1.
 * Same rounding and bound as dh_mat4_mul_f32 on affine inputs, and the same
 * values when the inputs' bottom rows are exactly 0 0 0 1 (zeros may differ
 * in sign).
 */
void dh_mat4_mul_affine_f32(const dh_mat4_f32 *A, const dh_mat4_f32 *B, dh_mat4_f32 *out);

/**
 * @brief T = X * T (pre-multiplication, full product): the motion X is
 * expressed in the BASE (reference) frame (Paul 1981 eq. 1.50).
 */
void dh_mat4_premul_f32(dh_mat4_f32 *T, const dh_mat4_f32 *X);

/**
 * @brief T = T * X (post-multiplication, full product): the motion X is
 * expressed in T's own (current) frame (Paul 1981 eq. 1.51).
 */
void dh_mat4_postmul_f32(dh_mat4_f32 *T, const dh_mat4_f32 *X);

/* ======================================================================
 * Application. u and v may be the same object. Cannot fail unless a
 * status is returned.
 * ==================================================================== */

/**
 * @brief v = R*u + p: a point (w = 1) through an affine T (bottom row not
 * read). Error per component <= 4 * 2^-24 * (sum |R_ij u_j| + |p_i|).
 */
void dh_mat4_apply_point_f32(const dh_mat4_f32 *T, const dh_vec3_f32 *u, dh_vec3_f32 *v);

/** @brief v = R*u: a direction (w = 0); p and the bottom row are not read. */
void dh_mat4_apply_dir_f32(const dh_mat4_f32 *T, const dh_vec3_f32 *u, dh_vec3_f32 *v);

/** @brief v = T*u, full homogeneous product (all 16 entries used). */
void dh_mat4_apply_vec4_f32(const dh_mat4_f32 *T, const dh_vec4_f32 *u, dh_vec4_f32 *v);

/**
 * @brief v = (x/w, y/w, z/w) with (x, y, z, w) = T*u (full product):
 *        a homogeneous point, e.g. through a perspective transform (eq. 1.128).
 * Each component is one correctly rounded division of the computed product;
 * a zero result is returned as +0. Error: test_mat4_props asserts <= 4 *
 * 2^-24 * (the row sums of |T||u| divided by |w|).
 * @return DH_OK; DH_ERR_DOMAIN if w == 0 (point at infinity);
 *         DH_ERR_NAN if T or u holds a NaN/Inf; DH_ERR_OVERFLOW if the
 *         inputs are finite but the result is not. v untouched on error.
 */
dh_status dh_mat4_apply_point_h_f32(const dh_mat4_f32 *T, const dh_vec4_f32 *u, dh_vec3_f32 *v);

/**
 * @brief Q = P * T^-1 (eq. 1.21): the plane P carried along with the points
 * moved by T, so that Q*(T*u) == P*u (eq. 1.22). The inverse is taken as
 * dh_mat4_inv_auto_f32 takes it (closed form for rigid T, else the general
 * inverse with the same decision), into one 4x4 temporary. Invariance:
 * test_mat4_props asserts |Q v - P u| <= 28 * 2^-24 * |P| (|u|_1 + 1) on
 * rigid and scaled-rigid T.
 * DH_SMALL=1: the general (certified) inverse for every T, rigid or not:
 * the same statuses; values within the general inverse's bound, or, for a
 * T that is rigid only within DH_MAT4_RIGID_TOL, within the distance
 * between that inverse and the closed form.
 * @return DH_OK; DH_ERR_NAN (T or P not finite), DH_ERR_SINGULAR,
 *         DH_ERR_OVERFLOW as dh_mat4_inv_f32. Q untouched on error.
 */
dh_status dh_mat4_apply_plane_f32(const dh_mat4_f32 *T, const dh_plane_f32 *P, dh_plane_f32 *Q);

/**
 * @brief Q = P * Tinv (row vector times matrix) where the caller already
 * holds the inverse. P and Q may alias. Cannot fail.
 */
void dh_plane_mul_f32(const dh_plane_f32 *P, const dh_mat4_f32 *Tinv, dh_plane_f32 *Q);

/**
 * @brief v[i] = R*u[i] + p for i < count (dh_mat4_apply_point_f32 on each).
 * u and v may be the same array (in-place); otherwise they must not
 * overlap. count == 0 does nothing (u, v may then be NULL).
 */
void dh_mat4_apply_points_f32(const dh_mat4_f32 *T, const dh_vec3_f32 *u, dh_vec3_f32 *v, size_t count);

/* ======================================================================
 * Inverses
 * ==================================================================== */

/**
 * @brief Closed-form inverse of a rigid transform (eq. 1.57):
 * out = [R^T, -R^T p; 0 0 0 1]. Rigidity is NOT checked (use
 * dh_mat4_check_rigid_f32 or dh_mat4_inv_auto_f32); the bottom row of T is
 * not read. out may alias T. The translation is computed as 0 - (p . n)
 * etc., so it never holds -0. The rotation part is exact (a transpose);
 * error vs the exact inverse of T: test_mat4_props asserts <= 4.5 * 2^-24
 * * (1 + |p|_1).
 * Cannot fail.
 */
void dh_mat4_inv_rigid_f32(const dh_mat4_f32 *T, dh_mat4_f32 *out);

/**
 * @brief General 4x4 inverse with a scale-invariant, proven singularity
 *        test (cond and E: see DH_MAT4_COND_MAX).
 *
 * DH_OK needs a computed estimate of cond below DH_MAT4_COND_MAX and a
 * right residual ||B X_B - I||_1 <= 1/2 (X_B the computed B^-1), which
 * proves T non-singular: a singular T is never DH_OK. A T with cond below
 * DH_MAT4_COND_MAX / 2 is never DH_ERR_SINGULAR. Both tests are made on
 * one float matrix that is the same for T and every exact 2^k T, so their
 * statuses differ only where one of them is DH_ERR_OVERFLOW. The status
 * does not depend on the path or the build (DH_SMALL: values may differ
 * in the last bits, within the bound).
 *
 * Accuracy (DH_OK): max|E (X - T^-1) E^-1| <= 5 cond 2^-24 max|E T^-1 E^-1|
 * (affine-type T: that for the R^-1 block, for 1 / w relative to itself,
 * the translation within 5 cond 2^-24 max|R^-1| |p|_1 / |w|), plus 2^-147
 * absolute where elements underflow. The factor 5 is not proven: it is the
 * bound test_mat4_inv_regress asserts (measured: docs/accuracy_mat4.md).
 * Integer / 0 / +-1 transforms invert exactly. Zero results are +0.
 *
 * @return DH_OK; DH_ERR_NAN if any element is NaN/Inf;
 *         DH_ERR_SINGULAR if not accepted as above, or max|T_ij| < FLT_MIN
 *         (affine-type T: max|R_ij|);
 *         DH_ERR_OVERFLOW if an element of T^-1 exceeds FLT_MAX (or is
 *         within the error bound of it), for affine-type T also if a sum
 *         |R^-1_i0 p_0| + |R^-1_i1 p_1| + |R^-1_i2 p_2| over |w| does, or if
 *         elements falling below FLT_MIN could raise the balanced residual
 *         by more than 2^-4 (only for max|T_ij| >= 2^78).
 *         out untouched on error; may alias T.
 */
dh_status dh_mat4_inv_f32(const dh_mat4_f32 *T, dh_mat4_f32 *out);

/**
 * @brief Rotation part of T orthonormal with det +1, within @p tol.
 * @param T matrix to check (not NULL)
 * Criterion: |n.n - 1|, |o.o - 1|, |a.a - 1|, |n.o|, |n.a|, |o.a| <= tol and
 * n . (o x a) > 0. p and the bottom row are not examined.
 * @param tol tolerance, finite and >= 0 (e.g. 1e-5f for float data).
 * @return DH_OK; DH_ERR_NOT_RIGID; DH_ERR_NAN if an entry of R is NaN/Inf;
 *         DH_ERR_ARG if tol is negative or NaN.
 */
dh_status dh_mat4_check_rot_f32(const dh_mat4_f32 *T, float tol);

/**
 * @brief T is a rigid transform within @p tol: every element finite, the
 *        bottom row exactly 0 0 0 1, and the rotation part accepted by
 *        dh_mat4_check_rot_f32(T, tol).
 * @return DH_OK; DH_ERR_NOT_RIGID; DH_ERR_NAN if any element is NaN/Inf;
 *         DH_ERR_ARG if tol is negative or NaN.
 */
dh_status dh_mat4_check_rigid_f32(const dh_mat4_f32 *T, float tol);

/**
 * @brief out = T^-1: the closed-form rigid inverse when
 *        dh_mat4_check_rigid_f32(T, DH_MAT4_RIGID_TOL) accepts T, else
 *        dh_mat4_inv_f32.
 * The closed form returns R^T and -R^T p, which for a T that is rigid only
 * within the tolerance are not R^-1 and -R^-1 p: with R^T R = I + F,
 * |F_ij| <= 1e-5 (plus rounding), ||R^T - R^-1||_2 <= 3 |F|max (1 + 5e-5),
 * so every element satisfies |out - T^-1| <= 3.1e-5 (1 + |p|_1) (about
 * 520 2^-24; for an orthonormal R the rigid inverse's rounding alone).
 * Callers that need dh_mat4_inv_f32's accuracy on such input call it.
 * @return as dh_mat4_inv_f32 (DH_ERR_NAN, DH_ERR_SINGULAR, DH_ERR_OVERFLOW);
 *         out untouched on error; out may alias T.
 */
dh_status dh_mat4_inv_auto_f32(const dh_mat4_f32 *T, dh_mat4_f32 *out);

/* ---- misc ---- */
/**
 * @brief Whether every element of T is finite.
 * @return DH_OK if every element is finite; DH_ERR_NAN if one is NaN or
 *         +-Inf. No other status.
 */
dh_status dh_mat4_check_finite_f32(const dh_mat4_f32 *T);

#ifdef __cplusplus
}
#endif

#endif /* DHMATH_MAT4_H */
