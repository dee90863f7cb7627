/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_track.c - the float tracker on the Puma 560, UR5, KUKA KR5,
 * Stanford arm (closed form) and Panda (damped steps only), seeded random
 * paths. Every call is checked against the guarantees of track.h in
 * double: the step bound (the float dq_max and vmax dt), the joint limits,
 * finiteness, the acceleration bound where amax is set, and DH_TRACK_OK
 * only when the double reference FK (support_robots.c) of q_out is within
 * the tolerances (plus the float FK bound of robot.h, 3e-7 m, and 1e-6
 * rad). Paths:
 * - smooth joint-space paths (cosine profile, 1 deg or 1 mm inside the
 *   limits) whose rates stay within half of vmax and whose true smallest
 *   singular value stays >= 1e-2: every call OK;
 * - straight lines passing 1 mm from a wrist singularity (joint 5 at 0),
 *   and horizontal lines whose target position crosses the axis of joint 1
 *   (the shoulder singularity of an arm without shoulder offset; near it
 *   for the others), the target then held: OK again, once the target stops,
 *   within the time the step bound allows for the distance left
 *   (ceil(max_i |q_end_i - q_stop_i| / dq_max_i) + 2 calls);
 * - a line leaving the workspace and coming back: UNREACHABLE outside,
 *   OK again as above;
 * - a target that jumps: LAGGING until reached, OK within the same time
 *   bound; with amax, without a velocity step (the acceleration bound).
 * The Panda has no closed form: its damped steps can drift in the null
 * space towards a singularity the path avoids, or stall against a limit
 * after a jump or a return into the workspace (track.h); for it every
 * guarantee is checked on every call, and its OK calls and recoveries are
 * counted and printed, not required.
 */
#include "dht.h"
#include "support_robots.h"
#include "dhmath/track.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define DT 1e-3f
#define VMAX_R 180.0f /* deg/s */
#define VMAX_P 0.5f   /* m/s */

typedef struct {
    const dhs_robot *d;
    dh_robot r;
    dh_ikc_model_f32 m;
    int closed;
} rig;

static void rig_make(rig *g, const dhs_robot *d, float amax_r)
{
    uint32_t i;
    g->d = d;
    DHT_EQ_INT(dhs_build(d, &g->r), DH_OK);
    for (i = 0; i < g->r.n; i++) {
        const int rev = g->r.joint[i].type == DH_JOINT_REVOLUTE;
        DHT_EQ_INT(dh_robot_set_rates_f32(&g->r, i, rev ? VMAX_R : VMAX_P * (float)d->unit_per_m,
                                          rev ? amax_r : amax_r / 360.0f * (float)d->unit_per_m),
                   DH_OK);
    }
    g->closed = dh_ikc_analyse_f32(&g->r, &g->m) == DH_OK && g->m.kind != DH_IKC_NONE;
}

typedef struct {
    float qp[DH_MAX_JOINTS];  /* previous output */
    float sp[DH_MAX_JOINTS];  /* previous step */
    long calls, ok, lag, unr;
    int have_sp;
} chk;

static void chk_start(chk *c, const float *q0, uint32_t n)
{
    memset(c, 0, sizeof *c);
    memcpy(c->qp, q0, n * sizeof(float));
}

static double ulpf(double x)
{
    int e;
    (void)frexp(fabs(x) > 1e-30 ? fabs(x) : 1e-30, &e);
    return ldexp(1.0, e - 24);
}

/* one call with every guarantee checked; returns the state */
static int last_near_singular; /* the last call's rep.near_singular */

/* twin: step_checked of test_track_q.c */
static dh_track_state step_checked(rig *g, dh_track_f32 *t, chk *c, const dh_mat4_f32 *target, const char *what)
{
    float q[DH_MAX_JOINTS];
    dh_track_report_f32 rep;
    uint32_t i;
    const dh_status st = dh_track_step_f32(t, target, q, &rep);
    DHT_EQ_INT(st, DH_OK);
    for (i = 0; i < g->r.n; i++) {
        const dh_joint *j = &g->r.joint[i];
        const double s = (double)q[i] - (double)c->qp[i];
        DHT_TRUE_MSG(isfinite(q[i]), "%s %s call %ld: joint %u not finite", g->d->name, what, c->calls, (unsigned)i);
        DHT_TRUE_MSG(fabs(s) <= (double)t->dq_max[i] && fabs(s) <= (double)j->vmax * (double)DT,
                     "%s %s call %ld: joint %u step %.9g beyond %.9g", g->d->name, what, c->calls, (unsigned)i, s,
                     (double)t->dq_max[i]);
        if (j->qmin <= j->qmax)
            DHT_TRUE_MSG(q[i] >= j->qmin && q[i] <= j->qmax, "%s %s call %ld: joint %u = %.9g outside [%g, %g]",
                         g->d->name, what, c->calls, (unsigned)i, (double)q[i], (double)j->qmin, (double)j->qmax);
        if (isfinite(j->amax) && c->have_sp) {
            const double A = (double)j->amax * DT * DT;
            const double qm = fmax(fabs(q[i]), fabs(c->qp[i]));
            DHT_TRUE_MSG(fabs(s - c->sp[i]) <= A * (1 + 1e-6) + 4 * ulpf(qm),
                         "%s %s call %ld: joint %u step change %.9g beyond amax dt^2 %.9g", g->d->name, what,
                         c->calls, (unsigned)i, fabs(s - c->sp[i]), A);
        }
        c->sp[i] = (float)s;
        c->qp[i] = q[i];
    }
    c->have_sp = 1;
    if (rep.state == DH_TRACK_OK) {
        double ep, er;
        dhs_true_error_f32(&g->r, q, target, &ep, &er);
        DHT_TRUE_MSG(ep <= t->pos_tol + 3e-7 * g->d->unit_per_m && er <= t->rot_tol + 1e-6,
                     "%s %s call %ld: OK with error %.3g / %.3g rad", g->d->name, what, c->calls, ep, er);
        c->ok++;
    } else if (rep.state == DH_TRACK_LAGGING) {
        c->lag++;
    } else {
        c->unr++;
    }
    DHT_TRUE(isfinite(rep.manip) && rep.sigma_min >= 0.0f);
    last_near_singular = rep.near_singular;
    c->calls++;
    return rep.state;
}

/* at the tracker's q: the smallest over the closed-form solutions of the
 * target of max_i |solution_i - q_i| / dq_max_i (> 1: none in the step box) */
static double box_ratio(rig *g, const dh_track_f32 *t, const dh_mat4_f32 *target)
{
    dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
    uint32_t ns = 0, k, i;
    double best = 1e30;
    if (dh_ikc_f32(&g->m, target, t->q, 0u, sol, &ns) != DH_OK) return 0.0;
    for (k = 0; k < ns; k++) {
        double r = 0.0;
        for (i = 0; i < g->r.n; i++) r = fmax(r, fabs((double)sol[k].q[i] - t->q[i]) / (double)t->dq_max[i]);
        best = fmin(best, r);
    }
    return best;
}

/* the target held after a path: OK again, after the last call in the
 * singular neighbourhood (rep.near_singular), within the time the step
 * bound allows for the distance left from there (plus 2 calls); then OK
 * every call (twin: hold_until_ok of test_track_q.c) */
static void hold_until_ok(rig *g, dh_track_f32 *t, chk *c, const dh_mat4_f32 *target, const char *what, long max_calls)
{
    float q_mark[DH_MAX_JOINTS];
    long k, first_ok = -1, mark = 0;
    double need = 0.0;
    uint32_t i;
    memcpy(q_mark, t->q, sizeof q_mark);
    for (k = 0; k < max_calls; k++) {
        const dh_track_state s = step_checked(g, t, c, target, what);
        if (s == DH_TRACK_OK && first_ok < 0) first_ok = k;
        /* the target reached while sigma_min is below the threshold, the
         * nearest closed-form solution maybe outside the step box: q stays */
        if (s == DH_TRACK_OK && last_near_singular && g->closed) dht_reach_max("hold.ok_box_ratio", box_ratio(g, t, target));
        /* the same away from the singular neighbourhood (sigma_min at or
         * above the threshold): the tracker holds the reached pose */
        if (s == DH_TRACK_OK && !last_near_singular && g->closed)
            dht_reach_max("hold.ok_far_box_ratio", box_ratio(g, t, target));
        if (s != DH_TRACK_OK && last_near_singular) {
            mark = k + 1;
            memcpy(q_mark, t->q, sizeof q_mark);
        }
        if (first_ok >= 0) DHT_TRUE_MSG(s == DH_TRACK_OK, "%s %s: OK lost at hold call %ld", g->d->name, what, k);
        if (first_ok >= 0 && k > first_ok + 5) break;
    }
    DHT_TRUE_MSG(first_ok >= 0, "%s %s: never OK in %ld calls of a held target", g->d->name, what, max_calls);
    for (i = 0; i < g->r.n; i++) {
        const double steps = fabs((double)t->q[i] - q_mark[i]) / t->dq_max[i];
        if (steps > need) need = steps;
    }
    DHT_TRUE_MSG(first_ok - mark <= (long)ceil(need) + 2, "%s %s: OK %ld calls after the singular neighbourhood, the bound allows %.1f",
                 g->d->name, what, first_ok - mark + 1, need);
}

/* 1 when the closed-form solver has a solution of T within the limits
 * (test input selection only) */
static int reachable(rig *g, const dh_mat4_f32 *T, const float *q_ref)
{
    dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
    uint32_t ns = 0;
    return !g->closed || dh_ikc_f32(&g->m, T, q_ref, 0u, sol, &ns) == DH_OK;
}

/* true smallest singular value of the float Jacobian at q, in double
 * (power iteration on (J J^T)^-1 is avoided: Jacobi eigenvalues) */
static double sigma_true(rig *g, const float *q)
{
    float J[6 * DH_MAX_JOINTS];
    double A[36], ev[6], mn;
    int i, j, k;
    const int n = (int)g->r.n;
    (void)dh_jacobian_f32(&g->r, q, J, NULL);
    for (i = 0; i < 6; i++)
        for (j = 0; j < 6; j++) {
            double v = 0;
            for (k = 0; k < n; k++) v += (double)J[i * n + k] * J[j * n + k];
            A[i * 6 + j] = v;
        }
    dhr_sym_eig(A, 6, ev);
    mn = ev[0];
    for (i = 1; i < 6; i++) mn = fmin(mn, ev[i]);
    return sqrt(fmax(mn, 0.0));
}

static void target_of(rig *g, const float *q, dh_mat4_f32 *T)
{
    double qd[DH_MAX_JOINTS];
    uint32_t i;
    for (i = 0; i < g->r.n; i++) qd[i] = q[i];
    dhs_target_f32(&g->r, qd, T);
}

/* a random configuration within the limits, joints within +-150 deg */
static void random_q(rig *g, float *q)
{
    double qd[DHS_MAX_JOINTS];
    uint32_t i;
    dhs_random_q(g->d, qd);
    for (i = 0; i < g->r.n; i++) q[i] = (float)qd[i];
}

static const dhs_robot *const robots[] = { &dhs_puma560_m, &dhs_ur5_m, &dhs_kuka_kr5_m, &dhs_stanford_m,
                                           &dhs_panda_m };
#define N_ROBOTS (sizeof robots / sizeof robots[0])

/* smooth paths: every call OK */
static void smooth_paths_every_call_ok(void)
{
    size_t ri;
    for (ri = 0; ri < N_ROBOTS; ri++) {
        rig g;
        long path, n_path = DHT_ITER(12), calls = 0, not_ok = 0;
        rig_make(&g, robots[ri], INFINITY);
        for (path = 0; path < n_path; path++) {
            float qa[DH_MAX_JOINTS], qb[DH_MAX_JOINTS], q[DH_MAX_JOINTS];
            double dmax = 0.0, T;
            long k, N;
            uint32_t i;
            int tries = 0, good;
            dh_track_f32 t;
            chk c;
            do { /* far enough from singularities all along */
                random_q(&g, qa);
                for (i = 0; i < g.r.n; i++) {
                    const dh_joint *j = &g.r.joint[i];
                    const double span = (j->type == DH_JOINT_REVOLUTE) ? 40.0 : 0.1 * g.d->unit_per_m;
                    double v = qa[i] + dht_rand_uniform(-span, span);
                    /* 1 deg (1 mm) inside the limits: a path onto a limit
                     * is the limits' case, not smooth tracking */
                    const double in = (j->type == DH_JOINT_REVOLUTE) ? 1.0 : 1e-3 * g.d->unit_per_m;
                    if (j->qmin <= j->qmax) v = fmin(fmax(v, j->qmin + in), j->qmax - in);
                    qb[i] = (float)v;
                }
                good = 1;
                for (k = 0; k <= 20 && good; k++) {
                    for (i = 0; i < g.r.n; i++) q[i] = qa[i] + (qb[i] - qa[i]) * (float)k / 20.0f;
                    if (sigma_true(&g, q) < 1e-2 * g.d->unit_per_m) good = 0;
                }
            } while (!good && ++tries < 100);
            DHT_TRUE(good);
            for (i = 0; i < g.r.n; i++) {
                const double vm = g.r.joint[i].vmax;
                dmax = fmax(dmax, fabs((double)qb[i] - qa[i]) / vm);
            }
            /* cosine profile: peak rate pi/2 D / T = vmax / 2 */
            T = dmax * 3.14159265358979 + 10 * DT;
            N = (long)(T / DT) + 1;
            DHT_EQ_INT(dh_track_init_f32(&t, &g.r, g.closed ? &g.m : NULL, qa, DT), DH_OK);
            chk_start(&c, qa, g.r.n);
            for (k = 1; k <= N; k++) {
                const double s = 0.5 - 0.5 * cos(3.14159265358979 * (double)k / (double)N);
                dh_mat4_f32 Tg;
                double qd[DH_MAX_JOINTS];
                for (i = 0; i < g.r.n; i++) qd[i] = qa[i] + (qb[i] - qa[i]) * s;
                dhs_target_f32(&g.r, qd, &Tg);
                if (step_checked(&g, &t, &c, &Tg, "smooth") != DH_TRACK_OK) {
                    /* damped steps alone (Panda) drift in the null space
                     * and may meet a singularity the path avoids: counted,
                     * not required */
                    DHT_TRUE_MSG(!g.closed, "%s smooth path %ld call %ld: not OK", g.d->name, path, k);
                    not_ok++;
                }
            }
            calls += c.calls;
        }
        printf("%s: %ld smooth paths, %ld calls, %ld not OK\n", g.d->name, n_path, calls, not_ok);
    }
}

/* a line of length 2h through p_s + offset, orientation R_s fixed */
static void line_target(const dh_mat4_f32 *Ts, const double *off, const double *u, double h, double s,
                        dh_mat4_f32 *T)
{
    int k;
    *T = *Ts;
    for (k = 0; k < 3; k++) T->m[3][k] = (float)(Ts->m[3][k] + off[k] + u[k] * h * (2 * s - 1));
}

/* tracker started on the solution of the first target nearest q_near */
static int start_at(rig *g, dh_track_f32 *t, chk *c, const dh_mat4_f32 *T0, const float *q_near)
{
    dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
    uint32_t ns = 0, idx = 0;
    if (dh_ikc_f32(&g->m, T0, q_near, 0u, sol, &ns) != DH_OK) return 0;
    DHT_EQ_INT(dh_ikc_nearest_f32(sol, ns, q_near, g->r.n, &idx), DH_OK);
    DHT_EQ_INT(dh_track_init_f32(t, &g->r, &g->m, sol[idx].q, DT), DH_OK);
    chk_start(c, sol[idx].q, g->r.n);
    return 1;
}

/* lines 1 mm from the wrist singularity (joint 5 at 0) and through the
 * shoulder singularity, then held */
static void singular_lines(void)
{
    size_t ri;
    for (ri = 0; ri < 4u; ri++) { /* the closed-form robots */
        rig g;
        long line, n_line = DHT_ITER(10), lag = 0, calls = 0;
        rig_make(&g, robots[ri], INFINITY);
        DHT_TRUE(g.closed);
        for (line = 0; line < n_line; line++) {
            float qs[DH_MAX_JOINTS];
            dh_mat4_f32 Ts, T;
            double off[3], u[3], h = 0.05 * g.d->unit_per_m;
            const double speed = 0.1 * g.d->unit_per_m; /* per s */
            long k, N = (long)(2 * h / speed / DT);
            dh_track_f32 t;
            chk c;
            int k3;
            const int shoulder = (int)(line & 1);
            random_q(&g, qs);
            if (!shoulder) {
                qs[4] = 0.0f; /* wrist singular */
                dhr_rand_unit3(off);
                for (k3 = 0; k3 < 3; k3++) off[k3] *= 1e-3 * g.d->unit_per_m;
            } else {
                /* shoulder: move joint 2/3 until the wrist centre is over
                 * the base axis is robot specific; use the line through the
                 * base axis at the wrist centre's height instead: the target
                 * position crosses x = y = 0 of the base frame */
                off[0] = off[1] = off[2] = 0.0;
            }
            target_of(&g, qs, &Ts);
            dhr_rand_unit3(u);
            if (shoulder) {
                /* horizontal line through the base axis at the target's height */
                const double r0 = sqrt((double)Ts.m[3][0] * Ts.m[3][0] + (double)Ts.m[3][1] * Ts.m[3][1]);
                u[0] = Ts.m[3][0] / r0;
                u[1] = Ts.m[3][1] / r0;
                u[2] = 0.0;
                off[0] = -Ts.m[3][0];
                off[1] = -Ts.m[3][1];
                h = fmin(r0, 0.3 * g.d->unit_per_m);
                N = (long)(2 * h / speed / DT);
            }
            line_target(&Ts, off, u, h, 1.0, &T);
            if (!reachable(&g, &T, qs)) continue;
            line_target(&Ts, off, u, h, 0.0, &T);
            if (!start_at(&g, &t, &c, &T, qs)) continue;
            for (k = 1; k <= N; k++) {
                line_target(&Ts, off, u, h, (double)k / (double)N, &T);
                (void)step_checked(&g, &t, &c, &T, shoulder ? "shoulder line" : "wrist line");
            }
            hold_until_ok(&g, &t, &c, &T, shoulder ? "shoulder line end" : "wrist line end", 20000);
            lag += c.lag + c.unr;
            calls += c.calls;
        }
        printf("%s: %ld singular lines, %ld calls, %ld not OK\n", g.d->name, n_line, calls, lag);
    }
}

/* out of the workspace and back (twin: leaving_the_workspace of test_track_q.c) */
static void leaving_the_workspace(void)
{
    size_t ri;
    for (ri = 0; ri < N_ROBOTS; ri++) {
        rig g;
        long line, n_line = DHT_ITER(6), unr = 0, back = 0;
        rig_make(&g, robots[ri], INFINITY);
        for (line = 0; line < n_line; line++) {
            float qs[DH_MAX_JOINTS];
            dh_mat4_f32 Ts, T;
            double u[3], r0, h;
            const double speed = 0.2 * g.d->unit_per_m;
            long k, N;
            dh_track_f32 t;
            chk c;
            random_q(&g, qs);
            target_of(&g, qs, &Ts);
            r0 = sqrt((double)Ts.m[3][0] * Ts.m[3][0] + (double)Ts.m[3][1] * Ts.m[3][1] +
                      (double)Ts.m[3][2] * Ts.m[3][2]);
            u[0] = Ts.m[3][0] / r0;
            u[1] = Ts.m[3][1] / r0;
            u[2] = Ts.m[3][2] / r0;
            h = 2.0 * g.d->unit_per_m; /* far beyond every arm's reach */
            N = (long)(h / speed / DT);
            DHT_EQ_INT(dh_track_init_f32(&t, &g.r, g.closed ? &g.m : NULL, qs, DT), DH_OK);
            chk_start(&c, qs, g.r.n);
            for (k = 1; k <= 2 * N; k++) {
                const double s = (k <= N) ? (double)k / N : (double)(2 * N - k) / N;
                int j;
                T = Ts;
                for (j = 0; j < 3; j++) T.m[3][j] = (float)(Ts.m[3][j] + u[j] * h * s);
                (void)step_checked(&g, &t, &c, &T, "workspace line");
            }
            DHT_TRUE_MSG(c.unr > 0, "%s: a target 2 m outside never UNREACHABLE", g.d->name);
            if (g.closed) {
                hold_until_ok(&g, &t, &c, &Ts, "workspace line end", 40000);
            } else {
                /* damped steps alone may stall at a limit on the way back:
                 * the guarantees are checked, reaching it is counted */
                for (k = 0; k < 5000; k++)
                    if (step_checked(&g, &t, &c, &Ts, "workspace line end, damped only") == DH_TRACK_OK) break;
                if (k < 5000) back++;
            }
            unr += c.unr;
        }
        printf("%s: %ld lines out of the workspace, %ld calls UNREACHABLE", g.d->name, n_line, unr);
        if (!g.closed) printf(", %ld reached again (damped steps only)", back);
        printf("\n");
    }
}

/* a jump of the target: no jump of the joints; with amax no velocity step */
static void target_jumps(void)
{
    size_t ri;
    int acc;
    for (acc = 0; acc < 2; acc++)
        for (ri = 0; ri < N_ROBOTS; ri++) {
            rig g;
            long jump, n_jump = DHT_ITER(8), calls = 0, reached = 0;
            rig_make(&g, robots[ri], acc ? 720.0f : INFINITY);
            for (jump = 0; jump < n_jump; jump++) {
                float qa[DH_MAX_JOINTS], qb[DH_MAX_JOINTS];
                dh_mat4_f32 Ta, Tb;
                dh_track_f32 t;
                chk c;
                long k;
                uint32_t i;
                random_q(&g, qa);
                for (i = 0; i < g.r.n; i++) {
                    const dh_joint *j = &g.r.joint[i];
                    const double span = (j->type == DH_JOINT_REVOLUTE) ? 30.0 : 0.05 * g.d->unit_per_m;
                    double v = qa[i] + dht_rand_uniform(-span, span);
                    if (j->qmin <= j->qmax) v = fmin(fmax(v, j->qmin), j->qmax);
                    qb[i] = (float)v;
                }
                if (sigma_true(&g, qb) < 1e-2 || sigma_true(&g, qa) < 1e-2) continue;
                target_of(&g, qa, &Ta);
                target_of(&g, qb, &Tb);
                if (!reachable(&g, &Tb, qa) || !reachable(&g, &Ta, qa)) continue;
                DHT_EQ_INT(dh_track_init_f32(&t, &g.r, g.closed ? &g.m : NULL, qa, DT), DH_OK);
                chk_start(&c, qa, g.r.n);
                for (k = 0; k < 5; k++) (void)step_checked(&g, &t, &c, &Ta, "before the jump");
                if (acc) {
                    /* reached in at most the bang-bang time of the largest
                     * joint distance (plus the rate limit) */
                    long first_ok = -1;
                    for (k = 0; k < 20000 && first_ok < 0; k++)
                        if (step_checked(&g, &t, &c, &Tb, "jump with amax") == DH_TRACK_OK) first_ok = k;
                    DHT_TRUE_MSG(first_ok >= 0 || !g.closed, "%s: jump with amax never reached", g.d->name);
                } else if (g.closed) {
                    hold_until_ok(&g, &t, &c, &Tb, "jump", 20000);
                } else {
                    /* damped steps alone can stall against a joint limit
                     * far from a jumped target: the guarantees are
                     * checked, reaching it is counted */
                    for (k = 0; k < 5000; k++)
                        if (step_checked(&g, &t, &c, &Tb, "jump, damped only") == DH_TRACK_OK) break;
                    if (k < 5000) reached++;
                }
                calls += c.calls;
            }
            printf("%s: %ld target jumps%s, %ld calls", g.d->name, n_jump, acc ? " with amax 720 deg/s^2" : "",
                   calls);
            if (!g.closed && !acc) printf(", %ld reached (damped steps only)", reached);
            printf("\n");
        }
}

/* bad targets: the joints brake, the status says why (twin: bad_targets_brake of test_track_q.c) */
static void bad_targets_brake(void)
{
    rig g;
    dh_track_f32 t;
    dh_track_report_f32 rep;
    float q0[6] = { 10, -60, 70, 20, 40, 30 }, q[6];
    dh_mat4_f32 T;
    uint32_t i;
    rig_make(&g, &dhs_ur5_m, INFINITY);
    DHT_EQ_INT(dh_track_init_f32(&t, &g.r, &g.m, q0, DT), DH_OK);
    target_of(&g, q0, &T);
    T.m[3][0] = NAN;
    DHT_EQ_INT(dh_track_step_f32(&t, &T, q, &rep), DH_ERR_NAN);
    DHT_EQ_INT(rep.state, DH_TRACK_UNREACHABLE);
    for (i = 0; i < 6u; i++) DHT_TRUE(q[i] == q0[i]);
    target_of(&g, q0, &T);
    T.m[0][3] = 0.5f;
    DHT_EQ_INT(dh_track_step_f32(&t, &T, q, &rep), DH_ERR_NOT_RIGID);
    target_of(&g, q0, &T);
    T.m[0][0] *= 1.1f;
    DHT_EQ_INT(dh_track_step_f32(&t, &T, q, &rep), DH_ERR_NOT_RIGID);
    /* init errors */
    DHT_EQ_INT(dh_track_init_f32(&t, &g.r, &g.m, q0, 0.0f), DH_ERR_ARG);
    DHT_EQ_INT(dh_track_init_f32(&t, &g.r, &g.m, q0, NAN), DH_ERR_ARG);
    q0[1] = 1000.0f;
    DHT_EQ_INT(dh_track_init_f32(&t, &g.r, &g.m, q0, DT), DH_ERR_LIMIT);
    q0[1] = NAN;
    DHT_EQ_INT(dh_track_init_f32(&t, &g.r, &g.m, q0, DT), DH_ERR_NAN);
}

/* dh_track_sync_f32: joint commands made elsewhere (a ramp at constant
 * velocity) set the tracker's q and v exactly; the tracker then continues
 * from that velocity: the next targets, on the same ramp, are reached with
 * every step and change of step within the bounds measured from the synced
 * steps. Errors leave the tracker untouched. */
static void sync_continues(void)
{
    rig g;
    dh_track_f32 t;
    static dh_track_f32 keep; /* off the stack: a 16 KB target runs this suite */
    chk c;
    float q0[6] = { 10, -60, 70, 20, 40, 30 }, q[6], bad[6];
    const float d[6] = { 0.002f, -0.0015f, 0.001f, 0.0025f, -0.002f, 0.001f }; /* deg per period */
    dh_mat4_f32 T;
    uint32_t i;
    int k;
    rig_make(&g, &dhs_ur5_m, 3000.0f);
    DHT_EQ_INT(dh_track_init_f32(&t, &g.r, &g.m, q0, DT), DH_OK);
    memcpy(q, q0, sizeof q);
    for (k = 1; k <= 20; k++) {
        float qn[6];
        for (i = 0; i < 6u; i++) qn[i] = q0[i] + (float)k * d[i];
        DHT_EQ_INT(dh_track_sync_f32(&t, qn), DH_OK);
        for (i = 0; i < 6u; i++) {
            DHT_TRUE(t.q[i] == qn[i]);
            DHT_TRUE(fabs((double)t.v[i] - ((double)qn[i] - (double)q[i]) / (double)DT) <=
                     4.0 * ulpf(q[i]) / (double)DT);
        }
        memcpy(q, qn, sizeof q);
    }
    /* on along the ramp through the tracker */
    chk_start(&c, q, 6u);
    for (i = 0; i < 6u; i++) c.sp[i] = (float)((double)q[i] - (double)(q0[i] + 19.0f * d[i])); /* the last synced step */
    c.have_sp = 1;
    for (k = 21; k <= 60; k++) {
        float qn[6];
        for (i = 0; i < 6u; i++) qn[i] = q0[i] + (float)k * d[i];
        target_of(&g, qn, &T);
        DHT_EQ_INT(step_checked(&g, &t, &c, &T, "sync ramp"), DH_TRACK_OK);
    }
    /* errors: tracker untouched */
    keep = t;
    memcpy(bad, q, sizeof bad);
    bad[2] = NAN;
    DHT_EQ_INT(dh_track_sync_f32(&t, bad), DH_ERR_NAN);
    DHT_TRUE(memcmp(&t, &keep, sizeof t) == 0);
    bad[2] = 1000.0f;
    DHT_EQ_INT(dh_track_sync_f32(&t, bad), DH_ERR_LIMIT);
    DHT_TRUE(memcmp(&t, &keep, sizeof t) == 0);
}

static const dht_case cases[] = {
    DHT_CASE(bad_targets_brake),
    DHT_CASE(smooth_paths_every_call_ok),
    DHT_CASE(singular_lines),
    DHT_CASE(leaving_the_workspace),
    DHT_CASE(target_jumps),
    DHT_CASE(sync_continues),
};

DHT_MAIN(cases)
