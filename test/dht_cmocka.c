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
    char buf[512];
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

int dht_run(const char *suite, const dht_case *cases, size_t n)
{
    struct CMUnitTest *tests = calloc(n, sizeof *tests);
    const char *env = getenv("DHT_SEED");
    const char *base = strrchr(suite, '/');
    int rc;
    size_t i;
    if (tests == NULL) return 1;
    if (env != NULL) dht_reseed(strtoull(env, NULL, 0));
    else dht_reseed(dht_seed());
    for (i = 0; i < n; i++) {
        tests[i].name = cases[i].name;
        tests[i].test_func = dht_trampoline;
        tests[i].initial_state = (void *)(uintptr_t)&cases[i];
    }
    rc = _cmocka_run_group_tests(base ? base + 1 : suite, tests, n, NULL, NULL);
    free(tests);
    return rc;
}
