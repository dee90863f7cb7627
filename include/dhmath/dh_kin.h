/**
 * @file dh_kin.h
 * @brief Geometric Jacobian, orientation error and numerical inverse
 *        kinematics (float) for a dh_robot.
 *
 * Units: joint values in DEGREES for revolute joints and in the robot's
 * length unit for prismatic joints (as everywhere in dhmath); the Jacobian
 * is per RADIAN for revolute joints (so J * qdot, qdot in rad/s, gives m/s
 * and rad/s), orientation errors are in radians.
 *
 * Float only (f-suffixed constants, no double), and no libm: square roots
 * are computed in integer arithmetic (correctly rounded, bit-identical to
 * an IEEE sqrtf) and the angle of a(dR) with the library's own atan2
 * (src/dh_mathf.h), because newlib's sqrtf / atan2f alone take 72 / 176
 * bytes of stack on Cortex-M0+.
 *
 * No heap, no recursion, reentrant. Stack: the WORST-CASE CHAIN including
 * every callee and the libgcc soft-float helpers, as measured by
 * tools/check_guards.sh (tools/dh_stack.py, limit 256 bytes), is for
 * Cortex-M0+ / M4F at -Os and -O2:
 * - dh_ik_f32: 232 / 240 (M0+), 200 / 192 (M4F);
 * - dh_jacobian_f32, dh_jacobian_tool_f32: 208 / 208 (M0+), 160 / 160 (M4F);
 * - dh_rot_error_f32: 248 / 232 (M0+), 164 / 180 (M4F);
 * - dh_pose_error_f32: 240 / 224 (M0+), 156 / 164 (M4F).
 * The Jacobian keeps one 3x4 running frame (no link matrix, no 4x4
 * product); dh_ik_f32 keeps every vector and matrix in the caller's
 * workspace and calls shallow blocks one after the other.
 * Pointers must not be NULL (DH_ASSERT).
 */
#ifndef DHMATH_DH_KIN_H
#define DHMATH_DH_KIN_H

#include "dhmath/dh_robot.h"

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
 * frame i (modified DH), base included (seed 003, "Jacobian Matrix").
 *
 * @param r  robot (float path), conv standard or modified.
 * @param q  n joint values (deg / length), any finite values (limits are
 *           not checked).
 * @param J  6*n floats, output. Must not overlap q or r.
 * @param T_end may be NULL; else receives the end frame, bottom row exactly
 *           0 0 0 1 (the same value as dh_fk_f32 up to rounding: the
 *           chain is accumulated link by link from the DH definitions,
 *           then the tool is applied).
 * @return DH_OK (also for n == 0: J has no entries, T_end = base * tool);
 *         DH_ERR_NAN for a non-finite q (J, T_end untouched);
 *         DH_ERR_ARG for n > DH_MAX_JOINTS, the float path unavailable
 *         (DH_ROBOT_HAS_F32 clear), unknown convention or joint type
 *         (J, T_end untouched); DH_ERR_OVERFLOW when q + offset (theta
 *         offset of a revolute joint, d of a prismatic one) overflows to
 *         infinity (checked first: J, T_end untouched) or when an entry of
 *         J or of the end frame is not finite (J and T_end hold the
 *         computed values).
 *
 * Accuracy (test/test_jacobian.c, docs/accuracy_kin.md): against central
 * finite differences of the double-precision reference FK, Puma 560, UR5
 * and Panda in metres, 36 seeds: largest entry error 3.5e-7 in the linear
 * rows, 2.7e-7 in the angular rows, 5.5e-7 in the tool frame; 9.1e-7 for
 * random 1..7-joint robots of both conventions with prismatic joints,
 * base and tool.
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
 * @brief Orientation error a(dR), dR = R_target * R^T (seed 003).
 *
 * w is the rotation vector (unit axis times angle in radians, angle in
 * [0, pi]) with R_target = Rot(w) * R. Cases (seed 003): identity -> 0
 * (recognised by u = 0, not by the diagonal alone, which rounds to exactly
 * 1 in float below ~3e-4 rad); angle <= 90 deg: w = atan2(|u|, tr - 1) / |u| * u with
 * u = (r32 - r23, r13 - r31, r21 - r12); angle > 90 deg: the axis is taken
 * from the symmetric part (dR + dR^T)/2 (largest diagonal first) and signed
 * like u, which stays accurate up to and at 180 deg (the seed's diagonal
 * special cases (1,-1,-1) etc. give pi times the unit axis). No acos is
 * used, so there is no domain error near 0 or 180 deg.
 *
 * @param R_target, R rotation matrices (column-major dh_mat3_f32),
 *        orthonormal within DH_ROT_ERROR_TOL and with det > 0. May alias
 *        each other.
 * @param w output (may not overlap the inputs).
 * @return DH_OK; DH_ERR_NAN for non-finite input; DH_ERR_NOT_RIGID if an
 *         input is not orthonormal within DH_ROT_ERROR_TOL or is a
 *         reflection (w untouched on error).
 *
 * Accuracy (test/test_jacobian.c, docs/accuracy_kin.md): |w - w_ref|
 * <= 6.3e-7 rad measured over random float rotations at all angles, below
 * 1e-5 rad (4.8e-8), around 90 deg and within 1e-6 rad of 180 deg (at
 * exactly pi the sign of w is arbitrary, both are the same rotation).
 */
dh_status dh_rot_error_f32(const dh_mat3_f32 *R_target, const dh_mat3_f32 *R, dh_vec3_f32 *w);

/**
 * @brief Pose error between two frames: e[0..2] = p_target - p (length
 * unit), e[3..5] = a(R_target R^T) (rad, as dh_rot_error_f32).
 *
 * The error IK drives to zero (seed 003). Bottom rows are not read.
 * @return DH_OK; DH_ERR_NAN for a non-finite entry; DH_ERR_NOT_RIGID for a
 *         rotation part not orthonormal within DH_ROT_ERROR_TOL or a
 *         reflection (e untouched on error).
 */
dh_status dh_pose_error_f32(const dh_mat4_f32 *T_target, const dh_mat4_f32 *T, float e[6]);

/** Task-space mask bit for dh_ik_params.mask: drive the x position error to 0. */
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

/** IK parameters; fill with dh_ik_params_default() and adjust. */
typedef struct {
    uint32_t max_iter;   /**< bound on the number of trial steps (FK + Jacobian evaluations after the first), >= 1 */
    uint32_t mask;       /**< DH_IK_* bits of the error components to drive to 0 (non-zero, within DH_IK_FULL) */
    float tol_pos;       /**< position tolerance (length unit), >= 0, on the norm of the masked position components */
    float tol_rot;       /**< orientation tolerance (rad), >= 0, on the norm of the masked rotation-vector components */
    float w_rot;         /**< weight of orientation vs position error (length unit per rad), > 0 */
    uint32_t restarts;   /**< restarts from deterministic pseudo-random configurations after a stall (local minimum), within max_iter */
} dh_ik_params;

/** IK outcome figures (for the returned configuration). */
typedef struct {
    uint32_t iterations; /**< trial steps taken (each one FK + Jacobian) */
    float err_pos;       /**< position error norm of the masked components (length unit) */
    float err_rot;       /**< orientation error norm of the masked components (rad) */
} dh_ik_result;

/**
 * Sugihara's constant damping bias, relative to the robot's characteristic
 * length L squared: W_N = mu E_k + DH_IK_WBAR * L^2. Small (near the float
 * noise of J^T J) so that convergence stays fast near singular targets; it
 * keeps the normal matrix positive definite for redundant arms.
 */
#define DH_IK_WBAR 1e-7f

/** Workspace floats needed by dh_ik_f32 for an n-joint robot: n^2 + 20 n + 45
 *  (201 for n = 6, 234 for n = 7). Besides the two Jacobians and the normal
 *  matrix it holds the Jacobian pass's frame, dR and the solver's float
 *  state, so that dh_ik_f32 stays within its stack budget. */
#define DH_IK_WORK_FLOATS(n) ((n) * (n) + 20u * (n) + 45u)

/**
 * @brief Defaults for a robot described in metres: max_iter 2000, mask
 * DH_IK_FULL, tol_pos 1e-6 (m), tol_rot 1e-5 (rad), w_rot 1 (m/rad),
 * restarts 200. Typical solves take 8..60 steps on average
 * (docs/accuracy_kin.md); the bound only matters for hard targets and for
 * unreachable targets within the reach bound (out of the joint box, or a
 * local minimum), which can take all 2000 steps (1.3 ms on an x86-64 host
 * for a 6-joint arm); targets beyond the reach bound stop after a few
 * attempts (Puma 560, 10 m away: about 40 steps). Lower max_iter for a
 * tighter worst case: with 400 / 40 the Puma 560 success rate drops to
 * 98.2..99.4% depending on the target set.
 * For a millimetre robot use tol_pos ~1e-3 and w_rot ~1000 (the float
 * resolution of a 1000 mm coordinate is 6e-5 mm).
 */
void dh_ik_params_default(dh_ik_params *p);

/**
 * @brief Numerical inverse kinematics: Levenberg-Marquardt with Sugihara's
 * damping (seed 003 / T. Sugihara 2011).
 *
 * Minimises E = 1/2 (|e_pos|^2 + w_rot^2 |e_rot|^2) over the masked
 * components of dh_pose_error_f32(target, FK(q)), in the scaled variables
 * x = q in radians (revolute) and q / L (prismatic; L = sum of |a|, |d|,
 * prismatic travel and tool offset): each step solves
 * (J^T J + (mu E + DH_IK_WBAR L^2) I) dx = J^T e by an LDL^T
 * factorisation, with mu = 1
 * (Sugihara) tripled after a rejected step and halved after an accepted
 * one (floor 1e-3). A trial point is accepted only if it lowers E.
 *
 * Joint limits (qmin <= qmax) are enforced inside the iteration: a joint on
 * a bound whose step points outward is removed from the system, which is
 * solved again for the other joints, and the remaining step is clamped into
 * the box. Joints without limits (qmin > qmax) are free, with no wrapping
 * (multi-turn and prismatic joints are safe). q0 outside its limits is first
 * clamped into them.
 *
 * An attempt stalls after 4 steps in a row that lower E by less than 1%
 * (or an empty projected step); it is then restarted from a deterministic
 * pseudo-random configuration in the box (limited joints uniform in their
 * range, free joints q0 +- 180 deg / +- L), up to p->restarts times within
 * p->max_iter steps. The result is the best configuration of all attempts
 * (a converged one first, then the lowest E), and the status says how the
 * attempt that produced it ended (see below).
 * The call is deterministic: same inputs, bitwise same outputs.
 *
 * Reach bound: R = ||B|| (sum over the joints of |a| + |d|, |d + q| at the
 * ends of a prismatic range, + |p_tool|), ||B|| a bound of the base's 3x3
 * norm (1 for a rotation), is an upper bound of |p_end - p_base| within
 * the limits (unbounded with an unlimited prismatic joint). A target whose
 * masked position distance from the base origin exceeds R (1 + 1e-4) +
 * tol_pos cannot be reached: it gets at most 3 restarts (best effort for
 * q) and the result is DH_ERR_UNREACHABLE.
 *
 * Once both tolerances are met, up to 3 further steps refine the solution
 * towards the float resolution of the forward kinematics (a step that does
 * not lower E ends the refinement).
 *
 * @param r      robot (float path), 1..DH_MAX_JOINTS joints.
 * @param target desired end frame (base * A_1..A_n * tool): a rigid-motion
 *               transform, bottom row exactly 0 0 0 1 (every mode), rotation
 *               part orthonormal within DH_ROT_ERROR_TOL with det > 0
 *               (only when a rotation bit is in the mask; position-only
 *               solves do not read it).
 * @param q0     start configuration (n values, deg / length, finite).
 * @param q      result (n values); may alias q0.
 * @param p      parameters (see dh_ik_params).
 * @param work   caller workspace of at least DH_IK_WORK_FLOATS(n) floats,
 *               not overlapping anything else; contents undefined after.
 * @param work_len its length in floats.
 * @param res    iterations and final errors of the returned q.
 *
 * @return the status describes the returned configuration:
 * - DH_OK: both tolerances met;
 * - DH_ERR_NO_CONVERGENCE: the best configuration comes from the attempt
 *   that max_iter cut off while it was still making progress (not
 *   stalled): more steps may converge;
 * - DH_ERR_UNREACHABLE: the best configuration comes from an attempt that
 *   stalled above the tolerance (no step could lower E by 1% in 4 tries: a
 *   local minimum, the target out of reach, joints stuck at limits or a
 *   tolerance below the float resolution), or the target is beyond the
 *   reach bound (decided before the first step; also when its squared
 *   distance overflows E: then no step is taken, q = q0 clamped into the
 *   limits, res.iterations = 0, res.err_pos = the distance computed
 *   without overflow, FLT_MAX if it exceeds FLT_MAX);
 * - DH_ERR_SINGULAR: the best configuration comes from an attempt whose
 *   damped normal matrix could not be factored in float (non-finite
 *   Jacobian);
 *   for these four, q is that configuration, within the limits, and res
 *   describes it;
 * - DH_ERR_ARG: n == 0 or > DH_MAX_JOINTS, work NULL or work_len too small,
 *   max_iter == 0, mask 0 or with unknown bits, negative / non-finite
 *   tolerance, w_rot <= 0, non-finite or so large that w_rot^2 * 16
 *   overflows (w_rot > 4.6e18), float path unavailable, unknown
 *   convention or joint type;
 * - DH_ERR_NAN: non-finite entry in target (any of the 16) or q0;
 * - DH_ERR_NOT_RIGID: target bottom row not exactly 0 0 0 1 (for example
 *   a perspective matrix), or, when the orientation is driven, a target
 *   rotation part not orthonormal within DH_ROT_ERROR_TOL / a reflection,
 *   or an end rotation that is not one (a scaling base or tool);
 * - DH_ERR_OVERFLOW: the forward kinematics of the start is not finite, or
 *   E of the start overflows for a target within the reach bound (a robot
 *   whose reach is unbounded or beyond ~1e19 length units);
 *   for these four, q and res are untouched.
 *
 * Cost per step: one Jacobian pass (n sin/cos, 30 n multiply-adds), the
 * n x n normal matrix (6 n^2 multiply-adds) and an LDL^T solve (n^3/6),
 * repeated at most n times when joints are frozen at limits.
 *
 * Measured (test/test_ik.c, docs/accuracy_kin.md; 1000 random reachable
 * targets per seed, 9 seeds, defaults, true error judged with a double
 * FK): full pose to 1e-6 m / 1e-5 rad, Puma 560 99.4-99.9% (mean 46-57
 * steps; the misses are folded-elbow targets with the wrist centre next to
 * the shoulder, q3 near 92.7 or -87.3 deg), UR5 100% (mean 21-23),
 * Panda 99.9-100% (mean 25-27); the same in millimetre models (Puma
 * 99.4-99.8%); position only 99.9-100% (mean 8-24). Host time per solve
 * (x86-64, -O2) 30-80 us on average.
 *
 * Stack: worst-case chain including callees and libgcc (tools/dh_stack.py,
 * checked against 256 bytes by tools/check_guards.sh): 232 / 240 bytes on
 * Cortex-M0+ and 200 / 192 on Cortex-M4F at -Os / -O2 (deepest: the
 * Jacobian pass, or the rotation vector with its atan2). dh_ik_f32's own
 * frame is 104..128 bytes; everything else is in the workspace.
 */
dh_status dh_ik_f32(const dh_robot *r, const dh_mat4_f32 *target, const float *q0, float *q,
                    const dh_ik_params *p, float *work, size_t work_len, dh_ik_result *res);

#ifdef __cplusplus
}
#endif

#endif /* DHMATH_DH_KIN_H */
