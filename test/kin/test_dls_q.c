/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_dls_q.c - fixed-point singularity measures and damped-least-squares
 * step (dh_manipulability_q, dh_dls_step_q) against double precision.
 *
 * The references read the SAME integer Jacobian (dh_jacobian_q at random
 * configurations of the Puma 560, UR5 and Panda in mm) in its documented
 * units (length unit, rad) and compute in double: the exact damped step
 * J^T (J J^T + lambda^2 I)^-1 e by Cholesky, the determinant of J J^T and
 * its eigenvalues (cyclic Jacobi), so that every difference is the fixed
 * path's own rounding. The bounds are derived below from the documented
 * method (dh_dls_q.c), not fitted.
 */
#include "dht.h"
#include "support_robots.h"
#include "dhmath/kin.h"
#include "dhmath/frame.h"

#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846
#define Q30 1073741824.0
#define Q29 536870912.0
#define QPOS ((double)((int32_t)1 << DH_QPOS_FRAC))
#define M6 6

/* one scratch for every call (the suites run one case at a time) */
static dh_dls_work_q wk;

/* ---- double helpers --------------------------------------------------- */

/* J in (length unit, rad): revolute linear rows dh_qpos, the rest Q2.30. */
static void jac_num(const dh_robot *r, const int32_t *J, double *Jn)
{
    const unsigned n = r->n;
    unsigned k, i;
    for (k = 0; k < 6; k++)
        for (i = 0; i < n; i++)
            Jn[k * n + i] = J[k * n + i] / ((k < 3 && r->joint[i].type == DH_JOINT_REVOLUTE) ? QPOS : Q30);
}

/* G = J J^T (+ lam2 I), 6 x 6 (cols == 0) or J^T J, n x n (cols). */
static unsigned gram(const double *Jn, unsigned n, int cols, double lam2, double *G)
{
    const unsigned m = cols ? n : 6;
    unsigned a, b, t;
    for (a = 0; a < m; a++)
        for (b = 0; b < m; b++) {
            double s = (a == b) ? lam2 : 0.0;
            if (cols)
                for (t = 0; t < 6; t++) s += Jn[t * n + a] * Jn[t * n + b];
            else
                for (t = 0; t < n; t++) s += Jn[a * n + t] * Jn[b * n + t];
            G[a * m + b] = s;
        }
    return m;
}

/* Cholesky G = L L^T (m x m); returns 0 when not positive definite. */
static int chol(const double *G, unsigned m, double *L)
{
    unsigned i, j, k;
    memset(L, 0, sizeof(double) * m * m);
    for (j = 0; j < m; j++) {
        double d = G[j * m + j];
        for (k = 0; k < j; k++) d -= L[j * m + k] * L[j * m + k];
        if (!(d > 0)) return 0;
        L[j * m + j] = sqrt(d);
        for (i = j + 1; i < m; i++) {
            double s = G[i * m + j];
            for (k = 0; k < j; k++) s -= L[i * m + k] * L[j * m + k];
            L[i * m + j] = s / L[j * m + j];
        }
    }
    return 1;
}

/* x = (L L^T)^-1 b. */
static void chol_solve(const double *L, unsigned m, const double *b, double *x)
{
    unsigned i, k;
    for (i = 0; i < m; i++) {
        double s = b[i];
        for (k = 0; k < i; k++) s -= L[i * m + k] * x[k];
        x[i] = s / L[i * m + i];
    }
    for (i = m; i-- > 0;) {
        double s = x[i];
        for (k = i + 1; k < m; k++) s -= L[k * m + i] * x[k];
        x[i] = s / L[i * m + i];
    }
}

/* Smallest eigenvalue of the symmetric m x m matrix G (cyclic Jacobi). */
static double eig_min(const double *G, unsigned m)
{
    double A[64];
    unsigned p, q, k, sweep;
    double mn;
    memcpy(A, G, sizeof(double) * m * m);
    for (sweep = 0; sweep < 60; sweep++) {
        double off = 0;
        for (p = 0; p < m; p++)
            for (q = p + 1; q < m; q++) off += A[p * m + q] * A[p * m + q];
        if (off == 0) break;
        for (p = 0; p < m; p++)
            for (q = p + 1; q < m; q++) {
                const double apq = A[p * m + q];
                double th, t, c, s;
                if (apq == 0) continue;
                th = (A[q * m + q] - A[p * m + p]) / (2 * apq);
                t = (th >= 0 ? 1.0 : -1.0) / (fabs(th) + sqrt(th * th + 1));
                c = 1 / sqrt(t * t + 1);
                s = t * c;
                for (k = 0; k < m; k++) {
                    const double akp = A[k * m + p], akq = A[k * m + q];
                    A[k * m + p] = c * akp - s * akq;
                    A[k * m + q] = s * akp + c * akq;
                }
                for (k = 0; k < m; k++) {
                    const double apk = A[p * m + k], aqk = A[q * m + k];
                    A[p * m + k] = c * apk - s * aqk;
                    A[q * m + k] = s * apk + c * aqk;
                }
            }
    }
    mn = A[0];
    for (p = 1; p < m; p++)
        if (A[p * m + p] < mn) mn = A[p * m + p];
    return mn;
}

/* The largest g <= 28 with mx 2^(g - F) below 2^28. */
static int fmt1(uint32_t mx)
{
    int g, bl = 0;
    if (mx == 0) return 28;
    while ((mx >> bl) > 1u) bl++;
    g = DH_QPOS_FRAC + 27 - bl;
    return g > 28 ? 28 : g;
}

/* The row formats of the method: linear rows from the largest |linear
 * revolute entry| and lambda (dh_qpos), angular rows from lambda; one
 * format (the linear one) when the Gram matrix is J^T J (cols). */
static void fmt_g(const dh_robot *r, const int32_t *J, int32_t lambda, int cols, int *g)
{
    uint32_t mx = (uint32_t)lambda;
    unsigned k, i;
    for (k = 0; k < 3; k++)
        for (i = 0; i < r->n; i++)
            if (r->joint[i].type == DH_JOINT_REVOLUTE) {
                const int32_t v = J[k * r->n + i];
                const uint32_t a = v < 0 ? 0u - (uint32_t)v : (uint32_t)v;
                if (a > mx) mx = a;
            }
    g[0] = fmt1(mx);
    g[1] = cols ? g[0] : fmt1((uint32_t)lambda);
}

/* Frobenius norm of an r x c matrix. */
static double fro(const double *A, unsigned rr, unsigned c)
{
    double s = 0;
    unsigned k;
    for (k = 0; k < rr * c; k++) s += A[k] * A[k];
    return sqrt(s);
}

/* Random configuration of the fixed robot, Q16.16 degrees / dh_qpos. */
static void rand_q(const dhs_robot *d, const dh_robot *r, int32_t *q)
{
    double qd[DHS_MAX_JOINTS];
    dhs_random_q(d, qd);
    dhs_q_from_double(r, qd, q);
}

/* ---- damped step accuracy ------------------------------------------------
 *
 * Bound, per output component in LSB (derivation; method in dh_dls_q.c).
 * x = G^-1 e, G = J J^T + lambda^2 I, dq = J^T x in (length, rad); Dn =
 * diag(2^c_k) 2^-g the equilibration (A' = Dn^-1 G Dn^-1, diagonal in
 * [1/4, 1)); J_g = B 2^-g the Jacobian in the common format.
 * 1. J rounded to Q(g): dq(J_g) - dq(J) to first order is
 *    M^-1 dJ^T (e - J dq) - M^-1 J^T dJ dq, M = J^T J + lambda^2 I, so
 *    |.| <= |dJ| |e| / lambda^2 + |dJ| |dq| / (2 lambda) (|M^-1| <=
 *    lambda^-2, |M^-1 J^T| <= 1 / (2 lambda), |e - J dq| <= |e|), dJ =
 *    J_g - J computed here (the rounding is the documented one).
 * 2. The factor: the equilibrated entries are rounded once (2^-31); each
 *    L_ij is a Q60 sum rounded to Q30 (2^-31) times the pivot's reciprocal
 *    root (relative error eps_r = 7e-10 + 4 2^-29 of dh_q_rsqrt29 with
 *    three steps, dh_qmath.h) rounded again (2^-31): with the reciprocal
 *    read as the exact 1 / L_jj, L L^T = A' + E, |E_jj| <= 2 eps_r + 2^-29,
 *    |E_jk| <= 3 2^-30 (|L| <= 1 as A'_kk < 1). Then dq changes by
 *    J^T Dn^-1 A'^-1 E Dn x: at most |J^T Dn^-1 A'^-1|_F |E|_F |Dn x|.
 * 3. The substitutions round every z_i, y_i to the unit u of the scaled
 *    right-hand side (<= 1 unit each, L_ii <= 1): L L^T y = b + r with
 *    |r| <= sqrt(6) (1 + sqrt(6)) u, u <= 2^-25 max(|b|_inf, |A'^-1| |b|)
 *    (b = Dn^-1 e, scaled to [2^26, 2^27) units, then down until the
 *    intermediates are below 2^29, the excess estimate at most 2x high),
 *    and the final sum rounds 6 terms by half of u 2^(3 - c_min + g) / 2^g:
 *    dq changes by |J^T Dn^-1 A'^-1| |r| + 4 * 6 u / min Dn.
 * 4. Output: the sum's magnitude is truncated to 31 bits and times 180/pi
 *    in Q6.25 (relative 2^-29 together), then rounded (0.5 LSB).
 * Sum, times 180/pi 2^16 (revolute) or 2^F (prismatic), + 0.5 LSB.
 */
static double dls_bound(const dh_robot *r, const int32_t *J, int32_t lambda, const double *Jn, const double *G,
                        const double *x, const double *e, const double *dqn, double *row)
{
    const unsigned n = r->n;
    int g[2];
    const double lam = lambda / QPOS, eps_r = 7e-10 + 4.0 / Q29;
    double dJ[6 * DHS_MAX_JOINTS], Dn[6], Ai[36], Ap[36], L[36], W[6 * DHS_MAX_JOINTS], b[6], col[6], t[6];
    double dmin = 1e300, ne = 0, ndq = 0, nb = 0, bmax = 0, nDx = 0, nE, nAi, nW, u, rnorm, tot;
    unsigned k, i, j;
    fmt_g(r, J, lambda, 0, g);
    for (k = 0; k < 6; k++)
        for (i = 0; i < n; i++) {
            const int from = (k < 3 && r->joint[i].type == DH_JOINT_REVOLUTE) ? DH_QPOS_FRAC : 30;
            /* round half up of J 2^(g - from), as dh_q_rshr */
            const double v = ldexp((double)J[k * n + i], g[k >= 3] - from);
            dJ[k * n + i] = ldexp(floor(v + 0.5), -g[k >= 3]) - Jn[k * n + i];
        }
    for (k = 0; k < 6; k++) {
        double gk = G[k * 6 + k] * ldexp(1.0, 2 * g[k >= 3]);   /* in Q(2g) units */
        int c = 0;
        while (gk >= ldexp(1.0, 30)) { gk /= 4; c++; }
        while (gk < ldexp(1.0, 28)) { gk *= 4; c--; }
        Dn[k] = ldexp(1.0, c + 15 - g[k >= 3]);
        if (Dn[k] < dmin) dmin = Dn[k];
        ne += e[k] * e[k];
        b[k] = e[k] / Dn[k];
        nb += b[k] * b[k];
        if (fabs(b[k]) > bmax) bmax = fabs(b[k]);
        nDx += (Dn[k] * x[k]) * (Dn[k] * x[k]);
    }
    for (i = 0; i < n; i++) ndq += dqn[i] * dqn[i];
    ne = sqrt(ne);
    ndq = sqrt(ndq);
    nb = sqrt(nb);
    nDx = sqrt(nDx);
    /* A' and its inverse, W = J^T Dn^-1 A'^-1 */
    for (k = 0; k < 6; k++)
        for (j = 0; j < 6; j++) Ap[k * 6 + j] = G[k * 6 + j] / (Dn[k] * Dn[j]);
    DHT_TRUE(chol(Ap, 6, L));
    for (j = 0; j < 6; j++) {
        for (k = 0; k < 6; k++) t[k] = (k == j);
        chol_solve(L, 6, t, col);
        for (k = 0; k < 6; k++) Ai[k * 6 + j] = col[k];
    }
    for (i = 0; i < n; i++)
        for (j = 0; j < 6; j++) {
            double s = 0;
            for (k = 0; k < 6; k++) s += Jn[k * n + i] / Dn[k] * Ai[k * 6 + j];
            W[i * 6 + j] = s;
        }
    nAi = fro(Ai, 6, 6);
    nW = fro(W, n, 6);
    nE = sqrt(6 * pow(2 * eps_r + 2.0 / Q30, 2) + 30 * pow(3.0 / Q30, 2));
    u = ldexp(1.0, -25) * fmax(bmax, nAi * nb);
    rnorm = sqrt(6.0) * (1 + sqrt(6.0)) * u;
    tot = fro(dJ, 6, n) * (ne / (lam * lam) + ndq / (2 * lam)) + nW * nE * nDx + nW * rnorm + 24 * u / dmin;
    for (i = 0; i < n; i++) {
        const double K = (r->joint[i].type == DH_JOINT_REVOLUTE) ? 180 / PI * 65536 : QPOS;
        row[i] = 0.5 + K * (tot + ldexp(fabs(dqn[i]), -29));
    }
    return tot;
}

/* The exact damped step in (length, rad) from the integer J and e. */
static void dls_ref(const dh_robot *r, const double *Jn, const double *e, double lam, double *G, double *x,
                    double *dqn)
{
    const unsigned n = r->n;
    double L[36];
    unsigned i, k;
    gram(Jn, n, 0, lam * lam, G);
    DHT_TRUE(chol(G, 6, L));
    chol_solve(L, 6, e, x);
    for (i = 0; i < n; i++) {
        double s = 0;
        for (k = 0; k < 6; k++) s += Jn[k * n + i] * x[k];
        dqn[i] = s;
    }
}

static void dls_accuracy(const dhs_robot *d, const char *name)
{
    dh_robot r;
    int32_t q[DHS_MAX_JOINTS], J[6 * DHS_MAX_JOINTS], e[6], dq[DHS_MAX_JOINTS];
    double Jn[6 * DHS_MAX_JOINTS], G[36], x[6], en[6], dqn[DHS_MAX_JOINTS], row[DHS_MAX_JOINTS];
    double worst = 0, worst_b = 0, worst_ratio = 0;
    const double L = 1000.0 * d->unit_per_m / 1000.0;   /* 1 m in the robot's unit */
    long it, cnt = DHT_ITER(3000);
    unsigned i, k;
    DHT_EQ_INT(dhs_build_q(d, &r), DH_OK);
    for (it = 0; it < cnt; it++) {
        /* damping from 1e-3 to 1 m (length unit / rad), errors up to 1 cm, 0.05 rad */
        const double lam = L * pow(10.0, dht_rand_uniform(-3, 0));
        const int32_t lq = dhs_to_q(lam, DH_QPOS_FRAC);
        rand_q(d, &r, q);
        DHT_EQ_INT(dh_jacobian_q(&r, q, J, NULL), DH_OK);
        for (k = 0; k < 3; k++) e[k] = dhs_to_q(dht_rand_uniform(-0.01, 0.01) * L, DH_QPOS_FRAC);
        for (k = 3; k < 6; k++) e[k] = dhs_to_q(dht_rand_uniform(-0.05, 0.05), 29);
        for (k = 0; k < 6; k++) en[k] = e[k] / (k < 3 ? QPOS : Q29);
        DHT_EQ_INT(dh_dls_step_q(&r, J, e, lq, NULL, &wk, dq), DH_OK);
        jac_num(&r, J, Jn);
        dls_ref(&r, Jn, en, lq / QPOS, G, x, dqn);
        dls_bound(&r, J, lq, Jn, G, x, en, dqn, row);
        for (i = 0; i < r.n; i++) {
            const double K = (r.joint[i].type == DH_JOINT_REVOLUTE) ? 180 / PI * 65536 : QPOS;
            const double err = fabs(dq[i] - dqn[i] * K);
            DHT_TRUE_MSG(err <= row[i], "%s: joint %u error %.3g LSB > bound %.3g (dq %ld ref %.6g)", name, i, err,
                         row[i], (long)dq[i], dqn[i] * K);
            if (err > worst) worst = err;
            if (row[i] > worst_b) worst_b = row[i];
            if (err / row[i] > worst_ratio) worst_ratio = err / row[i];
        }
    }
    dht_printf("%s (%ld steps): largest error %.3g LSB, largest bound %.3g LSB, largest error/bound %.3g\n", name,
               cnt, worst, worst_b, worst_ratio);
}

static void dls_puma(void) { dls_accuracy(&dhs_puma560_mm, "puma560_mm"); }
static void dls_ur5(void) { dls_accuracy(&dhs_ur5_mm, "ur5_mm"); }
static void dls_panda(void) { dls_accuracy(&dhs_panda_mm, "panda_mm"); }
static void dls_ur5_m(void) { dls_accuracy(&dhs_ur5_m, "ur5_m"); }

/* dq_max: every |dq_i| <= dq_max_i exactly, the unscaled step's direction
 * (ratio rho = min dq_max_i / |dq_i| applied to all, within the bound of
 * the unscaled step times rho plus 1 LSB), and a joint at its bound. */
static void dls_scaled(void)
{
    const dhs_robot *d = &dhs_ur5_mm;
    dh_robot r;
    int32_t q[6], J[36], e[6], dq[6], dqs[6], mx[6];
    long it, cnt = DHT_ITER(2000);
    unsigned i, k;
    DHT_EQ_INT(dhs_build_q(d, &r), DH_OK);
    for (it = 0; it < cnt; it++) {
        double rho = 1e300, at = 0;
        rand_q(d, &r, q);
        DHT_EQ_INT(dh_jacobian_q(&r, q, J, NULL), DH_OK);
        for (k = 0; k < 3; k++) e[k] = dhs_to_q(dht_rand_uniform(-20, 20), DH_QPOS_FRAC);
        for (k = 3; k < 6; k++) e[k] = dhs_to_q(dht_rand_uniform(-0.1, 0.1), 29);
        for (i = 0; i < 6; i++) mx[i] = (int32_t)(dht_rand_u32() % 65536u) * ((it % 3 == 0) ? 1 : 40);
        DHT_EQ_INT(dh_dls_step_q(&r, J, e, DH_QPOS(5.0), NULL, &wk, dq), DH_OK);
        DHT_EQ_INT(dh_dls_step_q(&r, J, e, DH_QPOS(5.0), mx, &wk, dqs), DH_OK);
        double lim = 1;   /* |dq| of the limiting joint */
        for (i = 0; i < 6; i++)
            if (dq[i] != 0 && (double)mx[i] / fabs((double)dq[i]) < rho) {
                rho = (double)mx[i] / fabs((double)dq[i]);
                lim = fabs((double)dq[i]);
            }
        if (rho > 1) rho = 1;
        for (i = 0; i < 6; i++) {
            DHT_TRUE_MSG(dqs[i] <= mx[i] && dqs[i] >= -mx[i], "joint %u: %ld beyond %ld", i, (long)dqs[i], (long)mx[i]);
            /* the unscaled outputs are rounded (0.5 LSB): rho from them is off
             * by 0.5 / lim relative, the joint itself by 0.5 rho; the 31-bit
             * mantissas (2^-28 relative) and the floor (1 LSB) */
            DHT_NEAR((double)dqs[i], rho * dq[i],
                     0.5 * rho + rho * fabs((double)dq[i]) * (0.5 / lim + ldexp(1.0, -28)) + 1.0);
            if (fabs((double)dqs[i]) >= mx[i] - 1.0 - mx[i] * ldexp(1.0, -27)) at = 1;
        }
        if (rho < 1) DHT_TRUE(at);
    }
}

/* ---- singularity measures ------------------------------------------------ */

/*
 * log2 w: the pivots' relative error is tr(A'^-1 E) to first order (E as
 * in dls_bound: |E_jj| <= 2 eps_r + 2^-29, |E_jk| <= 3 2^-30), the
 * Q(g) rounding of J adds tr(G^-1 dG), dG = J_g J_g^T - J J^T; the
 * product of the pivot roots is renormalised m times (2^-30 relative
 * each), the logarithm has 16 bits by repeated squaring (floor: < 2^-16,
 * each squaring truncated by 2^-30 relative: < 2^-25 in all). In Q16.16:
 * 1 + 2^16 (|A'^-1|_F |E|_F + |G^-1|_F |dG|_F) / (2 ln 2) + 2^-8.
 *
 * sigma_min: a lower bound on sqrt(lambda_min(G)) for every input; above
 * sqrt(lambda_min / m) / 2 where lambda_min(A') > 8 delta (the factor of A'
 * - delta I then loses at most a fraction 1/8 of the smallest eigenvalue,
 * the trace at most m times it; the factor 2 covers both and the margins).
 */
static void manip_check(const dh_robot *r, const int32_t *J, const char *name, double *wl, double *sl)
{
    const unsigned n = r->n;
    const int cols = n < 6;
    double Jn[6 * DHS_MAX_JOINTS], G[64], L[64], Ai[64], Ap[64], Gi[64], dG[64], Jg[6 * DHS_MAX_JOINTS], t[8],
        col[8], Dn[8];
    double logw, lmin, lminp, sig, ref, bnd, eps_r = 7e-10 + 4.0 / Q29;
    int32_t w, s;
    unsigned m, k, j, i;
    int g[2];
    fmt_g(r, J, 0, cols, g);
    jac_num(r, J, Jn);
    m = gram(Jn, n, cols, 0.0, G);
    for (k = 0; k < 6; k++)
        for (i = 0; i < n; i++) {
            const int from = (k < 3 && r->joint[i].type == DH_JOINT_REVOLUTE) ? DH_QPOS_FRAC : 30;
            Jg[k * n + i] = ldexp(floor(ldexp((double)J[k * n + i], g[k >= 3] - from) + 0.5), -g[k >= 3]);
        }
    gram(Jg, n, cols, 0.0, dG);
    for (k = 0; k < m * m; k++) dG[k] -= G[k];
    DHT_EQ_INT(dh_manipulability_q(J, n, &wk, &w, &s), DH_OK);
    lmin = eig_min(G, m);
    sig = s / QPOS;
    ref = lmin > 0 ? sqrt(lmin) : 0;
    DHT_TRUE_MSG(sig <= ref, "%s: sigma_min bound %.9g above the smallest singular value %.9g", name, sig, ref);
    for (k = 0; k < m; k++) {
        const int gk_ = cols ? g[0] : g[k >= 3];
        double gk = G[k * m + k] * ldexp(1.0, 2 * gk_);
        int c = 0;
        if (gk == 0) { Dn[k] = 1; continue; }
        while (gk >= ldexp(1.0, 30)) { gk /= 4; c++; }
        while (gk < ldexp(1.0, 28)) { gk *= 4; c--; }
        Dn[k] = ldexp(1.0, c + 15 - gk_);
    }
    for (k = 0; k < m; k++)
        for (j = 0; j < m; j++) Ap[k * m + j] = G[k * m + j] / (Dn[k] * Dn[j]);
    lminp = eig_min(Ap, m);
    if (lminp > 8 * ldexp(1.0, -21)) {
        DHT_TRUE_MSG(sig >= 0.5 * sqrt(lmin / m), "%s: sigma_min bound %.9g far below %.9g", name, sig, ref);
    }
    if (ref > 0 && sig / ref < *sl) *sl = sig / ref;
    if (!chol(Ap, m, L) || lminp < ldexp(1.0, -20)) return;   /* near singular: log only from here */
    for (j = 0; j < m; j++) {
        for (k = 0; k < m; k++) t[k] = (k == j);
        chol_solve(L, m, t, col);
        for (k = 0; k < m; k++) Ai[k * m + j] = col[k];
    }
    for (j = 0; j < m; j++) {
        for (k = 0; k < m; k++) Gi[k * m + j] = Ai[k * m + j] / (Dn[k] * Dn[j]);
    }
    logw = 0;
    DHT_TRUE(chol(G, m, L));
    for (k = 0; k < m; k++) logw += log2(L[k * m + k]);
    bnd = 1 + 65536 * (fro(Ai, m, m) * sqrt(m * pow(2 * eps_r + 2.0 / Q30, 2) + m * m * pow(3.0 / Q30, 2)) +
                       fro(Gi, m, m) * fro(dG, m, m)) / (2 * log(2.0)) + 256;
    DHT_TRUE_MSG(w != INT32_MIN, "%s: log2 w reported singular, ref %.9g", name, logw);
    DHT_TRUE_MSG(fabs(w - logw * 65536) <= bnd, "%s: log2 w %.9g, ref %.9g, bound %.3g LSB", name, w / 65536.0,
                 logw, bnd);
    if (fabs(w - logw * 65536) > *wl) *wl = fabs(w - logw * 65536);
}

static void manip_robot(const dhs_robot *d, const char *name)
{
    dh_robot r;
    int32_t q[DHS_MAX_JOINTS], J[6 * DHS_MAX_JOINTS];
    double wl = 0, sl = 1e300;
    long it, cnt = DHT_ITER(2000);
    DHT_EQ_INT(dhs_build_q(d, &r), DH_OK);
    for (it = 0; it < cnt; it++) {
        rand_q(d, &r, q);
        if (it % 4 == 1 && r.n >= 6) q[4] = dhs_to_q(dht_rand_uniform(-1e-3, 1e-3), 16);   /* wrist */
        if (it % 4 == 2 && r.n >= 6) q[4] = dhs_to_q(dht_rand_uniform(-0.2, 0.2), 16);
        if (it % 8 == 3 && r.n >= 6) q[4] = 0;
        DHT_EQ_INT(dh_jacobian_q(&r, q, J, NULL), DH_OK);
        manip_check(&r, J, name, &wl, &sl);
    }
    dht_printf("%s (%ld configs): largest log2 w error %.3g LSB (Q16.16), smallest sigma bound / sigma %.3g\n", name,
               cnt, wl, sl);
}

static void manip_puma(void) { manip_robot(&dhs_puma560_mm, "puma560_mm"); }
static void manip_ur5(void) { manip_robot(&dhs_ur5_mm, "ur5_mm"); }
static void manip_panda(void) { manip_robot(&dhs_panda_mm, "panda_mm"); }
static void manip_stanford(void) { manip_robot(&dhs_stanford_mm, "stanford_mm"); }

/* n < 6: J^T J (a planar 2R arm with a prismatic joint). */
static void manip_short(void)
{
    dh_robot r;
    int32_t q[3], J[18];
    double wl = 0, sl = 1e300;
    long it;
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_q(&r, DH_JOINT_REVOLUTE, 0, 0, DH_QPOS(300.0), 0), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_q(&r, DH_JOINT_REVOLUTE, 0, 0, DH_QPOS(200.0), 0), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_q(&r, DH_JOINT_PRISMATIC, 0, 0, 0, 0), DH_OK);
    for (it = 0; it < DHT_ITER(500); it++) {
        q[0] = dhs_to_q(dht_rand_uniform(-180, 180), 16);
        q[1] = dhs_to_q(it % 5 == 0 ? dht_rand_uniform(-0.01, 0.01) : dht_rand_uniform(-180, 180), 16);
        q[2] = DH_QPOS(50.0);
        DHT_EQ_INT(dh_jacobian_q(&r, q, J, NULL), DH_OK);
        manip_check(&r, J, "planar", &wl, &sl);
    }
}

/* ---- statuses -------------------------------------------------------------- */

static void dls_errors(void)
{
    dh_robot r, r3;
    int32_t q[6] = {0}, J[36], e[6] = {DH_QPOS(1.0), 0, 0, 0, 0, 0}, dq[6], mx[6] = {1, 1, 1, 1, 1, 1}, w, s;
    int32_t J3[18];
    unsigned i;
    DHT_EQ_INT(dhs_build_q(&dhs_ur5_mm, &r), DH_OK);
    q[1] = DH_Q16(-30.0);
    q[2] = DH_Q16(60.0);
    q[4] = DH_Q16(30.0);
    DHT_EQ_INT(dh_jacobian_q(&r, q, J, NULL), DH_OK);
    for (i = 0; i < 6; i++) dq[i] = 77;
    DHT_EQ_INT(dh_dls_step_q(&r, J, e, -1, NULL, &wk, dq), DH_ERR_ARG);
    mx[2] = -1;
    DHT_EQ_INT(dh_dls_step_q(&r, J, e, 0, mx, &wk, dq), DH_ERR_ARG);
    for (i = 0; i < 6; i++) DHT_EQ_INT(dq[i], 77);   /* untouched */
    mx[2] = 1;
    /* zero error: zero step */
    memset(e, 0, sizeof e);
    DHT_EQ_INT(dh_dls_step_q(&r, J, e, DH_QPOS(1.0), mx, &wk, dq), DH_OK);
    for (i = 0; i < 6; i++) DHT_EQ_INT(dq[i], 0);
    /* dq_max 0 for one joint that moves: every joint stays */
    e[0] = DH_QPOS(3.0);
    mx[0] = 0;
    for (i = 1; i < 6; i++) mx[i] = INT32_MAX;
    DHT_EQ_INT(dh_dls_step_q(&r, J, e, DH_QPOS(1.0), mx, &wk, dq), DH_OK);
    for (i = 0; i < 6; i++) DHT_EQ_INT(dq[i], 0);
    /* undamped, singular: a 3-joint arm's 6 x 6 J J^T has rank 3 */
    DHT_EQ_INT(dh_robot_init(&r3, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_q(&r3, DH_JOINT_REVOLUTE, 0, 0, DH_QPOS(300.0), 0), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_q(&r3, DH_JOINT_REVOLUTE, 0, 0, DH_QPOS(200.0), 0), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_q(&r3, DH_JOINT_PRISMATIC, 0, 0, 0, 0), DH_OK);
    q[0] = DH_Q16(20.0);
    q[1] = DH_Q16(40.0);
    q[2] = 0;
    DHT_EQ_INT(dh_jacobian_q(&r3, q, J3, NULL), DH_OK);
    for (i = 0; i < 3; i++) dq[i] = 77;
    DHT_EQ_INT(dh_dls_step_q(&r3, J3, e, 0, NULL, &wk, dq), DH_ERR_SINGULAR);
    for (i = 0; i < 3; i++) DHT_EQ_INT(dq[i], 0);
    /* damped, the same arm: the least-squares step with damping */
    DHT_EQ_INT(dh_dls_step_q(&r3, J3, e, DH_QPOS(1.0), NULL, &wk, dq), DH_OK);
    /* undamped and far from singular: the exact Newton step (UR5) */
    DHT_EQ_INT(dh_dls_step_q(&r, J, e, 0, NULL, &wk, dq), DH_OK);
    /* manipulability: n out of range */
    DHT_EQ_INT(dh_manipulability_q(J, 0, &wk, &w, &s), DH_ERR_ARG);
    DHT_EQ_INT(dh_manipulability_q(J, DH_MAX_JOINTS + 1u, &wk, &w, &s), DH_ERR_ARG);
    DHT_EQ_INT(dh_manipulability_q(J, 6, &wk, NULL, NULL), DH_OK);
    /* a robot without the fixed path */
    r.flags &= ~DH_ROBOT_HAS_Q;
    DHT_EQ_INT(dh_dls_step_q(&r, J, e, 0, NULL, &wk, dq), DH_ERR_UNAVAILABLE);
}

/* Saturated Jacobian entries and huge errors: never UB, a status. */
static void dls_extreme(void)
{
    dh_robot r;
    int32_t J[36], e[6], dq[6], mx[6], w, s;
    unsigned i, k, it;
    dh_status st;
    DHT_EQ_INT(dhs_build_q(&dhs_ur5_mm, &r), DH_OK);
    for (it = 0; it < 200; it++) {
        for (k = 0; k < 36; k++) {
            const uint32_t u = dht_rand_u32();
            J[k] = (it % 4 == 0) ? (int32_t)u : (int32_t)(u % 2001u) - 1000;
            if (it % 7 == 0 && k % 5 == 0) J[k] = (k & 1) ? INT32_MIN : INT32_MAX;
        }
        for (k = 0; k < 6; k++) e[k] = (it % 3 == 0) ? (int32_t)dht_rand_u32() : (k & 1 ? INT32_MIN : INT32_MAX);
        for (i = 0; i < 6; i++) mx[i] = (int32_t)(dht_rand_u32() >> 1);
        st = dh_dls_step_q(&r, J, e, (int32_t)(dht_rand_u32() >> (1 + it % 31)), mx, &wk, dq);
        DHT_TRUE(st == DH_OK || st == DH_ERR_OVERFLOW || st == DH_ERR_SINGULAR);
        for (i = 0; i < 6; i++) DHT_TRUE(dq[i] <= mx[i] && dq[i] >= -mx[i]);
        st = dh_dls_step_q(&r, J, e, (int32_t)(dht_rand_u32() >> (1 + it % 31)), NULL, &wk, dq);
        DHT_TRUE(st == DH_OK || st == DH_ERR_OVERFLOW || st == DH_ERR_SINGULAR);
        DHT_EQ_INT(dh_manipulability_q(J, 6, &wk, &w, &s), DH_OK);
        DHT_TRUE(s >= 0);
    }
}

static const dht_case cases[] = {
    DHT_CASE(dls_puma),       DHT_CASE(dls_ur5),       DHT_CASE(dls_panda),     DHT_CASE(dls_ur5_m),
    DHT_CASE(dls_scaled),     DHT_CASE(manip_puma),    DHT_CASE(manip_ur5),     DHT_CASE(manip_panda),
    DHT_CASE(manip_stanford), DHT_CASE(manip_short),   DHT_CASE(dls_errors),    DHT_CASE(dls_extreme),
};
DHT_MAIN(cases)
