/* SPDX-License-Identifier: Apache-2.0 */
/*
 * support_motion_q.h - shared helpers of the fixed-point motion tests
 * (support_motion_q.c).
 */
#ifndef SUPPORT_MOTION_Q_H
#define SUPPORT_MOTION_Q_H

#include "support_robots.h"
#include "dhmath/ikc.h"
#include "dhmath/motion.h"

#define DHSM_QPOS ((double)((int32_t)1 << DH_QPOS_FRAC))
#define DHSM_Q16 65536.0
#define DHSM_Q30 1073741824.0
/* Length unit per mm: 1, or 2^(16 - DH_QPOS_FRAC) in a finer format, whose
 * range (ikc.h: 2^(30 - DH_QPOS_FRAC) units for the closed form) does not
 * hold the robots in mm: the robots and paths then have the same lengths
 * in LSB as at DH_QPOS_FRAC 16. */
#define DHSM_LS (DH_QPOS_FRAC > 16 ? ldexp(1.0, 16 - DH_QPOS_FRAC) : 1.0)

/* a robot (in units of LS mm), its fixed build and closed-form model */
typedef struct {
    const dhs_robot *d;
    dh_robot r;
    dh_ikc_model_q m;
} dhsm_rig;

/* g = d scaled to LS mm, built in fixed point, every joint's rates vdeg
 * deg/s and adeg deg/s^2, its closed-form model */
void dhsm_rig_make(dhsm_rig *g, const dhs_robot *d, double vdeg, double adeg);
/* the tool point p (LSB / QPOS) and frame T of q, double reference FK */
void dhsm_tool_mm(const dhsm_rig *g, const int32_t *q, double *p, dhr_mat4 *T);
/* the fixed frame of the reference FK of q */
void dhsm_target_of(const dhsm_rig *g, const int32_t *q, dh_frame_q *T);
double dhsm_dot3(const double *a, const double *b);
double dhsm_dist3(const double *a, const double *b);

/* double reference of a path in mm: the segment pa pb, or the circle
 * (centre c, normal n, radius R) through pa, via, pb */
typedef struct {
    double pa[3], pb[3], c[3], n[3], R;
    int arc;
} dhsm_ref;

/* the reference of p (its ends), an arc through via (NULL: a line) */
void dhsm_ref_make(dhsm_ref *rp, const dh_path_q *p, const dh_qpos *via);
/* distance (mm) of p from the reference path */
double dhsm_ref_dist(const dhsm_ref *rp, const double *p);
/* rotation angle (rad) between the rotations of two fixed frames */
double dhsm_rot_between(const dh_frame_q *F, const dh_frame_q *G);

/* a configuration of the robot's region, away from its singularities:
 * the UR5's dhs_ur5_safe_q(15), the Puma within 10 degrees of
 * (10, -30, 45, 20, 35, -60) (seeded) */
void dhsm_region_q(const dhsm_rig *g, double *q);
/* 1 when every point of p at 16 samples has a closed-form solution */
int dhsm_path_reachable(const dhsm_rig *g, const dh_path_q *p, const int32_t *qref);

#endif /* SUPPORT_MOTION_Q_H */
