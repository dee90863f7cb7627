/* SPDX-License-Identifier: Apache-2.0 */
#include <stdio.h>
#include "dhmath/dhmath.h"

int main(void)
{
    dh_robot arm;              /* caller-owned, no heap */
    dh_mat4_f32 T;
    const float q[2] = { 30.0f, 45.0f };   /* joint angles in degrees */

    dh_robot_init(&arm, DH_CONV_STANDARD);
    dh_robot_add_joint_f32(&arm, DH_JOINT_REVOLUTE, 0.0f, 0.0f, 0.4f, 0.0f);
    dh_robot_add_joint_f32(&arm, DH_JOINT_REVOLUTE, 0.0f, 0.0f, 0.3f, 0.0f);

    if (dh_fk_f32(&arm, q, &T) != DH_OK) return 1;
    printf("tool at x=%.4f y=%.4f\n", (double)DH_M4(&T, 0, 3), (double)DH_M4(&T, 1, 3));

    dh_mat4_inv_rigid_f32(&T, &T);     /* base expressed in the tool frame */
    printf("base at x=%.4f y=%.4f\n", (double)DH_M4(&T, 0, 3), (double)DH_M4(&T, 1, 3));
    return 0;
}
