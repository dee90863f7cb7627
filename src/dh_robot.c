/*
 * dh_robot.c - building a robot description from float parameters
 * (init, joints, limits, base/tool). The fixed-point constants of each
 * float parameter are prepared here too, so one description serves both
 * FK paths. The integer-only setters live in dh_robot_q.c.
 */
#include "dhmath/dh_robot.h"
#include "dhmath/dh_trig.h"
#include "dh_robot_impl.h"
#if DH_SMALL

#include "dhmath/dh_fixed.h"
#include "dhmath/dh_mat4.h"
#endif

#define F32_MASK_NO (DH_ROBOT_F32_NO_JOINT | DH_ROBOT_F32_NO_BASE | DH_ROBOT_F32_NO_TOOL)
#define Q_MASK_NO (DH_ROBOT_Q_NO_JOINT | DH_ROBOT_Q_NO_BASE | DH_ROBOT_Q_NO_TOOL)

#if !DH_SMALL
/* Recompute the summary bits from the reason bits. */
static uint32_t summary(uint32_t f)
{
    f &= ~(DH_ROBOT_HAS_F32 | DH_ROBOT_HAS_Q);
    if ((f & F32_MASK_NO) == 0u) f |= DH_ROBOT_HAS_F32;
    if ((f & Q_MASK_NO) == 0u) f |= DH_ROBOT_HAS_Q;
    return f;
}
#endif

/* NaN - NaN and Inf - Inf are NaN, which compares unequal to 0. */
static int is_finite(float x)
{
    return (x - x) == 0.0f;
}

#if DH_SMALL
/*
 * Round x * 2^frac to the nearest int32 (ties away from zero), as the
 * default build below, bit for bit. Returns 0 when stored, 1 when x is
 * finite but the result not representable, 2 when x is NaN or infinite
 * (out untouched in both cases), so that callers OR the results of several
 * conversions and test finiteness and range at once. rem is in (-1, 1)
 * and 2 rem is exact, so its truncation is +1 for rem >= 0.5, -1 for
 * rem <= -0.5 and 0 otherwise: the default's steps (its INT32_MAX test
 * cannot succeed: the largest float below 2^31 is 2^31 - 128, an integer,
 * so rem is 0 there).
 */
static unsigned to_fix(float x, unsigned frac, int32_t *out)
{
    float v, rem;
    int32_t i;
    /* 2^frac and 2^(31 - frac), frac in 8..24: powers of two below 2^25,
     * exact as floats */
    const float scale = (float)(1u << frac), lim = (float)(1u << (31u - frac));
    if (!(x - x == 0.0f)) return 2u;           /* NaN or Inf */
    /* x * 2^frac is in [-2^31, 2^31) iff -2^(31 - frac) <= x < 2^(31 - frac) */
    if (x >= lim || x < -lim) return 1u;
    v = x * scale;                            /* exact */
    i = (int32_t)v;
    rem = v - (float)i;
    *out = i + (int32_t)(rem + rem);
    return 0u;
}

/* Same, saturating to the int32 range instead of failing (finite x). */
static int32_t to_fix_sat(float x, unsigned frac)
{
    int32_t v;
    if (to_fix(x, frac, &v) == 0u) return v;
    return (x < 0.0f) ? INT32_MIN : INT32_MAX;
}

#else /* !DH_SMALL */

/*
 * Round x * 2^frac to the nearest int32 (ties away from zero). Returns 1
 * when the result is representable, 0 otherwise (out untouched). The
 * scaling is exact (power of two); the remainder after truncation is exact
 * because for |v| >= 2^23 a float has no fraction bits.
 */
static int to_fix(float x, unsigned frac, int32_t *out)
{
    float v = x * (float)((uint32_t)1u << frac);
    float rem;
    int32_t i;
    if (!(v < 2147483648.0f) || !(v >= -2147483648.0f)) return 0;
    i = (int32_t)v;
    rem = v - (float)i;
    if (rem >= 0.5f) {
        if (i == INT32_MAX) return 0;
        i++;
    } else if (rem <= -0.5f) {
        i--;
    }
    *out = i;
    return 1;
}

/* Same, saturating to the int32 range instead of failing (limits). */
static int32_t to_fix_sat(float x, unsigned frac)
{
    int32_t v;
    if (to_fix(x, frac, &v)) return v;
    return (x < 0.0f) ? INT32_MIN : INT32_MAX;
}

#endif /* DH_SMALL */

#if DH_SMALL
/*
 * Size-first build: one code path that reuses the integer setters of
 * dh_robot_q.c for the fixed half of every float setter. The float setter
 * validates everything first (r untouched on error), converts each constant
 * with to_fix (the same rounding as the default build, so the fixed copies
 * are bit-identical), lets dh_robot_add_joint_q / dh_robot_frame_q_ (the
 * shared body of dh_robot_set_base_q and dh_robot_set_tool_q) store them,
 * then stores the float half and corrects the bits that describe the float
 * path with dh_robot_flags_ (one copy of the summary rule for both objects,
 * dh_robot_impl.h). dh_robot_init is the sequence of setters that produce
 * the empty description: DH_MAX_JOINTS zero joints (n then reset to 0) and
 * the identity given to the float frame setter for the base and the tool,
 * starting from no flag at all; every field ends with the value the default
 * build writes. Its worst-case stack is then that of the float frame setter
 * plus its own frame (Cortex-M0+ -Os with libgcc: 228 bytes, under 256).
 */

/* which: 0 base, 1 tool; the tool's flag bits are the base's shifted by 1 */
static dh_status set_frame_f32(dh_robot *r, const dh_mat4_f32 *src, unsigned which)
{
    dh_frame_q F;
    int32_t spare; /* the bottom row, converted only for its finiteness */
    unsigned e;
    unsigned st = 0u;  /* to_fix results ORed: 2 NaN/Inf, 1 does not fit */
    unsigned bad = 0u; /* 1: not the identity, 2: bottom row not 0 0 0 1 */
    DH_ASSERT(r != NULL);
    DH_ASSERT(src != NULL);
    for (e = 0u; e < 16u; e++) {
        /* element (c, k) = (e / 4, e % 4) of src: columns 0..2 rotation
         * (Q2.30), column 3 position; the bottom row (k = 3) is converted
         * only for its finiteness */
        const unsigned c = e >> 2, k = e & 3u;
        const float x = src->m[c][k];
        int32_t *const col = (c < 3u) ? F.r[c] : F.p; /* r[c] or p */
        st |= to_fix(x, (c < 3u) ? 30u : (unsigned)DH_QPOS_FRAC, (k == 3u) ? &spare : &col[k]);
        if (x != ((c == k) ? 1.0f : 0.0f)) bad |= (k == 3u) ? 2u : 1u;
    }
    if (st & 2u) return DH_ERR_NAN;
    if (bad & 2u) return DH_ERR_NOT_RIGID;
    *((which != 0u) ? &r->tool : &r->base) = *src;
    if (st == 0u) {
        /* fixed copy, its identity / small-rows bits; this marks the float
         * frame stale, which dh_robot_flags_ below corrects */
        (void)dh_robot_frame_q_(r, &F, which);
    }
    /* an identity always fits: a frame that does not is no identity */
    dh_robot_flags_(r, (DH_ROBOT_F32_NO_BASE | DH_ROBOT_BASE_ID_F32 | DH_ROBOT_Q_NO_BASE) << which,
                    ((st != 0u) ? DH_ROBOT_Q_NO_BASE : ((bad != 0u) ? 0u : DH_ROBOT_BASE_ID_F32)) << which);
    return DH_OK;
}

dh_status dh_robot_set_base_f32(dh_robot *r, const dh_mat4_f32 *base)
{
    return set_frame_f32(r, base, 0u);
}

dh_status dh_robot_set_tool_f32(dh_robot *r, const dh_mat4_f32 *tool)
{
    return set_frame_f32(r, tool, 1u);
}

dh_status dh_robot_init(dh_robot *r, dh_convention conv)
{
    DH_ASSERT(r != NULL);
    if (conv != DH_CONV_STANDARD && conv != DH_CONV_MODIFIED) return DH_ERR_ARG;
    r->conv = conv;
    r->n = 0u;
    r->flags = 0u; /* every bit is set by the setters below */
    /* every slot as an empty joint; the call after the last one fails */
    while (dh_robot_add_joint_f32(r, DH_JOINT_REVOLUTE, 0.0f, 0.0f, 0.0f, 0.0f) == DH_OK) {
    }
    r->n = 0u;
    /* identity base, then the float setters copy it to the base (an exact
     * overlap, read before it is stored) and the tool, with both fixed
     * copies and every identity / small-rows / summary bit */
    dh_mat4_identity_f32(&r->base);
    (void)set_frame_f32(r, &r->base, 0u);
    (void)set_frame_f32(r, &r->base, 1u);
    return DH_OK;
}

dh_status dh_robot_add_joint_f32(dh_robot *r, dh_joint_type type, float a, float d,
                                 float alpha_deg, float theta_deg)
{
    dh_joint *j;
    float v[4];
    int32_t x[4];
    int k;
    unsigned st = 0u;
    uint32_t f;
    DH_ASSERT(r != NULL);
    if (r->n >= (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    if (type != DH_JOINT_REVOLUTE && type != DH_JOINT_PRISMATIC) return DH_ERR_ARG;
    v[0] = a;
    v[1] = d;
    v[2] = alpha_deg;
    v[3] = theta_deg;
    for (k = 0; k < 4; k++) st |= to_fix(v[k], (k < 2) ? (unsigned)DH_QPOS_FRAC : 16u, &x[k]);
    if (st & 2u) return DH_ERR_NAN;
    if (st != 0u) {
        /* fixed copy of an unavailable joint: zeros, sin/cos 0 and 1 */
        for (k = 0; k < 4; k++) x[k] = 0;
    }
    /* nothing fails from here on: the float fields first (so no float is
     * kept across the calls), then the fixed half and sin/cos of alpha */
    f = r->flags;
    j = &r->joint[r->n];
    j->a = v[0];
    j->d = v[1];
    j->alpha_deg = v[2];
    j->theta_deg = v[3];
    j->qmin = 1.0f;
    j->qmax = -1.0f;
    (void)dh_robot_add_joint_q(r, type, x[0], x[1], x[2], x[3]);
    (void)dh_sincos_f32(j->alpha_deg, &j->sa, &j->ca); /* finite input: cannot fail */
    /* dh_robot_add_joint_q marked the float path unavailable: undo that
     * unless an earlier joint was added with it (f: the flags before) */
    dh_robot_flags_(r, DH_ROBOT_F32_NO_JOINT & ~f, (uint32_t)st * DH_ROBOT_Q_NO_JOINT); /* st 0 or 1 */
    return DH_OK;
}

#else /* !DH_SMALL */

static int is_ident_f32(const dh_mat4_f32 *T)
{
    int c, r;
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++)
            if (T->m[c][r] != ((c == r) ? 1.0f : 0.0f)) return 0;
    return 1;
}

static int is_ident_q(const dh_frame_q *F)
{
    int c, r;
    for (c = 0; c < 3; c++) {
        if (F->p[c] != 0) return 0;
        for (r = 0; r < 3; r++)
            if (F->r[c][r] != ((c == r) ? DH_Q30_ONE : 0)) return 0;
    }
    return 1;
}



dh_status dh_robot_init(dh_robot *r, dh_convention conv)
{
    uint32_t i;
    int c;
    DH_ASSERT(r != NULL);
    if (conv != DH_CONV_STANDARD && conv != DH_CONV_MODIFIED) return DH_ERR_ARG;
    r->conv = conv;
    r->n = 0u;
    for (i = 0u; i < (uint32_t)DH_MAX_JOINTS; i++) {
        dh_joint *j = &r->joint[i];
        j->type = DH_JOINT_REVOLUTE;
        j->a = 0.0f;
        j->d = 0.0f;
        j->alpha_deg = 0.0f;
        j->theta_deg = 0.0f;
        j->qmin = 1.0f;
        j->qmax = -1.0f;
        j->sa = 0.0f;
        j->ca = 1.0f;
        j->a_q = 0;
        j->d_q = 0;
        j->alpha_q = 0;
        j->theta_q = 0;
        j->sa_q = 0;
        j->ca_q = DH_Q30_ONE;
        j->qmin_q = 1;
        j->qmax_q = -1;
    }
    for (c = 0; c < 4; c++) {
        int k;
        for (k = 0; k < 4; k++) {
            r->base.m[c][k] = (c == k) ? 1.0f : 0.0f;
            r->tool.m[c][k] = (c == k) ? 1.0f : 0.0f;
        }
    }
    for (c = 0; c < 3; c++) {
        int k;
        r->base_q.p[c] = 0;
        r->tool_q.p[c] = 0;
        for (k = 0; k < 3; k++) {
            r->base_q.r[c][k] = (c == k) ? DH_Q30_ONE : 0;
            r->tool_q.r[c][k] = (c == k) ? DH_Q30_ONE : 0;
        }
    }
    r->flags = summary(DH_ROBOT_BASE_ID_F32 | DH_ROBOT_TOOL_ID_F32 | DH_ROBOT_BASE_ID_Q |
                       DH_ROBOT_TOOL_ID_Q | DH_ROBOT_BASE_SMALL_Q);
    return DH_OK;
}

dh_status dh_robot_add_joint_f32(dh_robot *r, dh_joint_type type, float a, float d,
                                 float alpha_deg, float theta_deg)
{
    dh_joint *j;
    float sa, ca;
    int32_t aq = 0, dq = 0, alq = 0, thq = 0;
    int fits;
    DH_ASSERT(r != NULL);
    if (r->n >= (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    if (type != DH_JOINT_REVOLUTE && type != DH_JOINT_PRISMATIC) return DH_ERR_ARG;
    if (!is_finite(a) || !is_finite(d) || !is_finite(alpha_deg) || !is_finite(theta_deg))
        return DH_ERR_NAN;
    (void)dh_sincos_f32(alpha_deg, &sa, &ca); /* finite input: cannot fail */

    fits = to_fix(a, (unsigned)DH_QPOS_FRAC, &aq);
    fits &= to_fix(d, (unsigned)DH_QPOS_FRAC, &dq);
    fits &= to_fix(alpha_deg, 16u, &alq);
    fits &= to_fix(theta_deg, 16u, &thq);

    j = &r->joint[r->n];
    j->type = type;
    j->a = a;
    j->d = d;
    j->alpha_deg = alpha_deg;
    j->theta_deg = theta_deg;
    j->qmin = 1.0f;
    j->qmax = -1.0f;
    j->sa = sa;
    j->ca = ca;
    if (fits) {
        j->a_q = aq;
        j->d_q = dq;
        j->alpha_q = alq;
        j->theta_q = thq;
        dh_sincos_q(alq, &j->sa_q, &j->ca_q);
    } else {
        j->a_q = 0;
        j->d_q = 0;
        j->alpha_q = 0;
        j->theta_q = 0;
        j->sa_q = 0;
        j->ca_q = DH_Q30_ONE;
        r->flags |= DH_ROBOT_Q_NO_JOINT;
    }
    j->qmin_q = 1;
    j->qmax_q = -1;
    r->n++;
    r->flags = summary(r->flags);
    return DH_OK;
}

#endif /* DH_SMALL */

dh_status dh_robot_set_limits_f32(dh_robot *r, uint32_t i, float qmin, float qmax)
{
    dh_joint *j;
    unsigned frac;
    DH_ASSERT(r != NULL);
    if (i >= r->n || r->n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    if (!is_finite(qmin) || !is_finite(qmax)) return DH_ERR_NAN;
    if (qmin > qmax) return DH_ERR_ARG;
    j = &r->joint[i];
    frac = (j->type == DH_JOINT_REVOLUTE) ? 16u : (unsigned)DH_QPOS_FRAC;
    j->qmin = qmin;
    j->qmax = qmax;
    j->qmin_q = to_fix_sat(qmin, frac);
    j->qmax_q = to_fix_sat(qmax, frac);
    return DH_OK;
}

#if !DH_SMALL
/*
 * Shared by base and tool: validate, store the float frame, convert to Q.
 * which: 0 base, 1 tool.
 */
static dh_status set_frame_f32(dh_robot *r, const dh_mat4_f32 *src, int which)
{
    dh_frame_q F;
    dh_mat4_f32 T;
    int c, k, fits = 1;
    uint32_t f;
    DH_ASSERT(r != NULL);
    DH_ASSERT(src != NULL);
    T = *src;
    for (c = 0; c < 4; c++)
        for (k = 0; k < 4; k++)
            if (!is_finite(T.m[c][k])) return DH_ERR_NAN;
    if (T.m[0][3] != 0.0f || T.m[1][3] != 0.0f || T.m[2][3] != 0.0f || T.m[3][3] != 1.0f)
        return DH_ERR_NOT_RIGID;
    for (c = 0; c < 3; c++) {
        fits &= to_fix(T.m[3][c], (unsigned)DH_QPOS_FRAC, &F.p[c]);
        for (k = 0; k < 3; k++) {
            fits &= to_fix(T.m[c][k], 30u, &F.r[c][k]);
        }
    }
    f = r->flags;
    if (which == 0) {
        r->base = T;
        f &= ~(DH_ROBOT_F32_NO_BASE | DH_ROBOT_BASE_ID_F32 | DH_ROBOT_Q_NO_BASE);
        if (is_ident_f32(&T)) f |= DH_ROBOT_BASE_ID_F32;
        if (fits) {
            r->base_q = F;
            f &= ~(DH_ROBOT_BASE_ID_Q | DH_ROBOT_BASE_SMALL_Q);
            if (is_ident_q(&F)) f |= DH_ROBOT_BASE_ID_Q;
            if (dh_robot_rows_small_q_(&F)) f |= DH_ROBOT_BASE_SMALL_Q;
        } else {
            f |= DH_ROBOT_Q_NO_BASE;
        }
    } else {
        r->tool = T;
        f &= ~(DH_ROBOT_F32_NO_TOOL | DH_ROBOT_TOOL_ID_F32 | DH_ROBOT_Q_NO_TOOL);
        if (is_ident_f32(&T)) f |= DH_ROBOT_TOOL_ID_F32;
        if (fits) {
            r->tool_q = F;
            f &= ~DH_ROBOT_TOOL_ID_Q;
            if (is_ident_q(&F)) f |= DH_ROBOT_TOOL_ID_Q;
        } else {
            f |= DH_ROBOT_Q_NO_TOOL;
        }
    }
    r->flags = summary(f);
    return DH_OK;
}

dh_status dh_robot_set_base_f32(dh_robot *r, const dh_mat4_f32 *base)
{
    return set_frame_f32(r, base, 0);
}

dh_status dh_robot_set_tool_f32(dh_robot *r, const dh_mat4_f32 *tool)
{
    return set_frame_f32(r, tool, 1);
}

#endif /* !DH_SMALL */

dh_status dh_robot_check_limits_f32(const dh_robot *r, const float *q)
{
    uint32_t i;
    DH_ASSERT(r != NULL);
    DH_ASSERT(q != NULL);
    if (r->n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    for (i = 0u; i < r->n; i++)
        if (!is_finite(q[i])) return DH_ERR_NAN;
    for (i = 0u; i < r->n; i++) {
        const dh_joint *j = &r->joint[i];
        if (j->qmin <= j->qmax && (q[i] < j->qmin || q[i] > j->qmax)) return DH_ERR_LIMIT;
    }
    return DH_OK;
}
