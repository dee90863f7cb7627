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
 * One branch: Newton steps on the exact chain with its Jacobian split as
 * the idealised chain's is block triangular: the joint 5 point (the wrist
 * centre of the idealised chain) moves with joints 1-3 only, so their
 * step solves the 3x3 position block; the rotation error less what that
 * step turns then gives joints 4-6 from the 3x3 block of axes 4, 5, 6.
 * The blocks are the exact chain's at the iterate (axes and origins of
 * its frames); what the split leaves out is the motion of the joint 5
 * point with joints 4 and 5, the wrist offsets (a4, a5, d5) times their
 * steps.
 *
 * Stack: the entry keeps the work data of ikc_refine.h; the evaluation
 * helpers and the step run from it one after the other.
 */
#include "dhmath/ikc.h"
#include "dhmath/trig.h"
#include "ikc_impl.h"
#include "ikc_refine.h"
#include "../internal/dh_floatops.h"

#include <math.h>

/* Largest joint step (rad): a larger Newton step is scaled down to it. */
#define RW_MAX_STEP 0.2f
/* A block whose determinant is below this (the position block relative
 * to the cube of the exact chain's length scale, the wrist block of unit
 * axes absolutely) is singular there: the branch is not refined. */
#define RW_SING_TOL 1e-6f

/* x <- the 3x3 A (columns A[0..2], A[3..5], A[6..8]) solved for x (Cramer,
 * cross products); 0 when |det| <= tol. */
static int rw_solve(const float *A, float *x, float tol)
{
    float bc[3], det, e0, e1, e2;
    bc[0] = A[4] * A[8] - A[5] * A[7];
    bc[1] = A[5] * A[6] - A[3] * A[8];
    bc[2] = A[3] * A[7] - A[4] * A[6];
    det = A[0] * bc[0] + A[1] * bc[1] + A[2] * bc[2];
    if (!(fabsf(det) > tol)) return 0;
    det = 1.0f / det;
    e0 = x[0];
    e1 = x[1];
    e2 = x[2];
    /* x1 = e . (b x c), x2 = e . (c x a), x3 = e . (a x b), over det */
    x[0] = det * (e0 * bc[0] + e1 * bc[1] + e2 * bc[2]);
    x[1] = det * (e0 * (A[7] * A[2] - A[8] * A[1]) + e1 * (A[8] * A[0] - A[6] * A[2]) +
                  e2 * (A[6] * A[1] - A[7] * A[0]));
    x[2] = det * (e0 * (A[1] * A[5] - A[2] * A[4]) + e1 * (A[2] * A[3] - A[0] * A[5]) +
                  e2 * (A[0] * A[4] - A[1] * A[3]));
    return 1;
}

/* The errors (u[0..2], u[3..5]) and the joint 5 point (u[6..8]) of the
 * evaluation into the canonical base frame (pre_inv), when there is a base
 * frame. */
static void rw_canonical(const dh_ikc_model_f32 *m, float *u)
{
    const dh_mat4_f32 *P = &m->pre_inv;
    uint32_t k, r;
    if ((m->xframes & 1u) == 0u) return;
    for (k = 0; k < 9u; k += 3u) {
        float *v = &u[k];
        const float x = v[0], y = v[1], z = v[2];
        for (r = 0; r < 3u; r++) v[r] = P->m[0][r] * x + P->m[1][r] * y + P->m[2][r] * z + ((k == 6u) ? P->m[3][r] : 0.0f);
    }
}

/* One step of the branch at q (degrees; w after an evaluation that did not
 * converge): the exact frames 0..5 walked from cs (rotation R: columns x,
 * y, z; origin o up to frame 2), the position block's columns
 * z_i x (p - o_i) of joints 1-3 into J, joints 1-3's step into u[0..2],
 * the rotation error less z_0 dt1 + z_1 dt2 + z_2 dt3 (z_1 kept in
 * u[9..11]), the wrist block's columns z_3, z_4, z_5 into J and joints
 * 4-6's step into u[3..5]; the step scaled to at most RW_MAX_STEP and
 * added to q (wrapped). 0 at a singular block or a step not finite. */
static DH_NOINLINE int rw_step(dh_ikc_ref_work_f32 *w, float *q)
{
    const dh_ikc_model_f32 *m = w->m;
    float *u = w->u;
    float R[9] = { 1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f };
    float o[3] = { 0.0f, 0.0f, 0.0f }, J[9], big = 0.0f, f = 1.0f;
    uint32_t i, r;
    rw_canonical(m, u);
    for (i = 0; i < 6u; i++) {
        const float c = w->cs[2u * i], s = w->cs[2u * i + 1u];
        float *col = &J[3u * (i % 3u)];
        if (i < 3u) {
            const float px = u[6] - o[0], py = u[7] - o[1], pz = u[8] - o[2];
            col[0] = R[7] * pz - R[8] * py;
            col[1] = R[8] * px - R[6] * pz;
            col[2] = R[6] * py - R[7] * px;
        } else {
            for (r = 0; r < 3u; r++) col[r] = R[6u + r];
        }
        if (i == 1u)
            for (r = 0; r < 3u; r++) u[9u + r] = R[6u + r];
        if (i == 2u) {
            const float L = m->xlen;
            if (!rw_solve(J, u, RW_SING_TOL * L * L * L)) return 0;
            for (r = 0; r < 3u; r++) u[3u + r] -= u[9u + r] * u[1] + R[6u + r] * u[2];
            u[5] -= u[0];
        }
        if (i == 5u) break;
        /* frame i+1 = frame i Rz(theta) Tz(d) Tx(a) Rx(alpha), exact chain */
        for (r = 0; r < 3u; r++) {
            const float x = R[r];
            if (i < 2u) o[r] += m->xd[i] * R[6u + r];
            R[r] = c * x + s * R[3u + r];
            R[3u + r] = c * R[3u + r] - s * x;
            if (i < 2u) o[r] += m->xa[i] * R[r];
        }
        for (r = 0; r < 3u; r++) {
            const float y = R[3u + r];
            R[3u + r] = m->xca[i] * y + m->xsa[i] * R[6u + r];
            R[6u + r] = m->xca[i] * R[6u + r] - m->xsa[i] * y;
        }
    }
    if (!rw_solve(J, &u[3], RW_SING_TOL)) return 0;
    for (i = 0; i < 6u; i++)
        if (fabsf(u[i]) > big) big = fabsf(u[i]);
    if (!(big <= 1e30f)) return 0;
    if (big > RW_MAX_STEP) f = RW_MAX_STEP / big;
    for (i = 0; i < 6u; i++) q[i] = dh_wrap180_f32(q[i] + DH_RAD2DEG_F * f * u[i]);
    return 1;
}

/* Each raw branch refined in its slot: evaluations of the exact chain
 * (ikc_refine.h) and steps (rw_step) until the verdict, at most
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
        while (it < DH_IKC_REF_DONE) {
            dh_ikc_ref_trig_f32_(sol[s].q, &w);
            dh_ikc_ref_fk_f32_(&w, 0);
            dh_ikc_ref_tool_f32_(&w);
            dh_ikc_ref_base_f32_(&w);
            dh_ikc_ref_rot_f32_(&w);
            it = dh_ikc_ref_pos_f32_(&w, &sol[s], it);
            if (it < DH_IKC_REF_DONE && !rw_step(&w, sol[s].q)) it = DH_IKC_REF_DONE;
        }
    }
    return raw;
}
