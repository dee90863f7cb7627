/*
 * dh_trig_f32.c - float sine/cosine of angles in degrees through the
 * whole-degree table (contract in include/dhmath/dh_trig.h).
 *
 * Method:
 *  1. a = |deg|. Below 2^23 (the fast path, one branch) a is rounded to the
 *     nearest whole degree i by the addition of 2^23: a + 2^23 lies in
 *     [2^23, 2^24], where the float spacing is 1, so the sum is
 *     2^23 + round(a) and its bit pattern minus that of 2^23 is i
 *     (0..2^23; at the top the exponent steps up and the difference of the
 *     bit patterns is still i = 2^23). t = sum - 2^23 is exact (Sterbenz)
 *     and so is f = a - t, in [-0.5, 0.5] (a - t is a multiple of ulp(a)
 *     below 1 in magnitude, or the Sterbenz case for a < 1). At or above
 *     2^23 every float is an integer M * 2^e; it is replaced by the float
 *     of i = (M mod 360) * (2^e mod 360) mod 360 (integer arithmetic, out
 *     of line: rare), which then takes the fast path with f = 0. The
 *     reduction is therefore exact for every finite float, so the error
 *     does not depend on the size of the angle.
 *  2. i = 180 h + r, r in 0..179, h = floor(i/180) an exact multiply-shift
 *     (no division). sin(i) = (-1)^h sin(r), cos(i) = (-1)^h cos(r), and
 *     with d = 90 - r (in -89..90): sin(r) = T[90 - |d|],
 *     cos(r) = sign(d) T[|d|]. The table values are read as bit patterns
 *     and the signs applied with XOR (no branch, no multiply): S = +-sin i,
 *     C = +-cos i exactly. (DH_SMALL: the same floats converted from the
 *     Q2.30 table, so that the float table is not linked; see
 *     dh_trig_tab_f32.)
 *  3. sin = S + (S (cos f - 1) + C sin f), cos = C + (C (cos f - 1) - S sin f)
 *     with sin f = A1 f + A3 f^3 and cos f - 1 = B2 f^2 (f in degrees,
 *     t = f pi/180, |t| <= 0.00873 rad: the omitted terms are
 *     t^5/120 < 4.2e-13 and t^4/24 < 2.5e-10). The correction is at most
 *     0.0088 in magnitude, so its coefficient, rounding and truncation
 *     errors stay below 2.2e-9 (docs/accuracy_trig.md) and the correctly
 *     rounded table value dominates: bound 2^-25 + 2^-25 + 2.2e-9 < 6.2e-8.
 *     At f = 0 the correction is exactly zero and the table value is
 *     returned.
 *  4. Signed zeros: a table zero with a negative sign is -0 (sin 180,
 *     cos 90 + 180 h), but then f = +0 (x - x is +0 in round-to-nearest,
 *     and the large path passes whole degrees), so cos f - 1 = B2 * +0 = -0
 *     and sin f = +0; the correction S * (-0) + C * (+0) (resp.
 *     C * (-0) - S * (+0)) is +0 when S (resp. C) is -0, and -0 + +0 = +0:
 *     every exact zero comes out +0. Then odd symmetry: the sign bit of the
 *     sine of a negative input is flipped, so sin(-x) == -sin(x) bit for
 *     bit, zeros included.
 * Requires IEEE binary32 with round-to-nearest (the default), evaluation in
 * float (FLT_EVAL_METHOD 0, or a compiler that rounds assignments as C99
 * requires: the rounding of a + 2^23 is the reduction), and no
 * value-changing optimisations: -ffast-math would fold (a + 2^23) - 2^23
 * into a and drop signed zeros; the error proof assumes separate multiply
 * and add (no FMA contraction, the ISO C default of gcc with -std=c99).
 * All arithmetic is single precision (float literals), no libm.
 */
#include <string.h>

#include "dhmath/dh_trig.h"
#include "dh_trig_tables.h"

/* Taylor coefficients in f (degrees): t = f * pi/180. */
#define DH_TRIG_A1 0.017453292519943295f    /* pi/180 */
#define DH_TRIG_A3 (-8.86096155701298e-07f)  /* -(pi/180)^3 / 6 */
#define DH_TRIG_B2 (-1.5230870989335428e-04f) /* -(pi/180)^2 / 2 */

/* 2^23 and its bit pattern: a + 2^23 rounds a to a whole number for
 * 0 <= a < 2^23 */
#define DH_TRIG_RND    8388608.0f
#define DH_TRIG_RND_BITS 0x4B000000u

/* ceil(2^32 / 180): (i * DH_TRIG_DIV180_64) >> 32 == i / 180 for every
 * i < 2^24. Proof: the constant exceeds 2^32/180 by d < 0.58, so the
 * estimate exceeds i/180 by i d / 2^32 < 2.3e-3, less than the distance
 * 1/180 from i/180 (fraction at most 179/180) to the next integer.
 * Checked exhaustively as well. */
#define DH_TRIG_DIV180_64 23860930u

#if !DH_SMALL
/* 2^e mod 360 for e = 0..14; for e >= 3, 2^(e+12) == 2^e (mod 360) because
 * 2^e == 0 (mod 8) and 2^12 = 4096 == 1 (mod 45). */
static const uint16_t dh_trig_pow2_mod360[15] = {
    1u, 2u, 4u, 8u, 16u, 32u, 64u, 128u, 256u, 152u, 304u, 248u, 136u, 272u, 184u
};
#endif

static float dh_trig_nan_f32(void)
{
    const uint32_t qnan = 0x7FC00000u;
    float r;
    memcpy(&r, &qnan, sizeof r);
    return r;
}

#if DH_SMALL
/* The whole degrees mod 360 of a finite float a >= 2^23 (magnitude bit
 * pattern mag), as a float (exact: < 360). a = M * 2^e with the 24-bit
 * significand M and e = 0..104, so a is an integer of 24 + e bits; they are
 * shifted in from the top, doubling the remainder mod 360 at each step
 * (binary long division: 2 i + 1 < 720, one conditional subtraction). The
 * same exact integer as the table method of the default build, without the
 * table and the multiply-shift reduction; at most 128 steps on this rare
 * path. */
static float dh_trig_big_deg(uint32_t mag)
{
    uint32_t k = (mag >> 23) - 126u;       /* 24 + e bits */
    uint32_t m = (mag << 8) | 0x80000000u; /* M (implicit bit set) at the top */
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
#else /* !DH_SMALL */
/* The whole degrees mod 360 of a finite float a >= 2^23 (magnitude bit
 * pattern mag), as a float (exact: < 360). a = M * 2^e with the 24-bit
 * significand M and e = 0..104; 2^e mod 360 comes from
 * dh_trig_pow2_mod360 (exponents above 14 are brought into 3..14 by steps
 * of 12). Out of line so that the fast path stays small. */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((noinline, cold))
#endif
static float dh_trig_big_deg(uint32_t mag)
{
    uint32_t e = (mag >> 23) - 150u;           /* 0..104 for finite a */
    uint32_t mant = (mag & 0x007FFFFFu) | 0x00800000u;
    uint32_t i;
    while (e >= 15u) {
        e -= 12u;                              /* at most 8 passes */
    }
    i = dh_trig_mod360(dh_trig_mod360(mant) * dh_trig_pow2_mod360[e]);
    return (float)i;
}
#endif /* DH_SMALL */

#if DH_SMALL
/*
 * (-1)^neg sin(n deg) for n = 0..90 as the correctly rounded float of the
 * default build's table dh_trig_sin_f32, taken from the Q2.30 table instead
 * (the float table is then not linked: 364 bytes). The conversion of the
 * int32 rounds to nearest even and the scaling by 2^-30 is exact, so the
 * result is the float nearest to the Q2.30 entry. That is the correctly
 * rounded sine except where the entry lies exactly halfway between two
 * floats: n = 1 (entry 0x011DF0B3, 25 bits, rounded up from the true value,
 * which the float must round down: entry - 1 converts exactly to it) and
 * n = 19 (0x14D61BD0, 29 bits, rounded down, the float rounds up: entry + 1
 * breaks the tie upwards). Checked for all 91 entries with exact rational
 * arithmetic, and the whole function bit for bit against the default build
 * for every float input. Only the bit 0 of neg is used; the negation is
 * exact (|v| <= 2^30). A zero entry comes out +0 where the default build
 * has -0 (sin 180, cos 90 + 180 h); the result is the same: step 4 above
 * shows that every exact zero result is +0 whatever the zero's sign, and a
 * nonzero correction is not affected by it.
 */
static float dh_trig_tab_f32(uint32_t n, uint32_t neg)
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
#if DH_SMALL
    uint32_t bits, mag, i, h, r, du, neg, ad, sb;
#else
    uint32_t bits, mag, i, h, r, du, neg, ad, hs, sb, cb;
#endif
    float a, sum, f, f2, sf, cm, s0, c0, ss;

    DH_ASSERT(s != NULL);
    DH_ASSERT(c != NULL);
    memcpy(&bits, &deg, sizeof bits);
    mag = bits & 0x7FFFFFFFu;
    memcpy(&a, &mag, sizeof a);                /* a = |deg|, exact */
    if (mag >= 0x4B000000u) {                  /* a >= 2^23, Inf or NaN: rare */
        if (mag >= 0x7F800000u) {
            *s = dh_trig_nan_f32();
            *c = *s;
            return DH_ERR_NAN;
        }
        a = dh_trig_big_deg(mag);              /* same angle mod 360, < 360 */
    }

    /* whole degrees i = round(a), fraction f = a - i in [-0.5, 0.5] (step 1) */
    sum = a + DH_TRIG_RND;
    memcpy(&i, &sum, sizeof i);
    i -= DH_TRIG_RND_BITS;                     /* 0..2^23 */
    f = a - (sum - DH_TRIG_RND);               /* both subtractions exact */

    /* i = 180 h + r; sin i = (-1)^h T[90 - |d|], cos i = (-1)^h sign(d) T[|d|]
     * with d = 90 - r. Unsigned throughout: du is d modulo 2^32, its top
     * bit is the sign of d, |d| = (du ^ neg) - neg in 0..90. */
    h = (uint32_t)(dh_trig_mul64(i, DH_TRIG_DIV180_64) >> 32);
    r = i - 180u * h;                          /* 0..179 */
    du = 90u - r;
    neg = 0u - (du >> 31);
    ad = (du ^ neg) - neg;                     /* |d|, 0..90 */
#if DH_SMALL
    s0 = dh_trig_tab_f32(90u - ad, h);         /* (-1)^h T[90 - |d|] */
    c0 = dh_trig_tab_f32(ad, h ^ (du >> 31));  /* (-1)^h sign(d) T[|d|] */
#else
    hs = h << 31;                              /* sign bit of (-1)^h */
    memcpy(&sb, &dh_trig_sin_f32[90u - ad], sizeof sb);
    memcpy(&cb, &dh_trig_sin_f32[ad], sizeof cb);
    sb ^= hs;
    cb ^= (du ^ hs) & 0x80000000u;
    memcpy(&s0, &sb, sizeof s0);
    memcpy(&c0, &cb, sizeof c0);
#endif

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

#if DH_SMALL
/* dh_sincos_f32 writes the quiet NaN of the default wrappers below to both
 * outputs when it fails, so its sine (which 0) or cosine (which 1) is
 * returned as it is; one body for both wrappers. */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((noinline))
#endif
static float dh_trig_pick_f32(float deg, unsigned which)
{
    float sc[2];
    (void)dh_sincos_f32(deg, &sc[0], &sc[1]);
    return sc[which];
}

float dh_sin_f32(float deg)
{
    return dh_trig_pick_f32(deg, 0u);
}

float dh_cos_f32(float deg)
{
    return dh_trig_pick_f32(deg, 1u);
}
#else /* !DH_SMALL */
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
#endif /* DH_SMALL */
