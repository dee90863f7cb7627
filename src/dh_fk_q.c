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
 * Overflow analysis. Rotation entries are kept symmetric, in
 * [-INT32_MAX, INT32_MAX] (saturation is symmetric and the setters raise
 * INT32_MIN), so every product x*y with x a rotation entry and |y| <= 2^31
 * is below 2^62 in magnitude and a sum or difference of two of them is below
 * 2^63: the two-term sums cannot wrap. Three-term sums (tool product) halve
 * each product first (error 2^-61 relative, far below one LSB). Rounding
 * adds 2^29 to a value below 2^63 - 2^32: no wrap either.
 */
#include "dhmath/dh_robot.h"
#include "dhmath/dh_trig.h"
#include "dh_port.h"

#define MUL(a, b) dh_port_smull((a), (b))
#define HALF29 ((int64_t)1 << 29)
#define HALF28 ((int64_t)1 << 28)

/* 360 degrees in Q16.16 times 182: the largest multiple of a full turn
 * below 2^32, used to bring q + offset back into the int32 range exactly. */
#define TURNS_182 ((int64_t)4293918720)

/* Round a Q60 sum to Q30, saturate symmetrically. */
static int32_t rot(int64_t x, int *ovf)
{
    int64_t v = (x + HALF29) >> 30;
    if (v > INT32_MAX) {
        *ovf = 1;
        return INT32_MAX;
    }
    if (v < -(int64_t)INT32_MAX) {
        *ovf = 1;
        return -INT32_MAX;
    }
    return (int32_t)v;
}

/* p + round(x / 2^30), saturated to int32 (x: lengths times Q2.30). */
static int32_t pos(int32_t p, int64_t x, int *ovf)
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

/* Same for a sum of halved products (round at bit 29). */
static int32_t rot_h(int64_t x, int *ovf)
{
    int64_t v = (x + HALF28) >> 29;
    if (v > INT32_MAX) {
        *ovf = 1;
        return INT32_MAX;
    }
    if (v < -(int64_t)INT32_MAX) {
        *ovf = 1;
        return -INT32_MAX;
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
static dh_q16 add_angle(int32_t q, dh_q16 off)
{
    int64_t t = (int64_t)q + (int64_t)off;
    if (t > INT32_MAX) t -= TURNS_182;
    else if (t < INT32_MIN) t += TURNS_182;
    return (dh_q16)t;
}

/* Joint values: sin/cos(theta) and d; sets *ovf when d + q saturates. */
static void joint_values(const dh_joint *j, int32_t q, dh_q30 *st, dh_q30 *ct, dh_qpos *d, int *ovf)
{
    if (j->type == DH_JOINT_REVOLUTE) {
        dh_sincos_q(add_angle(q, j->theta_q), st, ct);
        *d = j->d_q;
    } else {
        int64_t v = (int64_t)q + (int64_t)j->d_q;
        dh_sincos_q(j->theta_q, st, ct);
        if (v > INT32_MAX) {
            *ovf = 1;
            v = INT32_MAX;
        } else if (v < INT32_MIN) {
            *ovf = 1;
            v = INT32_MIN;
        }
        *d = (dh_qpos)v;
    }
}

/*
 * The x-twist applied to a pair of columns (y, z) of a frame, per row:
 * y' = ca y + sa z, z' = ca z - sa y. alpha of 0, +-90 and 180 degrees
 * (exact 0 / +-1 from the table) take the multiplication-free branch,
 * which gives bit-identical results to the general one.
 */
#define TWIST_ONE 0
#define TWIST_P90 1
#define TWIST_M90 2
#define TWIST_180 3
#define TWIST_GEN 4

static int twist_kind(dh_q30 sa, dh_q30 ca)
{
    if (sa == 0 && ca == DH_Q30_ONE) return TWIST_ONE;
    if (sa == DH_Q30_ONE && ca == 0) return TWIST_P90;
    if (sa == -DH_Q30_ONE && ca == 0) return TWIST_M90;
    if (sa == 0 && ca == -DH_Q30_ONE) return TWIST_180;
    return TWIST_GEN;
}

static void twist(int kind, dh_q30 sa, dh_q30 ca, int32_t y, int32_t z, int32_t *y2, int32_t *z2,
                  int *ovf)
{
    switch (kind) {
    case TWIST_ONE: *y2 = y; *z2 = z; break;
    case TWIST_P90: *y2 = z; *z2 = -y; break;
    case TWIST_M90: *y2 = -z; *z2 = y; break;
    case TWIST_180: *y2 = -y; *z2 = -z; break;
    default:
        *y2 = rot(MUL(ca, y) + MUL(sa, z), ovf);
        *z2 = rot(MUL(ca, z) - MUL(sa, y), ovf);
        break;
    }
}

/* Standard DH joint applied in place: T <- T * Rz(theta) Tz(d) Tx(a) Rx(alpha). */
static void step_std(dh_frame_q *T, dh_q30 st, dh_q30 ct, const dh_joint *j, dh_qpos d, int *ovf)
{
    int k, kind = twist_kind(j->sa_q, j->ca_q);
    for (k = 0; k < 3; k++) {
        int32_t nx = T->r[0][k], ox = T->r[1][k], ax = T->r[2][k];
        int32_t n1 = rot(MUL(ct, nx) + MUL(st, ox), ovf);
        int32_t u = rot(MUL(ct, ox) - MUL(st, nx), ovf);
        T->p[k] = pos(T->p[k], MUL(d, ax) + MUL(j->a_q, n1), ovf);
        T->r[0][k] = n1;
        twist(kind, j->sa_q, j->ca_q, u, ax, &T->r[1][k], &T->r[2][k], ovf);
    }
}

/* Modified DH joint in place: T <- T * Rx(alpha) Tx(a) Rz(theta) Tz(d). */
static void step_mod(dh_frame_q *T, dh_q30 st, dh_q30 ct, const dh_joint *j, dh_qpos d, int *ovf)
{
    int k, kind = twist_kind(j->sa_q, j->ca_q);
    for (k = 0; k < 3; k++) {
        int32_t nx = T->r[0][k], o1, a1;
        twist(kind, j->sa_q, j->ca_q, T->r[1][k], T->r[2][k], &o1, &a1, ovf);
        T->p[k] = pos(T->p[k], MUL(j->a_q, nx) + MUL(d, a1), ovf);
        T->r[0][k] = rot(MUL(ct, nx) + MUL(st, o1), ovf);
        T->r[1][k] = rot(MUL(ct, o1) - MUL(st, nx), ovf);
        T->r[2][k] = a1;
    }
}

/* The link matrix of joint j (a step applied to the identity, written out). */
static void link_direct(dh_frame_q *A, dh_convention conv, dh_q30 st, dh_q30 ct, const dh_joint *j,
                        dh_qpos d, int *ovf)
{
    dh_q30 sa = j->sa_q, ca = j->ca_q;
    if (conv == DH_CONV_STANDARD) {
        /* n = (ct, st, 0), o = ca u + sa z, a = ca z - sa u with u = (-st, ct, 0) */
        A->r[0][0] = ct;
        A->r[0][1] = st;
        A->r[0][2] = 0;
        A->r[1][0] = rot(-MUL(ca, st), ovf);
        A->r[1][1] = rot(MUL(ca, ct), ovf);
        A->r[1][2] = sa;
        A->r[2][0] = rot(MUL(sa, st), ovf);
        A->r[2][1] = rot(-MUL(sa, ct), ovf);
        A->r[2][2] = ca;
        A->p[0] = pos(0, MUL(j->a_q, ct), ovf);
        A->p[1] = pos(0, MUL(j->a_q, st), ovf);
        A->p[2] = d;
    } else {
        /* n = (ct, st ca, st sa), o = (-st, ct ca, ct sa), a = (0, -sa, ca),
         * p = (a, -sa d, ca d) */
        A->r[0][0] = ct;
        A->r[0][1] = rot(MUL(st, ca), ovf);
        A->r[0][2] = rot(MUL(st, sa), ovf);
        A->r[1][0] = -st;
        A->r[1][1] = rot(MUL(ct, ca), ovf);
        A->r[1][2] = rot(MUL(ct, sa), ovf);
        A->r[2][0] = 0;
        A->r[2][1] = -sa;
        A->r[2][2] = ca;
        A->p[0] = j->a_q;
        A->p[1] = pos(0, -MUL(sa, d), ovf);
        A->p[2] = pos(0, MUL(ca, d), ovf);
    }
}

/* out = A * B (out must not alias A or B); three-term sums with halved products. */
static void mul_frame(dh_frame_q *out, const dh_frame_q *A, const dh_frame_q *B, int *ovf)
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
    if (i >= r->n) return DH_ERR_ARG;
    if ((r->flags & DH_ROBOT_HAS_Q) == 0u) return DH_ERR_OVERFLOW;
    joint_values(&r->joint[i], q, &st, &ct, &d, &ovf);
    link_direct(A, r->conv, st, ct, &r->joint[i], d, &ovf);
    return ovf ? DH_ERR_OVERFLOW : DH_OK;
}

static dh_status fk_q(const dh_robot *r, const int32_t *q, dh_frame_q *frames, dh_frame_q *T_end)
{
    dh_frame_q acc;
    uint32_t i = 0u;
    int ovf = 0;
    DH_ASSERT(r != NULL);
    DH_ASSERT(q != NULL);
    if (r->n == 0u) return DH_ERR_ARG;
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
        if (r->conv == DH_CONV_STANDARD) step_std(&acc, st, ct, j, d, &ovf);
        else step_mod(&acc, st, ct, j, d, &ovf);
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
