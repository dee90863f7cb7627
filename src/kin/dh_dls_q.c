/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_dls_q.c - singularity measures and one damped-least-squares step of
 * the fixed-point Jacobian (integer only: no float, no libm, no 64-bit
 * division).
 *
 * Method. J (dh_jacobian_q's formats) is read as B, each row in one
 * format Q(g_k): linear rows (revolute entries from dh_qpos, prismatic
 * ones from Q2.30) with g the largest value <= 28 for which the largest
 * linear revolute entry and the damping stay below 2^28, angular rows
 * (from Q2.30) with the largest g <= 28 for which the damping does; one
 * format for all rows when G = B^T B (n < 6: its sums run over the rows).
 * The Gram matrix G (B B^T or B^T B, plus lambda^2 in each row's format)
 * is exact in 64 bits (n <= 32 products below 2^56) and is equilibrated
 * by powers of two, A'_kl = G_kl 2^-(c_k + c_l) with A'_kk in [1/4, 1)
 * in Q2.30 (as a real, A' = D^-1 G D^-1, D = diag(2^(c_k + 15))); A' is
 * factored A' = L L^T (Cholesky by columns, sums of exact products in
 * Q60 rounded once, each pivot's reciprocal square root by dh_q_rsqrt29
 * with three Newton steps). The damped step solves
 * (J J^T + lambda^2 I) x = e as A' y = D^-1 S e (S = diag(2^g_k)) and
 * forms dq = B^T D^-1 y in 64-bit sums; the right-hand side is scaled
 * to [2^26, 2^27) to leave the substitutions headroom and scaled down
 * again, by the bits an intermediate exceeded, if one reaches 2^29 (only
 * near a singularity with little damping). The uniform scaling to dq_max
 * uses a 32-bit shift-subtract quotient rounded down, so that no output
 * exceeds its bound.
 *
 * Smallest singular value: lambda_min(G) >= 1 / trace(G^-1) (the largest
 * eigenvalue of G^-1 is at most its trace, which is at most m times it).
 * The factor is taken of A' - delta I (delta = 2^-21, more than the
 * factorization's backward error), so that L L^T <= A' in the positive
 * semidefinite order and sum_k D_k^-2 |L^-1 e_k|^2 (in J's units) bounds
 * trace(G^-1) from above; L^-1 is formed in Q18, every term rounded up,
 * the root rounded down and lowered by 2^-10 relative and 1 LSB.
 *
 * Manipulability: log2 sqrt det G = sum_k log2(D_k 2^-g_k) + sum_j log2
 * L_jj, the pivots' roots multiplied in 31-bit mantissas, the logarithm
 * of the product by 16 repeated squarings (Q16.16).
 */
#include "dhmath/kin.h"
#include "kin_impl.h"
#include "../internal/dh_qmath.h"

#define DLSQ_M 6u                         /* largest Gram order */
#define DLSQ_TRI ((DLSQ_M * (DLSQ_M + 1u)) / 2u)
#define DLSQ_R2D25 1922527338             /* 180 / pi in Q6.25 */
#define DLSQ_DMIN_FB 20u                  /* pivot floor with damping, 2^-40 (Q60 bits) */
#define DLSQ_DSING_FB 36u                 /* undamped pivot below 2^-24: singular */
#define DLSQ_DELTA30 512                  /* delta of the singular-value factor, 2^-21 in Q2.30 */

/* The call's state and matrices: the caller's dh_dls_work_q (kin.h; L: A'
 * then its factor, packed lower triangle by rows, the diagonal holding the
 * pivots' reciprocal roots iy: 1 / L_jj = iy 2^-ik in Q2.30; c: D =
 * diag(2^(c + 15)); y: the right-hand side and solution), so that no
 * frame of these functions holds more than a few scalars. */
typedef dh_dls_work_q dlsq_ctx;

typedef char dlsq_work_fits[(sizeof(((dh_dls_work_q *)0)->L) == DLSQ_TRI * sizeof(int32_t)) ? 1 : -1];

DH_INLINE uint32_t dlsq_tri(uint32_t i, uint32_t j) { return (i * (i + 1u)) / 2u + j; }

/* x 2^s, rounded (s < 0) or exact (s >= 0, |x 2^s| known to fit). */
static DH_NOINLINE int64_t dlsq_shift(int64_t x, int s)
{
    if (s >= 0) return (int64_t)((uint64_t)x << (unsigned)s);
    if (s < -62) return 0;
    return dh_q_rshr(x, (unsigned)(-s));
}

/* x 2^s as dlsq_shift gives it for a result known to fit 32 bits (the
 * formats keep B below 2^28), in 32 bits: rounded ties up (s < 0: floor
 * plus the bit below the point; by 31 bits -1 exactly for x < -2^30, by
 * more always 0) or exact. */
DH_INLINE int32_t dlsq_cv(int32_t x, int s)
{
    if (s >= 0) return (int32_t)((uint32_t)x << (unsigned)s);
    if (s < -31) return 0;
    if (s == -31) return (x < -0x40000000) ? -1 : 0;
    return (x >> (unsigned)(-s)) + ((x >> (unsigned)(-s - 1)) & 1);
}

/* Format of J's entries in row k: dh_qpos for linear revolute ones, else
 * Q2.30 (prismatic columns' linear rows, angular rows). */
DH_INLINE int dlsq_from(const dlsq_ctx *c, uint32_t k, uint32_t i)
{
    return (k < 3u && ((c->pris >> i) & 1u) == 0u) ? DH_QPOS_FRAC : 30;
}

/* B_ki in Q(g). */
static int32_t dlsq_b(const dlsq_ctx *c, uint32_t k, uint32_t i)
{
    return dlsq_cv(c->J[k * c->n + i], c->g[k >= 3u] - dlsq_from(c, k, i));
}

/* Format of Gram row a. */
static int dlsq_ga(const dlsq_ctx *c, uint32_t a) { return c->cols ? c->g[0] : c->g[a >= 3u]; }

/* G_ab, exact; with revolute columns only and G = B B^T, one shift per
 * row of B. */
static DH_NOINLINE int64_t dlsq_gram(const dlsq_ctx *c, uint32_t a, uint32_t b)
{
    int64_t s = 0;
    uint32_t t;
    if (c->cols) {
        for (t = 0; t < 6u; t++) s = dh_q_mla64(s, dlsq_b(c, t, a), dlsq_b(c, t, b));
    } else if (c->pris != 0u) {
        for (t = 0; t < c->n; t++) s = dh_q_mla64(s, dlsq_b(c, a, t), dlsq_b(c, b, t));
    } else {
        const int32_t *const pa = &c->J[a * c->n], *const pb = &c->J[b * c->n];
        const int sa = c->g[a >= 3u] - dlsq_from(c, a, 0u), sb = c->g[b >= 3u] - dlsq_from(c, b, 0u);
        for (t = 0; t < c->n; t++) s = dh_q_mla64(s, dlsq_cv(pa[t], sa), dlsq_cv(pb[t], sb));
    }
    return s;
}

/* The largest g <= 28 with mx 2^(g - F) < 2^28. */
static int dlsq_fmt1(uint32_t mx)
{
    const int g = (mx == 0u) ? 28 : DH_QPOS_FRAC + 27 - (int)(31u - dh_port_clz(mx));
    return (g > 28) ? 28 : g;
}

/* Row formats: linear rows from the largest linear revolute entry and
 * lam, angular rows from lam (both dh_qpos), so that lam and every entry
 * stay below 2^28; one format for both when G = B^T B (its sums run over
 * the rows). */
static DH_NOINLINE void dlsq_format(dlsq_ctx *c, int32_t lam)
{
    uint32_t mx = (uint32_t)lam, k, i;
    for (k = 0; k < 3u; k++)
        for (i = 0; i < c->n; i++)
            if (((c->pris >> i) & 1u) == 0u) {
                const uint32_t a = dh_q_abs_u32(c->J[k * c->n + i]);
                if (a > mx) mx = a;
            }
    c->g[0] = (int16_t)dlsq_fmt1(mx);
    c->g[1] = c->cols ? c->g[0] : (int16_t)dlsq_fmt1((uint32_t)lam);
}

/* A' = D^-1 (G + lam^2 I) D^-1 - shift I into c->L and c->c (lam in
 * dh_qpos, below 2^28 in every row's format); a zero row of B gives a
 * unit row (not shifted). Returns the zero rows, bit a for row a. */
static DH_NOINLINE uint32_t dlsq_equil(dlsq_ctx *c, int32_t lam, int32_t shift)
{
    uint32_t a, b, zero = 0u;
    for (a = 0; a < c->m; a++) {
        const int32_t la = (int32_t)dlsq_shift(lam, dlsq_ga(c, a) - DH_QPOS_FRAC);
        const int64_t h = dlsq_gram(c, a, a) + dh_q_mul64(la, la);
        if (h == 0) {
            c->c[a] = 0;
            c->L[dlsq_tri(a, a)] = DH_Q_ONE30;
            zero |= 1u << a;
        } else {
            const int ca = ((int)dh_q_bitlen64((uint64_t)h) - 29) >> 1;
            c->c[a] = (int16_t)ca;
            c->L[dlsq_tri(a, a)] = (int32_t)dlsq_shift(h, -2 * ca) - shift;
        }
        for (b = 0; b < a; b++)
            c->L[dlsq_tri(a, b)] = (int32_t)dlsq_shift(dlsq_gram(c, a, b), -(c->c[a] + c->c[b]));
    }
    return zero;
}

/* c->L = A' from save (dlsq_equil's, unshifted), less shift on the
 * diagonal of the rows not in zero: what dlsq_equil(c, 0, shift) writes. */
static DH_NOINLINE void dlsq_restore(dlsq_ctx *c, const int32_t *save, uint32_t zero, int32_t shift)
{
    uint32_t a, p;
    for (p = 0; p < dlsq_tri(c->m, 0); p++) c->L[p] = save[p];
    for (a = 0; a < c->m; a++)
        if (((zero >> a) & 1u) == 0u) c->L[dlsq_tri(a, a)] -= shift;
}

/* 1 unless -2^lb < x < 2^lb (no 64-bit constant: shifts only). */
static int dlsq_out_of(int64_t x, unsigned lb)
{
    const int64_t h = x >> lb;
    return (h != 0 && h != -1) || x == -((int64_t)1 << lb);
}

/* s (Q60) times pivot j's reciprocal root, into Q2.30; *bad when the
 * magnitude of s / 2^30 or of the result reaches 2^lb (lb <= 31). */
static int32_t dlsq_div(const dlsq_ctx *c, uint32_t j, int64_t s, unsigned lb, int *bad)
{
    const int64_t s30 = dh_q_rshr(s, 30u);
    int64_t x;
    if (dlsq_out_of(s30, lb)) {
        *bad = 1;
        return 0;
    }
    x = dh_q_rshr(dh_q_mul64((int32_t)s30, c->L[dlsq_tri(j, j)]), (unsigned)c->ik[j]);
    if (dlsq_out_of(x, lb)) {
        *bad = 1;
        return 0;
    }
    return (int32_t)x;
}

/* Pivot j (Q60, > 0): its reciprocal root iy 2^-ik on the diagonal. */
static DH_NOINLINE void dlsq_pivot(dlsq_ctx *c, uint32_t j, int64_t d)
{
    int32_t mant;
    int t;
    dh_q_norm_even((uint64_t)d, &mant, &t);
    c->L[dlsq_tri(j, j)] = dh_q_rsqrt29(mant, 3u);
    c->ik[j] = (int16_t)(14 + t / 2);
}

/* Cholesky of A' in place (the diagonal receives the pivots' reciprocal
 * roots). Pivots below 2^fb (Q60) are raised to it when raise is set;
 * otherwise the factorization stops: returns 1. */
static DH_NOINLINE int dlsq_chol(dlsq_ctx *c, unsigned fb, int raise)
{
    uint32_t i, j, k;
    for (j = 0; j < c->m; j++) {
        int64_t d = (int64_t)((uint64_t)(int64_t)c->L[dlsq_tri(j, j)] << 30);
        int bad = 0;
        for (k = 0; k < j; k++) d -= dh_q_mul64(c->L[dlsq_tri(j, k)], c->L[dlsq_tri(j, k)]);
        if (d < 0 || (d >> fb) == 0) {
            if (!raise) return 1;
            d = (int64_t)1 << fb;
        }
        dlsq_pivot(c, j, d);
        for (i = j + 1u; i < c->m; i++) {
            int64_t s = (int64_t)((uint64_t)(int64_t)c->L[dlsq_tri(i, j)] << 30);
            for (k = 0; k < j; k++) s -= dh_q_mul64(c->L[dlsq_tri(i, k)], c->L[dlsq_tri(j, k)]);
            c->L[dlsq_tri(i, j)] = dlsq_div(c, j, s, 31u, &bad);
        }
        if (bad) return 1;
    }
    return 0;
}

/* ---- singularity measures ------------------------------------------------ */

/* floor(65536 log2(x / 2^30)) for x in [2^30, 2^31): 16 squarings. */
static int32_t dlsq_log2_frac(uint32_t x0)
{
    uint32_t x = x0, f = 0u;
    unsigned b;
    for (b = 0; b < 16u; b++) {
        const uint64_t s = (uint64_t)dh_q_mul64((int32_t)x, (int32_t)x) >> 30;   /* x < 2^31 */
        f <<= 1;
        if (s >= ((uint64_t)1 << 31)) {
            x = (uint32_t)(s >> 1);
            f |= 1u;
        } else {
            x = (uint32_t)s;
        }
    }
    return (int32_t)f;
}

/* log2 sqrt det G in Q16.16 from the factor of A': G = D A' D with
 * D = diag(2^(c_k + 15)) in Q(g_k) units (A' read as a real), L_jj =
 * 2^ik_j / iy_j, so log2 sqrt det G = sum (c_j + 15 - g_j + ik_j -
 * log2 iy_j); the iy_j are multiplied in 31-bit mantissas. */
static DH_NOINLINE int32_t dlsq_logdet(const dlsq_ctx *c)
{
    uint32_t P = 0x40000000u, j;
    int32_t e = 0;
    for (j = 0; j < c->m; j++) {
        const uint32_t v = (uint32_t)c->L[dlsq_tri(j, j)];
        const unsigned bl = 32u - dh_port_clz(v);
        const uint32_t mant = (bl >= 31u) ? (v >> (bl - 31u)) : (v << (31u - bl));
        uint64_t p = ((uint64_t)P * mant) >> 30;
        /* log2 v = bl - 1 + log2(mant / 2^30) */
        e += c->c[j] + 15 - dlsq_ga(c, j) + c->ik[j] - ((int32_t)bl - 1);
        if (p >= ((uint64_t)1 << 31)) {
            p >>= 1;
            e--;
        }
        P = (uint32_t)p;
    }
    return e * 65536 - dlsq_log2_frac(P);
}

/* Lower bound on the smallest singular value of J in dh_qpos (DH_QPOS_FRAC
 * fraction bits, saturated at INT32_MAX) from the factor L of A' - delta I:
 * 2^F / sqrt(T), T = sum_k 2^-2(c_k + 15 - g_k) |L^-1 e_k|^2, every term
 * rounded up, the root rounded down, then lowered by 2^-10 relative and
 * 1 LSB for the rounding of L^-1. 0 when an entry of L^-1 reaches 2^11
 * (lambda_min(A' - delta I) below about 2^-22). */
static DH_NOINLINE int32_t dlsq_sigma(dlsq_ctx *c)
{
    int32_t *u = c->y, y, mant;
    uint64_t acc = 0u;
    uint32_t i, k, t;
    int bad = 0, cmin = 64, sh, te;
    int64_t v;
    for (k = 0; k < c->m; k++)
        if (c->c[k] - dlsq_ga(c, k) < cmin) cmin = c->c[k] - dlsq_ga(c, k);
    for (k = 0; k < c->m; k++) {
        uint64_t s2 = 0u;
        for (i = k; i < c->m; i++) {
            int64_t s = (int64_t)(i == k) << 48;   /* u in Q18 */
            for (t = k; t < i; t++) s -= dh_q_mul64(c->L[dlsq_tri(i, t)], u[t]);
            u[i] = dlsq_div(c, i, s, 29u, &bad);
            if (bad) return 0;
            s2 += (uint64_t)dh_q_mul64(u[i], u[i]) + ((uint64_t)dh_q_abs_u32(u[i]) << 3) + 16u;
        }
        /* s2 < 2^63 (m terms below 2^60 + 2^34); /16 then 2^-2(c_k - cmin), up */
        sh = 4 + 2 * (c->c[k] - dlsq_ga(c, k) - cmin);
        acc += (sh >= 63) ? 1u : ((s2 >> (unsigned)sh) + 1u);
    }
    /* T = acc 2^(4 + 2g - 60 - 2 cmin - 30) (D_k = 2^(c_k + 15)), so
     * sigma = 2^(F + 43 - g + cmin) / sqrt(acc) */
    dh_q_norm_even(acc, &mant, &te);
    y = dh_q_rsqrt29(mant, 3u);  /* 2^44 / sqrt(mant) */
    sh = DH_QPOS_FRAC + 31 + cmin - 44 - te / 2;
    if (sh >= 0) {
        v = (sh >= 31) ? INT32_MAX : (int64_t)y << (unsigned)sh;
        if (v > INT32_MAX) v = INT32_MAX;
    } else {
        v = (sh <= -62) ? 0 : (int64_t)y >> (unsigned)(-sh);
    }
    v -= (v >> 10) + 1;
    return (v < 0) ? 0 : (int32_t)v;
}

void dh_kin_manip_q_(dh_dls_work_q *c, int32_t *w, int32_t *sigma_min, int32_t *save)
{
    uint32_t i, zero = 0u, p;
    const uint32_t n = c->n;
    const int32_t *const J = c->J;
    c->pris = 0u;
    for (i = 0; i < n; i++)
        if (J[3u * n + i] == 0 && J[4u * n + i] == 0 && J[5u * n + i] == 0) c->pris |= 1u << i;
    c->cols = (n < 6u) ? 1u : 0u;
    c->m = (uint8_t)(c->cols ? n : 6u);
    dlsq_format(c, 0);
    if (w != NULL) {
        zero = dlsq_equil(c, 0, 0);
        if (save != NULL)
            for (p = 0; p < dlsq_tri(c->m, 0); p++) save[p] = c->L[p];
        *w = dlsq_chol(c, DLSQ_DSING_FB, 0) ? INT32_MIN : dlsq_logdet(c);
    }
    if (sigma_min != NULL) {
        if (w != NULL && save != NULL)
            dlsq_restore(c, save, zero, DLSQ_DELTA30);
        else
            (void)dlsq_equil(c, 0, DLSQ_DELTA30);
        *sigma_min = dlsq_chol(c, 0u, 0) ? 0 : dlsq_sigma(c);
    }
}

dh_status dh_manipulability_q(const int32_t *J, uint32_t n, dh_dls_work_q *work, int32_t *w, int32_t *sigma_min)
{
    DH_ASSERT(J != NULL);
    DH_ASSERT(work != NULL);
    if (n == 0u || n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    work->J = J;
    work->n = (uint8_t)n;
    dh_kin_manip_q_(work, w, sigma_min, NULL);
    return DH_OK;
}

/* ---- damped least squares ------------------------------------------------ */

/* e_k D_k^-1 2^s into y (Q2.30 units), every |y_k| < 2^27: s from the
 * largest term, less `down` bits. Returns s; all zero: y zero, INT32_MIN. */
static DH_NOINLINE int dlsq_rhs(const dlsq_ctx *c, const int32_t *e, int down, int32_t *y)
{
    int s = 127;
    uint32_t k;
    for (k = 0; k < 6u; k++) {
        const uint32_t a = dh_q_abs_u32(e[k]);
        if (a != 0u) {
            const int f = (k < 3u) ? DH_QPOS_FRAC : 29;
            const int sk = 27 - (int)(32u - dh_port_clz(a)) + f + c->c[k] - c->g[k >= 3u];
            if (sk < s) s = sk;
        }
    }
    if (s == 127) return INT32_MIN;
    s -= down;
    for (k = 0; k < 6u; k++) {
        const int f = (k < 3u) ? DH_QPOS_FRAC : 29;
        y[k] = (int32_t)dlsq_shift(e[k], s + c->g[k >= 3u] - f - c->c[k]);
    }
    return s;
}

/* Bits to scale b down by so that s (Q60) times pivot i's reciprocal
 * root falls below 2^27 (at least 1). */
static int dlsq_excess(const dlsq_ctx *c, uint32_t i, int64_t s)
{
    const uint64_t a = (s < 0) ? 0u - (uint64_t)s : (uint64_t)s;
    const int x = (int)dh_q_bitlen64(a) - 30 + 31 - c->ik[i] - 27;
    return (x < 1) ? 1 : x;
}

/* A' y = b in place (L z = b, L^T y = z). 0, or the bits by which b must
 * be scaled down for an intermediate that reached 2^29. */
static DH_NOINLINE int dlsq_solve(const dlsq_ctx *c, int32_t *y)
{
    uint32_t i, k;
    int bad = 0;
    for (i = 0; i < 6u; i++) {
        int64_t s = (int64_t)((uint64_t)(int64_t)y[i] << 30);
        for (k = 0; k < i; k++) s -= dh_q_mul64(c->L[dlsq_tri(i, k)], y[k]);
        y[i] = dlsq_div(c, i, s, 29u, &bad);
        if (bad) return dlsq_excess(c, i, s);
    }
    for (i = 6u; i-- > 0u;) {
        int64_t s = (int64_t)((uint64_t)(int64_t)y[i] << 30);
        for (k = i + 1u; k < 6u; k++) s -= dh_q_mul64(c->L[dlsq_tri(k, i)], y[k]);
        y[i] = dlsq_div(c, i, s, 29u, &bad);
        if (bad) return dlsq_excess(c, i, s);
    }
    return 0;
}

/* |dq_i| = mant 2^exp, mant in [2^30, 2^31) rounded down (mant 0: dq_i = 0),
 * sign in *neg: dq_i = 2^(g - s) sum_k B_ki 2^-c_k y_k in rad or length
 * units, times 180/pi 2^16 (revolute) or 2^F (prismatic). */
static DH_NOINLINE uint32_t dlsq_raw(const dlsq_ctx *c, const int32_t *y, int s, uint32_t i, int *ex, int *neg)
{
    int64_t t = 0;
    uint64_t a, p;
    uint32_t k;
    int cmin = 64, x;
    unsigned bl;
    for (k = 0; k < 6u; k++)
        if (c->c[k] < cmin) cmin = c->c[k];
    for (k = 0; k < 6u; k++) t += dh_q_rshr(dh_q_mul64(dlsq_b(c, k, i), y[k]), (unsigned)(c->c[k] - cmin + 3));
    *neg = t < 0;
    a = (t < 0) ? 0u - (uint64_t)t : (uint64_t)t;
    bl = dh_q_bitlen64(a);
    x = -s - cmin + 3 - 30;   /* D = 2^(c + 15): A' read as a real in [1/4, 1) */
    if (bl > 31u) {
        const unsigned drop = bl - 31u;
        a >>= drop;
        x += (int)drop;
    }
    if (((c->pris >> i) & 1u) != 0u) {
        p = a;
        x += DH_QPOS_FRAC;
    } else {
        p = a * (uint64_t)DLSQ_R2D25;
        x -= 9;
    }
    bl = dh_q_bitlen64(p);
    if (bl == 0u) return 0u;
    *ex = x + (int)bl - 31;
    if (bl >= 31u) {
        const unsigned drop = bl - 31u;
        return (uint32_t)(p >> drop);
    }
    {
        const unsigned up = 31u - bl;
        return (uint32_t)(p << up);
    }
}

/* rho = min_i dq_max_i / |dq_i| as q 2^z (q in (2^29, 2^31) rounded down,
 * or q = 0: rho = 0), |dq_i| = m[i] 2^ex[i]; q = UINT32_MAX when no joint
 * moves. */
static DH_NOINLINE uint32_t dlsq_ratio(uint32_t n, const int32_t *m, const int16_t *ex, const int32_t *dq_max, int *z)
{
    uint32_t i, best = UINT32_MAX;
    int bz = 0;
    for (i = 0; i < n; i++) {
        uint32_t a, q;
        unsigned bl;
        int qz;
        if (m[i] == 0) continue;
        if (dq_max[i] == 0) {
            *z = 0;
            return 0u;
        }
        a = (uint32_t)dq_max[i];
        bl = 32u - dh_port_clz(a);
        a <<= 31u - bl;
        q = dh_q_ufloor30(a, (uint32_t)m[i]);   /* a, m in [2^30, 2^31) */
        qz = (int)bl - 31 - ex[i] - 30;
        if (best == UINT32_MAX || qz <= bz - 2 ||
            (qz <= bz + 2 && dlsq_shift((int64_t)q, qz - bz + 2) < dlsq_shift((int64_t)best, 2))) {
            best = q;
            bz = qz;
        }
    }
    *z = bz;
    return best;
}

/* dq_i from |dq_i| = m 2^ex: times rho rounded down when q != UINT32_MAX
 * (rho < 1), else rounded; within dq_max_i (if given) or saturated (*ovf). */
static DH_NOINLINE int32_t dlsq_out(uint32_t m, int ex, int neg, uint32_t q, int z, const int32_t *dq_max, uint32_t i, int *ovf)
{
    int64_t v;
    if (m == 0u) return 0;
    if (q != UINT32_MAX) {
        const int sh = ex + z;
        if (sh >= 0) {
            v = INT64_MAX;   /* not reached: |dq_i| rho <= dq_max_i < 2^31 */
        } else {
            v = (sh <= -63) ? 0 : (int64_t)(((uint64_t)m * q) >> (unsigned)(-sh));
        }
    } else if (ex >= 0) {
        v = (ex >= 32) ? INT64_MAX : (int64_t)m << (unsigned)ex;
    } else {
        v = (ex <= -62) ? 0 : dh_q_rshr((int64_t)m, (unsigned)(-ex));
    }
    if (dq_max != NULL) {
        if (v > dq_max[i]) v = dq_max[i];
    } else if (v > INT32_MAX) {
        v = INT32_MAX;
        *ovf = 1;
    } else {
        /* in range */
    }
    return (int32_t)(neg ? -v : v);
}

static DH_NOINLINE dh_status dlsq_check(const dh_robot *r, int32_t lambda, const int32_t *dq_max)
{
    uint32_t i;
    if (r->n == 0u || r->n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    if ((r->flags & DH_ROBOT_HAS_Q) == 0u) return DH_ERR_UNAVAILABLE;
    for (i = 0; i < r->n; i++) {
        if (r->joint[i].type != DH_JOINT_REVOLUTE && r->joint[i].type != DH_JOINT_PRISMATIC) return DH_ERR_ARG;
        if (dq_max != NULL && dq_max[i] < 0) return DH_ERR_ARG;
    }
    return (lambda < 0) ? DH_ERR_ARG : DH_OK;
}

/* A' y = D^-1 S e 2^s into w->y, scaled down until the substitutions fit:
 * returns s, INT32_MIN for e = 0, INT32_MAX when no scale fits. */
static DH_NOINLINE int dlsq_solve_all(dlsq_ctx *c, const int32_t *e)
{
    int s, down = 0, tries;
    for (tries = 0; tries < 8; tries++) {
        int more;
        s = dlsq_rhs(c, e, down, c->y);
        if (s == INT32_MIN) return s;
        more = dlsq_solve(c, c->y);
        if (more == 0) return s;
        down += more;
    }
    return INT32_MAX;
}

/* The joint step from the solution (scale s), scaled to dq_max. */
static DH_NOINLINE dh_status dlsq_emit(dlsq_ctx *c, int s, const int32_t *dq_max, int32_t *dq)
{
    uint32_t i, q = UINT32_MAX, negs = 0u;
    int z = 0, ovf = 0;
    /* |dq_i| = dq[i] 2^ex[i] first (mantissas in dq), then scaled */
    for (i = 0; i < c->n; i++) {
        int ex = 0, neg = 0;
        dq[i] = (int32_t)dlsq_raw(c, c->y, s, i, &ex, &neg);
        c->ex[i] = (int16_t)((ex > 100) ? 100 : ((ex < -100) ? -100 : ex));
        if (neg) negs |= (uint32_t)1 << i;
    }
    if (dq_max != NULL) {
        q = dlsq_ratio(c->n, dq, c->ex, dq_max, &z);
        if (q != UINT32_MAX && q != 0u && (z >= 0 || (z > -32 && (q >> (unsigned)(-z)) != 0u)))
            q = UINT32_MAX;   /* rho >= 1 */
    }
    for (i = 0; i < c->n; i++)
        dq[i] = dlsq_out((uint32_t)dq[i], c->ex[i], (int)((negs >> i) & 1u), q, z, dq_max, i, &ovf);
    return ovf ? DH_ERR_OVERFLOW : DH_OK;
}

dh_status dh_kin_dls_q_(dh_dls_work_q *c, const int32_t *e, int32_t lambda, int32_t *dq)
{
    uint32_t i;
    int s;
    c->m = 6u;
    c->cols = 0;
    dlsq_format(c, lambda);
    (void)dlsq_equil(c, lambda, 0);
    for (i = 0; i < c->n; i++) dq[i] = 0;
    if (dlsq_chol(c, (lambda != 0) ? DLSQ_DMIN_FB : DLSQ_DSING_FB, lambda != 0))
        return (lambda != 0) ? DH_ERR_OVERFLOW : DH_ERR_SINGULAR;
    s = dlsq_solve_all(c, e);
    if (s == INT32_MIN) return DH_OK;
    if (s == INT32_MAX) return DH_ERR_OVERFLOW;
    return dlsq_emit(c, s, c->dq_max, dq);
}

uint32_t dh_kin_pris_q_(const dh_robot *r)
{
    uint32_t i, pris = 0u;
    for (i = 0; i < r->n; i++)
        if (r->joint[i].type == DH_JOINT_PRISMATIC) pris |= 1u << i;
    return pris;
}

dh_status dh_dls_step_q(const dh_robot *r, const int32_t *J, const int32_t e[6], int32_t lambda,
                        const int32_t *dq_max, dh_dls_work_q *work, int32_t *dq)
{
    dh_status st;
    DH_ASSERT(r != NULL);
    DH_ASSERT(J != NULL);
    DH_ASSERT(e != NULL);
    DH_ASSERT(dq != NULL);
    DH_ASSERT(work != NULL);
    st = dlsq_check(r, lambda, dq_max);
    if (st != DH_OK) return st;
    work->J = J;
    work->n = (uint8_t)r->n;
    work->dq_max = dq_max;
    work->pris = dh_kin_pris_q_(r);
    return dh_kin_dls_q_(work, e, lambda, dq);
}
