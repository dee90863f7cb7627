/*
 * dh_mat4_inv.c - inverses of float 4x4 transforms (seed 000, sec. 11):
 * the closed-form rigid inverse (eq. 1.57), a general inverse with a
 * scale-invariant singularity test, rigidity checks and the automatic
 * choice between the two inverses.
 *
 * Fix (issue 5 follow-up): non-affine T with p = 0 and a large bottom row
 * q, e.g. Persp(axis, 1e-3), were balanced with sg = 1, so the certified
 * path measured the condition number of T itself (~ |q|^2) and rejected
 * them as singular, while the default build's projective fast path
 * (whose bound has |p| |q| = 0) accepted T and its certified path
 * rejected 2^20 T: the status depended on the path and on the scale.
 * Such T is a similarity diag(1, 1, 1, sg), sg -> 0, away from
 * blockdiag(R, w); the balancing now takes q sg = 2^-24 of the rows of R
 * when p is exactly zero (the mirror of the q = 0 rule), so both builds
 * return DH_OK at every power-of-two scale with an exact inverse of
 * Persp. Why it is sound: see "p = 0" below.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "dhmath/dh_mat4.h"

#if DH_SMALL
/*
 * DH_SMALL: the general inverse is the certified path alone, with the
 * arithmetic of the default build's certified path (the same statuses and
 * bits as that path for every input), its balanced norms, residual and
 * unscaling from one loop, and the libm-free square root (correctly
 * rounded like sqrtf: same bits). The statuses are the default build's:
 * its adjugate fast paths accept only what its certified path accepts
 * (since the p = 0 fix above also for p = 0 and a large q).
 */
#include "dh_mathf.h"
#define DH_SQRTF dh_sqrtf_
#else
#define DH_SQRTF sqrtf
#endif

#if !DH_SMALL
static int dh_finite(float x) { return fabsf(x) <= FLT_MAX; }
#endif

#if defined(__GNUC__) || defined(__clang__)
#define DH_NOINLINE __attribute__((noinline))
#define DH_INLINE __inline__ __attribute__((always_inline))
#else
#define DH_NOINLINE
#define DH_INLINE
#endif

/* ---------------------------------------------------------------------- */
/* rigid inverse                                                          */
/* ---------------------------------------------------------------------- */

#if DH_SMALL
/* the same operations as loops: p is read first (out may alias T), then
 * R^T by pair swaps that read both elements before writing either (p is
 * not written), then the translation from R^T as stored in out (the same
 * products in the same order) */
/*
 * The affine completion shared with dh_inv_certified: with R^-1 (row
 * view) in rows 0..2, columns 0..2 of X, writes the translation
 * -(R^-1 p) = 0 - (p_x X_0i + p_y X_1i + p_z X_2i) into row 3 and the
 * bottom row 0 0 0 1 of T^-1 (column 3 of the row view). Returns NaN iff
 * a translation entry is NaN or Inf.
 */
static DH_NOINLINE float dh_affine_t(dh_mat4_f32 *X, float px, float py, float pz)
{
    float z = 0.0f;
    int i;
    for (i = 0; i < 3; i++) {
        const float t = 0.0f - (px * X->m[0][i] + py * X->m[1][i] + pz * X->m[2][i]);
        X->m[3][i] = t;
        X->m[i][3] = 0.0f;
        z += t * 0.0f;
    }
    X->m[3][3] = 1.0f;
    return z;
}

void dh_mat4_inv_rigid_f32(dh_mat4_f32 *out, const dh_mat4_f32 *T)
{
    float px, py, pz;
    int i, j;
    DH_ASSERT(out != NULL && T != NULL);
    px = T->m[3][0];
    py = T->m[3][1];
    pz = T->m[3][2];
    for (i = 0; i < 3; i++) {
        for (j = 0; j <= i; j++) {
            const float a = T->m[i][j], b = T->m[j][i];
            out->m[i][j] = b;
            out->m[j][i] = a;
        }
    }
    (void)dh_affine_t(out, px, py, pz);
}
#else
void dh_mat4_inv_rigid_f32(dh_mat4_f32 *out, const dh_mat4_f32 *T)
{
    float nx, ny, nz, ox, oy, oz, ax, ay, az, px, py, pz;
    DH_ASSERT(out != NULL && T != NULL);
    nx = T->m[0][0]; ny = T->m[0][1]; nz = T->m[0][2];
    ox = T->m[1][0]; oy = T->m[1][1]; oz = T->m[1][2];
    ax = T->m[2][0]; ay = T->m[2][1]; az = T->m[2][2];
    px = T->m[3][0]; py = T->m[3][1]; pz = T->m[3][2];
    /* eq. 1.57: rows of the inverse are n, o, a; column p is -R^T p.
     * 0 - dot (not -dot) keeps an exact zero positive. */
    out->m[0][0] = nx; out->m[0][1] = ox; out->m[0][2] = ax; out->m[0][3] = 0.0f;
    out->m[1][0] = ny; out->m[1][1] = oy; out->m[1][2] = ay; out->m[1][3] = 0.0f;
    out->m[2][0] = nz; out->m[2][1] = oz; out->m[2][2] = az; out->m[2][3] = 0.0f;
    out->m[3][0] = 0.0f - (px * nx + py * ny + pz * nz);
    out->m[3][1] = 0.0f - (px * ox + py * oy + pz * oz);
    out->m[3][2] = 0.0f - (px * ax + py * ay + pz * az);
    out->m[3][3] = 1.0f;
}
#endif

/* ---------------------------------------------------------------------- */
/* general inverse                                                        */
/* ---------------------------------------------------------------------- */

/*
 * The helpers below treat the storage m[i][j] as ROW i, COLUMN j of a
 * matrix M. For a dh_mat4_f32 (column-major) that M is T^T. Since
 * (T^T)^-1 = (T^-1)^T, inverting M in this view and storing the result the
 * same way yields T^-1 in the library's column-major layout, with no
 * transposition. Norms and residuals of M are the 1-norms and the right
 * residual T X - I of T.
 */

static int dh_is_affine(const dh_mat4_f32 *T);
#if !DH_SMALL
static DH_NOINLINE float dh_affine_prescale(const dh_mat4_f32 *T);
#endif

/* Unit roundoff of float, 2^-24. */
#define DH_U24 5.9604644775390625e-8f

/*
 * Balanced norms. The homogeneous coordinate carries a different unit from
 * the other three (a length against a pure number), so the condition test
 * is made on D^-1 M D with D = diag(1, 1, 1, sg): in T's terms the column p
 * is divided by sg and the bottom row multiplied by sg. The similarity does
 * not change what is computed, only how ill-conditioning is measured: a
 * rigid transform with |p| = 1e6 is as well conditioned as one with |p| = 1
 * (it is the same motion in other units). sg balances the last row and
 * column (Osborne's choice, sqrt(|p| / |q|)); for affine matrices (q = 0) it
 * makes the p column negligible.
 *
 * p = 0 (exactly: the three entries are +-0; p only below the range of
 * the sums, 2^-148, keeps sg = 1 as before). Osborne's factor is 0 and the
 * balanced condition number decreases towards that of blockdiag(R, w) as
 * sg -> 0, so sg = 2^-24 m3 / |q| (clamped to [2^-60, 2^60] like the
 * others) makes the q row negligible, as the q = 0 rule does for p.
 * Soundness: the certificate (b) proves M non-singular for ANY sg (an
 * induced norm of a similarity), and its rounding and underflow bounds
 * only use the clamp; but it bounds the error of the entries weighted by
 * sg (the bottom row of T^-1) only as ||.|| / sg, i.e. not at all for a
 * tiny sg. A rule that merely forced a tiny sg therefore accepts any
 * bottom row: with p not exactly zero, or q sg leaving the normal range
 * in the balanced matrix (its bits lost, and the unbalancing divides the
 * loss by sg), the returned bottom row can be wrong while the residual
 * passes. Here that row is exact by structure instead: row 3 of the row
 * view is (0, 0, 0, w), Gauss-Jordan never pivots on it before step 3
 * (zero in columns 0..2; an all-zero column is a zero pivot), so it stays
 * (0, 0, 0, 1/w), every residual entry weighted 1/sg is exactly 0, and
 * the bottom row of T^-1 is the elimination applied to q sg followed by
 * the exact power-of-two unbalancing: the error of a backward-stable
 * solve with R (pivots chosen on R alone), plus at most 2^-150 per entry
 * of q sg below FLT_MIN, i.e. 2^-150 / sg * ||R^-1|| / |w| after the
 * unbalancing (sg >= 2^-60). Measured: max|X - T^-1| <= 2.6 cond u
 * max|T^-1|, right residual <= 0.053, nothing below the condition limit
 * rejected (test_mat4_inv_regress, p_zero_magnitudes_sweep, 400 seeds).
 */
#if !DH_SMALL
/*
 * sg for |p|_1 / 4 == 0: 1 unless p is exactly 0 (not only below 2^-148),
 * else the mirror of the q = 0 rule below, q sg 2^-24 of the rows of R
 * (see "p = 0" above), clamped like the others. Out of line: no extra
 * registers in dh_inv_certified's frame (M0+ stack guard).
 */
static DH_NOINLINE float dh_balance_p0(const dh_mat4_f32 *M)
{
    /* |q| / 4 and the largest row sum of |R| / 4 as in dh_balance */
    const float rq = fabsf(M->m[0][3] * 0.25f) + fabsf(M->m[1][3] * 0.25f) + fabsf(M->m[2][3] * 0.25f);
    float m3 = 0.0f, sg;
    int i;
    for (i = 0; i < 3; i++) {
        const float rs = fabsf(M->m[i][0] * 0.25f) + fabsf(M->m[i][1] * 0.25f) + fabsf(M->m[i][2] * 0.25f);
        m3 = (rs > m3) ? rs : m3;
    }
    if (!(M->m[3][0] == 0.0f && M->m[3][1] == 0.0f && M->m[3][2] == 0.0f && rq > 0.0f && m3 > 0.0f)) return 1.0f;
    sg = m3 / rq * DH_U24;
    if (sg > 1.15292150e18f) sg = 1.15292150e18f;       /* 2^60 */
    if (sg < 8.67361738e-19f) sg = 8.67361738e-19f;     /* 2^-60 */
    return sg;
}

static float dh_balance(const dh_mat4_f32 *M)
{
    /* the sums are of |M_ij| / 4, so that three entries near FLT_MAX do not
     * overflow (which made sg = 2^60 and well-conditioned matrices with
     * entries ~2^126 "singular"); only ratios are used, which the exact
     * factor 1/4 does not change (below FLT_MIN it only rounds) */
    const float cp = fabsf(M->m[3][0] * 0.25f) + fabsf(M->m[3][1] * 0.25f) + fabsf(M->m[3][2] * 0.25f); /* |p| */
    const float rq = fabsf(M->m[0][3] * 0.25f) + fabsf(M->m[1][3] * 0.25f) + fabsf(M->m[2][3] * 0.25f); /* |q| */
    float m3 = 0.0f, sg;
    int i;
    for (i = 0; i < 3; i++) {
        const float rs = fabsf(M->m[i][0] * 0.25f) + fabsf(M->m[i][1] * 0.25f) + fabsf(M->m[i][2] * 0.25f);
        m3 = (rs > m3) ? rs : m3;
    }
    if (cp == 0.0f) return dh_balance_p0(M);
    if (rq > 0.0f) sg = DH_SQRTF(cp) / DH_SQRTF(rq);
    else sg = (m3 > 0.0f) ? cp / m3 * 16777216.0f : 1.0f;
    /* keep sg * (anything O(1..2^60)) finite */
    if (sg > 1.15292150e18f) sg = 1.15292150e18f;       /* 2^60 */
    if (sg < 8.67361738e-19f) sg = 8.67361738e-19f;     /* 2^-60 */
    return sg;
}
#endif

#if !DH_SMALL
/*
 * Row view: column 3 of rows 0..2 times f, row 3 of columns 0..2 over f,
 * f the power of two nearest to sg (within a factor sqrt(2); exact unless
 * an element leaves the normal range). undo == 0 gives the balanced
 * D^-1 M D, undo != 0 takes the inverse of that back to M^-1.
 */
static DH_NOINLINE void dh_rebalance(dh_mat4_f32 *X, float sg, int undo)
{
    float f = sg * 1.41421356f, fi;
    uint32_t b;
    int i;
    memcpy(&b, &f, sizeof b);
    b &= 0x7F800000u; /* sg in [2^-60, 2^60]: a normal power of two */
    memcpy(&f, &b, sizeof f);
    fi = 1.0f / f;
    if (undo) {
        const float t = f;
        f = fi;
        fi = t;
    }
    for (i = 0; i < 3; i++) {
        X->m[i][3] *= f;
        X->m[3][i] *= fi;
    }
}
#endif

/*
 * Element (i, j) of the row-view matrix the certified path works on: s M
 * (aff == 0), or for an affine T the matrix blockdiag(s R, 1) (aff != 0):
 * the inverse of an affine transform is [R^-1, -R^-1 p], so only R is
 * inverted. s is an exact power of two that makes the decision
 * independent of the scale of M (of R).
 */
static DH_INLINE float dh_at(const dh_mat4_f32 *M, int i, int j, float s, int aff)
{
    if (!aff || (i < 3 && j < 3)) return M->m[i][j] * s;
    return (i == j) ? 1.0f : 0.0f;
}

#if DH_SMALL
/* element (i, j) of the row view weighted like D^-1 . D with w in place of
 * sg: column 3 of rows 0..2 times w, columns 0..2 of row 3 over w */
static DH_NOINLINE float dh_wt(float q, int i, int j, float w)
{
    if (i < 3) return (j < 3) ? q : q * w;
    return (j < 3) ? q / w : q;
}

/*
 * The three balanced norms of the certified path in one loop (the row
 * weights of dh_norm_rows below, the same operations in the same order);
 * NaN if an element is NaN or Inf:
 *  - X != NULL: the residual ||X A - I||, A = dh_at(M, ., ., s, aff)
 *    (dh_residual below);
 *  - X == NULL: ||A|| (dh_norm_rows; 0 + 1 * A_ij is A_ij up to the sign
 *    of a zero), and W != NULL receives A (the X = A of dh_inv_certified
 *    below; a zero of A as +0 only changes signs of zeros of the inverse,
 *    which the unscaling maps to +0); M = the inverse with s == 1,
 *    aff == 0 gives ||X||;
 *  - aff < 0 (X == NULL, W == M, g = 1 / s): dh_unscale below,
 *    M = s M with the balanced norm of what that lost (its extra NaN
 *    propagation only turns an Inf, i.e. DH_ERR_OVERFLOW, into a NaN,
 *    which fails the same test).
 * Otherwise the value stored
 * in W (and measured) is dh_wt(q, ., ., g); g == 1 stores q itself. With
 * M == W, s == 1, aff == 0 and g the power of two of dh_rebalance (or its
 * inverse) this is the default build's dh_rebalance (q / g == q * (1 / g):
 * g is a normal power of two), with the balanced norm of the result
 * (X = 0 + 1 * X only maps -0 to +0, which changes no later sum,
 * comparison or unscaled value).
 */
static DH_NOINLINE float dh_bnorm(const dh_mat4_f32 *X, const dh_mat4_f32 *M, float s, float sg, int aff,
                                  dh_mat4_f32 *W, float g)
{
    float res = 0.0f, t = 0.0f;
    int i, j, k;
    for (i = 0; i < 4; i++) {
        float rs = 0.0f;
        for (j = 0; j < 4; j++) {
            float q = 0.0f;
            if (aff < 0) {
                /* dh_unscale */
                const float x = M->m[i][j], v = x * s + 0.0f;
                W->m[i][j] = v;
                q = v * g - x;
            } else {
                /* X == NULL: the term k == i alone, 0 + 1 * A_ij */
                for (k = 0; k < 4; k++) {
                    float x = 1.0f;
                    if (X != NULL) x = X->m[i][k];
                    else if (k != i) continue;
                    q += x * dh_at(M, k, j, s, aff);
                }
                if (j == i && X != NULL) q -= 1.0f;
                q = dh_wt(q, i, j, g);
                if (W != NULL) W->m[i][j] = q;
            }
            rs += dh_wt(fabsf(q), i, j, sg);
        }
        t += rs;
        res = (rs > res) ? rs : res;
    }
    return res + t * 0.0f;
}
#else
/* max row sum of D^-1 M D (row view; = balanced ||T||_1); NaN if an
 * element is NaN or Inf (t: a max alone would drop a NaN row) */
static DH_NOINLINE float dh_norm_rows(const dh_mat4_f32 *M, float sg, float s, int aff)
{
    float n = 0.0f, t = 0.0f;
    int i, j;
    for (i = 0; i < 4; i++) {
        float rs = 0.0f;
        for (j = 0; j < 4; j++) {
            const float v = fabsf(dh_at(M, i, j, s, aff));
            if (i < 3) rs += (j < 3) ? v : v * sg;
            else rs += (j < 3) ? v / sg : v;
        }
        t += rs;
        n = (rs > n) ? rs : n;
    }
    return n + t * 0.0f;
}

/* balanced ||X A - I|| in the row view, A = dh_at(M, ., ., s, aff) (row i
 * of X A is the combination of the rows of A with the weights of row i of
 * X); s is a power of two, so A is exact */
static DH_NOINLINE float dh_residual(const dh_mat4_f32 *X, const dh_mat4_f32 *M, float s, float sg, int aff)
{
    float res = 0.0f, t = 0.0f; /* t: NaN propagation, as in dh_norm_rows */
    int i, j, k;
    for (i = 0; i < 4; i++) {
        float rs = 0.0f;
        for (j = 0; j < 4; j++) {
            float q = 0.0f;
            for (k = 0; k < 4; k++) q += X->m[i][k] * dh_at(M, k, j, s, aff);
            if (j == i) q -= 1.0f;
            q = fabsf(q);
            /* balanced weights: column 3 times sg in rows 0..2, columns
             * 0..2 divided by sg in row 3 */
            if (i < 3) rs += (j < 3) ? q : q * sg;
            else rs += (j < 3) ? q / sg : q;
        }
        t += rs;
        res = (rs > res) ? rs : res;
    }
    return res + t * 0.0f;
}
#endif

/*
 * One Gauss-Jordan step after the interchange: row k divided by its pivot
 * (as a multiplication by the reciprocal), column k eliminated from the
 * other rows. Shared by both builds' dh_inv_gauss_jordan (inlined: the
 * same operations in the same order).
 */
static DH_INLINE void dh_gj_eliminate(dh_mat4_f32 *X, int k)
{
    float *rk = X->m[k];
    const float r = 1.0f / rk[k];
    int i, j;
    rk[k] = 1.0f;
    for (j = 0; j < 4; j++) rk[j] *= r;
    for (i = 0; i < 4; i++) {
        float *ri = X->m[i];
        float f;
        if (i == k) continue;
        f = ri[k];
        ri[k] = 0.0f;
        for (j = 0; j < 4; j++) ri[j] -= f * rk[j];
    }
}

#if DH_SMALL
/* the four elements of X with the indices u + n st, n = 0..3, exchanged
 * with those at v + n st (element index 4 i + j for X->m[i][j]): rows
 * u / 4, v / 4 with st = 1, columns u, v with st = 4; u == v leaves X as
 * it is */
static DH_NOINLINE void dh_swap4(dh_mat4_f32 *X, unsigned u, unsigned v, unsigned st)
{
    unsigned a = u, b = v, n;
    for (n = 0u; n < 4u; n++) {
        const float t = X->m[a >> 2][a & 3u];
        X->m[a >> 2][a & 3u] = X->m[b >> 2][b & 3u];
        X->m[b >> 2][b & 3u] = t;
        a += st;
        b += st;
    }
}

/* the same elimination as below (the same pivots, operations and order);
 * the interchanges by one helper, unconditionally (p == k swaps nothing) */
static DH_NOINLINE int dh_inv_gauss_jordan(dh_mat4_f32 *X)
{
    unsigned perm = 0u; /* pivot row of step k in bits 6 - 2k, 7 - 2k */
    int i, k;
    for (k = 0; k < 4; k++) {
        int p = k;
        for (i = k + 1; i < 4; i++) {
            if (fabsf(X->m[i][k]) > fabsf(X->m[p][k])) p = i;
        }
        if (X->m[p][k] == 0.0f) return 0;
        perm = perm * 4u + (unsigned)p;
        dh_swap4(X, 4u * (unsigned)k, 4u * (unsigned)p, 1u);
        dh_gj_eliminate(X, k);
    }
    /* undo the interchanges on the columns, last first */
    for (k = 3; k >= 0; k--) {
        dh_swap4(X, (unsigned)k, perm & 3u, 4u);
        perm >>= 2;
    }
    return 1;
}
#else
/*
 * In-place Gauss-Jordan with partial pivoting on the rows of M (i.e. on
 * the columns of T): X becomes X^-1. Returns 0 on an exactly zero pivot
 * (X then undefined).
 */
static DH_NOINLINE int dh_inv_gauss_jordan(dh_mat4_f32 *X)
{
    unsigned perm = 0u; /* pivot row of step k in bits 2k, 2k+1 */
    unsigned sh;        /* 2k */
    int i, j, k;
    for (k = 0; k < 4; k++) {
        float *rk;
        int p = k;
        for (i = k + 1; i < 4; i++) {
            if (fabsf(X->m[i][k]) > fabsf(X->m[p][k])) p = i;
        }
        if (X->m[p][k] == 0.0f) return 0;
        sh = 2u * (unsigned)k;
        perm |= (unsigned)p << sh;
        rk = X->m[k];
        if (p != k) {
            float *rp = X->m[p];
            for (j = 0; j < 4; j++) {
                const float tmp = rk[j];
                rk[j] = rp[j];
                rp[j] = tmp;
            }
        }
        dh_gj_eliminate(X, k);
    }
    /* undo the interchanges on the columns, last first */
    for (k = 3; k >= 0; k--) {
        unsigned p;
        sh = 2u * (unsigned)k;
        p = (perm >> sh) & 3u;
        if (p != (unsigned)k) {
            for (i = 0; i < 4; i++) {
                const float tmp = X->m[i][k];
                X->m[i][k] = X->m[i][p];
                X->m[i][p] = tmp;
            }
        }
    }
    return 1;
}
#endif

/*
 * Exact power-of-two scale s of the certified path: for affine T the one
 * of dh_affine_prescale (largest |R_ij| into [1, 2)); otherwise 1 when
 * max|T_ij| is in [2^-16, 2^17), else the one that brings it into [1, 2)
 * (or [2, 4) for the very top binade), so that nothing over- or
 * underflows. 0 for a zero or denormal matrix (R). T is finite here.
 */
#if DH_SMALL
/*
 * One pass over T: returns the scale s of dh_cert_scale below with the
 * affine prescale folded in (max over R only, always brought into [1, 2)),
 * 0 for a zero or denormal matrix (R), NaN if an element of T is NaN or
 * Inf (the scan of dh_inv_certified); and stores the factor sg of
 * dh_balance below (1 for affine T) in X->m[0][0] of the scratch X (no
 * pointer to a local in the caller: its frame stays small on Cortex-M0+).
 * The same sums as dh_balance: (0 + a) + b + c is bitwise a + b + c for
 * a >= 0, and |x| / 4 == |x / 4|.
 */
static DH_NOINLINE float dh_scan(const dh_mat4_f32 *T, int aff, dh_mat4_f32 *X)
{
    float mx = 0.0f, s = 0.0f, z = 0.0f, cp = 0.0f, rq = 0.0f, m3 = 0.0f, sg = 1.0f, pn = 0.0f;
    uint32_t e, b;
    int i, j;
    for (i = 0; i < 4; i++) {
        float rs = 0.0f;
        for (j = 0; j < 4; j++) {
            const float v = fabsf(T->m[i][j]), w = v * 0.25f;
            z += v * 0.0f;
            if (i < 3 && j < 3) rs += w;
            else if (j < 3) {               /* row 3: p */
                cp += w;
                pn += v;
            }
            else if (i < 3) rq += w;        /* column 3: q */
            if (!aff || (i < 3 && j < 3)) mx = (v > mx) ? v : mx;
        }
        m3 = (rs > m3) ? rs : m3;
    }
    if (mx >= FLT_MIN) {
        memcpy(&e, &mx, sizeof e);
        e >>= 23;
        b = 0x3F800000u; /* 1.0f */
        if (aff || e - (127u - 16u) > 32u) b = ((e >= 254u) ? 1u : 254u - e) << 23; /* e < 111 or e > 143 */
        memcpy(&s, &b, sizeof s);
    }
    if (!aff && (cp != 0.0f || rq > 0.0f)) {
        if (cp == 0.0f) {
            if (pn == 0.0f && m3 > 0.0f) sg = m3 / rq * DH_U24; /* p = 0 */
        } else if (rq > 0.0f) sg = DH_SQRTF(cp) / DH_SQRTF(rq);
        else if (m3 > 0.0f) sg = cp / m3 * 16777216.0f;
        if (sg > 1.15292150e18f) sg = 1.15292150e18f;       /* 2^60 */
        if (sg < 8.67361738e-19f) sg = 8.67361738e-19f;     /* 2^-60 */
    }
    X->m[0][0] = sg;
    return s + z;
}
#else
static DH_NOINLINE float dh_cert_scale(const dh_mat4_f32 *T, int aff)
{
    float mx = 0.0f, s = 1.0f;
    uint32_t e;
    int i, j;
    if (aff) return dh_affine_prescale(T);
    for (i = 0; i < 4; i++) {
        for (j = 0; j < 4; j++) {
            const float v = fabsf(T->m[i][j]);
            mx = (v > mx) ? v : mx;
        }
    }
    if (mx < FLT_MIN) return 0.0f;
    memcpy(&e, &mx, sizeof e);
    e >>= 23; /* biased exponent of the largest element, 1..254 */
    if (e < 127u - 16u || e > 127u + 16u) {
        const uint32_t bits = ((e >= 254u) ? 1u : 254u - e) << 23;
        memcpy(&s, &bits, sizeof s);
    }
    return s;
}
#endif

#if !DH_SMALL
/*
 * X = s X (+ 0.0f maps -0 to +0); returns the balanced norm (the weights of
 * dh_norm_rows) of what that lost, F / s = (s X) / s - X: 0 when every
 * element stayed exact, Inf when one overflowed, the gradual-underflow
 * errors (<= 2^-150 each, over s) otherwise. 1/s is a power of two
 * (s = 2^k, |k| <= 126), so (s X) / s is exact.
 */
static DH_NOINLINE float dh_unscale(dh_mat4_f32 *X, float s, float sg)
{
    const float si = 1.0f / s;
    float lost = 0.0f;
    int i, j;
    for (i = 0; i < 4; i++) {
        float rs = 0.0f;
        for (j = 0; j < 4; j++) {
            const float x = X->m[i][j];
            const float v = x * s + 0.0f;
            const float d = fabsf(v * si - x);
            X->m[i][j] = v;
            if (i < 3) rs += (j < 3) ? d : d * sg;
            else rs += (j < 3) ? d / sg : d;
        }
        lost = (rs > lost) ? rs : lost;
    }
    return lost;
}
#endif

/*
 * Certified general inverse into the scratch X (X must not alias T; its
 * content is undefined on error). Method: NaN/Inf scan; the matrix M
 * inverted is s T, or blockdiag(s3 R, 1) for an affine T (see dh_at), with
 * s, s3 exact powers of two that bring the largest element into [1, 2)
 * (s = 1 when max|T_ij| is in [2^-16, 2^17)); Gauss-Jordan with partial
 * pivoting on M; then
 *   (a) balanced cond = ||M|| ||X|| >= DH_MAT4_COND_MAX -> singular;
 *   (b) residual ||X M - I|| > 1/2 -> singular. (b) is a proof: a residual
 *       <= 1/2 implies M non-singular with ||M^-1|| <= 2 ||X||; for a
 *       singular M, X M - I has the eigenvalue -1 whatever X is.
 * In T's terms (M = T^T in this row view) (b) is the RIGHT residual
 * T X - I, the one Gauss-Jordan on M keeps small. The left residual X T - I
 * is not controlled: it can be up to cond times larger, i.e. above 1 for a
 * correct inverse when cond is near DH_MAT4_COND_MAX; either is a proof.
 * Underflow. Entries of T far below the largest become subnormal or 0 in
 * A = s T (error <= 2^-150 each): that perturbs the residual by at most
 * ||X|| * 2^-150 * 4 * 2^60 (balancing weight) < 2^79 * 2^-88 = 2^-9
 * (||X|| < 2^19 / na by (a), na >= 2^-60 since max|A_ij| >= 1), so the
 * proof covers T itself. The unscaling of the result is checked below.
 */
#if DH_SMALL
/* the same method and decisions as below, from the shared loops */
static DH_NOINLINE dh_status dh_inv_certified(dh_mat4_f32 *X, const dh_mat4_f32 *T)
{
    const int aff = dh_is_affine(T);
    const float s = dh_scan(T, aff, X), sg = X->m[0][0];
    float na, z = 0.0f, f = sg * 1.41421356f;
    uint32_t b;
    if (s != s) return DH_ERR_NAN;
    if (s == 0.0f) return DH_ERR_SINGULAR;
    /* X = A and its balanced norm */
    na = dh_bnorm(NULL, T, s, sg, aff, X, 1.0f);
    /* the power of two f of dh_rebalance: balance X, eliminate, unbalance
     * (with the norm of the result) */
    memcpy(&b, &f, sizeof b);
    b &= 0x7F800000u; /* sg in [2^-60, 2^60]: a normal power of two */
    memcpy(&f, &b, sizeof f);
    (void)dh_bnorm(NULL, X, 1.0f, sg, 0, X, f);
    if (!dh_inv_gauss_jordan(X)) return DH_ERR_SINGULAR;
    if (!(na * dh_bnorm(NULL, X, 1.0f, sg, 0, X, 1.0f / f) < DH_MAT4_COND_MAX)) return DH_ERR_SINGULAR;
    if (!(dh_bnorm(X, T, s, sg, aff, NULL, 1.0f) <= 0.5f)) return DH_ERR_SINGULAR;
    if (!(dh_bnorm(NULL, X, s, sg, -1, X, 1.0f / s) * na <= 0.0625f)) return DH_ERR_OVERFLOW;
    /* X and T are finite here: the products commute bitwise */
    if (aff) z = dh_affine_t(X, T->m[3][0], T->m[3][1], T->m[3][2]);
    if (z != z) return DH_ERR_OVERFLOW;
    return DH_OK;
}
#else
static DH_NOINLINE dh_status dh_inv_certified(dh_mat4_f32 *X, const dh_mat4_f32 *T)
{
    const int aff = dh_is_affine(T);
    float z = 0.0f, s, sg = 1.0f, na;
    int i, j;

    /* z is NaN iff an element is NaN or Inf (x * 0 is NaN exactly for
     * those) */
    for (i = 0; i < 4; i++) {
        for (j = 0; j < 4; j++) z += T->m[i][j] * 0.0f;
    }
    if (z != z) return DH_ERR_NAN;
    s = dh_cert_scale(T, aff);
    if (s == 0.0f) return DH_ERR_SINGULAR; /* zero or denormal matrix (or R) */
    if (!aff) sg = dh_balance(T); /* scale-free: a ratio of sums of |T_ij| */
    for (i = 0; i < 4; i++) {
        for (j = 0; j < 4; j++) X->m[i][j] = dh_at(T, i, j, s, aff);
    }
    /* eliminate on the balanced matrix: partial pivoting then works with
     * the magnitudes the balanced norms measure (on s M itself, with
     * |p| / |q| ~ 2^60, it returned inverses whose balanced residual was
     * > 1 for condition numbers ~10) */
    dh_rebalance(X, sg, 0);
    if (!dh_inv_gauss_jordan(X)) return DH_ERR_SINGULAR;
    dh_rebalance(X, sg, 1);
    /* (a) estimated condition number */
    na = dh_norm_rows(T, sg, s, aff);
    if (!(na * dh_norm_rows(X, sg, 1.0f, 0) < DH_MAT4_COND_MAX)) return DH_ERR_SINGULAR;
    /* (b) certificate (the rounding of the residual is below
     * 4 u na nx < 0.13) */
    if (!(dh_residual(X, T, s, sg, aff) <= 0.5f)) return DH_ERR_SINGULAR;
    /* T^-1 = s A^-1, or for affine T: R^-1 = s (s R)^-1 and the
     * translation -R^-1 p; "+ 0.0f" maps -0 to +0.
     * The certificate (b) is for the scaled X. If the returned s X differs
     * from it by F (overflow for s > 1; for s < 1 the gradual underflow of
     * elements below FLT_MIN, |F_ij| <= 2^-150), its residual differs by
     * (F / s) A: at most ||F / s|| * na in the balanced norm, ||F / s||
     * returned by dh_unscale. DH_OK only if that is <= 2^-4: then the residual of what is returned
     * is < 1/2 + 1/8 (rounding of (b)) + 2^-9 (flush of tiny entries of T,
     * above) + 2^-4 < 1, the proof holds for it. Otherwise the inverse
     * does not fit in float (Inf, or lost its meaning to underflow):
     * DH_ERR_OVERFLOW. */
    if (!(dh_unscale(X, s, sg) * na <= 0.0625f)) return DH_ERR_OVERFLOW;
    z = 0.0f;
    if (aff) {
        for (j = 0; j < 3; j++) {
            const float t = 0.0f - (X->m[0][j] * T->m[3][0] + X->m[1][j] * T->m[3][1] + X->m[2][j] * T->m[3][2]);
            X->m[3][j] = t;
            X->m[j][3] = 0.0f;
            z += t * 0.0f;
        }
        X->m[3][3] = 1.0f;
    }
    if (z != z) return DH_ERR_OVERFLOW;
    return DH_OK;
}
#endif

#if !DH_SMALL
/* ---------------------------------------------------------------------- */
/* general inverse: fast paths                                            */
/* ---------------------------------------------------------------------- */

/*
 * The fast paths accept a matrix only when a cheap test PROVES it well
 * conditioned; everything else (ill-conditioned, singular, NaN/Inf,
 * extreme magnitudes) goes to dh_inv_certified, which decides.
 *
 * Test. For an n x n matrix A with squared row norms rho_i and
 * S = sum rho_i = ||A||_F^2: every cofactor is a minor bounded by the
 * product of the other rows' norms (Hadamard's inequality), so
 *   n = 3: ||adj A||_F^2 <= 3 (rho0 rho1 + rho0 rho2 + rho1 rho2) <= S^2,
 *   n = 4: ||adj A||_F^2 <= 4 e3(rho) <= S^3 / 4   (Maclaurin),
 * and with ||A||_2 <= sqrt(S), A^-1 = adj A / det:
 *   cond_2(A) <= S^1.5 / |det|   (n = 3),   S^2 / (2 |det|)   (n = 4).
 * A fast path accepts only if that bound is <= DH_FAST_C = 2^16, tested
 * without roots or divisions as det^2 C^2 >= S^3 (n = 3) and
 * 4 det^2 C^2 >= S^4 (n = 4). Accepted matrices then have a 1-norm
 * condition number <= n 2^16 <= 2^18 = DH_MAT4_COND_MAX / 2, so the
 * certified criterion would accept them as well (the decision does not
 * depend on the path), and their inverse needs no residual check: the
 * adjugate's error is a few units of cond * u (measured in test_mat4_props).
 * For a singular matrix the computed det is only rounding noise, below
 * about 16 u S^(n/2), i.e. the bound would be > 2^18: it never passes.
 * Both sides of the test scale alike (degree 2n), so the test is
 * invariant under A -> c A; the range limits on S keep S^n, det^2 and the
 * products normal floats, so the decision is exact. A NaN or Inf anywhere
 * makes a comparison false.
 * Rotations (S = 3, det = 1) pass with a margin of 2^32 / 27.
 */
#define DH_FAST_C2 4294967296.0f               /* C^2 = 2^32 */
#define DH_FAST_LO3 5.9604644775390625e-8f     /* 2^-24: range of S, 3x3 */
#define DH_FAST_HI3 16777216.0f                /* 2^24 */
#define DH_FAST_LO4 1.52587890625e-5f          /* 2^-16: range of S, 4x4 */
#define DH_FAST_HI4 65536.0f                   /* 2^16 */
#define DH_FAST_PQ 268435456.0f               /* 2^28: |p|_1, |q|_1 limit, 4x4 */

/*
 * Affine T = [R p; 0 0 0 1]: T^-1 = [R^-1, -R^-1 p; 0 0 0 1]. With the
 * columns n, o, a of R, the rows of R^-1 are (o x a, a x n, n x o) / det,
 * det = n . (o x a) (seed eq. 1.57 is the special case R^-1 = R^T). The
 * test uses R only: p does not enter the conditioning of the inverse, so
 * a rigid transform is accepted whatever its length unit.
 * R is used as s R, s an exact power of two chosen by the caller so that
 * S is in range (s == 1 on the common path), and T^-1 = [s (sR)^-1, ...].
 * Writes out and returns 1, or returns 0 (out untouched).
 */
static DH_NOINLINE int dh_inv_affine(dh_mat4_f32 *out, const dh_mat4_f32 *T, float s)
{
    const float nx = T->m[0][0] * s, ny = T->m[0][1] * s, nz = T->m[0][2] * s;
    const float ox = T->m[1][0] * s, oy = T->m[1][1] * s, oz = T->m[1][2] * s;
    const float ax = T->m[2][0] * s, ay = T->m[2][1] * s, az = T->m[2][2] * s;
    const float px = T->m[3][0], py = T->m[3][1], pz = T->m[3][2];
    const float c00 = oy * az - oz * ay, c01 = oz * ax - ox * az, c02 = ox * ay - oy * ax; /* o x a */
    const float c10 = ay * nz - az * ny, c11 = az * nx - ax * nz, c12 = ax * ny - ay * nx; /* a x n */
    const float c20 = ny * oz - nz * oy, c21 = nz * ox - nx * oz, c22 = nx * oy - ny * ox; /* n x o */
    const float det = nx * c00 + ny * c01 + nz * c02;
    const float S = (nx * nx + ny * ny + nz * nz) + (ox * ox + oy * oy + oz * oz) + (ax * ax + ay * ay + az * az);
    float f, x00, x01, x02, x10, x11, x12, x20, x21, x22, t0, t1, t2;
    if (!(S >= DH_FAST_LO3 && S <= DH_FAST_HI3 && det * det * DH_FAST_C2 >= S * S * S)) return 0;
    f = s / det; /* s (sR)^-1 = R^-1; s / det is exact scaling of 1 / det */
    /* element (row i, column j) of R^-1 is c_ij f; "+ 0.0f" maps -0 to +0 */
    x00 = c00 * f + 0.0f; x01 = c01 * f + 0.0f; x02 = c02 * f + 0.0f;
    x10 = c10 * f + 0.0f; x11 = c11 * f + 0.0f; x12 = c12 * f + 0.0f;
    x20 = c20 * f + 0.0f; x21 = c21 * f + 0.0f; x22 = c22 * f + 0.0f;
    /* translation -R^-1 p; 0 - x is never -0 */
    t0 = 0.0f - (x00 * px + x01 * py + x02 * pz);
    t1 = 0.0f - (x10 * px + x11 * py + x12 * pz);
    t2 = 0.0f - (x20 * px + x21 * py + x22 * pz);
    /* R^-1 is finite by the test; the translation may overflow (or be NaN
     * from a NaN/Inf in p): then the certified path reports it */
    if (!((t0 - t0) + (t1 - t1) + (t2 - t2) == 0.0f)) return 0;
    out->m[0][0] = x00; out->m[0][1] = x10; out->m[0][2] = x20; out->m[0][3] = 0.0f;
    out->m[1][0] = x01; out->m[1][1] = x11; out->m[1][2] = x21; out->m[1][3] = 0.0f;
    out->m[2][0] = x02; out->m[2][1] = x12; out->m[2][2] = x22; out->m[2][3] = 0.0f;
    out->m[3][0] = t0; out->m[3][1] = t1; out->m[3][2] = t2; out->m[3][3] = 1.0f;
    return 1;
}

/*
 * Power of two s with max |s R_ij| in [1, 2), or 0 if R is zero, denormal,
 * or holds a NaN/Inf (then the certified path decides).
 */
static DH_NOINLINE float dh_affine_prescale(const dh_mat4_f32 *T)
{
    float mx = 0.0f, s;
    uint32_t e;
    int i, j;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            const float v = fabsf(T->m[i][j]);
            mx = (v > mx) ? v : mx;
        }
    }
    if (!(mx >= FLT_MIN && mx <= FLT_MAX)) return 0.0f;
    memcpy(&e, &mx, sizeof e);
    e >>= 23;                           /* 1..254 */
    e = (e >= 254u) ? 1u : 254u - e;    /* exponent of 2^(127 - e) */
    e <<= 23;
    memcpy(&s, &e, sizeof s);
    return s;
}

/*
 * General (projective) T = [R p; q^T w]: adjugate from the 2x2 minors of
 * two row pairs (two phases, so that few values are live at a time), in
 * the row view of the helpers above (M = T^T). The
 * test is made on the balanced matrix B = D^-1 T D, D = diag(1, 1, 1, sg),
 * sg^2 = |p| / |q| (Osborne): the homogeneous coordinate has another unit
 * than the others, and the balancing makes the test independent of the
 * length unit. det B = det T, and ||B||_F^2 = ||R||_F^2 + 2 |p| |q| + w^2
 * needs no sg (|p| |q| is bounded by |p|_1 |q|_1 to avoid a root). Writes out and returns 1, or returns 0 (out untouched).
 */
/* phase 1: the test, and columns 0, 1 of the inverse (row view) from the
 * 2x2 minors of rows 2, 3; returns 1 / det, or 0 if the test fails */
static DH_NOINLINE float dh_proj_phase1(dh_mat4_f32 *X, const dh_mat4_f32 *M)
{
    const float a00 = M->m[0][0], a01 = M->m[0][1], a02 = M->m[0][2], a03 = M->m[0][3];
    const float a10 = M->m[1][0], a11 = M->m[1][1], a12 = M->m[1][2], a13 = M->m[1][3];
    const float a20 = M->m[2][0], a21 = M->m[2][1], a22 = M->m[2][2], a23 = M->m[2][3];
    const float a30 = M->m[3][0], a31 = M->m[3][1], a32 = M->m[3][2], a33 = M->m[3][3];
    const float c5 = a22 * a33 - a32 * a23, c4 = a21 * a33 - a31 * a23, c3 = a21 * a32 - a31 * a22;
    const float c2 = a20 * a33 - a30 * a23, c1 = a20 * a32 - a30 * a22, c0 = a20 * a31 - a30 * a21;
    /* cofactors of row 0 (column 0 of the inverse), det by Laplace */
    const float x00 = a11 * c5 - a12 * c4 + a13 * c3;
    const float x10 = -a10 * c5 + a12 * c2 - a13 * c1;
    const float x20 = a10 * c4 - a11 * c2 + a13 * c0;
    const float x30 = -a10 * c3 + a11 * c1 - a12 * c0;
    const float det = a00 * x00 + a01 * x10 + a02 * x20 + a03 * x30;
    /* p = row 3 of M (columns 0..2), q = column 3 of M (rows 0..2); the
     * 1-norms bound the 2-norms: S below is >= ||B||_F^2 (an upper bound
     * keeps the test a proof) and still unit-free */
    const float p1 = fabsf(a30) + fabsf(a31) + fabsf(a32);
    const float q1 = fabsf(a03) + fabsf(a13) + fabsf(a23);
    const float S = (a00 * a00 + a01 * a01 + a02 * a02) + (a10 * a10 + a11 * a11 + a12 * a12) +
                    (a20 * a20 + a21 * a21 + a22 * a22) + 2.0f * (p1 * q1) + a33 * a33;
    float f;
    /* |p|_1, |q|_1 <= 2^28 and S <= 2^16 bound every product of entries
     * formed here and in phase 2 (no overflow); see the test above */
    if (!(p1 <= DH_FAST_PQ && q1 <= DH_FAST_PQ && S >= DH_FAST_LO4 && S <= DH_FAST_HI4 &&
          4.0f * DH_FAST_C2 * (det * det) >= (S * S) * (S * S))) {
        return 0.0f;
    }
    f = 1.0f / det;
    X->m[0][0] = x00 * f + 0.0f;
    X->m[1][0] = x10 * f + 0.0f;
    X->m[2][0] = x20 * f + 0.0f;
    X->m[3][0] = x30 * f + 0.0f;
    X->m[0][1] = (-a01 * c5 + a02 * c4 - a03 * c3) * f + 0.0f;
    X->m[1][1] = (a00 * c5 - a02 * c2 + a03 * c1) * f + 0.0f;
    X->m[2][1] = (-a00 * c4 + a01 * c2 - a03 * c0) * f + 0.0f;
    X->m[3][1] = (a00 * c3 - a01 * c1 + a02 * c0) * f + 0.0f;
    return f;
}

/* phase 2: columns 2, 3 of the inverse from the 2x2 minors of rows 0, 1 */
static DH_NOINLINE void dh_proj_phase2(dh_mat4_f32 *X, const dh_mat4_f32 *M, float f)
{
    const float a00 = M->m[0][0], a01 = M->m[0][1], a02 = M->m[0][2], a03 = M->m[0][3];
    const float a10 = M->m[1][0], a11 = M->m[1][1], a12 = M->m[1][2], a13 = M->m[1][3];
    const float s0 = a00 * a11 - a10 * a01, s1 = a00 * a12 - a10 * a02, s2 = a00 * a13 - a10 * a03;
    const float s3 = a01 * a12 - a11 * a02, s4 = a01 * a13 - a11 * a03, s5 = a02 * a13 - a12 * a03;
    const float a20 = M->m[2][0], a21 = M->m[2][1], a22 = M->m[2][2], a23 = M->m[2][3];
    const float a30 = M->m[3][0], a31 = M->m[3][1], a32 = M->m[3][2], a33 = M->m[3][3];
    X->m[0][2] = (a31 * s5 - a32 * s4 + a33 * s3) * f + 0.0f;
    X->m[1][2] = (-a30 * s5 + a32 * s2 - a33 * s1) * f + 0.0f;
    X->m[2][2] = (a30 * s4 - a31 * s2 + a33 * s0) * f + 0.0f;
    X->m[3][2] = (-a30 * s3 + a31 * s1 - a32 * s0) * f + 0.0f;
    X->m[0][3] = (-a21 * s5 + a22 * s4 - a23 * s3) * f + 0.0f;
    X->m[1][3] = (a20 * s5 - a22 * s2 + a23 * s1) * f + 0.0f;
    X->m[2][3] = (-a20 * s4 + a21 * s2 - a23 * s0) * f + 0.0f;
    X->m[3][3] = (a20 * s3 - a21 * s1 + a22 * s0) * f + 0.0f;
}

/* X (must not alias M) = M^-1 and 1, or 0 (X partly written) */
static int dh_inv_proj_fast(dh_mat4_f32 *X, const dh_mat4_f32 *M)
{
    const float f = dh_proj_phase1(X, M);
    if (f == 0.0f) return 0;
    dh_proj_phase2(X, M, f);
    return 1;
}

static DH_NOINLINE int dh_inv_affine_scaled(dh_mat4_f32 *out, const dh_mat4_f32 *T)
{
    const float s = dh_affine_prescale(T);
    return (s != 0.0f) && dh_inv_affine(out, T, s);
}
#endif

/* bottom row exactly 0 0 0 1 */
#if DH_SMALL
/* the same test on the bits: +-0 (sign shifted out) and exactly 1.0f */
static DH_NOINLINE int dh_is_affine(const dh_mat4_f32 *T)
{
    uint32_t b, z = 0u;
    int i;
    for (i = 0; i < 3; i++) {
        memcpy(&b, &T->m[i][3], sizeof b);
        z |= b << 1;
    }
    memcpy(&b, &T->m[3][3], sizeof b);
    return z == 0u && b == 0x3F800000u;
}
#else
static int dh_is_affine(const dh_mat4_f32 *T)
{
    return T->m[0][3] == 0.0f && T->m[1][3] == 0.0f && T->m[2][3] == 0.0f && T->m[3][3] == 1.0f;
}
#endif

/*
 * General inverse into X: the fast path for the input's shape, else the
 * certified path (X scratch, undefined on error, must not alias T). Used
 * by dh_mat4_apply_plane_f32 (DH_SMALL: the certified path alone).
 */
#if !DH_SMALL
static dh_status dh_inv_into(dh_mat4_f32 *X, const dh_mat4_f32 *T)
{
    if (dh_is_affine(T)) {
        if (dh_inv_affine(X, T, 1.0f) || dh_inv_affine_scaled(X, T)) return DH_OK;
        return dh_inv_certified(X, T);
    }
    return dh_inv_proj_fast(X, T) ? DH_OK : dh_inv_certified(X, T);
}
#endif

/*
 * The public general inverse (out untouched on error). A separate function
 * so that dh_mat4_inv_auto_f32 calls it without the public function's
 * frame (stack budget on Cortex-M0+).
 */
#if !DH_SMALL
static DH_NOINLINE dh_status dh_inv_general(dh_mat4_f32 *out, const dh_mat4_f32 *T)
{
    dh_mat4_f32 X; /* scratch of the certified path */
    dh_status st;
    if (dh_is_affine(T)) {
        /* R with ||R||_F^2 out of [2^-24, 2^24] is rescaled exactly first,
         * so the affine decision is invariant under any scaling of R */
        if (dh_inv_affine(out, T, 1.0f) || dh_inv_affine_scaled(out, T)) return DH_OK;
        st = dh_inv_certified(&X, T);
    } else {
        st = dh_inv_proj_fast(&X, T) ? DH_OK : dh_inv_certified(&X, T);
    }
    if (st == DH_OK) *out = X;
    return st;
}
#endif

#if DH_SMALL
/* the certified path alone, into a scratch (out untouched on error, out
 * may alias T) */
dh_status dh_mat4_inv_f32(dh_mat4_f32 *out, const dh_mat4_f32 *T)
{
    dh_mat4_f32 X;
    dh_status st;
    DH_ASSERT(out != NULL && T != NULL);
    st = dh_inv_certified(&X, T);
    if (st == DH_OK) *out = X;
    return st;
}
#else
dh_status dh_mat4_inv_f32(dh_mat4_f32 *out, const dh_mat4_f32 *T)
{
    DH_ASSERT(out != NULL && T != NULL);
    return dh_inv_general(out, T);
}
#endif

/* ---------------------------------------------------------------------- */
/* rigidity                                                               */
/* ---------------------------------------------------------------------- */

#if DH_SMALL
/* the same tests as loops: the sums (0 + a) + b + c differ from a + b + c
 * at most in the sign of a zero, which no comparison below sees */
dh_status dh_mat4_check_rot_f32(const dh_mat4_f32 *T, float tol)
{
    float det = 0.0f, z = 0.0f;
    int i, j, k, n, bad = 0;
    DH_ASSERT(T != NULL);
    if (!(tol >= 0.0f)) return DH_ERR_ARG;
    for (i = 0; i < 3; i++) {
        /* R^T R - I, row i up to the diagonal; z: NaN iff an entry of R
         * is NaN or Inf (x * 0), which takes precedence */
        for (j = 0; j <= i; j++) {
            float d = 0.0f;
            for (k = 0; k < 3; k++) {
                d += T->m[i][k] * T->m[j][k];
                z += T->m[i][k] * 0.0f;
            }
            if (i == j) d -= 1.0f;
            bad |= !(fabsf(d) <= tol);
        }
    }
    if (z != z) return DH_ERR_NAN;
    if (bad) return DH_ERR_NOT_RIGID;
    /* det R = n . (o x a) = sum of n_i (o_j a_k - o_k a_j), (i, j, k)
     * the cyclic permutations of (0, 1, 2), in the default's order */
    for (n = 0, i = 0, j = 1, k = 2; n < 3; n++) {
        const int t = i;
        det += T->m[0][i] * (T->m[1][j] * T->m[2][k] - T->m[1][k] * T->m[2][j]);
        i = j; /* (i, j, k) -> (j, k, i) */
        j = k;
        k = t;
    }
    if (!(det > 0.0f)) return DH_ERR_NOT_RIGID;
    return DH_OK;
}

dh_status dh_mat4_check_rigid_f32(const dh_mat4_f32 *T, float tol)
{
    DH_ASSERT(T != NULL);
    if (!(tol >= 0.0f)) return DH_ERR_ARG;
    if (!dh_mat4_isfinite_f32(T)) return DH_ERR_NAN;
    if (!dh_is_affine(T)) return DH_ERR_NOT_RIGID;
    return dh_mat4_check_rot_f32(T, tol);
}
#else
dh_status dh_mat4_check_rot_f32(const dh_mat4_f32 *T, float tol)
{
    float nx, ny, nz, ox, oy, oz, ax, ay, az, det;
    DH_ASSERT(T != NULL);
    if (!(tol >= 0.0f)) return DH_ERR_ARG;
    nx = T->m[0][0]; ny = T->m[0][1]; nz = T->m[0][2];
    ox = T->m[1][0]; oy = T->m[1][1]; oz = T->m[1][2];
    ax = T->m[2][0]; ay = T->m[2][1]; az = T->m[2][2];
    if (!(dh_finite(nx) && dh_finite(ny) && dh_finite(nz) && dh_finite(ox) && dh_finite(oy) &&
          dh_finite(oz) && dh_finite(ax) && dh_finite(ay) && dh_finite(az))) {
        return DH_ERR_NAN;
    }
    /* R^T R - I (the products of finite entries may overflow to Inf, which
     * then fails the comparisons as it should) */
    if (!(fabsf(nx * nx + ny * ny + nz * nz - 1.0f) <= tol &&
          fabsf(ox * ox + oy * oy + oz * oz - 1.0f) <= tol &&
          fabsf(ax * ax + ay * ay + az * az - 1.0f) <= tol &&
          fabsf(nx * ox + ny * oy + nz * oz) <= tol &&
          fabsf(nx * ax + ny * ay + nz * az) <= tol &&
          fabsf(ox * ax + oy * ay + oz * az) <= tol)) {
        return DH_ERR_NOT_RIGID;
    }
    /* det R = n . (o x a) */
    det = nx * (oy * az - oz * ay) + ny * (oz * ax - ox * az) + nz * (ox * ay - oy * ax);
    if (!(det > 0.0f)) return DH_ERR_NOT_RIGID;
    return DH_OK;
}

dh_status dh_mat4_check_rigid_f32(const dh_mat4_f32 *T, float tol)
{
    DH_ASSERT(T != NULL);
    if (!(tol >= 0.0f)) return DH_ERR_ARG;
    if (!dh_mat4_isfinite_f32(T)) return DH_ERR_NAN;
    if (!(T->m[0][3] == 0.0f && T->m[1][3] == 0.0f && T->m[2][3] == 0.0f && T->m[3][3] == 1.0f)) {
        return DH_ERR_NOT_RIGID;
    }
    return dh_mat4_check_rot_f32(T, tol);
}
#endif

/*
 * 1 iff the translation of the closed-form rigid inverse of T, -(R^T p),
 * is finite (the same products and sums as dh_mat4_inv_rigid_f32). A
 * rigid T with |p| near FLT_MAX can have an inverse translation beyond
 * FLT_MAX: the automatic inverse and the plane transform then report
 * DH_ERR_OVERFLOW like dh_mat4_inv_f32 instead of returning an Inf.
 */
static DH_NOINLINE int dh_rigid_t_ok(const dh_mat4_f32 *T)
{
    float z = 0.0f;
    int j;
    /* common case first, without the products: the entries of a rigid R
     * are within 1 + 1e-5 in magnitude, so |p_i| <= 2^125 bounds each
     * translation entry by 3 2^125 (1 + 1e-5) < 2^127 */
    if (fabsf(T->m[3][0]) <= 0x1p125f && fabsf(T->m[3][1]) <= 0x1p125f && fabsf(T->m[3][2]) <= 0x1p125f) return 1;
    for (j = 0; j < 3; j++) {
        const float t = T->m[3][0] * T->m[j][0] + T->m[3][1] * T->m[j][1] + T->m[3][2] * T->m[j][2];
        z += t - t;   /* NaN iff t is Inf or NaN */
    }
    return z == 0.0f;
}

dh_status dh_mat4_inv_auto_f32(dh_mat4_f32 *out, const dh_mat4_f32 *T)
{
#if DH_SMALL
    dh_mat4_f32 X; /* the certified path's scratch here: one frame less */
#endif
    dh_status st;
    DH_ASSERT(out != NULL && T != NULL);
    st = dh_mat4_check_rigid_f32(T, DH_MAT4_RIGID_TOL);
    if (st == DH_OK) {
        if (!dh_rigid_t_ok(T)) return DH_ERR_OVERFLOW;
        dh_mat4_inv_rigid_f32(out, T);
        return DH_OK;
    }
    if (st == DH_ERR_NAN) return DH_ERR_NAN;
#if DH_SMALL
    st = dh_inv_certified(&X, T);
    if (st == DH_OK) *out = X;
    return st;
#else
    return dh_inv_general(out, T);
#endif
}

/* ---------------------------------------------------------------------- */
/* planes                                                                 */
/* ---------------------------------------------------------------------- */

dh_status dh_mat4_apply_plane_f32(const dh_mat4_f32 *T, const dh_plane_f32 *P, dh_plane_f32 *Q)
{
    dh_mat4_f32 X; /* T^-1 (one 4x4 temporary; the inverse paths write into it) */
    dh_status st;
    DH_ASSERT(T != NULL && P != NULL && Q != NULL);
#if DH_SMALL
    /* NaN iff a coefficient is NaN or Inf */
    {
        const float z = P->a * 0.0f + P->b * 0.0f + P->c * 0.0f + P->d * 0.0f;
        if (z != z) return DH_ERR_NAN;
    }
#else
    if (!(dh_finite(P->a) && dh_finite(P->b) && dh_finite(P->c) && dh_finite(P->d))) return DH_ERR_NAN;
#endif
#if DH_SMALL
    /* the certified inverse for every T (no rigidity test): same statuses
     * as the default build's rigid/general choice, values within the
     * general inverse's bound */
    st = dh_inv_certified(&X, T);
    if (st != DH_OK) return st;
#else
    /* the inverse as dh_mat4_inv_auto_f32 takes it, into X */
    st = dh_mat4_check_rigid_f32(T, DH_MAT4_RIGID_TOL);
    if (st == DH_OK) {
        if (!dh_rigid_t_ok(T)) return DH_ERR_OVERFLOW;
        dh_mat4_inv_rigid_f32(&X, T);
    } else if (st == DH_ERR_NAN) {
        return DH_ERR_NAN;
    } else {
        st = dh_inv_into(&X, T);
        if (st != DH_OK) return st;
    }
#endif
    dh_plane_mul_f32(P, &X, Q);
    return DH_OK;
}
