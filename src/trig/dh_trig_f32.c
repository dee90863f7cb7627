/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_trig_f32.c - float sine/cosine of angles in degrees through the
 * whole-degree table (contract in include/dhmath/trig.h).
 *
 * Method:
 *  1. a = |deg|. Below 2^23 a is rounded to the nearest whole degree i by
 *     the addition of 2^23: the sum lies in [2^23, 2^24], where the float
 *     spacing is 1, so its bit pattern minus that of 2^23 is i (0..2^23).
 *     t = sum - 2^23 is exact (Sterbenz) and so is f = a - t, in
 *     [-0.5, 0.5]. At or above 2^23 every float is an integer, replaced by
 *     its exact value mod 360 (trig_big_deg), which then takes the same
 *     path with f = 0: the error does not depend on the size of the angle.
 *  2. i = 180 h + r, r in 0..179, h = floor(i/180) by an exact
 *     multiply-shift. sin(i) = (-1)^h sin(r), cos(i) = (-1)^h cos(r), and
 *     with d = 90 - r (in -89..90): sin(r) = T[90 - |d|],
 *     cos(r) = sign(d) T[|d|] (trig_tab): S = +-sin i, C = +-cos i
 *     exactly.
 *  3. sin = S + (S (cos f - 1) + C sin f), cos = C + (C (cos f - 1) - S sin f)
 *     with sin f = A1 f + A3 f^3 and cos f - 1 = B2 f^2 (f in degrees,
 *     |t| = |f| pi/180 <= 0.00873 rad: omitted terms t^5/120 < 4.2e-13 and
 *     t^4/24 < 2.5e-10). The correction is at most 0.0088, so its errors
 *     stay below 2.2e-9 (docs/accuracy_trig.md) and the correctly rounded
 *     table value dominates: bound 2^-25 + 2^-25 + 2.2e-9 < 6.2e-8. At
 *     f = 0 the correction is exactly zero.
 *  4. Signed zeros: a zero table value (sin 180, cos 90 + 180 h, of either
 *     sign) comes with f = +0, so cos f - 1 = -0, sin f = +0 and the
 *     correction is +0 when S (resp. C) is -0; -0 + +0 = +0: every exact
 *     zero comes out +0. Then the sign bit of the sine of a negative input
 *     is flipped: sin(-x) == -sin(x) bit for bit.
 * Requires IEEE binary32 with round-to-nearest, evaluation in float
 * (FLT_EVAL_METHOD 0, or assignments rounded as C99 requires) and no
 * value-changing optimisations (-ffast-math folds (a + 2^23) - 2^23 and
 * drops signed zeros; the proof assumes no FMA contraction). No libm.
 */
#include <string.h>

#include "dhmath/trig.h"
#include "../internal/dh_floatops.h"
#include "dh_trig_tables.h"

/* Taylor coefficients in f (degrees): t = f * pi/180. */
#define DH_TRIG_A1 DH_DEG2RAD_F                  /* pi/180 */
#define DH_TRIG_A3 (-8.86096155701298e-07f)      /* -(pi/180)^3 / 6 */
#define DH_TRIG_B2 (-1.5230870989335428e-04f)    /* -(pi/180)^2 / 2 */

/* 2^23 and its bit pattern */
#define DH_TRIG_RND      8388608.0f
#define DH_TRIG_RND_BITS 0x4B000000u

/* ceil(2^32 / 180): (i * DH_TRIG_DIV180_64) >> 32 == i / 180 for i < 2^24.
 * The constant exceeds 2^32/180 by d < 0.58, so the estimate exceeds i/180
 * by i d / 2^32 < 2.3e-3, less than the distance 1/180 from i/180 (fraction
 * at most 179/180) to the next integer. Checked exhaustively as well. */
#define DH_TRIG_DIV180_64 23860930u

static float trig_nan(void)
{
    const uint32_t qnan = 0x7FC00000u;
    float r;
    memcpy(&r, &qnan, sizeof r);
    return r;
}

/* Whole degrees mod 360 of a finite float a >= 2^23 (magnitude bits mag),
 * as a float (exact: < 360). a = M 2^e (24-bit M, e = 0..104) is an integer
 * of 24 + e bits, shifted in from the top while the remainder mod 360 is
 * doubled (binary long division: 2 i + 1 < 720, one conditional
 * subtraction per step; at most 128 steps on this rare path). */
static float trig_big_deg(uint32_t mag)
{
    uint32_t k = (mag >> 23) - 126u;       /* 24 + e bits */
    uint32_t m = (mag << 8) | 0x80000000u; /* M, implicit bit at the top */
    uint32_t i = 0u;
    do {
        i = 2u * i + (m >> 31);
        m <<= 1;
        if (i >= 360u) {
            i -= 360u;
        }
    } while (--k != 0u);
    return (float)i;
}

/*
 * (-1)^neg sin(n deg), n = 0..90, correctly rounded (only bit 0 of neg is
 * used). Fast paths: the float table, the sign applied to its bits. General
 * path: the float nearest to the Q2.30 entry (exact conversion and scaling),
 * so the float table is not linked. That is the correctly rounded sine
 * except where the entry lies exactly halfway between two floats: n = 1
 * (0x011DF0B3, rounded up from the true value, entry - 1 converts exactly
 * to the right float) and n = 19 (0x14D61BD0, rounded down: entry + 1
 * breaks the tie upwards); checked for all 91 entries with exact rational
 * arithmetic. A zero comes out +0 where the float table gives -0, which
 * does not change any result (step 4).
 */
#if DH_FAST_PATHS
static float trig_tab(uint32_t n, uint32_t neg)
{
    uint32_t b;
    float v;
    memcpy(&b, &dh_trig_sin_f32[n], sizeof b);
    b ^= neg << 31;
    memcpy(&v, &b, sizeof v);
    return v;
}
#else
static float trig_tab(uint32_t n, uint32_t neg)
{
    int32_t v = dh_trig_sin_q30[n];
    if (n == 1u) {
        v--;
    } else if (n == 19u) {
        v++;
    } else {
        /* every other entry converts to the correctly rounded float */
    }
    if (neg & 1u) {
        v = -v;
    }
    return (float)v * 0x1p-30f;
}
#endif

dh_status dh_sincos_f32(float deg, float *s, float *c)
{
    uint32_t bits, mag, i, h, r, du, neg, ad, sb;
    float a, sum, f, f2, sf, cm, s0, c0, ss;

    DH_ASSERT(s != NULL);
    DH_ASSERT(c != NULL);
    memcpy(&bits, &deg, sizeof bits);
    mag = bits & 0x7FFFFFFFu;
    memcpy(&a, &mag, sizeof a);                /* a = |deg|, exact */
    if (mag >= 0x4B000000u) {                  /* a >= 2^23, Inf or NaN: rare */
        if (mag >= 0x7F800000u) {
            *s = trig_nan();
            *c = *s;
            return DH_ERR_NAN;
        }
        a = trig_big_deg(mag);              /* same angle mod 360, < 360 */
    }

    /* i = round(a), f = a - i in [-0.5, 0.5] (step 1) */
    sum = a + DH_TRIG_RND;
    memcpy(&i, &sum, sizeof i);
    i -= DH_TRIG_RND_BITS;
    f = a - (sum - DH_TRIG_RND);               /* both subtractions exact */

    /* i = 180 h + r, d = 90 - r as du modulo 2^32 (top bit: sign of d),
     * |d| = (du ^ neg) - neg in 0..90 (step 2) */
    h = (uint32_t)(dh_trig_mul64(i, DH_TRIG_DIV180_64) >> 32);
    r = i - 180u * h;
    du = 90u - r;
    neg = 0u - (du >> 31);
    ad = (du ^ neg) - neg;
    s0 = trig_tab(90u - ad, h);
    c0 = trig_tab(ad, h ^ (du >> 31));

    f2 = f * f;
    sf = f * (DH_TRIG_A1 + f2 * DH_TRIG_A3);   /* sin f */
    cm = f2 * DH_TRIG_B2;                      /* cos f - 1 */
    ss = s0 + (s0 * cm + c0 * sf);
    *c = c0 + (c0 * cm - s0 * sf);
    memcpy(&sb, &ss, sizeof sb);
    sb ^= bits & 0x80000000u;
    memcpy(&ss, &sb, sizeof ss);               /* to a local: no memcpy call */
    *s = ss;
    return DH_OK;
}

/* dh_sincos_f32 writes the quiet NaN to both outputs when it fails, so its
 * sine (which 0) or cosine (which 1) is returned as it is. */
static DH_NOINLINE float trig_pick(float deg, unsigned which)
{
    float sc[2];
    (void)dh_sincos_f32(deg, &sc[0], &sc[1]);
    return sc[which];
}

float dh_sin_f32(float deg)
{
    return trig_pick(deg, 0u);
}

float dh_cos_f32(float deg)
{
    return trig_pick(deg, 1u);
}
