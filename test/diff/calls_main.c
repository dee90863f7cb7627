/* SPDX-License-Identifier: Apache-2.0 */
/* The library linked as dhmath. */
#define DIFF_TABLE diff_calls_main
#include "diff_calls.inc"
