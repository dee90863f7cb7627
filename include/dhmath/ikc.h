/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Index: the functions of ikc.h by source file (src/ikc/).
 *   dh_ikc.c    dh_ikc_analyse_f32, dh_ikc_why_str, dh_ikc_f32,
 *               dh_ikc_nearest_f32
 *   dh_ikc_q.c  dh_ikc_analyse_q, dh_ikc_q, dh_ikc_nearest_q
 */
/**
 * @file ikc.h
 * @brief Closed-form inverse kinematics: every solution, no iteration,
 *        float and fixed point, the structure recognised from the DH table.
 *
 * Families (dh_ikc_kind), each recognised from a dh_robot in standard or
 * modified DH with any base and tool frame and joint offsets:
 * - DH_IKC_WRIST_RRR: six revolute joints, axes 2 and 3 parallel, the last
 *   three axes meeting in one point at right angles (spherical wrist), any shoulder and
 *   elbow offsets (Puma 560, KUKA KR5, ABB IRB140; Paul 1981 ch. 3, the
 *   Puma's transform-equation solution); up to 8 solutions;
 * - DH_IKC_WRIST_RRP: the same wrist on an R-R-P arm (Stanford arm); up to
 *   8, four of them with the prismatic joint's extension negative (limits on
 *   the prismatic joint normally remove those);
 * - DH_IKC_PARALLEL_234: six revolute joints with axes 2, 3, 4 parallel
 *   (Universal Robots UR3/UR5/UR10 and e-series); up to 8;
 * - DH_IKC_SCARA: R-R-P-R with all four axes parallel (Adept Cobra 600); up to 2.
 *
 * Use: analyse the robot once (dh_ikc_analyse_f32 / dh_ikc_analyse_q) into
 * a caller-owned model, then solve any number of targets with it
 * (dh_ikc_f32 / dh_ikc_q) and pick one with dh_ikc_nearest_f32 / _q. The
 * model is a copy: analyse again after changing the robot. The fixed path
 * (analyse_q, dh_ikc_q, nearest_q) is integer only: no float, libm or
 * 64-bit division is linked, so it runs on Cortex-M0.
 *
 * Solutions: joint values as dh_fk_f32 / dh_fk_q take them (degrees for
 * revolute joints, the robot's length unit for prismatic ones; fixed: Q16.16
 * degrees and dh_qpos). A revolute value is first in (-180, 180] and is then
 * shifted by a multiple of 360 deg where that brings it inside the joint's
 * limits, to the shifted value nearest q_ref (no limits: it stays in
 * (-180, 180]). A solution with a value outside the limits is left out,
 * or kept and flagged DH_IKC_OUT_OF_LIMITS with DH_IKC_KEEP_OUT_OF_LIMITS.
 * Solutions are distinct configurations: a stretched elbow (two branches
 * coincide) or a singular shoulder gives its solution once.
 *
 * Singular cases are solved, not failed: wrist singular (axes 4 and 6
 * aligned) returns the one-parameter family's member whose joint 4 keeps
 * q_ref's value (the sum or difference of joints 4 and 6 is what the target
 * fixes; DH_IKC_PARALLEL_234, axes 2, 3, 4, 6 parallel: joint 6 keeps it),
 * flagged DH_IKC_SING_WRIST; shoulder singular (the wrist centre, or for
 * DH_IKC_PARALLEL_234 the joint 5 axis point, on axis 1) keeps joint 1
 * at q_ref's value, flagged DH_IKC_SING_SHOULDER, which also marks the
 * PARALLEL_234 shoulder branches met (that point on the cylinder about
 * axis 1 whose radius is the arm's offset along axis 2). Elbow stretched
 * or folded: flagged DH_IKC_SING_ELBOW.
 *
 * Boundary targets. A target whose wrist centre (DH_IKC_PARALLEL_234: the
 * joint 5 point; SCARA: the frame 3 origin) lies beyond the workspace's
 * boundary (elbow stretched or folded, the shoulder cylinder) by no more
 * than the rounding of its inputs is solved on the boundary, flagged as
 * above, within the accuracy bounds below. Fixed path, every family: that
 * point within 2^(5 - F) length units of the boundary (F = DH_QPOS_FRAC;
 * 2^-11 mm for robots in mm) is solved, beyond it by more than 2^(8 - F)
 * units DH_ERR_UNREACHABLE. Float path (L: the sum of the robot's |a| and
 * |d|): spherical wrist within 2.5e-7 L solved, beyond 1.5e-6 L
 * unreachable (the band of the singular flags is 5e-7 L); PARALLEL_234
 * within 1e-7 L solved, beyond 1.6e-6 L unreachable (band 4e-7 L).
 * A target within the band, inside or beyond, is solved at the boundary:
 * its joints differ from an exact solution's by up to the square root of
 * the band (0.12 deg for a Puma target 0.12 deg from stretched), and near
 * a singularity the target's rounding moves the joints by more than it
 * moves the pose (joint 2 of a folded Puma elbow, whose wrist centre lies
 * 0.5 mm from axis 2: 1.8 deg in the tests; docs/accuracy_kin.md). A joint limit that near may
 * drop such a solution (DH_ERR_LIMIT; DH_IKC_KEEP_OUT_OF_LIMITS keeps it).
 *
 * Accuracy (tests against double, test/ikc/test_ikc*.c; measured figures:
 * docs/accuracy_kin.md): for every solution FK(q) matches the target within
 * 2e-6 m in position and 2e-6 rad in orientation for float robots in metres
 * of up to 2 m reach, and within 5e-3 mm and 5e-6 rad on the fixed path for
 * robots in mm. Memory: caller-owned model and solution array, no heap,
 * every function within the 256 B stack guard. Method: docs/design.md
 * ("Closed-form inverse kinematics").
 */
#ifndef DHMATH_IKC_H
#define DHMATH_IKC_H

#include "dhmath/robot.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Largest number of solutions any family returns. */
#define DH_IKC_MAX_SOL 8u
/** Joints of the canonical chain the model stores (the families have 4 or 6). */
#define DH_IKC_JOINTS 6u
/** Family-specific constants in a model (layout private to src/). */
#define DH_IKC_K 24u

/** Closed-form family of a robot. */
typedef enum {
    DH_IKC_NONE = 0,         /**< no closed form (dh_ikc_model.why says why) */
    DH_IKC_WRIST_RRR = 1,    /**< 6R, axes 2 || 3, spherical wrist (Puma 560, KUKA KR5, ABB IRB140) */
    DH_IKC_WRIST_RRP = 2,    /**< R-R-P arm and a spherical wrist (Stanford arm) */
    DH_IKC_PARALLEL_234 = 3, /**< 6R with axes 2, 3, 4 parallel (Universal Robots) */
    DH_IKC_SCARA = 4         /**< R-R-P-R, four parallel axes (Adept Cobra 600) */
} dh_ikc_kind;

/** Why a robot has no closed form. */
typedef enum {
    DH_IKC_WHY_NONE = 0,   /**< it has one (kind != DH_IKC_NONE) */
    DH_IKC_WHY_JOINTS = 1, /**< joint count or types match no family (6R, RRP + 3R, RRPR) */
    DH_IKC_WHY_WRIST = 2,  /**< six joints, but the last three axes do not meet in one point and axes 2, 3, 4 are not parallel */
    DH_IKC_WHY_AXES = 3,   /**< the last three axes meet, but not at right angles, or axes 2 and 3 are not parallel (RRR) or the first three are not a Stanford R-R-P arm; SCARA axes not parallel */
    DH_IKC_WHY_PATH = 4    /**< the float (analyse_f32) or fixed (analyse_q) path of the robot is not prepared */
} dh_ikc_why;

/** @name Solution flags (dh_ikc_sol_f32.flags, dh_ikc_sol_q.flags)
 * The branch bits name the choice of each square-root sign: shoulder
 * (joint 1's two solutions), elbow (joint 3's, or for SCARA joint 2's),
 * wrist (joint 5's sign). The all-zero solution of a family is listed first.
 * @{ */
#define DH_IKC_SHOULDER_ALT 0x01u  /**< second shoulder branch */
#define DH_IKC_ELBOW_ALT 0x02u     /**< second elbow branch */
#define DH_IKC_WRIST_ALT 0x04u     /**< second wrist branch (wrist flipped) */
#define DH_IKC_REFINED 0x08u       /**< calibrated model: refined on the exact chain, converged (see below) */
#define DH_IKC_OUT_OF_LIMITS 0x10u /**< a joint value is outside its limits (kept with DH_IKC_KEEP_OUT_OF_LIMITS) */
#define DH_IKC_SING_WRIST 0x20u    /**< wrist singular: joint 4 (PARALLEL_234: joint 6) taken from q_ref */
#define DH_IKC_SING_SHOULDER 0x40u /**< shoulder singular: joint 1 taken from q_ref */
#define DH_IKC_SING_ELBOW 0x80u    /**< elbow stretched: the two elbow branches coincide (returned once) */
/** @} */

/** @name Calibration tolerance (dh_ikc_analyse_f32)
 * A six-revolute robot that no family fits exactly but that is within these
 * of DH_IKC_PARALLEL_234 or of DH_IKC_WRIST_RRR is a calibrated robot of
 * that family (model.calibrated = 1; PARALLEL_234 tried first): every
 * twist within DH_IKC_CAL_ANGLE_DEG of a multiple of 90 degrees is taken
 * as that multiple and the lengths that break the family's structure
 * within DH_IKC_CAL_OFFSET_REL of the sum of the chain's |a| and |d| as 0
 * (PARALLEL_234: a5 of the canonical chain; WRIST_RRR: the wrist offsets
 * a4, a5, d5, which keep axes 4, 5, 6 from meeting): the idealised chain.
 * dh_ikc_f32 solves the idealised chain in
 * closed form and refines every branch on the exact chain by at most
 * DH_IKC_CAL_STEPS Newton steps; a branch is returned (flagged
 * DH_IKC_REFINED) only when its residual on the exact chain is within
 * 4e-7 L in position (L: the sum of |a| and |d|) and 8e-7 rad, and left
 * out otherwise (none left: DH_ERR_UNREACHABLE); the accuracy bounds below
 * hold for it. PARALLEL_234: the steps are simplified Newton steps, and a
 * shoulder whose four branches are not all refined is
 * started again from the virtual target of one of its branches (the exact
 * errors there applied to the idealised chain), which finds the branches
 * that the idealised chain lacks or misplaces near the wrist singularity
 * (docs/design.md). A configuration whose joint 5 point lies within the
 * deviations' shift (about 1.3e-2 L for 2 mm and 0.5 deg) of the elbow's
 * boundary, or one at a singularity of the idealised blocks (s5, shoulder,
 * elbow), may be missing; near the elbow's boundary the solutions may
 * number more or fewer than the idealised chain's. WRIST_RRR: each
 * idealised branch is refined with the exact chain's Jacobian split into
 * the idealised wrist centre's and wrist's blocks, none restarted; a
 * configuration whose wrist centre lies within the deviations' shift (the
 * wrist offset plus the twists' deviation in radians times the arm's
 * lengths) of the elbow's boundary or of the shoulder's cylinder (where
 * its two shoulder branches meet), or one at a singularity (s5, shoulder,
 * elbow), may be missing: there the idealised chain may have no branch
 * for the target, and a reachable target may be DH_ERR_UNREACHABLE; the
 * solutions may number fewer than the idealised chain's. Beyond the
 * tolerance: no closed form (DH_ERR_UNAVAILABLE, why as for any robot).
 * The R-R-P wrist and SCARA families, and the fixed path
 * (dh_ikc_analyse_q), recognise exact robots only.
 * @{ */
#define DH_IKC_CAL_ANGLE_DEG 1.0f   /**< twist deviation, degrees */
#define DH_IKC_CAL_OFFSET_REL 0.01f /**< structure-breaking length, fraction of the reach */
#define DH_IKC_CAL_STEPS 12u        /**< Newton steps per branch at most */
/** @} */

/** Option bit for dh_ikc_f32 / dh_ikc_q: keep solutions outside the limits, flagged. */
#define DH_IKC_KEEP_OUT_OF_LIMITS 0x1u

/** Float model: the robot's canonical chain and family constants (caller-owned; fill with dh_ikc_analyse_f32). */
typedef struct {
    dh_ikc_kind kind;            /**< family, DH_IKC_NONE if none */
    dh_ikc_why why;              /**< reason when kind is DH_IKC_NONE */
    uint32_t n;                  /**< joints (6, or 4 for SCARA) */
    uint32_t prismatic;          /**< bit i set: joint i is prismatic */
    float a[DH_IKC_JOINTS];      /**< canonical standard-DH a */
    float d[DH_IKC_JOINTS];      /**< canonical d (revolute joints) or d offset (prismatic) */
    float sa[DH_IKC_JOINTS];     /**< canonical sin(alpha) */
    float ca[DH_IKC_JOINTS];     /**< canonical cos(alpha) */
    float off[DH_IKC_JOINTS];    /**< theta offset, degrees (revolute), or fixed theta (prismatic) */
    float qmin[DH_IKC_JOINTS];   /**< joint limits as in the robot (qmin > qmax: none) */
    float qmax[DH_IKC_JOINTS];   /**< upper limits */
    float k[DH_IKC_K];           /**< family constants */
    dh_mat4_f32 pre_inv;         /**< inverse of the frame before the canonical chain (base and MDH first link) */
    dh_mat4_f32 post_inv;        /**< inverse of the frame after it (tool) */
    /* Precomputed for the joint conversion of dh_ikc_f32 (from qmin, qmax): */
    float win_lo[DH_IKC_JOINTS]; /**< a revolute value v with win_lo <= v <= win_hi lies in (-180, 180] and within the limits */
    float win_hi[DH_IKC_JOINTS]; /**< upper end of that window */
    uint32_t wide;               /**< bit i set: joint i's limits are a turn or more apart (q_ref picks among the shifts) */
    float lim_w[2u * DH_IKC_JOINTS]; /**< revolute joint i's limits as a circular window of canonical values: centre
                                          lim_w[i] in (-180, 180], radius lim_w[6 + i] with a rounding margin (+inf:
                                          no bound); a value farther from the centre is outside the limits */
    uint32_t lim_any;            /**< 1: a radius of lim_w is finite and kind a spherical-wrist family (exact): dh_ikc_f32 prunes by it */
    uint32_t calibrated;         /**< 1: within the calibration tolerance of kind, not on it: a..ca hold the
                                      idealised chain, xa..xca the exact one, solutions refined; 0: exact */
    float xa[DH_IKC_JOINTS];     /**< exact canonical a (calibrated; 0 otherwise) */
    float xd[DH_IKC_JOINTS];     /**< exact canonical d */
    float xsa[DH_IKC_JOINTS];    /**< exact canonical sin(alpha) */
    float xca[DH_IKC_JOINTS];    /**< exact canonical cos(alpha) */
    float xlen;                  /**< sum of the exact chain's |a| and |d| (calibrated) */
    float xw5[3];                /**< the exact chain's joint 5 point in the tool frame (calibrated) */
    uint32_t xframes;            /**< bit 0: a base frame (pre_inv not the identity), bit 1: a tool frame */
} dh_ikc_model_f32;

/** Fixed-point model (fill with dh_ikc_analyse_q); lengths dh_qpos, sin/cos Q2.30, angles Q16.16. */
typedef struct {
    dh_ikc_kind kind;            /**< family, DH_IKC_NONE if none */
    dh_ikc_why why;              /**< reason when kind is DH_IKC_NONE */
    uint32_t n;                  /**< joints (6, or 4 for SCARA) */
    uint32_t prismatic;          /**< bit i set: joint i is prismatic */
    dh_qpos a[DH_IKC_JOINTS];    /**< canonical standard-DH a */
    dh_qpos d[DH_IKC_JOINTS];    /**< canonical d, or d offset (prismatic) */
    dh_q30 sa[DH_IKC_JOINTS];    /**< canonical sin(alpha) */
    dh_q30 ca[DH_IKC_JOINTS];    /**< canonical cos(alpha) */
    dh_q16 off[DH_IKC_JOINTS];   /**< theta offset (revolute) or fixed theta (prismatic), Q16.16 degrees */
    int32_t qmin[DH_IKC_JOINTS]; /**< limits as in the robot (Q16.16 deg / dh_qpos; qmin > qmax: none) */
    int32_t qmax[DH_IKC_JOINTS]; /**< upper limits */
    int32_t k[DH_IKC_K];         /**< family constants */
    dh_frame_q pre_inv;          /**< inverse of the frame before the canonical chain */
    dh_frame_q post_inv;         /**< inverse of the frame after it (tool) */
} dh_ikc_model_q;

/** One float solution. */
typedef struct {
    float q[DH_IKC_JOINTS]; /**< joint values (first n used) */
    uint32_t flags;         /**< DH_IKC_* solution flags */
} dh_ikc_sol_f32;

/** One fixed-point solution. */
typedef struct {
    int32_t q[DH_IKC_JOINTS]; /**< Q16.16 degrees (revolute) or dh_qpos (prismatic) */
    uint32_t flags;           /**< DH_IKC_* solution flags */
} dh_ikc_sol_q;

/**
 * @brief Recognise r's closed-form family (float path) and fill m.
 * @param r robot with its float path prepared (DH_ROBOT_HAS_F32).
 * @param m model (not NULL), every field written.
 * @return DH_OK (m->kind a family); DH_ERR_UNAVAILABLE no closed form or
 *   no float path (m->kind DH_IKC_NONE, m->why the reason); DH_ERR_ARG
 *   r->n > DH_MAX_JOINTS or an unknown convention (m->kind NONE, why JOINTS);
 *   DH_ERR_NOT_RIGID base or tool not rigid (m->kind NONE, why PATH).
 */
dh_status dh_ikc_analyse_f32(const dh_robot *r, dh_ikc_model_f32 *m);

/** @brief As dh_ikc_analyse_f32 for the fixed path (DH_ROBOT_HAS_Q), integer only. */
dh_status dh_ikc_analyse_q(const dh_robot *r, dh_ikc_model_q *m);

/** @brief Short English sentence for a reason (never NULL; unknown values: "unknown reason"). */
const char *dh_ikc_why_str(dh_ikc_why why);

/**
 * @brief Every closed-form solution of FK(q) = target (float).
 * @param m      model from dh_ikc_analyse_f32 (kind not NONE).
 * @param target end frame (base to tool), bottom row 0 0 0 1, rotation
 *               within DH_ROT_ERROR_TOL of orthonormal with det > 0.
 * @param q_ref  m->n finite values: reference for the singular splits and the
 *               360-degree shifts; NULL means all zeros.
 * @param opts   0 or DH_IKC_KEEP_OUT_OF_LIMITS.
 * @param sol    DH_IKC_MAX_SOL entries, written from index 0; may not overlap the inputs.
 * @param n_sol  number of solutions written (not NULL).
 * @return DH_OK (*n_sol >= 1); DH_ERR_UNREACHABLE no solution exists
 *   (*n_sol = 0); DH_ERR_LIMIT solutions exist but all are outside the
 *   limits and opts does not keep them (*n_sol = 0). With *n_sol = 0 and sol
 *   untouched: DH_ERR_UNAVAILABLE (m->kind NONE), DH_ERR_ARG (opts unknown
 *   bits, model fields out of range), DH_ERR_NAN (target or q_ref not
 *   finite), DH_ERR_NOT_RIGID (target not rigid).
 */
dh_status dh_ikc_f32(const dh_ikc_model_f32 *m, const dh_mat4_f32 *target, const float *q_ref, uint32_t opts,
                     dh_ikc_sol_f32 *sol, uint32_t *n_sol);

/**
 * @brief As dh_ikc_f32 in fixed point, integer only: target a dh_frame_q
 *        (rotation within 2^-10 of orthonormal, det > 0; else
 *        DH_ERR_NOT_RIGID), q_ref in Q16.16 degrees / dh_qpos (NULL: zeros).
 *        DH_ERR_OVERFLOW (*n_sol = 0) when an intermediate would saturate
 *        (a wrist centre more than 2^30 dh_qpos LSB from the base:
 *        2^(30 - DH_QPOS_FRAC) length units, 16384 at the default 16).
 */
dh_status dh_ikc_q(const dh_ikc_model_q *m, const dh_frame_q *target, const int32_t *q_ref, uint32_t opts,
                   dh_ikc_sol_q *sol, uint32_t *n_sol);

/**
 * @brief Index of the solution nearest q_ref: smallest sum over joints of
 *        |q_i - q_ref_i| (the first of equals). n joints, n_sol solutions;
 *        q_ref NULL means all zeros.
 * @return DH_OK; DH_ERR_ARG n_sol == 0 or n > DH_IKC_JOINTS (*index untouched);
 *         DH_ERR_NAN q_ref not finite.
 */
dh_status dh_ikc_nearest_f32(const dh_ikc_sol_f32 *sol, uint32_t n_sol, const float *q_ref, uint32_t n,
                             uint32_t *index);

/** @brief As dh_ikc_nearest_f32 in fixed point (sums in 64 bits, no overflow). */
dh_status dh_ikc_nearest_q(const dh_ikc_sol_q *sol, uint32_t n_sol, const int32_t *q_ref, uint32_t n,
                           uint32_t *index);

#ifdef __cplusplus
}
#endif

#endif /* DHMATH_IKC_H */
