/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_floatops.h - private float helpers shared by the float modules of
 * several families (not installed): degree constants, the libm-free square
 * root, float predicates and the rotation-column check.
 */
#ifndef DHMATH_SRC_INTERNAL_DH_FLOATOPS_H
#define DHMATH_SRC_INTERNAL_DH_FLOATOPS_H

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "dh_build.h"
#include "dh_mathf.h"

/* ---- constants ------------------------------------------------------------ */

/** 180 / pi and pi / 180, rounded to float. */
#define DH_RAD2DEG_F 57.295779513082320876798f
#define DH_DEG2RAD_F 0.017453292519943295f

/* ---- libm-free float helpers (the library links without libm) ----------- */

/** sqrt(x) for the float modules, bit for bit IEEE's (correctly rounded):
 *  the FPU instruction through __builtin_sqrtf where the compiler emits it
 *  without a libm call (single-precision hardware square root and
 *  -fno-math-errno, which the library's build sets: __NO_MATH_ERRNO__),
 *  else the integer version dh_sqrtf_ (src/internal/dh_mathf.c). */
#if (defined(__GNUC__) || defined(__clang__)) && defined(__NO_MATH_ERRNO__) && \
    (DH_MATHF_VSQRT || defined(__SSE_MATH__) || defined(__riscv_fsqrt))
#define DH_SQRT_INSN 1
#else
#define DH_SQRT_INSN 0
#endif
DH_INLINE float dh_sqrt_f32(float x)
{
#if DH_SQRT_INSN
    return __builtin_sqrtf(x);
#else
    return dh_sqrtf_(x);
#endif
}

/* ---- float predicates ----------------------------------------------------- */

/** 1 when floats are emulated (no FPU): float tests are cheaper on the bits. */
#if (defined(__arm__) && (defined(__SOFTFP__) || !defined(__ARM_FP))) || \
    (defined(__riscv) && !defined(__riscv_flen))
#define DH_SOFT_FLOAT 1
#else
#define DH_SOFT_FLOAT 0
#endif

/** a == b for floats: +0 equals -0, a NaN equals nothing. Written with
 *  C99's quiet comparison macros (<math.h>, no libm): compilers emit the
 *  one comparison of ==, and -Wfloat-equal has no == on floats to report. */
DH_INLINE int dh_feq_f32(float a, float b)
{
    return !islessgreater(a, b) && !isunordered(a, b);
}

/** 1 if x is finite (not NaN, not +-Inf). With an FPU: x - x is 0 exactly
 *  then and NaN otherwise; soft float: the exponent field is not all ones. */
DH_INLINE int dh_isfinite_f32(float x)
{
#if DH_SOFT_FLOAT
    uint32_t u;
    memcpy(&u, &x, sizeof u);
    return (u & 0x7F800000u) != 0x7F800000u;
#else
    return dh_feq_f32(x - x, 0.0f);
#endif
}

/** The bits of x and the float of bits b (bit-level tests and constants;
 *  dh_robot_check compares derived floats bit for bit, so -0 differs from
 *  +0 and a NaN from every float). */
DH_INLINE uint32_t dh_f32_bits(float x)
{
    uint32_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

DH_INLINE float dh_f32_from_bits(uint32_t b)
{
    float x;
    memcpy(&x, &b, sizeof x);
    return x;
}

/** 1 if v[0..len-1] are all finite: the exponent fields tested on the bits
 *  (no float compare per element, so the same cost with or without an FPU). */
DH_INLINE int dh_allfinite_f32(const float *v, uint32_t len)
{
    uint32_t k, u;
    int fin = 1;
    for (k = 0; k < len; k++) {
        float x = v[k];
        memcpy(&u, &x, sizeof u);
        if ((u & 0x7F800000u) == 0x7F800000u) fin = 0;
    }
    return fin;
}

/* ---- rotation check ------------------------------------------------------- */

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
    DH_UNROLL3
    for (a = 0; a < 3u; a++) {
        DH_UNROLL3
        for (b = a; b < 3u; b++) {
            float d = col[a][0] * col[b][0] + col[a][1] * col[b][1] + col[a][2] * col[b][2];
            if (a == b) d -= 1.0f;
            if (!(fabsf(d) <= tol)) return 0;
        }
    }
    return (c0[0] * (c1[1] * c2[2] - c1[2] * c2[1]) + c0[1] * (c1[2] * c2[0] - c1[0] * c2[2]) +
            c0[2] * (c1[0] * c2[1] - c1[1] * c2[0])) > 0.0f;
}

#endif /* DHMATH_SRC_INTERNAL_DH_FLOATOPS_H */
