/* SPDX-License-Identifier: Apache-2.0 */
/*
 * ikc_refine.h - PRIVATE interface of the refinement of calibrated robots
 * (src/ikc/, not installed): the work data and the evaluation helpers of
 * dh_ikc_refine.c (trigonometry, the exact chain's forward kinematics, the
 * tool and base frames, the errors and the verdict), which the refinement
 * of every calibrated family runs (dh_ikc_refine.c: DH_IKC_PARALLEL_234,
 * dh_ikc_refine_wrist.c: the spherical-wrist family). dh_ikc_refine.c
 * calls nothing of dh_ikc_refine_wrist.c.
 *
 * A branch b (canonical values q = b->q, degrees) starts with
 * dh_ikc_ref_trig_f32_(q, w) (w->cs: c1, s1, ..., c6, s6); then one
 * evaluation
 *   dh_ikc_ref_fk_f32_(w, 0); dh_ikc_ref_tool_f32_(w);
 *   dh_ikc_ref_base_f32_(w); dh_ikc_ref_rot_f32_(w);
 *   it = dh_ikc_ref_pos_f32_(w, b, it);
 * leaves in w->u the position error of the exact joint 5 point (frame 5's
 * origin) against the target's (u[0..2], target minus chain, base frame),
 * the rotation error (u[3..5], the rotation vector from the chain's end
 * frame to the target's, base frame) and the point (u[6..8]), w->cs
 * unchanged. dh_ikc_ref_frame1_f32_ and dh_ikc_ref_apply_f32_ then take
 * the errors into the idealised frame 1 and apply a family's step, which
 * turns w->cs with q, so the next evaluation needs no trigonometry.
 * Each helper is DH_NOINLINE and calls only trigonometry
 * (dh_ikc_ref_trig_f32_), so a caller's stack is its own frame plus one
 * helper's.
 */
#ifndef DHMATH_SRC_IKC_REFINE_H
#define DHMATH_SRC_IKC_REFINE_H

#include "dhmath/ikc.h"
#include "../internal/dh_floatops.h"

/* A step count past the last: the branch is done. */
#define DH_IKC_REF_DONE (DH_IKC_CAL_STEPS + 1u)

/* Work data of one refinement call: cs the cosines and sines of the
 * branch's canonical joint values (c1, s1, ..., c6, s6); u the exact
 * chain's end frame (columns x, y, z and the joint 5 point), then the
 * errors and the joint 5 point (see above), then a family's steps; m the
 * model, T the target. */
typedef struct {
    float cs[12];
    float u[12];
    const dh_ikc_model_f32 *m;
    const dh_mat4_f32 *T;
} dh_ikc_ref_work_f32;

/* cs of the canonical values q */
void dh_ikc_ref_trig_f32_(const float *q, dh_ikc_ref_work_f32 *w);
/* the exact (ideal 0) or idealised (1) chain's T06 from cs into u, its
 * point moved to the joint 5 point: dh_ikc_ref_fk_regs_f32_ with an FPU
 * (the frame in registers), dh_ikc_ref_fk_rows_f32_ with soft float
 * (whose frame would not stay in registers and would not fit the stack
 * budget), chosen here without a frame of its own */
void dh_ikc_ref_fk_regs_f32_(dh_ikc_ref_work_f32 *w, int ideal);
void dh_ikc_ref_fk_rows_f32_(dh_ikc_ref_work_f32 *w, int ideal);
DH_INLINE void dh_ikc_ref_fk_f32_(dh_ikc_ref_work_f32 *w, int ideal)
{
    if (DH_SOFT_FLOAT) {
        dh_ikc_ref_fk_rows_f32_(w, ideal);
    } else {
        dh_ikc_ref_fk_regs_f32_(w, ideal);
    }
}
/* u's rotation times the tool frame's; u <- pre u (each skipped when the
 * model has no such frame) */
void dh_ikc_ref_tool_f32_(dh_ikc_ref_work_f32 *w);
void dh_ikc_ref_base_f32_(dh_ikc_ref_work_f32 *w);
/* the rotation error into u[3..5] */
void dh_ikc_ref_rot_f32_(dh_ikc_ref_work_f32 *w);
/* the position error into u[0..2], the point into u[6..8], and the
 * verdict on b after it steps: converged: b flagged DH_IKC_REFINED and
 * DH_IKC_REF_DONE; not finite: DH_IKC_REF_DONE; else it + 1 (DH_IKC_REF_DONE
 * after DH_IKC_CAL_STEPS) */
uint32_t dh_ikc_ref_pos_f32_(dh_ikc_ref_work_f32 *w, dh_ikc_sol_f32 *b, uint32_t it);
/* b's DH_IKC_REFINED cleared; 0, or DH_IKC_REF_DONE when b is not finite */
uint32_t dh_ikc_ref_begin_f32_(dh_ikc_sol_f32 *b);
/* after an evaluation: the errors and the point into the basis of the
 * idealised frame 1 (pre^-1, Rz(theta1)^T, Rx(alpha1)^T of the idealised
 * chain), the point from frame 1's origin (a1 c1, a1 s1, d1), in place */
void dh_ikc_ref_frame1_f32_(dh_ikc_ref_work_f32 *w);
/* the steps (rad) of joints 1, 2, 3, 4, 5, 6 in u[9], u[6], u[7], u[8],
 * u[10], u[11], scaled to at most 0.2 rad, added to q (degrees, wrapped),
 * cs turned with them (series of each step's cosine and sine, unit length
 * restored); 0 when not finite */
int dh_ikc_ref_apply_f32_(dh_ikc_ref_work_f32 *w, float *q);

#endif /* DHMATH_SRC_IKC_REFINE_H */
