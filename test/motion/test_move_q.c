/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_move_q.c - the fixed-point move executor (motion.h: dh_move_joint_q,
 * dh_move_joint_step_q, dh_move_path_q, dh_move_target_q,
 * dh_move_advance_q) with the fixed tracker (dh_track_step_q) on the UR5
 * and the Puma 560 in mm, 1 kHz, seeded random line, arc and joint moves.
 *
 * Cartesian moves run the firmware loop (target, dh_track_step_q,
 * advance) between two configurations of a region away from the
 * singularities (the UR5's dhs_ur5_safe_q, the Puma near
 * (10, -30, 45, 20, 35, -60)), 4 to 12 degrees apart per joint; an arc's
 * via point is the tool point of the middle configuration moved a few
 * degrees. Each is checked against references computed here in double:
 * the line segment, and the circle through p_A, via, p_B (its centre from
 * the plane of the three points and the two bisector planes, Cramer's
 * rule). Every period: the target on the path within PATH_TOL =
 * 5e-3 mm (the bound, at DH_QPOS_FRAC 16; 328 LSB in another
 * format, with the robots in units of LS mm; the path's own bound is far below it,
 * test_path_q.c); at every OK period the tool (double reference FK of the
 * output) within the tracker's pos_tol plus the fixed FK's 4 n LSB of the
 * target, and within PATH_TOL of the path; the target's step within
 * vmax dt and its rotation within wmax dt (plus noise); held reported
 * exactly for the not-OK periods, the clock advanced by at most dt, the
 * feed override in [0, 1]. Over windows of w periods (ring of target
 * positions, one every DEC periods) the target's speed within vmax and its total acceleration
 * within amax times 1 + 1e-3 plus the noise terms 2 N / (w dt) and
 * 4 N / (w dt)^2, N the target's position noise (the path's bound, the
 * profile's 4 + 2^-27 2^e LSB of its distance 2^e, the clock's 1 us at
 * vmax, 1 LSB), w the least window with the noise at most 2.5e-4 of the
 * limit; over windows of OK periods the tool's speed likewise with the
 * tracker's tolerance in N. done only with the clock at the duration,
 * within 10 times the duration plus 5 s, and then the tool at B within
 * the tracker's tolerances.
 *
 * Joint moves from a configuration to another: every step within
 * vmax (1 - 2^-10) dt + 2 e and every change of step within
 * amax (1 - 2^-10) dt^2 + 4 e, e = 4 + 2^-27 |q1 - q0| (motion.h), done
 * only at the end with q == q1 exactly.
 *
 * A Puma 560 line faster than its wrist can follow (joint rates 150 deg/s,
 * the line of test_move.c in mm): not-OK periods occur and are reported
 * held, the target never jumps, and the move completes with the tool at B.
 *
 * Every status of the executor's functions for bad inputs, with the
 * outputs untouched.
 */
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_robots.h"
#include "support_motion_q.h"
#include "dhmath/motion.h"
#include "dhmath/track.h"
#include "dhmath/frame.h"

#define DT_US 1000u
#define DT 1e-3
#define QPOS DHSM_QPOS
#define Q16 DHSM_Q16
#define PI_D 3.14159265358979323846
#define LS DHSM_LS
/* length unit: the 5e-3 mm at DH_QPOS_FRAC 16, 328 LSB (the
 * tracker's default pos_tol, the closed form's bound, is 328 LSB in every
 * format), so 2^(16 - DH_QPOS_FRAC) times that in another format */
#define PATH_TOL (5e-3 * ldexp(1.0, 16 - DH_QPOS_FRAC))
#define REL_FD 1e-3
#define NOISE_FRAC 2.5e-4
#define DEC 6      /* one position kept every DEC periods (the micro:bit's RAM) */
#define RING 35    /* positions kept: the longest window (2 w for an acceleration) plus one, in DEC periods */
#define ROT_NOISE 3e-6  /* rad: the rotation of two targets (dh_pose_interp_q's 1.5e-6 each) */

/* one robot, one tracker, one move (the M0 target has 16 KB of RAM) */
static dhsm_rig the_rig;
static dh_move_q the_mv;
static int32_t ring[RING][3];   /* target positions, one every DEC periods */
static int32_t ring_tool[RING][3];  /* tool positions (LSB, rounded) of OK periods, one every DEC periods */

typedef struct {
    long periods, notok, done_at;
    int done;
} run_stats;

/* The firmware loop of a path move (the file's comment), every check made */
static void run_path(dhsm_rig *g, dh_track_q *t, dh_move_q *mv, const dhsm_ref *rp, const dh_cart_limits_q *lim,
                     run_stats *rs, const char *what)
{
    const double V = lim->vmax / QPOS, Ac = lim->amax / QPOS, W = lim->wmax / Q16 * PI_D / 180.0;
    const double pbound = (rp->arc ? 4.0 + ldexp(rp->R * QPOS, -26) : 0.87) / QPOS;   /* line: 0.5 LSB per component */
    const double N = pbound + mv->path.length / QPOS * (5.0 * ldexp(1.0, -(int)mv->e) + ldexp(1.0, -27)) + V * 1e-6 +
                     1.0 / QPOS;
    const double Nt = N + t->pos_tol / QPOS + (4.0 * g->r.n + 0.5) / QPOS + 1e-6;   /* the tool kept to 0.5 LSB */
    long wv = (long)ceil(2.0 * N / (NOISE_FRAC * V * DT)), wa = (long)ceil(sqrt(4.0 * N / (NOISE_FRAC * Ac)) / DT);
    long wt = (long)ceil(2.0 * Nt / (NOISE_FRAC * V * DT));
    const long limit = (long)((10.0 * mv->dur * 1e-6 + 5.0) / DT);
    dh_frame_q T, Tp;
    long k, okrun = 0;
    uint32_t clock0;
    int32_t q[DH_MAX_JOINTS];
    /* windows in whole multiples of DEC periods */
    wv = DEC * ((wv + DEC - 1) / DEC + (wv < 1));
    wa = DEC * ((wa + DEC - 1) / DEC + (wa < 1));
    wt = DEC * ((wt + DEC - 1) / DEC + (wt < 1));
    DHT_TRUE_MSG(2 * wa < DEC * RING && wv < DEC * RING && wt < DEC * RING, "%s: windows %ld %ld %ld periods", what, wv, wa, wt);
    memset(rs, 0, sizeof *rs);
    for (k = 0; k < limit && !rs->done; k++) {
        dh_track_report_q tr;
        dh_move_report_q mr;
        double pt[3], pq[3], d;
        dhr_mat4 F;
        int c;
        clock0 = mv->clock;
        DHT_EQ_INT(dh_move_target_q(mv, &T), DH_OK);
        for (c = 0; c < 3; c++) pt[c] = T.p[c] / QPOS;
        d = dhsm_ref_dist(rp, pt);
        DHT_TRUE_MSG(d <= PATH_TOL && d <= pbound + 1e-9, "%s period %ld: target %.3g mm off the path", what, k, d);
        if (k > 0) {
            double pp[3];
            for (c = 0; c < 3; c++) pp[c] = Tp.p[c] / QPOS;
            DHT_TRUE_MSG(dhsm_dist3(pt, pp) <= V * DT * (1 + REL_FD) + 2.0 * N, "%s period %ld: target step %.6g mm", what, k,
                         dhsm_dist3(pt, pp));
            DHT_TRUE_MSG(dhsm_rot_between(&T, &Tp) <= W * DT * (1 + REL_FD) + ROT_NOISE, "%s period %ld: target turn %.6g", what,
                         k, dhsm_rot_between(&T, &Tp));
        }
        Tp = T;
        if (k % DEC == 0) memcpy(ring[(k / DEC) % RING], T.p, sizeof ring[0]);
        DHT_EQ_INT(dh_track_step_q(t, &T, q, &tr), DH_OK);
        if (tr.state == DH_TRACK_OK) {
            dhsm_tool_mm(g, q, pq, &F);
            d = dhsm_dist3(pq, pt);
            DHT_TRUE_MSG(d <= t->pos_tol / QPOS + 4.0 * g->r.n / QPOS + 1e-6, "%s period %ld: tool %.3g mm from the target",
                         what, k, d);
            d = dhsm_ref_dist(rp, pq);
            DHT_TRUE_MSG(d <= PATH_TOL, "%s period %ld: tool %.3g mm off the path", what, k, d);
            if (k % DEC == 0)
                for (c = 0; c < 3; c++) ring_tool[(k / DEC) % RING][c] = (int32_t)floor(pq[c] * QPOS + 0.5);
            okrun++;
            if (okrun > wt && k % DEC == 0) {
                double sp = 0.0, x;
                for (c = 0; c < 3; c++) {
                    x = ((double)ring_tool[(k / DEC) % RING][c] - ring_tool[((k - wt) / DEC) % RING][c]) / QPOS;
                    sp += x * x;
                }
                sp = sqrt(sp) / (wt * DT);
                DHT_TRUE_MSG(sp <= V * (1 + REL_FD) + 2.0 * Nt / (wt * DT), "%s period %ld: tool speed %.6g > %.6g mm/s",
                             what, k, sp, V);
            }
        } else {
            rs->notok++;
            okrun = 0;
        }
        DHT_EQ_INT(dh_move_advance_q(mv, DT_US, tr.state, &mr), DH_OK);
        DHT_EQ_INT(mr.held, tr.state != DH_TRACK_OK);
        DHT_TRUE(mr.clock == mv->clock && mr.clock >= clock0 && mr.clock - clock0 <= DT_US);
        DHT_TRUE(mr.feed >= 0 && mr.feed <= DH_Q30_ONE);
        if (mr.done) {
            DHT_TRUE(mv->clock == mv->dur && tr.state == DH_TRACK_OK);
            rs->done = 1;
            rs->done_at = k;
        }
        /* finite differences of the target over windows ending here */
        if (k >= 2 * wa && k % DEC == 0) {
            const int32_t *a0 = ring[((k - 2 * wa) / DEC) % RING], *a1 = ring[((k - wa) / DEC) % RING];
            const int32_t *a2 = ring[(k / DEC) % RING];
            double acc = 0.0, x;
            for (c = 0; c < 3; c++) {
                x = ((double)a2[c] - 2.0 * a1[c] + a0[c]) / QPOS;
                acc += x * x;
            }
            acc = sqrt(acc) / ((wa * DT) * (wa * DT));
            DHT_TRUE_MSG(acc <= Ac * (1 + REL_FD) + 4.0 * N / ((wa * DT) * (wa * DT)),
                         "%s period %ld: acceleration %.6g > %.6g mm/s^2", what, k, acc, Ac);
        }
        if (k >= wv && k % DEC == 0) {
            const int32_t *a0 = ring[((k - wv) / DEC) % RING], *a1 = ring[(k / DEC) % RING];
            double sp = 0.0, x;
            for (c = 0; c < 3; c++) {
                x = ((double)a1[c] - a0[c]) / QPOS;
                sp += x * x;
            }
            sp = sqrt(sp) / (wv * DT);
            DHT_TRUE_MSG(sp <= V * (1 + REL_FD) + 2.0 * N / (wv * DT), "%s period %ld: speed %.6g > %.6g mm/s", what, k, sp, V);
        }
    }
    rs->periods = k;
    DHT_TRUE_MSG(rs->done, "%s: not done after %ld periods (duration %lu us, %ld not OK)", what, k,
                 (unsigned long)mv->dur, rs->notok);
    {
        dhr_mat4 F;
        double pq[3], pb[3];
        int c;
        dhsm_tool_mm(g, q, pq, &F);
        for (c = 0; c < 3; c++) pb[c] = mv->path.B.p[c] / QPOS;
        DHT_TRUE_MSG(dhsm_dist3(pq, pb) <= t->pos_tol / QPOS + 4.0 * g->r.n / QPOS + 1e-6, "%s: end %.3g mm from B", what,
                     dhsm_dist3(pq, pb));
    }
}

static const dhs_robot *const robots[] = { &dhs_ur5_mm, &dhs_puma560_mm };

static const dh_cart_limits_q LIM = { 250 << 16, 2000 << 16, 45 << 16, 360 << 16 };

static void cartesian_moves_q(void)
{
    dh_track_q trk; /* on the stack: the micro:bit's .data + .bss are full */
    size_t ri;
    for (ri = 0; ri < sizeof robots / sizeof robots[0]; ri++) {
        dhsm_rig *const g = &the_rig;
        long mvn, n = DHT_ITER(6), notok = 0, periods = 0;
        dhsm_rig_make(g, robots[ri], 180.0, 720.0);
        for (mvn = 0; mvn < n; mvn++) {
            double qa[DH_MAX_JOINTS], qb[DH_MAX_JOINTS], qm[DH_MAX_JOINTS];
            int32_t ia[DH_MAX_JOINTS], ib[DH_MAX_JOINTS], im[DH_MAX_JOINTS];
            dh_frame_q A, B, Mf;
            dh_qpos via[3];
            dh_path_q p;
            dhsm_ref rp;
            run_stats rs;
            const int arc = (mvn & 1) != 0;
            int tries = 0, ok = 0, i;
            while (!ok && tries++ < 50) {
                dhsm_region_q(g, qa);
                for (i = 0; i < 6; i++) {
                    const double dlt = dht_rand_uniform(4.0, 12.0) * (dht_rand_uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0);
                    qb[i] = qa[i] + dlt;
                    qm[i] = 0.5 * (qa[i] + qb[i]) + dht_rand_uniform(-4.0, 4.0);
                }
                dhs_q_from_double(&g->r, qa, ia);
                dhs_q_from_double(&g->r, qb, ib);
                dhs_q_from_double(&g->r, qm, im);
                dhsm_target_of(g, ia, &A);
                dhsm_target_of(g, ib, &B);
                dhsm_target_of(g, im, &Mf);
                memcpy(via, Mf.p, sizeof via);
                if (arc) {
                    if (dh_path_arc_q(&p, &A, via, &B) != DH_OK) continue;
                } else {
                    DHT_EQ_INT(dh_path_line_q(&p, &A, &B), DH_OK);
                }
                ok = dhsm_path_reachable(g, &p, ia);
            }
            DHT_TRUE(ok);
            dhsm_ref_make(&rp, &p, arc ? via : NULL);
            DHT_EQ_INT(dh_move_path_q(&the_mv, &p, &LIM), DH_OK);
            DHT_EQ_INT(dh_track_init_q(&trk, &g->r, &g->m, ia, DT_US), DH_OK);
            run_path(g, &trk, &the_mv, &rp, &LIM, &rs, arc ? "arc" : "line");
            notok += rs.notok;
            periods += rs.periods;
        }
        dht_printf("%s: %ld line and arc moves, %ld periods, %ld not OK\n", g->d->name, n, periods, notok);
    }
}

static void joint_moves_q(void)
{
    dhsm_rig *const g = &the_rig;
    long mvn, n = DHT_ITER(8);
    dhsm_rig_make(g, &dhs_ur5_mm, 180.0, 720.0);
    for (mvn = 0; mvn < n; mvn++) {
        double qa[DH_MAX_JOINTS], qb[DH_MAX_JOINTS];
        int32_t ia[DH_MAX_JOINTS], ib[DH_MAX_JOINTS], q[DH_MAX_JOINTS], qp[DH_MAX_JOINTS], sp[DH_MAX_JOINTS];
        int32_t vmax[DH_MAX_JOINTS], amax[DH_MAX_JOINTS];
        dh_move_report_q rep;
        dh_move_q *const mv = &the_mv;
        uint32_t i;
        long k;
        int have_sp = 0;
        dhs_ur5_safe_q(5.0, qa);
        dhs_ur5_safe_q(5.0, qb);
        dhs_q_from_double(&g->r, qa, ia);
        dhs_q_from_double(&g->r, qb, ib);
        for (i = 0; i < 6u; i++) {
            vmax[i] = (int32_t)(dht_rand_uniform(30.0, 180.0) * Q16);
            amax[i] = (int32_t)(dht_rand_uniform(100.0, 720.0) * Q16);
        }
        DHT_EQ_INT(dh_move_joint_q(mv, 6u, ia, ib, vmax, amax, (mvn & 1) ? vmax : NULL), DH_OK);
        memcpy(qp, ia, 6u * sizeof qp[0]);
        for (k = 0; k < 100000; k++) {
            DHT_EQ_INT(dh_move_joint_step_q(mv, DT_US, q, &rep), DH_OK);
            for (i = 0; i < 6u; i++) {
                const double e = 4.0 + ldexp(fabs((double)ib[i] - ia[i]), -27);
                const double s = (double)q[i] - qp[i];
                const double v = vmax[i] * (1.0 - ldexp(1.0, -10)) * DT, a = amax[i] * (1.0 - ldexp(1.0, -10)) * DT * DT;
                DHT_TRUE_MSG(fabs(s) <= v + 2.0 * e, "joint move %ld period %ld: joint %u step %.1f > %.1f", mvn, k,
                             (unsigned)i, s, v);
                if (have_sp)
                    DHT_TRUE_MSG(fabs(s - sp[i]) <= a + 4.0 * e, "joint move %ld period %ld: joint %u step change %.1f > %.1f",
                                 mvn, k, (unsigned)i, s - sp[i], a);
                sp[i] = (int32_t)s;
                qp[i] = q[i];
            }
            have_sp = 1;
            DHT_EQ_INT(rep.done, mv->clock == mv->dur);
            if (rep.done) break;
        }
        DHT_TRUE(rep.done);
        DHT_TRUE(memcmp(q, ib, 6u * sizeof q[0]) == 0);
        DHT_EQ_INT(dh_move_joint_step_q(mv, DT_US, q, &rep), DH_OK);
        DHT_TRUE(rep.done && memcmp(q, ib, 6u * sizeof q[0]) == 0);
    }
}

/* The Puma line its wrist cannot follow (the file's comment) */
static void lagging_puma_q(void)
{
    static const double QP[6] = { 10.0, -30.0, 45.0, 20.0, 35.0, -60.0 };
    static const dh_cart_limits_q PLIM = { 300 << 16, 1500 << 16, 90 << 16, 360 << 16 };
    dhsm_rig *const g = &the_rig;
    dh_track_q trk; /* on the stack: the micro:bit's .data + .bss are full */
    int it, n = (int)DHT_ITER(2), k;
    dhsm_rig_make(g, &dhs_puma560_mm, 150.0, 600.0);
    for (it = 0; it < n; it++) {
        double qa[DH_MAX_JOINTS];
        int32_t ia[DH_MAX_JOINTS];
        dh_frame_q A, B;
        dh_path_q p;
        dhsm_ref rp;
        run_stats rs;
        for (k = 0; k < 6; k++) qa[k] = QP[k] + ((it == 0) ? 0.0 : dht_rand_uniform(-2.0, 2.0));
        dhs_q_from_double(&g->r, qa, ia);
        dhsm_target_of(g, ia, &A);
        dh_frame_identity_q(&B);
        B.p[0] = (int32_t)((500.0 + ((it == 0) ? 0.0 : dht_rand_uniform(-10.0, 10.0))) * LS * QPOS);
        B.p[1] = (int32_t)((-30.0 + ((it == 0) ? 0.0 : dht_rand_uniform(-10.0, 10.0))) * LS * QPOS);
        B.p[2] = (int32_t)((1000.0 + ((it == 0) ? 0.0 : dht_rand_uniform(-10.0, 10.0))) * LS * QPOS);
        DHT_EQ_INT(dh_path_line_q(&p, &A, &B), DH_OK);
        dhsm_ref_make(&rp, &p, NULL);
        DHT_EQ_INT(dh_move_path_q(&the_mv, &p, &PLIM), DH_OK);
        DHT_EQ_INT(dh_track_init_q(&trk, &g->r, &g->m, ia, DT_US), DH_OK);
        run_path(g, &trk, &the_mv, &rp, &PLIM, &rs, "puma line");
        DHT_TRUE_MSG(rs.notok > 0, "the Puma line: no lagging period");
        dht_reach_max("move_q.puma_notok", (double)rs.notok);
        dht_printf("Puma line: %ld periods, %ld not OK (held), duration %lu us\n", rs.periods, rs.notok,
                   (unsigned long)the_mv.dur);
    }
}

static void move_q_errors(void)
{
    dh_move_q *const mv = &the_mv;
    dh_move_report_q rep, keep_rep;
    dh_frame_q T, keepT, A, B;
    dh_path_q p;
    int32_t q0[6] = { 0 }, q1[6] = { 65536, 0, 0, 0, 0, 0 }, v[6], a[6], q[6], keep_q[6];
    dh_cart_limits_q lim = LIM;
    int k;
    for (k = 0; k < 6; k++) {
        v[k] = 90 << 16;
        a[k] = 360 << 16;
    }
    memset(&keepT, 0x5a, sizeof keepT);
    memset(&keep_rep, 0x5a, sizeof keep_rep);
    memset(keep_q, 0x5a, sizeof keep_q);
    T = keepT;
    rep = keep_rep;
    memcpy(q, keep_q, sizeof q);
    /* no move */
    memset(mv, 0, sizeof *mv);
    DHT_EQ_INT(dh_move_target_q(mv, &T), DH_ERR_ARG);
    DHT_EQ_INT(dh_move_advance_q(mv, DT_US, DH_TRACK_OK, &rep), DH_ERR_ARG);
    DHT_EQ_INT(dh_move_joint_step_q(mv, DT_US, q, &rep), DH_ERR_ARG);
    /* bad joint moves leave no move */
    DHT_EQ_INT(dh_move_joint_q(mv, 0u, q0, q1, v, a, NULL), DH_ERR_ARG);
    DHT_EQ_INT(dh_move_joint_q(mv, DH_MAX_JOINTS + 1u, q0, q1, v, a, NULL), DH_ERR_ARG);
    v[2] = 0;
    DHT_EQ_INT(dh_move_joint_q(mv, 6u, q0, q1, v, a, NULL), DH_ERR_ARG);
    DHT_EQ_INT(mv->kind, (uint32_t)DH_MOVE_NONE);
    v[2] = 90 << 16;
    DHT_EQ_INT(dh_move_joint_q(mv, 6u, q0, q1, v, a, NULL), DH_OK);
    DHT_EQ_INT(dh_move_joint_step_q(mv, 0u, q, &rep), DH_ERR_ARG);
    DHT_EQ_INT(dh_move_joint_step_q(mv, 1000001u, q, &rep), DH_ERR_ARG);
    DHT_EQ_INT(dh_move_target_q(mv, &T), DH_ERR_ARG);
    DHT_EQ_INT(dh_move_advance_q(mv, DT_US, DH_TRACK_OK, &rep), DH_ERR_ARG);
    /* path moves */
    dh_frame_identity_q(&A);
    B = A;
    B.p[0] = 100 << 16;
    DHT_EQ_INT(dh_path_line_q(&p, &A, &B), DH_OK);
    lim.amax = -1;
    DHT_EQ_INT(dh_move_path_q(mv, &p, &lim), DH_ERR_ARG);
    DHT_EQ_INT(mv->kind, (uint32_t)DH_MOVE_NONE);
    DHT_EQ_INT(dh_move_path_q(mv, &p, &LIM), DH_OK);
    DHT_EQ_INT(dh_move_joint_step_q(mv, DT_US, q, &rep), DH_ERR_ARG);
    DHT_EQ_INT(dh_move_advance_q(mv, 0u, DH_TRACK_OK, &rep), DH_ERR_ARG);
    DHT_EQ_INT(dh_move_advance_q(mv, DT_US, (dh_track_state)77, &rep), DH_ERR_ARG);
    DHT_TRUE(memcmp(&T, &keepT, sizeof T) == 0);
    DHT_TRUE(memcmp(&rep, &keep_rep, sizeof rep) == 0);
    DHT_TRUE(memcmp(q, keep_q, sizeof q) == 0);
    /* the first target is A; a lagging tracker holds the clock at 0 */
    DHT_EQ_INT(dh_move_target_q(mv, &T), DH_OK);
    DHT_TRUE(memcmp(&T, &A, sizeof T) == 0);
    DHT_EQ_INT(dh_move_advance_q(mv, DT_US, DH_TRACK_LAGGING, &rep), DH_OK);
    DHT_TRUE(rep.held == 1 && rep.done == 0 && rep.clock == 0u && rep.feed == 0);
    DHT_EQ_INT(dh_move_advance_q(mv, DT_US, DH_TRACK_OK, &rep), DH_OK);
    DHT_TRUE(rep.held == 0 && rep.feed == DH_Q30_ONE);
    /* a path built in place (p == &mv->path) */
    DHT_EQ_INT(dh_path_line_q(&mv->path, &A, &B), DH_OK);
    DHT_EQ_INT(dh_move_path_q(mv, &mv->path, &LIM), DH_OK);
    DHT_TRUE(mv->dur > 0u && memcmp(&mv->path, &p, sizeof p) == 0);
    /* a corrupted copy of the path is no move */
    mv->path.qa.w = 0;
    mv->path.qa.x = 0;
    mv->path.qa.y = 0;
    mv->path.qa.z = 0;
    T = keepT;
    DHT_EQ_INT(dh_move_target_q(mv, &T), DH_ERR_ARG);
    DHT_TRUE(memcmp(&T, &keepT, sizeof T) == 0);
}

static const dht_case cases[] = {
    DHT_CASE(cartesian_moves_q),
    DHT_CASE(joint_moves_q),
    DHT_CASE(lagging_puma_q),
    DHT_CASE(move_q_errors),
};
DHT_MAIN(cases)
