/* SPDX-License-Identifier: Apache-2.0 */
/*
 * blend_q_impl.h - PRIVATE planning and evaluation of the fixed-point
 * blended corners (dh_blend_q.c; src/motion/, not installed), shared by
 * the blended sequence (dh_blend_seq_plan_q, dh_blend_seq_eval_q) and
 * any other user of one corner or one line at a time, so that each
 * bound is planned by one body (method: docs/design.md, "Blended
 * corners, fixed point").
 */
#ifndef DHMATH_SRC_BLEND_Q_IMPL_H
#define DHMATH_SRC_BLEND_Q_IMPL_H

#include "dhmath/motion.h"

/* The overlap tb (us) of the corner between the lines p1 and p2 (p2->A
 * equal to p1->B, both holding paths, lines or arcs of radius > 0,
 * lengths and angles >= 0; lim's fields > 0; their rates in g[0] and
 * g[1] from dh_blend_rates_q_, called by the caller: one call level
 * less, the 256 B guard; left as they are) within the radius R >= 0
 * that g[0].dev holds on the call (a field, not an argument: the 256 B
 * guard): each tail at b = (63/128) a of its line ((7/16) a of an arc),
 * tb the least of the bounds of the file comment of dh_blend_q.c (four,
 * and one per arc), 0 (at rest) when R is 0, a line has no motion, the
 * corner lies within R + 64 LSB of the int32 range or the blend does not
 * shorten the pair, into g[0].dur[4] and g[1].dur[0]; and
 * g[0].dev = (L1 b1 + 2 L2 b2) tb^2 / 2 rounded up (<= R; 0 for tb 0):
 * the bound on the tool point's distance from the corner in the overlap,
 * also for a brake of each line at its tail's acceleration. Nothing else
 * of g[0] and g[1] is written. */
void dh_blend_corner_q_(const dh_path_q *p1, const dh_path_q *p2, const dh_cart_limits_q *lim, dh_blend_seg_q *g);

/* The rates of s along the line or arc p within lim (lim's fields > 0),
 * V = min(Vt / L, wmax / th) and a = min(At / L, wdmax / th), both
 * lowered by 2^-10 (Vt, At: vmax, amax on a line, an arc's of
 * dh_path_move_q), and its tails' accelerations (63/128) a on a line,
 * (7/16) a on an arc, into g's planning state (fields of g that
 * dh_blend_line_q_ writes last); all 0 when p has no length and no
 * angle. */
void dh_blend_rates_q_(const dh_path_q *p, const dh_cart_limits_q *lim, dh_blend_seg_q *g);

/* g = the five-phase scaling of s from 0 to 1 along the line whose rates
 * dh_blend_rates_q_ put into g, with the tails' durations the caller set
 * in g->dur[0] (start) and g->dur[4] (end; each an overlap of
 * dh_blend_corner_q_ for this line, or 0 for rest): 1 when the tails fit
 * and every phase is below 2^28 us (g->T their sum), 0 when not (g holds
 * no scaling then). g->t0 and g->dev are not written. */
int dh_blend_line_q_(dh_blend_seg_q *g);

/* A line of the fixed queue (dh_queue_q.c): g = its scaling as
 * dh_blend_rates_q_ and dh_blend_line_q_ make it (the tails' durations
 * set in g->dur[0] and g->dur[4] by the caller; the same status, and 0
 * when Z's duration below reaches 2^30 us), and Z = a trapezoid that
 * bounds it for the queue's time warp (dh_motion_feed_bound_q_), never
 * evaluated (d 0): v >= s' and a >= |s''| of every phase (the rates V and
 * a times 1 + 2^-11, rounded up, in units of 2^-k of s; the held phases
 * keep within 2^-13 of them), with t1 = dur[0] + dur[1] and
 * t2 = t1 + dur[2]: Z's s'' is +a before t1 or later (the start tail's b
 * and the acceleration phase), -a after t2 or earlier (the deceleration
 * and the end tail), its duration at least t1 + t2 and where the held
 * deceleration would reach rest (so s' <= a (u + 1 us) within Z's phase
 * time of its ends, u the time to the nearer one, holds for the line up
 * to its end tail). So over a window that does not reach into a tail,
 * Z's s'' at its start bounds the line's from above where positive, at
 * its end from below where negative: the bound's hi and lo hold. */
int dh_blend_queue_line_q_(dh_blend_seg_q *g, const dh_path_q *p, const dh_cart_limits_q *lim, dh_profile_q *Z);

/* s (Q2.30) of the scaling g at its time t (us; t >= g->T: 1), held to
 * [0, 1]; g must hold a scaling (durations summing to g->T) */
dh_q30 dh_blend_s_q_(const dh_blend_seg_q *g, uint32_t t);

/* T->r = the overlap's rotation R2(s2) R_A2^T R1(s1) of the paths p1, p2
 * (p2->A equal to p1->B) at s1, s2 (Q2.30); T->p untouched */
void dh_blend_rot_q_(const dh_path_q *p1, const dh_path_q *p2, dh_q30 s1, dh_q30 s2, dh_frame_q *T);

/* The overlap's position p1(s1) + (p2(s2) - p2->A) from p1(s1) in T->p
 * and p2(s2) in T->r[0] (dh_motion_point_q_, called by the caller: one
 * call level less, the 256 B guard; T->r is written after, by
 * dh_blend_rot_q_), into T->p saturated to int32: 1 when it was (a
 * corner that dh_blend_corner_q_ blends keeps its overlap inside the
 * range, so only paths or scalings changed after planning can) */
int dh_blend_pos_q_(const dh_path_q *p2, dh_frame_q *T);

#endif /* DHMATH_SRC_BLEND_Q_IMPL_H */
