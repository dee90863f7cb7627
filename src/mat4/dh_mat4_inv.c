/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_mat4_inv.c - inverses of float 4x4 transforms: the closed-form rigid
 * inverse (Paul 1981 eq. 1.57), a general inverse with a certified
 * singularity test, rigidity checks, the automatic choice between the two
 * inverses, and the plane transform.
 *
 * Row view. The helpers treat the storage m[i][j] as row i, column j of a
 * matrix M; for a column-major dh_mat4_f32 that M is T^T. Since
 * (T^T)^-1 = (T^-1)^T, inverting M and storing the result the same way
 * yields T^-1 with no transposition. Norms of M are the 1-norms of T, and
 * the residual X M - I is the right residual T X - I.
 *
 * General inverse (inv_certified, compiled in every build). M is T, or
 * blockdiag(R, 1) for T = [R p; 0 w] with w a power of two (affine, or
 * 2^k times affine: T^-1 = [R^-1, -R^-1 p / w; 0, 1 / w]). inv_scan scales
 * M by the power of two s0 that brings max|M_ij| into [1, 2): A0 = s0 M is
 * the same float matrix for T and every exact 2^k T (each element is the
 * rounding of the same real number), and every decision below is taken on
 * A0 or on A = s M, s = s0 2^-E, 2^E within a factor 3 of the largest
 * element of the balanced A0 (s is clamped to the normal range only for
 * max|T_ij| below 2^-60 or in the top binades), so SINGULAR / OK do not
 * depend on k. Gauss-Jordan with partial pivoting on
 * the balanced A, whose largest element is then in [2^-2, 2]: no product
 * underflows that the balanced magnitudes do not make inevitable (with s
 * from max|T_ij| alone, a T whose largest elements sit in p would have all
 * its balanced elements near 2^-60, and their products would underflow).
 * Then
 *   (a) balanced cond = ||A|| ||X|| >= DH_MAT4_COND_MAX -> singular;
 *   (b) residual ||X A - I|| > 1/2 -> singular. A residual <= 1/2 proves A
 *       non-singular with ||A^-1|| <= 2 ||X||; for a singular A, X A - I
 *       has the eigenvalue -1 whatever X is. The left residual X T - I is
 *       not controlled (up to cond times larger); either would be a proof.
 * With r the computed residual, ||X|| <= (1 + r) ||A^-1||: a cond below
 * DH_MAT4_COND_MAX / 2 fails (a) only if r > 1 (then (b) fails anyway), so
 * it is SINGULAR only if (b) fails, i.e. if the elimination's residual
 * exceeds 1/2 at cond < 2^18 (a residual of a few cond u: measured <= 0.06
 * where cond u is up to 2^-6).
 * Balancing. The homogeneous coordinate carries another unit than the
 * other three, so the norms are those of D^-1 A D, D = diag(1, 1, 1, sg):
 * column p divided by sg, bottom row q times sg. sg = sqrt(|p| / |q|)
 * (Osborne) from the sums over A0 (elements <= 4); for q = 0,
 * 2^24 |p| / ||R|| (p negligible); for p = 0 in A0, 2^-24 ||R|| / |q|
 * (q negligible); clamped to [2^-60, 2^60]. A rigid T with |p| = 1e6 is
 * then as well conditioned as one with |p| = 1.
 * p = 0: (b) proves A non-singular for any sg, but bounds the bottom row
 * of T^-1 only as ||.|| / sg. That row is exact by structure here: row 3
 * of the row view is (0, 0, 0, w), never a pivot before step 3, so it
 * stays (0, 0, 0, 1/w) and the bottom row of T^-1 is a backward-stable
 * solve with R plus at most 2^-150 / sg ||R^-1|| / |w| of underflow.
 * Underflow of tiny entries of s T (<= 2^-150 each) perturbs the residual
 * by < ||X|| 2^-150 4 2^60 < 2^-9 (||X|| < 2^21 for a balanced largest
 * element >= 1/4 and cond < 2^19), so (b) covers T itself. Unscaling s X
 * loses F (overflow, or gradual underflow); the residual of what is
 * returned then grows by ||F / s|| na: DH_OK only if that is <= 2^-4
 * (total < 1/2 + 1/8 rounding + 2^-9 + 2^-4 < 1), else DH_ERR_OVERFLOW.
 * Each lost element is <= 2^-150 / s, weighted by <= 2^60, and na <= 8,
 * so this needs s < 2^-81, i.e. (s >= 1 / (6 max|T_ij|)) max|T_ij| >= 2^78.
 * The inverse of A does
 * not overflow below the condition limit: ||A^-1|| <= 2^19 / ||A|| with
 * ||A|| >= 1/4 balanced, times <= 2^60 unbalanced.
 *
 * Fast paths (DH_FAST_PATHS) accept a matrix only when a cheap test PROVES
 * it well conditioned; everything else goes to the general path, which
 * decides. For an n x n A with squared row norms rho_i and
 * S = sum rho_i = ||A||_F^2, Hadamard's inequality bounds every cofactor:
 *   n = 3: ||adj A||_F^2 <= S^2,  n = 4: ||adj A||_F^2 <= S^3 / 4
 * (Maclaurin), so with ||A||_2 <= sqrt(S) and A^-1 = adj A / det,
 *   cond_2(A) <= S^1.5 / |det| (n = 3),  S^2 / (2 |det|) (n = 4).
 * Accepted iff that is <= C = 2^10, tested as det^2 C^2 >= S^3 (n = 3),
 * 4 det^2 C^2 >= S^4 (n = 4): a 1-norm condition <= n 2^10 < 2^18 =
 * DH_MAT4_COND_MAX / 2, which the general path accepts too (the status does
 * not depend on the path). C bounds the adjugate's error, not only the
 * condition: the cofactors of an A with one large singular value cancel,
 * and the error grows like u S^(n/2) / |det| (sigma_1 / sigma_2 times
 * cond u): C = 2^16 would allow 15 cond u against the general path's 2,
 * with C = 2^10 the adjugate stays within the general inverse's bound
 * (rigid and scaled-rigid T, the common inputs, have S^1.5 / |det| = 3^1.5
 * times their scale: unaffected). For a
 * singular matrix the computed det is rounding noise below 16 u S^(n/2):
 * it never passes. Both sides scale alike (degree 2n) and the limits on S
 * keep every product normal, so the decision is exact and scale-free; a
 * NaN or Inf makes a comparison false. Rotations pass with margin 2^20/27.
 * The projective test is on the balanced B = D^-1 T D: det B = det T and
 * ||B||_F^2 = ||R||_F^2 + 2 |p| |q| + w^2 needs no sg (|p| |q| is bounded
 * by |p|_1 |q|_1).
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "dhmath/mat4.h"
#include "../internal/dh_floatops.h"
#include "../internal/dh_mathf.h"

/* Unit roundoff of float, 2^-24. */
#define DH_U24 5.9604644775390625e-8f

/* ---------------------------------------------------------------------- */
/* rigid inverse                                                          */
/* ---------------------------------------------------------------------- */

/*
 * Affine completion of inv_certified: with R^-1 (row view) in rows
 * 0..2, columns 0..2 of X and the corner w of T (a power of two), writes
 * the translation and bottom row of T^-1 as those of the affine
 * T0 = [R, p r; 0 0 0 1], r = 1 / w, times diag(1, 1, 1, r):
 * 0 - (R^-1 (p r)) (0 - dot keeps an exact zero positive) and 0 0 0 r.
 * For T = 2^k T0 (T0 affine) p r is T0's p, exactly. Returns NaN iff a
 * translation entry is NaN or Inf.
 */
static DH_NOINLINE float inv_affine_t(dh_mat4_f32 *X, const dh_mat4_f32 *T)
{
    const float r = 1.0f / T->m[3][3];
    const float px = T->m[3][0] * r, py = T->m[3][1] * r, pz = T->m[3][2] * r;
    float z = 0.0f;
    int i;
    for (i = 0; i < 3; i++) {
        const float t = 0.0f - (px * X->m[0][i] + py * X->m[1][i] + pz * X->m[2][i]);
        X->m[3][i] = t;
        X->m[i][3] = 0.0f;
        z += t * 0.0f;
    }
    X->m[3][3] = r;
    return z;
}

/* rows of the inverse are n, o, a; column p is -R^T p; every element is
 * read before the first write, so out may alias T. Two bodies: the entries
 * written out in registers (default build), or the same entries in the
 * same order from loops over a copy (size-first build). */
#if DH_FAST_PATHS
void dh_mat4_inv_rigid_f32(const dh_mat4_f32 *T, dh_mat4_f32 *out)
{
    float nx, ny, nz, ox, oy, oz, ax, ay, az, px, py, pz;
    DH_ASSERT(out != NULL && T != NULL);
    nx = T->m[0][0]; ny = T->m[0][1]; nz = T->m[0][2];
    ox = T->m[1][0]; oy = T->m[1][1]; oz = T->m[1][2];
    ax = T->m[2][0]; ay = T->m[2][1]; az = T->m[2][2];
    px = T->m[3][0]; py = T->m[3][1]; pz = T->m[3][2];
    out->m[0][0] = nx; out->m[0][1] = ox; out->m[0][2] = ax; out->m[0][3] = 0.0f;
    out->m[1][0] = ny; out->m[1][1] = oy; out->m[1][2] = ay; out->m[1][3] = 0.0f;
    out->m[2][0] = nz; out->m[2][1] = oz; out->m[2][2] = az; out->m[2][3] = 0.0f;
    out->m[3][0] = 0.0f - (px * nx + py * ny + pz * nz);
    out->m[3][1] = 0.0f - (px * ox + py * oy + pz * oz);
    out->m[3][2] = 0.0f - (px * ax + py * ay + pz * az);
    out->m[3][3] = 1.0f;
}
#else
void dh_mat4_inv_rigid_f32(const dh_mat4_f32 *T, dh_mat4_f32 *out)
{
    dh_mat4_f32 t;
    int c, r;
    DH_ASSERT(out != NULL && T != NULL);
    t = *T;
    for (c = 0; c < 3; c++) {
        for (r = 0; r < 3; r++) out->m[c][r] = t.m[r][c];
        out->m[c][3] = 0.0f;
        out->m[3][c] = 0.0f - (t.m[3][0] * t.m[c][0] + t.m[3][1] * t.m[c][1] + t.m[3][2] * t.m[c][2]);
    }
    out->m[3][3] = 1.0f;
}
#endif

/* ---------------------------------------------------------------------- */
/* general inverse                                                        */
/* ---------------------------------------------------------------------- */

/* bits of w if the bottom row is exactly 0 0 0 w (+-0 on the bits: the
 * sign shifted out), else 0 */
static DH_NOINLINE uint32_t inv_bottom_w(const dh_mat4_f32 *T)
{
    uint32_t b, z = 0u;
    int i;
    for (i = 0; i < 3; i++) {
        memcpy(&b, &T->m[i][3], sizeof b);
        z |= b << 1;
    }
    memcpy(&b, &T->m[3][3], sizeof b);
    return (z == 0u) ? b : 0u;
}

/* bottom row exactly 0 0 0 1 */
DH_INLINE int inv_is_affine(const dh_mat4_f32 *T) { return inv_bottom_w(T) == 0x3F800000u; }

/* bottom row exactly 0 0 0 w, w a normal power of two: the affine type of
 * inv_certified (out of line: no extra value in its frame) */
static DH_NOINLINE DH_COLD int inv_affine_type(const dh_mat4_f32 *T)
{
    const uint32_t b = inv_bottom_w(T);
    return (b & 0x007FFFFFu) == 0u && (b & 0x7F800000u) != 0u;
}

/*
 * Element (i, j) of the row-view matrix the general path works on: s M
 * (aff == 0), or blockdiag(s R, 1) for an affine T (aff != 0).
 */
DH_INLINE float inv_at(const dh_mat4_f32 *M, int i, int j, float s, int aff)
{
    if (!aff || (i < 3 && j < 3)) return M->m[i][j] * s;
    return (i == j) ? 1.0f : 0.0f;
}

/* element (i, j) of the row view weighted like D^-1 . D with w in place of
 * sg: column 3 of rows 0..2 times w, columns 0..2 of row 3 over w */
static DH_NOINLINE DH_COLD float inv_wt(float q, int i, int j, float w)
{
    if (i < 3) return (j < 3) ? q : q * w;
    return (j < 3) ? q / w : q;
}

/*
 * The balanced norms (max row sum, weights inv_wt(., sg)) of the general
 * path in one loop; NaN if an element is NaN or Inf (t: a max alone would
 * drop a NaN row):
 *  - X != NULL: the residual ||X A - I||, A = inv_at(M, ., ., s, aff);
 *  - X == NULL: ||A|| (0 + 1 * A_ij), and W != NULL receives
 *    inv_wt(A_ij, ., ., g): with M == W, s == 1, aff == 0 and g a normal
 *    power of two this (re)balances W in place (q / g == q * (1 / g));
 *  - aff < 0 (W == M, g = 1 / s): the unscaling W = s M (+ 0 maps -0 to
 *    +0), returning the norm of what it lost, (s M) / s - M.
 * A zero stored as +0 instead of -0 changes no later sum, comparison or
 * unscaled value.
 */
static DH_NOINLINE DH_COLD float inv_bnorm(const dh_mat4_f32 *X, const dh_mat4_f32 *M, float s, float sg, int aff,
                                          dh_mat4_f32 *W, float g)
{
    float res = 0.0f, t = 0.0f;
    int i, j, k;
    for (i = 0; i < 4; i++) {
        float rs = 0.0f;
        for (j = 0; j < 4; j++) {
            float q = 0.0f;
            if (aff < 0) {
                const float x = M->m[i][j], v = x * s + 0.0f;
                W->m[i][j] = v;
                q = v * g - x;
            } else {
                /* X == NULL: the term k == i alone, 0 + 1 * A_ij */
                for (k = 0; k < 4; k++) {
                    float x = 1.0f;
                    if (X != NULL) x = X->m[i][k];
                    else if (k != i) continue;
                    q += x * inv_at(M, k, j, s, aff);
                }
                if (j == i && X != NULL) q -= 1.0f;
                q = inv_wt(q, i, j, g);
                if (W != NULL) W->m[i][j] = q;
            }
            rs += inv_wt(fabsf(q), i, j, sg);
        }
        t += rs;
        res = (rs > res) ? rs : res;
    }
    return res + t * 0.0f;
}

/* the four elements of X with the indices u + n st, n = 0..3, exchanged
 * with those at v + n st (element index 4 i + j for X->m[i][j]): rows
 * u / 4, v / 4 with st = 1, columns u, v with st = 4; u == v is a no-op */
static DH_NOINLINE DH_COLD void inv_swap4(dh_mat4_f32 *X, unsigned u, unsigned v, unsigned st)
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

/* One Gauss-Jordan step after the interchange: row k divided by its pivot
 * (as a multiplication by the reciprocal), column k eliminated from the
 * other rows */
DH_INLINE void inv_gj_eliminate(dh_mat4_f32 *X, int k)
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

/* In-place Gauss-Jordan with partial pivoting on the rows of X (the
 * columns of T): X becomes X^-1. Returns 0 on an exactly zero pivot (X
 * then undefined). */
static DH_NOINLINE DH_COLD int inv_gauss_jordan(dh_mat4_f32 *X)
{
    unsigned perm = 0u; /* pivot row of step k in bits 6 - 2k, 7 - 2k */
    int i, k;
    for (k = 0; k < 4; k++) {
        int p = k;
        for (i = k + 1; i < 4; i++) {
            if (fabsf(X->m[i][k]) > fabsf(X->m[p][k])) p = i;
        }
        if (dh_feq_f32(X->m[p][k], 0.0f)) return 0;
        perm = perm * 4u + (unsigned)p;
        inv_swap4(X, 4u * (unsigned)k, 4u * (unsigned)p, 1u);
        inv_gj_eliminate(X, k);
    }
    /* undo the interchanges on the columns, last first */
    for (k = 3; k >= 0; k--) {
        inv_swap4(X, (unsigned)k, perm & 3u, 4u);
        perm >>= 2;
    }
    return 1;
}

/*
 * The scaling of the general path: returns the power of two s that brings
 * the largest of (row sums of R, |w|, |p|_1 / sg, |q|_1 sg) of s M (M: T,
 * or blockdiag(R, 1) for the affine type), which is within a factor 3 of
 * its largest balanced element, into [1, 2), clamped to [2^-126, 2^127];
 * 0 for a zero or denormal matrix (R), NaN if an element of T is NaN or
 * Inf. sg (1 for the affine type) goes to X->m[0][0] of the scratch X (no
 * pointer to a local in the caller: a small frame on Cortex-M0+). Both
 * come from A0 = s0 M, s0 the power of two bringing max|M_ij| into [1, 2)
 * ([2, 4) for the top binade): A0 and s T are the same floats for T and
 * any exact 2^k T, so every later decision is too (unless s is clamped).
 */
static DH_NOINLINE DH_COLD float inv_scan(const dh_mat4_f32 *T, int aff, dh_mat4_f32 *X)
{
    float s, cp = 0.0f, rq = 0.0f, m3 = 0.0f, sg = 1.0f, w;
    uint32_t u, ur = 0u, ub = 0u, e, b;
    int i, j;
    /* largest |element| of R and of p, q, w, on the bits (for finite
     * floats the order of |x| is that of the bits without the sign; NaN
     * and Inf are above 0x7F7FFFFF) */
    for (i = 0; i < 4; i++) {
        for (j = 0; j < 4; j++) {
            memcpy(&u, &T->m[i][j], sizeof u);
            u &= 0x7FFFFFFFu;
            if (i < 3 && j < 3) ur = (u > ur) ? u : ur;
            else ub = (u > ub) ? u : ub;
        }
    }
    u = (ub > ur) ? ub : ur;
    if (u > 0x7F7FFFFFu) {
        u = 0x7FC00000u;                /* NaN */
        memcpy(&s, &u, sizeof s);
        return s;
    }
    if (!aff) ur = u;
    if (ur < 0x00800000u) return 0.0f;  /* zero or denormal */
    e = ur >> 23;
    b = (e >= 254u) ? 1u : 254u - e;    /* exponent field of s0 */
    e = b << 23;
    memcpy(&s, &e, sizeof s);
    /* row sums of R, |p|_1, |q|_1 of A0 = s0 M (elements <= 4) */
    for (i = 0; i < 3; i++) {
        float rs = 0.0f;
        for (j = 0; j < 3; j++) rs += fabsf(T->m[i][j]) * s;
        m3 = (rs > m3) ? rs : m3;
        rq += fabsf(T->m[i][3]) * s;    /* column 3: q */
        cp += fabsf(T->m[3][i]) * s;    /* row 3: p */
    }
    w = fabsf(T->m[3][3]) * s;
    if (aff) {
        cp = 0.0f;                      /* M = blockdiag(s0 R, 1) */
        rq = 0.0f;
        w = 1.0f;
    }
    /* sg (R = 0 gives 0 or Inf, which the clamp maps to 2^-60, 2^60) */
    if (dh_feq_f32(cp, 0.0f)) {
        if (!dh_feq_f32(rq, 0.0f)) sg = m3 / rq * DH_U24;          /* p exactly 0 */
    } else if (dh_feq_f32(rq, 0.0f)) {
        sg = cp / m3 * 16777216.0f;                      /* q exactly 0 */
    } else {
        sg = dh_sqrtf_(cp) / dh_sqrtf_(rq);
    }
    /* clamped to [2^-60, 2^60] on the bits (sg >= 0) */
    memcpy(&u, &sg, sizeof u);
    u = (u < 0x21800000u) ? 0x21800000u : u;
    u = (u > 0x5D800000u) ? 0x5D800000u : u;
    memcpy(&sg, &u, sizeof sg);
    X->m[0][0] = sg;
    /* within a factor 3 of the largest balanced element of A0, in
     * [2^-62, 2^4] (that of A0 is >= 1), on the bits: s = s0 2^-E, E its
     * exponent; exponent field b - E, clamped to the normal range */
    cp /= sg;
    rq *= sg;
    memcpy(&e, &m3, sizeof e);
    memcpy(&u, &w, sizeof u);
    e = (u > e) ? u : e;
    memcpy(&u, &cp, sizeof u);
    e = (u > e) ? u : e;
    memcpy(&u, &rq, sizeof u);
    e = (u > e) ? u : e;
    e = b + 127u - (e >> 23);
    if ((e - 1u) > 253u) {
        if ((e - 1u) >= 0x80000000u) {
            e = 1u;                     /* e <= 0 (wrapped) */
        } else {
            e = 254u;
        }
    }
    e <<= 23;
    memcpy(&s, &e, sizeof s);
    return s;
}

/* The general path (see the top of the file) into the scratch X (must not
 * alias T; undefined on error). */
static DH_NOINLINE DH_COLD dh_status inv_certified(const dh_mat4_f32 *T, dh_mat4_f32 *X)
{
    const int aff = inv_affine_type(T);
    const float s = inv_scan(T, aff, X), sg = X->m[0][0];
    float na, z = 0.0f, f = sg * 1.41421356f;
    uint32_t b;
    if (!dh_feq_f32(s, s)) return DH_ERR_NAN;
    if (dh_feq_f32(s, 0.0f)) return DH_ERR_SINGULAR;
    /* X = A and its balanced norm */
    na = inv_bnorm(NULL, T, s, sg, aff, X, 1.0f);
    /* f: the power of two nearest to sg (within sqrt(2)), exact for sg in
     * [2^-60, 2^60]; eliminate on the balanced X (partial pivoting then
     * sees the magnitudes the balanced norms measure), unbalance */
    memcpy(&b, &f, sizeof b);
    b &= 0x7F800000u;
    memcpy(&f, &b, sizeof f);
    (void)inv_bnorm(NULL, X, 1.0f, sg, 0, X, f);
    if (!inv_gauss_jordan(X)) return DH_ERR_SINGULAR;
    if (!(na * inv_bnorm(NULL, X, 1.0f, sg, 0, X, 1.0f / f) < DH_MAT4_COND_MAX)) return DH_ERR_SINGULAR;
    if (!(inv_bnorm(X, T, s, sg, inv_affine_type(T), NULL, 1.0f) <= 0.5f)) return DH_ERR_SINGULAR;
    if (!(inv_bnorm(NULL, X, s, sg, -1, X, 1.0f / s) * na <= 0.0625f)) return DH_ERR_OVERFLOW;
    /* X and T are finite here: the products commute bitwise. (The affine
     * type is asked again rather than kept across the calls: one value
     * less in this frame keeps the M0+ stack within its budget.) */
    if (inv_affine_type(T)) z = inv_affine_t(X, T);
    if (!dh_feq_f32(z, z)) return DH_ERR_OVERFLOW;
    return DH_OK;
}

#if DH_FAST_PATHS
/* ---------------------------------------------------------------------- */
/* general inverse: fast paths (tests at the top of the file)             */
/* ---------------------------------------------------------------------- */

#define DH_FAST_C2 1048576.0f                 /* C^2 = 2^20 */
#define DH_FAST_LO3 5.9604644775390625e-8f     /* 2^-24: range of S, 3x3 */
#define DH_FAST_HI3 16777216.0f                /* 2^24 */
#define DH_FAST_LO4 1.52587890625e-5f          /* 2^-16: range of S, 4x4 */
#define DH_FAST_HI4 65536.0f                   /* 2^16 */
#define DH_FAST_PQ 268435456.0f                /* 2^28: |p|_1, |q|_1 limit, 4x4 */

/*
 * Affine T = [R p; 0 0 0 1] (caller checked): the rows of R^-1 are
 * (o x a, a x n, n x o) / det, det = n . (o x a), n, o, a the columns of R.
 * The test uses R only (p does not enter the conditioning), on s R with s
 * an exact power of two chosen by the caller (1 on the common path), and
 * R^-1 = s (s R)^-1. Writes out and returns 1, or returns 0 (out
 * untouched; out may alias T).
 */
static DH_NOINLINE int inv_affine(dh_mat4_f32 *out, const dh_mat4_f32 *T, float s)
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
    f = s / det; /* exact scaling of 1 / det */
    /* element (row i, column j) of R^-1 is c_ij f; "+ 0.0f" maps -0 to +0 */
    x00 = c00 * f + 0.0f; x01 = c01 * f + 0.0f; x02 = c02 * f + 0.0f;
    x10 = c10 * f + 0.0f; x11 = c11 * f + 0.0f; x12 = c12 * f + 0.0f;
    x20 = c20 * f + 0.0f; x21 = c21 * f + 0.0f; x22 = c22 * f + 0.0f;
    t0 = 0.0f - (x00 * px + x01 * py + x02 * pz);
    t1 = 0.0f - (x10 * px + x11 * py + x12 * pz);
    t2 = 0.0f - (x20 * px + x21 * py + x22 * pz);
    /* the translation may overflow (or be NaN from p): the general path
     * reports it */
    if (!dh_feq_f32((t0 - t0) + (t1 - t1) + (t2 - t2), 0.0f)) return 0;
    out->m[0][0] = x00; out->m[0][1] = x10; out->m[0][2] = x20; out->m[0][3] = 0.0f;
    out->m[1][0] = x01; out->m[1][1] = x11; out->m[1][2] = x21; out->m[1][3] = 0.0f;
    out->m[2][0] = x02; out->m[2][1] = x12; out->m[2][2] = x22; out->m[2][3] = 0.0f;
    out->m[3][0] = t0; out->m[3][1] = t1; out->m[3][2] = t2; out->m[3][3] = 1.0f;
    return 1;
}

/* inv_affine with the power of two s that brings max|R_ij| into
 * [1, 2), after s = 1 failed (the decision is then invariant under any
 * scaling of R); 0 also for a zero, denormal or non-finite R */
static DH_NOINLINE int inv_affine_scaled(dh_mat4_f32 *out, const dh_mat4_f32 *T)
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
    if (!(mx >= FLT_MIN && mx <= FLT_MAX)) return 0;
    memcpy(&e, &mx, sizeof e);
    e >>= 23;                           /* 1..254 */
    e = (e >= 254u) ? 1u : 254u - e;    /* exponent of 2^(127 - e) */
    e <<= 23;
    memcpy(&s, &e, sizeof s);
    return inv_affine(out, T, s);
}

/*
 * Projective T = [R p; q^T w]: adjugate from the 2x2 minors of two row
 * pairs (two phases, few values live at a time), row view M = T^T.
 * Phase 1: the test, and columns 0, 1 of the inverse from the 2x2 minors
 * of rows 2, 3; returns 1 / det, or 0 if the test fails.
 */
static DH_NOINLINE float inv_proj_phase1(dh_mat4_f32 *X, const dh_mat4_f32 *M)
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
    /* p = row 3, q = column 3 (rows 0..2): S >= ||B||_F^2 (an upper bound
     * keeps the test a proof), unit-free */
    const float p1 = fabsf(a30) + fabsf(a31) + fabsf(a32);
    const float q1 = fabsf(a03) + fabsf(a13) + fabsf(a23);
    const float S = (a00 * a00 + a01 * a01 + a02 * a02) + (a10 * a10 + a11 * a11 + a12 * a12) +
                    (a20 * a20 + a21 * a21 + a22 * a22) + 2.0f * (p1 * q1) + a33 * a33;
    float f;
    /* |p|_1, |q|_1 <= 2^28 and S <= 2^16: no product here or in phase 2
     * overflows */
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
static DH_NOINLINE void inv_proj_phase2(dh_mat4_f32 *X, const dh_mat4_f32 *M, float f)
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
static DH_NOINLINE int inv_proj(dh_mat4_f32 *X, const dh_mat4_f32 *M)
{
    const float f = inv_proj_phase1(X, M);
    if (dh_feq_f32(f, 0.0f)) return 0;
    inv_proj_phase2(X, M, f);
    return 1;
}
#endif

/*
 * General inverse into the scratch X (must not alias T; undefined on
 * error): the fast path for the input's shape (default build), else the
 * general path (after inv_general's affine attempt only an affine T
 * that fails the fast test again gets here). The size-first build has the
 * general path only.
 */
#if DH_FAST_PATHS
DH_INLINE dh_status inv_into(dh_mat4_f32 *X, const dh_mat4_f32 *T)
{
    if (inv_is_affine(T)) {
        if (inv_affine(X, T, 1.0f) || inv_affine_scaled(X, T)) return DH_OK;
    } else {
        if (inv_proj(X, T)) return DH_OK;
    }
    return inv_certified(T, X);
}
#else
DH_INLINE dh_status inv_into(dh_mat4_f32 *X, const dh_mat4_f32 *T)
{
    return inv_certified(T, X);
}
#endif

/* The public general inverse (out untouched on error, out may alias T),
 * inlined into its two callers: no extra frame on the general path. The
 * default build tries the affine fast path straight into out first
 * (inv_affine reads T first). */
#if DH_FAST_PATHS
DH_INLINE dh_status inv_general(dh_mat4_f32 *out, const dh_mat4_f32 *T)
{
    dh_mat4_f32 X;
    dh_status st;
    if (inv_is_affine(T) && (inv_affine(out, T, 1.0f) || inv_affine_scaled(out, T))) return DH_OK;
    st = inv_into(&X, T);
    if (st != DH_OK) return st;
    *out = X;
    return DH_OK;
}
#else
DH_INLINE dh_status inv_general(dh_mat4_f32 *out, const dh_mat4_f32 *T)
{
    dh_mat4_f32 X;
    const dh_status st = inv_into(&X, T);
    if (st != DH_OK) return st;
    *out = X;
    return DH_OK;
}
#endif

dh_status dh_mat4_inv_f32(const dh_mat4_f32 *T, dh_mat4_f32 *out)
{
    DH_ASSERT(out != NULL && T != NULL);
    return inv_general(out, T);
}

/* ---------------------------------------------------------------------- */
/* rigidity                                                               */
/* ---------------------------------------------------------------------- */

dh_status dh_mat4_check_rot_f32(const dh_mat4_f32 *T, float tol)
{
    float det = 0.0f, z = 0.0f;
    int i, j, k, n, bad = 0;
    DH_ASSERT(T != NULL);
    if (!(tol >= 0.0f)) return DH_ERR_ARG;
    for (i = 0; i < 3; i++) {
        /* R^T R - I, row i up to the diagonal (products of finite entries
         * may overflow to Inf and fail the test); z: NaN iff an entry of
         * R is NaN or Inf, which takes precedence */
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
    if (!dh_feq_f32(z, z)) return DH_ERR_NAN;
    if (bad) return DH_ERR_NOT_RIGID;
    /* det R = n . (o x a) = sum of n_i (o_j a_k - o_k a_j) over the cyclic
     * permutations (i, j, k) of (0, 1, 2) */
    for (n = 0, i = 0, j = 1, k = 2; n < 3; n++) {
        const int t = i;
        det += T->m[0][i] * (T->m[1][j] * T->m[2][k] - T->m[1][k] * T->m[2][j]);
        i = j;
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
    if (dh_mat4_check_finite_f32(T) != DH_OK) return DH_ERR_NAN;
    if (!inv_is_affine(T)) return DH_ERR_NOT_RIGID;
    return dh_mat4_check_rot_f32(T, tol);
}

/*
 * 1 iff the translation of the closed-form rigid inverse of T, -(R^T p),
 * is finite (the same products and sums as dh_mat4_inv_rigid_f32): a
 * rigid T with |p| near FLT_MAX then gets DH_ERR_OVERFLOW like
 * dh_mat4_inv_f32 instead of an Inf.
 */
static DH_NOINLINE int inv_rigid_t_ok(const dh_mat4_f32 *T)
{
    float z = 0.0f;
    int j;
    /* the entries of a rigid R are within 1 + 1e-5 in magnitude, so
     * |p_i| <= 2^125 bounds each entry by 3 2^125 (1 + 1e-5) < 2^127 */
    if (fabsf(T->m[3][0]) <= 0x1p125f && fabsf(T->m[3][1]) <= 0x1p125f && fabsf(T->m[3][2]) <= 0x1p125f) return 1;
    for (j = 0; j < 3; j++) {
        const float t = T->m[3][0] * T->m[j][0] + T->m[3][1] * T->m[j][1] + T->m[3][2] * T->m[j][2];
        z += t - t;   /* NaN iff t is Inf or NaN */
    }
    return dh_feq_f32(z, 0.0f);
}

/*
 * The rigid choice of dh_mat4_inv_auto_f32: T^-1 into X by the closed form
 * and DH_OK if T is rigid, DH_ERR_NAN, DH_ERR_OVERFLOW, or DH_ERR_NOT_RIGID
 * (X untouched: the general inverse decides).
 */
static DH_FAST_NOINLINE dh_status inv_rigid_chk(dh_mat4_f32 *X, const dh_mat4_f32 *T)
{
    const dh_status st = dh_mat4_check_rigid_f32(T, DH_MAT4_RIGID_TOL);
    if (st != DH_OK) return st;
    if (!inv_rigid_t_ok(T)) return DH_ERR_OVERFLOW;
    dh_mat4_inv_rigid_f32(T, X);
    return DH_OK;
}

dh_status dh_mat4_inv_auto_f32(const dh_mat4_f32 *T, dh_mat4_f32 *out)
{
    dh_status st;
    DH_ASSERT(out != NULL && T != NULL);
    st = inv_rigid_chk(out, T);
    if (st == DH_OK) return DH_OK;
    if (st != DH_ERR_NOT_RIGID) return st;
    return inv_general(out, T);
}

/* ---------------------------------------------------------------------- */
/* planes                                                                 */
/* ---------------------------------------------------------------------- */

/* 1 iff every coefficient of P is finite (x * 0 is NaN exactly for a NaN
 * or Inf x); out of line in the default build: no value stays live in the
 * frame of dh_mat4_apply_plane_f32 (M0+ stack guard) */
static DH_FAST_NOINLINE int inv_plane_finite(const dh_plane_f32 *P)
{
    const float z = P->a * 0.0f + P->b * 0.0f + P->c * 0.0f + P->d * 0.0f;
    return dh_feq_f32(z, z);
}

/* T^-1 into X as dh_mat4_inv_auto_f32 takes it: the rigid inverse when it
 * applies (default build), else the general inverse, which alone gives the
 * same statuses (size-first build) */
#if DH_FAST_PATHS
DH_INLINE dh_status inv_auto_into(dh_mat4_f32 *X, const dh_mat4_f32 *T)
{
    const dh_status st = inv_rigid_chk(X, T);
    if (st != DH_ERR_NOT_RIGID) return st;
    return inv_into(X, T);
}
#else
DH_INLINE dh_status inv_auto_into(dh_mat4_f32 *X, const dh_mat4_f32 *T)
{
    return inv_into(X, T);
}
#endif

dh_status dh_mat4_apply_plane_f32(const dh_mat4_f32 *T, const dh_plane_f32 *P, dh_plane_f32 *Q)
{
    dh_mat4_f32 X; /* T^-1 */
    dh_status st;
    DH_ASSERT(T != NULL && P != NULL && Q != NULL);
    if (!inv_plane_finite(P)) return DH_ERR_NAN;
    st = inv_auto_into(&X, T);
    if (st != DH_OK) return st;
    dh_plane_mul_f32(P, &X, Q);
    return DH_OK;
}
