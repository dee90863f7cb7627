/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_ikc_refine_q.c - closed-form IK of calibrated robots, fixed point
 * (integer only: no float, no libm, no 64-bit division): the recognition of
 * a six-revolute chain within the calibration tolerance of
 * DH_IKC_PARALLEL_234 (dh_ikc_calibrate_q_, called by dh_ikc_analyse_q
 * after the exact detectors) and the refinement of the family solver's raw
 * solutions on the exact chain (dh_ikc_refine_q_, called by dh_ikc_q after
 * the solver has returned); interface in ikc_impl.h. Method: the float
 * twin's (dh_ikc_refine.c; docs/design.md, "Calibrated robots").
 *
 * Refinement of one branch: simplified Newton steps with the idealised
 * chain's Jacobian in the frame-1 split of the family (the position error
 * of the joint 5 point along axis 2 and the rotation error across it
 * depend on joints 1, 5, 6 only; the planar position error and the
 * rotation about axis 2 on joints 2, 3, 4 once those are known), each step
 * one exact forward kinematics; a branch is kept when its residual on the
 * exact chain is within REFQ_POS and REFQ_ROT, after at most
 * DH_IKC_CAL_STEPS steps.
 *
 * Formats: cosines and sines, rotation entries and rotation errors Q2.30;
 * points and position errors dh_qpos; joint steps Q2.30 radians; joint
 * values Q16.16 degrees. Products are int64, each sum rounded once.
 *
 * Stack: the entry keeps the work data (24 words: the cosines and sines of
 * the branch's joints, the exact frame or the errors); every helper runs
 * from the entry in sequence, none below another.
 */
#include "dhmath/ikc.h"
#include "dhmath/trig.h"
#include "ikc_impl.h"
#include "../internal/dh_qmath.h"

/* sin(1 deg) in Q2.30 (DH_IKC_CAL_ANGLE_DEG) */
#define REFQ_SIN_TOL ((int32_t)18739373)
/* DH_IKC_CAL_OFFSET_REL as a ratio: |x| * 100 <= the chain's length sum */
#define REFQ_OFFSET_DIV 100u
/* Converged: the joint 5 point's position error within REFQ_POS LSB of
 * dh_qpos (2^7: 2e-3 mm for robots in mm at DH_QPOS_FRAC 16) and the
 * rotation error within REFQ_ROT (2^11 2^-30 rad: 1.9e-6 rad), in the sum
 * of their squares over the squared bounds: e_p^2 2^8 + e_r^2 <= 2^22. */
#define REFQ_BOUND 0x40000u     /* 2^(11 + 7) */
#define REFQ_SCALE ((int32_t)16) /* 2^(11 - 7) */
/* an error component beyond this (LSB) is far from converged */
#define REFQ_ERR_BIG 0x100000u
/* Largest joint step, 0.2 rad in Q2.30 */
#define REFQ_MAX_STEP ((int32_t)214748365)
/* 180 / pi 2^24: Q2.30 radians times it, >> 38, is Q16.16 degrees */
#define REFQ_RAD2DEG ((int32_t)961263669)
/* two refined solutions this close on every joint (Q16.16 degrees, 1e-3
 * deg) are one */
#define REFQ_SAME ((int32_t)66)
/* a step count past the last: the branch is done */
#define REFQ_DONE (DH_IKC_CAL_STEPS + 1u)

/* m->k layout of DH_IKC_PARALLEL_234 (dh_ikc_par234_q.c), the entries read here */
enum { RQ_TAU = 0, RQ_S2 = 1, RQ_S23 = 2, RQ_SB = 3, RQ_W5 = 4, RQ_H = 5, RQ_E5 = 6 };

/* Private flag bits of the slots while dh_ikc_refine_q_ runs, cleared
 * before it returns: a slot waiting for a start from the virtual target
 * (refq_plan), one waiting for its refinement (a raw branch, or one
 * started), and a free one. */
#define REFQ_PEND 0x100u
#define REFQ_NEW 0x200u
#define REFQ_FREE 0x400u
#define REFQ_PRIVATE 0x700u
#define REFQ_BRANCH (DH_IKC_SHOULDER_ALT | DH_IKC_ELBOW_ALT | DH_IKC_WRIST_ALT)
#define REFQ_SINGS (DH_IKC_SING_WRIST | DH_IKC_SING_SHOULDER | DH_IKC_SING_ELBOW)
/* refq_plan: no restart */
#define REFQ_NONE 0xFFu
/* the wrist singular for a start: |n13|, |n23| within 2^11 LSB (as the solver) */
#define REFQ_SING_W ((uint32_t)1 << 11)
#define REFQ_POS_LIM ((uint64_t)1 << 30)
/* refq_offset, refq_twist: the idealised chain instead of the exact one */
#define REFQ_IDEAL 8u


/* ---- analysis ------------------------------------------------------------------ */

/* the exact chain of m (a..ca) copied to xa..xca (to 1), or back with
 * xa..xca cleared (to 0) */
static DH_NOINLINE void refq_keep(dh_ikc_model_q *m, int to)
{
    uint32_t i;
    for (i = 0; i < DH_IKC_JOINTS; i++) {
        if (to) {
            m->xa[i] = m->a[i];
            m->xd[i] = m->d[i];
            m->xsa[i] = m->sa[i];
            m->xca[i] = m->ca[i];
        } else {
            m->a[i] = m->xa[i];
            m->d[i] = m->xd[i];
            m->sa[i] = m->xsa[i];
            m->ca[i] = m->xca[i];
            m->xa[i] = 0;
            m->xd[i] = 0;
            m->xsa[i] = 0;
            m->xca[i] = 0;
        }
    }
}

/* The model completed as calibrated: frame 5's origin seen from the tool
 * (post^-1 (-a6, -d6 sa6, -d6 ca6), exact chain) and the frame bits. 0 on
 * overflow (the exact chain put back). */
static DH_NOINLINE int refq_complete(dh_ikc_model_q *m)
{
    const dh_frame_q *P = &m->post_inv;
    int32_t w[3];
    int ovf = 0;
    unsigned i;
    w[0] = -m->xa[5];
    w[1] = -dh_ikc_r30_q_(dh_q_mul64(m->xd[5], m->xsa[5]));
    w[2] = -dh_ikc_r30_q_(dh_q_mul64(m->xd[5], m->xca[5]));
    for (i = 0; i < 3u; i++)
        m->xw5[i] = dh_q_pos_rnd30(P->p[i], dh_q_mla64(dh_q_mla64(dh_q_mul64(P->r[0][i], w[0]), P->r[1][i], w[1]),
                                                       P->r[2][i], w[2]),
                                   &ovf);
    if (ovf) return 0;
    m->xframes = (dh_ikc_is_identity_q_(&m->pre_inv) ? 0u : 1u) | (dh_ikc_is_identity_q_(&m->post_inv) ? 0u : 2u);
    m->calibrated = 1u;
    return 1;
}

int dh_ikc_calibrate_q_(dh_ikc_model_q *m)
{
    uint64_t len = 0u;
    uint32_t i;
    if (m->n != 6u || m->prismatic != 0u) return 0;
    refq_keep(m, 1);
    for (i = 0; i < 6u; i++) {
        len += (uint64_t)dh_q_abs_u32(m->a[i]) + dh_q_abs_u32(m->d[i]);
        /* a twist within 1 degree of a multiple of 90 degrees: that multiple */
        if (dh_q_abs_u32(m->sa[i]) <= (uint32_t)REFQ_SIN_TOL) {
            m->sa[i] = 0;
            m->ca[i] = dh_ikc_sign_q_(m->ca[i]) * DH_Q_ONE30;
        } else if (dh_q_abs_u32(m->ca[i]) <= (uint32_t)REFQ_SIN_TOL) {
            m->ca[i] = 0;
            m->sa[i] = dh_ikc_sign_q_(m->sa[i]) * DH_Q_ONE30;
        } else {
            /* a general twist: kept */
        }
    }
    if ((uint64_t)dh_q_abs_u32(m->a[4]) * REFQ_OFFSET_DIV <= len) m->a[4] = 0;
    if (dh_ikc_detect_par234_q_(m) && refq_complete(m)) return 1;
    refq_keep(m, 0);
    m->kind = DH_IKC_NONE;
    return 0;
}

/* ---- refinement ---------------------------------------------------------------- */

/* Work data of one refinement: u the exact chain's end frame (columns x,
 * y, z Q2.30, the joint 5 point dh_qpos), then the errors (position u[0..2],
 * rotation u[3..5]) and the point u[6..8], then the steps; t and the
 * slots of u that the next helper does not read hold the cosines and sines
 * it reads (Q2.30, written by the entry through dh_sincos_q, so that no
 * helper calls it); m the model, T the target. */
typedef struct {
    int32_t u[12];
    int32_t t[2];
    const dh_ikc_model_q *m;
    const dh_frame_q *T;
} refq_work;

/* round(num 2^sh / den), saturated to +-(2^31 - 1); den != 0, |num|, |den|
 * < 2^62, sh <= 30. den normalised into [2^30, 2^31) by a shift that num
 * takes too (rounded), then one quotient bit per step; no division. */
static DH_NOINLINE int32_t refq_div(int64_t num, int64_t den, int sh)
{
    uint64_t a = dh_ikc_abs64_q_(num), b = dh_ikc_abs64_q_(den);
    const int neg = (num < 0) != (den < 0);
    int s = (int)dh_q_bitlen64(b) - 31;
    uint32_t q = 0u, r, bb, i;
    bb = (uint32_t)((s >= 0) ? b >> (unsigned)s : b << (unsigned)(-s));
    /* b 2^-s in [2^30, 2^31); a 2^(sh - s) */
    s = sh - s;
    if (s >= 0) {
        if (a != 0u && (int)dh_q_bitlen64(a) + s > 62) return neg ? -INT32_MAX : INT32_MAX;
        a <<= (unsigned)s;
    } else {
        const unsigned n = (unsigned)(-s);
        if (n > 62u) {
            a = 0u;
        } else {
            const unsigned n1 = n - 1u;
            const uint64_t half = (uint64_t)1 << n1;
            a = (a + half) >> n;
        }
    }
    if ((a >> 31) >= bb) return neg ? -INT32_MAX : INT32_MAX;
    r = (uint32_t)(a >> 31);
    for (i = 0; i < 31u; i++) {
        const unsigned at = 30u - i;
        const uint32_t bit = (uint32_t)(a >> at) & 1u;
        r = (r << 1) | bit;
        q <<= 1;
        if (r >= bb) {
            r -= bb;
            q |= 1u;
        }
    }
    if (q < (uint32_t)INT32_MAX && r >= bb - r) q++;
    return neg ? -(int32_t)q : (int32_t)q;
}

/* v saturated into int32 without a status (the verdict judges the result) */
DH_INLINE int32_t refq_sat(int64_t v)
{
    if (v > INT32_MAX) return INT32_MAX;
    if (v < -INT32_MAX) return -INT32_MAX;
    return (int32_t)v;
}

/* Joint i of the exact chain (cos, sin of its canonical value in t[0],
 * t[1]) applied to u in three helpers, each a pass over the three rows:
 * refq_turn the turn about z, refq_offset the offsets a_i, d_i (1 on
 * overflow), refq_twist the twist, and after joint 6 the point moved back
 * to the joint 5 point (frame 5's origin: p6 - a6 x6 - d6 z5; 1 on
 * overflow). */
static DH_NOINLINE void refq_turn(refq_work *w)
{
    const int32_t c = w->t[0], s = w->t[1];
    int32_t *u = w->u;
    uint32_t r;
    for (r = 0; r < 3u; r++) {
        const int32_t x = u[r], y = u[3u + r];
        u[r] = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(c, x), s, y));
        u[3u + r] = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(c, y), -s, x));
    }
}

static DH_NOINLINE int refq_offset(refq_work *w, uint32_t i)
{
    const uint32_t j = i & 7u;
    const int32_t a = ((i & REFQ_IDEAL) != 0u) ? w->m->a[j] : w->m->xa[j];
    const int32_t d = ((i & REFQ_IDEAL) != 0u) ? w->m->d[j] : w->m->xd[j];
    int32_t *u = w->u;
    uint32_t r;
    int ovf = 0;
    for (r = 0; r < 3u; r++) u[9u + r] = dh_q_pos_rnd30(u[9u + r], dh_q_mla64(dh_q_mul64(d, u[6u + r]), a, u[r]), &ovf);
    return ovf;
}

static DH_NOINLINE int refq_twist(refq_work *w, uint32_t i)
{
    const uint32_t j = i & 7u;
    const int ideal = (i & REFQ_IDEAL) != 0u;
    const int32_t sa = ideal ? w->m->sa[j] : w->m->xsa[j], ca = ideal ? w->m->ca[j] : w->m->xca[j];
    const int32_t a6 = ideal ? w->m->a[5] : w->m->xa[5], d6 = ideal ? w->m->d[5] : w->m->xd[5];
    int32_t *u = w->u;
    uint32_t r;
    int ovf = 0;
    for (r = 0; r < 3u; r++) {
        const int32_t y = u[3u + r], z = u[6u + r];
        u[3u + r] = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(ca, y), sa, z));
        u[6u + r] = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(ca, z), -sa, y));
        if (j == 5u) {
            const int32_t z5 = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(sa, u[3u + r]), ca, u[6u + r]));
            u[9u + r] = dh_q_pos_rnd30(u[9u + r], -dh_q_mla64(dh_q_mul64(a6, u[r]), d6, z5), &ovf);
        }
    }
    return ovf;
}

/* u <- the forward kinematics of the canonical values q on the exact
 * chain (id 0) or the idealised one (id REFQ_IDEAL), the point moved back
 * to the joint 5 point, without base and tool frames; 1 on overflow */
static DH_NOINLINE int refq_fk(refq_work *w, const int32_t *q, uint32_t id)
{
    uint32_t i;
    int ovf = 0;
    for (i = 0; i < 12u; i++) w->u[i] = ((i & 3u) == 0u && i < 9u) ? DH_Q_ONE30 : 0;
    for (i = 0; i < 6u; i++) {
        dh_sincos_q(q[i], &w->t[1], &w->t[0]);
        refq_turn(w);
        ovf |= refq_offset(w, i | id);
        ovf |= refq_twist(w, i | id);
    }
    return ovf;
}

/* u's rotation times the tool frame's (post = post_inv^-1, rotation S^T),
 * when there is one */
static DH_NOINLINE void refq_tool(refq_work *w)
{
    const dh_frame_q *P = &w->m->post_inv;
    int32_t *u = w->u;
    uint32_t c, r;
    if ((w->m->xframes & 2u) == 0u) return;
    for (r = 0; r < 3u; r++) {
        const int32_t x = u[r], y = u[3u + r], z = u[6u + r];
        for (c = 0; c < 3u; c++)
            u[3u * c + r] = dh_ikc_r30_q_(dh_q_mla64(dh_q_mla64(dh_q_mul64(x, P->r[0][c]), y, P->r[1][c]), z, P->r[2][c]));
    }
}

/* u <- pre u (pre = pre_inv^-1: each column v to R^T v, the point to
 * R^T (v - p)), when there is a base frame; 1 on overflow */
static DH_NOINLINE int refq_base(refq_work *w)
{
    const dh_frame_q *P = &w->m->pre_inv;
    int32_t *u = w->u;
    uint32_t c, r;
    int ovf = 0;
    if ((w->m->xframes & 1u) == 0u) return 0;
    for (r = 0; r < 3u; r++) u[9u + r] = dh_q_sat32((int64_t)u[9u + r] - P->p[r], &ovf);
    for (c = 0; c < 4u; c++) {
        int32_t *v = &u[3u * c];
        const int32_t x = v[0], y = v[1], z = v[2];
        for (r = 0; r < 3u; r++) {
            const int64_t t = dh_q_mla64(dh_q_mla64(dh_q_mul64(P->r[r][0], x), P->r[r][1], y), P->r[r][2], z);
            v[r] = (c == 3u) ? dh_q_pos_rnd30(0, t, &ovf) : dh_ikc_r30_q_(t);
        }
    }
    return ovf;
}

/* The rotation error (x x xt + y x yt + z x zt) / 2 (rad, Q2.30) of u
 * against the target, component by component (the first two into t), then
 * into u[3..5] (the rotation is not read after it). */
static DH_NOINLINE void refq_rot(refq_work *w)
{
    const dh_frame_q *T = w->T;
    int32_t *u = w->u;
    int32_t e2 = 0;
    uint32_t j, k;
    for (j = 0; j < 3u; j++) {
        const uint32_t a = (j == 2u) ? 0u : j + 1u, b = (j == 0u) ? 2u : j - 1u;
        int64_t e = 0;
        for (k = 0; k < 3u; k++) e = dh_q_mla64(dh_q_mla64(e, u[3u * k + a], T->r[k][b]), -u[3u * k + b], T->r[k][a]);
        e2 = (int32_t)dh_q_rshr(e, 31u);
        if (j < 2u) w->t[j] = e2;
    }
    u[3] = w->t[0];
    u[4] = w->t[1];
    u[5] = e2;
}

/* The position error of the joint 5 point (target minus chain) into
 * u[0..2], the point into u[6..8]. */
static DH_NOINLINE void refq_perr(refq_work *w)
{
    const dh_frame_q *T = w->T;
    const int32_t *p = w->m->xw5;
    int32_t *u = w->u;
    uint32_t k;
    for (k = 0; k < 3u; k++) {
        const int64_t t = dh_q_mla64(dh_q_mla64(dh_q_mul64(T->r[0][k], p[0]), T->r[1][k], p[1]), T->r[2][k], p[2]);
        u[k] = refq_sat((int64_t)T->p[k] + dh_q_rshr(t, 30u) - u[9u + k]);
        u[6u + k] = u[9u + k];
    }
}

/* The verdict on branch b after it steps: converged: b flagged
 * DH_IKC_REFINED, REFQ_DONE; else it + 1 (REFQ_DONE after
 * DH_IKC_CAL_STEPS). */
static DH_NOINLINE uint32_t refq_pos(const refq_work *w, dh_ikc_sol_q *b, uint32_t it)
{
    const int32_t *u = w->u;
    int64_t ep = 0;
    uint32_t k;
    for (k = 0; k < 6u; k++)
        if (dh_q_abs_u32(u[k]) > REFQ_ERR_BIG) return it + 1u;
    /* e_p^2 2^4 + e_r^2 2^-4 <= 2^18 (e_r^2 2^-4 from e_r (e_r / 16), within e_r / 16 below it) */
    for (k = 0; k < 3u; k++)
        ep = dh_q_mla64(dh_q_mla64(ep, u[k] * REFQ_SCALE, u[k]), u[3u + k], u[3u + k] / REFQ_SCALE);
    if (ep <= (int64_t)REFQ_BOUND) {
        b->flags |= DH_IKC_REFINED;
        return REFQ_DONE;
    }
    return it + 1u;
}

/* The errors and the point into the basis of the base frame of the
 * canonical chain (pre^-1), when there is one; 1 on overflow. */
static DH_NOINLINE int refq_unbase(refq_work *w)
{
    const dh_frame_q *P = &w->m->pre_inv;
    int32_t *u = w->u;
    uint32_t k, r;
    int ovf = 0;
    if ((w->m->xframes & 1u) == 0u) return 0;
    for (k = 0; k < 3u; k++) {
        int32_t *v = &u[3u * k];
        const int32_t x = v[0], y = v[1], z = v[2];
        for (r = 0; r < 3u; r++) {
            const int64_t t = dh_q_mla64(dh_q_mla64(dh_q_mul64(P->r[0][r], x), P->r[1][r], y), P->r[2][r], z);
            v[r] = dh_q_pos_rnd30((k == 2u) ? P->p[r] : 0, t, &ovf);
        }
    }
    return ovf;
}

/* Then into the idealised frame 1 (c1, s1 in u[9], u[10]), in place, in
 * two helpers: refq_frame1 the point from frame 1's origin (a1 c1, a1 s1,
 * d1) and Rz(theta1)^T, refq_alpha1 Rx(alpha1)^T. */
static DH_NOINLINE void refq_frame1(refq_work *w)
{
    const dh_ikc_model_q *m = w->m;
    const int32_t c1 = w->u[9], s1 = w->u[10];
    int32_t *u = w->u;
    uint32_t k;
    u[6] = refq_sat((int64_t)u[6] - dh_ikc_r30_q_(dh_q_mul64(m->a[0], c1)));
    u[7] = refq_sat((int64_t)u[7] - dh_ikc_r30_q_(dh_q_mul64(m->a[0], s1)));
    u[8] = refq_sat((int64_t)u[8] - m->d[0]);
    for (k = 0; k < 9u; k += 3u) {
        const int32_t x = u[k], y = u[k + 1u];
        u[k] = refq_sat(dh_q_rshr(dh_q_mla64(dh_q_mul64(c1, x), s1, y), 30u));
        u[k + 1u] = refq_sat(dh_q_rshr(dh_q_mla64(dh_q_mul64(c1, y), -s1, x), 30u));
    }
}

static DH_NOINLINE void refq_alpha1(refq_work *w)
{
    const int32_t ca = w->m->ca[0], sa = w->m->sa[0];
    int32_t *u = w->u;
    uint32_t k;
    for (k = 0; k < 9u; k += 3u) {
        const int32_t y = u[k + 1u], z = u[k + 2u];
        u[k + 1u] = refq_sat(dh_q_rshr(dh_q_mla64(dh_q_mul64(ca, y), sa, z), 30u));
        u[k + 2u] = refq_sat(dh_q_rshr(dh_q_mla64(dh_q_mul64(ca, z), -sa, y), 30u));
    }
}

/* Joints 1, 5, 6 (rad, Q2.30) from the error along axis 2 and the rotation
 * error across it (rows lin_z, ang_x, ang_y of the idealised Jacobian in
 * frame 1: joint 1 (-tau (px + a1), 0, tau), joint 5 (0, sb sphi,
 * -sb cphi), joint 6 (0, w5 s5 cphi, w5 s5 sphi)) into u[9..11], joint
 * 6's part of the rotation about axis 2 (sb w5 c5) added to u[5]; u[9],
 * u[10] cos and sin of phi = theta2 + s2 theta3 + s23 theta4, u[11] s5,
 * t[0] c5; in two helpers: refq_a joint 1's step into u[2] (0 at a
 * singularity: the joint 5 point on the plane of axes 1 and 2 within
 * 2^-20 of the reach, or |s5| within 2^-20), refq_a2 the rest. */
static DH_NOINLINE int refq_a(refq_work *w)
{
    const dh_ikc_model_q *m = w->m;
    int32_t *u = w->u;
    const int64_t r = (int64_t)u[6] + m->a[0];
    if ((dh_ikc_abs64_q_(r) << 20) <= (uint64_t)dh_q_abs_u32(u[6]) + dh_q_abs_u32(u[7]) + dh_q_abs_u32(m->a[0]) ||
        dh_q_abs_u32(u[11]) <= 1024u)
        return 0;
    u[2] = refq_div(-(int64_t)m->k[RQ_TAU] * u[2], r, 30);
    return 1;
}

static DH_NOINLINE void refq_a2(refq_work *w)
{
    const dh_ikc_model_q *m = w->m;
    const int32_t cp = w->u[9], sp = w->u[10], d1 = w->u[2];
    int32_t *u = w->u;
    const int32_t r2 = refq_sat((int64_t)u[4] - (int64_t)m->k[RQ_TAU] * d1);
    u[11] = m->k[RQ_W5] * refq_div(dh_q_mla64(dh_q_mul64(cp, u[3]), sp, r2), u[11], 0);
    u[10] = m->k[RQ_SB] * refq_sat(dh_q_rshr(dh_q_mla64(dh_q_mul64(sp, u[3]), -cp, r2), 30u));
    u[9] = d1;
    u[5] = refq_sat((int64_t)u[5] + (int64_t)(m->k[RQ_SB] * m->k[RQ_W5]) * dh_ikc_r30_q_(dh_q_mul64(w->t[0], u[11])));
}

/* Joints 2, 3, 4 from the planar errors and the rotation about axis 2 less
 * the parts of joints 1 and 6 (u[9], u[11]): rows lin_x, lin_y, ang_z of
 * the idealised Jacobian in frame 1, a planar 3R, in two helpers. refq_b
 * (u[3], u[4] cos and sin of theta2 + s2 theta3, t[0], t[1] c2, s2; u[5]
 * om, the rotation about axis 2 less joint 6's part): o3 = a2 (c2, s2) +
 * a3 (cos, sin)(theta2 + s2 theta3) (the origin of frame 3) into u[3],
 * u[4], the cross (c2, s2) x o3 into u[2], the planar right sides gx, gy
 * into u[1], u[0]; 0 at a singularity (elbow stretched or folded within
 * 2^-20). refq_b2: the steps (rad, Q2.30) into u[6..8]. */
static DH_NOINLINE int refq_b(refq_work *w)
{
    const dh_ikc_model_q *m = w->m;
    const int32_t *t = w->t;
    int32_t *u = w->u;
    const int32_t om = u[5];
    int32_t cr;
    u[3] = refq_sat(dh_q_rshr(dh_q_mla64(dh_q_mul64(m->a[1], t[0]), m->a[2], u[3]), 30u));
    u[4] = refq_sat(dh_q_rshr(dh_q_mla64(dh_q_mul64(m->a[1], t[1]), m->a[2], u[4]), 30u));
    cr = refq_sat(dh_q_rshr(dh_q_mla64(dh_q_mul64(t[0], u[4]), -t[1], u[3]), 30u));
    if (dh_ikc_abs64_q_(dh_q_mul64(m->a[1], cr)) <= (dh_ikc_abs64_q_(dh_q_mul64(m->a[1], m->a[2])) >> 20)) return 0;
    u[2] = cr;
    u[1] = refq_sat(dh_q_rshr(dh_q_mul64(u[6], om), 30u) - u[1]);
    u[0] = refq_sat(dh_q_rshr(dh_q_mul64(u[7], om), 30u) + u[0] -
                    (int64_t)m->k[RQ_TAU] * dh_q_rshr(dh_q_mul64(u[8], u[9]), 30u));
    return dh_q_abs_u32(u[0]) <= 0x40000000u && dh_q_abs_u32(u[1]) <= 0x40000000u;
}

static DH_NOINLINE void refq_b2(refq_work *w)
{
    const dh_ikc_model_q *m = w->m;
    const int32_t *t = w->t;
    int32_t *u = w->u;
    const int64_t det = dh_q_mul64(m->a[1], u[2]);
    const int32_t gx = u[1], gy = u[0];
    const int32_t u3 = refq_div(dh_q_mla64(dh_q_mul64(gx, u[4]), -gy, u[3]), det, 30);
    const int32_t u4 =
        refq_div(dh_q_mul64(m->a[1], refq_sat(dh_q_rshr(dh_q_mla64(dh_q_mul64(t[0], gy), -t[1], gx), 30u))), det, 30);
    u[6] = refq_sat((int64_t)u[5] - u3 - u4);
    u[7] = m->k[RQ_S2] * u3;
    u[8] = m->k[RQ_S23] * u4;
}

/* The steps (rad, Q2.30; joints 1, 5, 6 in u[9..11], 2, 3, 4 in u[6..8]),
 * scaled to at most REFQ_MAX_STEP, added to q (Q16.16 degrees, wrapped
 * into (-180, 180]). */
static DH_NOINLINE void refq_apply(refq_work *w, int32_t *q)
{
    /* joint i's step in u[refq_order[i]] */
    static const uint8_t refq_order[6] = {9u, 6u, 7u, 8u, 10u, 11u};
    const int32_t *u = w->u;
    uint32_t big = 0u, i;
    for (i = 6u; i < 12u; i++)
        if (dh_q_abs_u32(u[i]) > big) big = dh_q_abs_u32(u[i]);
    for (i = 0; i < 6u; i++) {
        int32_t x = u[refq_order[i]];
        if (big > (uint32_t)REFQ_MAX_STEP) x = refq_div(dh_q_mul64(x, REFQ_MAX_STEP), (int64_t)big, 0);
        q[i] = dh_ikc_wrap180_q_(q[i] + (int32_t)dh_q_rshr(dh_q_mul64(x, REFQ_RAD2DEG), 38u));
    }
}

/* The refined solutions, distinct, packed to the front, their private
 * flags cleared; their count. */
static DH_NOINLINE uint32_t refq_pack(dh_ikc_sol_q *sol)
{
    uint32_t s, k, i, n = 0;
    for (s = 0; s < DH_IKC_MAX_SOL; s++) {
        int keep = (sol[s].flags & (DH_IKC_REFINED | REFQ_FREE)) == DH_IKC_REFINED;
        sol[s].flags &= ~(uint32_t)REFQ_PRIVATE;
        for (k = 0; keep && k < n; k++) {
            for (i = 0; i < 6u; i++) {
                const int32_t d = dh_ikc_wrap180_q_(sol[k].q[i] - sol[s].q[i]);
                if (d > REFQ_SAME || d < -REFQ_SAME) break;
            }
            if (i == 6u) keep = 0;
        }
        if (!keep) continue;
        if (n != s) sol[n] = sol[s];
        n++;
    }
    return n;
}

/* theta2 + s2 theta3 (+ s23 theta4 with with4) of the canonical values q
 * (each in (-180, 180]: the sum within +-540 degrees) */
DH_INLINE int32_t refq_phi(const dh_ikc_model_q *m, const int32_t *q, int with4)
{
    int32_t v = q[1] + m->k[RQ_S2] * q[2];
    if (with4) v += m->k[RQ_S23] * q[3];
    return v;
}

/* ---- restart from the virtual target ------------------------------------------ */

/* Slots 0..raw-1 flagged REFQ_NEW (the raw branches), the others
 * REFQ_FREE. */
static DH_NOINLINE void refq_marks(dh_ikc_sol_q *sol, uint32_t raw)
{
    uint32_t s;
    for (s = 0; s < DH_IKC_MAX_SOL; s++) sol[s].flags = (s < raw) ? (sol[s].flags | REFQ_NEW) : REFQ_FREE;
}

/* The branches of shoulder sh (0 or DH_IKC_SHOULDER_ALT) that did not
 * converge, or that the idealised chain did not have, marked REFQ_PEND
 * (those that did not converge in their slots, the missing ones in free
 * slots while there are any). Returns src + 16 st: src the slot whose
 * values start them (a converged branch of the shoulder when there is
 * one), st a pending slot other than src (its q takes the exact errors
 * at src); REFQ_NONE when there is no restart (every branch converged,
 * a singular branch, no branch of the shoulder, no such st). */
static DH_NOINLINE uint32_t refq_plan(dh_ikc_sol_q *sol, uint32_t sh)
{
    uint32_t s, c, src = DH_IKC_MAX_SOL, done = 0u, st = DH_IKC_MAX_SOL;
    for (s = 0; s < DH_IKC_MAX_SOL; s++) {
        const uint32_t f = sol[s].flags;
        if ((f & REFQ_FREE) != 0u || (f & DH_IKC_SHOULDER_ALT) != sh) continue;
        if ((f & REFQ_SINGS) != 0u) return REFQ_NONE;
        if ((f & DH_IKC_REFINED) != 0u) {
            done |= 1u << ((f & (DH_IKC_ELBOW_ALT | DH_IKC_WRIST_ALT)) >> 1);
            src = s;
        } else if (src == DH_IKC_MAX_SOL || (sol[src].flags & DH_IKC_REFINED) == 0u) {
            src = s;
        } else {
            /* an unconverged branch after a converged one: the start stays */
        }
    }
    if (src == DH_IKC_MAX_SOL) return REFQ_NONE;
    for (c = 0; c < 4u; c++) {
        const uint32_t f = sh | (c << 1);
        uint32_t slot = DH_IKC_MAX_SOL;
        if (((done >> c) & 1u) != 0u) continue;
        /* its own unconverged slot, else the first free one */
        for (s = DH_IKC_MAX_SOL; s > 0u; s--)
            if ((sol[s - 1u].flags & REFQ_FREE) != 0u) slot = s - 1u;
        for (s = 0; s < DH_IKC_MAX_SOL; s++)
            if ((sol[s].flags & (REFQ_FREE | REFQ_PEND | REFQ_BRANCH | DH_IKC_REFINED)) == f) slot = s;
        if (slot == DH_IKC_MAX_SOL) continue;
        sol[slot].flags = f | REFQ_PEND;
        if (slot != src && st == DH_IKC_MAX_SOL) st = slot;
    }
    return (st == DH_IKC_MAX_SOL) ? REFQ_NONE : src + 16u * st;
}

/* The first-order virtual target of the canonical values whose exact
 * errors (refq_rot, refq_perr, refq_unbase: the joint 5 point's position
 * error and the rotation error, canonical base) are in e, from the
 * idealised chain's T06 there in u (refq_fk, REFQ_IDEAL): T'06 = the
 * errors applied to it, the target whose idealised solution of the
 * branch is those values up to the change of the deviations' effect
 * between them and that solution. Its vectors as the family solver reads
 * them into u: the joint 5 point u[0..2], x6 u[3..5], axis 6 u[6..8]. */
static DH_NOINLINE void refq_virtual(refq_work *w, const int32_t *e)
{
    const int32_t sa = w->m->sa[5], ca = w->m->ca[5];
    int32_t *u = w->u;
    uint32_t k;
    for (k = 0; k < 3u; k++) u[3u + k] = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(sa, u[3u + k]), ca, u[6u + k]));
    /* axis 6, then x6, each turned by the rotation error */
    for (k = 0; k < 6u; k += 3u) {
        const int32_t *a = &u[(k == 0u) ? 3u : 0u];
        int32_t *o = &u[(k == 0u) ? 6u : 3u];
        const int32_t x = a[0], y = a[1], z = a[2];
        o[0] = refq_sat((int64_t)x + dh_ikc_r30_q_(dh_q_mul64(e[4], z) - dh_q_mul64(e[5], y)));
        o[1] = refq_sat((int64_t)y + dh_ikc_r30_q_(dh_q_mul64(e[5], x) - dh_q_mul64(e[3], z)));
        o[2] = refq_sat((int64_t)z + dh_ikc_r30_q_(dh_q_mul64(e[3], y) - dh_q_mul64(e[4], x)));
    }
    for (k = 0; k < 3u; k++) u[k] = refq_sat((int64_t)u[9u + k] + e[k]);
}

/* The idealised chain's solution of slot b's branch (its flags) for the
 * target whose vectors are in u (refq_virtual): the closed form of
 * DH_IKC_PARALLEL_234 (dh_ikc_par234_q.c) for one branch, in three
 * helpers: refq_sh joint 1 (cos, sin into t[0], t[1]), refq_wr joints 5,
 * 6 and phi (q[3]; cos, sin into u[9], u[10]), refq_el joints 2, 3, 4.
 * 0 when the branch does not exist there (inside the shoulder cylinder,
 * the wrist singular, beyond the elbow's reach, or an overflow). */
static DH_NOINLINE int refq_sh(refq_work *w, dh_ikc_sol_q *b)
{
    const int32_t *k = w->m->k, *p = w->u;
    const int32_t th = (k[RQ_TAU] > 0) ? k[RQ_H] : -k[RQ_H];
    const int64_t v = dh_q_mla64(dh_q_mul64(p[0], p[0]), p[1], p[1]) - dh_q_mul64(k[RQ_H], k[RQ_H]);
    int32_t r;
    if (v <= 0) return 0;
    r = (int32_t)dh_q_isqrt62((uint64_t)v);
    if ((b->flags & DH_IKC_SHOULDER_ALT) != 0u) r = -r;
    b->q[0] = dh_ikc_atan2_q_(dh_q_mla64(dh_q_mul64(th, p[0]), r, p[1]), dh_q_mul64(r, p[0]) - dh_q_mul64(th, p[1]));
    dh_sincos_q(b->q[0], &w->t[1], &w->t[0]);
    return 1;
}

static DH_NOINLINE int refq_wr(refq_work *w, dh_ikc_sol_q *b)
{
    const int32_t *k = w->m->k, *x = &w->u[3], *z = &w->u[6];
    const int32_t c1 = w->t[0], s1 = w->t[1];
    const int32_t cp = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(c1, z[0]), s1, z[1]));
    const int32_t sp = (k[RQ_TAU] > 0) ? z[2] : -z[2];
    int32_t sn, cs, s5, c5, n11, n21, n31, mx, my, phi;
    if (dh_q_abs_u32(cp) <= REFQ_SING_W && dh_q_abs_u32(sp) <= REFQ_SING_W) return 0;
    phi = dh_ikc_atan2_q_((k[RQ_W5] > 0) ? sp : -sp, (k[RQ_W5] > 0) ? cp : -cp);
    dh_sincos_q(phi, &sn, &cs);
    s5 = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(cs, cp), sn, sp));
    if (k[RQ_W5] < 0) s5 = -s5;
    c5 = dh_ikc_r30_q_(dh_q_mul64(s1, z[0]) - dh_q_mul64(c1, z[1]));
    if ((k[RQ_TAU] * k[RQ_SB] * k[RQ_W5]) > 0) c5 = -c5;
    b->q[4] = 0;
    (void)dh_atan2_q(s5, c5, &b->q[4]);
    n11 = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(c1, x[0]), s1, x[1]));
    n21 = (k[RQ_TAU] > 0) ? x[2] : -x[2];
    n31 = dh_ikc_r30_q_(dh_q_mul64(s1, x[0]) - dh_q_mul64(c1, x[1]));
    if (k[RQ_TAU] < 0) n31 = -n31;
    mx = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(cs, n11), sn, n21));
    my = dh_ikc_r30_q_(dh_q_mul64(cs, n21) - dh_q_mul64(sn, n11));
    if (k[RQ_SB] < 0) s5 = -s5;
    if ((k[RQ_W5] * k[RQ_SB]) > 0) my = -my;
    b->q[5] = dh_ikc_atan2_q_(dh_q_mul64(my, DH_Q_ONE30), dh_q_mla64(dh_q_mul64(c5, mx), s5, n31));
    if ((b->flags & DH_IKC_WRIST_ALT) != 0u) {
        b->q[4] = dh_ikc_wrap180_q_(-b->q[4]);
        b->q[5] = dh_ikc_wrap180_q_(b->q[5] + DH_IKC_Q16_180);
        phi = dh_ikc_wrap180_q_(phi + DH_IKC_Q16_180);
        cs = -cs;
        sn = -sn;
    }
    b->q[3] = phi;
    w->u[9] = cs;
    w->u[10] = sn;
    return 1;
}

static DH_NOINLINE int refq_el(refq_work *w, dh_ikc_sol_q *b)
{
    const dh_ikc_model_q *m = w->m;
    const int32_t *k = m->k, *p = w->u;
    const int32_t c1 = w->t[0], s1 = w->t[1], cs = w->u[9], sn = w->u[10];
    int64_t x, y;
    int32_t psi = 0, s3, c3, A, B, t3;
    x = dh_q_rshr(dh_q_mla64(dh_q_mul64(c1, p[0]), s1, p[1]), 30u) - m->a[0] -
        dh_q_rshr(dh_q_mla64(dh_q_mul64(m->a[3], cs), k[RQ_E5], sn), 30u);
    y = (k[RQ_TAU] > 0) ? (int64_t)p[2] - m->d[0] : (int64_t)m->d[0] - p[2];
    y -= dh_q_rshr(dh_q_mul64(m->a[3], sn) - dh_q_mul64(k[RQ_E5], cs), 30u);
    if (dh_ikc_abs64_q_(x) > REFQ_POS_LIM || dh_ikc_abs64_q_(y) > REFQ_POS_LIM) return 0;
    w->u[9] = (int32_t)x;
    w->u[10] = (int32_t)y;
    if (dh_ikc_elbow_q_(m->a[1], m->a[2], w->u[9], w->u[10], w->t) == 0u) return 0;
    (void)dh_atan2_q(w->t[0], w->t[1], &psi);
    t3 = dh_ikc_wrap180_q_(((b->flags & DH_IKC_ELBOW_ALT) != 0u) ? -psi : psi);
    dh_sincos_q(t3, &s3, &c3);
    A = m->a[1] + dh_ikc_r30_q_(dh_q_mul64(m->a[2], c3));
    B = dh_ikc_r30_q_(dh_q_mul64(m->a[2], s3));
    if (k[RQ_S2] < 0) B = -B;
    y = dh_q_mul64(A, w->u[10]) - dh_q_mul64(B, w->u[9]);
    x = dh_q_mla64(dh_q_mul64(A, w->u[9]), B, w->u[10]);
    if (x == 0 && y == 0) return 0;
    b->q[1] = dh_ikc_atan2_q_(y, x);
    b->q[2] = t3;
    A = dh_ikc_wrap180_q_(dh_ikc_wrap180_q_(b->q[3] - b->q[1]) - ((k[RQ_S2] > 0) ? t3 : -t3));
    b->q[3] = (k[RQ_S23] < 0) ? dh_ikc_wrap180_q_(-A) : A;
    return 1;
}

/* Slot b after its start (ok 1 when it has one): flagged REFQ_NEW; none:
 * free again. */
static DH_NOINLINE void refq_started(dh_ikc_sol_q *b, int ok)
{
    b->flags = ok ? ((b->flags & REFQ_BRANCH) | REFQ_NEW) : REFQ_FREE;
}

/* The exact errors at the canonical values q, canonical base, into
 * u[0..5] (refq_rot, refq_perr, refq_unbase); 1 on overflow. */
static DH_NOINLINE int refq_errors(refq_work *w, const int32_t *q)
{
    if (refq_fk(w, q, 0u) != 0) return 1;
    refq_tool(w);
    if (refq_base(w) != 0) return 1;
    refq_rot(w);
    refq_perr(w);
    return refq_unbase(w);
}

/* Five rounds over the slots (k: round k >> 3, slot k & 7). Round 0
 * refines the raw branches. Rounds 1 and 3 restart shoulder 0, then the
 * other: its missing and unconverged branches marked (refq_plan), the
 * virtual target of one of its branches formed (refq_errors, refq_fk on
 * the idealised chain, refq_virtual) and each marked slot started from it
 * (refq_sh, refq_wr, refq_el: near the wrist singularity the idealised
 * joint 1 can be degrees off, which the wrist turns into a planar point
 * beyond the elbow's reach for one wrist branch and into a start without
 * a solution near it for the other); rounds 2 and 4 refine those starts.
 * Each refinement at most DH_IKC_CAL_STEPS steps, each one exact forward
 * kinematics. The helpers run in sequence from here, and so do the
 * dh_sincos_q calls of the steps that fill w.t for them. */
uint32_t dh_ikc_refine_q_(const dh_ikc_model_q *m, const dh_frame_q *T, dh_ikc_sol_q *sol, uint32_t raw)
{
    refq_work w;
    uint32_t k, s, it;
    w.m = m;
    w.T = T;
    refq_marks(sol, (raw > DH_IKC_MAX_SOL) ? DH_IKC_MAX_SOL : raw);
    for (k = 0; k < 5u * DH_IKC_MAX_SOL; k++) {
        int32_t *q = sol[k & 7u].q;
        if ((k & 8u) != 0u) {
            /* a restart round, whole */
            it = refq_plan(sol, (k < 2u * DH_IKC_MAX_SOL) ? 0u : DH_IKC_SHOULDER_ALT);
            k += DH_IKC_MAX_SOL - 1u;
            if (it == REFQ_NONE || refq_errors(&w, sol[it & 15u].q) != 0) continue;
            for (s = 0; s < 6u; s++) sol[it >> 4].q[s] = w.u[s];
            if (refq_fk(&w, sol[it & 15u].q, REFQ_IDEAL) != 0) continue;
            refq_virtual(&w, sol[it >> 4].q);
            for (s = 0; s < DH_IKC_MAX_SOL; s++)
                if ((sol[s].flags & REFQ_PEND) != 0u)
                    refq_started(&sol[s], refq_sh(&w, &sol[s]) && refq_wr(&w, &sol[s]) && refq_el(&w, &sol[s]));
            continue;
        }
        if ((sol[k & 7u].flags & REFQ_NEW) == 0u) continue;
        sol[k & 7u].flags &= ~(uint32_t)(REFQ_NEW | DH_IKC_REFINED);
        it = 0u;
        while (it < REFQ_DONE) {
            it = (refq_fk(&w, q, 0u) != 0) ? REFQ_DONE : it;
            if (it < REFQ_DONE) {
                refq_tool(&w);
                if (refq_base(&w) != 0) it = REFQ_DONE;
            }
            if (it < REFQ_DONE) {
                refq_rot(&w);
                refq_perr(&w);
                it = refq_pos(&w, &sol[k & 7u], it);
            }
            if (it < REFQ_DONE && refq_unbase(&w) != 0) it = REFQ_DONE;
            if (it < REFQ_DONE) {
                dh_sincos_q(q[0], &w.u[10], &w.u[9]);
                refq_frame1(&w);
                refq_alpha1(&w);
                dh_sincos_q(refq_phi(m, q, 1), &w.u[10], &w.u[9]);
                dh_sincos_q(q[4], &w.u[11], &w.t[0]);
                if (refq_a(&w) == 0) it = REFQ_DONE;
            }
            if (it < REFQ_DONE) {
                refq_a2(&w);
                dh_sincos_q(refq_phi(m, q, 0), &w.u[4], &w.u[3]);
                dh_sincos_q(q[1], &w.t[1], &w.t[0]);
                if (refq_b(&w) == 0) it = REFQ_DONE;
            }
            if (it < REFQ_DONE) {
                refq_b2(&w);
                refq_apply(&w, q);
            }
        }
    }
    return refq_pack(sol);
}
