/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_ikc_refine_wrist.c - closed-form IK of calibrated robots, float: the
 * refinement of the spherical-wrist family's raw solutions (a calibrated
 * DH_IKC_WRIST_RRR model, recognised by dh_ikc_calibrate_f32_ in
 * dh_ikc_refine.c) on the exact chain; interface in ikc_impl.h, the
 * evaluation helpers (trigonometry, exact forward kinematics, errors,
 * verdict) in dh_ikc_refine.c (ikc_refine.h). Method and convergence
 * argument: docs/design.md ("Calibrated robots", "Spherical wrist").
 *
 * One branch: simplified Newton steps with the idealised chain's Jacobian
 * at the iterate, block triangular in the basis of the idealised frame 1:
 * the joint 5 point (the idealised chain's wrist centre) moves with joints
 * 1-3 only (joint 1 across the plane of axes 2 and 3, joints 2 and 3 in
 * it), so their step comes from one division and a 2x2; the rotation
 * error less what that step turns, taken into frame 3, gives joints 4-6
 * from the wrist's closed-form 3x3 inverse (determinant s5). Each step
 * one exact forward kinematics.
 *
 * Stack: the entry keeps the work data of ikc_refine.h; the evaluation
 * helpers and the blocks run from it one after the other, each working in
 * place in the work data.
 */
#include "dhmath/ikc.h"
#include "dhmath/trig.h"
#include "ikc_impl.h"
#include "ikc_refine.h"
#include "../internal/dh_floatops.h"

#include <math.h>

/* A block whose determinant is at most this (the 1 x 1 of joint 1 relative
 * to L, the planar 2x2 to |a2| L, the wrist's s5 absolutely) is singular
 * there: the branch is not refined. */
#define RW_SING_TOL 1e-6f

/* Joints 1-3 (after dh_ikc_ref_frame1_f32_: errors e (u[0..2]) and r
 * (u[3..5]) and the joint 5 point p (u[6..8]) in frame 1, p from its
 * origin). Idealised rows in frame 1 (tau = sin alpha1 = +-1, cos alpha1 =
 * 0; axes 2 and 3 along z1, joint 3's sign s2 = cos alpha2; o2 = a2 (c2,
 * s2) the origin of frame 2):
 *   e_z = -tau (a1 + p_x) dt1
 *   e_x = tau p_z dt1 - p_y dt2 - (p_y - o2_y) u3,  u3 = s2 dt3
 *   e_y =               p_x dt2 + (p_x - o2_x) u3
 * and the rotation they turn, tau dt1 about y1 and dt2 + u3 about z1,
 * taken from r. The steps into u[9], u[6], u[7] (dh_ikc_ref_apply_f32_'s
 * places); 0 at the shoulder's or the elbow's singularity. */
static DH_NOINLINE int rw_arm(dh_ikc_ref_work_f32 *w)
{
    const dh_ikc_model_f32 *m = w->m;
    float *u = w->u;
    const float tau = m->sa[0], ox = m->a[1] * w->cs[2], oy = m->a[1] * w->cs[3];
    const float px = m->a[0] + u[6];
    float d1, d2, u3, rx, det;
    det = u[7] * ox - u[6] * oy;
    if (!(fabsf(px) > RW_SING_TOL * m->xlen) || !(fabsf(det) > RW_SING_TOL * fabsf(m->a[1]) * m->xlen)) return 0;
    d1 = -tau * u[2] / px;
    rx = u[0] - tau * u[8] * d1;
    d2 = (rx * (u[6] - ox) + (u[7] - oy) * u[1]) / det;
    u3 = -(u[7] * u[1] + u[6] * rx) / det;
    u[4] -= tau * d1;
    u[5] -= d2 + u3;
    u[9] = d1;
    u[6] = d2;
    u[7] = m->ca[1] * u3;
    return 1;
}

/* Joints 4-6: the rotation error left (u[3..5], frame 1) into frame 3
 * (Rz(phi)^T, phi = theta2 + s2 theta3, then Rx(alpha2 + alpha3)^T), w;
 * with the idealised wrist (sigma4 = sin alpha4, sigma5 = sin alpha5,
 * +-1) axes 4, 5, 6 there are (0, 0, 1), sigma4 (s4, -c4, 0) and sigma5
 * (c4 s5, s4 s5, -sigma4 c5), so
 *   dt5 = sigma4 (s4 w_x - c4 w_y),  dt6 = sigma5 (c4 w_x + s4 w_y) / s5,
 *   dt4 = w_z + sigma4 sigma5 c5 dt6;
 * into u[8], u[10], u[11]; 0 at the wrist singularity. */
static DH_NOINLINE int rw_wrist(dh_ikc_ref_work_f32 *w)
{
    const dh_ikc_model_f32 *m = w->m;
    const float *cs = w->cs;
    float *u = w->u;
    const float s2 = m->ca[1], ct = s2 * m->ca[2], st = s2 * m->sa[2];
    const float cp = cs[2] * cs[4] - s2 * cs[3] * cs[5], sp = cs[3] * cs[4] + s2 * cs[2] * cs[5];
    float x, y, z;
    if (!(fabsf(cs[9]) > RW_SING_TOL)) return 0;
    x = cp * u[3] + sp * u[4];
    y = cp * u[4] - sp * u[3];
    z = ct * u[5] - st * y;
    y = ct * y + st * u[5];
    u[10] = m->sa[3] * (cs[7] * x - cs[6] * y);
    u[11] = m->sa[4] * (cs[6] * x + cs[7] * y) / cs[9];
    u[8] = z + m->sa[3] * m->sa[4] * cs[8] * u[11];
    return 1;
}

/* Each raw branch refined in its slot: evaluations of the exact chain
 * (ikc_refine.h) and steps (frame 1, rw_arm, rw_wrist, the update) until
 * the verdict, at most
 * DH_IKC_CAL_STEPS steps. Returns raw (clamped to DH_IKC_MAX_SOL); the
 * converged branches flagged DH_IKC_REFINED. */
uint32_t dh_ikc_refine_wrist_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, dh_ikc_sol_f32 *sol, uint32_t raw)
{
    dh_ikc_ref_work_f32 w;
    uint32_t s, it;
    w.m = m;
    w.T = T;
    if (raw > DH_IKC_MAX_SOL) raw = DH_IKC_MAX_SOL;
    for (s = 0; s < raw; s++) {
        it = dh_ikc_ref_begin_f32_(&sol[s]);
        if (it < DH_IKC_REF_DONE) dh_ikc_ref_trig_f32_(sol[s].q, &w);
        while (it < DH_IKC_REF_DONE) {
            dh_ikc_ref_fk_f32_(&w, 0);
            dh_ikc_ref_tool_f32_(&w);
            dh_ikc_ref_base_f32_(&w);
            dh_ikc_ref_rot_f32_(&w);
            it = dh_ikc_ref_pos_f32_(&w, &sol[s], it);
            if (it < DH_IKC_REF_DONE) {
                dh_ikc_ref_frame1_f32_(&w);
                if (!rw_arm(&w) || !rw_wrist(&w) || !dh_ikc_ref_apply_f32_(&w, sol[s].q)) it = DH_IKC_REF_DONE;
            }
        }
    }
    return raw;
}
