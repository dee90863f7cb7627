/**
 * @file dh_trig.h
 * @brief Sine and cosine of angles in DEGREES through a whole-degree lookup
 *        table, in float and in fixed point.
 */
#ifndef DHMATH_DH_TRIG_H
#define DHMATH_DH_TRIG_H

#include "dhmath/dh_common.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * @brief sin and cos of @p deg degrees (float).
 * Contract (filled in by the implementation): exact reduction of any finite
 * angle, whole degrees give the double value rounded to float, multiples of
 * 90 give exactly 0 and +-1, sin(-x) == -sin(x) bitwise, |s|,|c| <= 1.
 * @return DH_OK, or DH_ERR_NAN for NaN/Inf input (outputs then NaN).
 */
dh_status dh_sincos_f32(float deg, float *s, float *c);
/** @brief sin of @p deg degrees; NaN for NaN/Inf input. */
float dh_sin_f32(float deg);
/** @brief cos of @p deg degrees; NaN for NaN/Inf input. */
float dh_cos_f32(float deg);

/**
 * @brief sin and cos of @p deg_q16 degrees (Q16.16) as Q2.30.
 * Integer only; defined for every int32 input. Cannot fail.
 */
void dh_sincos_q(dh_q16 deg_q16, dh_q30 *s_q30, dh_q30 *c_q30);
dh_q30 dh_sin_q(dh_q16 deg_q16);
dh_q30 dh_cos_q(dh_q16 deg_q16);

#ifdef __cplusplus
}
#endif

#endif /* DHMATH_DH_TRIG_H */
