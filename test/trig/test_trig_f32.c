/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_trig_f32.c - dh_sincos_f32 / dh_sin_f32 / dh_cos_f32 against an
 * independent double-precision reference.
 *
 * Reference: the float input is converted to double exactly, reduced with
 * fmod(x, 360.0) (exact in IEEE arithmetic) and then into the first quadrant
 * by subtracting multiples of 90 (exact: the value has at most 24
 * significant bits and is below 360), and only then converted to radians and
 * passed to libm sin/cos in double. So the reference error is ~1e-16 for
 * every input, however large.
 *
 * Error bound asserted (DHT_F32_TOL): proven 6.2e-8 = half an ulp of the table
 * entry (2^-25) + half an ulp of the result (2^-25) + < 2.5e-9 for the
 * correction term; measured 6.03e-8 over every float in [1, 360). The
 * project requirement is 1.2e-7.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_ref.h"
#include "dhmath/trig.h"

#define DHT_F32_TOL 6.2e-8

static void ref_f32(float x, double *s, double *c)
{
    double d = (double)x;
    dhr_sincos_deg(d, s, c);
}

typedef struct {
    double max_s, max_c;
    float at_s, at_c;
    unsigned long n;
} err_acc;

/* checks one input, accumulates its error, fails above tol (twin: check_one of test_trig_q.c) */
static void check_one(float x, err_acc *acc)
{
    float s, c;
    double rs, rc, es, ec;
    DHT_EQ_INT(dh_sincos_f32(x, &s, &c), DH_OK);
    ref_f32(x, &rs, &rc);
    es = fabs((double)s - rs);
    ec = fabs((double)c - rc);
    if (es > acc->max_s) { acc->max_s = es; acc->at_s = x; }
    if (ec > acc->max_c) { acc->max_c = ec; acc->at_c = x; }
    acc->n++;
    DHT_TRUE_MSG(es <= DHT_F32_TOL, "sin(%.9g): %.9g vs %.17g (err %.3g)", (double)x, (double)s, rs, es);
    DHT_TRUE_MSG(ec <= DHT_F32_TOL, "cos(%.9g): %.9g vs %.17g (err %.3g)", (double)x, (double)c, rc, ec);
    DHT_TRUE_MSG(fabsf(s) <= 1.0f && fabsf(c) <= 1.0f, "|sin|,|cos| > 1 at %.9g", (double)x);
}

static void report(const char *what, const err_acc *acc)
{
    dht_printf("trig_f32 %s: %lu inputs, max |err| sin %.3g (at %.9g), cos %.3g (at %.9g)\n",
               what, acc->n, acc->max_s, (double)acc->at_s, acc->max_c, (double)acc->at_c);
}

/* every 0.001 degree over +-720 degrees */
static void dense_sweep_0001_deg(void)
{
    err_acc acc = { 0, 0, 0, 0, 0 };
    long k, step = 1440000L / DHT_ITER(1440000L);
    for (k = -720000L; k <= 720000L; k += step) {
        check_one((float)((double)k * 0.001), &acc);
    }
    report("sweep 0.001 deg over +-720", &acc);
}

/* Every float in [1, 360) (exhaustive on the host): together with the exact
 * reduction this covers every (whole degree mod 360, fraction) pair that any
 * float >= 1 can produce, so the bound holds for every float of any size. */
static void every_float_in_first_turn(void)
{
    err_acc acc = { 0, 0, 0, 0, 0 };
    const uint32_t lo = 0x3F800000u;  /* 1.0f */
    const uint32_t hi = 0x43B40000u;  /* 360.0f */
    uint32_t b, step = (hi - lo) / DHT_ITER(hi - lo);
    for (b = lo; b < hi; b += step) {
        check_one(dht_f32_from_bits(b), &acc);
    }
    report("every float in [1,360)", &acc);
}

/* Floats below 1 (n = 0, every fraction): a bit-pattern stride of 61 over
 * [2^-40, 1) plus the smallest values. */
static void small_angles(void)
{
    err_acc acc = { 0, 0, 0, 0, 0 };
    uint32_t b;
    const uint32_t lo = 0x2B800000u, hi = 0x3F800000u;
    uint32_t step = 61u * ((hi - lo) / 61u / DHT_ITER((hi - lo) / 61u));
    for (b = lo; b < hi; b += step) {
        check_one(dht_f32_from_bits(b), &acc);
    }
    check_one(0.0f, &acc);
    check_one(FLT_MIN, &acc);
    check_one(dht_f32_from_bits(1u), &acc); /* smallest denormal */
    check_one(nextafterf(1.0f, 0.0f), &acc);
    report("floats in [2^-40,1)", &acc);
}

/* Uniform random |deg| <= 1e6: no growth of the error with the angle. */
static void random_up_to_1e6(void)
{
    err_acc acc = { 0, 0, 0, 0, 0 };
    long i, n = DHT_ITER(2000000L);
    for (i = 0; i < n; i++) {
        check_one((float)dht_rand_uniform(-1e6, 1e6), &acc);
    }
    /* the CMSIS-DSP trouble spots: +-180 and +-3600 and just around them */
    check_one(180.0f, &acc);
    check_one(-180.0f, &acc);
    check_one(3600.0f, &acc);
    check_one(-3600.0f, &acc);
    check_one(nextafterf(3600.0f, 0.0f), &acc);
    check_one(nextafterf(-3600.0f, 0.0f), &acc);
    check_one(nextafterf(180.0f, 0.0f), &acc);
    check_one(nextafterf(1e6f, 0.0f), &acc);
    check_one(1e6f, &acc);
    check_one(-1e6f, &acc);
    report("random |deg| <= 1e6", &acc);
}

/* The top of the fast path: every float in [2^22, 2^23) (fractions 0 and
 * 0.5 only, so the rounding to the nearest whole degree meets a tie at
 * every other input and rounds it to even), where a + 2^23 reaches 2^24
 * and its exponent steps up, and the first floats of the large path. */
static void fast_path_top(void)
{
    err_acc acc = { 0, 0, 0, 0, 0 };
    const uint32_t lo = 0x4A800000u;  /* 2^22 */
    const uint32_t hi = 0x4B000000u;  /* 2^23 */
    uint32_t b, step = (hi - lo) / DHT_ITER(hi - lo);
    for (b = lo; b < hi; b += step) {
        check_one(dht_f32_from_bits(b), &acc);
        check_one(-dht_f32_from_bits(b), &acc);
    }
    for (b = hi - 16u; b < hi + 16u; b++) {
        check_one(dht_f32_from_bits(b), &acc);
        check_one(-dht_f32_from_bits(b), &acc);
    }
    report("every float in [2^22,2^23)", &acc);
}

/* Random bit patterns of every finite magnitude up to FLT_MAX, and the
 * boundary of the integer-only range (2^23, 2^24). Above 2^23 every float is
 * an integer, so the result must also be bit-identical to that of the whole
 * degree fmod(x, 360). */
static void huge_angles(void)
{
    err_acc acc = { 0, 0, 0, 0, 0 };
    static const float fixed[] = {
        8388607.5f, 8388608.0f, 8388609.0f, 16777215.0f, 16777216.0f, 16777218.0f,
        1e7f, 1e8f, 1e9f, 1e10f, 1e20f, 1e30f, 3e38f, FLT_MAX, -FLT_MAX, -1e30f
    };
    long i, n = DHT_ITER(1000000L);
    for (i = 0; i < (long)(sizeof fixed / sizeof fixed[0]); i++) {
        check_one(fixed[i], &acc);
    }
    for (i = 0; i < n; i++) {
        /* exponent field 1..254, random mantissa and sign */
        uint32_t r = dht_rand_u32();
        uint32_t e = 1u + dht_rand_u32() % 254u;
        float x = dht_f32_from_bits((r & 0x807FFFFFu) | (e << 23));
        check_one(x, &acc);
        if (fabsf(x) >= 8388608.0f) {
            float s1, c1, s2, c2;
            float w = (float)fmod(fabs((double)x), 360.0);
            DHT_EQ_INT(dh_sincos_f32(x, &s1, &c1), DH_OK);
            DHT_EQ_INT(dh_sincos_f32(w, &s2, &c2), DH_OK);
            if (x < 0) s2 = -s2;
            DHT_EQ_F32_BITS(s1, s2);
            DHT_EQ_F32_BITS(c1, c2);
        }
    }
    report("random finite floats up to FLT_MAX", &acc);
}

/* Every exponent of the integer-only range (2^23 .. FLT_MAX: the exact
 * reduction mod 360 works on 24 + e bits, e = 0..104, a loop of up to 128
 * steps in the DH_SMALL build, tables and multiply-shifts in the default
 * one), with mantissas that set the lowest, the highest, every other and
 * every bit: bit-identical to the whole degree fmod(|x|, 360), the odd
 * symmetry applied for a negative x. */
static void huge_angles_every_exponent(void)
{
    err_acc acc = { 0, 0, 0, 0, 0 };
    static const uint32_t mant[] = { 0x000000u, 0x000001u, 0x400000u, 0x2AAAAAu, 0x555555u, 0x7FFFFFu };
    uint32_t e, k, sgn;
    for (e = 150u; e <= 254u; e++) {
        for (k = 0; k < sizeof mant / sizeof mant[0]; k++) {
            for (sgn = 0; sgn < 2u; sgn++) {
                float x = dht_f32_from_bits((sgn << 31) | (e << 23) | mant[k]);
                float w = (float)fmod(fabs((double)x), 360.0);
                float s1, c1, s2, c2;
                check_one(x, &acc); /* against the double reference */
                DHT_EQ_INT(dh_sincos_f32(x, &s1, &c1), DH_OK);
                DHT_EQ_INT(dh_sincos_f32(w, &s2, &c2), DH_OK);
                if (sgn) s2 = -s2;
                DHT_EQ_F32_BITS(s1, s2);
                DHT_EQ_F32_BITS(c1, c2);
                DHT_EQ_F32_BITS(dh_sin_f32(x), s2);
                DHT_EQ_F32_BITS(dh_cos_f32(x), c2);
            }
        }
    }
    report("every exponent of the integer-only range", &acc);
}

/* Every whole degree in [-1080, 1080]: the double value rounded to float
 * (the generator verified that for all 91 table entries this equals the
 * correctly rounded value); multiples of 90 exactly 0 and +-1. */
static void whole_degrees(void)
{
    int n;
    for (n = -1080; n <= 1080; n++) {
        float s, c;
        double rs, rc;
        DHT_EQ_INT(dh_sincos_f32((float)n, &s, &c), DH_OK);
        ref_f32((float)n, &rs, &rc);
        DHT_TRUE_MSG(s == (float)rs, "sin(%d) = %.9g, want %.9g", n, (double)s, (double)(float)rs);
        DHT_TRUE_MSG(c == (float)rc, "cos(%d) = %.9g, want %.9g", n, (double)c, (double)(float)rc);
        if (n % 90 == 0) {
            int q = ((n % 360) + 360) % 360 / 90;
            static const float sv[4] = { 0.0f, 1.0f, 0.0f, -1.0f };
            static const float cv[4] = { 1.0f, 0.0f, -1.0f, 0.0f };
            DHT_TRUE(s == sv[q]);
            DHT_TRUE(c == cv[q]);
            if (n >= 0) {
                /* exact zeros of non-negative angles are +0 */
                if (sv[q] == 0.0f) DHT_EQ_INT(dht_f32_bits(s), 0);
                if (cv[q] == 0.0f) DHT_EQ_INT(dht_f32_bits(c), 0);
            }
        }
    }
}

/* The whole degrees whose table entry, sin 1 or sin 19, lies exactly
 * halfway between two floats in its Q2.30 rounding (0x011DF0B3 and
 * 0x14D61BD0, the only two of the 91): the DH_SMALL build takes the float
 * table from the Q2.30 one and breaks these ties towards the correctly
 * rounded sine, so they are pinned here with their bits (not through libm):
 * sin 1 = 0x1.1df0b2p-6, sin 19 = 0x1.4d61bep-2, in every quadrant and for
 * both signs, through the sine and through the cosine. */
static void table_tie_entries(void)
{
    static const float t[2] = { 0x1.1df0b2p-6f, 0x1.4d61bep-2f };
    static const int deg[2] = { 1, 19 };
    int e, k;
    for (e = 0; e < 2; e++) {
        for (k = -4; k < 4; k++) {
            /* x = 180 k + n and 180 k + 180 - n: sin = (-1)^k T;
             * x = 90 + 180 k - n and 90 + 180 k + n: cos = -+(-1)^k T */
            const float sg = (k & 1) ? -1.0f : 1.0f;
            const int n = deg[e];
            float s, c;
            DHT_EQ_INT(dh_sincos_f32((float)(180 * k + n), &s, &c), DH_OK);
            DHT_EQ_F32_BITS(s, sg * t[e]);
            DHT_EQ_INT(dh_sincos_f32((float)(180 * k + 180 - n), &s, &c), DH_OK);
            DHT_EQ_F32_BITS(s, sg * t[e]);
            DHT_EQ_INT(dh_sincos_f32((float)(90 + 180 * k - n), &s, &c), DH_OK);
            DHT_EQ_F32_BITS(c, sg * t[e]);
            DHT_EQ_INT(dh_sincos_f32((float)(90 + 180 * k + n), &s, &c), DH_OK);
            DHT_EQ_F32_BITS(c, -sg * t[e]);
            DHT_EQ_F32_BITS(dh_sin_f32((float)(-n - 360 * k)), -t[e]);
            DHT_EQ_F32_BITS(dh_cos_f32((float)(90 - n + 360 * k)), t[e]);
        }
    }
}

/* sin(-x) == -sin(x) and cos(-x) == cos(x) bit for bit; single-output
 * variants agree with dh_sincos_f32. */
static void symmetry_and_variants(void)
{
    long i, n = DHT_ITER(1000000L);
    for (i = 0; i < n; i++) {
        float x, s1, c1, s2, c2;
        switch (i & 3) {
        case 0: x = (float)dht_rand_uniform(0, 720); break;
        case 1: x = (float)dht_rand_uniform(0, 1e6); break;
        case 2: x = (float)(dht_rand_u32() % 1440u) * 0.25f; break;  /* quadrant edges */
        default: x = dht_f32_from_bits(dht_rand_u32() & 0x7F7FFFFFu); break;
        }
        DHT_EQ_INT(dh_sincos_f32(x, &s1, &c1), DH_OK);
        DHT_EQ_INT(dh_sincos_f32(-x, &s2, &c2), DH_OK);
        DHT_EQ_F32_BITS(s2, -s1);
        DHT_EQ_F32_BITS(c2, c1);
        DHT_EQ_F32_BITS(dh_sin_f32(x), s1);
        DHT_EQ_F32_BITS(dh_cos_f32(x), c1);
        DHT_EQ_F32_BITS(dh_sin_f32(-x), s2);
    }
    {
        float s, c;
        DHT_EQ_INT(dh_sincos_f32(-0.0f, &s, &c), DH_OK);
        DHT_EQ_INT(dht_f32_bits(s), 0x80000000u);
        DHT_TRUE(c == 1.0f);
    }
}

/* Bound |s|,|c| <= 1 just below every quadrant edge and multiple of 90
 * within two turns, where rounding could push a value past 1. */
static void bounded_near_edges(void)
{
    int q;
    for (q = -8; q <= 8; q++) {
        float e = (float)(q * 90);
        float x = e;
        int j;
        for (j = 0; j < 64; j++) {
            float s, c;
            x = nextafterf(x, -1e9f);
            DHT_EQ_INT(dh_sincos_f32(x, &s, &c), DH_OK);
            DHT_TRUE(fabsf(s) <= 1.0f && fabsf(c) <= 1.0f);
        }
        x = e;
        for (j = 0; j < 64; j++) {
            float s, c;
            x = nextafterf(x, 1e9f);
            DHT_EQ_INT(dh_sincos_f32(x, &s, &c), DH_OK);
            DHT_TRUE(fabsf(s) <= 1.0f && fabsf(c) <= 1.0f);
        }
    }
}

/* NaN and infinities: DH_ERR_NAN, both outputs NaN; the single-output
 * variants return NaN. */
static void nan_and_inf(void)
{
    const float bad[] = { dht_f32_from_bits(0x7FC00000u), dht_f32_from_bits(0xFFC00000u), dht_f32_from_bits(0x7F800001u),
                          dht_f32_from_bits(0x7FFFFFFFu), dht_f32_from_bits(0x7F800000u), dht_f32_from_bits(0xFF800000u) };
    size_t i;
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        float s = 0.5f, c = 0.5f;
        DHT_EQ_INT(dh_sincos_f32(bad[i], &s, &c), DH_ERR_NAN);
        DHT_TRUE(s != s);
        DHT_TRUE(c != c);
        s = dh_sin_f32(bad[i]);
        c = dh_cos_f32(bad[i]);
        DHT_TRUE(s != s);
        DHT_TRUE(c != c);
    }
}

static const dht_case cases[] = {
    DHT_CASE(whole_degrees),
    DHT_CASE(table_tie_entries),
    DHT_CASE(dense_sweep_0001_deg),
    DHT_CASE(every_float_in_first_turn),
    DHT_CASE(small_angles),
    DHT_CASE(random_up_to_1e6),
    DHT_CASE(fast_path_top),
    DHT_CASE(huge_angles),
    DHT_CASE(huge_angles_every_exponent),
    DHT_CASE(symmetry_and_variants),
    DHT_CASE(bounded_near_edges),
    DHT_CASE(nan_and_inf),
};
DHT_MAIN(cases)
