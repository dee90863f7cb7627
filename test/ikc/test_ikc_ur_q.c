/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_ikc_ur_q.c - fixed-point closed-form IK of the families
 * DH_IKC_PARALLEL_234 (UR3, UR5, UR10) and DH_IKC_SCARA (Cobra 600), robots
 * in mm: every solution against the double reference FK
 * (test/support_robots.h) within 5e-3 mm and 5e-6 (rotation entries, ~rad),
 * completeness (the generating configuration among the solutions within
 * 2e-3 deg / mm) on random in-limit configurations away from the
 * singularities, singular cases flagged and FK-correct, targets on the
 * workspace boundary (B / 2 beyond it solved, 4 B beyond it refused, B =
 * 64 LSB of the position format; the shoulder cylinder meeting the elbow's
 * boundary), unreachable targets, the statuses of the fixed solvers.
 */
#include "dht.h"
#include "support_ikc.h"
#include "dhmath/ikc.h"
#include "dhmath/frame.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* lengths scaled by DHK_LS and the tolerances DHK_POS_TOL, DHK_ROT_TOL,
 * DHK_COMP_DEG: support_ikc.h */
#define AWAY 1e-2     /* normalised distance from the singularities */
/* shoulder part below which a target is in the shoulder band (the joint 5
 * point within about 0.2 mm of the shoulder cylinder on the UR3): joint 1
 * free by the target's rounding, which the solver's search along the
 * shoulder's freedom must absorb when the elbow is near its boundary */
#define SBAND 2e-4
#define PI_D 3.14159265358979323846
#define D2R (PI_D / 180.0)

/* ---- robots --------------------------------------------------------------- */

static void robot_mm(dhs_robot *d, const dhs_robot *src)
{
    *d = *src;
    dhk_scale_desc(d);
}

/* ---- reference checks (and support_ikc.h) ---------------------------------- */

/* SCARA: the rounding of the target and of the Q16.16 arm angles moves the
 * exact solution by about J^-1 of it; the 2R Jacobian's determinant is
 * a1 a2 s2, so the bound is (|a1| + |a2|) (2 LSB) / |a1 a2 s2| */
static int scara_conditioned(const dhs_robot *d, const double *q)
{
    const double a1 = fabs(d->j[0].a), a2 = fabs(d->j[1].a);
    const double det = a1 * a2 * fabs(sin((q[1] + d->j[1].theta_deg) * D2R));
    const double dx = 4.0 * ldexp(1.0, -DH_QPOS_FRAC) + (a1 + a2) * ldexp(2.0, -16) * D2R;
    return (a1 + a2) * dx / det / D2R <= 0.5 * DHK_COMP_DEG;
}

/* probe (may be NULL): the prefix of the reach probes of the singular
 * distances drawn (dhk_reach_sing), and, for the targets in the shoulder
 * band (shoulder part below SBAND), "<probe>.sband_e" (their smallest
 * elbow part) and "<probe>.sband_ew" (their smallest max of the elbow and
 * wrist parts): the corners of the shoulder band and the elbow's boundary */
static void random_run(const dhs_robot *d, dh_ikc_kind kind, long iters, const char *probe)
{
    dh_robot r;
    dh_ikc_model_q m;
    dhk_stats st;
    long it;
    memset(&st, 0, sizeof st);
    dhk_build_q(d, kind, &r, &m);
    for (it = 0; it < iters; it++) {
        double q[6] = {0}, part[3];
        int32_t qq[6] = {0};
        dhr_mat4 Td;
        dh_frame_q T;
        dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
        uint32_t ns = 0;
        dh_status rc;
        int comp, found;
        dhs_random_q(d, q);
        dhs_q_from_double(&r, q, qq);
        comp = dhk_sing_parts(d, q, part) >= AWAY &&
               (d->n == 4u ? scara_conditioned(d, q) : dhk_well_conditioned_q(d, q, 0.5 * DHK_COMP_DEG, 6));
        if (probe) {
            dhk_reach_sing(probe, part);
            if (part[0] < SBAND) {
                char name[48];
                snprintf(name, sizeof name, "%s.sband_e", probe);
                dht_reach_min(name, part[1]);
                snprintf(name, sizeof name, "%s.sband_ew", probe);
                dht_reach_min(name, fmax(part[1], part[2]));
            }
        }
        dhs_fk_ref_q(&r, qq, NULL, &Td);
        dhs_to_frame_q(&Td, &T);
        rc = dh_ikc_q(&m, &T, NULL, 0u, sol, &ns);
        if (rc == DH_ERR_LIMIT && !comp) rc = dh_ikc_q(&m, &T, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &ns);
        DHT_TRUE_MSG(rc == DH_OK && ns >= 1u, "%s: status %d, %u solutions for q %.6f %.6f %.6f %.6f %.6f %.6f",
                     d->name, (int)rc, (unsigned)ns, q[0], q[1], q[2], q[3], q[4], q[5]);
        found = dhk_check_sols_q(&r, &Td, sol, ns, qq, &st);
        st.targets++;
        if (comp) {
            st.comp++;
            DHT_TRUE_MSG(found >= 0, "%s: generating configuration %.6f %.6f %.6f %.6f %.6f %.6f not among %u solutions",
                         d->name, q[0], q[1], q[2], q[3], q[4], q[5], (unsigned)ns);
        }
    }
    dht_printf("%s: %ld targets (%ld completeness), %ld solutions, max err %.3g mm, %.3g\n", d->name, st.targets,
               st.comp, st.sols, st.pos, st.rot);
    DHT_TRUE(st.comp >= iters / 4);
}

/* the singular distances drawn are the reach probes "<robot>" (ur3_mm.e:
 * the smallest elbow part of dhk_sing_parts; test/regression_seeds.txt) */
static void ur_random(void)
{
    dhs_robot d;
    robot_mm(&d, &dhs_ur3_mm);
    random_run(&d, DH_IKC_PARALLEL_234, DHT_ITER(10000), d.name);
    robot_mm(&d, &dhs_ur5_mm);
    random_run(&d, DH_IKC_PARALLEL_234, DHT_ITER(10000), d.name);
    robot_mm(&d, &dhs_ur10_mm);
    random_run(&d, DH_IKC_PARALLEL_234, DHT_ITER(10000), d.name);
}

static void scara_random(void)
{
    dhs_robot d;
    robot_mm(&d, &dhs_cobra600_mm);
    random_run(&d, DH_IKC_SCARA, DHT_ITER(10000), d.name);
}

/* ---- singular cases ------------------------------------------------------- */

/* solve q (Q values) with qref, every solution FK-correct; the flags ORed,
 * the count returned */
static uint32_t solve_q(const dh_robot *r, const dh_ikc_model_q *m, const int32_t *qq, const int32_t *qref,
                        dh_ikc_sol_q *sol, uint32_t *fl)
{
    dhr_mat4 Td;
    dh_frame_q T;
    uint32_t ns = 0, s;
    dhs_fk_ref_q(r, qq, NULL, &Td);
    dhs_to_frame_q(&Td, &T);
    DHT_EQ_INT(dh_ikc_q(m, &T, qref, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &ns), DH_OK);
    (void)dhk_check_sols_q(r, &Td, sol, ns, NULL, NULL);
    *fl = 0u;
    for (s = 0; s < ns; s++) *fl |= sol[s].flags;
    return ns;
}

/* 1 when qq is among the solutions within tol deg */
static int among(const dh_robot *r, const dh_ikc_sol_q *sol, uint32_t ns, const int32_t *qq, double tol)
{
    uint32_t s, i;
    for (s = 0; s < ns; s++) {
        double w = 0.0;
        for (i = 0; i < r->n; i++) {
            double dd = dhk_jdiff_q(r, i, sol[s].q[i], qq[i]);
            if (dd > w) w = dd;
        }
        if (w <= tol) return 1;
    }
    return 0;
}

static const dhs_robot *const g_ur[3] = {&dhs_ur3_mm, &dhs_ur5_mm, &dhs_ur10_mm};

/* one robot of these tests in mm: description, integer robot, model */
typedef struct {
    dhs_robot d;
    dh_robot r;
    dh_ikc_model_q m;
} urq_case;

/* body on each of the first count robots of UR3, UR5, UR10, Cobra 600 */
static void urq_each(unsigned count, void (*body)(const urq_case *rc))
{
    unsigned i;
    for (i = 0; i < count; i++) {
        urq_case rc;
        robot_mm(&rc.d, i < 3u ? g_ur[i] : &dhs_cobra600_mm);
        dhk_build_q(&rc.d, i < 3u ? DH_IKC_PARALLEL_234 : DH_IKC_SCARA, &rc.r, &rc.m);
        body(&rc);
    }
}

/* q5 = 0 or 180: wrist singular, joint 6 from q_ref */
static void ur_wrist_singular_case(const urq_case *rc)
{
    long it, n = 0;
    /* until DHT_ITER(500) targets pass the filter (at most 20 times as many tries) */
    for (it = 0; it < 20L * DHT_ITER(500) && n < DHT_ITER(500); it++) {
        double q[6], part[3];
        int32_t qq[6], qref[6] = {0};
        dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
        uint32_t ns, fl;
        dhs_random_q(&rc->d, q);
        q[4] = (it & 1) ? 180.0 : 0.0;
        (void)dhk_sing_parts(&rc->d, q, part);
        if (part[0] < 0.1 || part[1] < 0.1) continue;
        dhs_q_from_double(&rc->r, q, qq);
        qref[5] = qq[5];
        ns = solve_q(&rc->r, &rc->m, qq, qref, sol, &fl);
        DHT_TRUE_MSG((fl & DH_IKC_SING_WRIST) != 0u, "%s: q5 = %g not flagged", rc->d.name, q[4]);
        DHT_TRUE(ns <= 6u);
        DHT_TRUE_MSG(among(&rc->r, sol, ns, qq, 1e-2), "%s: q not found with qref6 = q6", rc->d.name);
        n++;
    }
    DHT_TRUE(n > 0);
}

static void ur_wrist_singular(void) { urq_each(3u, ur_wrist_singular_case); }

/* the joint 5 point on the cylinder u = 0: flagged, returned once; the
 * singular distances drawn are the reach probes "u0.<robot>" */
static void ur_shoulder_singular_case(const urq_case *rc)
{
    long it;
    int found = 0;
    for (it = 0; it < 20L * DHT_ITER(500) && found < DHT_ITER(500); it++) {
        const double a2 = rc->d.j[1].a, a3 = rc->d.j[2].a, e5 = rc->d.j[4].d;
        double q[6], X, Y, R, c, phi;
        int32_t qq[6];
        dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
        uint32_t ns, fl;
        dhs_random_q(&rc->d, q);
        phi = (q[1] + q[2] + q[3]) * D2R;
        X = a2 + a3 * cos(q[2] * D2R);
        Y = a3 * sin(q[2] * D2R);
        R = sqrt(X * X + Y * Y);
        c = -e5 * sin(phi);
        if (fabs(c) >= R) continue;
        q[1] = (-atan2(Y, X) + ((it & 1) ? 1 : -1) * acos(c / R)) / D2R;
        q[3] = phi / D2R - q[1] - q[2];
        dhs_q_from_double(&rc->r, q, qq);
        {
            double part[3];
            char pre[40];
            (void)dhk_sing_parts(&rc->d, q, part);
            snprintf(pre, sizeof pre, "u0.%s", rc->d.name);
            dhk_reach_sing(pre, part);
        }
        ns = solve_q(&rc->r, &rc->m, qq, NULL, sol, &fl);
        DHT_TRUE_MSG((fl & DH_IKC_SING_SHOULDER) != 0u, "%s: u = 0 not flagged", rc->d.name);
        DHT_TRUE_MSG(ns <= 4u, "%s: %u solutions with the shoulder branches merged", rc->d.name, (unsigned)ns);
        found++;
    }
    DHT_TRUE(found > 0);
}

static void ur_shoulder_singular(void) { urq_each(3u, ur_shoulder_singular_case); }

/* stretched or folded elbow: UR q3 = 0 / 180, SCARA q2 = 0 */
static void elbow_singular_case(const urq_case *rc)
{
    long it, n = 0;
    for (it = 0; it < 20L * DHT_ITER(500) && n < DHT_ITER(500); it++) {
        double q[6] = {0}, part[3];
        int32_t qq[6] = {0};
        dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
        uint32_t ns, fl, j = (rc->d.n == 4u) ? 1u : 2u;
        dhs_random_q(&rc->d, q);
        q[j] = (rc->d.n == 6u && (it & 1)) ? 180.0 : 0.0;
        (void)dhk_sing_parts(&rc->d, q, part);
        if (part[0] < 0.1 || part[2] < 0.1) continue;
        dhs_q_from_double(&rc->r, q, qq);
        ns = solve_q(&rc->r, &rc->m, qq, NULL, sol, &fl);
        DHT_TRUE_MSG((fl & DH_IKC_SING_ELBOW) != 0u, "%s: q%u = %g not flagged", rc->d.name, (unsigned)j + 1u, q[j]);
        DHT_TRUE(ns <= (rc->d.n == 4u ? 1u : 7u));
        n++;
    }
    DHT_TRUE(n > 0);
}

static void elbow_singular(void) { urq_each(4u, elbow_singular_case); }

/* SCARA with joint 3's frame origin on axis 1 (a1 = a2 folded is not the
 * Cobra; a test table with equal links): joint 1 from q_ref, flagged */
static void scara_shoulder_singular(void)
{
    dhs_robot d;
    dh_robot r;
    dh_ikc_model_q m;
    double q[6] = {30.0, 180.0, 100.0 * DHK_LS, 20.0, 0.0, 0.0};
    int32_t qq[6] = {0}, qref[6] = {0};
    dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
    uint32_t ns, fl;
    robot_mm(&d, &dhs_cobra600_mm);
    d.j[1].a = d.j[0].a;
    d.j[1].qmin = -180.0;
    d.j[1].qmax = 180.0;
    dhk_build_q(&d, DH_IKC_SCARA, &r, &m);
    dhs_q_from_double(&r, q, qq);
    qref[0] = qq[0];
    ns = solve_q(&r, &m, qq, qref, sol, &fl);
    DHT_TRUE((fl & DH_IKC_SING_SHOULDER) != 0u);
    DHT_TRUE((fl & DH_IKC_SING_ELBOW) != 0u);
    DHT_EQ_INT(ns, 1);
    DHT_TRUE(among(&r, sol, ns, qq, DHK_COMP_DEG));
}

/* ---- targets on and beyond the workspace boundary -------------------------- */

/* B of src/ikc/dh_ikc_par234_q.c: 64 LSB of the position format, in length units */
#define BOUND ldexp(64.0, -DH_QPOS_FRAC)

/* T translated by dist along the unit vector e */
static void shift(dhr_mat4 *T, const double *e, double dist)
{
    int i;
    for (i = 0; i < 3; i++) T->m[3][i] += dist * e[i];
}

/* dh_ikc_q of Td (any limits); when DH_OK, every solution checked against
 * Td; the flags ORed into *fl */
static dh_status solve_T(const dh_robot *r, const dh_ikc_model_q *m, const dhr_mat4 *Td, dh_ikc_sol_q *sol,
                         uint32_t *ns, uint32_t *fl)
{
    dh_frame_q T;
    dh_status rc;
    uint32_t s;
    *ns = 9;
    dhs_to_frame_q(Td, &T);
    rc = dh_ikc_q(m, &T, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, sol, ns);
    *fl = 0u;
    if (rc == DH_OK) (void)dhk_check_sols_q(r, Td, sol, *ns, NULL, NULL);
    for (s = 0; rc == DH_OK && s < *ns; s++) *fl |= sol[s].flags;
    return rc;
}

static double norm3(double *e)
{
    const double n = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    int i;
    for (i = 0; i < 3; i++) e[i] /= n;
    return n;
}

/* Stretched elbow with the wrist offset d5 in line with the arm (q3 = 0, q4
 * = +-90, whichever puts the joint 5 point farther): the joint 5 point on
 * the sphere about the frame 1 origin of radius sqrt((|a2| + |a3| + |d5|)^2
 * + h^2) (h = d2 + d3 + d4), beyond which no configuration reaches.
 * Moved outward by B / 2 the target is solved (the generating
 * configuration among the solutions, elbow flagged); by 4 B it is
 * unreachable. Folded (q3 = 180): moved by B / 2 into the elbow's hole the
 * generating branch is solved; by 4 B it is not among the solutions. */
static void ur_boundary_elbow_case(const urq_case *rc)
{
    long it, n[2] = {0, 0};
    for (it = 0; it < 20L * DHT_ITER(200) && (n[0] < DHT_ITER(200) || n[1] < DHT_ITER(200)); it++) {
        const int folded = (int)(it & 1);
        const double L = fabs(rc->d.j[1].a) + fabs(rc->d.j[2].a), e5 = fabs(rc->d.j[4].d);
        const double h = rc->d.j[1].d + rc->d.j[2].d + rc->d.j[3].d;
        double q[6], part[3], e[3], R, best = -1.0;
        int32_t qq[6];
        dhr_mat4 F[DHS_MAX_JOINTS], Td, Ts;
        dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
        uint32_t ns, fl;
        int k, i;
        if (n[folded] >= DHT_ITER(200)) continue;
        dhs_random_q(&rc->d, q);
        q[2] = folded ? 180.0 : 0.0;
        for (k = 0; k < 2; k++) { /* q4 = +-90: the joint 5 point farther from the frame 1 origin */
            double qt[6];
            memcpy(qt, q, sizeof qt);
            qt[3] = k ? -90.0 : 90.0;
            dhs_fk_desc(&rc->d, qt, F, NULL);
            for (i = 0; i < 3; i++) e[i] = F[4].m[3][i] - F[0].m[3][i];
            R = norm3(e);
            if (R > best) {
                best = R;
                q[3] = qt[3];
            }
        }
        /* UR10 folded: |u| <= |a2| - |a3| + |d5| = 0.09 L */
        (void)dhk_sing_parts(&rc->d, q, part);
        if (part[0] < 0.05 || part[2] < 0.1) continue;
        dhs_q_from_double(&rc->r, q, qq);
        dhs_fk_ref_q(&rc->r, qq, F, &Td);
        if (!folded) {
            /* outward from the frame 1 origin, on the sphere of the
             * largest reach */
            for (i = 0; i < 3; i++) e[i] = F[4].m[3][i] - F[0].m[3][i];
            R = norm3(e);
            DHT_TRUE_MSG(fabs(R - sqrt((L + e5) * (L + e5) + h * h)) <= 4.0 * ldexp(1.0, -DH_QPOS_FRAC),
                         "%s: joint 5 point at %.9g from the frame 1 origin", rc->d.name, R);
        } else {
            /* toward joint 2's axis in the arm's plane (normal z1):
             * the frame 3 origin less its z1 component */
            double z[3], w[3], dz = 0.0;
            for (i = 0; i < 3; i++) {
                z[i] = F[0].m[2][i];
                w[i] = F[2].m[3][i] - F[0].m[3][i];
                dz += w[i] * z[i];
            }
            for (i = 0; i < 3; i++) e[i] = -(w[i] - dz * z[i]);
            R = norm3(e);
            DHT_TRUE_MSG(fabs(R - fabs(fabs(rc->d.j[1].a) - fabs(rc->d.j[2].a))) <= 4.0 * ldexp(1.0, -DH_QPOS_FRAC),
                         "%s: folded planar point at %.9g", rc->d.name, R);
        }
        Ts = Td;
        shift(&Ts, e, 0.5 * BOUND);
        DHT_EQ_INT(solve_T(&rc->r, &rc->m, &Ts, sol, &ns, &fl), DH_OK);
        DHT_TRUE_MSG((fl & DH_IKC_SING_ELBOW) != 0u, "%s: B / 2 beyond the elbow's reach not flagged", rc->d.name);
        DHT_TRUE_MSG(among(&rc->r, sol, ns, qq, DHK_COMP_DEG), "%s: %s elbow B / 2 beyond: q not among %u solutions",
                     rc->d.name, folded ? "folded" : "stretched", (unsigned)ns);
        Ts = Td;
        shift(&Ts, e, 4.0 * BOUND);
        if (!folded) {
            DHT_EQ_INT(solve_T(&rc->r, &rc->m, &Ts, sol, &ns, &fl), DH_ERR_UNREACHABLE);
            DHT_EQ_INT(ns, 0);
        } else if (solve_T(&rc->r, &rc->m, &Ts, sol, &ns, &fl) == DH_OK) {
            DHT_TRUE_MSG(!among(&rc->r, sol, ns, qq, 0.1), "%s: folded elbow 4 B beyond: q among the solutions",
                         rc->d.name);
        }
        n[folded]++;
    }
    DHT_TRUE(n[0] > 0 && n[1] > 0);
}

static void ur_boundary_elbow(void) { urq_each(3u, ur_boundary_elbow_case); }

/* A configuration with the joint 5 point on the shoulder cylinder (u = 0,
 * as ur_shoulder_singular); elbow (q3 = 0 or 180) offset by `off` deg, or
 * away from it when off < 0; |s5| at least s5min. */
static int u_zero_q(const dhs_robot *d, long it, double off, double s5min, double *q)
{
    const double a2 = d->j[1].a, a3 = d->j[2].a, e5 = d->j[4].d;
    double X, Y, Rr, c, phi, part[3];
    dhs_random_q(d, q);
    if (off >= 0.0) q[2] = ((it & 2) ? 180.0 : 0.0) + dht_rand_uniform(-off, off);
    phi = (q[1] + q[2] + q[3]) * D2R;
    X = a2 + a3 * cos(q[2] * D2R);
    Y = a3 * sin(q[2] * D2R);
    Rr = sqrt(X * X + Y * Y);
    c = -e5 * sin(phi);
    if (fabs(c) >= Rr) return 0;
    q[1] = (-atan2(Y, X) + ((it & 1) ? 1 : -1) * acos(c / Rr)) / D2R;
    q[3] = phi / D2R - q[1] - q[2];
    (void)dhk_sing_parts(d, q, part);
    return part[2] >= s5min && (off >= 0.0 || part[1] >= 0.1);
}

/* The joint 5 point moved B / 2 into the shoulder cylinder (radius |h| about
 * axis 1): solved, flagged, the generating configuration among the
 * solutions within 1e-2 deg (the merged branch takes joint 1 from the
 * point's direction: the Q16.16 rounding of q moves u by up to ~30 LSB,
 * joint 1 by 30 / |h| rad, which the wrist amplifies by 1 / |s5| <= 3.3);
 * 4 B into it: unreachable (no configuration puts the joint 5 point nearer
 * axis 1 than |h|). */
static void ur_boundary_shoulder_case(const urq_case *rc)
{
    long it, n = 0;
    for (it = 0; it < 20L * DHT_ITER(200) && n < DHT_ITER(200); it++) {
        const double h = rc->d.j[1].d + rc->d.j[2].d + rc->d.j[3].d;
        double q[6], e[3], ez = 0.0, R;
        int32_t qq[6];
        dhr_mat4 F[DHS_MAX_JOINTS], Td, Ts;
        dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
        uint32_t ns, fl;
        int i;
        if (!u_zero_q(&rc->d, it, -1.0, 0.3, q)) continue;
        dhs_q_from_double(&rc->r, q, qq);
        dhs_fk_ref_q(&rc->r, qq, F, &Td);
        /* from axis 1 (base z through the base origin) to the joint 5 point */
        for (i = 0; i < 3; i++) {
            e[i] = F[4].m[3][i] - rc->d.base.m[3][i];
            ez += e[i] * rc->d.base.m[2][i];
        }
        for (i = 0; i < 3; i++) e[i] -= ez * rc->d.base.m[2][i];
        R = norm3(e);
        DHT_TRUE_MSG(fabs(R - fabs(h)) <= 4.0 * ldexp(1.0, -DH_QPOS_FRAC),
                     "%s: joint 5 point at %.9g from axis 1, |h| = %.9g", rc->d.name, R, fabs(h));
        Ts = Td;
        shift(&Ts, e, -0.5 * BOUND);
        DHT_EQ_INT(solve_T(&rc->r, &rc->m, &Ts, sol, &ns, &fl), DH_OK);
        DHT_TRUE_MSG((fl & DH_IKC_SING_SHOULDER) != 0u, "%s: B / 2 inside the cylinder not flagged", rc->d.name);
        DHT_TRUE_MSG(among(&rc->r, sol, ns, qq, 1e-2), "%s: B / 2 inside the cylinder: q not among %u solutions",
                     rc->d.name, (unsigned)ns);
        Ts = Td;
        shift(&Ts, e, -4.0 * BOUND);
        DHT_EQ_INT(solve_T(&rc->r, &rc->m, &Ts, sol, &ns, &fl), DH_ERR_UNREACHABLE);
        DHT_EQ_INT(ns, 0);
        n++;
    }
    DHT_TRUE(n > 0);
}

static void ur_boundary_shoulder(void) { urq_each(3u, ur_boundary_shoulder_case); }

/* The joint 5 point on the shoulder cylinder and the elbow within 0.05 deg
 * of stretched or folded: the rounding of the target moves the exact
 * joint 1 by up to sqrt(2 |h| LSB) / |h| (3e-4 rad), which the wrist
 * amplifies into the planar point; every such target is solved. */
static void ur_boundary_corner_case(const urq_case *rc)
{
    long it, n = 0;
    for (it = 0; it < 20L * DHT_ITER(500) && n < DHT_ITER(500); it++) {
        double q[6];
        int32_t qq[6];
        dhr_mat4 Td;
        dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
        uint32_t ns, fl;
        if (!u_zero_q(&rc->d, it, 0.05, 0.05, q)) continue;
        dhs_q_from_double(&rc->r, q, qq);
        dhs_fk_ref_q(&rc->r, qq, NULL, &Td);
        DHT_TRUE_MSG(solve_T(&rc->r, &rc->m, &Td, sol, &ns, &fl) == DH_OK && ns >= 1u,
                     "%s: corner target refused, q %.6f %.6f %.6f %.6f %.6f %.6f", rc->d.name, q[0], q[1], q[2], q[3],
                     q[4], q[5]);
        n++;
    }
    DHT_TRUE(n > 0);
}

static void ur_boundary_corner(void) { urq_each(3u, ur_boundary_corner_case); }

/* ---- unreachable and statuses --------------------------------------------- */

static void unreachable_case(const urq_case *rc)
{
    long it;
    for (it = 0; it < DHT_ITER(200); it++) {
        double q[6] = {0}, L = 0, sc, rxy;
        int32_t qq[6] = {0};
        dhr_mat4 Td;
        dh_frame_q T;
        dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
        uint32_t ns = 9, i;
        for (i = 0; i < rc->d.n; i++) L += fabs(rc->d.j[i].a) + fabs(rc->d.j[i].d);
        dhs_random_q(&rc->d, q);
        dhs_q_from_double(&rc->r, q, qq);
        dhs_fk_ref_q(&rc->r, qq, NULL, &Td);
        rxy = sqrt(Td.m[3][0] * Td.m[3][0] + Td.m[3][1] * Td.m[3][1]);
        sc = dht_rand_uniform(1.2, 5.0) * L / (rxy > 1e-3 ? rxy : 1e-3);
        Td.m[3][0] *= sc;
        Td.m[3][1] *= sc;
        dhs_to_frame_q(&Td, &T);
        DHT_EQ_INT(dh_ikc_q(&rc->m, &T, NULL, 0u, sol, &ns), DH_ERR_UNREACHABLE);
        DHT_EQ_INT(ns, 0);
    }
    if (rc->d.n == 4u) {
        /* a tool axis not parallel to the joint axes */
        double q[6] = {10.0, 20.0, 100.0 * DHK_LS, 30.0, 0.0, 0.0};
        int32_t qq[6] = {0};
        dhr_mat4 Td, Rx, T2;
        dh_frame_q T;
        dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
        uint32_t ns = 9;
        dhs_q_from_double(&rc->r, q, qq);
        dhs_fk_ref_q(&rc->r, qq, NULL, &Td);
        dhr_rotx(0.01, &Rx);
        dhr_mul(&Td, &Rx, &T2);
        dhs_to_frame_q(&T2, &T);
        DHT_EQ_INT(dh_ikc_q(&rc->m, &T, NULL, 0u, sol, &ns), DH_ERR_UNREACHABLE);
        DHT_EQ_INT(ns, 0);
    }
}

static void unreachable(void) { urq_each(4u, unreachable_case); }

/* the joint 5 point (UR) or joint 3 origin (SCARA) beyond 2^30 LSB: OVERFLOW */
static void overflow(void)
{
    unsigned ri;
    for (ri = 0; ri < 2u; ri++) {
        dhs_robot d;
        dh_robot r;
        dh_ikc_model_q m;
        dh_frame_q T;
        dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
        uint32_t ns = 9;
        int i;
        robot_mm(&d, ri == 0u ? &dhs_ur5_mm : &dhs_cobra600_mm);
        dhk_build_q(&d, ri == 0u ? DH_IKC_PARALLEL_234 : DH_IKC_SCARA, &r, &m);
        memset(&T, 0, sizeof T);
        for (i = 0; i < 3; i++) T.r[i][i] = (int32_t)1 << 30;
        if (ri == 1u) { /* tool axis down as the Cobra's */
            T.r[1][1] = -((int32_t)1 << 30);
            T.r[2][2] = -((int32_t)1 << 30);
        }
        T.p[0] = INT32_MAX;
        T.p[1] = 5;
        T.p[2] = 7;
        DHT_EQ_INT(dh_ikc_q(&m, &T, NULL, 0u, sol, &ns), DH_ERR_OVERFLOW);
        DHT_EQ_INT(ns, 0);
    }
}

/* what the fixed detectors recognise: as the float ones */
static void detect(void)
{
    dhs_robot d;
    dh_robot r;
    dh_ikc_model_q m;
    robot_mm(&d, &dhs_ur5_mm);
    d.j[1].alpha_deg = 1.0; /* axes 2, 3 not parallel */
    DHT_EQ_INT(dhs_build(&d, &r), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_q(&r, &m), DH_ERR_UNAVAILABLE);
    DHT_EQ_INT(m.kind, DH_IKC_NONE);
    DHT_EQ_INT(m.why, DH_IKC_WHY_WRIST);
    robot_mm(&d, &dhs_ur5_mm);
    d.j[4].a = 10.0; /* a5 != 0 */
    DHT_EQ_INT(dhs_build(&d, &r), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_q(&r, &m), DH_ERR_UNAVAILABLE);
    DHT_EQ_INT(m.why, DH_IKC_WHY_WRIST);
    robot_mm(&d, &dhs_cobra600_mm);
    d.j[1].alpha_deg = 179.0; /* SCARA axes not parallel */
    DHT_EQ_INT(dhs_build(&d, &r), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_q(&r, &m), DH_ERR_UNAVAILABLE);
    DHT_EQ_INT(m.why, DH_IKC_WHY_AXES);
}

/* not the family: each structural condition of the fixed detectors broken
 * on its own, as in the float suite (twin: not_family of test_ikc_ur.c) */
static void not_family(const dhs_robot *d, dh_ikc_kind kind)
{
    dh_robot r;
    dh_ikc_model_q m;
    dh_status st;
    DHT_EQ_INT(dhs_build(d, &r), DH_OK);
    st = dh_ikc_analyse_q(&r, &m);
    DHT_TRUE_MSG(st == DH_OK || st == DH_ERR_UNAVAILABLE, "%s: status %d", d->name, (int)st);
    DHT_TRUE_MSG(m.kind != kind, "%s: still recognised as kind %d", d->name, (int)kind);
}

static void detect_each(void)
{
    dhs_robot d;
    unsigned i;
    for (i = 0; i < 5u; i++) {
        robot_mm(&d, &dhs_ur5_mm);
        d.name = "ur5, one twist 1 deg off";
        d.j[i].alpha_deg += 1.0;
        not_family(&d, DH_IKC_PARALLEL_234);
    }
    robot_mm(&d, &dhs_ur5_mm);
    d.j[4].a = 10.0;
    not_family(&d, DH_IKC_PARALLEL_234);
    for (i = 1; i < 3u; i++) {
        robot_mm(&d, &dhs_ur5_mm);
        d.name = "ur5, a2 or a3 zero";
        d.j[i].a = 0.0;
        not_family(&d, DH_IKC_PARALLEL_234);
    }
    for (i = 0; i < 3u; i++) {
        robot_mm(&d, &dhs_cobra600_mm);
        d.name = "cobra600, one twist 1 deg off";
        d.j[i].alpha_deg += 1.0;
        not_family(&d, DH_IKC_SCARA);
    }
    robot_mm(&d, &dhs_cobra600_mm);
    d.j[0].a = 0.0;
    not_family(&d, DH_IKC_SCARA);
    robot_mm(&d, &dhs_cobra600_mm); /* the second link folded onto itself: a2 + a3 cos 180 = 0 */
    d.j[2].a = d.j[1].a;
    d.j[2].theta_deg = 180.0;
    not_family(&d, DH_IKC_SCARA);
    /* each twist sign on its own: still the family, still complete */
    for (i = 0; i < 5u; i++) {
        robot_mm(&d, &dhs_ur5_mm);
        d.name = "ur5, one twist mirrored";
        d.j[i].alpha_deg = dhs_mirror_twist(d.j[i].alpha_deg);
        random_run(&d, DH_IKC_PARALLEL_234, DHT_ITER(400), NULL);
    }
    for (i = 0; i < 3u; i++) {
        robot_mm(&d, &dhs_cobra600_mm);
        d.name = "cobra600, one twist mirrored";
        d.j[i].alpha_deg = dhs_mirror_twist(d.j[i].alpha_deg);
        random_run(&d, DH_IKC_SCARA, DHT_ITER(400), NULL);
    }
}

static const dht_case cases[] = {
    DHT_CASE(ur_random),
    DHT_CASE(scara_random),
    DHT_CASE(ur_wrist_singular),
    DHT_CASE(ur_shoulder_singular),
    DHT_CASE(elbow_singular),
    DHT_CASE(scara_shoulder_singular),
    DHT_CASE(ur_boundary_elbow),
    DHT_CASE(ur_boundary_shoulder),
    DHT_CASE(ur_boundary_corner),
    DHT_CASE(unreachable),
    DHT_CASE(overflow),
    DHT_CASE(detect),
    DHT_CASE(detect_each),
};
DHT_MAIN(cases)
