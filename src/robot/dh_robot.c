/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_robot.c - building a robot description from float parameters (init,
 * joints, limits, base/tool). Each float setter validates everything first
 * (r untouched on error), converts the fixed-point copy of each constant
 * with dh_robot_f32_to_fix_, lets the integer setters of dh_robot_q.c store it,
 * then stores the float half and corrects the bits that describe the float
 * path with dh_robot_flags_.
 */
#include "dhmath/robot.h"
#include "dhmath/trig.h"
#include "dhmath/frame.h"
#include "dhmath/mat4.h"
#include "../internal/dh_floatops.h"
#include "robot_impl.h"

/* src converted to F (columns 0..2 rotation Q2.30, column 3 position
 * dh_qpos) and compared with the identity, for robot_set_frame and
 * robot_check_frame. Returns the dh_robot_f32_to_fix_ results ORed (2 NaN/Inf, 1 does
 * not fit; F is complete only when 0); *bad = 1: not the identity, 2:
 * bottom row not 0 0 0 1. Inlined: the setter's code stays as it is. */
DH_INLINE unsigned robot_frame_to_fix(const dh_mat4_f32 *src, dh_frame_q *F, unsigned *bad)
{
    int32_t spare; /* the bottom row, converted only for its finiteness */
    unsigned e;
    unsigned st = 0u, b = 0u;
    for (e = 0u; e < 16u; e++) {
        /* element (c, k) = (e / 4, e % 4) */
        const unsigned c = e >> 2, k = e & 3u;
        const float x = src->m[c][k];
        int32_t *const col = (c < 3u) ? F->r[c] : F->p;
        st |= dh_robot_f32_to_fix_(x, (c < 3u) ? 30u : (unsigned)DH_QPOS_FRAC, (k == 3u) ? &spare : &col[k]);
        if (!dh_feq_f32(x, (c == k) ? 1.0f : 0.0f)) b |= (k == 3u) ? 2u : 1u;
    }
    *bad = b;
    return st;
}

/* which: 0 base, 1 tool; the tool's flag bits are the base's shifted by 1 */
static dh_status robot_set_frame(dh_robot *r, const dh_mat4_f32 *src, unsigned which)
{
    dh_frame_q F;
    unsigned st;  /* dh_robot_f32_to_fix_ results ORed: 2 NaN/Inf, 1 does not fit */
    unsigned bad; /* 1: not the identity, 2: bottom row not 0 0 0 1 */
    DH_ASSERT(r != NULL);
    DH_ASSERT(src != NULL);
    st = robot_frame_to_fix(src, &F, &bad);
    if (st & 2u) return DH_ERR_NAN;
    if (bad & 2u) return DH_ERR_NOT_RIGID;
    {
        /* element by element: a loop is smaller than the unrolled struct copy */
        dh_mat4_f32 *dst = (which != 0u) ? &r->tool : &r->base;
        unsigned e;
        for (e = 0u; e < 16u; e++) dst->m[e >> 2][e & 3u] = src->m[e >> 2][e & 3u];
    }
    if (st == 0u) {
        /* fixed copy and its bits; this marks the float frame stale, which
         * dh_robot_flags_ below corrects */
        (void)dh_robot_frame_q_(r, &F, which);
    }
    /* an identity always fits: a frame that does not is no identity */
    dh_robot_flags_(r, (DH_ROBOT_F32_NO_BASE | DH_ROBOT_BASE_ID_F32 | DH_ROBOT_Q_NO_BASE) << which,
                    ((st != 0u) ? DH_ROBOT_Q_NO_BASE : ((bad != 0u) ? 0u : DH_ROBOT_BASE_ID_F32)) << which);
    return DH_OK;
}

dh_status dh_robot_set_base_f32(dh_robot *r, const dh_mat4_f32 *base)
{
    return robot_set_frame(r, base, 0u);
}

dh_status dh_robot_set_tool_f32(dh_robot *r, const dh_mat4_f32 *tool)
{
    return robot_set_frame(r, tool, 1u);
}

/* The state the setters leave for the empty description (every slot the
 * joint dh_robot_add_joint_f32(r, DH_JOINT_REVOLUTE, 0, 0, 0, 0) writes, n
 * reset to 0, identity base and tool set with the float setters), made
 * with the integer setter (which writes the same slot), identity frames and
 * the flags of that state: no float arithmetic, so a firmware building its
 * robot with the _q setters links no soft float. */
dh_status dh_robot_init(dh_robot *r, dh_convention conv)
{
    DH_ASSERT(r != NULL);
    if (conv != DH_CONV_STANDARD && conv != DH_CONV_MODIFIED) return DH_ERR_ARG;
    r->conv = conv;
    r->n = 0u;
    r->flags = 0u;
    while (dh_robot_add_joint_q(r, DH_JOINT_REVOLUTE, 0, 0, 0, 0) == DH_OK) {
    }
    r->n = 0u;
    /* the identities are constants (no float arithmetic either) */
    dh_mat4_identity_f32(&r->base);
    dh_mat4_identity_f32(&r->tool);
    dh_frame_identity_q(&r->base_q);
    dh_frame_identity_q(&r->tool_q);
    r->flags = dh_robot_summary_(DH_ROBOT_BASE_ID_F32 | DH_ROBOT_TOOL_ID_F32 | DH_ROBOT_BASE_ID_Q |
                                 DH_ROBOT_TOOL_ID_Q | DH_ROBOT_BASE_SMALL_Q);
    return DH_OK;
}

dh_status dh_robot_add_joint_f32(dh_robot *r, dh_joint_type type, float theta_deg, float d,
                                 float a, float alpha_deg)
{
    dh_joint *j;
    float v[4];
    int32_t x[4];
    int k;
    unsigned st = 0u;
    uint32_t f;
    dh_status s;
    DH_ASSERT(r != NULL);
    v[0] = a;
    v[1] = d;
    v[2] = alpha_deg;
    v[3] = theta_deg;
    for (k = 0; k < 4; k++) st |= dh_robot_f32_to_fix_(v[k], (k < 2) ? (unsigned)DH_QPOS_FRAC : 16u, &x[k]);
    if (st & 2u) return DH_ERR_NAN;
    if (st != 0u) {
        /* fixed copy of an unavailable joint: zeros, sin/cos 0 and 1 */
        for (k = 0; k < 4; k++) x[k] = 0;
    }
    /* the fixed half checks n and type (DH_ERR_ARG, r untouched) and
     * writes the slot's float fields as for a joint without them, no
     * limits among them; nothing fails after it: the float parameters
     * and sin/cos of alpha */
    f = r->flags;
    s = dh_robot_add_joint_q(r, type, x[3], x[1], x[0], x[2]);
    if (s != DH_OK) return s;
    j = &r->joint[r->n - 1u]; /* the slot just written */
    j->a = v[0];
    j->d = v[1];
    j->alpha_deg = v[2];
    j->theta_deg = v[3];
    (void)dh_sincos_f32(v[2], &j->sa, &j->ca); /* finite input: cannot fail */
    /* dh_robot_add_joint_q marked the float path unavailable: undo that
     * unless an earlier joint was added with it (f: the flags before) */
    dh_robot_flags_(r, DH_ROBOT_F32_NO_JOINT & ~f, (uint32_t)st * DH_ROBOT_Q_NO_JOINT); /* st 0 or 1 */
    return DH_OK;
}

dh_status dh_robot_set_limits_f32(dh_robot *r, uint32_t i, float qmin, float qmax)
{
    dh_joint *j;
    unsigned frac;
    unsigned st = 0u; /* saturation is the contract: status unused */
    DH_ASSERT(r != NULL);
    if (i >= r->n || r->n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    if (!dh_isfinite_f32(qmin) || !dh_isfinite_f32(qmax)) return DH_ERR_NAN;
    if (qmin > qmax) return DH_ERR_ARG;
    j = &r->joint[i];
    frac = (j->type == DH_JOINT_REVOLUTE) ? 16u : (unsigned)DH_QPOS_FRAC;
    j->qmin = qmin;
    j->qmax = qmax;
    j->qmin_q = dh_robot_f32_to_fix_sat_(qmin, frac, &st);
    j->qmax_q = dh_robot_f32_to_fix_sat_(qmax, frac, &st);
    return DH_OK;
}

/* The fixed copy of a valid float rate limit x (> 0, not NaN) as
 * dh_robot_set_rates_f32 stores it: +inf -> INT32_MAX (unlimited), else
 * rounded to nearest and clamped to [1, INT32_MAX - 1]. */
static int32_t robot_rate_q(float x, unsigned frac)
{
    int32_t v = INT32_MAX - 1;
    if (dh_f32_bits(x) == 0x7F800000u) return INT32_MAX;
    if (dh_robot_f32_to_fix_(x, frac, &v) != 0u) return INT32_MAX - 1;
    if (v == INT32_MAX) v = INT32_MAX - 1;
    return (v < 1) ? 1 : v;
}

dh_status dh_robot_set_rates_f32(dh_robot *r, uint32_t i, float vmax, float amax)
{
    dh_joint *j;
    unsigned frac;
    DH_ASSERT(r != NULL);
    if (i >= r->n || r->n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    if (!dh_feq_f32(vmax, vmax) || !dh_feq_f32(amax, amax)) return DH_ERR_NAN;
    if (!(vmax > 0.0f) || !(amax > 0.0f)) return DH_ERR_ARG;
    j = &r->joint[i];
    frac = (j->type == DH_JOINT_REVOLUTE) ? 16u : (unsigned)DH_QPOS_FRAC;
    j->vmax = vmax;
    j->amax = amax;
    j->vmax_q = robot_rate_q(vmax, frac);
    j->amax_q = robot_rate_q(amax, frac);
    return DH_OK;
}

/* 0 when a rate limit pair is what one of the setters leaves: the float
 * one > 0 (+inf allowed, no NaN), the fixed one > 0, and either the fixed
 * one is the float one converted (dh_robot_set_rates_f32) or the float one
 * is the fixed one converted (dh_robot_set_rates_q). */
static unsigned robot_check_rate(float x, int32_t xq, unsigned frac)
{
    if (!(x > 0.0f) || xq <= 0) return 1u;
    if (robot_rate_q(x, frac) == xq) return 0u;
    return (dh_robot_rate_bits_(xq, frac) == dh_f32_bits(x)) ? 0u : 1u;
}

dh_status dh_robot_check_limits_f32(const dh_robot *r, const float *q)
{
    uint32_t i;
    DH_ASSERT(r != NULL);
    DH_ASSERT(q != NULL);
    if (r->n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    for (i = 0u; i < r->n; i++)
        if (!dh_isfinite_f32(q[i])) return DH_ERR_NAN;
    for (i = 0u; i < r->n; i++) {
        const dh_joint *j = &r->joint[i];
        if (j->qmin <= j->qmax && (q[i] < j->qmin || q[i] > j->qmax)) return DH_ERR_LIMIT;
    }
    return DH_OK;
}

/* ---- dh_robot_check -------------------------------------------------------
 * The setters leave every description in a state that the primary fields
 * (conv, n, type, a, d, alpha_deg, theta_deg, the limits, base, tool, the
 * fixed parameters and frames) determine up to the setter history recorded
 * in the reason bits. The check recomputes each derived field with the
 * setters' own code (dh_sincos_f32, dh_sincos_q, dh_robot_f32_to_fix_, the
 * identity and small-rows tests) and compares bit for bit:
 *   joint: sa, ca = dh_sincos_f32(alpha_deg); sa_q, ca_q =
 *     dh_sincos_q(alpha_q); the float parameters finite; and one of: the
 *     fixed parameters are the float ones converted (added with _f32); the
 *     float ones do not fit and the fixed ones are 0 (_f32, then
 *     DH_ROBOT_Q_NO_JOINT is set); the float ones are +0 (added with _q,
 *     then DH_ROBOT_F32_NO_JOINT is set). Each of those two bits is set
 *     only when a joint of its kind exists. Limits are independent fields
 *     (dh_robot_set_limits_q sets the fixed ones alone): only finiteness.
 *     Rate limits: each pair as one of the rate setters leaves it (see
 *     robot_check_rate).
 *   base and tool: see robot_check_frame.
 *   flags: no unknown bit, the summary bits as dh_robot_flags_ makes them. */

/* 0 when the float and fixed base (which 0) or tool (1) and their bits are
 * a state that robot_set_frame and dh_robot_frame_q_ leave: the float frame
 * finite with bottom row 0 0 0 1 and its identity bit right; the fixed
 * frame's identity bit (and for the base its small-rows bit) right; and
 * either the fixed frame is the float one converted (no reason bit), or
 * the float one does not fit (Q_NO, last set with _f32), or the fixed one
 * was set alone (F32_NO, not both frames the identity). */
static DH_NOINLINE unsigned robot_check_frame(const dh_robot *r, unsigned which)
{
    const dh_mat4_f32 *M = (which != 0u) ? &r->tool : &r->base;
    const dh_frame_q *G = (which != 0u) ? &r->tool_q : &r->base_q;
    const uint32_t f = r->flags >> which;
    dh_frame_q F = { { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 } }, { 0, 0, 0 } };
    unsigned e, bad;
    const unsigned st = robot_frame_to_fix(M, &F, &bad); /* as in robot_set_frame */
    uint32_t diff = 0u, idq = 0u, mask, want; /* F vs G, G vs the identity */
    if ((st & 2u) != 0u || (bad & 2u) != 0u) return 1u;
    for (e = 0u; e < 12u; e++) {
        const unsigned c = e / 3u, k = e % 3u;
        const int32_t g = (c < 3u) ? G->r[c][k] : G->p[k];
        const int32_t fv = (st != 0u) ? g : ((c < 3u) ? F.r[c][k] : F.p[k]); /* F only where stored */
        diff |= (uint32_t)g ^ (uint32_t)fv;
        idq |= (uint32_t)g ^ ((c == k) ? (uint32_t)DH_Q30_ONE : 0u);
    }
    /* the identity and small-rows bits as the setters set them */
    mask = DH_ROBOT_BASE_ID_F32 | DH_ROBOT_BASE_ID_Q;
    want = 0u;
    if (bad == 0u) want |= DH_ROBOT_BASE_ID_F32;
    if (idq == 0u) want |= DH_ROBOT_BASE_ID_Q;
    if (which == 0u) {
        mask |= DH_ROBOT_BASE_SMALL_Q;
        if (dh_robot_rows_small_q_(G) != 0) want |= DH_ROBOT_BASE_SMALL_Q;
    }
    if ((f & mask) != want) return 1u;
    if ((f & DH_ROBOT_Q_NO_BASE) != 0u) return ((f & DH_ROBOT_F32_NO_BASE) != 0u || st == 0u) ? 1u : 0u;
    if ((f & DH_ROBOT_F32_NO_BASE) != 0u) return (idq == 0u && bad == 0u) ? 1u : 0u;
    return (st != 0u || diff != 0u) ? 1u : 0u;
}

/* 0 when joint j is a state the setters leave; *need |= the joint reason
 * bit it calls for, *allow |= the one it permits (see above). */
static DH_NOINLINE unsigned robot_check_joint(const dh_joint *j, uint32_t *need, uint32_t *allow)
{
    float sa, ca;
    dh_q30 sq, cq;
    int32_t x[4] = { 0, 0, 0, 0 };
    uint32_t zf, zq, dq;
    unsigned st;
    st = dh_robot_f32_to_fix_(j->a, (unsigned)DH_QPOS_FRAC, &x[0]) | dh_robot_f32_to_fix_(j->d, (unsigned)DH_QPOS_FRAC, &x[1]) |
         dh_robot_f32_to_fix_(j->alpha_deg, 16u, &x[2]) | dh_robot_f32_to_fix_(j->theta_deg, 16u, &x[3]);
    zf = dh_f32_bits(j->a) | dh_f32_bits(j->d) | dh_f32_bits(j->alpha_deg) | dh_f32_bits(j->theta_deg);
    if ((st & 2u) != 0u || !dh_isfinite_f32(j->qmin) || !dh_isfinite_f32(j->qmax)) return 1u;
    /* dq: used only when st == 0, i.e. all four converted */
    dq = ((uint32_t)x[0] ^ (uint32_t)j->a_q) | ((uint32_t)x[1] ^ (uint32_t)j->d_q) |
         ((uint32_t)x[2] ^ (uint32_t)j->alpha_q) | ((uint32_t)x[3] ^ (uint32_t)j->theta_q);
    zq = (uint32_t)j->a_q | (uint32_t)j->d_q | (uint32_t)j->alpha_q | (uint32_t)j->theta_q;
    (void)dh_sincos_f32(j->alpha_deg, &sa, &ca);
    dh_sincos_q(j->alpha_q, &sq, &cq);
    {
        const unsigned frac = (j->type == DH_JOINT_REVOLUTE) ? 16u : (unsigned)DH_QPOS_FRAC;
        if ((robot_check_rate(j->vmax, j->vmax_q, frac) | robot_check_rate(j->amax, j->amax_q, frac)) != 0u)
            return 1u;
    }
    if (dh_f32_bits(sa) != dh_f32_bits(j->sa) || dh_f32_bits(ca) != dh_f32_bits(j->ca) || sq != j->sa_q ||
        cq != j->ca_q)
        return 1u;
    if (zf == 0u) *allow |= DH_ROBOT_F32_NO_JOINT;
    if (st == 0u && dq == 0u) return 0u;
    if (st != 0u && zq == 0u) {
        *need |= DH_ROBOT_Q_NO_JOINT;
        return 0u;
    }
    if (zf == 0u) {
        *need |= DH_ROBOT_F32_NO_JOINT;
        return 0u;
    }
    return 1u;
}

dh_status dh_robot_check(const dh_robot *r)
{
    const uint32_t known = DH_ROBOT_HAS_F32 | DH_ROBOT_HAS_Q | DH_ROBOT_F32_NO_JOINT |
                           DH_ROBOT_F32_NO_BASE | DH_ROBOT_F32_NO_TOOL | DH_ROBOT_Q_NO_JOINT |
                           DH_ROBOT_Q_NO_BASE | DH_ROBOT_Q_NO_TOOL | DH_ROBOT_BASE_ID_F32 |
                           DH_ROBOT_TOOL_ID_F32 | DH_ROBOT_BASE_ID_Q | DH_ROBOT_TOOL_ID_Q |
                           DH_ROBOT_BASE_SMALL_Q;
    const uint32_t jbits = DH_ROBOT_F32_NO_JOINT | DH_ROBOT_Q_NO_JOINT;
    uint32_t i, need = 0u, allow = 0u; /* joint reason bits the joints call for / permit */
    unsigned bad = 0u;
    DH_ASSERT(r != NULL);
    if (r->conv != DH_CONV_STANDARD && r->conv != DH_CONV_MODIFIED) return DH_ERR_ARG;
    if (r->n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    for (i = 0u; i < r->n; i++)
        if (r->joint[i].type != DH_JOINT_REVOLUTE && r->joint[i].type != DH_JOINT_PRISMATIC) return DH_ERR_ARG;
    for (i = 0u; i < r->n; i++) bad |= robot_check_joint(&r->joint[i], &need, &allow);
    /* each joint bit set when called for, and only when permitted; no
     * unknown bit; the summary bits as the setters compute them */
    allow |= need;
    if ((r->flags & jbits & ~allow) != 0u || (need & ~r->flags) != 0u ||
        (r->flags & ~known) != 0u || dh_robot_summary_(r->flags) != r->flags)
        bad = 1u;
    bad |= robot_check_frame(r, 0u) | robot_check_frame(r, 1u);
    return (bad != 0u) ? DH_ERR_INCONSISTENT : DH_OK;
}
