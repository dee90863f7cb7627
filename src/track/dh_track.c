/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_track.c - the float tracker: one bounded joint step per control
 * period (method in track.h and docs/design.md, "Tracking").
 *
 * The step box. For joint i with step bound d = vmax dt, previous step p
 * and A = amax dt^2 (the largest change of step between periods), the
 * step s of this period lies in
 *   [-d, d] and [p - A, p + A]            (rate and acceleration),
 *   [qmin - q, qmax - q]                  (limits),
 *   s <= -A + sqrt(A^2 + 2 A (qmax - q))  (and its mirror for qmin),
 * the last one the braking condition v^2 <= 2 amax D on the velocity
 * after the step and the distance D left to the limit: it holds after
 * every step, so braking by A per period is always in the next box
 * ((p - A)^2 + 2 A (p - A) = p^2 - A^2 <= 2 A D). The same curve towards
 * the closed-form solution keeps the approach from overshooting it.
 *
 * The step bound is exact on the floats: q + s is rounded, so the result
 * is moved towards q one ulp at a time until |q_out - q| <= dq_max in
 * float, and dq_max is vmax dt less 2^-20 relative, more than the
 * rounding of that float difference.
 */
#include "dhmath/track.h"
#include "../internal/dh_floatops.h"
#include "../kin/kin_impl.h"
#include "../ikc/ikc_impl.h"

#define TRACK_INF_BITS 0x7F800000u


static float track_inf(void)
{
    return dh_f32_from_bits(TRACK_INF_BITS);
}

static float track_abs(float x)
{
    return (x < 0.0f) ? -x : x;
}

static float track_clamp(float x, float lo, float hi)
{
    if (x < lo) x = lo;
    if (x > hi) x = hi;
    return x;
}

/* the float next to x towards y (x != y, both finite) */
static float track_toward(float x, float y)
{
    uint32_t u = dh_f32_bits(x);
    if (dh_feq_f32(x, 0.0f)) return (y > 0.0f) ? dh_f32_from_bits(1u) : dh_f32_from_bits(0x80000001u);
    /* towards y: away from 0 (magnitude up) when y lies beyond x */
    if (x > 0.0f) {
        if (y > x) u++;
        else u--;
    } else {
        if (y < x) u++;
        else u--;
    }
    return dh_f32_from_bits(u);
}

/* L: sum of |a|, |d|, prismatic travel, |p_tool| (1 when 0), the
 * length dh_ik_params_default_f32 scales by (its w_rot is L / 4) */
static DH_NOINLINE float track_length(const dh_robot *r)
{
    dh_ik_params_f32 p;
    dh_ik_params_default_f32(r, &p);
    return 4.0f * p.w_rot;
}

dh_status dh_track_init_f32(dh_track_f32 *t, const dh_robot *r, const dh_ikc_model_f32 *m, const float *q0,
                            float dt)
{
    uint32_t i;
    dh_status st;
    float L;
    DH_ASSERT(t != NULL);
    DH_ASSERT(r != NULL);
    DH_ASSERT(q0 != NULL);
    if (r->n == 0u || r->n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    if (!(dt > 0.0f) || !dh_isfinite_f32(dt)) return DH_ERR_ARG;
    if ((r->flags & DH_ROBOT_HAS_F32) == 0u) return DH_ERR_UNAVAILABLE;
    if (m != NULL && (m->kind == DH_IKC_NONE || m->n != r->n)) return DH_ERR_ARG;
    st = dh_robot_check_limits_f32(r, q0);
    if (st != DH_OK) return st;
    t->r = r;
    t->m = m;
    t->dt = dt;
    L = track_length(r);
    for (i = 0u; i < r->n; i++) {
        const float d = r->joint[i].vmax * dt;
        t->q[i] = q0[i];
        t->v[i] = 0.0f;
        t->dq_max[i] = dh_isfinite_f32(d) ? d * (1.0f - 9.5367431640625e-7f) : track_inf();
    }
    t->lambda = 0.02f * L;
    t->sing_threshold = 0.005f * L;
    t->pos_tol = 2e-6f * L;
    t->rot_tol = 2e-5f;
    t->reach = L * 1.0001f;
    st = dh_jacobian_f32(r, t->q, t->J, &t->T);
    return (st == DH_OK) ? DH_OK : DH_ERR_OVERFLOW;
}

/* the step box of this period (t->lo, t->hi), see the file comment */
static DH_NOINLINE void track_box(dh_track_f32 *t)
{
    const uint32_t n = t->r->n;
    uint32_t i;
    for (i = 0u; i < n; i++) {
        const dh_joint *j = &t->r->joint[i];
        /* below the bound of track_put by 2^-21: rounding never pushes a
         * step of the box back */
        const float q = t->q[i], d = t->dq_max[i] * (1.0f - 9.5367431640625e-7f);
        float lo = -d, hi = d;
        const float A = j->amax * t->dt * t->dt;
        const int lim = j->qmin <= j->qmax;
        if (dh_isfinite_f32(A)) {
            const float p = t->v[i] * t->dt;
            lo = (p - A > lo) ? p - A : lo;
            hi = (p + A < hi) ? p + A : hi;
            if (lim) {
                const float bh = -A + dh_sqrt_f32(A * A + 2.0f * A * (j->qmax - q));
                const float bl = A - dh_sqrt_f32(A * A + 2.0f * A * (q - j->qmin));
                hi = (bh < hi) ? bh : hi;
                lo = (bl > lo) ? bl : lo;
            }
        }
        if (lim) {
            hi = (j->qmax - q < hi) ? j->qmax - q : hi;
            lo = (j->qmin - q > lo) ? j->qmin - q : lo;
        }
        if (lo > hi) { /* rounding only: the braking step is in the box */
            const float mid = 0.5f * (lo + hi);
            lo = mid;
            hi = mid;
        }
        t->lo[i] = lo;
        t->hi[i] = hi;
    }
}

/* t->dq scaled by one factor in [0, 1] so that each entry stays on its
 * side of 0 within the box, then clamped into the box */
static DH_NOINLINE void track_fit(dh_track_f32 *t)
{
    const uint32_t n = t->r->n;
    uint32_t i;
    float s = 1.0f;
    for (i = 0u; i < n; i++) {
        const float x = t->dq[i];
        const float b = (x > 0.0f) ? t->hi[i] : t->lo[i];
        if (!dh_feq_f32(x, 0.0f)) {
            const float lim = (x > 0.0f) ? ((b > 0.0f) ? b : 0.0f) : ((b < 0.0f) ? b : 0.0f);
            if (x * s > lim && x > 0.0f) s = lim / x;
            if (x * s < lim && x < 0.0f) s = lim / x;
        }
    }
    for (i = 0u; i < n; i++) t->dq[i] = track_clamp(t->dq[i] * s, t->lo[i], t->hi[i]);
}

/* the closed-form solution (of t->sol, t->ns, from dh_ikc_f32 with
 * status st) nearest t->q in time into t->qs; 1 when there is one within
 * the limits, else 0 (*unreach: none at all or none within the limits) */
static DH_NOINLINE int track_pick(dh_track_f32 *t, dh_status st, int *unreach)
{
    const uint32_t n = t->r->n;
    uint32_t ns = (st == DH_OK) ? t->ns : 0u, k, i, best = 0u;
    float bt = 0.0f, bs = 0.0f;
    int found = 0;
    for (k = 0u; k < ns; k++) {
        float tm = 0.0f, sm = 0.0f;
        int in = 1;
        for (i = 0u; i < n; i++) {
            /* a solution on a limit may come out beyond it by rounding:
             * within 1e-4 deg (or 1e-7 L) it is put on the limit */
            const dh_joint *j = &t->r->joint[i];
            const float tol = (j->type == DH_JOINT_REVOLUTE) ? 1e-4f : 1e-7f * t->reach;
            float x = t->sol[k].q[i];
            if (j->type == DH_JOINT_REVOLUTE && j->qmin <= j->qmax) {
                /* the 360-degree shift nearest q when it is within the
                 * limits up to the tolerance: dh_ikc_f32 shifts a value
                 * just beyond a limit by 360 degrees into the range */
                const float y = (x - t->q[i] > 180.0f) ? x - 360.0f : ((x - t->q[i] < -180.0f) ? x + 360.0f : x);
                if (y >= j->qmin - tol && y <= j->qmax + tol) x = y;
            }
            if (j->qmin <= j->qmax) {
                if (x < j->qmin - tol || x > j->qmax + tol) in = 0;
                x = track_clamp(x, j->qmin, j->qmax);
                t->sol[k].q[i] = x;
            }
        }
        if (!in) continue;
        for (i = 0u; i < n; i++) {
            const float d = track_abs(t->sol[k].q[i] - t->q[i]);
            const float v = t->r->joint[i].vmax;
            const float ti = dh_isfinite_f32(v) ? d / v : 0.0f;
            tm = (ti > tm) ? ti : tm;
            sm += d;
            if (found && tm > bt) break;   /* slower than the best: out */
        }
        if (!found || tm < bt || (tm <= bt && sm < bs)) {
            best = k;
            bt = tm;
            bs = sm;
            found = 1;
        }
    }
    *unreach = 0;
    if (st == DH_ERR_UNREACHABLE || (st == DH_OK && !found)) *unreach = 1;
    if (!found) return 0;
    for (i = 0u; i < n; i++) t->qs[i] = t->sol[best].q[i];
    return 1;
}

/* 1 when the step to t->qs lies in the box (t->dq set to it) */
static DH_NOINLINE int track_reached(dh_track_f32 *t)
{
    const uint32_t n = t->r->n;
    uint32_t i;
    int in = 1;
    for (i = 0u; i < n; i++) {
        const float s = t->qs[i] - t->q[i];
        if (!(s >= t->lo[i] && s <= t->hi[i])) in = 0;
        t->dq[i] = s;
    }
    return in;
}

/* the step towards t->qs at the bound: straight in joint space, each joint
 * also braking so as to stop at its target value */
static DH_NOINLINE void track_head(dh_track_f32 *t)
{
    const uint32_t n = t->r->n;
    uint32_t i;
    for (i = 0u; i < n; i++) {
        const float D = t->qs[i] - t->q[i];
        const float A = t->r->joint[i].amax * t->dt * t->dt;
        float s = D;
        if (dh_isfinite_f32(A)) {
            const float b = -A + dh_sqrt_f32(A * A + 2.0f * A * track_abs(D));
            if (track_abs(s) > b) s = (D > 0.0f) ? b : -b;
        }
        t->dq[i] = s;
    }
    track_fit(t);
}

/* the damping of this period from t->sg: lambda^2 (1 - (sg/threshold)^2)
 * below the threshold, plus a floor of 10^-6 lambda^2 that keeps the step
 * defined for any J */
static DH_NOINLINE void track_damping(dh_track_f32 *t)
{
    float lam2 = 0.0f;
    if (t->sg < t->sing_threshold) {
        const float x = t->sg / t->sing_threshold;
        lam2 = t->lambda * t->lambda * (1.0f - x * x);
    }
    lam2 += 1e-6f * t->lambda * t->lambda;
    t->lam = dh_sqrt_f32(lam2);
}

/* a joint that cannot move the way the step wants (against a limit, or
 * braking) leaves the solve: its Jacobian column is cleared (t->J is
 * recomputed at q_out); 1 when one did */
static DH_NOINLINE int track_block(dh_track_f32 *t)
{
    const uint32_t n = t->r->n;
    uint32_t i, k;
    int blocked = 0;
    for (i = 0u; i < n; i++) {
        if ((t->dq[i] > 0.0f && !(t->hi[i] > 0.0f)) || (t->dq[i] < 0.0f && !(t->lo[i] < 0.0f))) {
            for (k = 0u; k < 6u; k++) t->J[k * n + i] = 0.0f;
            blocked = 1;
        }
    }
    return blocked;
}

/* 1 when the fitted step t->dq stalls: the linearised error (rotation
 * weighted by L) drops by less than 19 % */
static DH_NOINLINE int track_stalls(const dh_track_f32 *t)
{
    const uint32_t n = t->r->n;
    const float L = t->reach;
    float e2 = 0.0f, r2 = 0.0f;
    uint32_t i, k;
    for (k = 0u; k < 6u; k++) {
        const float w = (k < 3u) ? 1.0f : L * L;
        float s = t->e[k];
        for (i = 0u; i < n; i++) {
            const float c = (t->r->joint[i].type == DH_JOINT_REVOLUTE) ? DH_DEG2RAD_F : 1.0f;
            s -= t->J[k * n + i] * t->dq[i] * c;
        }
        e2 += w * t->e[k] * t->e[k];
        r2 += w * s * s;
    }
    return (r2 > 0.81f * e2) ? 1 : 0;
}

/* 1 when the pose error in t->e is within pos_tol and rot_tol */
static DH_NOINLINE int track_within(const dh_track_f32 *t)
{
    const float *const e = t->e;
    const float p2 = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
    const float r2 = e[3] * e[3] + e[4] * e[4] + e[5] * e[5];
    return (p2 <= t->pos_tol * t->pos_tol && r2 <= t->rot_tol * t->rot_tol) ? 1 : 0;
}

/* 1 when t->dq does not bring q nearer t->qs in time */
static DH_NOINLINE int track_away(const dh_track_f32 *t)
{
    const uint32_t n = t->r->n;
    float before = 0.0f, after = 0.0f;
    uint32_t i;
    for (i = 0u; i < n; i++) {
        const float v = t->r->joint[i].vmax;
        const float w = dh_isfinite_f32(v) ? 1.0f / v : 1.0f;
        const float b = track_abs(t->qs[i] - t->q[i]) * w;
        const float a = track_abs(t->qs[i] - t->q[i] - t->dq[i]) * w;
        before = (b > before) ? b : before;
        after = (a > after) ? a : after;
    }
    return (after >= before) ? 1 : 0;
}

/* without a closed form: the step so far (t->keep) accumulated and the
 * box shifted by it (sign +1), or back (sign -1, t->dq += keep) */
static DH_NOINLINE void track_shift(dh_track_f32 *t, int sign)
{
    const uint32_t n = t->r->n;
    uint32_t i;
    for (i = 0u; i < n; i++) {
        if (sign > 0) {
            t->keep[i] = t->dq[i];
            t->qs[i] = t->q[i] + t->dq[i];
            t->lo[i] -= t->dq[i];
            t->hi[i] -= t->dq[i];
        } else {
            t->lo[i] += t->keep[i];
            t->hi[i] += t->keep[i];
            t->dq[i] += t->keep[i];
        }
    }
}

/* 1 when the target lies beyond the reach bound (robots without a closed
 * form) */
static DH_NOINLINE int track_beyond(const dh_track_f32 *t, const dh_mat4_f32 *target)
{
    const float px = target->m[3][0] - t->r->base.m[3][0], py = target->m[3][1] - t->r->base.m[3][1],
                pz = target->m[3][2] - t->r->base.m[3][2];
    return (px * px + py * py + pz * pz > t->reach * t->reach) ? 1 : 0;
}

static DH_NOINLINE void track_zero(dh_track_f32 *t)
{
    uint32_t i;
    for (i = 0u; i < t->r->n; i++) t->dq[i] = 0.0f;
}

/* q_out[i] = q[i] + dq[i] within the limits and exactly within dq_max */
static DH_NOINLINE float track_put(const dh_track_f32 *t, uint32_t i)
{
    const dh_joint *j = &t->r->joint[i];
    /* the float difference is within 2^-24 of the exact one */
    const float q = t->q[i], d = t->dq_max[i] * (1.0f - 4.76837158203125e-7f);
    float x = q + t->dq[i];
    int guard;
    if (j->qmin <= j->qmax) x = track_clamp(x, j->qmin, j->qmax);
    for (guard = 0; guard < 64 && !dh_feq_f32(x, q) && track_abs(x - q) > d; guard++) x = track_toward(x, q);
    if (!dh_isfinite_f32(x) || track_abs(x - q) > d) x = q;
    return x;
}

/* braking: each velocity towards 0 by at most amax dt (at once when amax
 * is unlimited) */
static DH_NOINLINE void track_brake(dh_track_f32 *t)
{
    const uint32_t n = t->r->n;
    uint32_t i;
    for (i = 0u; i < n; i++) {
        const float A = t->r->joint[i].amax * t->dt * t->dt;
        const float p = t->v[i] * t->dt;
        float s = 0.0f;
        if (dh_isfinite_f32(A)) s = (p > A) ? p - A : ((p < -A) ? p + A : 0.0f);
        t->dq[i] = track_clamp(s, t->lo[i], t->hi[i]);
    }
}

/* DH_OK for a finite rigid target (bottom row 0 0 0 1, rotation within
 * DH_ROT_ERROR_TOL of orthonormal, det > 0), else DH_ERR_NAN or
 * DH_ERR_NOT_RIGID */
static DH_NOINLINE dh_status track_target_ok(const dh_mat4_f32 *target)
{
    uint32_t c, k;
    for (c = 0u; c < 4u; c++)
        for (k = 0u; k < 4u; k++)
            if (!dh_isfinite_f32(target->m[c][k])) return DH_ERR_NAN;
    if (!dh_feq_f32(target->m[0][3], 0.0f) || !dh_feq_f32(target->m[1][3], 0.0f) ||
        !dh_feq_f32(target->m[2][3], 0.0f) || !dh_feq_f32(target->m[3][3], 1.0f))
        return DH_ERR_NOT_RIGID;
    return dh_kin_rot_ok_f32_(&target->m[0][0], &target->m[1][0], &target->m[2][0]) ? DH_OK : DH_ERR_NOT_RIGID;
}

/* the report from t->e (pose error at q_out) */
static DH_NOINLINE void track_fill(const dh_track_f32 *t, int fk, int unreach, dh_track_report_f32 *rep)
{
    const float *const e = t->e;
    rep->pos_err = fk ? dh_sqrt_f32(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]) : 0.0f;
    rep->rot_err = fk ? dh_sqrt_f32(e[3] * e[3] + e[4] * e[4] + e[5] * e[5]) : 0.0f;
    rep->near_singular = 0;
    if (rep->sigma_min < t->sing_threshold) rep->near_singular = 1;
    if (fk && rep->pos_err <= t->pos_tol && rep->rot_err <= t->rot_tol)
        rep->state = DH_TRACK_OK;
    else
        rep->state = (unreach || !fk) ? DH_TRACK_UNREACHABLE : DH_TRACK_LAGGING;
}

/* q_out into t->q and t->v */
static DH_NOINLINE void track_move(dh_track_f32 *t)
{
    uint32_t i;
    for (i = 0u; i < t->r->n; i++) {
        const float x = track_put(t, i);
        t->v[i] = (x - t->q[i]) / t->dt;
        t->q[i] = x;
    }
}

/* One damped step from the Jacobian in t->J and the pose error in t->e
 * (ok: 0 when it could not be computed) into t->dq, fitted into the box;
 * 1 when it stalls. */
static DH_NOINLINE int track_damped(dh_track_f32 *t, int ok)
{
    if (!ok || dh_manipulability_ws_f32_(t->J, t->r->n, NULL, &t->sg, t->ws) != DH_OK) {
        track_zero(t);
        track_fit(t);
        return 1;
    }
    track_damping(t);
    if (dh_dls_step_ws_f32_(t->r, t->J, t->e, t->lam, NULL, t->dq, t->ws) != DH_OK ||
        (track_block(t) && dh_dls_step_ws_f32_(t->r, t->J, t->e, t->lam, NULL, t->dq, t->ws) != DH_OK)) {
        track_zero(t);
        track_fit(t);
        return 1;
    }
    track_fit(t);
    return track_stalls(t);
}

/* 1 when the pose error of the target from t->T is in t->e */
static int track_err(dh_track_f32 *t, const dh_mat4_f32 *target)
{
    return (dh_kin_pose_error_f32_(target, &t->T, t->e, t->ws) == DH_OK) ? 1 : 0;
}

/* 1 when the closed form's argument checks pass (their status in t->ist) */
static DH_NOINLINE int track_ikc_args(dh_track_f32 *t, const dh_mat4_f32 *target)
{
    t->ist = dh_ikc_args_f32_(t->m, target, t->q, DH_IKC_KEEP_OUT_OF_LIMITS);
    return (t->ist == DH_OK) ? 1 : 0;
}

/* The step towards a valid target, the closed form's raw solutions (if
 * any) in t->sol, t->ns: the solution nearest in time if the box holds
 * it; else, where q already reaches the target, no step; else, away from
 * singularities, straight for that solution at the bound; near them the
 * damped step, unless it stalls or moves away from it; without a solution
 * the damped step. 1 when there is no closed form and q does not reach
 * the target (track_more follows). */
static DH_NOINLINE int track_chase(dh_track_f32 *t, const dh_mat4_f32 *target)
{
    int have = 0, ok;
    t->unreach = 0;
    if (t->m != NULL) {
        const dh_status st = (t->ist != DH_OK) ? t->ist
                                               : dh_ikc_finish_f32_(t->m, t->q, DH_IKC_KEEP_OUT_OF_LIMITS, t->sol,
                                                                    &t->ns);
        have = track_pick(t, st, &t->unreach);
    }
    if (have && track_reached(t)) return 0;
    /* q already reaches the target (the pose error from t->T, FK at q):
     * it keeps its place (the zero step fitted into the box), never a run
     * for a solution outside the box that would lose the reached pose */
    ok = track_err(t, target);
    if (ok && track_within(t)) {
        track_zero(t);
        track_fit(t);
        return 0;
    }
    /* sigma_min at q (t->J is the Jacobian at q) */
    if (dh_manipulability_ws_f32_(t->J, t->r->n, NULL, &t->sg, t->ws) != DH_OK) t->sg = 0.0f;
    if (have) {
        if (t->sg < t->sing_threshold && !track_damped(t, ok) && !track_away(t)) return 0;
        track_head(t);
        return 0;
    }
    (void)track_damped(t, ok);
    return (t->m == NULL) ? 1 : 0;
}

/* Without a closed form: two more damped steps from the point reached, in
 * what is left of the box. */
static DH_NOINLINE void track_more(dh_track_f32 *t, const dh_mat4_f32 *target)
{
    int it;
    for (it = 0; it < 2; it++) {
        track_shift(t, 1);
        if (dh_kin_jacobian_f32_(t->r, t->qs, t->J, &t->T, t->ws) != DH_OK) {
            track_zero(t);
            track_shift(t, -1);
            break;
        }
        (void)track_damped(t, track_err(t, target));
        track_shift(t, -1);
    }
    t->unreach = track_beyond(t, target);
}

/* The report at q_out (t->J, t->T recomputed there) */
static DH_NOINLINE void track_end(dh_track_f32 *t, const dh_mat4_f32 *target, dh_status tst, dh_track_report_f32 *rep)
{
    int fk = 0;
    rep->manip = 0.0f;
    rep->sigma_min = 0.0f;
    if (dh_kin_jacobian_f32_(t->r, t->q, t->J, &t->T, t->ws) == DH_OK) {
        (void)dh_manipulability_ws_f32_(t->J, t->r->n, &rep->manip, &rep->sigma_min, t->ws);
        /* the target passed its checks (tst): T's alone */
        if (tst == DH_OK && dh_kin_pose_error_to_f32_(target, &t->T, t->e, t->ws) == DH_OK) fk = 1;
    }
    track_fill(t, fk, t->unreach, rep);
}

/* The library calls are made one level below this function at most, the
 * closed-form solver's from here (dh_ikc_raw_f32_ has no frame), so the
 * stack stays the deepest callee plus two small frames. */
dh_status dh_track_step_f32(dh_track_f32 *t, const dh_mat4_f32 *target, float *q_out, dh_track_report_f32 *rep)
{
    dh_status tst;
    uint32_t i;
    DH_ASSERT(t != NULL);
    DH_ASSERT(t->r != NULL);
    DH_ASSERT(q_out != NULL);
    DH_ASSERT(rep != NULL);
    DH_ASSERT(t->r->n >= 1u && t->r->n <= (uint32_t)DH_MAX_JOINTS);
    tst = track_target_ok(target);
    track_box(t);
    t->unreach = 1;
    t->ns = 0u;
    if (tst != DH_OK) {
        track_brake(t);
    } else {
        if (t->m != NULL && track_ikc_args(t, target)) t->ns = dh_ikc_raw_f32_(t->m, target, t->q, t->sol);
        if (track_chase(t, target)) track_more(t, target);
    }
    track_move(t);
    track_end(t, target, tst, rep);
    for (i = 0u; i < t->r->n; i++) q_out[i] = t->q[i];
    return tst;
}

/* The checks come before any write, and t->J and t->T are recomputed at
 * the new configuration (the step reads them at t->q); a failed Jacobian
 * recomputes them at the old one, which init or a step had computed. The
 * old configuration is kept in t->lo, which every step writes first. */
dh_status dh_track_sync_f32(dh_track_f32 *t, const float *q)
{
    uint32_t i;
    dh_status st;
    DH_ASSERT(t != NULL);
    DH_ASSERT(t->r != NULL);
    DH_ASSERT(q != NULL);
    DH_ASSERT(t->r->n >= 1u && t->r->n <= (uint32_t)DH_MAX_JOINTS);
    st = dh_robot_check_limits_f32(t->r, q);
    if (st != DH_OK) return st;
    for (i = 0u; i < t->r->n; i++) t->lo[i] = t->q[i];
    if (dh_kin_jacobian_f32_(t->r, q, t->J, &t->T, t->ws) != DH_OK) {
        (void)dh_kin_jacobian_f32_(t->r, t->q, t->J, &t->T, t->ws);
        return DH_ERR_OVERFLOW;
    }
    for (i = 0u; i < t->r->n; i++) {
        const float v = (q[i] - t->lo[i]) / t->dt;
        t->v[i] = dh_isfinite_f32(v) ? v : 0.0f;
        t->q[i] = q[i];
    }
    return DH_OK;
}
