/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_track_q.c - the fixed-point tracker on the Puma 560, UR5, KUKA KR5,
 * Stanford arm (closed form) and Panda (damped steps only), all in mm,
 * seeded random paths, 1 kHz. Every call is checked in exact integers
 * against the guarantees of track.h, with bounds computed here from the
 * robot's rates (not read from the tracker): |step| <= floor(vmax_q dt_us /
 * 10^6), the joint limits, and with amax |step - previous step| <= A =
 * floor(floor(amax_q dt_us / 10^6) dt_us / 10^6) and the braking condition
 * s^2 <= 2 A D (D the distance left to the limit ahead); DH_TRACK_OK only when the
 * double reference FK (support_robots.c) of q_out is within pos_tol and
 * rot_tol of the target (plus the fixed FK's own error, 4 n LSB of
 * position and 1e-6 rad). Paths as test_track.c: smooth paths at half
 * vmax away from singularities (every call OK for the closed-form robots),
 * lines 1 mm from the wrist singularity and through the shoulder
 * singularity then held (OK again within the time the step bound allows),
 * a line leaving the workspace and coming back, a target that jumps (with
 * and without amax). A report without FK (measured 0) must hold the closed
 * form's bounds with state OK and a singularity bound at most the smallest
 * singular value of the double Jacobian; |det J| without J is checked
 * against double near each singularity (detj_against_double), the
 * defaults and the measured cases in defaults_and_measured. The closed form is used only for a robot whose reach
 * fits its range (ikc.h: 2^30 LSB, 2^(30 - DH_QPOS_FRAC) mm): with
 * DH_QPOS_FRAC 20 (1024 mm) the robots in mm are tracked by damped steps
 * only, and the line leaving the workspace stops within the format.
 */
#include "dht.h"
#include "support_robots.h"
#include "dhmath/track.h"
#include "dhmath/frame.h"
#include "../../src/ikc/ikc_impl.h"   /* dh_ikc_detj_q_ against double */

#include <math.h>
#include <string.h>

#define DT_US 1000u
#define QPOS ((double)((int32_t)1 << DH_QPOS_FRAC))
#define VMAX_R (180 * 65536)            /* 180 deg/s */
#define AMAX_R (720 * 65536)            /* 720 deg/s^2 */

typedef struct {
    const dhs_robot *d;
    dh_robot r;
    dh_ikc_model_q m;
    int closed;
    int64_t dqm[DH_MAX_JOINTS], A[DH_MAX_JOINTS];   /* the bounds, computed here */
} rig;

/* a bound on the distance of the tool from the base, mm: the lengths, the
 * prismatic travel, the base and tool offsets */
static double reach_mm(const dhs_robot *d)
{
    double L = 0.0;
    unsigned i;
    for (i = 0; i < d->n; i++) {
        const dhs_joint_desc *j = &d->j[i];
        L += fabs(j->a) + fabs(j->d);
        if (j->type == DH_JOINT_PRISMATIC) L += fmax(fabs(j->qmin), fabs(j->qmax));
    }
    for (i = 0; i < 3; i++) L += fabs(DHR_M4(&d->base, i, 3)) + fabs(DHR_M4(&d->tool, i, 3));
    return L;
}

static void rig_make(rig *g, const dhs_robot *d, int acc)
{
    uint32_t i;
    g->d = d;
    DHT_EQ_INT(dhs_build_q(d, &g->r), DH_OK);
    for (i = 0; i < g->r.n; i++) {
        const int rev = g->r.joint[i].type == DH_JOINT_REVOLUTE;
        const int32_t v = rev ? VMAX_R : (int32_t)(500.0 * QPOS);      /* 500 mm/s */
        const int32_t a = acc ? (rev ? AMAX_R : (int32_t)(1000.0 * QPOS)) : INT32_MAX;
        DHT_EQ_INT(dh_robot_set_rates_q(&g->r, i, v, a), DH_OK);
        g->dqm[i] = ((int64_t)v * DT_US) / 1000000;
        g->A[i] = acc ? ((((int64_t)a * DT_US) / 1000000) * DT_US) / 1000000 : -1;
    }
    g->closed = dh_ikc_analyse_q(&g->r, &g->m) == DH_OK && g->m.kind != DH_IKC_NONE &&
                reach_mm(d) <= ldexp(1.0, 30 - DH_QPOS_FRAC);
}

typedef struct {
    int32_t qp[DH_MAX_JOINTS];
    int64_t sp[DH_MAX_JOINTS];
    long calls, ok, lag, unr, cf;   /* cf: OK reports without FK (measured 0) */
} chk;

static void chk_start(chk *c, const int32_t *q0, uint32_t n)
{
    memset(c, 0, sizeof *c);
    memcpy(c->qp, q0, n * sizeof(int32_t));
}

static int last_near_singular;
static dh_track_report_q last_rep;   /* the last call's report */

/* the Jacobian of the fixed robot's parameters at q in double (linear
 * rows in the robot's unit per rad, reference point the tool point) from
 * the reference FK's frames: |det J| (6 joints) and its smallest singular
 * value into *sg */
static double jac_double(const dh_robot *r, const int32_t *q, double *sg)
{
    dhr_mat4 F[DHS_MAX_JOINTS], T, B;
    double J[36], A[36], ev[6], det = 1.0;
    int i, j, k;
    dhs_fk_ref_q(r, q, F, &T);
    dhr_from_q(&r->base_q, &B);
    for (i = 0; i < 6; i++) {
        const dhr_mat4 *Z = (r->conv == DH_CONV_STANDARD) ? (i == 0 ? &B : &F[i - 1]) : &F[i];
        double z[3], d[3];
        for (k = 0; k < 3; k++) {
            z[k] = DHR_M4(Z, k, 2);
            d[k] = DHR_M4(&T, k, 3) - DHR_M4(Z, k, 3);
        }
        for (k = 0; k < 3; k++) {
            const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
            if (r->joint[i].type == DH_JOINT_REVOLUTE) {
                J[k * 6 + i] = z[k1] * d[k2] - z[k2] * d[k1];
                J[(k + 3) * 6 + i] = z[k];
            } else {
                J[k * 6 + i] = z[k];
                J[(k + 3) * 6 + i] = 0.0;
            }
        }
    }
    for (i = 0; i < 6; i++)
        for (j = 0; j < 6; j++) {
            double v = 0.0;
            for (k = 0; k < 6; k++) v += J[i * 6 + k] * J[j * 6 + k];
            A[i * 6 + j] = v;
        }
    dhr_sym_eig(A, 6, ev);
    *sg = ev[0];
    for (i = 1; i < 6; i++) *sg = fmin(*sg, ev[i]);
    *sg = sqrt(fmax(*sg, 0.0));
    /* |det J| by elimination with partial pivoting */
    for (k = 0; k < 6; k++) {
        int p = k;
        for (i = k + 1; i < 6; i++)
            if (fabs(J[i * 6 + k]) > fabs(J[p * 6 + k])) p = i;
        if (J[p * 6 + k] == 0.0) return 0.0;
        if (p != k)
            for (j = 0; j < 6; j++) {
                const double x = J[k * 6 + j];
                J[k * 6 + j] = J[p * 6 + j];
                J[p * 6 + j] = x;
            }
        det *= J[k * 6 + k];
        for (i = k + 1; i < 6; i++) {
            const double f = J[i * 6 + k] / J[k * 6 + k];
            for (j = k; j < 6; j++) J[i * 6 + j] -= f * J[k * 6 + j];
        }
    }
    return fabs(det);
}

/* one robot and one tracker for every case (the M0 target has 16 KB of RAM) */
static rig the_rig;
static dh_track_q the_trk;

/* one call with every guarantee checked; returns the state (twin: step_checked of test_track.c) */
static dh_track_state step_checked(rig *g, dh_track_q *t, chk *c, const dh_frame_q *target, const char *what)
{
    int32_t q[DH_MAX_JOINTS];
    dh_track_report_q rep;
    uint32_t i;
    DHT_EQ_INT(dh_track_step_q(t, target, q, &rep), DH_OK);
    for (i = 0; i < g->r.n; i++) {
        const dh_joint *j = &g->r.joint[i];
        const int64_t s = (int64_t)q[i] - c->qp[i];
        DHT_TRUE_MSG(s <= g->dqm[i] && s >= -g->dqm[i], "%s %s call %ld: joint %u step %lld beyond %lld",
                     g->d->name, what, c->calls, (unsigned)i, (long long)s, (long long)g->dqm[i]);
        if (j->qmin_q <= j->qmax_q)
            DHT_TRUE_MSG(q[i] >= j->qmin_q && q[i] <= j->qmax_q, "%s %s call %ld: joint %u outside its limits",
                         g->d->name, what, c->calls, (unsigned)i);
        if (g->A[i] >= 0) {
            const int64_t A = g->A[i];
            DHT_TRUE_MSG(s - c->sp[i] <= A && c->sp[i] - s <= A, "%s %s call %ld: joint %u step change %lld > %lld",
                         g->d->name, what, c->calls, (unsigned)i, (long long)(s - c->sp[i]), (long long)A);
            if (j->qmin_q <= j->qmax_q && A > 0) {
                /* braking: v^2 <= 2 amax D, D the distance left to the limit ahead */
                const int64_t D = (s > 0) ? (int64_t)j->qmax_q - q[i] : (int64_t)q[i] - j->qmin_q;
                const double sa = fabs((double)s);
                DHT_TRUE_MSG(sa * sa <= 2.0 * (double)A * (double)D,
                             "%s %s call %ld: joint %u cannot stop before its limit", g->d->name, what, c->calls, (unsigned)i);
            }
        }
        c->sp[i] = s;
        c->qp[i] = q[i];
    }
    if (rep.state == DH_TRACK_OK) {
        dhr_mat4 F[DHS_MAX_JOINTS], T;
        double ep, er;
        dhs_fk_ref_q(&g->r, q, F, &T);
        ep = dhs_pos_err_q(target, &T);
        er = dhs_rot_err_q(target, &T);
        DHT_TRUE_MSG(ep <= (t->pos_tol + 4.0 * g->r.n) / QPOS && er <= t->rot_tol / 536870912.0 + 1e-6,
                     "%s %s call %ld: OK with error %.3g / %.3g rad", g->d->name, what, c->calls, ep, er);
        c->ok++;
    } else if (rep.state == DH_TRACK_LAGGING) {
        c->lag++;
    } else {
        c->unr++;
    }
    DHT_TRUE(rep.sigma_min >= 0);
    DHT_TRUE(rep.measured == 0 || rep.measured == 1);
    if (!rep.measured) {
        /* the closed form's bounds, and a singularity bound without J:
         * at most the smallest singular value (every 8th call: double
         * eigenvalues are slow on the M0) */
        DHT_EQ_INT(rep.state, DH_TRACK_OK);
        DHT_EQ_INT(rep.pos_err, t->cf_pos);
        DHT_EQ_INT(rep.rot_err, DH_TRACK_CF_ROT_Q);
        DHT_TRUE(rep.near_singular == 0 && rep.sigma_min >= t->sing_threshold);
        if ((c->cf & 7) == 0) {
            double sg;
            (void)jac_double(&g->r, q, &sg);
            DHT_TRUE_MSG(rep.sigma_min / QPOS <= sg, "%s %s call %ld: sigma bound %.6g above sigma_min %.6g",
                         g->d->name, what, c->calls, rep.sigma_min / QPOS, sg);
        }
        c->cf++;
    } else {
        DHT_EQ_INT(rep.near_singular, rep.sigma_min < t->sing_threshold);
    }
    last_near_singular = rep.near_singular;
    last_rep = rep;
    c->calls++;
    return rep.state;
}

/* at the tracker's q: the smallest over the closed-form solutions of the
 * target of max_i |solution_i - q_i| / dq_max_i (> 1: none in the step
 * box; twin: box_ratio of test_track.c) */
static double box_ratio(rig *g, const dh_track_q *t, const dh_frame_q *target)
{
    dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
    uint32_t ns = 0, k, i;
    double best = 1e30;
    if (dh_ikc_q(&g->m, target, t->q, 0u, sol, &ns) != DH_OK) return 0.0;
    for (k = 0; k < ns; k++) {
        double r = 0.0;
        for (i = 0; i < g->r.n; i++) r = fmax(r, fabs((double)sol[k].q[i] - t->q[i]) / (double)g->dqm[i]);
        best = fmin(best, r);
    }
    return best;
}

/* the target held: OK again, after the last call in the singular
 * neighbourhood, within the time the step bound allows for the distance
 * left from there (plus 2 calls); then OK every call (twin: hold_until_ok of test_track.c) */
static void hold_until_ok(rig *g, dh_track_q *t, chk *c, const dh_frame_q *target, const char *what, long max_calls)
{
    int32_t q_mark[DH_MAX_JOINTS];
    long k, first_ok = -1, mark = 0;
    double need = 0.0;
    uint32_t i;
    memcpy(q_mark, t->q, sizeof q_mark);
    for (k = 0; k < max_calls; k++) {
        const dh_track_state s = step_checked(g, t, c, target, what);
        if (s == DH_TRACK_OK && first_ok < 0) first_ok = k;
        /* the target reached, the nearest closed-form solution maybe
         * outside the step box: q stays */
        if (s == DH_TRACK_OK && g->closed)
            dht_reach_max(last_near_singular ? "hold.ok_box_ratio" : "hold.ok_far_box_ratio", box_ratio(g, t, target));
        if (s != DH_TRACK_OK && last_near_singular) {
            mark = k + 1;
            memcpy(q_mark, t->q, sizeof q_mark);
        }
        if (first_ok >= 0) DHT_TRUE_MSG(s == DH_TRACK_OK, "%s %s: OK lost at hold call %ld", g->d->name, what, k);
        if (first_ok >= 0 && k > first_ok + 5) break;
    }
    DHT_TRUE_MSG(first_ok >= 0, "%s %s: never OK in %ld calls of a held target", g->d->name, what, max_calls);
    for (i = 0; i < g->r.n; i++) {
        const double steps = fabs((double)t->q[i] - q_mark[i]) / (double)g->dqm[i];
        if (steps > need) need = steps;
    }
    DHT_TRUE_MSG(first_ok - mark <= (long)ceil(need) + 2, "%s %s: OK %ld calls after the singular neighbourhood, the bound allows %.1f",
                 g->d->name, what, first_ok - mark + 1, need);
}

/* the fixed target of configuration q (double reference FK of the fixed robot) */
static void target_of(rig *g, const int32_t *q, dh_frame_q *T)
{
    dhr_mat4 F[DHS_MAX_JOINTS], R;
    dhs_fk_ref_q(&g->r, q, F, &R);
    dhs_to_frame_q(&R, T);
}

static void random_q(rig *g, int32_t *q)
{
    double qd[DHS_MAX_JOINTS];
    dhs_random_q(g->d, qd);
    dhs_q_from_double(&g->r, qd, q);
}

static int reachable(rig *g, const dh_frame_q *T, const int32_t *q_ref)
{
    dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
    uint32_t ns = 0;
    return !g->closed || dh_ikc_q(&g->m, T, q_ref, 0u, sol, &ns) == DH_OK;
}

/* smallest singular value of the fixed Jacobian at q with its linear rows
 * in metres (double, Jacobi): the selection test_track.c makes */
static double sigma_true(rig *g, const int32_t *q)
{
    int32_t J[6 * DH_MAX_JOINTS];
    double A[36], ev[6], mn;
    int i, j, k;
    const int n = (int)g->r.n;
    (void)dh_jacobian_q(&g->r, q, J, NULL);
    for (i = 0; i < 6; i++)
        for (j = 0; j < 6; j++) {
            double v = 0;
            for (k = 0; k < n; k++) {
                const int ri = i < 3 && g->r.joint[k].type == DH_JOINT_REVOLUTE, rj = j < 3 && g->r.joint[k].type == DH_JOINT_REVOLUTE;
                /* linear rows in metres, as test_track.c's robots in m */
                const double si = ri ? g->d->unit_per_m : 1.0, sj = rj ? g->d->unit_per_m : 1.0;
                v += (J[i * n + k] / (ri ? QPOS : 1073741824.0) / si) * (J[j * n + k] / (rj ? QPOS : 1073741824.0) / sj);
            }
            A[i * 6 + j] = v;
        }
    dhr_sym_eig(A, 6, ev);
    mn = ev[0];
    for (i = 1; i < 6; i++) mn = fmin(mn, ev[i]);
    return sqrt(fmax(mn, 0.0));
}

static const dhs_robot *const robots[] = { &dhs_puma560_mm, &dhs_ur5_mm, &dhs_kuka_kr5_mm, &dhs_stanford_mm,
                                           &dhs_panda_mm };
#define N_ROBOTS (sizeof robots / sizeof robots[0])

/* smooth paths: every call OK (closed form) */
static void smooth_paths_every_call_ok(void)
{
    size_t ri;
    for (ri = 0; ri < N_ROBOTS; ri++) {
        rig *const gp = &the_rig;
        long path, n_path = DHT_ITER(8), calls = 0, not_ok = 0, cf = 0;
        rig_make(gp, robots[ri], 0);
        for (path = 0; path < n_path; path++) {
            int32_t qa[DH_MAX_JOINTS], qb[DH_MAX_JOINTS], q[DH_MAX_JOINTS];
            double dmax = 0.0, T;
            long k, N;
            uint32_t i;
            int tries = 0, good;
            dh_track_q *const tp = &the_trk;
            chk c;
            do {
                random_q(gp, qa);
                for (i = 0; i < gp->r.n; i++) {
                    const dh_joint *j = &gp->r.joint[i];
                    const double span = (j->type == DH_JOINT_REVOLUTE) ? 40.0 * 65536 : 100.0 * QPOS;
                    double v = qa[i] + dht_rand_uniform(-span, span);
                    if (j->qmin_q <= j->qmax_q) v = fmin(fmax(v, j->qmin_q), j->qmax_q);
                    qb[i] = (int32_t)v;
                }
                good = 1;
                for (k = 0; k <= 20 && good; k++) {
                    for (i = 0; i < gp->r.n; i++) q[i] = qa[i] + (int32_t)((double)(qb[i] - qa[i]) * k / 20.0);
                    if (sigma_true(gp, q) < 1e-2) good = 0;
                }
            } while (!good && ++tries < 100);
            DHT_TRUE(good);
            for (i = 0; i < gp->r.n; i++) dmax = fmax(dmax, fabs((double)qb[i] - qa[i]) / (double)gp->r.joint[i].vmax_q);
            T = dmax * 3.14159265358979 + 0.01;   /* cosine profile: peak rate vmax / 2 */
            N = (long)(T * 1e6 / DT_US) + 1;
            DHT_EQ_INT(dh_track_init_q(tp, &gp->r, gp->closed ? &gp->m : NULL, qa, DT_US), DH_OK);
            chk_start(&c, qa, gp->r.n);
            for (k = 1; k <= N; k++) {
                const double s = 0.5 - 0.5 * cos(3.14159265358979 * (double)k / (double)N);
                dh_frame_q Tg;
                for (i = 0; i < gp->r.n; i++) q[i] = qa[i] + (int32_t)floor((double)(qb[i] - qa[i]) * s + 0.5);
                target_of(gp, q, &Tg);
                /* a target on a limit that a 360-degree shift keeps in range:
                 * the closed form may return the shifted value */
                for (i = 0; i < gp->r.n; i++) {
                    const dh_joint *j = &gp->r.joint[i];
                    const int64_t turn = (int64_t)360 << 16;
                    if (gp->closed && j->type == DH_JOINT_REVOLUTE && j->qmin_q <= j->qmax_q &&
                        ((q[i] >= j->qmax_q - 8 && q[i] - turn >= j->qmin_q) ||
                         (q[i] <= j->qmin_q + 8 && q[i] + turn <= j->qmax_q)))
                        dht_reach_max("smooth.limit_turn", 1.0);
                }
                if (step_checked(gp, tp, &c, &Tg, "smooth") != DH_TRACK_OK) {
                    DHT_TRUE_MSG(!gp->closed, "%s smooth path %ld call %ld: state %d, errors %ld LSB / %ld (Q29 rad)",
                                 gp->d->name, path, k, (int)last_rep.state, (long)last_rep.pos_err, (long)last_rep.rot_err);
                    not_ok++;
                }
            }
            calls += c.calls;
            cf += c.cf;
        }
        dht_printf("%s: %ld smooth paths, %ld calls, %ld not OK, %ld OK without FK\n", gp->d->name, n_path, calls,
                   not_ok, cf);
    }
}

/* a line of length 2h (mm) through p_s + off, orientation fixed */
static void line_target(const dh_frame_q *Ts, const double *off, const double *u, double h, double s, dh_frame_q *T)
{
    int k;
    *T = *Ts;
    for (k = 0; k < 3; k++) T->p[k] = Ts->p[k] + (int32_t)floor((off[k] + u[k] * h * (2 * s - 1)) * QPOS + 0.5);
}

static int start_at(rig *g, dh_track_q *t, chk *c, const dh_frame_q *T0, const int32_t *q_near)
{
    dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
    uint32_t ns = 0, idx = 0;
    if (dh_ikc_q(&g->m, T0, q_near, 0u, sol, &ns) != DH_OK) return 0;
    DHT_EQ_INT(dh_ikc_nearest_q(sol, ns, q_near, g->r.n, &idx), DH_OK);
    DHT_EQ_INT(dh_track_init_q(t, &g->r, &g->m, sol[idx].q, DT_US), DH_OK);
    chk_start(c, sol[idx].q, g->r.n);
    return 1;
}

/* lines 1 mm from the wrist singularity and through the shoulder singularity, then held */
static void singular_lines(void)
{
    size_t ri;
    for (ri = 0; ri < 4u; ri++) {
        rig *const gp = &the_rig;
        long line, n_line = DHT_ITER(8), lag = 0, calls = 0;
        rig_make(gp, robots[ri], 0);
        if (reach_mm(robots[ri]) > ldexp(1.0, 30 - DH_QPOS_FRAC)) {
            dht_printf("%s: reach beyond the closed form's range at DH_QPOS_FRAC %d, no singular lines\n",
                       gp->d->name, DH_QPOS_FRAC);
            continue;
        }
        DHT_TRUE(gp->closed);
        for (line = 0; line < n_line; line++) {
            int32_t qs[DH_MAX_JOINTS];
            dh_frame_q Ts, T;
            double off[3], u[3], h = 50.0;
            const double speed = 100.0;   /* mm/s */
            long k, N = (long)(2 * h / speed * 1e6 / DT_US);
            dh_track_q *const tp = &the_trk;
            chk c;
            int k3;
            const int shoulder = (int)(line & 1);
            random_q(gp, qs);
            if (!shoulder) {
                qs[4] = 0;
                dhr_rand_unit3(off);
                for (k3 = 0; k3 < 3; k3++) off[k3] *= 1.0;   /* 1 mm */
            } else {
                off[0] = off[1] = off[2] = 0.0;
            }
            target_of(gp, qs, &Ts);
            dhr_rand_unit3(u);
            if (shoulder) {
                const double x = Ts.p[0] / QPOS, y = Ts.p[1] / QPOS, r0 = sqrt(x * x + y * y);
                u[0] = x / r0;
                u[1] = y / r0;
                u[2] = 0.0;
                off[0] = -x;
                off[1] = -y;
                h = fmin(r0, 300.0);
                N = (long)(2 * h / speed * 1e6 / DT_US);
            }
            line_target(&Ts, off, u, h, 1.0, &T);
            if (!reachable(gp, &T, qs)) continue;
            line_target(&Ts, off, u, h, 0.0, &T);
            if (!start_at(gp, tp, &c, &T, qs)) continue;
            for (k = 1; k <= N; k++) {
                line_target(&Ts, off, u, h, (double)k / (double)N, &T);
                (void)step_checked(gp, tp, &c, &T, shoulder ? "shoulder line" : "wrist line");
            }
            hold_until_ok(gp, tp, &c, &T, shoulder ? "shoulder line end" : "wrist line end", 20000);
            lag += c.lag + c.unr;
            calls += c.calls;
        }
        dht_printf("%s: %ld singular lines, %ld calls, %ld not OK\n", gp->d->name, n_line, calls, lag);
    }
}

/* out of the workspace and back (twin: leaving_the_workspace of test_track.c) */
static void leaving_the_workspace(void)
{
    size_t ri;
    for (ri = 0; ri < N_ROBOTS; ri++) {
        rig *const gp = &the_rig;
        long line, n_line = DHT_ITER(4), unr = 0, back = 0, short_of = 0;
        rig_make(gp, robots[ri], 0);
        for (line = 0; line < n_line; line++) {
            int32_t qs[DH_MAX_JOINTS];
            dh_frame_q Ts, T;
            double u[3], r0, h;
            int outside;
            const double speed = 200.0;
            long k, N;
            dh_track_q *const tp = &the_trk;
            chk c;
            random_q(gp, qs);
            target_of(gp, qs, &Ts);
            r0 = sqrt((double)Ts.p[0] * Ts.p[0] + (double)Ts.p[1] * Ts.p[1] + (double)Ts.p[2] * Ts.p[2]) / QPOS;
            for (k = 0; k < 3; k++) u[k] = Ts.p[k] / QPOS / r0;
            /* 2 m out, or as far as the format represents (3 % short of
             * 2^31 LSB: with DH_QPOS_FRAC 20 the KR5's reach is beyond it,
             * and only the per-call guarantees are checked) */
            h = fmin(2000.0, 0.97 * ldexp(1.0, 31 - DH_QPOS_FRAC) - r0);
            outside = r0 + h > 1.01 * reach_mm(gp->d);
            if (!outside) short_of++;
            N = (long)(h / speed * 1e6 / DT_US);
            DHT_EQ_INT(dh_track_init_q(tp, &gp->r, gp->closed ? &gp->m : NULL, qs, DT_US), DH_OK);
            chk_start(&c, qs, gp->r.n);
            for (k = 1; k <= 2 * N; k++) {
                const double s = (k <= N) ? (double)k / N : (double)(2 * N - k) / N;
                int j;
                T = Ts;
                for (j = 0; j < 3; j++) T.p[j] = Ts.p[j] + (int32_t)floor(u[j] * h * s * QPOS + 0.5);
                (void)step_checked(gp, tp, &c, &T, "workspace line");
            }
            DHT_TRUE_MSG(c.unr > 0 || !outside, "%s: a target %.0f mm outside the reach never UNREACHABLE",
                         gp->d->name, r0 + h - reach_mm(gp->d));
            if (gp->closed) {
                hold_until_ok(gp, tp, &c, &Ts, "workspace line end", 40000);
            } else {
                /* damped steps alone can stall stretched against a joint
                 * limit: the guarantees are checked, the return counted */
                for (k = 0; k < 5000; k++)
                    if (step_checked(gp, tp, &c, &Ts, "workspace line end, damped only") == DH_TRACK_OK) break;
                if (k < 5000) back++;
            }
            unr += c.unr;
        }
        dht_printf("%s: %ld lines out of the workspace (%ld ending within the reach: the format's range), "
                   "%ld calls UNREACHABLE%s", gp->d->name, n_line, short_of, unr, gp->closed ? "\n" : "");
        if (!gp->closed) dht_printf(", %ld reached again by damped steps only\n", back);
    }
}

/* a jump of the target: no jump of the joints; with amax no velocity step */
static void target_jumps(void)
{
    size_t ri;
    int acc;
    for (acc = 0; acc < 2; acc++)
        for (ri = 0; ri < N_ROBOTS; ri++) {
            rig *const gp = &the_rig;
            long jump, n_jump = DHT_ITER(6), calls = 0, reached = 0;
            rig_make(gp, robots[ri], acc);
            for (jump = 0; jump < n_jump; jump++) {
                int32_t qa[DH_MAX_JOINTS], qb[DH_MAX_JOINTS];
                dh_frame_q Ta, Tb;
                dh_track_q *const tp = &the_trk;
                chk c;
                long k;
                uint32_t i;
                random_q(gp, qa);
                for (i = 0; i < gp->r.n; i++) {
                    const dh_joint *j = &gp->r.joint[i];
                    const double span = (j->type == DH_JOINT_REVOLUTE) ? 30.0 * 65536 : 50.0 * QPOS;
                    double v = qa[i] + dht_rand_uniform(-span, span);
                    if (j->qmin_q <= j->qmax_q) v = fmin(fmax(v, j->qmin_q), j->qmax_q);
                    qb[i] = (int32_t)v;
                }
                if (sigma_true(gp, qb) < 1e-2 || sigma_true(gp, qa) < 1e-2) continue;
                target_of(gp, qa, &Ta);
                target_of(gp, qb, &Tb);
                if (!reachable(gp, &Tb, qa) || !reachable(gp, &Ta, qa)) continue;
                DHT_EQ_INT(dh_track_init_q(tp, &gp->r, gp->closed ? &gp->m : NULL, qa, DT_US), DH_OK);
                chk_start(&c, qa, gp->r.n);
                for (k = 0; k < 5; k++) (void)step_checked(gp, tp, &c, &Ta, "before the jump");
                if (acc) {
                    long first_ok = -1;
                    for (k = 0; k < 20000 && first_ok < 0; k++)
                        if (step_checked(gp, tp, &c, &Tb, "jump with amax") == DH_TRACK_OK) first_ok = k;
                    DHT_TRUE_MSG(first_ok >= 0 || !gp->closed, "%s: jump with amax never reached", gp->d->name);
                } else if (gp->closed) {
                    hold_until_ok(gp, tp, &c, &Tb, "jump", 20000);
                } else {
                    for (k = 0; k < 5000; k++)
                        if (step_checked(gp, tp, &c, &Tb, "jump, damped only") == DH_TRACK_OK) break;
                    if (k < 5000) reached++;
                }
                calls += c.calls;
            }
            dht_printf("%s: %ld target jumps%s, %ld calls, %ld reached by damped steps only\n", gp->d->name, n_jump,
                       acc ? " with amax" : "", calls, reached);
        }
}

/* |det J| of the closed form's model (dh_ikc_detj_q_, the tracker's
 * singularity bound without J) against double on random configurations
 * and near each singularity (joint 5 and 3 near 0 and 180 deg, the wrist
 * centre near axis 1): a lower bound, within 2^-20 relative and 2^-20
 * L^3 of the true value; then the tracker at such configurations: its
 * report without J only where its bound proves sigma_min >= threshold,
 * and a bound at most the true smallest singular value */
static void detj_against_double(void)
{
    size_t ri;
    for (ri = 0; ri < 4u; ri++) {
        rig *const gp = &the_rig;
        dh_track_q *const tp = &the_trk;
        long k, n = DHT_ITER(400), cfs = 0, near = 0;
        double L = 0.0, worst = 0.0;
        uint32_t i;
        rig_make(gp, robots[ri], 0);
        if (!gp->closed) continue;
        for (i = 0; i < 6u; i++) L += fabs(ldexp(gp->r.joint[i].a_q, -DH_QPOS_FRAC)) + fabs(ldexp(gp->r.joint[i].d_q, -DH_QPOS_FRAC));
        L += reach_mm(gp->d);
        for (k = 0; k < n; k++) {
            int32_t q[DH_MAX_JOINTS], qo[DH_MAX_JOINTS];
            double det, sg, lo;
            uint32_t mant;
            int32_t ex;
            dh_frame_q T;
            dh_track_report_q rep;
            random_q(gp, q);
            if (k % 4 == 1) {
                /* joint 5, or the elbow, or joint 1's lever near 0: up to 1e-3 deg from a zero of its factor */
                const uint32_t j = (k % 12 == 1) ? 4u : 2u;
                const double z = dht_rand_uniform(-1e-3, 1e-3) + ((k % 8 == 1) ? 180.0 : 0.0);
                if (gp->r.joint[j].type == DH_JOINT_REVOLUTE) {
                    const double v = z - ldexp(gp->m.off[j], -16);
                    if (v * 65536.0 >= gp->r.joint[j].qmin_q && v * 65536.0 <= gp->r.joint[j].qmax_q) q[j] = (int32_t)floor(v * 65536.0);
                }
            }
            det = jac_double(&gp->r, q, &sg);
            mant = dh_ikc_detj_q_(&gp->m, q, &ex);
            lo = ldexp((double)mant, ex);
            DHT_TRUE_MSG(lo <= det * (1.0 + 1e-12), "%s: |det J| bound %.9g above %.9g", gp->d->name, lo, det);
            DHT_TRUE_MSG(det - lo <= ldexp(det, -20) + ldexp(L * L * L, -20), "%s: |det J| bound %.9g, true %.9g",
                         gp->d->name, lo, det);
            if (det > 0.0) worst = fmax(worst, (det - lo) / (det + L * L * L));
            /* the tracker at q, the target FK(q): a zero step, OK */
            DHT_EQ_INT(dh_track_init_q(tp, &gp->r, &gp->m, q, DT_US), DH_OK);
            target_of(gp, q, &T);
            DHT_EQ_INT(dh_track_step_q(tp, &T, qo, &rep), DH_OK);
            DHT_EQ_INT(rep.state, DH_TRACK_OK);
            if (!rep.measured) {
                /* manip: log2 of the bound at q_out (the closed-form
                 * solution of FK(q), q up to rounding), less than 8 LSB
                 * below (trq_log2); sigma_min at most the true one at q_out */
                const double lg = 65536.0 * log2(ldexp((double)dh_ikc_detj_q_(&gp->m, qo, &ex), ex));
                (void)jac_double(&gp->r, qo, &sg);
                DHT_TRUE_MSG(rep.manip <= lg + 1e-6 && rep.manip > lg - 8.0, "%s: manip %ld, 65536 log2 |det J| %.3f",
                             gp->d->name, (long)rep.manip, lg);
                cfs++;
                DHT_TRUE_MSG(rep.sigma_min / QPOS <= sg && rep.sigma_min >= tp->sing_threshold,
                             "%s: sigma bound %.6g, true %.6g", gp->d->name, rep.sigma_min / QPOS, sg);
                DHT_TRUE(!rep.near_singular);
            } else if (rep.near_singular) {
                near++;
            }
        }
        dht_printf("%s: |det J| against double, %ld configurations, worst %.3g (relative to |det J| + L^3), "
                   "%ld reports without J, %ld near-singular\n", gp->d->name, n, worst, cfs, near);
    }
}

/* The defaults: pos_tol is the closed form's bound (328 LSB, 5e-3 mm for
 * the robots in mm, at least ikc.h's bound), so that a reached closed-form
 * solution is reported without FK; a tighter pos_tol or rot_tol, or a
 * target orthonormal only within DH_ROT_ERROR_TOL_Q, is measured by FK
 * (and still OK only within the tolerances: step_checked) */
static void defaults_and_measured(void)
{
    rig *const gp = &the_rig;
    dh_track_q *const tp = &the_trk;
    const int32_t q0[6] = { DH_Q16(10.0), DH_Q16(-60.0), DH_Q16(70.0), DH_Q16(20.0), DH_Q16(40.0), DH_Q16(30.0) };
    int variant;
    rig_make(gp, &dhs_ur5_mm, 0);
    if (!gp->closed) return;
    for (variant = 0; variant < 4; variant++) {
        dh_frame_q T;
        chk c;
        DHT_EQ_INT(dh_track_init_q(tp, &gp->r, &gp->m, q0, DT_US), DH_OK);
        DHT_EQ_INT(tp->pos_tol, tp->cf_pos);
        DHT_TRUE(tp->cf_pos >= (int32_t)ceil(5e-3 * 65536.0) && tp->rot_tol >= DH_TRACK_CF_ROT_Q);
        target_of(gp, q0, &T);
        if (variant == 1) tp->pos_tol = tp->cf_pos - 1;
        if (variant == 2) tp->rot_tol = DH_TRACK_CF_ROT_Q - 1;
        if (variant == 3) T.r[0][0] += 4096;   /* 3.8e-6 from orthonormal: rigid, not tight */
        chk_start(&c, q0, 6u);
        DHT_EQ_INT(step_checked(gp, tp, &c, &T, "defaults"), DH_TRACK_OK);
        DHT_EQ_INT(last_rep.measured, variant == 0 ? 0 : 1);
    }
}

/* bad targets: the joints brake; init errors (twin: bad_targets_brake of test_track.c) */
static void bad_targets_brake(void)
{
    rig *const gp = &the_rig;
    dh_track_q *const tp = &the_trk;
    dh_track_report_q rep;
    int32_t q0[6] = { DH_Q16(10.0), DH_Q16(-60.0), DH_Q16(70.0), DH_Q16(20.0), DH_Q16(40.0), DH_Q16(30.0) }, q[6];
    dh_frame_q T;
    uint32_t i;
    rig_make(gp, &dhs_ur5_mm, 0);
    DHT_EQ_INT(dh_track_init_q(tp, &gp->r, &gp->m, q0, DT_US), DH_OK);
    target_of(gp, q0, &T);
    T.r[0][0] = T.r[0][0] / 2;
    DHT_EQ_INT(dh_track_step_q(tp, &T, q, &rep), DH_ERR_NOT_RIGID);
    DHT_EQ_INT(rep.state, DH_TRACK_UNREACHABLE);
    for (i = 0; i < 6u; i++) DHT_EQ_INT(q[i], q0[i]);
    DHT_EQ_INT(dh_track_init_q(tp, &gp->r, &gp->m, q0, 0u), DH_ERR_ARG);
    DHT_EQ_INT(dh_track_init_q(tp, &gp->r, &gp->m, q0, 1000001u), DH_ERR_ARG);
    q0[1] = DH_Q16(1000.0);
    DHT_EQ_INT(dh_track_init_q(tp, &gp->r, &gp->m, q0, DT_US), DH_ERR_LIMIT);
}

static const dht_case cases[] = {
    DHT_CASE(bad_targets_brake),
    DHT_CASE(detj_against_double),
    DHT_CASE(defaults_and_measured),
    DHT_CASE(smooth_paths_every_call_ok),
    DHT_CASE(singular_lines),
    DHT_CASE(leaving_the_workspace),
    DHT_CASE(target_jumps),
};

DHT_MAIN(cases)
