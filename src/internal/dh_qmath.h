/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_qmath.h - private fixed-point arithmetic shared by the fixed modules
 * of several families (not installed): Q rounding, saturation, integer
 * square roots and division. Integer only.
 */
#ifndef DHMATH_SRC_INTERNAL_DH_QMATH_H
#define DHMATH_SRC_INTERNAL_DH_QMATH_H

#include <stdint.h>
#include "dh_build.h"

/* ---- fixed-point helpers (Q rounding, saturation) ------------------------ */

/** 1.0 in Q2.30, and half an LSB of a result taken >> 30. */
#define DH_Q_ONE30 ((int32_t)0x40000000)
#define DH_Q_HALF30 ((int64_t)0x20000000)

/* a b and acc + a b (modulo 2^64). Out of line where the product is the
 * 16-bit-partials kernel (DH_PORT_MUL64_IS_CALL, ARMv6-M): inlined many
 * times it makes GCC spill and the callers' frames exceed 256 bytes. */
#if DH_PORT_MUL64_IS_CALL && (defined(__GNUC__) || defined(__clang__))
#define DH_Q_MUL_FN static DH_NOINLINE __attribute__((unused))
#else
#define DH_Q_MUL_FN DH_INLINE
#endif
/** a b, exact. */
DH_Q_MUL_FN int64_t dh_q_mul64(int32_t a, int32_t b)
{
    return dh_port_smull(a, b);
}
/** acc + a b modulo 2^64. */
DH_Q_MUL_FN int64_t dh_q_mla64(int64_t acc, int32_t a, int32_t b)
{
    return dh_port_smlal(acc, a, b);
}

/** round(x / 2^sh), ties up, 1 <= sh <= 62, any x (cannot overflow). */
DH_INLINE int64_t dh_q_rshr(int64_t x, unsigned sh)
{
    return ((x >> (sh - 1u)) + (int64_t)1) >> 1;
}

/* dh_q_lo30 and dh_q_hi_chk are plain inline, not DH_INLINE: forced
 * inlining makes GCC schedule the unrolled fast paths worse. */
/** Bits 30..61 of t from its two words: t >> 30 when that fits int32. */
static inline int32_t dh_q_lo30(int64_t t)
{
    const uint64_t u = (uint64_t)t;
    const uint32_t hi = (uint32_t)(u >> 32), lo = (uint32_t)u;
    const uint32_t r = (hi << 2) | (lo >> 30);
    return (int32_t)r;
}

/** Bits 30 and 31 are clear iff t >> 30 fits int32 (high word in
 *  [-2^29, 2^29)): OR the words of several results, test once. */
static inline uint32_t dh_q_hi_chk(int64_t t)
{
    return (uint32_t)((uint64_t)t >> 32) + 0x20000000u;
}

/** round(x / 2^30), ties up, where the caller knows that it fits int32. */
DH_INLINE int32_t dh_q_rnd30_fit(int64_t x)
{
    return dh_q_lo30(x + DH_Q_HALF30);
}

/** INT32_MIN when bit 31 of w is set, else INT32_MAX (the saturated value
 *  of a result with the sign of w). */
DH_INLINE int32_t dh_q_sat_sign(uint32_t w)
{
    const uint32_t r = 0x7FFFFFFFu ^ (0u - (w >> 31));
    return (int32_t)r;
}

/** v saturated to int32; sets *ovf to DH_ERR_OVERFLOW when it did not fit. */
DH_INLINE int32_t dh_q_sat32(int64_t v, int *ovf)
{
    if ((((uint64_t)v + 0x80000000u) >> 32) != 0u) {
        *ovf = (int)DH_ERR_OVERFLOW;
        return dh_q_sat_sign((uint32_t)((uint64_t)v >> 32));
    }
    return (int32_t)v;
}

/** round(x / 2^30), ties up, saturated (*ovf as dh_q_sat32); a Q2.30 entry
 *  from a sum of Q2.30 products, |x| < 2^63 - 2^29. */
DH_INLINE int32_t dh_q_rnd30(int64_t x, int *ovf)
{
    int64_t t = x + DH_Q_HALF30;
    if ((dh_q_hi_chk(t) >> 30) != 0u) {
        *ovf = (int)DH_ERR_OVERFLOW;
        return dh_q_sat_sign((uint32_t)((uint64_t)t >> 32));
    }
    return dh_q_lo30(t);
}

/** p + round(x / 2^30), ties up, saturated (*ovf as dh_q_sat32): a position
 *  plus rotation x position products (Q2.30 x Qpos >> 30 = Qpos). */
DH_INLINE int32_t dh_q_pos_rnd30(int32_t p, int64_t x, int *ovf)
{
    return dh_q_sat32((int64_t)p + ((x + DH_Q_HALF30) >> 30), ovf);
}

/** |x| as uint32 (exact also for INT32_MIN). */
DH_INLINE uint32_t dh_q_abs_u32(int32_t x)
{
    return x < 0 ? 0u - (uint32_t)x : (uint32_t)x;
}

/** floor(sqrt(v)) for v < 2^62, digit by digit (31 bit pairs), in uint32:
 *  after j digits the remainder is at most 2 root < 2^(j+1), so the shifted
 *  remainder fits 32 bits for the first 30 digits; at the 31st a remainder
 *  >= 2^30 shifted is >= 2^32 > the trial 4 root + 1, a digit 1. Leading
 *  zero pairs of the high word are skipped (digits 0, remainder 0). Integer
 *  only, no division. */
static inline uint32_t dh_q_isqrt62(uint64_t v)
{
    const uint32_t hi = (uint32_t)(v >> 32) & 0x3FFFFFFFu, lo = (uint32_t)v;
    uint32_t rem = 0u, root = 0u, trial;
    int i;

    if (hi != 0u)
        for (i = (int)((31u - dh_port_clz(hi)) & ~1u); i >= 0; i -= 2) {
            rem = (rem << 2) | ((hi >> i) & 3u);
            root <<= 1;
            trial = (root << 1) | 1u;
            if (rem >= trial) {
                rem -= trial;
                root |= 1u;
            }
        }
    for (i = 30; i >= 2; i -= 2) {
        rem = (rem << 2) | ((lo >> i) & 3u);
        root <<= 1;
        trial = (root << 1) | 1u;
        if (rem >= trial) {
            rem -= trial;
            root |= 1u;
        }
    }
    root <<= 1;
    trial = (root << 1) | 1u;
    if ((rem >> 30) != 0u || ((rem << 2) | (lo & 3u)) >= trial) root |= 1u;
    return root;
}

/* ---- fixed-point square roots (integer only, no division) --------------- */

/** Number of significant bits of v (0 for 0). */
DH_INLINE unsigned dh_q_bitlen64(uint64_t v)
{
    const uint32_t hi = (uint32_t)(v >> 32), lo = (uint32_t)v;
    if (hi != 0u) return 64u - dh_port_clz(hi);
    return 32u - dh_port_clz(lo);
}

/**
 * 1 / sqrt(x / 2^30) in Q3.29 for x in [2^28, 2^30] (a value in [1/4, 1],
 * result in [1, 2]): `steps` (1..3) Newton steps Y <- Y (3 - x Y^2) / 2
 * from the tangent of 1/sqrt at 0.36 (x below 1/2) or 0.72 (above), which
 * lies below the root (relative error <= 5%, then 3.8e-3, 2.1e-5, 7e-10,
 * plus a few LSB of rounding). Integer only.
 */
static inline int32_t dh_q_rsqrt29(int32_t x, unsigned steps)
{
    int32_t y;
    unsigned i;
    /* tangents 2.5 - 2.31481 x and 1.76777 - 0.818415 x (Q29 constants) */
    if (x < (int32_t)0x20000000)
        y = (int32_t)1342177280 - (int32_t)(dh_q_mul64(x, 1242756741) >> 30);
    else
        y = (int32_t)949062656 - (int32_t)(dh_q_mul64(x, 439380859) >> 30);
    for (i = 0; i < steps; i++) {
        int32_t t = (int32_t)(dh_q_mul64(x, y) >> 29);  /* x y, Q30 */
        t = (int32_t)(dh_q_mul64(t, y) >> 29);          /* x y^2, Q30, near 1 */
        y += (int32_t)(dh_q_mul64(y, DH_Q_ONE30 - t) >> 31);
    }
    return y;
}

/** v normalised for dh_q_rsqrt29: v = (*m) 2^(*t) with *m in [2^28, 2^30)
 *  and *t even (may be negative); v > 0. */
DH_INLINE void dh_q_norm_even(uint64_t v, int32_t *m, int *t)
{
    int sh = (int)dh_q_bitlen64(v) - 30;
    if (sh & 1) sh++;
    *t = sh;
    *m = (sh >= 0) ? (int32_t)(v >> (unsigned)sh) : (int32_t)(v << (unsigned)(-sh));
}

/** sqrt(v) for any uint64 v, within 2^-28 relative (0 for 0): the
 *  normalised v times its reciprocal square root (three Newton steps). */
static inline uint32_t dh_q_sqrt_u64(uint64_t v)
{
    int32_t m, y;
    int t, sh;
    uint64_t r;
    if (v == 0u) return 0u;
    dh_q_norm_even(v, &m, &t);
    y = dh_q_rsqrt29(m, 3u);
    /* sqrt(m) = m y / 2^44 (m y < 2^61); times 2^(t/2) */
    r = (uint64_t)dh_q_mul64(m, y);
    sh = 44 - t / 2;
    if (sh > 0) return (uint32_t)((r + ((uint64_t)1 << (sh - 1))) >> (unsigned)sh);
    return (uint32_t)(r << (unsigned)(-sh));
}

/** round(n 2^frac / d), ties up, for d in [1, 2^31), frac <= 30 and
 *  n 2^frac / d below 2^31: the integer part by one 32-bit division, then one
 *  bit per step (r < d < 2^31, so 2 r fits). No 64-bit division. */
static inline uint32_t dh_q_udiv(uint32_t n, uint32_t d, unsigned frac)
{
    uint32_t q = n / d, r = n - q * d, i;
    for (i = 0u; i <= frac; i++) {
        r <<= 1;
        q <<= 1;
        if (r >= d) {
            r -= d;
            q |= 1u;
        }
    }
    return (q >> 1) + (q & 1u);
}

/** floor(a 2^30 / b) for b > 0 and a < 2 b (result below 2^31): one
 *  quotient bit per step, the remainder below 2 b in 64 bits. No division. */
static inline uint32_t dh_q_ufloor30(uint32_t a, uint32_t b)
{
    uint64_t r = a;
    uint32_t q = 0u, i;
    for (i = 0u; i < 31u; i++) {
        q <<= 1;
        if (r >= b) {
            r -= b;
            q |= 1u;
        }
        r <<= 1;
    }
    return q;
}

#endif /* DHMATH_SRC_INTERNAL_DH_QMATH_H */
