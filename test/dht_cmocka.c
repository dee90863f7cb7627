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

/* 1 when every term of spec (NAME<VALUE or NAME>VALUE, joined by ',', see
 * dht.h) holds for the probes recorded; else 0, after printing each term
 * that does not hold or does not parse. */
static int dht_reach_check(const char *spec)
{
    int ok = 1;
    const char *t = spec;
    while (*t != '\0') {
        const char *end = strchr(t, ',');
        size_t len = end ? (size_t)(end - t) : strlen(t);
        const char *op = t;
        while (op < t + len && *op != '<' && *op != '>') op++;
        if (op == t || op == t + len || op + 1 == t + len) {
            dht_printf("DHT_REACH: \"%.*s\" is not NAME<VALUE or NAME>VALUE\n", (int)len, t);
            ok = 0;
        } else {
            char num[64], *stop;
            size_t nlen = (size_t)(t + len - (op + 1));
            double lim;
            int is_max = 0;
            double v = 0.0;
            const int found = dht_reach_value(t, (size_t)(op - t), &is_max, &v);
            if (nlen >= sizeof num) nlen = sizeof num - 1;
            memcpy(num, op + 1, nlen);
            num[nlen] = '\0';
            lim = strtod(num, &stop);
            if (stop == num || *stop != '\0') {
                dht_printf("DHT_REACH: \"%.*s\": \"%s\" is not a number\n", (int)len, t, num);
                ok = 0;
            } else if (!found) {
                dht_printf("DHT_REACH: %.*s never recorded: the seed no longer reaches the input its regression line "
                           "names\n", (int)(op - t), t);
                ok = 0;
            } else if (is_max != (*op == '>')) {
                dht_printf("DHT_REACH: %.*s is a %s probe, \"%.*s\" asks the other side\n", (int)(op - t), t,
                           is_max ? "max" : "min", (int)len, t);
                ok = 0;
            } else if (!(is_max ? v > lim : v < lim)) {
                dht_printf("DHT_REACH: %.*s %s %.17g, not %c %g: the seed no longer reaches the input its regression "
                           "line names\n", (int)(op - t), t, is_max ? "max" : "min", v, *op, lim);
                ok = 0;
            }
        }
        t += len;
        if (*t == ',') t++;
    }
    return ok;
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
    dht_reach_report();
    /* DHT_REACH: what the seed of a regression line must reach */
    if (getenv("DHT_REACH") != NULL && !dht_reach_check(getenv("DHT_REACH"))) {
        fprintf(stderr, "%s: DHT_REACH=\"%s\" not reached (seed 0x%llx)\n", name, getenv("DHT_REACH"),
                (unsigned long long)seed);
        return rc != 0 ? rc : 3;
    }
    return rc;
}
