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
#include "../../src/ikc/ikc_impl.h" /* the pruned solve against the full one */

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
static long cf_checked;        /* steps checked by cf_is_nearest */
static long cf_unmeasured;     /* of those, reported without FK (measured 0) */

/* A step that took the closed-form solution as it is (OK, t->cf),
 * against the full solve of the target from the tracker's q before the
 * step (dh_ikc_f32, every solution, the same q_ref): q_out is one of its
 * solutions bit for bit, and no solution within the limits (after the
 * 360-degree shift nearest q, with track_limit's 1e-4 deg and clamp) is faster to
 * reach (max |dq_i| / vmax_i) beyond the float rounding of the times. */
static void cf_is_nearest(rig *g, const float *qp, const dh_mat4_f32 *target, const float *q, const char *what,
                          long call)
{
    dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
    uint32_t ns = 0, k, i, hit = DH_IKC_MAX_SOL;
    double tm[DH_IKC_MAX_SOL];
    DHT_EQ_INT(dh_ikc_f32(&g->m, target, qp, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &ns), DH_OK);
    for (k = 0; k < ns; k++) {
        tm[k] = 0.0;
        if (hit == DH_IKC_MAX_SOL && memcmp(sol[k].q, q, g->r.n * sizeof(float)) == 0) hit = k;
        for (i = 0; i < g->r.n && tm[k] >= 0.0; i++) {
            const dh_joint *j = &g->r.joint[i];
            const int lim = j->qmin <= j->qmax, rev = j->type == DH_JOINT_REVOLUTE;
            const double tol = rev ? 1e-4 : 1e-7 * 4.0 * g->d->unit_per_m;
            double x = sol[k].q[i], best = 1e30;
            int c;
            for (c = -1; c <= 1; c++) {
                const double y = x + 360.0 * c;
                const double z = lim ? fmin(fmax(y, j->qmin), j->qmax) : y; /* track_limit's clamp */
                if ((c != 0 && (!rev || !lim)) || (lim && (y < j->qmin - tol || y > j->qmax + tol))) continue;
                if (fabs(z - qp[i]) < best) best = fabs(z - qp[i]);
            }
            if (best > 1e29) tm[k] = -1.0; /* outside the limits: not a candidate */
            else tm[k] = fmax(tm[k], best / (double)j->vmax);
        }
    }
    DHT_TRUE_MSG(hit < ns, "%s %s call %ld: q_out is none of the full solve's %u solutions", g->d->name, what, call,
                 (unsigned)ns);
    for (k = 0; k < ns; k++)
        if (tm[k] >= 0.0)
            DHT_TRUE_MSG(tm[k] >= tm[hit] * (1.0 - 1e-6),
                         "%s %s call %ld: solution %u reached in %.9g s, q_out's in %.9g s", g->d->name, what, call,
                         (unsigned)k, tm[k], tm[hit]);
    cf_checked++;
}

/* twin: step_checked of test_track_q.c */
static dh_track_state step_checked(rig *g, dh_track_f32 *t, chk *c, const dh_mat4_f32 *target, const char *what)
{
    float q[DH_MAX_JOINTS], qp[DH_MAX_JOINTS];
    dh_track_report_f32 rep;
    uint32_t i;
    dh_status st;
    memcpy(qp, t->q, sizeof qp);
    st = dh_track_step_f32(t, target, q, &rep);
    DHT_EQ_INT(st, DH_OK);
    if (g->closed && rep.state == DH_TRACK_OK && t->cf) {
        cf_is_nearest(g, qp, target, q, what, c->calls);
        if (!rep.measured) cf_unmeasured++;
    }
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
    /* not measured: OK by the closed form, its bounds within the
     * tolerances (FK checked above all the same), sigma_min proved at or
     * above the threshold */
    if (!rep.measured)
        DHT_TRUE_MSG(rep.state == DH_TRACK_OK && rep.pos_err == t->cfp && rep.rot_err == 2e-6f &&
                         rep.pos_err <= t->pos_tol && rep.rot_err <= t->rot_tol && !rep.near_singular &&
                         rep.sigma_min >= t->sing_threshold,
                     "%s %s call %ld: unmeasured report state %d, %.3g / %.3g, sigma_min %.3g", g->d->name, what,
                     c->calls, (int)rep.state, (double)rep.pos_err, (double)rep.rot_err, (double)rep.sigma_min);
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
        /* the closed-form steps were compared with the full solve, also
         * where every report was measured (the bound on sigma_min below
         * the threshold on the whole path) */
        DHT_TRUE(!g.closed || cf_checked > 0);
        dht_reach_max("smooth.cf_all_measured", (g.closed && cf_unmeasured == 0) ? 1.0 : 0.0);
        cf_checked = 0;
        cf_unmeasured = 0;
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

/* |det J| at q in double: the Jacobian of the double reference FK of the
 * robot's stored parameters (dhs_fk_ref_f32), then LU with partial
 * pivoting */
static double det_true(rig *g, const float *q)
{
    static dhr_mat4 F[DH_MAX_JOINTS]; /* off the stack: a 16 KB target runs this suite */
    dhr_mat4 T;
    double qd[DH_MAX_JOINTS], A[36], det = 1.0;
    int i, j, k;
    for (i = 0; i < 6; i++) qd[i] = q[i];
    dhs_fk_ref_f32(&g->r, qd, F, &T);
    for (i = 0; i < 6; i++) {
        /* joint i's axis: frame i - 1 (standard; the base for i = 0) or
         * frame i (modified) */
        const dhr_mat4 *B = (g->r.conv == DH_CONV_MODIFIED) ? &F[i] : (i == 0 ? NULL : &F[i - 1]);
        double z[3], o[3];
        for (k = 0; k < 3; k++) {
            z[k] = B ? B->m[2][k] : (double)g->r.base.m[2][k];
            o[k] = B ? B->m[3][k] : (double)g->r.base.m[3][k];
        }
        if (g->r.joint[i].type == DH_JOINT_REVOLUTE) {
            const double r0 = T.m[3][0] - o[0], r1 = T.m[3][1] - o[1], r2 = T.m[3][2] - o[2];
            A[0 * 6 + i] = z[1] * r2 - z[2] * r1;
            A[1 * 6 + i] = z[2] * r0 - z[0] * r2;
            A[2 * 6 + i] = z[0] * r1 - z[1] * r0;
            for (k = 0; k < 3; k++) A[(3 + k) * 6 + i] = z[k];
        } else {
            for (k = 0; k < 3; k++) {
                A[k * 6 + i] = z[k];
                A[(3 + k) * 6 + i] = 0.0;
            }
        }
    }
    for (k = 0; k < 6; k++) {
        int p = k;
        for (i = k + 1; i < 6; i++)
            if (fabs(A[i * 6 + k]) > fabs(A[p * 6 + k])) p = i;
        if (p != k)
            for (j = 0; j < 6; j++) {
                const double x = A[k * 6 + j];
                A[k * 6 + j] = A[p * 6 + j];
                A[p * 6 + j] = x;
            }
        det *= A[k * 6 + k];
        if (A[k * 6 + k] == 0.0) return 0.0;
        for (i = k + 1; i < 6; i++) {
            const double f = A[i * 6 + k] / A[k * 6 + k];
            for (j = k; j < 6; j++) A[i * 6 + j] -= f * A[k * 6 + j];
        }
    }
    return fabs(det);
}

/* The singularity measures of a step that reaches the target by the closed
 * form, on random configurations of every closed-form family and near
 * their singularities (joint 5's sine, UR joint 3's sine, down to 0):
 * - sing_threshold 0: the report holds the family's closed form of
 *   |det J| (measured 0) for every closed-form step: against |det J|
 *   of the Jacobian in double, and sigma_min below the true smallest
 *   singular value;
 * - the default threshold: not measured only where the bound proves
 *   sigma_min at or above it (so never where the true one is below);
 *   measured, the report's measures are dh_manipulability_f32's at q_out
 *   and near_singular its flag;
 * - pos_tol below the closed form's residual bound: the errors measured. */
static void closed_form_measures(void)
{
    static const dhs_robot *const fam[] = { &dhs_puma560_m, &dhs_ur5_m,     &dhs_kuka_kr5_m, &dhs_stanford_m,
                                            &dhs_ur3_m,     &dhs_ur10_m,    &dhs_abb_irb140_m, &dhs_puma560_mm,
                                            &dhs_ur5_mm,    &dhs_stanford_mm };
    size_t ri;
    for (ri = 0; ri < sizeof fam / sizeof fam[0]; ri++) {
        rig g;
        long k, n = DHT_ITER(400), cheap[2] = { 0, 0 }, total[2] = { 0, 0 };
        double worst = 0.0;
        char probe[64];
        rig_make(&g, fam[ri], INFINITY);
        DHT_TRUE(g.closed);
        for (k = 0; k < n; k++) {
            float q[DH_MAX_JOINTS], qo[DH_MAX_JOINTS], J[36], w, sg;
            dh_mat4_f32 T;
            dh_track_f32 t;
            dh_track_report_f32 rep;
            const int kind = (int)(k % 3);
            int tiny;
            random_q(&g, q);
            if (kind != 0) { /* near a singularity: 10^-6 .. 10 deg */
                const double dlt = pow(10.0, dht_rand_uniform(-6.0, 1.0)) * ((dht_rand_u32() & 1u) ? 1 : -1);
                const uint32_t jn = (kind == 2 && g.m.kind == DH_IKC_PARALLEL_234) ? 2u : 4u;
                q[jn] = (float)(-g.r.joint[jn].theta_deg + dlt);
                if (g.r.joint[jn].qmin <= g.r.joint[jn].qmax &&
                    (q[jn] < g.r.joint[jn].qmin || q[jn] > g.r.joint[jn].qmax))
                    continue;
            }
            target_of(&g, q, &T);
            for (tiny = 0; tiny < 2; tiny++) {
                DHT_EQ_INT(dh_track_init_f32(&t, &g.r, &g.m, q, DT), DH_OK);
                if (tiny) t.sing_threshold = 0.0f;
                DHT_EQ_INT(dh_track_step_f32(&t, &T, qo, &rep), DH_OK);
                if (rep.state != DH_TRACK_OK) continue;
                total[tiny]++;
                DHT_EQ_INT(dh_jacobian_f32(&g.r, qo, J, NULL), DH_OK);
                DHT_EQ_INT(dh_manipulability_f32(J, 6u, &w, &sg), DH_OK);
                if (rep.measured) {
                    DHT_TRUE(rep.manip == w && rep.sigma_min == sg && rep.near_singular == (sg < t.sing_threshold));
                    DHT_TRUE_MSG(tiny || sigma_true(&g, qo) >= t.sing_threshold || rep.near_singular ||
                                     sg >= t.sing_threshold,
                                 "%s: measured flag", g.d->name);
                } else {
                    const double dt = det_true(&g, qo), st = sigma_true(&g, qo);
                    const double L3 = pow(t.reach, 3.0);
                    /* relative, and near a singularity absolute: the
                     * cancellation of a factor's terms in float, 1e-7 L^3 */
                    const double err = fabs((double)rep.manip - dt) / (dt + 1e-3 * L3);
                    cheap[tiny]++;
                    worst = fmax(worst, err);
                    DHT_TRUE_MSG(err <= 1e-4, "%s q %s: |det J| %.9g by the closed form, %.9g in double",
                                 g.d->name, dhs_qf_str(qo, 6u, 0), (double)rep.manip, dt);
                    DHT_TRUE_MSG((double)rep.sigma_min <= st + 1e-6 * t.reach,
                                 "%s q %s: sigma_min bound %.9g above the true %.9g", g.d->name,
                                 dhs_qf_str(qo, 6u, 0), (double)rep.sigma_min, st);
                    DHT_TRUE(rep.sigma_min >= t.sing_threshold && !rep.near_singular);
                    if (!tiny) DHT_TRUE(st >= t.sing_threshold);
                }
            }
        }
        /* every family's closed form is exercised */
        DHT_TRUE_MSG(total[1] > 0 && 2 * cheap[1] >= total[1], "%s: %ld of %ld by the closed form of det J",
                     g.d->name, cheap[1], total[1]);
        snprintf(probe, sizeof probe, "detj.%s", g.d->name);
        dht_reach_max(probe, worst);
        printf("%s: %ld / %ld OK steps by the closed form of det J (default threshold), %ld / %ld (threshold "
               "0), worst relative error %.3g\n",
               g.d->name, cheap[0], total[0], cheap[1], total[1], worst);
    }
    /* pos_tol below the closed form's bound: the errors are measured */
    {
        rig g;
        dh_track_f32 t;
        dh_track_report_f32 rep;
        float q0[6] = { 10, -60, 70, 20, 40, 30 }, q[6];
        dh_mat4_f32 T;
        double ep, er;
        rig_make(&g, &dhs_ur5_m, INFINITY);
        target_of(&g, q0, &T);
        DHT_EQ_INT(dh_track_init_f32(&t, &g.r, &g.m, q0, DT), DH_OK);
        DHT_EQ_INT(dh_track_step_f32(&t, &T, q, &rep), DH_OK);
        DHT_TRUE(rep.state == DH_TRACK_OK && !rep.measured);
        DHT_EQ_INT(dh_track_init_f32(&t, &g.r, &g.m, q0, DT), DH_OK);
        t.pos_tol = 0.5f * t.cfp;
        DHT_EQ_INT(dh_track_step_f32(&t, &T, q, &rep), DH_OK);
        DHT_TRUE(rep.measured);
        dhs_true_error_f32(&g.r, q, &T, &ep, &er);
        DHT_TRUE(rep.state != DH_TRACK_OK || (ep <= t.pos_tol + 3e-7 && er <= t.rot_tol + 1e-6));
        DHT_EQ_INT(dh_track_init_f32(&t, &g.r, &g.m, q0, DT), DH_OK);
        t.rot_tol = 1e-6f;
        DHT_EQ_INT(dh_track_step_f32(&t, &T, q, &rep), DH_OK);
        DHT_TRUE(rep.measured);
    }
}

/* The pruned solve (dh_ikc_raw_win_f32_, the tracker's first solve)
 * against the full one (dh_ikc_raw_f32_) on random and near-singular
 * targets (joint 5, and joint 3 of PARALLEL_234, within 10^-6 .. 10 deg of
 * its singular value, or on it), with windows of 0.05 deg to unbounded per
 * joint about references near the target's configuration: every pruned
 * solution is one of the full solve's, bit for bit with its flags, in the
 * same order, and every full solution left out lies outside the window on
 * some revolute joint (in double, less the float rounding of the
 * solver's distance to the centre, 2^-24 of 360 deg). */
static void pruned_solve_is_full(void)
{
    static const dhs_robot *const fam[] = { &dhs_puma560_m, &dhs_ur5_m, &dhs_kuka_kr5_m, &dhs_stanford_m,
                                            &dhs_ur3_m,     &dhs_ur10_m, &dhs_abb_irb140_m };
    static const float ths[] = { 0.05f, 0.2f, 1.0f, 10.0f, 90.0f, INFINITY };
    size_t ri;
    long left = 0;
    for (ri = 0; ri < sizeof fam / sizeof fam[0]; ri++) {
        rig g;
        long k, n = DHT_ITER(300), kept = 0, all = 0;
        rig_make(&g, fam[ri], INFINITY);
        DHT_TRUE(g.closed);
        for (k = 0; k < n; k++) {
            dh_ikc_sol_f32 full[DH_IKC_MAX_SOL], part[DH_IKC_MAX_SOL];
            float q[DH_MAX_JOINTS], wq[18], *const qr = wq, *const win = wq + 6;
            dh_mat4_f32 T;
            uint32_t nf, np, i, j, p = 0;
            const int kind = (int)(k % 4);
            const double spread = pow(10.0, dht_rand_uniform(-3.0, 1.5));
            random_q(&g, q);
            if (kind == 1 || kind == 2) { /* near a singularity, or on it */
                const double dlt = (dht_rand_u32() & 3u) ? pow(10.0, dht_rand_uniform(-6.0, 1.0)) *
                                                               ((dht_rand_u32() & 1u) ? 1 : -1)
                                                         : 0.0;
                const uint32_t jn = (kind == 2 && g.m.kind == DH_IKC_PARALLEL_234) ? 2u : 4u;
                q[jn] = (float)(-g.r.joint[jn].theta_deg + dlt);
            }
            target_of(&g, q, &T);
            for (i = 0; i < 6u; i++) {
                const int rev = g.r.joint[i].type == DH_JOINT_REVOLUTE;
                qr[i] = (float)(q[i] + (rev ? dht_rand_uniform(-spread, spread) : 0.0));
                win[i] = dh_ikc_ref_f32_(qr[i] + g.m.off[i]);
                win[6u + i] = rev ? ths[dht_rand_u32() % 6u] : INFINITY;
            }
            DHT_EQ_INT(dh_ikc_args_f32_(&g.m, &T, qr, DH_IKC_KEEP_OUT_OF_LIMITS), DH_OK);
            nf = dh_ikc_raw_f32_(&g.m, &T, qr, full);
            np = dh_ikc_raw_win_f32_(&g.m, &T, wq, part);
            DHT_TRUE(nf <= DH_IKC_MAX_SOL && np <= nf);
            for (j = 0; j < nf; j++) {
                if (p < np && memcmp(&full[j], &part[p], sizeof full[j]) == 0) {
                    p++;
                    continue;
                }
                /* left out: outside the window on some revolute joint */
                {
                    int out = 0;
                    for (i = 0; i < 6u; i++) {
                        const double d = fmod(fabs((double)full[j].q[i] - win[i]), 360.0);
                        if (fmin(d, 360.0 - d) > (double)win[6u + i] - 2.2e-5) out = 1;
                    }
                    DHT_TRUE_MSG(out, "%s q %s: full solution %u left out within the window", g.d->name,
                                 dhs_qf_str(q, 6u, 0), (unsigned)j);
                }
                left++;
            }
            DHT_TRUE_MSG(p == np, "%s q %s: pruned solution %u is none of the full solve's in order", g.d->name,
                         dhs_qf_str(q, 6u, 0), (unsigned)p);
            kept += np;
            all += nf;
        }
        printf("%s: %ld targets, %ld of %ld solutions within the windows\n", g.d->name, n, kept, all);
    }
    /* the windows left solutions out */
    DHT_TRUE(left > 0);
}

static const dht_case cases[] = {
    DHT_CASE(bad_targets_brake),
    DHT_CASE(smooth_paths_every_call_ok),
    DHT_CASE(singular_lines),
    DHT_CASE(leaving_the_workspace),
    DHT_CASE(target_jumps),
    DHT_CASE(sync_continues),
    DHT_CASE(closed_form_measures),
    DHT_CASE(pruned_solve_is_full),
};

DHT_MAIN(cases)
