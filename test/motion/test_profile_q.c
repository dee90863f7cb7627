/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_profile_q.c - the fixed-point profiles (motion.h, "Fixed point")
 * against double-precision references computed here: the analytic minimum
 * durations (trapezoid: d/v + v/a when d >= v^2/a, else 2 sqrt(d/a); the
 * seven-phase closed forms), the positions of the ideal profiles stretched
 * to the returned duration, and the limits checked by finite differences
 * of the output over windows of a few periods.
 */
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_ref.h"
#include "dhmath/motion.h"

/* The duration quantum of the contracts: T within [Tmin, Tmin + 1 us +
 * 2^-26 Tmin]; positions within POS_LSB + 2^-25 |d| LSB of the ideal
 * profile (the eval's 4 + 2^-27 |d| and the ratios' rounding to 2^-30);
 * finite differences within 1e-3 relative of their limit once the
 * rounding of the positions over the window (k POS_LSB / h^n, k = 2, 4, 8
 * for the first, second, third difference) is taken out. */
#define POS_LSB 8.0
#define LIM_REL 1e-3

/* ideal rest-to-rest profile (double): phases of the first half */
typedef struct {
    double D, T, tj, ta, v, a, j;
} ref_prof;

/* the minimum-time trapezoid (j == 0: tj = 0) or seven-phase profile */
static void ref_plan(ref_prof *r, double D, double V, double A, double J)
{
    double tA = (J > 0.0) ? A / J : 0.0, tj, ta, tv;
    if (J > 0.0 && V * J < A * A) {
        tj = sqrt(V / J);
        ta = 2.0 * tj;
    } else {
        tj = tA;
        ta = tj + V / A;
    }
    tv = D / V - ta;
    if (tv < 0.0) {
        tv = 0.0;
        if (J <= 0.0) {
            tj = 0.0;
            ta = sqrt(D / A);
        } else if (D >= 2.0 * A * A * A / (J * J)) {
            tj = tA;
            ta = 0.5 * tj + sqrt(0.25 * tj * tj + D / A);
        } else {
            tj = cbrt(D / (2.0 * J));
            ta = 2.0 * tj;
        }
    }
    r->D = D;
    r->T = 2.0 * ta + tv;
    r->tj = tj;
    r->ta = ta;
}

/* r stretched to T (uniform time scaling) and its peaks */
static void ref_stretch(ref_prof *r, double T)
{
    const double k = T / r->T;
    r->tj *= k;
    r->ta *= k;
    r->T = T;
    r->v = r->D / (r->T - r->ta);
    r->a = r->v / (r->ta - r->tj);
    r->j = (r->tj > 0.0) ? r->a / r->tj : 0.0;
}

/* position of r at t (first half, mirrored) */
static double ref_pos(const ref_prof *r, double t)
{
    double tj = r->tj, ta = r->ta, v = r->v, a = r->a, j = r->j, u, p;
    int back = t > 0.5 * r->T;
    if (back) t = r->T - t;
    if (t < tj) {
        p = j * t * t * t / 6.0;
    } else if (t < ta - tj) {
        u = t - tj;
        p = a * tj * tj / 6.0 + 0.5 * a * tj * u + 0.5 * a * u * u;
    } else if (t < ta) {
        u = ta - t;
        p = 0.5 * v * ta - v * u + j * u * u * u / 6.0;
    } else {
        p = 0.5 * v * ta + v * (t - ta);
    }
    return back ? r->D - p : p;
}

/* log-uniform in [lo, hi] */
static double draw_log(double lo, double hi)
{
    return exp(dht_rand_uniform(log(lo), log(hi)));
}

/* Draws distance and limits (Q16.16 units: up to 30000 units, rates up to
 * 30000 units/s^k) with a minimum duration below 600 s. */
static void draw_case(int32_t *d, int32_t *V, int32_t *A, int32_t *J, int jerk, ref_prof *r)
{
    do {
        *d = (int32_t)draw_log(1.0, 2147483647.0);
        *V = (int32_t)draw_log(256.0, 2e9);
        *A = (int32_t)draw_log(256.0, 2e9);
        *J = jerk ? (int32_t)draw_log(256.0, 2e9) : 0;
        ref_plan(r, *d, *V, *A, jerk ? (double)*J : 0.0);
    } while (r->T > 600.0 || r->T < 2e-4);
    if (dht_rand_u32() & 1u) *d = -*d;
}

/* checks p against r (ideal, stretched to p->T) and the limits V, A, J by
 * finite differences over windows of w periods of dt */
static void check_profile(const dh_profile_q *p, ref_prof *r, double V, double A, double J, double *worst)
{
    const double D = fabs((double)p->d), sg = (p->d < 0) ? -1.0 : 1.0;
    const double e = POS_LSB + D * pow(2.0, -25);
    const uint32_t n = 400u, dt = (p->T / n > 0u) ? p->T / n : 1u;
    uint32_t t, w;
    int32_t pos, vel, acc, q[4];
    double h, fd, lim;
    int k;
    ref_stretch(r, p->T * 1e-6);
    /* the rates of the shape p holds (its rounded ratios and T), in double */
    {
        const double Ts = p->T * 1e-6, xj = p->xj / 1073741824.0, xa = p->xa / 1073741824.0;
        const double vi = D / (Ts * (1.0 - xa)), ai = vi / (Ts * (xa - xj)), ji = (xj > 0.0) ? ai / (Ts * xj) : 0.0;
        DHT_TRUE_MSG(vi <= V * (1.0 + 1e-8) && ai <= A * (1.0 + 1e-8) && (J <= 0.0 || ji <= J * (1.0 + 1e-8)),
                     "rates of the held shape %.9g %.9g %.9g over %.9g %.9g %.9g", vi, ai, ji, V, A, J);
    }
    /* ends and positions against the ideal profile */
    DHT_EQ_INT(dh_profile_eval_q(p, 0u, &pos, &vel, &acc), DH_OK);
    DHT_TRUE(pos == 0 && vel == 0 && acc == 0);
    DHT_EQ_INT(dh_profile_eval_q(p, p->T, &pos, &vel, &acc), DH_OK);
    DHT_TRUE(pos == p->d && vel == 0 && acc == 0);
    for (t = 0u; t <= p->T; t += dt) {
        DHT_EQ_INT(dh_profile_eval_q(p, t, &pos, &vel, &acc), DH_OK);
        DHT_TRUE_MSG(fabs(sg * pos - ref_pos(r, t * 1e-6)) <= e, "pos %ld vs %.3f at t=%lu of T=%lu",
                     (long)pos, sg * ref_pos(r, t * 1e-6), (unsigned long)t, (unsigned long)p->T);
        DHT_TRUE(fabs((double)vel) <= p->v && fabs((double)acc) <= p->a);
    }
    /* finite differences: the window w periods long enough that the
     * positions' rounding is below the tolerance, at most n / 8 */
    for (k = 1; k <= 3; k++) {
        lim = (k == 1) ? V : (k == 2) ? A : J;
        if (lim <= 0.0) continue;
        for (w = 1u; w < n / 8u; w++) {
            h = w * dt * 1e-6;
            if ((double)(1 << k) * e / pow(h, k) < 0.1 * LIM_REL * lim) break;
        }
        h = w * dt * 1e-6;
        for (t = 0u; t + (uint32_t)k * w * dt <= p->T + 2u * w * dt; t += dt) {
            int i;
            for (i = 0; i <= k; i++) DHT_EQ_INT(dh_profile_eval_q(p, t + (uint32_t)i * w * dt, &q[i], &vel, &acc), DH_OK);
            fd = (k == 1) ? (double)q[1] - q[0]
               : (k == 2) ? (double)q[2] - 2.0 * q[1] + q[0]
                          : (double)q[3] - 3.0 * q[2] + 3.0 * q[1] - q[0];
            fd = fabs(fd) / pow(h, k);
            /* worst of the difference less the positions' rounding, relative */
            if ((fd - (double)(1 << k) * e / pow(h, k)) / lim > worst[k - 1])
                worst[k - 1] = (fd - (double)(1 << k) * e / pow(h, k)) / lim;
            DHT_TRUE_MSG(fd <= lim * (1.0 + LIM_REL) + (double)(1 << k) * e / pow(h, k),
                         "difference %d: %.9g over limit %.9g (window %lu us at t=%lu of T=%lu)", k, fd, lim,
                         (unsigned long)(w * dt), (unsigned long)t, (unsigned long)p->T);
        }
    }
}

static void run_plans(int jerk)
{
    int it, n = DHT_ITER(400);
    double worst[3] = { 0.0, 0.0, 0.0 }, over = 0.0;
    for (it = 0; it < n; it++) {
        int32_t d, V, A, J;
        ref_prof r;
        dh_profile_q p;
        double Tmin;
        draw_case(&d, &V, &A, &J, jerk, &r);
        Tmin = r.T * 1e6;
        DHT_TRUE_MSG((jerk ? dh_profile_scurve_q(&p, d, V, A, J) : dh_profile_trap_q(&p, d, V, A)) == DH_OK,
                     "plan of d %ld V %ld A %ld J %ld", (long)d, (long)V, (long)A, (long)J);
        /* the duration: the analytic minimum rounded up to whole us */
        DHT_TRUE_MSG(p.T >= Tmin && p.T <= Tmin + 1.0 + pow(2.0, -26) * Tmin, "T %lu us vs minimum %.6f us",
                     (unsigned long)p.T, Tmin);
        if (p.T - Tmin > over) over = p.T - Tmin;
        /* the planner's case split (ref_plan) against the least duration of
         * the feasible regimes (support_ref.c) */
        DHT_NEAR(Tmin, 1e6 * (jerk ? dhr_scurve_tmin(d, V, A, J) : dhr_trap_tmin(d, V, A)), 1e-9 * Tmin);
        DHT_TRUE(p.v <= V && p.a <= A && p.j <= J && p.d == d);
        DHT_EQ_INT(p.kind, jerk ? DH_PROFILE_SCURVE : DH_PROFILE_TRAP);
        check_profile(&p, &r, V, A, jerk ? (double)J : 0.0, worst);
    }
    dht_printf("%s: T - Tmin <= %.4f us; finite differences less rounding / limit: v %.6f a %.6f j %.6f\n",
               jerk ? "scurve_q" : "trap_q", over, worst[0], worst[1], worst[2]);
}

static void trap_q_vs_double(void)
{
    run_plans(0);
}

static void scurve_q_vs_double(void)
{
    run_plans(1);
}

static void stretch_q_keeps_shape(void)
{
    int it, n = DHT_ITER(200);
    double worst[3] = { 0.0, 0.0, 0.0 };
    for (it = 0; it < n; it++) {
        int32_t d, V, A, J;
        ref_prof r;
        dh_profile_q p, o;
        uint32_t T;
        const int jerk = it & 1;
        draw_case(&d, &V, &A, &J, jerk, &r);
        DHT_TRUE_MSG((jerk ? dh_profile_scurve_q(&p, d, V, A, J) : dh_profile_trap_q(&p, d, V, A)) == DH_OK,
                     "plan of d %ld V %ld A %ld J %ld", (long)d, (long)V, (long)A, (long)J);
        o = p;
        T = p.T + (uint32_t)(dht_rand_uniform(0.0, 3.0) * p.T);
        if (T >= 0x80000000u) T = 0x7FFFFFFFu;
        if (dh_profile_stretch_q(&p, T) != DH_OK) continue;   /* a peak below 1 LSB/s^k */
        DHT_TRUE(p.T == T && p.xj == o.xj && p.xa == o.xa && p.v <= o.v && p.a <= o.a && p.j <= o.j);
        check_profile(&p, &r, V, A, jerk ? (double)J : 0.0, worst);
    }
    dht_printf("stretch_q: finite differences less rounding / limit: v %.6f a %.6f j %.6f\n", worst[0], worst[1], worst[2]);
}

static void quintic_q_vs_double(void)
{
    int it, n = DHT_ITER(200);
    for (it = 0; it < n; it++) {
        const int32_t d = (int32_t)draw_log(1.0, 2147483647.0) * ((dht_rand_u32() & 1u) ? -1 : 1);
        const uint32_t T = (uint32_t)draw_log(1e3, 1e8);
        const double D = fabs((double)d), Ts = T * 1e-6, e = POS_LSB + D * pow(2.0, -25);
        dh_profile_q p;
        uint32_t t;
        int32_t pos, vel, acc;
        if (dh_profile_quintic_q(&p, d, T) != DH_OK) {
            DHT_TRUE(60.0 * D / (Ts * Ts * Ts) > 2147483647.0); /* the jerk does not fit */
            continue;
        }
        DHT_TRUE(p.v >= 1.875 * D / Ts - 1e-8 * p.v && p.v <= 1.875 * D / Ts + 1.0 + 1e-8 * p.v);
        DHT_TRUE(p.a >= 5.7735026918962576 * D / (Ts * Ts) - 1e-8 * p.a);
        for (t = 0u; t <= T; t += (T / 97u > 0u) ? T / 97u : 1u) {
            const double x = t / (double)T;
            const double pr = D * x * x * x * (10.0 - 15.0 * x + 6.0 * x * x);
            const double vr = 30.0 * D / Ts * x * x * (1.0 - x) * (1.0 - x);
            DHT_EQ_INT(dh_profile_eval_q(&p, t, &pos, &vel, &acc), DH_OK);
            DHT_TRUE_MSG(fabs(fabs((double)pos) - pr) <= e, "quintic pos %ld vs %.3f", (long)pos, pr);
            DHT_TRUE(fabs(fabs((double)vel) - vr) <= 2.0 + 1e-8 * p.v);
            DHT_TRUE(fabs((double)vel) <= p.v && fabs((double)acc) <= p.a);
        }
    }
}

static void profile_q_special(void)
{
    dh_profile_q p, keep;
    int32_t pos = 7, vel = 7, acc = 7;
    memset(&keep, 0x5a, sizeof keep);
    p = keep;
    /* bad limits and durations: p untouched */
    DHT_EQ_INT(dh_profile_trap_q(&p, 100, 0, 5), DH_ERR_ARG);
    DHT_EQ_INT(dh_profile_trap_q(&p, 100, 5, -1), DH_ERR_ARG);
    DHT_EQ_INT(dh_profile_scurve_q(&p, 100, 5, 5, 0), DH_ERR_ARG);
    DHT_EQ_INT(dh_profile_scurve_q(&p, 100, INT32_MIN, 5, 5), DH_ERR_ARG);
    DHT_EQ_INT(dh_profile_quintic_q(&p, 100, 0u), DH_ERR_ARG);
    DHT_EQ_INT(dh_profile_quintic_q(&p, 100, 0x80000000u), DH_ERR_ARG);
    /* 2^31 LSB at 1 LSB/s: far beyond 2^31 us */
    DHT_EQ_INT(dh_profile_trap_q(&p, INT32_MIN, 1, 1), DH_ERR_OVERFLOW);
    DHT_EQ_INT(dh_profile_scurve_q(&p, INT32_MIN, 1, 1, 1), DH_ERR_OVERFLOW);
    /* 2^31 LSB in 1 us: the peaks do not fit */
    DHT_EQ_INT(dh_profile_quintic_q(&p, INT32_MIN, 1u), DH_ERR_OVERFLOW);
    DHT_TRUE(memcmp(&p, &keep, sizeof p) == 0);
    /* eval of no profile */
    DHT_EQ_INT(dh_profile_eval_q(&keep, 5u, &pos, &vel, &acc), DH_ERR_ARG);
    DHT_TRUE(pos == 7 && vel == 7 && acc == 7);
    /* d == 0: no motion, T = 0; a stretch only sets T */
    DHT_EQ_INT(dh_profile_scurve_q(&p, 0, 5, 5, 5), DH_OK);
    DHT_TRUE(p.T == 0u && p.v == 0);
    DHT_EQ_INT(dh_profile_stretch_q(&p, 1000u), DH_OK);
    DHT_TRUE(p.T == 1000u);
    DHT_EQ_INT(dh_profile_eval_q(&p, 500u, &pos, &vel, &acc), DH_OK);
    DHT_TRUE(pos == 0 && vel == 0 && acc == 0);
    /* INT32_MIN distance: fine within the limits; stretch below T refused */
    DHT_EQ_INT(dh_profile_trap_q(&p, INT32_MIN, 1 << 30, 1 << 30), DH_OK);
    DHT_EQ_INT(dh_profile_eval_q(&p, p.T, &pos, &vel, &acc), DH_OK);
    DHT_EQ_INT(pos, INT32_MIN);
    {
        ref_prof r;
        double worst[3] = { 0.0, 0.0, 0.0 };
        ref_plan(&r, 2147483648.0, 1073741824.0, 1073741824.0, 0.0);
        check_profile(&p, &r, 1073741824.0, 1073741824.0, 0.0, worst);
    }
    keep = p;
    DHT_EQ_INT(dh_profile_stretch_q(&p, p.T - 1u), DH_ERR_ARG);
    DHT_EQ_INT(dh_profile_stretch_q(&p, 0x80000000u), DH_ERR_ARG);
    DHT_TRUE(memcmp(&p, &keep, sizeof p) == 0);
    /* 1 LSB at the largest rates: the triangle 2 sqrt(1 / amax) = 43.2 us */
    DHT_EQ_INT(dh_profile_trap_q(&p, 1, INT32_MAX, INT32_MAX), DH_OK);
    DHT_TRUE(p.T >= 2e6 * sqrt(1.0 / 2147483647.0) && p.T <= 2e6 * sqrt(1.0 / 2147483647.0) + 1.0);
}

static const dht_case cases[] = {
    DHT_CASE(trap_q_vs_double),
    DHT_CASE(scurve_q_vs_double),
    DHT_CASE(stretch_q_keeps_shape),
    DHT_CASE(quintic_q_vs_double),
    DHT_CASE(profile_q_special),
};
DHT_MAIN(cases)
