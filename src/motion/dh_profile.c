/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_profile.c - rest-to-rest time scaling: the time-optimal trapezoid and
 * seven-phase profiles, the quintic of given duration, uniform time
 * stretching and evaluation.
 *
 * Every profile is symmetric in time, so only its first half is
 * evaluated: for t > T/2 the outputs are those at T - t mirrored (p = d -
 * p(T - t), v = v(T - t), a = -a(T - t)); p(0) = 0 and p(T) = d exactly.
 * The trapezoid is the seven-phase profile with tj = 0 (no jerk phases).
 *
 * Time optimality (Biagiotti & Melchiorri 2008, 3.4, rest to rest): the
 * first half accelerates as hard as the limits allow, reaching the peak
 * acceleration A' = min(amax, sqrt(vmax jmax)) after tj = A'/jmax, and
 * cruises at vmax when the distance allows it; otherwise the peak velocity
 * is the largest the distance allows: with amax reached when
 * |d| >= 2 amax^3/jmax^2 (then ta = tj/2 + sqrt(tj^2/4 + |d|/amax)), else
 * tj = cbrt(|d| / (2 jmax)), ta = 2 tj. In every case the distance is
 * v (ta + tv) and T = 2 ta + tv.
 *
 * After the phase times are fixed, the peaks are recomputed from them
 * (v = |d| / (ta + tv), a = v / (ta - tj), j = a / tj) so that the
 * evaluation meets the distance, and held to the limits (a rounding can
 * put them an ulp above); the evaluation clamps |vel| and |acc| to the
 * peaks as well, so no output exceeds a limit.
 */
#include <float.h>
#include <math.h>

#include "dhmath/motion.h"
#include "../internal/dh_floatops.h"
#include "motion_impl.h"

/* v (> 0, finite) brought into [2^-60, 2^60] by at most two exact factors
 * 2^+-60 (float spans 2^-149 .. 2^128), *f multiplied by r for each
 * factor 2^60 and divided by r for each 2^-60 (r a power of two: exact) */
static float profile_scale(float v, float r, float *f)
{
    const float lo = 8.673617379884035e-19f, hi = 1.152921504606847e18f; /* 2^-60, 2^60 */
    float a = v;
    int i;
    for (i = 0; i < 2; i++) {
        if (a < lo) {
            a *= hi;
            *f *= r;
        }
        if (a > hi) {
            a *= lo;
            *f /= r;
        }
    }
    return a;
}

/* The square root (cube == 0) or the cube root (cube == 1) of n / m for
 * finite n >= 0, m > 0, without underflow or overflow of the quotient: n
 * and m are first brought into [2^-60, 2^60] by exact factors 2^+-60
 * (at most two each), whose root 2^+-30 or 2^+-20 goes into f; n / m is
 * then a normal float. The cube root: a first guess from the exponent bits
 * (within 4 %), four Newton steps y <- (2y + x/y^2)/3, each of which
 * squares the relative error. */
float dh_motion_root_f32_(float n, float m, int cube)
{
    const float s = cube ? 1048576.0f : 1073741824.0f;   /* 2^20 or 2^30 */
    float f = 1.0f, x, y;
    int i;
    if (!(n > 0.0f)) return 0.0f;
    x = profile_scale(n, 1.0f / s, &f);
    x /= profile_scale(m, s, &f);
    if (!cube) return dh_sqrt_f32(x) * f;
    y = dh_f32_from_bits(dh_f32_bits(x) / 3u + 709921077u);
    for (i = 0; i < 4; i++) y = (2.0f * y + x / (y * y)) * (1.0f / 3.0f);
    return y * f;
}

/* 1 when x is a finite float > 0 */
static int profile_pos(float x)
{
    return dh_isfinite_f32(x) && x > 0.0f;
}

/* The peaks of a trapezoid or seven-phase profile of distance D (> 0)
 * from its phase times (tj == 0: trapezoid), held to vl, al, jl, then
 * written to p with T and the kind. DH_ERR_OVERFLOW (p untouched) when a
 * time or a peak is not a positive finite float. */
static dh_status profile_finish(dh_profile_f32 *p, float d, float tj, float ta, float tv, float T,
                                float vl, float al, float jl, dh_profile_kind kind)
{
    float D = fabsf(d), v, a, j = 0.0f;
    v = D / (ta + tv);
    a = v / (ta - tj);
    if (v > vl) v = vl;
    if (a > al) a = al;
    if (!profile_pos(T) || !profile_pos(ta) || !profile_pos(v) || !profile_pos(a)) return DH_ERR_OVERFLOW;
    if (kind == DH_PROFILE_SCURVE) {
        j = a / tj;
        if (j > jl) j = jl;
        if (!profile_pos(tj) || !profile_pos(j)) return DH_ERR_OVERFLOW;
    }
    p->d = d;
    p->T = T;
    p->tj = tj;
    p->ta = ta;
    p->tv = tv;
    p->v = v;
    p->a = a;
    p->j = j;
    p->kind = (uint32_t)kind;
    return DH_OK;
}

/* p = the profile of d == 0: no motion, duration 0 */
static void profile_zero(dh_profile_f32 *p, float d, dh_profile_kind kind)
{
    p->d = d;
    p->T = 0.0f;
    p->tj = 0.0f;
    p->ta = 0.0f;
    p->tv = 0.0f;
    p->v = 0.0f;
    p->a = 0.0f;
    p->j = 0.0f;
    p->kind = (uint32_t)kind;
}

dh_status dh_profile_trap_f32(dh_profile_f32 *p, float d, float vmax, float amax)
{
    float D, ta, tv;
    DH_ASSERT(p != NULL);
    if (!dh_isfinite_f32(d) || !dh_isfinite_f32(vmax) || !dh_isfinite_f32(amax)) return DH_ERR_NAN;
    if (!(vmax > 0.0f) || !(amax > 0.0f)) return DH_ERR_ARG;
    D = fabsf(d);
    if (!(D > 0.0f)) {
        profile_zero(p, d, DH_PROFILE_TRAP);
        return DH_OK;
    }
    ta = vmax / amax;
    if (D / vmax >= ta) {   /* |d| >= vmax^2 / amax: vmax reached */
        tv = D / vmax - ta;
    } else {
        ta = dh_motion_root_f32_(D, amax, 0);
        tv = 0.0f;
    }
    return profile_finish(p, d, 0.0f, ta, tv, 2.0f * ta + tv, vmax, amax, 0.0f, DH_PROFILE_TRAP);
}

dh_status dh_profile_scurve_f32(dh_profile_f32 *p, float d, float vmax, float amax, float jmax)
{
    float D, tj, ta, tv, tA;
    DH_ASSERT(p != NULL);
    if (!dh_isfinite_f32(d) || !dh_isfinite_f32(vmax) || !dh_isfinite_f32(amax) || !dh_isfinite_f32(jmax)) {
        return DH_ERR_NAN;
    }
    if (!(vmax > 0.0f) || !(amax > 0.0f) || !(jmax > 0.0f)) return DH_ERR_ARG;
    D = fabsf(d);
    if (!(D > 0.0f)) {
        profile_zero(p, d, DH_PROFILE_SCURVE);
        return DH_OK;
    }
    tA = amax / jmax;                 /* jerk time to reach amax */
    if (vmax / amax >= tA) {          /* vmax jmax >= amax^2: amax reached on the way to vmax */
        tj = tA;
        ta = tj + vmax / amax;
    } else {
        tj = dh_motion_root_f32_(vmax, jmax, 0);
        ta = 2.0f * tj;
    }
    tv = D / vmax - ta;
    if (!(tv >= 0.0f)) {              /* vmax not reached */
        tv = 0.0f;
        if (D / amax >= 2.0f * tA * tA) { /* |d| >= 2 amax^3 / jmax^2: amax reached */
            tj = tA;
            ta = 0.5f * tj + dh_sqrt_f32(0.25f * tj * tj + D / amax);
        } else {
            tj = 0.7937005259840998f * dh_motion_root_f32_(D, jmax, 1); /* cbrt(1/2) */
            ta = 2.0f * tj;
        }
    }
    return profile_finish(p, d, tj, ta, tv, 2.0f * ta + tv, vmax, amax, jmax, DH_PROFILE_SCURVE);
}

/* The peaks of the quintic of distance d and duration T (> 0) written to
 * p: v = 15/8 |d|/T, a = 10/sqrt(3) |d|/T^2, j = 60 |d|/T^3.
 * DH_ERR_OVERFLOW (p untouched) when one is not finite. */
static dh_status profile_quintic_set(dh_profile_f32 *p, float d, float T)
{
    float r = fabsf(d) / T;
    float v = 1.875f * r, a = 5.773502691896258f * (r / T), j = 60.0f * ((r / T) / T);
    if (!dh_isfinite_f32(v) || !dh_isfinite_f32(a) || !dh_isfinite_f32(j)) return DH_ERR_OVERFLOW;
    p->d = d;
    p->T = T;
    p->tj = 0.0f;
    p->ta = 0.0f;
    p->tv = 0.0f;
    p->v = v;
    p->a = a;
    p->j = j;
    p->kind = (uint32_t)DH_PROFILE_QUINTIC;
    return DH_OK;
}

dh_status dh_profile_quintic_f32(dh_profile_f32 *p, float d, float T)
{
    DH_ASSERT(p != NULL);
    if (!dh_isfinite_f32(d) || !dh_isfinite_f32(T)) return DH_ERR_NAN;
    if (!(T > 0.0f)) return DH_ERR_ARG;
    return profile_quintic_set(p, d, T);
}

dh_status dh_profile_stretch_f32(dh_profile_f32 *p, float T)
{
    float k;
    DH_ASSERT(p != NULL);
    if (!dh_isfinite_f32(T)) return DH_ERR_NAN;
    if (T < p->T) return DH_ERR_ARG;
    if (!(T > p->T)) return DH_OK;
    if (!(p->T > 0.0f)) {             /* d == 0: nothing moves */
        p->T = T;
        return DH_OK;
    }
    if (p->kind == (uint32_t)DH_PROFILE_QUINTIC) return profile_quintic_set(p, p->d, T);
    k = T / p->T;
    /* the old peaks bound the new ones (they scale by 1/k, 1/k^2, 1/k^3);
     * profile_finish writes p only on success */
    return profile_finish(p, p->d, p->tj * k, p->ta * k, p->tv * k, T, p->v, p->a, p->j, (dh_profile_kind)p->kind);
}

/* The first half of p at 0 <= t <= T/2: magnitudes for a positive d */
static void profile_half(const dh_profile_f32 *p, float t, float *pos, float *vel, float *acc)
{
    float tj = p->tj, ta = p->ta, v = p->v, a = p->a, j = p->j, x, r, u;
    if (p->kind == (uint32_t)DH_PROFILE_QUINTIC) {
        x = t / p->T;
        r = fabsf(p->d);
        u = 1.0f - x;
        *pos = r * (x * x * x * (10.0f + x * (6.0f * x - 15.0f)));
        *vel = (r / p->T) * (30.0f * (x * x) * (u * u));
        *acc = ((r / p->T) / p->T) * (60.0f * x * u * (1.0f - 2.0f * x));
    } else if (t < tj) {                /* jerk +j */
        *acc = j * t;
        *vel = 0.5f * j * t * t;
        *pos = j * t * t * t * (1.0f / 6.0f);
    } else if (t < ta - tj) {           /* constant acceleration a */
        u = t - tj;
        x = 0.5f * a * tj;              /* velocity at the end of the jerk phase */
        *acc = a;
        *vel = x + a * u;
        *pos = a * tj * tj * (1.0f / 6.0f) + x * u + 0.5f * a * u * u;
    } else if (t < ta) {                /* jerk -j, from the end of the phase back */
        u = ta - t;
        *acc = j * u;
        *vel = v - 0.5f * j * u * u;
        *pos = 0.5f * v * ta - v * u + j * u * u * u * (1.0f / 6.0f);
    } else {                            /* cruise */
        *acc = 0.0f;
        *vel = v;
        *pos = 0.5f * v * ta + v * (t - ta);
    }
    if (*vel > p->v) *vel = p->v;
    if (*acc > p->a) *acc = p->a;
}

dh_status dh_profile_eval_f32(const dh_profile_f32 *p, float t, float *pos, float *vel, float *acc)
{
    float ph, vh, ah, sg;
    int back;
    DH_ASSERT(p != NULL && pos != NULL && vel != NULL && acc != NULL);
    if (isunordered(t, t)) return DH_ERR_NAN;
    if (!(t > 0.0f) || !(p->T > 0.0f)) {
        *pos = (t >= p->T) ? p->d : 0.0f;
        *vel = 0.0f;
        *acc = 0.0f;
        return DH_OK;
    }
    if (t >= p->T) {
        *pos = p->d;
        *vel = 0.0f;
        *acc = 0.0f;
        return DH_OK;
    }
    back = t > 0.5f * p->T;
    profile_half(p, back ? p->T - t : t, &ph, &vh, &ah);
    sg = (p->d < 0.0f) ? -1.0f : 1.0f;
    *pos = back ? p->d - sg * ph : sg * ph;
    *vel = sg * vh;
    *acc = back ? -sg * ah : sg * ah;
    return DH_OK;
}
