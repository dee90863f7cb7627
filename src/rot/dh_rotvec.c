/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_rotvec.c - rotation vector phi = theta k <-> rotation matrix (exp and
 * log maps): Rodrigues' formula on the angle |phi| carried to about 2^-44
 * relative, and the logarithm through the unit quaternion.
 */
#include <float.h>
#include <math.h>

#include "dhmath/rot.h"
#include "../internal/dh_mathf.h"
#include "../internal/dh_floatops.h"
#include "rot_impl.h"

/* a * a = *h + *l exactly (Dekker's product; Veltkamp's split done on the
 * bits: the high part keeps 12 significant bits, so each partial product
 * has at most 24 and is exact, fused or not). Needs a * a normal: the low
 * part of a square below 2^-102 is lost to underflow. */
static void rotvec_square2(float a, float *h, float *l)
{
    const float ah = dh_f32_from_bits(dh_f32_bits(a) & 0xFFFFF000u);
    const float al = a - ah; /* exact: the 12 low bits */
    *h = a * a;
    *l = ((ah * ah - *h) + 2.0f * ah * al) + al * al;
}

/* a + b = *s + *e exactly (Knuth's TwoSum, any order of magnitudes) */
static void rotvec_sum2(float a, float b, float *s, float *e)
{
    const float t = a + b;
    const float bb = t - a;
    *s = t;
    *e = (a - (t - bb)) + (b - bb);
}

/* |(x, y, z)| as th + tl to about 2^-44 relative: the sum of squares as an
 * unevaluated float pair, the float square root th, and the correction
 * tl = (x^2 + y^2 + z^2 - th^2) / (2 th) from the exact residual (th^2 is
 * within 2 ulp of the sum, so s - ph is exact by Sterbenz's lemma). */
static DH_NOINLINE float rotvec_norm3_2(float x, float y, float z, float *tl)
{
    float h1, l1, h2, l2, h3, l3, s1, e1, s2, e2, th, ph, pl;
    rotvec_square2(x, &h1, &l1);
    rotvec_square2(y, &h2, &l2);
    rotvec_square2(z, &h3, &l3);
    rotvec_sum2(h1, h2, &s1, &e1);
    rotvec_sum2(s1, h3, &s2, &e2);
    th = dh_sqrt_f32(s2);
    rotvec_square2(th, &ph, &pl);
    *tl = (((s2 - ph) - pl) + ((l1 + l2 + l3) + (e1 + e2))) / (2.0f * th);
    return th;
}

dh_status dh_rotvec_to_mat3_f32(const dh_vec3_f32 *phi, dh_mat3_f32 *R)
{
    float x, y, z, m, t, tl, d, u, su, cu, k[3], sh, ch;
    int scaled;
    DH_ASSERT(R != NULL && phi != NULL);
    x = phi->x;
    y = phi->y;
    z = phi->z;
    if (!dh_isfinite_f32(x) || !dh_isfinite_f32(y) || !dh_isfinite_f32(z)) return DH_ERR_NAN;
    m = fabsf(x);
    if (fabsf(y) > m) m = fabsf(y);
    if (fabsf(z) > m) m = fabsf(z);
    if (dh_feq_f32(m, 0.0f)) {
        k[0] = 0.0f;
        k[1] = 0.0f;
        k[2] = 1.0f;
        dh_rot_rodrigues_f32_(R, k, 0.0f, 1.0f, 0.0f); /* exactly I */
        return DH_OK;
    }
    /* within 2^-63 .. 2^63 the squares neither overflow nor underflow:
     * |phi| directly, else scaled by 1 / m */
    scaled = !(m >= 1.0842022e-19f && m <= 9.2233720e18f);
    if (scaled) {
        x /= m;
        y /= m;
        z /= m;
    }
    /* The angle t + tl is |phi| to about 2^-44 relative: the float |phi|
     * alone is off by up to 1.5 ulp (3.6e-7 rad just below pi), an error
     * that R inherits in full. k = phi / (t + tl), to first order. */
    t = rotvec_norm3_2(x, y, z, &tl);
    d = tl / t;
    k[0] = x / t;
    k[1] = y / t;
    k[2] = z / t;
    k[0] -= k[0] * d;
    k[1] -= k[1] * d;
    k[2] -= k[2] * d;
    if (scaled) {
        t *= m;
        tl *= m;
        if (!dh_isfinite_f32(t)) return DH_ERR_NAN;   /* |phi| > FLT_MAX */
    }
    dh_sincosf_(0.5f * t, &sh, &ch);     /* libm-free, exact reduction */
    /* (sh, ch) rotated on by u = tl / 2: to first order while u^2 / 2 is
     * below 2^-27 (|phi| up to about 2^11), else exactly (huge lengths,
     * where tl itself can be large) */
    u = 0.5f * tl;
    if (fabsf(u) <= 1.220703125e-4f) { /* 2^-13 */
        su = u;
        cu = 1.0f;
    } else {
        dh_sincosf_(u, &su, &cu);
    }
    d = sh;
    sh = sh * cu + ch * su;
    ch = ch * cu - d * su;
    dh_rot_rodrigues_f32_(R, k, 2.0f * sh * ch, 1.0f - 2.0f * sh * sh, 2.0f * sh * sh);
    return DH_OK;
}

dh_status dh_mat3_to_rotvec_f32(const dh_mat3_f32 *R, dh_vec3_f32 *phi)
{
    dh_quat_f32 q;
    float n, f;
    dh_status st;
    DH_ASSERT(R != NULL && phi != NULL);
    st = dh_mat3_to_quat_f32(R, &q); /* checks R; w >= 0 */
    if (st != DH_OK) return st;
    n = dh_sqrt_f32(q.x * q.x + q.y * q.y + q.z * q.z);
    if (dh_feq_f32(n, 0.0f)) {
        phi->x = 0.0f;
        phi->y = 0.0f;
        phi->z = 0.0f;
        return DH_OK;
    }
    f = 2.0f * dh_atan2f_(n, q.w) / n; /* t / |v| = t / sin(t/2), in [2, pi] */
    phi->x = f * q.x;
    phi->y = f * q.y;
    phi->z = f * q.z;
    return DH_OK;
}
