/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_errors_kin.c - bad input to the Jacobian, the orientation / pose
 * errors and the inverse kinematics (docs/errors.md, section kin.h).
 *
 * Outputs are pre-filled with a canary and checked untouched, or equal to
 * the documented value. IK results on unreachable targets are judged with
 * the double reference FK of test/support_robots.c.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_canary.h"
#include "support_robots.h"
#include "dhmath/kin.h"
#include "dhmath/mat4.h"
#include "dhmath/frame.h"



#define NJ 6
static float work[DH_IK_WORK_FLOATS(DH_MAX_JOINTS)];

static void puma(dh_robot *r)
{
    DHT_EQ_INT(dhs_build(&dhs_puma560_m, r), DH_OK);
    DHT_EQ_INT(r->n, NJ);
}

/* Jacobian: NaN/Inf q -> NAN; n > DH_MAX_JOINTS, unknown convention or
 * joint type -> ARG; float path unavailable -> UNAVAILABLE; J and T_end
 * untouched */
static void kin_jacobian_bad(void)
{
    dh_robot r, r2;
    float q[NJ] = { 10.0f, -20.0f, 30.0f, 40.0f, -50.0f, 60.0f };
    float J[6 * DH_MAX_JOINTS];
    dh_mat4_f32 T;
    unsigned k, tool;
    puma(&r);
    for (tool = 0; tool < 2; tool++) {
        dh_status (*jac)(const dh_robot *, const float *, float *, dh_mat4_f32 *) =
            tool ? dh_jacobian_tool_f32 : dh_jacobian_f32;
        for (k = 0; k < NJ * 4; k++) {
            float qb[NJ];
            memcpy(qb, q, sizeof qb);
            qb[k / 4] = bad_value(k);
            CANARY(J);
            CANARY(T);
            DHT_EQ_INT(jac(&r, qb, J, &T), DH_ERR_NAN);
            UNTOUCHED(J);
            UNTOUCHED(T);
        }
        r2 = r;
        r2.n = DH_MAX_JOINTS + 1u;
        DHT_EQ_INT(jac(&r2, q, J, &T), DH_ERR_ARG);
        UNTOUCHED(J);
        UNTOUCHED(T);
        r2 = r;
        r2.conv = (dh_convention)5;
        DHT_EQ_INT(jac(&r2, q, J, &T), DH_ERR_ARG);
        UNTOUCHED(J);
        UNTOUCHED(T);
        r2 = r;
        r2.joint[3].type = (dh_joint_type)7;
        DHT_EQ_INT(jac(&r2, q, J, &T), DH_ERR_ARG);
        UNTOUCHED(J);
        UNTOUCHED(T);
        /* float path unavailable (base set from fixed point only) */
        r2 = r;
        {
            dh_frame_q F;
            dh_frame_trans_q(0, 0, DH_QPOS_ONE, &F);
            DHT_EQ_INT(dh_robot_set_base_q(&r2, &F), DH_OK);
        }
        DHT_EQ_INT(jac(&r2, q, J, &T), DH_ERR_UNAVAILABLE);
        UNTOUCHED(J);
        UNTOUCHED(T);
        /* ... also with no joints (nothing else would catch the stale base) */
        DHT_EQ_INT(dh_robot_init(&r2, DH_CONV_STANDARD), DH_OK);
        {
            dh_frame_q F;
            dh_frame_trans_q(0, 0, DH_QPOS_ONE, &F);
            DHT_EQ_INT(dh_robot_set_tool_q(&r2, &F), DH_OK);
        }
        DHT_EQ_INT(jac(&r2, q, J, &T), DH_ERR_UNAVAILABLE);
        UNTOUCHED(T);
        /* n == 0 with a valid float path: DH_OK, T_end = base * tool, J not written */
        DHT_EQ_INT(dh_robot_init(&r2, DH_CONV_MODIFIED), DH_OK);
        {
            dh_mat4_f32 B;
            dh_mat4_trans_f32(1.0f, 2.0f, 3.0f, &B);
            DHT_EQ_INT(dh_robot_set_base_f32(&r2, &B), DH_OK);
            DHT_EQ_INT(dh_mat4_rotz_f32(90.0f, &B), DH_OK);
            DHT_EQ_INT(dh_robot_set_tool_f32(&r2, &B), DH_OK);
        }
        CANARY(J);
        DHT_EQ_INT(jac(&r2, q, J, &T), DH_OK);
        UNTOUCHED(J);
        DHT_EQ_F32_BITS(DH_M4(&T, 0, 3), 1.0f);
        DHT_EQ_F32_BITS(DH_M4(&T, 2, 3), 3.0f);
        DHT_EQ_F32_BITS(DH_M4(&T, 1, 0), 1.0f);
        /* q + theta offset (or prismatic q + d) overflows: OVERFLOW before
         * anything is computed, J and T_end untouched */
        r2 = r;
        r2.joint[2].theta_deg = FLT_MAX;
        {
            float qo[NJ];
            memcpy(qo, q, sizeof qo);
            qo[2] = FLT_MAX;
            CANARY(J);
            CANARY(T);
            DHT_EQ_INT(jac(&r2, qo, J, &T), DH_ERR_OVERFLOW);
            UNTOUCHED(T);
            UNTOUCHED(J);
        }
        /* finite but non-finite result (prismatic 3e38 through a scaling
         * base): OVERFLOW with J and T_end holding the computed values */
        DHT_EQ_INT(dh_robot_init(&r2, DH_CONV_STANDARD), DH_OK);
        DHT_EQ_INT(dh_robot_add_joint_f32(&r2, DH_JOINT_PRISMATIC, 0.0f, 0.0f, 0.0f, 0.0f), DH_OK);
        DHT_EQ_INT(dh_robot_add_joint_f32(&r2, DH_JOINT_REVOLUTE, 0.0f, 0.0f, 1.0f, 0.0f), DH_OK);
        {
            dh_mat4_f32 B;
            float qh[2] = { 3e38f, 0.0f };
            dh_mat4_scale_f32(4.0f, 4.0f, 4.0f, &B);
            DHT_EQ_INT(dh_robot_set_base_f32(&r2, &B), DH_OK);
            CANARY(J);
            CANARY(T);
            DHT_EQ_INT(jac(&r2, qh, J, &T), DH_ERR_OVERFLOW);
            DHT_TRUE(!is_canary(&T, sizeof T));
            DHT_EQ_INT(dh_mat4_check_finite_f32(&T), DH_ERR_NAN);
            DHT_TRUE(!is_canary(J, 12 * sizeof(float)));
        }
    }
}

static void set_rot3(dh_mat3_f32 *R, const dh_mat4_f32 *T)
{
    dh_mat4_get_rot_f32(T, R);
}

/* rot_error / pose_error: NaN/Inf -> NAN; not orthonormal or a reflection
 * -> NOT_RIGID; outputs untouched */
static void kin_rot_pose_error_bad(void)
{
    dh_mat4_f32 A, B;
    dh_mat3_f32 Ra, Rb;
    dh_vec3_f32 w;
    float e[6];
    unsigned k;
    DHT_EQ_INT(dh_mat4_rot_axis_f32(1.0f, 2.0f, 3.0f, 40.0f, &A), DH_OK);
    DHT_EQ_INT(dh_mat4_rotx_f32(-70.0f, &B), DH_OK);
    for (k = 0; k < 9 * 4; k++) {
        set_rot3(&Ra, &A);
        set_rot3(&Rb, &B);
        Ra.m[(k / 4) / 3][(k / 4) % 3] = bad_value(k);
        CANARY(w);
        DHT_EQ_INT(dh_rot_error_f32(&Ra, &Rb, &w), DH_ERR_NAN);
        UNTOUCHED(w);
        DHT_EQ_INT(dh_rot_error_f32(&Rb, &Ra, &w), DH_ERR_NAN);
        UNTOUCHED(w);
    }
    for (k = 0; k < 12 * 4; k++) {
        dh_mat4_f32 C = A;
        C.m[(k / 4) / 3][(k / 4) % 3] = bad_value(k);
        CANARY(e);
        DHT_EQ_INT(dh_pose_error_f32(&C, &B, e), DH_ERR_NAN);
        UNTOUCHED(e);
        DHT_EQ_INT(dh_pose_error_f32(&B, &C, e), DH_ERR_NAN);
        UNTOUCHED(e);
    }
    /* bottom rows are not read */
    {
        dh_mat4_f32 C = A;
        C.m[0][3] = bad_value(0);
        C.m[3][3] = 5.0f;
        DHT_EQ_INT(dh_pose_error_f32(&C, &B, e), DH_OK);
    }
    /* scaled, sheared, reflected */
    for (k = 0; k < 3; k++) {
        set_rot3(&Ra, &A);
        set_rot3(&Rb, &B);
        if (k == 0) {
            unsigned i;
            for (i = 0; i < 9; i++) Ra.m[i / 3][i % 3] *= 1.002f;
        } else if (k == 1) {
            Ra.m[1][0] += 0.01f;
        } else {
            Ra.m[2][0] = -Ra.m[2][0];
            Ra.m[2][1] = -Ra.m[2][1];
            Ra.m[2][2] = -Ra.m[2][2];   /* a -> -a: orthonormal, det -1 */
        }
        CANARY(w);
        DHT_EQ_INT(dh_rot_error_f32(&Ra, &Rb, &w), DH_ERR_NOT_RIGID);
        UNTOUCHED(w);
        DHT_EQ_INT(dh_rot_error_f32(&Rb, &Ra, &w), DH_ERR_NOT_RIGID);
        UNTOUCHED(w);
        DHT_EQ_INT(dh_rot_error_f32(&Ra, &Ra, &w), DH_ERR_NOT_RIGID);
        UNTOUCHED(w);
        {
            dh_mat4_f32 C = A;
            dh_mat4_set_rot_f32(&C, &Ra);
            CANARY(e);
            DHT_EQ_INT(dh_pose_error_f32(&C, &B, e), DH_ERR_NOT_RIGID);
            UNTOUCHED(e);
            DHT_EQ_INT(dh_pose_error_f32(&B, &C, e), DH_ERR_NOT_RIGID);
            UNTOUCHED(e);
        }
    }
}

static void ik_setup(const dh_robot *r, dh_ik_params_f32 *p, dh_ik_result_f32 *res)
{
    dh_ik_params_default_f32(r, p);
    memset(res, 0, sizeof *res);
}

/* IK argument errors: every one -> its status with q and res untouched */
static void kin_ik_bad_args(void)
{
    dh_robot r, r2;
    dh_ik_params_f32 p, pb;
    dh_ik_result_f32 res;
    dh_mat4_f32 target;
    float q0[NJ] = { 0.0f, -45.0f, 120.0f, 0.0f, 45.0f, 0.0f }; /* within the limits */
    float q[NJ];
    unsigned k;
    puma(&r);
    ik_setup(&r, &p, &res);
    DHT_EQ_INT(dh_fk_f32(&r, q0, &target), DH_OK);
    /* n == 0 and n > DH_MAX_JOINTS */
    DHT_EQ_INT(dh_robot_init(&r2, DH_CONV_STANDARD), DH_OK);
    CANARY(q);
    CANARY(res);
    DHT_EQ_INT(dh_ik_f32(&r2, &target, q0, &p, work, sizeof work / sizeof work[0], q, &res), DH_ERR_ARG);
    UNTOUCHED(q);
    UNTOUCHED(res);
    r2 = r;
    r2.n = DH_MAX_JOINTS + 1u;
    DHT_EQ_INT(dh_ik_f32(&r2, &target, q0, &p, work, sizeof work / sizeof work[0], q, &res), DH_ERR_ARG);
    UNTOUCHED(q);
    UNTOUCHED(res);
    /* workspace: NULL (documented as DH_ERR_ARG, not an assert) and too short */
    DHT_EQ_INT(dh_ik_f32(&r, &target, q0, &p, NULL, 1000u, q, &res), DH_ERR_ARG);
    DHT_EQ_INT(dh_ik_f32(&r, &target, q0, &p, work, DH_IK_WORK_FLOATS(NJ) - 1u, q, &res), DH_ERR_ARG);
    UNTOUCHED(q);
    UNTOUCHED(res);
    /* parameters */
    for (k = 0; k < 13; k++) {
        pb = p;
        switch (k) {
        case 0: pb.max_iter = 0u; break;
        case 1: pb.mask = 0u; break;
        case 2: pb.mask = 0x40u; break;
        case 3: pb.mask = DH_IK_FULL | 0x80000000u; break;
        case 4: pb.tol_pos = -1e-9f; break;
        case 5: pb.tol_rot = bad_value(0); break;
        case 6: pb.tol_pos = bad_value(1); break;
        case 7: pb.tol_rot = -1.0f; break;
        case 8: pb.w_rot = 0.0f; break;
        case 9: pb.w_rot = -1.0f; break;
        case 10: pb.w_rot = bad_value(0); break;
        case 11: pb.w_rot = bad_value(1); break;
        default: pb.w_rot = 1e20f; break; /* w_rot^2 overflows */
        }
        DHT_EQ_INT(dh_ik_f32(&r, &target, q0, &pb, work, sizeof work / sizeof work[0], q, &res), DH_ERR_ARG);
        UNTOUCHED(q);
        UNTOUCHED(res);
    }
    /* NaN/Inf target (any of the 16 entries) or q0 */
    for (k = 0; k < 16 * 4; k++) {
        dh_mat4_f32 tb = target;
        tb.m[(k / 4) / 4][(k / 4) % 4] = bad_value(k);
        DHT_EQ_INT(dh_ik_f32(&r, &tb, q0, &p, work, sizeof work / sizeof work[0], q, &res), DH_ERR_NAN);
        UNTOUCHED(q);
        UNTOUCHED(res);
    }
    for (k = 0; k < NJ * 4; k++) {
        float qb[NJ];
        memcpy(qb, q0, sizeof qb);
        qb[k / 4] = bad_value(k);
        DHT_EQ_INT(dh_ik_f32(&r, &target, qb, &p, work, sizeof work / sizeof work[0], q, &res), DH_ERR_NAN);
        UNTOUCHED(q);
        UNTOUCHED(res);
    }
    /* non-rigid target rotation: scaled, reflected */
    for (k = 0; k < 2; k++) {
        dh_mat4_f32 tb = target;
        if (k == 0) {
            unsigned i;
            for (i = 0; i < 9; i++) tb.m[i / 3][i % 3] *= 1.01f;
        } else {
            tb.m[0][0] = -tb.m[0][0];
            tb.m[0][1] = -tb.m[0][1];
            tb.m[0][2] = -tb.m[0][2];
        }
        DHT_EQ_INT(dh_ik_f32(&r, &tb, q0, &p, work, sizeof work / sizeof work[0], q, &res), DH_ERR_NOT_RIGID);
        UNTOUCHED(q);
        UNTOUCHED(res);
        /* position-only IK does not read the target rotation */
        pb = p;
        pb.mask = DH_IK_POSITION;
        DHT_EQ_INT(dh_ik_f32(&r, &tb, q0, &pb, work, sizeof work / sizeof work[0], q, &res), DH_OK);
        CANARY(q);
        CANARY(res);
    }
    /* float path unavailable -> UNAVAILABLE, untouched */
    r2 = r;
    {
        dh_frame_q F;
        dh_frame_identity_q(&F);
        F.p[0] = 1;
        DHT_EQ_INT(dh_robot_set_tool_q(&r2, &F), DH_OK);
    }
    DHT_EQ_INT(dh_ik_f32(&r2, &target, q0, &p, work, sizeof work / sizeof work[0], q, &res), DH_ERR_UNAVAILABLE);
    UNTOUCHED(q);
    UNTOUCHED(res);
    /* a finite target so far away that the squared error overflows is out
     * of reach: UNREACHABLE at once (no step), q = the clamped q0, res.err_pos
     * the distance computed without overflow */
    {
        dh_mat4_f32 tb = target;
        dh_mat4_f32 T0;
        unsigned j;
        tb.m[3][0] = 1e30f;
        CANARY(q);
        CANARY(res);
        DHT_EQ_INT(dh_ik_f32(&r, &tb, q0, &p, work, sizeof work / sizeof work[0], q, &res), DH_ERR_UNREACHABLE);
        for (j = 0; j < NJ; j++) DHT_EQ_F32_BITS(q[j], q0[j]);
        DHT_EQ_INT(res.iterations, 0);
        DHT_EQ_INT(dh_fk_f32(&r, q0, &T0), DH_OK);
        DHT_NEAR(res.err_pos, 1e30, 1e24);
        DHT_TRUE(res.err_rot >= 0.0f && res.err_rot <= 3.1416f);
        /* farther than FLT_MAX in norm: err_pos saturates to FLT_MAX */
        tb.m[3][0] = 3e38f;
        tb.m[3][1] = -3e38f;
        DHT_EQ_INT(dh_ik_f32(&r, &tb, q0, &p, work, sizeof work / sizeof work[0], q, &res), DH_ERR_UNREACHABLE);
        DHT_EQ_F32_BITS(res.err_pos, FLT_MAX);
        /* position only, the same */
        pb = p;
        pb.mask = DH_IK_POSITION;
        tb.m[3][1] = 0.0f;
        tb.m[3][0] = -2e20f;
        DHT_EQ_INT(dh_ik_f32(&r, &tb, q0, &pb, work, sizeof work / sizeof work[0], q, &res), DH_ERR_UNREACHABLE);
        DHT_NEAR(res.err_pos, 2e20, 1e15);
        (void)T0;
    }
    /* ... but when the reach is unbounded (a prismatic joint without
     * limits) the overflow cannot be judged: OVERFLOW, untouched */
    {
        dh_robot rp;
        dh_mat4_f32 tb;
        float qp[2] = { 0.0f, 0.0f };
        DHT_EQ_INT(dh_robot_init(&rp, DH_CONV_STANDARD), DH_OK);
        DHT_EQ_INT(dh_robot_add_joint_f32(&rp, DH_JOINT_REVOLUTE, 0.0f, 0.0f, 0.5f, 90.0f), DH_OK);
        DHT_EQ_INT(dh_robot_add_joint_f32(&rp, DH_JOINT_PRISMATIC, 0.0f, 0.0f, 0.0f, 0.0f), DH_OK);
        dh_mat4_identity_f32(&tb);
        tb.m[3][2] = 1e30f;
        pb = p;
        pb.mask = DH_IK_POSITION;
        CANARY(q);
        CANARY(res);
        DHT_EQ_INT(dh_ik_f32(&rp, &tb, qp, &pb, work, sizeof work / sizeof work[0], q, &res), DH_ERR_OVERFLOW);
        UNTOUCHED(q);
        UNTOUCHED(res);
    }
    /* w_rot so large that w_rot^2 pi^2 overflows: ARG */
    pb = p;
    pb.w_rot = 1e19f;
    CANARY(q);
    CANARY(res);
    DHT_EQ_INT(dh_ik_f32(&r, &target, q0, &pb, work, sizeof work / sizeof work[0], q, &res), DH_ERR_ARG);
    UNTOUCHED(q);
    UNTOUCHED(res);
}

/* Targets that are not a rigid-motion transform (defect 2): a bottom row
 * other than 0 0 0 1 (e.g. a perspective matrix) is NOT_RIGID in every
 * mode, at once, outputs untouched; a rotation part off by more than
 * DH_ROT_ERROR_TOL (sheared, scaled, reflected) is NOT_RIGID when the
 * orientation is driven and ignored in position-only mode. */
static void kin_ik_not_rigid(void)
{
    dh_robot r;
    dh_ik_params_f32 p, pp;
    dh_ik_result_f32 res;
    dh_mat4_f32 target;
    float q0[NJ] = { 0.0f, -45.0f, 120.0f, 0.0f, 45.0f, 0.0f };
    float q[NJ];
    unsigned k;
    puma(&r);
    ik_setup(&r, &p, &res);
    pp = p;
    pp.mask = DH_IK_POSITION;
    DHT_EQ_INT(dh_fk_f32(&r, q0, &target), DH_OK);
    for (k = 0; k < 8; k++) {
        dh_mat4_f32 tb = target;
        switch (k) {
        case 0: tb.m[2][3] = -0.5f; break;       /* perspective persp(z, 2): -1/d in the bottom row */
        case 1: tb.m[0][3] = 1e-7f; break;
        case 2: tb.m[1][3] = -1e-30f; break;
        case 3: tb.m[3][3] = 1.0000001f; break;
        case 4: tb.m[3][3] = 2.0f; break;          /* homogeneous scale */
        case 5: tb.m[3][3] = 0.0f; break;
        case 6: tb.m[3][3] = -1.0f; break;
        default: tb.m[2][3] = -0.5f; tb.m[3][3] = 0.0f; break;
        }
        CANARY(q);
        CANARY(res);
        DHT_EQ_INT(dh_ik_f32(&r, &tb, q0, &p, work, sizeof work / sizeof work[0], q, &res), DH_ERR_NOT_RIGID);
        UNTOUCHED(q);
        UNTOUCHED(res);
        DHT_EQ_INT(dh_ik_f32(&r, &tb, q0, &pp, work, sizeof work / sizeof work[0], q, &res), DH_ERR_NOT_RIGID);
        UNTOUCHED(q);
        UNTOUCHED(res);
    }
    /* the exact perspective matrix of the review: persp(z, 2) */
    {
        dh_mat4_f32 P;
        dh_mat4_identity_f32(&P);
        P.m[2][3] = -0.5f;
        DHT_EQ_INT(dh_ik_f32(&r, &P, q0, &p, work, sizeof work / sizeof work[0], q, &res), DH_ERR_NOT_RIGID);
        DHT_EQ_INT(dh_ik_f32(&r, &P, q0, &pp, work, sizeof work / sizeof work[0], q, &res), DH_ERR_NOT_RIGID);
        UNTOUCHED(q);
        UNTOUCHED(res);
    }
    /* rotation part: sheared by just over / within the tolerance */
    for (k = 0; k < 2; k++) {
        dh_mat4_f32 tb = target;
        tb.m[1][0] += (k == 0) ? 2.5e-3f : 2e-4f;
        CANARY(q);
        CANARY(res);
        if (k == 0) {
            DHT_EQ_INT(dh_ik_f32(&r, &tb, q0, &p, work, sizeof work / sizeof work[0], q, &res), DH_ERR_NOT_RIGID);
            UNTOUCHED(q);
            UNTOUCHED(res);
        } else {
            /* within the tolerance: accepted, solved to about the skew */
            dh_status st = dh_ik_f32(&r, &tb, q0, &p, work, sizeof work / sizeof work[0], q, &res);
            DHT_TRUE(!is_canary(&res, sizeof res));
            DHT_TRUE(st == DH_OK || st == DH_ERR_UNREACHABLE);
        }
        DHT_EQ_INT(dh_ik_f32(&r, &tb, q0, &pp, work, sizeof work / sizeof work[0], q, &res), DH_OK);
    }
    /* a non-rigid base makes the end rotation non-rigid: NOT_RIGID in full
     * mode (a(dR) undefined), solved in position-only mode */
    {
        dh_robot rs = r;
        dh_mat4_f32 B, tb;
        dh_mat4_scale_f32(1.5f, 1.5f, 1.5f, &B);
        DHT_EQ_INT(dh_robot_set_base_f32(&rs, &B), DH_OK);
        dh_mat4_f32 Ts;
        float qt[NJ] = { 20.0f, -30.0f, 100.0f, 10.0f, 30.0f, 10.0f };   /* within the limits */
        DHT_EQ_INT(dh_fk_f32(&rs, qt, &Ts), DH_OK);
        dh_mat4_identity_f32(&tb);     /* rigid target at a reachable position */
        for (k = 0; k < 3; k++) tb.m[3][k] = Ts.m[3][k];
        CANARY(q);
        CANARY(res);
        DHT_EQ_INT(dh_ik_f32(&rs, &tb, q0, &p, work, sizeof work / sizeof work[0], q, &res), DH_ERR_NOT_RIGID);
        UNTOUCHED(q);
        UNTOUCHED(res);
        DHT_EQ_INT(dh_ik_f32(&rs, &tb, q0, &pp, work, sizeof work / sizeof work[0], q, &res), DH_OK);
    }
}

/* double position error |p_target - FK(q)| from the reference FK */
static double ref_pos_err(const dh_robot *r, const dh_mat4_f32 *target, const float *q)
{
    double qd[NJ], s = 0.0;
    dhr_mat4 R;
    unsigned i;
    for (i = 0; i < r->n; i++) qd[i] = q[i];
    dhs_fk_ref_f32(r, qd, NULL, &R);
    for (i = 0; i < 3; i++) {
        const double d = (double)target->m[3][i] - R.m[3][i];
        s += d * d;
    }
    return sqrt(s);
}

/* Unreachable targets: DH_ERR_UNREACHABLE, q the best configuration found,
 * within the limits, res describing it (checked with the double FK); q may
 * alias q0 */
static void kin_ik_unreachable(void)
{
    dh_robot r;
    dh_ik_params_f32 p;
    dh_ik_result_f32 res, res2;
    float q0[NJ] = { 0.0f, -45.0f, 180.0f, 0.0f, 45.0f, 0.0f };
    float q[NJ], qa[NJ];
    unsigned it;
    puma(&r);
    for (it = 0; it < DHT_ITER(6u); it++) {
        dh_mat4_f32 target;
        double dir[3], n, dist = 4.0 + 3.0 * it;
        dh_status st;
        unsigned i;
        /* beyond the Puma's reach (~0.9 m from the shoulder) */
        dir[0] = dht_rand_uniform(-1, 1);
        dir[1] = dht_rand_uniform(-1, 1);
        dir[2] = dht_rand_uniform(-1, 1);
        n = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
        DHT_EQ_INT(dh_mat4_rotz_f32(30.0f, &target), DH_OK);
        for (i = 0; i < 3; i++) target.m[3][i] = (float)(dist * dir[i] / n);
        ik_setup(&r, &p, &res);
        p.mask = (it % 2u) ? DH_IK_POSITION : DH_IK_FULL;
        st = dh_ik_f32(&r, &target, q0, &p, work, sizeof work / sizeof work[0], q, &res);
        /* beyond the reach bound: UNREACHABLE, decided early (a few
         * attempts, not the whole step budget) */
        DHT_EQ_INT(st, DH_ERR_UNREACHABLE);
        DHT_TRUE_MSG(res.iterations <= 400u, "%lu steps", (unsigned long)res.iterations);
        DHT_EQ_INT(dh_robot_check_limits_f32(&r, q), DH_OK);
        DHT_TRUE(res.iterations >= 1u && res.iterations <= p.max_iter);
        /* res describes q */
        DHT_NEAR(res.err_pos, ref_pos_err(&r, &target, q), 1e-5 * dist);
        /* cannot be closer than the reach allows (every |a| + |d| of the
         * Puma, base and tool sum to less than 2 m) */
        DHT_TRUE(res.err_pos >= dist - 2.0);
        /* q aliasing q0 gives bitwise the same answer */
        memcpy(qa, q0, sizeof qa);
        DHT_EQ_INT(dh_ik_f32(&r, &target, qa, &p, work, sizeof work / sizeof work[0], qa, &res2), st);
        DHT_TRUE(memcmp(qa, q, sizeof q) == 0);
        DHT_TRUE(memcmp(&res, &res2, sizeof res) == 0);
    }
    /* max_iter = 1 on a reachable but distant target: not converged, the
     * best q so far (no worse than q0) */
    {
        dh_mat4_f32 target;
        float qt[NJ] = { 60.0f, -80.0f, 150.0f, 30.0f, 20.0f, -40.0f };
        double e0;
        DHT_EQ_INT(dh_fk_f32(&r, qt, &target), DH_OK);
        ik_setup(&r, &p, &res);
        p.max_iter = 1u;
        DHT_TRUE(dh_ik_f32(&r, &target, q0, &p, work, sizeof work / sizeof work[0], q, &res) != DH_OK);
        e0 = ref_pos_err(&r, &target, q0);
        DHT_TRUE(res.err_pos <= e0 * (1.0 + 1e-6));
        DHT_EQ_INT(res.iterations, 1u);
    }
    /* q0 beyond its limits is clamped first: the result is within them */
    {
        dh_mat4_f32 target;
        float qt[NJ] = { 20.0f, -30.0f, 170.0f, 10.0f, 30.0f, 10.0f };
        float qbad[NJ] = { 1e30f, -1e30f, 500.0f, -300.0f, 1000.0f, 1e20f };
        DHT_EQ_INT(dh_fk_f32(&r, qt, &target), DH_OK);
        ik_setup(&r, &p, &res);
        (void)dh_ik_f32(&r, &target, qbad, &p, work, sizeof work / sizeof work[0], q, &res);
        DHT_EQ_INT(dh_robot_check_limits_f32(&r, q), DH_OK);
    }
}

/* The status describes the returned configuration (defect 1):
 * UNREACHABLE when the attempts stalled above the tolerance (or the target
 * is beyond the reach bound), NO_CONVERGENCE only when max_iter cut an
 * attempt that was still improving. */
static void kin_ik_status(void)
{
    dh_robot r, r2;
    dh_ik_params_f32 p;
    dh_ik_result_f32 res;
    dh_mat4_f32 target;
    float q0[NJ] = { 0.0f, 30.0f, -60.0f, 0.0f, 45.0f, 0.0f };
    float q[NJ];
    dh_status st;
    unsigned mode;
    puma(&r);
    /* the review's example: trans(10, 0, 0), 10 m away (the Puma reaches
     * < 1.1 m): UNREACHABLE after a few attempts, not NO_CONVERGENCE after
     * the whole budget; the best effort is the stretched arm */
    for (mode = 0; mode < 2; mode++) {
        dh_mat4_trans_f32(10.0f, 0.0f, 0.0f, &target);
        ik_setup(&r, &p, &res);
        p.mask = mode ? DH_IK_POSITION : DH_IK_FULL;
        st = dh_ik_f32(&r, &target, q0, &p, work, sizeof work / sizeof work[0], q, &res);
        dht_printf("puma trans(10,0,0) %s: status %d after %lu steps, residual %.6g m\n", mode ? "position" : "full",
                   (int)st, (unsigned long)res.iterations, (double)res.err_pos);
        DHT_EQ_INT(st, DH_ERR_UNREACHABLE);
        DHT_TRUE(res.iterations < 400u);
        DHT_EQ_INT(dh_robot_check_limits_f32(&r, q), DH_OK);
        DHT_NEAR(res.err_pos, ref_pos_err(&r, &target, q), 1e-5);
        DHT_TRUE(res.err_pos > 8.9f && res.err_pos < 9.6f);
    }
    /* reachable, but max_iter cuts the first attempt while every step still
     * lowers E by far more than 1%: NO_CONVERGENCE */
    {
        float qt[NJ] = { 60.0f, -80.0f, 120.0f, 30.0f, 20.0f, -40.0f };   /* within the limits */
        uint32_t m;
        DHT_EQ_INT(dh_fk_f32(&r, qt, &target), DH_OK);
        for (m = 1; m <= 3; m++) {
            ik_setup(&r, &p, &res);
            p.max_iter = m;
            DHT_EQ_INT(dh_ik_f32(&r, &target, q0, &p, work, sizeof work / sizeof work[0], q, &res),
                       DH_ERR_NO_CONVERGENCE);
            DHT_EQ_INT(res.iterations, m);
        }
    }
    /* within the reach bound but not reachable within the joint limits
     * (planar 2R, both joints limited so that neither elbow solution is
     * admissible): every attempt stalls, whatever the budget -> UNREACHABLE */
    DHT_EQ_INT(dh_robot_init(&r2, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r2, DH_JOINT_REVOLUTE, 0, 0, 0.6f, 0), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r2, DH_JOINT_REVOLUTE, 0, 0, 0.4f, 0), DH_OK);
    DHT_EQ_INT(dh_robot_set_limits_f32(&r2, 0, 50.0f, 90.0f), DH_OK);
    DHT_EQ_INT(dh_robot_set_limits_f32(&r2, 1, 0.0f, 150.0f), DH_OK);
    {
        float qa[2] = { 35.0f, -70.0f }, q2[2], qs[2] = { 60.0f, 10.0f };
        dh_robot rf;
        DHT_EQ_INT(dh_robot_init(&rf, DH_CONV_STANDARD), DH_OK);
        DHT_EQ_INT(dh_robot_add_joint_f32(&rf, DH_JOINT_REVOLUTE, 0, 0, 0.6f, 0), DH_OK);
        DHT_EQ_INT(dh_robot_add_joint_f32(&rf, DH_JOINT_REVOLUTE, 0, 0, 0.4f, 0), DH_OK);
        DHT_EQ_INT(dh_fk_f32(&rf, qa, &target), DH_OK);
        for (mode = 0; mode < 3; mode++) {
            ik_setup(&r2, &p, &res);
            p.mask = DH_IK_PX | DH_IK_PY;
            p.restarts = (mode == 0) ? 0u : (mode == 1) ? 20u : 200u;
            st = dh_ik_f32(&r2, &target, qs, &p, work, sizeof work / sizeof work[0], q2, &res);
            dht_printf("2R outside its limits, %lu restarts: status %d after %lu steps, residual %.4g m\n",
                       (unsigned long)p.restarts, (int)st, (unsigned long)res.iterations, (double)res.err_pos);
            DHT_EQ_INT(st, DH_ERR_UNREACHABLE);
            DHT_EQ_INT(dh_robot_check_limits_f32(&r2, q2), DH_OK);
            DHT_TRUE(res.err_pos > 1e-3f);
        }
    }
}

static const dht_case cases[] = {
    DHT_CASE(kin_jacobian_bad),
    DHT_CASE(kin_rot_pose_error_bad),
    DHT_CASE(kin_ik_bad_args),
    DHT_CASE(kin_ik_unreachable),
    DHT_CASE(kin_ik_not_rigid),
    DHT_CASE(kin_ik_status),
};
DHT_MAIN(cases)
