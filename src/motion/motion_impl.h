/* SPDX-License-Identifier: Apache-2.0 */
/*
 * motion_impl.h - PRIVATE slerp steps of the motion family (src/motion/,
 * not installed): the Cartesian paths (dh_path.c) keep the unit
 * quaternions of their end frames and call the slerp of dh_interp.c
 * directly, without dh_pose_interp_f32's checks and conversions, to stay
 * within the 256 B stack budget.
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

#endif /* DHMATH_SRC_MOTION_IMPL_H */
