/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_build.h - private build switches shared by every family of src/ (not
 * installed, not part of the API): inlining hints, the configuration-check
 * symbols and the port layer (dh_port.h).
 *
 * It is also the one place that decides what the size-first build
 * (DH_SMALL, config.h) turns off. A .c file never tests DH_SMALL; it
 * tests the switches below, which keep one body per public function: the
 * general path is always compiled, and a fast path is an addition in front
 * of it, guarded by `if (DH_FAST_PATHS ...)` or `#if DH_FAST_PATHS`.
 */
#ifndef DHMATH_SRC_INTERNAL_DH_BUILD_H
#define DHMATH_SRC_INTERNAL_DH_BUILD_H

#include <stdint.h>
#include <string.h>
#include "dhmath/config.h"
#include "dhmath/common.h"
#include "dh_port.h"

/* ---- what the size-first build turns off -------------------------------- */

/** 1: fast paths (special cases, unrolled kernels) run in front of the
 *  general path; 0: the general path alone. */
#if DH_SMALL
#define DH_FAST_PATHS 0
#else
#define DH_FAST_PATHS 1
#endif

/* ---- inlining hints ------------------------------------------------------- */

#if defined(__GNUC__) || defined(__clang__)
/** Keep a helper out of line (one copy, bounded caller frames). */
#define DH_NOINLINE __attribute__((noinline))
/** Inline a small helper into every caller. */
#define DH_INLINE static __inline__ __attribute__((always_inline))
#else
#define DH_NOINLINE
#define DH_INLINE static
#endif

/** Out of line only in the size-first build (one copy instead of several). */
#if DH_FAST_PATHS
#define DH_SIZE_NOINLINE
#else
#define DH_SIZE_NOINLINE DH_NOINLINE
#endif

/** A general path that a fast path precedes in the default build: out of
 *  line there (the fast path keeps a short prologue), inlined into its one
 *  caller when it runs alone (DH_FAST_PATHS 0). */
#if DH_FAST_PATHS
#define DH_GENERAL_FN static DH_NOINLINE
#else
#define DH_GENERAL_FN DH_INLINE
#endif

/** The general path behind a fast path (dh_mat4_inv.c): optimized for size
 *  (smaller frames: stack budget on Cortex-M0+), calls to it unlikely. Not
 *  cold in the size-first build, where it is the only path. */
#if DH_FAST_PATHS && (defined(__GNUC__) || defined(__clang__))
#define DH_COLD __attribute__((cold))
#else
#define DH_COLD
#endif

/** Out of line in the default build only (callers' frames stay small on
 *  Cortex-M0+ there); the size-first build inlines its single call. */
#if DH_FAST_PATHS
#define DH_FAST_NOINLINE DH_NOINLINE
#else
#define DH_FAST_NOINLINE
#endif

/* ---- speed/size switches ------------------------------------------------- */

/** Inlined in the default build (constant arguments such as the DH
 *  convention fold into each copy), one out-of-line copy in the size-first
 *  build. */
#if DH_FAST_PATHS
#define DH_SPEED_INLINE DH_INLINE
#else
#define DH_SPEED_INLINE static DH_NOINLINE
#endif

/** 1: a small hot leaf shared by several callers is inlined into them
 *  (speed over code size); 0 when optimising for size (-Os) and in the
 *  size-first build, which keep its one out-of-line copy. */
#if DH_FAST_PATHS && !defined(__OPTIMIZE_SIZE__)
#define DH_HOT_INLINE 1
#else
#define DH_HOT_INLINE 0
#endif

/** Unrolls the next loop 3 / 4 times with GCC when not optimising for
 *  size (constant offsets, no loop counter); nothing otherwise. */
#if defined(__GNUC__) && !defined(__clang__) && !defined(__OPTIMIZE_SIZE__)
#define DH_UNROLL3 _Pragma("GCC unroll 3")
#define DH_UNROLL4 _Pragma("GCC unroll 4")
#else
#define DH_UNROLL3
#define DH_UNROLL4
#endif

/* ---- configuration check (include/dhmath/config.h, src/config/dh_config.c) --- */

/** Defined by the library, referenced by every application translation
 *  unit with ITS values: a mismatch of an interface setting fails to link. */
extern const uint8_t DH_CFG_SYM_MAX_JOINTS_;
extern const uint8_t DH_CFG_SYM_QPOS_FRAC_;

#endif /* DHMATH_SRC_INTERNAL_DH_BUILD_H */
