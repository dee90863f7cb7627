/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_ikc_wrist_q.c - closed-form IK, fixed point (integer only: no float,
 * no libm, no 64-bit division; tools/check.sh guards): the spherical-wrist
 * families DH_IKC_WRIST_RRR (Puma 560, KUKA KR5, ABB IRB140) and
 * DH_IKC_WRIST_RRP (Stanford arm), detector and solver behind the front
 * end dh_ikc_q.c (formats and ranges described there); interface in
 * ikc_impl.h; method: docs/design.md ("Closed-form inverse kinematics"),
 * after Paul 1981 ch. 3.
 *
 * Position, RRR (alpha1 = +-90 with tau = sin alpha1, alpha2 in {0, 180}
 * with sigma = cos alpha2; joints 1-based in formulas, 0-based in code).
 * The wrist centre o = p - R06 (a6, d6 s_alpha6, d6 c_alpha6) is the origin
 * of frame 4. In frame 1 it is Rz(t2) (A, B) + h z with
 * A = a2 + a3 c3 + e s3, B = sigma (a3 s3 - e c3), e = s_alpha3 d4,
 * h = d2 + sigma (d3 + c_alpha3 d4); frame 0 gives
 * (px, py) = Rz(t1) (u, -tau h), u = a1 + x1, so u = +-sqrt(px^2 + py^2 - h^2)
 * (the shoulder branches), t1 = atan2(tau h px + u py, u px - tau h py),
 * and (vx, vy) = (u - a1, tau (pz - d1)) = Rz(t2) (A, B). Then
 * |v|^2 - a2^2 - rho^2 = 2 a2 rho cos(t3 - phi) (rho^2 = a3^2 + e^2,
 * phi = atan2(e, a3)): with D = |2 a2 rho| and K the left side times sgn
 * (a2), t3 = phi +- atan2(sqrt((D - K)(D + K)), K). Each factor is shifted
 * below 2^31 on its own (the near-zero one keeps its bits, which is what
 * the stretched elbow needs), the shifts made even in sum, and K shifted by
 * half the sum. t2 = atan2(A vy - B vx, A vx + B vy).
 *
 * Position, RRP (alpha1, alpha2 = +-90, tau1, tau2; joint 3 prismatic with
 * fixed theta3). A3 (0, 0, d4) = Rz(theta3) (a3, -e) + L z with
 * L = d3 + c_alpha3 d4, so in frame 1 the wrist centre is
 * Rz(t2) (X2, -tau2 L) + h z, X2 = a2 + gx, h = d2 + tau2 gy,
 * (gx, gy) = Rz(theta3) (a3, -e). t1 as above; |v|^2 = X2^2 + L^2 gives
 * L = +-sqrt(|v|^2 - X2^2) (the two signs: ELBOW_ALT is the negative
 * extension, which limits on d3 normally remove) and
 * t2 = atan2(X2 vy + tau2 L vx, X2 vx - tau2 L vy).
 *
 * Wrist (both families). R03 = Rz(t1) Rx(alpha1) Rz(tb) C with tb = t2 +
 * sigma t3, C = Rx(alpha2 + alpha3) (RRR) or tb = t2, C = Rx(alpha2)
 * Rz(theta3) Rx(alpha3) (RRP); C is a model constant. Only two columns of
 * M = R03^T R06 Rx(alpha6)^T are needed: M e_x = R03^T (R06 e_x) and
 * M e_z = R03^T (s_alpha6 R06 e_y + c_alpha6 R06 e_z); the shoulder part
 * Rx(alpha1)^T Rz(t1)^T is applied once per shoulder branch. For the
 * orthogonal wrist (alpha4, alpha5 = +-90, signs s4a, s5a):
 * M e_z = (s5a s5 c4, s5a s5 s4, -s4a s5a c5), so t4 = atan2(s5a m23, s5a m13)
 * (s5 >= 0 branch), s5 = s5a (c4 m13 + s4 m23), c5 = -s4a s5a m33, and with
 * m' = Rz(-t4) M e_x = (c5 c6, -s4a s5a s6, s4a s5 c6):
 * t6 = atan2(-s4a s5a m'y, c5 m'x + s4a s5 m'z). The other wrist branch is
 * (t4 + 180, -t5, t6 + 180), no second atan2. Wrist singular (|m13| and
 * |m23| both <= 2^11 LSB: orientation error <= 2.7e-6 rad): t4 = the reference, t5 and t6 from
 * the same formulas (t6 absorbs the choice), one solution.
 *
 * Cost (all solutions of the Puma 560): 2 atan2 for joint 1, 2 for the
 * elbow, 4 for joint 2, 3 per arm branch for the wrist (12): 20 atan2;
 * sin/cos of t1 (2), t3 (4), tb and t4 (2 per arm branch, 8): 14;
 * 3 integer square roots (u, two elbow radicands); about 250 products.
 * Factors 0 and +-1 (exact twists, zero tool offsets) are not multiplied.
 */
#include "dhmath/ikc.h"
#include "dhmath/frame.h"
#include "dhmath/trig.h"
#include "ikc_impl.h"
#include "../internal/dh_qmath.h"

/* wrist singular: |m13|, |m23| <= 2^-19 (orientation error <= 2.7e-6 rad) */
#define WRISTQ_SING_WRIST ((int32_t)1 << 11)
/* Tolerances on lengths are counted in LSB, so that the solver does the
 * same on the same raw values for every DH_QPOS_FRAC (units quoted for
 * DH_QPOS_FRAC 16, robots in mm). Shoulder singular: wrist centre within
 * 16 LSB (2.4e-4 units) of axis 1. */
#define WRISTQ_SING_AXIS 16
/* reach tolerance: 2^7 LSB (2^-9 units) of the wrist centre, as a bound
 * on a squared length: 2^7 (sum of the magnitudes involved) */
#define WRISTQ_REACH_SH 7
/* stretched / folded elbow: within 8 LSB (2^-13 units) */
#define WRISTQ_FOLD_SH 3
/* intermediate lengths, raw */
#define WRISTQ_POS_LIM ((int64_t)1 << 30)

/* model constants of the wrist families (m->k) */
#define K_TAU1 0 /* sign of sin alpha1 */
#define K_SIG 1  /* RRR: sign of cos alpha2 (sigma); RRP: sign of sin alpha2 (tau2) */
#define K_S4 2   /* sign of sin alpha4 */
#define K_S5 3   /* sign of sin alpha5 */
#define K_H 4    /* h, dh_qpos */
#define K_E 5    /* RRR: e = s_alpha3 d4; RRP: X2 */
#define K_RHO 6  /* RRR: delta = rho - |a2| (dh_qpos) */
#define K_PHI 7  /* RRR: phi, Q16.16 deg */
#define K_LOFF 8 /* RRP: c_alpha3 d4 */
#define K_W 9    /* 9..11: w = (a6, d6 s_alpha6, d6 c_alpha6) */
#define K_C 12   /* 12..20: C row-major, Q2.30 */

/* round(n / d) for |n| < 2^62, 0 < d < 2^32, quotient below 2^31 in
 * magnitude: restoring division bit by bit (no 64-bit division) */
static DH_NOINLINE int32_t wristq_div_rnd(int64_t n, uint64_t d)
{
    uint64_t a = dh_ikc_abs64_q_(n) + (d >> 1), r = 0u, qt = 0u;
    int i;
    for (i = 63; i >= 0; i--) {
        r = (r << 1) | ((a >> i) & 1u);
        qt <<= 1;
        if (r >= d) {
            r -= d;
            qt |= 1u;
        }
    }
    return n < 0 ? -(int32_t)qt : (int32_t)qt;
}

/* v <- Rz(t)^T v in the plane (x, y): (c x + s y, c y - s x). A quarter
 * turn (c = 0, s = +-1: twists of +-90 deg) swaps without products (the
 * rounded products are +-a, +-b exactly, modulo 2^32); otherwise the
 * products that skip exact factors when c is 0 or +-1, the plain ones when
 * it is not (the same sums) */
static DH_NOINLINE void wristq_rot2(int32_t *x, int32_t *y, int32_t c, int32_t s)
{
    const int32_t a = *x, b = *y;
    if (c == 0 && (s == DH_Q_ONE30 || s == -DH_Q_ONE30)) {
        *x = (int32_t)(s > 0 ? (uint32_t)b : 0u - (uint32_t)b);
        *y = (int32_t)(s > 0 ? 0u - (uint32_t)a : (uint32_t)a);
        return;
    }
    if (c == 0 || c == DH_Q_ONE30 || c == -DH_Q_ONE30) {
        *x = dh_ikc_r30_q_(dh_ikc_mla_q_(dh_ikc_mla_q_(0, c, a), s, b));
        *y = dh_ikc_r30_q_(dh_ikc_mla_q_(dh_ikc_mla_q_(0, c, b), -s, a));
        return;
    }
    *x = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(c, a), s, b));
    *y = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(c, b), -s, a));
}

/* ---- wrist families: detector ------------------------------------------- */

/* C = Rx(alpha2) Rz(theta3) Rx(alpha3) (RRP) into k[K_C..] */
static DH_NOINLINE void wristq_c_rrp(dh_ikc_model_q *m, int32_t s3, int32_t c3)
{
    int32_t *C = &m->k[K_C];
    const int32_t sa3 = m->sa[2], ca3 = m->ca[2], sa2 = m->sa[1], ca2 = m->ca[1];
    int32_t r1[3], r2[3];
    unsigned j;
    /* Rz(theta3) Rx(alpha3) = [c3, -s3 ca3, s3 sa3; s3, c3 ca3, -c3 sa3; 0, sa3, ca3] */
    C[0] = c3;
    C[1] = dh_ikc_r30_q_(-dh_q_mul64(s3, ca3));
    C[2] = dh_ikc_r30_q_(dh_q_mul64(s3, sa3));
    r1[0] = s3;
    r1[1] = dh_ikc_r30_q_(dh_q_mul64(c3, ca3));
    r1[2] = dh_ikc_r30_q_(-dh_q_mul64(c3, sa3));
    r2[0] = 0;
    r2[1] = sa3;
    r2[2] = ca3;
    for (j = 0; j < 3u; j++) {
        C[3u + j] = dh_ikc_r30_q_(dh_q_mul64(ca2, r1[j]) - dh_q_mul64(sa2, r2[j]));
        C[6u + j] = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(sa2, r1[j]), ca2, r2[j]));
    }
}

int dh_ikc_detect_wrist_q_(dh_ikc_model_q *m)
{
    int32_t *k = m->k;
    const uint32_t p = m->prismatic;
    int32_t e, s3, c3;
    int64_t h;

    if (m->n != 6u || !dh_ikc_spherical_q_(m) || !dh_ikc_small_q_(m->ca[3]) || !dh_ikc_small_q_(m->ca[4]) || !dh_ikc_small_q_(m->ca[0]))
        return 0;
    k[K_TAU1] = dh_ikc_sign_q_(m->sa[0]);
    k[K_S4] = dh_ikc_sign_q_(m->sa[3]);
    k[K_S5] = dh_ikc_sign_q_(m->sa[4]);
    k[K_W] = m->a[5];
    k[K_W + 1] = dh_ikc_r30_q_(dh_q_mul64(m->d[5], m->sa[5]));
    k[K_W + 2] = dh_ikc_r30_q_(dh_q_mul64(m->d[5], m->ca[5]));
    e = dh_ikc_r30_q_(dh_q_mul64(m->sa[2], m->d[3]));
    if (p == 0u) {
        int32_t sig;
        uint32_t rho;
        if (!dh_ikc_small_q_(m->sa[1]) || m->a[1] == 0) return 0;
        sig = dh_ikc_sign_q_(m->ca[1]);
        h = (int64_t)m->d[2] + dh_ikc_r30_q_(dh_q_mul64(m->ca[2], m->d[3]));
        h = (int64_t)m->d[1] + (sig > 0 ? h : -h);
        {
            /* delta = rho - |a2| = (rho^2 - a2^2) / (rho + |a2|), the
             * numerator exact: 2 |a2| rho = a2^2 + rho^2 - delta^2 then
             * keeps the folded elbow exact to the rounding of delta */
            const int64_t r2 = dh_q_mla64(dh_q_mul64(m->a[2], m->a[2]), e, e);
            const int64_t num = r2 - dh_q_mul64(m->a[1], m->a[1]);
            rho = dh_q_isqrt62((uint64_t)r2);
            if (rho == 0u) return 0;
            k[K_RHO] = wristq_div_rnd(num, (uint64_t)rho + dh_q_abs_u32(m->a[1]));
        }
        k[K_SIG] = sig;
        k[K_E] = e;
        k[K_PHI] = dh_ikc_atan2_q_(e, m->a[2]);
        /* C = Rx(alpha2 + alpha3): sin, cos = sigma s_alpha3, sigma c_alpha3 */
        s3 = sig > 0 ? m->sa[2] : -m->sa[2];
        c3 = sig > 0 ? m->ca[2] : -m->ca[2];
        memset(&k[K_C], 0, 9u * sizeof k[0]);
        k[K_C] = DH_Q_ONE30;
        k[K_C + 4] = c3;
        k[K_C + 5] = -s3;
        k[K_C + 7] = s3;
        k[K_C + 8] = c3;
        m->kind = DH_IKC_WRIST_RRR;
    } else if (p == 0x4u) {
        int32_t tau2, gx, gy;
        int64_t x2;
        if (!dh_ikc_small_q_(m->ca[1])) return 0;
        tau2 = dh_ikc_sign_q_(m->sa[1]);
        dh_sincos_q(m->off[2], &s3, &c3);
        gx = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(c3, m->a[2]), s3, e));
        gy = dh_ikc_r30_q_(dh_q_mul64(s3, m->a[2]) - dh_q_mul64(c3, e));
        x2 = (int64_t)m->a[1] + gx;
        h = (int64_t)m->d[1] + (tau2 > 0 ? gy : -gy);
        k[K_SIG] = tau2;
        k[K_E] = (int32_t)x2;
        k[K_LOFF] = dh_ikc_r30_q_(dh_q_mul64(m->ca[2], m->d[3]));
        wristq_c_rrp(m, s3, c3);
        m->kind = DH_IKC_WRIST_RRP;
    } else {
        return 0;
    }
    k[K_H] = (int32_t)h; /* |h| <= 3 2^29 */
    m->why = DH_IKC_WHY_NONE;
    return 1;
}

/* ---- wrist families: solver --------------------------------------------- */

/*
 * Stack. The whole call chain of dh_ikc_q stays within 256 bytes on
 * Cortex-M0, so the solver keeps its state in the solution array, not in
 * its frames, and calls one helper at a time: T06 arrives in sol[0..1]
 * (ikc_impl.h); solution slot 4 s + 2 b + w holds shoulder branch s,
 * elbow branch b, wrist branch w. wristq_centre leaves the wrist centre in
 * sol[4] (o, vy, u, shoulder singular); wristq_shoulder puts each shoulder
 * branch's data into its elbow-2 slots (slot 4 s + 2: t1, vx, flags, M's x
 * column after the shoulder rotation; slot 4 s + 3: vy, the elbow pair,
 * the z column); wristq_arm_* writes q[0..2] of slots 4 s and 4 s + 2 once it
 * has read them, and wristq_wrist reads its columns before it writes a pair
 * of slots. Empty slots carry WRISTQ_EMPTY flags and are squeezed out at the
 * end. The chain is front end -> solver -> one helper -> dh_sincos_q or
 * dh_atan2_q.
 */
#define WRISTQ_EMPTY 0xFFFFFFFFu
#define WRISTQ_ABSENT ((int32_t)-1)

/* c v / 2^30 modulo 2^32 for c in {0, 2^30, -2^30} */
DH_INLINE uint32_t wristq_exact_term(int32_t c, int32_t v)
{
    if (c == 0) return 0u;
    return c > 0 ? (uint32_t)v : 0u - (uint32_t)v;
}

/* C^T v, C row-major (column i of C dotted with v). When every entry of C
 * is 0 or +-1 (exact twists, the usual case) the sums of +-v terms are
 * taken modulo 2^32: the same bits as the rounded products (the int64 sum
 * is a multiple of 2^30, and its rounding keeps its bits 30..61) */
static DH_NOINLINE void wristq_ct(const int32_t *C, int32_t *v)
{
    const int32_t x = v[0], y = v[1], z = v[2];
    unsigned i;
    for (i = 0; i < 9u; i++)
        if (C[i] != 0 && C[i] != DH_Q_ONE30 && C[i] != -DH_Q_ONE30) break;
    if (i == 9u) {
        for (i = 0; i < 3u; i++)
            v[i] = (int32_t)(wristq_exact_term(C[i], x) + wristq_exact_term(C[3u + i], y) +
                             wristq_exact_term(C[6u + i], z));
        return;
    }
    for (i = 0; i < 3u; i++) v[i] = dh_ikc_r30_q_(dh_ikc_mla_q_(dh_ikc_mla_q_(dh_ikc_mla_q_(0, C[i], x), C[3u + i], y), C[6u + i], z));
}

/* wrist centre o, vy and u into sol[4].q (o, vy, u, shoulder singular);
 * 1 on overflow, -1 when the shoulder cannot reach, else 0 */
static DH_NOINLINE int wristq_centre(const dh_ikc_model_q *m, dh_ikc_sol_q *sol)
{
    const int32_t *k = m->k;
    const int32_t *c0 = DH_IKC_T06_COL_(sol, 0u), *c1 = DH_IKC_T06_COL_(sol, 1u), *c2 = DH_IKC_T06_COL_(sol, 2u);
    const int32_t *p = DH_IKC_T06_COL_(sol, 3u);
    int32_t *o = sol[4].q;
    int64_t v;
    unsigned i;

    for (i = 0; i < 3u; i++) {
        v = dh_ikc_mla_q_(dh_ikc_mla_q_(dh_ikc_mla_q_(0, k[K_W], c0[i]), k[K_W + 1], c1[i]), k[K_W + 2], c2[i]);
        v = (int64_t)p[i] - ((v + DH_Q_HALF30) >> 30);
        if (dh_ikc_abs64_q_(v) > (uint64_t)WRISTQ_POS_LIM) return 1;
        o[i] = (int32_t)v;
    }
    v = (int64_t)o[2] - m->d[0];
    if (k[K_TAU1] < 0) v = -v;
    if (dh_ikc_abs64_q_(v) > (uint64_t)WRISTQ_POS_LIM) return 1;
    o[3] = (int32_t)v;
    v = dh_q_mla64(dh_q_mul64(o[0], o[0]), o[1], o[1]) - dh_q_mul64(k[K_H], k[K_H]);
    /* inside the cylinder of radius |h| by less than 2^7 LSB: u = 0 */
    if (v < -(((int64_t)dh_q_abs_u32(o[0]) + (int64_t)dh_q_abs_u32(o[1]) + (int64_t)dh_q_abs_u32(k[K_H]) + 1)
              << WRISTQ_REACH_SH))
        return -1;
    o[5] = dh_q_abs_u32(o[0]) <= (uint32_t)WRISTQ_SING_AXIS && dh_q_abs_u32(o[1]) <= (uint32_t)WRISTQ_SING_AXIS;
    o[4] = (o[5] || v <= 0) ? 0 : (int32_t)dh_q_isqrt62((uint64_t)v);
    return 0;
}

/* u of shoulder branch s into slot 4 s + 2 q[0]: +-o[4], or the boundary
 * value u' when the planar point (u - a1, vy) lies beyond the arm's reach
 * (|v| below the folded radius |delta| (RRR) or |X2| (RRP), or above the
 * stretched radius |a2| + rho (RRR)) and u' = a1 +- sqrt(r^2 - vy^2) on
 * that radius r, of the branch's sign and nearest u, satisfies
 * |u'^2 - u^2| <= 2^WRISTQ_REACH_SH (|ox| + |oy| + 1): u^2 = ox^2 + oy^2 - h^2
 * moves by 2 (ox dox + oy doy) when the wrist centre moves, so u' is u for
 * a wrist centre at most 2^(WRISTQ_REACH_SH - 1) sqrt(2) LSB away. Near the
 * shoulder cylinder (u small) a rounding of the target moves u by much
 * more than a rounding; this keeps such targets on the boundary solvable. */
static DH_NOINLINE void wristq_reach(const dh_ikc_model_q *m, dh_ikc_sol_q *sol, unsigned s)
{
    const int32_t *k = m->k, *o = sol[4].q;
    const int32_t u = s ? -o[4] : o[4], vy = o[3];
    const int64_t vx = (int64_t)u - m->a[0];
    int64_t v2, r2, d;
    uint32_t w;
    int32_t c[2];
    unsigned i;

    sol[4u * s + 2u].q[0] = u;
    if (o[5] || dh_ikc_abs64_q_(vx) > (uint64_t)WRISTQ_POS_LIM) return;
    v2 = dh_q_mla64(dh_q_mul64((int32_t)vx, (int32_t)vx), vy, vy);
    if (m->kind == DH_IKC_WRIST_RRR) {
        const int64_t s2 = dh_q_mla64(dh_q_mla64(dh_q_mul64(m->a[1], m->a[1]), m->a[2], m->a[2]), k[K_E], k[K_E]);
        const int64_t f2 = dh_q_mul64(k[K_RHO], k[K_RHO]);
        if (v2 < f2) r2 = f2;
        else if (v2 > 2 * s2 - f2) r2 = 2 * s2 - f2; /* (|a2| + rho)^2 */
        else return;
    } else {
        r2 = dh_q_mul64(k[K_E], k[K_E]);
        if (v2 >= r2) return;
    }
    r2 -= dh_q_mul64(vy, vy);
    if (r2 < 0) return; /* vy alone is beyond: the elbow decides */
    w = dh_q_isqrt62((uint64_t)r2);
    c[0] = m->a[0] + (int32_t)w;
    c[1] = m->a[0] - (int32_t)w;
    /* the candidate of the branch's sign nearest u, if within the bound */
    d = -1;
    for (i = 0; i < 2u; i++) {
        const int64_t du = (int64_t)c[i] - u;
        int64_t dd;
        if ((s ? c[i] > 0 : c[i] < 0) || dh_ikc_abs64_q_(c[i]) > (uint64_t)WRISTQ_POS_LIM) continue;
        dd = dh_q_mul64(c[i], c[i]) - dh_q_mul64(u, u);
        if (dh_ikc_abs64_q_(dd) > ((uint64_t)dh_q_abs_u32(o[0]) + dh_q_abs_u32(o[1]) + 1u) << WRISTQ_REACH_SH) continue;
        if (d < 0 || (int64_t)dh_ikc_abs64_q_(du) < d) {
            d = (int64_t)dh_ikc_abs64_q_(du);
            sol[4u * s + 2u].q[0] = c[i];
        }
    }
}

/* shoulder branch s: joint 1 and the shoulder part of M into slots 4 s + 2, 4 s + 3 */
static DH_NOINLINE int wristq_shoulder(const dh_ikc_model_q *m, dh_ikc_sol_q *sol, unsigned s, int32_t cref0)
{
    const int32_t *k = m->k;
    const int32_t *c0 = DH_IKC_T06_COL_(sol, 0u), *c1 = DH_IKC_T06_COL_(sol, 1u), *c2 = DH_IKC_T06_COL_(sol, 2u);
    const int32_t *o = sol[4].q;
    dh_ikc_sol_q *d0 = &sol[4u * s + 2u], *d1 = &sol[4u * s + 3u];
    int32_t t1, sn, cs, u = d0->q[0];
    int64_t v;
    unsigned i;

    if (o[5]) {
        t1 = cref0;
        dh_sincos_q(t1, &sn, &cs);
        u = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(cs, o[0]), sn, o[1]));
    } else {
        const int32_t th = k[K_TAU1] > 0 ? k[K_H] : -k[K_H];
        t1 = dh_ikc_atan2_q_(dh_q_mla64(dh_q_mul64(th, o[0]), u, o[1]), dh_q_mul64(u, o[0]) - dh_q_mul64(th, o[1]));
        dh_sincos_q(t1, &sn, &cs);
    }
    v = (int64_t)u - m->a[0];
    if (dh_ikc_abs64_q_(v) > (uint64_t)WRISTQ_POS_LIM) return 1;
    /* Rx(alpha1)^T Rz(t1)^T applied to R06 e_x and to R06 Rx(alpha6)^T e_z */
    for (i = 0; i < 3u; i++) {
        d0->q[3u + i] = c0[i];
        d1->q[3u + i] = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(m->sa[5], c1[i]), m->ca[5], c2[i]));
    }
    wristq_rot2(&d0->q[3], &d0->q[4], cs, sn);
    wristq_rot2(&d1->q[3], &d1->q[4], cs, sn);
    wristq_rot2(&d0->q[4], &d0->q[5], m->ca[0], m->sa[0]);
    wristq_rot2(&d1->q[4], &d1->q[5], m->ca[0], m->sa[0]);
    d0->q[0] = t1;
    d0->q[1] = (int32_t)v;
    d0->q[2] = (int32_t)((o[5] ? DH_IKC_SING_SHOULDER : 0u) | (s ? DH_IKC_SHOULDER_ALT : 0u));
    d1->q[0] = o[3];
    return 0;
}

/* write arm angles (t1, t2, t3) and flags into slot j */
DH_INLINE void wristq_put_arm(dh_ikc_sol_q *d, int32_t t1, int32_t t2, int32_t t3, uint32_t flags)
{
    d->q[0] = t1;
    d->q[1] = t2;
    d->q[2] = t3;
    d->flags = flags;
}

/* RRR elbow of shoulder s: the pair (sqrt((D - K)(D + K)), K) scaled to
 * int32 into slot 4 s + 3 q[1..2]; SING_ELBOW or WRISTQ_ABSENT into the
 * shoulder's flags */
static DH_NOINLINE void wristq_elbow_rrr(const dh_ikc_model_q *m, dh_ikc_sol_q *sol, unsigned s)
{
    const int32_t *k = m->k;
    const int32_t a2 = m->a[1], a3 = m->a[2], e = k[K_E];
    dh_ikc_sol_q *d0 = &sol[4u * s + 2u], *d1 = &sol[4u * s + 3u];
    const int32_t vx = d0->q[1], vy = d1->q[0];
    int64_t K, ds, df, tol;
    unsigned s1, s2;
    uint32_t S;

    /* K = |v|^2 - a2^2 - a3^2 - e^2 and |D| = 2 |a2| rho =
     * a2^2 + a3^2 + e^2 - delta^2, both from exact products (a rounded rho
     * times 2 a2 would move a nearly folded elbow by units of 1e-3) */
    ds = dh_q_mla64(dh_q_mla64(dh_q_mul64(a2, a2), a3, a3), e, e);
    K = dh_q_mla64(dh_q_mul64(vx, vx), vy, vy) - ds;
    ds -= dh_q_mul64(k[K_RHO], k[K_RHO]);
    df = ds + K;
    ds -= K;
    /* beyond stretched or folded by at most 2^(WRISTQ_REACH_SH - 1) sqrt(2)
     * LSB of |v| (|v|^2 moves by 2 |v| d|v|; ds and df are exact products
     * but for delta's rounding of 1 LSB): solved at the boundary */
    tol = ((int64_t)dh_q_abs_u32(vx) + (int64_t)dh_q_abs_u32(vy) + 1) << WRISTQ_REACH_SH;
    if (ds < -tol || df < -tol) {
        d0->q[2] = WRISTQ_ABSENT;
        return;
    }
    /* |v|^2 within tol = 2 |v| 4 LSB of stretched (ds = 0) or folded
     * (df = 0) counts as exactly there; the wrist centre then moves by
     * tol / (|v| + |a2 - rho|) <= 8 LSB */
    tol = (((int64_t)dh_q_abs_u32(vx) + (int64_t)dh_q_abs_u32(vy)) << WRISTQ_FOLD_SH) + 1;
    if (ds <= tol) ds = 0;
    if (df <= tol) df = 0;
    /* cos(t3 - phi) = K / (2 a2 rho): with a2 < 0 the roles swap */
    if (a2 < 0) {
        tol = ds;
        ds = df;
        df = tol;
        K = -K;
    }
    s1 = dh_ikc_fit31_q_(ds);
    s2 = dh_ikc_fit31_q_(df);
    if (((s1 + s2) & 1u) != 0u) s1++;
    S = dh_q_isqrt62((uint64_t)dh_q_mul64((int32_t)(ds >> s1), (int32_t)(df >> s2)));
    if (S == 0u) d0->q[2] |= (int32_t)DH_IKC_SING_ELBOW;
    /* the pair (S, K 2^-(s1 + s2) / 2), both rounded below 2^30 */
    {
        const unsigned sh = (s1 + s2) >> 1;
        K >>= sh;
    }
    s1 = 0u;
    while ((((uint64_t)S | dh_ikc_abs64_q_(K)) >> s1) >= ((uint64_t)1 << 30)) s1++;
    d1->q[1] = (s1 != 0u) ? (int32_t)dh_q_rshr((int64_t)S, s1) : (int32_t)S;
    d1->q[2] = (s1 != 0u) ? (int32_t)dh_q_rshr(K, s1) : (int32_t)K;
}

/* RRR arm angles of shoulder s: t3 = phi +- psi, then t2, into slots 4 s,
 * 4 s + 2; psi and sin/cos t3 go to q[3..5] of slot 4 s (free until its
 * wrist), so that no local needs an address */
static DH_NOINLINE void wristq_arm_rrr(const dh_ikc_model_q *m, dh_ikc_sol_q *sol, unsigned s)
{
    const int32_t *k = m->k;
    const dh_ikc_sol_q *d0 = &sol[4u * s + 2u], *d1 = &sol[4u * s + 3u];
    const int32_t t1 = d0->q[0], vx = d0->q[1], vy = d1->q[0];
    const uint32_t f0 = (uint32_t)d0->q[2];
    int32_t *w = &sol[4u * s].q[3];
    int32_t A, B, t3;
    unsigned b, ne = ((f0 & DH_IKC_SING_ELBOW) != 0u) ? 1u : 2u;

    w[2] = 0;
    (void)dh_atan2_q(d1->q[1], d1->q[2], &w[2]);
    for (b = 0; b < ne; b++) {
        t3 = dh_ikc_wrap180_q_(k[K_PHI] + (b ? -w[2] : w[2]));
        dh_sincos_q(t3, &w[0], &w[1]);
        A = m->a[1] + dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(m->a[2], w[1]), k[K_E], w[0]));
        B = dh_ikc_r30_q_(dh_q_mul64(m->a[2], w[0]) - dh_q_mul64(k[K_E], w[1]));
        if (k[K_SIG] < 0) B = -B;
        wristq_put_arm(&sol[4u * s + 2u * b], t1,
                    dh_ikc_atan2_q_(dh_q_mul64(A, vy) - dh_q_mul64(B, vx), dh_q_mla64(dh_q_mul64(A, vx), B, vy)), t3,
                    f0 | (b ? DH_IKC_ELBOW_ALT : 0u));
    }
}

/* RRP: the extension L of shoulder s into slot 4 s + 3 q[1] */
static DH_NOINLINE void wristq_elbow_rrp(const dh_ikc_model_q *m, dh_ikc_sol_q *sol, unsigned s)
{
    const int32_t x2 = m->k[K_E];
    dh_ikc_sol_q *d0 = &sol[4u * s + 2u], *d1 = &sol[4u * s + 3u];
    const int32_t vx = d0->q[1], vy = d1->q[0];
    int64_t L2 = dh_q_mla64(dh_q_mul64(vx, vx), vy, vy) - dh_q_mul64(x2, x2);
    /* as the RRR elbow: within 2^7 LSB of L = 0 counts as there */
    if (L2 < -(((int64_t)dh_q_abs_u32(vx) + (int64_t)dh_q_abs_u32(vy) + (int64_t)dh_q_abs_u32(x2) + 1)
               << WRISTQ_REACH_SH)) {
        d0->q[2] = WRISTQ_ABSENT;
        return;
    }
    d1->q[1] = (L2 <= 0) ? 0 : (int32_t)dh_q_isqrt62((uint64_t)L2);
    if (d1->q[1] == 0) d0->q[2] |= (int32_t)DH_IKC_SING_ELBOW;
}

/* RRP arm of shoulder s: t2 and d3 for +-L into slots 4 s, 4 s + 2 */
static DH_NOINLINE void wristq_arm_rrp(const dh_ikc_model_q *m, dh_ikc_sol_q *sol, unsigned s)
{
    const int32_t *k = m->k;
    const dh_ikc_sol_q *d0 = &sol[4u * s + 2u], *d1 = &sol[4u * s + 3u];
    const int32_t t1 = d0->q[0], vx = d0->q[1], vy = d1->q[0], L = d1->q[1], x2 = k[K_E];
    const uint32_t f0 = (uint32_t)d0->q[2];
    unsigned b, nl = (L == 0) ? 1u : 2u;

    for (b = 0; b < nl; b++) {
        const int32_t l = b ? -L : L, tl = k[K_SIG] > 0 ? l : -l;
        wristq_put_arm(&sol[4u * s + 2u * b], t1,
                    dh_ikc_atan2_q_(dh_q_mla64(dh_q_mul64(x2, vy), tl, vx), dh_q_mul64(x2, vx) - dh_q_mul64(tl, vy)),
                    l - k[K_LOFF], f0 | (b ? DH_IKC_ELBOW_ALT : 0u));
    }
}

/* joints 4..6 of the arm in slot j = 4 s + 2 b, its flip into slot j + 1;
 * the two columns of M are worked on in place in q[3..5] of these slots
 * (for j = 4 s + 2 they are the shoulder's copies, read for the last time) */
static DH_NOINLINE void wristq_wrist(const dh_ikc_model_q *m, dh_ikc_sol_q *sol, unsigned j, int32_t cref3)
{
    const int32_t *k = m->k;
    dh_ikc_sol_q *d = &sol[j];
    const dh_ikc_sol_q *src = &sol[(j & ~3u) + 2u];
    int32_t *const n = &sol[j].q[3];
    int32_t *const z = &sol[j + 1u].q[3];
    int32_t sc[2], t4, t5;
    unsigned i, sing;

    if (d != src)
        for (i = 0; i < 3u; i++) {
            n[i] = src[0].q[3u + i];
            z[i] = src[1].q[3u + i];
        }
    /* tb = t2 + sigma t3 (RRR) or t2 (RRP) */
    t4 = d->q[1];
    if (m->kind == DH_IKC_WRIST_RRR) t4 += (k[K_SIG] < 0) ? -d->q[2] : d->q[2];
    dh_sincos_q(t4, &sc[0], &sc[1]);
    wristq_rot2(&n[0], &n[1], sc[1], sc[0]);
    wristq_rot2(&z[0], &z[1], sc[1], sc[0]);
    wristq_ct(&k[K_C], n);
    wristq_ct(&k[K_C], z);
    sing = (dh_q_abs_u32(z[0]) <= (uint32_t)WRISTQ_SING_WRIST && dh_q_abs_u32(z[1]) <= (uint32_t)WRISTQ_SING_WRIST);
    if (sing)
        t4 = cref3;
    else
        t4 = dh_ikc_atan2_q_(k[K_S5] > 0 ? z[1] : -z[1], k[K_S5] > 0 ? z[0] : -z[0]);
    dh_sincos_q(t4, &sc[0], &sc[1]);
    /* s5 into z[0], c5 into z[2] */
    z[0] = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(sc[1], z[0]), sc[0], z[1]));
    if (k[K_S5] < 0) z[0] = -z[0];
    if (k[K_S4] == k[K_S5]) z[2] = -z[2];
    /* (s5, c5) = (0, 0) only for a degenerate M (saturated entries): t5 = 0
     * then, as dh_ikc_atan2_q_ answers (0, 0) */
    t5 = 0;
    (void)dh_atan2_q(z[0], z[2], &t5);
    /* m' = Rz(-t4) M e_x into n[0], n[1] */
    wristq_rot2(&n[0], &n[1], sc[1], sc[0]);
    if (k[K_S4] == k[K_S5]) n[1] = -n[1];
    n[0] = dh_ikc_atan2_q_(n[1], ((k[K_S4] > 0) ? dh_q_mla64(dh_q_mul64(z[2], n[0]), z[0], n[2])
                                             : dh_q_mul64(z[2], n[0]) - dh_q_mul64(z[0], n[2])) >> 30);
    n[2] = n[0];
    n[0] = t4;
    n[1] = t5;
    if (sing) {
        d->flags |= DH_IKC_SING_WRIST;
        d[1].flags = WRISTQ_EMPTY;
        return;
    }
    d[1].q[0] = d->q[0];
    d[1].q[1] = d->q[1];
    d[1].q[2] = d->q[2];
    z[0] = dh_ikc_wrap180_q_(t4 + DH_IKC_Q16_180);
    z[1] = dh_ikc_wrap180_q_(-t5);
    z[2] = dh_ikc_wrap180_q_(n[2] + DH_IKC_Q16_180);
    d[1].flags = d->flags | DH_IKC_WRIST_ALT;
}

dh_status dh_ikc_wrist_q_(const dh_ikc_model_q *m, const int32_t *q_ref, dh_ikc_sol_q *sol, uint32_t *count)
{
    uint32_t s, j, cnt = 0, nsh;
    int32_t cref3;
    int st;

    *count = 0;
    st = wristq_centre(m, sol);
    if (st > 0) return DH_ERR_OVERFLOW;
    if (st < 0) return DH_OK; /* unreachable */
    nsh = sol[4].q[5] ? 1u : 2u;
    for (s = 0; s < nsh; s++) {
        wristq_reach(m, sol, s);
        /* u = 0 on both branches: one solution */
        if (s == 1u && sol[4].q[4] == 0 && sol[6].q[0] == 0) {
            nsh = 1u;
            break;
        }
        if (wristq_shoulder(m, sol, s, dh_ikc_cref_q_(m, q_ref, 0u))) return DH_ERR_OVERFLOW;
    }
    for (j = 0; j < DH_IKC_MAX_SOL; j++) sol[j].flags = WRISTQ_EMPTY;
    if (nsh == 1u) sol[6].q[2] = WRISTQ_ABSENT;
    cref3 = dh_ikc_cref_q_(m, q_ref, 3u);
    for (s = 0; s < 2u; s++) {
        if (sol[4u * s + 2u].q[2] == WRISTQ_ABSENT) continue;
        if (m->kind == DH_IKC_WRIST_RRR)
            wristq_elbow_rrr(m, sol, s);
        else
            wristq_elbow_rrp(m, sol, s);
        if (sol[4u * s + 2u].q[2] == WRISTQ_ABSENT) continue;
        if (m->kind == DH_IKC_WRIST_RRR)
            wristq_arm_rrr(m, sol, s);
        else
            wristq_arm_rrp(m, sol, s);
        for (j = 4u * s; j <= 4u * s + 2u; j += 2u)
            if (sol[j].flags != WRISTQ_EMPTY) wristq_wrist(m, sol, j, cref3);
    }
    for (j = 0; j < DH_IKC_MAX_SOL; j++)
        if (sol[j].flags != WRISTQ_EMPTY) {
            if (j != cnt) sol[cnt] = sol[j];
            cnt++;
        }
    *count = cnt;
    return DH_OK;
}

/* ---- wrist families: |det J| -------------------------------------------- */

/*
 * With the reference point at the wrist centre o, J = [J11 0; J21 J22]
 * (the wrist's columns have no linear part), so det J = det J11 det J22
 * with J22 = [z4 z5 z6]: det J22 = +-sin alpha4 sin alpha5 s5 = +-s5.
 * J11's columns are z_i x (o - p_i) (revolute) or z_i (prismatic), and
 * with z2 = +-z3 (RRR) det J11 = [(z1 x (o - p1)) . z2] [z2 . ((p3 - p2) x
 * (o - p3))]: the first factor is +-u (the wrist centre's distance from
 * the plane of axes 1 and 2: (px, py) = Rz(t1) (u, -tau h), u = a1 + A c2 -
 * B s2 in the notation at the top), the second +-a2 B. RRR: |det J| =
 * |a2| |a3 s3 - e c3| |a1 + A c2 - B s2| |s5|. RRP: (z2 x (o - p2)) x z3 =
 * -L z2 in frame 1, so |det J| = |L| |a1 + X2 c2 + tau2 L s2| |s5|.
 */
uint32_t dh_ikc_wrist_detj_q_(const dh_ikc_model_q *m, const int32_t *q, int32_t *ex)
{
    const int32_t *k = m->k;
    int32_t s, c, A, B;
    uint32_t p;
    uint64_t sum;
    int64_t u;
    /* one sine or cosine pair at a time (a small frame) */
    *ex = -30;
    dh_sincos_q(dh_ikc_theta_q_(m, q, 4u), &s, &c);
    p = dh_ikc_pmul_q_((uint32_t)1 << 30, dh_ikc_lows_q_(s), 30, ex);
    if (m->kind == DH_IKC_WRIST_RRR) {
        const int32_t e = k[K_E];
        const uint64_t l3 = (uint64_t)dh_q_abs_u32(m->a[2]) + dh_q_abs_u32(e);
        int64_t bb;
        dh_sincos_q(dh_ikc_theta_q_(m, q, 2u), &s, &c);
        bb = dh_q_mul64(m->a[2], s) - dh_q_mul64(e, c);   /* B sigma, Q30 */
        A = dh_ikc_r30_q_(((int64_t)m->a[1] << 30) + dh_q_mla64(dh_q_mul64(m->a[2], c), e, s));
        B = dh_ikc_r30_q_(k[K_SIG] > 0 ? bb : -bb);
        p = dh_ikc_pmul_q_(p, dh_q_abs_u32(m->a[1]), DH_QPOS_FRAC, ex);
        p = dh_ikc_pmul_q_(p, dh_ikc_low_q_(bb, l3), DH_QPOS_FRAC, ex);
        dh_sincos_q(dh_ikc_theta_q_(m, q, 1u), &s, &c);
        u = ((int64_t)m->a[0] << 30) + dh_q_mul64(A, c) - dh_q_mul64(B, s);
        sum = (uint64_t)dh_q_abs_u32(m->a[0]) + dh_q_abs_u32(m->a[1]) + 2u * l3;
    } else {
        /* L = d3 + c_alpha3 d4, d3 = q3 + the d offset */
        const int64_t L = (int64_t)q[2] + m->d[2] + k[K_LOFF];
        if (L >= ((int64_t)1 << 30) || L <= -((int64_t)1 << 30)) return 0u;
        p = dh_ikc_pmul_q_(p, dh_ikc_low_q_((int64_t)(dh_ikc_abs64_q_(L) << 30), 0u), DH_QPOS_FRAC, ex);
        dh_sincos_q(dh_ikc_theta_q_(m, q, 1u), &s, &c);
        u = ((int64_t)m->a[0] << 30) + dh_q_mul64(k[K_E], c) + dh_q_mul64(k[K_SIG] > 0 ? (int32_t)L : -(int32_t)L, s);
        sum = (uint64_t)dh_q_abs_u32(m->a[0]) + dh_q_abs_u32(k[K_E]) + dh_ikc_abs64_q_(L);
    }
    return dh_ikc_pmul_q_(p, dh_ikc_low_q_(u, sum), DH_QPOS_FRAC, ex);
}
