/* SPDX-License-Identifier: Apache-2.0 */
/* Host backend of dht: every case is a cmocka unit test. */
#include <stdarg.h>
#include <setjmp.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "dht.h"

static void dht_trampoline(void **state)
{
    const dht_case *c = (const dht_case *)*state;
    /* each case starts from the same seed, so a failure reproduces alone */
    dht_reseed(dht_seed());
    c->fn();
}

void dht_fail(const char *file, int line, const char *fmt, ...)
{
    char buf[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    fail_msg("%s:%d: %s (seed 0x%llx; rerun with DHT_SEED=0x%llx)", file, line, buf,
             (unsigned long long)dht_seed(), (unsigned long long)dht_seed());
    abort(); /* not reached: fail_msg longjmps */
}

void dht_printf(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    fflush(stdout);
}

static long dht_div = 1;

long dht_iter_div(void) { return dht_div; }

/* DHT_ITER_DIV from the environment: a positive decimal number (as a seed
 * without 0x), at most 10^9; 1 when unset. */
static int dht_parse_div(const char *env, long *div)
{
    uint64_t v;
    if (env == NULL) { *div = 1; return 1; }
    if (env[0] == '0' && (env[1] == 'x' || env[1] == 'X')) return 0;
    if (!dht_parse_seed(env, &v) || v == 0u || v > 1000000000u) return 0;
    *div = (long)v;
    return 1;
}

int dht_run(const char *suite, const dht_case *cases, size_t n)
{
    struct CMUnitTest *tests;
    const char *env = getenv("DHT_SEED");
    const char *base = strrchr(suite, '/');
    const char *name = base ? base + 1 : suite;
    uint64_t seed = dht_seed();
    int rc;
    size_t i;
    if (env != NULL && !dht_parse_seed(env, &seed)) {
        fprintf(stderr, "%s: DHT_SEED=\"%s\" is not a seed: give decimal digits without a leading "
                "zero, or 0x and 1 to 16 hex digits (at most 2^64 - 1)\n", name, env);
        return 2;
    }
    if (!dht_parse_div(getenv("DHT_ITER_DIV"), &dht_div)) {
        fprintf(stderr, "%s: DHT_ITER_DIV=\"%s\" is not a loop-count divisor: give a decimal "
                "number from 1 to 1000000000\n", name, getenv("DHT_ITER_DIV"));
        return 2;
    }
    dht_reseed(seed);
    printf("%s: seed 0x%llx%s, DHT_ITER_DIV %ld\n", name, (unsigned long long)seed,
           env != NULL ? " (DHT_SEED)" : " (default)", dht_div);
    fflush(stdout);
    tests = calloc(n, sizeof *tests);
    if (tests == NULL) return 1;
    for (i = 0; i < n; i++) {
        tests[i].name = cases[i].name;
        tests[i].test_func = dht_trampoline;
        tests[i].initial_state = (void *)(uintptr_t)&cases[i];
    }
    rc = _cmocka_run_group_tests(name, tests, n, NULL, NULL);
    free(tests);
    return rc;
}
