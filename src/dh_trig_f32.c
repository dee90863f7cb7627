/*
 * dh_trig_f32.c - float sine/cosine of angles in degrees through the
 * whole-degree table (contract in include/dhmath/dh_trig.h).
 *
 * Method:
 *  1. |deg| is split exactly into whole degrees i and a fraction f in
 *     [0, 1): below 2^23 (the fast path, one branch) by one float->int and
 *     one int->float conversion (a - trunc(a) is exact in binary32); at or
 *     above 2^23 every float is an integer M * 2^e and
 *     i = (M mod 360) * (2^e mod 360) mod 360 in integer arithmetic, f = 0.
 *     The reduction is therefore exact for every finite float, so the error
 *     does not depend on the size of the angle.
 *  2. i = 90 q + m, m in 0..89, quadrant k = q mod 4, with q = floor(i/90)
 *     an exact multiply-shift (no division).
 *  3. S = sin(90k + m), C = cos(90k + m) are table entries with the
 *     quadrant's sign: the index (m or 90 - m) is selected by a mask, not a
 *     branch (gcc compiles a plain select into a branch on x86, and random
 *     quadrants mispredict it half of the time), the sign comes from a
 *     5-entry table. Then
 *     sin = S + (S (cos f - 1) + C sin f), cos = C + (C (cos f - 1) - S sin f)
 *     with Taylor polynomials in f for sin f and cos f - 1 (f < 1 degree =
 *     0.01745 rad: the first omitted terms are t^5/120 < 1.4e-11 and
 *     t^6/720 < 4e-14). The correction is at most 0.0175, so its rounding
 *     errors are ~1e-9 and the correctly rounded table value dominates; at
 *     f = 0 the correction is exactly zero and the table value is returned.
 *  4. Signed zeros: a table zero with a negative quadrant sign is -0
 *     (sin 180, cos 90), but then f = +0 (a - trunc(a) of an integer, or
 *     the +0 of the large path), so cos f - 1 = -0, sin f = +0 and the
 *     correction S * (-0) + C * (+0) (resp. C * (-0) - S * (+0)) is +0 when
 *     S (resp. C) is -0; -0 + +0 = +0 in round-to-nearest, so every exact
 *     zero comes out +0 without a "+ 0.0f". Then odd symmetry: the sign bit
 *     of the sine of a negative input is flipped, so sin(-x) == -sin(x) bit
 *     for bit, zeros included. (Verified bit-identical to the earlier
 *     version that added 0.0f, on every 7th finite float of both signs.)
 * Requires IEEE binary32 with round-to-nearest (the default) and no
 * value-changing optimisations: -ffast-math would drop signed zeros (step
 * 4); the error proof and the bit-identity check assume separate multiply
 * and add (no FMA contraction, the ISO C default of gcc with -std=c99).
 * All arithmetic is single precision (float literals), no libm.
 */
#include <string.h>

#include "dhmath/dh_trig.h"
#include "dh_trig_tables.h"

/* Taylor coefficients in f (degrees): t = f * pi/180. */
#define DH_TRIG_A1 0.017453292519943295f   /* pi/180 */
#define DH_TRIG_A3 (-8.86096155701298e-07f) /* -(pi/180)^3 / 6 */
#define DH_TRIG_B2 (-1.5230870989335428e-04f) /* -(pi/180)^2 / 2 */
#define DH_TRIG_B4 3.866323851562993e-09f   /* (pi/180)^4 / 24 */

/* ceil(2^32 / 90): (i * DH_TRIG_DIV90_64) >> 32 == i / 90 for every
 * i < 2^24. Proof: the constant exceeds 2^32/90 by d < 0.17, so the
 * estimate exceeds i/90 by i d / 2^32 < 6.6e-4, less than the distance
 * 1/90 from i/90 (fraction at most 89/90) to the next integer. Checked
 * exhaustively as well. */
#define DH_TRIG_DIV90_64 47721859u

/* 2^e mod 360 for e = 0..14; for e >= 3, 2^(e+12) == 2^e (mod 360) because
 * 2^e == 0 (mod 8) and 2^12 = 4096 == 1 (mod 45). */
/* sign of sin(90 j + m) for j = 0..4 (index k + 1 for the cosine) */
static const float dh_trig_qsign[5] = { 1.0f, 1.0f, -1.0f, -1.0f, 1.0f };

static const uint16_t dh_trig_pow2_mod360[15] = {
    1u, 2u, 4u, 8u, 16u, 32u, 64u, 128u, 256u, 152u, 304u, 248u, 136u, 272u, 184u
};

static float dh_trig_nan_f32(void)
{
    const uint32_t qnan = 0x7FC00000u;
    float r;
    memcpy(&r, &qnan, sizeof r);
    return r;
}

dh_status dh_sincos_f32(float deg, float *s, float *c)
{
    uint32_t bits, mag, i, q, k, m, sb;
    float a, f, f2, sf, cm, s0, c0, ss;

    DH_ASSERT(s != NULL);
    DH_ASSERT(c != NULL);
    memcpy(&bits, &deg, sizeof bits);
    mag = bits & 0x7FFFFFFFu;
    memcpy(&a, &mag, sizeof a);                /* a = |deg|, exact */

    if (mag < 0x4B000000u) {                   /* a < 2^23: the fast path */
        int32_t n = (int32_t)a;                /* truncation == floor, fits */
        f = a - (float)n;                      /* exact, in [0, 1) */
        i = (uint32_t)n;
    } else if (mag < 0x7F800000u) {            /* a = M * 2^e, an integer */
        uint32_t e = (mag >> 23) - 150u;       /* 0..104 for finite a */
        uint32_t mant = (mag & 0x007FFFFFu) | 0x00800000u;
        while (e >= 15u) {
            e -= 12u;                          /* at most 8 passes */
        }
        i = dh_trig_mod360(dh_trig_mod360(mant) * dh_trig_pow2_mod360[e]);
        f = 0.0f;
    } else {                                   /* NaN or +-Inf */
        *s = dh_trig_nan_f32();
        *c = *s;
        return DH_ERR_NAN;
    }

    /* q = floor(i / 90) exactly for i < 2^24 (DH_TRIG_DIV90_64); the
     * quadrant is k = q mod 4 (90 * 4 = 360) and m = i - 90 q is in 0..89,
     * so the table indices m and 90 - m are in 0..90. */
    q = (uint32_t)(((uint64_t)i * DH_TRIG_DIV90_64) >> 32);
    m = i - 90u * q;
    k = q & 3u;
    {
        /* sin(90k + m) = +-T[odd ? 90 - m : m], cos(90k + m) = sin(90(k+1) + m):
         * index select by mask (branch free), sign from a table */
        uint32_t is = m ^ ((m ^ (90u - m)) & (0u - (k & 1u)));
        s0 = dh_trig_sin_f32[is] * dh_trig_qsign[k];
        c0 = dh_trig_sin_f32[90u - is] * dh_trig_qsign[k + 1u];
    }

    f2 = f * f;
    sf = f * (DH_TRIG_A1 + f2 * DH_TRIG_A3);   /* sin f */
    cm = f2 * (DH_TRIG_B2 + f2 * DH_TRIG_B4);  /* cos f - 1 */
    ss = s0 + (s0 * cm + c0 * sf);
    *c = c0 + (c0 * cm - s0 * sf);
    memcpy(&sb, &ss, sizeof sb);
    sb ^= bits & 0x80000000u;
    memcpy(s, &sb, sizeof sb);
    return DH_OK;
}

float dh_sin_f32(float deg)
{
    float s, c;
    if (dh_sincos_f32(deg, &s, &c) != DH_OK) {
        return dh_trig_nan_f32();
    }
    return s;
}

float dh_cos_f32(float deg)
{
    float s, c;
    if (dh_sincos_f32(deg, &s, &c) != DH_OK) {
        return dh_trig_nan_f32();
    }
    return c;
}
