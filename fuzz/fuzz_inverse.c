/* SPDX-License-Identifier: Apache-2.0 */
/*
 * fuzz_inverse.c - general 4x4 inverse dh_mat4_inv_f32 and the automatic
 * choice dh_mat4_inv_auto_f32 (mat4.h) on arbitrary and structured
 * matrices.
 *
 * Invariants:
 *  - status is DH_OK, DH_ERR_NAN (exactly when an element is NaN/Inf),
 *    DH_ERR_SINGULAR or DH_ERR_OVERFLOW; out untouched on error; out == T
 *    (aliasing) gives the same bits and status;
 *  - DH_OK: every element finite, and the result carries its promised
 *    proof of non-singularity: some induced norm (the 1-norm or inf-norm
 *    of D^-1 R D, D = diag(1,1,1,s), s = 2^k for k = -240..240 and the
 *    Osborne factor sqrt(|q|_1 / |p|_1) of T: any such similarity gives a
 *    valid norm) of the right residual R = T X - I or of the left residual
 *    R = X T - I, evaluated in double, is < 1 -- so T is never singular
 *    when DH_OK is returned. Either side is a proof (T X or X T singular
 *    would give R the eigenvalue -1). The library certifies the right
 *    residual (Gauss-Jordan on the rows of its column-major storage, i.e.
 *    on T^T); for cond near the limit 2^19 the left residual of a correct
 *    inverse can exceed 1 (it is up to cond times the right one), so
 *    demanding the left one alone was wrong (fuzz/corpus/fuzz_inverse/
 *    proj_1e35_right_residual: right 0.0055, left 1.7, X within
 *    0.02 cond u of T^-1);
 *  - affine T (bottom row exactly 0 0 0 1) whose 3x3 part A has
 *    max(||A||,1) max(||A^-1||,1) < 2^12 (1-norms, double) and a normal
 *    largest element >= 2^-60 is accepted (the balanced condition number
 *    of such T tends to that product, far below DH_MAT4_COND_MAX = 2^19),
 *    and then |X - T^-1| <= 5.5 * cond * 2^-24 * max|T^-1| + 4.3 * 2^-24
 *    * (1 + |p|_1) * max(1, ||A^-1||), the contract's measured figures
 *    (general and rigid) combined;
 *  - dh_mat4_inv_auto_f32: when dh_mat4_check_rigid_f32(T, DH_MAT4_RIGID_TOL)
 *    accepts T it returns DH_OK with the bits of dh_mat4_inv_rigid_f32,
 *    otherwise exactly what dh_mat4_inv_f32 returns.
 * Input: mode byte (0: 16 raw floats; 1: affine with A of random
 * mantissas/exponents; 2: rigid from an axis, angle and translation scaled
 * by 2^e; 3: mode 1 with the third column replaced by a combination of the
 * first two, i.e. numerically singular), then numbers.
 */
#include <float.h>
#include <math.h>

#include "dhmath/mat4.h"
#include "fuzz_common.h"

#define U24 5.9604644775390625e-8

typedef double m4d[4][4]; /* [row][col] */

/* Gauss-Jordan with partial pivoting in double; returns 0 if singular */
static int inv_d(const m4d A, m4d X, int n)
{
    double M[4][8];
    int i, j, k;
    for (i = 0; i < n; i++)
        for (j = 0; j < n; j++) {
            M[i][j] = A[i][j];
            M[i][n + j] = (i == j) ? 1.0 : 0.0;
        }
    for (k = 0; k < n; k++) {
        int p = k;
        for (i = k + 1; i < n; i++)
            if (fabs(M[i][k]) > fabs(M[p][k])) p = i;
        if (M[p][k] == 0.0) return 0;
        if (p != k)
            for (j = 0; j < 2 * n; j++) {
                const double t = M[p][j];
                M[p][j] = M[k][j];
                M[k][j] = t;
            }
        for (i = 0; i < n; i++) {
            if (i == k) continue;
            {
                const double f = M[i][k] / M[k][k];
                for (j = 0; j < 2 * n; j++) M[i][j] -= f * M[k][j];
            }
        }
    }
    for (i = 0; i < n; i++)
        for (j = 0; j < n; j++) X[i][j] = M[i][n + j] / M[i][i];
    return 1;
}

static double norm1_d(const m4d A, int n, double s) /* 1-norm of D^-1 A D, D = diag(1,..,1,s) */
{
    double w = 0.0;
    int i, j;
    for (j = 0; j < n; j++) {
        double c = 0.0;
        for (i = 0; i < n; i++) {
            double v = fabs(A[i][j]);
            if (n == 4 && i == 3 && j != 3) v /= s;
            if (n == 4 && j == 3 && i != 3) v *= s;
            c += v;
        }
        if (c > w) w = c;
    }
    return w;
}

static double norminf_d(const m4d A, double s) /* inf-norm of D^-1 A D, D = diag(1,1,1,s) */
{
    double w = 0.0;
    int i, j;
    for (i = 0; i < 4; i++) {
        double r = 0.0;
        for (j = 0; j < 4; j++) {
            double v = fabs(A[i][j]);
            if (i == 3 && j != 3) v /= s;
            if (j == 3 && i != 3) v *= s;
            r += v;
        }
        if (r > w) w = r;
    }
    return w;
}

/* smallest of the balanced 1- and inf-norms of R over the scalings tried
 * (every one an induced norm, so any value < 1 proves non-singularity) */
static double proof_norm(const m4d R, double sg)
{
    double best = fmin(norm1_d(R, 4, sg), norminf_d(R, sg));
    int k;
    for (k = -240; k <= 240; k++) {
        const double s = ldexp(1.0, k);
        best = fmin(best, fmin(norm1_d(R, 4, s), norminf_d(R, s)));
    }
    return best;
}

static void to_d(m4d A, const dh_mat4_f32 *T)
{
    int r, c;
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++) A[r][c] = (double)DH_M4(T, r, c);
}

static double ranged(fz_in *in, int emin, int emax) /* mantissa in [-1, 1] times 2^[emin, emax] */
{
    const double m = fz_unit(in);
    const int e = emin + (int)(fz_u8(in) % (unsigned)(emax - emin + 1));
    return ldexp(m, e);
}

static void build(fz_in *in, unsigned mode, dh_mat4_f32 *T)
{
    int r, c;
    dh_mat4_identity_f32(T);
    if (mode == 0u) {
        for (c = 0; c < 4; c++)
            for (r = 0; r < 4; r++) T->m[c][r] = fz_f32_bits(in);
        return;
    }
    if (mode == 2u) {
        const double kx = fz_unit(in), ky = fz_unit(in), kz = fz_unit(in), t = fz_unit(in) * 3.14159265358979;
        const double n = sqrt(kx * kx + ky * ky + kz * kz);
        const double x = n > 0 ? kx / n : 0, y = n > 0 ? ky / n : 0, z = n > 0 ? kz / n : 1;
        const double co = cos(t), s = sin(t), v = 1 - co;
        const int e = (int)(fz_u8(in) % 64u) - 20;
        DH_M4(T, 0, 0) = (float)(x * x * v + co); DH_M4(T, 0, 1) = (float)(x * y * v - z * s); DH_M4(T, 0, 2) = (float)(x * z * v + y * s);
        DH_M4(T, 1, 0) = (float)(x * y * v + z * s); DH_M4(T, 1, 1) = (float)(y * y * v + co); DH_M4(T, 1, 2) = (float)(y * z * v - x * s);
        DH_M4(T, 2, 0) = (float)(x * z * v - y * s); DH_M4(T, 2, 1) = (float)(y * z * v + x * s); DH_M4(T, 2, 2) = (float)(z * z * v + co);
        for (r = 0; r < 3; r++) DH_M4(T, r, 3) = (float)ldexp(fz_unit(in), e);
        return;
    }
    {
        const int e0 = (int)(fz_u8(in) % 200u) - 100; /* common scale of A */
        for (r = 0; r < 3; r++)
            for (c = 0; c < 3; c++) DH_M4(T, r, c) = (float)ranged(in, e0 - 8, e0 + 8);
        for (r = 0; r < 3; r++) DH_M4(T, r, 3) = (float)ranged(in, -40, 40);
        if (mode == 3u) {
            const double a = fz_unit(in), b = fz_unit(in);
            for (r = 0; r < 3; r++)
                DH_M4(T, r, 2) = (float)(a * (double)DH_M4(T, r, 0) + b * (double)DH_M4(T, r, 1));
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in;
    dh_mat4_f32 T, X, S, Y;
    dh_status st, st2;
    unsigned mode;
    int r, c, finite = 1, affine;

    in.p = data;
    in.n = size;
    mode = fz_u8(&in) % 4u;
    build(&in, mode, &T);
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++)
            if (!isfinite(T.m[c][r])) finite = 0;
    affine = finite && DH_M4(&T, 3, 0) == 0.0f && DH_M4(&T, 3, 1) == 0.0f && DH_M4(&T, 3, 2) == 0.0f &&
             DH_M4(&T, 3, 3) == 1.0f;

    memset(&S, 0x6b, sizeof S);
    X = S;
    st = dh_mat4_inv_f32(&T, &X);
    FZ_CHECK(st == DH_OK || st == DH_ERR_NAN || st == DH_ERR_SINGULAR || st == DH_ERR_OVERFLOW, "status %d", (int)st);
    FZ_CHECK((st == DH_ERR_NAN) == !finite, "status %d for %s input", (int)st, finite ? "finite" : "non-finite");
    Y = T;
    st2 = dh_mat4_inv_f32(&Y, &Y);
    FZ_CHECK(st2 == st && memcmp(&Y, st == DH_OK ? &X : &T, sizeof Y) == 0, "in-place inverse differs");
    if (st != DH_OK) {
        FZ_CHECK(memcmp(&X, &S, sizeof X) == 0, "out written on error %d", (int)st);
    } else {
        m4d Td, Xd, Rl, Rr;
        double left, right, sg = 1.0, pn = 0.0, qn = 0.0;
        int i, j, k;
        for (c = 0; c < 4; c++)
            for (r = 0; r < 4; r++) FZ_CHECK(isfinite(X.m[c][r]), "DH_OK with non-finite element");
        to_d(Td, &T);
        to_d(Xd, &X);
        for (i = 0; i < 4; i++)
            for (j = 0; j < 4; j++) {
                Rl[i][j] = (i == j) ? -1.0 : 0.0;
                Rr[i][j] = Rl[i][j];
                for (k = 0; k < 4; k++) {
                    Rl[i][j] += Xd[i][k] * Td[k][j];
                    Rr[i][j] += Td[i][k] * Xd[k][j];
                }
            }
        for (i = 0; i < 3; i++) {
            pn += fabs(Td[i][3]);
            qn += fabs(Td[3][i]);
        }
        /* norm1_d multiplies p by sg and divides q by it: Osborne's
         * balance (|p| sg = |q| / sg) is sg = sqrt(|q| / |p|) */
        if (pn > 0.0 && qn > 0.0) sg = sqrt(qn) / sqrt(pn);
        right = proof_norm(Rr, sg);
        left = (right < 1.0) ? right : proof_norm(Rl, sg);
        FZ_CHECK(right < 1.0 || left < 1.0,
                 "DH_OK without a proof of non-singularity: min norm of TX - I = %.3g, of XT - I = %.3g (mode %u)",
                 right, left, mode);
    }

    /* affine, well conditioned: must invert, within the measured figures */
    if (affine) {
        m4d A, Ai, Td, Ti;
        double mx = 0.0;
        for (r = 0; r < 4; r++)
            for (c = 0; c < 4; c++) {
                A[r][c] = (double)DH_M4(&T, r, c);
                if (fabs(A[r][c]) > mx) mx = fabs(A[r][c]);
            }
        if (mx >= 0x1p-60 && inv_d(A, Ai, 3)) {
            const double nA = norm1_d(A, 3, 1.0), nAi = norm1_d(Ai, 3, 1.0);
            const double cond = fmax(nA, 1.0) * fmax(nAi, 1.0);
            if (cond < 4096.0) {
                double maxinv = 0.0, p1, worst = 0.0, bound;
                to_d(Td, &T);
                FZ_CHECK(inv_d(Td, Ti, 4), "double inverse");
                /* the inverse's translation -R^-1 p may not fit a float even
                 * for a well-conditioned R: then DH_ERR_OVERFLOW is the
                 * documented answer */
                for (r = 0; r < 4; r++)
                    for (c = 0; c < 4; c++)
                        if (fabs(Ti[r][c]) > maxinv) maxinv = fabs(Ti[r][c]);
                if (!(maxinv >= 0x1p126 && st == DH_ERR_OVERFLOW)) {
                maxinv = 0.0;
                FZ_CHECK(st == DH_OK, "well-conditioned affine matrix (cond %.3g) rejected: %d (mode %u)", cond, (int)st,
                         mode);
                p1 = fabs(Td[0][3]) + fabs(Td[1][3]) + fabs(Td[2][3]);
                for (r = 0; r < 4; r++)
                    for (c = 0; c < 4; c++)
                        if (fabs(Ti[r][c]) > maxinv) maxinv = fabs(Ti[r][c]);
                for (r = 0; r < 4; r++)
                    for (c = 0; c < 4; c++) {
                        const double e = fabs((double)DH_M4(&X, r, c) - Ti[r][c]);
                        if (e > worst) worst = e;
                    }
                bound = 5.5 * cond * U24 * maxinv + 4.3 * U24 * (1.0 + p1) * fmax(1.0, nAi);
                FZ_CHECK(worst <= bound, "affine inverse error %.3g > %.3g (cond %.3g, |p| %.3g, mode %u)", worst, bound,
                         cond, p1, mode);
                }
            }
        }
    }

    /* automatic choice */
    {
        dh_mat4_f32 Z, W;
        dh_status sa;
        memset(&Z, 0x6b, sizeof Z);
        sa = dh_mat4_inv_auto_f32(&T, &Z);
        if (finite && dh_mat4_check_rigid_f32(&T, DH_MAT4_RIGID_TOL) == DH_OK) {
            dh_mat4_inv_rigid_f32(&T, &W);
            FZ_CHECK(sa == DH_OK && memcmp(&Z, &W, sizeof Z) == 0, "inv_auto of a rigid T: %d / not the rigid inverse",
                     (int)sa);
        } else {
            FZ_CHECK(sa == st && memcmp(&Z, st == DH_OK ? &X : &S, sizeof Z) == 0,
                     "inv_auto %d differs from inv_f32 %d", (int)sa, (int)st);
        }
    }
    return 0;
}
