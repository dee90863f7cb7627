/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_itrig_q.c - inverse trigonometry in fixed point: atan2 of two int32
 * and asin/acos of Q2.30, results in Q16.16 degrees (contracts in
 * include/dhmath/trig.h). Integer only: no float, no libm, no division;
 * 32x32->64 products and 64-bit shifts/adds only.
 *
 * Method (vectoring CORDIC, Volder 1959, on magnitudes):
 *  1. mx = max(|x|, |y|), mn = min as uint32 (|INT32_MIN| = 2^31 exactly);
 *     both shifted left by the same amount until mx is in [2^30, 2^31]
 *     (exact: any common scale gives the same bits).
 *  2. The first-octant angle phi = atan(mn / mx) in [0, 45] deg is reduced
 *     by the rotations of atan(2^-i) deg, i = 1..29 (their sum, 54.9 deg,
 *     covers the octant; atan(2^-i) < 2 atan(2^-i-1), so after step i the
 *     remaining angle is at most atan(2^-i)). The vector (x, y) is kept as
 *     x and |y| with the sign of y apart, so every operation is on
 *     unsigned values: x += |y| >> i, |y| = ||y| - (x >> i)| (the sign of y
 *     flips when x >> i is the larger), theta +-= atan(2^-i).
 *     Range: x grows to at most the CORDIC gain prod_{i>=1} sqrt(1 + 4^-i)
 *     = 1.16444 times |(mx, mn)| <= sqrt(2) 2^31, i.e. < 3.54e9 < 2^32;
 *     |y| <= |(x, y)| as well. theta (int32, units 2^-25 deg) stays within
 *     +-54.9 deg = +-1.85e9.
 *  3. Error of the octant angle before the final rounding: each step
 *     truncates x and |y| by < 1 unit each, an angle of < sqrt(2) / 2^30
 *     rad at a radius >= 2^30 (the radius only grows), 29 steps: 3.8e-8
 *     rad; that perturbation can also enlarge the residual by as much, so
 *     2 x 3.8e-8 rad + the last residual atan(2^-29) = 1.9e-9 rad + the 29
 *     table roundings (0.5 unit of 2^-25 deg each): 4.9e-6 deg = 0.32 LSB
 *     of Q16.16. Rounded once to Q16.16 (0.5 LSB): total < 0.83 LSB, so
 *     the exact values 0 and 45 (and after the reflections 90, 135, 180)
 *     come out exact.
 *  4. The octant result is clamped to [0, 45 deg] and reflected exactly
 *     in Q16.16: 90 - phi for |y| > |x|, 180 - phi for x < 0, the sign of
 *     y last (atan2(-y, x) == -atan2(y, x) except at 180).
 * asin / acos: c = floor(sqrt(2^60 - s^2)) (s the clamped Q2.30 magnitude;
 * digit-by-digit square root, remainder < 2^32) at the scale of s, then
 * the same first-quadrant atan2: the root's error (< 1 unit at 2^30)
 * moves the angle by < 2^-30 rad = 0.004 LSB.
 */
#include "dhmath/trig.h"
#include "../internal/dh_qmath.h"

#define DH_ITRIG_Q16_45  ((uint32_t)45 << 16)
#define DH_ITRIG_Q16_90  ((uint32_t)90 << 16)
#define DH_ITRIG_Q16_180 ((uint32_t)180 << 16)
#define DH_ITRIG_Q30     0x40000000u
#define DH_ITRIG_Q30_TOL 0x40000200u   /* 1 + 2^-21 in Q2.30 */
#define DH_ITRIG_STEPS   29u

/* atan2(ay, ax) in Q16.16 degrees, [0, 90 deg], for magnitudes not both 0 */
static DH_NOINLINE uint32_t itrigq_atan2_u(uint32_t ay, uint32_t ax)
{
    /* round(atan(2^-i) * 180/pi * 2^25), i = 1..29 */
    static const uint32_t itrigq_atan_tab[DH_ITRIG_STEPS] = {
        891375203u, 470978177u, 239075877u, 120001869u, 60059434u, 30037045u,
        15019439u, 7509834u, 3754931u, 1877468u, 938734u, 469367u, 234684u,
        117342u, 58671u, 29335u, 14668u, 7334u, 3667u, 1833u, 917u, 458u, 229u,
        115u, 57u, 29u, 14u, 7u, 4u
    };
    uint32_t w = 0u, x = ax, y = ay, yneg = 0u, i, t;
    int32_t th = 0;

    if (ay > ax) {
        w = 1u;
        x = ay;
        y = ax;
    }

    /* 1. normalise: x in [2^30, 2^31] */
    if (x < 0x00008000u) { x <<= 16; y <<= 16; }
    if (x < 0x00800000u) { x <<= 8; y <<= 8; }
    if (x < 0x08000000u) { x <<= 4; y <<= 4; }
    if (x < 0x20000000u) { x <<= 2; y <<= 2; }
    if (x < 0x40000000u) { x <<= 1; y <<= 1; }

    /* 2. vectoring: drive y to 0 */
    for (i = 1u; i <= DH_ITRIG_STEPS; i++) {
        uint32_t tx = x >> i, a = itrigq_atan_tab[i - 1u];
        x += y >> i;
        th = yneg ? th - (int32_t)a : th + (int32_t)a;
        if (y >= tx) {
            y -= tx;
        } else {
            y = tx - y;
            yneg ^= 1u;
        }
    }

    /* 3. round to Q16.16 (2^9 units), clamp to the octant */
    if (th < 0) th = 0;
    t = ((uint32_t)th + 256u) >> 9;
    if (t > DH_ITRIG_Q16_45) t = DH_ITRIG_Q16_45;
    return w ? DH_ITRIG_Q16_90 - t : t;
}

/* Q16.16 magnitude <= 180 deg -> int32 with the sign neg */
static int32_t itrigq_signed(uint32_t t, uint32_t neg)
{
    return neg ? -(int32_t)t : (int32_t)t;
}

dh_status dh_atan2_q(int32_t y, int32_t x, dh_q16 *deg_q16)
{
    uint32_t ax, ay, t;

    DH_ASSERT(deg_q16 != NULL);
    ax = dh_q_abs_u32(x);
    ay = dh_q_abs_u32(y);
    if ((ax | ay) == 0u) return DH_ERR_DOMAIN;
    t = itrigq_atan2_u(ay, ax);
    if (x < 0) t = DH_ITRIG_Q16_180 - t;
    /* y < 0 next to the negative x axis: -180 is outside (-180, 180] */
    if (y < 0 && t == DH_ITRIG_Q16_180) t--;
    *deg_q16 = itrigq_signed(t, (y < 0) ? 1u : 0u);
    return DH_OK;
}

/* floor(sqrt(2^60 - a^2)) for a <= 2^30 (dh_q_isqrt62, dh_qmath.h) */
static uint32_t itrigq_cofactor(uint32_t a)
{
    return dh_q_isqrt62(((uint64_t)1 << 60) - (uint64_t)dh_q_mul64((int32_t)a, (int32_t)a));
}

/* |v| clamped to 2^30 when within 1 + 2^-21; 1 (out of domain) otherwise */
static int itrigq_unit_q(int32_t v, uint32_t *a)
{
    uint32_t m = dh_q_abs_u32(v);
    if (m > DH_ITRIG_Q30_TOL) return 1;
    *a = (m > DH_ITRIG_Q30) ? DH_ITRIG_Q30 : m;
    return 0;
}

dh_status dh_asin_q(dh_q30 s_q30, dh_q16 *deg_q16)
{
    uint32_t a;

    DH_ASSERT(deg_q16 != NULL);
    if (itrigq_unit_q(s_q30, &a) != 0) return DH_ERR_DOMAIN;
    *deg_q16 = itrigq_signed(itrigq_atan2_u(a, itrigq_cofactor(a)), (s_q30 < 0) ? 1u : 0u);
    return DH_OK;
}

dh_status dh_acos_q(dh_q30 c_q30, dh_q16 *deg_q16)
{
    uint32_t a, t;

    DH_ASSERT(deg_q16 != NULL);
    if (itrigq_unit_q(c_q30, &a) != 0) return DH_ERR_DOMAIN;
    t = itrigq_atan2_u(itrigq_cofactor(a), a);
    if (c_q30 < 0) t = DH_ITRIG_Q16_180 - t;
    *deg_q16 = (int32_t)t;
    return DH_OK;
}
