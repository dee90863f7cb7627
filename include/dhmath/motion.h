/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Index: the functions of motion.h by source file (src/motion/).
 *   dh_interp.c      dh_slerp_f32, dh_pose_interp_f32, dh_pose_angle_f32
 *   dh_profile.c     dh_profile_trap_f32, dh_profile_scurve_f32,
 *                    dh_profile_quintic_f32, dh_profile_stretch_f32,
 *                    dh_profile_eval_f32
 *   dh_joint_move.c  dh_joint_move_f32, dh_joint_move_eval_f32
 *   dh_path.c        dh_path_line_f32, dh_path_arc_f32, dh_path_eval_f32,
 *                    dh_path_move_f32, dh_path_move_jerk_f32,
 *                    dh_path_move_eval_f32
 *   dh_blend.c       dh_blend_plan_f32, dh_blend_eval_f32,
 *                    dh_blend_seq_plan_f32, dh_blend_seq_eval_f32,
 *                    dh_blend_seq_plan_jerk_f32
 *   dh_move.c        dh_move_joint_f32, dh_move_joint_step_f32,
 *                    dh_move_path_f32, dh_move_path_jerk_f32,
 *                    dh_move_target_f32, dh_move_advance_f32
 *   dh_queue.c       dh_queue_init_f32, dh_queue_add_joint_f32,
 *                    dh_queue_add_path_f32, dh_queue_add_path_blend_f32,
 *                    dh_queue_add_path_jerk_f32, dh_queue_add_path_blend_jerk_f32,
 *                    dh_queue_target_f32,
 *                    dh_queue_advance_f32, dh_queue_stop_f32,
 *                    dh_queue_resume_f32
 *   dh_interp_q.c    dh_slerp_q, dh_pose_interp_q, dh_pose_angle_q
 *   dh_profile_q.c   dh_profile_trap_q, dh_profile_scurve_q,
 *                    dh_profile_quintic_q, dh_profile_stretch_q,
 *                    dh_profile_eval_q
 *   dh_joint_move_q.c dh_joint_move_q, dh_joint_move_eval_q
 *   dh_path_q.c      dh_path_line_q, dh_path_arc_q, dh_path_eval_q,
 *                    dh_path_move_q, dh_path_move_jerk_q, dh_path_move_eval_q
 *   dh_move_q.c      dh_move_joint_q, dh_move_joint_step_q, dh_move_path_q,
 *                    dh_move_path_jerk_q, dh_move_target_q, dh_move_advance_q
 *   dh_blend_q.c     dh_blend_seq_plan_q, dh_blend_seq_eval_q
 */
/**
 * @file motion.h
 * @brief Motion primitives: pose interpolation (position linear,
 *        orientation along the shortest great arc), rest-to-rest time
 *        scaling (trapezoidal, jerk-limited seven-phase, quintic) and the
 *        synchronised point-to-point joint move, Cartesian paths and
 *        their moves, and the move executor that runs a joint move, or a
 *        Cartesian move through the caller's tracker, one control period
 *        per call.
 *
 * Conventions:
 * - a path parameter s is in [0, 1]; angles at the API are in DEGREES;
 * - a profile moves a scalar from 0 to a signed distance d (any length or
 *   angle unit u) in a time T (any time unit, s below); velocity is in u/s,
 *   acceleration u/s^2, jerk u/s^3. Limits are magnitudes (> 0) and hold
 *   for either sign of d;
 * - every profile is rest to rest: zero velocity and acceleration at t = 0
 *   and t = T, symmetric in time (v(T - t) = v(t), a(T - t) = -a(t)), and
 *   evaluated from its nearer end, so that p(0) = 0 and p(T) = d exactly.
 *
 * Pointers must not be NULL (checked with DH_ASSERT). On a non-OK status
 * every output is left untouched. The float functions use float only (no
 * double, no libm); the fixed ones (section "Fixed point") integers only.
 * All are reentrant, use no heap and less than 256 bytes of stack.
 * Methods: docs/design.md ("Motion").
 */
#ifndef DHMATH_MOTION_H
#define DHMATH_MOTION_H

#include "dhmath/common.h"
#include "dhmath/rot.h"
#include "dhmath/track.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ======================================================================
 * Pose interpolation
 * ==================================================================== */

/**
 * @brief Spherical linear interpolation (Shoemake 1985) along the SHORTEST
 *        great arc from a to b: out = a (a* b)^s, b replaced by -b when
 *        a . b < 0 (q and -q are the same rotation).
 * @param a, b quaternions with finite components and a normal largest
 *        component (normalised here, as dh_quat_normalize_f32).
 * @param s path parameter in [0, 1].
 * @param out unit quaternion: s == 0 gives a / |a| and s == 1 gives
 *        +-b / |b| (the sign of the shortest arc) bit for bit as
 *        dh_quat_normalize_f32 returns them. The rotation angle from a to
 *        out is s times the angle from a to b (uniform angular speed).
 * At exactly 180 degrees (a . b == 0) both arcs are equally short; b is
 * taken as given (not negated), so the rotation axis of the path is that
 * of a* b. Near 180 degrees the path flips to the other arc when the sign
 * of a . b changes: inherent to a shortest-arc rule.
 * @return DH_OK; DH_ERR_NAN for a NaN/Inf component or s; DH_ERR_ARG for s
 *         outside [0, 1]; DH_ERR_ZERO_AXIS for a zero or denormal a or b.
 *         out may alias a or b.
 * Components within 1e-6 of the exact interpolation of a/|a| and b/|b|.
 */
dh_status dh_slerp_f32(const dh_quat_f32 *a, const dh_quat_f32 *b, float s, dh_quat_f32 *out);

/**
 * @brief T = the pose at s between the rigid frames A and B: position
 *        p_A + s (p_B - p_A), rotation along the shortest great arc from
 *        R_A to R_B at uniform angular speed (dh_slerp_f32 of their unit
 *        quaternions, dh_mat3_to_quat_f32).
 * @param A, B rigid frames: accepted by dh_mat4_check_rigid_f32(., DH_ROT_TOL).
 * @param s path parameter in [0, 1]; s == 0 gives T == A and s == 1 gives
 *        T == B bit for bit.
 * @param T output frame (bottom row 0 0 0 1). At 180 degrees between R_A
 *        and R_B the arc is chosen as in dh_slerp_f32.
 * @return DH_OK; DH_ERR_NAN for a NaN/Inf entry or s; DH_ERR_NOT_RIGID if
 *         A or B is not a rigid frame; DH_ERR_ARG for s outside [0, 1];
 *         DH_ERR_OVERFLOW when p_B - p_A overflows. T untouched on error;
 *         T may alias A or B.
 * Rotation entries within 2e-6 of the exact interpolation of the input
 * rotations; position within 2 ulp of the largest position magnitude.
 */
dh_status dh_pose_interp_f32(const dh_mat4_f32 *A, const dh_mat4_f32 *B, float s, dh_mat4_f32 *T);

/**
 * @brief deg = the angle in [0, 180] degrees of the rotation R_A^T R_B
 *        that takes frame A's orientation to frame B's (the length of the
 *        shortest arc of dh_pose_interp_f32).
 * @param A, B rigid frames (dh_mat4_check_rigid_f32(., DH_ROT_TOL)).
 * @param deg output angle: atan2(|vee(M - M^T)|, tr M - 1) with
 *        M = R_A^T R_B (2 sin t and 2 cos t), no acos near +-1, so small
 *        angles and those near 180 degrees are accurate.
 * @return DH_OK; DH_ERR_NAN for a NaN/Inf entry; DH_ERR_NOT_RIGID if A or
 *         B is not a rigid frame. deg untouched on error.
 * Error <= 1e-4 degrees against the angle of the float rotations.
 */
dh_status dh_pose_angle_f32(const dh_mat4_f32 *A, const dh_mat4_f32 *B, float *deg);

/* ======================================================================
 * Time scaling (rest-to-rest profiles)
 * ==================================================================== */

/** @brief The form of a dh_profile_f32. */
typedef enum {
    DH_PROFILE_TRAP = 0,   /**< trapezoidal velocity: acceleration +-a or 0 */
    DH_PROFILE_SCURVE = 1, /**< seven phases: jerk +-j or 0 */
    DH_PROFILE_QUINTIC = 2 /**< quintic polynomial d (10 x^3 - 15 x^4 + 6 x^5), x = t / T */
} dh_profile_kind;

/**
 * @brief A rest-to-rest profile from 0 to d, written by the dh_profile_*
 *        initialisers and read by dh_profile_eval_f32 (read-only for the
 *        user). Phases of the trapezoid and the seven-phase profile:
 *        jerk +j for tj, accel +a for ta - 2 tj, jerk -j for tj, cruise
 *        at v for tv, then the mirror image; T = 2 ta + tv.
 */
typedef struct {
    float d;  /**< signed distance (u) */
    float T;  /**< duration (s); 0 when d == 0 and nothing stretched it */
    float tj; /**< duration of each jerk phase (0 for the trapezoid and the quintic) */
    float ta; /**< duration of the acceleration phase, jerk phases included (0 for the quintic) */
    float tv; /**< duration of the cruise phase (0 for the quintic) */
    float v;  /**< peak |velocity| (u/s) */
    float a;  /**< peak |acceleration| (u/s^2) */
    float j;  /**< peak |jerk| (u/s^3); 0 for the trapezoid (unbounded) */
    uint32_t kind; /**< form of the profile: a dh_profile_kind value (a word, so no padding) */
} dh_profile_f32;

/**
 * @brief p = the time-optimal trapezoidal profile for |d| within vmax and
 *        amax: T = |d|/vmax + vmax/amax when |d| >= vmax^2/amax (vmax is
 *        reached), else T = 2 sqrt(|d|/amax) (a triangle).
 * @param p output profile (kind DH_PROFILE_TRAP, j = 0).
 * @param d signed distance, any finite value (0 gives T = 0).
 * @param vmax, amax limits, finite and > 0.
 * p->v <= vmax and p->a <= amax exactly (the peaks are recomputed from the
 * rounded phase times and then held to the limits); T within 4 float
 * roundings of the formula.
 * @return DH_OK; DH_ERR_NAN for a NaN/Inf argument; DH_ERR_ARG for a limit
 *         <= 0; DH_ERR_OVERFLOW when the duration or a peak is not a
 *         positive finite float (d and the limits too far apart for float).
 *         p untouched on error.
 */
dh_status dh_profile_trap_f32(dh_profile_f32 *p, float d, float vmax, float amax);

/**
 * @brief p = the time-optimal seven-phase (jerk-limited, "double S")
 *        rest-to-rest profile for |d| within vmax, amax and jmax
 *        (Biagiotti & Melchiorri 2008, 3.4): the jerk is +-jmax or 0, and
 *        the cruise and the constant-acceleration phases appear only when
 *        |d| is long enough to reach vmax and amax (both, one or neither).
 * @param p output profile (kind DH_PROFILE_SCURVE).
 * @param d signed distance, any finite value (0 gives T = 0).
 * @param vmax, amax, jmax limits, finite and > 0.
 * p->v <= vmax, p->a <= amax and p->j <= jmax exactly; T within 8 float
 * roundings of the minimum (docs/design.md, "Motion").
 * @return DH_OK; DH_ERR_NAN for a NaN/Inf argument; DH_ERR_ARG for a limit
 *         <= 0; DH_ERR_OVERFLOW when the duration or a peak is not a
 *         positive finite float. p untouched on error.
 */
dh_status dh_profile_scurve_f32(dh_profile_f32 *p, float d, float vmax, float amax, float jmax);

/**
 * @brief p = the quintic d (10 x^3 - 15 x^4 + 6 x^5), x = t / T, of the
 *        given duration: zero velocity and acceleration at both ends; peaks
 *        v = 1.875 |d| / T, a = 5.7735 |d| / T^2, j = 60 |d| / T^3.
 * @param p output profile (kind DH_PROFILE_QUINTIC, tj = ta = tv = 0).
 * @param d signed distance, any finite value.
 * @param T duration, finite and > 0.
 * @return DH_OK; DH_ERR_NAN for a NaN/Inf argument; DH_ERR_ARG for T <= 0;
 *         DH_ERR_OVERFLOW when a peak is not finite. p untouched on error.
 */
dh_status dh_profile_quintic_f32(dh_profile_f32 *p, float d, float T);

/**
 * @brief Stretches p to the longer duration T by uniform time scaling,
 *        p(t) -> p(t / k), k = T / p->T >= 1: the same distance, every
 *        phase k times longer, peaks v / k, a / k^2, j / k^3, so the
 *        profile stays within any limits it met (a profile with d == 0
 *        only takes the new T).
 * @param p profile from a dh_profile_* initialiser, modified in place.
 * @param T new duration, finite and >= p->T (T == p->T leaves p as it is).
 * The new peaks never exceed the old ones.
 * @return DH_OK; DH_ERR_NAN for a NaN/Inf T; DH_ERR_ARG for T < p->T;
 *         DH_ERR_OVERFLOW when a new peak or phase time is not a positive
 *         finite float (k so large that it underflows). p untouched on error.
 */
dh_status dh_profile_stretch_f32(dh_profile_f32 *p, float T);

/**
 * @brief Position, velocity and acceleration of the profile p at time t.
 * @param p profile from a dh_profile_* function.
 * @param t time (s), any value but NaN: clamped to [0, p->T] (t <= 0 gives
 *        0, 0, 0; t >= p->T gives d, 0, 0 exactly).
 * @param pos, vel, acc outputs; |vel| <= p->v and |acc| <= p->a always.
 * For t > T/2 the mirror image of the first half is evaluated (from d
 * back), so both ends are exact; the two halves meet within 2 ulp of |d|.
 * @return DH_OK; DH_ERR_NAN for a NaN t (outputs untouched).
 */
dh_status dh_profile_eval_f32(const dh_profile_f32 *p, float t, float *pos, float *vel, float *acc);

/* ======================================================================
 * Synchronised joint move
 * ==================================================================== */

/**
 * @brief Point-to-point move of n joints from q0 to q1 that brings every
 *        joint to rest at the same time T, each within its own limits,
 *        with T as short as the slowest joint allows: each joint's
 *        time-optimal profile (dh_profile_scurve_f32, or
 *        dh_profile_trap_f32 when jmax is NULL), then every profile
 *        stretched to the longest duration by dh_profile_stretch_f32.
 * @param prof output: n profiles of q1[i] - q0[i], all with prof[i].T == T.
 * @param n number of joints, >= 1.
 * @param q0, q1 start and end positions (n each, finite).
 * @param vmax, amax, jmax per-joint limits (n each, finite, > 0); jmax may
 *        be NULL (trapezoids).
 * @return DH_OK; DH_ERR_ARG for n == 0 or a limit <= 0; DH_ERR_NAN for a
 *         NaN/Inf value; DH_ERR_OVERFLOW when q1[i] - q0[i] or a profile
 *         overflows or its stretch underflows (as dh_profile_trap_f32,
 *         _scurve_f32, _stretch_f32). On error every prof[i] is all zero:
 *         no move and duration 0, so evaluating it keeps the joints at q0.
 */
dh_status dh_joint_move_f32(dh_profile_f32 *prof, uint32_t n, const float *q0, const float *q1,
                            const float *vmax, const float *amax, const float *jmax);

/**
 * @brief Joint positions, velocities and accelerations of a joint move at
 *        time t: q = q0 + p_i(t) for t <= T/2, q1 - (d_i - p_i(t)) after,
 *        so t <= 0 gives q0 and t >= T gives q1 bit for bit; a joint whose
 *        profile has d_i == 0 stays at q0 (the no move of a failed call).
 * @param prof, n, q0, q1 the move of dh_joint_move_f32 and its endpoints.
 * @param t time (s), any value but NaN (clamped as dh_profile_eval_f32).
 * @param q, qd, qdd outputs (n each).
 * @return DH_OK; DH_ERR_ARG for n == 0; DH_ERR_NAN for a NaN t. Outputs
 *         untouched on error.
 */
dh_status dh_joint_move_eval_f32(const dh_profile_f32 *prof, uint32_t n, const float *q0, const float *q1,
                                 float t, float *q, float *qd, float *qdd);

/* ======================================================================
 * Cartesian paths and moves
 * ==================================================================== */

/** @brief The form of a dh_path_f32. */
typedef enum {
    DH_PATH_LINE = 0, /**< straight line from p_A to p_B */
    DH_PATH_ARC = 1   /**< circular arc from p_A through a via point to p_B */
} dh_path_kind;

/**
 * @brief A Cartesian path from frame A to frame B, written by
 *        dh_path_line_f32 / dh_path_arc_f32 and read by dh_path_eval_f32
 *        (read-only for the user, who reads length, angle, radius and
 *        sweep). Position advances along the line or arc in proportion to
 *        s, orientation along the shortest arc from R_A to R_B in
 *        proportion to s (as dh_pose_interp_f32).
 */
typedef struct {
    dh_mat4_f32 A;   /**< start frame (s = 0) */
    dh_mat4_f32 B;   /**< end frame (s = 1) */
    float u0[3];     /**< arc: p_A - centre (0 for a line) */
    float u1[3];     /**< arc: p_B - centre (0 for a line) */
    float n[3];      /**< arc: unit normal; the arc turns counterclockwise about it (0 for a line) */
    dh_quat_f32 qa;  /**< unit quaternion of R_A (dh_mat3_to_quat_f32) */
    dh_quat_f32 qb;  /**< unit quaternion of R_B, of the sign with qa . qb >= 0 (the shorter arc) */
    float length;    /**< position length of the path (the user's length unit) */
    float angle;     /**< rotation angle from R_A to R_B, degrees in [0, 180] (dh_pose_angle_f32) */
    float radius;    /**< arc radius (0 for a line) */
    float sweep;     /**< arc angle about the centre, degrees in (0, 360) (0 for a line) */
    uint32_t kind;   /**< a dh_path_kind value */
} dh_path_f32;

/**
 * @brief p = the straight line from frame A to frame B: position
 *        p_A + s (p_B - p_A), orientation slerped along the shortest arc.
 * @param p output path (kind DH_PATH_LINE); p->length = |p_B - p_A| (no
 *        overflow of the squares), p->angle as dh_pose_angle_f32.
 * @param A, B rigid frames (dh_mat4_check_rigid_f32(., DH_ROT_TOL)); equal
 *        positions are fine (a pure rotation, length 0).
 * @return DH_OK; DH_ERR_NAN for a NaN/Inf entry; DH_ERR_NOT_RIGID if A or
 *         B is not a rigid frame; DH_ERR_OVERFLOW when p_B - p_A or its
 *         length overflows. p untouched on error.
 * length within 4 FLT_EPSILON length, angle as dh_pose_angle_f32 (1e-4 degrees).
 */
dh_status dh_path_line_f32(dh_path_f32 *p, const dh_mat4_f32 *A, const dh_mat4_f32 *B);

/**
 * @brief p = the circular arc from p_A through the point via to p_B (the
 *        circle through the three points, traversed p_A -> via -> p_B),
 *        orientation slerped along the shortest arc from R_A to R_B.
 * @param p output path (kind DH_PATH_ARC): radius, sweep (degrees),
 *        length = radius * sweep in radians, angle as dh_pose_angle_f32.
 * @param A, B rigid frames (dh_mat4_check_rigid_f32(., DH_ROT_TOL)).
 * @param via a point on the arc (3 floats, the position unit of A and B).
 * The triangle p_A, via, p_B must not be thin: |a x b| > 2^-10 L^2 with
 * a = via - p_A, b = p_B - p_A and L its longest side, so the radius is
 * at most 512 L (a flatter arc is a line).
 * @return DH_OK; DH_ERR_NAN for a NaN/Inf entry or via; DH_ERR_NOT_RIGID
 *         if A or B is not a rigid frame; DH_ERR_OVERFLOW when a side of
 *         the triangle overflows; DH_ERR_SINGULAR for collinear or
 *         coincident points (the thin triangle above). p untouched on error.
 * radius within E = 16 FLT_EPSILON (S + R + L) / (|a x b| / L^2) of the
 * circle through the three points (S the largest of |p_A|, |via|, |p_B|),
 * sweep within 2 E / R + 2 FLT_EPSILON sweep (radians), length within 9 E.
 */
dh_status dh_path_arc_f32(dh_path_f32 *p, const dh_mat4_f32 *A, const float via[3], const dh_mat4_f32 *B);

/**
 * @brief T = the frame of the path p at s: position at the fraction s of
 *        the length along the line or arc, rotation at the fraction s of
 *        p->angle along the shortest arc (the slerp of dh_pose_interp_f32).
 * @param p path from dh_path_line_f32 or dh_path_arc_f32.
 * @param s path parameter, any value but NaN: clamped to [0, 1]; s <= 0
 *        gives T == p->A and s >= 1 gives T == p->B bit for bit.
 * @param T output frame (must not alias p).
 * The arc is evaluated from its nearer end (p_A + (cos phi - 1) u0 +
 * sin phi n x u0, phi = s sweep, and the mirror image from p_B).
 * @return DH_OK; DH_ERR_NAN for a NaN s; DH_ERR_ARG when p holds no path
 *         (quaternions not unit: e.g. all zero). T untouched on error.
 * Position within 4 FLT_EPSILON S of the exact line, within 3 E (see
 * dh_path_arc_f32) of the exact arc at s; rotation as dh_pose_interp_f32.
 */
dh_status dh_path_eval_f32(const dh_path_f32 *p, float s, dh_mat4_f32 *T);

/**
 * @brief Cartesian limits of a move: magnitudes of the tool point's speed
 *        and TOTAL acceleration (tangential and centripetal) and of the
 *        tool's angular speed and acceleration.
 */
typedef struct {
    float vmax; /**< linear speed (length unit / s) */
    float amax; /**< linear acceleration, total: |d^2 p / dt^2| (length unit / s^2) */
    float wmax; /**< angular speed (deg/s) */
    float wdmax; /**< angular acceleration (deg/s^2) */
} dh_cart_limits_f32;

/**
 * @brief prof = the time-optimal trapezoidal profile of s from 0 to 1
 *        along the path p within lim: s' <= min(V / length, wmax / angle),
 *        s'' <= min(At / length, wdmax / angle) (terms of length or angle
 *        0 left out), V and At the speed and tangential acceleration of
 *        the tool point: on a line V = vmax, At = amax; on an arc of
 *        radius R, V = min(vmax, sqrt(amax R / sqrt 2)) and
 *        At = sqrt(amax^2 - (V^2 / R)^2), so the centripetal acceleration
 *        is at most amax / sqrt 2 and the total at most amax.
 * @param prof output (dh_profile_trap_f32 of d = 1, or of d = 0 when
 *        length and angle are 0: T = 0).
 * @param p path from dh_path_line_f32 or dh_path_arc_f32.
 * @param lim limits, each finite and > 0.
 * Speed, acceleration and angular rates within their limits up to float
 * rounding (1e-6 relative).
 * @return DH_OK; DH_ERR_NAN for a NaN/Inf limit; DH_ERR_ARG for a limit
 *         <= 0; DH_ERR_OVERFLOW when a limit of s or the profile is not
 *         a positive finite float. On error *prof is all zero: no move,
 *         duration 0, so dh_path_move_eval_f32 keeps the frame at p->A.
 */
dh_status dh_path_move_f32(dh_profile_f32 *prof, const dh_path_f32 *p, const dh_cart_limits_f32 *lim);

/**
 * @brief Jerk limits of a Cartesian move (dh_path_move_jerk_f32):
 *        magnitudes of the tool point's TOTAL jerk |d^3 p / dt^3| and of
 *        the tool's angular jerk.
 */
typedef struct {
    float jmax;  /**< linear jerk, total: |d^3 p / dt^3| (length unit / s^3) */
    float wjmax; /**< angular jerk (deg/s^3) */
} dh_cart_jerk_f32;

/**
 * @brief prof = the time-optimal scaling of s from 0 to 1 along the path p
 *        within lim and the jerk limits jerk: the seven-phase profile
 *        (dh_profile_scurve_f32 of d = 1) with s' and s'' bounded as in
 *        dh_path_move_f32 and s''' <= min(Jt / length, wjmax / angle).
 *        On a line V, At as dh_path_move_f32 and Jt = jmax. On an arc of
 *        radius R the tool point's jerk is (x''' - x'^3 / R^2) t +
 *        (3 x' x'' / R) n (x the arc length), so V = min(vmax,
 *        sqrt(amax R / sqrt 2), cbrt(jmax R^2 / 4)), At = min(
 *        sqrt(amax^2 - (V^2 / R)^2), jmax R / (12 V)), Jt = jmax / 2: the
 *        TOTAL jerk is at most jmax and the total acceleration at most amax.
 * @param prof output (kind DH_PROFILE_SCURVE; d = 0 and T = 0 when length
 *        and angle are 0).
 * @param p path from dh_path_line_f32 or dh_path_arc_f32.
 * @param lim limits, each finite and > 0.
 * @param jerk jerk limits, each finite and > 0; NULL: no jerk limit, prof
 *        is that of dh_path_move_f32 (a trapezoid) bit for bit.
 * Speed, acceleration, jerk and angular rates within their limits up to
 * float rounding (1e-6 relative).
 * @return DH_OK; DH_ERR_NAN for a NaN/Inf limit; DH_ERR_ARG for a limit
 *         <= 0; DH_ERR_OVERFLOW when a limit of s or the profile is not
 *         a positive finite float. On error *prof is all zero (as
 *         dh_path_move_f32).
 */
dh_status dh_path_move_jerk_f32(dh_profile_f32 *prof, const dh_path_f32 *p, const dh_cart_limits_f32 *lim,
                                const dh_cart_jerk_f32 *jerk);

/**
 * @brief T = the frame of the move (prof, p) at time t: dh_path_eval_f32
 *        at s = the profile's position; v = the tool point's speed
 *        p->length * ds/dt (>= 0).
 * @param prof, p the move of dh_path_move_f32 or dh_path_move_jerk_f32
 *        and its path.
 * @param t time (s), any value but NaN (clamped as dh_profile_eval_f32):
 *        t <= 0 gives p->A and t >= prof->T gives p->B bit for bit; a
 *        profile with d == 0 (no motion, or a failed call) keeps p->A.
 * @param T output frame (must not alias p).
 * @param v output: the tool point's speed (length unit / s).
 * @return DH_OK; DH_ERR_NAN for a NaN t; DH_ERR_ARG when p holds no path
 *         (as dh_path_eval_f32). T and v untouched on error.
 */
dh_status dh_path_move_eval_f32(const dh_profile_f32 *prof, const dh_path_f32 *p, float t, dh_mat4_f32 *T,
                                float *v);

/* ======================================================================
 * Move executor (one call per control period)
 * ==================================================================== */

/** @brief The form of a dh_move_f32 (0: no move). */
typedef enum {
    DH_MOVE_NONE = 0,  /**< no move: written by a failed constructor, or by none (all zero) */
    DH_MOVE_JOINT = 1, /**< synchronised joint move (dh_move_joint_f32) */
    DH_MOVE_PATH = 2   /**< Cartesian path move (dh_move_path_f32) */
} dh_move_kind;

/**
 * @brief One move being executed, written by dh_move_joint_f32 /
 *        dh_move_path_f32 and advanced once per control period by
 *        dh_move_joint_step_f32 / dh_move_advance_f32 (read-only for the
 *        user, who reads dur and clock).
 */
typedef struct {
    dh_profile_f32 prof[DH_MAX_JOINTS]; /**< joint move: one per joint; path move: prof[0], of s */
    dh_path_f32 path;                   /**< path move: a copy of the path */
    float q0[DH_MAX_JOINTS];            /**< joint move: start configuration */
    float q1[DH_MAX_JOINTS];            /**< joint move: end configuration */
    float ws[2][DH_MAX_JOINTS];         /**< joint move: workspace (planning limits, velocity, acceleration) */
    float dur;                          /**< duration of the move (s) */
    float clock;                        /**< time into the move (s), in [0, dur] */
    float feed;                         /**< path move: feed override r in [0, 1], d clock / dt (1 otherwise) */
    float fcap;                         /**< path move: ceiling of r, in [0, 1] (dh_move_advance_f32) */
    uint32_t lag;                       /**< path move: 1 when the last period was not OK */
    uint32_t n;                         /**< joint move: number of joints */
    uint32_t kind;                      /**< a dh_move_kind value */
} dh_move_f32;

/** @brief What one period of a move did. */
typedef struct {
    float clock; /**< time into the move after this period (s) */
    float feed;  /**< path move: the feed override r after this period, in [0, 1]; joint move: 1 */
    int held;    /**< path move: 1 when the tracker was not OK this period (r falls); joint move: 0 */
    int done;    /**< 1 when the move is complete (see dh_move_advance_f32, dh_move_joint_step_f32) */
} dh_move_report_f32;

/**
 * @brief Starts a synchronised joint move of n joints from q0 to q1,
 *        sampled once per period by dh_move_joint_step_f32 (no tracker:
 *        the samples are within the limits by construction).
 * @param mv output move (kind DH_MOVE_JOINT, clock 0, dur the move's T).
 * @param n number of joints, 1..DH_MAX_JOINTS.
 * @param q0, q1 start and end positions (n each, finite; may alias).
 * @param vmax, amax, jmax per-joint limits (n each, finite, > 0); jmax may
 *        be NULL (trapezoids). The move is planned by dh_joint_move_f32
 *        within vmax and amax lowered by 2^-10 (jmax as given), a margin
 *        for the rounding of the sampled steps (dh_move_joint_step_f32).
 * @return DH_OK; DH_ERR_ARG for n outside 1..DH_MAX_JOINTS or a limit
 *         <= 0; DH_ERR_NAN for a NaN/Inf value; DH_ERR_OVERFLOW as
 *         dh_joint_move_f32. On error mv holds no move (kind
 *         DH_MOVE_NONE): the step functions return DH_ERR_ARG on it, so a
 *         failed start never resumes an older move.
 */
dh_status dh_move_joint_f32(dh_move_f32 *mv, uint32_t n, const float *q0, const float *q1, const float *vmax,
                            const float *amax, const float *jmax);

/**
 * @brief One control period of a joint move: the clock advances by dt
 *        (capped at dur) and q = the move at the new clock
 *        (dh_joint_move_eval_f32).
 * Let c, c' be the clock before and after the call (c' - c <= dt up to
 * the rounding of the sum). Each joint's step q(c') - q(c) is within
 * vmax_i (1 - 2^-10) (c' - c) + e_i and its change of step within
 * amax_i (1 - 2^-10) dt^2 + 2 e_i, e_i = vmax_i 2 ulp(dur) +
 * 4 ulp(max(|q0_i|, |q1_i|)) + 4 ulp(|q1_i - q0_i|) the rounding of the
 * clock and of q (changes of step for equal periods); so each step is
 * within vmax_i dt itself wherever e_i + vmax_i ulp(dur) <= 2^-10
 * vmax_i dt.
 * @param mv move from dh_move_joint_f32.
 * @param dt control period (s), finite, > 0 (may differ between calls).
 * @param q output: n joint values (must not alias mv); q == q1 bit for
 *        bit once the clock is at dur.
 * @param rep report: clock c'; held 0; done 1 when c' == dur (then
 *        q == q1; every later call returns q1 and done again).
 * @return DH_OK; DH_ERR_NAN for a NaN/Inf dt; DH_ERR_ARG for dt <= 0 or an
 *         mv that holds no joint move (written by no constructor, a failed
 *         one, or dh_move_path_f32). On error mv, q and rep are untouched.
 */
dh_status dh_move_joint_step_f32(dh_move_f32 *mv, float dt, float *q, dh_move_report_f32 *rep);

/**
 * @brief Starts a Cartesian move along the path p within lim
 *        (dh_path_move_f32), executed by the caller's tracker: each
 *        period dh_move_target_f32 gives the frame to track, the caller
 *        calls dh_track_step_f32 on it, and dh_move_advance_f32 advances
 *        the clock with the tracker's state.
 * Start: the move does not check where the robot is. Its first target is
 * p->A; the clock holds until the tracker reports OK there, so a tool
 * away from p->A is brought onto it by the tracker within the tracker's
 * rate and acceleration bounds, and the move starts from there. The feed
 * override r starts at 1 (dh_move_advance_f32).
 * @param mv output move (kind DH_MOVE_PATH, clock 0, dur the profile's T;
 *        p copied).
 * @param p path from dh_path_line_f32 or dh_path_arc_f32.
 * @param lim Cartesian limits, each finite and > 0.
 * @return DH_OK; DH_ERR_NAN for a NaN/Inf limit; DH_ERR_ARG for a limit
 *         <= 0 or a p that holds no path (as dh_path_eval_f32);
 *         DH_ERR_OVERFLOW as dh_path_move_f32. On error mv holds no move
 *         (as dh_move_joint_f32).
 */
dh_status dh_move_path_f32(dh_move_f32 *mv, const dh_path_f32 *p, const dh_cart_limits_f32 *lim);

/**
 * @brief Starts a jerk-limited Cartesian move along the path p within lim
 *        and jerk (dh_path_move_jerk_f32), executed as a move of
 *        dh_move_path_f32 (dh_move_target_f32, dh_move_advance_f32; the
 *        same start and holding of the clock).
 * @param mv output move (kind DH_MOVE_PATH, clock 0, dur the profile's T;
 *        p copied).
 * @param p path from dh_path_line_f32 or dh_path_arc_f32.
 * @param lim Cartesian limits, each finite and > 0.
 * @param jerk jerk limits, each finite and > 0; NULL: the move of
 *        dh_move_path_f32.
 * @return DH_OK; DH_ERR_NAN for a NaN/Inf limit; DH_ERR_ARG for a limit
 *         <= 0 or a p that holds no path (as dh_path_eval_f32);
 *         DH_ERR_OVERFLOW as dh_path_move_jerk_f32. On error mv holds no
 *         move (as dh_move_joint_f32).
 */
dh_status dh_move_path_jerk_f32(dh_move_f32 *mv, const dh_path_f32 *p, const dh_cart_limits_f32 *lim,
                                const dh_cart_jerk_f32 *jerk);

/**
 * @brief T = the frame to track this period: the path's frame at the
 *        move's clock (dh_path_move_eval_f32), p->A at clock 0, p->B bit
 *        for bit once the clock is at dur.
 * Between two periods the clock advances by r dt (dh_move_advance_f32),
 * so the target moves by at most r lim->vmax dt in position and
 * r lim->wmax dt in rotation (up to the path's and the profile's rounding,
 * motion.h above), and at r == 0 it does not move.
 * @param mv move from dh_move_path_f32 or dh_move_path_jerk_f32.
 * @param T output frame.
 * @return DH_OK; DH_ERR_ARG for an mv that holds no path move (written by
 *         no constructor, a failed one, or dh_move_joint_f32): T untouched.
 */
dh_status dh_move_target_f32(const dh_move_f32 *mv, dh_mat4_f32 *T);

/**
 * @brief Ends a control period of a path move: state is the tracker's
 *        report (dh_track_report_f32.state) of its step towards this
 *        period's dh_move_target_f32; the clock advances by r dt (capped
 *        at dur), r in [0, 1] the move's feed override.
 * - state OK, clock == dur: done (the tracker reached p->B within its
 *   pos_tol and rot_tol); the clock stays at dur.
 * - state OK, clock < dur: r rises towards its ceiling (1 until the
 *   tracker lagged); with r at 1 the clock advances by dt exactly, so a
 *   move the tracker follows runs its profile bit for bit.
 * - state LAGGING or UNREACHABLE (held 1): r falls towards 0, where the
 *   clock and the target hold; the move slows down on its own schedule
 *   instead of jumping, and stops at a stretch that stays unreachable.
 *   A stretch of such periods while the path moves lowers the ceiling to
 *   7/8 of r at its start; the ceiling rises by 2 r per second of OK
 *   periods at it (relative), so the move settles below the speed the
 *   joints could not follow and speeds up again where they can.
 * r changes each period by at most what keeps the commanded s' r and
 * d(s' r)/dt within the profile's peaks prof[0].v and prof[0].a, so the
 * target's speed, acceleration and angular rates stay within lim (not
 * the jerk of dh_move_path_jerk_f32 while r changes; docs/design.md).
 * At clock 0 (s' = 0) r falls to 0 and rises back at once.
 * @param mv move from dh_move_path_f32 or dh_move_path_jerk_f32.
 * @param dt control period (s), finite, > 0 (the tracker's dt).
 * @param state the tracker's state this period, a dh_track_state value.
 * @param rep report: clock and r after the call, held, done.
 * @return DH_OK; DH_ERR_NAN for a NaN/Inf dt; DH_ERR_ARG for dt <= 0, a
 *         state that is no dh_track_state, or an mv that holds no path
 *         move. On error mv and rep are untouched.
 */
dh_status dh_move_advance_f32(dh_move_f32 *mv, float dt, dh_track_state state, dh_move_report_f32 *rep);

/**
 * @brief The time scaling of s from 0 to 1 of one path of a blended
 *        sequence and its place on the sequence's clock (read-only for
 *        the user, who reads t0, T and dev): a tail at each end at a
 *        reduced acceleration (from rest at b0 for tb0, reaching u0 over
 *        e0; the mirror image at the end: b1, tb1, u1, e1; a tail of
 *        duration 0 is a rest), between them acceleration +-a and a
 *        cruise at v (from u0 up to v at a for t1, cruise tv, down to u1
 *        at a for t3).
 */
typedef struct {
    float v;   /**< peak ds/dt (1/s) */
    float a;   /**< |d2s/dt2| outside the tails (1/s^2) */
    float b0;  /**< |d2s/dt2| in the start tail, <= a */
    float u0;  /**< ds/dt at the end of the start tail: b0 tb0 */
    float e0;  /**< s covered by the start tail: b0 tb0^2 / 2 */
    float tb0; /**< duration of the start tail: the overlap with the line before (0: none) */
    float b1;  /**< |d2s/dt2| in the end tail, <= a */
    float u1;  /**< ds/dt at the start of the end tail: b1 tb1 */
    float e1;  /**< s covered by the end tail: b1 tb1^2 / 2 */
    float tb1; /**< duration of the end tail: the overlap with the line after (0: none) */
    float t1;  /**< duration of the acceleration from u0 to v */
    float tv;  /**< duration of the cruise at v */
    float t3;  /**< duration of the deceleration from v to u1 */
    float T;   /**< duration of the line: tb0 + t1 + tv + t3 + tb1 (jerk-limited: t1 + tv + t3) (0: no motion) */
    float t0;  /**< its start on the sequence's clock (s) */
    float dev; /**< bound on the distance of the tool point from its END corner during that overlap */
    float j;   /**< 0: the trapezoid above. > 0: the jerk-limited scaling of dh_blend_seq_plan_jerk_f32, the line's bound of |d3s/dt3| (1/s^3): from rest to v over t1 (|s''| <= b0, |s'''| <= k0, ramps tj1), cruise tv, to rest over t3 (b1, k1, tj3); tb0 and tb1 are the overlaps, inside t1 / 2 and t3 / 2; u0, e0 the s' and s at tb0, u1, e1 at T - tb1 (s' and 1 - s); tb0 + t1 + ... is then not T */
    float k0;  /**< jerk-limited: |d3s/dt3| of the acceleration from rest (1/s^3) */
    float k1;  /**< jerk-limited: |d3s/dt3| of the deceleration to rest (1/s^3) */
    float tj1; /**< jerk-limited: duration of each jerk phase of the acceleration (s) */
    float tj3; /**< jerk-limited: duration of each jerk phase of the deceleration (s) */
} dh_blend_seg_f32;

/* ======================================================================
 * Move queue, stop and resume (one call pair per control period)
 * ==================================================================== */

/** @brief The state of a dh_queue_f32 (its phase field). */
typedef enum {
    DH_QUEUE_RUN = 0,     /**< moves run (or the queue is empty and the next one appended starts) */
    DH_QUEUE_BRAKE = 1,   /**< the running move is being brought to rest after dh_queue_stop_f32 */
    DH_QUEUE_STOPPED = 2  /**< at rest after a stop; dh_queue_resume_f32 continues */
} dh_queue_phase;

/**
 * @brief One queued move as its constructor takes it (read-only for the
 *        user): a joint move to q1 (dh_move_joint_f32 without q0: it
 *        starts where the robot is when it starts) or a path move
 *        (dh_move_path_f32, planned when appended).
 */
typedef struct {
    dh_path_f32 path;              /**< path move: the path */
    dh_profile_f32 prof;           /**< path move: its profile of s (dh_path_move_f32, dh_path_move_jerk_f32) */
    float q1[DH_MAX_JOINTS];       /**< joint move: end configuration */
    float vmax[DH_MAX_JOINTS];     /**< joint move: velocity limits */
    float amax[DH_MAX_JOINTS];     /**< joint move: acceleration limits */
    float jmax[DH_MAX_JOINTS];     /**< joint move: jerk limits (when jerk is 1) */
    uint32_t jerk;                 /**< 1 when jerk-limited: joint move with jmax, path move of dh_queue_add_path_jerk_f32 with jerk; 2: line of dh_queue_add_path_blend_jerk_f32 */
    uint32_t n;                    /**< joint move: number of joints */
    uint32_t kind;                 /**< DH_MOVE_JOINT or DH_MOVE_PATH */
    dh_cart_limits_f32 lim;        /**< path move: its limits */
    float radius;                  /**< path move: blend radius of its corner with the next move (0: at rest) */
    float ctb;                     /**< path move: overlap of that corner (s; 0: at rest), planned when the next is appended */
    float cb[2];                   /**< path move: the corner's tail accelerations of s, its own and the next move's */
    float rate[2];                 /**< path move: the bounds of s' and s'' of its blended scalings (arcs: beside the centripetal acceleration) */
    dh_cart_jerk_f32 jk;           /**< line of dh_queue_add_path_blend_jerk_f32 (jerk 2): its jerk limits */
    dh_blend_seg_f32 seg;          /**< line of dh_queue_add_path_blend_jerk_f32: its jerk-limited scaling of s with its corners as planned so far */
} dh_queue_item_f32;

/**
 * @brief A queue of moves in a caller-owned array of items, and the move
 *        it is running (read-only for the user, who reads count, seq and
 *        phase). Written by dh_queue_init_f32.
 */
typedef struct {
    dh_queue_item_f32 *items;      /**< the caller's array (ring buffer) */
    uint32_t cap;                  /**< its number of items */
    uint32_t head;                 /**< index of the oldest queued move (the running one) */
    uint32_t count;                /**< queued moves, the running one included */
    uint32_t seq;                  /**< moves completed since dh_queue_init_f32: the running move's number */
    uint32_t phase;                /**< a dh_queue_phase value */
    uint32_t started;              /**< 1 when mv holds the running move's plan */
    uint32_t last;                 /**< kind of the last move completed (DH_MOVE_NONE before any) */
    uint32_t resume;               /**< 1 when a resume waits for the brake to reach rest */
    uint32_t pend;                 /**< 1 between dh_queue_target_f32 and dh_queue_advance_f32 */
    uint32_t n;                    /**< joints of the robot (tracker) of the last target call */
    uint32_t braked;               /**< 1 when the running move's state is its brake's (after a stop) */
    dh_move_f32 mv;                /**< plan of the running move (or of the last one completed) */
    float s0;                      /**< path move: s at the plan's start (its profile runs from s0 to 1) */
    float vs;                      /**< path move: limit of ds/dt (its first plan's peak) */
    float as;                      /**< path move: limit of d2s/dt2 (its first plan's peak) */
    float tb;                      /**< time into the brake (s) */
    float tbend;                   /**< duration of the brake (s) */
    float dt;                      /**< control period of the pending target call (s) */
    float next;                    /**< the clock, or brake time, the pending period advances to */
    float bq[DH_MAX_JOINTS];       /**< brake: joint (path move: [0] is s) at its start */
    float bs[DH_MAX_JOINTS];       /**< brake: direction of travel (+1, -1; 0 at rest) */
    float bv[DH_MAX_JOINTS];       /**< brake: |velocity| at its start */
    float ba[DH_MAX_JOINTS];       /**< brake: acceleration at its start, along the travel */
    float bap[DH_MAX_JOINTS];      /**< brake: peak deceleration */
    float bj[DH_MAX_JOINTS];       /**< brake: jerk (0: none) */
    float bt[3][DH_MAX_JOINTS];    /**< brake: durations of its three phases */
    float bx[DH_MAX_JOINTS];       /**< brake: distance to rest, at most the distance left */
    float bend[DH_MAX_JOINTS];     /**< brake: the move's end (q1, or s = 1), never passed */
    dh_blend_seg_f32 bl[2];        /**< blended lines: scaling of the running line [0] and of the next [1] in their overlap */
    float bo[2];                   /**< blended lines: s where each scaling starts (0, or where a stop left the line) */
    uint32_t bmode;                /**< blended lines: 0 none; 1 the running line; 2 and the next; 3 the next starts at bo[0] */
    uint32_t stopq;                /**< 1 when a stop waits for the end of an overlap of jerk-limited blended lines */
} dh_queue_f32;

/** @brief What the caller does this period (dh_queue_target_f32). */
typedef struct {
    uint32_t kind;              /**< DH_MOVE_JOINT: command q (then dh_track_sync_f32); DH_MOVE_PATH: track T; DH_MOVE_NONE: nothing to do */
    float q[DH_MAX_JOINTS];     /**< joint command (n joints) */
    dh_mat4_f32 T;              /**< frame to track */
} dh_queue_cmd_f32;

/** @brief What one period of the queue did. */
typedef struct {
    uint32_t seq;   /**< number of the move that ran this period (moves completed before it) */
    float clock;    /**< its clock after the period (s); the brake's time while braking */
    float feed;     /**< path move: its feed override r after the period (dh_move_report_f32); else 1 */
    int held;       /**< 1 when the clock held (path move, tracker not OK, or waiting for rest) */
    int done;       /**< 1 when the move completed this period */
    int last;       /**< 1 when the queue is empty after this period (the last move done) */
    int stopped;    /**< 1 when at rest after a stop (phase DH_QUEUE_STOPPED) */
} dh_queue_report_f32;

/**
 * @brief Starts an empty queue over the caller's array of cap items
 *        (phase DH_QUEUE_RUN, seq 0, nothing planned).
 * @param qu output queue.
 * @param items the caller's array (not copied; owned by the queue until
 *        it is initialised again).
 * @param cap its number of items, >= 1.
 * @return DH_OK; DH_ERR_ARG for cap == 0 (qu untouched).
 */
dh_status dh_queue_init_f32(dh_queue_f32 *qu, dh_queue_item_f32 *items, uint32_t cap);

/**
 * @brief Appends a joint move of n joints to q1 within vmax, amax (and
 *        jmax when not NULL), as dh_move_joint_f32 plans it when it
 *        starts: from the tracker's configuration then (the previous
 *        move's end: q1 of a joint move, the configuration the tracker
 *        reached at a path move's B).
 * @param qu queue from dh_queue_init_f32.
 * @param n number of joints, 1..DH_MAX_JOINTS (the tracker's robot's).
 * @param q1 end configuration (n, finite, within the robot's limits: the
 *        tracker's configuration is synchronised to every command).
 * @param vmax, amax, jmax limits (n each, finite, > 0); jmax may be NULL.
 * @return DH_OK; DH_ERR_ARG for n outside 1..DH_MAX_JOINTS or a limit
 *         <= 0; DH_ERR_NAN for a NaN/Inf value; DH_ERR_LIMIT when the
 *         queue holds cap moves already (the queue's limit: nothing is
 *         overwritten). On error qu and its items are untouched.
 */
dh_status dh_queue_add_joint_f32(dh_queue_f32 *qu, uint32_t n, const float *q1, const float *vmax,
                                 const float *amax, const float *jmax);

/**
 * @brief Appends a Cartesian move along p within lim (dh_move_path_f32):
 *        it starts at p->A (the clock holds until the tracker is OK
 *        there). Its corner with the next move runs at rest; the corner
 *        of the move before it is blended when that one was appended
 *        with a radius (dh_queue_add_path_blend_f32).
 * @param qu queue from dh_queue_init_f32.
 * @param p path from dh_path_line_f32 or dh_path_arc_f32 (copied).
 * @param lim Cartesian limits, each finite and > 0 (copied).
 * @return DH_OK; DH_ERR_NAN, DH_ERR_ARG, DH_ERR_OVERFLOW as
 *         dh_move_path_f32; DH_ERR_LIMIT when the queue is full. On error
 *         qu and its items are untouched.
 */
dh_status dh_queue_add_path_f32(dh_queue_f32 *qu, const dh_path_f32 *p, const dh_cart_limits_f32 *lim);

/**
 * @brief Appends a Cartesian move along p within lim, as
 *        dh_queue_add_path_f32, whose corner with the NEXT move is blended
 *        within radius: passed without stopping, the lines left only
 *        inside the ball of that radius about the corner.
 * Blended when both moves are paths (lines or arcs) with motion and equal
 * limits, the next starts at p->B (as dh_blend_plan_f32 requires), is
 * queued when this one starts (from rest, in the overlap with the move
 * before, or resuming) and the blend is shorter; else at rest (as with a
 * joint move, radius 0). Method: dh_blend_plan_f32's superposition, each
 * tail within half its path, the tails' tangential accelerations summing
 * to at most amax (at a corner with an arc a share of it, the rest for
 * the arcs' centripetal accelerations) (docs/design.md, "Blended corners
 * in the queue"). Speed, TOTAL
 * acceleration, angular speed and acceleration within lim up to float
 * rounding (1e-6 relative) at every period, with the feed override (held
 * inside an overlap), a stop (inside an overlap each line brakes at its
 * tail's acceleration, within the radius) and a resume (from rest: the
 * first line to its end, then the next). Outside the overlaps the target
 * is on its path as dh_path_eval_f32's.
 * @param qu, p, lim as dh_queue_add_path_f32 (p and lim copied).
 * @param radius blend radius (p's length unit), finite and >= 0. The
 *        queue's path moves are trapezoids of s, whose acceleration steps:
 *        no jerk limit holds in a blend, so none is jerk-limited.
 * @return DH_OK; DH_ERR_NAN for a NaN/Inf radius; DH_ERR_ARG for
 *         radius < 0; then the statuses of dh_queue_add_path_f32. On
 *         error qu and its items are untouched.
 */
dh_status dh_queue_add_path_blend_f32(dh_queue_f32 *qu, const dh_path_f32 *p, const dh_cart_limits_f32 *lim,
                                      float radius);

/**
 * @brief Appends a jerk-limited Cartesian move along p within lim and
 *        jerk (dh_move_path_jerk_f32: the seven-phase profile of s of
 *        dh_path_move_jerk_f32, TOTAL linear jerk within jerk->jmax on
 *        lines and arcs), run as dh_queue_add_path_f32's moves are.
 * Feed override r as dh_move_advance_f32's: speed and TOTAL acceleration
 * within lim at every r; the jerk within jerk while r is constant (a
 * change of r adds s' r' and s'' r r' terms that the rule bounds in
 * acceleration only). Stop: s brakes from its rate s' r and acceleration
 * s'' r^2 with jerk +-j (j = the plan's peak |s'''|), its deceleration
 * ramped to at most the plan's peak |s''| and back, so the tool's speed,
 * acceleration and jerk stay within lim and jerk (docs/design.md, "Stop
 * and resume"), never beyond B. Resume: a seven-phase profile of s from
 * where it stopped to 1 within the first plan's peaks of s', s'' and
 * s'''. Its corners with the moves before and after it run at rest
 * (dh_queue_add_path_blend_jerk_f32 blends jerk-limited lines).
 * @param qu, p, lim as dh_queue_add_path_f32 (p, lim and jerk copied).
 * @param jerk jerk limits, each finite and > 0; NULL: the move of
 *        dh_queue_add_path_f32.
 * @return DH_OK; DH_ERR_LIMIT when the queue is full (checked first);
 *         then DH_ERR_NAN, DH_ERR_ARG, DH_ERR_OVERFLOW as
 *         dh_move_path_jerk_f32. On error qu and its queued moves are
 *         untouched (the free item's profile is overwritten: it is
 *         planned there).
 */
dh_status dh_queue_add_path_jerk_f32(dh_queue_f32 *qu, const dh_path_f32 *p, const dh_cart_limits_f32 *lim,
                                     const dh_cart_jerk_f32 *jerk);

/**
 * @brief Appends a jerk-limited line along p within lim and jerk whose
 *        corner with the NEXT such line is blended within radius, as
 *        dh_blend_seq_plan_jerk_f32 blends a sequence's corners.
 * The line's scaling of s is dh_blend_seq_plan_jerk_f32's (seven phases),
 * planned again when the next line is appended, by the same corner rule
 * (docs/design.md, "Jerk-limited blended corners in the queue"). The
 * corner is blended when both are lines of this function with equal
 * limits, the next starts at p->B, is queued when this one starts, the
 * blend is shorter and keeps this line's peak speed; else at rest.
 * Speed, TOTAL acceleration, angular speed and acceleration within lim
 * at every feed override r (held inside an overlap); TOTAL jerk and
 * angular jerk within jerk while r is constant, in a stop and a resume,
 * all up to float rounding (1e-6 relative). A stop inside an overlap
 * waits for its end (qu->stopq; the tool within radius of the corner),
 * then the next line brakes alone with jerk +-its bound; a resume runs a
 * line from rest to its end, its corner after at rest. Outside the
 * overlaps the target is on the line as dh_path_eval_f32's.
 * @param qu, p, lim as dh_queue_add_path_f32 (p, lim and jerk copied).
 * @param jerk jerk limits, each finite and > 0.
 * @param radius blend radius (p's length unit), finite and >= 0.
 * @return DH_OK; DH_ERR_LIMIT when the queue is full (checked first);
 *         DH_ERR_NAN for a NaN/Inf radius, DH_ERR_ARG for radius < 0 or
 *         an arc (dh_queue_add_path_jerk_f32 runs an arc, at rest); then
 *         the statuses of dh_queue_add_path_jerk_f32. On error qu and its
 *         queued moves are untouched (the free item is overwritten).
 */
dh_status dh_queue_add_path_blend_jerk_f32(dh_queue_f32 *qu, const dh_path_f32 *p, const dh_cart_limits_f32 *lim,
                                           const dh_cart_jerk_f32 *jerk, float radius);

/**
 * @brief Begins a control period: the command of the running move after
 *        this period (joint move) or the frame to track this period (path
 *        move), starting the next queued move when the last one is done.
 * A period: this call; for kind JOINT dh_track_sync_f32(t, cmd.q) (state
 * OK), for kind PATH dh_track_step_f32(t, &cmd.T, ...) (its state); then
 * dh_queue_advance_f32(qu, state, &rep). A joint move after another
 * move starts from t->q once every |t->v[i]| <= amax_i dt / 2 (so its
 * first step is within amax_i dt^2 of the last); until then, and while
 * stopped or with nothing queued, the last move's command at rest is
 * repeated (a path's frame, or t->q after a joint move; DH_MOVE_NONE
 * before any move). The first move starts at once from t->q, a path move
 * as dh_move_path_f32's. Commands keep the move's limits as
 * dh_move_joint_step_f32's and dh_move_target_f32's do.
 * @param qu queue.
 * @param t the caller's tracker (read only: q, v, r->n).
 * @param dt control period (s), finite, > 0 (the tracker's dt).
 * @param cmd output command.
 * @return DH_OK; DH_ERR_NAN for a NaN/Inf dt or a t->q that is not
 *         finite; DH_ERR_ARG for dt <= 0, a target call already pending,
 *         or a joint move for another number of joints than t's robot
 *         has: qu and cmd untouched. DH_ERR_OVERFLOW (or another status
 *         of dh_profile_scurve_f32, _trap_f32, _stretch_f32) when a joint
 *         move cannot be planned from t->q: it stays queued, unstarted,
 *         the last plan is dropped (the hold command becomes
 *         DH_MOVE_NONE) and cmd is untouched.
 */
dh_status dh_queue_target_f32(dh_queue_f32 *qu, const dh_track_f32 *t, float dt, dh_queue_cmd_f32 *cmd);

/**
 * @brief Ends the control period begun by dh_queue_target_f32: state is
 *        the tracker's state of this period (DH_TRACK_OK after a joint
 *        command or DH_MOVE_NONE; it is read for path moves only).
 * Joint move: its clock (or brake) advances to the commanded time. Path
 * move: dh_move_advance_f32 itself (the clock advances by r dt, its feed
 * override r falling while the tracker is not OK and rising while it is;
 * rep->feed is r); a path's brake time advances only on OK. A move is done
 * when its clock reached its duration (a path move: and the tracker OK at
 * B), and is then removed from the queue (seq + 1); a brake that reached
 * rest sets phase DH_QUEUE_STOPPED (stopped 1), or resumes at once when
 * dh_queue_resume_f32 was called during it.
 * @param qu queue with a pending target call.
 * @param state a dh_track_state value.
 * @param rep report of the period.
 * @return DH_OK; DH_ERR_ARG for no pending target call or a state that is
 *         no dh_track_state. On error qu and rep are untouched.
 */
dh_status dh_queue_advance_f32(dh_queue_f32 *qu, dh_track_state state, dh_queue_report_f32 *rep);

/**
 * @brief Stops: brings the running move to rest along its own path and
 *        within its own limits, from the state it has after the last
 *        period (no jump in position, velocity, and with jerk limits in
 *        acceleration):
 * - joint move: each joint decelerates from its velocity and acceleration
 *   at amax_i (1 - 2^-10) (with jmax: jerk +-jmax_i, acceleration ramped
 *   to -a_p and back, a_p <= amax_i (1 - 2^-10)) and stops within
 *   v1 / a + 3 a / j, v1 = |v| + a^2 / (2 j) (|v| / a without jmax) of the
 *   stop, a = amax_i (1 - 2^-10), j = jmax_i; never beyond q1;
 * - path move: s decelerates from its rate s' r (r the feed override) at
 *   the acceleration of its plan (within lim) and stops within s' r / s''
 *   of the stop (jerk-limited: jerk +-j, the deceleration ramped to
 *   a_p <= A and back, within v1 / A + 3 A / j, v1 = s' r +
 *   (s'' r^2)^2 / (2 j), A and j the plan's peak |s''| and |s'''|),
 *   never beyond B; the brake time advances only when the tracker is OK;
 * - inside an overlap of jerk-limited blended lines: at the overlap's end
 *   (phase RUN and stopq 1 until then), the next line's brake from there.
 * A move not started, held at its start (clock 0) or at its end, or no
 * move at all, is at rest: the stop is immediate (phase STOPPED). A stop
 * while braking or stopped changes nothing. Queued moves stay queued and
 * do not start until dh_queue_resume_f32; moves appended while stopped
 * are queued likewise.
 * @param qu queue from dh_queue_init_f32 (not between target and advance).
 * @return DH_OK; DH_ERR_ARG for a call between dh_queue_target_f32 and
 *         dh_queue_advance_f32 (qu untouched).
 */
dh_status dh_queue_stop_f32(dh_queue_f32 *qu);

/**
 * @brief Resumes after a stop: the stopped move is planned again from
 *        rest where it stopped to its end within the same limits (a joint
 *        move by dh_move_joint_f32 to q1, a path move by a trapezoid of s
 *        to 1 within the first plan's rates of s, a seven-phase profile
 *        within its jerk too when jerk-limited), so it ends exactly at
 *        its end (q1 bit for bit; B), and then the rest of the queue runs.
 * Called while braking, the move resumes when the brake reaches rest;
 * called while running, it changes nothing.
 * @param qu queue from dh_queue_init_f32 (not between target and advance).
 * @return DH_OK; DH_ERR_ARG for a call between dh_queue_target_f32 and
 *         dh_queue_advance_f32 (qu untouched).
 */
dh_status dh_queue_resume_f32(dh_queue_f32 *qu);

/* ======================================================================
 * Blended corner between two Cartesian moves, lines or arcs (dh_blend.c)
 * ==================================================================== */

/**
 * @brief The time scaling of s from 0 to 1 of one move of a blend
 *        (read-only for the user): acceleration +-a, cruise at v, and at
 *        the corner's end a tail of duration tb at the reduced
 *        acceleration b (from speed u = b tb to rest, over the distance
 *        e = b tb^2 / 2). The first move runs it forwards (the tail
 *        ends at the corner), the second backwards in time (its tail
 *        starts at the corner).
 */
typedef struct {
    float v;  /**< peak ds/dt (1/s) */
    float a;  /**< |d2s/dt2| outside the tail (1/s^2) */
    float b;  /**< |d2s/dt2| in the tail (1/s^2), <= a */
    float u;  /**< ds/dt at the start of the tail: b tb */
    float e;  /**< s covered by the tail: b tb^2 / 2 */
    float t1; /**< duration of the acceleration from rest to v */
    float tv; /**< duration of the cruise at v */
    float t3; /**< duration of the deceleration from v to u at a */
    float tb; /**< duration of the tail (the overlap) */
    float T;  /**< duration of the move: t1 + tv + t3 + tb (0: no motion) */
} dh_blend_prof_f32;

/**
 * @brief Two consecutive path moves blended at their corner (written by
 *        dh_blend_plan_f32, read by dh_blend_eval_f32; read-only for the
 *        user, who reads t0, tb, T and dev).
 */
typedef struct {
    dh_path_f32 p1;         /**< first path (a copy) */
    dh_path_f32 p2;         /**< second path (a copy), starting at p1's end frame */
    dh_blend_prof_f32 m1;   /**< scaling of the first line, tail at its end */
    dh_blend_prof_f32 m2;   /**< scaling of the second line, evaluated backwards (tail at its start) */
    float t0;               /**< start of the overlap on the pair's clock (= the first move's): m1.T - tb */
    float tb;               /**< duration of the overlap (s); 0: the moves run back to back */
    float T;                /**< duration of the pair: t0 + m2.T */
    float dev;              /**< bound on the distance of the tool point from the corner during the overlap */
} dh_blend_f32;

/**
 * @brief bl = path moves p1 then p2 (lines or arcs) blended at their
 *        corner by superposition: in the overlap [t0, t0 + tb] the
 *        position is p1(t) + (p2(t - t0) - corner), the rotation
 *        Exp(s2 w2) R1(t) (w2 p2's world rotation vector); elsewhere that
 *        of the one move running. Each move is a trapezoid of s within
 *        dh_path_move_f32's bounds whose part in the overlap accelerates
 *        gently (two lines: L_i s_i'' <= amax / max(1, |d2 - d1|), d_i the
 *        directions; with an arc: L1 s1'' + L2 s2'' <= sh amax and its
 *        speed within sqrt((1 - sh) amax rho); th1 s1'' + th2 s2'' <=
 *        (63/64) wdmax), tb held so that the sums of both moves (speed,
 *        TOTAL acceleration, angular speed and acceleration) stay within
 *        lim and the tool within radius of the corner (docs/design.md,
 *        "Blended corners").
 * @param bl output.
 * @param p1, p2 lines or arcs; p2->A equal to p1->B within DH_ROT_TOL
 *        (positions relative to max(1, |p1->B's position|)). Straight
 *        continuations, pure rotations and moves of length 0 are fine.
 * @param lim limits, each finite and > 0.
 * @param radius blend radius (length unit), finite and >= 0.
 * tb = 0 (the moves back to back, each dh_path_move_f32's rest-to-rest
 * trapezoid, at rest at the corner) when radius is 0, a move has no
 * motion, or the blend would not be shorter; otherwise bl->T is less than
 * the back-to-back duration. Limits met up to float rounding (1e-6
 * relative); bl->dev <= radius.
 * @return DH_OK; DH_ERR_NAN for a NaN/Inf limit or radius; DH_ERR_ARG for
 *         a limit <= 0, radius < 0, p1 or p2 no path (neither a line nor
 *         an arc) or p2->A not p1->B; DH_ERR_OVERFLOW when a rate or a
 *         duration is not a positive finite float. bl untouched on error.
 */
dh_status dh_blend_plan_f32(dh_blend_f32 *bl, const dh_path_f32 *p1, const dh_path_f32 *p2,
                            const dh_cart_limits_f32 *lim, float radius);

/**
 * @brief T = the frame of the blended pair bl at time t (s, the first
 *        move's clock): the first line's frame for t <= t0, the second's
 *        at t - t0 for t >= t0 + tb, their superposition in between.
 * @param bl pair from dh_blend_plan_f32.
 * @param t time, any value but NaN: clamped to [0, bl->T]; t <= 0 gives
 *        p1->A and t >= bl->T gives p2->B bit for bit.
 * @param T output frame (must not alias bl).
 * Outside the overlap the position is dh_path_eval_f32's; inside, within
 * bl->dev of the corner up to 8 FLT_EPSILON (S + rho) (S the largest
 * position magnitude of the paths, rho the largest arc radius, 0 for
 * lines).
 * @return DH_OK; DH_ERR_NAN for a NaN t; DH_ERR_ARG when bl holds no
 *         blend (its paths not unit quaternions: e.g. all zero). T
 *         untouched on error.
 */
dh_status dh_blend_eval_f32(const dh_blend_f32 *bl, float t, dh_mat4_f32 *T);

/* ======================================================================
 * Blended sequence of Cartesian moves, lines and arcs (dh_blend.c)
 * ==================================================================== */


/**
 * @brief A sequence of n path moves blended at their corners, over the
 *        caller's paths and array of n scalings (written by
 *        dh_blend_seq_plan_f32, read by dh_blend_seq_eval_f32; read-only
 *        for the user, who reads n and T). Neither array is copied: both
 *        must stay unchanged while the sequence is used.
 */
typedef struct {
    const dh_path_f32 *p;  /**< the caller's paths */
    dh_blend_seg_f32 *seg; /**< the caller's scalings, one per path */
    uint32_t n;            /**< number of paths */
    float T;               /**< duration of the sequence (s) */
} dh_blend_seq_f32;

/**
 * @brief sq = the n paths p[0..n-1] (lines or arcs) one after the other,
 *        each corner k (p[k] to p[k+1]) blended within radius[k] as by
 *        dh_blend_plan_f32 (superposed in the overlap, one path's pose
 *        elsewhere), each tail within half its path (so a path between
 *        two blended corners has one at each end).
 *        Method and proofs: docs/design.md ("Blended sequences").
 * @param sq output sequence.
 * @param seg the caller's array of n scalings (written; owned by sq).
 * @param p the caller's n paths (dh_path_line_f32, dh_path_arc_f32),
 *        p[k+1].A equal to p[k].B as dh_blend_plan_f32 requires (not
 *        copied: owned by sq). Lines of length 0, pure rotations and
 *        straight continuations are fine.
 * @param n number of paths, >= 1.
 * @param radius n - 1 blend radii (length unit), finite and >= 0 (NULL
 *        allowed when n == 1).
 * @param lim limits, each finite and > 0.
 * A corner is run at rest (tb 0 at both sides) when its radius is 0, a
 * path next to it has no motion, or its blend alone would not shorten
 * the pair; and every corner is, when the whole sequence so planned
 * would not be shorter than its paths' rest-to-rest trapezoids back to
 * back. Otherwise sq->T is less than that. Speed, TOTAL acceleration,
 * angular speed and acceleration within lim up to float rounding (1e-6
 * relative), seg[k].dev <= radius[k].
 * @return DH_OK; DH_ERR_NAN for a NaN/Inf limit or radius; DH_ERR_ARG for
 *         n == 0, a limit <= 0, a radius < 0, a p[k] that is no path
 *         (neither a line nor an arc) or a p[k+1].A that is not p[k].B;
 *         DH_ERR_OVERFLOW when a rate or a duration is not a positive
 *         finite float. sq and seg untouched on error.
 */
dh_status dh_blend_seq_plan_f32(dh_blend_seq_f32 *sq, dh_blend_seg_f32 *seg, const dh_path_f32 *p, uint32_t n,
                                const float *radius, const dh_cart_limits_f32 *lim);

/**
 * @brief T = the frame of the blended sequence sq at time t (s, on the
 *        sequence's clock): the frame of path k at its own time
 *        t - seg[k].t0 where one path runs, the superposition of paths k
 *        and k+1 in their overlap.
 * @param sq sequence from dh_blend_seq_plan_f32 or dh_blend_seq_plan_jerk_f32.
 * @param t time, any value but NaN: clamped to [0, sq->T]; t <= 0 gives
 *        p[0].A and t >= sq->T gives p[n-1].B bit for bit.
 * @param T output frame (must not alias the lines).
 * Outside the overlaps the position is dh_path_eval_f32's; inside, within
 * seg[k].dev of corner k up to 8 FLT_EPSILON (S + rho) (S the largest
 * position magnitude of the paths, rho the largest arc radius, 0 for
 * lines).
 * @return DH_OK; DH_ERR_NAN for a NaN t; DH_ERR_ARG when sq holds no
 *         sequence (n 0, or an entry that holds no path). T untouched on
 *         error.
 */
dh_status dh_blend_seq_eval_f32(const dh_blend_seq_f32 *sq, float t, dh_mat4_f32 *T);

/**
 * @brief sq = the n LINES p[0..n-1] one after the other, each a
 *        jerk-limited scaling of s (ramped acceleration, |s'''| within
 *        jmax / L and wjmax / angle), each corner k blended within
 *        radius[k]: line k's deceleration and line k+1's acceleration
 *        superposed for tb, with L_i |s''| <= amax / max(1, |d2 - d1|)
 *        and L_i |s'''| <= jmax / max(1, |d1 + d2|) in them (d_i the
 *        directions), tb the longest that keeps the tool within radius[k]
 *        of the corner and the rotation's cross terms within 1/64 of
 *        wdmax and wjmax (docs/design.md, "Jerk-limited blended
 *        sequences"). Speed, TOTAL acceleration and jerk, angular speed,
 *        acceleration and jerk within lim and jerk up to float rounding
 *        (1e-6 relative); seg[k].dev <= radius[k]; evaluated by
 *        dh_blend_seq_eval_f32 (same position bounds).
 * @param sq, seg, p, n, radius, lim as dh_blend_seq_plan_f32, every p[k]
 *        a line: an arc's tail adds the centripetal jerk (L s')^3 / rho^2
 *        + 3 L^2 s' s'' / rho along turning tangents, which no proved
 *        bound through tb holds yet, so arcs are refused.
 * @param jerk jmax (TOTAL linear jerk) and wjmax, finite and > 0 (not
 *        NULL: dh_blend_seq_plan_f32 plans without a jerk limit).
 * A corner runs at rest (tb 0, the lines' own bounds) when its radius is
 * 0, a line next to it has no motion or its overlap would not exceed the
 * time its lowered bounds cost; all do when the sequence would not be
 * shorter than its lines' rest-to-rest seven-phase scalings back to back.
 * @return DH_OK; dh_blend_seq_plan_f32's statuses in its order, then
 *         DH_ERR_NAN for a NaN/Inf jerk limit, DH_ERR_ARG for one <= 0 or
 *         an arc; DH_ERR_OVERFLOW for a bound of s that is not a
 *         positive finite float or a bound of the duration that is not
 *         finite. sq and seg untouched on error.
 */
dh_status dh_blend_seq_plan_jerk_f32(dh_blend_seq_f32 *sq, dh_blend_seg_f32 *seg, const dh_path_f32 *p, uint32_t n,
                                     const float *radius, const dh_cart_limits_f32 *lim, const dh_cart_jerk_f32 *jerk);

/* ======================================================================
 * Fixed point (integer only: no float, no libm, no 64-bit division)
 *
 * Formats: quaternions and rotations Q2.30 (dh_quat_q, dh_frame_q), path
 * parameters s Q2.30 in [0, 0x40000000] (0 .. 1), angles Q16.16 degrees,
 * positions dh_qpos (DH_QPOS_FRAC fraction bits, the user's length unit).
 * Pointers must not be NULL (DH_ASSERT); on a non-OK status every output
 * is left untouched.
 * ==================================================================== */

/**
 * @brief Fixed twin of dh_slerp_f32: out = a (a* b)^s along the SHORTEST
 *        great arc (b replaced by -b when a . b < 0), through the degree
 *        trig (dh_atan2_q, dh_sincos_q), integer only.
 * @param a, b quaternions, any int32 components (INT32_MIN included), not
 *        all zero: each is normalised first (exact shifts to a common
 *        scale, an integer square root).
 * @param s path parameter, Q2.30 in [0, 0x40000000].
 * @param out unit quaternion (Q2.30): s == 0 gives a normalised and
 *        s == 0x40000000 gives +-b normalised (the sign of the shorter
 *        arc), both exactly as normalised here. At a . b == 0 (180
 *        degrees) b is taken as given.
 * @return DH_OK; DH_ERR_ZERO_AXIS for a or b all zero; DH_ERR_ARG for s
 *         outside [0, 0x40000000]. out may alias a or b.
 * Components within 4e-7 of the exact slerp of a / |a| and b / |b|
 * (dh_atan2_q's 1 LSB of Q16.16 degrees and the rounding of s h dominate).
 */
dh_status dh_slerp_q(const dh_quat_q *a, const dh_quat_q *b, dh_q30 s, dh_quat_q *out);

/**
 * @brief Fixed twin of dh_pose_interp_f32: T = the pose at s between the
 *        fixed frames A and B: position p_A + s (p_B - p_A) rounded once
 *        (from p_B for s > 1/2), rotation dh_slerp_q of the unit
 *        quaternions of R_A and R_B (dh_frame_to_quat_q), as a rotation
 *        by dh_quat_to_frame_q.
 * @param A, B frames with orthonormal rotations (dh_frame_ortho_error_q
 *        <= DH_ROT_TOL_Q, det > 0); positions any int32.
 * @param s path parameter, Q2.30 in [0, 0x40000000]; s == 0 gives T == A
 *        and s == 0x40000000 gives T == B bit for bit.
 * @param T output frame; its position lies between p_A and p_B
 *        component by component (no overflow for any positions).
 * @return DH_OK; DH_ERR_NOT_RIGID if A or B is not a rotation as above;
 *         DH_ERR_ARG for s outside [0, 0x40000000]. T may alias A or B.
 * Position within 0.5 LSB of the exact value; rotation entries within
 * 1.5e-6 of the exact interpolation of the rotations of A and B.
 */
dh_status dh_pose_interp_q(const dh_frame_q *A, const dh_frame_q *B, dh_q30 s, dh_frame_q *T);

/**
 * @brief Fixed twin of dh_pose_angle_f32: deg = the angle in [0, 180]
 *        degrees of R_A^T R_B: atan2(|vee(M - M^T)|, tr M - 1) of
 *        M = R_A^T R_B from exact 64-bit dot products, each term rounded
 *        once to Q3.29, accurate at 0 and 180 degrees alike.
 * @param A, B frames with orthonormal rotations (as dh_pose_interp_q).
 * @param deg output, Q16.16 degrees in [0, 180 * 65536].
 * @return DH_OK; DH_ERR_NOT_RIGID if A or B is not a rotation (deg untouched).
 * Within 2e-5 degrees of the angle between the exact rotations that A and
 * B round (dh_atan2_q's 1 LSB, 1.5e-5 degrees, dominates).
 */
dh_status dh_pose_angle_q(const dh_frame_q *A, const dh_frame_q *B, dh_q16 *deg);

/**
 * @brief A fixed-point rest-to-rest profile from 0 to d (the fixed twin of
 *        dh_profile_f32), written by the dh_profile_*_q initialisers and
 *        read by dh_profile_eval_q (read-only for the user).
 * Units: positions in position LSB of any fixed format (Q16.16 degrees for
 * joints, dh_qpos for lengths), time in whole microseconds (uint32, below
 * 2^31: 35.8 minutes), rates in the same LSB per second, per second^2,
 * per second^3 (int32: Q16.16 degrees give up to 32767 deg/s, deg/s^2,
 * deg/s^3). The shape is stored as the ratios of its phase times to T, so
 * stretching (dh_profile_stretch_q) only changes T and the peaks.
 */
typedef struct {
    int32_t d;     /**< signed distance (LSB) */
    uint32_t T;    /**< duration (us); 0 when d == 0 and nothing stretched it */
    dh_q30 xj;     /**< tj / T, each jerk phase (0 for the trapezoid and the quintic) */
    dh_q30 xa;     /**< ta / T, the acceleration phase with its jerk phases (0 for the quintic); cruise 1 - 2 xa */
    int32_t v;     /**< peak |velocity| (LSB/s), >= 1 when d != 0 */
    int32_t a;     /**< peak |acceleration| (LSB/s^2) */
    int32_t j;     /**< peak |jerk| (LSB/s^3); 0 for the trapezoid */
    uint32_t kind; /**< a dh_profile_kind value */
} dh_profile_q;

/**
 * @brief Fixed twin of dh_profile_trap_f32: the time-optimal trapezoid for
 *        |d| within vmax and amax, T = |d|/vmax + vmax/amax when
 *        |d| >= vmax^2/amax, else 2 sqrt(|d|/amax), rounded UP to whole
 *        microseconds (the profile stretched to it).
 * @param p output profile (kind DH_PROFILE_TRAP, xj = 0, j = 0).
 * @param d signed distance (LSB), any int32 (0 gives T = 0).
 * @param vmax, amax limits (LSB/s, LSB/s^2), > 0.
 * T >= the analytic minimum and below it plus 1 us + 2^-26 T; p->v <= vmax
 * and p->a <= amax, and the motion of the held shape (its rounded ratios)
 * within them up to 1e-8 relative (the ratios are rounded toward lower rates).
 * @return DH_OK; DH_ERR_ARG for a limit <= 0; DH_ERR_OVERFLOW when T would
 *         reach 2^31 us, or a phase is shorter than 2^-30 T. p untouched
 *         on error.
 */
dh_status dh_profile_trap_q(dh_profile_q *p, int32_t d, int32_t vmax, int32_t amax);

/**
 * @brief Fixed twin of dh_profile_scurve_f32: the time-optimal seven-phase
 *        (jerk-limited) profile for |d| within vmax, amax and jmax, the
 *        duration rounded UP to whole microseconds as dh_profile_trap_q.
 * @param p output profile (kind DH_PROFILE_SCURVE).
 * @param d signed distance (LSB), any int32 (0 gives T = 0).
 * @param vmax, amax, jmax limits (LSB/s, /s^2, /s^3), > 0.
 * T >= the minimum of the float twin's closed forms and below it plus
 * 1 us + 2^-26 T; peaks within the limits, and the motion of the held
 * shape within them up to 1e-8 relative (as dh_profile_trap_q).
 * @return DH_OK; DH_ERR_ARG for a limit <= 0; DH_ERR_OVERFLOW when T would
 *         reach 2^31 us or a phase is shorter than 2^-30 T. p untouched
 *         on error.
 */
dh_status dh_profile_scurve_q(dh_profile_q *p, int32_t d, int32_t vmax, int32_t amax, int32_t jmax);

/**
 * @brief Fixed twin of dh_profile_quintic_f32: d (10 x^3 - 15 x^4 + 6 x^5),
 *        x = t / T, of the given duration; peaks 1.875 |d|/T,
 *        5.7735 |d|/T^2, 60 |d|/T^3 (T in s), each rounded up.
 * @param p output profile (kind DH_PROFILE_QUINTIC, xj = xa = 0).
 * @param d signed distance (LSB), any int32.
 * @param T duration (us), 1 .. 2^31 - 1.
 * @return DH_OK; DH_ERR_ARG for T outside 1 .. 2^31 - 1; DH_ERR_OVERFLOW
 *         when a peak does not fit int32. p untouched on error.
 */
dh_status dh_profile_quintic_q(dh_profile_q *p, int32_t d, uint32_t T);

/**
 * @brief Fixed twin of dh_profile_stretch_f32: p stretched to the longer
 *        duration T by uniform time scaling (the same ratios, peaks
 *        recomputed for T and never above the old ones).
 * @param p profile from a dh_profile_*_q initialiser, modified in place.
 * @param T new duration (us), p->T <= T < 2^31 (T == p->T changes nothing).
 * @return DH_OK; DH_ERR_ARG for T < p->T or T >= 2^31; DH_ERR_OVERFLOW
 *         when a new peak rounds to 0 (T too long for the LSB of the
 *         rates). p untouched on error.
 */
dh_status dh_profile_stretch_q(dh_profile_q *p, uint32_t T);

/**
 * @brief Position, velocity and acceleration of p at time t (us), integer
 *        only: t == 0 gives 0, 0, 0 and t >= p->T gives d, 0, 0 exactly;
 *        for t > T/2 the mirror image of the first half is taken from d.
 * @param p profile from a dh_profile_*_q function (or one with d == 0).
 * @param t time (us), any uint32.
 * @param pos, vel, acc outputs (LSB, LSB/s, LSB/s^2); |vel| <= p->v and
 *        |acc| <= p->a always.
 * Position within 4 + 2^-27 |d| LSB of the exact shape of p's ratios at t
 * (the halves meet within that at T/2).
 * @return DH_OK; DH_ERR_ARG when p (with d != 0) holds no profile: its T,
 *         peaks, kind or ratios out of range (outputs untouched).
 */
dh_status dh_profile_eval_q(const dh_profile_q *p, uint32_t t, int32_t *pos, int32_t *vel, int32_t *acc);

/**
 * @brief Fixed twin of dh_joint_move_f32: n joints from q0 to q1, every
 *        joint at rest at the same time T (whole microseconds), each
 *        within its own limits, T as short as the slowest joint allows:
 *        each joint's dh_profile_scurve_q (dh_profile_trap_q when jmax is
 *        NULL), then every profile stretched to the longest duration.
 * @param prof output: n profiles of q1[i] - q0[i], all with prof[i].T == T.
 * @param n number of joints, >= 1.
 * @param q0, q1 start and end positions (n each; Q16.16 degrees, or
 *        dh_qpos for prismatic joints: any fixed format, the LSB of d).
 * @param vmax, amax, jmax per-joint limits (n each, > 0, in LSB per
 *        second^k as dh_profile_q); jmax may be NULL (trapezoids).
 * T is the longest of the joints' rounded-up optimal durations (within
 * 1 us + 2^-26 T of the slowest joint's minimum).
 * @return DH_OK; DH_ERR_ARG for n == 0 or a limit <= 0; DH_ERR_OVERFLOW
 *         when q1[i] - q0[i] does not fit int32, or a profile or its
 *         stretch overflows (as dh_profile_trap_q, _scurve_q, _stretch_q).
 *         On error every prof[i] is all zero: no move, duration 0, so
 *         evaluating it keeps the joints at q0.
 */
dh_status dh_joint_move_q(dh_profile_q *prof, uint32_t n, const int32_t *q0, const int32_t *q1,
                          const int32_t *vmax, const int32_t *amax, const int32_t *jmax);

/**
 * @brief Fixed twin of dh_joint_move_eval_f32: joint positions,
 *        velocities and accelerations of a joint move at time t (us):
 *        q = q0 + p_i(t) for t <= T/2, q1 - (d_i - p_i(t)) after, so t == 0
 *        gives q0 and t >= T gives q1 exactly; a joint whose profile has
 *        d_i == 0 stays at q0 (the no move of a failed call).
 * @param prof, n, q0, q1 the move of dh_joint_move_q and its endpoints.
 * @param t time (us), any uint32.
 * @param q, qd, qdd outputs (n each; LSB, LSB/s, LSB/s^2).
 * @return DH_OK; DH_ERR_ARG for n == 0 or a profile that holds none (as
 *         dh_profile_eval_q). Outputs untouched on error.
 */
dh_status dh_joint_move_eval_q(const dh_profile_q *prof, uint32_t n, const int32_t *q0, const int32_t *q1,
                               uint32_t t, int32_t *q, int32_t *qd, int32_t *qdd);

/* ======================================================================
 * Fixed-point Cartesian paths, moves and the move executor
 * (integer only: no float, no 64-bit division)
 * ==================================================================== */

/**
 * @brief A fixed-point Cartesian path from frame A to frame B (the twin of
 *        dh_path_f32), written by dh_path_line_q / dh_path_arc_q and read
 *        by dh_path_eval_q (read-only for the user, who reads length,
 *        angle, radius and sweep): position along the line or arc in
 *        proportion to s, orientation along the shortest arc from R_A to
 *        R_B in proportion to s (as dh_pose_interp_q).
 */
typedef struct {
    dh_frame_q A;      /**< start frame (s = 0) */
    dh_frame_q B;      /**< end frame (s = 1) */
    dh_quat_q qa;      /**< unit quaternion of R_A (Q2.30) */
    dh_quat_q qb;      /**< unit quaternion of R_B, of the sign with qa . qb >= 0 */
    dh_q30 k[3];       /**< unit axis of qa* qb (Q2.30; 0 without rotation) */
    dh_q16 h;          /**< half the angle of qa* qb, Q16.16 degrees in [0, 90] */
    dh_qpos u0[3];     /**< arc: p_A - centre (0 for a line) */
    dh_qpos w0[3];     /**< arc: u0 turned a quarter turn along the motion (0 for a line) */
    dh_qpos u1[3];     /**< arc: p_B - centre (0 for a line) */
    dh_qpos w1[3];     /**< arc: u1 turned a quarter turn along the motion (0 for a line) */
    dh_qpos length;    /**< position length of the path (dh_qpos) */
    dh_q16 angle;      /**< rotation angle from R_A to R_B, Q16.16 degrees in [0, 180] (dh_pose_angle_q) */
    dh_qpos radius;    /**< arc radius (0 for a line) */
    dh_q16 sweep;      /**< arc angle about the centre, Q16.16 degrees in (0, 360) (0 for a line) */
    uint32_t sw;       /**< arc: the sweep in 2^-23 degrees (what the evaluation uses) */
    uint32_t kind;     /**< a dh_path_kind value */
} dh_path_q;

/**
 * @brief Fixed twin of dh_path_line_f32: p = the straight line from A to
 *        B, position p_A + s (p_B - p_A), orientation slerped along the
 *        shortest arc.
 * @param p output path (kind DH_PATH_LINE); p->length = |p_B - p_A|
 *        (floor of the exact root, within 1 LSB), p->angle as
 *        dh_pose_angle_q.
 * @param A, B frames with orthonormal rotations (dh_frame_ortho_error_q
 *        <= DH_ROT_TOL_Q, det > 0); equal positions are fine (length 0).
 * @return DH_OK; DH_ERR_NOT_RIGID if A or B is not a rotation as above;
 *         DH_ERR_OVERFLOW when a component of p_B - p_A or the length
 *         does not fit int32. p untouched on error; p must not alias A or B.
 */
dh_status dh_path_line_q(dh_path_q *p, const dh_frame_q *A, const dh_frame_q *B);

/**
 * @brief Fixed twin of dh_path_arc_f32: p = the circular arc from p_A
 *        through the point via to p_B, orientation slerped along the
 *        shortest arc from R_A to R_B. Method: src/motion/dh_path_q.c.
 * @param p output path (kind DH_PATH_ARC): radius (dh_qpos), sweep (Q16.16
 *        degrees; the evaluation uses sw, 2^-23 degrees), length = radius
 *        times the sweep in radians, angle as dh_pose_angle_q.
 * @param A, B frames with orthonormal rotations (as dh_path_line_q).
 * @param via a point on the arc (3 dh_qpos).
 * Every side of the triangle p_A, via, p_B, the radius and the length must
 * be below 2^30 LSB (16384 units at Q16.16) and the whole circle within
 * int32; the triangle must not be thin: y L > M^2 / 1024 (y the distance
 * of via from the chord p_A p_B of length L, M the longest side; the
 * float twin's |a x b| > 2^-10 M^2), so the radius is at most 512 M.
 * @return DH_OK; DH_ERR_NOT_RIGID if A or B is not a rotation;
 *         DH_ERR_OVERFLOW when a side, the radius, the length or the
 *         circle is beyond the range above; DH_ERR_SINGULAR for
 *         collinear or coincident points (the thin triangle above). On
 *         error *p is all zero (it holds no path: its fields are the
 *         planning's scratch); p must not alias A, B or via.
 * The evaluated points lie within 4 LSB + 2^-26 R of the circle through
 * the three points (docs/design.md, "Fixed-point paths and moves").
 */
dh_status dh_path_arc_q(dh_path_q *p, const dh_frame_q *A, const dh_qpos via[3], const dh_frame_q *B);

/**
 * @brief Fixed twin of dh_path_eval_f32: T = the frame of the path p at s:
 *        position at the fraction s of the line or the sweep of the arc,
 *        rotation at the fraction s of p->angle along the shortest arc
 *        (the slerp of dh_pose_interp_q: qa (cos s h, sin s h k) about
 *        the path's fixed axis k, from qb for s > 1/2).
 * @param p path from dh_path_line_q or dh_path_arc_q.
 * @param s path parameter, Q2.30, any int32: clamped to [0, 0x40000000];
 *        s <= 0 gives T == p->A and s >= 0x40000000 gives T == p->B
 *        exactly.
 * @param T output frame (must not alias p).
 * Both evaluated from the nearer end. Line: position within 0.5 LSB of
 * p_A + s (p_B - p_A). Arc: angle s sweep to 2^-23 degrees, position
 * within 4 LSB + 2^-26 R of the circle. Rotation entries as
 * dh_pose_interp_q (1.5e-6).
 * @return DH_OK; DH_ERR_ARG when p holds no path (all zero, or quaternions
 *         not unit). T untouched on error.
 */
dh_status dh_path_eval_q(const dh_path_q *p, dh_q30 s, dh_frame_q *T);

/**
 * @brief Cartesian limits of a fixed-point move (the twin of
 *        dh_cart_limits_f32): magnitudes of the tool point's speed and
 *        TOTAL acceleration and of the tool's angular speed and
 *        acceleration, each > 0.
 */
typedef struct {
    int32_t vmax;  /**< linear speed, dh_qpos per s (32767 units/s at Q16.16) */
    int32_t amax;  /**< linear acceleration, total, dh_qpos per s^2 */
    int32_t wmax;  /**< angular speed, Q16.16 deg/s */
    int32_t wdmax; /**< angular acceleration, Q16.16 deg/s^2 */
} dh_cart_limits_q;

/**
 * @brief Fixed twin of dh_path_move_f32: prof = the time-optimal
 *        trapezoid of the path parameter along p within lim, on the
 *        distance D = 2^e LSB (s = position 2^(30 - e), Q2.30 exact).
 * Rates of s as the float twin: s' <= min(V / length, wmax / angle),
 * s'' <= min(At / length, wdmax / angle) (terms of length or angle 0 left
 * out); on a line V = vmax, At = amax; on an arc of radius R
 * V = min(vmax, sqrt(amax R / sqrt 2)) and At = amax sqrt(1 - (V^2 /
 * (amax R))^2), both rounded down. e is the largest exponent <= 30 for
 * which both rates times 2^e fit int32, and each is floor(rate 2^e) (never
 * above the float rate): the profile's rate cap of 32767 units/s^k does
 * not apply to the tool's speed, and the position resolution of the
 * profile is 2^-e of the path.
 * @param prof output (dh_profile_trap_q of d = 2^e; d = 0 and T = 0 when
 *        length and angle are 0).
 * @param e output exponent, 0..30 (30 for no motion).
 * @param p path from dh_path_line_q or dh_path_arc_q.
 * @param lim limits, each > 0.
 * Speed, acceleration and angular rates of the profile's motion within
 * lim up to 1e-8 relative (the profile's held shape, dh_profile_trap_q,
 * and the rounding of the length); T within the rounding of the rates
 * (1 LSB of the smaller of prof->v, prof->a) of the float twin's.
 * @return DH_OK; DH_ERR_ARG for a limit <= 0 or a p that holds no path;
 *         DH_ERR_OVERFLOW when a rate of s does not fit int32 at e = 0 or
 *         rounds to 0, or as dh_profile_trap_q (T reaching 2^31 us). On
 *         error *prof is all zero and *e is 30 (no move: the frame stays
 *         at p->A).
 */
dh_status dh_path_move_q(dh_profile_q *prof, uint32_t *e, const dh_path_q *p, const dh_cart_limits_q *lim);

/**
 * @brief Jerk limits of a fixed-point Cartesian move (the twin of
 *        dh_cart_jerk_f32): magnitudes of the tool point's TOTAL jerk and
 *        of the tool's angular jerk, each > 0.
 */
typedef struct {
    int32_t jmax;  /**< linear jerk, total |d^3 p / dt^3|, dh_qpos per s^3 */
    int32_t wjmax; /**< angular jerk, Q16.16 deg/s^3 */
} dh_cart_jerk_q;

/**
 * @brief Fixed twin of dh_path_move_jerk_f32: prof = the time-optimal
 *        seven-phase profile (dh_profile_scurve_q) of the path parameter
 *        along p within lim and jerk, on the distance D = 2^e LSB as
 *        dh_path_move_q. Rates of s as dh_path_move_q and
 *        s''' <= min(Jt / length, wjmax / angle); on a line Jt = jmax; on
 *        an arc of radius R, V is further held to floor(cbrt(jmax R^2 / 4)),
 *        At to floor(jmax R / (12 V)) and Jt = floor(jmax / 2), so the
 *        TOTAL jerk |x''' - x'^3 / R^2| + 3 x' |x''| / R (x the arc length)
 *        is within jmax and the total acceleration within amax (method:
 *        docs/design.md, "Paths and moves, fixed point"). e is the largest
 *        exponent <= 30 for which all three rates times 2^e fit int32.
 *        Integer only, no division by a variable in a period.
 * @param prof output (kind DH_PROFILE_SCURVE of d = 2^e; d = 0 and T = 0
 *        when length and angle are 0).
 * @param e output exponent, 0..30 (30 for no motion).
 * @param p path from dh_path_line_q or dh_path_arc_q.
 * @param lim limits, each > 0.
 * @param jerk jerk limits, each > 0; NULL: dh_path_move_q (the trapezoid).
 * Speed, total acceleration, total jerk and angular rates of the
 * profile's motion within lim and jerk up to 1e-8 relative (the held
 * shape, dh_profile_scurve_q); T the seven-phase minimum for the rates of
 * s within 1 us + 2^-26 T.
 * @return DH_OK; DH_ERR_ARG for a limit <= 0 or a p that holds no path;
 *         DH_ERR_OVERFLOW when a rate of s does not fit int32 at e = 0 or
 *         rounds to 0, or as dh_profile_scurve_q. On error *prof is all
 *         zero and *e is 30 (no move).
 */
dh_status dh_path_move_jerk_q(dh_profile_q *prof, uint32_t *e, const dh_path_q *p, const dh_cart_limits_q *lim,
                              const dh_cart_jerk_q *jerk);

/**
 * @brief Fixed twin of dh_path_move_eval_f32: T = the frame of the move
 *        (prof, e, p) at time t (us): dh_path_eval_q at s = the profile's
 *        position times 2^(30 - e); t == 0 gives p->A and t >= prof->T
 *        gives p->B exactly; a profile with d == 0 keeps p->A.
 * @param prof, e, p the move of dh_path_move_q and its path.
 * @param t time (us), any uint32.
 * @param T output frame (must not alias p).
 * @return DH_OK; DH_ERR_ARG when p holds no path, e > 30, or prof is not
 *         a profile of d 0 or 2^e (T untouched).
 */
dh_status dh_path_move_eval_q(const dh_profile_q *prof, uint32_t e, const dh_path_q *p, uint32_t t, dh_frame_q *T);

/**
 * @brief One fixed-point move being executed (the twin of dh_move_f32),
 *        written by dh_move_joint_q / dh_move_path_q and advanced once
 *        per control period by dh_move_joint_step_q / dh_move_advance_q
 *        (read-only for the user, who reads dur and clock).
 */
typedef struct {
    dh_profile_q prof[DH_MAX_JOINTS]; /**< joint move: one per joint; path move: prof[0], of s on 2^e */
    dh_path_q path;                   /**< path move: a copy of the path */
    int32_t q0[DH_MAX_JOINTS];        /**< joint move: start configuration */
    int32_t q1[DH_MAX_JOINTS];        /**< joint move: end configuration */
    uint32_t dur;                     /**< duration of the move (us) */
    uint32_t clock;                   /**< time into the move (us), in [0, dur] */
    uint32_t cfrac;                   /**< path move: fraction of a us of the clock, Q2.30 */
    dh_q30 feed;                      /**< path move: feed override r, Q2.30 in [0, 1] (1 otherwise) */
    dh_q30 fcap;                      /**< path move: ceiling of r, Q2.30 in [0, 1] */
    uint32_t e;                       /**< path move: the profile's distance is 2^e (dh_path_move_q) */
    uint32_t lag;                     /**< path move: 1 when the last period was not OK */
    int32_t ps[3];                    /**< scratch of the fixed queue's evaluations (dh_queue_q.c); unused by the executor */
    uint32_t n;                       /**< joint move: number of joints */
    uint32_t kind;                    /**< a dh_move_kind value */
} dh_move_q;

/** @brief What one period of a fixed-point move did. */
typedef struct {
    uint32_t clock; /**< time into the move after this period (us) */
    dh_q30 feed;    /**< path move: the feed override r after this period (Q2.30); joint move: 1 */
    int held;       /**< path move: 1 when the tracker was not OK this period (r falls); joint move: 0 */
    int done;       /**< 1 when the move is complete */
} dh_move_report_q;

/**
 * @brief Fixed twin of dh_move_joint_f32: starts a synchronised joint
 *        move of n joints from q0 to q1 (dh_joint_move_q within vmax and
 *        amax each lowered by floor(x / 1024), jmax as given), sampled
 *        once per period by dh_move_joint_step_q.
 * @param mv output move (kind DH_MOVE_JOINT, clock 0, dur the move's T).
 * @param n number of joints, 1..DH_MAX_JOINTS.
 * @param q0, q1 start and end (n each; Q16.16 degrees or dh_qpos; may
 *        alias each other or mv->q0, mv->q1).
 * @param vmax, amax, jmax per-joint limits (LSB/s^k, > 0); jmax may be
 *        NULL (trapezoids).
 * @return DH_OK; DH_ERR_ARG for n outside 1..DH_MAX_JOINTS or a limit
 *         <= 0; DH_ERR_OVERFLOW as dh_joint_move_q. On error mv holds no
 *         move (kind DH_MOVE_NONE): the step functions return DH_ERR_ARG.
 */
dh_status dh_move_joint_q(dh_move_q *mv, uint32_t n, const int32_t *q0, const int32_t *q1, const int32_t *vmax,
                          const int32_t *amax, const int32_t *jmax);

/**
 * @brief Fixed twin of dh_move_joint_step_f32: one control period of a
 *        joint move: the clock advances by dt (capped at dur) and q = the
 *        move at the new clock (dh_joint_move_eval_q).
 * Each step q(c') - q(c) is within vmax_i (1 - 2^-10) (c' - c) + 2 e_i and
 * each change of step within amax_i (1 - 2^-10) dt^2 + 4 e_i,
 * e_i = 4 + 2^-27 |q1_i - q0_i| LSB (dh_profile_eval_q's position bound).
 * @param mv move from dh_move_joint_q.
 * @param dt control period (us), 1..10^6 (may differ between calls).
 * @param q output: n joint values (must not alias mv); q == q1 exactly
 *        once the clock is at dur.
 * @param rep report: clock, feed 1, held 0, done 1 when the clock is at
 *        dur (every later call returns q1 and done again).
 * @return DH_OK; DH_ERR_ARG for dt outside 1..10^6 or an mv that holds no
 *         joint move. On error mv, q and rep are untouched.
 */
dh_status dh_move_joint_step_q(dh_move_q *mv, uint32_t dt, int32_t *q, dh_move_report_q *rep);

/**
 * @brief Fixed twin of dh_move_path_f32: starts a Cartesian move along p
 *        within lim (dh_path_move_q), executed by the caller's tracker:
 *        each period dh_move_target_q gives the frame to track, the caller
 *        calls dh_track_step_q on it, and dh_move_advance_q advances the
 *        clock with the tracker's state. The first target is p->A; the
 *        clock holds until the tracker is OK there.
 * @param mv output move (kind DH_MOVE_PATH, clock 0, dur the profile's T;
 *        p copied).
 * @param p path from dh_path_line_q or dh_path_arc_q; may be &mv->path
 *        (a path built in place saves its copy's RAM).
 * @param lim Cartesian limits, each > 0.
 * @return DH_OK; DH_ERR_ARG for a limit <= 0 or a p that holds no path;
 *         DH_ERR_OVERFLOW as dh_path_move_q. On error mv holds no move
 *         (its path as it was).
 */
dh_status dh_move_path_q(dh_move_q *mv, const dh_path_q *p, const dh_cart_limits_q *lim);

/**
 * @brief Fixed twin of dh_move_path_jerk_f32: starts a jerk-limited
 *        Cartesian move along p within lim and jerk (dh_path_move_jerk_q),
 *        executed as a move of dh_move_path_q (dh_move_target_q,
 *        dh_move_advance_q): only the profile of s differs.
 * @param mv output move (kind DH_MOVE_PATH, clock 0, dur the profile's T;
 *        p copied).
 * @param p path from dh_path_line_q or dh_path_arc_q; may be &mv->path.
 * @param lim Cartesian limits, each > 0.
 * @param jerk jerk limits, each > 0; NULL: dh_move_path_q.
 * The jerk bound holds while the feed override r is constant (1 while the
 * tracker is OK); while r changes, speed and acceleration stay within lim
 * and the jerk is not bounded by jerk (docs/design.md).
 * @return DH_OK; DH_ERR_ARG for a limit <= 0 or a p that holds no path;
 *         DH_ERR_OVERFLOW as dh_path_move_jerk_q. On error mv holds no
 *         move (its path as it was).
 */
dh_status dh_move_path_jerk_q(dh_move_q *mv, const dh_path_q *p, const dh_cart_limits_q *lim,
                              const dh_cart_jerk_q *jerk);

/**
 * @brief Fixed twin of dh_move_target_f32: T = the frame to track this
 *        period, the path's frame at the move's clock (dh_path_move_eval_q):
 *        p->A at clock 0, p->B exactly once the clock is at dur; at r == 0
 *        it does not move.
 * @param mv move from dh_move_path_q.
 * @param T output frame.
 * @return DH_OK; DH_ERR_ARG for an mv that holds no path move (T untouched).
 */
dh_status dh_move_target_q(const dh_move_q *mv, dh_frame_q *T);

/**
 * @brief Fixed twin of dh_move_advance_f32: ends a control period of a
 *        path move; state is the tracker's report (dh_track_report_q.state)
 *        of its step towards this period's target. The clock advances by
 *        r dt (us, its fraction kept in cfrac), capped at dur.
 * - state OK, clock == dur: done; the clock stays at dur.
 * - state OK, clock < dur: r rises towards its ceiling; at r == 1 the
 *   clock advances by dt exactly.
 * - state LAGGING or UNREACHABLE (held 1): r falls towards 0, where the
 *   clock and the target hold: the move slows down instead of jumping.
 *   The ceiling after such a stretch and its recovery as the float twin
 *   (7/8 of r at its start, rising by 2 r per second of OK periods).
 * r changes each period by at most what keeps the commanded s' r and
 * d(s' r)/dt within the profile's peaks (src/motion/dh_move_q.c).
 * @param mv move from dh_move_path_q.
 * @param dt control period (us), 1..10^6 (the tracker's dt_us).
 * @param state the tracker's state this period, a dh_track_state value.
 * @param rep report: clock and r after the call, held, done.
 * @return DH_OK; DH_ERR_ARG for dt outside 1..10^6, a state that is no
 *         dh_track_state, or an mv that holds no path move. On error mv
 *         and rep are untouched.
 */
dh_status dh_move_advance_q(dh_move_q *mv, uint32_t dt, dh_track_state state, dh_move_report_q *rep);

/* ======================================================================
 * Fixed-point blended sequence of Cartesian line moves (dh_blend_q.c)
 * ==================================================================== */

/**
 * @brief The time scaling of s from 0 to 1 of one line of a fixed-point
 *        blended sequence and its place on the sequence's clock (the twin
 *        of dh_blend_seg_f32; read-only for the user, who reads t0, T,
 *        dur[0] and dur[4] (the overlaps) and dev). Five phases of constant
 *        s'': the start tail (from rest, at the reduced acceleration of
 *        the overlap with the line before; duration 0: at rest there), the
 *        acceleration to the cruise, the cruise, the deceleration, the end
 *        tail (to rest, in the overlap with the line after). Phase k holds
 *        s = s[k] + P[k] x + Q[k] x^2 at x = (time into the phase) / dur[k].
 */
typedef struct {
    uint32_t t0;     /**< start of the line on the sequence's clock (us) */
    uint32_t T;      /**< duration of the line: the sum of dur (us; 0: no motion) */
    uint32_t dur[5]; /**< phase durations (us): start tail, acceleration, cruise, deceleration, end tail */
    int32_t s[5];    /**< s at each phase's start (Q2.30); the last phase ends at 0x40000000 exactly */
    int32_t P[5];    /**< s' dur at each phase's start (Q2.30) */
    int32_t Q[5];    /**< s'' dur^2 / 2 of each phase (Q2.30, signed) */
    dh_qpos dev;     /**< bound on the distance of the tool point from the END corner during that overlap */
} dh_blend_seg_q;

/**
 * @brief A fixed-point sequence of n line moves blended at their corners
 *        over the caller's lines and array of n scalings (the twin of
 *        dh_blend_seq_f32; written by dh_blend_seq_plan_q, read by
 *        dh_blend_seq_eval_q; read-only for the user, who reads n and T).
 *        Neither array is copied: both must stay unchanged while the
 *        sequence is used.
 */
typedef struct {
    const dh_path_q *p;    /**< the caller's lines */
    dh_blend_seg_q *seg;   /**< the caller's scalings, one per line */
    uint32_t n;            /**< number of lines */
    uint32_t T;            /**< duration of the sequence (us) */
} dh_blend_seq_q;

/**
 * @brief Fixed twin of dh_blend_seq_plan_f32: sq = the n paths p[0..n-1]
 *        run one after the other, each corner k (between p[k] and p[k+1])
 *        blended within radius[k] by superposition (the last part of p[k]
 *        at a reduced deceleration overlapping the first part of p[k+1] at
 *        a reduced acceleration), each tail within half its path. Integer
 *        only. Method, proofs and rounding: docs/design.md ("Blended
 *        corners, fixed point"; an arc's as in dh_queue_add_path_blend_q).
 * @param sq output sequence.
 * @param seg the caller's array of n scalings (written; owned by sq).
 * @param p the caller's n lines or arcs (dh_path_line_q, dh_path_arc_q), each
 *        p[k+1].A equal to p[k].B (every entry; not copied: owned by sq);
 *        lengths 0, pure rotations and straight continuations are fine.
 * @param n number of paths, >= 1.
 * @param radius n - 1 blend radii (dh_qpos), >= 0 (NULL allowed when n == 1).
 * @param lim limits, each > 0.
 * A corner runs at rest (dur[4] of p[k], dur[0] of p[k+1] 0) when its
 * radius is 0, a path next to it has no motion, it is within radius[k] + 64
 * LSB of the int32 range, or its blend would not shorten the pair; every
 * corner does when blending would not shorten the whole sequence.
 * The planned motion (the phases as held) keeps the tool point's speed,
 * TOTAL acceleration, angular speed and angular acceleration within lim
 * (the plan's margin of 2^-10 covers the planning's integer rounding);
 * seg[k].dev <= radius[k].
 * @return DH_OK; DH_ERR_ARG for n == 0, a limit <= 0, a radius < 0, a p[k]
 *         that holds no path (or an arc of radius <= 0) or a p[k+1].A that
 *         is not p[k].B; DH_ERR_OVERFLOW when a phase of a path reaches
 *         2^28 us (268 s) or the lines at rest 2^31 us. sq untouched on
 *         error; seg's contents are then unspecified.
 */
dh_status dh_blend_seq_plan_q(dh_blend_seq_q *sq, dh_blend_seg_q *seg, const dh_path_q *p, uint32_t n,
                              const dh_qpos *radius, const dh_cart_limits_q *lim);

/**
 * @brief Fixed twin of dh_blend_seq_eval_f32: T = the frame of the blended
 *        sequence sq at time t (us, on the sequence's clock): path k's
 *        frame (dh_path_eval_q at its s) where it runs alone, in an overlap
 *        the superposition of paths k and k+1: position p_k(s_k) +
 *        (p_k+1(s_k+1) - corner), rotation R_k+1(s_k+1) R_corner^T R_k(s_k).
 * @param sq sequence from dh_blend_seq_plan_q.
 * @param t time (us), any uint32: t == 0 gives p[0].A and t >= sq->T gives
 *        p[n-1].B exactly.
 * @param T output frame (must not alias the lines).
 * Outside the overlaps the position is on path k as dh_path_eval_q's;
 * inside, within seg[k].dev of corner k plus 2 LSB + 32 2^-30 (L_k +
 * L_k+1) (the rounding of the held scalings) and each arc's 4 LSB +
 * 2^-26 R (dh_path_eval_q's). Rotation
 * entries as dh_path_eval_q's (1.5e-6) plus a few 2^-30.
 * @return DH_OK; DH_ERR_ARG when sq holds no sequence (n 0, a line that
 *         holds no path, or a scaling out of range; T untouched);
 *         DH_ERR_OVERFLOW when an overlap's position leaves the int32
 *         range, T then holding it saturated (only for lines or scalings
 *         changed after planning: the plan keeps every blend inside).
 */
dh_status dh_blend_seq_eval_q(const dh_blend_seq_q *sq, uint32_t t, dh_frame_q *T);

/* ======================================================================
 * Fixed-point move queue, stop and resume (dh_queue_q.c)
 * ==================================================================== */

/**
 * @brief One queued fixed-point move as its constructor takes it (the
 *        twin of dh_queue_item_f32; read-only for the user): a joint move
 *        to q1 (dh_move_joint_q without q0: it starts where the robot is
 *        when it starts; trapezoids) or a path move (dh_move_path_q, its
 *        plan checked when appended and made when it starts).
 */
typedef struct {
    dh_path_q path;              /**< path move: the path */
    dh_cart_limits_q lim;        /**< path move: its limits */
    dh_profile_q prof;           /**< path move: its profile of s on 2^e (dh_path_move_q) */
    uint32_t e;                  /**< path move: the profile's exponent */
    int32_t q1[DH_MAX_JOINTS];   /**< joint move: end configuration */
    int32_t vmax[DH_MAX_JOINTS]; /**< joint move: velocity limits (LSB/s) */
    int32_t amax[DH_MAX_JOINTS]; /**< joint move: acceleration limits (LSB/s^2) */
    int32_t jmax[DH_MAX_JOINTS]; /**< joint move: jerk limits (LSB/s^3; 0: the trapezoid) */
    uint32_t n;                  /**< joint move: number of joints */
    uint32_t kind;               /**< DH_MOVE_JOINT or DH_MOVE_PATH */
    dh_blend_seg_q seg;          /**< blended line (dh_queue_add_path_blend_q): its scaling of s (prof then bounds it) */
    dh_qpos radius;              /**< blended line: the radius of its corner with the next move */
    uint32_t blend;              /**< 1 for a blended line */
} dh_queue_item_q;

/**
 * @brief A fixed-point queue of moves in a caller-owned array of items and
 *        the move it is running (the twin of dh_queue_f32; read-only for
 *        the user, who reads count, seq and phase). Written by
 *        dh_queue_init_q.
 */
typedef struct {
    dh_queue_item_q *items;      /**< the caller's array (ring buffer) */
    uint32_t cap;                /**< its number of items */
    uint32_t head;               /**< index of the oldest queued move (the running one) */
    uint32_t count;              /**< queued moves, the running one included */
    uint32_t seq;                /**< moves completed since dh_queue_init_q: the running move's number */
    uint32_t phase;              /**< a dh_queue_phase value */
    uint32_t started;            /**< 1 when mv holds the running move's plan */
    uint32_t hold;               /**< the command repeated at rest: DH_MOVE_NONE, DH_MOVE_JOINT (hq), DH_MOVE_PATH (mv's frame) */
    uint32_t sync;               /**< 1 when the next path command follows joint commands (dh_queue_cmd_q.sync) */
    uint32_t pend;               /**< 1 between dh_queue_target_q and dh_queue_advance_q */
    uint32_t dt;                 /**< control period of the pending target call (us) */
    dh_q30 r;                    /**< joint move: its time warp d clock / dt, Q2.30 in [0, 1] (path move: mv.feed) */
    uint32_t rfrac;              /**< joint move: fraction of a us of its warped clock, Q2.30 */
    dh_q30 fcap;                 /**< path move: the ceiling of its feed override when the stop began */
    int32_t hq[DH_MAX_JOINTS];   /**< the last joint command */
    dh_move_report_q mrep;       /**< workspace: the running path move's report */
    dh_move_q mv;                /**< plan of the running move (or of the last one completed) */
    uint32_t bl;                 /**< 1 when mv is a blended line (its s from bg, mv.prof[0] its bound) */
    dh_blend_seg_q bg;           /**< blended line in mv: its scaling of s */
    dh_blend_seg_q bs[2];        /**< workspace: the scalings of a corner being planned */
    dh_profile_q bz[2];          /**< workspace: their bounds */
} dh_queue_q;

/** @brief What the caller does this period (dh_queue_target_q). */
typedef struct {
    uint32_t kind;             /**< DH_MOVE_JOINT: command q; DH_MOVE_PATH: track T (dh_track_step_q); DH_MOVE_NONE: nothing to do */
    uint32_t sync;             /**< kind PATH after joint commands: 1 once, re-initialise the tracker at q (dh_track_init_q) first */
    int32_t q[DH_MAX_JOINTS];  /**< joint command (n joints); with sync, the last joint command */
    dh_frame_q T;              /**< frame to track */
} dh_queue_cmd_q;

/** @brief What one period of the fixed-point queue did. */
typedef struct {
    uint32_t seq;   /**< number of the move that ran this period (moves completed before it) */
    uint32_t clock; /**< its clock after the period (us) */
    dh_q30 feed;    /**< its time warp r after the period (path move: its feed override), Q2.30 in [0, 1] */
    int held;       /**< 1 when the clock held (path move, tracker not OK; or waiting for rest, or stopped) */
    int done;       /**< 1 when the move completed this period */
    int last;       /**< 1 when the queue is empty after this period (the last move done) */
    int stopped;    /**< 1 when at rest after a stop (phase DH_QUEUE_STOPPED) */
} dh_queue_report_q;

/**
 * @brief Fixed twin of dh_queue_init_f32: an empty queue over the
 *        caller's array of cap items (phase DH_QUEUE_RUN, seq 0, nothing
 *        planned, no command to hold).
 * @param qu output queue.
 * @param items the caller's array (not copied; owned by the queue until
 *        it is initialised again).
 * @param cap its number of items, >= 1.
 * @return DH_OK; DH_ERR_ARG for cap == 0 (qu untouched).
 */
dh_status dh_queue_init_q(dh_queue_q *qu, dh_queue_item_q *items, uint32_t cap);

/**
 * @brief Appends a joint move of n joints to q1 within vmax and amax
 *        (and jmax when not NULL: seven-phase profiles), as
 *        dh_move_joint_q plans it when it starts: from the last joint
 *        command, or after a path move from the tracker's configuration.
 * @param qu queue from dh_queue_init_q.
 * @param n number of joints, 1..DH_MAX_JOINTS (the tracker's robot's).
 * @param q1 end configuration (n; Q16.16 degrees or dh_qpos), within the
 *        robot's limits.
 * @param vmax, amax, jmax limits (n each, LSB/s, LSB/s^2 and LSB/s^3,
 *        > 0); jmax may be NULL (trapezoids). The jerk bound holds while
 *        the move's time warp is 1 (not during a stop or a resume, which
 *        keep velocity and acceleration within vmax and amax).
 * @return DH_OK; DH_ERR_ARG for n outside 1..DH_MAX_JOINTS or a limit
 *         <= 0; DH_ERR_LIMIT when the queue holds cap moves already
 *         (nothing is overwritten). On error qu and its items are untouched.
 */
dh_status dh_queue_add_joint_q(dh_queue_q *qu, uint32_t n, const int32_t *q1, const int32_t *vmax,
                               const int32_t *amax, const int32_t *jmax);

/**
 * @brief Appends a Cartesian move along p within lim (dh_move_path_q):
 *        it starts at p->A (its clock holds until the tracker is OK
 *        there) and ends at rest at p->B.
 * @param qu queue from dh_queue_init_q.
 * @param p path from dh_path_line_q or dh_path_arc_q (copied).
 * @param lim Cartesian limits, each > 0 (copied).
 * @return DH_OK; DH_ERR_LIMIT when the queue is full (checked first);
 *         DH_ERR_ARG, DH_ERR_OVERFLOW as dh_move_path_q (its profile of s
 *         is planned here, into the free item). On error qu and its
 *         queued items are untouched.
 */
dh_status dh_queue_add_path_q(dh_queue_q *qu, const dh_path_q *p, const dh_cart_limits_q *lim);

/**
 * @brief Appends a Cartesian line or arc move along p within lim, as
 *        dh_queue_add_path_q, whose corner with the NEXT move is blended
 *        within radius: passed without stopping, the paths left only
 *        inside the ball of that radius about the corner.
 * Blended when the next move is also appended by this function, has the
 * same limits, starts at p->B (the same frame, bit for bit), is appended
 * while this one has not started, both move and the blend is shorter
 * than a stop there (dh_blend_seq_plan_q's corner: tails at (63/128) of
 * each path's acceleration, each within half its path, the overlap within
 * radius; an arc's tails at (7/16), its centripetal acceleration in an
 * overlap within amax / 16). Each path runs a five-phase scaling of s
 * (dh_blend_seg_q) on the queue's clock, in an overlap the superposition
 * of the two (dh_blend_seq_eval_q's). Speed, TOTAL acceleration, angular speed and
 * acceleration within lim (the plan's 2^-10 margin covers the rounding)
 * with the feed override, a stop and a resume: the time warp r changes
 * only in periods that do not reach into an overlap (docs/design.md,
 * "Fixed-point queue"), so a stop or a lagging tracker inside an overlap
 * slows the move from its end, on the planned blend within radius of the
 * corner. Outside the overlaps the target is on its path.
 * @param qu queue from dh_queue_init_q.
 * @param p path from dh_path_line_q or dh_path_arc_q (copied).
 * @param lim Cartesian limits, each > 0 (copied).
 * @param radius blend radius (dh_qpos), >= 0 (0: at rest).
 * @return DH_OK; DH_ERR_LIMIT when the queue is full (checked first);
 *         DH_ERR_ARG for radius < 0, a p that holds no path (or an arc of
 *         radius <= 0, a negative length or angle) or a limit <= 0;
 *         DH_ERR_OVERFLOW when a phase of the path reaches 2^28 us or its
 *         bound 2^30 us. On error qu and its queued items are untouched.
 */
dh_status dh_queue_add_path_blend_q(dh_queue_q *qu, const dh_path_q *p, const dh_cart_limits_q *lim,
                                    dh_qpos radius);

/**
 * @brief Appends a jerk-limited Cartesian move along p within lim and
 *        jerk (dh_move_path_jerk_q), otherwise as dh_queue_add_path_q.
 * @param qu queue from dh_queue_init_q.
 * @param p path from dh_path_line_q or dh_path_arc_q (copied).
 * @param lim Cartesian limits, each > 0 (copied).
 * @param jerk jerk limits, each > 0; NULL: dh_queue_add_path_q.
 * The jerk bound holds while the feed override is constant (not during a
 * stop, a resume or a slow-down for the tracker, which keep speed and
 * acceleration within lim).
 * @return DH_OK; DH_ERR_LIMIT when the queue is full (checked first);
 *         DH_ERR_ARG, DH_ERR_OVERFLOW as dh_move_path_jerk_q. On error qu
 *         and its queued items are untouched.
 */
dh_status dh_queue_add_path_jerk_q(dh_queue_q *qu, const dh_path_q *p, const dh_cart_limits_q *lim,
                                   const dh_cart_jerk_q *jerk);

/**
 * @brief Begins a control period of dt = t->dt_us: the command of the
 *        running move after this period (joint move) or the frame to
 *        track this period (path move), starting the next queued move
 *        when the last one is done.
 * A period: this call; kind JOINT: the caller commands cmd.q (no tracker
 * call); kind PATH: with cmd.sync 1 dh_track_init_q(t, ..., cmd.q, ...)
 * first (the tracker restarts at the last joint command, at rest), then
 * dh_track_step_q(t, &cmd.T, ...); then dh_queue_advance_q(qu, state,
 * &rep). A joint move starts from the last joint command, or after a
 * path move from t->q once every 2 |t->v[i]| <= floor(floor(amax_i dt /
 * 10^6) dt / 10^6); until then, while stopped and with nothing queued, the
 * command at rest is repeated (the last joint command or path frame;
 * DH_MOVE_NONE before any move). A path move starts at once.
 * Commands keep the move's limits: a joint move's are dh_move_joint_step_q's
 * at a clock advancing by r dt (r = 1 but after dh_queue_stop_q and
 * dh_queue_resume_q, r changing by at most what keeps every joint's
 * acceleration within amax_i (1 - 2^-10)), a path move's dh_move_target_q's
 * (dh_move_advance_q's feed override). Method and proof: docs/design.md
 * ("Fixed-point queue").
 * @param qu queue.
 * @param t the caller's tracker (read only: q, v, dt_us, r->n).
 * @param cmd output command.
 * @return DH_OK; DH_ERR_ARG for a target call already pending or a joint
 *         move for another number of joints than t's robot has: qu and
 *         cmd untouched. A status of dh_move_joint_q or dh_move_path_q
 *         when the running move cannot be planned: it stays queued,
 *         unstarted, and cmd is untouched.
 */
dh_status dh_queue_target_q(dh_queue_q *qu, const dh_track_q *t, dh_queue_cmd_q *cmd);

/**
 * @brief Ends the control period begun by dh_queue_target_q: state is the
 *        tracker's state of this period (DH_TRACK_OK after a joint command
 *        or DH_MOVE_NONE; it is read for path moves only).
 * Joint move: its clock advanced in dh_queue_target_q. Path move:
 * dh_move_advance_q (its feed override r falls while the tracker is not
 * OK and rises while it is; while braking after dh_queue_stop_q it falls
 * whatever the state). A move is done when its clock reached its
 * duration (a path move: and the tracker OK at B) and is then removed
 * from the queue (seq + 1). A brake that reached rest (r 0, or the move
 * done) sets phase DH_QUEUE_STOPPED.
 * @param qu queue with a pending target call.
 * @param state a dh_track_state value.
 * @param rep report of the period.
 * @return DH_OK; DH_ERR_ARG for no pending target call or a state that is
 *         no dh_track_state. On error qu and rep are untouched.
 */
dh_status dh_queue_advance_q(dh_queue_q *qu, dh_track_state state, dh_queue_report_q *rep);

/**
 * @brief Stops: brings the running move to rest along its own path within
 *        its own limits by the time warp r of its clock falling to 0 (no
 *        jump in position or velocity): a joint move's r falls by at most
 *        what keeps every joint's acceleration within amax_i (1 - 2^-10),
 *        a path move's feed override as when its tracker lags (within the
 *        profile's peaks, so within lim). Where the plan already
 *        decelerates at its limit r cannot fall and the move comes to rest
 *        at its end instead. A move not started, held at its start (clock
 *        0), at its end or at r == 0, or no move, is at rest: the stop is
 *        immediate (phase STOPPED). A stop while braking or stopped
 *        changes nothing. Queued moves stay queued and do not start until
 *        dh_queue_resume_q.
 * @param qu queue from dh_queue_init_q (not between target and advance).
 * @return DH_OK; DH_ERR_ARG for a call between dh_queue_target_q and
 *         dh_queue_advance_q (qu untouched).
 */
dh_status dh_queue_stop_q(dh_queue_q *qu);

/**
 * @brief Resumes after (or during) a stop: r rises again from where it is
 *        towards 1 (a path move: towards the ceiling its feed override had
 *        when the stop began), within the same bounds as its fall, so the
 *        move continues along its own plan and ends exactly at its end (q1;
 *        B), and then the rest of the queue runs. Called while running, it
 *        changes nothing.
 * @param qu queue from dh_queue_init_q (not between target and advance).
 * @return DH_OK; DH_ERR_ARG for a call between dh_queue_target_q and
 *         dh_queue_advance_q (qu untouched).
 */
dh_status dh_queue_resume_q(dh_queue_q *qu);

#ifdef __cplusplus
}
#endif

#endif /* DHMATH_MOTION_H */
