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
 * every input (test/test_port.c checks the edge values on every target the
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

#include "dhmath/dh_config.h"

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

/** @brief Saturate x to a signed @p bits-bit value, bits in 1..32. */
static inline int32_t dh_port_ssat_c(int32_t x, unsigned bits)
{
    int32_t hi, lo;
    if (bits >= 32u) return x;
    hi = (int32_t)((1u << (bits - 1u)) - 1u);
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
