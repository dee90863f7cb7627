/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Index: the functions of rot.h by source file (src/rot/).
 *   dh_euler.c       dh_euler_parse, dh_euler_name, dh_euler_to_mat3_f32,
 *                    dh_mat3_to_euler_f32
 *   dh_quat.c        dh_quat_to_mat3_f32, dh_mat3_to_quat_f32,
 *                    dh_quat_normalize_f32, dh_quat_mul_f32, dh_quat_conj_f32,
 *                    dh_quat_from_axis_angle_f32
 *   dh_axis_angle.c  dh_mat4_to_axis_angle_f32, dh_axis_angle_to_mat3_f32,
 *                    dh_mat3_to_axis_angle_f32
 *   dh_rotvec.c      dh_rotvec_to_mat3_f32, dh_mat3_to_rotvec_f32
 *   dh_mat3.c        dh_skew_f32, dh_vee_f32, dh_angvel_f32,
 *                    dh_angvel_body_f32, dh_mat3_check_rot_f32,
 *                    dh_mat3_orthonormalize_f32
 *   dh_rot_q.c       dh_frame_to_euler_q, dh_euler_to_frame_q,
 *                    dh_frame_to_quat_q, dh_quat_to_frame_q,
 *                    dh_frame_to_axis_angle_q
 *   dh_frame_conv.c  dh_frame_from_mat4_q, dh_frame_to_mat4_q
 */
/**
 * @file rot.h
 * @brief Float rotation conversions: Euler angles (all 12 sequences,
 *        intrinsic and extrinsic), unit quaternions, angle-axis, rotation
 *        vector (log / exp maps), skew-symmetric matrices, angular velocity
 *        and re-orthonormalisation of a drifted rotation matrix.
 *
 * Conventions:
 * - a rotation is a dh_mat3_f32, column-major (element row r, column c is
 *   R->m[c][r], read it with DH_M3(R, r, c)); vectors are columns, v' = R v;
 * - Rx(t), Ry(t), Rz(t) are the elementary rotations of Paul 1981 (eq.
 *   1.32-1.34), right-handed: Rz(t) has rows (c -s 0), (s c 0), (0 0 1);
 * - angles at the API are in DEGREES, except the rotation vector of the
 *   log / exp maps and the angular velocity, which are in RADIANS (rad and
 *   rad/s: the physical convention, as the Jacobian of kin.h);
 * - degree -> matrix conversions use dh_sincos_f32, so multiples of 90
 *   degrees give exact 0 and +-1 entries;
 * - matrix -> parameter conversions ("extraction") first check their input:
 *   DH_ERR_NAN if any entry is NaN or infinite, else DH_ERR_NOT_RIGID if
 *   dh_mat3_check_rot_f32(R, DH_ROT_TOL) rejects it (not orthonormal within
 *   1e-4, or a reflection). A matrix accepted within the tolerance is used
 *   as it is (it is not re-orthonormalised first; call
 *   dh_mat3_orthonormalize_f32 for that).
 *
 * Pointers must not be NULL (checked with DH_ASSERT). Unless a contract
 * says otherwise, outputs may alias inputs of the same type (the same
 * object; partial overlap of different objects is not allowed), and on a
 * non-OK status every output is left untouched.
 *
 * All functions are float-only (no double arithmetic, no libm),
 * reentrant, use no heap and less than 256 bytes of stack. "Entry error"
 * means max |R_ij - R_ij(exact)| over the nine entries; bounds are against
 * the exact result for the given float inputs. Measured accuracy:
 * docs/accuracy_rot.md; cost and stack: docs/generated/performance_target.md,
 * docs/generated/footprint.md; methods: docs/design.md ("Rotations").
 */
#ifndef DHMATH_ROT_H
#define DHMATH_ROT_H

#include "dhmath/common.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * Orthonormality tolerance of every extraction function of this header:
 * R is accepted when every entry of R^T R - I is within DH_ROT_TOL and
 * det R > 0 (the same value as DH_MAT4_AXIS_TOL of mat4.h).
 */
#define DH_ROT_TOL 1e-4f

/**
 * Gimbal-lock threshold of dh_mat3_to_euler_f32: the sequence is treated as
 * being at its pole when the cosine (Tait-Bryan) or sine (proper Euler) of
 * the middle angle, as measured from the matrix, is at most this value
 * (2^-22: the middle angle within 1.4e-5 degrees of the pole).
 */
#define DH_EULER_POLE_TOL 2.384185791015625e-7f

/**
 * Largest deviation max |(R^T R - I)_ij| accepted by
 * dh_mat3_orthonormalize_f32 (beyond it the matrix is not considered a
 * drifted rotation and DH_ERR_NOT_RIGID is returned).
 */
#define DH_ROT_ORTHO_MAX_DEV 0.25f

/* ======================================================================
 * Euler angles
 * ==================================================================== */

/**
 * @brief Euler angle sequence, named as in scipy.spatial.transform.Rotation.
 *
 * Upper case = INTRINSIC (rotations about the axes of the moving frame,
 * each applied after the previous one, i.e. post-multiplied): for the
 * angles (a, b, c) given in the order of the letters,
 *   "XYZ": R = Rx(a) Ry(b) Rz(c)   (the Cardan angles common in robotics).
 * Lower case = EXTRINSIC (rotations about the fixed axes of the reference
 * frame, each pre-multiplied): angles again in the order of the letters,
 *   "xyz": R = Rz(c) Ry(b) Rx(a),
 * so "xyz" with (a, b, c) is the same matrix as "ZYX" with (c, b, a).
 *
 * Tait-Bryan sequences use three different axes, proper Euler sequences
 * repeat the first axis as the third. The numeric values are part of the
 * API: 0..5 intrinsic Tait-Bryan, 6..11 intrinsic proper, 12..23 the
 * extrinsic ones in the same order.
 */
typedef enum {
    DH_EULER_XYZ = 0,  /**< intrinsic, R = Rx(a) Ry(b) Rz(c) */
    DH_EULER_XZY = 1,  /**< intrinsic, R = Rx(a) Rz(b) Ry(c) */
    DH_EULER_YXZ = 2,  /**< intrinsic, R = Ry(a) Rx(b) Rz(c) */
    DH_EULER_YZX = 3,  /**< intrinsic, R = Ry(a) Rz(b) Rx(c) */
    DH_EULER_ZXY = 4,  /**< intrinsic, R = Rz(a) Rx(b) Ry(c) */
    DH_EULER_ZYX = 5,  /**< intrinsic, R = Rz(a) Ry(b) Rx(c) (yaw, pitch, roll) */
    DH_EULER_XYX = 6,  /**< intrinsic, R = Rx(a) Ry(b) Rx(c) */
    DH_EULER_XZX = 7,  /**< intrinsic, R = Rx(a) Rz(b) Rx(c) */
    DH_EULER_YXY = 8,  /**< intrinsic, R = Ry(a) Rx(b) Ry(c) */
    DH_EULER_YZY = 9,  /**< intrinsic, R = Ry(a) Rz(b) Ry(c) */
    DH_EULER_ZXZ = 10, /**< intrinsic, R = Rz(a) Rx(b) Rz(c) */
    DH_EULER_ZYZ = 11, /**< intrinsic, R = Rz(a) Ry(b) Rz(c) */
    DH_EULER_xyz = 12, /**< extrinsic, R = Rz(c) Ry(b) Rx(a) */
    DH_EULER_xzy = 13, /**< extrinsic, R = Ry(c) Rz(b) Rx(a) */
    DH_EULER_yxz = 14, /**< extrinsic, R = Rz(c) Rx(b) Ry(a) */
    DH_EULER_yzx = 15, /**< extrinsic, R = Rx(c) Rz(b) Ry(a) */
    DH_EULER_zxy = 16, /**< extrinsic, R = Ry(c) Rx(b) Rz(a) */
    DH_EULER_zyx = 17, /**< extrinsic, R = Rx(c) Ry(b) Rz(a) */
    DH_EULER_xyx = 18, /**< extrinsic, R = Rx(c) Ry(b) Rx(a) */
    DH_EULER_xzx = 19, /**< extrinsic, R = Rx(c) Rz(b) Rx(a) */
    DH_EULER_yxy = 20, /**< extrinsic, R = Ry(c) Rx(b) Ry(a) */
    DH_EULER_yzy = 21, /**< extrinsic, R = Ry(c) Rz(b) Ry(a) */
    DH_EULER_zxz = 22, /**< extrinsic, R = Rz(c) Rx(b) Rz(a) */
    DH_EULER_zyz = 23  /**< extrinsic, R = Rz(c) Ry(b) Rz(a) */
} dh_euler_seq;

/** Number of dh_euler_seq values (valid values are 0 .. DH_EULER_COUNT-1). */
#define DH_EULER_COUNT 24

/**
 * @brief Parse a sequence name such as "XYZ", "zyz" (scipy spelling).
 * @param str exactly three letters followed by the terminating NUL, all
 *        from {X, Y, Z} (intrinsic) or all from {x, y, z} (extrinsic), with
 *        no letter equal to the one before it (so "XYX" is valid, "XXY" and
 *        "XyZ" are not). Read only up to the first mismatch or the 4th char.
 * @param seq output sequence.
 * @return DH_OK; DH_ERR_ARG for any other string (seq untouched).
 */
dh_status dh_euler_parse(const char *str, dh_euler_seq *seq);

/**
 * @brief Name of a sequence ("XYZ", "zyz", ...), the inverse of
 *        dh_euler_parse. Never NULL: an out-of-range value gives "???",
 *        which dh_euler_parse rejects.
 */
const char *dh_euler_name(dh_euler_seq seq);

/**
 * @brief R = rotation of the Euler angles @p ang_deg in sequence @p seq
 *        (see dh_euler_seq for the product of each sequence).
 * @param R output rotation.
 * @param seq sequence, 0 .. DH_EULER_COUNT-1.
 * @param ang_deg angles (a, b, c) in degrees, in the order of the letters
 *        of the sequence name; any finite values (no range restriction).
 * @return DH_OK; DH_ERR_ARG if seq is out of range; DH_ERR_NAN if an angle
 *         is NaN or infinite. R untouched on error. ang_deg must not lie
 *         inside R.
 * Entries never hold -0; angles that are multiples of 90 give exact 0/+-1
 * entries (the result is then bitwise an exact signed permutation matrix).
 * Entry error <= 3e-7 for angles in [-360, 360].
 */
dh_status dh_euler_to_mat3_f32(dh_euler_seq seq, const float ang_deg[3], dh_mat3_f32 *R);

/**
 * @brief Euler angles of sequence @p seq of the rotation R: the inverse of
 *        dh_euler_to_mat3_f32.
 *
 * Output ranges (degrees, order of the letters):
 * - Tait-Bryan: first and third in (-180, 180], middle in [-90, 90];
 * - proper Euler: first and third in (-180, 180], middle in [0, 180].
 *
 * Gimbal lock: at the pole (middle angle +-90 Tait-Bryan, 0 / 180 proper)
 * only the sum or difference of the first and third angle is defined.
 * When the measured cosine (Tait-Bryan) or sine (proper) of the middle
 * angle is at most DH_EULER_POLE_TOL, the THIRD angle (in the order of the
 * letters, intrinsic and extrinsic alike, as scipy does) is exactly 0 and
 * the whole rotation about the locked axis is in the first. The status is
 * still DH_OK; a caller that needs to know can test the middle angle. Near
 * the pole the first and third angles are individually ill-conditioned,
 * but together they still reproduce R.
 *
 * Error bounds: the exact rotation of the returned angles reproduces R
 * within 6e-7 per entry everywhere, poles included; with the middle angle
 * at least 1 deg from a pole the angles are within 2.5e-5 deg of the exact
 * ones; near a pole the middle angle is within 1e-5 deg.
 *
 * @param R rotation; must pass dh_mat3_check_rot_f32(R, DH_ROT_TOL).
 * @param seq sequence, 0 .. DH_EULER_COUNT-1.
 * @param ang_deg output angles (a, b, c) in degrees; must not lie inside R.
 * @return DH_OK; DH_ERR_ARG if seq is out of range; DH_ERR_NAN if an entry
 *         of R is NaN/Inf; DH_ERR_NOT_RIGID if R is not a rotation within
 *         DH_ROT_TOL. ang_deg untouched on error.
 */
dh_status dh_mat3_to_euler_f32(const dh_mat3_f32 *R, dh_euler_seq seq, float ang_deg[3]);

/* ======================================================================
 * Quaternions
 * ==================================================================== */

/**
 * @brief Quaternion w + x i + y j + z k, scalar part FIRST in memory.
 * A unit quaternion (cos(t/2), sin(t/2) k) is the rotation by t about the
 * unit axis k (Hamilton convention, active rotation: v' = q v q*, the same
 * rotation as dh_axis_angle_to_mat3_f32(k, t)). q and -q are the same
 * rotation; the conversions from a matrix return the one with w >= 0.
 */
typedef struct {
    float w; /**< scalar part, cos(t/2) for a unit quaternion */
    float x; /**< i component, sin(t/2) k_x */
    float y; /**< j component, sin(t/2) k_y */
    float z; /**< k component, sin(t/2) k_z */
} dh_quat_f32;

/**
 * @brief R = rotation of the quaternion q.
 * @param R output rotation.
 * @param q any quaternion with finite components and a non-zero norm; it
 *        need not be unit: the rotation of q / |q| is returned (the formula
 *        divides by |q|^2, after an exact rescaling when the largest
 *        component is outside [2^-32, 2^32], so no overflow or underflow).
 * @return DH_OK; DH_ERR_NAN if a component is NaN/Inf; DH_ERR_ZERO_AXIS if
 *         max |component| < FLT_MIN (zero or denormal quaternion). R
 *         untouched on error.
 * Entry error <= 6e-7 against the exact rotation of the float q.
 */
dh_status dh_quat_to_mat3_f32(const dh_quat_f32 *q, dh_mat3_f32 *R);

/**
 * @brief Unit quaternion of the rotation R (Shepperd 1978; no division by
 *        a small number, no cancellation near 180 degrees).
 *
 * The result is normalised and its sign chosen so that w >= 0 (w is never
 * -0). At exactly 180 degrees (w == 0) the component chosen by the method,
 * that of the largest diagonal entry, is positive (the same axis as
 * dh_mat4_to_axis_angle_f32 and dh_mat3_to_axis_angle_f32 return).
 *
 * Error bounds: components within 2e-7 of the exact unit quaternion (up
 * to the sign ambiguity when |w| < 1e-6), | |q| - 1 | <= 2.4e-7.
 * @return DH_OK; DH_ERR_NAN; DH_ERR_NOT_RIGID (see file comment). q
 *         untouched on error.
 */
dh_status dh_mat3_to_quat_f32(const dh_mat3_f32 *R, dh_quat_f32 *q);

/**
 * @brief out = q / |q|, keeping the sign of q (no w >= 0 canonicalisation,
 *        so that a sequence of quaternions stays continuous).
 * Overflow/underflow free: the largest component is first scaled to about
 * 1, so any finite q with a normal largest component works (1e-30 and
 * 1e30 alike). Result: | |out| - 1 | <= 2.4e-7 and components within
 * 2e-7 of the exact q / |q|.
 * @return DH_OK; DH_ERR_NAN if a component is NaN/Inf; DH_ERR_ZERO_AXIS if
 *         max |component| < FLT_MIN (zero or denormal). out untouched on
 *         error; out may alias q.
 */
dh_status dh_quat_normalize_f32(const dh_quat_f32 *q, dh_quat_f32 *out);

/**
 * @brief out = a * b (Hamilton product): the rotation b followed by a,
 *        i.e. R(a*b) = R(a) R(b). No normalisation, no status (IEEE
 *        semantics: NaN/Inf propagate). out may alias a and/or b.
 * Error per component <= 4 * 2^-24 * sum |a_i b_j| (four products summed).
 */
void dh_quat_mul_f32(const dh_quat_f32 *a, const dh_quat_f32 *b, dh_quat_f32 *out);

/** @brief out = conjugate of q = (w, -x, -y, -z): the inverse rotation of a unit q. out may alias q. */
void dh_quat_conj_f32(const dh_quat_f32 *q, dh_quat_f32 *out);

/**
 * @brief q = (cos(t/2), sin(t/2) k) for the rotation by @p deg degrees about
 *        @p axis, with k = axis / |axis|.
 * The angle is not reduced, so the sign of w follows cos(deg/2): deg and
 * deg + 360 give q and -q (the same rotation).
 * @param q output quaternion.
 * @param axis any finite non-zero length (normalised here, overflow free).
 * @param deg angle in degrees, any finite value.
 * @return DH_OK; DH_ERR_NAN if an argument is NaN/Inf; DH_ERR_ZERO_AXIS if
 *         max |axis component| < FLT_MIN. q untouched on error.
 * Error bound: components within 2e-7 for |deg| <= 720.
 */
dh_status dh_quat_from_axis_angle_f32(const dh_vec3_f32 *axis, float deg, dh_quat_f32 *q);

/* ======================================================================
 * Equivalent angle and axis of a 4x4 (Paul 1981, "Equivalent Angle and Axis of Rotation")
 * ==================================================================== */

/**
 * @brief Rotation part R of T -> unit axis k and angle theta in [0, 180]
 *        degrees with R = Rot(k, theta) (eq. 1.73).
 *
 * The robust form of Paul 1981 (eq. 1.76, 1.81, 1.92-1.103;
 * method in docs/design.md): accurate at every angle up to and at 180
 * degrees; 90 and 180 come out exact.
 * Special cases: theta == 0 (d == 0 and trace == 3) returns k = (0, 0, 1),
 * theta = 0. At theta == 180 exactly, k and -k describe the same rotation;
 * the one whose largest-diagonal component is positive is returned.
 * Example 1.1 (eq. 1.104) gives theta = 120 exactly and k = (1, 1, 1) *
 * 0.57735026 (1/sqrt(3) within 1 ulp).
 * Bounds test_mat4_props asserts (float-rounded Rot(k, theta) as input):
 * |theta error| <= 3e-5 deg; |Rot(k_out, theta_out) - R| <= 17 * 2^-24 per
 * entry; |k - k_exact| <= 5e-7 for theta >= 1 deg (below, |k - k_exact| *
 * theta_rad <= 4e-9: the axis is ill defined); ||k| - 1| <= 3.1e-7.
 * Measured figures: docs/accuracy_mat4.md.
 *
 * @param T transform; only the rotation part is read.
 * @param k output unit axis.
 * @param theta_deg output angle in degrees, 0 <= theta <= 180.
 * @return DH_OK; DH_ERR_NAN if an entry of R is NaN/Inf; DH_ERR_NOT_RIGID if
 *         R is not a rotation within DH_MAT4_AXIS_TOL (see
 *         dh_mat4_check_rot_f32). k and theta untouched on error.
 */
dh_status dh_mat4_to_axis_angle_f32(const dh_mat4_f32 *T, dh_vec3_f32 *k, float *theta_deg);

/* ======================================================================
 * Angle-axis, rotation vector (log / exp), skew matrices
 * ==================================================================== */

/**
 * @brief R = Rot(k, deg), the rotation by @p deg degrees about the unit
 *        axis k = axis / |axis| (Rodrigues: R = c I + s [k]x + (1-c) k k^T,
 *        Paul 1981 eq. 1.70), s and c from dh_sincos_f32(deg).
 * A coordinate axis gives bitwise Rx/Ry/Rz(deg), with exact 0/+-1 entries
 * at multiples of 90.
 * @param R output rotation.
 * @param axis any finite non-zero length (normalised here, overflow free).
 * @param deg angle in degrees, any finite value.
 * @return DH_OK; DH_ERR_NAN if an argument is NaN/Inf; DH_ERR_ZERO_AXIS if
 *         max |axis component| < FLT_MIN. R untouched on error.
 * Entry error <= 4e-7 for |deg| <= 720.
 */
dh_status dh_axis_angle_to_mat3_f32(const dh_vec3_f32 *axis, float deg, dh_mat3_f32 *R);

/**
 * @brief Unit axis k and angle in [0, 180] degrees of the rotation R, with
 *        R = Rot(k, angle).
 *
 * This is exactly dh_mat4_to_axis_angle_f32 (Paul 1981 eq. 1.73-1.103, robust
 * form) applied to R: the same algorithm, results and special cases, for a
 * 3x3 input. At 0 degrees k = (0, 0, 1); at exactly 180 degrees k and -k
 * are the same rotation and the one whose component of the largest
 * diagonal entry is positive is returned; 90 and 180 are exact.
 * Error bounds, near 0 and at 180 degrees too: R reproduced within 3e-7
 * per entry, the angle within 2e-5 deg.
 * @param R rotation; must pass dh_mat3_check_rot_f32(R, DH_ROT_TOL).
 * @param axis output unit axis.
 * @param deg output angle in degrees, 0 <= deg <= 180.
 * @return DH_OK; DH_ERR_NAN; DH_ERR_NOT_RIGID (see file comment). axis and
 *         deg untouched on error.
 */
dh_status dh_mat3_to_axis_angle_f32(const dh_mat3_f32 *R, dh_vec3_f32 *axis, float *deg);

/**
 * @brief Exponential map: R = exp([phi]x), the rotation by |phi| RADIANS
 *        about phi / |phi| (phi = 0 gives exactly I).
 * No cancellation for small t = |phi| and no overflow for large
 * components (method: docs/design.md).
 * @param R output rotation.
 * @param phi rotation vector in radians, any finite value whose length
 *        |phi| is also finite (not reduced: a length above 2 pi simply
 *        wraps).
 * @return DH_OK; DH_ERR_NAN if a component is NaN/Inf, and also when the
 *         components are finite but |phi| exceeds FLT_MAX (e.g. FLT_MAX in
 *         two components: the angle has no float value). R untouched on
 *         error.
 * Entry error <= 4e-7 for |phi| <= 4 pi (down to 1e-30), and for larger
 * lengths that are exact in float (an axis-aligned phi); |phi| itself is
 * carried to about 2^-44 relative (method: docs/design.md).
 */
dh_status dh_rotvec_to_mat3_f32(const dh_vec3_f32 *phi, dh_mat3_f32 *R);

/**
 * @brief Logarithm map: rotation vector phi = t k (RADIANS) of R, with
 *        t in [0, pi], so that dh_rotvec_to_mat3_f32(phi) == R.
 * Accurate down to t == 0 and up to t == pi, where phi and -phi are the
 * same rotation and the sign follows dh_mat3_to_quat_f32 (method:
 * docs/design.md). Error bounds: |phi - phi_exact| <= 7.5e-7 rad for
 * t <= pi - 1e-3; within 1e-3 of pi only the reproduced matrix is
 * meaningful: R reproduced within 5.5e-7 per entry.
 * @return DH_OK; DH_ERR_NAN; DH_ERR_NOT_RIGID (see file comment). phi
 *         untouched on error.
 */
dh_status dh_mat3_to_rotvec_f32(const dh_mat3_f32 *R, dh_vec3_f32 *phi);

/**
 * @brief S = [v]x, the skew-symmetric matrix with S u = v x u:
 *        rows (0 -vz vy), (vz 0 -vx), (-vy vx 0).
 * Exact (negation only; the zero diagonal is +0). No status.
 */
void dh_skew_f32(const dh_vec3_f32 *v, dh_mat3_f32 *S);

/**
 * @brief v = vee(S): the vector of the skew-symmetric PART of S,
 *        v = (S21 - S12, S02 - S20, S10 - S01) / 2 (the symmetric part of a
 *        general S is ignored, which is the least-squares vee).
 * Evaluated as S21/2 - S12/2 etc., so vee(skew(v)) == v bitwise for any
 * finite v whose halves are not denormal, and no overflow. No status
 * (IEEE semantics). v may not alias S (different types).
 */
void dh_vee_f32(const dh_mat3_f32 *S, dh_vec3_f32 *v);

/**
 * @brief Angular velocity in the REFERENCE (space) frame of a rotating
 *        frame R(t): w = vee(Rdot R^T) (S(w) = Rdot R^T, Spong et al. 2006).
 * @param w output in rad/s when Rdot is per second (any consistent time
 *        unit; Rdot is dR/dt with the angle in radians).
 * @param R rotation; must pass dh_mat3_check_rot_f32(R, DH_ROT_TOL).
 * @param Rdot time derivative of R, finite. It is not checked for
 *        consistency (Rdot R^T skew-symmetric); its symmetric part is
 *        ignored (see dh_vee_f32).
 * @return DH_OK; DH_ERR_NAN if an entry of R or Rdot is NaN/Inf;
 *         DH_ERR_NOT_RIGID if R is not a rotation; DH_ERR_OVERFLOW if the
 *         inputs are finite but w is not (|Rdot| near FLT_MAX). w
 *         untouched on error.
 * Error bound: |w - w_exact| <= 3e-7 * max(1, |w|) per component.
 */
dh_status dh_angvel_f32(const dh_mat3_f32 *R, const dh_mat3_f32 *Rdot, dh_vec3_f32 *w);

/**
 * @brief Angular velocity in the BODY (moving) frame: w_b = vee(R^T Rdot)
 *        = R^T w. Same contract as dh_angvel_f32.
 */
dh_status dh_angvel_body_f32(const dh_mat3_f32 *R, const dh_mat3_f32 *Rdot, dh_vec3_f32 *w);

/* ======================================================================
 * Checks and re-orthonormalisation
 * ==================================================================== */

/**
 * @brief R is a rotation within @p tol: every entry of R^T R - I (column
 *        dot products c_i . c_j - delta_ij) within tol and
 *        det R = c0 . (c1 x c2) > 0.
 * @param R matrix to check.
 * @param tol finite, >= 0 (DH_ROT_TOL is what the extraction functions use).
 * @return DH_OK; DH_ERR_NOT_RIGID; DH_ERR_NAN if an entry is NaN/Inf;
 *         DH_ERR_ARG if tol is negative, NaN or infinite.
 */
dh_status dh_mat3_check_rot_f32(const dh_mat3_f32 *R, float tol);

/**
 * @brief out = the rotation nearest to R (orthogonal polar factor,
 *        closest in the Frobenius norm), for a rotation matrix that has
 *        drifted (accumulated products, integration, Q format conversion).
 *
 * Newton-Schulz iteration, at most 8 steps, not biased towards any column
 * (method: docs/design.md). Result: max |(out^T out - I)_ij| <= 4e-7 and
 * out within 3e-7 per entry of the exact polar factor (for perturbations
 * of up to 0.05 per entry).
 * An exact rotation is returned unchanged within rounding (at most one
 * step is taken).
 * @return DH_OK; DH_ERR_NAN if an entry is NaN/Inf; DH_ERR_NOT_RIGID if
 *         max |(R^T R - I)_ij| > DH_ROT_ORTHO_MAX_DEV or det R <= 0 (too
 *         far from a rotation to be repaired meaningfully, or a
 *         reflection); DH_ERR_NO_CONVERGENCE if 8 steps do not reach the
 *         tolerance (not observed; out is then left untouched too).
 *         out untouched on error; out may alias R.
 */
dh_status dh_mat3_orthonormalize_f32(const dh_mat3_f32 *R, dh_mat3_f32 *out);

/* ======================================================================
 * Fixed point (integer only: no float, no libm, no 64-bit division)
 * ==================================================================== */

/**
 * DH_ROT_TOL in Q2.30 LSB (1e-4 2^30): the orthonormality tolerance of the
 * fixed extractions below. F's rotation is accepted when
 * dh_frame_ortho_error_q(F) <= DH_ROT_TOL_Q and det > 0, else
 * DH_ERR_NOT_RIGID (the float path's policy; the position is not read).
 */
#define DH_ROT_TOL_Q 107374
/** DH_EULER_POLE_TOL in Q2.30 LSB (2^-22). */
#define DH_EULER_POLE_TOL_Q 256

/** Quaternion in Q2.30 (1.0 = 0x40000000), scalar part first, as dh_quat_f32. */
typedef struct {
    dh_q30 w; /**< scalar part */
    dh_q30 x; /**< i component */
    dh_q30 y; /**< j component */
    dh_q30 z; /**< k component */
} dh_quat_q;

/**
 * @brief Euler angles (Q16.16 degrees) of F's rotation: the fixed
 *        counterpart of dh_mat3_to_euler_f32, with its output ranges and
 *        gimbal-lock policy: when the measured cosine (Tait-Bryan) or sine
 *        (proper) of the middle angle is at most DH_EULER_POLE_TOL_Q, the
 *        third angle (in the order of the letters) is exactly 0 and the
 *        whole rotation about the locked axis is in the first.
 *
 * Error bounds (asserted against double by test_rot_q): with the
 * middle angle at least 1 deg from a pole, angles within 2e-5 deg of the
 * exact ones of the rotation; everywhere, the exact rotation of the
 * returned angles reproduces F within 6e-7 per entry; near a pole the
 * middle angle is within 1e-5 deg.
 * @param F rotation part read (Q2.30); position ignored.
 * @param seq sequence, 0 .. DH_EULER_COUNT-1.
 * @param ang_deg output (a, b, c), Q16.16 degrees.
 * @return DH_OK; DH_ERR_ARG (seq out of range); DH_ERR_NOT_RIGID (see
 *         DH_ROT_TOL_Q). ang_deg untouched on error.
 */
dh_status dh_frame_to_euler_q(const dh_frame_q *F, dh_euler_seq seq, dh_q16 ang_deg[3]);

/**
 * @brief F = rotation of the Euler angles (Q16.16 degrees, any int32) in
 *        sequence seq (products as dh_euler_to_mat3_f32), position 0.
 *        Sines and cosines from dh_sincos_q (multiples of 90 deg exact),
 *        each of the three elementary turns rounded once per entry: entry
 *        error <= 4 LSB (4e-9).
 * @return DH_OK; DH_ERR_ARG for seq out of range (F untouched). ang_deg
 *         must not lie inside F.
 */
dh_status dh_euler_to_frame_q(dh_euler_seq seq, const dh_q16 ang_deg[3], dh_frame_q *F);

/**
 * @brief Unit quaternion (Q2.30) of F's rotation (Shepperd 1978), the fixed
 *        counterpart of dh_mat3_to_quat_f32: normalised, w >= 0; at w == 0
 *        the component of the largest diagonal entry is positive.
 *        Components within 2e-7 of the exact unit quaternion (the bound
 *        test_rot_q asserts).
 * @return DH_OK; DH_ERR_NOT_RIGID (see DH_ROT_TOL_Q; q untouched).
 */
dh_status dh_frame_to_quat_q(const dh_frame_q *F, dh_quat_q *q);

/**
 * @brief F = rotation of q / |q| (position 0) for any non-zero q: the
 *        components are brought to a common scale (exact shifts), q is
 *        normalised in integer arithmetic, then R is formed with one
 *        rounding per entry: entry error <= 6e-7 (the bound test_rot_q
 *        asserts).
 *        INT32_MIN components are accepted (never negated).
 * @return DH_OK; DH_ERR_ZERO_AXIS when all four components are 0 (F
 *         untouched).
 */
dh_status dh_quat_to_frame_q(const dh_quat_q *q, dh_frame_q *F);

/**
 * @brief Unit axis (Q2.30) and angle (Q16.16 degrees, [0, 180]) of F's
 *        rotation, the fixed counterpart of dh_mat3_to_axis_angle_f32 with
 *        its special cases: at 0 degrees axis = (0, 0, 1); at 180 degrees
 *        the axis whose component of the largest diagonal entry is
 *        positive. The angle is one atan2 (accurate at 0 and 180 alike),
 *        within 2e-5 deg; the axis from the quaternion's vector part.
 * @return DH_OK; DH_ERR_NOT_RIGID (see DH_ROT_TOL_Q; outputs untouched).
 */
dh_status dh_frame_to_axis_angle_q(const dh_frame_q *F, dh_dir3_q *axis, dh_q16 *deg);

/* ======================================================================
 * Fixed <-> float frames (these use float)
 * ==================================================================== */

/**
 * @brief F = T converted to fixed point: rotation entries x 2^30 and
 *        positions x 2^DH_QPOS_FRAC, rounded to nearest (ties away from
 *        zero); exact whenever the float value is representable.
 *
 * Rigidity of the rotation part is NOT checked (the frame holds any 3x3
 * matrix; use dh_frame_ortho_error_q() or dh_mat4_check_rigid_f32()); the
 * bottom row must be exactly 0 0 0 1.
 * @return DH_OK;
 *   DH_ERR_NAN if any of the 16 elements is NaN or infinite (F untouched);
 *   DH_ERR_OVERFLOW if a rotation entry is outside [-2, 2) or a position
 *   outside the dh_qpos range (saturated value written, rest converted);
 *   DH_ERR_NOT_RIGID if the bottom row is not 0 0 0 1 (F fully written
 *   from the top three rows). NaN takes precedence over overflow, overflow
 *   over not-rigid.
 */
dh_status dh_frame_from_mat4_q(const dh_mat4_f32 *T, dh_frame_q *F);

/**
 * @brief T = F as a float 4x4 (bottom row 0 0 0 1). Each element is the
 *        fixed-point value rounded once to float (round to nearest even);
 *        values with <= 24 significant bits are exact. Cannot fail.
 */
void dh_frame_to_mat4_q(const dh_frame_q *F, dh_mat4_f32 *T);

#ifdef __cplusplus
}
#endif

#endif /* DHMATH_ROT_H */
