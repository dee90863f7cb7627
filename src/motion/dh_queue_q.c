/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_queue_q.c - the fixed-point queue of moves, the twin of dh_queue.c:
 * a ring of moves in the caller's array, run one control period at a
 * time, with stop and resume (contract in motion.h, method and proof in
 * docs/design.md, "Fixed-point queue"). Integer only: no float, no 64-bit
 * division (bit-serial quotients).
 *
 * Ring. items[head] is the running move; appending writes
 * items[(head + count) mod cap] and never overwrites a queued move. A
 * path's profile of s is planned when it is appended (as
 * dh_path_move_jerk_q plans it: dh_motion_path_rates_q_, dh_motion_profile_q_)
 * into its item and copied into qu->mv when it starts; a joint move is
 * planned when it starts, from the last joint command or the tracker's
 * configuration, as dh_move_joint_q plans it (each joint's profile in
 * place by dh_motion_profile_q_, then stretched to the longest): one call
 * level less than through dh_move_joint_q, as the path's frame is
 * evaluated here by dh_path_eval_q rather than through dh_move_target_q
 * (the 256 B stack guard).
 *
 * Time warp. Every move runs its own plan X(tau) at a clock tau with
 * d tau / dt = r in [0, 1]: a path move's r is dh_move_advance_q's feed
 * override (which falls while the tracker lags), a joint move's r is the
 * queue's own (1 but during a stop or a resume). The commanded velocity
 * is X' r (within the plan's, so within its limits) and the acceleration
 * X'' r^2 + X' r', which r keeps within the limit A by changing each
 * period by at most the bound of dh_motion_feed_bound_q_ (dh_move_q.c:
 * the plan's s'' sampled over the last and the next period, taken along
 * the travel). A joint move takes the least bound over its joints, each
 * with its own A = amax_i - floor(amax_i / 1024), the planning's limit.
 * A stop drives r to 0 (a path move: its feed override as if the tracker
 * lagged), a resume back up: the move stays on its own path and ends at
 * its exact end.
 */
#include <string.h>

#include "dhmath/motion.h"
#include "../internal/dh_build.h"
#include "motion_impl.h"
#include "blend_q_impl.h"

/* the longest control period (us) */
#define QUEUEQ_DT_MAX 1000000u

/* the index of the k-th queued move (k <= count < 2 cap) */
static uint32_t queueq_index(const dh_queue_q *qu, uint32_t k)
{
    const uint32_t i = qu->head + k;
    return (i >= qu->cap) ? i - qu->cap : i;
}

/* floor(x dt / 10^6) for dt <= 10^6: one quotient bit per step (below 2^31) */
static uint32_t queueq_per(uint32_t x, uint32_t dt)
{
    uint64_t n = (uint64_t)x * dt, q = 0u;
    uint32_t bit = 52u;
    while (bit > 0u) {
        bit--;
        if ((n >> bit) >= QUEUEQ_DT_MAX) {
            n -= (uint64_t)QUEUEQ_DT_MAX << bit;
            q |= (uint64_t)1 << bit;
        }
    }
    return (uint32_t)q;
}

/* the free item (not a blended line until its function says so), or
 * NULL when the queue is full */
static dh_queue_item_q *queueq_free(dh_queue_q *qu)
{
    dh_queue_item_q *it = NULL;
    if (qu->count < qu->cap) {
        it = &qu->items[queueq_index(qu, qu->count)];
        it->blend = 0u;
    }
    return it;
}

dh_status dh_queue_init_q(dh_queue_q *qu, dh_queue_item_q *items, uint32_t cap)
{
    DH_ASSERT(qu != NULL && items != NULL);
    if (cap == 0u) return DH_ERR_ARG;
    (void)memset(qu, 0, sizeof *qu);
    qu->items = items;
    qu->cap = cap;
    qu->phase = (uint32_t)DH_QUEUE_RUN;
    qu->hold = (uint32_t)DH_MOVE_NONE;
    qu->r = DH_Q30_ONE;
    qu->mv.kind = (uint32_t)DH_MOVE_NONE;
    return DH_OK;
}

dh_status dh_queue_add_joint_q(dh_queue_q *qu, uint32_t n, const int32_t *q1, const int32_t *vmax,
                               const int32_t *amax, const int32_t *jmax)
{
    dh_queue_item_q *it;
    uint32_t i;
    DH_ASSERT(qu != NULL && q1 != NULL && vmax != NULL && amax != NULL);
    if (n == 0u || n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    for (i = 0u; i < n; i++)
        if (vmax[i] <= 0 || amax[i] <= 0 || (jmax != NULL && jmax[i] <= 0)) return DH_ERR_ARG;
    it = queueq_free(qu);
    if (it == NULL) return DH_ERR_LIMIT;
    for (i = 0u; i < n; i++) {
        it->q1[i] = q1[i];
        it->vmax[i] = vmax[i];
        it->amax[i] = amax[i];
        it->jmax[i] = (jmax != NULL) ? jmax[i] : 0;
    }
    it->n = n;
    it->kind = (uint32_t)DH_MOVE_JOINT;
    qu->count++;
    return DH_OK;
}

/* the planned path move in the free item it (status st of its planning)
 * appended; called after the planning, not above it (the 256 B guard) */
static dh_status queueq_path_item(dh_queue_q *qu, dh_queue_item_q *it, const dh_path_q *p, const dh_cart_limits_q *lim,
                                  dh_status st)
{
    if (st != DH_OK) return st;
    it->e = dh_motion_path_e_q_(&it->prof);
    it->path = *p;
    it->lim = *lim;
    it->n = 0u;
    it->kind = (uint32_t)DH_MOVE_PATH;
    qu->count++;
    return DH_OK;
}

/* Each append plans as dh_path_move_jerk_q does, its two steps called
 * from here, into the free item */
dh_status dh_queue_add_path_q(dh_queue_q *qu, const dh_path_q *p, const dh_cart_limits_q *lim)
{
    dh_queue_item_q *it;
    dh_status st;
    DH_ASSERT(qu != NULL && p != NULL && lim != NULL);
    it = queueq_free(qu);
    if (it == NULL) return DH_ERR_LIMIT;
    st = dh_motion_path_rates_q_(&it->prof, p, lim, NULL);
    if (st == DH_OK) st = dh_motion_profile_q_(&it->prof);
    return queueq_path_item(qu, it, p, lim, st);
}

dh_status dh_queue_add_path_jerk_q(dh_queue_q *qu, const dh_path_q *p, const dh_cart_limits_q *lim,
                                   const dh_cart_jerk_q *jerk)
{
    dh_queue_item_q *it;
    dh_status st;
    DH_ASSERT(qu != NULL && p != NULL && lim != NULL);
    it = queueq_free(qu);
    if (it == NULL) return DH_ERR_LIMIT;
    st = dh_motion_path_rates_q_(&it->prof, p, lim, jerk);
    if (st == DH_OK) st = dh_motion_profile_q_(&it->prof);
    return queueq_path_item(qu, it, p, lim, st);
}

/* the checks of dh_queue_add_path_blend_q's path and limits, in the
 * order of its statuses */
static dh_status queueq_line_ok(const dh_path_q *p, const dh_cart_limits_q *lim)
{
    if (lim->vmax <= 0 || lim->amax <= 0 || lim->wmax <= 0 || lim->wdmax <= 0) return DH_ERR_ARG;
    if (!dh_motion_path_ok_q_(p) || p->length < 0 || p->angle < 0) return DH_ERR_ARG;
    if (p->kind == (uint32_t)DH_PATH_ARC && p->radius <= 0) return DH_ERR_ARG;
    return DH_OK;
}

/* The queued move before the free item when the line p (within lim) can
 * blend with it: a blended line with a radius, not started, with the same
 * limits, ending where p starts; NULL when not. Its radius then in
 * qu->bs[0].dev (dh_blend_corner_q_ reads it there). */
static DH_NOINLINE dh_queue_item_q *queueq_blend_prev(dh_queue_q *qu, const dh_path_q *p, const dh_cart_limits_q *lim)
{
    dh_queue_item_q *pv;
    if (qu->count == 0u || (qu->count == 1u && qu->started != 0u)) return NULL;
    pv = &qu->items[queueq_index(qu, qu->count - 1u)];
    if (pv->kind != (uint32_t)DH_MOVE_PATH || pv->blend == 0u || pv->radius <= 0) return NULL;
    if (memcmp(&pv->lim, lim, sizeof *lim) != 0 || memcmp(&pv->path.B, &p->A, sizeof p->A) != 0) return NULL;
    qu->bs[0].dev = pv->radius;
    return pv;
}

/* 1 when the corner of dh_blend_corner_q_ (in qu->bs) has an overlap:
 * then qu->bs hold the tails' durations of the two lines' scalings with
 * it (pv's start tail as planned, it's end tail at rest) */
static int queueq_blend_tails(dh_queue_q *qu, const dh_queue_item_q *pv)
{
    qu->bs[0].dur[0] = pv->seg.dur[0];
    qu->bs[1].dur[4] = 0u;
    return qu->bs[0].dur[4] > 0u;
}

/* the scalings with the corner (qu->bs, qu->bz) into the items pv and it
 * (pv's dev the corner's, in bs[0].dev) */
static DH_NOINLINE void queueq_blend_keep(dh_queue_q *qu, dh_queue_item_q *pv, dh_queue_item_q *it)
{
    pv->seg = qu->bs[0];
    pv->prof = qu->bz[0];
    it->seg = qu->bs[1];
    it->seg.dev = 0;
    it->prof = qu->bz[1];
}

/* the free item it = the line p within lim and radius, its scaling to be
 * planned at rest at both ends (the corner before it after) */
static DH_NOINLINE void queueq_blend_item(dh_queue_item_q *it, const dh_path_q *p, const dh_cart_limits_q *lim,
                                          dh_qpos radius)
{
    it->path = *p;
    it->lim = *lim;
    it->seg.dur[0] = 0u;
    it->seg.dur[4] = 0u;
    it->seg.t0 = 0u;
    it->seg.dev = 0;
    it->radius = radius;
    it->e = 0u;
    it->n = 0u;
}

dh_status dh_queue_add_path_blend_q(dh_queue_q *qu, const dh_path_q *p, const dh_cart_limits_q *lim,
                                    dh_qpos radius)
{
    dh_queue_item_q *it, *pv;
    dh_status st;
    DH_ASSERT(qu != NULL && p != NULL && lim != NULL);
    it = queueq_free(qu);
    if (it == NULL) return DH_ERR_LIMIT;
    if (radius < 0) return DH_ERR_ARG;
    st = queueq_line_ok(p, lim);
    if (st != DH_OK) return st;
    queueq_blend_item(it, p, lim, radius);
    if (dh_blend_queue_line_q_(&it->seg, &it->path, &it->lim, &it->prof) == 0) return DH_ERR_OVERFLOW;
    /* the corner with the move before, planned from this frame (the 256 B
     * guard): kept when both lines' scalings with it fit */
    pv = queueq_blend_prev(qu, &it->path, &it->lim);
    if (pv != NULL) {
        dh_blend_rates_q_(&pv->path, &it->lim, &qu->bs[0]);
        dh_blend_rates_q_(&it->path, &it->lim, &qu->bs[1]);
        dh_blend_corner_q_(&pv->path, &it->path, &it->lim, qu->bs);
        if (queueq_blend_tails(qu, pv) != 0 &&
            (dh_blend_queue_line_q_(&qu->bs[0], &pv->path, &pv->lim, &qu->bz[0]) &
             dh_blend_queue_line_q_(&qu->bs[1], &it->path, &it->lim, &qu->bz[1])) != 0)
            queueq_blend_keep(qu, pv, it);
    }
    it->kind = (uint32_t)DH_MOVE_PATH;
    it->blend = 1u;
    qu->count++;
    return DH_OK;
}

/* the running move's clock and warp at its start (dh_move_q.c's rule) */
static void queueq_clock0(dh_queue_q *qu, uint32_t dur)
{
    dh_motion_start_q_(&qu->mv, dur);
    qu->r = DH_Q30_ONE;
    qu->rfrac = 0u;
    qu->started = 1u;
}

/* the head path move started: its planned profile and path into mv */
static DH_NOINLINE void queueq_start_path(dh_queue_q *qu, const dh_queue_item_q *it)
{
    dh_move_q *const mv = &qu->mv;
    mv->prof[0] = it->prof;
    mv->e = it->e;
    mv->path = it->path;
    mv->n = 0u;
    mv->kind = (uint32_t)DH_MOVE_PATH;
    qu->bl = it->blend;
    if (it->blend != 0u) {
        qu->bg = it->seg;
        queueq_clock0(qu, it->seg.T);
    } else {
        queueq_clock0(qu, it->prof.T);
    }
}

/* where the head joint move it starts: the last joint command, or after a
 * path move the tracker's configuration once every 2 |v_i| <=
 * floor(floor(amax_i dt / 10^6) dt / 10^6); NULL while it waits */
static DH_NOINLINE const int32_t *queueq_joint_from(const dh_queue_q *qu, const dh_track_q *t, const dh_queue_item_q *it)
{
    uint32_t i;
    if (qu->hold == (uint32_t)DH_MOVE_JOINT) return qu->hq;
    if (qu->hold == (uint32_t)DH_MOVE_PATH) {
        for (i = 0u; i < it->n; i++) {
            const int64_t v = t->v[i];
            const uint64_t m = (uint64_t)((v < 0) ? -v : v);
            if (2u * m > queueq_per(queueq_per((uint32_t)it->amax[i], t->dt_us), t->dt_us)) return NULL;
        }
    }
    return t->q;
}

/* The head joint move's distances from q0 and its lowered limits into
 * mv's profiles, as dh_move_joint_q fills them: DH_ERR_OVERFLOW for a
 * distance beyond int32. mv then holds no move, and a hold command that
 * was its frame is dropped. */
static DH_NOINLINE dh_status queueq_joint_fill(dh_queue_q *qu, const int32_t *q0, const dh_queue_item_q *it)
{
    dh_move_q *const mv = &qu->mv;
    dh_status st = DH_OK;
    uint32_t i;
    mv->kind = (uint32_t)DH_MOVE_NONE;
    if (qu->hold == (uint32_t)DH_MOVE_PATH) qu->hold = (uint32_t)DH_MOVE_NONE;
    for (i = 0u; i < it->n; i++) {
        const int64_t d = (int64_t)it->q1[i] - q0[i];
        if (d > INT32_MAX || d < INT32_MIN) st = DH_ERR_OVERFLOW;
        mv->q0[i] = q0[i];
        mv->q1[i] = it->q1[i];
        mv->prof[i].d = (int32_t)d;
        mv->prof[i].v = it->vmax[i] - (int32_t)((uint32_t)it->vmax[i] >> 10);
        mv->prof[i].a = it->amax[i] - (int32_t)((uint32_t)it->amax[i] >> 10);
        mv->prof[i].j = it->jmax[i];
    }
    mv->n = it->n;
    return st;
}

/* The filled joint move planned as dh_move_joint_q plans it (each
 * joint's profile in place, then all stretched to the longest), and
 * started (a frame of its own: the 256 B guard) */
static DH_NOINLINE dh_status queueq_joint_plan(dh_queue_q *qu)
{
    dh_move_q *const mv = &qu->mv;
    uint32_t i, T = 0u;
    dh_status st = DH_OK;
    for (i = 0u; i < mv->n && st == DH_OK; i++) {
        st = dh_motion_profile_q_(&mv->prof[i]);
        if (st == DH_OK && mv->prof[i].T > T) T = mv->prof[i].T;
    }
    for (i = 0u; i < mv->n && st == DH_OK; i++) st = dh_profile_stretch_q(&mv->prof[i], T);
    if (st != DH_OK) return st;
    mv->e = 0u;
    mv->kind = (uint32_t)DH_MOVE_JOINT;
    queueq_clock0(qu, T);
    qu->sync = 1u;
    return DH_OK;
}

/* A joint move's time warp r after a stop or a resume: towards 0 while
 * braking, else towards 1, by at most the least bound over its joints
 * (the file comment) */
static DH_NOINLINE void queueq_warp(dh_queue_q *qu, uint32_t dt)
{
    const dh_move_q *mv = &qu->mv;
    const dh_queue_item_q *it = &qu->items[qu->head];
    const dh_q30 r = qu->r;
    const int rise = qu->phase != (uint32_t)DH_QUEUE_BRAKE;
    int32_t x = DH_Q30_ONE;
    uint32_t i;
    for (i = 0u; i < mv->n; i++) {
        int32_t b, A;
        if (mv->prof[i].d == 0) continue;
        A = it->amax[i] - (int32_t)((uint32_t)it->amax[i] >> 10);
        b = dh_motion_feed_bound_q_(&mv->prof[i], A, mv->clock, r, dt, rise);
        if (b < x) x = b;
    }
    if (rise == 0)
        qu->r = (r > x) ? r - x : 0;
    else
        qu->r = (DH_Q30_ONE - r > x) ? r + x : DH_Q30_ONE;
}

/* One period of the running joint move: its clock advanced by r dt (the
 * fraction of a us carried; held while stopped) and q = the move there,
 * each joint from its nearer end as dh_move_joint_step_q evaluates it */
static DH_NOINLINE void queueq_joint_step(dh_queue_q *qu, uint32_t dt, int32_t *q)
{
    dh_move_q *const mv = &qu->mv;
    const dh_q30 r = (qu->phase == (uint32_t)DH_QUEUE_STOPPED) ? 0 : qu->r;
    const uint64_t adv = (uint64_t)(uint32_t)r * dt + qu->rfrac;
    uint64_t c = (uint64_t)mv->clock + (adv >> 30);
    uint32_t i;
    qu->rfrac = (uint32_t)(adv & 0x3FFFFFFFu);
    if (c > mv->dur) c = mv->dur;
    for (i = 0u; i < mv->n; i++) {
        const dh_profile_q *pr = &mv->prof[i];
        int32_t p;
        /* mv->ps the evaluation's scratch (a small frame) */
        (void)dh_profile_eval_q(pr, (uint32_t)c, &mv->ps[0], &mv->ps[1], &mv->ps[2]);
        p = mv->ps[0];
        q[i] = ((c >= pr->T || c > pr->T - c) && pr->d != 0) ? (int32_t)((int64_t)mv->q1[i] - ((int64_t)pr->d - p))
                                                         : (int32_t)((int64_t)mv->q0[i] + p);
        qu->hq[i] = q[i];
    }
    mv->clock = (uint32_t)c;
}

/* s of the path move in mv at its clock, Q2.30; -1 for a profile out of
 * range (dh_queue_target_q refuses it) */
static DH_NOINLINE int32_t queueq_s(dh_move_q *mv)
{
    uint32_t s;
    if (mv->e > 30u || mv->clock > mv->dur) return -1;
    if (dh_profile_eval_q(&mv->prof[0], mv->clock, &mv->ps[0], &mv->ps[1], &mv->ps[2]) != DH_OK) return -1;
    if (mv->ps[0] < 0 || (uint32_t)mv->ps[0] > (1u << mv->e)) return -1;
    s = (uint32_t)mv->ps[0] << (30u - mv->e);
    return (int32_t)s;
}

/* 1 when the blended line in mv runs in its end tail (clock c beyond
 * T - tb): with the next line, queued (the corner was planned with it) */
static int queueq_overlap(const dh_queue_q *qu)
{
    const dh_blend_seg_q *g = &qu->bg;
    return g->dur[4] > 0u && qu->mv.clock > g->T - g->dur[4] && qu->count >= 2u;
}

/* The frame of the blended line in mv in its overlap with the next line
 * (whose clock is c - (T - tb)): the superposition */
static DH_NOINLINE dh_status queueq_blend_frame(const dh_queue_q *qu, dh_frame_q *T)
{
    const dh_blend_seg_q *g = &qu->bg;
    const dh_queue_item_q *nx = &qu->items[queueq_index(qu, 1u)];
    const dh_q30 s1 = dh_blend_s_q_(g, qu->mv.clock);
    const dh_q30 s2 = dh_blend_s_q_(&nx->seg, qu->mv.clock - (g->T - g->dur[4]));
    int sat;
    dh_motion_point_q_(&qu->mv.path, s1, T->p);
    dh_motion_point_q_(&nx->path, s2, T->r[0]);
    sat = dh_blend_pos_q_(&nx->path, T);
    dh_blend_rot_q_(&qu->mv.path, &nx->path, s1, s2, T);
    return (sat != 0) ? DH_ERR_OVERFLOW : DH_OK;
}

dh_status dh_queue_target_q(dh_queue_q *qu, const dh_track_q *t, dh_queue_cmd_q *cmd)
{
    dh_status st;
    uint32_t kind;
    DH_ASSERT(qu != NULL && t != NULL && t->r != NULL && cmd != NULL);
    if (qu->pend != 0u || t->dt_us == 0u || t->dt_us > QUEUEQ_DT_MAX) return DH_ERR_ARG;
    if (qu->started == 0u && qu->count > 0u && qu->phase == (uint32_t)DH_QUEUE_RUN) {
        /* the head move started when it can (a joint move waits for rest) */
        const dh_queue_item_q *it = &qu->items[qu->head];
        if (it->kind == (uint32_t)DH_MOVE_PATH) {
            queueq_start_path(qu, it);
        } else {
            const int32_t *q0;
            if (it->n != t->r->n) return DH_ERR_ARG;
            q0 = queueq_joint_from(qu, t, it);
            if (q0 != NULL) {
                st = queueq_joint_fill(qu, q0, it);
                if (st == DH_OK) st = queueq_joint_plan(qu);
                if (st != DH_OK) return st;
            }
        }
    }
    kind = (qu->started != 0u) ? qu->mv.kind : qu->hold;
    if (kind == (uint32_t)DH_MOVE_PATH) {
        if (qu->bl != 0u && queueq_overlap(qu)) {
            st = queueq_blend_frame(qu, &cmd->T);
        } else {
            /* a blended line alone at its s (its last frame once done) */
            const int32_t s = (qu->bl != 0u) ? dh_blend_s_q_(&qu->bg, qu->mv.clock) : queueq_s(&qu->mv);
            if (s < 0) return DH_ERR_ARG;
            st = dh_path_eval_q(&qu->mv.path, s, &cmd->T);
        }
        if (st != DH_OK) return st;
        cmd->sync = qu->sync;
        if (qu->sync != 0u) (void)memcpy(cmd->q, qu->hq, sizeof cmd->q);
        qu->sync = 0u;
    } else if (kind == (uint32_t)DH_MOVE_JOINT) {
        if (qu->started != 0u) {
            if (qu->phase == (uint32_t)DH_QUEUE_BRAKE ||
                (qu->phase == (uint32_t)DH_QUEUE_RUN && qu->r < DH_Q30_ONE))
                queueq_warp(qu, t->dt_us);
            queueq_joint_step(qu, t->dt_us, cmd->q);
        } else {
            (void)memcpy(cmd->q, qu->hq, sizeof cmd->q);
        }
        cmd->sync = 0u;
    } else {
        cmd->sync = 0u;
    }
    cmd->kind = kind;
    qu->dt = t->dt_us;
    qu->pend = 1u;
    return DH_OK;
}

/* 1 when the running move is at rest where it is: at its start, its end,
 * or with its clock held (r 0) */
static int queueq_at_rest(const dh_queue_q *qu)
{
    const dh_move_q *mv = &qu->mv;
    const dh_q30 r = (mv->kind == (uint32_t)DH_MOVE_PATH) ? mv->feed : qu->r;
    return mv->clock == 0u || mv->clock >= mv->dur || r == 0;
}

/* 1 when the braking move's next command is this period's: its warp at
 * 0, or a path move's clock at its end already at the start of this
 * period (c0; its frame then stays B until the tracker is OK there) */
static int queueq_still(const dh_queue_q *qu, uint32_t c0)
{
    const dh_move_q *mv = &qu->mv;
    if (mv->kind == (uint32_t)DH_MOVE_PATH) return mv->feed == 0 || c0 >= mv->dur;
    return qu->r == 0;
}

/* 1 when this period of the blended line in mv reaches into one of its
 * tails (an overlap): the window [c0 - r dt - 2, c0 + dt + 2] of the
 * bound (dh_motion_feed_bound_q_) meets [0, dur0) or (T - dur4, T] of a
 * tail that is not 0; r then holds. Not at the line's end (c0 >= T):
 * its tracker decides there, as for any path move. */
static int queueq_blend_hold(const dh_queue_q *qu, uint32_t c0)
{
    const dh_blend_seg_q *g = &qu->bg;
    const int64_t back = (int64_t)(((uint64_t)(uint32_t)qu->mv.feed * qu->dt) >> 30);
    if (c0 >= g->T) return 0;
    if (g->dur[0] > 0u && (int64_t)c0 - back - 2 < (int64_t)g->dur[0]) return 1;
    return g->dur[4] > 0u && (int64_t)c0 + (int64_t)qu->dt + 2 > (int64_t)g->T - (int64_t)g->dur[4];
}

/* One held period of the blended line in mv: its clock advanced by r dt
 * (the fraction carried), capped at T when it ends at rest; 1 when it
 * passed T with an end tail: the hand-over (queueq_handover) */
static int queueq_blend_tick(dh_queue_q *qu)
{
    dh_move_q *const mv = &qu->mv;
    const uint64_t adv = (uint64_t)(uint32_t)mv->feed * qu->dt + mv->cfrac;
    const uint64_t c = (uint64_t)mv->clock + (adv >> 30);
    mv->cfrac = (uint32_t)(adv & 0x3FFFFFFFu);
    if (c >= mv->dur && qu->bg.dur[4] > 0u) {
        mv->clock = (uint32_t)c;
        return 1;
    }
    if (c >= mv->dur) {
        mv->clock = mv->dur;
        mv->cfrac = 0u;
    } else {
        mv->clock = (uint32_t)c;
    }
    return 0;
}

/* The blended line in mv passed its end in the overlap: removed from the
 * queue (seq + 1) and the next line runs on from its clock
 * c - (T - tb) = c - T + tb, with the same warp, ceiling and fraction */
static DH_NOINLINE void queueq_handover(dh_queue_q *qu)
{
    dh_move_q *const mv = &qu->mv;
    const dh_queue_item_q *nx;
    const uint32_t c = mv->clock - qu->bg.T + qu->bg.dur[4];
    qu->head = queueq_index(qu, 1u);
    qu->count--;
    qu->seq++;
    nx = &qu->items[qu->head];
    qu->bg = nx->seg;
    mv->prof[0] = nx->prof;
    mv->path = nx->path;
    mv->dur = nx->seg.T;
    mv->clock = (c < mv->dur) ? c : mv->dur;
}

/* the running move completed: removed from the queue, its end held */
static void queueq_done(dh_queue_q *qu)
{
    qu->hold = qu->mv.kind;
    qu->started = 0u;
    qu->head = queueq_index(qu, 1u);
    qu->count--;
    qu->seq++;
    if (qu->phase == (uint32_t)DH_QUEUE_BRAKE) qu->phase = (uint32_t)DH_QUEUE_STOPPED;
}

/* What the running move is this period (queueq_advance_end) */
enum { QUEUEQ_IDLE = 0, QUEUEQ_OVERLAP = 1, QUEUEQ_PATH = 2, QUEUEQ_JOINT = 3 };

/* The period's end after the path move's advance, if any (mode
 * QUEUEQ_PATH: dh_move_advance_q has run unless stopped): the report, the
 * overlap's tick and hand-over, the move's completion and the brake's
 * rest. Called last by dh_queue_advance_q, apart from the path move's
 * advance, so that the deepest call of a period has the public call's
 * small frame above it. */
static DH_NOINLINE void queueq_advance_end(dh_queue_q *qu, dh_track_state state, dh_queue_report_q *rep, uint32_t c0,
                                           int mode)
{
    dh_move_q *const mv = &qu->mv;
    const int stopped = qu->phase == (uint32_t)DH_QUEUE_STOPPED;
    dh_q30 feed = mv->feed;
    int done = 0, held = state != DH_TRACK_OK || stopped, over = 0;
    if (mode == QUEUEQ_OVERLAP) {
        /* in an overlap: r holds (stopped: the clock too) */
        if (!stopped) over = queueq_blend_tick(qu);
    } else if (mode == QUEUEQ_PATH) {
        if (!stopped) done = qu->mrep.done;
    } else if (mode == QUEUEQ_JOINT) {
        done = mv->clock >= mv->dur;
        held = stopped;
        feed = qu->r;
    } else {
        held = 1;   /* nothing running: the command at rest */
        feed = DH_Q30_ONE;
    }
    qu->pend = 0u;
    rep->feed = feed;
    rep->seq = qu->seq;
    rep->clock = (qu->started != 0u) ? mv->clock : 0u;
    if (over != 0) queueq_handover(qu);
    if (done != 0) queueq_done(qu);
    if ((done | over) == 0 && qu->phase == (uint32_t)DH_QUEUE_BRAKE && qu->started != 0u && queueq_still(qu, c0))
        qu->phase = (uint32_t)DH_QUEUE_STOPPED;
    rep->held = held;
    rep->done = done | over;
    rep->last = qu->count == 0u;
    rep->stopped = qu->phase == (uint32_t)DH_QUEUE_STOPPED;
}

/* the running move's mode this period, its clock at c0 */
static DH_NOINLINE int queueq_mode(const dh_queue_q *qu, uint32_t c0)
{
    int mode = QUEUEQ_IDLE;
    if (qu->started != 0u) {
        mode = QUEUEQ_JOINT;
        if (qu->mv.kind == (uint32_t)DH_MOVE_PATH) {
            mode = (qu->bl != 0u && queueq_blend_hold(qu, c0)) ? QUEUEQ_OVERLAP : QUEUEQ_PATH;
        }
    }
    return mode;
}

dh_status dh_queue_advance_q(dh_queue_q *qu, dh_track_state state, dh_queue_report_q *rep)
{
    uint32_t c0;
    int mode;
    DH_ASSERT(qu != NULL && rep != NULL);
    if (qu->pend == 0u) return DH_ERR_ARG;
    if (state != DH_TRACK_OK && state != DH_TRACK_LAGGING && state != DH_TRACK_UNREACHABLE) return DH_ERR_ARG;
    c0 = qu->mv.clock;
    mode = queueq_mode(qu, c0);
    if (mode == QUEUEQ_PATH && qu->phase != (uint32_t)DH_QUEUE_STOPPED) {
        /* braking: the feed override falls as if the tracker lagged, but
         * at the end (s' = 0) the tracker's state decides done */
        const int brake = qu->phase == (uint32_t)DH_QUEUE_BRAKE && qu->mv.clock < qu->mv.dur;
        const dh_status st = dh_move_advance_q(&qu->mv, qu->dt, brake ? DH_TRACK_LAGGING : state, &qu->mrep);
        if (st != DH_OK) return st;
    }
    queueq_advance_end(qu, state, rep, c0, mode);
    return DH_OK;
}

dh_status dh_queue_stop_q(dh_queue_q *qu)
{
    DH_ASSERT(qu != NULL);
    if (qu->pend != 0u) return DH_ERR_ARG;
    if (qu->phase != (uint32_t)DH_QUEUE_RUN) return DH_OK;
    if (qu->started != 0u && qu->mv.kind == (uint32_t)DH_MOVE_PATH) qu->fcap = qu->mv.fcap;
    qu->phase = (qu->started != 0u && !queueq_at_rest(qu)) ? (uint32_t)DH_QUEUE_BRAKE : (uint32_t)DH_QUEUE_STOPPED;
    return DH_OK;
}

dh_status dh_queue_resume_q(dh_queue_q *qu)
{
    DH_ASSERT(qu != NULL);
    if (qu->pend != 0u) return DH_ERR_ARG;
    if (qu->phase == (uint32_t)DH_QUEUE_RUN) return DH_OK;
    if (qu->started != 0u && qu->mv.kind == (uint32_t)DH_MOVE_PATH) {
        qu->mv.fcap = qu->fcap;
        qu->mv.lag = 0u;
    }
    qu->phase = (uint32_t)DH_QUEUE_RUN;
    return DH_OK;
}
