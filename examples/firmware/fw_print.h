/* SPDX-License-Identifier: Apache-2.0 */
/*
 * fw_print.h - output of the fixed-point firmware examples without
 * printf: printf would link newlib's floating-point conversion, and these
 * images must link no float routine (examples/firmware/no_float.cmake).
 */
#ifndef FW_PRINT_H
#define FW_PRINT_H

#include <stdint.h>

#include "dhmath/dhmath.h"

/** Writes `key` followed by the n integers of v in decimal, then a newline. */
void fw_put_line(const char *key, const int32_t *v, unsigned n);

/** Writes "what: <status text>" and returns 1 (the exit status of a failure). */
int fw_fail(const char *what, dh_status st);

#endif /* FW_PRINT_H */
