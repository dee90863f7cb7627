/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bench_ref.c - robot DH tables and the plain double-precision reference
 * forward kinematics used by the benchmark (as a timed peer) and by the
 * accuracy data generator (as the reference).
 *
 * The tables are examples/robots/puma560.dh, ur5.dh and kuka_kr5.dh (sources in their
 * headers), read at build time by tools/gen_robots.py.
 */
#include "bench_common.h"
#include "dh_robots.h"

#include <math.h>

#define BENCH_PI 3.14159265358979323846

#define BENCH_JOINT(type, a, d, alpha, theta, qmin, qmax) { a, d, alpha, theta, qmin, qmax },
const bench_dh_robot bench_puma560 = { "Puma 560", DHR_PUMA560_N, { DHR_PUMA560_JOINTS(BENCH_JOINT) } };
const bench_dh_robot bench_ur5 = { "UR5", DHR_UR5_N, { DHR_UR5_JOINTS(BENCH_JOINT) } };
const bench_dh_robot bench_kr5 = { "KUKA KR5", DHR_KUKA_KR5_N, { DHR_KUKA_KR5_JOINTS(BENCH_JOINT) } };

/* T <- T * A for 4x4 column-major double matrices (plain triple loop). */
static void mul4(double T[4][4], double A[4][4])
{
    double R[4][4];
    int c, r, k;
    for (c = 0; c < 4; c++) {
        for (r = 0; r < 4; r++) {
            double s = 0.0;
            for (k = 0; k < 4; k++) s += T[k][r] * A[c][k];
            R[c][r] = s;
        }
    }
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) T[c][r] = R[c][r];
}

/* Standard DH link matrix Rz(theta) Tz(d) Tx(a) Rx(alpha), column-major. */
static void link_std(double A[4][4], double a, double d, double alpha_deg, double theta_deg)
{
    double th = theta_deg * (BENCH_PI / 180.0), al = alpha_deg * (BENCH_PI / 180.0);
    double ct = cos(th), st = sin(th), ca = cos(al), sa = sin(al);
    A[0][0] = ct;       A[0][1] = st;       A[0][2] = 0.0; A[0][3] = 0.0;
    A[1][0] = -st * ca; A[1][1] = ct * ca;  A[1][2] = sa;  A[1][3] = 0.0;
    A[2][0] = st * sa;  A[2][1] = -ct * sa; A[2][2] = ca;  A[2][3] = 0.0;
    A[3][0] = a * ct;   A[3][1] = a * st;   A[3][2] = d;   A[3][3] = 1.0;
}

void bench_ref_fk_params(unsigned n, const double *a, const double *d, const double *alpha_deg,
                         const double *theta_deg, const double *q, double T[4][4])
{
    unsigned i;
    int c, r;
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) T[c][r] = (c == r) ? 1.0 : 0.0;
    for (i = 0; i < n; i++) {
        double A[4][4];
        link_std(A, a[i], d[i], alpha_deg[i], q[i] + theta_deg[i]);
        mul4(T, A);
    }
}

void bench_ref_fk(const bench_dh_robot *rb, double scale, const double *q, double T[4][4])
{
    unsigned i;
    int c, r;
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) T[c][r] = (c == r) ? 1.0 : 0.0;
    for (i = 0; i < rb->n; i++) {
        const bench_dh_row *j = &rb->j[i];
        double A[4][4];
        link_std(A, j->a * scale, j->d * scale, j->alpha_deg, q[i] + j->theta_deg);
        mul4(T, A);
    }
}

void bench_ref_prepare(const bench_dh_robot *rb, double scale, bench_ref_model *m)
{
    unsigned i;
    m->n = rb->n;
    for (i = 0; i < rb->n; i++) {
        double al = rb->j[i].alpha_deg * (BENCH_PI / 180.0);
        m->a[i] = rb->j[i].a * scale;
        m->d[i] = rb->j[i].d * scale;
        m->sa[i] = sin(al);
        m->ca[i] = cos(al);
        m->theta_deg[i] = rb->j[i].theta_deg;
    }
}

void bench_ref_fk_model(const bench_ref_model *m, const double *q_deg, double T[4][4])
{
    unsigned i;
    int c, r;
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) T[c][r] = (c == r) ? 1.0 : 0.0;
    for (i = 0; i < m->n; i++) {
        double th = (q_deg[i] + m->theta_deg[i]) * (BENCH_PI / 180.0);
        double ct = cos(th), st = sin(th), ca = m->ca[i], sa = m->sa[i], A[4][4];
        A[0][0] = ct;       A[0][1] = st;       A[0][2] = 0.0; A[0][3] = 0.0;
        A[1][0] = -st * ca; A[1][1] = ct * ca;  A[1][2] = sa;  A[1][3] = 0.0;
        A[2][0] = st * sa;  A[2][1] = -ct * sa; A[2][2] = ca;  A[2][3] = 0.0;
        A[3][0] = m->a[i] * ct; A[3][1] = m->a[i] * st; A[3][2] = m->d[i]; A[3][3] = 1.0;
        mul4(T, A);
    }
}

double bench_rand(uint64_t *s, double lo, double hi)
{
    uint64_t x = *s;
    x ^= x >> 12;
    x ^= x << 25;
    x ^= x >> 27;
    *s = x;
    x *= 0x2545F4914F6CDD1DULL;
    return lo + (hi - lo) * ((double)(x >> 11) * (1.0 / 9007199254740992.0));
}
