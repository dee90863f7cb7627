/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_path_q.c - fixed-point Cartesian paths (line, circular arc through a
 * via point) between two fixed frames and their time-optimal trapezoidal
 * moves, the twins of dh_path.c. Integer only: no float, no libm, no
 * 64-bit division (32x32->64 products, bit-serial quotients).
 *
 * Orientation: the slerp of the unit quaternions of R_A and R_B along the
 * shorter arc (as dh_pose_interp_q), qa (cos s h, sin s h k) with the axis
 * k and half angle h of qa* qb found once, when the path is made: an
 * evaluation is one dh_sincos_q, one quaternion product and the unit
 * quaternion's matrix (no normalisation, no atan2), from qb for s > 1/2.
 * Line: p_A + round(s (p_B - p_A) / 2^30) from the nearer end
 * (dh_motion_lerp_q_): within 0.5 LSB of the exact line.
 *
 * Arc. With a = via - p_A and b = p_B - p_A (exact integers; every side of
 * the triangle below 2^30 LSB), e1 = b / |b| and the unit normal
 * n = (a x b) / |a x b| are integer normalisations (the cross product is
 * exact in 64 bits), e2 = e1 x n (each component one rounding). In the
 * plane (e1, e2) the points are p_A = (0, 0), p_B = (L, 0) with L = |b|,
 * and via = (x, y), x = a . e1, y = a . e2 > 0. The circumcentre is
 * (L / 2, yc), yc = (x (x - L) + y^2) / (2 y) (an exact 64-bit numerator,
 * one bit-serial quotient), the radius R = sqrt(L^2 / 4 + yc^2) and the
 * half sweep h = atan2(L / 2, -yc) in (0, 180) degrees: dh_atan2_q,
 * refined by one Newton step, h + (L cos h + 2 yc sin h) / (2 R) (the
 * residual of the rounded angle, exact products), to 2^-23 degrees.
 * The arc runs from p_A over via (y > 0) to p_B, clockwise in (e1, e2).
 * Relative to its ends:
 *   p(phi) = p_A + (cos phi - 1) u0 + sin phi w0,  phi = s sweep, s <= 1/2
 *   p(psi) = p_B + (cos psi - 1) u1 - sin psi w1,  psi = (1 - s) sweep,
 * u0 = p_A - c = -(L/2) e1 - yc e2, w0 = -yc e1 + (L/2) e2 (u0 turned a
 * quarter along the motion), u1 = p_B - c = (L/2) e1 - yc e2,
 * w1 = -yc e1 - (L/2) e2, each component one rounding of an exact 64-bit
 * sum. The angle phi is s times the sweep held to 2^-23 degrees (a 62-bit
 * product): its Q16.16 part goes to dh_sincos_q and the rest d (below
 * 2^-16 degrees, 2.7e-7 rad) is added to first order, sin + d cos and
 * cos - d sin (the second order d^2 / 2 is below 4e-14), so the point
 * moves smoothly with s instead of in steps of 2^-16 degrees.
 * The thin-triangle test of the float twin, |a x b| > 2^-10 M^2 with M
 * the longest side, is y L > M^2 / 1024 here; the radius must be below
 * 2^30 LSB.
 *
 * A move scales s by one trapezoid (dh_profile_trap_q) of the distance
 * D = 2^e LSB, s = position 2^(30 - e) (Q2.30, exact), with the rates of
 * s of the float twin (dh_path.c: s' <= V / length and wmax / angle,
 * s'' <= At / length and wdmax / angle; on an arc V = min(vmax,
 * sqrt(amax R / sqrt 2)), At = amax sqrt(1 - (V^2 / (amax R))^2)), each
 * a quotient num / den of integers; e is the largest exponent <= 30 for
 * which both rates times 2^e fit int32, and each rate is floor(num 2^e /
 * den) (bit-serial): below the float rate, never above. So the rates of s
 * do not meet the 32767 units/s^k cap of the fixed profiles for any
 * speed; the position resolution of s is 2^-e of the path.
 *
 * A jerk-limited move (dh_path_move_jerk_q) plans the seven-phase profile
 * instead, with a third rate s''' <= min(Jt / length, wjmax / angle). On
 * a line Jt = jmax; on an arc the float twin's split of the TOTAL jerk:
 * V also <= cbrt(jmax R^2 / 4) (the largest integer v with
 * 4 v^3 <= jmax R^2, compared as 96-bit products), At from that V and
 * then <= floor(jmax R / (12 V)), Jt = floor(jmax / 2), so
 * |x'''| + x'^3 / R^2 + 3 x' |x''| / R <= jmax / 2 + jmax / 4 + jmax / 4
 * for the rounded V and At (docs/design.md, "Paths and moves, fixed
 * point").
 */
#include <string.h>

#include "dhmath/motion.h"
#include "dhmath/trig.h"
#include "../rot/rot_impl.h"
#include "../internal/dh_qmath.h"
#include "motion_impl.h"

/* 2^30: the largest side, radius and coordinate of an arc (LSB) */
#define PATHQ_LIM 0x40000000LL
/* 180/pi 2^23 / 2^30 in Q20 (180/pi 2^13): the Newton step of the half sweep */
#define PATHQ_RAD2DEG7 469367
/* pi/180 in Q31 (2^31 pi / 180 = 37480660.6): lengths of arcs */
#define PATHQ_DEG2RAD31 37480660
/* pi/180 / 2^16 in Q40 (2^24 pi / 180 = 292818.9): the first-order term */
#define PATHQ_LSB2RAD40 292818
/* 2^-1/4 in Q30, rounded down, less 2^-27 (dh_q_sqrt_u64's error) */
#define PATHQ_R4SQRT2 902905642

/* ---- integer helpers ---------------------------------------------------- */

/* floor(n / d) for d > 0 and n / d < 2^32: one quotient bit per step, the
 * remainder below 2 d in 64 bits (d < 2^62). No division. */
static DH_NOINLINE uint32_t pathq_udiv64(uint64_t n, uint64_t d)
{
    uint64_t r = n;
    uint32_t q = 0u;
    int k;
    for (k = 31; k >= 0; k--) {
        if ((r >> (unsigned)k) >= d) {
            r -= d << (unsigned)k;
            q |= 1u << (unsigned)k;
        }
    }
    return q;
}

/* round(n / d) for d > 0 and |n / d| < 2^31 (signed n) */
static int32_t pathq_sdiv64(int64_t n, uint64_t d)
{
    const uint64_t un = (n < 0) ? 0u - (uint64_t)n : (uint64_t)n;
    const uint32_t q = pathq_udiv64(un + (d >> 1), d);
    return (n < 0) ? -(int32_t)q : (int32_t)q;
}

/* floor(sqrt(v)) for v < 2^64 (within 1 LSB above 2^62) */
static uint32_t pathq_isqrt64(uint64_t v)
{
    if (v < ((uint64_t)1 << 62)) return dh_q_isqrt62(v);
    return dh_q_isqrt62(v >> 2) << 1;
}

/* v (len 3 or 4 components, not all 0) normalised to a unit vector in
 * Q2.30 in u, v overwritten by the magnitudes: the components shifted
 * (exact to the left, rounded to the right: below 2^-30 of the largest) so
 * that the largest lies in [2^29, 2^30), the norm an integer square root
 * of the exact sum of squares, each component round(c 2^30 / norm). 0 when
 * v is 0 (in place: the callers' frames stay small, the 256 B guard). */
static DH_NOINLINE int pathq_unit(int64_t *v, unsigned len, dh_q30 *u)
{
    uint64_t mx = 0u, s = 0u;
    uint32_t nrm;
    unsigned k, sh = 0u;
    for (k = 0; k < len; k++) {
        u[k] = (v[k] < 0) ? -1 : 1;
        v[k] = (v[k] < 0) ? (int64_t)(0u - (uint64_t)v[k]) : v[k];
        if ((uint64_t)v[k] > mx) mx = (uint64_t)v[k];
    }
    if (mx == 0u) return 0;
    while ((mx >> sh) >= 0x40000000u) sh++;
    mx = 0u;
    for (k = 0; k < len; k++) {
        uint64_t m = (uint64_t)v[k];
        if (sh != 0u) {
            const unsigned h = sh - 1u;
            m = (m + ((uint64_t)1 << h)) >> sh;
        }
        if (m > 0x3FFFFFFFu) m = 0x3FFFFFFFu;
        v[k] = (int64_t)m;
        if (m > mx) mx = m;
    }
    for (sh = 0u; (mx << sh) < 0x20000000u; sh++) {
    }
    for (k = 0; k < len; k++) {
        v[k] <<= sh;
        s += (uint64_t)v[k] * (uint64_t)v[k];
    }
    nrm = dh_q_isqrt62(s);
    for (k = 0; k < len; k++) u[k] *= (int32_t)dh_q_udiv((uint32_t)v[k], nrm, 30u);
    return 1;
}

/* ---- paths -------------------------------------------------------------- */

/* 1 when p holds a path: a kind and unit quaternions within a factor 2 (an
 * all-zero struct holds none) */
static int pathq_ok(const dh_path_q *p)
{
    const dh_quat_q *a = &p->qa, *b = &p->qb;
    const int64_t lo = (int64_t)1 << 59, hi = (int64_t)1 << 61;
    const int64_t na = dh_q_mul64(a->w, a->w) + dh_q_mul64(a->x, a->x) + dh_q_mul64(a->y, a->y) + dh_q_mul64(a->z, a->z);
    const int64_t nb = dh_q_mul64(b->w, b->w) + dh_q_mul64(b->x, b->x) + dh_q_mul64(b->y, b->y) + dh_q_mul64(b->z, b->z);
    if (p->kind != (uint32_t)DH_PATH_LINE && p->kind != (uint32_t)DH_PATH_ARC) return 0;
    return na > lo && na < hi && nb > lo && nb < hi;
}

/* dh_motion_path_ok_q_ (motion_impl.h) */
int dh_motion_path_ok_q_(const dh_path_q *p)
{
    return pathq_ok(p);
}

/* Component c (0: w, 1..3: x, y, z) of r = qa* qb, exact in 64 bits: the
 * axis and half angle of the path's rotation (pathq_axis, pathq_half) */
static int64_t pathq_rv(const dh_path_q *p, unsigned c)
{
    const dh_quat_q *a = &p->qa, *b = &p->qb;
    if (c == 0u)
        return dh_q_mul64(a->w, b->w) + dh_q_mul64(a->x, b->x) + dh_q_mul64(a->y, b->y) + dh_q_mul64(a->z, b->z);
    if (c == 1u)
        return dh_q_mul64(a->w, b->x) - dh_q_mul64(b->w, a->x) - dh_q_mul64(a->y, b->z) + dh_q_mul64(a->z, b->y);
    if (c == 2u)
        return dh_q_mul64(a->w, b->y) - dh_q_mul64(b->w, a->y) - dh_q_mul64(a->z, b->x) + dh_q_mul64(a->x, b->z);
    return dh_q_mul64(a->w, b->z) - dh_q_mul64(b->w, a->z) - dh_q_mul64(a->x, b->y) + dh_q_mul64(a->y, b->x);
}

/* The half angle h of r = qa* qb (qa . qb >= 0): atan2(|v|, w) of its
 * parts rounded to Q2.30 (dh_atan2_q, in [0, 90] degrees); 0 when v
 * rounds to 0 (no rotation to 2^-30) */
static DH_NOINLINE void pathq_half(dh_path_q *p)
{
    const int32_t w = (int32_t)dh_q_rshr(pathq_rv(p, 0u), 30u);
    uint64_t s = 0u;
    uint32_t n;
    unsigned c;
    for (c = 1u; c <= 3u; c++) {
        const int32_t x = (int32_t)dh_q_rshr(pathq_rv(p, c), 30u);
        s += (uint64_t)dh_q_mul64(x, x);
    }
    n = dh_q_isqrt62(s);
    p->h = 0;
    if (n != 0u) (void)dh_atan2_q((int32_t)n, (w < 0) ? 0 : w, &p->h);
}

/* The unit axis k of r = qa* qb: its vector part exact in 64 bits,
 * normalised (0 without rotation) */
static DH_NOINLINE void pathq_axis(dh_path_q *p)
{
    int64_t v[3];
    unsigned c;
    for (c = 0u; c < 3u; c++) {
        v[c] = pathq_rv(p, c + 1u);
        p->k[c] = 0;
    }
    if (!pathq_unit(v, 3u, p->k))
        for (c = 0u; c < 3u; c++) p->k[c] = 0;
}

/* q (from dh_frame_to_quat_q) normalised in place by pathq_unit */
static DH_NOINLINE void pathq_quat(dh_quat_q *q)
{
    int64_t v[4];
    dh_q30 u[4];
    v[0] = q->w;
    v[1] = q->x;
    v[2] = q->y;
    v[3] = q->z;
    if (!pathq_unit(v, 4u, u)) return;
    q->w = u[0];
    q->x = u[1];
    q->y = u[2];
    q->z = u[3];
}

/* p's ends, their unit quaternions (pathq_quat, made by the caller: one
 * call level less) on the shorter arc, the axis and half angle between
 * them, angle and kind */
static DH_NOINLINE void pathq_finish(dh_path_q *p, const dh_frame_q *A, const dh_frame_q *B, dh_q16 deg,
                                     dh_path_kind kind)
{
    unsigned k;
    dh_motion_shorter_q_(&p->qa, &p->qb);
    pathq_half(p);
    pathq_axis(p);
    if (p->h == 0)
        for (k = 0; k < 3u; k++) p->k[k] = 0;
    p->A = *A;
    p->B = *B;
    p->angle = deg;
    p->kind = (uint32_t)kind;
}

/* The checks of both paths: rotations accepted (DH_ERR_NOT_RIGID) */
static dh_status pathq_check(const dh_frame_q *A, const dh_frame_q *B)
{
    if (!dh_rot_ok_q_(A, DH_ROT_TOL_Q) || !dh_rot_ok_q_(B, DH_ROT_TOL_Q)) return DH_ERR_NOT_RIGID;
    return DH_OK;
}

/* |p_B - p_A| into *len (floor of the root); DH_ERR_OVERFLOW when a
 * component or the length does not fit int32 */
static DH_NOINLINE dh_status pathq_line_len(const dh_frame_q *A, const dh_frame_q *B, int32_t *len)
{
    uint64_t s = 0u;
    uint32_t l;
    unsigned i;
    for (i = 0; i < 3u; i++) {
        const int64_t d = (int64_t)B->p[i] - A->p[i];
        if (d > INT32_MAX || d < -INT32_MAX) return DH_ERR_OVERFLOW;
        s += (uint64_t)(d * d);
    }
    l = pathq_isqrt64(s);
    if (l > (uint32_t)INT32_MAX) return DH_ERR_OVERFLOW;
    *len = (int32_t)l;
    return DH_OK;
}

dh_status dh_path_line_q(dh_path_q *p, const dh_frame_q *A, const dh_frame_q *B)
{
    int32_t len = 0;
    dh_q16 deg = 0;
    dh_status st;
    DH_ASSERT(p != NULL && A != NULL && B != NULL);
    st = pathq_check(A, B);
    if (st == DH_OK) st = pathq_line_len(A, B, &len);
    if (st != DH_OK) return st;
    (void)dh_pose_angle_q(A, B, &deg);
    (void)memset(p, 0, sizeof *p);
    p->length = (dh_qpos)len;
    /* accepted frames: the conversions cannot fail */
    (void)dh_frame_to_quat_q(A, &p->qa);
    (void)dh_frame_to_quat_q(B, &p->qb);
    pathq_quat(&p->qa);
    pathq_quat(&p->qb);
    pathq_finish(p, A, B, deg, DH_PATH_LINE);
    return DH_OK;
}

/* Planning an arc uses the output path as its scratch (no copy on the
 * stack: the 256 B guard), all overwritten by the circle or zeroed on
 * error: a = via - p_A in u0, b = p_B - p_A in u1, e1 in w0, e2 in w1,
 * the plane's x, y, L in k, yc in h. */

/* the squares of |b| (*lb) and of the longest side (returned), from a, b */
static uint64_t pathq_sides(const dh_path_q *p, uint64_t *lb)
{
    uint64_t la = 0u, lc = 0u;
    unsigned k;
    *lb = 0u;
    for (k = 0; k < 3u; k++) {
        const int64_t c = (int64_t)p->u1[k] - p->u0[k];
        la += (uint64_t)dh_q_mul64(p->u0[k], p->u0[k]);
        *lb += (uint64_t)dh_q_mul64(p->u1[k], p->u1[k]);
        lc += (uint64_t)(c * c);
    }
    return (la > *lb) ? ((la > lc) ? la : lc) : ((*lb > lc) ? *lb : lc);
}

/* The plane of the arc: e1 = b / |b|, e2 = e1 x n (n the unit normal of
 * a x b, exact in 64 bits). DH_ERR_SINGULAR for collinear or coincident
 * points. */
static DH_NOINLINE dh_status pathq_plane(dh_path_q *p)
{
    const int32_t *a = p->u0, *b = p->u1;
    int64_t v[3];
    dh_q30 n[3];
    unsigned k;
    v[0] = dh_q_mul64(a[1], b[2]) - dh_q_mul64(a[2], b[1]);
    v[1] = dh_q_mul64(a[2], b[0]) - dh_q_mul64(a[0], b[2]);
    v[2] = dh_q_mul64(a[0], b[1]) - dh_q_mul64(a[1], b[0]);
    if (!pathq_unit(v, 3u, n)) return DH_ERR_SINGULAR;
    for (k = 0; k < 3u; k++) v[k] = b[k];
    if (!pathq_unit(v, 3u, p->w0)) return DH_ERR_SINGULAR;
    p->w1[0] = (dh_q30)dh_q_rshr(dh_q_mul64(p->w0[1], n[2]) - dh_q_mul64(p->w0[2], n[1]), 30u);
    p->w1[1] = (dh_q30)dh_q_rshr(dh_q_mul64(p->w0[2], n[0]) - dh_q_mul64(p->w0[0], n[2]), 30u);
    p->w1[2] = (dh_q30)dh_q_rshr(dh_q_mul64(p->w0[0], n[1]) - dh_q_mul64(p->w0[1], n[0]), 30u);
    return DH_OK;
}

/* The triangle in the plane at the scale 2^f (f fraction bits below the
 * LSB), lb = |b|^2 and M2 the longest side squared: x = a . e1,
 * y = a . e2, L = |b| into k, yc into h. DH_ERR_SINGULAR
 * for a thin triangle; 1 in *big when |yc| reaches 2^30 at this scale. */
static DH_NOINLINE dh_status pathq_tri(dh_path_q *p, unsigned f, uint64_t lb, uint64_t M2, int *big)
{
    const int32_t *a = p->u0;
    const dh_q30 *e1 = p->w0, *e2 = p->w1;
    int32_t *xyl = p->k;
    const unsigned sh = 30u - f, f2 = 2u * f;
    int64_t num;
    *big = 0;
    xyl[0] = (int32_t)dh_q_rshr(dh_q_mul64(a[0], e1[0]) + dh_q_mul64(a[1], e1[1]) + dh_q_mul64(a[2], e1[2]), sh);
    xyl[1] = (int32_t)dh_q_rshr(dh_q_mul64(a[0], e2[0]) + dh_q_mul64(a[1], e2[1]) + dh_q_mul64(a[2], e2[2]), sh);
    xyl[2] = (int32_t)dh_q_isqrt62(lb << f2);
    /* y L (twice the area) against M^2 / 1024, both at the scale 2^2f */
    if (xyl[1] <= 0 || (uint64_t)dh_q_mul64(xyl[1], xyl[2]) <= ((M2 << f2) >> 10)) return DH_ERR_SINGULAR;
    /* yc = (x (x - L) + y^2) / (2 y): |x|, y, L < 2^30, |x - L| < 2^31 */
    num = dh_q_mul64(xyl[0], (int32_t)((int64_t)xyl[0] - xyl[2])) + dh_q_mul64(xyl[1], xyl[1]);
    if ((num < 0 ? -num : num) >= (int64_t)xyl[1] * 2 * (PATHQ_LIM - 1)) {
        *big = 1;
        return DH_OK;
    }
    p->h = pathq_sdiv64(num, (uint64_t)xyl[1] * 2u);
    return DH_OK;
}

/* The circle's radius, sweep and length at the scale 2^f from L and yc
 * (the plane's scratch in k[2], h) into p */
static DH_NOINLINE dh_status pathq_sweep(dh_path_q *p, unsigned f)
{
    const int32_t L = p->k[2], yc = p->h;
    int32_t sn, cs, d;
    int64_t hx;
    uint32_t R, Rf, sw;
    uint64_t X;
    dh_q16 h = 0;
    Rf = dh_q_isqrt62(((uint64_t)dh_q_mul64(L, L) + 4u * (uint64_t)dh_q_mul64(yc, yc)) >> 2);
    R = (uint32_t)(((uint64_t)Rf + ((uint64_t)1 << f >> 1)) >> f);
    if (R >= (uint32_t)PATHQ_LIM || R == 0u) return DH_ERR_OVERFLOW;
    /* half sweep: atan2(L, -2 yc), one Newton step to 2^-23 degrees */
    (void)dh_atan2_q(L, -2 * yc, &h);
    dh_sincos_q(h, &sn, &cs);
    hx = dh_q_mul64(L, cs) + 2 * dh_q_mul64(yc, sn);   /* 2 R delta 2^30 (delta in rad) */
    if (hx > ((int64_t)1 << 41)) hx = (int64_t)1 << 41;
    if (hx < -((int64_t)1 << 41)) hx = -((int64_t)1 << 41);
    d = pathq_sdiv64(hx * PATHQ_RAD2DEG7, ((uint64_t)Rf * 2u) << 20);   /* delta, 2^-23 deg */
    if (d > 4096) d = 4096;
    if (d < -4096) d = -4096;
    sw = 2u * (uint32_t)((int64_t)h * 128 + d);
    /* length = R sweep pi/180 (sweep in 2^-23 degrees), below 2^31 */
    X = (uint64_t)R * sw;
    X = ((X >> 31) * PATHQ_DEG2RAD31 + ((((X & 0x7FFFFFFFu) * PATHQ_DEG2RAD31) >> 31)) + ((uint64_t)1 << 22)) >> 23;
    if (X > (uint64_t)INT32_MAX) return DH_ERR_OVERFLOW;
    p->radius = (dh_qpos)R;
    p->sw = sw;
    p->sweep = (dh_q16)((sw + 64u) >> 7);
    p->length = (dh_qpos)X;
    return DH_OK;
}

/* u0, w0, u1, w1 at the scale 2^f from the plane (e1 in w0, e2 in w1, each
 * index read before it is overwritten) and L, yc; DH_ERR_OVERFLOW when the
 * circle (centre +- R, with room for rounding) leaves int32 */
static DH_NOINLINE dh_status pathq_vectors(dh_path_q *p, const dh_frame_q *A, unsigned f)
{
    const int32_t L = p->k[2], yc = p->h;
    const int64_t R = p->radius;
    unsigned k;
    for (k = 0; k < 3u; k++) {
        const int64_t he = dh_q_mul64(L, p->w0[k]), ye = 2 * dh_q_mul64(yc, p->w1[k]);
        const int64_t hf = dh_q_mul64(L, p->w1[k]), yf = 2 * dh_q_mul64(yc, p->w0[k]);
        int64_t c;
        p->u0[k] = (dh_qpos)dh_q_rshr(-he - ye, 31u + f);
        p->u1[k] = (dh_qpos)dh_q_rshr(he - ye, 31u + f);
        p->w0[k] = (dh_qpos)dh_q_rshr(hf - yf, 31u + f);
        p->w1[k] = (dh_qpos)dh_q_rshr(-hf - yf, 31u + f);
        c = (int64_t)A->p[k] - p->u0[k];
        if (c + R + 64 > INT32_MAX || c - R - 64 < INT32_MIN) return DH_ERR_OVERFLOW;
    }
    return DH_OK;
}

/* a = via - p_A into u0, b = p_B - p_A into u1: DH_ERR_OVERFLOW for a
 * side of 2^30 LSB or more */
static DH_NOINLINE dh_status pathq_arc_init(dh_path_q *p, const dh_frame_q *A, const dh_qpos via[3],
                                            const dh_frame_q *B)
{
    uint64_t lb;
    unsigned k;
    for (k = 0; k < 3u; k++) {
        const int64_t da = (int64_t)via[k] - A->p[k], db = (int64_t)B->p[k] - A->p[k];
        if (da >= PATHQ_LIM || da <= -PATHQ_LIM || db >= PATHQ_LIM || db <= -PATHQ_LIM) return DH_ERR_OVERFLOW;
        p->u0[k] = (int32_t)da;
        p->u1[k] = (int32_t)db;
    }
    return (pathq_sides(p, &lb) >= (uint64_t)1 << 60) ? DH_ERR_OVERFLOW : DH_OK;
}

/* The triangle's coordinates at the finest scale 2^-f LSB at which they
 * and yc stay below 2^30 (f <= 29: their rounding does not grow with the
 * conditioning of the circle, a via point near an end), by pathq_tri */
static DH_NOINLINE dh_status pathq_arc_fit(dh_path_q *p, unsigned *f)
{
    uint64_t lb;
    const uint64_t M2 = pathq_sides(p, &lb);
    dh_status st;
    int big = 1;
    for (*f = 0u; *f < 29u && (M2 << (2u * *f + 2u)) < ((uint64_t)1 << 60); (*f)++) {
    }
    for (;;) {
        st = pathq_tri(p, *f, lb, M2, &big);
        if (st != DH_OK || big == 0) return st;
        if (*f == 0u) return DH_ERR_OVERFLOW;   /* the radius reaches 2^30 LSB */
        (*f)--;
    }
}

/* on error p holds no path (all zero): its fields were the planning's
 * scratch (pathq_arc_init, pathq_plane, pathq_arc_fit, pathq_sweep and
 * pathq_vectors one after the other, one call level each) */
dh_status dh_path_arc_q(dh_path_q *p, const dh_frame_q *A, const dh_qpos via[3], const dh_frame_q *B)
{
    dh_q16 deg = 0;
    dh_status st;
    unsigned f = 0u;
    DH_ASSERT(p != NULL && A != NULL && via != NULL && B != NULL);
    (void)memset(p, 0, sizeof *p);
    st = pathq_check(A, B);
    if (st == DH_OK) st = pathq_arc_init(p, A, via, B);
    if (st == DH_OK) st = pathq_plane(p);
    if (st == DH_OK) st = pathq_arc_fit(p, &f);
    if (st == DH_OK) st = pathq_sweep(p, f);
    if (st == DH_OK) st = pathq_vectors(p, A, f);
    if (st != DH_OK) {
        (void)memset(p, 0, sizeof *p);
        return st;
    }
    p->k[0] = 0;
    p->k[1] = 0;
    p->k[2] = 0;
    p->h = 0;
    (void)dh_pose_angle_q(A, B, &deg);
    (void)dh_frame_to_quat_q(A, &p->qa);
    (void)dh_frame_to_quat_q(B, &p->qb);
    pathq_quat(&p->qa);
    pathq_quat(&p->qb);
    pathq_finish(p, A, B, deg, DH_PATH_ARC);
    return DH_OK;
}

/* dh_motion_point_q_ (motion_impl.h): a line's dh_motion_lerp_q_ (and
 * an arc's ends, exact), else the arc's point from the nearer end */
DH_NOINLINE void dh_motion_point_q_(const dh_path_q *p, dh_q30 s, dh_qpos pos[3])
{
    const int back = s > (DH_Q30_ONE / 2);
    const dh_frame_q *E = back ? &p->B : &p->A;
    const dh_qpos *u = back ? p->u1 : p->u0, *w = back ? p->w1 : p->w0;
    const uint32_t f = (uint32_t)(back ? DH_Q30_ONE - s : s);   /* <= 2^29 */
    const uint64_t phi = (uint64_t)f * p->sw;                    /* 2^-53 degrees, < 2^61 */
    int32_t sn, cs, dl;
    int64_t cm;
    unsigned k;
    if (p->kind != (uint32_t)DH_PATH_ARC || s <= 0 || s >= DH_Q30_ONE) {
        for (k = 0; k < 3u; k++) pos[k] = dh_motion_lerp_q_(p->A.p[k], p->B.p[k], (s < 0) ? 0 : ((s > DH_Q30_ONE) ? DH_Q30_ONE : s));
        return;
    }
    dh_sincos_q((dh_q16)(phi >> 37), &sn, &cs);
    /* the rest of phi below 2^-16 degrees, to first order (file comment) */
    dl = (int32_t)((phi & (((uint64_t)1 << 37) - 1u)) >> 7);   /* 2^-46 degrees, < 2^30 */
    {
        const int32_t ds = (int32_t)dh_q_rshr(dh_q_rshr(dh_q_mul64(cs, dl), 30u) * PATHQ_LSB2RAD40, 40u);
        const int32_t dc = (int32_t)dh_q_rshr(dh_q_rshr(dh_q_mul64(sn, dl), 30u) * PATHQ_LSB2RAD40, 40u);
        sn += ds;
        cm = (int64_t)cs - dc - DH_Q30_ONE;
    }
    if (back) sn = -sn;
    for (k = 0; k < 3u; k++)
        pos[k] = (dh_qpos)((int64_t)E->p[k] + dh_q_rshr(cm * u[k] + dh_q_mul64(sn, w[k]), 30u));
}

/* T's rotation at 0 < s < 2^30: e (cos f h, +-sin f h k) from the nearer
 * end e (qa, or qb backwards with f = 1 - s), the quaternion product
 * rounded once per component and turned into a matrix by the unit
 * quaternion's formula (both factors unit within a few LSB, so no
 * normalisation: the entries move by a few 2^-30) */
static DH_NOINLINE void pathq_rot(const dh_path_q *p, dh_q30 s, dh_frame_q *T)
{
    const int back = s > (DH_Q30_ONE / 2);
    const int32_t f = back ? DH_Q30_ONE - s : s;
    int32_t sn, cs;
    dh_quat_q q;
    dh_sincos_q((dh_q16)dh_q_rshr(dh_q_mul64(f, p->h), 30u), &sn, &cs);
    dh_motion_turn_q_(back ? &p->qb : &p->qa, cs, back ? -sn : sn, p->k, &q);
    dh_motion_quat_rot_q_(&q, T);
}

/* dh_motion_turn_q_ (motion_impl.h) */
DH_NOINLINE void dh_motion_turn_q_(const dh_quat_q *e, int32_t cs, int32_t sn, const int32_t k[3], dh_quat_q *out)
{
    const int32_t r0 = (int32_t)dh_q_rshr(dh_q_mul64(sn, k[0]), 30u);
    const int32_t r1 = (int32_t)dh_q_rshr(dh_q_mul64(sn, k[1]), 30u);
    const int32_t r2 = (int32_t)dh_q_rshr(dh_q_mul64(sn, k[2]), 30u);
    out->w = (int32_t)dh_q_rshr(dh_q_mul64(e->w, cs) - dh_q_mul64(e->x, r0) - dh_q_mul64(e->y, r1) - dh_q_mul64(e->z, r2), 30u);
    out->x = (int32_t)dh_q_rshr(dh_q_mul64(e->w, r0) + dh_q_mul64(e->x, cs) + dh_q_mul64(e->y, r2) - dh_q_mul64(e->z, r1), 30u);
    out->y = (int32_t)dh_q_rshr(dh_q_mul64(e->w, r1) - dh_q_mul64(e->x, r2) + dh_q_mul64(e->y, cs) + dh_q_mul64(e->z, r0), 30u);
    out->z = (int32_t)dh_q_rshr(dh_q_mul64(e->w, r2) + dh_q_mul64(e->x, r1) - dh_q_mul64(e->y, r0) + dh_q_mul64(e->z, cs), 30u);
}

/* dh_motion_quat_rot_q_ (motion_impl.h) */
DH_NOINLINE void dh_motion_quat_rot_q_(const dh_quat_q *q, dh_frame_q *T)
{
    const int64_t one = (int64_t)1 << 60;
    const int32_t w = q->w, x = q->x, y = q->y, z = q->z;
    /* r[col][row] */
    T->r[0][0] = (dh_q30)dh_q_rshr(one - 2 * (dh_q_mul64(y, y) + dh_q_mul64(z, z)), 30u);
    T->r[1][1] = (dh_q30)dh_q_rshr(one - 2 * (dh_q_mul64(x, x) + dh_q_mul64(z, z)), 30u);
    T->r[2][2] = (dh_q30)dh_q_rshr(one - 2 * (dh_q_mul64(x, x) + dh_q_mul64(y, y)), 30u);
    T->r[1][0] = (dh_q30)dh_q_rshr(dh_q_mul64(x, y) - dh_q_mul64(w, z), 29u);
    T->r[0][1] = (dh_q30)dh_q_rshr(dh_q_mul64(x, y) + dh_q_mul64(w, z), 29u);
    T->r[2][0] = (dh_q30)dh_q_rshr(dh_q_mul64(x, z) + dh_q_mul64(w, y), 29u);
    T->r[0][2] = (dh_q30)dh_q_rshr(dh_q_mul64(x, z) - dh_q_mul64(w, y), 29u);
    T->r[2][1] = (dh_q30)dh_q_rshr(dh_q_mul64(y, z) - dh_q_mul64(w, x), 29u);
    T->r[1][2] = (dh_q30)dh_q_rshr(dh_q_mul64(y, z) + dh_q_mul64(w, x), 29u);
}

dh_status dh_path_eval_q(const dh_path_q *p, dh_q30 s, dh_frame_q *T)
{
    dh_qpos pos[3];
    unsigned i;
    DH_ASSERT(p != NULL && T != NULL);
    if (!pathq_ok(p)) return DH_ERR_ARG;
    if (s <= 0 || s >= DH_Q30_ONE) {
        *T = (s > 0) ? p->B : p->A;
        return DH_OK;
    }
    dh_motion_point_q_(p, s, pos);
    pathq_rot(p, s, T);
    for (i = 0; i < 3u; i++) T->p[i] = pos[i];
    return DH_OK;
}

/* ---- moves -------------------------------------------------------------- */

/* A bound num / den on a rate of s (num, den below 2^31); den 0: none */
typedef struct {
    uint32_t num;
    uint32_t den;
} pathq_rate;

/* *b = min(*b, num / den) for den > 0 (exact cross products) */
DH_INLINE void pathq_bound(pathq_rate *b, uint32_t num, uint32_t den)
{
    if (den == 0u) return;
    if (b->den == 0u || (uint64_t)num * b->den < (uint64_t)b->num * den) {
        b->num = num;
        b->den = den;
    }
}

/* 1 when x y > z w (x, z below 2^64, y, w below 2^32): both 96-bit
 * products compared as their top 64 bits and low 32 bits */
static int pathq_gt96(uint64_t x, uint32_t y, uint64_t z, uint32_t w)
{
    const uint64_t xl = (x & 0xFFFFFFFFu) * y, zl = (z & 0xFFFFFFFFu) * w;
    const uint64_t xh = (x >> 32) * y + (xl >> 32), zh = (z >> 32) * w + (zl >> 32);
    if (xh != zh) return xh > zh;
    return (xl & 0xFFFFFFFFu) > (zl & 0xFFFFFFFFu);
}

/* The largest v <= cap (1 <= cap < 2^31) with 4 v^3 <= jmax R^2
 * (v = floor(cbrt(jmax R^2 / 4)), the speed bound of a jerk-limited
 * arc), at least 1: one bit per step from the top, 4 v^2 below 2^64 and
 * jmax R^2 below 2^91 compared as 96-bit products */
static DH_NOINLINE uint32_t pathq_arc_vj(uint32_t R, uint32_t jmax, uint32_t cap)
{
    const uint64_t R2 = (uint64_t)R * R;
    uint32_t v = 0u, bit = 0x40000000u;
    while (bit != 0u) {
        const uint32_t t = v | bit;
        if (t <= cap && !pathq_gt96(4u * ((uint64_t)t * t), t, R2, jmax)) v = t;
        bit >>= 1;
    }
    return (v == 0u) ? 1u : v;
}

/* The speed bound V (LSB/s) of an arc of radius R within lim:
 * min(vmax, sqrt(amax R / sqrt 2)) rounded down, at least 1 (file
 * comment) */
static DH_NOINLINE uint32_t pathq_arc_v(uint32_t R, const dh_cart_limits_q *lim)
{
    uint32_t v = (uint32_t)(((uint64_t)dh_q_sqrt_u64((uint64_t)(uint32_t)lim->amax * R) * PATHQ_R4SQRT2) >> 30);
    if (v > (uint32_t)lim->vmax) v = (uint32_t)lim->vmax;
    return (v == 0u) ? 1u : v;
}

/* The tangential acceleration At (LSB/s^2) of an arc of radius R at the
 * speed v within lim: amax sqrt(1 - (v^2 / (amax R))^2) rounded down
 * (file comment); jmax > 0 (a jerk-limited move, dh_path_move_jerk_q)
 * lowers it to floor(jmax R / (12 v)) */
static DH_NOINLINE uint32_t pathq_arc_at(uint32_t R, const dh_cart_limits_q *lim, uint32_t v, uint32_t jmax)
{
    const uint64_t aR = (uint64_t)(uint32_t)lim->amax * R;
    uint64_t n, dd;
    uint32_t c, at;
    unsigned sh = 0u;
    /* r = V^2 / (amax R) <= 2^-1/2, rounded up; At = amax sqrt(1 - r^2) rounded down */
    n = (uint64_t)v * v;
    dd = aR;
    while (dd >= ((uint64_t)1 << 31)) {
        dd >>= 1;
        sh++;
    }
    n = (n >> sh) + 1u;
    if (dd == 0u) dd = 1u;
    c = (n >= dd) ? (uint32_t)DH_Q30_ONE : pathq_udiv64(n << 30, dd) + 1u;
    if (c > (uint32_t)DH_Q30_ONE) c = (uint32_t)DH_Q30_ONE;
    c = dh_q_isqrt62(((uint64_t)1 << 60) - (uint64_t)c * c);   /* sqrt(1 - r^2), Q30, down */
    at = (uint32_t)(((uint64_t)(uint32_t)lim->amax * c) >> 30);
    /* At 12 V > jmax R: At = floor(jmax R / (12 V)) (below the old At) */
    if (jmax != 0u && pathq_gt96(12u * (uint64_t)v, at, (uint64_t)jmax * R, 1u))
        at = pathq_udiv64((uint64_t)jmax * R, 12u * (uint64_t)v);
    return at;
}

/* dh_motion_tool_va_q_ (motion_impl.h) */
DH_NOINLINE uint64_t dh_motion_tool_va_q_(const dh_path_q *p, const dh_cart_limits_q *lim)
{
    uint32_t V = (uint32_t)lim->vmax, At = (uint32_t)lim->amax;
    if (p->kind == (uint32_t)DH_PATH_ARC) {
        V = pathq_arc_v((uint32_t)p->radius, lim);
        At = pathq_arc_at((uint32_t)p->radius, lim, V, 0u);
    }
    return ((uint64_t)V << 32) | At;
}

/* floor(b 2^e) of a bound */
static uint32_t pathq_scaled(const pathq_rate *b, unsigned e)
{
    return pathq_udiv64((uint64_t)b->num << e, b->den);
}

/* The tool's speed V, tangential acceleration At and jerk Jt (jk NULL:
 * 0) along p within lim and jk into prof's v, a and j (below 2^31: never
 * above vmax, amax, jmax; file comment), for pathq_rates; DH_ERR_ARG for
 * a limit <= 0 or a p that holds no path. Called by the public functions
 * beside pathq_rates, not under it (the 256 B guard). */
static DH_NOINLINE dh_status pathq_limits(dh_profile_q *prof, const dh_path_q *p, const dh_cart_limits_q *lim,
                                          const dh_cart_jerk_q *jk)
{
    uint32_t V, At, Jt;
    if (lim->vmax <= 0 || lim->amax <= 0 || lim->wmax <= 0 || lim->wdmax <= 0) return DH_ERR_ARG;
    if (jk != NULL && (jk->jmax <= 0 || jk->wjmax <= 0)) return DH_ERR_ARG;
    if (!pathq_ok(p)) return DH_ERR_ARG;
    V = (uint32_t)lim->vmax;
    At = (uint32_t)lim->amax;
    Jt = (jk != NULL) ? (uint32_t)jk->jmax : 0u;
    if (p->kind == (uint32_t)DH_PATH_ARC) {
        /* each step called from here (the 256 B guard) */
        V = pathq_arc_v((uint32_t)p->radius, lim);
        if (Jt != 0u) V = pathq_arc_vj((uint32_t)p->radius, Jt, V);
        At = pathq_arc_at((uint32_t)p->radius, lim, V, Jt);
        Jt >>= 1;
    }
    prof->v = (int32_t)V;
    prof->a = (int32_t)At;
    prof->j = (int32_t)Jt;
    return DH_OK;
}

/* The rates of s along p into prof's d = 2^e, v, a and j (0 without jk:
 * the trapezoid; file comment), from the tool's V, At, Jt that
 * pathq_limits left in prof's v, a and j, for dh_motion_profile_q_ to
 * plan in place */
static DH_NOINLINE dh_status pathq_rates(dh_profile_q *prof, const dh_path_q *p, const dh_cart_limits_q *lim,
                                         const dh_cart_jerk_q *jk)
{
    pathq_rate b[3] = { { 0u, 0u }, { 0u, 0u }, { 0u, 0u } };
    int k;
    /* speed, acceleration, jerk: the tool's over the length, the angular
     * over the angle, the smaller */
    for (k = 0; k < ((jk != NULL) ? 3 : 2); k++) {
        const int32_t tool = (k == 0) ? prof->v : ((k == 1) ? prof->a : prof->j);
        const int32_t rot = (k == 0) ? lim->wmax : ((k == 1 || jk == NULL) ? lim->wdmax : jk->wjmax);
        if (p->length > 0) pathq_bound(&b[k], (uint32_t)tool, (uint32_t)p->length);
        if (p->angle > 0) pathq_bound(&b[k], (uint32_t)rot, (uint32_t)p->angle);
    }
    prof->d = 0;
    prof->v = 1;
    prof->a = 1;
    prof->j = (jk != NULL) ? 1 : 0;
    if (p->length <= 0 && p->angle <= 0) return DH_OK;
    /* the largest e <= 30 with every rate times 2^e within int32 */
    for (k = 30; k >= 0; k--) {
        if (((uint64_t)b[0].num << k) < (uint64_t)INT32_MAX * b[0].den &&
            ((uint64_t)b[1].num << k) < (uint64_t)INT32_MAX * b[1].den &&
            (b[2].den == 0u || ((uint64_t)b[2].num << k) < (uint64_t)INT32_MAX * b[2].den)) {
            break;
        }
    }
    if (k < 0) return DH_ERR_OVERFLOW;
    prof->v = (int32_t)pathq_scaled(&b[0], (unsigned)k);
    prof->a = (int32_t)pathq_scaled(&b[1], (unsigned)k);
    if (jk != NULL) prof->j = (int32_t)pathq_scaled(&b[2], (unsigned)k);
    if (prof->v == 0 || prof->a == 0 || (jk != NULL && prof->j == 0)) return DH_ERR_OVERFLOW;
    prof->d = (int32_t)1 << k;
    return DH_OK;
}

/* dh_motion_path_rates_q_ (motion_impl.h): the tool's limits, then the
 * rates of s, each called from here */
dh_status dh_motion_path_rates_q_(dh_profile_q *prof, const dh_path_q *p, const dh_cart_limits_q *lim,
                                  const dh_cart_jerk_q *jk)
{
    const dh_status st = pathq_limits(prof, p, lim, jk);
    return (st == DH_OK) ? pathq_rates(prof, p, lim, jk) : st;
}

uint32_t dh_motion_path_e_q_(const dh_profile_q *prof)
{
    uint32_t e = 0u;
    if (prof->d <= 0) return 30u;
    while (e < 30u && ((uint32_t)prof->d >> e) > 1u) e++;
    return e;
}

/* the move planned in place (the rates of s, then the profile); on error
 * no move: prof all zero, *e 30 */
dh_status dh_path_move_q(dh_profile_q *prof, uint32_t *e, const dh_path_q *p, const dh_cart_limits_q *lim)
{
    dh_status st;
    DH_ASSERT(prof != NULL && e != NULL && p != NULL && lim != NULL);
    st = dh_motion_path_rates_q_(prof, p, lim, NULL);
    if (st == DH_OK) st = dh_motion_profile_q_(prof);
    if (st != DH_OK) (void)memset(prof, 0, sizeof *prof);
    *e = dh_motion_path_e_q_(prof);
    return st;
}

dh_status dh_path_move_jerk_q(dh_profile_q *prof, uint32_t *e, const dh_path_q *p, const dh_cart_limits_q *lim,
                              const dh_cart_jerk_q *jerk)
{
    dh_status st;
    DH_ASSERT(prof != NULL && e != NULL && p != NULL && lim != NULL);
    st = dh_motion_path_rates_q_(prof, p, lim, jerk);
    if (st == DH_OK) st = dh_motion_profile_q_(prof);
    if (st != DH_OK) (void)memset(prof, 0, sizeof *prof);
    *e = dh_motion_path_e_q_(prof);
    return st;
}

dh_status dh_path_move_eval_q(const dh_profile_q *prof, uint32_t e, const dh_path_q *p, uint32_t t, dh_frame_q *T)
{
    int32_t s = 0, sd, sdd;
    DH_ASSERT(prof != NULL && p != NULL && T != NULL);
    if (e > 30u || !pathq_ok(p)) return DH_ERR_ARG;
    if (prof->d != 0 && prof->d != ((int32_t)1 << e)) return DH_ERR_ARG;
    if (dh_profile_eval_q(prof, t, &s, &sd, &sdd) != DH_OK) return DH_ERR_ARG;
    return dh_path_eval_q(p, (dh_q30)((uint32_t)s << (30u - e)), T);
}
