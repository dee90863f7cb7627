/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file dh_port.h
 * @brief Port layer: the few Cortex-M instructions the fixed-point code
 *        benefits from (SMULL, SMLAL, SSAT, CLZ, QADD), each behind a
 *        static inline function with a portable plain-C fallback.
 *
 * Selection. An instruction is used only when DH_USE_INTRINSICS is 1 AND
 * the compiler is GCC or Clang targeting an ARM core that has it:
 *
 * | feature            | macro                 | used when                                  |
 * |--------------------|-----------------------|--------------------------------------------|
 * | SMULL / SMLAL      | DH_PORT_HAS_SMULL     | __ARM_ARCH_7M__, __ARM_ARCH_7EM__, __ARM_ARCH_8M_MAIN__ (M3/M4/M7/M33); emitted by the compiler from the widening product (see dh_port_smull) |
 * | SSAT               | DH_PORT_HAS_SSAT      | __ARM_FEATURE_SAT (M3 and up)              |
 * | CLZ                | DH_PORT_HAS_CLZ       | __ARM_FEATURE_CLZ (M3 and up)              |
 * | QADD               | DH_PORT_HAS_QADD      | __ARM_FEATURE_DSP (M4/M7/M33)              |
 *
 * Everywhere else (Cortex-M0/M0+/M23, the host, DH_USE_INTRINSICS == 0) the
 * plain-C version is compiled. Both versions give bit-identical results for
 * every input (test/internal/test_port.c checks the edge values on every target the
 * suite runs on).
 *
 * Implementation-defined behaviour relied upon (checked at compile time
 * below; true for GCC, Clang and armcc/armclang): `>>` of a negative signed
 * value is an arithmetic shift, and converting an out-of-range unsigned value
 * to a signed type of the same width wraps modulo 2^N. No undefined
 * behaviour is relied upon (no signed overflow, no left shift of negative
 * values, no shift by the type width).
 *
 * This header is private to the library (it lives in port/, on the
 * library's private include path) and to the tests.
 */
#ifndef DHMATH_DH_PORT_H
#define DHMATH_DH_PORT_H

#include <stdint.h>

#include "dhmath/config.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- compile-time checks of the implementation-defined behaviour ------ */

/** Fails to compile unless >> of negative int32/int64 is arithmetic. */
typedef char dh_port_check_asr[(((int32_t)-5 >> 1) == -3 && ((int64_t)-5 >> 1) == -3) ? 1 : -1];
/** Fails to compile unless unsigned -> signed conversion wraps (32 and 16 bits). */
typedef char dh_port_check_wrap[((int32_t)(uint32_t)0xFFFFFFFEu == -2 &&
                                 (int16_t)(uint16_t)0x8001u == -32767) ? 1 : -1];

/* ---- feature selection ------------------------------------------------ */

#if DH_USE_INTRINSICS && (defined(__GNUC__) || defined(__clang__)) && defined(__arm__)
#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__) || defined(__ARM_ARCH_8M_MAIN__)
#define DH_PORT_HAS_SMULL 1
#endif
#if defined(__ARM_FEATURE_SAT)
#define DH_PORT_HAS_SSAT 1
#endif
#if defined(__ARM_FEATURE_CLZ)
#define DH_PORT_HAS_CLZ 1
#endif
#if defined(__ARM_FEATURE_DSP)
#define DH_PORT_HAS_QADD 1
#endif
#endif

#ifndef DH_PORT_HAS_SMULL
#define DH_PORT_HAS_SMULL 0
#endif
#ifndef DH_PORT_HAS_SSAT
#define DH_PORT_HAS_SSAT 0
#endif
#ifndef DH_PORT_HAS_CLZ
#define DH_PORT_HAS_CLZ 0
#endif
#ifndef DH_PORT_HAS_QADD
#define DH_PORT_HAS_QADD 0
#endif

/* ---- plain-C versions (always compiled: the tests compare against them) */

/* 64-bit value from two 32-bit words (no 64-bit shift is executed). */
#define DH_PORT_W64(h, l) (((uint64_t)(uint32_t)(h) << 32) | (uint32_t)(l))

/**
 * @brief acc + a*b modulo 2^64 with four 16x16->32 multiplies and 32-bit
 *        add-with-carry only: the form for cores without SMULL (ARMv6-M),
 *        where a 64-bit product would call the general 64x64 routine
 *        __aeabi_lmul. Compiled (and tested) on every platform.
 *
 * Balanced split: a = ah 2^16 + al with al = the low half read as int16
 * (in [-2^15, 2^15)) and ah = round(a / 2^16) in [-2^15, 2^15]; same for b.
 * Then a b = ah bh 2^32 + m 2^16 + al bl with m = ah bl + al bh, and every
 * partial result fits int32 with no overflow: |ah bh|, |al bl| <= 2^30, and
 * m in [-2^31, 2^31 - 1] (m = 2^31 would need ah = bl = al = bh = -2^15, but
 * ah = -2^15 forces al >= 0). Two 64-bit additions built from words, so the
 * compiler emits ADDS/ADCS pairs (Cortex-M0, -O2: ~26 instructions per
 * product, against ~50 through __aeabi_lmul).
 */
static inline uint64_t dh_port_mac16(uint64_t acc, int32_t a, int32_t b)
{
    int32_t al = (int32_t)(int16_t)(uint16_t)((uint32_t)a & 0xFFFFu);   /* SXTH */
    int32_t bl = (int32_t)(int16_t)(uint16_t)((uint32_t)b & 0xFFFFu);
    int32_t ah = ((a >> 15) + 1) >> 1, bh = ((b >> 15) + 1) >> 1;
    int32_t m = ah * bl + al * bh, ll = al * bl;
    acc += DH_PORT_W64(ah * bh + (m >> 16), (uint32_t)m << 16);
    acc += DH_PORT_W64(ll >> 31, ll);
    return acc;
}

/* 1 where a 32x32->64 product would be a library call (ARMv6-M, ARMv8-M baseline) */
#if defined(__ARM_ARCH_6M__) || defined(__ARM_ARCH_8M_BASE__)
#define DH_PORT_MUL64_IS_CALL 1
#else
#define DH_PORT_MUL64_IS_CALL 0
#endif

/* 1 when the fixed-point kernels use the 16-bit split of
 * dh_port_dot2r30_s16() (below) instead of 64-bit products. Follows
 * DH_PORT_MUL64_IS_CALL; a host build may predefine it to 1 (e.g.
 * CMAKE_C_FLAGS=-DDH_PORT_USE_SPLIT16=1) to run the whole test suite
 * through the ARMv6-M code paths. */
#ifndef DH_PORT_USE_SPLIT16
#define DH_PORT_USE_SPLIT16 DH_PORT_MUL64_IS_CALL
#endif

/** @brief Full signed product a*b as int64 (never overflows: |a*b| <= 2^62). */
static inline int64_t dh_port_smull_c(int32_t a, int32_t b)
{
#if DH_PORT_MUL64_IS_CALL
    return (int64_t)dh_port_mac16(0u, a, b);
#else
    return (int64_t)a * (int64_t)b;
#endif
}

/**
 * @brief acc + a*b modulo 2^64 (like the SMLAL instruction). The caller is
 *        responsible for the range: on wraparound the result is the wrapped
 *        value, never undefined behaviour.
 */
static inline int64_t dh_port_smlal_c(int64_t acc, int32_t a, int32_t b)
{
#if DH_PORT_MUL64_IS_CALL
    return (int64_t)dh_port_mac16((uint64_t)acc, a, b);
#else
    return (int64_t)((uint64_t)acc + (uint64_t)dh_port_smull_c(a, b));
#endif
}

/** @brief Saturate x to a signed @p bits-bit value, bits in 1..32 (0 and
 *  values above 32 return x unchanged). */
static inline int32_t dh_port_ssat_c(int32_t x, unsigned bits)
{
    int32_t hi, lo;
    if (bits - 1u >= 31u) return x;     /* the shift below is by 0..30 */
    hi = (int32_t)(((uint32_t)1 << (bits - 1u)) - 1u);
    lo = -hi - 1;
    return x > hi ? hi : (x < lo ? lo : x);
}

/** @brief Number of leading zero bits of x; 32 for x == 0. */
static inline unsigned dh_port_clz_c(uint32_t x)
{
    unsigned n = 0;
    if (x == 0u) return 32u;
    if ((x & 0xFFFF0000u) == 0u) { n += 16u; x <<= 16; }
    if ((x & 0xFF000000u) == 0u) { n += 8u; x <<= 8; }
    if ((x & 0xF0000000u) == 0u) { n += 4u; x <<= 4; }
    if ((x & 0xC0000000u) == 0u) { n += 2u; x <<= 2; }
    if ((x & 0x80000000u) == 0u) { n += 1u; }
    return n;
}

/** @brief a + b saturated to [INT32_MIN, INT32_MAX]. */
static inline int32_t dh_port_qadd_c(int32_t a, int32_t b)
{
    uint32_t s = (uint32_t)a + (uint32_t)b;
    /* overflow iff a and b have the same sign and s has the other one */
    if ((~((uint32_t)a ^ (uint32_t)b) & ((uint32_t)a ^ s)) & 0x80000000u)
        return a < 0 ? INT32_MIN : INT32_MAX;
    return (int32_t)s;
}

/* ---- 16-bit split kernel for rounded two-term sums (ARMv6-M) ---------- */

/* Forced inlining for the kernels below: at -Os GCC otherwise keeps them
 * out of line, and a call per product costs more than the product. */
#if defined(__GNUC__) || defined(__clang__)
#define DH_PORT_INLINE static inline __attribute__((always_inline))
#else
#define DH_PORT_INLINE static inline
#endif

/**
 * @brief A value split as v = h 2^16 + l for dh_port_dot2r30_s16().
 *
 * Two kinds of split, both exact: a row split (dh_port_split_row, l in
 * [-2^15, 2^15), any int32 v) for the values that change per use, and a
 * constant split (dh_port_split_k, l in (-2^15, 2^15]) for the factors
 * that are prepared once and used many times. The two low-half ranges
 * differ on purpose: a product of two low halves then lies in
 * [-2^30, 2^30 - 2^15], so the sum of two of them fits int32.
 */
typedef struct {
    int32_t h;  /**< high part */
    int32_t l;  /**< low part, |l| <= 2^15 */
} dh_port_s16;

/** @brief Row split of v, v < 2^31 - 2^15: l = low half as int16 in
 *  [-2^15, 2^15), h = (v - l) / 2^16 in [-2^15, 2^15). (For larger v,
 *  v - l would leave int32 and h wrap; the FK's entries stay below 1.6 2^30.) */
DH_PORT_INLINE dh_port_s16 dh_port_split_row(int32_t v)
{
    dh_port_s16 r;
    r.l = (int32_t)(int16_t)(uint16_t)((uint32_t)v & 0xFFFFu);             /* SXTH */
    r.h = (int32_t)((uint32_t)v - (uint32_t)r.l) >> 16;                      /* exact: v - l = h 2^16 */
    return r;
}

/**
 * @brief Constant split of v, |v| <= 2^31 - 2^15: l in (-2^15, 2^15],
 *        h = (v - l) / 2^16. (Outside that range h would not fit the
 *        arithmetic below; the callers split values of at most 2^30.)
 */
DH_PORT_INLINE dh_port_s16 dh_port_split_k(int32_t v)
{
    /* h = floor((v + 2^15 - 1) / 2^16) (no overflow for |v| <= 2^31 - 2^15),
     * l = v - h 2^16 in (-2^15, 2^15]; branch free */
    dh_port_s16 r;
    r.h = (int32_t)((uint32_t)v + 0x7FFFu) >> 16;
    r.l = (int32_t)((uint32_t)v - ((uint32_t)r.h << 16));
    return r;
}

/**
 * @brief floor((c x + s y + 2^29) / 2^30): the exact sum of two products
 *        rounded once (half up) to Q2.30 scale, with eight 16x16->32
 *        multiplies and 32-bit additions only (no 64-bit arithmetic, no
 *        library call on ARMv6-M).
 *
 * c, s are constant splits (dh_port_split_k), x, y row splits
 * (dh_port_split_row). With S = c x + s y:
 *     S = 2^32 H + 2^16 M + L,  H = ch xh + sh yh,
 *     M = ch xl + cl xh + sh yl + sl yh,  L = cl xl + sl yl,
 *     floor((S + 2^29) / 2^30) = 4 H + floor((M + 2^13 + floor(L / 2^16)) / 2^14)
 * (the low 16 bits of L cannot carry into the floor). Every partial
 * product is at most 2^30 in magnitude for any inputs (no undefined
 * behaviour); L lies in [-2^31, 2^31 - 2^16] by the choice of the low
 * ranges; the sums are formed modulo 2^32.
 *
 * Domain (the caller's proof obligation): x, y < 2^31 - 2^15 (row split),
 * |c|, |s| <= 2^31 - 2^15 (constant split), |c| + |s| + |x| + |y| <= 2^32 - 2^18
 * keeps |M + 2^13 + floor(L / 2^16)| <= (|c| + |s| + |x| + |y|) / 2 + 2^17
 * below 2^31, and the true result must fit int32. Then the result is
 * exact; outside, it is an unspecified int32 (still no undefined
 * behaviour). Example: rotation entries of a row of norm <= 1.5001
 * (|x| + |y| <= 2.1215 * 2^30) times a sine/cosine pair (|c| + |s| <=
 * 1.4143 * 2^30). test/internal/test_port.c checks it against the 64-bit sum.
 * Cortex-M0, gcc -O2: about 30 instructions (8 MULS).
 */
DH_PORT_INLINE int32_t dh_port_dot2r30_s16(dh_port_s16 c, dh_port_s16 x, dh_port_s16 s, dh_port_s16 y)
{
    uint32_t hi = (uint32_t)(c.h * x.h) + (uint32_t)(s.h * y.h);
    uint32_t mid = (uint32_t)(c.h * x.l) + (uint32_t)(c.l * x.h) + (uint32_t)(s.h * y.l) +
                   (uint32_t)(s.l * y.h);
    uint32_t lo = (uint32_t)(c.l * x.l) + (uint32_t)(s.l * y.l);
    mid += 0x2000u + (uint32_t)((int32_t)lo >> 16);
    return (int32_t)((hi << 2) + (uint32_t)((int32_t)mid >> 14));
}

/* ---- dispatching versions: what the library calls ---------------------- */

/** @brief a*b as int64 (SMULL when available; 4 x MULS on ARMv6-M). */
static inline int64_t dh_port_smull(int32_t a, int32_t b)
{
#if DH_PORT_HAS_SMULL
    /* GCC and Clang compile the widening product to one SMULL, and a sum
     * of them to SMLAL. This is used instead of inline asm on purpose:
     * asm pins 64-bit register pairs, and measured on Cortex-M4 (6-joint
     * fixed FK under QEMU) the asm version executed ~25 % more
     * instructions because of the register shuffles around it. */
    return (int64_t)a * (int64_t)b;
#else
    return dh_port_smull_c(a, b);
#endif
}

/** @brief acc + a*b modulo 2^64 (SMLAL when available). */
static inline int64_t dh_port_smlal(int64_t acc, int32_t a, int32_t b)
{
    /* modulo 2^64 like the instruction; compiles to SMLAL where it exists */
    return dh_port_smlal_c(acc, a, b);
}

/**
 * @brief Saturate x to a signed @p bits-bit value. @p bits must be an
 *        integer constant expression in 1..32 (SSAT takes an immediate).
 */
#if DH_PORT_HAS_SSAT
#define DH_PORT_SSAT(x, bits) ((int32_t)__extension__({ int32_t dh_r_; \
    __asm__("ssat %0, %1, %2" : "=r"(dh_r_) : "I"(bits), "r"((int32_t)(x)) : "cc"); dh_r_; }))
#else
#define DH_PORT_SSAT(x, bits) dh_port_ssat_c((x), (bits))
#endif

/** @brief Leading zeros of x, 32 for x == 0 (CLZ when available). */
static inline unsigned dh_port_clz(uint32_t x)
{
#if DH_PORT_HAS_CLZ
    uint32_t r;
    __asm__("clz %0, %1" : "=r"(r) : "r"(x));
    return (unsigned)r;
#else
    return dh_port_clz_c(x);
#endif
}

/** @brief Saturating a + b (QADD when available). */
static inline int32_t dh_port_qadd(int32_t a, int32_t b)
{
#if DH_PORT_HAS_QADD
    int32_t r;
    __asm__("qadd %0, %1, %2" : "=r"(r) : "r"(a), "r"(b) : "cc");
    return r;
#else
    return dh_port_qadd_c(a, b);
#endif
}

#ifdef __cplusplus
}
#endif

#endif /* DHMATH_DH_PORT_H */
