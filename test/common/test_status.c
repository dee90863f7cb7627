/* SPDX-License-Identifier: Apache-2.0 */
#include "dht.h"
#include "dhmath/common.h"
#include <string.h>

static void status_strings_are_distinct(void)
{
    int i, j;
    for (i = 0; i <= (int)DH_ERR_INCONSISTENT; i++) {
        const char *a = dh_status_str((dh_status)i);
        DHT_TRUE(a != NULL);
        DHT_TRUE(strcmp(a, "unknown status") != 0);
        for (j = 0; j < i; j++) DHT_TRUE(strcmp(a, dh_status_str((dh_status)j)) != 0);
    }
    DHT_TRUE(strcmp(dh_status_str((dh_status)99), "unknown status") == 0);
}

static const dht_case cases[] = { DHT_CASE(status_strings_are_distinct) };
DHT_MAIN(cases)
