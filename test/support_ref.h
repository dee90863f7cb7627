/* SPDX-License-Identifier: Apache-2.0 */
/*
 * support_ref.h - double-precision reference helpers for the tests.
 *
 * Nothing here calls dhmath: the matrices are built from the textbook
 * definitions with libm sin/cos of radians in double, products are plain
 * triple loops in double and the inverse is Gauss-Jordan with partial
 * pivoting in double. Tests compare the float code under test against these.
 *
 * Matrices are column-major like dh_mat4_f32: m[col][row]; DHR_M4(T, r, c)
 * is element (row r, column c). Like the library, a helper takes the object
 * it acts on first, then its inputs, and its outputs last.
 */
#ifndef SUPPORT_REF_H
#define SUPPORT_REF_H

#include "dhmath/common.h"

#define DHR_PI 3.14159265358979323846

/** Double 4x4 matrix, column-major m[col][row]. */
typedef struct { double m[4][4]; } dhr_mat4;

#define DHR_M4(T, r, c) ((T)->m[(c)][(r)])

double dhr_deg2rad(double deg);
double dhr_rad2deg(double rad);

void dhr_identity(dhr_mat4 *T);
void dhr_trans(double x, double y, double z, dhr_mat4 *T);
void dhr_rotx(double deg, dhr_mat4 *T);
void dhr_roty(double deg, dhr_mat4 *T);
void dhr_rotz(double deg, dhr_mat4 *T);
/** Elementary transforms (angles in degrees; whole multiples of 90 exact). */
/** Rotation about axis k (normalised here) by deg, built as C Rot(z) C^T with a
 *  frame C whose z axis is k (seed eq. 1.65), not from eq. 1.70. Returns 0 if
 *  |k| == 0, else 1. */
int dhr_rot_axis(double kx, double ky, double kz, double deg, dhr_mat4 *T);

/** out = A * B; out may alias A or B. */
void dhr_mul(const dhr_mat4 *A, const dhr_mat4 *B, dhr_mat4 *out);
/** v = T * u (4-vectors); v may alias u. */
void dhr_apply4(const dhr_mat4 *T, const double u[4], double v[4]);
/** Gauss-Jordan with partial pivoting. Returns 0 (out untouched) on an
 *  exactly zero pivot, else 1. out may alias T. */
int dhr_inv(const dhr_mat4 *T, dhr_mat4 *out);
/** Determinant by Gaussian elimination with partial pivoting. */
double dhr_det(const dhr_mat4 *T);
/** Infinity norm (max row sum of |.|). */
double dhr_norm_inf(const dhr_mat4 *T);
/** ||T||inf * ||T^-1||inf; HUGE_VAL when dhr_inv fails. */
double dhr_cond_inf(const dhr_mat4 *T);
/** max |T_ij| */
double dhr_max_abs(const dhr_mat4 *T);

/** Conversions (to_f32 rounds to nearest; from_q is exact: rotation
 *  Q2.30, position Q with DH_QPOS_FRAC fraction bits, bottom row 0 0 0 1). */
void dhr_from_f32(const dh_mat4_f32 *T, dhr_mat4 *D);
void dhr_to_f32(const dhr_mat4 *D, dh_mat4_f32 *T);
void dhr_from_q(const dh_frame_q *F, dhr_mat4 *D);
/** max |T_ij - D_ij| over all 16 elements (HUGE_VAL if any is NaN). */
double dhr_max_abs_diff(const dh_mat4_f32 *T, const dhr_mat4 *D);
/** max |A_ij - B_ij| between two double matrices. */
double dhr_max_abs_diff_d(const dhr_mat4 *A, const dhr_mat4 *B);
/** Largest |position difference| (translation column) of two double
 *  matrices (NaN if a difference is NaN). */
double dhr_pos_diff(const dhr_mat4 *A, const dhr_mat4 *B);
/** Largest |rotation entry difference| (3x3 part) of two double matrices
 *  (NaN if a difference is NaN). */
double dhr_rot_diff(const dhr_mat4 *A, const dhr_mat4 *B);

/** Random unit 3-vector (uniform on the sphere) from dht_rand_uniform. */
void dhr_rand_unit3(double k[3]);

/** Eigenvalues of the symmetric m x m matrix A (row-major, destroyed) by
 * cyclic Jacobi rotations into ev[0..m-1], unordered. */
void dhr_sym_eig(double *A, int m, double *ev);
/** Random rigid transform: rotation about a random axis by an angle in
 *  [-180, 180) deg, translation components uniform in [-tmax, tmax). */
void dhr_rand_rigid(double tmax, dhr_mat4 *T);
/** Random matrix with entries uniform in [-1, 1) (a general 4x4). */
void dhr_rand_general(dhr_mat4 *T);

/** Double 3x3 matrix, row-major: d[r][c] is element (row r, column c)
 *  (dh_mat3_f32 is column-major: DH_M3(R, r, c) == R->m[c][r]). */
typedef struct { double d[3][3]; } dhr_mat3;

/** out = A * B; out may alias A or B. */
void dhr_mat3_mul(const dhr_mat3 *A, const dhr_mat3 *B, dhr_mat3 *out);
/** Rotation matrix of the unit quaternion w + xi + yj + zk (textbook formula,
 *  no normalisation). */
void dhr_mat3_from_quat(double w, double x, double y, double z, dhr_mat3 *R);
/** Rounds each entry to the nearest float. */
void dhr_mat3_to_f32(const dhr_mat3 *D, dh_mat3_f32 *R);
/** max |R_ij - D_ij| over the 9 entries (NaN if any entry of R is NaN). */
double dhr_mat3_max_diff(const dh_mat3_f32 *R, const dhr_mat3 *D);

/** Size of one float ulp at |x| (2^-149 for x == 0). */
double dhr_ulp_f32(double x);
void dhr_sincos_deg(double d, double *s, double *c);

/** The minimum rest-to-rest duration of the distance |d| within V, A
 *  (trapezoid: |d|/V + V/A when |d| >= V^2/A, else 2 sqrt(|d|/A)). */
double dhr_trap_tmin(double d, double V, double A);
/** The same within V, A, J (seven phases): the least duration among the
 *  four regimes that are feasible for |d| (not a planner's case split). */
double dhr_scurve_tmin(double d, double V, double A, double J);

#endif /* SUPPORT_REF_H */
