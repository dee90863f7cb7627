/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_itrig_f32.c - inverse trigonometry in degrees, float (contracts in
 * include/dhmath/trig.h). The arithmetic is the libm-free atan2 of
 * src/internal/dh_mathf.c (one reduction and polynomial for the radian and the
 * degree results; method and error budget there); this file holds the
 * statuses, the clamp of asin/acos arguments just outside [-1, 1] and the
 * range (-180, 180] of atan2.
 */

#include "dhmath/trig.h"
#include "../internal/dh_floatops.h"
#include "../internal/dh_mathf.h"

#define DH_ITRIG_ABS  0x7FFFFFFFu
#define DH_ITRIG_INF  0x7F800000u
#define DH_ITRIG_ONE  0x3F800000u   /* 1.0f */
#define DH_ITRIG_TOL  0x3F800004u   /* 1 + 2^-21: four ulp above 1 */
#define DH_ITRIG_M180 0xC3340000u   /* -180.0f */
#define DH_ITRIG_M180_UP 0xC333FFFFu /* the float just above -180 */

dh_status dh_atan2_f32(float y, float x, float *deg)
{
    uint32_t ax, ay, r;

    DH_ASSERT(deg != NULL);
    ax = dh_f32_bits(x) & DH_ITRIG_ABS;
    ay = dh_f32_bits(y) & DH_ITRIG_ABS;
    if (ax >= DH_ITRIG_INF || ay >= DH_ITRIG_INF) return DH_ERR_NAN;
    if ((ax | ay) == 0u) return DH_ERR_DOMAIN;
    r = dh_f32_bits(dh_atan2f_deg_(y, x, 0.0f));
    if (r == DH_ITRIG_M180) {
        /* y = -0 (x < 0): the negative x axis is +180; y < 0 rounded to
         * -180: the nearest value inside (-180, 180] */
        r = (ay == 0u) ? (r & DH_ITRIG_ABS) : DH_ITRIG_M180_UP;
    }
    *deg = dh_f32_from_bits(r);
    return DH_OK;
}

/* v with |v| in (1, 1 + 2^-21] replaced by +-1; DH_ERR_NAN / DH_ERR_DOMAIN
 * otherwise (v untouched) */
static dh_status itrig_unit_arg(float *v)
{
    uint32_t b = dh_f32_bits(*v), m = b & DH_ITRIG_ABS;
    if (m >= DH_ITRIG_INF) return DH_ERR_NAN;
    if (m > DH_ITRIG_TOL) return DH_ERR_DOMAIN;
    if (m > DH_ITRIG_ONE) *v = dh_f32_from_bits((b & ~DH_ITRIG_ABS) | DH_ITRIG_ONE);
    return DH_OK;
}

dh_status dh_asin_f32(float s, float *deg)
{
    dh_status st;

    DH_ASSERT(deg != NULL);
    st = itrig_unit_arg(&s);
    if (st != DH_OK) return st;
    *deg = dh_asinf_deg_(s, 0u);
    return DH_OK;
}

dh_status dh_acos_f32(float c, float *deg)
{
    dh_status st;

    DH_ASSERT(deg != NULL);
    st = itrig_unit_arg(&c);
    if (st != DH_OK) return st;
    *deg = dh_asinf_deg_(c, 1u);
    return DH_OK;
}
