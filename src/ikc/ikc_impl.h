/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_ikc_impl.h - PRIVATE interface between the closed-form IK front ends
 * (dh_ikc.c float, dh_ikc_q.c fixed) and the family solvers (not installed).
 *
 * The front end turns the robot into the canonical chain of the model
 * (standard DH, joints 1..n with a, d, alpha, theta offset; an MDH robot's
 * first a/alpha moved into pre, since Tx(a) Rx(alpha) = Rx(alpha) Tx(a)),
 * and a target T into T06 = pre^-1 T post^-1. A family solver then works
 * on canonical joint values c_i: theta_i = q_i + off_i in degrees for a
 * revolute joint, d_i = q_i + d offset for a prismatic one. It writes raw
 * solutions (canonical values, each revolute value in (-180, 180], flags
 * = branch and singularity bits only) to sol[0..count-1]; the front end
 * subtracts the offsets, applies the 360-degree shifts and the limits.
 * Float solvers get q_ref, the caller's reference (may be NULL: zeros),
 * and dh_ikc_cref_f32_ gives joint i's in canonical values, for the
 * singular splits; the fixed solvers get cref: q_ref in canonical values
 * (never NULL).
 *
 * Stack: a float solver gets the TARGET T (not T06) and forms only the vectors
 * of T06 it needs with dh_ikc_t06_vec_f32_ (T06 (v, w) = pre^-1 T post^-1
 * (v, w), identities skipped), so that no 4x4 sits on the stack below
 * the atan2 / sincos calls (256 B per public function with callees).
 *
 * Detectors read the canonical chain of m (a, d, sa, ca, off, prismatic,
 * n) and, when the family applies, fill m->k and return 1 (else 0, m->k
 * unspecified). The layout of m->k belongs to each family and is written
 * down next to its detector.
 */
#ifndef DHMATH_SRC_IKC_IMPL_H
#define DHMATH_SRC_IKC_IMPL_H

#include "dhmath/ikc.h"
#include "../internal/dh_build.h"

/* ---- float (dh_ikc.c: wrist families; dh_ikc_ur.c: UR and SCARA) ---- */
/* out = T06 (v, w): w = 1 a point, 0 a direction; out may alias v. */
void dh_ikc_t06_vec_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *v, float w, float *out);
/* q_ref[i] (0 when q_ref is NULL) plus joint i's theta or d offset. */
float dh_ikc_cref_f32_(const dh_ikc_model_f32 *m, const float *q_ref, uint32_t i);
int dh_ikc_detect_wrist_f32_(dh_ikc_model_f32 *m);   /* sets kind WRIST_RRR or WRIST_RRP */
int dh_ikc_detect_par234_f32_(dh_ikc_model_f32 *m);
int dh_ikc_detect_scara_f32_(dh_ikc_model_f32 *m);
uint32_t dh_ikc_wrist_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *q_ref,
                           dh_ikc_sol_f32 *sol);
uint32_t dh_ikc_par234_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *q_ref,
                            dh_ikc_sol_f32 *sol);
uint32_t dh_ikc_scara_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *q_ref,
                           dh_ikc_sol_f32 *sol);

/* ---- fixed, integer only (dh_ikc_q.c: wrist families; dh_ikc_ur_q.c: UR and SCARA) ----
 * Same contract, except for two inputs, because the whole call chain of
 * dh_ikc_q must stay within 256 bytes of stack on Cortex-M0 (the front end
 * keeps no frame or array on its stack while a solver runs):
 * - T06 arrives in the solution array: columns n and o of R06 in
 *   sol[0].q[0..2] and sol[0].q[3..5], column a in sol[1].q[0..2], the
 *   position in sol[1].q[3..5] (Q2.30, dh_qpos); DH_IKC_T06_COL_(sol, c)
 *   is column c = 0..3. A solver may use all of sol[0..DH_IKC_MAX_SOL-1]
 *   as scratch.
 * - the reference is the caller's q_ref (NULL: zeros); the canonical
 *   reference value of joint i is dh_ikc_cref_q_(m, q_ref, i).
 * A solver returns DH_ERR_OVERFLOW when an intermediate would saturate
 * (count 0), else DH_OK with *count (0 = unreachable). */
#define DH_IKC_T06_COL_(sol, c) (&(sol)[(c) >> 1].q[3u * ((c) & 1u)])
int32_t dh_ikc_cref_q_(const dh_ikc_model_q *m, const int32_t *q_ref, uint32_t i);
int dh_ikc_detect_wrist_q_(dh_ikc_model_q *m);
int dh_ikc_detect_par234_q_(dh_ikc_model_q *m);
int dh_ikc_detect_scara_q_(dh_ikc_model_q *m);
dh_status dh_ikc_wrist_q_(const dh_ikc_model_q *m, const int32_t *q_ref, dh_ikc_sol_q *sol, uint32_t *count);
dh_status dh_ikc_par234_q_(const dh_ikc_model_q *m, const int32_t *q_ref, dh_ikc_sol_q *sol, uint32_t *count);
dh_status dh_ikc_scara_q_(const dh_ikc_model_q *m, const int32_t *q_ref, dh_ikc_sol_q *sol, uint32_t *count);

/* Shared fixed helpers (defined in dh_ikc_q.c). */
#define DH_IKC_Q16_180 ((int32_t)11796480)
#define DH_IKC_Q16_360 ((int32_t)23592960)
/* atan2 in Q16.16 degrees of two int64 of a common scale (|.| < 2^63): both
 * rounded by one shift below 2^30 + 1, then dh_atan2_q; (0, 0) gives 0. */
int32_t dh_ikc_atan2_q_(int64_t y, int64_t x);
/* acc + c v, |c| <= 2^30; factors 0 and +-2^30 cost no multiplication. */
int64_t dh_ikc_mla_q_(int64_t acc, int32_t c, int32_t v);
/* The right shift that brings a non-negative int64 below 2^31. */
unsigned dh_ikc_fit31_q_(int64_t v);
/* x in (-540, 540] deg (Q16.16) -> (-180, 180]. */
DH_INLINE int32_t dh_ikc_wrap180_q_(int32_t x)
{
    if (x > DH_IKC_Q16_180) return x - DH_IKC_Q16_360;
    if (x <= -DH_IKC_Q16_180) return x + DH_IKC_Q16_360;
    return x;
}

/* ---- closed-form IK helpers ----------------------------------------------- */

/** x (degrees, |x| < 900) shifted by a multiple of 360 into (-180, 180];
 *  exact: each step's result is smaller than x in magnitude and on the grid
 *  of x's ulp (360 is a multiple of it), so it is representable. */
DH_INLINE float dh_wrap180_f32(float x)
{
    float v = x;
    if (v > 180.0f) v -= 360.0f;
    if (v > 180.0f) v -= 360.0f;
    if (v <= -180.0f) v += 360.0f;
    if (v <= -180.0f) v += 360.0f;
    return v;
}


#endif /* DHMATH_SRC_IKC_IMPL_H */
