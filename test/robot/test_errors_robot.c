/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_errors_robot.c - bad input to the robot description and forward
 * kinematics (docs/errors.md, section robot.h).
 *
 * Robots with 0 joints, a full robot, a description whose n field is beyond
 * DH_MAX_JOINTS (a corrupted or foreign struct), unknown enum values,
 * NaN/Inf parameters and joint values, limits, prismatic joints beyond
 * limits and beyond the representable range, constants that do not fit the
 * fixed path. Outputs are pre-filled with a canary and checked untouched
 * (or equal to the documented value). References: test/support_robots.c
 * (double DH chains built from the elementary matrices).
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_canary.h"
#include "support_robots.h"
#include "dhmath/frame.h"
#include "dhmath/mat4.h"
#include "dhmath/robot.h"


/* NaN, +Inf, -Inf and a negative NaN payload variant */
static float bad_value_nan(unsigned k)
{
    static const uint32_t b[4] = { 0x7FC00000u, 0x7F800000u, 0xFF800000u, 0xFFC00001u };
    return f32_bits(b[k & 3u]);
}

/* a 3-joint robot R-P-R in metres with limits on every joint */
static void small_robot(dh_robot *r, dh_convention conv)
{
    DHT_EQ_INT(dh_robot_init(r, conv), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(r, DH_JOINT_REVOLUTE, 0.0f, 0.1f, 0.3f, 90.0f), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(r, DH_JOINT_PRISMATIC, 10.0f, 0.2f, 0.0f, -90.0f), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(r, DH_JOINT_REVOLUTE, 5.0f, 0.0f, 0.25f, 0.0f), DH_OK);
    DHT_EQ_INT(dh_robot_set_limits_f32(r, 0, -170.0f, 170.0f), DH_OK);
    DHT_EQ_INT(dh_robot_set_limits_f32(r, 1, 0.0f, 0.5f), DH_OK);
    DHT_EQ_INT(dh_robot_set_limits_f32(r, 2, -120.0f, 120.0f), DH_OK);
}

/* init: unknown convention -> ARG, r untouched */
static void robot_init_bad_conv(void)
{
    dh_robot r;
    CANARY(r);
    DHT_EQ_INT(dh_robot_init(&r, (dh_convention)2), DH_ERR_ARG);
    UNTOUCHED(r);
    DHT_EQ_INT(dh_robot_init(&r, (dh_convention)-1), DH_ERR_ARG);
    UNTOUCHED(r);
}

/* adding joints: full robot, unknown type, NaN/Inf parameters -> error,
 * r untouched (byte for byte) */
static void robot_add_joint_bad(void)
{
    dh_robot r, copy;
    unsigned i, k, pos;
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    copy = r;
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, (dh_joint_type)2, 0.0f, 0.0f, 0.1f, 0.0f), DH_ERR_ARG);
    DHT_EQ_INT(dh_robot_add_joint_q(&r, (dh_joint_type)-1, 0, 0, 0, 0), DH_ERR_ARG);
    DHT_TRUE(memcmp(&r, &copy, sizeof r) == 0);
    for (pos = 0; pos < 4; pos++) {
        for (k = 0; k < 4; k++) {
            float p[4] = { 0.1f, 0.2f, 30.0f, 40.0f };
            p[pos] = bad_value_nan(k);
            DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_PRISMATIC, p[3], p[1], p[0], p[2]), DH_ERR_NAN);
            DHT_TRUE(memcmp(&r, &copy, sizeof r) == 0);
        }
    }
    /* fill to capacity, then one more (both builders) */
    for (i = 0; i < (unsigned)DH_MAX_JOINTS; i++)
        DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0.0f, 0.0f, 0.1f, 0.0f), DH_OK);
    DHT_EQ_INT(r.n, DH_MAX_JOINTS);
    copy = r;
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0.0f, 0.0f, 0.1f, 0.0f), DH_ERR_ARG);
    DHT_EQ_INT(dh_robot_add_joint_q(&r, DH_JOINT_REVOLUTE, 0, 0, 1, 0), DH_ERR_ARG);
    /* the parameters are tested first: NaN on a full robot is DH_ERR_NAN */
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0.0f, bad_value_nan(0), 0.1f, 0.0f), DH_ERR_NAN);
    DHT_TRUE(memcmp(&r, &copy, sizeof r) == 0);
}

/* Constants that do not fit the fixed path: the joint is added, the fixed
 * path is marked unavailable (dh_fk_q -> UNAVAILABLE, T untouched), the float
 * path is unaffected and correct. */
static void robot_unrepresentable_fixed_constants(void)
{
    const float big = (float)ldexp(1.0, 31 - DH_QPOS_FRAC); /* first length beyond dh_qpos */
    static const float angs[] = { 32768.0f, -32768.5f, 1e30f };
    unsigned k;
    for (k = 0; k < 5; k++) {
        dh_robot r;
        dh_frame_q Tq;
        dh_mat4_f32 T;
        int32_t qq[2] = { 0, 0 };
        float q[2] = { 10.0f, 20.0f };
        double qd[2] = { 10.0, 20.0 };
        dhr_mat4 R;
        DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
        DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0.0f, 0.0f, 1.0f, 0.0f), DH_OK);
        if (k == 0) DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0.0f, 0.0f, big, 0.0f), DH_OK);
        else if (k == 1) DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0.0f, -big * 2.0f, 0.0f, 0.0f), DH_OK);
        else DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, (k >= 3) ? angs[k - 2] : 0.0f, 0.0f,
                                               0.5f, (k == 2) ? angs[0] : 0.0f),
                        DH_OK);
        DHT_EQ_INT(r.n, 2);
        DHT_TRUE((r.flags & DH_ROBOT_HAS_Q) == 0u);
        DHT_TRUE((r.flags & DH_ROBOT_Q_NO_JOINT) != 0u);
        DHT_TRUE((r.flags & DH_ROBOT_HAS_F32) != 0u);
        CANARY(Tq);
        DHT_EQ_INT(dh_fk_q(&r, qq, &Tq), DH_ERR_UNAVAILABLE);
        UNTOUCHED(Tq);
        DHT_EQ_INT(dh_link_q(&r, 0, 0, &Tq), DH_ERR_UNAVAILABLE);
        UNTOUCHED(Tq);
        {
            dh_frame_q frames[2];
            CANARY(frames);
            DHT_EQ_INT(dh_fk_frames_q(&r, qq, frames, &Tq), DH_ERR_UNAVAILABLE);
            UNTOUCHED(frames);
            UNTOUCHED(Tq);
        }
        /* float path: q = 0 on joint 1 so that the float sum q + theta is
         * theta itself; the reference gets theta reduced exactly (a double
         * of 1e30 degrees cannot be converted to radians accurately) */
        q[1] = 0.0f;
        qd[1] = 0.0;
        DHT_EQ_INT(dh_fk_f32(&r, q, &T), DH_OK);
        {
            dh_robot r2 = r;
            r2.joint[1].theta_deg = (float)fmod((double)r.joint[1].theta_deg, 360.0);
            dhs_fk_ref_f32(&r2, qd, NULL, &R);
        }
        /* 3e-7 relative to the reach (docs/accuracy_fk.md) */
        DHT_TRUE(dhs_pos_err_f32(&T, &R) <= 3e-7 * (1.5 + fabs((double)r.joint[1].a) + fabs((double)r.joint[1].d)));
        DHT_TRUE(dhs_rot_err_f32(&T, &R) <= 3.1e-7);
    }
}

/* limits: i >= n -> ARG, NaN/Inf -> NAN, qmin > qmax -> ARG, r untouched;
 * limits beyond the Q range saturate the fixed-path limits */
static void robot_set_limits_bad(void)
{
    dh_robot r, copy;
    unsigned k;
    small_robot(&r, DH_CONV_STANDARD);
    copy = r;
    DHT_EQ_INT(dh_robot_set_limits_f32(&r, 3, -1.0f, 1.0f), DH_ERR_ARG);
    DHT_EQ_INT(dh_robot_set_limits_f32(&r, 0xFFFFFFFFu, -1.0f, 1.0f), DH_ERR_ARG);
    DHT_EQ_INT(dh_robot_set_limits_f32(&r, 0, 1.0f, -1.0f), DH_ERR_ARG);
    DHT_EQ_INT(dh_robot_set_limits_q(&r, 3, -1, 1), DH_ERR_ARG);
    DHT_EQ_INT(dh_robot_set_limits_q(&r, 1, 2, 1), DH_ERR_ARG);
    for (k = 0; k < 4; k++) {
        DHT_EQ_INT(dh_robot_set_limits_f32(&r, 1, bad_value_nan(k), 1.0f), DH_ERR_NAN);
        DHT_EQ_INT(dh_robot_set_limits_f32(&r, 1, -1.0f, bad_value_nan(k)), DH_ERR_NAN);
    }
    DHT_TRUE(memcmp(&r, &copy, sizeof r) == 0);
    /* beyond the Q range: saturated fixed limits */
    DHT_EQ_INT(dh_robot_set_limits_f32(&r, 0, -1e9f, 1e9f), DH_OK);
    DHT_EQ_INT(r.joint[0].qmin_q, INT32_MIN);
    DHT_EQ_INT(r.joint[0].qmax_q, INT32_MAX);
    DHT_EQ_INT(dh_robot_set_limits_f32(&r, 1, -FLT_MAX, 40000.0f), DH_OK);
    DHT_EQ_INT(r.joint[1].qmin_q, INT32_MIN);
    DHT_EQ_INT(r.joint[1].qmax_q, (40000.0 * ldexp(1.0, DH_QPOS_FRAC) >= 2147483648.0)
                                      ? INT32_MAX : (int32_t)(40000.0 * ldexp(1.0, DH_QPOS_FRAC)));
}

/* rate limits: i >= n or <= 0 -> ARG, NaN -> NAN, r untouched; +inf is
 * unlimited (INT32_MAX); finite values round to nearest, clamp to [1,
 * INT32_MAX - 1]; the fixed setter's float copy is the value / 2^frac
 * rounded to nearest (checked against double) */
static void robot_set_rates_bad_and_exact(void)
{
    dh_robot r, copy;
    const float inf = f32_bits(0x7F800000u);
    int32_t k;
    small_robot(&r, DH_CONV_STANDARD);
    copy = r;
    DHT_EQ_INT(dh_robot_set_rates_f32(&r, 3, 1.0f, 1.0f), DH_ERR_ARG);
    DHT_EQ_INT(dh_robot_set_rates_f32(&r, 0, 0.0f, 1.0f), DH_ERR_ARG);
    DHT_EQ_INT(dh_robot_set_rates_f32(&r, 0, 1.0f, -2.0f), DH_ERR_ARG);
    DHT_EQ_INT(dh_robot_set_rates_f32(&r, 0, -inf, 1.0f), DH_ERR_ARG);
    DHT_EQ_INT(dh_robot_set_rates_f32(&r, 0, bad_value_nan(0), 1.0f), DH_ERR_NAN);
    DHT_EQ_INT(dh_robot_set_rates_f32(&r, 0, 1.0f, bad_value_nan(3)), DH_ERR_NAN);
    DHT_EQ_INT(dh_robot_set_rates_q(&r, 3, 1, 1), DH_ERR_ARG);
    DHT_EQ_INT(dh_robot_set_rates_q(&r, 0, 0, 1), DH_ERR_ARG);
    DHT_EQ_INT(dh_robot_set_rates_q(&r, 0, 1, INT32_MIN), DH_ERR_ARG);
    DHT_TRUE(memcmp(&r, &copy, sizeof r) == 0);
    /* defaults: unlimited on both paths */
    DHT_TRUE(r.joint[2].vmax == inf && r.joint[2].amax == inf);
    DHT_EQ_INT(r.joint[2].vmax_q, INT32_MAX);
    DHT_EQ_INT(r.joint[2].amax_q, INT32_MAX);
    DHT_EQ_INT(dh_robot_set_rates_f32(&r, 0, 180.0f, inf), DH_OK);
    DHT_EQ_INT(r.joint[0].vmax_q, 180 * 65536);
    DHT_EQ_INT(r.joint[0].amax_q, INT32_MAX);
    DHT_EQ_INT(dh_robot_set_rates_f32(&r, 1, 1e-30f, 1e30f), DH_OK); /* prismatic */
    DHT_EQ_INT(r.joint[1].vmax_q, 1);
    DHT_EQ_INT(r.joint[1].amax_q, INT32_MAX - 1);
    DHT_EQ_INT(dh_robot_set_rates_f32(&r, 2, 0.25f, 32767.0f), DH_OK);
    DHT_EQ_INT(r.joint[2].vmax_q, 16384);
    DHT_EQ_INT(r.joint[2].amax_q, 32767 * 65536);
    DHT_EQ_INT(dh_robot_check(&r), DH_OK);
    /* fixed setter: float copies against double, every bit length */
    for (k = 1; k > 0 && k < INT32_MAX; k = (k < 0x40000000) ? k * 2 + (k & 5) : INT32_MAX - 1) {
        const int32_t vals[3] = { k, k < INT32_MAX - 1 ? k + 1 : k, (int32_t)((uint32_t)k | 0x55u) == INT32_MAX ? k : (int32_t)((uint32_t)k | 0x55u) };
        unsigned m;
        for (m = 0; m < 3u; m++) {
            DHT_EQ_INT(dh_robot_set_rates_q(&r, 2, vals[m], INT32_MAX), DH_OK);
            DHT_TRUE_MSG(r.joint[2].vmax == (float)ldexp((double)vals[m], -16), "vmax_q %ld: %a", (long)vals[m],
                         (double)r.joint[2].vmax);
            DHT_TRUE(r.joint[2].amax == inf);
            DHT_EQ_INT(dh_robot_set_rates_q(&r, 1, 3, vals[m]), DH_OK);
            DHT_TRUE_MSG(r.joint[1].amax == (float)ldexp((double)vals[m], -DH_QPOS_FRAC), "amax_q %ld: %a",
                         (long)vals[m], (double)r.joint[1].amax);
            DHT_EQ_INT(dh_robot_check(&r), DH_OK);
        }
        if (k == INT32_MAX - 1) break;
    }
}

/* base/tool: NaN/Inf -> NAN, bottom row not 0 0 0 1 -> NOT_RIGID, r
 * untouched; not representable in Q -> OK with the fixed path off */
static void robot_base_tool_bad(void)
{
    dh_robot r, copy;
    dh_mat4_f32 B;
    unsigned e, k;
    small_robot(&r, DH_CONV_MODIFIED);
    copy = r;
    for (e = 0; e < 16; e++) {
        for (k = 0; k < 4; k++) {
            dh_mat4_identity_f32(&B);
            B.m[e / 4][e % 4] = bad_value_nan(k);
            DHT_EQ_INT(dh_robot_set_base_f32(&r, &B), DH_ERR_NAN);
            DHT_EQ_INT(dh_robot_set_tool_f32(&r, &B), DH_ERR_NAN);
        }
    }
    for (e = 0; e < 4; e++) {
        dh_mat4_identity_f32(&B);
        B.m[e][3] = (e == 3) ? 1.0000001f : -1e-38f;
        DHT_EQ_INT(dh_robot_set_base_f32(&r, &B), DH_ERR_NOT_RIGID);
        DHT_EQ_INT(dh_robot_set_tool_f32(&r, &B), DH_ERR_NOT_RIGID);
    }
    DHT_TRUE(memcmp(&r, &copy, sizeof r) == 0);
    /* not representable: rotation entry 2.0, position beyond dh_qpos */
    dh_mat4_scale_f32(2.0f, 1.0f, 1.0f, &B);
    DHT_EQ_INT(dh_robot_set_base_f32(&r, &B), DH_OK);
    DHT_TRUE((r.flags & DH_ROBOT_HAS_Q) == 0u && (r.flags & DH_ROBOT_Q_NO_BASE) != 0u);
    DHT_TRUE((r.flags & DH_ROBOT_HAS_F32) != 0u);
    dh_mat4_trans_f32(0.0f, (float)ldexp(1.0, 32 - DH_QPOS_FRAC), 0.0f, &B);
    DHT_EQ_INT(dh_robot_set_tool_f32(&r, &B), DH_OK);
    DHT_TRUE((r.flags & DH_ROBOT_Q_NO_TOOL) != 0u);
    {
        dh_frame_q T;
        int32_t q[3] = { 0, 0, 0 };
        CANARY(T);
        DHT_EQ_INT(dh_fk_q(&r, q, &T), DH_ERR_UNAVAILABLE);
        UNTOUCHED(T);
    }
    /* setting representable frames again restores the fixed path */
    dh_mat4_identity_f32(&B);
    DHT_EQ_INT(dh_robot_set_base_f32(&r, &B), DH_OK);
    DHT_EQ_INT(dh_robot_set_tool_f32(&r, &B), DH_OK);
    DHT_TRUE((r.flags & DH_ROBOT_HAS_Q) != 0u);
}

/* limit checks: NaN first (even on a joint without limits), then LIMIT;
 * prismatic joints beyond their limits */
static void robot_check_limits_bad(void)
{
    dh_robot r;
    unsigned k;
    float q[3] = { 0.0f, 0.25f, 0.0f };
    int32_t qq[3] = { 0, 0, 0 };
    small_robot(&r, DH_CONV_STANDARD);
    DHT_EQ_INT(dh_robot_check_limits_f32(&r, q), DH_OK);
    q[1] = 0.5000001f;                           /* prismatic just beyond */
    DHT_EQ_INT(dh_robot_check_limits_f32(&r, q), DH_ERR_LIMIT);
    q[1] = -1e-30f;
    DHT_EQ_INT(dh_robot_check_limits_f32(&r, q), DH_ERR_LIMIT);
    q[1] = 0.5f;                                 /* on the limit: inside */
    DHT_EQ_INT(dh_robot_check_limits_f32(&r, q), DH_OK);
    q[0] = 1e30f;
    DHT_EQ_INT(dh_robot_check_limits_f32(&r, q), DH_ERR_LIMIT);
    q[0] = 0.0f;
    for (k = 0; k < 4; k++) {
        q[2] = bad_value_nan(k);
        q[1] = 7.0f; /* also out of limits: NaN is reported first */
        DHT_EQ_INT(dh_robot_check_limits_f32(&r, q), DH_ERR_NAN);
    }
    /* a joint without limits still rejects NaN */
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_PRISMATIC, 0.0f, 0.0f, 0.0f, 0.0f), DH_OK);
    q[0] = bad_value_nan(0);
    DHT_EQ_INT(dh_robot_check_limits_f32(&r, q), DH_ERR_NAN);
    q[0] = -FLT_MAX;
    DHT_EQ_INT(dh_robot_check_limits_f32(&r, q), DH_OK);
    /* fixed limits */
    small_robot(&r, DH_CONV_STANDARD);
    qq[1] = (int32_t)(0.5 * ldexp(1.0, DH_QPOS_FRAC)) + 1;
    DHT_EQ_INT(dh_robot_check_limits_q(&r, qq), DH_ERR_LIMIT);
    qq[1] = 0;
    qq[0] = INT32_MIN;
    DHT_EQ_INT(dh_robot_check_limits_q(&r, qq), DH_ERR_LIMIT);
    qq[0] = 170 * 65536;
    DHT_EQ_INT(dh_robot_check_limits_q(&r, qq), DH_OK);
    DHT_EQ_INT(dh_robot_set_limits_q(&r, 0, INT32_MIN, INT32_MAX), DH_OK);
    qq[0] = INT32_MIN;
    DHT_EQ_INT(dh_robot_check_limits_q(&r, qq), DH_OK);
}

/* float FK: n == 0 -> ARG; NaN/Inf q -> NAN; q + offset overflowing ->
 * OVERFLOW (T untouched); float path unavailable -> UNAVAILABLE; huge prismatic
 * values whose frame is not finite -> OVERFLOW with T written */
/* twin: robot_fk_q_bad */
static void robot_fk_f32_bad(void)
{
    dh_robot r;
    dh_mat4_f32 T, A, frames[3];
    float q[3] = { 10.0f, 0.1f, -20.0f };
    unsigned k, j;
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    CANARY(T);
    DHT_EQ_INT(dh_fk_f32(&r, q, &T), DH_ERR_ARG);
    UNTOUCHED(T);
    CANARY(frames);
    DHT_EQ_INT(dh_fk_frames_f32(&r, q, frames, &T), DH_ERR_ARG);
    UNTOUCHED(frames);
    UNTOUCHED(T);
    DHT_EQ_INT(dh_link_f32(&r, 0, 0.0f, &A), DH_ERR_ARG);
    for (j = 0; j < 2; j++) {
        small_robot(&r, j ? DH_CONV_MODIFIED : DH_CONV_STANDARD);
        for (k = 0; k < 3 * 4; k++) {
            float qb[3] = { 10.0f, 0.1f, -20.0f };
            qb[k / 4] = bad_value_nan(k);
            CANARY(T);
            DHT_EQ_INT(dh_fk_f32(&r, qb, &T), DH_ERR_NAN);
            UNTOUCHED(T);
            CANARY(frames);
            DHT_EQ_INT(dh_fk_frames_f32(&r, qb, frames, &T), DH_ERR_NAN);
            UNTOUCHED(frames);
            UNTOUCHED(T);
            CANARY(A);
            DHT_EQ_INT(dh_link_f32(&r, k / 4, qb[k / 4], &A), DH_ERR_NAN);
            UNTOUCHED(A);
        }
        /* q + offset overflows to infinity (theta offset 5, d offset 0.2) */
        q[0] = 10.0f; q[1] = FLT_MAX; q[2] = 0.0f;
        r.joint[1].d = FLT_MAX; /* offset of the prismatic joint */
        CANARY(T);
        DHT_EQ_INT(dh_fk_f32(&r, q, &T), DH_ERR_OVERFLOW);
        UNTOUCHED(T);
        CANARY(A);
        DHT_EQ_INT(dh_link_f32(&r, 1, q[1], &A), DH_ERR_OVERFLOW);
        UNTOUCHED(A);
        r.joint[1].d = 0.2f;
        q[1] = 0.1f;
        q[2] = -FLT_MAX;
        r.joint[2].theta_deg = -FLT_MAX;
        DHT_EQ_INT(dh_fk_f32(&r, q, &T), DH_ERR_OVERFLOW);
        UNTOUCHED(T);
        r.joint[2].theta_deg = 5.0f;
        /* huge prismatic value: finite sum, non-finite frame (through a
         * scaling base, allowed) -> OVERFLOW, T written */
        {
            dh_mat4_f32 S;
            dh_mat4_scale_f32(4.0f, 4.0f, 4.0f, &S);
            DHT_EQ_INT(dh_robot_set_base_f32(&r, &S), DH_OK);
        }
        q[1] = 3e38f;
        q[2] = 0.0f;
        DHT_EQ_INT(dh_fk_f32(&r, q, &T), DH_ERR_OVERFLOW);
        DHT_TRUE(!is_canary(&T, sizeof T));
        DHT_EQ_INT(dh_mat4_check_finite_f32(&T), DH_ERR_NAN);
        DHT_EQ_F32_BITS(DH_M4(&T, 3, 3), 1.0f);
        DHT_EQ_INT(dh_fk_frames_f32(&r, q, frames, NULL), DH_ERR_OVERFLOW);
        DHT_EQ_INT(dh_fk_frames_f32(&r, q, frames, &T), DH_ERR_OVERFLOW);
        {
            dh_mat4_f32 I;
            dh_mat4_identity_f32(&I);
            DHT_EQ_INT(dh_robot_set_base_f32(&r, &I), DH_OK);
        }
        /* huge but finite revolute angles are fine (exact reduction) */
        {
            float qh[3] = { 1e30f, 0.25f, -3e38f };
            double qd[3];
            dhr_mat4 R;
            /* the reference reduces the float sums q + theta exactly */
            qd[0] = fmod((double)(qh[0] + r.joint[0].theta_deg), 360.0) - (double)r.joint[0].theta_deg;
            qd[1] = 0.25;
            qd[2] = fmod((double)(qh[2] + r.joint[2].theta_deg), 360.0) - (double)r.joint[2].theta_deg;
            DHT_EQ_INT(dh_fk_f32(&r, qh, &T), DH_OK);
            dhs_fk_ref_f32(&r, qd, NULL, &R);
            DHT_TRUE(dhs_pos_err_f32(&T, &R) <= 3e-7);
            DHT_TRUE(dhs_rot_err_f32(&T, &R) <= 3.1e-7);
        }
        /* link index beyond n */
        CANARY(A);
        DHT_EQ_INT(dh_link_f32(&r, 3, 0.0f, &A), DH_ERR_ARG);
        UNTOUCHED(A);
    }
    /* float path unavailable: a joint added with _q, or a base set with _q */
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_q(&r, DH_JOINT_REVOLUTE, 0, 0, DH_QPOS_ONE, 0), DH_OK);
    q[0] = 0.0f;
    CANARY(T);
    DHT_EQ_INT(dh_fk_f32(&r, q, &T), DH_ERR_UNAVAILABLE);
    UNTOUCHED(T);
    DHT_EQ_INT(dh_link_f32(&r, 0, 0.0f, &A), DH_ERR_UNAVAILABLE);
    small_robot(&r, DH_CONV_STANDARD);
    {
        dh_frame_q F;
        dh_frame_trans_q(DH_QPOS_ONE, 0, 0, &F);
        DHT_EQ_INT(dh_robot_set_base_q(&r, &F), DH_OK);
        DHT_EQ_INT(dh_robot_set_tool_q(&r, &F), DH_OK);
    }
    DHT_TRUE((r.flags & DH_ROBOT_HAS_F32) == 0u);
    q[0] = 0.0f; q[1] = 0.0f; q[2] = 0.0f;
    DHT_EQ_INT(dh_fk_f32(&r, q, &T), DH_ERR_UNAVAILABLE);
    UNTOUCHED(T);
}

/* fixed FK: n == 0 -> ARG; saturation of d + q and of positions ->
 * OVERFLOW with T written (saturated); every int32 revolute value is fine */
/* twin: robot_fk_f32_bad */
static void robot_fk_q_bad(void)
{
    dh_robot r;
    dh_frame_q T, A, frames[3];
    int32_t q[3] = { 0, 0, 0 };
    unsigned k;
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_MODIFIED), DH_OK);
    CANARY(T);
    DHT_EQ_INT(dh_fk_q(&r, q, &T), DH_ERR_ARG);
    UNTOUCHED(T);
    CANARY(frames);
    DHT_EQ_INT(dh_fk_frames_q(&r, q, frames, &T), DH_ERR_ARG);
    UNTOUCHED(frames);
    UNTOUCHED(T);
    DHT_EQ_INT(dh_link_q(&r, 0, 0, &A), DH_ERR_ARG);
    for (k = 0; k < 2; k++) {
        small_robot(&r, k ? DH_CONV_MODIFIED : DH_CONV_STANDARD);
        CANARY(A);
        DHT_EQ_INT(dh_link_q(&r, 3, 0, &A), DH_ERR_ARG);
        UNTOUCHED(A);
        /* prismatic q = INT32_MAX: d + q saturates */
        q[0] = 0; q[1] = INT32_MAX; q[2] = 0;
        CANARY(A);
        DHT_EQ_INT(dh_link_q(&r, 1, q[1], &A), DH_ERR_OVERFLOW);
        /* A written with d = INT32_MAX: standard p = (a c, a s, d), modified
         * with alpha = -90 p = (a, -sa d, ca d) = (0, d, 0) */
        DHT_EQ_INT(k ? A.p[1] : A.p[2], INT32_MAX);
        CANARY(T);
        DHT_EQ_INT(dh_fk_q(&r, q, &T), DH_ERR_OVERFLOW);
        DHT_TRUE(!is_canary(&T, sizeof T));
        DHT_EQ_INT(dh_fk_frames_q(&r, q, frames, NULL), DH_ERR_OVERFLOW);
        /* negative side: offset -1 + INT32_MIN saturates; offset +0.2 +
         * INT32_MIN fits and is accepted */
        q[1] = INT32_MIN;
        DHT_EQ_INT(dh_fk_q(&r, q, &T), DH_OK);
        r.joint[1].d_q = -DH_QPOS_ONE;
        DHT_EQ_INT(dh_fk_q(&r, q, &T), DH_ERR_OVERFLOW);
        r.joint[1].d_q = (int32_t)(0.2 * ldexp(1.0, DH_QPOS_FRAC) + 0.5);
        /* every revolute int32 (incl. INT32_MIN) vs the double reference */
        {
            static const int32_t ext[] = { INT32_MIN, INT32_MAX, -1, 0x12345678 };
            unsigned i;
            for (i = 0; i < 4; i++) {
                dhr_mat4 R;
                q[0] = ext[i]; q[1] = (int32_t)(0.3 * ldexp(1.0, DH_QPOS_FRAC)); q[2] = ext[3 - i];
                DHT_EQ_INT(dh_fk_q(&r, q, &T), DH_OK);
                dhs_fk_ref_q(&r, q, NULL, &R);
                DHT_TRUE(dhs_pos_err_q(&T, &R) <= 4.0 * ldexp(1.0, -DH_QPOS_FRAC));
                DHT_TRUE(dhs_rot_err_q(&T, &R) <= 8.0 * ldexp(1.0, -30));
            }
        }
    }
}

/* a description whose n is beyond DH_MAX_JOINTS (corrupted, or built for a
 * larger DH_MAX_JOINTS): every function that walks the joints reports
 * DH_ERR_ARG without reading past joint[], outputs untouched */
static void robot_n_beyond_capacity(void)
{
    dh_robot r, copy;
    dh_mat4_f32 T, frames[DH_MAX_JOINTS + 1];
    dh_frame_q F, framesq[DH_MAX_JOINTS + 1];
    float q[DH_MAX_JOINTS + 1];
    int32_t qq[DH_MAX_JOINTS + 1];
    unsigned i;
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    for (i = 0; i < (unsigned)DH_MAX_JOINTS; i++) {
        DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0.0f, 0.0f, 0.1f, 0.0f), DH_OK);
        DHT_EQ_INT(dh_robot_set_limits_f32(&r, i, -10.0f, 10.0f), DH_OK);
    }
    for (i = 0; i < (unsigned)DH_MAX_JOINTS + 1u; i++) {
        q[i] = 0.0f;
        qq[i] = 0;
    }
    r.n = (uint32_t)DH_MAX_JOINTS + 1u;
    copy = r;
    CANARY(T);
    DHT_EQ_INT(dh_fk_f32(&r, q, &T), DH_ERR_ARG);
    UNTOUCHED(T);
    CANARY(frames);
    DHT_EQ_INT(dh_fk_frames_f32(&r, q, frames, &T), DH_ERR_ARG);
    UNTOUCHED(frames);
    DHT_EQ_INT(dh_link_f32(&r, DH_MAX_JOINTS, 0.0f, &T), DH_ERR_ARG);
    UNTOUCHED(T);
    CANARY(F);
    DHT_EQ_INT(dh_fk_q(&r, qq, &F), DH_ERR_ARG);
    UNTOUCHED(F);
    CANARY(framesq);
    DHT_EQ_INT(dh_fk_frames_q(&r, qq, framesq, &F), DH_ERR_ARG);
    UNTOUCHED(framesq);
    DHT_EQ_INT(dh_link_q(&r, DH_MAX_JOINTS, 0, &F), DH_ERR_ARG);
    UNTOUCHED(F);
    DHT_EQ_INT(dh_robot_check_limits_f32(&r, q), DH_ERR_ARG);
    DHT_EQ_INT(dh_robot_check_limits_q(&r, qq), DH_ERR_ARG);
    DHT_EQ_INT(dh_robot_set_limits_f32(&r, DH_MAX_JOINTS, -1.0f, 1.0f), DH_ERR_ARG);
    DHT_EQ_INT(dh_robot_set_limits_q(&r, DH_MAX_JOINTS, -1, 1), DH_ERR_ARG);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0.0f, 0.0f, 0.1f, 0.0f), DH_ERR_ARG);
    DHT_EQ_INT(dh_robot_add_joint_q(&r, DH_JOINT_REVOLUTE, 0, 0, 1, 0), DH_ERR_ARG);
    /* the parameters are tested first: NaN on a full robot is DH_ERR_NAN */
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0.0f, bad_value_nan(0), 0.1f, 0.0f), DH_ERR_NAN);
    DHT_TRUE(memcmp(&r, &copy, sizeof r) == 0);
}

/* the flags of an empty description */
#define INIT_FLAGS (DH_ROBOT_HAS_F32 | DH_ROBOT_HAS_Q | DH_ROBOT_BASE_ID_F32 | DH_ROBOT_TOOL_ID_F32 | \
                    DH_ROBOT_BASE_ID_Q | DH_ROBOT_TOOL_ID_Q | DH_ROBOT_BASE_SMALL_Q)

/* every field of an empty description (dh_robot_init) */
static void check_empty(const dh_robot *r, dh_convention conv)
{
    unsigned i, c, k;
    DHT_EQ_INT(r->conv, conv);
    DHT_EQ_INT(r->n, 0);
    DHT_EQ_INT(r->flags, INIT_FLAGS);
    for (i = 0; i < (unsigned)DH_MAX_JOINTS; i++) {
        const dh_joint *j = &r->joint[i];
        DHT_EQ_INT(j->type, DH_JOINT_REVOLUTE);
        DHT_EQ_F32_BITS(j->a, 0.0f);
        DHT_EQ_F32_BITS(j->d, 0.0f);
        DHT_EQ_F32_BITS(j->alpha_deg, 0.0f);
        DHT_EQ_F32_BITS(j->theta_deg, 0.0f);
        DHT_EQ_F32_BITS(j->qmin, 1.0f);
        DHT_EQ_F32_BITS(j->qmax, 0.0f); /* no limits: qmin 1 > qmax 0 */
        DHT_EQ_F32_BITS(j->sa, 0.0f);
        DHT_EQ_F32_BITS(j->ca, 1.0f);
        DHT_EQ_INT(j->a_q, 0);
        DHT_EQ_INT(j->d_q, 0);
        DHT_EQ_INT(j->alpha_q, 0);
        DHT_EQ_INT(j->theta_q, 0);
        DHT_EQ_INT(j->sa_q, 0);
        DHT_EQ_INT(j->ca_q, DH_Q30_ONE);
        DHT_EQ_INT(j->qmin_q, 1);
        DHT_EQ_INT(j->qmax_q, 0);
    }
    for (c = 0; c < 4; c++) {
        for (k = 0; k < 4; k++) {
            DHT_EQ_F32_BITS(r->base.m[c][k], (c == k) ? 1.0f : 0.0f);
            DHT_EQ_F32_BITS(r->tool.m[c][k], (c == k) ? 1.0f : 0.0f);
        }
    }
    for (c = 0; c < 3; c++) {
        DHT_EQ_INT(r->base_q.p[c], 0);
        DHT_EQ_INT(r->tool_q.p[c], 0);
        for (k = 0; k < 3; k++) {
            DHT_EQ_INT(r->base_q.r[c][k], (c == k) ? DH_Q30_ONE : 0);
            DHT_EQ_INT(r->tool_q.r[c][k], (c == k) ? DH_Q30_ONE : 0);
        }
    }
}

/* init writes every field (over a canary and over a used description:
 * full, joints of both kinds, limits, frames of both kinds) */
static void robot_init_every_field(void)
{
    dh_robot r;
    dh_mat4_f32 B;
    dh_frame_q F;
    unsigned pass, i;
    CANARY(r);
    for (pass = 0; pass < 3; pass++) {
        dh_convention conv = (pass == 1) ? DH_CONV_MODIFIED : DH_CONV_STANDARD;
        DHT_EQ_INT(dh_robot_init(&r, conv), DH_OK);
        check_empty(&r, conv);
        for (i = 0; i < (unsigned)DH_MAX_JOINTS; i++) {
            if (i & 1u) {
                DHT_EQ_INT(dh_robot_add_joint_q(&r, DH_JOINT_PRISMATIC, -(13 << 16), -9, 7, 11 << 16), DH_OK);
            } else {
                DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_PRISMATIC, (pass == 2) ? 1e30f : 10.0f, -1.5f, 0.25f, 30.0f),
                           DH_OK);
            }
            DHT_EQ_INT(dh_robot_set_limits_f32(&r, i, -2.0f, 3.0f), DH_OK);
        }
        dh_mat4_trans_f32(1.0f, 2.0f, 3.0f, &B);
        DHT_EQ_INT(dh_robot_set_base_f32(&r, &B), DH_OK);
        dh_frame_trans_q(5, 6, 7, &F);
        DHT_EQ_INT(dh_robot_set_tool_q(&r, &F), DH_OK);
        DHT_TRUE(r.flags != INIT_FLAGS);
    }
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_MODIFIED), DH_OK);
    check_empty(&r, DH_CONV_MODIFIED);
}

/* init after every reason bit was set and every identity / small-rows bit
 * cleared: the exact flag word before (the rules of robot.h), then an
 * empty description again (the DH_SMALL init builds every flag from the
 * setters, starting from none) */
static void robot_init_after_every_reason(void)
{
    dh_robot r;
    dh_mat4_f32 B;
    dh_frame_q F;
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_q(&r, DH_JOINT_REVOLUTE, 4, 2, 1, 3), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0.0f, 0.0f, 1e30f, 0.0f), DH_OK);
    /* fixed base with rows far above norm 1.5 (the float base, still the
     * identity, is stale), then a float base that does not fit: the fixed
     * copy stays, its bits stay cleared */
    dh_frame_identity_q(&F);
    F.r[0][0] = INT32_MAX;
    F.r[1][0] = INT32_MIN;
    DHT_EQ_INT(dh_robot_set_base_q(&r, &F), DH_OK);
    DHT_EQ_INT(r.flags, DH_ROBOT_F32_NO_JOINT | DH_ROBOT_Q_NO_JOINT | DH_ROBOT_F32_NO_BASE |
                            DH_ROBOT_BASE_ID_F32 | DH_ROBOT_TOOL_ID_F32 | DH_ROBOT_TOOL_ID_Q);
    dh_mat4_trans_f32(0.0f, 1e30f, 0.0f, &B);
    DHT_EQ_INT(dh_robot_set_base_f32(&r, &B), DH_OK);
    DHT_EQ_INT(r.base_q.r[0][0], INT32_MAX);
    DHT_EQ_INT(r.base_q.r[1][0], INT32_MIN);
    /* a fixed tool that is no identity: the float tool (still the
     * identity) is stale */
    dh_frame_trans_q(0, 0, 1, &F);
    DHT_EQ_INT(dh_robot_set_tool_q(&r, &F), DH_OK);
    DHT_EQ_INT(r.flags, DH_ROBOT_F32_NO_JOINT | DH_ROBOT_Q_NO_JOINT | DH_ROBOT_Q_NO_BASE |
                            DH_ROBOT_F32_NO_TOOL | DH_ROBOT_TOOL_ID_F32);
    /* a float tool that does not fit: both tool reasons swap */
    dh_mat4_trans_f32(-1e30f, 0.0f, 0.0f, &B);
    DHT_EQ_INT(dh_robot_set_tool_f32(&r, &B), DH_OK);
    DHT_EQ_INT(r.flags, DH_ROBOT_F32_NO_JOINT | DH_ROBOT_Q_NO_JOINT | DH_ROBOT_Q_NO_BASE |
                            DH_ROBOT_Q_NO_TOOL);
    DHT_EQ_INT(r.tool_q.p[2], 1);
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_MODIFIED), DH_OK);
    check_empty(&r, DH_CONV_MODIFIED);
}

/* The fixed-point copies made by the float setters: nearest, ties away from
 * zero, the ends of the Q ranges exact (-2^31 fits, the largest float below
 * the upper end fits), sin/cos of alpha exact at quarter turns. */
static void robot_fixed_copies_rounding(void)
{
    const float lsb = ldexpf(1.0f, -DH_QPOS_FRAC), dl = ldexpf(1.0f, -16), rl = ldexpf(1.0f, -30);
    const float below2 = 2.0f - ldexpf(1.0f, -23); /* largest float below 2 */
    const float qmax = ldexpf(1.0f, 31 - DH_QPOS_FRAC);
    dh_robot r;
    dh_mat4_f32 B;
    dh_frame_q keep;
    unsigned w, c, k;
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_PRISMATIC, -0.5f * dl, -1.5f * lsb, 1.5f * lsb, 2.5f * dl), DH_OK);
    DHT_EQ_INT(r.joint[0].a_q, 2);
    DHT_EQ_INT(r.joint[0].d_q, -2);
    DHT_EQ_INT(r.joint[0].alpha_q, 3);
    DHT_EQ_INT(r.joint[0].theta_q, -1);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 32768.0f - ldexpf(1.0f, -9), -2.5f * lsb, 0.49999997f * lsb,
                                      -32768.0f), DH_OK);
    DHT_EQ_INT(r.joint[1].a_q, 0);
    DHT_EQ_INT(r.joint[1].d_q, -3);
    DHT_EQ_INT(r.joint[1].alpha_q, INT32_MIN);
    DHT_EQ_INT(r.joint[1].theta_q, 2147483520);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0.0f, qmax - 128.0f * lsb, -qmax, 90.0f), DH_OK);
    DHT_EQ_INT(r.joint[2].a_q, INT32_MIN);
    DHT_EQ_INT(r.joint[2].d_q, 2147483520);
    DHT_EQ_INT(r.joint[2].sa_q, DH_Q30_ONE);
    DHT_EQ_INT(r.joint[2].ca_q, 0);
    DHT_EQ_F32_BITS(r.joint[2].sa, 1.0f);
    DHT_EQ_F32_BITS(r.joint[2].ca, 0.0f);
    /* -32490 = -90 - 90 turns */
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0.0f, 0.0f, 0.0f, -32490.0f), DH_OK);
    DHT_EQ_INT(r.joint[3].alpha_q, (int32_t)(-32490 * (int64_t)65536));
    DHT_EQ_INT(r.joint[3].sa_q, -DH_Q30_ONE);
    DHT_EQ_INT(r.joint[3].ca_q, 0);
    DHT_TRUE((r.flags & DH_ROBOT_HAS_Q) != 0u);
    /* base, then the same frame as tool */
    for (w = 0; w < 2; w++) {
        const dh_frame_q *Fq = w ? &r.tool_q : &r.base_q;
        dh_mat4_identity_f32(&B);
        B.m[0][0] = -2.0f;
        B.m[1][0] = 1.5f * rl;
        B.m[2][0] = -2.5f * rl;
        B.m[0][1] = below2;
        B.m[2][2] = -0.49999997f * rl;
        B.m[3][0] = -qmax;
        B.m[3][1] = 0.5f * lsb;
        B.m[3][2] = -0.5f * lsb;
        DHT_EQ_INT(w ? dh_robot_set_tool_f32(&r, &B) : dh_robot_set_base_f32(&r, &B), DH_OK);
        DHT_EQ_INT(Fq->r[0][0], INT32_MIN);
        DHT_EQ_INT(Fq->r[1][0], 2);
        DHT_EQ_INT(Fq->r[2][0], -3);
        DHT_EQ_INT(Fq->r[0][1], 2147483520);
        DHT_EQ_INT(Fq->r[1][1], DH_Q30_ONE);
        DHT_EQ_INT(Fq->r[2][2], 0);
        DHT_EQ_INT(Fq->p[0], INT32_MIN);
        DHT_EQ_INT(Fq->p[1], 1);
        DHT_EQ_INT(Fq->p[2], -1);
        DHT_TRUE((r.flags & DH_ROBOT_HAS_Q) != 0u && (r.flags & DH_ROBOT_HAS_F32) != 0u);
        DHT_TRUE((r.flags & (w ? DH_ROBOT_TOOL_ID_Q | DH_ROBOT_TOOL_ID_F32 : DH_ROBOT_BASE_ID_Q | DH_ROBOT_BASE_ID_F32)) == 0u);
        if (!w) DHT_TRUE((r.flags & DH_ROBOT_BASE_SMALL_Q) == 0u); /* row 0 has norm 2 */
        for (c = 0; c < 4; c++)
            for (k = 0; k < 4; k++)
                DHT_EQ_F32_BITS(w ? r.tool.m[c][k] : r.base.m[c][k], B.m[c][k]);
        /* not representable (position at the upper end): the float frame is
         * stored, the fixed copy kept as it was, the fixed path unavailable */
        keep = *Fq;
        B.m[3][1] = qmax;
        DHT_EQ_INT(w ? dh_robot_set_tool_f32(&r, &B) : dh_robot_set_base_f32(&r, &B), DH_OK);
        DHT_TRUE(memcmp(Fq, &keep, sizeof keep) == 0);
        DHT_TRUE((r.flags & DH_ROBOT_HAS_Q) == 0u && (r.flags & DH_ROBOT_HAS_F32) != 0u);
        DHT_TRUE((r.flags & (w ? DH_ROBOT_Q_NO_TOOL : DH_ROBOT_Q_NO_BASE)) != 0u);
        DHT_EQ_F32_BITS(w ? r.tool.m[3][1] : r.base.m[3][1], qmax);
        /* the identity again: both paths, identity bits set */
        dh_mat4_identity_f32(&B);
        DHT_EQ_INT(w ? dh_robot_set_tool_f32(&r, &B) : dh_robot_set_base_f32(&r, &B), DH_OK);
        DHT_TRUE((r.flags & DH_ROBOT_HAS_Q) != 0u);
        DHT_TRUE((r.flags & (w ? DH_ROBOT_TOOL_ID_Q | DH_ROBOT_TOOL_ID_F32 : DH_ROBOT_BASE_ID_Q | DH_ROBOT_BASE_ID_F32 |
                                                                              DH_ROBOT_BASE_SMALL_Q)) ==
                 (w ? DH_ROBOT_TOOL_ID_Q | DH_ROBOT_TOOL_ID_F32 : DH_ROBOT_BASE_ID_Q | DH_ROBOT_BASE_ID_F32 | DH_ROBOT_BASE_SMALL_Q));
        /* an entry that rounds to 0 in Q2.30: identity in fixed point only */
        B.m[1][2] = 0.25f * rl;
        DHT_EQ_INT(w ? dh_robot_set_tool_f32(&r, &B) : dh_robot_set_base_f32(&r, &B), DH_OK);
        DHT_TRUE((r.flags & (w ? DH_ROBOT_TOOL_ID_Q : DH_ROBOT_BASE_ID_Q)) != 0u);
        DHT_TRUE((r.flags & (w ? DH_ROBOT_TOOL_ID_F32 : DH_ROBOT_BASE_ID_F32)) == 0u);
    }
}

/* NaN/Inf is reported before a bad bottom row; r untouched */
static void robot_frame_nan_before_not_rigid(void)
{
    dh_robot r, copy;
    dh_mat4_f32 B;
    unsigned e, k;
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    copy = r;
    for (e = 0; e < 16; e++) {
        for (k = 0; k < 4; k++) {
            dh_mat4_identity_f32(&B);
            B.m[(e + 5u) % 4u][3] = 0.5f; /* bottom row wrong somewhere */
            B.m[e / 4][e % 4] = bad_value_nan(k);
            DHT_EQ_INT(dh_robot_set_base_f32(&r, &B), DH_ERR_NAN);
            DHT_EQ_INT(dh_robot_set_tool_f32(&r, &B), DH_ERR_NAN);
        }
    }
    DHT_TRUE(memcmp(&r, &copy, sizeof r) == 0);
}

/* The reason bits: a joint added with _q keeps the float path unavailable
 * after later float joints; a fixed frame makes the float one stale unless
 * both are the identity; the float setter makes it current again; a frame
 * set from the robot's own copy keeps its values. */
static void robot_flag_bookkeeping(void)
{
    dh_robot r;
    dh_mat4_f32 B;
    dh_frame_q F, keep;
    unsigned w;
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_q(&r, DH_JOINT_REVOLUTE, 4, 2, 1, 3), DH_OK);
    DHT_TRUE((r.flags & DH_ROBOT_HAS_F32) == 0u);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0.0f, 0.0f, 0.5f, 0.0f), DH_OK);
    DHT_TRUE((r.flags & DH_ROBOT_HAS_F32) == 0u && (r.flags & DH_ROBOT_F32_NO_JOINT) != 0u);
    DHT_TRUE((r.flags & DH_ROBOT_HAS_Q) != 0u);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0.0f, 0.0f, 1e30f, 0.0f), DH_OK);
    DHT_TRUE((r.flags & (DH_ROBOT_HAS_F32 | DH_ROBOT_HAS_Q)) == 0u);
    DHT_TRUE((r.flags & (DH_ROBOT_F32_NO_JOINT | DH_ROBOT_Q_NO_JOINT)) == (DH_ROBOT_F32_NO_JOINT | DH_ROBOT_Q_NO_JOINT));
    for (w = 0; w < 2; w++) {
        const uint32_t no_f32 = w ? DH_ROBOT_F32_NO_TOOL : DH_ROBOT_F32_NO_BASE;
        const uint32_t id_q = w ? DH_ROBOT_TOOL_ID_Q : DH_ROBOT_BASE_ID_Q;
        dh_frame_q *own = w ? &r.tool_q : &r.base_q;
        DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
        DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0.0f, 0.0f, 0.5f, 0.0f), DH_OK);
        dh_frame_identity_q(&F);
        DHT_EQ_INT(w ? dh_robot_set_tool_q(&r, &F) : dh_robot_set_base_q(&r, &F), DH_OK);
        DHT_TRUE((r.flags & DH_ROBOT_HAS_F32) != 0u && (r.flags & id_q) != 0u); /* both identity */
        dh_frame_trans_q(0, 1, 0, &F);
        DHT_EQ_INT(w ? dh_robot_set_tool_q(&r, &F) : dh_robot_set_base_q(&r, &F), DH_OK);
        DHT_TRUE((r.flags & DH_ROBOT_HAS_F32) == 0u && (r.flags & no_f32) != 0u && (r.flags & id_q) == 0u);
        DHT_TRUE((r.flags & DH_ROBOT_HAS_Q) != 0u);
        keep = *own;
        DHT_EQ_INT(w ? dh_robot_set_tool_q(&r, own) : dh_robot_set_base_q(&r, own), DH_OK);
        DHT_TRUE(memcmp(own, &keep, sizeof keep) == 0);
        dh_mat4_trans_f32(0.0f, 2.0f, 0.0f, &B);
        DHT_EQ_INT(w ? dh_robot_set_tool_f32(&r, &B) : dh_robot_set_base_f32(&r, &B), DH_OK);
        DHT_TRUE((r.flags & (DH_ROBOT_HAS_F32 | DH_ROBOT_HAS_Q)) == (DH_ROBOT_HAS_F32 | DH_ROBOT_HAS_Q));
        DHT_EQ_INT(own->p[1], 2 * DH_QPOS_ONE);
        /* a fixed identity while the float frame is not: float path stale */
        dh_frame_identity_q(&F);
        DHT_EQ_INT(w ? dh_robot_set_tool_q(&r, &F) : dh_robot_set_base_q(&r, &F), DH_OK);
        DHT_TRUE((r.flags & DH_ROBOT_HAS_F32) == 0u && (r.flags & id_q) != 0u);
        /* the float frame from the robot's own copy */
        DHT_EQ_INT(w ? dh_robot_set_tool_f32(&r, &r.tool) : dh_robot_set_base_f32(&r, &r.base), DH_OK);
        DHT_TRUE((r.flags & DH_ROBOT_HAS_F32) != 0u);
        DHT_EQ_F32_BITS(w ? r.tool.m[3][1] : r.base.m[3][1], 2.0f);
        DHT_EQ_INT(own->p[1], 2 * DH_QPOS_ONE);
    }
}

static const dht_case cases[] = {
    DHT_CASE(robot_init_bad_conv),
    DHT_CASE(robot_add_joint_bad),
    DHT_CASE(robot_unrepresentable_fixed_constants),
    DHT_CASE(robot_set_limits_bad),
    DHT_CASE(robot_set_rates_bad_and_exact),
    DHT_CASE(robot_base_tool_bad),
    DHT_CASE(robot_check_limits_bad),
    DHT_CASE(robot_fk_f32_bad),
    DHT_CASE(robot_fk_q_bad),
    DHT_CASE(robot_n_beyond_capacity),
    DHT_CASE(robot_init_every_field),
    DHT_CASE(robot_init_after_every_reason),
    DHT_CASE(robot_fixed_copies_rounding),
    DHT_CASE(robot_frame_nan_before_not_rigid),
    DHT_CASE(robot_flag_bookkeeping),
};
DHT_MAIN(cases)
