/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_joint_move.c - synchronised point-to-point joint moves (motion.h):
 * the duration against the slowest joint's analytic minimum computed here
 * in double, every joint within its own limits by finite differences of the
 * sampled float output, every joint at rest at q1 at the same time, exact
 * ends. Finite-difference margins as in test_profile.c: windows of T / 500,
 * the rounding of the outputs over a window at most 2.4e-4 of a limit, the
 * position's rounding now that of max(|q0|, |q1|) (drawn within 4 |d| of
 * the move, below: 9.6e-4 of vmax; the margin is 2e-3).
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_ref.h"
#include "dhmath/motion.h"

#define NJ 8
#define N_WIN 500
#define REL_T 2e-6
#define REL_FD 2e-3

static double rlog(double lo, double hi) { return pow(10.0, dht_rand_uniform(lo, hi)); }

static void moves(int jerk)
{
    int it, n = DHT_ITER(300);
    for (it = 0; it < n; it++) {
        uint32_t nj = 1u + dht_rand_u32() % NJ, i;
        float q0[NJ], q1[NJ], vm[NJ], am[NJ], jm[NJ], q[NJ], qd[NJ], qdd[NJ], pq[NJ], pqd[NJ], pqdd[NJ];
        dh_profile_f32 prof[NJ];
        double Tref = 0.0, h, wv = 0.0, wa = 0.0, wj = 0.0;
        float T;
        int k;
        for (i = 0; i < nj; i++) {
            double d = rlog(-2.0, 2.0) * ((dht_rand_u32() & 1u) ? -1.0 : 1.0), ti;
            if (dht_rand_u32() % 8u == 0u) d = 0.0;   /* a joint that stays */
            q0[i] = (float)dht_rand_uniform(-2.0 * fabs(d), 2.0 * fabs(d));
            q1[i] = (float)((double)q0[i] + d);
            vm[i] = (float)rlog(-1.0, 1.0);
            am[i] = (float)rlog(-1.0, 2.0);
            jm[i] = (float)rlog(0.0, 3.0);
            ti = jerk ? dhr_scurve_tmin((double)q1[i] - q0[i], vm[i], am[i], jm[i])
                      : dhr_trap_tmin((double)q1[i] - q0[i], vm[i], am[i]);
            if (ti > Tref) Tref = ti;
        }
        DHT_EQ_INT(dh_joint_move_f32(prof, nj, q0, q1, vm, am, jerk ? jm : NULL), DH_OK);
        T = prof[0].T;
        DHT_TRUE_MSG(fabs(T - Tref) <= REL_T * Tref, "T %.9g vs the slowest joint's minimum %.9g", (double)T, Tref);
        for (i = 0; i < nj; i++) {
            DHT_EQ_F32_BITS(prof[i].T, T);
            DHT_TRUE(prof[i].v <= vm[i] && prof[i].a <= am[i]);
            if (jerk) DHT_TRUE(prof[i].j <= jm[i]);
        }
        if (!(T > 0.0f)) continue;
        /* exact ends */
        DHT_EQ_INT(dh_joint_move_eval_f32(prof, nj, q0, q1, 0.0f, pq, pqd, pqdd), DH_OK);
        DHT_TRUE(memcmp(pq, q0, nj * sizeof(float)) == 0);
        DHT_EQ_INT(dh_joint_move_eval_f32(prof, nj, q0, q1, T, q, qd, qdd), DH_OK);
        DHT_TRUE(memcmp(q, q1, nj * sizeof(float)) == 0);
        for (i = 0; i < nj; i++) DHT_TRUE(qd[i] == 0.0f && qdd[i] == 0.0f);
        /* every joint moves until T (none arrives early): at T (1 - 1e-3)
         * each moving joint still has speed */
        DHT_EQ_INT(dh_joint_move_eval_f32(prof, nj, q0, q1, T * 0.999f, q, qd, qdd), DH_OK);
        for (i = 0; i < nj; i++) DHT_TRUE(q1[i] == q0[i] || qd[i] != 0.0f);
        /* limits by finite differences */
        h = (double)T / N_WIN;
        for (k = 1; k <= N_WIN; k++) {
            float t = (k == N_WIN) ? T : (float)(h * k);
            DHT_EQ_INT(dh_joint_move_eval_f32(prof, nj, q0, q1, t, q, qd, qdd), DH_OK);
            for (i = 0; i < nj; i++) {
                double fv = fabs((double)q[i] - pq[i]) / h / vm[i], fa = fabs((double)qd[i] - pqd[i]) / h / am[i];
                double fj = fabs((double)qdd[i] - pqdd[i]) / h / jm[i];
                if (fv > wv) wv = fv;
                if (fa > wa) wa = fa;
                if (fj > wj) wj = fj;
                DHT_TRUE(fabs(qd[i]) <= vm[i] && fabs(qdd[i]) <= am[i]);
            }
            memcpy(pq, q, sizeof q);
            memcpy(pqd, qd, sizeof qd);
            memcpy(pqdd, qdd, sizeof qdd);
        }
        DHT_TRUE_MSG(wv <= 1.0 + REL_FD, "velocity by finite differences %.9g x vmax", wv);
        DHT_TRUE_MSG(wa <= 1.0 + REL_FD, "acceleration by finite differences %.9g x amax", wa);
        if (jerk) DHT_TRUE_MSG(wj <= 1.0 + REL_FD, "jerk by finite differences %.9g x jmax", wj);
    }
}

static void scurve_moves(void) { moves(1); }
static void trap_moves(void) { moves(0); }

/* the slowest joint keeps its time-optimal profile */
static void slowest_keeps_its_profile(void)
{
    const float q0[3] = { 0.0f, 10.0f, -5.0f }, q1[3] = { 1.0f, 9.0f, 20.0f };
    const float vm[3] = { 1.0f, 2.0f, 3.0f }, am[3] = { 4.0f, 5.0f, 6.0f }, jm[3] = { 40.0f, 50.0f, 60.0f };
    dh_profile_f32 prof[3], p;
    DHT_EQ_INT(dh_joint_move_f32(prof, 3u, q0, q1, vm, am, jm), DH_OK);
    DHT_EQ_INT(dh_profile_scurve_f32(&p, 25.0f, 3.0f, 6.0f, 60.0f), DH_OK);
    DHT_TRUE(memcmp(&p, &prof[2], sizeof p) == 0);
    DHT_EQ_INT(dh_joint_move_f32(prof, 3u, q0, q1, vm, am, NULL), DH_OK);
    DHT_EQ_INT(dh_profile_trap_f32(&p, 25.0f, 3.0f, 6.0f), DH_OK);
    DHT_TRUE(memcmp(&p, &prof[2], sizeof p) == 0);
}

static const dht_case cases[] = {
    DHT_CASE(scurve_moves),
    DHT_CASE(trap_moves),
    DHT_CASE(slowest_keeps_its_profile),
};
DHT_MAIN(cases)
