/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_frame_q.c - fixed-point rigid frames (frame.h).
 *
 * References are computed here in double precision from the INTEGER inputs
 * (never from results of the code under test), so "within 0.5 LSB of the
 * reference" checks the one-rounding contract directly. Double sums of
 * products below 2^63 carry an error below 2^-20 LSB, far inside the
 * tolerance. Measured maxima are printed with dht_printf.
 */
#include "dht.h"
#include "dhmath/frame.h"
#include "dhmath/trig.h"
#include "dhmath/rot.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

#define Q30 1073741824.0
#define EPS_LSB (1.0 / 1048576.0) /* double rounding allowance, 2^-20 LSB */

static const double PI = 3.14159265358979323846;

/* ---- random inputs --------------------------------------------------------- */

static int32_t rnd_i32(void) { return (int32_t)dht_rand_u32(); }

/* uniform integer in [-m, m], m <= 2^31 - 1 */
static int32_t rnd_range(int32_t m)
{
    return (int32_t)floor(dht_rand_uniform(-(double)m, (double)m + 1.0));
}

static dh_q16 rnd_angle(void) { return rnd_range(720 * 65536); }

/* random axis: unit Q2.30 vectors, small integers, or full-range int32 */
static void rnd_axis(int32_t k[3])
{
    unsigned kind = dht_rand_u32() % 3u, i;
    do {
        for (i = 0; i < 3u; i++) {
            if (kind == 0u) k[i] = rnd_range(0x40000000);
            else if (kind == 1u) k[i] = rnd_range(5);
            else k[i] = rnd_i32();
        }
    } while (k[0] == 0 && k[1] == 0 && k[2] == 0);
}

/* a rigid frame: random rotation about a random axis, position in +-pmax LSB */
static void rnd_rigid(dh_frame_q *F, int32_t pmax)
{
    int32_t k[3];
    rnd_axis(k);
    DHT_EQ_INT(dh_frame_rot_axis_q(k[0], k[1], k[2], rnd_angle(), F), DH_OK);
    F->p[0] = rnd_range(pmax);
    F->p[1] = rnd_range(pmax);
    F->p[2] = rnd_range(pmax);
}

/* a frame with arbitrary int32 entries (exact / saturating paths) */
static void rnd_garbage(dh_frame_q *F)
{
    unsigned i, j;
    for (i = 0; i < 3u; i++) {
        for (j = 0; j < 3u; j++) F->r[i][j] = rnd_i32();
        F->p[i] = rnd_i32();
    }
}

/* ---- reference helpers ---------------------------------------------------- */

/* Expected saturated integer for an exact real value x (LSB units): returns
 * 1 and sets *sat when x is clearly outside int32, 0 when inside, -1 when
 * too close to the boundary to decide with double. */
static int ref_class(double x, int32_t *sat)
{
    if (x >= 2147483647.5 + 1.0) { *sat = INT32_MAX; return 1; }
    if (x < -2147483648.5 - 1.0) { *sat = INT32_MIN; return 1; }
    if (x > 2147483646.0 || x < -2147483647.0) return -1;
    return 0;
}

/* check one output against the exact real value x: <= 0.5 LSB or saturated;
 * returns |error| in LSB (0 for saturated) and records whether saturation
 * was expected. */
static double check_out(int32_t got, double x, int *sat_expected)
{
    int32_t s;
    int c = ref_class(x, &s);
    if (c == 1) {
        DHT_EQ_INT(got, s);
        *sat_expected = 1;
        return 0.0;
    }
    if (c == -1) return 0.0;
    DHT_NEAR(got, x, 0.5 + EPS_LSB);
    return fabs((double)got - x);
}

static double ref_r(const dh_frame_q *F, int row, int col) { return (double)F->r[col][row]; }

/* ---- constructors ------------------------------------------------------------ */

static void identity_and_translation_are_exact(void)
{
    dh_frame_q F;
    int i, j;
    memset(&F, 0x5A, sizeof F);
    dh_frame_identity_q(&F);
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) DHT_EQ_INT(F.r[i][j], i == j ? DH_Q30_ONE : 0);
        DHT_EQ_INT(F.p[i], 0);
    }
    DHT_EQ_INT(dh_frame_ortho_error_q(&F), 0);
    dh_frame_trans_q(INT32_MIN, INT32_MAX, -7, &F);
    DHT_EQ_INT(F.p[0], INT32_MIN);
    DHT_EQ_INT(F.p[1], INT32_MAX);
    DHT_EQ_INT(F.p[2], -7);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) DHT_EQ_INT(F.r[i][j], i == j ? DH_Q30_ONE : 0);
}

/* Elementary rotations: structure of eq. 1.32-1.34 with the trig values,
 * and closeness to the double reference (dh_sincos_q contract <= 2 LSB). */
static void elementary_rotations(void)
{
    long k, n = DHT_ITER(20000);
    double worst = 0.0;
    for (k = 0; k < n; k++) {
        dh_q16 deg = (k < 9) ? (dh_q16)((k - 4) * 90 * 65536) : rnd_angle();
        double th = (double)deg / 65536.0 * PI / 180.0, c = cos(th) * Q30, s = sin(th) * Q30;
        /* expected matrices, row-major [row][col] */
        double ex[3][3][3] = {
            { { Q30, 0, 0 }, { 0, c, -s }, { 0, s, c } },
            { { c, 0, s }, { 0, Q30, 0 }, { -s, 0, c } },
            { { c, -s, 0 }, { s, c, 0 }, { 0, 0, Q30 } } };
        dh_frame_q F[3];
        int a, r, col;
        dh_frame_rotx_q(deg, &F[0]);
        dh_frame_roty_q(deg, &F[1]);
        dh_frame_rotz_q(deg, &F[2]);
        for (a = 0; a < 3; a++) {
            for (r = 0; r < 3; r++) {
                for (col = 0; col < 3; col++) {
                    double e = fabs(ref_r(&F[a], r, col) - ex[a][r][col]);
                    if (ex[a][r][col] == 0.0 || ex[a][r][col] == Q30) DHT_EQ_INT(ref_r(&F[a], r, col), ex[a][r][col]);
                    DHT_TRUE_MSG(e <= 2.0, "rot axis %d deg %ld entry (%d,%d) err %.3f LSB", a, (long)deg, r, col, e);
                    if (e > worst) worst = e;
                }
                DHT_EQ_INT(F[a].p[r], 0);
            }
            if (k < 9) DHT_EQ_INT(dh_frame_ortho_error_q(&F[a]), 0); /* multiples of 90: exact */
        }
    }
    dht_printf("rotx/y/z: max entry error %.3f LSB (Q2.30) over %ld angles\n", worst, n);
}

/* exact max |(R^T R - I)_ij| of F in LSB (columns r[i]; double sums of
 * products below 2^63, error below 2^-20 LSB) */
static double ortho_exact(const dh_frame_q *F)
{
    double e = 0.0;
    int i, j;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            double d = ((double)F->r[i][0] * F->r[j][0] + (double)F->r[i][1] * F->r[j][1] +
                        (double)F->r[i][2] * F->r[j][2]) / Q30 - (i == j ? Q30 : 0.0);
            if (fabs(d) > e) e = fabs(d);
        }
    }
    return e;
}

/*
 * Rot(k, theta) vs the double Rodrigues formula (eq. 1.70) with exact sin/cos.
 * Entries: ROT_AXIS_ERR_LSB, from 201 seeds x 30000 axes (max 2.29 LSB).
 * Orthonormality, derived: the raw matrix R0 (entries a few LSB off) gets
 * one Newton step R1 = round(R0 round(M)), M = (3I - R0^T R0)/2. The exact
 * step X = R0 M has X^T X - I = O(e0^2), far below an LSB; the rounding of
 * M (dM, symmetric, <= 1/2) adds X^T R0 dM + dM^T R0^T X = 2 dM (to first
 * order), <= 1 LSB; the final rounding D2 (<= 1/2 per entry) adds X^T D2 +
 * D2^T X, each entry a column of X (length 1) times a column of D2
 * (length <= sqrt(3)/2): <= sqrt(3). So |R1^T R1 - I| <= 1 + sqrt(3) =
 * 2.74 LSB exactly, and dh_frame_ortho_error_q(), rounded, <= 3.
 */
#define ROT_AXIS_ERR_LSB 3.0
#define ROT_AXIS_ORTHO_EXACT (1.0 + 1.7320508075688772 + EPS_LSB)
static void axis_rotation_vs_double(void)
{
    long k, n = DHT_ITER(30000);
    double worst = 0.0, worst_exact = 0.0;
    int32_t worst_ortho = 0;
    for (k = 0; k < n; k++) {
        int32_t ax[3];
        dh_q16 deg = rnd_angle();
        dh_frame_q F;
        double u[3], nn, th, c, s, v, R[3][3];
        int r, col;
        rnd_axis(ax);
        if (k < 3) { ax[0] = ax[1] = ax[2] = 0; ax[k] = (k == 1) ? INT32_MIN : 1; }
        DHT_EQ_INT(dh_frame_rot_axis_q(ax[0], ax[1], ax[2], deg, &F), DH_OK);
        nn = sqrt((double)ax[0] * ax[0] + (double)ax[1] * ax[1] + (double)ax[2] * ax[2]);
        for (r = 0; r < 3; r++) u[r] = ax[r] / nn;
        th = (double)deg / 65536.0 * PI / 180.0;
        c = cos(th); s = sin(th); v = 1.0 - c;
        R[0][0] = u[0] * u[0] * v + c;        R[0][1] = u[1] * u[0] * v - u[2] * s; R[0][2] = u[2] * u[0] * v + u[1] * s;
        R[1][0] = u[0] * u[1] * v + u[2] * s; R[1][1] = u[1] * u[1] * v + c;        R[1][2] = u[2] * u[1] * v - u[0] * s;
        R[2][0] = u[0] * u[2] * v - u[1] * s; R[2][1] = u[1] * u[2] * v + u[0] * s; R[2][2] = u[2] * u[2] * v + c;
        for (r = 0; r < 3; r++) {
            for (col = 0; col < 3; col++) {
                double e = fabs(ref_r(&F, r, col) - R[r][col] * Q30);
                DHT_TRUE_MSG(e <= ROT_AXIS_ERR_LSB, "rot_axis(%ld, %ld, %ld, deg %ld) entry (%d,%d): %.3f LSB > "
                             "bound %.3f", (long)ax[0], (long)ax[1], (long)ax[2], (long)deg, r, col, e,
                             ROT_AXIS_ERR_LSB);
                if (e > worst) worst = e;
            }
            DHT_EQ_INT(F.p[r], 0);
        }
        {
            double ex = ortho_exact(&F);
            int32_t eo = dh_frame_ortho_error_q(&F);
            DHT_TRUE_MSG(ex <= ROT_AXIS_ORTHO_EXACT && eo <= 3, "rot_axis(%ld, %ld, %ld, deg %ld): |R^T R - I| "
                         "%.3f LSB (reported %ld) > bound %.3f (3)", (long)ax[0], (long)ax[1], (long)ax[2],
                         (long)deg, ex, (long)eo, ROT_AXIS_ORTHO_EXACT);
            if (ex > worst_exact) worst_exact = ex;
            if (eo > worst_ortho) worst_ortho = eo;
        }
    }
    dht_reach_max("rot_axis.ortho_reported", (double)worst_ortho); /* LSB: dh_frame_ortho_error_q, bound 3 */
    dht_printf("rot_axis: max entry error %.3f LSB, max |R^T R - I| %.3f LSB exact, %ld LSB reported, "
               "over %ld cases\n", worst, worst_exact, (long)worst_ortho, n);
}

static void axis_rotation_special_cases(void)
{
    dh_frame_q F, G;
    int i, j;
    /* zero axis: status, F untouched */
    memset(&F, 0x33, sizeof F);
    G = F;
    DHT_EQ_INT(dh_frame_rot_axis_q(0, 0, 0, 30 * 65536, &F), DH_ERR_ZERO_AXIS);
    DHT_TRUE(memcmp(&F, &G, sizeof F) == 0);
    /* any scale along x gives rotx to within 1 LSB (scale-independence) */
    for (i = 0; i < 3; i++) {
        static const int32_t scales[] = { 1, 0x40000000, INT32_MIN };
        int32_t ax[3] = { 0, 0, 0 };
        dh_frame_q E;
        ax[i] = scales[i];
        DHT_EQ_INT(dh_frame_rot_axis_q(ax[0], ax[1], ax[2], 37 * 65536 + 1234, &F), DH_OK);
        if (i == 0) dh_frame_rotx_q(37 * 65536 + 1234, &E);
        else if (i == 1) dh_frame_roty_q(37 * 65536 + 1234, &E);
        else dh_frame_rotz_q(-(37 * 65536 + 1234), &E); /* negative axis */
        for (j = 0; j < 9; j++) DHT_NEAR(F.r[j / 3][j % 3], E.r[j / 3][j % 3], 1.0);
    }
}

/* ---- composition ---------------------------------------------------------- */

/* exact real value of (A*B) entries in LSB units */
static void ref_mul(const dh_frame_q *A, const dh_frame_q *B, double R[3][3], double p[3])
{
    int i, j, k;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            double s = 0.0;
            for (k = 0; k < 3; k++) s += (double)A->r[k][i] * (double)B->r[j][k];
            R[i][j] = s / Q30;
        }
        {
            double s = (double)A->p[i] * Q30;
            for (k = 0; k < 3; k++) s += (double)A->r[k][i] * (double)B->p[k];
            p[i] = s / Q30;
        }
    }
}

static double check_mul(const dh_frame_q *A, const dh_frame_q *B, int *any_sat)
{
    dh_frame_q O, O2;
    double R[3][3], p[3], worst = 0.0, e;
    int i, j, sat = 0;
    dh_status st = dh_frame_mul_q(A, B, &O);
    ref_mul(A, B, R, p);
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            e = check_out(O.r[j][i], R[i][j], &sat);
            if (e > worst) worst = e;
        }
        e = check_out(O.p[i], p[i], &sat);
        if (e > worst) worst = e;
    }
    if (sat) DHT_EQ_INT(st, DH_ERR_OVERFLOW);
    if (st == DH_OK) DHT_EQ_INT(sat, 0);
    /* aliasing: out == A and out == B give the same bits */
    O2 = *A;
    DHT_EQ_INT(dh_frame_mul_q(&O2, B, &O2), st);
    DHT_TRUE(memcmp(&O, &O2, sizeof O) == 0);
    O2 = *B;
    DHT_EQ_INT(dh_frame_mul_q(A, &O2, &O2), st);
    DHT_TRUE(memcmp(&O, &O2, sizeof O) == 0);
    *any_sat |= sat;
    return worst;
}

static void compose_rigid_vs_double(void)
{
    long k, n = DHT_ITER(50000);
    double worst = 0.0;
    int sat = 0;
    for (k = 0; k < n; k++) {
        dh_frame_q A, B;
        double e;
        rnd_rigid(&A, 0x7FFFFFFF);
        rnd_rigid(&B, 0x7FFFFFFF);
        e = check_mul(&A, &B, &sat);
        if (e > worst) worst = e;
    }
    dht_printf("mul (rigid, fast path): max error %.4f LSB vs exact, saturation seen %d\n", worst, sat);
    DHT_TRUE(sat); /* full-range positions do overflow sometimes; must be reported */
}

static void compose_arbitrary_entries_exact_path(void)
{
    long k, n = DHT_ITER(50000);
    double worst = 0.0;
    int sat = 0;
    for (k = 0; k < n; k++) {
        dh_frame_q A, B;
        double e;
        rnd_garbage(&A);
        if (k & 1) rnd_rigid(&B, 0x7FFFFFFF); else rnd_garbage(&B);
        /* scale A down sometimes so that non-saturated exact-path results occur */
        if (k & 2) { int i, j; for (i = 0; i < 3; i++) for (j = 0; j < 3; j++) A.r[i][j] /= 64; }
        e = check_mul(&A, &B, &sat);
        if (e > worst) worst = e;
    }
    dht_printf("mul (arbitrary entries): max error %.4f LSB vs exact\n", worst);
    DHT_TRUE(sat);
}

/* 64-bit accumulator corner cases: three (-2)*(-2) products = +12 must give
 * +INT32_MAX (not a wrapped negative); position sums at the int64 limits. */
static void compose_accumulator_extremes(void)
{
    dh_frame_q A, B, O;
    int i, j, sat = 0;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) { A.r[i][j] = INT32_MIN; B.r[i][j] = INT32_MIN; }
        A.p[i] = INT32_MIN; B.p[i] = INT32_MIN;
    }
    DHT_EQ_INT(dh_frame_mul_q(&A, &B, &O), DH_ERR_OVERFLOW);
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) DHT_EQ_INT(O.r[i][j], INT32_MAX);
        DHT_EQ_INT(O.p[i], INT32_MAX);   /* 3 * 2^31 * 2 - 2^31 > 0 */
    }
    /* fast path limits: entries exactly +-1.0 with extreme positions */
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) A.r[i][j] = -DH_Q30_ONE;
        A.p[i] = INT32_MIN;
        B.p[i] = INT32_MIN;
    }
    dh_frame_identity_q(&B);
    for (i = 0; i < 3; i++) B.p[i] = INT32_MIN;
    DHT_EQ_INT(dh_frame_mul_q(&A, &B, &O), DH_ERR_OVERFLOW);
    for (i = 0; i < 3; i++) DHT_EQ_INT(O.p[i], INT32_MAX); /* +3*2^31 - 2^31 */
    for (i = 0; i < 3; i++) { for (j = 0; j < 3; j++) A.r[i][j] = DH_Q30_ONE; A.p[i] = INT32_MIN; }
    DHT_EQ_INT(dh_frame_mul_q(&A, &B, &O), DH_ERR_OVERFLOW);
    for (i = 0; i < 3; i++) DHT_EQ_INT(O.p[i], INT32_MIN); /* -4 * 2^31 */
    (void)check_mul(&A, &B, &sat);
    DHT_TRUE(sat);
    /* rounding ties go up: 0.5 LSB -> 1, -0.5 LSB -> 0 */
    dh_frame_identity_q(&A);
    A.r[0][0] = 1; A.r[1][1] = DH_Q30_ONE; A.r[2][2] = DH_Q30_ONE;
    dh_frame_identity_q(&B);
    B.r[0][0] = (int32_t)0x20000000; /* 0.5 * 2^30: product 2^29 -> 0.5 LSB */
    DHT_EQ_INT(dh_frame_mul_q(&A, &B, &O), DH_OK);
    DHT_EQ_INT(O.r[0][0], 1);
    B.r[0][0] = -(int32_t)0x20000000;
    DHT_EQ_INT(dh_frame_mul_q(&A, &B, &O), DH_OK);
    DHT_EQ_INT(O.r[0][0], 0);
}

/* ---- inverse -------------------------------------------------------------- */

/* the 12 entries of F as text, for failure messages */
static const char *frame_str(const dh_frame_q *F, char buf[256])
{
    snprintf(buf, 256, "r cols {%ld %ld %ld | %ld %ld %ld | %ld %ld %ld} p {%ld %ld %ld}",
             (long)F->r[0][0], (long)F->r[0][1], (long)F->r[0][2], (long)F->r[1][0], (long)F->r[1][1],
             (long)F->r[1][2], (long)F->r[2][0], (long)F->r[2][1], (long)F->r[2][2], (long)F->p[0],
             (long)F->p[1], (long)F->p[2]);
    return buf;
}

/*
 * T * T^-1 for a frame whose R is not exactly orthonormal (every rounded
 * rotation): the inverse is exact (R^T, -R^T p rounded once, checked
 * here), so what remains is R R^T - I. Derivation (docs/design.md, fixed
 * frames): with E = R^T R - I, largest entry e (LSB, computed exactly
 * here), M = R R^T - I has the eigenvalues of E, so every |M_ij| <=
 * ||M||_2 = ||E||_2 <= 3 e. The product rounds once:
 *   rotation  |(T T^-1 - I)_ij| <= 3 e + 0.5,
 *   position  |(T T^-1)_p,i| <= 0.5 + sqrt(3)/2 sqrt(1 + 3 e 2^-30)
 *                              + 3 e 2^-30 |p|_2
 * (R d for the inverse's rounding d, |d_j| <= 1/2, plus M p).
 */
static void inverse_vs_double_and_identity(void)
{
    long k, n = DHT_ITER(50000);
    double worst_inv = 0.0, worst_rid = 0.0, worst_pid = 0.0, worst_e = 0.0, worst_slack = -1e9;
    char buf[256];
    for (k = 0; k < n; k++) {
        dh_frame_q F, I, P, Q;
        int i, j, sat = 0;
        double e, pn, brot, bpos;
        if (k & 1) {
            rnd_rigid(&F, 1 << 28);
        } else {   /* a DH-like link Rz(theta) Tz(d) Tx(a) Rx(alpha) from elementary rotations */
            dh_frame_q X;
            dh_frame_rotz_q(rnd_angle(), &F);
            dh_frame_trans_q(rnd_range(1 << 27), 0, rnd_range(1 << 27), &X);
            DHT_EQ_INT(dh_frame_mul_q(&F, &X, &F), DH_OK);
            dh_frame_rotx_q(rnd_angle(), &X);
            DHT_EQ_INT(dh_frame_mul_q(&F, &X, &F), DH_OK);
        }
        DHT_EQ_INT(dh_frame_inv_q(&F, &I), DH_OK);
        for (i = 0; i < 3; i++) {
            double s = 0.0, ei;
            for (j = 0; j < 3; j++) {
                DHT_EQ_INT(I.r[j][i], F.r[i][j]); /* exact transpose */
                s -= (double)F.r[i][j] * (double)F.p[j];
            }
            ei = check_out(I.p[i], s / Q30, &sat);
            if (ei > worst_inv) worst_inv = ei;
        }
        /* alias */
        Q = F;
        DHT_EQ_INT(dh_frame_inv_q(&Q, &Q), DH_OK);
        DHT_TRUE(memcmp(&Q, &I, sizeof Q) == 0);
        e = ortho_exact(&F);
        if (e > worst_e) worst_e = e;
        pn = sqrt((double)F.p[0] * F.p[0] + (double)F.p[1] * F.p[1] + (double)F.p[2] * F.p[2]);
        brot = 3.0 * e + 0.5 + EPS_LSB;
        bpos = 0.5 + 0.5 * sqrt(3.0) * sqrt(1.0 + 3.0 * e / Q30) + 3.0 * e / Q30 * pn + EPS_LSB;
        /* T * T^-1 ~ I */
        DHT_EQ_INT(dh_frame_mul_q(&F, &I, &P), DH_OK);
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++) {
                double d = fabs((double)P.r[j][i] - (i == j ? Q30 : 0.0));
                DHT_TRUE_MSG(d <= brot, "T*T^-1 rotation entry (%d,%d): %.0f LSB > bound 3e + 0.5 = %.3f "
                             "(e %.3f LSB) for F = %s", i, j, d, brot, e, frame_str(&F, buf));
                if (d > worst_rid) worst_rid = d;
                if (d - brot > worst_slack) worst_slack = d - brot;
            }
            DHT_TRUE_MSG(fabs((double)P.p[i]) <= bpos, "T*T^-1 position %d: %ld LSB > bound %.3f (e %.3f LSB, "
                         "|p| %.4g) for F = %s", i, (long)P.p[i], bpos, e, pn, frame_str(&F, buf));
            if (fabs((double)P.p[i]) > worst_pid) worst_pid = fabs((double)P.p[i]);
        }
    }
    dht_reach_max("inv.rot_lsb", worst_rid); /* LSB: the largest rotation entry of T*T^-1 - I */
    dht_printf("inv: max p error %.4f LSB vs exact; T*T^-1: rotation max %.0f LSB, position max %.0f LSB "
               "(|p| <= 2^28 LSB); inputs' |R^T R - I| up to %.3f LSB (rotation bound 3e + 0.5, "
               "closest approach %.3f LSB)\n", worst_inv, worst_rid, worst_pid, worst_e, worst_slack);
}

static void inverse_saturates_and_exact_path(void)
{
    dh_frame_q F, I;
    long k, n = DHT_ITER(20000);
    int i, j, sat = 0;
    dh_frame_identity_q(&F);
    F.p[0] = INT32_MIN; /* -(-2^31) does not fit */
    DHT_EQ_INT(dh_frame_inv_q(&F, &I), DH_ERR_OVERFLOW);
    DHT_EQ_INT(I.p[0], INT32_MAX);
    DHT_EQ_INT(I.p[1], 0);
    for (k = 0; k < n; k++) {
        dh_status st;
        rnd_garbage(&F);
        st = dh_frame_inv_q(&F, &I);
        sat = 0;
        for (i = 0; i < 3; i++) {
            double s = 0.0;
            for (j = 0; j < 3; j++) s -= (double)F.r[i][j] * (double)F.p[j];
            (void)check_out(I.p[i], s / Q30, &sat);
        }
        if (sat) DHT_EQ_INT(st, DH_ERR_OVERFLOW);
    }
}

/* ---- points and directions -------------------------------------------------- */

static void apply_point_and_dir_vs_double(void)
{
    long k, n = DHT_ITER(50000);
    double worst = 0.0;
    int any_sat = 0;
    for (k = 0; k < n; k++) {
        dh_frame_q F;
        dh_vec3_q u, v, w;
        int32_t in[3], outp[3], outd[3];
        int i, j, sat = 0, satd = 0, which;
        dh_status sp, sd;
        which = (int)(k % 3);
        if (which == 2) rnd_garbage(&F); else rnd_rigid(&F, which ? 0x7FFFFFFF : (1 << 24));
        u.x = rnd_i32(); u.y = rnd_i32(); u.z = rnd_i32();
        if (which == 0) { u.x >>= 6; u.y >>= 6; u.z >>= 6; }
        in[0] = u.x; in[1] = u.y; in[2] = u.z;
        sp = dh_frame_apply_point_q(&F, &u, &v);
        sd = dh_frame_apply_dir_q(&F, &u, &w);
        outp[0] = v.x; outp[1] = v.y; outp[2] = v.z;
        outd[0] = w.x; outd[1] = w.y; outd[2] = w.z;
        for (i = 0; i < 3; i++) {
            double s = 0.0, e;
            for (j = 0; j < 3; j++) s += (double)F.r[j][i] * (double)in[j];
            e = check_out(outd[i], s / Q30, &satd);
            if (e > worst) worst = e;
            e = check_out(outp[i], (s + (double)F.p[i] * Q30) / Q30, &sat);
            if (e > worst) worst = e;
        }
        if (sat) DHT_EQ_INT(sp, DH_ERR_OVERFLOW);
        if (satd) DHT_EQ_INT(sd, DH_ERR_OVERFLOW);
        if (sp == DH_OK) DHT_EQ_INT(sat, 0);
        if (sd == DH_OK) DHT_EQ_INT(satd, 0);
        any_sat |= sat | satd;
        /* aliasing u == v */
        w = u;
        DHT_EQ_INT(dh_frame_apply_point_q(&F, &w, &w), sp);
        DHT_TRUE(w.x == v.x && w.y == v.y && w.z == v.z);
    }
    dht_printf("apply point/dir: max error %.4f LSB vs exact\n", worst);
    DHT_TRUE(any_sat);
}

/* ---- drift and re-orthonormalisation -------------------------------------- */

static void ortho_error_measure(void)
{
    dh_frame_q F;
    dh_frame_identity_q(&F);
    F.r[0][0] += 1000;          /* (1 + e)^2 - 1 = 2e + e^2 -> 2000 LSB */
    DHT_EQ_INT(dh_frame_ortho_error_q(&F), 2000);
    dh_frame_identity_q(&F);
    F.r[0][1] = 1 << 20;        /* col0.col1 = 2^20 LSB; col0.col0 - 1 = 2^40/2^30 = 1024 */
    DHT_EQ_INT(dh_frame_ortho_error_q(&F), 1 << 20);
    {   /* garbage saturates, never wraps */
        int i, j;
        for (i = 0; i < 3; i++) for (j = 0; j < 3; j++) F.r[i][j] = INT32_MIN;
        DHT_EQ_INT(dh_frame_ortho_error_q(&F), INT32_MAX);
        DHT_EQ_INT(dh_frame_orthonormalize_q(&F, &F), DH_ERR_NOT_RIGID);
        DHT_EQ_INT(F.r[1][2], INT32_MIN); /* untouched */
    }
    {   /* a negative dot product beyond -2 saturates to INT32_MIN, whose
         * magnitude 2^31 is reported as INT32_MAX */
        int j;
        dh_frame_identity_q(&F);
        for (j = 0; j < 3; j++) {
            F.r[0][j] = INT32_MIN;
            F.r[1][j] = INT32_MAX;
        }
        DHT_EQ_INT(dh_frame_ortho_error_q(&F), INT32_MAX);
    }
    /* refused in each direction of the 1/8 test: a column too short
     * (|c0|^2 - 1 = -3/4) and two columns at a negative angle
     * (c0 . c1 = -1/4), F untouched */
    dh_frame_identity_q(&F);
    F.r[0][0] = DH_Q30_ONE / 2;
    DHT_EQ_INT(dh_frame_orthonormalize_q(&F, &F), DH_ERR_NOT_RIGID);
    DHT_EQ_INT(F.r[0][0], DH_Q30_ONE / 2);
    dh_frame_identity_q(&F);
    F.r[1][0] = -DH_Q30_ONE / 4;
    DHT_EQ_INT(dh_frame_orthonormalize_q(&F, &F), DH_ERR_NOT_RIGID);
    DHT_EQ_INT(F.r[1][0], -DH_Q30_ONE / 4);
    DHT_EQ_INT(F.r[1][1], DH_Q30_ONE);
    /* just inside: c0 . c1 = -1/16 is repaired to about 3/4 (1/16)^2 =
     * 3.1e6 LSB (quadratic convergence), below 2^22 */
    F.r[1][0] = -DH_Q30_ONE / 16;
    DHT_EQ_INT(dh_frame_orthonormalize_q(&F, &F), DH_OK);
    DHT_TRUE_MSG(dh_frame_ortho_error_q(&F) < (1 << 22), "after one step from 1/16: %ld",
                 (long)dh_frame_ortho_error_q(&F));
    /* one step repairs a visibly perturbed rotation */
    DHT_EQ_INT(dh_frame_rot_axis_q(3, -4, 12, 77 * 65536, &F), DH_OK);
    F.r[0][0] += 10000; F.r[1][2] -= 8000; F.r[2][1] += 6000;
    DHT_TRUE(dh_frame_ortho_error_q(&F) > 10000);
    {   /* out of place: the same step */
        dh_frame_q G;
        DHT_EQ_INT(dh_frame_orthonormalize_q(&F, &G), DH_OK);
        DHT_EQ_INT(dh_frame_orthonormalize_q(&F, &F), DH_OK);
        DHT_TRUE(memcmp(&F, &G, sizeof F) == 0);
    }
    DHT_TRUE_MSG(dh_frame_ortho_error_q(&F) <= 2, "after one step %ld", (long)dh_frame_ortho_error_q(&F));
    /* far from orthonormal: refused, F untouched (in place and out of place) */
    F.r[0][0] = DH_Q30_ONE / 2;
    {
        dh_frame_q G = F, H, K;
        DHT_EQ_INT(dh_frame_orthonormalize_q(&F, &F), DH_ERR_NOT_RIGID);
        DHT_TRUE(memcmp(&F, &G, sizeof F) == 0);
        dh_frame_identity_q(&H);
        K = H;
        DHT_EQ_INT(dh_frame_orthonormalize_q(&F, &H), DH_ERR_NOT_RIGID);
        DHT_TRUE(memcmp(&H, &K, sizeof H) == 0);
    }
}

static void drift_bounded_with_orthonormalisation(void)
{
    long k, n = DHT_ITER(100000);
    dh_frame_q Fa, Fb, S[4];
    int32_t ea = 0, eb_max = 0;
    int i;
    /* small rotations about a few fixed axes, applied in a varying order */
    DHT_EQ_INT(dh_frame_rot_axis_q(1, 2, 3, 65536 / 3, &S[0]), DH_OK);
    DHT_EQ_INT(dh_frame_rot_axis_q(-5, 1, 2, 65536 / 7, &S[1]), DH_OK);
    DHT_EQ_INT(dh_frame_rot_axis_q(0x40000000, 0, 7, 12345, &S[2]), DH_OK);
    DHT_EQ_INT(dh_frame_rot_axis_q(2, -9, 1, 65536 / 2 + 3, &S[3]), DH_OK);
    dh_frame_identity_q(&Fa);
    dh_frame_identity_q(&Fb);
    for (k = 0; k < n; k++) {
        const dh_frame_q *s = &S[dht_rand_u32() & 3u];
        DHT_EQ_INT(dh_frame_mul_q(&Fa, s, &Fa), DH_OK);
        DHT_EQ_INT(dh_frame_mul_q(&Fb, s, &Fb), DH_OK);
        if ((k & 63) == 63) {
            DHT_EQ_INT(dh_frame_orthonormalize_q(&Fb, &Fb), DH_OK);
            i = dh_frame_ortho_error_q(&Fb);
            if (i > eb_max) eb_max = i;
        }
    }
    ea = dh_frame_ortho_error_q(&Fa);
    dht_printf("drift after %ld compositions: |R^T R - I| = %ld LSB without re-orthonormalisation, "
               "max %ld LSB with one step every 64\n", n, (long)ea, (long)eb_max);
    DHT_TRUE(eb_max <= 4);
    DHT_TRUE(ea > 8 * (eb_max + 1) || n < 100000);
    DHT_TRUE(ea > eb_max);
}

/* ---- conversions ------------------------------------------------------------ */

static void conversions(void)
{
    dh_mat4_f32 T, U;
    dh_frame_q F, G;
    long k, n = DHT_ITER(20000);
    int i, j;
    const double ps = ldexp(1.0, DH_QPOS_FRAC);
    for (k = 0; k < n; k++) {
        rnd_rigid(&F, 0x7FFFFFFF);
        dh_frame_to_mat4_q(&F, &T);
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++) {
                double ref = (double)F.r[j][i] / Q30;
                DHT_TRUE(fabs(DH_M4(&T, i, j) - ref) <= fabs(ref) * ldexp(1.0, -24));
            }
            DHT_TRUE(fabs(DH_M4(&T, i, 3) - F.p[i] / ps) <= fabs(F.p[i] / ps) * ldexp(1.0, -24));
            DHT_TRUE(DH_M4(&T, 3, i) == 0.0f);
        }
        DHT_TRUE(DH_M4(&T, 3, 3) == 1.0f);
        /* float -> fixed: nearest integer to x * 2^k */
        {
            dh_status st = dh_frame_from_mat4_q(&T, &G);
            int sat = 0;
            for (i = 0; i < 3; i++) {
                for (j = 0; j < 3; j++) {
                    double x = (double)DH_M4(&T, i, j) * Q30;
                    DHT_NEAR(G.r[j][i], x, 0.5);
                    DHT_NEAR(G.r[j][i], F.r[j][i], fabs((double)F.r[j][i]) * ldexp(1.0, -24) + 0.5);
                }
                {
                    double x = (double)DH_M4(&T, i, 3) * ps;
                    if (x >= 2147483648.0) { sat = 1; DHT_EQ_INT(G.p[i], INT32_MAX); }
                    else DHT_NEAR(G.p[i], x, 0.5);
                }
            }
            DHT_EQ_INT(st, sat ? DH_ERR_OVERFLOW : DH_OK);
        }
    }
    /* exact values round-trip exactly; ties away from zero */
    dh_frame_identity_q(&F);
    F.r[0][1] = 3; F.r[1][0] = -3; F.p[0] = -(1 << 20); F.p[2] = 12345;
    dh_frame_to_mat4_q(&F, &T);
    DHT_EQ_INT(dh_frame_from_mat4_q(&T, &G), DH_OK);
    DHT_TRUE(memcmp(&F, &G, sizeof F) == 0);
    DH_M4(&T, 0, 0) = (float)(2.5 / Q30);
    DH_M4(&T, 1, 1) = (float)(-2.5 / Q30);
    DHT_EQ_INT(dh_frame_from_mat4_q(&T, &G), DH_OK);
    DHT_EQ_INT(G.r[0][0], 3);
    DHT_EQ_INT(G.r[1][1], -3);
    /* rotation entry 2.0 does not fit Q2.30 ([-2, 2)); -2.0 does */
    U = T;
    DH_M4(&U, 2, 2) = 2.0f;
    DH_M4(&U, 0, 2) = -2.0f;
    DHT_EQ_INT(dh_frame_from_mat4_q(&U, &G), DH_ERR_OVERFLOW);
    DHT_EQ_INT(G.r[2][2], INT32_MAX);
    DHT_EQ_INT(G.r[2][0], INT32_MIN);
    DHT_EQ_INT(G.r[0][0], 3);
    /* position out of range */
    U = T;
    DH_M4(&U, 1, 3) = -(float)ldexp(1.0, 31 - DH_QPOS_FRAC) * 1.5f;
    DHT_EQ_INT(dh_frame_from_mat4_q(&U, &G), DH_ERR_OVERFLOW);
    DHT_EQ_INT(G.p[1], INT32_MIN);
    /* non-finite: F untouched */
    U = T;
    DH_M4(&U, 3, 2) = (float)NAN;
    memset(&G, 0x11, sizeof G);
    F = G;
    DHT_EQ_INT(dh_frame_from_mat4_q(&U, &G), DH_ERR_NAN);
    DHT_TRUE(memcmp(&F, &G, sizeof F) == 0);
    U = T;
    DH_M4(&U, 2, 1) = (float)INFINITY;
    DHT_EQ_INT(dh_frame_from_mat4_q(&U, &G), DH_ERR_NAN);
    DHT_TRUE(memcmp(&F, &G, sizeof F) == 0);
    /* bottom row */
    U = T;
    DH_M4(&U, 3, 0) = 0.25f;
    DHT_EQ_INT(dh_frame_from_mat4_q(&U, &G), DH_ERR_NOT_RIGID);
    DHT_EQ_INT(G.r[0][0], 3);
}

static const dht_case cases[] = {
    DHT_CASE(identity_and_translation_are_exact),
    DHT_CASE(elementary_rotations),
    DHT_CASE(axis_rotation_vs_double),
    DHT_CASE(axis_rotation_special_cases),
    DHT_CASE(compose_rigid_vs_double),
    DHT_CASE(compose_arbitrary_entries_exact_path),
    DHT_CASE(compose_accumulator_extremes),
    DHT_CASE(inverse_vs_double_and_identity),
    DHT_CASE(inverse_saturates_and_exact_path),
    DHT_CASE(apply_point_and_dir_vs_double),
    DHT_CASE(ortho_error_measure),
    DHT_CASE(drift_bounded_with_orthonormalisation),
    DHT_CASE(conversions),
};
DHT_MAIN(cases)
