/**
 * @file dh_trig.h
 * @brief Sine and cosine of angles in DEGREES through a whole-degree lookup
 *        table, in float and in fixed point.
 *
 * Common to both paths: the reduction of the angle is exact (the error does
 * not grow with the angle); whole degrees return the correctly rounded table
 * value, so multiples of 90 degrees give exactly 0 and +-1; sin(-x) ==
 * -sin(x) and cos(-x) == cos(x) bit for bit. Shifting an angle by whole
 * turns gives the same bits as long as its sign does not change. DH_SMALL
 * builds give the same bits for every input. Thread-safe and reentrant (no
 * state; const tables only). Method and error derivation: docs/design.md
 * ("Lookup-table trigonometry"), docs/accuracy_trig.md. Measured cost and
 * stack: docs/performance_target.md, docs/footprint.md.
 */
#ifndef DHMATH_DH_TRIG_H
#define DHMATH_DH_TRIG_H

#include "dhmath/dh_common.h"

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
 * overflow for any int32 input (proof in src/dh_trig_q.c).
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

#ifdef __cplusplus
}
#endif

#endif /* DHMATH_DH_TRIG_H */
