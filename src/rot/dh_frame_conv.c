/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_frame_conv.c - conversions between the float dh_mat4_f32 and the
 * fixed-point dh_frame_q. This is the only frame file that uses float (no
 * double, no libm): scaling by a power of two is exact in float, and the
 * rounding to an integer is done with exact float operations.
 */
#include "dhmath/frame.h"
#include "dhmath/rot.h"
#include "../internal/dh_floatops.h"

/* 2^e as float, 0 <= e <= 30 (exact). */
static float frame_conv_pow2f(unsigned e)
{
    return (float)((uint32_t)1 << e);
}

/*
 * Round a finite float to the nearest int32, ties away from zero, with
 * saturation (*ovf set). Every step is exact: |x| >= 2^23 is already an
 * integer (2^31 is a float, so the range test is exact); below, the
 * truncation t fits and x - t is exact.
 */
static int32_t frame_conv_round_sat(float x, uint32_t *ovf)
{
    int32_t t;
    float f;
    if (x >= 2147483648.0f) { *ovf = 1u; return INT32_MAX; }
    if (x < -2147483648.0f) { *ovf = 1u; return INT32_MIN; }
    if (x >= 8388608.0f || x <= -8388608.0f) return (int32_t)x;
    t = (int32_t)x;                  /* truncation toward zero */
    f = x - (float)t;                /* exact, in (-1, 1) */
    if (f >= 0.5f) t += 1;
    else if (f <= -0.5f) t -= 1;
    return t;
}

dh_status dh_frame_from_mat4_q(const dh_mat4_f32 *T, dh_frame_q *F)
{
    const float rs = frame_conv_pow2f(30u), ps = frame_conv_pow2f((unsigned)DH_QPOS_FRAC);
    uint32_t ovf = 0u;
    unsigned i, j;
    DH_ASSERT(F != NULL && T != NULL);
    for (j = 0; j < 4u; j++)
        for (i = 0; i < 4u; i++)
            if (!dh_isfinite_f32(T->m[j][i])) return DH_ERR_NAN;
    for (j = 0; j < 3u; j++) {
        for (i = 0; i < 3u; i++) {
            /* Q2.30 range is [-2, 2): x * 2^30 must be in [-2^31, 2^31) */
            F->r[j][i] = frame_conv_round_sat(T->m[j][i] * rs, &ovf);
        }
        F->p[j] = frame_conv_round_sat(T->m[3][j] * ps, &ovf);
    }
    if (ovf) return DH_ERR_OVERFLOW;
    if (!dh_feq_f32(DH_M4(T, 3, 0), 0.0f) || !dh_feq_f32(DH_M4(T, 3, 1), 0.0f) || !dh_feq_f32(DH_M4(T, 3, 2), 0.0f) ||
        !dh_feq_f32(DH_M4(T, 3, 3), 1.0f))
        return DH_ERR_NOT_RIGID;
    return DH_OK;
}

void dh_frame_to_mat4_q(const dh_frame_q *F, dh_mat4_f32 *T)
{
    const float rs = 1.0f / frame_conv_pow2f(30u), ps = 1.0f / frame_conv_pow2f((unsigned)DH_QPOS_FRAC);
    unsigned i, j;
    DH_ASSERT(F != NULL && T != NULL);
    for (j = 0; j < 3u; j++) {
        for (i = 0; i < 3u; i++) T->m[j][i] = (float)F->r[j][i] * rs;
        T->m[j][3] = 0.0f;
        T->m[3][j] = (float)F->p[j] * ps;
    }
    T->m[3][3] = 1.0f;
}
