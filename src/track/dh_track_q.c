/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_track_q.c - tracking IK in fixed point (integer only: no float, no
 * libm, no 64-bit division): dh_track_init_q, dh_track_step_q.
 *
 * The float tracker's method (dh_track.c, docs/design.md "Tracking") on
 * integers, with every bound exact:
 * - step box of joint i for this period: |s| <= dq_max = floor(vmax_q
 *   dt_us / 10^6); with an acceleration limit |s - v| <= A, A =
 *   floor(floor(amax_q dt_us / 10^6) dt_us / 10^6) (v the previous step);
 *   within the limits; and, with A, the braking condition: a step s
 *   towards a limit at distance D (before the step) satisfies
 *   s (s + 2 A) <= 2 A D, i.e. s <= isqrt(A^2 + 2 A D) - A (rounded down),
 *   which is s^2 <= 2 A (D - s): v^2 <= 2 amax (distance left), and the
 *   steps s - A, s - 2A, ... then stop the joint before the limit.
 *   The previous step braked by A keeps all of these, so the box is never
 *   empty.
 * - every step is clamped into the box in integers, so the bounds hold
 *   exactly, for every status.
 */
#include "dhmath/track.h"
#include "dhmath/frame.h"
#include "../internal/dh_qmath.h"
#include "../kin/kin_impl.h"
#include "../ikc/ikc_impl.h"
#include "../rot/rot_impl.h"

#define TRQ_DEG180 ((int32_t)180 << 16)   /* 180 deg, Q16.16 */
#define TRQ_NONE INT32_MAX   /* no acceleration limit */
#define TRQ_STEP_CAP (((int32_t)1 << 30) - 1)
#define TRQ_CF_POS 328        /* the closed form's FK bound, 5e-3 units at DH_QPOS_FRAC 16 (ikc.h), robots within 2^27 LSB */
#define TRQ_TIGHT 256         /* rotation orthonormal within 2^-22 (Q2.30): the closed form's bounds hold */
#define TRQ_CLAMPED 0x100u    /* private flag of t->sol: a value was moved onto a limit */

/* ---- integer helpers ----------------------------------------------------- */

/* floor(x / 10^6) for x < 2^63, by 32-bit divisions of 8-bit chunks. */
static uint64_t trq_div1e6(uint64_t x)
{
    uint64_t q = 0u;
    uint32_t r = 0u;
    int b;
    for (b = 56; b >= 0; b -= 8) {
        const uint32_t cur = (r << 8) | (uint32_t)((x >> (unsigned)b) & 0xFFu);
        q = (q << 8) | (cur / 1000000u);
        r = cur % 1000000u;
    }
    return q;
}

/* floor(x dt_us / 10^6) for 0 <= x < 2^31, saturated below INT32_MAX. */
static int32_t trq_per(int32_t x, uint32_t dt_us)
{
    const uint64_t v = trq_div1e6((uint64_t)(uint32_t)x * dt_us);
    return (v >= (uint64_t)INT32_MAX) ? INT32_MAX - 1 : (int32_t)v;
}

static int64_t trq_clamp64(int64_t x, int64_t lo, int64_t hi) { return (x < lo) ? lo : ((x > hi) ? hi : x); }

/* x 2^s, rounded (s < 0) or exact (s >= 0, small s). */
static int64_t trq_sh(int64_t x, int s)
{
    return (s >= 0) ? (int64_t)((uint64_t)x << (unsigned)s) : dh_q_rshr(x, (unsigned)(-s));
}

/* Largest s >= 0 with s (s + 2A) <= 2 A D (rounded down), D >= 0, A > 0. */
static int64_t trq_brake_max(int64_t A, int64_t D)
{
    const uint64_t a2 = (uint64_t)A * (uint64_t)A, ad = (uint64_t)A * (uint64_t)D;   /* < 2^62, < 2^63 */
    unsigned k = 0u;
    uint64_t x;
    for (;;) {
        /* each term below 2^61 before the sum: no wrap-around */
        const unsigned sh = 2u * k;
        const uint64_t u = a2 >> sh, w = ad >> sh;
        x = ((u >> 61) == 0u && (w >> 61) == 0u) ? u + (w << 1) : UINT64_MAX;
        if (x < ((uint64_t)1 << 62)) break;
        k++;
    }
    return ((int64_t)dh_q_isqrt62(x) << k) - A;
}

/* ---- setup ------------------------------------------------------------- */

/* Characteristic length L in dh_qpos: sum of |a|, |d|, the prismatic
 * travel (limited joints) and |tool p| (saturated at 2^30). */
static DH_NOINLINE int32_t trq_length(const dh_robot *r)
{
    int64_t L = 0;
    uint32_t i, k;
    for (i = 0u; i < r->n; i++) {
        const dh_joint *j = &r->joint[i];
        L += (int64_t)dh_q_abs_u32(j->a_q);
        L += (int64_t)dh_q_abs_u32(j->d_q);
        if (j->type == DH_JOINT_PRISMATIC && j->qmin_q <= j->qmax_q) L += (int64_t)j->qmax_q - j->qmin_q;
    }
    for (k = 0u; k < 3u; k++) L += (int64_t)dh_q_abs_u32(r->tool_q.p[k]);
    if (L < DH_QPOS_ONE) L = DH_QPOS_ONE;
    return (L > ((int64_t)1 << 30)) ? ((int32_t)1 << 30) : (int32_t)L;
}

/* The factor of the singularity bound without J (docs/design.md,
 * "Tracking in fixed point"): with D = diag(2^-k I3, I3) and M = D J,
 * sigma_min(J) >= min(1, 2^k) sigma_min(M), and sigma_min(M) = 1 /
 * |M^-1| >= |det M| / |adj M|_F, where row j of adj M (the cofactors of
 * column j) has the norm of the other five columns' volume, at most the
 * product of their norms (Hadamard): sigma_min(J) >= |det J| 2^-3k
 * min(1, 2^k) / sqrt(sum_j prod_{i != j} c_i), c_i >= |column i of M|^2 =
 * 1 + 2^-2k |linear part|^2 (revolute; the linear part at most the chain
 * after the axis long, R_i = sum over j >= i of |a_j| + |d_j| (+ the
 * prismatic travel) + |tool p| (each component)) or 2^-2k (prismatic).
 * k is the best of four, R_i 2^-k from at most 1 to at most 8; every
 * step rounded towards a smaller bound. hp_k 0: no bound (no model with
 * a |det J| formula, or a prismatic joint without limits). */
static uint32_t trq_hp_try(const uint32_t *R, uint32_t *c, uint32_t pris, int sh, int k, int32_t *e)
{
    uint64_t sum = 0u;
    uint32_t i, j;
    if (k < -3) return 0u;
    for (i = 0u; i < 6u; i++) {
        if ((pris >> i) & 1u) {
            c[i] = (k >= 4) ? 1u : ((uint32_t)1 << (unsigned)(8 - 2 * k));   /* 2^-2k in Q8, up */
        } else {
            const uint32_t x = (sh >= 0) ? (uint32_t)(((uint64_t)R[i] + (((uint64_t)1 << sh) - 1u)) >> sh)
                                         : ((R[i] >> (unsigned)(31 + sh)) != 0u ? 0xFFFFFFFFu : R[i] << (unsigned)(-sh));
            if (x > 128u) return 0u;   /* R 2^-k beyond 8 */
            c[i] = 256u + x * x;       /* Q8, below 2^15 */
        }
    }
    for (j = 0u; j < 6u; j++) {
        uint64_t p = 256u;
        for (i = 0u; i < 6u; i++)
            if (i != j) {
                /* p c rounded up, p below 2^8 65^5 < 2^39 and c below 2^15: in two halves */
                const uint64_t lo = (uint64_t)((uint32_t)p & 0xFFFFFFu) * c[i], hi = (p >> 24) * c[i];
                p = ((hi << 24) + lo + 255u) >> 8;
            }
        sum += p;
    }
    *e = -3 * k + ((k < 0) ? k : 0);
    /* 1 / sqrt(sum) in Q30: the root in Q8 rounded up */
    return dh_q_ufloor30(256u, dh_q_isqrt62(sum << 8) + 1u);
}

/* The chain lengths R_i (dh_qpos: sums of magnitudes) divided by 2^s0
 * rounded up, s0 the least shift that brings R_0 (the largest) below 2^31,
 * into t->gs[0..5] (the measures' scratch, free here); joint i prismatic:
 * bit i of *pris. Returns s0, or -1 for no bound (a prismatic joint
 * without limits). */
static uint64_t trq_hp_len(const dh_robot *r, uint32_t i)
{
    const dh_joint *j = &r->joint[i];
    uint64_t x = (uint64_t)dh_q_abs_u32(j->a_q) + dh_q_abs_u32(j->d_q);
    if (j->type == DH_JOINT_PRISMATIC)
        x += (dh_q_abs_u32(j->qmin_q) > dh_q_abs_u32(j->qmax_q)) ? dh_q_abs_u32(j->qmin_q) : dh_q_abs_u32(j->qmax_q);
    return x;
}

static DH_NOINLINE int trq_hp_chain(dh_track_q *t, uint32_t *pris)
{
    const dh_robot *const r = t->r;
    const uint64_t tool = (uint64_t)dh_q_abs_u32(r->tool_q.p[0]) + dh_q_abs_u32(r->tool_q.p[1]) +
                          dh_q_abs_u32(r->tool_q.p[2]);
    uint64_t acc = tool;
    uint32_t i;
    int s0 = 0;
    *pris = 0u;
    for (i = 0u; i < 6u; i++) {
        if (r->joint[i].type == DH_JOINT_PRISMATIC) {
            if (r->joint[i].qmin_q > r->joint[i].qmax_q) return -1;
            *pris |= 1u << i;
        }
        acc += trq_hp_len(r, i);
    }
    while ((acc >> s0) >= ((uint64_t)1 << 31)) s0++;
    acc = tool;
    for (i = 0u; i < 6u; i++) {
        const uint32_t j = 5u - i;
        acc += trq_hp_len(r, j);
        t->gs[j] = (int32_t)(uint32_t)((acc + (((uint64_t)1 << s0) - 1u)) >> s0);
    }
    return s0;
}

/* The rest of dh_track_init_q after the Jacobian at q0: t->jt, t->pris,
 * t->uni and the singularity bound's factor t->hp_k, t->hp_e. */
static DH_NOINLINE void trq_hp_init(dh_track_q *t)
{
    uint32_t pris = 0u, i;
    int k, k0, s0;
    t->jt = 1;
    t->pris = dh_kin_pris_q_(t->r);
    t->uni = 1;
    for (i = 1u; i < t->r->n; i++)
        if (t->r->joint[i].vmax_q != t->r->joint[0].vmax_q) t->uni = 0;
    t->hp_k = 0u;
    t->hp_e = 0;
    if (t->m == NULL || t->r->n != 6u || t->m->kind == DH_IKC_SCARA) return;
    s0 = trq_hp_chain(t, &pris);
    if (s0 < 0) return;
    /* k0: the smallest k with every R_i <= 2^k (R_0 the largest) */
    k0 = (int)dh_q_bitlen64((uint64_t)(uint32_t)t->gs[0]) + s0 - DH_QPOS_FRAC;
    for (k = k0 - 3; k <= k0; k++) {
        int32_t e = 0;
        /* R 2^-k in Q4: R' / 2^(k + F - 4 - s0) */
        const uint32_t v = trq_hp_try((const uint32_t *)t->gs, (uint32_t *)&t->gs[6], pris,
                                      k + DH_QPOS_FRAC - 4 - s0, k, &e);
        /* v 2^e above hp_k 2^hp_e? (both in [2^23, 2^30]: compare by shifts) */
        if (v != 0u && (t->hp_k == 0u || (e >= t->hp_e ? ((uint64_t)v << (unsigned)(e - t->hp_e > 40 ? 40 : e - t->hp_e)) > t->hp_k
                                                        : v > ((uint64_t)t->hp_k << (unsigned)(t->hp_e - e > 40 ? 40 : t->hp_e - e))))) {
            t->hp_k = v;
            t->hp_e = e;
        }
    }
}

dh_status dh_track_init_q(dh_track_q *t, const dh_robot *r, const dh_ikc_model_q *m, const int32_t *q0,
                          uint32_t dt_us)
{
    uint32_t i, n;
    int32_t L;
    dh_status st;
    DH_ASSERT(t != NULL);
    DH_ASSERT(r != NULL);
    DH_ASSERT(q0 != NULL);
    n = r->n;
    if (n == 0u || n > (uint32_t)DH_MAX_JOINTS || dt_us == 0u || dt_us > 1000000u) return DH_ERR_ARG;
    if ((r->flags & DH_ROBOT_HAS_Q) == 0u) return DH_ERR_UNAVAILABLE;
    if (m != NULL && (m->kind == DH_IKC_NONE || m->n != n)) return DH_ERR_ARG;
    st = dh_robot_check_limits_q(r, q0);
    if (st != DH_OK) return st;
    t->r = r;
    t->m = m;
    t->dt_us = dt_us;
    for (i = 0u; i < n; i++) {
        const dh_joint *j = &r->joint[i];
        t->q[i] = q0[i];
        t->v[i] = 0;
        t->dq_max[i] = (j->vmax_q >= INT32_MAX) ? INT32_MAX : trq_per(j->vmax_q, dt_us);
        t->dv_max[i] = (j->amax_q >= INT32_MAX) ? TRQ_NONE : trq_per(trq_per(j->amax_q, dt_us), dt_us);
    }
    L = trq_length(r);
    t->reach = L + (L >> 13);
    /* in J's units (length unit, rad), not scaled by L: the angular rows
     * do not grow with the length unit */
    t->lambda = (int32_t)(((int64_t)DH_QPOS_ONE * 1311) >> 16);          /* 0.02 */
    t->sing_threshold = (int32_t)(((int64_t)DH_QPOS_ONE * 328) >> 16);   /* 0.005 */
    /* the closed form's bound (at least 2^-19 L): OK without FK by default */
    t->cf_pos = TRQ_CF_POS * (int32_t)(((uint32_t)L + ((uint32_t)1 << 27) - 1u) >> 27);
    t->pos_tol = t->cf_pos;
    t->rot_tol = 10737;                                        /* 2e-5 rad, Q3.29 */
    t->qsv = 0;
    t->quv = 0;
    /* dh_jacobian_q in two private calls (its checks once here, then its
     * body writing FK straight into t->T), as in every step */
    if (dh_kin_jac_check_q_(r) != DH_OK || dh_kin_jac_q_(r, t->q, t->J, &t->T) != 0) return DH_ERR_OVERFLOW;
    trq_hp_init(t);
    return DH_OK;
}

/* ---- the step box ------------------------------------------------------ */

/* The step box of joint i into t->lo[i], t->hi[i]. */
static DH_NOINLINE void trq_box1(dh_track_q *t, uint32_t i)
{
    const dh_joint *j = &t->r->joint[i];
    const int64_t q = t->q[i], A = t->dv_max[i];
    const int lim = j->qmin_q <= j->qmax_q;
    /* a step is at most 2^30 - 1 LSB, and q + s stays within
     * [-INT32_MAX, INT32_MAX] */
    const int64_t cap = (t->dq_max[i] < TRQ_STEP_CAP) ? t->dq_max[i] : TRQ_STEP_CAP;
    int64_t lo = -cap, hi = cap;
    if ((int64_t)INT32_MAX - q < hi) hi = (int64_t)INT32_MAX - q;
    if (-(int64_t)INT32_MAX - q > lo) lo = -(int64_t)INT32_MAX - q;
    if (A != TRQ_NONE) {
        lo = (t->v[i] - A > lo) ? t->v[i] - A : lo;
        hi = (t->v[i] + A < hi) ? t->v[i] + A : hi;
        if (lim && A > 0) {
            const int64_t bh = trq_brake_max(A, (int64_t)j->qmax_q - q);
            const int64_t bl = -trq_brake_max(A, q - j->qmin_q);
            hi = (bh < hi) ? bh : hi;
            lo = (bl > lo) ? bl : lo;
        }
    }
    if (lim) {
        hi = ((int64_t)j->qmax_q - q < hi) ? (int64_t)j->qmax_q - q : hi;
        lo = ((int64_t)j->qmin_q - q > lo) ? (int64_t)j->qmin_q - q : lo;
    }
    if (lo > hi) {
        /* not reached (the braking step lies in the box); kept safe:
         * the previous velocity braked, within every bound it meets */
        lo = trq_clamp64(t->v[i] - trq_clamp64(t->v[i], -A, A), lo, hi);
        hi = lo;
    }
    t->lo[i] = (int32_t)lo;
    t->hi[i] = (int32_t)hi;
}

static DH_NOINLINE void trq_box(dh_track_q *t)
{
    uint32_t i;
    for (i = 0u; i < t->r->n; i++) trq_box1(t, i);
}

/* t->dq scaled by one factor in [0, 1] so that each entry stays within
 * its side of the box, then clamped into the box. */
static DH_NOINLINE void trq_fit(dh_track_q *t)
{
    uint32_t i, s = (uint32_t)1 << 30;
    for (i = 0u; i < t->r->n; i++) {
        const int32_t x = t->dq[i];
        if (x != 0) {
            const int32_t b = (x > 0) ? t->hi[i] : t->lo[i];
            const uint32_t ax = dh_q_abs_u32(x);
            const uint32_t lim = ((x > 0) == (b > 0)) ? dh_q_abs_u32(b) : 0u;
            if (lim < ax) {
                const uint32_t r = dh_q_ufloor30(lim, ax);
                if (r < s) s = r;
            }
        }
    }
    for (i = 0u; i < t->r->n; i++) {
        const int64_t p = dh_q_mul64(t->dq[i], (int32_t)s);
        const int64_t v = (p < 0) ? -((-p) >> 30) : (p >> 30);   /* toward 0 */
        t->dq[i] = (int32_t)trq_clamp64(v, t->lo[i], t->hi[i]);
    }
}

/* ---- closed form ---------------------------------------------------------- */

/* x shifted by 360 deg towards q when it is more than 180 deg from q and
 * the shifted value lies within j's limits widened by 8 LSB; else x
 * (values beyond 2^29 LSB, 8192 deg, are left as they are). */
static int32_t trq_turn(int32_t x, int32_t q, const dh_joint *j)
{
    const int32_t big = (int32_t)1 << 29;
    int32_t y = x;
    if (x > big || x < -big || q > big || q < -big) return x;
    if (x - q > TRQ_DEG180) y = x - 2 * TRQ_DEG180;
    if (x - q < -TRQ_DEG180) y = x + 2 * TRQ_DEG180;
    return (y + 8 >= j->qmin_q && y - 8 <= j->qmax_q) ? y : x;
}

/* 1 when value i of the solution is within the limits, a value beyond one
 * by at most 8 LSB (the closed form's rounding, 1.2e-4 deg) put on it
 * (flagged TRQ_CLAMPED); else 0. A revolute value more than 180 deg from
 * q is first shifted by 360 deg towards q when that lands within the
 * limits so widened (trq_turn): dh_ikc_q shifts a value just beyond a
 * limit by 360 deg into the range. */
static int trq_onto1(const dh_track_q *t, dh_ikc_sol_q *sol, uint32_t i)
{
    const dh_joint *j = &t->r->joint[i];
    const int32_t lo = j->qmin_q, hi = j->qmax_q;
    int32_t x = sol->q[i];
    if (lo > hi) return 1;
    if (j->type == DH_JOINT_REVOLUTE) x = trq_turn(x, t->q[i], j);
    /* beyond a limit by more than 8 LSB (exact unsigned distances) */
    if (x < lo || x > hi) {
        if ((x < lo ? (uint32_t)lo - (uint32_t)x : (uint32_t)x - (uint32_t)hi) > 8u) return 0;
        x = (x < lo) ? lo : hi;
        sol->flags |= TRQ_CLAMPED;
    }
    sol->q[i] = x;
    return 1;
}

/* a b exactly for a, b below 2^31 (a 32-bit multiply on every core) */
static int64_t trq_mul(uint32_t a, uint32_t b)
{
    return dh_q_mul64((int32_t)a, (int32_t)b);
}

/* The motion of the nearest solution since the last period, qn - t->qs,
 * into t->qu (t->quv 1) when t->qs holds the last period's (t->qsv) and
 * no joint of it moved more than its step bound; else t->quv 0. */
static void trq_motion(dh_track_q *t, const int32_t *qn)
{
    uint32_t i;
    int ok = t->qsv;
    for (i = 0u; i < t->r->n && ok; i++) {
        const int64_t u = (int64_t)qn[i] - t->qs[i];
        if (u > t->dq_max[i] || -u > t->dq_max[i]) ok = 0;
        else t->qu[i] = (int32_t)u;
    }
    t->quv = ok;
    t->qsv = 1;
}

/* The solution nearest t->q in time (largest |q*_i - q_i| / vmax_i, then
 * the sum of |q*_i - q_i|) among the st's t->ns solutions within the
 * limits (trq_onto1, joint by joint; a solution already slower than the
 * best is left there) into t->qs: 1 when there is one; t->unreach when there is no
 * solution or none within the limits. */
static DH_NOINLINE int trq_nearest(dh_track_q *t, dh_status st)
{
    const uint32_t n = t->r->n;
    uint32_t ns = t->ns, k, i, best = 0u;
    int64_t bs = 0;
    uint32_t btn = 0u, btd = 1u;   /* best time as a ratio btn / btd */
    int found = 0;
    if (st != DH_OK) ns = 0u;
    for (k = 0u; k < ns; k++) {
        uint32_t tn = 0u, td = 1u;
        int64_t sm = 0;
        /* joint by joint; a solution already slower than the best (one
         * rate) is left: it loses whatever its other joints */
        for (i = 0u; i < n && !(found && t->uni && tn > btn); i++) {
            uint32_t du, d, v;
            if (!trq_onto1(t, &t->sol[k], i)) break;
            /* |q*_i - q_i| exact in uint32, saturated at INT32_MAX */
            du = (t->sol[k].q[i] >= t->q[i]) ? (uint32_t)t->sol[k].q[i] - (uint32_t)t->q[i]
                                             : (uint32_t)t->q[i] - (uint32_t)t->sol[k].q[i];
            d = (du > (uint32_t)INT32_MAX) ? (uint32_t)INT32_MAX : du;
            v = (uint32_t)t->r->joint[i].vmax_q;
            sm += (int64_t)d;
            /* time d / v > tn / td ? (v INT32_MAX: unlimited, time 0);
             * every factor below 2^31: exact signed products; with one
             * rate for every joint (t->uni) the times compare as d */
            if (v < (uint32_t)INT32_MAX) {
                const int64_t now = t->uni ? (int64_t)d : trq_mul(d, td);
                const int64_t was = t->uni ? (int64_t)tn : trq_mul(tn, v);
                if (now > was) {
                    tn = d;
                    td = t->uni ? 1u : v;
                }
            }
        }
        if (i < n) continue;   /* beyond a limit, or slower */
        if (found) {
            /* tn / td against btn / btd, then the sums */
            const int64_t x = t->uni ? (int64_t)tn : trq_mul(tn, btd), y = t->uni ? (int64_t)btn : trq_mul(btn, td);
            if (x > y || (x == y && sm >= bs)) continue;
        }
        best = k;
        btn = tn;
        btd = td;
        bs = sm;
        found = 1;
    }
    t->unreach = (st == DH_ERR_UNREACHABLE || (st == DH_OK && !found)) ? 1 : 0;
    if (!found) {
        t->qsv = 0;
        return 0;
    }
    trq_motion(t, t->sol[best].q);
    for (i = 0u; i < n; i++) t->qs[i] = t->sol[best].q[i];
    t->clamp = (t->sol[best].flags & TRQ_CLAMPED) != 0u;
    return 1;
}

/* 1 when the closed form's argument checks pass and T06 is in t->sol (the
 * status in t->ist) */
static DH_NOINLINE int trq_ikc_args(dh_track_q *t)
{
    if (t->m == NULL) return 0;
    /* a tight target passes the closed form's own rigidity check */
    t->ist = t->tight ? dh_ikc_args_rigid_q_(t->m, t->tgt, t->sol)
                      : dh_ikc_args_q_(t->m, t->tgt, DH_IKC_KEEP_OUT_OF_LIMITS, t->sol);
    return (t->ist == DH_OK) ? 1 : 0;
}

/* The closed form's solution nearest in time (t->ist, t->ns: dh_ikc_q's
 * status and count) in t->qs (t->have, t->unreach) and the step towards
 * it clamped into the box: 1 when the box does not hold it (the target is
 * chased). */
static DH_NOINLINE int trq_pick(dh_track_q *t)
{
    uint32_t i;
    int reached = 0;
    if (t->m == NULL) return 1;
    t->have = trq_nearest(t, t->ist);
    if (t->have) {
        reached = 1;
        for (i = 0u; i < t->r->n; i++) {
            const int64_t s = (int64_t)t->qs[i] - t->q[i];
            if (s < t->lo[i] || s > t->hi[i]) reached = 0;
            t->dq[i] = (int32_t)trq_clamp64(s, t->lo[i], t->hi[i]);
        }
    }
    return !reached;
}

/* The step towards t->qs at the bound, each joint braking so as to stop
 * at its target value. When the solution moves from period to period
 * (t->quv: by t->qu, within the step bound), the braking is relative to
 * that motion: the step is u + w, w braking towards the distance left
 * after u, and each joint is clamped into its box, so that a solution
 * moving at a steady rate is caught instead of followed at a constant
 * lag. */
static DH_NOINLINE void trq_head(dh_track_q *t)
{
    uint32_t i;
    for (i = 0u; i < t->r->n; i++) {
        const int64_t u = t->quv ? t->qu[i] : 0, D = (int64_t)t->qs[i] - t->q[i] - u, A = t->dv_max[i];
        int64_t s = D;
        if (A != TRQ_NONE && A > 0) {
            const int64_t b = trq_brake_max(A, D < 0 ? -D : D);
            if (s > b) s = b;
            if (s < -b) s = -b;
        }
        s += u;
        t->dq[i] = (int32_t)(t->quv ? trq_clamp64(s, t->lo[i], t->hi[i]) : trq_clamp64(s, INT32_MIN + 1, INT32_MAX));
    }
    if (!t->quv) trq_fit(t);
}

/* ---- damped steps ---------------------------------------------------------- */

/* e[0..2] = position error of the target from t->T (dh_qpos), e[3..5]
 * the rotation error in t->rw; 0 when a component does not fit. */
static DH_NOINLINE int trq_epos(dh_track_q *t)
{
    uint32_t k;
    for (k = 0u; k < 3u; k++) {
        const int64_t d = (int64_t)t->tgt->p[k] - t->T.p[k];
        if (d > INT32_MAX || d < -(int64_t)INT32_MAX) return 0;
        t->e[k] = (int32_t)d;
    }
    t->e[3] = t->rw.x;
    t->e[4] = t->rw.y;
    t->e[5] = t->rw.z;
    return 1;
}

/* e = pose error of the target from t->T: position dh_qpos, rotation
 * Q3.29 rad; 0 when a component does not fit. */
static DH_NOINLINE int trq_error(dh_track_q *t)
{
    /* the target passed its check in trq_begin (every caller runs with
     * t->tst == DH_OK) */
    if (dh_kin_rot_error_to_q_(t->tgt, &t->T, &t->rD, &t->rw, t->rq) != DH_OK) return 0;
    return trq_epos(t);
}

/* |e|^2 / 2^8 with the rotation weighed by L (dh_qpos), each component
 * clamped to 2^31: below 2^57. */
static uint64_t trq_enorm2(const int32_t *e, int32_t L)
{
    uint64_t s = 0u;
    uint32_t k;
    for (k = 0u; k < 6u; k++) {
        int64_t x = (k < 3u) ? (int64_t)e[k] : (dh_q_mul64(e[k], L) >> 29);
        x = trq_clamp64(x, -(int64_t)INT32_MAX, INT32_MAX) >> 4;
        s += (uint64_t)(x * x);
    }
    return s;
}

/* Damping lambda sqrt(1 - x^2 + 2^-20), x = sigma / threshold clamped to
 * [0, 1]: full damping at a singularity, 2^-10 lambda away from one. */
static DH_NOINLINE int32_t trq_damping(const dh_track_q *t, int32_t sg)
{
    uint32_t x = (uint32_t)1 << 30, x2;
    if (sg < t->sing_threshold) x = dh_q_ufloor30((uint32_t)(sg < 0 ? 0 : sg), (uint32_t)t->sing_threshold);
    x2 = (uint32_t)(((uint64_t)x * x) >> 30);
    return (int32_t)(((uint64_t)(uint32_t)t->lambda *
                      dh_q_sqrt_u64((uint64_t)(((uint32_t)1 << 30) - x2 + 1024u) << 30)) >> 30);
}

/* r = e - J dq (the linearised residual of the step), into t->e. */
static DH_NOINLINE void trq_residual(dh_track_q *t)
{
    const uint32_t n = t->r->n;
    uint32_t i, k;
    for (k = 0u; k < 6u; k++) {
        int64_t s = 0;
        for (i = 0u; i < n; i++) {
            const int rev = t->r->joint[i].type == DH_JOINT_REVOLUTE;
            /* x: the step in rad or length units times 2^20 */
            const int32_t x = rev ? (int32_t)(dh_q_mul64(t->dq[i], 18740330) >> 26)     /* pi/180 in Q30 */
                                  : (int32_t)trq_sh(t->dq[i], 20 - DH_QPOS_FRAC);
            const int64_t p = dh_q_mul64(t->J[k * n + i], x);
            /* linear revolute: dh_qpos 2^20; angular: Q30 2^20 -> Q29; linear prismatic: Q30 2^20 -> dh_qpos */
            s += dh_q_rshr(p, (unsigned)((k < 3u) ? (rev ? 20 : 50 - DH_QPOS_FRAC) : 21));
        }
        t->e[k] = (int32_t)trq_clamp64((int64_t)t->e[k] - s, -(int64_t)INT32_MAX, INT32_MAX);
    }
}

/* 1 when the pose error in t->e is within pos_tol and rot_tol; its
 * squared position and rotation parts into *p2, *r2 */
static int trq_within(const dh_track_q *t, uint64_t *p2, uint64_t *r2)
{
    uint32_t k;
    *p2 = 0u;
    *r2 = 0u;
    for (k = 0u; k < 3u; k++) {
        *p2 += (uint64_t)dh_q_mul64(t->e[k], t->e[k]);
        *r2 += (uint64_t)dh_q_mul64(t->e[k + 3u], t->e[k + 3u]);
    }
    return (*p2 <= (uint64_t)dh_q_mul64(t->pos_tol, t->pos_tol) &&
            *r2 <= (uint64_t)dh_q_mul64(t->rot_tol, t->rot_tol)) ? 1 : 0;
}

/* The pose error into t->e, whether it is within the tolerances into
 * t->at, and the damping into t->lam (from t->sg): 1 when the error could
 * be computed. */
static DH_NOINLINE int trq_prep(dh_track_q *t)
{
    uint64_t p2, r2;
    if (!trq_error(t)) return 0;
    t->at = trq_within(t, &p2, &r2);
    t->lam = trq_damping(t, t->sg);
    if (t->lam < 1) t->lam = 1;
    return 1;
}

/* The damped step (dh_dls_step_q without a bound) into t->dq. */
static DH_NOINLINE dh_status trq_solve(dh_track_q *t)
{
    t->work.J = t->J;
    t->work.n = (uint8_t)t->r->n;
    t->work.dq_max = NULL;
    t->work.pris = t->pris;
    return dh_kin_dls_q_(&t->work, t->e, t->lam, t->dq);
}

/* A joint that cannot move the way the step wants (against a limit, or
 * braking) leaves the solve: its column is cleared (t->J is recomputed at
 * q_out). 1 when one did (the step is solved again for the others). */
static DH_NOINLINE int trq_block(dh_track_q *t)
{
    const uint32_t n = t->r->n;
    uint32_t i, k;
    int blocked = 0;
    for (i = 0u; i < n; i++)
        if ((t->dq[i] > 0 && t->hi[i] <= 0) || (t->dq[i] < 0 && t->lo[i] >= 0)) {
            for (k = 0u; k < 6u; k++) t->J[k * n + i] = 0;
            blocked = 1;
        }
    return blocked;
}

/* The damped step fitted into the box; 1 when it stalls (the linearised
 * error drops by less than a tenth). */
static DH_NOINLINE int trq_settle(dh_track_q *t)
{
    uint64_t e2;
    trq_fit(t);
    e2 = trq_enorm2(t->e, t->reach);
    trq_residual(t);
    return (trq_enorm2(t->e, t->reach) * 100u > e2 * 81u) ? 1 : 0;
}

/* No damped step: zero, fitted into the box; stalls. */
static DH_NOINLINE int trq_none(dh_track_q *t)
{
    uint32_t i;
    for (i = 0u; i < t->r->n; i++) t->dq[i] = 0;
    trq_fit(t);
    return 1;
}

/* Braking: each step towards 0 by at most A (at once without an
 * acceleration limit). */
static DH_NOINLINE void trq_brake(dh_track_q *t)
{
    uint32_t i;
    for (i = 0u; i < t->r->n; i++) {
        const int64_t A = t->dv_max[i], p = t->v[i];
        int64_t s = 0;
        if (A != TRQ_NONE) s = (p > A) ? p - A : ((p < -A) ? p + A : 0);
        t->dq[i] = (int32_t)trq_clamp64(s, t->lo[i], t->hi[i]);
    }
    t->unreach = 1;
}

/* Largest |qs_i - q_i - a dq_i| / w_i over the joints (a = 0 or 1) as
 * *num / *den, w_i = vmax_q (65536 when unlimited). */
static void trq_tmax(const dh_track_q *t, int a, uint32_t *num, uint32_t *den)
{
    uint32_t i, tn = 0u, td = 1u;
    for (i = 0u; i < t->r->n; i++) {
        const int64_t d64 = (int64_t)t->qs[i] - t->q[i] - (a ? t->dq[i] : 0);
        const uint32_t d = (uint32_t)trq_clamp64(d64 < 0 ? -d64 : d64, 0, INT32_MAX);
        const uint32_t w = (t->r->joint[i].vmax_q >= INT32_MAX) ? 65536u : (uint32_t)t->r->joint[i].vmax_q;
        if ((uint64_t)d * td > (uint64_t)tn * w) {
            tn = d;
            td = w;
        }
    }
    *num = tn;
    *den = td;
}

/* 1 when t->dq does not bring q nearer t->qs in time. */
static DH_NOINLINE int trq_away(const dh_track_q *t)
{
    uint32_t bn, bd, an, ad;
    trq_tmax(t, 0, &bn, &bd);
    trq_tmax(t, 1, &an, &ad);
    return (uint64_t)an * bd >= (uint64_t)bn * ad;
}

/* The next damped step starts from the point reached (no closed form):
 * t->J and t->T there, the box less the step so far (kept in t->keep). 0
 * when the Jacobian there saturates (the step so far is kept). */
static DH_NOINLINE int trq_shift(dh_track_q *t)
{
    const uint32_t n = t->r->n;
    uint32_t i;
    for (i = 0u; i < n; i++) {
        t->keep[i] = t->dq[i];
        t->qs[i] = t->q[i] + t->dq[i];
    }
    if (dh_kin_jac_q_(t->r, t->qs, t->J, &t->T) != 0) {
        for (i = 0u; i < n; i++) t->dq[i] = t->keep[i];
        return 0;
    }
    for (i = 0u; i < n; i++) {
        t->lo[i] -= t->keep[i];
        t->hi[i] -= t->keep[i];
    }
    return 1;
}

/* The box and the step back from the point reached. */
static DH_NOINLINE void trq_unshift(dh_track_q *t)
{
    uint32_t i;
    for (i = 0u; i < t->r->n; i++) {
        t->lo[i] += t->keep[i];
        t->hi[i] += t->keep[i];
        t->dq[i] += t->keep[i];
    }
}

/* 1 when the target's position is beyond the reach bound from the base. */
static DH_NOINLINE int trq_beyond(const dh_track_q *t)
{
    const dh_frame_q *const target = t->tgt;
    uint64_t s = 0u;
    uint32_t k;
    for (k = 0u; k < 3u; k++) {
        const int64_t d = (int64_t)target->p[k] - t->r->base_q.p[k];
        if (d > t->reach || d < -(int64_t)t->reach) return 1;
        s += (uint64_t)(d * d);
    }
    return s > (uint64_t)dh_q_mul64(t->reach, t->reach);
}

typedef char trq_gs_fits[(sizeof(((dh_track_q *)0)->gs) == DH_DLS_SAVE_Q * sizeof(int32_t)) ? 1 : -1];

/* dh_manipulability_q of t->J */
static DH_NOINLINE void trq_manip(dh_track_q *t, int32_t *w, int32_t *sigma_min)
{
    t->work.J = t->J;
    t->work.n = (uint8_t)t->r->n;
    dh_kin_manip_q_(&t->work, w, sigma_min, t->gs);
}

/* Away from singularities with a closed-form solution: straight for it
 * at the bound (1); else 0 (damped steps follow). */
static DH_NOINLINE int trq_straight(dh_track_q *t)
{
    if (!t->have || t->sg < t->sing_threshold) return 0;
    trq_head(t);
    return 1;
}

/* After the damped steps: with a closed-form solution, straight for it
 * when the step stalls or moves away from it; without a closed form,
 * UNREACHABLE beyond the reach bound. */
static DH_NOINLINE void trq_settled(dh_track_q *t)
{
    if (t->have) {
        if (t->stall || trq_away(t)) trq_head(t);
    } else {
        if (t->m == NULL && trq_beyond(t)) t->unreach = 1;
    }
}

/* The step's arguments and state into t; t->tst DH_OK for a rigid target
 * (rotation orthonormal within DH_ROT_ERROR_TOL_Q, det > 0), else
 * DH_ERR_NOT_RIGID. */
static DH_NOINLINE void trq_begin(dh_track_q *t, const dh_frame_q *target, int32_t *q_out, dh_track_report_q *rep)
{
    t->tgt = target;
    t->out = q_out;
    t->rep = rep;
    t->have = 0;
    t->at = 0;
    t->unreach = 0;
    t->ns = 0u;
    t->ist = DH_ERR_UNAVAILABLE;
    t->clamp = 0;
    t->cf = 0;
    t->tight = dh_rot_ok_q_(target, TRQ_TIGHT);
    t->tst = (t->tight || dh_kin_rot_ok_q_(target)) ? DH_OK : DH_ERR_NOT_RIGID;
}

/* J and T at q when a closed-form step left them at an earlier q */
static DH_NOINLINE void trq_need_j(dh_track_q *t)
{
    if (!t->jt) (void)dh_kin_jac_q_(t->r, t->q, t->J, &t->T);
    t->jt = 1;
}

/* q_out into t->q, t->v and q_out (the step clamped into the box) */
static DH_NOINLINE void trq_move(dh_track_q *t)
{
    uint32_t i;
    for (i = 0u; i < t->r->n; i++) {
        const int64_t s = trq_clamp64(t->dq[i], t->lo[i], t->hi[i]);
        const int32_t x = (int32_t)((int64_t)t->q[i] + s);
        t->v[i] = x - t->q[i];
        t->q[i] = x;
        t->out[i] = x;
    }
}

/* The report's defaults, t->J and t->T at q_out: 1 when they fit. */
static DH_NOINLINE int trq_at_out(dh_track_q *t)
{
    dh_track_report_q *const rep = t->rep;
    rep->manip = INT32_MIN;
    rep->sigma_min = 0;
    rep->pos_err = INT32_MAX;
    rep->rot_err = INT32_MAX;
    rep->measured = 1;
    t->jt = 1;
    return (dh_kin_jac_q_(t->r, t->q, t->J, &t->T) == 0) ? 1 : 0;
}

/* The report from the pose error at q_out in t->e (ok: 0 when there is
 * none): OK when within the tolerances. */
static DH_NOINLINE void trq_fill(const dh_track_q *t, int ok)
{
    dh_track_report_q *const rep = t->rep;
    const dh_status tst = t->tst;
    uint64_t p2 = 0u, r2 = 0u;
    int in = 0;
    if (ok) {
        in = trq_within(t, &p2, &r2);
        rep->pos_err = (int32_t)trq_clamp64(dh_q_sqrt_u64(p2), 0, INT32_MAX);
        rep->rot_err = (int32_t)trq_clamp64(dh_q_sqrt_u64(r2), 0, INT32_MAX);
    }
    if (in)
        rep->state = DH_TRACK_OK;
    else
        rep->state = (t->unreach || tst != DH_OK) ? DH_TRACK_UNREACHABLE : DH_TRACK_LAGGING;
    rep->near_singular = (rep->sigma_min < t->sing_threshold) ? 1 : 0;
}

/* 65536 log2(mant 2^ex), mant in [2^30, 2^31), from the top 16 bits of
 * mant by 16 squarings in 32 bits (x in Q15), each rounded down: below the
 * exact value by less than 8 LSB (the mantissa's truncation 2^-15 and the
 * squarings' add 2^-15 / ln 2 and at most as much again to the log). */
static int32_t trq_log2(uint32_t mant, int32_t ex)
{
    uint32_t x = mant >> 15, f = 0u, b;
    for (b = 0u; b < 16u; b++) {
        x = (x * x) >> 15;   /* x below 2^16: the square below 2^32 */
        f <<= 1;
        if (x >= 0x10000u) {
            x >>= 1;
            f |= 1u;
        }
    }
    return (ex + 30) * 65536 + (int32_t)f;
}

/* When q_out (t->q) is the nearest closed-form solution of the target
 * (t->cf): 1 when the report is complete without J or FK (the report filled: state OK,
 * the closed form's error bounds, the singularity bound without J). That
 * needs tolerances no tighter than the closed form's bounds, a target
 * orthonormal within 2^-22 and no value moved onto a limit (the closed
 * form's bounds are those of its own solutions), and a |det J| bound that
 * proves sigma_min >= sing_threshold. */
static DH_NOINLINE int trq_cf_done(dh_track_q *t)
{
    dh_track_report_q *const rep = t->rep;
    uint32_t mant;
    int32_t ex;
    int sh;
    int64_t v;
    if (!t->cf || !t->tight || t->clamp || t->hp_k == 0u || t->pos_tol < t->cf_pos || t->rot_tol < DH_TRACK_CF_ROT_Q) return 0;
    mant = dh_ikc_detj_q_(t->m, t->q, &ex);
    if (mant == 0u) return 0;
    /* sigma = mant 2^ex hp_k 2^(hp_e - 30) in dh_qpos, rounded down */
    v = dh_q_mul64((int32_t)mant, (int32_t)t->hp_k);
    sh = ex + t->hp_e - 30 + DH_QPOS_FRAC;
    if (sh >= 0)
        v = (sh >= 2) ? INT32_MAX : (v << sh);   /* v >= 2^30: shifted by 2 or more it saturates */
    else
        v = (sh <= -63) ? 0 : (v >> -sh);
    if (v > INT32_MAX) v = INT32_MAX;
    if (v < t->sing_threshold) return 0;
    rep->state = DH_TRACK_OK;
    rep->pos_err = t->cf_pos;
    rep->rot_err = DH_TRACK_CF_ROT_Q;
    rep->manip = trq_log2(mant, ex);
    rep->sigma_min = (int32_t)v;
    rep->near_singular = 0;
    rep->measured = 0;
    return 1;
}

/* The stages are called one after the other from here, each library call
 * at most one small frame below this function (the closed-form solver's
 * and its finish from here: dh_ikc_raw_q_ has no frame), with the state
 * in t, so the stack stays the deepest library call plus two small
 * frames. */
dh_status dh_track_step_q(dh_track_q *t, const dh_frame_q *target, int32_t *q_out, dh_track_report_q *rep)
{
    int k = 0;
    DH_ASSERT(t != NULL);
    DH_ASSERT(t->r != NULL);
    DH_ASSERT(target != NULL);
    DH_ASSERT(q_out != NULL);
    DH_ASSERT(rep != NULL);
    DH_ASSERT(t->r->n >= 1u && t->r->n <= (uint32_t)DH_MAX_JOINTS);
    trq_begin(t, target, q_out, rep);
    trq_box(t);
    if (t->tst != DH_OK) {
        trq_brake(t);
        t->qsv = 0;
    } else {
        if (trq_ikc_args(t)) {
            t->ist = dh_ikc_raw_q_(t->m, t->q, t->sol, &t->ns);
            if (t->ist == DH_OK) t->ist = dh_ikc_finish_q_(t->m, t->q, t->sol, &t->ns);
        }
        if (!trq_pick(t)) {
            t->cf = 1;
        } else {
            trq_need_j(t);
            trq_manip(t, NULL, &t->sg);
            /* q already reaching the target keeps its place (the zero
             * step fitted into the box): no run for a solution outside
             * the box that would lose the reached pose */
            if (trq_prep(t) && t->at) {
                (void)trq_none(t);
            } else if (!trq_straight(t)) {
                /* damped steps: one, or up to three without a closed form,
                 * each on the Jacobian of the point reached */
                for (;;) {
                    if (trq_prep(t) && trq_solve(t) == DH_OK && (!trq_block(t) || trq_solve(t) == DH_OK))
                        t->stall = trq_settle(t);
                    else
                        t->stall = trq_none(t);
                    if (k > 0) trq_unshift(t);
                    if (t->m != NULL || ++k > 2 || !trq_shift(t)) break;
                    trq_manip(t, NULL, &t->sg);
                }
                trq_settled(t);
            } else {
                /* straight for the closed-form solution (trq_straight) */
            }
        }
    }
    trq_move(t);
    t->jt = 0;
    if (trq_cf_done(t)) return DH_OK;
    k = trq_at_out(t);
    if (k) {
        trq_manip(t, &t->rep->manip, &t->rep->sigma_min);
        k = (t->tst == DH_OK) ? trq_error(t) : 0;
    }
    trq_fill(t, k);
    return t->tst;
}
