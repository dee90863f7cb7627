/* SPDX-License-Identifier: Apache-2.0 */
/*
 * fw_float_motion.c - firmware example for a core with a single-precision
 * FPU (Cortex-M4F): a UR5 draws a square with blended corners, then a
 * circle, one tracker call per 1 ms period (1 kHz), in float.
 *
 * The UR5 (examples/robots/ur5.dh, metres) is built at run time with the
 * float setters and given joint rate limits: 180 deg/s on every joint, the
 * UR5's published joint speed (Universal Robots, UR5 technical
 * specification; docs/references.md), and 720 deg/s^2, this example's
 * choice (the specification publishes no acceleration). dh_ikc_analyse_f32
 * finds its closed form; dh_track_init_f32 starts the tracker at Q0.
 *
 * The moves keep the tool's orientation at Q0's and move its position in
 * the base's x-y plane, within LIM (0.25 m/s, 2 m/s^2):
 *   - a square of SIDE (0.1 m) from the start position p0: +x, +y, -x, -y,
 *     planned by dh_blend_seq_plan_f32 with RADIUS (10 mm) at its three
 *     inner corners (it starts and ends at rest at p0); each period tracks
 *     dh_blend_seq_eval_f32 at that period's time;
 *   - a circle of CIRCLE_R (50 mm) through p0, centre p0 + (CIRCLE_R, 0, 0),
 *     as two half-circle arcs (dh_path_arc_f32), each a path move
 *     (dh_move_path_f32: target, tracker call, advance each period; at rest
 *     between the arcs).
 *
 * Output (one "key: values" line each; floats with 9 digits, enough to
 * read back the exact value; lengths in m, angles in degrees):
 *   dt: <period s>  vmax: <deg/s>  amax: <deg/s^2>  pos_tol: <tracker's, m>
 *   lim: <speed m/s> <accel m/s^2>  radius: <blend radius m>
 *   q0: <6 joints>  p0: <start position>  corner: <i> <x y z> (i = 0..4)
 *   overlap: <i> <first period> <last period> of the blend at corner i
 *   circle: <centre x y z> <radius>
 *   q: <period> <state 0 ok, 1 lagging, 2 unreachable> <6 joints>, every
 *      period from 0 (the start) to the end of the circle; periods 1 ..
 *      square_end draw the square, the rest the circle
 *   square_end: <its last period>
 *   line_dev: <largest distance of FK(q) from the square's outline, in the
 *      periods outside the overlaps>
 *   blend_dev: <largest distance of FK(q) from the corner, in the overlaps>
 *   circle_dev: <largest distance of FK(q) from the circle>
 *   peak_rate: <largest |q_k - q_(k-1)| / dt over joints and periods>
 *   peak_accel: <largest |q_k - 2 q_(k-W) + q_(k-2W)| / (W dt)^2, W = 4:
 *      the mean acceleration over windows of 4 periods (one period's second
 *      difference of float joints carries rounding of its own)>
 *   periods: <ok> <lagging> <unreachable>
 * examples/firmware/check_output.py recomputes the FK of every printed
 * configuration in double precision from the DH table and checks the
 * path deviations, rates and accelerations against the limits and the
 * summary lines against its own figures.
 */
#include <math.h>
#include <stdio.h>

#include "dhmath/dhmath.h"

#define DT 0.001f           /* 1 kHz */
#define VMAX 180.0f         /* deg/s, every joint */
#define AMAX 720.0f         /* deg/s^2, every joint */
#define SIDE 0.1f           /* m */
#define RADIUS 0.01f        /* m, every inner corner */
#define CIRCLE_R 0.05f      /* m */
#define ARC_PERIODS 20000u  /* a path move's periods at most */
#define W 4u                /* periods per window of the acceleration */

typedef struct {
    float d, a, alpha;
} ur5_row;

/* examples/robots/ur5.dh: Universal Robots' published DH table */
static const ur5_row ur5[6] = {
    { 0.089159f, 0.0f, 90.0f },  { 0.0f, -0.425f, 0.0f },    { 0.0f, -0.39225f, 0.0f },
    { 0.10915f, 0.0f, 90.0f },   { 0.09465f, 0.0f, -90.0f }, { 0.0823f, 0.0f, 0.0f },
};

static const float Q0[6] = { 20.0f, -110.0f, 95.0f, -75.0f, 60.0f, 30.0f };
static const float SQX[5] = { 0.0f, SIDE, SIDE, 0.0f, 0.0f };
static const float SQY[5] = { 0.0f, 0.0f, SIDE, SIDE, 0.0f };

/* Everything the loop measures; static: no heap, a small stack */
typedef struct {
    dh_robot r;
    dh_ikc_model_f32 m;
    dh_track_f32 t;
    dh_path_f32 lines[4];
    dh_blend_seg_f32 seg[4];
    dh_blend_seq_f32 sq;
    dh_path_f32 arc;
    dh_move_f32 mv;
    float p0[3];
    float hist[2u * W + 1u][6]; /* the last 2W + 1 configurations, hist[k % (2W + 1)] */
    unsigned k;                 /* periods run */
    unsigned ovl[3][2];         /* overlaps: first and last period */
    unsigned count[3];          /* periods per tracker state */
    float line_dev, blend_dev, circle_dev, peak_rate, peak_accel;
} motion;

static motion g;

static float absf(float x)
{
    return x < 0.0f ? -x : x;
}

static void print_vec(const char *key, const float *v, unsigned n)
{
    unsigned i;
    printf("%s:", key);
    for (i = 0; i < n; i++) printf(" %.9g", (double)v[i]);
    printf("\n");
}

/* Position of the tool at q, relative to p0 */
static int tool_at(const float *q, float *x, float *y, float *z)
{
    dh_mat4_f32 T;
    if (dh_fk_f32(&g.r, q, &T) != DH_OK) return 1;
    *x = DH_M4(&T, 0, 3) - g.p0[0];
    *y = DH_M4(&T, 1, 3) - g.p0[1];
    *z = DH_M4(&T, 2, 3) - g.p0[2];
    return 0;
}

/* Distance of (x, y, z) from the square's outline (its four sides) */
static float square_dist(float x, float y, float z)
{
    float best = -1.0f, d, u, v;
    unsigned i;
    for (i = 0; i < 4u; i++) {
        /* closest point of side i: clamp the coordinate along it */
        u = x - SQX[i];
        v = y - SQY[i];
        if (SQX[i] == SQX[i + 1u]) {
            const float lo = SQY[i] < SQY[i + 1u] ? SQY[i] : SQY[i + 1u];
            v = y < lo ? y - lo : (y > lo + SIDE ? y - lo - SIDE : 0.0f);
        } else {
            const float lo = SQX[i] < SQX[i + 1u] ? SQX[i] : SQX[i + 1u];
            u = x < lo ? x - lo : (x > lo + SIDE ? x - lo - SIDE : 0.0f);
        }
        d = sqrtf(u * u + v * v + z * z);
        if (best < 0.0f || d < best) best = d;
    }
    return best;
}

/* Records period k's configuration q and state: prints it, and updates
 * the peak rate and the windowed acceleration */
static void record(const float *q, dh_track_state st)
{
    const unsigned n = 2u * W + 1u;
    float *cur = g.hist[g.k % n];
    unsigned j;
    for (j = 0; j < 6u; j++) cur[j] = q[j];
    printf("q: %u %d", g.k, (int)st);
    for (j = 0; j < 6u; j++) printf(" %.9g", (double)q[j]);
    printf("\n");
    g.count[st]++;
    for (j = 0; g.k >= 1u && j < 6u; j++) {
        const float rate = absf(cur[j] - g.hist[(g.k - 1u) % n][j]) / DT;
        if (rate > g.peak_rate) g.peak_rate = rate;
    }
    for (j = 0; g.k >= 2u * W && j < 6u; j++) {
        const float acc = absf((cur[j] - g.hist[(g.k - W) % n][j]) - (g.hist[(g.k - W) % n][j] - g.hist[(g.k - 2u * W) % n][j])) /
                          ((float)W * DT * (float)W * DT);
        if (acc > g.peak_accel) g.peak_accel = acc;
    }
    g.k++;
}

static int in_overlap(unsigned k)
{
    unsigned i;
    for (i = 0; i < 3u; i++)
        if (k >= g.ovl[i][0] && k <= g.ovl[i][1]) return (int)i + 1;
    return 0;
}

static int build_robot(void)
{
    unsigned i;
    if (dh_robot_init(&g.r, DH_CONV_STANDARD) != DH_OK) return 1;
    for (i = 0; i < 6u; i++) {
        if (dh_robot_add_joint_f32(&g.r, DH_JOINT_REVOLUTE, 0.0f, ur5[i].d, ur5[i].a, ur5[i].alpha) != DH_OK ||
            dh_robot_set_limits_f32(&g.r, i, -360.0f, 360.0f) != DH_OK ||
            dh_robot_set_rates_f32(&g.r, i, VMAX, AMAX) != DH_OK)
            return 1;
    }
    return dh_ikc_analyse_f32(&g.r, &g.m) == DH_OK ? 0 : 1;
}

/* The square: plan, then one tracker call per period on the sequence's frame */
static int draw_square(const dh_mat4_f32 *A0, const dh_cart_limits_f32 *lim)
{
    const float radius[3] = { RADIUS, RADIUS, RADIUS };
    dh_mat4_f32 A = *A0, B, T;
    dh_track_report_f32 rep;
    float q[6], x, y, z, d;
    unsigned i, k, nk;
    int c;

    for (i = 0; i < 4u; i++) {
        B = A;
        DH_M4(&B, 0, 3) = g.p0[0] + SQX[i + 1u];
        DH_M4(&B, 1, 3) = g.p0[1] + SQY[i + 1u];
        if (dh_path_line_f32(&g.lines[i], &A, &B) != DH_OK) return 1;
        A = B;
    }
    if (dh_blend_seq_plan_f32(&g.sq, g.seg, g.lines, 4u, radius, lim) != DH_OK) return 1;
    for (i = 0; i < 3u; i++) {
        /* the blend at corner i + 1: line i + 1's start tail, in periods (rounded outwards) */
        const float t0 = g.seg[i + 1u].t0, t1 = g.seg[i + 1u].t0 + g.seg[i + 1u].tb0;
        g.ovl[i][0] = (unsigned)(t0 / DT);
        g.ovl[i][1] = (unsigned)(t1 / DT) + 1u;
        printf("overlap: %u %u %u\n", i + 1u, g.ovl[i][0], g.ovl[i][1]);
    }
    nk = (unsigned)(g.sq.T / DT) + 1u;
    for (k = 1; k <= nk; k++) {
        float tk = (float)k * DT;
        if (tk > g.sq.T) tk = g.sq.T;
        if (dh_blend_seq_eval_f32(&g.sq, tk, &T) != DH_OK) return 1;
        if (dh_track_step_f32(&g.t, &T, q, &rep) != DH_OK) return 1;
        record(q, rep.state);
        if (tool_at(q, &x, &y, &z) != 0) return 1;
        c = in_overlap(k);
        if (c) {
            d = sqrtf((x - SQX[c]) * (x - SQX[c]) + (y - SQY[c]) * (y - SQY[c]) + z * z);
            if (d > g.blend_dev) g.blend_dev = d;
        } else {
            d = square_dist(x, y, z);
            if (d > g.line_dev) g.line_dev = d;
        }
    }
    printf("square_end: %u\n", g.k - 1u);
    return 0;
}

/* One half of the circle: a path move along the arc A -> via -> B */
static int draw_arc(const dh_mat4_f32 *A, const float via[3], const dh_mat4_f32 *B, const dh_cart_limits_f32 *lim)
{
    dh_mat4_f32 T;
    dh_track_report_f32 trep;
    dh_move_report_f32 rep;
    float q[6], x, y, z, u, d;
    unsigned k = 0;

    if (dh_path_arc_f32(&g.arc, A, via, B) != DH_OK || dh_move_path_f32(&g.mv, &g.arc, lim) != DH_OK) return 1;
    do {
        if (dh_move_target_f32(&g.mv, &T) != DH_OK || dh_track_step_f32(&g.t, &T, q, &trep) != DH_OK ||
            dh_move_advance_f32(&g.mv, DT, trep.state, &rep) != DH_OK)
            return 1;
        record(q, trep.state);
        if (tool_at(q, &x, &y, &z) != 0) return 1;
        u = x - CIRCLE_R;
        d = sqrtf(u * u + y * y) - CIRCLE_R;
        d = sqrtf(d * d + z * z);
        if (d > g.circle_dev) g.circle_dev = d;
        k++;
    } while (!rep.done && k < ARC_PERIODS);
    return rep.done ? 0 : 1;
}

int main(void)
{
    const dh_cart_limits_f32 lim = { 0.25f, 2.0f, 90.0f, 360.0f };
    dh_mat4_f32 A, B;
    float via[3], c[4], lv[2];
    unsigned i;

    if (build_robot() != 0 || dh_track_init_f32(&g.t, &g.r, &g.m, Q0, DT) != DH_OK) return 1;
    if (dh_fk_f32(&g.r, Q0, &A) != DH_OK) return 1;
    for (i = 0; i < 3u; i++) g.p0[i] = DH_M4(&A, i, 3);
    printf("dt: %.9g\nvmax: %.9g\namax: %.9g\npos_tol: %.9g\n", (double)DT, (double)VMAX, (double)AMAX,
           (double)g.t.pos_tol);
    lv[0] = lim.vmax;
    lv[1] = lim.amax;
    print_vec("lim", lv, 2);
    printf("radius: %.9g\n", (double)RADIUS);
    print_vec("q0", Q0, 6);
    print_vec("p0", g.p0, 3);
    for (i = 0; i < 5u; i++) {
        const float p[3] = { g.p0[0] + SQX[i], g.p0[1] + SQY[i], g.p0[2] };
        printf("corner: %u %.9g %.9g %.9g\n", i, (double)p[0], (double)p[1], (double)p[2]);
    }
    c[0] = g.p0[0] + CIRCLE_R;
    c[1] = g.p0[1];
    c[2] = g.p0[2];
    c[3] = CIRCLE_R;
    print_vec("circle", c, 4);

    record(Q0, DH_TRACK_OK); /* period 0: at rest at the start */
    if (draw_square(&A, &lim) != 0) return 1;

    /* the circle: p0 -> p0 + (2R, 0, 0) below the x axis, then back above it */
    B = A;
    DH_M4(&B, 0, 3) = g.p0[0] + 2.0f * CIRCLE_R;
    via[0] = g.p0[0] + CIRCLE_R;
    via[1] = g.p0[1] - CIRCLE_R;
    via[2] = g.p0[2];
    if (draw_arc(&A, via, &B, &lim) != 0) return 1;
    via[1] = g.p0[1] + CIRCLE_R;
    if (draw_arc(&B, via, &A, &lim) != 0) return 1;

    printf("line_dev: %.9g\nblend_dev: %.9g\ncircle_dev: %.9g\n", (double)g.line_dev, (double)g.blend_dev,
           (double)g.circle_dev);
    printf("peak_rate: %.9g\npeak_accel: %.9g\n", (double)g.peak_rate, (double)g.peak_accel);
    printf("periods: %u %u %u\n", g.count[0], g.count[1], g.count[2]);
    return 0;
}
