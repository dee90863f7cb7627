/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_dls.c - singularity measures of a float Jacobian and one damped
 * least-squares (DLS) step.
 *
 * Both work on the symmetric positive semidefinite normal matrix A (J J^T,
 * 6 x 6, or J^T J when n < 6), stored packed (lower triangle by rows, 21
 * floats, and 6 of scratch: on the stack of the public functions, in the
 * tracker's state for the _ws_ variants) and factored A = L L^T by
 * Cholesky. The work is split into small functions (one entry of A, one
 * column of L^-1 per call) so that no frame holds much beside the matrix.
 *
 * Manipulability (Yoshikawa 1985): w = sqrt(det A) = prod L_ii.
 *
 * Lower bound on the smallest singular value: for A positive definite,
 * lambda_max(A^-1) <= trace(A^-1) = ||L^-1||_F^2, so lambda_min(A) >=
 * 1 / ||L^-1||_F^2, at most m times (m = 6 or n) below the true value.
 * Float rounding: the computed L satisfies L L^T = A + E with ||E||_2 <=
 * 2 gamma_7 trace(A) (forming A in float and Cholesky's backward error,
 * Higham 2002 ch. 10), and the forward substitutions for L^-1 are accurate
 * to cond(L) gamma_6 relative. The bound returned is therefore
 *   sigma_min^2 >= (1 - 2^-8) / ||L^-1||_F^2 - 32 u trace(A),  u = 2^-24,
 * and 0 when that is not positive (a pivot <= 0 included): a lower bound
 * on the smallest singular value of the J given, resolved down to about
 * sqrt(32 u trace(A)) (5e-3 for a 1 m arm in metres, trace(A) about 10).
 *
 * DLS step (Wampler 1986, Nakamura and Hanafusa 1986): dq = J^T (J J^T +
 * lambda^2 I)^-1 e, per radian for revolute joints, then converted to
 * degrees and scaled down uniformly to the caller's per-joint bounds (the
 * direction of the step is kept). With lambda > 0 every Schur complement
 * of A is at least lambda^2, so a pivot that rounding pushes below it is
 * raised to lambda^2.
 */
#include "dhmath/kin.h"
#include "../internal/dh_floatops.h"
#include "kin_impl.h"

/* u = 2^-24, the unit roundoff of float */
#define DLS_U 5.9604644775390625e-8f

/* entry p of the packed lower triangle of J J^T (jjt != 0) or J^T J:
 * row i, column j (j <= i) with p = i (i + 1) / 2 + j. One entry per call
 * keeps the frames small on cores with few registers. */
static DH_NOINLINE float dls_entry(const float *J, uint32_t n, int jjt, uint32_t p_in)
{
    uint32_t i = 0u, k, len, stride, p = p_in;
    const float *a;
    const float *b;
    float s = 0.0f;
    while (p > i) {
        i++;
        p -= i;
    }
    if (jjt != 0) {
        a = &J[i * n];
        b = &J[p * n];
        len = n;
        stride = 1u;
    } else {
        a = &J[i];
        b = &J[p];
        len = 6u;
        stride = n;
    }
    for (k = 0u; k < len; k++) s += a[k * stride] * b[k * stride];
    return s;
}

/* A (packed lower) = J J^T (jjt != 0, 6 x 6) or J^T J (n x n) */
static DH_NOINLINE void dls_normal(const float *J, uint32_t n, int jjt, float *A)
{
    const uint32_t m = (jjt != 0) ? 6u : n;
    uint32_t p;
    for (p = 0u; p < m * (m + 1u) / 2u; p++) A[p] = dls_entry(J, n, jjt, p);
}

/* trace (d = 0) or product (d = 1) of the diagonal of the packed A */
static DH_NOINLINE float dls_diag(const float *A, uint32_t m, int d)
{
    uint32_t i;
    float v = (d != 0) ? 1.0f : 0.0f;
    for (i = 0u; i < m; i++) {
        const float x = A[i * (i + 3u) / 2u];
        v = (d != 0) ? v * x : v + x;
    }
    return v;
}

/* In-place Cholesky of the packed m x m matrix A: L (lower, packed).
 * A pivot below floor is set to floor when floor > 0; returns 1 when a
 * pivot is <= 0 (L incomplete), else 0. */
static DH_NOINLINE int dls_chol(float *A, uint32_t m, float floor)
{
    uint32_t i, j, k;
    for (i = 0u; i < m; i++) {
        float *Ri = &A[i * (i + 1u) / 2u];
        for (j = 0u; j <= i; j++) {
            const float *Rj = &A[j * (j + 1u) / 2u];
            float s = Ri[j];
            for (k = 0u; k < j; k++) s -= Ri[k] * Rj[k];
            if (j < i) {
                Ri[j] = s / Rj[j];
            } else {
                if (floor > 0.0f && !(s >= floor)) s = floor;
                if (!(s > 0.0f)) return 1;
                Ri[i] = dh_sqrt_f32(s);
            }
        }
    }
    return 0;
}

/* squared norm of column c of L^-1 (L packed, m x m) by forward
 * substitution, x (m floats) as scratch */
static DH_NOINLINE float dls_inv_col(const float *A, uint32_t m, uint32_t c, float *x)
{
    uint32_t i, k;
    float t = 0.0f;
    for (i = c; i < m; i++) {
        const float *Ri = &A[i * (i + 1u) / 2u];
        float s = (i == c) ? 1.0f : 0.0f;
        for (k = c; k < i; k++) s -= Ri[k] * x[k];
        x[i] = s / Ri[i];
        t += x[i] * x[i];
    }
    return t;
}

/* ||L^-1||_F^2: the columns' squares summed (scratch after the matrix) */
DH_INLINE float dls_inv_sum(float *A, uint32_t m)
{
    uint32_t c;
    float t = 0.0f;
    for (c = 0u; c < m; c++) t += dls_inv_col(A, m, c, &A[21]);
    return t;
}

/* y = A^-1 e with the packed factor L of A (6 x 6): L z = e, L^T y = z */
static DH_NOINLINE void dls_solve(const float *A, const float *e, float *y)
{
    uint32_t i, k;
    for (i = 0u; i < 6u; i++) {
        const float *Ri = &A[i * (i + 1u) / 2u];
        float t = e[i];
        for (k = 0u; k < i; k++) t -= Ri[k] * y[k];
        y[i] = t / Ri[i];
    }
    i = 6u;
    while (i > 0u) {
        float t;
        i--;
        t = y[i];
        for (k = i + 1u; k < 6u; k++) t -= A[k * (k + 1u) / 2u + i] * y[k];
        y[i] = t / A[i * (i + 1u) / 2u + i];
    }
}

/* dq = J^T y in joint units (degrees for revolute joints) */
static DH_NOINLINE void dls_joint(const dh_robot *r, const float *J, const float *y, float *dq)
{
    const uint32_t n = r->n;
    uint32_t i, k;
    for (k = 0u; k < n; k++) {
        float v = 0.0f;
        for (i = 0u; i < 6u; i++) v += J[i * n + k] * y[i];
        if (r->joint[k].type == DH_JOINT_REVOLUTE) v *= DH_RAD2DEG_F;
        dq[k] = v;
    }
}

static int dls_finite(const float *x, uint32_t len)
{
    uint32_t i;
    float s = 0.0f;
    for (i = 0u; i < len; i++) s += x[i] * 0.0f; /* NaN when any x[i] is NaN or Inf */
    return dh_feq_f32(s, 0.0f);
}

/* the body of both entry points (inlined, as dls_step_body) */
DH_INLINE dh_status dls_manip_body(const float *J, uint32_t n, float *w, float *sigma_min, float *ws)
{
    float *const A = ws;
    float tr, wv, tinv, lb;
    uint32_t m;
    DH_ASSERT(J != NULL);
    if (n == 0u || n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    if (!dls_finite(J, 6u * n)) return DH_ERR_NAN;
    m = (n >= 6u) ? 6u : n;
    dls_normal(J, n, n >= 6u, A);
    tr = dls_diag(A, m, 0);
    if (!dh_isfinite_f32(tr)) return DH_ERR_OVERFLOW;
    if (dls_chol(A, m, 0.0f) != 0) {
        wv = 0.0f;
        lb = 0.0f;
    } else {
        tinv = dls_inv_sum(A, m);
        wv = dls_diag(A, m, 1);
        lb = (1.0f - 0.00390625f) / tinv - 32.0f * DLS_U * tr;
    }
    if (!dh_isfinite_f32(wv)) return DH_ERR_OVERFLOW;
    if (w != NULL) *w = wv;
    if (sigma_min != NULL) *sigma_min = (lb > 0.0f) ? dh_sqrt_f32(lb) : 0.0f;
    return DH_OK;
}

/* the body of both entry points (inlined: the public one keeps the matrix
 * in its own frame, one call level less) */
DH_INLINE dh_status dls_step_body(const dh_robot *r, const float *J, const float *e, float lambda, const float *dq_max,
                                  float *dq, float *ws)
{
    float *const A = ws, *const y = ws + 21;
    float tr, l2, s = 1.0f;
    uint32_t n, i, k;
    DH_ASSERT(r != NULL);
    DH_ASSERT(J != NULL);
    DH_ASSERT(e != NULL);
    DH_ASSERT(dq != NULL);
    n = r->n;
    if (n == 0u || n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    if (!dh_feq_f32(lambda, lambda)) return DH_ERR_NAN;
    if (!(lambda >= 0.0f) || !dh_isfinite_f32(lambda)) return DH_ERR_ARG;
    if (dq_max != NULL)
        for (k = 0u; k < n; k++)
            if (!(dq_max[k] >= 0.0f)) return DH_ERR_ARG;
    if (!dls_finite(J, 6u * n) || !dls_finite(e, 6u)) return DH_ERR_NAN;
    dls_normal(J, n, 1, A);
    tr = dls_diag(A, 6u, 0);
    l2 = lambda * lambda;
    for (i = 0u; i < 6u; i++) A[i * (i + 1u) / 2u + i] += l2;
    if (!dh_isfinite_f32(tr + l2 * 6.0f)) return DH_ERR_OVERFLOW;
    /* lambda == 0: a pivot within rounding of 0 is a singular J J^T */
    if (dls_chol(A, 6u, l2) != 0) {
        for (k = 0u; k < n; k++) dq[k] = 0.0f;
        return DH_ERR_SINGULAR;
    }
    if (!(l2 > 0.0f)) {
        for (i = 0u; i < 6u; i++) {
            const float p = A[i * (i + 1u) / 2u + i];
            if (!(p * p > 64.0f * DLS_U * tr)) {
                for (k = 0u; k < n; k++) dq[k] = 0.0f;
                return DH_ERR_SINGULAR;
            }
        }
    }
    dls_solve(A, e, y);
    dls_joint(r, J, y, dq);
    if (!dls_finite(dq, n)) {
        for (k = 0u; k < n; k++) dq[k] = 0.0f;
        return DH_ERR_OVERFLOW;
    }
    if (dq_max != NULL) {
        for (k = 0u; k < n; k++) {
            const float a = (dq[k] < 0.0f) ? -dq[k] : dq[k];
            if (a * s > dq_max[k]) s = dq_max[k] / a;
        }
        for (k = 0u; k < n; k++) {
            float v = dq[k] * s;
            /* the rounding of the product may pass the bound by an ulp */
            if (v > dq_max[k]) v = dq_max[k];
            if (v < -dq_max[k]) v = -dq_max[k];
            dq[k] = v;
        }
    }
    return DH_OK;
}

dh_status dh_manipulability_ws_f32_(const float *J, uint32_t n, float *w, float *sigma_min, float *ws)
{
    return dls_manip_body(J, n, w, sigma_min, ws);
}

dh_status dh_manipulability_f32(const float *J, uint32_t n, float *w, float *sigma_min)
{
    float ws[DH_DLS_WS_FLOATS];
    return dls_manip_body(J, n, w, sigma_min, ws);
}

dh_status dh_dls_step_ws_f32_(const dh_robot *r, const float *J, const float *e, float lambda, const float *dq_max,
                              float *dq, float *ws)
{
    return dls_step_body(r, J, e, lambda, dq_max, dq, ws);
}

dh_status dh_dls_step_f32(const dh_robot *r, const float *J, const float e[6], float lambda, const float *dq_max,
                          float *dq)
{
    float ws[DH_DLS_WS_FLOATS];
    return dls_step_body(r, J, e, lambda, dq_max, dq, ws);
}
