/* SPDX-License-Identifier: Apache-2.0 */
/*
 * fuzz_rotextract.c - rotation extraction (rot.h, mat4.h):
 * angle-axis, Euler (all 24 sequences and invalid ones), quaternion,
 * rotation vector, and re-orthonormalisation.
 *
 * Invariants:
 *  - every extraction returns exactly dh_mat3_check_rot_f32(R, DH_ROT_TOL)
 *    (DH_ERR_NAN / DH_ERR_NOT_RIGID / DH_OK); an invalid Euler sequence
 *    gives DH_ERR_ARG; outputs untouched on error;
 *  - on DH_OK the outputs are finite and in their documented ranges
 *    (angle in [0, 180]; Euler first/third in (-180, 180], middle in
 *    [-90, 90] or [0, 180]; quaternion w >= 0 and never -0, | |q| - 1 |
 *    <= 2.4e-7; | |phi| | <= pi) and they reproduce R: the rotation of the
 *    returned parameters, evaluated in double here, is within
 *    FZ_REPRO_EXACT + FZ_REPRO_K * dev of R per entry, where dev =
 *    max |(R^T R - I)_ij| of the input in double (for an exactly rounded
 *    rotation dev ~ 1e-7 and the contracts promise 4e-7..5e-7; an input
 *    accepted within DH_ROT_TOL is used as it is, so its own distance from
 *    the nearest rotation, about dev / 2, adds up to a small multiple:
 *    measured max (err - 5e-7) / dev = 2.21 over 8.2 million fuzzed
 *    inputs (300 s, all extraction functions), so K = 3);
 *  - the forward conversions of the library applied to the returned
 *    parameters give rotations orthonormal within 1e-6;
 *  - dh_mat4_to_axis_angle_f32 on the same R gives the same bits as
 *    dh_mat3_to_axis_angle_f32;
 *  - dh_mat3_orthonormalize_f32: DH_OK gives max |(X^T X - I)_ij| <= 4e-7
 *    and det > 0; a finite input with dev <= 0.2 and det >= 0.5 must be
 *    accepted; out untouched on error.
 * Input: mode byte (0: nine raw floats; 1: an exact rotation from a random
 * axis and angle rounded to float, plus a perturbation of up to 2^-k per
 * entry, k from the input), Euler sequence byte, then the numbers.
 */
#include <float.h>
#include <math.h>

#include "dhmath/mat4.h"
#include "dhmath/rot.h"
#include "fuzz_common.h"

#define FZ_PI 3.14159265358979323846
#define FZ_REPRO_EXACT 5e-7
#define FZ_REPRO_K 3.0
/* Euler angles: the contract of dh_mat3_to_euler_f32 (rot.h) is 6e-7 per
 * entry for exact rotations (three angles rounded to float degrees; measured
 * 5.1e-7); the fuzzer found yzy (-5.4e-8, 179.999985, 0), 1.5e-5 deg from
 * the pole, at 5.0e-7 + rounding, above the generic 5e-7 */
#define FZ_REPRO_EULER 6e-7

typedef double m3d[3][3]; /* [row][col] */

static void rot_axis_d(m3d R, double kx, double ky, double kz, double rad)
{
    const double n = sqrt(kx * kx + ky * ky + kz * kz);
    const double x = kx / n, y = ky / n, z = kz / n, c = cos(rad), s = sin(rad), v = 1.0 - c;
    R[0][0] = x * x * v + c;     R[0][1] = x * y * v - z * s; R[0][2] = x * z * v + y * s;
    R[1][0] = x * y * v + z * s; R[1][1] = y * y * v + c;     R[1][2] = y * z * v - x * s;
    R[2][0] = x * z * v - y * s; R[2][1] = y * z * v + x * s; R[2][2] = z * z * v + c;
}

static void mul_d(m3d out, const m3d A, const m3d B)
{
    m3d t;
    unsigned i, j, k;
    for (i = 0; i < 3u; i++)
        for (j = 0; j < 3u; j++) {
            t[i][j] = 0.0;
            for (k = 0; k < 3u; k++) t[i][j] += A[i][k] * B[k][j];
        }
    memcpy(out, t, sizeof t);
}

static void elem_d(m3d R, unsigned axis, double deg)
{
    static const double e[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
    const double t = fmod(deg, 360.0) * (FZ_PI / 180.0);
    rot_axis_d(R, e[axis][0], e[axis][1], e[axis][2], t);
}

/* rotation of Euler angles of sequence seq, in double (rot.h table) */
static void euler_d(m3d R, unsigned seq, const float ang[3])
{
    static const char *const names[12] = { "XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX",
                                            "XYX", "XZX", "YXY", "YZY", "ZXZ", "ZYZ" };
    const char *nm = names[seq % 12u];
    m3d A, B, C;
    elem_d(A, (unsigned)(nm[0] - 'X'), ang[0]);
    elem_d(B, (unsigned)(nm[1] - 'X'), ang[1]);
    elem_d(C, (unsigned)(nm[2] - 'X'), ang[2]);
    if (seq < 12u) { /* intrinsic: A B C */
        mul_d(R, A, B);
        mul_d(R, R, C);
    } else {         /* extrinsic: C B A */
        mul_d(R, C, B);
        mul_d(R, R, A);
    }
}

static double dev_f(const dh_mat3_f32 *R) /* max |(R^T R - I)_ij| in double */
{
    double w = 0.0;
    unsigned i, j, k;
    for (i = 0; i < 3u; i++)
        for (j = 0; j < 3u; j++) {
            double s = (i == j) ? -1.0 : 0.0;
            for (k = 0; k < 3u; k++) s += (double)R->m[i][k] * (double)R->m[j][k];
            if (fabs(s) > w) w = fabs(s);
        }
    return w;
}

static double det_f(const dh_mat3_f32 *R)
{
    const double a = R->m[0][0], b = R->m[1][0], c = R->m[2][0];
    const double d = R->m[0][1], e = R->m[1][1], f = R->m[2][1];
    const double g = R->m[0][2], h = R->m[1][2], i = R->m[2][2];
    return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
}

static double repro_err(const dh_mat3_f32 *R, const m3d X)
{
    double w = 0.0;
    unsigned r, c;
    for (r = 0; r < 3u; r++)
        for (c = 0; c < 3u; c++) {
            const double e = fabs(X[r][c] - (double)DH_M3(R, r, c));
            if (e > w) w = e;
        }
    return w;
}

static void check_ortho_out(const dh_mat3_f32 *X, double tol, const char *what)
{
    const double d = dev_f(X);
    FZ_CHECK(d <= tol && det_f(X) > 0.0, "%s: result not a rotation (dev %.3g, det %.9g)", what, d, det_f(X));
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in;
    dh_mat3_f32 R;
    unsigned mode, seq, i, j;
    dh_status chk, st;
    double dev, tol;

    in.p = data;
    in.n = size;
    mode = fz_u8(&in) & 1u;
    seq = fz_u8(&in) % 26u; /* 24 and 25 are invalid */
    if (mode == 0u) {
        for (i = 0; i < 3u; i++)
            for (j = 0; j < 3u; j++) R.m[i][j] = fz_f32_bits(&in);
    } else {
        m3d X;
        const double kx = fz_unit(&in), ky = fz_unit(&in), kz = fz_unit(&in);
        const double ang = fz_unit(&in) * FZ_PI;
        const unsigned k = 8u + fz_u8(&in) % 40u;
        if (kx == 0.0 && ky == 0.0 && kz == 0.0) rot_axis_d(X, 0, 0, 1, ang);
        else rot_axis_d(X, kx, ky, kz, ang);
        for (i = 0; i < 3u; i++)
            for (j = 0; j < 3u; j++) DH_M3(&R, i, j) = (float)(X[i][j] + ldexp(fz_unit(&in), -(int)k));
    }
    chk = dh_mat3_check_rot_f32(&R, DH_ROT_TOL);
    FZ_CHECK(chk == DH_OK || chk == DH_ERR_NAN || chk == DH_ERR_NOT_RIGID, "check_rot %d", (int)chk);
    dev = (chk == DH_ERR_NAN) ? 0.0 : dev_f(&R);
    tol = FZ_REPRO_EXACT + FZ_REPRO_K * dev;

    /* ---- angle-axis (3x3 and 4x4 entry points) ---- */
    {
        dh_vec3_f32 k = { 9.0f, 9.0f, 9.0f }, k4 = k;
        float deg = 999.0f, deg4 = 999.0f;
        dh_mat4_f32 T;
        dh_mat4_identity_f32(&T);
        for (i = 0; i < 3u; i++)
            for (j = 0; j < 3u; j++) T.m[i][j] = R.m[i][j];
        st = dh_mat3_to_axis_angle_f32(&R, &k, &deg);
        FZ_CHECK(st == chk, "to_axis_angle %d vs check %d", (int)st, (int)chk);
        FZ_CHECK(dh_mat4_to_axis_angle_f32(&T, &k4, &deg4) == st && memcmp(&k, &k4, sizeof k) == 0 &&
                     memcmp(&deg, &deg4, sizeof deg) == 0,
                 "mat4 and mat3 axis-angle differ");
        if (st != DH_OK) {
            FZ_CHECK(k.x == 9.0f && deg == 999.0f, "axis-angle output written on error");
        } else {
            const double n = sqrt((double)k.x * k.x + (double)k.y * k.y + (double)k.z * k.z);
            m3d X;
            dh_mat3_f32 Y;
            FZ_CHECK(deg >= 0.0f && deg <= 180.0f, "angle %.9g", (double)deg);
            FZ_CHECK(fabs(n - 1.0) <= 1e-6, "axis length %.9g", n);
            rot_axis_d(X, k.x, k.y, k.z, (double)deg * (FZ_PI / 180.0));
            FZ_CHECK(repro_err(&R, X) <= tol, "axis-angle reproduces R within %.3g > %.3g (dev %.3g)",
                     repro_err(&R, X), tol, dev);
            FZ_CHECK(dh_axis_angle_to_mat3_f32(&k, deg, &Y) == DH_OK, "axis_angle_to_mat3");
            check_ortho_out(&Y, 1e-6, "axis_angle_to_mat3");
        }
    }
    /* ---- Euler ---- */
    {
        float a[3] = { 999.0f, 999.0f, 999.0f };
        st = dh_mat3_to_euler_f32(&R, (dh_euler_seq)seq, a);
        if (seq >= (unsigned)DH_EULER_COUNT) {
            FZ_CHECK(st == DH_ERR_ARG, "invalid sequence %u: st %d", seq, (int)st);
        } else {
            FZ_CHECK(st == chk, "to_euler(%s) %d vs check %d", dh_euler_name((dh_euler_seq)seq), (int)st, (int)chk);
        }
        if (st != DH_OK) {
            FZ_CHECK(a[0] == 999.0f && a[1] == 999.0f && a[2] == 999.0f, "Euler output written on error");
        } else {
            const int proper = (seq % 12u) >= 6u;
            m3d X;
            dh_mat3_f32 Y;
            FZ_CHECK(a[0] > -180.0f && a[0] <= 180.0f && a[2] > -180.0f && a[2] <= 180.0f,
                     "%s: first/third %.9g %.9g", dh_euler_name((dh_euler_seq)seq), (double)a[0], (double)a[2]);
            FZ_CHECK(proper ? (a[1] >= 0.0f && a[1] <= 180.0f) : (a[1] >= -90.0f && a[1] <= 90.0f), "%s: middle %.9g",
                     dh_euler_name((dh_euler_seq)seq), (double)a[1]);
            euler_d(X, seq, a);
            FZ_CHECK(repro_err(&R, X) <= FZ_REPRO_EULER + FZ_REPRO_K * dev,
                     "%s (%.9g %.9g %.9g) reproduces R within %.3g > %.3g (dev %.3g)",
                     dh_euler_name((dh_euler_seq)seq), (double)a[0], (double)a[1], (double)a[2], repro_err(&R, X),
                     FZ_REPRO_EULER + FZ_REPRO_K * dev, dev);
            FZ_CHECK(dh_euler_to_mat3_f32((dh_euler_seq)seq, a, &Y) == DH_OK, "euler_to_mat3");
            check_ortho_out(&Y, 1e-6, "euler_to_mat3");
        }
    }
    /* ---- quaternion ---- */
    {
        dh_quat_f32 q = { 9.0f, 9.0f, 9.0f, 9.0f };
        st = dh_mat3_to_quat_f32(&R, &q);
        FZ_CHECK(st == chk, "to_quat %d vs check %d", (int)st, (int)chk);
        if (st != DH_OK) {
            FZ_CHECK(q.w == 9.0f && q.x == 9.0f, "quaternion written on error");
        } else {
            const double n = sqrt((double)q.w * q.w + (double)q.x * q.x + (double)q.y * q.y + (double)q.z * q.z);
            m3d X;
            dh_mat3_f32 Y;
            FZ_CHECK(q.w >= 0.0f && !signbit(q.w), "w = %.9g", (double)q.w);
            FZ_CHECK(fabs(n - 1.0) <= 2.4e-7, "|q| - 1 = %.3g", n - 1.0);
            {
                const double w = q.w / n, x = q.x / n, y = q.y / n, z = q.z / n;
                X[0][0] = 1 - 2 * (y * y + z * z); X[0][1] = 2 * (x * y - w * z);     X[0][2] = 2 * (x * z + w * y);
                X[1][0] = 2 * (x * y + w * z);     X[1][1] = 1 - 2 * (x * x + z * z); X[1][2] = 2 * (y * z - w * x);
                X[2][0] = 2 * (x * z - w * y);     X[2][1] = 2 * (y * z + w * x);     X[2][2] = 1 - 2 * (x * x + y * y);
            }
            FZ_CHECK(repro_err(&R, X) <= tol, "quaternion reproduces R within %.3g > %.3g (dev %.3g)", repro_err(&R, X),
                     tol, dev);
            FZ_CHECK(dh_quat_to_mat3_f32(&q, &Y) == DH_OK, "quat_to_mat3");
            check_ortho_out(&Y, 1e-6, "quat_to_mat3");
        }
    }
    /* ---- rotation vector ---- */
    {
        dh_vec3_f32 phi = { 9.0f, 9.0f, 9.0f };
        st = dh_mat3_to_rotvec_f32(&R, &phi);
        FZ_CHECK(st == chk, "to_rotvec %d vs check %d", (int)st, (int)chk);
        if (st != DH_OK) {
            FZ_CHECK(phi.x == 9.0f && phi.y == 9.0f && phi.z == 9.0f, "rotvec written on error");
        } else {
            const double t = sqrt((double)phi.x * phi.x + (double)phi.y * phi.y + (double)phi.z * phi.z);
            m3d X;
            dh_mat3_f32 Y;
            FZ_CHECK(t <= FZ_PI + 1e-6, "|phi| = %.9g", t);
            if (t > 0.0) rot_axis_d(X, phi.x, phi.y, phi.z, t);
            else rot_axis_d(X, 0, 0, 1, 0.0);
            FZ_CHECK(repro_err(&R, X) <= tol, "rotvec reproduces R within %.3g > %.3g (dev %.3g)", repro_err(&R, X),
                     tol, dev);
            FZ_CHECK(dh_rotvec_to_mat3_f32(&phi, &Y) == DH_OK, "rotvec_to_mat3");
            check_ortho_out(&Y, 1e-6, "rotvec_to_mat3");
        }
    }
    /* ---- re-orthonormalisation ---- */
    {
        dh_mat3_f32 X;
        memset(&X, 0x77, sizeof X);
        st = dh_mat3_orthonormalize_f32(&R, &X);
        FZ_CHECK(st == DH_OK || st == DH_ERR_NAN || st == DH_ERR_NOT_RIGID || st == DH_ERR_NO_CONVERGENCE,
                 "orthonormalize %d", (int)st);
        if (chk == DH_ERR_NAN) FZ_CHECK(st == DH_ERR_NAN, "orthonormalize of non-finite R: %d", (int)st);
        if (st != DH_OK) {
            dh_mat3_f32 S;
            memset(&S, 0x77, sizeof S);
            FZ_CHECK(memcmp(&X, &S, sizeof X) == 0, "orthonormalize wrote out on error");
            FZ_CHECK(chk == DH_ERR_NAN || !(dev <= 0.2 && det_f(&R) >= 0.5),
                     "orthonormalize rejected (st %d) dev %.3g det %.3g", (int)st, dev, det_f(&R));
        } else {
            check_ortho_out(&X, 4e-7, "orthonormalize");
        }
    }
    return 0;
}
