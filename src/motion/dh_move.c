/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_move.c - the move executor: a joint move sampled once per control
 * period, and a Cartesian path move whose frames the caller's tracker
 * follows (contract in motion.h, method in docs/design.md, "Motion").
 *
 * The functions call only the profile, joint move and path functions: the
 * tracker is the caller's, so each stays within the stack budget.
 *
 * Clock. A move's clock runs from 0 to its duration and is capped there,
 * so the end is reached exactly (the joint move's q1 and the path's B bit
 * for bit). A joint move's clock advances by dt every period. A path
 * move's clock advances by r dt, r in [0, 1] its feed override (time
 * scaling: the target's path parameter is s(clock), so its rate is
 * s'(clock) r): r falls while the tracker is not OK and rises again while
 * it is, each period by at most what keeps the target's acceleration
 * along the path within the profile's peak (move_feed_bounds). While the
 * tracker is OK with r at 1 the clock advances by dt exactly, as r dt is
 * dt: a move the tracker follows runs its profile bit for bit.
 *
 * Ceiling. Each stretch of not-OK periods (an episode) that begins while
 * the path moves sets the ceiling of r to MOVE_CEIL times the r it began
 * at, so r settles below the rate the joints could not follow instead of
 * rising into it again; the ceiling rises by MOVE_CREEP times r's largest
 * rise in every OK period with r at it, so the move speeds up again where
 * the joints can follow. A tool away from the path's start is brought onto
 * it with the clock at 0 (s' = 0 there: r falls to 0 and rises back to
 * its ceiling in one period each, and the ceiling is not lowered).
 */
#include "dhmath/motion.h"
#include "../internal/dh_build.h"
#include "../internal/dh_floatops.h"
#include "motion_impl.h"

/* 1 - 2^-10: the joint move's planning margin under the caller's limits */
#define MOVE_MARGIN 0.9990234375f

/* the ceiling of r after an episode of not-OK periods begun at r */
#define MOVE_CEIL 0.875f
/* the ceiling's relative rise per second of OK periods at it (1/s) */
#define MOVE_CREEP 2.0f

/* 1 when mv holds a move of the given kind with a consistent clock and
 * override */
static int move_holds(const dh_move_f32 *mv, uint32_t kind)
{
    if (mv->kind != kind) return 0;
    if (!dh_isfinite_f32(mv->dur) || !(mv->dur >= 0.0f)) return 0;
    if (!(mv->clock >= 0.0f) || !(mv->clock <= mv->dur)) return 0;
    if (!(mv->feed >= 0.0f) || !(mv->feed <= 1.0f) || !(mv->fcap >= 0.0f) || !(mv->fcap <= 1.0f)) return 0;
    return (kind != (uint32_t)DH_MOVE_JOINT) || (mv->n >= 1u && mv->n <= (uint32_t)DH_MAX_JOINTS);
}

/* the period's status: DH_ERR_NAN for a NaN/Inf dt, DH_ERR_ARG for
 * dt <= 0 or an mv that holds no move of the kind */
static dh_status move_period_ok(const dh_move_f32 *mv, uint32_t kind, float dt)
{
    if (!move_holds(mv, kind)) return DH_ERR_ARG;
    if (!dh_isfinite_f32(dt)) return DH_ERR_NAN;
    return (dt > 0.0f) ? DH_OK : DH_ERR_ARG;
}

/* the clock advanced by dt, capped at the duration */
static float move_next_clock(const dh_move_f32 *mv, float dt)
{
    const float c = mv->clock + dt;
    return (c < mv->dur) ? c : mv->dur;
}

/* the override at its start: r = its ceiling = 1 */
static void move_feed_init(dh_move_f32 *mv)
{
    mv->feed = 1.0f;
    mv->fcap = 1.0f;
    mv->lag = 0u;
}

dh_status dh_move_joint_f32(dh_move_f32 *mv, uint32_t n, const float *q0, const float *q1, const float *vmax,
                            const float *amax, const float *jmax)
{
    uint32_t i;
    dh_status st;
    DH_ASSERT(mv != NULL && q0 != NULL && q1 != NULL && vmax != NULL && amax != NULL);
    mv->kind = (uint32_t)DH_MOVE_NONE;
    if (n == 0u || n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    /* the limits lowered by the margin (NaN, Inf and <= 0 stay so, and
     * dh_joint_move_f32 reports them) */
    for (i = 0u; i < n; i++) {
        mv->ws[0][i] = vmax[i] * MOVE_MARGIN;
        mv->ws[1][i] = amax[i] * MOVE_MARGIN;
    }
    st = dh_joint_move_f32(mv->prof, n, q0, q1, mv->ws[0], mv->ws[1], jmax);
    if (st != DH_OK) return st;
    for (i = 0u; i < n; i++) {
        const float a = q0[i], b = q1[i];
        mv->q0[i] = a;
        mv->q1[i] = b;
    }
    mv->n = n;
    mv->dur = mv->prof[0].T;
    mv->clock = 0.0f;
    move_feed_init(mv);
    mv->kind = (uint32_t)DH_MOVE_JOINT;
    return DH_OK;
}

dh_status dh_move_joint_step_f32(dh_move_f32 *mv, float dt, float *q, dh_move_report_f32 *rep)
{
    float c;
    dh_status st;
    DH_ASSERT(mv != NULL && q != NULL && rep != NULL);
    st = move_period_ok(mv, (uint32_t)DH_MOVE_JOINT, dt);
    if (st != DH_OK) return st;
    c = move_next_clock(mv, dt);
    st = dh_joint_move_eval_f32(mv->prof, mv->n, mv->q0, mv->q1, c, q, mv->ws[0], mv->ws[1]);
    if (st != DH_OK) return st;
    mv->clock = c;
    rep->clock = c;
    rep->feed = 1.0f;
    rep->held = 0;
    rep->done = !(c < mv->dur);
    return DH_OK;
}

dh_status dh_move_path_jerk_f32(dh_move_f32 *mv, const dh_path_f32 *p, const dh_cart_limits_f32 *lim,
                                const dh_cart_jerk_f32 *jerk)
{
    dh_status st;
    DH_ASSERT(mv != NULL && p != NULL && lim != NULL);
    mv->kind = (uint32_t)DH_MOVE_NONE;
    st = dh_path_move_jerk_f32(&mv->prof[0], p, lim, jerk);
    if (st != DH_OK) return st;
    if (!dh_motion_path_ok_f32_(p)) return DH_ERR_ARG;
    mv->path = *p;
    mv->n = 0u;
    mv->dur = mv->prof[0].T;
    mv->clock = 0.0f;
    move_feed_init(mv);
    mv->kind = (uint32_t)DH_MOVE_PATH;
    return DH_OK;
}

dh_status dh_move_path_f32(dh_move_f32 *mv, const dh_path_f32 *p, const dh_cart_limits_f32 *lim)
{
    DH_ASSERT(mv != NULL && p != NULL && lim != NULL);
    return dh_move_path_jerk_f32(mv, p, lim, NULL);
}

/* dh_path_move_eval_f32's frame at the clock, from its two steps (the
 * profile's s, then the path at s): one call level less on the stack */
dh_status dh_move_target_f32(const dh_move_f32 *mv, dh_mat4_f32 *T)
{
    float s, sd, sdd;
    DH_ASSERT(mv != NULL && T != NULL);
    if (!move_holds(mv, (uint32_t)DH_MOVE_PATH) || !dh_motion_path_ok_f32_(&mv->path)) return DH_ERR_ARG;
    if (dh_profile_eval_f32(&mv->prof[0], mv->clock, &s, &sd, &sdd) != DH_OK || !dh_isfinite_f32(s)) return DH_ERR_ARG;
    return dh_path_eval_f32(&mv->path, s, T);
}

/* The largest rise of r this period within the acceleration A of s:
 * k = s'(clock) / dt > 0, p >= 0 the largest s'' near the clock. The
 * target's second difference over the period is at most
 * k (r' - r) + p r'^2, held to A: the root of
 * p x^2 + (k + 2 p r) x - (A - p r^2) = 0 in its cancellation-free form. */
float dh_motion_feed_rise_f32_(float k, float p, float A, float r)
{
    const float b = k + 2.0f * p * r, c = A - p * r * r;
    float den;
    if (!(c > 0.0f)) return 0.0f;
    den = b + dh_sqrt_f32(b * b + 4.0f * p * c);
    return (den > 0.0f) ? 2.0f * c / den : 0.0f;
}

/* The largest rise (*up) and fall (*dn) of r this period that keep the
 * target's acceleration along the path within the profile's peak A (docs/
 * design.md, "Motion"): s'' is bounded over the last and the next period
 * by its values at their ends and at the clock (the trapezoid's s'' falls
 * monotonically; the profile's first and last phases, clamped to 0 by the
 * evaluation, are taken at +-A), widened by j dt for the seven-phase
 * profile (its s'' is j-Lipschitz). 1 (no bound) where s' is 0. */
static void move_feed_bounds(const dh_move_f32 *mv, float dt, float *up, float *dn)
{
    const dh_profile_f32 *pr = &mv->prof[0];
    const float A = pr->a, r = mv->feed, tb = mv->clock - r * dt, tf = mv->clock + dt;
    float s, sd, a0, hi, lo, k;
    *up = 1.0f;
    *dn = 1.0f;
    (void)dh_profile_eval_f32(pr, tb, &s, &sd, &hi);
    lo = hi;
    if (!(tb > 0.0f)) hi = A;
    (void)dh_profile_eval_f32(pr, tf, &s, &sd, &a0);
    if (!(tf < mv->dur)) a0 = -A;
    if (a0 > hi) hi = a0;
    if (a0 < lo) lo = a0;
    (void)dh_profile_eval_f32(pr, mv->clock, &s, &sd, &a0);
    if (a0 > hi) hi = a0;
    if (a0 < lo) lo = a0;
    /* the seven-phase s'' is not monotone but j-Lipschitz: within j dt of
     * the value at the clock over the period's clocks (0 for the trapezoid) */
    hi += pr->j * dt;
    lo -= pr->j * dt;
    if (!(sd > 0.0f)) return;
    k = sd / dt;
    *up = dh_motion_feed_rise_f32_(k, (hi > 0.0f) ? hi : 0.0f, A, r);
    *dn = (A + ((lo < 0.0f) ? lo : 0.0f) * r * r) / k;
    if (!(*dn > 0.0f)) *dn = 0.0f;
}

/* r after a period whose tracker state was OK (ok 1) or not, and the
 * ceiling's update (the file's comment) */
static DH_NOINLINE float move_feed_next(dh_move_f32 *mv, float dt, int ok)
{
    float up, dn;
    if (ok != 0 && mv->feed >= 1.0f && mv->fcap >= 1.0f) {
        /* at full feed and ceiling: r stays 1, no bound needed */
        mv->lag = 0u;
        return 1.0f;
    }
    move_feed_bounds(mv, dt, &up, &dn);
    return dh_motion_feed_goal_f32_(mv, dt, ok, up, dn);
}

float dh_motion_feed_goal_f32_(dh_move_f32 *mv, float dt, int ok, float up, float dn)
{
    const float r = mv->feed;
    float goal, c = mv->fcap;
    if (ok != 0) {
        if (r >= c) c += MOVE_CREEP * c * dt;
        if (c > 1.0f) c = 1.0f;
        goal = c;
        mv->lag = 0u;
    } else {
        if (mv->lag == 0u && mv->clock > 0.0f && r > 0.0f) c = MOVE_CEIL * r;
        goal = 0.0f;
        mv->lag = 1u;
    }
    mv->fcap = c;
    if (goal > r) return (r + up < goal) ? r + up : goal;
    return (r - dn > goal) ? r - dn : goal;
}

dh_status dh_move_advance_f32(dh_move_f32 *mv, float dt, dh_track_state state, dh_move_report_f32 *rep)
{
    dh_status st;
    int done = 0, ok = 0, held = 1;
    DH_ASSERT(mv != NULL && rep != NULL);
    st = move_period_ok(mv, (uint32_t)DH_MOVE_PATH, dt);
    if (st != DH_OK) return st;
    if (state != DH_TRACK_OK && state != DH_TRACK_LAGGING && state != DH_TRACK_UNREACHABLE) return DH_ERR_ARG;
    if (state == DH_TRACK_OK) {
        ok = 1;
        held = 0;
    }
    if (ok != 0 && !(mv->clock < mv->dur)) {
        done = 1;
    } else {
        mv->feed = move_feed_next(mv, dt, ok);
        mv->clock = move_next_clock(mv, mv->feed * dt);
    }
    rep->clock = mv->clock;
    rep->feed = mv->feed;
    rep->held = held;
    rep->done = done;
    return DH_OK;
}
