/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_blend_q_edges.c - the fixed-point blended sequences
 * (dh_blend_seq_plan_q, dh_blend_seq_eval_q) at their edges, in mm at
 * Q16.16 (units of 2^(16 - F) mm in other length formats):
 * - every DH_ERR_ARG of the plan (sq untouched) and of the evaluation
 *   (a sequence whose scalings or lines were changed after planning: T
 *   untouched), a single line;
 * - the overlap of a corner against a double-precision reference of the
 *   plan's formula (docs/design.md, "Blended corners, fixed point"), one
 *   case for each of its four bounds (the tails' speed, half a line, the
 *   radius, the rotations' cross term) binding, and the choice between
 *   blending and rest;
 * - degenerate geometry: a straight continuation, a reversal, a line of
 *   no motion, rotation-only lines, a radius of 1 LSB and one far above
 *   half a line, a line of 1 LSB at the largest limits; each sampled
 *   every 1 ms: the point on its line within 1 LSB outside the overlaps,
 *   within the corner's dev + 2 LSB + 32 2^-30 (L1 + L2) of it inside
 *   (the contract), t = 0 and t >= T at the ends exactly;
 * - range: durations beyond the plan's range (DH_ERR_OVERFLOW, sq
 *   untouched), a sequence just inside it, a corner too near the int32
 *   range for its radius (at rest) and the same corner at the origin
 *   (blended), and the saturation of an overlap's position whose line was
 *   moved after planning (DH_ERR_OVERFLOW, the position held to int32).
 */
#include <math.h>
#include <string.h>

#include "dht.h"
#include "dhmath/motion.h"

#define PI_D 3.14159265358979323846
#define Q30 1073741824.0
/* lengths in units of 2^(16 - DH_QPOS_FRAC) mm (mm at Q16.16): the same
 * LSB values in every length format, as the planner works in LSB, so the
 * range cases sit at the int32 edge in every build */
#define QPOS 65536.0
#define MM(x) ((dh_qpos)((x) * QPOS))
#define DEG(x) ((int32_t)((x) * 65536.0))
#define NL 3

static dh_frame_q fr[NL + 1];
static dh_path_q line[NL];
static dh_blend_seg_q seg[NL];
static dh_qpos rad[NL];

/* frame k: position (mm) and a rotation of deg degrees about z then
 * deg2 about x */
static void set_frame(unsigned k, double x, double y, double z, double deg, double deg2)
{
    const double c = cos(deg * PI_D / 180.0), s = sin(deg * PI_D / 180.0);
    const double c2 = cos(deg2 * PI_D / 180.0), s2 = sin(deg2 * PI_D / 180.0);
    /* R = Rz(deg) Rx(deg2), r[col][row] */
    const double R[3][3] = { { c, -s * c2, s * s2 }, { s, c * c2, -c * s2 }, { 0.0, s2, c2 } };
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) fr[k].r[j][i] = (dh_q30)llround(R[i][j] * Q30);
    fr[k].p[0] = (dh_qpos)llround(x * QPOS);
    fr[k].p[1] = (dh_qpos)llround(y * QPOS);
    fr[k].p[2] = (dh_qpos)llround(z * QPOS);
}

static void make_lines(unsigned n)
{
    unsigned k;
    for (k = 0; k < n; k++) DHT_EQ_INT(dh_path_line_q(&line[k], &fr[k], &fr[k + 1u]), DH_OK);
}

static dh_cart_limits_q limits(double v, double a, double w, double wd)
{
    dh_cart_limits_q lim;
    lim.vmax = MM(v);
    lim.amax = MM(a);
    lim.wmax = DEG(w);
    lim.wdmax = DEG(wd);
    return lim;
}

/* distance (LSB) of the integer point x from line k's segment */
static double seg_dist(unsigned k, const dh_qpos x[3])
{
    double d[3], r[3], dd = 0.0, s = 0.0, e = 0.0;
    int i;
    for (i = 0; i < 3; i++) {
        d[i] = (double)fr[k + 1u].p[i] - fr[k].p[i];
        r[i] = (double)x[i] - fr[k].p[i];
        dd += d[i] * d[i];
        s += r[i] * d[i];
    }
    s = (dd > 0.0) ? fmin(fmax(s / dd, 0.0), 1.0) : 0.0;
    for (i = 0; i < 3; i++) e += (r[i] - s * d[i]) * (r[i] - s * d[i]);
    return sqrt(e);
}

/* the contract's position bounds, sampled every 1 ms, and the ends */
static void check_positions(const dh_blend_seq_q *sq)
{
    dh_frame_q T;
    uint32_t t, k;
    DHT_EQ_INT(dh_blend_seq_eval_q(sq, 0u, &T), DH_OK);
    DHT_TRUE(memcmp(&T, &fr[0], sizeof T) == 0);
    DHT_EQ_INT(dh_blend_seq_eval_q(sq, sq->T, &T), DH_OK);
    DHT_TRUE(memcmp(&T, &fr[sq->n], sizeof T) == 0);
    DHT_EQ_INT(dh_blend_seq_eval_q(sq, UINT32_MAX, &T), DH_OK);
    DHT_TRUE(memcmp(&T, &fr[sq->n], sizeof T) == 0);
    for (t = 0u; t < sq->T; t += 1000u) {
        DHT_EQ_INT(dh_blend_seq_eval_q(sq, t, &T), DH_OK);
        k = 0u;
        while (k + 1u < sq->n && seg[k + 1u].t0 <= t) k++;
        if (k > 0u && t - seg[k].t0 < seg[k].dur[0]) {
            double d = 0.0;
            int i;
            for (i = 0; i < 3; i++) d += ((double)T.p[i] - fr[k].p[i]) * ((double)T.p[i] - fr[k].p[i]);
            DHT_TRUE_MSG(sqrt(d) <= seg[k - 1u].dev + 2.0 + 32.0 / Q30 * ((double)line[k - 1u].length + line[k].length),
                         "t %lu: %.3f LSB from corner %u, dev %ld", (unsigned long)t, sqrt(d), (unsigned)k,
                         (long)seg[k - 1u].dev);
        } else {
            DHT_TRUE_MSG(seg_dist(k, T.p) <= 1.0, "t %lu: %.3f LSB off line %u", (unsigned long)t, seg_dist(k, T.p),
                         (unsigned)k);
        }
    }
}

/* ---- the overlap against its double reference ---------------------------- */

typedef struct {
    double V, a; /* rates of s, lowered by 2^-10 */
} ref_rates;

static ref_rates ref_rate(unsigned k, const dh_cart_limits_q *lim)
{
    const double L = line[k].length, th = line[k].angle, m = 1.0 - 1.0 / 1024.0;
    ref_rates r = { 1e300, 1e300 };
    if (L > 0.0) {
        r.V = fmin(r.V, lim->vmax / L);
        r.a = fmin(r.a, lim->amax / L);
    }
    if (th > 0.0) {
        r.V = fmin(r.V, lim->wmax / th);
        r.a = fmin(r.a, lim->wdmax / th);
    }
    r.V *= m;
    r.a *= m;
    return r;
}

/* the closed forms' duration (s) of a line of rates r with one tail (b, tb s) */
static double ref_time(ref_rates r, double b, double tb)
{
    const double u = b * tb, E = 1.0 - u * tb / 2.0, need = (r.V * r.V - u * u / 2.0) / r.a;
    double v = r.V, T = 0.0;
    if (E >= need)
        T = (E - need) / r.V;
    else
        v = sqrt(r.a * E + u * u / 2.0);
    return T + tb + (2.0 * v - u) / r.a;
}

/* corner 0's overlap (us) by the plan's formula in double, *which the
 * binding bound (0 speed, 1 half line, 2 radius, 3 rotation), *blend
 * whether the pair is shorter blended (-1: too near to call) */
static double ref_overlap(const dh_cart_limits_q *lim, dh_qpos R, int *which, int *blend)
{
    const ref_rates r1 = ref_rate(0u, lim), r2 = ref_rate(1u, lim);
    const double b1 = 63.0 / 128.0 * r1.a, b2 = 63.0 / 128.0 * r2.a;
    const double L1 = line[0].length, L2 = line[1].length, th1 = line[0].angle, th2 = line[1].angle;
    double bound[4], tb, x, y;
    int i;
    bound[0] = fmin(r1.V / b1, r2.V / b2);
    bound[1] = fmin(sqrt(128.0 / 191.0 / b1), sqrt(128.0 / 191.0 / b2));
    bound[2] = (L1 + L2 > 0.0) ? sqrt(2.0 * R / (L1 * b1 + 2.0 * L2 * b2)) : 1e300;
    bound[3] = (th1 > 0.0 && th2 > 0.0)
                   ? sqrt(lim->wdmax * (180.0 / PI_D) * 65536.0 / 16.0 / (th1 * b1 * th2 * b2))
                   : 1e300;
    *which = 0;
    for (i = 1; i < 4; i++)
        if (bound[i] < bound[*which]) *which = i;
    tb = floor(bound[*which] * (1.0 - 1.0 / 1024.0) * 1e6) * 1e-6;
    x = ref_time(r1, 0.0, 0.0) + ref_time(r2, 0.0, 0.0) + tb - ref_time(r1, b1, tb);
    y = ref_time(r2, b2, tb);
    *blend = (fabs(x - y) < 1e-6 * x) ? -1 : (y < x);
    return tb * 1e6;
}

/* two lines with corner 0 of radius R: the plan's overlap against the
 * reference, the bound that binds as expected, positions checked */
static void one_corner(const dh_cart_limits_q *lim, dh_qpos R, int expect)
{
    dh_blend_seq_q sq;
    int which, blend;
    double tb;
    make_lines(2u);
    rad[0] = R;
    DHT_EQ_INT(dh_blend_seq_plan_q(&sq, seg, line, 2u, rad, lim), DH_OK);
    tb = ref_overlap(lim, R, &which, &blend);
    DHT_EQ_INT(which, expect);
    DHT_TRUE(blend != -1);
    if (blend == 1) {
        DHT_TRUE_MSG(fabs((double)seg[0].dur[4] - tb) <= 1.0 + 1e-6 * tb, "overlap %lu us, reference %.1f us",
                     (unsigned long)seg[0].dur[4], tb);
        DHT_TRUE(seg[0].dev <= R && seg[0].dev > 0);
        /* the tails within half a line each */
        DHT_TRUE(seg[0].s[4] >= DH_Q30_ONE / 2 && seg[1].s[1] <= DH_Q30_ONE / 2);
    } else {
        DHT_EQ_INT(seg[0].dur[4], 0);
        DHT_EQ_INT(seg[0].dev, 0);
    }
    DHT_EQ_INT(seg[0].dur[4], seg[1].dur[0]);
    DHT_EQ_INT(sq.T, seg[1].t0 + seg[1].T);
    check_positions(&sq);
}

static void overlap_bounds(void)
{
    dh_cart_limits_q lim;
    /* the tails' speed: slow lines, fast accelerations, a wide radius */
    set_frame(0u, 0.0, 0.0, 0.0, 0.0, 0.0);
    set_frame(1u, 200.0, 0.0, 0.0, 0.0, 0.0);
    set_frame(2u, 200.0, 200.0, 0.0, 0.0, 0.0);
    lim = limits(10.0, 5000.0, 90.0, 500.0);
    one_corner(&lim, MM(1000.0), 0);
    /* half a line: fast lines, a wide radius */
    lim = limits(1000.0, 1000.0, 90.0, 500.0);
    one_corner(&lim, MM(1000.0), 1);
    /* the radius */
    lim = limits(100.0, 1000.0, 90.0, 500.0);
    one_corner(&lim, MM(1.0), 2);
    /* the rotations' cross term: short lines turning far */
    set_frame(1u, 10.0, 0.0, 0.0, 90.0, 0.0);
    set_frame(2u, 10.0, 10.0, 0.0, 90.0, 90.0);
    lim = limits(100.0, 1000.0, 90.0, 100.0);
    one_corner(&lim, MM(100.0), 3);
}

/* ---- degenerate geometry -------------------------------------------------- */

static void plan_check(unsigned n, const dh_cart_limits_q *lim)
{
    dh_blend_seq_q sq;
    make_lines(n);
    DHT_EQ_INT(dh_blend_seq_plan_q(&sq, seg, line, n, rad, lim), DH_OK);
    check_positions(&sq);
}

static void degenerate(void)
{
    dh_cart_limits_q lim = limits(200.0, 1000.0, 90.0, 500.0);
    /* a straight continuation: blended, the point on the line throughout */
    set_frame(0u, 0.0, 0.0, 0.0, 0.0, 0.0);
    set_frame(1u, 100.0, 0.0, 0.0, 0.0, 0.0);
    set_frame(2u, 300.0, 0.0, 0.0, 0.0, 0.0);
    rad[0] = MM(20.0);
    plan_check(2u, &lim);
    DHT_TRUE(seg[0].dur[4] > 0u);
    /* a reversal */
    set_frame(2u, 20.0, 0.0, 0.0, 0.0, 0.0);
    plan_check(2u, &lim);
    DHT_TRUE(seg[0].dur[4] > 0u);
    /* a line of no motion between two: both corners at rest, it lasts 0 */
    set_frame(2u, 100.0, 0.0, 0.0, 0.0, 0.0);
    set_frame(3u, 100.0, 100.0, 0.0, 0.0, 0.0);
    rad[1] = MM(20.0);
    plan_check(3u, &lim);
    DHT_EQ_INT(seg[1].T, 0);
    DHT_EQ_INT(seg[0].dur[4] | seg[1].dur[0] | seg[1].dur[4] | seg[2].dur[0], 0);
    /* rotation-only lines, blended: the position stays exactly */
    set_frame(1u, 0.0, 0.0, 0.0, 40.0, 0.0);
    set_frame(2u, 0.0, 0.0, 0.0, 40.0, 60.0);
    plan_check(2u, &lim);
    DHT_TRUE(seg[0].dur[4] > 0u);
    DHT_EQ_INT(line[0].length | line[1].length, 0);
    /* radii of 1 to 2^20 LSB (16 mm): the radius binds; blended as the
     * reference decides (below about 1/16 mm the blend does not shorten
     * the pair), its dev within the radius; the widest blended */
    set_frame(1u, 100.0, 0.0, 0.0, 0.0, 0.0);
    set_frame(2u, 100.0, 100.0, 0.0, 0.0, 0.0);
    {
        dh_qpos r;
        for (r = 1; r <= (1 << 20); r *= 4) one_corner(&lim, r, 2);
    }
    DHT_TRUE(seg[0].dur[4] > 0u);
    rad[0] = MM(30000.0);
    /* a radius far above half a line: the tails within half their lines */
    plan_check(2u, &lim);
    DHT_TRUE(seg[0].dur[4] > 0u && seg[0].s[4] >= DH_Q30_ONE / 2 && seg[1].s[1] <= DH_Q30_ONE / 2);
    /* a line of 1 LSB at the largest limits: one short scaling */
    fr[1] = fr[0];
    fr[1].p[0] += 1;
    lim.vmax = lim.amax = lim.wmax = lim.wdmax = INT32_MAX;
    plan_check(1u, &lim);
    DHT_TRUE(seg[0].T > 0u && seg[0].T < 100u);
}

/* ---- statuses ------------------------------------------------------------- */

static void plan_args(void)
{
    const dh_cart_limits_q good = limits(200.0, 1000.0, 90.0, 500.0);
    dh_cart_limits_q lim = good;
    dh_blend_seq_q sq, probe;
    dh_path_q keep;
    int i;
    set_frame(0u, 0.0, 0.0, 0.0, 0.0, 0.0);
    set_frame(1u, 100.0, 0.0, 0.0, 10.0, 0.0);
    set_frame(2u, 100.0, 100.0, 0.0, 10.0, 20.0);
    make_lines(2u);
    rad[0] = MM(10.0);
    memset(&sq, 0x5A, sizeof sq);
    memset(&probe, 0x5A, sizeof probe);
    DHT_EQ_INT(dh_blend_seq_plan_q(&sq, seg, line, 0u, rad, &lim), DH_ERR_ARG);
    for (i = 0; i < 4; i++) {
        int32_t *f = (i == 0) ? &lim.vmax : (i == 1) ? &lim.amax : (i == 2) ? &lim.wmax : &lim.wdmax;
        *f = 0;
        DHT_EQ_INT(dh_blend_seq_plan_q(&sq, seg, line, 2u, rad, &lim), DH_ERR_ARG);
        *f = -1;
        DHT_EQ_INT(dh_blend_seq_plan_q(&sq, seg, line, 2u, rad, &lim), DH_ERR_ARG);
        lim = good;
    }
    rad[0] = -1;
    DHT_EQ_INT(dh_blend_seq_plan_q(&sq, seg, line, 2u, rad, &lim), DH_ERR_ARG);
    rad[0] = MM(10.0);
    keep = line[1];
    line[1].length = -1;
    DHT_EQ_INT(dh_blend_seq_plan_q(&sq, seg, line, 2u, rad, &lim), DH_ERR_ARG);
    line[1] = keep;
    line[1].angle = -1;
    DHT_EQ_INT(dh_blend_seq_plan_q(&sq, seg, line, 2u, rad, &lim), DH_ERR_ARG);
    line[1] = keep;
    line[1].kind = (uint32_t)DH_PATH_ARC;
    DHT_EQ_INT(dh_blend_seq_plan_q(&sq, seg, line, 2u, rad, &lim), DH_ERR_ARG);
    line[1] = keep;
    line[1].qb.w = 0;
    line[1].qb.x = 0;
    line[1].qb.y = 0;
    line[1].qb.z = 0;
    DHT_EQ_INT(dh_blend_seq_plan_q(&sq, seg, line, 2u, rad, &lim), DH_ERR_ARG);
    line[1] = keep;
    line[1].A.r[0][0] += 1;
    DHT_EQ_INT(dh_blend_seq_plan_q(&sq, seg, line, 2u, rad, &lim), DH_ERR_ARG);
    line[1] = keep;
    DHT_TRUE(memcmp(&sq, &probe, sizeof sq) == 0);
    /* a single line (no radius needed) */
    DHT_EQ_INT(dh_blend_seq_plan_q(&sq, seg, line, 1u, NULL, &lim), DH_OK);
    DHT_EQ_INT(sq.n, 1);
    DHT_EQ_INT(sq.T, seg[0].T);
    DHT_EQ_INT(seg[0].dur[0] | seg[0].dur[4], 0);
    check_positions(&sq);
}

/* a blended pair, corner at the origin, then each change after planning
 * the evaluation refuses (T untouched) or saturates */
static void eval_args(void)
{
    const dh_cart_limits_q lim = limits(200.0, 1000.0, 90.0, 500.0);
    dh_blend_seq_q sq;
    dh_blend_seg_q keep;
    dh_path_q kp;
    dh_frame_q T, probe;
    uint32_t tov, tl;
    set_frame(0u, -100.0, 0.0, 0.0, 0.0, 0.0);
    set_frame(1u, 0.0, 0.0, 0.0, 10.0, 0.0);
    set_frame(2u, 0.0, -100.0, 0.0, 10.0, 20.0);
    make_lines(2u);
    rad[0] = MM(10.0);
    DHT_EQ_INT(dh_blend_seq_plan_q(&sq, seg, line, 2u, rad, &lim), DH_OK);
    DHT_TRUE(seg[0].dur[4] > 2u);
    tov = seg[1].t0 + seg[1].dur[0] / 2u; /* in the overlap */
    tl = seg[0].t0 + seg[0].dur[1] / 2u;  /* line 0 alone */
    memset(&probe, 0x3C, sizeof probe);
    T = probe;
    /* a start outside [0, 1] */
    keep = seg[1];
    seg[1].s[2] = -1;
    DHT_EQ_INT(dh_blend_seq_eval_q(&sq, tov, &T), DH_ERR_ARG);
    seg[1].s[2] = DH_Q30_ONE + 1;
    DHT_EQ_INT(dh_blend_seq_eval_q(&sq, tov, &T), DH_ERR_ARG);
    /* durations that do not sum to T, a duration of 2^31 us */
    seg[1] = keep;
    seg[1].dur[2] += 1u;
    DHT_EQ_INT(dh_blend_seq_eval_q(&sq, tov, &T), DH_ERR_ARG);
    seg[1] = keep;
    seg[1].dur[2] += 0x80000000u - seg[1].T;
    seg[1].T = 0x80000000u;
    DHT_EQ_INT(dh_blend_seq_eval_q(&sq, tov, &T), DH_ERR_ARG);
    seg[1] = keep;
    /* the line before in the overlap */
    keep = seg[0];
    seg[0].dur[1] += 1u;
    DHT_EQ_INT(dh_blend_seq_eval_q(&sq, tov, &T), DH_ERR_ARG);
    seg[0] = keep;
    /* the lines of the overlap holding no path */
    kp = line[0];
    memset(&line[0], 0, sizeof line[0]);
    DHT_EQ_INT(dh_blend_seq_eval_q(&sq, tov, &T), DH_ERR_ARG);
    line[0] = kp;
    kp = line[1];
    memset(&line[1], 0, sizeof line[1]);
    DHT_EQ_INT(dh_blend_seq_eval_q(&sq, tov, &T), DH_ERR_ARG);
    line[1] = kp;
    DHT_TRUE(memcmp(&T, &probe, sizeof T) == 0);
    /* a sequence of no lines */
    {
        dh_blend_seq_q none = sq;
        none.n = 0u;
        DHT_EQ_INT(dh_blend_seq_eval_q(&none, tl, &T), DH_ERR_ARG);
    }
    DHT_TRUE(memcmp(&T, &probe, sizeof T) == 0);
    /* changed polynomials: s held to [0, 1], so the line's ends exactly */
    keep = seg[0];
    seg[0].Q[1] = INT32_MIN;
    DHT_EQ_INT(dh_blend_seq_eval_q(&sq, tl, &T), DH_OK);
    DHT_TRUE(memcmp(&T, &fr[0], sizeof T) == 0);
    seg[0].Q[1] = INT32_MAX;
    seg[0].P[1] = INT32_MAX;
    DHT_EQ_INT(dh_blend_seq_eval_q(&sq, tl, &T), DH_OK);
    DHT_TRUE(memcmp(&T, &fr[1], sizeof T) == 0);
    seg[0] = keep;
    /* the overlap's position beyond int32 (line 0 at s 0 moved to the
     * range's edge, line 1 leaving the corner downwards in y and in x):
     * saturated and reported, its rotation still the blend's */
    DHT_EQ_INT(dh_blend_seq_eval_q(&sq, tov, &probe), DH_OK);
    seg[0].P[4] = INT32_MIN;
    line[0].A.p[0] = INT32_MIN;
    line[0].A.p[1] = INT32_MIN;
    line[0].A.p[2] = INT32_MAX;
    line[1].B.p[0] = MM(-100.0);
    line[1].B.p[2] = MM(100.0);
    DHT_EQ_INT(dh_blend_seq_eval_q(&sq, tov, &T), DH_ERR_OVERFLOW);
    DHT_EQ_INT(T.p[0], INT32_MIN);
    DHT_EQ_INT(T.p[1], INT32_MIN);
    DHT_EQ_INT(T.p[2], INT32_MAX);
    seg[0] = keep;
    make_lines(2u);
    {
        /* s of line 0 held at 0 changes the rotation, so compare only after
         * the lines are back: the same time evaluates as before */
        DHT_EQ_INT(dh_blend_seq_eval_q(&sq, tov, &T), DH_OK);
        DHT_TRUE(memcmp(&T, &probe, sizeof T) == 0);
    }
}

/* durations beyond the range; a corner near the range's edge */
static void range(void)
{
    dh_cart_limits_q lim = limits(1.0, 1.0 / 256.0, 90.0, 500.0);
    dh_blend_seq_q sq, probe;
    memset(&sq, 0x5A, sizeof sq);
    memset(&probe, 0x5A, sizeof probe);
    /* 2^31 - 1 LSB at 1 LSB/s: 2^31 s */
    set_frame(0u, 0.0, 0.0, 0.0, 0.0, 0.0);
    fr[1] = fr[0];
    fr[1].p[0] = INT32_MAX;
    lim.vmax = 1;
    lim.amax = 1;
    make_lines(1u);
    DHT_EQ_INT(dh_blend_seq_plan_q(&sq, seg, line, 1u, NULL, &lim), DH_ERR_OVERFLOW);
    /* an acceleration of 250 s, a cruise of 250 s: 750 s each line, two
     * fit (1.5e9 us), three do not (2^31 us is 2147 s) */
    lim = limits(1.0, 1.0 / 256.0, 90.0, 500.0);
    set_frame(1u, 500.0, 0.0, 0.0, 0.0, 0.0);
    set_frame(2u, 500.0, 500.0, 0.0, 0.0, 0.0);
    set_frame(3u, 0.0, 500.0, 0.0, 0.0, 0.0);
    make_lines(3u);
    rad[0] = rad[1] = MM(5.0);
    DHT_EQ_INT(dh_blend_seq_plan_q(&sq, seg, line, 3u, rad, &lim), DH_ERR_OVERFLOW);
    DHT_TRUE(memcmp(&sq, &probe, sizeof sq) == 0);
    DHT_EQ_INT(dh_blend_seq_plan_q(&sq, seg, line, 2u, rad, &lim), DH_OK);
    DHT_TRUE(sq.T > 1400000000u && sq.T < 1600000000u);
    {
        dh_frame_q T;
        DHT_EQ_INT(dh_blend_seq_eval_q(&sq, sq.T, &T), DH_OK);
        DHT_TRUE(memcmp(&T, &fr[2], sizeof T) == 0);
        DHT_EQ_INT(dh_blend_seq_eval_q(&sq, sq.T / 4u, &T), DH_OK);
        DHT_TRUE(seg_dist(0u, T.p) <= 1.0 || seg_dist(1u, T.p) <= 1.0);
    }
    /* a corner 10 mm inside the range with a radius of 20 mm: at rest;
     * the same lines moved to the origin: blended */
    lim = limits(200.0, 1000.0, 90.0, 500.0);
    set_frame(0u, 32600.0, 0.0, 0.0, 0.0, 0.0);
    set_frame(1u, 32757.0, 0.0, 0.0, 0.0, 0.0);
    set_frame(2u, 32757.0, -200.0, 0.0, 0.0, 0.0);
    rad[0] = MM(20.0);
    plan_check(2u, &lim);
    DHT_EQ_INT(seg[0].dur[4], 0);
    set_frame(0u, -157.0, 0.0, 0.0, 0.0, 0.0);
    set_frame(1u, 0.0, 0.0, 0.0, 0.0, 0.0);
    set_frame(2u, 0.0, -200.0, 0.0, 0.0, 0.0);
    plan_check(2u, &lim);
    DHT_TRUE(seg[0].dur[4] > 0u);
}

static const dht_case cases[] = {
    DHT_CASE(overlap_bounds), DHT_CASE(degenerate), DHT_CASE(plan_args), DHT_CASE(eval_args), DHT_CASE(range),
};
DHT_MAIN(cases)
