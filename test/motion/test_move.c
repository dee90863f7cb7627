/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_move.c - the move executor (motion.h: dh_move_joint_f32,
 * dh_move_joint_step_f32, dh_move_path_f32, dh_move_target_f32,
 * dh_move_advance_f32) on the UR5 in metres with joint rates set, at
 * 1 kHz, seeded random moves.
 *
 * Cartesian moves run the firmware loop of motion.h with the real tracker
 * (target, dh_track_step_f32, advance). Every output is checked against
 * the tracker's guarantees (track.h) in double: the step within the float
 * dq_max and vmax dt, the change of step within amax dt^2 (1 + 1e-6) + 4
 * ulp of q, the joint limits, finiteness. Lines and arcs run between two
 * configurations of a region away from the singularities, every point of
 * the path with a closed-form solution whose smallest singular value bound
 * is at least twice the tracker's threshold. The target is the path's
 * point at the move's clock (the path's own bound, motion.h: 4 FLT_EPSILON
 * S on a line, 3 E on an arc); at every OK period the tool (double
 * reference FK of the output) is at the target's path point within the
 * tracker's tolerances plus the float FK bound (3e-7 m, 1e-6 rad) plus
 * the path's bound; over windows of OK periods the finite differences of
 * the tool's position and rotation are within vmax, amax and wmax times
 * 1 + 1e-3. The tool's error is at most ERR = pos_tol + 3e-7 at each
 * sample (ERR_R = rot_tol + 1e-6 in rotation), so each window is the
 * least number of periods w for which that noise is at most 2.5e-4 of
 * the limit: 2 ERR / (w dt) for a speed, 4 ERR / (w dt)^2 for an
 * acceleration. Every period the clock advances by r dt (r the feed
 * override it reports, in [0, 1]), by dt bit for bit at r == 1, and r
 * stays 1 while the tracker is OK from its first advance on (a feasible
 * move runs as without the override); the commanded s (the profile in
 * double at the clock) has s' and s'' within the profile's peaks by finite
 * differences over SW periods; at r == 0 the target holds bit for bit
 * (before any OK period it is A bit for bit). done comes only with the
 * clock at the duration and the tool at B, within 10 times the duration
 * plus 5 s.
 *
 * A move that starts with the tool away from A (a few degrees per joint):
 * the clock holds at 0 until the tracker is OK at A, then the move runs as
 * above.
 *
 * Joint moves: each step within vmax (1 - 2^-10) times the clock's advance
 * plus the rounding of motion.h (vmax 2 ulp(duration) + 4 ulp of q and of
 * q1 - q0), each change of step within amax (1 - 2^-10) dt^2 plus twice
 * that rounding, done only at the end with q == q1 bit for bit; then a
 * line from there with a tracker started at q1.
 *
 * A line through the axis of joint 1 (the UR5 cannot bring its wrist
 * within d4 of that axis): not OK there, the move slows to a stop there
 * within the profile's rates (over the last tenth of the run its clock
 * advances by less than 1 % of the time), done never reported.
 *
 * A Puma 560 line the wrist cannot follow at its speed (docs/motion.md's
 * Puma line, ending in the base's orientation): completes, with at most a
 * quarter of the not-OK periods of a clock that holds on them, and after
 * the first episode of not-OK periods at most as many as in it.
 *
 * Every status of the five functions for bad inputs, with the outputs and
 * the move untouched.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_ref.h"
#include "support_robots.h"
#include "dhmath/motion.h"
#include "dhmath/track.h"

#define DT 1e-3f
#define VMAX_R 180.0f  /* deg/s */
#define AMAX_R 3000.0f /* deg/s^2 */
#define EPS ((double)FLT_EPSILON)
#define REL_FD 1e-3
#define NOISE_FRAC 2.5e-4
#define RING 24   /* frames kept, one every RING_STEP periods */
#define RING_STEP 20

static const double Q_HOME[DH_MAX_JOINTS] = { 0, -90, 90, 0, 90, 0 };

static const dh_cart_limits_f32 LIM = { 0.25f, 2.0f, 45.0f, 360.0f };

typedef struct {
    dh_robot r;
    dh_ikc_model_f32 m;
} rig;

static void rig_make(rig *g)
{
    uint32_t i;
    DHT_EQ_INT(dhs_build(&dhs_ur5_m, &g->r), DH_OK);
    for (i = 0; i < g->r.n; i++) DHT_EQ_INT(dh_robot_set_rates_f32(&g->r, i, VMAX_R, AMAX_R), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_f32(&g->r, &g->m), DH_OK);
}

static double ulpf(double x)
{
    int e;
    (void)frexp(fabs(x) > 1e-30 ? fabs(x) : 1e-30, &e);
    return ldexp(1.0, e - 24);
}

/* the guarantees of track.h for one output q after qp (previous step sp,
 * have_sp: sp known) within vmax, amax (joint unit / s, / s^2) */
static void check_step(const rig *g, const dh_track_f32 *t, const float *q, float *qp, float *sp, int *have_sp,
                       const float *vmax, const float *amax, const double *slack, long call)
{
    uint32_t i;
    for (i = 0; i < g->r.n; i++) {
        const dh_joint *j = &g->r.joint[i];
        const double s = (double)q[i] - (double)qp[i];
        const double A = (double)amax[i] * DT * DT;
        DHT_TRUE_MSG(isfinite(q[i]), "call %ld: joint %u not finite", call, (unsigned)i);
        DHT_TRUE_MSG(fabs(s) <= (double)t->dq_max[i] && fabs(s) <= (double)vmax[i] * (double)DT,
                     "call %ld: joint %u step %.9g beyond %.9g", call, (unsigned)i, s, (double)t->dq_max[i]);
        DHT_TRUE_MSG(q[i] >= j->qmin && q[i] <= j->qmax, "call %ld: joint %u outside its limits", call, (unsigned)i);
        if (*have_sp)
            DHT_TRUE_MSG(fabs(s - sp[i]) <= A * (1 + 1e-6) + 4 * ulpf(fmax(fabs(q[i]), fabs(qp[i]))) + (slack ? slack[i] : 0.0),
                         "call %ld: joint %u step change %.9g beyond amax dt^2 %.9g q %.9g qp %.9g sl %g", call, (unsigned)i,
                         fabs(s - sp[i]), A, (double)q[i], (double)qp[i], slack ? slack[i] : 0.0);
        sp[i] = (float)s;
        qp[i] = q[i];
    }
    *have_sp = 1;
}

static void fk_d(const rig *g, const float *q, dhr_mat4 *T)
{
    double qd[DH_MAX_JOINTS];
    uint32_t i;
    for (i = 0; i < g->r.n; i++) qd[i] = q[i];
    dhs_fk_ref_f32(&g->r, qd, NULL, T);
}

/* rotation angle (rad) of A^T B */
static double rot_between(const dhr_mat4 *A, const dhr_mat4 *B)
{
    double R[3][3];
    int c, k, l;
    for (c = 0; c < 3; c++)
        for (k = 0; k < 3; k++) {
            R[c][k] = 0.0;
            for (l = 0; l < 3; l++) R[c][k] += A->m[k][l] * B->m[c][l];
        }
    return dhs_rot_angle(R);
}

static double dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

static double dist3f(const float *a, const float *b)
{
    const double d[3] = { (double)a[0] - b[0], (double)a[1] - b[1], (double)a[2] - b[2] };
    return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

/* double reference of a path: the line, or the circle through p_A, via,
 * p_B (centre c, radius R, unit normal n, sweep) */
typedef struct {
    double pa[3], pb[3], c[3], n[3], u0[3], R, sweep, E;
    int arc;
} ref_path;

static void ref_make(ref_path *rp, const dh_mat4_f32 *A, const dh_mat4_f32 *B, const float *via)
{
    double a[3], b[3], x[3], a2, b2, x2, w[3], u1[3], cr[3], S, L;
    int k;
    memset(rp, 0, sizeof *rp);
    for (k = 0; k < 3; k++) {
        rp->pa[k] = A->m[3][k];
        rp->pb[k] = B->m[3][k];
    }
    rp->arc = via != NULL;
    if (!rp->arc) {
        rp->E = 4.0 * EPS * fmax(sqrt(rp->pa[0] * rp->pa[0] + rp->pa[1] * rp->pa[1] + rp->pa[2] * rp->pa[2]),
                                 sqrt(rp->pb[0] * rp->pb[0] + rp->pb[1] * rp->pb[1] + rp->pb[2] * rp->pb[2]));
        return;
    }
    for (k = 0; k < 3; k++) {
        a[k] = via[k] - rp->pa[k];
        b[k] = rp->pb[k] - rp->pa[k];
    }
    x[0] = a[1] * b[2] - a[2] * b[1];
    x[1] = a[2] * b[0] - a[0] * b[2];
    x[2] = a[0] * b[1] - a[1] * b[0];
    a2 = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
    b2 = b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
    x2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
    /* centre - p_A = (|a|^2 b - |b|^2 a) x (a x b) / (2 |a x b|^2) */
    for (k = 0; k < 3; k++) w[k] = a2 * b[k] - b2 * a[k];
    cr[0] = w[1] * x[2] - w[2] * x[1];
    cr[1] = w[2] * x[0] - w[0] * x[2];
    cr[2] = w[0] * x[1] - w[1] * x[0];
    for (k = 0; k < 3; k++) {
        rp->c[k] = rp->pa[k] + cr[k] / (2.0 * x2);
        rp->n[k] = x[k] / sqrt(x2);
        rp->u0[k] = rp->pa[k] - rp->c[k];
        u1[k] = rp->pb[k] - rp->c[k];
    }
    rp->R = sqrt(rp->u0[0] * rp->u0[0] + rp->u0[1] * rp->u0[1] + rp->u0[2] * rp->u0[2]);
    {
        const double cx = rp->u0[1] * u1[2] - rp->u0[2] * u1[1], cy = rp->u0[2] * u1[0] - rp->u0[0] * u1[2],
                     cz = rp->u0[0] * u1[1] - rp->u0[1] * u1[0];
        double sw = atan2(cx * rp->n[0] + cy * rp->n[1] + cz * rp->n[2],
                          rp->u0[0] * u1[0] + rp->u0[1] * u1[1] + rp->u0[2] * u1[2]);
        rp->sweep = (sw < 0.0) ? sw + 2.0 * DHR_PI : sw;
    }
    L = sqrt(fmax(fmax(a2, b2), (rp->pb[0] - via[0]) * (rp->pb[0] - via[0]) +
                                    (rp->pb[1] - via[1]) * (rp->pb[1] - via[1]) +
                                    (rp->pb[2] - via[2]) * (rp->pb[2] - via[2])));
    S = fmax(fmax(sqrt(rp->pa[0] * rp->pa[0] + rp->pa[1] * rp->pa[1] + rp->pa[2] * rp->pa[2]),
                  sqrt(rp->pb[0] * rp->pb[0] + rp->pb[1] * rp->pb[1] + rp->pb[2] * rp->pb[2])),
             sqrt((double)via[0] * via[0] + (double)via[1] * via[1] + (double)via[2] * via[2]));
    /* motion.h: a point of the arc at s within 3 E, E = 16 EPS (S + R + L) / (|a x b| / L^2) */
    rp->E = 3.0 * 16.0 * EPS * (S + rp->R + L) / (sqrt(x2) / (L * L));
}

/* the reference point at s */
static void ref_point(const ref_path *rp, double s, double *p)
{
    int k;
    if (!rp->arc) {
        for (k = 0; k < 3; k++) p[k] = rp->pa[k] + s * (rp->pb[k] - rp->pa[k]);
        return;
    }
    {
        const double ph = s * rp->sweep, c = cos(ph), sn = sin(ph);
        const double v[3] = { rp->n[1] * rp->u0[2] - rp->n[2] * rp->u0[1], rp->n[2] * rp->u0[0] - rp->n[0] * rp->u0[2],
                              rp->n[0] * rp->u0[1] - rp->n[1] * rp->u0[0] };
        for (k = 0; k < 3; k++) p[k] = rp->c[k] + c * rp->u0[k] + sn * v[k];
    }
}

/* 1 when the branch of the closed-form solutions that starts nearest q
 * (into q: the solution at A) runs along the path within the robot's
 * rates: at each of 129 points the solution nearest the previous one is
 * within 4 degrees of it per joint, has a smallest singular value bound of
 * at least twice the tracker's threshold, and the joint rates and
 * accelerations of the move (s' <= prof.v, |s''| <= prof.a) estimated
 * from the differences are within half the robot's (test input selection) */
#define NPT 128
static int path_good(const rig *g, const dh_path_f32 *p, float thr, float *q)
{
    dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
    float J[6 * DH_MAX_JOINTS], w, sg, qr[DH_MAX_JOINTS], qm[DH_MAX_JOINTS];
    dh_profile_f32 prof;
    dh_mat4_f32 T;
    uint32_t ns, k, i;
    int it;
    if (dh_path_move_f32(&prof, p, &LIM) != DH_OK) return 0;
    memcpy(qr, q, sizeof qr);
    for (it = 0; it <= NPT; it++) {
        double best = 1e30;
        uint32_t kb = 0;
        if (dh_path_eval_f32(p, (float)it / (float)NPT, &T) != DH_OK) return 0;
        ns = 0;
        if (dh_ikc_f32(&g->m, &T, qr, 0u, sol, &ns) != DH_OK || ns == 0) return 0;
        for (k = 0; k < ns; k++) {
            double d = 0.0;
            for (i = 0; i < g->r.n; i++) d = fmax(d, fabs((double)sol[k].q[i] - qr[i]));
            if (d < best) {
                best = d;
                kb = k;
            }
        }
        if (best > 4.0) return 0;
        if (dh_jacobian_f32(&g->r, sol[kb].q, J, NULL) != DH_OK) return 0;
        if (dh_manipulability_f32(J, g->r.n, &w, &sg) != DH_OK || sg < 2.0f * thr) return 0;
        for (i = 0; it > 0 && i < g->r.n; i++) {
            const double d1 = ((double)sol[kb].q[i] - qr[i]) * NPT;
            const double d2 = it > 1 ? ((double)sol[kb].q[i] - 2.0 * qr[i] + qm[i]) * NPT * NPT : 0.0;
            if (fabs(d1) * prof.v > 0.5 * g->r.joint[i].vmax) return 0;
            if (fabs(d2) * prof.v * prof.v + fabs(d1) * prof.a > 0.5 * g->r.joint[i].amax) return 0;
        }
        memcpy(qm, qr, sizeof qm);
        memcpy(qr, sol[kb].q, g->r.n * sizeof(float));
        if (it == 0) memcpy(q, qr, g->r.n * sizeof(float));
    }
    return 1;
}

/* ring of the tool's frames, one every RING_STEP periods (the last
 * RING of them: 3 KiB, within the micro:bit's RAM), and the states */
typedef struct {
    dhr_mat4 T[RING];
    long n;   /* samples so far */
    long run; /* OK samples in a row up to the last */
} ring;

/* the frame back periods before the last sample (back a multiple of
 * RING_STEP, the last sample a kept one) */
static const dhr_mat4 *ring_at(const ring *rg, long back)
{
    return &rg->T[((rg->n - 1 - back) / RING_STEP) % RING];
}

/* a window rounded up to a multiple of RING_STEP (a longer window only
 * lowers the noise) */
static long ring_window(double w)
{
    return RING_STEP * (long)ceil(w / RING_STEP);
}

/* the finite-difference checks of the windows that end at the last
 * sample (a kept one) */
static void ring_check(const ring *rg, const dh_cart_limits_f32 *lim, long wv, long wa, long ww)
{
    const double dt = (double)DT;
    if (rg->run > wv) {
        const double d = dist3(&ring_at(rg, 0)->m[3][0], &ring_at(rg, wv)->m[3][0]) / (wv * dt);
        DHT_TRUE_MSG(d <= lim->vmax * (1.0 + REL_FD), "speed %.9g x vmax (window %ld)", d / lim->vmax, wv);
    }
    if (rg->run > 2 * wa) {
        const dhr_mat4 *a = ring_at(rg, 0), *b = ring_at(rg, wa), *c = ring_at(rg, 2 * wa);
        double acc = 0.0;
        int k;
        for (k = 0; k < 3; k++) {
            const double x = (a->m[3][k] - 2.0 * b->m[3][k] + c->m[3][k]) / ((wa * dt) * (wa * dt));
            acc += x * x;
        }
        acc = sqrt(acc);
        DHT_TRUE_MSG(acc <= lim->amax * (1.0 + REL_FD), "acceleration %.9g x amax (window %ld)", acc / lim->amax, wa);
    }
    if (rg->run > ww) {
        const double w = rot_between(ring_at(rg, 0), ring_at(rg, ww)) * (180.0 / DHR_PI) / (ww * dt);
        DHT_TRUE_MSG(w <= lim->wmax * (1.0 + REL_FD), "angular speed %.9g x wmax (window %ld)", w / lim->wmax, ww);
    }
}

static ring g_ring;

/* s of the trapezoid prof at the float clock t, in double (the profile's
 * own fields; from its nearer end): the commanded path parameter without
 * the profile's float rounding */
static double ref_s_d(const dh_profile_f32 *pr, double x)
{
    const double T = pr->T, ta = pr->ta, a = pr->a, v = pr->v, d = pr->d;
    if (!(x > 0.0)) return 0.0;
    if (x >= T) return d;
    if (x > 0.5 * T) return d - ref_s_d(pr, T - x);
    if (x < ta) return 0.5 * a * x * x;
    return 0.5 * a * ta * ta + v * (x - ta);
}

static double ref_s(const dh_profile_f32 *pr, float t)
{
    return ref_s_d(pr, (double)t);
}

/* the commanded path parameter of the last 2 SW + 1 periods */
#define SW 32
typedef struct {
    double s[2 * SW + 1];
    long n;
} sring;
static sring g_sr;

/* s (ref_s at the clock after a period) appended, and the finite
 * differences over SW periods that end there checked against the profile's
 * peaks: the feed override keeps s' r within v and (s' r)' within a
 * (docs/design.md, "Motion"). The noise: the clock's and the profile's
 * float rounding (v ulp(T) + 4 ulp(d) per sample). */
static void sring_check(sring *sr, const dh_profile_f32 *pr, double s, long call)
{
    const double w = SW * (double)DT, e = (double)pr->v * ulpf(pr->T) + 4.0 * ulpf(pr->d);
    sr->s[sr->n % (2 * SW + 1)] = s;
    sr->n++;
    if (sr->n > SW) {
        const double x0 = sr->s[(sr->n - 1) % (2 * SW + 1)], x1 = sr->s[(sr->n - 1 - SW) % (2 * SW + 1)];
        DHT_TRUE_MSG(fabs(x0 - x1) / w <= (double)pr->v * (1.0 + REL_FD) + 2.0 * e / w,
                     "call %ld: s' %.9g beyond the profile's %.9g", call, fabs(x0 - x1) / w, (double)pr->v);
    }
    if (sr->n > 2 * SW) {
        const double x0 = sr->s[(sr->n - 1) % (2 * SW + 1)], x1 = sr->s[(sr->n - 1 - SW) % (2 * SW + 1)];
        const double x2 = sr->s[(sr->n - 1 - 2 * SW) % (2 * SW + 1)];
        DHT_TRUE_MSG(fabs(x0 - 2.0 * x1 + x2) / (w * w) <= (double)pr->a * (1.0 + REL_FD) + 4.0 * e / (w * w),
                     "call %ld: s'' %.9g beyond the profile's %.9g", call, fabs(x0 - 2.0 * x1 + x2) / (w * w),
                     (double)pr->a);
    }
}

/* one period of a path move checked: c the clock before, mrep the report,
 * ok the tracker's state; the clock advances by r dt (r the override
 * after the period, in [0, 1]), capped at the duration */
static void check_period(const dh_move_f32 *mv, float c, const dh_move_report_f32 *mrep, int ok, sring *sr, long call)
{
    const double want = fmin((double)c + (double)mrep->feed * (double)DT, (double)mv->dur);
    DHT_TRUE(mrep->clock == mv->clock && mrep->feed == mv->feed && mrep->feed >= 0.0f && mrep->feed <= 1.0f);
    DHT_TRUE(mrep->held == !ok);
    if (ok && !(c < mv->dur)) {
        DHT_TRUE(mrep->done && mrep->clock == mv->dur);
    } else {
        DHT_TRUE(!mrep->done);
        DHT_TRUE_MSG(fabs((double)mrep->clock - want) <= 2.0 * ulpf(mv->dur), "call %ld: clock %.9g, %.9g + %.9g dt",
                     call, (double)mrep->clock, (double)c, (double)mrep->feed);
        /* r == 1: the profile's clock bit for bit */
        if (mrep->feed == 1.0f) DHT_TRUE(mrep->clock == ((c + DT < mv->dur) ? c + DT : mv->dur));
    }
    sring_check(sr, &mv->prof[0], ref_s(&mv->prof[0], mv->clock), call);
}

/* the tool's position (double FK of the tracker's q) into p */
static void tool_at(const rig *g, const float *q, double *p)
{
    dhr_mat4 T;
    int k;
    fk_d(g, q, &T);
    for (k = 0; k < 3; k++) p[k] = T.m[3][k];
}

/* One Cartesian move (path p, reference rp) run by the firmware loop of
 * motion.h with the tracker t from its q, every period checked; returns
 * the periods held at clock 0 before the first OK. */
typedef struct {
    long first_done; /* calls up to the first done */
    long notok;      /* not-OK calls up to the first done */
    long first_ep;   /* not-OK calls of the first episode after an OK period */
} run_stats;

static long run_path(rig *g, dh_track_f32 *t, const dh_path_f32 *p, const ref_path *rp, const dh_cart_limits_f32 *lim,
                     run_stats *rs)
{
    dh_move_f32 mv;
    dh_move_report_f32 mrep;
    dh_track_report_f32 rep;
    dh_mat4_f32 F, Fp;
    float q[DH_MAX_JOINTS], qp[DH_MAX_JOINTS], sp[DH_MAX_JOINTS], vmax[DH_MAX_JOINTS], amax[DH_MAX_JOINTS];
    const double err = (double)t->pos_tol + 3e-7, err_r = (double)t->rot_tol + 1e-6;
    const long wv = ring_window(2.0 * err / (NOISE_FRAC * lim->vmax * DT));
    const long wa = ring_window(sqrt(4.0 * err / (NOISE_FRAC * lim->amax * DT * DT)));
    const long ww = ring_window(2.0 * err_r * (180.0 / DHR_PI) / (NOISE_FRAC * lim->wmax * DT));
    long call, max_calls, dones = 0, notok = 0, start_held = 0;
    int have_sp = 0, any_ok = 0, all_ok = 1, ep_state = 0;
    float fprev = 1.0f;
    uint32_t i;
    DHT_TRUE(2 * wa < RING * RING_STEP && wv < RING * RING_STEP && ww < RING * RING_STEP);
    for (i = 0; i < g->r.n; i++) {
        vmax[i] = g->r.joint[i].vmax;
        amax[i] = g->r.joint[i].amax;
    }
    memcpy(qp, t->q, sizeof qp);
    memset(&g_sr, 0, sizeof g_sr);
    DHT_EQ_INT(dh_move_path_f32(&mv, p, lim), DH_OK);
    DHT_TRUE(mv.feed == 1.0f);
    DHT_TRUE(mv.clock == 0.0f && mv.dur > 0.0f);
    /* 10 times the duration plus 5 s, and 3 more calls */
    max_calls = (long)ceil((10.0 * mv.dur + 5.0) / DT) + 3;
    if (rs != NULL) memset(rs, 0, sizeof *rs);
    memset(&g_ring, 0, sizeof g_ring);
    memset(&Fp, 0, sizeof Fp);
    for (call = 0; call < max_calls && dones < 3; call++) {
        dhr_mat4 Tc, *const T = &Tc;
        const float c = mv.clock;
        double pr[3], tgt[3];
        float s, sv, sa;
        int k;
        DHT_EQ_INT(dh_move_target_f32(&mv, &F), DH_OK);
        for (k = 0; k < 3; k++) tgt[k] = F.m[3][k];
        /* the target is the path's point at the clock */
        DHT_EQ_INT(dh_profile_eval_f32(&mv.prof[0], c, &s, &sv, &sa), DH_OK);
        ref_point(rp, s, pr);
        DHT_TRUE_MSG(dist3(tgt, pr) <= rp->E, "call %ld: target %.3g from the path's point", call, dist3(tgt, pr));
        if (!any_ok) DHT_TRUE(c == 0.0f && memcmp(&F, &p->A, sizeof F) == 0);
        /* r == 0: the clock and the target held */
        if (call > 0 && fprev == 0.0f) DHT_TRUE(memcmp(&F, &Fp, sizeof F) == 0);
        DHT_EQ_INT(dh_track_step_f32(t, &F, q, &rep), DH_OK);
        check_step(g, t, q, qp, sp, &have_sp, vmax, amax, NULL, call);
        fk_d(g, q, T);
        if (g_ring.n % RING_STEP == 0) g_ring.T[(g_ring.n / RING_STEP) % RING] = Tc;
        g_ring.n++;
        g_ring.run = (rep.state == DH_TRACK_OK) ? g_ring.run + 1 : 0;
        DHT_EQ_INT(dh_move_advance_f32(&mv, DT, rep.state, &mrep), DH_OK);
        DHT_TRUE(mrep.clock >= 0.0f && mrep.clock <= mv.dur);
        check_period(&mv, c, &mrep, rep.state == DH_TRACK_OK, &g_sr, call);
        if (rep.state == DH_TRACK_OK) {
            DHT_TRUE_MSG(dist3(&T->m[3][0], pr) <= err + rp->E, "call %ld: tool %.3g from the path's point", call,
                         dist3(&T->m[3][0], pr));
            /* a move the tracker follows (OK since its first advance):
             * r stays 1 and the clock advances by dt, as without the override */
            if (all_ok && any_ok) DHT_TRUE(mrep.feed == 1.0f);
            if ((g_ring.n - 1) % RING_STEP == 0) ring_check(&g_ring, lim, wv, wa, ww);
            any_ok = 1;
        } else {
            notok++;
            if (!any_ok) start_held++;
            /* before the first OK the clock holds at 0 (s' = 0: r falls to 0 at once) */
            if (!any_ok) DHT_TRUE(mrep.clock == 0.0f && mrep.feed == 0.0f);
            if (any_ok) all_ok = 0;
            if (rs != NULL && dones == 0) rs->notok++;
            if (rs != NULL && any_ok && ep_state < 2) {
                ep_state = 1;
                rs->first_ep++;
            }
        }
        if (rs != NULL && ep_state == 1 && rep.state == DH_TRACK_OK) ep_state = 2;
        if (rs != NULL && mrep.done && dones == 0) rs->first_done = call + 1;
        fprev = mrep.feed;
        if (mrep.done) {
            double ep, er;
            DHT_TRUE(c == mv.dur && rep.state == DH_TRACK_OK);
            dhs_true_error_f32(&g->r, q, &p->B, &ep, &er);
            DHT_TRUE_MSG(ep <= err && er <= err_r, "done with the tool %.3g m, %.3g rad from B", ep, er);
            DHT_TRUE(memcmp(&F, &p->B, sizeof F) == 0);
            dones++;
        }
        Fp = F;
    }
    DHT_TRUE_MSG(dones == 3, "no done in %ld calls (duration %g s, %ld not OK, clock %g, r %g)", max_calls,
                 (double)mv.dur, notok, (double)mv.clock, (double)mv.feed);
    dht_reach_max("move.path_not_ok", (double)notok);
    return start_held;
}
static void frames_of(const rig *g, const double *qa, const double *qb, dh_mat4_f32 *A, dh_mat4_f32 *B)
{
    dhs_target_f32(&g->r, qa, A);
    dhs_target_f32(&g->r, qb, B);
}

static void start_tracker(rig *g, dh_track_f32 *t, const double *q0)
{
    float qf[DH_MAX_JOINTS];
    uint32_t i;
    for (i = 0; i < g->r.n; i++) qf[i] = (float)q0[i];
    DHT_EQ_INT(dh_track_init_f32(t, &g->r, &g->m, qf, DT), DH_OK);
}


/* a line or an arc (arc != 0) between two configurations of the safe
 * region, accepted by path_good */
static void draw_path(rig *g, const dh_track_f32 *t, int arc, float *q0, dh_path_f32 *p, float *via,
                      dh_mat4_f32 *A, dh_mat4_f32 *B)
{
    double qa[DH_MAX_JOINTS];
    int tries, k;
    for (tries = 0; tries < 2000; tries++) {
        double qb[DH_MAX_JOINTS], e[3], d[3], h;
        dhs_ur5_safe_q(0.0, qa);
        for (k = 0; k < 6; k++) qb[k] = qa[k] + dht_rand_uniform(-15.0, 15.0);
        if (fabs(qb[4]) < 45.0 || fabs(qb[4]) > 135.0 || fabs(qb[2]) < 55.0 || fabs(qb[2]) > 125.0) continue;
        frames_of(g, qa, qb, A, B);
        if (arc) {
            for (k = 0; k < 3; k++) d[k] = B->m[3][k] - A->m[3][k];
            dhr_rand_unit3(e);
            h = (e[0] * d[0] + e[1] * d[1] + e[2] * d[2]) / (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            for (k = 0; k < 3; k++) e[k] -= h * d[k];
            h = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
            if (h < 0.1) continue;
            for (k = 0; k < 3; k++)
                via[k] = (float)(0.5 * (A->m[3][k] + B->m[3][k]) +
                                 dht_rand_uniform(0.2, 0.5) * dist3f(&A->m[3][0], &B->m[3][0]) * e[k] / h);
            if (dh_path_arc_f32(p, A, via, B) != DH_OK) continue;
        } else if (dh_path_line_f32(p, A, B) != DH_OK) {
            continue;
        }
        if (p->length < 0.02f) continue;
        for (k = 0; k < DH_MAX_JOINTS; k++) q0[k] = (float)qa[k];
        if (path_good(g, p, t->sing_threshold, q0)) return;
    }
    DHT_TRUE_MSG(0, "no path drawn in 2000 tries");
}


static void cart_moves(int arc, int offset)
{
    rig g;
    dh_track_f32 t;
    int it, n = (int)DHT_ITER(12);
    rig_make(&g);
    for (it = 0; it < n; it++) {
        float q0[DH_MAX_JOINTS];
        dh_mat4_f32 A, B;
        dh_path_f32 p;
        float via[3];
        ref_path rp;
        long start_held;
        /* the thresholds of a tracker at any configuration */
        start_tracker(&g, &t, Q_HOME);
        draw_path(&g, &t, arc, q0, &p, via, &A, &B);
        ref_make(&rp, &A, &B, arc ? via : NULL);
        /* the tracker starts at the branch's solution of A, or a few
         * degrees per joint away from it */
        if (offset) {
            uint32_t i;
            for (i = 0; i < g.r.n; i++) q0[i] += (float)dht_rand_uniform(-2.0, 2.0);
        }
        DHT_EQ_INT(dh_track_init_f32(&t, &g.r, &g.m, q0, DT), DH_OK);
        start_held = run_path(&g, &t, &p, &rp, &LIM, NULL);
        /* 2 degrees at 180 deg/s take 11 periods at least */
        if (offset) DHT_TRUE(start_held > 0);
    }
}

static void lines(void)
{
    cart_moves(0, 0);
}

static void arcs(void)
{
    cart_moves(1, 0);
}

static void offset_start(void)
{
    cart_moves(0, 1);
}

/* joint moves within random limits, then a line from where each ends */
static void joint_moves(void)
{
    rig g;
    dh_track_f32 t;
    int it, n = (int)DHT_ITER(8);
    long strict = 0;
    rig_make(&g);
    for (it = 0; it < n; it++) {
        double q0[DH_MAX_JOINTS], qb[DH_MAX_JOINTS], rnd[DH_MAX_JOINTS];
        float qa[DH_MAX_JOINTS], q1[DH_MAX_JOINTS], vmax[DH_MAX_JOINTS], amax[DH_MAX_JOINTS], jmax[DH_MAX_JOINTS];
        float q[DH_MAX_JOINTS], qp[DH_MAX_JOINTS];
        double sp[DH_MAX_JOINTS];
        const int jerk = it & 1;
        dh_move_f32 mv;
        dh_move_report_f32 rep;
        dh_mat4_f32 A, B;
        dh_path_f32 p;
        ref_path rp;
        long call, max_calls, dones = 0;
        float c = 0.0f;
        uint32_t i;
        dhs_ur5_safe_q(0.0, q0);
        dhs_ur5_safe_q(0.0, qb);
        for (i = 0; i < 6; i++) {
            qa[i] = (float)q0[i];
            q1[i] = (float)qb[i];
            vmax[i] = (float)dht_rand_uniform(20.0, 250.0);
            amax[i] = (float)dht_rand_uniform(100.0, 5000.0);
            jmax[i] = (float)dht_rand_uniform(2000.0, 100000.0);
        }
        if (it == 0) {
            /* a fixed first move on which the strict bound applies to every
             * joint whatever the seed: fast joints, |q| < 128 deg, 30 deg
             * moves, a short duration (the rounding terms below the margin) */
            static const float fa[6] = { 10.0f, -60.0f, 80.0f, -70.0f, -90.0f, 20.0f };
            static const float fb[6] = { 40.0f, -90.0f, 50.0f, -100.0f, -60.0f, 50.0f };
            for (i = 0; i < 6; i++) {
                qa[i] = fa[i];
                q1[i] = fb[i];
                q0[i] = fa[i];
                qb[i] = fb[i];
                vmax[i] = 250.0f;
                amax[i] = 2000.0f;
            }
        }
        DHT_EQ_INT(dh_move_joint_f32(&mv, 6u, qa, q1, vmax, amax, jerk ? jmax : NULL), DH_OK);
        DHT_TRUE(mv.clock == 0.0f && mv.dur > 0.0f);
        /* motion.h: the rounding of the clock and of q */
        for (i = 0; i < 6; i++)
            rnd[i] = (double)vmax[i] * 2.0 * ulpf(mv.dur) + 4.0 * ulpf(fmax(fabs(q0[i]), fabs(qb[i]))) +
                     4.0 * ulpf((double)q1[i] - qa[i]);
        memcpy(qp, qa, sizeof qp);
        max_calls = (long)ceil(mv.dur / DT);
        for (call = 0; call < max_calls + 3; call++) {
            DHT_EQ_INT(dh_move_joint_step_f32(&mv, DT, q, &rep), DH_OK);
            DHT_TRUE(rep.clock == mv.clock && !rep.held);
            for (i = 0; i < 6; i++) {
                const double s = (double)q[i] - qp[i], dc = (double)rep.clock - c;
                const double m = 1.0 - 1.0 / 1024.0;
                DHT_TRUE(isfinite(q[i]));
                DHT_TRUE(dc >= 0.0 && dc <= (double)DT * (1.0 + 1e-3));
                DHT_TRUE_MSG(fabs(s) <= vmax[i] * m * dc + rnd[i], "call %ld: joint %u step %.9g beyond %.9g", call,
                             (unsigned)i, fabs(s), vmax[i] * m * dc + rnd[i]);
                /* where the margin covers the rounding: within vmax dt itself */
                if (rnd[i] + (double)vmax[i] * ulpf(mv.dur) <= (double)vmax[i] * DT / 1024.0) {
                    DHT_TRUE_MSG(fabs(s) <= (double)vmax[i] * DT, "call %ld: joint %u step beyond vmax dt", call,
                                 (unsigned)i);
                    strict++;
                }
                if (call > 0)
                    DHT_TRUE_MSG(fabs(s - sp[i]) <= amax[i] * m * (double)DT * DT + 2.0 * rnd[i],
                                 "call %ld: joint %u step change %.9g beyond %.9g", call, (unsigned)i, fabs(s - sp[i]),
                                 amax[i] * m * (double)DT * DT + 2.0 * rnd[i]);
                sp[i] = s;
                qp[i] = q[i];
            }
            c = rep.clock;
            if (rep.done) {
                DHT_TRUE(rep.clock == mv.dur && memcmp(q, q1, 6u * sizeof(float)) == 0);
                /* no earlier than the clock's steps allow (each within dt (1 + 1e-3), above) */
                DHT_TRUE((double)(call + 1) * DT * (1.0 + 1e-3) >= (double)mv.dur);
                dones++;
            } else {
                DHT_TRUE(rep.clock < mv.dur);
            }
        }
        DHT_TRUE_MSG(dones >= 3, "joint move: %ld done within %ld calls (duration %g s)", dones, max_calls + 3,
                     (double)mv.dur);
        /* a line from where the move ended, the tracker started there */
        for (i = 0; i < 6; i++) qb[i] = (double)q1[i] + dht_rand_uniform(-5.0, 5.0);
        {
            double qe[DH_MAX_JOINTS];
            for (i = 0; i < 6; i++) qe[i] = q1[i];
            frames_of(&g, qe, qb, &A, &B);
        }
        DHT_EQ_INT(dh_path_line_f32(&p, &A, &B), DH_OK);
        ref_make(&rp, &A, &B, NULL);
        DHT_EQ_INT(dh_track_init_f32(&t, &g.r, &g.m, q1, DT), DH_OK);
        memcpy(qp, q1, sizeof qp);
        if (path_good(&g, &p, t.sing_threshold, qp)) (void)run_path(&g, &t, &p, &rp, &LIM, NULL);
    }
    /* the strict bound was checked (on every joint of the fixed first move) */
    DHT_TRUE(strict >= 6);
}

/* a line through the axis of joint 1, tool pointing down: the middle is
 * unreachable, the feed override brings the clock to a hold there within
 * the profile's rates and the move never ends */
static void unreachable_middle(void)
{
    rig g;
    dh_track_f32 t;
    int it, n = (int)DHT_ITER(4);
    rig_make(&g);
    for (it = 0; it < n; it++) {
        const double th = dht_rand_uniform(-180.0, 180.0), rho = dht_rand_uniform(0.35, 0.5),
                     z = dht_rand_uniform(0.1, 0.4);
        dhr_mat4 D, Rz, Rx;
        dh_mat4_f32 A, B, F, Fp;
        dh_path_f32 p;
        dh_move_f32 mv;
        dh_move_report_f32 mrep;
        dh_track_report_f32 rep;
        ref_path rp;
        dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
        float q[DH_MAX_JOINTS], qp[DH_MAX_JOINTS], sp[DH_MAX_JOINTS], vmax[DH_MAX_JOINTS], amax[DH_MAX_JOINTS];
        uint32_t ns = 0, i;
        long call, calls, notok = 0;
        int have_sp = 0;
        float fprev = 1.0f;
        float c10 = 0.0f;
        double far = 0.0;
        dhr_rotz(th, &Rz);
        dhr_rotx(180.0, &Rx);
        dhr_mul(&Rz, &Rx, &D);
        D.m[3][0] = rho * cos(th * DHR_PI / 180.0);
        D.m[3][1] = rho * sin(th * DHR_PI / 180.0);
        D.m[3][2] = z;
        dhr_to_f32(&D, &A);
        D.m[3][0] = -D.m[3][0];
        D.m[3][1] = -D.m[3][1];
        dhr_to_f32(&D, &B);
        DHT_EQ_INT(dh_path_line_f32(&p, &A, &B), DH_OK);
        ref_make(&rp, &A, &B, NULL);
        DHT_EQ_INT(dh_ikc_f32(&g.m, &A, NULL, 0u, sol, &ns), DH_OK);
        DHT_TRUE(ns > 0u);
        DHT_EQ_INT(dh_track_init_f32(&t, &g.r, &g.m, sol[0].q, DT), DH_OK);
        for (i = 0; i < g.r.n; i++) {
            vmax[i] = g.r.joint[i].vmax;
            amax[i] = g.r.joint[i].amax;
        }
        memcpy(qp, t.q, sizeof qp);
        memset(&g_sr, 0, sizeof g_sr);
        DHT_EQ_INT(dh_move_path_f32(&mv, &p, &LIM), DH_OK);
        calls = (long)ceil(mv.dur / DT) + 2000;
        memset(&Fp, 0, sizeof Fp);
        for (call = 0; call < calls; call++) {
            const float c = mv.clock;
            double tgt[3], tool[3];
            int k;
            DHT_EQ_INT(dh_move_target_f32(&mv, &F), DH_OK);
            for (k = 0; k < 3; k++) tgt[k] = F.m[3][k];
            if (call > 0 && fprev == 0.0f) DHT_TRUE(memcmp(&F, &Fp, sizeof F) == 0);
            DHT_EQ_INT(dh_track_step_f32(&t, &F, q, &rep), DH_OK);
            check_step(&g, &t, q, qp, sp, &have_sp, vmax, amax, NULL, call);
            DHT_EQ_INT(dh_move_advance_f32(&mv, DT, rep.state, &mrep), DH_OK);
            DHT_TRUE(!mrep.done && mrep.clock < mv.dur);
            check_period(&mv, c, &mrep, rep.state == DH_TRACK_OK, &g_sr, call);
            tool_at(&g, q, tool);
            if (rep.state != DH_TRACK_OK) notok++;
            if (call == calls - calls / 10) c10 = mrep.clock;
            fprev = mrep.feed;
            Fp = F;
            far = fmax(far, dist3(tool, tgt));
        }
        /* the move met the unreachable stretch (every call above: never
         * done, the clock short of the end); at the stretch's edge the
         * tracker can reach a held target and advance the clock a period
         * before it lags again, so the last call may be OK or held */
        DHT_TRUE(notok > 0);
        /* the move stopped there on its own schedule: the clock has held
         * (r at 0) for the last periods (at least a tenth of the run) */
        /* the move stopped there on its own schedule: over the last tenth
         * of the calls its clock advanced by less than 1 % of their time */
        DHT_TRUE_MSG((double)(mv.clock - c10) < 0.01 * (double)(calls / 10) * DT,
                     "the clock advanced %.3g s over the last %ld calls", (double)(mv.clock - c10), calls / 10);
        dht_reach_max("move.unreachable_last_tenth_advance", (double)(mv.clock - c10) / ((double)(calls / 10) * DT));
        /* measured, not bounded: the tool's distance from the target */
        dht_reach_max("move.unreachable_tool_target_over_vdt", far / ((double)LIM.vmax * DT));
    }
}

/* The not-OK periods and the periods up to done of the line p from the
 * tracker at q0 under a clock that advances by dt on OK periods only and
 * holds otherwise (the executor without a feed override), within the
 * bound of run_path; the move's frames from dh_move_target_f32. */
static long hold_clock_notok(rig *g, dh_track_f32 *t, const float *q0, const dh_path_f32 *p,
                             const dh_cart_limits_f32 *lim, long *periods)
{
    dh_move_f32 mv;
    dh_track_report_f32 rep;
    dh_mat4_f32 F;
    float q[DH_MAX_JOINTS];
    long call, max_calls, notok = 0;
    DHT_EQ_INT(dh_track_init_f32(t, &g->r, &g->m, q0, DT), DH_OK);
    DHT_EQ_INT(dh_move_path_f32(&mv, p, lim), DH_OK);
    max_calls = (long)ceil((10.0 * mv.dur + 5.0) / DT) + 3;
    for (call = 0; call < max_calls; call++) {
        DHT_EQ_INT(dh_move_target_f32(&mv, &F), DH_OK);
        DHT_EQ_INT(dh_track_step_f32(t, &F, q, &rep), DH_OK);
        if (rep.state != DH_TRACK_OK) {
            notok++;
        } else if (mv.clock < mv.dur) {
            mv.clock = (mv.clock + DT < mv.dur) ? mv.clock + DT : mv.dur;
        } else {
            break;
        }
    }
    *periods = call + 1;
    return notok;
}

/* The Puma 560 (metres) with joint rates 150 deg/s and 600 deg/s^2, a line
 * at 0.3 m/s and 1.5 m/s^2 from near q = (10, -30, 45, 20, 35, -60) to
 * near (0.5, -0.03, 1.0) with the base's orientation: the wrist is asked
 * for more than its rates (docs/motion.md's Puma line with the base's
 * orientation at its end; the first draw exactly that). The run of
 * run_path (every joint step within vmax dt and its change within
 * amax dt^2, s' and s'' within the profile's peaks by finite differences,
 * the tool's speed and acceleration over OK windows, done at B) completes
 * within its bound, with at most a quarter of the not-OK periods of the
 * clock that holds on them, and after the first episode at most as many
 * not-OK periods as in it. */
static void infeasible_puma(void)
{
    static const double QP[6] = { 10.0, -30.0, 45.0, 20.0, 35.0, -60.0 };
    static const dh_cart_limits_f32 PLIM = { 0.3f, 1.5f, 90.0f, 360.0f };
    dh_track_f32 t;
    rig g;
    uint32_t i;
    int it, n = (int)DHT_ITER(3);
    DHT_EQ_INT(dhs_build(&dhs_puma560_m, &g.r), DH_OK);
    for (i = 0; i < g.r.n; i++) DHT_EQ_INT(dh_robot_set_rates_f32(&g.r, i, 150.0f, 600.0f), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_f32(&g.r, &g.m), DH_OK);
    for (it = 0; it < n; it++) {
        double qa[DH_MAX_JOINTS];
        float q0[DH_MAX_JOINTS];
        dh_mat4_f32 A, B;
        dh_path_f32 p;
        ref_path rp;
        run_stats rs;
        long old_notok, old_periods;
        int k;
        for (i = 0; i < 6u; i++) {
            qa[i] = QP[i] + ((it == 0) ? 0.0 : dht_rand_uniform(-2.0, 2.0));
            q0[i] = (float)qa[i];
        }
        dhs_target_f32(&g.r, qa, &A);
        memset(&B, 0, sizeof B);
        for (k = 0; k < 3; k++) B.m[k][k] = 1.0f;
        B.m[3][3] = 1.0f;
        B.m[3][0] = 0.5f + ((it == 0) ? 0.0f : (float)dht_rand_uniform(-0.01, 0.01));
        B.m[3][1] = -0.03f + ((it == 0) ? 0.0f : (float)dht_rand_uniform(-0.01, 0.01));
        B.m[3][2] = 1.0f + ((it == 0) ? 0.0f : (float)dht_rand_uniform(-0.01, 0.01));
        DHT_EQ_INT(dh_path_line_f32(&p, &A, &B), DH_OK);
        ref_make(&rp, &A, &B, NULL);
        old_notok = hold_clock_notok(&g, &t, q0, &p, &PLIM, &old_periods);
        DHT_EQ_INT(dh_track_init_f32(&t, &g.r, &g.m, q0, DT), DH_OK);
        (void)run_path(&g, &t, &p, &rp, &PLIM, &rs);
        DHT_TRUE_MSG(rs.notok > 0 && 4 * rs.notok <= old_notok,
                     "%ld not-OK periods of %ld, a held clock %ld of %ld", rs.notok, rs.first_done, old_notok,
                     old_periods);
        DHT_TRUE_MSG(old_periods < (long)ceil((10.0 * (double)p.length / 0.3 + 5.0) / DT), "a held clock: %ld periods",
                     old_periods);
        DHT_TRUE_MSG(rs.notok - rs.first_ep <= rs.first_ep, "%ld not-OK periods after the first episode's %ld",
                     rs.notok - rs.first_ep, rs.first_ep);
        dht_reach_max("move.puma_notok_over_held", (double)rs.notok / (double)old_notok);
        dht_reach_max("move.puma_after_first_over_first", (double)(rs.notok - rs.first_ep) / (double)rs.first_ep);
    }
}

/* the five calls on an mv that holds no move of their kind (path: 1 for
 * a path move's calls): DH_ERR_ARG, outputs and mv untouched */
static void no_move(dh_move_f32 *mv, int path, int joint)
{
    float q[DH_MAX_JOINTS], q2[DH_MAX_JOINTS];
    dh_move_report_f32 rep, rep2;
    dh_mat4_f32 F, F2;
    dh_move_f32 keep = *mv;
    memset(q, 0x5a, sizeof q);
    memset(&rep, 0x5a, sizeof rep);
    memset(&F, 0x5a, sizeof F);
    memcpy(q2, q, sizeof q);
    rep2 = rep;
    F2 = F;
    if (joint) DHT_EQ_INT(dh_move_joint_step_f32(mv, DT, q, &rep), DH_ERR_ARG);
    if (path) {
        DHT_EQ_INT(dh_move_target_f32(mv, &F), DH_ERR_ARG);
        DHT_EQ_INT(dh_move_advance_f32(mv, DT, DH_TRACK_OK, &rep), DH_ERR_ARG);
    }
    DHT_TRUE(memcmp(q, q2, sizeof q) == 0 && memcmp(&rep, &rep2, sizeof rep) == 0);
    DHT_TRUE(memcmp(&F, &F2, sizeof F) == 0 && memcmp(mv, &keep, sizeof keep) == 0);
}

/* a bad period on a valid move: status st, outputs and mv untouched */
static void bad_dt(dh_move_f32 *mv, float dt, dh_status st)
{
    float q[DH_MAX_JOINTS], q2[DH_MAX_JOINTS];
    dh_move_report_f32 rep, rep2;
    dh_move_f32 keep = *mv;
    memset(q, 0x5a, sizeof q);
    memset(&rep, 0x5a, sizeof rep);
    memcpy(q2, q, sizeof q);
    rep2 = rep;
    if (mv->kind == (uint32_t)DH_MOVE_JOINT)
        DHT_EQ_INT(dh_move_joint_step_f32(mv, dt, q, &rep), st);
    else
        DHT_EQ_INT(dh_move_advance_f32(mv, dt, DH_TRACK_OK, &rep), st);
    DHT_TRUE(memcmp(q, q2, sizeof q) == 0 && memcmp(&rep, &rep2, sizeof rep) == 0);
    DHT_TRUE(memcmp(mv, &keep, sizeof keep) == 0);
}

static void bad_periods(dh_move_f32 *mv)
{
    bad_dt(mv, (float)NAN, DH_ERR_NAN);
    bad_dt(mv, (float)INFINITY, DH_ERR_NAN);
    bad_dt(mv, -(float)INFINITY, DH_ERR_NAN);
    bad_dt(mv, 0.0f, DH_ERR_ARG);
    bad_dt(mv, -1e-3f, DH_ERR_ARG);
}

static void move_bad(void)
{
    rig g;
    dh_move_f32 mv, keep;
    dh_move_report_f32 rep;
    dh_path_f32 p;
    dh_mat4_f32 A, B;
    dh_cart_limits_f32 lim;
    float q0[DH_MAX_JOINTS], q1[DH_MAX_JOINTS], v[DH_MAX_JOINTS], a[DH_MAX_JOINTS], j[DH_MAX_JOINTS];
    double qb[DH_MAX_JOINTS];
    const float nan = (float)NAN, inf = (float)INFINITY;
    uint32_t i;
    int k;
    rig_make(&g);
    for (i = 0; i < 6; i++) {
        q0[i] = (float)Q_HOME[i];
        q1[i] = (float)Q_HOME[i] + 10.0f;
        v[i] = 90.0f;
        a[i] = 900.0f;
        j[i] = 9000.0f;
    }
    /* a move written by no constructor */
    memset(&mv, 0, sizeof mv);
    no_move(&mv, 1, 1);
    /* a valid start, then each bad argument in turn */
    DHT_EQ_INT(dh_move_joint_f32(&mv, 6u, q0, q1, v, a, j), DH_OK);
    bad_periods(&mv);
    no_move(&mv, 1, 0); /* a joint move given to the path calls */
    for (k = 0; k < 2; k++) {
        const float bad = k ? inf : nan;
        q1[2] = bad;
        DHT_EQ_INT(dh_move_joint_f32(&mv, 6u, q0, q1, v, a, j), DH_ERR_NAN);
        no_move(&mv, 1, 1);
        q1[2] = (float)Q_HOME[2] + 10.0f;
        q0[3] = bad;
        DHT_EQ_INT(dh_move_joint_f32(&mv, 6u, q0, q1, v, a, j), DH_ERR_NAN);
        q0[3] = (float)Q_HOME[3];
        v[1] = bad;
        DHT_EQ_INT(dh_move_joint_f32(&mv, 6u, q0, q1, v, a, j), DH_ERR_NAN);
        v[1] = 90.0f;
        a[4] = bad;
        DHT_EQ_INT(dh_move_joint_f32(&mv, 6u, q0, q1, v, a, j), DH_ERR_NAN);
        a[4] = 900.0f;
        j[5] = bad;
        DHT_EQ_INT(dh_move_joint_f32(&mv, 6u, q0, q1, v, a, j), DH_ERR_NAN);
        no_move(&mv, 1, 1);
        j[5] = 9000.0f;
    }
    DHT_EQ_INT(dh_move_joint_f32(&mv, 0u, q0, q1, v, a, j), DH_ERR_ARG);
    DHT_EQ_INT(dh_move_joint_f32(&mv, (uint32_t)DH_MAX_JOINTS + 1u, q0, q1, v, a, j), DH_ERR_ARG);
    no_move(&mv, 1, 1);
    v[0] = 0.0f;
    DHT_EQ_INT(dh_move_joint_f32(&mv, 6u, q0, q1, v, a, NULL), DH_ERR_ARG);
    v[0] = 90.0f;
    a[3] = -1.0f;
    DHT_EQ_INT(dh_move_joint_f32(&mv, 6u, q0, q1, v, a, NULL), DH_ERR_ARG);
    a[3] = 900.0f;
    j[0] = 0.0f;
    DHT_EQ_INT(dh_move_joint_f32(&mv, 6u, q0, q1, v, a, j), DH_ERR_ARG);
    no_move(&mv, 1, 1);
    j[0] = 9000.0f;
    /* the duration overflows: 3e38 degrees at the smallest speed */
    q1[1] = 3e38f;
    v[1] = 1e-30f;
    DHT_EQ_INT(dh_move_joint_f32(&mv, 6u, q0, q1, v, a, NULL), DH_ERR_OVERFLOW);
    no_move(&mv, 1, 1);
    q1[1] = (float)Q_HOME[1] + 10.0f;
    v[1] = 90.0f;
    /* a clock that no call wrote: beyond the duration, NaN */
    DHT_EQ_INT(dh_move_joint_f32(&mv, 6u, q0, q1, v, a, j), DH_OK);
    keep = mv;
    mv.clock = mv.dur * 2.0f;
    no_move(&mv, 1, 1);
    mv.clock = nan;
    no_move(&mv, 1, 1);
    mv = keep;
    mv.n = 0u;
    no_move(&mv, 1, 1);
    mv = keep;
    mv.kind = 7u;
    no_move(&mv, 1, 1);

    /* path moves */
    dhs_target_f32(&g.r, Q_HOME, &A);
    for (i = 0; i < 6; i++) qb[i] = Q_HOME[i] + 5.0;
    dhs_target_f32(&g.r, qb, &B);
    DHT_EQ_INT(dh_path_line_f32(&p, &A, &B), DH_OK);
    DHT_EQ_INT(dh_move_path_f32(&mv, &p, &LIM), DH_OK);
    bad_periods(&mv);
    no_move(&mv, 0, 1); /* a path move given to the joint step */
    /* a state that is no dh_track_state */
    keep = mv;
    memset(&rep, 0x5a, sizeof rep);
    {
        dh_move_report_f32 rep2 = rep;
        DHT_EQ_INT(dh_move_advance_f32(&mv, DT, (dh_track_state)3, &rep), DH_ERR_ARG);
        DHT_EQ_INT(dh_move_advance_f32(&mv, DT, (dh_track_state)-1, &rep), DH_ERR_ARG);
        DHT_TRUE(memcmp(&rep, &rep2, sizeof rep) == 0 && memcmp(&mv, &keep, sizeof mv) == 0);
    }
    for (k = 0; k < 8; k++) {
        float *f;
        lim = LIM;
        f = (k & 3) == 0 ? &lim.vmax : (k & 3) == 1 ? &lim.amax : (k & 3) == 2 ? &lim.wmax : &lim.wdmax;
        *f = (k < 4) ? nan : inf;
        DHT_EQ_INT(dh_move_path_f32(&mv, &p, &lim), DH_ERR_NAN);
        no_move(&mv, 1, 1);
        *f = (k < 4) ? 0.0f : -1.0f;
        DHT_EQ_INT(dh_move_path_f32(&mv, &p, &lim), DH_ERR_ARG);
        no_move(&mv, 1, 1);
    }
    /* a path written by no constructor */
    DHT_EQ_INT(dh_move_path_f32(&mv, &p, &LIM), DH_OK);
    memset(&p, 0, sizeof p);
    DHT_EQ_INT(dh_move_path_f32(&mv, &p, &LIM), DH_ERR_ARG);
    no_move(&mv, 1, 1);
    /* the duration overflows: a line to 3e38 at 1e-30 m/s */
    B = A;
    B.m[3][0] = 3e38f;
    DHT_EQ_INT(dh_path_line_f32(&p, &A, &B), DH_OK);
    lim = LIM;
    lim.vmax = 1e-30f;
    lim.amax = 1e-30f;
    DHT_EQ_INT(dh_move_path_f32(&mv, &p, &lim), DH_ERR_OVERFLOW);
    no_move(&mv, 1, 1);
}

static const dht_case cases[] = {
    DHT_CASE(lines),
    DHT_CASE(arcs),
    DHT_CASE(offset_start),
    DHT_CASE(joint_moves),
    DHT_CASE(unreachable_middle),
    DHT_CASE(infeasible_puma),
    DHT_CASE(move_bad),
};
DHT_MAIN(cases)
