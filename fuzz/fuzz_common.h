/* SPDX-License-Identifier: Apache-2.0 */
/*
 * fuzz_common.h - shared helpers of the libFuzzer targets in fuzz/.
 *
 * Host-only test code (built by tools/fuzz.sh with clang and
 * -fsanitize=fuzzer,address,undefined): it may use stdio, libm and double.
 *
 * FZ_CHECK(cond, fmt, ...) is the invariant check of every target: on
 * failure it prints the invariant and the values involved and calls
 * abort(), which libFuzzer reports as a crash and saves as an artifact.
 *
 * fz_in is a cursor over the fuzzer's bytes; reads past the end return
 * zeros, so every input, however short, is a valid (if boring) case.
 */
#ifndef DHMATH_FUZZ_COMMON_H
#define DHMATH_FUZZ_COMMON_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include <math.h>

#define FZ_CHECK(cond, ...)                                                        \
    do {                                                                           \
        if (!(cond)) {                                                             \
            fprintf(stderr, "%s:%d: invariant failed: %s\n  ", __FILE__, __LINE__, \
                    #cond);                                                        \
            fprintf(stderr, __VA_ARGS__);                                          \
            fprintf(stderr, "\n");                                                 \
            abort();                                                               \
        }                                                                          \
    } while (0)

typedef struct {
    const uint8_t *p;
    size_t n;
} fz_in;

static inline uint8_t fz_u8(fz_in *in)
{
    uint8_t v = 0;
    if (in->n > 0) {
        v = in->p[0];
        in->p++;
        in->n--;
    }
    return v;
}

static inline uint32_t fz_u32(fz_in *in)
{
    uint32_t v = 0;
    unsigned k;
    for (k = 0; k < 4u; k++) v |= (uint32_t)fz_u8(in) << (8u * k);
    return v;
}

static inline int32_t fz_i32(fz_in *in)
{
    uint32_t u = fz_u32(in);
    int32_t v;
    memcpy(&v, &u, sizeof v);
    return v;
}

/* Any float bit pattern (NaN, Inf, denormals included). */
static inline float fz_f32_bits(fz_in *in)
{
    uint32_t u = fz_u32(in);
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

/* A finite double in [-1, 1] with 32 bits of resolution. */
static inline double fz_unit(fz_in *in)
{
    return (double)fz_i32(in) / 2147483648.0;
}

static inline uint32_t fz_f32_to_bits(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u;
}

/* largest finite |number| written in a text (strtod at every digit run),
 * for tolerances that must cover rounding the text's values to float */
static inline double fz_max_number(const char *buf, size_t len)
{
    char tmp[65];
    double m = 0.0;
    size_t k = 0;
    while (k < len) {
        if ((buf[k] >= '0' && buf[k] <= '9') || buf[k] == '.') {
            size_t n = 0;
            double v;
            while (k + n < len && n < 64u && strchr("0123456789.eE+-", buf[k + n]) != NULL &&
                   buf[k + n] != '\0')
                n++;
            memcpy(tmp, buf + k, n);
            tmp[n] = '\0';
            v = fabs(strtod(tmp, NULL));
            if (v > m && v <= (double)FLT_MAX) m = v;
            k += n ? n : 1u;
        } else {
            k++;
        }
    }
    return m;
}

#endif /* DHMATH_FUZZ_COMMON_H */
