/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_errors_motion.c - bad input to motion.h (docs/errors.md, "motion.h"):
 * every status of every row, with the outputs checked untouched.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_canary.h"
#include "dhmath/motion.h"
#include "dhmath/mat4.h"

static void rigid(dh_mat4_f32 *T, float x)
{
    dh_mat4_rotz_f32(30.0f, T);
    DH_M4(T, 0, 3) = x;
}

static void motion_slerp_bad(void)
{
    const dh_quat_f32 a = { 1.0f, 0.0f, 0.0f, 0.0f }, b = { 0.5f, 0.5f, 0.5f, 0.5f }, z = { 0.0f, 1e-39f, 0.0f, 0.0f };
    dh_quat_f32 out, bad;
    unsigned k;
    for (k = 0; k < 4u; k++) {
        CANARY(out);
        DHT_EQ_INT(dh_slerp_f32(&a, &b, bad_value(k), &out), DH_ERR_NAN);
        UNTOUCHED(out);
        bad = b;
        bad.y = bad_value(k);
        DHT_EQ_INT(dh_slerp_f32(&a, &bad, 0.5f, &out), DH_ERR_NAN);
        DHT_EQ_INT(dh_slerp_f32(&bad, &a, 0.5f, &out), DH_ERR_NAN);
        UNTOUCHED(out);
    }
    DHT_EQ_INT(dh_slerp_f32(&a, &b, -1e-30f, &out), DH_ERR_ARG);
    DHT_EQ_INT(dh_slerp_f32(&a, &b, 1.0000001f, &out), DH_ERR_ARG);
    DHT_EQ_INT(dh_slerp_f32(&a, &z, 0.5f, &out), DH_ERR_ZERO_AXIS);
    DHT_EQ_INT(dh_slerp_f32(&z, &b, 0.5f, &out), DH_ERR_ZERO_AXIS);
    UNTOUCHED(out);
    /* unnormalised inputs of any normal scale are fine */
    bad = b;
    bad.w = bad.x = bad.y = bad.z = 1e30f;
    DHT_EQ_INT(dh_slerp_f32(&a, &bad, 1.0f, &out), DH_OK);
    DHT_TRUE(memcmp(&out, &b, sizeof out) == 0);
}

static void motion_pose_bad(void)
{
    dh_mat4_f32 A, B, T, bad;
    float deg;
    unsigned k;
    rigid(&A, 1.0f);
    rigid(&B, 2.0f);
    for (k = 0; k < 4u; k++) {
        CANARY(T);
        CANARY(deg);
        bad = B;
        DH_M4(&bad, 1, 2) = bad_value(k);
        DHT_EQ_INT(dh_pose_interp_f32(&A, &bad, 0.5f, &T), DH_ERR_NAN);
        DHT_EQ_INT(dh_pose_angle_f32(&bad, &A, &deg), DH_ERR_NAN);
        bad = B;
        DH_M4(&bad, 2, 3) = bad_value(k);
        DHT_EQ_INT(dh_pose_interp_f32(&bad, &A, 0.5f, &T), DH_ERR_NAN);
        DHT_EQ_INT(dh_pose_interp_f32(&A, &B, bad_value(k), &T), DH_ERR_NAN);
        UNTOUCHED(T);
        UNTOUCHED(deg);
    }
    CANARY(T);
    CANARY(deg);
    bad = B;
    DH_M4(&bad, 0, 0) *= 1.001f;                /* scaled */
    DHT_EQ_INT(dh_pose_interp_f32(&A, &bad, 0.5f, &T), DH_ERR_NOT_RIGID);
    DHT_EQ_INT(dh_pose_angle_f32(&A, &bad, &deg), DH_ERR_NOT_RIGID);
    bad = B;
    DH_M4(&bad, 3, 0) = 1e-6f;                  /* bottom row */
    DHT_EQ_INT(dh_pose_interp_f32(&bad, &B, 0.5f, &T), DH_ERR_NOT_RIGID);
    DHT_EQ_INT(dh_pose_angle_f32(&bad, &B, &deg), DH_ERR_NOT_RIGID);
    DHT_EQ_INT(dh_pose_interp_f32(&A, &B, -0.5f, &T), DH_ERR_ARG);
    DHT_EQ_INT(dh_pose_interp_f32(&A, &B, 2.0f, &T), DH_ERR_ARG);
    rigid(&bad, -FLT_MAX);
    rigid(&B, FLT_MAX);
    DHT_EQ_INT(dh_pose_interp_f32(&bad, &B, 0.5f, &T), DH_ERR_OVERFLOW);
    UNTOUCHED(T);
    UNTOUCHED(deg);
}

static void motion_profile_bad(void)
{
    dh_profile_f32 p, good;
    float pos, vel, acc;
    unsigned k;
    for (k = 0; k < 4u; k++) {
        float x = bad_value(k);
        CANARY(p);
        DHT_EQ_INT(dh_profile_trap_f32(&p, x, 1.0f, 1.0f), DH_ERR_NAN);
        DHT_EQ_INT(dh_profile_trap_f32(&p, 1.0f, x, 1.0f), DH_ERR_NAN);
        DHT_EQ_INT(dh_profile_trap_f32(&p, 1.0f, 1.0f, x), DH_ERR_NAN);
        DHT_EQ_INT(dh_profile_scurve_f32(&p, x, 1.0f, 1.0f, 1.0f), DH_ERR_NAN);
        DHT_EQ_INT(dh_profile_scurve_f32(&p, 1.0f, x, 1.0f, 1.0f), DH_ERR_NAN);
        DHT_EQ_INT(dh_profile_scurve_f32(&p, 1.0f, 1.0f, x, 1.0f), DH_ERR_NAN);
        DHT_EQ_INT(dh_profile_scurve_f32(&p, 1.0f, 1.0f, 1.0f, x), DH_ERR_NAN);
        DHT_EQ_INT(dh_profile_quintic_f32(&p, x, 1.0f), DH_ERR_NAN);
        DHT_EQ_INT(dh_profile_quintic_f32(&p, 1.0f, x), DH_ERR_NAN);
        UNTOUCHED(p);
    }
    DHT_EQ_INT(dh_profile_trap_f32(&p, 1.0f, 0.0f, 1.0f), DH_ERR_ARG);
    DHT_EQ_INT(dh_profile_trap_f32(&p, 1.0f, 1.0f, -1.0f), DH_ERR_ARG);
    DHT_EQ_INT(dh_profile_scurve_f32(&p, 1.0f, -0.0f, 1.0f, 1.0f), DH_ERR_ARG);
    DHT_EQ_INT(dh_profile_scurve_f32(&p, 1.0f, 1.0f, 0.0f, 1.0f), DH_ERR_ARG);
    DHT_EQ_INT(dh_profile_scurve_f32(&p, 1.0f, 1.0f, 1.0f, -2.0f), DH_ERR_ARG);
    DHT_EQ_INT(dh_profile_quintic_f32(&p, 1.0f, 0.0f), DH_ERR_ARG);
    /* durations or peaks beyond float */
    DHT_EQ_INT(dh_profile_trap_f32(&p, FLT_MAX, 1e-30f, 1.0f), DH_ERR_OVERFLOW);
    DHT_EQ_INT(dh_profile_scurve_f32(&p, FLT_MAX, 1e-30f, 1.0f, 1.0f), DH_ERR_OVERFLOW);
    DHT_EQ_INT(dh_profile_quintic_f32(&p, FLT_MAX, 1e-20f), DH_ERR_OVERFLOW);
    UNTOUCHED(p);
    /* stretch */
    DHT_EQ_INT(dh_profile_trap_f32(&good, 1e-30f, 1.0f, 1.0f), DH_OK);
    for (k = 0; k < 4u; k++) {
        p = good;
        DHT_EQ_INT(dh_profile_stretch_f32(&p, bad_value(k)), DH_ERR_NAN);
        DHT_TRUE(memcmp(&p, &good, sizeof p) == 0);
    }
    DHT_EQ_INT(dh_profile_stretch_f32(&p, good.T * 0.5f), DH_ERR_ARG);
    DHT_EQ_INT(dh_profile_stretch_f32(&p, 1e38f), DH_ERR_OVERFLOW); /* the peaks underflow to 0 */
    DHT_TRUE(memcmp(&p, &good, sizeof p) == 0);
    /* eval */
    CANARY(pos);
    CANARY(vel);
    CANARY(acc);
    DHT_EQ_INT(dh_profile_eval_f32(&good, bad_value(0), &pos, &vel, &acc), DH_ERR_NAN);
    DHT_EQ_INT(dh_profile_eval_f32(&good, bad_value(3), &pos, &vel, &acc), DH_ERR_NAN);
    UNTOUCHED(pos);
    UNTOUCHED(vel);
    UNTOUCHED(acc);
}

static void motion_joint_move_bad(void)
{
    float q0[2] = { 0.0f, 1.0f }, q1[2] = { 1.0f, 2.0f }, vm[2] = { 1.0f, 1.0f }, am[2] = { 1.0f, 1.0f };
    float jm[2] = { 1.0f, 1.0f }, q[2], qd[2], qdd[2];
    dh_profile_f32 prof[2], good[2], zero[2];
    unsigned k;
    memset(zero, 0, sizeof zero);
    CANARY(prof);
    DHT_EQ_INT(dh_joint_move_f32(prof, 0u, q0, q1, vm, am, jm), DH_ERR_ARG);
    UNTOUCHED(prof);
    for (k = 0; k < 4u; k++) {
        q0[1] = bad_value(k);
        CANARY(prof);
        DHT_EQ_INT(dh_joint_move_f32(prof, 2u, q0, q1, vm, am, jm), DH_ERR_NAN);
        DHT_TRUE(memcmp(prof, zero, sizeof prof) == 0);
        q0[1] = 1.0f;
        jm[1] = bad_value(k);
        CANARY(prof);
        DHT_EQ_INT(dh_joint_move_f32(prof, 2u, q0, q1, vm, am, jm), DH_ERR_NAN);
        DHT_TRUE(memcmp(prof, zero, sizeof prof) == 0);
        jm[1] = 1.0f;
    }
    am[1] = 0.0f;
    CANARY(prof);
    DHT_EQ_INT(dh_joint_move_f32(prof, 2u, q0, q1, vm, am, NULL), DH_ERR_ARG);
    DHT_TRUE(memcmp(prof, zero, sizeof prof) == 0);
    am[1] = 1.0f;
    q0[1] = -FLT_MAX;
    q1[1] = FLT_MAX;
    CANARY(prof);
    DHT_EQ_INT(dh_joint_move_f32(prof, 2u, q0, q1, vm, am, jm), DH_ERR_OVERFLOW);
    DHT_TRUE(memcmp(prof, zero, sizeof prof) == 0);
    /* joint 0 moves 1e-30 while joint 1 needs 3e38: joint 0's stretched peaks underflow */
    q0[0] = 0.0f;
    q1[0] = 1e-30f;
    q0[1] = 0.0f;
    q1[1] = 3e38f;
    CANARY(prof);
    DHT_EQ_INT(dh_joint_move_f32(prof, 2u, q0, q1, vm, am, NULL), DH_ERR_OVERFLOW);
    DHT_TRUE(memcmp(prof, zero, sizeof prof) == 0);
    /* evaluating the move of a failed call keeps the joints at q0 */
    DHT_EQ_INT(dh_joint_move_eval_f32(prof, 2u, q0, q1, 0.5f, q, qd, qdd), DH_OK);
    DHT_TRUE(memcmp(q, q0, sizeof q) == 0 && qd[0] == 0.0f && qdd[1] == 0.0f);
    q1[0] = 1.0f;
    q1[1] = 2.0f;
    DHT_EQ_INT(dh_joint_move_f32(good, 2u, q0, q1, vm, am, jm), DH_OK);
    CANARY(q);
    CANARY(qd);
    CANARY(qdd);
    DHT_EQ_INT(dh_joint_move_eval_f32(good, 0u, q0, q1, 1.0f, q, qd, qdd), DH_ERR_ARG);
    DHT_EQ_INT(dh_joint_move_eval_f32(good, 2u, q0, q1, bad_value(0), q, qd, qdd), DH_ERR_NAN);
    UNTOUCHED(q);
    UNTOUCHED(qd);
    UNTOUCHED(qdd);
}

static const dht_case cases[] = {
    DHT_CASE(motion_slerp_bad),
    DHT_CASE(motion_pose_bad),
    DHT_CASE(motion_profile_bad),
    DHT_CASE(motion_joint_move_bad),
};
DHT_MAIN(cases)
