/* SPDX-License-Identifier: Apache-2.0 */
/*
 * ikc_impl.h - PRIVATE interface of the closed-form IK family (src/ikc/,
 * not installed) between the front ends (dh_ikc.c float, dh_ikc_q.c fixed),
 * the family solvers (dh_ikc_wrist*.c, dh_ikc_par234*.c, dh_ikc_scara*.c)
 * and the helpers they share (dh_ikc_common*.c and the inline helpers
 * below). The common files call no solver and no front end.
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
#include "../internal/dh_floatops.h"
#include "../internal/dh_qmath.h"

/* ---- float: solvers (dh_ikc_wrist.c, dh_ikc_par234.c, dh_ikc_scara.c) and
 * common helpers (dh_ikc_common.c) ---- */
/* out = T06 (v, w): w = 1 a point, 0 a direction; out may alias v. */
void dh_ikc_t06_vec_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *v, float w, float *out);
/* q_ref[i] (0 when q_ref is NULL) plus joint i's theta or d offset. */
static inline float dh_ikc_cref_f32_(const dh_ikc_model_f32 *m, const float *q_ref, uint32_t i)
{
    const float v = (q_ref != NULL) ? q_ref[i] : 0.0f;
    return v + (((m->prismatic >> i) & 1u) ? m->d[i] : m->off[i]);
}
int dh_ikc_detect_wrist_f32_(dh_ikc_model_f32 *m);   /* sets kind WRIST_RRR or WRIST_RRP */
int dh_ikc_detect_par234_f32_(dh_ikc_model_f32 *m);
int dh_ikc_detect_scara_f32_(dh_ikc_model_f32 *m);
uint32_t dh_ikc_wrist_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *q_ref,
                           dh_ikc_sol_f32 *sol);
uint32_t dh_ikc_par234_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *q_ref,
                            dh_ikc_sol_f32 *sol);
uint32_t dh_ikc_scara_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *q_ref,
                           dh_ikc_sol_f32 *sol);
/* dh_ikc_f32 in three calls (dh_ikc.c), for a caller that must not keep
 * dh_ikc_f32's frame under its own (the tracker, src/track/): the
 * argument checks (dh_ikc_f32's statuses before anything is written); the
 * raw solutions of the model's solver into sol (their count, not yet
 * clamped to DH_IKC_MAX_SOL; inline: no frame of its own); and the joint values,
 * limits and count of dh_ikc_f32 from the raw count in *n_sol (*n_sol and
 * status as dh_ikc_f32's). */
dh_status dh_ikc_args_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *q_ref, uint32_t opts);
/* Calibrated robots (dh_ikc_refine.c): dh_ikc_calibrate_f32_ is the
 * analysis of a chain that no family fits exactly (m->a..ca exact on
 * entry): 1 with m->kind, m->k, the idealised chain in a..ca, the exact one
 * in xa..xca and m->calibrated = 1 when it is within the calibration
 * tolerance of DH_IKC_PARALLEL_234; 0 with m as on entry (calibrated 0)
 * when the chain is not six revolute joints; 2 with the chain idealised as
 * the spherical-wrist family takes it: the caller then runs
 * dh_ikc_detect_wrist_f32_(m) and passes its answer as ok to
 * dh_ikc_calibrated_f32_, which completes the calibrated model (ok 1,
 * returns 1) or puts the exact chain back (returns 0, m->kind NONE). The
 * wrist detector runs from the caller because its stack and the analysis's
 * leave no room for a frame between them (256 B on Cortex-M0+).
 * dh_ikc_refine_f32_: the raw solutions sol[0..raw-1] (canonical values
 * of the idealised chain, raw clamped to DH_IKC_MAX_SOL) refined in place
 * on the exact chain for the target T, and (DH_IKC_PARALLEL_234) the
 * branches restarted from a virtual target in their slots or in the free
 * ones (every slot of sol may be written), the converged ones flagged DH_IKC_REFINED; returns the
 * number of slots up to the last one used. dh_ikc_pack_f32_ then keeps
 * the converged ones, distinct, packed to the front in order, and returns
 * their count. Called after the solver has
 * returned (its frames are not below the refinement's), one after the
 * other. dh_ikc_raw_f32_ gives the idealised solutions only: dh_ikc_args_f32_
 * refuses a calibrated model (DH_ERR_UNAVAILABLE), so that a caller of the
 * three calls treats it as a robot without a closed form; dh_ikc_f32
 * refines. */
int dh_ikc_calibrate_f32_(dh_ikc_model_f32 *m);
int dh_ikc_calibrated_f32_(dh_ikc_model_f32 *m, int ok);
/* The refinement by family (inline: no frame of its own):
 * DH_IKC_PARALLEL_234 in dh_ikc_refine.c, the spherical-wrist family in
 * dh_ikc_refine_wrist.c (the raw branches refined in their slots, none
 * restarted). */
uint32_t dh_ikc_refine_par234_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, dh_ikc_sol_f32 *sol,
                                   uint32_t raw);
uint32_t dh_ikc_refine_wrist_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, dh_ikc_sol_f32 *sol,
                                  uint32_t raw);
static inline uint32_t dh_ikc_refine_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, dh_ikc_sol_f32 *sol,
                                          uint32_t raw)
{
    if (m->kind == DH_IKC_PARALLEL_234) return dh_ikc_refine_par234_f32_(m, T, sol, raw);
    return dh_ikc_refine_wrist_f32_(m, T, sol, raw);
}
uint32_t dh_ikc_pack_f32_(dh_ikc_sol_f32 *sol, uint32_t raw);
static inline uint32_t dh_ikc_raw_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *q_ref,
                                       dh_ikc_sol_f32 *sol)
{
    switch (m->kind) {
    case DH_IKC_WRIST_RRR:
    case DH_IKC_WRIST_RRP: return dh_ikc_wrist_f32_(m, T, q_ref, sol);
    case DH_IKC_PARALLEL_234: return dh_ikc_par234_f32_(m, T, q_ref, sol);
    default: return dh_ikc_scara_f32_(m, T, q_ref, sol);
    }
}
dh_status dh_ikc_finish_f32_(const dh_ikc_model_f32 *m, const float *q_ref, uint32_t opts, dh_ikc_sol_f32 *sol,
                             uint32_t *n_sol);
/* The raw solutions of dh_ikc_raw_f32_ that can lie within a window of
 * joint values (the tracker's step, src/track/), for a 6-joint model:
 * wq[0..5] is the reference (q_ref, not NULL), wq[6 + i] joint i's
 * canonical centre in (-180, 180] and wq[12 + i] a distance in degrees
 * (+inf: no bound; a prismatic joint's is not read). A solver may leave a
 * branch as soon as one of its revolute canonical values c is outside the
 * window (dh_ikc_out_f32_(wq + 6, i, c)); every solution it returns is one
 * of dh_ikc_raw_f32_'s with q_ref = wq (the same operations on the same
 * inputs: the same values and flags), in their order, and it returns each
 * of those within the window on every joint. The wrist families with an
 * FPU and PARALLEL_234 leave branches; the others return every solution
 * (soft float: the in-place wrist solver). Four arguments, as the solvers
 * (no argument on the stack). */
uint32_t dh_ikc_wrist_win_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *wq,
                               dh_ikc_sol_f32 *sol);
uint32_t dh_ikc_par234_win_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *wq,
                                dh_ikc_sol_f32 *sol);
/* dh_ikc_wrist_f32_ pruned by the model's limit window m->lim_w
 * (dh_ikc_out_f32_ on joints 1-3; see dh_ikc_wrist_win_f32_ for what it
 * returns): with an FPU; soft float, every solution. */
uint32_t dh_ikc_wrist_lim_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *q_ref,
                               dh_ikc_sol_f32 *sol);
static inline uint32_t dh_ikc_raw_win_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *wq,
                                           dh_ikc_sol_f32 *sol)
{
    switch (m->kind) {
    case DH_IKC_WRIST_RRR:
    case DH_IKC_WRIST_RRP:
        return DH_SOFT_FLOAT ? dh_ikc_wrist_f32_(m, T, wq, sol) : dh_ikc_wrist_win_f32_(m, T, wq, sol);
    case DH_IKC_PARALLEL_234: return dh_ikc_par234_win_f32_(m, T, wq, sol);
    default: return dh_ikc_scara_f32_(m, T, wq, sol);
    }
}
/* 1 when the canonical value c of revolute joint i lies outside the window
 * w (centres w[0..5], distances w[6..11]; wq + 6 of dh_ikc_raw_win_f32_):
 * c and the centre are both in (-180, 180] (or c a reference value a whole
 * number of turns from the centre, which stays), so their distance modulo
 * 360 degrees is d or 360 - d; a NaN stays. */
DH_INLINE int dh_ikc_out_f32_(const float *w, uint32_t i, float c)
{
    const float d = fabsf(c - w[i]), th = w[6u + i];
    return d > th && 360.0f - d > th;
}

/* ---- fixed, integer only (dh_ikc_wrist_q.c, dh_ikc_par234_q.c,
 * dh_ikc_scara_q.c; common helpers dh_ikc_common_q.c) ----
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

/* dh_ikc_q in three calls, for a caller that must not keep dh_ikc_q's
 * frame under its own (the tracker, src/track/): the argument checks and
 * T06 into sol (dh_ikc_q's statuses before a solver runs; dh_ikc_q calls
 * it too); the model's solver (inline: no frame of its own; the raw count
 * in *count); and the joint values, limits and count of dh_ikc_q with
 * DH_IKC_KEEP_OUT_OF_LIMITS from the raw count in *n_sol (*n_sol and
 * status as dh_ikc_q's). */
dh_status dh_ikc_args_q_(const dh_ikc_model_q *m, const dh_frame_q *target, uint32_t opts, dh_ikc_sol_q *sol);
/* dh_ikc_args_q_ (opts 0) for a target whose rigidity the caller has
 * checked at least as tightly (dh_rot_ok_q_ within 2^-10, det > 0). */
dh_status dh_ikc_args_rigid_q_(const dh_ikc_model_q *m, const dh_frame_q *target, dh_ikc_sol_q *sol);
static inline dh_status dh_ikc_raw_q_(const dh_ikc_model_q *m, const int32_t *q_ref, dh_ikc_sol_q *sol,
                                      uint32_t *count)
{
    if (m->kind == DH_IKC_PARALLEL_234) return dh_ikc_par234_q_(m, q_ref, sol, count);
    if (m->kind == DH_IKC_SCARA) return dh_ikc_scara_q_(m, q_ref, sol, count);
    return dh_ikc_wrist_q_(m, q_ref, sol, count);
}
dh_status dh_ikc_finish_q_(const dh_ikc_model_q *m, const int32_t *q_ref, dh_ikc_sol_q *sol, uint32_t *n_sol);

/* Shared fixed helpers (defined in dh_ikc_common_q.c). */
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

/* ---- float helpers shared by the front end and the solvers --------------- */

/* |sin| or |cos| of a twist at most this is taken as 0 (dh_sincos_f32
 * gives exact 0 and +-1 at multiples of 90 degrees, so tables with exact
 * twists pass with any margin). */
#define IKC_TWIST_EPS 1e-6f
/* A length at most this times the chain's length scale L (sum of |a|, |d|)
 * is taken as 0. */
#define IKC_LEN_EPS 1e-6f
/* Position tolerance of the clamps and merges, relative to L: a target
 * this close to the boundary of a branch's workspace is solved on it. */
#define IKC_POS_REL 4e-7f
/* Boundary bound (PARALLEL_234 and SCARA): tol = IKC_POS_REL L (4e-7 L;
 * L the sum of the robot's |a| and |d|, 3.6e-7 m for the UR3 in metres).
 * A joint 5 point (SCARA: frame 3 origin) within tol beyond the elbow's
 * reach (stretched or folded) is merged onto it (DH_IKC_SING_ELBOW); one
 * within tol of the shoulder cylinder, inside or outside, is on it
 * (DH_IKC_SING_SHOULDER, one branch); near the cylinder joint 1 is
 * searched for within the same tol of radial distance (par234_search).
 * A solution's FK is thus within about 2 tol of the target (shoulder and
 * elbow, orthogonal in the tests: 1.5e-6 m for the UR10 in metres). The
 * float rounding of the target, T06 and the planar point takes up to about
 * tol / 2 of the band (UR10 stretched): a joint 5 point within tol / 4
 * (1e-7 L) beyond the workspace boundary is solved, one farther than
 * 3 tol (1.2e-6 L) beyond it is DH_ERR_UNREACHABLE (test/ikc/test_ikc_ur.c,
 * ikc_ur_beyond: tol / 4 solved, 4 tol refused). */

/* x reduced into (-180, 180] (|x| < 540). */
static inline float dh_ikc_wrap_f32_(float x)
{
    if (x > 180.0f) x -= 360.0f;
    else if (x <= -180.0f) x += 360.0f;
    return x;
}

static inline int dh_ikc_is_identity_f32_(const dh_mat4_f32 *T)
{
    uint32_t c, r;
    for (c = 0; c < 4u; c++)
        for (r = 0; r < 4u; r++)
            if (!dh_feq_f32(T->m[c][r], (c == r) ? 1.0f : 0.0f)) return 0;
    return 1;
}

/* The last three axes meet in one point: a4 = a5 = d5 = 0 and axes 4, 5
 * and 5, 6 not parallel (joints 4..6 revolute). */
static inline int dh_ikc_spherical_f32_(const dh_ikc_model_f32 *m)
{
    return m->n == 6u && (m->prismatic & 0x38u) == 0u && dh_feq_f32(m->a[3], 0.0f) && dh_feq_f32(m->a[4], 0.0f) &&
           dh_feq_f32(m->d[4], 0.0f) && !dh_feq_f32(m->sa[3], 0.0f) && !dh_feq_f32(m->sa[4], 0.0f);
}

/* out = A (x, w) for w = 1 (point) or 0 (direction); out may alias x. */
static inline void dh_ikc_xform_f32_(const dh_mat4_f32 *A, const float *x, float w, float *out)
{
    const float x0 = x[0], x1 = x[1], x2 = x[2];
    uint32_t i;
    for (i = 0; i < 3u; i++)
        out[i] = dh_mla_f32_(A->m[3][i], w, dh_mla_f32_(A->m[2][i], x2, dh_mla_f32_(A->m[1][i], x1, A->m[0][i] * x0)));
}

DH_INLINE int dh_ikc_zero_f32_(float x, float eps)
{
    return fabsf(x) <= eps;
}

DH_INLINE float dh_ikc_sign_f32_(float x)
{
    return x < 0.0f ? -1.0f : 1.0f;
}

/* atan2 in degrees, (-180, 180]; (0, 0) gives 0. dh_atan2f_dg_ (3 ulp):
 * the correctly rounded degree version's double-float arithmetic needs 80
 * more bytes of stack on Cortex-M0+, more than the budget leaves. */
DH_INLINE float dh_ikc_atan2_f32_(float y, float x)
{
    if (dh_feq_f32(y, 0.0f) && dh_feq_f32(x, 0.0f)) return 0.0f;
    return dh_atan2f_dg_(y, x);
}

/* A reference angle (any finite degrees) in (-180, 180]. */
static inline float dh_ikc_ref_f32_(float x)
{
    float v = x;
    if (!(fabsf(v) <= 540.0f)) {
        const float t = v * (1.0f / 360.0f);
        if (fabsf(t) < 8388608.0f) {
            const int32_t turns = (int32_t)t;
            v -= 360.0f * (float)turns;
        }
        if (!(fabsf(v) <= 540.0f)) v = 0.0f; /* |x| >= 2^23 turns: no fraction left */
    }
    return dh_wrap180_f32(v);
}

/* Sum of |a_i| and |d_i| of the first n canonical joints (length scale). */
static inline float dh_ikc_len_scale_f32_(const dh_ikc_model_f32 *m, uint32_t n)
{
    float L = 0.0f;
    uint32_t i;
    for (i = 0; i < n; i++) L += fabsf(m->a[i]) + fabsf(m->d[i]);
    return L > 0.0f ? L : 1.0f;
}

/* ---- fixed helpers shared by the front end and the solvers ---------------- */

/* |cos alpha| or |sin alpha| this small counts as zero (6e-8) */
#define DH_IKC_TOL_ALPHA 64

DH_INLINE int32_t dh_ikc_sign_q_(int32_t x)
{
    return x < 0 ? -1 : 1;
}

DH_INLINE int dh_ikc_small_q_(int32_t x)
{
    return x <= DH_IKC_TOL_ALPHA && x >= -DH_IKC_TOL_ALPHA;
}

DH_INLINE uint64_t dh_ikc_abs64_q_(int64_t x)
{
    return x < 0 ? (uint64_t)0 - (uint64_t)x : (uint64_t)x;
}

DH_INLINE int32_t dh_ikc_r30_q_(int64_t x)
{
    return dh_q_rnd30_fit(x);
}

/* The end of a detector that accepts m as kind: the tool offset of joint
 * j in its own frame (a_j, d_j sin alpha_j, d_j cos alpha_j, Q16.16) into
 * w[0..2], m->kind and m->why set; returns 1. */
DH_INLINE int dh_ikc_accept_q_(dh_ikc_model_q *m, dh_ikc_kind kind, uint32_t j, int32_t *w)
{
    w[0] = m->a[j];
    w[1] = dh_ikc_r30_q_(dh_q_mul64(m->d[j], m->sa[j]));
    w[2] = dh_ikc_r30_q_(dh_q_mul64(m->d[j], m->ca[j]));
    m->kind = kind;
    m->why = DH_IKC_WHY_NONE;
    return 1;
}

/* any int32 angle -> (-180, 180] (32-bit remainder, no negation of INT32_MIN) */
static inline int32_t dh_ikc_reduce_q_(int32_t x)
{
    const uint32_t a = dh_q_abs_u32(x) % (uint32_t)DH_IKC_Q16_360;
    int32_t r = (int32_t)a;
    if (x < 0) r = -r;
    return dh_ikc_wrap180_q_(r);
}

/* spherical wrist of the canonical chain: a4 = a5 = d5 = 0, alpha4, alpha5 not 0 or 180 */
static inline int dh_ikc_spherical_q_(const dh_ikc_model_q *m)
{
    return m->a[3] == 0 && m->a[4] == 0 && m->d[4] == 0 && !dh_ikc_small_q_(m->sa[3]) && !dh_ikc_small_q_(m->sa[4]);
}

/* Boundary bound: a point within B = 2^DH_IKC_BOUND_SH LSB of the position
 * format (64 LSB; 9.8e-4 mm at DH_QPOS_FRAC 16 in mm) beyond the boundary
 * of the 2R annulus (stretched or folded elbow) or inside the shoulder
 * cylinder is clamped onto it and solved; the 2R refuses |v| beyond
 * |a2| + |a3| + B or below ||a2| - |a3|| - B (tolerances 2^(sh + 1) (l + 1)
 * on the products (l - |v|)(l + |v|) ~ 2 l dist). B covers the rounding of
 * the target (1/2 LSB per coordinate) and of the wrist terms of the planar
 * point (a few LSB), and stays far below the FK residual of the tests
 * (5e-3 mm = 328 LSB). The shoulder (px^2 + py^2 - h^2 ~ 2 |h| dist) trades
 * up to B of radial distance for the 2R's reach (par234q_band in dh_ikc_par234_q.c), so a solved
 * target is within B (shoulder) and B (2R, orthogonal to it) of its
 * solution's FK, and a target farther than about 2 B from the workspace
 * is refused. SCARA's 2R refuses beyond B alike. Elbow fold 2^5 LSB: the UR planar point carries the error of
 * the wrist terms (a few LSB), which a 2^3 LSB band missed for the UR3
 * folded (|a2| - |a3| = 30 mm). */
#define DH_IKC_BOUND_SH 6
#define DH_IKC_FOLD_SH 5

/* the tolerance of a product (l - dist)(l + dist) ~ 2 l (l - dist): a
 * distance B from a circle of radius l (l >= 0) */
DH_INLINE int64_t dh_ikc_btol_q_(uint32_t l)
{
    return ((int64_t)l + 1) << (DH_IKC_BOUND_SH + 1);
}

/* 2R reach of (vx, vy) with links l1, l2: ds = (|l1| + |l2|)^2 - |v|^2 and
 * df = |v|^2 - (|l1| - |l2|)^2 from exact products (D = 2 |l1 l2|, K =
 * |v|^2 - l1^2 - l2^2: ds = D - K, df = D + K) */
DH_INLINE void dh_ikc_dsdf_q_(int32_t l1, int32_t l2, int32_t vx, int32_t vy, int64_t *ds, int64_t *df)
{
    const int64_t D = 2 * (int64_t)dh_ikc_abs64_q_(dh_q_mul64(l1, l2));
    const int64_t K = dh_q_mla64(dh_q_mla64(dh_q_mul64(vx, vx), vy, vy), l1, -l1) - dh_q_mul64(l2, l2);
    *ds = D - K;
    *df = D + K;
}

/* the outer and inner radii |l1| + |l2|, ||l1| - |l2|| (|l| < 2^31) */
DH_INLINE uint32_t dh_ikc_lsum_q_(int32_t l1, int32_t l2)
{
    return dh_q_abs_u32(l1) + dh_q_abs_u32(l2);
}

DH_INLINE uint32_t dh_ikc_ldif_q_(int32_t l1, int32_t l2)
{
    const uint32_t a = dh_q_abs_u32(l1), b = dh_q_abs_u32(l2);
    return a > b ? a - b : b - a;
}

/* The 2R elbow shared by both families: link lengths l1, l2 (l1 l2 != 0),
 * planar point (vx, vy). Writes the pair (S, K sgn D) scaled below 2^30
 * into out[0..1]; returns 0 unreachable, 1 stretched or folded, 2 two
 * branches. */
unsigned dh_ikc_elbow_q_(int32_t l1, int32_t l2, int32_t vx, int32_t vy, int32_t *out);

/* |det J| of the model's canonical chain at the robot's joint values q (the
 * 6 x 6 geometric Jacobian, per rad, lengths in the robot's unit; the same
 * for the robot: base, tool and the reference point do not change it), as
 * a lower bound mant 2^*ex with mant in [2^30, 2^31) for the spherical
 * wrist and PARALLEL_234 families (method: the family's function);
 * 0 (no bound) for SCARA, a factor within its rounding margin of 0, or a
 * prismatic value beyond 2^30 LSB. Integer only. */
uint32_t dh_ikc_wrist_detj_q_(const dh_ikc_model_q *m, const int32_t *q, int32_t *ex);
/* canonical angle of revolute joint i at the robot's value q[i] (modulo
 * 2^32 LSB: 65536 deg, a whole number of turns) */
DH_INLINE int32_t dh_ikc_theta_q_(const dh_ikc_model_q *m, const int32_t *q, uint32_t i)
{
    const uint32_t t = (uint32_t)q[i] + (uint32_t)m->off[i];
    return (int32_t)t;
}
uint32_t dh_ikc_par234_detj_q_(const dh_ikc_model_q *m, const int32_t *q, int32_t *ex);
static inline uint32_t dh_ikc_detj_q_(const dh_ikc_model_q *m, const int32_t *q, int32_t *ex)
{
    if (m->kind == DH_IKC_PARALLEL_234) return dh_ikc_par234_detj_q_(m, q, ex);
    if (m->kind == DH_IKC_WRIST_RRR || m->kind == DH_IKC_WRIST_RRP) return dh_ikc_wrist_detj_q_(m, q, ex);
    return 0u;
}
/* Helpers of the two (dh_ikc_common_q.c): lower bounds on |x| 2^-30 in
 * dh_qpos (x a sum of products of lengths and sines, sum the magnitudes of
 * its lengths) and on |s| (a sine, Q2.30); p 2^*ex times f 2^-fb as a
 * mantissa in [2^30, 2^31) (returned) and *ex, rounded down (0 when p or
 * f is 0; p below 2^31). */
uint32_t dh_ikc_low_q_(int64_t x, uint64_t sum);
uint32_t dh_ikc_lows_q_(int32_t s);
uint32_t dh_ikc_pmul_q_(uint32_t p, uint32_t f, int fb, int32_t *ex);

#endif /* DHMATH_SRC_IKC_IMPL_H */
