/* SPDX-License-Identifier: Apache-2.0 */
/*
 * support_robots.c - shipped robot descriptions and the double-precision
 * reference forward kinematics (see support_robots.h for sources).
 */
#include "support_robots.h"
#include "dh_robots.h"
#include "dht.h"

#include <math.h>
#include <stdio.h>


/* The tables: examples/robots/ *.dh, turned into macros at build time by
 * tools/gen_robots.py (panda_mm is panda.dh with lengths times 1000). */
#define DHS_JOINT(type, a, d, alpha, theta, qmin, qmax) { type, a, d, alpha, theta, qmin, qmax },
#define DHS_ROBOT(R) { DHR_##R##_NAME, DHR_##R##_CONV, DHR_##R##_N, DHR_##R##_UNIT_PER_M, \
                       { DHR_##R##_JOINTS(DHS_JOINT) }, DHR_##R##_BASE, DHR_##R##_TOOL }

const dhs_robot dhs_puma560_m = DHS_ROBOT(PUMA560);
const dhs_robot dhs_puma560_mm = DHS_ROBOT(PUMA560_MM);
const dhs_robot dhs_ur5_m = DHS_ROBOT(UR5);
const dhs_robot dhs_ur5_mm = DHS_ROBOT(UR5_MM);
const dhs_robot dhs_panda_m = DHS_ROBOT(PANDA);
const dhs_robot dhs_panda_mm = DHS_ROBOT(PANDA_MM);
const dhs_robot dhs_ur3_m = DHS_ROBOT(UR3);
const dhs_robot dhs_ur3_mm = DHS_ROBOT(UR3_MM);
const dhs_robot dhs_ur10_m = DHS_ROBOT(UR10);
const dhs_robot dhs_ur10_mm = DHS_ROBOT(UR10_MM);
const dhs_robot dhs_cobra600_m = DHS_ROBOT(COBRA600);
const dhs_robot dhs_cobra600_mm = DHS_ROBOT(COBRA600_MM);
const dhs_robot dhs_kuka_kr5_m = DHS_ROBOT(KUKA_KR5);
const dhs_robot dhs_kuka_kr5_mm = DHS_ROBOT(KUKA_KR5_MM);
const dhs_robot dhs_abb_irb140_m = DHS_ROBOT(ABB_IRB140);
const dhs_robot dhs_abb_irb140_mm = DHS_ROBOT(ABB_IRB140_MM);
const dhs_robot dhs_stanford_m = DHS_ROBOT(STANFORD);
const dhs_robot dhs_stanford_mm = DHS_ROBOT(STANFORD_MM);

/* ------------------------------------------------------------------------ */

void dhs_link(dh_convention conv, dh_joint_type type, double a, double d,
              double alpha_deg, double theta_deg, double q, dhr_mat4 *A)
{
    dhr_mat4 rz, tz, tx, rx;
    double theta = theta_deg, dd = d;
    if (type == DH_JOINT_REVOLUTE) theta += q; else dd += q;
    dhr_rotz(theta, &rz);
    dhr_trans(0, 0, dd, &tz);
    dhr_trans(a, 0, 0, &tx);
    dhr_rotx(alpha_deg, &rx);
    if (conv == DH_CONV_STANDARD) {          /* Rz Tz Tx Rx */
        dhr_mul(&rz, &tz, A);
        dhr_mul(A, &tx, A);
        dhr_mul(A, &rx, A);
    } else {                                 /* Rx Tx Rz Tz */
        dhr_mul(&rx, &tx, A);
        dhr_mul(A, &rz, A);
        dhr_mul(A, &tz, A);
    }
}

void dhs_fk_desc(const dhs_robot *d, const double *q, dhr_mat4 *frames, dhr_mat4 *T)
{
    dhr_mat4 acc = d->base, A;
    unsigned i;
    for (i = 0; i < d->n; i++) {
        const dhs_joint_desc *j = &d->j[i];
        dhs_link(d->conv, j->type, j->a, j->d, j->alpha_deg, j->theta_deg, q[i], &A);
        dhr_mul(&acc, &A, &acc);
        if (frames) frames[i] = acc;
    }
    if (T) dhr_mul(&acc, &d->tool, T);
}

void dhs_fk_ref_f32(const dh_robot *r, const double *q, dhr_mat4 *frames, dhr_mat4 *T)
{
    dhr_mat4 acc, A, tool;
    uint32_t i;
    dhr_from_f32(&r->base, &acc);
    for (i = 0; i < r->n; i++) {
        const dh_joint *j = &r->joint[i];
        dhs_link(r->conv, j->type, (double)j->a, (double)j->d, (double)j->alpha_deg,
                 (double)j->theta_deg, q[i], &A);
        dhr_mul(&acc, &A, &acc);
        if (frames) frames[i] = acc;
    }
    if (T) {
        dhr_from_f32(&r->tool, &tool);
        dhr_mul(&acc, &tool, T);
    }
}

void dhs_fk_ref_q(const dh_robot *r, const int32_t *q, dhr_mat4 *frames, dhr_mat4 *T)
{
    dhr_mat4 acc, A, tool;
    uint32_t i;
    dhr_from_q(&r->base_q, &acc);
    for (i = 0; i < r->n; i++) {
        const dh_joint *j = &r->joint[i];
        double qv = (j->type == DH_JOINT_REVOLUTE) ? ldexp((double)q[i], -16)
                                                    : ldexp((double)q[i], -DH_QPOS_FRAC);
        dhs_link(r->conv, j->type, ldexp((double)j->a_q, -DH_QPOS_FRAC),
                 ldexp((double)j->d_q, -DH_QPOS_FRAC), ldexp((double)j->alpha_q, -16),
                 ldexp((double)j->theta_q, -16), qv, &A);
        dhr_mul(&acc, &A, &acc);
        if (frames) frames[i] = acc;
    }
    if (T) {
        dhr_from_q(&r->tool_q, &tool);
        dhr_mul(&acc, &tool, T);
    }
}

/* ------------------------------------------------------------------------ */

void dhs_to_frame_q(const dhr_mat4 *D, dh_frame_q *F)
{
    int c, r;
    for (c = 0; c < 3; c++)
        for (r = 0; r < 3; r++) F->r[c][r] = dhs_to_q(D->m[c][r], 30);
    for (r = 0; r < 3; r++) F->p[r] = dhs_to_q(D->m[3][r], DH_QPOS_FRAC);
}

/* twin: dhs_build_q */
dh_status dhs_build(const dhs_robot *d, dh_robot *r)
{
    dh_mat4_f32 T;
    dh_status st;
    unsigned i;
    st = dh_robot_init(r, d->conv);
    if (st != DH_OK) return st;
    if (d->n > DH_MAX_JOINTS) return DH_ERR_ARG;
    for (i = 0; i < d->n; i++) {
        const dhs_joint_desc *j = &d->j[i];
        st = dh_robot_add_joint_f32(r, j->type, (float)j->theta_deg, (float)j->d, (float)j->a,
                                    (float)j->alpha_deg);
        if (st != DH_OK) return st;
        if (j->qmin <= j->qmax) {
            st = dh_robot_set_limits_f32(r, i, (float)j->qmin, (float)j->qmax);
            if (st != DH_OK) return st;
        }
    }
    dhr_to_f32(&d->base, &T);
    st = dh_robot_set_base_f32(r, &T);
    if (st != DH_OK) return st;
    dhr_to_f32(&d->tool, &T);
    return dh_robot_set_tool_f32(r, &T);
}

/* twin: dhs_build */
dh_status dhs_build_q(const dhs_robot *d, dh_robot *r)
{
    dh_frame_q F;
    dh_status st;
    unsigned i;
    st = dh_robot_init(r, d->conv);
    if (st != DH_OK) return st;
    if (d->n > DH_MAX_JOINTS) return DH_ERR_ARG;
    for (i = 0; i < d->n; i++) {
        const dhs_joint_desc *j = &d->j[i];
        st = dh_robot_add_joint_q(r, j->type, dhs_to_q(j->theta_deg, 16), dhs_to_q(j->d, DH_QPOS_FRAC),
                                  dhs_to_q(j->a, DH_QPOS_FRAC), dhs_to_q(j->alpha_deg, 16));
        if (st != DH_OK) return st;
        if (j->qmin <= j->qmax) {
            int frac = (j->type == DH_JOINT_REVOLUTE) ? 16 : DH_QPOS_FRAC;
            st = dh_robot_set_limits_q(r, i, dhs_to_q(j->qmin, frac), dhs_to_q(j->qmax, frac));
            if (st != DH_OK) return st;
        }
    }
    dhs_to_frame_q(&d->base, &F);
    st = dh_robot_set_base_q(r, &F);
    if (st != DH_OK) return st;
    dhs_to_frame_q(&d->tool, &F);
    return dh_robot_set_tool_q(r, &F);
}

void dhs_random_q(const dhs_robot *d, double *q)
{
    unsigned i;
    for (i = 0; i < d->n; i++) {
        const dhs_joint_desc *j = &d->j[i];
        if (j->qmin <= j->qmax) q[i] = dht_rand_uniform(j->qmin, j->qmax);
        else if (j->type == DH_JOINT_REVOLUTE) q[i] = dht_rand_uniform(-180.0, 180.0);
        else q[i] = dht_rand_uniform(-1.0, 1.0);
    }
}

void dhs_random_q_robot(const dh_robot *r, double *q)
{
    uint32_t i;
    for (i = 0; i < r->n; i++) {
        const dh_joint *j = &r->joint[i];
        if (j->qmin <= j->qmax) q[i] = dht_rand_uniform((double)j->qmin, (double)j->qmax);
        else if (j->type == DH_JOINT_REVOLUTE) q[i] = dht_rand_uniform(-180.0, 180.0);
        else q[i] = dht_rand_uniform(-1.0, 1.0);
    }
}

void dhs_ur5_safe_q(double margin, double *q)
{
    int k;
    for (k = 0; k < DH_MAX_JOINTS; k++) q[k] = 0.0;
    q[0] = dht_rand_uniform(-170.0, 170.0);
    q[1] = dht_rand_uniform(-140.0 + margin, -40.0 - margin);
    q[2] = dht_rand_uniform(55.0 + margin, 125.0 - margin) * (dht_rand_uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0);
    q[3] = dht_rand_uniform(-170.0, 170.0);
    q[4] = dht_rand_uniform(45.0 + margin, 135.0 - margin) * (dht_rand_uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0);
    q[5] = dht_rand_uniform(-170.0, 170.0);
}

void dhs_target_f32(const dh_robot *r, const double *q, dh_mat4_f32 *T)
{
    dhr_mat4 D;
    dhs_fk_ref_f32(r, q, NULL, &D);
    dhr_to_f32(&D, T);
}

double dhs_joint_dist(const dh_robot *r, uint32_t i, double a, double b)
{
    double d = a - b;
    if (r->joint[i].type == DH_JOINT_REVOLUTE) {
        d = fmod(d, 360.0);
        if (d > 180.0) d -= 360.0;
        if (d < -180.0) d += 360.0;
    }
    return fabs(d);
}

const char *dhs_q_str(const double *q, uint32_t n, int slot)
{
    static char buf[2][DHS_MAX_JOINTS * 26];
    char *o = buf[slot & 1];
    size_t k = 0;
    uint32_t i;
    o[0] = '\0';
    for (i = 0; i < n && i < DHS_MAX_JOINTS; i++)
        k += (size_t)snprintf(o + k, sizeof buf[0] - k, "%s%.17g", i ? " " : "", q[i]);
    return o;
}

const char *dhs_qf_str(const float *q, uint32_t n, int slot)
{
    double d[DHS_MAX_JOINTS];
    uint32_t i;
    for (i = 0; i < n && i < DHS_MAX_JOINTS; i++) d[i] = (double)q[i];
    return dhs_q_str(d, n, slot);
}

double dhs_chain_reach(const dhs_robot *d, const double *q)
{
    double L = 0.0;
    unsigned i;
    for (i = 0; i < 3; i++) L += fabs(d->base.m[3][i]) + fabs(d->tool.m[3][i]);
    for (i = 0; i < d->n; i++) {
        L += fabs(d->j[i].a) + fabs(d->j[i].d);
        if (d->j[i].type == DH_JOINT_PRISMATIC) L += fabs(q[i]);
    }
    return L > 1.0 ? L : 1.0;
}

int32_t dhs_to_q(double x, int frac)
{
    double v = floor(ldexp(x, frac) + 0.5);
    if (v >= 2147483647.0) return INT32_MAX;
    if (v <= -2147483648.0) return INT32_MIN;
    return (int32_t)v;
}

void dhs_q_from_double(const dh_robot *r, const double *q, int32_t *qq)
{
    uint32_t i;
    for (i = 0; i < r->n; i++)
        qq[i] = dhs_to_q(q[i], r->joint[i].type == DH_JOINT_REVOLUTE ? 16 : DH_QPOS_FRAC);
}

double dhs_pos_err_f32(const dh_mat4_f32 *T, const dhr_mat4 *R)
{
    dhr_mat4 D;
    dhr_from_f32(T, &D);
    return dhr_pos_diff(&D, R);
}

double dhs_rot_err_f32(const dh_mat4_f32 *T, const dhr_mat4 *R)
{
    dhr_mat4 D;
    dhr_from_f32(T, &D);
    return dhr_rot_diff(&D, R);
}

int dhs_bottom_ok_f32(const dh_mat4_f32 *T)
{
    return T->m[0][3] == 0.0f && T->m[1][3] == 0.0f && T->m[2][3] == 0.0f && T->m[3][3] == 1.0f;
}

double dhs_pos_err_q(const dh_frame_q *F, const dhr_mat4 *R)
{
    dhr_mat4 D;
    dhr_from_q(F, &D);
    return dhr_pos_diff(&D, R);
}

double dhs_rot_err_q(const dh_frame_q *F, const dhr_mat4 *R)
{
    dhr_mat4 D;
    dhr_from_q(F, &D);
    return dhr_rot_diff(&D, R);
}

double dhs_rot_angle(double R[3][3])
{
    double ux = R[1][2] - R[2][1], uy = R[2][0] - R[0][2], uz = R[0][1] - R[1][0];
    double s = sqrt(ux * ux + uy * uy + uz * uz), c = R[0][0] + R[1][1] + R[2][2] - 1.0;
    return atan2(s, c);
}

void dhs_true_error_f32(const dh_robot *r, const float *q, const dh_mat4_f32 *target, double *ep, double *er)
{
    dhr_mat4 T;
    double qd[DHS_MAX_JOINTS], D[3][3];
    uint32_t i;
    int a, b, k;
    for (i = 0; i < r->n && i < DHS_MAX_JOINTS; i++) qd[i] = (double)q[i];
    dhs_fk_ref_f32(r, qd, NULL, &T);
    *ep = 0;
    for (k = 0; k < 3; k++) {
        double d = (double)target->m[3][k] - T.m[3][k];
        *ep += d * d;
    }
    *ep = sqrt(*ep);
    for (a = 0; a < 3; a++)
        for (b = 0; b < 3; b++) {
            double s = 0;
            for (k = 0; k < 3; k++) s += (double)target->m[k][a] * T.m[k][b];
            D[b][a] = s;
        }
    *er = dhs_rot_angle(D);
}

int dhs_limit_twin_f32(const dh_robot *r, const float *c, const float *qn, double slack_deg, double slack_len)
{
    uint32_t i;
    for (i = 0; i < r->n; i++) {
        const dh_joint *j = &r->joint[i];
        const double slack = (j->type == DH_JOINT_REVOLUTE) ? slack_deg : slack_len;
        const double lo = (double)j->qmin, hi = (double)j->qmax, x = (double)c[i], y = (double)qn[i];
        if (j->qmin > j->qmax) continue;
        if (x < lo && !(lo - x <= slack && y >= lo && y - lo <= slack)) return 0;
        if (x > hi && !(x - hi <= slack && y <= hi && hi - y <= slack)) return 0;
    }
    return 1;
}

double dhs_mirror_twist(double alpha_deg)
{
    if (fabs(alpha_deg) < 1.0) return 180.0;
    if (fabs(fabs(alpha_deg) - 180.0) < 1.0) return 0.0;
    return -alpha_deg;
}
