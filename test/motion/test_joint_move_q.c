/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_joint_move_q.c - the fixed-point synchronised joint move (motion.h,
 * "Fixed point"): the duration against the slowest joint's analytic
 * minimum computed here in double (the least duration among the feasible
 * regimes of the seven-phase profile, not the planner's case split), every
 * joint within its own limits by finite differences of the output over
 * windows of a few periods, every joint at rest at q1 at the same time,
 * exact ends, errors. Joints in Q16.16 degrees.
 */
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_ref.h"
#include "dhmath/motion.h"

#define NJ 6
#define Q16 65536.0
/* positions within POS_LSB + 2^-25 |d| LSB of the ideal profile (the
 * profile's bound, test_profile_q.c); differences within 1e-3 of the limit
 * plus that rounding over the window (k e / h^n) */
#define POS_LSB 8.0
#define LIM_REL 1e-3

static double draw_log(double lo, double hi)
{
    return exp(dht_rand_uniform(log(lo), log(hi)));
}

/* joint i by finite differences of order k (1 velocity, 2 acceleration, 3
 * jerk) against lim over windows w periods of dt long */
static void check_joint(const dh_profile_q *prof, uint32_t nj, const int32_t *q0, const int32_t *q1, uint32_t i,
                        int k, double lim, double *worst)
{
    const double e = POS_LSB + fabs((double)prof[i].d) * pow(2.0, -25);
    const uint32_t T = prof[0].T, dt = (T / 300u > 0u) ? T / 300u : 1u;
    int32_t q[4][NJ], qd[NJ], qdd[NJ];
    uint32_t t, w;
    double h = 0.0, fd;
    int m;
    for (w = 1u; w < 40u; w++) {
        h = w * dt * 1e-6;
        if ((double)(1 << k) * e / pow(h, k) < 0.1 * LIM_REL * lim) break;
    }
    h = w * dt * 1e-6;
    for (t = 0u; t <= T + 2u * w * dt; t += dt) {
        for (m = 0; m <= k; m++)
            DHT_EQ_INT(dh_joint_move_eval_q(prof, nj, q0, q1, t + (uint32_t)m * w * dt, q[m], qd, qdd), DH_OK);
        fd = (k == 1) ? (double)q[1][i] - q[0][i]
           : (k == 2) ? (double)q[2][i] - 2.0 * q[1][i] + q[0][i]
                      : (double)q[3][i] - 3.0 * q[2][i] + 3.0 * q[1][i] - q[0][i];
        fd = fabs(fd) / pow(h, k);
        if ((fd - (double)(1 << k) * e / pow(h, k)) / lim > *worst) *worst = (fd - (double)(1 << k) * e / pow(h, k)) / lim;
        DHT_TRUE_MSG(fd <= lim * (1.0 + LIM_REL) + (double)(1 << k) * e / pow(h, k),
                     "joint %lu difference %d: %.9g over limit %.9g", (unsigned long)i, k, fd, lim);
        DHT_TRUE(fabs((double)qd[i]) <= prof[i].v && fabs((double)qdd[i]) <= prof[i].a);
    }
}

static void moves(int jerk)
{
    int it, n = DHT_ITER(100);
    double worst = 0.0, over = 0.0;
    for (it = 0; it < n; it++) {
        const uint32_t nj = 1u + dht_rand_u32() % NJ;
        int32_t q0[NJ], q1[NJ], vm[NJ], am[NJ], jm[NJ], q[NJ], qd[NJ], qdd[NJ];
        dh_profile_q prof[NJ];
        double Tref = 0.0, tm;
        uint32_t i;
        for (i = 0u; i < nj; i++) {
            q0[i] = (int32_t)(dht_rand_uniform(-360.0, 360.0) * Q16);
            q1[i] = (dht_rand_u32() % 5u == 0u) ? q0[i] : (int32_t)(dht_rand_uniform(-360.0, 360.0) * Q16);
            vm[i] = (int32_t)(draw_log(10.0, 500.0) * Q16);
            am[i] = (int32_t)(draw_log(50.0, 5000.0) * Q16);
            jm[i] = (int32_t)(draw_log(500.0, 30000.0) * Q16);
            tm = jerk ? dhr_scurve_tmin(fabs((double)q1[i] - q0[i]), vm[i], am[i], jm[i])
                      : dhr_trap_tmin(fabs((double)q1[i] - q0[i]), vm[i], am[i]);
            if (tm > Tref) Tref = tm;
        }
        DHT_EQ_INT(dh_joint_move_q(prof, nj, q0, q1, vm, am, jerk ? jm : NULL), DH_OK);
        Tref *= 1e6;
        for (i = 0u; i < nj; i++) DHT_EQ_INT(prof[i].T, prof[0].T);
        DHT_TRUE_MSG(prof[0].T >= Tref && prof[0].T <= Tref + 1.0 + pow(2.0, -26) * Tref,
                     "T %lu us vs slowest minimum %.6f us", (unsigned long)prof[0].T, Tref);
        if (prof[0].T - Tref > over) over = prof[0].T - Tref;
        /* exact ends, at rest at T */
        DHT_EQ_INT(dh_joint_move_eval_q(prof, nj, q0, q1, 0u, q, qd, qdd), DH_OK);
        DHT_TRUE(memcmp(q, q0, nj * sizeof q[0]) == 0);
        DHT_EQ_INT(dh_joint_move_eval_q(prof, nj, q0, q1, prof[0].T, q, qd, qdd), DH_OK);
        DHT_TRUE(memcmp(q, q1, nj * sizeof q[0]) == 0);
        for (i = 0u; i < nj; i++) DHT_TRUE(qd[i] == 0 && qdd[i] == 0);
        /* limits of one joint per move (the cost of the windows) */
        i = dht_rand_u32() % nj;
        check_joint(prof, nj, q0, q1, i, 1, vm[i], &worst);
        check_joint(prof, nj, q0, q1, i, 2, am[i], &worst);
        if (jerk) check_joint(prof, nj, q0, q1, i, 3, jm[i], &worst);
    }
    dht_printf("joint_move_q (%s): T - slowest minimum <= %.4f us; differences less rounding / limit <= %.6f\n",
               jerk ? "jerk" : "trapezoid", over, worst);
}

static void joint_move_q_trap(void)
{
    moves(0);
}

static void joint_move_q_scurve(void)
{
    moves(1);
}

static void joint_move_q_errors(void)
{
    const int32_t q0[2] = { 0, INT32_MIN + 1 }, q1[2] = { 100 << 16, 1 }, ok1[2] = { 100 << 16, 0 };
    const int32_t vm[2] = { 100 << 16, 100 << 16 }, am[2] = { 1000 << 16, 1000 << 16 }, bad[2] = { 100 << 16, 0 };
    dh_profile_q prof[2], zero[2];
    int32_t q[2] = { 7, 7 }, qd[2], qdd[2];
    memset(zero, 0, sizeof zero);
    DHT_EQ_INT(dh_joint_move_q(prof, 0u, q0, ok1, vm, am, NULL), DH_ERR_ARG);
    /* q1 - q0 beyond int32: no move for every joint */
    DHT_EQ_INT(dh_joint_move_q(prof, 2u, q0, q1, vm, am, NULL), DH_ERR_OVERFLOW);
    DHT_TRUE(memcmp(prof, zero, sizeof prof) == 0);
    DHT_EQ_INT(dh_joint_move_q(prof, 2u, q0, ok1, vm, bad, NULL), DH_ERR_ARG);
    DHT_TRUE(memcmp(prof, zero, sizeof prof) == 0);
    DHT_EQ_INT(dh_joint_move_q(prof, 2u, q0, ok1, vm, am, bad), DH_ERR_ARG);
    DHT_TRUE(memcmp(prof, zero, sizeof prof) == 0);
    /* the no move keeps q0 */
    DHT_EQ_INT(dh_joint_move_eval_q(prof, 2u, q0, ok1, 12345u, q, qd, qdd), DH_OK);
    DHT_TRUE(q[0] == q0[0] && q[1] == q0[1] && qd[0] == 0 && qdd[1] == 0);
    DHT_EQ_INT(dh_joint_move_eval_q(prof, 0u, q0, ok1, 0u, q, qd, qdd), DH_ERR_ARG);
    /* a corrupt profile: outputs untouched */
    memset(prof, 0x5a, sizeof prof);
    q[0] = 7;
    DHT_EQ_INT(dh_joint_move_eval_q(prof, 2u, q0, ok1, 10u, q, qd, qdd), DH_ERR_ARG);
    DHT_EQ_INT(q[0], 7);
    /* INT32_MIN + 1 to 0 (2^31 - 1 LSB, 32768 deg) fits, to 1 does not */
    DHT_EQ_INT(dh_joint_move_q(prof, 2u, q0, ok1, vm, am, NULL), DH_OK);
    DHT_EQ_INT(dh_joint_move_eval_q(prof, 2u, q0, ok1, prof[0].T, q, qd, qdd), DH_OK);
    DHT_TRUE(q[0] == ok1[0] && q[1] == 0);
}

static const dht_case cases[] = {
    DHT_CASE(joint_move_q_trap),
    DHT_CASE(joint_move_q_scurve),
    DHT_CASE(joint_move_q_errors),
};
DHT_MAIN(cases)
