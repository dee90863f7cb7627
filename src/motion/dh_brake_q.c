/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_brake_q.c - the fixed-point jerk-limited brake of s, shared by the
 * move executor (dh_move_q.c) and the queue (dh_queue_q.c, through the
 * executor's period steps): from s' = v0 >= 0 and s'' = a0 >= 0 to rest
 * in three phases, s''' = -J1 until s'' = -ap, s'' = -ap held, s''' =
 * +J3 back to 0 (method and proof in docs/design.md, "Lag on a
 * seven-phase path move"). Integer only: no float, no 64-bit division
 * (bit-serial quotients).
 *
 * Plan. The ideal brake at the limits A (of s'') and j (of s''') has
 * ap = min(A, sqrt(j v0 + a0^2 / 2)), phases (a0 + ap) / j, (j v0 +
 * a0^2 / 2 - ap^2) / (j ap) and ap / j (seconds), each rounded down to
 * whole us and 1 us added: D1, D2, D3. The level is then taken from them,
 * ap = floor((2 10^6 v0 + a0 D1) / (D1 + 2 D2 + D3)), which leaves s' at
 * the end the quotient's remainder over 2 10^6 (below (D1 + 2 D2 + D3) /
 * (2 10^6) LSB/s). D2 grows (by 1 + D2 / 8 us) until ap <= A,
 * (a0 + ap) 10^6 <= j D1 and ap 10^6 <= j D3: every phase then keeps
 * |s''| <= A and |s'''| <= j exactly.
 *
 * Evaluation. Phase k (2 10^6 s'_k = W_k, an exact integer; s''_k = a_k,
 * its change c_k over the phase) is the cubic s_k + P x + Q x^2 + R x^3
 * of x = (t - t_k) / D_k (Q2.30), P = s'_k D_k, Q = a_k D_k^2 / 2,
 * R = c_k D_k^2 / 6, in 2^-8 LSB, each rounded from a 96-bit product
 * divided bit-serially when the phase is entered (the period's frame
 * only multiplies); s_{k+1} is phase k's sum s_k + P + Q + R, so s is
 * continuous exactly.
 */
#include "dhmath/motion.h"
#include "../internal/dh_build.h"
#include "../internal/dh_qmath.h"
#include "motion_impl.h"

/* 2 10^12 / 2^8 and 6 10^12 / 2^8: the divisors of P, Q (2^-8 LSB) and R */
#define BRAKEQ_D2 7812500000u
#define BRAKEQ_D6 23437500000u
#define BRAKEQ_MEGA 1000000u
/* 2 10^12: (2 10^6 s') (us) into LSB */
#define BRAKEQ_T2 2000000000000u
/* the longest brake phase (us): a move's duration is below 2^31 us */
#define BRAKEQ_TMAX 0x40000000u

/* the uint64 in the two words p (low first), and its store (the struct
 * holds words: no 64-bit memory access, which the M4F makes with VFP) */
static uint64_t brakeq_get(const uint32_t *p)
{
    return ((uint64_t)p[1] << 32) | p[0];
}

static void brakeq_put(uint32_t *p, uint64_t v)
{
    p[0] = (uint32_t)v;
    p[1] = (uint32_t)(v >> 32);
}

/* floor((u 2^32 + w) / d) (up 1: rounded to nearest) for d in 1..2^63
 * and a quotient below 2^64: the 96 bits into a remainder below d, one
 * quotient bit per step (no division, no call) */
static DH_NOINLINE uint64_t brakeq_div96(uint64_t d, uint64_t u, uint32_t w, int up)
{
    uint64_t r = 0u, q = 0u;
    uint32_t i;
    for (i = 96u; i > 0u; i--) {
        const uint32_t sh = (i > 32u) ? i - 33u : i - 1u;
        uint32_t bit = (w >> (sh & 31u)) & 1u;
        if (i > 32u) {
            const uint64_t t = u >> sh;
            bit = (uint32_t)t & 1u;
        }
        r = (r << 1) | bit;
        q <<= 1;
        if (r >= d) {
            r -= d;
            q |= 1u;
        }
    }
    if (up != 0 && r >= d - r) q++;
    return q;
}

/* floor(x m / d) (up 1: rounded to nearest), brakeq_div96's bounds
 * (the 64-bit arguments first: in registers, not on the stack) */
DH_INLINE uint64_t brakeq_muldiv(uint64_t d, uint64_t x, uint32_t m, int up)
{
    const uint64_t lo = (uint64_t)(uint32_t)x * m;
    return brakeq_div96(d, (x >> 32) * m + (lo >> 32), (uint32_t)lo, up);
}

/* c x / 2^30 rounded (x Q2.30 in [0, 2^30], |c| below 2^61) */
static int64_t brakeq_mul30(int64_t c, uint32_t x)
{
    const uint64_t a = (c < 0) ? (uint64_t)0 - (uint64_t)c : (uint64_t)c;
    const uint64_t p = (((a >> 32) * x) << 2) + (((a & 0xFFFFFFFFu) * x + 0x20000000u) >> 30);
    return (c < 0) ? -(int64_t)p : (int64_t)p;
}

/* |s''| at the start of phase k (LSB/s^2): a0, ap, ap (signs +, -, -) */
static uint32_t brakeq_acc(const dh_brake_q *b, uint32_t k)
{
    return (k == 0u) ? (uint32_t)b->a0 : (uint32_t)b->ap;
}

/* term n (1: P, 2: Q, 3: R) of phase k into b->c (the file comment);
 * s'' changes by -(a0 + ap), 0, +ap over the three phases */
static DH_NOINLINE void brakeq_coef(dh_brake_q *b, uint32_t k, uint32_t n)
{
    const uint32_t D = b->d[k];
    uint64_t x = brakeq_get(b->w), v;
    uint64_t div = BRAKEQ_D2;
    int neg = 0;
    if (n == 2u) {
        x = (uint64_t)brakeq_acc(b, k) * D;
        neg = k != 0u;
    } else if (n == 3u) {
        x = (uint64_t)((k == 0u) ? (uint32_t)b->a0 + (uint32_t)b->ap : ((k == 1u) ? 0u : (uint32_t)b->ap)) * D;
        neg = k == 0u;
        div = BRAKEQ_D6;
    } else {
        /* P = W D / (2 10^12) */
    }
    v = brakeq_muldiv(div, x, D, 1);
    brakeq_put(&b->c[2u * n], (neg != 0) ? (uint64_t)0 - v : v);
}

/* phase k entered: its P, Q, R */
static void brakeq_enter(dh_brake_q *b, uint32_t k)
{
    uint32_t n;
    b->k = k;
    for (n = 1u; n <= 3u; n++) brakeq_coef(b, k, n);
}

void dh_motion_brake_seek_q_(dh_brake_q *b, uint32_t t)
{
    uint32_t t0 = 0u, k;
    for (k = 0u; k < b->k; k++) t0 += b->d[k];
    while (b->k < 2u && t >= t0 + b->d[b->k]) {
        const uint32_t D = b->d[b->k];
        const uint32_t dn = (b->k == 0u) ? (uint32_t)b->ap - (uint32_t)b->a0 : 2u * (uint32_t)b->ap;
        const uint32_t dp = (uint32_t)0 - dn;
        uint64_t w = brakeq_get(b->w);
        brakeq_put(b->c, brakeq_get(b->c) + brakeq_get(&b->c[2]) + brakeq_get(&b->c[4]) + brakeq_get(&b->c[6]));
        /* W_{k+1} = W_k + (a_k + a_{k+1}) D_k: a0 - ap, -2 ap, -ap */
        if (b->k == 0u && b->a0 >= b->ap)
            w += (uint64_t)dp * D;
        else
            w -= (uint64_t)dn * D;
        brakeq_put(b->w, w);
        t0 += D;
        brakeq_enter(b, b->k + 1u);
    }
}

int32_t dh_motion_brake_s_q_(const dh_brake_q *b, uint32_t t)
{
    uint32_t t0 = 0u, k, u, x, x2, x3;
    int64_t s;
    for (k = 0u; k < b->k; k++) t0 += b->d[k];
    u = (t > t0) ? t - t0 : 0u;
    x = (u >= b->d[b->k]) ? (uint32_t)DH_Q30_ONE : dh_q_ufloor30(u, b->d[b->k]);
    x2 = (uint32_t)(((uint64_t)x * x + 0x20000000u) >> 30);
    x3 = (uint32_t)(((uint64_t)x2 * x + 0x20000000u) >> 30);
    s = (int64_t)brakeq_get(b->c) + brakeq_mul30((int64_t)brakeq_get(&b->c[2]), x);
    s += brakeq_mul30((int64_t)brakeq_get(&b->c[4]), x2) + brakeq_mul30((int64_t)brakeq_get(&b->c[6]), x3);
    return (int32_t)dh_q_rshr(s, 8u);
}

/* a duration (us) of x 10^6 / d, rounded down and 1 us added, held to BRAKEQ_TMAX */
static DH_NOINLINE uint32_t brakeq_us(uint64_t d, uint64_t x)
{
    const uint64_t t = brakeq_muldiv(d, x, BRAKEQ_MEGA, 0) + 1u;
    return (t > BRAKEQ_TMAX) ? BRAKEQ_TMAX : (uint32_t)t;
}

/* the ideal level min(A, sqrt(j v0 + a0^2 / 2)), at least 1 */
static DH_NOINLINE uint32_t brakeq_peak(uint32_t v0, uint32_t a0, uint32_t A, uint32_t j)
{
    const uint32_t ap = dh_q_sqrt_u64((uint64_t)j * v0 + (((uint64_t)a0 * a0) >> 1));
    if (ap > A) return A;
    return (ap == 0u) ? 1u : ap;
}

/* the ideal hold (us): (2 j v0 + a0^2 - 2 ap^2) / (2 j ap), 0 when negative */
static DH_NOINLINE uint32_t brakeq_hold(uint32_t v0, uint32_t a0, uint32_t ap, uint32_t j)
{
    const uint64_t n2 = 2u * ((uint64_t)j * v0) + (uint64_t)a0 * a0, m2 = 2u * ((uint64_t)ap * ap);
    return (n2 > m2) ? brakeq_us(2u * ((uint64_t)j * ap), n2 - m2) : 0u;
}

/* 1 when ap = floor((W0 + a0 D1) / (D1 + 2 D2 + D3)) (W0 in b->w; the
 * file comment) meets ap <= A, (a0 + ap) 10^6 <= j D1 and ap 10^6 <= j D3
 * (b->ap then set) */
static DH_NOINLINE int brakeq_fits(dh_brake_q *b, uint32_t A, uint32_t j)
{
    const uint64_t num = brakeq_get(b->w) + (uint64_t)(uint32_t)b->a0 * b->d[0];
    const uint64_t ap = brakeq_div96((uint64_t)b->d[0] + 2u * (uint64_t)b->d[1] + b->d[2], num >> 32, (uint32_t)num, 0);
    if (ap > A) return 0;
    b->ap = (int32_t)ap;
    if (((uint64_t)(uint32_t)b->a0 + ap) * BRAKEQ_MEGA > (uint64_t)j * b->d[0]) return 0;
    return ap * BRAKEQ_MEGA <= (uint64_t)j * b->d[2];
}

dh_status dh_motion_brake_plan_q_(dh_brake_q *b, int32_t v0, int32_t a0, int32_t A, int32_t j)
{
    uint32_t n = 0u, ap;
    if (v0 < 0 || a0 < 0 || A <= 0 || j <= 0 || a0 > A) return DH_ERR_ARG;
    b->a0 = a0;
    brakeq_put(b->w, 2u * ((uint64_t)BRAKEQ_MEGA * (uint32_t)v0));
    /* the ideal brake's phase times (the file comment) */
    ap = brakeq_peak((uint32_t)v0, (uint32_t)a0, (uint32_t)A, (uint32_t)j);
    b->d[0] = brakeq_us((uint32_t)j, (uint64_t)(uint32_t)a0 + ap);
    b->d[2] = brakeq_us((uint32_t)j, ap);
    b->d[1] = brakeq_hold((uint32_t)v0, (uint32_t)a0, ap, (uint32_t)j);
    while (brakeq_fits(b, (uint32_t)A, (uint32_t)j) == 0) {
        b->d[1] += 1u + (b->d[1] >> 3);
        n++;
        if (n >= 256u || b->d[1] >= BRAKEQ_TMAX) return DH_ERR_OVERFLOW;
    }
    brakeq_put(b->c, 0u);
    brakeq_enter(b, 0u);
    return DH_OK;
}

uint32_t dh_motion_brake_dur_q_(const dh_brake_q *b)
{
    const uint64_t T = (uint64_t)b->d[0] + b->d[1] + b->d[2];
    return (T > (uint64_t)INT32_MAX) ? 0u : (uint32_t)T;
}

int32_t dh_motion_brake_reach_q_(const dh_brake_q *b)
{
    /* s' <= v0 + a0 D1 / (2 10^6) throughout (phase 0, w = W0): the
     * distance is at most that times the duration, rounded up */
    const uint64_t num = brakeq_get(b->w) + (uint64_t)(uint32_t)b->a0 * b->d[0];
    const uint64_t T = (uint64_t)b->d[0] + b->d[1] + b->d[2];
    const uint64_t r = brakeq_muldiv(BRAKEQ_T2, num, (T > 0xFFFFFFFFu) ? 0xFFFFFFFFu : (uint32_t)T, 0) + 1u;
    return (r > (uint64_t)INT32_MAX) ? INT32_MAX : (int32_t)r;
}
