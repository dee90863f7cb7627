/* SPDX-License-Identifier: Apache-2.0 */
/*
 * robot_app.c - a consumer whose robot comes from a robot file through
 * dhmath_add_robot() (test/consumer/robot/CMakeLists.txt): planar.dh as
 * `const dh_robot consumer_arm` in flash. FK at q = (30, 45) deg puts the
 * tool at (0.4 cos 30 + 0.3 cos 75, 0.4 sin 30 + 0.3 sin 75), float and
 * fixed point. Exit status 0 when every check holds.
 */
#include <stdio.h>

#include "dhmath/dhmath.h"

extern const dh_robot consumer_arm;

static int near(float a, float b, float tol)
{
    float d = a - b;
    return d <= tol && d >= -tol;
}

int main(void)
{
    dh_mat4_f32 T;
    dh_frame_q Tq;
    const float q[2] = { 30.0f, 45.0f };
    const int32_t qq[2] = { 30 * DH_Q16_ONE, 45 * DH_Q16_ONE };
    int bad = 0;

    bad |= dh_robot_check(&consumer_arm) != DH_OK;
    bad |= dh_fk_f32(&consumer_arm, q, &T) != DH_OK;
    bad |= !near(DH_M4(&T, 0, 3), 0.42405587f, 1e-6f) || !near(DH_M4(&T, 1, 3), 0.48977775f, 1e-6f);
    bad |= dh_fk_q(&consumer_arm, qq, &Tq) != DH_OK;
    bad |= !near((float)Tq.p[0] / (float)DH_QPOS_ONE, 0.42405587f, 1e-4f) ||
           !near((float)Tq.p[1] / (float)DH_QPOS_ONE, 0.48977775f, 1e-4f);
    printf("generated robot consumer_arm, %u joints: %s\n", (unsigned)consumer_arm.n, bad ? "FAILED" : "ok");
    return bad ? 1 : 0;
}
