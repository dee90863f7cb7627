/*
 * dh_jacobian_q.c - geometric Jacobian of the fixed-point chain (base and
 * tool frame). Integer only: no float, no libm, no 64-bit division.
 *
 * The chain is the one dh_fk_q builds (dh_fk_step_q_: the same step, the
 * same bits), accumulated in one frame in place. While the frames are
 * accumulated, column i of J holds o_i (rows 0..2, dh_qpos) and z_i (rows
 * 3..5, Q2.30), the origin and z axis of frame i-1 (standard DH) or frame
 * i (modified DH); once the end point p_e is known, a revolute column
 * becomes [z_i x (p_e - o_i); z_i] and a prismatic one [z_i; 0].
 *
 * Cross product: each component is z_a d_b - z_b d_a with d = p_e - o_i.
 * When every component of d lies in (-2^31, 2^31) (any realistic robot),
 * the two exact products (each below 2^62 - 2^31 in magnitude) are summed
 * exactly and rounded once (<= 0.5 LSB). Otherwise the four products
 * z_a p_b, z_b p_a, z_a o_b, z_b o_a (int32 x int32, each <= 2^62) are
 * quartered first (floor, exact below 2^60 each, sum below 2^62: no wrap)
 * and the sum rounded at bit 28: within 0.5 + 2^-26 LSB. Either way a
 * result outside int32 saturates with its sign and DH_ERR_OVERFLOW.
 *
 * Error against the exact Jacobian of the exact robot: the FK frames'
 * error (dh_fk_q: a few LSB per rotation entry, about half an LSB of
 * position per joint plus the rotation error times the reach) carried
 * through one cross product; measured in test/test_jacobian_q.c against
 * a double reference, next to the float Jacobian of the same robot.
 */
#include "dhmath/dh_kin.h"
#include "dhmath/dh_fixed.h"
#include "dh_kin_impl.h"
#include "dh_internal.h"

/* Column c of J = the joint axis: F's p in rows 0..2, F's a in rows 3..5. */
static void jacq_axis(const dh_frame_q *F, int32_t *J, uint32_t n, uint32_t c)
{
    uint32_t k;
    for (k = 0; k < 3u; k++) {
        J[k * n + c] = F->p[k];
        J[(k + 3u) * n + c] = F->r[2][k];
    }
}

/* z_a d_b - z_b d_a, rounded to int32 (file comment), d = p - o. */
static DH_NOINLINE int32_t jacq_cross1(int32_t za, int32_t zb, int32_t pa, int32_t pb, int32_t oa,
                                       int32_t ob, int *ovf)
{
    const int64_t da = (int64_t)pa - oa, db = (int64_t)pb - ob;
    const int64_t lim = (int64_t)INT32_MAX;
    int64_t t;
    if (da >= -lim && da <= lim && db >= -lim && db <= lim) {
        t = dh_q_mul64(za, (int32_t)db) - dh_q_mul64(zb, (int32_t)da);
        return dh_q_rnd30(t, ovf);
    }
    t = (dh_q_mul64(za, pb) >> 2) - (dh_q_mul64(zb, pa) >> 2) - (dh_q_mul64(za, ob) >> 2) +
        (dh_q_mul64(zb, oa) >> 2);
    return dh_q_sat32(dh_q_rshr(t, 28u), ovf);
}

/* Complete the columns of J with the end point p (cross products). */
static DH_NOINLINE int jacq_cols(const dh_robot *r, const int32_t *p, int32_t *J)
{
    const uint32_t n = r->n;
    uint32_t i, k;
    int ovf = 0;
    for (i = 0; i < n; i++) {
        int32_t *col = J + i;
        if (r->joint[i].type == DH_JOINT_REVOLUTE) {
            const int32_t ox = col[0u * n], oy = col[1u * n], oz = col[2u * n];
            const int32_t zx = col[3u * n], zy = col[4u * n], zz = col[5u * n];
            col[0u * n] = jacq_cross1(zy, zz, p[1], p[2], oy, oz, &ovf);
            col[1u * n] = jacq_cross1(zz, zx, p[2], p[0], oz, ox, &ovf);
            col[2u * n] = jacq_cross1(zx, zy, p[0], p[1], ox, oy, &ovf);
        } else {
            for (k = 0; k < 3u; k++) {
                col[k * n] = col[(k + 3u) * n];
                col[(k + 3u) * n] = 0;
            }
        }
    }
    return ovf;
}

/* round((a0 v0 + a1 v1 + a2 v2) / 2^30) from halved products (each below
 * 2^61, the sum below 2^63: no wrap; rounded at bit 29), saturated. */
static DH_NOINLINE int32_t jacq_dot3(const int32_t *a, int32_t v0, int32_t v1, int32_t v2, int *ovf)
{
    const int64_t t = (dh_q_mul64(a[0], v0) >> 1) + (dh_q_mul64(a[1], v1) >> 1) + (dh_q_mul64(a[2], v2) >> 1);
    return dh_q_sat32(dh_q_rshr(t, 29u), ovf);
}

/* Both halves of every column rotated by R^T (R = F's rotation: row k of
 * R^T is column k of R, F->r[k]). */
static DH_NOINLINE int jacq_to_tool(const dh_frame_q *F, int32_t *J, uint32_t n)
{
    uint32_t c, h, k;
    int ovf = 0;
    for (c = 0; c < n; c++)
        for (h = 0; h < 6u; h += 3u) {
            int32_t *col = J + h * n + c;
            const int32_t vx = col[0], vy = col[n], vz = col[2u * n];
            for (k = 0; k < 3u; k++) col[k * n] = jacq_dot3(F->r[k], vx, vy, vz, &ovf);
        }
    return ovf;
}

/* Argument checks of the public Jacobians (nothing written). */
static DH_NOINLINE dh_status jacq_check(const dh_robot *r)
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

/* The chain with the axes stored in J, then the tool and the columns. */
DH_INLINE int jacq_chain(const dh_robot *r, const int32_t *q, int32_t *J, dh_frame_q *F)
{
    uint32_t i;
    int ovf = 0;
    *F = r->base_q;
    for (i = 0; i < r->n; i++) {
        if (r->conv == DH_CONV_STANDARD) jacq_axis(F, J, r->n, i);
        ovf |= dh_fk_step_q_(r, i, q[i], F);
        if (r->conv != DH_CONV_STANDARD) jacq_axis(F, J, r->n, i);
    }
    ovf |= dh_fk_tool_q_(r, F);
    ovf |= jacq_cols(r, F->p, J);
    return ovf;
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

    st = jacq_check(r);
    if (st != DH_OK) return st;
    ovf = jacq_chain(r, q, J, &F);
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
