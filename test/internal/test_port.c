/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_port.c - port/dh_port.h: the dispatching functions (intrinsics on
 * Cortex-M3/M4/M7 target builds, plain C elsewhere) against the plain-C
 * versions and against references written independently here, on edge
 * values and on seeded random values; the 16-bit split kernel of the
 * fixed-point FK against the exact 64-bit sum on its whole domain.
 */
#include "dht.h"
#include "../../src/internal/dh_port.h" /* private to the library: not on the test include path */

static const int32_t edges[] = {
    0, 1, -1, 2, -2, 3, INT32_MAX, INT32_MIN, INT32_MAX - 1, INT32_MIN + 1,
    0x40000000, -0x40000000, 0x3FFFFFFF, -0x3FFFFFFF, 0x20000000, -0x20000000,
    0xFFFF, -0xFFFF, 0x10000, -0x10000, 0x8000, -0x8000, 0x7FFF, -0x7FFF,
    0x12345678, -0x12345678, 0x7FFF0000, (int32_t)0x80008000u, 0x0000FFFF, 0x00010001
};
#define NEDGES (sizeof(edges) / sizeof(edges[0]))

/* exact a*b from magnitudes (|a|,|b| <= 2^31, product <= 2^62) */
static int64_t ref_mul(int32_t a, int32_t b)
{
    uint64_t ma = a < 0 ? (uint64_t)0 - (uint64_t)(int64_t)a : (uint64_t)a;
    uint64_t mb = b < 0 ? (uint64_t)0 - (uint64_t)(int64_t)b : (uint64_t)b;
    uint64_t m = ma * mb;
    return ((a < 0) != (b < 0)) ? -(int64_t)m : (int64_t)m;
}

static int32_t rand_edge_or_random(void)
{
    uint32_t r = dht_rand_u32();
    if ((r & 3u) == 0u) return edges[dht_rand_u32() % NEDGES];
    return (int32_t)dht_rand_u32();
}

static void report_features(void)
{
    dht_printf("dh_port: SMULL %d SSAT %d CLZ %d QADD %d, 64-bit product is a call %d (DH_USE_INTRINSICS %d)\n",
               DH_PORT_HAS_SMULL, DH_PORT_HAS_SSAT, DH_PORT_HAS_CLZ, DH_PORT_HAS_QADD,
               DH_PORT_MUL64_IS_CALL, DH_USE_INTRINSICS);
    /* the fallback must be used exactly when the build does not allow intrinsics */
    if (!DH_USE_INTRINSICS) {
        DHT_EQ_INT(DH_PORT_HAS_SMULL + DH_PORT_HAS_SSAT + DH_PORT_HAS_CLZ + DH_PORT_HAS_QADD, 0);
    }
#if !defined(__arm__)
    DHT_EQ_INT(DH_PORT_HAS_SMULL + DH_PORT_HAS_SSAT + DH_PORT_HAS_CLZ + DH_PORT_HAS_QADD, 0);
#endif
}

static void smull_edges_and_random(void)
{
    size_t i, j;
    long k, n = DHT_ITER(200000);
    for (i = 0; i < NEDGES; i++)
        for (j = 0; j < NEDGES; j++) {
            int32_t a = edges[i], b = edges[j];
            int64_t r = ref_mul(a, b);
            DHT_EQ_INT(dh_port_smull(a, b), r);
            DHT_EQ_INT(dh_port_smull_c(a, b), r);
        }
    for (k = 0; k < n; k++) {
        int32_t a = rand_edge_or_random(), b = rand_edge_or_random();
        int64_t r = ref_mul(a, b);
        DHT_EQ_INT(dh_port_smull(a, b), r);
        DHT_EQ_INT(dh_port_smull_c(a, b), r);
    }
}

/* the ARMv6-M 16-bit partial-product kernel, tested on every platform */
static void mac16_matches_exact_product(void)
{
    size_t i, j;
    long k, n = DHT_ITER(300000);
    for (i = 0; i < NEDGES; i++)
        for (j = 0; j < NEDGES; j++) {
            uint64_t acc = ((uint64_t)dht_rand_u32() << 32) | dht_rand_u32();
            DHT_EQ_INT(dh_port_mac16(acc, edges[i], edges[j]), acc + (uint64_t)ref_mul(edges[i], edges[j]));
        }
    for (k = 0; k < n; k++) {
        int32_t a = rand_edge_or_random(), b = rand_edge_or_random();
        uint64_t acc = ((uint64_t)dht_rand_u32() << 32) | dht_rand_u32();
        /* bias towards the split boundaries: low halves near 0x8000, high near +-2^15 */
        if (k & 1) a = (int32_t)(((uint32_t)a & 0xFFFF0000u) | (0x7FFFu + (dht_rand_u32() & 3u)));
        if (k & 2) b = (int32_t)(((uint32_t)b & 0x0000FFFFu) | ((dht_rand_u32() & 1u) ? 0x7FFF0000u : 0x80000000u));
        DHT_EQ_INT(dh_port_mac16(acc, a, b), acc + (uint64_t)ref_mul(a, b));
    }
}

static void smlal_wraps_like_hardware(void)
{
    static const int64_t accs[] = {
        0, 1, -1, INT64_MAX, INT64_MIN, (int64_t)1 << 62, -((int64_t)1 << 62),
        (int64_t)1 << 29, INT64_MAX - ((int64_t)1 << 40)
    };
    size_t i, j, m;
    for (m = 0; m < sizeof(accs) / sizeof(accs[0]); m++)
        for (i = 0; i < NEDGES; i++)
            for (j = 0; j < NEDGES; j++) {
                int32_t a = edges[i], b = edges[j];
                /* reference: modulo-2^64 sum, as SMLAL does */
                uint64_t r = (uint64_t)accs[m] + (uint64_t)ref_mul(a, b);
                DHT_EQ_INT((uint64_t)dh_port_smlal(accs[m], a, b), r);
                DHT_EQ_INT((uint64_t)dh_port_smlal_c(accs[m], a, b), r);
            }
}

static int32_t ref_sat(int64_t x, unsigned bits)
{
    int64_t hi = ((int64_t)1 << (bits - 1u)) - 1, lo = -hi - 1;
    return (int32_t)(x > hi ? hi : (x < lo ? lo : x));
}

static void ssat_every_width_and_constant_forms(void)
{
    size_t i;
    unsigned bits;
    long n = DHT_ITER(20000);
    for (bits = 1; bits <= 32u; bits++)
        for (i = 0; i < NEDGES; i++) DHT_EQ_INT(dh_port_ssat_c(edges[i], bits), ref_sat(edges[i], bits));
    for (i = 0; i < NEDGES + (size_t)n; i++) {
        int32_t x = i < NEDGES ? edges[i] : rand_edge_or_random();
        /* the macro needs constant widths (SSAT immediate) */
        DHT_EQ_INT(DH_PORT_SSAT(x, 1), ref_sat(x, 1));
        DHT_EQ_INT(DH_PORT_SSAT(x, 8), ref_sat(x, 8));
        DHT_EQ_INT(DH_PORT_SSAT(x, 16), ref_sat(x, 16));
        DHT_EQ_INT(DH_PORT_SSAT(x, 30), ref_sat(x, 30));
        DHT_EQ_INT(DH_PORT_SSAT(x, 31), ref_sat(x, 31));
        DHT_EQ_INT(DH_PORT_SSAT(x, 32), x);
        /* ssat boundary values exactly */
        DHT_EQ_INT(DH_PORT_SSAT((int32_t)0x1FFFFFFF, 30), 0x1FFFFFFF);
        DHT_EQ_INT(DH_PORT_SSAT((int32_t)0x20000000, 30), 0x1FFFFFFF);
        DHT_EQ_INT(DH_PORT_SSAT((int32_t)-0x20000000, 30), -0x20000000);
        DHT_EQ_INT(DH_PORT_SSAT((int32_t)-0x20000001, 30), -0x20000000);
    }
}

static unsigned ref_clz(uint32_t x)
{
    unsigned n = 0;
    uint32_t bit = 0x80000000u;
    while (bit != 0u && (x & bit) == 0u) { n++; bit >>= 1; }
    return n;
}

static void clz_all_bit_positions(void)
{
    unsigned b;
    long k, n = DHT_ITER(100000);
    DHT_EQ_INT(dh_port_clz(0u), 32);
    DHT_EQ_INT(dh_port_clz_c(0u), 32);
    for (b = 0; b < 32u; b++) {
        uint32_t x = (uint32_t)1 << b;
        DHT_EQ_INT(dh_port_clz(x), 31u - b);
        DHT_EQ_INT(dh_port_clz_c(x), 31u - b);
        DHT_EQ_INT(dh_port_clz(x | (x - 1u)), 31u - b);
        DHT_EQ_INT(dh_port_clz_c(x | (x - 1u)), ref_clz(x | (x - 1u)));
    }
    for (k = 0; k < n; k++) {
        uint32_t x = dht_rand_u32() >> (dht_rand_u32() % 32u);
        DHT_EQ_INT(dh_port_clz(x), ref_clz(x));
        DHT_EQ_INT(dh_port_clz_c(x), ref_clz(x));
    }
}

static void qadd_saturates(void)
{
    size_t i, j;
    long k, n = DHT_ITER(100000);
    for (i = 0; i < NEDGES; i++)
        for (j = 0; j < NEDGES; j++) {
            int64_t s = (int64_t)edges[i] + edges[j];
            int32_t r = s > INT32_MAX ? INT32_MAX : (s < INT32_MIN ? INT32_MIN : (int32_t)s);
            DHT_EQ_INT(dh_port_qadd(edges[i], edges[j]), r);
            DHT_EQ_INT(dh_port_qadd_c(edges[i], edges[j]), r);
        }
    for (k = 0; k < n; k++) {
        int32_t a = rand_edge_or_random(), b = rand_edge_or_random();
        int64_t s = (int64_t)a + b;
        int32_t r = s > INT32_MAX ? INT32_MAX : (s < INT32_MIN ? INT32_MIN : (int32_t)s);
        DHT_EQ_INT(dh_port_qadd(a, b), r);
        DHT_EQ_INT(dh_port_qadd_c(a, b), r);
    }
}


/* ---- 16-bit split kernel of the fixed-point FK (ARMv6-M path) ----------- */

/* |v| as int64 */
static int64_t abs64(int32_t v)
{
    return v < 0 ? -(int64_t)v : (int64_t)v;
}

/* exact floor((c x + s y + 2^29) / 2^30) when |c x + s y| < 2^63 - 2^29 */
static int64_t ref_dot2r30(int32_t c, int32_t x, int32_t s, int32_t y)
{
    int64_t t = ref_mul(c, x) + ref_mul(s, y) + ((int64_t)1 << 29);
    return t >> 30;   /* arithmetic shift = floor (checked in dh_port.h) */
}

/* a random value of magnitude up to 2^bits, biased to split boundaries */
static int32_t rand_mag(unsigned bits)
{
    uint32_t r = dht_rand_u32();
    int32_t v = (int32_t)(dht_rand_u32() >> (32u - bits)) - (int32_t)(dht_rand_u32() >> (32u - bits));
    switch (r & 7u) {
    case 0: v = (int32_t)(((uint32_t)v & 0xFFFF0000u) | 0x8000u); break;  /* low half 0x8000 */
    case 1: v = (int32_t)(((uint32_t)v & 0xFFFF0000u) | 0x7FFFu); break;
    case 2: { /* near the top of the range; 2^31 itself is clamped to INT32_MAX */
        int64_t m = ((int64_t)1 << bits) - (int64_t)(dht_rand_u32() & 0xFFFFu);
        if (m > INT32_MAX) m = INT32_MAX;
        v = (int32_t)(v < 0 ? -m : m);
        break;
    }
    default: break;
    }
    return v;
}

/* the splits are exact and in their documented ranges */
static void split16_ranges(void)
{
    long k, n = DHT_ITER(200000);
    for (k = 0; k < n + (long)NEDGES; k++) {
        int32_t v = k < (long)NEDGES ? edges[k] : rand_edge_or_random();
        if (v < 0x7FFF8000) {
            dh_port_s16 r = dh_port_split_row(v);
            DHT_EQ_INT((int64_t)r.h * 65536 + r.l, v);
            DHT_TRUE(r.l >= -32768 && r.l < 32768);
            DHT_TRUE(r.h >= -32768 && r.h < 32768);
        }
        if (abs64(v) <= 0x7FFF8000LL) {
            dh_port_s16 kq = dh_port_split_k(v);
            DHT_EQ_INT((int64_t)kq.h * 65536 + kq.l, v);
            DHT_TRUE(kq.l > -32768 && kq.l <= 32768);
            DHT_TRUE(kq.h >= -32768 && kq.h <= 32768);
        }
    }
}

/* dh_port_dot2r30_s16 equals the exactly rounded 64-bit sum on its domain
 * |c| + |s| + |x| + |y| <= 2^32 - 2^18, x, y < 2^31 - 2^15 (result in
 * int32), including the
 * extremes of the low halves (0x8000 / 0x7FFF) and the FK's own ranges */
static void dot2r30_s16_exact(void)
{
    long k, n = DHT_ITER(1000000), tested = 0;
    static const int32_t ks[] = { 0x40000000, -0x40000000, 0, 1, -1, 0x3FFF8000, -0x3FFF8000, 0x2D413CCD,
                                  -0x2D413CCD, 0x00008000, -0x00007FFF, 0x7FFF8000 / 2 };
    static const int32_t xs[] = { 0x60000000, -0x60000000, 0x5FFF8000, -0x60008000, 0x7FFF, -0x8000, 0x8000,
                                  0x40000000, -0x40000000, 0, 0x12348000, -0x12348000 };
    size_t a, b, c2, d2;
    /* structured extremes: rotation-like factors and row entries */
    for (a = 0; a < sizeof ks / sizeof ks[0]; a++)
        for (b = 0; b < sizeof ks / sizeof ks[0]; b++)
            for (c2 = 0; c2 < sizeof xs / sizeof xs[0]; c2++)
                for (d2 = 0; d2 < sizeof xs / sizeof xs[0]; d2 += 3) {
                    int32_t c = ks[a], s = ks[b], x = xs[c2], y = xs[d2];
                    int64_t r;
                    if (abs64(c) + abs64(s) + abs64(x) + abs64(y) > 0xFFFC0000LL) continue;
                    if (x >= 0x7FFF8000 || y >= 0x7FFF8000) continue;
                    r = ref_dot2r30(c, x, s, y);
                    if (r > INT32_MAX || r < INT32_MIN) continue;
                    DHT_EQ_INT(dh_port_dot2r30_s16(dh_port_split_k(c), dh_port_split_row(x), dh_port_split_k(s),
                                                   dh_port_split_row(y)), r);
                    tested++;
                }
    for (k = 0; k < n; k++) {
        int32_t c, s, x, y;
        int64_t r;
        switch (k % 3) {
        case 0:   /* sine/cosine pair and a row of norm <= 1.5 (the FK rotation sums) */
            c = rand_mag(30); s = rand_mag(30); x = rand_mag(30); y = rand_mag(30);
            x += x / 2; y += y / 2;
            break;
        case 1:   /* lengths |a| + |d| <= 2^30 times rotation entries (FK positions) */
            c = rand_mag(29); s = rand_mag(29); x = rand_mag(30); y = rand_mag(30);
            break;
        default:  /* anything on the domain boundary */
            c = rand_mag(31); s = rand_mag(31); x = rand_mag(31); y = rand_mag(31);
            break;
        }
        if (abs64(c) > 0x7FFF8000LL || abs64(s) > 0x7FFF8000LL) continue;
        if (x >= 0x7FFF8000 || y >= 0x7FFF8000) continue;
        if (abs64(c) + abs64(s) + abs64(x) + abs64(y) > 0xFFFC0000LL) continue;
        r = ref_dot2r30(c, x, s, y);
        if (r > INT32_MAX || r < INT32_MIN) continue;
        DHT_EQ_INT(dh_port_dot2r30_s16(dh_port_split_k(c), dh_port_split_row(x), dh_port_split_k(s),
                                       dh_port_split_row(y)), r);
        tested++;
    }
    dht_printf("dot2r30_s16: %ld sums checked against the exact 64-bit value\n", tested);
    DHT_TRUE(tested > n / 4);
}

static const dht_case cases[] = {
    DHT_CASE(report_features),
    DHT_CASE(smull_edges_and_random),
    DHT_CASE(mac16_matches_exact_product),
    DHT_CASE(smlal_wraps_like_hardware),
    DHT_CASE(ssat_every_width_and_constant_forms),
    DHT_CASE(clz_all_bit_positions),
    DHT_CASE(qadd_saturates),
    DHT_CASE(split16_ranges),
    DHT_CASE(dot2r30_s16_exact),
};
DHT_MAIN(cases)
