/* SPDX-License-Identifier: Apache-2.0 */
/*
 * support_motion_q.c - shared by the fixed-point motion tests
 * (test_move_q.c, test_queue_q.c): a robot in mm (in units of DHSM_LS mm) with
 * its fixed closed-form model, double-precision FK of fixed
 * configurations, and double references of fixed paths (the segment, and
 * the circle through p_A, via, p_B: its centre from the plane of the three
 * points and the two bisector planes, Cramer's rule). Nothing here calls
 * the code under test but the set-up of the robot (dhs_build_q,
 * dh_robot_set_rates_q, dh_ikc_analyse_q).
 */
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_motion_q.h"

void dhsm_rig_make(dhsm_rig *g, const dhs_robot *d, double vdeg, double adeg)
{
    dhs_robot fmt;   /* d in units of DHSM_LS mm: the same lengths in LSB in every format (on the stack: the micro:bit's RAM) */
    uint32_t i;
    int k;
    g->d = d;
    fmt = *d;
    for (i = 0; i < d->n; i++) {
        fmt.j[i].a *= DHSM_LS;
        fmt.j[i].d *= DHSM_LS;
        if (d->j[i].type == DH_JOINT_PRISMATIC) {
            fmt.j[i].qmin *= DHSM_LS;
            fmt.j[i].qmax *= DHSM_LS;
        }
    }
    for (k = 0; k < 3; k++) {
        DHR_M4(&fmt.base, k, 3) *= DHSM_LS;
        DHR_M4(&fmt.tool, k, 3) *= DHSM_LS;
    }
    fmt.unit_per_m *= DHSM_LS;
    DHT_EQ_INT(dhs_build_q(&fmt, &g->r), DH_OK);
    for (i = 0; i < g->r.n; i++)
        DHT_EQ_INT(dh_robot_set_rates_q(&g->r, i, (int32_t)(vdeg * DHSM_Q16), (int32_t)(adeg * DHSM_Q16)), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_q(&g->r, &g->m), DH_OK);
}

void dhsm_tool_mm(const dhsm_rig *g, const int32_t *q, double *p, dhr_mat4 *T)
{
    dhs_fk_ref_q(&g->r, q, NULL, T);
    p[0] = DHR_M4(T, 0, 3);
    p[1] = DHR_M4(T, 1, 3);
    p[2] = DHR_M4(T, 2, 3);
}

void dhsm_target_of(const dhsm_rig *g, const int32_t *q, dh_frame_q *T)
{
    dhr_mat4 R;
    dhs_fk_ref_q(&g->r, q, NULL, &R);
    dhs_to_frame_q(&R, T);
}

double dhsm_dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double dhsm_dist3(const double *a, const double *b)
{
    const double d[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
    return sqrt(dhsm_dot3(d, d));
}

void dhsm_ref_make(dhsm_ref *rp, const dh_path_q *p, const dh_qpos *via)
{
    int k;
    memset(rp, 0, sizeof *rp);
    for (k = 0; k < 3; k++) {
        rp->pa[k] = p->A.p[k] / DHSM_QPOS;
        rp->pb[k] = p->B.p[k] / DHSM_QPOS;
    }
    rp->arc = via != NULL;
    if (rp->arc) {
        /* rows: n . c = n . pa; (v - pa) . c = (|v|^2 - |pa|^2) / 2; (pb - pa) . c likewise */
        double M[3][3], r[3], v[3], det, x[3];
        int i, j;
        for (k = 0; k < 3; k++) v[k] = via[k] / DHSM_QPOS;
        for (k = 0; k < 3; k++) {
            M[1][k] = v[k] - rp->pa[k];
            M[2][k] = rp->pb[k] - rp->pa[k];
        }
        M[0][0] = M[1][1] * M[2][2] - M[1][2] * M[2][1];
        M[0][1] = M[1][2] * M[2][0] - M[1][0] * M[2][2];
        M[0][2] = M[1][0] * M[2][1] - M[1][1] * M[2][0];
        r[0] = dhsm_dot3(M[0], rp->pa);
        r[1] = 0.5 * (dhsm_dot3(v, v) - dhsm_dot3(rp->pa, rp->pa));
        r[2] = 0.5 * (dhsm_dot3(rp->pb, rp->pb) - dhsm_dot3(rp->pa, rp->pa));
        det = M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
              M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
        for (j = 0; j < 3; j++) {
            double Mj[3][3], dj;
            memcpy(Mj, M, sizeof Mj);
            for (i = 0; i < 3; i++) Mj[i][j] = r[i];
            dj = Mj[0][0] * (Mj[1][1] * Mj[2][2] - Mj[1][2] * Mj[2][1]) -
                 Mj[0][1] * (Mj[1][0] * Mj[2][2] - Mj[1][2] * Mj[2][0]) +
                 Mj[0][2] * (Mj[1][0] * Mj[2][1] - Mj[1][1] * Mj[2][0]);
            x[j] = dj / det;
        }
        for (k = 0; k < 3; k++) {
            rp->c[k] = x[k];
            rp->n[k] = M[0][k] / sqrt(dhsm_dot3(M[0], M[0]));
        }
        rp->R = dhsm_dist3(rp->c, rp->pa);
    }
}

/* distance (mm) of p from the reference path */
double dhsm_ref_dist(const dhsm_ref *rp, const double *p)
{
    double d[3], u[3], t, h, rho;
    int k;
    if (!rp->arc) {
        for (k = 0; k < 3; k++) {
            d[k] = rp->pb[k] - rp->pa[k];
            u[k] = p[k] - rp->pa[k];
        }
        t = dhsm_dot3(d, d) > 0.0 ? dhsm_dot3(u, d) / dhsm_dot3(d, d) : 0.0;
        t = fmin(fmax(t, 0.0), 1.0);
        for (k = 0; k < 3; k++) u[k] = rp->pa[k] + t * d[k];
        return dhsm_dist3(p, u);
    }
    for (k = 0; k < 3; k++) d[k] = p[k] - rp->c[k];
    h = dhsm_dot3(d, rp->n);
    for (k = 0; k < 3; k++) d[k] -= h * rp->n[k];
    rho = sqrt(dhsm_dot3(d, d));
    return sqrt(h * h + (rho - rp->R) * (rho - rp->R));
}

/* rotation angle (rad) between the rotations of two fixed frames */
double dhsm_rot_between(const dh_frame_q *F, const dh_frame_q *G)
{
    double R[3][3];
    int i, j, k;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            R[i][j] = 0.0;
            for (k = 0; k < 3; k++) R[i][j] += (F->r[j][k] / DHSM_Q30) * (G->r[i][k] / DHSM_Q30);
        }
    return dhs_rot_angle(R);
}

/* a configuration of the robot's region: the UR5's dhs_ur5_safe_q(15), the
 * Puma within 10 degrees of (10, -30, 45, 20, 35, -60) */
void dhsm_region_q(const dhsm_rig *g, double *q)
{
    static const double QP[6] = { 10.0, -30.0, 45.0, 20.0, 35.0, -60.0 };
    int i;
    if (g->d == &dhs_ur5_mm) {
        dhs_ur5_safe_q(15.0, q);
        return;
    }
    for (i = 0; i < 6; i++) q[i] = QP[i] + dht_rand_uniform(-10.0, 10.0);
}

/* 1 when every point of the path at 16 samples has a closed-form solution */
int dhsm_path_reachable(const dhsm_rig *g, const dh_path_q *p, const int32_t *qref)
{
    dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
    dh_frame_q T;
    uint32_t ns = 0;
    int k;
    for (k = 0; k <= 16; k++) {
        DHT_EQ_INT(dh_path_eval_q(p, (dh_q30)(((int64_t)k << 30) / 16), &T), DH_OK);
        if (dh_ikc_q(&g->m, &T, qref, 0u, sol, &ns) != DH_OK || ns == 0u) return 0;
    }
    return 1;
}
