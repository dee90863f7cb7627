/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bench_target.c - on-target benchmark firmware: instructions (under QEMU
 * with -icount shift=0) or cycles (on hardware) per call of dhmath
 * operations, float and fixed point, on Cortex-M0/M0+, M4F and M7, with
 * newlib's sinf/cosf and (bench_cglm.c) cglm as peers.
 *
 * Counter
 * - SysTick on the processor clock, 24-bit, counting down from 0xFFFFFF;
 *   its interrupt counts the wraps, so the count is 64 bits wide.
 *   Under QEMU with -icount shift=0 virtual time advances exactly 1 ns per
 *   executed guest instruction, and SysTick ticks once per clock period of
 *   the board (40 ns on MPS2 at 25 MHz, 62.5 ns on the micro:bit at 16 MHz),
 *   so ticks x (ns per tick) = executed instructions.
 * - ARMv7-M (M3/M4/M7): DWT->CYCCNT is enabled and used instead if it
 *   advances (real hardware; QEMU 7.2 does not model the DWT, the register
 *   reads 0). The report says which counter was used.
 * - Calibration: a loop of exactly 2 instructions per iteration (SUBS, BNE)
 *   run for 10^5 and 1.01 * 10^7 iterations; the difference is 2 * 10^7
 *   instructions. Instructions per tick = 2e7 / ticks: 40 or 62.5 under
 *   icount (+-1 tick of quantisation; the report rounds it). A ratio below 1.5 means the counter counts core clock
 *   cycles (hardware): the figures are then cycles, unscaled.
 *
 * Method per operation: bt_run() calls a wrapper fn(i) through a pointer
 * for i = 0..n-1 over precomputed inputs (indexed by i). The same loop runs
 * with the wrapper calling a null twin of the function (same prototype,
 * returns at once) and with an empty wrapper; the differences give the
 * function's own instructions and the cost of the whole call (see
 * "operations" below).
 *
 * Output: lines starting with "BT " on the semihosting console, parsed by
 * bench/target/report.py. Exit status: 0, or 1 if a sanity check failed
 * (an operation returned an error, results disagree).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "bench_target.h"
#include "dh_robots.h"

#ifndef BENCH_CORE
#define BENCH_CORE "unknown core"
#endif
#ifndef BENCH_OPT
#define BENCH_OPT "?"
#endif

#define BT_DEG2RAD 0.017453292519943295f

/* ---- counter ------------------------------------------------------------ */

#define BT_SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define BT_SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define BT_SYST_CVR (*(volatile uint32_t *)0xE000E018u)
#define BT_DEMCR (*(volatile uint32_t *)0xE000EDFCu)
#define BT_DWT_CTRL (*(volatile uint32_t *)0xE0001000u)
#define BT_DWT_CYCCNT (*(volatile uint32_t *)0xE0001004u)

#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__)
#define BT_HAS_DWT 1
#else
#define BT_HAS_DWT 0
#endif

static volatile uint32_t bt_wraps;
static int bt_use_dwt;
#if BT_HAS_DWT
static uint32_t bt_dwt_last;
static uint64_t bt_dwt_hi;
#endif

void SysTick_Handler(void);
void SysTick_Handler(void)
{
    bt_wraps = bt_wraps + 1u;
}

static BT_NOINLINE uint64_t bt_now(void)
{
    uint32_t w, v;
#if BT_HAS_DWT
    if (bt_use_dwt) {
        uint32_t c = BT_DWT_CYCCNT;
        if (c < bt_dwt_last) {
            bt_dwt_hi += (uint64_t)1 << 32;
        }
        bt_dwt_last = c;
        return bt_dwt_hi + c;
    }
#endif
    do {
        w = bt_wraps;
        v = BT_SYST_CVR;
    } while (w != bt_wraps);
    return ((uint64_t)w << 24) + (0xFFFFFFu - v);
}

/* Exactly 2 instructions per iteration (n >= 1). */
static BT_NOINLINE void bt_spin(uint32_t n)
{
#if defined(__ARM_ARCH_6M__)
    /* GCC passes Thumb-1 inline asm in divided syntax: SUB sets the flags */
    __asm__ volatile("1:\n\tsub %0, #1\n\tbne 1b" : "+l"(n) : : "cc");
#else
    __asm__ volatile("1:\n\tsubs %0, %0, #1\n\tbne 1b" : "+l"(n) : : "cc");
#endif
}

static void bt_counter_init(void)
{
#if BT_HAS_DWT
    uint32_t c0, c1;
    BT_DEMCR |= 1u << 24;   /* TRCENA */
    BT_DWT_CYCCNT = 0u;
    BT_DWT_CTRL |= 1u;      /* CYCCNTENA */
    c0 = BT_DWT_CYCCNT;
    bt_spin(1000u);
    c1 = BT_DWT_CYCCNT;
    if (c1 != c0) {
        bt_use_dwt = 1;
        bt_dwt_last = BT_DWT_CYCCNT;
        return;
    }
#endif
    BT_SYST_CSR = 0u;
    BT_SYST_RVR = 0xFFFFFFu;
    BT_SYST_CVR = 0u;        /* any write clears the counter */
    BT_SYST_CSR = 7u;        /* ENABLE | TICKINT | CLKSOURCE = processor clock */
}

/* scale = bt_num / bt_den instructions per tick (1/1 for cycles) */
static uint64_t bt_num = 1u, bt_den = 1u;
static const char *bt_unit = "cycles";

static int bt_calibrate(void)
{
    uint64_t t0, t1, t2, d1, d2, ticks;
    t0 = bt_now();
    bt_spin(100000u);
    t1 = bt_now();
    bt_spin(10100000u);
    t2 = bt_now();
    d1 = t1 - t0;
    d2 = t2 - t1;
    ticks = d2 - d1;
    printf("BT calib|%s|%llu|%llu\n", bt_use_dwt ? "DWT CYCCNT" : "SysTick",
           (unsigned long long)20000000u, (unsigned long long)ticks);
    if (ticks == 0u || d2 <= d1) {
        printf("BT error|counter does not advance\n");
        return 0;
    }
    if (ticks * 3u <= 2u * 20000000u) {
        /* >= 1.5 instructions per tick: a virtual clock (QEMU -icount). */
        bt_num = 20000000u;
        bt_den = ticks;
        bt_unit = "instructions";
    }
    printf("BT unit|%s|%llu|%llu\n", bt_unit, (unsigned long long)bt_num,
           (unsigned long long)bt_den);
    return 1;
}

static BT_NOINLINE uint64_t bt_run(bt_fn fn, uint32_t n)
{
    uint64_t t0, t1;
    uint32_t i;
    t0 = bt_now();
    for (i = 0; i < n; i++) {
        fn(i);
    }
    t1 = bt_now();
    return t1 - t0;
}

/* ---- inputs --------------------------------------------------------------- */

__attribute__((aligned(16))) dh_mat4_f32 bt_A[BT_NSET];
__attribute__((aligned(16))) dh_mat4_f32 bt_B[BT_NSET];
__attribute__((aligned(16))) dh_mat4_f32 bt_out;
__attribute__((aligned(16))) dh_mat4_f32 bt_M[BT_NSET];
dh_vec3_f32 bt_pts[BT_NSET];
dh_vec3_f32 bt_vout;
volatile uint32_t bt_sink;

static dh_frame_q bt_FA[BT_NSET], bt_FB[BT_NSET], bt_Fout;
static dh_vec3_q bt_ptq[BT_NSET], bt_vq;
static float bt_ang_f[BT_NANG];
static dh_q16 bt_ang_q[BT_NANG];
static float bt_s, bt_c;
static dh_q30 bt_sq, bt_cq;
static dh_q16 bt_aq;
static float bt_qf[BT_NSET][6];
static int32_t bt_qq[BT_NSET][6];
static dh_robot bt_puma_mm;
/* the float robot, whose storage bt_queue_q's queue takes once the float
 * benchmarks of a move are done (bt_track: nothing reads the float robot
 * after them until the next move builds it again) */
static union {
    dh_robot r;
    dh_queue_q qu;
} bt_puma_m_u;
#define bt_puma_m (bt_puma_m_u.r)
static float bt_J[36];
static uint32_t bt_status;   /* OR of every status returned in the timed loops */
static dh_vec4_f32 bt_p4[BT_NSET], bt_v4out;   /* homogeneous points, w in [0.5, 2) */
static dh_plane_f32 bt_pl[BT_NSET], bt_plout;
static float bt_fl[BT_NSET];                   /* focal lengths in [0.5, 2) */
static int bt_axis[BT_NSET];                   /* 0, 1, 2, 0, ... */

static uint32_t bt_rng = 0x2545F491u;

static uint32_t bt_rand(void)
{
    /* xorshift32 (Marsaglia 2003) */
    bt_rng ^= bt_rng << 13;
    bt_rng ^= bt_rng >> 17;
    bt_rng ^= bt_rng << 5;
    return bt_rng;
}

/* uniform in [lo, hi) */
static float bt_uniform(float lo, float hi)
{
    return lo + (hi - lo) * ((float)(bt_rand() >> 8) * (1.0f / 16777216.0f));
}

static dh_q16 bt_to_q16(float deg)
{
    float x = deg * 65536.0f;
    return (dh_q16)(x < 0.0f ? x - 0.5f : x + 0.5f);
}

/* Puma 560, standard DH, metres: examples/robots/puma560.dh (through
 * tools/gen_robots.py at build time). Columns: a, d, alpha (deg), joint
 * limits (deg). */
#define BT_JOINT(type, a, d, alpha, theta, qmin, qmax) \
    { (float)(a), (float)(d), (float)(alpha), (float)(qmin), (float)(qmax) },
static const float bt_puma_tab[6][5] = { DHR_PUMA560_JOINTS(BT_JOINT) };
/* UR5 (CB3), standard DH, metres: examples/robots/ur5.dh */
static const float bt_ur5_tab[6][5] = { DHR_UR5_JOINTS(BT_JOINT) };

static uint32_t bt_robot_of(dh_robot *r, const float (*tab)[5], float scale)
{
    uint32_t st;
    uint32_t j;
    st = (uint32_t)dh_robot_init(r, DH_CONV_STANDARD);
    for (j = 0; j < 6u; j++) {
        st |= (uint32_t)dh_robot_add_joint_f32(r, DH_JOINT_REVOLUTE, 0.0f, tab[j][1] * scale, tab[j][0] * scale,
                                               tab[j][2]);
        st |= (uint32_t)dh_robot_set_limits_f32(r, j, tab[j][3], tab[j][4]);
    }
    return st;
}

static uint32_t bt_robot(dh_robot *r, float scale)
{
    return bt_robot_of(r, bt_puma_tab, scale);
}

/* Random rigid transform: axis uniform in the cube (not tiny), angle in
 * +-180 deg, translation in +-reach. */
static uint32_t bt_rigid(dh_mat4_f32 *T, float reach)
{
    float kx, ky, kz;
    uint32_t st;
    do {
        kx = bt_uniform(-1.0f, 1.0f);
        ky = bt_uniform(-1.0f, 1.0f);
        kz = bt_uniform(-1.0f, 1.0f);
    } while (kx * kx + ky * ky + kz * kz < 0.01f);
    st = (uint32_t)dh_mat4_rot_axis_f32(kx, ky, kz, bt_uniform(-180.0f, 180.0f), T);
    DH_M4(T, 0, 3) = bt_uniform(-reach, reach);
    DH_M4(T, 1, 3) = bt_uniform(-reach, reach);
    DH_M4(T, 2, 3) = bt_uniform(-reach, reach);
    return st;
}

static BT_NOINLINE uint32_t bt_inputs(void)
{
    uint32_t st = 0u, k, j;
    dh_mat4_f32 T;
    for (k = 0; k < BT_NANG; k++) {
        bt_ang_f[k] = bt_uniform(-720.0f, 720.0f);
        bt_ang_q[k] = bt_to_q16(bt_uniform(-720.0f, 720.0f));
    }
    for (k = 0; k < BT_NSET; k++) {
        st |= bt_rigid(&bt_A[k], 1.0f);
        st |= bt_rigid(&bt_B[k], 1.0f);
        bt_pts[k].x = bt_uniform(-1.0f, 1.0f);
        bt_pts[k].y = bt_uniform(-1.0f, 1.0f);
        bt_pts[k].z = bt_uniform(-1.0f, 1.0f);
        /* fixed frames in mm (positions up to 1000 mm) */
        st |= bt_rigid(&T, 1000.0f);
        st |= (uint32_t)dh_frame_from_mat4_q(&T, &bt_FA[k]);
        st |= bt_rigid(&T, 1000.0f);
        st |= (uint32_t)dh_frame_from_mat4_q(&T, &bt_FB[k]);
        bt_ptq[k].x = (dh_qpos)bt_to_q16(bt_uniform(-1000.0f, 1000.0f));
        bt_ptq[k].y = (dh_qpos)bt_to_q16(bt_uniform(-1000.0f, 1000.0f));
        bt_ptq[k].z = (dh_qpos)bt_to_q16(bt_uniform(-1000.0f, 1000.0f));
        for (j = 0; j < 6u; j++) {
            float q = bt_uniform(bt_puma_tab[j][3], bt_puma_tab[j][4]);
            bt_qf[k][j] = q;
            bt_qq[k][j] = bt_to_q16(q);
        }
    }
    for (k = 0; k < BT_NSET; k++) {
        bt_M[k] = bt_A[k];
    }
    st |= bt_robot(&bt_puma_m, 1.0f);
    st |= bt_robot(&bt_puma_mm, 1000.0f);
    /* inputs of the later rows from a generator of their own, so that the
     * inputs above and the IK targets drawn afterwards stay the sequence
     * they have always been (soft-float costs depend on the data) */
    {
        const uint32_t saved = bt_rng;
        bt_rng = 0x9E3779B9u;
        for (k = 0; k < BT_NSET; k++) {
            bt_p4[k].x = bt_uniform(-1.0f, 1.0f);
            bt_p4[k].y = bt_uniform(-1.0f, 1.0f);
            bt_p4[k].z = bt_uniform(-1.0f, 1.0f);
            bt_p4[k].w = bt_uniform(0.5f, 2.0f);
            bt_pl[k].a = bt_uniform(-1.0f, 1.0f);
            bt_pl[k].b = bt_uniform(-1.0f, 1.0f);
            bt_pl[k].c = bt_uniform(-1.0f, 1.0f);
            bt_pl[k].d = bt_uniform(-1.0f, 1.0f);
            bt_fl[k] = bt_uniform(0.5f, 2.0f);
            bt_axis[k] = (int)(k % 3u);
        }
        bt_rng = saved;
    }
    return st;
}

/* ---- operations -----------------------------------------------------------
 *
 * Every dhmath operation has two wrappers built from one body macro: op_X
 * calls the library function, nul_X calls a null twin with the same
 * prototype that returns at once (noipa: the compiler may not look inside
 * it, so the call and the use of its result stay). Both wrappers execute the
 * same index arithmetic, argument set-up, call and status store, so
 *     (ticks(op_X) - ticks(nul_X)) / n
 * is the function's own instructions minus those of the null twin's body
 * (`bx lr`, or `movs r0, #0; bx lr`), which report.py counts in the
 * disassembly and adds back. ticks(op_X) - ticks(op_empty) is the whole
 * call as the benchmark makes it (used for the comparison with the inline
 * cglm code).
 */

static BT_NOINLINE void op_empty(uint32_t i)
{
    (void)i;
}

/* null twins */
static BT_NOIPA dh_status z_sincos_f32(float deg, float *s, float *c)
{
    (void)deg; (void)s; (void)c;
    return DH_OK;
}
static BT_NOIPA void z_sincos_q(dh_q16 deg, dh_q30 *s, dh_q30 *c)
{
    (void)deg; (void)s; (void)c;
}
static BT_NOIPA dh_status z_atan2_q(int32_t y, int32_t x, dh_q16 *deg)
{
    (void)y; (void)x; (void)deg;
    return DH_OK;
}
static BT_NOIPA void z_mat_mul(const dh_mat4_f32 *A, const dh_mat4_f32 *B, dh_mat4_f32 *out)
{
    (void)out; (void)A; (void)B;
}
static BT_NOIPA void z_mat_inv_rigid(const dh_mat4_f32 *T, dh_mat4_f32 *out)
{
    (void)out; (void)T;
}
static BT_NOIPA dh_status z_mat_inv(const dh_mat4_f32 *T, dh_mat4_f32 *out)
{
    (void)out; (void)T;
    return DH_OK;
}
static BT_NOIPA void z_mat_point(const dh_mat4_f32 *T, const dh_vec3_f32 *u, dh_vec3_f32 *v)
{
    (void)T; (void)u; (void)v;
}
static BT_NOIPA dh_status z_mat_rot1(float deg, dh_mat4_f32 *T)
{
    (void)T; (void)deg;
    return DH_OK;
}
static BT_NOIPA dh_status z_mat_rot_axis(float kx, float ky, float kz, float deg, dh_mat4_f32 *T)
{
    (void)T; (void)kx; (void)ky; (void)kz; (void)deg;
    return DH_OK;
}
static BT_NOIPA dh_status z_mat_persp(int axis, float f, dh_mat4_f32 *T)
{
    (void)T; (void)axis; (void)f;
    return DH_OK;
}
static BT_NOIPA void z_mat_vec4(const dh_mat4_f32 *T, const dh_vec4_f32 *u, dh_vec4_f32 *v)
{
    (void)T; (void)u; (void)v;
}
static BT_NOIPA dh_status z_mat_point_h(const dh_mat4_f32 *T, const dh_vec4_f32 *u, dh_vec3_f32 *v)
{
    (void)T; (void)u; (void)v;
    return DH_OK;
}
static BT_NOIPA void z_plane_mul(const dh_plane_f32 *P, const dh_mat4_f32 *Tinv, dh_plane_f32 *Q)
{
    (void)P; (void)Tinv; (void)Q;
}
static BT_NOIPA dh_status z_frame_mul(const dh_frame_q *A, const dh_frame_q *B, dh_frame_q *out)
{
    (void)out; (void)A; (void)B;
    return DH_OK;
}
static BT_NOIPA dh_status z_frame_inv(const dh_frame_q *F, dh_frame_q *out)
{
    (void)out; (void)F;
    return DH_OK;
}
static BT_NOIPA dh_status z_frame_point(const dh_frame_q *F, const dh_vec3_q *u, dh_vec3_q *v)
{
    (void)F; (void)u; (void)v;
    return DH_OK;
}
static BT_NOIPA dh_status z_fk_f32(const dh_robot *r, const float *q, dh_mat4_f32 *T)
{
    (void)r; (void)q; (void)T;
    return DH_OK;
}
static BT_NOIPA dh_status z_fk_q(const dh_robot *r, const int32_t *q, dh_frame_q *T)
{
    (void)r; (void)q; (void)T;
    return DH_OK;
}
static BT_NOIPA dh_status z_jacobian(const dh_robot *r, const float *q, float *J, dh_mat4_f32 *T)
{
    (void)r; (void)q; (void)J; (void)T;
    return DH_OK;
}

/* wrapper bodies, F = the function to call */
#define B_sincos_f32(F) bt_status |= (uint32_t)F(bt_ang_f[i & (BT_NANG - 1u)], &bt_s, &bt_c)
#define B_sincos_q(F) F(bt_ang_q[i & (BT_NANG - 1u)], &bt_sq, &bt_cq)
#define B_atan2_q(F) bt_status |= (uint32_t)F(bt_ptq[BT_IA(i)].y, bt_ptq[BT_IA(i)].x, &bt_aq)
#define B_mul_affine(F) F(&bt_A[BT_IA(i)], &bt_B[BT_IB(i)], &bt_out)
#define B_mul(F) F(&bt_A[BT_IA(i)], &bt_B[BT_IB(i)], &bt_out)
#define B_inv_rigid(F) F(&bt_A[BT_IA(i)], &bt_out)
#define B_inv_rigid_ip(F) F(&bt_M[BT_IA(i)], &bt_M[BT_IA(i)])
#define B_inv(F) bt_status |= (uint32_t)F(&bt_A[BT_IA(i)], &bt_out)
#define B_apply_point(F) F(&bt_A[BT_IA(i)], &bt_pts[BT_IB(i)], &bt_vout)
#define B_rotx(F) bt_status |= (uint32_t)F(bt_ang_f[i & (BT_NANG - 1u)], &bt_out)
#define B_rot_axis(F)                                                                      \
    bt_status |= (uint32_t)F(bt_pts[BT_IA(i)].x, bt_pts[BT_IA(i)].y, bt_pts[BT_IA(i)].z, \
                             bt_ang_f[i & (BT_NANG - 1u)], &bt_out)
#define B_persp(F) bt_status |= (uint32_t)F(bt_axis[BT_IB(i)], bt_fl[BT_IA(i)], &bt_out)
#define B_apply_dir(F) F(&bt_A[BT_IA(i)], &bt_pts[BT_IB(i)], &bt_vout)
#define B_apply_vec4(F) F(&bt_A[BT_IA(i)], &bt_p4[BT_IB(i)], &bt_v4out)
#define B_apply_point_h(F) bt_status |= (uint32_t)F(&bt_A[BT_IA(i)], &bt_p4[BT_IB(i)], &bt_vout)
#define B_plane_mul(F) F(&bt_pl[BT_IB(i)], &bt_A[BT_IA(i)], &bt_plout)
#define B_frame_mul(F) bt_status |= (uint32_t)F(&bt_FA[BT_IA(i)], &bt_FB[BT_IB(i)], &bt_Fout)
#define B_frame_inv(F) bt_status |= (uint32_t)F(&bt_FA[BT_IA(i)], &bt_Fout)
#define B_frame_point(F) bt_status |= (uint32_t)F(&bt_FA[BT_IA(i)], &bt_ptq[BT_IB(i)], &bt_vq)
#define B_fk_f32(F) bt_status |= (uint32_t)F(&bt_puma_m, bt_qf[BT_IA(i)], &bt_out)
#define B_fk_q(F) bt_status |= (uint32_t)F(&bt_puma_mm, bt_qq[BT_IA(i)], &bt_Fout)
#define B_jacobian(F) bt_status |= (uint32_t)F(&bt_puma_m, bt_qf[BT_IA(i)], bt_J, &bt_out)

#define BT_PAIR(tag, real, null)                                  \
    static BT_NOIPA void op_##tag(uint32_t i) { B_##tag(real); }  \
    static BT_NOIPA void nul_##tag(uint32_t i) { B_##tag(null); }

BT_PAIR(sincos_f32, dh_sincos_f32, z_sincos_f32)
BT_PAIR(sincos_q, dh_sincos_q, z_sincos_q)
BT_PAIR(atan2_q, dh_atan2_q, z_atan2_q)
BT_PAIR(mul_affine, dh_mat4_mul_affine_f32, z_mat_mul)
BT_PAIR(mul, dh_mat4_mul_f32, z_mat_mul)
BT_PAIR(inv_rigid, dh_mat4_inv_rigid_f32, z_mat_inv_rigid)
BT_PAIR(inv_rigid_ip, dh_mat4_inv_rigid_f32, z_mat_inv_rigid)
BT_PAIR(inv, dh_mat4_inv_f32, z_mat_inv)
BT_PAIR(apply_point, dh_mat4_apply_point_f32, z_mat_point)
BT_PAIR(rotx, dh_mat4_rotx_f32, z_mat_rot1)
BT_PAIR(rot_axis, dh_mat4_rot_axis_f32, z_mat_rot_axis)
BT_PAIR(persp, dh_mat4_persp_f32, z_mat_persp)
BT_PAIR(apply_dir, dh_mat4_apply_dir_f32, z_mat_point)
BT_PAIR(apply_vec4, dh_mat4_apply_vec4_f32, z_mat_vec4)
BT_PAIR(apply_point_h, dh_mat4_apply_point_h_f32, z_mat_point_h)
BT_PAIR(plane_mul, dh_plane_mul_f32, z_plane_mul)
BT_PAIR(frame_mul, dh_frame_mul_q, z_frame_mul)
BT_PAIR(frame_inv, dh_frame_inv_q, z_frame_inv)
BT_PAIR(frame_point, dh_frame_apply_point_q, z_frame_point)
BT_PAIR(fk_f32, dh_fk_f32, z_fk_f32)
BT_PAIR(fk_q, dh_fk_q, z_fk_q)
BT_PAIR(jacobian, dh_jacobian_f32, z_jacobian)

static BT_NOINLINE void op_newlib_sincos(uint32_t i)
{
    float r = bt_ang_f[i & (BT_NANG - 1u)] * BT_DEG2RAD;
    bt_s = sinf(r);
    bt_c = cosf(r);
}

#define BT_OPD(name, tag, zname, n) { "dhmath", name, op_##tag, nul_##tag, zname " nul_" #tag, n }

static const bt_op bt_ops_dh[] = {
    BT_OPD("dh_sincos_f32", sincos_f32, "z_sincos_f32", 4096u),
    BT_OPD("dh_sincos_q", sincos_q, "z_sincos_q", 4096u),
    BT_OPD("dh_atan2_q (points in +-1000 Q16.16)", atan2_q, "z_atan2_q", 1024u),
    BT_OPD("dh_mat4_mul_affine_f32", mul_affine, "z_mat_mul", 1024u),
    BT_OPD("dh_mat4_mul_f32", mul, "z_mat_mul", 1024u),
    BT_OPD("dh_mat4_inv_rigid_f32", inv_rigid, "z_mat_inv_rigid", 1024u),
    BT_OPD("dh_mat4_inv_rigid_f32 (in place)", inv_rigid_ip, "z_mat_inv_rigid", 1024u),
    BT_OPD("dh_mat4_inv_f32", inv, "z_mat_inv", 1024u),
    BT_OPD("dh_mat4_apply_point_f32", apply_point, "z_mat_point", 1024u),
    BT_OPD("dh_mat4_rotx_f32", rotx, "z_mat_rot1", 1024u),
    BT_OPD("dh_mat4_rot_axis_f32", rot_axis, "z_mat_rot_axis", 1024u),
    BT_OPD("dh_mat4_persp_f32", persp, "z_mat_persp", 1024u),
    BT_OPD("dh_mat4_apply_dir_f32", apply_dir, "z_mat_point", 1024u),
    BT_OPD("dh_mat4_apply_vec4_f32", apply_vec4, "z_mat_vec4", 1024u),
    BT_OPD("dh_mat4_apply_point_h_f32", apply_point_h, "z_mat_point_h", 1024u),
    BT_OPD("dh_plane_mul_f32", plane_mul, "z_plane_mul", 1024u),
    BT_OPD("dh_frame_mul_q", frame_mul, "z_frame_mul", 1024u),
    BT_OPD("dh_frame_inv_q", frame_inv, "z_frame_inv", 1024u),
    BT_OPD("dh_frame_apply_point_q", frame_point, "z_frame_point", 1024u),
    BT_OPD("dh_fk_f32 (Puma 560, m)", fk_f32, "z_fk_f32", 512u),
    BT_OPD("dh_fk_q (Puma 560, mm)", fk_q, "z_fk_q", 512u),
    BT_OPD("dh_jacobian_f32 (Puma 560)", jacobian, "z_jacobian", 128u),
    { "newlib", "sinf + cosf (from degrees)", op_newlib_sincos, 0, "", 4096u },
};

/* ---- fixed Jacobian and rotation conversions, next to their float
 * counterparts (inputs derived from the sets above, no random draws) ---- */
static dh_mat3_f32 bt_R3[BT_NSET];
static dh_quat_f32 bt_qtin[BT_NSET], bt_qt;
static dh_quat_q bt_qqin[BT_NSET], bt_qtq;
static float bt_eul[3], bt_deg;
static dh_q16 bt_eulq[3], bt_degq;
static int32_t bt_Jq[36];
static dh_vec3_f32 bt_v3;
static dh_dir3_q bt_dq;
static dh_mat3_f32 bt_R3out;

static BT_NOINLINE uint32_t bt_inputs_kinq(void)
{
    uint32_t st = 0u, k, c, r;
    for (k = 0; k < BT_NSET; k++) {
        for (c = 0; c < 3u; c++)
            for (r = 0; r < 3u; r++) bt_R3[k].m[c][r] = bt_A[k].m[c][r];
        st |= (uint32_t)dh_mat3_to_quat_f32(&bt_R3[k], &bt_qtin[k]);
        st |= (uint32_t)dh_frame_to_quat_q(&bt_FA[k], &bt_qqin[k]);
    }
    return st;
}

static BT_NOIPA dh_status z_jacobian_q(const dh_robot *r, const int32_t *q, int32_t *J, dh_frame_q *T)
{
    (void)r; (void)q; (void)J; (void)T;
    return DH_OK;
}
static BT_NOIPA dh_status z_to_euler_f32(const dh_mat3_f32 *R, dh_euler_seq s, float *a)
{
    (void)R; (void)s; (void)a;
    return DH_OK;
}
static BT_NOIPA dh_status z_to_euler_q(const dh_frame_q *F, dh_euler_seq s, dh_q16 *a)
{
    (void)F; (void)s; (void)a;
    return DH_OK;
}
static BT_NOIPA dh_status z_from_euler_f32(dh_euler_seq s, const float *a, dh_mat3_f32 *R)
{
    (void)R; (void)s; (void)a;
    return DH_OK;
}
static BT_NOIPA dh_status z_from_euler_q(dh_euler_seq s, const dh_q16 *a, dh_frame_q *F)
{
    (void)F; (void)s; (void)a;
    return DH_OK;
}
static BT_NOIPA dh_status z_to_quat_f32(const dh_mat3_f32 *R, dh_quat_f32 *q)
{
    (void)R; (void)q;
    return DH_OK;
}
static BT_NOIPA dh_status z_to_quat_q(const dh_frame_q *F, dh_quat_q *q)
{
    (void)F; (void)q;
    return DH_OK;
}
static BT_NOIPA dh_status z_from_quat_f32(const dh_quat_f32 *q, dh_mat3_f32 *R)
{
    (void)R; (void)q;
    return DH_OK;
}
static BT_NOIPA dh_status z_from_quat_q(const dh_quat_q *q, dh_frame_q *F)
{
    (void)F; (void)q;
    return DH_OK;
}
static BT_NOIPA dh_status z_axis_f32(const dh_mat3_f32 *R, dh_vec3_f32 *k, float *d)
{
    (void)R; (void)k; (void)d;
    return DH_OK;
}
static BT_NOIPA dh_status z_axis_q(const dh_frame_q *F, dh_dir3_q *k, dh_q16 *d)
{
    (void)F; (void)k; (void)d;
    return DH_OK;
}
static BT_NOIPA dh_status z_roterr_f32(const dh_mat3_f32 *A, const dh_mat3_f32 *B, dh_vec3_f32 *w)
{
    (void)A; (void)B; (void)w;
    return DH_OK;
}
static BT_NOIPA dh_status z_roterr_q(const dh_frame_q *A, const dh_frame_q *B, dh_dir3_q *w)
{
    (void)A; (void)B; (void)w;
    return DH_OK;
}

#define B_jacobian_q(F) bt_status |= (uint32_t)F(&bt_puma_mm, bt_qq[BT_IA(i)], bt_Jq, &bt_Fout)
#define B_to_euler_f32(F) bt_status |= (uint32_t)F(&bt_R3[BT_IA(i)], DH_EULER_ZYX, bt_eul)
#define B_to_euler_q(F) bt_status |= (uint32_t)F(&bt_FA[BT_IA(i)], DH_EULER_ZYX, bt_eulq)
#define B_from_euler_f32(F) bt_status |= (uint32_t)F(DH_EULER_ZYX, &bt_ang_f[i & (BT_NANG - 4u)], &bt_R3out)
#define B_from_euler_q(F) bt_status |= (uint32_t)F(DH_EULER_ZYX, &bt_ang_q[i & (BT_NANG - 4u)], &bt_Fout)
#define B_to_quat_f32(F) bt_status |= (uint32_t)F(&bt_R3[BT_IA(i)], &bt_qt)
#define B_to_quat_q(F) bt_status |= (uint32_t)F(&bt_FA[BT_IA(i)], &bt_qtq)
#define B_from_quat_f32(F) bt_status |= (uint32_t)F(&bt_qtin[BT_IA(i)], &bt_R3out)
#define B_from_quat_q(F) bt_status |= (uint32_t)F(&bt_qqin[BT_IA(i)], &bt_Fout)
#define B_axis_f32(F) bt_status |= (uint32_t)F(&bt_R3[BT_IA(i)], &bt_v3, &bt_deg)
#define B_axis_q(F) bt_status |= (uint32_t)F(&bt_FA[BT_IA(i)], &bt_dq, &bt_degq)
#define B_roterr_f32(F) bt_status |= (uint32_t)F(&bt_R3[BT_IA(i)], &bt_R3[BT_IB(i)], &bt_v3)
#define B_roterr_q(F) bt_status |= (uint32_t)F(&bt_FA[BT_IA(i)], &bt_FB[BT_IB(i)], &bt_dq)

BT_PAIR(jacobian_q, dh_jacobian_q, z_jacobian_q)
BT_PAIR(to_euler_f32, dh_mat3_to_euler_f32, z_to_euler_f32)
BT_PAIR(to_euler_q, dh_frame_to_euler_q, z_to_euler_q)
BT_PAIR(from_euler_f32, dh_euler_to_mat3_f32, z_from_euler_f32)
BT_PAIR(from_euler_q, dh_euler_to_frame_q, z_from_euler_q)
BT_PAIR(to_quat_f32, dh_mat3_to_quat_f32, z_to_quat_f32)
BT_PAIR(to_quat_q, dh_frame_to_quat_q, z_to_quat_q)
BT_PAIR(from_quat_f32, dh_quat_to_mat3_f32, z_from_quat_f32)
BT_PAIR(from_quat_q, dh_quat_to_frame_q, z_from_quat_q)
BT_PAIR(axis_f32, dh_mat3_to_axis_angle_f32, z_axis_f32)
BT_PAIR(axis_q, dh_frame_to_axis_angle_q, z_axis_q)
BT_PAIR(roterr_f32, dh_rot_error_f32, z_roterr_f32)
BT_PAIR(roterr_q, dh_rot_error_q, z_roterr_q)

static const bt_op bt_ops_kinq[] = {
    BT_OPD("dh_jacobian_q (Puma 560, mm)", jacobian_q, "z_jacobian_q", 128u),
    BT_OPD("dh_mat3_to_euler_f32 (ZYX)", to_euler_f32, "z_to_euler_f32", 512u),
    BT_OPD("dh_frame_to_euler_q (ZYX)", to_euler_q, "z_to_euler_q", 512u),
    BT_OPD("dh_euler_to_mat3_f32 (ZYX)", from_euler_f32, "z_from_euler_f32", 512u),
    BT_OPD("dh_euler_to_frame_q (ZYX)", from_euler_q, "z_from_euler_q", 512u),
    BT_OPD("dh_mat3_to_quat_f32", to_quat_f32, "z_to_quat_f32", 512u),
    BT_OPD("dh_frame_to_quat_q", to_quat_q, "z_to_quat_q", 512u),
    BT_OPD("dh_quat_to_mat3_f32", from_quat_f32, "z_from_quat_f32", 512u),
    BT_OPD("dh_quat_to_frame_q", from_quat_q, "z_from_quat_q", 512u),
    BT_OPD("dh_mat3_to_axis_angle_f32", axis_f32, "z_axis_f32", 512u),
    BT_OPD("dh_frame_to_axis_angle_q", axis_q, "z_axis_q", 512u),
    BT_OPD("dh_rot_error_f32", roterr_f32, "z_roterr_f32", 512u),
    BT_OPD("dh_rot_error_q", roterr_q, "z_roterr_q", 512u),
};

static void bt_measure(const bt_op *op)
{
    uint64_t base, t, tz = 0u;
    uint32_t warm = op->n < 16u ? op->n : 16u;
    (void)bt_run(op->fn, warm);     /* caches / branch predictors on hardware */
    base = bt_run(op_empty, op->n);
    t = bt_run(op->fn, op->n);
    if (op->null_fn != 0) {
        tz = bt_run(op->null_fn, op->n);
    }
    printf("BT op|%s|%s|%lu|%llu|%llu|%llu|%s\n", op->group, op->name, (unsigned long)op->n,
           (unsigned long long)t, (unsigned long long)base, (unsigned long long)tz,
           op->null_sym);
}

/* ---- inverse kinematics: one solve at a time ------------------------------ */

#define BT_NIK 16u

#define BT_NIKC (BT_NSET == 8u ? 4u : BT_NSET)
#define BT_NDLS 4u

#if defined(__ARM_FP) || !defined(__arm__)
#define BT_IKC_FLOAT 1
#else
#define BT_IKC_FLOAT 0
#endif

/* The numerical IK's work array and the closed-form IK's models, targets
 * and solutions share memory (used one after the other), and so does
 * main's list of cglm operations (measured before bt_ik): the Cortex-M0's
 * 16 KiB hold them all this way. */
static union {
    bt_op cglm_ops[12];
    float ik_work[DH_IK_WORK_FLOATS(6u)];
    struct {
        dh_ikc_model_q mq;
        dh_frame_q Tq[BT_NIKC];
        dh_ikc_sol_q solq[DH_IKC_MAX_SOL];
#if BT_IKC_FLOAT
        dh_ikc_model_f32 mf;
        dh_mat4_f32 Tf[BT_NIKC];
        dh_ikc_sol_f32 solf[DH_IKC_MAX_SOL];
#endif
    } c;
    struct {   /* damped least-squares steps (bt_dls) */
        float J[BT_NDLS][36];
        float e[BT_NDLS][6];
        int32_t Jq[BT_NDLS][36];
        int32_t eq[BT_NDLS][6];
        dh_dls_work_q w;
    } d;
    int32_t ikq_work[DH_IK_WORK_Q(6u)];   /* bt_ik_q */
    struct {   /* trackers (bt_track; their robots in bt_puma_m / bt_puma_mm) */
        dh_ikc_model_q mq;
        dh_track_q tq;
        union {   /* bt_track_q's, then bt_period_q's */
            struct {
                dh_ikc_sol_q solq[DH_IKC_MAX_SOL];
                int32_t Jq[36];
                dh_dls_work_q w;
            } k;
            dh_move_q mvq;   /* its path built in place: mvq.path */
            struct {               /* bt_blend_q's two lines and their scalings */
                dh_path_q lines[2];
                dh_blend_seg_q seg[2];
            } b;
            dh_queue_item_q qit[2];   /* bt_queue_q's items (its queue in bt_puma_m_u) */
        } u;
#if BT_IKC_FLOAT
        dh_ikc_model_f32 mf;
        dh_track_f32 tf;
        dh_ikc_sol_f32 solf[DH_IKC_MAX_SOL];
        float J[36];
        dh_move_f32 mv;
        dh_path_f32 path;
        dh_queue_f32 qu;              /* bt_queue_f32's queue and items */
        dh_queue_item_f32 qit[2];
#endif
    } t;
#if BT_IKC_FLOAT
    struct {   /* closed-form IK against opw_kinematics (bt_opw) */
        dh_robot rf, rq;
        dh_ikc_model_f32 mf;
        dh_ikc_model_q mq;
        dh_mat4_f32 Tf[BT_NOPW];
        dh_frame_q Tq[BT_NOPW];
        dh_ikc_sol_f32 solf[DH_IKC_MAX_SOL];
        dh_ikc_sol_q solq[DH_IKC_MAX_SOL];
        float qo[8][6];
    } o;
#endif
} bt_mem;
#define bt_ik_work bt_mem.ik_work

static BT_NOINLINE void bt_ik(void)
{
    dh_ik_params_f32 p;
    dh_ik_result_f32 res;
    float qt[6], q0[6], q[6];
    dh_mat4_f32 target;
    uint64_t t0, t1, tnull;
    uint32_t k, j;
    dh_ik_params_default_f32(&bt_puma_m, &p);
    p.tol_pos = 1e-6f;
    t0 = bt_now();
    t1 = bt_now();
    tnull = t1 - t0;
    for (k = 0; k < BT_NIK; k++) {
        dh_status st;
        for (j = 0; j < 6u; j++) {
            /* reachable target: FK of a configuration inside 80 % of the
             * limits; start 10..20 deg away on every joint */
            float lo = 0.8f * bt_puma_tab[j][3], hi = 0.8f * bt_puma_tab[j][4];
            float off = bt_uniform(10.0f, 20.0f);
            qt[j] = bt_uniform(lo, hi);
            q0[j] = qt[j] + ((bt_rand() & 1u) ? off : -off);
        }
        st = dh_fk_f32(&bt_puma_m, qt, &target);
        if (st != DH_OK) {
            bt_status |= (uint32_t)st;
            continue;
        }
        t0 = bt_now();
        st = dh_ik_f32(&bt_puma_m, &target, q0, &p, bt_ik_work, sizeof bt_mem.ik_work / sizeof bt_mem.ik_work[0],
                       q, &res);
        t1 = bt_now();
        printf("BT ik|%lu|%d|%lu|%llu|%llu|%lu\n", (unsigned long)k, (int)st,
               (unsigned long)res.iterations, (unsigned long long)(t1 - t0),
               (unsigned long long)tnull, (unsigned long)(res.err_pos * 1e9f));
    }
}

/* ---- fixed-point inverse kinematics: one solve at a time ------------------- */

#define BT_NIKQ 64u

/* As bt_ik on the Puma 560 in mm, all integer: target = dh_fk_q of a random
 * Q configuration within 80 % of the limits, start 10..20 deg away on every
 * joint, dh_ik_params_default_q with tolerances 0.9e-3 mm and 0.9e-5 rad (full pose).
 * The workspace shares bt_mem with the other sections (the micro:bit's RAM). */
static BT_NOINLINE void bt_ik_q(void)
{
    int32_t *const bt_ikq_work = bt_mem.ikq_work;
    dh_ik_params_q p;
    dh_ik_result_q res;
    int32_t qt[6], q0[6], q[6];
    dh_frame_q target;
    uint64_t t0, t1, tnull;
    uint32_t k, j;
    dh_ik_params_default_q(&bt_puma_mm, &p);
    p.tol_pos = DH_QPOS(0.9e-3);    /* 0.9 of 1e-3 mm, 1e-5 rad: room for dh_fk_q's error */
    p.tol_rot = DH_Q30(0.9e-5);
    t0 = bt_now();
    t1 = bt_now();
    tnull = t1 - t0;
    for (k = 0; k < BT_NIKQ; k++) {
        dh_status st;
        for (j = 0; j < 6u; j++) {
            float lo = 0.8f * bt_puma_tab[j][3], hi = 0.8f * bt_puma_tab[j][4];
            float off = bt_uniform(10.0f, 20.0f);
            float v = bt_uniform(lo, hi);
            qt[j] = bt_to_q16(v);
            q0[j] = bt_to_q16(v + ((bt_rand() & 1u) ? off : -off));
        }
        st = dh_fk_q(&bt_puma_mm, qt, &target);
        if (st != DH_OK) {
            bt_status |= (uint32_t)st;
            continue;
        }
        t0 = bt_now();
        st = dh_ik_q(&bt_puma_mm, &target, q0, &p, bt_ikq_work, sizeof bt_mem.ikq_work / sizeof bt_mem.ikq_work[0],
                     q, &res);
        t1 = bt_now();
        printf("BT ikq|%lu|%d|%lu|%llu|%llu|%ld\n", (unsigned long)k, (int)st, (unsigned long)res.iterations,
               (unsigned long long)(t1 - t0), (unsigned long long)tnull, (long)res.err_pos);
    }
}

/* ---- closed-form inverse kinematics: all solutions ------------------------- */


/* Targets: FK of random configurations within the limits (untimed). The
 * loop of BT_NIKC solves is timed as a whole; the same loop with the call
 * left out gives the loop's own count. */
static BT_NOINLINE void bt_ikc(void)
{
    dh_ikc_model_q *const mq = &bt_mem.c.mq;
    dh_frame_q *const Tq = bt_mem.c.Tq;
    dh_ikc_sol_q *const solq = bt_mem.c.solq;
#if BT_IKC_FLOAT
    dh_ikc_model_f32 *const mf = &bt_mem.c.mf;
    dh_mat4_f32 *const Tf = bt_mem.c.Tf;
    dh_ikc_sol_f32 *const solf = bt_mem.c.solf;
#endif
    uint32_t k, j, nsol, total, st = 0u;
    uint64_t t0, t1, tl;
    const uint32_t saved = bt_rng;
    bt_rng = 0x85EBCA6Bu;
    for (k = 0; k < BT_NIKC; k++) {
        float q[6];
        int32_t qq[6];
        for (j = 0; j < 6u; j++) {
            q[j] = bt_uniform(bt_puma_tab[j][3], bt_puma_tab[j][4]);
            qq[j] = bt_to_q16(q[j]);
        }
#if BT_IKC_FLOAT
        st |= (uint32_t)dh_fk_f32(&bt_puma_m, q, &Tf[k]);
#endif
        st |= (uint32_t)dh_fk_q(&bt_puma_mm, qq, &Tq[k]);
    }
    bt_rng = saved;
#if BT_IKC_FLOAT
    st |= (uint32_t)dh_ikc_analyse_f32(&bt_puma_m, mf);
#endif
    st |= (uint32_t)dh_ikc_analyse_q(&bt_puma_mm, mq);
    if (st != 0u) {
        printf("BT error|closed-form IK set-up returned status %lu\n", (unsigned long)st);
        bt_status |= st;
        return;
    }
    t0 = bt_now();
    for (k = 0; k < BT_NIKC; k++) {
        bt_sink = k;
    }
    t1 = bt_now();
    tl = t1 - t0;
#if BT_IKC_FLOAT
    total = 0u;
    t0 = bt_now();
    for (k = 0; k < BT_NIKC; k++) {
        st |= (uint32_t)dh_ikc_f32(mf, &Tf[k], NULL, 0u, solf, &nsol);
        total += nsol;
    }
    t1 = bt_now();
    printf("BT ikc|dh_ikc_f32 (Puma 560, m, all solutions)|%lu|%llu|%llu|%lu|%lu\n", (unsigned long)BT_NIKC,
           (unsigned long long)(t1 - t0), (unsigned long long)tl, (unsigned long)total, (unsigned long)st);
#endif
    total = 0u;
    t0 = bt_now();
    for (k = 0; k < BT_NIKC; k++) {
        st |= (uint32_t)dh_ikc_q(mq, &Tq[k], NULL, 0u, solq, &nsol);
        total += nsol;
    }
    t1 = bt_now();
    printf("BT ikc|dh_ikc_q (Puma 560, mm, all solutions)|%lu|%llu|%llu|%lu|%lu\n", (unsigned long)BT_NIKC,
           (unsigned long long)(t1 - t0), (unsigned long long)tl, (unsigned long)total, (unsigned long)st);
    bt_status |= st;
}

/* ---- closed-form inverse kinematics of a calibrated robot --------------------- */

#if BT_IKC_FLOAT
/* The UR5 (fam 0) or the Puma 560 (fam 1) exact (cal 0), and calibrated
 * (cal 1; within the calibration tolerance of ikc.h; the kind of
 * deviations a calibrated table holds): UR5 a2 +1.5 mm, d4 -1 mm, a5 1 mm,
 * twists 2 and 4 +0.4 and +0.3 deg, joint 3's offset +0.3 deg; Puma 560 a
 * wrist offset a4 0.4 mm, a5 -0.3 mm, d5 0.5 mm and the twists off by up to
 * 0.2 deg. */
static uint32_t bt_cal_robot(dh_robot *r, uint32_t fam, int cal)
{
    static const float dev[2][6][4] = {
        { { 0.0f, 0.0f, 0.0f, 0.0f }, { 0.0015f, 0.0f, 0.4f, 0.0f }, { 0.0f, 0.0f, 0.0f, 0.3f },
          { 0.0f, -0.001f, 0.3f, 0.0f }, { 0.001f, 0.0f, 0.0f, 0.0f }, { 0.0f, 0.0f, 0.0f, 0.0f } },
        { { 0.0f, 0.0f, 0.15f, 0.0f }, { 0.0f, 0.0f, -0.1f, 0.0f }, { 0.0f, 0.0f, -0.2f, 0.0f },
          { 0.0004f, 0.0f, 0.1f, 0.0f }, { -0.0003f, 0.0005f, 0.15f, 0.0f }, { 0.0f, 0.0f, 0.2f, 0.0f } }
    };
    const float(*tab)[5] = (fam == 0u) ? bt_ur5_tab : bt_puma_tab;
    const float k = cal ? 1.0f : 0.0f;
    uint32_t st, j;
    st = (uint32_t)dh_robot_init(r, DH_CONV_STANDARD);
    for (j = 0; j < 6u; j++) {
        const float *dv = dev[fam][j];
        st |= (uint32_t)dh_robot_add_joint_f32(r, DH_JOINT_REVOLUTE, k * dv[3], tab[j][1] + k * dv[1],
                                               tab[j][0] + k * dv[0], tab[j][2] + k * dv[2]);
        st |= (uint32_t)dh_robot_set_limits_f32(r, j, tab[j][3], tab[j][4]);
    }
    return st;
}

/* 1 when the Puma 560 configuration q (deg) is at least 1e-2 from the
 * singularities as test/ikc/test_ikc_calib_wrist.c draws its
 * configurations: s5^2, (u / L)^2 (u = a2 c2 + a3 c23 - d4 s23, the wrist
 * centre's distance across axis 1 from the shoulder's plane; L 1.706 m)
 * and, for the elbow, sin^2(theta3 - phi) (phi = -87.3 deg) at least 1e-1
 * (the wrist centre 1 cm from the elbow's boundary): the calibrated solve
 * finds every branch there (ikc.h). From q alone, so that the exact and
 * the calibrated robot get the same configurations. */
static int bt_puma_away(const float *q)
{
    float s5, c5, se, ce, s2, c2, s23, c23, u;
    (void)dh_sincos_f32(q[4], &s5, &c5);
    (void)dh_sincos_f32(q[2] + 87.3f, &se, &ce);
    (void)dh_sincos_f32(q[1], &s2, &c2);
    (void)dh_sincos_f32(q[1] + q[2], &s23, &c23);
    u = 0.4318f * c2 + 0.0203f * c23 - 0.4318f * s23;
    return s5 * s5 >= 1e-2f && se * se >= 1e-1f && u * u >= 1e-2f * 1.706f * 1.706f;
}

/* dh_ikc_f32 on the UR5 and the Puma 560, each exact and calibrated, the
 * targets FK of the same random configurations on each robot (untimed),
 * as bt_ikc; the Puma 560's redrawn until bt_puma_away. */
static BT_NOINLINE void bt_ikc_cal(void)
{
    static const char *const name[4] = { "UR5", "UR5 calibrated", "Puma 560", "Puma 560 calibrated" };
    dh_ikc_model_f32 *const mf = &bt_mem.c.mf;
    dh_mat4_f32 *const Tf = bt_mem.c.Tf;
    dh_ikc_sol_f32 *const solf = bt_mem.c.solf;
    dh_robot r;
    uint32_t k, j, nsol, total, st, cal;
    uint64_t t0, t1, tl;
    t0 = bt_now();
    for (k = 0; k < BT_NIKC; k++) {
        bt_sink = k;
    }
    t1 = bt_now();
    tl = t1 - t0;
    for (cal = 0; cal < 4u; cal++) {
        const uint32_t saved = bt_rng;
        const float(*tab)[5] = (cal < 2u) ? bt_ur5_tab : bt_puma_tab;
        st = bt_cal_robot(&r, cal >> 1, (int)(cal & 1u));
        bt_rng = 0x27D4EB2Fu;
        for (k = 0; k < BT_NIKC; k++) {
            float q[6];
            do {
                for (j = 0; j < 6u; j++) q[j] = bt_uniform(tab[j][3], tab[j][4]);
            } while (cal >= 2u && !bt_puma_away(q));
            st |= (uint32_t)dh_fk_f32(&r, q, &Tf[k]);
        }
        bt_rng = saved;
        st |= (uint32_t)dh_ikc_analyse_f32(&r, mf);
        if (st != 0u || mf->calibrated != (cal & 1u)) {
            printf("BT error|calibrated closed-form IK set-up returned status %lu\n", (unsigned long)st);
            bt_status |= 1u;
            return;
        }
        total = 0u;
        t0 = bt_now();
        for (k = 0; k < BT_NIKC; k++) {
            st |= (uint32_t)dh_ikc_f32(mf, &Tf[k], NULL, 0u, solf, &nsol);
            total += nsol;
        }
        t1 = bt_now();
        printf("BT ikc|dh_ikc_f32 (%s, m, all solutions)|%lu|%llu|%llu|%lu|%lu\n", name[cal], (unsigned long)BT_NIKC,
               (unsigned long long)(t1 - t0), (unsigned long long)tl, (unsigned long)total, (unsigned long)st);
        bt_status |= st;
    }
}
#endif

/* ---- closed-form inverse kinematics against opw_kinematics ------------------ */

#if !BENCH_HAVE_OPW
/* stand-ins: the firmware was built without opw_kinematics */
uint32_t bt_opw_setup(const dh_mat4_f32 *T, uint32_t n)
{
    (void)T;
    (void)n;
    return 0u;
}

void bt_opw_solve(uint32_t k)
{
    (void)k;
}

uint32_t bt_opw_solutions(float q_dh_deg[8][6])
{
    (void)q_dh_deg;
    return 0u;
}
#endif

#if BT_IKC_FLOAT
/* KUKA KR6 R700 sixx, standard DH, metres: the robot of opw_kinematics'
 * example makeKukaKR6_R700_sixx (include/opw_kinematics/
 * opw_parameters_examples.h: a1 0.025, a2 -0.035, b 0, c1 0.4, c2 0.315,
 * c3 0.365, c4 0.08, joint 2 offset -pi/2, joints 1, 4, 6 sign -1) as a DH
 * table with the same base and flange frames. Columns: a, d, alpha, theta
 * offset (deg). Limits +-170 deg on every joint are this benchmark's choice
 * (the targets' configurations are drawn within them); q_ref is the home
 * (0, -90, 90, 0, 0, 0) deg, as a controller would pass its last position. */
static const float bt_kr6_tab[6][4] = {
    { 0.025f, 0.4f, -90.0f, 0.0f }, { 0.315f, 0.0f, 0.0f, 0.0f },  { -0.035f, 0.0f, 90.0f, 90.0f },
    { 0.0f, 0.365f, -90.0f, 0.0f }, { 0.0f, 0.0f, 90.0f, 0.0f },   { 0.0f, 0.08f, 0.0f, 0.0f }
};
static const float bt_kr6_qref[6] = { 0.0f, -90.0f, 90.0f, 0.0f, 0.0f, 0.0f };
static const int32_t bt_kr6_qref_q[6] = { 0, -90 * 65536, 90 * 65536, 0, 0, 0 };

static uint32_t bt_kr6(dh_robot *r, float scale)
{
    uint32_t st, j;
    st = (uint32_t)dh_robot_init(r, DH_CONV_STANDARD);
    for (j = 0; j < 6u; j++) {
        st |= (uint32_t)dh_robot_add_joint_f32(r, DH_JOINT_REVOLUTE, bt_kr6_tab[j][3], bt_kr6_tab[j][1] * scale,
                                               bt_kr6_tab[j][0] * scale, bt_kr6_tab[j][2]);
        st |= (uint32_t)dh_robot_set_limits_f32(r, j, -170.0f, 170.0f);
    }
    return st;
}

static float bt_wrap180(float x)
{
    x = fmodf(x, 360.0f);
    if (x > 180.0f) {
        x -= 360.0f;
    }
    if (x <= -180.0f) {
        x += 360.0f;
    }
    return x;
}

/* Solution sets of the last opw solve and of dh_ikc_f32 (nsol solutions in
 * bt_mem.o.solf) for one target: opw's finite solutions wrapped to
 * (-180, 180] and kept within the limits must be as many as dhmath's, each
 * matched by one of dhmath's within 1e-3 deg on every joint. Adds to the
 * counts; worst: largest distance of an opw solution to its nearest. */
static void bt_opw_match(uint32_t nsol, uint32_t *kept_all, uint32_t *count_bad, uint32_t *unmatched, float *worst)
{
    uint32_t no = bt_opw_solutions(bt_mem.o.qo), s, t, j, kept = 0u;
    for (s = 0; s < no; s++) {
        float best = 1e30f;
        int in = 1;
        for (j = 0; j < 6u; j++) {
            bt_mem.o.qo[s][j] = bt_wrap180(bt_mem.o.qo[s][j]);
            in = in && fabsf(bt_mem.o.qo[s][j]) <= 170.0f;
        }
        if (!in) {
            continue;
        }
        kept++;
        for (t = 0; t < nsol; t++) {
            float d = 0.0f;
            for (j = 0; j < 6u; j++) {
                d = fmaxf(d, fabsf(bt_wrap180(bt_mem.o.qo[s][j] - bt_mem.o.solf[t].q[j])));
            }
            best = fminf(best, d);
        }
        if (best < 1e30f && best > *worst) {
            *worst = best;
        }
        if (!(best <= 1e-3f)) {
            *unmatched += 1u;
        }
    }
    *kept_all += kept;
    if (kept != nsol) {
        *count_bad += 1u;
    }
}

/* dh_ikc_f32 and dh_ikc_q (limits, q_ref) and opw_kinematics::inverse<float>
 * on the same KR6 targets (FK of random configurations within the limits,
 * untimed); each loop of BT_NOPW solves timed as a whole, minus the same
 * loop without the call. */
static BT_NOINLINE void bt_opw(void)
{
    uint32_t k, j, nsol, total, st = 0u, nopw, kept = 0u, count_bad = 0u, unmatched = 0u;
    uint64_t t0, t1, tl;
    float worst = 0.0f;
    const uint32_t saved = bt_rng;
    st |= bt_kr6(&bt_mem.o.rf, 1.0f);
    st |= bt_kr6(&bt_mem.o.rq, 1000.0f);
    st |= (uint32_t)dh_ikc_analyse_f32(&bt_mem.o.rf, &bt_mem.o.mf);
    st |= (uint32_t)dh_ikc_analyse_q(&bt_mem.o.rq, &bt_mem.o.mq);
    bt_rng = 0x68E31DA4u;
    for (k = 0; k < BT_NOPW; k++) {
        float q[6];
        int32_t qq[6];
        for (j = 0; j < 6u; j++) {
            q[j] = bt_uniform(-170.0f, 170.0f);
            qq[j] = bt_to_q16(q[j]);
        }
        st |= (uint32_t)dh_fk_f32(&bt_mem.o.rf, q, &bt_mem.o.Tf[k]);
        st |= (uint32_t)dh_fk_q(&bt_mem.o.rq, qq, &bt_mem.o.Tq[k]);
    }
    bt_rng = saved;
    if (st != 0u) {
        printf("BT error|KR6 R700 set-up returned status %lu\n", (unsigned long)st);
        bt_status |= st;
        return;
    }
    nopw = bt_opw_setup(bt_mem.o.Tf, BT_NOPW);
    t0 = bt_now();
    for (k = 0; k < BT_NOPW; k++) {
        bt_sink = k;
    }
    t1 = bt_now();
    tl = t1 - t0;
    total = 0u;
    t0 = bt_now();
    for (k = 0; k < BT_NOPW; k++) {
        st |= (uint32_t)dh_ikc_f32(&bt_mem.o.mf, &bt_mem.o.Tf[k], bt_kr6_qref, 0u, bt_mem.o.solf, &nsol);
        total += nsol;
    }
    t1 = bt_now();
    printf("BT opw|dh_ikc_f32 (KR6 R700, m, solutions within the limits, q_ref)|%lu|%llu|%llu|%lu|%lu\n",
           (unsigned long)BT_NOPW, (unsigned long long)(t1 - t0), (unsigned long long)tl, (unsigned long)total,
           (unsigned long)st);
    total = 0u;
    t0 = bt_now();
    for (k = 0; k < BT_NOPW; k++) {
        st |= (uint32_t)dh_ikc_q(&bt_mem.o.mq, &bt_mem.o.Tq[k], bt_kr6_qref_q, 0u, bt_mem.o.solq, &nsol);
        total += nsol;
    }
    t1 = bt_now();
    printf("BT opw|dh_ikc_q (KR6 R700, mm, solutions within the limits, q_ref)|%lu|%llu|%llu|%lu|%lu\n",
           (unsigned long)BT_NOPW, (unsigned long long)(t1 - t0), (unsigned long long)tl, (unsigned long)total,
           (unsigned long)st);
    bt_status |= st;
    if (nopw != BT_NOPW) {
        printf("BT opwpeer|absent\n");
        return;
    }
    t0 = bt_now();
    for (k = 0; k < BT_NOPW; k++) {
        bt_opw_solve(k);
    }
    t1 = bt_now();
    /* untimed: the solutions, and the check against dh_ikc_f32 */
    total = 0u;
    for (k = 0; k < BT_NOPW; k++) {
        st |= (uint32_t)dh_ikc_f32(&bt_mem.o.mf, &bt_mem.o.Tf[k], bt_kr6_qref, 0u, bt_mem.o.solf, &nsol);
        bt_opw_solve(k);
        total += bt_opw_solutions(bt_mem.o.qo);
        bt_opw_match(nsol, &kept, &count_bad, &unmatched, &worst);
    }
    printf("BT opw|opw_kinematics::inverse<float> (KR6 R700, m, 8 raw solutions, no limits)|%lu|%llu|%llu|%lu|%lu\n",
           (unsigned long)BT_NOPW, (unsigned long long)(t1 - t0), (unsigned long long)tl, (unsigned long)total,
           (unsigned long)st);
    printf("BT opwcheck|%lu|%lu|%lu|%lu|%lu\n", (unsigned long)BT_NOPW, (unsigned long)count_bad,
           (unsigned long)unmatched, (unsigned long)kept, (unsigned long)(worst * 1e6f + 0.5f));
    bt_status |= st;
}
#endif

/* ---- damped least-squares steps (6 joints) ------------------------------- */

/* Inputs: the Jacobians of the Puma 560 at BT_NDLS of the FK configurations
 * (metres / mm) and pose errors of up to 1 mm and 1e-3 rad per component,
 * what a tracker sees between two periods; damping the trackers' defaults
 * (float 0.02 L, L the robot's length sum; fixed 0.02 in J's units), step
 * bounds 180 deg/s x 1 ms. */
static float bt_dls_lam, bt_dls_max[6], bt_dls_dq[6];
static int32_t bt_dls_maxq[6], bt_dls_dqq[6];

static BT_NOINLINE uint32_t bt_inputs_dls(void)
{
    uint32_t st = 0u, k, j;
    dh_mat4_f32 T;
    const uint32_t saved = bt_rng;
    bt_rng = 0x27D4EB2Fu;
    for (k = 0; k < BT_NDLS; k++) {
        st |= (uint32_t)dh_jacobian_f32(&bt_puma_m, bt_qf[k], bt_mem.d.J[k], &T);
        st |= (uint32_t)dh_jacobian_q(&bt_puma_mm, bt_qq[k], bt_mem.d.Jq[k], &bt_Fout);
        for (j = 0; j < 6u; j++) {
            const float x = bt_uniform(-1e-3f, 1e-3f);   /* m or rad */
            bt_mem.d.e[k][j] = x;
            /* mm in dh_qpos, rad in Q3.29 */
            bt_mem.d.eq[k][j] = j < 3u ? bt_to_q16(x * 1000.0f) : (int32_t)(x * 536870912.0f);
        }
    }
    bt_rng = saved;
    bt_dls_lam = 0.0f;
    for (j = 0; j < 6u; j++) {
        bt_dls_lam += bt_puma_tab[j][0] + bt_puma_tab[j][1];
        bt_dls_max[j] = 0.18f;
        bt_dls_maxq[j] = 11796;   /* floor(180 x 2^16 x 1e-3) */
    }
    bt_dls_lam *= 0.02f;
    return st;
}

static BT_NOIPA dh_status z_dls_f32(const dh_robot *r, const float *J, const float e[6], float lambda,
                                   const float *dq_max, float *dq)
{
    (void)r; (void)J; (void)e; (void)lambda; (void)dq_max; (void)dq;
    return DH_OK;
}
static BT_NOIPA dh_status z_dls_q(const dh_robot *r, const int32_t *J, const int32_t e[6], int32_t lambda,
                                 const int32_t *dq_max, dh_dls_work_q *work, int32_t *dq)
{
    (void)r; (void)J; (void)e; (void)lambda; (void)dq_max; (void)work; (void)dq;
    return DH_OK;
}
#define B_dls_f32(F) \
    bt_status |= (uint32_t)F(&bt_puma_m, bt_mem.d.J[i & (BT_NDLS - 1u)], bt_mem.d.e[i & (BT_NDLS - 1u)], \
                             bt_dls_lam, bt_dls_max, bt_dls_dq)
#define B_dls_q(F)                                                                                          \
    bt_status |= (uint32_t)F(&bt_puma_mm, bt_mem.d.Jq[i & (BT_NDLS - 1u)], bt_mem.d.eq[i & (BT_NDLS - 1u)], \
                             DH_QPOS(0.02), bt_dls_maxq, &bt_mem.d.w, bt_dls_dqq)
BT_PAIR(dls_f32, dh_dls_step_f32, z_dls_f32)
BT_PAIR(dls_q, dh_dls_step_q, z_dls_q)

static const bt_op bt_ops_dls[] = {
    BT_OPD("dh_dls_step_f32 (Puma 560, m)", dls_f32, "z_dls_f32", 64u),
    BT_OPD("dh_dls_step_q (Puma 560, mm)", dls_q, "z_dls_q", 64u),
};

/* ---- tracking along a smooth move ------------------------------------------
 *
 * One tracker call per period of a move: the targets are the FK of a
 * minimum-jerk joint move (10 s^3 - 15 s^4 + 6 s^5) of BT_NTRK periods of
 * 1 ms, 12-20 deg per joint, peak speed below the 180 deg/s limit on every
 * joint (the UR5's published joint speed, set on both robots): consecutive
 * targets a tracker follows, not one target repeated. Each call is timed
 * on its own (the counter's own cost is measured over as many empty
 * intervals), and so are, per period, the closed-form solve of the same
 * target with the tracker's configuration as q_ref (what the tracker solves
 * inside) and the public Jacobian and singularity measures at the
 * tracker's output (what its report computes): each line gives the sum and
 * the largest single call. */
#define BT_NTRK 256u

typedef struct {
    const char *robot;
    const float (*tab)[5];
    float qa[6];    /* start of the move, deg */
    float dq[6];    /* displacement, deg */
} bt_move;

static const bt_move bt_moves[2] = {
    { "UR5", bt_ur5_tab, { 20.0f, -110.0f, 95.0f, -75.0f, 60.0f, 30.0f },
      { 15.0f, 18.0f, -20.0f, 12.0f, -15.0f, 20.0f } },
    { "Puma 560", bt_puma_tab, { 10.0f, -40.0f, 30.0f, 20.0f, 45.0f, -30.0f },
      { 15.0f, 18.0f, -20.0f, 12.0f, -15.0f, 20.0f } },
};

typedef struct {
    uint64_t sum, max;
} bt_acc;

static void bt_acc_add(bt_acc *a, uint64_t t0, uint64_t t1)
{
    const uint64_t d = t1 - t0;
    a->sum += d;
    if (d > a->max) {
        a->max = d;
    }
}

/* joint values of period k of the move */
static void bt_move_q(const bt_move *mv, uint32_t k, float *q)
{
    const float s = (float)k / (float)BT_NTRK;
    const float p = s * s * s * (10.0f + s * (-15.0f + 6.0f * s));
    uint32_t j;
    for (j = 0; j < 6u; j++) {
        q[j] = mv->qa[j] + p * mv->dq[j];
    }
}

/* the move's robot in r (lengths times scale) with the rate limit on every joint */
static uint32_t bt_move_robot(const bt_move *mv, dh_robot *r, float scale)
{
    uint32_t j, st = bt_robot_of(r, mv->tab, scale);
    for (j = 0; j < 6u; j++) {
        st |= (uint32_t)dh_robot_set_rates_f32(r, j, 180.0f, INFINITY);
    }
    return st;
}

/* BT track|name|calls|ticks|ticks of as many empty intervals|largest call|ok|lagging|unreachable|status */
static void bt_track_print(const char *op, const char *robot, const char *unit, const bt_acc *a,
                           const bt_acc *null, const uint32_t *states, uint32_t st)
{
    printf("BT track|%s (%s, %s)|%lu|%llu|%llu|%llu|%lu|%lu|%lu|%lu\n", op, robot, unit, (unsigned long)BT_NTRK,
           (unsigned long long)a->sum, (unsigned long long)null->sum, (unsigned long long)a->max,
           (unsigned long)states[0], (unsigned long)states[1], (unsigned long)states[2], (unsigned long)st);
}

/* twin: bt_track_f32 (the same timed loop on the fixed types and calls) */
static BT_NOINLINE void bt_track_q(const bt_move *mv, dh_robot *r, const bt_acc *null)
{
    dh_track_q *const t = &bt_mem.t.tq;
    dh_track_report_q rep;
    dh_frame_q T;
    bt_acc aik = { 0u, 0u }, atr = { 0u, 0u }, ams = { 0u, 0u };
    uint32_t states[3] = { 0u, 0u, 0u }, none[3] = { 0u, 0u, 0u };
    uint32_t st, k, j, ns;
    uint64_t t0, t1;
    float qf[6];
    int32_t q[6], w, sg;
    st = bt_move_robot(mv, r, 1000.0f);
    for (j = 0; j < 6u; j++) {
        q[j] = bt_to_q16(mv->qa[j]);
    }
    st |= (uint32_t)dh_ikc_analyse_q(r, &bt_mem.t.mq);
    st |= (uint32_t)dh_track_init_q(t, r, &bt_mem.t.mq, q, 1000u);
    for (k = 1; k <= BT_NTRK && st == 0u; k++) {
        bt_move_q(mv, k, qf);
        for (j = 0; j < 6u; j++) {
            q[j] = bt_to_q16(qf[j]);
        }
        st |= (uint32_t)dh_fk_q(r, q, &T);
        t0 = bt_now();
        st |= (uint32_t)dh_ikc_q(&bt_mem.t.mq, &T, t->q, DH_IKC_KEEP_OUT_OF_LIMITS, bt_mem.t.u.k.solq, &ns);
        t1 = bt_now();
        bt_acc_add(&aik, t0, t1);
        t0 = bt_now();
        st |= (uint32_t)dh_track_step_q(t, &T, q, &rep);
        t1 = bt_now();
        bt_acc_add(&atr, t0, t1);
        states[rep.state]++;
        t0 = bt_now();
        st |= (uint32_t)dh_jacobian_q(r, q, bt_mem.t.u.k.Jq, &T);
        st |= (uint32_t)dh_manipulability_q(bt_mem.t.u.k.Jq, 6u, &bt_mem.t.u.k.w, &w, &sg);
        t1 = bt_now();
        bt_acc_add(&ams, t0, t1);
    }
    bt_track_print("dh_track_step_q", mv->robot, "mm", &atr, null, states, st);
    bt_track_print("dh_ikc_q", mv->robot, "mm", &aik, null, none, st);
    bt_track_print("dh_jacobian_q + dh_manipulability_q", mv->robot, "mm", &ams, null, none, st);
}

#if BT_IKC_FLOAT
/* twin: bt_track_q */
static BT_NOINLINE void bt_track_f32(const bt_move *mv, dh_robot *r, const bt_acc *null)
{
    dh_track_f32 *const t = &bt_mem.t.tf;
    dh_track_report_f32 rep;
    dh_mat4_f32 T;
    bt_acc aik = { 0u, 0u }, atr = { 0u, 0u }, ams = { 0u, 0u };
    uint32_t states[3] = { 0u, 0u, 0u }, none[3] = { 0u, 0u, 0u };
    uint32_t st, k, ns;
    uint64_t t0, t1;
    float q[6], w, sg;
    st = bt_move_robot(mv, r, 1.0f);
    st |= (uint32_t)dh_ikc_analyse_f32(r, &bt_mem.t.mf);
    st |= (uint32_t)dh_track_init_f32(t, r, &bt_mem.t.mf, mv->qa, 1e-3f);
    for (k = 1; k <= BT_NTRK && st == 0u; k++) {
        bt_move_q(mv, k, q);
        st |= (uint32_t)dh_fk_f32(r, q, &T);
        t0 = bt_now();
        st |= (uint32_t)dh_ikc_f32(&bt_mem.t.mf, &T, t->q, DH_IKC_KEEP_OUT_OF_LIMITS, bt_mem.t.solf, &ns);
        t1 = bt_now();
        bt_acc_add(&aik, t0, t1);
        t0 = bt_now();
        st |= (uint32_t)dh_track_step_f32(t, &T, q, &rep);
        t1 = bt_now();
        bt_acc_add(&atr, t0, t1);
        states[rep.state]++;
        t0 = bt_now();
        st |= (uint32_t)dh_jacobian_f32(r, q, bt_mem.t.J, &T);
        st |= (uint32_t)dh_manipulability_f32(bt_mem.t.J, 6u, &w, &sg);
        t1 = bt_now();
        bt_acc_add(&ams, t0, t1);
    }
    bt_track_print("dh_track_step_f32", mv->robot, "m", &atr, null, states, st);
    bt_track_print("dh_ikc_f32", mv->robot, "m", &aik, null, none, st);
    bt_track_print("dh_jacobian_f32 + dh_manipulability_f32", mv->robot, "m", &ams, null, none, st);
}
#endif

#if BT_IKC_FLOAT
/* ---- one period of a Cartesian move ----------------------------------------
 *
 * A line move from the FK of the tracker move's start to the FK of its
 * middle (dq / 2), within 0.25 m/s, 2 m/s^2, 90 deg/s and 360 deg/s^2,
 * executed as a firmware does it: per period of 1 ms, dh_move_target_f32,
 * dh_track_step_f32 on that frame, dh_move_advance_f32 with the tracker's
 * state, timed together. Beside it, untimed for the period, the
 * closed-form solve of the same frame with the tracker's configuration as
 * q_ref (the limit's reference). jerk NULL: the trapezoid of
 * dh_move_path_f32 ("move period f32", "dh_ikc_f32 line"); else the
 * seven-phase move of dh_move_path_jerk_f32 within jerk ("jerk period
 * f32", "dh_ikc_f32 jerk line"). */
static BT_NOINLINE void bt_period_f32(const bt_move *mv, dh_robot *r, const dh_cart_jerk_f32 *jerk)
{
    dh_track_f32 *const t = &bt_mem.t.tf;
    dh_move_f32 *const m = &bt_mem.t.mv;
    const dh_cart_limits_f32 lim = { 0.25f, 2.0f, 90.0f, 360.0f };
    dh_track_report_f32 rep;
    dh_move_report_f32 mrep;
    dh_mat4_f32 A, B, T;
    bt_acc aik = { 0u, 0u }, aper = { 0u, 0u }, nul = { 0u, 0u };
    uint32_t states[3] = { 0u, 0u, 0u };
    uint32_t st, n = 0u, ns, j;
    uint64_t t0, t1;
    float q[6];
    st = bt_move_robot(mv, r, 1.0f);
    st |= (uint32_t)dh_ikc_analyse_f32(r, &bt_mem.t.mf);
    st |= (uint32_t)dh_fk_f32(r, mv->qa, &A);
    for (j = 0; j < 6u; j++) {
        q[j] = mv->qa[j] + 0.5f * mv->dq[j];
    }
    st |= (uint32_t)dh_fk_f32(r, q, &B);
    st |= (uint32_t)dh_path_line_f32(&bt_mem.t.path, &A, &B);
    st |= (uint32_t)dh_move_path_jerk_f32(m, &bt_mem.t.path, &lim, jerk);
    st |= (uint32_t)dh_track_init_f32(t, r, &bt_mem.t.mf, mv->qa, 1e-3f);
    mrep.done = 0;
    while (st == 0u && mrep.done == 0 && n < 4u * BT_NTRK) {
        st |= (uint32_t)dh_move_target_f32(m, &T);
        t0 = bt_now();
        st |= (uint32_t)dh_ikc_f32(&bt_mem.t.mf, &T, t->q, DH_IKC_KEEP_OUT_OF_LIMITS, bt_mem.t.solf, &ns);
        t1 = bt_now();
        bt_acc_add(&aik, t0, t1);
        t0 = bt_now();
        st |= (uint32_t)dh_move_target_f32(m, &T);
        st |= (uint32_t)dh_track_step_f32(t, &T, q, &rep);
        st |= (uint32_t)dh_move_advance_f32(m, 1e-3f, rep.state, &mrep);
        t1 = bt_now();
        bt_acc_add(&aper, t0, t1);
        states[rep.state]++;
        n++;
    }
    if (mrep.done == 0) {
        st |= 0x100u;   /* the move did not finish within 4 x BT_NTRK periods */
    }
    /* the counter's own cost over as many intervals as periods */
    for (j = 0; j < n; j++) {
        t0 = bt_now();
        t1 = bt_now();
        bt_acc_add(&nul, t0, t1);
    }
    printf("BT track|%s (%s, %s)|%lu|%llu|%llu|%llu|%lu|%lu|%lu|%lu\n",
           (jerk == NULL) ? "move period f32" : "jerk period f32", mv->robot, "m",
           (unsigned long)n, (unsigned long long)aper.sum, (unsigned long long)nul.sum,
           (unsigned long long)aper.max, (unsigned long)states[0], (unsigned long)states[1],
           (unsigned long)states[2], (unsigned long)st);
    printf("BT track|%s (%s, %s)|%lu|%llu|%llu|%llu|0|0|0|%lu\n",
           (jerk == NULL) ? "dh_ikc_f32 line" : "dh_ikc_f32 jerk line", mv->robot, "m",
           (unsigned long)n, (unsigned long long)aik.sum, (unsigned long long)nul.sum,
           (unsigned long long)aik.max, (unsigned long)st);
}
#endif

/* q = qa + f dq of mv (Q16.16 deg) and F = its FK on r; the status */
static uint32_t bt_fk_at_q(const bt_move *mv, const dh_robot *r, float f, dh_frame_q *F, int32_t *q)
{
    uint32_t j;
    for (j = 0; j < 6u; j++) {
        q[j] = bt_to_q16(mv->qa[j] + f * mv->dq[j]);
    }
    return (uint32_t)dh_fk_q(r, q, F);
}

/* the fixed robot of mv in mm and its closed-form model, the line's ends
 * A = FK(qa) and B = FK(qa + dq / 2), and q = qa (the tracker's start);
 * the statuses or'ed */
static uint32_t bt_line_q(const bt_move *mv, dh_robot *r, dh_frame_q *A, dh_frame_q *B, int32_t *q)
{
    uint32_t st;
    st = bt_move_robot(mv, r, 1000.0f);
    st |= (uint32_t)dh_ikc_analyse_q(r, &bt_mem.t.mq);
    st |= bt_fk_at_q(mv, r, 0.5f, B, q);
    st |= bt_fk_at_q(mv, r, 0.0f, A, q);
    return st;
}

/* twin: bt_period_f32 on the fixed types and calls, the robot in mm
 * (0.25 m/s and 2 m/s^2 as 250 mm/s and 2000 mm/s^2): the period timed
 * whole ("move period q", jerk-limited "jerk period q"), and within it the
 * tracker call on its own ("dh_track_step_q line", "dh_track_step_q jerk
 * line": the rest of the period is the move's target and advance) */
static BT_NOINLINE void bt_period_q(const bt_move *mv, dh_robot *r, const dh_cart_jerk_q *jerk)
{
    dh_track_q *const t = &bt_mem.t.tq;
    dh_move_q *const m = &bt_mem.t.u.mvq;
    const dh_cart_limits_q lim = { 250 << 16, 2000 << 16, 90 << 16, 360 << 16 };
    dh_track_report_q rep;
    dh_move_report_q mrep;
    dh_frame_q A, B, T;
    bt_acc atr = { 0u, 0u }, aper = { 0u, 0u }, nul = { 0u, 0u };
    uint32_t states[3] = { 0u, 0u, 0u };
    uint32_t st, n = 0u, j;
    uint64_t t0, t1, t2, t3;
    int32_t q[6];
    st = bt_line_q(mv, r, &A, &B, q);
    st |= (uint32_t)dh_path_line_q(&m->path, &A, &B);
    st |= (uint32_t)dh_move_path_jerk_q(m, &m->path, &lim, jerk);
    st |= (uint32_t)dh_track_init_q(t, r, &bt_mem.t.mq, q, 1000u);
    mrep.done = 0;
    while (st == 0u && mrep.done == 0 && n < 4u * BT_NTRK) {
        t0 = bt_now();
        st |= (uint32_t)dh_move_target_q(m, &T);
        t1 = bt_now();
        st |= (uint32_t)dh_track_step_q(t, &T, q, &rep);
        t2 = bt_now();
        st |= (uint32_t)dh_move_advance_q(m, 1000u, rep.state, &mrep);
        t3 = bt_now();
        bt_acc_add(&aper, t0, t3);
        bt_acc_add(&atr, t1, t2);
        states[rep.state]++;
        n++;
    }
    if (mrep.done == 0) {
        st |= 0x100u;   /* the move did not finish within 4 x BT_NTRK periods */
    }
    /* the counter's own cost over as many intervals as periods */
    for (j = 0; j < n; j++) {
        t0 = bt_now();
        t1 = bt_now();
        bt_acc_add(&nul, t0, t1);
    }
    printf("BT track|%s (%s, %s)|%lu|%llu|%llu|%llu|%lu|%lu|%lu|%lu\n",
           (jerk == NULL) ? "move period q" : "jerk period q", mv->robot, "mm",
           (unsigned long)n, (unsigned long long)aper.sum, (unsigned long long)nul.sum,
           (unsigned long long)aper.max, (unsigned long)states[0], (unsigned long)states[1],
           (unsigned long)states[2], (unsigned long)st);
    printf("BT track|%s (%s, %s)|%lu|%llu|%llu|%llu|0|0|0|%lu\n",
           (jerk == NULL) ? "dh_track_step_q line" : "dh_track_step_q jerk line", mv->robot, "mm",
           (unsigned long)n, (unsigned long long)atr.sum, (unsigned long long)nul.sum,
           (unsigned long long)atr.max, (unsigned long)st);
}

/* bt_period_q's move as two lines blended at its middle (FK(qa) to
 * FK(qa + dq / 2) to FK(qa + dq), radius 20 mm, the same limits): a
 * period is dh_blend_seq_eval_q at its time and dh_track_step_q on that
 * frame, timed whole ("blend period q"); the tracker starts on the first
 * frame and the clock advances by 1 ms every period */
static BT_NOINLINE void bt_blend_q(const bt_move *mv, dh_robot *r)
{
    dh_track_q *const t = &bt_mem.t.tq;
    const dh_cart_limits_q lim = { 250 << 16, 2000 << 16, 90 << 16, 360 << 16 };
    const dh_qpos radius[1] = { 20 << 16 };
    dh_track_report_q rep;
    dh_frame_q F, T;
    dh_blend_seq_q sq;
    bt_acc aper = { 0u, 0u }, nul = { 0u, 0u };
    uint32_t states[3] = { 0u, 0u, 0u };
    uint32_t st, n = 0u, j, clock = 0u;
    uint64_t t0, t1;
    int32_t q[6];
    /* the first line FK(qa) to FK(qa + dq / 2) (in T, F), the tracker at
     * qa; the second to FK(qa + dq) (in T) */
    st = bt_line_q(mv, r, &T, &F, q);
    st |= (uint32_t)dh_path_line_q(&bt_mem.t.u.b.lines[0], &T, &F);
    st |= (uint32_t)dh_track_init_q(t, r, &bt_mem.t.mq, q, 1000u);
    st |= bt_fk_at_q(mv, r, 1.0f, &T, q);
    st |= (uint32_t)dh_path_line_q(&bt_mem.t.u.b.lines[1], &F, &T);
    st |= (uint32_t)dh_blend_seq_plan_q(&sq, bt_mem.t.u.b.seg, bt_mem.t.u.b.lines, 2u, radius, &lim);
    while (st == 0u && n < 16u * BT_NTRK && (clock < sq.T || n == 0u)) {
        clock = (sq.T - clock > 1000u) ? clock + 1000u : sq.T;
        t0 = bt_now();
        st |= (uint32_t)dh_blend_seq_eval_q(&sq, clock, &T);
        st |= (uint32_t)dh_track_step_q(t, &T, q, &rep);
        t1 = bt_now();
        bt_acc_add(&aper, t0, t1);
        states[rep.state]++;
        n++;
    }
    if (clock < sq.T) {
        st |= 0x100u;   /* the sequence did not finish within 16 x BT_NTRK periods */
    }
    for (j = 0; j < n; j++) {
        t0 = bt_now();
        t1 = bt_now();
        bt_acc_add(&nul, t0, t1);
    }
    printf("BT track|%s (%s, %s)|%lu|%llu|%llu|%llu|%lu|%lu|%lu|%lu\n", "blend period q", mv->robot, "mm",
           (unsigned long)n, (unsigned long long)aper.sum, (unsigned long long)nul.sum,
           (unsigned long long)aper.max, (unsigned long)states[0], (unsigned long)states[1],
           (unsigned long)states[2], (unsigned long)st);
}

/* the "BT track" line of n periods timed in *a with the tracker's states
 * (robot in unit), the counter's own cost measured over as many intervals */
static void bt_track_row(const char *name, const char *robot, const char *unit, uint32_t n, const bt_acc *a,
                         const uint32_t states[3], uint32_t st)
{
    bt_acc nul = { 0u, 0u };
    uint64_t t0, t1;
    uint32_t j;
    for (j = 0; j < n; j++) {
        t0 = bt_now();
        t1 = bt_now();
        bt_acc_add(&nul, t0, t1);
    }
    printf("BT track|%s (%s, %s)|%lu|%llu|%llu|%llu|%lu|%lu|%lu|%lu\n", name, robot, unit, (unsigned long)n,
           (unsigned long long)a->sum, (unsigned long long)nul.sum, (unsigned long long)a->max,
           (unsigned long)states[0], (unsigned long)states[1], (unsigned long)states[2], (unsigned long)st);
}

/* twin: bt_queue_f32. bt_period_q's line through the fixed queue
 * (dh_queue_q): a period is dh_queue_target_q, dh_track_step_q on its
 * frame and dh_queue_advance_q, timed whole; the queue is stopped at the
 * 100th period and resumed once at rest, so the periods of the brake and
 * of the resume (the feed override's bounds each period) are among those
 * timed. radius 0: the line alone ("queue period q"); else bt_blend_q's
 * two lines appended by dh_queue_add_path_blend_q, their corner blended
 * within radius ("queue blend period q"), so the overlap's periods are
 * timed too. */
static BT_NOINLINE void bt_queue_q(const bt_move *mv, dh_robot *r, dh_qpos radius)
{
    dh_track_q *const t = &bt_mem.t.tq;
    dh_queue_q *const qu = &bt_puma_m_u.qu;
    const dh_cart_limits_q lim = { 250 << 16, 2000 << 16, 90 << 16, 360 << 16 };
    dh_track_report_q rep;
    dh_queue_report_q qrep;
    dh_queue_cmd_q cmd;
    dh_frame_q A, B;
    bt_acc aper = { 0u, 0u };
    uint32_t states[3] = { 0u, 0u, 0u };
    uint32_t st, n = 0u;
    uint64_t t0, t1;
    int32_t q[6];
    st = bt_line_q(mv, r, &A, &B, q);
    st |= (uint32_t)dh_track_init_q(t, r, &bt_mem.t.mq, q, 1000u);
    st |= (uint32_t)dh_queue_init_q(qu, bt_mem.t.u.qit, 2u);
    /* each line built in the queue's move (copied when appended) */
    st |= (uint32_t)dh_path_line_q(&qu->mv.path, &A, &B);
    if (radius == 0) {
        st |= (uint32_t)dh_queue_add_path_q(qu, &qu->mv.path, &lim);
    } else {
        st |= (uint32_t)dh_queue_add_path_blend_q(qu, &qu->mv.path, &lim, radius);
        /* the second line B to FK(qa + dq) (in A) */
        st |= bt_fk_at_q(mv, r, 1.0f, &A, q);
        st |= (uint32_t)dh_path_line_q(&qu->mv.path, &B, &A);
        st |= (uint32_t)dh_queue_add_path_blend_q(qu, &qu->mv.path, &lim, 0);
    }
    qrep.last = 0;
    while (st == 0u && qrep.last == 0 && n < 16u * BT_NTRK) {
        if (n == 100u) {
            st |= (uint32_t)dh_queue_stop_q(qu);
        }
        if (qu->phase == (uint32_t)DH_QUEUE_STOPPED) {
            st |= (uint32_t)dh_queue_resume_q(qu);
        }
        t0 = bt_now();
        st |= (uint32_t)dh_queue_target_q(qu, t, &cmd);
        rep.state = DH_TRACK_OK;
        if (cmd.kind == (uint32_t)DH_MOVE_PATH) {
            st |= (uint32_t)dh_track_step_q(t, &cmd.T, q, &rep);
        }
        st |= (uint32_t)dh_queue_advance_q(qu, rep.state, &qrep);
        t1 = bt_now();
        bt_acc_add(&aper, t0, t1);
        states[rep.state]++;
        n++;
    }
    if (qrep.last == 0) {
        st |= 0x100u;   /* the queue did not finish within 16 x BT_NTRK periods */
    }
    bt_track_row((radius == 0) ? "queue period q" : "queue blend period q", mv->robot, "mm", n, &aper, states, st);
}

#if BT_IKC_FLOAT
/* twin: bt_queue_q on the float types and calls (the robot in metres),
 * its two lines blended within radius: a period (dh_queue_target_f32,
 * dh_track_step_f32 on its frame, dh_queue_advance_f32) timed whole
 * ("queue blend period f32"), stopped at the 100th period and resumed at
 * rest; after each period, untimed for it, the closed-form solve of its
 * frame with the tracker's configuration before the period as q_ref
 * ("dh_ikc_f32 queue blend", the limit's reference) */
static BT_NOINLINE void bt_queue_f32(const bt_move *mv, dh_robot *r, float radius)
{
    dh_track_f32 *const t = &bt_mem.t.tf;
    dh_queue_f32 *const qu = &bt_mem.t.qu;
    const dh_cart_limits_f32 lim = { 0.25f, 2.0f, 90.0f, 360.0f };
    dh_track_report_f32 rep;
    dh_queue_report_f32 qrep;
    dh_queue_cmd_f32 cmd;
    dh_mat4_f32 A, B;
    bt_acc aik = { 0u, 0u }, aper = { 0u, 0u };
    uint32_t states[3] = { 0u, 0u, 0u }, none[3] = { 0u, 0u, 0u };
    uint32_t st, n = 0u, ns, j;
    uint64_t t0, t1;
    float q[6], qref[6];
    st = bt_move_robot(mv, r, 1.0f);
    st |= (uint32_t)dh_ikc_analyse_f32(r, &bt_mem.t.mf);
    st |= (uint32_t)dh_track_init_f32(t, r, &bt_mem.t.mf, mv->qa, 1e-3f);
    st |= (uint32_t)dh_queue_init_f32(qu, bt_mem.t.qit, 2u);
    /* FK(qa) to FK(qa + dq / 2), blended into FK(qa + dq / 2) to
     * FK(qa + dq); each line built in the queue's move (copied when
     * appended) */
    st |= (uint32_t)dh_fk_f32(r, mv->qa, &A);
    for (j = 0; j < 6u; j++) {
        q[j] = mv->qa[j] + 0.5f * mv->dq[j];
    }
    st |= (uint32_t)dh_fk_f32(r, q, &B);
    st |= (uint32_t)dh_path_line_f32(&qu->mv.path, &A, &B);
    st |= (uint32_t)dh_queue_add_path_blend_f32(qu, &qu->mv.path, &lim, radius);
    for (j = 0; j < 6u; j++) {
        q[j] = mv->qa[j] + mv->dq[j];
    }
    st |= (uint32_t)dh_fk_f32(r, q, &A);
    st |= (uint32_t)dh_path_line_f32(&qu->mv.path, &B, &A);
    st |= (uint32_t)dh_queue_add_path_blend_f32(qu, &qu->mv.path, &lim, 0.0f);
    qrep.last = 0;
    while (st == 0u && qrep.last == 0 && n < 16u * BT_NTRK) {
        if (n == 100u) {
            st |= (uint32_t)dh_queue_stop_f32(qu);
        }
        if (qu->phase == (uint32_t)DH_QUEUE_STOPPED) {
            st |= (uint32_t)dh_queue_resume_f32(qu);
        }
        for (j = 0; j < 6u; j++) {
            qref[j] = t->q[j];
        }
        t0 = bt_now();
        st |= (uint32_t)dh_queue_target_f32(qu, t, 1e-3f, &cmd);
        rep.state = DH_TRACK_OK;
        if (cmd.kind == (uint32_t)DH_MOVE_PATH) {
            st |= (uint32_t)dh_track_step_f32(t, &cmd.T, q, &rep);
        }
        st |= (uint32_t)dh_queue_advance_f32(qu, rep.state, &qrep);
        t1 = bt_now();
        bt_acc_add(&aper, t0, t1);
        t0 = bt_now();
        st |= (uint32_t)dh_ikc_f32(&bt_mem.t.mf, &cmd.T, qref, DH_IKC_KEEP_OUT_OF_LIMITS, bt_mem.t.solf, &ns);
        t1 = bt_now();
        bt_acc_add(&aik, t0, t1);
        states[rep.state]++;
        n++;
    }
    if (qrep.last == 0) {
        st |= 0x100u;   /* the queue did not finish within 16 x BT_NTRK periods */
    }
    bt_track_row("queue blend period f32", mv->robot, "m", n, &aper, states, st);
    bt_track_row("dh_ikc_f32 queue blend", mv->robot, "m", n, &aik, none, st);
}
#endif

/* Runs after the sanity checks: the micro:bit's RAM has no room for more
 * robots, so each move's robot is built in the storage of bt_puma_m (float,
 * metres) and bt_puma_mm (fixed, mm), which nothing uses afterwards. A
 * status other than DH_OK is printed on the line (report.py fails on it). */
static BT_NOINLINE void bt_track(void)
{
#if BT_IKC_FLOAT
    static const dh_cart_jerk_f32 jerk_f = { 20.0f, 3600.0f };   /* 20 m/s^3, 3600 deg/s^3 */
#endif
    static const dh_cart_jerk_q jerk_q = { 20000 << 16, 3600 << 16 };
    bt_acc null = { 0u, 0u };
    uint64_t t0, t1;
    uint32_t m, k;
    /* the counter's own cost, summed over as many intervals as calls */
    for (k = 0; k < BT_NTRK; k++) {
        t0 = bt_now();
        t1 = bt_now();
        bt_acc_add(&null, t0, t1);
    }
    for (m = 0; m < 2u; m++) {
#if BT_IKC_FLOAT
        bt_track_f32(&bt_moves[m], &bt_puma_m, &null);
        bt_period_f32(&bt_moves[m], &bt_puma_m, NULL);
        bt_period_f32(&bt_moves[m], &bt_puma_m, &jerk_f);
        bt_queue_f32(&bt_moves[m], &bt_puma_m, 0.02f);
#endif
        bt_track_q(&bt_moves[m], &bt_puma_mm, &null);
        bt_period_q(&bt_moves[m], &bt_puma_mm, NULL);
        bt_period_q(&bt_moves[m], &bt_puma_mm, &jerk_q);
        bt_blend_q(&bt_moves[m], &bt_puma_mm);
        bt_queue_q(&bt_moves[m], &bt_puma_mm, 0);
        bt_queue_q(&bt_moves[m], &bt_puma_mm, 20 << 16);
    }
}

/* ---- sanity checks (the numbers mean something only if these pass) -------- */

static int bt_check(const char *name, int ok)
{
    printf("BT check|%s|%s\n", name, ok ? "ok" : "FAIL");
    return ok ? 0 : 1;
}

static BT_NOINLINE int bt_checks(void)
{
    int fail = 0;
    float s, c, d;
    dh_mat4_f32 T;
    dh_frame_q F;
    uint32_t j;
    fail += bt_check("all timed calls returned DH_OK", bt_status == 0u);
    (void)dh_sincos_f32(bt_ang_f[3], &s, &c);
    d = s - sinf(bt_ang_f[3] * BT_DEG2RAD);
    fail += bt_check("dh_sincos_f32 agrees with newlib sinf (1e-5)", d < 1e-5f && d > -1e-5f);
    (void)dh_fk_f32(&bt_puma_m, bt_qf[1], &T);
    (void)dh_fk_q(&bt_puma_mm, bt_qq[1], &F);
    for (j = 0; j < 3u; j++) {
        d = (float)F.p[j] * (1.0f / 65536.0f) - 1000.0f * DH_M4(&T, j, 3);
        if (d > 0.01f || d < -0.01f) {
            break;
        }
    }
    fail += bt_check("dh_fk_q (mm) agrees with dh_fk_f32 (m) within 0.01 mm", j == 3u);
    fail += bt_check("cglm affine product agrees with dhmath (1e-5)", bt_cglm_check());
    return fail;
}

/* ---- stack high-water mark ------------------------------------------------ */

extern uint32_t __stack_limit__[];
extern uint32_t __stack_top__[];
#define BT_PAINT 0xA5C3F00Du

/* Fills the unused part of the stack (from its limit up to 64 bytes below
 * the current stack pointer) with a pattern. */
static BT_NOINLINE void bt_stack_paint(void)
{
    volatile uint32_t *p = __stack_limit__;
    uint32_t *sp;
    __asm__ volatile("mov %0, sp" : "=r"(sp));
    while (p < sp - 16) {
        *p++ = BT_PAINT;
    }
}

/* Bytes of stack ever used since bt_stack_paint(). */
static uint32_t bt_stack_used(void)
{
    const volatile uint32_t *p = __stack_limit__;
    while (p < __stack_top__ && *p == BT_PAINT) {
        p++;
    }
    return (uint32_t)((uintptr_t)__stack_top__ - (uintptr_t)p);
}

/* Every section main calls is a function of its own (BT_NOINLINE): inlined,
 * their locals would all be in main's frame, which stays on the stack under
 * every later section. The deepest chain is then main, bt_track, a move's
 * section (its frames, reports and commands) and newlib's printf of its
 * line; the library calls within a section stay within 256 B each
 * (tools/check_guards.sh). */
int main(void)
{
    bt_op *const ops = bt_mem.cglm_ops;
    uint32_t n, k, st;
    int fail;
    bt_stack_paint();
    bt_counter_init();
    printf("BT core|%s|%s|%s\n", BENCH_CORE, BENCH_OPT, __VERSION__);
    if (!bt_calibrate()) {
        return 1;
    }
    st = bt_inputs();
    if (st != 0u) {
        printf("BT error|input generation returned status %lu\n", (unsigned long)st);
        return 1;
    }
    for (k = 0; k < sizeof bt_ops_dh / sizeof bt_ops_dh[0]; k++) {
        bt_measure(&bt_ops_dh[k]);
    }
    /* fixed Jacobian and rotation conversions */
    if (bt_inputs_kinq() != 0u) {
        printf("BT error|rotation inputs returned a status\n");
        return 1;
    }
    for (k = 0; k < sizeof bt_ops_kinq / sizeof bt_ops_kinq[0]; k++) {
        bt_measure(&bt_ops_kinq[k]);
    }
    bt_cglm_setup();
    n = bt_cglm_ops(ops, (uint32_t)(sizeof bt_mem.cglm_ops / sizeof bt_mem.cglm_ops[0]));
    for (k = 0; k < n; k++) {
        bt_measure(&ops[k]);
    }
    bt_ik();
    bt_ik_q();
    bt_ikc();
#if BT_IKC_FLOAT
    bt_ikc_cal();
    bt_opw();
#endif
    if (bt_inputs_dls() != 0u) {
        printf("BT error|damped least-squares inputs returned a status\n");
        return 1;
    }
    for (k = 0; k < sizeof bt_ops_dls / sizeof bt_ops_dls[0]; k++) {
        bt_measure(&bt_ops_dls[k]);
    }
    fail = bt_checks();
    bt_track();
    printf("BT stack|%lu|%lu\n", (unsigned long)bt_stack_used(),
           (unsigned long)((uintptr_t)__stack_top__ - (uintptr_t)__stack_limit__));
    printf("BT end|%d\n", fail);
    return fail ? 1 : 0;
}
