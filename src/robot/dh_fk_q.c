/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_fk_q.c - fixed-point forward kinematics (integer only: no float, no
 * libm, no 64-bit division; checked with arm-none-eabi-nm).
 *
 * Formats: rotation entries Q2.30, positions dh_qpos (DH_QPOS_FRAC fraction
 * bits), angles dh_q16 degrees. The link update is the float one (see
 * dh_fk_f32.c): two plane rotations of the columns with the position
 * update in between. Every output entry is one or two exact products
 * summed and rounded ONCE (half up); the intermediate rounded entries are
 * reused as the float code reuses its intermediate floats.
 *
 * General step (fkq_step): any base, any lengths, any twist; every entry is
 * range checked and saturates (DH_ERR_OVERFLOW). The exact twists (0, +-90,
 * 180 degrees) need no branch: with c, s in {0, +-2^30} every product is
 * exact, so each entry comes out as y, z, or a negation, and -INT32_MIN
 * rounds to 2^31, which saturates to INT32_MAX with the overflow flag.
 *
 * Fast path (DH_FAST_PATHS, in front of the general step, bit-identical to
 * it): taken when the robot's base rows have norm <= 1.5
 * (DH_ROBOT_BASE_SMALL_Q; then no rotation entry can leave Q2.30, see
 * below) and, on cores without a 32x32->64 multiply, the joint's |a| + |d|
 * <= 2^30. Rotation entries are rounded without a range check; exact
 * twists are a column swap and negation masks chosen once per joint, so
 * the row loop has no branch on the twist; only positions are range
 * checked. The two-term sums are one SMULL + SMLAL on Cortex-M3/M4/M7 and
 * dh_port_dot2r30_s16() (eight 16x16 MULS, no 64-bit arithmetic) on
 * ARMv6-M, with the sine/cosine/length factors split once per joint. The
 * first link of an identity base (and dh_link_q) is written out
 * (fkq_link_direct): its entries cannot saturate.
 *
 * Why the fast path cannot overflow. Each joint multiplies the rows of the
 * rotation by Rz(theta) Rx(alpha) built from sines and cosines with
 * |s|, |c| <= 2^30 and s^2 + c^2 <= 1 + 2^-28 (dh_trig.h: error <= 1.05
 * LSB), so a row norm grows at most by (1 + 2^-27) plus 1 LSB per joint:
 * after DH_MAX_JOINTS <= 32 joints every row has norm <= 1.5001, every
 * entry is below 2^31 (so negating one never meets INT32_MIN) and two
 * entries of a row have |x| + |y| <= sqrt(2) 1.5001 2^30 = 2.1215 2^30.
 *  - rotation sums c x + s y: |c| + |s| <= 1.4143 2^30, so
 *    |c| + |s| + |x| + |y| <= 3.54 2^30, inside the domain of
 *    dh_port_dot2r30_s16 (4 2^30 - 2^18), and the result is an entry of
 *    a row of norm <= 1.5001: it fits int32;
 *  - positions p + round(d z + a x): 64-bit path: |d z + a x| <=
 *    sqrt(d^2 + a^2) sqrt(z^2 + x^2) < 2.13 2^61, plus |p 2^30| <= 2^61,
 *    stays below 2^63 (no wrap), and the high word tells whether the
 *    result fits; split path: |a| + |d| <= 2^30 gives
 *    |d| + |a| + |z| + |x| <= 3.13 2^30 and |round(..)| <= 1.5001 2^30,
 *    then p + that is added with a 32-bit overflow test.
 *
 * General step overflow analysis. Every product is x*y with |x| <= 2^31
 * and |y| <= 2^31 - 1: rotation entries (any int32) meet sines, cosines
 * (|.| <= 2^30) or lengths, and lengths a, d are used with INT32_MIN
 * raised to -INT32_MAX (one LSB, documented saturation). So each product
 * is below 2^62 in magnitude and a sum or difference of two is below 2^63:
 * the two-term sums cannot wrap. Three-term sums (tool product) halve each
 * product first (error 2^-61 relative, far below one LSB). Rounding adds
 * 2^29 to a value below 2^63 - 2^32: no wrap either.
 */
#include "dhmath/robot.h"
#include "dhmath/trig.h"
#include "dhmath/frame.h" /* dh_frame_identity_q */
#include "../internal/dh_build.h"
#include "robot_impl.h"

#define HALF29 ((int64_t)1 << 29)
#define HALF28 ((int64_t)1 << 28)

/* 64-bit products of the general step, the link matrix and the tool
 * product. Out of line where they are a 16-bit-partials kernel (ARMv6-M):
 * inlined many times, that kernel makes GCC spill and the callers' frames
 * exceed the 256-byte stack budget. */
#if DH_PORT_MUL64_IS_CALL
static DH_NOINLINE int64_t fkq_mul64(int32_t a, int32_t b)
{
    return dh_port_smull(a, b);
}
static DH_NOINLINE int64_t fkq_mla64(int64_t acc, int32_t a, int32_t b)
{
    return dh_port_smlal(acc, a, b);
}
#define MUL(a, b) fkq_mul64((a), (b))
#define MLA(acc, a, b) fkq_mla64((acc), (a), (b))
#else
#define MUL(a, b) dh_port_smull((a), (b))
#define MLA(acc, a, b) dh_port_smlal((acc), (a), (b))
#endif

/* INT32_MIN when bit 31 of w is set, else INT32_MAX (the saturated value
 * of a result with the sign of w; the uint32 -> int32 conversion wraps,
 * checked in dh_port.h). */
DH_PORT_INLINE int32_t fkq_sat_sign(uint32_t w)
{
    return (int32_t)(0x7FFFFFFFu ^ (0u - (w >> 31)));
}

/* Length operand: INT32_MIN raised to -INT32_MAX (see the overflow note). */
DH_PORT_INLINE int32_t fkq_len(int32_t x)
{
    return (x == INT32_MIN) ? -INT32_MAX : x;
}

/* v saturated to int32 (|v| < 2^63 - 2^31); sets *ovf to DH_ERR_OVERFLOW
 * when it does not fit (v + 2^31 then leaves [0, 2^32)). Every flag of
 * this file is 0 or DH_ERR_OVERFLOW, so that it is the status itself. */
DH_INLINE int32_t fkq_sat32_inline(int64_t v, int *ovf)
{
    if (((uint64_t)(v + ((int64_t)1 << 31)) >> 32) != 0u) {
        *ovf = (int)DH_ERR_OVERFLOW;
        return fkq_sat_sign((uint32_t)((uint64_t)v >> 32));
    }
    return (int32_t)v;
}

static DH_NOINLINE int32_t fkq_sat32(int64_t v, int *ovf)
{
    return fkq_sat32_inline(v, ovf);
}

/* p + round(x / 2^30) (half up), saturated: |x| below 2^63 - 2^29. */
static DH_NOINLINE int32_t fkq_add_rnd30(int32_t p, int64_t x, int *ovf)
{
    return fkq_sat32(p + ((x + HALF29) >> 30), ovf);
}

/* Columns i and i + 1 of T turned by cs = (s, c): x' = c x + s y,
 * y' = c y - s x, each rounded once and saturated. */
static DH_NOINLINE void fkq_turn(dh_frame_q *T, unsigned i, const dh_q30 *cs, int *ovf)
{
    const dh_q30 s = cs[0], c = cs[1];
    int k;
    for (k = 0; k < 3; k++) {
        const int32_t x = T->r[i][k], y = T->r[i + 1u][k];
        T->r[i][k] = fkq_add_rnd30(0, MLA(MUL(c, x), s, y), ovf);
        T->r[i + 1u][k] = fkq_add_rnd30(0, MUL(c, y) - MUL(s, x), ovf);
    }
}

#if DH_FAST_PATHS
/* bits 30..61 of t (t >> 30 when that fits int32), from the two words */
DH_INLINE int32_t fkq_lo30(int64_t t)
{
    return (int32_t)(((uint32_t)((uint64_t)t & 0xFFFFFFFFu) >> 30) | ((uint32_t)((uint64_t)t >> 32) << 2));
}

/* round(x / 2^30) when the caller knows that it fits int32 (no check). */
DH_INLINE int32_t fkq_rnd30_fit(int64_t x)
{
    return fkq_lo30(x + HALF29);
}

/*
 * A twist class is a set of bits: TW_NA / TW_NB negate the first / the
 * second value of the pair (standard DH: u, z; modified DH: the roles are
 * exchanged, see fkq_fast_prep), TW_SWAP exchanges columns 1 and 2, TW_GEN is
 * the general twist (multiplications).
 */
#define TW_NA 1u
#define TW_NB 2u
#define TW_SWAP 4u
#define TW_GEN 8u
#define TW_ONE 0u                       /* alpha = 0: (y, z) */
#define TW_P90 5u                       /* +90: (z, -y), TW_NA | TW_SWAP */
#define TW_M90 6u                       /* -90: (-z, y), TW_NB | TW_SWAP */
#define TW_180 3u                       /* 180: (-y, -z), TW_NA | TW_NB */

/* Exact classes need sa, ca both exact: alpha = 90 +- 1 LSB has sa
 * rounded to exactly 1 but ca != 0, and alpha = +-1 LSB has ca exactly 1
 * but sa != 0; those are general twists. */
DH_PORT_INLINE unsigned fkq_twist_kind(dh_q30 sa, dh_q30 ca)
{
    unsigned kind = TW_GEN;
    if (sa == DH_Q30_ONE || sa == -DH_Q30_ONE) {
        if (ca == 0) {
            kind = TW_M90;
            if (sa > 0) kind = TW_P90;
        }
    } else if (ca == DH_Q30_ONE || ca == -DH_Q30_ONE) {
        if (sa == 0) {
            kind = TW_180;
            if (ca > 0) kind = TW_ONE;
        }
    }
    return kind;
}

/*
 * fkq_k: a factor used for a whole joint (sine, cosine, length), fkq_r: a
 * rotation entry; DOT2(c, x, s, y) = round((c x + s y) / 2^30), one
 * rounding, no range check (callers keep to the bounds in the file
 * comment).
 */
#if DH_PORT_USE_SPLIT16
/* |x| as uint32 (x != INT32_MIN here: lengths went through fkq_len()) */
DH_INLINE uint32_t fkq_abs_u(int32_t x)
{
    return x < 0 ? 0u - (uint32_t)x : (uint32_t)x;
}

typedef dh_port_s16 fkq_k;
typedef dh_port_s16 fkq_r;
#define KQ(v) dh_port_split_k(v)
#define RQ(v) dh_port_split_row(v)
#define DOT2(c, x, s, y) dh_port_dot2r30_s16((c), (x), (s), (y))
/* the split kernel needs the lengths' factors small (see the file comment) */
#define FAST_LENGTHS(a, d) (fkq_abs_u(a) + fkq_abs_u(d) <= 0x40000000u)
#else
typedef int32_t fkq_k;
typedef int32_t fkq_r;
#define KQ(v) (v)
#define RQ(v) (v)
#define DOT2(c, x, s, y) fkq_lo30(dh_port_smlal(dh_port_smlal(HALF29, (c), (x)), (s), (y)))
#define FAST_LENGTHS(a, d) 1
#endif

/* p + round((d z + a x) / 2^30), saturated (sets *ovf). One body per
 * multiply: the split kernel (DH_PORT_USE_SPLIT16) with a 32-bit overflow
 * test, or two SMLAL with the test on the high word. */
#if DH_PORT_USE_SPLIT16
DH_INLINE int32_t fkq_pos_fast(int32_t p, fkq_k kd, int32_t z, fkq_k ka, int32_t x, int *ovf)
{
    /* a zero length (most joints have one) drops its four products; a
     * zero split is the exact zero term, so the sum is the same */
    const fkq_k k0 = KQ(0);
    uint32_t r, s;
    if ((ka.h | ka.l) == 0) r = (uint32_t)DOT2(kd, RQ(z), k0, RQ(0));
    else if ((kd.h | kd.l) == 0) r = (uint32_t)DOT2(ka, RQ(x), k0, RQ(0));
    else r = (uint32_t)DOT2(kd, RQ(z), ka, RQ(x));
    s = (uint32_t)p + r;
    /* signed overflow iff p and r have the same sign and s the other one */
    if ((~((uint32_t)p ^ r) & ((uint32_t)p ^ s)) & 0x80000000u) {
        *ovf = (int)DH_ERR_OVERFLOW;
        return fkq_sat_sign((uint32_t)p);
    }
    return (int32_t)s;
}
#else
DH_INLINE int32_t fkq_pos_fast(int32_t p, fkq_k kd, int32_t z, fkq_k ka, int32_t x, int *ovf)
{
    /* p 2^30 + 2^29 + d z + a x modulo 2^64 (no wrap, file comment) */
    int64_t t = (int64_t)(DH_PORT_W64(p >> 2, (uint32_t)p << 30) + (uint64_t)HALF29);
    uint32_t hi;
    t = dh_port_smlal(dh_port_smlal(t, kd, z), ka, x);
    hi = (uint32_t)((uint64_t)t >> 32);
    if (hi + 0x20000000u >= 0x40000000u) {
        *ovf = (int)DH_ERR_OVERFLOW;
        return fkq_sat_sign(hi);
    }
    return fkq_lo30(t);
}
#endif

/* (v ^ m) - m: v or -v for a mask m of all zeros or all ones; v !=
 * INT32_MIN on the fast path */
#define NEGM(v, m) ((int32_t)(((uint32_t)(v) ^ (m)) - (m)))

/*
 * Exact twists (alpha 0, +90, -90, 180) are a swap of columns 1 and 2
 * and two negations, chosen once per joint; the row loops are generated
 * for the swap as a constant (0: twists 0 and 180, 1: +-90) plus one loop
 * for a general alpha, so only the negation masks are data:
 *  standard, (u, z) -> (y2, z2): 0 (u, z), +90 (z, -u), -90 (-z, u),
 *    180 (-u, -z): m1 negates u (TW_NA), m2 negates z (TW_NB), a swap
 *    stores u in column 2 and z in column 1;
 *  modified, (y, z) -> (o1, a1): 0 (y, z), +90 (z, -y), -90 (-z, y),
 *    180 (-y, -z): a swap reads o1 from column 2 and a1 from column 1,
 *    the sign of o1 (TW_NB) is folded into the factors ks, kc1, m2
 *    negates a1 (TW_NA).
 */

/* Factors of one joint for the fast path, prepared once per joint. */
typedef struct {
    fkq_k kc, ks, kns, kc1;     /* ct, st (modified: +-st), -st, modified: +-ct */
    fkq_k kd, ka;               /* d, a */
    fkq_k kca, ksa, knsa;       /* ca, sa, -sa (general twist only) */
    uint32_t m1, m2;            /* negation masks of the exact twists */
} fkq_joint;

/* sh1, sh2: the kind bits (0: TW_NA, 1: TW_NB) that negate the first and
 * the second value of the pair; fold: all ones when the first value's
 * sign goes into ks and kc1 (modified DH), else 0. Branch free: kind is
 * data, the other arguments are constants of the caller. */
DH_INLINE void fkq_fast_prep(fkq_joint *J, dh_q30 st, dh_q30 ct, dh_qpos a, dh_qpos d, unsigned kind,
                              unsigned sh1, unsigned sh2, uint32_t fold)
{
    const uint32_t m1 = 0u - ((kind >> sh1) & 1u);
    J->m1 = m1;
    J->m2 = 0u - ((kind >> sh2) & 1u);
    J->kc = KQ(ct);
    J->kns = KQ(-st);
    J->ks = KQ(NEGM(st, m1 & fold));
    J->kc1 = KQ(NEGM(ct, m1 & fold));
    J->kd = KQ(d);
    J->ka = KQ(a);
}

/* Rows of a standard DH joint: O = I * A (O may be I: row k of I is read
 * before row k of O is written). gen 0: an exact twist, whose rows are u and
 * z moved (swap 0 or 1) and negated; gen 1: a general twist. gen and swap
 * are constants. Returns DH_ERR_OVERFLOW when a position saturated, else 0. */
DH_INLINE int fkq_fast_std_rows(const fkq_joint *J, const dh_frame_q *I, dh_frame_q *O, int haslen, int gen,
                            int swap)
{
    int ovf = 0, k;
    DH_UNROLL3
    for (k = 0; k < 3; k++) {
        const fkq_r x = RQ(I->r[0][k]), y = RQ(I->r[1][k]);
        const int32_t z = I->r[2][k], p = I->p[k];
        const int32_t n1 = DOT2(J->kc, x, J->ks, y);
        const int32_t u = DOT2(J->kc, y, J->kns, x);
        O->p[k] = haslen ? fkq_pos_fast(p, J->kd, z, J->ka, n1, &ovf) : p;
        O->r[0][k] = n1;
        if (gen) {
            const fkq_r U = RQ(u), Z = RQ(z);
            O->r[1][k] = DOT2(J->kca, U, J->ksa, Z);
            O->r[2][k] = DOT2(J->kca, Z, J->knsa, U);
        } else {
            O->r[1 + swap][k] = NEGM(u, J->m1);
            O->r[2 - swap][k] = NEGM(z, J->m2);
        }
    }
    return ovf;
}

/* Rows of a modified DH joint with an exact twist (same contract). */
DH_INLINE int fkq_fast_mod_rows(const fkq_joint *J, const dh_frame_q *I, dh_frame_q *O, int haslen, int swap)
{
    int ovf = 0, k;
    DH_UNROLL3
    for (k = 0; k < 3; k++) {
        const int32_t xv = I->r[0][k], p = I->p[k];
        const fkq_r x = RQ(xv);
        const fkq_r o = RQ(I->r[1 + swap][k]);
        const int32_t a1 = NEGM(I->r[2 - swap][k], J->m2);
        O->p[k] = haslen ? fkq_pos_fast(p, J->ka, xv, J->kd, a1, &ovf) : p;
        O->r[0][k] = DOT2(J->kc, x, J->ks, o);
        O->r[1][k] = DOT2(J->kc1, o, J->kns, x);
        O->r[2][k] = a1;
    }
    return ovf;
}

/* Rows of a modified DH joint with a general twist (same contract). */
DH_INLINE int fkq_fast_mod_rows_gen(const fkq_joint *J, const dh_frame_q *I, dh_frame_q *O, int haslen)
{
    int ovf = 0, k;
    DH_UNROLL3
    for (k = 0; k < 3; k++) {
        const int32_t xv = I->r[0][k], p = I->p[k];
        const fkq_r x = RQ(xv);
        const fkq_r Y = RQ(I->r[1][k]), Z = RQ(I->r[2][k]);
        const fkq_r o = RQ(DOT2(J->kca, Y, J->ksa, Z));
        const int32_t a1 = DOT2(J->kca, Z, J->knsa, Y);
        O->p[k] = haslen ? fkq_pos_fast(p, J->ka, xv, J->kd, a1, &ovf) : p;
        O->r[0][k] = DOT2(J->kc, x, J->ks, o);
        O->r[1][k] = DOT2(J->kc1, o, J->kns, x);
        O->r[2][k] = a1;
    }
    return ovf;
}

/* One joint by the fast path: O = I * A (O may be I); mod: 0 standard, 1
 * modified (a constant of each caller); v = (st, ct, sa, ca, d, a) from
 * fkq_joint_values. */
DH_INLINE int fkq_fast_step(const dh_frame_q *I, dh_frame_q *O, unsigned mod, const dh_q30 *v)
{
    fkq_joint J;
    const unsigned kind = fkq_twist_kind(v[2], v[3]);
    const int haslen = (v[4] | v[5]) != 0;
    const int swap = (kind & TW_SWAP) != 0u;
    fkq_fast_prep(&J, v[0], v[1], v[5], v[4], kind, mod, mod ^ 1u, 0u - mod);
    if ((kind & TW_GEN) != 0u) {
        J.kca = KQ(v[3]);
        J.ksa = KQ(v[2]);
        J.knsa = KQ(-v[2]);
        return mod ? fkq_fast_mod_rows_gen(&J, I, O, haslen) : fkq_fast_std_rows(&J, I, O, haslen, 1, 0);
    }
    if (mod) return swap ? fkq_fast_mod_rows(&J, I, O, haslen, 1) : fkq_fast_mod_rows(&J, I, O, haslen, 0);
    return swap ? fkq_fast_std_rows(&J, I, O, haslen, 0, 1) : fkq_fast_std_rows(&J, I, O, haslen, 0, 0);
}

/* fkq_fast_step() for each convention (one copy each, out of the caller's
 * frame, the convention folded; they call nothing, so the joint's sine
 * and cosine are computed before, in the caller's smaller frame). */
static DH_NOINLINE int fkq_fast_std(const dh_frame_q *I, dh_frame_q *O, const dh_q30 *v)
{
    return fkq_fast_step(I, O, 0u, v);
}

static DH_NOINLINE int fkq_fast_mod(const dh_frame_q *I, dh_frame_q *O, const dh_q30 *v)
{
    return fkq_fast_step(I, O, 1u, v);
}

/* round(c x / 2^30) (half up) for |c| <= 2^30 and |x| < 2^31 - 2^15, no
 * range check (the result fits int32): on ARMv6-M dot2 with a zero second
 * term (folded away: four MULS, no 64-bit arithmetic, no call). */
#if DH_PORT_USE_SPLIT16
#define MULR30(c, x) dh_port_dot2r30_s16(dh_port_split_k(c), dh_port_split_row(x), dh_port_split_k(0), dh_port_split_row(0))
/* the same for a length l (any int32 but INT32_MIN) and |x| <= 2^30: 0
 * for a zero length (common), the split kernel where |l| <= 2^31 - 2^16
 * (its constant-split domain), else the 64-bit product */
#define MULR30L(l, x) ((l) == 0 ? 0 : fkq_abs_u(l) <= 0x7FFF0000u ? MULR30((l), (x)) : fkq_rnd30_fit(MUL((l), (x))))
#else
#define MULR30(c, x) fkq_rnd30_fit(MUL((c), (x)))
#define MULR30L(l, x) ((l) == 0 ? 0 : MULR30((l), (x)))
#endif
/* MULR30 by a twist sine/cosine c; ex: the twist is exact (sa, ca in
 * {0, +-2^30}), where the product is 0 or +-x without rounding */
#define MULR30T(c, x, ex) ((ex) ? ((c) == 0 ? 0 : ((c) > 0 ? (x) : -(x))) : MULR30((c), (x)))

/* The link matrix of joint j (a step applied to the identity, written
 * out; v from fkq_joint_values). Cannot saturate: every entry is a
 * product of two sines/cosines (|.| <= 2^30) or of one and a length, which
 * rounds into int32 unchecked. */
static DH_NOINLINE void fkq_link_direct(dh_frame_q *A, unsigned mod, const dh_q30 *v)
{
    const dh_q30 st = v[0], ct = v[1], sa = v[2], ca = v[3];
    const dh_qpos d = v[4], a = v[5];
    const int ex = ((uint32_t)(sa | ca) & 0x3FFFFFFFu) == 0u;
    if (mod == 0u) {
        /* n = (ct, st, 0), o = ca u + sa z, a = ca z - sa u with u = (-st, ct, 0) */
        A->r[0][0] = ct;
        A->r[0][1] = st;
        A->r[0][2] = 0;
        A->r[1][0] = MULR30T(ca, -st, ex);
        A->r[1][1] = MULR30T(ca, ct, ex);
        A->r[1][2] = sa;
        A->r[2][0] = MULR30T(sa, st, ex);
        A->r[2][1] = MULR30T(sa, -ct, ex);
        A->r[2][2] = ca;
        A->p[0] = MULR30L(a, ct);
        A->p[1] = MULR30L(a, st);
        A->p[2] = d;
    } else {
        /* n = (ct, st ca, st sa), o = (-st, ct ca, ct sa), a = (0, -sa, ca),
         * p = (a, -sa d, ca d) */
        A->r[0][0] = ct;
        A->r[0][1] = MULR30T(ca, st, ex);
        A->r[0][2] = MULR30T(sa, st, ex);
        A->r[1][0] = -st;
        A->r[1][1] = MULR30T(ca, ct, ex);
        A->r[1][2] = MULR30T(sa, ct, ex);
        A->r[2][0] = 0;
        A->r[2][1] = -sa;
        A->r[2][2] = ca;
        A->p[0] = a;
        A->p[1] = MULR30L(d, -sa);
        A->p[2] = MULR30L(d, ca);
    }
}

#endif /* DH_FAST_PATHS */

/* dst = src unless they are the same frame. */
static DH_NOINLINE void fkq_copy_frame(dh_frame_q *dst, const dh_frame_q *src)
{
    if (dst != src) *dst = *src;
}

/* Joint values of joint j at q: v = (sin theta, cos theta, sin alpha,
 * cos alpha, d, a), d = d + q saturated, lengths with INT32_MIN raised to
 * -INT32_MAX (the documented one-LSB raise, not an overflow). theta = q +
 * offset is brought back into int32 by whole turns (exact). Returns
 * DH_ERR_OVERFLOW when d + q saturated, else 0. */
DH_INLINE int fkq_joint_values(const dh_joint *j, int32_t q, dh_q30 *v)
{
    const uint32_t th = (uint32_t)j->theta_q;
    uint32_t qt = 0u, t;
    int32_t qd = 0;
    int64_t qs;
    int ovf = 0;
    if (j->type == DH_JOINT_REVOLUTE) qt = (uint32_t)q;
    else qd = q;
    /* t = theta + q modulo 2^32; when the sum leaves int32 (both terms of
     * one sign, t of the other) the true sum is t +- 2^32, and 182 turns
     * (2^32 - 2^20) back is t + 2^20 when t wrapped negative, t - 2^20
     * otherwise (the uint32 -> int32 conversion wraps, dh_port.h) */
    t = th + qt;
    if (((t ^ th) & (t ^ qt)) >> 31) t += 0xFFF00000u + ((t >> 31) << 21);
    dh_sincos_q((dh_q16)t, &v[0], &v[1]);
    v[2] = j->sa_q;
    v[3] = j->ca_q;
    qs = (int64_t)j->d_q + qd;
    v[4] = fkq_len(DH_FAST_PATHS ? fkq_sat32_inline(qs, &ovf) : fkq_sat32(qs, &ovf));
    v[5] = fkq_len(j->a_q);
    return ovf;
}

/* T <- T * A in place, the general step, v = (st, ct, sa, ca, d, a) from
 * fkq_joint_values; mod: 0 standard, 1 modified. Sets *ovf to DH_ERR_OVERFLOW
 * when an entry saturated. Standard DH turns (n, o) by theta, moves p
 * by a n + d a, then twists (o, a) by alpha; modified DH twists first,
 * moves p by a n + d a with the twisted a, then turns. */
DH_GENERAL_FN void fkq_step(dh_frame_q *T, unsigned mod, const dh_q30 *v, int *ovf)
{
    int k;
    fkq_turn(T, mod, &v[2u * mod], ovf);
    for (k = 0; k < 3; k++)
        T->p[k] = fkq_add_rnd30(T->p[k], MLA(MUL(v[5], T->r[0][k]), v[4], T->r[2][k]), ovf);
    fkq_turn(T, mod ^ 1u, &v[2u * (mod ^ 1u)], ovf);
}

#if !DH_FAST_PATHS
/* fkq_step() for joint i of r at q (one copy for dh_link_q and the chain):
 * DH_ERR_OVERFLOW when d + q or an entry saturated, else 0. */
static DH_NOINLINE int fkq_joint_step(dh_frame_q *T, const dh_robot *r, uint32_t i, int32_t q)
{
    dh_q30 v[6];
    int ovf = fkq_joint_values(&r->joint[i], q, v);
    fkq_step(T, r->conv != DH_CONV_STANDARD, v, &ovf);
    return ovf;
}
#endif

/* a0 b[0]/2 + a1 b[1]/2 + a2 b[2]/2 (each product halved, floor), exact in
 * 64 bits (|each| <= 2^61). */
static DH_NOINLINE int64_t fkq_dot3h(int32_t a0, int32_t a1, int32_t a2, const int32_t *b)
{
    return (MUL(a0, b[0]) >> 1) + (MUL(a1, b[1]) >> 1) + (MUL(a2, b[2]) >> 1);
}

/* out = A * B, three-term sums of halved products rounded at bit 29 (not
 * dh_frame_mul_q, which rounds the exact sum: one LSB apart in rare cases,
 * so a different status at the int32 edge). out may be A (row k of A is
 * read before row k of out is written), not B. Returns DH_ERR_OVERFLOW
 * when an entry saturated, else 0. */
static DH_NOINLINE int fkq_mul_frame(dh_frame_q *out, const dh_frame_q *A, const dh_frame_q *B)
{
    int c, k, ovf = 0;
    for (k = 0; k < 3; k++) {
        const int32_t a0 = A->r[0][k], a1 = A->r[1][k], a2 = A->r[2][k], p = A->p[k];
        for (c = 0; c < 4; c++) {
            /* columns n, o, a, then p (plus the position of A) */
            const int32_t *b = c < 3 ? B->r[c] : B->p;
            int32_t *o = c < 3 ? &out->r[c][k] : &out->p[k];
            *o = fkq_sat32((c < 3 ? 0 : p) + ((fkq_dot3h(a0, a1, a2, b) + HALF28) >> 29), &ovf);
        }
    }
    return ovf;
}

/* Twin bodies: the link written out (fkq_link_direct) in the default build,
 * the general step on the identity in the size-first build. */
#if DH_FAST_PATHS
dh_status dh_link_q(const dh_robot *r, uint32_t i, int32_t q, dh_frame_q *A)
{
    dh_q30 v[6];
    int ovf;
    DH_ASSERT(r != NULL);
    DH_ASSERT(A != NULL);
    if (i >= r->n || r->n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    if ((r->flags & DH_ROBOT_HAS_Q) == 0u) return DH_ERR_UNAVAILABLE;
    ovf = fkq_joint_values(&r->joint[i], q, v);
    fkq_link_direct(A, r->conv != DH_CONV_STANDARD, v);
    return (dh_status)ovf;
}
#else
dh_status dh_link_q(const dh_robot *r, uint32_t i, int32_t q, dh_frame_q *A)
{
    DH_ASSERT(r != NULL);
    DH_ASSERT(A != NULL);
    if (i >= r->n || r->n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    if ((r->flags & DH_ROBOT_HAS_Q) == 0u) return DH_ERR_UNAVAILABLE;
    dh_frame_identity_q(A);
    return (dh_status)fkq_joint_step(A, r, i, q);
}
#endif

/* out = cur * A_i(q[i]) (out may be cur); sets *ovf, the chain's flag, to
 * DH_ERR_OVERFLOW when an entry or d + q saturated (the inlined step
 * updates that flag in place: a flag of its own, returned and ORed in,
 * costs the Puma chain instructions on Cortex-M0 and M4). The default
 * build writes the first link of an identity base out, takes the fast
 * step where its bounds hold (file comment) and the general step
 * otherwise; the size-first build always takes the general step. */
#if DH_FAST_PATHS
DH_INLINE void fkq_chain_joint(const dh_robot *r, uint32_t i, const int32_t *q, const dh_frame_q *cur, dh_frame_q *out,
                               int *ovf)
{
    dh_q30 v[6];
    *ovf |= fkq_joint_values(&r->joint[i], q[i], v);
    if (i == 0u && (r->flags & DH_ROBOT_BASE_ID_Q) != 0u) {
        fkq_link_direct(out, r->conv != DH_CONV_STANDARD, v);
    } else if ((r->flags & DH_ROBOT_BASE_SMALL_Q) != 0u && FAST_LENGTHS(v[5], v[4])) {
        *ovf |= (r->conv == DH_CONV_STANDARD) ? fkq_fast_std(cur, out, v) : fkq_fast_mod(cur, out, v);
    } else {
        fkq_copy_frame(out, cur);
        fkq_step(out, r->conv != DH_CONV_STANDARD, v, ovf);
    }
}
#else
DH_INLINE void fkq_chain_joint(const dh_robot *r, uint32_t i, const int32_t *q, const dh_frame_q *cur, dh_frame_q *out,
                               int *ovf)
{
    fkq_copy_frame(out, cur);
    *ovf |= fkq_joint_step(out, r, i, q[i]);
}
#endif

/* T_end = cur * tool; returns the overflow flag. The default build copies
 * for an identity tool; the size-first build always multiplies (by the
 * identity: every entry exact, no overflow, the same bits as the copy). */
#if DH_FAST_PATHS
DH_INLINE int fkq_tool(const dh_robot *r, const dh_frame_q *cur, dh_frame_q *T_end)
{
    if ((r->flags & DH_ROBOT_TOOL_ID_Q) == 0u) return fkq_mul_frame(T_end, cur, &r->tool_q);
    fkq_copy_frame(T_end, cur);
    return 0;
}
#else
DH_INLINE int fkq_tool(const dh_robot *r, const dh_frame_q *cur, dh_frame_q *T_end)
{
    return fkq_mul_frame(T_end, cur, &r->tool_q);
}
#endif

/* The chain is built in the caller's memory (frames[i], or T_end), from
 * the base; nothing is written before the argument checks. */
static dh_status fkq_all(const dh_robot *r, const int32_t *q, dh_frame_q *frames, dh_frame_q *T_end)
{
    const dh_frame_q *cur = &r->base_q;
    dh_frame_q *out = T_end;
    uint32_t i;
    int ovf = 0;
    DH_ASSERT(r != NULL);
    DH_ASSERT(q != NULL);
    if (r->n == 0u || r->n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    if ((r->flags & DH_ROBOT_HAS_Q) == 0u) return DH_ERR_UNAVAILABLE;
    for (i = 0u; i < r->n; i++) {
        if (frames) out = &frames[i];
        fkq_chain_joint(r, i, q, cur, out, &ovf);
        cur = out;
    }
    if (T_end) ovf |= fkq_tool(r, cur, T_end);
    return (dh_status)ovf;
}

dh_status dh_fk_q(const dh_robot *r, const int32_t *q, dh_frame_q *T)
{
    DH_ASSERT(T != NULL);
    return fkq_all(r, q, NULL, T);
}

dh_status dh_fk_frames_q(const dh_robot *r, const int32_t *q, dh_frame_q *frames, dh_frame_q *T_end)
{
    DH_ASSERT(frames != NULL);
    return fkq_all(r, q, frames, T_end);
}

/* ---- private blocks of the fixed Jacobian (dh_kin_impl.h) --------------- */

/* fkq_joint_values of joint i of r at q into v[6] (sin theta, cos theta, sin
 * alpha, cos alpha, d, a; the lengths raised from INT32_MIN). */
int dh_fk_values_q_(const dh_robot *r, uint32_t i, int32_t q, dh_q30 *v)
{
    return fkq_joint_values(&r->joint[i], q, v);
}

/* T <- T * tool in place (nothing for an identity tool), as fkq_all. */
int dh_fk_tool_q_(const dh_robot *r, dh_frame_q *T)
{
    if ((r->flags & DH_ROBOT_TOOL_ID_Q) != 0u) return 0;
    return fkq_mul_frame(T, T, &r->tool_q);
}
