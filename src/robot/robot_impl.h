/* SPDX-License-Identifier: Apache-2.0 */
/*
 * robot_impl.h - PRIVATE to the robot family (src/robot/, not installed):
 * the robot description's shared blocks, and the fixed FK steps that the
 * fixed Jacobian (src/kin/dh_jacobian_q.c) evaluates through kin_impl.h.
 */
#ifndef DHMATH_SRC_ROBOT_IMPL_H
#define DHMATH_SRC_ROBOT_IMPL_H

#include "dhmath/common.h"
#include "dhmath/robot.h"
#include "../internal/dh_floatops.h"

/* 1 when every row of F's rotation part has Euclidean norm <= 1.5
 * (DH_ROBOT_BASE_SMALL_Q, the test of the fixed FK fast path). */
int dh_robot_rows_small_q_(const dh_frame_q *F);

/* flags with the summary bits DH_ROBOT_HAS_F32 / DH_ROBOT_HAS_Q
 * recomputed from the reason bits (inline: dh_robot_flags_ stays one
 * function of the size-first core). */
static inline uint32_t dh_robot_summary_(uint32_t flags)
{
    const uint32_t f32_no = DH_ROBOT_F32_NO_JOINT | DH_ROBOT_F32_NO_BASE | DH_ROBOT_F32_NO_TOOL;
    const uint32_t q_no = DH_ROBOT_Q_NO_JOINT | DH_ROBOT_Q_NO_BASE | DH_ROBOT_Q_NO_TOOL;
    uint32_t f = flags & ~(DH_ROBOT_HAS_F32 | DH_ROBOT_HAS_Q);
    if ((f & f32_no) == 0u) f |= DH_ROBOT_HAS_F32;
    if ((f & q_no) == 0u) f |= DH_ROBOT_HAS_Q;
    return f;
}

/* r->flags = ((r->flags & ~clear) | set) with the summary bits
 * DH_ROBOT_HAS_F32 / DH_ROBOT_HAS_Q recomputed from the reason bits. */
void dh_robot_flags_(dh_robot *r, uint32_t clear, uint32_t set);

/* Float bits of a fixed rate limit v > 0 with frac fraction bits, as
 * dh_robot_set_rates_q stores it (INT32_MAX: +inf). Integer only. */
uint32_t dh_robot_rate_bits_(int32_t v, unsigned frac);

/* dh_robot_set_base_q (which 0) and dh_robot_set_tool_q (which 1). */
dh_status dh_robot_frame_q_(dh_robot *r, const dh_frame_q *src, unsigned which);

/* Fixed path (dh_fk_q.c): v[6] = (sin theta, cos theta, sin alpha, cos
 * alpha, d, a) of joint i at q as the FK step uses them (d + q saturated,
 * lengths with INT32_MIN raised to -INT32_MAX), and T <- T * tool in
 * place (as dh_fk_q). No argument checks; DH_ERR_OVERFLOW when a value
 * saturated, else 0. */
int dh_fk_values_q_(const dh_robot *r, uint32_t i, int32_t q, dh_q30 *v);
int dh_fk_tool_q_(const dh_robot *r, dh_frame_q *T);

/* ---- float to fixed conversion (dh_robot.c) ------------------------------ */

/**
 * x * 2^frac (frac 0..30) rounded to the nearest int32, ties away from zero,
 * into *out. Returns 0 when stored, 1 when x is finite but the result is
 * out of range, 2 when x is NaN or Inf (*out untouched in both cases), so
 * that callers OR the results of several conversions. Exact: the scaling is
 * by a power of two and the range test is on x itself (2^(31 - frac) is a
 * float); rem = v - trunc(v) is in (-1, 1), so the truncation of 2 rem is
 * +-1 exactly when |rem| >= 0.5. The largest float below 2^31 is an
 * integer, so i + 1 cannot overflow.
 */
static inline unsigned dh_robot_f32_to_fix_(float x, unsigned frac, int32_t *out)
{
    const uint32_t p = 1u << (frac & 31u), pl = 1u << (31u - frac);
    const float lim = (float)pl;
    float v, rem;
    int32_t i;
    if (!dh_isfinite_f32(x)) return 2u;
    if (x >= lim || x < -lim) return 1u;
    v = x * (float)p;
    i = (int32_t)v;
    rem = v - (float)i;
    rem += rem;
    *out = i + (int32_t)rem;
    return 0u;
}

/** The same, saturated to the int32 range by the sign of x when out of
 *  range (finite x); *st |= the dh_robot_f32_to_fix_ status. */
static inline int32_t dh_robot_f32_to_fix_sat_(float x, unsigned frac, unsigned *st)
{
    int32_t v;
    const unsigned e = dh_robot_f32_to_fix_(x, frac, &v);
    *st |= e;
    if (e == 0u) return v;
    return (x < 0.0f) ? INT32_MIN : INT32_MAX;
}


#endif /* DHMATH_SRC_ROBOT_IMPL_H */
