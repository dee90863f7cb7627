/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Target backend of dht (test/dht.h): runs the same test sources as the
 * host on bare-metal Cortex-M under QEMU, printing through semihosting
 * (newlib's rdimon syscalls; startup in port/startup_cm.c).
 *
 * Semantics match the host backend (test/dht_cmocka.c):
 *  - every case starts from the same seed (reseeded per case), so a failing
 *    case reproduces on its own; the seed is printed on failure;
 *  - a failed check prints file:line, the expression and the values, and
 *    stops the current case (longjmp back into the runner); the remaining
 *    cases still run;
 *  - the return value (main's, hence QEMU's exit status) is the number of
 *    failed cases, capped at 255, 0 when all passed. A crash (fault,
 *    DH_ASSERT trap) ends the run through the fault handler with status 3.
 *
 * The target has no environment: DHT_SEED is a build option here
 * (-DDHT_SEED=0x... at configure time, see port/dh_target.cmake).
 *
 * Output format (cmocka-like, one line per event; the time per case is the
 * host's wall clock through semihosting SYS_CLOCK, a guide for choosing
 * DHT_ITER_DIV, not a benchmark):
 *   [==========] test_x: Running 3 test(s).
 *   [ RUN      ] case_name
 *   [       OK ] case_name (120 ms)
 *   [  FAILED  ] case_name
 *   [==========] test_x: 3 test(s) run.
 *   [  PASSED  ] 2 test(s).
 *   [  FAILED  ] 1 test(s), listed below:
 *   [  FAILED  ] case_name
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "dht.h"

#ifndef DHT_ITER_DIV
#define DHT_ITER_DIV 1
#endif

long dht_iter_div(void) { return (long)DHT_ITER_DIV; }

#ifndef DHT_TARGET_MAX_CASES
#define DHT_TARGET_MAX_CASES 256
#endif

static jmp_buf dht_jump;
static int dht_in_case;

void dht_fail(const char *file, int line, const char *fmt, ...)
{
    char buf[512];
    va_list ap;
    const char *base = strrchr(file, '/');
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    printf("%s:%d: %s (seed 0x%llx; replay on the target with -DDHT_SEED=0x%llx, "
           "on the host with DHT_SEED=0x%llx)\n",
           base ? base + 1 : file, line, buf, (unsigned long long)dht_seed(),
           (unsigned long long)dht_seed(), (unsigned long long)dht_seed());
    fflush(stdout);
    if (dht_in_case) {
        longjmp(dht_jump, 1);
    }
    /* a check outside any case (cannot happen through dht_run) */
    _Exit(1);
}

void dht_printf(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    fflush(stdout);
}

/* The case being run is kept in a static, not a local: non-volatile locals
 * of a function that called setjmp are indeterminate after longjmp. */
static const dht_case *dht_current;

/* Runs one case; 0 = passed, 1 = a check failed. setjmp lives in this
 * small function so that no caller state is live across the longjmp. */
static int dht_run_case(void)
{
    if (setjmp(dht_jump) != 0) {
        dht_in_case = 0;
        return 1;
    }
    dht_in_case = 1;
    dht_current->fn();
    dht_in_case = 0;
    return 0;
}

int dht_run(const char *suite, const dht_case *cases, size_t n)
{
    static unsigned char failed[DHT_TARGET_MAX_CASES];
    const char *base = strrchr(suite, '/');
    const uint64_t seed = dht_seed();
    size_t nfailed = 0, i;
    clock_t t0;
    const char *name = base ? base + 1 : suite;

    memset(failed, 0, sizeof failed);
    printf("[==========] %s: Running %u test(s). (DHT_ITER_DIV %d, seed 0x%llx)\n", name,
           (unsigned)n, (int)DHT_ITER_DIV, (unsigned long long)seed);
    fflush(stdout);
    for (i = 0; i < n; i++) {
        dht_current = &cases[i];
        printf("[ RUN      ] %s\n", cases[i].name);
        fflush(stdout);
        dht_reseed(seed);
        t0 = clock();
        if (dht_run_case() == 0) {
            printf("[       OK ] %s (%ld ms)\n", cases[i].name,
                   (long)((clock() - t0) * 1000 / CLOCKS_PER_SEC));
        } else {
            nfailed++;
            if (i < DHT_TARGET_MAX_CASES) {
                failed[i] = 1;
            }
            printf("[  FAILED  ] %s\n", cases[i].name);
        }
        fflush(stdout);
    }
    /* every case starts from the suite seed, and so does the next suite */
    dht_reseed(seed);
    dht_reach_report();
    printf("[==========] %s: %u test(s) run.\n", name, (unsigned)n);
    printf("[  PASSED  ] %u test(s).\n", (unsigned)(n - nfailed));
    if (nfailed > 0) {
        printf("[  FAILED  ] %u test(s), listed below:\n", (unsigned)nfailed);
        for (i = 0; i < n && i < DHT_TARGET_MAX_CASES; i++) {
            if (failed[i]) {
                printf("[  FAILED  ] %s\n", cases[i].name);
            }
        }
    }
    fflush(stdout);
    return nfailed > 255 ? 255 : (int)nfailed;
}
