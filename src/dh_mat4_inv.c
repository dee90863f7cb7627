/*
 * dh_mat4_inv.c - inverses of float 4x4 transforms (seed 000, sec. 11):
 * the closed-form rigid inverse (eq. 1.57), a general inverse with a
 * scale-invariant singularity test, rigidity checks and the automatic
 * choice between the two inverses.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "dhmath/dh_mat4.h"

static int dh_finite(float x) { return fabsf(x) <= FLT_MAX; }

/* ---------------------------------------------------------------------- */
/* rigid inverse                                                          */
/* ---------------------------------------------------------------------- */

void dh_mat4_inv_rigid_f32(dh_mat4_f32 *out, const dh_mat4_f32 *T)
{
    float nx, ny, nz, ox, oy, oz, ax, ay, az, px, py, pz;
    DH_ASSERT(out != NULL && T != NULL);
    nx = T->m[0][0]; ny = T->m[0][1]; nz = T->m[0][2];
    ox = T->m[1][0]; oy = T->m[1][1]; oz = T->m[1][2];
    ax = T->m[2][0]; ay = T->m[2][1]; az = T->m[2][2];
    px = T->m[3][0]; py = T->m[3][1]; pz = T->m[3][2];
    /* eq. 1.57: rows of the inverse are n, o, a; column p is -R^T p.
     * 0 - dot (not -dot) keeps an exact zero positive. */
    out->m[0][0] = nx; out->m[0][1] = ox; out->m[0][2] = ax; out->m[0][3] = 0.0f;
    out->m[1][0] = ny; out->m[1][1] = oy; out->m[1][2] = ay; out->m[1][3] = 0.0f;
    out->m[2][0] = nz; out->m[2][1] = oz; out->m[2][2] = az; out->m[2][3] = 0.0f;
    out->m[3][0] = 0.0f - (px * nx + py * ny + pz * nz);
    out->m[3][1] = 0.0f - (px * ox + py * oy + pz * oz);
    out->m[3][2] = 0.0f - (px * ax + py * ay + pz * az);
    out->m[3][3] = 1.0f;
}

/* ---------------------------------------------------------------------- */
/* general inverse                                                        */
/* ---------------------------------------------------------------------- */

/*
 * The helpers below treat the storage m[i][j] as ROW i, COLUMN j of a
 * matrix M. For a dh_mat4_f32 (column-major) that M is T^T. Since
 * (T^T)^-1 = (T^-1)^T, inverting M in this view and storing the result the
 * same way yields T^-1 in the library's column-major layout, with no
 * transposition. Norms and residuals of M are the 1-norms and the right
 * residual T X - I of T.
 */

/* Unit roundoff of float, 2^-24. */
#define DH_U24 5.9604644775390625e-8f

/* max_i sum_j |M(i, j)| (= ||T||_1) */
static float dh_norm_rows(const dh_mat4_f32 *M)
{
    float n = 0.0f;
    int i;
    for (i = 0; i < 4; i++) {
        const float rs = fabsf(M->m[i][0]) + fabsf(M->m[i][1]) + fabsf(M->m[i][2]) + fabsf(M->m[i][3]);
        n = (rs > n) ? rs : n;
    }
    return n;
}

/* ||X M - I||inf in the row view (row i of X M is the combination of the
 * rows of M with the weights of row i of X) */
static float dh_residual(const dh_mat4_f32 *X, const dh_mat4_f32 *M)
{
    float res = 0.0f;
    int i, j;
    for (i = 0; i < 4; i++) {
        float q[4], rs;
        for (j = 0; j < 4; j++) {
            q[j] = X->m[i][0] * M->m[0][j] + X->m[i][1] * M->m[1][j] + X->m[i][2] * M->m[2][j] +
                   X->m[i][3] * M->m[3][j];
        }
        q[i] -= 1.0f;
        rs = fabsf(q[0]) + fabsf(q[1]) + fabsf(q[2]) + fabsf(q[3]);
        res = (rs > res) ? rs : res;
    }
    return res;
}

/*
 * Adjugate / determinant (Laplace expansion by the 2x2 minors of rows 0,1
 * and rows 2,3 of M): straight-line and vector friendly, accurate for well
 * conditioned matrices. Writes X = M^-1 and returns 1, or returns 0 when
 * det == 0 (X then unchanged).
 */
static int dh_inv_cofactor(const dh_mat4_f32 *M, dh_mat4_f32 *X)
{
    const float (*a)[4] = M->m;
    float (*x)[4] = X->m;
    float s0, s1, s2, s3, s4, s5, c0, c1, c2, c3, c4, c5, det, f;
    int i, j;
    s0 = a[0][0] * a[1][1] - a[1][0] * a[0][1];
    s1 = a[0][0] * a[1][2] - a[1][0] * a[0][2];
    s2 = a[0][0] * a[1][3] - a[1][0] * a[0][3];
    s3 = a[0][1] * a[1][2] - a[1][1] * a[0][2];
    s4 = a[0][1] * a[1][3] - a[1][1] * a[0][3];
    s5 = a[0][2] * a[1][3] - a[1][2] * a[0][3];
    c5 = a[2][2] * a[3][3] - a[3][2] * a[2][3];
    c4 = a[2][1] * a[3][3] - a[3][1] * a[2][3];
    c3 = a[2][1] * a[3][2] - a[3][1] * a[2][2];
    c2 = a[2][0] * a[3][3] - a[3][0] * a[2][3];
    c1 = a[2][0] * a[3][2] - a[3][0] * a[2][2];
    c0 = a[2][0] * a[3][1] - a[3][0] * a[2][1];
    det = s0 * c5 - s1 * c4 + s2 * c3 + s3 * c2 - s4 * c1 + s5 * c0;
    if (det == 0.0f) return 0;
    x[0][0] =  a[1][1] * c5 - a[1][2] * c4 + a[1][3] * c3;
    x[0][1] = -a[0][1] * c5 + a[0][2] * c4 - a[0][3] * c3;
    x[0][2] =  a[3][1] * s5 - a[3][2] * s4 + a[3][3] * s3;
    x[0][3] = -a[2][1] * s5 + a[2][2] * s4 - a[2][3] * s3;
    x[1][0] = -a[1][0] * c5 + a[1][2] * c2 - a[1][3] * c1;
    x[1][1] =  a[0][0] * c5 - a[0][2] * c2 + a[0][3] * c1;
    x[1][2] = -a[3][0] * s5 + a[3][2] * s2 - a[3][3] * s1;
    x[1][3] =  a[2][0] * s5 - a[2][2] * s2 + a[2][3] * s1;
    x[2][0] =  a[1][0] * c4 - a[1][1] * c2 + a[1][3] * c0;
    x[2][1] = -a[0][0] * c4 + a[0][1] * c2 - a[0][3] * c0;
    x[2][2] =  a[3][0] * s4 - a[3][1] * s2 + a[3][3] * s0;
    x[2][3] = -a[2][0] * s4 + a[2][1] * s2 - a[2][3] * s0;
    x[3][0] = -a[1][0] * c3 + a[1][1] * c1 - a[1][2] * c0;
    x[3][1] =  a[0][0] * c3 - a[0][1] * c1 + a[0][2] * c0;
    x[3][2] = -a[3][0] * s3 + a[3][1] * s1 - a[3][2] * s0;
    x[3][3] =  a[2][0] * s3 - a[2][1] * s1 + a[2][2] * s0;
    f = 1.0f / det;
    for (i = 0; i < 4; i++) {
        for (j = 0; j < 4; j++) x[i][j] *= f;
    }
    return 1;
}

/*
 * In-place Gauss-Jordan with partial pivoting on the rows of M (i.e. on
 * the columns of T): X becomes X^-1. Returns 0 on an exactly zero pivot
 * (X then undefined).
 */
static int dh_inv_gauss_jordan(dh_mat4_f32 *X)
{
    float (*x)[4] = X->m;
    unsigned char perm[4];
    int i, j, k;
    for (k = 0; k < 4; k++) {
        int p = k;
        float big = fabsf(x[k][k]), r;
        for (i = k + 1; i < 4; i++) {
            if (fabsf(x[i][k]) > big) {
                big = fabsf(x[i][k]);
                p = i;
            }
        }
        if (big == 0.0f) return 0;
        perm[k] = (unsigned char)p;
        if (p != k) {
            for (j = 0; j < 4; j++) {
                const float tmp = x[k][j];
                x[k][j] = x[p][j];
                x[p][j] = tmp;
            }
        }
        r = 1.0f / x[k][k];
        x[k][k] = 1.0f;
        for (j = 0; j < 4; j++) x[k][j] *= r;
        for (i = 0; i < 4; i++) {
            if (i != k) {
                const float f = x[i][k];
                x[i][k] = 0.0f;
                for (j = 0; j < 4; j++) x[i][j] -= f * x[k][j];
            }
        }
    }
    /* undo the interchanges on the columns, last first */
    for (k = 3; k >= 0; k--) {
        const int p = perm[k];
        if (p != k) {
            for (i = 0; i < 4; i++) {
                const float tmp = x[i][k];
                x[i][k] = x[i][p];
                x[i][p] = tmp;
            }
        }
    }
    return 1;
}

dh_status dh_mat4_inv_f32(dh_mat4_f32 *out, const dh_mat4_f32 *T)
{
    dh_mat4_f32 A;          /* s * T when T needs scaling */
    dh_mat4_f32 X;          /* the inverse being built */
    const dh_mat4_f32 *M = T;
    float m4[4] = { 0.0f, 0.0f, 0.0f, 0.0f }, z4[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
    float mx, z, s = 1.0f, na, nx;
    uint32_t e;
    int i, j;

    DH_ASSERT(out != NULL && T != NULL);

    /* Lane-wise (vector-shaped) scan: z is NaN iff an element is NaN or
     * Inf (x * 0 is NaN exactly for those); mx = max |T_ij|. */
    for (i = 0; i < 4; i++) {
        for (j = 0; j < 4; j++) {
            const float v = fabsf(T->m[i][j]);
            z4[j] += T->m[i][j] * 0.0f;
            m4[j] = (v > m4[j]) ? v : m4[j];
        }
    }
    z = (z4[0] + z4[1]) + (z4[2] + z4[3]);
    mx = (m4[0] > m4[1]) ? m4[0] : m4[1];
    mx = (m4[2] > mx) ? m4[2] : mx;
    mx = (m4[3] > mx) ? m4[3] : mx;
    if (z != z) return DH_ERR_NAN;
    if (mx < FLT_MIN) return DH_ERR_SINGULAR; /* zero or denormal matrix */
    memcpy(&e, &mx, sizeof e);
    e >>= 23; /* biased exponent of the largest element, 1..254 */
    if (e < 127u - 16u || e > 127u + 16u) {
        /* exact power-of-two scaling that brings the largest element into
         * [1, 2) (or [2, 4) for the very top binade), so that neither the
         * cofactors nor the determinant over- or underflow */
        const uint32_t bits = ((e >= 254u) ? 1u : 254u - e) << 23;
        memcpy(&s, &bits, sizeof s);
        for (i = 0; i < 4; i++) {
            for (j = 0; j < 4; j++) A.m[i][j] = T->m[i][j] * s;
        }
        M = &A;
    }
    na = dh_norm_rows(M);

    /* Fast path: cofactors, accepted when the estimated condition number is
     * below the limit AND the residual is as small as a backward stable
     * method leaves (8 u ||X|| ||M||). Otherwise (ill-conditioned or
     * singular input) Gauss-Jordan with pivoting decides. */
    if (dh_inv_cofactor(M, &X)) {
        nx = dh_norm_rows(&X);
        if (na * nx < DH_MAT4_COND_MAX && dh_residual(&X, M) <= 8.0f * DH_U24 * na * nx) {
            goto accept;
        }
    }
    X = *M;
    if (!dh_inv_gauss_jordan(&X)) return DH_ERR_SINGULAR;
    nx = dh_norm_rows(&X);
    /* (1) estimated condition number */
    if (!(na * nx < DH_MAT4_COND_MAX)) return DH_ERR_SINGULAR;
    /* (2) certificate: ||X M - I|| <= 1/2 proves M non-singular with
     * ||M^-1|| <= 2 ||X||; for a singular M, X M - I has the eigenvalue -1,
     * so the test fails whatever X is (the rounding of the residual is
     * below 4 u na nx < 0.13). */
    if (!(dh_residual(&X, M) <= 0.5f)) return DH_ERR_SINGULAR;

accept:
    /* T^-1 = s X (exact power of two unless it overflows); "+ 0.0f" maps
     * -0 to +0 */
    for (j = 0; j < 4; j++) z4[j] = 0.0f;
    for (i = 0; i < 4; i++) {
        for (j = 0; j < 4; j++) {
            const float v = X.m[i][j] * s + 0.0f;
            X.m[i][j] = v;
            z4[j] += v * 0.0f; /* NaN iff some v overflowed to Inf */
        }
    }
    z = (z4[0] + z4[1]) + (z4[2] + z4[3]);
    if (z != z) return DH_ERR_OVERFLOW;
    *out = X;
    return DH_OK;
}

/* ---------------------------------------------------------------------- */
/* rigidity                                                               */
/* ---------------------------------------------------------------------- */

dh_status dh_mat4_check_rot_f32(const dh_mat4_f32 *T, float tol)
{
    float nx, ny, nz, ox, oy, oz, ax, ay, az, det;
    DH_ASSERT(T != NULL);
    if (!(tol >= 0.0f)) return DH_ERR_ARG;
    nx = T->m[0][0]; ny = T->m[0][1]; nz = T->m[0][2];
    ox = T->m[1][0]; oy = T->m[1][1]; oz = T->m[1][2];
    ax = T->m[2][0]; ay = T->m[2][1]; az = T->m[2][2];
    if (!(dh_finite(nx) && dh_finite(ny) && dh_finite(nz) && dh_finite(ox) && dh_finite(oy) &&
          dh_finite(oz) && dh_finite(ax) && dh_finite(ay) && dh_finite(az))) {
        return DH_ERR_NAN;
    }
    /* R^T R - I (the products of finite entries may overflow to Inf, which
     * then fails the comparisons as it should) */
    if (!(fabsf(nx * nx + ny * ny + nz * nz - 1.0f) <= tol &&
          fabsf(ox * ox + oy * oy + oz * oz - 1.0f) <= tol &&
          fabsf(ax * ax + ay * ay + az * az - 1.0f) <= tol &&
          fabsf(nx * ox + ny * oy + nz * oz) <= tol &&
          fabsf(nx * ax + ny * ay + nz * az) <= tol &&
          fabsf(ox * ax + oy * ay + oz * az) <= tol)) {
        return DH_ERR_NOT_RIGID;
    }
    /* det R = n . (o x a) */
    det = nx * (oy * az - oz * ay) + ny * (oz * ax - ox * az) + nz * (ox * ay - oy * ax);
    if (!(det > 0.0f)) return DH_ERR_NOT_RIGID;
    return DH_OK;
}

dh_status dh_mat4_check_rigid_f32(const dh_mat4_f32 *T, float tol)
{
    DH_ASSERT(T != NULL);
    if (!(tol >= 0.0f)) return DH_ERR_ARG;
    if (!dh_mat4_isfinite_f32(T)) return DH_ERR_NAN;
    if (!(T->m[0][3] == 0.0f && T->m[1][3] == 0.0f && T->m[2][3] == 0.0f && T->m[3][3] == 1.0f)) {
        return DH_ERR_NOT_RIGID;
    }
    return dh_mat4_check_rot_f32(T, tol);
}

dh_status dh_mat4_inv_auto_f32(dh_mat4_f32 *out, const dh_mat4_f32 *T)
{
    dh_status st;
    DH_ASSERT(out != NULL && T != NULL);
    st = dh_mat4_check_rigid_f32(T, DH_MAT4_RIGID_TOL);
    if (st == DH_OK) {
        dh_mat4_inv_rigid_f32(out, T);
        return DH_OK;
    }
    if (st == DH_ERR_NAN) return DH_ERR_NAN;
    return dh_mat4_inv_f32(out, T);
}
