/* SPDX-License-Identifier: Apache-2.0 */
/*
 * fw_fixed_track.c - firmware example for a core without FPU (Cortex-M0+):
 * a control loop with a 1 ms period (1 kHz) that tracks a straight line of
 * UR5 poses through the neighbourhood of the wrist singularity in fixed
 * point, integer only (no float routine linked:
 * examples/firmware/no_float.cmake). Whether one period's call fits in 1 ms
 * on a given core: docs/generated/performance_target.md ("Tracking").
 *
 * The UR5 table lives in flash (`dhmath gen examples/robots/ur5_mm.dh
 * dhg_ur5_mm`, run by the build); the firmware copies it to RAM once and
 * sets the joint speed limits there: 180 deg/s on every joint, the UR5's
 * published joint speed (Universal Robots, UR5 technical specification;
 * docs/references.md). No acceleration limit is set (the specification
 * publishes none). Then dh_ikc_analyse_q once, dh_track_init_q at the
 * first target with dt = 1000 us, and one dh_track_step_q per period.
 *
 * The path: the configuration QS, 0.2 deg from the wrist singularity
 * (joint 5 at 0: axes 4 and 6 parallel), gives the pose Ts = dh_fk_q(QS).
 * The targets keep Ts's rotation and move their position on a line at
 * 100 mm/s (LINE_STEP per period), 100 mm long, whose middle passes
 * LINE_OFF (0.5 mm) from Ts's position: target k = Ts.p + LINE_OFF + (k -
 * LINE_N / 2) LINE_STEP, k = 0 .. LINE_N, all in integers. The exact
 * solutions along it turn joints 4 and 6 by some 160 deg while joint 5
 * passes within hundredths of a degree of 0: faster than 180 deg/s, so
 * the tracker lags (every step within its bound) and catches up. After
 * the line the last target is held until the tracker reports OK (at most
 * HOLD_MAX periods).
 *
 * Output (raw fixed-point integers through fw_print.c; printf would link
 * newlib's floating-point conversion):
 *   dt_us: <period>               vmax_q16: <6 joint speed limits, dh_q16 deg/s>
 *   bound_q16: <6 step bounds t.dq_max = floor(vmax_q dt_us / 10^6)>
 *   sing_q16: <QS>                sing_p_qpos / line_r_q30: Ts's position and rotation
 *   line_off_qpos / line_step_qpos / line_n: the line as above
 *   k: <period> <state> <6 joint values, dh_q16 deg>, for k = 0 (the
 *      start, on the first target) and every period after it
 *   max_step_q16: <per joint the largest |q_k - q_(k-1)|>
 *   periods: <ok> <lagging> <unreachable> <near_singular>
 *   final: <state> <pos_err dh_qpos> <rot_err Q3.29 rad> <pos_tol> <rot_tol>
 *          <measured: 1 errors by FK, 0 the closed form's bounds>
 * examples/firmware/check_output.py recomputes the targets, the FK of
 * every configuration and the step bounds in double precision from
 * examples/robots/ur5_mm.dh and the printed integers.
 */
#include <string.h>

#include "dhmath/dhmath.h"
#include "fw_print.h"

/* UR5 in mm (examples/robots/ur5_mm.dh), generated into .rodata by
 * dhmath_add_robot() (examples/firmware/CMakeLists.txt) */
extern const dh_robot dhg_ur5_mm;

#define DT_US 1000u                          /* 1 kHz */
#define VMAX DH_Q16(180.0)                   /* deg/s, every joint */
#define LINE_N 1000                          /* periods: 100 mm at 100 mm/s */
#define HOLD_MAX 3000                        /* periods the last target is held at most */

/* joint 5 at 0.2 deg: 0.2 deg from the wrist singularity */
static const dh_q16 QS[6] = { DH_Q16(30.0), DH_Q16(-100.0), DH_Q16(100.0), DH_Q16(-90.0), DH_Q16(0.2),
                              DH_Q16(60.0) };
/* 0.5 mm along z; 0.1 mm per period along (0.6, 0.8, 0), perpendicular to it */
static const dh_qpos LINE_OFF[3] = { 0, 0, DH_QPOS(0.5) };
static const dh_qpos LINE_STEP[3] = { DH_QPOS(0.06), DH_QPOS(0.08), 0 };

/* static, not on the stack */
static dh_robot robot;
static dh_ikc_model_q model;
static dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
static dh_track_q trk;

/* the target of period k (0..LINE_N): Ts's rotation, position on the line */
static void line_target(const dh_frame_q *Ts, int32_t k, dh_frame_q *T)
{
    uint32_t i;
    *T = *Ts;
    for (i = 0; i < 3u; i++) T->p[i] = Ts->p[i] + LINE_OFF[i] + (k - LINE_N / 2) * LINE_STEP[i];
}

static void put_period(int32_t k, dh_track_state s, const int32_t *q)
{
    int32_t v[8];
    v[0] = k;
    v[1] = (int32_t)s;
    memcpy(&v[2], q, 6u * sizeof q[0]);
    fw_put_line("k:", v, 8u);
}

int main(void)
{
    dh_frame_q Ts, T;
    dh_track_report_q rep;
    int32_t q[6], q_prev[6], max_step[6] = { 0 }, count[4] = { 0 }, v[9], k;
    uint32_t i, n_sol, best;
    dh_status st = DH_OK;

    /* the flash table with rate limits, in RAM */
    robot = dhg_ur5_mm;
    for (i = 0; i < 6u && st == DH_OK; i++) st = dh_robot_set_rates_q(&robot, i, VMAX, INT32_MAX);
    if (st != DH_OK) return fw_fail("dh_robot_set_rates_q", st);
    st = dh_ikc_analyse_q(&robot, &model);
    if (st != DH_OK) return fw_fail("dh_ikc_analyse_q", st);

    st = dh_fk_q(&robot, QS, &Ts);
    if (st != DH_OK) return fw_fail("dh_fk_q", st);
    /* start on the first target, on the closed-form solution nearest QS */
    line_target(&Ts, 0, &T);
    st = dh_ikc_q(&model, &T, QS, 0u, sol, &n_sol);
    if (st != DH_OK) return fw_fail("dh_ikc_q", st);
    st = dh_ikc_nearest_q(sol, n_sol, QS, 6u, &best);
    if (st != DH_OK) return fw_fail("dh_ikc_nearest_q", st);
    st = dh_track_init_q(&trk, &robot, &model, sol[best].q, DT_US);
    if (st != DH_OK) return fw_fail("dh_track_init_q", st);

    v[0] = (int32_t)trk.dt_us;
    fw_put_line("dt_us:", v, 1u);
    for (i = 0; i < 6u; i++) v[i] = robot.joint[i].vmax_q;
    fw_put_line("vmax_q16:", v, 6u);
    fw_put_line("bound_q16:", trk.dq_max, 6u);
    fw_put_line("sing_q16:", QS, 6u);
    fw_put_line("sing_p_qpos:", Ts.p, 3u);
    for (i = 0; i < 9u; i++) v[i] = Ts.r[i % 3u][i / 3u];
    fw_put_line("line_r_q30:", v, 9u);
    fw_put_line("line_off_qpos:", LINE_OFF, 3u);
    fw_put_line("line_step_qpos:", LINE_STEP, 3u);
    v[0] = LINE_N;
    fw_put_line("line_n:", v, 1u);

    memcpy(q, trk.q, sizeof q);
    put_period(0, DH_TRACK_OK, q);
    rep.state = DH_TRACK_LAGGING;
    for (k = 1; k <= LINE_N + HOLD_MAX; k++) {
        if (k > LINE_N && rep.state == DH_TRACK_OK) break;
        line_target(&Ts, k <= LINE_N ? k : LINE_N, &T);
        memcpy(q_prev, q, sizeof q);
        st = dh_track_step_q(&trk, &T, q, &rep);
        if (st != DH_OK) return fw_fail("dh_track_step_q", st);
        for (i = 0; i < 6u; i++) {
            const int32_t d = q[i] >= q_prev[i] ? q[i] - q_prev[i] : q_prev[i] - q[i];
            if (d > max_step[i]) max_step[i] = d;
        }
        count[rep.state]++;
        if (rep.near_singular) count[3]++;
        put_period(k, rep.state, q);
    }
    fw_put_line("max_step_q16:", max_step, 6u);
    fw_put_line("periods:", count, 4u);
    v[0] = (int32_t)rep.state;
    v[1] = rep.pos_err;
    v[2] = rep.rot_err;
    v[3] = trk.pos_tol;
    v[4] = trk.rot_tol;
    v[5] = rep.measured;
    fw_put_line("final:", v, 6u);
    return rep.state == DH_TRACK_OK ? 0 : 1;
}
