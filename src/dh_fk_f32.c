/*
 * dh_fk_f32.c - float forward kinematics.
 *
 * Cost per joint: one dh_sincos_f32 and one in-place affine update of the
 * accumulated frame, written out from the DH definitions (seed 003) with
 * sin/cos(alpha) taken from the description (computed once):
 *
 * Standard, T <- T * Rz(theta) Tz(d) Tx(a) Rx(alpha), columns n o a p:
 *   n1 = ct n + st o,  u = ct o - st n
 *   p <- p + d a + a_len n1      (Tz along the old z, Tx along the new x)
 *   n <- n1,  o <- ca u + sa a,  a <- ca a - sa u
 * Modified, T <- T * Rx(alpha) Tx(a) Rz(theta) Tz(d):
 *   o1 = ca o + sa a,  a1 = ca a - sa o
 *   p <- p + a_len n + d a1
 *   n <- ct n + st o1,  o <- ct o1 - st n,  a <- a1
 * That is 10 multiplications per row, 30 per joint, against 36 for a
 * general affine product plus the link-matrix construction.
 *
 * Stack: the chain is accumulated in the caller's output (frames[i], or
 * T itself when only the end frame is wanted, the tool then applied in
 * place row by row), not in a local 4x4, so the deepest path
 * (fk_f32 > dh_sincos_f32 > libgcc) stays within the 256-byte budget of
 * issue 5 on Cortex-M0+ (figures in docs/footprint.md).
 *
 * Speed (issue 6): every step is done in place on one frame (frames[i] is
 * first a copy of frames[i-1]), so the row loop has only zero-distance
 * dependences; on x86-64/NEON it also carries the bottom row (FK_ROWS),
 * which makes each column one 4-lane vector and lets -O2 vectorise the
 * step; the final finiteness test sums x - x instead of branching per
 * element. Puma 560 on x86-64 -O2: 1414 -> 1067 instructions per call
 * (callgrind), ~0.27x -> ~0.21x the time of KDL's JntToCart; Cortex-M4F
 * unchanged at -O2 (1163) and 1126 -> 1107 at -Os (tools/target_bench.sh).
 * The arithmetic of rows 0-2 is the same, in the same order, as before.
 */
#include "dhmath/dh_robot.h"
#include "dhmath/dh_trig.h"
#include "dhmath/dh_mat4.h" /* dh_mat4_mul_affine_f32 */

static int is_finite(float x)
{
    return (x - x) == 0.0f;
}

/* Rows updated per joint step. With 4-lane float SIMD (SSE on x86-64,
 * NEON, AltiVec) the homogeneous bottom row rides along in the fourth lane:
 * each column of the column-major frame is then one vector and the whole
 * step is a handful of vector operations (GCC/Clang vectorise the loop at
 * -O2 without -march). Its value there is (0 0 0 1) up to the sign of zero
 * and it is rewritten by set_bottom() anyway. On scalar FPUs (Cortex-M)
 * the fourth row would be 33% more work for nothing, so only 3 rows. */
#if defined(__SSE__) || defined(__ARM_NEON) || defined(__ARM_NEON__) || defined(__ALTIVEC__)
#define FK_ROWS 4
#else
#define FK_ROWS 3
#endif

#if DH_SMALL

/*
 * DH_SMALL: the same arithmetic with less code. One step serves both
 * conventions: a joint is two plane rotations of the columns with the
 * position update in between. Standard DH turns (n, o) by theta, then
 * p <- (p + d a) + a_len n, then twists (o, a) by alpha; modified DH
 * twists first, then p <- (p + a_len n) + d a, then turns. Every entry is
 * computed by the same operations in the same order as step_std /
 * step_mod of the default build, so a step gives the same bits (rows
 * 0..2; the bottom row is written as 0 0 0 1).
 * The link matrix is not written out: dh_link_f32 is the step applied to
 * the identity, and an identity base takes the general step too. That
 * gives the same values as the default's written-out link, but a zero
 * entry may have the other sign (the step's 1 * 0 - 0 * 1 is +0 where
 * -st * ca is -0, and the reverse); every nonzero entry, hence every
 * later product, is the same bits, and the header promises nothing about
 * signs of zeros (the bottom row is still exactly 0 0 0 1). This is the
 * only difference from the default build; it saves the 144-byte
 * link_direct. The q checks and the joint values share one function; the
 * tool product is dh_mat4_mul_affine_f32.
 */
#if defined(__GNUC__) || defined(__clang__)
#define FK_NOINLINE __attribute__((noinline))
#else
#define FK_NOINLINE
#endif

static void set_bottom(dh_mat4_f32 *T)
{
    T->m[0][3] = 0.0f;
    T->m[1][3] = 0.0f;
    T->m[2][3] = 0.0f;
    T->m[3][3] = 1.0f;
}

/* Columns i and i + 1 of T turned by sc = (s, c): x' = c x + s y,
 * y' = c y - s x. */
static FK_NOINLINE void turn(dh_mat4_f32 *T, int i, const float *sc)
{
    const float s = sc[0], c = sc[1];
    int k;
    for (k = 0; k < 3; k++) {
        float x = T->m[i][k], y = T->m[i + 1][k];
        T->m[i][k] = c * x + s * y;
        T->m[i + 1][k] = c * y - s * x;
    }
}

/* One joint in place (r: the convention); v = (sin theta, cos theta,
 * sin alpha, cos alpha, d, a) from joint_values. Standard: theta on
 * columns (0, 1), then p + d a + a_len n, then alpha on (1, 2); modified:
 * alpha first, p + a_len n + d a, then theta. */
static FK_NOINLINE void step(dh_mat4_f32 *T, const dh_robot *r, const float v[6])
{
    const int mod = r->conv != DH_CONV_STANDARD;
    const float *x1 = T->m[2 - 2 * mod], *x2 = T->m[2 * mod];
    int k;
    turn(T, mod, v + 2 * mod);
    for (k = 0; k < 3; k++) T->m[3][k] = (T->m[3][k] + v[4 + mod] * x1[k]) + v[5 - mod] * x2[k];
    turn(T, !mod, v + 2 - 2 * mod);
    set_bottom(T);
}

/* Checks joint j's value q: DH_ERR_NAN when q is not finite,
 * DH_ERR_OVERFLOW when q + offset overflows, else DH_OK and, when v is
 * not NULL, v = (sin theta, cos theta, sin alpha, cos alpha, d, a). */
static FK_NOINLINE dh_status joint_values(const dh_joint *j, float q, float *v)
{
    /* (theta, d) with q added to the joint's variable */
    float td[2];
    const int k = j->type != DH_JOINT_REVOLUTE;
    td[0] = j->theta_deg;
    td[1] = j->d;
    td[k] = q + td[k];
    if (!is_finite(q)) return DH_ERR_NAN;
    if (!is_finite(td[k])) return DH_ERR_OVERFLOW;
    if (v) {
        (void)dh_sincos_f32(td[0], &v[0], &v[1]);
        v[2] = j->sa;
        v[3] = j->ca;
        v[4] = td[1];
        v[5] = j->a;
    }
    return DH_OK;
}

/* dst = src unless they are the same frame. */
static FK_NOINLINE void copy(dh_mat4_f32 *dst, const dh_mat4_f32 *src)
{
    if (dst != src) *dst = *src;
}

/* DH_OK when T is finite (its bottom row is 0 0 0 1 here, so that is its
 * 3x4 part), else DH_ERR_OVERFLOW: x - x is 0 for a finite x and NaN
 * otherwise, and a NaN stays in the sum. */
static FK_NOINLINE dh_status frame_finite(const dh_mat4_f32 *T)
{
    float z = 0.0f;
    int c, k;
    for (c = 0; c < 4; c++)
        for (k = 0; k < 4; k++) z += T->m[c][k] - T->m[c][k];
    return (z == 0.0f) ? DH_OK : DH_ERR_OVERFLOW;
}

dh_status dh_link_f32(const dh_robot *r, uint32_t i, float q, dh_mat4_f32 *A)
{
    float v[6];
    dh_status st;
    DH_ASSERT(r != NULL);
    DH_ASSERT(A != NULL);
    if (i >= r->n || r->n > (uint32_t)DH_MAX_JOINTS || (r->flags & DH_ROBOT_HAS_F32) == 0u)
        return DH_ERR_ARG;
    st = joint_values(&r->joint[i], q, v);
    if (st == DH_OK) {
        dh_mat4_identity_f32(A);
        step(A, r, v);
    }
    return st;
}

/* T_end = last * tool when T_end is not NULL (last: frames[n-1], or T_end
 * itself); DH_ERR_OVERFLOW when the result (or, without T_end, the last
 * frame) is not finite. A non-finite chain frame always reaches T_end
 * (x*inf, x*0*inf). */
static dh_status finish(const dh_robot *r, const dh_mat4_f32 *last, dh_mat4_f32 *T_end)
{
    const dh_mat4_f32 *out = last;
    if (T_end) {
        if (r->flags & DH_ROBOT_TOOL_ID_F32) copy(T_end, last);
        else dh_mat4_mul_affine_f32(T_end, last, &r->tool);
        out = T_end;
    }
    return frame_finite(out);
}

/*
 * The chain: frames may be NULL (end frame only; T_end then not NULL),
 * T_end may be NULL. Built in frames[] or in T_end, from the base; with
 * an identity base the first link is written out, as by default. Every q
 * is checked before anything is written. The tool product (finish) is
 * dh_mat4_mul_affine_f32: the same operations in the same order as the
 * default build's row-by-row product.
 */
static FK_NOINLINE dh_status fk_f32(const dh_robot *r, const float *q, dh_mat4_f32 *frames, dh_mat4_f32 *T_end)
{
    const dh_mat4_f32 *src = &r->base;
    dh_mat4_f32 *dst = T_end;
    uint32_t i;
    dh_status st;
    DH_ASSERT(r != NULL);
    DH_ASSERT(q != NULL);
    if (r->n == 0u || r->n > (uint32_t)DH_MAX_JOINTS || (r->flags & DH_ROBOT_HAS_F32) == 0u)
        return DH_ERR_ARG;
    for (i = 0u; i < r->n; i++) {
        st = joint_values(&r->joint[i], q[i], NULL);
        if (st != DH_OK) return st;
    }
    for (i = 0u; i < r->n; i++) {
        float v[6];
        const dh_joint *j = &r->joint[i];
        if (frames) dst = &frames[i];
        /* DH_OK: q[i] passed the loop above */
        if (joint_values(j, q[i], v) == DH_OK) {
            copy(dst, src);
            step(dst, r, v);
        }
        src = dst;
    }
    return DH_OK;
}

/* The chain, then the tool and the finiteness test: called one after the
 * other, so the frames of fk_f32 and of the tool product are never on the
 * stack together (the deepest path stays within 256 bytes on M0+). */
static FK_NOINLINE dh_status fk_all(const dh_robot *r, const float *q, dh_mat4_f32 *frames, dh_mat4_f32 *T_end)
{
    dh_status st = fk_f32(r, q, frames, T_end);
    if (st != DH_OK) return st;
    return finish(r, frames ? &frames[r->n - 1u] : T_end, T_end);
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

#else /* !DH_SMALL: the code below is the default build, unchanged */

/* One joint, in place: T = T * A on the first FK_ROWS rows. Single
 * pointer, each row read completely before it is written, so the compiler
 * sees the exact (zero-distance) dependences and may vectorise over rows. */
static void step_std(dh_mat4_f32 *T, float st, float ct, float sa, float ca, float a, float d)
{
    int k;
    for (k = 0; k < FK_ROWS; k++) {
        float nx = T->m[0][k], ox = T->m[1][k], ax = T->m[2][k], px = T->m[3][k];
        float n1 = ct * nx + st * ox;
        float u = ct * ox - st * nx;
        T->m[3][k] = px + d * ax + a * n1;
        T->m[0][k] = n1;
        T->m[1][k] = ca * u + sa * ax;
        T->m[2][k] = ca * ax - sa * u;
    }
}

static void step_mod(dh_mat4_f32 *T, float st, float ct, float sa, float ca, float a, float d)
{
    int k;
    for (k = 0; k < FK_ROWS; k++) {
        float nx = T->m[0][k], ox = T->m[1][k], ax = T->m[2][k], px = T->m[3][k];
        float o1 = ca * ox + sa * ax;
        float a1 = ca * ax - sa * ox;
        T->m[3][k] = px + a * nx + d * a1;
        T->m[0][k] = ct * nx + st * o1;
        T->m[1][k] = ct * o1 - st * nx;
        T->m[2][k] = a1;
    }
}

/* The link matrix itself (what a step applied to the identity gives).
 * Out of line: its many live products would otherwise sit in the frame of
 * dh_link_f32 while dh_sincos_f32 runs (the Jacobian calls dh_link_f32 per
 * joint, so that frame is on its deepest path). */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((noinline))
#endif
static void link_direct(dh_mat4_f32 *A, dh_convention conv, const dh_joint *j, const float v[3])
{
    /* v = (sin theta, cos theta, d) from joint_values; four arguments, so
     * all in registers (no outgoing stack arguments in the callers) */
    const float st = v[0], ct = v[1], d = v[2], sa = j->sa, ca = j->ca, a = j->a;
    if (conv == DH_CONV_STANDARD) {
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
    A->m[0][3] = 0.0f;
    A->m[1][3] = 0.0f;
    A->m[2][3] = 0.0f;
    A->m[3][3] = 1.0f;
}

/* v = (sin theta, cos theta, d) of joint j at value q (q and the sum
 * already known finite). */
static void joint_values(const dh_joint *j, float q, float v[3])
{
    if (j->type == DH_JOINT_REVOLUTE) {
        (void)dh_sincos_f32(q + j->theta_deg, &v[0], &v[1]);
        v[2] = j->d;
    } else {
        (void)dh_sincos_f32(j->theta_deg, &v[0], &v[1]);
        v[2] = q + j->d;
    }
}

/* DH_OK when every joint value and its sum with the offset is finite;
 * DH_ERR_NAN for a non-finite q (checked first per joint), DH_ERR_OVERFLOW
 * when q + offset overflows. */
static dh_status check_q(const dh_robot *r, const float *q)
{
    uint32_t i;
    for (i = 0u; i < r->n; i++) {
        const dh_joint *j = &r->joint[i];
        float off = (j->type == DH_JOINT_REVOLUTE) ? j->theta_deg : j->d;
        if (!is_finite(q[i])) return DH_ERR_NAN;
        if (!is_finite(q[i] + off)) return DH_ERR_OVERFLOW;
    }
    return DH_OK;
}

static void set_bottom(dh_mat4_f32 *T)
{
    T->m[0][3] = 0.0f;
    T->m[1][3] = 0.0f;
    T->m[2][3] = 0.0f;
    T->m[3][3] = 1.0f;
}

/* out = A * B for affine frames (bottom rows taken as 0 0 0 1), row by row:
 * out may be A (each row of A is read before it is written), not B. The
 * same operations in the same order as a separate product. */
static void mul_affine(dh_mat4_f32 *out, const dh_mat4_f32 *A, const dh_mat4_f32 *B)
{
    int c, k;
    for (k = 0; k < 3; k++) {
        float r0 = A->m[0][k], r1 = A->m[1][k], r2 = A->m[2][k], r3 = A->m[3][k];
        for (c = 0; c < 3; c++)
            out->m[c][k] = r0 * B->m[c][0] + r1 * B->m[c][1] + r2 * B->m[c][2];
        out->m[3][k] = (r0 * B->m[3][0] + r1 * B->m[3][1] + r2 * B->m[3][2]) + r3;
    }
    set_bottom(out);
}

/* 1 when the 3x4 part of T is finite. x - x is 0 for a finite x and NaN
 * for an infinity or a NaN, and NaN propagates through the sums: one
 * branch instead of twelve. One accumulator per row, in scalars (no array
 * in memory); with FK_ROWS == 4 the bottom row (finite: set_bottom() has
 * run) makes the four sums one vector. */
static int frame_finite(const dh_mat4_f32 *T)
{
    float z0 = T->m[0][0] - T->m[0][0], z1 = T->m[0][1] - T->m[0][1], z2 = T->m[0][2] - T->m[0][2];
#if FK_ROWS == 4
    float z3 = T->m[0][3] - T->m[0][3];
#endif
    int c;
    for (c = 1; c < 4; c++) {
        z0 += T->m[c][0] - T->m[c][0];
        z1 += T->m[c][1] - T->m[c][1];
        z2 += T->m[c][2] - T->m[c][2];
#if FK_ROWS == 4
        z3 += T->m[c][3] - T->m[c][3];
#endif
    }
#if FK_ROWS == 4
    z0 += z3;
#endif
    return (z0 + z1) + z2 == 0.0f;
}

dh_status dh_link_f32(const dh_robot *r, uint32_t i, float q, dh_mat4_f32 *A)
{
    const dh_joint *j;
    float v[3];
    DH_ASSERT(r != NULL);
    DH_ASSERT(A != NULL);
    if (i >= r->n || r->n > (uint32_t)DH_MAX_JOINTS || (r->flags & DH_ROBOT_HAS_F32) == 0u)
        return DH_ERR_ARG;
    j = &r->joint[i];
    {
        float off = (j->type == DH_JOINT_REVOLUTE) ? j->theta_deg : j->d;
        if (!is_finite(q)) return DH_ERR_NAN;
        if (!is_finite(q + off)) return DH_ERR_OVERFLOW;
    }
    joint_values(j, q, v);
    link_direct(A, r->conv, j, v);
    return DH_OK;
}

/* Shared body: frames may be NULL (end frame only; T_end then not NULL),
 * T_end may be NULL. The chain is built in frames[] or in T_end. */
static dh_status fk_f32(const dh_robot *r, const float *q, dh_mat4_f32 *frames, dh_mat4_f32 *T_end)
{
    const dh_mat4_f32 *src;
    dh_mat4_f32 *dst;
    uint32_t i = 0u;
    dh_status st;
    DH_ASSERT(r != NULL);
    DH_ASSERT(q != NULL);
    if (r->n == 0u || r->n > (uint32_t)DH_MAX_JOINTS || (r->flags & DH_ROBOT_HAS_F32) == 0u)
        return DH_ERR_ARG;
    st = check_q(r, q);
    if (st != DH_OK) return st;

    dst = frames ? &frames[0] : T_end;
    if (r->flags & DH_ROBOT_BASE_ID_F32) {
        float v[3];
        const dh_joint *j = &r->joint[0];
        joint_values(j, q[0], v);
        link_direct(dst, r->conv, j, v);
        src = dst;
        i = 1u;
    } else {
        src = &r->base;
    }
    if (r->conv == DH_CONV_STANDARD) {
        for (; i < r->n; i++) {
            float v[3];
            const dh_joint *j = &r->joint[i];
            if (frames) dst = &frames[i];
            if (dst != src) *dst = *src;
            joint_values(j, q[i], v);
            step_std(dst, v[0], v[1], j->sa, j->ca, j->a, v[2]);
            src = dst;
        }
    } else {
        for (; i < r->n; i++) {
            float v[3];
            const dh_joint *j = &r->joint[i];
            if (frames) dst = &frames[i];
            if (dst != src) *dst = *src;
            joint_values(j, q[i], v);
            step_mod(dst, v[0], v[1], j->sa, j->ca, j->a, v[2]);
            src = dst;
        }
    }
    if (frames) {
        for (i = 0u; i < r->n; i++) set_bottom(&frames[i]);
        if (T_end == NULL) return frame_finite(dst) ? DH_OK : DH_ERR_OVERFLOW;
    }
    /* dst: the last chain frame (frames[n-1], or T_end itself) */
    if (r->flags & DH_ROBOT_TOOL_ID_F32) {
        if (dst != T_end) *T_end = *dst;
        set_bottom(T_end);
    } else {
        mul_affine(T_end, dst, &r->tool);
    }
    /* a non-finite chain frame always reaches T_end (x*inf, x*0*inf) */
    return frame_finite(T_end) ? DH_OK : DH_ERR_OVERFLOW;
}

dh_status dh_fk_f32(const dh_robot *r, const float *q, dh_mat4_f32 *T)
{
    DH_ASSERT(T != NULL);
    return fk_f32(r, q, NULL, T);
}

dh_status dh_fk_frames_f32(const dh_robot *r, const float *q, dh_mat4_f32 *frames, dh_mat4_f32 *T_end)
{
    DH_ASSERT(frames != NULL);
    return fk_f32(r, q, frames, T_end);
}

#endif /* DH_SMALL */
