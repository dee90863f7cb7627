/* SPDX-License-Identifier: Apache-2.0 */
#include "support_canary.h"

#include <string.h>

void fill_canary(void *p, size_t n) { memset(p, 0xA5, n); }

int is_canary(const void *p, size_t n)
{
    const unsigned char *b = (const unsigned char *)p;
    size_t i;
    for (i = 0; i < n; i++)
        if (b[i] != 0xA5u) return 0;
    return 1;
}

float f32_bits(uint32_t u)
{
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

float bad_value(unsigned k)
{
    static const uint32_t b[4] = { 0x7FC00000u, 0x7F800000u, 0xFF800000u, 0x7F800001u };
    return f32_bits(b[k & 3u]);
}
