/* SPDX-License-Identifier: Apache-2.0 */
/*
 * fw_fixed_motion.c - firmware example for a core without FPU (Cortex-M0+):
 * a UR5 draws a square with blended corners, then a circle, one tracker
 * call per 1 ms period (1 kHz), in fixed point, integer only (no float
 * routine linked: examples/firmware/no_float.cmake). The fixed half of the
 * issue's example; fw_float_motion.c is the float half.
 *
 * The UR5 table lives in flash (`dhmath gen examples/robots/ur5_mm.dh
 * dhg_ur5_mm`, run by the build); the firmware copies it to RAM and sets
 * the joint rate limits there: 180 deg/s on every joint, the UR5's
 * published joint speed (Universal Robots, UR5 technical specification;
 * docs/references.md), and 720 deg/s^2, this example's choice (the
 * specification publishes no acceleration). dh_ikc_analyse_q finds the
 * closed form; dh_track_init_q starts the tracker at Q0, dt 1000 us.
 *
 * The moves keep the tool's orientation at Q0's and move its position in
 * the base's x-y plane, within 250 mm/s and 1000 mm/s^2 (lim in main; at
 * 2000 mm/s^2 this square asks more than 720 deg/s^2 of the joints near
 * its corners, and the fixed sequence, which has no feed override, runs
 * on while the tracker lags):
 *   - a square of SIDE (100 mm) from the start position p0: +x, +y, -x, -y,
 *     planned by dh_blend_seq_plan_q with RADIUS (10 mm) at its three inner
 *     corners (it starts and ends at rest at p0); each period tracks
 *     dh_blend_seq_eval_q at that period's time;
 *   - a circle of CIRCLE_R (50 mm) through p0, centre p0 + (CIRCLE_R, 0, 0),
 *     as two half-circle arcs (dh_path_arc_q), each a path move
 *     (dh_move_path_q: target, tracker call, advance each period).
 *
 * Output (raw fixed-point integers through fw_print.c; lengths dh_qpos,
 * angles Q16.16 degrees, times us):
 *   dt_us: <period>  vmax_q16: <deg/s>  amax_q16: <deg/s^2>
 *   bound_q16: <the tracker's step bound floor(vmax dt)>
 *   pos_tol_qpos: <the tracker's position tolerance>
 *   lim_qpos: <speed> <accel>  radius_qpos: <blend radius>
 *   q0_q16: <6 joints>  p0_qpos: <start position>
 *   corner: <i> <x y z> (i = 0..4)  dev_qpos: <i> <the plan's bound seg.dev>
 *   overlap: <i> <first period> <last period> of the blend at corner i
 *   circle: <centre x y z> <radius>
 *   q: <period> <state 0 ok, 1 lagging, 2 unreachable> <6 joints>, every
 *      period from 0 (the start) to the end of the circle; periods 1 ..
 *      square_end draw the square, the rest the circle
 *   square_end: <its last period>
 *   line_dev_qpos: <largest distance of FK(q) from the square's outline, in
 *      the periods outside the overlaps (integer square root, rounded up)>
 *   blend_dev_qpos: <largest distance of FK(q) from the corner, in the overlaps>
 *   circle_dev_qpos: <largest distance of FK(q) from the circle>
 *   peak_step_q16: <largest |q_k - q_(k-1)| over joints and periods>
 *   peak_acc_q16: <largest |q_k - 2 q_(k-W) + q_(k-2W)|, W = 4 periods>
 *   periods: <ok> <lagging> <unreachable>
 * examples/firmware/check_output.py recomputes the FK of every printed
 * configuration in double precision from the DH table and checks the path
 * deviations, rates and accelerations against the limits and the summary
 * lines against its own figures.
 */
#include <string.h>

#include "dhmath/dhmath.h"
#include "fw_print.h"

/* UR5 in mm (examples/robots/ur5_mm.dh), generated into .rodata by
 * dhmath_add_robot() (examples/firmware/CMakeLists.txt) */
extern const dh_robot dhg_ur5_mm;

#define DT_US 1000u             /* 1 kHz */
#define VMAX DH_Q16(180.0)      /* deg/s, every joint */
#define AMAX DH_Q16(720.0)      /* deg/s^2, every joint */
#define SIDE DH_QPOS(100.0)     /* mm */
#define RADIUS DH_QPOS(10.0)    /* mm, every inner corner */
#define CIRCLE_R DH_QPOS(50.0)  /* mm */
#define ARC_PERIODS 20000u      /* a path move's periods at most */
#define HOLD_MAX 2000u          /* periods at the square's end until the tracker is ok */
#define W 4u                    /* periods per window of the acceleration */

static const dh_q16 Q0[6] = { DH_Q16(20.0), DH_Q16(-110.0), DH_Q16(95.0), DH_Q16(-75.0), DH_Q16(60.0),
                              DH_Q16(30.0) };
static const int32_t SQX[5] = { 0, SIDE, SIDE, 0, 0 };
static const int32_t SQY[5] = { 0, 0, SIDE, SIDE, 0 };

/* Everything the loop measures; static: no heap, a small stack */
typedef struct {
    dh_robot r;
    dh_ikc_model_q m;
    dh_track_q t;
    dh_path_q lines[4];
    dh_blend_seg_q seg[4];
    dh_blend_seq_q sq;
    dh_move_q mv;                /* its path: the arc, built in place */
    dh_qpos p0[3];
    int32_t hist[2u * W + 1u][6]; /* the last 2W + 1 configurations, hist[k % (2W + 1)] */
    uint32_t k;                   /* periods run */
    uint32_t ovl[3][2];           /* overlaps: first and last period */
    int32_t count[3];             /* periods per tracker state */
    int32_t line_dev, blend_dev, circle_dev, peak_step, peak_acc;
} motion;

static motion g;

static int32_t iabs(int32_t x)
{
    return x < 0 ? -x : x;
}

/* ceil(sqrt(v)) for v < 2^62, bit by bit */
static int32_t isqrt_up(uint64_t v)
{
    uint64_t r = 0u, bit = (uint64_t)1 << 62, x = v;
    while (bit > x) bit >>= 2;
    while (bit != 0u) {
        if (x >= r + bit) {
            x -= r + bit;
            r = (r >> 1) + bit;
        } else {
            r >>= 1;
        }
        bit >>= 2;
    }
    return (int32_t)(r + ((x != 0u) ? 1u : 0u));
}

/* |(x, y, z)| (dh_qpos), rounded up */
static int32_t norm3(int64_t x, int64_t y, int64_t z)
{
    return isqrt_up((uint64_t)(x * x + y * y + z * z));
}

/* the position of the tool at q, relative to p0 */
static int tool_at(const int32_t *q, int64_t d[3])
{
    dh_frame_q T;
    uint32_t i;
    if (dh_fk_q(&g.r, q, &T) != DH_OK) return 1;
    for (i = 0; i < 3u; i++) d[i] = (int64_t)T.p[i] - g.p0[i];
    return 0;
}

/* distance of d from the square's outline (its four sides) */
static int32_t square_dist(const int64_t d[3])
{
    int32_t best = INT32_MAX, e;
    int64_t u, v, lo;
    uint32_t i;
    for (i = 0; i < 4u; i++) {
        u = d[0] - SQX[i];
        v = d[1] - SQY[i];
        if (SQX[i] == SQX[i + 1u]) {
            lo = SQY[i] < SQY[i + 1u] ? SQY[i] : SQY[i + 1u];
            v = d[1] < lo ? d[1] - lo : (d[1] > lo + SIDE ? d[1] - lo - SIDE : 0);
        } else {
            lo = SQX[i] < SQX[i + 1u] ? SQX[i] : SQX[i + 1u];
            u = d[0] < lo ? d[0] - lo : (d[0] > lo + SIDE ? d[0] - lo - SIDE : 0);
        }
        e = norm3(u, v, d[2]);
        if (e < best) best = e;
    }
    return best;
}

/* Records period k's configuration q and state: prints it, and updates
 * the peak step and the windowed second difference */
static void record(const int32_t *q, dh_track_state st)
{
    const uint32_t n = 2u * W + 1u;
    int32_t *cur = g.hist[g.k % n], v[8];
    uint32_t j;
    memcpy(cur, q, 6u * sizeof q[0]);
    v[0] = (int32_t)g.k;
    v[1] = (int32_t)st;
    memcpy(&v[2], q, 6u * sizeof q[0]);
    fw_put_line("q:", v, 8u);
    g.count[st]++;
    for (j = 0; g.k >= 1u && j < 6u; j++) {
        const int32_t s = iabs(cur[j] - g.hist[(g.k - 1u) % n][j]);
        if (s > g.peak_step) g.peak_step = s;
    }
    for (j = 0; g.k >= 2u * W && j < 6u; j++) {
        const int32_t *a = g.hist[(g.k - W) % n], *b = g.hist[(g.k - 2u * W) % n];
        const int32_t acc = iabs((cur[j] - a[j]) - (a[j] - b[j]));
        if (acc > g.peak_acc) g.peak_acc = acc;
    }
    g.k++;
}

/* the corner (1..3) whose overlap holds period k, 0 for none */
static uint32_t in_overlap(uint32_t k)
{
    uint32_t i;
    for (i = 0; i < 3u; i++)
        if (k >= g.ovl[i][0] && k <= g.ovl[i][1]) return i + 1u;
    return 0u;
}

/* the square: plan, then one tracker call per period on the sequence's frame */
static int draw_square(const dh_frame_q *A0, const dh_cart_limits_q *lim)
{
    const dh_qpos radius[3] = { RADIUS, RADIUS, RADIUS };
    dh_frame_q A = *A0, B, T;
    dh_track_report_q rep;
    int32_t q[6], v[4];
    int64_t d[3];
    uint32_t i, k, c, t = 0u;
    dh_status st;
    for (i = 0; i < 4u; i++) {
        B = A;
        B.p[0] = g.p0[0] + SQX[i + 1u];
        B.p[1] = g.p0[1] + SQY[i + 1u];
        st = dh_path_line_q(&g.lines[i], &A, &B);
        if (st != DH_OK) return fw_fail("dh_path_line_q", st);
        A = B;
    }
    st = dh_blend_seq_plan_q(&g.sq, g.seg, g.lines, 4u, radius, lim);
    if (st != DH_OK) return fw_fail("dh_blend_seq_plan_q", st);
    for (i = 0; i < 3u; i++) {
        /* the blend at corner i + 1: line i + 1's start tail, in periods (rounded outwards) */
        g.ovl[i][0] = g.seg[i + 1u].t0 / DT_US;
        g.ovl[i][1] = (g.seg[i + 1u].t0 + g.seg[i + 1u].dur[0]) / DT_US + 1u;
        v[0] = (int32_t)(i + 1u);
        v[1] = (int32_t)g.ovl[i][0];
        v[2] = (int32_t)g.ovl[i][1];
        fw_put_line("overlap:", v, 3u);
        v[1] = g.seg[i].dev;
        fw_put_line("dev_qpos:", v, 2u);
    }
    rep.state = DH_TRACK_LAGGING;
    for (k = 1u; t < g.sq.T || (rep.state != DH_TRACK_OK && k < g.sq.T / DT_US + HOLD_MAX); k++) {
        t = (g.sq.T - t > DT_US) ? t + DT_US : g.sq.T;
        st = dh_blend_seq_eval_q(&g.sq, t, &T);
        if (st == DH_OK) st = dh_track_step_q(&g.t, &T, q, &rep);
        if (st != DH_OK) return fw_fail("square period", st);
        record(q, rep.state);
        if (tool_at(q, d) != 0) return fw_fail("dh_fk_q", DH_ERR_ARG);
        c = in_overlap(k);
        if (c != 0u) {
            const int32_t e = norm3(d[0] - SQX[c], d[1] - SQY[c], d[2]);
            if (e > g.blend_dev) g.blend_dev = e;
        } else {
            const int32_t e = square_dist(d);
            if (e > g.line_dev) g.line_dev = e;
        }
    }
    v[0] = (int32_t)(g.k - 1u);
    fw_put_line("square_end:", v, 1u);
    return rep.state == DH_TRACK_OK ? 0 : fw_fail("square end", DH_ERR_LIMIT);
}

/* one half of the circle: a path move along the arc A -> via -> B */
static int draw_arc(const dh_frame_q *A, const dh_qpos via[3], const dh_frame_q *B, const dh_cart_limits_q *lim)
{
    dh_frame_q T;
    dh_track_report_q trep;
    dh_move_report_q rep;
    int32_t q[6];
    int64_t d[3];
    uint32_t k = 0u;
    dh_status st = dh_path_arc_q(&g.mv.path, A, via, B);
    if (st == DH_OK) st = dh_move_path_q(&g.mv, &g.mv.path, lim);
    if (st != DH_OK) return fw_fail("dh_path_arc_q / dh_move_path_q", st);
    do {
        st = dh_move_target_q(&g.mv, &T);
        if (st == DH_OK) st = dh_track_step_q(&g.t, &T, q, &trep);
        if (st == DH_OK) st = dh_move_advance_q(&g.mv, DT_US, trep.state, &rep);
        if (st != DH_OK) return fw_fail("arc period", st);
        record(q, trep.state);
        if (tool_at(q, d) != 0) return fw_fail("dh_fk_q", DH_ERR_ARG);
        {
            const int64_t u = d[0] - CIRCLE_R;
            const int32_t e = iabs(norm3(u, d[1], 0) - CIRCLE_R);
            const int32_t f = norm3(e, d[2], 0);
            if (f > g.circle_dev) g.circle_dev = f;
        }
        k++;
    } while (!rep.done && k < ARC_PERIODS);
    return rep.done ? 0 : fw_fail("arc end", DH_ERR_LIMIT);
}

int main(void)
{
    const dh_cart_limits_q lim = { DH_QPOS(250.0), DH_QPOS(1000.0), DH_Q16(90.0), DH_Q16(360.0) };
    dh_frame_q A, B;
    dh_qpos via[3];
    int32_t v[6];
    uint32_t i;
    dh_status st = DH_OK;

    g.r = dhg_ur5_mm;
    for (i = 0; i < 6u && st == DH_OK; i++) st = dh_robot_set_rates_q(&g.r, i, VMAX, AMAX);
    if (st != DH_OK) return fw_fail("dh_robot_set_rates_q", st);
    st = dh_ikc_analyse_q(&g.r, &g.m);
    if (st == DH_OK) st = dh_track_init_q(&g.t, &g.r, &g.m, Q0, DT_US);
    if (st == DH_OK) st = dh_fk_q(&g.r, Q0, &A);
    if (st != DH_OK) return fw_fail("set-up", st);
    memcpy(g.p0, A.p, sizeof g.p0);

    v[0] = (int32_t)DT_US;
    fw_put_line("dt_us:", v, 1u);
    v[0] = VMAX;
    fw_put_line("vmax_q16:", v, 1u);
    v[0] = AMAX;
    fw_put_line("amax_q16:", v, 1u);
    fw_put_line("bound_q16:", g.t.dq_max, 6u);
    v[0] = g.t.pos_tol;
    fw_put_line("pos_tol_qpos:", v, 1u);
    v[0] = lim.vmax;
    v[1] = lim.amax;
    fw_put_line("lim_qpos:", v, 2u);
    v[0] = RADIUS;
    fw_put_line("radius_qpos:", v, 1u);
    fw_put_line("q0_q16:", Q0, 6u);
    fw_put_line("p0_qpos:", g.p0, 3u);
    for (i = 0; i < 5u; i++) {
        v[0] = (int32_t)i;
        v[1] = g.p0[0] + SQX[i];
        v[2] = g.p0[1] + SQY[i];
        v[3] = g.p0[2];
        fw_put_line("corner:", v, 4u);
    }
    v[0] = g.p0[0] + CIRCLE_R;
    v[1] = g.p0[1];
    v[2] = g.p0[2];
    v[3] = CIRCLE_R;
    fw_put_line("circle:", v, 4u);

    record(Q0, DH_TRACK_OK); /* period 0: at rest at the start */
    if (draw_square(&A, &lim) != 0) return 1;

    /* the circle: p0 -> p0 + (2R, 0, 0) below the x axis, then back above it */
    B = A;
    B.p[0] = g.p0[0] + 2 * CIRCLE_R;
    via[0] = g.p0[0] + CIRCLE_R;
    via[1] = g.p0[1] - CIRCLE_R;
    via[2] = g.p0[2];
    if (draw_arc(&A, via, &B, &lim) != 0) return 1;
    via[1] = g.p0[1] + CIRCLE_R;
    if (draw_arc(&B, via, &A, &lim) != 0) return 1;

    fw_put_line("line_dev_qpos:", &g.line_dev, 1u);
    fw_put_line("blend_dev_qpos:", &g.blend_dev, 1u);
    fw_put_line("circle_dev_qpos:", &g.circle_dev, 1u);
    fw_put_line("peak_step_q16:", &g.peak_step, 1u);
    fw_put_line("peak_acc_q16:", &g.peak_acc, 1u);
    fw_put_line("periods:", g.count, 3u);
    return 0;
}
