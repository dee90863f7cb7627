/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_queue_stop.c - stop and resume of a queue of blended lines at the
 * states the contract names (motion.h, dh_queue_stop_f32 and
 * dh_queue_resume_f32), deterministic, on the UR5 with its closed form
 * and the tracker in the loop at 1 kHz:
 * - no move at all, or a move not started: the stop is immediate (phase
 *   STOPPED); a second stop changes nothing; resume while running changes
 *   nothing;
 * - inside a blended corner (both lines moving), in a blended line before
 *   or after its corner, or in a line after a corner run at rest: the stop
 *   brakes (phase BRAKE); a stop while braking changes nothing; a resume
 *   while braking continues the queue once the brake is at rest, or a
 *   resume after it;
 * - through all of it the target never jumps (each step within
 *   vmax dt (1 + 1e-3) + 1e-6 m in position and wmax dt (1 + 1e-3) +
 *   1e-4 deg in rotation), every line completes in order and the last
 *   target is the last line's B bit for bit.
 */
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_motion.h"
#include "support_robots.h"
#include "dhmath/motion.h"
#include "dhmath/track.h"

#define DT 1e-3f
#define CAP 3
#define NL 3
#define MAXCALL 20000L
#define RAD2DEG 57.29577951308232

typedef struct {
    dh_robot r;
    dh_ikc_model_f32 m;
    dh_track_f32 t;
} rig;

/* static: the micro:bit's RAM holds them beside the rig on the stack */
static dh_queue_f32 qu;
static dh_queue_item_f32 items[CAP];
static rig *G;

static const dh_cart_limits_f32 LIM = { 0.1f, 1.0f, 30.0f, 300.0f };
static const double Q0[6] = { 30.0, -80.0, 90.0, -100.0, -90.0, 20.0 };
static const double STEP[NL][6] = {
    { 8.0, -6.0, 5.0, 4.0, -3.0, 6.0 },
    { -7.0, 5.0, 6.0, -4.0, 5.0, -3.0 },
    { 5.0, 4.0, -6.0, 3.0, 2.0, -5.0 },
};

/* the queue's hash (and its items') */
static uint64_t queue_hash(void)
{
    return dhm_hash(&qu, sizeof qu, items, sizeof items);
}

/* corner k's configuration and frame */
static void corner(uint32_t k, double *q, dh_mat4_f32 *T)
{
    uint32_t i, c;
    for (i = 0; i < 6u; i++) q[i] = Q0[i];
    for (c = 0; c < k; c++)
        for (i = 0; i < 6u; i++) q[i] += STEP[c][i];
    dhs_target_f32(&G->r, q, T);
}

/* rotation angle (deg) between the rotations of A and B: of R = R_A^T R_B
 * in double, atan2 of its antisymmetric part's norm and trace - 1 (exact
 * for small angles, unlike acos of the trace) */
static double rot_deg(const dh_mat4_f32 *A, const dh_mat4_f32 *B)
{
    double R[3][3], v[3];
    int i, j, k;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            R[i][j] = 0.0;
            for (k = 0; k < 3; k++) R[i][j] += (double)A->m[i][k] * (double)B->m[j][k];
        }
    v[0] = R[1][2] - R[2][1];
    v[1] = R[2][0] - R[0][2];
    v[2] = R[0][1] - R[1][0];
    return atan2(sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), R[0][0] + R[1][1] + R[2][2] - 1.0) * RAD2DEG;
}

/* a stop and a second stop: the phase expected, the second changes nothing */
static void stop_twice(uint32_t phase)
{
    uint64_t h;
    DHT_EQ_INT(dh_queue_stop_f32(&qu), DH_OK);
    DHT_TRUE_MSG(qu.phase == phase, "phase %u, expected %u (bmode %u, clock %.9g of %.9g)", (unsigned)qu.phase,
                 (unsigned)phase, (unsigned)qu.bmode, (double)qu.mv.clock, (double)qu.mv.dur);
    h = queue_hash();
    DHT_EQ_INT(dh_queue_stop_f32(&qu), DH_OK);
    DHT_TRUE(queue_hash() == h);
}

/* One run of the NL lines (corner radius 0.02, the last 0) with the stop
 * of the given mode: 0 in the first corner's overlap, resumed while
 * braking; 1 there, resumed 50 periods after rest; 2 in the second line
 * once its clock has left 0 (corners run at rest), resumed at once; 3 in
 * the first line before its corner, resumed at once; 4 in the second line
 * after its corner's overlap, resumed 50 periods after rest. */
static void run(int mode)
{
    dh_mat4_f32 A, B, prev;
    dh_queue_cmd_f32 cmd;
    dh_queue_report_f32 rep;
    dh_track_report_f32 trep;
    dh_path_f32 ln;
    double q[6];
    float q0[6];
    uint32_t k, done = 0;
    long call, stop_call = -1, rest_call = -1;
    int have = 0, resumed = 0;
    corner(0u, q, &A);
    for (k = 0; k < 6u; k++) q0[k] = (float)q[k];
    DHT_EQ_INT(dh_track_init_f32(&G->t, &G->r, &G->m, q0, DT), DH_OK);
    DHT_EQ_INT(dh_queue_init_f32(&qu, items, CAP), DH_OK);
    /* no move at all: immediate; resume while running: nothing */
    stop_twice((uint32_t)DH_QUEUE_STOPPED);
    DHT_EQ_INT(dh_queue_resume_f32(&qu), DH_OK);
    DHT_EQ_INT(qu.phase, DH_QUEUE_RUN);
    {
        const uint64_t h = queue_hash();
        DHT_EQ_INT(dh_queue_resume_f32(&qu), DH_OK);
        DHT_TRUE(queue_hash() == h);
    }
    for (k = 0; k < NL; k++) {
        corner(k, q, &A);
        corner(k + 1u, q, &B);
        DHT_EQ_INT(dh_path_line_f32(&ln, &A, &B), DH_OK);
        DHT_EQ_INT(dh_queue_add_path_blend_f32(&qu, &ln, &LIM, (k + 1u < NL && mode != 2) ? 0.02f : 0.0f), DH_OK);
    }
    /* queued, not started: immediate */
    stop_twice((uint32_t)DH_QUEUE_STOPPED);
    DHT_EQ_INT(dh_queue_resume_f32(&qu), DH_OK);
    DHT_EQ_INT(qu.phase, DH_QUEUE_RUN);
    for (call = 0; call < MAXCALL && done < NL; call++) {
        DHT_EQ_INT(dh_queue_target_f32(&qu, &G->t, DT, &cmd), DH_OK);
        DHT_EQ_INT(cmd.kind, DH_MOVE_PATH);
        if (have) {
            double d = 0.0;
            for (k = 0; k < 3u; k++) d += pow((double)cmd.T.m[3][k] - (double)prev.m[3][k], 2.0);
            DHT_TRUE_MSG(sqrt(d) <= (double)LIM.vmax * DT * (1.0 + 1e-3) + 1e-6, "mode %d call %ld: step %.9g m",
                         mode, call, sqrt(d));
            DHT_TRUE_MSG(rot_deg(&cmd.T, &prev) <= (double)LIM.wmax * DT * (1.0 + 1e-3) + 1e-4,
                         "mode %d call %ld: turn %.9g deg", mode, call, rot_deg(&cmd.T, &prev));
        }
        prev = cmd.T;
        have = 1;
        DHT_EQ_INT(dh_track_step_f32(&G->t, &cmd.T, G->t.q, &trep), DH_OK);
        DHT_EQ_INT(dh_queue_advance_f32(&qu, trep.state, &rep), DH_OK);
        if (rep.done) {
            done++;
            DHT_EQ_INT(rep.seq + 1u, done);
        }
        if (rep.stopped && rest_call < 0) rest_call = call;
        if (stop_call < 0 && qu.phase == (uint32_t)DH_QUEUE_RUN &&
            (((mode == 0 || mode == 1) && qu.bmode == 2u && qu.bl[1].T > 0.0f && qu.bl[0].tb1 > 0.0f) ||
             (mode == 2 && done == 1u && !rep.done && qu.mv.clock > 0.0f) ||
             (mode == 3 && done == 0u && qu.bmode == 1u && qu.mv.clock > 0.0f) ||
             (mode == 4 && done == 1u && !rep.done && qu.bmode == 1u && qu.bl[0].tb0 > 0.0f && qu.mv.clock > 0.0f))) {
            stop_call = call;
            stop_twice((uint32_t)DH_QUEUE_BRAKE);
            if (mode != 1 && mode != 4) {
                DHT_EQ_INT(dh_queue_resume_f32(&qu), DH_OK);
                DHT_EQ_INT(qu.phase, DH_QUEUE_BRAKE);
                resumed = 1;
            }
        }
        if ((mode == 1 || mode == 4) && rest_call >= 0 && !resumed && call - rest_call >= 50) {
            DHT_EQ_INT(qu.phase, DH_QUEUE_STOPPED);
            DHT_EQ_INT(dh_queue_resume_f32(&qu), DH_OK);
            DHT_EQ_INT(qu.phase, DH_QUEUE_RUN);
            resumed = 1;
        }
    }
    DHT_TRUE_MSG(stop_call >= 0, "mode %d: no stop", mode);
    DHT_TRUE(resumed);
    DHT_TRUE_MSG(done == NL, "mode %d: %u of %u lines done in %ld periods", mode, (unsigned)done, (unsigned)NL, call);
    DHT_TRUE(rep.last);
    corner(NL, q, &B);
    DHT_TRUE(memcmp(&cmd.T, &B, sizeof B) == 0);
    /* done: no move at all */
    stop_twice((uint32_t)DH_QUEUE_STOPPED);
    DHT_EQ_INT(dh_queue_resume_f32(&qu), DH_OK);
    DHT_EQ_INT(qu.phase, DH_QUEUE_RUN);
}

/* A corner is blended only between two path moves of equal limits
 * (motion.h, dh_queue_add_path_blend_f32): the first line's overlap
 * ctb > 0 with the same limits, 0 (at rest) when the next line differs in
 * any one of them; a line's corner with an arc is blended, an arc's with
 * radius 0 is not; none after a joint move. */
static void queue_blend_needs_equal_limits(void)
{
    dh_mat4_f32 A, B, C;
    dh_path_f32 l1, l2, arc;
    dh_cart_limits_f32 lim;
    double q[6];
    float q1[6], v[6], a[6], via[3];
    unsigned k;
    rig g;
    G = &g;
    DHT_EQ_INT(dhs_build(&dhs_ur5_m, &g.r), DH_OK);
    corner(0u, q, &A);
    corner(1u, q, &B);
    corner(2u, q, &C);
    DHT_EQ_INT(dh_path_line_f32(&l1, &A, &B), DH_OK);
    DHT_EQ_INT(dh_path_line_f32(&l2, &B, &C), DH_OK);
    for (k = 0; k <= 4u; k++) {
        lim = LIM;
        if (k == 1u) lim.vmax *= 0.5f;
        if (k == 2u) lim.amax *= 0.5f;
        if (k == 3u) lim.wmax *= 0.5f;
        if (k == 4u) lim.wdmax *= 0.5f;
        DHT_EQ_INT(dh_queue_init_f32(&qu, items, CAP), DH_OK);
        DHT_EQ_INT(dh_queue_add_path_blend_f32(&qu, &l1, &LIM, 0.02f), DH_OK);
        DHT_EQ_INT(dh_queue_add_path_blend_f32(&qu, &l2, &lim, 0.0f), DH_OK);
        DHT_TRUE_MSG((k == 0u) == (items[0].ctb > 0.0f), "limits %u: overlap %.9g", k, (double)items[0].ctb);
    }
    /* an arc after the line (blended), or the line after an arc of radius 0 (at rest) */
    for (k = 0; k < 3u; k++) via[k] = 0.5f * (DH_M4(&B, k, 3) + DH_M4(&C, k, 3)) + ((k == 2u) ? 0.01f : 0.0f);
    DHT_EQ_INT(dh_path_arc_f32(&arc, &B, via, &C), DH_OK);
    DHT_EQ_INT(dh_queue_init_f32(&qu, items, CAP), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_blend_f32(&qu, &l1, &LIM, 0.02f), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_blend_f32(&qu, &arc, &LIM, 0.0f), DH_OK);
    DHT_TRUE_MSG(items[0].ctb > 0.0f, "line-arc corner: overlap %.9g", (double)items[0].ctb);
    for (k = 0; k < 3u; k++) via[k] = 0.5f * (DH_M4(&A, k, 3) + DH_M4(&B, k, 3)) + ((k == 2u) ? 0.01f : 0.0f);
    DHT_EQ_INT(dh_path_arc_f32(&arc, &A, via, &B), DH_OK);
    DHT_EQ_INT(dh_queue_init_f32(&qu, items, CAP), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_blend_f32(&qu, &arc, &LIM, 0.0f), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_blend_f32(&qu, &l2, &LIM, 0.02f), DH_OK);
    DHT_TRUE(items[0].ctb == 0.0f);
    for (k = 0; k < 6u; k++) {
        q1[k] = (float)q[k];
        v[k] = 90.0f;
        a[k] = 900.0f;
    }
    DHT_EQ_INT(dh_queue_init_f32(&qu, items, CAP), DH_OK);
    DHT_EQ_INT(dh_queue_add_joint_f32(&qu, 6u, q1, v, a, NULL), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_blend_f32(&qu, &l2, &LIM, 0.02f), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_blend_f32(&qu, &l2, &LIM, 0.0f), DH_OK);
    DHT_TRUE(items[0].ctb == 0.0f);
}

static void queue_stop_states(void)
{
    uint32_t i;
    rig g;
    G = &g;
    DHT_EQ_INT(dhs_build(&dhs_ur5_m, &g.r), DH_OK);
    for (i = 0; i < g.r.n; i++) DHT_EQ_INT(dh_robot_set_rates_f32(&g.r, i, 180.0f, 3000.0f), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_f32(&g.r, &g.m), DH_OK);
    run(0);
    run(1);
    run(2);
    run(3);
    run(4);
}

static const dht_case cases[] = {
    DHT_CASE(queue_blend_needs_equal_limits),
    DHT_CASE(queue_stop_states),
};

DHT_MAIN(cases)
