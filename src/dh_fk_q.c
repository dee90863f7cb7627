/*
 * dh_fk_q.c - fixed-point forward kinematics (integer only: no float, no
 * libm, no 64-bit division; checked with arm-none-eabi-nm).
 *
 * Formats: rotation entries Q2.30, positions dh_qpos (DH_QPOS_FRAC fraction
 * bits), angles dh_q16 degrees. The link update is the same as the float
 * one (see dh_fk_f32.c); every output entry is one or two 32x32->64
 * products summed exactly in 64 bits and rounded once (half up), then
 * saturated.
 *
 * Overflow analysis. Every product is x*y with |x| <= 2^31 and
 * |y| <= 2^31 - 1: rotation entries (any int32) meet sines, cosines
 * (|.| <= 2^30) or lengths, and lengths a, d are used with INT32_MIN raised
 * to -INT32_MAX (one LSB, documented saturation). So each product is below
 * 2^62 in magnitude and a sum or difference of two of them is below 2^63:
 * the two-term sums cannot wrap. Three-term sums (tool product) halve each
 * product first (error 2^-61 relative, far below one LSB). Rounding adds
 * 2^29 to a value below 2^63 - 2^32: no wrap either. Negations go through
 * neg() (INT32_MIN saturates).
 */
#include "dhmath/dh_robot.h"
#include "dhmath/dh_trig.h"
#include "dh_port.h"

/* The four step variants stay separate functions: inlined together into
 * fk_q they would not share stack slots (over 1 KB on Cortex-M0 at -O2). */
#if defined(__GNUC__) || defined(__clang__)
#define FKQ_NOINLINE __attribute__((noinline))
#else
#define FKQ_NOINLINE
#endif

#define MUL(a, b) dh_port_smull((a), (b))
#define MLA(acc, a, b) dh_port_smlal((acc), (a), (b))
#define HALF29 ((int64_t)1 << 29)
#define HALF28 ((int64_t)1 << 28)

/* 360 degrees in Q16.16 times 182: the largest multiple of a full turn
 * below 2^32, used to bring q + offset back into the int32 range exactly. */
#define TURNS_182 ((int64_t)4293918720)

/*
 * Round x / 2^30 to nearest (half up) into int32, saturating and setting
 * *ovf. t >> 30 fits in int32 iff the high word of t lies in
 * [-2^29, 2^29), which is one add and one unsigned compare on the high
 * register; the result is then the low word shifted and or-ed (the uint32
 * -> int32 conversion wraps, checked in dh_port.h).
 */
static inline int32_t rnd30(int64_t x, int *ovf)
{
    int64_t t = x + HALF29;
    int32_t hi = (int32_t)(t >> 32);
    if ((uint32_t)hi + 0x20000000u >= 0x40000000u) {
        *ovf = 1;
        return (hi < 0) ? INT32_MIN : INT32_MAX;
    }
    /* bits 30..61 of t, composed from the two words (the uint32 -> int32
     * conversion wraps, checked in dh_port.h); written this way the
     * compiler keeps a 32-bit value and the next product stays one SMULL */
    return (int32_t)(((uint32_t)t >> 30) | ((uint32_t)hi << 2));
}

/*
 * Same rounding without the range check, for robots whose base rotation
 * rows have norm <= 1.5 (DH_ROBOT_BASE_SMALL_Q). Each joint multiplies the
 * rows of the rotation by Rz(theta) Rx(alpha) built from sines and cosines
 * with |s|, |c| <= 2^30 and s^2 + c^2 <= 1 + 2^-28 (dh_trig.h: error
 * <= 1.05 LSB), so a row norm grows at most by (1 + 2^-27) plus 1 LSB per
 * joint: after DH_MAX_JOINTS <= 32 joints every entry and every two-term
 * combination of a row is below 1.5001 < 2 and cannot leave Q2.30.
 */
static inline int32_t rnd30_nc(int64_t x, int *ovf)
{
    int64_t t = x + HALF29;
    (void)ovf;
    return (int32_t)(((uint32_t)t >> 30) | ((uint32_t)(int32_t)(t >> 32) << 2));
}

/* p + round(x / 2^30), saturated to int32 (x: lengths times Q2.30). */
static inline int32_t pos(int32_t p, int64_t x, int *ovf)
{
    int64_t v = (int64_t)p + ((x + HALF29) >> 30);
    if (v > INT32_MAX) {
        *ovf = 1;
        return INT32_MAX;
    }
    if (v < INT32_MIN) {
        *ovf = 1;
        return INT32_MIN;
    }
    return (int32_t)v;
}

/* -x, saturating INT32_MIN to INT32_MAX. */
static inline int32_t neg(int32_t x, int *ovf)
{
    if (x == INT32_MIN) {
        *ovf = 1;
        return INT32_MAX;
    }
    return -x;
}

/* Length operand: INT32_MIN raised to -INT32_MAX (see the overflow note). */
static inline int32_t len(int32_t x)
{
    return (x == INT32_MIN) ? -INT32_MAX : x;
}

/* Sum of halved products rounded at bit 29 (three-term sums). */
static int32_t rot_h(int64_t x, int *ovf)
{
    int64_t v = (x + HALF28) >> 29;
    if (v > INT32_MAX) {
        *ovf = 1;
        return INT32_MAX;
    }
    if (v < INT32_MIN) {
        *ovf = 1;
        return INT32_MIN;
    }
    return (int32_t)v;
}

static int32_t pos_h(int32_t p, int64_t x, int *ovf)
{
    int64_t v = (int64_t)p + ((x + HALF28) >> 29);
    if (v > INT32_MAX) {
        *ovf = 1;
        return INT32_MAX;
    }
    if (v < INT32_MIN) {
        *ovf = 1;
        return INT32_MIN;
    }
    return (int32_t)v;
}

/* theta = q + offset in Q16.16 degrees, reduced by whole turns into int32
 * when the sum leaves it (exact: the sine and cosine do not change). */
static inline dh_q16 add_angle(int32_t q, dh_q16 off)
{
    int64_t t = (int64_t)q + (int64_t)off;
    if (t > INT32_MAX) t -= TURNS_182;
    else if (t < INT32_MIN) t += TURNS_182;
    return (dh_q16)t;
}

/* Joint values: sin/cos(theta) and d (never INT32_MIN); sets *ovf when
 * d + q saturates. */
static void joint_values(const dh_joint *j, int32_t q, dh_q30 *st, dh_q30 *ct, dh_qpos *d, int *ovf)
{
    if (j->type == DH_JOINT_REVOLUTE) {
        dh_sincos_q(add_angle(q, j->theta_q), st, ct);
        *d = len(j->d_q);
    } else {
        int64_t v = (int64_t)q + (int64_t)j->d_q;
        dh_sincos_q(j->theta_q, st, ct);
        if (v > INT32_MAX) {
            *ovf = 1;
            v = INT32_MAX;
        } else if (v < -(int64_t)INT32_MAX) {
            *ovf = (v < INT32_MIN) ? 1 : *ovf;
            v = -(int64_t)INT32_MAX;
        }
        *d = (dh_qpos)v;
    }
}

/*
 * The x-twist by alpha applied to a pair (y, z) of one row:
 * y' = ca y + sa z, z' = ca z - sa y. alpha of 0, +-90 and 180 degrees
 * (exact 0 / +-1 from the table) take the multiplication-free branch,
 * which gives the same values as the general one.
 */
#define TWIST_ONE 0
#define TWIST_P90 1
#define TWIST_M90 2
#define TWIST_180 3
#define TWIST_GEN 4

static inline int twist_kind(dh_q30 sa, dh_q30 ca)
{
    if (sa == 0 && ca == DH_Q30_ONE) return TWIST_ONE;
    if (sa == DH_Q30_ONE && ca == 0) return TWIST_P90;
    if (sa == -DH_Q30_ONE && ca == 0) return TWIST_M90;
    if (sa == 0 && ca == -DH_Q30_ONE) return TWIST_180;
    return TWIST_GEN;
}

#define TWIST(kind, sa, ca, y, z, y2, z2, ovf, RND) do { \
    switch (kind) { \
    case TWIST_ONE: (y2) = (y); (z2) = (z); break; \
    case TWIST_P90: (y2) = (z); (z2) = neg((y), (ovf)); break; \
    case TWIST_M90: (y2) = neg((z), (ovf)); (z2) = (y); break; \
    case TWIST_180: (y2) = neg((y), (ovf)); (z2) = neg((z), (ovf)); break; \
    default: \
        (y2) = RND(MLA(MUL((ca), (y)), (sa), (z)), (ovf)); \
        (z2) = RND(MUL((ca), (z)) - MUL((sa), (y)), (ovf)); \
        break; \
    } } while (0)

/* Standard DH joint applied in place: T <- T * Rz(theta) Tz(d) Tx(a) Rx(alpha).
 * Generated twice: with range-checked rotation rounding and without it
 * (see rnd30_nc for when that is safe). */
#define DEF_STEP_STD(name, RND) \
static FKQ_NOINLINE void name(dh_frame_q *T, dh_q30 st, dh_q30 ct, const dh_joint *j, dh_qpos d, int *ovf) \
{ \
    const dh_q30 sa = j->sa_q, ca = j->ca_q; \
    const dh_qpos a = len(j->a_q); \
    const int kind = twist_kind(sa, ca); \
    int k; \
    for (k = 0; k < 3; k++) { \
        int32_t nx = T->r[0][k], ox = T->r[1][k], ax = T->r[2][k]; \
        int32_t n1 = RND(MLA(MUL(ct, nx), st, ox), ovf); \
        int32_t u = RND(MUL(ct, ox) - MUL(st, nx), ovf); \
        int32_t o2, a2; \
        int64_t dp = 0; \
        if (d != 0) dp = MUL(d, ax); \
        if (a != 0) dp += MUL(a, n1); \
        T->p[k] = pos(T->p[k], dp, ovf); \
        TWIST(kind, sa, ca, u, ax, o2, a2, ovf, RND); \
        T->r[0][k] = n1; \
        T->r[1][k] = o2; \
        T->r[2][k] = a2; \
    } \
}

/* Modified DH joint in place: T <- T * Rx(alpha) Tx(a) Rz(theta) Tz(d). */
#define DEF_STEP_MOD(name, RND) \
static FKQ_NOINLINE void name(dh_frame_q *T, dh_q30 st, dh_q30 ct, const dh_joint *j, dh_qpos d, int *ovf) \
{ \
    const dh_q30 sa = j->sa_q, ca = j->ca_q; \
    const dh_qpos a = len(j->a_q); \
    const int kind = twist_kind(sa, ca); \
    int k; \
    for (k = 0; k < 3; k++) { \
        int32_t nx = T->r[0][k], ox = T->r[1][k], ax = T->r[2][k], o1, a1; \
        int64_t dp = 0; \
        TWIST(kind, sa, ca, ox, ax, o1, a1, ovf, RND); \
        if (a != 0) dp = MUL(a, nx); \
        if (d != 0) dp += MUL(d, a1); \
        T->p[k] = pos(T->p[k], dp, ovf); \
        T->r[0][k] = RND(MLA(MUL(ct, nx), st, o1), ovf); \
        T->r[1][k] = RND(MUL(ct, o1) - MUL(st, nx), ovf); \
        T->r[2][k] = a1; \
    } \
}

DEF_STEP_STD(step_std, rnd30)
DEF_STEP_STD(step_std_nc, rnd30_nc)
DEF_STEP_MOD(step_mod, rnd30)
DEF_STEP_MOD(step_mod_nc, rnd30_nc)

/* The link matrix of joint j (a step applied to the identity, written out). */
static FKQ_NOINLINE void link_direct(dh_frame_q *A, dh_convention conv, dh_q30 st, dh_q30 ct, const dh_joint *j,
                        dh_qpos d, int *ovf)
{
    dh_q30 sa = j->sa_q, ca = j->ca_q;
    if (conv == DH_CONV_STANDARD) {
        /* n = (ct, st, 0), o = ca u + sa z, a = ca z - sa u with u = (-st, ct, 0) */
        A->r[0][0] = ct;
        A->r[0][1] = st;
        A->r[0][2] = 0;
        A->r[1][0] = rnd30(-MUL(ca, st), ovf);
        A->r[1][1] = rnd30(MUL(ca, ct), ovf);
        A->r[1][2] = sa;
        A->r[2][0] = rnd30(MUL(sa, st), ovf);
        A->r[2][1] = rnd30(-MUL(sa, ct), ovf);
        A->r[2][2] = ca;
        A->p[0] = pos(0, MUL(j->a_q, ct), ovf);
        A->p[1] = pos(0, MUL(j->a_q, st), ovf);
        A->p[2] = d;
    } else {
        /* n = (ct, st ca, st sa), o = (-st, ct ca, ct sa), a = (0, -sa, ca),
         * p = (a, -sa d, ca d) */
        A->r[0][0] = ct;
        A->r[0][1] = rnd30(MUL(st, ca), ovf);
        A->r[0][2] = rnd30(MUL(st, sa), ovf);
        A->r[1][0] = -st;
        A->r[1][1] = rnd30(MUL(ct, ca), ovf);
        A->r[1][2] = rnd30(MUL(ct, sa), ovf);
        A->r[2][0] = 0;
        A->r[2][1] = -sa;
        A->r[2][2] = ca;
        A->p[0] = j->a_q;
        A->p[1] = pos(0, -MUL(sa, d), ovf);
        A->p[2] = pos(0, MUL(ca, d), ovf);
    }
}

/* out = A * B (out must not alias A or B); three-term sums with halved products. */
static FKQ_NOINLINE void mul_frame(dh_frame_q *out, const dh_frame_q *A, const dh_frame_q *B, int *ovf)
{
    int c, k;
    for (k = 0; k < 3; k++) {
        int32_t a0 = A->r[0][k], a1 = A->r[1][k], a2 = A->r[2][k];
        for (c = 0; c < 3; c++)
            out->r[c][k] = rot_h((MUL(a0, B->r[c][0]) >> 1) + (MUL(a1, B->r[c][1]) >> 1) +
                                     (MUL(a2, B->r[c][2]) >> 1),
                                 ovf);
        out->p[k] = pos_h(A->p[k], (MUL(a0, B->p[0]) >> 1) + (MUL(a1, B->p[1]) >> 1) +
                                       (MUL(a2, B->p[2]) >> 1),
                          ovf);
    }
}

dh_status dh_link_q(const dh_robot *r, uint32_t i, int32_t q, dh_frame_q *A)
{
    dh_q30 st, ct;
    dh_qpos d;
    int ovf = 0;
    DH_ASSERT(r != NULL);
    DH_ASSERT(A != NULL);
    if (i >= r->n || r->n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    if ((r->flags & DH_ROBOT_HAS_Q) == 0u) return DH_ERR_OVERFLOW;
    joint_values(&r->joint[i], q, &st, &ct, &d, &ovf);
    link_direct(A, r->conv, st, ct, &r->joint[i], d, &ovf);
    return ovf ? DH_ERR_OVERFLOW : DH_OK;
}

static dh_status fk_q(const dh_robot *r, const int32_t *q, dh_frame_q *frames, dh_frame_q *T_end)
{
    dh_frame_q acc;
    uint32_t i = 0u;
    int ovf = 0, small;
    DH_ASSERT(r != NULL);
    DH_ASSERT(q != NULL);
    small = (r->flags & DH_ROBOT_BASE_SMALL_Q) != 0u;
    if (r->n == 0u || r->n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    if ((r->flags & DH_ROBOT_HAS_Q) == 0u) return DH_ERR_OVERFLOW;

    if (r->flags & DH_ROBOT_BASE_ID_Q) {
        dh_q30 st, ct;
        dh_qpos d;
        joint_values(&r->joint[0], q[0], &st, &ct, &d, &ovf);
        link_direct(&acc, r->conv, st, ct, &r->joint[0], d, &ovf);
        if (frames) frames[0] = acc;
        i = 1u;
    } else {
        acc = r->base_q;
    }
    for (; i < r->n; i++) {
        dh_q30 st, ct;
        dh_qpos d;
        const dh_joint *j = &r->joint[i];
        joint_values(j, q[i], &st, &ct, &d, &ovf);
        if (small) {
            if (r->conv == DH_CONV_STANDARD) step_std_nc(&acc, st, ct, j, d, &ovf);
            else step_mod_nc(&acc, st, ct, j, d, &ovf);
        } else {
            if (r->conv == DH_CONV_STANDARD) step_std(&acc, st, ct, j, d, &ovf);
            else step_mod(&acc, st, ct, j, d, &ovf);
        }
        if (frames) frames[i] = acc;
    }
    if (T_end) {
        if (r->flags & DH_ROBOT_TOOL_ID_Q) *T_end = acc;
        else mul_frame(T_end, &acc, &r->tool_q, &ovf);
    }
    return ovf ? DH_ERR_OVERFLOW : DH_OK;
}

dh_status dh_fk_q(const dh_robot *r, const int32_t *q, dh_frame_q *T)
{
    DH_ASSERT(T != NULL);
    return fk_q(r, q, NULL, T);
}

dh_status dh_fk_frames_q(const dh_robot *r, const int32_t *q, dh_frame_q *frames, dh_frame_q *T_end)
{
    DH_ASSERT(frames != NULL);
    return fk_q(r, q, frames, T_end);
}
