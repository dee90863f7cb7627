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
 * axes, small integers, every pair of the int32 edge values) and > 10^7
 * asin/acos inputs (a strided pass over [-2^30, 2^30], the
 * neighbourhoods of 0, +-1/2 and +-1).
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

static void check_atan2(int32_t y, int32_t x)
{
    int32_t d = 0x5A5A5A5A;
    double ref, e;
    DHT_EQ_INT(dh_atan2_q(y, x, &d), DH_OK);
    DHT_TRUE_MSG(d > -DEG180 && d <= DEG180, "atan2_q(%ld, %ld) = %ld outside (-180, 180]", (long)y,
                 (long)x, (long)d);
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
    DHT_CASE(atan2_scale_and_symmetry),
    DHT_CASE(asin_acos_values),
    DHT_CASE(asin_acos_sweep),
    DHT_CASE(asin_odd),
};
DHT_MAIN(cases)
