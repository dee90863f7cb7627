/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_jacobian.c - geometric Jacobian (base and tool frame) (method:
 * docs/design.md, "Kinematics").
 *
 * Column i: revolute [z_i x (p_e - o_i); z_i] per radian, prismatic
 * [z_i; 0]; z_i, o_i of frame i-1 (standard DH) or frame i (modified).
 * While the frames are accumulated, column i holds o_i (rows 0..2) and z_i
 * (rows 3..5), completed in place once p_e is known.
 *
 * Stack (<= 256 B per public function with callees and libgcc): the running
 * frame is a 3x4 updated in place, row by row, from the DH definitions:
 *   standard, F <- F * Rz(theta) Tz(d) Tx(a) Rx(alpha), columns n o a p:
 *     n' = c n + s o,  u = c o - s n,  p' = p + d a + a_len n',
 *     o' = ca u + sa a,  a' = ca a - sa u
 *   modified, F <- F * Rx(alpha) Tx(a) Rz(theta) Tz(d):
 *     o1 = ca o + sa a,  a' = ca a - sa o,  p' = p + a_len n + d a',
 *     n' = c n + s o1,  o' = c o1 - s n
 * The only callees are dh_sincos_f32, the libm-free dh_mathf.h and libgcc;
 * the blocks are noinline so that the worst case is a chain of small frames
 * (jac_run is inlined into both public Jacobians: no wrapper frame).
 */
#include "dhmath/kin.h"
#include "dhmath/trig.h"
#include "kin_impl.h"
#include "../internal/dh_mathf.h"
#include "../internal/dh_floatops.h"

#include <float.h>
#include <math.h>
#include <string.h>

/* Column c of J = the joint axis: F's p in rows 0..2, F's a in rows 3..5. */
static void jac_axis(const float *F, float *J, uint32_t n, uint32_t c)
{
    uint32_t k;
    for (k = 0; k < 3u; k++) {
        J[k * n + c] = F[9u + k];
        J[(k + 3u) * n + c] = F[6u + k];
    }
}

/* F <- F * A (standard DH), t = (sin theta, cos theta, d). */
static DH_NOINLINE void jac_std(float *F, const float *t, const dh_joint *j)
{
    uint32_t k;
    for (k = 0; k < 3u; k++) {
        float nx = F[k], ox = F[3u + k], ax = F[6u + k];
        float n1 = t[1] * nx + t[0] * ox, u = t[1] * ox - t[0] * nx;
        F[9u + k] = F[9u + k] + t[2] * ax + j->a * n1;
        F[k] = n1;
        F[3u + k] = j->ca * u + j->sa * ax;
        F[6u + k] = j->ca * ax - j->sa * u;
    }
}

/* F <- F * A (modified DH), arguments as jac_std. */
static DH_NOINLINE void jac_mod(float *F, const float *t, const dh_joint *j)
{
    uint32_t k;
    for (k = 0; k < 3u; k++) {
        float nx = F[k], ox = F[3u + k], ax = F[6u + k];
        float o1 = j->ca * ox + j->sa * ax, a1 = j->ca * ax - j->sa * ox;
        F[9u + k] = F[9u + k] + j->a * nx + t[2] * a1;
        F[k] = t[1] * nx + t[0] * o1;
        F[3u + k] = t[1] * o1 - t[0] * nx;
        F[6u + k] = a1;
    }
}

/* F <- F * A_i; the axis of joint i goes to column i of J before the
 * update (standard DH) or after it (modified DH). */
DH_INLINE void jac_link(const dh_robot *r, uint32_t i, const float *t, float *F, float *J)
{
    if (r->conv == DH_CONV_STANDARD) {
        jac_axis(F, J, r->n, i);
        jac_std(F, t, &r->joint[i]);
    } else {
        jac_mod(F, t, &r->joint[i]);
        jac_axis(F, J, r->n, i);
    }
}

/* F = the base's 3x4 part. */
static void jac_start(const dh_robot *r, float *F)
{
    uint32_t c, k;
    for (c = 0; c < 4u; c++)
        for (k = 0; k < 3u; k++) F[3u * c + k] = r->base.m[c][k];
}

/* F <- F * tool (in place, row by row). */
static DH_NOINLINE void jac_tool(const dh_robot *r, float *F)
{
    const dh_mat4_f32 *T = &r->tool;
    uint32_t i, k;
    if ((r->flags & DH_ROBOT_TOOL_ID_F32) != 0u) return;
    for (k = 0; k < 3u; k++) {
        float r0 = F[k], r1 = F[3u + k], r2 = F[6u + k], r3 = F[9u + k];
        for (i = 0; i < 3u; i++) F[3u * i + k] = r0 * T->m[i][0] + r1 * T->m[i][1] + r2 * T->m[i][2];
        F[9u + k] = (r0 * T->m[3][0] + r1 * T->m[3][1] + r2 * T->m[3][2]) + r3;
    }
}

/* 1 when v[0..len-1] are all finite. */
static DH_NOINLINE int jac_all_finite(const float *v, uint32_t len)
{
    return dh_allfinite_f32(v, len);
}

/* Complete the columns of J with the end point F's p (cross products). */
static DH_NOINLINE void jac_cols(const dh_robot *r, const float *F, float *J)
{
    const uint32_t n = r->n;
    uint32_t i, k;
    for (i = 0; i < n; i++) {
        float *col = J + i;
        if (r->joint[i].type == DH_JOINT_REVOLUTE) {
            float dx = F[9] - col[0u * n], dy = F[10] - col[1u * n], dz = F[11] - col[2u * n];
            col[0u * n] = col[4u * n] * dz - col[5u * n] * dy;
            col[1u * n] = col[5u * n] * dx - col[3u * n] * dz;
            col[2u * n] = col[3u * n] * dy - col[4u * n] * dx;
        } else {
            for (k = 0; k < 3u; k++) {
                col[k * n] = col[(k + 3u) * n];
                col[(k + 3u) * n] = 0.0f;
            }
        }
    }
}

int dh_kin_jac_f32_(const dh_robot *r, const float *scd, float *J, float *F)
{
    uint32_t i;
    jac_start(r, F);
    for (i = 0; i < r->n; i++) jac_link(r, i, &scd[3u * i], F, J);
    jac_tool(r, F);
    jac_cols(r, F, J);
    return jac_all_finite(J, 6u * r->n) & jac_all_finite(F, 12u);
}

/* Both halves of every column rotated by R^T (R = F's rotation). */
static DH_NOINLINE void jac_to_tool(const float *F, float *J, uint32_t n)
{
    uint32_t c, h, k;
    for (c = 0; c < n; c++)
        for (h = 0; h < 6u; h += 3u) {
            float vx = J[(h + 0u) * n + c], vy = J[(h + 1u) * n + c], vz = J[(h + 2u) * n + c];
            for (k = 0; k < 3u; k++)
                J[(h + k) * n + c] = F[3u * k] * vx + F[3u * k + 1u] * vy + F[3u * k + 2u] * vz;
        }
}

/* Argument checks of the public Jacobians (nothing written). */
static DH_NOINLINE dh_status jac_check(const dh_robot *r, const float *q)
{
    uint32_t i, n = r->n;
    if (n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    /* float path unavailable (J untouched, also for n == 0) */
    if ((r->flags & DH_ROBOT_HAS_F32) == 0u) return DH_ERR_UNAVAILABLE;
    if (r->conv != DH_CONV_STANDARD && r->conv != DH_CONV_MODIFIED) return DH_ERR_ARG;
    for (i = 0; i < n; i++) {
        if (!dh_allfinite_f32(&q[i], 1u)) return DH_ERR_NAN;
        if (r->joint[i].type != DH_JOINT_REVOLUTE && r->joint[i].type != DH_JOINT_PRISMATIC)
            return DH_ERR_ARG;
    }
    for (i = 0; i < n; i++) {
        const dh_joint *j = &r->joint[i];
        float v = q[i] + ((j->type == DH_JOINT_REVOLUTE) ? j->theta_deg : j->d);
        if (!dh_allfinite_f32(&v, 1u)) return DH_ERR_OVERFLOW;
    }
    return DH_OK;
}

/* sin, cos of theta and d of joint i at q into t[0..2]. */
static DH_NOINLINE void jac_trig(const dh_joint *j, float q, float *t)
{
    if (j->type == DH_JOINT_REVOLUTE) {
        (void)dh_sincos_f32(q + j->theta_deg, &t[0], &t[1]);
        t[2] = j->d;
    } else {
        (void)dh_sincos_f32(j->theta_deg, &t[0], &t[1]);
        t[2] = q + j->d;
    }
}

/* T_end (may be NULL) = F with the bottom row 0 0 0 1. */
static DH_NOINLINE void jac_store(const float *F, dh_mat4_f32 *T_end)
{
    uint32_t c, k;
    if (T_end == NULL) return;
    for (c = 0; c < 4u; c++) {
        for (k = 0; k < 3u; k++) T_end->m[c][k] = F[3u * c + k];
        T_end->m[c][3] = (c == 3u) ? 1.0f : 0.0f;
    }
}

/* Shared body of the Jacobians (tool != 0: tool frame); w: 15 floats of
 * scratch (the end frame F, then one joint's sin, cos, d). */
DH_INLINE dh_status jac_run(const dh_robot *r, const float *q, float *J, dh_mat4_f32 *T_end, int tool, float *w)
{
    float *const F = w, *const t = w + 12;
    uint32_t i;
    int fin;
    dh_status st;

    DH_ASSERT(r != NULL);
    DH_ASSERT(q != NULL);
    DH_ASSERT(J != NULL);

    st = jac_check(r, q);
    if (st != DH_OK) return st;
    jac_start(r, F);
    for (i = 0; i < r->n; i++) {
        jac_trig(&r->joint[i], q[i], t);
        jac_link(r, i, t, F, J);
    }
    jac_tool(r, F);
    jac_cols(r, F, J);
    fin = jac_all_finite(J, 6u * r->n) & jac_all_finite(F, 12u);
    if (tool) jac_to_tool(F, J, r->n);
    jac_store(F, T_end);
    return fin ? DH_OK : DH_ERR_OVERFLOW;
}

dh_status dh_jacobian_f32(const dh_robot *r, const float *q, float *J, dh_mat4_f32 *T_end)
{
    float w[15];
    return jac_run(r, q, J, T_end, 0, w);
}

dh_status dh_jacobian_tool_f32(const dh_robot *r, const float *q, float *J, dh_mat4_f32 *T_end)
{
    float w[15];
    return jac_run(r, q, J, T_end, 1, w);
}

dh_status dh_kin_jacobian_f32_(const dh_robot *r, const float *q, float *J, dh_mat4_f32 *T_end, float *w)
{
    return jac_run(r, q, J, T_end, 0, w);
}
