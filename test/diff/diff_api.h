/* SPDX-License-Identifier: Apache-2.0 */
/*
 * diff_api.h - inputs, outputs and the wrapper table of test_builds_agree.
 *
 * Every public function has one wrapper w_<name>(in, out) in diff_calls.inc,
 * which is compiled twice: calls_main.c (the library the test links as
 * dhmath) and calls_alt.c (the copy built with the other DH_SMALL value,
 * its symbols renamed dhalt_*; dh_alt_names.h maps the plain names onto
 * them). A wrapper reads the fields of diff_in it needs and writes its
 * results to diff_out; the test fills diff_out with a canary first, so
 * untouched outputs compare equal too.
 */
#ifndef DIFF_API_H
#define DIFF_API_H

#include <stddef.h>
#include <stdint.h>

#include "dhmath/dhmath.h"

typedef struct {
    uint32_t sel;            /* per-wrapper selector: aliasing, NULL T_end, ... */
    int32_t k[8];            /* integer arguments */
    float f[8];              /* float scalar arguments */
    float q[DH_MAX_JOINTS];  /* float joint values / q0 */
    int32_t qi[DH_MAX_JOINTS]; /* fixed joint values */
    dh_mat4_f32 M[2];
    dh_mat3_f32 R[2];
    dh_frame_q F[2];
    dh_vec3_f32 v[4];
    dh_vec4_f32 v4;
    dh_plane_f32 pl;
    dh_quat_f32 qt[2];
    dh_vec3_q vq;
    dh_ik_params_f32 ikp;
    dh_ik_params_q ikpq;
    char str[8];
    const dh_robot *rob;     /* read-only robot (FK, Jacobian, IK, setters copy it) */
} diff_in;

/* Every member is 4-byte data: no padding, so memcmp compares values only.
 * The members are ordered by use so that most functions compare a short
 * prefix (DIFF_OUT_SMALL). */
typedef struct {
    int32_t st;              /* status or integer result */
    int32_t seq;
    int32_t k[8];
    float f[8];
    dh_vec3_f32 v;
    dh_vec4_f32 v4;
    dh_plane_f32 pl;
    dh_quat_f32 qt;
    dh_vec3_q vq;
    dh_mat3_f32 R;
    dh_mat4_f32 M;
    dh_frame_q F;
    dh_vec3_f32 pts[4];
    dh_ik_params_f32 ikp;
    dh_ik_params_q ikpq;
    char str[32];            /* string results (the pointers differ between copies) */
    /* DIFF_OUT_SMALL */
    float q[DH_MAX_JOINTS];
    dh_ik_result_f32 ikres;
    dh_ik_result_q ikresq;
    int32_t qi[DH_MAX_JOINTS];
    float J[6 * DH_MAX_JOINTS];
    dh_mat4_f32 Mf[DH_MAX_JOINTS];
    dh_frame_q Ff[DH_MAX_JOINTS];
    int32_t Ji[6 * DH_MAX_JOINTS]; /* fixed Jacobian (integer words: after the float J, Mf) */
    dh_quat_q qq;            /* fixed quaternion */
    dh_dir3_q dq;            /* fixed axis / rotation vector */
    dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
    dh_ikc_sol_q solq[DH_IKC_MAX_SOL];
    dh_ikc_model_f32 mf;
    dh_ikc_model_q mq;
    /* DIFF_OUT_FRAMES */
    dh_robot rob;
} diff_out;

#define DIFF_OUT_SMALL offsetof(diff_out, q)
#define DIFF_OUT_FRAMES offsetof(diff_out, rob)
#define DIFF_OUT_ALL sizeof(diff_out)

typedef void (*diff_call)(const diff_in *in, diff_out *out);

/* IK workspace (caller-owned, contents undefined after the call) */
#define DIFF_IK_WORK DH_IK_WORK_FLOATS(DH_MAX_JOINTS)
#define DIFF_IKQ_WORK DH_IK_WORK_Q(DH_MAX_JOINTS)

/*
 * The table: X(name, generator, count, compared bytes, comparison).
 * Order is irrelevant; counts are inputs per function (>= 10^6 except the
 * iterative IK solver, see test_builds_agree.c).
 */
#define DIFF_FUNCS(X) \
    X(dh_status_str, g_status, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_sincos_f32, g_angle_f, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_sin_f32, g_angle_f, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_cos_f32, g_angle_f, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_sincos_q, g_ints, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_sin_q, g_ints, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_cos_q, g_ints, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_atan2_f32, g_atan2_f, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_asin_f32, g_unit_f, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_acos_f32, g_unit_f, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_atan2_q, g_ints, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_asin_q, g_unit_q, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_acos_q, g_unit_q, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_frame_identity_q, g_ints, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_frame_trans_q, g_ints, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_frame_rotx_q, g_ints, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_frame_roty_q, g_ints, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_frame_rotz_q, g_ints, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_frame_rot_axis_q, g_ints, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_frame_mul_q, g_frames, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_frame_inv_q, g_frames, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_frame_apply_point_q, g_frames, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_frame_apply_dir_q, g_frames, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_frame_orthonormalize_q, g_frames, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_frame_ortho_error_q, g_frames, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_frame_from_mat4_q, g_mat1, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_frame_to_mat4_q, g_frames, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_identity_f32, g_mat1, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_trans_f32, g_mat1, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_rotx_f32, g_angle_f, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_roty_f32, g_angle_f, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_rotz_f32, g_angle_f, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_rot_axis_f32, g_axis_f, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_scale_f32, g_mat1, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_persp_f32, g_persp, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_from_noap_f32, g_mat1, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_n_f32, g_mat1, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_o_f32, g_mat1, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_a_f32, g_mat1, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_p_f32, g_mat1, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_get_rot_f32, g_mat1, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_set_rot_f32, g_mats, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_mul_f32, g_mats, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_mul_affine_f32, g_mats, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_premul_f32, g_mats, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_postmul_f32, g_mats, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_apply_point_f32, g_mat1, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_apply_dir_f32, g_mat1, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_apply_vec4_f32, g_mat1, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_apply_point_h_f32, g_mat1, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_apply_plane_f32, g_inv, 1000000, DIFF_OUT_SMALL, C_PLANE) \
    X(dh_plane_mul_f32, g_mat1, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_apply_points_f32, g_mat1, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_inv_rigid_f32, g_inv, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_inv_f32, g_inv, 1000000, DIFF_OUT_SMALL, C_INV) \
    X(dh_mat4_check_rot_f32, g_check, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_check_rigid_f32, g_check, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_inv_auto_f32, g_inv, 1000000, DIFF_OUT_SMALL, C_INV) \
    X(dh_mat4_to_axis_angle_f32, g_rot, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat4_check_finite_f32, g_mat1, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_euler_parse, g_string, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_euler_name, g_ints, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_euler_to_mat3_f32, g_euler, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat3_to_euler_f32, g_rot, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_quat_to_mat3_f32, g_quat, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat3_to_quat_f32, g_rot, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_quat_normalize_f32, g_quat, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_quat_mul_f32, g_quat, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_quat_conj_f32, g_quat, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_quat_from_axis_angle_f32, g_axis_f, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_axis_angle_to_mat3_f32, g_axis_f, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat3_to_axis_angle_f32, g_rot, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_rotvec_to_mat3_f32, g_rotvec, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat3_to_rotvec_f32, g_rot, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_skew_f32, g_mat1, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_vee_f32, g_rot, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_angvel_f32, g_rot, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_angvel_body_f32, g_rot, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat3_check_rot_f32, g_check, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_mat3_orthonormalize_f32, g_rot, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_robot_init, g_setter, 1000000, DIFF_OUT_ALL, C_BITS) \
    X(dh_robot_add_joint_f32, g_setter, 1000000, DIFF_OUT_ALL, C_BITS) \
    X(dh_robot_add_joint_q, g_setter, 1000000, DIFF_OUT_ALL, C_BITS) \
    X(dh_robot_set_limits_f32, g_setter, 1000000, DIFF_OUT_ALL, C_BITS) \
    X(dh_robot_set_limits_q, g_setter, 1000000, DIFF_OUT_ALL, C_BITS) \
    X(dh_robot_set_rates_f32, g_setter, 1000000, DIFF_OUT_ALL, C_BITS) \
    X(dh_robot_set_rates_q, g_setter, 1000000, DIFF_OUT_ALL, C_BITS) \
    X(dh_robot_set_base_f32, g_setter, 1000000, DIFF_OUT_ALL, C_BITS) \
    X(dh_robot_set_tool_f32, g_setter, 1000000, DIFF_OUT_ALL, C_BITS) \
    X(dh_robot_set_base_q, g_setter, 1000000, DIFF_OUT_ALL, C_BITS) \
    X(dh_robot_set_tool_q, g_setter, 1000000, DIFF_OUT_ALL, C_BITS) \
    X(dh_robot_check_limits_f32, g_robot, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_robot_check_limits_q, g_robot, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_robot_check, g_robot, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_link_f32, g_robot, 1000000, DIFF_OUT_SMALL, C_ZERO_SIGN) \
    X(dh_fk_f32, g_robot, 1000000, DIFF_OUT_SMALL, C_ZERO_SIGN) \
    X(dh_fk_frames_f32, g_robot, 1000000, DIFF_OUT_FRAMES, C_ZERO_SIGN) \
    X(dh_link_q, g_robot, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_fk_q, g_robot, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_fk_frames_q, g_robot, 1000000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_jacobian_f32, g_robot, 1000000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_jacobian_tool_f32, g_robot, 1000000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_rot_error_f32, g_rot, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_manipulability_f32, g_robot, 1000000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_dls_step_f32, g_robot, 1000000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_jacobian_q, g_robot, 1000000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_jacobian_tool_q, g_robot, 1000000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_rot_error_q, g_frames, 1000000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_frame_to_euler_q, g_frames, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_euler_to_frame_q, g_ints, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_frame_to_quat_q, g_frames, 1000000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_quat_to_frame_q, g_ints, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_frame_to_axis_angle_q, g_frames, 1000000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_pose_error_f32, g_check, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_ik_params_default_f32, g_robot, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_ik_f32, g_ik, DIFF_IK_COUNT, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_ikc_analyse_f32, g_ikc, DIFF_IKC_COUNT, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_ikc_analyse_q, g_ikc, DIFF_IKC_COUNT, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_ikc_why_str, g_status, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_ikc_f32, g_ikc, DIFF_IKC_COUNT, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_ikc_q, g_ikc, DIFF_IKC_COUNT, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_ikc_nearest_f32, g_ikc, DIFF_IKC_COUNT, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_ikc_nearest_q, g_ikc, DIFF_IKC_COUNT, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_ik_params_default_q, g_robot, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_ik_q, g_ikq, DIFF_IKQ_COUNT, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_slerp_f32, g_slerp, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_pose_interp_f32, g_pose, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_pose_angle_f32, g_pose, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_profile_trap_f32, g_motion, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_profile_scurve_f32, g_motion, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_profile_quintic_f32, g_motion, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_profile_stretch_f32, g_motion, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_profile_eval_f32, g_motion, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_joint_move_f32, g_motion, 1000000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_joint_move_eval_f32, g_motion, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_path_line_f32, g_path, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_path_arc_f32, g_path, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_path_eval_f32, g_path, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_path_move_f32, g_path, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_path_move_jerk_f32, g_path, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_path_move_eval_f32, g_path, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_blend_plan_f32, g_path, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_blend_eval_f32, g_path, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_blend_seq_plan_f32, g_path, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_blend_seq_eval_f32, g_path, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_blend_seq_plan_jerk_f32, g_path, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_move_joint_f32, g_motion, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_move_joint_step_f32, g_motion, 1000000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_move_path_f32, g_path, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_move_path_jerk_f32, g_path, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_move_target_f32, g_path, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_move_advance_f32, g_path, 1000000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_queue_init_f32, g_path, 100000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_queue_add_joint_f32, g_path, 100000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_queue_add_path_f32, g_path, 100000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_queue_add_path_blend_f32, g_path, 100000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_queue_add_path_jerk_f32, g_path, 100000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_queue_add_path_blend_jerk_f32, g_path, 100000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_queue_target_f32, g_path, 100000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_queue_advance_f32, g_path, 100000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_queue_stop_f32, g_path, 100000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_queue_resume_f32, g_path, 100000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_track_init_f32, g_robot, DIFF_IK_COUNT, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_track_step_f32, g_robot, DIFF_IK_COUNT, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_track_sync_f32, g_robot, DIFF_IK_COUNT, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_manipulability_q, g_robot, 100000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_dls_step_q, g_robot, 100000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_track_init_q, g_robot, 100000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_track_step_q, g_robot, 20000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_slerp_q, g_ints, 100000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_pose_interp_q, g_frames, 100000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_pose_angle_q, g_frames, 100000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_profile_trap_q, g_ints, 100000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_profile_scurve_q, g_ints, 100000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_profile_quintic_q, g_ints, 100000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_profile_stretch_q, g_ints, 100000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_profile_eval_q, g_ints, 100000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_joint_move_q, g_ints, 100000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_joint_move_eval_q, g_ints, 100000, DIFF_OUT_SMALL, C_BITS) \
    X(dh_path_line_q, g_fpath, 100000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_path_arc_q, g_fpath, 100000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_path_eval_q, g_fpath, 100000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_path_move_q, g_fpath, 50000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_path_move_jerk_q, g_fpath, 50000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_path_move_eval_q, g_fpath, 50000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_move_joint_q, g_fpath, 50000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_move_joint_step_q, g_fpath, 50000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_move_path_q, g_fpath, 50000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_move_path_jerk_q, g_fpath, 50000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_move_target_q, g_fpath, 20000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_move_advance_q, g_fpath, 20000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_blend_seq_plan_q, g_fpath, 20000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_blend_seq_eval_q, g_fpath, 20000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_queue_init_q, g_fpath, 20000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_queue_add_joint_q, g_fpath, 20000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_queue_add_path_q, g_fpath, 20000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_queue_add_path_jerk_q, g_fpath, 20000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_queue_add_path_blend_q, g_fpath, 20000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_queue_target_q, g_fpath, 20000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_queue_advance_q, g_fpath, 20000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_queue_stop_q, g_fpath, 20000, DIFF_OUT_FRAMES, C_BITS) \
    X(dh_queue_resume_q, g_fpath, 20000, DIFF_OUT_FRAMES, C_BITS)

/* enum of the table rows */
#define DIFF_ENUM(name, gen, count, len, cmp) E_##name,
enum { DIFF_FUNCS(DIFF_ENUM) DIFF_NFUNCS };
#undef DIFF_ENUM

extern const diff_call diff_calls_main[DIFF_NFUNCS];
extern const diff_call diff_calls_alt[DIFF_NFUNCS];

#endif /* DIFF_API_H */
