/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_ikc_refine_q.c - closed-form IK of calibrated robots, fixed point
 * (integer only: no float, no libm, no 64-bit division): the recognition of
 * a six-revolute chain within the calibration tolerance of
 * DH_IKC_PARALLEL_234 (dh_ikc_calibrate_q_, called by dh_ikc_analyse_q
 * after the exact detectors) and the refinement of the family solver's raw
 * solutions on the exact chain (dh_ikc_refine_q_ and dh_ikc_restart_q_,
 * called by dh_ikc_q after the solver has returned); interface in
 * ikc_impl.h. Method: the float twin's (dh_ikc_refine.c; docs/design.md,
 * "Calibrated robots").
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
 * A shoulder whose four branches are not all refined then starts again
 * from the virtual target of one of its branches (the exact errors there
 * applied to the idealised chain's T06), solved in closed form for each of
 * its missing branches, and those starts are refined.
 *
 * Formats: cosines and sines, rotation entries and rotation errors Q2.30;
 * points and position errors dh_qpos; joint steps Q2.30 radians; joint
 * values Q16.16 degrees. Products are int64, each sum rounded once.
 *
 * Stack: each of the two entries keeps its work data (the exact or
 * idealised frame, the errors, the virtual target; cosines and sines, 14
 * words); every helper runs from an entry in sequence, none below
 * another, and so do the trigonometry and elbow calls. The exact errors
 * at a restart's start wait in the q of a slot it fills, the unconverged
 * branches in the slots after the refined ones (caller memory).
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

/* Private flag bits of the slots between dh_ikc_refine_q_ and
 * dh_ikc_restart_q_, cleared on the refined ones: a slot waiting for a
 * start from the virtual target (refq_plan), a branch that did not
 * converge (a restart's start when its shoulder has no refined one), and
 * a free one. */
#define REFQ_PEND 0x100u
#define REFQ_UNCONV 0x200u
#define REFQ_FREE 0x400u
#define REFQ_PRIVATE 0x700u
#define REFQ_BRANCH (DH_IKC_SHOULDER_ALT | DH_IKC_ELBOW_ALT | DH_IKC_WRIST_ALT)
#define REFQ_SINGS (DH_IKC_SING_WRIST | DH_IKC_SING_SHOULDER | DH_IKC_SING_ELBOW)
/* refq_plan: no restart; dh_ikc_restart_q_: an overflow (its plan's bit) */
#define REFQ_NONE 0x80u
#define REFQ_OVF 0x100u
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

/* Joint i of the exact chain, or of the idealised one with i | REFQ_IDEAL
 * (cos, sin of its canonical value in t[0], t[1]), applied to u in three
 * helpers, each a pass over the three rows: refq_turn the turn about z,
 * refq_offset the offsets a_i, d_i (1 on overflow), refq_twist the twist. */
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

static DH_NOINLINE void refq_twist(refq_work *w, uint32_t i)
{
    const uint32_t j = i & 7u;
    const int ideal = (i & REFQ_IDEAL) != 0u;
    const int32_t sa = ideal ? w->m->sa[j] : w->m->xsa[j], ca = ideal ? w->m->ca[j] : w->m->xca[j];
    int32_t *u = w->u;
    uint32_t r;
    for (r = 0; r < 3u; r++) {
        const int32_t y = u[3u + r], z = u[6u + r];
        u[3u + r] = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(ca, y), sa, z));
        u[6u + r] = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(ca, z), -sa, y));
    }
}

/* u <- the identity frame (a forward kinematics starts; joint 6's offsets
 * are left out: the point ends at the joint 5 point, frame 5's origin) */
static DH_NOINLINE void refq_fk_init(refq_work *w)
{
    uint32_t i;
    for (i = 0; i < 12u; i++) w->u[i] = ((i & 3u) == 0u && i < 9u) ? DH_Q_ONE30 : 0;
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

/* The refined solutions among sol[0..raw-1], distinct, swapped to the
 * front, their private flags cleared; after them the unconverged ones
 * flagged REFQ_UNCONV, every other slot REFQ_FREE; the refined count. */
static DH_NOINLINE uint32_t refq_pack(dh_ikc_sol_q *sol, uint32_t raw)
{
    uint32_t s, k, i, n = 0;
    for (s = 0; s < raw; s++) {
        int keep = (sol[s].flags & (DH_IKC_REFINED | REFQ_FREE | REFQ_UNCONV)) == DH_IKC_REFINED;
        for (k = 0; keep && k < n; k++) {
            for (i = 0; i < 6u; i++) {
                const int32_t d = dh_ikc_wrap180_q_(sol[k].q[i] - sol[s].q[i]);
                if (d > REFQ_SAME || d < -REFQ_SAME) break;
            }
            if (i == 6u) keep = 0;
        }
        if ((sol[s].flags & DH_IKC_REFINED) != 0u) sol[s].flags = keep ? (sol[s].flags & ~(uint32_t)REFQ_PRIVATE) : REFQ_FREE;
        if (!keep) continue;
        for (i = 0; n != s && i < 6u; i++) {
            const int32_t t = sol[n].q[i];
            sol[n].q[i] = sol[s].q[i];
            sol[s].q[i] = t;
        }
        k = sol[n].flags;
        sol[n].flags = sol[s].flags;
        sol[s].flags = (n != s) ? k : sol[s].flags;
        n++;
    }
    for (s = n; s < DH_IKC_MAX_SOL; s++)
        sol[s].flags = (s < raw && (sol[s].flags & (REFQ_FREE | DH_IKC_REFINED)) == 0u) ? (sol[s].flags | REFQ_UNCONV)
                                                                                       : REFQ_FREE;
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

/* The branches of shoulder sh (0 or DH_IKC_SHOULDER_ALT) that are not
 * among the n refined solutions sol[0..n-1] (the idealised chain lacked
 * them, or they did not converge), marked REFQ_PEND in free slots or in
 * the unconverged ones of the shoulder (refq_pack), while there are any.
 * Returns src + 16 st: src the slot whose values start them (a refined
 * branch of the shoulder, else an unconverged one), st the first marked;
 * REFQ_NONE when there is no restart (every branch refined, a singular
 * one, no start, no slot). */
/* A slot of flags f open to a start of shoulder sh: free, or unconverged
 * and of sh or of the other shoulder when that has a refined branch (bit
 * 4 of done) */
DH_INLINE int refq_open(uint32_t f, uint32_t sh, uint32_t done)
{
    return (f & REFQ_FREE) != 0u ||
           ((f & REFQ_UNCONV) != 0u && ((f & DH_IKC_SHOULDER_ALT) == sh || (done & 0x10u) != 0u));
}

static DH_NOINLINE uint32_t refq_plan(dh_ikc_sol_q *sol, uint32_t n, uint32_t shx)
{
    const uint32_t sh = shx & DH_IKC_SHOULDER_ALT;
    uint32_t s, c, src = DH_IKC_MAX_SOL, done = 0u, st = DH_IKC_MAX_SOL;
    for (s = 0; s < DH_IKC_MAX_SOL; s++) {
        const uint32_t f = sol[s].flags;
        if ((s >= n && (f & REFQ_UNCONV) == 0u) || (f & DH_IKC_SHOULDER_ALT) != sh) continue;
        if ((f & REFQ_SINGS) != 0u) return REFQ_NONE;
        if (s < n) done |= 1u << ((f & (DH_IKC_ELBOW_ALT | DH_IKC_WRIST_ALT)) >> 1);
        if (s < n || src == DH_IKC_MAX_SOL) src = s;
    }
    /* again: only a shoulder with branches, none refined (each a start
     * beyond the elbow's reach or a failed refinement) */
    if ((shx & DH_IKC_RESTART_AGAIN_) != 0u && (done != 0u || src == DH_IKC_MAX_SOL)) return REFQ_NONE;
    /* a shoulder the idealised chain lacks: from a branch of the other */
    for (s = 0; src == DH_IKC_MAX_SOL && s < DH_IKC_MAX_SOL; s++)
        if (s < n || (sol[s].flags & REFQ_UNCONV) != 0u) src = s;
    if (src == DH_IKC_MAX_SOL) return REFQ_NONE;
    /* the other shoulder's unconverged slots are free when it has a refined branch */
    for (s = 0; s < n; s++)
        if ((sol[s].flags & DH_IKC_SHOULDER_ALT) != sh) done |= 0x10u;
    s = n;
    for (c = 0; c < 4u; c++) {
        if (((done >> c) & 1u) != 0u) continue;
        while (s < DH_IKC_MAX_SOL && (s == src || !refq_open(sol[s].flags, sh, done))) s++;
        if (s == DH_IKC_MAX_SOL) break;
        sol[s].flags = sh | (c << 1) | REFQ_PEND;
        if (st == DH_IKC_MAX_SOL) st = s;
    }
    return (st == DH_IKC_MAX_SOL) ? REFQ_NONE : src + 16u * st;
}

/* The first-order virtual target of the canonical values whose exact
 * errors (refq_rot, refq_perr, refq_unbase: the joint 5 point's position
 * error and the rotation error, canonical base) are in e, from the
 * idealised chain's T06 there in u (the idealised forward kinematics): T'06
 * = the errors applied to it, the target whose idealised solution of the
 * branch is those values up to the change of the deviations' effect
 * between them and that solution. Its vectors as the family solver reads
 * them into u: the joint 5 point u[0..2], x6 u[3..5], axis 6 u[6..8]; in
 * two helpers, refq_zaxis axis 6 (sa6 y6 + ca6 z6) into u[3..5],
 * refq_spin (twice) a vector turned by the rotation error, then the point
 * moved by the position error. */
static DH_NOINLINE void refq_zaxis(refq_work *w)
{
    const int32_t sa = w->m->sa[5], ca = w->m->ca[5];
    int32_t *u = w->u;
    uint32_t k;
    for (k = 0; k < 3u; k++) u[3u + k] = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(sa, u[3u + k]), ca, u[6u + k]));
}

/* v: 0 axis 6 (u[3..5] into u[6..8]), 1 x6 (u[0..2] into u[3..5]), 2 the
 * point (u[9..11] plus the position error into u[0..2]) */
static DH_NOINLINE void refq_spin(refq_work *w, const int32_t *e, uint32_t v)
{
    int32_t *u = w->u;
    const int32_t *a = &u[(v == 0u) ? 3u : 0u];
    int32_t *o = &u[(v == 0u) ? 6u : 3u];
    uint32_t k;
    if (v == 2u) {
        for (k = 0; k < 3u; k++) u[k] = refq_sat((int64_t)u[9u + k] + e[k]);
        return;
    }
    for (k = 0; k < 3u; k++) {
        const uint32_t k1 = (k == 2u) ? 0u : k + 1u, k2 = (k == 0u) ? 2u : k - 1u;
        /* (e_r x a)_k = e_k1 a_k2 - e_k2 a_k1 */
        const int64_t c = dh_q_mul64(e[3u + k1], a[k2]) - dh_q_mul64(e[3u + k2], a[k1]);
        o[k] = refq_sat((int64_t)a[k] + dh_ikc_r30_q_(c));
    }
}

/* (y, x) of a common scale rounded by one shift below 2^30 into o[0],
 * o[1] (the atan2 arguments of a start); 0 when both are 0 */
DH_INLINE int refq_args(int32_t *o, int64_t y, int64_t x)
{
    const uint64_t ay = dh_ikc_abs64_q_(y), ax = dh_ikc_abs64_q_(x);
    const unsigned n = dh_q_bitlen64(ay > ax ? ay : ax);
    const unsigned sh = (n > 30u) ? n - 30u : 0u;
    o[0] = (int32_t)((sh != 0u) ? dh_q_rshr(y, sh) : y);
    o[1] = (int32_t)((sh != 0u) ? dh_q_rshr(x, sh) : x);
    return (ay | ax) != 0u;
}

/* The idealised chain's solution of slot b's branch (its flags) for the
 * target whose vectors are in u (refq_zaxis, refq_spin): the closed form
 * of DH_IKC_PARALLEL_234 (dh_ikc_par234_q.c) for one branch. The helpers
 * form the arguments of its angles, dh_ikc_refine_q_ takes the atan2,
 * sine, cosine and elbow calls between them: refq_s1 joint 1's (u[9],
 * u[10]; cos, sin of t1 then in t[0], t[1]), refq_w1 phi's (u[9], u[10];
 * its cos, sin then there), refq_w2 joint 5's (q[1], q[2]), refq_w3
 * joint 6's (q[1], q[2]), refq_w4 the wrist flip, refq_e1 the planar
 * point (u[9], u[10]; the elbow's pair then in t), refq_e2 joint 3,
 * refq_e3 joint 2's (t[0], t[1], after cos, sin of t3 there), refq_e4
 * joint 4. 0 where the branch does not exist (inside the shoulder
 * cylinder, the wrist singular, an overflow). */
static DH_NOINLINE int refq_s1(refq_work *w, const dh_ikc_sol_q *b)
{
    const int32_t *k = w->m->k, *p = w->u;
    const int32_t th = (k[RQ_TAU] > 0) ? k[RQ_H] : -k[RQ_H];
    const int64_t v = dh_q_mla64(dh_q_mul64(p[0], p[0]), p[1], p[1]) - dh_q_mul64(k[RQ_H], k[RQ_H]);
    int32_t r;
    if (v <= 0) return 0;
    r = (int32_t)dh_q_isqrt62((uint64_t)v);
    if ((b->flags & DH_IKC_SHOULDER_ALT) != 0u) r = -r;
    return refq_args(&w->u[9], dh_q_mla64(dh_q_mul64(th, p[0]), r, p[1]), dh_q_mul64(r, p[0]) - dh_q_mul64(th, p[1]));
}

/* n13 (cp) and n23 (sp) of the target in frame 1 into o[0], o[1] */
static DH_NOINLINE void refq_n3(const refq_work *w, int32_t *o)
{
    const int32_t *z = &w->u[6];
    o[0] = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(w->t[0], z[0]), w->t[1], z[1]));
    o[1] = (w->m->k[RQ_TAU] > 0) ? z[2] : -z[2];
}

static DH_NOINLINE int refq_w1(refq_work *w)
{
    int32_t n[2];
    refq_n3(w, n);
    if (dh_q_abs_u32(n[0]) <= REFQ_SING_W && dh_q_abs_u32(n[1]) <= REFQ_SING_W) return 0;
    /* (y, x) = w5 (sp, cp) */
    w->u[9] = (w->m->k[RQ_W5] > 0) ? n[1] : -n[1];
    w->u[10] = (w->m->k[RQ_W5] > 0) ? n[0] : -n[0];
    return 1;
}

static DH_NOINLINE void refq_w2(const refq_work *w, dh_ikc_sol_q *b)
{
    const int32_t *k = w->m->k, *z = &w->u[6];
    int32_t n[2], s5, c5;
    refq_n3(w, n);
    s5 = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(w->u[9], n[0]), w->u[10], n[1]));
    c5 = dh_ikc_r30_q_(dh_q_mul64(w->t[1], z[0]) - dh_q_mul64(w->t[0], z[1]));
    if (k[RQ_W5] < 0) s5 = -s5;
    if ((k[RQ_TAU] * k[RQ_SB] * k[RQ_W5]) > 0) c5 = -c5;
    b->q[1] = s5;
    b->q[2] = c5;
}

static DH_NOINLINE void refq_w3(const refq_work *w, dh_ikc_sol_q *b)
{
    const int32_t *k = w->m->k, *x = &w->u[3];
    const int32_t c1 = w->t[0], s1 = w->t[1], cs = w->u[9], sn = w->u[10];
    const int32_t n11 = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(c1, x[0]), s1, x[1]));
    const int32_t n21 = (k[RQ_TAU] > 0) ? x[2] : -x[2];
    int32_t n31 = dh_ikc_r30_q_(dh_q_mul64(s1, x[0]) - dh_q_mul64(c1, x[1]));
    int32_t my = dh_ikc_r30_q_(dh_q_mul64(cs, n21) - dh_q_mul64(sn, n11));
    const int32_t mx = dh_ikc_r30_q_(dh_q_mla64(dh_q_mul64(cs, n11), sn, n21));
    if (k[RQ_TAU] < 0) n31 = -n31;
    if (k[RQ_SB] < 0) n31 = -n31; /* with sb s5 */
    if ((k[RQ_W5] * k[RQ_SB]) > 0) my = -my;
    (void)refq_args(&b->q[1], dh_q_mul64(my, DH_Q_ONE30), dh_q_mla64(dh_q_mul64(b->q[2], mx), b->q[1], n31));
}

static DH_NOINLINE void refq_w4(refq_work *w, dh_ikc_sol_q *b)
{
    if ((b->flags & DH_IKC_WRIST_ALT) == 0u) return;
    b->q[4] = dh_ikc_wrap180_q_(-b->q[4]);
    b->q[5] = dh_ikc_wrap180_q_(b->q[5] + DH_IKC_Q16_180);
    b->q[3] = dh_ikc_wrap180_q_(b->q[3] + DH_IKC_Q16_180);
    w->u[9] = -w->u[9];
    w->u[10] = -w->u[10];
}

static DH_NOINLINE int refq_e1(refq_work *w)
{
    const dh_ikc_model_q *m = w->m;
    const int32_t *k = m->k, *p = w->u;
    const int32_t cs = w->u[9], sn = w->u[10];
    int64_t x, y;
    x = dh_q_rshr(dh_q_mla64(dh_q_mul64(w->t[0], p[0]), w->t[1], p[1]), 30u) - m->a[0] -
        dh_q_rshr(dh_q_mla64(dh_q_mul64(m->a[3], cs), k[RQ_E5], sn), 30u);
    y = (k[RQ_TAU] > 0) ? (int64_t)p[2] - m->d[0] : (int64_t)m->d[0] - p[2];
    y -= dh_q_rshr(dh_q_mul64(m->a[3], sn) - dh_q_mul64(k[RQ_E5], cs), 30u);
    if (dh_ikc_abs64_q_(x) > REFQ_POS_LIM || dh_ikc_abs64_q_(y) > REFQ_POS_LIM) return 0;
    w->u[9] = (int32_t)x;
    w->u[10] = (int32_t)y;
    return 1;
}

/* e: dh_ikc_elbow_q_'s verdict on the planar point (u[9], u[10]), its
 * pair in t. 0 (beyond the elbow's reach): the elbow stretched or folded
 * towards the point, the pair (0, K sgn D) into t (K = |v|^2 - a2^2 -
 * a3^2, D = 2 a2 a3). Returns 1 (a start either way). */
static DH_NOINLINE uint32_t refq_reach(refq_work *w, unsigned e)
{
    const int32_t l1 = w->m->a[1], l2 = w->m->a[2];
    int64_t k;
    if (e != 0u) return 1u;
    k = dh_q_mla64(dh_q_mul64(w->u[9], w->u[9]), w->u[10], w->u[10]) - dh_q_mla64(dh_q_mul64(l1, l1), l2, l2);
    if ((l1 < 0) != (l2 < 0)) k = -k;
    w->t[0] = 0;
    w->t[1] = (k < 0) ? -DH_Q_ONE30 : DH_Q_ONE30;
    return 1u;
}

static DH_NOINLINE void refq_e2(dh_ikc_sol_q *b)
{
    if ((b->flags & DH_IKC_ELBOW_ALT) != 0u) b->q[2] = dh_ikc_wrap180_q_(-b->q[2]);
}

static DH_NOINLINE int refq_e3(refq_work *w)
{
    const dh_ikc_model_q *m = w->m;
    int32_t A = m->a[1] + dh_ikc_r30_q_(dh_q_mul64(m->a[2], w->t[0]));
    int32_t B = dh_ikc_r30_q_(dh_q_mul64(m->a[2], w->t[1]));
    if (m->k[RQ_S2] < 0) B = -B;
    return refq_args(w->t, dh_q_mul64(A, w->u[10]) - dh_q_mul64(B, w->u[9]),
                     dh_q_mla64(dh_q_mul64(A, w->u[9]), B, w->u[10]));
}

static DH_NOINLINE void refq_e4(const refq_work *w, dh_ikc_sol_q *b)
{
    const int32_t *k = w->m->k;
    const int32_t t3 = b->q[2];
    const int32_t a = dh_ikc_wrap180_q_(dh_ikc_wrap180_q_(b->q[3] - b->q[1]) - ((k[RQ_S2] > 0) ? t3 : -t3));
    b->q[3] = (k[RQ_S23] < 0) ? dh_ikc_wrap180_q_(-a) : a;
}

/* Slot b after its start (ok 1 when it has one): its branch's flags; none:
 * REFQ_FREE (dh_ikc_refine_q_ leaves it out). */
static DH_NOINLINE void refq_started(dh_ikc_sol_q *b, uint32_t ok)
{
    b->flags = (ok != 0u) ? (b->flags & REFQ_BRANCH) : REFQ_FREE;
}

/* Each solution of sol[0..raw-1] that is neither refined nor free refined
 * in its slot: at most DH_IKC_CAL_STEPS steps, each one exact forward
 * kinematics; the helpers run in sequence from here, and so do the
 * dh_sincos_q calls that fill w.t for them. Then the refined ones packed
 * (refq_pack); returns their count. */
uint32_t dh_ikc_refine_q_(const dh_ikc_model_q *m, const dh_frame_q *T, dh_ikc_sol_q *sol, uint32_t raw)
{
    refq_work w;
    uint32_t s, it, i;
    w.m = m;
    w.T = T;
    if (raw > DH_IKC_MAX_SOL) raw = DH_IKC_MAX_SOL;
    for (s = 0; s < raw; s++) {
        int32_t *q = sol[s].q;
        it = 0u;
        if ((sol[s].flags & (DH_IKC_REFINED | REFQ_FREE | REFQ_UNCONV)) != 0u) it = REFQ_DONE;
        while (it < REFQ_DONE) {
            int ovf = 0;
            refq_fk_init(&w);
            for (i = 0; i < 6u; i++) {
                dh_sincos_q(q[i], &w.t[1], &w.t[0]);
                refq_turn(&w);
                if (i < 5u) ovf |= refq_offset(&w, i);
                refq_twist(&w, i);
            }
            refq_tool(&w);
            it = (ovf != 0 || refq_base(&w) != 0) ? REFQ_DONE : it;
            if (it < REFQ_DONE) {
                refq_rot(&w);
                refq_perr(&w);
                it = refq_pos(&w, &sol[s], it);
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
    return refq_pack(sol, raw);
}

/* Shoulder sh restarted (refq_plan) from the virtual target of one of its
 * refined branches src: the exact errors there (an exact pass: refq_tool
 * .. refq_unbase, kept in the q of the first slot the restart fills), the
 * idealised chain's T06 there (an idealised pass) turned into the virtual
 * target (refq_zaxis, refq_spin), and each marked slot started from it
 * (refq_s1 .. refq_e4 and the trigonometry and elbow calls between them,
 * from here): near the wrist singularity the idealised joint 1 can be
 * degrees off, which the wrist turns into a planar point beyond the
 * elbow's reach for one wrist branch and into a start without a solution
 * near it for the other. Returns the number of slots in use (n plus the
 * marked ones; a start that failed free), for dh_ikc_refine_q_. */
uint32_t dh_ikc_restart_q_(const dh_ikc_model_q *m, const dh_frame_q *T, dh_ikc_sol_q *sol, uint32_t n, uint32_t sh)
{
    refq_work w;
    uint32_t pl, i, it;
    w.m = m;
    w.T = T;
    pl = refq_plan(sol, n, sh);
    if (pl == REFQ_NONE) return n;
    /* an exact pass, then an idealised one; an overflow sets REFQ_OVF in pl */
    for (it = 0; it < 2u && pl < REFQ_OVF; it++) {
        refq_fk_init(&w);
        for (i = 0; i < 6u; i++) {
            dh_sincos_q(sol[pl & 15u].q[i], &w.t[1], &w.t[0]);
            refq_turn(&w);
            if (i < 5u && refq_offset(&w, i | (it * REFQ_IDEAL)) != 0) pl |= REFQ_OVF;
            refq_twist(&w, i | (it * REFQ_IDEAL));
        }
        if (it == 0u) {
            refq_tool(&w);
            if (refq_base(&w) != 0) pl |= REFQ_OVF;
        }
        if (it == 0u && pl < REFQ_OVF) {
            refq_rot(&w);
            refq_perr(&w);
            if (refq_unbase(&w) != 0) pl |= REFQ_OVF;
        }
        for (i = 0; it == 0u && pl < REFQ_OVF && i < 6u; i++) sol[(pl >> 4) & 15u].q[i] = w.u[i];
    }
    if (pl < REFQ_OVF) {
        refq_zaxis(&w);
        refq_spin(&w, sol[pl >> 4].q, 0u);
        refq_spin(&w, sol[pl >> 4].q, 1u);
        refq_spin(&w, sol[pl >> 4].q, 2u);
    }
    /* an unconverged start is left out */
    if ((pl & 15u) >= n) sol[pl & 15u].flags = REFQ_FREE;
    for (i = 0; i < DH_IKC_MAX_SOL; i++) {
        if ((sol[i].flags & REFQ_PEND) == 0u) continue;
        it = (pl < REFQ_OVF) ? (uint32_t)refq_s1(&w, &sol[i]) : 0u;
        if (it != 0u) {
            sol[i].q[0] = 0;
            (void)dh_atan2_q(w.u[9], w.u[10], &sol[i].q[0]);
            dh_sincos_q(sol[i].q[0], &w.t[1], &w.t[0]);
            it = (uint32_t)refq_w1(&w);
        }
        if (it != 0u) {
            sol[i].q[3] = 0;
            (void)dh_atan2_q(w.u[9], w.u[10], &sol[i].q[3]);
            dh_sincos_q(sol[i].q[3], &w.u[10], &w.u[9]);
            refq_w2(&w, &sol[i]);
            sol[i].q[4] = 0;
            (void)dh_atan2_q(sol[i].q[1], sol[i].q[2], &sol[i].q[4]);
            refq_w3(&w, &sol[i]);
            sol[i].q[5] = 0;
            (void)dh_atan2_q(sol[i].q[1], sol[i].q[2], &sol[i].q[5]);
            refq_w4(&w, &sol[i]);
            it = (uint32_t)refq_e1(&w);
        }
        if (it != 0u) it = refq_reach(&w, dh_ikc_elbow_q_(m->a[1], m->a[2], w.u[9], w.u[10], w.t));
        if (it != 0u) {
            sol[i].q[2] = 0;
            (void)dh_atan2_q(w.t[0], w.t[1], &sol[i].q[2]);
            refq_e2(&sol[i]);
            dh_sincos_q(sol[i].q[2], &w.t[1], &w.t[0]);
            it = (uint32_t)refq_e3(&w);
        }
        if (it != 0u) {
            sol[i].q[1] = 0;
            (void)dh_atan2_q(w.t[0], w.t[1], &sol[i].q[1]);
            refq_e4(&w, &sol[i]);
        }
        refq_started(&sol[i], it);
    }
    /* the slots up to the last one in use */
    i = DH_IKC_MAX_SOL;
    while (i > n && (sol[i - 1u].flags & REFQ_FREE) != 0u) i--;
    return i;
}
