/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_frame_q.c - fixed-point rigid frames (integer only).
 *
 * Rotation entries are Q2.30, positions have DH_QPOS_FRAC fraction bits.
 * Every output is one 64-bit sum of products rounded once,
 * out = floor((sum + 2^29) / 2^30) (round to nearest, ties up), then
 * saturated to int32 (DH_ERR_OVERFLOW). Rotation x position products do not
 * depend on DH_QPOS_FRAC (Q2.30 x Qpos >> 30 = Qpos); a translation p enters
 * the same sum as the product p 2^30.
 *
 * General path: frameq_col() takes each sum modulo 2^64 and reads the result
 * from its two words; where that does not fit, the sign of the saturation
 * comes from a sum of halved high words. The fast paths (DH_FAST_PATHS) of
 * the product, the inverse and the point/direction transforms compute the
 * same sums unrolled with one deferred range test per call, and hand the
 * call to the general path when that test fails.
 *
 * Implementation-defined behaviour relied on (arithmetic >> of negative
 * values, modulo conversion to signed) is checked at compile time in
 * port/dh_port.h.
 */
#include "dhmath/frame.h"
#include "dhmath/trig.h"
#include "../internal/dh_qmath.h"

/* ---- constructors -------------------------------------------------------- */

void dh_frame_identity_q(dh_frame_q *F)
{
    unsigned i, j;
    DH_ASSERT(F != NULL);
    for (i = 0; i < 3u; i++) {
        for (j = 0; j < 3u; j++) F->r[i][j] = (i == j) ? DH_Q_ONE30 : 0;
        F->p[i] = 0;
    }
}

void dh_frame_trans_q(dh_qpos x, dh_qpos y, dh_qpos z, dh_frame_q *F)
{
    DH_ASSERT(F != NULL);
    dh_frame_identity_q(F);
    F->p[0] = x;
    F->p[1] = y;
    F->p[2] = z;
}

/* Elementary rotation about axis ax (0 x, 1 y, 2 z), a1 = (ax + 1) mod 3,
 * a2 = (ax + 2) mod 3: column a1 = c e_a1 + s e_a2, column a2 = -s e_a1 + c e_a2
 * (for ax = y: Rot(y) of Paul 1981 eq. 1.33). */
static DH_SIZE_NOINLINE void frameq_rot_elem(dh_frame_q *F, unsigned a1, unsigned a2, dh_q16 deg)
{
    dh_q30 s, c;
    DH_ASSERT(F != NULL);
    dh_sincos_q(deg, &s, &c);
    dh_frame_identity_q(F);
    F->r[a1][a1] = c;
    F->r[a1][a2] = s;
    F->r[a2][a1] = -s;                 /* |s| <= 2^30 (dh_sincos_q): exact */
    F->r[a2][a2] = c;
}

void dh_frame_rotx_q(dh_q16 deg, dh_frame_q *F) { frameq_rot_elem(F, 1u, 2u, deg); }
void dh_frame_roty_q(dh_q16 deg, dh_frame_q *F) { frameq_rot_elem(F, 2u, 0u, deg); }
void dh_frame_rotz_q(dh_q16 deg, dh_frame_q *F) { frameq_rot_elem(F, 0u, 1u, deg); }

/* ---- general kernel ------------------------------------------------------- */

/* modes of frameq_col */
#define DH_COL_RP ((int32_t)-1)     /* R b + p */
#define DH_COL_R ((int32_t)0)       /* R b */
#define DH_COL_NEG_R ((int32_t)1)   /* -R b */

/*
 * o[i] = round((sgn (row i of R) . b + (p_i & pm) 2^30) / 2^30), i = 0..2,
 * ties up, saturated; pm = -1 for DH_COL_RP, else 0; sgn = -1 for
 * DH_COL_NEG_R. Returns DH_ERR_OVERFLOW if an output saturated, else DH_OK.
 * The sum S is taken modulo 2^64. The true sum T is below
 * 3 * 2^62 + 2^61 + 2^29 in magnitude, so S = T exactly when the high word
 * of S is in [-2^29, 2^29); otherwise |T| >= 2^61 and only its sign is
 * needed. With the high words h_k of the four terms, T = (sum h_k) 2^32 + L,
 * 0 <= L < 2^34, so sum h_k has the sign of T and |sum h_k| >= 2^29 - 4;
 * H = sum (h_k >> 1) (|h_k| <= 2^30: no overflow) is within 4 of half of
 * it, hence has the same sign.
 */
static DH_NOINLINE unsigned frameq_col(int32_t *o, const dh_frame_q *A, const int32_t *b, int32_t mode)
{
    unsigned st = 0u, i, k;
    for (i = 0; i < 3u; i++) {
        const int32_t pm = (mode < 0) ? -1 : 0;
        int64_t S0 = DH_Q_HALF30 + (int64_t)(A->p[i] & pm) * DH_Q_ONE30;   /* |.| <= 2^61 */
        uint64_t S = (uint64_t)S0;
        int32_t H = (int32_t)(S0 >> 32) >> 1;
        for (k = 0; k < 3u; k++) {
            int64_t q = dh_q_mul64(A->r[k][i], b[k]);
            if (mode > 0) q = -q;                 /* |q| <= 2^62: safe */
            S += (uint64_t)q;
            H += (int32_t)(q >> 32) >> 1;         /* |H| < 2^31 */
        }
        if ((dh_q_hi_chk((int64_t)S) >> 30) != 0u) {
            st = (unsigned)DH_ERR_OVERFLOW;
            o[i] = H < 0 ? INT32_MIN : INT32_MAX;
        } else {
            o[i] = dh_q_lo30((int64_t)S);
        }
    }
    return st;
}

/* ---- rotation about an axis, re-orthonormalisation ------------------------ */

/* dh_q_rshr, one out-of-line copy */
static DH_NOINLINE int64_t frameq_rsh(int64_t x, unsigned sh)
{
    return dh_q_rshr(x, sh);
}

/* round(a b / 2^sh) */
static DH_NOINLINE int64_t frameq_mulr(int32_t a, int32_t b, unsigned sh)
{
    return frameq_rsh(dh_q_mul64(a, b), sh);
}

/* (a + ea / 2^16) (b + eb / 2^16) in the scale of a b, rounded once, the
 * ea eb / 2^32 term dropped: a b + round((a eb + b ea) / 2^16) */
static DH_NOINLINE int64_t frameq_pp(int32_t a, int32_t ea, int32_t b, int32_t eb)
{
    return dh_q_mul64(a, b) + frameq_rsh(dh_q_mul64(a, eb) + dh_q_mul64(b, ea), 16u);
}

/* 2^29 + P (1 - c) with P = Ph 2^30 + Pl, 0 <= Pl < 2^30:
 * 2^29 + P - Ph c + round(-Pl c / 2^30); |c| <= 2^30, so -c is exact */
static DH_NOINLINE int64_t frameq_vers(int64_t P, int32_t c)
{
    int32_t Ph = (int32_t)(P >> 30), Pl = (int32_t)(P - (int64_t)Ph * DH_Q_ONE30);
    return DH_Q_HALF30 + P - dh_q_mul64(Ph, c) + frameq_mulr(Pl, -c, 30u);
}

/* split x = U 2^16 + E, E in [-2^15, 2^15) */
static void frameq_split16(int64_t x, int32_t *U, int32_t *E)
{
    *U = (int32_t)frameq_rsh(x, 16u);
    *E = (int32_t)(x - (int64_t)*U * 65536);
}

/* a . b of two columns (|entries| <= 1.25 where used: no overflow) */
static DH_NOINLINE int64_t frameq_col_dot(const int32_t *a, const int32_t *b)
{
    int64_t e = 0;
    unsigned k;
    for (k = 0; k < 3u; k++) e += dh_q_mul64(a[k], b[k]);
    return e;
}

/*
 * R <- R (3 I - R^T R) / 2 in place (one Newton step towards the nearest
 * rotation): M = (3 I - R^T R) / 2 rounded once per entry, then R M rounded
 * once per entry, row i of R M being M (symmetric) times row i of R. For R
 * that pass frameq_ortho_chk() no sum can overflow and no entry of R M leaves
 * [-2, 2): ||R||_2 <= sqrt(1 + 3/8) < 1.18 and ||M||_2 <= 1 + 3/16 + 2^-28,
 * so every entry is below 1.4 and frameq_col() never saturates.
 */
static DH_NOINLINE void frameq_ortho_step(dh_frame_q *F)
{
    dh_frame_q M;                       /* M.p: row i of R (DH_COL_R ignores p) */
    int32_t o[3];
    unsigned i, j;
    for (i = 0; i < 3u; i++)
        for (j = 0; j < 3u; j++)
            M.r[i][j] = (int32_t)((((i == j) ? ((int64_t)3 << 60) : 0) + ((int64_t)1 << 30) -
                                   frameq_col_dot(F->r[i], F->r[j])) >> 31);
    for (i = 0; i < 3u; i++) {
        for (j = 0; j < 3u; j++) M.p[j] = F->r[j][i];
        (void)frameq_col(o, &M, M.p, DH_COL_R);
        for (j = 0; j < 3u; j++) F->r[j][i] = o[j];
    }
}

/*
 * F = Rot(k, deg) of Paul 1981 eq. 1.70, position 0; returns 0 for a zero
 * axis (F untouched). Integer only:
 *  1. w = k scaled by a power of two, largest |component| in [2^30, 2^31)
 *     (exact, except for an INT32_MIN component: the others are halved);
 *  2. |w|^2 (exact, in [2^60, 3 * 2^62)) normalised to X in [2^29, 2^31);
 *  3. Y = 1/sqrt(X / 2^30) by four Newton steps Y <- Y (3 - x Y^2) / 2
 *     from a piecewise linear seed below the root (iterates stay below it,
 *     so no intermediate overflows), good to about 2^-29;
 *  4. u = w Y in Q46, split as (U + E / 2^16) / 2^30, and one Newton step
 *     u <- u + u (1 - |u|^2) / 2 with |u|^2 in Q60 (error far below 2^-40);
 *  5. each entry k_i k_j vers + (i == j ? c : +-s k_m) summed in Q60 and
 *     rounded once; it is within 1 + 1 LSB of [-1, 1], read unchecked.
 * U[3] = 1, E[3] = 0 let the diagonal term c = c * 1 share the s k_m code.
 */
static DH_NOINLINE int frameq_axis_build(dh_frame_q *F, int32_t kx, int32_t ky, int32_t kz, dh_q16 deg)
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
    for (i = 0; i < 3u; i++) m |= dh_q_abs_u32(k[i]);
    if (m == 0u) return 0;
    sh = (int)dh_port_clz(m) - 1;                            /* step 1 */
    for (i = 0; i < 3u; i++) {
        U[i] = sh >= 0 ? (int32_t)((uint32_t)k[i] << (unsigned)sh) : k[i] / 2;   /* w */
        n2 += (uint64_t)dh_q_mul64(U[i], U[i]);
    }
    /* step 2: X = n2 / 2^(30, 32 or 34); h is the shift of step 4 */
    n2 >>= 30;
    while (n2 >= ((uint64_t)1 << 31)) { n2 >>= 2; h++; }
    X = (int32_t)n2;
    /* step 3: seed 1.75 - 0.75 x below 1, 1.25 - 0.25 x above */
    Y = X < DH_Q_ONE30 ? (int32_t)0x70000000 - (X - (X >> 2)) : (int32_t)0x50000000 - (X >> 2);
    for (i = 0; i < 4u; i++) {
        int32_t t = (int32_t)frameq_mulr(X, Y, 30u);
        t = (int32_t)frameq_mulr(t, Y, 30u);
        Y += (int32_t)frameq_mulr(Y, DH_Q_ONE30 - t, 31u);     /* Y (3 - t) / 2, one rounding */
    }
    /* step 4: D = 1 - |u|^2 in Q52 (|D| < 2^-24), u += u D / 2 in Q46 */
    for (i = 0; i < 3u; i++) {
        frameq_split16(frameq_mulr(U[i], Y, h), &U[i], &E[i]);
        n += frameq_pp(U[i], E[i], U[i], E[i]);
    }
    D = (int32_t)frameq_rsh(((int64_t)1 << 60) - n, 8u);
    for (i = 0; i < 3u; i++)
        frameq_split16((int64_t)U[i] * 65536 + E[i] + frameq_mulr(U[i], D, 37u), &U[i], &E[i]);
    U[3] = DH_Q_ONE30;
    E[3] = 0;
    dh_sincos_q(deg, &s, &c);
    /* step 5: k_i k_j = P, P vers by frameq_vers (|c| <= 2^30: -c exact) */
    for (j = 0; j < 3u; j++) {
        for (i = 0; i < 3u; i++) {
            unsigned mm = (i == j) ? 3u : 3u - i - j;
            int64_t T = frameq_pp(i == j ? c : s, 0, U[mm], E[mm]);
            /* s [k]x: (1,0) +kz, (0,1) -kz, (0,2) +ky, (2,0) -ky, (2,1) +kx,
             * (1,2) -kx; bits 3 j + i of 0x8C mark the negative ones */
            if ((0x8Cu >> (3u * j + i)) & 1u) T = -T;
            F->r[j][i] = (int32_t)((frameq_vers(frameq_pp(U[i], E[i], U[j], E[j]), c) + T) >> 30);
        }
        F->p[j] = 0;
    }
    return 1;
}

/* Rounding the nine entries leaves |R^T R - I| at a few LSB; one Newton
 * step brings it to the rounding level (its checks cannot fail here: entries
 * within 1 + 2 LSB, error far below 1/8). Separate calls: the stack depth
 * is the larger of the two. */
dh_status dh_frame_rot_axis_q(dh_q30 kx, dh_q30 ky, dh_q30 kz, dh_q16 deg, dh_frame_q *F)
{
    DH_ASSERT(F != NULL);
    if (!frameq_axis_build(F, kx, ky, kz, deg)) return DH_ERR_ZERO_AXIS;
    frameq_ortho_step(F);
    return DH_OK;
}

/* ---- fast paths ------------------------------------------------------------ */

#if DH_FAST_PATHS
/*
 * Each output is accumulated modulo 2^64 as 2^29 + at most three products
 * (+ a translation p 2^30), read with dh_q_lo30(), and dh_q_hi_chk() of
 * all outputs is OR-ed and tested once. The test is complete for any int32
 * inputs: without wraparound it is exactly "the result fits int32", and a
 * wrapped sum lies at least 2^61 + 2^29 from 0 (bound at frameq_col()), so its
 * high word fails the test too.
 */

/* 2^29 + p 2^30: one SMLAL where the core has it, else two shifts */
#if DH_PORT_MUL64_IS_CALL
#define DH_HALF_PLUS_P(ap) \
    ((int64_t)((uint64_t)DH_Q_HALF30 + DH_PORT_W64((ap) >> 2, (uint32_t)(ap) << 30)))
#else
#define DH_HALF_PLUS_P(ap) dh_port_smlal(DH_Q_HALF30, (ap), DH_Q_ONE30)
#endif

/* acc + row i of A times the 3 contiguous values b, modulo 2^64 */
DH_INLINE int64_t frameq_row_dot(int64_t acc, const dh_frame_q *A, unsigned i, const int32_t *b)
{
    const int64_t s0 = dh_port_smlal(acc, A->r[0][i], b[0]);
    const int64_t s1 = dh_port_smlal(s0, A->r[1][i], b[1]);
    return dh_port_smlal(s1, A->r[2][i], b[2]);
}

/* A B into *tp (never A or B); returns the check word. Written out row by
 * row: in a loop, compilers hoist the 12 values of B and spill them. */
static DH_NOINLINE uint32_t frameq_mul_fast(dh_frame_q *tp, const dh_frame_q *A, const dh_frame_q *B)
{
    uint32_t chk = 0u;
    int64_t acc;
    acc = frameq_row_dot(DH_Q_HALF30, A, 0u, B->r[0]); tp->r[0][0] = dh_q_lo30(acc); chk |= dh_q_hi_chk(acc);
    acc = frameq_row_dot(DH_Q_HALF30, A, 0u, B->r[1]); tp->r[1][0] = dh_q_lo30(acc); chk |= dh_q_hi_chk(acc);
    acc = frameq_row_dot(DH_Q_HALF30, A, 0u, B->r[2]); tp->r[2][0] = dh_q_lo30(acc); chk |= dh_q_hi_chk(acc);
    acc = frameq_row_dot(DH_HALF_PLUS_P(A->p[0]), A, 0u, B->p); tp->p[0] = dh_q_lo30(acc); chk |= dh_q_hi_chk(acc);
    acc = frameq_row_dot(DH_Q_HALF30, A, 1u, B->r[0]); tp->r[0][1] = dh_q_lo30(acc); chk |= dh_q_hi_chk(acc);
    acc = frameq_row_dot(DH_Q_HALF30, A, 1u, B->r[1]); tp->r[1][1] = dh_q_lo30(acc); chk |= dh_q_hi_chk(acc);
    acc = frameq_row_dot(DH_Q_HALF30, A, 1u, B->r[2]); tp->r[2][1] = dh_q_lo30(acc); chk |= dh_q_hi_chk(acc);
    acc = frameq_row_dot(DH_HALF_PLUS_P(A->p[1]), A, 1u, B->p); tp->p[1] = dh_q_lo30(acc); chk |= dh_q_hi_chk(acc);
    acc = frameq_row_dot(DH_Q_HALF30, A, 2u, B->r[0]); tp->r[0][2] = dh_q_lo30(acc); chk |= dh_q_hi_chk(acc);
    acc = frameq_row_dot(DH_Q_HALF30, A, 2u, B->r[1]); tp->r[1][2] = dh_q_lo30(acc); chk |= dh_q_hi_chk(acc);
    acc = frameq_row_dot(DH_Q_HALF30, A, 2u, B->r[2]); tp->r[2][2] = dh_q_lo30(acc); chk |= dh_q_hi_chk(acc);
    acc = frameq_row_dot(DH_HALF_PLUS_P(A->p[2]), A, 2u, B->p); tp->p[2] = dh_q_lo30(acc); chk |= dh_q_hi_chk(acc);
    return chk;
}

/* p = -R^T p of F as 2^29 - sum (nothing negated: INT32_MIN entries are
 * fine); returns the check word */
static DH_NOINLINE uint32_t frameq_inv_p_fast(const dh_frame_q *F, int32_t *p)
{
    uint32_t chk = 0u;
    unsigned i;
    for (i = 0; i < 3u; i++) {
        int64_t s = dh_port_smull(F->r[i][0], F->p[0]);
        int64_t acc;
        s = dh_port_smlal(s, F->r[i][1], F->p[1]);
        s = dh_port_smlal(s, F->r[i][2], F->p[2]);
        acc = (int64_t)((uint64_t)DH_Q_HALF30 - (uint64_t)s);
        p[i] = dh_q_lo30(acc);
        chk |= dh_q_hi_chk(acc);
    }
    return chk;
}

/* o = R u (+ p masked by pm); returns the check word */
static DH_NOINLINE uint32_t frameq_apply_fast(const dh_frame_q *F, const int32_t *in, int32_t pm, int32_t *o)
{
    uint32_t chk = 0u;
    unsigned i;
    for (i = 0; i < 3u; i++) {
        int64_t acc = DH_HALF_PLUS_P(F->p[i] & pm);
        acc = dh_port_smlal(acc, F->r[0][i], in[0]);
        acc = dh_port_smlal(acc, F->r[1][i], in[1]);
        acc = dh_port_smlal(acc, F->r[2][i], in[2]);
        o[i] = dh_q_lo30(acc);
        chk |= dh_q_hi_chk(acc);
    }
    return chk;
}
#endif /* DH_FAST_PATHS */

/* ---- composition ------------------------------------------------------------ */

/* general path of dh_frame_mul_q: column j of A B is A times column j of
 * [R_B p_B; 0 0 0 1] */
DH_GENERAL_FN unsigned frameq_mul_gen(dh_frame_q *t, const dh_frame_q *A, const dh_frame_q *B)
{
    unsigned st = 0u, j;
    for (j = 0; j < 3u; j++) st |= frameq_col(&t->r[j][0], A, B->r[j], DH_COL_R);
    st |= frameq_col(t->p, A, B->p, DH_COL_RP);
    return st;
}

/* Computed into a local, so out may alias A and/or B. Twin bodies: the
 * default build tries frameq_mul_fast first and takes the general path when
 * its check word fails; the size-first build has the general path only. */
#if DH_FAST_PATHS
dh_status dh_frame_mul_q(const dh_frame_q *A, const dh_frame_q *B, dh_frame_q *out)
{
    dh_frame_q t;
    unsigned st = 0u;
    DH_ASSERT(out != NULL && A != NULL && B != NULL);
    if ((frameq_mul_fast(&t, A, B) >> 30) != 0u) st = frameq_mul_gen(&t, A, B);
    *out = t;
    return (dh_status)st;
}
#else
dh_status dh_frame_mul_q(const dh_frame_q *A, const dh_frame_q *B, dh_frame_q *out)
{
    dh_frame_q t;
    unsigned st;
    DH_ASSERT(out != NULL && A != NULL && B != NULL);
    st = frameq_mul_gen(&t, A, B);
    *out = t;
    return (dh_status)st;
}
#endif

/* general path of dh_frame_inv_q: R' = R^T, p' = -R^T p (rows of R^T are
 * the columns of R), computed into a local (out may be F) */
DH_GENERAL_FN unsigned frameq_inv_gen(dh_frame_q *out, const dh_frame_q *F)
{
    dh_frame_q t;
    unsigned st, i, j;
    for (i = 0; i < 3u; i++)
        for (j = 0; j < 3u; j++) t.r[i][j] = F->r[j][i];
    st = frameq_col(t.p, &t, F->p, DH_COL_NEG_R);
    *out = t;
    return st;
}

/* The default build computes p first (frameq_inv_p_fast) and, when it fits,
 * transposes R in place (also correct when out == F); otherwise, and
 * always in the size-first build, the general path. */
#if DH_FAST_PATHS
dh_status dh_frame_inv_q(const dh_frame_q *F, dh_frame_q *out)
{
    int32_t p[3];
    unsigned i, j;
    DH_ASSERT(out != NULL && F != NULL);
    if ((frameq_inv_p_fast(F, p) >> 30) != 0u) return (dh_status)frameq_inv_gen(out, F);
    for (i = 0; i < 3u; i++) {
        out->r[i][i] = F->r[i][i];
        for (j = i + 1u; j < 3u; j++) {
            int32_t x = F->r[i][j], y = F->r[j][i];
            out->r[i][j] = y;
            out->r[j][i] = x;
        }
        out->p[i] = p[i];
    }
    return DH_OK;
}
#else
dh_status dh_frame_inv_q(const dh_frame_q *F, dh_frame_q *out)
{
    DH_ASSERT(out != NULL && F != NULL);
    return (dh_status)frameq_inv_gen(out, F);
}
#endif

/* o = R in (+ p for DH_COL_RP); returns the status word: frameq_apply_fast,
 * and the general frameq_col when its check word fails (default build), or
 * frameq_col alone (size-first build) */
#if DH_FAST_PATHS
DH_INLINE unsigned frameq_apply_in(const dh_frame_q *F, const int32_t *in, int32_t pm, int32_t *o)
{
    unsigned st = 0u;
    if ((frameq_apply_fast(F, in, pm, o) >> 30) != 0u) st = frameq_col(o, F, in, pm);
    return st;
}
#else
DH_INLINE unsigned frameq_apply_in(const dh_frame_q *F, const int32_t *in, int32_t pm, int32_t *o)
{
    return frameq_col(o, F, in, pm);
}
#endif

/* v = R u (+ p for DH_COL_RP) */
static dh_status frameq_apply(const dh_frame_q *F, const dh_vec3_q *u, dh_vec3_q *v, int32_t pm)
{
    int32_t in[3], o[3];
    unsigned st;
    DH_ASSERT(F != NULL && u != NULL && v != NULL);
    in[0] = u->x; in[1] = u->y; in[2] = u->z;
    st = frameq_apply_in(F, in, pm, o);
    v->x = o[0]; v->y = o[1]; v->z = o[2];
    return (dh_status)st;
}

dh_status dh_frame_apply_point_q(const dh_frame_q *F, const dh_vec3_q *u, dh_vec3_q *v)
{
    return frameq_apply(F, u, v, DH_COL_RP);
}

dh_status dh_frame_apply_dir_q(const dh_frame_q *F, const dh_vec3_q *u, dh_vec3_q *v)
{
    return frameq_apply(F, u, v, DH_COL_R);
}

/* ---- orthonormality --------------------------------------------------------- */

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
        for (i = 0; i < 3u; i++) T.p[i] = (i == j) ? -DH_Q_ONE30 : 0;
        (void)frameq_col(e, &T, F->r[j], DH_COL_RP);
        for (i = 0; i < 3u; i++) {
            uint32_t m = dh_q_abs_u32(e[i]);
            if (m > worst) worst = m;
        }
    }
    return worst > (uint32_t)INT32_MAX ? INT32_MAX : (int32_t)worst;
}

/* entries <= 1.25 (keeps every sum far from 2^63), then |R^T R - I| <= 1/8
 * per entry, exact in Q60 */
static DH_NOINLINE dh_status frameq_ortho_chk(const dh_frame_q *F)
{
    unsigned i, j;
    for (i = 0; i < 3u; i++)
        for (j = 0; j < 3u; j++)
            if (((uint32_t)F->r[i][j] + 0x50000000u) > 0xA0000000u) return DH_ERR_NOT_RIGID;
    for (i = 0; i < 3u; i++)
        for (j = i; j < 3u; j++) {
            int64_t e = frameq_col_dot(F->r[i], F->r[j]) - ((i == j) ? ((int64_t)1 << 60) : 0);
            if (e > ((int64_t)1 << 57) || e < -((int64_t)1 << 57)) return DH_ERR_NOT_RIGID;
        }
    return DH_OK;
}

/* checks and step are separate calls: the stack depth is the larger of the two */
dh_status dh_frame_orthonormalize_q(const dh_frame_q *F, dh_frame_q *out)
{
    dh_status st;
    DH_ASSERT(F != NULL && out != NULL);
    st = frameq_ortho_chk(F);
    if (st == DH_OK) {
        *out = *F; /* exact overlap when out is F */
        frameq_ortho_step(out);
    }
    return st;
}
