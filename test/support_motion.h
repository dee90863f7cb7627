/* SPDX-License-Identifier: Apache-2.0 */
/*
 * support_motion.h - shared helpers of the float queue tests
 * (support_motion.c): the double distances of a target from a line or an
 * arc, rotations of sampled targets, and the finite-difference checks of
 * speed and acceleration against Cartesian limits.
 */
#ifndef SUPPORT_MOTION_H
#define SUPPORT_MOTION_H

#include <stddef.h>
#include <stdint.h>

#include "support_robots.h"
#include "dhmath/ikc.h"
#include "dhmath/motion.h"
#include "dhmath/track.h"

#define DHM_REL 1e-3       /* relative tolerance of a finite difference against its limit */
#define DHM_ANG_NOISE 1e-4 /* degrees: rounding of a sampled rotation */
#define DHM_RAD2DEG 57.29577951308232

/* The seeded queue tests' Cartesian limits (metres, degrees), drawn in
 * this order: vmax, amax, wmax, wdmax, then with jk jmax and wjmax. */
void dhm_draw_limits(dh_cart_limits_f32 *lim, dh_cart_jerk_f32 *jk);

double dhm_dist3(const double a[3], const double b[3]);
/* distance of x from the segment a b */
double dhm_seg_dist(const float a[3], const float b[3], const double x[3]);
/* distance of x from the arc p (dh_path_arc_f32: the circle of centre
 * p_A - u0, radius |u0|, in the plane of normal n, within its sweep; beyond
 * the sweep the distance from the nearer end) */
double dhm_arc_dist(const dh_path_f32 *p, const double x[3]);
/* unit quaternion (w, x, y, z) of T's rotation, in double (Shepperd) */
void dhm_quat_of(const dh_mat4_f32 *T, double q[4]);
/* v = the rotation vector (degrees) of Rb Ra^T, from quaternions */
void dhm_rotvec(const float *qa, const float *qb, double v[3]);
/* a segment from a to b drawn: 0 for a line (half the segments, and every
 * chord shorter than 1 cm), 1 for an arc whose via point (into via) is
 * off the chord's middle by 0.1 to 0.4 of the chord, in a random
 * direction across it */
int dhm_draw_via(const float a[3], const float b[3], float via[3]);
/* q = qp with each of r's joints moved by a uniform draw in [-step, step]
 * (degrees), held 5 degrees inside its limits */
void dhm_draw_q(const dh_robot *r, const float *qp, double step, float *q);
/* rows 0..n-2 of h moved to rows 1..n-1 (row 0 then free for the newest) */
void dhm_push(float (*h)[7], int n);
/* a sample: T's position and quaternion into h[7] */
void dhm_sample(const dh_mat4_f32 *T, float h[7]);
/* the speed (linear, angular) between the samples h0 and h1, hdt apart,
 * within lim times 1 + DHM_REL (plus 4 ulp of the positions' scale and
 * DHM_ANG_NOISE); call names the period in a failure */
void dhm_check_speed(const float *h0, const float *h1, double hdt, const dh_cart_limits_f32 *lim, double ulp,
                     long call);
/* the acceleration (linear, angular) of the samples h[0], h[w], h[2 w]
 * over (w dt = hdt)^2 within lim likewise (h: rows of 7) */
void dhm_check_acc(const float (*h)[7], int w, double hdt, const dh_cart_limits_f32 *lim, double ulp, long call);

/* The third differences of the samples h[0], h[w], h[2 w], h[3 w]
 * (hdt = w periods): TOTAL jerk and angular jerk within jk times
 * 1 + DHM_REL (plus 8 ulp of the positions' scale and 8 DHM_ANG_NOISE);
 * worst[0], worst[1] raised to the ratios to the limits seen (linear,
 * angular) */
/* a line from (0.2, 0, 0) to (0.4, 0.2, 0), identity rotation, and an
 * arc between the same ends through (0.3, 0.1, 0.2): the paths of the
 * queue tests' status checks */
void dhm_line_arc(dh_path_f32 *line, dh_path_f32 *arc);
/* the queued line k that qu runs (its seq, at most n - 1) and the tool's
 * position x (T's column 3); in an overlap of blended lines (bmode 2)
 * checks that line k + 1 exists and x lies within radius[k] (plus 1e-6
 * and 8 ulp of the scale S) of the corner cp[k + 1] and returns 1, else
 * returns 0 (the caller checks x against line k, cp[k] to cp[k + 1]) */
int dhm_check_corner(const dh_queue_f32 *qu, const dh_mat4_f32 *T, uint32_t n, const float (*cp)[3],
                     const float *radius, double S, long call, uint32_t *k, double x[3]);
void dhm_check_jerk(const float (*h)[7], int w, double hdt, const dh_cart_jerk_f32 *jk, double ulp, long call,
                    double worst[2]);

/* The finite-difference checks of a stream of targets, one per period
 * dt: the caller's sample rows sp (ns = 2 ws + 1, every period) and lp
 * (nl >= 2 w / wd + 1, every wd periods), nh the samples so far (0 to
 * start) */
typedef struct {
    float (*sp)[7];
    float (*lp)[7];
    int ns, nl, ws, wd, w;
    double dt;
    long nh;
} dhm_fd;
/* T sampled into f: its step, the speed and acceleration over ws periods
 * every period and over w periods every wd (dhm_check_speed,
 * dhm_check_acc); 1 when lp[0] is a new sample (lp[k] then k wd periods
 * before it, for the first nh / wd + 1 rows) */
int dhm_fd_push(dhm_fd *f, const dh_mat4_f32 *T, const dh_cart_limits_f32 *lim, double ulp, long call);

/* FNV-1a hash of the na bytes at a, then the nb bytes at b */
uint64_t dhm_hash(const void *a, size_t na, const void *b, size_t nb);

/* a robot of the queue tests, a configuration about which its paths are
 * drawn, and whether its tracker runs the closed form */
typedef struct {
    const dhs_robot *d;
    double q[DH_MAX_JOINTS];
    int closed;
} dhm_robot_case;

extern const dhm_robot_case dhm_puma560, dhm_ur5, dhm_panda;

/* a robot built from its table, its closed-form model and tracker */
typedef struct {
    dh_robot r;
    dh_ikc_model_f32 m;
    dh_track_f32 t;
    int closed;
} dhm_rig;

/* g = c's robot, every joint at 180 deg/s and 3000 deg/s^2, its
 * closed-form model when c->closed */
void dhm_rig_make(dhm_rig *g, const dhm_robot_case *c);

#endif
