/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_fk_f32.c - float forward kinematics.
 *
 * Per joint: one dh_sincos_f32 and one in-place update of the accumulated
 * frame, written out from the DH definitions with sin/cos(alpha) taken
 * from the description. A joint is two plane rotations of the columns
 * with the position update in between:
 *
 * Standard, T <- T * Rz(theta) Tz(d) Tx(a) Rx(alpha), columns n o a p:
 *   n1 = ct n + st o,  u = ct o - st n
 *   p <- (p + d a) + a_len n1
 *   n <- n1,  o <- ca u + sa a,  a <- ca a - sa u
 * Modified (Craig), T <- T * Rx(alpha) Tx(a) Rz(theta) Tz(d):
 *   o1 = ca o + sa a,  a1 = ca a - sa o
 *   p <- (p + a_len n) + d a1
 *   n <- ct n + st o1,  o <- ct o1 - st n,  a <- a1
 * 30 multiplications per joint against 36 for a general affine product.
 *
 * Stack: the chain is accumulated in the caller's output (frames[i], or
 * T itself), not in a local 4x4, and the tool product runs after the
 * chain, so the deepest path stays within 256 bytes on Cortex-M0+.
 */
#include "dhmath/robot.h"
#include "dhmath/trig.h"
#include "dhmath/mat4.h" /* dh_mat4_identity_f32, dh_mat4_mul_affine_f32 */
#include "../internal/dh_floatops.h"

/* Rows updated per joint step. With 4-lane float SIMD the bottom row rides
 * along in the fourth lane, so each column is one vector and -O2
 * vectorises the step; it is rewritten by fk_set_bottom() anyway. Scalar FPUs
 * (Cortex-M) update only the 3 rows that matter. */
#if defined(__SSE__) || defined(__ARM_NEON) || defined(__ARM_NEON__) || defined(__ALTIVEC__)
#define FK_ROWS 4
#else
#define FK_ROWS 3
#endif

/* 1 where the chain without frames runs in registers (fk_chain_regs): the
 * float ABI must keep 12 FPU registers across the dh_sincos_f32 calls, as
 * AAPCS-VFP does (s16-s31 callee-saved: Cortex-M4F/M7). Not with soft float
 * (the locals spill, and the Cortex-M0+ frame passes 256 bytes) nor on
 * x86-64 (no callee-saved XMM register: every joint would spill them). */
#if defined(__arm__) && !DH_SOFT_FLOAT
#define FK_REG_CHAIN 1
#else
#define FK_REG_CHAIN 0
#endif

/* 1: each step writes the bottom row 0 0 0 1 (size-first build); 0: one
 * pass over the frames at the end (the default build; with FK_ROWS 4 a
 * step leaves the bottom row 0 0 0 1 only up to the sign of zero). */
#define FK_BOTTOM_EACH (!DH_FAST_PATHS)

static void fk_set_bottom(dh_mat4_f32 *T)
{
    T->m[0][3] = 0.0f;
    T->m[1][3] = 0.0f;
    T->m[2][3] = 0.0f;
    T->m[3][3] = 1.0f;
}

#if !DH_FAST_PATHS
/* The general step. The default build's fast step (fk_fast_step, below)
 * computes the same bits for every input, so it has no fallback to it. */

/* Columns i and i + 1 of T turned by (s, c) on the first FK_ROWS rows:
 * x' = c x + s y, y' = c y - s x. */
DH_SPEED_INLINE void fk_turn(dh_mat4_f32 *T, unsigned i, const float *sc)
{
    const float s = sc[0], c = sc[1];
    int k;
    for (k = 0; k < FK_ROWS; k++) {
        const float x = T->m[i][k], y = T->m[i + 1u][k];
        T->m[i][k] = c * x + s * y;
        T->m[i + 1u][k] = c * y - s * x;
    }
}

/* One joint in place in convention conv; v = (sin theta,
 * cos theta, sin alpha, cos alpha, d, a). Standard: theta on columns
 * (0, 1), then p + d a + a_len n, then alpha on (1, 2); modified: alpha
 * first, p + a_len n + d a, then theta. */
DH_SPEED_INLINE void fk_step(dh_mat4_f32 *T, dh_convention conv, const float v[6])
{
    const unsigned mod = conv != DH_CONV_STANDARD;
    const float *x1 = T->m[2u - 2u * mod], *x2 = T->m[2u * mod];
    int k;
    fk_turn(T, mod, v + 2u * mod);
    for (k = 0; k < FK_ROWS; k++) T->m[3][k] = (T->m[3][k] + v[4u + mod] * x1[k]) + v[5u - mod] * x2[k];
    fk_turn(T, 1u - mod, v + 2u - 2u * mod);
    if (FK_BOTTOM_EACH) fk_set_bottom(T);
}
#endif

/* v = (sin theta, cos theta, sin alpha, cos alpha, d, a) of joint j. */
DH_INLINE void fk_joint_sincos(const dh_joint *j, float theta, float d, float v[6])
{
    (void)dh_sincos_f32(theta, &v[0], &v[1]);
    v[2] = j->sa;
    v[3] = j->ca;
    v[4] = d;
    v[5] = j->a;
}

/* Checks joint j's value q: DH_ERR_NAN when q is not finite,
 * DH_ERR_OVERFLOW when q + offset overflows, else DH_OK and, when v is
 * not NULL, the joint values v (fk_joint_sincos) at q. */
DH_SPEED_INLINE dh_status fk_joint_values(const dh_joint *j, float q, float *v)
{
    const int prism = j->type != DH_JOINT_REVOLUTE;
    const float x = q + (prism ? j->d : j->theta_deg); /* q added to the joint's variable */
    if (!dh_isfinite_f32(q)) return DH_ERR_NAN;
    if (!dh_isfinite_f32(x)) return DH_ERR_OVERFLOW;
    if (v) fk_joint_sincos(j, prism ? j->theta_deg : x, prism ? x : j->d, v);
    return DH_OK;
}

#if DH_FAST_PATHS
/* fk_joint_values() of a q already checked, without the checks. */
DH_INLINE void fk_joint_checked(const dh_joint *j, float q, float v[6])
{
    if (j->type == DH_JOINT_REVOLUTE) fk_joint_sincos(j, q + j->theta_deg, j->d, v);
    else fk_joint_sincos(j, j->theta_deg, q + j->d, v);
}

/* fk_step() on the first FK_ROWS rows, one row at a time, each row read
 * completely before it is written (zero-distance dependences only, so the
 * compiler may vectorise over rows); conv is a constant of each caller.
 * The same operations in the same order as fk_step(); the bottom row is left
 * to the caller. sin/cos(alpha) and a come from j itself (the values that
 * v holds), so they load straight into registers. */
DH_INLINE void fk_fast_step(dh_mat4_f32 *T, dh_convention conv, const dh_joint *j, const float v[6])
{
    const float st = v[0], ct = v[1], sa = j->sa, ca = j->ca, d = v[4], a = j->a;
    int k;
    for (k = 0; k < FK_ROWS; k++) {
        const float nx = T->m[0][k], ox = T->m[1][k], ax = T->m[2][k], px = T->m[3][k];
        if (conv == DH_CONV_STANDARD) {
            const float n1 = ct * nx + st * ox, u = ct * ox - st * nx;
            T->m[3][k] = px + d * ax + a * n1;
            T->m[0][k] = n1;
            T->m[1][k] = ca * u + sa * ax;
            T->m[2][k] = ca * ax - sa * u;
        } else {
            const float o1 = ca * ox + sa * ax, a1 = ca * ax - sa * ox;
            T->m[3][k] = px + a * nx + d * a1;
            T->m[0][k] = ct * nx + st * o1;
            T->m[1][k] = ct * o1 - st * nx;
            T->m[2][k] = a1;
        }
    }
}

/* The link matrix written out (what fk_step() gives on the identity, with
 * the zeros of the definitions' signs). Out of line: its live products
 * would otherwise sit in the caller's frame while dh_sincos_f32 runs. */
static DH_NOINLINE void fk_link_direct(dh_mat4_f32 *A, unsigned mod, const float v[6])
{
    const float st = v[0], ct = v[1], sa = v[2], ca = v[3], d = v[4], a = v[5];
    if (mod == 0u) {
        A->m[0][0] = ct;       A->m[0][1] = st;       A->m[0][2] = 0.0f;
        A->m[1][0] = -st * ca; A->m[1][1] = ct * ca;  A->m[1][2] = sa;
        A->m[2][0] = st * sa;  A->m[2][1] = -ct * sa; A->m[2][2] = ca;
        A->m[3][0] = a * ct;   A->m[3][1] = a * st;   A->m[3][2] = d;
    } else {
        A->m[0][0] = ct;       A->m[0][1] = st * ca;  A->m[0][2] = st * sa;
        A->m[1][0] = -st;      A->m[1][1] = ct * ca;  A->m[1][2] = ct * sa;
        A->m[2][0] = 0.0f;     A->m[2][1] = -sa;      A->m[2][2] = ca;
        A->m[3][0] = a;        A->m[3][1] = -sa * d;  A->m[3][2] = ca * d;
    }
    fk_set_bottom(A);
}

/* fk_fast_step() on one row (n, o, a, p) of a frame held in the caller's
 * locals, standard DH (same operations in the same order); joint values
 * st, ct, sa, ca, d and the length len */
DH_INLINE void fk_row_std(float *n, float *o, float *a, float *p, float st, float ct, float sa, float ca,
                              float d, float len)
{
    const float n1 = ct * *n + st * *o, u = ct * *o - st * *n;
    *p = *p + d * *a + len * n1;
    *n = n1;
    *o = ca * u + sa * *a;
    *a = ca * *a - sa * u;
}

/* the same for modified DH */
DH_INLINE void fk_row_mod(float *n, float *o, float *a, float *p, float st, float ct, float sa, float ca,
                              float d, float len)
{
    const float o1 = ca * *o + sa * *a, a1 = ca * *a - sa * *o;
    *p = *p + len * *n + d * a1;
    {
        const float n1 = ct * *n + st * o1;
        *o = ct * o1 - st * *n;
        *n = n1;
    }
    *a = a1;
}

/*
 * fk_chain_from() into T alone (no frames), with the frame in locals: the 12
 * entries stay in registers across the joints and the dh_sincos_f32 calls
 * (callee-saved FPU registers) instead of 12 loads and 12 stores per
 * joint. The joint values are not checked first: their finiteness is
 * summed on the way (x - x is 0 for a finite x, NaN otherwise) and T is
 * written only when every one passed; returns 0 then, else 1 with T
 * untouched (the caller's checks then give the status). src may not be T.
 * An identity base starts from the first link as fk_link_direct() writes it
 * (the frames path's bits, signs of zeros included).
 */
/* fk_joint_checked() on a q not checked yet; returns 0 when q and q plus
 * the offset are finite, else NaN (x - x). */
DH_INLINE float fk_joint_unchecked(const dh_joint *j, float q, float v[6])
{
    const float x = q + (j->type == DH_JOINT_REVOLUTE ? j->theta_deg : j->d);
    if (j->type == DH_JOINT_REVOLUTE) fk_joint_sincos(j, x, j->d, v);
    else fk_joint_sincos(j, j->theta_deg, x, v);
    return (q - q) + (x - x);
}

DH_INLINE int fk_chain_regs(const dh_robot *r, const float *q, dh_mat4_f32 *T, const dh_mat4_f32 *src,
                         dh_convention conv)
{
    float n0, n1, n2, o0, o1, o2, a0, a1, a2, p0, p1, p2, z = 0.0f;
    uint32_t i = 0u;
    if (r->flags & DH_ROBOT_BASE_ID_F32) {
        /* identity base: the first link as fk_link_direct() writes it */
        float v[6];
        z = fk_joint_unchecked(&r->joint[0], q[0], v);
        {
            const float st = v[0], ct = v[1], sa = v[2], ca = v[3], d = v[4], a = v[5];
            if (conv == DH_CONV_STANDARD) {
                n0 = ct;       n1 = st;       n2 = 0.0f;
                o0 = -st * ca; o1 = ct * ca;  o2 = sa;
                a0 = st * sa;  a1 = -ct * sa; a2 = ca;
                p0 = a * ct;   p1 = a * st;   p2 = d;
            } else {
                n0 = ct;       n1 = st * ca;  n2 = st * sa;
                o0 = -st;      o1 = ct * ca;  o2 = ct * sa;
                a0 = 0.0f;     a1 = -sa;      a2 = ca;
                p0 = a;        p1 = -sa * d;  p2 = ca * d;
            }
        }
        i = 1u;
    } else {
        n0 = src->m[0][0]; n1 = src->m[0][1]; n2 = src->m[0][2];
        o0 = src->m[1][0]; o1 = src->m[1][1]; o2 = src->m[1][2];
        a0 = src->m[2][0]; a1 = src->m[2][1]; a2 = src->m[2][2];
        p0 = src->m[3][0]; p1 = src->m[3][1]; p2 = src->m[3][2];
    }
    for (; i < r->n; i++) {
        float v[6];
        const dh_joint *j = &r->joint[i];
        z += fk_joint_unchecked(j, q[i], v);
        {
            const float st = v[0], ct = v[1], sa = j->sa, ca = j->ca, d = v[4], a = j->a;
            if (conv == DH_CONV_STANDARD) {
                fk_row_std(&n0, &o0, &a0, &p0, st, ct, sa, ca, d, a);
                fk_row_std(&n1, &o1, &a1, &p1, st, ct, sa, ca, d, a);
                fk_row_std(&n2, &o2, &a2, &p2, st, ct, sa, ca, d, a);
            } else {
                fk_row_mod(&n0, &o0, &a0, &p0, st, ct, sa, ca, d, a);
                fk_row_mod(&n1, &o1, &a1, &p1, st, ct, sa, ca, d, a);
                fk_row_mod(&n2, &o2, &a2, &p2, st, ct, sa, ca, d, a);
            }
        }
    }
    if (!dh_feq_f32(z, 0.0f)) return 1;
    T->m[0][0] = n0; T->m[0][1] = n1; T->m[0][2] = n2;
    T->m[1][0] = o0; T->m[1][1] = o1; T->m[1][2] = o2;
    T->m[2][0] = a0; T->m[2][1] = a1; T->m[2][2] = a2;
    T->m[3][0] = p0; T->m[3][1] = p1; T->m[3][2] = p2;
    return 0;
}
#endif

/* dst = src unless they are the same frame. */
DH_SPEED_INLINE void fk_copy(dh_mat4_f32 *dst, const dh_mat4_f32 *src)
{
    if (dst != src) *dst = *src;
}

/* Rows summed by fk_frame_finite(): the bottom row is 0 0 0 1 there, so 3 and
 * 4 give the same status; 4 is the shorter loop, 3 the faster. */
#define FK_TEST_ROWS (DH_FAST_PATHS ? 3 : 4)

/* DH_OK when the 3x4 part of T is finite (its bottom row is 0 0 0 1), else
 * DH_ERR_OVERFLOW: x - x is 0 for a finite x and NaN otherwise, and a NaN
 * stays in the sums (one branch instead of twelve). */
static DH_SIZE_NOINLINE dh_status fk_frame_finite(const dh_mat4_f32 *T)
{
    float z = 0.0f;
    int c, k;
    DH_UNROLL4
    for (c = 0; c < 4; c++)
        for (k = 0; k < FK_TEST_ROWS; k++) z += T->m[c][k] - T->m[c][k];
    return dh_feq_f32(z, 0.0f) ? DH_OK : DH_ERR_OVERFLOW;
}

/* The link A from the joint values v of robot r: written out (fk_link_direct)
 * in the default build, fk_step() on the identity in the size-first build (the
 * same nonzero entries; a zero entry may have the other sign). */
#if DH_FAST_PATHS
DH_INLINE void fk_link(dh_mat4_f32 *A, const dh_robot *r, const float v[6])
{
    fk_link_direct(A, r->conv != DH_CONV_STANDARD, v);
}
#else
DH_INLINE void fk_link(dh_mat4_f32 *A, const dh_robot *r, const float v[6])
{
    dh_mat4_identity_f32(A);
    fk_step(A, r->conv, v);
}
#endif

dh_status dh_link_f32(const dh_robot *r, uint32_t i, float q, dh_mat4_f32 *A)
{
    float v[6];
    dh_status st;
    DH_ASSERT(r != NULL);
    DH_ASSERT(A != NULL);
    if (i >= r->n || r->n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    if ((r->flags & DH_ROBOT_HAS_F32) == 0u) return DH_ERR_UNAVAILABLE;
    st = fk_joint_values(&r->joint[i], q, v);
    if (st == DH_OK) fk_link(A, r, v);
    return st;
}

/* Joint j at *q (already checked) applied to T in place: fk_fast_step in the
 * default build, step in the size-first build. */
#if DH_FAST_PATHS
DH_INLINE void fk_joint(dh_mat4_f32 *T, dh_convention conv, const dh_joint *j, const float *q)
{
    float v[6];
    fk_joint_checked(j, *q, v);
    fk_fast_step(T, conv, j, v);
}
#else
DH_INLINE void fk_joint(dh_mat4_f32 *T, dh_convention conv, const dh_joint *j, const float *q)
{
    float v[6];
    /* DH_OK: q passed the check before the chain */
    if (fk_joint_values(j, *q, v) == DH_OK) fk_step(T, conv, v);
}
#endif

/* Joints i.. of the chain from src into frames[i..] (or dst); q already
 * checked. */
DH_INLINE void fk_chain_from(const dh_robot *r, const float *q, dh_mat4_f32 *frames, dh_mat4_f32 *dst0,
                  const dh_mat4_f32 *src0, uint32_t i0, dh_convention conv)
{
    const dh_mat4_f32 *src = src0;
    dh_mat4_f32 *dst = dst0;
    uint32_t i;
    for (i = i0; i < r->n; i++) {
        if (frames) dst = &frames[i];
        fk_copy(dst, src);
        fk_joint(dst, conv, &r->joint[i], &q[i]);
        src = dst;
    }
}

/* The chain, built in frames[] or in T_end (frames may be NULL, then T_end
 * is not NULL). Every q is checked before anything is written. Twin
 * bodies: the default build runs the chain without frames in registers
 * (FK_REG_CHAIN, checked on the way; the loop gives the status when a
 * joint value fails), writes the first link of an identity base out and
 * has one chain loop per convention; the size-first build has one loop. */
#if DH_FAST_PATHS
static DH_NOINLINE dh_status fk_chain(const dh_robot *r, const float *q, dh_mat4_f32 *frames,
                                           dh_mat4_f32 *T_end)
{
    const dh_mat4_f32 *src = &r->base;
    dh_mat4_f32 *dst = T_end;
    uint32_t i;
    dh_status st;
    DH_ASSERT(r != NULL);
    DH_ASSERT(q != NULL);
    if (r->n == 0u || r->n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    if ((r->flags & DH_ROBOT_HAS_F32) == 0u) return DH_ERR_UNAVAILABLE;
    if (FK_REG_CHAIN && !frames) {
        /* one copy for both conventions (the test per joint is cheaper
         * than a second copy of the loop in flash) */
        if (!fk_chain_regs(r, q, T_end, src, r->conv)) return DH_OK;
    }
    for (i = 0u; i < r->n; i++) {
        st = fk_joint_values(&r->joint[i], q[i], NULL);
        if (st != DH_OK) return st;
    }
    i = 0u;
    if (r->flags & DH_ROBOT_BASE_ID_F32) {
        float v[6];
        if (frames) dst = frames;
        fk_joint_checked(&r->joint[0], q[0], v);
        fk_link_direct(dst, r->conv != DH_CONV_STANDARD, v);
        src = dst;
        i = 1u;
    }
    if (r->conv == DH_CONV_STANDARD) fk_chain_from(r, q, frames, dst, src, i, DH_CONV_STANDARD);
    else fk_chain_from(r, q, frames, dst, src, i, DH_CONV_MODIFIED);
    return DH_OK;
}
#else
static DH_NOINLINE dh_status fk_chain(const dh_robot *r, const float *q, dh_mat4_f32 *frames,
                                           dh_mat4_f32 *T_end)
{
    uint32_t i;
    dh_status st;
    DH_ASSERT(r != NULL);
    DH_ASSERT(q != NULL);
    if (r->n == 0u || r->n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    if ((r->flags & DH_ROBOT_HAS_F32) == 0u) return DH_ERR_UNAVAILABLE;
    for (i = 0u; i < r->n; i++) {
        st = fk_joint_values(&r->joint[i], q[i], NULL);
        if (st != DH_OK) return st;
    }
    fk_chain_from(r, q, frames, T_end, &r->base, 0u, r->conv);
    return DH_OK;
}
#endif

/* The chain, then the bottom rows, the tool (T_end = last * tool when
 * T_end is not NULL) and the finiteness test of the result (or, without
 * T_end, of the last frame); a non-finite chain frame always reaches
 * T_end (x*inf, x*0*inf). Called one after the other, the chain and the
 * tool product are never on the stack together. */
static DH_NOINLINE dh_status fk_all(const dh_robot *r, const float *q, dh_mat4_f32 *frames, dh_mat4_f32 *T_end)
{
    const dh_mat4_f32 *last = T_end;
    uint32_t i;
    const dh_status st = fk_chain(r, q, frames, T_end);
    if (st != DH_OK) return st;
    if (frames) last = &frames[r->n - 1u];
    if (!FK_BOTTOM_EACH && frames) {
        for (i = 0u; i < r->n; i++) fk_set_bottom(&frames[i]);
    }
    if (T_end) {
        if (r->flags & DH_ROBOT_TOOL_ID_F32) {
            fk_copy(T_end, last);
            if (!FK_BOTTOM_EACH) fk_set_bottom(T_end);
        } else {
            dh_mat4_mul_affine_f32(last, &r->tool, T_end);
        }
        last = T_end;
    }
    return fk_frame_finite(last);
}

dh_status dh_fk_f32(const dh_robot *r, const float *q, dh_mat4_f32 *T)
{
    DH_ASSERT(T != NULL);
    return fk_all(r, q, NULL, T);
}

dh_status dh_fk_frames_f32(const dh_robot *r, const float *q, dh_mat4_f32 *frames, dh_mat4_f32 *T_end)
{
    DH_ASSERT(frames != NULL);
    return fk_all(r, q, frames, T_end);
}
