/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_jacobian_q.c - geometric Jacobian of the fixed-point chain (base and
 * tool frame). Integer only: no float, no libm, no 64-bit division.
 *
 * The chain is the one dh_fk_q builds (the FK step's formulas, roundings
 * and saturations: the same bits), accumulated in one frame in place, row
 * by row (a small stack frame: the FK's unrolled fast step and this
 * function's frame together would exceed the 256-byte budget on ARMv6-M). While the frames are
 * accumulated, column i of J holds o_i (rows 0..2, dh_qpos) and z_i (rows
 * 3..5, Q2.30), the origin and z axis of frame i-1 (standard DH) or frame
 * i (modified DH); once the end point p_e is known, a revolute column
 * becomes [z_i x (p_e - o_i); z_i] and a prismatic one [z_i; 0].
 *
 * Cross product: each component is z_a d_b - z_b d_a with d = p_e - o_i.
 * When every component of d lies in (-2^31, 2^31) (any realistic robot),
 * d replaces o in the column and the two exact products (each below
 * 2^62 - 2^31 in magnitude) are summed exactly and rounded once. Otherwise
 * d = 4 h + l is split (jacq_cross1) and the exact sum is still rounded
 * once, or saturated when it is far outside int32. Either way <= 0.5 LSB,
 * and a result outside int32 saturates with its sign and DH_ERR_OVERFLOW.
 *
 * Error against the exact Jacobian of the exact robot: the FK frames'
 * error (dh_fk_q: a few LSB per rotation entry, about half an LSB of
 * position per joint plus the rotation error times the reach) carried
 * through one cross product; measured in test/kin/test_jacobian_q.c against
 * a double reference, next to the float Jacobian of the same robot.
 */
#include "dhmath/kin.h"
#include "dhmath/frame.h"
#include "kin_impl.h"
#include "../internal/dh_qmath.h"

/* Column c of J = the joint axis: F's p in rows 0..2, F's a in rows 3..5. */
static void jacq_axis(const dh_frame_q *F, int32_t *J, uint32_t n, uint32_t c)
{
    uint32_t k;
    for (k = 0; k < 3u; k++) {
        J[k * n + c] = F->p[k];
        J[(k + 3u) * n + c] = F->r[2][k];
    }
}

/* Rows 0..2 of a revolute column (o on entry) replaced by the lever arm
 * d = p - o. Returns 0 when every component lies in (-2^31, 2^31) (rows
 * hold d); otherwise rows hold floor(d / 4) and the result is 0x100 |
 * the three remainders d mod 4, two bits each (component k at bit 2k). */
static DH_NOINLINE uint32_t jacq_lever(int32_t *col, uint32_t n, const int32_t *p)
{
    uint32_t k, ext = 0u;
    for (k = 0; k < 3u; k++) {
        const int64_t d = (int64_t)p[k] - col[k * n];
        if (d < -(int64_t)INT32_MAX || d > (int64_t)INT32_MAX) ext = 0x100u;
    }
    for (k = 0; k < 3u; k++) {
        const int64_t d = (int64_t)p[k] - col[k * n];
        if (ext != 0u) {
            col[k * n] = (int32_t)(d >> 2);
            ext |= ((uint32_t)d & 3u) << (2u * k);
        } else {
            col[k * n] = (int32_t)d;
        }
    }
    return ext;
}

/* Component k of z x d (z in rows 3..5, the lever arm as jacq_lever left
 * it): z_a d_b - z_b d_a, a = k + 1, b = k + 2 (mod 3), rounded once.
 * ext 0: two exact products, |z| <= 2^31, |d| < 2^31, the difference below
 * 2^63 - 2^32. Else d = 4 h + l: X = z_a h_b - z_b h_a (|h| <= 2^30, so
 * |X| <= 2^62) and Y = z_a l_b - z_b l_a (|Y| < 2^34); the value 4 X + Y
 * fits int64 when |X| < 2^61 and is rounded once; otherwise it is at
 * least 2^63 - 2^34 in magnitude, far beyond int32: saturated by the sign
 * of X. */
static DH_NOINLINE int32_t jacq_cross1(const int32_t *col, uint32_t n, uint32_t ext, uint32_t k, int *ovf)
{
    const uint32_t a = (k + 1u) % 3u, b = (k + 2u) % 3u;
    const int32_t za = col[(a + 3u) * n], zb = col[(b + 3u) * n];
    int64_t x = dh_q_mul64(za, col[b * n]) - dh_q_mul64(zb, col[a * n]);
    if (ext != 0u) {
        const int32_t lb = (int32_t)((ext >> (2u * b)) & 3u), la = (int32_t)((ext >> (2u * a)) & 3u);
        if (x >= ((int64_t)1 << 61) || x <= -((int64_t)1 << 61)) {
            *ovf = (int)DH_ERR_OVERFLOW;
            return dh_q_sat_sign((uint32_t)((uint64_t)x >> 32));
        }
        x = (int64_t)((uint64_t)x << 2) + (dh_q_mul64(za, lb) - dh_q_mul64(zb, la));
    }
    return dh_q_rnd30(x, ovf);
}

/* Complete the columns of J with the end point p: revolute z x (p - o),
 * prismatic [z; 0]. */
static DH_NOINLINE int jacq_cols(const dh_robot *r, const int32_t *p, int32_t *J)
{
    const uint32_t n = r->n;
    uint32_t i, k;
    int32_t t[3];
    int ovf = 0;
    for (i = 0; i < n; i++) {
        int32_t *col = &J[i];
        if (r->joint[i].type != DH_JOINT_REVOLUTE) {
            for (k = 0; k < 3u; k++) {
                t[k] = col[(k + 3u) * n];
                col[(k + 3u) * n] = 0;
            }
        } else {
            const uint32_t ext = jacq_lever(col, n, p);
            for (k = 0; k < 3u; k++) t[k] = jacq_cross1(col, n, ext, k, &ovf);
        }
        for (k = 0; k < 3u; k++) col[k * n] = t[k];
    }
    return ovf;
}

/* round((a0 v0 + a1 v1 + a2 v2) / 2^30), v_j = col[j n], from halved
 * products (each below 2^61, the sum below 2^63: no wrap; rounded at bit
 * 29), saturated. */
static DH_NOINLINE int32_t jacq_dot3(const int32_t *a, const int32_t *col, uint32_t n, int *ovf)
{
    const int64_t t = (dh_q_mul64(a[0], col[0]) >> 1) + (dh_q_mul64(a[1], col[n]) >> 1) +
                      (dh_q_mul64(a[2], col[2u * n]) >> 1);
    return dh_q_sat32(dh_q_rshr(t, 29u), ovf);
}

/* Both halves of every column rotated by R^T (R = F's rotation: row k of
 * R^T is column k of R, F->r[k]). */
static DH_NOINLINE int jacq_to_tool(const dh_frame_q *F, int32_t *J, uint32_t n)
{
    uint32_t c, h, k;
    int32_t t[3];
    int ovf = 0;
    for (c = 0; c < n; c++)
        for (h = 0; h < 6u; h += 3u) {
            int32_t *col = J + h * n + c;
            for (k = 0; k < 3u; k++) t[k] = jacq_dot3(F->r[k], col, n, &ovf);
            for (k = 0; k < 3u; k++) col[k * n] = t[k];
        }
    return ovf;
}

/* Argument checks of the public Jacobians (nothing written). */
DH_NOINLINE dh_status dh_kin_jac_check_q_(const dh_robot *r)
{
    uint32_t i, n = r->n;
    if (n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    if ((r->flags & DH_ROBOT_HAS_Q) == 0u) return DH_ERR_UNAVAILABLE;
    if (r->conv != DH_CONV_STANDARD && r->conv != DH_CONV_MODIFIED) return DH_ERR_ARG;
    for (i = 0; i < n; i++)
        if (r->joint[i].type != DH_JOINT_REVOLUTE && r->joint[i].type != DH_JOINT_PRISMATIC)
            return DH_ERR_ARG;
    return DH_OK;
}

/* round((a b + c d) / 2^30) saturated (|a b + c d| < 2^63 - 2^29: every
 * product is a rotation entry, |.| <= 2^31, times a sine, cosine or a
 * length of magnitude <= 2^31 - 1, and the sum of two < 2^63 - 2^32). */
static DH_NOINLINE int32_t jacq_dot2(int32_t a, int32_t b, int32_t c, int32_t d, int *ovf)
{
    return dh_q_rnd30(dh_q_mla64(dh_q_mul64(a, b), c, d), ovf);
}

/* p + round((a b + c d) / 2^30) saturated (dh_q_pos_rnd30). */
static DH_NOINLINE int32_t jacq_pos2(int32_t p, int32_t a, int32_t b, int32_t c, int32_t d, int *ovf)
{
    return dh_q_pos_rnd30(p, dh_q_mla64(dh_q_mul64(a, b), c, d), ovf);
}

/* Row k of F <- F * A in place, v = (st, ct, sa, ca, d, a) from
 * dh_fk_values_q_; the formulas, intermediate roundings and saturations of
 * the FK step (dh_fk_q.c), so the same bits:
 *   standard: n' = c n + s o, u = c o - s n, p' = p + d a + a_len n',
 *             o' = ca u + sa a, a' = ca a - sa u;
 *   modified: o1 = ca o + sa a, a' = ca a - sa o, p' = p + a_len n + d a',
 *             n' = c n + s o1, o' = c o1 - s n. */
static DH_NOINLINE int jacq_row(dh_frame_q *F, uint32_t k, const dh_q30 *v, unsigned mod)
{
    const int32_t x = F->r[0][k], y = F->r[1][k], z = F->r[2][k];
    int ovf = 0;
    if (!mod) {
        const int32_t n1 = jacq_dot2(v[1], x, v[0], y, &ovf), u = jacq_dot2(v[1], y, -v[0], x, &ovf);
        F->p[k] = jacq_pos2(F->p[k], v[5], n1, v[4], z, &ovf);
        F->r[0][k] = n1;
        F->r[1][k] = jacq_dot2(v[3], u, v[2], z, &ovf);
        F->r[2][k] = jacq_dot2(v[3], z, -v[2], u, &ovf);
    } else {
        const int32_t o1 = jacq_dot2(v[3], y, v[2], z, &ovf), a1 = jacq_dot2(v[3], z, -v[2], y, &ovf);
        F->p[k] = jacq_pos2(F->p[k], v[5], x, v[4], a1, &ovf);
        F->r[0][k] = jacq_dot2(v[1], x, v[0], o1, &ovf);
        F->r[1][k] = jacq_dot2(v[1], o1, -v[0], x, &ovf);
        F->r[2][k] = a1;
    }
    return ovf;
}

/* The chain with the axes stored in J: F = base * A_1 .. A_n. Out of line, so that the public frame (F) and this one
 * (the joint values) stay within the stack budget below the trig. F
 * starts as the base. */
static DH_NOINLINE int jacq_chain(const dh_robot *r, const int32_t *q, int32_t *J, dh_frame_q *F)
{
    dh_q30 v[6];
    uint32_t i, k;
    int ovf = 0;
    *F = r->base_q;
    for (i = 0; i < r->n; i++) {
        ovf |= dh_fk_values_q_(r, i, q[i], v);
        if (r->conv == DH_CONV_STANDARD) jacq_axis(F, J, r->n, i);
        for (k = 0; k < 3u; k++) ovf |= jacq_row(F, k, v, r->conv != DH_CONV_STANDARD);
        if (r->conv != DH_CONV_STANDARD) jacq_axis(F, J, r->n, i);
    }
    return ovf;
}

/* The chain, the tool and the columns into F (inlined into the public
 * Jacobians: no frame of its own there). */
DH_INLINE int jacq_body(const dh_robot *r, const int32_t *q, int32_t *J, dh_frame_q *F)
{
    int ovf = jacq_chain(r, q, J, F);
    ovf |= dh_fk_tool_q_(r, F);
    ovf |= jacq_cols(r, F->p, J);
    return ovf;
}

/* The same for dh_ik_q, which evaluates with F in its workspace
 * (kin_impl.h). */
int dh_kin_jac_q_(const dh_robot *r, const int32_t *q, int32_t *J, dh_frame_q *F)
{
    return jacq_body(r, q, J, F);
}

/* Shared body of the two public Jacobians (tool != 0: tool frame). */
DH_INLINE dh_status jacq_run(const dh_robot *r, const int32_t *q, int32_t *J, dh_frame_q *T_end, int tool)
{
    dh_frame_q F;
    int ovf;
    dh_status st;

    DH_ASSERT(r != NULL);
    DH_ASSERT(q != NULL);
    DH_ASSERT(J != NULL);

    st = dh_kin_jac_check_q_(r);
    if (st != DH_OK) return st;
    ovf = jacq_body(r, q, J, &F);
    if (tool) ovf |= jacq_to_tool(&F, J, r->n);
    if (T_end != NULL) *T_end = F;
    return ovf ? DH_ERR_OVERFLOW : DH_OK;
}

dh_status dh_jacobian_q(const dh_robot *r, const int32_t *q, int32_t *J, dh_frame_q *T_end)
{
    return jacq_run(r, q, J, T_end, 0);
}

dh_status dh_jacobian_tool_q(const dh_robot *r, const int32_t *q, int32_t *J, dh_frame_q *T_end)
{
    return jacq_run(r, q, J, T_end, 1);
}
