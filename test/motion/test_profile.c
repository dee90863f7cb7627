/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_profile.c - rest-to-rest profiles (motion.h): durations against the
 * analytic minimum computed here in double, limits measured by finite
 * differences of the sampled float output, exact endpoints, continuity,
 * stretching, and the quintic against its polynomial in double.
 *
 * Finite-difference bounds. The window is h = T / 500 (a few control
 * periods of a move sampled at T / 2000). A forward difference of an output
 * over h is the mean of its derivative over the window, so in exact
 * arithmetic it is within the derivative's limit; the float outputs add
 * their rounding divided by h. Position: |p| <= |d|, error <= 4 ulp of |d|
 * at each end, so at most 8 * 2^-24 |d| / h = 2.4e-4 |d| / T <= 2.4e-4
 * vmax (the mean speed |d|/T never exceeds vmax). Velocity: error <= 4 ulp
 * of the peak v' at each end, over h: 8 * 2^-24 v' / h <= 1.2e-4 a' ta /
 * (T / 500) <= 6e-5 amax (v' = a' (ta - tj), ta <= T / 2). Acceleration
 * likewise <= 3e-5 jmax (a' = j' tj, tj <= T / 4). Every one is below the
 * 1e-3 relative margin of the check.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "dht.h"
#include "dhmath/motion.h"

#define REL_FD 1e-3   /* finite-difference margin over a limit */
#define REL_T 2e-6    /* duration vs the analytic minimum: 8 float roundings + the cube root's 2 ulp, with margin */
#define N_WIN 500     /* windows per move */

static double rlog(double lo, double hi) { return pow(10.0, dht_rand_uniform(lo, hi)); }
static double rsign(void) { return (dht_rand_u32() & 1u) ? -1.0 : 1.0; }

/* ---- references in double ------------------------------------------------ */

/* the brief's formula: d/v + v/a when d >= v^2/a, else 2 sqrt(d/a) */
static double trap_tmin(double d, double v, double a)
{
    d = fabs(d);
    return (d >= v * v / a) ? d / v + v / a : 2.0 * sqrt(d / a);
}

/* The seven-phase minimum as the least duration among the four regimes
 * whose profile is feasible (peaks within the limits, phases >= 0):
 * 1 amax and vmax reached, 2 vmax only, 3 amax only, 4 neither. *reg
 * receives the regime. */
static double scurve_tmin(double d, double V, double A, double J, int *reg)
{
    double best = HUGE_VAL, T, tj, ta, slack = 1e-12;
    d = fabs(d);
    *reg = 0;
    /* 1: accel phase A/J + V/A, distance V (ta + tv) */
    tj = A / J;
    ta = tj + V / A;
    if (V * J >= A * A * (1.0 - slack) && d >= V * ta * (1.0 - slack)) {
        T = d / V + ta;
        if (T < best) { best = T; *reg = 1; }
    }
    /* 2: tj = sqrt(V/J), ta = 2 tj, peak accel sqrt(VJ) <= A */
    tj = sqrt(V / J);
    ta = 2.0 * tj;
    if (J * tj <= A * (1.0 + slack) && d >= V * ta * (1.0 - slack)) {
        T = d / V + ta;
        if (T < best) { best = T; *reg = 2; }
    }
    /* 3: tj = A/J, A (ta - tj) ta = d, ta >= 2 tj, peak v <= V */
    tj = A / J;
    ta = 0.5 * tj + sqrt(0.25 * tj * tj + d / A);
    if (ta >= 2.0 * tj * (1.0 - slack) && A * (ta - tj) <= V * (1.0 + slack)) {
        T = 2.0 * ta;
        if (T < best) { best = T; *reg = 3; }
    }
    /* 4: d = 2 J tj^3, peaks J tj <= A, J tj^2 <= V */
    tj = cbrt(d / (2.0 * J));
    if (J * tj <= A * (1.0 + slack) && J * tj * tj <= V * (1.0 + slack)) {
        T = 4.0 * tj;
        if (T < best) { best = T; *reg = 4; }
    }
    return best;
}

/* ---- drawing limits and a distance in a chosen regime --------------------- */

typedef struct { double d, V, A, J; } lims;

/* regime 1..4 of the seven-phase profile, or a point on a boundary
 * between two (edge != 0) */
static void draw_scurve(int reg, int edge, lims *L)
{
    double A = rlog(-2.0, 3.0), J = rlog(-1.0, 4.0), V, d1, d2, d;
    if (reg == 2 || (reg == 4 && (dht_rand_u32() & 1u))) V = A * A / J * rlog(-2.0, -0.01);
    else V = A * A / J * rlog(0.01, 2.0);
    if (V * J >= A * A) {              /* amax reachable: d1 = amax reached, d2 = vmax reached */
        d1 = 2.0 * A * A * A / (J * J);
        d2 = V * (V / A + A / J);
    } else {
        d1 = d2 = 2.0 * V * sqrt(V / J);
    }
    switch (reg) {
    case 1: case 2: d = d2 * rlog(0.0, 2.0); break;
    case 3: d = d1 * pow(d2 / d1, dht_rand_uniform(0.0, 1.0)); break;
    default: d = d1 * rlog(-3.0, 0.0); break;
    }
    if (edge) d = (dht_rand_u32() & 1u) ? d1 : d2;
    L->d = rsign() * d;
    L->V = V;
    L->A = A;
    L->J = J;
}

/* ---- checks on a sampled profile -------------------------------------------- */

/* Finite differences over N_WIN windows against the limits (jl <= 0: no
 * jerk check), exact ends, monotone position, outputs within the peaks. */
static void check_sampled(const dh_profile_f32 *p, double vl, double al, double jl)
{
    float T = p->T, d = p->d, p0, v0, a0, p1, v1, a1;
    double h = (double)T / N_WIN, sg = d < 0.0f ? -1.0 : 1.0, worst_v = 0, worst_a = 0, worst_j = 0;
    int k;
    DHT_EQ_INT(dh_profile_eval_f32(p, 0.0f, &p0, &v0, &a0), DH_OK);
    DHT_TRUE(p0 == 0.0f && v0 == 0.0f && a0 == 0.0f);
    DHT_EQ_INT(dh_profile_eval_f32(p, T, &p1, &v1, &a1), DH_OK);
    DHT_EQ_F32_BITS(p1, d);
    DHT_TRUE(v1 == 0.0f && a1 == 0.0f);
    for (k = 1; k <= N_WIN; k++) {
        double t = (k == N_WIN) ? (double)T : h * k, fv, fa, fj;
        DHT_EQ_INT(dh_profile_eval_f32(p, (float)t, &p1, &v1, &a1), DH_OK);
        fv = fabs((double)p1 - p0) / h;
        fa = fabs((double)v1 - v0) / h;
        fj = fabs((double)a1 - a0) / h;
        if (fv / vl > worst_v) worst_v = fv / vl;
        if (fa / al > worst_a) worst_a = fa / al;
        if (fj / jl > worst_j) worst_j = fj / jl;
        DHT_TRUE_MSG(sg * ((double)p1 - p0) >= -8.0 * FLT_EPSILON * fabs(d), "position goes back at t=%g", t);
        DHT_TRUE_MSG(sg * v1 >= 0.0f && fabs(v1) <= p->v && fabs(a1) <= p->a,
                     "outputs beyond the peaks at t=%g: v %g a %g", t, (double)v1, (double)a1);
        p0 = p1;
        v0 = v1;
        a0 = a1;
    }
    DHT_TRUE_MSG(worst_v <= 1.0 + REL_FD, "velocity by finite differences %.9g x vmax", worst_v);
    DHT_TRUE_MSG(worst_a <= 1.0 + REL_FD, "acceleration by finite differences %.9g x amax", worst_a);
    if (jl > 0.0) DHT_TRUE_MSG(worst_j <= 1.0 + REL_FD, "jerk by finite differences %.9g x jmax", worst_j);
}

/* The velocity output is the derivative of the position output and the
 * acceleration that of the velocity: over a window h the forward
 * difference is the mean derivative, within L h / 4 of the mean of the
 * two end values when the derivative is Lipschitz with constant L (the
 * trapezoid rule), or within half a jump J0 where it jumps (the
 * trapezoid's acceleration, L = 0 then). Windows of T / 1000: the
 * rounding of the outputs over h is at most 8 * 2^-24 * 1000 |d| / T <=
 * 4.8e-4 of the peak velocity (|d| / T <= v), 2.4e-4 of the peak
 * acceleration (v <= a T / 2); the margin is 2e-3 of the peak. */
static void check_consistent(const dh_profile_f32 *p, double lv, double la, double jump)
{
    double h = (double)p->T / (2 * N_WIN);
    int k;
    for (k = 0; k < 2 * N_WIN; k++) {
        float p0, v0, a0, p1, v1, a1;
        double t = h * k, fv, fa;
        (void)dh_profile_eval_f32(p, (float)t, &p0, &v0, &a0);
        (void)dh_profile_eval_f32(p, (float)(t + h), &p1, &v1, &a1);
        fv = ((double)p1 - p0) / h - 0.5 * ((double)v0 + v1);
        fa = ((double)v1 - v0) / h - 0.5 * ((double)a0 + a1);
        DHT_TRUE_MSG(fabs(fv) <= lv * h / 4.0 + 2e-3 * p->v, "velocity output vs positions at t=%g: %g", t, fv);
        DHT_TRUE_MSG(fabs(fa) <= la * h / 4.0 + 0.5 * jump + 2e-3 * p->a, "acceleration output vs velocities at t=%g: %g",
                     t, fa);
    }
}

/* both halves meet at T/2 and at every phase boundary: outputs just
 * before and just after differ by their slope times the gap plus rounding */
static void check_joins(const dh_profile_f32 *p)
{
    float ts[4];
    int i;
    ts[0] = 0.5f * p->T;
    ts[1] = p->tj;
    ts[2] = p->ta - p->tj;
    ts[3] = p->ta;
    for (i = 0; i < 4; i++) {
        float tm = ts[i] * (1.0f - 4.0f * FLT_EPSILON), tp = ts[i] * (1.0f + 4.0f * FLT_EPSILON), pm, vm, am, pp, vp, ap;
        double gap = (double)tp - tm;
        if (!(ts[i] > 0.0f)) continue;
        (void)dh_profile_eval_f32(p, tm, &pm, &vm, &am);
        (void)dh_profile_eval_f32(p, tp, &pp, &vp, &ap);
        DHT_TRUE_MSG(fabs((double)pp - pm) <= p->v * gap + 8.0 * FLT_EPSILON * fabs(p->d),
                     "position jumps at join %d (t=%g): %g", i, (double)ts[i], (double)pp - pm);
        DHT_TRUE_MSG(fabs((double)vp - vm) <= p->a * gap + 8.0 * FLT_EPSILON * p->v,
                     "velocity jumps at join %d (t=%g): %g", i, (double)ts[i], (double)vp - vm);
        if (p->kind == DH_PROFILE_SCURVE) {
            DHT_TRUE_MSG(fabs((double)ap - am) <= p->j * gap + 8.0 * FLT_EPSILON * p->a,
                         "acceleration jumps at join %d (t=%g): %g", i, (double)ts[i], (double)ap - am);
        }
    }
}

/* ---- cases ------------------------------------------------------------------ */

static void trap_duration_is_minimum(void)
{
    int it, n = DHT_ITER(20000), cruise = 0, triangle = 0;
    double worst = 0.0;
    for (it = 0; it < n; it++) {
        double V = rlog(-2.0, 2.0), A = rlog(-2.0, 3.0), dc = V * V / A, d, ref;
        dh_profile_f32 p;
        switch (it % 3) {
        case 0: d = dc * rlog(0.0, 3.0); break;   /* vmax reached */
        case 1: d = dc * rlog(-3.0, 0.0); break;  /* triangle */
        default: d = dc; break;                   /* the boundary */
        }
        d *= rsign();
        DHT_EQ_INT(dh_profile_trap_f32(&p, (float)d, (float)V, (float)A), DH_OK);
        ref = trap_tmin((float)d, (float)V, (float)A);
        DHT_TRUE_MSG(fabs(p.T - ref) <= REL_T * ref, "T %.9g vs minimum %.9g (d %g v %g a %g)", (double)p.T, ref, d, V, A);
        if (fabs(p.T - ref) / ref > worst) worst = fabs(p.T - ref) / ref;
        DHT_TRUE(p.kind == DH_PROFILE_TRAP && p.tj == 0.0f && p.j == 0.0f);
        DHT_TRUE(p.v <= (float)V && p.a <= (float)A);
        if (p.tv > 0.0f) cruise++; else triangle++;
    }
    DHT_TRUE(cruise > 0 && triangle > 0);
    dht_printf("trapezoid: worst relative duration error %.3g\n", worst);
}

static void scurve_duration_is_minimum(void)
{
    int it, n = DHT_ITER(40000), seen[5] = { 0, 0, 0, 0, 0 };
    double worst = 0.0;
    for (it = 0; it < n; it++) {
        lims L;
        dh_profile_f32 p;
        double ref;
        int reg;
        draw_scurve(1 + it % 4, (it % 9) == 8, &L);
        DHT_EQ_INT(dh_profile_scurve_f32(&p, (float)L.d, (float)L.V, (float)L.A, (float)L.J), DH_OK);
        ref = scurve_tmin((float)L.d, (float)L.V, (float)L.A, (float)L.J, &reg);
        DHT_TRUE_MSG(fabs(p.T - ref) <= REL_T * ref, "T %.9g vs minimum %.9g (regime %d; d %g v %g a %g j %g)",
                     (double)p.T, ref, reg, L.d, L.V, L.A, L.J);
        DHT_TRUE(p.v <= (float)L.V && p.a <= (float)L.A && p.j <= (float)L.J);
        DHT_TRUE(fabs(2.0 * p.ta + p.tv - p.T) <= 2.0 * FLT_EPSILON * p.T);
        if (fabs(p.T - ref) / ref > worst) worst = fabs(p.T - ref) / ref;
        seen[reg]++;
    }
    DHT_TRUE_MSG(seen[1] > 0 && seen[2] > 0 && seen[3] > 0 && seen[4] > 0 && seen[0] == 0,
                 "regimes met: %d %d %d %d (none feasible: %d)", seen[1], seen[2], seen[3], seen[4], seen[0]);
    dht_printf("seven-phase: worst relative duration error %.3g\n", worst);
}

static void trap_within_limits(void)
{
    int it, n = DHT_ITER(400);
    for (it = 0; it < n; it++) {
        double V = rlog(-2.0, 2.0), A = rlog(-2.0, 3.0), d = rsign() * V * V / A * rlog(-2.0, 2.0);
        dh_profile_f32 p;
        DHT_EQ_INT(dh_profile_trap_f32(&p, (float)d, (float)V, (float)A), DH_OK);
        check_sampled(&p, (float)V, (float)A, 0.0);
        check_consistent(&p, A, 0.0, A);
        check_joins(&p);
    }
}

static void scurve_within_limits(void)
{
    int it, n = DHT_ITER(400);
    for (it = 0; it < n; it++) {
        lims L;
        dh_profile_f32 p;
        draw_scurve(1 + it % 4, (it % 9) == 8, &L);
        DHT_EQ_INT(dh_profile_scurve_f32(&p, (float)L.d, (float)L.V, (float)L.A, (float)L.J), DH_OK);
        check_sampled(&p, (float)L.V, (float)L.A, (float)L.J);
        check_consistent(&p, L.A, L.J, 0.0);
        check_joins(&p);
    }
}

static void stretch_keeps_limits(void)
{
    int it, n = DHT_ITER(400);
    for (it = 0; it < n; it++) {
        lims L;
        dh_profile_f32 p, q;
        float T;
        draw_scurve(1 + it % 4, 0, &L);
        if (it & 1) DHT_EQ_INT(dh_profile_scurve_f32(&p, (float)L.d, (float)L.V, (float)L.A, (float)L.J), DH_OK);
        else DHT_EQ_INT(dh_profile_trap_f32(&p, (float)L.d, (float)L.V, (float)L.A), DH_OK);
        T = p.T * (float)rlog(0.0, 1.5);
        q = p;
        DHT_EQ_INT(dh_profile_stretch_f32(&q, T), DH_OK);
        DHT_EQ_F32_BITS(q.T, T);
        DHT_TRUE(fabs(2.0 * q.ta + q.tv - T) <= 4.0 * FLT_EPSILON * T);
        DHT_TRUE(q.v <= p.v && q.a <= p.a && q.j <= p.j && q.kind == p.kind);
        /* the peaks scale by 1/k, 1/k^2, 1/k^3 */
        DHT_NEAR(q.v, (double)p.v * p.T / T, 1e-6 * p.v);
        DHT_NEAR(q.a, (double)p.a * p.T / T * p.T / T, 1e-6 * p.a);
        check_sampled(&q, (float)L.V, (float)L.A, (it & 1) ? (float)L.J : 0.0);
        check_joins(&q);
        /* a second stretch to the same T changes nothing */
        p = q;
        DHT_EQ_INT(dh_profile_stretch_f32(&q, T), DH_OK);
        DHT_TRUE(memcmp(&p, &q, sizeof p) == 0);
    }
}

static void quintic_vs_double(void)
{
    int it, n = DHT_ITER(20000);
    for (it = 0; it < n; it++) {
        double d = rsign() * rlog(-3.0, 3.0), T = rlog(-2.0, 2.0), t, x, pr, vr, ar;
        float fd = (float)d, fT = (float)T, pos, vel, acc;
        dh_profile_f32 p;
        DHT_EQ_INT(dh_profile_quintic_f32(&p, fd, fT), DH_OK);
        d = fd;
        T = fT;
        DHT_NEAR(p.v, 1.875 * fabs(d) / T, 1e-6 * p.v);
        DHT_NEAR(p.a, 10.0 / sqrt(3.0) * fabs(d) / (T * T), 1e-6 * p.a);
        DHT_NEAR(p.j, 60.0 * fabs(d) / (T * T * T), 1e-6 * p.j);
        t = (float)dht_rand_uniform(0.0, T);
        x = t / T;
        pr = d * x * x * x * (10.0 - 15.0 * x + 6.0 * x * x);
        vr = d / T * 30.0 * x * x * (1.0 - x) * (1.0 - x);
        ar = d / (T * T) * 60.0 * x * (1.0 - x) * (1.0 - 2.0 * x);
        DHT_EQ_INT(dh_profile_eval_f32(&p, (float)t, &pos, &vel, &acc), DH_OK);
        /* error: a few roundings of |d| (position), of the peaks (v, a) */
        DHT_NEAR(pos, pr, 8.0 * FLT_EPSILON * fabs(d));
        DHT_NEAR(vel, vr, 8.0 * FLT_EPSILON * p.v);
        DHT_NEAR(acc, ar, 16.0 * FLT_EPSILON * p.a);
        if (it < DHT_ITER(200)) {
            check_sampled(&p, p.v, p.a, p.j);
            check_joins(&p);
        }
    }
}

static void ends_and_clamping(void)
{
    dh_profile_f32 p;
    float pos, vel, acc;
    const float inf = HUGE_VALF;
    DHT_EQ_INT(dh_profile_scurve_f32(&p, -3.0f, 2.0f, 5.0f, 40.0f), DH_OK);
    DHT_EQ_INT(dh_profile_eval_f32(&p, -1.0f, &pos, &vel, &acc), DH_OK);
    DHT_TRUE(pos == 0.0f && vel == 0.0f && acc == 0.0f);
    DHT_EQ_INT(dh_profile_eval_f32(&p, -inf, &pos, &vel, &acc), DH_OK);
    DHT_TRUE(pos == 0.0f && vel == 0.0f && acc == 0.0f);
    DHT_EQ_INT(dh_profile_eval_f32(&p, p.T + 1.0f, &pos, &vel, &acc), DH_OK);
    DHT_TRUE(pos == -3.0f && vel == 0.0f && acc == 0.0f);
    DHT_EQ_INT(dh_profile_eval_f32(&p, inf, &pos, &vel, &acc), DH_OK);
    DHT_TRUE(pos == -3.0f && vel == 0.0f && acc == 0.0f);
    /* d < 0: the mirror image of d > 0 */
    {
        dh_profile_f32 m;
        float t, pm, vm, am;
        DHT_EQ_INT(dh_profile_scurve_f32(&m, 3.0f, 2.0f, 5.0f, 40.0f), DH_OK);
        DHT_EQ_F32_BITS(m.T, p.T);
        for (t = 0.0f; t < p.T; t += 0.01f) {
            (void)dh_profile_eval_f32(&p, t, &pos, &vel, &acc);
            (void)dh_profile_eval_f32(&m, t, &pm, &vm, &am);
            DHT_TRUE(pos == -pm && vel == -vm && acc == -am);
        }
    }
    /* d == 0: no motion, T == 0 until stretched */
    DHT_EQ_INT(dh_profile_trap_f32(&p, 0.0f, 1.0f, 1.0f), DH_OK);
    DHT_TRUE(p.T == 0.0f && p.v == 0.0f);
    DHT_EQ_INT(dh_profile_eval_f32(&p, 0.5f, &pos, &vel, &acc), DH_OK);
    DHT_TRUE(pos == 0.0f && vel == 0.0f && acc == 0.0f);
    DHT_EQ_INT(dh_profile_stretch_f32(&p, 2.0f), DH_OK);
    DHT_TRUE(p.T == 2.0f);
    DHT_EQ_INT(dh_profile_eval_f32(&p, 0.5f, &pos, &vel, &acc), DH_OK);
    DHT_TRUE(pos == 0.0f && vel == 0.0f && acc == 0.0f);
}

/* the extremes of float: a distance of one denormal, the largest float */
static void extreme_scales(void)
{
    static const float ds[] = { 1e-45f, 1e-30f, 1.0f, 1e30f, 3.4e38f };
    size_t i;
    for (i = 0; i < sizeof ds / sizeof ds[0]; i++) {
        dh_profile_f32 p;
        dh_status st = dh_profile_scurve_f32(&p, ds[i], 1.0f, 1.0f, 1.0f);
        int reg;
        double ref = scurve_tmin(ds[i], 1.0, 1.0, 1.0, &reg);
        if (st == DH_OK) {
            DHT_TRUE_MSG(fabs(p.T - ref) <= REL_T * ref, "d %g: T %.9g vs %.9g", (double)ds[i], (double)p.T, ref);
            check_sampled(&p, 1.0, 1.0, 1.0);
        } else {
            DHT_EQ_INT(st, DH_ERR_OVERFLOW);
            DHT_TRUE_MSG(!(ref <= FLT_MAX), "d %g refused although T %g", (double)ds[i], ref);
        }
        st = dh_profile_trap_f32(&p, ds[i], 1.0f, 1.0f);
        ref = trap_tmin(ds[i], 1.0, 1.0);
        if (st == DH_OK) {
            DHT_TRUE_MSG(fabs(p.T - ref) <= REL_T * ref, "d %g: T %.9g vs %.9g", (double)ds[i], (double)p.T, ref);
        } else {
            DHT_EQ_INT(st, DH_ERR_OVERFLOW);
            DHT_TRUE(!(ref <= FLT_MAX));
        }
    }
}

static const dht_case cases[] = {
    DHT_CASE(trap_duration_is_minimum),
    DHT_CASE(scurve_duration_is_minimum),
    DHT_CASE(trap_within_limits),
    DHT_CASE(scurve_within_limits),
    DHT_CASE(stretch_keeps_limits),
    DHT_CASE(quintic_vs_double),
    DHT_CASE(ends_and_clamping),
    DHT_CASE(extreme_scales),
};
DHT_MAIN(cases)
