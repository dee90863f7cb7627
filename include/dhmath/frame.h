/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Index: the functions of frame.h by source file (src/frame/).
 *   dh_frame_q.c  dh_frame_identity_q, dh_frame_trans_q, dh_frame_rotx_q,
 *                 dh_frame_roty_q, dh_frame_rotz_q, dh_frame_rot_axis_q,
 *                 dh_frame_mul_q, dh_frame_inv_q, dh_frame_apply_point_q,
 *                 dh_frame_apply_dir_q, dh_frame_orthonormalize_q,
 *                 dh_frame_ortho_error_q
 */
/**
 * @file frame.h
 * @brief Fixed-point rigid frames: rotation Q2.30, position dh_qpos
 *        (DH_QPOS_FRAC fraction bits), angles in degrees Q16.16.
 *
 * Integer only (no float, no libm, no 64-bit division). The conversions
 * between dh_frame_q and dh_mat4_f32 are in rot.h (they use float).
 *
 * Arithmetic contract shared by every function below:
 * - Each output entry is ONE exact 64-bit sum of products rounded once:
 *   out = floor(sum / 2^30 + 1/2), i.e. round to nearest with ties toward
 *   +infinity. A translation is added inside the same sum (as p * 2^30),
 *   so an output is within 0.5 LSB of the exact value of the formula for
 *   the given integer inputs.
 * - Rotation x rotation: three Q2.30 x Q2.30 products, >> 30 -> Q2.30.
 *   Rotation x position: Q2.30 x Qpos >> 30 -> Qpos, for every
 *   DH_QPOS_FRAC in 8..24 (the position format does not enter the shift).
 * - Results that do not fit int32 are saturated to INT32_MIN / INT32_MAX
 *   with the correct sign, written, and DH_ERR_OVERFLOW is returned (all
 *   other outputs are still computed normally). There is no wraparound and
 *   no sentinel value.
 * - Any int32 value is accepted in every field of a dh_frame_q (rotation
 *   entries in [-2, 2)), with no intermediate overflow; DH_SMALL builds
 *   give the same bits and statuses (method: docs/design.md, "Fixed-point
 *   frames").
 * - Outputs may alias inputs (results are computed into locals first).
 * - NULL pointers are programmer errors: DH_ASSERT.
 * - Every function uses at most 256 bytes of stack.
 *
 * Accuracy is quoted per function in LSB: 1 LSB of a rotation entry is
 * 2^-30, 1 LSB of a position is 2^-DH_QPOS_FRAC units; equation numbers
 * are those of Paul 1981. Measured accuracy: docs/accuracy_fixed.md; cost
 * and stack: docs/generated/performance_target.md, docs/generated/footprint.md.
 */
#ifndef DHMATH_FRAME_H
#define DHMATH_FRAME_H

#include "dhmath/common.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- compile-time constants ------------------------------------------- */

/**
 * @name Fixed-point constants from decimal literals
 * DH_Q16(90.5) (Q16.16 degrees), DH_Q30(0.70710678) (Q2.30) and
 * DH_QPOS(123.25) (dh_qpos, DH_QPOS_FRAC fraction bits): the literal times
 * 2^16, 2^30 or 2^DH_QPOS_FRAC, rounded to the nearest int32 (halves away
 * from zero: the fraction is split off exactly in double), as an int32_t.
 * Each is an arithmetic constant expression (C99 6.6), so it may
 * initialise a static or const object, e.g. a robot table or a limit, and
 * no float code is emitted for a literal argument (the compiler folds it).
 * It is not an integer constant expression (no case label, array size).
 * Range: the rounded value must fit int32 (Q16.16 below +-32768 deg, Q2.30
 * in [-2, 2), dh_qpos below +-2^(31 - DH_QPOS_FRAC)); outside it the
 * expression divides by zero, which makes a static initialiser a compile
 * error in C and draws -Wdiv-by-zero from GCC and Clang elsewhere. The
 * argument is evaluated several times: pass a literal or constant.
 * @{
 */
/** @cond */
#define DH_FIX_FITS_(v) ((v) > -2147483648.5 && (v) < 2147483647.5)
#define DH_FIX_ROUND_(x, s)                                                         \
    ((int32_t)((int32_t)((x) * (s)) +                                               \
               ((((x) * (s)) - (double)(int32_t)((x) * (s))) >= 0.5 ? 1 :           \
                ((((x) * (s)) - (double)(int32_t)((x) * (s))) <= -0.5 ? -1 : 0)) +  \
               (1 / DH_FIX_FITS_((x) * (s)) - 1)))
/** @endcond */
/** Q16.16 degrees from a literal in degrees. */
#define DH_Q16(x) ((dh_q16)DH_FIX_ROUND_((x), 65536.0))
/** Q2.30 from a literal in [-2, 2) (1.0 -> 0x40000000 exactly). */
#define DH_Q30(x) ((dh_q30)DH_FIX_ROUND_((x), 1073741824.0))
/** dh_qpos from a literal length (DH_QPOS_FRAC fraction bits). */
#define DH_QPOS(x) ((dh_qpos)DH_FIX_ROUND_((x), (double)((int32_t)1 << DH_QPOS_FRAC)))
/** @} */

/**
 * @brief F = identity (rotation I exactly, position 0). Cannot fail.
 * @param[out] F frame to write.
 */
void dh_frame_identity_q(dh_frame_q *F);

/**
 * @brief F = Trans(x, y, z) (Paul 1981 eq. 1.24): rotation I, position (x, y, z).
 * @param[out] F frame to write.
 * @param x,y,z translation, dh_qpos (DH_QPOS_FRAC fraction bits), any int32.
 */
void dh_frame_trans_q(dh_qpos x, dh_qpos y, dh_qpos z, dh_frame_q *F);

/**
 * @brief F = Rot(x, deg) (eq. 1.32), position 0.
 *
 * Entries are exactly the dh_sincos_q() values (c, s, and -s), so whole
 * degrees are correctly rounded and multiples of 90 degrees are exact
 * (test_frame_q asserts every entry within 2 LSB of the exact value).
 * @param[out] F frame to write.
 * @param deg angle in degrees, Q16.16, any int32 (full range of dh_sincos_q).
 */
void dh_frame_rotx_q(dh_q16 deg, dh_frame_q *F);
/** @brief F = Rot(y, deg) (eq. 1.33); otherwise as dh_frame_rotx_q(). */
void dh_frame_roty_q(dh_q16 deg, dh_frame_q *F);
/** @brief F = Rot(z, deg) (eq. 1.34); otherwise as dh_frame_rotx_q(). */
void dh_frame_rotz_q(dh_q16 deg, dh_frame_q *F);

/**
 * @brief F = Rot(k, deg) (eq. 1.70), rotation about the axis k through
 *        the origin; position 0.
 *
 * The axis is normalised internally in integer arithmetic, so any common
 * scale of (kx, ky, kz) is accepted: Q2.30 unit vectors, integers, any
 * int32 values including INT32_MIN (the unit axis is exact to about 2^-44;
 * only an INT32_MIN component costs the others their lowest bit). The
 * result is given one re-orthonormalisation step
 * (dh_frame_orthonormalize_q()). Entries within 3 LSB of the exact
 * formula (dh_sincos_q's error included; checked over 200 seeds of random
 * axes), dh_frame_ortho_error_q(F) <= 3 (derived in docs/design.md).
 *
 * @param[out] F frame to write.
 * @param kx,ky,kz axis, any common scale (int32).
 * @param deg angle in degrees, Q16.16, any int32.
 * @return DH_OK; DH_ERR_ZERO_AXIS if kx == ky == kz == 0 (F untouched).
 */
dh_status dh_frame_rot_axis_q(dh_q30 kx, dh_q30 ky, dh_q30 kz, dh_q16 deg, dh_frame_q *F);

/**
 * @brief out = A * B (rigid composition: R = Ra Rb, p = Ra pb + pa).
 *
 * One rounding per output: <= 0.5 LSB vs. the exact product of the integer
 * inputs. May alias A and/or B.
 * @return DH_OK, or DH_ERR_OVERFLOW if any entry saturated (all 12 entries
 *         written, saturated ones at INT32_MIN / INT32_MAX).
 */
dh_status dh_frame_mul_q(const dh_frame_q *A, const dh_frame_q *B, dh_frame_q *out);

/**
 * @brief out = F^-1 for a rigid F (eq. 1.57): R' = R^T (exact copy),
 *        p' = -R^T p (one rounding per entry, <= 0.5 LSB).
 *
 * Rigidity is not checked: for a non-orthonormal R the result is R^T and
 * -R^T p, not the general inverse. T * T^-1 (dh_frame_mul_q) then differs
 * from I by R R^T - I: with e = dh_frame_ortho_error_q(F), at most 3 e + 2
 * LSB per rotation entry and 1.4 + (3 e + 1.5) |p| 2^-30 LSB per position
 * entry (|p| in position LSB; derivation in docs/design.md). May alias F.
 * @return DH_OK, or DH_ERR_OVERFLOW if a position entry saturated (written).
 */
dh_status dh_frame_inv_q(const dh_frame_q *F, dh_frame_q *out);

/**
 * @brief v = R u + p (point, w = 1). u, v in dh_qpos; may alias.
 *        One rounding per component (<= 0.5 LSB vs. exact).
 * @return DH_OK, or DH_ERR_OVERFLOW if a component saturated (written).
 */
dh_status dh_frame_apply_point_q(const dh_frame_q *F, const dh_vec3_q *u, dh_vec3_q *v);

/**
 * @brief v = R u (direction, w = 0; the position of F is ignored). u and v
 *        share any scale (dh_qpos or Q2.30 alike); may alias.
 * @return DH_OK, or DH_ERR_OVERFLOW if a component saturated (written).
 */
dh_status dh_frame_apply_dir_q(const dh_frame_q *F, const dh_vec3_q *u, dh_vec3_q *v);

/**
 * @brief out = F with its rotation part re-orthonormalised by one Newton
 *        step R <- R (3 I - R^T R) / 2 (position copied), the fixed twin of
 *        dh_mat3_orthonormalize_f32.
 *
 * The step is quadratically convergent: an input error e (largest
 * |R^T R - I| entry) becomes about 3/4 e^2 plus rounding, so frames
 * accumulated over many compositions stay within a few LSB of orthonormal
 * when this is called regularly (e.g. once every 64 compositions). Keeps
 * the sign of det R.
 * @return DH_OK; DH_ERR_NOT_RIGID (out untouched) if an entry exceeds 1.25
 *         in magnitude or the error exceeds 1/8 (2^27 LSB), where a single
 *         step would not be reliable. No other status: for the accepted
 *         inputs every entry of the step stays inside [-2, 2) (proved in
 *         the source), so it cannot saturate. out may alias F.
 */
dh_status dh_frame_orthonormalize_q(const dh_frame_q *F, dh_frame_q *out);

/**
 * @brief Largest |(R^T R - I)_ij| in Q2.30 LSB (drift measure), exact up
 *        to the one rounding; defined for every input, saturated at
 *        INT32_MAX. 0 for the identity and the exact 90-degree rotations.
 */
int32_t dh_frame_ortho_error_q(const dh_frame_q *F);

#ifdef __cplusplus
}
#endif

#endif /* DHMATH_FRAME_H */
