/*
 * dh_frame_q.c - fixed-point rigid frames (integer only).
 *
 * Rotation entries are Q2.30, positions have DH_QPOS_FRAC fraction bits.
 * Every output is one 64-bit sum of products rounded ONCE:
 *
 *     out = floor((sum + 2^29) / 2^30)      (round to nearest, ties up)
 *
 * then saturated to int32 (DH_ERR_OVERFLOW). The rotation x position
 * products do not depend on DH_QPOS_FRAC (Q2.30 x Qpos >> 30 = Qpos), and a
 * translation term p is added as the product p * 2^30 inside the same sum.
 *
 * Two paths give bit-identical results:
 *  - fast path: the sum is accumulated modulo 2^64 (one SMULL/SMLAL per
 *    term on Cortex-M3/M4/M7), the result read from the two halves, and a
 *    single deferred range test per call decides whether any output
 *    saturated OR the 64-bit sum wrapped (see the comment above
 *    dh_frame_mul_q for why one test covers both, for any int32 inputs);
 *  - exact path (only when that test fails): each 62-bit product p is split
 *    as 4*(p >> 2) + (p & 3) and the parts are summed separately, which
 *    cannot overflow for up to four terms, gives the same rounding, and
 *    saturates correctly.
 * DH_SMALL builds keep only the first (the direction of a saturation is
 * then taken from the high words, see dh_col) and a compact
 * dh_frame_rot_axis_q; same bits and status codes.
 *
 * Implementation-defined behaviour relied on (arithmetic >> of negative
 * values, modulo conversion to signed) is checked at compile time in
 * port/dh_port.h.
 */
#include "dhmath/dh_fixed.h"
#include "dhmath/dh_trig.h"
#include "../port/dh_port.h" /* relative: src/ compiles with only include/ on the path */

/* Keeps the rarely used exact path out of line: when GCC -O3 inlines it,
 * the register allocation of the fast path degrades (measured on
 * Cortex-M4: 383 instead of 220 instructions per dh_frame_mul_q). */
#if defined(__GNUC__) || defined(__clang__)
#define DH_NOINLINE __attribute__((noinline))
#else
#define DH_NOINLINE
#endif

/* Product for the code off the hot path (exact path, constructors): out
 * of line on ARMv6-M, where the inlined 16-bit kernel makes GCC spill and
 * the callers' frames exceed the 256-byte stack budget. */
#if DH_PORT_MUL64_IS_CALL
static DH_NOINLINE int64_t dh_mul64(int32_t a, int32_t b) { return dh_port_smull(a, b); }
#else
static inline int64_t dh_mul64(int32_t a, int32_t b) { return dh_port_smull(a, b); }
#endif

#define DH_ONE30 ((int32_t)0x40000000)      /* 1.0 in Q2.30 */
#define DH_HALF30 ((int64_t)0x20000000)     /* 0.5 LSB of a >>30 result */

#if !DH_SMALL
/* ---- helpers ------------------------------------------------------------ */

/*
 * floor(acc / 2^30) taken from the two 32-bit halves, valid when the high
 * word is in [-2^29, 2^29) (the result fits int32). Unchecked: the fast
 * paths below test the high words with dh_hi_chk(); the callers that use
 * it alone (dh_axis_entry, dh_frame_orthonormalize_chk_q) have results
 * bounded well inside [-2, 2) by construction (see there).
 */
static inline int32_t dh_lo30(int64_t acc)
{
    return (int32_t)(((uint32_t)((uint64_t)acc >> 32) << 2) | ((uint32_t)((uint64_t)acc & 0xFFFFFFFFu) >> 30));
}

/*
 * Exact path: round((c + sign * sum_{i<n} a[i]*b[i]) / 2^sh), ties up,
 * saturated to int32, with c = c30 * 2^30. n <= 4, |c30| <= 2^30 (so
 * |c| <= 2^60), 2 <= sh <= 31. |a[i]*b[i]| <= 2^62, so every partial sum
 * of the quarters stays below 2^58 + 2^60 * 4 < 2^63. (c is passed as an
 * int32: an int64 argument on the stack made GCC copy it through a VFP
 * register on Cortex-M4F, which the integer-only guard rejects.)
 */
static DH_NOINLINE int32_t dh_dot_exact(const int32_t *a, const int32_t *b, unsigned n, int negate,
                                        int32_t c30, unsigned sh, uint32_t *ovf)
{
    int64_t h = (int64_t)c30 * ((int64_t)1 << 28), r;
    uint32_t l = 0u;
    const unsigned s2 = sh - 2u;        /* the second step of the division */
    unsigned i;
    for (i = 0; i < n; i++) {
        int64_t p = dh_mul64(a[i], b[i]);
        if (negate) p = -p;                          /* |p| <= 2^62: safe */
        h += p >> 2;
        l += (uint32_t)((uint64_t)p & 3u);
    }
    /* value + 2^(sh-1) = 4h + (l + 2^(sh-1)); floor division by 2^sh in two steps */
    l = (l + ((uint32_t)1 << (sh - 1u))) >> 2;
    h += (int64_t)l;
    r = h >> s2;
    if (r > INT32_MAX) { *ovf = 1u; return INT32_MAX; }
    if (r < INT32_MIN) { *ovf = 1u; return INT32_MIN; }
    return (int32_t)r;
}

#endif /* !DH_SMALL */

/* ---- constructors -------------------------------------------------------- */

void dh_frame_identity_q(dh_frame_q *F)
{
    unsigned i, j;
    DH_ASSERT(F != NULL);
    for (i = 0; i < 3u; i++) {
        for (j = 0; j < 3u; j++) F->r[i][j] = (i == j) ? DH_ONE30 : 0;
        F->p[i] = 0;
    }
}

void dh_frame_trans_q(dh_frame_q *F, dh_qpos x, dh_qpos y, dh_qpos z)
{
    DH_ASSERT(F != NULL);
    dh_frame_identity_q(F);
    F->p[0] = x;
    F->p[1] = y;
    F->p[2] = z;
}

/* DH_SMALL: one out-of-line copy, the three public functions become tail calls */
#if DH_SMALL
#define DH_ROT_ELEM_ATTR static DH_NOINLINE
#else
#define DH_ROT_ELEM_ATTR static
#endif

/* Writes the elementary rotation about axis ax (0 x, 1 y, 2 z), given
 * a1 = (ax + 1) mod 3 and a2 = (ax + 2) mod 3. */
DH_ROT_ELEM_ATTR void dh_frame_rot_elem(dh_frame_q *F, unsigned a1, unsigned a2, dh_q16 deg)
{
    dh_q30 s, c;
    DH_ASSERT(F != NULL);
    dh_sincos_q(deg, &s, &c);
    dh_frame_identity_q(F);
    /* columns a1, a2 of Rot(ax): r[a1] = c e_a1 + s e_a2, r[a2] = -s e_a1 + c e_a2.
     * For ax = y (a1 = z, a2 = x) this gives the seed's Rot(y) (eq. 1.33). */
    F->r[a1][a1] = c;
    F->r[a1][a2] = s;
    F->r[a2][a1] = -s;                 /* |s| <= 2^30 (dh_sincos_q): exact */
    F->r[a2][a2] = c;
}

void dh_frame_rotx_q(dh_frame_q *F, dh_q16 deg) { dh_frame_rot_elem(F, 1u, 2u, deg); }
void dh_frame_roty_q(dh_frame_q *F, dh_q16 deg) { dh_frame_rot_elem(F, 2u, 0u, deg); }
void dh_frame_rotz_q(dh_frame_q *F, dh_q16 deg) { dh_frame_rot_elem(F, 0u, 1u, deg); }

#if DH_SMALL
/*
 * DH_SMALL: one general path per operation, same bits and status codes as
 * the default build for every input (checked bit for bit against it on
 * random and extreme inputs during development; the suites hold both
 * builds to the same references):
 *  - one kernel, dh_col(), serves the product, the inverse, the point and
 *    direction transforms, the orthonormalisation step and the
 *    orthonormality error. It is the default's fast path, and where that
 *    path's range test fails (the result saturates) it takes the direction
 *    of the saturation from a sum of halved high words instead of
 *    recomputing the sum by the exact path;
 *  - dh_frame_rot_axis_q() does the default's integer steps in one
 *    function with shared rounding helpers, and the Newton step of
 *    dh_frame_orthonormalize_chk_q() without that function's entry checks
 *    (they cannot fail there), so the constructor does not pull it in.
 */

/* modes of dh_col */
#define DH_COL_RP ((int32_t)-1)     /* R b + p */
#define DH_COL_R ((int32_t)0)       /* R b */
#define DH_COL_NEG_R ((int32_t)1)   /* -R b */

/*
 * o[i] = round((sgn (row i of R) . b + (p_i & pm) 2^30) / 2^30), i = 0..2,
 * ties up, saturated to int32; pm = -1 for DH_COL_RP, else 0,
 * sgn = -1 for DH_COL_NEG_R. Returns DH_ERR_OVERFLOW
 * if an output saturated, else DH_OK (0).
 * The default build's fast path and its range test (see the comment above
 * its dh_frame_mul_q): the sum S is taken modulo 2^64 and is the exact
 * result whenever its high word is in [-2^29, 2^29); otherwise the true
 * sum T is out of range (|T| >= 2^61) and only its sign is needed. That
 * comes from the high words h_k of the four terms: T = (sum h_k) 2^32 + L
 * with 0 <= L < 2^34, so |T| >= 2^61 gives sum h_k the sign of T, with
 * |sum h_k| >= 2^29 - 4; H = sum (h_k >> 1) (|h_k| <= 2^30: no overflow)
 * is within 4 of half of it, so it has the same sign. Same bits and status
 * as the default build's fast + exact paths, for ANY int32 inputs.
 */
static DH_NOINLINE unsigned dh_col(int32_t *o, const dh_frame_q *A, const int32_t *b, int32_t mode)
{
    unsigned st = 0u, i, k;
    for (i = 0; i < 3u; i++) {
        const int32_t pm = (mode < 0) ? -1 : 0;   /* all ones for DH_COL_RP */
        int64_t S0 = DH_HALF30 + (int64_t)(A->p[i] & pm) * DH_ONE30;   /* |.| <= 2^61 */
        uint64_t S = (uint64_t)S0;
        int32_t H = (int32_t)(S0 >> 32) >> 1;
        uint32_t hi;
        for (k = 0; k < 3u; k++) {
            int64_t q = dh_mul64(A->r[k][i], b[k]);
            if (mode > 0) q = -q;                 /* |q| <= 2^62: safe */
            S += (uint64_t)q;
            H += (int32_t)(q >> 32) >> 1;         /* |H| < 2^31 */
        }
        hi = (uint32_t)(S >> 32);
        if ((hi + 0x20000000u) >> 30) {
            st = (unsigned)DH_ERR_OVERFLOW;
            o[i] = H < 0 ? INT32_MIN : INT32_MAX;
        } else {
            o[i] = (int32_t)((hi << 2) | ((uint32_t)S >> 30));
        }
    }
    return st;
}

/* round(x / 2^sh), ties up, 1 <= sh <= 62: floor((x + 2^(sh-1)) / 2^sh)
 * = floor((floor(x / 2^(sh-1)) + 1) / 2), which cannot overflow */
static DH_NOINLINE int64_t dh_rsh(int64_t x, unsigned sh)
{
    return ((x >> (sh - 1u)) + (int64_t)1) >> 1;
}

/* round(a b / 2^sh) */
static DH_NOINLINE int64_t dh_mulr(int32_t a, int32_t b, unsigned sh)
{
    return dh_rsh(dh_mul64(a, b), sh);
}

/* (a + ea / 2^16) (b + eb / 2^16) in the scale of a b, rounded once, the
 * ea eb / 2^32 term dropped: a b + round((a eb + b ea) / 2^16) */
static DH_NOINLINE int64_t dh_pp(int32_t a, int32_t ea, int32_t b, int32_t eb)
{
    return dh_mul64(a, b) + dh_rsh(dh_mul64(a, eb) + dh_mul64(b, ea), 16u);
}

/* 2^29 + P (1 - c) with P = Ph 2^30 + Pl, 0 <= Pl < 2^30:
 * 2^29 + P - Ph c + round(-Pl c / 2^30); |c| <= 2^30, so -c is exact */
static DH_NOINLINE int64_t dh_vers(int64_t P, int32_t c)
{
    int32_t Ph = (int32_t)(P >> 30), Pl = (int32_t)(P - (int64_t)Ph * DH_ONE30);
    return DH_HALF30 + P - dh_mul64(Ph, c) + dh_mulr(Pl, -c, 30u);
}

/* split x = U 2^16 + E, E in [-2^15, 2^15) */
static void dh_split16(int64_t x, int32_t *U, int32_t *E)
{
    *U = (int32_t)dh_rsh(x, 16u);
    *E = (int32_t)(x - (int64_t)*U * 65536);
}

/* a . b of two columns (|entries| <= 1.25 where used: no overflow) */
static DH_NOINLINE int64_t dh_dot3(const int32_t *a, const int32_t *b)
{
    int64_t e = 0;
    unsigned k;
    for (k = 0; k < 3u; k++) e += dh_mul64(a[k], b[k]);
    return e;
}

/*
 * R <- R (3 I - R^T R) / 2 in place, bit for bit the step of the default build
 * without its entry checks: M = (3 I - R^T R) / 2 rounded once per entry
 * (entries <= 1.25: the sums cannot overflow), then R M rounded once per
 * entry (never saturates for the inputs that pass the checks, see the
 * default code). Column j of R M is R times column j of M (symmetric).
 */
static DH_NOINLINE void dh_ortho_step(dh_frame_q *F)
{
    dh_frame_q R;
    int32_t M[3][3];
    unsigned i, j;
    R = *F;
    for (i = 0; i < 3u; i++)
        for (j = 0; j < 3u; j++)
            M[i][j] = (int32_t)((((i == j) ? ((int64_t)3 << 60) : 0) + ((int64_t)1 << 30) -
                                 dh_dot3(R.r[i], R.r[j])) >> 31);
    for (j = 0; j < 3u; j++) (void)dh_col(F->r[j], &R, M[j], DH_COL_R);
}

/*
 * Same operations in the same order as the default build's dh_axis_scale,
 * dh_inv_sqrt_q30, dh_unit_refine and dh_axis_entry (see their comments
 * below), so the same bits, in one function: unit axis
 * (U + E / 2^16) / 2^30, then eq. 1.70 summed in Q60 and rounded once per
 * entry, then the Newton step of dh_frame_orthonormalize_chk_q(), whose
 * checks cannot fail here (entries within 1 + 2 LSB, error far below 1/8).
 * U[3] = 1, E[3] = 0 let the diagonal term c = c * 1 share the code of the
 * s k_m terms.
 */
static DH_NOINLINE int dh_axis_build(dh_frame_q *F, int32_t kx, int32_t ky, int32_t kz, dh_q16 deg)
{
    int32_t k[3];
    int32_t U[4], E[4], X, Y, s, c, D;
    uint32_t m = 0u;
    uint64_t n2 = 0u;
    int64_t n = 0;
    unsigned i, j, h = 14u;
    int sh;
    k[0] = kx; k[1] = ky; k[2] = kz;
    /* the OR of the magnitudes has the leading bit of the largest one */
    for (i = 0; i < 3u; i++) m |= k[i] < 0 ? 0u - (uint32_t)k[i] : (uint32_t)k[i];
    if (m == 0u) return 0;
    /* 1. leading bit to bit 30 (sh = -1 only for an INT32_MIN component:
     *    then the others are halved, truncating toward zero) */
    sh = (int)dh_port_clz(m) - 1;
    for (i = 0; i < 3u; i++) {
        U[i] = sh >= 0 ? (int32_t)((uint32_t)k[i] << (unsigned)sh) : k[i] / 2;   /* w */
        n2 += (uint64_t)dh_mul64(U[i], U[i]);
    }
    /* 2. n2 in [2^60, 3 * 2^62): X = n2 / 2^(30, 32 or 34) in [2^29, 2^31);
     *    the shift of step 4 is half of that minus one */
    n2 >>= 30;
    while (n2 >= ((uint64_t)1 << 31)) { n2 >>= 2; h++; }
    X = (int32_t)n2;
    /* 3. Y = 1/sqrt(x), piecewise linear seed and four Newton steps */
    Y = X < DH_ONE30 ? (int32_t)0x70000000 - (X - (X >> 2)) : (int32_t)0x50000000 - (X >> 2);
    for (i = 0; i < 4u; i++) {
        int32_t t = (int32_t)dh_mulr(X, Y, 30u);
        t = (int32_t)dh_mulr(t, Y, 30u);
        /* Y (3 - t) / 2 rounded once = Y + round(Y (1 - t) / 2): the
         * default's round((2 Y 1.5 - Y t) / 2^31) without its Y 2^31 term */
        Y += (int32_t)dh_mulr(Y, DH_ONE30 - t, 31u);
    }
    /* 4. u = w Y in Q46, split; |u|^2 in Q60; one Newton step on the vector */
    for (i = 0; i < 3u; i++) {
        dh_split16(dh_mulr(U[i], Y, h), &U[i], &E[i]);
        n += dh_pp(U[i], E[i], U[i], E[i]);
    }
    D = (int32_t)dh_rsh(((int64_t)1 << 60) - n, 8u);
    for (i = 0; i < 3u; i++)
        dh_split16((int64_t)U[i] * 65536 + E[i] + dh_mulr(U[i], D, 37u), &U[i], &E[i]);
    U[3] = DH_ONE30;
    E[3] = 0;
    dh_sincos_q(deg, &s, &c);
    /* eq. 1.70: k_i k_j vers + (i == j ? c : +-s k_m), in Q60, one rounding;
     * k_i k_j = P = Ph 2^30 + Pl, P vers = P - Ph c + round(-Pl c / 2^30) */
    for (j = 0; j < 3u; j++) {
        for (i = 0; i < 3u; i++) {
            int64_t T;
            unsigned mm = (i == j) ? 3u : 3u - i - j;
            T = dh_pp(i == j ? c : s, 0, U[mm], E[mm]);
            /* s [k]x: (1,0) +kz, (0,1) -kz, (0,2) +ky, (2,0) -ky, (2,1) +kx, (1,2) -kx */
            if ((0x8Cu >> (3u * j + i)) & 1u) T = -T;     /* bits 3 j + i of (0,1) (2,0) (1,2) */
            /* |c| <= 2^30 (dh_sincos_q): -c is exact; the entry is within
             * 1 + 1 LSB of [-1, 1], read without a range check */
            F->r[j][i] = (int32_t)((dh_vers(dh_pp(U[i], E[i], U[j], E[j]), c) + T) >> 30);
        }
        F->p[j] = 0;
    }
    return 1;
}

/* separate steps, so that the stack depth is the larger of the two */
dh_status dh_frame_rot_axis_q(dh_frame_q *F, dh_q30 kx, dh_q30 ky, dh_q30 kz, dh_q16 deg)
{
    DH_ASSERT(F != NULL);
    if (!dh_axis_build(F, kx, ky, kz, deg)) return DH_ERR_ZERO_AXIS;
    dh_ortho_step(F);
    return DH_OK;
}

/* Computed into a local, so out may alias A and/or B: column j of the
 * result is A times column j of [R_B p_B; 0 0 0 1]. */
dh_status dh_frame_mul_q(dh_frame_q *out, const dh_frame_q *A, const dh_frame_q *B)
{
    dh_frame_q t;
    unsigned st = 0u, j;
    DH_ASSERT(out != NULL && A != NULL && B != NULL);
    for (j = 0; j < 3u; j++) st |= dh_col(&t.r[j][0], A, B->r[j], DH_COL_R);
    st |= dh_col(t.p, A, B->p, DH_COL_RP);
    *out = t;
    return (dh_status)st;
}

/* R' = R^T, p' = -R^T p (rows of R^T are the columns of R) */
dh_status dh_frame_inv_q(dh_frame_q *out, const dh_frame_q *F)
{
    dh_frame_q t;
    unsigned st, i, j;
    DH_ASSERT(out != NULL && F != NULL);
    for (i = 0; i < 3u; i++)
        for (j = 0; j < 3u; j++) t.r[i][j] = F->r[j][i];
    st = dh_col(t.p, &t, F->p, DH_COL_NEG_R);
    *out = t;
    return (dh_status)st;
}

/* v = R u (+ p for DH_COL_RP) */
static dh_status dh_frame_apply(const dh_frame_q *F, const dh_vec3_q *u, dh_vec3_q *v, int32_t pm)
{
    int32_t in[3], o[3];
    unsigned st;
    DH_ASSERT(F != NULL && u != NULL && v != NULL);
    in[0] = u->x; in[1] = u->y; in[2] = u->z;
    st = dh_col(o, F, in, pm);
    v->x = o[0]; v->y = o[1]; v->z = o[2];
    return (dh_status)st;
}

dh_status dh_frame_apply_point_q(const dh_frame_q *F, const dh_vec3_q *u, dh_vec3_q *v)
{
    return dh_frame_apply(F, u, v, DH_COL_RP);
}

dh_status dh_frame_apply_dir_q(const dh_frame_q *F, const dh_vec3_q *u, dh_vec3_q *v)
{
    return dh_frame_apply(F, u, v, DH_COL_R);
}

/* (R^T R)_ij - delta_ij = col_i . col_j - delta_ij, in Q2.30, one rounding,
 * saturated: column j of R^T R - I is R^T col_j - e_j (p of T = -e_j) */
int32_t dh_frame_ortho_error_q(const dh_frame_q *F)
{
    dh_frame_q T;
    int32_t e[3];
    uint32_t worst = 0u;
    unsigned i, j;
    DH_ASSERT(F != NULL);
    for (i = 0; i < 3u; i++)
        for (j = 0; j < 3u; j++) T.r[i][j] = F->r[j][i];
    for (j = 0; j < 3u; j++) {
        for (i = 0; i < 3u; i++) T.p[i] = (i == j) ? -DH_ONE30 : 0;
        (void)dh_col(e, &T, F->r[j], DH_COL_RP);
        for (i = 0; i < 3u; i++) {
            uint32_t m = e[i] < 0 ? 0u - (uint32_t)e[i] : (uint32_t)e[i];
            if (m > worst) worst = m;
        }
    }
    return worst > (uint32_t)INT32_MAX ? INT32_MAX : (int32_t)worst;
}

/* the checks of dh_frame_orthonormalize_chk_q(), as in the default build:
 * entries <= 1.25, then (R^T R - I) 2^60 exactly (no overflow) <= 1/8 */
static DH_NOINLINE dh_status dh_ortho_chk(const dh_frame_q *F)
{
    unsigned i, j;
    for (i = 0; i < 3u; i++)
        for (j = 0; j < 3u; j++)
            if (((uint32_t)F->r[i][j] + 0x50000000u) > 0xA0000000u) return DH_ERR_NOT_RIGID;
    for (i = 0; i < 3u; i++)
        for (j = i; j < 3u; j++) {
            int64_t e = dh_dot3(F->r[i], F->r[j]) - ((i == j) ? ((int64_t)1 << 60) : 0);
            if (e > ((int64_t)1 << 57) || e < -((int64_t)1 << 57)) return DH_ERR_NOT_RIGID;
        }
    return DH_OK;
}

/* checks and step are separate calls, so that the stack depth is the
 * larger of the two */
dh_status dh_frame_orthonormalize_chk_q(dh_frame_q *F)
{
    dh_status st;
    DH_ASSERT(F != NULL);
    st = dh_ortho_chk(F);
    if (st == DH_OK) dh_ortho_step(F);
    return st;
}

#else /* !DH_SMALL: the fast and exact paths */

/* |x| as uint32 (exact also for INT32_MIN). */
static uint32_t dh_abs_u32(int32_t x)
{
    return x < 0 ? 0u - (uint32_t)x : (uint32_t)x;
}

/* Scale magnitude m by 2^sh (sh > 0 left, sh < 0 right, truncating) and reapply the sign of x. */
static int32_t dh_scale_signed(int32_t x, int sh)
{
    uint32_t m = dh_abs_u32(x);
    m = sh >= 0 ? (m << (unsigned)sh) : (m >> (unsigned)(-sh));
    /* m < 2^31 here, so the conversion and the negation are exact */
    return x < 0 ? -(int32_t)m : (int32_t)m;
}

/* round(x / 2^sh) for int64 x, 1 <= sh <= 62, |x| < 2^62 (ties up). */
static int64_t dh_rshr64(int64_t x, unsigned sh)
{
    const unsigned s1 = sh - 1u;
    const int64_t half = (int64_t)((uint64_t)1 << s1);
    return (x + half) >> sh;
}

/*
 * Unit vector of (kx, ky, kz), integer only, to about 2^-44:
 * u_i = (U[i] + E[i] / 2^16) / 2^30 with U Q2.30 and E in [-2^15, 2^15].
 *  1. scale by a power of two so the largest |component| is in
 *     [2^30, 2^31) (exact, except when a component is INT32_MIN: then the
 *     others lose their lowest bit, relative 2^-31);
 *  2. n2 = |w|^2 (exact, 64 bit unsigned, in [2^60, 3 * 2^62)), normalised
 *     to X in [2^29, 2^31) (Q2.30, x in [0.5, 2)) by an even shift s2 of 30..34;
 *  3. Y = 1/sqrt(x) by four Newton steps Y <- Y (3 - x Y^2) / 2 from a
 *     piecewise linear seed (relative error <= 6 %, 1.5 e^2 per step),
 *     good to about 2^-29;
 *  4. u = w Y / 2^(15 + s2/2) in Q46, then one Newton step on the vector
 *     u <- u + u (1 - |u|^2) / 2 with |u|^2 evaluated in Q60 from the
 *     split U, E (the error left is far below 2^-40).
 */
/*
 * Y = 1/sqrt(x) in Q2.30 for X = x 2^30 in [2^29, 2^31) (step 3 above).
 * From a seed below the root, Newton's iterates stay below it, so
 * x Y <= sqrt(x) < 1.5 and x Y^2 <= 1: no intermediate can overflow, and
 * plain rounded shifts are used (no saturation needed).
 */
static DH_NOINLINE int32_t dh_inv_sqrt_q30(int32_t X)
{
    int32_t Y = X < DH_ONE30 ? (int32_t)0x70000000 - (X - (X >> 2))   /* 1.75 - 0.75 x */
                             : (int32_t)0x50000000 - (X >> 2);         /* 1.25 - 0.25 x */
    int it;
    for (it = 0; it < 4; it++) {
        int32_t t = (int32_t)dh_rshr64(dh_mul64(X, Y), 30u);    /* x Y */
        t = (int32_t)dh_rshr64(dh_mul64(t, Y), 30u);            /* x Y^2 */
        /* Y (3 - t) / 2 = (2 Y 1.5 - Y t) / 2, one rounding */
        Y = (int32_t)dh_rshr64(2 * dh_mul64(Y, (int32_t)0x60000000) - dh_mul64(Y, t), 31u);
    }
    return Y;
}

/* split x = U 2^16 + E, E in [-2^15, 2^15) */
static void dh_split16(int64_t x, int32_t *U, int32_t *E)
{
    *U = (int32_t)dh_rshr64(x, 16u);
    *E = (int32_t)(x - (int64_t)*U * 65536);
}

/* step 4 above: u = w Y / 2^(15 + s2/2) in Q46, one Newton step, split.
 * w may alias U (each w[i] is read before U[i] is written). */
static DH_NOINLINE void dh_unit_refine(const int32_t *w, int32_t Y, int s2, int32_t *U, int32_t *E)
{
    int64_t n = 0;
    int32_t D;
    unsigned i;
    for (i = 0; i < 3u; i++) dh_split16(dh_rshr64(dh_mul64(w[i], Y), (unsigned)(s2 >> 1) - 1u), &U[i], &E[i]);
    /* |u|^2 in Q60: U^2 + 2 U E / 2^16 (E^2 / 2^32 < 1 is dropped) */
    for (i = 0; i < 3u; i++)
        n += dh_mul64(U[i], U[i]) + dh_rshr64(2 * dh_mul64(U[i], E[i]), 16u);
    /* D = (1 - |u|^2) in Q52 (|1 - |u|^2| < 2^-24, far inside int32) */
    D = (int32_t)dh_rshr64(((int64_t)1 << 60) - n, 8u);
    /* u += u d / 2: in Q46, U * D / 2^(30 + 52 - 46 + 1) */
    for (i = 0; i < 3u; i++)
        dh_split16((int64_t)U[i] * 65536 + E[i] + dh_rshr64(dh_mul64(U[i], D), 37u), &U[i], &E[i]);
}

/*
 * Steps 1-2 above: w = k scaled by a power of two, *s2, and returns X
 * (0 for the zero vector). The steps are separate functions called one
 * after the other from dh_frame_rot_axis_q() so the stack depth is the
 * largest step, not their sum.
 */
static DH_NOINLINE int32_t dh_axis_scale(int32_t kx, int32_t ky, int32_t kz, int32_t *w, int *s2)
{
    uint32_t m = dh_abs_u32(kx);
    uint64_t n2;
    int sh;
    unsigned i;
    if (dh_abs_u32(ky) > m) m = dh_abs_u32(ky);
    if (dh_abs_u32(kz) > m) m = dh_abs_u32(kz);
    if (m == 0u) return 0;
    sh = (int)dh_port_clz(m) - 1;                /* leading bit to bit 30 */
    w[0] = dh_scale_signed(kx, sh);
    w[1] = dh_scale_signed(ky, sh);
    w[2] = dh_scale_signed(kz, sh);
    n2 = 0u;
    for (i = 0; i < 3u; i++) n2 += (uint64_t)dh_mul64(w[i], w[i]);
    /* n2 in [2^60, 3 * 2^62): pick an even shift giving X in [2^29, 2^31) */
    *s2 = (n2 >= ((uint64_t)1 << 63)) ? 34 : ((n2 >= ((uint64_t)1 << 61)) ? 32 : 30);
    return (int32_t)(n2 >> *s2);
}

/*
 * Entry (row i, column j) of eq. 1.70, R = k k^T vers + c I + s [k]x with
 * vers = 1 - c, summed in Q60 and rounded once:
 *   k_i k_j (Q60)     P = U_i U_j + (U_i E_j + U_j E_i) / 2^16
 *   k_i k_j vers      P = Ph 2^30 + Pl:  Ph 2^30 - Ph c + round(Pl (2^30 - c) / 2^30)
 *   s k_m             s U_m + round(s E_m / 2^16)
 * Every term is below 2^61 in magnitude: no overflow; the entry is within
 * 1 + 1 LSB in magnitude, so it is read without a range check.
 */
static DH_NOINLINE int32_t dh_axis_entry(const int32_t *U, const int32_t *E, unsigned i, unsigned j,
                                         int32_t s, int32_t c)
{
    int32_t ns = -c;                    /* |c| <= 2^30 (dh_sincos_q): exact */
    int64_t P = dh_mul64(U[i], U[j]) +
                dh_rshr64(dh_mul64(U[i], E[j]) + dh_mul64(U[j], E[i]), 16u);
    int32_t Ph = (int32_t)(P >> 30), Pl = (int32_t)(P - (int64_t)Ph * DH_ONE30);
    int64_t acc = dh_port_smlal(DH_HALF30, Ph, DH_ONE30);
    acc = dh_port_smlal(acc, Ph, ns);
    acc += Pl + dh_rshr64(dh_mul64(Pl, ns), 30u);
    if (i == j) {
        acc = dh_port_smlal(acc, c, DH_ONE30);
    } else {
        /* s [k]x: (i,j) = (1,0) +kz, (0,1) -kz, (0,2) +ky, (2,0) -ky, (2,1) +kx, (1,2) -kx */
        unsigned m = 3u - i - j;
        int positive = (i == j + 1u) || (i == 0u && j == 2u);
        int64_t t = dh_mul64(s, U[m]) + dh_rshr64(dh_mul64(s, E[m]), 16u);
        acc += positive ? t : -t;
    }
    return dh_lo30(acc);
}

/* F = the rounded eq. 1.70 matrix (position 0); 0 for a zero axis (F untouched) */
static DH_NOINLINE int dh_axis_build(dh_frame_q *F, int32_t kx, int32_t ky, int32_t kz, dh_q16 deg)
{
    int32_t U[3], E[3], s, c, X;
    int s2 = 0;
    unsigned i, j;
    X = dh_axis_scale(kx, ky, kz, U, &s2);     /* U holds w here */
    if (X == 0) return 0;
    dh_unit_refine(U, dh_inv_sqrt_q30(X), s2, U, E);
    dh_sincos_q(deg, &s, &c);
    for (j = 0; j < 3u; j++) {          /* column */
        for (i = 0; i < 3u; i++) F->r[j][i] = dh_axis_entry(U, E, i, j, s, c);
        F->p[j] = 0;
    }
    return 1;
}

dh_status dh_frame_rot_axis_q(dh_frame_q *F, dh_q30 kx, dh_q30 ky, dh_q30 kz, dh_q16 deg)
{
    DH_ASSERT(F != NULL);
    if (!dh_axis_build(F, kx, ky, kz, deg)) return DH_ERR_ZERO_AXIS;
    /* Rounding the nine entries leaves |R^T R - I| at a few LSB; one Newton
     * step brings it to the rounding level so that T * T^-1 stays within a
     * few LSB of I. Cannot fail here: entries are within 1 + 2 LSB and the
     * error is far below the 1/8 limit. */
    return dh_frame_orthonormalize_chk_q(F);
}

/* ---- composition ---------------------------------------------------------- */

/*
 * Fast-path results are read with dh_lo30() without the saturation test;
 * dh_hi_chk() gives a word whose bits 30 and 31 are clear exactly when the
 * high word is in [-2^29, 2^29), so the checks of many outputs can be
 * OR-ed and tested once.
 */
static inline uint32_t dh_hi_chk(int64_t acc)
{
    return (uint32_t)((uint64_t)acc >> 32) + 0x20000000u;
}

/*
 * Fast path of the products: each output is accumulated modulo 2^64 (no
 * UB, port/dh_port.h) as 2^29 + sum of at most three Q2.30 x int32
 * products (+ a translation p * 2^30), the result is read from the two
 * 32-bit halves, and the range test is deferred (dh_hi_chk OR-ed over all
 * outputs, tested once). That test is complete for ANY int32 inputs:
 *  - without wraparound it is exactly "the result fits int32";
 *  - the true sum is bounded by 3 * 2^62 + 2^61 - 2^30 + 2^29 in magnitude
 *    (three products of at most 2^62, INT32_MIN^2, one translation term),
 *    so a wrapped sum lies at least 2^61 + 2^29 away from 0 and its high
 *    word is outside [-2^29, 2^29) too.
 * If the test fails, all outputs are recomputed by the exact path, which
 * saturates correctly. No input guard is needed.
 */

/* one fast-path output: row i of A times 3 contiguous values of B */
#define DH_DOT3(dst, i, bcol) do { \
        int64_t acc_ = dh_port_smlal(DH_HALF30, A->r[0][i], (bcol)[0]); \
        acc_ = dh_port_smlal(acc_, A->r[1][i], (bcol)[1]); \
        acc_ = dh_port_smlal(acc_, A->r[2][i], (bcol)[2]); \
        (dst) = dh_lo30(acc_); \
        chk |= dh_hi_chk(acc_); \
    } while (0)

/* 2^29 + p 2^30 (start of a position sum): one SMLAL where the core has
 * it, else two shifts instead of a 16-bit-partials product */
#if DH_PORT_MUL64_IS_CALL
#define DH_HALF_PLUS_P(ap) \
    ((int64_t)((uint64_t)DH_HALF30 + DH_PORT_W64((ap) >> 2, (uint32_t)(ap) << 30)))
#else
#define DH_HALF_PLUS_P(ap) dh_port_smlal(DH_HALF30, (ap), DH_ONE30)
#endif

/* output row i (rotation row i and p_i) by the fast path */
#define DH_MUL_ROW(i) do { \
        DH_DOT3(tp->r[0][i], i, B->r[0]); \
        DH_DOT3(tp->r[1][i], i, B->r[1]); \
        DH_DOT3(tp->r[2][i], i, B->r[2]); \
        { \
            int64_t acc_ = DH_HALF_PLUS_P(A->p[i]); \
            acc_ = dh_port_smlal(acc_, A->r[0][i], B->p[0]); \
            acc_ = dh_port_smlal(acc_, A->r[1][i], B->p[1]); \
            acc_ = dh_port_smlal(acc_, A->r[2][i], B->p[2]); \
            tp->p[i] = dh_lo30(acc_); \
            chk |= dh_hi_chk(acc_); \
        } \
    } while (0)

/* fast path of A * B into *tp (a local of the caller, never A or B);
 * returns the deferred check word */
static DH_NOINLINE uint32_t dh_mul_fast(dh_frame_q *tp, const dh_frame_q *A, const dh_frame_q *B)
{
    uint32_t chk = 0u;
    /* rows unrolled by hand: with a loop, compilers hoist the 12 values of
     * B out of it and spill them to the stack, which costs more than
     * loading them where needed */
    DH_MUL_ROW(0);
    DH_MUL_ROW(1);
    DH_MUL_ROW(2);
    return chk;
}

/* exact path of A * B into t (only after the fast path's test failed) */
static DH_NOINLINE uint32_t dh_mul_exact(dh_frame_q *t, const dh_frame_q *A, const dh_frame_q *B)
{
    int32_t a[4], b[4];
    uint32_t ovf = 0u;
    unsigned i, j;
    for (i = 0; i < 3u; i++) {
        a[0] = A->r[0][i]; a[1] = A->r[1][i]; a[2] = A->r[2][i]; a[3] = A->p[i];
        for (j = 0; j < 4u; j++) {
            const int32_t *bc = (j < 3u) ? B->r[j] : B->p;
            b[0] = bc[0]; b[1] = bc[1]; b[2] = bc[2]; b[3] = DH_ONE30;
            /* rotation entries: 3 terms; position: 4 (the p_i 2^30 term) */
            if (j < 3u) t->r[j][i] = dh_dot_exact(a, b, 3u, 0, 0, 30u, &ovf);
            else t->p[i] = dh_dot_exact(a, b, 4u, 0, 0, 30u, &ovf);
        }
    }
    return ovf;
}

/* Computed into a local, so out may alias A and/or B. The two paths are
 * separate functions so the stack depth is the larger of the two, not
 * their sum. */
dh_status dh_frame_mul_q(dh_frame_q *out, const dh_frame_q *A, const dh_frame_q *B)
{
    dh_frame_q t;
    uint32_t ovf = 0u;
    DH_ASSERT(out != NULL && A != NULL && B != NULL);
    if (dh_mul_fast(&t, A, B) >> 30) ovf = dh_mul_exact(&t, A, B);
    *out = t;
    return ovf ? DH_ERR_OVERFLOW : DH_OK;
}

/* p' = -R^T p by the fast path; returns the deferred check word.
 * Row i of R^T is column i of R. acc = 2^29 - sum mod 2^64 (nothing is
 * negated, so INT32_MIN entries are fine); the bound above is symmetric. */
static DH_NOINLINE uint32_t dh_inv_p_fast(const dh_frame_q *F, int32_t *p)
{
    uint32_t chk = 0u;
    unsigned i;
    for (i = 0; i < 3u; i++) {
        int64_t s = dh_port_smull(F->r[i][0], F->p[0]);
        int64_t acc;
        s = dh_port_smlal(s, F->r[i][1], F->p[1]);
        s = dh_port_smlal(s, F->r[i][2], F->p[2]);
        acc = (int64_t)((uint64_t)DH_HALF30 - (uint64_t)s);
        p[i] = dh_lo30(acc);
        chk |= dh_hi_chk(acc);
    }
    return chk;
}

static DH_NOINLINE uint32_t dh_inv_p_exact(const dh_frame_q *F, int32_t *p)
{
    uint32_t ovf = 0u;
    unsigned i;
    for (i = 0; i < 3u; i++) p[i] = dh_dot_exact(F->r[i], F->p, 3u, 1, 0, 30u, &ovf);
    return ovf;
}

dh_status dh_frame_inv_q(dh_frame_q *out, const dh_frame_q *F)
{
    int32_t p[3];
    uint32_t ovf = 0u;
    unsigned i, j;
    DH_ASSERT(out != NULL && F != NULL);
    if (dh_inv_p_fast(F, p) >> 30) ovf = dh_inv_p_exact(F, p);
    /* transpose in place (also correct when out == F), then the position */
    for (i = 0; i < 3u; i++) {
        out->r[i][i] = F->r[i][i];
        for (j = i + 1u; j < 3u; j++) {
            int32_t x = F->r[i][j], y = F->r[j][i];
            out->r[i][j] = y;
            out->r[j][i] = x;
        }
        out->p[i] = p[i];
    }
    return ovf ? DH_ERR_OVERFLOW : DH_OK;
}

/* o = R u (+ p masked by with_p) by the fast path; returns the check word */
static DH_NOINLINE uint32_t dh_apply_fast(const dh_frame_q *F, const int32_t *in, int32_t with_p, int32_t *o)
{
    uint32_t chk = 0u;
    unsigned i;
    for (i = 0; i < 3u; i++) {
        int64_t acc = DH_HALF_PLUS_P(F->p[i] & with_p);
        acc = dh_port_smlal(acc, F->r[0][i], in[0]);
        acc = dh_port_smlal(acc, F->r[1][i], in[1]);
        acc = dh_port_smlal(acc, F->r[2][i], in[2]);
        o[i] = dh_lo30(acc);
        chk |= dh_hi_chk(acc);
    }
    return chk;
}

static DH_NOINLINE uint32_t dh_apply_exact(const dh_frame_q *F, const int32_t *in, int32_t with_p, int32_t *o)
{
    uint32_t ovf = 0u;
    unsigned i;
    for (i = 0; i < 3u; i++) {
        int32_t a[4], b[4];
        a[0] = F->r[0][i]; a[1] = F->r[1][i]; a[2] = F->r[2][i]; a[3] = F->p[i] & with_p;
        b[0] = in[0]; b[1] = in[1]; b[2] = in[2]; b[3] = DH_ONE30;
        o[i] = dh_dot_exact(a, b, 4u, 0, 0, 30u, &ovf);
    }
    return ovf;
}

/* v = R u (+ p when with_p == -1): shared by the point and direction transforms. */
static dh_status dh_frame_apply(const dh_frame_q *F, const dh_vec3_q *u, dh_vec3_q *v, int32_t with_p)
{
    int32_t in[3], o[3];
    uint32_t ovf = 0u;
    DH_ASSERT(F != NULL && u != NULL && v != NULL);
    in[0] = u->x; in[1] = u->y; in[2] = u->z;
    if (dh_apply_fast(F, in, with_p, o) >> 30) ovf = dh_apply_exact(F, in, with_p, o);
    v->x = o[0]; v->y = o[1]; v->z = o[2];
    return ovf ? DH_ERR_OVERFLOW : DH_OK;
}

dh_status dh_frame_apply_point_q(const dh_frame_q *F, const dh_vec3_q *u, dh_vec3_q *v)
{
    return dh_frame_apply(F, u, v, -1);      /* mask: keep p */
}

dh_status dh_frame_apply_dir_q(const dh_frame_q *F, const dh_vec3_q *u, dh_vec3_q *v)
{
    return dh_frame_apply(F, u, v, 0);       /* mask: drop p */
}

/* ---- orthonormality ------------------------------------------------------- */

int32_t dh_frame_ortho_error_q(const dh_frame_q *F)
{
    uint32_t ovf = 0u, worst = 0u;
    unsigned i, j;
    DH_ASSERT(F != NULL);
    for (i = 0; i < 3u; i++)
        for (j = i; j < 3u; j++) {
            /* (R^T R)_ij - delta_ij = col_i . col_j - delta_ij, in Q2.30 */
            int32_t e = dh_dot_exact(F->r[i], F->r[j], 3u, 0, i == j ? -DH_ONE30 : 0, 30u, &ovf);
            uint32_t m = dh_abs_u32(e);
            if (m > worst) worst = m;
        }
    return worst > (uint32_t)INT32_MAX ? INT32_MAX : (int32_t)worst;
}

/* acc + sum_k a[k sa] b[k sb], k = 0..2, modulo 2^64 (out of line: inlined,
 * the 16-bit kernel of ARMv6-M makes the caller's frame grow past 256 bytes) */
static DH_NOINLINE int64_t dh_dot3s(int64_t acc, const int32_t *a, unsigned sa, const int32_t *b, unsigned sb)
{
    acc = dh_port_smlal(acc, a[0], b[0]);
    acc = dh_port_smlal(acc, a[sa], b[sb]);
    return dh_port_smlal(acc, a[2u * sa], b[2u * sb]);
}

dh_status dh_frame_orthonormalize_chk_q(dh_frame_q *F)
{
    int32_t M[3][3], row[3];
    unsigned i, j;
    DH_ASSERT(F != NULL);
    /* |entries| <= 1.25 keeps every sum below far from 2^63 and lets the
     * 1/8 test below decide convergence. */
    for (i = 0; i < 3u; i++)
        for (j = 0; j < 3u; j++)
            if (((uint32_t)F->r[i][j] + 0x50000000u) > 0xA0000000u) return DH_ERR_NOT_RIGID;
    /* M = (3 I - R^T R) / 2, symmetric; one rounding per entry.
     * (R^T R)_ij = column i . column j. */
    for (i = 0; i < 3u; i++)
        for (j = i; j < 3u; j++) {
            int64_t e = dh_dot3s(0, F->r[i], 1u, F->r[j], 1u);       /* E 2^60, |E| < 4.7 */
            int64_t acc = ((i == j) ? ((int64_t)3 << 60) : 0) + ((int64_t)1 << 30) - e;
            M[i][j] = (int32_t)(acc >> 31);
            M[j][i] = M[i][j];
            e -= (i == j) ? ((int64_t)1 << 60) : 0;                   /* (E - I) 2^60 */
            if (e > ((int64_t)1 << 57) || e < -((int64_t)1 << 57)) return DH_ERR_NOT_RIGID; /* > 1/8 */
        }
    /* R <- R M, row by row in place: row i of the result is row i of R times M.
     * No entry can leave [-2, 2): with R^T R = I + E, |E_ij| <= 1/8 (checked
     * above), ||R||_2 <= sqrt(1 + ||E||_F) <= sqrt(1 + 3/8) < 1.18 and
     * M = I - E/2 (rounded) has ||M||_2 <= 1 + 3/16 + 2^-28, so every entry
     * of R M is below 1.4 in magnitude: read unchecked, no overflow status. */
    for (i = 0; i < 3u; i++) {
        row[0] = F->r[0][i]; row[1] = F->r[1][i]; row[2] = F->r[2][i];
        for (j = 0; j < 3u; j++) F->r[j][i] = dh_lo30(dh_dot3s(DH_HALF30, row, 1u, M[j], 1u));
    }
    return DH_OK;
}

#endif /* DH_SMALL */

void dh_frame_orthonormalize_q(dh_frame_q *F)
{
    (void)dh_frame_orthonormalize_chk_q(F);
}
