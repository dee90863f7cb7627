/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Self-test of the target test infrastructure (port/startup_cm.c,
 * test/dht_target.c, the linker scripts), run by ctest on every target
 * through port/selftest/expect.cmake, which checks the exit status and
 * the output. Two cases fail on purpose: the run must end with QEMU's
 * exit status 2 (the number of failed cases) and print both failures,
 * proving that a failing test fails ctest on the target.
 */
#include "dht.h"

#include <math.h>

static int initialised_data = 12345;   /* .data: copied by Reset_Handler */
static volatile int zero_data;         /* .bss: zeroed by Reset_Handler */
static volatile double vd = 2.0;       /* keep the compiler from folding */
static volatile float vf = 3.0f;

static void startup_copies_data_and_zeroes_bss(void)
{
    DHT_EQ_INT(initialised_data, 12345);
    DHT_EQ_INT(zero_data, 0);
    initialised_data++;
    DHT_EQ_INT(initialised_data, 12346);
}

/* On FPU cores this executes VFP instructions (the FPU must have been
 * enabled); on the M7 also double-precision ones. */
static void float_and_double_arithmetic(void)
{
    float f = vf;
    double d = vd;
    DHT_EQ_F32_BITS(f * f + 1.0f, 10.0f);
    DHT_NEAR(sqrt(d), 1.4142135623730951, 0.0);
    DHT_NEAR((double)sqrtf(f), 1.7320508075688772, 1e-7);
    DHT_NEAR(sin(d), 0.90929742682568170, 1e-16);
}

static void deliberately_failing_near(void)
{
    dht_printf("expected failure follows: ");
    DHT_NEAR(vd * 0.25, 0.25, 1e-3);
}

static void deliberately_failing_int(void)
{
    dht_printf("expected failure follows: ");
    DHT_EQ_INT(-5000000000LL, (long long)vd);
}

static void runs_after_failures(void)
{
    dht_printf("iterations %d\n", (int)DHT_ITER(1000));
    DHT_TRUE(DHT_ITER(1000) >= 1);
}

static const dht_case cases[] = {
    DHT_CASE(startup_copies_data_and_zeroes_bss),
    DHT_CASE(float_and_double_arithmetic),
    DHT_CASE(deliberately_failing_near),
    DHT_CASE(deliberately_failing_int),
    DHT_CASE(runs_after_failures),
};
DHT_MAIN(cases)
