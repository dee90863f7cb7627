/* SPDX-License-Identifier: Apache-2.0 */
/*
 * support_robots.h - shipped robot models as double-precision descriptions
 * and an independent double-precision reference forward kinematics.
 *
 * Used by the FK, Jacobian/IK and CLI tests. Nothing here calls the code
 * under test except dhs_build()/dhs_build_q(), which fill a dh_robot through
 * the public API. The references multiply the elementary 4x4 matrices of the
 * DH definitions (Rz, Tz, Tx, Rx) in double with the helpers of
 * support_ref.h (libm sin/cos of radians), so they share no code and no
 * algebraic shortcut with the library.
 *
 * Units: revolute joint values in DEGREES, prismatic ones in the robot's
 * length unit (m for the *_m models, mm for the *_mm models).
 * Matrices are column-major like dh_mat4_f32: m[col][row].
 *
 * The tables are examples/robots/ *.dh (sources and units in their header
 * comments), read at build time by tools/gen_robots.py; panda_mm is panda.dh
 * with lengths times 1000.
 */
#ifndef SUPPORT_ROBOTS_H
#define SUPPORT_ROBOTS_H

#include "dhmath/robot.h"
#include "support_ref.h"

#define DHS_MAX_JOINTS 8

typedef struct {
    dh_joint_type type;
    double a, d, alpha_deg, theta_deg;  /* as in the DH table (theta/d = offset) */
    double qmin, qmax;                  /* deg (R) or length (P) */
} dhs_joint_desc;

typedef struct {
    const char *name;
    dh_convention conv;
    unsigned n;
    double unit_per_m;                  /* 1 for metres, 1000 for millimetres */
    dhs_joint_desc j[DHS_MAX_JOINTS];
    dhr_mat4 base, tool;
} dhs_robot;

/* The shipped models (examples/robots/ *.dh). */
extern const dhs_robot dhs_puma560_m, dhs_puma560_mm;
extern const dhs_robot dhs_ur5_m, dhs_ur5_mm;
extern const dhs_robot dhs_panda_m, dhs_panda_mm;
extern const dhs_robot dhs_ur3_m, dhs_ur3_mm;
extern const dhs_robot dhs_ur10_m, dhs_ur10_mm;
extern const dhs_robot dhs_cobra600_m, dhs_cobra600_mm;
extern const dhs_robot dhs_kuka_kr5_m, dhs_kuka_kr5_mm;
extern const dhs_robot dhs_abb_irb140_m, dhs_abb_irb140_mm;
extern const dhs_robot dhs_stanford_m, dhs_stanford_mm;

/* ---- building a dh_robot from a description (through the public API) ---- */

/** init + add_joint_f32 + set_limits_f32 + set_base_f32/set_tool_f32.
 *  Returns the first non-OK status (DH_ERR_ARG if n > DH_MAX_JOINTS). */
dh_status dhs_build(const dhs_robot *d, dh_robot *r);
/** Integer-only build: init + add_joint_q + set_limits_q + set_base_q/set_tool_q
 *  with the parameters rounded to Q here (round to nearest). */
dh_status dhs_build_q(const dhs_robot *d, dh_robot *r);

/* ---- random joint values ---- */

/** Uniform within the description's limits (no limits: +-180 deg / +-1 unit). */
void dhs_random_q(const dhs_robot *d, double *q);
/** Same, from the limits stored in a dh_robot (float limits). */
void dhs_random_q_robot(const dh_robot *r, double *q);
/** A UR5 configuration away from its singularities, margin deg (0..20)
 *  inside the widest bands: joint 2 in [-140, -40], |joint 3| in
 *  [55, 125] (elbow bent), |joint 5| in [45, 135] (wrist away from 0 and
 *  180), joints 1, 4, 6 in [-170, 170]; q[6..] = 0. */
void dhs_ur5_safe_q(double margin, double *q);

/** Link matrix of one joint (standard or modified convention) at value q. */
void dhs_link(dh_convention conv, dh_joint_type type, double a, double d,
              double alpha_deg, double theta_deg, double q, dhr_mat4 *A);

/* ---- reference forward kinematics ---- */

/**
 * From a description (exact double parameters). frames (may be NULL, else
 * n entries) receives base*A1..A_{i+1}; T (may be NULL) the end frame with
 * the tool.
 */
void dhs_fk_desc(const dhs_robot *d, const double *q, dhr_mat4 *frames, dhr_mat4 *T);
/**
 * From a dh_robot's float parameters as stored (a, d, alpha_deg, theta_deg,
 * base, tool), evaluated in double: the reference for the float path.
 */
void dhs_fk_ref_f32(const dh_robot *r, const double *q, dhr_mat4 *frames, dhr_mat4 *T);
/**
 * From a dh_robot's fixed-point parameters as stored (a_q, d_q, alpha_q,
 * theta_q, base_q, tool_q) and Q joint values (dh_q16 deg for R, dh_qpos for
 * P), evaluated in double: the reference for the fixed path on the same
 * Q-rounded inputs. Lengths come out in the robot's unit (not Q).
 */
void dhs_fk_ref_q(const dh_robot *r, const int32_t *q, dhr_mat4 *frames, dhr_mat4 *T);

/* ---- targets, joint distances, messages ---- */

/** The float target of joint values q (deg / length): the double reference
 *  FK of r's stored float parameters (dhs_fk_ref_f32), rounded to float. */
void dhs_target_f32(const dh_robot *r, const double *q, dh_mat4_f32 *T);
/** |a - b| of joint i: modulo 360 (in [0, 180]) for a revolute joint, plain
 *  for a prismatic one. */
double dhs_joint_dist(const dh_robot *r, uint32_t i, double a, double b);
/** "q1 q2 ..." (%.17g) of n joint values, for failure messages; two
 *  buffers (slot 0 or 1), so that one message can show two vectors. */
const char *dhs_q_str(const double *q, uint32_t n, int slot);
/** dhs_q_str of float joint values. */
const char *dhs_qf_str(const float *q, uint32_t n, int slot);

/** Sum of every length in the chain at q (base and tool offsets, |a|, |d|,
 *  and |q| of prismatic joints), at least 1: the scale of the position
 *  error. */
double dhs_chain_reach(const dhs_robot *d, const double *q);

/* ---- conversions and error measures ---- */

/** Round to nearest Q with `frac` fraction bits (saturating; for test inputs). */
int32_t dhs_to_q(double x, int frac);
/** A double frame -> Q (rotation Q2.30, position DH_QPOS_FRAC fraction
 *  bits), each entry by dhs_to_q; the bottom row is not read. */
void dhs_to_frame_q(const dhr_mat4 *D, dh_frame_q *F);
/** Joint values in deg / length -> Q (dh_q16 for R, dh_qpos for P). */
void dhs_q_from_double(const dh_robot *r, const double *q, int32_t *qq);

/** Rotation angle (rad) of the double 3x3 R (column-major R[col][row]),
 *  robust near 0 and pi: atan2 of the skew part's norm and trace - 1. */
double dhs_rot_angle(double R[3][3]);
/** True errors of float joint values q for a float target: position norm
 *  and rotation angle of R_target R(q)^T, by the double reference FK of
 *  r's stored float parameters (dhs_fk_ref_f32). */
void dhs_true_error_f32(const dh_robot *r, const float *q, const dh_mat4_f32 *target, double *ep, double *er);

/** The twist (deg) that flips a joint axis: 0 <-> 180, a <-> -a otherwise. */
double dhs_mirror_twist(double alpha_deg);
/**
 * 1 when the closed-form solution c (flagged outside the limits) and the
 * in-limit numerical solution qn straddle a limit by no more than the
 * slack: on every joint where c lies outside its limits, c is at most the
 * slack (slack_deg for revolute joints, slack_len for prismatic ones)
 * beyond the limit it crosses and qn at most that inside it.
 */
int dhs_limit_twin_f32(const dh_robot *r, const float *c, const float *qn, double slack_deg, double slack_len);
/** Largest |position difference| (length unit; NaN propagates). */
double dhs_pos_err_f32(const dh_mat4_f32 *T, const dhr_mat4 *R);
/** Largest |rotation entry difference| (3x3 part; NaN propagates). */
double dhs_rot_err_f32(const dh_mat4_f32 *T, const dhr_mat4 *R);
/** Bottom row exactly 0 0 0 1. */
int dhs_bottom_ok_f32(const dh_mat4_f32 *T);
/** Largest |position difference| in length units (Q converted to double). */
double dhs_pos_err_q(const dh_frame_q *F, const dhr_mat4 *R);
/** Largest |rotation entry difference| in units of 1.0 (divide by 2^-30 for LSB). */
double dhs_rot_err_q(const dh_frame_q *F, const dhr_mat4 *R);

#endif /* SUPPORT_ROBOTS_H */
