/* SPDX-License-Identifier: Apache-2.0 */
/* fw_print.c - integer output of the fixed-point firmware examples (fw_print.h). */
#include "fw_print.h"

#include <stdio.h>

void fw_put_line(const char *key, const int32_t *v, unsigned n)
{
    char buf[16];
    unsigned i;
    fputs(key, stdout);
    for (i = 0; i < n; i++) {
        uint32_t u = v[i] < 0 ? 0u - (uint32_t)v[i] : (uint32_t)v[i];
        int k = (int)sizeof buf - 1;
        buf[k] = '\0';
        do {
            buf[--k] = (char)('0' + u % 10u);
            u /= 10u;
        } while (u != 0u);
        if (v[i] < 0) buf[--k] = '-';
        buf[--k] = ' ';
        fputs(buf + k, stdout);
    }
    fputs("\n", stdout);
}

int fw_fail(const char *what, dh_status st)
{
    fputs(what, stdout);
    fputs(": ", stdout);
    fputs(dh_status_str(st), stdout);
    fputs("\n", stdout);
    return 1;
}
