/* SPDX-License-Identifier: Apache-2.0 */
/*
 * fixed_const_m0.c - compiled for Cortex-M0+ (soft float) by
 * test/fixed_const_m0.cmake: the constant macros of frame.h in static
 * initialisers and in code must not reference any routine (no soft-float
 * __aeabi_f or __aeabi_d call: the compiler folds them). With
 * -DDH_CONST_OUT_OF_RANGE it must not compile (a literal outside the
 * Q16.16 range in a static initialiser).
 */
#include "dhmath/frame.h"

int32_t dh_const_probe(unsigned i);

static const dh_q16 probe_deg[4] = { DH_Q16(90.5), DH_Q16(-32768.0), DH_Q16(32767.99998), DH_Q16(0.001) };
static const dh_q30 probe_unit[4] = { DH_Q30(0.70710678), DH_Q30(-2.0), DH_Q30(1.0), DH_Q30(-0.25) };
static const dh_qpos probe_len = DH_QPOS(123.25);
#ifdef DH_CONST_OUT_OF_RANGE
static const dh_q16 probe_bad = DH_Q16(32768.0);
#endif

int32_t dh_const_probe(unsigned i)
{
    int32_t local = DH_Q16(-12.75) + DH_Q30(0.5);
#ifdef DH_CONST_OUT_OF_RANGE
    local += probe_bad;
#endif
    return probe_deg[i & 3u] + probe_unit[(i >> 2) & 3u] + probe_len + local;
}
