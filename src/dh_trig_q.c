/*
 * dh_trig_q.c - fixed-point sine/cosine of Q16.16 degrees as Q2.30
 * (contract in include/dhmath/dh_trig.h). Integer only: no float, no libm,
 * no division of any width; 32x32->64 multiplies only.
 *
 * Method (same as the float path):
 *  1. u = |x| as an unsigned magnitude (0 .. 2^31; INT32_MIN is never
 *     negated as a signed value). Whole degrees u >> 16 (0..32768) are
 *     reduced modulo 360 exactly by dh_trig_mod360(); the fraction
 *     fr = u & 0xFFFF is f = fr / 65536 degree.
 *  2. n = 90 k + m, m in 0..89, table indices m and 90 - m: both in 0..90
 *     for every input, so no table read can leave the 91-entry table.
 *  3. T = f in radians in units of 2^-37 (T < 2^31.2); then
 *     sin f = T - T^3/6 and 1 - cos f = T^2/2 - T^4/24 in the same units
 *     (first omitted terms: t^5/120 < 0.02 LSB of Q2.30 and t^6/720
 *     < 1e-4 LSB). The corrections S (cos f - 1) + C sin f and
 *     C (cos f - 1) - S sin f are accumulated in 64 bits in units of 2^-67
 *     and rounded once to Q2.30, so the result is table value (0.5 LSB) +
 *     one rounding (0.5 LSB) + approximation error (< 0.05 LSB).
 *  4. The first-quadrant results are clamped to [0, 1.0] (the true values
 *     lie there, so the clamp can only reduce the error), the quadrant
 *     symmetry applied, and the input sign applied to the sine by negating
 *     a value of magnitude <= 2^30 (never overflows).
 * Every shift is of an unsigned value; no signed overflow is possible.
 */
#include "dhmath/dh_trig.h"
#include "dh_trig_tables.h"

#define DH_TRIG_KT    2398762259u   /* round(pi/180 * 2^37) */
#define DH_TRIG_INV3  1431655765u   /* round(2^32 / 3) */
#define DH_TRIG_INV6  715827883u    /* round(2^32 / 6) */
#define DH_TRIG_Q30   0x40000000u

static void dh_trig_core_q(dh_q16 x, dh_q30 *s_out, dh_q30 *c_out)
{
    uint32_t u, n, k, m, fr, sv, cv, t, h, h3, t3, h2, t4, sf, cm;
    uint64_t pa, pb, pc;
    int32_t ss, cc, sq, cq;

    /* (uint32_t)x is defined (modulo 2^32); 0u - that is the magnitude */
    u = (x < 0) ? (0u - (uint32_t)x) : (uint32_t)x;
    n = dh_trig_mod360(u >> 16);
    fr = u & 0xFFFFu;

    k = (uint32_t)(n >= 90u) + (uint32_t)(n >= 180u) + (uint32_t)(n >= 270u);
    m = n - 90u * k;
    sv = (uint32_t)dh_trig_sin_q30[m];          /* sin m, 0..2^30 */
    cv = (uint32_t)dh_trig_sin_q30[90u - m];    /* cos m, 0..2^30 */

    /* f in radians, units 2^-37: T <= 65535 * KT / 2^16 < 2^31.2 */
    t  = (uint32_t)(((uint64_t)fr * DH_TRIG_KT + 0x8000u) >> 16);
    h  = (uint32_t)(((uint64_t)t * t + ((uint64_t)1 << 37)) >> 38);      /* t^2/2  */
    h3 = (uint32_t)(((uint64_t)h * DH_TRIG_INV3 + 0x80000000u) >> 32);   /* t^2/6  */
    t3 = (uint32_t)(((uint64_t)t * h3 + ((uint64_t)1 << 36)) >> 37);     /* t^3/6  */
    h2 = (uint32_t)(((uint64_t)h * h + ((uint64_t)1 << 36)) >> 37);      /* t^4/4  */
    t4 = (uint32_t)(((uint64_t)h2 * DH_TRIG_INV6 + 0x80000000u) >> 32);  /* t^4/24 */
    sf = t - t3;                                /* sin f       (>= 0) */
    cm = h - t4;                                /* 1 - cos f   (>= 0) */

    /* sin(m+f) = S + (C sin f - S (1 - cos f)); units 2^-67, < 2^62 */
    pa = (uint64_t)cv * sf;
    pb = (uint64_t)sv * cm;
    if (pa >= pb) {
        uint32_t d = (uint32_t)((pa - pb + ((uint64_t)1 << 36)) >> 37);
        sv = (sv + d > DH_TRIG_Q30) ? DH_TRIG_Q30 : sv + d;
    } else {
        uint32_t d = (uint32_t)((pb - pa + ((uint64_t)1 << 36)) >> 37);
        sv = (d > sv) ? 0u : sv - d;
    }
    /* cos(m+f) = C - (C (1 - cos f) + S sin f) */
    pc = (uint64_t)cv * cm + (uint64_t)dh_trig_sin_q30[m] * sf;
    {
        uint32_t d = (uint32_t)((pc + ((uint64_t)1 << 36)) >> 37);
        cv = (d > cv) ? 0u : cv - d;
    }

    sq = (int32_t)sv;                           /* both in 0..2^30 */
    cq = (int32_t)cv;
    ss = (k & 1u) ? cq : sq;
    cc = (k & 1u) ? sq : cq;
    if (k >= 2u) {
        ss = -ss;
    }
    if (k == 1u || k == 2u) {
        cc = -cc;
    }
    if (x < 0) {
        ss = -ss;
    }
    *s_out = ss;
    *c_out = cc;
}

void dh_sincos_q(dh_q16 deg_q16, dh_q30 *s_q30, dh_q30 *c_q30)
{
    DH_ASSERT(s_q30 != NULL);
    DH_ASSERT(c_q30 != NULL);
    dh_trig_core_q(deg_q16, s_q30, c_q30);
}

dh_q30 dh_sin_q(dh_q16 deg_q16)
{
    dh_q30 s, c;
    dh_trig_core_q(deg_q16, &s, &c);
    return s;
}

dh_q30 dh_cos_q(dh_q16 deg_q16)
{
    dh_q30 s, c;
    dh_trig_core_q(deg_q16, &s, &c);
    return c;
}
