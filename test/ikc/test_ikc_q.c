/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_ikc_q.c - fixed-point closed-form IK, spherical-wrist families
 * (dh_ikc_analyse_q, dh_ikc_q, dh_ikc_nearest_q): every solution against
 * the double reference FK (test/support_robots.h) within 5e-3 mm and 5e-6
 * (rotation entries, ~rad), completeness (the generating configuration
 * among the solutions within 2e-3 deg) on random in-limit configurations
 * away from the singularities, singular cases, limits and 360-degree
 * shifts, MDH, base and tool, robots without a closed form, every status.
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
#define AWAY 1e-2     /* distance from the singularities (sin, or 10 mm) */
#define PI_D 3.14159265358979323846

/* ---- robots --------------------------------------------------------------- */

/* the shipped Puma 560 in mm, scaled */
static void puma(dhs_robot *d)
{
    *d = dhs_puma560_mm;
    dhk_scale_desc(d);
}

static void desc_set(dhs_robot *d, const char *name, dh_convention conv, unsigned n, const dhs_joint_desc *j)
{
    memset(d, 0, sizeof *d);
    d->name = name;
    d->conv = conv;
    d->n = n;
    d->unit_per_m = 1000.0;
    memcpy(d->j, j, n * sizeof *j);
    dhr_identity(&d->base);
    dhr_identity(&d->tool);
    dhk_scale_desc(d);
}

/* KUKA KR5 (KR 5 arc) in mm, standard DH: P. Corke, Robotics Toolbox for
 * Python, models/DH/KR5.py (as examples/robots/kuka_kr5.dh, which names its
 * sources), with the 115 mm flange as d6. Fields: type, a, d, alpha,
 * theta offset, qmin, qmax. */
static const dhs_joint_desc kr5_j[6] = {
    {DH_JOINT_REVOLUTE, 180.0, 400.0, -90.0, 0.0, -155.0, 155.0},
    {DH_JOINT_REVOLUTE, 600.0, 0.0, 0.0, 0.0, -180.0, 65.0},
    {DH_JOINT_REVOLUTE, 120.0, 0.0, 90.0, 0.0, -15.0, 158.0},
    {DH_JOINT_REVOLUTE, 0.0, -620.0, -90.0, 0.0, -350.0, 350.0},
    {DH_JOINT_REVOLUTE, 0.0, 0.0, 90.0, 0.0, -130.0, 130.0},
    {DH_JOINT_REVOLUTE, 0.0, -115.0, 180.0, 0.0, -350.0, 350.0},
};
/* ABB IRB 140 in mm, standard DH: P. Corke, Robotics Toolbox for Python,
 * models/DH/IRB140.py (as examples/robots/abb_irb140.dh). */
static const dhs_joint_desc irb140_j[6] = {
    {DH_JOINT_REVOLUTE, 70.0, 352.0, -90.0, 0.0, -180.0, 180.0},
    {DH_JOINT_REVOLUTE, 360.0, 0.0, 0.0, 0.0, -100.0, 100.0},
    {DH_JOINT_REVOLUTE, 0.0, 0.0, -90.0, 0.0, -220.0, 60.0},
    {DH_JOINT_REVOLUTE, 0.0, 380.0, 90.0, 0.0, -200.0, 200.0},
    {DH_JOINT_REVOLUTE, 0.0, 0.0, -90.0, 0.0, -120.0, 120.0},
    {DH_JOINT_REVOLUTE, 0.0, 65.0, 0.0, 0.0, -400.0, 400.0},
};
/* Stanford arm in mm, standard DH: P. Corke, Robotics Toolbox for Python,
 * models/DH/Stanford.py (kinematics from Stanford AIM-177, fig. 2.3; as
 * examples/robots/stanford.dh); joint 3 prismatic, theta -90, a 20.3. */
static const dhs_joint_desc stanford_j[6] = {
    {DH_JOINT_REVOLUTE, 0.0, 412.0, -90.0, 0.0, -170.0, 170.0},
    {DH_JOINT_REVOLUTE, 0.0, 154.0, 90.0, 0.0, -170.0, 170.0},
    {DH_JOINT_PRISMATIC, 20.3, 0.0, 0.0, -90.0, 304.8, 1270.0},
    {DH_JOINT_REVOLUTE, 0.0, 0.0, -90.0, 0.0, -170.0, 170.0},
    {DH_JOINT_REVOLUTE, 0.0, 0.0, 90.0, 0.0, -90.0, 90.0},
    {DH_JOINT_REVOLUTE, 0.0, 0.0, 0.0, 0.0, -170.0, 170.0},
};
/* Test tables (not real robots) for what the three above leave out:
 * alpha2 = 180 (sigma = -1), d3 != 0, a tool along z, alpha6 = 180;
 * theta offsets on revolute joints, alpha3 = +90, a prismatic d6 tool. */
static const dhs_joint_desc sigma_j[6] = {
    {DH_JOINT_REVOLUTE, 180.0, 400.0, 90.0, 0.0, -155.0, 155.0},
    {DH_JOINT_REVOLUTE, 600.0, 135.0, 180.0, 0.0, -180.0, 65.0},
    {DH_JOINT_REVOLUTE, 120.0, 135.0, -90.0, 0.0, -15.0, 158.0},
    {DH_JOINT_REVOLUTE, 0.0, 620.0, 90.0, 0.0, -350.0, 350.0},
    {DH_JOINT_REVOLUTE, 0.0, 0.0, 90.0, 0.0, -130.0, 130.0},
    {DH_JOINT_REVOLUTE, 0.0, 0.0, 180.0, 0.0, -350.0, 350.0},
};
static const dhs_joint_desc offsets_j[6] = {
    {DH_JOINT_REVOLUTE, 70.0, 352.0, -90.0, 0.0, -180.0, 180.0},
    {DH_JOINT_REVOLUTE, 360.0, 0.0, 0.0, -90.0, -100.0, 100.0},
    {DH_JOINT_REVOLUTE, 0.0, 0.0, 90.0, 180.0, -220.0, 60.0},
    {DH_JOINT_REVOLUTE, 0.0, 380.0, -90.0, 0.0, -200.0, 200.0},
    {DH_JOINT_REVOLUTE, 0.0, 0.0, 90.0, 0.0, -120.0, 120.0},
    {DH_JOINT_REVOLUTE, 0.0, 65.0, 0.0, 0.0, -400.0, 400.0},
};

/* ---- reference checks (and support_ikc.h) ---------------------------------- */

/* 1 when a joint of q lies within DHK_COMP_DEG of one of its limits: the
 * solution that matches q within DHK_COMP_DEG may then lie beyond that limit
 * by as much (flagged DH_IKC_OUT_OF_LIMITS and dropped by default) */
static int near_limit(const dh_robot *r, const int32_t *q)
{
    unsigned i;
    for (i = 0; i < r->n; i++) {
        const dh_joint *j = &r->joint[i];
        if (j->qmin_q <= j->qmax_q && (dhk_jdiff_q(r, i, q[i], j->qmin_q) <= DHK_COMP_DEG || dhk_jdiff_q(r, i, q[i], j->qmax_q) <= DHK_COMP_DEG))
            return 1;
    }
    return 0;
}

/* 1 when q of the SDH description d (identity base) is AWAY from the wrist,
 * elbow and shoulder singularities of the families */
static int away_u(const dhs_robot *d, const double *q, double umin)
{
    dhr_mat4 fr[6], T;
    double o[3], o1[3], h2, u2, t3;
    int i;
    if (fabs(sin((q[4] + d->j[4].theta_deg) * PI_D / 180.0)) < AWAY) return 0;
    if (d->j[2].type == DH_JOINT_REVOLUTE) {
        double e = sin(d->j[2].alpha_deg * PI_D / 180.0) * d->j[3].d;
        t3 = (q[2] + d->j[2].theta_deg) * PI_D / 180.0;
        if (fabs(sin(t3 - atan2(e, d->j[2].a))) < AWAY) return 0;
    } else if (fabs(q[2] + d->j[2].d) < 10.0 * DHK_LS) {
        return 0;
    }
    dhs_fk_desc(d, q, fr, &T);
    for (i = 0; i < 3; i++) o[i] = fr[3].m[3][i];
    /* o in frame 1: the offset h of the wrist centre along z1 */
    for (i = 0; i < 3; i++)
        o1[i] = fr[0].m[i][0] * (o[0] - fr[0].m[3][0]) + fr[0].m[i][1] * (o[1] - fr[0].m[3][1]) +
                fr[0].m[i][2] * (o[2] - fr[0].m[3][2]);
    h2 = o1[2] * o1[2];
    u2 = o[0] * o[0] + o[1] * o[1] - h2;
    return u2 > umin * umin * DHK_LS * DHK_LS;
}

static int away(const dhs_robot *d, const double *q)
{
    return away_u(d, q, 10.0);
}

static int well_conditioned(const dhs_robot *d, const double *q)
{
    return dhk_well_conditioned_q(d, q, 0.5 * DHK_COMP_DEG, 6);
}

/* random in-limit configurations of d (filter: the SDH description f).
 * Reach probes: "<name>.elbow_deg", the nearest a configuration came to the
 * stretched or folded elbow of f (deg), "<name>.kept", the ill-conditioned
 * targets solved only with the out-of-limit solutions kept, and
 * "<name>.near_limit", the generating configurations found only among
 * those (stats.near_limit), "<name>.first_order", those found only by
 * dhk_first_order_match_q. */
static void random_run(const dhs_robot *d, const dhs_robot *f, dh_ikc_kind kind, long iters)
{
    dh_robot r;
    dh_ikc_model_q m;
    dhk_stats st;
    long it, kept = 0, first_order = 0;
    char probe[48];
    memset(&st, 0, sizeof st);
    dhk_build_q(d, kind, &r, &m);
    for (it = 0; it < iters; it++) {
        double q[6];
        int32_t qq[6];
        dhr_mat4 Td;
        dh_frame_q T;
        dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
        uint32_t ns = 0;
        dh_status rc;
        int comp, found;
        dhs_random_q(d, q);
        dhs_q_from_double(&r, q, qq);
        if (f->j[2].type == DH_JOINT_REVOLUTE) {
            snprintf(probe, sizeof probe, "%s.elbow_deg", d->name);
            dht_reach_min(probe, fabs(remainder(q[2] + f->j[2].theta_deg -
                                                atan2(sin(f->j[2].alpha_deg * PI_D / 180.0) * f->j[3].d, f->j[2].a) *
                                                    180.0 / PI_D,
                                                180.0)));
        }
        comp = away(f, q) && well_conditioned(d, q);
        dhs_fk_ref_q(&r, qq, NULL, &Td);
        dhs_to_frame_q(&Td, &T);
        rc = dh_ikc_q(&m, &T, NULL, 0u, sol, &ns);
        if (rc == DH_ERR_LIMIT && !comp) {
            /* ill-conditioned: the in-limit configuration may move across a
             * limit; the solutions kept out of limits are checked */
            rc = dh_ikc_q(&m, &T, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &ns);
            kept++;
        }
        DHT_TRUE_MSG(rc == DH_OK && ns >= 1u, "%s: status %d, %u solutions for q %.6f %.6f %.6f %.6f %.6f %.6f",
                     d->name, (int)rc, (unsigned)ns, q[0], q[1], q[2], q[3], q[4], q[5]);
        found = dhk_check_sols_q(&r, &Td, sol, ns, qq, &st);
        st.targets++;
        if (comp && found < 0 && near_limit(&r, qq)) {
            /* the generating configuration's own solution may lie beyond
             * the limit by a rounding: search the solutions kept out of
             * limits too (every one still checked for its residuals) */
            DHT_EQ_INT(dh_ikc_q(&m, &T, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &ns), DH_OK);
            found = dhk_check_sols_q(&r, &Td, sol, ns, qq, NULL);
            st.near_limit++;
        }
        if (comp && found < 0) {
            /* beyond DHK_COMP_DEG: the same branch when the solution's own
             * residual explains the distance to first order */
            found = dhk_first_order_match_q(d, q, &r, &Td, sol, ns, qq);
            if (found >= 0) first_order++;
        }
        if (comp) {
            st.comp++;
            DHT_TRUE_MSG(found >= 0, "%s: generating configuration %.6f %.6f %.6f %.6f %.6f %.6f not among %u solutions",
                         d->name, q[0], q[1], q[2], q[3], q[4], q[5], (unsigned)ns);
        }
    }
    snprintf(probe, sizeof probe, "%s.kept", d->name);
    dht_reach_max(probe, (double)kept);
    snprintf(probe, sizeof probe, "%s.first_order", d->name);
    dht_reach_max(probe, (double)first_order);
    snprintf(probe, sizeof probe, "%s.near_limit", d->name);
    dht_reach_max(probe, (double)st.near_limit);
    dht_printf("%s: %ld targets (%ld completeness), %ld solutions, max err %.3g mm, %.3g\n", d->name, st.targets,
               st.comp, st.sols, st.pos, st.rot);
    DHT_TRUE(st.comp >= iters / 2);
}

static void puma_random(void)
{
    dhs_robot d;
    puma(&d);
    random_run(&d, &d, DH_IKC_WRIST_RRR, DHT_ITER(10000));
}

static void kr5_random(void)
{
    dhs_robot d;
    desc_set(&d, "kr5_mm", DH_CONV_STANDARD, 6, kr5_j);
    random_run(&d, &d, DH_IKC_WRIST_RRR, DHT_ITER(10000));
}

static void irb140_random(void)
{
    dhs_robot d;
    desc_set(&d, "irb140_mm", DH_CONV_STANDARD, 6, irb140_j);
    random_run(&d, &d, DH_IKC_WRIST_RRR, DHT_ITER(10000));
}

static void test_tables_random(void)
{
    dhs_robot d;
    desc_set(&d, "sigma_test", DH_CONV_STANDARD, 6, sigma_j);
    random_run(&d, &d, DH_IKC_WRIST_RRR, DHT_ITER(5000));
    desc_set(&d, "offsets_test", DH_CONV_STANDARD, 6, offsets_j);
    random_run(&d, &d, DH_IKC_WRIST_RRR, DHT_ITER(5000));
}

static void stanford_random(void)
{
    dhs_robot d;
    desc_set(&d, "stanford_mm", DH_CONV_STANDARD, 6, stanford_j);
    random_run(&d, &d, DH_IKC_WRIST_RRP, DHT_ITER(10000));
}

/* the Puma 560 as an MDH table: joint i takes the SDH a/alpha of joint i-1;
 * joint 0 gets a = 50, alpha = 30 (a non-trivial first link, pre frame) */
static void mdh_random(void)
{
    dhs_robot d, f;
    unsigned i;
    puma(&f);
    d = f;
    d.name = "puma560_mdh_mm";
    d.conv = DH_CONV_MODIFIED;
    for (i = 5; i >= 1; i--) {
        d.j[i].a = f.j[i - 1].a;
        d.j[i].alpha_deg = f.j[i - 1].alpha_deg;
    }
    d.j[0].a = 50.0 * DHK_LS;
    d.j[0].alpha_deg = 30.0;
    random_run(&d, &f, DH_IKC_WRIST_RRR, DHT_ITER(3000));
}

/* the Puma 560 with a base and a tool frame */
static void puma_base_tool(dhs_robot *d)
{
    dhr_mat4 A, B;
    puma(d);
    d->name = "puma560_base_tool_mm";
    dhr_rotz(30.0, &A);
    dhr_trans(100.0 * DHK_LS, -50.0 * DHK_LS, 200.0 * DHK_LS, &B);
    dhr_mul(&A, &B, &d->base);
    dhr_rotx(10.0, &A);
    B = d->base;
    dhr_mul(&B, &A, &d->base);
    dhr_trans(10.0 * DHK_LS, 20.0 * DHK_LS, 80.0 * DHK_LS, &A);
    dhr_rotx(20.0, &B);
    dhr_mul(&A, &B, &d->tool);
}

/* the Puma's description (d), integer robot (r) and closed-form model (m) */
typedef struct {
    dhs_robot d;
    dh_robot r;
    dh_ikc_model_q m;
} puma_q;

/* the Puma (base_tool: with puma_base_tool's base and tool) into *p */
static void puma_model(int base_tool, puma_q *p)
{
    if (base_tool) puma_base_tool(&p->d);
    else puma(&p->d);
    dhk_build_q(&p->d, DH_IKC_WRIST_RRR, &p->r, &p->m);
}

static void base_tool_random(void)
{
    dhs_robot d, f;
    dhr_mat4 A, B;
    puma(&f);
    puma_base_tool(&d);
    random_run(&d, &f, DH_IKC_WRIST_RRR, DHT_ITER(3000));
    /* the same with the KR5 (alpha6 = 180, a tool along z) */
    desc_set(&d, "kr5_base_tool_mm", DH_CONV_STANDARD, 6, kr5_j);
    dhr_rotz(-45.0, &A);
    dhr_trans(0.0, 300.0 * DHK_LS, 0.0, &B);
    dhr_mul(&A, &B, &d.base);
    dhr_trans(0.0, 0.0, 115.0 * DHK_LS, &d.tool);
    desc_set(&f, "kr5_mm", DH_CONV_STANDARD, 6, kr5_j);
    random_run(&d, &f, DH_IKC_WRIST_RRR, DHT_ITER(3000));
}

/* ---- singular cases ------------------------------------------------------- */

static void solve_q(const dh_robot *r, const dh_ikc_model_q *m, const int32_t *qq, const int32_t *qref, uint32_t opts,
                    dh_ikc_sol_q *sol, uint32_t *ns, dhr_mat4 *Td)
{
    dh_frame_q T;
    dhs_fk_ref_q(r, qq, NULL, Td);
    dhs_to_frame_q(Td, &T);
    DHT_EQ_INT(dh_ikc_q(m, &T, qref, opts, sol, ns), DH_OK);
    (void)dhk_check_sols_q(r, Td, sol, *ns, NULL, NULL);
}

static void singular_wrist(void)
{
    puma_q pm;
    long it;
    long tested = 0;
    puma_model(0, &pm);
    for (it = 0; it < DHT_ITER(500); it++) {
        double q[6];
        int32_t qq[6];
        dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
        uint32_t ns, s, hits = 0;
        dhr_mat4 Td;
        dhs_random_q(&pm.d, q);
        /* a well-conditioned arm (elbow far from stretched and folded,
         * shoulder bent): its angles come out within a few LSB, so the
         * wrist sees less than the 2^-19 of its singular test */
        q[1] = dht_rand_uniform(-60.0, 60.0);
        q[2] = dht_rand_uniform(-40.0, 40.0);
        q[4] = 30.0;
        if (!away_u(&pm.d, q, 200.0)) continue;
        tested++;
        q[4] = 0.0;
        dhs_q_from_double(&pm.r, q, qq);
        solve_q(&pm.r, &pm.m, qq, qq, 0u, sol, &ns, &Td);
        DHT_TRUE(ns >= 1u && ns <= 7u);
        for (s = 0; s < ns; s++) {
            /* the generating arm branch is singular (the others are not, in general) */
            if (dhk_jdiff_q(&pm.r, 0, sol[s].q[0], qq[0]) > DHK_COMP_DEG || dhk_jdiff_q(&pm.r, 1, sol[s].q[1], qq[1]) > DHK_COMP_DEG ||
                dhk_jdiff_q(&pm.r, 2, sol[s].q[2], qq[2]) > DHK_COMP_DEG)
                continue;
            hits++;
            DHT_TRUE((sol[s].flags & DH_IKC_SING_WRIST) != 0u);
            DHT_TRUE((sol[s].flags & DH_IKC_WRIST_ALT) == 0u);
            /* joint 4 keeps the reference's value */
            DHT_TRUE(dhk_jdiff_q(&pm.r, 3, sol[s].q[3], qq[3]) == 0.0);
        }
        DHT_EQ_INT(hits, 1);
    }
    DHT_TRUE(tested >= DHT_ITER(500) / 4);
}

static void singular_elbow(void)
{
    dhs_robot P;
    dh_robot r;
    dh_ikc_model_q m;
    puma(&P);
    /* stretched: t3 = phi = atan2(s_alpha3 d4, a3) */
    const double phi = atan2(-431.8, 20.3) * 180.0 / PI_D;
    double q[6] = {20.0, -30.0, 0.0, 40.0, 50.0, -60.0};
    int32_t qq[6];
    dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
    uint32_t ns, s;
    dhr_mat4 Td;
    q[2] = phi;
    dhk_build_q(&P, DH_IKC_WRIST_RRR, &r, &m);
    dhs_q_from_double(&r, q, qq);
    solve_q(&r, &m, qq, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &ns, &Td);
    DHT_EQ_INT(ns, 4);
    for (s = 0; s < ns; s++) {
        DHT_TRUE((sol[s].flags & DH_IKC_SING_ELBOW) != 0u);
        DHT_TRUE((sol[s].flags & DH_IKC_ELBOW_ALT) == 0u);
    }
    DHT_TRUE(dhk_check_sols_q(&r, &Td, sol, ns, qq, NULL) >= 0);
}

/* The folded elbow with the wrist centre on the shoulder cylinder (u = 0):
 * a rounding of the target moves u by far more than a rounding there, so
 * the rounded wrist centre can lie inside the folded radius; such targets
 * are solved on the boundary. The sweep covers +-4 LSB of joint 3 around
 * the fold and +-0.03 deg of joint 2 around u = 0; the two listed
 * configurations are random draws that once came back unreachable. */
static void boundary_folded(void)
{
    static const double seen[2][6] = {
        {-134.376743, 50.400184, 92.694226, 197.892038, -71.685242, -229.089479},
        {-128.923767, 18.078812, 92.700125, -87.316141, -4.757050, -109.683987}};
    const double a2 = 431.8, a3 = 20.3, e = -431.8;
    const double t3 = atan2(e, a3) + PI_D; /* folded: t3 - phi = 180 deg */
    const double A = a2 + a3 * cos(t3) + e * sin(t3), B = a3 * sin(t3) - e * cos(t3);
    const double t2 = 90.0 - atan2(B, A) * 180.0 / PI_D; /* vx = 0 */
    puma_q pm;
    dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
    dhr_mat4 Td;
    uint32_t ns, s;
    int i, j, k;
    puma_model(1, &pm);
    for (i = 0; i < 2; i++) {
        int32_t qq[6];
        dhs_q_from_double(&pm.r, seen[i], qq);
        solve_q(&pm.r, &pm.m, qq, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &ns, &Td);
        DHT_TRUE(ns >= 1u);
        for (s = 0; s < ns; s++) DHT_TRUE((sol[s].flags & DH_IKC_SING_ELBOW) != 0u);
    }
    for (j = -3; j <= 3; j++)
        for (k = -4; k <= 4; k++) {
            double q[6] = {-130.0, 0.0, 0.0, 40.0, 50.0, -60.0};
            int32_t qq[6];
            q[1] = t2 + 0.01 * j;
            dhs_q_from_double(&pm.r, q, qq);
            qq[2] = (int32_t)floor(t3 * 180.0 / PI_D * 65536.0 + 0.5) + k;
            solve_q(&pm.r, &pm.m, qq, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &ns, &Td);
            DHT_TRUE(ns >= 1u);
        }
}

/* A target moved radially beyond the stretched elbow: by 0.9 of 2^(5 - F)
 * units it is solved, by 1.1 of 2^(8 - F) units it is unreachable (the
 * bounds of ikc.h; F = DH_QPOS_FRAC, the robot in units of 2^(F - 16)
 * mm). Moved by 0.9 of 2^(5 - F) beyond the folded elbow it is solved; farther in that direction is not beyond by as much: the Puma's
 * folded wrist centre lies within |delta| of the shoulder cylinder, where
 * joint 1 turns such a point back to within 2 LSB of the workspace. */
static void boundary_beyond(void)
{
    const double phi = atan2(-431.8, 20.3) * 180.0 / PI_D;
    const double rho = sqrt(20.3 * 20.3 + 431.8 * 431.8);
    puma_q pm;
    dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
    dh_frame_q T;
    uint32_t ns, s;
    int i, far, folded;
    puma_model(0, &pm);
    for (folded = 0; folded < 2; folded++) {
        double q[6] = {20.0, -30.0, 0.0, 40.0, 50.0, -60.0}, w[3], nw = 0.0, wz = 0.0;
        dhr_mat4 fr[6], Td;
        int32_t qq[6];
        q[2] = folded ? phi + 180.0 : phi;
        dhs_q_from_double(&pm.r, q, qq);
        dhs_fk_ref_q(&pm.r, qq, fr, &Td);
        /* from the joint 2 axis (frame 1) to the wrist centre (origin of
         * frame 4), normal to that axis: outward for stretched, inward for folded */
        for (i = 0; i < 3; i++) w[i] = fr[3].m[3][i] - fr[0].m[3][i];
        for (i = 0; i < 3; i++) wz += w[i] * fr[0].m[2][i];
        for (i = 0; i < 3; i++) {
            w[i] -= wz * fr[0].m[2][i];
            nw += w[i] * w[i];
        }
        nw = sqrt(nw);
        DHT_TRUE(fabs(nw - (folded ? rho - 431.8 : rho + 431.8) * DHK_LS) < 1e-3 * DHK_LS);
        for (far = 0; far < 2 - folded; far++) {
            dhr_mat4 Tm = Td;
            const double dist = (far ? ldexp(1.1, 8 - DH_QPOS_FRAC) : ldexp(0.9, 5 - DH_QPOS_FRAC)) * (folded ? -1.0 : 1.0);
            for (i = 0; i < 3; i++) Tm.m[3][i] += dist * w[i] / nw;
            dhs_to_frame_q(&Tm, &T);
            if (far) {
                DHT_EQ_INT(dh_ikc_q(&pm.m, &T, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &ns), DH_ERR_UNREACHABLE);
                DHT_EQ_INT(ns, 0);
            } else {
                DHT_EQ_INT(dh_ikc_q(&pm.m, &T, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &ns), DH_OK);
                DHT_TRUE(ns >= 1u);
                /* stretched: flagged; folded, the Puma's wrist centre lies
                 * within |delta| of the shoulder cylinder, where the
                 * target's rounding moves |v| by more than 2^5 LSB: the
                 * solutions may be the two branches of a point just inside */
                for (s = 0; s < ns && !folded; s++) DHT_TRUE((sol[s].flags & DH_IKC_SING_ELBOW) != 0u);
                (void)dhk_check_sols_q(&pm.r, &Tm, sol, ns, NULL, NULL);
            }
        }
    }
}

/* a Puma with d3 = 0 (h = 0): the wrist centre on axis 1 */
static void singular_shoulder(void)
{
    dhs_robot P, d;
    dh_robot r;
    dh_ikc_model_q m;
    const double t3 = 30.0 * PI_D / 180.0, a2 = 431.8, a3 = 20.3, e = -431.8;
    const double A = a2 + a3 * cos(t3) + e * sin(t3), B = a3 * sin(t3) - e * cos(t3);
    double q[6] = {0.0, 0.0, 30.0, 10.0, 40.0, 20.0};
    int32_t qq[6], qref[6] = {0, 0, 0, 0, 0, 0};
    dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
    uint32_t ns, s;
    dhr_mat4 Td;
    puma(&P);
    d = P;
    d.j[2].d = 0.0;
    dhk_build_q(&d, DH_IKC_WRIST_RRR, &r, &m);
    q[1] = atan2(A, B) * 180.0 / PI_D;
    q[0] = 25.0;
    dhs_q_from_double(&r, q, qq);
    qref[0] = qq[0] + 3 * 65536; /* joint 1 comes from the reference */
    solve_q(&r, &m, qq, qref, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &ns, &Td);
    DHT_TRUE(ns >= 1u && ns <= 4u);
    for (s = 0; s < ns; s++) {
        DHT_TRUE((sol[s].flags & DH_IKC_SING_SHOULDER) != 0u);
        DHT_TRUE((sol[s].flags & DH_IKC_SHOULDER_ALT) == 0u);
        DHT_EQ_INT(sol[s].q[0], qref[0]);
    }
}

/* ---- limits --------------------------------------------------------------- */

static void limits_shift(void)
{
    puma_q pm;
    double q[6] = {10.0, -20.0, 30.0, 200.0, 40.0, -250.0};
    int32_t qq[6], qref[6];
    dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
    uint32_t ns, idx;
    dhr_mat4 Td;
    int f;
    puma_model(0, &pm);
    dhs_q_from_double(&pm.r, q, qq);
    /* q_ref = the configuration: joints 4 and 6 shifted to 200 and -250 */
    memcpy(qref, qq, sizeof qref);
    solve_q(&pm.r, &pm.m, qq, qref, 0u, sol, &ns, &Td);
    f = dhk_check_sols_q(&pm.r, &Td, sol, ns, qq, NULL);
    DHT_TRUE(f >= 0);
    DHT_TRUE(fabs(ldexp((double)sol[f].q[3], -16) - 200.0) < DHK_COMP_DEG);
    DHT_TRUE(fabs(ldexp((double)sol[f].q[5], -16) + 250.0) < DHK_COMP_DEG);
    DHT_EQ_INT(dh_ikc_nearest_q(sol, ns, qref, 6, &idx), DH_OK);
    DHT_EQ_INT(idx, f);
    /* q_ref zero: the values nearest 0, -160 and 110 */
    solve_q(&pm.r, &pm.m, qq, NULL, 0u, sol, &ns, &Td);
    f = dhk_check_sols_q(&pm.r, &Td, sol, ns, qq, NULL);
    DHT_TRUE(f >= 0);
    DHT_TRUE(fabs(ldexp((double)sol[f].q[3], -16) + 160.0) < DHK_COMP_DEG);
    DHT_TRUE(fabs(ldexp((double)sol[f].q[5], -16) - 110.0) < DHK_COMP_DEG);
    /* wide limits (more than three turns): joint 4 shifted next to q_ref = 1000 */
    DHT_EQ_INT(dh_robot_set_limits_q(&pm.r, 3, -2000 * 65536, 2000 * 65536), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_q(&pm.r, &pm.m), DH_OK);
    qref[3] = 1000 * 65536;
    solve_q(&pm.r, &pm.m, qq, qref, 0u, sol, &ns, &Td);
    f = dhk_check_sols_q(&pm.r, &Td, sol, ns, qq, NULL);
    DHT_TRUE(f >= 0);
    DHT_TRUE(fabs(ldexp((double)sol[f].q[3], -16) - 920.0) < DHK_COMP_DEG);
    qref[3] = -2000 * 65536;
    solve_q(&pm.r, &pm.m, qq, qref, 0u, sol, &ns, &Td);
    f = dhk_check_sols_q(&pm.r, &Td, sol, ns, qq, NULL);
    DHT_TRUE(f >= 0);
    DHT_TRUE(fabs(ldexp((double)sol[f].q[3], -16) + 1960.0) < DHK_COMP_DEG);
}

/* The contract's shift, in double: the value v + 360 k in [lo, hi]
 * nearest ref (ties: the lower), or v when there is none */
static double shift_ref(double v, double lo, double hi, double ref)
{
    double best = v, bd = 1e300, c;
    int k;
    for (k = -10; k <= 10; k++) {
        c = v + 360.0 * k;
        if (c >= lo && c <= hi && fabs(c - ref) < bd) {
            best = c;
            bd = fabs(c - ref);
        }
    }
    return best;
}

/* Limits of joint 4 reaching beyond +-540 deg, less than three turns apart
 * ([-900, 0], [600, 1000], [600, 700]: the candidates searched one by one)
 * or more ([100, 2000]: the first shift inside by a remainder, q_ref beyond
 * the upper limit): joint 4 of the generating solution (200 deg, in
 * (-180, 180] -160) is the shift nearest q_ref inside the limits
 * (shift_ref), or outside them kept, flagged and in (-180, 180]. */
static void limits_shift_beyond_540(void)
{
    static const double lim[][3] = {
        { -900.0, 0.0, -600.0 }, { -900.0, 0.0, -1000.0 }, { -900.0, 0.0, -700.0 }, { 600.0, 1000.0, 0.0 },
        { 600.0, 700.0, 0.0 },   { 100.0, 2000.0, 5000.0 }, { 100.0, 2000.0, 700.0 }, { 100.0, 2000.0, -3000.0 },
    };
    puma_q pm;
    double q[6] = {10.0, -20.0, 30.0, 200.0, 40.0, -50.0};
    int32_t qq[6], qref[6];
    dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
    uint32_t ns;
    dhr_mat4 Td;
    unsigned k;
    int f;
    puma_model(0, &pm);
    dhs_q_from_double(&pm.r, q, qq);
    for (k = 0; k < sizeof lim / sizeof lim[0]; k++) {
        const double want = shift_ref(-160.0, lim[k][0], lim[k][1], lim[k][2]);
        const int inside = want >= lim[k][0] && want <= lim[k][1];
        memcpy(qref, qq, sizeof qref);
        qref[3] = (int32_t)(lim[k][2] * 65536.0);
        DHT_EQ_INT(dh_robot_set_limits_q(&pm.r, 3, (int32_t)(lim[k][0] * 65536.0), (int32_t)(lim[k][1] * 65536.0)),
                   DH_OK);
        DHT_EQ_INT(dh_ikc_analyse_q(&pm.r, &pm.m), DH_OK);
        solve_q(&pm.r, &pm.m, qq, qref, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &ns, &Td);
        f = dhk_check_sols_q(&pm.r, &Td, sol, ns, qq, NULL);
        DHT_TRUE(f >= 0);
        DHT_TRUE_MSG(fabs(ldexp((double)sol[f].q[3], -16) - want) < DHK_COMP_DEG, "limits [%g, %g], q_ref %g: %.6f, want %g",
                     lim[k][0], lim[k][1], lim[k][2], ldexp((double)sol[f].q[3], -16), want);
        DHT_EQ_INT((sol[f].flags & DH_IKC_OUT_OF_LIMITS) != 0u, !inside);
    }
}

static void limits_drop_keep(void)
{
    dhs_robot P, d, dn;
    dh_robot r, rn;
    dh_ikc_model_q m, mn;
    double q[6] = {90.0, -20.0, 30.0, 20.0, 40.0, -50.0};
    int32_t qq[6];
    dh_ikc_sol_q sol[DH_IKC_MAX_SOL], all[DH_IKC_MAX_SOL];
    uint32_t ns, na, s, i;
    dhr_mat4 Td;
    dh_frame_q T;
    unsigned j;
    puma(&P);
    d = P;
    dn = P;
    d.j[0].qmin = 0.0;
    d.j[0].qmax = 1.0;
    for (j = 0; j < 6; j++) dn.j[j].qmin = 1.0, dn.j[j].qmax = -1.0; /* no limits */
    dhk_build_q(&d, DH_IKC_WRIST_RRR, &r, &m);
    dhk_build_q(&dn, DH_IKC_WRIST_RRR, &rn, &mn);
    dhs_q_from_double(&rn, q, qq);
    dhs_fk_ref_q(&rn, qq, NULL, &Td);
    dhs_to_frame_q(&Td, &T);
    DHT_EQ_INT(dh_ikc_q(&mn, &T, NULL, 0u, all, &na), DH_OK);
    DHT_EQ_INT(na, 8);
    (void)dhk_check_sols_q(&rn, &Td, all, na, NULL, NULL);
    for (s = 0; s < na; s++) DHT_EQ_INT(all[s].flags & DH_IKC_OUT_OF_LIMITS, 0);
    ns = 99;
    DHT_EQ_INT(dh_ikc_q(&m, &T, NULL, 0u, sol, &ns), DH_ERR_LIMIT);
    DHT_EQ_INT(ns, 0);
    DHT_EQ_INT(dh_ikc_q(&m, &T, NULL, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &ns), DH_OK);
    DHT_EQ_INT(ns, 8);
    for (s = 0; s < ns; s++) {
        DHT_TRUE((sol[s].flags & DH_IKC_OUT_OF_LIMITS) != 0u);
        for (i = 0; i < 6; i++) DHT_EQ_INT(sol[s].q[i], all[s].q[i]);
    }
    /* the Puma's own limits drop some of the eight and keep the rest */
    dhk_build_q(&P, DH_IKC_WRIST_RRR, &r, &m);
    DHT_EQ_INT(dh_ikc_q(&m, &T, NULL, 0u, sol, &ns), DH_OK);
    DHT_TRUE(ns >= 1u && ns < 8u);
    for (s = 0; s < ns; s++) DHT_EQ_INT(dh_robot_check_limits_q(&r, sol[s].q), DH_OK);
}

/* ---- robots without a closed form ---------------------------------------- */

static void analyse_why(const dhs_robot *d, dh_ikc_why why)
{
    dh_robot r;
    dh_ikc_model_q m;
    DHT_EQ_INT(dhs_build(d, &r), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_q(&r, &m), DH_ERR_UNAVAILABLE);
    DHT_EQ_INT(m.kind, DH_IKC_NONE);
    DHT_EQ_INT(m.why, why);
}

/* A model whose fields are out of range (ikc.h, dh_ikc_q: DH_ERR_ARG, no
 * solution, sol untouched): a frame entry beyond 1.1, a revolute offset
 * at -180 (outside (-180, 180]), a joint count not the family's, an
 * unknown kind; and a robot without joints has no closed form. */
static void model_out_of_range(void)
{
    puma_q pm;
    dh_ikc_model_q bad;
    dh_ikc_sol_q sol[DH_IKC_MAX_SOL], keep[DH_IKC_MAX_SOL];
    double q[6] = {10.0, -20.0, 30.0, 40.0, 50.0, 60.0};
    int32_t qq[6];
    uint32_t ns, k;
    dhr_mat4 Td;
    dh_frame_q T;
    dh_robot r0;
    puma_model(0, &pm);
    dhs_q_from_double(&pm.r, q, qq);
    dhs_fk_ref_q(&pm.r, qq, NULL, &Td);
    dhs_to_frame_q(&Td, &T);
    DHT_EQ_INT(dh_ikc_q(&pm.m, &T, NULL, 0u, sol, &ns), DH_OK);
    memset(keep, 0x5A, sizeof keep);
    for (k = 0; k < 6u; k++) {
        bad = pm.m;
        if (k == 0u) bad.post_inv.r[1][2] = DH_Q30(1.2);
        if (k == 1u) bad.pre_inv.r[0][0] = -DH_Q30(1.2);
        if (k == 2u) bad.off[1] = -180 * 65536;
        if (k == 3u) bad.n = 4u;
        if (k == 4u) bad.kind = DH_IKC_SCARA;
        if (k == 5u) bad.kind = (dh_ikc_kind)77;
        memcpy(sol, keep, sizeof sol);
        ns = 99u;
        DHT_EQ_INT(dh_ikc_q(&bad, &T, NULL, 0u, sol, &ns), DH_ERR_ARG);
        DHT_EQ_INT(ns, 0u);
        DHT_TRUE(memcmp(sol, keep, sizeof sol) == 0);
    }
    DHT_EQ_INT(dh_robot_init(&r0, DH_CONV_STANDARD), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_q(&r0, &bad), DH_ERR_UNAVAILABLE);
    DHT_EQ_INT(bad.kind, DH_IKC_NONE);
}

static void no_closed_form(void)
{
    dhs_robot P, d;
    dh_robot r;
    dh_ikc_model_q m;
    dh_frame_q F;
    unsigned i;
    static const dhs_joint_desc rrrr[4] = {
        {DH_JOINT_REVOLUTE, 100.0, 0.0, 0.0, 0.0, 1.0, -1.0},
        {DH_JOINT_REVOLUTE, 100.0, 0.0, 0.0, 0.0, 1.0, -1.0},
        {DH_JOINT_REVOLUTE, 100.0, 0.0, 0.0, 0.0, 1.0, -1.0},
        {DH_JOINT_REVOLUTE, 100.0, 0.0, 0.0, 0.0, 1.0, -1.0},
    };
    static const dhs_joint_desc rrpr[4] = {
        {DH_JOINT_REVOLUTE, 100.0, 0.0, 90.0, 0.0, 1.0, -1.0},
        {DH_JOINT_REVOLUTE, 100.0, 0.0, 90.0, 0.0, 1.0, -1.0},
        {DH_JOINT_PRISMATIC, 0.0, 0.0, 0.0, 0.0, 1.0, -1.0},
        {DH_JOINT_REVOLUTE, 0.0, 0.0, 0.0, 0.0, 1.0, -1.0},
    };
    puma(&P);
    d = P;
    analyse_why(&dhs_panda_mm, DH_IKC_WHY_JOINTS);       /* 7 joints */
    d.j[4].a = 30.0 * DHK_LS;                               /* wrist axes do not meet */
    analyse_why(&d, DH_IKC_WHY_WRIST);
    for (i = 0; i < 5u; i++) {                          /* twist 1, 4 or 5 one degree off */
        if (i == 1u || i == 2u) continue;               /* (joint 3's twist is free in the family) */
        d = P;
        d.j[i].alpha_deg += 1.0;
        analyse_why(&d, DH_IKC_WHY_AXES);
    }
    d = P;
    d.j[1].alpha_deg = 90.0;                            /* axes 2 and 3 not parallel */
    analyse_why(&d, DH_IKC_WHY_AXES);
    d = P;
    d.j[2].type = DH_JOINT_PRISMATIC;                   /* R-R-P, but alpha2 = 0 */
    analyse_why(&d, DH_IKC_WHY_AXES);
    d = P;
    d.j[0].type = DH_JOINT_PRISMATIC;                   /* P-R-R + wrist */
    analyse_why(&d, DH_IKC_WHY_JOINTS);
    desc_set(&d, "rrrr", DH_CONV_STANDARD, 4, rrrr);
    analyse_why(&d, DH_IKC_WHY_JOINTS);
    desc_set(&d, "rrpr", DH_CONV_STANDARD, 4, rrpr);
    analyse_why(&d, DH_IKC_WHY_AXES);
    /* fixed path not prepared: a length beyond the dh_qpos range */
    d = P;
    d.j[1].a = ldexp(1.0, 32 - DH_QPOS_FRAC);
    analyse_why(&d, DH_IKC_WHY_PATH);
    /* representable, but beyond the solver's 2^29-unit range */
    d = P;
    d.j[1].a = ldexp(1.0, 29 - DH_QPOS_FRAC) + DHK_LS;
    analyse_why(&d, DH_IKC_WHY_PATH);
    d = P;
    d.j[2].d = -ldexp(1.0, 29 - DH_QPOS_FRAC) - DHK_LS;
    analyse_why(&d, DH_IKC_WHY_PATH);
    /* base not rigid (fixed path only), tool a reflection */
    DHT_EQ_INT(dhs_build(&P, &r), DH_OK);
    dh_frame_identity_q(&F);
    F.r[0][0] = DH_Q30(1.01);
    DHT_EQ_INT(dh_robot_set_base_q(&r, &F), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_q(&r, &m), DH_ERR_NOT_RIGID);
    DHT_EQ_INT(m.kind, DH_IKC_NONE);
    DHT_EQ_INT(m.why, DH_IKC_WHY_PATH);
    DHT_EQ_INT(dhs_build(&P, &r), DH_OK);
    dh_frame_identity_q(&F);
    F.r[2][2] = -DH_Q30(1.0);
    DHT_EQ_INT(dh_robot_set_tool_q(&r, &F), DH_OK);
    DHT_EQ_INT(dh_ikc_analyse_q(&r, &m), DH_ERR_NOT_RIGID);
    /* bad descriptions */
    DHT_EQ_INT(dhs_build(&P, &r), DH_OK);
    r.n = DH_MAX_JOINTS + 1u;
    DHT_EQ_INT(dh_ikc_analyse_q(&r, &m), DH_ERR_ARG);
    DHT_EQ_INT(m.kind, DH_IKC_NONE);
    DHT_EQ_INT(m.why, DH_IKC_WHY_JOINTS);
    r.n = 6;
    r.conv = (dh_convention)7;
    DHT_EQ_INT(dh_ikc_analyse_q(&r, &m), DH_ERR_ARG);
    r.conv = DH_CONV_STANDARD;
    r.joint[3].type = (dh_joint_type)5;
    DHT_EQ_INT(dh_ikc_analyse_q(&r, &m), DH_ERR_ARG);
}

/* ---- statuses of dh_ikc_q and dh_ikc_nearest_q ---------------------------- */

static void solve_errors(void)
{
    puma_q pm;
    dh_ikc_model_q bad;
    dh_frame_q T, X;
    dh_ikc_sol_q sol[DH_IKC_MAX_SOL], canary[DH_IKC_MAX_SOL];
    uint32_t ns;
    int32_t qq[6] = {0, 0, 0, 0, 30 << 16, 0}, qref[6];
    dhr_mat4 Td;
    unsigned i;
    puma_model(0, &pm);
    dhs_fk_ref_q(&pm.r, qq, NULL, &Td);
    dhs_to_frame_q(&Td, &T);
    memset(canary, 0xA5, sizeof canary);
#define EXPECT_UNTOUCHED(call, status)                                   \
    do {                                                                 \
        memcpy(sol, canary, sizeof sol);                                 \
        ns = 77;                                                         \
        DHT_EQ_INT(call, status);                                        \
        DHT_EQ_INT(ns, 0);                                               \
        DHT_TRUE(memcmp(sol, canary, sizeof sol) == 0);                  \
    } while (0)
    EXPECT_UNTOUCHED(dh_ikc_q(&pm.m, &T, NULL, 2u, sol, &ns), DH_ERR_ARG);
    bad = pm.m;
    bad.n = 5;
    EXPECT_UNTOUCHED(dh_ikc_q(&bad, &T, NULL, 0u, sol, &ns), DH_ERR_ARG);
    bad = pm.m;
    bad.kind = (dh_ikc_kind)9;
    EXPECT_UNTOUCHED(dh_ikc_q(&bad, &T, NULL, 0u, sol, &ns), DH_ERR_ARG);
    bad = pm.m;
    bad.off[2] = 200 * 65536; /* offsets are stored in (-180, 180] */
    EXPECT_UNTOUCHED(dh_ikc_q(&bad, &T, NULL, 0u, sol, &ns), DH_ERR_ARG);
    bad = pm.m;
    bad.pre_inv.r[0][0] = INT32_MIN;
    EXPECT_UNTOUCHED(dh_ikc_q(&bad, &T, NULL, 0u, sol, &ns), DH_ERR_ARG);
    bad = pm.m;
    bad.kind = DH_IKC_NONE;
    EXPECT_UNTOUCHED(dh_ikc_q(&bad, &T, NULL, 0u, sol, &ns), DH_ERR_UNAVAILABLE);
    /* not rigid: scaled, sheared, reflected, INT32_MIN entries */
    X = T;
    X.r[0][0] += (X.r[0][0] >= 0 ? 1 : -1) * (1 << 21);
    EXPECT_UNTOUCHED(dh_ikc_q(&pm.m, &X, NULL, 0u, sol, &ns), DH_ERR_NOT_RIGID);
    X = T;
    for (i = 0; i < 3; i++) X.r[2][i] = -X.r[2][i];
    EXPECT_UNTOUCHED(dh_ikc_q(&pm.m, &X, NULL, 0u, sol, &ns), DH_ERR_NOT_RIGID);
    X = T;
    X.r[1][1] = INT32_MIN;
    EXPECT_UNTOUCHED(dh_ikc_q(&pm.m, &X, NULL, 0u, sol, &ns), DH_ERR_NOT_RIGID);
    /* regression: every entry 1.09 (each below the 1.1 entry bound), so a
     * column's dot product, 3.56, lies above the int32 range of Q2.30 (it
     * was rounded to int32 and overflowed when 1 was subtracted) */
    for (i = 0; i < 9; i++) X.r[i / 3][i % 3] = (int32_t)(1.09 * 1073741824.0);
    EXPECT_UNTOUCHED(dh_ikc_q(&pm.m, &X, NULL, 0u, sol, &ns), DH_ERR_NOT_RIGID);
    for (i = 0; i < 9; i++) X.r[i / 3][i % 3] = (i % 2) ? -(int32_t)(1.09 * 1073741824.0) : (int32_t)(1.09 * 1073741824.0);
    EXPECT_UNTOUCHED(dh_ikc_q(&pm.m, &X, NULL, 0u, sol, &ns), DH_ERR_NOT_RIGID);
    /* far away: overflow (any coordinate, INT32_MIN and INT32_MAX included) */
    for (i = 0; i < 3; i++) {
        X = T;
        X.p[i] = dhs_to_q(20000.0 * DHK_LS, DH_QPOS_FRAC);
        ns = 77;
        DHT_EQ_INT(dh_ikc_q(&pm.m, &X, NULL, 0u, sol, &ns), DH_ERR_OVERFLOW);
        DHT_EQ_INT(ns, 0);
        X.p[i] = INT32_MIN;
        DHT_EQ_INT(dh_ikc_q(&pm.m, &X, NULL, 0u, sol, &ns), DH_ERR_OVERFLOW);
        X.p[i] = INT32_MAX;
        DHT_EQ_INT(dh_ikc_q(&pm.m, &X, NULL, 0u, sol, &ns), DH_ERR_OVERFLOW);
        DHT_EQ_INT(ns, 0);
    }
    /* unreachable: 3000 mm away, rotation of the target */
    X = T;
    X.p[0] = dhs_to_q(3000.0 * DHK_LS, DH_QPOS_FRAC);
    ns = 77;
    DHT_EQ_INT(dh_ikc_q(&pm.m, &X, NULL, 0u, sol, &ns), DH_ERR_UNREACHABLE);
    DHT_EQ_INT(ns, 0);
    /* extreme references: INT32_MIN / INT32_MAX in every joint */
    for (i = 0; i < 6; i++) qref[i] = (i & 1u) ? INT32_MAX : INT32_MIN;
    DHT_EQ_INT(dh_ikc_q(&pm.m, &T, qref, 0u, sol, &ns), DH_OK);
    (void)dhk_check_sols_q(&pm.r, &Td, sol, ns, NULL, NULL);
    DHT_EQ_INT(dh_ikc_q(&pm.m, &T, qref, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &ns), DH_OK);
    (void)dhk_check_sols_q(&pm.r, &Td, sol, ns, NULL, NULL);
#undef EXPECT_UNTOUCHED
}

static void nearest(void)
{
    dh_ikc_sol_q s[3];
    int32_t ref[6] = {INT32_MIN, INT32_MIN, INT32_MIN, INT32_MIN, INT32_MIN, INT32_MIN};
    uint32_t idx = 42;
    unsigned i;
    memset(s, 0, sizeof s);
    for (i = 0; i < 6; i++) {
        s[0].q[i] = INT32_MAX;
        s[1].q[i] = INT32_MAX - 1;
        s[2].q[i] = INT32_MAX - 1;
    }
    DHT_EQ_INT(dh_ikc_nearest_q(s, 0, ref, 6, &idx), DH_ERR_ARG);
    DHT_EQ_INT(idx, 42);
    DHT_EQ_INT(dh_ikc_nearest_q(s, 3, ref, 7, &idx), DH_ERR_ARG);
    DHT_EQ_INT(idx, 42);
    /* sums of 6 x (2^32 - 1) do not wrap; ties give the first */
    DHT_EQ_INT(dh_ikc_nearest_q(s, 3, ref, 6, &idx), DH_OK);
    DHT_EQ_INT(idx, 1);
    s[0].q[0] = 5;
    DHT_EQ_INT(dh_ikc_nearest_q(s, 3, NULL, 1, &idx), DH_OK);
    DHT_EQ_INT(idx, 0);
    DHT_EQ_INT(dh_ikc_nearest_q(s, 3, ref, 0, &idx), DH_OK);
    DHT_EQ_INT(idx, 0);
}

static const dht_case cases[] = {
    DHT_CASE(puma_random),
    DHT_CASE(kr5_random),
    DHT_CASE(irb140_random),
    DHT_CASE(stanford_random),
    DHT_CASE(test_tables_random),
    DHT_CASE(mdh_random),
    DHT_CASE(base_tool_random),
    DHT_CASE(singular_wrist),
    DHT_CASE(singular_elbow),
    DHT_CASE(singular_shoulder),
    DHT_CASE(boundary_folded),
    DHT_CASE(boundary_beyond),
    DHT_CASE(limits_shift),
    DHT_CASE(limits_shift_beyond_540),
    DHT_CASE(limits_drop_keep),
    DHT_CASE(model_out_of_range),
    DHT_CASE(no_closed_form),
    DHT_CASE(solve_errors),
    DHT_CASE(nearest),
};
DHT_MAIN(cases)
