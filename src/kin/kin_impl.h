/* SPDX-License-Identifier: Apache-2.0 */
/*
 * kin_impl.h - PRIVATE blocks of the kinematics family (src/kin/, not
 * installed): the Jacobian and orientation-error blocks that the IK solvers
 * call. dh_ik_f32 calls them one after the other on its workspace
 * to stay within the 256 B stack budget; the Jacobian pass calls no
 * trigonometry (sin/cos precomputed) and only libgcc below it.
 * F (12 floats): the 3x4 part of a frame by columns n, o, a, p,
 * F[3c + k] = row k of column c (as dh_mat4_f32.m[c][k]).
 */
#ifndef DHMATH_SRC_KIN_IMPL_H
#define DHMATH_SRC_KIN_IMPL_H

#include "dhmath/kin.h"
#include "../robot/robot_impl.h" /* the fixed FK steps */

/* Jacobian (6 x n row-major, base frame) and end frame F from
 * scd[3i..3i+2] = sin theta_i, cos theta_i, d_i. No argument checks (n,
 * convention, joint types, float path: the caller's job); J, F, scd do not
 * overlap. 1 when every entry of J and F is finite, else 0. */
int dh_kin_jac_f32_(const dh_robot *r, const float *scd, float *J, float *F);

/* dh_jacobian_f32 with its scratch in the caller's w (15 floats,
 * overlapping nothing else): the tracker keeps it in its workspace. Same
 * contract. */
dh_status dh_kin_jacobian_f32_(const dh_robot *r, const float *q, float *J, dh_mat4_f32 *T_end, float *w);

/* dh_manipulability_f32 and dh_dls_step_f32 with their matrices in the
 * caller's ws (DH_DLS_WS_FLOATS floats, overlapping nothing): the
 * tracker (src/track/) calls them on its state to stay within the stack
 * budget. Same contracts. */
#define DH_DLS_WS_FLOATS 27u
dh_status dh_manipulability_ws_f32_(const float *J, uint32_t n, float *w, float *sigma_min, float *ws);
dh_status dh_dls_step_ws_f32_(const dh_robot *r, const float *J, const float *e, float lambda, const float *dq_max,
                              float *dq, float *ws);

/* dh_pose_error_f32 with dR in the caller's d (9 floats, overlapping
 * nothing): the tracker keeps it in its workspace. Same contract. */
dh_status dh_kin_pose_error_f32_(const dh_mat4_f32 *T_target, const dh_mat4_f32 *T, float *e, float *d);
/* The same for a target that has passed these checks already (finite,
 * rotation within DH_ROT_ERROR_TOL, det > 0): T's checks alone, the same
 * status and e. */
dh_status dh_kin_pose_error_to_f32_(const dh_mat4_f32 *T_target, const dh_mat4_f32 *T, float *e, float *d);

/* a(dR) of dh_rot_error_f32 for dR row-major, d[3 row + col], into w[0..2]
 * (d and w do not overlap). */
void dh_kin_rotvec_f32_(const float *d, float *w);

/* dh_rot_cols_ok_f32 with DH_ROT_ERROR_TOL (columns c0, c1, c2). */
int dh_kin_rot_ok_f32_(const float *c0, const float *c1, const float *c2);

/* dh_jacobian_q's body (dh_jacobian_q.c) without its argument checks (n,
 * fixed path, convention, joint types: the caller's) and with the end
 * frame F supplied by the caller; nonzero when an entry saturated. */
int dh_kin_jac_q_(const dh_robot *r, const int32_t *q, int32_t *J, dh_frame_q *F);

/* The argument checks of dh_jacobian_q (they depend on the robot alone):
 * DH_OK, DH_ERR_ARG or DH_ERR_UNAVAILABLE as dh_jacobian_q returns them. */
dh_status dh_kin_jac_check_q_(const dh_robot *r);

/* dh_rot_error_q's body (dh_pose_error_q.c) without its rigidity checks (the
 * caller's): s->w = a(Rt R^T), Q3.29 rad; s->D (dR) and s->q scratch, in
 * the caller's memory (dh_ik_q keeps them off the stack: 19 words). */
typedef struct {
    dh_frame_q D;
    dh_dir3_q w;
    int32_t q[4];
} dh_kin_rot_scratch_q;
void dh_kin_rot_error_q_(const dh_frame_q *F_target, const dh_frame_q *F, dh_kin_rot_scratch_q *s);
/* dh_rot_ok_q_ with DH_ROT_ERROR_TOL_Q: the checks of dh_rot_error_q on
 * one frame (1 when they pass). */
int dh_kin_rot_ok_q_(const dh_frame_q *F);
/* dh_rot_error_q with its scratch D (dR) and q (4 words) in the caller's
 * memory (the tracker's), for a target F_target that has passed
 * dh_kin_rot_ok_q_ already: F's check alone, the same status and w. */
dh_status dh_kin_rot_error_to_q_(const dh_frame_q *F_target, const dh_frame_q *F, dh_frame_q *D, dh_dir3_q *w,
                                 int32_t *q);

/* The bodies of dh_manipulability_q and dh_dls_step_q (dh_dls_q.c) on
 * the state in c, for a caller that keeps c between calls (the tracker):
 * dh_kin_manip_q_ reads c->J and c->n (1..DH_MAX_JOINTS); dh_kin_dls_q_
 * reads c->J, c->n, c->dq_max and c->pris (dh_kin_pris_q_ of the robot)
 * after dh_dls_step_q's argument checks (the caller's). Same results and
 * statuses. With both w and sigma_min, save (DH_DLS_SAVE_Q words, or
 * NULL) keeps the equilibrated Gram matrix for the second factorization,
 * which is then not formed twice. */
#define DH_DLS_SAVE_Q 21u
void dh_kin_manip_q_(dh_dls_work_q *c, int32_t *w, int32_t *sigma_min, int32_t *save);
dh_status dh_kin_dls_q_(dh_dls_work_q *c, const int32_t *e, int32_t lambda, int32_t *dq);
/* bit i set when joint i of r is prismatic */
uint32_t dh_kin_pris_q_(const dh_robot *r);

#endif /* DHMATH_SRC_KIN_IMPL_H */
