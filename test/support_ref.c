/* SPDX-License-Identifier: Apache-2.0 */
/*
 * support_ref.c - double-precision reference helpers (see support_ref.h).
 * Independent of the library: only libm in double and plain loops.
 */
#include <float.h>
#include <math.h>

#include "dht.h"
#include "support_ref.h"

double dhr_deg2rad(double deg) { return deg * (DHR_PI / 180.0); }
double dhr_rad2deg(double rad) { return rad * (180.0 / DHR_PI); }

void dhr_identity(dhr_mat4 *T)
{
    int c, r;
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) T->m[c][r] = (c == r) ? 1.0 : 0.0;
}

void dhr_trans(double x, double y, double z, dhr_mat4 *T)
{
    dhr_identity(T);
    DHR_M4(T, 0, 3) = x;
    DHR_M4(T, 1, 3) = y;
    DHR_M4(T, 2, 3) = z;
}

/* sin/cos of degrees; whole multiples of 90 are set exactly */
static void dhr_sincos(double deg, double *s, double *c)
{
    double q = deg / 90.0;
    if (q == floor(q) && fabs(q) < 1e15) {
        long n = (long)fmod(q, 4.0);
        if (n < 0) n += 4;
        *s = (n == 1) ? 1.0 : (n == 3) ? -1.0 : 0.0;
        *c = (n == 0) ? 1.0 : (n == 2) ? -1.0 : 0.0;
        return;
    }
    *s = sin(dhr_deg2rad(deg));
    *c = cos(dhr_deg2rad(deg));
}

void dhr_rotx(double deg, dhr_mat4 *T)
{
    double s, c;
    dhr_sincos(deg, &s, &c);
    dhr_identity(T);
    DHR_M4(T, 1, 1) = c; DHR_M4(T, 1, 2) = -s;
    DHR_M4(T, 2, 1) = s; DHR_M4(T, 2, 2) = c;
}

void dhr_roty(double deg, dhr_mat4 *T)
{
    double s, c;
    dhr_sincos(deg, &s, &c);
    dhr_identity(T);
    DHR_M4(T, 0, 0) = c;  DHR_M4(T, 0, 2) = s;
    DHR_M4(T, 2, 0) = -s; DHR_M4(T, 2, 2) = c;
}

void dhr_rotz(double deg, dhr_mat4 *T)
{
    double s, c;
    dhr_sincos(deg, &s, &c);
    dhr_identity(T);
    DHR_M4(T, 0, 0) = c; DHR_M4(T, 0, 1) = -s;
    DHR_M4(T, 1, 0) = s; DHR_M4(T, 1, 1) = c;
}

int dhr_rot_axis(double kx, double ky, double kz, double deg, dhr_mat4 *T)
{
    /* frame C with a = k, n any unit vector orthogonal to k, o = a x n;
     * Rot(k) = C Rot(z) C^T (seed eq. 1.65) */
    double len = sqrt(kx * kx + ky * ky + kz * kz);
    double a[3], n[3], o[3], t[3], nl;
    dhr_mat4 C, Ct, Rz, tmp;
    int i;
    if (!(len > 0.0)) return 0;
    a[0] = kx / len; a[1] = ky / len; a[2] = kz / len;
    /* helper vector: the coordinate axis least aligned with a */
    if (fabs(a[0]) <= fabs(a[1]) && fabs(a[0]) <= fabs(a[2])) { t[0] = 1; t[1] = 0; t[2] = 0; }
    else if (fabs(a[1]) <= fabs(a[2])) { t[0] = 0; t[1] = 1; t[2] = 0; }
    else { t[0] = 0; t[1] = 0; t[2] = 1; }
    /* n = t x a, normalised; o = a x n */
    n[0] = t[1] * a[2] - t[2] * a[1];
    n[1] = t[2] * a[0] - t[0] * a[2];
    n[2] = t[0] * a[1] - t[1] * a[0];
    nl = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (i = 0; i < 3; i++) n[i] /= nl;
    o[0] = a[1] * n[2] - a[2] * n[1];
    o[1] = a[2] * n[0] - a[0] * n[2];
    o[2] = a[0] * n[1] - a[1] * n[0];
    dhr_identity(&C);
    for (i = 0; i < 3; i++) {
        C.m[0][i] = n[i];
        C.m[1][i] = o[i];
        C.m[2][i] = a[i];
    }
    dhr_identity(&Ct);
    for (i = 0; i < 3; i++) {
        Ct.m[i][0] = n[i];
        Ct.m[i][1] = o[i];
        Ct.m[i][2] = a[i];
    }
    dhr_rotz(deg, &Rz);
    dhr_mul(&C, &Rz, &tmp);
    dhr_mul(&tmp, &Ct, T);
    return 1;
}

void dhr_mul(const dhr_mat4 *A, const dhr_mat4 *B, dhr_mat4 *out)
{
    dhr_mat4 r;
    int i, j, k;
    for (j = 0; j < 4; j++)
        for (i = 0; i < 4; i++) {
            double s = 0.0;
            for (k = 0; k < 4; k++) s += DHR_M4(A, i, k) * DHR_M4(B, k, j);
            DHR_M4(&r, i, j) = s;
        }
    *out = r;
}

void dhr_apply4(const dhr_mat4 *T, const double u[4], double v[4])
{
    double r[4];
    int i, k;
    for (i = 0; i < 4; i++) {
        double s = 0.0;
        for (k = 0; k < 4; k++) s += DHR_M4(T, i, k) * u[k];
        r[i] = s;
    }
    for (i = 0; i < 4; i++) v[i] = r[i];
}

int dhr_inv(const dhr_mat4 *T, dhr_mat4 *out)
{
    double a[4][8]; /* row-major augmented [T | I] */
    int i, j, k, p;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            a[i][j] = DHR_M4(T, i, j);
            a[i][j + 4] = (i == j) ? 1.0 : 0.0;
        }
    for (k = 0; k < 4; k++) {
        double piv, best = -1.0;
        p = k;
        for (i = k; i < 4; i++)
            if (fabs(a[i][k]) > best) { best = fabs(a[i][k]); p = i; }
        if (best == 0.0) return 0;
        if (p != k)
            for (j = 0; j < 8; j++) { double t = a[k][j]; a[k][j] = a[p][j]; a[p][j] = t; }
        piv = a[k][k];
        for (j = 0; j < 8; j++) a[k][j] /= piv;
        for (i = 0; i < 4; i++) {
            double f;
            if (i == k) continue;
            f = a[i][k];
            if (f != 0.0)
                for (j = 0; j < 8; j++) a[i][j] -= f * a[k][j];
        }
    }
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) DHR_M4(out, i, j) = a[i][j + 4];
    return 1;
}

double dhr_det(const dhr_mat4 *T)
{
    double a[4][4], det = 1.0;
    int i, j, k, p;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) a[i][j] = DHR_M4(T, i, j);
    for (k = 0; k < 4; k++) {
        double best = -1.0;
        p = k;
        for (i = k; i < 4; i++)
            if (fabs(a[i][k]) > best) { best = fabs(a[i][k]); p = i; }
        if (best == 0.0) return 0.0;
        if (p != k) {
            for (j = 0; j < 4; j++) { double t = a[k][j]; a[k][j] = a[p][j]; a[p][j] = t; }
            det = -det;
        }
        det *= a[k][k];
        for (i = k + 1; i < 4; i++) {
            double f = a[i][k] / a[k][k];
            for (j = k; j < 4; j++) a[i][j] -= f * a[k][j];
        }
    }
    return det;
}

double dhr_norm_inf(const dhr_mat4 *T)
{
    double best = 0.0;
    int i, j;
    for (i = 0; i < 4; i++) {
        double s = 0.0;
        for (j = 0; j < 4; j++) s += fabs(DHR_M4(T, i, j));
        if (s > best) best = s;
    }
    return best;
}

double dhr_cond_inf(const dhr_mat4 *T)
{
    dhr_mat4 inv;
    if (!dhr_inv(T, &inv)) return HUGE_VAL;
    return dhr_norm_inf(T) * dhr_norm_inf(&inv);
}

double dhr_max_abs(const dhr_mat4 *T)
{
    double best = 0.0;
    int c, r;
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++)
            if (fabs(T->m[c][r]) > best) best = fabs(T->m[c][r]);
    return best;
}

void dhr_from_f32(const dh_mat4_f32 *T, dhr_mat4 *D)
{
    int c, r;
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) D->m[c][r] = (double)T->m[c][r];
}

void dhr_from_q(const dh_frame_q *F, dhr_mat4 *out)
{
    int c, r;
    dhr_identity(out);
    for (c = 0; c < 3; c++)
        for (r = 0; r < 3; r++) out->m[c][r] = ldexp((double)F->r[c][r], -30);
    for (r = 0; r < 3; r++) out->m[3][r] = ldexp((double)F->p[r], -DH_QPOS_FRAC);
}

void dhr_to_f32(const dhr_mat4 *D, dh_mat4_f32 *T)
{
    int c, r;
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) T->m[c][r] = (float)D->m[c][r];
}

double dhr_max_abs_diff(const dh_mat4_f32 *T, const dhr_mat4 *D)
{
    double best = 0.0;
    int c, r;
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) {
            double d = fabs((double)T->m[c][r] - D->m[c][r]);
            if (!(d <= best)) best = (d == d) ? d : HUGE_VAL;
        }
    return best;
}

double dhr_max_abs_diff_d(const dhr_mat4 *A, const dhr_mat4 *B)
{
    double best = 0.0;
    int c, r;
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) {
            double d = fabs(A->m[c][r] - B->m[c][r]);
            if (!(d <= best)) best = (d == d) ? d : HUGE_VAL;
        }
    return best;
}

double dhr_pos_diff(const dhr_mat4 *A, const dhr_mat4 *B)
{
    double e = 0.0;
    int i;
    for (i = 0; i < 3; i++) {
        double d = fabs(A->m[3][i] - B->m[3][i]);
        if (!(d <= e)) e = d; /* NaN propagates */
    }
    return e;
}

double dhr_rot_diff(const dhr_mat4 *A, const dhr_mat4 *B)
{
    double e = 0.0;
    int c, i;
    for (c = 0; c < 3; c++)
        for (i = 0; i < 3; i++) {
            double d = fabs(A->m[c][i] - B->m[c][i]);
            if (!(d <= e)) e = d;
        }
    return e;
}

void dhr_rand_unit3(double k[3])
{
    /* uniform z in [-1, 1) and azimuth: uniform on the sphere */
    double z = dht_rand_uniform(-1.0, 1.0);
    double phi = dht_rand_uniform(0.0, 2.0 * DHR_PI);
    double r = sqrt(1.0 - z * z);
    k[0] = r * cos(phi);
    k[1] = r * sin(phi);
    k[2] = z;
}

void dhr_rand_rigid(double tmax, dhr_mat4 *T)
{
    double k[3];
    dhr_rand_unit3(k);
    dhr_rot_axis(k[0], k[1], k[2], dht_rand_uniform(-180.0, 180.0), T);
    DHR_M4(T, 0, 3) = dht_rand_uniform(-tmax, tmax);
    DHR_M4(T, 1, 3) = dht_rand_uniform(-tmax, tmax);
    DHR_M4(T, 2, 3) = dht_rand_uniform(-tmax, tmax);
}

void dhr_rand_general(dhr_mat4 *T)
{
    int c, r;
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) T->m[c][r] = dht_rand_uniform(-1.0, 1.0);
}

void dhr_mat3_mul(const dhr_mat3 *A, const dhr_mat3 *B, dhr_mat3 *out)
{
    dhr_mat3 t;
    int i, j, k;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            double s = 0.0;
            for (k = 0; k < 3; k++) s += A->d[i][k] * B->d[k][j];
            t.d[i][j] = s;
        }
    *out = t;
}

void dhr_mat3_from_quat(double w, double x, double y, double z, dhr_mat3 *R)
{
    R->d[0][0] = 1 - 2 * (y * y + z * z); R->d[0][1] = 2 * (x * y - w * z); R->d[0][2] = 2 * (x * z + w * y);
    R->d[1][0] = 2 * (x * y + w * z); R->d[1][1] = 1 - 2 * (x * x + z * z); R->d[1][2] = 2 * (y * z - w * x);
    R->d[2][0] = 2 * (x * z - w * y); R->d[2][1] = 2 * (y * z + w * x); R->d[2][2] = 1 - 2 * (x * x + y * y);
}

void dhr_mat3_to_f32(const dhr_mat3 *D, dh_mat3_f32 *R)
{
    int r, c;
    for (r = 0; r < 3; r++)
        for (c = 0; c < 3; c++) DH_M3(R, r, c) = (float)D->d[r][c];
}

double dhr_mat3_max_diff(const dh_mat3_f32 *R, const dhr_mat3 *D)
{
    double m = 0.0;
    int r, c;
    for (r = 0; r < 3; r++)
        for (c = 0; c < 3; c++) {
            double e = fabs((double)DH_M3(R, r, c) - D->d[r][c]);
            if (!(e <= m)) m = e; /* NaN propagates as a failure */
        }
    return m;
}

double dhr_ulp_f32(double x)
{
    int e;
    x = fabs(x);
    if (x < (double)FLT_MIN) return ldexp(1.0, -149);
    (void)frexp(x, &e); /* x = f 2^e, f in [0.5, 1) */
    return ldexp(1.0, e - 24);
}

/* sin and cos of d degrees, the reduction exact (d with at most 53
 * significant bits, any sign): the references of the sine tables */
void dhr_sincos_deg(double d, double *s, double *c)
{
    double r = fmod(fabs(d), 360.0), s0, c0, t;
    int k = 0;
    while (r >= 90.0) {
        r -= 90.0;
        k++;
    }
    t = r * (DHR_PI / 180.0);
    s0 = sin(t);
    c0 = cos(t);
    switch (k) {
    case 0: *s = s0; *c = c0; break;
    case 1: *s = c0; *c = -s0; break;
    case 2: *s = -s0; *c = -c0; break;
    default: *s = -c0; *c = s0; break;
    }
    if (d < 0) *s = -*s;
}

/* eigenvalues of the symmetric m x m matrix A (row-major, destroyed) by
 * cyclic Jacobi rotations */
void dhr_sym_eig(double *A, int m, double *ev)
{
    int sweep, p, q, k;
    for (sweep = 0; sweep < 60; sweep++) {
        double off = 0.0, dia = 0.0;
        for (p = 0; p < m; p++)
            for (q = 0; q < m; q++) {
                if (p != q) off += A[p * m + q] * A[p * m + q];
                else dia += A[p * m + q] * A[p * m + q];
            }
        if (off <= 1e-34 * dia || off == 0.0) break;
        for (p = 0; p < m; p++)
            for (q = p + 1; q < m; q++) {
                double apq = A[p * m + q], th, t, c, s;
                if (apq == 0.0) continue;
                th = (A[q * m + q] - A[p * m + p]) / (2.0 * apq);
                t = (th >= 0 ? 1.0 : -1.0) / (fabs(th) + sqrt(th * th + 1.0));
                c = 1.0 / sqrt(t * t + 1.0);
                s = t * c;
                for (k = 0; k < m; k++) { /* columns p, q */
                    double akp = A[k * m + p], akq = A[k * m + q];
                    A[k * m + p] = c * akp - s * akq;
                    A[k * m + q] = s * akp + c * akq;
                }
                for (k = 0; k < m; k++) { /* rows p, q */
                    double apk = A[p * m + k], aqk = A[q * m + k];
                    A[p * m + k] = c * apk - s * aqk;
                    A[q * m + k] = s * apk + c * aqk;
                }
            }
    }
    for (p = 0; p < m; p++) ev[p] = A[p * m + p];
}

double dhr_trap_tmin(double d, double v, double a)
{
    d = fabs(d);
    return (d >= v * v / a) ? d / v + v / a : 2.0 * sqrt(d / a);
}

/* the seven-phase minimum: the least duration among the feasible regimes
 * (test_profile.c derives the same four) */
double dhr_scurve_tmin(double d, double V, double A, double J)
{
    double best = HUGE_VAL, tj, ta, sl = 1e-12;
    d = fabs(d);
    if (d == 0.0) return 0.0;
    tj = A / J;
    ta = tj + V / A;
    if (V * J >= A * A * (1 - sl) && d >= V * ta * (1 - sl) && d / V + ta < best) best = d / V + ta;
    tj = sqrt(V / J);
    ta = 2 * tj;
    if (J * tj <= A * (1 + sl) && d >= V * ta * (1 - sl) && d / V + ta < best) best = d / V + ta;
    tj = A / J;
    ta = 0.5 * tj + sqrt(0.25 * tj * tj + d / A);
    if (ta >= 2 * tj * (1 - sl) && A * (ta - tj) <= V * (1 + sl) && 2 * ta < best) best = 2 * ta;
    tj = cbrt(d / (2 * J));
    if (J * tj <= A * (1 + sl) && J * tj * tj <= V * (1 + sl) && 4 * tj < best) best = 4 * tj;
    return best;
}
