/**
 * @file dh_mat4.h
 * @brief Float 4x4 homogeneous transforms (seed 000): constructors,
 *        composition, application to points/directions/planes, inverses,
 *        equivalent angle and axis.
 *
 * Conventions (seed 000, eq. 1.20, 1.56):
 * - a transform T has the columns n, o, a, p; points are columns and are
 *   mapped as v = T*u; planes are rows and are mapped as Q = P*T^-1;
 * - storage is column-major, element (row r, column c) is T->m[c][r]
 *   (DH_M4(T, r, c)), so n, o, a, p are each four contiguous floats;
 * - angles are in DEGREES (any finite value; the rotation constructors use
 *   dh_sincos_f32, so whole multiples of 90 give exact 0 and +-1);
 * - lengths are in the caller's unit, unchanged.
 *
 * Pointers must not be NULL (checked with DH_ASSERT). Unless a contract
 * says otherwise, outputs may alias inputs (the same object; partial
 * overlap of different objects is not allowed), and on a non-OK status
 * every output is left untouched.
 *
 * Accuracy figures quoted below were measured against double-precision
 * references (test/test_mat4_props.c, docs/accuracy_mat4.md).
 * All functions are float-only, reentrant, use no heap and at most 256
 * bytes of stack.
 */
#ifndef DHMATH_DH_MAT4_H
#define DHMATH_DH_MAT4_H

#include "dhmath/dh_common.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * Condition-number limit of dh_mat4_inv_f32: a matrix whose (balanced,
 * 1-norm) condition number, estimated as ||T|| * ||X|| with X the computed
 * inverse, is at least this value is reported as DH_ERR_SINGULAR (see the
 * method in dh_mat4_inv_f32). 2^19 = 524288: above it a float inverse
 * keeps fewer than about two correct decimal digits (measured relative
 * error <= 3.1 * cond * 2^-24).
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
void dh_mat4_trans_f32(dh_mat4_f32 *T, float x, float y, float z);

/**
 * @brief T = Rot(x, deg) (eq. 1.32): rows (1 0 0), (0 c -s), (0 s c).
 * @param T output (untouched on error)
 * @param deg angle in degrees, any finite value.
 * @return DH_OK; DH_ERR_NAN if deg is NaN or infinite (T untouched).
 * The entries are exactly dh_sincos_f32(deg) and 0 - s (so no -0 appears:
 * Rot(x, 0) is bitwise the identity; multiples of 90 are exact).
 */
dh_status dh_mat4_rotx_f32(dh_mat4_f32 *T, float deg);

/** @brief T = Rot(y, deg) (eq. 1.33): rows (c 0 s), (0 1 0), (-s 0 c). Same contract as rotx. */
dh_status dh_mat4_roty_f32(dh_mat4_f32 *T, float deg);

/** @brief T = Rot(z, deg) (eq. 1.34): rows (c -s 0), (s c 0), (0 0 1). Same contract as rotx. */
dh_status dh_mat4_rotz_f32(dh_mat4_f32 *T, float deg);

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
 * Accuracy (random unit axes of any length 1e-30..1e30, random non-integer
 * angles in [-720, 720]): max |entry - exact| measured 2.9e-7 (4.8 * 2^-24);
 * for a coordinate axis (any positive length) it is bitwise Rot(x|y|z, deg).
 * No -0 entries. Stack: 72 B (Cortex-M0+), 40 B (M4).
 */
dh_status dh_mat4_rot_axis_f32(dh_mat4_f32 *T, float kx, float ky, float kz, float deg);

/**
 * @brief T = diag(sx, sy, sz, 1) (eq. 1.113). Values stored as given. Cannot fail.
 */
void dh_mat4_scale_f32(dh_mat4_f32 *T, float sx, float sy, float sz);

/**
 * @brief Perspective transform along an axis (eq. 1.127 for the y axis):
 *        identity with -1/f in the bottom row, in the column of the axis,
 *        so a point u maps to w = 1 - u_axis / f.
 * @param T output (untouched on error)
 * @param axis 0 = x, 1 = y, 2 = z.
 * @param f focal length (any finite non-zero value; the seed uses f > 0).
 * @return DH_OK; DH_ERR_ARG if axis is not 0..2; DH_ERR_NAN if f is NaN/Inf;
 *         DH_ERR_DOMAIN if f == 0 or |1/f| overflows (|f| < 2^-128).
 *         T untouched on error.
 */
dh_status dh_mat4_persp_f32(dh_mat4_f32 *T, int axis, float f);

/**
 * @brief T = [n o a p; 0 0 0 1] (eq. 1.56). The vectors are copied as given
 * (no orthonormality check; see dh_mat4_check_rigid_f32). Cannot fail.
 */
void dh_mat4_from_noap_f32(dh_mat4_f32 *T, const dh_vec3_f32 *n, const dh_vec3_f32 *o,
                           const dh_vec3_f32 *a, const dh_vec3_f32 *p);

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
 * |err_rc| <= 4 * 2^-24 * sum_k |A_rk||B_kc| a priori (measured 2.9 * 2^-24
 * * sum). Straight-line, column by column on whole 4-float columns (SSE2
 * vector code on x86-64 at -O2). Stack (own frame + soft-float calls):
 * 176 B (M0+ -O2), 96 B (M4F -O2).
 */
void dh_mat4_mul_f32(dh_mat4_f32 *out, const dh_mat4_f32 *A, const dh_mat4_f32 *B);

/**
 * @brief out = A * B for affine transforms: the bottom rows of A and B are
 * IGNORED (taken as 0 0 0 1; their values, even NaN, do not affect the
 * result) and the bottom row of out is written 0 0 0 1.
 * Same rounding and bound as dh_mat4_mul_f32 on affine inputs, and the same
 * values when the inputs' bottom rows are exactly 0 0 0 1 (zeros may differ
 * in sign). x86-64 GCC 12 -O2: 72 instructions (cglm glm_mul: about 60).
 * Stack: 160 B (M0+ -O2, incl. soft-float calls), 88 B (M4F).
 */
void dh_mat4_mul_affine_f32(dh_mat4_f32 *out, const dh_mat4_f32 *A, const dh_mat4_f32 *B);

/**
 * @brief T = X * T (pre-multiplication, full product): the motion X is
 * expressed in the BASE (reference) frame (seed sec. 9, eq. 1.50).
 */
void dh_mat4_premul_f32(dh_mat4_f32 *T, const dh_mat4_f32 *X);

/**
 * @brief T = T * X (post-multiplication, full product): the motion X is
 * expressed in T's own (current) frame (seed sec. 9, eq. 1.51).
 */
void dh_mat4_postmul_f32(dh_mat4_f32 *T, const dh_mat4_f32 *X);

/* ======================================================================
 * Application. u and v may be the same object. Cannot fail unless a
 * status is returned.
 * ==================================================================== */

/**
 * @brief v = R*u + p: a point (w = 1) through an affine T (bottom row not
 * read). Error per component <= 4 * 2^-24 * (sum |R_ij u_j| + |p_i|) a priori
 * (measured 2.8 * 2^-24 * that sum).
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
 * a zero result is returned as +0. Measured error <= 1.9 * 2^-24 * (the row
 * sums of |T||u| divided by |w|).
 * @return DH_OK; DH_ERR_DOMAIN if w == 0 (point at infinity);
 *         DH_ERR_NAN if T or u holds a NaN/Inf; DH_ERR_OVERFLOW if the
 *         inputs are finite but the result is not. v untouched on error.
 */
dh_status dh_mat4_apply_point_h_f32(const dh_mat4_f32 *T, const dh_vec4_f32 *u, dh_vec3_f32 *v);

/**
 * @brief Q = P * T^-1 (eq. 1.21): the plane P carried along with the points
 * moved by T, so that Q*(T*u) == P*u (eq. 1.22). The inverse is taken as
 * dh_mat4_inv_auto_f32 takes it (closed form for rigid T, else the general
 * inverse with the same decision), into one 4x4 temporary. Measured
 * invariance |Q v - P u| <= 13.5 * 2^-24 * |P| (|u|_1 + 1) on rigid and
 * scaled-rigid T. Stack (worst case incl. soft-float calls): 240 B (M0+
 * -Os/-O2), 156 B (M4F -O2).
 * DH_SMALL=1: the general (certified) inverse for every T, rigid or not:
 * the same statuses, values within the general inverse's bound; stack
 * 256 B (M0+ -Os).
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
 * measured error of the whole vs the exact inverse of T
 * <= 2.3 * 2^-24 * (1 + |p|_1). Cannot fail. x86-64 GCC 12 -O2: 54
 * instructions (scalar; plain C gives the compiler no transpose shuffles).
 * Stack: 96 B (M0+ incl. soft-float calls), 0 B (M4F).
 */
void dh_mat4_inv_rigid_f32(dh_mat4_f32 *out, const dh_mat4_f32 *T);

/**
 * @brief General 4x4 inverse with a scale-invariant, proven singularity
 *        test.
 *
 * Fast paths (no residual needed): they accept a matrix only when a cheap
 * bound PROVES its 2-norm condition number <= 2^16 (hence its 1-norm
 * condition <= 2^18 = DH_MAT4_COND_MAX / 2, which the certified criterion
 * below accepts as well, so the decision does not depend on the path):
 * - affine T (bottom row exactly 0 0 0 1): R^-1 from the cross products of
 *   the columns of R (adjugate), -R^-1 p; accepted iff det(R)^2 2^32 >=
 *   ||R||_F^6, from cond_2(R) <= ||R||_F^3 / |det R| (Hadamard's inequality
 *   on the cofactors). R is rescaled by an exact power of two first when
 *   ||R||_F^2 is outside [2^-24, 2^24], so the test and the result are
 *   invariant under any scaling of R (the R^-1 block scales exactly); p
 *   (its length unit) does not enter the test;
 * - other T: 4x4 adjugate from 2x2 minors; accepted iff
 *   4 det^2 2^32 >= S^4, S >= ||B||_F^2 of the balanced B = D T D^-1,
 *   D = diag(1, 1, 1, sg), sg^2 = |p| / |q|, i.e. p / sg and q sg
 *   (cond_2(B) <= S^2 / (2 |det|);
 *   S is formed as ||R||_F^2 + 2 |p|_1 |q|_1 + w^2, independent of the
 *   length unit), with S in [2^-16, 2^16] and |p|_1, |q|_1 <= 2^28.
 * For a singular matrix the computed determinant is rounding noise, far
 * below those bounds: a matrix rank-deficient before rounding to float
 * never passes.
 *
 * Certified path (everything else: ill-conditioned, singular, extreme
 * magnitudes): the matrix M = s T (s an exact power of two bringing
 * max|T_ij| into [1, 2) when it is outside [2^-16, 2^17)), or for affine T
 * M = blockdiag(s R, 1) with max|s R_ij| in [1, 2), is balanced by the
 * power of two nearest to sg (exact) and inverted by Gauss-Jordan with
 * partial pivoting (X non-finite -> DH_ERR_SINGULAR), then
 *   (a) cond = ||M|| * ||X|| >= DH_MAT4_COND_MAX -> DH_ERR_SINGULAR;
 *   (b) right residual ||M X - I|| > 1/2 -> DH_ERR_SINGULAR. (b) is a
 *       proof: a residual <= 1/2 implies M non-singular and
 *       ||M^-1|| <= 2||X||, ||X - M^-1|| <= ||M^-1|| / 2; for a singular M
 *       the residual is >= 1 whatever X is. The proof covers T itself
 *       (entries of T that underflow in s T change the residual by less
 *       than 2^-9) and the returned s X (see DH_ERR_OVERFLOW). The left
 *       residual X T - I is not bounded by it: near the condition limit it
 *       can exceed 1 for an inverse within the accuracy below (it is up to
 *       cond times the right one).
 * Norms: the 1-norm of the balanced D M D^-1, D = diag(1,1,1,sg),
 * sg = sqrt(|p|_1 / |q|_1) (p = column 3, q = bottom row, diagonal
 * excluded; 1 for affine M); when q = 0 (p = 0 exactly) sg makes p (q)
 * 2^-24 of the rows of R, so [R p; 0 w] and [R 0; q^T w] are judged like
 * blockdiag(R, w): e.g. dh_mat4_persp_f32 with any focal distance down to
 * 1e-12 inverts, exactly, at every scale (with p = 0 the bottom row of
 * the inverse is exact by the elimination's structure; the proof (b)
 * weights it by sg). Both tests are invariant under T -> 2^k T
 * (and the affine ones under R -> c R for any c); a rigid transform with
 * |p| = 1e6 is accepted like one with |p| = 1.
 *
 * Measured (test_mat4_props, 10 seeds; docs/accuracy_mat4.md): matrices
 * rank 3 or 2 rounded to float, scaled by 1e-20..1e20, are always reported;
 * matrices with cond up to 8.8e4 at any scale 1e-20..1e20 always invert,
 * with max |X - T^-1| <= 3.1 * cond * 2^-24 * max|T^-1| (fast paths
 * alone: <= 4.8 * cond * 2^-24, cond up to 1e3); rigid transforms invert
 * within 3.6 * 2^-24 * (1 + |p|_1); T and 2^k T (k in -40..40) always get
 * the same status. Integer / 0 / +-1 transforms such as the seed's invert
 * exactly. Zero results are +0. Extreme magnitudes (test_mat4_inv_regress,
 * 11 seeds x 20000 projective matrices, largest entries 2^60..2^127,
 * others down to 2^-140; and 10^6 more in a throwaway driver): every
 * DH_OK has a right residual <= 0.063 and
 * max |X - T^-1| <= 3.2 * cond * 2^-24 * max|T^-1| (cond: the smallest
 * 1-norm condition number of D T D^-1 over D = diag(1, 1, 1, 2^k)); no
 * matrix whose balanced condition number (as defined above) is below
 * 2^19 is reported singular.
 * Cost (x86-64 GCC 12 -O2, callgrind, incl. a call wrapper): about 230
 * instructions for affine input, 380 for a general one on the fast paths;
 * the certified path (singular or ill-conditioned input) about 2000.
 * DH_SMALL=1 (dh_config.h): no fast paths, the certified path decides and
 * computes every inverse (same statuses: the fast paths accept only what
 * it accepts); values within the bounds above, possibly differing from
 * the default build's fast-path results in the last bits; cost for a
 * rigid T on Cortex-M4F -Os: 7178 instructions against 166
 * (docs/performance_target.md, "-Os DH_SMALL").
 * Stack (worst case incl. soft-float calls): 248 B (M0+ -O2), 240 B
 * (M0+ -Os), 148 B (M4F -O2); DH_SMALL 248 B (M0+ -Os).
 *
 * @return DH_OK;
 *         DH_ERR_NAN if any element is NaN/Inf;
 *         DH_ERR_SINGULAR if singular by the criterion above, or
 *         max|T_ij| < FLT_MIN (zero or denormal matrix; for affine T:
 *         max|R_ij| < FLT_MIN);
 *         DH_ERR_OVERFLOW if an element of the inverse exceeds FLT_MAX
 *         (only possible for max|T_ij| below ~2^-100, or an affine T
 *         whose -R^-1 p overflows), or if elements of the inverse fall
 *         below FLT_MIN and the bits they lose (gradual underflow, <= 2^-150
 *         each) could raise the balanced residual of the returned matrix
 *         by more than 2^-4 (only for non-affine T with max|T_ij| >= 2^17
 *         and a strongly unbalanced last row/column; measured: 16 of
 *         10^6 random matrices with entries up to 2^127, all with
 *         max|T_ij| > 2^120 and |p|_1 / |q|_1 outside [2^-39, 2^39]).
 *         Subnormal elements
 *         that pass this test, and those of the affine and fast paths,
 *         carry an absolute error of at most 2^-150 besides the relative
 *         error quoted above (it matters only when max|T_ij| > 2^100).
 *         out untouched on error. out may alias T.
 */
dh_status dh_mat4_inv_f32(dh_mat4_f32 *out, const dh_mat4_f32 *T);

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
 * @return as dh_mat4_inv_f32 (DH_ERR_NAN, DH_ERR_SINGULAR, DH_ERR_OVERFLOW);
 *         out untouched on error; out may alias T.
 * Stack (worst case incl. soft-float calls): 256 B (M0+ -O2), 248 B (M0+
 * -Os), 164 B (M4F -O2).
 */
dh_status dh_mat4_inv_auto_f32(dh_mat4_f32 *out, const dh_mat4_f32 *T);

/* ======================================================================
 * Equivalent angle and axis (seed sec. 13)
 * ==================================================================== */

/**
 * @brief Rotation part R of T -> unit axis k and angle theta in [0, 180]
 *        degrees with R = Rot(k, theta) (eq. 1.73).
 *
 * Algorithm (seed sec. 13, robust form): 2 cos(theta) = trace - 1 (eq.
 * 1.76) and 2 sin(theta) = |d| with d = (o_z - a_y, a_x - n_z, n_y - o_x)
 * (eq. 1.81); theta from atan2 of the two, evaluated in one of three
 * octant forms so that 90 and 180 come out exact. For theta <= 90, k = d/|d|
 * (eq. 1.83-1.85, renormalised). For theta > 90, the component of k of the
 * largest diagonal element is taken from eq. 1.92-1.94 (sign of d) and the
 * other two from the pair sums eq. 1.95-1.103, then k is normalised; this
 * stays accurate up to and at 180 degrees.
 *
 * Special cases: theta == 0 (d == 0 and trace == 3) returns k = (0, 0, 1),
 * theta = 0. At theta == 180 exactly (d == 0), k and -k describe the same
 * rotation; the one whose largest-diagonal component is positive is
 * returned. Example 1.1 (eq. 1.104) gives theta = 120 exactly and
 * k = (1, 1, 1) * 0.57735026 (1/sqrt(3) within 1 ulp).
 * Accuracy (random unit k; theta uniform in [0, 180], within 1e-3 deg of 0
 * and of 180, and around 90; the float-rounded Rot(k, theta) as input),
 * measured over 10 seeds: |theta error| <= 1.5e-5 deg; max |Rot(k_out,
 * theta_out) - R| <= 5.0e-7 (8.3 * 2^-24); |k - k_exact| <= 2.4e-7 for
 * theta >= 1 deg; below 1 deg the axis is physically ill defined and
 * |k - k_exact| * theta_rad <= 1.9e-9; ||k| - 1| <= 1.6e-7.
 * Stack: 80 B (M4, M0+).
 *
 * @param T transform; only the rotation part is read.
 * @param k output unit axis.
 * @param theta_deg output angle in degrees, 0 <= theta <= 180.
 * @return DH_OK; DH_ERR_NAN if an entry of R is NaN/Inf; DH_ERR_NOT_RIGID if
 *         R is not a rotation within DH_MAT4_AXIS_TOL (see
 *         dh_mat4_check_rot_f32). k and theta untouched on error.
 */
dh_status dh_mat4_to_axis_angle_f32(const dh_mat4_f32 *T, dh_vec3_f32 *k, float *theta_deg);

/* ---- misc ---- */
/** @brief 1 if every element of T is finite, else 0. Cannot fail. */
int dh_mat4_isfinite_f32(const dh_mat4_f32 *T);

#ifdef __cplusplus
}
#endif

#endif /* DHMATH_DH_MAT4_H */
