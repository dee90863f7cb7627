/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_euler.c - Euler angles <-> rotation matrix for the 12 axis sequences,
 * intrinsic (upper-case names) and extrinsic (lower-case names), with the
 * scipy naming convention and an explicit gimbal-lock policy (method:
 * docs/design.md, "Rotations").
 */
#include <math.h>

#include "dhmath/rot.h"
#include "dhmath/trig.h"
#include "../internal/dh_mathf.h"
#include "../internal/dh_floatops.h"


/* axes of the 12 intrinsic sequences, in dh_euler_seq order (0 x, 1 y, 2 z) */
static const unsigned char euler_axes[12][3] = {
    {0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0},
    {0, 1, 0}, {0, 2, 0}, {1, 0, 1}, {1, 2, 1}, {2, 0, 2}, {2, 1, 2}
};

static const char euler_names[DH_EULER_COUNT][4] = {
    "XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX",
    "XYX", "XZX", "YXY", "YZY", "ZXZ", "ZYZ",
    "xyz", "xzy", "yxz", "yzx", "zxy", "zyx",
    "xyx", "xzx", "yxy", "yzy", "zxz", "zyz"
};

dh_status dh_euler_parse(const char *str, dh_euler_seq *seq)
{
    int ax[3], n, idx, lower = 0;
    DH_ASSERT(str != NULL && seq != NULL);
    for (n = 0; n < 3; n++) {
        char ch = str[n];
        int is_lower;
        if (ch >= 'X' && ch <= 'Z') {
            ax[n] = ch - 'X';
            is_lower = 0;
        } else if (ch >= 'x' && ch <= 'z') {
            ax[n] = ch - 'x';
            is_lower = 1;
        } else {
            return DH_ERR_ARG; /* also catches a NUL before the 3rd letter */
        }
        if (n == 0) {
            lower = is_lower;
        } else if (is_lower != lower || ax[n] == ax[n - 1]) {
            return DH_ERR_ARG;
        }
    }
    if (str[3] != '\0') return DH_ERR_ARG;
    for (idx = 0; idx < 12; idx++) {
        if (euler_axes[idx][0] == ax[0] && euler_axes[idx][1] == ax[1] &&
            euler_axes[idx][2] == ax[2]) {
            *seq = (dh_euler_seq)(idx + (lower ? 12 : 0));
            return DH_OK;
        }
    }
    return DH_ERR_ARG; /* not reached: every valid triple is in the table */
}

const char *dh_euler_name(dh_euler_seq seq)
{
    unsigned int u = (unsigned int)seq;
    if (u >= (unsigned int)DH_EULER_COUNT) return "???";
    return euler_names[u];
}

/* M = M Rq(t), sine s, cosine c: only columns q+1 and q+2 (cyclic) change. */
static void euler_post_rot(dh_mat3_f32 *M, int q, float s, float c)
{
    int u = (q == 2) ? 0 : q + 1, w = (q == 0) ? 2 : q - 1, r; /* no division (Cortex-M0) */
    for (r = 0; r < 3; r++) {
        float mu = M->m[u][r], mw = M->m[w][r];
        M->m[u][r] = c * mu + s * mw;
        M->m[w][r] = c * mw - s * mu;
    }
}

dh_status dh_euler_to_mat3_f32(dh_euler_seq seq, const float ang_deg[3], dh_mat3_f32 *R)
{
    unsigned int u = (unsigned int)seq;
    int ax[3], n, r, c;
    float sn[3], cs[3];
    dh_mat3_f32 M;
    DH_ASSERT(R != NULL && ang_deg != NULL);
    if (u >= (unsigned int)DH_EULER_COUNT) return DH_ERR_ARG;
    for (n = 0; n < 3; n++) {
        if (dh_sincos_f32(ang_deg[n], &sn[n], &cs[n]) != DH_OK) return DH_ERR_NAN;
    }
    if (u < 12u) {
        for (n = 0; n < 3; n++) ax[n] = euler_axes[u][n];
    } else {
        /* extrinsic (a, b, c) about l0, l1, l2 = intrinsic (c, b, a) about
         * l2, l1, l0: reverse the axes and the angles */
        float t;
        for (n = 0; n < 3; n++) ax[n] = euler_axes[u - 12u][2 - n];
        t = sn[0]; sn[0] = sn[2]; sn[2] = t;
        t = cs[0]; cs[0] = cs[2]; cs[2] = t;
    }
    for (c = 0; c < 3; c++) {
        for (r = 0; r < 3; r++) M.m[c][r] = (r == c) ? 1.0f : 0.0f;
    }
    for (n = 0; n < 3; n++) euler_post_rot(&M, ax[n], sn[n], cs[n]);
    for (c = 0; c < 3; c++) {
        for (r = 0; r < 3; r++) R->m[c][r] = M.m[c][r] + 0.0f; /* no -0 */
    }
    return DH_OK;
}

/* atan2(y, x) in DEGREES, in (-180, 180]: dh_atan2f_ only sees angles of
 * at most 45 deg, combined as phi, +-90 -+ phi, +-180 -+ phi, so the result
 * near +-90 and +-180 is limited only by the final rounding in degrees.
 * atan2(+-0, x < 0) is 180. */
static float euler_atan2_deg(float y, float x)
{
    float ax = fabsf(x), ay = fabsf(y), d;
    if (dh_feq_f32(ax, 0.0f) && dh_feq_f32(ay, 0.0f)) {
        d = 0.0f;                                               /* undefined: 0 */
    } else if (ay <= ax && x > 0.0f) {
        d = dh_atan2f_(y, x) * DH_RAD2DEG_F;                    /* [-45, 45] */
    } else if (ay > ax && y > 0.0f) {
        d = 90.0f - dh_atan2f_(x, y) * DH_RAD2DEG_F;            /* (45, 135) */
    } else if (ay > ax) {
        d = -90.0f + dh_atan2f_(x, -y) * DH_RAD2DEG_F;          /* (-135, -45) */
    } else if (!(y < 0.0f)) {
        d = 180.0f - dh_atan2f_(y, -x) * DH_RAD2DEG_F;          /* [135, 180] */
    } else {
        d = -180.0f + dh_atan2f_(-y, -x) * DH_RAD2DEG_F;        /* (-180, -135] */
    }
    if (d > 180.0f || d <= -180.0f) d = 180.0f;
    return d + 0.0f; /* no -0 */
}

static float euler_clamp(float d, float lo, float hi)
{
    if (d < lo) d = lo;
    if (d > hi) d = hi;
    return d + 0.0f;
}

/*
 * Intrinsic angles (a, b, c), in degrees, of R = Ri(a) Rj(b) Rk(c); e_i x
 * e_j = s e_l, l the axis that is neither i nor j. The angle f on the pole
 * side (c for zero_first == 0, read from row i; a for zero_first == 1,
 * read from column k) is 0 at the pole; g is fitted to the residual rotation
 * (R Rk(c)^T = Ri(a) Rj(b), or Ri(a)^T R = Rj(b) Rk(c)), from the
 * column / row j of it: p = cf R(j,j) + t sf P2, q = cf Q1 + t sf Q2.
 *   Tait-Bryan (k == l): row i = cb cc e_i - s cb sc e_j + s sb e_k,
 *     column k = s sb e_i - s cb sa e_j + cb ca e_k.
 *   proper (k == i): row i = cb e_i + sb sc e_j + s sb cc e_l,
 *     column i = cb e_i + sb sa e_j - s sb ca e_l.
 */
static void euler_solve(const dh_mat3_f32 *R, int i, int j, int k, int zero_first, float out[3])
{
    int proper = (i == k);
    int l = proper ? 3 - i - j : k;
    float s = (j == i + 1 || j == i - 2) ? 1.0f : -1.0f; /* cyclic: xy, yz, zx */
    float t = s, u = s, y, x, p2, q1, q2, n, b, f, g, cf, sf;

    if (!proper && !zero_first) {
        y = -s * DH_M3(R, i, j); x = DH_M3(R, i, i); p2 = DH_M3(R, j, i); q1 = DH_M3(R, k, j); q2 = DH_M3(R, k, i);
    } else if (!proper) {
        y = -s * DH_M3(R, j, k); x = DH_M3(R, k, k); p2 = DH_M3(R, k, j); q1 = DH_M3(R, j, i); q2 = DH_M3(R, k, i);
    } else if (!zero_first) {
        y = DH_M3(R, i, j); x = s * DH_M3(R, i, l); p2 = DH_M3(R, j, l); q1 = DH_M3(R, l, j); q2 = DH_M3(R, l, l); t = -s;
    } else {
        y = DH_M3(R, j, i); x = -s * DH_M3(R, l, i); p2 = DH_M3(R, l, j); q1 = DH_M3(R, j, l); q2 = DH_M3(R, l, l); u = -s;
    }
    n = dh_sqrt_f32(x * x + y * y);           /* cos b (Tait-Bryan), sin b (proper) */
    b = proper ? euler_atan2_deg(n, DH_M3(R, i, i)) : euler_atan2_deg(s * DH_M3(R, i, k), n);
    if (n <= DH_EULER_POLE_TOL) {
        f = 0.0f; cf = 1.0f; sf = 0.0f;
    } else {
        f = euler_atan2_deg(y, x);
        cf = x / n;
        sf = y / n;
    }
    g = euler_atan2_deg(u * (cf * q1 + t * sf * q2), cf * DH_M3(R, j, j) + t * sf * p2);
    out[0] = zero_first ? f : g;
    out[1] = b;
    out[2] = zero_first ? g : f;
}

dh_status dh_mat3_to_euler_f32(const dh_mat3_f32 *R, dh_euler_seq seq, float ang_deg[3])
{
    unsigned int u = (unsigned int)seq;
    const unsigned char *ax;
    float dg[3], t;
    int proper;
    dh_status st;
    DH_ASSERT(R != NULL && ang_deg != NULL);
    if (u >= (unsigned int)DH_EULER_COUNT) return DH_ERR_ARG;
    st = dh_mat3_check_rot_f32(R, DH_ROT_TOL);
    if (st != DH_OK) return st;
    if (u < 12u) {
        ax = euler_axes[u];
        euler_solve(R, ax[0], ax[1], ax[2], 0, dg);
    } else {
        /* extrinsic (a, b, c) = intrinsic (c, b, a) of the reversed axes;
         * the letter-third angle c (intrinsic first) is 0 at the pole */
        ax = euler_axes[u - 12u];
        euler_solve(R, ax[2], ax[1], ax[0], 1, dg);
        t = dg[0]; dg[0] = dg[2]; dg[2] = t;
    }
    proper = (ax[0] == ax[2]);
    /* the clamps only guard the documented ranges of the middle angle */
    ang_deg[0] = dg[0];
    ang_deg[1] = proper ? euler_clamp(dg[1], 0.0f, 180.0f) : euler_clamp(dg[1], -90.0f, 90.0f);
    ang_deg[2] = dg[2];
    return DH_OK;
}
