/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_errors_fixed.c - bad input to the fixed-point frames
 * (docs/errors.md, section frame.h).
 *
 * Overflow in composition, inversion and point/direction transforms must
 * saturate the affected entries to INT32_MIN / INT32_MAX with the right
 * sign, compute every other entry normally and return DH_ERR_OVERFLOW.
 * The reference is the formula of frame.h evaluated in double: each
 * output is a sum of at most three int32 x int32 products (< 2^62 each,
 * rounded to double with an error below 2^10) plus a translation, divided
 * by 2^30, so the double value is within 2^-18 LSB of the exact one. An
 * in-range output must be within 0.5 LSB (+ that 2^-18) of it; an output
 * whose reference lies more than 1 LSB beyond the int32 range must be
 * saturated.
 */
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_canary.h"
#include "dhmath/frame.h"
#include "dhmath/mat4.h"
#include "dhmath/trig.h"
#include "dhmath/rot.h"

#define TWO30 1073741824.0
#define TWO31 2147483648.0
#define REF_SLACK (1.0 / 262144.0) /* 2^-18 LSB: double rounding of the reference */


static int32_t rand_i32(void) { return (int32_t)dht_rand_u32(); }

/* random int32 biased to the extremes (a third each: full range, near
 * +-2^31, small) */
static int32_t rand_edge(void)
{
    const uint32_t k = dht_rand_u32() % 3u;
    if (k == 0u) return rand_i32();
    if (k == 1u) return (dht_rand_u32() & 1u) ? INT32_MAX - (int32_t)(dht_rand_u32() % 1024u)
                                              : INT32_MIN + (int32_t)(dht_rand_u32() % 1024u);
    return (int32_t)(dht_rand_u32() % 2048u) - 1024;
}

static void rand_frame_any(dh_frame_q *F)
{
    int c, r;
    for (c = 0; c < 3; c++) {
        F->p[c] = rand_edge();
        for (r = 0; r < 3; r++) F->r[c][r] = rand_edge();
    }
}

/*
 * Check one output against its double reference. Returns 1 if it must have
 * saturated, 0 if it must not, 2 if the reference is within 1 LSB of the
 * int32 range ends, where rounding decides (either the rounded value or the
 * saturated one is accepted, and the status is not predicted).
 */
static int check_entry(int32_t got, double ref, const char *what, int i)
{
    if (ref >= TWO31 + 1.0) {
        DHT_TRUE_MSG(got == INT32_MAX, "%s[%d]: ref %.17g, got %ld (want INT32_MAX)", what, i, ref, (long)got);
        return 1;
    }
    if (ref <= -TWO31 - 1.0) {
        DHT_TRUE_MSG(got == INT32_MIN, "%s[%d]: ref %.17g, got %ld (want INT32_MIN)", what, i, ref, (long)got);
        return 1;
    }
    if (ref >= TWO31 - 1.0 || ref <= -TWO31 + 1.0) {
        DHT_TRUE_MSG(fabs((double)got - ref) <= 0.5 + REF_SLACK || got == INT32_MAX || got == INT32_MIN,
                     "%s[%d]: ref %.17g got %ld", what, i, ref, (long)got);
        return 2;
    }
    DHT_TRUE_MSG(fabs((double)got - ref) <= 0.5 + REF_SLACK, "%s[%d]: ref %.17g got %ld (diff %.3g)",
                 what, i, ref, (long)got, fabs((double)got - ref));
    return 0;
}

/* expected status from the OR of check_entry results (bit 1 = ambiguous) */
static void check_status(dh_status st, int sat)
{
    if (sat & 2) return;
    DHT_EQ_INT(st, (sat & 1) ? DH_ERR_OVERFLOW : DH_OK);
}

/* exact-ish double: (a0 b0 + a1 b1 + a2 b2) / 2^30 + t */
static double dot3(int32_t a0, int32_t b0, int32_t a1, int32_t b1, int32_t a2, int32_t b2, double t)
{
    return ((double)a0 * b0 + (double)a1 * b1 + (double)a2 * b2) / TWO30 + t;
}

/* ---------------------------------------------------------------------- */

/* Rot(k, deg) with k = 0 -> DH_ERR_ZERO_AXIS (F untouched) for any angle;
 * every other int32 axis, including INT32_MIN components, is accepted */
static void fixed_rot_axis_zero_and_extreme(void)
{
    static const int32_t degs[] = { 0, 1, INT32_MIN, INT32_MAX, 90 * 65536 };
    static const int32_t ax[][3] = {
        { INT32_MIN, 0, 0 }, { INT32_MIN, INT32_MIN, INT32_MIN }, { INT32_MAX, INT32_MIN, 1 },
        { 1, 0, 0 }, { 0, 0, -1 }, { 1, 1, 1 }, { INT32_MIN, INT32_MAX, INT32_MAX }
    };
    dh_frame_q F;
    unsigned i, k;
    for (i = 0; i < sizeof degs / sizeof degs[0]; i++) {
        CANARY(F);
        DHT_EQ_INT(dh_frame_rot_axis_q(0, 0, 0, degs[i], &F), DH_ERR_ZERO_AXIS);
        UNTOUCHED(F);
    }
    for (k = 0; k < sizeof ax / sizeof ax[0]; k++) {
        for (i = 0; i < sizeof degs / sizeof degs[0]; i++) {
            const double kx = ax[k][0], ky = ax[k][1], kz = ax[k][2];
            const double n = sqrt(kx * kx + ky * ky + kz * kz);
            const double x = kx / n, y = ky / n, z = kz / n;
            const double th = fmod((double)degs[i] / 65536.0, 360.0) * (3.14159265358979323846 / 180.0);
            const double c = cos(th), s = sin(th), v = 1.0 - c;
            double R[3][3]; /* R[row][col], eq. 1.70 */
            int r, cc;
            R[0][0] = x * x * v + c;     R[0][1] = x * y * v - z * s; R[0][2] = x * z * v + y * s;
            R[1][0] = x * y * v + z * s; R[1][1] = y * y * v + c;     R[1][2] = y * z * v - x * s;
            R[2][0] = x * z * v - y * s; R[2][1] = y * z * v + x * s; R[2][2] = z * z * v + c;
            DHT_EQ_INT(dh_frame_rot_axis_q(ax[k][0], ax[k][1], ax[k][2], degs[i], &F), DH_OK);
            for (r = 0; r < 3; r++) {
                DHT_EQ_INT(F.p[r], 0);
                for (cc = 0; cc < 3; cc++) DHT_NEAR((double)F.r[cc][r], R[r][cc] * TWO30, 1.93);
            }
            DHT_TRUE(dh_frame_ortho_error_q(&F) <= 2);
        }
    }
}

/* Rot(x|y|z) of the extreme angles: exactly the dh_sincos_q values */
static void fixed_rot_elem_extreme_angles(void)
{
    static const int32_t degs[] = { INT32_MIN, INT32_MAX, INT32_MIN + 1, -1 };
    unsigned i;
    for (i = 0; i < sizeof degs / sizeof degs[0]; i++) {
        dh_frame_q F;
        dh_q30 s, c;
        dh_sincos_q(degs[i], &s, &c);
        dh_frame_rotx_q(degs[i], &F);
        DHT_EQ_INT(F.r[0][0], DH_Q30_ONE);
        DHT_EQ_INT(F.r[1][1], c);
        DHT_EQ_INT(F.r[1][2], s);
        DHT_EQ_INT(F.r[2][1], -s);
        DHT_EQ_INT(F.r[2][2], c);
        dh_frame_roty_q(degs[i], &F);
        DHT_EQ_INT(F.r[1][1], DH_Q30_ONE);
        DHT_EQ_INT(F.r[0][0], c);
        DHT_EQ_INT(F.r[2][0], s);
        DHT_EQ_INT(F.r[0][2], -s);
        dh_frame_rotz_q(degs[i], &F);
        DHT_EQ_INT(F.r[2][2], DH_Q30_ONE);
        DHT_EQ_INT(F.r[0][1], s);
        DHT_EQ_INT(F.r[1][0], -s);
        DHT_EQ_INT(dh_frame_ortho_error_q(&F), dh_frame_ortho_error_q(&F)); /* defined */
        DHT_TRUE(dh_frame_ortho_error_q(&F) <= 2);
    }
}

/* compose: saturated entries at the right end, the rest exact, status
 * DH_ERR_OVERFLOW iff something saturated; aliasing allowed */
static void fixed_mul_overflow(void)
{
    dh_frame_q A, B, C, D;
    uint32_t it;
    /* translation overflow both ways */
    dh_frame_trans_q(INT32_MAX, INT32_MIN, 5, &A);
    dh_frame_trans_q(1, -1, -5, &B);
    DHT_EQ_INT(dh_frame_mul_q(&A, &B, &C), DH_ERR_OVERFLOW);
    DHT_EQ_INT(C.p[0], INT32_MAX);
    DHT_EQ_INT(C.p[1], INT32_MIN);
    DHT_EQ_INT(C.p[2], 0);
    DHT_EQ_INT(C.r[0][0], DH_Q30_ONE);
    DHT_EQ_INT(C.r[1][0], 0);
    /* just inside: no overflow */
    dh_frame_trans_q(0, 0, 0, &B);
    DHT_EQ_INT(dh_frame_mul_q(&A, &B, &C), DH_OK);
    DHT_EQ_INT(C.p[0], INT32_MAX);
    DHT_EQ_INT(C.p[1], INT32_MIN);
    /* rotation overflow: every entry -2.0; (-2)(-2) * 3 = 12 */
    memset(&A, 0, sizeof A);
    {
        int c, r;
        for (c = 0; c < 3; c++)
            for (r = 0; r < 3; r++) A.r[c][r] = INT32_MIN;
    }
    B = A;
    DHT_EQ_INT(dh_frame_mul_q(&A, &B, &C), DH_ERR_OVERFLOW);
    DHT_EQ_INT(C.r[0][0], INT32_MAX);
    DHT_EQ_INT(C.r[2][1], INT32_MAX);
    DHT_EQ_INT(C.p[0], 0);
    /* random arbitrary frames vs the double formula, also aliased */
    for (it = 0; it < DHT_ITER(100000u); it++) {
        int c, r, sat = 0;
        dh_status st;
        rand_frame_any(&A);
        rand_frame_any(&B);
        st = dh_frame_mul_q(&A, &B, &C);
        for (c = 0; c < 3; c++) {
            for (r = 0; r < 3; r++)
                sat |= check_entry(C.r[c][r], dot3(A.r[0][r], B.r[c][0], A.r[1][r], B.r[c][1],
                                                   A.r[2][r], B.r[c][2], 0.0), "R", c * 3 + r);
            sat |= check_entry(C.p[c], dot3(A.r[0][c], B.p[0], A.r[1][c], B.p[1], A.r[2][c], B.p[2],
                                            (double)A.p[c]), "p", c);
        }
        check_status(st, sat);
        D = A;
        DHT_EQ_INT(dh_frame_mul_q(&D, &B, &D), st);
        DHT_TRUE(memcmp(&C, &D, sizeof C) == 0);
        D = B;
        DHT_EQ_INT(dh_frame_mul_q(&A, &D, &D), st);
        DHT_TRUE(memcmp(&C, &D, sizeof C) == 0);
    }
}

/* rigid inverse: p' = -R^T p saturates (e.g. -INT32_MIN); rigidity is not
 * checked (R^T, -R^T p for any R) */
static void fixed_inv_overflow(void)
{
    dh_frame_q F, G, H;
    uint32_t it;
    dh_frame_trans_q(INT32_MIN, INT32_MAX, 0, &F);
    DHT_EQ_INT(dh_frame_inv_q(&F, &G), DH_ERR_OVERFLOW);
    DHT_EQ_INT(G.p[0], INT32_MAX);   /* -(-2^31) saturates */
    DHT_EQ_INT(G.p[1], -INT32_MAX);  /* exact */
    DHT_EQ_INT(G.p[2], 0);
    DHT_EQ_INT(G.r[0][0], DH_Q30_ONE);
    for (it = 0; it < DHT_ITER(100000u); it++) {
        int c, r, sat = 0;
        dh_status st;
        rand_frame_any(&F);
        st = dh_frame_inv_q(&F, &G);
        for (c = 0; c < 3; c++) {
            for (r = 0; r < 3; r++) DHT_EQ_INT(G.r[c][r], F.r[r][c]);
            sat |= check_entry(G.p[c], -dot3(F.r[c][0], F.p[0], F.r[c][1], F.p[1], F.r[c][2], F.p[2], 0.0),
                               "p", c);
        }
        check_status(st, sat);
        H = F;
        DHT_EQ_INT(dh_frame_inv_q(&H, &H), st);
        DHT_TRUE(memcmp(&G, &H, sizeof G) == 0);
    }
}

/* point / direction transforms: saturate per component, u and v may alias */
static void fixed_apply_overflow(void)
{
    dh_frame_q F;
    dh_vec3_q u, v, w;
    uint32_t it;
    dh_frame_trans_q(1, -1, 0, &F);
    u.x = INT32_MAX; u.y = INT32_MIN; u.z = 7;
    DHT_EQ_INT(dh_frame_apply_point_q(&F, &u, &v), DH_ERR_OVERFLOW);
    DHT_EQ_INT(v.x, INT32_MAX);
    DHT_EQ_INT(v.y, INT32_MIN);
    DHT_EQ_INT(v.z, 7);
    DHT_EQ_INT(dh_frame_apply_dir_q(&F, &u, &v), DH_OK); /* p ignored */
    DHT_EQ_INT(v.x, INT32_MAX);
    DHT_EQ_INT(v.y, INT32_MIN);
    /* -I applied to INT32_MIN: +2^31 saturates */
    memset(&F, 0, sizeof F);
    F.r[0][0] = -DH_Q30_ONE; F.r[1][1] = -DH_Q30_ONE; F.r[2][2] = -DH_Q30_ONE;
    u.x = INT32_MIN; u.y = INT32_MAX; u.z = 0;
    DHT_EQ_INT(dh_frame_apply_dir_q(&F, &u, &v), DH_ERR_OVERFLOW);
    DHT_EQ_INT(v.x, INT32_MAX);
    DHT_EQ_INT(v.y, -INT32_MAX);
    DHT_EQ_INT(v.z, 0);
    for (it = 0; it < DHT_ITER(100000u); it++) {
        int c, sat = 0, satd = 0;
        dh_status st, std;
        int32_t in[3];
        rand_frame_any(&F);
        u.x = rand_edge(); u.y = rand_edge(); u.z = rand_edge();
        in[0] = u.x; in[1] = u.y; in[2] = u.z;
        st = dh_frame_apply_point_q(&F, &u, &v);
        std = dh_frame_apply_dir_q(&F, &u, &w);
        for (c = 0; c < 3; c++) {
            const int32_t got = (c == 0) ? v.x : (c == 1) ? v.y : v.z;
            const int32_t gotd = (c == 0) ? w.x : (c == 1) ? w.y : w.z;
            const double d = dot3(F.r[0][c], in[0], F.r[1][c], in[1], F.r[2][c], in[2], 0.0);
            sat |= check_entry(got, d + (double)F.p[c], "v", c);
            satd |= check_entry(gotd, d, "w", c);
        }
        check_status(st, sat);
        check_status(std, satd);
        /* in place */
        DHT_EQ_INT(dh_frame_apply_point_q(&F, &u, &u), st);
        DHT_TRUE(memcmp(&u, &v, sizeof u) == 0);
    }
}

/*
 * Saturation direction when the 64-bit sum wraps, and the exact edges of
 * the int32 range. A fast 64-bit accumulation wraps modulo 2^64 for sums
 * beyond 2^63 (three products of 2^62), so the sign of the wrapped sum is
 * wrong; the result must still saturate toward the sign of the TRUE sum.
 * All expected values are exact (worked out below), for every build
 * (DH_SMALL takes the saturation direction from the high words instead
 * of an exact recomputation: this is its check).
 */
static void fixed_saturation_wrap_and_edges(void)
{
    dh_frame_q A, B, C;
    dh_vec3_q u, v;
    int c, r;
    /* mul: (-2)(2 - 2^-30) * 3 < -2^63 / 2^30: every rotation entry
     * saturates to INT32_MIN (the wrapped sum is positive) */
    for (c = 0; c < 3; c++) {
        for (r = 0; r < 3; r++) {
            A.r[c][r] = INT32_MIN;
            B.r[c][r] = INT32_MAX;
        }
        A.p[c] = 0;
        B.p[c] = 0;
    }
    DHT_EQ_INT(dh_frame_mul_q(&A, &B, &C), DH_ERR_OVERFLOW);
    for (c = 0; c < 3; c++) {
        for (r = 0; r < 3; r++) DHT_EQ_INT(C.r[c][r], INT32_MIN);
        DHT_EQ_INT(C.p[c], 0);
    }
    /* inv: p' = -R^T p = -3 * 2^62 (wraps to +2^62) and +3 * (2^62 - 2^31) */
    A.p[0] = INT32_MIN;
    A.p[1] = INT32_MIN;
    A.p[2] = INT32_MIN;
    DHT_EQ_INT(dh_frame_inv_q(&A, &C), DH_ERR_OVERFLOW);
    for (c = 0; c < 3; c++) DHT_EQ_INT(C.p[c], INT32_MIN);
    A.p[0] = INT32_MAX;
    A.p[1] = INT32_MAX;
    A.p[2] = INT32_MAX;
    DHT_EQ_INT(dh_frame_inv_q(&A, &C), DH_ERR_OVERFLOW);
    for (c = 0; c < 3; c++) DHT_EQ_INT(C.p[c], INT32_MAX);
    /* apply: 3 * 2^62 + p 2^30 for p = -2^31, 0, 2^31 - 1 (the last two
     * beyond 2^63) all saturate up; with u = INT32_MAX all saturate down */
    A.p[0] = INT32_MIN;
    A.p[1] = 0;
    A.p[2] = INT32_MAX;
    u.x = INT32_MIN; u.y = INT32_MIN; u.z = INT32_MIN;
    DHT_EQ_INT(dh_frame_apply_point_q(&A, &u, &v), DH_ERR_OVERFLOW);
    DHT_EQ_INT(v.x, INT32_MAX); DHT_EQ_INT(v.y, INT32_MAX); DHT_EQ_INT(v.z, INT32_MAX);
    DHT_EQ_INT(dh_frame_apply_dir_q(&A, &u, &v), DH_ERR_OVERFLOW);
    DHT_EQ_INT(v.x, INT32_MAX); DHT_EQ_INT(v.y, INT32_MAX); DHT_EQ_INT(v.z, INT32_MAX);
    u.x = INT32_MAX; u.y = INT32_MAX; u.z = INT32_MAX;
    DHT_EQ_INT(dh_frame_apply_point_q(&A, &u, &v), DH_ERR_OVERFLOW);
    DHT_EQ_INT(v.x, INT32_MIN); DHT_EQ_INT(v.y, INT32_MIN); DHT_EQ_INT(v.z, INT32_MIN);
    /* range edges, ties up: p_0 of A * B is 2^30 b0 + b1 (+ 2^29 to round)
     * with A.r[0][0] = 1.0, A.r[1][0] = 2^-30, everything else 0 */
    memset(&A, 0, sizeof A);
    memset(&B, 0, sizeof B);
    A.r[0][0] = DH_Q30_ONE;
    A.r[1][0] = 1;
    B.p[0] = INT32_MAX;
    B.p[1] = (1 << 29) - 1;            /* INT32_MAX + 0.5 - 2^-30: fits */
    DHT_EQ_INT(dh_frame_mul_q(&A, &B, &C), DH_OK);
    DHT_EQ_INT(C.p[0], INT32_MAX);
    B.p[1] = 1 << 29;                  /* INT32_MAX + 0.5: rounds up, saturates */
    DHT_EQ_INT(dh_frame_mul_q(&A, &B, &C), DH_ERR_OVERFLOW);
    DHT_EQ_INT(C.p[0], INT32_MAX);
    DHT_EQ_INT(C.p[1], 0);
    B.p[0] = INT32_MIN;
    B.p[1] = -(1 << 29);               /* INT32_MIN - 0.5: rounds up to INT32_MIN, fits */
    DHT_EQ_INT(dh_frame_mul_q(&A, &B, &C), DH_OK);
    DHT_EQ_INT(C.p[0], INT32_MIN);
    B.p[1] = -(1 << 29) - 1;           /* INT32_MIN - 0.5 - 2^-30: saturates */
    DHT_EQ_INT(dh_frame_mul_q(&A, &B, &C), DH_ERR_OVERFLOW);
    DHT_EQ_INT(C.p[0], INT32_MIN);
    /* the same edges through apply (u = (b0, b1, 0)) and inv (p' = -R^T p) */
    u.x = INT32_MAX; u.y = (1 << 29) - 1; u.z = 0;
    DHT_EQ_INT(dh_frame_apply_dir_q(&A, &u, &v), DH_OK);
    DHT_EQ_INT(v.x, INT32_MAX);
    u.y = 1 << 29;
    DHT_EQ_INT(dh_frame_apply_dir_q(&A, &u, &v), DH_ERR_OVERFLOW);
    DHT_EQ_INT(v.x, INT32_MAX);
    /* inv: p'_0 = -(r00 p0 + r01 p1 + r02 p2) with column 0 of R = (1, 2^-30, 0):
     * -(INT32_MIN 2^30 + 2^29 - 1) = INT32_MAX + 0.5 + 2^-30 ... rounds to 2^31: saturates;
     * -(INT32_MIN 2^30 + 2^29 + 1) = INT32_MAX + 0.5 - 2^-30: fits */
    memset(&A, 0, sizeof A);
    A.r[0][0] = DH_Q30_ONE;
    A.r[0][1] = 1;
    A.p[0] = INT32_MIN;
    A.p[1] = (1 << 29) - 1;
    DHT_EQ_INT(dh_frame_inv_q(&A, &C), DH_ERR_OVERFLOW);
    DHT_EQ_INT(C.p[0], INT32_MAX);
    A.p[1] = (1 << 29) + 1;
    DHT_EQ_INT(dh_frame_inv_q(&A, &C), DH_OK);
    DHT_EQ_INT(C.p[0], INT32_MAX);
    A.p[1] = 1 << 29;                  /* exactly INT32_MAX + 0.5: ties up, saturates */
    DHT_EQ_INT(dh_frame_inv_q(&A, &C), DH_ERR_OVERFLOW);
    DHT_EQ_INT(C.p[0], INT32_MAX);
}

/* re-orthonormalisation refuses frames too far from a rotation (F
 * untouched, also by the void form); ortho_error saturates */
static void fixed_orthonormalize_bad(void)
{
    dh_frame_q F, G, H, K;
    dh_frame_identity_q(&F);
    F.p[0] = 123;
    F.r[0][0] = (int32_t)(1.3 * TWO30); /* entry beyond 1.25 */
    G = F;
    DHT_EQ_INT(dh_frame_orthonormalize_q(&F, &F), DH_ERR_NOT_RIGID);
    DHT_TRUE(memcmp(&F, &G, sizeof F) == 0);
    dh_frame_identity_q(&H); /* out of place: out untouched too */
    K = H;
    DHT_EQ_INT(dh_frame_orthonormalize_q(&F, &H), DH_ERR_NOT_RIGID);
    DHT_TRUE(memcmp(&H, &K, sizeof H) == 0);
    /* entries within 1.25 but R^T R - I beyond 1/8 (0.7 off the diagonal) */
    dh_frame_identity_q(&F);
    F.r[1][0] = (int32_t)(0.7 * TWO30);
    G = F;
    DHT_EQ_INT(dh_frame_orthonormalize_q(&F, &F), DH_ERR_NOT_RIGID);
    DHT_TRUE(memcmp(&F, &G, sizeof F) == 0);
    /* a reflection is kept a reflection (det sign preserved, documented) */
    dh_frame_identity_q(&F);
    F.r[2][2] = -DH_Q30_ONE;
    F.r[0][0] = DH_Q30_ONE + 1000;
    DHT_EQ_INT(dh_frame_orthonormalize_q(&F, &F), DH_OK);
    DHT_TRUE(F.r[2][2] < 0);
    DHT_TRUE(dh_frame_ortho_error_q(&F) <= 2);
    /* saturation of the drift measure: every entry -2.0 */
    {
        int c, r;
        for (c = 0; c < 3; c++)
            for (r = 0; r < 3; r++) F.r[c][r] = INT32_MIN;
    }
    DHT_EQ_INT(dh_frame_ortho_error_q(&F), INT32_MAX);
    G = F;
    DHT_EQ_INT(dh_frame_orthonormalize_q(&F, &F), DH_ERR_NOT_RIGID);
    DHT_TRUE(memcmp(&F, &G, sizeof F) == 0);
}


static void mat4_identity(dh_mat4_f32 *T)
{
    int c, r;
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) T->m[c][r] = (c == r) ? 1.0f : 0.0f;
}

/* float -> fixed: NaN/Inf anywhere -> NAN (F untouched); out of range ->
 * saturated + OVERFLOW; bottom row -> NOT_RIGID (F written); precedence */
static void fixed_from_mat4_bad(void)
{
    static const uint32_t bad[] = { 0x7FC00000u, 0x7F800000u, 0xFF800000u, 0xFF800001u };
    const double pos_lim = ldexp(1.0, 31 - DH_QPOS_FRAC);
    dh_mat4_f32 T;
    dh_frame_q F;
    unsigned e, k;
    for (e = 0; e < 16; e++) {
        for (k = 0; k < 4; k++) {
            mat4_identity(&T);
            T.m[e / 4][e % 4] = f32_bits(bad[k]);
            T.m[0][0] = (e == 0) ? T.m[0][0] : 5.0f; /* an overflow elsewhere: NaN wins */
            CANARY(F);
            DHT_EQ_INT(dh_frame_from_mat4_q(&T, &F), DH_ERR_NAN);
            UNTOUCHED(F);
        }
    }
    /* rotation entries: -2.0 fits exactly, 2.0 and beyond saturate */
    mat4_identity(&T);
    T.m[0][0] = -2.0f;
    T.m[1][0] = 2.0f;
    T.m[2][0] = 1e30f;
    T.m[0][1] = -1e30f;
    T.m[1][1] = 1.9999999f;
    T.m[3][0] = (float)pos_lim;          /* 2^(31-F): saturates */
    T.m[3][1] = (float)-pos_lim;         /* fits: INT32_MIN */
    T.m[3][2] = 1.5f;
    CANARY(F);
    DHT_EQ_INT(dh_frame_from_mat4_q(&T, &F), DH_ERR_OVERFLOW);
    DHT_EQ_INT(F.r[0][0], INT32_MIN);
    DHT_EQ_INT(F.r[1][0], INT32_MAX);
    DHT_EQ_INT(F.r[2][0], INT32_MAX);
    DHT_EQ_INT(F.r[0][1], INT32_MIN);
    DHT_EQ_INT(F.r[1][1], (int32_t)(1.9999999f * 1073741824.0f));
    DHT_EQ_INT(F.r[2][2], DH_Q30_ONE);
    DHT_EQ_INT(F.p[0], INT32_MAX);
    DHT_EQ_INT(F.p[1], INT32_MIN);
    DHT_EQ_INT(F.p[2], (int32_t)(1.5 * ldexp(1.0, DH_QPOS_FRAC)));
    /* overflow takes precedence over a bad bottom row */
    T.m[0][3] = 0.5f;
    DHT_EQ_INT(dh_frame_from_mat4_q(&T, &F), DH_ERR_OVERFLOW);
    /* bad bottom row alone: NOT_RIGID, F fully written from the top rows */
    for (e = 0; e < 4; e++) {
        DHT_EQ_INT(dh_mat4_rotz_f32(90.0f, &T), DH_OK);
        T.m[3][0] = 3.0f;
        T.m[e][3] = (e == 3) ? 2.0f : 1.0f;
        CANARY(F);
        DHT_EQ_INT(dh_frame_from_mat4_q(&T, &F), DH_ERR_NOT_RIGID);
        DHT_EQ_INT(F.r[0][1], DH_Q30_ONE);
        DHT_EQ_INT(F.r[1][0], -DH_Q30_ONE);
        DHT_EQ_INT(F.r[0][0], 0);
        DHT_EQ_INT(F.r[2][2], DH_Q30_ONE);
        DHT_EQ_INT(F.p[0], (int32_t)(3.0 * ldexp(1.0, DH_QPOS_FRAC)));
        DHT_EQ_INT(F.p[1], 0);
    }
}

static const dht_case cases[] = {
    DHT_CASE(fixed_rot_axis_zero_and_extreme),
    DHT_CASE(fixed_rot_elem_extreme_angles),
    DHT_CASE(fixed_mul_overflow),
    DHT_CASE(fixed_inv_overflow),
    DHT_CASE(fixed_apply_overflow),
    DHT_CASE(fixed_saturation_wrap_and_edges),
    DHT_CASE(fixed_orthonormalize_bad),
    DHT_CASE(fixed_from_mat4_bad),
};
DHT_MAIN(cases)
