/* SPDX-License-Identifier: Apache-2.0 */
/*
 * motion_impl.h - PRIVATE helpers of the motion family (src/motion/, not
 * installed): the Cartesian paths (dh_path.c) keep the unit quaternions of
 * their end frames and call the slerp of dh_interp.c directly, without
 * dh_pose_interp_f32's checks and conversions, to stay within the 256 B
 * stack budget; the move executor (dh_move.c) checks a path with the
 * test of dh_path.c; the jerk bound of an arc (dh_path.c) takes the
 * profiles' cube root.
 */
#ifndef DHMATH_SRC_MOTION_IMPL_H
#define DHMATH_SRC_MOTION_IMPL_H

#include "dhmath/motion.h"

/* qb replaced by -qb when qa . qb < 0: the shorter of the two arcs */
void dh_motion_shorter_f32_(const dh_quat_f32 *qa, dh_quat_f32 *qb);

/* The slerp of the unit quaternions qa, qb (qa . qb >= 0) at s in [0, 1]
 * into *out (which may alias qa or qb); s == 0 and s == 1 (and no rotation
 * between them) copy the nearer end. */
void dh_motion_slerp_f32_(const dh_quat_f32 *qa, const dh_quat_f32 *qb, float s, dh_quat_f32 *out);

/* 1 when p holds a path (its quaternions unit within a factor 2, as
 * dh_path_line_f32 / dh_path_arc_f32 write them), 0 when not (e.g. all
 * zero); the test of dh_path_eval_f32's DH_ERR_ARG (dh_path.c) */
int dh_motion_path_ok_f32_(const dh_path_f32 *p);

/* *sl = min(*sl, num / den) for den > 0 (*sl == 0: no bound yet); a
 * quotient of +Inf bounds nothing. DH_ERR_OVERFLOW when it underflows to
 * 0 or is NaN (dh_path.c); the rate bounds of a path move (dh_path.c) and
 * of a blend's tails (dh_blend.c) */
dh_status dh_motion_bound_f32_(float *sl, float num, float den);

/* The square root (cube == 0) or the cube root (cube == 1) of n / m for
 * finite n >= 0, m > 0 (0 for n == 0), without underflow or overflow of
 * the quotient (dh_profile.c); the jerk bound of an arc (dh_path.c) */
float dh_motion_root_f32_(float n, float m, int cube);

/* ---- fixed point (dh_interp_q.c) ---- */

/* qb replaced by -qb when qa . qb < 0: the shorter arc; unit inputs (no
 * INT32_MIN to negate). */
void dh_motion_shorter_q_(const dh_quat_q *qa, dh_quat_q *qb);

/* The slerp of the unit Q2.30 quaternions qa, qb (qa . qb >= 0) at s in
 * [0, 2^30] into out (may alias qa or qb); s == 0 and s == 2^30 (and no
 * rotation between them) copy the nearer end. */
void dh_motion_slerp_q_(const dh_quat_q *qa, const dh_quat_q *qb, dh_q30 s, dh_quat_q *out);

/* pa + round(s (pb - pa) / 2^30) for s in [0, 2^30], from pb for
 * s > 2^29: between pa and pb, exact at both ends, cannot overflow. */
int32_t dh_motion_lerp_q_(int32_t pa, int32_t pb, dh_q30 s);

/* ---- fixed point (dh_profile_q.c) ---- */

/* In place: p->d, p->v = vmax, p->a = amax, p->j = jmax (0: the
 * trapezoid) replaced by the time-optimal profile of d within them
 * (dh_profile_trap_q, dh_profile_scurve_q), with their statuses; p holds
 * no profile on error. The initialisers (through a copy) and the joint
 * move (dh_joint_move_q.c, in its output) call it. */
dh_status dh_motion_profile_q_(dh_profile_q *p);

#endif /* DHMATH_SRC_MOTION_IMPL_H */
