/* SPDX-License-Identifier: Apache-2.0 */
/*
 * motion_impl.h - PRIVATE helpers of the motion family (src/motion/, not
 * installed): the Cartesian paths (dh_path.c) keep the unit quaternions of
 * their end frames and call the slerp of dh_interp.c directly, without
 * dh_pose_interp_f32's checks and conversions, to stay within the 256 B
 * stack budget; the move executor (dh_move.c) checks a path with the
 * test of dh_path.c; the blends take an arc's rates and a path's points
 * relative to an end from dh_path.c; the jerk bound of an arc (dh_path.c) takes the
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

/* For the arc p (radius > 0) within amax: *V (the speed bound so far)
 * lowered to sqrt(amax R / sqrt 2), *At = amax sqrt(1 - (V^2 / (R amax))^2)
 * the tangential acceleration beside the centripetal one, as
 * dh_path_move_f32 takes them (dh_path.c); the blends' rates (dh_blend.c) */
void dh_motion_arc_rates_f32_(const dh_path_f32 *p, float amax, float *V, float *At);

/* T's position column (rows 0-2) = p(s) less p's end (end 0: p_A,
 * s = x; end 1: p_B, s = 1 - x) for x in [0, 1], an arc from its nearer
 * end (dh_path.c); the superposition of blends (dh_blend.c) */
void dh_motion_path_off_f32_(const dh_path_f32 *p, float x, int end, dh_mat4_f32 *T);

/* The square root (cube == 0) or the cube root (cube == 1) of n / m for
 * finite n >= 0, m > 0 (0 for n == 0), without underflow or overflow of
 * the quotient (dh_profile.c); the jerk bound of an arc (dh_path.c) */
float dh_motion_root_f32_(float n, float m, int cube);

/* The feed override r after a period of the path move mv (dh_move.c):
 * ok 1 when the tracker was OK; up and dn the largest rise and fall of r
 * that keep the target within its limits this period (1: no bound). r
 * moves towards its ceiling (ok) or 0 (not ok) by at most them, and the
 * ceiling and mv->lag are updated (dh_move_advance_f32's rule). The
 * queue's blended lines (dh_queue.c) take it with their own bounds. */
float dh_motion_feed_goal_f32_(dh_move_f32 *mv, float dt, int ok, float up, float dn);

/* The largest rise of r within the acceleration A of s: k = s' / dt > 0,
 * p >= 0 the largest s'' near the clock (dh_move.c) */
float dh_motion_feed_rise_f32_(float k, float p, float A, float r);

/* ---- the queue's blended lines (dh_blend.c, called by dh_queue.c) ---- */

/* The corner of the paths p1 then p2 within lim and radius as the queue
 * blends it (docs/design.md, "Blended corners in the queue"): the
 * overlap tb, b[0] the end tail's |s''| of p1 and b[1] the start tail's
 * of p2 (L1 b1 + L2 b2 <= amax, or a share of it at a corner with an arc,
 * each tail within half its path); 0 (and b 0) when the corner runs at
 * rest: not two paths with motion, p2 not
 * starting at p1's end, radius 0, or a blend not shorter. */
float dh_blend_corner_f32_(const dh_path_f32 *p1, const dh_path_f32 *p2, const dh_cart_limits_f32 *lim, float radius,
                           float b[2]);

/* r = the bounds V of s' and a of s'' of the path p (length or angle
 * > 0, as dh_path_move_f32 accepted it) within lim, as its blended
 * scalings take them (an arc's beside its centripetal acceleration); the
 * queue keeps them in its item when a path move is appended */
void dh_blend_rates_f32_(const dh_path_f32 *p, const dh_cart_limits_f32 *lim, float r[2]);

/* g = the scaling of s over the distance D (s from 1 - D to 1) of a path
 * with the bounds r (dh_blend_rates_f32_), with the tails g->b0, tb0, b1,
 * tb1 as set by the caller (a tail of duration 0 is a rest); 1 when the
 * tails fit the distance, 0 when not (then g is no valid scaling). */
int dh_blend_seg_plan_f32_(dh_blend_seg_f32 *g, const float r[2], float D);

/* s of the scaling g started at s0, at its time t (clamped to [0, T]:
 * s0 before, 1 after when T > 0) */
float dh_blend_seg_s_f32_(const dh_blend_seg_f32 *g, float s0, float t);

/* s' of the scaling g at its time t, and s'' into *sdd (both 0 outside
 * (0, T)) */
float dh_blend_seg_rate_f32_(const dh_blend_seg_f32 *g, float t, float *sdd);

/* T = the superposition of path p1 at s1 and path p2 at s2 (the
 * overlap of dh_blend_eval_f32), s1 and s2 given in T's column 3 (rows 0
 * and 1), in three calls made one after the other (each call's stack
 * apart): dh_blend_pose_rot_f32_ puts the slerps q1(s1) and q2(s2) into
 * T's columns 0 and 1;
 * dh_blend_compose_f32_ (with p2's qa) makes T's rotation
 * q2(s2) q_A2* q1(s1) and bottom row; dh_blend_pose_pos_f32_ its position
 * from x1 = 1 - s1 and x2 = s2: p1's B plus p1(s1) - p1's B plus
 * p2(s2) - p2's A (dh_motion_path_off_f32_). */
void dh_blend_pose_rot_f32_(const dh_path_f32 *p1, const dh_path_f32 *p2, dh_mat4_f32 *T);
void dh_blend_compose_f32_(const dh_quat_f32 *qa2, dh_mat4_f32 *T);
void dh_blend_pose_pos_f32_(const dh_path_f32 *p1, const dh_path_f32 *p2, float x1, float x2, dh_mat4_f32 *T);

/* g = the jerk-limited scaling of s over the distance D (s from 1 - D to
 * 1) of the line p within lim and jk, at rest at both ends (its own
 * bounds of s'' and s''', no overlap): dh_blend_seq_plan_jerk_f32's
 * scaling of a line, which dh_blend_seg_s_f32_ and dh_blend_seg_rate_f32_
 * evaluate (g->j > 0) */
void dh_blend_jline_f32_(dh_blend_seg_f32 *g, const dh_path_f32 *p, const dh_cart_limits_f32 *lim,
                         const dh_cart_jerk_f32 *jk, float D);

/* The corner of the queued jerk-limited lines i1 then i2 (their paths
 * p1, p2; i1's lim, jk and radius) as the queue blends it
 * (docs/design.md, "Jerk-limited blended corners in the queue"):
 * i1->seg p1's scaling as planned (its start as set, its end at rest),
 * i2->seg p2's (dh_blend_jline_f32_, D 1); both planned again with the
 * corner's lowered bounds and overlap, tb returned, or left at rest at
 * the corner (0 returned) when it is not two lines that join, radius is
 * 0, the blend is not shorter, or it would change p1's speed while p1's
 * start is blended. */
float dh_blend_jcorner_f32_(dh_queue_item_f32 *i1, dh_queue_item_f32 *i2);

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

/* ---- fixed point (dh_path_q.c) ---- */

/* 1 when p holds a path (a kind, unit quaternions within a factor 2), 0
 * when not (e.g. all zero): the test of dh_path_eval_q's DH_ERR_ARG; the
 * blended sequences (dh_blend_q.c) check their lines with it */
int dh_motion_path_ok_q_(const dh_path_q *p);

/* out = e (cs, sn k) (Q2.30: e a unit quaternion, cs and sn the cosine
 * and sine of a half angle, k a unit axis; each product rounded once);
 * out must not alias e. A path's slerp from an end quaternion (dh_path_eval_q)
 * and the blended sequences' overlaps (dh_blend_q.c) */
void dh_motion_turn_q_(const dh_quat_q *e, int32_t cs, int32_t sn, const int32_t k[3], dh_quat_q *out);

/* pos = the position of the path p at s (held to [0, 2^30]): a line's
 * dh_motion_lerp_q_, an arc's point (within 4 LSB + 2^-26 R of the
 * circle; its ends exact); dh_path_eval_q's, and the blended corners'
 * overlaps' (dh_blend_q.c) */
void dh_motion_point_q_(const dh_path_q *p, dh_q30 s, dh_qpos pos[3]);

/* The tool's speed bound V (high word) and tangential acceleration At
 * (low word) of a move along p within lim (lim's fields > 0; an arc of
 * radius > 0): vmax and amax on a line, an arc's as dh_path_move_q
 * plans them (V >= 1, At >= 0, each rounded down) */
uint64_t dh_motion_tool_va_q_(const dh_path_q *p, const dh_cart_limits_q *lim);

/* T->r = the rotation of the unit quaternion q (Q2.30, each entry rounded
 * once); T->p untouched */
void dh_motion_quat_rot_q_(const dh_quat_q *q, dh_frame_q *T);

/* ---- fixed point (dh_profile_q.c) ---- */

/* In place: p->d, p->v = vmax, p->a = amax, p->j = jmax (0: the
 * trapezoid) replaced by the time-optimal profile of d within them
 * (dh_profile_trap_q, dh_profile_scurve_q), with their statuses; p holds
 * no profile on error. The initialisers (through a copy) and the joint
 * move (dh_joint_move_q.c, in its output) call it. */
dh_status dh_motion_profile_q_(dh_profile_q *p);

/* ---- fixed point (dh_path_q.c) ---- */

/* The rates of s of a move along p within lim and jk (NULL: the
 * trapezoid) into prof's d = 2^e (0: no motion), v, a and j, for
 * dh_motion_profile_q_ to plan in place (dh_path_move_jerk_q's first
 * step; the executor and the queue call the two steps themselves, so no
 * frame of a path function lies under the planner's: the 256 B guard).
 * DH_ERR_ARG for a limit <= 0 or a p that holds no path, DH_ERR_OVERFLOW
 * for a rate of s beyond int32 at e = 0 or rounding to 0. */
dh_status dh_motion_path_rates_q_(dh_profile_q *prof, const dh_path_q *p, const dh_cart_limits_q *lim,
                                  const dh_cart_jerk_q *jk);
/* e of a profile of d = 2^e from dh_motion_path_rates_q_ (30 for d = 0) */
uint32_t dh_motion_path_e_q_(const dh_profile_q *prof);

/* ---- fixed point (dh_move_q.c) ---- */

/* mv's clock, its fraction, feed override and ceiling at the start of a
 * move of duration dur (dh_move_q.c; the fixed queue starts its moves so) */
void dh_motion_start_q_(dh_move_q *mv, uint32_t dur);

/* The largest rise (rise 1) or fall (rise 0), Q2.30, of the time warp r
 * of the profile pr (a trapezoid or a seven-phase profile; r that of the last period, dt its
 * length in us) at clock this period that keeps the commanded
 * acceleration within A (dh_move_q.c); 2^30 where s' is 0 */
int32_t dh_motion_feed_bound_q_(const dh_profile_q *pr, int32_t A, uint32_t clock, dh_q30 r, uint32_t dt, int rise);

#endif /* DHMATH_SRC_MOTION_IMPL_H */
