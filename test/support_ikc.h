/* SPDX-License-Identifier: Apache-2.0 */
/*
 * support_ikc.h - what the closed-form IK suites share beyond
 * support_robots.h: the singular distances of the families
 * DH_IKC_PARALLEL_234 and DH_IKC_SCARA (test_ikc_ur.c, test_ikc_ur_q.c)
 * and, for the fixed-point suites (test_ikc_q.c, test_ikc_ur_q.c), the
 * length scaling, the solution check against the reference FK and the
 * conditioning bound of the completeness check.
 *
 * Like the library, a helper takes what it acts on first, then its inputs,
 * and its outputs last.
 */
#ifndef SUPPORT_IKC_H
#define SUPPORT_IKC_H

#include "support_robots.h"
#include "dhmath/ikc.h"

#include <math.h>

/* ---- float and fixed ----------------------------------------------------- */

/** Normalised distances of q (deg / length) of the description d from the
 *  singularities of DH_IKC_PARALLEL_234 and DH_IKC_SCARA: part[0] shoulder
 *  |u| / L (u: the joint 5 point's coordinate along x1 from the base, L the
 *  sum of all |a| and |d|), part[1] elbow |a2 a3 s3| / (|a2| + |a3|)^2,
 *  part[2] wrist |s5|; for a SCARA (4 joints) part[1] = |a1 a2 s2| / (|a1| +
 *  |a2|)^2 and the others 1. Returns the smallest part. */
double dhk_sing_parts(const dhs_robot *d, const double *q, double part[3]);

/** Reach probes (test/dht.h) of the singular distances part (as
 *  dhk_sing_parts) of one input: the smallest part[0], part[1], part[2]
 *  under "<prefix>.s", ".e", ".w" (shoulder, elbow, wrist), and the
 *  smallest larger one of each pair, the inputs near two singularities at
 *  once, under ".se", ".ew", ".sw". */
void dhk_reach_sing(const char *prefix, const double part[3]);

/* ---- fixed point (robots in mm) ---------------------------------------- */

/* The accuracy targets are for robots in mm at DH_QPOS_FRAC 16. At other
 * fraction bits (tools/check.sh variants) every length of the test robots
 * and targets is scaled by DHK_LS = 2^(16 - DH_QPOS_FRAC), so that the
 * solver sees the same raw values, and the length tolerances scale with it. */
#define DHK_LS ldexp(1.0, 16 - DH_QPOS_FRAC)
#define DHK_POS_TOL (5e-3 * DHK_LS) /* mm at DH_QPOS_FRAC 16 */
#define DHK_ROT_TOL 5e-6            /* rotation entries (rad for small errors) */
#define DHK_COMP_DEG 2e-3           /* completeness, deg (mm for a prismatic joint) */

/** Lengths of d (a, d, prismatic limits, base and tool translations) times
 *  DHK_LS, in place. */
void dhk_scale_desc(dhs_robot *d);
/** dhs_build + dh_ikc_analyse_q; checks the model's kind and DH_IKC_WHY_NONE. */
void dhk_build_q(const dhs_robot *d, dh_ikc_kind kind, dh_robot *r, dh_ikc_model_q *m);
/** |a - b| of joint i of Q joint values: deg modulo 360 (revolute), length
 *  divided by DHK_LS (prismatic). */
double dhk_jdiff_q(const dh_robot *r, uint32_t i, int32_t a, int32_t b);

/** What dhk_check_sols_q accumulates over a run. */
typedef struct {
    long targets, comp, sols, near_limit;
    double pos, rot;
} dhk_stats;

/** Every solution's reference FK (dhs_fk_ref_q) within DHK_POS_TOL and
 *  DHK_ROT_TOL of Td (checked). Returns the index of the first solution
 *  within DHK_COMP_DEG of qgen on every joint, or -1 (and -1 when qgen is
 *  NULL). st (may be NULL) accumulates the largest errors and the count. */
int dhk_check_sols_q(const dh_robot *r, const dhr_mat4 *Td, const dh_ikc_sol_q *sol, uint32_t ns,
                     const int32_t *qgen, dhk_stats *st);

/** 1 when the first-order bound of the distance between q and the exact
 *  inverse of its Q-rounded target is within tol on the first nj joints.
 *  The target is rounded (2^-DH_QPOS_FRAC, 2^-30) and the arm angles are
 *  Q16.16 values that the wrist angles absorb, so that inverse differs
 *  from q by about J^-1 (target rounding + J_arm x 2 LSB); J by central
 *  differences of the double FK of the description d (6 joints). Near a
 *  singularity (elbow almost stretched, wrist centre near axis 2, joint 5
 *  near 0), and more so where two of them meet, this exceeds 2e-3 deg even
 *  at 1e-2 from each. */
int dhk_well_conditioned_q(const dhs_robot *d, const double *q, double tol, int nj);

/** Index of the first of sol[0..ns) that is the configuration q (qgen in
 *  Q16.16) to first order: on every joint within 2 x sum_j |J^-1_ij| x
 *  (|e_j| + rounding of the target), at least DHK_COMP_DEG, where e is the
 *  measured pose error of that solution against Td (double FK) and J the
 *  Jacobian of the description d at q; the factor 2 covers the
 *  second-order rest. A solution whose residual is within tolerance but
 *  whose joints sit on an ill-conditioned direction (an elbow near
 *  stretched and a wrist near singular at once) is then the same branch,
 *  not a missing one. -1 when none is. */
int dhk_first_order_match_q(const dhs_robot *d, const double *q, const dh_robot *r, const dhr_mat4 *Td,
                            const dh_ikc_sol_q *sol, uint32_t ns, const int32_t *qgen);

#endif /* SUPPORT_IKC_H */
