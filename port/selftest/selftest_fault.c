/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Self-test of the fault path of port/startup_cm.c: a test that crashes
 * (here like DH_ASSERT's default trap, __builtin_trap) must end the
 * emulator with status 3 and a message, not hang until the ctest timeout.
 * Checked by port/selftest/expect.cmake.
 */
#include "dht.h"

static void trap_like_dh_assert(void)
{
    dht_printf("about to trap\n");
    __builtin_trap();
}

static void never_runs(void)
{
    DHT_TRUE(0);
}

static const dht_case cases[] = { DHT_CASE(trap_like_dh_assert), DHT_CASE(never_runs) };
DHT_MAIN(cases)
