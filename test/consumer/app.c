/* SPDX-License-Identifier: Apache-2.0 */
/*
 * app.c - an external consumer of dhmath, built by test/consumer/run.sh
 * through add_subdirectory, the installed CMake package, pkg-config and a
 * cross build with a minimal toolchain file. It uses the robot (layout of
 * DH_MAX_JOINTS), fixed-point and float rotation paths (square roots) and
 * checks the results against values worked out by hand.
 *   EXPECT_MAX_JOINTS  the DH_MAX_JOINTS the build is meant to see (8)
 * Exit status 0 when every check holds.
 */
#include <stdio.h>

#include "dhmath/dhmath.h"

#ifndef EXPECT_MAX_JOINTS
#define EXPECT_MAX_JOINTS 8
#endif
#if DH_MAX_JOINTS != EXPECT_MAX_JOINTS
#error "the consumer does not see the DH_MAX_JOINTS it was configured with"
#endif

static int near(float a, float b, float tol)
{
    float d = a - b;
    return d <= tol && d >= -tol;
}

int main(void)
{
    dh_robot arm;
    dh_mat4_f32 T;
    dh_mat3_f32 R;
    dh_quat_f32 qt;
    dh_frame_q Tq;
    const float q[2] = { 30.0f, 45.0f };
    const int32_t qq[2] = { 30 * DH_Q16_ONE, 45 * DH_Q16_ONE };
    int bad = 0, i, j;

    /* planar two-link arm, links 0.4 and 0.3: tool at
     * (0.4 cos 30 + 0.3 cos 75, 0.4 sin 30 + 0.3 sin 75), rotated 75 deg
     * about z, i.e. the quaternion (cos 37.5, 0, 0, sin 37.5) */
    bad |= dh_robot_init(&arm, DH_CONV_STANDARD) != DH_OK;
    bad |= dh_robot_add_joint_f32(&arm, DH_JOINT_REVOLUTE, 0.0f, 0.0f, 0.4f, 0.0f) != DH_OK;
    bad |= dh_robot_add_joint_f32(&arm, DH_JOINT_REVOLUTE, 0.0f, 0.0f, 0.3f, 0.0f) != DH_OK;
    bad |= dh_fk_f32(&arm, q, &T) != DH_OK;
    bad |= !near(DH_M4(&T, 0, 3), 0.42405587f, 1e-6f) || !near(DH_M4(&T, 1, 3), 0.48977775f, 1e-6f);
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) DH_M3(&R, i, j) = DH_M4(&T, i, j);
    }
    bad |= dh_mat3_to_quat_f32(&R, &qt) != DH_OK;
    bad |= !near(qt.w, 0.79335334f, 1e-6f) || !near(qt.x, 0.0f, 1e-6f) || !near(qt.y, 0.0f, 1e-6f) ||
           !near(qt.z, 0.60876143f, 1e-6f);
    /* the fixed path: the same position in dh_qpos, within 1e-4 */
    bad |= dh_fk_q(&arm, qq, &Tq) != DH_OK;
    bad |= !near((float)Tq.p[0] / (float)DH_QPOS_ONE, 0.42405587f, 1e-4f) ||
           !near((float)Tq.p[1] / (float)DH_QPOS_ONE, 0.48977775f, 1e-4f);
    /* a full robot fits; one joint more does not */
    for (i = 2; i < DH_MAX_JOINTS; i++) {
        bad |= dh_robot_add_joint_f32(&arm, DH_JOINT_PRISMATIC, 0.0f, 0.0f, 0.0f, 0.0f) != DH_OK;
    }
    bad |= dh_robot_add_joint_f32(&arm, DH_JOINT_PRISMATIC, 0.0f, 0.0f, 0.0f, 0.0f) != DH_ERR_ARG;
    printf("dhmath %s (%d.%d.%d), DH_MAX_JOINTS %d: %s\n", DH_VERSION_STRING, DH_VERSION_MAJOR,
           DH_VERSION_MINOR, DH_VERSION_PATCH, DH_MAX_JOINTS, bad ? "FAILED" : "ok");
    return bad ? 1 : 0;
}
