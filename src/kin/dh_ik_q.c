/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_ik_q.c - numerical inverse kinematics in fixed point (integer only:
 * no float, no libm, no 64-bit division). The method of dh_ik.c
 * (Levenberg-Marquardt with the damping of Sugihara 2011, projected on the
 * joint box, deterministic restarts) on the fixed chain of dh_jacobian_q.
 *
 * Scales. Every length (Jacobian linear rows, position error, w_rot times
 * the angular rows and the rotation error) is in dh_qpos shifted right by
 * sp, the smallest shift that brings 2 L and w below 2^28, so that the
 * weighted Jacobian B (6 x n) has entries below 2^29 and the weighted
 * error es (clamped to 2^30) keeps every sum of products of the normal
 * equations H = B^T B + Lambda, g = B^T es in int64. Revolute columns are
 * per radian, prismatic ones per L (as dh_ik.c).
 *
 * Solve. H is equilibrated by powers of two, H' = D H D with D = diag(2^-c_j)
 * chosen so that H'_jj is in [1/4, 1) (Q2.30): then every |H'_jk| <= 1
 * (Cauchy-Schwarz), and the Cholesky factor of H' is bounded by 1 as well.
 * The factor is computed with one reciprocal square root per pivot (Newton,
 * dh_q_rsqrt29: no division); a pivot below 2^-20 is raised to it (the
 * modified Cholesky factorisation of Gill, Murray and Wright 1981, as the
 * float LDL^T). g' = D g, normalised to 20 bits, and the two triangular
 * solves in Q2.30 with saturation checks: a solve that overflows is
 * retried with more damping, as an overflowing float solve.
 *
 * Damping: mu = 2^m, m in [-10, 40], times 4 after a rejected step and
 * halved after an accepted one (dh_ik.c: 3 and 1/2).
 *
 * Stack: the vectors, matrices, the frame and the int64 state live in the
 * caller's workspace (int64 as two words); the blocks below are noinline
 * and called one after the other from dh_ik_q.
 */
#include "dhmath/kin.h"
#include "dhmath/frame.h"
#include "dhmath/trig.h"
#include "kin_impl.h"
#include "../internal/dh_qmath.h"

#define IKQ_POLISH_STEPS 0u     /* refinement steps after the tolerance is met */
#define IKQ_STALL_STEPS 4u      /* steps in a row with less than 1% progress: stalled */
#define IKQ_MU_MAX 40           /* mu = 2^m */
#define IKQ_MU_MIN (-10)
#define IKQ_MU_UP 2             /* mu times 4 after a rejected step */
#define IKQ_GBITS 20            /* bits of the normalised right-hand side */
#define IKQ_GBITS_DROP 8        /* fewer bits when the solve overflows (twice at most) */
#define IKQ_DMIN60 ((int64_t)1 << 40)   /* pivot floor, 2^-20 in Q60 */
#define IKQ_HOPELESS_RESTARTS 3u
#define IKQ_ID_BOTH (DH_ROBOT_BASE_ID_Q | DH_ROBOT_TOOL_ID_Q)
#define IKQ_ES_MAX ((int64_t)1 << 30)   /* clamp of the scaled error */
#define IKQ_B_MAX (((int32_t)1 << 29) - 1)   /* clamp of the weighted Jacobian */
#define IKQ_LAMBDA_MAX ((int64_t)1 << 61)
/* 180 / pi * 2^25 */
#define IKQ_R2D25 1922527338

/* Workspace layout (int32 words), n joints; slot s = 0, 1 (current / trial). */
#define OFF_J(n, s) ((s) * 6u * (n))                 /* 6n each: Jacobian, then B */
#define OFF_E(n, s) (12u * (n) + 6u * (s))           /* 6 each: scaled weighted error */
#define OFF_Q(n, s) (12u * (n) + 12u + (s) * (n))    /* n each: joint values */
#define OFF_QBEST(n) (14u * (n) + 12u)               /* n: best configuration */
#define OFF_DQ(n) (15u * (n) + 12u)                  /* n: step in joint units */
#define OFF_C(n) (16u * (n) + 12u)                   /* n: column exponents c_j */
#define OFF_Y(n) (17u * (n) + 12u)                   /* n: right-hand side, then solution */
#define OFF_IY(n) (18u * (n) + 12u)                  /* n: 1/sqrt(pivot) mantissa, Q3.29 */
#define OFF_IK(n) (19u * (n) + 12u)                  /* n: its shift */
#define OFF_F(n) (20u * (n) + 12u)                   /* 12: frame of the evaluation */
#define OFF_S(n) (20u * (n) + 24u)                   /* IKQ_S_COUNT scalars */
#define OFF_ST(n) (20u * (n) + 48u)                  /* 8: ikq_state */
#define OFF_G64(n) (20u * (n) + 56u)                 /* 2n: g, int64 */
#define OFF_D(n) (22u * (n) + 56u)                   /* 19: dh_kin_rot_scratch_q: dR, w, q */
#define OFF_R(n) (22u * (n) + 68u)                   /* 3: its w, orientation error, Q3.29 */
#define OFF_H(n) (22u * (n) + 75u)                   /* n*n: H', then its factor */
#define OFF_Q0(n) ((n) * (n) + 22u * (n) + 75u)      /* n: q0 */
/* The layout ends at DH_IK_WORK_Q(n) words (a quadratic in n: equal at three n, equal at every n),
 * and the rotation scratch at OFF_D fills its 19 words up to OFF_H. */
typedef char ikq_work_is_layout[(DH_IK_WORK_Q(1u) == OFF_Q0(1u) + 1u && DH_IK_WORK_Q(2u) == OFF_Q0(2u) + 2u &&
                                 DH_IK_WORK_Q(3u) == OFF_Q0(3u) + 3u) ? 1 : -1];
typedef char ikq_scratch_fits[(sizeof(dh_kin_rot_scratch_q) == (OFF_H(1u) - OFF_D(1u)) * sizeof(int32_t)) ? 1 : -1];

/* Scalar state slots (workspace words); int64 values take two. */
enum {
    S_E = 0, S_TE = 2, S_BE = 4, S_WBAR = 6, /* int64: E current, trial, best; damping bias */
    S_EP = 8, S_ER, S_TEP, S_TER, S_BEP, S_BER,
    S_MU, S_SP, S_L, S_W, S_LS, S_WS,  /* L, w and both shifted right by sp */
    IKQ_S_COUNT
};
typedef char ikq_state_fits[(IKQ_S_COUNT <= 24) ? 1 : -1];   /* OFF_S holds 24 words */

enum { K_NONE = 0, K_CONV, K_STALL, K_CUT };
enum { M_FIRST = 0, M_TRIAL, M_RESTART };
enum { EV_OK = 0, EV_FK, EV_RIGID };
enum { A_STEP = 0, A_OVER, A_RETRY, A_BREAK, A_FAIL };

/* Counters and flags of the solve: in the workspace (OFF_ST), not in
 * dh_ik_q's frame, which every block's stack adds to. */
typedef struct {
    uint32_t iter, stall, polish, restarts, rng;
    uint8_t cs, mode, conv, end, best_kind, hopeless;
} ikq_state;
typedef char ikq_st_fits[(sizeof(ikq_state) <= 8u * sizeof(int32_t)) ? 1 : -1];   /* OFF_ST: 8 words */

/* What the blocks share: four pointers in dh_ik_q's frame (which the
 * Jacobian pass and every block add to); n is r->n, the state and a copy
 * of q0 are in the workspace (IKQ_ST, OFF_Q0). */
typedef struct {
    const dh_robot *r;
    const dh_frame_q *target;
    const dh_ik_params_q *p;
    int32_t *w;             /* workspace */
} ikq_ctx;
#define IKQ_ST(c) ((ikq_state *)(void *)((c)->w + OFF_ST((c)->r->n)))

/* ---- small helpers ------------------------------------------------------- */

static int64_t ikq_get64(const int32_t *w, uint32_t k)
{
    const uint64_t u = ((uint64_t)(uint32_t)w[k + 1u] << 32) | (uint32_t)w[k];
    return (int64_t)u;
}

static void ikq_put64(int32_t *w, uint32_t k, int64_t v)
{
    const uint64_t u = (uint64_t)v;
    w[k] = (int32_t)(uint32_t)u;
    w[k + 1u] = (int32_t)(uint32_t)(u >> 32);
}

static uint64_t ikq_abs64(int64_t v) { return v < 0 ? 0u - (uint64_t)v : (uint64_t)v; }

/* round(x 2^-s) for any shift s (left shifts only where the result fits) */
static int64_t ikq_shift(int64_t x, int s)
{
    if (x == 0) return 0;
    if (s > 62) return (x < 0) ? -1 : 0;
    if (s > 0) return dh_q_rshr(x, (unsigned)s);
    return (int64_t)((uint64_t)x << (unsigned)(-s));
}

static int32_t ikq_clamp(const dh_joint *jt, int64_t v)
{
    if (jt->qmin_q <= jt->qmax_q) {
        if (v < jt->qmin_q) return jt->qmin_q;
        if (v > jt->qmax_q) return jt->qmax_q;
    }
    if (v > INT32_MAX) return INT32_MAX;
    if (v < INT32_MIN) return INT32_MIN;
    return (int32_t)v;
}

static int ikq_rot_mode(uint32_t mask) { return (mask & (DH_IK_FULL & ~DH_IK_POSITION)) != 0u; }

static uint32_t ikq_sat_add(uint32_t a, uint32_t b)
{
    return (a > 0x7FFFFFFFu - b) ? 0x7FFFFFFFu : a + b;
}

/* |a - b| over the masked components (int32 positions), saturated at
 * INT32_MAX; b may be NULL (|a|). The halved differences fit 32 bits. */
static DH_NOINLINE uint32_t ikq_dist(const int32_t *a, const int32_t *b, uint32_t mask)
{
    uint64_t s = 0u;
    uint32_t k, h;
    for (k = 0; k < 3u; k++) {
        int64_t d;
        uint64_t m;
        if ((mask & (1u << k)) == 0u) continue;
        d = (int64_t)a[k] - (b != NULL ? b[k] : 0);
        m = ikq_abs64(d) >> 1;
        if (m >= ((uint64_t)1 << 31)) return 0x7FFFFFFFu;
        s += m * m;
    }
    h = dh_q_sqrt_u64(s);
    return (h >= 0x40000000u) ? 0x7FFFFFFFu : 2u * h;
}

/* ---- robot scales -------------------------------------------------------- */

/* |tool_q p| (dh_qpos, saturated). */
static uint32_t ikq_tool_len(const dh_robot *r)
{
    return ikq_dist(r->tool_q.p, NULL, 7u);
}

static DH_NOINLINE uint32_t ikq_length(const dh_robot *r)
{
    uint32_t L = 0u, i;
    for (i = 0; i < r->n && i < (uint32_t)DH_MAX_JOINTS; i++) {
        const dh_joint *jt = &r->joint[i];
        L = ikq_sat_add(L, dh_q_abs_u32(jt->a_q));
        L = ikq_sat_add(L, dh_q_abs_u32(jt->d_q));
        if (jt->type == DH_JOINT_PRISMATIC && jt->qmin_q <= jt->qmax_q) {
            const uint32_t lo = dh_q_abs_u32(jt->qmin_q), hi = dh_q_abs_u32(jt->qmax_q);
            L = ikq_sat_add(L, lo > hi ? lo : hi);
        }
    }
    L = ikq_sat_add(L, ikq_tool_len(r));
    return (L == 0u) ? (uint32_t)DH_QPOS_ONE : L;
}

void dh_ik_params_default_q(const dh_robot *r, dh_ik_params_q *p)
{
    uint32_t L;
    DH_ASSERT(r != NULL);
    DH_ASSERT(p != NULL);
    L = ikq_length(r);
    p->max_iter = 500u;
    p->mask = DH_IK_FULL;
    p->tol_pos = (int32_t)((L >> 20) > 0u ? (L >> 20) : 1u);
    p->tol_rot = 10737;
    p->w_rot = (int32_t)((L >> 2) > 0u ? (L >> 2) : 1u);
    p->restarts = 50u;
}

/* 1 when det R > 0 (R = F's rotation, Q2.30). */
static DH_NOINLINE int ikq_det_pos(const dh_frame_q *F)
{
    int32_t x[3];
    int64_t det = 0;
    uint32_t k;
    int ovf = 0;
    for (k = 0; k < 3u; k++) {
        const uint32_t a = (k + 1u) % 3u, b = (k + 2u) % 3u;
        x[k] = dh_q_rnd30(dh_q_mul64(F->r[1][a], F->r[2][b]) - dh_q_mul64(F->r[1][b], F->r[2][a]), &ovf);
    }
    for (k = 0; k < 3u; k++) det = dh_q_mla64(det, F->r[0][k], x[k]);
    return det > 0;
}

/* 1 when F's rotation is one within DH_ROT_ERROR_TOL_Q with det > 0
 * (inlined into dh_ik_q: the public ortho check's stack adds to its frame
 * only). */
DH_INLINE int ikq_rot_ok(const dh_frame_q *F)
{
    return dh_frame_ortho_error_q(F) <= DH_ROT_ERROR_TOL_Q && ikq_det_pos(F);
}

static DH_NOINLINE dh_status ikq_args(const dh_robot *r, const dh_ik_params_q *p, const int32_t *work,
                                      size_t work_len)
{
    uint32_t i, n = r->n;
    if (n == 0u || n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    if (work == NULL || work_len < (size_t)DH_IK_WORK_Q(n)) return DH_ERR_ARG;
    if (p->max_iter == 0u || p->mask == 0u || (p->mask & ~(uint32_t)DH_IK_FULL) != 0u) return DH_ERR_ARG;
    if (p->tol_pos < 0 || p->tol_rot < 0 || p->w_rot <= 0) return DH_ERR_ARG;
    if ((r->flags & DH_ROBOT_HAS_Q) == 0u) return DH_ERR_UNAVAILABLE;
    if (r->conv != DH_CONV_STANDARD && r->conv != DH_CONV_MODIFIED) return DH_ERR_ARG;
    for (i = 0; i < n; i++)
        if (r->joint[i].type != DH_JOINT_REVOLUTE && r->joint[i].type != DH_JOINT_PRISMATIC) return DH_ERR_ARG;
    return DH_OK;     /* the caller checks the target rotation (stack depth) */
}

/* L, the shift sp, w = min(w_rot, L) and the damping bias into the state. */
static DH_NOINLINE void ikq_scales(const ikq_ctx *c)
{
    int32_t *S = c->w + OFF_S(c->r->n);
    const uint32_t L = ikq_length(c->r);
    const uint32_t w = ((uint32_t)c->p->w_rot < L) ? (uint32_t)c->p->w_rot : L;
    const uint32_t big = (L > 0x3FFFFFFFu) ? 0xFFFFFFFFu : 2u * L;
    int sp = (int)dh_q_bitlen64(big > w ? big : w) - 28;
    uint32_t Ls;
    if (sp < 0) sp = 0;
    Ls = L >> (unsigned)sp;
    S[S_L] = (int32_t)L;
    S[S_W] = (int32_t)w;
    S[S_LS] = (int32_t)Ls;
    S[S_WS] = (int32_t)(w >> (unsigned)sp);
    S[S_SP] = sp;
    S[S_MU] = 0;
    ikq_put64(S, S_WBAR, (((int64_t)Ls * (int64_t)Ls) >> 23) + 1);
}

/* max(||B||_1, ||B||_inf) of the base rotation in Q2.28 (>= ||B||_2). */
static DH_NOINLINE uint32_t ikq_base_gain(const dh_robot *r)
{
    uint32_t i, k, gmax = 0u;
    for (i = 0; i < 3u; i++) {
        uint32_t rs = 0u, cs = 0u;
        for (k = 0; k < 3u; k++) {
            rs += dh_q_abs_u32(r->base_q.r[k][i]) >> 2;
            cs += dh_q_abs_u32(r->base_q.r[i][k]) >> 2;
        }
        if (rs > gmax) gmax = rs;
        if (cs > gmax) gmax = cs;
    }
    return gmax;
}

/* Upper bound of |p_end - p_base| (dh_qpos) within the limits, -1 when
 * unbounded (a prismatic joint without limits). */
static DH_NOINLINE int64_t ikq_reach(const dh_robot *r, uint32_t tool_len)
{
    int64_t R = 0;
    uint32_t i, gain;
    for (i = 0; i < r->n; i++) {
        const dh_joint *jt = &r->joint[i];
        R += (int64_t)dh_q_abs_u32(jt->a_q);
        if (jt->type == DH_JOINT_REVOLUTE) {
            R += (int64_t)dh_q_abs_u32(jt->d_q);
        } else {
            int64_t lo, hi;
            if (jt->qmin_q > jt->qmax_q) return -1;
            lo = (int64_t)jt->qmin_q + jt->d_q;
            hi = (int64_t)jt->qmax_q + jt->d_q;
            lo = lo < 0 ? -lo : lo;
            hi = hi < 0 ? -hi : hi;
            R += (lo > hi) ? lo : hi;
        }
    }
    R += (int64_t)tool_len;
    /* R < 2^37, gain < 2^31 (Q2.28): R gain / 2^28 plus 1e-4 R, the
     * product exact below R = 2^32 and of R / 64 above (no wrap; the lost
     * low bits of R are far below the slack there) */
    gain = ikq_base_gain(r);
    if (R < ((int64_t)1 << 32)) return (int64_t)(((uint64_t)R * gain) >> 28) + (R >> 13) + 1;
    return (int64_t)((((uint64_t)R >> 6) * gain) >> 22) + (R >> 13) + 1;
}

static DH_NOINLINE int ikq_hopeless(const ikq_ctx *c, int64_t R)
{
    if (R < 0) return 0;
    return (int64_t)ikq_dist(c->target->p, c->r->base_q.p, c->p->mask) > R + c->p->tol_pos;
}

static DH_NOINLINE void ikq_init(ikq_ctx *c)
{
    uint32_t i;
    IKQ_ST(c)->iter = 0u;
    IKQ_ST(c)->stall = 0u;
    IKQ_ST(c)->polish = 0u;
    IKQ_ST(c)->rng = 0x2545F491u;
    IKQ_ST(c)->cs = 0u;
    IKQ_ST(c)->mode = (uint8_t)M_FIRST;
    IKQ_ST(c)->conv = 0u;
    IKQ_ST(c)->end = 0u;
    IKQ_ST(c)->best_kind = K_NONE;
    IKQ_ST(c)->hopeless = 0u;
    IKQ_ST(c)->restarts = c->p->restarts;
    for (i = 0; i < c->r->n; i++) c->w[OFF_Q(c->r->n, 1u) + i] = ikq_clamp(&c->r->joint[i], c->w[OFF_Q0(c->r->n) + i]);
}

/* ---- evaluation ------------------------------------------------------------ */

/* Position part of the trial slot's error: es[0..2] and S_TEP. */
static DH_NOINLINE void ikq_pos_err(const ikq_ctx *c)
{
    const uint32_t n = c->r->n, mask = c->p->mask;
    const int32_t *Fp = c->w + OFF_F(n) + 9u;   /* dh_frame_q p */
    int32_t *es = c->w + OFF_E(n, IKQ_ST(c)->cs ^ 1u), *S = c->w + OFF_S(n);
    const int sp = S[S_SP];
    uint32_t k;
    for (k = 0; k < 3u; k++) {
        int64_t v = 0;
        if ((mask & (1u << k)) != 0u) {
            v = (int64_t)c->target->p[k] - Fp[k];
            if (sp > 0) v = dh_q_rshr(v, (unsigned)sp);
            if (v > IKQ_ES_MAX) v = IKQ_ES_MAX;
            if (v < -IKQ_ES_MAX) v = -IKQ_ES_MAX;
        }
        es[k] = (int32_t)v;
    }
}

/* Rotation part (w at OFF_R, or 0 when not driven): es[3..5],
 * S_TER, and E of the whole error into S_TE. */
static DH_NOINLINE void ikq_rot_err(const ikq_ctx *c)
{
    const uint32_t n = c->r->n, mask = c->p->mask;
    const int32_t *wr = c->w + OFF_R(n);
    int32_t *es = c->w + OFF_E(n, IKQ_ST(c)->cs ^ 1u), *S = c->w + OFF_S(n);
    uint64_t r2 = 0u;
    int64_t E = 0;
    uint32_t k, h;
    for (k = 3u; k < 6u; k++) {
        int64_t v = 0;
        if ((mask & (1u << k)) != 0u) {
            v = dh_q_rshr(dh_q_mul64(wr[k - 3u], S[S_WS]), 29u);
            r2 += (uint64_t)dh_q_mul64(wr[k - 3u], wr[k - 3u]);
            if (v > IKQ_ES_MAX) v = IKQ_ES_MAX;
            if (v < -IKQ_ES_MAX) v = -IKQ_ES_MAX;
        }
        es[k] = (int32_t)v;
    }
    for (k = 0; k < 6u; k++) E = dh_q_mla64(E, es[k], es[k]);
    ikq_put64(S, S_TE, E >> 1);
    h = dh_q_sqrt_u64(r2);   /* Q3.29 */
    S[S_TER] = (h >= 0x40000000u) ? INT32_MAX : (int32_t)(2u * h);
}

/* B = weighted Jacobian of the current point into the (free) trial slot:
 * linear rows J >> sp (revolute) or z (L >> sp) (prismatic), angular rows
 * z (w >> sp) (revolute) or 0, masked rows 0. */
static DH_NOINLINE void ikq_weigh(const ikq_ctx *c)
{
    const uint32_t n = c->r->n, mask = c->p->mask;
    const int32_t *J = c->w + OFF_J(n, IKQ_ST(c)->cs), *S = c->w + OFF_S(n);
    int32_t *B = c->w + OFF_J(n, IKQ_ST(c)->cs ^ 1u);
    const int32_t sp = S[S_SP], Ls = S[S_LS], Ws = S[S_WS];
    uint32_t i, k;
    for (k = 0; k < 6u; k++) {
        const int on = (mask & (1u << k)) != 0u;
        for (i = 0; i < n; i++) {
            const int32_t x = J[k * n + i];
            int32_t v = 0;
            if (on) {
                if (c->r->joint[i].type == DH_JOINT_PRISMATIC)
                    v = (k < 3u) ? (int32_t)dh_q_rshr(dh_q_mul64(x, Ls), 30u) : 0;
                else if (k >= 3u)
                    v = (int32_t)dh_q_rshr(dh_q_mul64(x, Ws), 30u);
                else
                    v = (sp == 0) ? x : (((x >> (sp - 1)) + 1) >> 1);
            }
            if (v > IKQ_B_MAX) v = IKQ_B_MAX;     /* only for a base that scales lengths */
            if (v < -IKQ_B_MAX) v = -IKQ_B_MAX;
            B[k * n + i] = v;
        }
    }
}

/* (B^T B)_ij, exact (|B| < 2^29: the sum is below 2^61). */
DH_INLINE int64_t ikq_dot6(const int32_t *B, uint32_t n, uint32_t i, uint32_t j)
{
    int64_t h = 0;
    uint32_t k;
    for (k = 0; k < 6u; k++) h = dh_q_mla64(h, B[k * n + i], B[k * n + j]);
    return h;
}

/* Column j of the normal equations: H_jj = (B^T B)_jj + Lambda_jj into
 * D64, g_j = (B^T es)_j into G64, the exponent c_j and H'_jj = H_jj 2^-2c_j
 * (Q2.30, in [1/4, 1)). Lambda_jj = mu min(E, (B^T B)_jj) + wbar
 * (dh_ik.c). Returns the bit length of |g_j| 2^-c_j (-64 for g_j = 0). */
static DH_NOINLINE int ikq_diag(const ikq_ctx *c, uint32_t j)
{
    const uint32_t n = c->r->n;
    int32_t *w = c->w;
    const int32_t *B = w + OFF_J(n, IKQ_ST(c)->cs ^ 1u), *es = w + OFF_E(n, IKQ_ST(c)->cs), *S = w + OFF_S(n);
    const int mu = S[S_MU];
    int64_t h = 0, g = 0, lam, E;
    uint32_t k;
    int cj;
    for (k = 0; k < 6u; k++) g = dh_q_mla64(g, B[k * n + j], es[k]);
    h = ikq_dot6(B, n, j, j);
    E = ikq_get64(S, S_E);
    lam = (E < h) ? E : h;
    if (mu >= 0) lam = (lam > (IKQ_LAMBDA_MAX >> mu)) ? IKQ_LAMBDA_MAX : lam << mu;
    else lam >>= -mu;
    h += lam + ikq_get64(S, S_WBAR);
    cj = ((int)dh_q_bitlen64((uint64_t)h) - 29) >> 1;
    w[OFF_C(n) + j] = cj;
    ikq_put64(w, OFF_G64(n) + 2u * j, g);
    w[OFF_H(n) + j * n + j] = (int32_t)ikq_shift(h, 2 * cj);
    return (g != 0) ? (int)dh_q_bitlen64(ikq_abs64(g)) - cj : -64;
}

/* H'_ij = (B^T B)_ij 2^-(c_i + c_j) for i > j, both free (else 0). */
static DH_NOINLINE void ikq_offdiag(const ikq_ctx *c, uint32_t free_bits)
{
    const uint32_t n = c->r->n;
    const int32_t *B = c->w + OFF_J(n, IKQ_ST(c)->cs ^ 1u), *C = c->w + OFF_C(n);
    int32_t *H = c->w + OFF_H(n);
    uint32_t i, j;
    for (i = 1u; i < n; i++)
        for (j = 0; j < i; j++) {
            int64_t h = 0;
            if ((((free_bits >> i) & (free_bits >> j)) & 1u) != 0u) h = ikq_shift(ikq_dot6(B, n, i, j), C[i] + C[j]);
            H[i * n + j] = (int32_t)h;
        }
}

/* H' over the free joints (the others: identity row and column, g = 0);
 * returns the largest bit length of D g. */
static DH_NOINLINE int ikq_normal(const ikq_ctx *c, uint32_t free_bits)
{
    const uint32_t n = c->r->n;
    uint32_t j;
    int eg = -64;
    for (j = 0; j < n; j++) {
        if (((free_bits >> j) & 1u) != 0u) {
            const int b = ikq_diag(c, j);
            if (b > eg) eg = b;
        } else {
            c->w[OFF_C(n) + j] = 0;
            ikq_put64(c->w, OFF_G64(n) + 2u * j, 0);
            c->w[OFF_H(n) + j * n + j] = DH_Q_ONE30;
        }
    }
    ikq_offdiag(c, free_bits);
    return eg;
}

/* Y = g' = D g 2^-eg (frozen joints: g = 0). */
static DH_NOINLINE void ikq_rhs(const ikq_ctx *c, int eg)
{
    const uint32_t n = c->r->n;
    int32_t *Y = c->w + OFF_Y(n);
    const int32_t *C = c->w + OFF_C(n);
    uint32_t j;
    for (j = 0; j < n; j++) Y[j] = (int32_t)ikq_shift(ikq_get64(c->w, OFF_G64(n) + 2u * j), C[j] + eg);
}

/* x = s30 / sqrt(pivot j), saturated: 1 when it does not fit int32. */
static int32_t ikq_div(const int32_t *w, uint32_t n, uint32_t j, int64_t s60, int *bad)
{
    const int64_t s = dh_q_rshr(s60, 30u);
    int64_t x;
    if (s > INT32_MAX || s < -INT32_MAX) {
        *bad = 1;
        return 0;
    }
    x = dh_q_rshr(dh_q_mul64((int32_t)s, w[OFF_IY(n) + j]), (unsigned)w[OFF_IK(n) + j]);
    if (x > INT32_MAX || x < -INT32_MAX) {
        *bad = 1;
        return 0;
    }
    return (int32_t)x;
}

/* Column j of L (H' = L L^T in place, lower triangle): the pivot, raised
 * to 2^-20 when below, its reciprocal square root, then L_ij, i > j. */
static DH_NOINLINE int ikq_chol_col(const ikq_ctx *c, uint32_t j)
{
    const uint32_t n = c->r->n;
    int32_t *w = c->w, *H = w + OFF_H(n);
    int64_t d = (int64_t)((uint64_t)(int64_t)H[j * n + j] << 30);
    uint32_t i, k;
    int32_t m;
    int t, bad = 0;
    for (k = 0; k < j; k++) d -= dh_q_mul64(H[j * n + k], H[j * n + k]);
    if (d < IKQ_DMIN60) d = IKQ_DMIN60;
    dh_q_norm_even((uint64_t)d, &m, &t);
    w[OFF_IY(n) + j] = dh_q_rsqrt29(m, 2u);
    w[OFF_IK(n) + j] = 14 + t / 2;
    for (i = j + 1u; i < n; i++) {
        int64_t s = (int64_t)((uint64_t)(int64_t)H[i * n + j] << 30);
        for (k = 0; k < j; k++) s -= dh_q_mul64(H[i * n + k], H[j * n + k]);
        H[i * n + j] = ikq_div(w, n, j, s, &bad);
    }
    return bad;
}

/* L z = g', L^T y = z in Y; -1 when a value does not fit. */
static DH_NOINLINE int ikq_solve(const ikq_ctx *c)
{
    const uint32_t n = c->r->n;
    int32_t *w = c->w, *H = w + OFF_H(n), *Y = w + OFF_Y(n);
    uint32_t i, k;
    int bad = 0;
    for (i = 0; i < n; i++) {
        int64_t s = (int64_t)((uint64_t)(int64_t)Y[i] << 30);
        for (k = 0; k < i; k++) s -= dh_q_mul64(H[i * n + k], Y[k]);
        Y[i] = ikq_div(w, n, i, s, &bad);
    }
    for (i = n; i-- > 0u;) {
        int64_t s = (int64_t)((uint64_t)(int64_t)Y[i] << 30);
        for (k = i + 1u; k < n; k++) s -= dh_q_mul64(H[k * n + i], Y[k]);
        Y[i] = ikq_div(w, n, i, s, &bad);
    }
    return bad ? -1 : 0;
}

/* Joint step from the solution: revolute Y 2^(eg - c - 30) rad in Q16.16
 * degrees, prismatic that many L in dh_qpos; saturated. */
static DH_NOINLINE void ikq_step(const ikq_ctx *c, int eg)
{
    const uint32_t n = c->r->n;
    const int32_t *w = c->w, *Y = w + OFF_Y(n), *C = w + OFF_C(n);
    int32_t *dq = c->w + OFF_DQ(n);
    uint32_t i;
    for (i = 0; i < n; i++) {
        const int pr = c->r->joint[i].type == DH_JOINT_PRISMATIC;
        const int64_t prod = dh_q_mul64(Y[i], pr ? w[OFF_S(n) + S_L] : IKQ_R2D25);
        const int sh = (pr ? 30 : 39) + C[i] - eg;
        int64_t v;
        if (prod == 0) {
            v = 0;
        } else if (sh <= 0) {
            v = (prod < 0) ? INT32_MIN : INT32_MAX;
        } else {
            v = dh_q_rshr(prod, (unsigned)(sh > 62 ? 62 : sh));
            if (v > INT32_MAX) v = INT32_MAX;
            if (v < INT32_MIN) v = INT32_MIN;
        }
        dq[i] = (int32_t)v;
    }
}

/* Free joints on a bound whose step points outward (bits). */
static DH_NOINLINE uint32_t ikq_freeze(const ikq_ctx *c, uint32_t free_bits)
{
    const uint32_t n = c->r->n;
    const int32_t *qa = c->w + OFF_Q(n, IKQ_ST(c)->cs), *dq = c->w + OFF_DQ(n);
    uint32_t i, frozen = 0u;
    for (i = 0; i < n; i++) {
        const dh_joint *jt = &c->r->joint[i];
        if (((free_bits >> i) & 1u) == 0u || jt->qmin_q > jt->qmax_q) continue;
        if ((qa[i] <= jt->qmin_q && dq[i] < 0) || (qa[i] >= jt->qmax_q && dq[i] > 0)) frozen |= 1u << i;
    }
    return frozen;
}

static DH_NOINLINE int ikq_apply(const ikq_ctx *c, uint32_t free_bits)
{
    const uint32_t n = c->r->n;
    const int32_t *qa = c->w + OFF_Q(n, IKQ_ST(c)->cs), *dq = c->w + OFF_DQ(n);
    int32_t *qb = c->w + OFF_Q(n, IKQ_ST(c)->cs ^ 1u);
    uint32_t i;
    int moved = 0;
    for (i = 0; i < n; i++) {
        const int32_t d = ((free_bits >> i) & 1u) ? dq[i] : 0;
        qb[i] = ikq_clamp(&c->r->joint[i], (int64_t)qa[i] + d);
        if (qb[i] != qa[i]) moved = 1;
    }
    return moved;
}

static DH_NOINLINE void ikq_sample(ikq_ctx *c)
{
    const int32_t L = c->w[OFF_S(c->r->n) + S_L];
    int32_t *qo = c->w + OFF_Q(c->r->n, IKQ_ST(c)->cs ^ 1u);
    uint32_t i;
    for (i = 0; i < c->r->n; i++) {
        const dh_joint *jt = &c->r->joint[i];
        uint32_t x = IKQ_ST(c)->rng;
        int32_t u;
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        IKQ_ST(c)->rng = x;
        u = (int32_t)(x >> 1);      /* [0, 2^31) */
        if (jt->qmin_q <= jt->qmax_q) {
            const uint32_t range = (uint32_t)jt->qmax_q - (uint32_t)jt->qmin_q;
            qo[i] = ikq_clamp(jt, (int64_t)jt->qmin_q + (dh_q_mul64((int32_t)(range >> 1), u) >> 30));
        } else if (jt->type == DH_JOINT_REVOLUTE) {
            qo[i] = ikq_clamp(jt, (int64_t)c->w[OFF_Q0(c->r->n) + i] + (dh_q_mul64(u, 360 * 65536) >> 31) - 180 * 65536);
        } else {
            qo[i] = ikq_clamp(jt, (int64_t)c->w[OFF_Q0(c->r->n) + i] + (dh_q_mul64(u, L) >> 30) - L);
        }
    }
    IKQ_ST(c)->mode = (uint8_t)M_RESTART;
}

/* ---- acceptance (dh_ik.c) ------------------------------------------------- */

static int ikq_met(const int32_t *S, const dh_ik_params_q *p)
{
    return S[S_EP] <= p->tol_pos && S[S_ER] <= p->tol_rot;
}

/* 0 reject, 1 accept with progress, 2 accept with less than 1% (1/128). */
static int ikq_better(const ikq_ctx *c, const int32_t *S)
{
    const dh_ik_params_q *p = c->p;
    const int64_t E = ikq_get64(S, S_E), TE = ikq_get64(S, S_TE);
    int64_t a, b;
    if (IKQ_ST(c)->conv) return (TE < E && S[S_TEP] <= p->tol_pos && S[S_TER] <= p->tol_rot) ? 1 : 0;
    if (TE < E) {
        a = TE;
        b = E;
    } else if (S[S_ER] <= p->tol_rot && S[S_TER] <= p->tol_rot && S[S_TEP] < S[S_EP]) {
        a = S[S_TEP];
        b = S[S_EP];
    } else if (S[S_EP] <= p->tol_pos && S[S_TEP] <= p->tol_pos && S[S_TER] < S[S_ER]) {
        a = S[S_TER];
        b = S[S_ER];
    } else {
        return 0;
    }
    return (a < b - (b >> 7)) ? 1 : 2;
}

static void ikq_take(ikq_ctx *c, int32_t *S)
{
    IKQ_ST(c)->cs = (uint8_t)(IKQ_ST(c)->cs ^ 1u);
    ikq_put64(S, S_E, ikq_get64(S, S_TE));
    S[S_EP] = S[S_TEP];
    S[S_ER] = S[S_TER];
}

static DH_NOINLINE unsigned ikq_update(ikq_ctx *c, int ev)
{
    const dh_ik_params_q *p = c->p;
    int32_t *S = c->w + OFF_S(c->r->n);
    const int acc = (IKQ_ST(c)->mode == M_TRIAL && ev == EV_OK) ? ikq_better(c, S) : 0;
    if (IKQ_ST(c)->mode == M_FIRST) {
        if (ev != EV_OK) return A_FAIL;
    } else {
        IKQ_ST(c)->iter++;
    }
    IKQ_ST(c)->end = 0u;
    if (IKQ_ST(c)->mode != M_TRIAL) {
        if (ev != EV_OK) {
            if (IKQ_ST(c)->restarts > 0u && IKQ_ST(c)->iter < p->max_iter) {
                IKQ_ST(c)->restarts--;
                return A_RETRY;
            }
            return A_BREAK;
        }
        ikq_take(c, S);
        S[S_MU] = 0;
        IKQ_ST(c)->stall = 0u;
        IKQ_ST(c)->polish = 0u;
        IKQ_ST(c)->conv = (uint8_t)ikq_met(S, p);
    } else if (acc != 0) {
        IKQ_ST(c)->stall = (acc == 1) ? 0u : IKQ_ST(c)->stall + 1u;
        ikq_take(c, S);
        if (IKQ_ST(c)->conv) IKQ_ST(c)->polish++;
        if (S[S_MU] > IKQ_MU_MIN) S[S_MU]--;
        if (!IKQ_ST(c)->conv && ikq_met(S, p)) {
            IKQ_ST(c)->conv = 1u;
            S[S_MU] = IKQ_MU_MIN;
        }
    } else {
        IKQ_ST(c)->stall++;
        S[S_MU] += IKQ_MU_UP;
        if (IKQ_ST(c)->conv) IKQ_ST(c)->polish = IKQ_POLISH_STEPS;
    }
    if (IKQ_ST(c)->mode == M_TRIAL && !IKQ_ST(c)->conv && (IKQ_ST(c)->stall >= IKQ_STALL_STEPS || S[S_MU] > IKQ_MU_MAX))
        IKQ_ST(c)->end = (uint8_t)K_STALL;
    IKQ_ST(c)->mode = (uint8_t)M_TRIAL;
    if (IKQ_ST(c)->end == 0u && !(IKQ_ST(c)->conv && IKQ_ST(c)->polish + 1u > IKQ_POLISH_STEPS) && IKQ_ST(c)->iter < p->max_iter) return A_STEP;
    return A_OVER;
}

static DH_NOINLINE int ikq_damp(ikq_ctx *c)
{
    int32_t *mu = c->w + OFF_S(c->r->n) + S_MU;
    IKQ_ST(c)->stall++;
    *mu += IKQ_MU_UP;
    return !IKQ_ST(c)->conv && IKQ_ST(c)->stall < IKQ_STALL_STEPS && *mu <= IKQ_MU_MAX;
}

static DH_NOINLINE int ikq_record(ikq_ctx *c)
{
    int32_t *S = c->w + OFF_S(c->r->n);
    const unsigned kind = IKQ_ST(c)->conv ? K_CONV : (IKQ_ST(c)->end != 0u ? IKQ_ST(c)->end : K_CUT);
    uint32_t i;
    if (IKQ_ST(c)->best_kind == K_NONE || (kind == K_CONV && IKQ_ST(c)->best_kind != K_CONV) ||
        ((kind == K_CONV) == (IKQ_ST(c)->best_kind == K_CONV) && ikq_get64(S, S_E) < ikq_get64(S, S_BE))) {
        IKQ_ST(c)->best_kind = (uint8_t)kind;
        ikq_put64(S, S_BE, ikq_get64(S, S_E));
        S[S_BEP] = S[S_EP];
        S[S_BER] = S[S_ER];
        for (i = 0; i < c->r->n; i++) c->w[OFF_QBEST(c->r->n) + i] = c->w[OFF_Q(c->r->n, IKQ_ST(c)->cs) + i];
    }
    if (IKQ_ST(c)->conv || IKQ_ST(c)->end == 0u || IKQ_ST(c)->restarts == 0u || IKQ_ST(c)->iter >= c->p->max_iter) return 1;
    IKQ_ST(c)->restarts--;
    return 0;
}

static DH_NOINLINE dh_status ikq_finish(const ikq_ctx *c, int32_t *q, dh_ik_result_q *res)
{
    const int32_t *S = c->w + OFF_S(c->r->n);
    uint32_t i;
    for (i = 0; i < c->r->n; i++) q[i] = c->w[OFF_QBEST(c->r->n) + i];
    res->iterations = IKQ_ST(c)->iter;
    res->err_pos = S[S_BEP];
    res->err_rot = S[S_BER];
    if (IKQ_ST(c)->best_kind == K_CONV) return DH_OK;
    if (IKQ_ST(c)->hopeless || IKQ_ST(c)->best_kind == K_STALL) return DH_ERR_UNREACHABLE;
    return DH_ERR_NO_CONVERGENCE;
}

/* Errors of the trial slot from its frame (blocks in a row; the Jacobian
 * pass and the start's rotation check are dh_ik_q's, one frame less on the
 * stack). */
static DH_NOINLINE int ikq_eval(const ikq_ctx *c)
{
    const uint32_t n = c->r->n;
    ikq_pos_err(c);
    c->w[OFF_S(n) + S_TEP] = (int32_t)ikq_dist(c->target->p, c->w + OFF_F(n) + 9u, c->p->mask);
    if (ikq_rot_mode(c->p->mask))   /* w = a(Rt R^T), dh_rot_error_q's core */
        dh_kin_rot_error_q_(c->target, (const dh_frame_q *)(const void *)(c->w + OFF_F(n)),
                            (dh_kin_rot_scratch_q *)(void *)(c->w + OFF_D(n)));
    else
        c->w[OFF_R(n)] = c->w[OFF_R(n) + 1u] = c->w[OFF_R(n) + 2u] = 0;
    ikq_rot_err(c);
    return EV_OK;
}

/* Projected step: at most n + 1 solves; a solve that overflows is repeated
 * with more damping. 1 when a trial point was made. */
static DH_NOINLINE int ikq_make_step(ikq_ctx *c)
{
    const uint32_t n = c->r->n;
    int k = 0, again = 1;
    ikq_weigh(c);
    while (again != 0) {
        uint32_t free_bits = (1u << n) - 1u, pass, frozen = 1u;
        k = 0;
        for (pass = 0; (pass <= n) && (frozen != 0u) && (k == 0); pass++) {
            int eg = ikq_normal(c, free_bits) - IKQ_GBITS, s = -1, tries;
            int bad = 0;
            uint32_t j;
            for (j = 0; j < n; j++) bad |= ikq_chol_col(c, j);
            if (bad == 0)
                for (tries = 0; tries < 3 && s != 0; tries++, eg += IKQ_GBITS_DROP) {
                    ikq_rhs(c, eg);
                    s = ikq_solve(c);
                }
            if (s != 0) {
                k = -1;
            } else {
                ikq_step(c, eg - IKQ_GBITS_DROP);
                frozen = ikq_freeze(c, free_bits);
                free_bits &= ~frozen;
            }
        }
        if (k == 0) k = ikq_apply(c, free_bits);
        again = (k < 0) ? ikq_damp(c) : 0;
    }
    return k > 0;
}

dh_status dh_ik_q(const dh_robot *r, const dh_frame_q *target, const int32_t *q0, const dh_ik_params_q *p,
                  int32_t *work, size_t work_len, int32_t *q, dh_ik_result_q *res)
{
    ikq_ctx cx, *c = &cx;
    dh_status st;
    uint32_t i;

    DH_ASSERT(r != NULL);
    DH_ASSERT(target != NULL);
    DH_ASSERT(q0 != NULL);
    DH_ASSERT(q != NULL);
    DH_ASSERT(p != NULL);
    DH_ASSERT(res != NULL);

    st = ikq_args(r, p, work, work_len);
    if (st != DH_OK) return st;
    if (ikq_rot_mode(p->mask) && !ikq_rot_ok(target)) return DH_ERR_NOT_RIGID;
    c->r = r;
    c->target = target;
    c->p = p;
    c->w = work;
    for (i = 0; i < r->n; i++) work[OFF_Q0(r->n) + i] = q0[i];
    ikq_init(c);
    ikq_scales(c);
    if (ikq_hopeless(c, ikq_reach(r, ikq_tool_len(r)))) {
        IKQ_ST(c)->hopeless = 1u;
        if (IKQ_ST(c)->restarts > IKQ_HOPELESS_RESTARTS) IKQ_ST(c)->restarts = IKQ_HOPELESS_RESTARTS;
    }
    for (;;) {
        const uint32_t t = IKQ_ST(c)->cs ^ 1u;
        dh_frame_q *F = (dh_frame_q *)(void *)(work + OFF_F(c->r->n));
        int ev = EV_FK;
        unsigned act;
        if (dh_kin_jac_q_(r, work + OFF_Q(c->r->n, t), work + OFF_J(c->r->n, t), F) == 0) {
            /* a chain of DH links is a rotation: only a base or tool can make it none */
            if (IKQ_ST(c)->mode == M_FIRST && ikq_rot_mode(p->mask) && (r->flags & IKQ_ID_BOTH) != IKQ_ID_BOTH &&
                !ikq_rot_ok(F))
                ev = EV_RIGID;
            else
                ev = ikq_eval(c);
        }
        act = ikq_update(c, ev);
        if (act == A_FAIL) return (ev == EV_RIGID) ? DH_ERR_NOT_RIGID : DH_ERR_OVERFLOW;
        if (act == A_RETRY) {
            ikq_sample(c);
            continue;
        }
        if (act == A_STEP) {
            if (ikq_make_step(c)) continue;
            IKQ_ST(c)->end = (uint8_t)K_STALL;
        }
        if (act == A_BREAK || ikq_record(c)) break;
        ikq_sample(c);
    }
    return ikq_finish(c, q, res);
}
