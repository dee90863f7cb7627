/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dht.h - the tiny assertion layer every dhmath test is written against.
 *
 * The same test sources run on the host (backend: cmocka, test/dht_cmocka.c)
 * and on emulated Cortex-M (backend: semihosting runner, test/dht_target.c).
 * A test file defines `static void name(void)` cases and ends with
 *
 *     static const dht_case cases[] = { DHT_CASE(name), ... };
 *     DHT_MAIN(cases)
 *
 * Checks stop the current case on failure (longjmp in both backends) after
 * printing file:line, the expression and the values.
 *
 * Randomness: dht_rand_u32()/dht_rand_uniform() from a seed that is printed
 * when the suite starts and on failure; DHT_SEED in the environment (host)
 * overrides it, and a DHT_SEED that is not a seed (dht_parse_seed) makes
 * the suite fail without running. DHT_ITER(n) scales loop counts: full on
 * the host, reduced on slow targets (DHT_ITER_DIV, set per target by CMake,
 * or in the host's environment).
 */
#ifndef DHT_H
#define DHT_H

#include <stdint.h>
#include <stddef.h>

typedef void (*dht_fn)(void);
typedef struct {
    const char *name;
    dht_fn fn;
} dht_case;

#define DHT_CASE(f) { #f, f }
#define DHT_NCASES(arr) (sizeof(arr) / sizeof((arr)[0]))

int dht_run(const char *suite, const dht_case *cases, size_t n);
#define DHT_MAIN(arr) \
    int main(void) { return dht_run(__FILE__, (arr), DHT_NCASES(arr)); }

/* Failure reporting: never returns. */
void dht_fail(const char *file, int line, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((noreturn, format(printf, 3, 4)))
#endif
    ;
/* Informational output (goes to stdout on host, semihosting on target). */
void dht_printf(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

#define DHT_TRUE(c) \
    do { if (!(c)) dht_fail(__FILE__, __LINE__, "check failed: %s", #c); } while (0)
#define DHT_TRUE_MSG(c, ...) \
    do { if (!(c)) dht_fail(__FILE__, __LINE__, __VA_ARGS__); } while (0)
#define DHT_EQ_INT(a, b) \
    do { long long dht_a_ = (long long)(a), dht_b_ = (long long)(b); \
         if (dht_a_ != dht_b_) dht_fail(__FILE__, __LINE__, "%s == %s: %lld != %lld", #a, #b, dht_a_, dht_b_); } while (0)
/* |a - b| <= tol, NaN fails. */
#define DHT_NEAR(a, b, tol) \
    do { double dht_a_ = (double)(a), dht_b_ = (double)(b), dht_t_ = (double)(tol); \
         double dht_d_ = dht_a_ - dht_b_; if (dht_d_ < 0) dht_d_ = -dht_d_; \
         if (!(dht_d_ <= dht_t_)) dht_fail(__FILE__, __LINE__, "%s ~ %s: %.17g vs %.17g (diff %.3g > tol %.3g)", \
                                           #a, #b, dht_a_, dht_b_, dht_d_, dht_t_); } while (0)
/* Bitwise float equality (distinguishes -0 and +0). */
#define DHT_EQ_F32_BITS(a, b) \
    do { float dht_a_ = (a), dht_b_ = (b); uint32_t dht_ua_, dht_ub_; \
         dht_memcpy4(&dht_ua_, &dht_a_); dht_memcpy4(&dht_ub_, &dht_b_); \
         if (dht_ua_ != dht_ub_) dht_fail(__FILE__, __LINE__, "%s == %s bitwise: %.9g (0x%08lx) vs %.9g (0x%08lx)", \
                                          #a, #b, (double)dht_a_, (unsigned long)dht_ua_, (double)dht_b_, (unsigned long)dht_ub_); } while (0)

void dht_memcpy4(void *dst, const void *src);
/* The bits of a float and the float of a bit pattern (IEEE binary32). */
uint32_t dht_f32_bits(float f);
float dht_f32_from_bits(uint32_t u);

/* Seeded PRNG (xorshift64*). The seed is printed by the runner on failure. */
uint64_t dht_seed(void);
void dht_reseed(uint64_t s);
uint32_t dht_rand_u32(void);
/* uniform in [lo, hi) */
double dht_rand_uniform(double lo, double hi);

/* Parses a seed: decimal digits without a leading zero ("0" itself is
 * fine) or 0x/0X followed by 1..16 hex digits, the whole string, at most
 * 2^64 - 1. Returns 1 and sets *seed, or 0 (no octal, sign, blank or
 * suffix: "08", "010", "abc", " 1", "-1", "1x" are all refused). */
int dht_parse_seed(const char *s, uint64_t *seed);

/* Reach probes: a test records the hardest input of a kind that it met,
 * under a name (at most DHT_REACH_MAX_PROBES names, each at most 47
 * characters): dht_reach_min keeps the smallest value recorded,
 * dht_reach_max the largest. When the suite ends, every probe's extreme is
 * printed ("reach NAME min VALUE"). A regression line of
 * test/regression_seeds.txt names what its seed must reach, "NAME<VALUE"
 * (a min probe below VALUE) or "NAME>VALUE" (a max probe above it), several
 * joined by ','; the host runner gets it in DHT_REACH and fails the suite
 * when a named probe was never recorded or stayed on the other side, so a
 * change in the order of the draws fails loudly instead of testing nothing.
 * Cross builds record nothing (DHT_REACH_RECORD 0, test/dht_common.c): the
 * check is the host runner's. */
#define DHT_REACH_MAX_PROBES 48
void dht_reach_min(const char *name, double v);
void dht_reach_max(const char *name, double v);
/* prints every probe's extreme (both backends call it when a suite ends) */
void dht_reach_report(void);
/* 1 and the probe's kind and extreme when name[0..len) was recorded, else 0
 * (the host runner checks DHT_REACH with it) */
int dht_reach_value(const char *name, size_t len, int *is_max, double *v);

/* Loop-count divisor: DHT_ITER_DIV of the build on a target (set per core
 * by CMake), the DHT_ITER_DIV environment variable on the host (a positive
 * decimal number, default 1; tools/seeds.sh uses it for many-seed runs). */
long dht_iter_div(void);
/* loop count n divided by dht_iter_div(), at least 1 */
long dht_iter(long n);
/* (0 * (n) + ...: the count keeps n's signedness, as loop counters of
 * n's type compare with it without a sign-compare warning on ILP32) */
#define DHT_ITER(n) (0 * (n) + dht_iter((long)(n)))

#endif /* DHT_H */
