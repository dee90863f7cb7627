/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_jerk_q.c - the fixed-point jerk-limited moves (motion.h:
 * dh_path_move_jerk_q, dh_move_path_jerk_q, dh_queue_add_path_jerk_q,
 * dh_queue_add_joint_q with jmax) in mm (Q16.16), seeded, against
 * references computed here in double.
 *
 * Paths (lines and arcs between tool frames of random UR5
 * configurations): the duration equals the seven-phase minimum
 * (dhr_scurve_tmin) for the rates of s of the float twin's rule, computed
 * in double from the integer limits (line: V / L, A / L, J / L and the
 * angular ones over the angle; arc of radius R: V = min(vmax,
 * sqrt(amax R / sqrt 2), cbrt(J R^2 / 4)), At = min(amax sqrt(1 -
 * (V^2 / (amax R))^2), J R / (12 V)), Jt = J / 2), within the rounding
 * of the rates (1 LSB of each rate of s, 1 LSB of V) and 2 us; speed,
 * total acceleration, total jerk, angular speed, acceleration and jerk by
 * finite differences (first, second, third) of the evaluated frames over
 * windows of w periods at 1 kHz within the limits times 1 + 1e-3 plus the
 * noise terms 2 N / h, 4 N / h^2, 8 N / h^3 (h = w dt), w the least window
 * with each noise term within 2.5e-4 of its limit (N: the arc's 4 LSB +
 * 2^-26 R, the profile's 4 + 2^-27 2^e LSB of 2^e, 1 LSB; the rotation's
 * 3e-6 rad); every sampled point within 5e-3 mm of the double line or
 * circle; the ends exact.
 *
 * Executor: a jerk-limited line or arc run by dh_move_advance_q with a
 * stretch of LAGGING periods (the feed override falls) and OK periods
 * after it (it rises): the target's speed and total acceleration over
 * windows within the limits (the jerk is bounded only while r is
 * constant, motion.h); r reaches 0 when the stretch began in the first
 * half of the move; the move completes at B exactly.
 *
 * Queue (UR5, fixed tracker): jerk-limited joint moves and a jerk-limited
 * line, one stop at a random period and a resume after a rest; every
 * joint command over windows within vmax and amax, and within jmax over
 * windows where the time warp stayed 1; the path targets' speed and
 * total acceleration within the Cartesian limits; stopped reported and
 * the commands still while stopped; every move completes, joint moves at
 * q1 exactly.
 *
 * Every status of the new functions, with the outputs as the contracts
 * say.
 */
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_ref.h"
#include "support_robots.h"
#include "support_motion_q.h"
#include "dhmath/motion.h"
#include "dhmath/track.h"
#include "dhmath/frame.h"

#define DT_US 1000u
#define DT 1e-3
#define QPOS DHSM_QPOS
#define Q16 DHSM_Q16
#define LS DHSM_LS
#define PI_D 3.14159265358979323846
#define PATH_TOL (5e-3 * ldexp(1.0, 16 - DH_QPOS_FRAC))
#define REL_FD 1e-3
#define NOISE_FRAC 2.5e-4
#define ROT_NOISE 3e-6
#define RING 16   /* ring entries (the micro:bit's RAM) */
#define CAP 1u    /* queue items: each move appended as the queue drains (RAM) */

static dhsm_rig the_rig;
/* the executor's move or the queue, one at a time (the micro:bit's RAM) */
static union {
    dh_move_q mv;
    dh_queue_q qu;
} the_mem;
static int32_t ring[RING][6]; /* positions (6 joints or 3 coordinates), one every dec periods */
static unsigned char ring_r1[RING];        /* 1 when r was 1 since the entry before */

/* the least window (periods) with k N / (w dt)^m within NOISE_FRAC of lim */
static long window(double k, double N, double lim, int m)
{
    const double h = pow(k * N / (NOISE_FRAC * lim), 1.0 / m);
    const long w = (long)ceil(h / DT);
    return w < 1 ? 1 : w;
}

/* the double rates of s of a jerk-limited move along p (file comment) */
static void ref_rates(const dh_path_q *p, const dh_cart_limits_q *lim, const dh_cart_jerk_q *jk, double *r)
{
    double V = lim->vmax / QPOS, A = lim->amax / QPOS, J = jk->jmax / QPOS, At = A, Jt = J;
    const double L = p->length / QPOS, ang = p->angle / Q16;
    if (p->kind == (uint32_t)DH_PATH_ARC) {
        const double R = p->radius / QPOS;
        V = fmin(V, fmin(sqrt(A * R / sqrt(2.0)), cbrt(J * R * R / 4.0)));
        At = fmin(A * sqrt(1.0 - pow(V * V / (A * R), 2.0)), J * R / (12.0 * V));
        Jt = J / 2.0;
    }
    r[0] = V / L;
    r[1] = At / L;
    r[2] = Jt / L;
    if (ang > 0.0) {
        r[0] = fmin(r[0], lim->wmax / Q16 / ang);
        r[1] = fmin(r[1], lim->wdmax / Q16 / ang);
        r[2] = fmin(r[2], jk->wjmax / Q16 / ang);
    }
    r[3] = V * QPOS;
}

/* a random line or arc between tool frames of UR5 configurations (via:
 * the arc's via point) */
static int path_rand(const dhsm_rig *g, int arc, dh_path_q *p, dh_qpos *via, int32_t *ia)
{
    double qa[DH_MAX_JOINTS], qb[DH_MAX_JOINTS];
    int32_t ib[DH_MAX_JOINTS], im[DH_MAX_JOINTS];
    dh_frame_q A, B, M;
    int i;
    dhsm_region_q(g, qa);
    for (i = 0; i < 6; i++) qb[i] = qa[i] + dht_rand_uniform(4.0, 12.0) * (dht_rand_uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0);
    dhs_q_from_double(&g->r, qa, ia);
    dhs_q_from_double(&g->r, qb, ib);
    for (i = 0; i < 6; i++) im[i] = ia[i] / 2 + ib[i] / 2 + (int32_t)(dht_rand_uniform(-4.0, 4.0) * Q16);
    dhsm_target_of(g, ia, &A);
    dhsm_target_of(g, ib, &B);
    dhsm_target_of(g, im, &M);
    memcpy(via, M.p, 3u * sizeof via[0]);
    return arc ? dh_path_arc_q(p, &A, via, &B) == DH_OK : dh_path_line_q(p, &A, &B) == DH_OK;
}

static void draw_limits(dh_cart_limits_q *lim, dh_cart_jerk_q *jk)
{
    lim->vmax = (int32_t)(dht_rand_uniform(50.0, 400.0) * LS * QPOS);
    lim->amax = (int32_t)(dht_rand_uniform(500.0, 3000.0) * LS * QPOS);
    lim->wmax = (int32_t)(dht_rand_uniform(30.0, 180.0) * Q16);
    lim->wdmax = (int32_t)(dht_rand_uniform(200.0, 1000.0) * Q16);
    jk->jmax = (int32_t)(dht_rand_uniform(3000.0, 30000.0) * LS * QPOS);
    jk->wjmax = (int32_t)(dht_rand_uniform(2000.0, 20000.0) * Q16);
}

/* position (mm) and angle from A (rad) of the move at t us */
static void sample(const dh_profile_q *pr, uint32_t e, const dh_path_q *p, const dhsm_ref *rp, long t, double *x)
{
    dh_frame_q F;
    int c;
    DHT_EQ_INT(dh_path_move_eval_q(pr, e, p, (uint32_t)t, &F), DH_OK);
    for (c = 0; c < 3; c++) x[c] = F.p[c] / QPOS;
    x[3] = dhsm_rot_between(&p->A, &F);
    DHT_TRUE_MSG(dhsm_ref_dist(rp, x) <= PATH_TOL, "t %ld: %.3g mm off the path", t, dhsm_ref_dist(rp, x));
}

/* the m-th difference (m 1..3) over w periods from period k: |linear| in
 * mm/s^m into d[0], angular in rad/s^m into d[1] */
static void diff_m(const dh_profile_q *pr, uint32_t e, const dh_path_q *p, const dhsm_ref *rp, long k, long w, int m,
                   double *d)
{
    static const double cf[3][4] = { { -1.0, 1.0, 0.0, 0.0 }, { 1.0, -2.0, 1.0, 0.0 }, { -1.0, 3.0, -3.0, 1.0 } };
    double x[4], s[4] = { 0.0, 0.0, 0.0, 0.0 };
    const double h = pow(w * DT, m);
    int i, c;
    for (i = 0; i <= m; i++) {
        sample(pr, e, p, rp, (k + i * w) * (long)DT_US, x);
        for (c = 0; c < 4; c++) s[c] += cf[m - 1][i] * x[c];
    }
    d[0] = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]) / h;
    d[1] = fabs(s[3]) / h;
}

/* the limits of one derivative m over every window of a move; 0 when the
 * move is too short for its window */
static long check_fd(const dh_profile_q *pr, uint32_t e, const dh_path_q *p, const dhsm_ref *rp, const double *lin,
                     const double *rot, double N, int m, long mv)
{
    static const double kn[3] = { 2.0, 4.0, 8.0 };
    const long wl = window(kn[m - 1], N, lin[m - 1], m), wr = window(kn[m - 1], ROT_NOISE, rot[m - 1], m);
    const long w = wl > wr ? wl : wr, nk = (long)(pr->T / DT_US) + 2;
    long k, cnt = 0;
    for (k = 0; k + m * w <= nk; k += (w > 4 ? w / 4 : 1)) {
        double d[2];
        const double h = pow(w * DT, m);
        diff_m(pr, e, p, rp, k, w, m, d);
        DHT_TRUE_MSG(d[0] <= lin[m - 1] * (1 + REL_FD) + kn[m - 1] * N / h, "move %ld: d%d linear %.6g > %.6g (w %ld)",
                     mv, m, d[0], lin[m - 1], w);
        DHT_TRUE_MSG(d[1] <= rot[m - 1] * (1 + REL_FD) + kn[m - 1] * ROT_NOISE / h,
                     "move %ld: d%d angular %.6g > %.6g (w %ld)", mv, m, d[1], rot[m - 1], w);
        cnt++;
    }
    return cnt;
}

static void jerk_paths_q_vs_double(void)
{
    dhsm_rig *const g = &the_rig;
    long i, n = DHT_ITER(40), win[3] = { 0, 0, 0 };
    double worst_T = 0.0;
    dhsm_rig_make(g, &dhs_ur5_mm, 180.0, 720.0);
    for (i = 0; i < n; i++) {
        const int arc = (i & 1) != 0;
        dh_path_q p;
        dh_qpos via[3];
        int32_t ia[DH_MAX_JOINTS];
        dh_cart_limits_q lim;
        dh_cart_jerk_q jk;
        dh_profile_q pr;
        dh_frame_q T;
        dhsm_ref rp;
        uint32_t e = 99u;
        double r[4], Tref, N, lin[3], rot[3], lo, hi;
        int m;
        if (!path_rand(g, arc, &p, via, ia)) continue;
        draw_limits(&lim, &jk);
        DHT_EQ_INT(dh_path_move_jerk_q(&pr, &e, &p, &lim, &jk), DH_OK);
        DHT_EQ_INT((int)pr.kind, (int)DH_PROFILE_SCURVE);
        DHT_EQ_INT(pr.d, (int32_t)1 << e);
        ref_rates(&p, &lim, &jk, r);
        Tref = dhr_scurve_tmin(1.0, r[0], r[1], r[2]);
        /* the fixed V rounds down by < 1 LSB, which raises J R / (12 V) by as much */
        lo = Tref * (1.0 - 1e-7 - 2.0 / r[3]) - 1e-6;
        hi = Tref * (1.0 + 1e-6 + 2.0 / pr.v + 2.0 / pr.a + 2.0 / pr.j + 4.0 / r[3]) + 2e-6;
        DHT_TRUE_MSG(pr.T * 1e-6 >= lo && pr.T * 1e-6 <= hi, "move %ld: T %.9f s, the minimum %.9f", i, pr.T * 1e-6, Tref);
        if (fabs(pr.T * 1e-6 / Tref - 1.0) > worst_T) worst_T = fabs(pr.T * 1e-6 / Tref - 1.0);
        DHT_EQ_INT(dh_path_move_eval_q(&pr, e, &p, 0u, &T), DH_OK);
        DHT_TRUE(memcmp(&T, &p.A, sizeof T) == 0);
        DHT_EQ_INT(dh_path_move_eval_q(&pr, e, &p, pr.T, &T), DH_OK);
        DHT_TRUE(memcmp(&T, &p.B, sizeof T) == 0);
        dhsm_ref_make(&rp, &p, arc ? via : NULL);
        N = ((arc ? 4.0 + ldexp(p.radius, -26) : 0.5) + 1.0) / QPOS +
            p.length / QPOS * (5.0 * ldexp(1.0, -(int)e) + ldexp(1.0, -27));
        lin[0] = lim.vmax / QPOS;
        lin[1] = lim.amax / QPOS;
        lin[2] = jk.jmax / QPOS;
        rot[0] = lim.wmax / Q16 * PI_D / 180.0;
        rot[1] = lim.wdmax / Q16 * PI_D / 180.0;
        rot[2] = jk.wjmax / Q16 * PI_D / 180.0;
        for (m = 1; m <= 3; m++) win[m - 1] += check_fd(&pr, e, &p, &rp, lin, rot, N, m, i);
    }
    DHT_TRUE(win[0] > 10 * n && win[1] > 10 * n && win[2] > 2 * n);
    /* integers only: a double's conversion needs more heap than the
     * micro:bit leaves beside this suite */
    dht_printf("%ld jerk-limited moves: T within %ld ppb of the minimum; windows %ld (speed) %ld (acceleration) %ld "
               "(jerk)\n", n, (long)ceil(worst_T * 1e9), win[0], win[1], win[2]);
}

/* ring entry k periods back (k < RING) */
static int32_t *ring_at(long at, long k)
{
    return ring[(at - k + RING) % RING];
}

/* the Cartesian target's speed (one entry) and acceleration (window wa
 * entries of dec periods) at ring entry at, limits V, A (LSB/s^k) */
static void ring_cart(long at, long filled, long dec, long wa, double N, double V, double A, const char *what)
{
    const int32_t *p0, *p1, *p2;
    double s1 = 0.0, s2 = 0.0, h = dec * DT;
    int c;
    if (filled >= 2) {
        p0 = ring_at(at, 1);
        p1 = ring_at(at, 0);
        for (c = 0; c < 3; c++) s1 += pow((double)p1[c] - p0[c], 2.0);
        DHT_TRUE_MSG(sqrt(s1) / h <= V * (1 + REL_FD) + 2.0 * N / h, "%s: speed %.6g > %.6g", what, sqrt(s1) / h, V);
    }
    if (filled > 2 * wa) {
        p0 = ring_at(at, 2 * wa);
        p1 = ring_at(at, wa);
        p2 = ring_at(at, 0);
        h = wa * dec * DT;
        for (c = 0; c < 3; c++) s2 += pow((double)p2[c] - 2.0 * p1[c] + p0[c], 2.0);
        DHT_TRUE_MSG(sqrt(s2) / (h * h) <= A * (1 + REL_FD) + 4.0 * N / (h * h), "%s: acceleration %.6g > %.6g (w %ld)",
                     what, sqrt(s2) / (h * h), A, wa);
    }
}

static void executor_stop_q(void)
{
    dhsm_rig *const g = &the_rig;
    long i, n = DHT_ITER(12), zero = 0;
    dhsm_rig_make(g, &dhs_ur5_mm, 180.0, 720.0);
    for (i = 0; i < n; i++) {
        dh_path_q p;
        dh_qpos via[3];
        int32_t ia[DH_MAX_JOINTS];
        dh_cart_limits_q lim;
        dh_cart_jerk_q jk;
        dh_move_q *const mv = &the_mem.mv;
        dh_move_report_q rep;
        dh_frame_q T;
        long k, k0, len, at = -1, filled = 0, wa, dec;
        double N, A;
        uint32_t c0 = 0u;
        if (!path_rand(g, (i & 1) != 0, &p, via, ia)) continue;
        draw_limits(&lim, &jk);
        DHT_EQ_INT(dh_move_path_jerk_q(mv, &p, &lim, &jk), DH_OK);
        /* even moves: the stretch begins in the first half (r must reach 0) */
        k0 = (long)dht_rand_uniform(0.0, mv->dur / ((i & 1) != 0 ? 1000.0 : 2000.0));
        len = (long)(mv->dur / 1000u) + 1000;
        /* noise: the path and profile, the clock's 1 us at vmax, 1 LSB */
        N = 6.0 + ldexp(p.radius, -26) + lim.vmax * 1e-6 + ldexp((double)p.length, -27);
        A = lim.amax;
        /* entries dec periods apart, the acceleration's 2 wa within the ring */
        wa = window(4.0, N, A, 2);
        dec = 1 + 2 * wa / (RING - 4);
        wa = 1 + wa / dec;
        for (k = 0; k < 10L * len; k++) {
            const dh_track_state st = (k >= k0 && k < k0 + len) ? DH_TRACK_LAGGING : DH_TRACK_OK;
            DHT_EQ_INT(dh_move_target_q(mv, &T), DH_OK);
            if (k % dec == 0) {
                at = (at + 1) % RING;
                memcpy(ring[at], T.p, 3u * sizeof T.p[0]);
                filled++;
                ring_cart(at, filled, dec, wa, N, lim.vmax, A, "executor");
            }
            if (k == k0) c0 = mv->clock;
            DHT_EQ_INT(dh_move_advance_q(mv, DT_US, st, &rep), DH_OK);
            DHT_TRUE(rep.feed >= 0 && rep.feed <= DH_Q30_ONE && rep.held == (st != DH_TRACK_OK));
            if (k == k0 + len - 1 && 2u * c0 <= mv->dur && (uint64_t)mv->prof[0].a * 2000u > (uint64_t)mv->prof[0].j * 4u) {
                DHT_TRUE_MSG(rep.feed == 0, "move %ld: r %d after the stop", i, (int)rep.feed);
                zero++;
            }
            if (rep.done) break;
        }
        DHT_TRUE_MSG(rep.done, "move %ld: not done", i);
        DHT_EQ_INT(dh_move_target_q(mv, &T), DH_OK);
        DHT_TRUE(memcmp(&T, &p.B, sizeof T) == 0);
    }
    DHT_TRUE(zero > 0);
    dht_printf("%ld jerk-limited executor moves with a stretch of lagging periods, %ld brought to r = 0\n", n, zero);
}

/* every joint of the ring's newest entry: step within vmax, change over wa
 * entries within amax, third difference over wj entries within jmax when
 * r stayed 1 (limits in LSB/s^k, entries dec periods apart; noise N,
 * NJ for the jerk) */
static long jerk_windows; /* windows of the joints' jerk checked by ring_joints */

static void ring_joints(long at, long filled, long dec, long wa, long wj, double N, double NJ, const int32_t *v, const int32_t *a,
                        const int32_t *j)
{
    const double h = dec * DT;
    int i;
    long k, r1 = 1;
    for (k = 0; k < 3 * wj && k < filled; k++) r1 &= ring_r1[(at - k + RING) % RING];
    jerk_windows += filled > 3 * wj && r1;
    for (i = 0; i < 6; i++) {
        if (filled >= 2) {
            const double d = fabs((double)ring_at(at, 0)[i] - ring_at(at, 1)[i]) / h;
            DHT_TRUE_MSG(d <= v[i] * (1 + REL_FD) + 2.0 * N / h, "joint %d: rate %.6g > %d", i, d, (int)v[i]);
        }
        if (filled > 2 * wa) {
            const double hw = wa * h;
            const double d = fabs((double)ring_at(at, 0)[i] - 2.0 * ring_at(at, wa)[i] + ring_at(at, 2 * wa)[i]) / (hw * hw);
            DHT_TRUE_MSG(d <= a[i] * (1 + REL_FD) + 4.0 * N / (hw * hw), "joint %d: acceleration %.6g > %d", i, d, (int)a[i]);
        }
        if (filled > 3 * wj && r1) {
            const double hw = wj * h;
            const double d = fabs((double)ring_at(at, 0)[i] - 3.0 * ring_at(at, wj)[i] + 3.0 * ring_at(at, 2 * wj)[i] -
                                  ring_at(at, 3 * wj)[i]) /
                             (hw * hw * hw);
            DHT_TRUE_MSG(d <= j[i] * (1 + REL_FD) + 8.0 * NJ / (hw * hw * hw), "joint %d: jerk %.6g > %d", i, d, (int)j[i]);
        }
    }
}

/* one queue: joint move to ib, jerk-limited line to the tool frame of ic,
 * joint move back to ia (all jerk-limited), stopped at period kstop and
 * resumed rest periods after it came to rest */
static void run_queue(dhsm_rig *g, long kstop, long rest, long *stats)
{
    static const dh_cart_limits_q LIM = { 250 << 16, 2000 << 16, 45 << 16, 360 << 16 };
    static const dh_cart_jerk_q JK = { 8000 << 16, 3000 << 16 };
    dh_queue_q *const qu = &the_mem.qu;
    dh_track_q trk; /* on the stack: the micro:bit's .data + .bss are full */
    dh_queue_item_q items[CAP]; /* on the stack: the micro:bit's .data + .bss has no room for it */
    double qa[DH_MAX_JOINTS], qb[DH_MAX_JOINTS], qc[DH_MAX_JOINTS];
    int32_t ia[DH_MAX_JOINTS], ib[DH_MAX_JOINTS], ic[DH_MAX_JOINTS], v[6], a[6], j[6], q[DH_MAX_JOINTS];
    dh_frame_q B, C;
    dh_path_q p;
    dh_queue_cmd_q cmd;
    dh_queue_report_q rep;
    dh_track_report_q trep;
    long k, at = -1, filled = 0, stopped_at = -1, done = 0, dec, wa, wj;
    /* noise (LSB): a joint command's 4 + 2^-27 |d| and 1 us at vmax (NJ),
     * with the tracker's output (N) */
    const double N = 30.0, NJ = 13.0;
    int i, ok = 0, tries = 0, r1 = 1, added = 0;
    dh_q30 rprev = DH_Q30_ONE;
    while (!ok && tries++ < 50) {
        dhsm_region_q(g, qa);
        dhsm_region_q(g, qb);
        for (i = 0; i < 6; i++) qc[i] = qb[i] + dht_rand_uniform(-8.0, 8.0);
        dhs_q_from_double(&g->r, qa, ia);
        dhs_q_from_double(&g->r, qb, ib);
        dhs_q_from_double(&g->r, qc, ic);
        dhsm_target_of(g, ib, &B);
        dhsm_target_of(g, ic, &C);
        DHT_EQ_INT(dh_path_line_q(&p, &B, &C), DH_OK);
        ok = dhsm_path_reachable(g, &p, ib);
    }
    DHT_TRUE(ok);
    for (i = 0; i < 6; i++) {
        v[i] = g->r.joint[i].vmax_q;
        a[i] = g->r.joint[i].amax_q;
        j[i] = (int32_t)(dht_rand_uniform(300.0, 1500.0) * Q16);
    }
    wa = window(4.0, N, a[0], 2);
    wj = window(8.0, NJ, j[0], 3);
    for (i = 1; i < 6; i++) {
        if (window(8.0, NJ, j[i], 3) > wj) wj = window(8.0, NJ, j[i], 3);
        if (window(4.0, N, a[i], 2) > wa) wa = window(4.0, N, a[i], 2);
    }
    /* entries dec periods apart, the jerk's 3 wj entries within the ring */
    dec = 1 + 3 * wj / (RING - 8);
    wa = 1 + wa / dec;
    wj = 1 + wj / dec;
    DHT_TRUE(3 * wj < RING);
    DHT_EQ_INT(dh_queue_init_q(qu, items, CAP), DH_OK);
    DHT_EQ_INT(dh_track_init_q(&trk, &g->r, &g->m, ia, DT_US), DH_OK);
    memcpy(q, ia, sizeof q);
    for (k = 0; k < 200000 && done < 3; k++) {
        dh_track_state st = DH_TRACK_OK;
        int32_t qprev[DH_MAX_JOINTS];
        memcpy(qprev, q, sizeof q);
        /* the three moves appended as the queue drains */
        /* after 3 wj entries at rest (the jerk windows then cover the first
         * move from its start) */
        if (added < 3 && qu->count < qu->cap && k >= 3 * wj * dec) {
            if (added == 1)
                DHT_EQ_INT(dh_queue_add_path_jerk_q(qu, &p, &LIM, &JK), DH_OK);
            else
                DHT_EQ_INT(dh_queue_add_joint_q(qu, 6u, (added == 0) ? ib : ia, v, a, j), DH_OK);
            added++;
        }
        if (k == kstop) DHT_EQ_INT(dh_queue_stop_q(qu), DH_OK);
        if (stopped_at >= 0 && k == stopped_at + rest) DHT_EQ_INT(dh_queue_resume_q(qu), DH_OK);
        DHT_EQ_INT(dh_queue_target_q(qu, &trk, &cmd), DH_OK);
        if (cmd.kind == (uint32_t)DH_MOVE_PATH) {
            if (cmd.sync) DHT_EQ_INT(dh_track_init_q(&trk, &g->r, &g->m, cmd.q, DT_US), DH_OK);
            DHT_EQ_INT(dh_track_step_q(&trk, &cmd.T, q, &trep), DH_OK);
            st = trep.state;
        } else if (cmd.kind == (uint32_t)DH_MOVE_JOINT) {
            memcpy(q, cmd.q, sizeof q);
        }
        DHT_EQ_INT(dh_queue_advance_q(qu, st, &rep), DH_OK);
        if (stopped_at >= 0 && k > stopped_at && k < stopped_at + rest)
            DHT_TRUE_MSG(memcmp(q, qprev, sizeof q) == 0 && rep.stopped, "period %ld: moved while stopped", k);
        if (rep.stopped && stopped_at < 0) stopped_at = k;
        /* the jerk bound holds for joint commands while the warp stays 1 */
        if (cmd.kind == (uint32_t)DH_MOVE_PATH || qu->phase != (uint32_t)DH_QUEUE_RUN || rep.feed != DH_Q30_ONE ||
            rprev != DH_Q30_ONE)
            r1 = 0;
        rprev = rep.feed;
        if (k % dec == 0) {
            at = (at + 1) % RING;
            memcpy(ring[at], q, sizeof ring[0]);   /* the UR5's 6 joints */
            ring_r1[at] = (unsigned char)r1;
            r1 = 1;
            filled++;
        }
        if (k % dec == 0 && cmd.kind != (uint32_t)DH_MOVE_PATH) ring_joints(at, filled, dec, wa, wj, N, NJ, v, a, j);
        if (rep.done) {
            done++;
            if (done == 1) DHT_TRUE(memcmp(q, ib, 6u * sizeof q[0]) == 0);
        }
    }
    DHT_EQ_INT(done, 3);
    DHT_TRUE(memcmp(q, ia, 6u * sizeof q[0]) == 0);
    stats[0] += k;
    stats[1] += stopped_at >= 0;
}

static void queue_jerk_stop_q(void)
{
    dhsm_rig *const g = &the_rig;
    long i, n = DHT_ITER(6), stats[2] = { 0, 0 };
    jerk_windows = 0;
    dhsm_rig_make(g, &dhs_ur5_mm, 120.0, 480.0);
    for (i = 0; i < n; i++) run_queue(g, (long)dht_rand_uniform(50.0, 2500.0), (long)dht_rand_uniform(1.0, 300.0), stats);
    DHT_TRUE(stats[1] > 0 && jerk_windows > 3 * n);
    dht_printf("%ld queues, %ld periods, %ld stopped and resumed, %ld windows of the joints' jerk\n", n, stats[0],
               stats[1], jerk_windows);
}

static void jerk_q_errors(void)
{
    dhsm_rig *const g = &the_rig;
    dh_queue_item_q items[1]; /* on the stack, as run_queue's */
    dh_path_q p, zero;
    dh_qpos via[3];
    int32_t ia[DH_MAX_JOINTS], v[6], a[6], j[6];
    dh_cart_limits_q lim = { 100 << 16, 1000 << 16, 90 << 16, 900 << 16 };
    dh_cart_jerk_q jk = { 5000 << 16, 5000 << 16 };
    dh_profile_q pr, pt, none;
    dh_frame_q A;
    uint32_t e = 7u, et;
    int i;
    dhsm_rig_make(g, &dhs_ur5_mm, 180.0, 720.0);
    DHT_TRUE(path_rand(g, 0, &p, via, ia));
    memset(&none, 0, sizeof none);
    /* NULL: the trapezoid bit for bit */
    DHT_EQ_INT(dh_path_move_jerk_q(&pr, &e, &p, &lim, NULL), DH_OK);
    DHT_EQ_INT(dh_path_move_q(&pt, &et, &p, &lim), DH_OK);
    DHT_TRUE(memcmp(&pr, &pt, sizeof pr) == 0 && e == et);
    /* limits <= 0 */
    jk.jmax = 0;
    DHT_EQ_INT(dh_path_move_jerk_q(&pr, &e, &p, &lim, &jk), DH_ERR_ARG);
    DHT_TRUE(memcmp(&pr, &none, sizeof pr) == 0 && e == 30u);
    jk.jmax = 5000 << 16;
    jk.wjmax = -1;
    DHT_EQ_INT(dh_path_move_jerk_q(&pr, &e, &p, &lim, &jk), DH_ERR_ARG);
    jk.wjmax = 5000 << 16;
    lim.amax = 0;
    DHT_EQ_INT(dh_path_move_jerk_q(&pr, &e, &p, &lim, &jk), DH_ERR_ARG);
    lim.amax = 1000 << 16;
    /* a path that holds none */
    memset(&zero, 0, sizeof zero);
    DHT_EQ_INT(dh_path_move_jerk_q(&pr, &e, &zero, &lim, &jk), DH_ERR_ARG);
    /* a jerk rate of s that rounds to 0: a 2 LSB line at the largest speed, jerk 1 */
    A = p.A;
    A.p[0] += 2;
    DHT_EQ_INT(dh_path_line_q(&zero, &p.A, &A), DH_OK);
    lim.vmax = INT32_MAX;
    jk.jmax = 1;
    DHT_EQ_INT(dh_path_move_jerk_q(&pr, &e, &zero, &lim, &jk), DH_ERR_OVERFLOW);
    DHT_TRUE(memcmp(&pr, &none, sizeof pr) == 0 && e == 30u);
    /* the executor: no move on error, a move otherwise */
    DHT_EQ_INT(dh_move_path_jerk_q(&the_mem.mv, &zero, &lim, &jk), DH_ERR_OVERFLOW);
    DHT_EQ_INT((int)the_mem.mv.kind, (int)DH_MOVE_NONE);
    DHT_EQ_INT(dh_move_target_q(&the_mem.mv, &A), DH_ERR_ARG);
    lim.vmax = 100 << 16;
    jk.jmax = 5000 << 16;
    DHT_EQ_INT(dh_move_path_jerk_q(&the_mem.mv, &p, &lim, &jk), DH_OK);
    DHT_EQ_INT((int)the_mem.mv.kind, (int)DH_MOVE_PATH);
    DHT_EQ_INT((int)the_mem.mv.prof[0].kind, (int)DH_PROFILE_SCURVE);
    jk.wjmax = 0;
    DHT_EQ_INT(dh_move_path_jerk_q(&the_mem.mv, &p, &lim, &jk), DH_ERR_ARG);
    DHT_EQ_INT((int)the_mem.mv.kind, (int)DH_MOVE_NONE);
    DHT_EQ_INT(dh_move_path_jerk_q(&the_mem.mv, &p, &lim, NULL), DH_OK);
    DHT_EQ_INT((int)the_mem.mv.prof[0].kind, (int)DH_PROFILE_TRAP);
    /* the queue */
    DHT_EQ_INT(dh_queue_init_q(&the_mem.qu, items, 1u), DH_OK);
    DHT_EQ_INT(dh_queue_add_path_jerk_q(&the_mem.qu, &p, &lim, &jk), DH_ERR_ARG);
    DHT_EQ_INT(the_mem.qu.count, 0u);
    jk.wjmax = 5000 << 16;
    for (i = 0; i < 6; i++) {
        v[i] = 90 << 16;
        a[i] = 360 << 16;
        j[i] = 0;
    }
    DHT_EQ_INT(dh_queue_add_joint_q(&the_mem.qu, 6u, ia, v, a, j), DH_ERR_ARG);
    j[5] = -5;
    DHT_EQ_INT(dh_queue_add_joint_q(&the_mem.qu, 6u, ia, v, a, j), DH_ERR_ARG);
    DHT_EQ_INT(the_mem.qu.count, 0u);
    DHT_EQ_INT(dh_queue_add_path_jerk_q(&the_mem.qu, &p, &lim, &jk), DH_OK);
    DHT_EQ_INT(the_mem.qu.items[0].prof.kind, (uint32_t)DH_PROFILE_SCURVE);
    DHT_EQ_INT(dh_queue_add_path_jerk_q(&the_mem.qu, &p, &lim, &jk), DH_ERR_LIMIT);
    DHT_EQ_INT(dh_queue_add_path_jerk_q(&the_mem.qu, &p, &lim, NULL), DH_ERR_LIMIT);
    DHT_EQ_INT(the_mem.qu.count, 1u);
}

static const dht_case cases[] = {
    DHT_CASE(jerk_paths_q_vs_double),
    DHT_CASE(executor_stop_q),
    DHT_CASE(queue_jerk_stop_q),
    DHT_CASE(jerk_q_errors),
};
DHT_MAIN(cases)
