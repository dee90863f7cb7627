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
#include "dhmath/trig.h"
#include "../internal/dh_floatops.h"
#include "../kin/kin_impl.h"
#include "../ikc/ikc_impl.h"

#define TRACK_INF_BITS 0x7F800000u
/* the branch bits of a closed-form solution's flags */
#define TRACK_BRANCH (DH_IKC_SHOULDER_ALT | DH_IKC_ELBOW_ALT | DH_IKC_WRIST_ALT)


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

/* The closed form's residual bound in the robot's unit (t->cfp, the
 * contract of ikc.h scaled: 2e-6 m for reach 2 m, so 1e-6 of the reach
 * bound plus the base offset) and the factor of the Hong-Pan bound
 * (t->hpg = (5 / F)^(5/2), F >= ||J||_F^2 for every configuration: 6 unit
 * axes plus, per revolute joint i, the square of a bound on the distance
 * from its axis to the tool point: |p_tool| + |a_i| + the sum over k > i of
 * |a_k| + |d_k| + prismatic travel, since d_i lies along the axis in
 * either convention and a_i of a modified table before it); hpg 0 where
 * the closed form of |det J| does not apply */
static DH_NOINLINE void track_bounds(dh_track_f32 *t)
{
    const dh_robot *r = t->r;
    const float *pb = &r->base.m[3][0], *pt = &r->tool.m[3][0];
    float R = dh_sqrt_f32(pt[0] * pt[0] + pt[1] * pt[1] + pt[2] * pt[2]), F = 0.0f, x;
    uint32_t i = r->n;
    t->cfp = 1e-6f * (t->reach + dh_sqrt_f32(pb[0] * pb[0] + pb[1] * pb[1] + pb[2] * pb[2]));
    while (i > 0u) {
        const dh_joint *j = &r->joint[i - 1u];
        i--;
        /* joint i's own d (and travel) lies along its axis */
        F += 1.0f + ((j->type == DH_JOINT_REVOLUTE) ? (R + track_abs(j->a)) * (R + track_abs(j->a)) : 0.0f);
        R += track_abs(j->a) + track_abs(j->d);
        if (j->type != DH_JOINT_REVOLUTE)
            R += (j->qmin <= j->qmax) ? ((track_abs(j->qmin) > track_abs(j->qmax)) ? track_abs(j->qmin)
                                                                                  : track_abs(j->qmax))
                                      : track_inf();
    }
    t->hpg = 0.0f;
    if (t->m != NULL && t->m->n == 6u &&
        (t->m->kind == DH_IKC_WRIST_RRR || t->m->kind == DH_IKC_WRIST_RRP || t->m->kind == DH_IKC_PARALLEL_234) &&
        dh_isfinite_f32(F)) {
        x = 5.0f / F;
        t->hpg = x * x * dh_sqrt_f32(x) * (1.0f - 1e-5f);
    }
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
    track_bounds(t);
    t->jq = 1;
    t->br = 0u;
    st = dh_jacobian_f32(r, t->q, t->J, &t->T);
    return (st == DH_OK) ? DH_OK : DH_ERR_OVERFLOW;
}

/* the step box of this period (t->lo, t->hi), see the file comment; with
 * a closed-form solution (t->have) also t->dq = t->qs - t->q and 1 when the
 * box holds that step, else 0 */
static DH_NOINLINE int track_box(dh_track_f32 *t)
{
    const uint32_t n = t->r->n;
    uint32_t i;
    int in = t->have;
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
        if (t->have) {
            const float s = t->qs[i] - q;
            if (!(s >= lo && s <= hi)) in = 0;
            t->dq[i] = s;
        }
    }
    return in;
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

/* joint i's value *x of a closed-form solution, for a joint with limits:
 * shifted by 360 degrees and clamped onto the limits as track_pick takes
 * it; 1 when it is within the limits up to the tolerance */
static DH_NOINLINE int track_limit(const dh_track_f32 *t, uint32_t i, float *xp)
{
    /* a solution on a limit may come out beyond it by rounding: within
     * 1e-4 deg (or 1e-7 L) it is put on the limit */
    const dh_joint *j = &t->r->joint[i];
    const float tol = (j->type == DH_JOINT_REVOLUTE) ? 1e-4f : 1e-7f * t->reach;
    float x = *xp;
    int in = 1;
    if (j->type == DH_JOINT_REVOLUTE) {
        /* the 360-degree shift nearest q when it is within the limits up
         * to the tolerance: dh_ikc_f32 shifts a value just beyond a limit
         * by 360 degrees into the range */
        const float y = (x - t->q[i] > 180.0f) ? x - 360.0f : ((x - t->q[i] < -180.0f) ? x + 360.0f : x);
        if (y >= j->qmin - tol && y <= j->qmax + tol) x = y;
    }
    if (x < j->qmin - tol || x > j->qmax + tol) in = 0;
    *xp = track_clamp(x, j->qmin, j->qmax);
    return in;
}

/* A distance from q_i beyond which joint i's value of a solution takes
 * longer than bt to reach wherever track_limit takes it: bt vmax (1 +
 * 1e-6) plus the tolerance of a clamp and the rounding of a shift by 360
 * degrees and of the differences (|values| at most 180 + |qmin| + |qmax|);
 * +inf for an unlimited rate */
static DH_NOINLINE float track_thr(const dh_track_f32 *t, uint32_t i, float bt)
{
    const dh_joint *j = &t->r->joint[i];
    const float X = 180.0f + ((j->qmin <= j->qmax) ? track_abs(j->qmin) + track_abs(j->qmax) : 0.0f);
    return bt * j->vmax * (1.0f + 1e-6f) + 2e-4f + 2e-7f * t->reach + 2.4e-7f * (X + track_abs(t->q[i]) + 360.0f);
}

/* 1 when a value dd from q_i, or after a shift by 360 degrees, lies
 * beyond th */
static int track_far(float dd, float th)
{
    const float d = track_abs(dd);
    return (d > th && track_abs(360.0f - d) > th) ? 1 : 0;
}

/* the closed-form solution (of t->sol, t->ns, from dh_ikc_f32 with
 * status st) nearest t->q in time into t->qs; 1 when there is one within
 * the limits, else 0 (*unreach: none at all or none within the limits);
 * t->cf = 1 when t->qs holds that solution's values unchanged (no limit
 * clamp or shift by 360 degrees here) */
static DH_NOINLINE int track_pick(dh_track_f32 *t, dh_status st, int *unreach)
{
    const uint32_t n = t->r->n;
    uint32_t ns = (st == DH_OK) ? t->ns : 0u, k, i, best = 0u, moved = 0u, first = 0u, c;
    float bt = 0.0f, bs = 0.0f, th4 = 0.0f, th2 = 0.0f;
    int found = 0;
    /* the solution on the branch of the last one first: the others then
     * leave at their first slower joint (the result does not depend on
     * the order: the first index wins among equals) */
    for (k = 0u; k < ns; k++)
        if (((t->sol[k].flags ^ t->br) & TRACK_BRANCH) == 0u) {
            first = k;
            break;
        }
    for (c = 0u; c < ns; c++) {
        float tm = 0.0f, sm = 0.0f;
        int in = 1;
        k = (c == 0u) ? first : ((c <= first) ? c - 1u : c);
        /* joint 5 or 3 alone slower than the best: out (the branches
         * differ there first) */
        if (found && n == 6u &&
            (track_far(t->sol[k].q[4] - t->q[4], th4) || track_far(t->sol[k].q[2] - t->q[2], th2)))
            continue;
        for (i = 0u; i < n && in; i++) {
            const dh_joint *j = &t->r->joint[i];
            float *const x = &t->sol[k].q[i];
            const float x0 = *x, dd = x0 - t->q[i];
            float d;
            /* within the limits and half a turn of q: no shift, no clamp */
            if (j->qmin <= j->qmax && !(x0 >= j->qmin && x0 <= j->qmax && dd <= 180.0f && dd >= -180.0f)) {
                if (!track_limit(t, i, x)) in = 0;
                if (!dh_feq_f32(*x, x0)) moved |= 1u << k;
            }
            /* the time: vmax > 0, +inf for an unlimited joint (d / inf = 0) */
            d = track_abs(*x - t->q[i]);
            tm = (d / j->vmax > tm) ? d / j->vmax : tm;
            sm += d;
            if (found && tm > bt) in = 0;   /* slower than the best: out */
        }
        if (in && (!found || tm < bt || (tm <= bt && (sm < bs || (sm <= bs && k < best))))) {
            best = k;
            bt = tm;
            bs = sm;
            found = 1;
            if (n == 6u) {
                th4 = track_thr(t, 4u, bt);
                th2 = track_thr(t, 2u, bt);
            }
        }
    }
    *unreach = 0;
    if (st == DH_ERR_UNREACHABLE || (st == DH_OK && !found)) *unreach = 1;
    if (!found) return 0;
    for (i = 0u; i < n; i++) t->qs[i] = t->sol[best].q[i];
    t->cf = ((moved >> best) & 1u) ? 0 : 1;
    t->br = t->sol[best].flags;
    return 1;
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
    /* the closed-form solution itself when the step is the one to it */
    float x = t->cf ? t->qs[i] : q + t->dq[i];
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
    rep->measured = fk;
    rep->near_singular = 0;
    if (rep->sigma_min < t->sing_threshold) rep->near_singular = 1;
    if (fk && rep->pos_err <= t->pos_tol && rep->rot_err <= t->rot_tol)
        rep->state = DH_TRACK_OK;
    else
        rep->state = (unreach || !fk) ? DH_TRACK_UNREACHABLE : DH_TRACK_LAGGING;
}

/* q_out into t->q and t->v; the closed-form solution itself (t->cf) when
 * its step is within the bound as the box made it (track_put otherwise;
 * t->cf 0 when that moved it) */
static DH_NOINLINE void track_move(dh_track_f32 *t)
{
    uint32_t i;
    for (i = 0u; i < t->r->n; i++) {
        float x = t->qs[i];
        if (!t->cf || !(track_abs(x - t->q[i]) <= t->dq_max[i] * (1.0f - 4.76837158203125e-7f))) {
            x = track_put(t, i);
            if (!dh_feq_f32(x, t->qs[i])) t->cf = 0;
        }
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

/* The target's status (track_target_ok's) and, with a closed form, the
 * closed form's argument checks in t->ist (DH_ERR_UNAVAILABLE without
 * one). Those checks include track_target_ok's, in its order (q is finite):
 * their DH_OK, DH_ERR_NAN and DH_ERR_NOT_RIGID are the target's status. */
static DH_NOINLINE dh_status track_check(dh_track_f32 *t, const dh_mat4_f32 *target)
{
    if (t->m == NULL) {
        t->ist = DH_ERR_UNAVAILABLE;
        return track_target_ok(target);
    }
    t->ist = dh_ikc_args_f32_(t->m, target, t->q, DH_IKC_KEEP_OUT_OF_LIMITS);
    if (t->ist == DH_OK || t->ist == DH_ERR_NAN || t->ist == DH_ERR_NOT_RIGID) return t->ist;
    return track_target_ok(target);
}

/* The window of this period's pruned solve (dh_ikc_raw_win_f32_) in
 * t->ws[0..17], for a 6-joint wrist (with an FPU) or PARALLEL_234 model:
 * the reference q, joint i's canonical centre (q_i plus its offset in
 * (-180, 180]) and the distance
 *   th_i = tau vmax_i (1 + 1e-5) + 2e-4 + 4.8e-7 (|q_i| + |off_i| + |qmin_i|
 *          + |qmax_i| + 720),   tau = max_j dq_max_j / vmax_j (about dt)
 * (+inf for a prismatic joint or an unlimited rate); 1 when some th_i is
 * finite (the window can leave a solution out), else 0 (no window).
 *
 * Why the pruned solve gives the step of the full one whenever the box
 * holds its pick. track_pick returns the lexicographic minimum of (time,
 * sum, index) over the solutions within the limits; the pruned solve
 * returns a subset S of the full set, the same values in the same order,
 * so the same minimum whenever it is in S. Let P' be S's pick, in the box
 * with each step |s_i| <= dq_max_i (track_bound: the box is within it
 * unless its sides cross), so its time is at most tau; the
 * full pick P* is no slower, so each of its joints moves by at most
 * tau vmax_i (1 + 2^-21) from q_i after track_limit (whose clamp moves a
 * value by at most 1e-4). Its canonical value c_i differs from that value
 * by a whole number of turns, the offset and the roundings of the
 * conversion, track_limit and the centre (each within 2^-24 of at most the
 * terms summed above, 8 of them), so c_i is within th_i of the centre
 * modulo 360 and P* is in S: P' = P*, with the same values and flags, and
 * the step, its status and its report are those of the full solve. When
 * the box does not hold S's pick (or S is empty), the full solve follows:
 * the step is the full solve's in every case. */
static DH_NOINLINE int track_window(dh_track_f32 *t)
{
    const dh_ikc_model_f32 *m = t->m;
    float *const w = t->ws;
    float tau = 0.0f;
    uint32_t i;
    int any = 0;
    /* soft float: the wrist families solve every branch (ikc_impl.h) */
    if (m->n != 6u ||
        !(((m->kind == DH_IKC_WRIST_RRR || m->kind == DH_IKC_WRIST_RRP) && !DH_SOFT_FLOAT) ||
          m->kind == DH_IKC_PARALLEL_234))
        return 0;
    for (i = 0u; i < 6u; i++) {
        /* an unlimited rate (inf) adds no time; a finite rate with an
         * unbounded step makes tau inf (no window) */
        const float v = t->r->joint[i].vmax;
        if (dh_isfinite_f32(v) && !(t->dq_max[i] / v <= tau)) tau = t->dq_max[i] / v;
    }
    for (i = 0u; i < 6u; i++) {
        const dh_joint *j = &t->r->joint[i];
        const float lim = (j->qmin <= j->qmax) ? track_abs(j->qmin) + track_abs(j->qmax) : 0.0f;
        const float th = tau * j->vmax * (1.0f + 1e-5f) + 2e-4f +
                         4.8e-7f * (track_abs(t->q[i]) + track_abs(m->off[i]) + lim + 720.0f);
        w[i] = t->q[i];
        w[6u + i] = dh_ikc_ref_f32_(t->q[i] + m->off[i]);
        w[12u + i] = track_inf();
        if (j->type == DH_JOINT_REVOLUTE && dh_isfinite_f32(th)) {
            w[12u + i] = th;
            any = 1;
        }
    }
    return any;
}

/* 1 when every joint of the step t->dq is within its bound dq_max (the
 * box's sides cross beyond it only after dh_track_sync_f32 left a velocity
 * above the rate, with an acceleration limit) */
static DH_NOINLINE int track_bound(const dh_track_f32 *t)
{
    uint32_t i;
    for (i = 0u; i < t->r->n; i++)
        if (!(track_abs(t->dq[i]) <= t->dq_max[i])) return 0;
    return 1;
}

/* The step towards a valid target, the closed form's raw solutions (if
 * any) in t->sol, raw of them (into t->ns): the solution nearest in time
 * (t->have: there is one within the limits) and the step box; 1 when the
 * box holds it (t->dq the step to it, t->cf kept only then), else 0
 * (track_chase follows). */
static DH_NOINLINE int track_nearest(dh_track_f32 *t, uint32_t raw)
{
    t->ns = raw;
    t->unreach = 0;
    t->have = 0;
    if (t->m != NULL) {
        const dh_status st = (t->ist != DH_OK) ? t->ist
                                               : dh_ikc_finish_f32_(t->m, t->q, DH_IKC_KEEP_OUT_OF_LIMITS, t->sol,
                                                                    &t->ns);
        t->have = track_pick(t, st, &t->unreach);
    }
    if (track_box(t)) return 1;
    t->cf = 0;
    return 0;
}

/* t->J and t->T at t->q (a step that took the closed-form solution as it
 * is left them elsewhere: t->jq 0) */
static DH_NOINLINE void track_at(dh_track_f32 *t)
{
    if (!t->jq) (void)dh_kin_jacobian_f32_(t->r, t->q, t->J, &t->T, t->ws);
    t->jq = 1;
}

/* The step when the box does not hold the nearest solution (track_nearest
 * 0; t->J and t->T at q): where q already reaches the target, no step;
 * else, away from singularities, straight for that solution at the bound;
 * near them the damped step, unless it stalls or moves away from it;
 * without a solution the damped step. 1 when there is no closed form and
 * q does not reach the target (track_more follows). */
static DH_NOINLINE int track_chase(dh_track_f32 *t, const dh_mat4_f32 *target)
{
    const int have = t->have;
    int ok;
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

/* The closed form's rotation residual bound (ikc.h: 2e-6 rad). */
#define TRACK_CF_ROT 2e-6f

/* the error bound of a dh_sincos_f32 value (6.2e-8) of an angle that float
 * sums of total magnitude x degrees have rounded (2^-24 x each, 1.04e-9 x
 * in radians), with room: 1.3e-7 + 5e-9 x */
static float track_dtrig(float x)
{
    return 1.3e-7f + 5e-9f * x;
}

/* |v| less its error bound d, at least 0 */
static float track_low(float v, float d)
{
    const float x = track_abs(v) - d;
    return (x > 0.0f) ? x : 0.0f;
}

/* |det J| of the arm and wrist of the spherical-wrist families without
 * joint 5's factor (docs/design.md, "Tracking": |a2 v g| for R-R-R, |h g|
 * for R-R-P): its value into *w, a lower bound on the exact one returned */
static DH_NOINLINE float track_det_wrist(const dh_track_f32 *t, float *w)
{
    const dh_ikc_model_f32 *m = t->m;
    const float *a = m->a, t2 = t->q[1] + m->off[1], e = m->sa[2] * m->d[3];
    const float ae = track_abs(a[2]) + track_abs(e), d2 = track_dtrig(track_abs(t2));
    float s2, c2, s3, c3, h, dh, g, dg;
    (void)dh_sincos_f32(t2, &s2, &c2);
    if (m->kind == DH_IKC_WRIST_RRR) {
        const float t3 = t->q[2] + m->off[2], d3 = track_dtrig(track_abs(t3));
        (void)dh_sincos_f32(t3, &s3, &c3);
        h = a[2] * s3 - e * c3;
        dh = ae * (d3 + 2.4e-7f);
        g = a[0] + c2 * (a[1] + a[2] * c3 + e * s3) - m->ca[1] * s2 * h;
        dg = (track_abs(a[0]) + track_abs(a[1]) + 2.0f * ae) * (d2 + d3 + 6e-7f);
        *w = track_abs(a[1] * h * g);
        return track_abs(a[1]) * track_low(h, dh) * track_low(g, dg);
    }
    /* R-R-P: theta3 fixed, d3 = q3 + its offset */
    (void)dh_sincos_f32(m->off[2], &s3, &c3);
    h = t->q[2] + m->d[2] + m->d[3] * m->ca[2];
    dh = 2.4e-7f * (track_abs(t->q[2]) + track_abs(m->d[2]) + track_abs(m->d[3]));
    g = a[0] + c2 * (a[1] + a[2] * c3 + e * s3) + m->sa[1] * s2 * h;
    dg = (track_abs(a[0]) + track_abs(a[1]) + ae + track_abs(h) + dh) *
             (d2 + track_dtrig(track_abs(m->off[2])) + 6e-7f) + dh;
    *w = track_abs(h * g);
    return track_low(h, dh) * track_low(g, dg);
}

/* The same for axes 2, 3, 4 parallel: |a2 a3 s3 g| */
static DH_NOINLINE float track_det_par(const dh_track_f32 *t, float *w)
{
    const dh_ikc_model_f32 *m = t->m;
    const float *a = m->a, *q = t->q;
    const float s2 = dh_ikc_sign_f32_(m->ca[1]), s23 = s2 * dh_ikc_sign_f32_(m->ca[2]);
    const float t2 = q[1] + m->off[1], t3 = q[2] + m->off[2], t4 = q[3] + m->off[3];
    float sn2, c2, s3, c3, s4, c4, x, y, g, dg;
    (void)dh_sincos_f32(t2, &sn2, &c2);
    (void)dh_sincos_f32(t3, &s3, &c3);
    (void)dh_sincos_f32(t4, &s4, &c4);
    /* cos, sin of theta2 + s2 theta3 (x, y), then of + s23 theta4 */
    x = c2 * c3 - s2 * sn2 * s3;
    y = sn2 * c3 + s2 * c2 * s3;
    g = a[0] + a[1] * c2 + a[2] * x + a[3] * (x * c4 - s23 * y * s4) + s23 * m->sa[3] * m->d[4] * (y * c4 + s23 * x * s4);
    /* each sine or cosine of a sum within twice its terms' bounds and
     * 3e-7 of rounding; 4e-6: the twists the family takes as 0 or 90
     * degrees within 1e-6 */
    dg = (track_abs(a[0]) + track_abs(a[1]) + track_abs(a[2]) + track_abs(a[3]) + track_abs(m->d[4])) *
         (2.0f * (track_dtrig(track_abs(t2)) + track_dtrig(track_abs(t3)) + track_dtrig(track_abs(t4))) + 4.3e-6f);
    *w = track_abs(a[1] * a[2] * s3 * g);
    return track_abs(a[1] * a[2]) * track_low(s3, track_dtrig(track_abs(t3))) * track_low(g, dg);
}

/* joint 5's factor |sin(alpha4) sin(alpha5) sin(theta5)|: its value times
 * *w into *w, a lower bound on it times lb returned */
static DH_NOINLINE float track_det_five(const dh_track_f32 *t, float lb, float *w)
{
    const dh_ikc_model_f32 *m = t->m;
    const float t5 = t->q[4] + m->off[4], k = track_abs(m->sa[3] * m->sa[4]);
    float s5, c5;
    (void)dh_sincos_f32(t5, &s5, &c5);
    *w *= k * track_abs(s5);
    return lb * k * track_low(s5, track_dtrig(track_abs(t5)));
}

/* The report of a step that took the nearest closed-form solution as it
 * is (t->cf, q_out == t->qs), without FK or Jacobian, when the closed
 * form's residual bounds are within pos_tol and rot_tol and the Hong-Pan
 * bound from |det J| (closed form per family) proves sigma_min at or
 * above the threshold: 1 (rep written; t->J and t->T stay where they
 * were, t->jq 0); else 0 (track_end follows). */
static DH_NOINLINE int track_cheap(dh_track_f32 *t, dh_track_report_f32 *rep)
{
    float w = 0.0f, lb;
    if (!t->cf || !(t->hpg > 0.0f) || !(t->pos_tol >= t->cfp) || !(t->rot_tol >= TRACK_CF_ROT)) return 0;
    lb = (t->m->kind == DH_IKC_PARALLEL_234) ? track_det_par(t, &w) : track_det_wrist(t, &w);
    /* 1e-5: the products' rounding and the model's copy of the table */
    lb = track_det_five(t, lb, &w) * t->hpg * (1.0f - 1e-5f);
    if (!(lb >= t->sing_threshold) || !dh_isfinite_f32(w)) return 0;
    rep->state = DH_TRACK_OK;
    rep->pos_err = t->cfp;
    rep->rot_err = TRACK_CF_ROT;
    rep->manip = w;
    rep->sigma_min = lb;
    rep->near_singular = 0;
    rep->measured = 0;
    t->jq = 0;
    return 1;
}

/* The report at q_out (t->J, t->T recomputed there) */
static DH_NOINLINE void track_end(dh_track_f32 *t, const dh_mat4_f32 *target, dh_status tst, dh_track_report_f32 *rep)
{
    int fk = 0;
    rep->manip = 0.0f;
    rep->sigma_min = 0.0f;
    t->jq = 1;
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
    tst = track_check(t, target);
    t->unreach = 1;
    t->ns = 0u;
    t->cf = 0;
    if (tst != DH_OK) {
        t->have = 0;
        (void)track_box(t);
        track_brake(t);
    } else if (!(t->ist == DH_OK && track_window(t) &&
                 track_nearest(t, dh_ikc_raw_win_f32_(t->m, target, t->ws, t->sol)) && track_bound(t)) &&
               !track_nearest(t, (t->ist == DH_OK) ? dh_ikc_raw_f32_(t->m, target, t->q, t->sol) : 0u)) {
        /* the solutions within this period's window first: when the box
         * holds the nearest of them, it is the nearest of all
         * (track_window); else every solution. Neither box holds one. */
        track_at(t);
        if (track_chase(t, target)) track_more(t, target);
    } else {
        /* a closed-form solution in the box: t->dq is the step to it */
    }
    track_move(t);
    if (!track_cheap(t, rep)) track_end(t, target, tst, rep);
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
    t->jq = 1;
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
