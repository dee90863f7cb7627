/* SPDX-License-Identifier: Apache-2.0 */
/* Private to dh_robot.c and dh_robot_q.c (not installed). */
#ifndef DHMATH_DH_ROBOT_IMPL_H
#define DHMATH_DH_ROBOT_IMPL_H

#include "dhmath/dh_common.h"
#include "dhmath/dh_robot.h"

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

/* dh_robot_set_base_q (which 0) and dh_robot_set_tool_q (which 1). */
dh_status dh_robot_frame_q_(dh_robot *r, const dh_frame_q *src, unsigned which);

#endif
