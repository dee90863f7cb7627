/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bench_host.c - host benchmark of dhmath against peer libraries
 * (the speed goals of docs/performance.md). Run through tools/bench.sh, which also collects the
 * callgrind instruction counts and writes docs/generated/performance_host.md.
 *
 * Usage:
 *   bench_host [--reps N] [--csv FILE]   time every operation: N (>= 11,
 *                                        default 15) interleaved repetitions,
 *                                        median ns/op, table on stdout
 *   bench_host --count N                 run every operation exactly N times,
 *                                        no timing (for callgrind: inclusive
 *                                        Ir of bw_<id> / N = instructions/op)
 *   --only SUBSTR                        (either mode) only the operations
 *                                        whose id contains SUBSTR, and the harness
 *
 * Method: see bench_common.h. Inputs are random sets generated once with a
 * fixed seed (BENCH_NIN_TRIG angles, BENCH_NIN_FK joint configurations,
 * BENCH_NIN matrices); iteration k uses set k mod the set size, so inputs
 * change every call and branch predictors cannot learn the sequence.
 * Peers are compiled in only when found at configure time
 * (BENCH_HAVE_CGLM, BENCH_HAVE_FIXMATH, BENCH_HAVE_CPP); a missing peer is
 * reported as skipped.
 */
#define _GNU_SOURCE 1 /* sincosf */
#include "bench_common.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "dhmath/dhmath.h"

#if BENCH_HAVE_CGLM
#include <cglm/cglm.h>
#endif
#if BENCH_HAVE_FIXMATH
#include <libfixmath/fix16.h>
#endif

#define PI_D 3.14159265358979323846

volatile float bench_sink_f;
volatile double bench_sink_d;
volatile int32_t bench_sink_i;

/* ---- inputs and outputs --------------------------------------------------- */

static float in_deg[BENCH_NIN_TRIG];                 /* +-720 degrees */
static dh_q16 in_deg_q[BENCH_NIN_TRIG];              /* same, Q16.16 */
#if BENCH_HAVE_FIXMATH
static fix16_t in_rad_fx[BENCH_NIN_TRIG];            /* same in radians, fix16 (converted in double, untimed) */
#endif
static dh_mat4_f32 in_A[BENCH_NIN], in_B[BENCH_NIN];   /* random rigid transforms */
static dh_frame_q in_Aq[BENCH_NIN], in_Bq[BENCH_NIN];  /* same, fixed point (positions in m, Q16) */
static double in_q_deg[BENCH_NIN_FK][6];           /* Puma 560 joint angles within limits */
static float in_q_f[BENCH_NIN_FK][6];
static int32_t in_q_q[BENCH_NIN_FK][6];

static float out_s[BENCH_NIN_TRIG], out_c[BENCH_NIN_TRIG];
static dh_q30 out_sq[BENCH_NIN_TRIG], out_cq[BENCH_NIN_TRIG];
static dh_mat4_f32 out_M[BENCH_NIN_FK];
static dh_frame_q out_Fq[BENCH_NIN_FK];
static double out_D[BENCH_NIN_FK][4][4];
static dh_status out_st[BENCH_NIN_FK];

/* closed-form IK: models of robots with their joint limits, targets = FK of
 * random in-limit configurations (computed untimed) */
static dh_robot ikc_puma_r, ikc_puma_mm_r, ikc_kr5_r, ikc_kr6_r, ikc_kr6_mm_r;
static dh_ikc_model_f32 ikc_puma, ikc_kr5, ikc_kr6;
static dh_ikc_model_q ikc_puma_q, ikc_kr6_q;
static dh_mat4_f32 in_T_puma[BENCH_NIN_IKC], in_T_kr5[BENCH_NIN_IKC], in_T_kr6[BENCH_NIN_IKC];
static dh_frame_q in_T_puma_q[BENCH_NIN_IKC], in_T_kr6_q[BENCH_NIN_IKC];

/* KUKA KR6 R700 sixx in standard DH (a, d in m; alpha, theta offset in deg):
 * the robot of opw_kinematics' example makeKukaKR6_R700_sixx
 * (include/opw_kinematics/opw_parameters_examples.h: a1 0.025, a2 -0.035,
 * b 0, c1 0.4, c2 0.315, c3 0.365, c4 0.08, joint 2 offset -pi/2, joints
 * 1, 4, 6 sign -1) written as a DH table with the same base and flange
 * frames; limits +-170 deg on every joint are this benchmark's choice (the
 * targets' configurations are drawn within them). */
const bench_dh_robot bench_kr6 = {
    "KUKA KR6 R700 sixx", 6u,
    { { 0.025, 0.4, -90.0, 0.0, -170.0, 170.0 },
      { 0.315, 0.0, 0.0, 0.0, -170.0, 170.0 },
      { -0.035, 0.0, 90.0, 90.0, -170.0, 170.0 },
      { 0.0, 0.365, -90.0, 0.0, -170.0, 170.0 },
      { 0.0, 0.0, 90.0, 0.0, -170.0, 170.0 },
      { 0.0, 0.08, 0.0, 0.0, -170.0, 170.0 } }
};
const double bench_kr6_sign[6] = { -1.0, 1.0, 1.0, -1.0, 1.0, -1.0 };
/* q_ref of the KR6 rows: the robot's home (0, -90, 90, 0, 0, 0) deg */
static const float kr6_qref[6] = { 0.0f, -90.0f, 90.0f, 0.0f, 0.0f, 0.0f };
static const int32_t kr6_qref_q[6] = { 0, -90 * 65536, 90 * 65536, 0, 0, 0 };
static dh_ikc_sol_f32 out_sol[DH_IKC_MAX_SOL];
static dh_ikc_sol_q out_sol_q[DH_IKC_MAX_SOL];
static uint32_t out_nsol;

static dh_robot puma_m;   /* metres, float path */
static dh_robot puma_mm;  /* millimetres, fixed path */
static bench_ref_model puma_ref; /* metres, double reference */

#if BENCH_HAVE_CGLM
static mat4 cg_A[BENCH_NIN], cg_B[BENCH_NIN], cg_T[BENCH_NIN], cg_out[BENCH_NIN];
#endif

/* ---- wrappers: one operation each ----------------------------------------- */

BENCH_NOINLINE void bw_empty(uint32_t i)
{
    i &= BENCH_TRIG_MASK;
    bench_sink_f = in_deg[i];
}

BENCH_NOINLINE void bw_dh_sincos_f32(uint32_t i)
{
    i &= BENCH_TRIG_MASK;
    (void)dh_sincos_f32(in_deg[i], &out_s[i], &out_c[i]);
    bench_sink_f = out_s[i];
}

BENCH_NOINLINE void bw_glibc_sinf_cosf(uint32_t i)
{
    i &= BENCH_TRIG_MASK;
    float r = in_deg[i] * (float)(PI_D / 180.0);
    out_s[i] = sinf(r);
    out_c[i] = cosf(r);
    bench_sink_f = out_s[i];
}

BENCH_NOINLINE void bw_glibc_sincosf(uint32_t i)
{
    i &= BENCH_TRIG_MASK;
    float r = in_deg[i] * (float)(PI_D / 180.0);
    sincosf(r, &out_s[i], &out_c[i]);
    bench_sink_f = out_s[i];
}

/* Tight loop: 64 independent calls per operation (consecutive angles of
 * the set, outputs stored), nothing between them but the loop; the report
 * divides by BENCH_LOOP_N. The library's function is called out of line
 * (as linked from libdhmath.a), glibc's likewise. */
#define BENCH_LOOP_N 64u
BENCH_NOINLINE void bw_dh_sincos_f32_loop(uint32_t i)
{
    uint32_t k, b = (i * BENCH_LOOP_N) & BENCH_TRIG_MASK;
    for (k = 0; k < BENCH_LOOP_N; k++) (void)dh_sincos_f32(in_deg[b + k], &out_s[b + k], &out_c[b + k]);
    bench_sink_f = out_s[b];
}

BENCH_NOINLINE void bw_glibc_sinf_cosf_loop(uint32_t i)
{
    uint32_t k, b = (i * BENCH_LOOP_N) & BENCH_TRIG_MASK;
    for (k = 0; k < BENCH_LOOP_N; k++) {
        const float r = in_deg[b + k] * (float)(PI_D / 180.0);
        out_s[b + k] = sinf(r);
        out_c[b + k] = cosf(r);
    }
    bench_sink_f = out_s[b];
}

BENCH_NOINLINE void bw_dh_sincos_q(uint32_t i)
{
    i &= BENCH_TRIG_MASK;
    dh_sincos_q(in_deg_q[i], &out_sq[i], &out_cq[i]);
    bench_sink_i = out_sq[i];
}

#if BENCH_HAVE_FIXMATH
BENCH_NOINLINE void bw_fix16_sin_cos(uint32_t i)
{
    i &= BENCH_TRIG_MASK;
    out_sq[i] = fix16_sin(in_rad_fx[i]);
    out_cq[i] = fix16_cos(in_rad_fx[i]);
    bench_sink_i = out_sq[i];
}
#endif

BENCH_NOINLINE void bw_dh_mul_affine(uint32_t i)
{
    i &= BENCH_MASK;
    dh_mat4_mul_affine_f32(&in_A[i], &in_B[i], &out_M[i]);
    bench_sink_f = out_M[i].m[3][0];
}

BENCH_NOINLINE void bw_dh_mul(uint32_t i)
{
    i &= BENCH_MASK;
    dh_mat4_mul_f32(&in_A[i], &in_B[i], &out_M[i]);
    bench_sink_f = out_M[i].m[3][0];
}

BENCH_NOINLINE void bw_dh_inv_rigid(uint32_t i)
{
    i &= BENCH_MASK;
    dh_mat4_inv_rigid_f32(&in_A[i], &out_M[i]);
    bench_sink_f = out_M[i].m[3][0];
}

BENCH_NOINLINE void bw_dh_inv(uint32_t i)
{
    i &= BENCH_MASK;
    out_st[i] = dh_mat4_inv_f32(&in_A[i], &out_M[i]);
    bench_sink_f = out_M[i].m[3][0];
}

BENCH_NOINLINE void bw_dh_frame_mul_q(uint32_t i)
{
    i &= BENCH_MASK;
    out_st[i] = dh_frame_mul_q(&in_Aq[i], &in_Bq[i], &out_Fq[i]);
    bench_sink_i = out_Fq[i].p[0];
}

BENCH_NOINLINE void bw_dh_frame_inv_q(uint32_t i)
{
    i &= BENCH_MASK;
    out_st[i] = dh_frame_inv_q(&in_Aq[i], &out_Fq[i]);
    bench_sink_i = out_Fq[i].p[0];
}

BENCH_NOINLINE void bw_dh_ikc_kr5(uint32_t i)
{
    i &= BENCH_IKC_MASK;
    out_st[i] = dh_ikc_f32(&ikc_kr5, &in_T_kr5[i], NULL, 0u, out_sol, &out_nsol);
    bench_sink_f = out_sol[0].q[0];
}

/* the KR6 rows solve as a controller would: joint limits and a q_ref */
BENCH_NOINLINE void bw_dh_ikc_kr6(uint32_t i)
{
    i &= BENCH_IKC_MASK;
    out_st[i] = dh_ikc_f32(&ikc_kr6, &in_T_kr6[i], kr6_qref, 0u, out_sol, &out_nsol);
    bench_sink_f = out_sol[0].q[0];
}

BENCH_NOINLINE void bw_dh_ikc_q_kr6(uint32_t i)
{
    i &= BENCH_IKC_MASK;
    out_st[i] = dh_ikc_q(&ikc_kr6_q, &in_T_kr6_q[i], kr6_qref_q, 0u, out_sol_q, &out_nsol);
    bench_sink_i = out_sol_q[0].q[0];
}

BENCH_NOINLINE void bw_dh_ikc_puma(uint32_t i)
{
    i &= BENCH_IKC_MASK;
    out_st[i] = dh_ikc_f32(&ikc_puma, &in_T_puma[i], NULL, 0u, out_sol, &out_nsol);
    bench_sink_f = out_sol[0].q[0];
}

BENCH_NOINLINE void bw_dh_ikc_q_puma(uint32_t i)
{
    i &= BENCH_IKC_MASK;
    out_st[i] = dh_ikc_q(&ikc_puma_q, &in_T_puma_q[i], NULL, 0u, out_sol_q, &out_nsol);
    bench_sink_i = out_sol_q[0].q[0];
}

BENCH_NOINLINE void bw_dh_fk_f32(uint32_t i)
{
    i &= BENCH_FK_MASK;
    out_st[i] = dh_fk_f32(&puma_m, in_q_f[i], &out_M[i]);
    bench_sink_f = out_M[i].m[3][0];
}

BENCH_NOINLINE void bw_dh_fk_q(uint32_t i)
{
    i &= BENCH_FK_MASK;
    out_st[i] = dh_fk_q(&puma_mm, in_q_q[i], &out_Fq[i]);
    bench_sink_i = out_Fq[i].p[0];
}

BENCH_NOINLINE void bw_ref_fk_double(uint32_t i)
{
    i &= BENCH_FK_MASK;
    bench_ref_fk_model(&puma_ref, in_q_deg[i], out_D[i]);
    bench_sink_d = out_D[i][3][0];
}

#if BENCH_HAVE_CGLM
BENCH_NOINLINE void bw_glm_mul(uint32_t i)
{
    i &= BENCH_MASK;
    glm_mul(cg_A[i], cg_B[i], cg_out[i]);
    bench_sink_f = cg_out[i][3][0];
}

BENCH_NOINLINE void bw_glm_mat4_mul(uint32_t i)
{
    i &= BENCH_MASK;
    glm_mat4_mul(cg_A[i], cg_B[i], cg_out[i]);
    bench_sink_f = cg_out[i][3][0];
}

/* in place (the cglm API): the stored matrix alternates between A and A^-1,
 * both rigid, so the input stays valid and no copy is timed */
BENCH_NOINLINE void bw_glm_inv_tr(uint32_t i)
{
    i &= BENCH_MASK;
    glm_inv_tr(cg_T[i]);
    bench_sink_f = cg_T[i][3][0];
}

BENCH_NOINLINE void bw_glm_mat4_inv(uint32_t i)
{
    i &= BENCH_MASK;
    glm_mat4_inv(cg_A[i], cg_out[i]);
    bench_sink_f = cg_out[i][3][0];
}
#endif

#if !BENCH_HAVE_CPP
int bench_cpp_setup(const float (*A)[16], const float (*B)[16], const double (*q_deg)[6], bench_op *o, int max)
{
    (void)A; (void)B; (void)q_deg; (void)o; (void)max;
    return -1;
}

int bench_cpp_kdl_fk_pos(uint32_t i, double p[3])
{
    (void)i; (void)p;
    return 0;
}
#endif

#if !BENCH_HAVE_OPW
int bench_opw_setup(const float (*T)[16], bench_op *o, int max)
{
    (void)T; (void)o; (void)max;
    return -1;
}

int bench_opw_solutions(uint32_t i, int dbl, double q_dh_deg[8][6])
{
    (void)i; (void)dbl; (void)q_dh_deg;
    return 0;
}
#endif

/* ---- operation table ------------------------------------------------------ */

#define MAX_OPS 48
static bench_op ops[MAX_OPS];
static int n_ops;

static void add_op(const char *id, const char *group, const char *lib, const char *desc, bench_fn fn)
{
    if (n_ops < MAX_OPS) {
        bench_op *o = &ops[n_ops++];
        o->id = id;
        o->group = group;
        o->lib = lib;
        o->desc = desc;
        o->fn = fn;
    }
}

/* ---- input generation (double precision, independent of dhmath) ------------ */

static uint64_t rng = 0x9E3779B97F4A7C15ULL;

/* random rotation from a random unit quaternion, random translation */
static void rand_rigid(double R[3][3], double p[3])
{
    double q0, q1, q2, q3, n;
    do {
        q0 = bench_rand(&rng, -1, 1);
        q1 = bench_rand(&rng, -1, 1);
        q2 = bench_rand(&rng, -1, 1);
        q3 = bench_rand(&rng, -1, 1);
        n = q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3;
    } while (n < 0.01 || n > 1.0);
    n = sqrt(n);
    q0 /= n; q1 /= n; q2 /= n; q3 /= n;
    /* R[row][col] */
    R[0][0] = 1 - 2 * (q2 * q2 + q3 * q3); R[0][1] = 2 * (q1 * q2 - q0 * q3); R[0][2] = 2 * (q1 * q3 + q0 * q2);
    R[1][0] = 2 * (q1 * q2 + q0 * q3); R[1][1] = 1 - 2 * (q1 * q1 + q3 * q3); R[1][2] = 2 * (q2 * q3 - q0 * q1);
    R[2][0] = 2 * (q1 * q3 - q0 * q2); R[2][1] = 2 * (q2 * q3 + q0 * q1); R[2][2] = 1 - 2 * (q1 * q1 + q2 * q2);
    p[0] = bench_rand(&rng, -1, 1);
    p[1] = bench_rand(&rng, -1, 1);
    p[2] = bench_rand(&rng, -1, 1);
}

static int32_t round_q(double x, int frac)
{
    return (int32_t)floor(x * (double)(1L << frac) + 0.5);
}

static void to_f32(dh_mat4_f32 *M, double R[3][3], const double p[3])
{
    int r, c;
    for (c = 0; c < 3; c++) {
        for (r = 0; r < 3; r++) M->m[c][r] = (float)R[r][c];
        M->m[c][3] = 0.0f;
    }
    for (r = 0; r < 3; r++) M->m[3][r] = (float)p[r];
    M->m[3][3] = 1.0f;
}

static void to_q(dh_frame_q *F, double R[3][3], const double p[3])
{
    int r, c;
    for (r = 0; r < 3; r++) {
        for (c = 0; c < 3; c++) F->r[c][r] = round_q(R[r][c], 30); /* r[col][row] */
        F->p[r] = round_q(p[r], DH_QPOS_FRAC);
    }
}

static int build_puma(dh_robot *r, double scale)
{
    unsigned i;
    if (dh_robot_init(r, DH_CONV_STANDARD) != DH_OK) return 0;
    for (i = 0; i < bench_puma560.n; i++) {
        const bench_dh_row *j = &bench_puma560.j[i];
        if (dh_robot_add_joint_f32(r, DH_JOINT_REVOLUTE, (float)j->theta_deg, (float)(j->d * scale),
                                   (float)(j->a * scale), (float)j->alpha_deg) != DH_OK)
            return 0;
    }
    return 1;
}

/* robot with its joint limits, for the closed-form IK rows */
static int build_limited(dh_robot *r, const bench_dh_robot *b, double scale)
{
    unsigned i;
    if (dh_robot_init(r, DH_CONV_STANDARD) != DH_OK) return 0;
    for (i = 0; i < b->n; i++) {
        const bench_dh_row *j = &b->j[i];
        if (dh_robot_add_joint_f32(r, DH_JOINT_REVOLUTE, (float)j->theta_deg, (float)(j->d * scale),
                                   (float)(j->a * scale), (float)j->alpha_deg) != DH_OK ||
            dh_robot_set_limits_f32(r, i, (float)j->qmin, (float)j->qmax) != DH_OK)
            return 0;
    }
    return 1;
}

/* the IK models and targets (FK of random in-limit configurations) */
static int make_ikc_inputs(void)
{
    uint32_t i;
    int k;
    if (!build_limited(&ikc_puma_r, &bench_puma560, 1.0) || !build_limited(&ikc_puma_mm_r, &bench_puma560, 1000.0) ||
        !build_limited(&ikc_kr5_r, &bench_kr5, 1.0) || dh_ikc_analyse_f32(&ikc_puma_r, &ikc_puma) != DH_OK ||
        dh_ikc_analyse_f32(&ikc_kr5_r, &ikc_kr5) != DH_OK || dh_ikc_analyse_q(&ikc_puma_mm_r, &ikc_puma_q) != DH_OK)
        return 0;
    if (!build_limited(&ikc_kr6_r, &bench_kr6, 1.0) || !build_limited(&ikc_kr6_mm_r, &bench_kr6, 1000.0) ||
        dh_ikc_analyse_f32(&ikc_kr6_r, &ikc_kr6) != DH_OK || dh_ikc_analyse_q(&ikc_kr6_mm_r, &ikc_kr6_q) != DH_OK)
        return 0;
    {
        /* KR6 targets from a generator of their own, so the other inputs
         * stay those of the runs without the KR6 rows */
        uint64_t rng6 = 0xD1B54A32D192ED03ULL;
        for (i = 0; i < BENCH_NIN_IKC; i++) {
            float q6[6];
            int32_t q6q[6];
            for (k = 0; k < 6; k++) {
                const bench_dh_row *j = &bench_kr6.j[k];
                q6[k] = (float)bench_rand(&rng6, j->qmin, j->qmax);
                q6q[k] = round_q((double)q6[k], 16);
            }
            if (dh_fk_f32(&ikc_kr6_r, q6, &in_T_kr6[i]) != DH_OK || dh_fk_q(&ikc_kr6_mm_r, q6q, &in_T_kr6_q[i]) != DH_OK)
                return 0;
        }
    }
    for (i = 0; i < BENCH_NIN_IKC; i++) {
        float qp[6], qk[6];
        int32_t qq[6];
        for (k = 0; k < 6; k++) {
            const bench_dh_row *j = &bench_puma560.j[k];
            qp[k] = (float)bench_rand(&rng, j->qmin, j->qmax);
            qq[k] = round_q((double)qp[k], 16);
            j = &bench_kr5.j[k];
            qk[k] = (float)bench_rand(&rng, j->qmin, j->qmax);
        }
        if (dh_fk_f32(&ikc_puma_r, qp, &in_T_puma[i]) != DH_OK || dh_fk_f32(&ikc_kr5_r, qk, &in_T_kr5[i]) != DH_OK ||
            dh_fk_q(&ikc_puma_mm_r, qq, &in_T_puma_q[i]) != DH_OK)
            return 0;
    }
    return 1;
}

static void make_inputs(void)
{
    uint32_t i;
    int k;
    for (i = 0; i < BENCH_NIN_TRIG; i++) {
        double d = bench_rand(&rng, -720.0, 720.0);
        in_deg[i] = (float)d;
        in_deg_q[i] = round_q(d, 16);
#if BENCH_HAVE_FIXMATH
        in_rad_fx[i] = round_q(d * (PI_D / 180.0), 16);
#endif
    }
    for (i = 0; i < BENCH_NIN; i++) {
        double R[3][3], p[3];
        rand_rigid(R, p);
        to_f32(&in_A[i], R, p);
        to_q(&in_Aq[i], R, p);
        rand_rigid(R, p);
        to_f32(&in_B[i], R, p);
        to_q(&in_Bq[i], R, p);
#if BENCH_HAVE_CGLM
        memcpy(cg_A[i], in_A[i].m, sizeof(mat4));
        memcpy(cg_B[i], in_B[i].m, sizeof(mat4));
        memcpy(cg_T[i], in_A[i].m, sizeof(mat4));
#endif
    }
    for (i = 0; i < BENCH_NIN_FK; i++) {
        for (k = 0; k < 6; k++) {
            const bench_dh_row *j = &bench_puma560.j[k];
            double q = bench_rand(&rng, j->qmin, j->qmax);
            in_q_f[i][k] = (float)q;
            in_q_deg[i][k] = (double)in_q_f[i][k];
            in_q_q[i][k] = round_q(q, 16);
        }
    }
}

/* ---- sanity checks: every peer computes the same thing --------------------- */

static int opw_on; /* the opw rows are in this build */
static void opw_check(int dbl);

#if BENCH_HAVE_CGLM
static double max_diff16(const float *x, const float *y)
{
    double m = 0.0;
    int k;
    for (k = 0; k < 16; k++) {
        double e = fabs((double)x[k] - (double)y[k]);
        if (e > m) m = e;
    }
    return m;
}
#endif

static int sanity(void)
{
    uint32_t i;
    int bad = 0;
    double e_fk = 0.0, e_kdl = 0.0, e_fkq = 0.0, e_cg = 0.0;
    for (i = 0; i < BENCH_NIN; i++) {
        double T[4][4], p[3];
        int k;
        bw_dh_fk_f32(i);
        bw_ref_fk_double(i);
        bench_ref_fk(&bench_puma560, 1.0, in_q_deg[i], T);
        for (k = 0; k < 3; k++) {
            double e = fabs((double)out_M[i].m[3][k] - T[3][k]);
            if (e > e_fk) e_fk = e;
            e = fabs(out_D[i][3][k] - T[3][k]);
            if (e > 1e-12) bad = 1;
        }
        bw_dh_fk_q(i);
        {
            double qd[6], Tq[4][4];
            for (k = 0; k < 6; k++) qd[k] = (double)in_q_q[i][k] / 65536.0;
            bench_ref_fk(&bench_puma560, 1000.0, qd, Tq);
            for (k = 0; k < 3; k++) {
                double e = fabs((double)out_Fq[i].p[k] / (double)(1L << DH_QPOS_FRAC) - Tq[3][k]);
                if (e > e_fkq) e_fkq = e;
            }
        }
        if (bench_cpp_kdl_fk_pos(i, p)) {
            for (k = 0; k < 3; k++) {
                double e = fabs(p[k] - T[3][k]);
                if (e > e_kdl) e_kdl = e;
            }
        }
#if BENCH_HAVE_CGLM
        bw_dh_mul_affine(i);
        bw_glm_mul(i);
        e_cg = fmax(e_cg, max_diff16(&out_M[i].m[0][0], &cg_out[i][0][0]));
        bw_dh_inv(i);
        bw_glm_mat4_inv(i);
        e_cg = fmax(e_cg, max_diff16(&out_M[i].m[0][0], &cg_out[i][0][0]));
#endif
    }
    {
        /* closed-form IK: every target is FK of an in-limit configuration,
         * so every call must find a solution */
        uint32_t bad_ikc = 0;
        for (i = 0; i < BENCH_NIN_IKC; i++) {
            bw_dh_ikc_kr5(i);
            bad_ikc += out_st[i] != DH_OK;
            bw_dh_ikc_puma(i);
            bad_ikc += out_st[i] != DH_OK;
            bw_dh_ikc_q_puma(i);
            bad_ikc += out_st[i] != DH_OK;
            bw_dh_ikc_kr6(i);
            bad_ikc += out_st[i] != DH_OK;
            bw_dh_ikc_q_kr6(i);
            bad_ikc += out_st[i] != DH_OK;
        }
        printf("sanity: closed-form IK calls without a solution: %u of %u\n", (unsigned)bad_ikc,
               5u * BENCH_NIN_IKC);
        if (bad_ikc != 0u) bad = 1;
    }
    opw_check(1);
    opw_check(0);
    printf("sanity: Puma FK |dp| dhmath f32 vs double ref %.2e m, dhmath q vs ref %.2e mm, "
           "KDL vs ref %.2e m, dhmath vs cglm products/inverses %.2e\n",
           e_fk, e_fkq, e_kdl, e_cg);
    if (bad || e_fk > 1e-5 || e_kdl > 1e-9 || e_cg > 1e-5 || e_fkq > 1e-2) {
        printf("sanity: FAILED (a peer or dhmath computes something else)\n");
        bad = 1;
    }
#if BENCH_HAVE_CGLM
    /* restore the in-place inverse inputs */
    for (i = 0; i < BENCH_NIN; i++) memcpy(cg_T[i], in_A[i].m, sizeof(mat4));
#endif
    return bad;
}

/* ---- opw_kinematics against dh_ikc_f32 ------------------------------------ */

static double wrap180(double x)
{
    x = fmod(x, 360.0);
    if (x > 180.0) x -= 360.0;
    if (x <= -180.0) x += 360.0;
    return x;
}

/* Solution sets of opw and dh_ikc_f32 (KR6, limits, q_ref) on every KR6
 * target: opw's finite solutions as DH joint values, wrapped to
 * (-180, 180] and kept where within the +-170 deg limits, must be as many
 * as dhmath's, each matched by one of dhmath's within 1e-3 deg on every
 * joint. Reported, not fatal: the lines go into the generated page. */
static void opw_check(int dbl)
{
    uint32_t i, n_count = 0u, n_sol = 0u, n_unmatched = 0u, shown = 0u;
    double worst = 0.0;
    const char *name = dbl ? "inverse<double>" : "inverse<float>";
    if (!opw_on) return;
    for (i = 0; i < BENCH_NIN_IKC; i++) {
        double qo[8][6];
        int no = bench_opw_solutions(i, dbl, qo), s, t, j;
        uint32_t kept = 0u;
        bw_dh_ikc_kr6(i);
        for (s = 0; s < no; s++) {
            int in = 1;
            double best = 1e300;
            for (j = 0; j < 6; j++) {
                qo[s][j] = wrap180(qo[s][j]);
                in = in && fabs(qo[s][j]) <= 170.0;
            }
            if (!in) continue;
            kept++;
            for (t = 0; t < (int)out_nsol; t++) {
                double d = 0.0;
                for (j = 0; j < 6; j++) d = fmax(d, fabs(wrap180(qo[s][j] - (double)out_sol[t].q[j])));
                best = fmin(best, d);
            }
            n_sol++;
            if (best < 1e300 && best > worst) worst = best;
            if (!(best <= 1e-3)) {
                n_unmatched++;
                if (shown++ < 4u)
                    printf("sanity: opw %s target %u solution (%.4f %.4f %.4f %.4f %.4f %.4f) deg: nearest dh_ikc_f32 "
                           "solution %.2e deg away\n", name, (unsigned)i, qo[s][0], qo[s][1], qo[s][2], qo[s][3],
                           qo[s][4], qo[s][5], best);
            }
        }
        if (kept != out_nsol) {
            n_count++;
            if (shown++ < 4u)
                printf("sanity: opw %s target %u: %u solutions within the limits, dh_ikc_f32 %u\n", name,
                       (unsigned)i, (unsigned)kept, (unsigned)out_nsol);
        }
    }
    printf("sanity: opw_kinematics %s vs dh_ikc_f32 (KR6 R700, %u targets, opw's solutions within the limits): "
           "%u targets with a different solution count, %u of %u opw solutions without a dh_ikc_f32 one within "
           "1e-3 deg, largest joint difference to the nearest %.2e deg\n",
           name, (unsigned)BENCH_NIN_IKC, (unsigned)n_count, (unsigned)n_unmatched, (unsigned)n_sol, worst);
}

/* ---- timing ---------------------------------------------------------------- */

/* CPU time of this thread: the host is shared (builds, QEMU runs), and
 * wall-clock samples would include time spent preempted. */
static double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

static double run_ns(bench_fn fn, uint32_t iters)
{
    uint32_t k;
    double t0 = now_ns();
    for (k = 0; k < iters; k++) fn(k);
    return (now_ns() - t0) / (double)iters;
}

static int cmp_d(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

#define MAX_REPS 101

int main(int argc, char **argv)
{
    int reps = 15, a, k, r;
    long count = 0;
    const char *csv = NULL, *only = NULL;
    static double samples[MAX_OPS][MAX_REPS];
    static uint32_t iters[MAX_OPS];
    double med[MAX_OPS], mn[MAX_OPS];

    for (a = 1; a < argc; a++) {
        if (strcmp(argv[a], "--reps") == 0 && a + 1 < argc) reps = atoi(argv[++a]);
        else if (strcmp(argv[a], "--count") == 0 && a + 1 < argc) count = atol(argv[++a]);
        else if (strcmp(argv[a], "--csv") == 0 && a + 1 < argc) csv = argv[++a];
        else if (strcmp(argv[a], "--only") == 0 && a + 1 < argc) only = argv[++a];
        else {
            fprintf(stderr, "usage: %s [--reps N (11..%d)] [--csv FILE] [--only SUBSTR] | --count N [--only SUBSTR]\n", argv[0], MAX_REPS);
            return 2;
        }
    }
    if (reps < 11 || reps > MAX_REPS) {
        fprintf(stderr, "--reps must be 11..%d\n", MAX_REPS);
        return 2;
    }

    make_inputs();
    bench_ref_prepare(&bench_puma560, 1.0, &puma_ref);
    if (!build_puma(&puma_m, 1.0) || !build_puma(&puma_mm, 1000.0)) {
        fprintf(stderr, "cannot build the Puma 560 model\n");
        return 1;
    }
    if (!make_ikc_inputs()) {
        fprintf(stderr, "cannot build the closed-form IK models or targets\n");
        return 1;
    }

    add_op("empty", "harness", "-", "call harness only (indirect call + volatile store)", bw_empty);
    add_op("dh_sincos_f32", "sincos_f32", "dhmath", "dh_sincos_f32(deg)", bw_dh_sincos_f32);
    add_op("glibc_sinf_cosf", "sincos_f32", "glibc", "sinf(r) + cosf(r), r = deg * (float)(pi/180)", bw_glibc_sinf_cosf);
    add_op("glibc_sincosf", "sincos_f32", "glibc", "sincosf(r), r = deg * (float)(pi/180)", bw_glibc_sincosf);
    add_op("dh_sincos_f32_loop", "sincos_loop", "dhmath", "64 x dh_sincos_f32(deg) in a tight loop of independent calls (per 64)", bw_dh_sincos_f32_loop);
    add_op("glibc_sinf_cosf_loop", "sincos_loop", "glibc", "64 x sinf(r) + cosf(r) in a tight loop (per 64)", bw_glibc_sinf_cosf_loop);
    add_op("dh_sincos_q", "sincos_q", "dhmath", "dh_sincos_q(deg Q16.16) -> Q2.30", bw_dh_sincos_q);
#if BENCH_HAVE_FIXMATH
    add_op("fix16_sin_cos", "sincos_q", "libfixmath", "fix16_sin(r) + fix16_cos(r), r fix16 radians (precomputed)", bw_fix16_sin_cos);
#else
    printf("skipped: libfixmath (libfixmath-dev not found at configure time)\n");
#endif
    add_op("dh_mul_affine", "compose", "dhmath", "dh_mat4_mul_affine_f32", bw_dh_mul_affine);
#if BENCH_HAVE_CGLM
    add_op("glm_mul", "compose", "cglm", "glm_mul (affine, SSE2)", bw_glm_mul);
#endif
    add_op("dh_frame_mul_q", "compose", "dhmath", "dh_frame_mul_q (fixed point, for information)", bw_dh_frame_mul_q);
    add_op("dh_mul", "mul4", "dhmath", "dh_mat4_mul_f32 (general 4x4)", bw_dh_mul);
#if BENCH_HAVE_CGLM
    add_op("glm_mat4_mul", "mul4", "cglm", "glm_mat4_mul (general 4x4, SSE2)", bw_glm_mat4_mul);
#endif
    add_op("dh_inv_rigid", "inv_rigid", "dhmath", "dh_mat4_inv_rigid_f32", bw_dh_inv_rigid);
#if BENCH_HAVE_CGLM
    add_op("glm_inv_tr", "inv_rigid", "cglm", "glm_inv_tr (in place, SSE2)", bw_glm_inv_tr);
#endif
    add_op("dh_frame_inv_q", "inv_rigid", "dhmath", "dh_frame_inv_q (for information, fixed point)", bw_dh_frame_inv_q);
    add_op("dh_inv", "inv_general", "dhmath", "dh_mat4_inv_f32 (reports singularity, general)", bw_dh_inv);
#if BENCH_HAVE_CGLM
    add_op("glm_mat4_inv", "inv_general", "cglm", "glm_mat4_inv (SSE2, no singularity report)", bw_glm_mat4_inv);
#else
    printf("skipped: cglm (libcglm-dev not found at configure time)\n");
#endif
    add_op("dh_fk_f32", "fk_puma", "dhmath", "dh_fk_f32, Puma 560 (m)", bw_dh_fk_f32);
    add_op("dh_fk_q", "fk_puma", "dhmath", "dh_fk_q, Puma 560 (mm, Q16 lengths)", bw_dh_fk_q);
    add_op("dh_ikc_kr5", "ikc", "dhmath", "dh_ikc_f32, KUKA KR5 (m), all solutions, targets FK of in-limit configurations", bw_dh_ikc_kr5);
    add_op("dh_ikc_puma", "ikc", "dhmath", "dh_ikc_f32, Puma 560 (m), all solutions", bw_dh_ikc_puma);
    add_op("dh_ikc_q_puma", "ikc", "dhmath", "dh_ikc_q, Puma 560 (mm), all solutions", bw_dh_ikc_q_puma);
    add_op("dh_ikc_kr6", "ikc_kr6", "dhmath", "dh_ikc_f32, KUKA KR6 R700 sixx (m), all solutions within +-170 deg limits, q_ref home", bw_dh_ikc_kr6);
    add_op("dh_ikc_q_kr6", "ikc_kr6", "dhmath", "dh_ikc_q, KUKA KR6 R700 sixx (mm), same limits and q_ref (for information, fixed point)", bw_dh_ikc_q_kr6);
    add_op("ref_fk_double", "fk_puma", "ref", "plain double DH FK (libm sin+cos of theta, sin/cos alpha precomputed, 4x4 products)", bw_ref_fk_double);
    {
        int got = bench_cpp_setup((const float (*)[16])(const void *)in_A, (const float (*)[16])(const void *)in_B,
                                  (const double (*)[6])in_q_deg, &ops[n_ops], MAX_OPS - n_ops);
        if (got < 0) {
            printf("skipped: Eigen and Orocos KDL (no C++ compiler or packages at configure time)\n");
        } else {
            n_ops += got;
        }
        got = bench_opw_setup((const float (*)[16])(const void *)in_T_kr6, &ops[n_ops], MAX_OPS - n_ops);
        if (got < 0) {
            printf("skipped: opw_kinematics (not in this build: git clone --branch 0.5.5 "
                   "https://github.com/Jmeyer1292/opw_kinematics and run OPW_DIR=<that clone> tools/bench.sh)\n");
        } else {
            n_ops += got;
            opw_on = 1;
        }
    }

    if (only != NULL) {
        /* keep the harness row and the operations whose id contains SUBSTR */
        int w = 1;
        for (k = 1; k < n_ops; k++)
            if (strstr(ops[k].id, only) != NULL) ops[w++] = ops[k];
        n_ops = w;
    }

    if (count > 0) {
        /* no sanity pass here: it would add calls to the counted wrappers */
        for (k = 0; k < n_ops; k++) {
            long it;
            for (it = 0; it < count; it++) ops[k].fn((uint32_t)it);
        }
        printf("count mode: every operation ran %ld times\n", count);
        return 0;
    }

    if (sanity() != 0) return 1;

    /* calibrate: about 2 ms per sample */
    for (k = 0; k < n_ops; k++) {
        double t = run_ns(ops[k].fn, 20000u);
        double n = 2e6 / (t > 0.1 ? t : 0.1);
        iters[k] = (uint32_t)(n < 1000.0 ? 1000.0 : (n > 4e7 ? 4e7 : n));
    }
    /* repetitions interleaved across operations, so slow drifts (frequency,
     * other load) hit every operation alike */
    for (r = 0; r < reps; r++)
        for (k = 0; k < n_ops; k++) samples[k][r] = run_ns(ops[k].fn, iters[k]);
    for (k = 0; k < n_ops; k++) {
        qsort(samples[k], (size_t)reps, sizeof(double), cmp_d);
        med[k] = samples[k][reps / 2];
        mn[k] = samples[k][0];
    }

    printf("\n%-18s %-12s %-11s %9s %9s %9s\n", "op", "group", "lib", "median_ns", "min_ns", "net_ns");
    for (k = 0; k < n_ops; k++)
        printf("%-18s %-12s %-11s %9.2f %9.2f %9.2f\n", ops[k].id, ops[k].group, ops[k].lib, med[k], mn[k],
               med[k] - med[0]);
    printf("(median of %d repetitions; net = median - median(empty))\n", reps);

    if (csv != NULL) {
        FILE *f = fopen(csv, "w");
        if (f == NULL) {
            perror(csv);
            return 1;
        }
        fprintf(f, "id,group,lib,median_ns,min_ns,net_ns,reps,desc\n");
        for (k = 0; k < n_ops; k++)
            fprintf(f, "%s,%s,%s,%.4f,%.4f,%.4f,%d,\"%s\"\n", ops[k].id, ops[k].group, ops[k].lib, med[k], mn[k],
                    med[k] - med[0], reps, ops[k].desc);
        fclose(f);
    }
    return 0;
}
