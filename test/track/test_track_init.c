/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_track_init.c - the trackers' start (track.h: dh_track_init_f32,
 * dh_track_init_q) with the models they refuse, and the trackers with the
 * closed forms of robots with a prismatic joint: the Stanford arm in mm
 * (DH_IKC_WRIST_RRP, fixed), with and without limits on that joint, and
 * the Cobra 600 (DH_IKC_SCARA, fixed and float):
 * - DH_ERR_ARG for a model of another joint count (the Cobra 600's SCARA
 *   for the UR5), a model of kind NONE (the Panda's), and a control
 *   period that is not finite and > 0 (float) or outside 1..10^6 us;
 * - started at q and given FK(q) (the double reference) as its target:
 *   state OK in one step, the output within pos_tol and rot_tol of the
 *   target by the double reference, within the limits; a target moved by
 *   1 length unit on the prismatic joint and 0.5 deg on the others reached
 *   OK the same way, every step within dq_max.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "dht.h"
#include "support_robots.h"
#include "dhmath/ikc.h"
#include "dhmath/track.h"

#define DT_US 1000u
#define QPOS ((double)((int32_t)1 << DH_QPOS_FRAC))

/* static: the micro:bit's RAM holds them beside the suite's stack (one
 * tracker and one model at a time) */
static dh_robot rob, other;
static union {
    dh_track_f32 f;
    dh_track_q q;
} trk;
static union {
    dh_ikc_model_f32 f;
    dh_ikc_model_q q;
} mdl;

static void track_init_refused(void)
{
    const float q0[6] = { 30.0f, -80.0f, 90.0f, -100.0f, -90.0f, 20.0f };
    static const float bad_dt[5] = { 0.0f, -1e-3f, INFINITY, -INFINITY, NAN };
    int32_t qq[6];
    unsigned k;
    /* float */
    DHT_EQ_INT(dhs_build(&dhs_ur5_m, &rob), DH_OK);
    DHT_EQ_INT(dhs_build(&dhs_cobra600_m, &other), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_f32(&other, &mdl.f), DH_OK);
    DHT_EQ_INT(mdl.f.kind, DH_IKC_SCARA);
    DHT_EQ_INT(dh_track_init_f32(&trk.f, &rob, &mdl.f, q0, 1e-3f), DH_ERR_ARG);
    DHT_EQ_INT(dhs_build(&dhs_panda_m, &other), DH_OK);
    DHT_TRUE(dh_ikc_analyse_f32(&other, &mdl.f) != DH_OK);
    DHT_EQ_INT(mdl.f.kind, DH_IKC_NONE);
    mdl.f.n = 6u;
    DHT_EQ_INT(dh_track_init_f32(&trk.f, &rob, &mdl.f, q0, 1e-3f), DH_ERR_ARG);
    for (k = 0; k < 5u; k++) DHT_EQ_INT(dh_track_init_f32(&trk.f, &rob, NULL, q0, bad_dt[k]), DH_ERR_ARG);
    DHT_EQ_INT(dh_ikc_analyse_f32(&rob, &mdl.f), DH_OK);
    DHT_EQ_INT(dh_track_init_f32(&trk.f, &rob, &mdl.f, q0, 1e-3f), DH_OK);
    /* fixed */
    DHT_EQ_INT(dhs_build_q(&dhs_ur5_mm, &rob), DH_OK);
    for (k = 0; k < 6u; k++) qq[k] = (int32_t)q0[k] * 65536;
    DHT_EQ_INT(dhs_build_q(&dhs_cobra600_mm, &other), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_q(&other, &mdl.q), DH_OK);
    DHT_EQ_INT(mdl.q.kind, DH_IKC_SCARA);
    DHT_EQ_INT(dh_track_init_q(&trk.q, &rob, &mdl.q, qq, DT_US), DH_ERR_ARG);
    DHT_EQ_INT(dhs_build_q(&dhs_panda_mm, &other), DH_OK);
    DHT_TRUE(dh_ikc_analyse_q(&other, &mdl.q) != DH_OK);
    DHT_EQ_INT(mdl.q.kind, DH_IKC_NONE);
    mdl.q.n = 6u;
    DHT_EQ_INT(dh_track_init_q(&trk.q, &rob, &mdl.q, qq, DT_US), DH_ERR_ARG);
    DHT_EQ_INT(dh_track_init_q(&trk.q, &rob, NULL, qq, 0u), DH_ERR_ARG);
    DHT_EQ_INT(dh_track_init_q(&trk.q, &rob, NULL, qq, 1000001u), DH_ERR_ARG);
    DHT_EQ_INT(dh_ikc_analyse_q(&rob, &mdl.q), DH_OK);
    DHT_EQ_INT(dh_track_init_q(&trk.q, &rob, &mdl.q, qq, DT_US), DH_OK);
}

/* the target of q (double reference FK, rounded to the fixed frame) */
static void target_of(const int32_t *q, dh_frame_q *T, dhr_mat4 *D)
{
    dhs_fk_ref_q(&rob, q, NULL, D);
    dhs_to_frame_q(D, T);
}

/* q_out within the limits, FK(q_out) within pos_tol (mm) and rot_tol of D */
static void check_reached(const int32_t *q, const dhr_mat4 *D)
{
    dhr_mat4 F;
    dh_frame_q T;
    uint32_t i;
    for (i = 0; i < rob.n; i++)
        if (rob.joint[i].qmin_q <= rob.joint[i].qmax_q) DHT_TRUE(q[i] >= rob.joint[i].qmin_q && q[i] <= rob.joint[i].qmax_q);
    dhs_fk_ref_q(&rob, q, NULL, &F);
    dhs_to_frame_q(&F, &T);
    DHT_TRUE_MSG(dhs_pos_err_q(&T, D) * QPOS <= (double)trk.q.pos_tol + 1.0, "position %.6g mm, pos_tol %ld LSB",
                 dhs_pos_err_q(&T, D), (long)trk.q.pos_tol);
    DHT_TRUE_MSG(dhs_rot_err_q(&T, D) <= ldexp((double)trk.q.rot_tol, -29) + 4e-9, "rotation %.6g rad, rot_tol %ld",
                 dhs_rot_err_q(&T, D), (long)trk.q.rot_tol);
}

/* the fixed tracker with its closed form (kind) on rob at the n
 * configurations qs: FK(q) reached in one step, then the target of q moved
 * by 1 length unit on the prismatic joint and 0.5 deg on the others */
static void fixed_run(dh_ikc_kind kind, const double (*qs)[6], uint32_t nq)
{
    int32_t q[6], qo[6];
    dh_frame_q T;
    dhr_mat4 D;
    dh_track_report_q rep;
    uint32_t k, i;
    long step;
    DHT_EQ_INT(dh_ikc_analyse_q(&rob, &mdl.q), DH_OK);
    DHT_EQ_INT(mdl.q.kind, kind);
    for (k = 0; k < nq; k++) {
        dhs_q_from_double(&rob, qs[k], q);
        DHT_EQ_INT(dh_track_init_q(&trk.q, &rob, &mdl.q, q, DT_US), DH_OK);
        target_of(q, &T, &D);
        DHT_EQ_INT(dh_track_step_q(&trk.q, &T, qo, &rep), DH_OK);
        DHT_EQ_INT(rep.state, DH_TRACK_OK);
        check_reached(qo, &D);
        for (i = 0; i < rob.n; i++) q[i] += (rob.joint[i].type == DH_JOINT_PRISMATIC) ? (int32_t)QPOS : 32768;
        target_of(q, &T, &D);
        for (step = 0; step < 100; step++) {
            int32_t prev[6];
            memcpy(prev, trk.q.q, sizeof prev);
            DHT_EQ_INT(dh_track_step_q(&trk.q, &T, qo, &rep), DH_OK);
            for (i = 0; i < rob.n; i++) DHT_TRUE(labs((long)qo[i] - (long)prev[i]) <= (long)trk.q.dq_max[i]);
            if (rep.state == DH_TRACK_OK) break;
        }
        DHT_TRUE_MSG(rep.state == DH_TRACK_OK, "configuration %u: state %d after %ld steps", (unsigned)k, (int)rep.state,
                     step);
        check_reached(qo, &D);
    }
}

/* rob's rates: 90 deg/s and 900 deg/s^2, 500 and 5000 mm/s^k */
static void set_rates(void)
{
    uint32_t i;
    for (i = 0; i < rob.n; i++) {
        const int rev = rob.joint[i].type == DH_JOINT_REVOLUTE;
        DHT_EQ_INT(dh_robot_set_rates_q(&rob, i, rev ? 90 * 65536 : (int32_t)(500.0 * QPOS),
                                        rev ? 900 * 65536 : (int32_t)(5000.0 * QPOS)), DH_OK);
    }
}

static void track_q_prismatic_closed_form(void)
{
    static const double qs[3][6] = {
        { 20.0, -30.0, 600.0, 40.0, 50.0, -60.0 },
        { -100.0, 60.0, 400.0, -120.0, -30.0, 150.0 },
        { 150.0, -150.0, 1100.0, 10.0, 80.0, 0.0 },
    };
    dhs_robot d = dhs_stanford_mm;
    DHT_EQ_INT(dhs_build_q(&d, &rob), DH_OK);
    set_rates();
    fixed_run(DH_IKC_WRIST_RRP, qs, 3u);
    /* the prismatic joint without limits */
    d.j[2].qmin = 1.0;
    d.j[2].qmax = -1.0;
    DHT_EQ_INT(dhs_build_q(&d, &rob), DH_OK);
    set_rates();
    fixed_run(DH_IKC_WRIST_RRP, qs, 3u);
}

/* The SCARA (Cobra 600, DH_IKC_SCARA) with its closed form in both
 * trackers: FK(q) reached in one step (float: the output within pos_tol
 * and rot_tol of the target by the double reference), a nearby target
 * within the steps' bounds. */
static void track_scara_closed_form(void)
{
    static const double qs[2][6] = { { 20.0, -40.0, 100.0, 30.0 }, { -35.0, 70.0, 50.0, -200.0 } };
    float q[4], qo[4], prev[4];
    dh_mat4_f32 T;
    dh_track_report_f32 rep;
    double ep, er;
    uint32_t k, i;
    long step;
    DHT_EQ_INT(dhs_build_q(&dhs_cobra600_mm, &rob), DH_OK);
    set_rates();
    fixed_run(DH_IKC_SCARA, qs, 2u);
    DHT_EQ_INT(dhs_build(&dhs_cobra600_m, &rob), DH_OK);
    for (i = 0; i < 4u; i++)
        DHT_EQ_INT(dh_robot_set_rates_f32(&rob, i, rob.joint[i].type == DH_JOINT_REVOLUTE ? 90.0f : 0.5f,
                                          rob.joint[i].type == DH_JOINT_REVOLUTE ? 900.0f : 5.0f), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_f32(&rob, &mdl.f), DH_OK);
    DHT_EQ_INT(mdl.f.kind, DH_IKC_SCARA);
    for (k = 0; k < 2u; k++) {
        double qd[6];
        for (i = 0; i < 4u; i++) {
            qd[i] = qs[k][i] * ((rob.joint[i].type == DH_JOINT_REVOLUTE) ? 1.0 : 1e-3);
            q[i] = (float)qd[i];
        }
        DHT_EQ_INT(dh_track_init_f32(&trk.f, &rob, &mdl.f, q, 1e-3f), DH_OK);
        dhs_target_f32(&rob, qd, &T);
        DHT_EQ_INT(dh_track_step_f32(&trk.f, &T, qo, &rep), DH_OK);
        DHT_EQ_INT(rep.state, DH_TRACK_OK);
        dhs_true_error_f32(&rob, qo, &T, &ep, &er);
        DHT_TRUE_MSG(ep <= (double)trk.f.pos_tol && er <= (double)trk.f.rot_tol, "%.3g m, %.3g rad", ep, er);
        for (i = 0; i < 4u; i++) qd[i] += (rob.joint[i].type == DH_JOINT_PRISMATIC) ? 1e-3 : 0.5;
        dhs_target_f32(&rob, qd, &T);
        for (step = 0; step < 100; step++) {
            memcpy(prev, trk.f.q, sizeof prev);
            DHT_EQ_INT(dh_track_step_f32(&trk.f, &T, qo, &rep), DH_OK);
            for (i = 0; i < 4u; i++) DHT_TRUE(fabsf(qo[i] - prev[i]) <= trk.f.dq_max[i]);
            if (rep.state == DH_TRACK_OK) break;
        }
        DHT_EQ_INT(rep.state, DH_TRACK_OK);
        dhs_true_error_f32(&rob, qo, &T, &ep, &er);
        DHT_TRUE_MSG(ep <= (double)trk.f.pos_tol && er <= (double)trk.f.rot_tol, "%.3g m, %.3g rad", ep, er);
    }
}

/* The closed form's bounds stand for the errors (measured 0) only while
 * pos_tol and rot_tol are at least those bounds (track.h, "Report"): the
 * UR5 at q given FK(q), with the default tolerances, with pos_tol below
 * the bound, with rot_tol below 2e-6 (float; the fixed twin likewise):
 * state OK every time, measured 1 and the errors within the tolerances
 * once one is tightened. A float target whose bottom row is not 0 0 0 1
 * is not rigid: DH_ERR_NOT_RIGID, state UNREACHABLE, errors 0, and the
 * joints at rest stay where they are. */
static void track_closed_form_bounds(void)
{
    const double qd[6] = { 30.0, -80.0, 90.0, -100.0, -90.0, 20.0 };
    float q[6], qo[6];
    int32_t qq[6], qqo[6];
    dh_mat4_f32 T, bad;
    dh_frame_q Tq;
    dhr_mat4 D;
    dh_track_report_f32 rep;
    dh_track_report_q repq;
    unsigned k, i;
    DHT_EQ_INT(dhs_build(&dhs_ur5_m, &rob), DH_OK);
    for (i = 0; i < 6u; i++) {
        DHT_EQ_INT(dh_robot_set_rates_f32(&rob, i, 90.0f, 900.0f), DH_OK);
        q[i] = (float)qd[i];
    }
    DHT_EQ_INT(dh_ikc_analyse_f32(&rob, &mdl.f), DH_OK);
    dhs_target_f32(&rob, qd, &T);
    for (k = 0; k < 3u; k++) {
        DHT_EQ_INT(dh_track_init_f32(&trk.f, &rob, &mdl.f, q, 1e-3f), DH_OK);
        if (k == 1u) trk.f.pos_tol = 0.5f * trk.f.cfp;
        if (k == 2u) trk.f.rot_tol = 1e-6f;
        DHT_EQ_INT(dh_track_step_f32(&trk.f, &T, qo, &rep), DH_OK);
        DHT_EQ_INT(rep.state, DH_TRACK_OK);
        DHT_EQ_INT(rep.measured, k != 0u);
        DHT_TRUE(rep.pos_err <= trk.f.pos_tol && rep.rot_err <= trk.f.rot_tol);
    }
    for (k = 0; k < 3u; k++) {
        DHT_EQ_INT(dh_track_init_f32(&trk.f, &rob, &mdl.f, q, 1e-3f), DH_OK);
        bad = T;
        DH_M4(&bad, 3, k) = 1e-3f;
        memset(&rep, 0x5A, sizeof rep);
        DHT_EQ_INT(dh_track_step_f32(&trk.f, &bad, qo, &rep), DH_ERR_NOT_RIGID);
        DHT_EQ_INT(rep.state, DH_TRACK_UNREACHABLE);
        DHT_TRUE(rep.pos_err == 0.0f && rep.rot_err == 0.0f);
        DHT_TRUE(memcmp(qo, q, sizeof qo) == 0);
    }
    /* fixed */
    DHT_EQ_INT(dhs_build_q(&dhs_ur5_mm, &rob), DH_OK);
    set_rates();
    DHT_EQ_INT(dh_ikc_analyse_q(&rob, &mdl.q), DH_OK);
    dhs_q_from_double(&rob, qd, qq);
    target_of(qq, &Tq, &D);
    for (k = 0; k < 3u; k++) {
        DHT_EQ_INT(dh_track_init_q(&trk.q, &rob, &mdl.q, qq, DT_US), DH_OK);
        if (k == 1u) trk.q.pos_tol = trk.q.cf_pos - 1;
        if (k == 2u) trk.q.rot_tol = DH_TRACK_CF_ROT_Q - 1;
        DHT_EQ_INT(dh_track_step_q(&trk.q, &Tq, qqo, &repq), DH_OK);
        DHT_EQ_INT(repq.state, DH_TRACK_OK);
        DHT_EQ_INT(repq.measured, k != 0u);
        DHT_TRUE(repq.pos_err <= trk.q.pos_tol && repq.rot_err <= trk.q.rot_tol);
    }
}

static const dht_case cases[] = {
    DHT_CASE(track_init_refused),
    DHT_CASE(track_q_prismatic_closed_form),
    DHT_CASE(track_scara_closed_form),
    DHT_CASE(track_closed_form_bounds),
};

DHT_MAIN(cases)
