/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Index: the functions of kin.h by source file (src/kin/).
 *   dh_jacobian.c      dh_jacobian_f32, dh_jacobian_tool_f32
 *   dh_jacobian_q.c    dh_jacobian_q, dh_jacobian_tool_q
 *   dh_pose_error.c    dh_rot_error_f32, dh_pose_error_f32
 *   dh_pose_error_q.c  dh_rot_error_q
 *   dh_ik.c            dh_ik_params_default_f32, dh_ik_f32
 *   dh_ik_q.c          dh_ik_params_default_q, dh_ik_q
 *   dh_dls.c           dh_manipulability_f32, dh_dls_step_f32
 *   dh_dls_q.c         dh_manipulability_q, dh_dls_step_q
 */
/**
 * @file kin.h
 * @brief Geometric Jacobian, orientation error and numerical inverse
 *        kinematics (float) for a dh_robot.
 *
 * Units: joint values in DEGREES for revolute joints and in the robot's
 * length unit for prismatic joints (as everywhere in dhmath); the Jacobian
 * is per RADIAN for revolute joints (so J * qdot, qdot in rad/s, gives m/s
 * and rad/s), orientation errors are in radians.
 *
 * The _q functions are the fixed-point counterparts (integer only: no
 * float, no libm, no 64-bit division; formats as frame.h). The float
 * ones use f-suffixed constants, no double and no libm: square roots
 * are correctly rounded (bit-identical to an IEEE sqrtf). No heap, no
 * recursion, reentrant; every function stays within 256 bytes of stack
 * including callees (dh_ik_f32 keeps its vectors and matrices in the
 * caller's workspace). Pointers must not be NULL (DH_ASSERT).
 *
 * Methods: docs/design.md ("Kinematics"); measured accuracy and success
 * rates: docs/accuracy_kin.md; cost and stack: docs/generated/performance_target.md,
 * docs/generated/footprint.md.
 */
#ifndef DHMATH_KIN_H
#define DHMATH_KIN_H

#include "dhmath/robot.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * Orthonormality tolerance of the rotation inputs of dh_rot_error_f32 and
 * dh_pose_error_f32: every entry of R^T R - I must be within it and det R
 * must be positive (a reflection is rejected), otherwise DH_ERR_NOT_RIGID.
 * A rotation that is off by up to this amount yields an
 * error vector of that order of inaccuracy.
 */
#define DH_ROT_ERROR_TOL 1e-3f

/**
 * @brief Geometric Jacobian in the base frame.
 *
 * J is 6 x n, row-major (J[row * n + col], n = r->n), rows vx vy vz wx wy wz
 * (linear velocity of the END POINT = origin of base * A_1..A_n * tool, and
 * angular velocity, both in base coordinates). Column i:
 * - revolute:  [ z_i x (p_end - o_i) ; z_i ]  per radian of q_i,
 * - prismatic: [ z_i ; 0 ]                    per length unit of q_i,
 * where z_i / o_i are the z axis / origin of frame i-1 (standard DH) or of
 * frame i (modified DH), base included (Spong et al. 2006, ch. 4).
 * Entry error vs double (test_jacobian: Puma 560, UR5, Panda in metres):
 * <= 4.5e-7 linear rows, 5e-7 angular rows (measured: docs/accuracy_kin.md).
 *
 * @param r  robot (float path), conv standard or modified.
 * @param q  n joint values (deg / length), any finite (limits not checked).
 * @param J  6*n floats, output. Must not overlap q or r.
 * @param T_end may be NULL; else receives the end frame, bottom row exactly
 *           0 0 0 1 (the same value as dh_fk_f32 up to rounding: the
 *           chain is accumulated link by link from the DH definitions,
 *           then the tool is applied).
 * @return DH_OK (also for n == 0: J has no entries, T_end = base * tool);
 *         DH_ERR_NAN for a non-finite q (J, T_end untouched);
 *         DH_ERR_UNAVAILABLE when the float path is unavailable
 *         (DH_ROBOT_HAS_F32 clear); DH_ERR_ARG for n > DH_MAX_JOINTS, unknown convention or joint type
 *         (J, T_end untouched); DH_ERR_OVERFLOW when q + offset (theta
 *         offset of a revolute joint, d of a prismatic one) overflows to
 *         infinity (checked first: J, T_end untouched) or when an entry of
 *         J or of the end frame is not finite (J and T_end hold the
 *         computed values).
 */
dh_status dh_jacobian_f32(const dh_robot *r, const float *q, float *J, dh_mat4_f32 *T_end);

/**
 * @brief Geometric Jacobian expressed in the tool (end) frame.
 *
 * Both halves of every column of dh_jacobian_f32 rotated by R_end^T: the
 * end point's linear and angular velocity in end-frame coordinates (same
 * reference point, the end frame's origin). Arguments, statuses and outputs
 * on error as dh_jacobian_f32.
 */
dh_status dh_jacobian_tool_f32(const dh_robot *r, const float *q, float *J, dh_mat4_f32 *T_end);

/**
 * @brief Geometric Jacobian of the fixed-point chain, base frame (integer
 * only): the columns of dh_jacobian_f32 from the chain dh_fk_q builds.
 *
 * J is 6 x n int32, row-major (J[row * n + col]), rows vx vy vz wx wy wz.
 * Revolute column: linear rows z_i x (p_end - o_i) in dh_qpos per RADIAN,
 * angular rows z_i in Q2.30. Prismatic column: linear rows z_i in Q2.30
 * (length per length, dimensionless), angular rows 0.
 * Each linear entry is the exact cross product of the integer frame
 * entries rounded once (<= 0.5 LSB). Against the exact robot (Puma 560,
 * UR5 and Panda in mm, DH_QPOS_FRAC 16) test_jacobian_q asserts its error
 * at most dh_jacobian_f32's on the same robot (linear rows: or the
 * position resolution); measured figures: docs/accuracy_kin.md.
 *
 * @param r  robot (fixed path), conv standard or modified.
 * @param q  n joint values: dh_q16 degrees (R), dh_qpos (P), any int32
 *           (as dh_fk_q; limits are not checked).
 * @param J  6*n int32, output. Must not overlap q or r.
 * @param T_end may be NULL; else receives the end frame, bit for bit the
 *           dh_fk_q result (n == 0: base * tool).
 * @return DH_OK (also for n == 0: J has no entries);
 *         DH_ERR_UNAVAILABLE when the fixed path is unavailable
 *         (DH_ROBOT_HAS_Q clear); DH_ERR_ARG for n > DH_MAX_JOINTS, unknown
 *         convention or joint type (J, T_end untouched for both);
 *         DH_ERR_OVERFLOW when d + q, an FK entry or an entry of J
 *         saturated (J and T_end written, saturated entries at INT32_MIN /
 *         INT32_MAX with the true sign; never wrapped).
 */
dh_status dh_jacobian_q(const dh_robot *r, const int32_t *q, int32_t *J, dh_frame_q *T_end);

/**
 * @brief dh_jacobian_q expressed in the tool (end) frame: both halves of
 * every column rotated by R_end^T (each component a three-term sum of
 * exact products rounded once, within 0.5 + 2^-29 LSB). Arguments,
 * statuses and outputs on error as dh_jacobian_q.
 */
dh_status dh_jacobian_tool_q(const dh_robot *r, const int32_t *q, int32_t *J, dh_frame_q *T_end);

/**
 * @brief Orientation error a(dR), dR = R_target * R^T (Sugihara 2011).
 *
 * w is the rotation vector (unit axis times angle in radians, angle in
 * [0, pi]) with R_target = Rot(w) * R: w = 0 for dR = I, and accurate at
 * every angle up to and at pi (no acos, so no domain error near 0 or pi;
 * method in docs/design.md). At exactly pi the sign of w is arbitrary
 * (both are the same rotation).
 *
 * @param R_target, R rotation matrices (column-major dh_mat3_f32),
 *        orthonormal within DH_ROT_ERROR_TOL and with det > 0. May alias
 *        each other.
 * @param w output (may not overlap the inputs).
 * @return DH_OK; DH_ERR_NAN for non-finite input; DH_ERR_NOT_RIGID if an
 *         input is not orthonormal within DH_ROT_ERROR_TOL or is a
 *         reflection (w untouched on error).
 *
 * Error: test_jacobian asserts |w - w_ref| <= 8e-7 rad against double in
 * every angle band up to 180 degrees.
 */
dh_status dh_rot_error_f32(const dh_mat3_f32 *R_target, const dh_mat3_f32 *R, dh_vec3_f32 *w);

/**
 * @brief Singularity measures of a Jacobian: manipulability w = sqrt(det(J
 * J^T)) (Yoshikawa 1985; sqrt(det(J^T J)) when n < 6) and a lower bound on
 * the smallest singular value of J (the 6th for n >= 6, the n-th for n < 6).
 *
 * J is 6 x n row-major as dh_jacobian_f32 writes it (per radian for
 * revolute columns, so both measures mix the length unit and radians as
 * J does). sigma_min <= the smallest singular value of the J given (exact
 * arithmetic on the float entries) on every input, at most sqrt(m) (m = 6
 * or n) times below it plus the float resolution: below about
 * sqrt(32 * 2^-24 * |J|_F^2) it is reported as 0. Method: src/kin/dh_dls.c.
 * @param J   6 * n finite floats.
 * @param n   joints, 1..DH_MAX_JOINTS.
 * @param w   manipulability (>= 0; 0 when J J^T is numerically singular),
 *            or NULL.
 * @param sigma_min lower bound (>= 0), or NULL.
 * @return DH_OK; DH_ERR_ARG n out of range; DH_ERR_NAN an entry of J not
 *         finite; DH_ERR_OVERFLOW J J^T or w overflows float. Outputs
 *         untouched on error.
 */
dh_status dh_manipulability_f32(const float *J, uint32_t n, float *w, float *sigma_min);

/**
 * @brief One damped least-squares step (Wampler 1986): dq = J^T (J J^T +
 * lambda^2 I)^-1 e, in joint units, scaled to per-joint bounds.
 *
 * The step that reduces |e - J dq| most for its size (resolved-rate
 * control, and the step dh_track_step_f32 takes). The solution per radian
 * is converted to degrees for revolute joints (prismatic: length unit);
 * then, when dq_max is given, the whole vector is scaled down by one factor
 * so that |dq[i]| <= dq_max[i] for every joint (the direction is kept; a
 * bound of 0 stops every joint).
 * @param r      robot (joint types, n = r->n in 1..DH_MAX_JOINTS).
 * @param J      6 x n Jacobian as dh_jacobian_f32 (per radian).
 * @param e      task error: e[0..2] position (length unit), e[3..5]
 *               rotation vector (rad), as dh_pose_error_f32(target, FK(q)).
 * @param lambda damping (length unit, >= 0, finite); 0 gives the
 *               pseudo-inverse step (a lambda whose square underflows
 *               float, < 1e-19, counts as 0).
 * @param dq_max n bounds (>= 0, +inf allowed), or NULL for no scaling.
 * @param dq     n outputs (may not overlap the inputs).
 * @return DH_OK; DH_ERR_SINGULAR lambda is 0 and J J^T is singular within
 *   float rounding (dq zeros); DH_ERR_OVERFLOW the step overflows float (dq
 *   zeros, or untouched when J J^T itself overflows). With dq untouched:
 *   DH_ERR_ARG (n, lambda < 0 or infinite, a dq_max entry < 0 or NaN),
 *   DH_ERR_NAN (lambda, J or e not finite).
 */
dh_status dh_dls_step_f32(const dh_robot *r, const float *J, const float e[6], float lambda, const float *dq_max,
                          float *dq);

/** DH_ROT_ERROR_TOL in Q2.30 LSB (1e-3 2^30), for dh_rot_error_q. */
#define DH_ROT_ERROR_TOL_Q 1073742

/**
 * @brief Orientation error a(dR), dR = R_target R^T, of two fixed frames'
 * rotations (Q2.30; positions ignored): the fixed counterpart of
 * dh_rot_error_f32 (integer only). w is the rotation vector in Q3.29
 * RADIANS (1.0 rad = 2^29; |w| <= pi), R_target = Rot(w) R; w = 0 for
 * dR = I; at exactly pi the sign of w is arbitrary. Error: test_rot_q
 * asserts |w - w_ref| <= 6.3e-7 rad against double at every angle.
 * @param F_target, F frames whose rotations are orthonormal within
 *        DH_ROT_ERROR_TOL_Q (dh_frame_ortho_error_q) with det > 0. May
 *        alias each other.
 * @param w output: each component in Q3.29 rad (1.0 rad = 2^29), not the
 *        Q2.30 of dh_dir3_q's other uses.
 * @return DH_OK; DH_ERR_NOT_RIGID if a rotation is not orthonormal within
 *         the tolerance or is a reflection (w untouched).
 */
dh_status dh_rot_error_q(const dh_frame_q *F_target, const dh_frame_q *F, dh_dir3_q *w);

/**
 * @brief Pose error between two frames: e[0..2] = p_target - p (length
 * unit), e[3..5] = a(R_target R^T) (rad, as dh_rot_error_f32).
 *
 * The error dh_ik_f32 drives to zero. Bottom rows are not read.
 * @return DH_OK; DH_ERR_NAN for a non-finite entry; DH_ERR_NOT_RIGID for a
 *         rotation part not orthonormal within DH_ROT_ERROR_TOL or a
 *         reflection (e untouched on error).
 */
dh_status dh_pose_error_f32(const dh_mat4_f32 *T_target, const dh_mat4_f32 *T, float e[6]);

/** Task-space mask bit for dh_ik_params_f32.mask: drive the x position error to 0. */
#define DH_IK_PX 0x01u
/** Mask bit: y position error. */
#define DH_IK_PY 0x02u
/** Mask bit: z position error. */
#define DH_IK_PZ 0x04u
/** Mask bit: orientation error about x. */
#define DH_IK_RX 0x08u
/** Mask bit: orientation error about y. */
#define DH_IK_RY 0x10u
/** Mask bit: orientation error about z. */
#define DH_IK_RZ 0x20u
/** Position only (orientation is free). */
#define DH_IK_POSITION 0x07u
/** Full pose. */
#define DH_IK_FULL 0x3Fu

/** IK parameters; fill with dh_ik_params_default_f32() for the robot and adjust. */
typedef struct {
    uint32_t max_iter;   /**< bound on the number of trial steps (FK + Jacobian evaluations after the first), >= 1 */
    uint32_t mask;       /**< DH_IK_* bits of the error components to drive to 0 (non-zero, within DH_IK_FULL) */
    float tol_pos;       /**< position tolerance (length unit), >= 0, on the norm of the masked position components */
    float tol_rot;       /**< orientation tolerance (rad), >= 0, on the norm of the masked rotation-vector components */
    float w_rot;         /**< weight of orientation vs position error (length unit per rad), > 0; at most L counts (dh_ik_f32) */
    uint32_t restarts;   /**< restarts from deterministic pseudo-random configurations after a stall (local minimum), within max_iter */
} dh_ik_params_f32;

/** IK outcome figures (for the returned configuration). */
typedef struct {
    uint32_t iterations; /**< trial steps taken (each one FK + Jacobian) */
    float err_pos;       /**< position error norm of the masked components (length unit) */
    float err_rot;       /**< orientation error norm of the masked components (rad) */
} dh_ik_result_f32;

/**
 * Sugihara's constant damping bias, relative to the robot's characteristic
 * length L squared: the damping of joint i is mu min(E_k, (J^T W^2 J)_ii) +
 * DH_IK_WBAR * L^2. Small (near the float noise of J^T J) so that
 * convergence stays fast near singular targets; it keeps the normal matrix
 * positive definite for redundant arms.
 */
#define DH_IK_WBAR 1e-7f

/** Workspace floats needed by dh_ik_f32 for an n-joint robot: n^2 + 20 n + 45
 *  (201 for n = 6, 234 for n = 7). Besides the two Jacobians and the normal
 *  matrix it holds the Jacobian pass's frame, dR and the solver's float
 *  state, so that dh_ik_f32 stays within its stack budget. */
#define DH_IK_WORK_FLOATS(n) ((n) * (n) + 20u * (n) + 45u)

/**
 * @brief Defaults for robot r, in its length unit: max_iter 2000, mask
 * DH_IK_FULL, tol_pos 1e-6 L, tol_rot 1e-5 (rad), w_rot L / 4 (length unit
 * per rad), restarts 200, where L = sum of |a|, |d|, prismatic travel
 * (limited joints) and |p_tool| (1 if that is 0 or not finite squared):
 * so a robot in mm gets the same solver as the one in m (tol_pos 1.7e-3
 * mm for a 1.7 m Puma 560). Reads only r's float joint and tool values
 * (any robot, no status). A target far beyond L (unlimited prismatic
 * joint) needs tol_pos above its coordinates' float resolution, 6e-8 |x|.
 * The step bound matters only for hard targets and for unreachable targets
 * within the reach bound, which can take all of max_iter; lower it (and
 * restarts) for a tighter worst case, at some cost in success rate
 * (docs/accuracy_kin.md).
 */
void dh_ik_params_default_f32(const dh_robot *r, dh_ik_params_f32 *p);

/**
 * @brief Numerical IK, Levenberg-Marquardt with Sugihara 2011's damping:
 * minimises E = 1/2 (|e_pos|^2 + w^2 |e_rot|^2), w = min(w_rot, L) (L as in
 * dh_ik_params_default_f32: a heavier weight drowns the position in the float
 * rounding), over the masked components of dh_pose_error_f32(target,
 * FK(q)), q within the joint limits (qmin <= qmax; q0 clamped first; qmin >
 * qmax: free, no wrapping). An attempt stalls after 4 steps in a row with
 * less than 1% progress (of E, or of one error while the other meets its
 * tolerance) and restarts from a deterministic pseudo-random configuration
 * (p->restarts, within p->max_iter steps); the best attempt is returned
 * (converged first, then lowest E). Same inputs, bitwise same outputs.
 * Restarts can return DH_OK far from q0 (continuous motion: track.h). Reach
 * bound: (sum of |a|, |d|, prismatic travel, |p_tool|) * base norm * (1 +
 * 1e-4) + tol_pos. Method: docs/design.md ("Kinematics").
 * @param r,target robot (float path), 1..DH_MAX_JOINTS joints; end frame,
 *               bottom row 0 0 0 1, driven rotation within DH_ROT_ERROR_TOL, det > 0.
 * @param q0,p,work,work_len start (n finite values); parameters; >=
 *               DH_IK_WORK_FLOATS(n) floats, overlapping nothing, clobbered.
 * @param q,res  result (may alias q0); iterations and errors of q.
 * @return for the returned q (within the limits; res describes it): DH_OK
 *   both tolerances met; DH_ERR_NO_CONVERGENCE max_iter cut off an attempt
 *   still progressing; DH_ERR_UNREACHABLE stalled above tolerance, or beyond
 *   the reach bound (if E would overflow: no step, q = clamped q0, res: 0
 *   iterations, err_pos the distance or FLT_MAX). Never DH_ERR_SINGULAR.
 *   With q, res untouched: DH_ERR_ARG (n, work, work_len, max_iter, mask,
 *   tolerances, w_rot <= 0, non-finite or > 4.6e18, convention/joint type);
 *   DH_ERR_UNAVAILABLE (no float path); DH_ERR_NAN (target, q0);
 *   DH_ERR_NOT_RIGID (target bottom row, driven target rotation, end
 *   rotation not one); DH_ERR_OVERFLOW (FK or E of the start).
 */
dh_status dh_ik_f32(const dh_robot *r, const dh_mat4_f32 *target, const float *q0, const dh_ik_params_f32 *p,
                    float *work, size_t work_len, float *q, dh_ik_result_f32 *res);

/** DH_ROT_ERROR_TOL in Q2.30 for the fixed-point functions (1e-3 * 2^30). */
#define DH_ROT_ERROR_TOL_Q 1073742

/** Fixed-point IK parameters; fill with dh_ik_params_default_q() and adjust. */
typedef struct {
    uint32_t max_iter;   /**< bound on the trial steps (FK + Jacobian after the first), >= 1 */
    uint32_t mask;       /**< DH_IK_* bits to drive to 0 (non-zero, within DH_IK_FULL) */
    int32_t tol_pos;     /**< position tolerance, dh_qpos, >= 0, on the masked position norm */
    int32_t tol_rot;     /**< orientation tolerance, Q2.30 rad, >= 0, on the masked rotation-vector norm */
    int32_t w_rot;       /**< weight of orientation vs position, dh_qpos per rad, > 0; at most L counts */
    uint32_t restarts;   /**< restarts from deterministic pseudo-random configurations, within max_iter */
} dh_ik_params_q;

/** Fixed-point IK outcome (for the returned configuration). */
typedef struct {
    uint32_t iterations; /**< trial steps taken (each one FK + Jacobian) */
    int32_t err_pos;     /**< masked position error norm, dh_qpos (saturated at INT32_MAX) */
    int32_t err_rot;     /**< masked orientation error norm, Q2.30 rad (saturated at INT32_MAX, 2 rad) */
} dh_ik_result_q;

/** Workspace int32 words needed by dh_ik_q for n joints: n^2 + 23 n + 75
 *  (249 for n = 6, 285 for n = 7): both Jacobians, the equilibrated
 *  normal matrix and its factor, the frame, the orientation error's
 *  scratch, the solver state and a copy of q0 (so that dh_ik_q stays
 *  within its stack budget). */
#define DH_IK_WORK_Q(n) ((n) * (n) + 23u * (n) + 75u)

/**
 * @brief Fixed-point defaults for robot r (integer only): max_iter 500,
 * mask DH_IK_FULL, tol_pos L / 2^20 (at least 1 LSB), tol_rot 10737 (1e-5
 * rad), w_rot L / 4, restarts 50, where L = sum of |a_q|, |d_q|,
 * prismatic travel (limited joints) and |tool_q p| in dh_qpos (one length
 * unit if that is 0; saturated at INT32_MAX). Reads only r's fixed fields.
 * The step budget is a quarter of dh_ik_params_default_f32's: it bounds the
 * worst case (the cost of a step on a Cortex-M0, measured:
 * docs/generated/performance_target.md, "Inverse kinematics in fixed
 * point") at a small cost in success rate for near-singular targets
 * (docs/accuracy_kin.md).
 */
void dh_ik_params_default_q(const dh_robot *r, dh_ik_params_q *p);

/**
 * @brief Numerical IK in fixed point (integer only: no float, libm or
 * 64-bit division): dh_ik_f32's method (Levenberg-Marquardt with Sugihara
 * 2011's damping, joint limits in the iteration, stall restarts, best
 * attempt returned, deterministic) on the fixed chain of dh_jacobian_q.
 * E = 1/2 (|e_pos|^2 + w^2 |e_rot|^2), w = min(w_rot, L), e_pos = target p
 * - FK p (dh_qpos), e_rot = a(R_target R^T) (rad). q in dh_q16 deg (R) or
 * dh_qpos (P), within the fixed limits (q0 clamped first). The errors are
 * those of dh_fk_q: add its error (docs/accuracy_fk.md) for the true one.
 * @param r      robot (fixed path), 1..DH_MAX_JOINTS joints.
 * @param target end frame; rotation (read only when the mask drives it)
 *               within DH_ROT_ERROR_TOL_Q of orthonormal, det > 0.
 * @param q0,p   start (n values); parameters.
 * @param work,work_len >= DH_IK_WORK_Q(n) words, overlapping nothing; clobbered.
 * @param q,res  result (may alias q0); iterations and errors of q.
 * @return for the returned q (res describes it): DH_OK both tolerances met;
 *   DH_ERR_NO_CONVERGENCE max_iter cut off an attempt still progressing;
 *   DH_ERR_UNREACHABLE stalled above tolerance, or the target beyond the
 *   reach bound (dh_ik_f32's, in dh_qpos). With q, res untouched:
 *   DH_ERR_ARG (n, work NULL or work_len too small, max_iter 0, mask,
 *   tolerance < 0, w_rot <= 0, convention or joint type);
 *   DH_ERR_UNAVAILABLE (no fixed path); DH_ERR_NOT_RIGID (driven target
 *   rotation, or the start's end rotation, not one); DH_ERR_OVERFLOW (FK
 *   or Jacobian of the start saturated). Trial points that saturate are
 *   rejected (never wrapped). Never DH_ERR_SINGULAR.
 */
dh_status dh_ik_q(const dh_robot *r, const dh_frame_q *target, const int32_t *q0, const dh_ik_params_q *p,
                  int32_t *work, size_t work_len, int32_t *q, dh_ik_result_q *res);

/* ---- singularity measures and damped least squares, fixed point ---------- */

/** Scratch of dh_manipulability_q and dh_dls_step_q (caller-owned, 152
 *  + 2 DH_MAX_JOINTS bytes on a 32-bit target, so that both stay within the
 *  256-byte stack budget): the call's state and matrices; its contents are
 *  unspecified between calls. */
typedef struct {
    int32_t L[21];  /**< equilibrated Gram matrix, then its factor (packed lower triangle) */
    int32_t y[6];   /**< right-hand side and solution */
    int16_t c[6];   /**< equilibration exponents */
    int16_t ik[6];  /**< pivot reciprocal exponents */
    int16_t ex[DH_MAX_JOINTS]; /**< exponents of the unscaled step */
    const int32_t *J;          /**< the call's Jacobian */
    const int32_t *dq_max;     /**< the call's step bounds (NULL: none) */
    uint32_t pris;             /**< bit i: column i is prismatic */
    uint8_t n;                 /**< columns of J */
    uint8_t m;                 /**< Gram order: 6 (rows) or n (columns) */
    uint8_t cols;              /**< 1: G = B^T B, 0: G = B B^T */
    int16_t g[2];              /**< formats of the linear and angular rows */
} dh_dls_work_q;

/**
 * @brief Singularity measures of a fixed-point Jacobian (integer only).
 *
 * J is dh_jacobian_q's (6 x n, row-major; a column whose angular rows are
 * all 0 is read as prismatic: linear rows Q2.30, else revolute: linear
 * rows dh_qpos per rad, angular rows Q2.30). G = J J^T for n >= 6, J^T J
 * for n < 6, in J's units (length unit, rad).
 * @param J  6 x n Jacobian (not NULL), as above.
 * @param n  columns of J, 1..DH_MAX_JOINTS.
 * @param w  may be NULL; else log2 sqrt(det G), the manipulability's base-2
 *           logarithm, in Q16.16 (a logarithm so that every robot and length
 *           unit fits: a UR5 in mm has sqrt det G near 2^26), or INT32_MIN
 *           when G is numerically singular (a pivot of the equilibrated G
 *           below 2^-24). Error against double: docs/accuracy_kin.md,
 *           test/kin/test_dls_q.c.
 * @param sigma_min may be NULL; else a LOWER BOUND on the smallest singular
 *           value of J in dh_qpos (DH_QPOS_FRAC fraction bits; saturated at
 *           INT32_MAX), 0 near a singularity: 1 / sqrt(trace G^-1), at most
 *           sqrt(6) (or sqrt(n)) below the true value, from a factor of the
 *           equilibrated G lowered by 2^-21 of its diagonal, rounded down.
 * @param work scratch (not NULL), overlapping nothing.
 * @return DH_OK; DH_ERR_ARG for n == 0 or n > DH_MAX_JOINTS (outputs untouched).
 */
dh_status dh_manipulability_q(const int32_t *J, uint32_t n, dh_dls_work_q *work, int32_t *w, int32_t *sigma_min);

/**
 * @brief One damped-least-squares step, fixed point (integer only):
 * dq = J^T (J J^T + lambda^2 I)^-1 e in joint units, scaled down uniformly
 * so that |dq_i| <= dq_max[i].
 *
 * @param r      robot (fixed path); gives n and which columns are prismatic.
 * @param J      dh_jacobian_q's Jacobian at the current configuration.
 * @param e      pose error: e[0..2] position in dh_qpos, e[3..5] rotation
 *               vector in Q3.29 rad (dh_rot_error_q's format), e.g. target
 *               minus current.
 * @param lambda damping, >= 0, in dh_qpos (the float step's lambda times
 *               2^DH_QPOS_FRAC: the same number in the length unit / rad).
 * @param dq_max NULL (no scaling) or n bounds >= 0 (dh_q16 deg / dh_qpos).
 * @param work   scratch (not NULL), overlapping nothing.
 * @param dq     n outputs: dh_q16 degrees (revolute), dh_qpos (prismatic).
 *               With dq_max: every |dq_i| <= dq_max[i] exactly (the ratio
 *               rounded down), the direction kept within 2^-29 relative.
 *               Must not overlap the inputs.
 * @return DH_OK; DH_ERR_ARG (n 0 or > DH_MAX_JOINTS, joint type, lambda < 0,
 *         a dq_max entry < 0; dq untouched); DH_ERR_UNAVAILABLE (no fixed
 *         path; dq untouched); DH_ERR_SINGULAR (lambda == 0 and J J^T
 *         numerically singular: a pivot of the equilibrated matrix below
 *         2^-24; dq zeros); DH_ERR_OVERFLOW (dq_max NULL and an entry
 *         saturated at INT32_MIN / INT32_MAX with its sign; or the solve
 *         could not be scaled into range, dq zeros).
 *         Error against the exact step in double: test/kin/test_dls_q.c.
 */
dh_status dh_dls_step_q(const dh_robot *r, const int32_t *J, const int32_t e[6], int32_t lambda,
                        const int32_t *dq_max, dh_dls_work_q *work, int32_t *dq);

#ifdef __cplusplus
}
#endif

#endif /* DHMATH_KIN_H */
