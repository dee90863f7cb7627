/*
 * dh_internal.h - private helpers shared by every module of src/ (not
 * installed, not part of the API). Each helper is defined here once.
 *
 * It is also the one place that decides what the size-first build
 * (DH_SMALL, dh_config.h) turns off. A .c file never tests DH_SMALL; it
 * tests the switches below, which keep one body per public function: the
 * general path is always compiled, and a fast path is an addition in front
 * of it, guarded by `if (DH_FAST_PATHS ...)` or `#if DH_FAST_PATHS`.
 */
#ifndef DHMATH_SRC_DH_INTERNAL_H
#define DHMATH_SRC_DH_INTERNAL_H

#include <stdint.h>
#include "dhmath/dh_config.h"
#include "dhmath/dh_common.h"
#include "../port/dh_port.h" /* relative: src/ compiles with only include/ on the path */

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

/* ---- constants ------------------------------------------------------------ */

/** 180 / pi and pi / 180, rounded to float. */
#define DH_RAD2DEG_F 57.295779513082320876798f
#define DH_DEG2RAD_F 0.017453292519943295f

/* ---- float predicates ----------------------------------------------------- */

/** 1 if x is finite (not NaN, not +-Inf): x - x is 0 exactly then, NaN otherwise. */
DH_INLINE int dh_isfinite_f32(float x)
{
    return (x - x) == 0.0f;
}

/* ---- trig and robot description helpers --------------------------------- */

/* ---- float transform helpers --------------------------------------------- */

/* ---- fixed-point helpers (Q rounding, saturation) ------------------------ */

/* ---- kinematics helpers ---------------------------------------------------- */

/** Inlined in the default build (constant arguments such as the DH
 *  convention fold into each copy), one out-of-line copy in the size-first
 *  build. */
#if DH_FAST_PATHS
#define DH_SPEED_INLINE DH_INLINE
#else
#define DH_SPEED_INLINE static DH_NOINLINE
#endif

/** Out of line in the default build (its callers' frames stay small),
 *  inlined into its one caller in the size-first build. */
#if DH_FAST_PATHS
#define DH_FAST_NOINLINE static DH_NOINLINE
#else
#define DH_FAST_NOINLINE DH_INLINE
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

#endif /* DHMATH_SRC_DH_INTERNAL_H */
