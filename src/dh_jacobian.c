/*
 * dh_jacobian.c - geometric Jacobian (base and tool frame) and the
 * orientation error a(dR) of seed 003.
 *
 * Jacobian (seed 003, "Jacobian Matrix"): for joint i with axis z_i through
 * the point o_i (both in the base frame) and the end point p_e,
 *   revolute:  column = [ z_i x (p_e - o_i) ; z_i ]   (per radian)
 *   prismatic: column = [ z_i ; 0 ]                   (per length unit)
 * The axis of joint i is z of frame i-1 for standard DH (A_i starts with
 * Rz(theta_i) Tz(d_i)) and z of frame i for modified DH (A_i ends with
 * Rz(theta_i) Tz(d_i)); the origin of that frame lies on the axis in both
 * cases. One pass over the chain: while the frames are accumulated, column
 * i temporarily holds o_i (rows 0..2) and z_i (rows 3..5); once p_e is known
 * the columns are completed in place. Stack: two 4x4 matrices.
 */
#include "dhmath/dh_kin.h"
#include "dhmath/dh_mat4.h"

#include <float.h>
#include <math.h>

static int jac_finite(float x) { return fabsf(x) <= FLT_MAX; }

/* Store the axis frame of column c: origin in rows 0..2, z in rows 3..5. */
static void jac_store_axis(float *J, uint32_t n, uint32_t c, const dh_mat4_f32 *T)
{
    uint32_t k;
    for (k = 0; k < 3u; k++) {
        J[k * n + c] = T->m[3][k];
        J[(k + 3u) * n + c] = T->m[2][k];
    }
}

dh_status dh_jacobian_f32(const dh_robot *r, const float *q, float *J, dh_mat4_f32 *T_end)
{
    dh_mat4_f32 T, A;
    uint32_t i, n, k;
    float pe[3];
    int finite = 1;

    DH_ASSERT(r != NULL);
    DH_ASSERT(q != NULL);
    DH_ASSERT(J != NULL);

    n = r->n;
    if (n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    /* float path unavailable: stale float base/tool or joints without float
     * parameters (checked here so that J stays untouched, also for n == 0) */
    if ((r->flags & DH_ROBOT_HAS_F32) == 0u) return DH_ERR_ARG;
    if (r->conv != DH_CONV_STANDARD && r->conv != DH_CONV_MODIFIED) return DH_ERR_ARG;
    for (i = 0; i < n; i++) {
        if (!jac_finite(q[i])) return DH_ERR_NAN;
        if (r->joint[i].type != DH_JOINT_REVOLUTE && r->joint[i].type != DH_JOINT_PRISMATIC)
            return DH_ERR_ARG;
    }
    T = r->base;
    for (i = 0; i < n; i++) {
        dh_status st;
        if (r->conv == DH_CONV_STANDARD) jac_store_axis(J, n, i, &T);
        st = dh_link_f32(r, i, q[i], &A);
        if (st != DH_OK) {
            /* not expected after the checks above; J is defined anyway */
            for (k = 0; k < 6u * n; k++) J[k] = 0.0f;
            return st;
        }
        dh_mat4_mul_affine_f32(&T, &T, &A);
        if (r->conv == DH_CONV_MODIFIED) jac_store_axis(J, n, i, &T);
    }
    dh_mat4_mul_affine_f32(&T, &T, &r->tool);
    for (k = 0; k < 3u; k++) pe[k] = T.m[3][k];

    for (i = 0; i < n; i++) {
        float ox = J[0u * n + i], oy = J[1u * n + i], oz = J[2u * n + i];
        float zx = J[3u * n + i], zy = J[4u * n + i], zz = J[5u * n + i];
        if (r->joint[i].type == DH_JOINT_REVOLUTE) {
            float dx = pe[0] - ox, dy = pe[1] - oy, dz = pe[2] - oz;
            J[0u * n + i] = zy * dz - zz * dy;
            J[1u * n + i] = zz * dx - zx * dz;
            J[2u * n + i] = zx * dy - zy * dx;
        } else {
            J[0u * n + i] = zx;
            J[1u * n + i] = zy;
            J[2u * n + i] = zz;
            J[3u * n + i] = 0.0f;
            J[4u * n + i] = 0.0f;
            J[5u * n + i] = 0.0f;
        }
    }
    for (k = 0; k < 6u * n; k++)
        if (!jac_finite(J[k])) finite = 0;
    if (!dh_mat4_isfinite_f32(&T)) finite = 0;
    if (T_end != NULL) *T_end = T;
    return finite ? DH_OK : DH_ERR_OVERFLOW;
}

dh_status dh_jacobian_tool_f32(const dh_robot *r, const float *q, float *J, dh_mat4_f32 *T_end)
{
    dh_mat4_f32 T;
    uint32_t n, c, h, k;
    dh_status st;

    DH_ASSERT(r != NULL);
    DH_ASSERT(q != NULL);
    DH_ASSERT(J != NULL);

    /* dh_jacobian_f32 returns DH_ERR_OVERFLOW both with T computed (a
     * non-finite result) and without it (a link that could not be formed:
     * J zero-filled, T not written). A written T always ends in 1, so a 0
     * placed there first tells the two apart; T is never used uninitialised. */
    T.m[3][3] = 0.0f;
    st = dh_jacobian_f32(r, q, J, &T);
    if (st != DH_OK && st != DH_ERR_OVERFLOW) return st;
    if (T.m[3][3] != 1.0f) return st;
    n = r->n;
    /* each half of each column: v' = R^T v (row k of R^T = column k of R) */
    for (c = 0; c < n; c++) {
        for (h = 0; h < 6u; h += 3u) {
            float vx = J[(h + 0u) * n + c], vy = J[(h + 1u) * n + c], vz = J[(h + 2u) * n + c];
            for (k = 0; k < 3u; k++)
                J[(h + k) * n + c] = T.m[k][0] * vx + T.m[k][1] * vy + T.m[k][2] * vz;
        }
    }
    if (T_end != NULL) *T_end = T;
    return st;
}

/* det of the 3x3 whose columns are c0, c1, c2: c0 . (c1 x c2) */
static float det3(const float *c0, const float *c1, const float *c2)
{
    return c0[0] * (c1[1] * c2[2] - c1[2] * c2[1]) + c0[1] * (c1[2] * c2[0] - c1[0] * c2[2]) +
           c0[2] * (c1[0] * c2[1] - c1[1] * c2[0]);
}

/* |x| <= tol for every entry of R^T R - I, and det R > 0 (a reflection is
 * orthonormal but not a rotation: its a(dR) would be meaningless). */
static int rot_is_orthonormal(const dh_mat3_f32 *R, float tol)
{
    uint32_t a, b, k;
    for (a = 0; a < 3u; a++)
        for (b = a; b < 3u; b++) {
            float s = 0.0f;
            for (k = 0; k < 3u; k++) s += R->m[a][k] * R->m[b][k];
            if (a == b) s -= 1.0f;
            if (!(fabsf(s) <= tol)) return 0;   /* NaN fails too */
        }
    return det3(R->m[0], R->m[1], R->m[2]) > 0.0f;
}

/*
 * a(dR) of seed 003 for d = dR (d[row][col]); writes w. Never fails for
 * finite input.
 */
static void rot_vec_of(float d[3][3], float w[3])
{
    float ux, uy, uz, un, tr, theta;

    /* The seed's identity case (diagonal 1, 1, 1 -> 0) is NOT tested on the
     * diagonal alone: in float the diagonal rounds to exactly 1 for angles
     * below ~3e-4 rad while the skew part still carries the rotation. The
     * identity falls out of the general case below (u = 0 -> w = 0). */
    ux = d[2][1] - d[1][2];
    uy = d[0][2] - d[2][0];
    uz = d[1][0] - d[0][1];
    un = sqrtf(ux * ux + uy * uy + uz * uz);   /* = 2 sin(theta) */
    tr = d[0][0] + d[1][1] + d[2][2] - 1.0f;   /* = 2 cos(theta) */
    theta = atan2f(un, tr);                    /* in [0, pi]: no acos domain issue */

    if (tr >= 0.0f) {
        /* theta <= 90 deg: u is accurate (seed's general case). As un -> 0,
         * theta/un -> 1/2 (atan2 keeps full relative accuracy there). */
        float f = (un > 0.0f) ? theta / un : 0.5f;
        w[0] = f * ux;
        w[1] = f * uy;
        w[2] = f * uz;
        return;
    }
    /* theta > 90 deg: u = 2 sin(theta) k loses its relative accuracy as
     * theta -> 180, so take the axis from the symmetric part, which does
     * not vanish there: (dR + dR^T)/2 = c I + (1 - c) k k^T, c = cos(theta).
     * The largest diagonal entry gives the best-conditioned component k_m;
     * the others follow from row m. The sign is the one of u (ambiguous
     * only at exactly 180 deg, where w and -w are the same rotation, and
     * there k_m > 0 is kept). The seed's diagonal special cases
     * (1,-1,-1), (-1,1,-1), (-1,-1,1) -> pi e_m are exact instances. */
    {
        float c = 0.5f * tr, omc = 1.0f - c;   /* omc in (1, 2] */
        float kv[3], km2, km, kn, s;
        uint32_t m = 0u, a;
        if (d[1][1] > d[m][m]) m = 1u;
        if (d[2][2] > d[m][m]) m = 2u;
        km2 = (d[m][m] - c) / omc;
        km = sqrtf(km2 > 0.0f ? km2 : 0.0f);
        if (!(km > 0.0f)) km = 1.0f;   /* unreachable for a rotation (km^2 >= 1/3) */
        for (a = 0; a < 3u; a++)
            kv[a] = (a == m) ? km : 0.5f * (d[a][m] + d[m][a]) / (omc * km);
        kn = sqrtf(kv[0] * kv[0] + kv[1] * kv[1] + kv[2] * kv[2]);
        s = (kv[0] * ux + kv[1] * uy + kv[2] * uz < 0.0f) ? -theta / kn : theta / kn;
        w[0] = s * kv[0];
        w[1] = s * kv[1];
        w[2] = s * kv[2];
    }
}

dh_status dh_rot_error_f32(const dh_mat3_f32 *R_target, const dh_mat3_f32 *R, dh_vec3_f32 *w)
{
    float d[3][3];          /* dR = R_target * R^T, d[row][col] */
    float v[3];
    uint32_t i, j, k;

    DH_ASSERT(R_target != NULL);
    DH_ASSERT(R != NULL);
    DH_ASSERT(w != NULL);

    for (i = 0; i < 3u; i++)
        for (j = 0; j < 3u; j++)
            if (!jac_finite(R_target->m[i][j]) || !jac_finite(R->m[i][j])) return DH_ERR_NAN;
    if (!rot_is_orthonormal(R_target, DH_ROT_ERROR_TOL) || !rot_is_orthonormal(R, DH_ROT_ERROR_TOL))
        return DH_ERR_NOT_RIGID;

    /* dR(i,j) = sum_k Rt(i,k) R(j,k); column-major: Rt(i,k) = m[k][i] */
    for (i = 0; i < 3u; i++)
        for (j = 0; j < 3u; j++) {
            float s = 0.0f;
            for (k = 0; k < 3u; k++) s += R_target->m[k][i] * R->m[k][j];
            d[i][j] = s;
        }
    rot_vec_of(d, v);
    w->x = v[0];
    w->y = v[1];
    w->z = v[2];
    return DH_OK;
}

/* Rotation part of a dh_mat4_f32 orthonormal within tol, det > 0. */
static int rot4_is_orthonormal(const dh_mat4_f32 *T, float tol)
{
    uint32_t a, b, k;
    for (a = 0; a < 3u; a++)
        for (b = a; b < 3u; b++) {
            float s = 0.0f;
            for (k = 0; k < 3u; k++) s += T->m[a][k] * T->m[b][k];
            if (a == b) s -= 1.0f;
            if (!(fabsf(s) <= tol)) return 0;
        }
    return det3(T->m[0], T->m[1], T->m[2]) > 0.0f;
}

dh_status dh_pose_error_f32(const dh_mat4_f32 *T_target, const dh_mat4_f32 *T, float e[6])
{
    float d[3][3];
    uint32_t i, j, k;

    DH_ASSERT(T_target != NULL);
    DH_ASSERT(T != NULL);
    DH_ASSERT(e != NULL);

    for (i = 0; i < 4u; i++)
        for (j = 0; j < 3u; j++)
            if (!jac_finite(T_target->m[i][j]) || !jac_finite(T->m[i][j])) return DH_ERR_NAN;
    if (!rot4_is_orthonormal(T_target, DH_ROT_ERROR_TOL) || !rot4_is_orthonormal(T, DH_ROT_ERROR_TOL))
        return DH_ERR_NOT_RIGID;
    for (i = 0; i < 3u; i++)
        for (j = 0; j < 3u; j++) {
            float s = 0.0f;
            for (k = 0; k < 3u; k++) s += T_target->m[k][i] * T->m[k][j];
            d[i][j] = s;
        }
    rot_vec_of(d, e + 3);
    for (k = 0; k < 3u; k++) e[k] = T_target->m[3][k] - T->m[3][k];
    return DH_OK;
}
