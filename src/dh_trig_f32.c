/*
 * dh_trig_f32.c - float sine/cosine of angles in degrees through the
 * whole-degree table (contract in include/dhmath/dh_trig.h).
 *
 * Method:
 *  1. |deg| is split exactly into whole degrees and a fraction f in [0, 1):
 *     below 2^23 by truncation to an integer (a - trunc(a) is exact in
 *     binary32), at or above 2^23 every float is an integer M * 2^e and the
 *     whole part modulo 360 is computed from M and e in integer arithmetic.
 *     The result n mod 360 is therefore exact for every finite float, so the
 *     error does not depend on the size of the angle.
 *  2. n = 90 k + m with m in 0..89 (quadrant k).
 *  3. sin(m + f) = S + (S (cos f - 1) + C sin f),
 *     cos(m + f) = C + (C (cos f - 1) - S sin f), S = sin m, C = cos m from
 *     the correctly rounded table; sin f, cos f - 1 are short Taylor
 *     polynomials in f (f < 1 degree = 0.01745 rad: the first omitted terms
 *     are t^5/120 < 1.4e-11 and t^6/720 < 4e-14). The correction is at most
 *     0.0175, so its rounding errors are ~1e-9 and the table value
 *     dominates; at f = 0 the correction is exactly +0 and the table value is
 *     returned unchanged.
 *  4. quadrant symmetry, then the sign of the input is applied to the sine
 *     by negation (so sin(-x) == -sin(x) and cos(-x) == cos(x) bit for bit).
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

/* 2^e mod 360 for e = 0..14; for e >= 3, 2^(e+12) == 2^e (mod 360) because
 * 2^e == 0 (mod 8) and 2^12 = 4096 == 1 (mod 45). */
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

/* deg must be finite (exponent field != 0xFF). */
static void dh_trig_core_f32(float deg, float *s_out, float *c_out)
{
    uint32_t bits, mag, n, k, m;
    float a, f, f2, sf, cm, s0, c0, sq, cq, ss, cc;

    memcpy(&bits, &deg, sizeof bits);
    mag = bits & 0x7FFFFFFFu;
    memcpy(&a, &mag, sizeof a);                /* a = |deg|, exact */

    if (mag < 0x4B000000u) {                   /* a < 2^23 */
        uint32_t i = (uint32_t)a;              /* truncation == floor, fits */
        f = a - (float)i;                      /* exact, in [0, 1) */
        n = dh_trig_mod360(i);
    } else {                                   /* a = M * 2^e, integer */
        uint32_t e = (mag >> 23) - 150u;       /* 0..104 for finite a */
        uint32_t mant = (mag & 0x007FFFFFu) | 0x00800000u;
        while (e >= 15u) {
            e -= 12u;                          /* at most 8 passes */
        }
        n = dh_trig_mod360(dh_trig_mod360(mant) * dh_trig_pow2_mod360[e]);
        f = 0.0f;
    }

    /* n in 0..359 -> quadrant k in 0..3 and m in 0..89 */
    k = (uint32_t)(n >= 90u) + (uint32_t)(n >= 180u) + (uint32_t)(n >= 270u);
    m = n - 90u * k;
    s0 = dh_trig_sin_f32[m];
    c0 = dh_trig_sin_f32[90u - m];

    f2 = f * f;
    sf = f * (DH_TRIG_A1 + f2 * DH_TRIG_A3);   /* sin f */
    cm = f2 * (DH_TRIG_B2 + f2 * DH_TRIG_B4);  /* cos f - 1 */
    sq = s0 + (s0 * cm + c0 * sf);
    cq = c0 + (c0 * cm - s0 * sf);

    /* quadrant: (s,c) -> k=1: (c,-s), k=2: (-s,-c), k=3: (-c,s).
     * 0.0f - x instead of -x so that exact zeros come out as +0. */
    ss = (k & 1u) ? cq : sq;
    cc = (k & 1u) ? sq : cq;
    if (k >= 2u) {
        ss = 0.0f - ss;
    }
    if (k == 1u || k == 2u) {
        cc = 0.0f - cc;
    }
    if (bits & 0x80000000u) {
        ss = -ss;                              /* odd: exact negation */
    }
    *s_out = ss;
    *c_out = cc;
}

dh_status dh_sincos_f32(float deg, float *s, float *c)
{
    uint32_t bits;
    DH_ASSERT(s != NULL);
    DH_ASSERT(c != NULL);
    memcpy(&bits, &deg, sizeof bits);
    if ((bits & 0x7F800000u) == 0x7F800000u) {  /* NaN or +-Inf */
        *s = dh_trig_nan_f32();
        *c = *s;
        return DH_ERR_NAN;
    }
    dh_trig_core_f32(deg, s, c);
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
