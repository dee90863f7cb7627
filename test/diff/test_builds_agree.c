/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_builds_agree - the default build and the size-first build
 * (DH_SMALL=1) agree on every public function.
 *
 * The library is linked twice: as dhmath (the configuration of this build
 * tree) and as a copy built with the other DH_SMALL value whose symbols are
 * renamed dhalt_* (test/diff/CMakeLists.txt). Every public function runs
 * on the same inputs in both (diff_calls.inc) and the outputs are compared
 * BITWISE, statuses included, outputs that must stay untouched included
 * (both are pre-filled with the same canary). Inputs: random data of the
 * function's domain mixed with edge values (NaN, +-Inf, +-0, subnormals,
 * FLT_MIN/FLT_MAX, huge values, whole degrees and multiples of 90, int32
 * edges INT32_MIN/INT32_MAX, +-2^30), in-place calls where the contract
 * allows them, and random standard / modified DH robots (revolute and
 * prismatic joints, exact and general twists, offsets, limits, float and
 * fixed base/tool, lengths that do not fit the fixed format, corrupted n).
 *
 * Documented exceptions (docs/design.md, "Size-first build"), checked
 * against their bound instead of bitwise:
 * - dh_mat4_inv_f32 / dh_mat4_inv_auto_f32: same status; values within
 *   the general inverse's bound (mat4.h): each build is within
 *   3.2 * cond * 2^-24 * max|T^-1| of T^-1 (cond: the smallest balanced
 *   1-norm condition number over D = diag(1, 1, 1, 2^k)), so the two may
 *   differ by twice that;
 * - dh_mat4_apply_plane_f32: same status; Q = P T^-1 within that bound
 *   carried through P plus the rounding of the product;
 * - dh_link_f32, dh_fk_f32, dh_fk_frames_f32: a zero entry may have the
 *   other sign (everything else bitwise; zero signs outside the places
 *   robot.h names are counted apart, see zero_documented).
 * Accepted everywhere and counted: a float output that is a NaN in both
 * builds may differ in payload and sign (IEEE 754 leaves them open; the
 * two builds combine NaN operands in different orders). Accepted for the
 * plane transform and counted: the default build's rigid closed form for a
 * T that is rigid only within DH_MAT4_RIGID_TOL (see plane_rigid_err).
 *
 * Counts: 10^6 inputs per function (dh_ik_f32 included, DIFF_IK_COUNT),
 * 10^5 for dh_ik_q (DIFF_IKQ_COUNT).
 * DHT_SEED selects the seed (printed on failure); DHT_DIFF_DIV divides
 * every count (quick local runs); DHT_DIFF_ONLY=<substring> runs only the
 * functions whose name contains it.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "dht.h"

/* dh_ik_f32: 10^6 solves with max_iter 1..64 and 0..3 restarts (about
 * 12 us per input for the two builds on an x86-64 host, against 0.3 us for
 * FK: the largest share of the test's time). */
#define DIFF_IK_COUNT 1000000
/* closed-form IK: 3 * 10^5 inputs per function (a few us per solve) */
#define DIFF_IKC_COUNT 300000
#define DIFF_IKQ_COUNT 100000

#include "diff_api.h"

/* ---- random data -------------------------------------------------------- */

static uint32_t ru(void) { return dht_rand_u32(); }
static uint32_t rn(uint32_t n) { return (uint32_t)(((uint64_t)ru() * n) >> 32); }
static double rd(double lo, double hi) { return dht_rand_uniform(lo, hi); }
static float fbits(uint32_t u) { float f; memcpy(&f, &u, 4); return f; }
static uint32_t bitsf(float f) { uint32_t u; memcpy(&u, &f, 4); return u; }

static const uint32_t edge_f[] = {
    0x7FC00000u, 0xFFC00000u, 0x7F800001u, 0x7FFFFFFFu, /* NaNs (quiet, signalling) */
    0x7F800000u, 0xFF800000u,                           /* +-Inf */
    0x00000000u, 0x80000000u,                           /* +-0 */
    0x00000001u, 0x80000001u, 0x007FFFFFu, 0x807FFFFFu, 0x00400000u, /* subnormals */
    0x00800000u, 0x80800000u,                           /* +-FLT_MIN */
    0x7F7FFFFFu, 0xFF7FFFFFu, 0x7F000000u, 0x5F000000u, 0xDF000000u, /* FLT_MAX, huge */
    0x3F800000u, 0xBF800000u, 0x3F000000u, 0x34000000u, /* 1, -1, 0.5, 2^-23 */
    0x4B000000u, 0x4AFFFFFFu, 0x4B000001u, 0xCB000000u, /* 2^23 and neighbours */
    0x4F000000u, 0xCF000000u, 0x47000000u, 0xC7000000u, /* 2^31, 32768 */
    0x42B40000u, 0xC2B40000u, 0x43340000u, 0xC3340000u, /* +-90, +-180 */
    0x43870000u, 0x43B40000u, 0xC3B40000u, 0x42340000u, /* 270, +-360, 45 */
    0x0C000000u, 0x72000000u, 0x1E3CE508u, 0x60AD78ECu  /* 2^-103, 2^101, 1e-20, 1e20 */
};
#define N_EDGE_F (sizeof edge_f / sizeof edge_f[0])

static float f_edge(void) { return fbits(edge_f[rn((uint32_t)N_EDGE_F)]); }

/* a float of magnitude around `scale`, with edge values mixed in */
static float f_gen(double scale)
{
    switch (rn(16u)) {
    case 0: return f_edge();
    case 1: return fbits(ru());                                   /* any bit pattern */
    case 2: return (float)((int32_t)rn(2001u) - 1000);            /* whole numbers */
    case 3: return (float)(90 * ((int32_t)rn(81u) - 40));         /* multiples of 90 */
    case 4: return (float)ldexp(rd(-1.0, 1.0), (int)rn(120u) - 60); /* any scale */
    case 5: return (float)(scale * (double)((int32_t)rn(9u) - 4) / 4.0); /* simple fractions */
    default: return (float)rd(-scale, scale);
    }
}

/* a float that is mostly a valid value in [-scale, scale] (edges 1/64) */
static float f_mild(double scale)
{
    uint32_t k = rn(64u);
    if (k == 0u) return f_edge();
    if (k < 8u) return (float)(90 * ((int32_t)rn(9u) - 4));
    if (k < 12u) return 0.0f;
    return (float)rd(-scale, scale);
}

static float f_angle(void)
{
    switch (rn(12u)) {
    case 0: return f_edge();
    case 1: return fbits(ru());
    case 2: return (float)((int32_t)rn(1441u) - 720);
    case 3: return (float)(90 * ((int32_t)rn(41u) - 20));
    case 4: return (float)rd(-1e7, 1e7);
    case 5: return (float)ldexp(rd(-1.0, 1.0), (int)rn(150u) - 20); /* up to 2^130 -> Inf */
    case 6: return (float)((int32_t)rn(721u) - 360) + (float)rd(-1e-3, 1e-3);
    case 7: return (float)rd(-0.5, 0.5);
    default: return (float)rd(-720.0, 720.0);
    }
}

static const int32_t edge_i[] = {
    INT32_MIN, INT32_MIN + 1, INT32_MAX, INT32_MAX - 1, 0, 1, -1, 2, -2,
    0x40000000, -0x40000000, 0x3FFFFFFF, -0x3FFFFFFF, 0x20000000, -0x20000000,
    0x7FFF0000, (int32_t)0x80010000u, 0x00010000, -0x00010000,
    90 << 16, -(90 << 16), 180 << 16, -(180 << 16), 270 << 16, 360 << 16, 45 << 16,
    0x5A0000 + 1, 0x5A0000 - 1, 0x01000000, 0x00FFFFFF, 0x00008000, 0x7FFFFFF0
};
#define N_EDGE_I (sizeof edge_i / sizeof edge_i[0])

static int32_t i_gen(void)
{
    switch (rn(8u)) {
    case 0: case 1: return edge_i[rn((uint32_t)N_EDGE_I)];
    case 2: return (int32_t)rn(81u) - 40;
    case 3: return (int32_t)ru() >> rn(31u);
    case 4: return ((int32_t)rn(721u) - 360) * 65536;
    default: return (int32_t)ru();
    }
}

static void v3_gen(dh_vec3_f32 *v, double scale)
{
    v->x = f_gen(scale); v->y = f_gen(scale); v->z = f_gen(scale);
}

/* a rotation matrix (main library), exact multiples of 90 now and then */
static void rot3_exact(dh_mat3_f32 *R)
{
    float a[3];
    int i;
    for (i = 0; i < 3; i++) {
        uint32_t k = rn(8u);
        if (k == 0u) a[i] = (float)(90 * ((int32_t)rn(9u) - 4));
        else if (k == 1u) a[i] = (float)rd(-1e-4, 1e-4);
        else if (k == 2u) a[i] = 180.0f + (float)rd(-1e-3, 1e-3);
        else a[i] = (float)rd(-180.0, 180.0);
    }
    if (dh_euler_to_mat3_f32((dh_euler_seq)rn(24u), a, R) != DH_OK) DHT_TRUE(0);
}

static void mat3_perturb(dh_mat3_f32 *R, double eps)
{
    int c, r;
    for (c = 0; c < 3; c++)
        for (r = 0; r < 3; r++) R->m[c][r] += (float)rd(-eps, eps);
}

static void mat3_gen(dh_mat3_f32 *R)
{
    static const double eps[] = { 1e-7, 1e-6, 3e-5, 5e-5, 1e-4, 2e-4, 5e-4, 1e-3, 3e-3, 0.05, 0.2, 0.4 };
    int c, r;
    uint32_t k = rn(16u);
    rot3_exact(R);
    if (k < 7u) return;
    if (k < 12u) { mat3_perturb(R, eps[rn(12u)]); return; }
    if (k == 12u) { for (r = 0; r < 3; r++) R->m[0][r] = -R->m[0][r]; return; } /* reflection */
    if (k == 13u) { R->m[rn(3u)][rn(3u)] = f_edge(); return; }
    if (k == 14u) {
        double s = ldexp(1.0, (int)rn(60u) - 30);
        for (c = 0; c < 3; c++) for (r = 0; r < 3; r++) R->m[c][r] = (float)(R->m[c][r] * s);
        return;
    }
    for (c = 0; c < 3; c++) for (r = 0; r < 3; r++) R->m[c][r] = f_gen(2.0);
}

static void mat4_set_rot(dh_mat4_f32 *M, const dh_mat3_f32 *R)
{
    int c, r;
    for (c = 0; c < 3; c++)
        for (r = 0; r < 3; r++) M->m[c][r] = R->m[c][r];
}

static double len_scale(void)
{
    static const double s[] = { 0.0, 1e-3, 0.1, 1.0, 1.0, 10.0, 1000.0, 1e5, 1e6, 1e20 };
    return s[rn(10u)];
}

/* a rigid transform: exact rotation and a translation of a random scale */
static void mat4_rigid(dh_mat4_f32 *M)
{
    dh_mat3_f32 R;
    double s = len_scale();
    rot3_exact(&R);
    dh_mat4_identity_f32(M);
    mat4_set_rot(M, &R);
    M->m[3][0] = (float)rd(-s, s);
    M->m[3][1] = (float)rd(-s, s);
    M->m[3][2] = (float)rd(-s, s);
}

static void mat4_gen(dh_mat4_f32 *M)
{
    int c, r;
    uint32_t k = rn(20u);
    mat4_rigid(M);
    switch (k) {
    case 0: case 1: case 2: case 3: case 4:
        return;                                         /* rigid */
    case 5: case 6: {                                   /* nearly rigid */
        dh_mat3_f32 R;
        static const double eps[] = { 1e-7, 3e-6, 9e-6, 1.1e-5, 5e-5, 1e-4, 1e-3, 1e-2 };
        double e = eps[rn(8u)];
        for (c = 0; c < 3; c++) for (r = 0; r < 3; r++) R.m[c][r] = M->m[c][r] + (float)rd(-e, e);
        mat4_set_rot(M, &R);
        return;
    }
    case 7: {                                           /* scaled rigid */
        double s = rn(2u) ? ldexp(1.0, (int)rn(80u) - 40) : rd(-10.0, 10.0);
        for (c = 0; c < 3; c++) for (r = 0; r < 3; r++) M->m[c][r] = (float)(M->m[c][r] * s);
        return;
    }
    case 8: case 9:                                     /* affine, general R */
        for (c = 0; c < 3; c++) for (r = 0; r < 3; r++) M->m[c][r] = (float)rd(-2.0, 2.0);
        return;
    case 10: case 11: {                                 /* general, any scale */
        double s = ldexp(1.0, (int)rn(240u) - 120);
        for (c = 0; c < 4; c++) for (r = 0; r < 4; r++) M->m[c][r] = (float)(rd(-1.0, 1.0) * s);
        return;
    }
    case 12:                                            /* projective bottom row */
        for (c = 0; c < 4; c++) M->m[c][3] = f_mild(1.0);
        return;
    case 13:                                            /* small integers (exact, often singular) */
        for (c = 0; c < 4; c++) for (r = 0; r < 4; r++) M->m[c][r] = (float)((int32_t)rn(5u) - 2);
        if (rn(2u)) { M->m[0][3] = 0.0f; M->m[1][3] = 0.0f; M->m[2][3] = 0.0f; M->m[3][3] = 1.0f; }
        return;
    case 14: {                                          /* rank deficient before rounding */
        float a = (float)rd(-2.0, 2.0), b = (float)rd(-2.0, 2.0);
        uint32_t dst = rn(4u), s1 = (dst + 1u) & 3u, s2 = (dst + 2u) & 3u;
        for (r = 0; r < 4; r++) M->m[dst][r] = a * M->m[s1][r] + b * M->m[s2][r];
        return;
    }
    case 15: case 16:                                   /* edge entries */
        for (c = (int)rn(3u); c >= 0; c--) M->m[rn(4u)][rn(4u)] = f_edge();
        return;
    case 17:                                            /* random bits */
        for (c = 0; c < 4; c++) for (r = 0; r < 4; r++) M->m[c][r] = fbits(ru());
        return;
    case 18: {                                          /* perspective times rigid */
        dh_mat4_f32 P;
        if (dh_mat4_persp_f32((int)rn(3u), (float)ldexp(rd(0.5, 1.0), (int)rn(80u) - 40), &P) == DH_OK)
            dh_mat4_mul_f32(&P, M, M);
        return;
    }
    default:                                            /* any float in any entry */
        for (c = 0; c < 4; c++) for (r = 0; r < 4; r++) M->m[c][r] = f_gen(4.0);
        return;
    }
}

static void frame_gen(dh_frame_q *F)
{
    int c, r;
    uint32_t k = rn(12u);
    int32_t s = (int32_t)rn(31u);
    if (dh_frame_rot_axis_q(i_gen(), i_gen(), i_gen(), i_gen(), F) != DH_OK) dh_frame_identity_q(F);
    for (r = 0; r < 3; r++) F->p[r] = (int32_t)ru() >> s;
    switch (k) {
    case 0: case 1: case 2: case 3: return;             /* rigid */
    case 4: case 5: {                                   /* drifted by a few LSB .. 2^27 */
        int32_t e = (int32_t)1 << rn(28u);
        for (c = 0; c < 3; c++) for (r = 0; r < 3; r++)
            F->r[c][r] += (int32_t)(rn((uint32_t)(2 * e + 1))) - e;
        return;
    }
    case 6: {                                           /* exact axis rotations */
        int32_t a = (int32_t)(rn(9u) * 90u) << 16;
        if (rn(3u) == 0u) dh_frame_rotx_q(a, F);
        else if (rn(2u)) dh_frame_roty_q(a, F);
        else dh_frame_rotz_q(a, F);
        for (r = 0; r < 3; r++) F->p[r] = i_gen();
        return;
    }
    case 7: case 8:                                     /* edge entries */
        for (c = (int)rn(4u); c >= 0; c--) {
            uint32_t j = rn(12u);
            if (j < 9u) F->r[j / 3u][j % 3u] = edge_i[rn((uint32_t)N_EDGE_I)];
            else F->p[j - 9u] = edge_i[rn((uint32_t)N_EDGE_I)];
        }
        return;
    default:                                            /* arbitrary int32 everywhere */
        for (c = 0; c < 3; c++) for (r = 0; r < 3; r++) F->r[c][r] = i_gen();
        for (r = 0; r < 3; r++) F->p[r] = i_gen();
        return;
    }
}

/* ---- robots ---------------------------------------------------------------- */

#define POOL_N 1024
static dh_robot pool[POOL_N];

static float joint_angle(void)
{
    switch (rn(8u)) {
    case 0: case 1: return 0.0f;
    case 2: return 90.0f;
    case 3: return -90.0f;
    case 4: return 180.0f;
    case 5: return (float)((int32_t)rn(721u) - 360);
    default: return (float)rd(-360.0, 360.0);
    }
}

static float joint_len(double s)
{
    uint32_t k = rn(8u);
    if (k < 2u) return 0.0f;
    if (k == 2u && rn(8u) == 0u) return (float)rd(4e4, 1e6) * (rn(2u) ? 1.0f : -1.0f); /* beyond dh_qpos */
    return (float)rd(-s, s);
}

static void frame_rigid_q(dh_frame_q *F, int32_t pscale)
{
    int r;
    if (dh_frame_rot_axis_q(i_gen(), i_gen(), i_gen(), (int32_t)ru(), F) != DH_OK) dh_frame_identity_q(F);
    for (r = 0; r < 3; r++) F->p[r] = (int32_t)(rn(2u * (uint32_t)pscale + 1u) - (uint32_t)pscale);
}

static void robot_base_tool(dh_robot *r, int tool, double s)
{
    dh_mat4_f32 M;
    dh_frame_q F;
    uint32_t k = rn(10u);
    if (k < 4u) return;                                 /* identity */
    if (k < 7u) {
        mat4_rigid(&M);
        M.m[3][0] = (float)rd(-s, s); M.m[3][1] = (float)rd(-s, s); M.m[3][2] = (float)rd(-s, s);
    } else if (k == 7u) {
        mat4_gen(&M);
    } else if (k == 8u) {
        frame_rigid_q(&F, rn(2u) ? 1 << 20 : INT32_MAX);
        if (rn(8u) == 0u) frame_gen(&F);
        if (tool) (void)dh_robot_set_tool_q(r, &F);
        else (void)dh_robot_set_base_q(r, &F);
        return;
    } else {
        dh_mat4_identity_f32(&M);
        M.m[3][rn(3u)] = (float)rd(-s, s);
    }
    if (tool) (void)dh_robot_set_tool_f32(r, &M);
    else (void)dh_robot_set_base_f32(r, &M);
}

static void robot_gen(dh_robot *r)
{
    static const double scales[] = { 1.0, 1.0, 0.1, 1000.0, 10.0 };
    double s = scales[rn(5u)];
    uint32_t n = rn(10u), j;
    (void)dh_robot_init(r, (dh_convention)rn(2u));
    if (n == 0u || n > DH_MAX_JOINTS) n = 1u + rn(DH_MAX_JOINTS);
    if (rn(32u) == 0u) n = 0u;
    for (j = 0; j < n; j++) {
        dh_joint_type t = rn(4u) == 0u ? DH_JOINT_PRISMATIC : DH_JOINT_REVOLUTE;
        if (rn(12u) == 0u) {
            int32_t sq = (int32_t)(s * 65536.0);
            (void)dh_robot_add_joint_q(r, t, rn(2u) ? i_gen() : 0,
                                       (int32_t)rn((uint32_t)(2 * sq + 1)) - sq,
                                       (int32_t)rn((uint32_t)(2 * sq + 1)) - sq, (int32_t)(joint_angle() * 65536.0f));
        } else {
            (void)dh_robot_add_joint_f32(r, t, rn(2u) ? joint_angle() : 0.0f, joint_len(s), joint_len(s), joint_angle());
        }
        if (rn(3u) == 0u) {
            float lo = (t == DH_JOINT_REVOLUTE) ? (float)rd(-270.0, 0.0) : (float)rd(-s, 0.0);
            float hi = (t == DH_JOINT_REVOLUTE) ? (float)rd(0.0, 270.0) : (float)rd(0.0, s);
            (void)dh_robot_set_limits_f32(r, j, lo, hi);
        } else if (rn(8u) == 0u) {
            int32_t lo = (int32_t)ru() >> 1;
            (void)dh_robot_set_limits_q(r, j, lo, lo + (int32_t)(ru() >> 2));
        }
    }
    robot_base_tool(r, 0, s);
    robot_base_tool(r, 1, s);
    if (rn(64u) == 0u) r->n = rn(2u) ? DH_MAX_JOINTS + 1u : 0xFFFFFFFFu; /* corrupted copy */
}

static void pool_make(void)
{
    int i;
    for (i = 0; i < POOL_N; i++) robot_gen(&pool[i]);
}

/* Robots with a closed form (ikc.h): the four families with random
 * lengths, twist signs, offsets, limits, conventions and base/tool frames,
 * plus every 8th one a pool robot (no closed form, mostly). Built at
 * start-up like the pool. */
#define IKC_POOL_N 256
static dh_robot ikc_pool[IKC_POOL_N];

static float sgn90(void) { return rn(2u) ? 90.0f : -90.0f; }
static float par0(void) { return rn(2u) ? 0.0f : 180.0f; }

static void ikc_robot_gen(dh_robot *r)
{
    /* canonical standard-DH rows: type, a, d, alpha */
    float a[6] = { 0 }, d[6] = { 0 }, al[6] = { 0 }, th[6] = { 0 };
    dh_joint_type t[6] = { DH_JOINT_REVOLUTE, DH_JOINT_REVOLUTE, DH_JOINT_REVOLUTE, DH_JOINT_REVOLUTE,
                           DH_JOINT_REVOLUTE, DH_JOINT_REVOLUTE };
    double s = rn(2u) ? 1.0 : 1000.0;
    uint32_t fam = rn(8u), n = 6u, j;
    dh_convention conv = (dh_convention)rn(2u);
    if (fam == 7u) { *r = pool[rn(POOL_N)]; return; }
    switch (fam & 3u) {
    case 0: /* spherical wrist on R-R-R (Puma, KR5, IRB140 shapes) */
        al[0] = sgn90(); al[1] = par0(); al[2] = sgn90(); al[3] = sgn90(); al[4] = sgn90();
        d[0] = (float)rd(0.0, 0.8 * s); a[0] = rn(2u) ? 0.0f : (float)rd(-0.3 * s, 0.3 * s);
        a[1] = (float)rd(0.2 * s, 0.7 * s); d[1] = rn(2u) ? 0.0f : (float)rd(-0.2 * s, 0.2 * s);
        a[2] = rn(2u) ? 0.0f : (float)rd(-0.2 * s, 0.2 * s); d[2] = rn(2u) ? 0.0f : (float)rd(-0.2 * s, 0.2 * s);
        d[3] = (float)rd(0.1 * s, 0.7 * s);
        break;
    case 1: /* spherical wrist on R-R-P (Stanford shape) */
        al[0] = sgn90(); al[1] = sgn90(); al[3] = sgn90(); al[4] = sgn90();
        t[2] = DH_JOINT_PRISMATIC;
        d[0] = (float)rd(0.0, 0.5 * s); d[1] = (float)rd(-0.2 * s, 0.2 * s); d[2] = (float)rd(0.0, 0.3 * s);
        break;
    case 2: /* axes 2, 3, 4 parallel (UR shape) */
        al[0] = sgn90(); al[1] = par0(); al[2] = par0(); al[3] = sgn90(); al[4] = sgn90();
        d[0] = (float)rd(0.05 * s, 0.2 * s); a[1] = (float)rd(-0.6 * s, -0.2 * s); a[2] = (float)rd(-0.6 * s, -0.2 * s);
        d[3] = (float)rd(0.05 * s, 0.2 * s); d[4] = (float)rd(0.05 * s, 0.2 * s);
        break;
    default: /* SCARA R-R-P-R */
        n = 4u;
        t[2] = DH_JOINT_PRISMATIC;
        al[1] = par0(); a[0] = (float)rd(0.2 * s, 0.4 * s); a[1] = (float)rd(0.2 * s, 0.4 * s);
        d[0] = (float)rd(0.0, 0.4 * s);
        break;
    }
    d[n - 1u] = rn(2u) ? 0.0f : (float)rd(0.0, 0.2 * s);
    if (rn(4u) == 0u) { a[n - 1u] = (float)rd(-0.1 * s, 0.1 * s); al[n - 1u] = joint_angle(); }
    for (j = 0; j < n; j++) th[j] = rn(2u) ? 0.0f : joint_angle();
    (void)dh_robot_init(r, conv);
    for (j = 0; j < n; j++) {
        /* modified DH: row j holds the a/alpha of canonical row j-1 (row 0: a random pre-twist) */
        float aj = a[j], alj = al[j];
        if (conv == DH_CONV_MODIFIED) {
            aj = (j == 0u) ? (rn(2u) ? 0.0f : (float)rd(-0.1 * s, 0.1 * s)) : a[j - 1u];
            alj = (j == 0u) ? (rn(2u) ? 0.0f : joint_angle()) : al[j - 1u];
        }
        (void)dh_robot_add_joint_f32(r, t[j], th[j], d[j], aj, alj);
        if (rn(2u)) {
            if (t[j] == DH_JOINT_REVOLUTE) (void)dh_robot_set_limits_f32(r, j, (float)rd(-270.0, -30.0), (float)rd(30.0, 270.0));
            else (void)dh_robot_set_limits_f32(r, j, (float)rd(-0.2 * s, 0.1 * s), (float)rd(0.2 * s, 1.0 * s));
        }
    }
    robot_base_tool(r, 0, s);
    robot_base_tool(r, 1, s);
}

static void ikc_pool_make(void)
{
    int i;
    for (i = 0; i < IKC_POOL_N; i++) ikc_robot_gen(&ikc_pool[i]);
}

static float q_f32(const dh_robot *r, uint32_t j)
{
    double s = 1.0;
    if (j < DH_MAX_JOINTS && r->joint[j].type == DH_JOINT_PRISMATIC) {
        s = fabs((double)r->joint[j].d) + fabs((double)r->joint[j].a) + 1.0;
        return (float)rd(-s, s);
    }
    switch (rn(16u)) {
    case 0: return rn(4u) ? (float)(90 * ((int32_t)rn(9u) - 4)) : f_edge();
    case 1: return (float)rd(-1e6, 1e6);
    case 2: return (j < DH_MAX_JOINTS) ? r->joint[j].qmin : 0.0f;
    case 3: return (j < DH_MAX_JOINTS) ? r->joint[j].qmax : 0.0f;
    default: return (float)rd(-360.0, 360.0);
    }
}

static int32_t q_q(const dh_robot *r, uint32_t j)
{
    uint32_t k = rn(16u);
    if (k == 0u) return edge_i[rn((uint32_t)N_EDGE_I)];
    if (k == 1u) return (int32_t)ru();
    if (k == 2u && j < DH_MAX_JOINTS) return r->joint[j].qmin_q;
    if (k == 3u && j < DH_MAX_JOINTS) return r->joint[j].qmax_q;
    if (j < DH_MAX_JOINTS && r->joint[j].type == DH_JOINT_PRISMATIC) return (int32_t)ru() >> 12;
    return (int32_t)rn(720u * 65536u) - 360 * 65536;
}

/* ---- generators: one diff_in per call -------------------------------------- */

typedef void (*diff_gen)(diff_in *in);

static void g_status(diff_in *in)
{
    in->k[0] = rn(8u) ? (int32_t)rn(16u) - 2 : (int32_t)ru();
}
static void g_angle_f(diff_in *in)
{
    in->f[0] = f_angle();
}
static void g_atan2_f(diff_in *in)
{
    in->f[0] = f_gen(1.0);
    in->f[1] = rn(8u) ? f_gen(1.0) : in->f[0] * (rn(2u) ? 1.0f : -1.0f); /* diagonals */
}
/* sines / cosines: mostly [-1, 1], the clamp band just outside, edges */
static void g_unit_f(diff_in *in)
{
    uint32_t k = rn(16u);
    if (k == 0u) in->f[0] = f_edge();
    else if (k == 1u) in->f[0] = fbits((0x3F800000u + rn(12u) - 6u) | (rn(2u) << 31)); /* around +-1 */
    else if (k == 2u) in->f[0] = fbits(rn(0x3F800001u) | (rn(2u) << 31));             /* any exponent */
    else in->f[0] = (float)rd(-1.0, 1.0);
}
static void g_unit_q(diff_in *in)
{
    uint32_t k = rn(8u);
    if (k == 0u) in->k[0] = i_gen();
    else if (k == 1u) in->k[0] = (0x40000000 + (int32_t)rn(2048u) - 1024) * (rn(2u) ? 1 : -1);
    else in->k[0] = (int32_t)rn(0x80000001u) - 0x40000000;
}
static void g_ints(diff_in *in)
{
    int i;
    for (i = 0; i < 8; i++) in->k[i] = i_gen();
    if (rn(16u) == 0u) { in->k[0] = 0; in->k[1] = 0; in->k[2] = 0; } /* zero axis */
    if (rn(2u)) in->k[0] = (int32_t)rn(30u) - 3;                    /* small (euler_name) */
}
static void g_frames(diff_in *in)
{
    frame_gen(&in->F[0]);
    frame_gen(&in->F[1]);
    in->vq.x = i_gen(); in->vq.y = i_gen(); in->vq.z = i_gen();
    in->sel = ru();
}
/* two fixed frames and a via point: half of the time rigid frames with
 * positions within +-2^26 LSB and the via point near their middle (paths
 * and moves that plan), else of any kind; integer limits and a selector */
static void g_fpath(diff_in *in)
{
    int i, r;
    g_frames(in);
    for (i = 0; i < 8; i++) in->k[i] = i_gen();
    if (rn(2u)) {
        const uint32_t span = 1u << (10u + rn(17u));
        int32_t mid[3];
        for (i = 0; i < 2; i++) {
            if (dh_frame_rot_axis_q(i_gen(), i_gen(), i_gen(), i_gen(), &in->F[i]) != DH_OK) dh_frame_identity_q(&in->F[i]);
            for (r = 0; r < 3; r++) in->F[i].p[r] = (int32_t)rn(2u * span + 1u) - (int32_t)span;
        }
        for (r = 0; r < 3; r++) mid[r] = in->F[0].p[r] / 2 + in->F[1].p[r] / 2;
        in->vq.x = mid[0] + (int32_t)rn(span + 1u) - (int32_t)(span / 2u);
        in->vq.y = mid[1] + (int32_t)rn(span + 1u) - (int32_t)(span / 2u);
        in->vq.z = mid[2] + (int32_t)rn(span + 1u) - (int32_t)(span / 2u);
    }
}
/* one matrix, vectors, a plane and floats */
static void g_mat1(diff_in *in)
{
    int i;
    mat4_gen(&in->M[0]);
    for (i = 0; i < 4; i++) v3_gen(&in->v[i], 10.0);
    in->v4.x = f_gen(10.0); in->v4.y = f_gen(10.0); in->v4.z = f_gen(10.0);
    in->v4.w = rn(2u) ? 1.0f : f_gen(2.0);
    in->pl.a = f_gen(1.0); in->pl.b = f_gen(1.0); in->pl.c = f_gen(1.0); in->pl.d = f_gen(10.0);
    for (i = 0; i < 4; i++) in->f[i] = f_gen(10.0);
    in->sel = ru();
}
/* two matrices and a 3x3 */
static void g_mats(diff_in *in)
{
    mat4_gen(&in->M[0]);
    mat4_gen(&in->M[1]);
    mat3_gen(&in->R[0]);
    in->sel = ru();
}
static void g_inv(diff_in *in)
{
    mat4_gen(&in->M[0]);
    in->pl.a = f_mild(1.0); in->pl.b = f_mild(1.0); in->pl.c = f_mild(1.0); in->pl.d = f_mild(10.0);
    in->sel = ru();
}
static void g_persp(diff_in *in)
{
    in->k[0] = rn(8u) ? (int32_t)rn(3u) : (int32_t)rn(7u) - 2;
    in->f[0] = rn(4u) ? (float)ldexp(rd(-1.0, 1.0), (int)rn(280u) - 150) : f_gen(10.0);
}
static float tol_gen(void)
{
    static const float t[] = { 1e-5f, 1e-4f, 1e-3f, 0.0f, -0.0f, -1e-5f, 1e-6f, 0.1f, 3e-5f };
    uint32_t k = rn(12u);
    if (k < 9u) return t[k];
    if (k == 9u) return f_edge();
    return (float)rd(0.0, 1e-3);
}
static void g_check(diff_in *in)
{
    mat4_gen(&in->M[0]);
    mat4_gen(&in->M[1]);
    mat3_gen(&in->R[0]);
    in->f[0] = tol_gen();
}
static void g_rot(diff_in *in)
{
    int c, r;
    mat3_gen(&in->R[0]);
    if (rn(2u)) mat3_gen(&in->R[1]);
    else for (c = 0; c < 3; c++) for (r = 0; r < 3; r++) in->R[1].m[c][r] = f_gen(20.0); /* Rdot */
    mat4_gen(&in->M[0]);
    mat4_set_rot(&in->M[0], &in->R[0]);
    in->k[0] = rn(16u) ? (int32_t)rn(24u) : (int32_t)rn(40u) - 8;
    in->sel = ru();
}
static void g_axis_f(diff_in *in)
{
    uint32_t k = rn(8u);
    if (k == 0u) {                                      /* coordinate axis, any positive length */
        in->f[0] = 0.0f; in->f[1] = 0.0f; in->f[2] = 0.0f;
        in->f[rn(3u)] = (float)ldexp(rd(0.5, 1.0), (int)rn(200u) - 100) * (rn(2u) ? 1.0f : -1.0f);
    } else if (k == 1u) {
        in->f[0] = f_gen(1.0); in->f[1] = f_gen(1.0); in->f[2] = f_gen(1.0);
    } else {
        double s = ldexp(1.0, (int)rn(200u) - 100);
        in->f[0] = (float)(rd(-1.0, 1.0) * s);
        in->f[1] = (float)(rd(-1.0, 1.0) * s);
        in->f[2] = (float)(rd(-1.0, 1.0) * s);
    }
    in->f[3] = f_angle();
    in->v[0].x = in->f[0]; in->v[0].y = in->f[1]; in->v[0].z = in->f[2];
}
static void g_euler(diff_in *in)
{
    in->k[0] = rn(16u) ? (int32_t)rn(24u) : (int32_t)rn(40u) - 8;
    in->f[0] = f_angle(); in->f[1] = f_angle(); in->f[2] = f_angle();
    if (rn(2u)) { in->f[0] = (float)rd(-360, 360); in->f[1] = (float)rd(-360, 360); in->f[2] = (float)rd(-360, 360); }
}
static void quat_gen(dh_quat_f32 *q)
{
    uint32_t k = rn(8u);
    double s = (k < 2u) ? ldexp(1.0, (int)rn(260u) - 130) : 1.0;
    if (k == 2u) { q->w = f_gen(1.0); q->x = f_gen(1.0); q->y = f_gen(1.0); q->z = f_gen(1.0); return; }
    q->w = (float)(rd(-1.0, 1.0) * s); q->x = (float)(rd(-1.0, 1.0) * s);
    q->y = (float)(rd(-1.0, 1.0) * s); q->z = (float)(rd(-1.0, 1.0) * s);
    if (k == 3u) q->x = 0.0f;
    if (k == 4u) { q->w = 0.0f; q->y = 0.0f; }
}
static void g_quat(diff_in *in)
{
    quat_gen(&in->qt[0]);
    quat_gen(&in->qt[1]);
    in->sel = ru();
}
static void g_rotvec(diff_in *in)
{
    uint32_t k = rn(8u);
    double s = (k == 0u) ? ldexp(1.0, -(int)rn(130u)) : (k == 1u) ? 12.6 : 3.2;
    if (k == 2u) { v3_gen(&in->v[0], 4.0); return; }
    if (k == 3u) { in->v[0].x = FLT_MAX; in->v[0].y = rn(2u) ? FLT_MAX : -FLT_MAX; in->v[0].z = f_mild(1.0); return; }
    in->v[0].x = (float)rd(-s, s); in->v[0].y = (float)rd(-s, s); in->v[0].z = (float)rd(-s, s);
}
static void g_string(diff_in *in)
{
    static const char alpha[] = "XYZxyzXYZxyzAa0 ";
    int i;
    memset(in->str, 0, sizeof in->str);
    if (rn(2u)) { /* a valid name, one character changed now and then */
        memcpy(in->str, dh_euler_name((dh_euler_seq)rn(24u)), 3);
        if (rn(4u) == 0u) in->str[rn(4u)] = alpha[rn(16u)];
        return;
    }
    for (i = 0; i < 4; i++) {
        uint32_t k = rn(20u);
        in->str[i] = (k < 16u) ? alpha[k] : (k == 16u) ? '\0' : (char)ru();
    }
    if (rn(2u)) in->str[3] = '\0';
}
static void g_setter(diff_in *in)
{
    int i;
    in->rob = &pool[rn(POOL_N)];
    in->k[0] = rn(4u) ? (int32_t)rn(2u) : (int32_t)rn(12u) - 2;
    for (i = 1; i < 8; i++) in->k[i] = i_gen();
    if (rn(2u)) { in->k[1] = (int32_t)ru() >> 8; in->k[2] = (int32_t)ru() >> 8; }
    in->f[0] = rn(3u) ? (float)rd(-2e3, 2e3) : f_gen(1e5);
    in->f[1] = rn(3u) ? (float)rd(-2e3, 2e3) : f_gen(1e5);
    if (rn(2u) && in->f[0] > in->f[1]) { float t = in->f[0]; in->f[0] = in->f[1]; in->f[1] = t; }
    in->f[2] = f_angle(); in->f[3] = rn(2u) ? joint_angle() : f_angle();
    mat4_gen(&in->M[0]);
    if (rn(4u) == 0u) dh_mat4_identity_f32(&in->M[0]);
    frame_gen(&in->F[0]);
    if (rn(4u) == 0u) dh_frame_identity_q(&in->F[0]);
    in->sel = ru();
}
static void g_robot(diff_in *in)
{
    const dh_robot *r = &pool[rn(POOL_N)];
    uint32_t j;
    in->rob = r;
    for (j = 0; j < DH_MAX_JOINTS; j++) {
        in->q[j] = q_f32(r, j);
        in->qi[j] = q_q(r, j);
    }
    if (rn(4u)) for (j = 0; j < DH_MAX_JOINTS; j++) if (!isfinite(in->q[j])) in->q[j] = 0.0f;
    in->k[0] = (r->n != 0u && r->n <= DH_MAX_JOINTS && rn(16u)) ? (int32_t)rn(r->n) : (int32_t)rn(12u) - 1;
    in->f[0] = q_f32(r, (uint32_t)in->k[0]);
    in->k[1] = q_q(r, (uint32_t)in->k[0]);
    in->sel = ru();
}
/* twin: g_ikq */
static void g_ik(diff_in *in)
{
    const dh_robot *r;
    uint32_t j;
    dh_mat4_f32 T;
    do {
        r = &pool[rn(POOL_N)];
    } while ((r->flags & DH_ROBOT_HAS_F32) == 0u && rn(8u) != 0u);
    in->rob = r;
    for (j = 0; j < DH_MAX_JOINTS; j++) in->q[j] = q_f32(r, j);
    if (dh_fk_f32(r, in->q, &T) != DH_OK || rn(8u) == 0u) mat4_gen(&T);
    in->M[0] = T;
    for (j = 0; j < DH_MAX_JOINTS; j++) in->q[j] = rn(2u) ? in->q[j] + (float)rd(-20.0, 20.0) : q_f32(r, j);
    dh_ik_params_default_f32(r, &in->ikp);
    in->ikp.max_iter = 1u + rn(64u);
    in->ikp.restarts = rn(4u);
    if (rn(4u) == 0u) in->ikp.mask = rn(2u) ? DH_IK_POSITION : (rn(8u) ? rn(64u) : ru());
    if (rn(4u) == 0u) { in->ikp.tol_pos = tol_gen(); in->ikp.tol_rot = tol_gen(); }
    if (rn(8u) == 0u) in->ikp.w_rot = f_gen(1e3);
    if (rn(16u) == 0u) in->ikp.max_iter = 0u;
    in->k[0] = (int32_t)rn(DIFF_IK_WORK + 1u);
    in->sel = ru() & (rn(16u) ? 1u : 3u);
}
/* twin: g_ik */
static void g_ikq(diff_in *in)
{
    const dh_robot *r;
    uint32_t j;
    dh_frame_q T;
    do {
        r = &pool[rn(POOL_N)];
    } while ((r->flags & DH_ROBOT_HAS_Q) == 0u && rn(8u) != 0u);
    in->rob = r;
    for (j = 0; j < DH_MAX_JOINTS; j++) in->qi[j] = q_q(r, j);
    if (dh_fk_q(r, in->qi, &T) != DH_OK || rn(8u) == 0u) frame_gen(&T);
    in->F[0] = T;
    for (j = 0; j < DH_MAX_JOINTS; j++)
        if (rn(2u)) in->qi[j] = (int32_t)((uint32_t)in->qi[j] + (uint32_t)((int32_t)rn(40u << 16) - (20 << 16)));
    dh_ik_params_default_q(r, &in->ikpq);
    in->ikpq.max_iter = 1u + rn(32u);
    in->ikpq.restarts = rn(4u);
    if (rn(4u) == 0u) in->ikpq.mask = rn(2u) ? DH_IK_POSITION : (rn(8u) ? rn(64u) : ru());
    if (rn(4u) == 0u) { in->ikpq.tol_pos = (int32_t)ru() >> rn(31u); in->ikpq.tol_rot = (int32_t)ru() >> rn(31u); }
    if (rn(8u) == 0u) in->ikpq.w_rot = (int32_t)ru();
    if (rn(16u) == 0u) in->ikpq.max_iter = 0u;
    in->k[0] = (int32_t)rn(DIFF_IKQ_WORK + 1u);
    in->sel = ru() & (rn(16u) ? 1u : 3u);
}

/* closed-form IK: a target from FK of a random configuration (a singular
 * wrist at times), else a random matrix; q_ref near it or arbitrary */
/* motion.h: a path parameter, a positive limit of any scale, a fraction */
static float s_gen(void)
{
    switch (rn(16u)) {
    case 0: return f_edge();
    case 1: return 0.0f;
    case 2: return 1.0f;
    case 3: return 0.5f;
    default: return (float)rd(0.0, 1.0);
    }
}
static float lim_gen(void)
{
    switch (rn(16u)) {
    case 0: return f_edge();
    case 1: return f_gen(1.0);
    default: return (float)ldexp(rd(0.5, 1.0), (int)rn(40u) - 20);
    }
}
static float frac_gen(void)
{
    switch (rn(16u)) {
    case 0: return f_edge();
    case 1: return (float)rd(-0.1, 1.1);
    case 2: return 1.0f;
    default: return (float)rd(0.0, 1.0);
    }
}
static void g_slerp(diff_in *in)
{
    quat_gen(&in->qt[0]);
    if (rn(4u)) in->qt[1] = in->qt[0];
    quat_gen(&in->qt[1]);
    in->f[0] = s_gen();
    in->sel = ru();
}
static void g_pose(diff_in *in)
{
    if (rn(4u)) mat4_rigid(&in->M[0]); else mat4_gen(&in->M[0]);
    if (rn(4u)) mat4_rigid(&in->M[1]); else mat4_gen(&in->M[1]);
    in->f[0] = s_gen();
    in->sel = ru();
}
static void g_motion(diff_in *in)
{
    int i;
    for (i = 0; i < 4; i++) in->f[i] = rn(8u) ? (float)ldexp(rd(-1.0, 1.0), (int)rn(40u) - 20) : f_gen(10.0);
    for (i = 4; i < 8; i++) in->f[i] = lim_gen();
    for (i = 0; i < DH_MAX_JOINTS; i++) in->q[i] = lim_gen();
    /* for the profiles: f[1..3] limits, f[4] a duration, f[5] a stretch
     * factor, f[6] the time as a fraction of the duration */
    in->f[1] = lim_gen();
    in->f[5] = rn(8u) ? (float)(1.0 + ldexp(rd(0.0, 1.0), (int)rn(10u) - 5)) : frac_gen();
    in->f[6] = frac_gen();
    in->q[2 % DH_MAX_JOINTS] = frac_gen();
    in->sel = ru();
}
/* a path: frames M[0], M[1] (g_pose), via f[0..2], s f[3], Cartesian
 * limits f[4..7], the time as a fraction of the duration q[2] */
static void g_path(diff_in *in)
{
    int i;
    double s = len_scale();
    g_pose(in);
    for (i = 0; i < 3; i++) in->f[i] = rn(16u) ? (float)rd(-s, s) : f_gen(s);
    in->f[3] = s_gen();
    for (i = 4; i < 8; i++) in->f[i] = lim_gen();
    in->q[0] = lim_gen();                    /* jerk limits */
    in->q[1 % DH_MAX_JOINTS] = lim_gen();
    in->q[2 % DH_MAX_JOINTS] = frac_gen();
}
static void g_ikc(diff_in *in)
{
    const dh_robot *r = &ikc_pool[rn(IKC_POOL_N)];
    uint32_t j;
    in->rob = r;
    for (j = 0; j < DH_MAX_JOINTS; j++) {
        in->q[j] = q_f32(r, j);
        in->qi[j] = q_q(r, j);
        if (rn(2u) && j < DH_MAX_JOINTS && r->joint[j].type == DH_JOINT_REVOLUTE) {
            in->q[j] = (float)rd(-180.0, 180.0);
            in->qi[j] = (int32_t)(in->q[j] * 65536.0f);
        }
    }
    if (rn(8u) == 0u) { in->q[4] = 0.0f; in->qi[4] = 0; }
    if (rn(8u) == 0u || dh_fk_f32(r, in->q, &in->M[0]) != DH_OK) mat4_gen(&in->M[0]);
    if (rn(8u) == 0u || dh_fk_q(r, in->qi, &in->F[0]) != DH_OK) frame_gen(&in->F[0]);
    for (j = 0; j < DH_MAX_JOINTS; j++) {
        if (rn(2u)) in->q[j] += (float)rd(-30.0, 30.0);
        else if (rn(8u) == 0u) in->q[j] = q_f32(r, j);
        if (rn(2u)) in->qi[j] = (int32_t)((uint32_t)in->qi[j] + (uint32_t)((int32_t)rn(60u << 16) - (30 << 16)));
        else if (rn(8u) == 0u) in->qi[j] = q_q(r, j);
    }
    if (rn(4u)) for (j = 0; j < DH_MAX_JOINTS; j++) if (!isfinite(in->q[j])) in->q[j] = 0.0f;
    in->k[1] = rn(8u) ? (int32_t)(rn(2u) * DH_IKC_KEEP_OUT_OF_LIMITS) : (int32_t)ru();
    in->k[2] = (int32_t)rn(7u) - 1;
    in->k[3] = (int32_t)rn(9u);
    in->k[4] = (int32_t)rn(DH_IKC_MAX_SOL + 1u);
    in->k[5] = (int32_t)rn(DH_IKC_JOINTS + 2u);
    in->sel = ru() & (rn(8u) ? 13u : 15u);
}

/* ---- comparison ------------------------------------------------------------- */

enum { C_BITS, C_INV, C_PLANE, C_ZERO_SIGN };

static double norm1_bal(const dh_mat4_f32 *A, double s)
{
    /* 1-norm (largest column sum) of D A D^-1, D = diag(1, 1, 1, s) */
    double best = 0.0;
    int c, r;
    for (c = 0; c < 4; c++) {
        double sum = 0.0;
        for (r = 0; r < 4; r++) {
            double f = 1.0;
            if (r == 3 && c < 3) f = s;
            if (c == 3 && r < 3) f = 1.0 / s;
            sum += fabs((double)A->m[c][r]) * f;
        }
        if (sum > best) best = sum;
    }
    return best;
}

/* 3.2 * cond * 2^-24 * max|X|, cond the smallest balanced condition number */
static double inv_bound(const dh_mat4_f32 *T, const dh_mat4_f32 *X)
{
    double cond = HUGE_VAL, mx = 0.0;
    int k, c, r;
    for (k = -150; k <= 150; k += 2) {
        double s = ldexp(1.0, k);
        double cd = norm1_bal(T, s) * norm1_bal(X, s);
        if (cd < cond) cond = cd;
    }
    for (c = 0; c < 4; c++) for (r = 0; r < 4; r++)
        if (fabs((double)X->m[c][r]) > mx) mx = fabs((double)X->m[c][r]);
    return 3.2 * cond * ldexp(1.0, -24) * mx;
}

/* 1 when the two inverses agree within twice the documented bound */
static int inv_close(const dh_mat4_f32 *T, const dh_mat4_f32 *Xa, const dh_mat4_f32 *Xb)
{
    double tol = 2.0 * (inv_bound(T, Xa) > inv_bound(T, Xb) ? inv_bound(T, Xa) : inv_bound(T, Xb))
                 + ldexp(1.0, -148);
    int c, r;
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) {
            double a = Xa->m[c][r], b = Xb->m[c][r];
            if (!isfinite(a) || !isfinite(b)) {
                if (bitsf(Xa->m[c][r]) != bitsf(Xb->m[c][r]) && !(isnan(a) && isnan(b))) return 0;
            } else if (fabs(a - b) > tol) {
                return 0;
            }
        }
    return 1;
}

/* Q = P T^-1 of both builds: the inverse's bound carried through P, plus
 * 4 roundings of the row-times-matrix product in each build. Returns 1
 * within that bound, 2 within it only after adding rigid_err (see
 * plane_rigid_err), 0 otherwise; *cross set when an Inf was accepted
 * against a finite value of the other sign. */
static int plane_close(const diff_in *in, const dh_plane_f32 *Qa, const dh_plane_f32 *Qb, double rigid_err,
                       int *cross)
{
    dh_mat4_f32 X;
    const float *P = &in->pl.a;
    const float *qa = &Qa->a, *qb = &Qb->a;
    double tX, pabs = 0.0;
    int i, j, res = 1;
    if (dh_mat4_inv_f32(&in->M[0], &X) != DH_OK) return 0;
    tX = 2.0 * inv_bound(&in->M[0], &X) + ldexp(1.0, -148);
    for (i = 0; i < 4; i++) pabs += fabs((double)P[i]);
    for (j = 0; j < 4; j++) {
        double sum = 0.0, tol, d;
        for (i = 0; i < 4; i++) sum += fabs((double)P[i] * (double)X.m[j][i]);
        tol = 2.0 * pabs * tX + 8.0 * ldexp(1.0, -24) * sum + ldexp(1.0, -148);
        if (!isfinite(qa[j]) || !isfinite(qb[j])) {
            /* an Inf is accepted against a finite value whose bound reaches
             * the overflow threshold on the Inf's side: the two unrounded
             * values lie within tol of each other, and the exact one may
             * round to either side of the threshold. Where tol exceeds
             * the finite value (a huge plane coefficient times an entry of
             * T^-1 that the bound leaves open), that finite value may
             * even have the other sign. */
            double fin = isfinite(qa[j]) ? (double)qa[j] : (double)qb[j];
            double inf = isfinite(qa[j]) ? (double)qb[j] : (double)qa[j];
            double reach;
            if (bitsf(qa[j]) == bitsf(qb[j]) || (isnan(qa[j]) && isnan(qb[j]))) continue;
            if (isnan(inf) || !isfinite(fin)) return 0;
            reach = (inf > 0.0) ? fin + tol : tol - fin;
            if (reach + pabs * rigid_err < (double)FLT_MAX) return 0;
            if (reach < (double)FLT_MAX) res = 2;
            if (fin != 0.0 && (fin < 0.0) != (inf < 0.0)) *cross = 1;
            continue;
        }
        d = fabs((double)qa[j] - (double)qb[j]);
        if (d > tol) {
            if (d > tol + pabs * rigid_err) return 0;
            res = 2;
        }
    }
    return res;
}

/*
 * Where the two builds take the inverse differently on purpose: the
 * default build's dh_mat4_apply_plane_f32 inverts as dh_mat4_inv_auto_f32
 * does, with the closed-form rigid inverse for any T that
 * dh_mat4_check_rigid_f32(T, DH_MAT4_RIGID_TOL) accepts, and the
 * size-first build always with the general inverse. For a T that is rigid
 * only within the tolerance, R^T is not R^-1: the two results then differ
 * by up to |P| times the distance between the two inverses, which is far
 * above the general inverse's bound that mat4.h quotes for DH_SMALL.
 * Returns that distance (largest entry), 0 when T is not accepted as rigid.
 */
static double plane_rigid_err(const dh_mat4_f32 *T)
{
    dh_mat4_f32 Xr, X;
    double e = 0.0;
    int c, r;
    if (dh_mat4_check_rigid_f32(T, DH_MAT4_RIGID_TOL) != DH_OK) return 0.0;
    if (dh_mat4_inv_f32(T, &X) != DH_OK) return 0.0;
    dh_mat4_inv_rigid_f32(T, &Xr);
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) {
            double d = fabs((double)Xr.m[c][r] - (double)X.m[c][r]);
            if (d > e) e = d;
        }
    return 2.0 * e;
}

static void dump_words(const char *what, const void *p, size_t n)
{
    const unsigned char *b = (const unsigned char *)p;
    size_t i;
    dht_printf("  %s (%lu bytes, 32-bit words in hex):", what, (unsigned long)n);
    for (i = 0; i + 4u <= n; i += 4u) {
        uint32_t w;
        memcpy(&w, b + i, 4);
        if ((i / 4u) % 8u == 0u) dht_printf("\n    [%3lu]", (unsigned long)(i / 4u));
        dht_printf(" %08lx", (unsigned long)w);
    }
    dht_printf("\n");
}

static void report(const char *what, const char *name, unsigned long idx, const diff_in *in, const diff_out *a,
                   const diff_out *b, size_t len)
{
    size_t i, shown = 0;
    dht_printf("%s %s, input %lu (seed 0x%llx), main DH_SMALL=%d, alt DH_SMALL=%d\n",
               what, name, idx, (unsigned long long)dht_seed(), 1 - DH_ALT_SMALL, DH_ALT_SMALL);
    dump_words("input (diff_in, robot pointer excluded)", in, offsetof(diff_in, rob));
    if (in->rob != NULL) dump_words("input robot", in->rob, sizeof *in->rob);
    dht_printf("  differing output words (offset in diff_out: main alt):\n");
    for (i = 0; i + 4u <= len && shown < 40u; i += 4u) {
        uint32_t wa, wb;
        memcpy(&wa, (const unsigned char *)a + i, 4);
        memcpy(&wb, (const unsigned char *)b + i, 4);
        if (wa != wb) {
            dht_printf("    word %4lu: %08lx (%.9g) %08lx (%.9g)\n", (unsigned long)(i / 4u),
                       (unsigned long)wa, (double)fbits(wa), (unsigned long)wb, (double)fbits(wb));
            shown++;
        }
    }
}

static unsigned long count_div(void)
{
    const char *e = getenv("DHT_DIFF_DIV");
    unsigned long d = e ? strtoul(e, NULL, 0) : 1ul;
    return d ? d : 1ul;
}

/* float_word[w]: word w of diff_out holds a float (else integer data) */
static unsigned char float_word[sizeof(diff_out) / 4u];

static void mark_floats(size_t off, size_t bytes)
{
    size_t w;
    for (w = off / 4u; w < (off + bytes) / 4u; w++) float_word[w] = 1u;
}

static void float_words_init(void)
{
    diff_out o;
    size_t k;
    memset(float_word, 0, sizeof float_word);
    mark_floats(offsetof(diff_out, f), sizeof o.f);
    mark_floats(offsetof(diff_out, v), sizeof o.v + sizeof o.v4 + sizeof o.pl + sizeof o.qt);
    mark_floats(offsetof(diff_out, R), sizeof o.R + sizeof o.M);
    mark_floats(offsetof(diff_out, pts), sizeof o.pts);
    mark_floats(offsetof(diff_out, q), sizeof o.q);
    mark_floats(offsetof(diff_out, ikres) + offsetof(dh_ik_result_f32, err_pos), 2u * sizeof(float));
    mark_floats(offsetof(diff_out, J), sizeof o.J + sizeof o.Mf);
    for (k = 0; k < DH_IKC_MAX_SOL; k++) mark_floats(offsetof(diff_out, sol) + k * sizeof o.sol[0], sizeof o.sol[0].q);
    mark_floats(offsetof(diff_out, mf) + offsetof(dh_ikc_model_f32, a),
                offsetof(dh_ikc_model_f32, k) + sizeof o.mf.k - offsetof(dh_ikc_model_f32, a));
    mark_floats(offsetof(diff_out, mf) + offsetof(dh_ikc_model_f32, pre_inv), sizeof o.mf.pre_inv + sizeof o.mf.post_inv);
}

static int is_nan_bits(uint32_t u) { return (u & 0x7FFFFFFFu) > 0x7F800000u; }

typedef struct {
    unsigned long bad, bound, zero_sign, nan_payload, rigid_plane, inf_cross, ok, zero_beyond;
    size_t zero_first, zero_last; /* words of the last zero-sign difference */
} diff_tally;

/*
 * robot.h documents the zero-sign difference for dh_link_f32 and for
 * "the first frame of dh_fk_f32 with an identity base". 1 when the
 * zero-sign differences of this input lie there: dh_link_f32; dh_fk_f32 of
 * a one-joint robot with an identity float base; frames[0] of
 * dh_fk_frames_f32 (and T_end of a one-joint robot) with an identity base.
 * Others are accepted as well (the sign of a zero is not part of any
 * contract) but counted apart, so that the documentation can be checked.
 */
static int zero_documented(int fn, const diff_in *in, const diff_tally *t)
{
    const size_t m0 = offsetof(diff_out, M) / 4u, mf0 = offsetof(diff_out, Mf) / 4u;
    int one = in->rob->n == 1u && (in->rob->flags & DH_ROBOT_BASE_ID_F32) != 0u;
    if (fn == E_dh_link_f32) return 1;
    if (fn == E_dh_fk_f32) return one;
    if ((in->rob->flags & DH_ROBOT_BASE_ID_F32) == 0u) return 0;
    if (t->zero_first >= mf0) return t->zero_last < mf0 + 16u;  /* frames[0] only */
    return one && t->zero_last < m0 + 16u;                       /* T_end of one joint */
}

/*
 * 1 when the outputs agree: bitwise, except
 * - a float word that is a NaN in both (the payload and sign of a NaN are
 *   not part of any contract: IEEE 754 leaves them open; counted);
 * - C_ZERO_SIGN: a float word that is +-0 in both;
 * - C_INV / C_PLANE: with equal statuses, the inverse (plane) within the
 *   documented bound.
 */
static int agree(unsigned long idx, const diff_in *in, const diff_out *a, const diff_out *b, size_t len, int cmp, diff_tally *t)
{
    size_t w, lo = 0, hi = 0;
    int nan = 0, zero = 0, region = 0;
    if (memcmp(a, b, len) == 0) return 1;
    if (cmp == C_INV) { lo = offsetof(diff_out, M) / 4u; hi = lo + 16u; }
    if (cmp == C_PLANE) { lo = offsetof(diff_out, pl) / 4u; hi = lo + 4u; }
    for (w = 0; w < len / 4u; w++) {
        uint32_t wa, wb;
        memcpy(&wa, (const unsigned char *)a + 4u * w, 4);
        memcpy(&wb, (const unsigned char *)b + 4u * w, 4);
        if (wa == wb) continue;
        if (float_word[w] && is_nan_bits(wa) && is_nan_bits(wb)) { nan = 1; continue; }
        if (cmp == C_ZERO_SIGN && float_word[w] && ((wa | wb) & 0x7FFFFFFFu) == 0u) {
            if (!zero) t->zero_first = w;
            t->zero_last = w;
            zero = 1;
            continue;
        }
        if (w >= lo && w < hi) { region = 1; continue; }
        return 0;
    }
    if (region) {
        if (a->st != DH_OK || b->st != DH_OK) return 0;
        if (cmp == C_INV && !inv_close(&in->M[0], &a->M, &b->M)) return 0;
        if (cmp == C_PLANE) {
            int cross = 0, pc = plane_close(in, &a->pl, &b->pl, plane_rigid_err(&in->M[0]), &cross);
            if (pc == 0) return 0;
            if (cross) t->inf_cross++;
            if (pc == 2) { t->rigid_plane++; if (t->rigid_plane <= 3u) report("NOTE (accepted only with the rigid-path term, see plane_rigid_err):", "dh_mat4_apply_plane_f32", idx, in, a, b, DIFF_OUT_SMALL); }
        }
        t->bound++;
    }
    if (zero) t->zero_sign++;
    if (nan) t->nan_payload++;
    return 1;
}

static void run(int fn, const char *name, diff_gen gen, unsigned long count, size_t len, int cmp)
{
    static diff_in in;
    static diff_out oa, ob;
    diff_tally t;
    unsigned long i;
    clock_t t0 = clock();
    const char *only = getenv("DHT_DIFF_ONLY");
    if (only != NULL && strstr(name, only) == NULL) return;
    count /= count_div();
    if (count == 0ul) count = 1ul;
    memset(&t, 0, sizeof t);
    float_words_init();
    pool_make();
    ikc_pool_make();
    for (i = 0; i < count; i++) {
        memset(&in, 0, sizeof in);
        gen(&in);
        memset(&oa, 0xA5, len);
        memset(&ob, 0xA5, len);
        diff_calls_main[fn](&in, &oa);
        diff_calls_alt[fn](&in, &ob);
        unsigned long zs = t.zero_sign;
        if (oa.st == (int32_t)DH_OK) t.ok++;
        if (!agree(i, &in, &oa, &ob, len, cmp, &t)) {
            if (t.bad < 3ul) report("DISAGREEMENT", name, i, &in, &oa, &ob, len);
            t.bad++;
        } else if (t.zero_sign != zs && !zero_documented(fn, &in, &t)) {
            if (t.zero_beyond < 2ul)
                report("NOTE (zero sign outside the documented places):", name, i, &in, &oa, &ob, len);
            t.zero_beyond++;
        }
    }
    dht_printf("%-30s %8lu inputs", name, count);
    if (t.ok != 0ul) dht_printf(" (%lu DH_OK)", t.ok);
    dht_printf(": %lu disagree; within the exception: %lu bound, %lu zero sign; %lu NaN payload",
               t.bad, t.bound, t.zero_sign, t.nan_payload);
    if (cmp == C_PLANE)
        dht_printf("; %lu only with the rigid-path term; %lu Inf against a finite value of the other sign",
                   t.rigid_plane, t.inf_cross);
    if (cmp == C_ZERO_SIGN) dht_printf("; %lu zero sign outside the documented places", t.zero_beyond);
    dht_printf(" (%.2f s)\n", (double)(clock() - t0) / CLOCKS_PER_SEC);
    DHT_TRUE_MSG(t.bad == 0ul, "%s: %lu of %lu inputs disagree between the builds", name, t.bad, count);
}

/* one test case per function */
#define DIFF_CASE(name, gen, count, len, cmp) \
    static void t_##name(void) { run(E_##name, #name, gen, (unsigned long)(count), len, cmp); }
DIFF_FUNCS(DIFF_CASE)
#undef DIFF_CASE

static const char *const public_fns[] = {
#include "dh_public_fns.inc"
};
static const char *const table_names[] = {
#define DIFF_NAME(name, gen, count, len, cmp) #name,
    DIFF_FUNCS(DIFF_NAME)
#undef DIFF_NAME
};

/* the table covers every public function of include/dhmath/ (and no other name) */
static void covers_every_public_function(void)
{
    size_t i, j, n_pub = sizeof public_fns / sizeof public_fns[0];
    dht_printf("seed 0x%llx; %lu public functions\n", (unsigned long long)dht_seed(), (unsigned long)n_pub);
    DHT_EQ_INT(n_pub, DIFF_NFUNCS);
    for (i = 0; i < n_pub; i++) {
        int found = 0;
        for (j = 0; j < (size_t)DIFF_NFUNCS; j++) found |= strcmp(public_fns[i], table_names[j]) == 0;
        DHT_TRUE_MSG(found, "public function %s is not compared", public_fns[i]);
    }
}

static const dht_case cases[] = {
    DHT_CASE(covers_every_public_function),
#define DIFF_CASE_ROW(name, gen, count, len, cmp) DHT_CASE(t_##name),
    DIFF_FUNCS(DIFF_CASE_ROW)
#undef DIFF_CASE_ROW
};
DHT_MAIN(cases)
