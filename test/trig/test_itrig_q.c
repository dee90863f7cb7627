/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_itrig_q.c - dh_atan2_q, dh_asin_q, dh_acos_q (int32 / Q2.30 in,
 * Q16.16 degrees out) against double precision: atan2 / asin / acos of
 * the exactly converted inputs times 180/pi times 65536 (relative error
 * ~1e-16, i.e. < 1e-8 LSB at 180 degrees).
 *
 * Asserted: |result - exact| <= 1 LSB (the contract) for every input, the
 * exact values at multiples of 45, the range (-180, 180], invariance under
 * a common power-of-two scale, odd symmetry, and the DH_ERR_DOMAIN cases
 * with the output untouched. Printed: the largest error in LSB. Host:
 * > 10^7 atan2 pairs (random at every scale, near the diagonals and the
 * axes, small integers, every pair of the int32 edge values), 3.7 x 10^5
 * pairs at the method's table points (reciprocal seed bucket edges,
 * Taylor segment centres and edges, tiny ratios, ratios next to 1),
 * 2 x 10^7 pairs in dense sweeps, and > 10^7 asin/acos inputs (a
 * strided pass over [-2^30, 2^30], the neighbourhoods of 0, +-1/2 and
 * +-1).
 */
#include <math.h>
#include <stdint.h>

#include "dht.h"
#include "dhmath/trig.h"

#define PI_D 3.14159265358979323846
#define Q16_PER_DEG 65536.0
#define Q30 1073741824.0
#define TOL_LSB 1.0
#define DEG180 ((int32_t)180 << 16)

static double worst_atan2, worst_atan2_m180, worst_asin, worst_acos;
static long n_atan2;   /* pairs checked */

static void check_atan2(int32_t y, int32_t x)
{
    int32_t d = 0x5A5A5A5A;
    double ref, e;
    DHT_EQ_INT(dh_atan2_q(y, x, &d), DH_OK);
    DHT_TRUE_MSG(d > -DEG180 && d <= DEG180, "atan2_q(%ld, %ld) = %ld outside (-180, 180]", (long)y,
                 (long)x, (long)d);
    n_atan2++;
    ref = atan2((double)y, (double)x) * (180.0 / PI_D) * Q16_PER_DEG;
    e = fabs((double)d - ref);
    if (d == -DEG180 + 1) {
        if (e > worst_atan2_m180) worst_atan2_m180 = e;    /* the value kept inside the range */
    } else if (e > worst_atan2) {
        worst_atan2 = e;
    }
    DHT_TRUE_MSG(e <= TOL_LSB, "atan2_q(%ld, %ld) = %ld, exact %.6f (error %.4f LSB)", (long)y, (long)x,
                 (long)d, ref, e);
}

static void check_asin_acos(int32_t s)
{
    int32_t d = 0x5A5A5A5A;
    double v = (double)s / Q30, e, ref;
    if (v > 1.0) v = 1.0;
    if (v < -1.0) v = -1.0;
    DHT_EQ_INT(dh_asin_q(s, &d), DH_OK);
    ref = asin(v) * (180.0 / PI_D) * Q16_PER_DEG;
    e = fabs((double)d - ref);
    if (e > worst_asin) worst_asin = e;
    DHT_TRUE_MSG(e <= TOL_LSB, "asin_q(%ld) = %ld, exact %.6f", (long)s, (long)d, ref);
    DHT_EQ_INT(dh_acos_q(s, &d), DH_OK);
    ref = acos(v) * (180.0 / PI_D) * Q16_PER_DEG;
    e = fabs((double)d - ref);
    if (e > worst_acos) worst_acos = e;
    DHT_TRUE_MSG(e <= TOL_LSB, "acos_q(%ld) = %ld, exact %.6f", (long)s, (long)d, ref);
}

static const int32_t edges[] = {
    INT32_MIN, INT32_MIN + 1, INT32_MIN + 2, -0x40000001, -0x40000000, -0x3FFFFFFF, -65536, -3, -2, -1, 0,
    1, 2, 3, 65536, 0x3FFFFFFF, 0x40000000, 0x40000001, 0x7FFFFFFE, INT32_MAX, 46341, -46341, 12345678
};
#define N_EDGES (sizeof edges / sizeof edges[0])

static void atan2_exact_values(void)
{
    static const int32_t mags[] = { 1, 2, 3, 1000, 0x40000000, 0x7FFFFFFF, 123456789 };
    unsigned i;
    int32_t d;
    for (i = 0; i < sizeof mags / sizeof mags[0]; i++) {
        int32_t v = mags[i];
        DHT_EQ_INT(dh_atan2_q(0, v, &d), DH_OK);
        DHT_EQ_INT(d, 0);
        DHT_EQ_INT(dh_atan2_q(0, -v, &d), DH_OK);
        DHT_EQ_INT(d, DEG180);
        DHT_EQ_INT(dh_atan2_q(v, 0, &d), DH_OK);
        DHT_EQ_INT(d, 90 << 16);
        DHT_EQ_INT(dh_atan2_q(-v, 0, &d), DH_OK);
        DHT_EQ_INT(d, -(90 << 16));
        DHT_EQ_INT(dh_atan2_q(v, v, &d), DH_OK);
        DHT_EQ_INT(d, 45 << 16);
        DHT_EQ_INT(dh_atan2_q(-v, v, &d), DH_OK);
        DHT_EQ_INT(d, -(45 << 16));
        DHT_EQ_INT(dh_atan2_q(v, -v, &d), DH_OK);
        DHT_EQ_INT(d, 135 << 16);
        DHT_EQ_INT(dh_atan2_q(-v, -v, &d), DH_OK);
        DHT_EQ_INT(d, -(135 << 16));
    }
    /* INT32_MIN: |INT32_MIN| = 2^31 is handled exactly */
    DHT_EQ_INT(dh_atan2_q(INT32_MIN, INT32_MIN, &d), DH_OK);
    DHT_EQ_INT(d, -(135 << 16));
    DHT_EQ_INT(dh_atan2_q(0, INT32_MIN, &d), DH_OK);
    DHT_EQ_INT(d, DEG180);
    DHT_EQ_INT(dh_atan2_q(INT32_MIN, 0, &d), DH_OK);
    DHT_EQ_INT(d, -(90 << 16));
    /* y < 0 next to the negative x axis: -180 + 1 LSB */
    DHT_EQ_INT(dh_atan2_q(-1, INT32_MIN, &d), DH_OK);
    DHT_EQ_INT(d, -DEG180 + 1);
    DHT_EQ_INT(dh_atan2_q(1, INT32_MIN, &d), DH_OK);
    DHT_EQ_INT(d, DEG180);
}

static void atan2_domain(void)
{
    int32_t d = 0x5A5A5A5A;
    DHT_EQ_INT(dh_atan2_q(0, 0, &d), DH_ERR_DOMAIN);
    DHT_EQ_INT(d, 0x5A5A5A5A);
}

static void atan2_edge_pairs(void)
{
    unsigned i, j;
    for (i = 0; i < N_EDGES; i++) {
        for (j = 0; j < N_EDGES; j++) {
            if (edges[i] == 0 && edges[j] == 0) continue;
            check_atan2(edges[i], edges[j]);
        }
    }
}

/* a random int32 of random magnitude (1 .. 31 significant bits) */
static int32_t rand_scaled(void)
{
    uint32_t u = dht_rand_u32();
    return (int32_t)u >> (dht_rand_u32() % 32u);
}

static void atan2_random(void)
{
    long i, n = DHT_ITER(10000000L);
    worst_atan2 = worst_atan2_m180 = 0.0;
    for (i = 0; i < n; i++) {
        int32_t y, x;
        switch (i % 6) {
        case 0: y = (int32_t)dht_rand_u32(); x = (int32_t)dht_rand_u32(); break;
        case 1: y = rand_scaled(); x = rand_scaled(); break;
        case 2:                                        /* near the diagonals */
            /* |x| < 2^30: y = x +- 1000 and -y stay in range */
            x = ((int32_t)dht_rand_u32() / 2) >> (dht_rand_u32() % 8u);
            y = x + (int32_t)(dht_rand_u32() % 2001u) - 1000;
            if (dht_rand_u32() & 1u) y = -y;
            break;
        case 3:                                        /* near the axes */
            x = (int32_t)dht_rand_u32();
            y = (int32_t)(dht_rand_u32() % 4001u) - 2000;
            if (dht_rand_u32() & 1u) {
                int32_t t = x;
                x = y;
                y = t;
            }
            break;
        case 4: y = (int32_t)(dht_rand_u32() % 201u) - 100; x = (int32_t)(dht_rand_u32() % 201u) - 100; break;
        default: y = rand_scaled(); x = (int32_t)dht_rand_u32(); break;
        }
        if (x == 0 && y == 0) continue;
        check_atan2(y, x);
    }
    dht_printf("atan2_q: %ld random pairs, max error %.4f LSB (%.4f LSB at -180 + 1 LSB)\n", n,
               worst_atan2, worst_atan2_m180);
}

/* (+-ay, +-ax) and (+-ax, +-ay) for magnitudes <= 2^31 (2^31 only as
 * INT32_MIN), not both 0 */
static void check_mags(uint32_t ay, uint32_t ax)
{
    static const int sgn[2] = { 1, -1 };
    unsigned a, b;
    for (a = 0; a < 2u; a++) {
        for (b = 0; b < 2u; b++) {
            int64_t y = sgn[a] * (int64_t)ay, x = sgn[b] * (int64_t)ax;
            if (y > INT32_MAX || x > INT32_MAX) continue;
            check_atan2((int32_t)y, (int32_t)x);
            check_atan2((int32_t)x, (int32_t)y);
        }
    }
}

/* a uniform draw in [0, n] (n < 2^32) */
static uint32_t rand_upto(uint32_t n)
{
    uint64_t v = ((uint64_t)dht_rand_u32() << 32) | dht_rand_u32();
    return (uint32_t)(v % ((uint64_t)n + 1u));
}

/* The method's table points (src/trig/dh_itrig_q.c): the larger magnitude
 * normalised into [2^30, 2^31] picks its reciprocal seed by bits 23..30,
 * and the ratio r = min / max its Taylor segment by rounding to k / 64.
 * Asserted with the contract at and next to every seed bucket edge (at
 * several scales, with the smaller magnitude 0, 1, just below the larger
 * one and random), at and next to every segment centre k / 64 and every
 * segment edge (2k + 1) / 128 for random larger magnitudes, tiny ratios,
 * ratios next to 1 and larger magnitudes next to 2^n and 2^n - 1. */
static void atan2_table_points(void)
{
    static const unsigned scales[] = { 0, 1, 7, 8, 15, 16, 22, 23 };
    long i, n = DHT_ITER(2000L);
    uint32_t j, k, sc, t;
    worst_atan2 = 0.0;
    n_atan2 = 0;
    for (j = 0; j <= 128u; j++) {                 /* seed bucket edges */
        for (sc = 0; sc < sizeof scales / sizeof scales[0]; sc++) {
            for (t = 0; t < 3u; t++) {
                uint32_t x = (((128u + j) << 23) - 1u + t) >> scales[sc];
                if (x > 0x80000000u || x < 2u) continue;
                check_mags(0u, x);
                check_mags(1u, x);
                check_mags(x - 1u, x);
                check_mags(rand_upto(x), x);
                check_mags(rand_upto(x >> 9), x);
            }
        }
    }
    for (i = 0; i < n; i++) {                     /* segment centres and edges */
        uint32_t x = 0x40000000u + rand_upto(0x40000000u);
        int32_t dy;
        k = (uint32_t)(i % 64);
        for (dy = -2; dy <= 2; dy++) {
            uint64_t yc = ((uint64_t)x * k + 32u) >> 6;            /* r = k / 64 */
            uint64_t ye = ((uint64_t)x * (2u * k + 1u) + 64u) >> 7;  /* (2k + 1) / 128 */
            if ((int64_t)yc + dy >= 0) check_mags((uint32_t)((int64_t)yc + dy), x);
            if ((int64_t)ye + dy < (int64_t)x) check_mags((uint32_t)((int64_t)ye + dy), x);
        }
        x &= ~(uint32_t)63u;                      /* r = k / 64 exactly */
        check_mags((uint32_t)(((uint64_t)x * k) >> 6), x);
        check_mags((uint32_t)(((uint64_t)(x >> (i % 31)) * k) >> 6) | 1u, x >> (i % 31));
    }
    for (i = 0; i < n; i++) {                     /* tiny ratios, ratios next to 1 */
        uint32_t x = rand_upto(0x80000000u - 2000u) + 1000u;
        uint32_t d = rand_upto(999u) + 1u;
        check_mags(d, x);
        check_mags(x - d, x);
        check_mags(rand_upto(x >> 20), x);
    }
    for (k = 1; k <= 31u; k++) {                  /* larger magnitude next to 2^k */
        uint32_t x = (uint32_t)1 << k;
        for (i = 0; i < 8; i++) {
            check_mags(rand_upto(x - 1u), x - 1u);
            check_mags(rand_upto(x), x);
            if (k < 31u) check_mags(rand_upto(x + 1u), x + 1u);
        }
        check_mags(x - 1u, x);
        check_mags(x / 2u, x - 1u);
    }
    dht_printf("atan2_q: %ld pairs at the table points, max error %.4f LSB\n", n_atan2, worst_atan2);
}

/* Dense sweeps of the smaller magnitude over [0, x] for larger magnitudes
 * in different seed buckets and scales: consecutive values at the start,
 * around r = 1/2 and at the end, and a stride of about x / 2^18 from a
 * random offset in between. */
static void atan2_dense_sweep(void)
{
    static const uint32_t xs[] = { 0x80000000u, 0x7FFFFFFFu, 0x40000000u, 0x40000001u, 0x5A5A5A5Au,
                                   0x6487ED51u, 12345678u, 1000003u, 65537u };
    long span = DHT_ITER(20000L), steps = DHT_ITER(1L << 18);
    unsigned m;
    worst_atan2 = 0.0;
    n_atan2 = 0;
    for (m = 0; m < sizeof xs / sizeof xs[0]; m++) {
        uint32_t x = xs[m], stride = x / (uint32_t)steps + 1u, y;
        long i;
        for (i = 0; i < span && (uint32_t)i <= x; i++) {
            check_mags((uint32_t)i, x);
            check_mags(x - (uint32_t)i, x);
            check_mags(x / 2u - (uint32_t)(span / 2) + (uint32_t)i, x);
        }
        for (y = rand_upto(stride - 1u); y <= x - stride; y += stride) check_mags(y, x);
    }
    dht_printf("atan2_q: %ld pairs in dense sweeps, max error %.4f LSB\n", n_atan2, worst_atan2);
}

static void atan2_scale_and_symmetry(void)
{
    long i, n = DHT_ITER(300000L);
    for (i = 0; i < n; i++) {
        int32_t y = (int32_t)dht_rand_u32() >> (dht_rand_u32() % 31u + 1u);
        int32_t x = (int32_t)dht_rand_u32() >> (dht_rand_u32() % 31u + 1u);
        int32_t a, b;
        unsigned k = 0;
        uint32_t m = (uint32_t)(y < 0 ? -y : y) | (uint32_t)(x < 0 ? -x : x);
        if (m == 0u) continue;
        while ((m << (k + 1u)) < 0x40000000u && m < (0x40000000u >> (k + 1u))) k++;
        DHT_EQ_INT(dh_atan2_q(y, x, &a), DH_OK);
        DHT_EQ_INT(dh_atan2_q((int32_t)((uint32_t)y << k), (int32_t)((uint32_t)x << k), &b), DH_OK);
        DHT_EQ_INT(a, b);
        DHT_EQ_INT(dh_atan2_q(-y, x, &b), DH_OK);
        if (a != DEG180 && a != -DEG180 + 1 && b != -DEG180 + 1) DHT_EQ_INT(b, -a);
    }
}

static void asin_acos_values(void)
{
    int32_t d = 0x5A5A5A5A;
    DHT_EQ_INT(dh_asin_q(0, &d), DH_OK);
    DHT_EQ_INT(d, 0);
    DHT_EQ_INT(dh_asin_q(0x40000000, &d), DH_OK);
    DHT_EQ_INT(d, 90 << 16);
    DHT_EQ_INT(dh_asin_q(-0x40000000, &d), DH_OK);
    DHT_EQ_INT(d, -(90 << 16));
    DHT_EQ_INT(dh_asin_q(0x20000000, &d), DH_OK);      /* asin 1/2 = 30 */
    DHT_EQ_INT(d, 30 << 16);
    DHT_EQ_INT(dh_acos_q(0x40000000, &d), DH_OK);
    DHT_EQ_INT(d, 0);
    DHT_EQ_INT(dh_acos_q(0, &d), DH_OK);
    DHT_EQ_INT(d, 90 << 16);
    DHT_EQ_INT(dh_acos_q(-0x40000000, &d), DH_OK);
    DHT_EQ_INT(d, DEG180);
    DHT_EQ_INT(dh_acos_q(-0x20000000, &d), DH_OK);     /* acos -1/2 = 120 */
    DHT_EQ_INT(d, 120 << 16);
    /* just outside +-1.0: clamped up to 1 + 2^-21 (512 LSB) */
    DHT_EQ_INT(dh_asin_q(0x40000200, &d), DH_OK);
    DHT_EQ_INT(d, 90 << 16);
    DHT_EQ_INT(dh_acos_q(-0x40000001, &d), DH_OK);
    DHT_EQ_INT(d, DEG180);
    d = 0x5A5A5A5A;
    DHT_EQ_INT(dh_asin_q(0x40000201, &d), DH_ERR_DOMAIN);
    DHT_EQ_INT(dh_asin_q(-0x40000201, &d), DH_ERR_DOMAIN);
    DHT_EQ_INT(dh_acos_q(0x40000201, &d), DH_ERR_DOMAIN);
    DHT_EQ_INT(dh_asin_q(INT32_MIN, &d), DH_ERR_DOMAIN);
    DHT_EQ_INT(dh_acos_q(INT32_MIN, &d), DH_ERR_DOMAIN);
    DHT_EQ_INT(dh_acos_q(INT32_MAX, &d), DH_ERR_DOMAIN);
    DHT_EQ_INT(d, 0x5A5A5A5A);
}

static void asin_acos_sweep(void)
{
    uint32_t stride = (uint32_t)(256L * dht_iter_div()) | 1u, k;   /* sparser on slow targets */
    int32_t s;
    long i, n = DHT_ITER(2000000L);
    worst_asin = worst_acos = 0.0;
    for (s = -0x40000200; s <= 0x40000200 - (int32_t)stride; s += (int32_t)stride) check_asin_acos(s);
    for (k = 0; k <= (uint32_t)DHT_ITER(200000L); k++) {
        check_asin_acos(0x40000000 - (int32_t)k);
        check_asin_acos(-0x40000000 + (int32_t)k);
        check_asin_acos((int32_t)k);
        check_asin_acos(0x20000000 - 100000 + (int32_t)k);
    }
    for (i = 0; i < n; i++) check_asin_acos((int32_t)((int64_t)(dht_rand_u32() % 0x80000401u) - 0x40000200));
    dht_printf("asin_q / acos_q: max error %.4f / %.4f LSB\n", worst_asin, worst_acos);
}

/* twin: asin_odd of test_itrig_f32.c */
static void asin_odd(void)
{
    long i, n = DHT_ITER(200000L);
    for (i = 0; i < n; i++) {
        int32_t s = (int32_t)(dht_rand_u32() % 0x40000201u), a, b;
        DHT_EQ_INT(dh_asin_q(s, &a), DH_OK);
        DHT_EQ_INT(dh_asin_q(-s, &b), DH_OK);
        DHT_EQ_INT(b, -a);
    }
}

static const dht_case cases[] = {
    DHT_CASE(atan2_exact_values),
    DHT_CASE(atan2_domain),
    DHT_CASE(atan2_edge_pairs),
    DHT_CASE(atan2_random),
    DHT_CASE(atan2_table_points),
    DHT_CASE(atan2_dense_sweep),
    DHT_CASE(atan2_scale_and_symmetry),
    DHT_CASE(asin_acos_values),
    DHT_CASE(asin_acos_sweep),
    DHT_CASE(asin_odd),
};
DHT_MAIN(cases)
