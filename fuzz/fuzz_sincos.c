/* SPDX-License-Identifier: Apache-2.0 */
/*
 * fuzz_sincos.c - dh_sincos_f32 / dh_sincos_q on arbitrary angles.
 *
 * Invariants (contracts in include/dhmath/trig.h):
 *  float: NaN/Inf -> DH_ERR_NAN with both outputs NaN; otherwise DH_OK,
 *         |s|, |c| <= 1, within the proven bound 6.2e-8 of double sin/cos
 *         of the exactly reduced angle (fmod is exact in double),
 *         dh_sin_f32/dh_cos_f32 bit-identical to dh_sincos_f32, and
 *         sin(-x) == -sin(x), cos(-x) == cos(x) bit for bit.
 *  fixed: every int32 valid, |s|, |c| <= 2^30, within 1.05 LSB of the
 *         double reference, dh_sin_q/dh_cos_q bit-identical, odd/even
 *         symmetry exact (x != INT32_MIN).
 * Input: three 4-byte words (a raw float, an int32 scaled by 2^-k so that
 * moderate angles with fractions are common, a Q16.16 angle) and k.
 */
#include <math.h>

#include "dhmath/trig.h"
#include "fuzz_common.h"

#define FZ_F32_BOUND 6.2e-8
#define FZ_Q30_BOUND 1.05

static const double k_deg2rad = 3.14159265358979323846 / 180.0;

static void check_f32(float deg)
{
    float s = 0.5f, c = 0.5f;
    dh_status st = dh_sincos_f32(deg, &s, &c);
    if (!isfinite(deg)) {
        FZ_CHECK(st == DH_ERR_NAN, "deg bits 0x%08x st %d", (unsigned)fz_f32_to_bits(deg), (int)st);
        FZ_CHECK(isnan(s) && isnan(c), "deg bits 0x%08x s %g c %g", (unsigned)fz_f32_to_bits(deg),
                 (double)s, (double)c);
        FZ_CHECK(isnan(dh_sin_f32(deg)) && isnan(dh_cos_f32(deg)), "deg bits 0x%08x",
                 (unsigned)fz_f32_to_bits(deg));
        return;
    }
    FZ_CHECK(st == DH_OK, "deg %.9g st %d", (double)deg, (int)st);
    FZ_CHECK(fabsf(s) <= 1.0f && fabsf(c) <= 1.0f, "deg %.9g s %.9g c %.9g", (double)deg,
             (double)s, (double)c);
    {
        /* fmod of a double holding a float is exact, so r is the exactly
         * reduced angle; the error of sin(r * pi/180) in double is ~1e-16. */
        const double r = fmod((double)deg, 360.0) * k_deg2rad;
        const double es = fabs((double)s - sin(r)), ec = fabs((double)c - cos(r));
        FZ_CHECK(es <= FZ_F32_BOUND && ec <= FZ_F32_BOUND,
                 "deg %.9g (bits 0x%08x): sin err %.3g cos err %.3g (bound %.3g)", (double)deg,
                 (unsigned)fz_f32_to_bits(deg), es, ec, FZ_F32_BOUND);
    }
    FZ_CHECK(fz_f32_to_bits(dh_sin_f32(deg)) == fz_f32_to_bits(s) &&
                 fz_f32_to_bits(dh_cos_f32(deg)) == fz_f32_to_bits(c),
             "deg %.9g: dh_sin_f32/dh_cos_f32 differ from dh_sincos_f32", (double)deg);
    {
        float s2 = 0.0f, c2 = 0.0f;
        FZ_CHECK(dh_sincos_f32(-deg, &s2, &c2) == DH_OK, "deg %.9g", (double)-deg);
        FZ_CHECK(fz_f32_to_bits(s2) == fz_f32_to_bits(-s) && fz_f32_to_bits(c2) == fz_f32_to_bits(c),
                 "deg %.9g: sin(-x) %a vs -sin(x) %a, cos(-x) %a vs cos(x) %a", (double)deg,
                 (double)s2, (double)-s, (double)c2, (double)c);
    }
}

static void check_q(int32_t x)
{
    dh_q30 s = 12345, c = 12345;
    dh_sincos_q(x, &s, &c);
    FZ_CHECK(s >= -DH_Q30_ONE && s <= DH_Q30_ONE && c >= -DH_Q30_ONE && c <= DH_Q30_ONE,
             "x %ld s %ld c %ld", (long)x, (long)s, (long)c);
    {
        const double r = fmod((double)x / 65536.0, 360.0) * k_deg2rad;
        const double es = fabs((double)s - sin(r) * 1073741824.0);
        const double ec = fabs((double)c - cos(r) * 1073741824.0);
        FZ_CHECK(es <= FZ_Q30_BOUND && ec <= FZ_Q30_BOUND,
                 "x %ld (%.9f deg): sin err %.4f LSB cos err %.4f LSB (bound %.2f)", (long)x,
                 (double)x / 65536.0, es, ec, FZ_Q30_BOUND);
    }
    FZ_CHECK(dh_sin_q(x) == s && dh_cos_q(x) == c, "x %ld: dh_sin_q/dh_cos_q differ", (long)x);
    if (x != INT32_MIN) {
        dh_q30 s2 = 0, c2 = 0;
        dh_sincos_q(-x, &s2, &c2);
        FZ_CHECK(s2 == -s && c2 == c, "x %ld: sin(-x) %ld vs %ld, cos(-x) %ld vs %ld", (long)x,
                 (long)s2, (long)-s, (long)c2, (long)c);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in;
    float raw, scaled;
    int32_t q, iv;
    unsigned k;

    in.p = data;
    in.n = size;
    raw = fz_f32_bits(&in);
    iv = fz_i32(&in);
    q = fz_i32(&in);
    k = fz_u8(&in) & 31u;
    /* (float)iv rounds (fine: it is the input); the power of two is exact */
    scaled = ldexpf((float)iv, -(int)k);

    check_f32(raw);
    check_f32(scaled);
    check_q(q);
    return 0;
}
