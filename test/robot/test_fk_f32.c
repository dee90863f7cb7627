/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_fk_f32.c - robot description (float side) and float forward
 * kinematics: published poses, random configurations against the double
 * reference of support_robots.c, dense single-joint sweeps, random robots
 * (both conventions, prismatic joints, offsets, base and tool), frames,
 * link matrices and every error path.
 */
#include "dht.h"
#include "support_robots.h"
#include "dhmath/robot.h"
#include "dhmath/mat4.h"
#include "dhmath/trig.h"

#include <math.h>
#include <string.h>

#define R2D (180.0 / 3.14159265358979323846)

/* Bounds: the largest errors measured on the host over several seeds
 * (figures in docs/accuracy_fk.md) with about 1.5x headroom for other
 * seeds and for FMA contraction on Cortex-M4F/M7. Metres for positions. */
#define MODEL_POS_TOL 4.5e-7    /* measured <= 3.0e-7 (Puma, UR5, Panda) */
#define MODEL_ROT_TOL 4.5e-7    /* measured <= 3.1e-7 */
#define EXACT_POS_TOL 6.0e-7    /* vs the exact double model (float q and parameters): measured 4.0e-7 */
#define EXACT_ROT_TOL 1.2e-6    /* measured 7.8e-7 */
#define RR_POS_TOL 4.0e-7       /* random robots (offsets, base, tool), times the reach: measured 2.8e-7 */
#define RR_ROT_TOL 1.3e-6       /* measured 8.7e-7 */
#define LINK_POS_TOL 4.0e-7     /* single link matrix: measured 2.6e-7 */
#define LINK_ROT_TOL 8.0e-7     /* measured 5.4e-7 (q + offset rounded to float once) */

static void build(const dhs_robot *d, dh_robot *r)
{
    DHT_EQ_INT(dhs_build(d, r), DH_OK);
    DHT_TRUE((r->flags & DH_ROBOT_HAS_F32) != 0u);
}

static void fk(const dh_robot *r, const double *qd, dh_mat4_f32 *T)
{
    float q[DHS_MAX_JOINTS];
    uint32_t i;
    for (i = 0; i < r->n; i++) q[i] = (float)qd[i];
    DHT_EQ_INT(dh_fk_f32(r, q, T), DH_OK);
    DHT_TRUE(dhs_bottom_ok_f32(T));
}

/* Reference on the float-rounded joint values (what the code receives). */
static void ref(const dh_robot *r, const double *qd, dhr_mat4 *R)
{
    double qf[DHS_MAX_JOINTS];
    uint32_t i;
    for (i = 0; i < r->n; i++) qf[i] = (double)(float)qd[i];
    dhs_fk_ref_f32(r, qf, NULL, R);
}

static void check_rot(const dh_mat4_f32 *T, const double R[3][3], double tol)
{
    int r, c;
    for (r = 0; r < 3; r++)
        for (c = 0; c < 3; c++) DHT_NEAR(DH_M4(T, r, c), R[r][c], tol);
}

/* ---- published / hand-derived poses ----------------------------------- */

static void puma_zero_pose(void)
{
    /* Corke RTB Puma560 (with the 0.67183 m pedestal as d1) at qz:
     * p = (0.4521, -0.15005, 1.10363), R = I. */
    static const double I3[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
    dh_robot r;
    dh_mat4_f32 T;
    double q[6] = { 0, 0, 0, 0, 0, 0 };
    build(&dhs_puma560_m, &r);
    fk(&r, q, &T);
    DHT_NEAR(DH_M4(&T, 0, 3), 0.4521, 1e-6);
    DHT_NEAR(DH_M4(&T, 1, 3), -0.15005, 1e-6);
    DHT_NEAR(DH_M4(&T, 2, 3), 1.10363, 1e-6);
    check_rot(&T, I3, 1e-7);
}

static void panda_published_pose(void)
{
    /* Franka Panda (modified DH, flange 0.107 on joint 7, hand
     * trans(0,0,0.103) rotz(-45)) at q = (1..7) rad: first row of T is
     * (-0.8583, 0.1178, 0.4994, 0.1372) to 4 decimals. */
    dh_robot r;
    dh_mat4_f32 T;
    double q[7];
    int i;
    for (i = 0; i < 7; i++) q[i] = (double)(i + 1) * R2D;
    build(&dhs_panda_m, &r);
    fk(&r, q, &T);
    DHT_NEAR(DH_M4(&T, 0, 0), -0.8583, 5e-5);
    DHT_NEAR(DH_M4(&T, 0, 1), 0.1178, 5e-5);
    DHT_NEAR(DH_M4(&T, 0, 2), 0.4994, 5e-5);
    DHT_NEAR(DH_M4(&T, 0, 3), 0.1372, 5e-5);
}

static void ur5_poses(void)
{
    /* UR5 (UR's published DH). q = 0: arm stretched along -x:
     * p = (a2 + a3, -(d4 + d6), d1 - d5) = (-0.81725, -0.19145, -0.005491),
     * n = x, o = z, a = -y. q = (0,-90,0,-90,0,0): arm straight up,
     * p = (0, -(d4 + d6), d1 - a2 - a3 + d5) = (0, -0.19145, 1.001059),
     * n = -x, o = -z, a = -y. Both follow from the DH table by hand. */
    static const double R0[3][3] = { { 1, 0, 0 }, { 0, 0, -1 }, { 0, 1, 0 } };
    static const double R1[3][3] = { { -1, 0, 0 }, { 0, 0, -1 }, { 0, -1, 0 } };
    dh_robot r;
    dh_mat4_f32 T;
    double q0[6] = { 0, 0, 0, 0, 0, 0 };
    double q1[6] = { 0, -90, 0, -90, 0, 0 };
    build(&dhs_ur5_m, &r);
    fk(&r, q0, &T);
    DHT_NEAR(DH_M4(&T, 0, 3), -0.81725, 1e-6);
    DHT_NEAR(DH_M4(&T, 1, 3), -0.19145, 1e-6);
    DHT_NEAR(DH_M4(&T, 2, 3), -0.005491, 1e-6);
    check_rot(&T, R0, 1e-7);
    fk(&r, q1, &T);
    DHT_NEAR(DH_M4(&T, 0, 3), 0.0, 1e-6);
    DHT_NEAR(DH_M4(&T, 1, 3), -0.19145, 1e-6);
    DHT_NEAR(DH_M4(&T, 2, 3), 1.001059, 1e-6);
    check_rot(&T, R1, 1e-7);
}

/* ---- random configurations vs the double reference --------------------- */

static void random_configs(const dhs_robot *d, double pos_tol, double rot_tol)
{
    dh_robot r;
    dh_mat4_f32 T;
    dhr_mat4 R, D;
    double q[DHS_MAX_JOINTS], ep = 0, er = 0, epd = 0, erd = 0;
    long k, n = DHT_ITER(10000);
    build(d, &r);
    for (k = 0; k < n; k++) {
        double e;
        dhs_random_q(d, q);
        fk(&r, q, &T);
        ref(&r, q, &R);
        e = dhs_pos_err_f32(&T, &R);
        if (e > ep) ep = e;
        DHT_TRUE_MSG(e <= pos_tol, "%s pos err %.3g at k=%ld", d->name, e, k);
        e = dhs_rot_err_f32(&T, &R);
        if (e > er) er = e;
        DHT_TRUE_MSG(e <= rot_tol, "%s rot err %.3g at k=%ld", d->name, e, k);
        /* vs the exact double description (adds float rounding of the
         * parameters and of q): reported, bounded loosely */
        dhs_fk_desc(d, q, NULL, &D);
        e = dhs_pos_err_f32(&T, &D);
        if (e > epd) epd = e;
        e = dhs_rot_err_f32(&T, &D);
        if (e > erd) erd = e;
    }
    DHT_TRUE_MSG(epd <= EXACT_POS_TOL && erd <= EXACT_ROT_TOL, "%s vs exact: %.3g %.3g", d->name, epd, erd);
    dht_printf("fk_f32 %-8s %ld configs: max pos err %.3g m, max rot err %.3g (vs exact double model: %.3g m, %.3g)\n",
               d->name, n, ep, er, epd, erd);
}

static void puma_random(void) { random_configs(&dhs_puma560_m, MODEL_POS_TOL, MODEL_ROT_TOL); }
static void ur5_random(void) { random_configs(&dhs_ur5_m, MODEL_POS_TOL, MODEL_ROT_TOL); }
static void panda_random(void) { random_configs(&dhs_panda_m, MODEL_POS_TOL, MODEL_ROT_TOL); }

/* Dense sweep of every joint in turn (others random), steps of about
 * 0.0137 deg, so most angles fall between the whole-degree table points. */
static void dense_sweep(void)
{
    const dhs_robot *models[3] = { &dhs_puma560_m, &dhs_ur5_m, &dhs_panda_m };
    int m;
    for (m = 0; m < 3; m++) {
        const dhs_robot *d = models[m];
        dh_robot r;
        dh_mat4_f32 T;
        dhr_mat4 R;
        double q[DHS_MAX_JOINTS], ep = 0, er = 0;
        unsigned j;
        long k, steps = DHT_ITER(4000);
        build(d, &r);
        for (j = 0; j < d->n; j++) {
            double lo = d->j[j].qmin, hi = d->j[j].qmax;
            dhs_random_q(d, q);
            for (k = 0; k <= steps; k++) {
                q[j] = lo + (hi - lo) * (double)k / (double)steps;
                fk(&r, q, &T);
                ref(&r, q, &R);
                if (dhs_pos_err_f32(&T, &R) > ep) ep = dhs_pos_err_f32(&T, &R);
                if (dhs_rot_err_f32(&T, &R) > er) er = dhs_rot_err_f32(&T, &R);
            }
        }
        DHT_TRUE_MSG(ep <= MODEL_POS_TOL && er <= MODEL_ROT_TOL, "%s sweep: %.3g m %.3g", d->name, ep, er);
        dht_printf("fk_f32 %-8s dense sweep: max pos err %.3g m, max rot err %.3g\n", d->name, ep, er);
    }
}

/* ---- random robots: both conventions, prismatic joints, offsets, base/tool */

static void random_robot(dhs_robot *d)
{
    dhr_mat4 A;
    unsigned i;
    memset(d, 0, sizeof *d);
    d->name = "random";
    d->conv = (dht_rand_u32() & 1u) ? DH_CONV_MODIFIED : DH_CONV_STANDARD;
    d->n = 1u + dht_rand_u32() % (DH_MAX_JOINTS < DHS_MAX_JOINTS ? DH_MAX_JOINTS : DHS_MAX_JOINTS);
    d->unit_per_m = 1.0;
    for (i = 0; i < d->n; i++) {
        dhs_joint_desc *j = &d->j[i];
        j->type = (dht_rand_u32() % 4u == 0u) ? DH_JOINT_PRISMATIC : DH_JOINT_REVOLUTE;
        j->a = dht_rand_uniform(-0.5, 0.5);
        j->d = dht_rand_uniform(-0.5, 0.5);
        j->alpha_deg = (dht_rand_u32() & 1u) ? 90.0 * (double)(int)(dht_rand_u32() % 4u)
                                              : dht_rand_uniform(-180.0, 180.0);
        j->theta_deg = (dht_rand_u32() & 1u) ? 0.0 : dht_rand_uniform(-180.0, 180.0);
        if (j->type == DH_JOINT_PRISMATIC) { j->qmin = -0.3; j->qmax = 0.3; }
        else { j->qmin = -400.0; j->qmax = 400.0; }
    }
    /* base: a rigid motion; tool: rigid, sometimes identity */
    dhr_rotz(dht_rand_uniform(-180, 180), &d->base);
    dhr_rotx(dht_rand_uniform(-180, 180), &A);
    dhr_mul(&d->base, &A, &d->base);
    d->base.m[3][0] = dht_rand_uniform(-1, 1);
    d->base.m[3][1] = dht_rand_uniform(-1, 1);
    d->base.m[3][2] = dht_rand_uniform(-1, 1);
    if (dht_rand_u32() & 1u) {
        dhr_identity(&d->tool);
    } else {
        dhr_rotx(dht_rand_uniform(-180, 180), &d->tool);
        dhr_rotz(dht_rand_uniform(-180, 180), &A);
        dhr_mul(&d->tool, &A, &d->tool);
        d->tool.m[3][0] = dht_rand_uniform(-0.2, 0.2);
        d->tool.m[3][2] = dht_rand_uniform(-0.2, 0.2);
    }
    if (dht_rand_u32() % 4u == 0u) dhr_identity(&d->base);
}

static void random_robots(void)
{
    long k, n = DHT_ITER(3000);
    double ep = 0, er = 0, elp = 0, elr = 0;
    for (k = 0; k < n; k++) {
        dhs_robot d;
        dh_robot r;
        dh_mat4_f32 T, frames[DH_MAX_JOINTS], T2;
        dhr_mat4 R, RF[DHS_MAX_JOINTS];
        double q[DHS_MAX_JOINTS], reach;
        float qf[DHS_MAX_JOINTS];
        uint32_t i;
        random_robot(&d);
        build(&d, &r);
        dhs_random_q(&d, q);
        for (i = 0; i < r.n; i++) qf[i] = (float)q[i];
        fk(&r, q, &T);
        ref(&r, q, &R);
        /* position error relative to the reach L (sum of all lengths) */
        reach = dhs_chain_reach(&d, q);
        if (dhs_pos_err_f32(&T, &R) / reach > ep) ep = dhs_pos_err_f32(&T, &R) / reach;
        if (dhs_rot_err_f32(&T, &R) > er) er = dhs_rot_err_f32(&T, &R);
        DHT_TRUE_MSG(dhs_pos_err_f32(&T, &R) <= RR_POS_TOL * reach, "robot %ld pos %.3g", k, dhs_pos_err_f32(&T, &R));
        DHT_TRUE_MSG(dhs_rot_err_f32(&T, &R) <= RR_ROT_TOL, "robot %ld rot %.3g", k, dhs_rot_err_f32(&T, &R));

        /* every frame, and T_end identical to dh_fk_f32 */
        {
            double qq[DHS_MAX_JOINTS];
            for (i = 0; i < r.n; i++) qq[i] = (double)qf[i];
            dhs_fk_ref_f32(&r, qq, RF, NULL);
        }
        DHT_EQ_INT(dh_fk_frames_f32(&r, qf, frames, &T2), DH_OK);
        DHT_TRUE(memcmp(&T, &T2, sizeof T) == 0);
        for (i = 0; i < r.n; i++) {
            DHT_TRUE(dhs_bottom_ok_f32(&frames[i]));
            DHT_TRUE(dhs_pos_err_f32(&frames[i], &RF[i]) <= RR_POS_TOL * reach);
            DHT_TRUE(dhs_rot_err_f32(&frames[i], &RF[i]) <= RR_ROT_TOL);
        }
        DHT_EQ_INT(dh_fk_frames_f32(&r, qf, frames, NULL), DH_OK);

        /* link matrices */
        for (i = 0; i < r.n; i++) {
            dh_mat4_f32 A;
            dhr_mat4 RA;
            const dh_joint *j = &r.joint[i];
            DHT_EQ_INT(dh_link_f32(&r, i, qf[i], &A), DH_OK);
            dhs_link(r.conv, j->type, (double)j->a, (double)j->d, (double)j->alpha_deg,
                     (double)j->theta_deg, (double)qf[i], &RA);
            DHT_TRUE(dhs_bottom_ok_f32(&A));
            if (dhs_pos_err_f32(&A, &RA) > elp) elp = dhs_pos_err_f32(&A, &RA);
            if (dhs_rot_err_f32(&A, &RA) > elr) elr = dhs_rot_err_f32(&A, &RA);
            DHT_TRUE(dhs_pos_err_f32(&A, &RA) <= LINK_POS_TOL);
            DHT_TRUE(dhs_rot_err_f32(&A, &RA) <= LINK_ROT_TOL);
        }
    }
    dht_printf("fk_f32 random robots (%ld): max pos err %.3g x reach, max rot err %.3g; link matrices %.3g m, %.3g\n",
               n, ep, er, elp, elr);
}

/* Large joint angles: exact reduction, error does not grow with |q|. */
static void large_angles(void)
{
    dh_robot r;
    dh_mat4_f32 T;
    dhr_mat4 R;
    double q[6], ep = 0, er = 0;
    long k;
    build(&dhs_ur5_m, &r);
    for (k = 0; k < DHT_ITER(2000); k++) {
        int i;
        for (i = 0; i < 6; i++) q[i] = dht_rand_uniform(-30000.0, 30000.0);
        fk(&r, q, &T);
        ref(&r, q, &R);
        if (dhs_pos_err_f32(&T, &R) > ep) ep = dhs_pos_err_f32(&T, &R);
        if (dhs_rot_err_f32(&T, &R) > er) er = dhs_rot_err_f32(&T, &R);
    }
    DHT_TRUE_MSG(ep <= MODEL_POS_TOL && er <= MODEL_ROT_TOL, "large angles %.3g %.3g", ep, er);
    dht_printf("fk_f32 ur5 |q| <= 30000 deg: max pos err %.3g m, max rot err %.3g\n", ep, er);
}

/* ---- description API and error paths ---------------------------------- */

static void init_and_add_errors(void)
{
    dh_robot r, r0;
    dh_mat4_f32 T;
    float q[DH_MAX_JOINTS + 1];
    uint32_t i;
    memset(q, 0, sizeof q);
    DHT_EQ_INT(dh_robot_init(&r, (dh_convention)7), DH_ERR_ARG);
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(r.n, 0);
    DHT_TRUE((r.flags & (DH_ROBOT_HAS_F32 | DH_ROBOT_HAS_Q)) == (DH_ROBOT_HAS_F32 | DH_ROBOT_HAS_Q));

    /* n == 0 -> DH_ERR_ARG, output untouched */
    memset(&T, 0x5a, sizeof T);
    DHT_EQ_INT(dh_fk_f32(&r, q, &T), DH_ERR_ARG);
    DHT_EQ_INT(((unsigned char *)&T)[0], 0x5a);

    /* bad type, non-finite parameters: robot untouched */
    r0 = r;
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, (dh_joint_type)5, 0, 0, 0, 0), DH_ERR_ARG);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0, 0, NAN, 0), DH_ERR_NAN);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0, INFINITY, 0, 0), DH_ERR_NAN);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0, 0, 0, -INFINITY), DH_ERR_NAN);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, NAN, 0, 0, 0), DH_ERR_NAN);
    DHT_TRUE(memcmp(&r, &r0, sizeof r) == 0);

    /* capacity: DH_MAX_JOINTS joints, the next one is refused */
    for (i = 0; i < (uint32_t)DH_MAX_JOINTS; i++)
        DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0, 0, 0.1f, 90), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0, 0, 0.1f, 90), DH_ERR_ARG);
    DHT_EQ_INT(r.n, DH_MAX_JOINTS);
    DHT_EQ_INT(dh_fk_f32(&r, q, &T), DH_OK);

    /* link index out of range */
    DHT_EQ_INT(dh_link_f32(&r, (uint32_t)DH_MAX_JOINTS, 0, &T), DH_ERR_ARG);
    DHT_EQ_INT(dh_link_f32(&r, 0, NAN, &T), DH_ERR_NAN);
}

static void nan_joint_values(void)
{
    dh_robot r;
    dh_mat4_f32 T, frames[6];
    float q[6] = { 10, 20, 30, 40, 50, 60 };
    float bad[3] = { NAN, INFINITY, -INFINITY };
    int i, b;
    build(&dhs_puma560_m, &r);
    for (b = 0; b < 3; b++)
        for (i = 0; i < 6; i++) {
            float qq[6];
            memcpy(qq, q, sizeof q);
            qq[i] = bad[b];
            memset(&T, 0x5a, sizeof T);
            memset(frames, 0x5a, sizeof frames);
            DHT_EQ_INT(dh_fk_f32(&r, qq, &T), DH_ERR_NAN);
            DHT_EQ_INT(((unsigned char *)&T)[17], 0x5a);
            DHT_EQ_INT(dh_fk_frames_f32(&r, qq, frames, &T), DH_ERR_NAN);
            DHT_EQ_INT(((unsigned char *)frames)[0], 0x5a);
            DHT_EQ_INT(dh_robot_check_limits_f32(&r, qq), DH_ERR_NAN);
        }
    /* finite q whose sum with the offset overflows to infinity */
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 3e38f, 0, 1, 0), DH_OK);
    q[0] = 3e38f;
    memset(&T, 0x5a, sizeof T);
    DHT_EQ_INT(dh_fk_f32(&r, q, &T), DH_ERR_OVERFLOW);
    DHT_EQ_INT(((unsigned char *)&T)[5], 0x5a);
    DHT_EQ_INT(dh_link_f32(&r, 0, q[0], &T), DH_ERR_OVERFLOW);
}

static void overflow_to_inf(void)
{
    dh_robot r;
    dh_mat4_f32 T;
    float q[2] = { 3e38f, 3e38f };
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_PRISMATIC, 0, 3e38f, 0, 0), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_PRISMATIC, 0, 3e38f, 0, 0), DH_OK);
    /* each d = q + 3e38 -> inf: refused before anything is written */
    q[0] = 1e38f;
    q[1] = 1e38f;
    DHT_EQ_INT(dh_fk_f32(&r, q, &T), DH_ERR_OVERFLOW);
    /* finite per joint but the sum of the chain overflows */
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_PRISMATIC, 0, 0, 0, 0), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_PRISMATIC, 0, 0, 0, 0), DH_OK);
    q[0] = 3e38f;
    q[1] = 3e38f;
    DHT_EQ_INT(dh_fk_f32(&r, q, &T), DH_ERR_OVERFLOW);
    DHT_TRUE(isinf(DH_M4(&T, 2, 3)));
}

static void limits(void)
{
    dh_robot r;
    float q[6] = { 0, 0, 0, 0, 0, 0 };
    build(&dhs_puma560_m, &r);
    DHT_EQ_INT(dh_robot_check_limits_f32(&r, q), DH_OK);
    q[1] = 110.0f;
    DHT_EQ_INT(dh_robot_check_limits_f32(&r, q), DH_OK);
    q[1] = 110.001f;
    DHT_EQ_INT(dh_robot_check_limits_f32(&r, q), DH_ERR_LIMIT);
    q[1] = 0;
    q[5] = -266.5f;
    DHT_EQ_INT(dh_robot_check_limits_f32(&r, q), DH_ERR_LIMIT);
    q[5] = 0;
    DHT_EQ_INT(dh_robot_set_limits_f32(&r, 6, 0, 1), DH_ERR_ARG);
    DHT_EQ_INT(dh_robot_set_limits_f32(&r, 0, 2, 1), DH_ERR_ARG);
    DHT_EQ_INT(dh_robot_set_limits_f32(&r, 0, NAN, 1), DH_ERR_NAN);
    DHT_EQ_INT(dh_robot_set_limits_f32(&r, 0, 0, INFINITY), DH_ERR_NAN);
    DHT_NEAR(r.joint[0].qmin, -160.0, 0);
    /* the fixed-path limits follow (deg Q16.16) */
    DHT_EQ_INT(r.joint[0].qmin_q, -160 * 65536);
    DHT_EQ_INT(r.joint[0].qmax_q, 160 * 65536);
    /* a joint without limits accepts anything finite */
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0, 0, 0, 0), DH_OK);
    q[0] = 1e30f;
    DHT_EQ_INT(dh_robot_check_limits_f32(&r, q), DH_OK);
    /* limits beyond the Q range saturate on the fixed side */
    DHT_EQ_INT(dh_robot_set_limits_f32(&r, 0, -1e30f, 1e30f), DH_OK);
    DHT_EQ_INT(r.joint[0].qmin_q, INT32_MIN);
    DHT_EQ_INT(r.joint[0].qmax_q, INT32_MAX);
}

static void base_tool(void)
{
    dh_robot r, r0;
    dh_mat4_f32 B, T, T2;
    dhr_mat4 R;
    double q[6] = { 10, -20, 30, -40, 50, -60 };
    int c, k;
    build(&dhs_puma560_m, &r);
    DHT_TRUE((r.flags & DH_ROBOT_BASE_ID_F32) && (r.flags & DH_ROBOT_TOOL_ID_F32));
    /* non-finite or non-affine frames refused, robot untouched */
    for (c = 0; c < 4; c++)
        for (k = 0; k < 4; k++) B.m[c][k] = (c == k) ? 1.0f : 0.0f;
    r0 = r;
    B.m[3][1] = NAN;
    DHT_EQ_INT(dh_robot_set_base_f32(&r, &B), DH_ERR_NAN);
    B.m[3][1] = 0;
    B.m[0][3] = 0.5f;
    DHT_EQ_INT(dh_robot_set_tool_f32(&r, &B), DH_ERR_NOT_RIGID);
    B.m[0][3] = 0;
    B.m[3][3] = 2.0f;
    DHT_EQ_INT(dh_robot_set_base_f32(&r, &B), DH_ERR_NOT_RIGID);
    DHT_TRUE(memcmp(&r, &r0, sizeof r) == 0);
    /* a scaled tool (affine, allowed by the robot file format) is applied as given */
    B.m[3][3] = 1.0f;
    B.m[0][0] = 2.0f;
    B.m[1][1] = 0.5f;
    B.m[3][0] = 0.1f;
    DHT_EQ_INT(dh_robot_set_tool_f32(&r, &B), DH_OK);
    DHT_TRUE((r.flags & DH_ROBOT_TOOL_ID_F32) == 0u);
    fk(&r, q, &T);
    ref(&r, q, &R);
    DHT_TRUE(dhs_pos_err_f32(&T, &R) <= MODEL_POS_TOL);
    DHT_TRUE(dhs_rot_err_f32(&T, &R) <= 2.0 * MODEL_ROT_TOL); /* entries up to 2 */
    /* setting the identity back restores the skip and the same result as before */
    for (c = 0; c < 4; c++)
        for (k = 0; k < 4; k++) B.m[c][k] = (c == k) ? 1.0f : 0.0f;
    DHT_EQ_INT(dh_robot_set_tool_f32(&r, &B), DH_OK);
    DHT_TRUE((r.flags & DH_ROBOT_TOOL_ID_F32) != 0u);
    fk(&r, q, &T);
    build(&dhs_puma560_m, &r0);
    fk(&r0, q, &T2);
    DHT_TRUE(memcmp(&T, &T2, sizeof T) == 0);
    /* a frame whose position does not fit Q leaves the float path usable and
     * makes the fixed one unavailable */
    B.m[3][0] = 1e6f;
    DHT_EQ_INT(dh_robot_set_base_f32(&r, &B), DH_OK);
    DHT_TRUE((r.flags & DH_ROBOT_HAS_F32) != 0u);
    DHT_TRUE((r.flags & DH_ROBOT_HAS_Q) == 0u);
    fk(&r, q, &T);
    DHT_NEAR(DH_M4(&T, 0, 3), 1e6 + (double)DH_M4(&T2, 0, 3), 0.07);
    B.m[3][0] = 0;
    DHT_EQ_INT(dh_robot_set_base_f32(&r, &B), DH_OK);
    DHT_TRUE((r.flags & DH_ROBOT_HAS_Q) != 0u);
}

/* ---- exact bits ---------------------------------------------------------- */

/* An angle for the bit tests: whole multiples of 90 degrees (sines and
 * cosines of exactly 0 and +-1, so zeros of either sign appear), or any. */
static float bit_angle(void)
{
    if (dht_rand_uniform(0, 1) < 0.5) return 90.0f * (float)floor(dht_rand_uniform(-4.0, 5.0));
    return (float)dht_rand_uniform(-360, 360);
}

/* A length for the bit tests: 0, -0 or any. */
static float bit_len(void)
{
    double u = dht_rand_uniform(0, 1);
    if (u < 0.2) return 0.0f;
    if (u < 0.3) return -0.0f;
    return (float)dht_rand_uniform(-2, 2);
}

/*
 * dh_link_f32, and dh_fk_f32 of the same joint alone behind the identity
 * base and tool, give exactly the link matrix written out (each entry a
 * sine, cosine or length, or one product of two; the signs of zeros
 * included), in both conventions, for R and P joints. Sines and cosines
 * from dh_sincos_f32 and the robot description, the products in the
 * test. DH_SMALL builds the link as the general step applied to the
 * identity: the same values, but a zero may come out with the other sign
 * (-st ca is -0 where the step's 1 * 0 - 0 * 1 is +0; the header promises
 * nothing about signs of zeros). There every nonzero entry must have the
 * same bits and every zero must be a zero; step_bits pins the small
 * build's exact bits, zeros included, for the identity base too.
 */
static void link_bits(void)
{
    long rep, nrep = DHT_ITER(3000);
    for (rep = 0; rep < nrep; rep++) {
        dh_robot r;
        dh_mat4_f32 A, T, E;
        const int conv = (int)(rep & 1), pris = (rep % 3) == 0;
        const float al = bit_angle(), th = bit_angle(), a = bit_len(), d = bit_len();
        const float q = pris ? bit_len() : bit_angle();
        float st, ct, sa, ca, dd;
        int c, k;
        DHT_EQ_INT(dh_robot_init(&r, conv ? DH_CONV_MODIFIED : DH_CONV_STANDARD), DH_OK);
        DHT_EQ_INT(dh_robot_add_joint_f32(&r, pris ? DH_JOINT_PRISMATIC : DH_JOINT_REVOLUTE, th, d, a, al), DH_OK);
        sa = r.joint[0].sa;
        ca = r.joint[0].ca;
        DHT_EQ_INT(dh_sincos_f32(pris ? th : q + th, &st, &ct), DH_OK);
        dd = pris ? q + d : d;
        if (conv == 0) {
            E.m[0][0] = ct;       E.m[0][1] = st;       E.m[0][2] = 0.0f;
            E.m[1][0] = -st * ca; E.m[1][1] = ct * ca;  E.m[1][2] = sa;
            E.m[2][0] = st * sa;  E.m[2][1] = -ct * sa; E.m[2][2] = ca;
            E.m[3][0] = a * ct;   E.m[3][1] = a * st;   E.m[3][2] = dd;
        } else {
            E.m[0][0] = ct;       E.m[0][1] = st * ca;  E.m[0][2] = st * sa;
            E.m[1][0] = -st;      E.m[1][1] = ct * ca;  E.m[1][2] = ct * sa;
            E.m[2][0] = 0.0f;     E.m[2][1] = -sa;      E.m[2][2] = ca;
            E.m[3][0] = a;        E.m[3][1] = -sa * dd; E.m[3][2] = ca * dd;
        }
        for (c = 0; c < 4; c++) E.m[c][3] = c == 3 ? 1.0f : 0.0f;
        memset(&A, 0x5a, sizeof A);
        DHT_EQ_INT(dh_link_f32(&r, 0, q, &A), DH_OK);
        DHT_EQ_INT(dh_fk_f32(&r, &q, &T), DH_OK);
        for (c = 0; c < 4; c++)
            for (k = 0; k < 4; k++) {
#if DH_SMALL
                if (E.m[c][k] == 0.0f) {
                    DHT_TRUE(A.m[c][k] == 0.0f);
                    DHT_TRUE(T.m[c][k] == 0.0f);
                    continue;
                }
#endif
                DHT_EQ_F32_BITS(A.m[c][k], E.m[c][k]);
                DHT_EQ_F32_BITS(T.m[c][k], E.m[c][k]);
            }
    }
}

/*
 * One joint behind a base: the documented update (dh_fk_f32.c), evaluated
 * here in the same order, gives the same bits, signs of zeros included,
 * in both conventions (DH_SMALL serves both with one step whose rotation
 * and position order depend on the convention). Bases: rotations by whole
 * multiples of 90 degrees (exact zeros of either sign) or any, and any
 * position. Assumes no FMA contraction (C99 mode, -ffp-contract=off).
 * DH_SMALL has no written-out link: an identity base goes through the
 * same step (dh_fk_f32), and so does dh_link_f32 (the step applied to the
 * identity), so both are held to these bits there, zeros included.
 */
static void step_bits(void)
{
    long rep, nrep = DHT_ITER(3000);
#if DH_SMALL
    long nid = 0;
#endif
    for (rep = 0; rep < nrep; rep++) {
        dh_robot r;
        dh_mat4_f32 B, Rx, T, E;
        const int conv = (int)(rep & 1), pris = (rep % 3) == 0;
        const float al = bit_angle(), th = bit_angle(), a = bit_len(), d = bit_len();
        const float q = pris ? bit_len() : bit_angle();
        float st, ct, sa, ca, dd;
        int c, k;
        DHT_EQ_INT(dh_mat4_rotz_f32(bit_angle(), &B), DH_OK);
        DHT_EQ_INT(dh_mat4_rotx_f32(bit_angle(), &Rx), DH_OK);
        dh_mat4_mul_f32(&B, &Rx, &B);
        for (k = 0; k < 3; k++) B.m[3][k] = bit_len();
#if DH_SMALL
        if (rep % 4 == 3) dh_mat4_identity_f32(&B); /* often enough the identity base */
#endif
        DHT_EQ_INT(dh_robot_init(&r, conv ? DH_CONV_MODIFIED : DH_CONV_STANDARD), DH_OK);
        DHT_EQ_INT(dh_robot_add_joint_f32(&r, pris ? DH_JOINT_PRISMATIC : DH_JOINT_REVOLUTE, th, d, a, al), DH_OK);
        DHT_EQ_INT(dh_robot_set_base_f32(&r, &B), DH_OK);
#if !DH_SMALL
        if ((r.flags & DH_ROBOT_BASE_ID_F32) != 0u) continue; /* the written-out link: link_bits */
#endif
        sa = r.joint[0].sa;
        ca = r.joint[0].ca;
        DHT_EQ_INT(dh_sincos_f32(pris ? th : q + th, &st, &ct), DH_OK);
        dd = pris ? q + d : d;
        E = B;
        for (k = 0; k < 3; k++) {
            const float nx = B.m[0][k], ox = B.m[1][k], ax = B.m[2][k], px = B.m[3][k];
            if (conv == 0) {
                const float n1 = ct * nx + st * ox, u = ct * ox - st * nx;
                E.m[3][k] = px + dd * ax + a * n1;
                E.m[0][k] = n1;
                E.m[1][k] = ca * u + sa * ax;
                E.m[2][k] = ca * ax - sa * u;
            } else {
                const float o1 = ca * ox + sa * ax, a1 = ca * ax - sa * ox;
                E.m[3][k] = px + a * nx + dd * a1;
                E.m[0][k] = ct * nx + st * o1;
                E.m[1][k] = ct * o1 - st * nx;
                E.m[2][k] = a1;
            }
        }
        for (c = 0; c < 4; c++) E.m[c][3] = c == 3 ? 1.0f : 0.0f;
        DHT_EQ_INT(dh_fk_f32(&r, &q, &T), DH_OK);
        for (c = 0; c < 4; c++)
            for (k = 0; k < 4; k++) DHT_EQ_F32_BITS(T.m[c][k], E.m[c][k]);
#if DH_SMALL
        if ((r.flags & DH_ROBOT_BASE_ID_F32) != 0u) {
            nid++;
            DHT_EQ_INT(dh_link_f32(&r, 0, q, &T), DH_OK);
            for (c = 0; c < 4; c++)
                for (k = 0; k < 4; k++) DHT_EQ_F32_BITS(T.m[c][k], E.m[c][k]);
        }
#endif
    }
#if DH_SMALL
    DHT_TRUE(nid > 0); /* the identity base was met */
#endif
}

static void q_only_robot_refused(void)
{
    dh_robot r;
    dh_mat4_f32 T;
    float q[6] = { 0, 0, 0, 0, 0, 0 };
    DHT_EQ_INT(dhs_build_q(&dhs_puma560_mm, &r), DH_OK);
    DHT_TRUE((r.flags & DH_ROBOT_HAS_F32) == 0u);
    DHT_TRUE((r.flags & DH_ROBOT_HAS_Q) != 0u);
    memset(&T, 0x5a, sizeof T);
    DHT_EQ_INT(dh_fk_f32(&r, q, &T), DH_ERR_UNAVAILABLE);
    DHT_EQ_INT(((unsigned char *)&T)[63], 0x5a);
    DHT_EQ_INT(dh_link_f32(&r, 0, 0, &T), DH_ERR_UNAVAILABLE);
    /* a float joint added later does not bring the float path back */
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_MODIFIED), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0, 0, 0, 0), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_q(&r, DH_JOINT_REVOLUTE, 0, 0, 0, 0), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0, 0, 0, 0), DH_OK);
    DHT_EQ_INT(dh_fk_f32(&r, q, &T), DH_ERR_UNAVAILABLE);
}

static const dht_case cases[] = {
    DHT_CASE(puma_zero_pose),
    DHT_CASE(panda_published_pose),
    DHT_CASE(ur5_poses),
    DHT_CASE(puma_random),
    DHT_CASE(ur5_random),
    DHT_CASE(panda_random),
    DHT_CASE(dense_sweep),
    DHT_CASE(random_robots),
    DHT_CASE(large_angles),
    DHT_CASE(init_and_add_errors),
    DHT_CASE(nan_joint_values),
    DHT_CASE(overflow_to_inf),
    DHT_CASE(limits),
    DHT_CASE(base_tool),
    DHT_CASE(q_only_robot_refused),
    DHT_CASE(link_bits),
    DHT_CASE(step_bits),
};
DHT_MAIN(cases)
