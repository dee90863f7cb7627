/* Private to dh_robot.c and dh_robot_q.c (not installed). */
#ifndef DHMATH_DH_ROBOT_IMPL_H
#define DHMATH_DH_ROBOT_IMPL_H

#include "dhmath/dh_common.h"

/* 1 when every row of F's rotation part has Euclidean norm <= 1.5 (the
 * DH_ROBOT_BASE_SMALL_Q test of the fixed FK fast path); integer only,
 * defined in dh_robot_q.c and shared by the float setters of dh_robot.c. */
int dh_robot_rows_small_q_(const dh_frame_q *F);

#endif
