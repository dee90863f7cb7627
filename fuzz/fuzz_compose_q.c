/* SPDX-License-Identifier: Apache-2.0 */
/*
 * fuzz_compose_q.c - fixed-point frame arithmetic (frame.h) against an
 * exact 128-bit integer reference computed here.
 *
 * Invariants:
 *  - dh_frame_mul_q, dh_frame_inv_q, dh_frame_apply_point_q/_dir_q: every
 *    output entry equals floor((exact sum + 2^29) / 2^30) saturated to
 *    int32 -- bit for bit, for ANY int32 inputs (the contract promises one
 *    rounding, ties up, so "a few LSB" is not needed); the status is
 *    DH_ERR_OVERFLOW exactly when some entry saturated, else DH_OK;
 *    aliasing (out == A, out == B, out == A == B, v == u) gives the same
 *    bits and status;
 *  - dh_frame_rot_axis_q: DH_ERR_ZERO_AXIS (frame untouched) for a zero
 *    axis, else within 2.5 LSB of the double-precision Rodrigues formula
 *    and |R^T R - I| <= 2 LSB (the contract's measured figures);
 *  - dh_frame_rotx/y/z_q: entries exactly the dh_sincos_q values;
 *  - dh_frame_ortho_error_q: equals the exact 128-bit value;
 *  - dh_frame_orthonormalize_q: DH_ERR_NOT_RIGID leaves F untouched;
 *    DH_OK only within its documented domain (entries <= 1.25, error
 *    <= 1/8), never DH_ERR_OVERFLOW, and the error after one Newton step
 *    is at most 2.25 e^2 + 2.25 e^3 (from E' = -3/4 E^2 + 1/4 E^3 with
 *    |(E^2)_ij| <= 3 e^2) plus 16 LSB of rounding.
 * Input: a mode byte (0: raw int32 frames; 1: rotations from
 * dh_frame_rot_axis_q with raw positions; 2: mode 1 plus a perturbation of
 * up to 2^(b) LSB per entry), then the integers.
 */
#include <math.h>

#include "dhmath/frame.h"
#include "dhmath/trig.h"
#include "fuzz_common.h"

__extension__ typedef __int128 i128;

#define ONE30 ((i128)1 << 30)
#define HALF30 ((i128)1 << 29)

static int32_t ref_round(i128 sum, int *sat)
{
    i128 r = (sum + HALF30) >> 30; /* arithmetic shift: floor */
    if (r > (i128)INT32_MAX) { *sat = 1; return INT32_MAX; }
    if (r < (i128)INT32_MIN) { *sat = 1; return INT32_MIN; }
    return (int32_t)r;
}

static int frame_eq(const dh_frame_q *a, const dh_frame_q *b)
{
    return memcmp(a, b, sizeof *a) == 0;
}

static void print_frame(const char *name, const dh_frame_q *F)
{
    unsigned i;
    fprintf(stderr, "%s: r(row-wise)", name);
    for (i = 0; i < 3u; i++)
        fprintf(stderr, " [%ld %ld %ld]", (long)F->r[0][i], (long)F->r[1][i], (long)F->r[2][i]);
    fprintf(stderr, " p [%ld %ld %ld]\n", (long)F->p[0], (long)F->p[1], (long)F->p[2]);
}

static void check_mul(const dh_frame_q *A, const dh_frame_q *B)
{
    dh_frame_q ref, out, X;
    int sat = 0;
    unsigned i, j, k;
    dh_status st, st2;

    /* element (row i, col j) is r[j][i] */
    for (i = 0; i < 3u; i++) {
        for (j = 0; j < 3u; j++) {
            i128 s = 0;
            for (k = 0; k < 3u; k++) s += (i128)A->r[k][i] * B->r[j][k];
            ref.r[j][i] = ref_round(s, &sat);
        }
        {
            i128 s = (i128)A->p[i] * ONE30;
            for (k = 0; k < 3u; k++) s += (i128)A->r[k][i] * B->p[k];
            ref.p[i] = ref_round(s, &sat);
        }
    }
    memset(&out, 0x5a, sizeof out);
    st = dh_frame_mul_q(A, B, &out);
    if (!frame_eq(&out, &ref) || st != (sat ? DH_ERR_OVERFLOW : DH_OK)) {
        print_frame("A", A);
        print_frame("B", B);
        print_frame("out", &out);
        print_frame("ref", &ref);
    }
    FZ_CHECK(frame_eq(&out, &ref), "dh_frame_mul_q differs from the exact reference (st %d)", (int)st);
    FZ_CHECK(st == (sat ? DH_ERR_OVERFLOW : DH_OK), "dh_frame_mul_q status %d, saturated %d", (int)st, sat);

    X = *A;
    st2 = dh_frame_mul_q(&X, B, &X);
    FZ_CHECK(frame_eq(&X, &ref) && st2 == st, "dh_frame_mul_q(out == A) differs");
    X = *B;
    st2 = dh_frame_mul_q(A, &X, &X);
    FZ_CHECK(frame_eq(&X, &ref) && st2 == st, "dh_frame_mul_q(out == B) differs");
    {
        dh_frame_q AA;
        dh_status sta = dh_frame_mul_q(A, A, &AA);
        X = *A;
        st2 = dh_frame_mul_q(&X, &X, &X);
        FZ_CHECK(frame_eq(&X, &AA) && st2 == sta, "dh_frame_mul_q(out == A == B) differs");
    }
}

static void check_inv(const dh_frame_q *F)
{
    dh_frame_q ref, out;
    int sat = 0;
    unsigned i, j, k;
    dh_status st;

    for (i = 0; i < 3u; i++)
        for (j = 0; j < 3u; j++) ref.r[i][j] = F->r[j][i];
    for (i = 0; i < 3u; i++) {
        i128 s = 0;
        /* row i of R^T = column i of R = F->r[i][k] */
        for (k = 0; k < 3u; k++) s -= (i128)F->r[i][k] * F->p[k];
        ref.p[i] = ref_round(s, &sat);
    }
    memset(&out, 0x5a, sizeof out);
    st = dh_frame_inv_q(F, &out);
    if (!frame_eq(&out, &ref)) {
        print_frame("F", F);
        print_frame("out", &out);
        print_frame("ref", &ref);
    }
    FZ_CHECK(frame_eq(&out, &ref), "dh_frame_inv_q differs from the exact reference");
    FZ_CHECK(st == (sat ? DH_ERR_OVERFLOW : DH_OK), "dh_frame_inv_q status %d, saturated %d", (int)st, sat);
    out = *F;
    FZ_CHECK(dh_frame_inv_q(&out, &out) == st && frame_eq(&out, &ref), "dh_frame_inv_q in place differs");
}

static void check_apply(const dh_frame_q *F, const dh_vec3_q *u)
{
    int pass;
    for (pass = 0; pass < 2; pass++) {
        const int32_t uu[3] = { u->x, u->y, u->z };
        int32_t ref[3];
        int sat = 0;
        unsigned i, k;
        dh_vec3_q v, w;
        dh_status st;
        for (i = 0; i < 3u; i++) {
            i128 s = pass == 0 ? (i128)F->p[i] * ONE30 : 0;
            for (k = 0; k < 3u; k++) s += (i128)F->r[k][i] * uu[k];
            ref[i] = ref_round(s, &sat);
        }
        st = pass == 0 ? dh_frame_apply_point_q(F, u, &v) : dh_frame_apply_dir_q(F, u, &v);
        FZ_CHECK(v.x == ref[0] && v.y == ref[1] && v.z == ref[2],
                 "%s: [%ld %ld %ld] vs exact [%ld %ld %ld]", pass == 0 ? "apply_point" : "apply_dir",
                 (long)v.x, (long)v.y, (long)v.z, (long)ref[0], (long)ref[1], (long)ref[2]);
        FZ_CHECK(st == (sat ? DH_ERR_OVERFLOW : DH_OK), "apply status %d, saturated %d", (int)st, sat);
        w = *u;
        st = pass == 0 ? dh_frame_apply_point_q(F, &w, &w) : dh_frame_apply_dir_q(F, &w, &w);
        FZ_CHECK(w.x == v.x && w.y == v.y && w.z == v.z && st == (sat ? DH_ERR_OVERFLOW : DH_OK),
                 "apply in place differs");
    }
}

/* exact max |(R^T R - I)_ij| in LSB, rounded as the library documents */
static i128 ref_ortho_error(const dh_frame_q *F)
{
    i128 worst = 0;
    unsigned i, j, k;
    for (i = 0; i < 3u; i++)
        for (j = i; j < 3u; j++) {
            i128 s = (i == j) ? -((i128)1 << 60) : 0, r;
            for (k = 0; k < 3u; k++) s += (i128)F->r[i][k] * F->r[j][k];
            r = (s + HALF30) >> 30;
            if (r < 0) r = -r;
            if (r > worst) worst = r;
        }
    return worst;
}

static void check_ortho(const dh_frame_q *F)
{
    const i128 e = ref_ortho_error(F);
    const int32_t lib = dh_frame_ortho_error_q(F);
    dh_frame_q G = *F;
    dh_status st;
    unsigned i, j, big = 0;

    FZ_CHECK(lib == (e > INT32_MAX ? INT32_MAX : (int32_t)e), "ortho_error %ld vs exact %.0f", (long)lib,
             (double)e);
    st = dh_frame_orthonormalize_q(&G, &G);
    FZ_CHECK(st == DH_OK || st == DH_ERR_NOT_RIGID, "orthonormalize status %d", (int)st);
    for (i = 0; i < 3u; i++)
        for (j = 0; j < 3u; j++)
            if (F->r[i][j] > 0x50000000 || F->r[i][j] < -0x50000000) big = 1;
    if (st == DH_ERR_NOT_RIGID) {
        FZ_CHECK(frame_eq(&G, F), "orthonormalize changed F on DH_ERR_NOT_RIGID");
        /* a frame well inside the domain must be accepted (the exact test
         * is on the unrounded error, so leave 2 LSB of margin) */
        FZ_CHECK(big || e > ((i128)1 << 27) - 2, "orthonormalize rejected e = %.0f LSB", (double)e);
        return;
    }
    FZ_CHECK(!big && e <= ((i128)1 << 27) + 2, "orthonormalize accepted e = %.0f LSB (big %u)", (double)e, big);
    FZ_CHECK(G.p[0] == F->p[0] && G.p[1] == F->p[1] && G.p[2] == F->p[2], "orthonormalize moved p");
    {
        const double ed = (double)e / 1073741824.0;
        const double bound = (2.25 * ed * ed + 2.25 * ed * ed * ed) * 1073741824.0 + 16.0;
        const double after = (double)ref_ortho_error(&G);
        FZ_CHECK(after <= bound, "orthonormalize: error %.0f LSB -> %.0f LSB (bound %.1f)", (double)e,
                 after, bound);
    }
}

static void check_rot_axis(int32_t kx, int32_t ky, int32_t kz, int32_t deg)
{
    dh_frame_q F, G;
    dh_status st;
    memset(&F, 0x33, sizeof F);
    G = F;
    st = dh_frame_rot_axis_q(kx, ky, kz, deg, &F);
    if (kx == 0 && ky == 0 && kz == 0) {
        FZ_CHECK(st == DH_ERR_ZERO_AXIS && frame_eq(&F, &G), "zero axis: st %d", (int)st);
        return;
    }
    FZ_CHECK(st == DH_OK, "rot_axis st %d", (int)st);
    {
        const double n = sqrt((double)kx * kx + (double)ky * ky + (double)kz * kz);
        const double k[3] = { kx / n, ky / n, kz / n };
        const double t = fmod((double)deg / 65536.0, 360.0) * (3.14159265358979323846 / 180.0);
        const double c = cos(t), s = sin(t), v = 1.0 - c;
        double R[3][3]; /* row, col */
        double worst = 0.0;
        unsigned i, j;
        R[0][0] = k[0] * k[0] * v + c;        R[0][1] = k[0] * k[1] * v - k[2] * s; R[0][2] = k[0] * k[2] * v + k[1] * s;
        R[1][0] = k[0] * k[1] * v + k[2] * s; R[1][1] = k[1] * k[1] * v + c;        R[1][2] = k[1] * k[2] * v - k[0] * s;
        R[2][0] = k[0] * k[2] * v - k[1] * s; R[2][1] = k[1] * k[2] * v + k[0] * s; R[2][2] = k[2] * k[2] * v + c;
        for (i = 0; i < 3u; i++)
            for (j = 0; j < 3u; j++) {
                const double e = fabs((double)F.r[j][i] - R[i][j] * 1073741824.0);
                if (e > worst) worst = e;
            }
        FZ_CHECK(worst <= 2.5, "rot_axis(%ld, %ld, %ld, %ld): entry error %.3f LSB", (long)kx, (long)ky,
                 (long)kz, (long)deg, worst);
        FZ_CHECK(ref_ortho_error(&F) <= 2, "rot_axis(%ld, %ld, %ld, %ld): ortho error %.0f LSB", (long)kx,
                 (long)ky, (long)kz, (long)deg, (double)ref_ortho_error(&F));
        FZ_CHECK(F.p[0] == 0 && F.p[1] == 0 && F.p[2] == 0, "rot_axis position not 0");
    }
}

static void check_elem(int32_t deg)
{
    dh_frame_q X, Y, Z;
    dh_q30 s, c;
    dh_sincos_q(deg, &s, &c);
    dh_frame_rotx_q(deg, &X);
    dh_frame_roty_q(deg, &Y);
    dh_frame_rotz_q(deg, &Z);
    /* (row, col) = r[col][row] */
    FZ_CHECK(X.r[0][0] == DH_Q30_ONE && X.r[1][1] == c && X.r[2][1] == -s && X.r[1][2] == s && X.r[2][2] == c &&
                 X.r[0][1] == 0 && X.r[0][2] == 0 && X.r[1][0] == 0 && X.r[2][0] == 0,
             "rotx(%ld) entries", (long)deg);
    FZ_CHECK(Y.r[1][1] == DH_Q30_ONE && Y.r[0][0] == c && Y.r[2][0] == s && Y.r[0][2] == -s && Y.r[2][2] == c &&
                 Y.r[1][0] == 0 && Y.r[1][2] == 0 && Y.r[0][1] == 0 && Y.r[2][1] == 0,
             "roty(%ld) entries", (long)deg);
    FZ_CHECK(Z.r[2][2] == DH_Q30_ONE && Z.r[0][0] == c && Z.r[1][0] == -s && Z.r[0][1] == s && Z.r[1][1] == c &&
                 Z.r[2][0] == 0 && Z.r[2][1] == 0 && Z.r[0][2] == 0 && Z.r[1][2] == 0,
             "rotz(%ld) entries", (long)deg);
    FZ_CHECK(X.p[0] == 0 && X.p[1] == 0 && X.p[2] == 0 && Z.p[2] == 0, "elementary rotation position");
}

static void read_frame(fz_in *in, dh_frame_q *F, unsigned mode)
{
    unsigned i, j;
    if (mode == 0u) {
        for (i = 0; i < 3u; i++)
            for (j = 0; j < 3u; j++) F->r[i][j] = fz_i32(in);
    } else {
        int32_t kx = fz_i32(in), ky = fz_i32(in), kz = fz_i32(in), deg = fz_i32(in);
        if (dh_frame_rot_axis_q(kx, ky, kz, deg, F) != DH_OK) dh_frame_identity_q(F);
        if (mode == 2u) {
            const unsigned b = fz_u8(in) % 28u;
            for (i = 0; i < 3u; i++)
                for (j = 0; j < 3u; j++) F->r[i][j] += fz_i32(in) >> (31u - b); /* |delta| <= 2^b */
        }
    }
    for (i = 0; i < 3u; i++) {
        F->p[i] = fz_i32(in);
        if (mode != 0u) F->p[i] >>= fz_u8(in) & 31u; /* small positions are common in robots */
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in;
    dh_frame_q A, B;
    dh_vec3_q u;
    unsigned mode;

    in.p = data;
    in.n = size;
    mode = fz_u8(&in) % 3u;
    read_frame(&in, &A, mode);
    read_frame(&in, &B, mode);
    u.x = fz_i32(&in);
    u.y = fz_i32(&in);
    u.z = fz_i32(&in);

    check_mul(&A, &B);
    check_inv(&A);
    check_apply(&A, &u);
    check_ortho(&A);
    check_rot_axis(u.x, u.y, u.z, B.p[0]);
    check_elem(B.p[1]);
    return 0;
}
