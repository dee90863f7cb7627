/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_ik.c - numerical inverse kinematics in float: Levenberg-Marquardt with
 * the damping of Sugihara 2011, projected on the joint box, with
 * deterministic restarts (method: docs/design.md, "Kinematics").
 *
 * Stack (<= 256 B per public function with callees and libgcc, M0+ and
 * M4F): every vector and matrix, the running frame of the Jacobian pass,
 * dR and the float state live in the caller's workspace; dh_ik_f32 calls
 * shallow noinline blocks one after the other instead of nesting the public
 * Jacobian and pose-error functions, so the frames do not add up.
 */
#include "dhmath/kin.h"
#include "dhmath/trig.h"
#include "kin_impl.h"
#include "../internal/dh_mathf.h"
#include "../internal/dh_floatops.h"

#include <float.h>
#include <math.h>

#define IK_POLISH_STEPS 3u      /* refinement steps after the tolerance is met */
#define IK_STALL_STEPS 4u       /* steps in a row with less than 1% progress: stalled */
#define IK_MU_MAX 1e12f
#define IK_MU_MIN 1e-3f         /* lowest multiplier of E in the damping */
#define IK_MU_UP 3.0f           /* damping factor after a rejected step */
#define IK_MU_DOWN 0.5f         /* damping factor after an accepted step */
#define IK_STALL_RATIO 0.99f    /* E must drop below this fraction to count as progress */
#define IK_HOPELESS_RESTARTS 3u /* restarts for a target beyond the reach bound */
#define IK_REACH_SLACK 1.0001f  /* relative slack on the reach bound (rounding) */
#define IK_WSTEP_MAX 1.0f       /* largest rotation weight of the step, relative to L */

/* Workspace layout (floats), n joints; slot s = 0, 1 (current / trial). */
#define OFF_J(n, s) ((s) * 6u * (n))                 /* 6n each: Jacobian */
#define OFF_E(n, s) (12u * (n) + 6u * (s))           /* 6 each: raw error */
#define OFF_Q(n, s) (12u * (n) + 12u + (s) * (n))    /* n each: joint values */
#define OFF_QBEST(n) (14u * (n) + 12u)               /* n: best configuration */
#define OFF_G(n) (15u * (n) + 12u)                   /* n: J^T W^2 e */
#define OFF_DX(n) (16u * (n) + 12u)                  /* n: step, scaled variables */
#define OFF_SCD(n) (17u * (n) + 12u)                 /* 3n: sin, cos theta, d per joint */
#define OFF_F(n) (20u * (n) + 12u)                   /* 12: frame of the Jacobian pass */
#define OFF_D(n) (20u * (n) + 24u)                   /* 9: dR row-major */
#define OFF_S(n) (20u * (n) + 33u)                   /* IK_S_COUNT scalars */
#define OFF_H(n) (20u * (n) + 45u)                   /* n*n: normal matrix, its LDL^T */

/* Scalar state slots (workspace floats). */
enum {
    S_E, S_EP, S_ER,        /* current point: E, masked position / rotation error norms */
    S_TE, S_TEP, S_TER,     /* last evaluated point */
    S_BE, S_BEP, S_BER,     /* best point over all attempts */
    S_MU, S_L, S_WBAR,
    IK_S_COUNT
};

/* How an attempt ended. */
enum { K_NONE = 0, K_CONV, K_STALL, K_CUT };
/* What the evaluated point is. */
enum { M_FIRST = 0, M_TRIAL, M_RESTART };
/* Result of an evaluation. */
enum { EV_OK = 0, EV_FK, EV_RIGID, EV_BIG };
/* What to do after an evaluation. */
enum { A_STEP = 0, A_OVER, A_RETRY, A_BREAK, A_FAIL };

/* Everything the blocks share (in dh_ik_f32's frame; vectors in work). */
typedef struct {
    const dh_robot *r;
    const dh_mat4_f32 *target;
    const dh_ik_params_f32 *p;
    const float *q0;
    float *w;               /* workspace */
    uint32_t n;
    uint32_t iter, stall, polish, restarts, rng;
    uint8_t cs;             /* slot of the current point; the other one is the trial slot */
    uint8_t mode, conv, end, best_kind, hopeless;
} ik_ctx;


/* Characteristic length L of the robot: sum of |a|, |d|, prismatic travel
 * and |p_tool|; 1 when that is 0, subnormal or its square overflows. */
static DH_NOINLINE float ik_length(const dh_robot *r)
{
    float L = 0.0f;
    uint32_t i;
    for (i = 0; i < r->n && i < (uint32_t)DH_MAX_JOINTS; i++) {
        const dh_joint *jt = &r->joint[i];
        L += fabsf(jt->a) + fabsf(jt->d);
        if (jt->type == DH_JOINT_PRISMATIC && jt->qmin <= jt->qmax)
            L += (fabsf(jt->qmin) > fabsf(jt->qmax)) ? fabsf(jt->qmin) : fabsf(jt->qmax);
    }
    L += dh_sqrtf_(r->tool.m[3][0] * r->tool.m[3][0] + r->tool.m[3][1] * r->tool.m[3][1] +
                       r->tool.m[3][2] * r->tool.m[3][2]);
    if (!(L > FLT_MIN) || !dh_isfinite_f32(L * L)) L = 1.0f;
    return L;
}

void dh_ik_params_default_f32(const dh_robot *r, dh_ik_params_f32 *p)
{
    float L;
    DH_ASSERT(r != NULL);
    DH_ASSERT(p != NULL);
    L = ik_length(r);
    p->max_iter = 2000u;
    p->mask = DH_IK_FULL;
    p->tol_pos = 1e-6f * L;
    p->tol_rot = 1e-5f;
    p->w_rot = 0.25f * L;
    p->restarts = 200u;
}

static int ik_rot_mode(uint32_t mask) { return (mask & (DH_IK_FULL & ~DH_IK_POSITION)) != 0u; }

/* Row weight: 0 for masked-out rows. */
static float ik_row_w(uint32_t mask, uint32_t row, float w_rot)
{
    if ((mask & (1u << row)) == 0u) return 0.0f;
    return (row < 3u) ? 1.0f : w_rot;
}

/* Jacobian column scale (1 or L) and joint unit per scaled variable. */
static float ik_col_scale(const dh_joint *jt, float L) { return (jt->type == DH_JOINT_REVOLUTE) ? 1.0f : L; }
static float ik_unit(const dh_joint *jt, float L) { return (jt->type == DH_JOINT_REVOLUTE) ? DH_RAD2DEG_F : L; }

static float ik_clamp(const dh_joint *jt, float v)
{
    if (jt->qmin <= jt->qmax) {
        if (v < jt->qmin) return jt->qmin;
        if (v > jt->qmax) return jt->qmax;
    }
    return v;
}

/* Masked norm of v[0..2], no overflow in the squares (+Inf only > FLT_MAX). */
static DH_NOINLINE float ik_norm3(const float *v, uint32_t mask)
{
    float m = 0.0f, s = 0.0f;
    uint32_t k;
    for (k = 0; k < 3u; k++)
        if ((mask & (1u << k)) != 0u && fabsf(v[k]) > m) m = fabsf(v[k]);
    if (!(m > 0.0f) || !dh_isfinite_f32(m)) return m;
    for (k = 0; k < 3u; k++)
        if ((mask & (1u << k)) != 0u) s += (v[k] / m) * (v[k] / m);
    return m * dh_sqrtf_(s);
}

/* Every check made before anything is written. */
static DH_NOINLINE dh_status ik_args(const ik_ctx *c, size_t work_len)
{
    const dh_robot *r = c->r;
    const dh_mat4_f32 *target = c->target;
    const dh_ik_params_f32 *p = c->p;
    const float *q0 = c->q0, *work = c->w;
    uint32_t i, n = r->n;
    if (n == 0u || n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    if (work == NULL || work_len < (size_t)DH_IK_WORK_FLOATS(n)) return DH_ERR_ARG;
    if (p->max_iter == 0u || p->mask == 0u || (p->mask & ~(uint32_t)DH_IK_FULL) != 0u)
        return DH_ERR_ARG;
    if (!(p->tol_pos >= 0.0f) || !(p->tol_rot >= 0.0f) || !dh_isfinite_f32(p->tol_pos) ||
        !dh_isfinite_f32(p->tol_rot))
        return DH_ERR_ARG;
    /* w_rot^2 times pi^2 (the largest orientation term of E) must be finite */
    if (!(p->w_rot > 0.0f) || !dh_isfinite_f32(p->w_rot * p->w_rot * 16.0f)) return DH_ERR_ARG;
    if ((r->flags & DH_ROBOT_HAS_F32) == 0u) return DH_ERR_UNAVAILABLE;
    if (r->conv != DH_CONV_STANDARD && r->conv != DH_CONV_MODIFIED) return DH_ERR_ARG;
    for (i = 0; i < n; i++)
        if (r->joint[i].type != DH_JOINT_REVOLUTE && r->joint[i].type != DH_JOINT_PRISMATIC)
            return DH_ERR_ARG;
    for (i = 0; i < 16u; i++)
        if (!dh_isfinite_f32(target->m[i / 4u][i % 4u])) return DH_ERR_NAN;
    for (i = 0; i < n; i++)
        if (!dh_isfinite_f32(q0[i])) return DH_ERR_NAN;
    /* bottom row exactly 0 0 0 1 (a projective target has no pose) */
    if (!dh_feq_f32(target->m[0][3], 0.0f) || !dh_feq_f32(target->m[1][3], 0.0f) ||
        !dh_feq_f32(target->m[2][3], 0.0f) || !dh_feq_f32(target->m[3][3], 1.0f))
        return DH_ERR_NOT_RIGID;
    return DH_OK;     /* the caller checks the rotation part (stack depth) */
}

/* Characteristic length L and the damping bias into the scalar state. */
static DH_NOINLINE void ik_scales(const ik_ctx *c)
{
    float *S = c->w + OFF_S(c->n);
    const float L = ik_length(c->r);
    S[S_L] = L;
    S[S_WBAR] = DH_IK_WBAR * L * L;
    S[S_MU] = 1.0f;
}

/* Upper bound of |p_end - p_base| within the limits, -1 when unbounded
 * (prismatic joint without limits); ||B||_2 <= sqrt(max row sum |B^T B|). */
static DH_NOINLINE float ik_reach(const dh_robot *r)
{
    const dh_mat4_f32 *B = &r->base;
    float R = 0.0f, gmax = 1.0f;
    uint32_t i, k, m;
    for (i = 0; i < r->n; i++) {
        const dh_joint *jt = &r->joint[i];
        R += fabsf(jt->a);
        if (jt->type == DH_JOINT_REVOLUTE) {
            R += fabsf(jt->d);
        } else {
            float lo, hi;
            if (jt->qmin > jt->qmax) return -1.0f;
            lo = fabsf(jt->qmin + jt->d);
            hi = fabsf(jt->qmax + jt->d);
            R += (lo > hi) ? lo : hi;
        }
    }
    R += dh_sqrtf_(r->tool.m[3][0] * r->tool.m[3][0] + r->tool.m[3][1] * r->tool.m[3][1] +
                       r->tool.m[3][2] * r->tool.m[3][2]);
    if ((r->flags & DH_ROBOT_BASE_ID_F32) == 0u) {
        gmax = 0.0f;
        for (i = 0; i < 3u; i++) {
            float rs = 0.0f;
            for (k = 0; k < 3u; k++) {
                float g = 0.0f;
                for (m = 0; m < 3u; m++) g += B->m[i][m] * B->m[k][m];
                rs += fabsf(g);
            }
            if (rs > gmax) gmax = rs;
        }
    }
    return R * dh_sqrtf_(gmax) * IK_REACH_SLACK;
}

/* 1 when the masked target distance from the base exceeds R + tol_pos. */
static DH_NOINLINE int ik_hopeless(const ik_ctx *c, float R)
{
    float v[3];
    uint32_t k;
    if (!(R >= 0.0f) || !dh_isfinite_f32(R)) return 0;
    for (k = 0; k < 3u; k++) v[k] = c->target->m[3][k] - c->r->base.m[3][k];
    return ik_norm3(v, c->p->mask) > R + c->p->tol_pos;
}

/* The rest of the context (r, target, p, q0, w set by the caller). */
static DH_NOINLINE void ik_init(ik_ctx *c)
{
    uint32_t i;
    c->n = c->r->n;
    c->iter = 0u;
    c->stall = 0u;
    c->polish = 0u;
    c->rng = 0x2545F491u;
    c->cs = 0u;
    c->mode = (uint8_t)M_FIRST;
    c->conv = 0u;
    c->end = 0u;
    c->best_kind = K_NONE;
    c->hopeless = 0u;
    c->restarts = c->p->restarts;
    /* the start, clamped into the box, is the first point evaluated (slot 1) */
    for (i = 0; i < c->n; i++) c->w[OFF_Q(c->n, 1u) + i] = ik_clamp(&c->r->joint[i], c->q0[i]);
}

/* sin, cos theta and d of every joint at the trial point (a non-finite
 * sum gives NaN, which the Jacobian pass reports). */
static DH_NOINLINE void ik_trig(const ik_ctx *c)
{
    const float *q = c->w + OFF_Q(c->n, c->cs ^ 1u);
    float *t = c->w + OFF_SCD(c->n);
    uint32_t i;
    for (i = 0; i < c->n; i++, t += 3) {
        const dh_joint *jt = &c->r->joint[i];
        if (jt->type == DH_JOINT_REVOLUTE) {
            (void)dh_sincos_f32(q[i] + jt->theta_deg, &t[0], &t[1]);
            t[2] = jt->d;
        } else {
            (void)dh_sincos_f32(jt->theta_deg, &t[0], &t[1]);
            t[2] = q[i] + jt->d;
        }
    }
}

/* Position error into the trial slot; dR = R_target R^T (row-major) when
 * the orientation is driven, else a zero orientation error. */
static DH_NOINLINE void ik_pos_err(const ik_ctx *c)
{
    const float *F = c->w + OFF_F(c->n);
    float *e = c->w + OFF_E(c->n, c->cs ^ 1u), *d = c->w + OFF_D(c->n);
    uint32_t i, j, k;
    for (k = 0; k < 3u; k++) e[k] = c->target->m[3][k] - F[9u + k];
    if (!ik_rot_mode(c->p->mask)) {
        e[3] = 0.0f;
        e[4] = 0.0f;
        e[5] = 0.0f;
        return;
    }
    for (i = 0; i < 3u; i++)
        for (j = 0; j < 3u; j++) {
            float s = 0.0f;
            for (k = 0; k < 3u; k++) s += c->target->m[k][i] * F[3u * k + j];
            d[3u * i + j] = s;
        }
}

/* Rotation weight of the step: w_rot, at most IK_WSTEP_MAX L. */
static float ik_wstep(const ik_ctx *c)
{
    const float wm = IK_WSTEP_MAX * c->w[OFF_S(c->n) + S_L];
    return (c->p->w_rot < wm) ? c->p->w_rot : wm;
}

/* Masked norms and E of the trial error into S_TE, S_TEP, S_TER; EV_BIG
 * when E is not finite (S_TEP then without overflow). */
static DH_NOINLINE int ik_norms(const ik_ctx *c)
{
    const uint32_t mask = c->p->mask;
    const float *e = c->w + OFF_E(c->n, c->cs ^ 1u);
    float *S = c->w + OFF_S(c->n);
    float sp = 0.0f, sr = 0.0f;
    uint32_t k;
    for (k = 0; k < 6u; k++) {
        if ((mask & (1u << k)) == 0u) continue;
        if (k < 3u) sp += e[k] * e[k];
        else sr += e[k] * e[k];
    }
    S[S_TEP] = dh_sqrtf_(sp);
    S[S_TER] = dh_sqrtf_(sr);
    S[S_TE] = 0.5f * (sp + ik_wstep(c) * ik_wstep(c) * sr);
    if (!dh_isfinite_f32(S[S_TE])) {
        S[S_TEP] = ik_norm3(e, mask);
        return EV_BIG;
    }
    return EV_OK;
}

/* B = W J C and W e of the current point (step weights), over the (free)
 * trial slot. */
static DH_NOINLINE void ik_weigh(const ik_ctx *c)
{
    const uint32_t n = c->n, mask = c->p->mask;
    const float *J = c->w + OFF_J(n, c->cs), *e = c->w + OFF_E(n, c->cs);
    float *B = c->w + OFF_J(n, c->cs ^ 1u), *we = c->w + OFF_E(n, c->cs ^ 1u);
    const float L = c->w[OFF_S(n) + S_L], ws = ik_wstep(c);
    uint32_t i, k;
    for (k = 0; k < 6u; k++) {
        const float wk = ik_row_w(mask, k, ws);
        we[k] = wk * e[k];
        for (i = 0; i < n; i++) B[k * n + i] = wk * (ik_col_scale(&c->r->joint[i], L) * J[k * n + i]);
    }
}

/* Lower triangle of H = B^T B + Lambda and g = B^T W e over the free
 * joints (the others: identity row/column, g = 0). Lambda is diagonal,
 * Lambda_ii = mu min(E, (B^T B)_ii) + DH_IK_WBAR L^2: Sugihara's damping,
 * capped per column so that a column that is weak next to E (a prismatic
 * joint far from its target, a lever arm long next to another joint's)
 * still takes a step of its own size. */
static DH_NOINLINE void ik_normal(const ik_ctx *c, uint32_t free_bits)
{
    const uint32_t n = c->n;
    const float *B = c->w + OFF_J(n, c->cs ^ 1u), *we = c->w + OFF_E(n, c->cs ^ 1u);
    const float *S = c->w + OFF_S(n);
    float *H = c->w + OFF_H(n), *g = c->w + OFF_G(n);
    uint32_t i, j, k;
    for (i = 0; i < n; i++) {
        const uint32_t fi = (free_bits >> i) & 1u;
        float s = 0.0f;
        if (fi)
            for (k = 0; k < 6u; k++) s += B[k * n + i] * we[k];
        g[i] = s;
        for (j = 0; j <= i; j++) {
            s = (i == j) ? 1.0f : 0.0f;
            if (fi && ((free_bits >> j) & 1u)) {
                s = 0.0f;
                for (k = 0; k < 6u; k++) s += B[k * n + i] * B[k * n + j];
                if (i == j) s += S[S_MU] * ((S[S_E] < s) ? S[S_E] : s) + S[S_WBAR];
            }
            H[i * n + j] = s;
        }
    }
}

/* H = L D L^T in place (no square root), then H dx = g; -1 if an entry
 * or dx is not finite. Every pivot of B^T B + Lambda is at least wbar in
 * exact arithmetic; one below it (rounding) is raised to it, which factors
 * H + Delta, Delta >= 0 diagonal (a modified Cholesky factorisation, Gill,
 * Murray and Wright 1981): positive definite, so dx is a descent direction
 * of the model whenever it is finite. */
static DH_NOINLINE int ik_ldl(const ik_ctx *c)
{
    const uint32_t n = c->n;
    float *H = c->w + OFF_H(n), *x = c->w + OFF_DX(n);
    const float *g = c->w + OFF_G(n);
    const float wbar = c->w[OFF_S(n) + S_WBAR], dmin = (wbar > FLT_MIN) ? wbar : FLT_MIN;
    uint32_t i, j, k;
    /* x[k] temporarily holds L_jk D_k for the current row j */
    for (j = 0; j < n; j++) {
        float *Hj = H + j * n;
        float d = Hj[j];
        for (k = 0; k < j; k++) {
            x[k] = Hj[k] * H[k * n + k];
            d -= Hj[k] * x[k];
        }
        if (!dh_isfinite_f32(d)) return -1;
        if (d < dmin) d = dmin;
        Hj[j] = d;
        for (i = j + 1u; i < n; i++) {
            float *Hi = H + i * n;
            float s = Hi[j];
            for (k = 0; k < j; k++) s -= Hi[k] * x[k];
            Hi[j] = s / d;
        }
    }
    /* L y = g, y / D, then L^T x = that */
    for (i = 0; i < n; i++) {
        float s = g[i];
        for (k = 0; k < i; k++) s -= H[i * n + k] * x[k];
        x[i] = s;
    }
    for (i = 0; i < n; i++) x[i] /= H[i * n + i];
    for (i = n; i-- > 0u;) {
        float s = x[i];
        for (k = i + 1u; k < n; k++) s -= H[k * n + i] * x[k];
        x[i] = s;
    }
    for (i = 0; i < n; i++)
        if (!dh_isfinite_f32(x[i])) return -1;
    return 0;
}

/* Free joints on a bound whose step points outward (bits). */
static DH_NOINLINE uint32_t ik_freeze(const ik_ctx *c, uint32_t free_bits)
{
    const uint32_t n = c->n;
    const float *qa = c->w + OFF_Q(n, c->cs), *dx = c->w + OFF_DX(n);
    const float L = c->w[OFF_S(n) + S_L];
    uint32_t i, frozen = 0u;
    for (i = 0; i < n; i++) {
        const dh_joint *jt = &c->r->joint[i];
        float dq;
        if (((free_bits >> i) & 1u) == 0u || jt->qmin > jt->qmax) continue;
        dq = dx[i] * ik_unit(jt, L);
        if ((qa[i] <= jt->qmin && dq < 0.0f) || (qa[i] >= jt->qmax && dq > 0.0f)) frozen |= 1u << i;
    }
    return frozen;
}

/* Trial = current + free joints' step, clamped; 0 for an empty step. */
static DH_NOINLINE int ik_apply(const ik_ctx *c, uint32_t free_bits)
{
    const uint32_t n = c->n;
    const float *qa = c->w + OFF_Q(n, c->cs), *dx = c->w + OFF_DX(n);
    float *qb = c->w + OFF_Q(n, c->cs ^ 1u);
    const float L = c->w[OFF_S(n) + S_L];
    uint32_t i;
    int moved = 0;
    for (i = 0; i < n; i++) {
        const dh_joint *jt = &c->r->joint[i];
        float dq = ((free_bits >> i) & 1u) ? dx[i] * ik_unit(jt, L) : 0.0f;
        qb[i] = ik_clamp(jt, qa[i] + dq);
        if (!dh_feq_f32(qb[i], qa[i])) moved = 1;
    }
    return moved;
}

/* Deterministic restart point (xorshift32) in the trial slot. */
static DH_NOINLINE void ik_sample(ik_ctx *c)
{
    const float L = c->w[OFF_S(c->n) + S_L];
    float *qo = c->w + OFF_Q(c->n, c->cs ^ 1u);
    uint32_t i;
    for (i = 0; i < c->n; i++) {
        const dh_joint *jt = &c->r->joint[i];
        uint32_t x = c->rng;
        float u;
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        c->rng = x;
        u = (float)(x >> 8) * (1.0f / 16777216.0f);     /* [0, 1) */
        if (jt->qmin <= jt->qmax) qo[i] = ik_clamp(jt, jt->qmin + u * (jt->qmax - jt->qmin));
        else if (jt->type == DH_JOINT_REVOLUTE) qo[i] = c->q0[i] + (u * 360.0f - 180.0f);
        else qo[i] = c->q0[i] + (2.0f * u - 1.0f) * L;
    }
    c->mode = (uint8_t)M_RESTART;
}

static int ik_met(const float *S, const dh_ik_params_f32 *p)
{
    return S[S_EP] <= p->tol_pos && S[S_ER] <= p->tol_rot;
}

/* Whether the trial point replaces the current one: 0 no, 1 yes with
 * progress, 2 yes with less than 1% progress. Before convergence a trial
 * is better when it lowers E, or when one tolerance is met at both points
 * and the other error drops (E alone cannot see a position error below the
 * float noise of w_rot times the rotation error, or the reverse); after
 * it, when it lowers E and still meets both tolerances. */
static int ik_better(const ik_ctx *c, const float *S)
{
    const dh_ik_params_f32 *p = c->p;
    float a, b;
    if (c->conv) return (S[S_TE] < S[S_E] && S[S_TEP] <= p->tol_pos && S[S_TER] <= p->tol_rot) ? 1 : 0;
    if (S[S_TE] < S[S_E]) {
        a = S[S_TE];
        b = S[S_E];
    } else if (S[S_ER] <= p->tol_rot && S[S_TER] <= p->tol_rot && S[S_TEP] < S[S_EP]) {
        a = S[S_TEP];
        b = S[S_EP];
    } else if (S[S_EP] <= p->tol_pos && S[S_TEP] <= p->tol_pos && S[S_TER] < S[S_ER]) {
        a = S[S_TER];
        b = S[S_ER];
    } else {
        return 0;
    }
    return (a < b * IK_STALL_RATIO) ? 1 : 2;
}

/* Make the trial slot the current point. */
static void ik_take(ik_ctx *c, float *S)
{
    c->cs = (uint8_t)(c->cs ^ 1u);
    S[S_E] = S[S_TE];
    S[S_EP] = S[S_TEP];
    S[S_ER] = S[S_TER];
}

/* Accept or reject the evaluated point, update damping and counters. */
static DH_NOINLINE unsigned ik_update(ik_ctx *c, int ev)
{
    const dh_ik_params_f32 *p = c->p;
    float *S = c->w + OFF_S(c->n);
    const int acc = (c->mode == M_TRIAL && ev == EV_OK) ? ik_better(c, S) : 0;
    if (c->mode == M_FIRST) {
        if (ev != EV_OK) return A_FAIL;
    } else {
        c->iter++;
    }
    c->end = 0u;
    if (c->mode != M_TRIAL) {
        if (ev != EV_OK) {
            /* a restart point that cannot be evaluated: try another */
            if (c->restarts > 0u && c->iter < p->max_iter) {
                c->restarts--;
                return A_RETRY;
            }
            return A_BREAK;
        }
        ik_take(c, S);
        S[S_MU] = 1.0f;
        c->stall = 0u;
        c->polish = 0u;
        c->conv = (uint8_t)ik_met(S, p);
    } else if (acc != 0) {
        c->stall = (acc == 1) ? 0u : c->stall + 1u;
        ik_take(c, S);
        if (c->conv) c->polish++;
        S[S_MU] = (S[S_MU] * IK_MU_DOWN > IK_MU_MIN) ? S[S_MU] * IK_MU_DOWN : IK_MU_MIN;
        if (!c->conv && ik_met(S, p)) {
            c->conv = 1u;
            S[S_MU] = IK_MU_MIN;    /* refine with the least damping */
        }
    } else {
        /* rejected (higher error, or the trial could not be evaluated) */
        c->stall++;
        S[S_MU] *= IK_MU_UP;
        if (c->conv) c->polish = IK_POLISH_STEPS;   /* at the float floor */
    }
    if (c->mode == M_TRIAL && !c->conv && (c->stall >= IK_STALL_STEPS || S[S_MU] > IK_MU_MAX))
        c->end = (uint8_t)K_STALL;
    c->mode = (uint8_t)M_TRIAL;
    if (c->end == 0u && !(c->conv && c->polish >= IK_POLISH_STEPS) && c->iter < p->max_iter) return A_STEP;
    return A_OVER;
}

/* A solve that did not give a finite step: more damping, as after a
 * rejected step; 0 when the attempt has stalled. */
static DH_NOINLINE int ik_damp(ik_ctx *c)
{
    const uint32_t m = OFF_S(c->n) + (uint32_t)S_MU;
    c->stall++;
    c->w[m] *= IK_MU_UP;
    return !c->conv && c->stall < IK_STALL_STEPS && !(c->w[m] > IK_MU_MAX);
}

/* End of an attempt: keep it if best (converged first, then lower E);
 * 1 when the solve is finished, 0 to restart. */
static DH_NOINLINE int ik_record(ik_ctx *c)
{
    float *S = c->w + OFF_S(c->n);
    const unsigned kind = c->conv ? K_CONV : (c->end != 0u ? c->end : K_CUT);
    uint32_t i;
    if (c->best_kind == K_NONE || (kind == K_CONV && c->best_kind != K_CONV) ||
        ((kind == K_CONV) == (c->best_kind == K_CONV) && S[S_E] < S[S_BE])) {
        c->best_kind = (uint8_t)kind;
        S[S_BE] = S[S_E];
        S[S_BEP] = S[S_EP];
        S[S_BER] = S[S_ER];
        for (i = 0; i < c->n; i++) c->w[OFF_QBEST(c->n) + i] = c->w[OFF_Q(c->n, c->cs) + i];
    }
    if (c->conv || c->end == 0u || c->restarts == 0u || c->iter >= c->p->max_iter) return 1;
    c->restarts--;
    return 0;
}

/* Start not evaluable: outputs untouched, except for a hopeless target
 * whose E overflows (UNREACHABLE, q = the clamped q0). */
static DH_NOINLINE dh_status ik_start_failed(const ik_ctx *c, int ev, float *q, dh_ik_result_f32 *res)
{
    const float *S = c->w + OFF_S(c->n);
    uint32_t i;
    if (ev == EV_RIGID) return DH_ERR_NOT_RIGID;
    if (ev == EV_FK || !c->hopeless) return DH_ERR_OVERFLOW;
    for (i = 0; i < c->n; i++) q[i] = c->w[OFF_Q(c->n, 1u) + i];
    res->iterations = 0u;
    res->err_pos = dh_isfinite_f32(S[S_TEP]) ? S[S_TEP] : FLT_MAX;
    res->err_rot = S[S_TER];
    return DH_ERR_UNREACHABLE;
}

/* Outputs and status from the best attempt. */
static DH_NOINLINE dh_status ik_finish(const ik_ctx *c, float *q, dh_ik_result_f32 *res)
{
    const float *S = c->w + OFF_S(c->n);
    uint32_t i;
    for (i = 0; i < c->n; i++) q[i] = c->w[OFF_QBEST(c->n) + i];
    res->iterations = c->iter;
    res->err_pos = S[S_BEP];
    res->err_rot = S[S_BER];
    if (c->best_kind == K_CONV) return DH_OK;
    if (c->hopeless || c->best_kind == K_STALL) return DH_ERR_UNREACHABLE;
    return DH_ERR_NO_CONVERGENCE;
}

dh_status dh_ik_f32(const dh_robot *r, const dh_mat4_f32 *target, const float *q0, const dh_ik_params_f32 *p,
                    float *work, size_t work_len, float *q, dh_ik_result_f32 *res)
{
    ik_ctx c;
    dh_status st;

    DH_ASSERT(r != NULL);
    DH_ASSERT(target != NULL);
    DH_ASSERT(q0 != NULL);
    DH_ASSERT(q != NULL);
    DH_ASSERT(p != NULL);
    DH_ASSERT(res != NULL);

    c.r = r;
    c.target = target;
    c.p = p;
    c.q0 = q0;
    c.w = work;
    st = ik_args(&c, work_len);
    if (st != DH_OK) return st;
    if (ik_rot_mode(p->mask) && !dh_kin_rot_ok_f32_(target->m[0], target->m[1], target->m[2]))
        return DH_ERR_NOT_RIGID;
    ik_init(&c);
    ik_scales(&c);
    if (ik_hopeless(&c, ik_reach(r))) {
        c.hopeless = 1u;
        if (c.restarts > IK_HOPELESS_RESTARTS) c.restarts = IK_HOPELESS_RESTARTS;
    }

    for (;;) {
        const uint32_t n = c.n;
        const unsigned t = c.cs ^ 1u;
        unsigned act;
        int ev = EV_FK, done;
        /* evaluate the trial slot (blocks called from here: shallow chain) */
        ik_trig(&c);
        if (dh_kin_jac_f32_(r, work + OFF_SCD(n), work + OFF_J(n, t), work + OFF_F(n))) {
            const float *F = work + OFF_F(n);
            ev = EV_RIGID;
            if (c.mode != M_FIRST || !ik_rot_mode(p->mask) || dh_kin_rot_ok_f32_(F, F + 3, F + 6)) {
                ik_pos_err(&c);
                if (ik_rot_mode(p->mask)) dh_kin_rotvec_f32_(work + OFF_D(n), work + OFF_E(n, t) + 3u);
                ev = ik_norms(&c);
            }
        }
        act = ik_update(&c, ev);
        if (act == A_FAIL) return ik_start_failed(&c, ev, q, res);
        if (act == A_RETRY) {
            ik_sample(&c);
            continue;
        }
        if (act == A_STEP) {
            /* projected step: at most n + 1 solves; a solve that overflows
             * is repeated with more damping */
            int k = 0, again = 1;
            ik_weigh(&c);
            while (again != 0) {
                uint32_t free_bits = (n >= 32u) ? 0xFFFFFFFFu : ((1u << n) - 1u), pass, frozen = 1u;
                k = 0;
                for (pass = 0; (pass <= n) && (frozen != 0u) && (k == 0); pass++) {
                    ik_normal(&c, free_bits);
                    if (ik_ldl(&c) != 0) {
                        k = -1;
                    } else {
                        frozen = ik_freeze(&c, free_bits);
                        free_bits &= ~frozen;
                    }
                }
                if (k == 0) k = ik_apply(&c, free_bits);
                again = (k < 0) ? ik_damp(&c) : 0;
            }
            if (k > 0) continue;
            c.end = (uint8_t)K_STALL;   /* an empty projected step, or no finite one */
        }
        done = (act == A_BREAK) ? 1 : ik_record(&c);
        if (done != 0) break;
        ik_sample(&c);      /* restart from a deterministic pseudo-random point */
    }
    return ik_finish(&c, q, res);
}
