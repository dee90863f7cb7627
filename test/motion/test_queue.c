/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_queue.c - the move queue with stop and resume (motion.h:
 * dh_queue_*) and the tracker's sync (track.h: dh_track_sync_f32), at
 * 1 kHz, seeded random queues.
 *
 * Joint queues on the Puma 560, UR5 and Panda: three joint moves of up to
 * 30 degrees per joint within random limits (all with jerk limits, or
 * none), run through the caller's loop (target, sync, advance), a fourth
 * append reported full with the queue untouched. Every command is checked
 * by finite differences: each step within vmax dt (plus 2 ulp of q), over
 * windows of W periods the second difference within amax (W dt)^2 and,
 * with jerk limits, the third within jmax (W dt)^3 (plus 8 ulp of q: the
 * windows make that rounding at most 2 % of the bound). Moves run in
 * order (the report's seq), each done once with the command equal to its
 * q1 bit for bit, the last one reported last. In most queues a stop comes
 * at a random period of a random move: the commands keep the limits
 * through it, rest comes within the analytic stopping time of the
 * velocity at the stop (the backward difference plus amax dt): v / A, or
 * v1 / A + 3 A / J with v1 = v + A^2 / (2 J) the most the velocity can
 * grow while the acceleration ramps down; the distance within v1 times
 * that time, never beyond q1; the command stays still while stopped; the
 * resume (at once, or during the brake) ends the move at q1 bit for bit.
 *
 * Path queues on the UR5 (closed form, the tracker in the loop): a line,
 * a joint move, a line, with the robot's rates equal to the joint moves'
 * limits, so every output meets the tracker's guarantees (track.h: step
 * within dq_max, change of step within amax dt^2 (1 + 1e-6) + 4 ulp of q),
 * through the joins and the joint moves as well. The targets are checked
 * over runs of OK periods (where the clock advances by dt): each step
 * within vmax dt, second differences over W2 periods within amax (W2 dt)^2
 * (both with 1e-3 relative and 1e-6 m for the path's rounding). A stop
 * in a random move: a line stops within (s' limit) / (s'' limit) of clock
 * time, on the line between the stop and B; it resumes and ends at B bit
 * for bit.
 *
 * The feed override: the Puma 560 line that its wrist cannot follow at
 * speed, run by a queue, gives every period's frame, clock and override of
 * the executor (dh_move_advance_f32) bit for bit, and completes.
 *
 * Every status of the seven functions and of dh_track_sync_f32 for bad
 * inputs, with the queue, the items and the tracker untouched.
 */
#include <float.h>
#include <math.h>
#include <string.h>
#include <stdio.h>

#include "dht.h"
#include "support_ref.h"
#include "support_robots.h"
#include "dhmath/motion.h"
#include "dhmath/track.h"

#define DT 1e-3f
#define W 5           /* window of the joint finite differences */
#define NH (3 * W + 1) /* samples kept */
#define W2 10          /* window of the target's second differences */
#define CAP 2
#define NMOVE 3

static double ulpf(double x)
{
    int e;
    (void)frexp(fabs(x) > 1e-30 ? fabs(x) : 1e-30, &e);
    return ldexp(1.0, e - 24);
}

/* the robot, its model and the tracker live on the stack of each case
 * (G points at them); the queue and the history are static: the
 * micro:bit's 16 KiB of RAM hold both only so divided */
typedef struct {
    dh_robot r;
    dh_ikc_model_f32 m;
    dh_track_f32 t;
} rig;
static rig *G;
static dh_queue_f32 qu;
static dh_queue_item_f32 items[CAP];
static float hist[NH][DH_MAX_JOINTS]; /* hist[m]: the command m periods ago */
static long nhist;

static void hist_push(const float *q, uint32_t n)
{
    int m;
    for (m = NH - 1; m > 0; m--) memcpy(hist[m], hist[m - 1], sizeof hist[0]);
    memcpy(hist[0], q, n * sizeof q[0]);
    nhist++;
}

/* the finite differences of the last commands within the limits */
static void check_fd(uint32_t n, const float *vmax, const float *amax, const float *jmax, long call)
{
    uint32_t i;
    for (i = 0; i < n; i++) {
        const double x0 = hist[0][i], x1 = hist[1][i], xw = hist[W][i], x2w = hist[2 * W][i], x3w = hist[3 * W][i];
        const double u = ulpf(fmax(fabs(x0), 180.0)), h = (double)W * DT;
        DHT_TRUE_MSG(isfinite(x0), "call %ld joint %u not finite", call, (unsigned)i);
        if (nhist >= 2)
            DHT_TRUE_MSG(fabs(x0 - x1) <= (double)vmax[i] * DT + 2 * u, "call %ld joint %u step %.9g over %.9g", call,
                         (unsigned)i, fabs(x0 - x1), (double)vmax[i] * DT);
        if (nhist >= 2 * W + 1)
            DHT_TRUE_MSG(fabs(x0 - 2 * xw + x2w) <= (double)amax[i] * h * h + 8 * u,
                         "call %ld joint %u second difference %.9g over %.9g", call, (unsigned)i,
                         fabs(x0 - 2 * xw + x2w), (double)amax[i] * h * h);
        if (jmax != NULL && nhist >= 3 * W + 1)
            DHT_TRUE_MSG(fabs(x0 - 3 * xw + 3 * x2w - x3w) <= (double)jmax[i] * h * h * h + 8 * u,
                         "call %ld joint %u third difference %.9g over %.9g", call, (unsigned)i,
                         fabs(x0 - 3 * xw + 3 * x2w - x3w), (double)jmax[i] * h * h * h);
    }
}

/* FNV-1a hash of n bytes: the state before an error, compared after it
 * (a copy of the queue and its items does not fit the micro:bit's RAM) */
static uint64_t hash_bytes(const void *p, size_t n)
{
    const unsigned char *b = (const unsigned char *)p;
    uint64_t h = 14695981039346656037ull;
    size_t i;
    for (i = 0; i < n; i++) h = (h ^ b[i]) * 1099511628211ull;
    return h;
}

static uint64_t keep;

static uint64_t state_hash(void)
{
    return hash_bytes(&qu, sizeof qu) ^ (hash_bytes(items, sizeof items) * 31u);
}

static void same(void)
{
    DHT_TRUE(state_hash() == keep);
}

static void save(void)
{
    keep = state_hash();
}

/* ---- joint queues ------------------------------------------------------ */

typedef struct {
    float q1[NMOVE][DH_MAX_JOINTS];
    float q0[DH_MAX_JOINTS]; /* where the running move started */
    float vmax[DH_MAX_JOINTS], amax[DH_MAX_JOINTS], jmax[DH_MAX_JOINTS];
    int jerk;
} jplan;

static jplan jp;

static void draw_joint_queue(const dh_robot *r, const float *qs)
{
    uint32_t i;
    int k;
    jp.jerk = dht_rand_uniform(0.0, 1.0) < 0.5;
    for (i = 0; i < r->n; i++) {
        jp.vmax[i] = (float)dht_rand_uniform(60.0, 250.0);
        jp.amax[i] = (float)dht_rand_uniform(100.0, 5000.0);
        jp.jmax[i] = (float)dht_rand_uniform(10000.0, 100000.0);
    }
    for (k = 0; k < NMOVE; k++)
        for (i = 0; i < r->n; i++) {
            const float prev = (k == 0) ? qs[i] : jp.q1[k - 1][i];
            double x = (double)prev + dht_rand_uniform(-30.0, 30.0);
            const double lo = (double)r->joint[i].qmin + 1.0, hi = (double)r->joint[i].qmax - 1.0;
            if (x < lo) x = lo;
            if (x > hi) x = hi;
            jp.q1[k][i] = (float)x;
        }
}

/* the stopping time bound (s) and distance bound of joint i from its
 * backward-difference velocity v (deg/s) */
static void stop_bound(uint32_t i, double v, double *tb, double *xb)
{
    const double A = jp.amax[i], J = jp.jmax[i];
    v = fabs(v) + A * DT;
    if (jp.jerk) {
        const double v1 = v + A * A / (2 * J);
        *tb = v1 / A + 3 * A / J;
        *xb = v1 * *tb;
    } else {
        *tb = v / A;
        *xb = v * v / (2 * A) + A * DT * DT;
    }
}

static void joint_queue_on(const dhs_robot *d)
{
    double qd[DH_MAX_JOINTS];
    float qs[DH_MAX_JOINTS], qstop[DH_MAX_JOINTS], vstop[DH_MAX_JOINTS];
    dh_queue_cmd_f32 cmd;
    dh_queue_report_f32 rep;
    uint32_t i;
    float stop_frac;
    long call, stopped_at = -1, resume_at = -1, stop_call = -1;
    int next = 0, stop_move, resume_in_brake, k;
    DHT_EQ_INT(dhs_build(d, &G->r), DH_OK);
    dhs_random_q_robot(&G->r, qd);
    for (i = 0; i < G->r.n; i++) qs[i] = (float)qd[i];
    DHT_EQ_INT(dh_track_init_f32(&G->t, &G->r, NULL, qs, DT), DH_OK);
    draw_joint_queue(&G->r, qs);
    DHT_EQ_INT(dh_queue_init_f32(&qu, items, CAP), DH_OK);
    for (k = 0; k < CAP; k++)
        DHT_EQ_INT(dh_queue_add_joint_f32(&qu, G->r.n, jp.q1[k], jp.vmax, jp.amax, jp.jerk ? jp.jmax : NULL), DH_OK);
    /* full: reported, nothing overwritten (the rest is appended as the
     * queue runs) */
    save();
    DHT_EQ_INT(dh_queue_add_joint_f32(&qu, G->r.n, qs, jp.vmax, jp.amax, NULL), DH_ERR_LIMIT);
    same();
    DHT_TRUE(memcmp(items[0].q1, jp.q1[0], G->r.n * sizeof(float)) == 0);
    /* a stop at a random time of a random move (the time a fraction of
     * the move's duration, read from the queue: input selection) */
    stop_move = (int)(dht_rand_u32() % NMOVE);
    stop_frac = (float)dht_rand_uniform(0.02, 0.98);
    resume_in_brake = dht_rand_uniform(0.0, 1.0) < 0.3;
    nhist = 0;
    hist_push(qs, G->r.n);
    memcpy(jp.q0, qs, sizeof qs);
    for (call = 0; call < 200000; call++) {
        DHT_EQ_INT(dh_queue_target_f32(&qu, &G->t, DT, &cmd), DH_OK);
        DHT_EQ_INT(cmd.kind, DH_MOVE_JOINT);
        DHT_EQ_INT(dh_track_sync_f32(&G->t, cmd.q), DH_OK);
        DHT_EQ_INT(dh_queue_advance_f32(&qu, DH_TRACK_OK, &rep), DH_OK);
        hist_push(cmd.q, G->r.n);
        check_fd(G->r.n, jp.vmax, jp.amax, jp.jerk ? jp.jmax : NULL, call);
        DHT_TRUE_MSG((int)rep.seq == next, "call %ld: move %u runs, %d expected", call, (unsigned)rep.seq, next);
        if (stopped_at >= 0 && resume_at < 0) {
            /* still while stopped */
            for (i = 0; i < G->r.n; i++) DHT_EQ_F32_BITS(cmd.q[i], qstop[i]);
            if (call >= stopped_at + 5) {
                DHT_EQ_INT(dh_queue_resume_f32(&qu), DH_OK);
                resume_at = call;
            }
        }
        if (rep.stopped && stopped_at < 0) {
            double T = 0.0;
            stopped_at = call;
            for (i = 0; i < G->r.n; i++) {
                double tb, xb;
                const double dir = (double)jp.q1[next][i] - jp.q0[i];
                stop_bound(i, vstop[i], &tb, &xb);
                if (tb > T) T = tb;
                DHT_TRUE_MSG(fabs((double)cmd.q[i] - qstop[i]) <= xb + 4 * ulpf(180.0),
                             "joint %u stopped %.9g from the stop, bound %.9g", (unsigned)i,
                             fabs((double)cmd.q[i] - qstop[i]), xb);
                DHT_TRUE_MSG(((double)jp.q1[next][i] - cmd.q[i]) * dir >= 0.0, "joint %u beyond q1: q0 %.9g q1 %.9g stop %.9g rest %.9g", (unsigned)i, (double)jp.q0[i], (double)jp.q1[next][i], (double)qstop[i], (double)cmd.q[i]);
                qstop[i] = cmd.q[i];
            }
            DHT_TRUE_MSG((double)(call - stop_call) * DT <= T + 2.0 * DT, "rest after %ld periods, bound %.9g s",
                         call - stop_call, T);
        }
        if (rep.done) {
            for (i = 0; i < G->r.n; i++) DHT_EQ_F32_BITS(cmd.q[i], jp.q1[next][i]);
            next++;
            if (next < NMOVE) memcpy(jp.q0, cmd.q, sizeof jp.q0);
            if (k < NMOVE) {
                DHT_EQ_INT(dh_queue_add_joint_f32(&qu, G->r.n, jp.q1[k], jp.vmax, jp.amax, jp.jerk ? jp.jmax : NULL),
                           DH_OK);
                k++;
            }
            DHT_EQ_INT(rep.last, next == NMOVE);
            if (next == NMOVE) break;
        }
        if (next == stop_move && stop_call < 0 && !rep.done && rep.clock >= stop_frac * qu.mv.dur) {
            stop_call = call;
            for (i = 0; i < G->r.n; i++) {
                qstop[i] = cmd.q[i];
                vstop[i] = (float)(((double)hist[0][i] - hist[1][i]) / DT);
            }
            DHT_EQ_INT(dh_queue_stop_f32(&qu), DH_OK);
            if (resume_in_brake) {
                DHT_EQ_INT(dh_queue_resume_f32(&qu), DH_OK);
                resume_at = call;
            }
        }
    }
    DHT_EQ_INT(next, NMOVE);
    DHT_EQ_INT(qu.count, 0);
    DHT_TRUE(stop_call >= 0);
    DHT_TRUE(stopped_at >= 0 || resume_in_brake);
}

static void joint_queues(void)
{
    static const dhs_robot *const robots[3] = { &dhs_puma560_m, &dhs_ur5_m, &dhs_panda_m };
    int it, n = (int)DHT_ITER(15);
    rig g;
    G = &g;
    for (it = 0; it < n; it++) joint_queue_on(robots[it % 3]);
    G = NULL;
}

/* ---- path queues on the UR5 ------------------------------------------- */

#define VMAX_R 180.0f
#define AMAX_R 3000.0f
static const dh_cart_limits_f32 LIM = { 0.1f, 1.0f, 30.0f, 300.0f };

static void frame_of(const double *q, dh_mat4_f32 *T)
{
    dhs_target_f32(&G->r, q, T);
}

static double dist3f(const float *a, const float *b)
{
    const double d[3] = { (double)a[0] - b[0], (double)a[1] - b[1], (double)a[2] - b[2] };
    return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

/* the least distance of the segment from A's to B's position to the base
 * z axis (the UR5 cannot bring its wrist near that axis: test input
 * selection keeps the lines away from it) */
static double axis_dist(const dh_mat4_f32 *A, const dh_mat4_f32 *B)
{
    const double ax = A->m[3][0], ay = A->m[3][1], dx = (double)B->m[3][0] - ax, dy = (double)B->m[3][1] - ay;
    const double d2 = dx * dx + dy * dy;
    double u = (d2 > 0.0) ? -(ax * dx + ay * dy) / d2 : 0.0;
    u = fmin(fmax(u, 0.0), 1.0);
    return sqrt((ax + u * dx) * (ax + u * dx) + (ay + u * dy) * (ay + u * dy));
}

/* the tracker's guarantees (track.h) for the output q after qp, sp */
static void check_track(const float *q, float *qp, float *sp, int *have, long call)
{
    uint32_t i;
    for (i = 0; i < G->r.n; i++) {
        const double s = (double)q[i] - qp[i], A = (double)AMAX_R * DT * DT;
        DHT_TRUE_MSG(fabs(s) <= (double)VMAX_R * DT, "call %ld: joint %u step %.9g", call, (unsigned)i, s);
        if (*have)
            DHT_TRUE_MSG(fabs(s - sp[i]) <= A * (1 + 1e-6) + 4 * ulpf(fmax(fabs(q[i]), fabs(qp[i]))),
                         "call %ld: joint %u change of step %.9g over %.9g", call, (unsigned)i, fabs(s - sp[i]), A);
        sp[i] = (float)s;
        qp[i] = q[i];
    }
    *have = 1;
}

static float tp[2 * W2 + 1][3]; /* target positions of the current run of OK periods */
static int ntp;

/* the targets' differences over the current run of OK periods */
static void check_target(const dh_mat4_f32 *T, long call)
{
    int m, k;
    for (m = 2 * W2; m > 0; m--) memcpy(tp[m], tp[m - 1], sizeof tp[0]);
    for (k = 0; k < 3; k++) tp[0][k] = T->m[3][k];
    ntp++;
    if (ntp >= 2)
        DHT_TRUE_MSG(dist3f(tp[0], tp[1]) <= (double)LIM.vmax * DT * (1 + 1e-3) + 1e-6, "call %ld: target step %.9g",
                     call, dist3f(tp[0], tp[1]));
    if (ntp >= 2 * W2 + 1) {
        double a2 = 0.0, h = (double)W2 * DT;
        for (k = 0; k < 3; k++) {
            const double x = (double)tp[0][k] - 2.0 * tp[W2][k] + tp[2 * W2][k];
            a2 += x * x;
        }
        DHT_TRUE_MSG(sqrt(a2) <= (double)LIM.amax * h * h * (1 + 1e-3) + 2e-6, "call %ld: target second difference %.9g",
                     call, sqrt(a2));
    }
}

static void path_queue(void)
{
    double qa[DH_MAX_JOINTS], qb[DH_MAX_JOINTS], qc[DH_MAX_JOINTS];
    float q0[DH_MAX_JOINTS], qp[DH_MAX_JOINTS], sp[DH_MAX_JOINTS], qcf[DH_MAX_JOINTS], vmax[DH_MAX_JOINTS],
        amax[DH_MAX_JOINTS];
    static dh_mat4_f32 A, B, Tstop; /* off the micro:bit's stack */
    static dh_path_f32 p1, p2;
    dh_queue_cmd_f32 cmd;
    dh_queue_report_f32 rep;
    dh_track_report_f32 trep;
    uint32_t i;
    long call, stop_call = -1, okp = 0;
    int have = 0, next = 0, stop_move = (int)(dht_rand_u32() % 3u), k, stopped = 0, far1;
    const float stop_frac = (float)dht_rand_uniform(0.02, 0.98);
    double tbound = 0.0;
    memset(&Tstop, 0, sizeof Tstop);
    do {
        dhs_ur5_safe_q(10.0, qa);
        for (k = 0; k < 6; k++) {
            qb[k] = qa[k] + dht_rand_uniform(-5.0, 5.0);
            qc[k] = qb[k] + dht_rand_uniform(-5.0, 5.0);
        }
        /* the first line from A to B, then the second's ends into A and B */
        frame_of(qa, &A);
        frame_of(qb, &B);
        far1 = !(axis_dist(&A, &B) < 0.3);
        DHT_EQ_INT(dh_path_line_f32(&p1, &A, &B), DH_OK);
        for (k = 0; k < 6; k++) qb[k] = qc[k] + dht_rand_uniform(-5.0, 5.0);
        frame_of(qc, &A);
        frame_of(qb, &B);
    } while (!far1 || axis_dist(&A, &B) < 0.3);
    DHT_EQ_INT(dh_path_line_f32(&p2, &A, &B), DH_OK);
    for (i = 0; i < G->r.n; i++) {
        q0[i] = (float)qa[i];
        qp[i] = q0[i];
        qcf[i] = (float)qc[i];
        vmax[i] = VMAX_R;
        amax[i] = AMAX_R;
    }
    DHT_EQ_INT(dh_track_init_f32(&G->t, &G->r, &G->m, q0, DT), DH_OK);
    DHT_EQ_INT(dh_queue_init_f32(&qu, items, CAP), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_f32(&qu, &p1, &LIM), DH_OK);
    DHT_EQ_INT(dh_queue_add_joint_f32(&qu, G->r.n, qcf, vmax, amax, NULL), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_f32(&qu, &p2, &LIM), DH_ERR_LIMIT);
    ntp = 0;
    for (call = 0; call < 100000; call++) {
        dh_track_state st = DH_TRACK_OK;
        const dh_path_f32 *pp = (next == 0) ? &p1 : &p2;
        DHT_EQ_INT(dh_queue_target_f32(&qu, &G->t, DT, &cmd), DH_OK);
        if (cmd.kind == DH_MOVE_JOINT) {
            DHT_EQ_INT(dh_track_sync_f32(&G->t, cmd.q), DH_OK);
            ntp = 0;
        } else {
            DHT_EQ_INT(cmd.kind, DH_MOVE_PATH);
            DHT_EQ_INT(dh_track_step_f32(&G->t, &cmd.T, G->t.q, &trep), DH_OK);
            st = trep.state;
        }
        DHT_EQ_INT(dh_queue_advance_f32(&qu, st, &rep), DH_OK);
        check_track(G->t.q, qp, sp, &have, call);
        if (cmd.kind == DH_MOVE_PATH && st == DH_TRACK_OK && !rep.held)
            check_target(&cmd.T, call);
        else if (cmd.kind == DH_MOVE_PATH)
            ntp = 0;
        DHT_TRUE_MSG((int)rep.seq == next, "call %ld: move %u runs, %d expected", call, (unsigned)rep.seq, next);
        if (stop_call >= 0 && !stopped && st == DH_TRACK_OK) okp++;
        if (rep.stopped && !stopped) {
            stopped = 1;
            if (next != 1) {
                /* on the line, between the stop and B, within the bound */
                const float *pe = &pp->B.m[3][0];
                DHT_TRUE_MSG((double)(okp - 1) * DT <= tbound + 2.0 * DT, "rest after %ld OK periods, bound %.9g s", okp,
                             tbound);
                DHT_TRUE(dist3f(&cmd.T.m[3][0], pe) <= dist3f(&Tstop.m[3][0], pe) + 1e-6);
            }
            DHT_EQ_INT(dh_queue_resume_f32(&qu), DH_OK);
        }
        if (rep.done) {
            if (cmd.kind == DH_MOVE_PATH) DHT_TRUE(memcmp(&cmd.T, &pp->B, sizeof cmd.T) == 0);
            else for (i = 0; i < G->r.n; i++) DHT_EQ_F32_BITS(cmd.q[i], qcf[i]);
            next++;
            /* the second line appended while the queue runs */
            if (next == 1) DHT_EQ_INT(dh_queue_add_path_f32(&qu, &p2, &LIM), DH_OK);
            DHT_EQ_INT(rep.last, next == 3);
            if (next == 3) break;
        }
        if (next == stop_move && stop_call < 0 && !rep.done && rep.clock >= stop_frac * qu.mv.dur && rep.clock > 0.0f &&
            !rep.held) {
            stop_call = call;
            if (cmd.kind == DH_MOVE_PATH) {
                /* the limits of s on a line: speed vmax / length, wmax / angle */
                const double ang = (double)pp->angle, len = (double)pp->length;
                double vs = LIM.vmax / len, as = LIM.amax / len;
                if (ang > 0.0) {
                    vs = fmin(vs, LIM.wmax / ang);
                    as = fmin(as, LIM.wdmax / ang);
                }
                tbound = vs / as;
                Tstop = cmd.T;
            }
            DHT_EQ_INT(dh_queue_stop_f32(&qu), DH_OK);
        }
    }
    if (next != 3) printf("stuck: next %d phase %u started %u clock %g dur %g stop_move %d stop_call %ld held %d kind %u st %d\n", next, (unsigned)qu.phase, (unsigned)qu.started, (double)qu.mv.clock, (double)qu.mv.dur, stop_move, stop_call, rep.held, (unsigned)cmd.kind, (int)trep.state);
    DHT_EQ_INT(next, 3);
    DHT_TRUE(stop_call >= 0);
    DHT_TRUE(stopped);
}

static void path_queues(void)
{
    int it, n = (int)DHT_ITER(10);
    rig g;
    G = &g;
    DHT_EQ_INT(dhs_build(&dhs_ur5_m, &G->r), DH_OK);
    for (it = 0; it < 6; it++) DHT_EQ_INT(dh_robot_set_rates_f32(&G->r, (uint32_t)it, VMAX_R, AMAX_R), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_f32(&G->r, &G->m), DH_OK);
    for (it = 0; it < n; it++) path_queue();
    G = NULL;
}

/* ---- the feed override: a queue's path move is the executor's ------------ */

/* the hash of every period's frame, clock and override of the infeasible
 * Puma line (test_move.c) run from q0 by the executor (queue 0) or by a
 * queue (queue 1), up to done; the periods into *periods */
static uint64_t puma_run(int queue, const float *q0, const dh_path_f32 *p, const dh_cart_limits_f32 *lim,
                         long *periods, long *notok)
{
    dh_move_f32 *const mv = &qu.mv; /* the executor's move in the unused queue's (RAM) */
    dh_move_report_f32 mrep;
    dh_queue_report_f32 rep;
    dh_queue_cmd_f32 cmd;
    dh_track_report_f32 trep;
    uint64_t h = 0u;
    long call;
    float c[2];
    DHT_EQ_INT(dh_track_init_f32(&G->t, &G->r, &G->m, q0, DT), DH_OK);
    if (queue) {
        DHT_EQ_INT(dh_queue_init_f32(&qu, items, CAP), DH_OK);
        DHT_EQ_INT(dh_queue_add_path_f32(&qu, p, lim), DH_OK);
    } else {
        DHT_EQ_INT(dh_move_path_f32(mv, p, lim), DH_OK);
    }
    *notok = 0;
    for (call = 0; call < 40000; call++) {
        int done;
        if (queue) {
            DHT_EQ_INT(dh_queue_target_f32(&qu, &G->t, DT, &cmd), DH_OK);
            DHT_EQ_INT(cmd.kind, DH_MOVE_PATH);
        } else {
            DHT_EQ_INT(dh_move_target_f32(mv, &cmd.T), DH_OK);
        }
        DHT_EQ_INT(dh_track_step_f32(&G->t, &cmd.T, G->t.q, &trep), DH_OK);
        if (trep.state != DH_TRACK_OK) (*notok)++;
        if (queue) {
            DHT_EQ_INT(dh_queue_advance_f32(&qu, trep.state, &rep), DH_OK);
            DHT_TRUE(rep.held == (trep.state != DH_TRACK_OK) && rep.feed == qu.mv.feed);
            c[0] = rep.clock;
            c[1] = rep.feed;
            done = rep.done;
        } else {
            DHT_EQ_INT(dh_move_advance_f32(mv, DT, trep.state, &mrep), DH_OK);
            c[0] = mrep.clock;
            c[1] = mrep.feed;
            done = mrep.done;
        }
        h ^= hash_bytes(&cmd.T, sizeof cmd.T) + 31u * hash_bytes(c, sizeof c) + (uint64_t)call;
        h *= 1099511628211ull;
        if (done) break;
    }
    *periods = call + 1;
    return h;
}

/* The Puma 560 line of test_move.c that the wrist cannot follow at its
 * speed, from near q = (10, -30, 45, 20, 35, -60): run by the queue, every
 * period's frame, clock and feed override are those of the executor bit
 * for bit, the move lags (the override acts) and completes in both. */
static void queue_feed(void)
{
    static const double QP[6] = { 10.0, -30.0, 45.0, 20.0, 35.0, -60.0 };
    static const dh_cart_limits_f32 PLIM = { 0.3f, 1.5f, 90.0f, 360.0f };
    dh_path_f32 p;
    dh_mat4_f32 A, B;
    double qa[DH_MAX_JOINTS];
    float q0[DH_MAX_JOINTS];
    long pe, pq, ne, nq;
    uint64_t he, hq;
    uint32_t i;
    rig g;
    G = &g;
    DHT_EQ_INT(dhs_build(&dhs_puma560_m, &G->r), DH_OK);
    for (i = 0; i < 6u; i++) DHT_EQ_INT(dh_robot_set_rates_f32(&G->r, i, 150.0f, 600.0f), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_f32(&G->r, &G->m), DH_OK);
    for (i = 0; i < 6u; i++) {
        qa[i] = QP[i] + dht_rand_uniform(-2.0, 2.0);
        q0[i] = (float)qa[i];
    }
    dhs_target_f32(&G->r, qa, &A);
    memset(&B, 0, sizeof B);
    for (i = 0; i < 4u; i++) B.m[i][i] = 1.0f;
    B.m[3][0] = 0.5f;
    B.m[3][1] = -0.03f;
    B.m[3][2] = 1.0f;
    DHT_EQ_INT(dh_path_line_f32(&p, &A, &B), DH_OK);
    he = puma_run(0, q0, &p, &PLIM, &pe, &ne);
    hq = puma_run(1, q0, &p, &PLIM, &pq, &nq);
    DHT_TRUE_MSG(pe < 40000 && pe == pq && ne == nq && ne > 0 && he == hq,
                 "executor %ld periods (%ld not OK), queue %ld (%ld)", pe, ne, pq, nq);
    G = NULL;
}

/* ---- errors --------------------------------------------------------------- */

static void queue_bad(void)
{
    float q[DH_MAX_JOINTS], v[DH_MAX_JOINTS], a[DH_MAX_JOINTS], bad[DH_MAX_JOINTS];
    dh_queue_cmd_f32 cmd;
    dh_queue_report_f32 rep;
    dh_path_f32 p, none;
    dh_mat4_f32 A, B;
    dh_cart_limits_f32 lim = LIM;
    double qd[DH_MAX_JOINTS] = { 10, -80, 80, 10, 80, 10 };
    uint64_t tkeep;
    uint32_t i;
    rig g;
    G = &g;
    memset(items, 0, sizeof items);
    DHT_EQ_INT(dhs_build(&dhs_ur5_m, &G->r), DH_OK);
    for (i = 0; i < 6; i++) {
        q[i] = (float)qd[i];
        v[i] = 100.0f;
        a[i] = 1000.0f;
    }
    DHT_EQ_INT(dh_track_init_f32(&G->t, &G->r, NULL, q, DT), DH_OK);
    memset(&qu, 0x5a, sizeof qu);
    save();
    DHT_EQ_INT(dh_queue_init_f32(&qu, items, 0), DH_ERR_ARG);
    same();
    DHT_EQ_INT(dh_queue_init_f32(&qu, items, CAP), DH_OK);
    DHT_EQ_INT(qu.count, 0);
    /* appends */
    save();
    DHT_EQ_INT(dh_queue_add_joint_f32(&qu, 0, q, v, a, NULL), DH_ERR_ARG);
    DHT_EQ_INT(dh_queue_add_joint_f32(&qu, DH_MAX_JOINTS + 1, q, v, a, NULL), DH_ERR_ARG);
    memcpy(bad, v, sizeof bad);
    bad[2] = 0.0f;
    DHT_EQ_INT(dh_queue_add_joint_f32(&qu, 6, q, bad, a, NULL), DH_ERR_ARG);
    DHT_EQ_INT(dh_queue_add_joint_f32(&qu, 6, q, v, a, bad), DH_ERR_ARG);
    bad[2] = NAN;
    DHT_EQ_INT(dh_queue_add_joint_f32(&qu, 6, q, v, bad, NULL), DH_ERR_NAN);
    DHT_EQ_INT(dh_queue_add_joint_f32(&qu, 6, bad, v, a, NULL), DH_ERR_NAN);
    bad[2] = -INFINITY;
    DHT_EQ_INT(dh_queue_add_joint_f32(&qu, 6, q, v, a, bad), DH_ERR_NAN);
    same();
    dhs_target_f32(&G->r, qd, &A);
    qd[0] += 5.0;
    dhs_target_f32(&G->r, qd, &B);
    DHT_EQ_INT(dh_path_line_f32(&p, &A, &B), DH_OK);
    memset(&none, 0, sizeof none);
    DHT_EQ_INT(dh_queue_add_path_f32(&qu, &none, &LIM), DH_ERR_ARG);
    lim.amax = -1.0f;
    DHT_EQ_INT(dh_queue_add_path_f32(&qu, &p, &lim), DH_ERR_ARG);
    lim.amax = NAN;
    DHT_EQ_INT(dh_queue_add_path_f32(&qu, &p, &lim), DH_ERR_NAN);
    same();
    /* period calls */
    DHT_EQ_INT(dh_queue_advance_f32(&qu, DH_TRACK_OK, &rep), DH_ERR_ARG);
    DHT_EQ_INT(dh_queue_target_f32(&qu, &G->t, 0.0f, &cmd), DH_ERR_ARG);
    DHT_EQ_INT(dh_queue_target_f32(&qu, &G->t, -DT, &cmd), DH_ERR_ARG);
    DHT_EQ_INT(dh_queue_target_f32(&qu, &G->t, NAN, &cmd), DH_ERR_NAN);
    DHT_EQ_INT(dh_queue_target_f32(&qu, &G->t, INFINITY, &cmd), DH_ERR_NAN);
    same();
    /* an empty queue: nothing to command */
    DHT_EQ_INT(dh_queue_target_f32(&qu, &G->t, DT, &cmd), DH_OK);
    DHT_EQ_INT(cmd.kind, DH_MOVE_NONE);
    save();
    DHT_EQ_INT(dh_queue_target_f32(&qu, &G->t, DT, &cmd), DH_ERR_ARG);
    DHT_EQ_INT(dh_queue_stop_f32(&qu), DH_ERR_ARG);
    DHT_EQ_INT(dh_queue_resume_f32(&qu), DH_ERR_ARG);
    DHT_EQ_INT(dh_queue_advance_f32(&qu, (dh_track_state)3, &rep), DH_ERR_ARG);
    same();
    DHT_EQ_INT(dh_queue_advance_f32(&qu, DH_TRACK_OK, &rep), DH_OK);
    DHT_EQ_INT(rep.last, 1);
    DHT_EQ_INT(rep.done, 0);
    /* a joint move for 5 joints on a 6-joint robot */
    DHT_EQ_INT(dh_queue_add_joint_f32(&qu, 5, q, v, a, NULL), DH_OK);
    save();
    DHT_EQ_INT(dh_queue_target_f32(&qu, &G->t, DT, &cmd), DH_ERR_ARG);
    same();
    /* a tracker configuration that is not finite */
    tkeep = hash_bytes(&G->t, sizeof G->t);
    G->t.q[1] = NAN;
    DHT_EQ_INT(dh_queue_target_f32(&qu, &G->t, DT, &cmd), DH_ERR_NAN);
    same();
    G->t.q[1] = q[1];
    /* sync: not finite, outside the limits: the tracker untouched */
    memcpy(bad, q, sizeof bad);
    bad[3] = NAN;
    DHT_EQ_INT(dh_track_sync_f32(&G->t, bad), DH_ERR_NAN);
    DHT_TRUE(hash_bytes(&G->t, sizeof G->t) == tkeep);
    bad[3] = G->r.joint[3].qmax + 1.0f;
    DHT_EQ_INT(dh_track_sync_f32(&G->t, bad), DH_ERR_LIMIT);
    DHT_TRUE(hash_bytes(&G->t, sizeof G->t) == tkeep);
    /* sync: the velocity from the last configuration, FK at the new one */
    memcpy(bad, q, sizeof bad);
    bad[0] += 0.01f;
    DHT_EQ_INT(dh_track_sync_f32(&G->t, bad), DH_OK);
    DHT_NEAR(G->t.v[0], ((double)bad[0] - q[0]) / DT, 1e-4);
    DHT_EQ_F32_BITS(G->t.v[1], 0.0f);
    DHT_EQ_F32_BITS(G->t.q[0], bad[0]);
    {
        dhr_mat4 R;
        double qq[DH_MAX_JOINTS];
        for (i = 0; i < 6; i++) qq[i] = bad[i];
        dhs_fk_ref_f32(&G->r, qq, NULL, &R);
        for (i = 0; i < 3; i++) DHT_NEAR(G->t.T.m[3][i], R.m[3][i], 1e-5);
    }
    /* a stop with nothing running is immediate; resume runs again */
    DHT_EQ_INT(dh_queue_init_f32(&qu, items, CAP), DH_OK);
    DHT_EQ_INT(dh_queue_stop_f32(&qu), DH_OK);
    DHT_EQ_INT(qu.phase, DH_QUEUE_STOPPED);
    DHT_EQ_INT(dh_queue_add_joint_f32(&qu, 6, q, v, a, NULL), DH_OK);
    DHT_EQ_INT(dh_queue_target_f32(&qu, &G->t, DT, &cmd), DH_OK);
    DHT_EQ_INT(cmd.kind, DH_MOVE_NONE);
    DHT_EQ_INT(dh_queue_advance_f32(&qu, DH_TRACK_OK, &rep), DH_OK);
    DHT_EQ_INT(rep.stopped, 1);
    DHT_EQ_INT(dh_queue_resume_f32(&qu), DH_OK);
    DHT_EQ_INT(qu.phase, DH_QUEUE_RUN);
    DHT_EQ_INT(dh_queue_target_f32(&qu, &G->t, DT, &cmd), DH_OK);
    DHT_EQ_INT(cmd.kind, DH_MOVE_JOINT);
    G = NULL;
}

static const dht_case cases[] = {
    DHT_CASE(joint_queues),
    DHT_CASE(path_queues),
    DHT_CASE(queue_feed),
    DHT_CASE(queue_bad),
};
DHT_MAIN(cases)
