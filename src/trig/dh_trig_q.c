/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_trig_q.c - fixed-point sine/cosine of Q16.16 degrees as Q2.30
 * (contract in include/dhmath/trig.h). Integer only: no float, no libm,
 * no division except one by the constant 3 where a 32x32->64 multiply
 * exists (the compiler makes it a multiply-high); 32x32->64 multiplies
 * only.
 *
 * Method (as the float path):
 *  1. u = |x| as an unsigned magnitude (0 .. 2^31; INT32_MIN is never
 *     negated as a signed value). Whole degrees n = u >> 16 (0..32768),
 *     fraction fr = u & 0xFFFF (f = fr / 65536 degree).
 *  2. n = 90 q + m, q = floor(n / 90) by an exact 32-bit multiply-shift,
 *     m in 0..89, quadrant k = q mod 4. The table indices m and 90 - m are
 *     in 0..90 for every input.
 *  3. T = f in radians in units of 2^-37 (T < 2^31.2); sin f = T - T^3/6
 *     and 1 - cos f = T^2/2 - T^4/24 in the same units (omitted terms
 *     t^5/120 < 0.02 LSB of Q2.30, t^6/720 < 1e-4 LSB). The corrections
 *     C sin f - S (1 - cos f) and C (1 - cos f) + S sin f (S = sin m,
 *     C = cos m) are formed in 64 bits in units of 2^-67 and rounded once:
 *     table value (0.5 LSB) + one rounding (0.5 LSB) + approximation and
 *     intermediate rounding (< 0.05 LSB).
 *  4. The first-quadrant results are clamped to [0, 1.0] (where the true
 *     values lie), then the quadrant symmetry and the input sign are
 *     applied to magnitudes <= 2^30 (never overflows).
 * Every shift is of an unsigned value; no signed overflow is possible.
 */
#include "dhmath/trig.h"
#include "dh_trig_tables.h"

#define DH_TRIG_KT    2398762259u   /* round(pi/180 * 2^37) */
#define DH_TRIG_INV3  1431655765u   /* round(2^32 / 3) */
#define DH_TRIG_Q30   0x40000000u
/* ceil(2^23 / 90): (n * DH_TRIG_DIV90_32) >> 23 == n / 90 for n <= 32768,
 * in 32 bits (n * 93207 < 2^32). The constant exceeds 2^23/90 by d < 0.25,
 * so the estimate exceeds n/90 by n d / 2^23 < 1e-3, less than the distance
 * 1/90 from n/90 (fraction at most 89/90) to the next integer. */
#define DH_TRIG_DIV90_32 93207u

/* uint32 holding the two's complement of a value in [-2^30, 2^30] -> int32,
 * without an implementation-defined out-of-range conversion. */
static int32_t trigq_u2i(uint32_t v)
{
    return (v & 0x80000000u) ? -(int32_t)(0u - v) : (int32_t)v;
}

/*
 * sin(m + f) and cos(m + f) (Q2.30) for the whole degrees m in
 * 0..89 and the fraction fr (f = fr / 65536 degree), steps 3 and 4 of the
 * file comment up to the clamp (a value below 0 wraps to >= 2^31). One whole body per multiply: 16-bit partials where
 * a 64-bit product is a call (DH_PORT_USE_SPLIT16, ARMv6-M), 32x32->64
 * products elsewhere; the same values for every fr (exhaustive test).
 */
typedef struct {
    uint32_t s, c;
} trig_q_sc;

#if DH_PORT_USE_SPLIT16
/* a b = h 2^32 + m 2^16 + l (m, l < 2^16) from four 16x16 products, for
 * a <= 2^30 and b < 2^31.2 (the callers' factors): then ah bl + al bh +
 * (al bl >> 16) < 2^30 + 2^31.2 + 2^16 fits uint32, no carry word needed. */
typedef struct {
    uint32_t h, m, l;
} trigq_p16;

DH_PORT_INLINE void trigq_p16_mul(trigq_p16 *r, uint32_t a, uint32_t b)
{
    const uint32_t al = a & 0xFFFFu, ah = a >> 16, bl = b & 0xFFFFu, bh = b >> 16;
    const uint32_t ll = al * bl;
    const uint32_t c = ah * bl + al * bh + (ll >> 16);
    r->h = ah * bh + (c >> 16);
    r->m = c & 0xFFFFu;
    r->l = ll & 0xFFFFu;
}

static trig_q_sc trigq_add_frac(uint32_t m, uint32_t fr)
{
    trig_q_sc r;
    const uint32_t sv = (uint32_t)dh_trig_sin_q30[m];       /* sin m, 0..2^30 */
    const uint32_t cv = (uint32_t)dh_trig_sin_q30[90u - m]; /* cos m, 0..2^30 */
    uint32_t t, h, h3, t3, t4, sf, cm, d;

    /* f in radians, units 2^-37: T <= 65535 * KT / 2^16 < 2^31.2. fr <
     * 2^16: T from two 32-bit products (exact: both partial products and
     * the sum stay below 2^32) */
    t  = fr * (DH_TRIG_KT >> 16) + ((fr * (DH_TRIG_KT & 0xFFFFu) + 0x8000u) >> 16);
    /* t^2/2, t^2/6, t^3/6, t^4/24 without 64-bit products (no __aeabi_lmul,
     * no out-of-line call): with the 16-bit halves th, tl of t (th < 2^15.2)
     * and the small factors h < 2^24.4, h3 < 2^22.9 (gh = h3 >> 16 < 2^7),
     * each rounding by 2^k, k > 32, only needs the exact high word
     * H = floor(a b / 2^32) = ah bh + floor((ah bl + al bh + floor(al bl /
     * 2^16)) / 2^16), whose inner sum stays below 2^32 for these bounds
     * (th gl < 2^31.2); then round(a b / 2^k) = (H + 2^(k-33)) >> (k - 32).
     * t^2: 2 th tl is added as (th tl >> 15) to the high word and its low
     * 15 bits, doubled, to the inner sum. (h + 1) / 3 for x = h + 1 =
     * xh 2^16 + xl: 2^16 = 3 * 21845 + 1, so x / 3 = xh 21845 + (xh + xl) / 3,
     * and y / 3 = (y * 43691) >> 17 for y < 2^17 (43691 = (2^17 + 1) / 3;
     * y 43691 < 2^32 for y <= 2^16 + 2^9). All four checked against the
     * 64-bit expressions for every fr (exhaustive, 2^16 inputs). */
    {
        const uint32_t th = t >> 16, tl = t & 0xFFFFu;
        uint32_t m2 = th * tl, ll = tl * tl, x, xh, gh, gl, hh, hl;
        h  = (th * th + (m2 >> 15) + ((((m2 & 0x7FFFu) << 1) + (ll >> 16)) >> 16) + 32u) >> 6;
        x  = h + 1u;
        xh = x >> 16;
        h3 = xh * 21845u + (((xh + (x & 0xFFFFu)) * 43691u) >> 17);
        gh = h3 >> 16;
        gl = h3 & 0xFFFFu;
        t3 = (th * gh + ((th * gl + tl * gh + ((tl * gl) >> 16)) >> 16) + 16u) >> 5;
        hh = h >> 16;
        hl = h & 0xFFFFu;
        t4 = (hh * gh + ((hh * gl + hl * gh + ((hl * gl) >> 16)) >> 16) + 32u) >> 6;
    }
    sf = t - t3;                                /* sin f,     0 .. 2^31.2 */
    cm = h - t4;                                /* 1 - cos f, 0 .. 2^24.4 */

    /* The two corrections from 16-bit partials (see trigq_p16): for
     * P = A - B or A + B (each split as H 2^32 + M 2^16 + L) the rounding
     * by 2^37 needs the high words, the middle halves and, from the low
     * halves, only the borrow / carry into the middle: X = floor(P / 2^16)
     * + 2^20 = (HA -+ HB) 2^16 + Z, Z = MA -+ MB + 2^20 -+ (borrow/carry)
     * in (2^20 - 2^17, 2^20 + 2^17), and floor(X / 2^21) =
     * (HA -+ HB + (Z >> 16)) >> 5; the difference is biased by 2^30 (a
     * multiple of 32; the result 2^25 higher, as in the 64-bit form). */
    {
        trigq_p16 pa, pb;
        uint32_t z;
        trigq_p16_mul(&pa, cv, sf);
        trigq_p16_mul(&pb, sv, cm);
        z = pa.m - pb.m + ((uint32_t)1 << 20) - (uint32_t)(pa.l < pb.l);
        d = (pa.h - pb.h + (z >> 16) + ((uint32_t)1 << 30)) >> 5;
        trigq_p16_mul(&pa, cv, cm);
        trigq_p16_mul(&pb, sv, sf);
        z = pa.m + pb.m + ((uint32_t)1 << 20) + ((pa.l + pb.l) >> 16);
        r.s = sv + d - ((uint32_t)1 << 25);      /* true value in [0, 2^30] */
        r.c = cv - ((pa.h + pb.h + (z >> 16)) >> 5);
    }
    return r;
}
#else
static trig_q_sc trigq_add_frac(uint32_t m, uint32_t fr)
{
    trig_q_sc r;
    const uint32_t sv = (uint32_t)dh_trig_sin_q30[m];       /* sin m, 0..2^30 */
    const uint32_t cv = (uint32_t)dh_trig_sin_q30[90u - m]; /* cos m, 0..2^30 */
    uint32_t t, h, h3, t3, t4, sf, cm, d;

    /* f in radians, units 2^-37: T <= 65535 * KT / 2^16 < 2^31.2 */
    t  = (uint32_t)((dh_trig_mul64(fr, DH_TRIG_KT) + 0x8000u) >> 16);
    h  = (uint32_t)((dh_trig_mul64(t, t) + ((uint64_t)1 << 37)) >> 38);      /* t^2/2  */
    /* the same value: INV3 = (2^32 - 1) / 3 exactly, so for h = 3 q + r
     * the product rounds to q + (r == 2) while h / 2^32 < 1/6, i.e. for
     * every h < 2^29 (here h < 2^24.5; also checked exhaustively below
     * 2^26). A division by a constant compiles to a multiply-high where
     * a 32x32->64 multiply exists; GCC expands the product by 0x55555555
     * instead into a 20-instruction shift-add chain at -O2 on Cortex-M4. */
    h3 = (h + 1u) / 3u;                                                     /* t^2/6  */
    t3 = (uint32_t)((dh_trig_mul64(t, h3) + ((uint64_t)1 << 36)) >> 37);     /* t^3/6  */
    t4 = (uint32_t)((dh_trig_mul64(h, h3) + ((uint64_t)1 << 37)) >> 38);     /* t^4/24 */
    sf = t - t3;                                /* sin f,     0 .. 2^31.2 */
    cm = h - t4;                                /* 1 - cos f, 0 .. 2^24.4 */

    /* sin(m+f) = S + (C sin f - S (1 - cos f)). The difference of the two
     * products (each < 2^61.2, units 2^-67) is biased by 2^62 so that it is
     * rounded by an unsigned shift (no signed right shift anywhere); the
     * bias 2^25 is taken off again in modular uint32 arithmetic. */
    d = (uint32_t)((dh_trig_mul64(cv, sf) - dh_trig_mul64(sv, cm)
                    + ((uint64_t)1 << 62) + ((uint64_t)1 << 36)) >> 37);
    r.s = sv + d - ((uint32_t)1 << 25);          /* true value in [0, 2^30] */
    /* cos(m+f) = C - (C (1 - cos f) + S sin f) */
    {
        const uint64_t pc = dh_trig_mul64(cv, cm) + dh_trig_mul64((uint32_t)dh_trig_sin_q30[m], sf);
        d = (uint32_t)((pc + ((uint64_t)1 << 36)) >> 37);
        r.c = cv - d;                           /* true value in [0, 2^30] */
    }
    return r;
}
#endif

void dh_sincos_q(dh_q16 deg_q16, dh_q30 *s_q30, dh_q30 *c_q30)
{
    uint32_t u, n, q, k, m, fr, sv, cv;

    DH_ASSERT(s_q30 != NULL);
    DH_ASSERT(c_q30 != NULL);

    /* (uint32_t)x is defined (modulo 2^32); 0u - that is the magnitude */
    u = (deg_q16 < 0) ? (0u - (uint32_t)deg_q16) : (uint32_t)deg_q16;
    n = u >> 16;                                /* 0..32768 whole degrees */
    fr = u & 0xFFFFu;

    q = (n * DH_TRIG_DIV90_32) >> 23;           /* floor(n / 90), exact */
    m = n - 90u * q;                            /* 0..89 */
    k = q & 3u;                                 /* quadrant: 90 * 4 = 360 */
    k |= (uint32_t)(deg_q16 < 0) << 2;          /* and the input's sign (one value live) */
    {
        const trig_q_sc r = trigq_add_frac(m, fr);
        sv = r.s;
        cv = r.c;
    }

    /* clamp to [0, 2^30]: a result below 0 wrapped to >= 2^31 */
    sv = (sv > DH_TRIG_Q30) ? ((sv >= 0x80000000u) ? 0u : DH_TRIG_Q30) : sv;
    cv = (cv > DH_TRIG_Q30) ? ((cv >= 0x80000000u) ? 0u : DH_TRIG_Q30) : cv;

    /* quadrant: (s,c) -> k=1: (c,-s), k=2: (-s,-c), k=3: (-c,s); then the
     * odd symmetry for a negative input (0u - v: the exact two's complement
     * of a magnitude <= 2^30) */
    if (k & 1u) {
        uint32_t sw = sv;
        sv = cv;
        cv = sw;
    }
    if (((k >> 1) ^ (k >> 2)) & 1u) sv = 0u - sv;
    if ((k ^ (k >> 1)) & 1u) cv = 0u - cv;
    *s_q30 = trigq_u2i(sv);
    *c_q30 = trigq_u2i(cv);
}

dh_q30 dh_sin_q(dh_q16 deg_q16)
{
    dh_q30 s, c;
    dh_sincos_q(deg_q16, &s, &c);
    return s;
}

dh_q30 dh_cos_q(dh_q16 deg_q16)
{
    dh_q30 s, c;
    dh_sincos_q(deg_q16, &s, &c);
    return c;
}
