/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_internal.h - private helpers shared by every module of src/ (not
 * installed, not part of the API). Each helper is defined here once.
 *
 * It is also the one place that decides what the size-first build
 * (DH_SMALL, dh_config.h) turns off. A .c file never tests DH_SMALL; it
 * tests the switches below, which keep one body per public function: the
 * general path is always compiled, and a fast path is an addition in front
 * of it, guarded by `if (DH_FAST_PATHS ...)` or `#if DH_FAST_PATHS`.
 */
#ifndef DHMATH_SRC_DH_INTERNAL_H
#define DHMATH_SRC_DH_INTERNAL_H

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "dhmath/dh_config.h"
#include "dhmath/dh_common.h"
#include "dh_mathf.h"
#include "../port/dh_port.h" /* relative: src/ compiles with only include/ on the path */

/* ---- what the size-first build turns off -------------------------------- */

/** 1: fast paths (special cases, unrolled kernels) run in front of the
 *  general path; 0: the general path alone. */
#if DH_SMALL
#define DH_FAST_PATHS 0
#else
#define DH_FAST_PATHS 1
#endif

/* ---- inlining hints ------------------------------------------------------- */

#if defined(__GNUC__) || defined(__clang__)
/** Keep a helper out of line (one copy, bounded caller frames). */
#define DH_NOINLINE __attribute__((noinline))
/** Inline a small helper into every caller. */
#define DH_INLINE static __inline__ __attribute__((always_inline))
#else
#define DH_NOINLINE
#define DH_INLINE static
#endif

/** Out of line only in the size-first build (one copy instead of several). */
#if DH_FAST_PATHS
#define DH_SIZE_NOINLINE
#else
#define DH_SIZE_NOINLINE DH_NOINLINE
#endif

/** A general path that a fast path precedes in the default build: out of
 *  line there (the fast path keeps a short prologue), inlined into its one
 *  caller when it runs alone (DH_FAST_PATHS 0). */
#if DH_FAST_PATHS
#define DH_GENERAL_FN static DH_NOINLINE
#else
#define DH_GENERAL_FN DH_INLINE
#endif

/* ---- constants ------------------------------------------------------------ */

/** 180 / pi and pi / 180, rounded to float. */
#define DH_RAD2DEG_F 57.295779513082320876798f
#define DH_DEG2RAD_F 0.017453292519943295f

/* ---- configuration check (include/dhmath/dh_config.h, src/dh_config.c) --- */

/** Defined by the library, referenced by every application translation
 *  unit with ITS values: a mismatch of an interface setting fails to link. */
extern const uint8_t DH_CFG_SYM_MAX_JOINTS_;
extern const uint8_t DH_CFG_SYM_QPOS_FRAC_;

/* ---- libm-free float helpers (the library links without libm) ----------- */

/** sqrt(x) for the float modules, bit for bit IEEE's (correctly rounded):
 *  the FPU instruction through __builtin_sqrtf where the compiler emits it
 *  without a libm call (single-precision hardware square root and
 *  -fno-math-errno, which the library's build sets: __NO_MATH_ERRNO__),
 *  else the integer version dh_sqrtf_ (src/dh_mathf.c). */
#if (defined(__GNUC__) || defined(__clang__)) && defined(__NO_MATH_ERRNO__) && \
    (DH_MATHF_VSQRT || defined(__SSE_MATH__) || defined(__riscv_fsqrt))
#define DH_SQRT_INSN 1
#else
#define DH_SQRT_INSN 0
#endif
DH_INLINE float dh_sqrt_f32(float x)
{
#if DH_SQRT_INSN
    return __builtin_sqrtf(x);
#else
    return dh_sqrtf_(x);
#endif
}

/* ---- float predicates ----------------------------------------------------- */

/** 1 when floats are emulated (no FPU): float tests are cheaper on the bits. */
#if (defined(__arm__) && (defined(__SOFTFP__) || !defined(__ARM_FP))) || \
    (defined(__riscv) && !defined(__riscv_flen))
#define DH_SOFT_FLOAT 1
#else
#define DH_SOFT_FLOAT 0
#endif

/** a == b for floats: +0 equals -0, a NaN equals nothing. Written with
 *  C99's quiet comparison macros (<math.h>, no libm): compilers emit the
 *  one comparison of ==, and -Wfloat-equal has no == on floats to report. */
DH_INLINE int dh_feq_f32(float a, float b)
{
    return !islessgreater(a, b) && !isunordered(a, b);
}

/** 1 if x is finite (not NaN, not +-Inf). With an FPU: x - x is 0 exactly
 *  then and NaN otherwise; soft float: the exponent field is not all ones. */
DH_INLINE int dh_isfinite_f32(float x)
{
#if DH_SOFT_FLOAT
    uint32_t u;
    memcpy(&u, &x, sizeof u);
    return (u & 0x7F800000u) != 0x7F800000u;
#else
    return dh_feq_f32(x - x, 0.0f);
#endif
}

/** The bits of x and the float of bits b (bit-level tests and constants;
 *  dh_robot_check compares derived floats bit for bit, so -0 differs from
 *  +0 and a NaN from every float). */
DH_INLINE uint32_t dh_f32_bits(float x)
{
    uint32_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

DH_INLINE float dh_f32_from_bits(uint32_t b)
{
    float x;
    memcpy(&x, &b, sizeof x);
    return x;
}

/** 1 if v[0..len-1] are all finite: the exponent fields tested on the bits
 *  (no float compare per element, so the same cost with or without an FPU). */
DH_INLINE int dh_allfinite_f32(const float *v, uint32_t len)
{
    uint32_t k, u;
    int fin = 1;
    for (k = 0; k < len; k++) {
        float x = v[k];
        memcpy(&u, &x, sizeof u);
        if ((u & 0x7F800000u) == 0x7F800000u) fin = 0;
    }
    return fin;
}

/* ---- trig and robot description helpers --------------------------------- */

/**
 * x * 2^frac (frac 0..30) rounded to the nearest int32, ties away from zero,
 * into *out. Returns 0 when stored, 1 when x is finite but the result is
 * out of range, 2 when x is NaN or Inf (*out untouched in both cases), so
 * that callers OR the results of several conversions. Exact: the scaling is
 * by a power of two and the range test is on x itself (2^(31 - frac) is a
 * float); rem = v - trunc(v) is in (-1, 1), so the truncation of 2 rem is
 * +-1 exactly when |rem| >= 0.5. The largest float below 2^31 is an
 * integer, so i + 1 cannot overflow.
 */
static inline unsigned dh_f32_to_fix(float x, unsigned frac, int32_t *out)
{
    const uint32_t p = 1u << (frac & 31u), pl = 1u << (31u - frac);
    const float lim = (float)pl;
    float v, rem;
    int32_t i;
    if (!dh_isfinite_f32(x)) return 2u;
    if (x >= lim || x < -lim) return 1u;
    v = x * (float)p;
    i = (int32_t)v;
    rem = v - (float)i;
    rem += rem;
    *out = i + (int32_t)rem;
    return 0u;
}

/** The same, saturated to the int32 range by the sign of x when out of
 *  range (finite x); *st |= the dh_f32_to_fix status. */
static inline int32_t dh_f32_to_fix_sat(float x, unsigned frac, unsigned *st)
{
    int32_t v;
    const unsigned e = dh_f32_to_fix(x, frac, &v);
    *st |= e;
    if (e == 0u) return v;
    return (x < 0.0f) ? INT32_MIN : INT32_MAX;
}


/* ---- float transform helpers --------------------------------------------- */

/** The general path behind a fast path (dh_mat4_inv.c): optimized for size
 *  (smaller frames: stack budget on Cortex-M0+), calls to it unlikely. Not
 *  cold in the size-first build, where it is the only path. */
#if DH_FAST_PATHS && (defined(__GNUC__) || defined(__clang__))
#define DH_COLD __attribute__((cold))
#else
#define DH_COLD
#endif

/** Out of line in the default build only (callers' frames stay small on
 *  Cortex-M0+ there); the size-first build inlines its single call. */
#if DH_FAST_PATHS
#define DH_FAST_NOINLINE DH_NOINLINE
#else
#define DH_FAST_NOINLINE
#endif

/* ---- fixed-point helpers (Q rounding, saturation) ------------------------ */

/** 1.0 in Q2.30, and half an LSB of a result taken >> 30. */
#define DH_Q_ONE30 ((int32_t)0x40000000)
#define DH_Q_HALF30 ((int64_t)0x20000000)

/* a b and acc + a b (modulo 2^64). Out of line where the product is the
 * 16-bit-partials kernel (DH_PORT_MUL64_IS_CALL, ARMv6-M): inlined many
 * times it makes GCC spill and the callers' frames exceed 256 bytes. */
#if DH_PORT_MUL64_IS_CALL && (defined(__GNUC__) || defined(__clang__))
#define DH_Q_MUL_FN static DH_NOINLINE __attribute__((unused))
#else
#define DH_Q_MUL_FN DH_INLINE
#endif
/** a b, exact. */
DH_Q_MUL_FN int64_t dh_q_mul64(int32_t a, int32_t b)
{
    return dh_port_smull(a, b);
}
/** acc + a b modulo 2^64. */
DH_Q_MUL_FN int64_t dh_q_mla64(int64_t acc, int32_t a, int32_t b)
{
    return dh_port_smlal(acc, a, b);
}

/** round(x / 2^sh), ties up, 1 <= sh <= 62, any x (cannot overflow). */
DH_INLINE int64_t dh_q_rshr(int64_t x, unsigned sh)
{
    return ((x >> (sh - 1u)) + (int64_t)1) >> 1;
}

/* dh_q_lo30 and dh_q_hi_chk are plain inline, not DH_INLINE: forced
 * inlining makes GCC schedule the unrolled fast paths worse. */
/** Bits 30..61 of t from its two words: t >> 30 when that fits int32. */
static inline int32_t dh_q_lo30(int64_t t)
{
    const uint64_t u = (uint64_t)t;
    const uint32_t hi = (uint32_t)(u >> 32), lo = (uint32_t)u;
    const uint32_t r = (hi << 2) | (lo >> 30);
    return (int32_t)r;
}

/** Bits 30 and 31 are clear iff t >> 30 fits int32 (high word in
 *  [-2^29, 2^29)): OR the words of several results, test once. */
static inline uint32_t dh_q_hi_chk(int64_t t)
{
    return (uint32_t)((uint64_t)t >> 32) + 0x20000000u;
}

/** round(x / 2^30), ties up, where the caller knows that it fits int32. */
DH_INLINE int32_t dh_q_rnd30_fit(int64_t x)
{
    return dh_q_lo30(x + DH_Q_HALF30);
}

/** INT32_MIN when bit 31 of w is set, else INT32_MAX (the saturated value
 *  of a result with the sign of w). */
DH_INLINE int32_t dh_q_sat_sign(uint32_t w)
{
    const uint32_t r = 0x7FFFFFFFu ^ (0u - (w >> 31));
    return (int32_t)r;
}

/** v saturated to int32; sets *ovf to DH_ERR_OVERFLOW when it did not fit. */
DH_INLINE int32_t dh_q_sat32(int64_t v, int *ovf)
{
    if ((((uint64_t)v + 0x80000000u) >> 32) != 0u) {
        *ovf = (int)DH_ERR_OVERFLOW;
        return dh_q_sat_sign((uint32_t)((uint64_t)v >> 32));
    }
    return (int32_t)v;
}

/** round(x / 2^30), ties up, saturated (*ovf as dh_q_sat32); a Q2.30 entry
 *  from a sum of Q2.30 products, |x| < 2^63 - 2^29. */
DH_INLINE int32_t dh_q_rnd30(int64_t x, int *ovf)
{
    int64_t t = x + DH_Q_HALF30;
    if ((dh_q_hi_chk(t) >> 30) != 0u) {
        *ovf = (int)DH_ERR_OVERFLOW;
        return dh_q_sat_sign((uint32_t)((uint64_t)t >> 32));
    }
    return dh_q_lo30(t);
}

/** p + round(x / 2^30), ties up, saturated (*ovf as dh_q_sat32): a position
 *  plus rotation x position products (Q2.30 x Qpos >> 30 = Qpos). */
DH_INLINE int32_t dh_q_pos_rnd30(int32_t p, int64_t x, int *ovf)
{
    return dh_q_sat32((int64_t)p + ((x + DH_Q_HALF30) >> 30), ovf);
}

/** -x, INT32_MIN saturated to INT32_MAX (*ovf as dh_q_sat32), never negated. */
DH_INLINE int32_t dh_q_neg_sat(int32_t x, int *ovf)
{
    if (x == INT32_MIN) {
        *ovf = (int)DH_ERR_OVERFLOW;
        return INT32_MAX;
    }
    return -x;
}

/** |x| as uint32 (exact also for INT32_MIN). */
DH_INLINE uint32_t dh_q_abs_u32(int32_t x)
{
    return x < 0 ? 0u - (uint32_t)x : (uint32_t)x;
}

/** floor(sqrt(v)) for v < 2^62, digit by digit (31 bit pairs; the
 *  remainder stays below 2 root + 1 <= 2^31 + 1). Integer only, no division. */
static inline uint32_t dh_q_isqrt62(uint64_t v)
{
    uint64_t rem = 0u;
    uint32_t root = 0u, i;

    for (i = 0u; i < 31u; i++) {
        uint64_t trial;
        rem = (rem << 2) | (v >> 60);
        v = (v << 2) & (((uint64_t)1 << 62) - 1u);
        root <<= 1;
        trial = ((uint64_t)root << 1) | 1u;
        if (rem >= trial) {
            rem -= trial;
            root |= 1u;
        }
    }
    return root;
}

/* ---- fixed-point square roots (integer only, no division) --------------- */

/** Number of significant bits of v (0 for 0). */
DH_INLINE unsigned dh_q_bitlen64(uint64_t v)
{
    const uint32_t hi = (uint32_t)(v >> 32), lo = (uint32_t)v;
    if (hi != 0u) return 64u - dh_port_clz(hi);
    return 32u - dh_port_clz(lo);
}

/**
 * 1 / sqrt(x / 2^30) in Q3.29 for x in [2^28, 2^30] (a value in [1/4, 1],
 * result in [1, 2]): `steps` (1..3) Newton steps Y <- Y (3 - x Y^2) / 2
 * from the tangent of 1/sqrt at 0.36 (x below 1/2) or 0.72 (above), which
 * lies below the root (relative error <= 5%, then 3.8e-3, 2.1e-5, 7e-10,
 * plus a few LSB of rounding). Integer only.
 */
static inline int32_t dh_q_rsqrt29(int32_t x, unsigned steps)
{
    int32_t y;
    unsigned i;
    /* tangents 2.5 - 2.31481 x and 1.76777 - 0.818415 x (Q29 constants) */
    if (x < (int32_t)0x20000000)
        y = (int32_t)1342177280 - (int32_t)(dh_q_mul64(x, 1242756741) >> 30);
    else
        y = (int32_t)949062656 - (int32_t)(dh_q_mul64(x, 439380859) >> 30);
    for (i = 0; i < steps; i++) {
        int32_t t = (int32_t)(dh_q_mul64(x, y) >> 29);  /* x y, Q30 */
        t = (int32_t)(dh_q_mul64(t, y) >> 29);          /* x y^2, Q30, near 1 */
        y += (int32_t)(dh_q_mul64(y, DH_Q_ONE30 - t) >> 31);
    }
    return y;
}

/** v normalised for dh_q_rsqrt29: v = (*m) 2^(*t) with *m in [2^28, 2^30)
 *  and *t even (may be negative); v > 0. */
DH_INLINE void dh_q_norm_even(uint64_t v, int32_t *m, int *t)
{
    int sh = (int)dh_q_bitlen64(v) - 30;
    if (sh & 1) sh++;
    *t = sh;
    *m = (sh >= 0) ? (int32_t)(v >> (unsigned)sh) : (int32_t)(v << (unsigned)(-sh));
}

/** sqrt(v) for any uint64 v, within 2^-28 relative (0 for 0): the
 *  normalised v times its reciprocal square root (three Newton steps). */
static inline uint32_t dh_q_sqrt_u64(uint64_t v)
{
    int32_t m, y;
    int t, sh;
    uint64_t r;
    if (v == 0u) return 0u;
    dh_q_norm_even(v, &m, &t);
    y = dh_q_rsqrt29(m, 3u);
    /* sqrt(m) = m y / 2^44 (m y < 2^61); times 2^(t/2) */
    r = (uint64_t)dh_q_mul64(m, y);
    sh = 44 - t / 2;
    if (sh > 0) return (uint32_t)((r + ((uint64_t)1 << (sh - 1))) >> (unsigned)sh);
    return (uint32_t)(r << (unsigned)(-sh));
}

/** round(n 2^frac / d), ties up, for d in [1, 2^31), frac <= 30 and
 *  n 2^frac / d below 2^31: the integer part by one 32-bit division, then one
 *  bit per step (r < d < 2^31, so 2 r fits). No 64-bit division. */
static inline uint32_t dh_q_udiv(uint32_t n, uint32_t d, unsigned frac)
{
    uint32_t q = n / d, r = n - q * d, i;
    for (i = 0u; i <= frac; i++) {
        r <<= 1;
        q <<= 1;
        if (r >= d) {
            r -= d;
            q |= 1u;
        }
    }
    return (q >> 1) + (q & 1u);
}

/* ---- kinematics helpers ---------------------------------------------------- */

/** The rotation check: 1 when the 3x3 with columns c0, c1, c2 (3 floats
 *  each) has every entry of R^T R - I within tol in magnitude and
 *  det R = c0 . (c1 x c2) > 0 (a reflection is not a rotation); 0 otherwise,
 *  also for NaN or overflowing products. */
DH_INLINE int dh_rot_cols_ok_f32(const float *c0, const float *c1, const float *c2, float tol)
{
    const float *col[3];
    unsigned a, b;
    col[0] = c0;
    col[1] = c1;
    col[2] = c2;
    for (a = 0; a < 3u; a++) {
        for (b = a; b < 3u; b++) {
            float d = col[a][0] * col[b][0] + col[a][1] * col[b][1] + col[a][2] * col[b][2];
            if (a == b) d -= 1.0f;
            if (!(fabsf(d) <= tol)) return 0;
        }
    }
    return (c0[0] * (c1[1] * c2[2] - c1[2] * c2[1]) + c0[1] * (c1[2] * c2[0] - c1[0] * c2[2]) +
            c0[2] * (c1[0] * c2[1] - c1[1] * c2[0])) > 0.0f;
}

/** An axis (v[0], v[1], v[2]) divided by its largest magnitude, so that its
 *  squares neither overflow nor underflow, and *len = its length then (in
 *  [1, sqrt 3]). DH_ERR_NAN for a NaN/Inf component, DH_ERR_ZERO_AXIS when
 *  the largest magnitude is below FLT_MIN; v and *len untouched then. */
DH_INLINE dh_status dh_axis_prescale_f32(float v[3], float *len)
{
    float m;
    if (!dh_isfinite_f32(v[0]) || !dh_isfinite_f32(v[1]) || !dh_isfinite_f32(v[2])) return DH_ERR_NAN;
    m = fabsf(v[0]);
    if (fabsf(v[1]) > m) m = fabsf(v[1]);
    if (fabsf(v[2]) > m) m = fabsf(v[2]);
    if (m < FLT_MIN) return DH_ERR_ZERO_AXIS;
    v[0] /= m;
    v[1] /= m;
    v[2] /= m;
    *len = dh_sqrt_f32(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return DH_OK;
}

/** The off-diagonal of R = S + [w]x, S symmetric with S01 = xy, S02 = xz,
 *  S12 = yz (+ 0.0f: no -0). */
DH_INLINE void dh_rot_offdiag_f32(dh_mat3_f32 *R, float xy, float xz, float yz, float wx, float wy,
                                  float wz)
{
    DH_M3(R, 0, 1) = (xy - wz) + 0.0f;
    DH_M3(R, 1, 0) = (xy + wz) + 0.0f;
    DH_M3(R, 0, 2) = (xz + wy) + 0.0f;
    DH_M3(R, 2, 0) = (xz - wy) + 0.0f;
    DH_M3(R, 1, 2) = (yz - wx) + 0.0f;
    DH_M3(R, 2, 1) = (yz + wx) + 0.0f;
}

/** Inlined in the default build (constant arguments such as the DH
 *  convention fold into each copy), one out-of-line copy in the size-first
 *  build. */
#if DH_FAST_PATHS
#define DH_SPEED_INLINE DH_INLINE
#else
#define DH_SPEED_INLINE static DH_NOINLINE
#endif

/** Unrolls the next loop 3 / 4 times with GCC when not optimising for
 *  size (constant offsets, no loop counter); nothing otherwise. */
#if defined(__GNUC__) && !defined(__clang__) && !defined(__OPTIMIZE_SIZE__)
#define DH_UNROLL3 _Pragma("GCC unroll 3")
#define DH_UNROLL4 _Pragma("GCC unroll 4")
#else
#define DH_UNROLL3
#define DH_UNROLL4
#endif

/* ---- closed-form IK helpers ----------------------------------------------- */

/** x (degrees, |x| < 900) shifted by a multiple of 360 into (-180, 180];
 *  exact: each step's result is smaller than x in magnitude and on the grid
 *  of x's ulp (360 is a multiple of it), so it is representable. */
DH_INLINE float dh_wrap180_f32(float x)
{
    float v = x;
    if (v > 180.0f) v -= 360.0f;
    if (v > 180.0f) v -= 360.0f;
    if (v <= -180.0f) v += 360.0f;
    if (v <= -180.0f) v += 360.0f;
    return v;
}

#endif /* DHMATH_SRC_DH_INTERNAL_H */
