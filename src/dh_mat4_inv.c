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

/* 2^e as a float for a biased exponent field 1..254 */
static float dh_pow2_biased(uint32_t biased)
{
    float f;
    const uint32_t bits = biased << 23;
    memcpy(&f, &bits, sizeof f);
    return f;
}

dh_status dh_mat4_inv_f32(dh_mat4_f32 *out, const dh_mat4_f32 *T)
{
    uint32_t bits[16];
    uint32_t mx = 0u, e;
    float s = 1.0f;
    float a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, a30, a31, a32, a33;
    float s0, s1, s2, s3, s4, s5, c0, c1, c2, c3, c4, c5, det, f, na, nb, t;
    float b[4][4]; /* adjugate, column-major like the matrices */
    int i, r;

    DH_ASSERT(out != NULL && T != NULL);

    /* largest |element| from the bit patterns: the ordering of non-negative
     * floats equals the ordering of their bits; NaN and Inf are the
     * patterns >= 0x7f800000. */
    memcpy(bits, T->m, sizeof bits);
    for (i = 0; i < 16; i++) {
        const uint32_t v = bits[i] & 0x7fffffffu;
        mx = (v > mx) ? v : mx;
    }
    if (mx >= 0x7f800000u) return DH_ERR_NAN;
    if (mx < 0x00800000u) return DH_ERR_SINGULAR; /* zero or denormal matrix */
    e = mx >> 23; /* biased exponent of the largest element, 1..254 */
    if (e < 127u - 16u || e > 127u + 16u) {
        /* exact power-of-two scaling to bring the largest element into
         * [1, 2) (or [2, 4) for the very top binade) */
        s = dh_pow2_biased((e >= 254u) ? 1u : 254u - e);
    }

    /* a_rc = s * T(row r, col c) */
    a00 = T->m[0][0] * s; a10 = T->m[0][1] * s; a20 = T->m[0][2] * s; a30 = T->m[0][3] * s;
    a01 = T->m[1][0] * s; a11 = T->m[1][1] * s; a21 = T->m[1][2] * s; a31 = T->m[1][3] * s;
    a02 = T->m[2][0] * s; a12 = T->m[2][1] * s; a22 = T->m[2][2] * s; a32 = T->m[2][3] * s;
    a03 = T->m[3][0] * s; a13 = T->m[3][1] * s; a23 = T->m[3][2] * s; a33 = T->m[3][3] * s;

    /* 2x2 minors of rows 0,1 (s*) and rows 2,3 (c*), by column pairs */
    s0 = a00 * a11 - a10 * a01;
    s1 = a00 * a12 - a10 * a02;
    s2 = a00 * a13 - a10 * a03;
    s3 = a01 * a12 - a11 * a02;
    s4 = a01 * a13 - a11 * a03;
    s5 = a02 * a13 - a12 * a03;
    c0 = a20 * a31 - a30 * a21;
    c1 = a20 * a32 - a30 * a22;
    c2 = a20 * a33 - a30 * a23;
    c3 = a21 * a32 - a31 * a22;
    c4 = a21 * a33 - a31 * a23;
    c5 = a22 * a33 - a32 * a23;

    /* Laplace expansion along rows 0,1 */
    det = s0 * c5 - s1 * c4 + s2 * c3 + s3 * c2 - s4 * c1 + s5 * c0;

    /* adjugate: b[c][r] = element (row r, col c) of adj(A) */
    b[0][0] =  a11 * c5 - a12 * c4 + a13 * c3;
    b[0][1] = -a10 * c5 + a12 * c2 - a13 * c1;
    b[0][2] =  a10 * c4 - a11 * c2 + a13 * c0;
    b[0][3] = -a10 * c3 + a11 * c1 - a12 * c0;
    b[1][0] = -a01 * c5 + a02 * c4 - a03 * c3;
    b[1][1] =  a00 * c5 - a02 * c2 + a03 * c1;
    b[1][2] = -a00 * c4 + a01 * c2 - a03 * c0;
    b[1][3] =  a00 * c3 - a01 * c1 + a02 * c0;
    b[2][0] =  a31 * s5 - a32 * s4 + a33 * s3;
    b[2][1] = -a30 * s5 + a32 * s2 - a33 * s1;
    b[2][2] =  a30 * s4 - a31 * s2 + a33 * s0;
    b[2][3] = -a30 * s3 + a31 * s1 - a32 * s0;
    b[3][0] = -a21 * s5 + a22 * s4 - a23 * s3;
    b[3][1] =  a20 * s5 - a22 * s2 + a23 * s1;
    b[3][2] = -a20 * s4 + a21 * s2 - a23 * s0;
    b[3][3] =  a20 * s3 - a21 * s1 + a22 * s0;

    /* infinity norms (max row sum) of A and adj(A) */
    na = 0.0f;
    nb = 0.0f;
    for (r = 0; r < 4; r++) {
        const float ra = fabsf(T->m[0][r] * s) + fabsf(T->m[1][r] * s) + fabsf(T->m[2][r] * s) +
                         fabsf(T->m[3][r] * s);
        const float rb = fabsf(b[0][r]) + fabsf(b[1][r]) + fabsf(b[2][r]) + fabsf(b[3][r]);
        na = (ra > na) ? ra : na;
        nb = (rb > nb) ? rb : nb;
    }
    /* cond_inf = na * nb / |det| >= DH_MAT4_COND_MAX  <=>  singular.
     * The scaled values are O(1), so neither side can overflow. */
    if (na * nb >= DH_MAT4_COND_MAX * fabsf(det)) return DH_ERR_SINGULAR;

    /* inverse of T = s * adj(A) / det(A); "+ 0.0f" maps -0 to +0 */
    f = s / det;
    t = 0.0f;
    for (i = 0; i < 4; i++) {
        for (r = 0; r < 4; r++) {
            b[i][r] = b[i][r] * f + 0.0f;
            t = (fabsf(b[i][r]) > t) ? fabsf(b[i][r]) : t;
        }
    }
    if (!dh_finite(t)) return DH_ERR_OVERFLOW;
    for (i = 0; i < 4; i++) {
        for (r = 0; r < 4; r++) out->m[i][r] = b[i][r];
    }
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
