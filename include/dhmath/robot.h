/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Index: the functions of robot.h by source file (src/robot/).
 *   dh_robot.c    dh_robot_init, dh_robot_add_joint_f32,
 *                 dh_robot_set_limits_f32, dh_robot_set_rates_f32,
 *                 dh_robot_set_base_f32,
 *                 dh_robot_set_tool_f32, dh_robot_check_limits_f32,
 *                 dh_robot_check
 *   dh_robot_q.c  dh_robot_add_joint_q, dh_robot_set_limits_q,
 *                 dh_robot_set_rates_q,
 *                 dh_robot_set_base_q, dh_robot_set_tool_q,
 *                 dh_robot_check_limits_q
 *   dh_fk_f32.c   dh_link_f32, dh_fk_f32, dh_fk_frames_f32
 *   dh_fk_q.c     dh_link_q, dh_fk_q, dh_fk_frames_q
 */
/**
 * @file robot.h
 * @brief Caller-owned robot description (standard or modified DH) and
 *        forward kinematics in float and fixed point.
 *
 * Joint variables: degrees for revolute joints, the robot's length unit for
 * prismatic joints (float: any unit; fixed: dh_qpos, typically millimetres).
 *
 * Standard DH (Paul 1981): A_i = Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i)
 * Modified DH (Craig):     A_i = Rx(alpha_{i-1}) Tx(a_{i-1}) Rz(theta_i) Tz(d_i)
 * (for modified DH the a/alpha stored in joint i are the ones that precede
 * it, as in Craig's table row i). Revolute: theta_i = q_i + theta offset,
 * d_i = d. Prismatic: theta_i = theta (fixed), d_i = q_i + d (offset).
 *
 * End frame: T = base * A_1 * ... * A_n * tool.
 *
 * Two paths share one description:
 * - float (dh_*_f32): the robot must have been built with
 *   dh_robot_add_joint_f32() (flag DH_ROBOT_HAS_F32);
 * - fixed (dh_*_q, integer only): rotation Q2.30, lengths dh_qpos
 *   (DH_QPOS_FRAC fraction bits), angles dh_q16 degrees. Available when every
 *   constant is representable (flag DH_ROBOT_HAS_Q). dh_robot_add_joint_f32()
 *   prepares both paths; dh_robot_add_joint_q() prepares only the fixed one.
 *
 * sin/cos of every alpha are computed once when the joint is added; FK
 * evaluates one sin/cos pair per joint (method: docs/design.md, "Forward
 * kinematics"). Error bounds: float FK as dh_fk_f32(), fixed FK as
 * dh_fk_q(); measured accuracy for the example robots:
 * docs/accuracy_fk.md; cost and stack: docs/generated/performance_target.md,
 * docs/generated/footprint.md (every function stays within 256 bytes of stack).
 *
 * Description out of range: dh_robot is a plain caller-owned struct, so
 * its n may hold any value (a corrupted copy, or one made with a larger
 * DH_MAX_JOINTS). Every function that walks the joints (limits, link, FK)
 * returns DH_ERR_ARG with its outputs untouched when n > DH_MAX_JOINTS,
 * and never reads or writes past joint[]. The full bad-input table is
 * docs/errors.md.
 *
 * Overflow (fixed path): a length a or d (or d + q) equal to INT32_MIN is
 * used as -INT32_MAX (one LSB), so no intermediate 64-bit sum can wrap;
 * any saturated output entry makes the function return DH_ERR_OVERFLOW.
 *
 * DH_SMALL=1 (config.h): every output and status is the default
 * build's, except that a zero entry of a float link or FK frame may have
 * the other sign and a NaN entry another payload.
 *
 * No function keeps state; a dh_robot may be shared read-only between
 * threads.
 */
#ifndef DHMATH_ROBOT_H
#define DHMATH_ROBOT_H

#include "dhmath/common.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Kind of joint. */
typedef enum {
    DH_JOINT_REVOLUTE = 0,  /**< joint variable is theta (degrees) */
    DH_JOINT_PRISMATIC = 1  /**< joint variable is d (length unit) */
} dh_joint_type;
/** DH convention of a whole robot. */
typedef enum {
    DH_CONV_STANDARD = 0,   /**< A = Rz(theta) Tz(d) Tx(a) Rx(alpha) */
    DH_CONV_MODIFIED = 1    /**< A = Rx(alpha) Tx(a) Rz(theta) Tz(d) (Craig) */
} dh_convention;

/** @name Flags in dh_robot.flags
 * DH_ROBOT_HAS_F32 and DH_ROBOT_HAS_Q are the public summary; the other
 * bits record why a path is unavailable and are maintained by the setters
 * (read them, never write them).
 * @{ */
#define DH_ROBOT_HAS_F32 0x1u   /**< float path prepared (all joints added with _f32, float base/tool current) */
#define DH_ROBOT_HAS_Q   0x2u   /**< fixed path prepared (every constant representable) */
#define DH_ROBOT_F32_NO_JOINT 0x10u  /**< a joint was added with dh_robot_add_joint_q (no float parameters) */
#define DH_ROBOT_F32_NO_BASE  0x20u  /**< base last set with dh_robot_set_base_q (float base stale) */
#define DH_ROBOT_F32_NO_TOOL  0x40u  /**< tool last set with dh_robot_set_tool_q (float tool stale) */
#define DH_ROBOT_Q_NO_JOINT   0x100u /**< a joint constant did not fit its Q format */
#define DH_ROBOT_Q_NO_BASE    0x200u /**< float base not representable in dh_frame_q */
#define DH_ROBOT_Q_NO_TOOL    0x400u /**< float tool not representable in dh_frame_q */
#define DH_ROBOT_BASE_ID_F32  0x1000u /**< float base is exactly the identity (product skipped) */
#define DH_ROBOT_TOOL_ID_F32  0x2000u /**< float tool is exactly the identity (product skipped) */
#define DH_ROBOT_BASE_ID_Q    0x4000u /**< fixed base is exactly the identity (product skipped) */
#define DH_ROBOT_TOOL_ID_Q    0x8000u /**< fixed tool is exactly the identity (product skipped) */
#define DH_ROBOT_BASE_SMALL_Q 0x10000u /**< every row of the fixed base rotation has norm <= 1.5: the chain's rotation entries cannot saturate, FK skips their range checks */
/** @} */

/** One joint: parameters as given plus constants precomputed once. */
typedef struct {
    dh_joint_type type;                 /**< revolute or prismatic */
    float a;                            /**< link length a (float path; 0 when added with _q) */
    float d;                            /**< link offset d (P joints: offset added to q) */
    float alpha_deg;                    /**< link twist alpha, degrees */
    float theta_deg;                    /**< joint angle theta (R joints: offset added to q), degrees */
    float qmin;                         /**< lower limit (deg for R, length for P) */
    float qmax;                         /**< upper limit; qmin > qmax = no limits */
    float sa;                           /**< sin(alpha), computed once */
    float ca;                           /**< cos(alpha), computed once */
    dh_qpos a_q;                        /**< fixed-path a */
    dh_qpos d_q;                        /**< fixed-path d */
    dh_q16 alpha_q;                     /**< fixed-path alpha (deg Q16.16) */
    dh_q16 theta_q;                     /**< fixed-path theta offset (deg Q16.16) */
    dh_q30 sa_q;                        /**< fixed-path sin(alpha) */
    dh_q30 ca_q;                        /**< fixed-path cos(alpha) */
    int32_t qmin_q;                     /**< fixed-path lower limit (dh_q16 deg for R, dh_qpos for P) */
    int32_t qmax_q;                     /**< fixed-path upper limit; qmin_q > qmax_q = no limits */
    float vmax;                         /**< velocity limit, deg/s (R) or length unit/s (P); +inf = unlimited */
    float amax;                         /**< acceleration limit, deg/s^2 or length unit/s^2; +inf = unlimited */
    int32_t vmax_q;                     /**< fixed-path velocity limit, dh_q16 deg/s or dh_qpos/s; INT32_MAX = unlimited */
    int32_t amax_q;                     /**< fixed-path acceleration limit, dh_q16 deg/s^2 or dh_qpos/s^2; INT32_MAX = unlimited */
} dh_joint;

/** Robot description. Initialise with dh_robot_init(); caller owns it. */
typedef struct {
    dh_convention conv;                 /**< DH convention of every joint */
    uint32_t n;                         /**< number of joints, 0..DH_MAX_JOINTS */
    uint32_t flags;                     /**< DH_ROBOT_* */
    dh_joint joint[DH_MAX_JOINTS];      /**< joints 0..n-1 */
    dh_mat4_f32 base;                   /**< float base (identity by default) */
    dh_mat4_f32 tool;                   /**< float tool (identity by default) */
    dh_frame_q base_q;                  /**< fixed base (identity by default) */
    dh_frame_q tool_q;                  /**< fixed tool (identity by default) */
} dh_robot;

/* ---- building a description -------------------------------------------- */

/**
 * @brief Empty robot: n = 0, identity base and tool on both paths, both
 *        paths available (flags HAS_F32 | HAS_Q and the identity bits).
 *
 * Integer only (the float fields are stored as bit patterns): a firmware
 * that builds its robot with this and the _q setters links no soft float.
 * @param r    robot to initialise (not NULL). Every field is written.
 * @param conv DH_CONV_STANDARD or DH_CONV_MODIFIED.
 * @return DH_OK, or DH_ERR_ARG for an unknown convention (r untouched).
 */
dh_status dh_robot_init(dh_robot *r, dh_convention conv);

/**
 * @brief Append a joint from float parameters (prepares both paths).
 *
 * Stores the parameters, computes sin/cos(alpha) once (dh_sincos_f32 for
 * the float path, dh_sincos_q of the rounded alpha for the fixed path) and
 * converts a, d (round to nearest, DH_QPOS_FRAC fraction bits) and alpha,
 * theta (deg Q16.16). When a constant does not fit its Q format (|a|, |d| >=
 * 2^(31-DH_QPOS_FRAC), |alpha|, |theta| >= 32768 deg) the joint is still added,
 * the fixed path is marked unavailable (DH_ROBOT_Q_NO_JOINT, dh_fk_q() then
 * returns DH_ERR_UNAVAILABLE) and the float path is unaffected. Limits: none.
 * @param r     robot (not NULL)
 * @param type  DH_JOINT_REVOLUTE or DH_JOINT_PRISMATIC
 * @param theta_deg joint angle (degrees; offset added to q for R joints)
 * @param d     link offset (length unit; offset added to q for P joints)
 * @param a     link length (length unit)
 * @param alpha_deg link twist (degrees)
 * @return DH_OK; DH_ERR_NAN when a parameter is NaN or infinite (tested
 *         first); DH_ERR_ARG when n == DH_MAX_JOINTS or type is unknown. On
 *         error r is untouched.
 */
dh_status dh_robot_add_joint_f32(dh_robot *r, dh_joint_type type, float theta_deg, float d,
                                 float a, float alpha_deg);

/**
 * @brief Append a joint from fixed-point parameters only (integer only).
 *
 * The joint's float parameters are set to +0 (sin/cos 0 and 1) and the
 * float path is marked unavailable (DH_ROBOT_F32_NO_JOINT: dh_fk_f32()
 * returns DH_ERR_UNAVAILABLE). sin/cos(alpha) come from
 * dh_sincos_q(alpha_deg). Limits: none on either path.
 * @param r     robot (not NULL)
 * @param type  DH_JOINT_REVOLUTE or DH_JOINT_PRISMATIC
 * @param theta_deg, d, a, alpha_deg the DH table's row: angles degrees
 *              Q16.16, lengths dh_qpos (DH_QPOS_FRAC fraction bits), any value
 * @return DH_OK; DH_ERR_ARG when full or type unknown (r untouched).
 */
dh_status dh_robot_add_joint_q(dh_robot *r, dh_joint_type type, dh_q16 theta_deg, dh_qpos d,
                               dh_qpos a, dh_q16 alpha_deg);

/**
 * @brief Joint limits of joint i (0-based), both paths.
 *
 * Degrees for R joints, length unit for P joints. The fixed-path limits are
 * the values rounded to dh_q16 / dh_qpos, saturated to the int32 range (a
 * limit beyond the Q range does not restrict fixed-point values).
 * @return DH_OK; DH_ERR_ARG when i >= n, n > DH_MAX_JOINTS or qmin > qmax;
 *         DH_ERR_NAN for NaN/Inf limits. On error r is untouched.
 */
dh_status dh_robot_set_limits_f32(dh_robot *r, uint32_t i, float qmin, float qmax);
/**
 * @brief Fixed-path limits only of joint i (dh_q16 deg for R, dh_qpos for P).
 *        The float limits are not changed. Integer only.
 * @return DH_OK; DH_ERR_ARG when i >= n, n > DH_MAX_JOINTS or qmin > qmax
 *         (r untouched).
 */
dh_status dh_robot_set_limits_q(dh_robot *r, uint32_t i, int32_t qmin, int32_t qmax);

/**
 * @brief Velocity and acceleration limits of joint i (0-based), both paths.
 *
 * vmax in deg/s (R) or length unit/s (P), amax in deg/s^2 or length
 * unit/s^2; +inf means unlimited (the default of every joint). The
 * tracker (track.h) keeps every joint within them. The fixed-path copies
 * (vmax_q, amax_q: dh_q16 per s / s^2 for R, dh_qpos per s / s^2 for P)
 * are the values rounded to nearest; +inf becomes INT32_MAX (unlimited); a
 * finite value is stored as at least 1 LSB and at most INT32_MAX - 1 (a
 * limit beyond the Q range is clamped, never made unlimited).
 * @return DH_OK; DH_ERR_ARG when i >= n, n > DH_MAX_JOINTS or a value is
 *         <= 0 (or -inf); DH_ERR_NAN for a NaN. On error r is untouched.
 */
dh_status dh_robot_set_rates_f32(dh_robot *r, uint32_t i, float vmax, float amax);
/**
 * @brief Velocity and acceleration limits of joint i from fixed-point values
 *        (dh_q16 deg/s and deg/s^2 for R, dh_qpos per s and s^2 for P);
 *        INT32_MAX means unlimited. Integer only: the float copies are
 *        the values divided by 2^16 (R) or 2^DH_QPOS_FRAC (P), rounded to
 *        nearest float (exact below 2^24 LSB) with INT32_MAX -> +inf, built
 *        as bit patterns (no soft float is linked).
 * @return DH_OK; DH_ERR_ARG when i >= n, n > DH_MAX_JOINTS or a value is
 *         <= 0 (r untouched).
 */
dh_status dh_robot_set_rates_q(dh_robot *r, uint32_t i, int32_t vmax_q, int32_t amax_q);

/**
 * @brief Base frame (pre-multiplies the chain), float.
 *
 * The bottom row must be exactly 0 0 0 1; the 3x3 part is used as given
 * (rigid or not: the robot file format allows scale()). Also sets the
 * fixed-path base when it fits (rotation entries rounded to Q2.30 must lie
 * in [-2, 2), positions in the dh_qpos range); otherwise the fixed path is
 * marked unavailable (DH_ROBOT_Q_NO_BASE) until a base that fits is set.
 * An exact identity is recorded (DH_ROBOT_BASE_ID_*) so FK skips the
 * product. base may point to r->base.
 * @return DH_OK; DH_ERR_NAN when an element is not finite; DH_ERR_NOT_RIGID
 *         when the bottom row is not 0 0 0 1. On error r is untouched.
 */
dh_status dh_robot_set_base_f32(dh_robot *r, const dh_mat4_f32 *base);
/** @brief Tool frame (post-multiplies the chain), float. Same contract as dh_robot_set_base_f32(). */
dh_status dh_robot_set_tool_f32(dh_robot *r, const dh_mat4_f32 *tool);
/**
 * @brief Base frame, fixed path only (integer only). Any values accepted
 *        (the 3x3 part need not be a rotation). Unless both the new fixed base and the
 *        float base are the identity, the float base becomes stale: the
 *        float path is unavailable (DH_ROBOT_F32_NO_BASE) until
 *        dh_robot_set_base_f32() is called. Clears DH_ROBOT_Q_NO_BASE.
 * @return DH_OK.
 */
dh_status dh_robot_set_base_q(dh_robot *r, const dh_frame_q *base);
/** @brief Tool frame, fixed path only. Same contract as dh_robot_set_base_q(). */
dh_status dh_robot_set_tool_q(dh_robot *r, const dh_frame_q *tool);

/**
 * @brief Check q (n values, deg for R, length for P) against the float limits.
 * @return DH_OK when every q[i] with limits is within [qmin, qmax];
 *         DH_ERR_NAN when any q[i] is NaN/Inf (checked first, all joints);
 *         DH_ERR_LIMIT otherwise; DH_ERR_ARG when n > DH_MAX_JOINTS.
 */
dh_status dh_robot_check_limits_f32(const dh_robot *r, const float *q);
/** @brief Check Q joint values (dh_q16 deg / dh_qpos) against the fixed limits.
 *  @return DH_OK or DH_ERR_LIMIT; DH_ERR_ARG when n > DH_MAX_JOINTS.
 *  Integer only. */
dh_status dh_robot_check_limits_q(const dh_robot *r, const int32_t *q);

/**
 * @brief Check that the derived fields of a description are the ones its
 *        setters compute: for a robot not built by the setters.
 *
 * FK trusts the derived fields (sin/cos of alpha, fixed copies of the float
 * constants, the flags) without looking at the primary ones. A description
 * written by hand as a static const initialiser, copied from elsewhere or
 * corrupted can hold wrong derived fields, and FK then returns a wrong
 * pose with DH_OK. Call this once at start-up on every dh_robot that was
 * not built by the setters at run time (hand-written or untrusted const
 * data); one generated by `dhmath gen` (docs/cli.md) passes by
 * construction, and so does every description the setters build. Each
 * derived field is recomputed with the setters' own code and compared bit
 * for bit (method: src/robot/dh_robot.c); joints n..DH_MAX_JOINTS-1 are not read.
 * Uses float (dh_sincos_f32) also for a fixed-only robot.
 * @param r robot (not NULL); not modified.
 * @return DH_OK when consistent; DH_ERR_ARG when conv is unknown, n >
 *         DH_MAX_JOINTS or the type of a joint 0..n-1 is unknown;
 *         DH_ERR_INCONSISTENT when a derived field, a flag bit or the
 *         pairing of a float constant with its fixed copy is not what the
 *         setters leave (also for NaN/Inf float constants or limits, a
 *         rate limit not > 0 or not paired with its fixed copy as a rate
 *         setter leaves it, or a float base/tool with bottom row not 0 0 0 1).
 */
dh_status dh_robot_check(const dh_robot *r);

/* ---- forward kinematics, float ------------------------------------------ */

/**
 * @brief Link matrix A_i of joint i (0-based) at joint value q.
 * @param r robot (not NULL)
 * @param i joint index, 0 <= i < n
 * @param q degrees (R) or length (P), finite.
 * @param A output (bottom row 0 0 0 1); untouched on error.
 * @return DH_OK; DH_ERR_ARG when i >= n or n > DH_MAX_JOINTS;
 *         DH_ERR_UNAVAILABLE when the float path is unavailable;
 *         DH_ERR_NAN for non-finite q; DH_ERR_OVERFLOW when q + offset
 *         overflows to infinity. On error A is untouched.
 */
dh_status dh_link_f32(const dh_robot *r, uint32_t i, float q, dh_mat4_f32 *A);

/**
 * @brief End frame T = base * A_1(q_0) .. A_n(q_{n-1}) * tool (float).
 *
 * Does not check joint limits (see dh_robot_check_limits_f32()). Any finite
 * q is accepted (angle reduction is exact, so the error does not grow with
 * |q|). For R joints the sum q + theta offset is rounded to float once
 * (<= 0.5 ulp of the sum). test_fk_f32 asserts, for the example robots in
 * metres: position <= 4.5e-7 m, rotation entries <= 4.5e-7 (measured
 * figures: docs/accuracy_fk.md).
 * @param r robot (not NULL), n >= 1
 * @param q n joint values (not NULL); must not alias T; T must not overlap *r (the chain is built in T)
 * @param T end frame; bottom row written as exactly 0 0 0 1
 * @return DH_OK; DH_ERR_ARG when n == 0 or n > DH_MAX_JOINTS, DH_ERR_UNAVAILABLE
 *         when the float path is unavailable (T untouched); DH_ERR_NAN when any q is NaN/Inf (T untouched);
 *         DH_ERR_OVERFLOW when q + offset overflows to infinity (T
 *         untouched) or when an entry of the result is not finite (huge
 *         prismatic values, base or tool; T written).
 */
dh_status dh_fk_f32(const dh_robot *r, const float *q, dh_mat4_f32 *T);

/**
 * @brief Every frame: frames[i] = base * A_1 .. A_{i+1} for i = 0..n-1 (tool
 * not applied); T_end (may be NULL) = frames[n-1] * tool.
 * @param r robot (not NULL), n >= 1
 * @param q n joint values (not NULL)
 * @param frames n entries (not NULL), must not overlap q, T_end or *r.
 * @param T_end end frame with the tool, or NULL when not wanted
 * @return as dh_fk_f32(); on DH_ERR_ARG / DH_ERR_NAN nothing is written.
 */
dh_status dh_fk_frames_f32(const dh_robot *r, const float *q, dh_mat4_f32 *frames, dh_mat4_f32 *T_end);

/* ---- forward kinematics, fixed point (integer only) --------------------- */

/**
 * @brief Link matrix A_i of joint i at Q joint value q (dh_q16 deg for R,
 *        dh_qpos for P).
 * @return DH_OK; DH_ERR_ARG when i >= n or n > DH_MAX_JOINTS (A untouched);
 *         DH_ERR_UNAVAILABLE when the fixed path is unavailable (A
 *         untouched); DH_ERR_OVERFLOW when d + q saturates (A written with the
 *         saturated d).
 */
dh_status dh_link_q(const dh_robot *r, uint32_t i, int32_t q, dh_frame_q *A);

/**
 * @brief End frame (fixed point): rotation Q2.30, position dh_qpos.
 *
 * q[i] is dh_q16 degrees for R joints (any int32: theta = q + offset is
 * reduced exactly, no wrap-around error), dh_qpos for P joints. 64-bit
 * accumulation, one rounding per entry and product; no float, no division.
 * Position error about half an LSB per joint plus the rotation error times
 * the reach; test_fk_q asserts, for the example robots in mm, DH_QPOS_FRAC
 * 16: <= 5e-4 mm and <= 64 LSB of Q2.30 per rotation entry (measured
 * figures: docs/accuracy_fk.md).
 * @param r robot (not NULL), n >= 1, fixed path prepared
 * @param q n joint values (not NULL): dh_q16 degrees (R) or dh_qpos (P)
 * @param T output, must not alias q or any part of *r.
 * @return DH_OK; DH_ERR_ARG when n == 0 or n > DH_MAX_JOINTS (T
 *         untouched); DH_ERR_UNAVAILABLE when the fixed path is
 *         unavailable (constants did not fit: T untouched); DH_ERR_OVERFLOW
 *         when a position or rotation entry saturated (T
 *         written with the saturated values).
 */
dh_status dh_fk_q(const dh_robot *r, const int32_t *q, dh_frame_q *T);

/**
 * @brief Every frame, fixed point: frames[i] = base * A_1 .. A_{i+1};
 *        T_end (may be NULL) = frames[n-1] * tool.
 * @return as dh_fk_q(); on DH_ERR_ARG or an unavailable path nothing is written.
 */
dh_status dh_fk_frames_q(const dh_robot *r, const int32_t *q, dh_frame_q *frames, dh_frame_q *T_end);

#ifdef __cplusplus
}
#endif

#endif /* DHMATH_ROBOT_H */
