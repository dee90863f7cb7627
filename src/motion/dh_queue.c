/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_queue.c - a queue of moves in the caller's array, run one control
 * period at a time, with stop and resume (contract in motion.h, method in
 * docs/design.md, "Motion").
 *
 * Ring. items[head] is the running move; appending writes
 * items[(head + count) % cap] and never overwrites a queued move. A move
 * is planned when it starts (into qu->mv, which keeps the plan of the
 * last move after it completes, for the hold command below): a joint
 * move by dh_move_joint_f32 from the tracker's configuration, a path move
 * by dh_move_path_f32, whose s runs from s0 (0, or where a stop left it)
 * to 1 along a trapezoid of s.
 *
 * Rest between moves. Every move is rest to rest. A joint move starts
 * only when the tracker's last velocity is within amax dt / 2 per joint,
 * so its first step is within amax dt^2 of the last one; until then the
 * last plan's command at rest is repeated (the path's frame, or the
 * tracker's own configuration after a joint move), which brings the
 * tracker to rest within its own bounds.
 *
 * Brake. Each coordinate (a joint, or s of a path) brakes from its
 * velocity v and acceleration a (taken along the travel, v >= 0) in three
 * phases: jerk -j until the acceleration is -ap, -ap held, jerk +j back
 * to 0 exactly as the velocity reaches 0, where
 * ap = min(A, sqrt(j v + a^2 / 2)) is the least peak deceleration that
 * stops in time (the shortest stop within A and j). Without a jerk limit
 * the deceleration A is applied at once (v / A, distance v^2 / (2 A)).
 * The distance is at most the one the plan had left (the plan itself is
 * one way to stop within the same limits), and is capped there against
 * rounding, so a brake never passes the move's end.
 */
#include "dhmath/motion.h"
#include "../internal/dh_build.h"
#include "../internal/dh_floatops.h"
#include "motion_impl.h"

/* 1 - 2^-10: dh_move_joint_f32's planning margin */
#define QUEUE_MARGIN 0.9990234375f

/* what the pending period does (dh_queue_f32.pend - 1) */
#define QUEUE_HOLD 1u
#define QUEUE_JOINT 2u
#define QUEUE_PATH 3u
#define QUEUE_BJOINT 4u
#define QUEUE_BPATH 5u

/* dh_queue_f32.bmode: the running move's blended lines */
#define QB_NONE 0u  /* not blended (a plain path move, a joint move, or none) */
#define QB_ONE 1u   /* a blended line: bl[0] on the clock */
#define QB_TWO 2u   /* and the next line: bl[1] from bl[0].T - bl[0].tb1 on, at bo[1] while bl[1].T is 0 */
#define QB_NEXT 3u  /* the head line, not started, starts at s = bo[0] */

static float queue_abs(float x)
{
    return (x < 0.0f) ? -x : x;
}

/* 1 when every x[i] (i < n) is finite and > 0 */
static int queue_positive(const float *x, uint32_t n)
{
    uint32_t i;
    for (i = 0u; i < n; i++)
        if (!(x[i] > 0.0f)) return 0;
    return 1;
}

/* 1 when every x[i] (i < n) is finite */
static int queue_finite(const float *x, uint32_t n)
{
    uint32_t i;
    for (i = 0u; i < n; i++)
        if (!dh_isfinite_f32(x[i])) return 0;
    return 1;
}

/* the status of a joint move's values: NaN/Inf first, then the limits */
static dh_status queue_joint_args(uint32_t n, const float *q1, const float *vmax, const float *amax,
                                  const float *jmax)
{
    if (n == 0u || n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    if (!queue_finite(q1, n) || !queue_finite(vmax, n) || !queue_finite(amax, n)) return DH_ERR_NAN;
    if (jmax != NULL && !queue_finite(jmax, n)) return DH_ERR_NAN;
    if (!queue_positive(vmax, n) || !queue_positive(amax, n)) return DH_ERR_ARG;
    return (jmax == NULL || queue_positive(jmax, n)) ? DH_OK : DH_ERR_ARG;
}

static dh_queue_item_f32 *queue_slot(dh_queue_f32 *qu, uint32_t k)
{
    return &qu->items[(qu->head + k) % qu->cap];
}

dh_status dh_queue_init_f32(dh_queue_f32 *qu, dh_queue_item_f32 *items, uint32_t cap)
{
    DH_ASSERT(qu != NULL && items != NULL);
    if (cap == 0u) return DH_ERR_ARG;
    qu->items = items;
    qu->cap = cap;
    qu->head = 0u;
    qu->count = 0u;
    qu->seq = 0u;
    qu->phase = (uint32_t)DH_QUEUE_RUN;
    qu->started = 0u;
    qu->last = (uint32_t)DH_MOVE_NONE;
    qu->resume = 0u;
    qu->pend = 0u;
    qu->n = 0u;
    qu->mv.kind = (uint32_t)DH_MOVE_NONE;
    qu->mv.clock = 0.0f;
    qu->mv.dur = 0.0f;
    qu->mv.feed = 1.0f;
    qu->mv.fcap = 1.0f;
    qu->s0 = 0.0f;
    qu->vs = 0.0f;
    qu->as = 0.0f;
    qu->tb = 0.0f;
    qu->tbend = 0.0f;
    qu->dt = 0.0f;
    qu->next = 0.0f;
    qu->braked = 0u;
    qu->bmode = QB_NONE;
    qu->stopq = 0u;
    return DH_OK;
}

dh_status dh_queue_add_joint_f32(dh_queue_f32 *qu, uint32_t n, const float *q1, const float *vmax,
                                 const float *amax, const float *jmax)
{
    dh_queue_item_f32 *it;
    uint32_t i;
    dh_status st;
    DH_ASSERT(qu != NULL && q1 != NULL && vmax != NULL && amax != NULL);
    st = queue_joint_args(n, q1, vmax, amax, jmax);
    if (st != DH_OK) return st;
    if (qu->count >= qu->cap) return DH_ERR_LIMIT;
    it = queue_slot(qu, qu->count);
    for (i = 0u; i < n; i++) {
        it->q1[i] = q1[i];
        it->vmax[i] = vmax[i];
        it->amax[i] = amax[i];
        it->jmax[i] = (jmax != NULL) ? jmax[i] : 0.0f;
    }
    it->path.kind = (uint32_t)DH_PATH_LINE;
    it->path.length = 0.0f;
    it->radius = 0.0f;
    it->ctb = 0.0f;
    it->jerk = 0u;
    if (jmax != NULL) it->jerk = 1u;
    it->n = n;
    it->kind = (uint32_t)DH_MOVE_JOINT;
    qu->count++;
    return DH_OK;
}

/* the radius of the last queued move, and the corner of the last two
 * (dh_blend_corner_f32_, when both are path moves with equal limits)
 * into the first one's ctb, cb; 1 when both are jerk-limited blended
 * lines with equal jerk limits too (the caller plans that corner:
 * dh_blend_jcorner_f32_), else 0 */
static DH_NOINLINE int queue_add_corner(dh_queue_f32 *qu, float radius)
{
    dh_queue_item_f32 *i1, *i2;
    queue_slot(qu, qu->count - 1u)->radius = radius;
    if (qu->count < 2u) return 0;
    i1 = queue_slot(qu, qu->count - 2u);
    i2 = queue_slot(qu, qu->count - 1u);
    i1->ctb = 0.0f;
    i1->cb[0] = 0.0f;
    i1->cb[1] = 0.0f;
    if (i1->kind != (uint32_t)DH_MOVE_PATH || i2->kind != (uint32_t)DH_MOVE_PATH) return 0;
    if (!dh_feq_f32(i1->lim.vmax, i2->lim.vmax) || !dh_feq_f32(i1->lim.amax, i2->lim.amax) ||
        !dh_feq_f32(i1->lim.wmax, i2->lim.wmax) || !dh_feq_f32(i1->lim.wdmax, i2->lim.wdmax))
        return 0;
    if (i1->jerk == 2u && i2->jerk == 2u)
        return (dh_feq_f32(i1->jk.jmax, i2->jk.jmax) && dh_feq_f32(i1->jk.wjmax, i2->jk.wjmax)) ? 1 : 0;
    /* another jerk-limited path move's corners run at rest (the tails are trapezoids) */
    if (i1->jerk != 0u || i2->jerk != 0u) return 0;
    i1->ctb = dh_blend_corner_f32_(&i1->path, &i2->path, &i1->lim, i1->radius, i1->cb);
    return 0;
}

/* the radius's status */
static DH_NOINLINE dh_status queue_radius(float radius)
{
    if (!dh_isfinite_f32(radius)) return DH_ERR_NAN;
    return (radius < 0.0f) ? DH_ERR_ARG : DH_OK;
}

/* The rest of the checks of a path move with the profile prof (the
 * path, room in the queue) and its item (radius 0): the status, the move
 * queued on DH_OK */
static DH_NOINLINE dh_status queue_add_item(dh_queue_f32 *qu, const dh_path_f32 *p, const dh_cart_limits_f32 *lim,
                                            const dh_profile_f32 *prof)
{
    dh_queue_item_f32 *it;
    if (!dh_motion_path_ok_f32_(p)) return DH_ERR_ARG;
    if (qu->count >= qu->cap) return DH_ERR_LIMIT;
    it = queue_slot(qu, qu->count);
    it->path = *p;
    if (prof != &it->prof) it->prof = *prof;
    it->lim = *lim;
    dh_blend_rates_f32_(p, lim, it->rate);
    it->radius = 0.0f;
    it->ctb = 0.0f;
    it->jerk = 0u;
    if (prof->kind == (uint32_t)DH_PROFILE_SCURVE) it->jerk = 1u;
    it->n = 0u;
    it->kind = (uint32_t)DH_MOVE_PATH;
    qu->count++;
    return DH_OK;
}

/* A path move appended (the radius's checks, then dh_move_path_f32's:
 * its profile, in this frame only) */
static DH_NOINLINE dh_status queue_add_path(dh_queue_f32 *qu, const dh_path_f32 *p, const dh_cart_limits_f32 *lim,
                                            float radius)
{
    dh_profile_f32 prof;
    dh_status st = queue_radius(radius);
    if (st == DH_OK) st = dh_path_move_f32(&prof, p, lim);
    if (st == DH_OK) st = queue_add_item(qu, p, lim, &prof);
    return st;
}

/* The corner is planned here, apart from the checks' deeper calls. */
dh_status dh_queue_add_path_f32(dh_queue_f32 *qu, const dh_path_f32 *p, const dh_cart_limits_f32 *lim)
{
    dh_status st;
    DH_ASSERT(qu != NULL && p != NULL && lim != NULL);
    st = queue_add_path(qu, p, lim, 0.0f);
    if (st == DH_OK) (void)queue_add_corner(qu, 0.0f);
    return st;
}

dh_status dh_queue_add_path_blend_f32(dh_queue_f32 *qu, const dh_path_f32 *p, const dh_cart_limits_f32 *lim,
                                      float radius)
{
    dh_status st;
    DH_ASSERT(qu != NULL && p != NULL && lim != NULL);
    st = queue_add_path(qu, p, lim, radius);
    if (st == DH_OK) (void)queue_add_corner(qu, radius);
    return st;
}

/* The profile is planned straight into the free item (no profile on this
 * frame: dh_path_move_jerk_f32 fills the stack budget on Cortex-M0+ with
 * one small frame above it); the corner after it runs at rest (the
 * blends' tails are trapezoids). */
dh_status dh_queue_add_path_jerk_f32(dh_queue_f32 *qu, const dh_path_f32 *p, const dh_cart_limits_f32 *lim,
                                     const dh_cart_jerk_f32 *jerk)
{
    dh_queue_item_f32 *it;
    dh_status st;
    DH_ASSERT(qu != NULL && p != NULL && lim != NULL);
    if (qu->count >= qu->cap) return DH_ERR_LIMIT;
    it = queue_slot(qu, qu->count);
    st = dh_path_move_jerk_f32(&it->prof, p, lim, jerk);
    if (st == DH_OK) st = queue_add_item(qu, p, lim, &it->prof);
    if (st == DH_OK) (void)queue_add_corner(qu, 0.0f);
    return st;
}

/* the queued line it made a jerk-limited blended line within jerk: its
 * scaling at rest (dh_blend_jline_f32_) */
static DH_NOINLINE void queue_item_jline(dh_queue_item_f32 *it, const dh_cart_jerk_f32 *jerk)
{
    it->jerk = 2u;
    it->jk = *jerk;
    dh_blend_jline_f32_(&it->seg, &it->path, &it->lim, &it->jk, 1.0f);
}

/* The line's checks as dh_queue_add_path_jerk_f32's (its profile planned
 * into the free item, which holds no move then), then the line's
 * scaling at rest (dh_blend_jline_f32_) and its corner with the move
 * before it (queue_add_corner returns 1 when both are such lines): both
 * items' scalings planned again with it (dh_blend_jcorner_f32_, called
 * from here apart from the checks' deeper calls), its overlap into the
 * first one's ctb. */
dh_status dh_queue_add_path_blend_jerk_f32(dh_queue_f32 *qu, const dh_path_f32 *p, const dh_cart_limits_f32 *lim,
                                           const dh_cart_jerk_f32 *jerk, float radius)
{
    dh_queue_item_f32 *it;
    dh_status st;
    DH_ASSERT(qu != NULL && p != NULL && lim != NULL && jerk != NULL);
    if (qu->count >= qu->cap) return DH_ERR_LIMIT;
    st = queue_radius(radius);
    if (st == DH_OK && p->kind != (uint32_t)DH_PATH_LINE) st = DH_ERR_ARG;
    it = queue_slot(qu, qu->count);
    if (st == DH_OK) st = dh_path_move_jerk_f32(&it->prof, p, lim, jerk);
    if (st == DH_OK) st = queue_add_item(qu, p, lim, &it->prof);
    if (st == DH_OK) {
        queue_item_jline(it, jerk);
        if (queue_add_corner(qu, radius) != 0)
            queue_slot(qu, qu->count - 2u)->ctb =
                dh_blend_jcorner_f32_(queue_slot(qu, qu->count - 2u), queue_slot(qu, qu->count - 1u));
    }
    return st;
}

/* ---- brake of one coordinate ------------------------------------------ */

static DH_NOINLINE float queue_brake_dist(const dh_queue_f32 *qu, uint32_t i, float tau);

/* the brake of coordinate i from its start set by the caller in the
 * brake's fields, x = bq[i] (position), v = bv[i], a = ba[i] (signed),
 * within the deceleration A = bap[i] and jerk j = bj[i] (0: none), never
 * beyond end (ahead along the travel): those fields replaced by the
 * brake's; its duration */
static DH_NOINLINE float queue_brake_plan(dh_queue_f32 *qu, uint32_t i, float end)
{
    const float x = qu->bq[i], v = qu->bv[i], a = qu->ba[i], A = qu->bap[i], j = qu->bj[i];
    const float rem = (end > x) ? end - x : x - end;
    float s, vp, ap, pk, t1 = 0.0f, t2 = 0.0f, t3 = 0.0f, d = 0.0f;
    s = (v > 0.0f) ? 1.0f : ((v < 0.0f) ? -1.0f : 0.0f);
    vp = s * v;
    ap = s * a;
    pk = 0.0f;
    if (!dh_feq_f32(s, 0.0f) && A > 0.0f) {
        if (j > 0.0f) {
            float v1;
            pk = dh_sqrt_f32(j * vp + 0.5f * ap * ap);
            if (pk > A) pk = A;
            if (pk < -ap) pk = -ap; /* only by rounding: the plan never decelerates faster than it can stop */
            t1 = (ap + pk) / j;
            v1 = vp + ap * t1 - 0.5f * j * t1 * t1;
            t2 = (v1 - 0.5f * pk * pk / j) / pk;
            if (!(t2 > 0.0f)) t2 = 0.0f;
            t3 = pk / j;
        } else {
            pk = A;
            t2 = vp / A;
        }
    }
    qu->bq[i] = x;
    qu->bs[i] = s;
    qu->bv[i] = vp;
    qu->ba[i] = ap;
    qu->bap[i] = pk;
    qu->bj[i] = j;
    qu->bt[0][i] = t1;
    qu->bt[1][i] = t2;
    qu->bt[2][i] = t3;
    qu->bx[i] = 0.0f;
    qu->bend[i] = end;
    if (!dh_feq_f32(s, 0.0f)) {
        float e;
        d = t1 + t2 + t3;
        e = queue_brake_dist(qu, i, d);
        if (!(e >= 0.0f)) e = 0.0f;
        qu->bx[i] = (e < rem) ? e : rem;
    }
    return d;
}

/* distance of coordinate i's brake at time tau (>= 0), before the cap */
static DH_NOINLINE float queue_brake_dist(const dh_queue_f32 *qu, uint32_t i, float tau)
{
    const float j = qu->bj[i], pk = qu->bap[i];
    const float t1 = qu->bt[0][i], t2 = qu->bt[1][i], t3 = qu->bt[2][i];
    float x = 0.0f, v = qu->bv[i], a = qu->ba[i], u, r = tau;
    if (dh_feq_f32(qu->bs[i], 0.0f)) return 0.0f;
    /* phase 1: jerk -j from a to -pk */
    u = (r < t1) ? r : t1;
    x = v * u + 0.5f * a * u * u - j * u * u * u / 6.0f;
    if (r <= t1) return x;
    v = v + a * t1 - 0.5f * j * t1 * t1;
    r -= t1;
    /* phase 2: -pk */
    u = (r < t2) ? r : t2;
    x += v * u - 0.5f * pk * u * u;
    if (r <= t2) return x;
    v -= pk * t2;
    r -= t2;
    /* phase 3: jerk +j from -pk to 0 */
    u = (r < t3) ? r : t3;
    x += v * u - 0.5f * pk * u * u + j * u * u * u / 6.0f;
    return x;
}

/* coordinate i's position at brake time tau: within [0, bx] of the start
 * along the travel, bx exactly from the end of the brake on */
static DH_NOINLINE float queue_brake_at(const dh_queue_f32 *qu, uint32_t i, float tau)
{
    float x = qu->bx[i], q;
    if (tau < qu->tbend) {
        x = queue_brake_dist(qu, i, tau);
        if (!(x >= 0.0f)) x = 0.0f;
        if (x > qu->bx[i]) x = qu->bx[i];
    }
    q = qu->bq[i] + qu->bs[i] * x;
    /* the rounding of the sum never passes the end */
    if ((qu->bs[i] > 0.0f && q > qu->bend[i]) || (qu->bs[i] < 0.0f && q < qu->bend[i])) q = qu->bend[i];
    return q;
}

/* ---- the running move ----------------------------------------------- */

/* s of the path plan at clock c (s0 + the profile, 1 at the end of a plan
 * that moves), with its rate and acceleration */
static float queue_path_s(const dh_queue_f32 *qu, float c, float *sd, float *sdd)
{
    float p, s;
    (void)dh_profile_eval_f32(&qu->mv.prof[0], c, &p, sd, sdd);
    s = qu->s0 + p;
    if ((c >= qu->mv.dur && !dh_feq_f32(qu->mv.prof[0].d, 0.0f)) || s > 1.0f) s = 1.0f;
    return s;
}

/* s where the path move is now: on its brake after a stop, else at its clock */
static DH_NOINLINE float queue_path_now(const dh_queue_f32 *qu)
{
    float sd, sdd;
    if (qu->braked != 0u) return queue_brake_at(qu, 0u, qu->tb);
    return queue_path_s(qu, qu->mv.clock, &sd, &sdd);
}

/* ---- blended lines ------------------------------------------------------ */

static const dh_queue_item_f32 *queue_at(const dh_queue_f32 *qu, uint32_t k)
{
    return &qu->items[(qu->head + k) % qu->cap];
}

/* the corner after queued move k (0: the running one), as planned when
 * the move after it was appended: its overlap tb (0: at rest; also when
 * k is the last queued) and the tails' accelerations b */
static float queue_corner(const dh_queue_f32 *qu, uint32_t k, float b[2])
{
    const dh_queue_item_f32 *i1 = queue_at(qu, k);
    b[0] = 0.0f;
    b[1] = 0.0f;
    if (k + 1u >= qu->count || !(i1->ctb > 0.0f)) return 0.0f;
    b[0] = i1->cb[0];
    b[1] = i1->cb[1];
    return i1->ctb;
}

/* the plan of the blended head line in mv (the executor's fields: path,
 * clock 0, duration, feed override at 1) */
static void queue_blend_mv(dh_queue_f32 *qu)
{
    qu->mv.path = queue_at(qu, 0u)->path;
    qu->mv.n = 0u;
    qu->mv.dur = qu->bl[0].T;
    qu->mv.clock = 0.0f;
    qu->mv.feed = 1.0f;
    qu->mv.fcap = 1.0f;
    qu->mv.lag = 0u;
    qu->mv.kind = (uint32_t)DH_MOVE_PATH;
}

/* g = no scaling (a line at rest) */
static void queue_seg_rest(dh_blend_seg_f32 *g)
{
    g->b0 = 0.0f;
    g->tb0 = 0.0f;
    g->b1 = 0.0f;
    g->tb1 = 0.0f;
    g->T = 0.0f;
    g->j = 0.0f;
}

/* the head line alone (QB_ONE) on bl[0] from s0 */
static void queue_blend_one(dh_queue_f32 *qu, float s0)
{
    queue_seg_rest(&qu->bl[1]);
    qu->bo[0] = s0;
    qu->bo[1] = 0.0f;
    qu->bmode = QB_ONE;
    queue_blend_mv(qu);
}

/* bl[i] = the jerk-limited scaling of queued line i from rest at s0: as
 * planned with its corners (its item's) from s0 = 0, its start at rest;
 * from s0 > 0 (where a stop left it) to its end at rest */
static DH_NOINLINE void queue_jline(dh_queue_f32 *qu, uint32_t i, float s0)
{
    const dh_queue_item_f32 *it = queue_at(qu, i);
    dh_blend_seg_f32 *g = &qu->bl[i];
    if (s0 > 0.0f) {
        dh_blend_jline_f32_(g, &it->path, &it->lim, &it->jk, 1.0f - s0);
    } else {
        *g = it->seg;
        g->tb0 = 0.0f;
    }
}

/* Plans the head line from rest at s = s0 with its corner after it
 * blended when it can be and its tail fits the distance left; 0 (nothing
 * planned) when s0 is 0 and the corner runs at rest: a plain path move. */
static DH_NOINLINE int queue_blend_from(dh_queue_f32 *qu, float s0)
{
    const dh_queue_item_f32 *it = queue_at(qu, 0u);
    dh_blend_seg_f32 *g = &qu->bl[0];
    float b[2];
    queue_seg_rest(g);
    g->tb1 = queue_corner(qu, 0u, b);
    g->b1 = b[0];
    if (!(s0 > 0.0f) && !(g->tb1 > 0.0f)) return 0;
    if (!dh_blend_seg_plan_f32_(g, it->rate, 1.0f - s0)) {
        /* the tail does not fit what a stop left of the line: at rest */
        queue_seg_rest(g);
        (void)dh_blend_seg_plan_f32_(g, it->rate, 1.0f - s0);
    }
    queue_blend_one(qu, s0);
    return 1;
}

/* Resumes two blended lines (in an overlap) from where their brake left
 * them: the first from s0 to its end at rest, the second held at s1 (it
 * starts from there when the first is done: QB_NEXT) */
static DH_NOINLINE void queue_blend_two(dh_queue_f32 *qu, float s0, float s1)
{
    const dh_queue_item_f32 *it = queue_at(qu, 0u);
    queue_seg_rest(&qu->bl[0]);
    if (it->jerk == 2u)
        dh_blend_jline_f32_(&qu->bl[0], &it->path, &it->lim, &it->jk, 1.0f - s0);
    else
        (void)dh_blend_seg_plan_f32_(&qu->bl[0], it->rate, 1.0f - s0);
    queue_seg_rest(&qu->bl[1]);
    qu->bo[0] = s0;
    qu->bo[1] = s1;
    queue_blend_mv(qu);
}

/* the next line joins in its overlap: its scaling, with its start tail
 * the corner's (the same as planned for the head's end tail) and its own
 * corner after it blended when it can be */
static DH_NOINLINE void queue_blend_next(dh_queue_f32 *qu)
{
    const dh_queue_item_f32 *it = queue_at(qu, 1u);
    dh_blend_seg_f32 *g = &qu->bl[1];
    float b[2];
    qu->bo[1] = 0.0f;
    qu->bmode = QB_TWO;
    if (it->jerk == 2u) {
        /* as planned with its corners; its end blended only when the next is queued */
        *g = it->seg;
        if (!(queue_corner(qu, 1u, b) > 0.0f)) g->tb1 = 0.0f;
        return;
    }
    (void)queue_corner(qu, 0u, b);
    g->b0 = b[1];
    g->tb0 = qu->bl[0].tb1;
    g->tb1 = queue_corner(qu, 1u, b);
    g->b1 = b[0];
    /* each tail within half the line: it fits */
    (void)dh_blend_seg_plan_f32_(g, it->rate, 1.0f);
    qu->bo[1] = 0.0f;
    qu->bmode = QB_TWO;
}

/* the s of the blended lines now: on their brake after a stop, else at
 * the clock (the next line's from its start on the head's clock) */
static DH_NOINLINE void queue_blend_now(const dh_queue_f32 *qu, float s[2])
{
    const dh_blend_seg_f32 *g = qu->bl;
    s[1] = 0.0f;
    if (qu->bmode == QB_NEXT) {
        s[0] = qu->bo[0];
    } else if (qu->braked != 0u) {
        s[0] = queue_brake_at(qu, 0u, qu->tb);
        if (qu->bmode == QB_TWO) s[1] = queue_brake_at(qu, 1u, qu->tb);
    } else {
        s[0] = dh_blend_seg_s_f32_(&g[0], qu->bo[0], qu->mv.clock);
        if (qu->bmode == QB_TWO) s[1] = dh_blend_seg_s_f32_(&g[1], qu->bo[1], qu->mv.clock - (g[0].T - g[0].tb1));
    }
}

/* s of the one blended line now (not QB_TWO) */
static DH_NOINLINE float queue_blend_s(const dh_queue_f32 *qu)
{
    float s[2];
    queue_blend_now(qu, s);
    return s[0];
}

/* the s of two blended lines now into T's column 3 (rows 0 and 1), for
 * dh_blend_pose_rot_f32_ */
static DH_NOINLINE void queue_blend_s2(const dh_queue_f32 *qu, dh_mat4_f32 *T)
{
    float s[2];
    queue_blend_now(qu, s);
    DH_M4(T, 0, 3) = s[0];
    DH_M4(T, 1, 3) = s[1];
}

/* The frame of blended lines this period (what): the next line joins
 * when the head's clock passed its overlap's start; T = the
 * superposition of two (its steps called from here) and 1, or 0 for one
 * line (the caller evaluates it at queue_blend_s) */
static DH_NOINLINE int queue_blend_pose(dh_queue_f32 *qu, uint32_t what, dh_mat4_f32 *T)
{
    if (what == QUEUE_PATH && qu->bmode == QB_ONE && qu->bl[0].tb1 > 0.0f &&
        qu->mv.clock > qu->bl[0].T - qu->bl[0].tb1)
        queue_blend_next(qu); /* the overlap begins */
    if (qu->bmode != QB_TWO) return 0;
    queue_blend_s2(qu, T);
    dh_blend_pose_rot_f32_(&queue_at(qu, 0u)->path, &queue_at(qu, 1u)->path, T);
    dh_blend_compose_f32_(&queue_at(qu, 1u)->path.qa, T);
    dh_blend_pose_pos_f32_(&queue_at(qu, 0u)->path, &queue_at(qu, 1u)->path, 1.0f - DH_M4(T, 0, 3), DH_M4(T, 1, 3), T);
    return 1;
}

/* The largest rise (*up) and fall (*dn) of the feed override this period
 * (dh_move.c's rule on the head line's scaling): 0 (r holds) when the
 * period's clocks reach into a tail (an overlap), 1 where s' is 0. */
static DH_NOINLINE void queue_blend_bounds(const dh_queue_f32 *qu, float *up, float *dn)
{
    const dh_blend_seg_f32 *g = &qu->bl[0];
    const float A = g->a, r = qu->mv.feed, c = qu->mv.clock, tb = c - r * qu->dt, tf = c + qu->dt;
    float sd, a0, hi, lo, k;
    *up = 0.0f;
    *dn = 0.0f;
    if ((qu->bmode == QB_TWO && qu->bl[1].T > 0.0f) || (g->tb0 > 0.0f && tb < g->tb0) ||
        (g->tb1 > 0.0f && tf > g->T - g->tb1))
        return;
    *up = 1.0f;
    *dn = 1.0f;
    (void)dh_blend_seg_rate_f32_(g, tb, &hi);
    lo = hi;
    if (!(tb > 0.0f)) hi = A;
    (void)dh_blend_seg_rate_f32_(g, tf, &a0);
    if (!(tf < g->T)) a0 = -A;
    if (a0 > hi) hi = a0;
    if (a0 < lo) lo = a0;
    sd = dh_blend_seg_rate_f32_(g, c, &a0);
    if (a0 > hi) hi = a0;
    if (a0 < lo) lo = a0;
    if (!(sd > 0.0f)) return;
    k = sd / qu->dt;
    *up = dh_motion_feed_rise_f32_(k, (hi > 0.0f) ? hi : 0.0f, A, r);
    *dn = (A + ((lo < 0.0f) ? lo : 0.0f) * r * r) / k;
    if (!(*dn > 0.0f)) *dn = 0.0f;
}

/* the head line is done and the next one runs on: it becomes the head's
 * scaling, on its own clock (the report's clock, the head's end, into
 * qu->next) */
static DH_NOINLINE void queue_blend_shift(dh_queue_f32 *qu, float clock)
{
    const float t01 = qu->bl[0].T - qu->bl[0].tb1;
    float c = clock - t01;
    qu->next = qu->bl[0].T;
    qu->bl[0] = qu->bl[1];
    qu->bo[0] = qu->bo[1];
    queue_seg_rest(&qu->bl[1]);
    qu->bo[1] = 0.0f;
    qu->bmode = QB_ONE;
    qu->mv.path = queue_at(qu, 1u)->path;
    qu->mv.dur = qu->bl[0].T;
    if (!(c > 0.0f)) c = 0.0f;
    qu->mv.clock = (c < qu->mv.dur) ? c : qu->mv.dur;
}

/* A period of blended lines (QB_ONE, QB_TWO): the feed override as
 * dh_move_advance_f32's, held in an overlap; the clock advances by r dt,
 * past the head's end only into the next line's overlap. 1 when the head
 * is done at rest (the tracker OK at its end), 2 when it is done and the
 * next line runs on (the head's clock past its end in their overlap). */
static DH_NOINLINE int queue_blend_period(dh_queue_f32 *qu, int ok)
{
    dh_move_f32 *mv = &qu->mv;
    const dh_blend_seg_f32 *g = qu->bl;
    float up = 0.0f, dn = 0.0f, c;
    if (!(g[0].tb1 > 0.0f) && !(mv->clock < mv->dur) && ok != 0) {
        qu->next = mv->clock;
        if (qu->bmode == QB_TWO) {
            /* the next line starts where it is held */
            qu->bo[0] = qu->bo[1];
            qu->bmode = QB_NEXT;
            mv->path = queue_at(qu, 1u)->path;
        }
        return 1;
    }
    if (ok != 0 && mv->feed >= 1.0f && mv->fcap >= 1.0f) {
        mv->lag = 0u;
    } else {
        queue_blend_bounds(qu, &up, &dn);
        mv->feed = dh_motion_feed_goal_f32_(mv, qu->dt, ok, up, dn);
    }
    c = mv->clock + mv->feed * qu->dt;
    if (qu->bmode == QB_TWO && g[1].T > 0.0f && !(c < mv->dur)) {
        queue_blend_shift(qu, c);
        return 2;
    }
    mv->clock = (c < mv->dur || g[0].tb1 > 0.0f) ? c : mv->dur;
    return 0;
}

/* 1 when the blended lines move (a stop brakes them) */
static int queue_blend_moving(const dh_queue_f32 *qu)
{
    const dh_blend_seg_f32 *g = qu->bl;
    if (qu->bmode == QB_TWO && g[1].T > 0.0f) return 1;
    return (qu->mv.clock > 0.0f || g[0].tb0 > 0.0f) && (qu->mv.clock < qu->mv.dur || g[0].tb1 > 0.0f);
}

/* bq[i] = s of each blended line i (two in an overlap) at its clock, for
 * queue_blend_state */
static DH_NOINLINE void queue_blend_pos(dh_queue_f32 *qu)
{
    uint32_t i;
    for (i = 0u; i < ((qu->bmode == QB_TWO) ? 2u : 1u); i++)
        qu->bq[i] = dh_blend_seg_s_f32_(&qu->bl[i], qu->bo[i],
                                        (i == 0u) ? qu->mv.clock : qu->mv.clock - (qu->bl[0].T - qu->bl[0].tb1));
}

/* the brake's start of blended line i (0: the head, 1: the next in an
 * overlap), into the brake's fields of coordinate i for queue_brake_plan
 * (bq = s: queue_blend_pos): bv, ba = its rate and acceleration under the
 * feed override r (s' r, s'' r^2), bap, bj = the deceleration and jerk
 * (0: none; jerk-limited lines), its tail's in an overlap, its line's
 * own alone */
static DH_NOINLINE void queue_blend_state(dh_queue_f32 *qu, uint32_t i)
{
    const dh_blend_seg_f32 *g = &qu->bl[i];
    const float r = qu->mv.feed, t = (i == 0u) ? qu->mv.clock : qu->mv.clock - (qu->bl[0].T - qu->bl[0].tb1);
    float sdd;
    qu->bv[i] = dh_blend_seg_rate_f32_(g, t, &sdd) * r;
    qu->ba[i] = sdd * r * r;
    qu->bap[i] = g->a;
    qu->bj[i] = g->j;
    if (i == 1u) {
        qu->bap[i] = g->b0;
        qu->bj[i] = g->k0;
    }
    if (i == 0u && g->tb1 > 0.0f && qu->bmode == QB_TWO) {
        qu->bap[i] = g->b1;
        qu->bj[i] = g->k1;
    }
}

/* 1 when the tracker is at rest for the joint move it: every
 * |v_i| <= amax_i dt / 2 */
static int queue_at_rest(const dh_track_f32 *t, const dh_queue_item_f32 *it, float dt)
{
    uint32_t i;
    for (i = 0u; i < it->n; i++)
        if (!(queue_abs(t->v[i]) <= 0.5f * it->amax[i] * dt)) return 0;
    return 1;
}

/* plans the path move it, from its profile of s (made when appended), or
 * from where a brake left it to 1 within that profile's rates of s */
static DH_NOINLINE dh_status queue_start_path(dh_queue_f32 *qu, const dh_queue_item_f32 *it)
{
    dh_move_f32 *mv = &qu->mv;
    dh_status st;
    float s0 = 0.0f;
    /* blended lines: resumed where the brake left them (one line, or two
     * in an overlap), started where the last resume held it, or starting
     * with a blended corner (0 from queue_blend_from: a plain move) */
    if (qu->braked != 0u && qu->bmode == QB_TWO) {
        queue_blend_two(qu, queue_brake_at(qu, 0u, qu->tbend), queue_brake_at(qu, 1u, qu->tbend));
        return DH_OK;
    }
    if (qu->braked != 0u && qu->bmode == QB_ONE) s0 = queue_brake_at(qu, 0u, qu->tbend);
    if (qu->bmode == QB_NEXT) s0 = qu->bo[0];
    if (!(qu->braked != 0u && qu->bmode == QB_NONE) && it->jerk == 2u) {
        queue_jline(qu, 0u, s0);
        queue_blend_one(qu, s0);
        return DH_OK;
    }
    if (!(qu->braked != 0u && qu->bmode == QB_NONE) && queue_blend_from(qu, s0) != 0) return DH_OK;
    s0 = 0.0f;
    qu->bmode = QB_NONE;
    if (qu->braked != 0u) s0 = qu->bq[0] + qu->bx[0];
    qu->vs = it->prof.v;
    qu->as = it->prof.a;
    mv->kind = (uint32_t)DH_MOVE_NONE;
    mv->prof[0] = it->prof;
    if (s0 > 0.0f && qu->vs > 0.0f && qu->as > 0.0f) {
        /* the rest of the path within the first plan's peaks of s (and its jerk) */
        if (it->jerk != 0u)
            st = dh_profile_scurve_f32(&mv->prof[0], (s0 < 1.0f) ? 1.0f - s0 : 0.0f, qu->vs, qu->as, it->prof.j);
        else
            st = dh_profile_trap_f32(&mv->prof[0], (s0 < 1.0f) ? 1.0f - s0 : 0.0f, qu->vs, qu->as);
        if (st != DH_OK) return st;
    } else {
        s0 = 0.0f;
    }
    qu->s0 = (s0 < 1.0f) ? s0 : 1.0f;
    mv->path = it->path;
    mv->n = 0u;
    mv->dur = mv->prof[0].T;
    mv->clock = 0.0f;
    mv->feed = 1.0f;
    mv->fcap = 1.0f;
    mv->lag = 0u;
    mv->kind = (uint32_t)DH_MOVE_PATH;
    return DH_OK;
}

/* the distance of joint i of the joint move it from q0 into *d (and the
 * endpoints into the plan); DH_ERR_OVERFLOW when it is not finite */
static DH_NOINLINE dh_status queue_joint_d(dh_move_f32 *mv, const dh_queue_item_f32 *it, uint32_t i, float q0, float *d)
{
    *d = it->q1[i] - q0;
    mv->q0[i] = q0;
    mv->q1[i] = it->q1[i];
    return dh_isfinite_f32(*d) ? DH_OK : DH_ERR_OVERFLOW;
}

/* the joint plan's end: every profile stretched to T (longest) */
static DH_NOINLINE void queue_joint_end(dh_queue_f32 *qu, uint32_t n, float T)
{
    qu->mv.n = n;
    qu->mv.dur = T;
    qu->mv.clock = 0.0f;
    qu->mv.feed = 1.0f;
    qu->mv.fcap = 1.0f;
    qu->mv.kind = (uint32_t)DH_MOVE_JOINT;
}

/* 1 when the head move is due to start this period (a joint move after a
 * plan waits for the tracker to be at rest); DH_ERR_ARG into *st for a
 * joint move of another joint count than the tracker's */
static DH_NOINLINE int queue_due(const dh_queue_f32 *qu, const dh_track_f32 *t, float dt, dh_status *st)
{
    const dh_queue_item_f32 *it = &qu->items[qu->head];
    *st = DH_OK;
    if (qu->phase != (uint32_t)DH_QUEUE_RUN || qu->count == 0u || qu->started != 0u) return 0;
    if (it->kind != (uint32_t)DH_MOVE_JOINT) return 1;
    if (it->n != t->r->n) {
        *st = DH_ERR_ARG;
        return 0;
    }
    return (qu->mv.kind == (uint32_t)DH_MOVE_NONE) || queue_at_rest(t, it, dt);
}

/* Plans the joint move it from q0 as dh_move_joint_f32 does: each joint's
 * time-optimal profile within the limits less 2^-10, all stretched to the
 * longest. The profile calls are made from here, one frame above them. */
static DH_NOINLINE dh_status queue_start_joint(dh_queue_f32 *qu, const dh_queue_item_f32 *it, const float *q0)
{
    dh_status st = DH_OK;
    float T = 0.0f, d = 0.0f;
    uint32_t i;
    qu->mv.kind = (uint32_t)DH_MOVE_NONE;
    qu->bmode = QB_NONE;
    for (i = 0u; i < it->n && st == DH_OK; i++) {
        st = queue_joint_d(&qu->mv, it, i, q0[i], &d);
        if (st == DH_OK) {
            if (it->jerk != 0u)
                st = dh_profile_scurve_f32(&qu->mv.prof[i], d, it->vmax[i] * QUEUE_MARGIN,
                                           it->amax[i] * QUEUE_MARGIN, it->jmax[i]);
            else
                st = dh_profile_trap_f32(&qu->mv.prof[i], d, it->vmax[i] * QUEUE_MARGIN, it->amax[i] * QUEUE_MARGIN);
        }
        if (st == DH_OK && qu->mv.prof[i].T > T) T = qu->mv.prof[i].T;
    }
    for (i = 0u; i < it->n && st == DH_OK; i++) st = dh_profile_stretch_f32(&qu->mv.prof[i], T);
    if (st == DH_OK) queue_joint_end(qu, it->n, T);
    return st;
}

/* what this period does (QUEUE_*) */
static uint32_t queue_what(const dh_queue_f32 *qu)
{
    if (qu->phase == (uint32_t)DH_QUEUE_BRAKE)
        return (qu->mv.kind == (uint32_t)DH_MOVE_JOINT) ? QUEUE_BJOINT : QUEUE_BPATH;
    if (qu->phase != (uint32_t)DH_QUEUE_RUN || qu->count == 0u || qu->started == 0u) return QUEUE_HOLD;
    return (qu->mv.kind == (uint32_t)DH_MOVE_JOINT) ? QUEUE_JOINT : QUEUE_PATH;
}

/* the joint command of this period for what (a joint plan, or none) */
static DH_NOINLINE void queue_joint_cmd(dh_queue_f32 *qu, const dh_track_f32 *t, uint32_t what, float dt,
                                        dh_queue_cmd_f32 *cmd)
{
    uint32_t i;
    qu->next = 0.0f;
    cmd->kind = (uint32_t)DH_MOVE_JOINT;
    if (what == QUEUE_JOINT) {
        qu->next = (qu->mv.clock + dt < qu->mv.dur) ? qu->mv.clock + dt : qu->mv.dur;
        (void)dh_joint_move_eval_f32(qu->mv.prof, qu->mv.n, qu->mv.q0, qu->mv.q1, qu->next, cmd->q, qu->mv.ws[0],
                                     qu->mv.ws[1]);
    } else if (what == QUEUE_BJOINT) {
        qu->next = (qu->tb + dt < qu->tbend) ? qu->tb + dt : qu->tbend;
        for (i = 0u; i < qu->mv.n; i++) cmd->q[i] = queue_brake_at(qu, i, qu->next);
    } else if (qu->mv.kind == (uint32_t)DH_MOVE_JOINT) {
        /* held after a joint move: the tracker's configuration again */
        for (i = 0u; i < t->r->n; i++) cmd->q[i] = t->q[i];
    } else {
        cmd->kind = (uint32_t)DH_MOVE_NONE;
    }
}

/* The planning (queue_start_*) and the path's frame (dh_path_eval_f32) are
 * called from here directly, one small frame above them. */
dh_status dh_queue_target_f32(dh_queue_f32 *qu, const dh_track_f32 *t, float dt, dh_queue_cmd_f32 *cmd)
{
    dh_status st;
    uint32_t what;
    DH_ASSERT(qu != NULL && t != NULL && t->r != NULL && cmd != NULL);
    DH_ASSERT(t->r->n >= 1u && t->r->n <= (uint32_t)DH_MAX_JOINTS);
    if (qu->pend != 0u) return DH_ERR_ARG;
    if (!dh_isfinite_f32(dt) || !queue_finite(t->q, t->r->n)) return DH_ERR_NAN;
    if (!(dt > 0.0f)) return DH_ERR_ARG;
    if (queue_due(qu, t, dt, &st)) {
        const dh_queue_item_f32 *it = &qu->items[qu->head];
        st = (it->kind == (uint32_t)DH_MOVE_JOINT) ? queue_start_joint(qu, it, t->q) : queue_start_path(qu, it);
        if (st == DH_OK) {
            qu->started = 1u;
            qu->braked = 0u;
        }
    }
    if (st != DH_OK) return st;
    what = queue_what(qu);
    if (qu->mv.kind == (uint32_t)DH_MOVE_PATH && what != QUEUE_JOINT && what != QUEUE_BJOINT) {
        /* the path's frame now: running, braking, or held at rest */
        qu->next = 0.0f;
        cmd->kind = (uint32_t)DH_MOVE_PATH;
        if (qu->bmode == QB_NONE) {
            (void)dh_path_eval_f32(&qu->mv.path, queue_path_now(qu), &cmd->T);
        } else if (queue_blend_pose(qu, what, &cmd->T) == 0) {
            (void)dh_path_eval_f32(&qu->mv.path, queue_blend_s(qu), &cmd->T);
        } else {
            /* the superposition of two lines, written by queue_blend_pose */
        }
    } else {
        queue_joint_cmd(qu, t, what, dt, cmd);
    }
    qu->pend = what;
    qu->dt = dt;
    qu->n = t->r->n;
    return DH_OK;
}

/* the move at the head is complete: removed from the queue */
static void queue_pop(dh_queue_f32 *qu)
{
    qu->last = qu->items[qu->head].kind;
    qu->head = (qu->head + 1u) % qu->cap;
    qu->count--;
    qu->seq++;
    qu->started = 0u;
}

/* the brake reached rest: stopped, or the move planned again at once
 * when a resume came during the brake */
static void queue_rest(dh_queue_f32 *qu)
{
    qu->phase = (uint32_t)DH_QUEUE_STOPPED;
    if (qu->resume != 0u) {
        qu->resume = 0u;
        qu->phase = (uint32_t)DH_QUEUE_RUN;
        qu->started = 0u;
    }
}

/* advances the pending period what; sets *held and *done */
static void queue_period(dh_queue_f32 *qu, uint32_t what, dh_track_state state, int *held, int *done)
{
    int ok = 0;
    if (state == DH_TRACK_OK) ok = 1;
    *held = 0;
    *done = 0;
    if (what == QUEUE_JOINT) {
        qu->mv.clock = qu->next;
        if (!(qu->next < qu->mv.dur)) *done = 1;
    } else if (what == QUEUE_PATH && qu->bmode != QB_NONE) {
        *held = 1 - ok;
        *done = queue_blend_period(qu, ok);
    } else if (what == QUEUE_PATH) {
        dh_move_report_f32 mrep;
        /* the executor's period: clock and feed override (dh_move.c) */
        (void)dh_move_advance_f32(&qu->mv, qu->dt, state, &mrep);
        *held = mrep.held;
        *done = mrep.done;
    } else if (what == QUEUE_BJOINT || what == QUEUE_BPATH) {
        if (what == QUEUE_BJOINT)
            qu->tb = qu->next;
        else if (ok == 0)
            *held = 1;
        else
            qu->tb = (qu->tb + qu->dt < qu->tbend) ? qu->tb + qu->dt : qu->tbend;
        if (!(qu->tb < qu->tbend)) queue_rest(qu);
    } else {
        *held = 1;
    }
}

static int queue_jerk_overlap(const dh_queue_f32 *qu);
static DH_NOINLINE void queue_stop_now(dh_queue_f32 *qu);

/* The period; then a stop deferred to an overlap's end acts when the
 * overlap ended (queue_stop_now). */
dh_status dh_queue_advance_f32(dh_queue_f32 *qu, dh_track_state state, dh_queue_report_f32 *rep)
{
    uint32_t what;
    int held, done;
    DH_ASSERT(qu != NULL && rep != NULL);
    if (qu->pend == 0u) return DH_ERR_ARG;
    if (state != DH_TRACK_OK && state != DH_TRACK_LAGGING && state != DH_TRACK_UNREACHABLE) return DH_ERR_ARG;
    what = qu->pend;
    qu->pend = 0u;
    rep->seq = qu->seq;
    queue_period(qu, what, state, &held, &done);
    rep->clock = (what == QUEUE_BJOINT || what == QUEUE_BPATH) ? qu->tb : qu->mv.clock;
    if (done == 2) rep->clock = qu->next;
    rep->feed = (what == QUEUE_PATH) ? qu->mv.feed : 1.0f;
    if (done != 0) queue_pop(qu);
    /* blended: the next line runs on */
    if (done == 2) qu->started = 1u;
    if (qu->stopq != 0u && queue_jerk_overlap(qu) == 0) queue_stop_now(qu);
    rep->held = held;
    rep->done = 0;
    if (done != 0) rep->done = 1;
    rep->last = 0;
    if (qu->count == 0u) rep->last = 1;
    rep->stopped = 0;
    if (qu->phase == (uint32_t)DH_QUEUE_STOPPED) rep->stopped = 1;
    return DH_OK;
}

/* a joint move's position, velocity and acceleration at its clock into
 * bq, ws[0], ws[1] */
static DH_NOINLINE void queue_joint_state(dh_queue_f32 *qu)
{
    (void)dh_joint_move_eval_f32(qu->mv.prof, qu->mv.n, qu->mv.q0, qu->mv.q1, qu->mv.clock, qu->bq, qu->mv.ws[0],
                                 qu->mv.ws[1]);
}

/* a joint move's brake from its state (queue_joint_state); its duration */
static DH_NOINLINE float queue_brake_joint(dh_queue_f32 *qu)
{
    const dh_queue_item_f32 *it = &qu->items[qu->head];
    float d = 0.0f, e;
    uint32_t i;
    for (i = 0u; i < qu->mv.n; i++) {
        qu->bv[i] = qu->mv.ws[0][i];
        qu->ba[i] = qu->mv.ws[1][i];
        qu->bap[i] = it->amax[i] * QUEUE_MARGIN;
        qu->bj[i] = (it->jerk != 0u) ? it->jmax[i] : 0.0f;
        e = queue_brake_plan(qu, i, qu->mv.q1[i]);
        if (e > d) d = e;
    }
    return d;
}

/* each blended line (two in an overlap) from its state */
static DH_NOINLINE float queue_brake_blend(dh_queue_f32 *qu)
{
    float d = 0.0f, e;
    uint32_t i;
    for (i = 0u; i < ((qu->bmode == QB_TWO) ? 2u : 1u); i++) {
        queue_blend_state(qu, i);
        e = queue_brake_plan(qu, i, 1.0f);
        if (e > d) d = e;
    }
    return d;
}

/* a path move from s, its rate and acceleration under the feed override
 * r: s' r, s'' r^2 */
static DH_NOINLINE float queue_brake_path(dh_queue_f32 *qu)
{
    const dh_queue_item_f32 *it = &qu->items[qu->head];
    float sd, sdd;
    qu->bq[0] = queue_path_s(qu, qu->mv.clock, &sd, &sdd);
    qu->bv[0] = sd * qu->mv.feed;
    qu->ba[0] = sdd * qu->mv.feed * qu->mv.feed;
    qu->bap[0] = qu->as;
    qu->bj[0] = (it->jerk != 0u) ? it->prof.j : 0.0f;
    return queue_brake_plan(qu, 0u, 1.0f);
}

/* plans the brake of the running move from its state at its clock (a
 * joint move's in bq, ws[0], ws[1]), each kind of move in its own step;
 * its duration */
static float queue_brake(dh_queue_f32 *qu)
{
    if (qu->mv.kind == (uint32_t)DH_MOVE_JOINT) return queue_brake_joint(qu);
    if (qu->bmode == QB_ONE || qu->bmode == QB_TWO) return queue_brake_blend(qu);
    return queue_brake_path(qu);
}

/* 1 while two jerk-limited blended lines overlap: a stop waits for the
 * overlap's end and acts from there (line 2 alone brakes at its own
 * bounds), since the corner's bounds hold only while line 1 decelerates
 * and line 2 accelerates (docs/design.md) */
static int queue_jerk_overlap(const dh_queue_f32 *qu)
{
    return (qu->bmode == QB_TWO && qu->bl[1].T > 0.0f && qu->bl[0].j > 0.0f) ? 1 : 0;
}

/* the stop of the running move from its state now: its brake, or at
 * rest at once (then running again when a resume came while it waited) */
static DH_NOINLINE void queue_stop_now(dh_queue_f32 *qu)
{
    qu->stopq = 0u;
    if (qu->count == 0u || qu->started == 0u ||
        ((qu->bmode == QB_ONE || qu->bmode == QB_TWO) ? !queue_blend_moving(qu)
                                                       : (!(qu->mv.clock > 0.0f) || !(qu->mv.clock < qu->mv.dur)))) {
        qu->phase = (qu->resume != 0u) ? (uint32_t)DH_QUEUE_RUN : (uint32_t)DH_QUEUE_STOPPED;
        qu->resume = 0u;
        return;
    }
    if (qu->mv.kind == (uint32_t)DH_MOVE_JOINT) queue_joint_state(qu);
    if (qu->mv.kind != (uint32_t)DH_MOVE_JOINT && (qu->bmode == QB_ONE || qu->bmode == QB_TWO)) queue_blend_pos(qu);
    qu->tb = 0.0f;
    qu->tbend = queue_brake(qu);
    qu->braked = 1u;
    qu->phase = (qu->tbend > 0.0f) ? (uint32_t)DH_QUEUE_BRAKE : (uint32_t)DH_QUEUE_STOPPED;
    if (qu->phase == (uint32_t)DH_QUEUE_STOPPED) queue_rest(qu);
}

dh_status dh_queue_stop_f32(dh_queue_f32 *qu)
{
    DH_ASSERT(qu != NULL);
    if (qu->pend != 0u) return DH_ERR_ARG;
    if (qu->phase != (uint32_t)DH_QUEUE_RUN) return DH_OK;
    qu->resume = 0u;
    if (queue_jerk_overlap(qu) != 0) {
        qu->stopq = 1u;
    } else {
        queue_stop_now(qu);
    }
    return DH_OK;
}

dh_status dh_queue_resume_f32(dh_queue_f32 *qu)
{
    DH_ASSERT(qu != NULL);
    if (qu->pend != 0u) return DH_ERR_ARG;
    if (qu->phase == (uint32_t)DH_QUEUE_BRAKE || qu->stopq != 0u) {
        qu->resume = 1u;
    } else if (qu->phase == (uint32_t)DH_QUEUE_STOPPED) {
        qu->phase = (uint32_t)DH_QUEUE_RUN;
        if (qu->braked != 0u) qu->started = 0u;
    } else {
        /* running: nothing to resume */
    }
    return DH_OK;
}
