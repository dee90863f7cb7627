/*
 * bench_cglm.c - peer rows: the same 4x4 operations from cglm's
 * header-only code (Debian libcglm-dev; cglm's plain C paths, since a
 * Cortex-M has neither SSE nor NEON).
 *
 * cglm stores mat4 column-major like dh_mat4_f32, so the same inputs are
 * used without conversion. glm_inv_tr() inverts in place: it works on its
 * own copy of the inputs (bt_cg_T), each call inverting one of them again
 * (the set alternates between T and T^-1, both rigid), so no copy is
 * counted in its figure.
 *
 * Built only when BENCH_HAVE_CGLM is defined (tools/target_bench.sh finds
 * the headers); otherwise it contributes no operation.
 */
#include <string.h>

#include "bench_target.h"

#if defined(BENCH_HAVE_CGLM)

#include <cglm/cglm.h>

#if defined(CGLM_SIMD) || defined(CGLM_SSE_FP) || defined(CGLM_NEON_FP)
#error "cglm selected a SIMD path on a Cortex-M build"
#endif

static CGLM_ALIGN_MAT mat4 bt_cg_T[BT_NSET];
vec3 bt_cg_vout; /* global: the stores must not be dead */

static float (*bt_m(dh_mat4_f32 *T))[4]
{
    return T->m;
}

static BT_NOINLINE void op_cg_mul(uint32_t i)
{
    glm_mul(bt_m(&bt_A[BT_IA(i)]), bt_m(&bt_B[BT_IB(i)]), bt_m(&bt_out));
}

static BT_NOINLINE void op_cg_mat4_mul(uint32_t i)
{
    glm_mat4_mul(bt_m(&bt_A[BT_IA(i)]), bt_m(&bt_B[BT_IB(i)]), bt_m(&bt_out));
}

static BT_NOINLINE void op_cg_inv_tr(uint32_t i)
{
    glm_inv_tr(bt_cg_T[BT_IA(i)]);
}

static BT_NOINLINE void op_cg_mat4_inv(uint32_t i)
{
    glm_mat4_inv(bt_m(&bt_A[BT_IA(i)]), bt_m(&bt_out));
}

static BT_NOINLINE void op_cg_mulv3(uint32_t i)
{
    dh_vec3_f32 *p = &bt_pts[BT_IB(i)];
    vec3 v;
    v[0] = p->x;
    v[1] = p->y;
    v[2] = p->z;
    glm_mat4_mulv3(bt_m(&bt_A[BT_IA(i)]), v, 1.0f, bt_cg_vout);
}

void bt_cglm_setup(void)
{
    uint32_t k;
    for (k = 0; k < BT_NSET; k++) {
        memcpy(bt_cg_T[k], bt_A[k].m, sizeof bt_cg_T[k]);
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
        { "cglm", "glm_mul (affine product)", op_cg_mul, 0, "", 1024u },
        { "cglm", "glm_mat4_mul (general product)", op_cg_mat4_mul, 0, "", 1024u },
        { "cglm", "glm_inv_tr (rigid inverse, in place)", op_cg_inv_tr, 0, "", 1024u },
        { "cglm", "glm_mat4_inv (general inverse)", op_cg_mat4_inv, 0, "", 1024u },
        { "cglm", "glm_mat4_mulv3 (point, w = 1)", op_cg_mulv3, 0, "", 1024u },
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
