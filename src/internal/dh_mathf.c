/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_mathf.c - libm-free float atan2, sin/cos (radians), atan2/asin/acos
 * in degrees and sqrt with a small stack (contracts in dh_mathf.h). Minimax coefficients (Lawson's
 * algorithm on the relative error, rounded to float):
 *   sin r = r + r z (S1 + z (S2 + z S3)),          |r| <= pi/4, z = r^2
 *   cos r = 1 - z/2 + z^2 (C1 + z (C2 + z C3))
 *   atan u = u + u z (T1 + z (T2 + ... + z T6)),   |u| <= 1/2
 * 2/pi (224 bits) and pi/2 (64 bits) as in the published expansion
 * 0.A2F9836E 4E441529 ...
 */

#include "dh_mathf.h"
#include "dh_floatops.h"


#define DH_MF_SIGN 0x80000000u
#define DH_MF_ABS 0x7FFFFFFFu
#define DH_MF_INF 0x7F800000u
#define DH_MF_ONE 0x3F800000u /* 1.0f */
#define DH_MF_PIO4_BITS 0x3F490FDAu /* largest float below pi/4 */

/* ---- atan2 ---------------------------------------------------------------- */

/*
 * The one atan2 body, shared by the radian result (dh_atan2f_) and the
 * degree result (dh_atan2f_deg_): the reduction of a non-NaN (y, x) to
 * angle = K pi/4 + (-1)^sneg (u + c), c = u z P(z) the polynomial's
 * correction, and (lo != 0) the tail ul of the reduced argument, u + ul
 * within ~2^-46 relative of the exact u. The tail needs the exact products
 * of mathf_two_prod, which the caller keeps in range (dh_atan2f_deg_ scales
 * max(|x|, |y|) into [1, 2) and leaves min/max >= 2^-61).
 */
typedef struct {
    float u, c, ul;
    uint32_t k, sneg;
} mathf_atan_parts;

/* a b = *hi + *lo exactly (Dekker's product: Veltkamp's split into 12-bit
 * halves, whose products are exact floats); |a|, |b| < 2^100, and the
 * products of the halves at least 2^-100 or zero. */
static void mathf_two_prod(float a, float b, float *hi, float *lo)
{
    float t = 4097.0f * a, ah = t - (t - a), al = a - ah;
    float v = 4097.0f * b, bh = v - (v - b), bl = b - bh;
    float p = a * b;
    *hi = p;
    *lo = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
}

DH_INLINE void mathf_atan2_parts(float y, float x, int lo, mathf_atan_parts *r)
{
    uint32_t xb = dh_f32_bits(x), yb = dh_f32_bits(y);
    uint32_t ax_b = xb & DH_MF_ABS, ay_b = yb & DH_MF_ABS;
    uint32_t xn, w, b, sneg, k;
    float ax, ay, mn, mx, u, z, ul = 0.0f;

    ax = dh_f32_from_bits(ax_b);
    ay = dh_f32_from_bits(ay_b);
    xn = xb >> 31;                     /* x negative (or -0): the left half-plane */
    w = (ay_b > ax_b) ? 1u : 0u;       /* |y| > |x|: reflected about the diagonal */
    mx = w ? ay : ax;
    mn = w ? ax : ay;
    if (ax_b == ay_b) {
        /* equal magnitudes (0, pi, pi/4, 3 pi/4): no 0/0, no inf - inf */
        b = (ax_b != 0u) ? 1u : 0u;
        u = 0.0f;
    } else if ((w ? ay_b : ax_b) < DH_MF_INF && mn + mn >= mx) {
        /* ratio in [1/2, 1) (2 mn: exact or inf, unlike 0.5f mx): pi/4 +
         * atan(u), u = (mn - mx) / (mn + mx) in [-1/3, 0), exact numerator,
         * the denominator's rounding error recovered (Fast2Sum) and
         * divided out; scaled by 1/4 near the top (exact) against overflow. */
        float n, d, e;
        if (mx > 0x1.0p+126f) {
            mx *= 0.25f;
            mn *= 0.25f;
        }
        b = 1u;
        n = mn - mx;
        d = mx + mn;
        e = mn - (d - mx);             /* mx + mn == d + e exactly */
        u = n / d;
        u = u - u * (e / d);           /* n / (d + e) to first order, |e / d| <= 2^-24 */
        if (lo) {
            /* ul = (n - u (d + e)) / (d + e): n - u d exactly from the
             * product (n - ph exact: ph is within a few ulp of n) */
            float ph, pl;
            mathf_two_prod(u, d, &ph, &pl);
            ul = (((n - ph) - pl) - u * e) / d;
        }
    } else {
        b = 0u;
        u = mn / mx;                   /* in [0, 1/2); mx > 0 here; 0 when mx is inf */
        if (lo) {
            float ph, pl;              /* ul = (mn - u mx) / mx, mn - ph exact */
            mathf_two_prod(u, mx, &ph, &pl);
            ul = ((mn - ph) - pl) / mx;
        }
    }
    z = u * u;
    r->u = u;
    r->ul = ul;
    r->c = u * (z * (DH_MF_T1 + z * (DH_MF_T2 + z * (DH_MF_T3 + z * (DH_MF_T4 + z * (DH_MF_T5 + z * DH_MF_T6))))));

    /* angle = K pi/4 + s atan(u):
     *   x >= 0, |y| <= |x|: K = b,      s = +    x >= 0, |y| > |x|: K = 2 - b, s = -
     *   x <  0, |y| <= |x|: K = 4 - b,  s = -    x <  0, |y| > |x|: K = 2 + b, s = + */
    sneg = w ^ xn;
    k = (w ? 2u : (xn ? 4u : 0u));
    r->k = sneg ? k - b : k + b;
    r->sneg = sneg;
}

float dh_atan2f_(float y, float x)
{
    /* K pi/4 = hi[K] + lo[K] (nearest floats), K = 0..4 */
    static const float pio4_hi[5] = {
        0.0f, 0x1.921fb6p-1f, 0x1.921fb6p+0f, 0x1.2d97c8p+1f, 0x1.921fb6p+1f
    };
    static const float pio4_lo[5] = {
        0.0f, -0x1.777a5cp-26f, -0x1.777a5cp-25f, -0x1.99bc5cp-28f, -0x1.777a5cp-24f
    };
    uint32_t ax_b = dh_f32_bits(x) & DH_MF_ABS, ay_b = dh_f32_bits(y) & DH_MF_ABS;
    mathf_atan_parts pt;
    float p, a;

    if (ax_b > DH_MF_INF || ay_b > DH_MF_INF) return x + y; /* NaN in, NaN out */
    mathf_atan2_parts(y, x, 0, &pt);
    p = pt.u + pt.c;
    if (pt.sneg) p = -p;
    {
        /* hi + p, error recovered (Fast2Sum: |hi| >= |p| if hi != 0), lo
         * added to the error: one final rounding */
        float hi = pio4_hi[pt.k], sum = hi + p;
        float err = p - (sum - hi);
        a = sum + (err + pio4_lo[pt.k]); /* >= 0 */
    }
    return dh_f32_from_bits(dh_f32_bits(a) ^ (dh_f32_bits(y) & DH_MF_SIGN));
}

float dh_atan2f_dg_(float y, float x)
{
    return dh_atan2f_dg_fb_inl_(y, x, 45.0f);
}

/* 180 / pi = DH_MF_R_HI + DH_MF_R_LO (+ 2.0e-15) */
#define DH_MF_R_HI 0x1.ca5dc2p+5f
#define DH_MF_R_LO (-0x1.670f82p-21f)

/* (mantissa with the implicit bit, unbiased exponent) of a positive finite
 * float (bits b), subnormals normalised: b = m 2^(e - 23), m in [2^23, 2^24) */
static uint32_t mathf_mant(uint32_t b, int32_t *e)
{
    int32_t ex = (int32_t)(b >> 23);
    uint32_t m = b & 0x007FFFFFu;
    if (ex == 0) {
        ex = 1;
        while ((m & 0x00800000u) == 0u) {
            m <<= 1;
            ex--;
        }
    } else {
        m |= 0x00800000u;
    }
    *e = ex - 127;
    return m;
}

/*
 * Degrees (method in dh_mathf.h). x and y are replaced by x 2^-E, y 2^-E
 * (exact; E the exponent of the larger): the larger magnitude in [1, 2),
 * the smaller one kept when min/max >= 2^-60 (exponent difference
 * dexp <= 60). Then (sign s, K from the shared reduction)
 *   deg = 45 K + s (R_hi u + R_hi (ul + c) + R_lo u) + corr,
 * with R_hi u exact (hi + lo), 45 K + hi by Fast2Sum (|hi| <= 28.7 < 45
 * when K != 0) and every small term added to its error: one final
 * rounding. Error before it (|u| <= 1/2, worst near |deg| = 26.6, in ulp
 * of the result): polynomial 0.07, the rounding of c and of R_hi c 0.25,
 * the tail sums < 0.05: < 0.4 ulp before the rounding, so the result is
 * within 1 ulp of the correctly rounded value. dexp > 60: atan(u) = u to
 * 2^-118 relative; 90 or 180 (correctly rounded: the tiny part, below
 * 2^-53 deg, is far below half an ulp of either) or s R q 2^-dexp with
 * q = my / mx in [1/2, 2) as R q (hi + lo) rounded once, then scaled (a
 * second rounding only for a subnormal result: within 1 ulp again); corr is
 * not added there (see the contract).
 */
float dh_atan2f_deg_(float y, float x, float corr)
{
    uint32_t xb = dh_f32_bits(x), yb = dh_f32_bits(y);
    uint32_t ax_b = xb & DH_MF_ABS, ay_b = yb & DH_MF_ABS;
    uint32_t big = (ay_b > ax_b) ? ay_b : ax_b, sml = (ay_b > ax_b) ? ax_b : ay_b;
    uint32_t mb, ms, sb, ss, res;
    int32_t eb, es = 0, dexp;
    mathf_atan_parts pt;
    float a;

    mb = mathf_mant(big, &eb);
    ms = (sml != 0u) ? mathf_mant(sml, &es) : 0u;
    dexp = (sml != 0u) ? eb - es : 255;
    sb = DH_MF_ONE | (mb & 0x007FFFFFu);                        /* big 2^-E */
    if (dexp <= 60 || ax_b > ay_b) {
        /* the shared reduction on the scaled pair (the smaller one exact
         * and normal, or +0); for dexp > 60 with |y| < |x| only the sign
         * of x matters (K = 0 or 4) */
        ss = (dexp <= 60) ? (((127u - (uint32_t)dexp) << 23) | (ms & 0x007FFFFFu)) : 0u;
        if (ay_b > ax_b) {
            mathf_atan2_parts(dh_f32_from_bits(sb), dh_f32_from_bits(ss | (xb & DH_MF_SIGN)), 1, &pt);
        } else {
            mathf_atan2_parts(dh_f32_from_bits(ss), dh_f32_from_bits(sb | (xb & DH_MF_SIGN)), 1, &pt);
        }
    } else {
        /* |y| >> |x|: 90 (the tiny part is below half an ulp of 90) */
        pt.k = 2u;
        pt.sneg = 0u;
        pt.u = 0.0f;
        pt.c = 0.0f;
        pt.ul = 0.0f;
    }
    if (dexp > 60 && sml != 0u && pt.k == 0u) {
        /* y tiny against x > 0: R q 2^-dexp */
        float fx = dh_f32_from_bits(sb), fy = dh_f32_from_bits(DH_MF_ONE | (ms & 0x007FFFFFu));
        float q = fy / fx, ph, pl, ql, v;
        mathf_two_prod(q, fx, &ph, &pl);
        ql = ((fy - ph) - pl) / fx;
        mathf_two_prod(DH_MF_R_HI, q, &ph, &pl);
        v = ph + (pl + (DH_MF_R_HI * ql + DH_MF_R_LO * q));         /* in [28, 115) */
        v *= 0x1.0p-60f;                                            /* exact */
        dexp -= 60;
        a = (dexp > 100) ? 0.0f : v * dh_f32_from_bits((127u - (uint32_t)dexp) << 23);
    } else {
        float ph, pl, tail, base = 45.0f * (float)pt.k, sum, err;
        mathf_two_prod(DH_MF_R_HI, pt.u, &ph, &pl);
        tail = pl + (DH_MF_R_HI * (pt.ul + pt.c) + DH_MF_R_LO * pt.u);
        if (pt.sneg) {
            ph = -ph;
            tail = -tail;
        }
        sum = base + ph;
        err = ph - (sum - base);
        a = sum + ((err + tail) + corr);
    }
    res = dh_f32_bits(a);
    return dh_f32_from_bits((res & DH_MF_ABS) ^ (yb & DH_MF_SIGN));
}

/*
 * asin / acos: with a = |v|, t = 1 - a^2 = th + tl to ~2^-46 relative
 * ((1 - a)(1 + a) for a >= 1/2: 1 - a exact, 1 + a by Fast2Sum; else
 * 1 - a^2 with a^2 exact), r = sqrt(th) correctly rounded and rl = (t - r^2)
 * / (2 r) (r^2 exact, th - r^2 exact: Sterbenz), so r + rl = sqrt(t) to
 * ~2^-46. asin a = atan2(a, r + rl) = atan2(a, r) - a rl / (a^2 + r^2)
 * (radians; a^2 + r^2 = 1 to 2^-23, the second order 2^-48), acos v =
 * atan2(r + rl, v) = atan2(r, v) + v rl: the first-order terms times 180/pi
 * are the corr of dh_atan2f_deg_ (|corr| <= 2^-22 |result|).
 */
float dh_asinf_deg_(float v, unsigned want_acos)
{
    uint32_t vb = dh_f32_bits(v);
    float a = dh_f32_from_bits(vb & DH_MF_ABS), th, tl, r, rl = 0.0f, ph, pl, deg;

    if (a >= 0.5f) {
        float p = 1.0f - a, qh = 1.0f + a, ql = a - (qh - 1.0f);
        mathf_two_prod(p, qh, &th, &tl);
        tl += p * ql;
    } else {
        float sh, sl;
        mathf_two_prod(a, a, &sh, &sl);
        th = 1.0f - sh;
        tl = ((1.0f - th) - sh) - sl;
    }
    r = dh_sqrtf_(th);
    if (!dh_feq_f32(th, 0.0f)) {
        mathf_two_prod(r, r, &ph, &pl);
        rl = (((th - ph) - pl) + tl) / (r + r);
    }
    if (want_acos != 0u) {
        return dh_atan2f_deg_(r, v, DH_MF_R_HI * (v * rl));
    }
    deg = dh_atan2f_deg_(a, r, -DH_MF_R_HI * (a * rl));
    return dh_f32_from_bits(dh_f32_bits(deg) ^ (vb & DH_MF_SIGN));
}

/* ---- sin / cos ------------------------------------------------------------ */

/* v 2^-63 as a float, rounded to nearest even, for 0 <= v < 2^63 (by hand:
 * libgcc's __aeabi_ul2f is stack-hungry on Cortex-M0+). A rounding carry
 * into 2^24 carries into the exponent field, which is right. */
static float mathf_q63_to_float(uint64_t v)
{
    uint32_t e = 63u, mant;
    uint64_t rest;
    if (v == 0u) return 0.0f;
    if ((v >> 32) == 0u) { v <<= 32; e -= 32u; }
    if ((v >> 48) == 0u) { v <<= 16; e -= 16u; }
    if ((v >> 56) == 0u) { v <<= 8; e -= 8u; }
    if ((v >> 60) == 0u) { v <<= 4; e -= 4u; }
    if ((v >> 62) == 0u) { v <<= 2; e -= 2u; }
    if ((v >> 63) == 0u) { v <<= 1; e -= 1u; }
    mant = (uint32_t)(v >> 40);              /* 2^23 .. 2^24 - 1 */
    rest = v << 24;                          /* the 40 bits below, as a 64-bit fraction */
    if (rest > 0x8000000000000000u || (rest == 0x8000000000000000u && (mant & 1u) != 0u)) mant++;
    /* 1.m 2^(e - 63): biased exponent e + 64, minus the leading bit's 1 */
    return dh_f32_from_bits(((e + 63u) << 23) + mant);
}

/*
 * Exact reduction of a finite a = |x| > pi/4 (bits mag): r in [-pi/4, pi/4]
 * and quadrant q with a = (4 j + q) pi/2 + r. a = M 2^e (e = exponent -
 * 150); the bits b_{e-1} .. b_{e+94} of 2/pi form W (earlier terms are
 * multiples of 4), tail error < 2^-70. Bits 95..94 of M W are q, bits
 * 93..30 a 64-bit fraction f (f >= 1/2: f - 1 and the next quadrant),
 * r = f pi/2 in fixed point, rounded once. The leading zero word makes the
 * window at s0 = e + 30 (6..134) need no special case.
 */
static DH_NOINLINE float mathf_reduce(uint32_t mag, uint32_t *quad)
{
    static const uint32_t two_over_pi[8] = {
        0x00000000u, 0xA2F9836Eu, 0x4E441529u, 0xFC2757D1u,
        0xF534DDC0u, 0xDB629599u, 0x3C439041u, 0xFE5163ABu
    };
    /* round(pi/2 2^63) */
    const uint64_t pio2_q63 = 0xC90FDAA22168C235u;
    uint32_t s0 = (mag >> 23) - 120u;    /* e + 30 = exponent - 150 + 30 */
    uint32_t wi = s0 >> 5, sh = s0 & 31u;
    uint32_t m = (mag & 0x007FFFFFu) | 0x00800000u;
    uint32_t w0, w1, w2, q, neg;
    uint64_t lo, mid, hi, t, u, f, fa, fb, pa, pb, lh, hl;
    float r;

    /* (v << sh) | (next >> (32 - sh)) without a shift by 32 when sh == 0 */
    w0 = (two_over_pi[wi] << sh) | ((two_over_pi[wi + 1u] >> 1) >> (31u - sh));
    w1 = (two_over_pi[wi + 1u] << sh) | ((two_over_pi[wi + 2u] >> 1) >> (31u - sh));
    w2 = (two_over_pi[wi + 2u] << sh) | ((two_over_pi[wi + 3u] >> 1) >> (31u - sh));
    lo = (uint64_t)m * w2;
    mid = (uint64_t)m * w1;
    hi = (uint64_t)m * w0;
    t = mid + (lo >> 32);                /* < 2^57: no carry lost */
    u = hi + (t >> 32);                  /* bits 64.. of the product */
    q = (uint32_t)(u >> 30) & 3u;
    f = (u << 34) | ((t & 0xFFFFFFFFu) << 2) | ((lo & 0xFFFFFFFFu) >> 30);
    neg = (uint32_t)(f >> 63);
    q = (q + neg) & 3u;
    if (neg) f = (~f) + 1u;              /* |f - 2^64|, <= 2^63 */
    /* r 2^63 = floor(f pio2_q63 / 2^64), the high half of the 128-bit
     * product; then one rounding to float */
    fa = f >> 32;
    fb = f & 0xFFFFFFFFu;
    pa = pio2_q63 >> 32;
    pb = pio2_q63 & 0xFFFFFFFFu;
    lh = fb * pa;
    hl = fa * pb;
    t = ((fb * pb) >> 32) + (lh & 0xFFFFFFFFu) + (hl & 0xFFFFFFFFu);
    u = fa * pa + (lh >> 32) + (hl >> 32) + (t >> 32);
    r = mathf_q63_to_float(u);          /* u < 2^63: r in [0, pi/4] */
    *quad = q;
    return neg ? -r : r;
}

void dh_sincosf_(float x, float *s, float *c)
{
    uint32_t xb, mag, q = 0u, sb, cb, swap;
    float r, sp, cp;

    DH_ASSERT(s != NULL);
    DH_ASSERT(c != NULL);
    xb = dh_f32_bits(x);
    mag = xb & DH_MF_ABS;
    if (mag >= DH_MF_INF) {
        *s = dh_f32_from_bits(0x7FC00000u);
        *c = *s;
        return;
    }
    if (mag <= DH_MF_PIO4_BITS) {
        r = dh_f32_from_bits(mag);        /* |x|; the sign is applied at the end */
    } else {
        r = mathf_reduce(mag, &q);
    }
    dh_sincosf_pio4_(r, &sp, &cp);
    /* quadrant q: (sin, cos) = (S, C), (C, -S), (-S, -C), (-C, S) */
    swap = q & 1u;
    sb = dh_f32_bits(swap ? cp : sp);
    cb = dh_f32_bits(swap ? sp : cp);
    sb ^= ((q >> 1) << 31) ^ (xb & DH_MF_SIGN);
    cb ^= (((q + 1u) >> 1) & 1u) << 31;
    *s = dh_f32_from_bits(sb);
    *c = dh_f32_from_bits(cb);
}

/*
 * Correctly rounded square root: VSQRT.F32 where the FPU has it
 * (DH_MATHF_VSQRT), else in integers: x = m 2^ex, the root of
 * M = m 2^K (K = 26 or 25: ex - K even, M in [2^48, 2^50)) bit by bit, 25
 * bits, the last one rounds (a float's root is never exactly half-way).
 */
#if DH_MATHF_VSQRT
float dh_sqrtf_(float x)
{
    float r;
    __asm__("vsqrt.f32 %0, %1" : "=t"(r) : "t"(x));
    return r;
}
#else
float dh_sqrtf_(float x)
{
    uint32_t u = dh_f32_bits(x), m, e, rem = 0u, root = 0u, i;
    int32_t eb;
    if ((u & 0x7FFFFFFFu) == 0u || u == 0x7F800000u) return x;      /* +-0, +Inf */
    if (u > 0x7F800000u) return dh_f32_from_bits(0x7FC00000u);        /* NaN, x < 0 */
    e = u >> 23;
    m = u & 0x007FFFFFu;
    eb = (int32_t)e;
    if (e == 0u) {          /* subnormal: normalise, eb may go down to -22 */
        eb = 1;
        while ((m & 0x00800000u) == 0u) {
            m <<= 1;
            eb--;
        }
    } else {
        m |= 0x00800000u;
    }
    /* M = mm 2^24, mm = m 2^(K - 24) < 2^26: 13 bit pairs of mm, 12 zero
     * pairs; one root bit per pair, remainder < 2^27 */
    m <<= (((uint32_t)eb & 1u) != 0u) ? 1u : 2u;
    for (i = 0; i < 25u; i++) {
        uint32_t trial;
        rem = (rem << 2) | ((i < 13u) ? (m >> (24u - 2u * i)) & 3u : 0u);
        trial = (root << 2) | 1u;
        if (rem >= trial) {
            rem -= trial;
            root = (root << 1) | 1u;
        } else {
            root <<= 1;
        }
    }
    /* root in [2^24, 2^25): round the last bit away; biased exponent
     * (eb + 152 - K) / 2 minus the implicit bit's 1 */
    m = (root >> 1) + (root & 1u);
    eb += (((uint32_t)eb & 1u) != 0u) ? (152 - 25) : (152 - 26);   /* >= 104, even */
    eb = (eb / 2) - 1;
    e = (uint32_t)eb;
    return dh_f32_from_bits((e << 23) + m);
}
#endif
