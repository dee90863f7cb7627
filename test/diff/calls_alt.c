/* SPDX-License-Identifier: Apache-2.0 */
/* The copy built with the other DH_SMALL value: every dh_* name maps to
 * its dhalt_* symbol (dh_alt_names.h, generated from the renamed archive). */
#include "dh_alt_names.h"
#define DIFF_TABLE diff_calls_alt
#include "diff_calls.inc"
