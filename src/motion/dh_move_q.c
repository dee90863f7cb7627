/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_move_q.c - the fixed-point move executor, the twin of dh_move.c: a
 * joint move sampled once per control period, and a Cartesian path move
 * whose frames the caller's tracker (dh_track_step_q) follows. Integer
 * only: no float, no 64-bit division (bit-serial quotients).
 *
 * Clock: whole microseconds from 0 to the move's duration, capped there,
 * plus a Q2.30 fraction of a microsecond that carries the rest of r dt
 * from period to period (r the feed override, Q2.30 in [0, 1]); at r == 1
 * the clock advances by dt exactly and the fraction is unchanged, so a
 * move the tracker follows runs its profile sample for sample.
 *
 * Feed override and its ceiling as the float twin (dh_move.c): r falls
 * while the tracker is not OK and rises while it is, each period by at
 * most what keeps the commanded acceleration of s within the profile's
 * peak A, with the profile's s'' bounded over the last and the next
 * period (low and high values lo, p; dh_motion_feed_bound_q_, which the
 * fixed queue, dh_queue_q.c, uses for its joint moves too). The rise is
 * the root x of
 * p x^2 + (k + 2 p r) x = A - p r^2 (k = s' / dt) in the float twin; here
 * its lower bound (A - p r^2) / (k + 2 p r + p), which meets the
 * inequality for x <= 1 (p x^2 <= p x) without a square root. The fall is
 * (A + lo r^2) / k as in the float twin. Every quotient is rounded towards
 * the smaller change (k up, numerators down) and taken bit-serially.
 */
#include <string.h>

#include "dhmath/motion.h"
#include "../internal/dh_build.h"
#include "../internal/dh_qmath.h"
#include "motion_impl.h"

/* the ceiling of r after an episode of not-OK periods begun at r: 7/8 (Q2.30) */
#define MOVEQ_CEIL 0x38000000
/* 2^32 2 / 10^6, rounded: the ceiling's relative rise, 2 per second */
#define MOVEQ_CREEP 8590
/* the longest control period (us) */
#define MOVEQ_DT_MAX 1000000u

/* 1 when mv holds a move of the given kind with a consistent clock and
 * override (a path move's path is checked where it is read: by
 * dh_path_eval_q in dh_move_target_q, once per period) */
static int moveq_holds(const dh_move_q *mv, uint32_t kind)
{
    if (mv->kind != kind) return 0;
    if (mv->dur > (uint32_t)INT32_MAX || mv->clock > mv->dur || mv->cfrac >= (uint32_t)DH_Q30_ONE) return 0;
    if (mv->feed < 0 || mv->feed > DH_Q30_ONE || mv->fcap < 0 || mv->fcap > DH_Q30_ONE) return 0;
    if (kind == (uint32_t)DH_MOVE_PATH) return mv->e <= 30u;
    return mv->n >= 1u && mv->n <= (uint32_t)DH_MAX_JOINTS;
}

/* the period's status: DH_ERR_ARG for dt outside 1..10^6 us or an mv that
 * holds no move of the kind */
static dh_status moveq_period_ok(const dh_move_q *mv, uint32_t kind, uint32_t dt)
{
    if (!moveq_holds(mv, kind)) return DH_ERR_ARG;
    return (dt >= 1u && dt <= MOVEQ_DT_MAX) ? DH_OK : DH_ERR_ARG;
}

/* the clock, its fraction, override and ceiling at the start of a move
 * (the fixed queue's moves start so too) */
void dh_motion_start_q_(dh_move_q *mv, uint32_t dur)
{
    mv->dur = dur;
    mv->clock = 0u;
    mv->cfrac = 0u;
    mv->feed = DH_Q30_ONE;
    mv->fcap = DH_Q30_ONE;
    mv->lag = 0u;
    mv->ps[0] = 0;
    mv->ps[1] = 0;
    mv->ps[2] = 0;
}

/* the clock advanced by r dt (r Q2.30 in [0, 1]) with its fraction,
 * capped at the duration */
static void moveq_tick(dh_move_q *mv, dh_q30 r, uint32_t dt)
{
    const uint64_t adv = (uint64_t)(uint32_t)r * dt + mv->cfrac;
    const uint64_t c = (uint64_t)mv->clock + (adv >> 30);
    if (c >= mv->dur) {
        mv->clock = mv->dur;
        mv->cfrac = 0u;
    } else {
        mv->clock = (uint32_t)c;
        mv->cfrac = (uint32_t)(adv & 0x3FFFFFFFu);
    }
}

/* mv->prof[i] = joint i's distance q1 - q0 (its stored q0, q1) and its
 * limits vmax and amax lowered by 2^-10, jmax as given (NULL: 0, the
 * trapezoid), checked in the order of dh_joint_move_q: DH_ERR_OVERFLOW
 * for a distance beyond int32, DH_ERR_ARG for a limit <= 0 */
static DH_NOINLINE dh_status moveq_joint_fill(dh_move_q *mv, const int32_t *vmax, const int32_t *amax,
                                              const int32_t *jmax)
{
    uint32_t i;
    for (i = 0u; i < mv->n; i++) {
        dh_profile_q *const pr = &mv->prof[i];
        const int64_t d = (int64_t)mv->q1[i] - mv->q0[i];
        if (d > INT32_MAX || d < INT32_MIN) return DH_ERR_OVERFLOW;
        if (vmax[i] <= 0 || amax[i] <= 0 || (jmax != NULL && jmax[i] <= 0)) return DH_ERR_ARG;
        pr->d = (int32_t)d;
        pr->v = vmax[i] - (vmax[i] >> 10);
        pr->a = amax[i] - (amax[i] >> 10);
        pr->j = (jmax != NULL) ? jmax[i] : 0;
    }
    return DH_OK;
}

/* The joint move is planned here as dh_joint_move_q plans it (each
 * joint's time-optimal profile in place, dh_motion_profile_q_, then every
 * profile stretched to the longest), on its stored ends and the lowered
 * limits: one call level less than through dh_joint_move_q (the 256 B
 * guard). */
dh_status dh_move_joint_q(dh_move_q *mv, uint32_t n, const int32_t *q0, const int32_t *q1, const int32_t *vmax,
                          const int32_t *amax, const int32_t *jmax)
{
    uint32_t i, T = 0u;
    dh_status st;
    DH_ASSERT(mv != NULL && q0 != NULL && q1 != NULL && vmax != NULL && amax != NULL);
    mv->kind = (uint32_t)DH_MOVE_NONE;
    if (n == 0u || n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    /* index by index, so q0 and q1 may alias mv->q0 and mv->q1 */
    for (i = 0u; i < n; i++) {
        const int32_t x = q0[i], y = q1[i];
        mv->q0[i] = x;
        mv->q1[i] = y;
    }
    mv->n = n;
    st = moveq_joint_fill(mv, vmax, amax, jmax);
    for (i = 0u; i < n && st == DH_OK; i++) {
        st = dh_motion_profile_q_(&mv->prof[i]);
        if (st == DH_OK && mv->prof[i].T > T) T = mv->prof[i].T;
    }
    for (i = 0u; i < n && st == DH_OK; i++) st = dh_profile_stretch_q(&mv->prof[i], T);
    if (st != DH_OK) return st;
    mv->e = 0u;
    dh_motion_start_q_(mv, T);
    mv->kind = (uint32_t)DH_MOVE_JOINT;
    return DH_OK;
}

/* each joint's profile evaluated here, from the nearer end as
 * dh_joint_move_eval_q does (one call level less: the 256 B guard) */
dh_status dh_move_joint_step_q(dh_move_q *mv, uint32_t dt, int32_t *q, dh_move_report_q *rep)
{
    int32_t p, qd, qdd;
    uint64_t c;
    uint32_t i;
    dh_status st;
    DH_ASSERT(mv != NULL && q != NULL && rep != NULL);
    st = moveq_period_ok(mv, (uint32_t)DH_MOVE_JOINT, dt);
    for (i = 0u; i < mv->n && st == DH_OK; i++) st = dh_profile_eval_q(&mv->prof[i], 0u, &p, &qd, &qdd);
    if (st != DH_OK) return DH_ERR_ARG;
    c = (uint64_t)mv->clock + dt;
    if (c > mv->dur) c = mv->dur;
    for (i = 0u; i < mv->n; i++) {
        const dh_profile_q *pr = &mv->prof[i];
        (void)dh_profile_eval_q(pr, (uint32_t)c, &p, &qd, &qdd);
        q[i] = ((c >= pr->T || c > pr->T - c) && pr->d != 0) ? (int32_t)((int64_t)mv->q1[i] - ((int64_t)pr->d - p))
                                                         : (int32_t)((int64_t)mv->q0[i] + p);
    }
    mv->clock = (uint32_t)c;
    rep->clock = mv->clock;
    rep->feed = DH_Q30_ONE;
    rep->held = 0;
    rep->done = mv->clock >= mv->dur;
    return DH_OK;
}

/* the path move of the profile planned into mv->prof[0] (its status st),
 * started */
static dh_status moveq_path_start(dh_move_q *mv, const dh_path_q *p, dh_status st)
{
    if (st != DH_OK) return st;
    mv->e = dh_motion_path_e_q_(&mv->prof[0]);
    mv->path = *p;
    mv->n = 0u;
    dh_motion_start_q_(mv, mv->prof[0].T);
    mv->kind = (uint32_t)DH_MOVE_PATH;
    return DH_OK;
}

/* The path moves plan as dh_path_move_jerk_q does, its two steps called
 * from here (the 256 B guard) */
dh_status dh_move_path_q(dh_move_q *mv, const dh_path_q *p, const dh_cart_limits_q *lim)
{
    dh_status st;
    DH_ASSERT(mv != NULL && p != NULL && lim != NULL);
    mv->kind = (uint32_t)DH_MOVE_NONE;
    st = dh_motion_path_rates_q_(&mv->prof[0], p, lim, NULL);
    if (st == DH_OK) st = dh_motion_profile_q_(&mv->prof[0]);
    return moveq_path_start(mv, p, st);
}

dh_status dh_move_path_jerk_q(dh_move_q *mv, const dh_path_q *p, const dh_cart_limits_q *lim,
                              const dh_cart_jerk_q *jerk)
{
    dh_status st;
    DH_ASSERT(mv != NULL && p != NULL && lim != NULL);
    mv->kind = (uint32_t)DH_MOVE_NONE;
    st = dh_motion_path_rates_q_(&mv->prof[0], p, lim, jerk);
    if (st == DH_OK) st = dh_motion_profile_q_(&mv->prof[0]);
    return moveq_path_start(mv, p, st);
}

dh_status dh_move_target_q(const dh_move_q *mv, dh_frame_q *T)
{
    int32_t s = 0, sd, sdd;
    DH_ASSERT(mv != NULL && T != NULL);
    if (!moveq_holds(mv, (uint32_t)DH_MOVE_PATH)) return DH_ERR_ARG;
    if (dh_profile_eval_q(&mv->prof[0], mv->clock, &s, &sd, &sdd) != DH_OK) return DH_ERR_ARG;
    if (s < 0 || (uint32_t)s > (1u << mv->e)) return DH_ERR_ARG;
    return dh_path_eval_q(&mv->path, (dh_q30)((uint32_t)s << (30u - mv->e)), T);
}

/* min(floor(n 2^30 / d), 2^30) or up to 2^-29 of it less, for d > 0 and
 * n >= 0 below 2^63: d scaled below 2^31 (rounded up, n down, so the
 * quotient never exceeds the exact one), then one quotient bit per step in
 * 32-bit words (no division) */
static uint32_t moveq_ratio(uint64_t n, uint64_t d)
{
    static const unsigned char sh[4] = { 16u, 8u, 4u, 2u };
    uint64_t nn = n, de = d;
    uint32_t r, dd, q = 0u, k;
    if (nn >= de) return (uint32_t)DH_Q30_ONE;
    for (k = 0u; k < 4u; k++) {
        if ((de >> (31u + sh[k])) != 0u) {
            nn >>= sh[k];
            de = (de >> sh[k]) + 1u;
        }
    }
    while ((de >> 31) != 0u) {
        nn >>= 1;
        de = (de >> 1) + 1u;
    }
    r = (uint32_t)nn;
    dd = (uint32_t)de;
    for (k = 0u; k < 30u; k++) {
        r <<= 1;
        q <<= 1;
        if (r >= dd) {
            r -= dd;
            q |= 1u;
        }
    }
    return q;
}

/* x r^2 (LSB/s^2, x >= 0 below 2^31, r Q2.30 in [0, 1]), rounded up */
static uint64_t moveq_r2(int64_t x, dh_q30 r)
{
    const uint64_t xr = ((uint64_t)x * (uint32_t)r + 0x3FFFFFFFu) >> 30;
    return (xr * (uint32_t)r + 0x3FFFFFFFu) >> 30;
}

/* s'' of the trapezoid pr along the travel at time t (us; before 0 it
 * counts as +a, after T as -a), its acceleration phases ta long */
static int32_t moveq_acc(const dh_profile_q *pr, uint32_t ta, int64_t t)
{
    if (t < (int64_t)ta) return pr->a;
    if (t > (int64_t)pr->T - (int64_t)ta) return -pr->a;
    return 0;
}

/* 2^40 / 10^6, rounded up */
#define MOVEQ_US2S40 1099512u

/* The largest rise (rise 1) or fall (rise 0) of r this period that keeps
 * the commanded acceleration of the profile pr (along the travel) within
 * A (file comment), r the warp of the last period; 2^30 (no bound) where
 * s' is 0 (at rest at the clock). Over the last period and the next,
 * [clock - r dt, clock + dt], s'' lies between hi and lo: a trapezoid's
 * s'' falls monotonically (+a, 0, -a), so there its values 2 us before
 * and after the window (the margin covers the rounding of the phase times
 * ta). A seven-phase profile's s'' is continuous, >= 0 in the first half,
 * <= 0 in the second, 0 in the cruise, and changes at most at j, so over
 * the window it is within [-j w, a] in the first half's acceleration,
 * [-a, j w] in the second half's deceleration and [-j w, j w] in the
 * cruise, w the longer side of the window plus 4 us (the rounding of ta
 * and of the clock), j w / 10^6 rounded up by 4 LSB/s^2 (a multiply by
 * 2^40 / 10^6 after a shift: within 2). Another profile kind takes +-a.
 * s' at the clock is bounded above by a (u + 1 us) (|s''| <= a and s' = 0
 * at the ends; u the time to the nearer end) and by the peak v:
 * K = 10^6 s' (LSB us/s^2, below 2^62), k = K / dt, and the quotients of
 * the file comment multiplied through by dt (no quotient for k). A larger
 * K and hi and a smaller lo only lower the bounds. */
DH_NOINLINE int32_t dh_motion_feed_bound_q_(const dh_profile_q *pr, int32_t A, uint32_t clock, dh_q30 r, uint32_t dt,
                                            int rise)
{
    const uint64_t back = ((uint64_t)(uint32_t)r * dt) >> 30;
    const uint32_t ta = (uint32_t)(((uint64_t)(uint32_t)pr->xa * pr->T) >> 30);
    const uint32_t u = (clock < pr->T) ? ((clock < pr->T - clock) ? clock : pr->T - clock) : 0u;
    const uint32_t u1 = u + 1u;
    const uint64_t ku = (uint64_t)pr->a * u1;
    uint64_t K = (uint64_t)pr->v * MOVEQ_DT_MAX, num, den;
    int64_t hi = pr->a, lo = -pr->a;
    if (u == 0u) return DH_Q30_ONE;
    if (ku < K) K = ku;
    if (pr->kind == (uint32_t)DH_PROFILE_TRAP) {
        hi = moveq_acc(pr, ta, (int64_t)clock - (int64_t)back - 2);
        lo = moveq_acc(pr, ta, (int64_t)clock + dt + 2);
    } else if (pr->kind == (uint32_t)DH_PROFILE_SCURVE) {
        const uint32_t w = ((back > dt) ? (uint32_t)back : dt) + 4u;
        const uint64_t jw = (uint64_t)(uint32_t)pr->j * w;
        const int64_t d = (int64_t)(((jw >> 20) * MOVEQ_US2S40) >> 20) + 4;
        if (u >= ta || clock > pr->T - clock) hi = (d < pr->a) ? d : pr->a;
        if (u >= ta || clock <= pr->T - clock) lo = (d < pr->a) ? -d : -(int64_t)pr->a;
    } else {
        /* the quintic: +-a */
    }
    if (rise != 0) {
        /* (A - p r^2) dt / (K + (2 p r + p) dt), p = max(hi, 0), the denominator rounded up */
        const uint64_t p = (hi > 0) ? (uint64_t)hi : 0u;
        num = moveq_r2((int64_t)p, r);
        den = K + ((((p * (uint32_t)r) >> 29) + 1u) + p) * dt;
    } else {
        /* (A + lo r^2) dt / K */
        num = (lo < 0) ? moveq_r2(-lo, r) : 0u;
        den = K;
    }
    return (int32_t)(((int64_t)A > (int64_t)num) ? moveq_ratio(((uint64_t)A - num) * dt, den) : 0u);
}

/* the goal of r after a period whose tracker state was OK (ok 1) or not,
 * and the ceiling's update (dh_move.c's method) */
static DH_NOINLINE dh_q30 moveq_feed_goal(dh_move_q *mv, uint32_t dt, int ok)
{
    const dh_q30 r = mv->feed;
    dh_q30 goal, c = mv->fcap;
    if (ok != 0) {
        if (r >= c) {
            const uint64_t inc = ((((uint64_t)(uint32_t)c * dt) >> 10) * MOVEQ_CREEP) >> 22;
            c = (inc + (uint32_t)c >= (uint64_t)DH_Q30_ONE) ? DH_Q30_ONE : (dh_q30)(c + (int32_t)inc);
        }
        goal = c;
        mv->lag = 0u;
    } else {
        if (mv->lag == 0u && mv->clock > 0u && r > 0) c = (dh_q30)dh_q_rshr(dh_q_mul64(MOVEQ_CEIL, r), 30u);
        goal = 0;
        mv->lag = 1u;
    }
    mv->fcap = c;
    return goal;
}

dh_status dh_move_advance_q(dh_move_q *mv, uint32_t dt, dh_track_state state, dh_move_report_q *rep)
{
    dh_status st;
    int done = 0, ok = 0;
    DH_ASSERT(mv != NULL && rep != NULL);
    st = moveq_period_ok(mv, (uint32_t)DH_MOVE_PATH, dt);
    if (st != DH_OK) return st;
    if (state != DH_TRACK_OK && state != DH_TRACK_LAGGING && state != DH_TRACK_UNREACHABLE) return DH_ERR_ARG;
    ok = state == DH_TRACK_OK;
    if (ok != 0 && mv->clock >= mv->dur) {
        done = 1;
    } else if (ok != 0 && mv->feed >= DH_Q30_ONE && mv->fcap >= DH_Q30_ONE) {
        mv->lag = 0u;   /* at full feed and ceiling: r stays 1, no bound needed */
        moveq_tick(mv, DH_Q30_ONE, dt);
    } else {
        /* the goal, the bound of the change towards it and r's update
         * called from here, one level down (the 256 B guard) */
        const dh_q30 goal = moveq_feed_goal(mv, dt, ok), r = mv->feed;
        const int32_t x = dh_motion_feed_bound_q_(&mv->prof[0], mv->prof[0].a, mv->clock, r, dt, goal > r);
        if (goal > r)
            mv->feed = ((int64_t)r + x < goal) ? r + x : goal;
        else
            mv->feed = ((int64_t)r - x > goal) ? r - x : goal;
        moveq_tick(mv, mv->feed, dt);
    }
    rep->clock = mv->clock;
    rep->feed = mv->feed;
    rep->held = !ok;
    rep->done = done;
    return DH_OK;
}
