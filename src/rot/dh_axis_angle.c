/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_axis_angle.c - equivalent angle and axis of a rotation, both ways:
 * rotation matrix (3x3 or the rotation of a 4x4) -> angle and axis (Paul
 * 1981, eq. 1.72-1.103; Example 1.1, eq. 1.104-1.112) and angle and axis
 * -> rotation matrix (Rodrigues' formula, Paul 1981 eq. 1.70; FloCal,
 * "Angle Axis").
 */
#include <float.h>
#include <math.h>

#include "dhmath/rot.h"
#include "dhmath/mat4.h"
#include "dhmath/trig.h"
#include "../internal/dh_mathf.h"
#include "../internal/dh_floatops.h"
#include "rot_impl.h"

/* theta = atan2(s2, c2) in degrees for s2 >= 0: dh_atan2f_ only sees
 * angles <= 45 deg, combined as x, 90 - x or 180 - x, so 90 and 180 are
 * exact and the degree conversion errs by < 1/2 ulp of 45. */
static float axis_angle_atan2_deg(float s2, float c2)
{
    float th;
    if (c2 >= s2) {
        th = dh_atan2f_(s2, c2) * DH_RAD2DEG_F;            /* [0, 45] */
    } else if (c2 >= -s2) {
        th = 90.0f - dh_atan2f_(c2, s2) * DH_RAD2DEG_F;    /* (45, 135] */
    } else {
        th = 180.0f - dh_atan2f_(s2, -c2) * DH_RAD2DEG_F;  /* (135, 180] */
    }
    if (th < 0.0f) th = 0.0f;
    if (th > 180.0f) th = 180.0f;
    return th;
}

dh_status dh_mat4_to_axis_angle_f32(const dh_mat4_f32 *T, dh_vec3_f32 *k, float *theta_deg)
{
    float nx, ny, nz, ox, oy, oz, ax, ay, az, dx, dy, dz, c2, s2, th, x, y, z, m, len;
    dh_status st;
    DH_ASSERT(T != NULL && k != NULL && theta_deg != NULL);
    st = dh_mat4_check_rot_f32(T, DH_MAT4_AXIS_TOL);
    if (st != DH_OK) return st;
    nx = T->m[0][0]; ny = T->m[0][1]; nz = T->m[0][2];
    ox = T->m[1][0]; oy = T->m[1][1]; oz = T->m[1][2];
    ax = T->m[2][0]; ay = T->m[2][1]; az = T->m[2][2];

    dx = oz - ay;               /* 2 kx sin(theta), eq. 1.77 */
    dy = ax - nz;               /* 2 ky sin(theta), eq. 1.78 */
    dz = ny - ox;               /* 2 kz sin(theta), eq. 1.79 */
    c2 = nx + oy + az - 1.0f;   /* 2 cos(theta), eq. 1.76 */
    s2 = dh_sqrtf_(dx * dx + dy * dy + dz * dz); /* 2 sin(theta), eq. 1.81; |d| <= ~2 */
    th = axis_angle_atan2_deg(s2, c2);

    if (c2 >= 0.0f) {
        /* theta <= 90: k = d / |d| (eq. 1.83-1.85), d scaled by its largest
         * component first (tiny angles do not underflow) */
        m = fabsf(dx);
        if (fabsf(dy) > m) m = fabsf(dy);
        if (fabsf(dz) > m) m = fabsf(dz);
        if (dh_feq_f32(m, 0.0f)) {
            /* no rotation: the axis is arbitrary, documented as +z */
            k->x = 0.0f;
            k->y = 0.0f;
            k->z = 1.0f;
            *theta_deg = 0.0f;
            return DH_OK;
        }
        x = dx / m;
        y = dy / m;
        z = dz / m;
    } else {
        /* theta > 90 (eq. 1.92-1.103 without the divisions): w = (2 diag_i -
         * c2, pair sums) = 2 k_i vers(theta) k is parallel to k with the sign
         * of k_i, i.e. of d_i (sgn(0) = +1); |w| >= 2/sqrt(3). */
        float sg;
        if (nx >= oy && nx >= az) {
            x = 2.0f * nx - c2;
            y = ny + ox;
            z = nz + ax;
            sg = dx;
        } else if (oy >= az) {
            x = ny + ox;
            y = 2.0f * oy - c2;
            z = oz + ay;
            sg = dy;
        } else {
            x = nz + ax;
            y = oz + ay;
            z = 2.0f * az - c2;
            sg = dz;
        }
        if (sg < 0.0f) {
            x = -x;
            y = -y;
            z = -z;
        }
    }
    len = dh_sqrtf_(x * x + y * y + z * z);
    k->x = x / len;
    k->y = y / len;
    k->z = z / len;
    *theta_deg = th;
    return DH_OK;
}

dh_status dh_axis_angle_to_mat3_f32(const dh_vec3_f32 *axis, float deg, dh_mat3_f32 *R)
{
    float k[3], len, s, c;
    dh_status st;
    DH_ASSERT(R != NULL && axis != NULL);
    if (!dh_isfinite_f32(deg)) return DH_ERR_NAN;
    k[0] = axis->x;
    k[1] = axis->y;
    k[2] = axis->z;
    st = dh_axis_prescale_f32(k, &len);
    if (st != DH_OK) return st;
    st = dh_sincos_f32(deg, &s, &c);
    if (st != DH_OK) return st;
    k[0] /= len;
    k[1] /= len;
    k[2] /= len;
    dh_rot_rodrigues_f32_(R, k, s, c, 1.0f - c);
    return DH_OK;
}

/* Checks R and copies it into T with zero translation (T untouched on
 * error); out of line: only the 4x4 stays in the caller's frame. */
static DH_NOINLINE dh_status axis_angle_to_mat4(dh_mat4_f32 *T, const dh_mat3_f32 *R)
{
    int c, r;
    const dh_status st = dh_mat3_check_rot_f32(R, DH_ROT_TOL); /* DH_ERR_NAN or DH_ERR_NOT_RIGID */
    if (st != DH_OK) return st;
    for (c = 0; c < 3; c++) {
        for (r = 0; r < 3; r++) T->m[c][r] = R->m[c][r];
        T->m[c][3] = 0.0f;
        T->m[3][c] = 0.0f;
    }
    T->m[3][3] = 1.0f;
    return DH_OK;
}

dh_status dh_mat3_to_axis_angle_f32(const dh_mat3_f32 *R, dh_vec3_f32 *axis, float *deg)
{
    /* the 4x4 version's algorithm: bitwise the same answer */
    dh_mat4_f32 T;
    dh_status st;
    DH_ASSERT(R != NULL && axis != NULL && deg != NULL);
    st = axis_angle_to_mat4(&T, R);
    if (st != DH_OK) return st;
    return dh_mat4_to_axis_angle_f32(&T, axis, deg);
}
