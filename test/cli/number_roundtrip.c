/* SPDX-License-Identifier: Apache-2.0 */
/*
 * number_roundtrip.c - the CLI's number parser (dh_expr_parse_number)
 * against its own output format: every finite float printed with %.9g (the
 * CLI's format, docs/cli.md) must parse back to the same float, bit for bit.
 *
 * Floats checked: every 4093rd bit pattern of the 2^32 (both signs, all
 * exponents, about 1.05 million), every 17th subnormal pattern, and the
 * edges listed in k_edges (FLT_MAX, FLT_MIN, the largest and smallest
 * subnormal, zeros, the floats around each power of two). Then texts that
 * must be rejected (they overflow, underflow to 0, or lose precision as a
 * subnormal) and accepted texts with their expected float, worked out by
 * hand from the IEEE 754 binary32 format:
 *   FLT_MAX = (2 - 2^-23) 2^127 = 3.40282346638528860e+38,
 *   the overflow threshold FLT_MAX + 2^103 = 3.40282356779733661e+38,
 *   FLT_MIN = 2^-126 = 1.17549435082228751e-38,
 *   smallest subnormal 2^-149 = 1.40129846432481707e-45.
 * Usage: cli_number_roundtrip [STRIDE] (default 4093).
 */
#include <float.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dh_expr.h"

static unsigned long g_checked, g_failed;

static uint32_t bits_of(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u;
}

static float float_of(uint32_t u)
{
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

static void fail(const char *what, const char *text)
{
    g_failed++;
    if (g_failed <= 20u) fprintf(stderr, "FAIL: %s: '%s'\n", what, text);
}

/* %.9g of f parses, and the parsed value rounds to f (same bits) */
static void roundtrip(uint32_t u)
{
    float f = float_of(u), g;
    char text[64];
    double v = 0.0;
    const char *why;
    if ((u & 0x7f800000u) == 0x7f800000u) return; /* Inf/NaN: not printable as a number */
    (void)snprintf(text, sizeof text, "%.9g", (double)f);
    g_checked++;
    why = dh_expr_parse_number(text, strlen(text), &v);
    if (why) {
        fail(why, text);
        return;
    }
    g = (float)v;
    if (bits_of(g) != u) fail("parses to another float", text);
}

/* text is rejected with a message containing `reason` */
static void rejected(const char *text, const char *reason)
{
    double v = 12345.0;
    const char *why = dh_expr_parse_number(text, strlen(text), &v);
    g_checked++;
    if (!why) fail("accepted (should be out of float range)", text);
    else if (!strstr(why, reason)) fail(why, text);
    if (v != 12345.0) fail("output written on error", text);
}

/* text is accepted and rounds to the float with bits u */
static void accepted(const char *text, uint32_t u)
{
    double v = 0.0;
    const char *why = dh_expr_parse_number(text, strlen(text), &v);
    g_checked++;
    if (why) fail(why, text);
    else if (bits_of((float)v) != u) fail("accepted as another float", text);
}

int main(int argc, char **argv)
{
    static const uint32_t k_edges[] = {
        0x00000000u, 0x80000000u,             /* +-0 */
        0x00000001u, 0x80000001u,             /* smallest subnormal 2^-149 */
        0x00000002u, 0x00000003u, 0x00400000u,
        0x007fffffu, 0x807fffffu,             /* largest subnormal */
        0x00800000u, 0x80800000u,             /* FLT_MIN */
        0x00800001u, 0x3f800000u, 0x3f7fffffu, 0x3f800001u,
        0x7f7fffffu, 0xff7fffffu,             /* FLT_MAX */
        0x7f7ffffeu, 0x7f000000u, 0x4b000000u, 0x4b7fffffu,
    };
    unsigned long stride = 4093u;
    uint64_t u;
    unsigned k, e;

    if (argc > 1) stride = strtoul(argv[1], NULL, 10);
    if (stride == 0u) stride = 1u;

    for (u = 0; u <= 0xffffffffu; u += stride) roundtrip((uint32_t)u);
    for (u = 0; u <= 0x007fffffu; u += 17u) {
        roundtrip((uint32_t)u);
        roundtrip((uint32_t)u | 0x80000000u);
    }
    for (k = 0; k < sizeof k_edges / sizeof k_edges[0]; k++) roundtrip(k_edges[k]);
    for (e = 1; e < 255u; e++) {          /* around every power of two */
        uint32_t p = e << 23;
        roundtrip(p);
        roundtrip(p - 1u);
        roundtrip(p + 1u);
        roundtrip(p | 0x80000000u);
    }

    /* the texts FLT_MAX and FLT_MIN print as (%.9g) */
    accepted("3.40282347e+38", 0x7f7fffffu);
    accepted("-3.40282347e+38", 0xff7fffffu);
    accepted("1.17549435e-38", 0x00800000u);
    accepted("1.40129846e-45", 0x00000001u);
    accepted("1.17549421e-38", 0x007fffffu);
    /* just below the overflow threshold: rounds to FLT_MAX */
    accepted("3.40282356e38", 0x7f7fffffu);
    /* at and beyond the threshold (ties round to even: 2^128, Inf) */
    rejected("340282356779733661637539395458142568448", "out of float range");
    rejected("3.40282357e38", "out of float range");
    rejected("3.5e38", "out of float range");
    rejected("-1e39", "out of float range");
    rejected("1e400", "out of float range");
    /* underflow to 0: below half the smallest subnormal, 7.00649232e-46 */
    rejected("7e-46", "underflows to 0");
    rejected("-1e-46", "underflows to 0");
    rejected("1e-400", "underflows to 0");
    /* a subnormal would change the value by more than float precision */
    rejected("1e-45", "subnormal");
    rejected("1.5e-45", "subnormal");
    rejected("1e-40", "subnormal");
    /* 2^-149 and 2^-140 written to 17 digits are held exactly */
    accepted("1.4012984643248171e-45", 0x00000001u);
    accepted("7.1746481373430634e-43", 0x00000200u);

    printf("number_roundtrip: %lu checks (stride %lu), %lu failures\n", g_checked, stride, g_failed);
    return g_failed ? 1 : 0;
}
