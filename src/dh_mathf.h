/*
 * dh_mathf.h - PRIVATE float helpers of the library's float path (not part
 * of the public API, not installed): libm-free replacements for atan2f and
 * sinf/cosf with a small, fixed stack.
 *
 * Why: newlib's sinf/cosf need more than the 256-byte stack budget of a
 * public function on Cortex-M0+ (a Payne-Hanek reduction with a large local
 * array) and pull in much flash; its atan2f also needs more stack than the
 * callers can afford. These helpers use no libm, no heap, no mutable data,
 * no recursion and no double (-Wdouble-promotion clean); on Cortex-M0+ their
 * only callees are libgcc's soft-float routines (and __aeabi_lmul).
 *
 * Requirements (as dh_trig_f32.c): IEEE binary32, round to nearest, float
 * evaluation (FLT_EVAL_METHOD 0 or assignments rounded as C99 requires),
 * no -ffast-math, no FMA contraction assumed by the error bounds.
 *
 * Accuracy is tested by test/test_mathf.c against double-precision libm
 * (dense sweeps, signed zeros, infinities, NaN).
 */
#ifndef DHMATH_SRC_DH_MATHF_H
#define DHMATH_SRC_DH_MATHF_H

#include "dhmath/dh_common.h"

/**
 * @brief Four-quadrant arc tangent of y / x in RADIANS, a drop-in for C99
 *        atan2f() without libm.
 *
 * Method: |y| and |x| are ordered (mn <= mx); for mn < mx / 2 the
 * argument is u = mn / mx, otherwise u = (mn - mx) / (mn + mx) (numerator
 * exact by Sterbenz, the denominator's rounding error recovered exactly
 * and divided out) and pi/4 is added, so |u| <= 1/2 with a single
 * rounding; atan(u) = u + u z P(z) (z = u^2, degree-5 minimax P, relative
 * error 2^-31.9). The octant and the quadrant are then applied as
 * K pi/4 + s atan(u), K = 0..4, with K pi/4 held as a two-float constant
 * (hi + lo) and hi + s atan(u) summed with its rounding error recovered
 * (Fast2Sum), so the result is rounded once at the end. One division
 * (two in the diagonal octants); no table beyond 10 floats.
 *
 * @param y any float (numerator, the sine side)
 * @param x any float (denominator, the cosine side)
 * @return the angle in [-pi, pi] (float(pi) = 3.14159274 at the ends),
 *         with the C99 Annex F special cases: atan2(+-0, +0 or x > 0) =
 *         +-0; atan2(+-0, -0 or x < 0) = +-pi; atan2(y, +-0) = +-pi/2
 *         for y != 0; atan2(+-y, +inf) = +-0 and atan2(+-y, -inf) = +-pi
 *         for finite y; atan2(+-inf, finite x) = +-pi/2;
 *         atan2(+-inf, +inf) = +-pi/4, atan2(+-inf, -inf) = +-3pi/4; the
 *         sign of a zero result is the sign of y. NaN in either argument
 *         returns a NaN (x + y).
 *         Error: <= 2 ulp of the exact result over the whole float range.
 */
float dh_atan2f_(float y, float x);

/**
 * @brief Sine and cosine of x in RADIANS, any finite x, without libm.
 *
 * Method: |x| <= pi/4 is used directly. Otherwise x * 2/pi is reduced
 * EXACTLY modulo 4 (Payne-Hanek in integers: the 24-bit significand times
 * a 96-bit window of 2/pi selected by the exponent, from a 224-bit const
 * table; no division, three 32x32->64 multiplications), which gives the
 * quadrant and r in [-pi/4, pi/4] with a 64-bit fraction, times pi/2 as
 * a 64-bit fixed-point product rounded to float once, so the result
 * does not degrade with |x| (e.g. 1e30 rad is reduced exactly, as the
 * float 1e30 is an exact number). Then minimax polynomials:
 * sin r = r + r z S(z) (relative error 2^-28), cos r = 1 - z/2 + z^2 C(z)
 * (2^-33), z = r^2, and the quadrant's swap and signs (bit operations).
 * sin is odd bit for bit (sin(-x) == -sin(x), sin(-0) = -0); cos is even.
 *
 * @param x angle in radians; NaN or +-Inf gives NaN in both outputs
 * @param s output sin x (not NULL); may not alias c
 * @param c output cos x (not NULL)
 * Error: <= 2 ulp of the exact sin / cos for every finite x.
 */
void dh_sincosf_(float x, float *s, float *c);

/*
 * VSQRT.F32 is the IEEE square root (correctly rounded, sqrt(-x) = NaN,
 * no errno) on ARM cores with a single-precision FPU; elsewhere the
 * integer version in dh_mathf.c gives the same bits.
 */
#if defined(__GNUC__) && defined(__arm__) && defined(__ARM_FP) && ((__ARM_FP & 4) != 0) && !defined(__SOFTFP__)
#define DH_MATHF_VSQRT 1
#else
#define DH_MATHF_VSQRT 0
#endif

/**
 * Square root of x, correctly rounded (IEEE binary32, round to nearest),
 * without libm: one instruction on an FPU core, an integer digit-by-digit
 * root elsewhere. +-0 -> +-0, +Inf -> +Inf, NaN or x < 0 -> NaN.
 */
float dh_sqrtf_(float x);

#endif /* DHMATH_SRC_DH_MATHF_H */
