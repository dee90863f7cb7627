/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_blend_q.c - a fixed-point sequence of line and arc moves blended at
 * their corners by superposition, the twin of dh_blend.c's sequences.
 * Integer only: no float, no 64-bit division (bit-serial quotients).
 * ("Line" below is either; an arc is named where it differs.)
 *
 * Planning (once per sequence) in a small normalised integer format
 * m 2^e (m a 32-bit mantissa in [2^31, 2^32), e an int32), every
 * operation truncated (within 2^-31 relative of its exact result; a
 * subtraction's relative error grows by the cancellation, at most 2^10
 * here: each difference is of a quantity and at most (1 - 2^-10) of it).
 * Notation of docs/design.md ("Blended corners", "Blended sequences"):
 * per line the bounds of s, V = min(Vt / L, wmax / th) and
 * a = min(At / L, wdmax / th), both lowered by 2^-10 (the margin that
 * covers the planning's rounding; Vt = vmax and At = amax on a line, on
 * an arc of radius rho dh_path_move_q's Vt = min(vmax,
 * sqrt(amax rho / sqrt 2)) and At = amax sqrt(1 - (Vt^2 / (amax rho))^2)).
 * A corner's tails take b_i = (63/128) a_i on a line, (7/16) a_i on an
 * arc, so that L1 b1 + L2 b2 <= (63/64) amax ((119/128) amax with an arc)
 * and th1 b1 + th2 b2 <= (63/64) wdmax for any signs (a brake in the
 * overlap included), and the overlap
 * tb = (1 - 2^-10) min(V_i / b_i, sqrt((128/191) / b_i),
 *      sqrt(2 R / (L1 b1 + 2 L2 b2)), sqrt((180/pi) wdmax / (16 th1 b1 th2 b2)),
 *      sqrt(amax rho_i / 16) / (L_i b_i) for each arc i)
 * rounded down to whole microseconds: the tail starts below the cruise
 * speed, fits half its line (tb^2 b (1 + b / a) <= 1, b / a <= 63/128),
 * keeps the tool point within R of the corner (also for a brake from
 * anywhere in the overlap; a chord is at most its arc), the cross term
 * of the two rotations within wdmax / 64, and an arc's centripetal
 * acceleration in the overlap within amax / 16 (the sum of the two is
 * convex in the time, so at most its larger end value): tangential and
 * centripetal together within (127/128) amax. An arc alone keeps its
 * tangential s'' L <= At and its centripetal acceleration within
 * Vt^2 / rho, perpendicular to it: within amax, as dh_path_move_q's.
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
#include "blend_q_impl.h"

/* ---- normalised integer format: m 2^e, m in [2^31, 2^32) or m == 0 ------ */

/* m in the high word, e + 2^30 in the low word: one uint64, passed and
 * returned in registers (the planners' frames stay small). Every value
 * the planning makes has |e| below 2^10 (its inputs are 32-bit integers,
 * each result a few products and quotients of them), so the biased
 * exponent stays within [0, 2^31) and decodes without a branch. */
typedef uint64_t bq_f;

#define BQ_BIAS 0x40000000u

/* 0 (m 0, e 0) */
#define BQ_ZERO ((bq_f)BQ_BIAS)

DH_INLINE uint32_t bq_m(bq_f a)
{
    return (uint32_t)(a >> 32);
}

DH_INLINE int32_t bq_e(bq_f a)
{
    return (int32_t)((uint32_t)a & 0x7FFFFFFFu) - (int32_t)BQ_BIAS;
}

DH_INLINE bq_f bq_pack(uint32_t m, int32_t e)
{
    return ((uint64_t)m << 32) | (uint32_t)((uint32_t)e + BQ_BIAS);
}

/* v 2^e, truncated to a 32-bit mantissa (for bq_addsub: the other
 * operations normalise by one bit) */
static DH_NOINLINE bq_f bq_make(uint64_t v, int32_t e)
{
    const unsigned n = dh_q_bitlen64(v);
    const uint32_t sh = 64u - (uint32_t)n;
    if (v == 0u) return bq_pack(0u, 0);
    /* the top bit to bit 63 (1 <= n <= 64), then the high word */
    return bq_pack((uint32_t)((v << sh) >> 32), e + (int32_t)n - 32);
}

/* v (exact; clz(0) is 32: m 0) */
static DH_NOINLINE bq_f bq_u(uint32_t v)
{
    const unsigned l = dh_port_clz(v);
    return bq_pack((uint32_t)((uint64_t)v << l), -(int32_t)l);
}

/* a b: the 64-bit product p of the mantissas from 16-bit halves (no
 * 64-bit multiply call on cores without one); both in [2^31, 2^32), so
 * p in [2^62, 2^64): its top 32 bits from bit 31 or 32 (or m 0 when an
 * operand is 0) */
static DH_NOINLINE bq_f bq_mul(bq_f a, bq_f b)
{
    const uint32_t x = bq_m(a), y = bq_m(b);
    const uint32_t x0 = x & 0xFFFFu, x1 = x >> 16, y0 = y & 0xFFFFu, y1 = y >> 16;
    const uint32_t p00 = x0 * y0, p01 = x0 * y1, p10 = x1 * y0, p11 = x1 * y1;
    const uint64_t mid = (uint64_t)p01 + p10;
    const uint64_t p = ((uint64_t)p11 << 32) + (mid << 16) + p00;
    const uint32_t hb = (uint32_t)(p >> 63), sh = 31u + hb;
    return bq_pack((uint32_t)(p >> sh), bq_e(a) + bq_e(b) + 31 + (int32_t)hb);
}

/* a / b for b != 0 (every divisor of the planning is a positive rate,
 * length, speed or duration): floor(a.m 2^32 / b.m) in (2^31, 2^33) (or
 * 0 when a is 0): the integer bit, then 32 restoring steps in 32 bits
 * (the bit shifted out carried), normalised by the integer bit */
static DH_NOINLINE bq_f bq_div(bq_f a, bq_f b)
{
    const uint32_t bm = bq_m(b), top = (uint32_t)(bq_m(a) >= bm);
    uint32_t r = bq_m(a) - bm * top, q = 0u, c, i;
    for (i = 0u; i < 32u; i++) {
        c = r >> 31;
        r <<= 1;
        q <<= 1;
        if (c != 0u || r >= bm) {
            r -= bm;
            q |= 1u;
        }
    }
    return bq_pack((uint32_t)((((uint64_t)top << 32) | q) >> top), bq_e(a) - bq_e(b) - 32 + (int32_t)top);
}

/* sqrt(a): m 2^k (k 29 or 30, e - k even) in [2^60, 2^62), so its root
 * is in [2^30, 2^31) (m 0 gives m 0) */
static DH_NOINLINE bq_f bq_sqrt(bq_f a)
{
    const int32_t e = bq_e(a);
    const unsigned k = 30u - ((uint32_t)e & 1u);
    return bq_pack(dh_q_isqrt62((uint64_t)bq_m(a) << k) << 1, (e - (int32_t)k) / 2 - 1);
}

/* 1 when a < b: by the biased exponent (0 for the value 0, below every
 * other's), then the mantissa */
DH_INLINE uint32_t bq_less(bq_f a, bq_f b)
{
    const uint32_t ka = ((uint32_t)a & 0x7FFFFFFFu) & (0u - (uint32_t)(bq_m(a) != 0u));
    const uint32_t kb = ((uint32_t)b & 0x7FFFFFFFu) & (0u - (uint32_t)(bq_m(b) != 0u));
    return (uint32_t)(ka < kb) | ((uint32_t)(ka == kb) & (uint32_t)(bq_m(a) < bq_m(b)));
}

/* 1 when a < b */
static DH_NOINLINE int bq_lt(bq_f a, bq_f b)
{
    return (int)bq_less(a, b);
}

/* a + b (sub 0) or max(a - b, 0) (sub 1), the smaller aligned to the
 * larger's exponent in 62 bits (bits below 2^-62 of the larger dropped) */
static DH_NOINLINE bq_f bq_addsub(bq_f a, bq_f b, int sub)
{
    bq_f x = a, y = b;
    uint64_t u, v;
    uint32_t d, lt;
    const uint32_t neg = bq_less(a, b);
    if (neg != 0u) {
        /* a + b = b + a; a - b is below 0 (0 below) */
        x = b;
        y = a;
    }
    /* x >= y: e(x) >= e(y), or y is 0 (v 0 whatever d: x + 0 is x) */
    d = (uint32_t)(bq_e(x) - bq_e(y));
    lt = (uint32_t)(d < 63u);
    d = d * lt + 63u * (1u - lt);
    u = (uint64_t)bq_m(x) << 30;
    v = ((uint64_t)bq_m(y) << 30) >> d;
    return bq_make((sub != 0) ? (u - v) & ((uint64_t)neg - 1u) : u + v, bq_e(x) - 30);
}

DH_INLINE bq_f bq_add(bq_f a, bq_f b)
{
    return bq_addsub(a, b, 0);
}

DH_INLINE bq_f bq_sub(bq_f a, bq_f b)
{
    return bq_addsub(a, b, 1);
}

/* a / 2 (exact; 0 stays 0: its exponent is never read) */
DH_INLINE bq_f bq_half(bq_f a)
{
    return a - 1u;
}

/* min(*x, y) into *x, y taken when *x is 0 (no bound yet) */
static void bq_min(bq_f *x, bq_f y)
{
    if (bq_m(*x) == 0u || bq_lt(y, *x)) *x = y;
}

/* a 2^k rounded down (or up when up), UINT32_MAX when it is 2^32 or more */
static DH_NOINLINE uint32_t bq_int(bq_f a, int32_t k, int up)
{
    const int32_t e = bq_e(a) + k;
    const uint32_t m = bq_m(a), u = (uint32_t)(up != 0);
    uint32_t sh;
    if (m == 0u) return 0u;
    /* m in [2^31, 2^32): 2^32 or more from e >= 1, below 1 from e <= -32 */
    if (e > 0) return UINT32_MAX;
    if (e <= -32) return u;
    sh = (uint32_t)(-e);
    return (uint32_t)(((uint64_t)m + (((uint64_t)u << sh) - u)) >> sh);
}

/* round(a 2^30) for 0 <= a < 2 */
DH_INLINE int32_t bq_q30(bq_f a)
{
    const uint32_t r = bq_int(a, 31, 0), h = (r >> 1) + (r & 1u);
    return (int32_t)h;
}

/* a normalised constant m 2^e (m in [2^31, 2^32)) */
#define BQ_C(m, e) (((uint64_t)(m) << 32) | (uint32_t)((uint32_t)(e) + BQ_BIAS))

/* 1, 10^6, and (each rounded down) 1e-6 (s per us), 63/128, 128/191,
 * 1 - 2^-10, 180/pi 2^16 / 16 */
#define BQ_ONE BQ_C(0x80000000u, -31)
#define BQ_MEGA BQ_C(0xF4240000u, -12)
#define BQ_MICRO BQ_C(2251799813u, -51)
#define BQ_TAIL BQ_C(0xFC000000u, -33)
#define BQ_HALF BQ_C(2878302690u, -32)
#define BQ_MARGIN BQ_C(0xFFC00000u, -32)
#define BQ_RAD2DEG BQ_C(3845054675u, -14)
/* 7/16 (an arc's tails), 1/16, 2^-1/2 (rounded down) */
#define BQ_TAIL_ARC BQ_C(0xE0000000u, -33)
#define BQ_SIXTEENTH BQ_C(0x80000000u, -35)
#define BQ_RSQRT2 BQ_C(0xB504F333u, -32)

/* every phase lasts less than 2^28 us (268 s): a line's five sum below
 * 2^31 */
#define BQ_DUR_MAX ((uint32_t)1 << 28)

/* min(a, b) */
DH_INLINE uint32_t bq_umin(uint32_t a, uint32_t b)
{
    const uint32_t lt = (uint32_t)(a < b);
    return b + (a - b) * lt;
}

/* us (a duration) in seconds */
DH_INLINE bq_f bq_sec(uint32_t us)
{
    return bq_mul(bq_u(us), BQ_MICRO);
}

/* ---- planning --------------------------------------------------------- */

/* The planning state of a line (u0, u1 the tails' inner speeds,
 * E = 1 - e0 - e1 the s left for the middle phases, v the cruise speed,
 * V and a the rates of s, b1 the end tail's acceleration; the start
 * tail's b0 in u0's words until bq_tails) is kept in the fields of its
 * scaling that are written last (s[0..3], t0, T; P[0..3] and Q[0..3]
 * until the phases are written), so the planners' frames stay small
 * (the 256 B guard): state i in the word pair of bq_wc. */
#define BQ_U0 0u
#define BQ_U1 1u
#define BQ_V 2u
#define BQ_RV 3u
#define BQ_RA 4u
#define BQ_B1 5u
#define BQ_EE 6u

/* the two words of state i of g (not BQ_V), the high one first */
static int32_t *bq_wc(dh_blend_seg_q *g, unsigned i)
{
    if (i < 2u) return &g->s[2u * i];
    if (i < BQ_B1) return &g->P[2u * (i - BQ_RV)];
    return &g->Q[2u * (i - BQ_B1)];
}

static void bq_put(dh_blend_seg_q *g, unsigned i, bq_f x)
{
    int32_t *w;
    if (i == BQ_V) {
        g->t0 = (uint32_t)(x >> 32);
        g->T = (uint32_t)x;
        return;
    }
    w = bq_wc(g, i);
    w[0] = (int32_t)(uint32_t)(x >> 32);
    w[1] = (int32_t)(uint32_t)x;
}

static bq_f bq_get(dh_blend_seg_q *g, unsigned i)
{
    const int32_t *w;
    if (i == BQ_V) return ((uint64_t)g->t0 << 32) | g->T;
    w = bq_wc(g, i);
    return ((uint64_t)(uint32_t)w[0] << 32) | (uint32_t)w[1];
}

/* dh_blend_rates_q_ (blend_q_impl.h): V = min(Vt / L, wmax / th),
 * a = min(At / L, wdmax / th) lowered by 2^-10 (Vt = vmax and At = amax
 * on a line, an arc's dh_path_move_q's: dh_motion_tool_va_q_), and the
 * tails' b = (63/128) a on a line, (7/16) a on an arc (states BQ_U0 and
 * BQ_B1, as bq_tails reads them). Each rate is a quotient of a
 * positive int32 (or an arc's Vt, At in [2^-1, 2^31)) by one (length and
 * angle at least 1 LSB), so within [2^-32, 2^31): always in the
 * planning's range. */
DH_NOINLINE void dh_blend_rates_q_(const dh_path_q *p, const dh_cart_limits_q *lim, dh_blend_seg_q *g)
{
    bq_f v = BQ_ZERO, a = BQ_ZERO;
    uint32_t at = 1u;
    if (p->length > 0) {
        const uint64_t va = dh_motion_tool_va_q_(p, lim);
        at = (uint32_t)va;
        bq_min(&v, bq_div(bq_u((uint32_t)(va >> 32)), bq_u((uint32_t)p->length)));
        bq_min(&a, bq_div(bq_u(at), bq_u((uint32_t)p->length)));
    }
    if (p->angle > 0) {
        bq_min(&v, bq_div(bq_u((uint32_t)lim->wmax), bq_u((uint32_t)p->angle)));
        bq_min(&a, bq_div(bq_u((uint32_t)lim->wdmax), bq_u((uint32_t)p->angle)));
    }
    /* an arc's At rounded to 0 (amax of a few LSB): a 0 with motion, which
     * dh_blend_line_q_ refuses */
    if (at == 0u) a = BQ_ZERO;
    v = bq_mul(v, BQ_MARGIN);
    a = bq_mul(a, BQ_MARGIN);
    bq_put(g, BQ_RV, v);
    bq_put(g, BQ_RA, a);
    a = bq_mul(a, (p->kind == (uint32_t)DH_PATH_ARC) ? BQ_TAIL_ARC : BQ_TAIL);
    bq_put(g, BQ_U0, a);
    bq_put(g, BQ_B1, a);
}

/* *tb = min(*tb, sqrt(n / d)) for d != 0 */
static void bq_min_sqrt(bq_f *tb, bq_f n, bq_f d)
{
    if (bq_m(d) != 0u) bq_min(tb, bq_sqrt(bq_div(n, d)));
}

/* The overlap (us, rounded down) of the corner between lines p1 and p2
 * (their rates and tails' accelerations b1, b2 in g1, g2: dh_blend_rates_q_)
 * within radius R and lim; 0 when the corner runs at rest (file
 * comment) */
static DH_NOINLINE uint32_t bq_overlap(const dh_path_q *p1, const dh_path_q *p2, dh_blend_seg_q *g1,
                                       dh_blend_seg_q *g2, dh_qpos R, const dh_cart_limits_q *lim)
{
    bq_f tb, x;
    uint32_t us, i;
    if (R <= 0 || bq_m(bq_get(g1, BQ_B1)) == 0u || bq_m(bq_get(g2, BQ_U0)) == 0u) return 0u;
    tb = bq_div(bq_get(g1, BQ_RV), bq_get(g1, BQ_B1));
    bq_min(&tb, bq_div(bq_get(g2, BQ_RV), bq_get(g2, BQ_U0)));
    bq_min_sqrt(&tb, BQ_HALF, bq_get(g1, BQ_B1));
    bq_min_sqrt(&tb, BQ_HALF, bq_get(g2, BQ_U0));
    /* L1 b1 + 2 L2 b2 */
    x = bq_mul(bq_u((uint32_t)p2->length), bq_get(g2, BQ_U0));
    x = bq_add(bq_mul(bq_u((uint32_t)p1->length), bq_get(g1, BQ_B1)), bq_add(x, x));
    bq_min_sqrt(&tb, bq_u(2u * (uint32_t)R), x);
    x = bq_mul(bq_mul(bq_u((uint32_t)p1->angle), bq_get(g1, BQ_B1)), bq_mul(bq_u((uint32_t)p2->angle), bq_get(g2, BQ_U0)));
    bq_min_sqrt(&tb, bq_mul(bq_u((uint32_t)lim->wdmax), BQ_RAD2DEG), x);
    /* each arc's centripetal acceleration in the overlap, (L s')^2 / rho
     * with s' <= b tb, within amax / 16: tb <= sqrt(amax rho / 16) / (L b) */
    for (i = 0u; i < 2u; i++) {
        const dh_path_q *p = (i == 0u) ? p1 : p2;
        if (p->kind == (uint32_t)DH_PATH_ARC) {
            x = bq_mul(bq_u((uint32_t)p->length), (i == 0u) ? bq_get(g1, BQ_B1) : bq_get(g2, BQ_U0));
            bq_min_sqrt(&tb, bq_mul(bq_mul(bq_u((uint32_t)lim->amax), bq_u((uint32_t)p->radius)), BQ_SIXTEENTH),
                        bq_mul(x, x));
        }
    }
    tb = bq_mul(tb, BQ_MARGIN);
    /* in us, at most BQ_DUR_MAX (a longer overlap belongs to lines too
     * long anyway: their scalings do not fit) */
    us = bq_int(bq_mul(tb, BQ_MEGA), 0, 0);
    return bq_umin(us, BQ_DUR_MAX);
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
static DH_NOINLINE bq_f bq_time(dh_blend_seg_q *g, bq_f b, uint32_t tb)
{
    const bq_f V = bq_get(g, BQ_RV), a = bq_get(g, BQ_RA), t = bq_sec(tb), u = bq_mul(b, t);
    const bq_f E = bq_sub(BQ_ONE, bq_half(bq_mul(u, t))), need = bq_need(V, a, BQ_ZERO, u);
    bq_f v = V, T = BQ_ZERO;
    if (!bq_lt(E, need))
        T = bq_div(bq_sub(E, need), V);
    else
        v = bq_sqrt(bq_add(bq_mul(a, E), bq_half(bq_mul(u, u))));
    return bq_add(bq_add(T, t), bq_div(bq_sub(bq_add(v, v), u), a));
}

/* the tails' speeds u0, u1 and the s left for the middle, E, of g's
 * tails (durations dur[0], dur[4]; accelerations b0 in the state BQ_U0,
 * b1 in BQ_B1, as dh_blend_rates_q_ puts them: any bits for a duration 0,
 * whose product with t = 0 is 0). Each tail takes at most 64/191 of the
 * line (bq_overlap's second bound), so E >= 63/191. */
static DH_NOINLINE void bq_tails(dh_blend_seg_q *g)
{
    const bq_f t0 = bq_sec(g->dur[0]), t4 = bq_sec(g->dur[4]);
    bq_put(g, BQ_U0, bq_mul(bq_get(g, BQ_U0), t0));
    bq_put(g, BQ_U1, bq_mul(bq_get(g, BQ_B1), t4));
    /* 1 - (e0 + e1) */
    bq_put(g, BQ_EE, bq_sub(BQ_ONE, bq_half(bq_add(bq_mul(bq_get(g, BQ_U0), t0), bq_mul(bq_get(g, BQ_U1), t4)))));
}

/* us = t 10^6 rounded up, 0 when it reaches BQ_DUR_MAX (out of range) */
DH_INLINE int bq_us(bq_f t, uint32_t *us)
{
    *us = bq_int(bq_mul(t, BQ_MEGA), 0, 1);
    return *us < BQ_DUR_MAX;
}

/* The cruise of the float twin's closed forms for g's rates: v and the
 * cruise's duration (us, rounded up) into g->dur[2]; 0 when it is out of
 * range. The tails' speeds are below V (bq_overlap's first bound). */
static DH_NOINLINE int bq_cruise(dh_blend_seg_q *g)
{
    int ok = 1;
    /* (u0^2 + u1^2) / 2, then the s to reach V from u0 and come down to
     * u1 (bq_need), in v's state (the planners' frames stay small) */
    bq_put(g, BQ_V, bq_half(bq_add(bq_mul(bq_get(g, BQ_U0), bq_get(g, BQ_U0)), bq_mul(bq_get(g, BQ_U1), bq_get(g, BQ_U1)))));
    bq_put(g, BQ_V, bq_div(bq_sub(bq_mul(bq_get(g, BQ_RV), bq_get(g, BQ_RV)), bq_get(g, BQ_V)), bq_get(g, BQ_RA)));
    g->dur[2] = 0u;
    if (!bq_lt(bq_get(g, BQ_EE), bq_get(g, BQ_V))) {
        ok = bq_us(bq_div(bq_sub(bq_get(g, BQ_EE), bq_get(g, BQ_V)), bq_get(g, BQ_RV)), &g->dur[2]);
        bq_put(g, BQ_V, bq_get(g, BQ_RV));
    } else {
        bq_put(g, BQ_V, bq_half(bq_add(bq_mul(bq_get(g, BQ_U0), bq_get(g, BQ_U0)), bq_mul(bq_get(g, BQ_U1), bq_get(g, BQ_U1)))));
        bq_put(g, BQ_V, bq_sqrt(bq_add(bq_mul(bq_get(g, BQ_RA), bq_get(g, BQ_EE)), bq_get(g, BQ_V))));
    }
    return ok;
}

/* the duration (us, rounded up) of phase k (1 or 3) at a between v and
 * the tail's speed (state u) into g->dur[k]; 0 when it is out of range */
static DH_NOINLINE int bq_ramp(dh_blend_seg_q *g, unsigned k, unsigned u)
{
    return bq_us(bq_div(bq_sub(bq_get(g, BQ_V), bq_get(g, u)), bq_get(g, BQ_RA)), &g->dur[k]);
}

/* t1 / 2 + tv + t3 / 2 (s) of g's middle durations into v's state (the
 * planners' frames stay small): bq_resolve's divisor */
static DH_NOINLINE void bq_middle_time(dh_blend_seg_q *g)
{
    bq_put(g, BQ_V, bq_add(bq_half(bq_add(bq_sec(g->dur[1]), bq_sec(g->dur[3]))), bq_sec(g->dur[2])));
}

/* v solved again from the distance with the rounded durations:
 * (E - u0 t1 / 2 - u1 t3 / 2) / (t1 / 2 + tv + t3 / 2) (the divisor is
 * positive: v > u0 makes dur[1] at least 1 us; in v's state from
 * bq_middle_time; the dividend in E's, its last use); 0 when it is below
 * a tail's speed (the rounding took the phase's room) */
static DH_NOINLINE int bq_resolve(dh_blend_seg_q *g)
{
    bq_put(g, BQ_EE, bq_sub(bq_get(g, BQ_EE), bq_half(bq_add(bq_mul(bq_get(g, BQ_U0), bq_sec(g->dur[1])),
                                                            bq_mul(bq_get(g, BQ_U1), bq_sec(g->dur[3]))))));
    bq_put(g, BQ_V, bq_div(bq_get(g, BQ_EE), bq_get(g, BQ_V)));
    return (bq_lt(bq_get(g, BQ_V), bq_get(g, BQ_U0)) | bq_lt(bq_get(g, BQ_V), bq_get(g, BQ_U1))) == 0;
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

/* s[k] from the phases, the rest to 1 (a few LSB: docs/design.md) added
 * to Q of the longest middle phase; 0 when the rest exceeds 2^-10 or an
 * s leaves [0, 1] (g no scaling then) */
static DH_NOINLINE int bq_starts(dh_blend_seg_q *g)
{
    int64_t s = 0;
    unsigned k, big = 1u;
    int ok;
    for (k = 2u; k < 4u; k++)
        if (g->dur[k] > g->dur[big]) big = k;
    for (k = 0u; k < 5u; k++) s += (int64_t)g->P[k] + g->Q[k];
    s = (int64_t)DH_Q30_ONE - s;
    ok = 0;
    if ((s >= -1048576) && (s <= 1048576)) { /* |s| <= 2^20 */
        g->Q[big] = (int32_t)((int64_t)g->Q[big] + s);
        ok = 1;
    }
    s = 0;
    for (k = 0u; k < 5u; k++) {
        g->s[k] = (int32_t)(uint32_t)s;
        s += (int64_t)g->P[k] + g->Q[k];
        ok &= (s >= 0) & (s <= DH_Q30_ONE);
    }
    return ok;
}

/* dh_blend_line_q_ (blend_q_impl.h): the phases of the file comment */
DH_NOINLINE int dh_blend_line_q_(dh_blend_seg_q *g)
{
    unsigned k;
    int ok;
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
    if (bq_m(bq_get(g, BQ_RA)) == 0u) return 0;
    bq_tails(g);
    ok = bq_cruise(g);
    ok &= bq_ramp(g, 1u, BQ_U0);
    ok &= bq_ramp(g, 3u, BQ_U1);
    if (ok == 0) return 0;
    bq_middle_time(g);
    ok = bq_resolve(g);
    bq_phase(g, 1u, bq_get(g, BQ_U0), bq_get(g, BQ_V));
    bq_phase(g, 0u, BQ_ZERO, bq_get(g, BQ_U0));
    bq_phase(g, 2u, bq_get(g, BQ_V), bq_get(g, BQ_V));
    bq_phase(g, 3u, bq_get(g, BQ_V), bq_get(g, BQ_U1));
    bq_phase(g, 4u, bq_get(g, BQ_U1), BQ_ZERO);
    /* each duration below 2^28: the sum is below 2^31 */
    g->T = g->dur[0] + g->dur[1] + g->dur[2] + g->dur[3] + g->dur[4];
    return ok & bq_starts(g);
}

/* the checks of dh_blend_seq_plan_q's arguments, in the order of its
 * statuses */
static DH_NOINLINE dh_status bq_check(const dh_path_q *p, uint32_t n, const dh_qpos *radius,
                                      const dh_cart_limits_q *lim)
{
    uint32_t k;
    if (n == 0u || lim->vmax <= 0 || lim->amax <= 0 || lim->wmax <= 0 || lim->wdmax <= 0) return DH_ERR_ARG;
    for (k = 0u; k < n; k++) {
        if (!dh_motion_path_ok_q_(&p[k])) return DH_ERR_ARG;
        if (p[k].length < 0 || p[k].angle < 0) return DH_ERR_ARG;
        if (p[k].kind == (uint32_t)DH_PATH_ARC && p[k].radius <= 0) return DH_ERR_ARG;
        if (k + 1u < n && (radius[k] < 0 || memcmp(&p[k].B, &p[k + 1u].A, sizeof p[k].B) != 0)) return DH_ERR_ARG;
    }
    return DH_OK;
}

/* 1 when the corner C keeps every point within R + 64 LSB of it inside
 * the int32 range (dh_blend_pos_q_: the blend's points are within dev + 2
 * LSB of it on lines, dev + 2 (4 LSB + 2^-26 rho) + 2 LSB with arcs,
 * rho < 2^30) */
static DH_NOINLINE int bq_inside(const dh_frame_q *C, dh_qpos R)
{
    unsigned i;
    for (i = 0u; i < 3u; i++) {
        const int64_t c = C->p[i];
        if (((c < 0) ? -c : c) > (int64_t)INT32_MAX - R - 64) return 0;
    }
    return 1;
}

/* (L1 b1 + 2 L2 b2) tb^2 / 2 (the bound of a brake too), rounded up:
 * the dev of the corner between lines p1 and p2 from its overlap tb (0
 * for 0) and tails b1, b2 */
static DH_NOINLINE dh_qpos bq_dev(const dh_path_q *p1, const dh_path_q *p2, uint32_t tb, bq_f b1, bq_f b2)
{
    const bq_f t = bq_sec(tb);
    bq_f x = bq_add(bq_mul(bq_u((uint32_t)p1->length), b1), bq_mul(bq_u((uint32_t)p2->length), bq_add(b2, b2)));
    x = bq_half(bq_mul(bq_mul(x, t), t));
    return (dh_qpos)bq_int(x, 0, 1);
}

/* dh_blend_corner_q_ (blend_q_impl.h): the overlap is 0 (at rest)
 * unless the pair so blended is shorter than at rest (the closed forms'
 * durations, bq_time) and the corner lies its radius and 64 LSB inside
 * the range (bq_inside) */
DH_NOINLINE void dh_blend_corner_q_(const dh_path_q *p1, const dh_path_q *p2, const dh_cart_limits_q *lim,
                                    dh_blend_seg_q *g)
{
    dh_blend_seg_q *const g1 = &g[0], *const g2 = &g[1];
    uint32_t tb = 0u;
    bq_f x;
    if (bq_inside(&p1->B, g1->dev)) tb = bq_overlap(p1, p2, g1, g2, g1->dev, lim);
    /* the dev of this tb (0 for 0) before the test below, which needs
     * neither line: fewer values live across its calls (the 256 B guard) */
    g1->dev = bq_dev(p1, p2, tb, bq_get(g1, BQ_B1), bq_get(g2, BQ_U0));
    if (tb > 0u) {
        /* blended: T1 + T2 - tb, at rest: R1 + R2 */
        x = bq_add(bq_time(g1, BQ_ZERO, 0u), bq_time(g2, BQ_ZERO, 0u));
        x = bq_sub(bq_add(x, bq_sec(tb)), bq_time(g1, bq_get(g1, BQ_B1), tb));
        if (!bq_lt(bq_time(g2, bq_get(g2, BQ_U0), tb), x)) {
            tb = 0u;
            g1->dev = 0;
        }
    }
    g1->dur[4] = tb;
    g2->dur[0] = tb;
}

/* 1 + 2^-11 (rounded down): the margin of a queued line's rates
 * (dh_blend_queue_line_q_) over its phases' */
#define BQ_UP BQ_C(0x80100000u, -31)

/* Z's v and a: the rates V and a of g's state times 1 + 2^-11, in units
 * of 2^-k of s (k <= 30 the largest that keeps both below 2^31), rounded
 * up */
static DH_NOINLINE void bq_warp_rates(dh_blend_seg_q *g, dh_profile_q *Z)
{
    const bq_f v = bq_mul(bq_get(g, BQ_RV), BQ_UP), a = bq_mul(bq_get(g, BQ_RA), BQ_UP);
    int32_t k = 30;
    while (bq_int(v, k, 1) > (uint32_t)INT32_MAX || bq_int(a, k, 1) > (uint32_t)INT32_MAX) k--;
    Z->v = (int32_t)bq_int(v, k, 1);
    Z->a = (int32_t)bq_int(a, k, 1);
}

/* Z's duration: t1 + t2 (t1 = dur[0] + dur[1], t2 = t1 + dur[2]), or
 * when longer t2 + v'/a3 + 1 us, rounded up: where the held deceleration
 * phase (P[3] = v' dur3, -2 Q[3] = a3 dur3^2) would reach rest, so that
 * Z's s' near its end, a (T - t) >= a3 (T - t), is not below the
 * line's. 0 when it reaches 2^30 us. */
static DH_NOINLINE uint32_t bq_warp_end(const dh_blend_seg_q *g)
{
    const uint32_t t1 = g->dur[0] + g->dur[1], t2 = t1 + g->dur[2];
    uint32_t tz = t1 + t2;
    if (g->Q[3] < 0 && g->P[3] > 0) {
        const bq_f x = bq_div(bq_mul(bq_u((uint32_t)g->P[3]), bq_u(g->dur[3])), bq_u((uint32_t)(-g->Q[3]) * 2u));
        const uint32_t e = bq_int(x, 0, 1);
        if (e >= ((uint32_t)1 << 30)) return 0u;
        if (t2 + e + 1u > tz) tz = t2 + e + 1u;
    }
    return (tz < ((uint32_t)1 << 30)) ? tz : 0u;
}

/* dh_blend_queue_line_q_ (blend_q_impl.h): Z's phase time from
 * xa = floor(ta 2^30 / T_Z) + 1, ta = T_Z - t2 (the bound computes
 * floor(xa T_Z / 2^30), in [ta, ta + 1] as T_Z < 2^30: its -a from at
 * most t2 on, its +a until at least T_Z - t2 >= t1) */
DH_NOINLINE int dh_blend_queue_line_q_(dh_blend_seg_q *g, const dh_path_q *p, const dh_cart_limits_q *lim,
                                       dh_profile_q *Z)
{
    uint32_t tz;
    int ok;
    dh_blend_rates_q_(p, lim, g);
    bq_warp_rates(g, Z);
    ok = dh_blend_line_q_(g);
    tz = bq_warp_end(g);
    Z->d = 0;
    Z->T = tz;
    Z->xj = 0;
    Z->xa = (tz > 0u) ? (dh_q30)(dh_q_ufloor30(tz - (g->dur[0] + g->dur[1] + g->dur[2]), tz) + 1u) : 0;
    Z->j = 0;
    Z->kind = (uint32_t)DH_PROFILE_TRAP;
    return ok & (int)((tz > 0u) || (g->T == 0u));
}

/* every corner at rest (for bq_build) */
static void bq_rest_all(dh_blend_seg_q *seg, uint32_t n)
{
    uint32_t k;
    for (k = 0u; k < n; k++) {
        seg[k].dur[0] = 0u;
        seg[k].dur[4] = 0u;
        seg[k].dev = 0;
    }
}

/* Every line's scaling with the tails of its corners as dh_blend_corner_q_ kept
 * them (none at the ends: bq_rest_sum), and its start t0: the sequence's
 * duration, UINT32_MAX when a scaling does not fit or the duration
 * reaches 2^31 us (then the caller plans every corner at rest: the
 * rest-to-rest scalings that bq_rest_sum made and summed, which fit) */
static DH_NOINLINE uint32_t bq_build(dh_blend_seg_q *seg, const dh_path_q *p, uint32_t n, const dh_cart_limits_q *lim)
{
    uint32_t k, t0 = 0u, bad = 0u;
    for (k = 0u; k < n; k++) {
        dh_blend_rates_q_(&p[k], lim, &seg[k]);
        bad |= (uint32_t)(dh_blend_line_q_(&seg[k]) == 0);
        seg[k].t0 = t0;
        /* t0 below 2^31 (else bad already) and a duration below 2^31: no wrap */
        t0 += seg[k].T - seg[k].dur[4];
        bad |= (uint32_t)(t0 >= (uint32_t)INT32_MAX);
    }
    return t0 | (0u - bad);
}

/* the lines' rest-to-rest durations summed (seg the scratch; every
 * overlap and dev 0): the sum, UINT32_MAX when a scaling does not fit or
 * the sum reaches 2^31 us */
static DH_NOINLINE uint32_t bq_rest_sum(dh_blend_seg_q *seg, const dh_path_q *p, uint32_t n,
                                        const dh_cart_limits_q *lim)
{
    uint32_t k, sum = 0u;
    for (k = 0u; k < n; k++) {
        seg[k].dur[0] = 0u;
        seg[k].dur[4] = 0u;
        seg[k].dev = 0;
        dh_blend_rates_q_(&p[k], lim, &seg[k]);
        if (!dh_blend_line_q_(&seg[k])) return UINT32_MAX;
        /* both below 2^31: the sum fits */
        sum += seg[k].T;
        if (sum >= (uint32_t)INT32_MAX) return UINT32_MAX;
    }
    return sum;
}

/* seg[k].dev = radius[k] for the n - 1 corners (dh_blend_corner_q_ reads
 * a corner's radius there) */
static DH_NOINLINE void bq_radii(dh_blend_seg_q *seg, const dh_qpos *radius, uint32_t n)
{
    uint32_t k;
    for (k = 0u; k + 1u < n; k++) seg[k].dev = radius[k];
}

/* seg[k] = the rates of line k (dh_blend_rates_q_), for
 * dh_blend_corner_q_, which reads them and leaves them */
static DH_NOINLINE void bq_rates_all(dh_blend_seg_q *seg, const dh_path_q *p, uint32_t n, const dh_cart_limits_q *lim)
{
    uint32_t k;
    for (k = 0u; k < n; k++) dh_blend_rates_q_(&p[k], lim, &seg[k]);
}

dh_status dh_blend_seq_plan_q(dh_blend_seq_q *sq, dh_blend_seg_q *seg, const dh_path_q *p, uint32_t n,
                              const dh_qpos *radius, const dh_cart_limits_q *lim)
{
    dh_status st;
    uint32_t rest, k, T;
    DH_ASSERT(sq != NULL && seg != NULL && p != NULL && lim != NULL);
    DH_ASSERT(n <= 1u || radius != NULL);
    st = bq_check(p, n, radius, lim);
    if (st != DH_OK) return st;
    rest = bq_rest_sum(seg, p, n, lim);
    if (rest == UINT32_MAX) return DH_ERR_OVERFLOW;
    T = rest;
    if (n > 1u) {
        /* each corner's overlap into seg[k].dur[4], seg[k + 1].dur[0], its
         * dev into seg[k].dev (its radius there on the call), for bq_build */
        bq_radii(seg, radius, n);
        bq_rates_all(seg, p, n, lim);
        for (k = 0u; k + 1u < n; k++) dh_blend_corner_q_(&p[k], &p[k + 1u], lim, &seg[k]);
        T = bq_build(seg, p, n, lim);
    }
    if (T >= rest) {
        /* at rest: the scalings and the sum of bq_rest_sum again */
        bq_rest_all(seg, n);
        T = bq_build(seg, p, n, lim);
    }
    sq->p = p;
    sq->seg = seg;
    sq->n = n;
    sq->T = T;
    return DH_OK;
}

/* ---- evaluation --------------------------------------------------------- */

/* dh_blend_s_q_ (blend_q_impl.h) */
DH_NOINLINE dh_q30 dh_blend_s_q_(const dh_blend_seg_q *g, uint32_t t)
{
    uint32_t k, x;
    int64_t s;
    if (t >= g->T) return DH_Q30_ONE;
    /* t < T = the sum of the durations: phase k < 5 */
    for (k = 0u; t >= g->dur[k]; k++) t -= g->dur[k];
    x = dh_q_ufloor30(t, g->dur[k]);
    s = (int64_t)g->s[k] + dh_q_rshr(dh_q_mul64(g->P[k], (int32_t)x), 30u) +
        dh_q_rshr(dh_q_mul64(g->Q[k], (int32_t)(((uint64_t)x * x) >> 30)), 30u);
    if (s < 0) return 0;
    return (s > DH_Q30_ONE) ? DH_Q30_ONE : (dh_q30)s;
}

/* 1 when g holds a scaling (durations summing to T, below 2^31 us; starts
 * in [0, 1]) */
static int bq_seg_ok(const dh_blend_seg_q *g)
{
    uint64_t sum = 0u;
    unsigned k;
    for (k = 0u; k < 5u; k++) {
        sum += g->dur[k];
        if ((uint32_t)g->s[k] > (uint32_t)DH_Q30_ONE) return 0;
    }
    return sum == g->T && g->T < (uint32_t)INT32_MAX;
}

/* dh_blend_rot_q_ (blend_q_impl.h): as quaternions q2(s2) qA2* q1(s1)
 * with q1(s1) = qB1 (cos f h1, -sin f h1 k1) (f = 1 - s1, line 1's slerp
 * from its end) and qA2, qB1 the unit quaternion of the same frame
 * (p1->B == p2->A) up to sign: +-q2(s2) (cos f h1, -sin f h1 k1) */
DH_NOINLINE void dh_blend_rot_q_(const dh_path_q *p1, const dh_path_q *p2, dh_q30 s1, dh_q30 s2, dh_frame_q *T)
{
    int32_t sn, cs;
    dh_quat_q q2, q;
    dh_sincos_q((dh_q16)dh_q_rshr(dh_q_mul64(s2, p2->h), 30u), &sn, &cs);
    dh_motion_turn_q_(&p2->qa, cs, sn, p2->k, &q2);
    dh_sincos_q((dh_q16)dh_q_rshr(dh_q_mul64(DH_Q30_ONE - s1, p1->h), 30u), &sn, &cs);
    dh_motion_turn_q_(&q2, cs, -sn, p1->k, &q);
    dh_motion_quat_rot_q_(&q, T);
}

/* dh_blend_pos_q_ (blend_q_impl.h) */
DH_NOINLINE int dh_blend_pos_q_(const dh_path_q *p2, dh_frame_q *T)
{
    unsigned i;
    int sat = 0;
    for (i = 0u; i < 3u; i++) {
        int64_t x = (int64_t)T->p[i] + T->r[0][i] - p2->A.p[i];
        if (x > INT32_MAX || x < INT32_MIN) {
            x = (x > 0) ? INT32_MAX : INT32_MIN;
            sat = 1;
        }
        T->p[i] = (dh_qpos)x;
    }
    return sat;
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
    const dh_path_q *p;
    dh_q30 s1, s2;
    uint32_t k;
    int sat;
    DH_ASSERT(sq != NULL && T != NULL);
    if (sq->n == 0u) return DH_ERR_ARG;
    if (t == 0u) return dh_path_eval_q(&sq->p[0], 0, T);
    k = bq_find(sq, t);
    g = &sq->seg[k];
    if (!bq_seg_ok(g)) return DH_ERR_ARG;
    if (k == 0u || t - g->t0 >= g->dur[0]) return dh_path_eval_q(&sq->p[k], dh_blend_s_q_(g, t - g->t0), T);
    /* in the overlap with the line before: the superposition */
    p = &sq->p[k - 1u];
    if (!bq_seg_ok(&g[-1]) || !dh_motion_path_ok_q_(&p[0]) || !dh_motion_path_ok_q_(&p[1])) return DH_ERR_ARG;
    s1 = dh_blend_s_q_(&g[-1], t - g[-1].t0);
    s2 = dh_blend_s_q_(g, t - g->t0);
    dh_motion_point_q_(&p[0], s1, T->p);
    dh_motion_point_q_(&p[1], s2, T->r[0]);
    sat = dh_blend_pos_q_(&p[1], T);
    dh_blend_rot_q_(&p[0], &p[1], s1, s2, T);
    return (sat != 0) ? DH_ERR_OVERFLOW : DH_OK;
}
