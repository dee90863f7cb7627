/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_quat.c - unit quaternions (w, x, y, z) <-> rotation matrices
 * (Shepperd's method for the matrix -> quaternion direction), normalisation,
 * Hamilton product, conjugate, quaternion of an angle and axis.
 */
#include <float.h>
#include <math.h>

#include "dhmath/rot.h"
#include "dhmath/trig.h"
#include "../internal/dh_floatops.h"
#include "rot_impl.h"

/* max |component|, or -1 if a component is NaN/Inf */
static float quat_maxabs(const dh_quat_f32 *q)
{
    float m;
    if (!dh_isfinite_f32(q->w) || !dh_isfinite_f32(q->x) || !dh_isfinite_f32(q->y) || !dh_isfinite_f32(q->z)) {
        return -1.0f;
    }
    m = fabsf(q->w);
    if (fabsf(q->x) > m) m = fabsf(q->x);
    if (fabsf(q->y) > m) m = fabsf(q->y);
    if (fabsf(q->z) > m) m = fabsf(q->z);
    return m;
}

/* Exact power of two bringing a largest component m into [2^-32, 2^32]. */
static float quat_prescale(float m)
{
    float f = 1.0f;
    while (m * f > 4294967296.0f) f *= 2.3283064365386963e-10f;  /* 2^-32, at most 3 times */
    while (m * f < 2.3283064365386963e-10f) f *= 4294967296.0f;  /* 2^32, at most 4 times */
    return f;
}

dh_status dh_quat_to_mat3_f32(const dh_quat_f32 *q, dh_mat3_f32 *R)
{
    float m, f, w, x, y, z, s, xx, yy, zz, xy, xz, yz, wx, wy, wz;
    DH_ASSERT(R != NULL && q != NULL);
    m = quat_maxabs(q);
    if (m < 0.0f) return DH_ERR_NAN;
    if (m < FLT_MIN) return DH_ERR_ZERO_AXIS;
    f = quat_prescale(m);
    w = q->w * f;
    x = q->x * f;
    y = q->y * f;
    z = q->z * f;
    s = 2.0f / (w * w + x * x + y * y + z * z); /* 2 / |q|^2 */
    xx = s * x * x;
    yy = s * y * y;
    zz = s * z * z;
    xy = s * x * y;
    xz = s * x * z;
    yz = s * y * z;
    wx = s * w * x;
    wy = s * w * y;
    wz = s * w * z;
    dh_rot_offdiag_f32(R, xy, xz, yz, wx, wy, wz);
    DH_M3(R, 0, 0) = 1.0f - (yy + zz);
    DH_M3(R, 1, 1) = 1.0f - (xx + zz);
    DH_M3(R, 2, 2) = 1.0f - (xx + yy);
    return DH_OK;
}

dh_status dh_mat3_to_quat_f32(const dh_mat3_f32 *R, dh_quat_f32 *q)
{
    float r00, r11, r22, t, p, f, w, x, y, z, n;
    dh_status st;
    DH_ASSERT(R != NULL && q != NULL);
    st = dh_mat3_check_rot_f32(R, DH_ROT_TOL);
    if (st != DH_OK) return st;
    r00 = DH_M3(R, 0, 0);
    r11 = DH_M3(R, 1, 1);
    r22 = DH_M3(R, 2, 2);
    t = r00 + r11 + r22;
    /* Shepperd 1978: the largest of t, r00, r11, r22 picks the component */
    if (t >= r00 && t >= r11 && t >= r22) {
        p = dh_sqrt_f32(1.0f + t);      /* 2|w| >= 1 */
        f = 0.5f / p;
        w = 0.5f * p;
        x = (DH_M3(R, 2, 1) - DH_M3(R, 1, 2)) * f;
        y = (DH_M3(R, 0, 2) - DH_M3(R, 2, 0)) * f;
        z = (DH_M3(R, 1, 0) - DH_M3(R, 0, 1)) * f;
    } else if (r00 >= r11 && r00 >= r22) {
        p = dh_sqrt_f32(1.0f + r00 - r11 - r22); /* 2|x| >= 1 */
        f = 0.5f / p;
        x = 0.5f * p;
        w = (DH_M3(R, 2, 1) - DH_M3(R, 1, 2)) * f;
        y = (DH_M3(R, 0, 1) + DH_M3(R, 1, 0)) * f;
        z = (DH_M3(R, 0, 2) + DH_M3(R, 2, 0)) * f;
    } else if (r11 >= r22) {
        p = dh_sqrt_f32(1.0f - r00 + r11 - r22);
        f = 0.5f / p;
        y = 0.5f * p;
        w = (DH_M3(R, 0, 2) - DH_M3(R, 2, 0)) * f;
        x = (DH_M3(R, 0, 1) + DH_M3(R, 1, 0)) * f;
        z = (DH_M3(R, 1, 2) + DH_M3(R, 2, 1)) * f;
    } else {
        p = dh_sqrt_f32(1.0f - r00 - r11 + r22);
        f = 0.5f / p;
        z = 0.5f * p;
        w = (DH_M3(R, 1, 0) - DH_M3(R, 0, 1)) * f;
        x = (DH_M3(R, 0, 2) + DH_M3(R, 2, 0)) * f;
        y = (DH_M3(R, 1, 2) + DH_M3(R, 2, 1)) * f;
    }
    /* normalise (largest component >= 1/2: no scaling needed) */
    n = dh_sqrt_f32(w * w + x * x + y * y + z * z);
    if (w < 0.0f) n = -n;
    q->w = w / n + 0.0f; /* + 0 turns a -0 into +0 */
    q->x = x / n;
    q->y = y / n;
    q->z = z / n;
    return DH_OK;
}

dh_status dh_quat_normalize_f32(const dh_quat_f32 *q, dh_quat_f32 *out)
{
    float m, f, w, x, y, z, n;
    DH_ASSERT(out != NULL && q != NULL);
    m = quat_maxabs(q);
    if (m < 0.0f) return DH_ERR_NAN;
    if (m < FLT_MIN) return DH_ERR_ZERO_AXIS;
    f = quat_prescale(m); /* exact: the squares can neither overflow nor underflow */
    w = q->w * f;
    x = q->x * f;
    y = q->y * f;
    z = q->z * f;
    n = dh_sqrt_f32(w * w + x * x + y * y + z * z); /* in [m f, 2 m f] */
    out->w = w / n;
    out->x = x / n;
    out->y = y / n;
    out->z = z / n;
    return DH_OK;
}

void dh_quat_mul_f32(const dh_quat_f32 *a, const dh_quat_f32 *b, dh_quat_f32 *out)
{
    float w, x, y, z;
    DH_ASSERT(out != NULL && a != NULL && b != NULL);
    w = a->w * b->w - a->x * b->x - a->y * b->y - a->z * b->z;
    x = a->w * b->x + a->x * b->w + a->y * b->z - a->z * b->y;
    y = a->w * b->y - a->x * b->z + a->y * b->w + a->z * b->x;
    z = a->w * b->z + a->x * b->y - a->y * b->x + a->z * b->w;
    out->w = w;
    out->x = x;
    out->y = y;
    out->z = z;
}

void dh_quat_conj_f32(const dh_quat_f32 *q, dh_quat_f32 *out)
{
    DH_ASSERT(out != NULL && q != NULL);
    out->w = q->w;
    out->x = -q->x;
    out->y = -q->y;
    out->z = -q->z;
}

dh_status dh_quat_from_axis_angle_f32(const dh_vec3_f32 *axis, float deg, dh_quat_f32 *q)
{
    float k[3], len, s, c;
    dh_status st;
    DH_ASSERT(q != NULL && axis != NULL);
    k[0] = axis->x;
    k[1] = axis->y;
    k[2] = axis->z;
    if (!dh_isfinite_f32(deg)) return DH_ERR_NAN;
    st = dh_axis_prescale_f32(k, &len);
    if (st != DH_OK) return st;
    st = dh_sincos_f32(0.5f * deg, &s, &c);
    if (st != DH_OK) return st;
    s /= len;
    q->w = c;
    q->x = s * k[0];
    q->y = s * k[1];
    q->z = s * k[2];
    return DH_OK;
}
