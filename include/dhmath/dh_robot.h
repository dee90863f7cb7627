/**
 * @file dh_robot.h
 * @brief Caller-owned robot description (standard or modified DH) and
 *        forward kinematics in float and fixed point.
 *
 * Joint variables: degrees for revolute joints, the robot's length unit for
 * prismatic joints (float: any unit; fixed: dh_qpos, typically millimetres).
 *
 * Standard DH (seed 003):  A_i = Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i)
 * Modified DH (Craig):     A_i = Rx(alpha_{i-1}) Tx(a_{i-1}) Rz(theta_i) Tz(d_i)
 * (for modified DH the a/alpha stored in joint i are the ones that precede
 * it, as in Craig's table row i). Revolute: theta_i = q_i + theta offset,
 * d_i = d. Prismatic: theta_i = theta (fixed), d_i = q_i + d (offset).
 *
 * End frame: T = base * A_1 * ... * A_n * tool.
 */
#ifndef DHMATH_DH_ROBOT_H
#define DHMATH_DH_ROBOT_H

#include "dhmath/dh_common.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum { DH_JOINT_REVOLUTE = 0, DH_JOINT_PRISMATIC = 1 } dh_joint_type;
typedef enum { DH_CONV_STANDARD = 0, DH_CONV_MODIFIED = 1 } dh_convention;

/** Flags in dh_robot.flags. */
#define DH_ROBOT_HAS_F32 0x1u   /**< float path prepared (all joints added with _f32) */
#define DH_ROBOT_HAS_Q   0x2u   /**< fixed path prepared (every constant representable) */

/** One joint: parameters as given plus constants precomputed once. */
typedef struct {
    dh_joint_type type;
    float a, d, alpha_deg, theta_deg;   /**< as given (float path) */
    float qmin, qmax;                   /**< limits (deg for R, length for P); qmin > qmax = no limits */
    float sa, ca;                       /**< sin/cos(alpha), computed once */
    dh_qpos a_q, d_q;                   /**< fixed-path lengths */
    dh_q16 theta_q;                     /**< fixed-path theta offset (deg Q16.16) */
    dh_q30 sa_q, ca_q;                  /**< fixed-path sin/cos(alpha) */
    int32_t qmin_q, qmax_q;             /**< fixed-path limits (dh_q16 deg for R, dh_qpos for P) */
} dh_joint;

/** Robot description. Initialise with dh_robot_init(); caller owns it. */
typedef struct {
    dh_convention conv;
    uint32_t n;                         /**< number of joints, 0..DH_MAX_JOINTS */
    uint32_t flags;                     /**< DH_ROBOT_HAS_* */
    dh_joint joint[DH_MAX_JOINTS];
    dh_mat4_f32 base, tool;             /**< float base and tool (identity by default) */
    dh_frame_q base_q, tool_q;          /**< fixed base and tool (identity by default) */
} dh_robot;

/** Empty robot (n = 0) with identity base/tool. DH_ERR_ARG for an unknown convention. */
dh_status dh_robot_init(dh_robot *r, dh_convention conv);

/**
 * Append a joint (float parameters). Precomputes sin/cos(alpha) for both
 * paths and the fixed-path constants (lengths converted with DH_QPOS_FRAC
 * fraction bits; when they do not fit the fixed path is marked unavailable
 * and dh_fk_q() returns DH_ERR_OVERFLOW, the float path is unaffected).
 * DH_ERR_ARG when full or type unknown, DH_ERR_NAN for non-finite values.
 */
dh_status dh_robot_add_joint_f32(dh_robot *r, dh_joint_type type, float a, float d,
                                 float alpha_deg, float theta_deg);
/** Append a joint with fixed-point parameters only (no float used). */
dh_status dh_robot_add_joint_q(dh_robot *r, dh_joint_type type, dh_qpos a, dh_qpos d,
                               dh_q16 alpha_deg, dh_q16 theta_deg);
/** Joint limits (deg for R, length for P). qmin <= qmax else DH_ERR_ARG. */
dh_status dh_robot_set_limits_f32(dh_robot *r, uint32_t i, float qmin, float qmax);
/** Base/tool frames. The float versions also set the fixed-path frames when they fit. */
dh_status dh_robot_set_base_f32(dh_robot *r, const dh_mat4_f32 *base);
dh_status dh_robot_set_tool_f32(dh_robot *r, const dh_mat4_f32 *tool);
dh_status dh_robot_set_base_q(dh_robot *r, const dh_frame_q *base);
dh_status dh_robot_set_tool_q(dh_robot *r, const dh_frame_q *tool);
/** DH_OK when every q[i] is within its limits, else DH_ERR_LIMIT (DH_ERR_NAN for NaN). */
dh_status dh_robot_check_limits_f32(const dh_robot *r, const float *q);

/** Link matrix A_i for joint i (0-based) at joint value q. */
dh_status dh_link_f32(const dh_robot *r, uint32_t i, float q, dh_mat4_f32 *A);
dh_status dh_link_q(const dh_robot *r, uint32_t i, int32_t q, dh_frame_q *A);

/** End frame T = base * A_1..A_n * tool. Does not check limits. */
dh_status dh_fk_f32(const dh_robot *r, const float *q, dh_mat4_f32 *T);
/**
 * Every frame: frames[i] = base * A_1 .. A_{i+1} for i = 0..n-1 (tool not
 * applied); T_end (may be NULL) = frames[n-1] * tool. frames holds n entries.
 */
dh_status dh_fk_frames_f32(const dh_robot *r, const float *q, dh_mat4_f32 *frames, dh_mat4_f32 *T_end);
/** Fixed path: q[i] is dh_q16 degrees for R joints, dh_qpos for P joints. */
dh_status dh_fk_q(const dh_robot *r, const int32_t *q, dh_frame_q *T);
dh_status dh_fk_frames_q(const dh_robot *r, const int32_t *q, dh_frame_q *frames, dh_frame_q *T_end);

#ifdef __cplusplus
}
#endif

#endif /* DHMATH_DH_ROBOT_H */
