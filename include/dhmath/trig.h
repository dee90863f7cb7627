/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Index: the functions of trig.h by source file (src/trig/).
 *   dh_trig_f32.c   dh_sincos_f32, dh_sin_f32, dh_cos_f32
 *   dh_trig_q.c     dh_sincos_q, dh_sin_q, dh_cos_q
 *   dh_itrig_f32.c  dh_atan2_f32, dh_asin_f32, dh_acos_f32
 *   dh_itrig_q.c    dh_atan2_q, dh_asin_q, dh_acos_q
 */
/**
 * @file trig.h
 * @brief Sine and cosine of angles in DEGREES through a whole-degree lookup
 *        table, and atan2, asin, acos returning degrees, in float and in
 *        fixed point.
 *
 * Common to both paths: the reduction of the angle is exact (the error does
 * not grow with the angle); whole degrees return the correctly rounded table
 * value, so multiples of 90 degrees give exactly 0 and +-1; sin(-x) ==
 * -sin(x) and cos(-x) == cos(x) bit for bit. Shifting an angle by whole
 * turns gives the same bits as long as its sign does not change. DH_SMALL
 * builds give the same bits for every input. Thread-safe and reentrant (no
 * state; const tables only). Method and error derivation: docs/design.md
 * ("Lookup-table trigonometry"), docs/accuracy_trig.md. Measured cost and
 * stack: docs/generated/performance_target.md, docs/generated/footprint.md.
 */
#ifndef DHMATH_TRIG_H
#define DHMATH_TRIG_H

#include "dhmath/common.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * @brief sin and cos of @p deg degrees (float).
 *
 * @param deg  angle in degrees, any float; every finite value (up to
 *             FLT_MAX) is reduced exactly.
 * @param s    out: sin(deg), in [-1, 1]. Must not be NULL (DH_ASSERT).
 * @param c    out: cos(deg), in [-1, 1]. Must not be NULL (DH_ASSERT).
 *             @p s and @p c must not point to the same float.
 *
 * Error bound: |error| <= 6.2e-8 against the exact sin/cos of @p deg
 * (half an ulp of the table value + half an ulp of the result + < 2.2e-9
 * for the correction). Whole degrees: the correctly rounded float of
 * sin/cos. Multiples of 90: exactly 0 and +-1; exact zeros of non-negative
 * angles are +0. Single-precision arithmetic only (no double, no libm, no
 * division).
 *
 * @return DH_OK; DH_ERR_NAN if @p deg is NaN or +-Inf, and then both
 *         outputs are set to a quiet NaN (never a table read).
 */
dh_status dh_sincos_f32(float deg, float *s, float *c);

/**
 * @brief sin of @p deg degrees (float); same reduction, accuracy and
 *        symmetry as dh_sincos_f32() and bit-identical to its sine output.
 * @param deg angle in degrees, any float.
 * @return sin(deg) in [-1, 1]; a quiet NaN for NaN or +-Inf input.
 */
float dh_sin_f32(float deg);

/**
 * @brief cos of @p deg degrees (float); same reduction, accuracy and
 *        symmetry as dh_sincos_f32() and bit-identical to its cosine output.
 * @param deg angle in degrees, any float.
 * @return cos(deg) in [-1, 1]; a quiet NaN for NaN or +-Inf input.
 */
float dh_cos_f32(float deg);

/**
 * @brief sin and cos of @p deg_q16 degrees (Q16.16) as Q2.30.
 *
 * @param deg_q16 angle in degrees, Q16.16: every int32 is valid
 *                (-32768 .. +32767.99998 degrees, step 1/65536 degree).
 * @param s_q30   out: sin, Q2.30 in [-0x40000000, 0x40000000]
 *                (1.0 == 0x40000000). Must not be NULL (DH_ASSERT).
 * @param c_q30   out: cos, Q2.30, same range. Must not be NULL (DH_ASSERT).
 *                @p s_q30 and @p c_q30 must not be the same object.
 *
 * Error bound: |error| <= 1.05 LSB (2^-30) against the exact values
 * (table rounding 0.5 + final rounding 0.5 + polynomial < 0.05). Whole
 * degrees: the correctly rounded Q2.30 value; multiples of 90: exactly 0
 * and +-0x40000000. sin(-x) == -sin(x), cos(-x) == cos(x) exactly
 * (INT32_MIN, -32768 degrees, gives sin(-8 deg)). No intermediate can
 * overflow for any int32 input (proof in src/trig/dh_trig_q.c).
 *
 * Integer only: no float, no libm, no division. Cannot fail.
 */
void dh_sincos_q(dh_q16 deg_q16, dh_q30 *s_q30, dh_q30 *c_q30);

/**
 * @brief sin of @p deg_q16 degrees (Q16.16) as Q2.30; bit-identical to the
 *        sine output of dh_sincos_q(). Defined for every int32.
 * @param deg_q16 angle in degrees, Q16.16, any int32.
 * @return sin, Q2.30 in [-0x40000000, 0x40000000].
 */
dh_q30 dh_sin_q(dh_q16 deg_q16);

/**
 * @brief cos of @p deg_q16 degrees (Q16.16) as Q2.30; bit-identical to the
 *        cosine output of dh_sincos_q(). Defined for every int32.
 * @param deg_q16 angle in degrees, Q16.16, any int32.
 * @return cos, Q2.30 in [-0x40000000, 0x40000000].
 */
dh_q30 dh_cos_q(dh_q16 deg_q16);

/* ---- inverse trigonometry in degrees -------------------------------- */

/**
 * @brief atan2(y, x) in degrees (float): the angle of the point (x, y).
 *
 * @param y,x  any finite floats, subnormal to FLT_MAX, not both zero.
 * @param deg  out: the angle in (-180, 180]. Must not be NULL (DH_ASSERT).
 *
 * Error bound: within 1 ulp of the correctly rounded degree value for
 * every finite input. Exact: 0 for y = 0 and x > 0 (the sign of y kept:
 * -0 for y = -0), 180 for y = +-0 and x < 0 (either sign of zero: the
 * range excludes -180), +-90 for x = +-0, +-45 and +-135 for |y| == |x|.
 * A value y < 0 whose angle rounds to -180 gives -179.99998 (the float
 * above -180). atan2(-y, x) == -atan2(y, x) bit for bit except at 180.
 * No libm, no double; the arithmetic is shared with the library's radian
 * atan2 (src/internal/dh_mathf.c).
 *
 * @return DH_OK; DH_ERR_NAN if x or y is NaN or +-Inf; DH_ERR_DOMAIN for
 *         x == y == 0 (either sign). *deg is untouched on an error.
 */
dh_status dh_atan2_f32(float y, float x, float *deg);

/**
 * @brief asin(s) in degrees (float), in [-90, 90].
 *
 * @param s    sine, |s| <= 1; 1 < |s| <= 1 + 2^-21 (four ulp above 1, the
 *             rounding of a unit vector's component) is taken as +-1.
 * @param deg  out: the angle. Must not be NULL (DH_ASSERT).
 *
 * Error bound: within 1 ulp of the correctly rounded value; exact 0, +-90
 * at 0, +-1; asin(-s) == -asin(s) bit for bit. sqrt(1 - s^2) in hi + lo
 * float arithmetic, then the atan2 of dh_atan2_f32().
 *
 * @return DH_OK; DH_ERR_NAN for NaN or +-Inf; DH_ERR_DOMAIN for
 *         |s| > 1 + 2^-21. *deg is untouched on an error.
 */
dh_status dh_asin_f32(float s, float *deg);

/**
 * @brief acos(c) in degrees (float), in [0, 180]; as dh_asin_f32()
 *        (same clamp just outside [-1, 1], same statuses, untouched *deg
 *        on an error, within 1 ulp of the correctly rounded value). Exact:
 *        0, 90, 180 at 1, 0, -1.
 * @param c    cosine, |c| <= 1 + 2^-21.
 * @param deg  out: the angle. Must not be NULL (DH_ASSERT).
 * @return DH_OK, DH_ERR_NAN or DH_ERR_DOMAIN.
 */
dh_status dh_acos_f32(float c, float *deg);

/**
 * @brief atan2(y, x) of two int32 of any common scale, in Q16.16 degrees.
 *
 * @param y,x      any int32 (INT32_MIN included), not both zero; only the
 *                 ratio matters (an exact common power of two gives the
 *                 same bits).
 * @param deg_q16  out: Q16.16 degrees in (-180, 180], i.e.
 *                 -11796479 .. 11796480. Must not be NULL (DH_ASSERT).
 *
 * Error bound: |error| <= 1 LSB (2^-16 deg = 1.5e-5 deg) against the exact
 * angle (analysis 0.83 LSB, src/trig/dh_itrig_q.c). Exact: 0, +-45, +-90,
 * +-135, 180 where |y| == |x| or one of them is 0; y == 0, x < 0 gives
 * +180; y < 0 whose angle rounds to -180 gives -180 + 1 LSB.
 * atan2(-y, x) == -atan2(y, x) except there. Integer only (CORDIC, a
 * 116-byte table), no division.
 *
 * @return DH_OK; DH_ERR_DOMAIN for x == y == 0 (*deg_q16 untouched).
 */
dh_status dh_atan2_q(int32_t y, int32_t x, dh_q16 *deg_q16);

/**
 * @brief asin of a Q2.30 sine, in Q16.16 degrees [-90, 90].
 *
 * @param s_q30    sine, Q2.30, |s| <= 0x40000000; up to 0x40000200
 *                 (1 + 2^-21) in magnitude is taken as +-1.0.
 * @param deg_q16  out: Q16.16 degrees. Must not be NULL (DH_ASSERT).
 *
 * Error bound: |error| <= 1 LSB of Q16.16 against the exact asin of the
 * input; exact 0, +-90 at 0, +-1.0; odd (asin(-s) == -asin(s)). Method:
 * the atan2 of dh_atan2_q() on (s, floor(sqrt(2^60 - s^2))). Integer only.
 *
 * @return DH_OK; DH_ERR_DOMAIN for |s_q30| > 0x40000200 (*deg_q16
 *         untouched).
 */
dh_status dh_asin_q(dh_q30 s_q30, dh_q16 *deg_q16);

/**
 * @brief acos of a Q2.30 cosine, in Q16.16 degrees [0, 180]; as
 *        dh_asin_q() (same clamp, status and bound). Exact 0, 90, 180 at
 *        +1.0, 0, -1.0.
 * @param c_q30    cosine, Q2.30, |c| <= 0x40000200.
 * @param deg_q16  out: Q16.16 degrees. Must not be NULL (DH_ASSERT).
 * @return DH_OK; DH_ERR_DOMAIN for |c_q30| > 0x40000200 (untouched).
 */
dh_status dh_acos_q(dh_q30 c_q30, dh_q16 *deg_q16);

#ifdef __cplusplus
}
#endif

#endif /* DHMATH_TRIG_H */
