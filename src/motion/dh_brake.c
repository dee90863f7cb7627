/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_brake.c - the brake of one coordinate to rest, shared by the queue's
 * stop (dh_queue.c) and the jerk-limited path moves' brake on a lag
 * (dh_move.c); method in docs/design.md, "Motion".
 *
 * A coordinate (a joint, or s of a path) brakes from its velocity v and
 * acceleration a (taken along the travel, v >= 0) in three phases: jerk
 * -j until the acceleration is -ap, -ap held, jerk +j back to 0 exactly
 * as the velocity reaches 0, where ap = min(A, sqrt(j v + a^2 / 2)) is
 * the least peak deceleration that stops in time (the shortest stop
 * within A and j). Without a jerk limit the deceleration A is applied at
 * once (v / A, distance v^2 / (2 A)). The distance is at most the one the
 * plan had left (the plan itself is one way to stop within the same
 * limits), and is capped there against rounding, so a brake never passes
 * the move's end.
 */
#include "dhmath/motion.h"
#include "../internal/dh_build.h"
#include "../internal/dh_floatops.h"
#include "motion_impl.h"

/* the brake b's distance at time tau (>= 0), before the cap (inlined in
 * the plan, so no frame of it lies under the plan's: the stack budget) */
DH_INLINE float brake_dist_in(const dh_brake_f32 *b, float tau)
{
    const float j = b->j, pk = b->ap, t1 = b->t[0], t2 = b->t[1], t3 = b->t[2];
    float x, v = b->v, a = b->a, u, r = tau;
    if (dh_feq_f32(b->s, 0.0f)) return 0.0f;
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

/* brake_dist_in, one copy for the evaluation */
static DH_NOINLINE float brake_dist(const dh_brake_f32 *b, float tau)
{
    return brake_dist_in(b, tau);
}

float dh_motion_brake_plan_f32_(dh_brake_f32 *b, float end)
{
    const float x = b->q, v = b->v, a = b->a, A = b->ap, j = b->j;
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
    b->s = s;
    b->v = vp;
    b->a = ap;
    b->ap = pk;
    b->t[0] = t1;
    b->t[1] = t2;
    b->t[2] = t3;
    b->x = 0.0f;
    b->end = end;
    if (!dh_feq_f32(s, 0.0f)) {
        float e;
        d = t1 + t2 + t3;
        e = brake_dist_in(b, d);
        if (!(e >= 0.0f)) e = 0.0f;
        b->x = (e < rem) ? e : rem;
    }
    return d;
}

float dh_motion_brake_at_f32_(const dh_brake_f32 *b, float tau, float tend)
{
    float x = b->x, q;
    if (tau < tend) {
        x = brake_dist(b, tau);
        if (!(x >= 0.0f)) x = 0.0f;
        if (x > b->x) x = b->x;
    }
    q = b->q + b->s * x;
    /* the rounding of the sum never passes the end */
    if ((b->s > 0.0f && q > b->end) || (b->s < 0.0f && q < b->end)) q = b->end;
    return q;
}
