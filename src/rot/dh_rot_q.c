/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_rot_q.c - rotation conversions of a fixed-point rotation (Q2.30):
 * Euler angles (all 24 sequences), unit quaternion (Shepperd 1978),
 * angle and axis, and the rotation vector that the orientation error
 * (src/kin/dh_pose_error_q.c) takes. Integer only: no float, no libm, no
 * 64-bit division (32-bit divisions and 32x32->64 products only).
 * Contracts in include/dhmath/rot.h.
 *
 * Every extraction first checks its input as the float path does
 * (dh_mat3_check_rot_f32 with DH_ROT_TOL, or DH_ROT_ERROR_TOL for the
 * orientation error): largest |(R^T R - I)_ij| (dh_frame_ortho_error_q)
 * within the tolerance and det R > 0, else DH_ERR_NOT_RIGID. An accepted
 * matrix has every entry below 1.0005 in magnitude, which bounds every
 * 64-bit sum below (no INT32_MIN can reach a negation either).
 *
 * Angles come from dh_atan2_q (<= 0.55 LSB of Q16.16 against the
 * exact angle of its integer arguments, which only the ratio enters), so
 * the extraction formulas of the float path are used in a division-free
 * form: the common positive factor 1/n of the float Euler solver is
 * dropped from both atan2 arguments, and 64-bit arguments are shifted by a
 * common amount into int32 (relative error 2^-30, 1e-7 LSB of the angle).
 * Near an Euler pole the middle angle is 90 - atan(z) (or atan(z), 180 -
 * atan(z)) with z = n / |c| small, taken directly as z in degrees (the
 * cubic term is below 2e-10 rad for z < 2^-10), so it is rounded once to
 * Q16.16 (<= 0.5 LSB = 7.6e-6 deg).
 *
 * Quaternion (Shepperd): the largest of 1 + t, 1 + 2 r_mm - t picks the
 * component q_m = sqrt(.) / 2 (>= 1/2), the others are (r_ab +- r_ba) /
 * (4 q_m) (bit-serial division, dh_q_udiv); the result is normalised
 * (|q| by an integer square root, four divisions) and signed w >= 0.
 * Angle and axis: the angle is atan2(|u| / 2, (tr - 1) / 2), u = (r21 -
 * r12, r02 - r20, r10 - r01) (one atan2: accurate at 0 and 180 alike), the
 * axis the quaternion's vector part normalised (robust at 180, where u
 * vanishes). Rotation vector: v sin-scaled by theta / |v|; for |v| < 1/16
 * the factor 2 asin(s) / s = 2 (1 + s^2/6 + 3 s^4/40 + 5 s^6/112) (next
 * term below 1e-11), so the error does not grow towards 0.
 */
#include "dhmath/rot.h"
#include "dhmath/frame.h"
#include "dhmath/trig.h"
#include "rot_impl.h"
#include "../internal/dh_qmath.h"

/* element (row a, column b) of a frame's rotation */
#define RQ(F, a, b) ((F)->r[(b)][(a)])

/* axes of the 12 intrinsic sequences (as dh_euler.c; 0 x, 1 y, 2 z) */
static const unsigned char rotq_axes[12][3] = {
    {0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0},
    {0, 1, 0}, {0, 2, 0}, {1, 0, 1}, {1, 2, 1}, {2, 0, 2}, {2, 1, 2}
};

/* ---- checks and small helpers ------------------------------------------- */

/* c_a . c_b - delta_ab of two columns, exact (entries below 1.25 2^30:
 * each product below 2^60.7, the sum below 2^63). */
static DH_NOINLINE int64_t rotq_dot(const int32_t *ca, const int32_t *cb, int64_t delta)
{
    return dh_q_mul64(ca[0], cb[0]) + dh_q_mul64(ca[1], cb[1]) + dh_q_mul64(ca[2], cb[2]) - delta;
}

/* 1 when F's rotation is orthonormal within tol LSB (every entry of
 * R^T R - I, exact, within tol 2^-30) and det > 0; an entry of magnitude
 * above 1.25 fails at once (its column's norm is then far from 1), which
 * bounds every product below. The cross product's two products are below
 * 2^61 each, the determinant's sum below 2^63. */
DH_NOINLINE int dh_rot_ok_q_(const dh_frame_q *F, int32_t tol)
{
    const int64_t lim = (int64_t)tol << 30;
    int64_t det = 0;
    unsigned a, b;
    for (a = 0; a < 3u; a++)
        for (b = 0; b < 3u; b++)
            if (dh_q_abs_u32(F->r[a][b]) > 0x50000000u) return 0;
    for (a = 0; a < 3u; a++)
        for (b = a; b < 3u; b++) {
            const int64_t d = rotq_dot(F->r[a], F->r[b], (a == b) ? ((int64_t)1 << 60) : 0);
            if (d > lim || d < -lim) return 0;
        }
    for (a = 0; a < 3u; a++) {
        const unsigned u = (a + 1u) % 3u, w = (a + 2u) % 3u;
        const int64_t c = dh_q_mul64(F->r[1][u], F->r[2][w]) - dh_q_mul64(F->r[1][w], F->r[2][u]);
        det += dh_q_mul64(F->r[0][a], (int32_t)(c >> 30));
    }
    return det > 0;
}

/* atan2 of two 64-bit values of a common scale, not both 0: both shifted
 * right by the same amount into int32 (only the ratio matters). */
static DH_NOINLINE dh_q16 rotq_atan2_64(int64_t y, int64_t x)
{
    const uint64_t ay = (y < 0) ? 0u - (uint64_t)y : (uint64_t)y;
    const uint64_t ax = (x < 0) ? 0u - (uint64_t)x : (uint64_t)x;
    uint64_t m = (ay > ax) ? ay : ax;
    unsigned sh = 0u;
    dh_q16 d = 0;
    while ((m >> sh) >= ((uint64_t)1 << 30)) sh++;
    (void)dh_atan2_q((int32_t)(y >> sh), (int32_t)(x >> sh), &d);
    return d;
}

/* dh_q_isqrt62 out of line (one copy; the callers' frames stay small) */
static DH_NOINLINE uint32_t rotq_isqrt(uint64_t v)
{
    return dh_q_isqrt62(v);
}

/* |v| of a Q2.30 3- or 4-vector (components below 2^31, squares summed
 * below 2^62 by the callers' bounds), Q2.30. */
static DH_NOINLINE uint32_t rotq_norm(const int32_t *v, unsigned len)
{
    uint64_t s = 0u;
    unsigned k;
    for (k = 0; k < len; k++) s += (uint64_t)dh_q_mul64(v[k], v[k]);
    return dh_q_isqrt62(s);   /* inline: one frame less on the deepest chains */
}

/* v * 2^frac / d rounded, the sign of v kept: |v| < 2^32, 1 <= d < 2^31,
 * result below 2^31 in magnitude (callers' bounds). */
static DH_NOINLINE int32_t rotq_div(int64_t v, uint32_t d, unsigned frac)
{
    const uint32_t a = (uint32_t)((v < 0) ? 0u - (uint64_t)v : (uint64_t)v);
    const uint32_t m = dh_q_udiv(a, d, frac);
    return (v < 0) ? -(int32_t)m : (int32_t)m;
}

/* ---- quaternion (Shepperd) ------------------------------------------------ */

/* Shepperd's off-diagonal sums: for the chosen component m (0 w, 1 x,
 * 2 y, 3 z) and each other component in order, o = r_ab + sign r_ba. */
static const signed char rotq_shep[4][3][3] = {
    { {2, 1, -1}, {0, 2, -1}, {1, 0, -1} },
    { {2, 1, -1}, {0, 1, 1}, {0, 2, 1} },
    { {0, 2, -1}, {0, 1, 1}, {1, 2, 1} },
    { {1, 0, -1}, {0, 2, 1}, {1, 2, 1} }
};

/* The Shepperd component m (largest of t, r00, r11, r22, in this order on
 * ties, as the float path) and 4 q_m^2 = 1 + big in [1, 4.002], Q2.30. */
static DH_NOINLINE uint64_t rotq_pick(const dh_frame_q *F, unsigned *m)
{
    const int32_t r00 = RQ(F, 0, 0), r11 = RQ(F, 1, 1), r22 = RQ(F, 2, 2);
    const int64_t t = (int64_t)r00 + r11 + r22;
    int64_t big = t;
    *m = 0u;
    if (!(t >= r00 && t >= r11 && t >= r22)) {
        *m = (r00 >= r11 && r00 >= r22) ? 1u : (r11 >= r22) ? 2u : 3u;
        big = 2 * (int64_t)RQ(F, *m - 1u, *m - 1u) - t;
    }
    return (uint64_t)(big + DH_Q_ONE30);
}

/* Unit quaternion q = (w, x, y, z) of a checked rotation, w >= 0 (at w ==
 * 0 the component of the largest diagonal entry is positive). The others
 * are o / (4 q_m) = o 2^28 / q_m (|o| < 2.002 2^30, q_m >= 2^29). */
static DH_NOINLINE void rotq_quat(const dh_frame_q *F, int32_t *q)
{
    unsigned m, k;
    const uint64_t big1 = rotq_pick(F, &m);
    const uint32_t qm = rotq_isqrt(big1 << 28);   /* q_m 2^30 = sqrt((1 + big) 2^28) */
    uint32_t nrm;
    q[m] = (int32_t)qm;
    for (k = 0; k < 3u; k++) {
        const signed char *e = rotq_shep[m][k];
        const int64_t o = (int64_t)RQ(F, e[0], e[1]) + e[2] * (int64_t)RQ(F, e[1], e[0]);
        q[k < m ? k : k + 1u] = rotq_div(o, qm, 28u);
    }
    nrm = rotq_norm(q, 4u);
    for (k = 0; k < 4u; k++) q[k] = rotq_div(q[k], nrm, 30u);
    if (q[0] < 0)
        for (k = 0; k < 4u; k++) q[k] = -q[k];
}

dh_status dh_frame_to_quat_q(const dh_frame_q *F, dh_quat_q *q)
{
    int32_t v[4];
    DH_ASSERT(F != NULL && q != NULL);
    if (!dh_rot_ok_q_(F, DH_ROT_TOL_Q)) return DH_ERR_NOT_RIGID;
    rotq_quat(F, v);
    q->w = v[0];
    q->x = v[1];
    q->y = v[2];
    q->z = v[3];
    return DH_OK;
}

dh_status dh_quat_to_frame_q(const dh_quat_q *q, dh_frame_q *F)
{
    int32_t v[4];
    uint32_t mx = 0u, nrm;
    unsigned k;
    DH_ASSERT(q != NULL && F != NULL);
    v[0] = q->w;
    v[1] = q->x;
    v[2] = q->y;
    v[3] = q->z;
    for (k = 0; k < 4u; k++)
        if (dh_q_abs_u32(v[k]) > mx) mx = dh_q_abs_u32(v[k]);
    if (mx == 0u) return DH_ERR_ZERO_AXIS;
    /* common scale: largest magnitude into [2^28, 2^29] (|q| <= 2^30) */
    while (mx > 0x20000000u) {
        for (k = 0; k < 4u; k++) v[k] >>= 1;
        mx >>= 1;
    }
    while (mx < 0x10000000u) {
        for (k = 0; k < 4u; k++) v[k] = (int32_t)((uint32_t)v[k] << 1);
        mx <<= 1;
    }
    nrm = rotq_norm(v, 4u);
    for (k = 0; k < 4u; k++) v[k] = rotq_div(v[k], nrm, 30u);
    /* R = I + 2 [ -(y^2+z^2)  xy-wz  xz+wy ; ... ] (products below 2^60,
     * entries within 1 + 2^-28: no saturation) */
    {
        int ovf = 0;
        const int32_t w = v[0], x = v[1], y = v[2], z = v[3];
        const int64_t one = (int64_t)1 << 60;
        RQ(F, 0, 0) = dh_q_rnd30(one - 2 * (dh_q_mul64(y, y) + dh_q_mul64(z, z)), &ovf);
        RQ(F, 1, 1) = dh_q_rnd30(one - 2 * (dh_q_mul64(x, x) + dh_q_mul64(z, z)), &ovf);
        RQ(F, 2, 2) = dh_q_rnd30(one - 2 * (dh_q_mul64(x, x) + dh_q_mul64(y, y)), &ovf);
        RQ(F, 0, 1) = dh_q_rnd30(2 * (dh_q_mul64(x, y) - dh_q_mul64(w, z)), &ovf);
        RQ(F, 1, 0) = dh_q_rnd30(2 * (dh_q_mul64(x, y) + dh_q_mul64(w, z)), &ovf);
        RQ(F, 0, 2) = dh_q_rnd30(2 * (dh_q_mul64(x, z) + dh_q_mul64(w, y)), &ovf);
        RQ(F, 2, 0) = dh_q_rnd30(2 * (dh_q_mul64(x, z) - dh_q_mul64(w, y)), &ovf);
        RQ(F, 1, 2) = dh_q_rnd30(2 * (dh_q_mul64(y, z) - dh_q_mul64(w, x)), &ovf);
        RQ(F, 2, 1) = dh_q_rnd30(2 * (dh_q_mul64(y, z) + dh_q_mul64(w, x)), &ovf);
        (void)ovf;
    }
    F->p[0] = 0;
    F->p[1] = 0;
    F->p[2] = 0;
    return DH_OK;
}

/* ---- angle and axis, rotation vector --------------------------------------- */

/* Angle of a (checked) rotation: atan2(|u| / 2, (tr - 1) / 2), Q16.16 deg
 * in [0, 180]. |u| <= 2.002 2^30 per component (it may exceed int32):
 * rotq_sq squares it exactly; the sum, 4 sin^2 2^60, fits uint64. */
/* u^2 for |u| < 2^32 (u = 2 a + b, b in {0, 1}: 4 a^2 + 4 a b + b). */
static DH_NOINLINE uint64_t rotq_sq(int64_t u)
{
    const int32_t a = (int32_t)(u >> 1), b = (int32_t)(u & 1);
    uint64_t r = (uint64_t)dh_q_mul64(a, a) << 2;
    if (b != 0) r += ((uint64_t)(int64_t)a << 2) + 1u;
    return r;
}

static DH_NOINLINE dh_q16 rotq_angle(const dh_frame_q *F)
{
    const int64_t u0 = (int64_t)RQ(F, 2, 1) - RQ(F, 1, 2), u1 = (int64_t)RQ(F, 0, 2) - RQ(F, 2, 0);
    const int64_t u2 = (int64_t)RQ(F, 1, 0) - RQ(F, 0, 1);
    const uint64_t s = rotq_sq(u0) + rotq_sq(u1) + rotq_sq(u2);
    const int64_t x2 = (int64_t)RQ(F, 0, 0) + RQ(F, 1, 1) + RQ(F, 2, 2) - DH_Q_ONE30;
    const uint32_t sn = rotq_isqrt(s >> 2);
    dh_q16 d = 0;
    if (sn == 0u && x2 >= 0) return 0;
    (void)dh_atan2_q((int32_t)sn, (int32_t)((x2 - (x2 & 1)) / 2), &d); /* floor(x2 / 2): exact division */
    return d < 0 ? 0 : d;
}

dh_status dh_frame_to_axis_angle_q(const dh_frame_q *F, dh_dir3_q *axis, dh_q16 *deg)
{
    int32_t q[4];
    uint32_t vn;
    DH_ASSERT(F != NULL && axis != NULL && deg != NULL);
    if (!dh_rot_ok_q_(F, DH_ROT_TOL_Q)) return DH_ERR_NOT_RIGID;
    rotq_quat(F, q);
    vn = rotq_norm(&q[1], 3u);
    *deg = rotq_angle(F);
    if (vn == 0u) {
        axis->x = 0;
        axis->y = 0;
        axis->z = DH_Q30_ONE;
        *deg = 0;
        return DH_OK;
    }
    axis->x = rotq_div(q[1], vn, 30u);
    axis->y = rotq_div(q[2], vn, 30u);
    axis->z = rotq_div(q[3], vn, 30u);
    return DH_OK;
}

/* pi / 180 * 2^36, rounded: Q16.16 degrees -> Q3.29 radians by >> 23 */
#define ROTQ_DEG2RAD36 INT32_C(1199381129)

/* Rotation vector (Q3.29 rad) of the checked-or-near rotation D (q: 4
 * words of scratch, the caller's: the frame stays small). */
DH_NOINLINE void dh_rot_vec_q_(const dh_frame_q *D, dh_dir3_q *w, int32_t *q)
{
    uint32_t vn, f;
    rotq_quat(D, q);
    vn = rotq_norm(&q[1], 3u);
    if (vn < 0x04000000u) {
        /* s < 1/16: f = 2 asin(s) / s in Q3.29 by its series (s^2 in Q2.30) */
        const uint32_t s2 = (uint32_t)dh_q_rshr(dh_q_mul64((int32_t)vn, (int32_t)vn), 30u); /* < 2^22 */
        uint32_t t = s2 * 5u / 112u;
        t = 0x40000000u / 40u * 3u + (uint32_t)dh_q_rshr(dh_q_mul64((int32_t)t, (int32_t)s2), 30u);
        t = 0x40000000u / 6u + (uint32_t)dh_q_rshr(dh_q_mul64((int32_t)t, (int32_t)s2), 30u);
        t = 0x40000000u + (uint32_t)dh_q_rshr(dh_q_mul64((int32_t)t, (int32_t)s2), 30u);
        f = (uint32_t)t;                                  /* 2 (...) in Q3.29 = (...) in Q2.30 */
    } else {
        const int64_t th = dh_q_rshr(dh_q_mul64(rotq_angle(D), ROTQ_DEG2RAD36), 23u);
        f = (uint32_t)rotq_div(th, vn, 30u);              /* theta / |v|, Q3.29 */
    }
    w->x = (int32_t)dh_q_rshr(dh_q_mul64(q[1], (int32_t)f), 30u);
    w->y = (int32_t)dh_q_rshr(dh_q_mul64(q[2], (int32_t)f), 30u);
    w->z = (int32_t)dh_q_rshr(dh_q_mul64(q[3], (int32_t)f), 30u);
}

/* ---- Euler angles --------------------------------------------------------- */

/* M <- M Rq(t) by (s, c): columns q+1 and q+2 (cyclic) turned, each entry
 * rounded once (as dh_euler.c's dh_euler_post_rot). */
static DH_NOINLINE void rotq_post_rot(dh_frame_q *M, unsigned qa, int32_t sn, int32_t cs)
{
    const unsigned u = (qa + 1u) % 3u, w = (qa + 2u) % 3u;
    unsigned r;
    int ovf = 0;
    for (r = 0; r < 3u; r++) {
        const int32_t mu = M->r[u][r], mw = M->r[w][r];
        M->r[u][r] = dh_q_rnd30(dh_q_mla64(dh_q_mul64(cs, mu), sn, mw), &ovf);
        M->r[w][r] = dh_q_rnd30(dh_q_mul64(cs, mw) - dh_q_mul64(sn, mu), &ovf);
    }
    (void)ovf; /* entries of a product of rotations: |.| <= 1 + 2^-28 */
}

dh_status dh_euler_to_frame_q(dh_euler_seq seq, const dh_q16 ang_deg[3], dh_frame_q *F)
{
    const unsigned u = (unsigned)seq;
    unsigned n;
    DH_ASSERT(ang_deg != NULL && F != NULL);
    if (u >= (unsigned)DH_EULER_COUNT) return DH_ERR_ARG;
    dh_frame_identity_q(F);
    for (n = 0; n < 3u; n++) {
        /* extrinsic (a, b, c) about l0, l1, l2 = intrinsic (c, b, a) about l2, l1, l0 */
        const unsigned m = (u < 12u) ? n : 2u - n;
        const unsigned ax = rotq_axes[(u < 12u) ? u : u - 12u][m];
        dh_q30 sn, cs;
        dh_sincos_q(ang_deg[m], &sn, &cs);
        rotq_post_rot(F, ax, sn, cs);
    }
    return DH_OK;
}

/* n = sqrt(x^2 + y^2), Q2.30 (entries of a checked rotation). */
static DH_NOINLINE int32_t rotq_hyp(int32_t x, int32_t y)
{
    return (int32_t)rotq_isqrt((uint64_t)dh_q_mul64(x, x) + (uint64_t)dh_q_mul64(y, y));
}

/* pi / 180 rounded in Q0.32 is not needed: 180 / pi * 2^-14 scales a Q2.30
 * small angle z (radians) to Q16.16 degrees: round(z * ROTQ_RAD2DEG >> 28). */
#define ROTQ_RAD2DEG_Q16 INT32_C(1877468) /* round(180 / pi * 2^15) */

/* Middle angle atan2(y, x) with y >= 0 for the proper (y = n) or x >= 0
 * for the Tait-Bryan (x = n) case: near the pole (the small one below
 * 2^-10 of the large one) the small angle is z in degrees (file comment). */
static DH_NOINLINE dh_q16 rotq_middle(int32_t y, int32_t x)
{
    const uint32_t ay = dh_q_abs_u32(y), ax = dh_q_abs_u32(x);
    dh_q16 d = 0;
    if (ay <= (ax >> 10) || ax <= (ay >> 10)) {
        const int ybig = ay > ax;
        const uint32_t sm = ybig ? ax : ay, bg = ybig ? ay : ax;
        /* z = sm / bg in Q2.30, then z 180/pi in Q16.16 */
        const uint32_t z = dh_q_udiv(sm, bg, 30u);
        const int32_t dz = (int32_t)dh_q_rshr(dh_q_mul64((int32_t)z, ROTQ_RAD2DEG_Q16), 29u);
        const int32_t q90 = 90 * DH_Q16_ONE, q180 = 180 * DH_Q16_ONE;
        if (ybig) d = (y > 0) ? ((x >= 0) ? q90 - dz : q90 + dz) : ((x >= 0) ? -q90 + dz : -q90 - dz);
        else if (x > 0) d = (y >= 0) ? dz : -dz;
        else d = (y >= 0) ? q180 - dz : -q180 + dz;
        return d;
    }
    (void)dh_atan2_q(y, x, &d);
    return d;
}

/* The float solver dh_euler_solve (src/rot/dh_euler.c), division free: the
 * atan2 arguments of g carry the common factor n instead of dividing by it. */
static DH_NOINLINE void rotq_solve(const dh_frame_q *F, unsigned i, unsigned j, unsigned k, int zero_first,
                                   dh_q16 *out)
{
    const int proper = (i == k);
    const unsigned l = proper ? 3u - i - j : k;
    const int32_t s = (j == i + 1u || j + 2u == i) ? 1 : -1;
    int32_t t = s, u = s, y, x, p2, q1, q2, n, b, f, g;
    if (!proper && !zero_first) {
        y = -s * RQ(F, i, j); x = RQ(F, i, i); p2 = RQ(F, j, i); q1 = RQ(F, k, j); q2 = RQ(F, k, i);
    } else if (!proper) {
        y = -s * RQ(F, j, k); x = RQ(F, k, k); p2 = RQ(F, k, j); q1 = RQ(F, j, i); q2 = RQ(F, k, i);
    } else if (!zero_first) {
        y = RQ(F, i, j); x = s * RQ(F, i, l); p2 = RQ(F, j, l); q1 = RQ(F, l, j); q2 = RQ(F, l, l); t = -s;
    } else {
        y = RQ(F, j, i); x = -s * RQ(F, l, i); p2 = RQ(F, l, j); q1 = RQ(F, j, l); q2 = RQ(F, l, l); u = -s;
    }
    n = rotq_hyp(x, y);                 /* cos b (Tait-Bryan), sin b (proper) */
    b = proper ? rotq_middle(n, RQ(F, i, i)) : rotq_middle(s * RQ(F, i, k), n);
    if (n <= DH_EULER_POLE_TOL_Q) {
        f = 0;
        g = rotq_atan2_64((int64_t)u * q1, RQ(F, j, j));
    } else {
        (void)dh_atan2_q(y, x, &f);
        g = rotq_atan2_64(u * (dh_q_mul64(x, q1) + t * dh_q_mul64(y, q2)),
                          dh_q_mul64(x, RQ(F, j, j)) + t * dh_q_mul64(y, p2));
    }
    out[0] = zero_first ? f : g;
    out[1] = b;
    out[2] = zero_first ? g : f;
}

dh_status dh_frame_to_euler_q(const dh_frame_q *F, dh_euler_seq seq, dh_q16 ang_deg[3])
{
    const unsigned u = (unsigned)seq;
    const unsigned char *ax;
    dh_q16 dg[3];
    DH_ASSERT(F != NULL && ang_deg != NULL);
    if (u >= (unsigned)DH_EULER_COUNT) return DH_ERR_ARG;
    if (!dh_rot_ok_q_(F, DH_ROT_TOL_Q)) return DH_ERR_NOT_RIGID;
    if (u < 12u) {
        ax = rotq_axes[u];
        rotq_solve(F, ax[0], ax[1], ax[2], 0, dg);
        ang_deg[0] = dg[0];
        ang_deg[2] = dg[2];
    } else {
        /* extrinsic (a, b, c) = intrinsic (c, b, a) of the reversed axes;
         * the letter-third angle (intrinsic first) is 0 at the pole */
        ax = rotq_axes[u - 12u];
        rotq_solve(F, ax[2], ax[1], ax[0], 1, dg);
        ang_deg[0] = dg[2];
        ang_deg[2] = dg[0];
    }
    ang_deg[1] = dg[1];
    return DH_OK;
}
