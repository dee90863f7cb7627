/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bench_target.h - shared declarations of the on-target benchmark firmware
 * (bench_target.c: counter, inputs, dhmath and newlib operations;
 * bench_cglm.c: the cglm peer operations).
 *
 * Not part of the library. See docs/generated/performance_target.md for the method.
 */
#ifndef BENCH_TARGET_H
#define BENCH_TARGET_H

#include <stdint.h>

#include "dhmath/dhmath.h"

#if defined(__GNUC__)
#define BT_NOINLINE __attribute__((noinline, noclone))
/* no inlining, cloning or interprocedural use of the body (null twins) */
#define BT_NOIPA __attribute__((noipa))
#else
#define BT_NOINLINE
#define BT_NOIPA
#endif

/*
 * Input set sizes (powers of two; indices are masked). The Cortex-M0 board
 * (micro:bit) has 16 KiB of RAM in total, so its sets are smaller. Input
 * variety matters for the instruction count only through data-dependent
 * paths (trig quadrants, range checks), which a few dozen inputs exercise.
 */
#if defined(__ARM_ARCH_6M__)
#define BT_NSET 8u      /* matrices / frames / points / FK configurations */
#define BT_NANG 64u     /* angles for sin/cos */
#else
#define BT_NSET 16u
#define BT_NANG 256u
#endif

/** One benchmarked operation: fn(i) performs one call on input set i. */
typedef void (*bt_fn)(uint32_t i);
typedef struct {
    const char *group; /**< "dhmath", "newlib", "cglm" */
    const char *name;  /**< operation name as printed in the report */
    bt_fn fn;          /**< wrapper doing one call */
    bt_fn null_fn;     /**< same wrapper calling a null twin of the function, or 0 (inline code) */
    const char *null_sym; /**< "<null twin> <its wrapper>": symbols whose instructions report.py counts */
    uint32_t n;        /**< calls per measurement */
} bt_op;

/* Inputs (filled once by bench_target.c before any measurement). Aligned
 * to 16 bytes so the cglm peer can use the same storage as its mat4. */
extern __attribute__((aligned(16))) dh_mat4_f32 bt_A[BT_NSET];
extern __attribute__((aligned(16))) dh_mat4_f32 bt_B[BT_NSET];
extern __attribute__((aligned(16))) dh_mat4_f32 bt_out;
extern dh_vec3_f32 bt_pts[BT_NSET];
/* Operands of the in-place rigid inverses (dhmath's, then cglm's: one
 * array for both, the micro:bit's RAM): T, T^-1, T, ..., rigid at every
 * step; each library's rows start from the inputs bt_A. */
extern __attribute__((aligned(16))) dh_mat4_f32 bt_M[BT_NSET];
extern dh_vec3_f32 bt_vout;
extern volatile uint32_t bt_sink;

/** Second operand index for call i: all BT_NSET^2 pairs over BT_NSET^2 calls. */
#define BT_IA(i) ((i) & (BT_NSET - 1u))
#define BT_IB(i) (((i) / BT_NSET + 3u * (i)) & (BT_NSET - 1u))

/**
 * cglm peer operations (bench_cglm.c). Writes at most max entries to ops
 * and returns their number; 0 when the firmware was built without cglm.
 * bt_cglm_setup() is called before the cglm operations are measured (it
 * resets bt_M to the inputs).
 */
uint32_t bt_cglm_ops(bt_op *ops, uint32_t max);
void bt_cglm_setup(void);
/** Sanity check: cglm affine product of bt_A[0] bt_B[1] vs dhmath's (1 = agree). */
int bt_cglm_check(void);

/*
 * opw_kinematics peer (bench_opw.cpp, FPU cores, only when built with a
 * clone of opw: BENCH_HAVE_OPW; bench_target.c has the stand-ins
 * otherwise). bt_opw_setup stores up to BT_NOPW targets and returns how many
 * (0 without opw); bt_opw_solve(k) runs opw_kinematics::inverse<float> on
 * target k; bt_opw_solutions writes the last solve's finite solutions as
 * the DH table's joint values in degrees (not wrapped) and returns their
 * number.
 */
#define BT_NOPW 16u
#ifdef __cplusplus
extern "C" {
#endif
uint32_t bt_opw_setup(const dh_mat4_f32 *T, uint32_t n);
void bt_opw_solve(uint32_t k);
uint32_t bt_opw_solutions(float q_dh_deg[8][6]);
#ifdef __cplusplus
}
#endif

#endif /* BENCH_TARGET_H */
