/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_ikc_q.c - closed-form inverse kinematics, fixed point (integer only:
 * no float, no libm, no 64-bit division; checked by tools/check.sh guards):
 * the front end (dh_ikc_analyse_q, dh_ikc_q, dh_ikc_nearest_q) and the
 * spherical-wrist families DH_IKC_WRIST_RRR (Puma 560, KUKA KR5, ABB
 * IRB140) and DH_IKC_WRIST_RRP (Stanford arm). Contract: ikc.h and the
 * private interface dh_ikc_impl.h; method: docs/design.md ("Closed-form
 * inverse kinematics"), after Paul 1981 ch. 3.
 *
 * Formats. Lengths are raw dh_qpos (DH_QPOS_FRAC fraction bits, written F
 * below); squares and products of two lengths are int64 with 2F fraction
 * bits; rotations and sines Q2.30; angles Q16.16 degrees. The code never
 * depends on F: every formula is homogeneous in the length unit.
 *
 * Ranges (why nothing wraps). analyse accepts a chain only when every
 * canonical |a|, |d| <= 2^29 raw (else DH_IKC_WHY_PATH); the solver returns
 * DH_ERR_OVERFLOW when a wrist-centre component or the planar vector
 * (vx, vy) exceeds 2^30 raw (2^14 units at F = 16). Then every square is
 * below 2^60, every sum of the few squares used below 2^62 (the domain of
 * dh_q_isqrt62), and each atan2 argument pair is an int64 brought below
 * 2^30 by one common rounding shift (ikq_atan2: only the ratio matters).
 * Rotation entries of a rigid target (within 2^-10 of orthonormal, and
 * every entry <= 1.1, checked first) stay below 1.001 in magnitude, so
 * their rotated copies are rounded without a range check and are never
 * INT32_MIN; the model's pre/post rotations are checked for entries <= 1.1
 * by dh_ikc_q, which bounds every three-term sum of ikq_t06 below 2^63.
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
 * Measured under QEMU on Cortex-M0 (-O2): 43,900 instructions per call.
 */
#include "dhmath/ikc.h"
#include "dhmath/frame.h"
#include "dhmath/trig.h"
#include "ikc_impl.h"
#include "../internal/dh_qmath.h"

#define Q16_180 DH_IKC_Q16_180
#define Q16_360 DH_IKC_Q16_360
/* |cos alpha| or |sin alpha| this small counts as zero (6e-8) */
#define IKQ_TOL_ALPHA 64
/* rigidity of the target, base and tool: |R^T R - I| <= 2^-10, entries <= 1.1 */
#define IKQ_ENTRY_MAX 0x46666666u
#define IKQ_RIGID_TOL ((int32_t)1 << 20)
/* wrist singular: |m13|, |m23| <= 2^-19 (orientation error <= 2.7e-6 rad) */
#define IKQ_SING_WRIST ((int32_t)1 << 11)
/* Tolerances on lengths are counted in LSB, so that the solver does the
 * same on the same raw values for every DH_QPOS_FRAC (units quoted for
 * DH_QPOS_FRAC 16, robots in mm). Shoulder singular: wrist centre within
 * 16 LSB (2.4e-4 units) of axis 1. */
#define IKQ_SING_AXIS 16
/* reach tolerance: 2^7 LSB (2^-9 units) of the wrist centre, as a bound
 * on a squared length: 2^7 (sum of the magnitudes involved) */
#define IKQ_REACH_SH 7
/* stretched / folded elbow: within 8 LSB (2^-13 units) */
#define IKQ_FOLD_SH 3
/* canonical lengths and intermediate lengths, raw */
#define IKQ_LEN_LIM ((int32_t)1 << 29)
#define IKQ_POS_LIM ((int64_t)1 << 30)

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

static const dh_frame_q ikq_identity = {
    {{DH_Q_ONE30, 0, 0}, {0, DH_Q_ONE30, 0}, {0, 0, DH_Q_ONE30}}, {0, 0, 0}};

/* ---- small helpers ------------------------------------------------------ */

/* any int32 angle -> (-180, 180] (32-bit remainder, no negation of INT32_MIN) */
static int32_t ikq_reduce(int32_t x)
{
    const uint32_t a = dh_q_abs_u32(x) % (uint32_t)Q16_360;
    int32_t r = (int32_t)a;
    if (x < 0) r = -r;
    return dh_ikc_wrap180_q_(r);
}

DH_INLINE int32_t ikq_sign(int32_t x)
{
    return x < 0 ? -1 : 1;
}

DH_INLINE int ikq_small(int32_t x)
{
    return x <= IKQ_TOL_ALPHA && x >= -IKQ_TOL_ALPHA;
}

DH_INLINE uint64_t ikq_abs64(int64_t x)
{
    return x < 0 ? (uint64_t)0 - (uint64_t)x : (uint64_t)x;
}

DH_INLINE int32_t ikq_r30(int64_t x)
{
    return dh_q_rnd30_fit(x);
}

/* round(n / d) for |n| < 2^62, 0 < d < 2^32, quotient below 2^31 in
 * magnitude: restoring division bit by bit (no 64-bit division) */
static DH_NOINLINE int32_t ikq_div_rnd(int64_t n, uint64_t d)
{
    uint64_t a = ikq_abs64(n) + (d >> 1), r = 0u, qt = 0u;
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

/* atan2 of two int64 of a common scale (|.| < 2^63): both rounded by the
 * same shift below 2^30 + 1, then dh_atan2_q; (0, 0) gives 0 */
DH_NOINLINE int32_t dh_ikc_atan2_q_(int64_t y, int64_t x)
{
    uint32_t hi = (uint32_t)((ikq_abs64(y) | ikq_abs64(x)) >> 30);
    unsigned s = 0u;
    dh_q16 a = 0;
    while (hi != 0u) {
        hi >>= 1;
        s++;
    }
    if (s != 0u) {
        y = dh_q_rshr(y, s);
        x = dh_q_rshr(x, s);
    }
    (void)dh_atan2_q((int32_t)y, (int32_t)x, &a);
    return a;
}

/* acc + c v, |c| <= 2^30: a factor 0 or +-1.0 (exact twists, sines and
 * cosines of multiples of 90 degrees, zero tool offsets) costs no
 * multiplication (the products of Cortex-M0 are 16-bit partials) */
DH_NOINLINE int64_t dh_ikc_mla_q_(int64_t acc, int32_t c, int32_t v)
{
    if (c == 0) return acc;
    if (c == DH_Q_ONE30) return acc + (int64_t)v * DH_Q_ONE30;
    if (c == -DH_Q_ONE30) return acc - (int64_t)v * DH_Q_ONE30;
    return dh_q_mla64(acc, c, v);
}

/* v <- Rz(t)^T v in the plane (x, y): (c x + s y, c y - s x) */
static DH_NOINLINE void ikq_rot2(int32_t *x, int32_t *y, int32_t c, int32_t s)
{
    const int32_t a = *x, b = *y;
    *x = ikq_r30(dh_ikc_mla_q_(dh_ikc_mla_q_(0, c, a), s, b));
    *y = ikq_r30(dh_ikc_mla_q_(dh_ikc_mla_q_(0, c, b), -s, a));
}

/* 1 when the columns c0, c1, c2 (Q2.30) are within 2^-10 of orthonormal
 * with det > 0; entries above 1.1 in magnitude fail first, which bounds
 * every three-term sum below (3.63 2^61 < 2^63) */
static DH_NOINLINE int ikq_rigid3(const int32_t *c0, const int32_t *c1, const int32_t *c2)
{
    const int32_t *c[3];
    unsigned a, b, i;
    int32_t x, y, z;
    c[0] = c0;
    c[1] = c1;
    c[2] = c2;
    for (a = 0; a < 3u; a++)
        for (i = 0; i < 3u; i++)
            if (dh_q_abs_u32(c[a][i]) > IKQ_ENTRY_MAX) return 0;
    for (a = 0; a < 3u; a++)
        for (b = a; b < 3u; b++) {
            /* the dot product rounded in 64 bits: up to 3.63 (above the
             * int32 range of Q2.30) before the identity is subtracted */
            int64_t d = dh_q_rshr(dh_q_mla64(dh_q_mla64(dh_q_mul64(c[a][0], c[b][0]), c[a][1], c[b][1]), c[a][2], c[b][2]),
                                  30u);
            if (a == b) d -= DH_Q_ONE30;
            if (d > IKQ_RIGID_TOL || d < -IKQ_RIGID_TOL) return 0;
        }
    x = ikq_r30(dh_q_mul64(c1[1], c2[2]) - dh_q_mul64(c1[2], c2[1]));
    y = ikq_r30(dh_q_mul64(c1[2], c2[0]) - dh_q_mul64(c1[0], c2[2]));
    z = ikq_r30(dh_q_mul64(c1[0], c2[1]) - dh_q_mul64(c1[1], c2[0]));
    return dh_q_mla64(dh_q_mla64(dh_q_mul64(c0[0], x), c0[1], y), c0[2], z) > 0;
}

DH_INLINE int ikq_rigid(const dh_frame_q *F)
{
    return ikq_rigid3(F->r[0], F->r[1], F->r[2]);
}

/* F <- F^-1 for a rigid F (entries <= 1.1): R^T, -R^T p; 1 on overflow */
static DH_NOINLINE int ikq_inv(dh_frame_q *F)
{
    int ovf = 0;
    int32_t q[3], t;
    unsigned i;
    for (i = 0; i < 3u; i++)
        q[i] = dh_q_pos_rnd30(0, -dh_q_mla64(dh_q_mla64(dh_q_mul64(F->r[i][0], F->p[0]), F->r[i][1], F->p[1]), F->r[i][2], F->p[2]), &ovf);
    t = F->r[0][1];
    F->r[0][1] = F->r[1][0];
    F->r[1][0] = t;
    t = F->r[0][2];
    F->r[0][2] = F->r[2][0];
    F->r[2][0] = t;
    t = F->r[1][2];
    F->r[1][2] = F->r[2][1];
    F->r[2][1] = t;
    F->p[0] = q[0];
    F->p[1] = q[1];
    F->p[2] = q[2];
    return ovf;
}

/* ---- analysis ----------------------------------------------------------- */

/* spherical wrist of the canonical chain: a4 = a5 = d5 = 0, alpha4, alpha5 not 0 or 180 */
static int ikq_spherical(const dh_ikc_model_q *m)
{
    return m->a[3] == 0 && m->a[4] == 0 && m->d[4] == 0 && !ikq_small(m->sa[3]) && !ikq_small(m->sa[4]);
}

/* canonical chain, limits, pre/post inverses (m->n set) */
static DH_NOINLINE dh_status ikq_chain(const dh_robot *r, dh_ikc_model_q *m)
{
    const uint32_t n = r->n;
    const int mdh = (r->conv == DH_CONV_MODIFIED);
    uint32_t i;
    int bad = 0;

    for (i = 0; i < n; i++) {
        const dh_joint *j = &r->joint[i];
        const dh_joint *nx = mdh ? ((i + 1u < n) ? &r->joint[i + 1u] : NULL) : j;
        if (j->type == DH_JOINT_PRISMATIC) m->prismatic |= 1u << i;
        m->d[i] = j->d_q;
        /* revolute: the offset modulo 360, in (-180, 180] (saves a
         * remainder per joint and solution) */
        m->off[i] = (j->type == DH_JOINT_PRISMATIC) ? j->theta_q : ikq_reduce(j->theta_q);
        m->qmin[i] = j->qmin_q;
        m->qmax[i] = j->qmax_q;
        if (nx != NULL) {
            m->a[i] = nx->a_q;
            m->sa[i] = nx->sa_q;
            m->ca[i] = nx->ca_q;
        } else {
            m->a[i] = 0;
            m->sa[i] = 0;
            m->ca[i] = DH_Q_ONE30;
        }
        if (dh_q_abs_u32(m->a[i]) > (uint32_t)IKQ_LEN_LIM || dh_q_abs_u32(m->d[i]) > (uint32_t)IKQ_LEN_LIM) bad = 1;
    }
    if (!ikq_rigid(&r->base_q) || !ikq_rigid(&r->tool_q)) {
        m->why = DH_IKC_WHY_PATH;
        return DH_ERR_NOT_RIGID;
    }
    m->pre_inv = r->base_q;
    if (mdh) {
        /* pre = base Rx(alpha_0) Tx(a_0): columns n, c o + s a, c a - s o;
         * position p + a_0 n */
        dh_frame_q *F = &m->pre_inv;
        const int32_t sa = r->joint[0].sa_q, ca = r->joint[0].ca_q;
        int ovf = 0;
        for (i = 0; i < 3u; i++) {
            const int32_t o = F->r[1][i], a = F->r[2][i];
            F->r[1][i] = dh_q_rnd30(dh_q_mla64(dh_q_mul64(ca, o), sa, a), &ovf);
            F->r[2][i] = dh_q_rnd30(dh_q_mul64(ca, a) - dh_q_mul64(sa, o), &ovf);
            F->p[i] = dh_q_pos_rnd30(F->p[i], dh_q_mul64(r->joint[0].a_q, F->r[0][i]), &ovf);
        }
        if (ovf) bad = 1;
    }
    m->post_inv = r->tool_q;
    if (ikq_inv(&m->pre_inv) || ikq_inv(&m->post_inv)) bad = 1;
    if (bad) {
        m->why = DH_IKC_WHY_PATH;
        return DH_ERR_UNAVAILABLE;
    }
    return DH_OK;
}

/* family, or the reason for none */
static DH_NOINLINE void ikq_classify(dh_ikc_model_q *m)
{
    const uint32_t p = m->prismatic;
    m->why = DH_IKC_WHY_NONE;
    if (m->n == 6u) {
        if (dh_ikc_detect_wrist_q_(m)) return;
        if (dh_ikc_detect_par234_q_(m)) {
            m->kind = DH_IKC_PARALLEL_234;
            return;
        }
        m->kind = DH_IKC_NONE;
        if (p != 0u && p != 0x4u)
            m->why = DH_IKC_WHY_JOINTS;
        else if (ikq_spherical(m))
            m->why = DH_IKC_WHY_AXES;
        else
            m->why = DH_IKC_WHY_WRIST;
    } else if (m->n == 4u) {
        if (dh_ikc_detect_scara_q_(m)) {
            m->kind = DH_IKC_SCARA;
            return;
        }
        m->kind = DH_IKC_NONE;
        m->why = (p == 0x4u) ? DH_IKC_WHY_AXES : DH_IKC_WHY_JOINTS;
    } else {
        m->kind = DH_IKC_NONE;
        m->why = DH_IKC_WHY_JOINTS;
    }
}

dh_status dh_ikc_analyse_q(const dh_robot *r, dh_ikc_model_q *m)
{
    uint32_t i;
    dh_status st;

    DH_ASSERT(r != NULL && m != NULL);
    memset(m, 0, sizeof *m);
    m->kind = DH_IKC_NONE;
    m->why = DH_IKC_WHY_JOINTS;
    m->pre_inv = ikq_identity;
    m->post_inv = ikq_identity;
    if ((r->conv != DH_CONV_STANDARD && r->conv != DH_CONV_MODIFIED) || r->n > DH_MAX_JOINTS) return DH_ERR_ARG;
    for (i = 0; i < r->n; i++)
        if (r->joint[i].type != DH_JOINT_REVOLUTE && r->joint[i].type != DH_JOINT_PRISMATIC) return DH_ERR_ARG;
    if ((r->flags & DH_ROBOT_HAS_Q) == 0u) {
        m->why = DH_IKC_WHY_PATH;
        return DH_ERR_UNAVAILABLE;
    }
    if (r->n == 0u || r->n > DH_IKC_JOINTS) return DH_ERR_UNAVAILABLE;
    m->n = r->n;
    st = ikq_chain(r, m);
    if (st != DH_OK) return st;
    ikq_classify(m);
    return (m->kind != DH_IKC_NONE) ? DH_OK : DH_ERR_UNAVAILABLE;
}

/* ---- wrist families: detector ------------------------------------------- */

/* C = Rx(alpha2) Rz(theta3) Rx(alpha3) (RRP) into k[K_C..] */
static DH_NOINLINE void ikq_c_rrp(dh_ikc_model_q *m, int32_t s3, int32_t c3)
{
    int32_t *C = &m->k[K_C];
    const int32_t sa3 = m->sa[2], ca3 = m->ca[2], sa2 = m->sa[1], ca2 = m->ca[1];
    int32_t r1[3], r2[3];
    unsigned j;
    /* Rz(theta3) Rx(alpha3) = [c3, -s3 ca3, s3 sa3; s3, c3 ca3, -c3 sa3; 0, sa3, ca3] */
    C[0] = c3;
    C[1] = ikq_r30(-dh_q_mul64(s3, ca3));
    C[2] = ikq_r30(dh_q_mul64(s3, sa3));
    r1[0] = s3;
    r1[1] = ikq_r30(dh_q_mul64(c3, ca3));
    r1[2] = ikq_r30(-dh_q_mul64(c3, sa3));
    r2[0] = 0;
    r2[1] = sa3;
    r2[2] = ca3;
    for (j = 0; j < 3u; j++) {
        C[3u + j] = ikq_r30(dh_q_mul64(ca2, r1[j]) - dh_q_mul64(sa2, r2[j]));
        C[6u + j] = ikq_r30(dh_q_mla64(dh_q_mul64(sa2, r1[j]), ca2, r2[j]));
    }
}

int dh_ikc_detect_wrist_q_(dh_ikc_model_q *m)
{
    int32_t *k = m->k;
    const uint32_t p = m->prismatic;
    int32_t e, s3, c3;
    int64_t h;

    if (m->n != 6u || !ikq_spherical(m) || !ikq_small(m->ca[3]) || !ikq_small(m->ca[4]) || !ikq_small(m->ca[0]))
        return 0;
    k[K_TAU1] = ikq_sign(m->sa[0]);
    k[K_S4] = ikq_sign(m->sa[3]);
    k[K_S5] = ikq_sign(m->sa[4]);
    k[K_W] = m->a[5];
    k[K_W + 1] = ikq_r30(dh_q_mul64(m->d[5], m->sa[5]));
    k[K_W + 2] = ikq_r30(dh_q_mul64(m->d[5], m->ca[5]));
    e = ikq_r30(dh_q_mul64(m->sa[2], m->d[3]));
    if (p == 0u) {
        int32_t sig;
        uint32_t rho;
        if (!ikq_small(m->sa[1]) || m->a[1] == 0) return 0;
        sig = ikq_sign(m->ca[1]);
        h = (int64_t)m->d[2] + ikq_r30(dh_q_mul64(m->ca[2], m->d[3]));
        h = (int64_t)m->d[1] + (sig > 0 ? h : -h);
        {
            /* delta = rho - |a2| = (rho^2 - a2^2) / (rho + |a2|), the
             * numerator exact: 2 |a2| rho = a2^2 + rho^2 - delta^2 then
             * keeps the folded elbow exact to the rounding of delta */
            const int64_t r2 = dh_q_mla64(dh_q_mul64(m->a[2], m->a[2]), e, e);
            const int64_t num = r2 - dh_q_mul64(m->a[1], m->a[1]);
            rho = dh_q_isqrt62((uint64_t)r2);
            if (rho == 0u) return 0;
            k[K_RHO] = ikq_div_rnd(num, (uint64_t)rho + dh_q_abs_u32(m->a[1]));
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
        if (!ikq_small(m->ca[1])) return 0;
        tau2 = ikq_sign(m->sa[1]);
        dh_sincos_q(m->off[2], &s3, &c3);
        gx = ikq_r30(dh_q_mla64(dh_q_mul64(c3, m->a[2]), s3, e));
        gy = ikq_r30(dh_q_mul64(s3, m->a[2]) - dh_q_mul64(c3, e));
        x2 = (int64_t)m->a[1] + gx;
        h = (int64_t)m->d[1] + (tau2 > 0 ? gy : -gy);
        k[K_SIG] = tau2;
        k[K_E] = (int32_t)x2;
        k[K_LOFF] = ikq_r30(dh_q_mul64(m->ca[2], m->d[3]));
        ikq_c_rrp(m, s3, c3);
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
 * (dh_ikc_impl.h); solution slot 4 s + 2 b + w holds shoulder branch s,
 * elbow branch b, wrist branch w. ikq_centre leaves the wrist centre in
 * sol[4] (o, vy, u, shoulder singular); ikq_shoulder puts each shoulder
 * branch's data into its elbow-2 slots (slot 4 s + 2: t1, vx, flags, M's x
 * column after the shoulder rotation; slot 4 s + 3: vy, the elbow pair,
 * the z column); ikq_arm_* writes q[0..2] of slots 4 s and 4 s + 2 once it
 * has read them, and ikq_wrist reads its columns before it writes a pair
 * of slots. Empty slots carry IKQ_EMPTY flags and are squeezed out at the
 * end. The chain is front end -> solver -> one helper -> dh_sincos_q or
 * dh_atan2_q.
 */
#define IKQ_EMPTY 0xFFFFFFFFu
#define IKQ_ABSENT ((int32_t)-1)

/* C^T v, C row-major (column i of C dotted with v) */
static DH_NOINLINE void ikq_ct(const int32_t *C, int32_t *v)
{
    const int32_t x = v[0], y = v[1], z = v[2];
    unsigned i;
    for (i = 0; i < 3u; i++) v[i] = ikq_r30(dh_ikc_mla_q_(dh_ikc_mla_q_(dh_ikc_mla_q_(0, C[i], x), C[3u + i], y), C[6u + i], z));
}

/* wrist centre o, vy and u into sol[4].q (o, vy, u, shoulder singular);
 * 1 on overflow, -1 when the shoulder cannot reach, else 0 */
static DH_NOINLINE int ikq_centre(const dh_ikc_model_q *m, dh_ikc_sol_q *sol)
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
        if (ikq_abs64(v) > (uint64_t)IKQ_POS_LIM) return 1;
        o[i] = (int32_t)v;
    }
    v = (int64_t)o[2] - m->d[0];
    if (k[K_TAU1] < 0) v = -v;
    if (ikq_abs64(v) > (uint64_t)IKQ_POS_LIM) return 1;
    o[3] = (int32_t)v;
    v = dh_q_mla64(dh_q_mul64(o[0], o[0]), o[1], o[1]) - dh_q_mul64(k[K_H], k[K_H]);
    /* inside the cylinder of radius |h| by less than 2^7 LSB: u = 0 */
    if (v < -(((int64_t)dh_q_abs_u32(o[0]) + (int64_t)dh_q_abs_u32(o[1]) + (int64_t)dh_q_abs_u32(k[K_H]) + 1)
              << IKQ_REACH_SH))
        return -1;
    o[5] = dh_q_abs_u32(o[0]) <= (uint32_t)IKQ_SING_AXIS && dh_q_abs_u32(o[1]) <= (uint32_t)IKQ_SING_AXIS;
    o[4] = (o[5] || v <= 0) ? 0 : (int32_t)dh_q_isqrt62((uint64_t)v);
    return 0;
}

/* u of shoulder branch s into slot 4 s + 2 q[0]: +-o[4], or the boundary
 * value u' when the planar point (u - a1, vy) lies beyond the arm's reach
 * (|v| below the folded radius |delta| (RRR) or |X2| (RRP), or above the
 * stretched radius |a2| + rho (RRR)) and u' = a1 +- sqrt(r^2 - vy^2) on
 * that radius r, of the branch's sign and nearest u, satisfies
 * |u'^2 - u^2| <= 2^IKQ_REACH_SH (|ox| + |oy| + 1): u^2 = ox^2 + oy^2 - h^2
 * moves by 2 (ox dox + oy doy) when the wrist centre moves, so u' is u for
 * a wrist centre at most 2^(IKQ_REACH_SH - 1) sqrt(2) LSB away. Near the
 * shoulder cylinder (u small) a rounding of the target moves u by much
 * more than a rounding; this keeps such targets on the boundary solvable. */
static DH_NOINLINE void ikq_reach(const dh_ikc_model_q *m, dh_ikc_sol_q *sol, unsigned s)
{
    const int32_t *k = m->k, *o = sol[4].q;
    const int32_t u = s ? -o[4] : o[4], vy = o[3];
    const int64_t vx = (int64_t)u - m->a[0];
    int64_t v2, r2, d;
    uint32_t w;
    int32_t c[2];
    unsigned i;

    sol[4u * s + 2u].q[0] = u;
    if (o[5] || ikq_abs64(vx) > (uint64_t)IKQ_POS_LIM) return;
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
        if ((s ? c[i] > 0 : c[i] < 0) || ikq_abs64(c[i]) > (uint64_t)IKQ_POS_LIM) continue;
        dd = dh_q_mul64(c[i], c[i]) - dh_q_mul64(u, u);
        if (ikq_abs64(dd) > ((uint64_t)dh_q_abs_u32(o[0]) + dh_q_abs_u32(o[1]) + 1u) << IKQ_REACH_SH) continue;
        if (d < 0 || (int64_t)ikq_abs64(du) < d) {
            d = (int64_t)ikq_abs64(du);
            sol[4u * s + 2u].q[0] = c[i];
        }
    }
}

/* shoulder branch s: joint 1 and the shoulder part of M into slots 4 s + 2, 4 s + 3 */
static DH_NOINLINE int ikq_shoulder(const dh_ikc_model_q *m, dh_ikc_sol_q *sol, unsigned s, int32_t cref0)
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
        u = ikq_r30(dh_q_mla64(dh_q_mul64(cs, o[0]), sn, o[1]));
    } else {
        const int32_t th = k[K_TAU1] > 0 ? k[K_H] : -k[K_H];
        t1 = dh_ikc_atan2_q_(dh_q_mla64(dh_q_mul64(th, o[0]), u, o[1]), dh_q_mul64(u, o[0]) - dh_q_mul64(th, o[1]));
        dh_sincos_q(t1, &sn, &cs);
    }
    v = (int64_t)u - m->a[0];
    if (ikq_abs64(v) > (uint64_t)IKQ_POS_LIM) return 1;
    /* Rx(alpha1)^T Rz(t1)^T applied to R06 e_x and to R06 Rx(alpha6)^T e_z */
    for (i = 0; i < 3u; i++) {
        d0->q[3u + i] = c0[i];
        d1->q[3u + i] = ikq_r30(dh_q_mla64(dh_q_mul64(m->sa[5], c1[i]), m->ca[5], c2[i]));
    }
    ikq_rot2(&d0->q[3], &d0->q[4], cs, sn);
    ikq_rot2(&d1->q[3], &d1->q[4], cs, sn);
    ikq_rot2(&d0->q[4], &d0->q[5], m->ca[0], m->sa[0]);
    ikq_rot2(&d1->q[4], &d1->q[5], m->ca[0], m->sa[0]);
    d0->q[0] = t1;
    d0->q[1] = (int32_t)v;
    d0->q[2] = (int32_t)((o[5] ? DH_IKC_SING_SHOULDER : 0u) | (s ? DH_IKC_SHOULDER_ALT : 0u));
    d1->q[0] = o[3];
    return 0;
}

/* shift of a non-negative int64 below 2^31 */
unsigned dh_ikc_fit31_q_(int64_t v)
{
    uint32_t hi = (uint32_t)((uint64_t)v >> 31);
    unsigned s = 0u;
    while (hi != 0u) {
        hi >>= 1;
        s++;
    }
    return s;
}

/* write arm angles (t1, t2, t3) and flags into slot j */
DH_INLINE void ikq_put_arm(dh_ikc_sol_q *d, int32_t t1, int32_t t2, int32_t t3, uint32_t flags)
{
    d->q[0] = t1;
    d->q[1] = t2;
    d->q[2] = t3;
    d->flags = flags;
}

/* RRR elbow of shoulder s: the pair (sqrt((D - K)(D + K)), K) scaled to
 * int32 into slot 4 s + 3 q[1..2]; SING_ELBOW or IKQ_ABSENT into the
 * shoulder's flags */
static DH_NOINLINE void ikq_elbow_rrr(const dh_ikc_model_q *m, dh_ikc_sol_q *sol, unsigned s)
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
    /* beyond stretched or folded by at most 2^(IKQ_REACH_SH - 1) sqrt(2)
     * LSB of |v| (|v|^2 moves by 2 |v| d|v|; ds and df are exact products
     * but for delta's rounding of 1 LSB): solved at the boundary */
    tol = ((int64_t)dh_q_abs_u32(vx) + (int64_t)dh_q_abs_u32(vy) + 1) << IKQ_REACH_SH;
    if (ds < -tol || df < -tol) {
        d0->q[2] = IKQ_ABSENT;
        return;
    }
    /* |v|^2 within tol = 2 |v| 4 LSB of stretched (ds = 0) or folded
     * (df = 0) counts as exactly there; the wrist centre then moves by
     * tol / (|v| + |a2 - rho|) <= 8 LSB */
    tol = (((int64_t)dh_q_abs_u32(vx) + (int64_t)dh_q_abs_u32(vy)) << IKQ_FOLD_SH) + 1;
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
    while ((((uint64_t)S | ikq_abs64(K)) >> s1) >= ((uint64_t)1 << 30)) s1++;
    d1->q[1] = (s1 != 0u) ? (int32_t)dh_q_rshr((int64_t)S, s1) : (int32_t)S;
    d1->q[2] = (s1 != 0u) ? (int32_t)dh_q_rshr(K, s1) : (int32_t)K;
}

/* RRR arm angles of shoulder s: t3 = phi +- psi, then t2, into slots 4 s,
 * 4 s + 2; psi and sin/cos t3 go to q[3..5] of slot 4 s (free until its
 * wrist), so that no local needs an address */
static DH_NOINLINE void ikq_arm_rrr(const dh_ikc_model_q *m, dh_ikc_sol_q *sol, unsigned s)
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
        A = m->a[1] + ikq_r30(dh_q_mla64(dh_q_mul64(m->a[2], w[1]), k[K_E], w[0]));
        B = ikq_r30(dh_q_mul64(m->a[2], w[0]) - dh_q_mul64(k[K_E], w[1]));
        if (k[K_SIG] < 0) B = -B;
        ikq_put_arm(&sol[4u * s + 2u * b], t1,
                    dh_ikc_atan2_q_(dh_q_mul64(A, vy) - dh_q_mul64(B, vx), dh_q_mla64(dh_q_mul64(A, vx), B, vy)), t3,
                    f0 | (b ? DH_IKC_ELBOW_ALT : 0u));
    }
}

/* RRP: the extension L of shoulder s into slot 4 s + 3 q[1] */
static DH_NOINLINE void ikq_elbow_rrp(const dh_ikc_model_q *m, dh_ikc_sol_q *sol, unsigned s)
{
    const int32_t x2 = m->k[K_E];
    dh_ikc_sol_q *d0 = &sol[4u * s + 2u], *d1 = &sol[4u * s + 3u];
    const int32_t vx = d0->q[1], vy = d1->q[0];
    int64_t L2 = dh_q_mla64(dh_q_mul64(vx, vx), vy, vy) - dh_q_mul64(x2, x2);
    /* as the RRR elbow: within 2^7 LSB of L = 0 counts as there */
    if (L2 < -(((int64_t)dh_q_abs_u32(vx) + (int64_t)dh_q_abs_u32(vy) + (int64_t)dh_q_abs_u32(x2) + 1)
               << IKQ_REACH_SH)) {
        d0->q[2] = IKQ_ABSENT;
        return;
    }
    d1->q[1] = (L2 <= 0) ? 0 : (int32_t)dh_q_isqrt62((uint64_t)L2);
    if (d1->q[1] == 0) d0->q[2] |= (int32_t)DH_IKC_SING_ELBOW;
}

/* RRP arm of shoulder s: t2 and d3 for +-L into slots 4 s, 4 s + 2 */
static DH_NOINLINE void ikq_arm_rrp(const dh_ikc_model_q *m, dh_ikc_sol_q *sol, unsigned s)
{
    const int32_t *k = m->k;
    const dh_ikc_sol_q *d0 = &sol[4u * s + 2u], *d1 = &sol[4u * s + 3u];
    const int32_t t1 = d0->q[0], vx = d0->q[1], vy = d1->q[0], L = d1->q[1], x2 = k[K_E];
    const uint32_t f0 = (uint32_t)d0->q[2];
    unsigned b, nl = (L == 0) ? 1u : 2u;

    for (b = 0; b < nl; b++) {
        const int32_t l = b ? -L : L, tl = k[K_SIG] > 0 ? l : -l;
        ikq_put_arm(&sol[4u * s + 2u * b], t1,
                    dh_ikc_atan2_q_(dh_q_mla64(dh_q_mul64(x2, vy), tl, vx), dh_q_mul64(x2, vx) - dh_q_mul64(tl, vy)),
                    l - k[K_LOFF], f0 | (b ? DH_IKC_ELBOW_ALT : 0u));
    }
}

/* joints 4..6 of the arm in slot j = 4 s + 2 b, its flip into slot j + 1;
 * the two columns of M are worked on in place in q[3..5] of these slots
 * (for j = 4 s + 2 they are the shoulder's copies, read for the last time) */
static DH_NOINLINE void ikq_wrist(const dh_ikc_model_q *m, dh_ikc_sol_q *sol, unsigned j, int32_t cref3)
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
    ikq_rot2(&n[0], &n[1], sc[1], sc[0]);
    ikq_rot2(&z[0], &z[1], sc[1], sc[0]);
    ikq_ct(&k[K_C], n);
    ikq_ct(&k[K_C], z);
    sing = (dh_q_abs_u32(z[0]) <= (uint32_t)IKQ_SING_WRIST && dh_q_abs_u32(z[1]) <= (uint32_t)IKQ_SING_WRIST);
    if (sing)
        t4 = cref3;
    else
        t4 = dh_ikc_atan2_q_(k[K_S5] > 0 ? z[1] : -z[1], k[K_S5] > 0 ? z[0] : -z[0]);
    dh_sincos_q(t4, &sc[0], &sc[1]);
    /* s5 into z[0], c5 into z[2] */
    z[0] = ikq_r30(dh_q_mla64(dh_q_mul64(sc[1], z[0]), sc[0], z[1]));
    if (k[K_S5] < 0) z[0] = -z[0];
    if (k[K_S4] == k[K_S5]) z[2] = -z[2];
    /* (s5, c5) = (0, 0) only for a degenerate M (saturated entries): t5 = 0
     * then, as dh_ikc_atan2_q_ answers (0, 0) */
    t5 = 0;
    (void)dh_atan2_q(z[0], z[2], &t5);
    /* m' = Rz(-t4) M e_x into n[0], n[1] */
    ikq_rot2(&n[0], &n[1], sc[1], sc[0]);
    if (k[K_S4] == k[K_S5]) n[1] = -n[1];
    n[0] = dh_ikc_atan2_q_(n[1], ((k[K_S4] > 0) ? dh_q_mla64(dh_q_mul64(z[2], n[0]), z[0], n[2])
                                             : dh_q_mul64(z[2], n[0]) - dh_q_mul64(z[0], n[2])) >> 30);
    n[2] = n[0];
    n[0] = t4;
    n[1] = t5;
    if (sing) {
        d->flags |= DH_IKC_SING_WRIST;
        d[1].flags = IKQ_EMPTY;
        return;
    }
    d[1].q[0] = d->q[0];
    d[1].q[1] = d->q[1];
    d[1].q[2] = d->q[2];
    z[0] = dh_ikc_wrap180_q_(t4 + Q16_180);
    z[1] = dh_ikc_wrap180_q_(-t5);
    z[2] = dh_ikc_wrap180_q_(n[2] + Q16_180);
    d[1].flags = d->flags | DH_IKC_WRIST_ALT;
}

dh_status dh_ikc_wrist_q_(const dh_ikc_model_q *m, const int32_t *q_ref, dh_ikc_sol_q *sol, uint32_t *count)
{
    uint32_t s, j, cnt = 0, nsh;
    int32_t cref3;
    int st;

    *count = 0;
    st = ikq_centre(m, sol);
    if (st > 0) return DH_ERR_OVERFLOW;
    if (st < 0) return DH_OK; /* unreachable */
    nsh = sol[4].q[5] ? 1u : 2u;
    for (s = 0; s < nsh; s++) {
        ikq_reach(m, sol, s);
        /* u = 0 on both branches: one solution */
        if (s == 1u && sol[4].q[4] == 0 && sol[6].q[0] == 0) {
            nsh = 1u;
            break;
        }
        if (ikq_shoulder(m, sol, s, dh_ikc_cref_q_(m, q_ref, 0u))) return DH_ERR_OVERFLOW;
    }
    for (j = 0; j < DH_IKC_MAX_SOL; j++) sol[j].flags = IKQ_EMPTY;
    if (nsh == 1u) sol[6].q[2] = IKQ_ABSENT;
    cref3 = dh_ikc_cref_q_(m, q_ref, 3u);
    for (s = 0; s < 2u; s++) {
        if (sol[4u * s + 2u].q[2] == IKQ_ABSENT) continue;
        if (m->kind == DH_IKC_WRIST_RRR)
            ikq_elbow_rrr(m, sol, s);
        else
            ikq_elbow_rrp(m, sol, s);
        if (sol[4u * s + 2u].q[2] == IKQ_ABSENT) continue;
        if (m->kind == DH_IKC_WRIST_RRR)
            ikq_arm_rrr(m, sol, s);
        else
            ikq_arm_rrp(m, sol, s);
        for (j = 4u * s; j <= 4u * s + 2u; j += 2u)
            if (sol[j].flags != IKQ_EMPTY) ikq_wrist(m, sol, j, cref3);
    }
    for (j = 0; j < DH_IKC_MAX_SOL; j++)
        if (sol[j].flags != IKQ_EMPTY) {
            if (j != cnt) sol[cnt] = sol[j];
            cnt++;
        }
    *count = cnt;
    return DH_OK;
}

/* ---- front end: solve --------------------------------------------------- */

/* kind known, n the family's, pre/post rotation entries <= 1.1 (the
 * products of ikq_t06 cannot wrap), revolute offsets in (-180, 180] */
static DH_NOINLINE int ikq_model_ok(const dh_ikc_model_q *m)
{
    unsigned c, i;
    for (c = 0; c < 3u; c++)
        for (i = 0; i < 3u; i++)
            if (dh_q_abs_u32(m->pre_inv.r[c][i]) > IKQ_ENTRY_MAX || dh_q_abs_u32(m->post_inv.r[c][i]) > IKQ_ENTRY_MAX)
                return 0;
    for (i = 0; i < m->n && i < DH_IKC_JOINTS; i++)
        if (((m->prismatic >> i) & 1u) == 0u && (m->off[i] > Q16_180 || m->off[i] <= -Q16_180)) return 0;
    switch (m->kind) {
    case DH_IKC_WRIST_RRR:
    case DH_IKC_WRIST_RRP:
    case DH_IKC_PARALLEL_234:
        return m->n == 6u;
    case DH_IKC_SCARA:
        return m->n == 4u;
    default:
        return 0;
    }
}

/* q (in (-180, 180]) shifted by a multiple of 360 into [lo, hi], nearest
 * ref (ties: the lower); *in = 0 when no shift is inside (q returned) */
static DH_NOINLINE int32_t ikq_shift(int32_t q, int32_t lo, int32_t hi, int32_t ref, int *in)
{
    const int64_t d = (int64_t)q - lo;
    const uint32_t P = (uint32_t)Q16_360;
    uint32_t rem, kmax, kk;
    int64_t first, c0;

    *in = 1;
    if (lo > hi) return q;
    if ((int64_t)hi - lo < 3 * (int64_t)P) {
        /* up to three candidates: no division */
        int32_t best;
        int64_t cand = q;
        while (cand - (int64_t)P >= lo) cand -= P;
        while (cand < lo) cand += P;
        if (cand > hi) {
            *in = 0;
            return q;
        }
        best = (int32_t)cand;
        for (cand += P; cand <= hi; cand += P)
            if (ikq_abs64(cand - ref) < ikq_abs64((int64_t)best - ref)) best = (int32_t)cand;
        return best;
    }
    rem = (uint32_t)ikq_abs64(d) % P;
    if (d < 0 && rem != 0u) rem = P - rem;
    first = (int64_t)lo + rem;
    if (first > hi) {
        *in = 0;
        return q;
    }
    kmax = (uint32_t)((int64_t)hi - first) / P;
    kk = 0;
    if (ref > first) {
        kk = (uint32_t)((int64_t)ref - first) / P;
        if (kk >= kmax) {
            kk = kmax;
        } else {
            c0 = first + (int64_t)kk * P;
            if ((int64_t)ref - c0 > c0 + P - ref) kk++;
        }
    }
    return (int32_t)(first + (int64_t)kk * P);
}

/* raw canonical solutions -> joint values, shifts, limits, compaction;
 * the count kept, or IKQ_FINISH_OVF when a prismatic value saturated */
#define IKQ_FINISH_OVF 0xFFFFFFFFu
static DH_NOINLINE uint32_t ikq_finish(const dh_ikc_model_q *m, const int32_t *q_ref, uint32_t opts,
                                       dh_ikc_sol_q *sol, uint32_t raw)
{
    uint32_t s, i, kept = 0;
    int ovf = 0;
    for (s = 0; s < raw; s++) {
        dh_ikc_sol_q *t = &sol[s];
        int all_in = 1;
        for (i = 0; i < m->n; i++) {
            int in = 1;
            if ((m->prismatic >> i) & 1u) {
                t->q[i] = dh_q_sat32((int64_t)t->q[i] - m->d[i], &ovf);
                if (m->qmin[i] <= m->qmax[i]) in = (t->q[i] >= m->qmin[i] && t->q[i] <= m->qmax[i]);
            } else {
                t->q[i] = ikq_shift(dh_ikc_wrap180_q_(t->q[i] - m->off[i]), m->qmin[i], m->qmax[i],
                                    (q_ref != NULL) ? q_ref[i] : 0, &in);
            }
            if (!in) all_in = 0;
        }
        if (!all_in) {
            if ((opts & DH_IKC_KEEP_OUT_OF_LIMITS) == 0u) continue;
            t->flags |= DH_IKC_OUT_OF_LIMITS;
        }
        if (kept != s) sol[kept] = *t;
        kept++;
    }
    return ovf ? IKQ_FINISH_OVF : kept;
}

/* v <- R v (+ p with addp) for a model frame; 1 on overflow */
static DH_NOINLINE int ikq_col_apply(const dh_frame_q *F, int32_t *v, int addp)
{
    const int32_t x = v[0], y = v[1], z = v[2];
    int ovf = 0;
    unsigned i;
    for (i = 0; i < 3u; i++) {
        const int64_t t = dh_q_mla64(dh_q_mla64(dh_q_mul64(F->r[0][i], x), F->r[1][i], y), F->r[2][i], z);
        v[i] = addp ? dh_q_pos_rnd30(F->p[i], t, &ovf) : dh_q_rnd30(t, &ovf);
    }
    return ovf;
}

/* row i of the scratch T06 times a model frame on the right; 1 on overflow */
static DH_NOINLINE int ikq_row_apply(const dh_frame_q *F, dh_ikc_sol_q *sol, unsigned i)
{
    int32_t *c0 = DH_IKC_T06_COL_(sol, 0u), *c1 = DH_IKC_T06_COL_(sol, 1u), *c2 = DH_IKC_T06_COL_(sol, 2u);
    int32_t *p = DH_IKC_T06_COL_(sol, 3u);
    const int32_t x = c0[i], y = c1[i], z = c2[i];
    int ovf = 0;
    c0[i] = dh_q_rnd30(dh_q_mla64(dh_q_mla64(dh_q_mul64(x, F->r[0][0]), y, F->r[0][1]), z, F->r[0][2]), &ovf);
    c1[i] = dh_q_rnd30(dh_q_mla64(dh_q_mla64(dh_q_mul64(x, F->r[1][0]), y, F->r[1][1]), z, F->r[1][2]), &ovf);
    c2[i] = dh_q_rnd30(dh_q_mla64(dh_q_mla64(dh_q_mul64(x, F->r[2][0]), y, F->r[2][1]), z, F->r[2][2]), &ovf);
    p[i] = dh_q_pos_rnd30(p[i], dh_q_mla64(dh_q_mla64(dh_q_mul64(x, F->p[0]), y, F->p[1]), z, F->p[2]), &ovf);
    return ovf;
}

/* T06 = pre_inv T post_inv into the scratch of sol, identity products
 * skipped; 1 on overflow */
static DH_NOINLINE int ikq_t06(const dh_ikc_model_q *m, const dh_frame_q *T, dh_ikc_sol_q *sol)
{
    unsigned c, i;
    int ovf = 0;
    for (c = 0; c < 4u; c++)
        for (i = 0; i < 3u; i++) DH_IKC_T06_COL_(sol, c)[i] = (c < 3u) ? T->r[c][i] : T->p[i];
    if (memcmp(&m->pre_inv, &ikq_identity, sizeof ikq_identity) != 0)
        for (c = 0; c < 4u; c++) ovf |= ikq_col_apply(&m->pre_inv, DH_IKC_T06_COL_(sol, c), c == 3u);
    if (memcmp(&m->post_inv, &ikq_identity, sizeof ikq_identity) != 0)
        for (i = 0; i < 3u; i++) ovf |= ikq_row_apply(&m->post_inv, sol, i);
    return ovf;
}

int32_t dh_ikc_cref_q_(const dh_ikc_model_q *m, const int32_t *q_ref, uint32_t i)
{
    const int32_t ref = (q_ref != NULL) ? q_ref[i] : 0;
    int ovf = 0;
    if ((m->prismatic >> i) & 1u) return dh_q_sat32((int64_t)ref + m->d[i], &ovf);
    return dh_ikc_wrap180_q_(ikq_reduce(ref) + m->off[i]);
}

dh_status dh_ikc_q(const dh_ikc_model_q *m, const dh_frame_q *target, const int32_t *q_ref, uint32_t opts,
                   dh_ikc_sol_q *sol, uint32_t *n_sol)
{
    dh_status st;
    uint32_t raw;

    DH_ASSERT(m != NULL && target != NULL && sol != NULL && n_sol != NULL);
    *n_sol = 0;
    if (m->kind == DH_IKC_NONE) return DH_ERR_UNAVAILABLE;
    if ((opts & ~DH_IKC_KEEP_OUT_OF_LIMITS) != 0u || !ikq_model_ok(m)) return DH_ERR_ARG;
    if (!ikq_rigid(target)) return DH_ERR_NOT_RIGID;
    if (ikq_t06(m, target, sol)) return DH_ERR_OVERFLOW;
    /* the raw count goes through *n_sol (no addressable local here) */
    if (m->kind == DH_IKC_PARALLEL_234)
        st = dh_ikc_par234_q_(m, q_ref, sol, n_sol);
    else if (m->kind == DH_IKC_SCARA)
        st = dh_ikc_scara_q_(m, q_ref, sol, n_sol);
    else
        st = dh_ikc_wrist_q_(m, q_ref, sol, n_sol);
    raw = *n_sol;
    *n_sol = 0;
    if (st != DH_OK) return st;
    if (raw == 0u) return DH_ERR_UNREACHABLE;
    raw = ikq_finish(m, q_ref, opts, sol, raw);
    if (raw == IKQ_FINISH_OVF) return DH_ERR_OVERFLOW;
    *n_sol = raw;
    return raw != 0u ? DH_OK : DH_ERR_LIMIT;
}

dh_status dh_ikc_nearest_q(const dh_ikc_sol_q *sol, uint32_t n_sol, const int32_t *q_ref, uint32_t n,
                           uint32_t *index)
{
    uint32_t s, i, best = 0;
    uint64_t best_d = 0;

    DH_ASSERT(sol != NULL && index != NULL);
    if (n_sol == 0u || n > DH_IKC_JOINTS) return DH_ERR_ARG;
    for (s = 0; s < n_sol; s++) {
        uint64_t d = 0;
        for (i = 0; i < n; i++) d += ikq_abs64((int64_t)sol[s].q[i] - ((q_ref != NULL) ? q_ref[i] : 0));
        if (s == 0u || d < best_d) {
            best = s;
            best_d = d;
        }
    }
    *index = best;
    return DH_OK;
}
