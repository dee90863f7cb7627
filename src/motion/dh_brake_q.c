/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_brake_q.c - the fixed-point jerk-limited brake of s, shared by the
 * move executor (dh_move_q.c) and the queue (dh_queue_q.c, through the
 * executor's period): from s' = v0 >= 0 and s'' = a0 >= 0 to rest in
 * three phases, s''' = -J1 until s'' = -ap, s'' = -ap held, s''' = +J3
 * back to 0 (method and proof in docs/design.md, "Fixed-point brake").
 * Integer only: no float, no 64-bit division (bit-serial quotients).
 *
 * Plan. The ideal brake at the limits A (of s'') and j (of s''') has
 * ap = min(A, sqrt(j v0 + a0^2 / 2)), phases (a0 + ap) / j, (j v0 +
 * a0^2 / 2 - ap^2) / (j ap) and ap / j (seconds). Its phase times
 * D1, D3 are rounded up to whole us (plus 1 us), D2 up, and then the
 * level is taken from them: ap = floor((2 10^6 v0 + a0 D1) / (D1 + 2 D2 +
 * D3)), which makes s' at the end 0 up to the quotient's remainder
 * (below (D1 + 2 D2 + D3) / (2 10^6) LSB/s). D2 grows (by 1 + D2 / 8 us)
 * until ap <= A, (a0 + ap) 10^6 <= j D1 and ap 10^6 <= j D3: every phase
 * then keeps |s''| <= A and |s'''| <= j exactly.
 *
 * Evaluation. Phase k (start state: 2 10^6 s'_k = W_k, an exact integer,
 * s''_k = a_k, its change c_k over the phase) is the cubic
 * s_k + P x + Q x^2 + R x^3 of x = (t - t_k) / D_k (Q2.30), P = s'_k D_k,
 * Q = a_k D_k^2 / 2, R = c_k D_k^2 / 6, each in 2^-8 LSB rounded to
 * nearest from a 96-bit product divided bit-serially; s_{k+1} is phase
 * k's sum P + Q + R, so s is continuous exactly and its rounding is
 * below 1 LSB per term.
 */
#include "dhmath/motion.h"
#include "../internal/dh_build.h"
#include "../internal/dh_qmath.h"
#include "motion_impl.h"

/* 2 10^12 / 2^8 and 6 10^12 / 2^8: the divisors of P, Q (2^-8 LSB) and R */
#define BRAKEQ_D2 7812500000u
#define BRAKEQ_D6 23437500000u
#define BRAKEQ_MEGA 1000000u
/* the longest brake phase (us): a move's duration is below 2^31 us */
#define BRAKEQ_TMAX 0x40000000u

/* floor(x m / d) (up 1: rounded to nearest) for d in 1..2^63 and a
 * quotient below 2^64: the 96-bit product's bits into a remainder below
 * d, one quotient bit per step (no division) */
static DH_NOINLINE uint64_t brakeq_muldiv(uint64_t x, uint32_t m, uint64_t d, int up)
{
    const uint64_t lo = (x & 0xFFFFFFFFu) * m, hi = (x >> 32) * m;
    const uint64_t mid = (lo >> 32) + (hi & 0xFFFFFFFFu);
    uint32_t w[3];
    uint64_t r = 0u, q = 0u;
    uint32_t i, b;
    w[0] = (uint32_t)((hi >> 32) + (mid >> 32));
    w[1] = (uint32_t)mid;
    w[2] = (uint32_t)lo;
    for (i = 0u; i < 3u; i++) {
        for (b = 32u; b > 0u; b--) {
            r = (r << 1) | ((w[i] >> (b - 1u)) & 1u);
            q <<= 1;
            if (r >= d) {
                r -= d;
                q |= 1u;
            }
        }
    }
    if (up != 0 && r >= d - r) q++;
    return q;
}

/* x m / d rounded to nearest, with the sign of x (|x| below 2^63) */
static int64_t brakeq_smuldiv(int64_t x, uint32_t m, uint64_t d)
{
    const uint64_t u = (x < 0) ? (uint64_t)0 - (uint64_t)x : (uint64_t)x;
    const uint64_t q = brakeq_muldiv(u, m, d, 1);
    return (x < 0) ? -(int64_t)q : (int64_t)q;
}

/* c x / 2^30 rounded (x Q2.30 in [0, 2^30], |c| below 2^61) */
static int64_t brakeq_mul30(int64_t c, uint32_t x)
{
    const uint64_t u = (c < 0) ? (uint64_t)0 - (uint64_t)c : (uint64_t)c;
    const uint64_t p = (((u >> 32) * x) << 2) + (((u & 0xFFFFFFFFu) * x + 0x20000000u) >> 30);
    return (c < 0) ? -(int64_t)p : (int64_t)p;
}

/* the brake's phase k: its duration, s'' at its start and its change */
static void brakeq_phase(const dh_brake_q *b, uint32_t k, uint32_t *D, int64_t *a, int64_t *c)
{
    *D = b->d[k];
    *a = (k == 0u) ? (int64_t)b->a0 : -(int64_t)b->ap;
    *c = (k == 0u) ? -((int64_t)b->a0 + b->ap) : ((k == 1u) ? 0 : (int64_t)b->ap);
}

/* The rise of s (2^-8 LSB) over phase k of the brake from its start to
 * x (Q2.30); *W = 2 10^6 s' at the phase's start, advanced to its end */
static DH_NOINLINE int64_t brakeq_rise(const dh_brake_q *b, uint32_t k, uint32_t x, int64_t *W)
{
    uint32_t D;
    int64_t a, c, P, Q, R, x2, x3;
    brakeq_phase(b, k, &D, &a, &c);
    P = brakeq_smuldiv(*W, D, BRAKEQ_D2);
    Q = brakeq_smuldiv(a * (int64_t)D, D, BRAKEQ_D2);
    R = brakeq_smuldiv(c * (int64_t)D, D, BRAKEQ_D6);
    *W += (2 * a + c) * (int64_t)D;
    x2 = brakeq_mul30((int64_t)x, x);
    x3 = brakeq_mul30(x2, x);
    return brakeq_mul30(P, x) + brakeq_mul30(Q, (uint32_t)x2) + brakeq_mul30(R, (uint32_t)x3);
}

int32_t dh_motion_brake_s_q_(const dh_brake_q *b, uint32_t t)
{
    int64_t W = 2 * (int64_t)BRAKEQ_MEGA * b->v0, s = 0;
    uint32_t k, u = t;
    for (k = 0u; k < 3u; k++) {
        const uint32_t D = b->d[k];
        if (u >= D) {
            s += brakeq_rise(b, k, DH_Q30_ONE, &W);
            u -= D;
        } else {
            s += brakeq_rise(b, k, dh_q_ufloor30(u, D), &W);
            break;
        }
    }
    return (int32_t)((s + 128) >> 8);
}

/* (a0 + ap) 10^6 <= j D1, ap 10^6 <= j D3 and ap <= A */
static int brakeq_fits(const dh_brake_q *b, int32_t A, int32_t j)
{
    const uint64_t jj = (uint32_t)j;
    if (b->ap > A) return 0;
    if (((uint64_t)(uint32_t)b->a0 + (uint32_t)b->ap) * BRAKEQ_MEGA > jj * b->d[0]) return 0;
    return (uint64_t)(uint32_t)b->ap * BRAKEQ_MEGA <= jj * b->d[2];
}

/* a duration (us) of x m / d, rounded up by 1 us and held to BRAKEQ_TMAX */
static uint32_t brakeq_us(uint64_t x, uint32_t m, uint64_t d)
{
    const uint64_t t = brakeq_muldiv(x, m, d, 0) + 1u;
    return (t > BRAKEQ_TMAX) ? BRAKEQ_TMAX : (uint32_t)t;
}

/* the ideal brake's level and its phase times rounded up (the file comment) */
static DH_NOINLINE void brakeq_ideal(dh_brake_q *b, int32_t A, int32_t j)
{
    const uint64_t jj = (uint32_t)j, v0 = (uint32_t)b->v0, a0 = (uint32_t)b->a0;
    const uint64_t n2 = 2u * jj * v0 + a0 * a0;
    uint64_t ap = dh_q_sqrt_u64(jj * v0 + ((a0 * a0) >> 1)), m2;
    if (ap > (uint32_t)A) ap = (uint32_t)A;
    if (ap == 0u) ap = 1u;
    m2 = 2u * ap * ap;
    b->d[0] = brakeq_us(a0 + ap, BRAKEQ_MEGA, jj);
    b->d[2] = brakeq_us(ap, BRAKEQ_MEGA, jj);
    b->d[1] = (n2 > m2) ? brakeq_us(n2 - m2, BRAKEQ_MEGA, 2u * jj * ap) : 0u;
}

dh_status dh_motion_brake_plan_q_(dh_brake_q *b, int32_t v0, int32_t a0, int32_t A, int32_t j)
{
    uint32_t n = 0u;
    if (v0 < 0 || a0 < 0 || A <= 0 || j <= 0 || a0 > A) return DH_ERR_ARG;
    b->v0 = v0;
    b->a0 = a0;
    brakeq_ideal(b, A, j);
    do {
        const uint64_t num = 2u * (uint64_t)BRAKEQ_MEGA * (uint32_t)v0 + (uint64_t)(uint32_t)a0 * b->d[0];
        const uint64_t den = (uint64_t)b->d[0] + 2u * (uint64_t)b->d[1] + b->d[2];
        const uint64_t ap = brakeq_muldiv(num, 1u, den, 0);
        b->ap = (ap > (uint32_t)INT32_MAX) ? INT32_MAX : (int32_t)ap;
        if (brakeq_fits(b, A, j)) return DH_OK;
        b->d[1] += 1u + (b->d[1] >> 3);
        n++;
    } while (n < 256u && b->d[1] < BRAKEQ_TMAX);
    return DH_ERR_OVERFLOW;
}
