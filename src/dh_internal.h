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

/**
 * x * 2^frac (frac 0..30) rounded to the nearest int32, ties away from zero,
 * into *out. Returns 0 when stored, 1 when x is finite but the result is
 * out of range, 2 when x is NaN or Inf (*out untouched in both cases), so
 * that callers OR the results of several conversions. Exact: the scaling is
 * by a power of two and the range test is on x itself (2^(31 - frac) is a
 * float); rem = v - trunc(v) is in (-1, 1), so the truncation of 2 rem is
 * +-1 exactly when |rem| >= 0.5. The largest float below 2^31 is an
 * integer, so i + 1 cannot overflow.
 */
static inline unsigned dh_f32_to_fix(float x, unsigned frac, int32_t *out)
{
    const uint32_t p = 1u << (frac & 31u), pl = 1u << (31u - frac);
    const float lim = (float)pl;
    float v, rem;
    int32_t i;
    if (!dh_isfinite_f32(x)) return 2u;
    if (x >= lim || x < -lim) return 1u;
    v = x * (float)p;
    i = (int32_t)v;
    rem = v - (float)i;
    rem += rem;
    *out = i + (int32_t)rem;
    return 0u;
}

/** The same, saturated to the int32 range by the sign of x when out of
 *  range (finite x); *st |= the dh_f32_to_fix status. */
static inline int32_t dh_f32_to_fix_sat(float x, unsigned frac, unsigned *st)
{
    int32_t v;
    const unsigned e = dh_f32_to_fix(x, frac, &v);
    *st |= e;
    if (e == 0u) return v;
    return (x < 0.0f) ? INT32_MIN : INT32_MAX;
}

/* ---- float transform helpers --------------------------------------------- */

/* ---- fixed-point helpers (Q rounding, saturation) ------------------------ */

/* ---- kinematics helpers ---------------------------------------------------- */

#endif /* DHMATH_SRC_DH_INTERNAL_H */
