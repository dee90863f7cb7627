/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_mathf.h - PRIVATE libm-free float helpers (not installed): newlib's
 * sinf/cosf/atan2f/sqrtf need more than the 256 B stack budget of a public
 * function on Cortex-M0+. No libm, heap, mutable data, recursion or double;
 * on Cortex-M0+ the only callees are libgcc's soft-float routines.
 * Requires IEEE binary32, round to nearest, no -ffast-math, no FMA
 * contraction (as dh_trig_f32.c). Tested by test/internal/test_mathf.c and (the
 * degree functions, through the public API) test/trig/test_itrig_f32.c.
 */
#ifndef DHMATH_SRC_DH_MATHF_H
#define DHMATH_SRC_DH_MATHF_H

#include <math.h>
#include <stdint.h>

#include "dhmath/common.h"
#include "dh_build.h"

/**
 * atan2f(y, x) in RADIANS without libm, with the C99 Annex F special cases
 * (the sign of a zero result is the sign of y; NaN in, NaN out), result in
 * [-pi, pi], <= 2 ulp. Method: u = mn / mx for mn < mx / 2, else
 * u = (mn - mx) / (mn + mx) + pi/4 (exact numerator, Fast2Sum on the
 * denominator), |u| <= 1/2, atan(u) = u + u z P(z), then K pi/4 (hi + lo)
 * +- atan(u) summed with Fast2Sum: one rounding at the end.
 */
float dh_atan2f_(float y, float x);

/**
 * atan2(y, x) in DEGREES plus corr (degrees, added before the one final
 * rounding), for finite (y, x) not both zero: the shared reduction of
 * dh_atan2f_ on (x, y) scaled by a power of two (max magnitude in [1, 2)),
 * then 45 K +- (180/pi) (u + ul + c) in double-float (hi + lo) arithmetic.
 * Result in [-180, 180] (y = -0 with x < 0 gives -180; the sign of a zero
 * result is that of y), within 1 ulp of the correctly rounded value when
 * |corr| <= 2^-20 |result|; corr is dropped where min/max < 2^-60.
 */
float dh_atan2f_deg_(float y, float x, float corr);

/**
 * atan2(y, x) in DEGREES, in (-180, 180] (y = +-0 with x < 0 gives 180),
 * within 3 ulp (results below 2^-100: 3 ulp of 2^-100; ratios that small
 * underflow), for finite (y, x) not both zero (both zero give 45; a NaN
 * in gives NaN out): the reduction of dh_atan2f_ in plain float (no bit
 * tests, no special cases; the polynomial in fused multiply-adds where
 * the core has them, dh_mla_f32_), 45 K degrees exact and atan(u) scaled
 * by 180/pi. For the closed-form solvers, whose callers take (0, 0) apart.
 */
float dh_atan2f_dg_(float y, float x);

/* The minimax coefficients of atan on [-1/3, 1/2] (dh_mathf.c). */
#define DH_MF_T1 (-0.33333326912f)
#define DH_MF_T2 0.19999488967f
#define DH_MF_T3 (-0.14272060333f)
#define DH_MF_T4 0.10940818909f
#define DH_MF_T5 (-0.079834060236f)
#define DH_MF_T6 0.03871351284f
/* 180 / pi rounded to float (DH_RAD2DEG_F) */
#define DH_MF_RAD2DEG 57.295779513082320876798f

/* a b + c (dh_mla_f32_) and c - a b (dh_mls_f32_): one fused multiply-add
 * (a single rounding) where the core has the instruction (__FP_FAST_FMAF:
 * Cortex-M4F, M7, RV32F), else the product and the sum rounded each (the
 * same bits as writing a * b + c or c - a * b). */
#if defined(__GNUC__) && defined(__FP_FAST_FMAF)
DH_INLINE float dh_mla_f32_(float a, float b, float c)
{
    return __builtin_fmaf(a, b, c);
}
DH_INLINE float dh_mls_f32_(float a, float b, float c)
{
    return __builtin_fmaf(-a, b, c);
}
#else
DH_INLINE float dh_mla_f32_(float a, float b, float c)
{
    return a * b + c;
}
DH_INLINE float dh_mls_f32_(float a, float b, float c)
{
    return c - a * b;
}
#endif

/* dh_atan2f_dg_'s body with fb returned for (+-0, +-0) (dh_atan2f_dg_: fb
 * 45, the value the general path gives them), inlined by a caller that has
 * the code space and the registers for it (the FPU builds' closed-form
 * wrist solver, whose fallback is a free angle): the zero test costs
 * nothing on the common path, it sits in the branch of equal magnitudes. */
DH_INLINE float dh_atan2f_dg_fb_inl_(float y, float x, float fb)
{
    /* 45 K degrees, indexed by (w << 2) | (xn << 1) | b (below) */
    static const float k45[8] = { 0.0f, 45.0f, 180.0f, 135.0f, 90.0f, 45.0f, 90.0f, 135.0f };
    const float ax = fabsf(x), ay = fabsf(y);
    float mx, mn, u, z, p, a;
    uint32_t w, xn, b, k, sneg;
    w = 0u; /* 1: reflected about the diagonal */
    if (ay > ax) w = 1u;
    xn = 0u; /* 1: the left half-plane */
    if (x < 0.0f) xn = 1u;
    mx = w ? ay : ax;
    mn = w ? ax : ay;
    if (!(mn < mx)) {
        /* equal magnitudes (or a NaN): 45 degrees off an axis; mn - mx
         * is 0, or NaN for a NaN; both zero (a NaN fails the tests): fb */
        if (mx <= 0.0f && mn <= 0.0f) return fb;
        b = 1u;
        u = mn - mx;
    } else if (mn + mn >= mx) {
        /* ratio in [1/2, 1): 45 + atan(u), u = (mn - mx) / (mn + mx) in
         * [-1/3, 0), the denominator's rounding error divided out, as in
         * mathf_atan2_parts; scaled by 1/4 near the top against overflow */
        float n, d, e;
        if (mx > 0x1.0p+126f) {
            mx *= 0.25f;
            mn *= 0.25f;
        }
        b = 1u;
        n = mn - mx;
        d = mx + mn;
        e = mn - (d - mx);
        u = n / d;
        u = u - u * (e / d);
    } else {
        b = 0u;
        u = mn / mx; /* in [0, 1/2); mx > 0 here */
    }
    z = u * u;
    /* u + u z P(z), Horner in multiply-adds (fused where the core has them:
     * each step rounds once, within the 3 ulp bound either way) */
    p = dh_mla_f32_(z, DH_MF_T6, DH_MF_T5);
    p = dh_mla_f32_(z, p, DH_MF_T4);
    p = dh_mla_f32_(z, p, DH_MF_T3);
    p = dh_mla_f32_(z, p, DH_MF_T2);
    p = dh_mla_f32_(z, p, DH_MF_T1);
    p = dh_mla_f32_(u, z * p, u) * DH_MF_RAD2DEG;
    /* angle = 45 K + s atan(u) degrees, K and s as in mathf_atan2_parts:
     * K = b (w 0, xn 0), 4 - b (w 0, xn 1), 2 - b (w 1, xn 0), 2 + b (w 1,
     * xn 1); s = -1 when w ^ xn */
    sneg = w ^ xn;
    k = (w << 2) | (xn << 1) | b;
    a = sneg ? k45[k] - p : k45[k] + p; /* in [0, 180] */
    return (y < 0.0f && a < 180.0f) ? -a : a;
}


/**
 * asin v (want_acos 0, in [-90, 90], odd bit for bit) or acos v (want_acos
 * 1, in [0, 180]) in DEGREES for |v| <= 1 (not NaN), within 1 ulp of the
 * correctly rounded value: sqrt(1 - v^2) in double-float and
 * dh_atan2f_deg_ with the first-order effect of its low part as corr.
 */
float dh_asinf_deg_(float v, unsigned want_acos);

/**
 * sin x and cos x (RADIANS) into *s, *c (not NULL, not aliased) without
 * libm, <= 2 ulp for every finite x; NaN or +-Inf gives NaN in both. |x| >
 * pi/4 is reduced EXACTLY modulo pi/2 (Payne-Hanek in integers on a
 * 224-bit 2/pi), then minimax polynomials; sin is odd and cos even bit for
 * bit.
 */
void dh_sincosf_(float x, float *s, float *c);

/* The minimax coefficients of sin and cos on [-pi/4, pi/4] (dh_mathf.c). */
#define DH_MF_S1 (-0.16666654603f)
#define DH_MF_S2 0.0083321603364f
#define DH_MF_S3 (-1.9515224212e-4f)
#define DH_MF_C1 0.041666645671f
#define DH_MF_C2 (-0.0013887315639f)
#define DH_MF_C3 2.4433085206e-5f

/**
 * sin r and cos r (RADIANS) for |r| <= pi/4 (a few ulp beyond is fine):
 * the polynomials of dh_sincosf_ without its argument reduction, so a
 * caller whose argument is known to be small has none of the reduction's
 * stack.
 */
DH_INLINE void dh_sincosf_pio4_(float r, float *s, float *c)
{
    float z = r * r;
    *s = r + r * (z * (DH_MF_S1 + z * (DH_MF_S2 + z * DH_MF_S3)));
    *c = 1.0f - (0.5f * z - z * (z * (DH_MF_C1 + z * (DH_MF_C2 + z * DH_MF_C3))));
}

/* VSQRT.F32 (single-precision FPU) gives the bits of the integer version. */
#if defined(__GNUC__) && defined(__arm__) && defined(__ARM_FP) && ((__ARM_FP & 4) != 0) && !defined(__SOFTFP__)
#define DH_MATHF_VSQRT 1
#else
#define DH_MATHF_VSQRT 0
#endif

/** sqrtf(x) correctly rounded without libm: +-0 -> +-0, +Inf -> +Inf,
 *  NaN or x < 0 -> NaN. */
float dh_sqrtf_(float x);

#endif /* DHMATH_SRC_DH_MATHF_H */
