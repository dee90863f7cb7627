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
 * for bit). A joint move's clock advances every period. A path move's
 * clock advances only when the tracker reported OK at the frame of the
 * current clock: the target is then never more than one period of the
 * move beyond the last frame reached, and a tool away from the path's
 * start is first brought onto it (the clock holds at 0).
 */
#include "dhmath/motion.h"
#include "../internal/dh_build.h"
#include "../internal/dh_floatops.h"
#include "motion_impl.h"

/* 1 - 2^-10: the joint move's planning margin under the caller's limits */
#define MOVE_MARGIN 0.9990234375f

/* 1 when mv holds a move of the given kind with a consistent clock */
static int move_holds(const dh_move_f32 *mv, uint32_t kind)
{
    if (mv->kind != kind) return 0;
    if (!dh_isfinite_f32(mv->dur) || !(mv->dur >= 0.0f)) return 0;
    if (!(mv->clock >= 0.0f) || !(mv->clock <= mv->dur)) return 0;
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

dh_status dh_move_advance_f32(dh_move_f32 *mv, float dt, dh_track_state state, dh_move_report_f32 *rep)
{
    dh_status st;
    int done = 0, held = 0;
    DH_ASSERT(mv != NULL && rep != NULL);
    st = move_period_ok(mv, (uint32_t)DH_MOVE_PATH, dt);
    if (st != DH_OK) return st;
    if (state != DH_TRACK_OK && state != DH_TRACK_LAGGING && state != DH_TRACK_UNREACHABLE) return DH_ERR_ARG;
    if (state != DH_TRACK_OK)
        held = 1;
    else if (mv->clock < mv->dur)
        mv->clock = move_next_clock(mv, dt);
    else
        done = 1;
    rep->clock = mv->clock;
    rep->held = held;
    rep->done = done;
    return DH_OK;
}
