/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_ikc_q.c - closed-form inverse kinematics, fixed point (integer only:
 * no float, no libm, no 64-bit division; checked by tools/check.sh guards):
 * the front end (dh_ikc_analyse_q, dh_ikc_q, dh_ikc_nearest_q): the model
 * and its canonical chain, the target checks, the dispatch to the family
 * solvers (dh_ikc_wrist_q.c, dh_ikc_par234_q.c, dh_ikc_scara_q.c), then
 * offsets, 360-degree shifts and limits. Contract: ikc.h and the private
 * interface ikc_impl.h; method: docs/design.md ("Closed-form inverse
 * kinematics"), after Paul 1981 ch. 3.
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
 * 2^30 by one common rounding shift (dh_ikc_atan2_q_: only the ratio matters).
 * Rotation entries of a rigid target (within 2^-10 of orthonormal, and
 * every entry <= 1.1, checked first) stay below 1.001 in magnitude, so
 * their rotated copies are rounded without a range check and are never
 * INT32_MIN; the model's pre/post rotations are checked for entries <= 1.1
 * by dh_ikc_q, which bounds every three-term sum of ikcq_t06 below 2^63.
 *
 */
#include "dhmath/ikc.h"
#include "dhmath/frame.h"
#include "dhmath/trig.h"
#include "ikc_impl.h"
#include "../internal/dh_qmath.h"

/* rigidity of the target, base and tool: |R^T R - I| <= 2^-10, entries <= 1.1 */
#define IKCQ_ENTRY_MAX 0x46666666u
#define IKCQ_RIGID_TOL ((int32_t)1 << 20)
/* canonical lengths and intermediate lengths, raw */
#define IKCQ_LEN_LIM ((int32_t)1 << 29)
/* 540 degrees, Q16.16: limits within (-540, 540] take ikcq_shift's int32 path */
#define IKCQ_Q16_540 ((int32_t)35389440)

/* ---- analysis ----------------------------------------------------------- */

/* 1 when the columns c0, c1, c2 (Q2.30) are within 2^-10 of orthonormal
 * with det > 0; entries above 1.1 in magnitude fail first, which bounds
 * every three-term sum below (3.63 2^61 < 2^63) */
static DH_NOINLINE int ikcq_rigid3(const int32_t *c0, const int32_t *c1, const int32_t *c2)
{
    const int32_t *c[3];
    unsigned a, b, i;
    int32_t x, y, z;
    c[0] = c0;
    c[1] = c1;
    c[2] = c2;
    for (a = 0; a < 3u; a++)
        for (i = 0; i < 3u; i++)
            if (dh_q_abs_u32(c[a][i]) > IKCQ_ENTRY_MAX) return 0;
    for (a = 0; a < 3u; a++)
        for (b = a; b < 3u; b++) {
            /* the dot product rounded in 64 bits: up to 3.63 (above the
             * int32 range of Q2.30) before the identity is subtracted */
            int64_t d = dh_q_rshr(dh_q_mla64(dh_q_mla64(dh_q_mul64(c[a][0], c[b][0]), c[a][1], c[b][1]), c[a][2], c[b][2]),
                                  30u);
            if (a == b) d -= DH_Q_ONE30;
            if (d > IKCQ_RIGID_TOL || d < -IKCQ_RIGID_TOL) return 0;
        }
    x = dh_ikc_r30_q_(dh_q_mul64(c1[1], c2[2]) - dh_q_mul64(c1[2], c2[1]));
    y = dh_ikc_r30_q_(dh_q_mul64(c1[2], c2[0]) - dh_q_mul64(c1[0], c2[2]));
    z = dh_ikc_r30_q_(dh_q_mul64(c1[0], c2[1]) - dh_q_mul64(c1[1], c2[0]));
    return dh_q_mla64(dh_q_mla64(dh_q_mul64(c0[0], x), c0[1], y), c0[2], z) > 0;
}

DH_INLINE int ikcq_rigid(const dh_frame_q *F)
{
    return ikcq_rigid3(F->r[0], F->r[1], F->r[2]);
}

/* F <- F^-1 for a rigid F (entries <= 1.1): R^T, -R^T p; 1 on overflow */
static DH_NOINLINE int ikcq_inv(dh_frame_q *F)
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

/* canonical chain, limits, pre/post inverses (m->n set) */
static DH_NOINLINE dh_status ikcq_chain(const dh_robot *r, dh_ikc_model_q *m)
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
        m->off[i] = (j->type == DH_JOINT_PRISMATIC) ? j->theta_q : dh_ikc_reduce_q_(j->theta_q);
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
        if (dh_q_abs_u32(m->a[i]) > (uint32_t)IKCQ_LEN_LIM || dh_q_abs_u32(m->d[i]) > (uint32_t)IKCQ_LEN_LIM) bad = 1;
    }
    if (!ikcq_rigid(&r->base_q) || !ikcq_rigid(&r->tool_q)) {
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
    if (ikcq_inv(&m->pre_inv) || ikcq_inv(&m->post_inv)) bad = 1;
    if (bad) {
        m->why = DH_IKC_WHY_PATH;
        return DH_ERR_UNAVAILABLE;
    }
    return DH_OK;
}

/* family, or the reason for none */
static DH_NOINLINE void ikcq_classify(dh_ikc_model_q *m)
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
        else if (dh_ikc_spherical_q_(m))
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
    static const dh_frame_q ikcq_identity = {
        {{DH_Q_ONE30, 0, 0}, {0, DH_Q_ONE30, 0}, {0, 0, DH_Q_ONE30}}, {0, 0, 0}};
    uint32_t i;
    dh_status st;

    DH_ASSERT(r != NULL && m != NULL);
    memset(m, 0, sizeof *m);
    m->kind = DH_IKC_NONE;
    m->why = DH_IKC_WHY_JOINTS;
    m->pre_inv = ikcq_identity;
    m->post_inv = ikcq_identity;
    if ((r->conv != DH_CONV_STANDARD && r->conv != DH_CONV_MODIFIED) || r->n > DH_MAX_JOINTS) return DH_ERR_ARG;
    for (i = 0; i < r->n; i++)
        if (r->joint[i].type != DH_JOINT_REVOLUTE && r->joint[i].type != DH_JOINT_PRISMATIC) return DH_ERR_ARG;
    if ((r->flags & DH_ROBOT_HAS_Q) == 0u) {
        m->why = DH_IKC_WHY_PATH;
        return DH_ERR_UNAVAILABLE;
    }
    if (r->n == 0u || r->n > DH_IKC_JOINTS) return DH_ERR_UNAVAILABLE;
    m->n = r->n;
    st = ikcq_chain(r, m);
    if (st != DH_OK) return st;
    ikcq_classify(m);
    return (m->kind != DH_IKC_NONE) ? DH_OK : DH_ERR_UNAVAILABLE;
}

/* ---- front end: solve --------------------------------------------------- */

/* kind known, n the family's, pre/post rotation entries <= 1.1 (the
 * products of ikcq_t06 cannot wrap), revolute offsets in (-180, 180] */
static DH_NOINLINE int ikcq_model_ok(const dh_ikc_model_q *m)
{
    unsigned c, i;
    for (c = 0; c < 3u; c++)
        for (i = 0; i < 3u; i++)
            if (dh_q_abs_u32(m->pre_inv.r[c][i]) > IKCQ_ENTRY_MAX || dh_q_abs_u32(m->post_inv.r[c][i]) > IKCQ_ENTRY_MAX)
                return 0;
    for (i = 0; i < m->n && i < DH_IKC_JOINTS; i++)
        if (((m->prismatic >> i) & 1u) == 0u && (m->off[i] > DH_IKC_Q16_180 || m->off[i] <= -DH_IKC_Q16_180)) return 0;
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
static int32_t ikcq_shift(int32_t q, int32_t lo, int32_t hi, int32_t ref, int *in)
{
    const int64_t d = (int64_t)q - lo, span = (int64_t)hi - lo;
    const uint32_t P = (uint32_t)DH_IKC_Q16_360;
    uint32_t rem, kmax, kk;
    int64_t first, c0;

    *in = 1;
    if (lo > hi) return q;
    if (lo > -IKCQ_Q16_540 && hi <= IKCQ_Q16_540) {
        /* limits within (-540, 540]: the candidates are q - 360, q and
         * q + 360 (q -+ 720 lie outside), all in int32; the distances to
         * ref (|.| < 2^32) are taken in uint32 */
        int32_t c = q - DH_IKC_Q16_360, best = q;
        uint32_t bd = 0u, dd;
        unsigned i;
        int found = 0;
        for (i = 0; i < 3u; i++) {
            if (c >= lo && c <= hi) {
                dd = (c >= ref) ? (uint32_t)c - (uint32_t)ref : (uint32_t)ref - (uint32_t)c;
                if (!found || dd < bd) {
                    best = c;
                    bd = dd;
                    found = 1;
                }
            }
            c += DH_IKC_Q16_360;
        }
        *in = found;
        return best;
    }
    if (span < 3 * (int64_t)P) {
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
            if (dh_ikc_abs64_q_(cand - ref) < dh_ikc_abs64_q_((int64_t)best - ref)) best = (int32_t)cand;
        return best;
    }
    rem = (uint32_t)dh_ikc_abs64_q_(d) % P;
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

/* *q (in (-180, 180]) <- ikcq_shift(*q, ...) in place; 1 when inside the
 * limits (the solver's slot holds the value: no addressable local in
 * ikcq_finish, whose frame is on the deepest chain) */
static DH_NOINLINE int ikcq_shift_at(int32_t *q, int32_t lo, int32_t hi, int32_t ref)
{
    int in = 1;
    *q = ikcq_shift(*q, lo, hi, ref, &in);
    return in;
}

/* raw canonical solutions -> joint values, shifts, limits, compaction;
 * the count kept, or IKCQ_FINISH_OVF when a prismatic value saturated.
 * Joint by joint (the limits, offset and reference loaded once), a mask
 * of the solutions outside a limit (raw <= DH_IKC_MAX_SOL < 32); without
 * DH_IKC_KEEP_OUT_OF_LIMITS a solution already outside is not converted
 * further (it is dropped) */
#define IKCQ_FINISH_OVF 0xFFFFFFFFu
static DH_NOINLINE uint32_t ikcq_finish(const dh_ikc_model_q *m, const int32_t *q_ref, uint32_t opts,
                                       dh_ikc_sol_q *sol, uint32_t raw)
{
    const uint32_t n = m->n, prismatic = m->prismatic;
    const uint32_t keep = opts & DH_IKC_KEEP_OUT_OF_LIMITS;
    uint32_t s, i, kept = 0, out = 0;
    int ovf = 0;
    for (i = 0; i < n; i++) {
        const int32_t lo = m->qmin[i], hi = m->qmax[i];
        if ((prismatic >> i) & 1u) {
            const int32_t d = m->d[i];
            for (s = 0; s < raw; s++) {
                int32_t *q = &sol[s].q[i];
                *q = dh_q_sat32((int64_t)*q - d, &ovf);
                if (lo <= hi && (*q < lo || *q > hi)) out |= 1u << s;
            }
        } else if (lo > -IKCQ_Q16_540 && hi <= IKCQ_Q16_540 && lo <= hi && hi - lo < DH_IKC_Q16_360) {
            /* one candidate at most (ikcq_shift's result without the
             * search): the least v + 360 k >= lo (k in -1..1, v in
             * (-180, 180]), inside when <= hi */
            const int32_t off = m->off[i];
            for (s = 0; s < raw; s++) {
                int32_t *q = &sol[s].q[i];
                const int32_t v = dh_ikc_wrap180_q_(*q - off);
                int32_t c;
                if (keep == 0u && ((out >> s) & 1u) != 0u) continue;
                if (v - DH_IKC_Q16_360 >= lo) {
                    c = v - DH_IKC_Q16_360;
                } else if (v < lo) {
                    c = v + DH_IKC_Q16_360;
                } else {
                    c = v;
                }
                if (c >= lo && c <= hi) {
                    *q = c;
                } else {
                    *q = v;
                    out |= 1u << s;
                }
            }
        } else {
            const int32_t off = m->off[i], ref = (q_ref != NULL) ? q_ref[i] : 0;
            for (s = 0; s < raw; s++) {
                int32_t *q = &sol[s].q[i];
                if (keep == 0u && ((out >> s) & 1u) != 0u) continue;
                *q = dh_ikc_wrap180_q_(*q - off);
                if (!ikcq_shift_at(q, lo, hi, ref)) out |= 1u << s;
            }
        }
    }
    for (s = 0; s < raw; s++) {
        if ((out >> s) & 1u) {
            if (keep == 0u) continue;
            sol[s].flags |= DH_IKC_OUT_OF_LIMITS;
        }
        if (kept != s) sol[kept] = sol[s];
        kept++;
    }
    return ovf ? IKCQ_FINISH_OVF : kept;
}

/* v <- R v (+ p with addp) for a model frame; 1 on overflow */
static DH_NOINLINE int ikcq_col_apply(const dh_frame_q *F, int32_t *v, int addp)
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
static DH_NOINLINE int ikcq_row_apply(const dh_frame_q *F, dh_ikc_sol_q *sol, unsigned i)
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

/* 1 when F is the identity frame, word by word (the same answer as a
 * memcmp with the identity frame: no padding; a fraction of its cost on the
 * cores whose memcmp goes byte by byte) */
static int ikcq_is_identity(const dh_frame_q *F)
{
    unsigned c, i;
    for (c = 0; c < 3u; c++) {
        for (i = 0; i < 3u; i++)
            if (F->r[c][i] != ((c == i) ? DH_Q_ONE30 : 0)) return 0;
        if (F->p[c] != 0) return 0;
    }
    return 1;
}

/* T06 = pre_inv T post_inv into the scratch of sol, identity products
 * skipped; 1 on overflow */
static DH_NOINLINE int ikcq_t06(const dh_ikc_model_q *m, const dh_frame_q *T, dh_ikc_sol_q *sol)
{
    unsigned c, i;
    int ovf = 0;
    for (c = 0; c < 4u; c++)
        for (i = 0; i < 3u; i++) DH_IKC_T06_COL_(sol, c)[i] = (c < 3u) ? T->r[c][i] : T->p[i];
    if (!ikcq_is_identity(&m->pre_inv))
        for (c = 0; c < 4u; c++) ovf |= ikcq_col_apply(&m->pre_inv, DH_IKC_T06_COL_(sol, c), c == 3u);
    if (!ikcq_is_identity(&m->post_inv))
        for (i = 0; i < 3u; i++) ovf |= ikcq_row_apply(&m->post_inv, sol, i);
    return ovf;
}

dh_status dh_ikc_args_q_(const dh_ikc_model_q *m, const dh_frame_q *target, uint32_t opts, dh_ikc_sol_q *sol)
{
    if (m->kind == DH_IKC_NONE) return DH_ERR_UNAVAILABLE;
    if ((opts & ~DH_IKC_KEEP_OUT_OF_LIMITS) != 0u || !ikcq_model_ok(m)) return DH_ERR_ARG;
    if (!ikcq_rigid(target)) return DH_ERR_NOT_RIGID;
    return ikcq_t06(m, target, sol) ? DH_ERR_OVERFLOW : DH_OK;
}

dh_status dh_ikc_args_rigid_q_(const dh_ikc_model_q *m, const dh_frame_q *target, dh_ikc_sol_q *sol)
{
    if (m->kind == DH_IKC_NONE) return DH_ERR_UNAVAILABLE;
    if (!ikcq_model_ok(m)) return DH_ERR_ARG;
    return ikcq_t06(m, target, sol) ? DH_ERR_OVERFLOW : DH_OK;
}

dh_status dh_ikc_finish_q_(const dh_ikc_model_q *m, const int32_t *q_ref, dh_ikc_sol_q *sol, uint32_t *n_sol)
{
    uint32_t raw = *n_sol;
    *n_sol = 0;
    if (raw == 0u) return DH_ERR_UNREACHABLE;
    raw = ikcq_finish(m, q_ref, DH_IKC_KEEP_OUT_OF_LIMITS, sol, raw);
    if (raw == IKCQ_FINISH_OVF) return DH_ERR_OVERFLOW;
    *n_sol = raw;
    return raw != 0u ? DH_OK : DH_ERR_LIMIT;
}

dh_status dh_ikc_q(const dh_ikc_model_q *m, const dh_frame_q *target, const int32_t *q_ref, uint32_t opts,
                   dh_ikc_sol_q *sol, uint32_t *n_sol)
{
    dh_status st;
    uint32_t raw;

    DH_ASSERT(m != NULL && target != NULL && sol != NULL && n_sol != NULL);
    *n_sol = 0;
    st = dh_ikc_args_q_(m, target, opts, sol);
    if (st != DH_OK) return st;
    /* the raw count goes through *n_sol (no addressable local here) */
    st = dh_ikc_raw_q_(m, q_ref, sol, n_sol);
    raw = *n_sol;
    *n_sol = 0;
    if (st != DH_OK) return st;
    if (raw == 0u) return DH_ERR_UNREACHABLE;
    raw = ikcq_finish(m, q_ref, opts, sol, raw);
    if (raw == IKCQ_FINISH_OVF) return DH_ERR_OVERFLOW;
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
        for (i = 0; i < n; i++) d += dh_ikc_abs64_q_((int64_t)sol[s].q[i] - ((q_ref != NULL) ? q_ref[i] : 0));
        if (s == 0u || d < best_d) {
            best = s;
            best_d = d;
        }
    }
    *index = best;
    return DH_OK;
}
