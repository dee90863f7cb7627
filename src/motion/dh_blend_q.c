/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_blend_q.c - a fixed-point sequence of line moves blended at their
 * corners by superposition, the twin of dh_blend.c's sequences. Integer
 * only: no float, no 64-bit division (bit-serial quotients).
 *
 * Planning (once per sequence) in a small normalised integer format
 * m 2^e (m a 32-bit mantissa in [2^31, 2^32), e an int32), every
 * operation truncated (within 2^-31 relative of its exact result; a
 * subtraction's relative error grows by the cancellation, at most 2^10
 * here: each difference is of a quantity and at most (1 - 2^-10) of it).
 * Notation of docs/design.md ("Blended corners", "Blended sequences"):
 * per line the bounds of s, V = min(vmax / L, wmax / th) and
 * a = min(amax / L, wdmax / th), both lowered by 2^-10 (the margin that
 * covers the planning's rounding). A corner's tails take
 * b_i = (63/128) a_i, so that L1 b1 + L2 b2 <= (63/64) amax and
 * th1 b1 + th2 b2 <= (63/64) wdmax for any signs (a brake in the
 * overlap included), and the overlap
 * tb = (1 - 2^-10) min(V_i / b_i, sqrt((128/191) / b_i),
 *      sqrt(2 R / (L1 b1 + 2 L2 b2)), sqrt((180/pi) wdmax / (16 th1 b1 th2 b2)))
 * rounded down to whole microseconds: the tail starts below the cruise
 * speed, fits half its line (tb^2 b (1 + b / a) <= 1, b / a = 63/128),
 * keeps the tool point within R of the corner (also for a brake from
 * anywhere in the overlap), and the cross term of the two rotations
 * within wdmax / 64.
 *
 * A line's scaling is five phases of constant s'' with whole-microsecond
 * durations: the start tail (b0, tb0), the acceleration at a to v, the
 * cruise, the deceleration at a to u1 = b1 tb1, the end tail (b1, tb1).
 * The middle durations are the float twin's (v = V with a cruise, else
 * v^2 = a (1 - e0 - e1) + (u0^2 + u1^2) / 2) rounded UP, and v is then
 * solved again from the distance with the rounded durations: the
 * distance grows with every duration and with v, so the new v is not
 * larger and the accelerations (v - u_i) / t are not larger either. Phase
 * k is held as its start s[k] and P[k] = s' dur, Q[k] = s'' dur^2 / 2
 * (Q2.30), so s = s[k] + P x + Q x^2 at x = time / dur (bit-serial,
 * Q2.30); s[k + 1] = s[k] + P[k] + Q[k] exactly, and the few LSB by which
 * the rounded phases miss 1 are added to Q of the longest middle phase,
 * so the line ends at s = 1 exactly.
 */
#include <string.h>

#include "dhmath/motion.h"
#include "dhmath/trig.h"
#include "../internal/dh_build.h"
#include "../internal/dh_qmath.h"
#include "motion_impl.h"

/* ---- normalised integer format: m 2^e, m in [2^31, 2^32) or m == 0 ------ */

/* m in the high word, e + 2^31 in the low word: one uint64, passed and
 * returned in registers (the planners' frames stay small) */
typedef uint64_t bq_f;

/* 0 (m 0, e 0) */
#define BQ_ZERO ((bq_f)0x80000000u)

#define BQ_BIAS 0x80000000u

DH_INLINE uint32_t bq_m(bq_f a)
{
    return (uint32_t)(a >> 32);
}

DH_INLINE int32_t bq_e(bq_f a)
{
    const uint32_t w = (uint32_t)a;
    uint32_t d;
    if (w >= BQ_BIAS) {
        d = w - BQ_BIAS;
        return (int32_t)d;
    }
    d = BQ_BIAS - w;
    return -(int32_t)d;
}

DH_INLINE bq_f bq_pack(uint32_t m, int32_t e)
{
    return ((uint64_t)m << 32) | (uint32_t)((uint32_t)e + BQ_BIAS);
}

/* v 2^e, truncated to a 32-bit mantissa */
DH_INLINE bq_f bq_make(uint64_t v, int32_t e)
{
    unsigned n;
    int32_t sh;
    if (v == 0u) return bq_pack(0u, 0);
    n = dh_q_bitlen64(v);
    sh = (int32_t)n;
    sh -= 32;
    if (n > 32u) {
        const unsigned r = n - 32u;
        return bq_pack((uint32_t)(v >> r), e + sh);
    }
    {
        const unsigned l = 32u - n;
        return bq_pack((uint32_t)(v << l), e + sh);
    }
}

/* a b: the 64-bit product of the mantissas from 16-bit halves (no
 * 64-bit multiply call on cores without one) */
static DH_NOINLINE bq_f bq_mul(bq_f a, bq_f b)
{
    const uint32_t x = bq_m(a), y = bq_m(b);
    const uint32_t x0 = x & 0xFFFFu, x1 = x >> 16, y0 = y & 0xFFFFu, y1 = y >> 16;
    const uint32_t p00 = x0 * y0, p01 = x0 * y1, p10 = x1 * y0, p11 = x1 * y1;
    const uint64_t mid = (uint64_t)p01 + p10;
    return bq_make(((uint64_t)p11 << 32) + (mid << 16) + p00, bq_e(a) + bq_e(b));
}

/* a / b for b != 0: floor(a.m 2^32 / b.m) (< 2^33): the integer bit,
 * then 32 restoring steps in 32 bits (the bit shifted out carried) */
static DH_NOINLINE bq_f bq_div(bq_f a, bq_f b)
{
    const uint32_t bm = bq_m(b);
    uint32_t r = bq_m(a), q = 0u, c, i, top = 0u;
    if (r == 0u || bm == 0u) return BQ_ZERO;
    if (r >= bm) {
        top = 1u;
        r -= bm;
    }
    for (i = 0u; i < 32u; i++) {
        c = r >> 31;
        r <<= 1;
        q <<= 1;
        if (c != 0u || r >= bm) {
            r -= bm;
            q |= 1u;
        }
    }
    return bq_make(((uint64_t)top << 32) | q, bq_e(a) - bq_e(b) - 32);
}

static DH_NOINLINE bq_f bq_sqrt(bq_f a)
{
    const int32_t e = bq_e(a);
    unsigned k = 30u;
    if (((uint32_t)e & 1u) != 0u) k = 29u;
    if (bq_m(a) == 0u) return a;
    return bq_make(dh_q_isqrt62((uint64_t)bq_m(a) << k), (e - (int32_t)k) / 2);
}

/* a + b (sub 0) or max(a - b, 0) (sub 1), the smaller aligned to the
 * larger's exponent in 62 bits */
static DH_NOINLINE bq_f bq_addsub(bq_f a, bq_f b, int sub)
{
    bq_f x = a, y = b;
    uint64_t u, v;
    int32_t de;
    uint32_t d;
    if (bq_m(b) == 0u) return a;
    if (bq_m(a) == 0u) return (sub != 0) ? a : b;
    if (bq_e(a) < bq_e(b)) {
        if (sub != 0) return bq_pack(0u, 0);
        x = b;
        y = a;
    }
    de = bq_e(x) - bq_e(y);
    d = (uint32_t)de;
    u = (uint64_t)bq_m(x) << 30;
    v = (d < 62u) ? ((uint64_t)bq_m(y) << 30) >> d : 0u;
    if (sub == 0) return bq_make(u + v, bq_e(x) - 30);
    return bq_make((u > v) ? u - v : 0u, bq_e(x) - 30);
}

DH_INLINE bq_f bq_add(bq_f a, bq_f b)
{
    return bq_addsub(a, b, 0);
}

DH_INLINE bq_f bq_sub(bq_f a, bq_f b)
{
    return bq_addsub(a, b, 1);
}

/* a / 2 (exact) */
DH_INLINE bq_f bq_half(bq_f a)
{
    return (bq_m(a) == 0u) ? a : bq_pack(bq_m(a), bq_e(a) - 1);
}

/* 1 when a < b */
static DH_NOINLINE int bq_lt(bq_f a, bq_f b)
{
    if (bq_m(a) == 0u || bq_m(b) == 0u) return bq_m(a) == 0u && bq_m(b) != 0u;
    if (bq_e(a) != bq_e(b)) return bq_e(a) < bq_e(b);
    return bq_m(a) < bq_m(b);
}

/* min(*x, y) into *x, y taken when *x is 0 (no bound yet) and y is not */
static void bq_min(bq_f *x, bq_f y)
{
    if (bq_m(y) != 0u && (bq_m(*x) == 0u || bq_lt(y, *x))) *x = y;
}

/* a 2^k rounded down (or up when up), UINT32_MAX when it is 2^32 or more */
static DH_NOINLINE uint32_t bq_int(bq_f a, int32_t k, int up)
{
    const int32_t e = bq_e(a) + k;
    const uint32_t m = bq_m(a);
    uint32_t sh, r;
    if (m == 0u) return 0u;
    if (e >= 0) return UINT32_MAX;
    if (e <= -33) return (up != 0) ? 1u : 0u;
    sh = (uint32_t)(-e);
    r = (sh >= 32u) ? 0u : m >> sh;
    if (up != 0 && ((uint64_t)r << sh) != m) r++;
    return r;
}

/* round(a 2^30) for 0 <= a < 2 */
DH_INLINE int32_t bq_q30(bq_f a)
{
    const uint32_t r = bq_int(a, 31, 0), h = (r >> 1) + (r & 1u);
    return (int32_t)h;
}

DH_INLINE bq_f bq_u(uint32_t v)
{
    return bq_make(v, 0);
}

/* 1e-6 (s per us), 63/128, 128/191, 1 - 2^-10, 180/pi 2^16 / 16 (each
 * rounded down) */
#define BQ_MICRO_M 2251799813u
#define BQ_MICRO_E (-51)
#define BQ_TAIL_M 63u
#define BQ_TAIL_E (-7)
#define BQ_HALF_M 2878302690u
#define BQ_HALF_E (-32)
#define BQ_MARGIN_M 1023u
#define BQ_MARGIN_E (-10)
#define BQ_RAD2DEG_M 3845054675u
#define BQ_RAD2DEG_E (-26 + 16 - 4)

DH_INLINE bq_f bq_k(uint32_t m, int32_t e)
{
    return bq_make(m, e);
}

/* us (a duration) in seconds */
DH_INLINE bq_f bq_sec(uint32_t us)
{
    return bq_mul(bq_u(us), bq_k(BQ_MICRO_M, BQ_MICRO_E));
}

/* ---- planning --------------------------------------------------------- */

/* The planning state of a line (u0, u1 the tails' inner speeds,
 * E = 1 - e0 - e1 the s left for the middle phases, v the cruise speed,
 * V and a the rates of s) is kept in the fields of its scaling that are
 * written last (s[], dev, t0, T; P[0..3] until the phases are written),
 * so the planners' frames stay small (the 256 B guard): state i in the
 * word pair of bq_wc. */
#define BQ_U0 0u
#define BQ_U1 1u
#define BQ_EE 2u
#define BQ_V 3u
#define BQ_RV 4u
#define BQ_RA 5u

/* the two words of state i of g (not BQ_V), the high one returned */
DH_INLINE const int32_t *bq_wc(const dh_blend_seg_q *g, unsigned i, const int32_t **lo)
{
    if (i == BQ_EE) {
        *lo = &g->dev;
        return &g->s[4];
    }
    if (i < 2u) {
        *lo = &g->s[2u * i + 1u];
        return &g->s[2u * i];
    }
    *lo = &g->P[2u * (i - BQ_RV) + 1u];
    return &g->P[2u * (i - BQ_RV)];
}

static void bq_put(dh_blend_seg_q *g, unsigned i, bq_f x)
{
    const int32_t hi = (int32_t)(uint32_t)(x >> 32), lo = (int32_t)(uint32_t)x;
    if (i == BQ_V) {
        g->t0 = (uint32_t)hi;
        g->T = (uint32_t)lo;
    } else if (i == BQ_EE) {
        g->s[4] = hi;
        g->dev = lo;
    } else if (i < 2u) {
        g->s[2u * i] = hi;
        g->s[2u * i + 1u] = lo;
    } else {
        g->P[2u * (i - BQ_RV)] = hi;
        g->P[2u * (i - BQ_RV) + 1u] = lo;
    }
}

DH_INLINE bq_f bq_get(const dh_blend_seg_q *g, unsigned i)
{
    const int32_t *hi, *lo;
    if (i == BQ_V) return ((uint64_t)g->t0 << 32) | g->T;
    hi = bq_wc(g, i, &lo);
    return ((uint64_t)(uint32_t)*hi << 32) | (uint32_t)*lo;
}

/* the rates V = min(vmax / L, wmax / th), a = min(amax / L, wdmax / th)
 * of s along the line p within lim (1/s, 1/s^2), lowered by 2^-10, into
 * g's state; both 0 when p has no length and no angle. DH_ERR_OVERFLOW
 * when a rate is 0 or 2^31 or more (out of the planning's range). */
static DH_NOINLINE dh_status bq_rates(const dh_path_q *p, const dh_cart_limits_q *lim, dh_blend_seg_q *g)
{
    bq_f v = BQ_ZERO, a = BQ_ZERO;
    if (p->length > 0) {
        bq_min(&v, bq_div(bq_u((uint32_t)lim->vmax), bq_u((uint32_t)p->length)));
        bq_min(&a, bq_div(bq_u((uint32_t)lim->amax), bq_u((uint32_t)p->length)));
    }
    if (p->angle > 0) {
        bq_min(&v, bq_div(bq_u((uint32_t)lim->wmax), bq_u((uint32_t)p->angle)));
        bq_min(&a, bq_div(bq_u((uint32_t)lim->wdmax), bq_u((uint32_t)p->angle)));
    }
    v = bq_mul(v, bq_k(BQ_MARGIN_M, BQ_MARGIN_E));
    a = bq_mul(a, bq_k(BQ_MARGIN_M, BQ_MARGIN_E));
    bq_put(g, BQ_RV, v);
    bq_put(g, BQ_RA, a);
    if ((p->length > 0 || p->angle > 0) && (bq_m(v) == 0u || bq_m(a) == 0u || bq_e(v) > 0 || bq_e(a) > 0))
        return DH_ERR_OVERFLOW;
    return DH_OK;
}

/* *tb = min(*tb, sqrt(n / d)) for d != 0 */
static void bq_min_sqrt(bq_f *tb, bq_f n, bq_f d)
{
    if (bq_m(d) != 0u) bq_min(tb, bq_sqrt(bq_div(n, d)));
}

/* b as bq_corner keeps a tail's acceleration: the end tail's in
 * Q[0..1] of its line (end 1), the start tail's in the state BQ_U0 */
static void bq_put_b(dh_blend_seg_q *g, int end, bq_f b)
{
    if (end != 0) {
        g->Q[0] = (int32_t)(uint32_t)(b >> 32);
        g->Q[1] = (int32_t)(uint32_t)b;
    } else {
        bq_put(g, BQ_U0, b);
    }
}

DH_INLINE bq_f bq_get_b(const dh_blend_seg_q *g, int end)
{
    if (end != 0) return ((uint64_t)(uint32_t)g->Q[0] << 32) | (uint32_t)g->Q[1];
    return bq_get(g, BQ_U0);
}

/* The overlap (us, rounded down) of the corner between lines p1 and p2
 * (their rates in g1, g2) within radius R and lim, its tails'
 * accelerations b1, b2 kept in g1, g2 (bq_put_b); 0 when the corner
 * runs at rest (file comment) */
static DH_NOINLINE uint32_t bq_overlap(const dh_path_q *p1, const dh_path_q *p2, dh_blend_seg_q *g1,
                                       dh_blend_seg_q *g2, dh_qpos R, const dh_cart_limits_q *lim)
{
    bq_f tb, x;
    uint32_t us;
    bq_put_b(g1, 1, bq_mul(bq_get(g1, BQ_RA), bq_k(BQ_TAIL_M, BQ_TAIL_E)));
    bq_put_b(g2, 0, bq_mul(bq_get(g2, BQ_RA), bq_k(BQ_TAIL_M, BQ_TAIL_E)));
    if (R <= 0 || bq_m(bq_get_b(g1, 1)) == 0u || bq_m(bq_get_b(g2, 0)) == 0u) return 0u;
    tb = bq_div(bq_get(g1, BQ_RV), bq_get_b(g1, 1));
    bq_min(&tb, bq_div(bq_get(g2, BQ_RV), bq_get_b(g2, 0)));
    bq_min_sqrt(&tb, bq_k(BQ_HALF_M, BQ_HALF_E), bq_get_b(g1, 1));
    bq_min_sqrt(&tb, bq_k(BQ_HALF_M, BQ_HALF_E), bq_get_b(g2, 0));
    /* L1 b1 + 2 L2 b2 */
    x = bq_mul(bq_u((uint32_t)p2->length), bq_get_b(g2, 0));
    x = bq_add(bq_mul(bq_u((uint32_t)p1->length), bq_get_b(g1, 1)), bq_add(x, x));
    bq_min_sqrt(&tb, bq_u(2u * (uint32_t)R), x);
    x = bq_mul(bq_mul(bq_u((uint32_t)p1->angle), bq_get_b(g1, 1)), bq_mul(bq_u((uint32_t)p2->angle), bq_get_b(g2, 0)));
    bq_min_sqrt(&tb, bq_mul(bq_u((uint32_t)lim->wdmax), bq_k(BQ_RAD2DEG_M, BQ_RAD2DEG_E)), x);
    tb = bq_mul(tb, bq_k(BQ_MARGIN_M, BQ_MARGIN_E));
    /* in us, capped below 2^29 (a longer overlap belongs to a line too
     * long anyway: its scaling does not fit) */
    us = bq_int(bq_mul(tb, bq_u(1000000u)), 0, 0);
    return (us > (uint32_t)INT32_MAX / 4u) ? (uint32_t)INT32_MAX / 4u : us;
}

/* (2 V^2 - u0^2 - u1^2) / (2 a): the s to reach V from u0 and come down to u1 */
DH_INLINE bq_f bq_need(bq_f V, bq_f a, bq_f u0, bq_f u1)
{
    return bq_div(bq_sub(bq_mul(V, V), bq_half(bq_add(bq_mul(u0, u0), bq_mul(u1, u1)))), a);
}

/* The duration (s) of the float twin's closed forms for a line with rates
 * V, a (g's state) and one tail (b, tb us): from rest at a to v, the
 * cruise, down at a to u = b tb, then the tail; v = V when the line
 * reaches it, else v^2 = a E + u^2 / 2 (E = 1 - b tb^2 / 2) */
static DH_NOINLINE bq_f bq_time(const dh_blend_seg_q *g, bq_f b, uint32_t tb)
{
    const bq_f V = bq_get(g, BQ_RV), a = bq_get(g, BQ_RA), t = bq_sec(tb), u = bq_mul(b, t);
    const bq_f E = bq_sub(bq_u(1u), bq_half(bq_mul(u, t))), need = bq_need(V, a, BQ_ZERO, u);
    bq_f v = V, T = BQ_ZERO;
    if (!bq_lt(E, need))
        T = bq_div(bq_sub(E, need), V);
    else
        v = bq_sqrt(bq_add(bq_mul(a, E), bq_half(bq_mul(u, u))));
    return bq_add(bq_add(T, t), bq_div(bq_sub(bq_add(v, v), u), a));
}

/* the tails' speeds u0, u1 and the s left for the middle, E, of g's
 * tails (durations dur[0], dur[4]; accelerations b0 in the state BQ_U0,
 * b1 in Q[0..1], as bq_corner keeps them: any value for a duration 0);
 * 0 when they leave none */
static DH_NOINLINE int bq_tails(dh_blend_seg_q *g)
{
    const bq_f t0 = bq_sec(g->dur[0]), t4 = bq_sec(g->dur[4]);
    bq_f e;
    bq_put(g, BQ_U0, bq_mul(bq_get(g, BQ_U0), t0));
    bq_put(g, BQ_U1, bq_mul(bq_get_b(g, 1), t4));
    e = bq_half(bq_add(bq_mul(bq_get(g, BQ_U0), t0), bq_mul(bq_get(g, BQ_U1), t4)));   /* e0 + e1 */
    if (!bq_lt(e, bq_u(1u))) return 0;
    bq_put(g, BQ_EE, bq_sub(bq_u(1u), e));
    return 1;
}

/* us = t 10^6 rounded up, 0 when it reaches 2^29 (out of range) */
DH_INLINE int bq_us(bq_f t, uint32_t *us)
{
    *us = bq_int(bq_mul(t, bq_u(1000000u)), 0, 1);
    return *us < (uint32_t)INT32_MAX / 4u;
}

/* the middle durations (us, rounded up) of the float twin's closed forms
 * for g's rates into g->dur[1..3], and v; 0 when out of range */
static DH_NOINLINE int bq_middle(dh_blend_seg_q *g)
{
    bq_f need, t = BQ_ZERO;
    if (bq_lt(bq_get(g, BQ_RV), bq_get(g, BQ_U0)) || bq_lt(bq_get(g, BQ_RV), bq_get(g, BQ_U1))) return 0;
    need = bq_need(bq_get(g, BQ_RV), bq_get(g, BQ_RA), bq_get(g, BQ_U0), bq_get(g, BQ_U1));
    if (!bq_lt(bq_get(g, BQ_EE), need)) {
        bq_put(g, BQ_V, bq_get(g, BQ_RV));
        t = bq_div(bq_sub(bq_get(g, BQ_EE), need), bq_get(g, BQ_RV));
    } else {
        need = bq_add(bq_mul(bq_get(g, BQ_U0), bq_get(g, BQ_U0)), bq_mul(bq_get(g, BQ_U1), bq_get(g, BQ_U1)));
        bq_put(g, BQ_V, bq_sqrt(bq_add(bq_mul(bq_get(g, BQ_RA), bq_get(g, BQ_EE)), bq_half(need))));
    }
    return bq_us(t, &g->dur[2]) &&
           bq_us(bq_div(bq_sub(bq_get(g, BQ_V), bq_get(g, BQ_U0)), bq_get(g, BQ_RA)), &g->dur[1]) &&
           bq_us(bq_div(bq_sub(bq_get(g, BQ_V), bq_get(g, BQ_U1)), bq_get(g, BQ_RA)), &g->dur[3]);
}

/* v solved again from the distance with the rounded durations:
 * (E - u0 t1 / 2 - u1 t3 / 2) / (t1 / 2 + tv + t3 / 2); 0 when it is
 * below a tail's speed (the rounding took the phase's room) */
static DH_NOINLINE int bq_resolve(dh_blend_seg_q *g)
{
    const bq_f t1 = bq_sec(g->dur[1]), t3 = bq_sec(g->dur[3]);
    bq_f n, den;
    n = bq_half(bq_add(bq_mul(bq_get(g, BQ_U0), t1), bq_mul(bq_get(g, BQ_U1), t3)));
    n = bq_sub(bq_get(g, BQ_EE), n);
    den = bq_add(bq_half(bq_add(t1, t3)), bq_sec(g->dur[2]));
    if (bq_m(den) == 0u) return 0;
    bq_put(g, BQ_V, bq_div(n, den));
    return !bq_lt(bq_get(g, BQ_V), bq_get(g, BQ_U0)) && !bq_lt(bq_get(g, BQ_V), bq_get(g, BQ_U1));
}

/* phase k's P = w dur and Q = +-|dw| dur / 2 (Q2.30) from its start
 * speed w, its end speed w2 */
static DH_NOINLINE void bq_phase(dh_blend_seg_q *g, unsigned k, bq_f w, bq_f w2)
{
    const bq_f t = bq_sec(g->dur[k]);
    const int neg = bq_lt(w2, w);
    const int32_t q = bq_q30(bq_half(bq_mul((neg != 0) ? bq_sub(w, w2) : bq_sub(w2, w), t)));
    g->P[k] = bq_q30(bq_mul(w, t));
    g->Q[k] = (neg != 0) ? -q : q;
}

/* s[k] from the phases, the rest to 1 added to Q of the longest middle
 * phase; 0 when an s leaves [0, 1] */
static DH_NOINLINE int bq_starts(dh_blend_seg_q *g)
{
    int64_t s = 0;
    unsigned k, big = 1u;
    for (k = 2u; k < 4u; k++)
        if (g->dur[k] > g->dur[big]) big = k;
    for (k = 0u; k < 5u; k++) s += (int64_t)g->P[k] + g->Q[k];
    s = (int64_t)DH_Q30_ONE - s;
    if (s > DH_Q30_ONE || s < -DH_Q30_ONE) return 0;
    g->Q[big] += (int32_t)s;
    s = 0;
    for (k = 0u; k < 5u; k++) {
        g->s[k] = (int32_t)s;
        s += (int64_t)g->P[k] + g->Q[k];
        if (s < 0 || s > DH_Q30_ONE) return 0;
    }
    return 1;
}

/* g = the scaling of a line (its rates in g's state, bq_rates) with its
 * tails (g->dur[0], dur[4] and their accelerations as bq_tails reads
 * them, set by the caller); 1 when the tails fit and every duration is
 * in range, 0 when not (g no scaling then); t0 and dev are the caller's
 * to set after */
static DH_NOINLINE int bq_seg(dh_blend_seg_q *g)
{
    unsigned k;
    for (k = 1u; k < 4u; k++) g->dur[k] = 0u;
    if (bq_m(bq_get(g, BQ_RV)) == 0u) {
        /* no motion: no time */
        for (k = 0u; k < 5u; k++) {
            g->s[k] = DH_Q30_ONE;
            g->P[k] = 0;
            g->Q[k] = 0;
        }
        g->dur[0] = 0u;
        g->dur[4] = 0u;
        g->T = 0u;
        return 1;
    }
    if (!bq_tails(g) || !bq_middle(g) || !bq_resolve(g)) return 0;
    bq_phase(g, 1u, bq_get(g, BQ_U0), bq_get(g, BQ_V));
    bq_phase(g, 0u, BQ_ZERO, bq_get(g, BQ_U0));
    bq_phase(g, 2u, bq_get(g, BQ_V), bq_get(g, BQ_V));
    bq_phase(g, 3u, bq_get(g, BQ_V), bq_get(g, BQ_U1));
    bq_phase(g, 4u, bq_get(g, BQ_U1), BQ_ZERO);
    /* each duration below 2^29: the sum fits 32 bits */
    g->T = g->dur[0] + g->dur[1] + g->dur[2] + g->dur[3] + g->dur[4];
    return g->T < (uint32_t)INT32_MAX && bq_starts(g);
}

/* the checks of dh_blend_seq_plan_q's arguments, in the order of its
 * statuses */
static DH_NOINLINE dh_status bq_check(const dh_path_q *p, uint32_t n, const dh_qpos *radius,
                                      const dh_cart_limits_q *lim)
{
    uint32_t k;
    if (n == 0u || lim->vmax <= 0 || lim->amax <= 0 || lim->wmax <= 0 || lim->wdmax <= 0) return DH_ERR_ARG;
    for (k = 0u; k < n; k++) {
        if (p[k].kind != (uint32_t)DH_PATH_LINE || !dh_motion_path_ok_q_(&p[k])) return DH_ERR_ARG;
        if (p[k].length < 0 || p[k].angle < 0) return DH_ERR_ARG;
        if (k + 1u < n && (radius[k] < 0 || memcmp(&p[k].B, &p[k + 1u].A, sizeof p[k].B) != 0)) return DH_ERR_ARG;
    }
    return DH_OK;
}

/* Corner k of the sequence: its overlap and its tails' b, kept for
 * bq_build: the overlap in seg[k].dur[4] and seg[k + 1].dur[0], the
 * tails' b by bq_overlap (bq_put_b); the overlap is 0
 * (at rest) unless the pair so blended is shorter than at rest (the
 * closed forms' durations, bq_time). The lines' rates go into the states
 * of seg[k] and seg[k + 1] (scratch). */
static DH_NOINLINE void bq_corner(dh_blend_seg_q *seg, const dh_path_q *p, uint32_t k, const dh_qpos *radius,
                                  const dh_cart_limits_q *lim)
{
    dh_blend_seg_q *g1 = &seg[k], *g2 = &seg[k + 1u];
    uint32_t tb;
    bq_f x;
    (void)bq_rates(&p[k], lim, g1);
    (void)bq_rates(&p[k + 1u], lim, g2);
    tb = bq_overlap(&p[k], &p[k + 1u], g1, g2, radius[k], lim);
    if (tb > 0u) {
        /* blended: T1 + T2 - tb, at rest: R1 + R2 */
        x = bq_add(bq_time(g1, BQ_ZERO, 0u), bq_time(g2, BQ_ZERO, 0u));
        x = bq_sub(bq_add(x, bq_sec(tb)), bq_time(g1, bq_get_b(g1, 1), tb));
        if (!bq_lt(bq_time(g2, bq_get_b(g2, 0), tb), x)) tb = 0u;
    }
    g1->dur[4] = tb;
    g2->dur[0] = tb;
}

/* (L1 b1 + 2 L2 b2) tb^2 / 2 (the bound of a brake too), rounded up:
 * corner k's dev from its overlap tb and tails b */
static DH_NOINLINE dh_qpos bq_dev(const dh_path_q *p, uint32_t tb, const bq_f b[2])
{
    const bq_f t = bq_sec(tb);
    bq_f x = bq_add(bq_mul(bq_u((uint32_t)p[0].length), b[0]), bq_mul(bq_u((uint32_t)p[1].length), bq_add(b[1], b[1])));
    x = bq_half(bq_mul(bq_mul(x, t), t));
    return (dh_qpos)bq_int(x, 0, 1);
}

/* Line k's tails (g->dur[0], dur[4]) as bq_corner kept them (both 0
 * at rest: bq_rest_all), none at the ends of the sequence, and its rates
 * into its state; its corner's dev (0 at rest) */
static DH_NOINLINE dh_qpos bq_prep(dh_blend_seg_q *seg, const dh_path_q *p, uint32_t k, uint32_t n,
                                   const dh_cart_limits_q *lim)
{
    dh_blend_seg_q *g = &seg[k];
    dh_qpos dev = 0;
    if (k == 0u) g->dur[0] = 0u;
    if (k + 1u >= n) g->dur[4] = 0u;
    if (g->dur[4] > 0u) {
        bq_f c[2];
        c[0] = bq_get_b(g, 1);
        c[1] = bq_get_b(&seg[k + 1u], 0);
        dev = bq_dev(&p[k], g->dur[4], c);
    }
    (void)bq_rates(&p[k], lim, g);
    return dev;
}

/* every corner at rest (for bq_build) */
static void bq_rest_all(dh_blend_seg_q *seg, uint32_t n)
{
    uint32_t k;
    for (k = 0u; k < n; k++) {
        seg[k].dur[0] = 0u;
        seg[k].dur[4] = 0u;
    }
}

/* Every line's scaling with the tails of its corners as bq_corner kept
 * them (bq_prep), and its start t0: the sequence's duration, or
 * UINT32_MAX when a scaling does not fit or the duration reaches 2^31 us */
static DH_NOINLINE uint32_t bq_build(dh_blend_seg_q *seg, const dh_path_q *p, uint32_t n, const dh_cart_limits_q *lim)
{
    uint32_t k, t0 = 0u;
    for (k = 0u; k < n; k++) {
        const dh_qpos dev = bq_prep(seg, p, k, n, lim);
        if (!bq_seg(&seg[k])) return UINT32_MAX;
        seg[k].dev = dev;
        seg[k].t0 = t0;
        /* both below 2^31: the sum fits */
        t0 += seg[k].T - seg[k].dur[4];
        if (t0 >= (uint32_t)INT32_MAX) return UINT32_MAX;
    }
    return t0;
}

/* the lines' rates checked, then their rest-to-rest durations summed
 * (seg the scratch): the sum, UINT32_MAX on overflow */
static DH_NOINLINE uint32_t bq_rest_sum(dh_blend_seg_q *seg, const dh_path_q *p, uint32_t n,
                                        const dh_cart_limits_q *lim)
{
    uint32_t k, sum = 0u;
    for (k = 0u; k < n; k++) {
        if (bq_rates(&p[k], lim, &seg[k]) != DH_OK) return UINT32_MAX;
        seg[k].dur[0] = 0u;
        seg[k].dur[4] = 0u;
        if (!bq_seg(&seg[k])) return UINT32_MAX;
        /* both below 2^31: the sum fits */
        sum += seg[k].T;
        if (sum >= (uint32_t)INT32_MAX) return UINT32_MAX;
    }
    return sum;
}

dh_status dh_blend_seq_plan_q(dh_blend_seq_q *sq, dh_blend_seg_q *seg, const dh_path_q *p, uint32_t n,
                              const dh_qpos *radius, const dh_cart_limits_q *lim)
{
    dh_status st;
    uint32_t rest, T, k;
    DH_ASSERT(sq != NULL && seg != NULL && p != NULL && lim != NULL);
    DH_ASSERT(n <= 1u || radius != NULL);
    st = bq_check(p, n, radius, lim);
    if (st != DH_OK) return st;
    rest = bq_rest_sum(seg, p, n, lim);
    if (rest == UINT32_MAX) return DH_ERR_OVERFLOW;
    T = UINT32_MAX;
    if (n > 1u) {
        for (k = 0u; k + 1u < n; k++) bq_corner(seg, p, k, radius, lim);
        T = bq_build(seg, p, n, lim);
    }
    if (T >= rest) {
        bq_rest_all(seg, n);
        T = bq_build(seg, p, n, lim);
    }
    if (T == UINT32_MAX) return DH_ERR_OVERFLOW;
    sq->p = p;
    sq->seg = seg;
    sq->n = n;
    sq->T = T;
    return DH_OK;
}

/* ---- evaluation --------------------------------------------------------- */

/* s (Q2.30) of the scaling g at its time t (us; t >= g->T: 1) */
static DH_NOINLINE dh_q30 bq_s(const dh_blend_seg_q *g, uint32_t t)
{
    uint32_t k, x, start = 0u;
    uint64_t x2;
    if (t >= g->T) return DH_Q30_ONE;
    for (k = 0u; k < 5u; k++) {
        if (t - start < g->dur[k]) break;
        start += g->dur[k];
    }
    if (k >= 5u) return DH_Q30_ONE;
    x = dh_q_ufloor30(t - start, g->dur[k]);
    x2 = ((uint64_t)x * x) >> 30;
    return (dh_q30)((int64_t)g->s[k] + dh_q_rshr(dh_q_mul64(g->P[k], (int32_t)x), 30u) +
                    dh_q_rshr((int64_t)g->Q[k] * (int64_t)x2, 30u));
}

/* 1 when g holds a scaling (durations summing to T, starts in [0, 1]) */
static int bq_seg_ok(const dh_blend_seg_q *g)
{
    uint64_t sum = 0u;
    unsigned k;
    for (k = 0u; k < 5u; k++) {
        sum += g->dur[k];
        if (g->s[k] < 0 || g->s[k] > DH_Q30_ONE) return 0;
    }
    return sum == g->T && g->T < (uint32_t)INT32_MAX;
}

/* Line 2's turn at s2 in the world: its slerp qa (cos s h, sin s h k)
 * is Exp(2 s h k_w) R_A2 with k_w = R_A2 k, so the overlap's rotation
 * is Exp(2 s2 h k_w) R1; w = (cos s2 h, sin s2 h k_w) */
static DH_NOINLINE void bq_axis(const dh_path_q *p2, dh_q30 s2, int32_t w[4])
{
    int32_t sn;
    unsigned i;
    dh_sincos_q((dh_q16)dh_q_rshr(dh_q_mul64(s2, p2->h), 30u), &sn, &w[0]);
    for (i = 0u; i < 3u; i++) {
        const int64_t x = dh_q_mul64(p2->A.r[0][i], p2->k[0]) + dh_q_mul64(p2->A.r[1][i], p2->k[1]) +
                          dh_q_mul64(p2->A.r[2][i], p2->k[2]);
        w[1u + i] = (int32_t)dh_q_rshr(dh_q_rshr(x, 30u) * sn, 30u);
    }
}

/* the column v turned by the unit quaternion w: v + w0 t + u x t,
 * t = 2 u x v (u = w[1..3]) */
static DH_NOINLINE void bq_col(const int32_t w[4], int32_t v[3])
{
    int32_t t[3];
    unsigned i;
    for (i = 0u; i < 3u; i++) {
        const unsigned a = (i + 1u) % 3u, b = (i + 2u) % 3u;
        t[i] = (int32_t)dh_q_rshr(dh_q_mul64(w[1u + a], v[b]) - dh_q_mul64(w[1u + b], v[a]), 29u);
    }
    for (i = 0u; i < 3u; i++) {
        const unsigned a = (i + 1u) % 3u, b = (i + 2u) % 3u;
        v[i] = (int32_t)((int64_t)v[i] + dh_q_rshr(dh_q_mul64(w[0], t[i]) + dh_q_mul64(w[1u + a], t[b]) -
                                                      dh_q_mul64(w[1u + b], t[a]),
                                                  30u));
    }
}

/* T's position moved by line 2's: + (p2(s2) - p_A2), held to int32 */
static DH_NOINLINE void bq_move(const dh_path_q *p2, dh_q30 s2, dh_frame_q *T)
{
    unsigned i;
    for (i = 0u; i < 3u; i++) {
        int64_t x = (int64_t)T->p[i] + dh_motion_lerp_q_(p2->A.p[i], p2->B.p[i], s2) - p2->A.p[i];
        if (x > INT32_MAX) x = INT32_MAX;
        if (x < INT32_MIN) x = INT32_MIN;
        T->p[i] = (dh_qpos)x;
    }
}

/* T (line 1's frame) turned and moved by line 2 at s2 (called after
 * line 1's dh_path_eval_q, so their frames are apart: the 256 B guard) */
static DH_NOINLINE void bq_turn(const dh_path_q *p2, dh_q30 s2, dh_frame_q *T)
{
    int32_t w[4];
    unsigned j;
    bq_axis(p2, s2, w);
    for (j = 0u; j < 3u; j++) bq_col(w, T->r[j]);
    bq_move(p2, s2, T);
}

/* the line running at t (the last with t0 <= t) */
static uint32_t bq_find(const dh_blend_seq_q *sq, uint32_t t)
{
    uint32_t k = 0u;
    while (k + 1u < sq->n && sq->seg[k + 1u].t0 <= t) k++;
    return k;
}

dh_status dh_blend_seq_eval_q(const dh_blend_seq_q *sq, uint32_t t, dh_frame_q *T)
{
    const dh_blend_seg_q *g;
    uint32_t k;
    DH_ASSERT(sq != NULL && T != NULL);
    if (sq->n == 0u) return DH_ERR_ARG;
    if (t == 0u) return dh_path_eval_q(&sq->p[0], 0, T);
    k = bq_find(sq, t);
    g = &sq->seg[k];
    if (!bq_seg_ok(g)) return DH_ERR_ARG;
    if (k == 0u || g->dur[0] == 0u || t - g->t0 >= g->dur[0])
        return dh_path_eval_q(&sq->p[k], bq_s(g, t - g->t0), T);
    /* in the overlap with the line before: the superposition */
    if (!bq_seg_ok(&sq->seg[k - 1u]) || !dh_motion_path_ok_q_(&sq->p[k])) return DH_ERR_ARG;
    if (dh_path_eval_q(&sq->p[k - 1u], bq_s(&sq->seg[k - 1u], t - sq->seg[k - 1u].t0), T) != DH_OK)
        return DH_ERR_ARG;
    bq_turn(&sq->p[k], bq_s(g, t - g->t0), T);
    return DH_OK;
}
