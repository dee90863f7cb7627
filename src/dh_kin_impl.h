/*
 * dh_kin_impl.h - PRIVATE interface between dh_jacobian.c and dh_ik.c (not
 * part of the public API, not installed).
 *
 * Why: dh_ik_f32 must stay within the 256-byte worst-case stack budget
 * (tools/check_guards.sh, callees and libgcc included). It therefore keeps
 * every matrix in its caller-supplied workspace and calls these building
 * blocks one after the other, instead of nesting public functions that each
 * carry their own 4x4 temporaries. Each block is shallow: the Jacobian pass
 * calls no trigonometry (the per-joint sin/cos are computed beforehand) and
 * only libgcc helpers below it.
 *
 * Frame layout used here ("F", 12 floats): the 3x4 part of a homogeneous
 * frame by columns, F[3c + k] = row k of column c, columns n, o, a, p (the
 * same order as dh_mat4_f32.m[c][k] with the bottom row left out).
 */
#ifndef DHMATH_SRC_DH_KIN_IMPL_H
#define DHMATH_SRC_DH_KIN_IMPL_H

#include "dhmath/dh_kin.h"

/*
 * Jacobian (6 x n row-major, base frame, as dh_jacobian_f32) and end frame F
 * (base * A_1..A_n * tool) from precomputed joint data scd[3i..3i+2] =
 * sin theta_i, cos theta_i, d_i (theta and d of the link, offsets included).
 * No argument checks: r->n <= DH_MAX_JOINTS, known convention and joint
 * types, float path available are the caller's job. J, F and scd must not
 * overlap. Returns 1 when every entry of J and F is finite, else 0 (J and F
 * hold the computed values).
 */
int dh_kin_jac_f32_(const dh_robot *r, const float *scd, float *J, float *F);

/*
 * Rotation vector a(dR) (FloCal, "Inverse Kinematics") (the method of dh_rot_error_f32) for
 * dR given row-major, d[3 * row + col]; writes w[0..2]. Never fails for
 * finite input; d and w must not overlap.
 */
void dh_kin_rotvec_f32_(const float *d, float *w);

/*
 * 1 when the 3x3 with columns c0, c1, c2 (3 floats each) is orthonormal
 * within DH_ROT_ERROR_TOL (every entry of R^T R - I) and has det > 0;
 * 0 otherwise (also for NaN).
 */
int dh_kin_rot_ok_f32_(const float *c0, const float *c1, const float *c2);


#endif /* DHMATH_SRC_DH_KIN_IMPL_H */
