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

/* a path's frames: A at (1, 0, 0), B at (0, 1, 0), via on their circle about the origin */
static void path_frames(dh_mat4_f32 *A, dh_mat4_f32 *B, float via[3])
{
    rigid(A, 1.0f);
    rigid(B, 0.0f);
    DH_M4(B, 1, 3) = 1.0f;
    via[0] = 0.70710678f;
    via[1] = 0.70710678f;
    via[2] = 0.0f;
}

static void motion_path_bad(void)
{
    dh_mat4_f32 A, B, bad, T;
    dh_path_f32 p, good;
    float via[3], v3[3];
    unsigned k;
    path_frames(&A, &B, via);
    for (k = 0; k < 4u; k++) {
        CANARY(p);
        bad = B;
        DH_M4(&bad, 2, 1) = bad_value(k);
        DHT_EQ_INT(dh_path_line_f32(&p, &A, &bad), DH_ERR_NAN);
        DHT_EQ_INT(dh_path_arc_f32(&p, &bad, via, &B), DH_ERR_NAN);
        bad = A;
        DH_M4(&bad, 0, 3) = bad_value(k);
        DHT_EQ_INT(dh_path_line_f32(&p, &bad, &B), DH_ERR_NAN);
        DHT_EQ_INT(dh_path_arc_f32(&p, &A, via, &bad), DH_ERR_NAN);
        memcpy(v3, via, sizeof v3);
        v3[2] = bad_value(k);
        DHT_EQ_INT(dh_path_arc_f32(&p, &A, v3, &B), DH_ERR_NAN);
        UNTOUCHED(p);
    }
    bad = B;
    DH_M4(&bad, 1, 1) *= 1.001f;                /* scaled */
    DHT_EQ_INT(dh_path_line_f32(&p, &A, &bad), DH_ERR_NOT_RIGID);
    DHT_EQ_INT(dh_path_arc_f32(&p, &bad, via, &B), DH_ERR_NOT_RIGID);
    bad = A;
    DH_M4(&bad, 3, 2) = 1e-6f;                  /* bottom row */
    DHT_EQ_INT(dh_path_arc_f32(&p, &bad, via, &B), DH_ERR_NOT_RIGID);
    /* p_B - p_A, a side or the line's length overflow */
    rigid(&bad, -FLT_MAX);
    rigid(&T, FLT_MAX);
    DHT_EQ_INT(dh_path_line_f32(&p, &bad, &T), DH_ERR_OVERFLOW);
    DHT_EQ_INT(dh_path_arc_f32(&p, &bad, via, &T), DH_ERR_OVERFLOW);
    rigid(&bad, 0.0f);
    rigid(&T, 3e38f);
    DH_M4(&T, 1, 3) = 3e38f;
    DHT_EQ_INT(dh_path_line_f32(&p, &bad, &T), DH_ERR_OVERFLOW);
    v3[0] = -3e38f;                             /* via - p_B overflows */
    v3[1] = 0.0f;
    v3[2] = 0.0f;
    DHT_EQ_INT(dh_path_arc_f32(&p, &bad, v3, &T), DH_ERR_OVERFLOW);
    rigid(&bad, FLT_MAX);                       /* via - p_A overflows */
    rigid(&T, FLT_MAX);
    DH_M4(&T, 1, 3) = 1.0f;
    v3[0] = -FLT_MAX;
    DHT_EQ_INT(dh_path_arc_f32(&p, &bad, v3, &T), DH_ERR_OVERFLOW);
    /* every difference finite, a side's length beyond float: |via - p_A| 4.2e38 */
    rigid(&bad, 0.0f);
    rigid(&T, 3e38f);
    v3[0] = 3e38f;
    v3[1] = 3e38f;
    v3[2] = 0.0f;
    DHT_EQ_INT(dh_path_arc_f32(&p, &bad, v3, &T), DH_ERR_OVERFLOW);
    /* every side finite, the arc's length beyond float: the circle through
     * (0, 0), (2e38, 0), (1e38, 1.2e38) has the radius 1.0167e38, the arc
     * over its top 3.5 rad */
    rigid(&T, 2e38f);
    v3[0] = 1e38f;
    v3[1] = 1.2e38f;
    DHT_EQ_INT(dh_path_arc_f32(&p, &bad, v3, &T), DH_ERR_OVERFLOW);
    /* a hundredth of it fits: radius sqrt(1 + 0.18333^2) 1e36 */
    rigid(&T, 2e36f);
    v3[0] = 1e36f;
    v3[1] = 1.2e36f;
    DHT_EQ_INT(dh_path_arc_f32(&good, &bad, v3, &T), DH_OK);
    DHT_NEAR(good.radius / 1e36, sqrt(1.0 + (0.44 / 2.4) * (0.44 / 2.4)), 1e-5);
    /* collinear, coincident and thin: no circle */
    v3[0] = 0.5f;
    v3[1] = 0.5f;
    v3[2] = 0.0f;
    DHT_EQ_INT(dh_path_arc_f32(&p, &A, v3, &B), DH_ERR_SINGULAR);   /* on the chord */
    v3[0] = 2.0f;
    v3[1] = -1.0f;
    DHT_EQ_INT(dh_path_arc_f32(&p, &A, v3, &B), DH_ERR_SINGULAR);   /* on the line beyond A */
    v3[0] = 1.0f;
    v3[1] = 0.0f;
    DHT_EQ_INT(dh_path_arc_f32(&p, &A, v3, &B), DH_ERR_SINGULAR);   /* via == p_A */
    DHT_EQ_INT(dh_path_arc_f32(&p, &A, via, &A), DH_ERR_SINGULAR);  /* p_B == p_A */
    v3[0] = 0.5f + 3e-4f;                        /* sagitta 4.2e-4 of a chord 1.41: |a x b| < 2^-10 L^2 */
    v3[1] = 0.5f + 3e-4f;
    DHT_EQ_INT(dh_path_arc_f32(&p, &A, v3, &B), DH_ERR_SINGULAR);
    v3[0] = 0.5f + 1e-3f;                        /* sagitta 1.41e-3: a circle */
    v3[1] = 0.5f + 1e-3f;
    DHT_EQ_INT(dh_path_arc_f32(&good, &A, v3, &B), DH_OK);
    UNTOUCHED(p);
    /* eval: NaN s (Inf is clamped) */
    DHT_EQ_INT(dh_path_arc_f32(&good, &A, via, &B), DH_OK);
    CANARY(T);
    DHT_EQ_INT(dh_path_eval_f32(&good, bad_value(0), &T), DH_ERR_NAN);
    DHT_EQ_INT(dh_path_eval_f32(&good, bad_value(3), &T), DH_ERR_NAN);
    memset(&good, 0, sizeof good);              /* no constructor wrote it */
    DHT_EQ_INT(dh_path_eval_f32(&good, 0.5f, &T), DH_ERR_ARG);
    DHT_EQ_INT(dh_path_eval_f32(&good, 0.0f, &T), DH_ERR_ARG);
    UNTOUCHED(T);
}

/* lim with its limit i (vmax, amax, wmax, wdmax) set to x */
static dh_cart_limits_f32 lim_with(dh_cart_limits_f32 lim, unsigned i, float x)
{
    switch (i) {
    case 0u: lim.vmax = x; break;
    case 1u: lim.amax = x; break;
    case 2u: lim.wmax = x; break;
    default: lim.wdmax = x; break;
    }
    return lim;
}

static void motion_path_move_bad(void)
{
    static const dh_profile_f32 zero;
    dh_mat4_f32 A, B, T;
    dh_path_f32 p;
    dh_profile_f32 prof;
    dh_cart_limits_f32 lim = { 1.0f, 1.0f, 1.0f, 1.0f }, l;
    float via[3], v;
    unsigned k, i;
    path_frames(&A, &B, via);
    DHT_EQ_INT(dh_path_arc_f32(&p, &A, via, &B), DH_OK);
    for (k = 0; k < 4u; k++) {
        for (i = 0; i < 4u; i++) {
            l = lim_with(lim, i, bad_value(k));
            CANARY(prof);
            DHT_EQ_INT(dh_path_move_f32(&prof, &p, &l), DH_ERR_NAN);
            DHT_TRUE(memcmp(&prof, &zero, sizeof prof) == 0);
        }
    }
    for (i = 0; i < 4u; i++) {
        l = lim_with(lim, i, (i & 1u) ? -1.0f : 0.0f);
        CANARY(prof);
        DHT_EQ_INT(dh_path_move_f32(&prof, &p, &l), DH_ERR_ARG);
        DHT_TRUE(memcmp(&prof, &zero, sizeof prof) == 0);
    }
    /* 1e-30 / length underflows; the duration overflows */
    l = lim;
    l.vmax = 1e-30f;
    l.amax = 1e-30f;
    rigid(&B, 3e38f);
    DHT_EQ_INT(dh_path_line_f32(&p, &A, &B), DH_OK);
    CANARY(prof);
    DHT_EQ_INT(dh_path_move_f32(&prof, &p, &l), DH_ERR_OVERFLOW);
    DHT_TRUE(memcmp(&prof, &zero, sizeof prof) == 0);
    l.vmax = 1e-20f;
    l.amax = 1e20f;
    rigid(&B, 1e20f);
    DHT_EQ_INT(dh_path_line_f32(&p, &A, &B), DH_OK);
    CANARY(prof);
    DHT_EQ_INT(dh_path_move_f32(&prof, &p, &l), DH_ERR_OVERFLOW);
    DHT_TRUE(memcmp(&prof, &zero, sizeof prof) == 0);
    /* the move of a failed call keeps the frame at A */
    DHT_EQ_INT(dh_path_move_eval_f32(&prof, &p, 0.5f, &T, &v), DH_OK);
    DHT_TRUE(memcmp(&T, &A, sizeof T) == 0 && v == 0.0f);
    DHT_EQ_INT(dh_path_move_f32(&prof, &p, &lim), DH_OK);
    CANARY(T);
    CANARY(v);
    DHT_EQ_INT(dh_path_move_eval_f32(&prof, &p, bad_value(0), &T, &v), DH_ERR_NAN);
    memset(&p, 0, sizeof p);                    /* no constructor wrote it */
    DHT_EQ_INT(dh_path_move_eval_f32(&prof, &p, 0.5f, &T, &v), DH_ERR_ARG);
    UNTOUCHED(T);
    UNTOUCHED(v);
}

static const dht_case cases[] = {
    DHT_CASE(motion_slerp_bad),
    DHT_CASE(motion_pose_bad),
    DHT_CASE(motion_profile_bad),
    DHT_CASE(motion_joint_move_bad),
    DHT_CASE(motion_path_bad),
    DHT_CASE(motion_path_move_bad),
};
DHT_MAIN(cases)
