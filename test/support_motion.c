/* SPDX-License-Identifier: Apache-2.0 */
/*
 * support_motion.c - shared helpers of the float queue tests (contract in
 * support_motion.h), in double.
 */
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "dht.h"
#include "support_motion.h"

#define REL DHM_REL
#define ANG_NOISE DHM_ANG_NOISE
#define RAD2DEG DHM_RAD2DEG

double dhm_dist3(const double a[3], const double b[3])
{
    const double d[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
    return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

double dhm_seg_dist(const float a[3], const float b[3], const double x[3])
{
    double d[3], r[3], dd = 0.0, s = 0.0, e[3];
    int i;
    for (i = 0; i < 3; i++) {
        d[i] = (double)b[i] - a[i];
        r[i] = x[i] - a[i];
        dd += d[i] * d[i];
        s += r[i] * d[i];
    }
    s = (dd > 0.0) ? s / dd : 0.0;
    s = fmin(fmax(s, 0.0), 1.0);
    for (i = 0; i < 3; i++) e[i] = r[i] - s * d[i];
    return sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
}

double dhm_arc_dist(const dh_path_f32 *p, const double x[3])
{
    double r[3], n[3], u[3], w[3], z = 0.0, nn = 0.0, rho = 0.0, rr = 0.0, ph, e[2], sw;
    int i;
    DHT_TRUE(p != NULL && p->kind == (uint32_t)DH_PATH_ARC);
    if (p == NULL) return INFINITY;
    sw = (double)p->sweep / RAD2DEG;
    for (i = 0; i < 3; i++) nn += (double)p->n[i] * p->n[i];
    for (i = 0; i < 3; i++) {
        n[i] = p->n[i] / sqrt(nn);
        u[i] = p->u0[i];
        r[i] = x[i] - ((double)p->A.m[3][i] - u[i]);
        z += r[i] * n[i];
        rho += u[i] * u[i];
    }
    rho = sqrt(rho);
    for (i = 0; i < 3; i++) {
        r[i] -= z * n[i];
        rr += r[i] * r[i];
    }
    w[0] = n[1] * u[2] - n[2] * u[1];
    w[1] = n[2] * u[0] - n[0] * u[2];
    w[2] = n[0] * u[1] - n[1] * u[0];
    ph = atan2(r[0] * w[0] + r[1] * w[1] + r[2] * w[2], r[0] * u[0] + r[1] * u[1] + r[2] * u[2]);
    if (ph < -0.5 * (2.0 * 3.14159265358979323846 - sw)) ph += 2.0 * 3.14159265358979323846;
    if (ph >= 0.0 && ph <= sw) {
        e[0] = z;
        e[1] = sqrt(rr) - rho;
        return sqrt(e[0] * e[0] + e[1] * e[1]);
    }
    for (i = 0; i < 3; i++) r[i] = x[i] - ((ph < 0.0) ? p->A.m[3][i] : p->B.m[3][i]);
    return sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
}

void dhm_quat_of(const dh_mat4_f32 *T, double q[4])
{
    double R[3][3], tr, s, n;
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) R[i][j] = T->m[j][i];
    tr = R[0][0] + R[1][1] + R[2][2];
    if (tr > 0.0) {
        s = 2.0 * sqrt(1.0 + tr);
        q[0] = 0.25 * s;
        q[1] = (R[2][1] - R[1][2]) / s;
        q[2] = (R[0][2] - R[2][0]) / s;
        q[3] = (R[1][0] - R[0][1]) / s;
    } else if (R[0][0] > R[1][1] && R[0][0] > R[2][2]) {
        s = 2.0 * sqrt(1.0 + R[0][0] - R[1][1] - R[2][2]);
        q[0] = (R[2][1] - R[1][2]) / s;
        q[1] = 0.25 * s;
        q[2] = (R[0][1] + R[1][0]) / s;
        q[3] = (R[0][2] + R[2][0]) / s;
    } else if (R[1][1] > R[2][2]) {
        s = 2.0 * sqrt(1.0 + R[1][1] - R[0][0] - R[2][2]);
        q[0] = (R[0][2] - R[2][0]) / s;
        q[1] = (R[0][1] + R[1][0]) / s;
        q[2] = 0.25 * s;
        q[3] = (R[1][2] + R[2][1]) / s;
    } else {
        s = 2.0 * sqrt(1.0 + R[2][2] - R[0][0] - R[1][1]);
        q[0] = (R[1][0] - R[0][1]) / s;
        q[1] = (R[0][2] + R[2][0]) / s;
        q[2] = (R[1][2] + R[2][1]) / s;
        q[3] = 0.25 * s;
    }
    n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (i = 0; i < 4; i++) q[i] /= n;
}

void dhm_rotvec(const float *qa, const float *qb, double v[3])
{
    /* qb * conj(qa) */
    const double w = (double)qb[0] * qa[0] + (double)qb[1] * qa[1] + (double)qb[2] * qa[2] + (double)qb[3] * qa[3];
    double x[3], n, th;
    int i;
    x[0] = -(double)qb[0] * qa[1] + (double)qb[1] * qa[0] - (double)qb[2] * qa[3] + (double)qb[3] * qa[2];
    x[1] = -(double)qb[0] * qa[2] + (double)qb[1] * qa[3] + (double)qb[2] * qa[0] - (double)qb[3] * qa[1];
    x[2] = -(double)qb[0] * qa[3] - (double)qb[1] * qa[2] + (double)qb[2] * qa[1] + (double)qb[3] * qa[0];
    n = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    th = 2.0 * atan2(n, fabs(w));
    for (i = 0; i < 3; i++) v[i] = (n > 0.0) ? ((w < 0.0) ? -1.0 : 1.0) * th * x[i] / n * RAD2DEG : 0.0;
}

int dhm_draw_via(const float a[3], const float b[3], float via[3])
{
    double d[3], e[3], h = 0.0, c = 0.0, x;
    int i;
    for (i = 0; i < 3; i++) {
        d[i] = (double)b[i] - a[i];
        c += d[i] * d[i];
    }
    if (dht_rand_u32() % 2u == 0u || c < 1e-4) return 0;
    do {
        for (i = 0; i < 3; i++) e[i] = dht_rand_uniform(-1.0, 1.0);
        x = (e[0] * d[0] + e[1] * d[1] + e[2] * d[2]) / c;
        h = 0.0;
        for (i = 0; i < 3; i++) {
            e[i] -= x * d[i];
            h += e[i] * e[i];
        }
    } while (h < 0.01);
    x = dht_rand_uniform(0.1, 0.4) * sqrt(c / h);
    for (i = 0; i < 3; i++) via[i] = (float)(0.5 * ((double)a[i] + b[i]) + x * e[i]);
    return 1;
}

void dhm_draw_q(const dh_robot *r, const float *qp, double step, float *q)
{
    uint32_t i;
    for (i = 0; i < r->n; i++) {
        const dh_joint *j = &r->joint[i];
        double v = qp[i] + dht_rand_uniform(-step, step);
        if (j->qmin <= j->qmax) v = fmin(fmax(v, j->qmin + 5.0), j->qmax - 5.0);
        q[i] = (float)v;
    }
}

void dhm_push(float (*h)[7], int n)
{
    int m;
    for (m = n - 1; m > 0; m--) memcpy(h[m], h[m - 1], sizeof h[0]);
}

void dhm_sample(const dh_mat4_f32 *T, float h[7])
{
    double q[4];
    int k;
    dhm_quat_of(T, q);
    for (k = 0; k < 3; k++) h[k] = T->m[3][k];
    for (k = 0; k < 4; k++) h[3 + k] = (float)q[k];
}

void dhm_check_speed(const float *h0, const float *h1, double hdt, const dh_cart_limits_f32 *lim, double ulp,
                        long call)
{
    double p0[3], p1[3], a[3], x;
    int k;
    for (k = 0; k < 3; k++) {
        p0[k] = h0[k];
        p1[k] = h1[k];
    }
    x = dhm_dist3(p0, p1);
    DHT_TRUE_MSG(x <= (double)lim->vmax * hdt * (1.0 + REL) + 4.0 * ulp, "call %ld: speed %.9g over %.9g (%.3g s)",
                 call, x / hdt, (double)lim->vmax, hdt);
    dhm_rotvec(&h1[3], &h0[3], a);
    x = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    DHT_TRUE_MSG(x <= (double)lim->wmax * hdt * (1.0 + REL) + ANG_NOISE, "call %ld: angular speed %.9g over %.9g",
                 call, x / hdt, (double)lim->wmax);
}

void dhm_check_acc(const float (*h)[7], int w, double hdt, const dh_cart_limits_f32 *lim, double ulp, long call)
{
    double a[3], b[3], x;
    int k;
    for (k = 0; k < 3; k++) a[k] = (double)h[0][k] - 2.0 * h[w][k] + h[2 * w][k];
    x = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    DHT_TRUE_MSG(x <= (double)lim->amax * hdt * hdt * (1.0 + REL) + 8.0 * ulp,
                 "call %ld: acceleration %.9g over %.9g (%.3g s)", call, x / (hdt * hdt), (double)lim->amax, hdt);
    dhm_rotvec(&h[w][3], &h[0][3], a);
    dhm_rotvec(&h[w][3], &h[2 * w][3], b);
    for (k = 0; k < 3; k++) a[k] += b[k];
    x = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    DHT_TRUE_MSG(x <= (double)lim->wdmax * hdt * hdt * (1.0 + REL) + 2.0 * ANG_NOISE,
                 "call %ld: angular acceleration %.9g over %.9g (%.3g s)", call, x / (hdt * hdt), (double)lim->wdmax,
                 hdt);
}

void dhm_line_arc(dh_path_f32 *line, dh_path_f32 *arc)
{
    dh_mat4_f32 A, B;
    const float v[3] = { 0.3f, 0.1f, 0.2f };
    memset(&A, 0, sizeof A);
    A.m[0][0] = A.m[1][1] = A.m[2][2] = A.m[3][3] = 1.0f;
    B = A;
    A.m[3][0] = 0.2f;
    B.m[3][0] = 0.4f;
    B.m[3][1] = 0.2f;
    DHT_EQ_INT(dh_path_line_f32(line, &A, &B), DH_OK);
    DHT_EQ_INT(dh_path_arc_f32(arc, &A, v, &B), DH_OK);
}

int dhm_check_corner(const dh_queue_f32 *qu, const dh_mat4_f32 *T, uint32_t n, const float (*cp)[3],
                     const float *radius, double S, long call, uint32_t *k, double x[3])
{
    const double tol = 1e-6 + 8.0 * FLT_EPSILON * S;
    double c[3], d;
    int i;
    *k = (qu->seq < n) ? qu->seq : n - 1u;
    for (i = 0; i < 3; i++) {
        x[i] = T->m[3][i];
        c[i] = cp[*k + 1u][i];
    }
    if (qu->bmode != 2u) return 0;
    d = dhm_dist3(x, c);
    DHT_TRUE_MSG(*k + 1u < n && d <= (double)radius[*k] + tol, "call %ld: %.9g from corner %u, radius %.9g", call, d,
                 (unsigned)*k, (double)radius[*k]);
    return 1;
}

void dhm_check_jerk(const float (*h)[7], int w, double hdt, const dh_cart_jerk_f32 *jk, double ulp, long call,
                    double worst[2])
{
    double a[3], b[3], c[3], x, h3 = hdt * hdt * hdt;
    int k;
    for (k = 0; k < 3; k++) a[k] = (double)h[0][k] - 3.0 * h[w][k] + 3.0 * h[2 * w][k] - h[3 * w][k];
    x = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    if (x / h3 / (double)jk->jmax > worst[0]) worst[0] = x / h3 / (double)jk->jmax;
    DHT_TRUE_MSG(x <= (double)jk->jmax * h3 * (1.0 + DHM_REL) + 8.0 * ulp, "call %ld: jerk %.9g over %.9g", call,
                 x / h3, (double)jk->jmax);
    /* rotation vectors relative to h[w]: along one move they are one axis
     * times the angle (a fixed world axis) */
    dhm_rotvec(&h[w][3], &h[0][3], a);
    dhm_rotvec(&h[w][3], &h[2 * w][3], b);
    dhm_rotvec(&h[w][3], &h[3 * w][3], c);
    for (k = 0; k < 3; k++) a[k] = a[k] + 3.0 * b[k] - c[k];
    x = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    if (x / h3 / (double)jk->wjmax > worst[1]) worst[1] = x / h3 / (double)jk->wjmax;
    DHT_TRUE_MSG(x <= (double)jk->wjmax * h3 * (1.0 + DHM_REL) + 8.0 * DHM_ANG_NOISE,
                 "call %ld: angular jerk %.9g over %.9g", call, x / h3, (double)jk->wjmax);
}

uint64_t dhm_hash(const void *a, size_t na, const void *b, size_t nb)
{
    const unsigned char *x = (const unsigned char *)a;
    uint64_t h = 14695981039346656037ull;
    size_t i;
    for (i = 0; i < na; i++) h = (h ^ x[i]) * 1099511628211ull;
    x = (const unsigned char *)b;
    for (i = 0; i < nb; i++) h = (h ^ x[i]) * 1099511628211ull;
    return h;
}

const dhm_robot_case dhm_puma560 = { &dhs_puma560_m, { 10.0, -30.0, 45.0, 20.0, 35.0, -60.0 }, 1 };
const dhm_robot_case dhm_ur5 = { &dhs_ur5_m, { 30.0, -80.0, 90.0, -100.0, -90.0, 20.0 }, 1 };
const dhm_robot_case dhm_panda = { &dhs_panda_m, { 0.0, -30.0, 0.0, -120.0, 0.0, 90.0, 45.0 }, 0 };

void dhm_rig_make(dhm_rig *g, const dhm_robot_case *c)
{
    uint32_t i;
    DHT_EQ_INT(dhs_build(c->d, &g->r), DH_OK);
    for (i = 0; i < g->r.n; i++) DHT_EQ_INT(dh_robot_set_rates_f32(&g->r, i, 180.0f, 3000.0f), DH_OK);
    g->closed = c->closed;
    if (c->closed) DHT_EQ_INT(dh_ikc_analyse_f32(&g->r, &g->m), DH_OK);
}

int dhm_fd_push(dhm_fd *f, const dh_mat4_f32 *T, const dh_cart_limits_f32 *lim, double ulp, long call)
{
    dhm_push(f->sp, f->ns);
    dhm_sample(T, f->sp[0]);
    f->nh++;
    if (f->nh >= 2) dhm_check_speed(f->sp[0], f->sp[1], f->dt, lim, ulp, call);
    if (f->nh >= f->ns) dhm_check_acc((const float (*)[7])f->sp, f->ws, (double)f->ws * f->dt, lim, ulp, call);
    if ((f->nh - 1) % f->wd != 0) return 0;
    dhm_push(f->lp, f->nl);
    memcpy(f->lp[0], f->sp[0], sizeof f->lp[0]);
    if (f->nh < (long)(2 * f->w / f->wd) * f->wd + 1) return 1;
    dhm_check_speed(f->lp[0], f->lp[f->w / f->wd], (double)f->w * f->dt, lim, ulp, call);
    dhm_check_acc((const float (*)[7])f->lp, f->w / f->wd, (double)f->w * f->dt, lim, ulp, call);
    return 1;
}

void dhm_draw_limits(dh_cart_limits_f32 *lim, dh_cart_jerk_f32 *jk)
{
    lim->vmax = (float)dht_rand_uniform(0.05, 0.2);
    lim->amax = (float)dht_rand_uniform(0.3, 2.0);
    lim->wmax = (float)dht_rand_uniform(15.0, 60.0);
    lim->wdmax = (float)dht_rand_uniform(60.0, 600.0);
    if (jk != NULL) {
        jk->jmax = (float)dht_rand_uniform(1.0, 20.0);
        jk->wjmax = (float)dht_rand_uniform(300.0, 6000.0);
    }
}
