/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_trig_tables.h - PRIVATE to the trig module (not installed): the
 * whole-degree quarter-wave sine tables (generated into dh_trig_tables.c
 * by tools/gen_trig_tables.py) and the 32x32->64 product both paths use.
 */
#ifndef DHMATH_DH_TRIG_TABLES_H
#define DHMATH_DH_TRIG_TABLES_H

#include <stdint.h>

#include "../internal/dh_build.h"

/** Entries per table: sin(0..90 degrees). */
#define DH_TRIG_TAB_LEN 91

/** sin(n deg), n = 0..90, correctly rounded to binary32 (read only where
 * DH_FAST_PATHS is 1; otherwise not linked). */
extern const float dh_trig_sin_f32[DH_TRIG_TAB_LEN];
/** sin(n deg), n = 0..90, correctly rounded to Q2.30. */
extern const int32_t dh_trig_sin_q30[DH_TRIG_TAB_LEN];

/*
 * a * b as uint64 (exact). Where a 64-bit product is a library call
 * (DH_PORT_USE_SPLIT16, src/internal/dh_port.h: ARMv6-M's __aeabi_lmul) it is
 * formed from four 16x16->32 products, a b = ah bh 2^32 + (ah bl + al bh)
 * 2^16 + al bl; no partial sum wraps (mid and mid2 are at most
 * (2^16 - 1)^2 + 2^16 - 1), and the helper stays out of line (inlined, its
 * 64-bit temporaries spill and the code doubles).
 */
#if DH_PORT_USE_SPLIT16 && (defined(__GNUC__) || defined(__clang__))
#define DH_TRIG_MUL_FN static DH_NOINLINE __attribute__((unused))
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
