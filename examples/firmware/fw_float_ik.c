/* SPDX-License-Identifier: Apache-2.0 */
/*
 * fw_float_ik.c - firmware example for a core with a single-precision FPU
 * (Cortex-M4F): forward kinematics, inverse kinematics to a pose, and the
 * pose's orientation as Euler angles, in float.
 *
 * The robot is a Puma 560 (examples/robots/puma560.dh: Corke's model of
 * the published parameters, metres, with its joint limits), built at run
 * time with the float setters. Everything lives on the stack: no heap, the
 * IK workspace is a local array of DH_IK_WORK_FLOATS(6) floats.
 *
 * Output (one "key: values" line each; angles in degrees, lengths in m,
 * floats printed with 9 digits, enough to read back the exact value):
 *   fk_q: <6 joint angles>          fk_p: <x y z>   fk_r: <R row by row>
 *   ik_goal_q: <6 joint angles>     the target pose is their FK:
 *   ik_target_p: <x y z>  ik_target_zyx: <yaw pitch roll of the target>
 *   ik_status: <dh_status name>  ik_q: <6 joint angles of the solution>
 *   euler_zyx: <yaw pitch roll of the FK pose>
 * examples/firmware/check_output.py recomputes the FK pose in double
 * precision, recomputes the Euler angles from the reference rotation and
 * checks that the exact FK of the printed IK solution reaches the exact
 * target pose (the FK of ik_goal_q) within the IK and FK tolerances.
 */
#include <stdio.h>

#include "dhmath/dhmath.h"

typedef struct {
    float d, a, alpha, qmin, qmax;
} puma_row;

static const puma_row puma[6] = {
    { 0.67183f, 0.0f, 90.0f, -160.0f, 160.0f },
    { 0.0f, 0.4318f, 0.0f, -110.0f, 110.0f },
    { 0.15005f, 0.0203f, -90.0f, -135.0f, 135.0f },
    { 0.4318f, 0.0f, 90.0f, -266.0f, 266.0f },
    { 0.0f, 0.0f, -90.0f, -100.0f, 100.0f },
    { 0.0f, 0.0f, 0.0f, -266.0f, 266.0f },
};

static void print_vec(const char *key, const float *v, unsigned n)
{
    unsigned i;
    printf("%s:", key);
    for (i = 0; i < n; i++) printf(" %.9g", (double)v[i]);
    printf("\n");
}

static void print_pose(const char *key_p, const char *key_r, const dh_mat4_f32 *T)
{
    float p[3], r[9];
    unsigned i;
    for (i = 0; i < 3u; i++) p[i] = DH_M4(T, i, 3);
    for (i = 0; i < 9u; i++) r[i] = DH_M4(T, i / 3u, i % 3u);
    print_vec(key_p, p, 3);
    if (key_r != NULL) print_vec(key_r, r, 9);
}

/* Orientation of T as intrinsic Z-Y-X (yaw, pitch, roll) angles. */
static dh_status print_zyx(const char *key, const dh_mat4_f32 *T)
{
    dh_mat3_f32 R;
    float ang[3];
    dh_status st;
    dh_mat4_get_rot_f32(T, &R);
    st = dh_mat3_to_euler_f32(&R, DH_EULER_ZYX, ang);
    if (st == DH_OK) print_vec(key, ang, 3);
    return st;
}

int main(void)
{
    static const float q_fk[6] = { 20.0f, -35.0f, 40.0f, 15.0f, 50.0f, -30.0f };
    static const float q_goal[6] = { -40.0f, 25.0f, -60.0f, 30.0f, -45.0f, 60.0f };
    static const float q_start[6] = { 0.0f, 0.0f, 0.0f, 0.0f, 10.0f, 0.0f };
    dh_robot arm;
    dh_mat4_f32 T, target;
    dh_ik_params_f32 par;
    dh_ik_result_f32 res;
    float work[DH_IK_WORK_FLOATS(6)];
    float q[6];
    dh_status st;
    unsigned i;

    if (dh_robot_init(&arm, DH_CONV_STANDARD) != DH_OK) return 1;
    for (i = 0; i < 6u; i++) {
        if (dh_robot_add_joint_f32(&arm, DH_JOINT_REVOLUTE, 0.0f, puma[i].d, puma[i].a,
                                   puma[i].alpha) != DH_OK ||
            dh_robot_set_limits_f32(&arm, i, puma[i].qmin, puma[i].qmax) != DH_OK)
            return 1;
    }

    /* FK of my arm */
    if (dh_fk_f32(&arm, q_fk, &T) != DH_OK) return 1;
    print_vec("fk_q", q_fk, 6);
    print_pose("fk_p", "fk_r", &T);

    /* pose to Euler angles */
    if (print_zyx("euler_zyx", &T) != DH_OK) return 1;

    /* IK to a pose: the target is a reachable pose (the FK of q_goal) */
    if (dh_fk_f32(&arm, q_goal, &target) != DH_OK) return 1;
    print_vec("ik_goal_q", q_goal, 6);
    print_pose("ik_target_p", NULL, &target);
    if (print_zyx("ik_target_zyx", &target) != DH_OK) return 1;
    dh_ik_params_default_f32(&arm, &par);
    par.tol_pos = 1e-6f; /* 1 um (the default is 1e-6 of the arm's size) */
    st = dh_ik_f32(&arm, &target, q_start, &par, work, sizeof work / sizeof work[0], q, &res);
    printf("ik_status: %s\n", dh_status_str(st));
    if (st != DH_OK) return 1;
    print_vec("ik_q", q, 6);
    return 0;
}
