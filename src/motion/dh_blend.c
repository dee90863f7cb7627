/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_blend.c - two path moves (lines or arcs) blended at their corner by
 * superposition.
 *
 * Each move scales s from 0 to 1 with a trapezoid of s' <= V and
 * |s''| <= a (the bounds of dh_path_move_f32 on a line: V = min(vmax / L,
 * wmax / angle), a = min(amax / L, wdmax / angle)), except that its last
 * tb (first move) or first tb (second move) runs at a reduced
 * acceleration b <= a: the tail, from the speed u = b tb to rest over
 * e = b tb^2 / 2. The second move is the time mirror of such a profile
 * (its tail at its start). The tails overlap: on [t0, t0 + tb],
 * t0 = T1 - tb, the position is p1(s1) + (p2(s2) - p_A2) (on lines
 * p1(s1) + s2 (p_B2 - p_A2)) and the rotation q2(s2) q_A2* q1(s1), i.e.
 * Exp(s2 w2) R1(s1) with w2 the second path's fixed world rotation
 * vector.
 *
 * The tails' accelerations (blend_share): L_i b_i <= c = amax /
 * max(1, |d2 - d1|); in the overlap the tool point's acceleration is the
 * constant L2 b2 d2 - L1 b1 d1, whose norm is convex in (L1 b1, L2 b2)
 * and so at most its largest value at a corner of [0, c]^2: c or
 * c |d2 - d1|, both <= amax. Then th1 b1 + th2 b2 <= (63/64) wdmax.
 * At a corner with an arc (radius rho) the tangents turn and the arc adds
 * its centripetal acceleration (L s')^2 / rho: the tails share amax,
 * L1 b1 + L2 b2 <= sh amax (any directions) and each arc's tail speed
 * L b tb <= sqrt((1 - sh) amax rho), so the sum is within amax; of the
 * shares sh = 1/2, 3/4, 15/16 the planner keeps the one with the largest
 * lower bound tb (b1 / a1 + b2 / a2 - 1) of the time saved
 * (blend_arc_overlap). An arc's V and a are dh_path_move_f32's (speed and
 * tangential acceleration beside its own centripetal acceleration).
 *
 * tb = (1 - 2^-10) min(V_i / b_i, sqrt(2 / (b_i (1 + b_i / a_i))),
 * sqrt(2 R / (L1 b1 + L2 b2)), sqrt((180/pi) wdmax / (16 th1 b1 th2 b2)))
 * (terms with a zero denominator left out), so that (docs/design.md,
 * "Blended corners"): u_i <= V_i (the tail starts below the cruise speed),
 * the tail fits the move (u^2 / (2 a) + e <= 1), the tool point stays
 * within R of the corner (L1 e1 + L2 e2 <= R: a chord is at most its
 * arc), and the cross term
 * |w1| |w2| (pi/180) <= (pi/180) th1 b1 th2 b2 tb^2 / 4 <= wdmax / 64 of
 * the angular acceleration of the composed rotation. In the overlap the
 * speeds are linear in time, one falling to 0 and one rising from 0, so
 * their sum is at most the larger end value L_i u_i <= vmax
 * (th_i u_i <= wmax). When the pair so planned is not shorter than the
 * two rest-to-rest trapezoids back to back (tails much gentler than a),
 * tb is 0 and the moves run back to back.
 */
#include <float.h>
#include <math.h>

#include "dhmath/motion.h"
#include "dhmath/mat4.h"
#include "../internal/dh_floatops.h"
#include "motion_impl.h"

#define BLEND_RAD2DEG 57.295779513082321f
#define BLEND_MARGIN 0.9990234375f    /* 1 - 2^-10: the rounding of the bounds */
#define BLEND_WSHARE 0.984375f        /* 63/64 of wdmax for the tails, 1/64 for the cross term */

/* The limits and a radius: DH_ERR_NAN for a NaN/Inf one, then
 * DH_ERR_ARG for a limit <= 0 */
static dh_status blend_check_lim(const dh_cart_limits_f32 *lim, float radius)
{
    const float x[5] = { lim->vmax, lim->amax, lim->wmax, lim->wdmax, radius };
    int i;
    for (i = 0; i < 5; i++) {
        if (!dh_isfinite_f32(x[i])) return DH_ERR_NAN;
    }
    for (i = 0; i < 4; i++) {
        if (!(x[i] > 0.0f)) return DH_ERR_ARG;
    }
    return DH_OK;
}

/* 1 when p holds a line or an arc */
static int blend_is_path(const dh_path_f32 *p)
{
    return dh_motion_path_ok_f32_(p) && (p->kind == (uint32_t)DH_PATH_LINE || p->kind == (uint32_t)DH_PATH_ARC);
}

/* 1 when p is an arc of radius > 0 (its tool point has a centripetal
 * acceleration) */
static int blend_is_arc(const dh_path_f32 *p)
{
    return p->kind == (uint32_t)DH_PATH_ARC && p->radius > 0.0f;
}

/* 1 when p2->A equals p1->B within DH_ROT_TOL (positions relative to
 * max(1, |p1->B's position|)) */
static int blend_joins(const dh_path_f32 *p1, const dh_path_f32 *p2)
{
    float sc = 1.0f, d;
    int i, j;
    for (i = 0; i < 3; i++) {
        if (fabsf(DH_M4(&p1->B, i, 3)) > sc) sc = fabsf(DH_M4(&p1->B, i, 3));
    }
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 4; j++) {
            d = fabsf(DH_M4(&p1->B, i, j) - DH_M4(&p2->A, i, j));
            if (!(d <= DH_ROT_TOL * ((j == 3) ? sc : 1.0f))) return 0;
        }
    }
    return 1;
}

/* The checks of dh_blend_plan_f32's arguments, in the order of its
 * statuses */
static dh_status blend_check(const dh_path_f32 *p1, const dh_path_f32 *p2, const dh_cart_limits_f32 *lim,
                             float radius)
{
    dh_status st = blend_check_lim(lim, radius);
    if (st != DH_OK) return st;
    if (radius < 0.0f || !blend_is_path(p1) || !blend_is_path(p2) || !blend_joins(p1, p2)) return DH_ERR_ARG;
    return DH_OK;
}

/* The bounds r[0] = V, r[1] = a of s for the path p within lim (those
 * of dh_path_move_f32: on an arc V and a leave room for its centripetal
 * acceleration), and r[2] = a (lowered by blend_share); all 0 when p has
 * no length and no angle: no motion */
static dh_status blend_rates(const dh_path_f32 *p, const dh_cart_limits_f32 *lim, float r[3])
{
    float V = lim->vmax, A = lim->amax;
    dh_status st;
    r[0] = 0.0f;
    r[1] = 0.0f;
    if (blend_is_arc(p)) dh_motion_arc_rates_f32_(p, lim->amax, &V, &A);
    st = dh_motion_bound_f32_(&r[0], V, p->length);
    if (st == DH_OK) st = dh_motion_bound_f32_(&r[0], lim->wmax, p->angle);
    if (st == DH_OK) st = dh_motion_bound_f32_(&r[1], A, p->length);
    if (st == DH_OK) st = dh_motion_bound_f32_(&r[1], lim->wdmax, p->angle);
    if (st == DH_OK && (p->length > 0.0f || p->angle > 0.0f) && (!(r[0] > 0.0f) || !(r[1] > 0.0f))) {
        st = DH_ERR_OVERFLOW;
    }
    r[2] = r[1];
    return st;
}



/* |d2 - d1| of the unit directions of two lines of length > 0 */
DH_INLINE float blend_turn(const dh_path_f32 *p1, const dh_path_f32 *p2)
{
    float d, g = 0.0f;
    int i;
    for (i = 0; i < 3; i++) {
        d = (DH_M4(&p2->B, i, 3) - DH_M4(&p2->A, i, 3)) / p2->length -
            (DH_M4(&p1->B, i, 3) - DH_M4(&p1->A, i, 3)) / p1->length;
        g += d * d;
    }
    return dh_sqrtf_(g);
}

/* *b1, *b2 (tail accelerations of s) scaled together so that
 * L1 b1 + L2 b2 <= c (c > 0; c 0: no such bound) and
 * th1 b1 + th2 b2 <= (63/64) wd (the cross term of the rotations gets the
 * last 1/64 through tb) */
DH_INLINE void blend_scale(const dh_path_f32 *p1, const dh_path_f32 *p2, float *b1, float *b2, float c, float wd)
{
    float x = p1->length * *b1 + p2->length * *b2;
    if (c > 0.0f && x > c) {
        x = c / x;
        *b1 *= x;
        *b2 *= x;
    }
    x = p1->angle * *b1 + p2->angle * *b2;
    if (x > BLEND_WSHARE * wd) {
        x = (BLEND_WSHARE * wd) / x;
        *b1 *= x;
        *b2 *= x;
    }
}

/* The tails' accelerations r1[2], r2[2] of s at a corner of two lines:
 * L_i b_i <= c = amax / max(1, |d2 - d1|) (so |L2 b2 d2 - L1 b1 d1| <=
 * amax), or with sum 1 L1 b1 + L2 b2 <= amax (the queue's: any signs of
 * the two), then blend_scale's angular rule. At a corner with an arc
 * they stay a (blend_overlap shares amax). */
static DH_NOINLINE void blend_share(const dh_path_f32 *p1, const dh_path_f32 *p2, float r1[3], float r2[3],
                                    const dh_cart_limits_f32 *lim, int sum)
{
    float c = lim->amax * BLEND_MARGIN, g;
    if (blend_is_arc(p1) || blend_is_arc(p2)) return;
    if (sum == 0 && p1->length > 0.0f && p2->length > 0.0f) {
        g = blend_turn(p1, p2);
        if (g > 1.0f) c /= g;
        if (p1->length * r1[2] > c) r1[2] = c / p1->length;
        if (p2->length * r2[2] > c) r2[2] = c / p2->length;
    }
    /* a move without length: its tail adds no linear acceleration */
    blend_scale(p1, p2, &r1[2], &r2[2], (sum != 0) ? c : 0.0f, lim->wdmax);
}

/* *m = min(*m, sqrt(n / d)) for d > 0 */
DH_INLINE void blend_min_sqrt(float *m, float n, float d)
{
    float r;
    if (!(d > 0.0f)) return;
    r = dh_sqrtf_(n / d);
    if (r < *m) *m = r;
}

/* *m = min(*m, sqrt(ac rho) / (L b)) for an arc p (length L, radius
 * rho) with the tail acceleration b: the tail's speed L b tb at most
 * gives the centripetal acceleration (L b tb)^2 / rho <= ac */
DH_INLINE void blend_arc_tb(float *m, const dh_path_f32 *p, float b, float ac)
{
    const float d = p->length * b;
    if (blend_is_arc(p) && d > 0.0f) blend_min_sqrt(m, ac * (p->radius / d), d);
}

/* The overlap tb of the paths p1, p2 with the rates r1, r2 (each V, a)
 * and the tails b1, b2 within lim and radius, each tail within fit / 2
 * of its path's s (fit 2: the whole path, 1: half of it), the radius held
 * by (L1 b1 + w L2 b2) tb^2 / 2 (w 1; the queue's 2: the second path may
 * brake to twice its s), an arc's centripetal acceleration in its tail
 * within ac (blend_arc_tb); 0 when not positive and finite */
DH_INLINE float blend_tb(const dh_path_f32 *p1, const dh_path_f32 *p2, const float r1[3], const float r2[3],
                         float b1, float b2, const dh_cart_limits_f32 *lim, float radius, float fit, float w, float ac)
{
    float tb = r1[0] / b1;
    if (r2[0] / b2 < tb) tb = r2[0] / b2;
    blend_min_sqrt(&tb, fit, b1 * (1.0f + b1 / r1[1]));
    blend_min_sqrt(&tb, fit, b2 * (1.0f + b2 / r2[1]));
    blend_min_sqrt(&tb, 2.0f * radius, p1->length * b1 + w * (p2->length * b2));
    blend_min_sqrt(&tb, BLEND_RAD2DEG * 0.0625f * lim->wdmax, (p1->angle * b1) * (p2->angle * b2));
    blend_arc_tb(&tb, p1, b1, ac);
    blend_arc_tb(&tb, p2, b2, ac);
    tb *= BLEND_MARGIN;
    return (tb > 0.0f && dh_isfinite_f32(tb)) ? tb : 0.0f;
}

/* The overlap tb of the lines p1, p2 with the rates r1, r2 (each V, a,
 * b; blend_share's b) within lim and radius (blend_tb's fit and w); 0
 * when a move has no motion or radius is 0 */
static DH_NOINLINE float blend_overlap(const dh_path_f32 *p1, const dh_path_f32 *p2, const float r1[3],
                                       const float r2[3], const dh_cart_limits_f32 *lim, float radius, float fit,
                                       float w)
{
    if (!(r1[2] > 0.0f) || !(r2[2] > 0.0f) || !(radius > 0.0f)) return 0.0f;
    return blend_tb(p1, p2, r1, r2, r1[2], r2[2], lim, radius, fit, w, 0.0f);
}

/* blend_overlap at a corner with an arc, the tails r1[2], r2[2] set
 * here: from a, for each share sh of blend_arc_sh within sh amax by
 * blend_scale, the one whose lower bound of the time saved,
 * tb (b1 / a1 + b2 / a2 - 1) (a tail at b costs at most
 * u (1 / b - 1 / a) = tb (1 - b / a), docs/design.md), is the largest
 * (b 0 when no share gives an overlap) */
static DH_NOINLINE float blend_arc_overlap(const dh_path_f32 *p1, const dh_path_f32 *p2, float r1[3], float r2[3],
                                           const dh_cart_limits_f32 *lim, float radius, float fit, float w)
{
    /* the shares sh of amax: the tails' tangential accelerations within
     * sh amax (L1 b1 + L2 b2), the arcs' centripetal ones within
     * (1 - sh) amax */
    static const float blend_arc_sh[3] = { 0.5f, 0.75f, 0.9375f };
    float b[2], tb, x, best = 0.0f, tbest = 0.0f;
    int i;
    r1[2] = 0.0f;
    r2[2] = 0.0f;
    for (i = 0; i < 3 && radius > 0.0f && r1[1] > 0.0f && r2[1] > 0.0f; i++) {
        b[0] = r1[1];
        b[1] = r2[1];
        blend_scale(p1, p2, &b[0], &b[1], blend_arc_sh[i] * (lim->amax * BLEND_MARGIN), lim->wdmax);
        tb = blend_tb(p1, p2, r1, r2, b[0], b[1], lim, radius, fit, w, (1.0f - blend_arc_sh[i]) * lim->amax);
        x = tb * (b[0] / r1[1] + b[1] / r2[1] - 1.0f);
        if (tb > 0.0f && (!(tbest > 0.0f) || x > best)) {
            best = x;
            tbest = tb;
            r1[2] = b[0];
            r2[2] = b[1];
        }
    }
    return tbest;
}

/* the overlap of the corner p1 | p2: blend_overlap, or blend_arc_overlap
 * at a corner with an arc (each called from the caller's frame) */
DH_INLINE float blend_corner_tb(const dh_path_f32 *p1, const dh_path_f32 *p2, float r1[3], float r2[3],
                                const dh_cart_limits_f32 *lim, float radius, float fit, float w)
{
    if (blend_is_arc(p1) || blend_is_arc(p2)) return blend_arc_overlap(p1, p2, r1, r2, lim, radius, fit, w);
    return blend_overlap(p1, p2, r1, r2, lim, radius, fit, w);
}

/* The peak v (*vo), cruise time (*tvo) and duration of one move with
 * the rates r (V, a, b; a > 0) and its tail of duration tb */
static DH_NOINLINE float blend_T(const float r[3], float tb, float *vo, float *tvo)
{
    const float V = r[0], a = r[1];
    const float u = r[2] * tb, e = 0.5f * u * tb;
    const float x = (V * V - 0.5f * u * u) / a + e; /* s covered when cruising at V for no time */
    float v, tv;
    if (x >= 1.0f) {
        v = dh_sqrtf_(a * (1.0f - e) + 0.5f * u * u);
        if (v < u) v = u;
        if (v > V) v = V;
        tv = 0.0f;
    } else {
        v = V;
        tv = (1.0f - x) / V;
    }
    *vo = v;
    *tvo = tv;
    return v / a + tv + (v - u) / a + tb;
}

/* the duration the tails of r1, r2 (each V, a, b; a > 0) and the
 * overlap tb add to the two rest-to-rest scalings, less tb (+Inf when
 * not finite): < 0 when the pair so planned is shorter */
static DH_NOINLINE float blend_gain(const float r1[3], const float r2[3], float tb)
{
    float v, tv, g;
    g = blend_T(r1, tb, &v, &tv) - blend_T(r1, 0.0f, &v, &tv);
    g += blend_T(r2, tb, &v, &tv) - blend_T(r2, 0.0f, &v, &tv);
    g -= tb;
    return dh_isfinite_f32(g) ? g : INFINITY;
}

/* m = the scaling of one move with the rates r (V, a, b; all 0: no
 * motion, m all zero) and its tail of duration tb. DH_ERR_OVERFLOW when a
 * time or a rate is not finite. */
static DH_NOINLINE dh_status blend_prof(dh_blend_prof_f32 *m, const float r[3], float tb)
{
    const float a = r[1];
    float v, tv;
    m->v = 0.0f;
    m->a = 0.0f;
    m->b = 0.0f;
    m->u = 0.0f;
    m->e = 0.0f;
    m->t1 = 0.0f;
    m->tv = 0.0f;
    m->t3 = 0.0f;
    m->tb = 0.0f;
    m->T = 0.0f;
    if (!(a > 0.0f)) return DH_OK;
    m->T = blend_T(r, tb, &v, &tv);
    m->v = v;
    m->a = a;
    m->b = r[2];
    m->u = r[2] * tb;
    m->e = 0.5f * m->u * tb;
    m->t1 = v / a;
    m->tv = tv;
    m->t3 = (v - m->u) / a;
    m->tb = tb;
    return (dh_isfinite_f32(m->T) && m->T > 0.0f && dh_isfinite_f32(v * v)) ? DH_OK : DH_ERR_OVERFLOW;
}

/* *T = the duration of the scaling of one move with the rates r and the
 * overlap tb (blend_prof's status, without its scaling) */
static DH_NOINLINE dh_status blend_dur(const float r[3], float tb, float *T)
{
    float v = 0.0f, tv = 0.0f;
    *T = 0.0f;
    if (!(r[1] > 0.0f)) return DH_OK;
    *T = blend_T(r, tb, &v, &tv);
    return (dh_isfinite_f32(*T) && *T > 0.0f && dh_isfinite_f32(v * v)) ? DH_OK : DH_ERR_OVERFLOW;
}

dh_status dh_blend_plan_f32(dh_blend_f32 *bl, const dh_path_f32 *p1, const dh_path_f32 *p2,
                            const dh_cart_limits_f32 *lim, float radius)
{
    float r1[3], r2[3], tb, T1, T2, U1, U2;
    dh_status st;
    DH_ASSERT(bl != NULL && p1 != NULL && p2 != NULL && lim != NULL);
    st = blend_check(p1, p2, lim, radius);
    if (st == DH_OK) st = blend_rates(p1, lim, r1);
    if (st == DH_OK) st = blend_rates(p2, lim, r2);
    /* the rest-to-rest pair, then the blend when it is shorter */
    if (st == DH_OK) st = blend_dur(r1, 0.0f, &T1);
    if (st == DH_OK) st = blend_dur(r2, 0.0f, &T2);
    if (st != DH_OK) return st;
    blend_share(p1, p2, r1, r2, lim, 0);
    tb = blend_corner_tb(p1, p2, r1, r2, lim, radius, 2.0f, 1.0f);
    if (tb > 0.0f && (blend_dur(r1, tb, &U1) != DH_OK || blend_dur(r2, tb, &U2) != DH_OK ||
                      !((U1 - tb) + U2 < T1 + T2))) {
        tb = 0.0f;
    }
    /* as planned above: no error */
    (void)blend_prof(&bl->m1, r1, tb);
    (void)blend_prof(&bl->m2, r2, tb);
    bl->p1 = *p1;
    bl->p2 = *p2;
    bl->tb = tb;
    bl->t0 = bl->m1.T - tb;
    bl->T = bl->t0 + bl->m2.T;
    bl->dev = 0.5f * tb * tb * (p1->length * r1[2] + p2->length * r2[2]);
    return DH_OK;
}

/* s (rest 0) or 1 - s (rest 1), each accurate near its own 0, of the
 * scaling m at time t, clamped to [0, m->T] */
static float blend_prof_eval(const dh_blend_prof_f32 *m, float t, int rest)
{
    float r, x;
    if (!(t > 0.0f)) return rest ? 1.0f : 0.0f;
    if (!(t < m->T)) return rest ? 0.0f : 1.0f;
    if (t >= m->T - m->tb) {
        r = m->T - t;
        x = 0.5f * m->b * r * r;
    } else if (t >= m->t1 + m->tv) {
        r = (m->T - m->tb) - t;
        x = m->e + r * (m->u + 0.5f * m->a * r);
    } else {
        x = (t >= m->t1) ? m->v * (0.5f * m->t1 + (t - m->t1)) : 0.5f * m->a * t * t;
        return rest ? 1.0f - x : x;
    }
    return rest ? x : 1.0f - x;
}

/* column c of T = the slerp of the path p at s (a quaternion w, x, y, z
 * kept in T until dh_blend_compose_f32_: the slerp's stack apart from the
 * composition's) */
static DH_NOINLINE void blend_slerp(const dh_path_f32 *p, float s, dh_mat4_f32 *T, int c)
{
    dh_quat_f32 q;
    dh_motion_slerp_f32_(&p->qa, &p->qb, s, &q);
    DH_M4(T, 0, c) = q.w;
    DH_M4(T, 1, c) = q.x;
    DH_M4(T, 2, c) = q.y;
    DH_M4(T, 3, c) = q.z;
}

/* T's rotation and bottom row in the overlap: q2 q_A2* q1, with q1 in
 * T's column 0 and q2 in its column 1 (blend_slerp); the temporaries in
 * blocks of their own, so that they may share the stack */
void dh_blend_compose_f32_(const dh_quat_f32 *qa2, dh_mat4_f32 *T)
{
    dh_quat_f32 q1;
    int i;
    q1.w = DH_M4(T, 0, 0);
    q1.x = DH_M4(T, 1, 0);
    q1.y = DH_M4(T, 2, 0);
    q1.z = DH_M4(T, 3, 0);
    {
        dh_quat_f32 c;
        dh_quat_conj_f32(qa2, &c);
        dh_quat_mul_f32(&c, &q1, &q1);
    }
    {
        dh_quat_f32 q2;
        q2.w = DH_M4(T, 0, 1);
        q2.x = DH_M4(T, 1, 1);
        q2.y = DH_M4(T, 2, 1);
        q2.z = DH_M4(T, 3, 1);
        dh_quat_mul_f32(&q2, &q1, &q1);
    }
    {
        dh_mat3_f32 R;
        (void)dh_quat_to_mat3_f32(&q1, &R);
        dh_mat4_set_rot_f32(T, &R);
    }
    for (i = 0; i < 3; i++) DH_M4(T, 3, i) = 0.0f;
    DH_M4(T, 3, 3) = 1.0f;
}

/* T's position in an overlap: p1's end plus p1's point at the distance
 * x1 of s from its end less that end, plus p2's point at s = x2 less its
 * start (dh_motion_path_off_f32_; on lines p_B1 - x1 (p_B1 - p_A1) +
 * x2 (p_B2 - p_A2)) */
void dh_blend_pose_pos_f32_(const dh_path_f32 *p1, const dh_path_f32 *p2, float x1, float x2, dh_mat4_f32 *T)
{
    float o[3];
    int i;
    dh_motion_path_off_f32_(p2, x2, 0, T);
    for (i = 0; i < 3; i++) o[i] = DH_M4(T, i, 3);
    dh_motion_path_off_f32_(p1, x1, 1, T);
    for (i = 0; i < 3; i++) DH_M4(T, i, 3) = (DH_M4(&p1->B, i, 3) + DH_M4(T, i, 3)) + o[i];
}

dh_status dh_blend_eval_f32(const dh_blend_f32 *bl, float t, dh_mat4_f32 *T)
{
    float t2;
    DH_ASSERT(bl != NULL && T != NULL);
    if (isunordered(t, t)) return DH_ERR_NAN;
    if (!dh_motion_path_ok_f32_(&bl->p1) || !dh_motion_path_ok_f32_(&bl->p2)) return DH_ERR_ARG;
    if (!(t > bl->t0)) return dh_path_eval_f32(&bl->p1, blend_prof_eval(&bl->m1, t, 0), T);
    /* the second move runs its scaling backwards: its s is the rest */
    t2 = (t < bl->T) ? bl->m2.T - (t - bl->t0) : 0.0f;
    if (!(t < bl->t0 + bl->tb)) return dh_path_eval_f32(&bl->p2, blend_prof_eval(&bl->m2, t2, 1), T);
    blend_slerp(&bl->p1, blend_prof_eval(&bl->m1, t, 0), T, 0);
    blend_slerp(&bl->p2, blend_prof_eval(&bl->m2, t2, 1), T, 1);
    dh_blend_compose_f32_(&bl->p2.qa, T);
    dh_blend_pose_pos_f32_(&bl->p1, &bl->p2, blend_prof_eval(&bl->m1, t, 1), blend_prof_eval(&bl->m2, t2, 1), T);
    return DH_OK;
}

/* ---- blended sequences ---------------------------------------------- */

/* The checks of dh_blend_seq_plan_f32's arguments (n >= 1), in the order
 * of its statuses */
static DH_NOINLINE dh_status seq_check(const dh_path_f32 *p, uint32_t n, const float *radius,
                                       const dh_cart_limits_f32 *lim)
{
    const dh_status st = blend_check_lim(lim, 0.0f);
    uint32_t k;
    for (k = 0u; k + 1u < n; k++) {
        if (!dh_isfinite_f32(radius[k])) return DH_ERR_NAN;
    }
    if (st != DH_OK) return st;
    for (k = 0u; k < n; k++) {
        if (!blend_is_path(&p[k])) return DH_ERR_ARG;
        if (k + 1u < n && (radius[k] < 0.0f || !blend_joins(&p[k], &p[k + 1u]))) return DH_ERR_ARG;
    }
    return DH_OK;
}

/* *T = the sum of the lines' rest-to-rest durations (blend_rates' and
 * blend_dur's statuses: every DH_ERR_OVERFLOW of the planning) */
static DH_NOINLINE dh_status seq_rest(const dh_path_f32 *p, uint32_t n, const dh_cart_limits_f32 *lim, float *T)
{
    float r[3], d = 0.0f;
    uint32_t k;
    dh_status st = DH_OK;
    *T = 0.0f;
    for (k = 0u; k < n && st == DH_OK; k++) {
        st = blend_rates(&p[k], lim, r);
        if (st == DH_OK) st = blend_dur(r, 0.0f, &d);
        *T += d;
    }
    if (st == DH_OK && !dh_isfinite_f32(*T)) st = DH_ERR_OVERFLOW;
    return st;
}

/* The corner between the lines p[0] and p[1] (rates checked by seq_rest):
 * the end tail of g[0] and the start tail of g[1] (b, tb) and g[0].dev,
 * as dh_blend_plan_f32 plans them but each tail within half its line */
static DH_NOINLINE void seq_corner(dh_blend_seg_f32 *g, const dh_path_f32 *p, const dh_cart_limits_f32 *lim,
                                   float radius)
{
    float r1[3], r2[3], tb;
    (void)blend_rates(&p[0], lim, r1);
    (void)blend_rates(&p[1], lim, r2);
    blend_share(&p[0], &p[1], r1, r2, lim, 0);
    tb = blend_corner_tb(&p[0], &p[1], r1, r2, lim, radius, 1.0f, 1.0f);
    if (!(tb > 0.0f)) {
        tb = 0.0f;
        r1[2] = 0.0f;
        r2[2] = 0.0f;
    }
    g[0].b1 = r1[2];
    g[0].tb1 = tb;
    g[1].b0 = r2[2];
    g[1].tb0 = tb;
    g[0].dev = 0.5f * tb * tb * (p[0].length * r1[2] + p[1].length * r2[2]);
}

/* the duration a tail of g's b and the overlap tb add to the rest-to-rest
 * scaling of the line p (the two as blend_dur plans them; +Inf when one
 * cannot be planned) */
static DH_NOINLINE float seq_cost(const dh_path_f32 *p, const dh_cart_limits_f32 *lim, float b, float tb)
{
    float r[3], T, U;
    (void)blend_rates(p, lim, r);
    r[2] = b;
    if (blend_dur(r, 0.0f, &T) != DH_OK || blend_dur(r, tb, &U) != DH_OK) return INFINITY;
    return U - T;
}

/* the corner g[0] | g[1] at rest (no tails) */
static void seq_at_rest(dh_blend_seg_f32 *g)
{
    g[0].b1 = 0.0f;
    g[0].tb1 = 0.0f;
    g[1].b0 = 0.0f;
    g[1].tb0 = 0.0f;
    g[0].dev = 0.0f;
}

/* g's scaling of s over the distance D from its line's rates r (V, a;
 * a == 0: no motion) and its tails (b0, tb0, b1, tb1): the cruise time
 * from e0 + (v^2 - u0^2) / (2 a) + v tv + (v^2 - u1^2) / (2 a) + e1 = D,
 * or no cruise and v = sqrt(a (D - e0 - e1) + (u0^2 + u1^2) / 2). 1 when
 * the tails fit (v >= u0, u1 without the clamp below), else 0. */
static DH_NOINLINE int seq_prof(dh_blend_seg_f32 *g, const float *r, float D)
{
    const float V = r[0], a = r[1];
    float x, v = 0.0f, tv = 0.0f, hi;
    int fit = 1;
    g->u0 = g->b0 * g->tb0;
    g->e0 = 0.5f * g->u0 * g->tb0;
    g->u1 = g->b1 * g->tb1;
    g->e1 = 0.5f * g->u1 * g->tb1;
    g->a = (a > 0.0f) ? a : 0.0f;
    g->j = 0.0f;
    g->k0 = 0.0f;
    g->k1 = 0.0f;
    g->tj1 = 0.0f;
    g->tj3 = 0.0f;
    g->t1 = 0.0f;
    g->t3 = 0.0f;
    g->T = 0.0f;
    if (a > 0.0f) {
        x = g->e0 + g->e1 + (V * V - 0.5f * (g->u0 * g->u0 + g->u1 * g->u1)) / a;
        if (x >= D) {
            v = dh_sqrtf_(a * (D - g->e0 - g->e1) + 0.5f * (g->u0 * g->u0 + g->u1 * g->u1));
            hi = (g->u0 > g->u1) ? g->u0 : g->u1;
            if (!(v >= hi)) fit = 0;
            if (v < hi) v = hi;
            if (v > V) v = V;
        } else {
            v = V;
            tv = (D - x) / V;
        }
        g->t1 = (v - g->u0) / a;
        g->t3 = (v - g->u1) / a;
        g->T = g->tb0 + g->t1 + tv + g->t3 + g->tb1;
    }
    g->v = v;
    g->tv = tv;
    return fit;
}

/* every line's scaling from its rates and tails, and its start t0 on the
 * sequence's clock; the sequence's duration */
static DH_NOINLINE float seq_build(dh_blend_seg_f32 *seg, const dh_path_f32 *p, uint32_t n,
                                   const dh_cart_limits_f32 *lim)
{
    float r[3], T = 0.0f;
    uint32_t k;
    for (k = 0u; k < n; k++) {
        (void)blend_rates(&p[k], lim, r);
        (void)seq_prof(&seg[k], r, 1.0f);
        seg[k].t0 = T;
        T = seg[k].t0 + (seg[k].T - seg[k].tb1);
    }
    return T;
}

dh_status dh_blend_seq_plan_f32(dh_blend_seq_f32 *sq, dh_blend_seg_f32 *seg, const dh_path_f32 *p, uint32_t n,
                                const float *radius, const dh_cart_limits_f32 *lim)
{
    float Trr = 0.0f, T = 0.0f;
    uint32_t k;
    int pass;
    dh_status st;
    DH_ASSERT(sq != NULL && seg != NULL && p != NULL && lim != NULL && (n <= 1u || radius != NULL));
    if (n == 0u) return DH_ERR_ARG;
    st = seq_check(p, n, radius, lim);
    if (st == DH_OK) st = seq_rest(p, n, lim, &Trr);
    if (st != DH_OK) return st;
    /* the blended corners, then all at rest when that is not shorter */
    for (pass = 0; pass < 2; pass++) {
        seg[0].b0 = 0.0f;
        seg[0].tb0 = 0.0f;
        seg[n - 1u].b1 = 0.0f;
        seg[n - 1u].tb1 = 0.0f;
        seg[n - 1u].dev = 0.0f;
        for (k = 0u; k + 1u < n; k++) {
            /* blended when shorter: (U1 - T1) + (U2 - T2) < tb */
            seq_corner(&seg[k], &p[k], lim, (pass == 0) ? radius[k] : 0.0f);
            if (seg[k].tb1 > 0.0f && !(seq_cost(&p[k], lim, seg[k].b1, seg[k].tb1) +
                                           seq_cost(&p[k + 1u], lim, seg[k + 1u].b0, seg[k].tb1) <
                                       seg[k].tb1)) {
                seq_at_rest(&seg[k]);
            }
        }
        T = seq_build(seg, p, n, lim);
        if (T < Trr) break;
    }
    sq->p = p;
    sq->seg = seg;
    sq->n = n;
    sq->T = T;
    return DH_OK;
}

/* the distance x of the scaling g at its time t in (0, g->T) covered
 * from its start (returns 0: the first half) or left to its end (returns
 * 1) */
static DH_NOINLINE int seg_eval(const dh_blend_seg_f32 *g, float t, float *x)
{
    float r;
    if (t < g->tb0 + g->t1 + 0.5f * g->tv) {
        if (t < g->tb0) {
            *x = 0.5f * g->b0 * t * t;
        } else if (t < g->tb0 + g->t1) {
            r = t - g->tb0;
            *x = g->e0 + r * (g->u0 + 0.5f * g->a * r);
        } else {
            *x = g->e0 + 0.5f * g->t1 * (g->u0 + g->v) + g->v * (t - g->tb0 - g->t1);
        }
        return 0;
    }
    r = g->T - t;
    if (r < g->tb1) {
        *x = 0.5f * g->b1 * r * r;
    } else if (r < g->tb1 + g->t3) {
        r -= g->tb1;
        *x = g->e1 + r * (g->u1 + 0.5f * g->a * r);
    } else {
        *x = g->e1 + 0.5f * g->t3 * (g->u1 + g->v) + g->v * (r - g->tb1 - g->t3);
    }
    return 1;
}

/* The distance covered at the time r in [0, ta] of a jerk-limited
 * change of speed from u to v >= u over ta, jerk phases tj (ta >= 2 tj,
 * tj > 0 when v > u): the acceleration rises at +j to ap, holds, and
 * falls at -j to 0, ap = (v - u) / (ta - tj), j = ap / tj. The speed is
 * point-symmetric about ta / 2 (w(r) + w(ta - r) = u + v), so the second
 * half is (u + v) (ta / 2 - m) + x(m), m = ta - r, from the first. */
static float jt_x(float u, float v, float tj, float ta, float r)
{
    float ap, j, m = r, x, c = 0.0f;
    if (!(ta > 0.0f) || !(tj > 0.0f)) return u * r;
    ap = (v - u) / (ta - tj);
    j = ap / tj;
    if (r > 0.5f * ta) {
        m = ta - r;
        c = (u + v) * (0.5f * ta - m);
    }
    if (m <= tj) {
        x = m * (u + (j * m) * m * (1.0f / 6.0f));
    } else {
        x = m * u + ap * tj * tj * (1.0f / 6.0f) + (m - tj) * (0.5f * ap * tj + 0.5f * ap * (m - tj));
    }
    return c + x;
}

/* seg_eval for a jerk-limited scaling (g->j > 0): the changes of speed
 * from rest to v over t1 and from v to rest over t3 (jt_x), the second
 * evaluated from the end; the overlaps lie inside them */
static int jseg_eval(const dh_blend_seg_f32 *g, float t, float *x)
{
    float r;
    if (t < g->t1 + 0.5f * g->tv) {
        *x = (t < g->t1) ? jt_x(0.0f, g->v, g->tj1, g->t1, t) : g->v * (0.5f * g->t1 + (t - g->t1));
        return 0;
    }
    r = g->T - t;
    *x = (r < g->t3) ? jt_x(0.0f, g->v, g->tj3, g->t3, r) : g->v * (0.5f * g->t3 + (r - g->t3));
    return 1;
}

/* s (rest 0) or 1 - s (rest 1), each accurate near its own 0, of the
 * scaling g at its time t, clamped to [0, g->T]: the first half from the
 * start, the second from the end */
static float seq_prof_eval(const dh_blend_seg_f32 *g, float t, int rest)
{
    float x;
    if (!(t > 0.0f)) return rest ? 1.0f : 0.0f;
    if (!(t < g->T)) return rest ? 0.0f : 1.0f;
    return (rest != ((g->j > 0.0f) ? jseg_eval(g, t, &x) : seg_eval(g, t, &x))) ? 1.0f - x : x;
}

/* s of line k of sq at the sequence's time t */
static DH_NOINLINE float seq_s(const dh_blend_seq_f32 *sq, uint32_t k, float t)
{
    return seq_prof_eval(&sq->seg[k], t - sq->seg[k].t0, 0);
}

/* column c of T = the slerp of line k of sq at the sequence's time t
 * (blend_slerp) */
static DH_NOINLINE void seq_slerp(const dh_blend_seq_f32 *sq, uint32_t k, float t, dh_mat4_f32 *T, int c)
{
    blend_slerp(&sq->p[k], seq_s(sq, k, t), T, c);
}

/* T's position in the overlap of lines k - 1 and k of sq at the
 * sequence's time t: line k - 1's end less what its s has left, plus
 * what line k's s has covered */
static DH_NOINLINE void seq_position(const dh_blend_seq_f32 *sq, uint32_t k, float t, dh_mat4_f32 *T)
{
    const dh_path_f32 *p = &sq->p[k - 1u];
    const dh_blend_seg_f32 *g = &sq->seg[k - 1u];
    dh_blend_pose_pos_f32_(&p[0], &p[1], seq_prof_eval(&g[0], t - g[0].t0, 1), seq_prof_eval(&g[1], t - g[1].t0, 0), T);
}

/* the index of the last line of sq with t0 <= t */
static DH_NOINLINE uint32_t seq_find(const dh_blend_seq_f32 *sq, float t)
{
    uint32_t k = 0u;
    while (k + 1u < sq->n && !(t < sq->seg[k + 1u].t0)) k++;
    return k;
}

/* The overlap's rotation is composed as dh_blend_eval_f32's, called from
 * here directly (one small frame above the slerp and the composition) */
dh_status dh_blend_seq_eval_f32(const dh_blend_seq_f32 *sq, float t, dh_mat4_f32 *T)
{
    uint32_t k;
    DH_ASSERT(sq != NULL && T != NULL);
    if (isunordered(t, t)) return DH_ERR_NAN;
    if (sq->n == 0u || sq->p == NULL || sq->seg == NULL) return DH_ERR_ARG;
    if (!(t > 0.0f)) return dh_path_eval_f32(&sq->p[0], 0.0f, T);
    if (!(t < sq->T)) return dh_path_eval_f32(&sq->p[sq->n - 1u], 1.0f, T);
    k = seq_find(sq, t);
    if (k == 0u || !(t - sq->seg[k].t0 < sq->seg[k].tb0)) return dh_path_eval_f32(&sq->p[k], seq_s(sq, k, t), T);
    if (!dh_motion_path_ok_f32_(&sq->p[k - 1u]) || !dh_motion_path_ok_f32_(&sq->p[k])) return DH_ERR_ARG;
    seq_slerp(sq, k - 1u, t, T, 0);
    seq_slerp(sq, k, t, T, 1);
    dh_blend_compose_f32_(&sq->p[k].qa, T);
    seq_position(sq, k, t, T);
    return DH_OK;
}

/* ---- jerk-limited blended sequences of lines ------------------------ */

/* The jerk limits: DH_ERR_NAN for a NaN/Inf one, DH_ERR_ARG for one
 * <= 0 or an arc among the n paths p */
static DH_NOINLINE dh_status jseq_check(const dh_path_f32 *p, uint32_t n, const dh_cart_jerk_f32 *jk)
{
    uint32_t k;
    if (!dh_isfinite_f32(jk->jmax) || !dh_isfinite_f32(jk->wjmax)) return DH_ERR_NAN;
    if (!(jk->jmax > 0.0f) || !(jk->wjmax > 0.0f)) return DH_ERR_ARG;
    for (k = 0u; k < n; k++) {
        if (p[k].kind != (uint32_t)DH_PATH_LINE) return DH_ERR_ARG;
    }
    return DH_OK;
}

/* r = V, a, j: the bounds of s', s'', s''' of the line p within lim and
 * jk (those of dh_path_move_jerk_f32 on a line); all 0 when p has no
 * motion */
static DH_NOINLINE dh_status jseq_rates(const dh_path_f32 *p, const dh_cart_limits_f32 *lim,
                                        const dh_cart_jerk_f32 *jk, float r[3])
{
    dh_status st;
    r[0] = 0.0f;
    r[1] = 0.0f;
    r[2] = 0.0f;
    st = dh_motion_bound_f32_(&r[0], lim->vmax, p->length);
    if (st == DH_OK) st = dh_motion_bound_f32_(&r[0], lim->wmax, p->angle);
    if (st == DH_OK) st = dh_motion_bound_f32_(&r[1], lim->amax, p->length);
    if (st == DH_OK) st = dh_motion_bound_f32_(&r[1], lim->wdmax, p->angle);
    if (st == DH_OK) st = dh_motion_bound_f32_(&r[2], jk->jmax, p->length);
    if (st == DH_OK) st = dh_motion_bound_f32_(&r[2], jk->wjmax, p->angle);
    if (st == DH_OK && (p->length > 0.0f || p->angle > 0.0f) &&
        (!(r[0] > 0.0f) || !(r[1] > 0.0f) || !(r[2] > 0.0f))) {
        st = DH_ERR_OVERFLOW;
    }
    return st;
}

/* *tj, *ta: the jerk phases and the duration of the time-optimal
 * jerk-limited change of speed by du within a, j (both > 0), from and to
 * acceleration 0: a reached when du >= a^2 / j (tj = a / j,
 * ta = du / a + tj), else tj = sqrt(du) / sqrt(j) (no underflow of a
 * quotient), ta = 2 tj; 0 for du <= 0 */
DH_INLINE void jt_times(float du, float a, float j, float *tj, float *ta)
{
    *tj = 0.0f;
    *ta = 0.0f;
    if (!(du > 0.0f)) return;
    if (du >= a * (a / j)) {
        *tj = a / j;
        *ta = du / a + *tj;
    } else {
        *tj = dh_sqrtf_(du) / dh_sqrtf_(j);
        *ta = 2.0f * *tj;
    }
}

/* s' at the time r in [0, ta / 2] of the change of speed from 0 to v
 * over ta with the jerk phases tj (jt_x's): j r^2 / 2 up to tj, then
 * ap tj / 2 + ap (r - tj) */
DH_INLINE float jt_v(float v, float tj, float ta, float r)
{
    float ap;
    if (!(ta > 0.0f) || !(tj > 0.0f)) return 0.0f;
    ap = v / (ta - tj);
    if (r <= tj) return 0.5f * (ap / tj) * r * r;
    return ap * (0.5f * tj + (r - tj));
}

/* s covered by the scaling g of a line that accelerates from rest to v
 * within g->b0, g->k0 (bounds of s'' and s''') and decelerates to rest
 * within g->b1, g->k1, without cruising: v (ta0 + ta1) / 2 (the speed of
 * each change is point-symmetric) */
DH_INLINE float jp_dist(const dh_blend_seg_f32 *g, float v)
{
    float tj, t0, t1;
    jt_times(v, g->b0, g->k0, &tj, &t0);
    jt_times(v, g->b1, g->k1, &tj, &t1);
    return 0.5f * v * (t0 + t1);
}

/* g's scaling of s over the distance D (s from 1 - D to 1) from s' <= V
 * and its bounds b0, k0, b1, k1: from rest to v over t1 (ramps tj1), a
 * cruise tv, to rest over t3 (ramps tj3), T; v = V and the cruise the
 * distance left when jp_dist(V) <= D, else the largest v with
 * jp_dist(v) <= D (jp_dist grows with v: bisection to one ulp) and the
 * tiny cruise at v that covers the rest exactly; all 0 when b0 is 0 (no
 * motion) */
static DH_NOINLINE void jp_fill(dh_blend_seg_f32 *g, float V, float D)
{
    float lo = 0.0f, hi = V, m = V, x;
    int i;
    for (i = 0; i < 200 && g->b0 > 0.0f; i++) {
        if (jp_dist(g, m) <= D) {
            lo = m;
            if (!(m < V)) break;
        } else {
            hi = m;
        }
        m = 0.5f * (lo + hi);
        if (!(m > lo) || !(m < hi)) break;
    }
    x = jp_dist(g, lo);
    g->v = lo;
    g->tv = (lo > 0.0f && x < D) ? (D - x) / lo : 0.0f;
    jt_times(lo, g->b0, g->k0, &g->tj1, &g->t1);
    jt_times(lo, g->b1, g->k1, &g->tj3, &g->t3);
    g->T = g->t1 + g->tv + g->t3;
}

/* jseq_bound's bound of one line's duration from its rates r */
static DH_NOINLINE float jseq_line_T(const float r[3])
{
    return 2.0f / r[0] + 4.0f * (r[0] / r[1] + r[1] / r[2] + 2.0f * (dh_sqrtf_(r[0]) / dh_sqrtf_(r[2])));
}

/* the statuses of the lines' rates (jseq_rates), then DH_ERR_OVERFLOW
 * when a line's duration bound 2 / V + 4 (V / a + a / j + 2 sqrt(V / j))
 * (above any of its scalings: each change of speed takes at most
 * V / a + a / j + 2 sqrt(V / j), the cruise at most 1 / V plus the
 * rounding of the bisection), or their sum, is not finite */
static DH_NOINLINE dh_status jseq_bound(const dh_path_f32 *p, uint32_t n, const dh_cart_limits_f32 *lim,
                                        const dh_cart_jerk_f32 *jk)
{
    float r[3], T = 0.0f;
    uint32_t i;
    dh_status st = DH_OK;
    for (i = 0u; i < n && st == DH_OK; i++) {
        st = jseq_rates(&p[i], lim, jk, r);
        if (st == DH_OK && r[1] > 0.0f) T += jseq_line_T(r);
    }
    if (st == DH_OK && !dh_isfinite_f32(T)) st = DH_ERR_OVERFLOW;
    return st;
}

/* *x, *y scaled together so that wx x + wy y <= w (w > 0) */
static void jseq_scale2(float *x, float *y, float wx, float wy, float w)
{
    float s = wx * *x + wy * *y;
    if (s > w) {
        s = w / s;
        *x *= s;
        *y *= s;
    }
}

/* One corner of jerk-limited lines: the scalings g[0] (the line before
 * the corner) and g[1] (the line after it) of the lines p[0], p[1]
 * within lim, jk and radius (the sequence's consecutive ones, or the
 * queue's items') */
typedef struct {
    dh_blend_seg_f32 *g[2];
    const dh_path_f32 *p[2];
    const dh_cart_limits_f32 *lim;
    const dh_cart_jerk_f32 *jk;
    float radius;
} jseq_corner;

/* The bounds of line 1's deceleration (g[0]->b1, k1) and line 2's
 * acceleration (g[1]->b0, k0) at the corner c, set to the lines' own by
 * jseq_unmark: at rest when the radius is 0 or a line has no motion
 * (g[0]->tb1 = 0), else lowered to L_i a_i' <= amax / max(1, |d2 - d1|)
 * and L_i j_i' <= jmax / max(1, |d1 + d2|) (in the overlap the tool's
 * acceleration is x2 d2 - x1 d1 and its jerk y1 d1 + y2 d2 with x_i, y_i
 * in [0, L_i a_i'] and [0, L_i j_i']: norms convex, at most their largest
 * value at a vertex of the box), then th1 a1' + th2 a2' <= (63/64) wdmax
 * and th1 j1' + th2 j2' <= (63/64) wjmax (the cross terms of the composed
 * rotation get the last 1/64 through tb), g[0]->tb1 = 1 marking the
 * corner for jseq_cost */
static DH_NOINLINE void jseq_red(const jseq_corner *c)
{
    dh_blend_seg_f32 *const *g = c->g;
    const dh_path_f32 *const *p = c->p;
    float ca = c->lim->amax * BLEND_MARGIN, cj = c->jk->jmax * BLEND_MARGIN, x;
    float *b[4];
    int i;
    b[0] = &g[0]->b1;
    b[1] = &g[0]->k1;
    b[2] = &g[1]->b0;
    b[3] = &g[1]->k0;
    g[0]->tb1 = (c->radius > 0.0f && *b[0] > 0.0f && *b[2] > 0.0f) ? 1.0f : 0.0f;
    if (!(g[0]->tb1 > 0.0f)) return;
    if (p[0]->length > 0.0f && p[1]->length > 0.0f) {
        x = blend_turn(p[0], p[1]);
        if (x > 1.0f) ca /= x;
        x = 4.0f - x * x; /* |d1 + d2|^2 of unit d1, d2 */
        if (x > 1.0f) cj /= dh_sqrtf_(x);
    }
    for (i = 0; i < 2; i++) {
        if (p[i]->length * *b[2 * i] > ca) *b[2 * i] = ca / p[i]->length;
        if (p[i]->length * *b[2 * i + 1] > cj) *b[2 * i + 1] = cj / p[i]->length;
    }
    jseq_scale2(b[0], b[2], p[0]->angle, p[1]->angle, BLEND_WSHARE * c->lim->wdmax);
    jseq_scale2(b[1], b[3], p[0]->angle, p[1]->angle, BLEND_WSHARE * c->jk->wjmax);
}

/* s'' at the time r in [0, ta / 2] of the change of speed from 0 to v
 * over ta with the jerk phases tj (jt_v's): j r up to tj, then ap */
DH_INLINE float jt_a(float v, float tj, float ta, float r)
{
    float ap;
    if (!(ta > 0.0f) || !(tj > 0.0f)) return 0.0f;
    ap = v / (ta - tj);
    return (r < tj) ? (ap / tj) * r : ap;
}

/* 1 when the tool stays within the radius of the corner c over its
 * overlap tb: L1 x1 + L2 x2 <= radius, x_i the s each line covers in tb
 * (jt_x; jseq_tb's first test, apart from jseq_ok's frame) */
static DH_NOINLINE int jseq_near(const jseq_corner *c, float tb)
{
    dh_blend_seg_f32 *const *g = c->g;
    const dh_path_f32 *const *p = c->p;
    return (p[0]->length * jt_x(0.0f, g[0]->v, g[0]->tj3, g[0]->t3, tb) +
                p[1]->length * jt_x(0.0f, g[1]->v, g[1]->tj1, g[1]->t1, tb) <=
            c->radius)
               ? 1
               : 0;
}

/* 1 when the overlap tb of the corner c (g[0]'s deceleration v, tj3, t3
 * and g[1]'s acceleration v, tj1, t1, tb within half of each) keeps the
 * cross terms of the composed rotation within their 1/64 (docs/design.md;
 * the radius is jseq_near's test): with w_i = th_i u_i (u_i
 * the s' at tb, the largest in the overlap) and P_i = th_i times the
 * lowered s'' bound, (pi/180) w1 w2 <= wdmax / 64,
 * (pi/180) (2 w2 P1 + P2 w1) <= wjmax / 128 and
 * (pi/180)^2 w2^2 w1 <= wjmax / 128 */
static DH_NOINLINE int jseq_ok(const jseq_corner *c, float tb)
{
    dh_blend_seg_f32 *const *g = c->g;
    const dh_path_f32 *const *p = c->p;
    const float w1 = p[0]->angle * jt_v(g[0]->v, g[0]->tj3, g[0]->t3, tb);
    const float w2 = p[1]->angle * jt_v(g[1]->v, g[1]->tj1, g[1]->t1, tb);
    if (!(w1 * w2 <= BLEND_RAD2DEG * (c->lim->wdmax * 0.015625f))) return 0;
    if (!(2.0f * w2 * (p[0]->angle * g[0]->b1) + (p[1]->angle * g[1]->b0) * w1 <=
          BLEND_RAD2DEG * (c->jk->wjmax * 0.0078125f))) {
        return 0;
    }
    return (w2 * w2) * w1 <= (BLEND_RAD2DEG * BLEND_RAD2DEG) * (c->jk->wjmax * 0.0078125f);
}

/* the overlap of the corner c (jseq_ok): the largest tb up to half of
 * both changes of speed that jseq_ok accepts (each of its terms grows
 * with tb: bisection), times 1 - 2^-10; 0 when none */
static DH_NOINLINE float jseq_tb(const jseq_corner *c)
{
    const float H = 0.5f * ((c->g[0]->t3 < c->g[1]->t1) ? c->g[0]->t3 : c->g[1]->t1);
    float lo = 0.0f, hi = H, m = H;
    int i;
    for (i = 0; i < 200 && H > 0.0f; i++) {
        if (jseq_near(c, m) != 0 && jseq_ok(c, m) != 0) {
            lo = m;
            if (!(m < H)) break;
        } else {
            hi = m;
        }
        m = 0.5f * (lo + hi);
        if (!(m > lo) || !(m < hi)) break;
    }
    lo *= BLEND_MARGIN;
    return (lo > 0.0f && dh_isfinite_f32(lo)) ? lo : 0.0f;
}

/* g's jerk-limited scaling (jp_fill over s = 1) from its line's rates
 * and the bounds of its acceleration (b0, k0) and deceleration (b1, k1) */
static DH_NOINLINE void jseq_prof(dh_blend_seg_f32 *g, const dh_path_f32 *p, const dh_cart_limits_f32 *lim,
                                  const dh_cart_jerk_f32 *jk)
{
    float r[3];
    (void)jseq_rates(p, lim, jk, r);
    jp_fill(g, r[0], 1.0f);
    g->a = r[1];
    g->j = r[2];
}

/* g[0]->dev (scratch until jseq_overlap) = the time the lowered bounds
 * of the corner c (jseq_red) add to its two lines, each line's other end
 * as set, over two calls: line i = 0's set, line i = 1's added (the time
 * line i takes with its own bounds at the corner's end, b, k of its
 * side, less with the ones it holds); the scalings are left as with the
 * lowered bounds (for jseq_tb) */
static DH_NOINLINE void jseq_cost(const jseq_corner *c, int i)
{
    dh_blend_seg_f32 *g = c->g[i];
    float *b = (i == 0) ? &g->b1 : &g->b0, *k = (i == 0) ? &g->k1 : &g->k0;
    float r[3], x = *b, y = *k, T;
    (void)jseq_rates(c->p[i], c->lim, c->jk, r);
    *b = r[1];
    *k = r[2];
    jp_fill(g, r[0], 1.0f);
    T = g->T;
    *b = x;
    *k = y;
    jp_fill(g, r[0], 1.0f);
    x = g->T - T;
    c->g[0]->dev = (i == 0) ? x : c->g[0]->dev + x;
}


/* the corner c at rest: its lines' own bounds, tb1 0 */
static DH_NOINLINE void jseq_unmark(const jseq_corner *c)
{
    float r[3];
    (void)jseq_rates(c->p[0], c->lim, c->jk, r);
    c->g[0]->b1 = r[1];
    c->g[0]->k1 = r[2];
    (void)jseq_rates(c->p[1], c->lim, c->jk, r);
    c->g[1]->b0 = r[1];
    c->g[1]->k0 = r[2];
    c->g[0]->tb1 = 0.0f;
}

/* the overlap tb of the corner c (0: at rest): tb1 = tb0 = tb, the s'
 * and s covered at its inner ends (u1, e1 of g[0]; u0, e0 of g[1]) and
 * g[0]->dev, the bound L1 e1 + L2 e0 of the distance from the corner */
static DH_NOINLINE void jseq_overlap(const jseq_corner *c, float tb)
{
    dh_blend_seg_f32 *const *g = c->g;
    g[0]->tb1 = tb;
    g[1]->tb0 = tb;
    g[0]->u1 = jt_v(g[0]->v, g[0]->tj3, g[0]->t3, tb);
    g[0]->e1 = jt_x(0.0f, g[0]->v, g[0]->tj3, g[0]->t3, tb);
    g[1]->u0 = jt_v(g[1]->v, g[1]->tj1, g[1]->t1, tb);
    g[1]->e0 = jt_x(0.0f, g[1]->v, g[1]->tj1, g[1]->t1, tb);
    g[0]->dev = c->p[0]->length * g[0]->e1 + c->p[1]->length * g[1]->e0;
}

/* c = corner k of the seq planner's lines with the radius radius */
static void jseq_at(jseq_corner *c, dh_blend_seg_f32 *seg, const dh_path_f32 *p, uint32_t k, float radius)
{
    c->g[0] = &seg[k];
    c->g[1] = &seg[k + 1u];
    c->p[0] = &p[k];
    c->p[1] = &p[k + 1u];
    c->radius = radius;
}

/* the first line's acceleration and the last line's deceleration at their
 * own bounds, at rest */
static DH_NOINLINE void jseq_ends(dh_blend_seg_f32 *seg, const dh_path_f32 *p, uint32_t n,
                                  const dh_cart_limits_f32 *lim, const dh_cart_jerk_f32 *jk)
{
    float r[3];
    (void)jseq_rates(&p[0], lim, jk, r);
    seg[0].b0 = r[1];
    seg[0].k0 = r[2];
    seg[0].tb0 = 0.0f;
    seg[0].u0 = 0.0f;
    seg[0].e0 = 0.0f;
    (void)jseq_rates(&p[n - 1u], lim, jk, r);
    seg[n - 1u].b1 = r[1];
    seg[n - 1u].k1 = r[2];
    seg[n - 1u].tb1 = 0.0f;
    seg[n - 1u].u1 = 0.0f;
    seg[n - 1u].e1 = 0.0f;
    seg[n - 1u].dev = 0.0f;
}

/* Planned in steps called from here, each with its stack apart: pass 0
 * all corners at rest (its duration the rest-to-rest sum Trr), pass 1
 * blended, kept when shorter than Trr, else pass 2 at rest again. A pass:
 * the corners' bounds (jseq_red), each marked corner kept when its
 * overlap exceeds its cost (jseq_cost, jseq_tb), the lines' scalings, the
 * overlaps (jseq_tb, jseq_overlap) and the starts t0 */
dh_status dh_blend_seq_plan_jerk_f32(dh_blend_seq_f32 *sq, dh_blend_seg_f32 *seg, const dh_path_f32 *p, uint32_t n,
                                     const float *radius, const dh_cart_limits_f32 *lim, const dh_cart_jerk_f32 *jerk)
{
    jseq_corner c;
    float Trr = 0.0f, T = 0.0f;
    uint32_t k;
    int pass;
    dh_status st;
    DH_ASSERT(sq != NULL && seg != NULL && p != NULL && lim != NULL && jerk != NULL && (n <= 1u || radius != NULL));
    if (n == 0u) return DH_ERR_ARG;
    st = seq_check(p, n, radius, lim);
    if (st == DH_OK) st = jseq_check(p, n, jerk);
    if (st == DH_OK) st = jseq_bound(p, n, lim, jerk);
    if (st != DH_OK) return st;
    c.lim = lim;
    c.jk = jerk;
    for (pass = 0; pass < 3; pass++) {
        jseq_ends(seg, p, n, lim, jerk);
        for (k = 0u; k + 1u < n; k++) {
            jseq_at(&c, seg, p, k, (pass == 1) ? radius[k] : 0.0f);
            jseq_unmark(&c);
            jseq_red(&c);
        }
        for (k = 0u; k + 1u < n; k++) {
            jseq_at(&c, seg, p, k, radius[k]);
            if (seg[k].tb1 > 0.0f) {
                jseq_cost(&c, 0);
                jseq_cost(&c, 1);
                if (!(seg[k].dev < jseq_tb(&c))) jseq_unmark(&c);
            }
        }
        for (k = 0u; k < n; k++) jseq_prof(&seg[k], &p[k], lim, jerk);
        for (k = 0u; k + 1u < n; k++) {
            jseq_at(&c, seg, p, k, radius[k]);
            jseq_overlap(&c, (seg[k].tb1 > 0.0f) ? jseq_tb(&c) : 0.0f);
        }
        T = 0.0f;
        for (k = 0u; k < n; k++) {
            seg[k].t0 = T;
            T = seg[k].t0 + (seg[k].T - seg[k].tb1);
        }
        if (pass == 0) Trr = T;
        if (pass == 1 && T < Trr) break;
    }
    sq->p = p;
    sq->seg = seg;
    sq->n = n;
    sq->T = T;
    return DH_OK;
}

/* ---- the queue's blended lines (dh_queue.c, motion_impl.h) ---------- */

float dh_blend_corner_f32_(const dh_path_f32 *p1, const dh_path_f32 *p2, const dh_cart_limits_f32 *lim, float radius,
                           float b[2])
{
    float r1[3], r2[3], tb;
    b[0] = 0.0f;
    b[1] = 0.0f;
    if (!blend_is_path(p1) || !blend_is_path(p2) || !blend_joins(p1, p2) || !(radius > 0.0f)) return 0.0f;
    if (blend_rates(p1, lim, r1) != DH_OK || blend_rates(p2, lim, r2) != DH_OK) return 0.0f;
    blend_share(p1, p2, r1, r2, lim, 1);
    tb = blend_corner_tb(p1, p2, r1, r2, lim, radius, 1.0f, 2.0f);
    if (!(tb > 0.0f)) return 0.0f;
    /* blended when shorter: (U1 - T1) + (U2 - T2) < tb, as seq_cost (a
     * duration that is not finite: at rest) */
    if (!(blend_gain(r1, r2, tb) < 0.0f)) return 0.0f;
    b[0] = r1[2];
    b[1] = r2[2];
    return tb;
}

void dh_blend_rates_f32_(const dh_path_f32 *p, const dh_cart_limits_f32 *lim, float r[2])
{
    float x[3];
    (void)blend_rates(p, lim, x);
    r[0] = x[0];
    r[1] = x[1];
}

int dh_blend_seg_plan_f32_(dh_blend_seg_f32 *g, const float r[2], float D)
{
    g->t0 = 0.0f;
    g->dev = 0.0f;
    return seq_prof(g, r, D);
}

float dh_blend_seg_s_f32_(const dh_blend_seg_f32 *g, float s0, float t)
{
    float x;
    if (!(t > 0.0f) || !(g->T > 0.0f)) return s0;
    if (!(t < g->T)) return 1.0f;
    if (((g->j > 0.0f) ? jseg_eval(g, t, &x) : seg_eval(g, t, &x)) != 0) return 1.0f - x;
    x += s0;
    return (x < 1.0f) ? x : 1.0f;
}

/* s' of the jerk-limited scaling g at its time t in (0, T), s'' into
 * *sdd: each change of speed point-symmetric about its middle (jt_v and
 * jt_a on its first half) */
static DH_NOINLINE float jseg_rate(const dh_blend_seg_f32 *g, float t, float *sdd)
{
    const float r = g->T - t;
    float ta = g->t3, tj = g->tj3, x = r, sg = -1.0f, m;
    if (t < g->t1) {
        ta = g->t1;
        tj = g->tj1;
        x = t;
        sg = 1.0f;
    }
    *sdd = 0.0f;
    if (!(x < ta)) return g->v;
    m = (x < 0.5f * ta) ? x : ta - x;
    *sdd = sg * jt_a(g->v, tj, ta, m);
    return (x < 0.5f * ta) ? jt_v(g->v, tj, ta, x) : g->v - jt_v(g->v, tj, ta, m);
}

/* s' of the trapezoidal scaling g at its time t in (0, T), s'' into *sdd */
static DH_NOINLINE float seg_rate(const dh_blend_seg_f32 *g, float t, float *sdd)
{
    float r = g->T - t;
    if (t < g->tb0) {
        *sdd = g->b0;
        return g->b0 * t;
    }
    if (t < g->tb0 + g->t1) {
        *sdd = g->a;
        return g->u0 + g->a * (t - g->tb0);
    }
    if (r < g->tb1) {
        *sdd = -g->b1;
        return g->b1 * r;
    }
    if (r < g->tb1 + g->t3) {
        *sdd = -g->a;
        return g->u1 + g->a * (r - g->tb1);
    }
    return g->v;
}

float dh_blend_seg_rate_f32_(const dh_blend_seg_f32 *g, float t, float *sdd)
{
    *sdd = 0.0f;
    if (!(t > 0.0f) || !(t < g->T)) return 0.0f;
    return (g->j > 0.0f) ? jseg_rate(g, t, sdd) : seg_rate(g, t, sdd);
}

void dh_blend_pose_rot_f32_(const dh_path_f32 *p1, const dh_path_f32 *p2, dh_mat4_f32 *T)
{
    dh_quat_f32 q;
    int c, i;
    for (c = 0; c < 2; c++) {
        const dh_path_f32 *p = (c == 0) ? p1 : p2;
        dh_motion_slerp_f32_(&p->qa, &p->qb, DH_M4(T, c, 3), &q);
        for (i = 0; i < 4; i++) DH_M4(T, i, c) = (i == 0) ? q.w : ((i == 1) ? q.x : ((i == 2) ? q.y : q.z));
    }
}



/* ---- the queue's jerk-limited blended lines (dh_queue.c) ------------ */

void dh_blend_jline_f32_(dh_blend_seg_f32 *g, const dh_path_f32 *p, const dh_cart_limits_f32 *lim,
                         const dh_cart_jerk_f32 *jk, float D)
{
    float r[3];
    (void)jseq_rates(p, lim, jk, r);
    g->b0 = r[1];
    g->k0 = r[2];
    g->b1 = r[1];
    g->k1 = r[2];
    g->tb0 = 0.0f;
    g->u0 = 0.0f;
    g->e0 = 0.0f;
    g->tb1 = 0.0f;
    g->u1 = 0.0f;
    g->e1 = 0.0f;
    g->t0 = 0.0f;
    g->dev = 0.0f;
    jp_fill(g, r[0], D);
    g->a = r[1];
    g->j = r[2];
}

/* The seq planner's corner (jseq_red, jseq_cost, jseq_tb, jseq_overlap)
 * on the pair, its steps called from here one after the other; the
 * first line's speed v as it was planned kept (its start overlap, when it
 * has one, was planned with it), else the corner at rest */
float dh_blend_jcorner_f32_(dh_queue_item_f32 *i1, dh_queue_item_f32 *i2)
{
    jseq_corner c;
    dh_blend_seg_f32 *const *g = c.g;
    const dh_path_f32 *p1 = &i1->path, *p2 = &i2->path;
    const dh_cart_limits_f32 *lim = &i1->lim;
    const dh_cart_jerk_f32 *jk = &i1->jk;
    const float v = i1->seg.v;
    float tb = 0.0f;
    c.g[0] = &i1->seg;
    c.g[1] = &i2->seg;
    c.p[0] = p1;
    c.p[1] = p2;
    c.lim = lim;
    c.jk = jk;
    c.radius = i1->radius;
    if (p1->kind == (uint32_t)DH_PATH_LINE && p2->kind == (uint32_t)DH_PATH_LINE && blend_joins(p1, p2)) {
        jseq_unmark(&c);
        jseq_red(&c);
    } else {
        g[0]->tb1 = 0.0f;
    }
    if (g[0]->tb1 > 0.0f) {
        jseq_cost(&c, 0);
        jseq_cost(&c, 1);
        if (!(g[0]->dev < jseq_tb(&c))) jseq_unmark(&c);
    }
    jseq_prof(g[0], p1, lim, jk);
    jseq_prof(g[1], p2, lim, jk);
    if (g[0]->tb1 > 0.0f && (!(g[0]->tb0 > 0.0f) || dh_feq_f32(g[0]->v, v))) tb = jseq_tb(&c);
    if (!(tb > 0.0f)) {
        jseq_unmark(&c);
        jseq_prof(g[0], p1, lim, jk);
        jseq_prof(g[1], p2, lim, jk);
    }
    jseq_overlap(&c, tb);
    if (!(tb > 0.0f)) g[0]->dev = 0.0f;
    return tb;
}
