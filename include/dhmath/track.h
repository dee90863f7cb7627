/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Index: the functions of track.h by source file (src/track/).
 *   dh_track.c    dh_track_init_f32, dh_track_step_f32, dh_track_sync_f32
 *   dh_track_q.c  dh_track_init_q, dh_track_step_q
 */
/**
 * @file track.h
 * @brief Tracking IK: one joint command per control period that never
 *        jumps, with the target pose reached whenever the joint rate
 *        limits allow it.
 *
 * The caller owns a dh_track_f32 (robot, closed-form model when the robot
 * has one, current configuration, control period) and calls
 * dh_track_step_f32 once per period with the next target frame.
 *
 * Guarantees of every step, whatever its status (float arithmetic on the
 * values stored, as the tests check them in double):
 * - |q_out[i] - q_prev[i]| <= t->dq_max[i] <= vmax[i] * dt (dh_robot_set_rates_f32);
 * - q_out within the joint limits (joints with limits);
 * - q_out finite;
 * - with a finite amax[i]: |(q_out - q_prev) - (q_prev - q_prev2)| <=
 *   amax[i] dt^2 (1 + 1e-6) + 4 ulp(|q|) (the float resolution of q),
 *   and the joint can always stop before its limit: its velocity v after
 *   the step satisfies v^2 <= 2 amax * (distance left to the limit ahead).
 * DH_TRACK_OK is returned only when FK(q_out) is within t->pos_tol and
 * t->rot_tol of the target.
 *
 * Report (rep->measured): 1 (every path but the one below) when pos_err,
 * rot_err are the errors of FK(q_out) and manip, sigma_min
 * dh_manipulability_f32's of the Jacobian at q_out. 0 when q_out is the
 * nearest closed-form solution as dh_ikc_f32 returned it, t->pos_tol >=
 * t->cfp and t->rot_tol >= 2e-6 (the closed form's residual bounds of
 * ikc.h, scaled to the robot: cfp = 1e-6 (reach + |p_base|); the
 * defaults qualify while |p_base| < L) and, for the spherical-wrist and
 * axes-2-3-4 families, the bound on sigma_min from |det J| proves it at
 * or above t->sing_threshold: then state OK, pos_err = t->cfp, rot_err =
 * 2e-6, manip = |det J| by the family's closed form, sigma_min = Hong and
 * Pan's bound |det J| (5 / F)^(5/2) (F >= ||J||_F^2 for the robot),
 * near_singular 0, and no FK or Jacobian is computed. Rejected targets
 * and an FK overflow at q_out: measured 0 with the errors 0 (state
 * UNREACHABLE).
 *
 * Method (docs/design.md, "Tracking"): for a closed-form robot, the
 * solution of dh_ikc_f32 nearest the current configuration in time (the
 * largest |q*_i - q_i| / vmax_i, then the sum of |q*_i - q_i|) is taken
 * when every joint can reach it this period (status OK). Otherwise, when
 * the current configuration already reaches the target, the joints keep
 * their place (the zero step fitted into the step box). Otherwise the
 * damped least-squares step (dh_dls_step_f32, damping raised near
 * singularities from the bound on the smallest singular value) is fitted
 * into the period's step box; where it stalls (it removes less than 19 %
 * of the linearised error, against a limit or with the elbow stretched)
 * or moves away from the nearest closed-form solution, the step heads at
 * the bound straight for that solution (continuous: never a jump to
 * another branch). Robots without a closed form
 * (m NULL) use the damped step alone. No restarts, no randomness: same
 * inputs, same outputs.
 *
 * Stack: within the 256 B guard (tools/check_guards.sh, Cortex-M0+ and
 * M4F).
 */
#ifndef DHMATH_TRACK_H
#define DHMATH_TRACK_H

#include "dhmath/kin.h"
#include "dhmath/ikc.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Outcome of one tracking step. */
typedef enum {
    DH_TRACK_OK = 0,          /**< target reached within pos_tol / rot_tol */
    DH_TRACK_LAGGING = 1,     /**< reachable, but not this period (rate or acceleration bound, branch far away, singular neighbourhood) */
    DH_TRACK_UNREACHABLE = 2  /**< no closed-form solution within the limits, or beyond the reach bound (no closed form) */
} dh_track_state;

/** What one step did (float). */
typedef struct {
    dh_track_state state;  /**< see dh_track_state */
    float pos_err;         /**< |p_target - p(q_out)|, length unit (measured 1), or its bound t->cfp (measured 0, OK) */
    float rot_err;         /**< rotation angle between target and FK(q_out), rad (measured 1), or its bound 2e-6 (measured 0, OK) */
    float manip;           /**< manipulability sqrt(det J J^T) at q_out: dh_manipulability_f32 (measured 1), |det J| by the family's closed form (measured 0) */
    float sigma_min;       /**< lower bound on the smallest singular value of J at q_out (see measured) */
    int near_singular;     /**< sigma_min < t->sing_threshold */
    int measured;          /**< 1: pos_err, rot_err from FK(q_out), manip, sigma_min from J at q_out; 0: closed-form bounds (state OK), or 0 errors (target rejected, FK overflow) */
} dh_track_report_f32;

/** Tracker state (float); fill with dh_track_init_f32, then adjust lambda,
 *  sing_threshold, pos_tol, rot_tol if wanted. */
typedef struct {
    const dh_robot *r;                 /**< robot (float path), not copied */
    const dh_ikc_model_f32 *m;         /**< closed-form model, NULL: damped steps only */
    float dt;                          /**< control period, s */
    float q[DH_MAX_JOINTS];            /**< current configuration (the last output) */
    float v[DH_MAX_JOINTS];            /**< last velocity (q - q_prev) / dt, joint unit / s */
    float dq_max[DH_MAX_JOINTS];       /**< step bound: vmax * dt rounded down by 2^-20 relative (+inf: unlimited) */
    float lambda;                      /**< largest damping of the DLS step (length unit; default 0.02 L) */
    float sing_threshold;              /**< near-singular threshold on sigma_min (default 0.005 L) and where the damping starts */
    float pos_tol;                     /**< "reached": position tolerance, length unit (default 2e-6 L) */
    float rot_tol;                     /**< "reached": rotation tolerance, rad (default 2e-5) */
    /* private workspace (keeps the step's stack small); read-only for the caller */
    float reach;                       /**< reach bound used for UNREACHABLE without a closed form */
    float J[6 * DH_MAX_JOINTS];        /**< Jacobian at q (when jq) */
    float dq[DH_MAX_JOINTS];           /**< step being built */
    float lo[DH_MAX_JOINTS];           /**< step box of this period, lower */
    float hi[DH_MAX_JOINTS];           /**< step box of this period, upper */
    float qs[DH_MAX_JOINTS];           /**< nearest closed-form solution */
    float keep[DH_MAX_JOINTS];         /**< step so far (damped steps only) */
    float e[6];                        /**< pose error at q */
    float ws[27];                      /**< damped step's matrices; the window of the pruned closed-form solve */
    float sg;                          /**< sigma_min bound at q */
    float lam;                         /**< damping of this period's step */
    uint32_t ns;                       /**< closed-form solutions found (raw, then kept) */
    dh_status ist;                     /**< closed form's argument status */
    int unreach;                       /**< the target is unreachable this period */
    dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL]; /**< closed-form solutions */
    dh_mat4_f32 T;                     /**< FK at q (when jq) */
    float cfp;                         /**< closed form's position residual bound, 1e-6 (reach + |p_base|) */
    float hpg;                         /**< Hong-Pan factor (5 / F)^(5/2), F >= ||J||_F^2; 0: no closed-form det J */
    int jq;                            /**< J and T hold the Jacobian and FK at q */
    int cf;                            /**< this step's q_out is the nearest closed-form solution as it is */
    int have;                          /**< a closed-form solution within the limits this step */
    uint32_t br;                       /**< flags of the last closed-form solution taken (its branch is tried first) */
} dh_track_f32;

/**
 * @brief Start tracking at q0: fills every field of t (defaults above with
 * L = sum over joints of |a| + |d| + the prismatic travel + |p_tool|) and the
 * Jacobian at q0.
 * @param t  tracker (not NULL), written.
 * @param r  robot (float path), 1..DH_MAX_JOINTS joints; rate limits from
 *           dh_robot_set_rates_f32 (unlimited joints have no step bound).
 * @param m  closed-form model from dh_ikc_analyse_f32 for r (kind not NONE),
 *           or NULL for damped steps only.
 * @param q0 n finite joint values within the limits.
 * @param dt control period in seconds, finite, > 0.
 * @return DH_OK; DH_ERR_ARG (dt, n, a model of another joint count or of
 *         kind NONE); DH_ERR_NAN (q0 not finite); DH_ERR_LIMIT (q0 outside
 *         the limits); DH_ERR_UNAVAILABLE (no float path); DH_ERR_OVERFLOW
 *         (FK of q0). t is not usable after an error.
 */
dh_status dh_track_init_f32(dh_track_f32 *t, const dh_robot *r, const dh_ikc_model_f32 *m, const float *q0,
                            float dt);

/**
 * @brief One control period: the next configuration towards target.
 *
 * Every status keeps the guarantees of the file comment; t->q and t->v
 * become q_out and its velocity.
 * @param t      tracker from dh_track_init_f32.
 * @param target next target frame (bottom row 0 0 0 1, rotation within
 *               DH_ROT_ERROR_TOL of orthonormal, det > 0).
 * @param q_out  n joint values (may alias t->q).
 * @param rep    report (not NULL).
 * @return DH_OK (rep->state says whether the target was reached);
 *   DH_ERR_NAN target not finite, DH_ERR_NOT_RIGID target not rigid: the
 *   joints then brake (each velocity towards 0 within amax, stopping at
 *   once when amax is unlimited), rep->state is DH_TRACK_UNREACHABLE with
 *   pos_err and rot_err 0.
 */
dh_status dh_track_step_f32(dh_track_f32 *t, const dh_mat4_f32 *target, float *q_out, dh_track_report_f32 *rep);

/**
 * @brief Sets the tracker's configuration to q, commanded by something
 *        else this period (a joint move): t->v = (q - t->q) / t->dt (its
 *        velocity from the last configuration), t->q = q, and the Jacobian
 *        and FK at q, so that the next dh_track_step_f32 continues from q
 *        with its guarantees (rate, acceleration, braking) measured from
 *        this velocity.
 * It checks no rate or acceleration: the command's own limits are the
 * caller's (dh_move_joint_step_f32, dh_queue_target_f32 keep them).
 * @param t tracker from dh_track_init_f32.
 * @param q n joint values within the joint limits (may alias t->q).
 * @return DH_OK; DH_ERR_NAN (q not finite); DH_ERR_LIMIT (q outside the
 *         limits); DH_ERR_OVERFLOW (FK of q overflows). On error t->q and
 *         t->v are untouched and the Jacobian and FK stay at t->q.
 */
dh_status dh_track_sync_f32(dh_track_f32 *t, const float *q);

/* ---- fixed point (integer only) ----------------------------------------- */

/** What one fixed-point step did. */
typedef struct {
    dh_track_state state;  /**< see dh_track_state */
    int32_t pos_err;       /**< |p_target - p(q_out)|, dh_qpos (saturated at INT32_MAX); measured 0: the closed form's bound t->cf_pos */
    int32_t rot_err;       /**< rotation angle between target and FK(q_out), Q3.29 rad (dh_rot_error_q's format); measured 0: DH_TRACK_CF_ROT_Q */
    int32_t manip;         /**< log2 of the manipulability at q_out, Q16.16 (dh_manipulability_q; INT32_MIN: singular); see dh_track_step_q for which */
    int32_t sigma_min;     /**< lower bound on the smallest singular value of J at q_out, dh_qpos; see dh_track_step_q for which */
    int near_singular;     /**< sigma_min < t->sing_threshold */
    int measured;          /**< 1: pos_err, rot_err from FK at q_out (dh_fk_q); 0: the closed form's contract bounds (state OK, q_out a closed-form solution of this target) */
} dh_track_report_q;

/** The fixed closed form's bound on the rotation error of its solutions
 *  (ikc.h: 5e-6 rad), Q3.29 rad: rot_err of a report with measured 0. */
#define DH_TRACK_CF_ROT_Q 2685

/** Tracker state (fixed point); fill with dh_track_init_q, then adjust
 *  lambda, sing_threshold, pos_tol, rot_tol if wanted. */
typedef struct {
    const dh_robot *r;                  /**< robot (fixed path), not copied */
    const dh_ikc_model_q *m;            /**< closed-form model, NULL: damped steps only */
    uint32_t dt_us;                     /**< control period, microseconds (1..1000000) */
    int32_t q[DH_MAX_JOINTS];           /**< current configuration (the last output): dh_q16 deg / dh_qpos */
    int32_t v[DH_MAX_JOINTS];           /**< last STEP q - q_prev (per period, joint LSB) */
    int32_t dq_max[DH_MAX_JOINTS];      /**< step bound floor(vmax_q dt_us / 10^6) (INT32_MAX: unlimited) */
    int32_t dv_max[DH_MAX_JOINTS];      /**< bound on the change of step, floor(floor(amax_q dt_us / 10^6) dt_us / 10^6) (INT32_MAX: unlimited) */
    int32_t lambda;                     /**< largest damping of the DLS step, dh_qpos (default 0.02 in J's units, not scaled by L) */
    int32_t sing_threshold;             /**< near-singular threshold on sigma_min, dh_qpos (default 0.005, not scaled by L), where the damping starts */
    int32_t pos_tol;                    /**< "reached": position tolerance, dh_qpos (default cf_pos) */
    int32_t rot_tol;                    /**< "reached": rotation tolerance, Q3.29 rad (default 10737 = 2e-5 rad) */
    /* private workspace (keeps the step's stack small); read-only for the caller */
    int32_t cf_pos;                     /**< the closed form's FK position bound, dh_qpos: 328 LSB (5e-3 units at DH_QPOS_FRAC 16, ikc.h) times ceil(L / 2^27 LSB) */
    int32_t reach;                      /**< reach bound (dh_qpos) for UNREACHABLE without a closed form */
    uint32_t hp_k;                      /**< singularity bound without J: the factor of |det J| (Q2.30; 0: none for this robot) */
    int32_t hp_e;                       /**< and its power of two */
    int jt;                             /**< J and T hold the Jacobian and FK at q */
    int tight;                          /**< the target's rotation is orthonormal within 2^-22 */
    int clamp;                          /**< the nearest solution was moved onto a limit */
    int uni;                            /**< every joint has the same vmax_q */
    int cf;                             /**< q_out is the nearest closed-form solution (in the step box) */
    int32_t J[6 * DH_MAX_JOINTS];       /**< Jacobian at q (when jt) */
    int32_t e[6];                       /**< pose error / residual */
    int32_t dq[DH_MAX_JOINTS];          /**< step being built */
    int32_t keep[DH_MAX_JOINTS];        /**< step kept between damped steps */
    int32_t lo[DH_MAX_JOINTS];          /**< step box of this period, lower */
    int32_t hi[DH_MAX_JOINTS];          /**< step box of this period, upper */
    int32_t qs[DH_MAX_JOINTS];          /**< nearest closed-form solution */
    int32_t qu[DH_MAX_JOINTS];          /**< its motion since the last period (when quv) */
    int qsv;                            /**< qs holds the last period's nearest closed-form solution */
    int quv;                            /**< qu holds its motion, each joint within dq_max */
    dh_ikc_sol_q sol[DH_IKC_MAX_SOL];   /**< closed-form solutions */
    dh_frame_q T;                       /**< FK at q (when jt) */
    dh_dls_work_q work;                 /**< scratch of the damped step */
    int32_t gs[21];                     /**< scratch of the singularity measures: the equilibrated Gram matrix */
    dh_frame_q rD;                      /**< scratch of the rotation error: dR */
    dh_dir3_q rw;                       /**< the rotation error */
    int32_t rq[4];                      /**< scratch of the rotation error: its quaternion */
    int32_t sg;                         /**< bound on the smallest singular value at the point of the step */
    int32_t lam;                        /**< damping of the step */
    uint32_t ns;                        /**< closed-form solution count */
    uint32_t pris;                      /**< bit i: joint i prismatic */
    dh_status ist;                      /**< closed form's status */
    dh_status tst;                      /**< the step's status */
    int have;                           /**< the step has a closed-form solution to run for */
    int unreach;                        /**< the target is unreachable this period */
    int stall;                          /**< the damped step stalls */
    int at;                             /**< q already reaches the target */
    const dh_frame_q *tgt;              /**< the step's target */
    int32_t *out;                       /**< the step's q_out */
    dh_track_report_q *rep;             /**< the step's report */
} dh_track_q;

/**
 * @brief Start tracking at q0 in fixed point (integer only): fills every
 * field of t, with L = sum of |a_q|, |d_q|, the prismatic travel and
 * |tool p| in dh_qpos, the closed form's position bound cf_pos = 328
 * ceil(L / 2^27) LSB (5e-3 units at DH_QPOS_FRAC 16 for robots within
 * 2048 units: ikc.h's bound for robots in mm), pos_tol = cf_pos, and the
 * Jacobian at q0.
 * @param t     tracker (not NULL), written.
 * @param r     robot (fixed path), 1..DH_MAX_JOINTS joints; rate limits
 *              from dh_robot_set_rates_q / _f32 (INT32_MAX: unlimited).
 * @param m     model from dh_ikc_analyse_q for r (kind not NONE), or NULL.
 * @param q0    n joint values within the limits (dh_q16 deg / dh_qpos).
 * @param dt_us control period in microseconds, 1..1000000.
 * @return DH_OK; DH_ERR_ARG (dt_us, n, a model of another joint count or
 *         of kind NONE); DH_ERR_LIMIT (q0 outside the limits);
 *         DH_ERR_UNAVAILABLE (no fixed path); DH_ERR_OVERFLOW (Jacobian
 *         or FK of q0 saturated). t is not usable after an error.
 */
dh_status dh_track_init_q(dh_track_q *t, const dh_robot *r, const dh_ikc_model_q *m, const int32_t *q0,
                          uint32_t dt_us);

/**
 * @brief One control period in fixed point: the next configuration
 * towards target, with dh_track_step_f32's method and guarantees, exact in
 * integers for every status: |q_out[i] - q_prev[i]| <= t->dq_max[i]
 * (<= vmax_q dt); q_out within the joint limits; with an acceleration
 * limit |(q_out - q_prev) - t->v[i]| <= t->dv_max[i] (<= amax_q dt^2) and
 * the braking condition s^2 <= 2 A D (step s, A = dv_max, D the distance
 * left to the limit ahead: v^2 <= 2 amax D) so that the bounds hold at the
 * next call too.
 * DH_TRACK_OK only when FK(q_out) (dh_fk_q) is within pos_tol and rot_tol
 * of the target.
 * When q_out is the nearest closed-form solution (in the step box), with
 * pos_tol >= t->cf_pos and rot_tol >= DH_TRACK_CF_ROT_Q (the defaults), a
 * target orthonormal within 2^-22, no value put on a limit, and the bound
 * |det J| K (docs/design.md "Tracking in fixed point") >= sing_threshold:
 * state OK, measured 0, pos_err and rot_err the closed form's bounds
 * (ikc.h), manip log2 |det J| and sigma_min |det J| K. Otherwise measured
 * 1, errors by FK and manip, sigma_min dh_manipulability_q's at q_out.
 * @param t      tracker from dh_track_init_q.
 * @param target next target frame; rotation orthonormal within
 *               DH_ROT_ERROR_TOL_Q, det > 0.
 * @param q_out  n joint values (may alias t->q).
 * @param rep    report (not NULL).
 * @return DH_OK (rep->state says whether the target was reached);
 *   DH_ERR_NOT_RIGID target not rigid: the joints brake (each step towards
 *   0 by at most dv_max, at once without an acceleration limit),
 *   rep->state DH_TRACK_UNREACHABLE, pos_err and rot_err INT32_MAX.
 */
dh_status dh_track_step_q(dh_track_q *t, const dh_frame_q *target, int32_t *q_out, dh_track_report_q *rep);

#ifdef __cplusplus
}
#endif

#endif /* DHMATH_TRACK_H */
