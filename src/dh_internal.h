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

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>
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

/** 1 when floats are emulated (no FPU): float tests are cheaper on the bits. */
#if (defined(__arm__) && (defined(__SOFTFP__) || !defined(__ARM_FP))) || \
    (defined(__riscv) && !defined(__riscv_flen))
#define DH_SOFT_FLOAT 1
#else
#define DH_SOFT_FLOAT 0
#endif

/** 1 if x is finite (not NaN, not +-Inf). With an FPU: x - x is 0 exactly
 *  then and NaN otherwise; soft float: the exponent field is not all ones. */
DH_INLINE int dh_isfinite_f32(float x)
{
#if DH_SOFT_FLOAT
    uint32_t u;
    (void)memcpy(&u, &x, sizeof u);
    return (u & 0x7F800000u) != 0x7F800000u;
#else
    return (x - x) == 0.0f;
#endif
}

/* ---- trig and robot description helpers --------------------------------- */

/* ---- float transform helpers --------------------------------------------- */

/* ---- fixed-point helpers (Q rounding, saturation) ------------------------ */

/* ---- kinematics helpers ---------------------------------------------------- */

/** The rotation check: 1 when the 3x3 with columns c0, c1, c2 (3 floats
 *  each) has every entry of R^T R - I within tol in magnitude and
 *  det R = c0 . (c1 x c2) > 0 (a reflection is not a rotation); 0 otherwise,
 *  also for NaN or overflowing products. */
DH_INLINE int dh_rot_cols_ok_f32(const float *c0, const float *c1, const float *c2, float tol)
{
    const float *col[3];
    unsigned a, b;
    col[0] = c0;
    col[1] = c1;
    col[2] = c2;
    for (a = 0; a < 3u; a++) {
        for (b = a; b < 3u; b++) {
            float d = col[a][0] * col[b][0] + col[a][1] * col[b][1] + col[a][2] * col[b][2];
            if (a == b) d -= 1.0f;
            if (!(fabsf(d) <= tol)) return 0;
        }
    }
    return (c0[0] * (c1[1] * c2[2] - c1[2] * c2[1]) + c0[1] * (c1[2] * c2[0] - c1[0] * c2[2]) +
            c0[2] * (c1[0] * c2[1] - c1[1] * c2[0])) > 0.0f;
}

/** An axis (v[0], v[1], v[2]) divided by its largest magnitude, so that its
 *  squares neither overflow nor underflow, and *len = its length then (in
 *  [1, sqrt 3]). DH_ERR_NAN for a NaN/Inf component, DH_ERR_ZERO_AXIS when
 *  the largest magnitude is below FLT_MIN; v and *len untouched then. */
DH_INLINE dh_status dh_axis_prescale_f32(float v[3], float *len)
{
    float m;
    if (!dh_isfinite_f32(v[0]) || !dh_isfinite_f32(v[1]) || !dh_isfinite_f32(v[2])) return DH_ERR_NAN;
    m = fabsf(v[0]);
    if (fabsf(v[1]) > m) m = fabsf(v[1]);
    if (fabsf(v[2]) > m) m = fabsf(v[2]);
    if (m < FLT_MIN) return DH_ERR_ZERO_AXIS;
    v[0] /= m;
    v[1] /= m;
    v[2] /= m;
    *len = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return DH_OK;
}

/** The off-diagonal of R = S + [w]x, S symmetric with S01 = xy, S02 = xz,
 *  S12 = yz (+ 0.0f: no -0). */
DH_INLINE void dh_rot_offdiag_f32(dh_mat3_f32 *R, float xy, float xz, float yz, float wx, float wy,
                                  float wz)
{
    DH_M3(R, 0, 1) = (xy - wz) + 0.0f;
    DH_M3(R, 1, 0) = (xy + wz) + 0.0f;
    DH_M3(R, 0, 2) = (xz + wy) + 0.0f;
    DH_M3(R, 2, 0) = (xz - wy) + 0.0f;
    DH_M3(R, 1, 2) = (yz - wx) + 0.0f;
    DH_M3(R, 2, 1) = (yz + wx) + 0.0f;
}

#endif /* DHMATH_SRC_DH_INTERNAL_H */
