/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_profile_q.c - fixed-point rest-to-rest time scaling: the time-optimal
 * trapezoid and seven-phase profiles, the quintic of given duration,
 * uniform stretching and evaluation. Integer only: no float, no libm, no
 * 64-bit division (32x32 and 64x32 products, 32-bit and bit-serial
 * divisions).
 *
 * A profile is stored as its distance d (position LSB), its duration T
 * (whole microseconds) and the ratios xj = tj / T, xa = ta / T (Q2.30) of
 * its phases; the peaks v, a, j follow from them. Uniform stretching
 * (p(t) -> p(t / k)) keeps the ratios, so the shape in normalised time
 * x = t / T is fixed at planning and the duration only scales the rates.
 *
 * Planning (once per move) follows the float twin's closed forms
 * (Biagiotti & Melchiorri 2008, 3.4; docs/design.md, "Motion") in a
 * normalised integer format m 2^e (m a 32-bit mantissa in [2^31, 2^32),
 * e an int32 exponent): products of mantissas, bit-serial quotients, an
 * integer square root and Newton's cube root, each within 2^-31 relative.
 * The optimal duration is then rounded UP to whole microseconds after a
 * factor 1 + 2^-27 that covers those roundings, so T >= the analytic
 * minimum and every peak, computed from the ratios and T, is within its
 * limit; T exceeds the minimum by less than 1 us + 2^-26 T.
 *
 * Evaluation (per control period) is Q2.30 arithmetic on x = floor(t
 * 2^30 / T) (bit-serial): the first half of the shape in four phases
 * (jerk +, constant acceleration, jerk -, cruise), written with bounded
 * ratios (x / (xa - xj), x / xj, ...) so no intermediate exceeds 2^31 in
 * Q2.30; the second half is the mirror image from d back, so p(0) = 0 and
 * p(T) = d exactly. Velocity and acceleration are the peaks times the
 * shape's fractions, never above the peaks.
 */
#include "dhmath/motion.h"
#include "../internal/dh_qmath.h"
#include "motion_impl.h"

/* ---- normalised integer format: m 2^e, m in [2^31, 2^32) or 0 ------------ */

/* m in the high word, e (two's complement) in the low word: one uint64,
 * passed and returned in registers */
typedef uint64_t profq_x;

static uint32_t profq_m(profq_x a)
{
    return (uint32_t)(a >> 32);
}

static int32_t profq_e(profq_x a)
{
    const uint32_t w = (uint32_t)a;
    const uint32_t u = w - 0x80000000u;
    int32_t e = (int32_t)u;   /* w - 2^31, in range for w >= 2^31 */
    if (w < 0x80000000u) {
        e = (int32_t)w;
    } else {
        e -= INT32_MAX;
        e -= 1;
    }
    return e;
}

static profq_x profq_pack(uint32_t m, int32_t e)
{
    return ((uint64_t)m << 32) | (uint32_t)e;
}

/* a 2^k (a power of two times a: exact) */
static profq_x profq_ldexp(profq_x a, int32_t k)
{
    return (profq_m(a) == 0u) ? a : profq_pack(profq_m(a), profq_e(a) + k);
}

/* v 2^e rounded to a 32-bit mantissa (inline: one frame less on the
 * planners' deepest chains) */
DH_INLINE profq_x profq_make(uint64_t v, int32_t e)
{
    uint64_t x = v;
    uint32_t m;
    int32_t k;
    unsigned n;
    if (x == 0u) return 0u;
    n = 64u - dh_q_bitlen64(x);
    x <<= n;
    m = (uint32_t)(x >> 32);
    k = e - (int32_t)n + 32;
    if ((x & 0x80000000u) != 0u) {   /* round to nearest */
        if (m == 0xFFFFFFFFu) {
            m = 0x80000000u;
            k++;
        } else {
            m++;
        }
    }
    return profq_pack(m, k);
}

static profq_x profq_u(uint32_t v)
{
    return profq_make(v, 0);
}

/* a b exactly from four 16-bit partial products (no 64-bit multiply
 * call on cores without one: a leaf on the planners' deepest chains) */
static uint64_t profq_umul(uint32_t a, uint32_t b)
{
    const uint32_t al = a & 0xFFFFu, ah = a >> 16, bl = b & 0xFFFFu, bh = b >> 16;
    const uint32_t ll = al * bl, lh = al * bh, hl = ah * bl;
    const uint32_t mid = (ll >> 16) + (lh & 0xFFFFu) + (hl & 0xFFFFu);
    const uint32_t hi = ah * bh + (lh >> 16) + (hl >> 16) + (mid >> 16);
    return ((uint64_t)hi << 32) | ((mid << 16) | (ll & 0xFFFFu));
}

static DH_NOINLINE profq_x profq_mul(profq_x a, profq_x b)
{
    return profq_make(profq_umul(profq_m(a), profq_m(b)), profq_e(a) + profq_e(b));
}

/* a / b, b != 0: floor(a.m 2^32 / b.m) (< 2^33): the integer bit, then
 * 32 restoring steps in 32 bits (the bit shifted out of the remainder
 * carried) */
static DH_NOINLINE profq_x profq_div(profq_x a, profq_x b)
{
    const uint32_t bm = profq_m(b);
    uint32_t r = profq_m(a), q = 0u, c, i, top = 0u;
    if (r >= bm) {
        top = 1u;
        r -= bm;
    }
    for (i = 0; i < 32u; i++) {
        c = r >> 31;
        r <<= 1;
        q <<= 1;
        if (c != 0u || r >= bm) {
            r -= bm;
            q |= 1u;
        }
    }
    return profq_make(((uint64_t)top << 32) | q, profq_e(a) - profq_e(b) - 32);
}

/* a + b, both >= 0 */
static DH_NOINLINE profq_x profq_add(profq_x a, profq_x b)
{
    profq_x x = a, y = b;
    int32_t de;
    if (profq_m(b) == 0u) return a;
    if (profq_m(a) == 0u) return b;
    if (profq_e(a) < profq_e(b)) {
        x = b;
        y = a;
    }
    de = profq_e(x) - profq_e(y);
    return profq_make(((uint64_t)profq_m(x) << 31) +
                          (((uint32_t)de < 63u) ? (((uint64_t)profq_m(y) << 31) >> (uint32_t)de) : 0u),
                      profq_e(x) - 31);
}

/* 1 when a < b (both >= 0, normalised) */
static DH_NOINLINE int profq_lt(profq_x a, profq_x b)
{
    if (profq_m(a) == 0u || profq_m(b) == 0u) return profq_m(b) != 0u && profq_m(a) == 0u;
    if (profq_e(a) != profq_e(b)) return profq_e(a) < profq_e(b);
    return profq_m(a) < profq_m(b);
}

static DH_NOINLINE profq_x profq_sqrt(profq_x a)
{
    /* m 2^e = (m 2^k) 2^(e - k), k (29 or 30) of e's parity, m 2^k < 2^62 */
    const int32_t e = profq_e(a);
    const uint32_t ue = (uint32_t)e;
    unsigned k = 30u;
    if ((ue & 1u) != 0u) k = 29u;
    if (profq_m(a) == 0u) return a;
    return profq_make(dh_q_isqrt62((uint64_t)profq_m(a) << k), (e - (int32_t)k) / 2);
}

/* Newton's y <- (2 y + a / y^2) / 3 from 2^ceil((e + 32) / 3) (above the
 * root, within a factor 2: it decreases to the root; six steps) */
static DH_NOINLINE profq_x profq_cbrt(profq_x a)
{
    const int32_t e3 = profq_e(a) + 32;
    profq_x y;
    unsigned i;
    if (profq_m(a) == 0u) return a;
    y = profq_pack(0x80000000u, ((e3 >= 0) ? (e3 + 2) / 3 : -((-e3) / 3)) - 31);
    for (i = 0; i < 6u; i++)   /* 1/3 = 0xAAAAAAAB 2^-33 */
        y = profq_mul(profq_add(profq_ldexp(y, 1), profq_div(a, profq_mul(y, y))), profq_pack(0xAAAAAAABu, -33));
    return y;
}

/* a 2^k rounded down (up when up), *ovf set when it is 2^31 or more */
static DH_NOINLINE uint32_t profq_int(profq_x a, int32_t k, int up, int *ovf)
{
    const int32_t e = profq_e(a) + k;
    const uint32_t m = profq_m(a);
    uint32_t r, sh;
    if (m == 0u) return 0u;
    if (e >= 0) {
        *ovf = 1;
        return 0u;
    }
    sh = (uint32_t)(-e);
    if (sh >= 32u) return up ? 1u : 0u;
    r = m >> sh;
    if (up && (m & ((1u << sh) - 1u)) != 0u) r++;
    if (r >= 0x80000000u) *ovf = 1;
    return r;
}

/* seconds to microseconds: 10^6 = 4096000000 2^-12, and 10^6 (1 + 2^-27) */
#define PROFQ_US profq_pack(4096000000u, -12)
#define PROFQ_US_UP profq_pack(4096000031u, -12)

/* ---- planning ------------------------------------------------------------ */

/* |d| as a uint32 (2^31 for INT32_MIN) */
static uint32_t profq_abs(int32_t d)
{
    return dh_q_abs_u32(d);
}

/* x rounded down, held to lim (> 0) */
static uint32_t profq_peak(profq_x x, int32_t lim, int *ovf)
{
    return profq_lt(x, profq_u((uint32_t)lim)) ? profq_int(x, 0, 0, ovf) : (uint32_t)lim;
}

/* num / (ts r 2^-30): a rate over a phase of the ratio r (Q2.30, > 0) of
 * the duration ts (seconds) */
DH_INLINE profq_x profq_rate(profq_x num, profq_x ts, int32_t r)
{
    return profq_div(num, profq_mul(ts, profq_make((uint32_t)r, -30)));
}

/* The peaks of the profile of distance D (> 0), duration r[0] = T (us,
 * > 0) and ratios r[1] = xj, r[2] = xa (Q2.30) written over the limits
 * lim[0..2] they are held to (the rounding of the normalised format can
 * put one an ulp above); lim[2] is the jerk only for jerk != 0.
 * DH_ERR_OVERFLOW (lim partly written) when a ratio is 0 where its phase
 * exists or a peak rounds to 0. */
static DH_NOINLINE dh_status profq_peaks(uint32_t D, const profq_x *r, int32_t *lim, int jerk)
{
    int ovf = 0;
    const dh_q30 xj = (dh_q30)r[1], xa = (dh_q30)r[2];
    const profq_x ts = profq_div(profq_u((uint32_t)r[0]), PROFQ_US);   /* T in seconds */
    profq_x x;
    if (xa <= xj || (jerk && xj <= 0)) return DH_ERR_OVERFLOW;
    x = profq_rate(profq_u(D), ts, DH_Q30_ONE - xa);    /* v = |d| / (T (1 - xa)) */
    lim[0] = (int32_t)profq_peak(x, lim[0], &ovf);
    x = profq_rate(x, ts, xa - xj);                     /* a = v / (T (xa - xj)) */
    lim[1] = (int32_t)profq_peak(x, lim[1], &ovf);
    lim[2] = jerk ? (int32_t)profq_peak(profq_rate(x, ts, xj), lim[2], &ovf) : 0;   /* j = a / (T xj) */
    return (ovf || lim[0] == 0 || lim[1] == 0 || (jerk && lim[2] == 0)) ? DH_ERR_OVERFLOW : DH_OK;
}

/* p = the profile of distance d, r (T, xj, xa as profq_peaks) and the
 * peaks pk */
static void profq_write(dh_profile_q *p, int32_t d, const profq_x *r, const int32_t *pk, uint32_t kind)
{
    p->d = d;
    p->T = (uint32_t)r[0];
    p->xj = (dh_q30)r[1];
    p->xa = (dh_q30)r[2];
    p->v = pk[0];
    p->a = pk[1];
    p->j = pk[2];
    p->kind = kind;
}

/* p = no motion (d == 0): duration 0, ratios and peaks 0 */
static void profq_zero(dh_profile_q *p, uint32_t kind)
{
    p->d = 0;
    p->T = 0u;
    p->xj = 0;
    p->xa = 0;
    p->v = 0;
    p->a = 0;
    p->j = 0;
    p->kind = kind;
}

/* Duration (us, rounded up, see the file comment) and ratios of the phase
 * times t[0] = tj, t[1] = ta and the total t[2] = T (seconds), written
 * over them as integers: t[0] = T (us), t[1] = xj, t[2] = xa (Q2.30);
 * DH_ERR_OVERFLOW when T reaches 2^31 us. The ratios are
 * rounded so the rates do not grow: xj up (a longer jerk phase), xa up by
 * one LSB more when there is a cruise (xa - xj does not shrink, and
 * 1 / (1 - xa) grows by at most 2^-28, inside the margin 2^-27 of T);
 * without a cruise xa = 1/2 exactly and xa - xj >= 1/4 shrinks by less
 * than 2^-28 relative, inside the margin 2^-26 of T^2. */
static DH_NOINLINE dh_status profq_times(profq_x *t, int cruise, uint32_t kind)
{
    int ovf = 0;
    const uint32_t Tus = profq_int(profq_mul(t[2], PROFQ_US_UP), 0, 1, &ovf);
    dh_q30 xa = 0x20000000, xj = 0;
    if (ovf || Tus == 0u) return DH_ERR_OVERFLOW;
    if (cruise) {
        xa = (dh_q30)profq_int(profq_div(t[1], t[2]), 30, 1, &ovf) + 1;
        if (xa > 0x20000000) xa = 0x20000000;
    }
    if (kind == (uint32_t)DH_PROFILE_SCURVE) {
        xj = (dh_q30)profq_int(profq_div(t[0], t[2]), 30, 1, &ovf);
        if (xj < 1) xj = 1;
        if (2 * xj > xa) xj = xa / 2;
    }
    t[0] = Tus;
    t[1] = (uint32_t)xj;
    t[2] = (uint32_t)xa;
    return DH_OK;
}

/* the checks of the initialisers: DH_ERR_ARG for a limit <= 0 */
static int profq_bad(const int32_t *lim, unsigned n)
{
    unsigned i;
    for (i = 0; i < n; i++)
        if (lim[i] <= 0) return 1;
    return 0;
}

/* The phases tj, ta and the duration T (seconds) of the time-optimal
 * profile of |d| (> 0) within lim (jerk == 0: the trapezoid, tj = ta)
 * into t[0..2]; 1 when it cruises at vmax. */
static DH_NOINLINE int profq_plan(profq_x *t, uint32_t D, const int32_t *lim, int jerk)
{
    profq_x x, tA = 0u;
    t[1] = profq_div(profq_u((uint32_t)lim[0]), profq_u((uint32_t)lim[1]));
    t[0] = t[1];
    if (jerk) {
        tA = profq_div(profq_u((uint32_t)lim[1]), profq_u((uint32_t)lim[2])); /* jerk time to reach amax */
        if (!profq_lt(t[1], tA)) {         /* vmax jmax >= amax^2: ta = tA + vmax / amax */
            t[0] = tA;
            t[1] = profq_add(tA, t[1]);
        } else {                           /* tj = sqrt(vmax / jmax), ta = 2 tj */
            t[0] = profq_sqrt(profq_div(profq_u((uint32_t)lim[0]), profq_u((uint32_t)lim[2])));
            t[1] = profq_ldexp(t[0], 1);
        }
    }
    x = profq_div(profq_u(D), profq_u((uint32_t)lim[0]));
    if (!profq_lt(x, t[1])) {              /* vmax reached: T = |d| / vmax + ta */
        t[2] = profq_add(x, t[1]);
        return 1;
    }
    x = profq_div(profq_u(D), profq_u((uint32_t)lim[1]));
    if (!jerk) {                           /* T = 2 sqrt(|d| / amax) */
        t[1] = profq_sqrt(x);
        t[0] = t[1];
    } else if (!profq_lt(x, profq_ldexp(profq_mul(tA, tA), 1))) {
        /* |d| >= 2 amax^3 / jmax^2: amax reached, ta = tj/2 + sqrt(tj^2/4 + |d|/amax) */
        t[0] = tA;
        t[1] = profq_add(profq_ldexp(tA, -1), profq_sqrt(profq_add(profq_ldexp(profq_mul(tA, tA), -2), x)));
    } else {                               /* tj = cbrt(|d| / (2 jmax)), ta = 2 tj */
        t[0] = profq_cbrt(profq_ldexp(profq_div(profq_u(D), profq_u((uint32_t)lim[2])), -1));
        t[1] = profq_ldexp(t[0], 1);
    }
    t[2] = profq_ldexp(t[1], 1);
    return 0;
}

/* dh_motion_profile_q_ (motion_impl.h): the initialisers' common body,
 * in place: checks, d == 0, plan, ratios, peaks */
DH_NOINLINE dh_status dh_motion_profile_q_(dh_profile_q *p)
{
    profq_x t[3];
    int32_t lim[3];
    const int32_t d = p->d;
    const int jerk = p->j != 0;
    const uint32_t kind = jerk ? (uint32_t)DH_PROFILE_SCURVE : (uint32_t)DH_PROFILE_TRAP;
    int cruise;
    dh_status st;
    lim[0] = p->v;
    lim[1] = p->a;
    lim[2] = jerk ? p->j : 1;
    if (profq_bad(lim, 3u)) return DH_ERR_ARG;
    if (d == 0) {
        profq_zero(p, kind);
        return DH_OK;
    }
    cruise = profq_plan(t, profq_abs(d), lim, jerk);
    st = profq_times(t, cruise, kind);
    if (st == DH_OK) st = profq_peaks(profq_abs(d), t, lim, jerk);
    if (st == DH_OK) profq_write(p, d, t, lim, kind);
    return st;
}

dh_status dh_profile_trap_q(dh_profile_q *p, int32_t d, int32_t vmax, int32_t amax)
{
    dh_profile_q w = { 0, 0u, 0, 0, 0, 0, 0, 0u };
    dh_status st;
    DH_ASSERT(p != NULL);
    w.d = d;
    w.v = vmax;
    w.a = amax;
    st = dh_motion_profile_q_(&w);
    if (st == DH_OK) *p = w;
    return st;
}

dh_status dh_profile_scurve_q(dh_profile_q *p, int32_t d, int32_t vmax, int32_t amax, int32_t jmax)
{
    dh_profile_q w = { 0, 0u, 0, 0, 0, 0, 0, 0u };
    dh_status st;
    DH_ASSERT(p != NULL);
    if (jmax <= 0) return DH_ERR_ARG;
    w.d = d;
    w.v = vmax;
    w.a = amax;
    w.j = jmax;
    st = dh_motion_profile_q_(&w);
    if (st == DH_OK) *p = w;
    return st;
}

/* the quintic's peaks for d and T (us, > 0) into p, rounded up (so they
 * bound the evaluation; at least 1 when d != 0) */
static DH_NOINLINE dh_status profq_quintic_set(dh_profile_q *p, int32_t d, uint32_t T)
{
    /* 1.875 = 15/8, 10/sqrt(3) = 5.7735, 60: mantissas m 2^e */
    int ovf = 0;
    const profq_x ts = profq_div(profq_u(T), PROFQ_US);
    const profq_x r = profq_div(profq_u(profq_abs(d)), ts);
    const uint32_t v = profq_int(profq_mul(profq_pack(0xF0000000u, -31), r), 0, 1, &ovf);
    const uint32_t a = profq_int(profq_div(profq_mul(profq_pack(0xB8C088B8u, -29), r), ts), 0, 1, &ovf);
    const uint32_t j = profq_int(profq_div(profq_div(profq_mul(profq_pack(0xF0000000u, -26), r), ts), ts), 0, 1, &ovf);
    if (ovf) return DH_ERR_OVERFLOW;
    p->d = d;
    p->T = T;
    p->xj = 0;
    p->xa = 0;
    p->v = (int32_t)v;
    p->a = (int32_t)a;
    p->j = (int32_t)j;
    p->kind = (uint32_t)DH_PROFILE_QUINTIC;
    return DH_OK;
}

dh_status dh_profile_quintic_q(dh_profile_q *p, int32_t d, uint32_t T)
{
    DH_ASSERT(p != NULL);
    if (T == 0u || T >= 0x80000000u) return DH_ERR_ARG;
    return profq_quintic_set(p, d, T);
}

dh_status dh_profile_stretch_q(dh_profile_q *p, uint32_t T)
{
    profq_x r[3];
    int32_t lim[3];
    dh_status st;
    DH_ASSERT(p != NULL);
    if (T < p->T || T >= 0x80000000u) return DH_ERR_ARG;
    if (T == p->T) return DH_OK;
    if (p->d == 0) {                       /* nothing moves */
        p->T = T;
        return DH_OK;
    }
    if (p->kind == (uint32_t)DH_PROFILE_QUINTIC) return profq_quintic_set(p, p->d, T);
    /* the old peaks bound the new ones (they scale by 1/k, 1/k^2, 1/k^3) */
    lim[0] = p->v;
    lim[1] = p->a;
    lim[2] = (p->j > 0) ? p->j : 1;
    r[0] = T;
    r[1] = (uint32_t)p->xj;
    r[2] = (uint32_t)p->xa;
    st = profq_peaks(profq_abs(p->d), r, lim, p->kind == (uint32_t)DH_PROFILE_SCURVE);
    if (st == DH_OK) profq_write(p, p->d, r, lim, p->kind);
    return st;
}

/* ---- evaluation ---------------------------------------------------------- */

/* n / d in Q2.30, n < 2 d, d > 0 */
static DH_NOINLINE int32_t profq_ratio(int32_t n, int32_t d)
{
    return (int32_t)dh_q_udiv((uint32_t)n, (uint32_t)d, 30u);
}

/* a b / 2^sh rounded (a, b >= 0, a b < 2^63) */
static DH_NOINLINE int32_t profq_mulr(int32_t a, int32_t b, unsigned sh)
{
    return (int32_t)dh_q_rshr(dh_q_mul64(a, b), sh);
}

/* The first half of the seven-phase shape (trapezoid: xj == 0) at x in
 * [0, 1/2] (Q2.30): f[0] = position / |d|, f[1] = velocity / peak, f[2] =
 * acceleration / peak, all Q2.30 in [0, 1]. Position = v^ S, v^ = 1 / (1 -
 * xa) the peak velocity of the normalised shape. */
static DH_NOINLINE void profq_shape(const dh_profile_q *p, int32_t x, int32_t *f)
{
    const int32_t xj = p->xj, xa = p->xa, ua = xa - xj;
    const int32_t ca = DH_Q30_ONE - xa;
    const int32_t h = (int32_t)dh_q_udiv(0x20000000u, (uint32_t)ca, 30u); /* v^ / 2 */
    int32_t g, k, m, u, S;
    if (x < xj) {                          /* jerk +: S = x^3 / (6 xj ua) */
        g = profq_ratio(x, ua);
        k = profq_ratio(x, xj);
        m = profq_mulr(g, k, 30u);
        S = profq_mulr(m, x, 30u) / 6;
        f[1] = m / 2;
        f[2] = k;
    } else if (x < ua) {                   /* acceleration: S = (xj^2 / 6 + xj u / 2 + u^2 / 2) / ua */
        u = x - xj;
        k = profq_ratio(xj, ua);
        g = profq_ratio(u, ua);
        S = profq_mulr(k, xj, 30u) / 6 + profq_mulr(k, u, 31u) + profq_mulr(g, u, 31u);
        f[1] = profq_ratio(xj / 2 + u, ua);
        f[2] = DH_Q30_ONE;
    } else if (x < xa) {                   /* jerk -, u = xa - x: S = xa / 2 - u + u^3 / (6 xj ua) */
        u = xa - x;
        g = profq_ratio(u, ua);
        k = profq_ratio(u, xj);
        m = profq_mulr(g, k, 30u);
        S = xa / 2 - u + profq_mulr(m, u, 30u) / 6;
        f[1] = DH_Q30_ONE - m / 2;
        f[2] = k;
    } else {                               /* cruise */
        S = x - xa / 2;
        f[1] = DH_Q30_ONE;
        f[2] = 0;
    }
    f[0] = profq_mulr(h, S, 29u);
}

/* The quintic 10 x^3 - 15 x^4 + 6 x^5 at x in [0, 1/2]: f as profq_shape;
 * velocity 30 x^2 (1-x)^2 = 16 w^2 of its peak 15/8, acceleration
 * 60 w (1 - 2x) = 6 sqrt(3) w (1 - 2x) of its peak 10 / sqrt(3), w = x (1 - x). */
static DH_NOINLINE void profq_quintic_shape(int32_t x, int32_t *f)
{
    const int32_t c = 697415773;            /* 6 sqrt(3), Q5.26 */
    int64_t q = 6 * (int64_t)x - 15 * (int64_t)DH_Q30_ONE;
    const int32_t w = profq_mulr(x, DH_Q30_ONE - x, 30u);
    unsigned i;
    q = dh_q_rshr(q * x, 30u) + 10 * (int64_t)DH_Q30_ONE;
    for (i = 0; i < 3u; i++) q = dh_q_rshr(q * x, 30u);
    f[0] = (int32_t)q;
    f[1] = profq_mulr(w, w, 26u);
    f[2] = profq_mulr(profq_mulr(c, w, 30u), DH_Q30_ONE - 2 * x, 26u);
    if (f[1] > DH_Q30_ONE) f[1] = DH_Q30_ONE;
    if (f[2] > DH_Q30_ONE) f[2] = DH_Q30_ONE;
}

/* 1 when p's ratios and peaks are those of a profile (for d != 0) */
static int profq_valid(const dh_profile_q *p)
{
    if (p->T == 0u || p->T >= 0x80000000u || p->v <= 0 || p->a <= 0) return 0;
    if (p->kind == (uint32_t)DH_PROFILE_QUINTIC) return 1;
    if (p->kind != (uint32_t)DH_PROFILE_TRAP && p->kind != (uint32_t)DH_PROFILE_SCURVE) return 0;
    if (p->xj < 0 || p->xj > 0x10000000 || p->xa < 2 * p->xj || p->xa <= p->xj || p->xa > 0x20000000) return 0;
    if (p->kind == (uint32_t)DH_PROFILE_SCURVE) return (p->xj > 0) && (p->j > 0);
    return p->xj == 0;
}

dh_status dh_profile_eval_q(const dh_profile_q *p, uint32_t t, int32_t *pos, int32_t *vel, int32_t *acc)
{
    int32_t f[3], x, pm, vm, am;
    uint64_t pu;
    uint32_t tt;
    int back;
    DH_ASSERT(p != NULL && pos != NULL && vel != NULL && acc != NULL);
    if (p->d != 0 && !profq_valid(p)) return DH_ERR_ARG;
    if (p->d == 0 || t == 0u || t >= p->T) {
        *pos = (p->d != 0 && t >= p->T) ? p->d : 0;
        *vel = 0;
        *acc = 0;
        return DH_OK;
    }
    back = t > p->T - t;
    tt = back ? p->T - t : t;
    x = (int32_t)dh_q_ufloor30(tt, p->T);
    if (p->kind == (uint32_t)DH_PROFILE_QUINTIC) {
        profq_quintic_shape(x, f);
    } else {
        profq_shape(p, x, f);
    }
    pu = (uint64_t)profq_abs(p->d) * (uint32_t)f[0];   /* below 2^61 */
    pm = (int32_t)dh_q_rshr((int64_t)pu, 30u);
    vm = profq_mulr(p->v, f[1], 30u);
    am = profq_mulr(p->a, f[2], 30u);
    if (vm > p->v) vm = p->v;
    if (am > p->a) am = p->a;
    if (p->d < 0) {
        pm = -pm;
        vm = -vm;
        am = -am;
    }
    *pos = back ? (int32_t)((int64_t)p->d - pm) : pm;
    *vel = vm;
    *acc = back ? -am : am;
    return DH_OK;
}
