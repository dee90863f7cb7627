/*
 * dh_trig_tables.h - PRIVATE to the trig module (not installed).
 *
 * Whole-degree quarter-wave sine tables (generated into dh_trig_tables.c by
 * tools/gen_trig_tables.py) and the exact integer reduction modulo 360 that
 * both the float and the fixed-point paths use.
 */
#ifndef DHMATH_DH_TRIG_TABLES_H
#define DHMATH_DH_TRIG_TABLES_H

#include <stdint.h>

#include "../port/dh_port.h" /* relative: src/ compiles with only include/ on the path */

/** Entries per table: sin(0..90 degrees). */
#define DH_TRIG_TAB_LEN 91

/** sin(n deg), n = 0..90, correctly rounded to binary32. 364 bytes; not
 * linked in DH_SMALL builds (the float path reads dh_trig_sin_q30). */
extern const float dh_trig_sin_f32[DH_TRIG_TAB_LEN];
/** sin(n deg), n = 0..90, correctly rounded to Q2.30. 364 bytes. */
extern const int32_t dh_trig_sin_q30[DH_TRIG_TAB_LEN];

/*
 * v mod 360 for 0 <= v < 2^24, exactly, with 32-bit multiplies only (no
 * divide: Cortex-M0 has none, and a library call would cost ~40 cycles).
 *
 * 4096 = 11*360 + 136, so v = h*4096 + l == h*136 + l (mod 360).
 * Fold 1: v < 2^24 -> h < 4096, result < 4095*136 + 4096 = 561016.
 * Fold 2: h <= 136 -> result < 136*136 + 4096 = 22592.
 * Then q = (v * 11650) >> 22 satisfies floor(v/360) - 1 <= q <= floor(v/360)
 * for v < 22592: 11650 / 2^22 lies below 1/360 by less than 2.1e-7, so q
 * undershoots v/360 by less than 22592 * 2.1e-7 < 0.005 (never more than
 * one step), and v * 11650 < 2^29 cannot overflow. One conditional
 * subtraction finishes.
 * Every intermediate is unsigned and far from 2^32. Verified exhaustively
 * for all v < 2^24 during development; test_trig_f32 checks the results for
 * huge floats bit for bit against fmod-reduced angles.
 */
static inline uint32_t dh_trig_mod360(uint32_t v)
{
    uint32_t q;
    v = (v >> 12) * 136u + (v & 4095u);
    v = (v >> 12) * 136u + (v & 4095u);
    q = (v * 11650u) >> 22;
    v -= q * 360u;
    if (v >= 360u) {
        v -= 360u;
    }
    return v;
}

/*
 * a * b as uint64 (exact). On cores where a 64-bit product is a library
 * call (ARMv6-M: __aeabi_lmul, a 64x64 multiply) it is formed from four
 * 16x16->32 products: with a = ah 2^16 + al, b = bh 2^16 + bl,
 *   a b = ah bh 2^32 + (ah bl + al bh) 2^16 + al bl.
 * No partial sum can wrap: mid = al bh + (al bl >> 16) and
 * mid2 = ah bl + (mid & 0xFFFF) are at most (2^16 - 1)^2 + 2^16 - 1 < 2^32,
 * and the high word is the exact floor(a b / 2^32) < 2^32. Selected by
 * DH_PORT_USE_SPLIT16 (port/dh_port.h), which a host build may set to run
 * the tests through this code. There the helper is a function of its own
 * (noinline): measured on Cortex-M0 under QEMU, dh_sincos_q takes 402
 * instructions at -O2 and 358 at -Os with it, 415 with it forced inline
 * (register spills of the 64-bit temporaries; twice the code) and 534
 * with __aeabi_lmul. Elsewhere it is the plain widening product. */
#if DH_PORT_USE_SPLIT16 && (defined(__GNUC__) || defined(__clang__))
#define DH_TRIG_MUL_FN static __attribute__((noinline, unused))
#else
#define DH_TRIG_MUL_FN static inline
#endif
DH_TRIG_MUL_FN uint64_t dh_trig_mul64(uint32_t a, uint32_t b)
{
#if DH_PORT_USE_SPLIT16
    uint32_t al = a & 0xFFFFu, ah = a >> 16, bl = b & 0xFFFFu, bh = b >> 16;
    uint32_t ll = al * bl;
    uint32_t mid = al * bh + (ll >> 16);
    uint32_t mid2 = ah * bl + (mid & 0xFFFFu);
    uint32_t hi = ah * bh + (mid >> 16) + (mid2 >> 16);
    uint32_t lo = (mid2 << 16) | (ll & 0xFFFFu);
    return DH_PORT_W64(hi, lo);
#else
    return (uint64_t)a * b;
#endif
}

#endif /* DHMATH_DH_TRIG_TABLES_H */
