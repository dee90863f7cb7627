/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_robot_q.c - the integer-only half of the robot description: joints,
 * limits and base/tool given directly in fixed point, and the flag rule
 * and fixed frame setter the float setters of dh_robot.c share. No float,
 * no libm, no 64-bit division.
 */
#include <string.h>

#include "dhmath/robot.h"
#include "dhmath/trig.h"
#include "robot_impl.h"

/* Bit patterns of float constants, stored as integers: no float
 * arithmetic. */
#define DH_F32_BITS_ONE 0x3F800000u
#define DH_F32_BITS_INF 0x7F800000u

static void robotq_put_f32_bits(float *dst, uint32_t bits)
{
    memcpy(dst, &bits, sizeof bits);
}

void dh_robot_flags_(dh_robot *r, uint32_t clear, uint32_t set)
{
    r->flags = dh_robot_summary_((r->flags & ~clear) | set);
}

/* Entries halved first: the sum of three squares stays below 3 * 2^60. */
int dh_robot_rows_small_q_(const dh_frame_q *F)
{
    const int64_t lim = (int64_t)9 << 56; /* (1.5 * 2^29)^2 = 2.25 * 2^58 */
    int k;
    for (k = 0; k < 3; k++) {
        int64_t s = 0;
        int c;
        for (c = 0; c < 3; c++) {
            int32_t h = F->r[c][k] >> 1;
            s += (int64_t)h * h;
        }
        if (s > lim) return 0;
    }
    return 1;
}

dh_status dh_robot_add_joint_q(dh_robot *r, dh_joint_type type, dh_q16 theta_deg, dh_qpos d,
                               dh_qpos a, dh_q16 alpha_deg)
{
    dh_joint *j;
    DH_ASSERT(r != NULL);
    if (r->n >= (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    if (type != DH_JOINT_REVOLUTE && type != DH_JOINT_PRISMATIC) return DH_ERR_ARG;
    /* every field of the slot; the float ones (last) as for a joint
     * without float parameters: +0, sin and cos of alpha 0 and 1, no
     * limits (qmin 1 > qmax 0), as bit patterns (no float arithmetic);
     * dh_robot_add_joint_f32 then stores its parameters over them */
    j = &r->joint[r->n];
    j->type = type;
    j->a_q = a;
    j->d_q = d;
    j->alpha_q = alpha_deg;
    j->theta_q = theta_deg;
    j->qmin_q = 1;
    j->qmax_q = 0;
    dh_sincos_q(alpha_deg, &j->sa_q, &j->ca_q);
    robotq_put_f32_bits(&j->a, 0u);
    robotq_put_f32_bits(&j->d, 0u);
    robotq_put_f32_bits(&j->alpha_deg, 0u);
    robotq_put_f32_bits(&j->theta_deg, 0u);
    robotq_put_f32_bits(&j->qmin, DH_F32_BITS_ONE);
    robotq_put_f32_bits(&j->qmax, 0u);
    robotq_put_f32_bits(&j->sa, 0u);
    robotq_put_f32_bits(&j->ca, DH_F32_BITS_ONE);
    j->vmax_q = INT32_MAX;
    j->amax_q = INT32_MAX;
    robotq_put_f32_bits(&j->vmax, DH_F32_BITS_INF);
    robotq_put_f32_bits(&j->amax, DH_F32_BITS_INF);
    r->n++;
    dh_robot_flags_(r, 0u, DH_ROBOT_F32_NO_JOINT);
    return DH_OK;
}

dh_status dh_robot_set_limits_q(dh_robot *r, uint32_t i, int32_t qmin, int32_t qmax)
{
    DH_ASSERT(r != NULL);
    if (i >= r->n || r->n > (uint32_t)DH_MAX_JOINTS || qmin > qmax) return DH_ERR_ARG;
    r->joint[i].qmin_q = qmin;
    r->joint[i].qmax_q = qmax;
    return DH_OK;
}

/* The float bits of v / 2^frac (v > 0, frac 0..30), rounded to nearest,
 * ties to even; INT32_MAX gives +inf. Integer only: the leading bit at p
 * gives the exponent p - frac (normal for every v and frac here), the 23
 * bits below it the mantissa; a carry out of the rounding moves into the
 * exponent field by the addition itself. */
uint32_t dh_robot_rate_bits_(int32_t v, unsigned frac)
{
    uint32_t u = (uint32_t)v, m, bits;
    unsigned p = 0u;
    if (v == INT32_MAX) return DH_F32_BITS_INF;
    while ((u >> p) > 1u) p++;
    if (p <= 23u) {
        m = u << (23u - p);
    } else {
        const unsigned sh = p - 23u;
        const uint32_t rest = u & ((1u << sh) - 1u), half = 1u << (sh - 1u);
        m = u >> sh;
        if (rest > half || (rest == half && (m & 1u) != 0u)) m++;
    }
    /* m holds the leading 1 at bit 23 (or 1 << 24 after a carry) */
    bits = ((uint32_t)(p + 127u - frac - 1u) << 23) + m;
    return bits;
}

dh_status dh_robot_set_rates_q(dh_robot *r, uint32_t i, int32_t vmax_q, int32_t amax_q)
{
    dh_joint *j;
    unsigned frac;
    DH_ASSERT(r != NULL);
    if (i >= r->n || r->n > (uint32_t)DH_MAX_JOINTS || vmax_q <= 0 || amax_q <= 0) return DH_ERR_ARG;
    j = &r->joint[i];
    frac = (j->type == DH_JOINT_REVOLUTE) ? 16u : (unsigned)DH_QPOS_FRAC;
    j->vmax_q = vmax_q;
    j->amax_q = amax_q;
    robotq_put_f32_bits(&j->vmax, dh_robot_rate_bits_(vmax_q, frac));
    robotq_put_f32_bits(&j->amax, dh_robot_rate_bits_(amax_q, frac));
    return DH_OK;
}

dh_status dh_robot_check_limits_q(const dh_robot *r, const int32_t *q)
{
    uint32_t i;
    DH_ASSERT(r != NULL);
    DH_ASSERT(q != NULL);
    if (r->n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    for (i = 0u; i < r->n; i++) {
        const dh_joint *j = &r->joint[i];
        if (j->qmin_q <= j->qmax_q && (q[i] < j->qmin_q || q[i] > j->qmax_q)) return DH_ERR_LIMIT;
    }
    return DH_OK;
}

/* which: 0 base, 1 tool; the tool's flag bits are the base's shifted left
 * by 1 (the small-rows bit exists for the base only). */
dh_status dh_robot_frame_q_(dh_robot *r, const dh_frame_q *src, unsigned which)
{
    dh_frame_q *dst;
    uint32_t clear = DH_ROBOT_Q_NO_BASE | DH_ROBOT_BASE_ID_Q | DH_ROBOT_F32_NO_BASE;
    uint32_t set = 0u;
    uint32_t diff = 0u; /* nonzero: src is not the identity */
    int c, k;
    DH_ASSERT(r != NULL);
    DH_ASSERT(src != NULL);
    if (which == 0u) {
        clear |= DH_ROBOT_BASE_SMALL_Q;
        if (dh_robot_rows_small_q_(src)) set = DH_ROBOT_BASE_SMALL_Q;
    }
    /* copy column by column (src may be dst; columns 0..2 rotation, 3
     * position), testing for the identity on the way */
    dst = (which != 0u) ? &r->tool_q : &r->base_q;
    for (c = 0; c < 4; c++) {
        const int32_t *s = (c < 3) ? src->r[c] : src->p;
        int32_t *d = (c < 3) ? dst->r[c] : dst->p;
        for (k = 0; k < 3; k++) {
            diff |= (uint32_t)s[k] ^ ((c == k) ? (uint32_t)DH_Q30_ONE : 0u);
            d[k] = s[k];
        }
    }
    if (diff == 0u) set |= DH_ROBOT_BASE_ID_Q;
    /* identity on both paths: the float frame is still current */
    if (diff != 0u || (r->flags & (DH_ROBOT_BASE_ID_F32 << which)) == 0u) set |= DH_ROBOT_F32_NO_BASE;
    dh_robot_flags_(r, clear << which, set << which);
    return DH_OK;
}

dh_status dh_robot_set_base_q(dh_robot *r, const dh_frame_q *base)
{
    return dh_robot_frame_q_(r, base, 0u);
}

dh_status dh_robot_set_tool_q(dh_robot *r, const dh_frame_q *tool)
{
    return dh_robot_frame_q_(r, tool, 1u);
}
