/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_jacobian_q.c - fixed-point geometric Jacobian (base and tool frame)
 * against an independent double reference, side by side with the float
 * Jacobian of the same robot in mm.
 *
 * The reference is the textbook geometric Jacobian (Spong et al. 2006,
 * ch. 4) evaluated in double from the frames of the double reference FK
 * of support_robots.c on the exact DH tables: column i is [z x (p - o); z]
 * (revolute) or [z; 0] (prismatic) with z, o of frame i-1 (standard DH)
 * or frame i (modified DH). The joint values are Q16.16 degrees whose
 * float copies are exact (multiples of 4 LSB below 2^26 LSB), so both paths see the same
 * configuration.
 */
#include "dht.h"
#include "support_robots.h"
#include "support_canary.h"
#include "dhmath/kin.h"
#include "dhmath/frame.h"

#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846
#define Q30 1073741824.0
#define QPOS ((double)((int32_t)1 << DH_QPOS_FRAC))

/* Reference Jacobian (6 x n row-major) and end rotation R (R[c][k]) of the
 * description d at the joint values q (deg / length). */
static void ref_jac(const dhs_robot *d, const double *q, double *J, double R[3][3])
{
    dhr_mat4 fr[DHS_MAX_JOINTS], T;
    const unsigned n = d->n;
    unsigned i, k;
    dhs_fk_desc(d, q, fr, &T);
    for (i = 0; i < n; i++) {
        const dhr_mat4 *F = (d->conv == DH_CONV_STANDARD) ? (i == 0 ? &d->base : &fr[i - 1]) : &fr[i];
        const double *z = F->m[2], *o = F->m[3];
        double dp[3];
        for (k = 0; k < 3; k++) dp[k] = T.m[3][k] - o[k];
        if (d->j[i].type == DH_JOINT_REVOLUTE) {
            J[0 * n + i] = z[1] * dp[2] - z[2] * dp[1];
            J[1 * n + i] = z[2] * dp[0] - z[0] * dp[2];
            J[2 * n + i] = z[0] * dp[1] - z[1] * dp[0];
            for (k = 0; k < 3; k++) J[(k + 3) * n + i] = z[k];
        } else {
            for (k = 0; k < 3; k++) {
                J[k * n + i] = z[k];
                J[(k + 3) * n + i] = 0.0;
            }
        }
    }
    for (i = 0; i < 3; i++)
        for (k = 0; k < 3; k++) R[i][k] = T.m[i][k];
}

/* Jt = R^T J, both halves of every column. */
static void ref_tool(unsigned n, const double *J, double R[3][3], double *Jt)
{
    unsigned c, h, k;
    for (c = 0; c < n; c++)
        for (h = 0; h < 6; h += 3)
            for (k = 0; k < 3; k++)
                Jt[(h + k) * n + c] = R[k][0] * J[(h + 0) * n + c] + R[k][1] * J[(h + 1) * n + c] +
                                      R[k][2] * J[(h + 2) * n + c];
}

/* Largest error of the linear (rows 0..2) and angular (rows 3..5) rows of
 * a fixed Jacobian (revolute columns: dh_qpos per rad, Q2.30) against Jd. */
static void err_q(const dhs_robot *d, const int32_t *J, const double *Jd, double *el, double *ea)
{
    const unsigned n = d->n;
    unsigned k, c;
    for (k = 0; k < 6; k++)
        for (c = 0; c < n; c++) {
            const int lin = k < 3 && d->j[c].type == DH_JOINT_REVOLUTE;
            const double v = (double)J[k * n + c] / (lin ? QPOS : Q30);
            const double e = fabs(v - Jd[k * n + c]);
            if (k < 3) { if (e > *el) *el = e; } else if (e > *ea) *ea = e;
        }
}

static void err_f(unsigned n, const float *J, const double *Jd, double *el, double *ea)
{
    unsigned k, c;
    for (k = 0; k < 6; k++)
        for (c = 0; c < n; c++) {
            const double e = fabs((double)J[k * n + c] - Jd[k * n + c]);
            if (k < 3) { if (e > *el) *el = e; } else if (e > *ea) *ea = e;
        }
}

/*
 * Bounds. The float Jacobian's linear entries are sums of products of
 * frame entries of magnitude up to the reach L (~1e3 mm), each rounded to
 * float (2^-24 relative), so its error is a few 1e-5 mm: it is measured
 * here on the same configurations, and the fixed error must not exceed it.
 * With a coarser position format (DH_QPOS_FRAC < 16, a build variant) the
 * fixed FK's own resolution dominates: FK about half an LSB of position per
 * joint plus the rounded lengths, so the limit is then also at least
 * 4 n LSB of dh_qpos. The angular rows are the chain's z axes (a few LSB of
 * Q2.30, 1e-8) against float's 1e-7: no such allowance is needed.
 */
static void accuracy(const dhs_robot *d, const char *name)
{
    dh_robot rf, rq;
    double qd[DHS_MAX_JOINTS], Jd[6 * DHS_MAX_JOINTS], Jdt[6 * DHS_MAX_JOINTS], R[3][3];
    int32_t qq[DHS_MAX_JOINTS], Jq[6 * DHS_MAX_JOINTS];
    float qf[DHS_MAX_JOINTS], Jf[6 * DHS_MAX_JOINTS];
    double ql = 0, qa = 0, fl = 0, fa = 0, qlt = 0, qat = 0, flt = 0, fat = 0, lim_l, lim_lt;
    dh_frame_q T, Tfk;
    long it, cnt = DHT_ITER(10000);
    unsigned i;
    DHT_EQ_INT(dhs_build(d, &rf), DH_OK);
    DHT_EQ_INT(dhs_build_q(d, &rq), DH_OK);
    for (it = 0; it < cnt; it++) {
        dhs_random_q(d, qd);
        for (i = 0; i < d->n; i++) {
            /* a multiple of 4 LSB: exact in float up to 1024 deg */
            qq[i] = 4 * dhs_to_q(qd[i], d->j[i].type == DH_JOINT_REVOLUTE ? 14 : DH_QPOS_FRAC - 2);
            qd[i] = (double)qq[i] / (d->j[i].type == DH_JOINT_REVOLUTE ? 65536.0 : QPOS);
            qf[i] = (float)qd[i];
            DHT_TRUE((double)qf[i] == qd[i]);
        }
        ref_jac(d, qd, Jd, R);
        ref_tool(d->n, Jd, R, Jdt);
        DHT_EQ_INT(dh_jacobian_q(&rq, qq, Jq, &T), DH_OK);
        DHT_EQ_INT(dh_fk_q(&rq, qq, &Tfk), DH_OK);
        DHT_TRUE(memcmp(&T, &Tfk, sizeof T) == 0);        /* the FK chain, bit for bit */
        err_q(d, Jq, Jd, &ql, &qa);
        DHT_EQ_INT(dh_jacobian_tool_q(&rq, qq, Jq, NULL), DH_OK);
        err_q(d, Jq, Jdt, &qlt, &qat);
        DHT_EQ_INT(dh_jacobian_f32(&rf, qf, Jf, NULL), DH_OK);
        err_f(d->n, Jf, Jd, &fl, &fa);
        DHT_EQ_INT(dh_jacobian_tool_f32(&rf, qf, Jf, NULL), DH_OK);
        err_f(d->n, Jf, Jdt, &flt, &fat);
    }
    dht_printf("%s (%ld configs): fixed lin %.3g mm ang %.3g | tool %.3g %.3g; float lin %.3g ang %.3g | tool %.3g %.3g\n",
               name, cnt, ql, qa, qlt, qat, fl, fa, flt, fat);
    lim_l = fl;
    lim_lt = flt;
    if (DH_QPOS_FRAC < 16) {
        const double res = 4.0 * d->n / QPOS;
        if (lim_l < res) lim_l = res;
        if (lim_lt < res) lim_lt = res;
    }
    DHT_TRUE_MSG(ql <= lim_l, "%s fixed linear error %.3g > %.3g", name, ql, lim_l);
    DHT_TRUE_MSG(qlt <= lim_lt, "%s fixed tool linear error %.3g > %.3g", name, qlt, lim_lt);
    DHT_TRUE_MSG(qa <= fa, "%s fixed angular error %.3g > float %.3g", name, qa, fa);
    DHT_TRUE_MSG(qat <= fat, "%s fixed tool angular error %.3g > float %.3g", name, qat, fat);
}

static void jacq_puma(void) { accuracy(&dhs_puma560_mm, "puma560_mm"); }
static void jacq_ur5(void) { accuracy(&dhs_ur5_mm, "ur5_mm"); }
static void jacq_panda(void) { accuracy(&dhs_panda_mm, "panda_mm"); }

/* A prismatic joint's column is [z; 0] in Q2.30, for both conventions,
 * and the Jacobian of a planar 2R arm is the textbook one. */
static void jacq_prismatic_planar(void)
{
    dh_robot r;
    int32_t q[3], J[18];
    dh_frame_q T;
    unsigned conv;
    for (conv = 0; conv < 2; conv++) {
        /* 2R planar (a = 300, 200 mm) then a prismatic joint along z */
        const double t1 = dht_rand_uniform(-180, 180), t2 = dht_rand_uniform(-180, 180);
        double a1 = 300, a2 = 200, s1, c1, s12, c12;
        DHT_EQ_INT(dh_robot_init(&r, (dh_convention)conv), DH_OK);
        if (conv == 0) {
            DHT_EQ_INT(dh_robot_add_joint_q(&r, DH_JOINT_REVOLUTE, 0, 0, DH_QPOS(300.0), 0), DH_OK);
            DHT_EQ_INT(dh_robot_add_joint_q(&r, DH_JOINT_REVOLUTE, 0, 0, DH_QPOS(200.0), 0), DH_OK);
            DHT_EQ_INT(dh_robot_add_joint_q(&r, DH_JOINT_PRISMATIC, 0, 0, 0, 0), DH_OK);
        } else {
            DHT_EQ_INT(dh_robot_add_joint_q(&r, DH_JOINT_REVOLUTE, 0, 0, 0, 0), DH_OK);
            DHT_EQ_INT(dh_robot_add_joint_q(&r, DH_JOINT_REVOLUTE, 0, 0, DH_QPOS(300.0), 0), DH_OK);
            DHT_EQ_INT(dh_robot_add_joint_q(&r, DH_JOINT_PRISMATIC, 0, 0, DH_QPOS(200.0), 0), DH_OK);
        }
        q[0] = dhs_to_q(t1, 16);
        q[1] = dhs_to_q(t2, 16);
        q[2] = DH_QPOS(50.0);
        DHT_EQ_INT(dh_jacobian_q(&r, q, J, &T), DH_OK);
        s1 = sin(q[0] / 65536.0 * PI / 180);
        c1 = cos(q[0] / 65536.0 * PI / 180);
        s12 = sin((q[0] + q[1]) / 65536.0 * PI / 180);
        c12 = cos((q[0] + q[1]) / 65536.0 * PI / 180);
        /* sin/cos within 1.05 LSB of Q2.30 times 500 mm (5e-7 mm), plus the
         * position format's own rounding: the FK step and the entry are
         * rounded once each (0.5 LSB), the lengths are exact */
        DHT_NEAR(J[0 * 3 + 0] / QPOS, -a1 * s1 - a2 * s12, 1e-6 + 2.0 / QPOS);
        DHT_NEAR(J[1 * 3 + 0] / QPOS, a1 * c1 + a2 * c12, 1e-6 + 2.0 / QPOS);
        DHT_NEAR(J[0 * 3 + 1] / QPOS, -a2 * s12, 1e-6 + 2.0 / QPOS);
        DHT_NEAR(J[1 * 3 + 1] / QPOS, a2 * c12, 1e-6 + 2.0 / QPOS);
        DHT_EQ_INT(J[2 * 3 + 0], 0);
        DHT_EQ_INT(J[5 * 3 + 0], DH_Q30_ONE);
        DHT_EQ_INT(J[5 * 3 + 1], DH_Q30_ONE);
        /* prismatic: linear z = (0, 0, 1) in Q2.30, angular 0 */
        DHT_EQ_INT(J[0 * 3 + 2], 0);
        DHT_EQ_INT(J[1 * 3 + 2], 0);
        DHT_EQ_INT(J[2 * 3 + 2], DH_Q30_ONE);
        DHT_EQ_INT(J[3 * 3 + 2], 0);
        DHT_EQ_INT(J[4 * 3 + 2], 0);
        DHT_EQ_INT(J[5 * 3 + 2], 0);
        DHT_NEAR(T.p[2] / QPOS, 50.0, 0.0);
    }
}


/* docs/errors.md rows of dh_jacobian_q / dh_jacobian_tool_q. */
static void jacq_bad(void)
{
    dh_robot r;
    int32_t q[DH_MAX_JOINTS], J[6 * DH_MAX_JOINTS];
    dh_frame_q T;
    dh_mat4_f32 B;
    unsigned k, which;
    memset(q, 0, sizeof q);
    for (which = 0; which < 2; which++) {
        dh_status (*jac)(const dh_robot *, const int32_t *, int32_t *, dh_frame_q *) =
            which ? dh_jacobian_tool_q : dh_jacobian_q;
        /* n > DH_MAX_JOINTS, unknown convention, unknown joint type: ARG, untouched */
        DHT_EQ_INT(dhs_build_q(&dhs_puma560_mm, &r), DH_OK);
        r.n = DH_MAX_JOINTS + 1u;
        CANARY(J);
        CANARY(T);
        DHT_EQ_INT(jac(&r, q, J, &T), DH_ERR_ARG);
        UNTOUCHED(J);
        UNTOUCHED(T);
        r.n = 6;
        r.conv = (dh_convention)7;
        DHT_EQ_INT(jac(&r, q, J, &T), DH_ERR_ARG);
        r.conv = DH_CONV_STANDARD;
        r.joint[4].type = (dh_joint_type)9;
        DHT_EQ_INT(jac(&r, q, J, &T), DH_ERR_ARG);
        UNTOUCHED(J);
        UNTOUCHED(T);
        /* fixed path unavailable (a base that does not fit dh_frame_q), also n == 0 */
        DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
        memset(&B, 0, sizeof B);
        for (k = 0; k < 4; k++) B.m[k][k] = 1.0f;
        B.m[3][0] = 1e9f;
        DHT_EQ_INT(dh_robot_set_base_f32(&r, &B), DH_OK);
        DHT_EQ_INT(jac(&r, q, J, &T), DH_ERR_UNAVAILABLE);
        DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0, 0, 100, 0), DH_OK);
        DHT_EQ_INT(jac(&r, q, J, &T), DH_ERR_UNAVAILABLE);
        UNTOUCHED(J);
        UNTOUCHED(T);
        /* 0 joints: OK, J not written, T_end = base * tool */
        DHT_EQ_INT(dh_robot_init(&r, DH_CONV_MODIFIED), DH_OK);
        dh_frame_trans_q(DH_QPOS(1.0), DH_QPOS(2.0), DH_QPOS(3.0), &T);
        DHT_EQ_INT(dh_robot_set_base_q(&r, &T), DH_OK);
        dh_frame_trans_q(DH_QPOS(10.0), 0, 0, &T);
        DHT_EQ_INT(dh_robot_set_tool_q(&r, &T), DH_OK);
        CANARY(J);
        DHT_EQ_INT(jac(&r, q, J, &T), DH_OK);
        UNTOUCHED(J);
        DHT_EQ_INT(T.p[0], DH_QPOS(11.0));
        DHT_EQ_INT(T.p[1], DH_QPOS(2.0));
        DHT_EQ_INT(T.p[2], DH_QPOS(3.0));
    }
}

/* Saturation: a lever arm p_end - o beyond int32 (base at one end of the
 * position range, the end point at the other) saturates the entry with
 * its sign and reports OVF; the other entries are computed normally. */
static void jacq_saturation(void)
{
    dh_robot r;
    int32_t q[2] = { 0, 0 }, J[12];
    dh_frame_q B, T;
    int sgn;
    for (sgn = -1; sgn <= 1; sgn += 2) {
        const int32_t a = (sgn < 0) ? INT32_MAX : -INT32_MAX;
        DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
        dh_frame_trans_q(sgn < 0 ? INT32_MIN : INT32_MAX, 0, 0, &B);
        DHT_EQ_INT(dh_robot_set_base_q(&r, &B), DH_OK);
        /* a = -sgn INT32_MAX twice: p_end = base - 2 sgn INT32_MAX */
        DHT_EQ_INT(dh_robot_add_joint_q(&r, DH_JOINT_REVOLUTE, 0, 0, a, 0), DH_OK);
        DHT_EQ_INT(dh_robot_add_joint_q(&r, DH_JOINT_REVOLUTE, 0, 0, a, 0), DH_OK);
        DHT_EQ_INT(dh_jacobian_q(&r, q, J, &T), DH_ERR_OVERFLOW);
        /* column 0: z x (p_end - base) = (0, p_end - base, 0), |.| = 2^32 - 2 */
        DHT_EQ_INT(J[1 * 2 + 0], sgn < 0 ? INT32_MAX : INT32_MIN);
        DHT_EQ_INT(J[0 * 2 + 0], 0);
        /* column 1: the lever arm -sgn INT32_MAX fits */
        DHT_EQ_INT(J[1 * 2 + 1], a);
        DHT_EQ_INT(J[5 * 2 + 0], DH_Q30_ONE);
        DHT_EQ_INT(T.p[0], sgn < 0 ? INT32_MAX - 1 : -INT32_MAX);
    }
    /* a lever arm beyond int32 along the joint axis: the exact product is 0
     * (no saturation, DH_OK) */
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    dh_frame_trans_q(DH_QPOS(3.0), 0, INT32_MIN, &B);
    DHT_EQ_INT(dh_robot_set_base_q(&r, &B), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_q(&r, DH_JOINT_REVOLUTE, 0, INT32_MAX, 0, 0), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_q(&r, DH_JOINT_REVOLUTE, 0, INT32_MAX, DH_QPOS(2.0), 0), DH_OK);
    DHT_EQ_INT(dh_jacobian_q(&r, q, J, &T), DH_OK);
    DHT_EQ_INT(T.p[2], INT32_MAX - 1);
    /* column 0: z x (2, 0, 2^32 - 2) = (0, 2, 0) mm */
    DHT_EQ_INT(J[0 * 2 + 0], 0);
    DHT_EQ_INT(J[1 * 2 + 0], DH_QPOS(2.0));
    DHT_EQ_INT(J[2 * 2 + 0], 0);
}

/* INT32_MIN entries (a base rotation of -2 entries, any int32 is accepted)
 * are never negated: every entry is the saturated exact value. */
static void jacq_int32_min(void)
{
    dh_robot r;
    int32_t q[1] = { 0 }, J[6];
    dh_frame_q B, T;
    unsigned c, k;
    dh_status st;
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    for (c = 0; c < 3; c++) {
        for (k = 0; k < 3; k++) B.r[c][k] = INT32_MIN;
        B.p[c] = INT32_MIN;
    }
    DHT_EQ_INT(dh_robot_set_base_q(&r, &B), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_q(&r, DH_JOINT_REVOLUTE, 0, 0, 0, 0), DH_OK);
    st = dh_jacobian_q(&r, q, J, &T);
    DHT_TRUE(st == DH_OK || st == DH_ERR_OVERFLOW);
    /* angular rows: the base z axis, copied */
    for (k = 0; k < 3; k++) DHT_EQ_INT(J[3 + k], INT32_MIN);
    /* linear rows: z x (p_end - base p) with the frame as computed */
    for (k = 0; k < 3; k++) {
        const unsigned a = (k + 1) % 3, b = (k + 2) % 3;
        double v = ((double)B.r[2][a] * ((double)T.p[b] - B.p[b]) - (double)B.r[2][b] * ((double)T.p[a] - B.p[a])) / Q30;
        v = floor(v + 0.5);
        if (v > INT32_MAX) v = INT32_MAX;
        if (v < INT32_MIN) v = INT32_MIN;
        DHT_EQ_INT(J[k], (int32_t)v);
    }
    /* tool frame: R^T of the end rotation, saturated with OVF where needed */
    st = dh_jacobian_tool_q(&r, q, J, &T);
    DHT_EQ_INT(st, DH_ERR_OVERFLOW);
    for (k = 0; k < 3; k++) {
        double v = 0;
        for (c = 0; c < 3; c++) v += (double)T.r[k][c] * (double)INT32_MIN;
        v = floor(v / Q30 + 0.5);
        if (v > INT32_MAX) v = INT32_MAX;
        if (v < INT32_MIN) v = INT32_MIN;
        DHT_EQ_INT(J[3 + k], (int32_t)v);
    }
}

static const dht_case cases[] = {
    DHT_CASE(jacq_puma),
    DHT_CASE(jacq_ur5),
    DHT_CASE(jacq_panda),
    DHT_CASE(jacq_prismatic_planar),
    DHT_CASE(jacq_bad),
    DHT_CASE(jacq_saturation),
    DHT_CASE(jacq_int32_min),
};
DHT_MAIN(cases)
