/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_itrig_f32.c - dh_atan2_f32, dh_asin_f32, dh_acos_f32
 * against a correctly rounded reference: libm atan2l / asinl / acosl of the
 * float inputs (exact in long double) times 180/pi in long double, rounded
 * once to float (on targets where long double is double the reference has
 * ~2^-52 relative error, far below the float ulp).
 *
 * Asserted: the contract, |result - CR| <= 1 ulp, measured as the distance
 * of the bit patterns (the ulp of the result's binade; across zero the sum
 * of both magnitudes); the range (-180, 180]; exact multiples of 45 and
 * the signed-zero rules; statuses with *deg untouched (canary). Printed:
 * the largest error against the unrounded reference in ulp and how many
 * results differ from CR. Host: > 2 * 10^7 atan2 inputs, > 3 * 10^7
 * asin/acos inputs; DHT_ITER scales them on targets.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "dht.h"
#include "dhmath/trig.h"

#define R_LD 57.295779513082320876798154814105170332L

/* distance in ulp between two floats (finite, not NaN) */
static uint32_t ulp_dist(float a, float b)
{
    uint32_t ua = dht_f32_bits(a), ub = dht_f32_bits(b);
    if ((ua ^ ub) & 0x80000000u) return (ua & 0x7FFFFFFFu) + (ub & 0x7FFFFFFFu);
    return ua > ub ? ua - ub : ub - ua;
}

/* |f - ref| in ulp of the binade of ref (2^-149 below FLT_MIN) */
static double ulp_err(float f, long double ref)
{
    long double a = fabsl(ref), u;
    int e;
    if (a < (long double)FLT_MIN) {
        u = ldexpl(1.0L, -149);
    } else {
        (void)frexpl(a, &e);
        u = ldexpl(1.0L, e - 24);
    }
    return (double)(fabsl((long double)f - ref) / u);
}

typedef struct {
    long n, not_cr;
    double max_err;
} stats;

static void check_one(stats *st, const char *what, float in1, float in2, float got, long double ref,
                      int is_atan2)
{
    float cr = (float)ref;
    double e;
    if (is_atan2 && in1 == 0.0f && in2 < 0.0f) {
        cr = 180.0f; /* documented: y = +-0, x < 0 gives +180 (either sign of zero) */
        e = ulp_err(got, 180.0L);
        if (e > st->max_err) st->max_err = e;
    } else if (is_atan2 && dht_f32_bits(cr) == 0xC3340000u) {
        cr = dht_f32_from_bits(0xC333FFFFu); /* the documented value above -180 */
    } else {
        e = ulp_err(got, ref);
        if (e > st->max_err) st->max_err = e;
    }
    DHT_TRUE_MSG(ulp_dist(got, cr) <= 1u, "%s(%a, %a) = %a, correctly rounded %a (exact %.21Lg)", what,
                 (double)in1, (double)in2, (double)got, (double)cr, ref);
    if (dht_f32_bits(got) != dht_f32_bits(cr)) st->not_cr++;
    st->n++;
}

static void check_atan2(stats *st, float y, float x)
{
    float d = -1234.0f;
    long double ref;
    DHT_EQ_INT(dh_atan2_f32(y, x, &d), DH_OK);
    DHT_TRUE_MSG(d > -180.0f && d <= 180.0f, "atan2(%a, %a) = %a outside (-180, 180]", (double)y,
                 (double)x, (double)d);
    ref = atan2l((long double)y, (long double)x) * R_LD;
    check_one(st, "atan2", y, x, d, ref, 1);
}

static void check_asin_acos(stats *sa, stats *sc, float s)
{
    float d = -1234.0f;
    DHT_EQ_INT(dh_asin_f32(s, &d), DH_OK);
    check_one(sa, "asin", s, 0.0f, d, asinl((long double)s) * R_LD, 0);
    DHT_EQ_INT(dh_acos_f32(s, &d), DH_OK);
    check_one(sc, "acos", s, 0.0f, d, acosl((long double)s) * R_LD, 0);
}

static void report(const char *what, const stats *st)
{
    dht_printf("%s: %ld inputs, max error %.4f ulp against the exact value (excluding -180), "
               "%ld not correctly rounded\n", what, st->n, st->max_err, st->not_cr);
}

/* a random finite float (any exponent, either sign) */
static float rand_finite(void)
{
    uint32_t u;
    do {
        u = dht_rand_u32();
    } while ((u & 0x7F800000u) == 0x7F800000u);
    return dht_f32_from_bits(u);
}

/* a random float with exponent in [emin, emax] */
static float rand_exp(int emin, int emax)
{
    double m = dht_rand_uniform(1.0, 2.0);
    int e = emin + (int)(dht_rand_u32() % (uint32_t)(emax - emin + 1));
    float f = (float)ldexp(m, e);
    return (dht_rand_u32() & 1u) ? -f : f;
}

static void atan2_exact_values(void)
{
    static const float mags[] = { 1.0f, 3.0f, 0.1f, 1e-45f, 1e-40f, FLT_MIN, FLT_MAX, 1e30f, 7.5e-20f };
    const float pz = 0.0f, nz = -0.0f;
    unsigned i;
    float d;
    for (i = 0; i < sizeof mags / sizeof mags[0]; i++) {
        float v = mags[i];
        DHT_EQ_INT(dh_atan2_f32(pz, v, &d), DH_OK);
        DHT_EQ_F32_BITS(d, pz);
        DHT_EQ_INT(dh_atan2_f32(nz, v, &d), DH_OK);
        DHT_EQ_F32_BITS(d, nz);
        DHT_EQ_INT(dh_atan2_f32(pz, -v, &d), DH_OK);
        DHT_EQ_F32_BITS(d, 180.0f);
        DHT_EQ_INT(dh_atan2_f32(nz, -v, &d), DH_OK);
        DHT_EQ_F32_BITS(d, 180.0f);             /* not -180: the range is (-180, 180] */
        DHT_EQ_INT(dh_atan2_f32(v, pz, &d), DH_OK);
        DHT_EQ_F32_BITS(d, 90.0f);
        DHT_EQ_INT(dh_atan2_f32(v, nz, &d), DH_OK);
        DHT_EQ_F32_BITS(d, 90.0f);
        DHT_EQ_INT(dh_atan2_f32(-v, pz, &d), DH_OK);
        DHT_EQ_F32_BITS(d, -90.0f);
        DHT_EQ_INT(dh_atan2_f32(-v, nz, &d), DH_OK);
        DHT_EQ_F32_BITS(d, -90.0f);
        DHT_EQ_INT(dh_atan2_f32(v, v, &d), DH_OK);
        DHT_EQ_F32_BITS(d, 45.0f);
        DHT_EQ_INT(dh_atan2_f32(-v, v, &d), DH_OK);
        DHT_EQ_F32_BITS(d, -45.0f);
        DHT_EQ_INT(dh_atan2_f32(v, -v, &d), DH_OK);
        DHT_EQ_F32_BITS(d, 135.0f);
        DHT_EQ_INT(dh_atan2_f32(-v, -v, &d), DH_OK);
        DHT_EQ_F32_BITS(d, -135.0f);
    }
    /* y < 0 next to the negative x axis: -180 rounded, the float above */
    DHT_EQ_INT(dh_atan2_f32(-1e-30f, -1.0f, &d), DH_OK);
    DHT_EQ_F32_BITS(d, dht_f32_from_bits(0xC333FFFFu));
    DHT_EQ_INT(dh_atan2_f32(-1e-45f, -FLT_MAX, &d), DH_OK);
    DHT_EQ_F32_BITS(d, dht_f32_from_bits(0xC333FFFFu));
    DHT_EQ_INT(dh_atan2_f32(1e-30f, -1.0f, &d), DH_OK);
    DHT_EQ_F32_BITS(d, 180.0f);
    /* extreme ratios: a subnormal angle, an angle that rounds to 0 */
    DHT_EQ_INT(dh_atan2_f32(1e-45f, 1.0f, &d), DH_OK);
    DHT_EQ_F32_BITS(d, (float)(atan2l((long double)1e-45f, 1.0L) * R_LD));
    DHT_EQ_INT(dh_atan2_f32(-1e-45f, FLT_MAX, &d), DH_OK);
    DHT_EQ_F32_BITS(d, -0.0f);
    DHT_EQ_INT(dh_atan2_f32(FLT_MAX, 1e-45f, &d), DH_OK);
    DHT_EQ_F32_BITS(d, 90.0f);
}

static void atan2_status(void)
{
    const float inf = dht_f32_from_bits(0x7F800000u), nan_ = dht_f32_from_bits(0x7FC00000u);
    const float bad[] = { inf, -inf, nan_, -nan_, dht_f32_from_bits(0x7F800001u) };
    unsigned i;
    float d = 12.5f;
    DHT_EQ_INT(dh_atan2_f32(0.0f, 0.0f, &d), DH_ERR_DOMAIN);
    DHT_EQ_INT(dh_atan2_f32(-0.0f, -0.0f, &d), DH_ERR_DOMAIN);
    DHT_EQ_INT(dh_atan2_f32(0.0f, -0.0f, &d), DH_ERR_DOMAIN);
    DHT_EQ_F32_BITS(d, 12.5f);
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        DHT_EQ_INT(dh_atan2_f32(bad[i], 1.0f, &d), DH_ERR_NAN);
        DHT_EQ_INT(dh_atan2_f32(1.0f, bad[i], &d), DH_ERR_NAN);
        DHT_EQ_INT(dh_atan2_f32(bad[i], bad[i], &d), DH_ERR_NAN);
        DHT_EQ_INT(dh_atan2_f32(0.0f, bad[i], &d), DH_ERR_NAN);
    }
    DHT_EQ_F32_BITS(d, 12.5f);
}

static void atan2_random(void)
{
    stats st = { 0, 0, 0.0 };
    long i, n = DHT_ITER(4000000L), negzero = 0;
    for (i = 0; i < n; i++) {
        float y, x, r;
        double a;
        switch (i % 8) {
        case 0: y = rand_finite(); x = rand_finite(); break;           /* any bit patterns */
        case 1: case 2:                                                /* uniform angle, any radius */
            a = dht_rand_uniform(-3.1416, 3.1416);
            r = rand_exp(-120, 120);
            x = (float)(fabs((double)r) * cos(a));
            y = (float)(fabs((double)r) * sin(a));
            break;
        case 3:                                                        /* near the diagonals */
            x = rand_finite();
            y = dht_f32_from_bits((dht_f32_bits(x) & 0x7FFFFFFFu) + (dht_rand_u32() % 4001u) - 2000u);
            if (dht_rand_u32() & 1u) y = -y;
            break;
        case 4:                                                        /* subnormal and tiny */
            x = dht_f32_from_bits(dht_rand_u32() & 0x80FFFFFFu);
            y = dht_f32_from_bits(dht_rand_u32() & 0x80FFFFFFu);
            break;
        case 5: y = rand_exp(90, 127); x = rand_exp(90, 127); break;   /* huge */
        case 6: y = rand_exp(-149, 127); x = rand_exp(-149, 127); break;
        default:                                                       /* 20..30 deg: the largest polynomial term */
            a = dht_rand_uniform(0.349, 0.524);
            x = (float)cos(a);
            y = (float)sin(a);
            break;
        }
        if (dht_f32_bits(x) == 0xFFFFFFFFu) continue;
        if (((dht_f32_bits(x) | dht_f32_bits(y)) & 0x7FFFFFFFu) == 0u) continue;
        if (((dht_f32_bits(x) & 0x7F800000u) == 0x7F800000u) || ((dht_f32_bits(y) & 0x7F800000u) == 0x7F800000u)) continue;
        if (dht_f32_bits(y) == 0x80000000u && x < 0.0f) negzero++;
        check_atan2(&st, y, x);
    }
    /* reach probe: how many inputs were atan2(-0, x < 0) */
    dht_reach_max("atan2_random.negzero_negx", (double)negzero);
    report("atan2 random", &st);
}

/* every 2^k-th float y over all exponents against fixed x, and the
 * reverse: a dense sweep of the ratio through every octant */
static void atan2_sweep(void)
{
    static const float xs[] = { 1.0f, -1.0f, 3.0e-39f, -7.0e33f };
    stats st = { 0, 0, 0.0 };
    uint32_t stride = (uint32_t)(1024L * dht_iter_div()) | 1u, u;   /* sparser on slow targets */
    unsigned k;
    for (k = 0; k < sizeof xs / sizeof xs[0]; k++) {
        for (u = 1u; u < 0x7F800000u - stride; u += stride) {
            float v = dht_f32_from_bits(u);
            check_atan2(&st, v, xs[k]);
            check_atan2(&st, -xs[k], v);
        }
    }
    report("atan2 sweep", &st);
}

static void atan2_symmetry(void)
{
    long i, n = DHT_ITER(200000L);
    for (i = 0; i < n; i++) {
        float y = rand_finite(), x = rand_finite(), a, b;
        if (((dht_f32_bits(x) | dht_f32_bits(y)) & 0x7FFFFFFFu) == 0u) continue;
        DHT_EQ_INT(dh_atan2_f32(y, x, &a), DH_OK);
        DHT_EQ_INT(dh_atan2_f32(-y, x, &b), DH_OK);
        if (fabsf(a) < 180.0f && dht_f32_bits(a) != 0xC333FFFFu && dht_f32_bits(b) != 0xC333FFFFu) {
            DHT_EQ_F32_BITS(b, -a);
        }
    }
}

static void asin_acos_exact_values(void)
{
    float d;
    DHT_EQ_INT(dh_asin_f32(0.0f, &d), DH_OK);
    DHT_EQ_F32_BITS(d, 0.0f);
    DHT_EQ_INT(dh_asin_f32(-0.0f, &d), DH_OK);
    DHT_EQ_F32_BITS(d, -0.0f);
    DHT_EQ_INT(dh_asin_f32(1.0f, &d), DH_OK);
    DHT_EQ_F32_BITS(d, 90.0f);
    DHT_EQ_INT(dh_asin_f32(-1.0f, &d), DH_OK);
    DHT_EQ_F32_BITS(d, -90.0f);
    DHT_EQ_INT(dh_acos_f32(1.0f, &d), DH_OK);
    DHT_EQ_F32_BITS(d, 0.0f);
    DHT_EQ_INT(dh_acos_f32(-1.0f, &d), DH_OK);
    DHT_EQ_F32_BITS(d, 180.0f);
    DHT_EQ_INT(dh_acos_f32(0.0f, &d), DH_OK);
    DHT_EQ_F32_BITS(d, 90.0f);
    DHT_EQ_INT(dh_acos_f32(-0.0f, &d), DH_OK);
    DHT_EQ_F32_BITS(d, 90.0f);
    DHT_EQ_INT(dh_asin_f32(0.5f, &d), DH_OK);     /* asin 1/2 = 30 exactly */
    DHT_EQ_F32_BITS(d, 30.0f);
    DHT_EQ_INT(dh_acos_f32(0.5f, &d), DH_OK);
    DHT_EQ_F32_BITS(d, 60.0f);
    DHT_EQ_INT(dh_acos_f32(-0.5f, &d), DH_OK);
    DHT_EQ_F32_BITS(d, 120.0f);
}

static void asin_acos_clamp_and_status(void)
{
    const float above1 = dht_f32_from_bits(0x3F800001u), tol = dht_f32_from_bits(0x3F800004u), out = dht_f32_from_bits(0x3F800005u);
    const float inf = dht_f32_from_bits(0x7F800000u), nan_ = dht_f32_from_bits(0x7FC00000u);
    float d = 12.5f;
    /* 1.0000001 (a rotation matrix entry one ulp above 1): clamped */
    DHT_EQ_INT(dh_asin_f32(above1, &d), DH_OK);
    DHT_EQ_F32_BITS(d, 90.0f);
    DHT_EQ_INT(dh_asin_f32(-tol, &d), DH_OK);
    DHT_EQ_F32_BITS(d, -90.0f);
    DHT_EQ_INT(dh_acos_f32(tol, &d), DH_OK);
    DHT_EQ_F32_BITS(d, 0.0f);
    DHT_EQ_INT(dh_acos_f32(-above1, &d), DH_OK);
    DHT_EQ_F32_BITS(d, 180.0f);
    d = 12.5f;
    DHT_EQ_INT(dh_asin_f32(out, &d), DH_ERR_DOMAIN);
    DHT_EQ_INT(dh_asin_f32(-out, &d), DH_ERR_DOMAIN);
    DHT_EQ_INT(dh_acos_f32(out, &d), DH_ERR_DOMAIN);
    DHT_EQ_INT(dh_acos_f32(-2.0f, &d), DH_ERR_DOMAIN);
    DHT_EQ_INT(dh_asin_f32(FLT_MAX, &d), DH_ERR_DOMAIN);
    DHT_EQ_INT(dh_asin_f32(inf, &d), DH_ERR_NAN);
    DHT_EQ_INT(dh_acos_f32(-inf, &d), DH_ERR_NAN);
    DHT_EQ_INT(dh_asin_f32(nan_, &d), DH_ERR_NAN);
    DHT_EQ_INT(dh_acos_f32(-nan_, &d), DH_ERR_NAN);
    DHT_EQ_F32_BITS(d, 12.5f);
}

/* every 2^k-th float in [0, 1], both signs, plus the neighbourhood of 1,
 * 1/2 and random inputs */
static void asin_acos_sweep(void)
{
    stats sa = { 0, 0, 0.0 }, sc = { 0, 0, 0.0 };
    uint32_t stride = (uint32_t)(96L * dht_iter_div()) | 1u, u;
    long i, n = DHT_ITER(1000000L);
    for (u = 0u; u <= 0x3F800000u; u += stride) {
        check_asin_acos(&sa, &sc, dht_f32_from_bits(u));
        check_asin_acos(&sa, &sc, dht_f32_from_bits(u | 0x80000000u));
    }
    for (u = 0u; u < (uint32_t)DHT_ITER(2000000L); u++) {
        check_asin_acos(&sa, &sc, dht_f32_from_bits(0x3F800000u - u));   /* just below 1 */
    }
    for (i = 0; i < n; i++) {
        float s = (float)dht_rand_uniform(-1.0, 1.0);
        check_asin_acos(&sa, &sc, s);
    }
    report("asin", &sa);
    report("acos", &sc);
}

/* twin: asin_odd of test_itrig_q.c */
static void asin_odd(void)
{
    long i, n = DHT_ITER(200000L);
    for (i = 0; i < n; i++) {
        float s = dht_f32_from_bits(dht_rand_u32() % 0x3F800001u), a, b;
        DHT_EQ_INT(dh_asin_f32(s, &a), DH_OK);
        DHT_EQ_INT(dh_asin_f32(-s, &b), DH_OK);
        DHT_EQ_F32_BITS(b, -a);
    }
}

static const dht_case cases[] = {
    DHT_CASE(atan2_exact_values),
    DHT_CASE(atan2_status),
    DHT_CASE(atan2_random),
    DHT_CASE(atan2_sweep),
    DHT_CASE(atan2_symmetry),
    DHT_CASE(asin_acos_exact_values),
    DHT_CASE(asin_acos_clamp_and_status),
    DHT_CASE(asin_acos_sweep),
    DHT_CASE(asin_odd),
};
DHT_MAIN(cases)
