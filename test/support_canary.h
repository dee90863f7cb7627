/* SPDX-License-Identifier: Apache-2.0 */
/* Helpers shared by the test_errors_*.c suites: outputs are pre-filled
 * with a canary pattern before a call that must fail, and checked after it
 * (docs/errors.md: outputs on error are untouched or documented). */
#ifndef SUPPORT_CANARY_H
#define SUPPORT_CANARY_H

#include <stddef.h>
#include <stdint.h>

#include "dht.h"

/* fill n bytes at p with 0xA5 */
void fill_canary(void *p, size_t n);
/* 1 when the n bytes at p are all still 0xA5 */
int is_canary(const void *p, size_t n);
/* the float with bit pattern u */
float f32_bits(uint32_t u);
/* k & 3: quiet NaN, +Inf, -Inf, signalling NaN */
float bad_value(unsigned k);

#define CANARY(x) fill_canary(&(x), sizeof(x))
#define UNTOUCHED(x) DHT_TRUE_MSG(is_canary(&(x), sizeof(x)), "%s written on error", #x)

#endif
