/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_interp_q.c - fixed-point pose interpolation: slerp of Q2.30
 * quaternions along the shortest arc, the pose between two fixed frames,
 * the angle between two fixed frames. Integer only: no float, no libm, no
 * 64-bit division (32x32->64 products, 32-bit divisions).
 *
 * Slerp as the float twin (dh_interp.c): with r = a* b = (cos h, sin h k)
 * the path is a (cos sh, sin sh k) for s <= 1/2 and b (cos (1-s)h,
 * -sin (1-s)h k) after, so each end is reached without rounding of the
 * other. The half angle h = atan2(|v|, w) comes from dh_atan2_q (Q16.16
 * degrees, <= 1 LSB), the sine and cosine of s h from dh_sincos_q (the
 * product s h rounded once to Q16.16), the axis k = v / |v| from an
 * integer normalisation (below), so there is no division by sin h: an
 * axis of a tiny rotation is as accurate as its components, and its error
 * is multiplied by sin sh, which is as small. The product of the rotor
 * with the nearer end is normalised once more, so the output is unit
 * within a few LSB.
 *
 * Normalisation of an integer vector (4 or 3 components, not all 0): the
 * components are brought to a common scale with the largest magnitude in
 * [2^29, 2^30) by exact shifts (left) or by rounding away at most two low
 * bits (right: a relative change below 2^-30 of the largest), their norm
 * n is an integer square root of the exact sum of squares (< 2^62), and
 * each component is round(c 2^30 / n) by the bit-serial division of
 * dh_q_udiv (|c| <= n).
 *
 * Position: p_A + round(s (p_B - p_A) / 2^30) (from p_B for s > 1/2): the
 * difference needs 33 bits, its product with s (<= 2^30) fits 63 bits,
 * and the result lies between p_A and p_B, so it cannot overflow.
 *
 * Angle: M = R_A^T R_B entry by entry as exact 64-bit dot products of
 * columns; the vee of M - M^T (2 sin t k) and tr M - 1 (2 cos t) are each
 * rounded once to Q3.29 and give t = atan2(|vee|, tr M - 1), accurate at
 * 0 and at 180 degrees alike.
 */
#include "dhmath/motion.h"
#include "dhmath/trig.h"
#include "../rot/rot_impl.h"
#include "../internal/dh_qmath.h"
#include "motion_impl.h"

/* v (len components, not all 0) normalised in place to a unit vector in
 * Q2.30 (see the file comment). 0 when all components are 0 (v as it was). */
static DH_NOINLINE int interpq_unit(int32_t *v, unsigned len)
{
    uint32_t mx = 0u, nrm, m;
    uint64_t s = 0u;
    unsigned k, sh = 0u;
    for (k = 0; k < len; k++)
        if (dh_q_abs_u32(v[k]) > mx) mx = dh_q_abs_u32(v[k]);
    if (mx == 0u) return 0;
    while ((mx >> sh) >= 0x40000000u) sh++;
    for (k = 0; k < len; k++) {
        /* |v_k| rounded to 2^-sh, at most 2^30 - 1: the squares sum below 2^62 */
        m = dh_q_abs_u32(v[k]);
        if (sh != 0u) m = (m + (1u << (sh - 1u))) >> sh;
        if (m > 0x3FFFFFFFu) m = 0x3FFFFFFFu;
        v[k] = (v[k] < 0) ? -(int32_t)m : (int32_t)m;
    }
    for (mx >>= sh; mx < 0x20000000u; mx <<= 1)
        for (k = 0; k < len; k++) v[k] = (int32_t)((uint32_t)v[k] << 1);
    for (k = 0; k < len; k++) s += (uint64_t)dh_q_mul64(v[k], v[k]);
    nrm = dh_q_isqrt62(s);
    for (k = 0; k < len; k++) {
        m = dh_q_udiv(dh_q_abs_u32(v[k]), nrm, 30u);
        v[k] = (v[k] < 0) ? -(int32_t)m : (int32_t)m;
    }
    return 1;
}

/* o = a b (Hamilton), or a* b when conj_a; each component a four-term
 * exact sum rounded once (unit inputs: |o_i| <= 2^30 + 2). o may alias a
 * (read first), not b. */
static DH_NOINLINE void interpq_mul(const dh_quat_q *a, const dh_quat_q *b, int conj_a, dh_quat_q *o)
{
    const int32_t sg = conj_a ? -1 : 1;
    const int32_t w = a->w, x = sg * a->x, y = sg * a->y, z = sg * a->z;
    o->w = (int32_t)dh_q_rshr(dh_q_mul64(w, b->w) - dh_q_mul64(x, b->x) - dh_q_mul64(y, b->y) - dh_q_mul64(z, b->z), 30u);
    o->x = (int32_t)dh_q_rshr(dh_q_mul64(w, b->x) + dh_q_mul64(x, b->w) + dh_q_mul64(y, b->z) - dh_q_mul64(z, b->y), 30u);
    o->y = (int32_t)dh_q_rshr(dh_q_mul64(w, b->y) - dh_q_mul64(x, b->z) + dh_q_mul64(y, b->w) + dh_q_mul64(z, b->x), 30u);
    o->z = (int32_t)dh_q_rshr(dh_q_mul64(w, b->z) + dh_q_mul64(x, b->y) - dh_q_mul64(y, b->x) + dh_q_mul64(z, b->w), 30u);
}

/* q normalised in place (interpq_unit on its components); 0 when all zero */
static DH_NOINLINE int interpq_unit_quat(dh_quat_q *q)
{
    int32_t v[4];
    int ok;
    v[0] = q->w;
    v[1] = q->x;
    v[2] = q->y;
    v[3] = q->z;
    ok = interpq_unit(v, 4u);
    q->w = v[0];
    q->x = v[1];
    q->y = v[2];
    q->z = v[3];
    return ok;
}

/* The angle f h, Q16.16 degrees, of the rotor (cos f h, sin f h k) of
 * r = a* b = (cos h, sin h k): f = s, or 1 - s when back; -1 when r has
 * no vector part. */
static DH_NOINLINE dh_q16 interpq_angle(const dh_quat_q *r, dh_q30 s, int back)
{
    const uint32_t n = dh_q_isqrt62((uint64_t)dh_q_mul64(r->x, r->x) + (uint64_t)dh_q_mul64(r->y, r->y) +
                                    (uint64_t)dh_q_mul64(r->z, r->z));
    dh_q16 h = 0;
    if (r->x == 0 && r->y == 0 && r->z == 0) return -1;
    (void)dh_atan2_q((int32_t)n, r->w, &h);   /* n >= 1 here */
    return (dh_q16)dh_q_rshr(dh_q_mul64(back ? DH_Q30_ONE - s : s, h), 30u);
}

/* r = (cs, sn k), k the unit vector of r's vector part (not zero) */
static DH_NOINLINE void interpq_rotor(dh_quat_q *r, int32_t sn, int32_t cs)
{
    int32_t v[3];
    unsigned k;
    v[0] = r->x;
    v[1] = r->y;
    v[2] = r->z;
    (void)interpq_unit(v, 3u);
    for (k = 0; k < 3u; k++) v[k] = (int32_t)dh_q_rshr(dh_q_mul64(v[k], sn), 30u);
    r->w = cs;
    r->x = v[0];
    r->y = v[1];
    r->z = v[2];
}

/* dh_motion_slerp_q_ (motion_impl.h) */
DH_NOINLINE void dh_motion_slerp_q_(const dh_quat_q *qa, const dh_quat_q *qb, dh_q30 s, dh_quat_q *out)
{
    dh_quat_q r;
    int32_t sn, cs;
    dh_q16 h;
    const int back = s > (DH_Q30_ONE / 2);
    const dh_quat_q *e = back ? qb : qa;
    interpq_mul(qa, qb, 1, &r);
    h = interpq_angle(&r, s, back);
    if (s <= 0 || s >= DH_Q30_ONE || h < 0) {
        *out = *e;
        return;
    }
    dh_sincos_q(h, &sn, &cs);
    interpq_rotor(&r, back ? -sn : sn, cs);
    interpq_mul(e, &r, 0, out);
    (void)interpq_unit_quat(out);
}

/* dh_motion_shorter_q_ (motion_impl.h) */
DH_NOINLINE void dh_motion_shorter_q_(const dh_quat_q *qa, dh_quat_q *qb)
{
    const int64_t d = dh_q_mul64(qa->w, qb->w) + dh_q_mul64(qa->x, qb->x) + dh_q_mul64(qa->y, qb->y) +
                      dh_q_mul64(qa->z, qb->z);
    if (d < 0) {
        qb->w = -qb->w;
        qb->x = -qb->x;
        qb->y = -qb->y;
        qb->z = -qb->z;
    }
}

dh_status dh_slerp_q(const dh_quat_q *a, const dh_quat_q *b, dh_q30 s, dh_quat_q *out)
{
    dh_quat_q qa, qb;
    DH_ASSERT(a != NULL && b != NULL && out != NULL);
    qa = *a;
    qb = *b;
    if (!interpq_unit_quat(&qa) || !interpq_unit_quat(&qb)) return DH_ERR_ZERO_AXIS;
    if (s < 0 || s > DH_Q30_ONE) return DH_ERR_ARG;
    dh_motion_shorter_q_(&qa, &qb);
    dh_motion_slerp_q_(&qa, &qb, s, out);
    return DH_OK;
}

/* dh_motion_lerp_q_ (motion_impl.h) */
DH_NOINLINE int32_t dh_motion_lerp_q_(int32_t pa, int32_t pb, dh_q30 s)
{
    const int64_t d = (int64_t)pb - pa;
    const int neg = d < 0;
    const uint64_t ud = neg ? 0u - (uint64_t)d : (uint64_t)d;   /* < 2^32 */
    const uint32_t hd = (uint32_t)(ud >> 1), ld = (uint32_t)(ud & 1u);
    const int back = s > (DH_Q30_ONE / 2);
    const int32_t f = back ? DH_Q30_ONE - s : s;
    /* f |d| = 2 f hd + f ld exactly (hd < 2^31); below 2^62 */
    const int64_t x = 2 * dh_q_mul64(f, (int32_t)hd) + ((ld != 0u) ? (int64_t)f : 0);
    const int64_t r = dh_q_rshr(x, 30u);
    const int64_t m = (neg != 0) ? -r : r;   /* s (pb - pa) or (1 - s) (pb - pa), rounded in magnitude */
    return back ? (int32_t)((int64_t)pb - m) : (int32_t)((int64_t)pa + m);
}

dh_status dh_pose_interp_q(const dh_frame_q *A, const dh_frame_q *B, dh_q30 s, dh_frame_q *T)
{
    dh_quat_q qa, qb;
    int32_t p[3];
    unsigned i;
    dh_status st;
    DH_ASSERT(A != NULL && B != NULL && T != NULL);
    if (!dh_rot_ok_q_(A, DH_ROT_TOL_Q) || !dh_rot_ok_q_(B, DH_ROT_TOL_Q)) return DH_ERR_NOT_RIGID;
    if (s < 0 || s > DH_Q30_ONE) return DH_ERR_ARG;
    if (s == 0 || s == DH_Q30_ONE) {
        *T = (s == 0) ? *A : *B;
        return DH_OK;
    }
    for (i = 0; i < 3u; i++) p[i] = dh_motion_lerp_q_(A->p[i], B->p[i], s);
    /* checked frames: the conversions cannot fail */
    (void)dh_frame_to_quat_q(A, &qa);
    (void)dh_frame_to_quat_q(B, &qb);
    (void)interpq_unit_quat(&qa);
    (void)interpq_unit_quat(&qb);
    dh_motion_shorter_q_(&qa, &qb);
    dh_motion_slerp_q_(&qa, &qb, s, &qa);
    st = dh_quat_to_frame_q(&qa, T);   /* unit qa: cannot fail; writes p = 0 */
    for (i = 0; i < 3u; i++) T->p[i] = p[i];
    return st;
}

/* column i of A's rotation . column j of B's, exact: entry (i, j) of
 * R_A^T R_B in Q4.60 (checked frames: entries below 1.25) */
static DH_NOINLINE int64_t interpq_dot(const dh_frame_q *A, const dh_frame_q *B, unsigned i, unsigned j)
{
    return dh_q_mul64(A->r[i][0], B->r[j][0]) + dh_q_mul64(A->r[i][1], B->r[j][1]) +
           dh_q_mul64(A->r[i][2], B->r[j][2]);
}

/* round(x / 2^31): Q4.60 to Q3.29 (|x| < 2^62.6 here) */
static DH_NOINLINE int32_t interpq_q29(int64_t x)
{
    return (int32_t)dh_q_rshr(x, 31u);
}

dh_status dh_pose_angle_q(const dh_frame_q *A, const dh_frame_q *B, dh_q16 *deg)
{
    int32_t v[3], c;
    uint32_t n;
    dh_q16 d = 0;
    DH_ASSERT(A != NULL && B != NULL && deg != NULL);
    if (!dh_rot_ok_q_(A, DH_ROT_TOL_Q) || !dh_rot_ok_q_(B, DH_ROT_TOL_Q)) return DH_ERR_NOT_RIGID;
    /* accepted frames: |M_ij| <= 1.0002, so the differences are below
     * 2.0004 and the trace minus 1 within [-2.0006, 2.0006]: Q3.29 fits */
    v[0] = interpq_q29(interpq_dot(A, B, 2u, 1u) - interpq_dot(A, B, 1u, 2u));
    v[1] = interpq_q29(interpq_dot(A, B, 0u, 2u) - interpq_dot(A, B, 2u, 0u));
    v[2] = interpq_q29(interpq_dot(A, B, 1u, 0u) - interpq_dot(A, B, 0u, 1u));
    c = interpq_q29(interpq_dot(A, B, 0u, 0u) + interpq_dot(A, B, 1u, 1u) + interpq_dot(A, B, 2u, 2u) -
                    (int64_t)1152921504606846976);   /* 1 in Q4.60 */
    n = dh_q_isqrt62((uint64_t)dh_q_mul64(v[0], v[0]) + (uint64_t)dh_q_mul64(v[1], v[1]) +
                     (uint64_t)dh_q_mul64(v[2], v[2]));
    /* n == c == 0 is not a rotation (|vee|^2 + (tr - 1)^2 = 4): d stays 0 */
    if (n != 0u || c != 0) (void)dh_atan2_q((int32_t)n, c, &d);
    *deg = (d < 0) ? 0 : d;
    return DH_OK;
}
