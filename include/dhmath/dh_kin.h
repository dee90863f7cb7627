/**
 * @file dh_kin.h
 * @brief Geometric Jacobian, orientation error and numerical inverse
 *        kinematics (float) for a dh_robot.
 */
#ifndef DHMATH_DH_KIN_H
#define DHMATH_DH_KIN_H

#include "dhmath/dh_robot.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * Geometric Jacobian in the base frame: J is 6 x n row-major (J[row*n+col]),
 * rows vx vy vz wx wy wz; columns per radian for revolute joints, per length
 * unit for prismatic joints. T_end (may be NULL) receives the end frame.
 */
dh_status dh_jacobian_f32(const dh_robot *r, const float *q, float *J, dh_mat4_f32 *T_end);
/** Same, expressed in the tool (end-effector) frame. */
dh_status dh_jacobian_tool_f32(const dh_robot *r, const float *q, float *J, dh_mat4_f32 *T_end);

/** Orientation error a(dR) (seed 003): rotation vector w (rad) with R_target = Rot(w) * R. */
dh_status dh_rot_error_f32(const dh_mat3_f32 *R_target, const dh_mat3_f32 *R, dh_vec3_f32 *w);

/** Task-space mask bits for dh_ik_params.mask. */
#define DH_IK_PX 0x01u
#define DH_IK_PY 0x02u
#define DH_IK_PZ 0x04u
#define DH_IK_RX 0x08u
#define DH_IK_RY 0x10u
#define DH_IK_RZ 0x20u
#define DH_IK_POSITION 0x07u
#define DH_IK_FULL 0x3Fu

typedef struct {
    uint32_t max_iter;   /**< iteration bound */
    uint32_t mask;       /**< DH_IK_* bits of the error components to drive to 0 */
    float tol_pos;       /**< position tolerance (length unit) */
    float tol_rot;       /**< orientation tolerance (rad) */
    float w_rot;         /**< weight of orientation vs position error (length unit per rad) */
} dh_ik_params;

typedef struct {
    uint32_t iterations;
    float err_pos;       /**< final position error norm */
    float err_rot;       /**< final orientation error norm (rad) */
} dh_ik_result;

/** Workspace floats needed by dh_ik_f32 for an n-joint robot. */
#define DH_IK_WORK_FLOATS(n) (6u * (n) + 3u * (n) * (n) + 8u * (n) + 64u)

void dh_ik_params_default(dh_ik_params *p);

/**
 * Numerical IK (damped least squares / Levenberg-Marquardt, Sugihara).
 * q0: start (n values), q: result (may alias q0). Joint limits are respected
 * during the iteration. Returns DH_OK (converged), DH_ERR_NO_CONVERGENCE
 * (max iterations; best q returned), DH_ERR_UNREACHABLE (stalled with a
 * residual; best q returned), DH_ERR_SINGULAR, DH_ERR_NAN, DH_ERR_ARG
 * (workspace too small, bad params).
 */
dh_status dh_ik_f32(const dh_robot *r, const dh_mat4_f32 *target, const float *q0, float *q,
                    const dh_ik_params *p, float *work, size_t work_len, dh_ik_result *res);

#ifdef __cplusplus
}
#endif

#endif /* DHMATH_DH_KIN_H */
