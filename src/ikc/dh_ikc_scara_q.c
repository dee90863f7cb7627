/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_ikc_scara_q.c - closed-form IK, fixed point, integer only (no float,
 * libm or 64-bit division; tools/check.sh guards): R-R-P-R with four
 * parallel axes (DH_IKC_SCARA), detector and solver behind the front end
 * dh_ikc_q.c; interface in ikc_impl.h. The algebra is that of the float
 * solver (dh_ikc_scara.c, docs/design.md "Closed-form inverse kinematics:
 * axes 2-3-4 parallel and SCARA"); the formats, ranges and tolerances
 * (counted in LSB) are those of dh_ikc_q.c.
 *
 * SCARA: psi = atan2(x4y, x4x); the frame 3 origin p3 = p - a4 x4 - d4 z'
 * gives the 2R (a1, |b|) with eta = s1 t2 + delta, t1 = atan2(A py - B px,
 * A px + B py), A = a1 + |b| cos eta, B = |b| sin eta;
 * d3 = s12 (pz - d1 - s1 d2); t4 = s123 (psi - t1 - (eta - delta) - g).
 *
 * Stack: as dh_ikc_q.c, the state lives in the solution array and the
 * solver calls one helper at a time.
 */
#include "dhmath/frame.h"
#include "dhmath/trig.h"
#include "ikc_impl.h"
#include "../internal/dh_qmath.h"

/* wrist singular / SCARA tilt: 2^11 LSB of Q2.30 (1.9e-6) */
#define SCARAQ_SING ((int32_t)1 << 11)
/* on axis 1: within 16 LSB */
#define SCARAQ_SING_AXIS 16
#define SCARAQ_POS_LIM ((int64_t)1 << 30)

/* ======================================================================
 * DH_IKC_SCARA: detector. Structure as the float one: R-R-P-R, alpha1,
 * alpha2, alpha3 in {0, 180}, a1 != 0, |b| != 0 for the effective second
 * link b = (a2 + a3 cos g, a3 sin g), g = s12 theta3.
 * ====================================================================== */

/* m->k layout, SCARA */
#define S_S1 0    /* sign of ca1 */
#define S_S12 1   /* sign of ca1 ca2 */
#define S_S123 2  /* sign of ca1 ca2 ca3 */
#define S_LB 3    /* |b|, dh_qpos */
#define S_DELTA 4 /* atan2(by, bx), Q16.16 deg */
#define S_Z0 5    /* d1 + s1 d2 */
#define S_G 6     /* g = s12 theta3, Q16.16 deg */
#define S_P 7     /* 7..9: (a4, d4 sa4, d4 ca4) */

int dh_ikc_detect_scara_q_(dh_ikc_model_q *m)
{
    int32_t *k = m->k;
    int32_t sg, cg, bx, by;
    int64_t z0;
    if (m->n != 4u || m->prismatic != 0x4u) return 0;
    if (!dh_ikc_small_q_(m->sa[0]) || !dh_ikc_small_q_(m->sa[1]) || !dh_ikc_small_q_(m->sa[2])) return 0;
    k[S_S1] = dh_ikc_sign_q_(m->ca[0]);
    k[S_S12] = k[S_S1] * dh_ikc_sign_q_(m->ca[1]);
    k[S_S123] = k[S_S12] * dh_ikc_sign_q_(m->ca[2]);
    /* the prismatic joint's fixed theta, any int32: reduced to (-180, 180] */
    {
        const uint32_t a = dh_q_abs_u32(m->off[2]) % (uint32_t)DH_IKC_Q16_360;
        int32_t g = (int32_t)a;
        if ((m->off[2] < 0) != (k[S_S12] < 0)) g = -g;
        k[S_G] = dh_ikc_wrap180_q_(g);
    }
    dh_sincos_q(k[S_G], &sg, &cg);
    bx = m->a[1] + dh_ikc_r30_q_(dh_q_mul64(m->a[2], cg));
    by = dh_ikc_r30_q_(dh_q_mul64(m->a[2], sg));
    k[S_LB] = (int32_t)dh_q_isqrt62((uint64_t)dh_q_mla64(dh_q_mul64(bx, bx), by, by));
    if (m->a[0] == 0 || k[S_LB] == 0) return 0;
    k[S_DELTA] = dh_ikc_atan2_q_(by, bx);
    z0 = (int64_t)m->d[0] + k[S_S1] * (int64_t)m->d[1];
    if (dh_ikc_abs64_q_(z0) > (uint64_t)SCARAQ_POS_LIM) return 0;
    k[S_Z0] = (int32_t)z0;
    return dh_ikc_accept_q_(m, DH_IKC_SCARA, 3u, &k[S_P]);
}

/* x4 into sol[2].q[0..2], z' into sol[2].q[3..5], p3 into sol[3].q[0..2]
 * (slots 2 and 3 never hold a SCARA solution); 1 on overflow, -1 when the
 * tool axis is not parallel to the joint axes */
static DH_NOINLINE int scaraq_vecs(const dh_ikc_model_q *m, dh_ikc_sol_q *sol)
{
    const int32_t *k = m->k;
    const int32_t *c0 = DH_IKC_T06_COL_(sol, 0u), *c1 = DH_IKC_T06_COL_(sol, 1u), *c2 = DH_IKC_T06_COL_(sol, 2u);
    const int32_t *p = DH_IKC_T06_COL_(sol, 3u);
    int32_t *x = sol[2].q, *z = &sol[2].q[3], *o = sol[3].q;
    int64_t v;
    unsigned i;
    for (i = 0; i < 3u; i++) {
        x[i] = c0[i];
        z[i] = dh_ikc_r30_q_(dh_ikc_mla_q_(dh_ikc_mla_q_(0, m->sa[3], c1[i]), m->ca[3], c2[i]));
        v = dh_ikc_mla_q_(dh_ikc_mla_q_(dh_ikc_mla_q_(0, k[S_P], c0[i]), k[S_P + 1], c1[i]), k[S_P + 2], c2[i]);
        v = (int64_t)p[i] - ((v + DH_Q_HALF30) >> 30);
        if (dh_ikc_abs64_q_(v) > (uint64_t)SCARAQ_POS_LIM) return 1;
        o[i] = (int32_t)v;
    }
    if (dh_q_abs_u32(z[0]) > (uint32_t)SCARAQ_SING || dh_q_abs_u32(z[1]) > (uint32_t)SCARAQ_SING) return -1;
    if ((z[2] < 0) != (k[S_S123] < 0)) return -1;
    v = (int64_t)o[2] - k[S_Z0];
    if (k[S_S12] < 0) v = -v;
    if (dh_ikc_abs64_q_(v) > (uint64_t)SCARAQ_POS_LIM) return 1;
    o[3] = (int32_t)v; /* d3 */
    o[4] = 0;
    (void)dh_atan2_q(x[1], x[0], &o[4]); /* psi */
    return 0;
}

/* elbow branch e into slot e (pair (S, Kd) and eta in sol[3].q[5],
 * sol[2].q[0..1] free after psi) */
static DH_NOINLINE void scaraq_branch(const dh_ikc_model_q *m, dh_ikc_sol_q *sol, unsigned e, uint32_t f, int32_t cref0)
{
    const int32_t *k = m->k;
    const int32_t *o = sol[3].q;
    int32_t *w = sol[2].q; /* w[0..1] the pair, w[2] eta, w[3..4] sin/cos eta */
    dh_ikc_sol_q *r = &sol[e];
    int32_t A, B, t1, b;
    w[3] = dh_ikc_wrap180_q_(e ? -w[2] : w[2]);
    r->flags = f | (e ? DH_IKC_ELBOW_ALT : 0u);
    if (dh_q_abs_u32(o[0]) <= (uint32_t)SCARAQ_SING_AXIS && dh_q_abs_u32(o[1]) <= (uint32_t)SCARAQ_SING_AXIS) {
        t1 = cref0;
        r->flags |= DH_IKC_SING_SHOULDER;
    } else {
        int32_t sn, cs;
        dh_sincos_q(w[3], &sn, &cs);
        A = m->a[0] + dh_ikc_r30_q_(dh_q_mul64(k[S_LB], cs));
        B = dh_ikc_r30_q_(dh_q_mul64(k[S_LB], sn));
        t1 = dh_ikc_atan2_q_(dh_q_mul64(A, o[1]) - dh_q_mul64(B, o[0]), dh_q_mla64(dh_q_mul64(A, o[0]), B, o[1]));
    }
    b = dh_ikc_wrap180_q_(w[3] - k[S_DELTA]); /* s1 t2 */
    r->q[0] = t1;
    r->q[1] = k[S_S1] > 0 ? b : dh_ikc_wrap180_q_(-b);
    r->q[2] = o[3];
    A = dh_ikc_wrap180_q_(dh_ikc_wrap180_q_(dh_ikc_wrap180_q_(o[4] - t1) - b) - k[S_G]);
    r->q[3] = k[S_S123] > 0 ? A : dh_ikc_wrap180_q_(-A);
    r->q[4] = 0;
    r->q[5] = 0;
}

dh_status dh_ikc_scara_q_(const dh_ikc_model_q *m, const int32_t *q_ref, dh_ikc_sol_q *sol, uint32_t *count)
{
    int st;
    unsigned ne, e;
    uint32_t f = 0u;
    *count = 0;
    st = scaraq_vecs(m, sol);
    if (st > 0) return DH_ERR_OVERFLOW;
    if (st < 0) return DH_OK;
    ne = dh_ikc_elbow_q_(m->a[0], m->k[S_LB], sol[3].q[0], sol[3].q[1], sol[2].q);
    if (ne == 0u) return DH_OK;
    if (ne == 1u) f = DH_IKC_SING_ELBOW;
    sol[2].q[2] = 0;
    (void)dh_atan2_q(sol[2].q[0], sol[2].q[1], &sol[2].q[2]);
    for (e = 0; e < ne; e++) scaraq_branch(m, sol, e, f, dh_ikc_cref_q_(m, q_ref, 0u));
    *count = ne;
    return DH_OK;
}
