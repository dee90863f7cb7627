/* SPDX-License-Identifier: Apache-2.0 */
/*
 * support_ikc.c - what the closed-form IK suites share (see support_ikc.h).
 */
#include "support_ikc.h"
#include "dht.h"

#include <stdio.h>
#include <string.h>

#define DHK_D2R (DHR_PI / 180.0)

double dhk_sing_parts(const dhs_robot *d, const double *q, double part[3])
{
    dhr_mat4 F[DHS_MAX_JOINTS];
    double m;
    int i;
    part[0] = part[2] = 1.0;
    if (d->n == 4u) {
        const double a1 = fabs(d->j[0].a), a2 = fabs(d->j[1].a);
        part[1] = a1 * a2 * fabs(sin((q[1] + d->j[1].theta_deg) * DHK_D2R)) / ((a1 + a2) * (a1 + a2));
    } else {
        const double a2 = fabs(d->j[1].a), a3 = fabs(d->j[2].a);
        double L = 0, u;
        unsigned j;
        for (j = 0; j < d->n; j++) L += fabs(d->j[j].a) + fabs(d->j[j].d);
        dhs_fk_desc(d, q, F, NULL);
        /* along x1 from the origin of the frame before joint 1 (the base) */
        u = (F[4].m[3][0] - d->base.m[3][0]) * F[0].m[0][0] + (F[4].m[3][1] - d->base.m[3][1]) * F[0].m[0][1] +
            (F[4].m[3][2] - d->base.m[3][2]) * F[0].m[0][2];
        part[0] = fabs(u) / L;
        part[1] = a2 * a3 * fabs(sin((q[2] + d->j[2].theta_deg) * DHK_D2R)) / ((a2 + a3) * (a2 + a3));
        part[2] = fabs(sin((q[4] + d->j[4].theta_deg) * DHK_D2R));
    }
    m = part[0];
    for (i = 1; i < 3; i++)
        if (part[i] < m) m = part[i];
    return m;
}

void dhk_reach_sing(const char *prefix, const double part[3])
{
    static const char *const suffix[6] = { "s", "e", "w", "se", "ew", "sw" };
    const double v[6] = { part[0], part[1], part[2], fmax(part[0], part[1]), fmax(part[1], part[2]),
                          fmax(part[0], part[2]) };
    char name[48];
    int k;
    for (k = 0; k < 6; k++) {
        snprintf(name, sizeof name, "%s.%s", prefix, suffix[k]);
        dht_reach_min(name, v[k]);
    }
}

/* ---- fixed point --------------------------------------------------------- */

void dhk_scale_desc(dhs_robot *d)
{
    unsigned i;
    for (i = 0; i < d->n; i++) {
        d->j[i].a *= DHK_LS;
        d->j[i].d *= DHK_LS;
        if (d->j[i].type == DH_JOINT_PRISMATIC) {
            d->j[i].qmin *= DHK_LS;
            d->j[i].qmax *= DHK_LS;
        }
    }
    for (i = 0; i < 3; i++) {
        d->base.m[3][i] *= DHK_LS;
        d->tool.m[3][i] *= DHK_LS;
    }
}

void dhk_build_q(const dhs_robot *d, dh_ikc_kind kind, dh_robot *r, dh_ikc_model_q *m)
{
    DHT_EQ_INT(dhs_build(d, r), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_q(r, m), DH_OK);
    DHT_EQ_INT(m->kind, kind);
    DHT_EQ_INT(m->why, DH_IKC_WHY_NONE);
}

double dhk_jdiff_q(const dh_robot *r, uint32_t i, int32_t a, int32_t b)
{
    double d;
    if (r->joint[i].type == DH_JOINT_PRISMATIC) return fabs(ldexp((double)a - (double)b, -DH_QPOS_FRAC)) / DHK_LS;
    d = fmod(ldexp((double)a - (double)b, -16), 360.0);
    if (d > 180.0) d -= 360.0;
    if (d < -180.0) d += 360.0;
    return fabs(d);
}

int dhk_check_sols_q(const dh_robot *r, const dhr_mat4 *Td, const dh_ikc_sol_q *sol, uint32_t ns,
                     const int32_t *qgen, dhk_stats *st)
{
    uint32_t s, i;
    int found = -1;
    for (s = 0; s < ns; s++) {
        dhr_mat4 Ts;
        double pe, re, worst = 0.0;
        dhs_fk_ref_q(r, sol[s].q, NULL, &Ts);
        pe = dhr_pos_diff(&Ts, Td);
        re = dhr_rot_diff(&Ts, Td);
        DHT_TRUE_MSG(pe <= DHK_POS_TOL && re <= DHK_ROT_TOL,
                     "solution %u of %u (flags 0x%x): pos err %.3g mm, rot err %.3g; q %ld %ld %ld %ld %ld %ld",
                     (unsigned)s, (unsigned)ns, (unsigned)sol[s].flags, pe, re, (long)sol[s].q[0], (long)sol[s].q[1],
                     (long)sol[s].q[2], (long)sol[s].q[3], (long)sol[s].q[4], (long)sol[s].q[5]);
        if (st) {
            if (pe > st->pos) st->pos = pe;
            if (re > st->rot) st->rot = re;
            st->sols++;
        }
        if (qgen) {
            for (i = 0; i < r->n; i++) {
                double d = dhk_jdiff_q(r, i, sol[s].q[i], qgen[i]);
                if (d > worst) worst = d;
            }
            if (worst <= DHK_COMP_DEG && found < 0) found = (int)s;
        }
    }
    return found;
}

/* w = the skew part of W = (Ra - Rb) / div Rr^T (m[col][row]): the small
 * rotation from Rb to Ra, or with Ra, Rb the two sides of a central
 * difference and div = 2h, a Jacobian's rotation column. */
static void ikcs_rot_diff(const dhr_mat4 *a, const dhr_mat4 *b, const dhr_mat4 *ref, double div, double w[3])
{
    double W[3][3];
    int i, j, c;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            W[i][j] = 0.0;
            for (c = 0; c < 3; c++) W[i][j] += (a->m[c][i] - b->m[c][i]) / div * ref->m[c][j];
        }
    w[0] = 0.5 * (W[2][1] - W[1][2]);
    w[1] = 0.5 * (W[0][2] - W[2][0]);
    w[2] = 0.5 * (W[1][0] - W[0][1]);
}

/* J (6 x 6, per degree / length unit of q, rows position then rotation)
 * by central differences of the double FK of d at q, and Ji = J^-1 by
 * Gauss-Jordan with partial pivoting. 0 when J is singular to 1e-12. */
static int ikcs_jac_inv(const dhs_robot *d, const double *q, double J[6][6], double Ji[6][6])
{
    double A[6][12], qp[6], qm[6], w[3];
    dhr_mat4 T0, Tp, Tm;
    const double h = 1e-4;
    int i, j, k, c;
    dhs_fk_desc(d, q, NULL, &T0);
    for (k = 0; k < 6; k++) {
        memcpy(qp, q, sizeof qp);
        memcpy(qm, q, sizeof qm);
        qp[k] += h;
        qm[k] -= h;
        dhs_fk_desc(d, qp, NULL, &Tp);
        dhs_fk_desc(d, qm, NULL, &Tm);
        for (i = 0; i < 3; i++) J[i][k] = (Tp.m[3][i] - Tm.m[3][i]) / (2.0 * h);
        ikcs_rot_diff(&Tp, &Tm, &T0, 2.0 * h, w);
        for (i = 0; i < 3; i++) J[3 + i][k] = w[i];
    }
    for (i = 0; i < 6; i++) {
        for (j = 0; j < 6; j++) {
            A[i][j] = J[i][j];
            A[i][6 + j] = (i == j) ? 1.0 : 0.0;
        }
    }
    for (c = 0; c < 6; c++) { /* Gauss-Jordan, partial pivoting */
        int piv = c;
        for (i = c + 1; i < 6; i++)
            if (fabs(A[i][c]) > fabs(A[piv][c])) piv = i;
        if (fabs(A[piv][c]) < 1e-12) return 0;
        for (j = 0; j < 12; j++) {
            double t = A[c][j];
            A[c][j] = A[piv][j];
            A[piv][j] = t;
        }
        for (i = 0; i < 6; i++) {
            double f;
            if (i == c) continue;
            f = A[i][c] / A[c][c];
            for (j = 0; j < 12; j++) A[i][j] -= f * A[c][j];
        }
    }
    for (i = 0; i < 6; i++)
        for (j = 0; j < 6; j++) Ji[i][j] = A[i][6 + j] / A[i][i];
    return 1;
}

int dhk_well_conditioned_q(const dhs_robot *d, const double *q, double tol, int nj)
{
    double J[6][6], Ji[6][6], dx[6];
    int i, j, k;
    if (!ikcs_jac_inv(d, q, J, Ji)) return 0;
    for (i = 0; i < 6; i++) {
        dx[i] = (i < 3) ? ldexp(1.0, -DH_QPOS_FRAC) : ldexp(2.0, -30);
        for (k = 0; k < 3; k++)
            dx[i] += fabs(J[i][k]) * ((d->j[k].type == DH_JOINT_REVOLUTE) ? ldexp(2.0, -16) : ldexp(2.0, -DH_QPOS_FRAC));
    }
    for (i = 0; i < nj; i++) {
        double b = 0.0;
        for (j = 0; j < 6; j++) b += fabs(Ji[i][j]) * dx[j];
        if (d->j[i].type == DH_JOINT_PRISMATIC) b /= DHK_LS; /* as dhk_jdiff_q */
        if (b > tol) return 0;
    }
    return 1;
}

int dhk_first_order_match_q(const dhs_robot *d, const double *q, const dh_robot *r, const dhr_mat4 *Td,
                            const dh_ikc_sol_q *sol, uint32_t ns, const int32_t *qgen)
{
    double J[6][6], Ji[6][6];
    uint32_t s;
    if (!ikcs_jac_inv(d, q, J, Ji)) return -1;
    for (s = 0; s < ns; s++) {
        dhr_mat4 Ts;
        double e[6];
        int i, j, ok = 1;
        dhs_fk_ref_q(r, sol[s].q, NULL, &Ts);
        for (i = 0; i < 3; i++) e[i] = Ts.m[3][i] - Td->m[3][i];
        ikcs_rot_diff(&Ts, Td, Td, 1.0, e + 3);
        for (i = 0; i < 6 && ok; i++) {
            double b = 0.0;
            for (j = 0; j < 6; j++) b += fabs(Ji[i][j]) * (fabs(e[j]) + ((j < 3) ? ldexp(1.0, -DH_QPOS_FRAC) : ldexp(2.0, -30)));
            b *= 2.0; /* the second-order rest */
            if (d->j[i].type == DH_JOINT_PRISMATIC) b /= DHK_LS; /* as dhk_jdiff_q */
            if (b < DHK_COMP_DEG) b = DHK_COMP_DEG;
            ok = dhk_jdiff_q(r, (uint32_t)i, sol[s].q[i], qgen[i]) <= b;
        }
        if (ok) return (int)s;
    }
    return -1;
}
