/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_ikc_par234_q.c - closed-form IK, fixed point, integer only (no float,
 * libm or 64-bit division; tools/check.sh guards): six revolute joints with
 * axes 2, 3, 4 parallel (DH_IKC_PARALLEL_234, Universal Robots), detector
 * and solver behind the front end dh_ikc_q.c; interface in ikc_impl.h.
 * The algebra is that of the float solver (dh_ikc_par234.c, docs/design.md
 * "Closed-form inverse kinematics: axes 2-3-4 parallel and SCARA"); the
 * formats, ranges and tolerances (counted in LSB) are those of dh_ikc_q.c.
 *
 * PARALLEL_234, per shoulder branch (u = +-sqrt(px^2 + py^2 - h^2) of the
 * joint 5 point p05 = p - R06 (a6, d6 sa6, d6 ca6)):
 *   t1 = atan2(tau h px + u py, u px - tau h py);
 *   N = R01^T R' (R' = R06 Rx(alpha6)^T): phi = atan2(w5 n23, w5 n13),
 *   s5 = w5 (cphi n13 + sphi n23) >= 0, c5 = -sb w5 n33, t5 = atan2(s5, c5);
 *   m' = Rz(-phi) N e_x: t6 = atan2(-w5 sb m'y, c5 m'x + s5 sb m'z);
 *   flip (phi + 180, -t5, t6 + 180); wrist singular (|n13|, |n23| <= 2^11
 *   LSB): t5 = 0 or 180, t6 = cref6, phi from Rz(phi) (c5 c6, -sb w5 s6) =
 *   (n11, n21), one record.
 *   Per wrist record the planar 2R point v = p1 - a4 (cphi, sphi) -
 *   sb d5 (sphi, -cphi), p1 = (c1 px + s1 py - a1, tau (pz - d1)):
 *   D^2 - K^2 = ((|a2| + |a3|)^2 - |v|^2) (|v|^2 - (|a2| - |a3|)^2) from
 *   exact products, t3 = atan2(+-sqrt(.), K sgn D); A = a2 + a3 c3,
 *   B = s2 a3 s3, t2 = atan2(A vy - B vx, A vx + B vy),
 *   t4 = s23 (phi - t2 - s2 t3).
 *
 * Cost (all 8 UR solutions): atan2 2 (joint 1) + 3 per shoulder (phi, t5,
 * t6) + 3 per wrist record (elbow pair, two t2) = 20; sin/cos 2 (t1) + 2
 * (phi) + 8 (t3) = 12; 2 + 4 integer square roots. The measured cost per
 * call is in docs/generated/performance_target.md.
 *
 * Boundary: a wrist record whose planar point is beyond the 2R's reach
 * is searched for along the shoulder's freedom within the bound B
 * (par234q_band, DH_IKC_BOUND_SH): near the shoulder cylinder the rounding of
 * the target leaves t1 free by up to 1e-3 rad, which moves the planar
 * point by tenths of mm. Such a target is solved with an FK residual
 * within about 2 B (B = 64 LSB, 9.8e-4 mm at DH_QPOS_FRAC 16 in mm); a
 * target farther than that from the workspace stays unreachable. The
 * search costs up to 63 evaluations (t1, the wrist) per record, on
 * targets near the boundary only.
 *
 * Stack: as dh_ikc_q.c, the state lives in the solution array and the
 * solver calls one helper at a time. PARALLEL_234 slots: p05, u, the
 * branch count (+ 4 on axis 1) and the search's hi in sol[5]; x' = x6 and
 * z' = axis 6 in sol[7]; the shoulder branch's t1, c1, s1, p1 and the
 * search's lo in sol[1]; N in sol[3] (the search's kept margin in its
 * flags); wrist record r = 4 s + 2 w holds (t1, t5, t6, phi, vx, vy)
 * until its elbow solutions overwrite slots r and r + 1.
 */
#include "dhmath/frame.h"
#include "dhmath/trig.h"
#include "ikc_impl.h"
#include "../internal/dh_qmath.h"

#define P234Q_EMPTY 0xFFFFFFFFu
/* wrist singular / SCARA tilt: 2^11 LSB of Q2.30 (1.9e-6) */
#define P234Q_SING ((int32_t)1 << 11)
/* on axis 1: within 16 LSB */
#define P234Q_SING_AXIS 16
/* shoulder cylinder band: px^2 + py^2 - h^2 within 2^4 (|h| + 1), a point
 * within 8 LSB of the cylinder: one branch */
#define P234Q_CYL_SH 4
/* evaluations per record: the branch's u, then the search (2^6 - 1, in pairs) */
#define P234Q_SEARCH_SH 6u
#define P234Q_SEARCH_LAST ((1u << P234Q_SEARCH_SH) - 1u)
/* par234q_done: no record (below every margin) */
#define P234Q_NO_MARGIN (-INT64_MAX)
/* par234q_done: overflow */
#define P234Q_K_OVF 0x80000000u
#define P234Q_POS_LIM ((int64_t)1 << 30)

/* the 2R's reach margin: >= 0 when |v| lies in the annulus widened by B
 * on each side (the points dh_ikc_elbow_q_ solves) */
static DH_NOINLINE int64_t par234q_margin(int32_t l1, int32_t l2, int32_t vx, int32_t vy)
{
    int64_t ds, df;
    dh_ikc_dsdf_q_(l1, l2, vx, vy, &ds, &df);
    ds += dh_ikc_btol_q_(dh_ikc_lsum_q_(l1, l2));
    df += dh_ikc_btol_q_(dh_ikc_ldif_q_(l1, l2));
    return ds < df ? ds : df;
}

/* ======================================================================
 * DH_IKC_PARALLEL_234: detector. Structure as the float one: six revolute
 * joints, alpha1 = +-90, alpha2, alpha3 in {0, 180}, alpha4, alpha5 = +-90,
 * a5 = 0, a2, a3 != 0.
 * ====================================================================== */

/* m->k layout, PARALLEL_234 */
#define P_TAU 0 /* sign of sa1 */
#define P_S2 1  /* sign of ca2 */
#define P_S23 2 /* sign of ca2 ca3 */
#define P_SB 3  /* s23 sign of sa4 */
#define P_W5 4  /* sign of sa5 */
#define P_H 5   /* h = d2 + s2 d3 + s23 d4, dh_qpos */
#define P_E5 6  /* sb d5 */
#define P_W 7   /* 7..9: (a6, d6 sa6, d6 ca6) */

int dh_ikc_detect_par234_q_(dh_ikc_model_q *m)
{
    int32_t *k = m->k;
    int64_t h;
    if (m->n != 6u || m->prismatic != 0u) return 0;
    if (!dh_ikc_small_q_(m->ca[0]) || !dh_ikc_small_q_(m->sa[1]) || !dh_ikc_small_q_(m->sa[2]) || !dh_ikc_small_q_(m->ca[3]) ||
        !dh_ikc_small_q_(m->ca[4]))
        return 0;
    if (m->a[4] != 0 || m->a[1] == 0 || m->a[2] == 0) return 0;
    k[P_TAU] = dh_ikc_sign_q_(m->sa[0]);
    k[P_S2] = dh_ikc_sign_q_(m->ca[1]);
    k[P_S23] = k[P_S2] * dh_ikc_sign_q_(m->ca[2]);
    k[P_SB] = k[P_S23] * dh_ikc_sign_q_(m->sa[3]);
    k[P_W5] = dh_ikc_sign_q_(m->sa[4]);
    h = (int64_t)m->d[1] + k[P_S2] * (int64_t)m->d[2] + k[P_S23] * (int64_t)m->d[3];
    /* |h| <= 2^30 keeps h^2 and the products with it in range */
    if (dh_ikc_abs64_q_(h) > (uint64_t)P234Q_POS_LIM) return 0;
    k[P_H] = (int32_t)h;
    k[P_E5] = k[P_SB] * m->d[4];
    return dh_ikc_accept_q_(m, DH_IKC_PARALLEL_234, 5u, &k[P_W]);
}

/* p05, x', z' from T06 (sol[0..1]) into sol[5] (px, py, pz, u, branch
 * count, on axis) and sol[7] (x', z'); 1 on overflow, -1 unreachable */
static DH_NOINLINE int par234q_point(const dh_ikc_model_q *m, dh_ikc_sol_q *sol)
{
    const int32_t *k = m->k;
    const int32_t *c0 = DH_IKC_T06_COL_(sol, 0u), *c1 = DH_IKC_T06_COL_(sol, 1u), *c2 = DH_IKC_T06_COL_(sol, 2u);
    const int32_t *p = DH_IKC_T06_COL_(sol, 3u);
    int32_t *o = sol[5].q, *xz = sol[7].q;
    int64_t v, band;
    unsigned i;
    for (i = 0; i < 3u; i++) {
        v = dh_ikc_mla_q_(dh_ikc_mla_q_(dh_ikc_mla_q_(0, k[P_W], c0[i]), k[P_W + 1], c1[i]), k[P_W + 2], c2[i]);
        v = (int64_t)p[i] - ((v + DH_Q_HALF30) >> 30);
        if (dh_ikc_abs64_q_(v) > (uint64_t)P234Q_POS_LIM) return 1;
        o[i] = (int32_t)v;
        xz[i] = c0[i];
        xz[3u + i] = dh_ikc_r30_q_(dh_ikc_mla_q_(dh_ikc_mla_q_(0, m->sa[5], c1[i]), m->ca[5], c2[i]));
    }
    v = dh_q_mla64(dh_q_mul64(o[0], o[0]), o[1], o[1]) - dh_q_mul64(k[P_H], k[P_H]);
    /* more than B inside the shoulder cylinder: unreachable */
    if (v < -dh_ikc_btol_q_(dh_q_abs_u32(k[P_H]))) return -1;
    band = ((int64_t)dh_q_abs_u32(k[P_H]) + 1) << P234Q_CYL_SH;
    /* o[4]: the branch count, + 4 on axis 1 */
    o[4] = 0;
    if (dh_q_abs_u32(o[0]) <= (uint32_t)P234Q_SING_AXIS && dh_q_abs_u32(o[1]) <= (uint32_t)P234Q_SING_AXIS) o[4] = 4;
    if (o[4] != 0 || v <= band) {
        o[3] = 0;
        o[4] += 1;
    } else {
        o[3] = (int32_t)dh_q_isqrt62((uint64_t)v);
        o[4] = 2;
    }
    o[5] = 0;
    return 0;
}

/* shoulder branch s = sol[1].flags with the joint 5 point at u =
 * sol[1].q[0] along x1 (par234q_next): t1, c1, s1, p1x, p1y into sol[1].q,
 * flags into sol[1].flags; 1 on overflow */
static DH_NOINLINE int par234q_shoulder(const dh_ikc_model_q *m, dh_ikc_sol_q *sol, int32_t cref0)
{
    const int32_t *k = m->k;
    const int32_t *o = sol[5].q;
    int32_t *d = sol[1].q;
    const uint32_t s = sol[1].flags;
    const int32_t u = d[0];
    int32_t sn, cs;
    int64_t v;
    if (o[4] > 2) {
        d[0] = cref0;
    } else {
        const int32_t th = k[P_TAU] > 0 ? k[P_H] : -k[P_H];
        d[0] = dh_ikc_atan2_q_(dh_q_mla64(dh_q_mul64(th, o[0]), u, o[1]), dh_q_mul64(u, o[0]) - dh_q_mul64(th, o[1]));
    }
    dh_sincos_q(d[0], &sn, &cs);
    d[1] = cs;
    d[2] = sn;
    v = ((dh_q_mla64(dh_q_mul64(cs, o[0]), sn, o[1]) + DH_Q_HALF30) >> 30) - m->a[0];
    if (dh_ikc_abs64_q_(v) > (uint64_t)P234Q_POS_LIM) return 1;
    d[3] = (int32_t)v;
    v = (int64_t)o[2] - m->d[0];
    if (k[P_TAU] < 0) v = -v;
    if (dh_ikc_abs64_q_(v) > (uint64_t)P234Q_POS_LIM) return 1;
    d[4] = (int32_t)v;
    sol[1].flags = (o[4] != 2 ? (uint32_t)DH_IKC_SING_SHOULDER : 0u) | (s != 0u ? DH_IKC_SHOULDER_ALT : 0u);
    return 0;
}

/* record (t1, t5, t6, phi, v) of a wrist branch into slot r: v = p1 -+
 * (a4 (c, s) + e5 (s, -c)) (sg = +1 for phi, -1 for phi + 180); 1 on
 * overflow */
static DH_NOINLINE int par234q_record(const dh_ikc_model_q *m, dh_ikc_sol_q *r, const int32_t *d, int32_t sg,
                                   int32_t c, int32_t s)
{
    const int32_t a4 = m->a[3], e5 = m->k[P_E5];
    int64_t x = dh_q_mla64(dh_q_mul64(a4, c), e5, s), y = dh_q_mul64(a4, s) - dh_q_mul64(e5, c);
    x = (int64_t)d[3] - sg * ((x + DH_Q_HALF30) >> 30);
    y = (int64_t)d[4] - sg * ((y + DH_Q_HALF30) >> 30);
    if (dh_ikc_abs64_q_(x) > (uint64_t)P234Q_POS_LIM || dh_ikc_abs64_q_(y) > (uint64_t)P234Q_POS_LIM) return 1;
    r->q[0] = d[0];
    r->q[4] = (int32_t)x;
    r->q[5] = (int32_t)y;
    return 0;
}

/* N = R01^T R' of the shoulder branch in sol[1]: n11, n21, n13, n23, c5
 * (= -sb w5 n33), n31 into sol[3].q (free until the elbow pass) */
static DH_NOINLINE void par234q_n(const dh_ikc_model_q *m, dh_ikc_sol_q *sol)
{
    const int32_t *k = m->k;
    const int32_t *d = sol[1].q, *xv = sol[7].q;
    int32_t *n = sol[3].q;
    const int32_t c1 = d[1], s1 = d[2];
    n[0] = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(c1, xv[0]), s1, xv[1]));
    n[1] = k[P_TAU] > 0 ? xv[2] : -xv[2];
    n[2] = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(c1, xv[3]), s1, xv[4]));
    n[3] = k[P_TAU] > 0 ? xv[5] : -xv[5];
    n[4] = dh_ikc_r30_q_(dh_q_mul64(s1, xv[3]) - dh_q_mul64(c1, xv[4])); /* tau n33 */
    if ((k[P_TAU] * k[P_SB] * k[P_W5]) > 0) n[4] = -n[4];
    n[5] = dh_ikc_r30_q_(dh_q_mul64(s1, xv[0]) - dh_q_mul64(c1, xv[1]));
    if (k[P_TAU] < 0) n[5] = -n[5];
}

/* the first wrist record of the shoulder branch in sol[1] into slot j (N
 * from par234q_n, worked on in place; 1 on overflow). A singular wrist takes
 * t6 = cref6 and has one record (SING_WRIST), unless bit j & ~2 of
 * sol[5].flags is set (par234q_done: that record is beyond the 2R's reach):
 * then phi from the third column as off the singularity (exact however
 * small s5), two records, flagged SING_WRIST. */
static DH_NOINLINE int par234q_wrist(const dh_ikc_model_q *m, dh_ikc_sol_q *sol, uint32_t j, int32_t cref5)
{
    const int32_t *k = m->k;
    int32_t *n = sol[3].q;
    dh_ikc_sol_q *r0 = &sol[j];
    int32_t sn, cs;
    r0->flags = sol[1].flags;
    if (dh_q_abs_u32(n[2]) <= (uint32_t)P234Q_SING && dh_q_abs_u32(n[3]) <= (uint32_t)P234Q_SING) {
        r0->flags |= DH_IKC_SING_WRIST;
    }
    if ((r0->flags & DH_IKC_SING_WRIST) != 0u && (sol[5].flags & (1u << (j & ~2u))) == 0u) {
        /* axes 2, 3, 4, 6 parallel: t6 = cref6, phi from the first column,
         * Rz(phi) g = (n11, n21), g = (c5 c6, -sb w5 s6) */
        r0->q[1] = n[4] < 0 ? DH_IKC_Q16_180 : 0;
        r0->q[2] = cref5;
        dh_sincos_q(cref5, &sn, &cs);
        if (n[4] < 0) cs = -cs;
        if (k[P_SB] * k[P_W5] > 0) sn = -sn;
        r0->q[3] = dh_ikc_atan2_q_(dh_q_mul64(n[1], cs) - dh_q_mul64(n[0], sn), dh_q_mla64(dh_q_mul64(n[0], cs), n[1], sn));
        dh_sincos_q(r0->q[3], &sn, &cs);
        return par234q_record(m, r0, sol[1].q, 1, cs, sn);
    }
    r0->q[3] = dh_ikc_atan2_q_(k[P_W5] > 0 ? n[3] : -n[3], k[P_W5] > 0 ? n[2] : -n[2]);
    dh_sincos_q(r0->q[3], &sn, &cs);
    /* s5 into n[2]; t5 */
    n[2] = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(cs, n[2]), sn, n[3]));
    if (k[P_W5] < 0) n[2] = -n[2];
    r0->q[1] = 0;
    (void)dh_atan2_q(n[2], n[4], &r0->q[1]);
    /* m' = Rz(-phi) N e_x: m'x into n[3], m'y into n[1], m'z = n31 */
    n[3] = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(cs, n[0]), sn, n[1]));
    n[1] = dh_ikc_r30_q_(dh_q_mul64(cs, n[1]) - dh_q_mul64(sn, n[0]));
    if (k[P_SB] < 0) n[2] = -n[2]; /* sb s5 */
    if (k[P_W5] * k[P_SB] > 0) n[1] = -n[1]; /* -w5 sb m'y */
    r0->q[2] = dh_ikc_atan2_q_(dh_q_mul64(n[1], DH_Q_ONE30), dh_q_mla64(dh_q_mul64(n[4], n[3]), n[2], n[5]));
    return par234q_record(m, r0, sol[1].q, 1, cs, sn);
}

/* the wrist flip (phi + 180, -t5, t6 + 180) of record src (of the shoulder
 * branch in sol[1]) into dst (dst may be src); 1 on overflow */
static DH_NOINLINE int par234q_flip(const dh_ikc_model_q *m, dh_ikc_sol_q *sol, dh_ikc_sol_q *dst,
                                 const dh_ikc_sol_q *src)
{
    const int32_t phi = src->q[3];
    int32_t sn, cs;
    dh_sincos_q(phi, &sn, &cs);
    dst->q[1] = dh_ikc_wrap180_q_(-src->q[1]);
    dst->q[2] = dh_ikc_wrap180_q_(src->q[2] + DH_IKC_Q16_180);
    dst->q[3] = dh_ikc_wrap180_q_(phi + DH_IKC_Q16_180);
    dst->flags = src->flags | DH_IKC_WRIST_ALT;
    return par234q_record(m, dst, sol[1].q, -1, cs, sn);
}

/* Record j's planar point is beyond the 2R's reach. Within B of the
 * shoulder cylinder t1 is ill-conditioned: the joint 5 point at u along x1
 * (u^2 = px^2 + py^2 - h^2 exact) and at any u' with |u'^2 - u^2| <=
 * 2^(sh + 1) (|h| + 1) (the same point moved by at most B radially) give
 * t1 apart by up to 1e-3 rad, which the wrist (phi, divided by s5) and the
 * planar point amplify to tenths of mm. dh_ikc_par234_q_ searches that
 * interval (u' of the branch's sign; either sign for the merged branch)
 * by thirds for the largest 2R margin and stops at the first u' the 2R
 * reaches. The interval [lo, hi] lives in sol[1].q[5] and sol[5].q[5],
 * the first margin of a pair in sol[3].flags (free during the search: the
 * solver's frame stays that of pass 1, within the stack budget). */
static DH_NOINLINE void par234q_band(const dh_ikc_model_q *m, dh_ikc_sol_q *sol, unsigned j)
{
    int32_t *o = sol[5].q;
    const int64_t v = dh_q_mla64(dh_q_mul64(o[0], o[0]), o[1], o[1]) - dh_q_mul64(m->k[P_H], m->k[P_H]);
    const int64_t t = dh_ikc_btol_q_(dh_q_abs_u32(m->k[P_H]));
    /* v >= -t (par234q_point); |u| <= 2^30.5 */
    const int64_t vhi = v + t, vlo = v - t;
    int32_t hi = (int32_t)dh_q_isqrt62((uint64_t)vhi), lo = -hi;
    if (o[4] != 1) {
        lo = vlo > 0 ? (int32_t)dh_q_isqrt62((uint64_t)vlo) : 0;
        if (j >= 4u) {
            const int32_t a = lo;
            lo = -hi;
            hi = -a;
        }
    }
    sol[1].q[5] = lo;
    o[5] = hi;
}

/* the third (hi - lo) 11 / 32 of the search interval */
DH_INLINE int32_t par234q_third(const dh_ikc_sol_q *sol)
{
    return (int32_t)((((int64_t)sol[5].q[5] - sol[1].q[5]) * 11) >> 5);
}

/* evaluation i of the search: even at lo + third, odd at hi - third */
static DH_NOINLINE int32_t par234q_cand(const dh_ikc_sol_q *sol, uint32_t i)
{
    return (i & 1u) ? sol[5].q[5] - par234q_third(sol) : sol[1].q[5] + par234q_third(sol);
}

/* margin f (< 0) of evaluation i: even, kept (f / 2^16, clamped, offset
 * by 2^31 so that unsigned order is the order); odd, the larger margin of
 * the pair at hi - third drops the lower third, else the upper */
static DH_NOINLINE void par234q_step(dh_ikc_sol_q *sol, uint32_t i, int64_t f)
{
    int64_t c = f >> 16;
    uint32_t b;
    if (c < -(int64_t)INT32_MAX) c = -(int64_t)INT32_MAX;
    b = (uint32_t)(c + ((int64_t)1 << 31));
    if ((i & 1u) == 0u) {
        sol[3].flags = b;
    } else if (sol[3].flags < b) {
        sol[1].q[5] += par234q_third(sol);
    } else {
        sol[5].q[5] -= par234q_third(sol);
    }
}

/* 1 when a margin f < 0 is not worth a search: two shoulder branches and
 * the planar point about 2^16 LSB (1 mm at DH_QPOS_FRAC 16) beyond the
 * annulus (in the tests the searches that reach start within a few tens
 * of LSB beyond B; most records of random targets beyond the reach are
 * far beyond it).
 * The merged branch (within 8 LSB of the cylinder, t1 free by up to 1e-3
 * rad, which the wrist divides by s5) is always searched. */
static DH_NOINLINE int par234q_hopeless(const dh_ikc_model_q *m, const dh_ikc_sol_q *sol, int64_t f)
{
    return sol[5].q[4] == 2 && f < -((int64_t)dh_ikc_lsum_q_(m->a[1], m->a[2]) << 17);
}

/* Evaluation k of dh_ikc_par234_q_: record j = 2 (k >> sh) (shoulder
 * branch j / 4, wrist branch (j / 2) & 1), i = k & (2^sh - 1): i = 0 at
 * the branch's u, i >= 1 the search. Its shoulder branch and u into
 * sol[1].flags and sol[1].q[0] (par234q_shoulder) and 0; 1 when there is
 * nothing to evaluate; 2 for the flip record at the branch's u, which
 * par234q_done wrote with the first. */
static DH_NOINLINE int par234q_next(dh_ikc_sol_q *sol, uint32_t k)
{
    const uint32_t j = (k >> P234Q_SEARCH_SH) << 1, s = j >> 2, i = k & P234Q_SEARCH_LAST;
    if (i == 0u) {
        if (s >= ((uint32_t)sol[5].q[4] & 3u)) return 1;
        if ((j & 2u) != 0u) return (sol[j].flags == P234Q_EMPTY) ? 1 : 2;
        sol[1].q[0] = s ? -sol[5].q[3] : sol[5].q[3];
    } else {
        if (sol[j].flags == P234Q_EMPTY) return 1;
        sol[1].q[0] = par234q_cand(sol, i - 1u);
    }
    sol[1].flags = s;
    return 0;
}

/* After evaluation k (par234q_wrist's record in slot j; st = 1: overflow,
 * 2: the flip record written at the branch's u): at the branch's u the
 * flip into slot j + 2, in the search the flip in place for the second
 * wrist branch (a singular wrist has one record, par234q_wrist); the 2R
 * margin. Returns the k that the loop continues from (k | (2^sh - 1):
 * record j done), or P234Q_K_OVF on an overflow at the branch's u. */
static DH_NOINLINE uint32_t par234q_done(const dh_ikc_model_q *m, dh_ikc_sol_q *sol, uint32_t k, int st)
{
    const uint32_t j = (k >> P234Q_SEARCH_SH) << 1, i = k & P234Q_SEARCH_LAST;
    dh_ikc_sol_q *r = &sol[j];
    const int one = (r->flags & DH_IKC_SING_WRIST) != 0u && (sol[5].flags & (1u << (j & ~2u))) == 0u;
    int64_t f = P234Q_NO_MARGIN;
    int e = st;
    if (e == 2) {
        e = 0;
    } else if (e == 0 && (j & 2u) != 0u) {
        e = one ? -1 : par234q_flip(m, sol, r, r);
    } else if (e == 0 && i == 0u) {
        if (one)
            sol[j + 2u].flags = P234Q_EMPTY;
        else if (par234q_flip(m, sol, &sol[j + 2u], r) != 0)
            return P234Q_K_OVF;
    } else {
        /* overflow */
    }
    if (e > 0 && i == 0u) return P234Q_K_OVF;
    if (e == 0) f = par234q_margin(m->a[1], m->a[2], r->q[4], r->q[5]);
    if (f >= 0) return k | P234Q_SEARCH_LAST;
    if (i == 0u && (r->flags & DH_IKC_SING_WRIST) != 0u && (j & 2u) == 0u && (sol[5].flags & (1u << j)) == 0u) {
        /* the singular wrist's record (t6 = cref6) beyond the reach: again
         * with phi as off the singularity (k - 1 wraps at 0: the loop's
         * increment returns to k) */
        sol[5].flags |= 1u << j;
        return k - 1u;
    }
    if (i == 0u) {
        /* beyond the reach: searched off axis 1, unless hopeless */
        if (sol[5].q[4] > 2 || par234q_hopeless(m, sol, f)) {
            r->flags = P234Q_EMPTY;
            return k | P234Q_SEARCH_LAST;
        }
        par234q_band(m, sol, j);
    } else if (i == P234Q_SEARCH_LAST) {
        r->flags = P234Q_EMPTY;
    } else {
        par234q_step(sol, i - 1u, f);
    }
    return k;
}

/* the ne elbow solutions of wrist record j into slots j, j + 1 (the pair
 * (S, Kd) of dh_ikc_elbow_q_ in slot j + 1) */
static DH_NOINLINE void par234q_elbow(const dh_ikc_model_q *m, dh_ikc_sol_q *sol, unsigned j, unsigned ne,
                                   int32_t cref1)
{
    const int32_t *k = m->k;
    dh_ikc_sol_q *r = &sol[j];
    const int32_t *pr = sol[j + 1u].q;
    const int32_t a2 = m->a[1], a3 = m->a[2];
    int32_t psi = 0, sc[2];
    unsigned e;
    sol[j + 1u].flags = P234Q_EMPTY;
    if (ne == 0u) {
        r->flags = P234Q_EMPTY;
        return;
    }
    if (ne == 1u) r->flags |= DH_IKC_SING_ELBOW;
    (void)dh_atan2_q(pr[0], pr[1], &psi);
    /* branch 1 first: slot j + 1 is written after the last read of pr,
     * slot j after the last read of the record */
    for (e = ne; e-- > 0u;) {
        dh_ikc_sol_q *o = &sol[j + e];
        int64_t x, y;
        int32_t A, B, t2;
        const int32_t t3 = dh_ikc_wrap180_q_(e ? -psi : psi);
        dh_sincos_q(t3, &sc[0], &sc[1]);
        A = a2 + dh_ikc_r30_q_(dh_q_mul64(a3, sc[1]));
        B = dh_ikc_r30_q_(dh_q_mul64(a3, sc[0]));
        if (k[P_S2] < 0) B = -B;
        y = dh_q_mul64(A, r->q[5]) - dh_q_mul64(B, r->q[4]);
        x = dh_q_mla64(dh_q_mul64(A, r->q[4]), B, r->q[5]);
        t2 = (x == 0 && y == 0) ? cref1 : dh_ikc_atan2_q_(y, x);
        /* t4 = s23 (phi - t2 - s2 t3) */
        A = dh_ikc_wrap180_q_(dh_ikc_wrap180_q_(r->q[3] - t2) - (k[P_S2] > 0 ? t3 : -t3));
        if (k[P_S23] < 0) A = dh_ikc_wrap180_q_(-A);
        o->flags = r->flags | (e ? DH_IKC_ELBOW_ALT : 0u);
        o->q[0] = r->q[0];
        o->q[4] = r->q[1];
        o->q[5] = r->q[2];
        o->q[1] = t2;
        o->q[2] = t3;
        o->q[3] = A;
    }
}

dh_status dh_ikc_par234_q_(const dh_ikc_model_q *m, const int32_t *q_ref, dh_ikc_sol_q *sol, uint32_t *count)
{
    uint32_t k, cnt = 0;
    int st;
    *count = 0;
    st = par234q_point(m, sol);
    if (st > 0) return DH_ERR_OVERFLOW;
    if (st < 0) return DH_OK; /* unreachable */
    for (k = 0; k < DH_IKC_MAX_SOL; k++) sol[k].flags = P234Q_EMPTY;
    sol[5].flags = 0u; /* par234q_wrist's bits */
    /* the wrist records at each shoulder branch's u, and for those beyond
     * the 2R's reach the search of par234q_band; one helper at a time */
    for (k = 0; k < (4u << P234Q_SEARCH_SH); k++) {
        st = par234q_next(sol, k);
        if (st == 1) continue;
        if (st == 0) {
            st = par234q_shoulder(m, sol, dh_ikc_cref_q_(m, q_ref, 0u));
            if (st == 0) {
                par234q_n(m, sol);
                st = par234q_wrist(m, sol, (k >> P234Q_SEARCH_SH) << 1, dh_ikc_cref_q_(m, q_ref, 5u));
            }
        }
        k = par234q_done(m, sol, k, st);
        if (k == P234Q_K_OVF) return DH_ERR_OVERFLOW;
    }
    for (k = 0; k < DH_IKC_MAX_SOL; k += 2u)
        if (sol[k].flags != P234Q_EMPTY)
            par234q_elbow(m, sol, k, dh_ikc_elbow_q_(m->a[1], m->a[2], sol[k].q[4], sol[k].q[5], sol[k + 1u].q),
                       dh_ikc_cref_q_(m, q_ref, 1u));
        else
            sol[k + 1u].flags = P234Q_EMPTY;
    for (k = 0; k < DH_IKC_MAX_SOL; k++)
        if (sol[k].flags != P234Q_EMPTY) {
            if (k != cnt) sol[cnt] = sol[k];
            cnt++;
        }
    *count = cnt;
    return DH_OK;
}

/* ======================================================================
 * DH_IKC_PARALLEL_234: |det J|. With w the common direction of axes 2-4,
 * the columns 3 - 2 and 4 - 3 have no angular part (w x (p2 - p3), w x
 * (p3 - p4)), and with the reference point at the joint 5 point P (on
 * axes 5 and 6: a5 = 0) columns 5 and 6 have no linear part; a Laplace
 * expansion along those four columns leaves det J = +-[w . ((p2 - p3) x
 * (p3 - p4))] [(P - p1) . (w x z1)] [w . (z5 x z6)] = +-(a2 a3 s3) u s5,
 * u = a1 + a2 c2 + a3 cos(t2 + s2 t3) + a4 cos phi + sb d5 sin phi (the
 * joint 5 point's distance from the plane of axes 1 and 2, phi = t2 +
 * s2 t3 + s23 t4 as above).
 * ====================================================================== */

uint32_t dh_ikc_par234_detj_q_(const dh_ikc_model_q *m, const int32_t *q, int32_t *ex)
{
    const int32_t *k = m->k;
    const int32_t t2 = dh_ikc_theta_q_(m, q, 1u), t3 = dh_ikc_theta_q_(m, q, 2u), t4 = dh_ikc_theta_q_(m, q, 3u);
    const uint32_t t23 = (uint32_t)t2 + (k[P_S2] > 0 ? (uint32_t)t3 : 0u - (uint32_t)t3);
    const uint32_t phi = t23 + (k[P_S23] > 0 ? (uint32_t)t4 : 0u - (uint32_t)t4);
    int32_t s, c, s3, c3;
    uint32_t p;
    int64_t u;
    /* one sine or cosine pair at a time (a small frame) */
    *ex = -30;
    dh_sincos_q(dh_ikc_theta_q_(m, q, 4u), &s, &c);
    p = dh_ikc_pmul_q_((uint32_t)1 << 30, dh_ikc_lows_q_(s), 30, ex);
    dh_sincos_q(t3, &s3, &c3);
    p = dh_ikc_pmul_q_(p, dh_ikc_lows_q_(s3), 30, ex);
    p = dh_ikc_pmul_q_(p, dh_q_abs_u32(m->a[1]), DH_QPOS_FRAC, ex);
    p = dh_ikc_pmul_q_(p, dh_q_abs_u32(m->a[2]), DH_QPOS_FRAC, ex);
    dh_sincos_q((int32_t)phi, &s, &c);
    u = ((int64_t)m->a[0] << 30) + dh_q_mla64(dh_q_mul64(m->a[3], c), k[P_E5], s);
    dh_sincos_q(t2, &s, &c);
    /* a3 cos(t2 + s2 t3) = a3 (c2 c3 - s2 sin(s2 t3)), the product rounded */
    u += dh_q_mul64(m->a[1], c) +
         dh_q_mul64(m->a[2], dh_ikc_r30_q_(dh_q_mul64(c, c3) - dh_q_mul64(s, k[P_S2] > 0 ? s3 : -s3)));
    return dh_ikc_pmul_q_(p, dh_ikc_low_q_(u, (uint64_t)dh_q_abs_u32(m->a[0]) + dh_q_abs_u32(m->a[1]) +
                                                 2u * dh_q_abs_u32(m->a[2]) + dh_q_abs_u32(m->a[3]) +
                                                 dh_q_abs_u32(k[P_E5])),
                          DH_QPOS_FRAC, ex);
}
