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
 * | SMULL / SMLAL      | DH_PORT_HAS_SMULL     | __ARM_ARCH_7M__, __ARM_ARCH_7EM__, __ARM_ARCH_8M_MAIN__ (M3/M4/M7/M33) |
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
/** Fails to compile unless uint32 -> int32 conversion wraps modulo 2^32. */
typedef char dh_port_check_wrap[((int32_t)(uint32_t)0xFFFFFFFEu == -2) ? 1 : -1];

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

/**
 * @brief Full signed product a*b as int64 (never overflows: |a*b| <= 2^62).
 *
 * On cores without a 32x32->64 multiply (Cortex-M0/M0+) the compiler would
 * call the general 64x64 library routine (__aeabi_lmul); this version uses
 * four 16x16->32 MULS instead, which is about half the work.
 */
static inline int64_t dh_port_smull_c(int32_t a, int32_t b)
{
#if defined(__arm__) && !DH_PORT_HAS_SMULL && defined(__ARM_ARCH_6M__)
    /* a = ah*2^16 + al, al in [0, 65535], ah in [-32768, 32767]; same for b. */
    uint32_t al = (uint32_t)a & 0xFFFFu, bl = (uint32_t)b & 0xFFFFu;
    int32_t ah = a >> 16, bh = b >> 16;
    uint32_t ll = al * bl;                          /* < 2^32 */
    int32_t m1 = ah * (int32_t)bl;                  /* |.| < 2^31 */
    int32_t m2 = (int32_t)al * bh;                  /* |.| < 2^31 */
    uint32_t hh = (uint32_t)(ah * bh);              /* |.| <= 2^30 */
    /* sum = hh*2^32 + (m1 + m2)*2^16 + ll, computed modulo 2^64 with the
     * mid terms sign-extended; the exact result fits int64. */
    uint32_t lo = ll, hi = hh, t;
    t = (uint32_t)m1 << 16; lo += t; hi += (lo < t) + (uint32_t)(m1 >> 16);
    t = (uint32_t)m2 << 16; lo += t; hi += (lo < t) + (uint32_t)(m2 >> 16);
    return (int64_t)(((uint64_t)hi << 32) | lo);
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
    return (int64_t)((uint64_t)acc + (uint64_t)dh_port_smull_c(a, b));
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

/** @brief a*b as int64 (SMULL when available). */
static inline int64_t dh_port_smull(int32_t a, int32_t b)
{
#if DH_PORT_HAS_SMULL
    int64_t r;
    __asm__("smull %Q0, %R0, %1, %2" : "=&r"(r) : "r"(a), "r"(b));
    return r;
#else
    return dh_port_smull_c(a, b);
#endif
}

/** @brief acc + a*b modulo 2^64 (SMLAL when available). */
static inline int64_t dh_port_smlal(int64_t acc, int32_t a, int32_t b)
{
#if DH_PORT_HAS_SMULL
    __asm__("smlal %Q0, %R0, %1, %2" : "+r"(acc) : "r"(a), "r"(b));
    return acc;
#else
    return dh_port_smlal_c(acc, a, b);
#endif
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
