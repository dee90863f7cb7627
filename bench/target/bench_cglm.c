/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bench_cglm.c - peer rows: the same 4x4 operations from cglm's
 * header-only code (Debian libcglm-dev; cglm's plain C paths, since a
 * Cortex-M has neither SSE nor NEON).
 *
 * cglm stores mat4 column-major like dh_mat4_f32, so the same inputs are
 * used without conversion. glm_inv_tr() inverts in place: it works on
 * bt_M, reset to the inputs before its rows (bt_cglm_setup), each call
 * inverting one of them again (the set alternates between T and T^-1,
 * both rigid), so no copy is counted in its figure.
 *
 * Built only when BENCH_HAVE_CGLM is defined (tools/target_bench.sh finds
 * the headers); otherwise it contributes no operation.
 */
#include "bench_target.h"

#if defined(BENCH_HAVE_CGLM)

#include <cglm/cglm.h>

#if defined(CGLM_SIMD) || defined(CGLM_SSE_FP) || defined(CGLM_NEON_FP)
#error "cglm selected a SIMD path on a Cortex-M build"
#endif


static float (*bt_m(const dh_mat4_f32 *T))[4]
{
    return (float (*)[4])T->m; /* cglm's prototypes take no const */
}

/*
 * Each cglm operation sits in an out-of-line function with the prototype
 * of the dhmath function it is compared with (cglm's code inlined there),
 * called from a wrapper with the same index arithmetic as dhmath's; a null
 * twin with the same prototype gives its own instructions exactly as for
 * dhmath. Both sides are thus measured the same way: as calls through a
 * noinline wrapper, from the first instruction of the function through its
 * return (and as whole calls).
 */
static BT_NOIPA void cg_mul(const dh_mat4_f32 *A, const dh_mat4_f32 *B, dh_mat4_f32 *out)
{
    glm_mul(bt_m(A), bt_m(B), out->m);
}

static BT_NOIPA void cg_mat4_mul(const dh_mat4_f32 *A, const dh_mat4_f32 *B, dh_mat4_f32 *out)
{
    glm_mat4_mul(bt_m(A), bt_m(B), out->m);
}

static BT_NOIPA void cg_inv_tr(dh_mat4_f32 *T)
{
    glm_inv_tr(T->m);
}

/* the out-of-place rigid inverse in cglm: copy, then invert the copy */
static BT_NOIPA void cg_inv_tr_copy(const dh_mat4_f32 *T, dh_mat4_f32 *out)
{
    glm_mat4_copy(bt_m(T), out->m);
    glm_inv_tr(out->m);
}

static BT_NOIPA void cg_mat4_inv(const dh_mat4_f32 *T, dh_mat4_f32 *out)
{
    glm_mat4_inv(bt_m(T), out->m);
}

static BT_NOIPA void cg_mulv3(const dh_mat4_f32 *T, const dh_vec3_f32 *u, dh_vec3_f32 *v)
{
    vec3 in, o;
    in[0] = u->x;
    in[1] = u->y;
    in[2] = u->z;
    glm_mat4_mulv3(bt_m(T), in, 1.0f, o);
    v->x = o[0];
    v->y = o[1];
    v->z = o[2];
}

/* null twins */
static BT_NOIPA void zc_mul(const dh_mat4_f32 *A, const dh_mat4_f32 *B, dh_mat4_f32 *out)
{
    (void)A; (void)B; (void)out;
}
static BT_NOIPA void zc_inv_tr(dh_mat4_f32 *T)
{
    (void)T;
}
static BT_NOIPA void zc_inv(const dh_mat4_f32 *T, dh_mat4_f32 *out)
{
    (void)T; (void)out;
}
static BT_NOIPA void zc_point(const dh_mat4_f32 *T, const dh_vec3_f32 *u, dh_vec3_f32 *v)
{
    (void)T; (void)u; (void)v;
}

#define C_mul(F) F(&bt_A[BT_IA(i)], &bt_B[BT_IB(i)], &bt_out)
#define C_mat4_mul(F) F(&bt_A[BT_IA(i)], &bt_B[BT_IB(i)], &bt_out)
#define C_inv_tr(F) F(&bt_M[BT_IA(i)])
#define C_inv_tr_copy(F) F(&bt_A[BT_IA(i)], &bt_out)
#define C_mat4_inv(F) F(&bt_A[BT_IA(i)], &bt_out)
#define C_mulv3(F) F(&bt_A[BT_IA(i)], &bt_pts[BT_IB(i)], &bt_vout)

#define BC_PAIR(tag, real, null)                                    \
    static BT_NOIPA void op_cg_##tag(uint32_t i) { C_##tag(real); } \
    static BT_NOIPA void nul_cg_##tag(uint32_t i) { C_##tag(null); }

BC_PAIR(mul, cg_mul, zc_mul)
BC_PAIR(mat4_mul, cg_mat4_mul, zc_mul)
BC_PAIR(inv_tr, cg_inv_tr, zc_inv_tr)
BC_PAIR(inv_tr_copy, cg_inv_tr_copy, zc_inv)
BC_PAIR(mat4_inv, cg_mat4_inv, zc_inv)
BC_PAIR(mulv3, cg_mulv3, zc_point)

void bt_cglm_setup(void)
{
    uint32_t k;
    for (k = 0; k < BT_NSET; k++) {
        bt_M[k] = bt_A[k];
    }
}

int bt_cglm_check(void)
{
    dh_mat4_f32 ref;
    int r, c;
    dh_mat4_mul_affine_f32(&bt_A[0], &bt_B[1], &ref);
    glm_mul(bt_m(&bt_A[0]), bt_m(&bt_B[1]), bt_m(&bt_out));
    for (c = 0; c < 4; c++) {
        for (r = 0; r < 4; r++) {
            float d = ref.m[c][r] - bt_out.m[c][r];
            if (d > 1e-5f || d < -1e-5f) {
                return 0;
            }
        }
    }
    return 1;
}

uint32_t bt_cglm_ops(bt_op *ops, uint32_t max)
{
    static const bt_op list[] = {
        { "cglm", "glm_mul (affine product)", op_cg_mul, nul_cg_mul, "zc_mul nul_cg_mul", 1024u },
        { "cglm", "glm_mat4_mul (general product)", op_cg_mat4_mul, nul_cg_mat4_mul,
          "zc_mul nul_cg_mat4_mul", 1024u },
        { "cglm", "glm_inv_tr (rigid inverse, in place)", op_cg_inv_tr, nul_cg_inv_tr,
          "zc_inv_tr nul_cg_inv_tr", 1024u },
        { "cglm", "glm_mat4_copy + glm_inv_tr (rigid inverse, out of place)", op_cg_inv_tr_copy,
          nul_cg_inv_tr_copy, "zc_inv nul_cg_inv_tr_copy", 1024u },
        { "cglm", "glm_mat4_inv (general inverse)", op_cg_mat4_inv, nul_cg_mat4_inv,
          "zc_inv nul_cg_mat4_inv", 1024u },
        { "cglm", "glm_mat4_mulv3 (point, w = 1)", op_cg_mulv3, nul_cg_mulv3, "zc_point nul_cg_mulv3",
          1024u },
    };
    uint32_t k, n = (uint32_t)(sizeof list / sizeof list[0]);
    if (n > max) {
        n = max;
    }
    for (k = 0; k < n; k++) {
        ops[k] = list[k];
    }
    return n;
}

#else /* !BENCH_HAVE_CGLM */

void bt_cglm_setup(void)
{
}

int bt_cglm_check(void)
{
    return 1;
}

uint32_t bt_cglm_ops(bt_op *ops, uint32_t max)
{
    (void)ops;
    (void)max;
    return 0;
}

#endif
