/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_ikc_common_q.c - closed-form IK, fixed point (integer only): the
 * helpers that several family solvers call (atan2 of int64 pairs, the
 * multiply-accumulate that skips exact factors, the 2R elbow, joint
 * references in canonical values); interface in ikc_impl.h. Calls no
 * solver and no front end.
 */
#include "dhmath/trig.h"
#include "ikc_impl.h"
#include "../internal/dh_qmath.h"

/* atan2 of two int64 of a common scale (|.| < 2^63): both rounded by the
 * same shift below 2^30 + 1, then dh_atan2_q; (0, 0) gives 0 */
DH_NOINLINE int32_t dh_ikc_atan2_q_(int64_t y, int64_t x)
{
    uint32_t hi = (uint32_t)((dh_ikc_abs64_q_(y) | dh_ikc_abs64_q_(x)) >> 30);
    unsigned s = 0u;
    dh_q16 a = 0;
    while (hi != 0u) {
        hi >>= 1;
        s++;
    }
    if (s != 0u) {
        y = dh_q_rshr(y, s);
        x = dh_q_rshr(x, s);
    }
    (void)dh_atan2_q((int32_t)y, (int32_t)x, &a);
    return a;
}

/* acc + c v, |c| <= 2^30: a factor 0 or +-1.0 (exact twists, sines and
 * cosines of multiples of 90 degrees, zero tool offsets) costs no
 * multiplication (the products of Cortex-M0 are 16-bit partials) */
DH_NOINLINE int64_t dh_ikc_mla_q_(int64_t acc, int32_t c, int32_t v)
{
    if (c == 0) return acc;
    if (c == DH_Q_ONE30) return acc + (int64_t)v * DH_Q_ONE30;
    if (c == -DH_Q_ONE30) return acc - (int64_t)v * DH_Q_ONE30;
    return dh_q_mla64(acc, c, v);
}

/* shift of a non-negative int64 below 2^31 */
unsigned dh_ikc_fit31_q_(int64_t v)
{
    const unsigned b = dh_q_bitlen64((uint64_t)v);
    return (b > 31u) ? b - 31u : 0u;
}

int32_t dh_ikc_cref_q_(const dh_ikc_model_q *m, const int32_t *q_ref, uint32_t i)
{
    const int32_t ref = (q_ref != NULL) ? q_ref[i] : 0;
    int ovf = 0;
    if ((m->prismatic >> i) & 1u) return dh_q_sat32((int64_t)ref + m->d[i], &ovf);
    return dh_ikc_wrap180_q_(dh_ikc_reduce_q_(ref) + m->off[i]);
}

/* The 2R elbow shared by both families: link lengths l1, l2 (l1 l2 != 0),
 * planar point (vx, vy). Writes the pair (S, K sgn D) scaled below 2^30
 * into out[0..1]; returns 0 unreachable, 1 stretched or folded, 2 two
 * branches. */
DH_NOINLINE unsigned dh_ikc_elbow_q_(int32_t l1, int32_t l2, int32_t vx, int32_t vy, int32_t *out)
{
    int64_t ds, df, Kd, tol;
    unsigned s1, s2, sh = 0u;
    uint32_t S;
    dh_ikc_dsdf_q_(l1, l2, vx, vy, &ds, &df);
    /* K sgn D: df - ds = 2 K, exactly halved */
    Kd = (df - ds) >> 1;
    if ((l1 < 0) != (l2 < 0)) Kd = -Kd;
    if (ds < -dh_ikc_btol_q_(dh_ikc_lsum_q_(l1, l2)) || df < -dh_ikc_btol_q_(dh_ikc_ldif_q_(l1, l2))) return 0u;
    tol = (((int64_t)dh_q_abs_u32(vx) + (int64_t)dh_q_abs_u32(vy)) << DH_IKC_FOLD_SH) + 1;
    if (ds <= tol) ds = 0;
    if (df <= tol) df = 0;
    s1 = dh_ikc_fit31_q_(ds);
    s2 = dh_ikc_fit31_q_(df);
    if (((s1 + s2) & 1u) != 0u) s1++;
    S = dh_q_isqrt62((uint64_t)dh_q_mul64((int32_t)(ds >> s1), (int32_t)(df >> s2)));
    {
        const unsigned sh2 = (s1 + s2) >> 1;
        Kd >>= sh2;
    }
    while ((((uint64_t)S | dh_ikc_abs64_q_(Kd)) >> sh) >= ((uint64_t)1 << 30)) sh++;
    out[0] = (sh != 0u) ? (int32_t)dh_q_rshr((int64_t)S, sh) : (int32_t)S;
    out[1] = (sh != 0u) ? (int32_t)dh_q_rshr(Kd, sh) : (int32_t)Kd;
    return (S == 0u) ? 1u : 2u;
}

/* ---- |det J| of the canonical chain (the tracker's singularity bound) ---- */

/* A lower bound on |x| 2^-30 (x a sum of products of lengths, dh_qpos, and
 * sines or cosines, Q2.30, or lengths times 2^30) in dh_qpos, below 2^31:
 * |x| less 2^-22 of sum (the magnitudes of the lengths in the sum: the
 * sines' error of 1.05 LSB, the products' rounding and twists within
 * DH_IKC_TOL_ALPHA of +-90 deg) and 4 LSB (the roundings to dh_qpos),
 * rounded down; 0 when that is not positive. */
uint32_t dh_ikc_low_q_(int64_t x, uint64_t sum)
{
    const uint64_t a = dh_ikc_abs64_q_(x), mg = (sum << 8) + ((uint64_t)4 << 30);
    const uint64_t v = (a > mg) ? (a - mg) >> 30 : 0u;
    return (v >= 0x80000000u) ? 0x7FFFFFFFu : (uint32_t)v;
}

/* A lower bound on |s| for a sine or cosine s (Q2.30): less 2^-22 (as
 * dh_ikc_low_q_), 0 when not positive. */
uint32_t dh_ikc_lows_q_(int32_t s)
{
    const uint32_t a = dh_q_abs_u32(s);
    return (a > 256u) ? a - 256u : 0u;
}

uint32_t dh_ikc_pmul_q_(uint32_t p, uint32_t f, int fb, int32_t *ex)
{
    uint64_t x;
    unsigned b;
    if (p == 0u || f == 0u) return 0u;
    x = (uint64_t)dh_q_mul64((int32_t)p, (int32_t)f);   /* both below 2^31 */
    b = dh_q_bitlen64(x);
    *ex -= fb;
    if (b > 31u) {
        const unsigned d = b - 31u;
        x >>= d;
        *ex += (int32_t)d;
    } else {
        const unsigned d = 31u - b;
        x <<= d;
        *ex -= (int32_t)d;
    }
    return (uint32_t)x;
}
