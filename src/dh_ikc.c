/*
 * dh_ikc.c - closed-form inverse kinematics, float: the front end (model,
 * canonical chain, target checks, offsets, 360-degree shifts, limits) and
 * the spherical-wrist families DH_IKC_WRIST_RRR (Puma 560, KUKA KR5, ABB
 * IRB140) and DH_IKC_WRIST_RRP (Stanford arm). The method follows Paul
 * 1981 ch. 3 (the arm positions the wrist centre, the wrist the
 * orientation); derivations: docs/design.md ("Closed-form inverse
 * kinematics").
 *
 * Canonical chain (dh_ikc_impl.h): standard DH joints with an MDH robot's
 * first Rx(alpha_0) Tx(a_0) moved into pre; T06 = pre^-1 T post^-1, the
 * products with an identity pre or post skipped.
 *
 * Stack: the front end keeps T06 (64 B); the family solvers keep one 3x3
 * and a few scalars and write their raw solutions straight into sol.
 */
#include "dhmath/dh_ikc.h"
#include "dhmath/dh_kin.h"
#include "dhmath/dh_mat4.h"
#include "dhmath/dh_trig.h"
#include "dh_ikc_impl.h"
#include "dh_internal.h"

#include <math.h>

/* Family constants of the wrist families, m->k. */
enum {
    KW_H = 0,      /* offset of the wrist centre from the plane of axis 1 (h) */
    KW_EPS,        /* length tolerance of the branch coincidences: 5e-7 L */
    KW_HZERO,      /* 1: |h| <= KW_EPS (wrist centre can reach axis 1) */
    KW_INV45,      /* 1 / (sin alpha4 sin alpha5) */
    KW_INVSA5,     /* 1 / sin alpha5 */
    KW_ORTHO,      /* 1: cos alpha4 = cos alpha5 = 0 (flip shortcut) */
    KW_CC45,       /* cos alpha4 cos alpha5 */
    /* RRR */
    KW_PHI,        /* atan2(e, a3) in degrees, e = sin(alpha3) d4 */
    KW_A2RHO,      /* a2^2 + a3^2 + e^2 */
    KW_D,          /* 2 a2 rho */
    KW_SIGMA,      /* cos alpha2 (+-1) */
    KW_SA23,       /* sigma sin alpha3 */
    KW_CA23,       /* sigma cos alpha3 */
    KW_INV2A2,     /* 1 / (2 a2) */
    KW_CPLUS,      /* |a2| + rho: wrist centre distance from axis 2, elbow stretched */
    KW_CMINUS,     /* ||a2| - rho|: the same, elbow folded */
    /* RRP */
    KW_W,          /* a2 + a3 cos th3 + e sin th3 (th3 the fixed theta of joint 3) */
    KW_Z3C,        /* cos(alpha3) d4: z3 = d3 + KW_Z3C */
    KW_S3,         /* sin, cos of the fixed theta of joint 3 */
    KW_C3,
    KW_COUNT
};

typedef char dh_ikc_k_fits_[(KW_COUNT <= (int)DH_IKC_K) ? 1 : -1];

/* Wrist singular when axis 6 is within this angle (rad) of axis 4: the
 * orientation error of the q_ref split is at most that angle. */
#define IKC_SING_WRIST 1.5e-6f
/* Length tolerance per unit of the characteristic length L. */
#define IKC_EPS_L 5e-7f

/* ---- small helpers --------------------------------------------------------- */

/* atan2 in degrees, fallback when both arguments are zero (free angle). */
static float ikc_atan2(float y, float x, float fallback)
{
    if (y == 0.0f && x == 0.0f) return fallback;
    return dh_atan2f_deg_(y, x, 0.0f);
}

/* x reduced into (-180, 180] (|x| < 540). */
static float ikc_wrap(float x)
{
    if (x > 180.0f) x -= 360.0f;
    else if (x <= -180.0f) x += 360.0f;
    return x;
}

static int ikc_is_identity(const dh_mat4_f32 *T)
{
    uint32_t c, r;
    for (c = 0; c < 4u; c++)
        for (r = 0; r < 4u; r++)
            if (T->m[c][r] != ((c == r) ? 1.0f : 0.0f)) return 0;
    return 1;
}

/* The last three axes meet in one point: a4 = a5 = d5 = 0 and axes 4, 5
 * and 5, 6 not parallel (joints 4..6 revolute). */
static int ikc_spherical(const dh_ikc_model_f32 *m)
{
    return m->n == 6u && (m->prismatic & 0x38u) == 0u && m->a[3] == 0.0f && m->a[4] == 0.0f &&
           m->d[4] == 0.0f && m->sa[3] != 0.0f && m->sa[4] != 0.0f;
}

/* ---- analysis -------------------------------------------------------------- */

/* Canonical chain of r into m (a, d, sa, ca, off, limits, prismatic) and
 * the frame before it into *pre. */
static DH_NOINLINE void ikc_canonical(const dh_robot *r, dh_ikc_model_f32 *m, dh_mat4_f32 *pre)
{
    uint32_t i, n = r->n;
    const int mdh = (r->conv == DH_CONV_MODIFIED);
    for (i = 0; i < n; i++) {
        const dh_joint *j = &r->joint[i];
        m->d[i] = j->d;
        m->off[i] = j->theta_deg;
        m->qmin[i] = j->qmin;
        m->qmax[i] = j->qmax;
        if (j->type == DH_JOINT_PRISMATIC) m->prismatic |= 1u << i;
        if (!mdh) {
            m->a[i] = j->a;
            m->sa[i] = j->sa;
            m->ca[i] = j->ca;
        } else if (i + 1u < n) {
            m->a[i] = r->joint[i + 1u].a;
            m->sa[i] = r->joint[i + 1u].sa;
            m->ca[i] = r->joint[i + 1u].ca;
        } else {
            m->a[i] = 0.0f;
            m->sa[i] = 0.0f;
            m->ca[i] = 1.0f;
        }
    }
    *pre = r->base;
    if (mdh) {
        /* base * Rx(alpha_0) Tx(a_0) */
        dh_mat4_f32 X;
        const dh_joint *j = &r->joint[0];
        dh_mat4_identity_f32(&X);
        X.m[1][1] = j->ca;
        X.m[1][2] = j->sa;
        X.m[2][1] = -j->sa;
        X.m[2][2] = j->ca;
        X.m[3][0] = j->a;
        dh_mat4_postmul_f32(pre, &X);
    }
}

/* Inverse of a frame (identity kept exact). */
static dh_status ikc_inverse(const dh_mat4_f32 *F, dh_mat4_f32 *out)
{
    if (ikc_is_identity(F)) {
        dh_mat4_identity_f32(out);
        return DH_OK;
    }
    return dh_mat4_inv_f32(F, out);
}

/* Why the canonical chain of m has no closed form (every detector said no). */
static dh_ikc_why ikc_why(const dh_ikc_model_f32 *m)
{
    if (m->n == 6u && (m->prismatic == 0u || m->prismatic == 0x4u))
        return ikc_spherical(m) ? DH_IKC_WHY_AXES : DH_IKC_WHY_WRIST;
    if (m->n == 4u && m->prismatic == 0x4u) return DH_IKC_WHY_AXES;
    return DH_IKC_WHY_JOINTS;
}

static dh_status ikc_none(dh_ikc_model_f32 *m, dh_ikc_why why, dh_status st)
{
    m->kind = DH_IKC_NONE;
    m->why = why;
    return st;
}

dh_status dh_ikc_analyse_f32(const dh_robot *r, dh_ikc_model_f32 *m)
{
    dh_mat4_f32 pre;
    uint32_t i;
    DH_ASSERT(r != NULL);
    DH_ASSERT(m != NULL);
    memset(m, 0, sizeof *m);
    dh_mat4_identity_f32(&m->pre_inv);
    dh_mat4_identity_f32(&m->post_inv);
    if (r->n > (uint32_t)DH_MAX_JOINTS || (r->conv != DH_CONV_STANDARD && r->conv != DH_CONV_MODIFIED))
        return ikc_none(m, DH_IKC_WHY_JOINTS, DH_ERR_ARG);
    for (i = 0; i < r->n; i++)
        if (r->joint[i].type != DH_JOINT_REVOLUTE && r->joint[i].type != DH_JOINT_PRISMATIC)
            return ikc_none(m, DH_IKC_WHY_JOINTS, DH_ERR_ARG);
    if ((r->flags & DH_ROBOT_HAS_F32) == 0u) return ikc_none(m, DH_IKC_WHY_PATH, DH_ERR_UNAVAILABLE);
    if (dh_mat4_check_rigid_f32(&r->base, DH_ROT_ERROR_TOL) != DH_OK ||
        dh_mat4_check_rigid_f32(&r->tool, DH_ROT_ERROR_TOL) != DH_OK)
        return ikc_none(m, DH_IKC_WHY_PATH, DH_ERR_NOT_RIGID);
    if (r->n == 0u || r->n > DH_IKC_JOINTS) return ikc_none(m, DH_IKC_WHY_JOINTS, DH_ERR_UNAVAILABLE);
    m->n = r->n;
    ikc_canonical(r, m, &pre);
    if (ikc_inverse(&pre, &m->pre_inv) != DH_OK || ikc_inverse(&r->tool, &m->post_inv) != DH_OK)
        return ikc_none(m, DH_IKC_WHY_PATH, DH_ERR_NOT_RIGID);
    if (dh_ikc_detect_wrist_f32_(m)) {
        m->why = DH_IKC_WHY_NONE;
        return DH_OK;
    }
    if (dh_ikc_detect_par234_f32_(m)) {
        m->kind = DH_IKC_PARALLEL_234;
        m->why = DH_IKC_WHY_NONE;
        return DH_OK;
    }
    if (dh_ikc_detect_scara_f32_(m)) {
        m->kind = DH_IKC_SCARA;
        m->why = DH_IKC_WHY_NONE;
        return DH_OK;
    }
    return ikc_none(m, ikc_why(m), DH_ERR_UNAVAILABLE);
}

const char *dh_ikc_why_str(dh_ikc_why why)
{
    switch (why) {
    case DH_IKC_WHY_NONE: return "the robot has a closed-form solution";
    case DH_IKC_WHY_JOINTS: return "the joint count or types match no closed-form family";
    case DH_IKC_WHY_WRIST: return "the last three axes do not meet in one point and axes 2, 3, 4 are not parallel";
    case DH_IKC_WHY_AXES: return "the wrist is spherical but the arm axes match no closed-form family";
    case DH_IKC_WHY_PATH: return "the robot's path is not prepared or its base or tool is not rigid";
    default: return "unknown reason";
    }
}

/* ---- solving ------------------------------------------------------------------ */

/* Every check of dh_ikc_f32 made before anything is written. */
static DH_NOINLINE dh_status ikc_args(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *q_ref,
                                      uint32_t opts)
{
    if ((opts & ~(uint32_t)DH_IKC_KEEP_OUT_OF_LIMITS) != 0u) return DH_ERR_ARG;
    if (m->kind == DH_IKC_NONE) return DH_ERR_UNAVAILABLE;
    switch (m->kind) {
    case DH_IKC_WRIST_RRR:
    case DH_IKC_WRIST_RRP:
    case DH_IKC_PARALLEL_234:
        if (m->n != 6u) return DH_ERR_ARG;
        break;
    case DH_IKC_SCARA:
        if (m->n != 4u) return DH_ERR_ARG;
        break;
    default:
        return DH_ERR_ARG;
    }
    if (!dh_allfinite_f32(&T->m[0][0], 16u)) return DH_ERR_NAN;
    if (q_ref != NULL && !dh_allfinite_f32(q_ref, m->n)) return DH_ERR_NAN;
    if (T->m[0][3] != 0.0f || T->m[1][3] != 0.0f || T->m[2][3] != 0.0f || T->m[3][3] != 1.0f)
        return DH_ERR_NOT_RIGID;
    if (!dh_rot_cols_ok_f32(T->m[0], T->m[1], T->m[2], DH_ROT_ERROR_TOL)) return DH_ERR_NOT_RIGID;
    return DH_OK;
}

/* Revolute value v in (-180, 180] shifted by a multiple of 360 into
 * [lo, hi], to the shifted value nearest ref; 0 when no shift fits (v
 * unchanged). The shift count is bounded by 1024 turns. */
static int ikc_shift(float *v, float lo, float hi, float ref)
{
    float t = ref, x, c;
    int32_t k;
    if (t < lo) t = lo;
    if (t > hi) t = hi;
    if (t > 368640.0f) t = 368640.0f;
    if (t < -368640.0f) t = -368640.0f;
    x = (t - *v) * (1.0f / 360.0f);
    k = (int32_t)(x + ((x >= 0.0f) ? 0.5f : -0.5f));
    c = *v + 360.0f * (float)k;
    if (c > hi) c -= 360.0f;
    else if (c < lo) c += 360.0f;
    if (c < lo || c > hi) return 0;
    *v = c;
    return 1;
}

/* Raw canonical solution -> joint values; 1 when within the limits. */
static int ikc_to_joints(const dh_ikc_model_f32 *m, const float *q_ref, float *q)
{
    uint32_t i;
    int in = 1;
    for (i = 0; i < m->n; i++) {
        const int lim = m->qmin[i] <= m->qmax[i];
        if ((m->prismatic >> i) & 1u) {
            q[i] -= m->d[i];
            if (lim && (q[i] < m->qmin[i] || q[i] > m->qmax[i])) in = 0;
        } else {
            float v = q[i] - m->off[i];
            if (!(fabsf(v) <= 540.0f)) {
                /* a theta offset beyond +-360 deg: whole turns off first */
                const float x = v * (1.0f / 360.0f);
                if (fabsf(x) < 8388608.0f) v -= 360.0f * (float)(int32_t)x;
            }
            v = ikc_wrap(ikc_wrap(v));
            if (lim && !ikc_shift(&v, m->qmin[i], m->qmax[i], (q_ref != NULL) ? q_ref[i] : 0.0f)) in = 0;
            q[i] = v;
        }
    }
    return in;
}

dh_status dh_ikc_f32(const dh_ikc_model_f32 *m, const dh_mat4_f32 *target, const float *q_ref, uint32_t opts,
                     dh_ikc_sol_f32 *sol, uint32_t *n_sol)
{
    dh_mat4_f32 T06;
    float cref[DH_IKC_JOINTS];
    uint32_t raw = 0, i, j, out = 0;
    dh_status st;
    DH_ASSERT(m != NULL);
    DH_ASSERT(target != NULL);
    DH_ASSERT(sol != NULL);
    DH_ASSERT(n_sol != NULL);
    *n_sol = 0;
    st = ikc_args(m, target, q_ref, opts);
    if (st != DH_OK) return st;
    for (i = 0; i < DH_IKC_JOINTS; i++) {
        float v = (q_ref != NULL && i < m->n) ? q_ref[i] : 0.0f;
        if (i < m->n) v += ((m->prismatic >> i) & 1u) ? m->d[i] : m->off[i];
        cref[i] = v;
    }
    T06 = *target;
    if (!ikc_is_identity(&m->pre_inv)) dh_mat4_premul_f32(&T06, &m->pre_inv);
    if (!ikc_is_identity(&m->post_inv)) dh_mat4_postmul_f32(&T06, &m->post_inv);
    switch (m->kind) {
    case DH_IKC_WRIST_RRR:
    case DH_IKC_WRIST_RRP: raw = dh_ikc_wrist_f32_(m, &T06, cref, sol); break;
    case DH_IKC_PARALLEL_234: raw = dh_ikc_par234_f32_(m, &T06, cref, sol); break;
    default: raw = dh_ikc_scara_f32_(m, &T06, cref, sol); break;
    }
    if (raw > DH_IKC_MAX_SOL) raw = DH_IKC_MAX_SOL;
    if (raw == 0u) return DH_ERR_UNREACHABLE;
    for (i = 0; i < raw; i++) {
        const int in = ikc_to_joints(m, q_ref, sol[i].q);
        if (!in) {
            if ((opts & DH_IKC_KEEP_OUT_OF_LIMITS) == 0u) continue;
            sol[i].flags |= DH_IKC_OUT_OF_LIMITS;
        }
        if (out != i) {
            for (j = 0; j < DH_IKC_JOINTS; j++) sol[out].q[j] = sol[i].q[j];
            sol[out].flags = sol[i].flags;
        }
        out++;
    }
    for (i = out; i < raw; i++) sol[i].flags = 0u;
    *n_sol = out;
    return (out == 0u) ? DH_ERR_LIMIT : DH_OK;
}

dh_status dh_ikc_nearest_f32(const dh_ikc_sol_f32 *sol, uint32_t n_sol, const float *q_ref, uint32_t n,
                             uint32_t *index)
{
    uint32_t s, i, best = 0;
    float dbest = 0.0f;
    DH_ASSERT(sol != NULL);
    DH_ASSERT(index != NULL);
    if (n_sol == 0u || n > DH_IKC_JOINTS) return DH_ERR_ARG;
    if (q_ref != NULL && !dh_allfinite_f32(q_ref, n)) return DH_ERR_NAN;
    for (s = 0; s < n_sol; s++) {
        float d = 0.0f;
        for (i = 0; i < n; i++) d += fabsf(sol[s].q[i] - ((q_ref != NULL) ? q_ref[i] : 0.0f));
        if (s == 0u || d < dbest) {
            dbest = d;
            best = s;
        }
    }
    *index = best;
    return DH_OK;
}

/* ---- spherical-wrist families ------------------------------------------------- */

int dh_ikc_detect_wrist_f32_(dh_ikc_model_f32 *m)
{
    float *k = m->k, L = 0.0f;
    uint32_t i;
    if (!ikc_spherical(m) || m->ca[0] != 0.0f) return 0;
    for (i = 0; i < 6u; i++) {
        L += fabsf(m->a[i]) + fabsf(m->d[i]);
        if (((m->prismatic >> i) & 1u) && m->qmin[i] <= m->qmax[i])
            L += (fabsf(m->qmin[i]) > fabsf(m->qmax[i])) ? fabsf(m->qmin[i]) : fabsf(m->qmax[i]);
    }
    k[KW_EPS] = IKC_EPS_L * ((L > 0.0f) ? L : 1.0f);
    k[KW_INV45] = 1.0f / (m->sa[3] * m->sa[4]);
    k[KW_INVSA5] = 1.0f / m->sa[4];
    k[KW_ORTHO] = (m->ca[3] == 0.0f && m->ca[4] == 0.0f) ? 1.0f : 0.0f;
    k[KW_CC45] = m->ca[3] * m->ca[4];
    if (m->prismatic == 0u) {
        const float e = m->sa[2] * m->d[3], a2 = m->a[1], a3 = m->a[2];
        const float rho = dh_sqrt_f32(a3 * a3 + e * e);
        if (m->sa[1] != 0.0f || a2 == 0.0f || !(rho > 0.0f)) return 0;
        k[KW_SIGMA] = m->ca[1];
        k[KW_H] = m->d[1] + m->ca[1] * (m->d[2] + m->ca[2] * m->d[3]);
        k[KW_PHI] = dh_atan2f_deg_(e, a3, 0.0f);
        k[KW_A2RHO] = a2 * a2 + rho * rho;
        k[KW_D] = 2.0f * a2 * rho;
        k[KW_SA23] = m->ca[1] * m->sa[2];
        k[KW_CA23] = m->ca[1] * m->ca[2];
        k[KW_INV2A2] = 1.0f / (2.0f * a2);
        k[KW_CPLUS] = fabsf(a2) + rho;
        k[KW_CMINUS] = fabsf(fabsf(a2) - rho);
        m->kind = DH_IKC_WRIST_RRR;
    } else if (m->prismatic == 0x4u) {
        const float e = m->sa[2] * m->d[3];
        float s3, c3;
        if (m->ca[1] != 0.0f) return 0;
        (void)dh_sincos_f32(m->off[2], &s3, &c3);
        k[KW_S3] = s3;
        k[KW_C3] = c3;
        k[KW_W] = m->a[1] + m->a[2] * c3 + e * s3;
        k[KW_H] = m->d[1] + m->sa[1] * (m->a[2] * s3 - e * c3);
        k[KW_Z3C] = m->ca[2] * m->d[3];
        m->kind = DH_IKC_WRIST_RRP;
    } else {
        return 0;
    }
    k[KW_HZERO] = (fabsf(k[KW_H]) <= k[KW_EPS]) ? 1.0f : 0.0f;
    return 1;
}

/* R <- R Rz(theta) Rx(alpha), R a 3x3 column-major (c, s of theta). */
static void ikc_rzrx(float *R, float c, float s, float sa, float ca)
{
    uint32_t r;
    for (r = 0; r < 3u; r++) {
        const float x = R[r], y = R[3u + r], z = R[6u + r];
        const float y1 = -s * x + c * y;
        R[r] = c * x + s * y;
        R[3u + r] = ca * y1 + sa * z;
        R[6u + r] = -sa * y1 + ca * z;
    }
}

/* Wrist of one arm solution: sol[0] holds the arm values (and its flags);
 * writes the wrist values into sol[0] and, unless singular, the second
 * wrist branch into sol[1]. Returns 1 or 2. R6 = R06 Rx(alpha6)^T
 * (column-major, 9 floats). */
static DH_NOINLINE uint32_t ikc_wrist(const dh_ikc_model_f32 *m, const float *R6, const float *cref,
                                      dh_ikc_sol_f32 *sol)
{
    const float *k = m->k;
    float R[9], mz[3], mx[3], c5, s5, s4, c4, c, s, xp, yp, n11, n21, t4, t5, t6;
    uint32_t i, j;
    for (i = 0; i < 9u; i++) R[i] = (i % 4u == 0u) ? 1.0f : 0.0f;
    (void)dh_sincos_f32(sol->q[0], &s, &c);
    ikc_rzrx(R, c, s, m->sa[0], m->ca[0]);
    if (m->kind == DH_IKC_WRIST_RRR) {
        (void)dh_sincos_f32(sol->q[1] + k[KW_SIGMA] * sol->q[2], &s, &c);
        ikc_rzrx(R, c, s, k[KW_SA23], k[KW_CA23]);
    } else {
        (void)dh_sincos_f32(sol->q[1], &s, &c);
        ikc_rzrx(R, c, s, m->sa[1], m->ca[1]);
        ikc_rzrx(R, k[KW_C3], k[KW_S3], m->sa[2], m->ca[2]);
    }
    /* M = R03^T R6: its third and first columns */
    for (i = 0; i < 3u; i++) {
        mz[i] = R[3u * i] * R6[6] + R[3u * i + 1u] * R6[7] + R[3u * i + 2u] * R6[8];
        mx[i] = R[3u * i] * R6[0] + R[3u * i + 1u] * R6[1] + R[3u * i + 2u] * R6[2];
    }
    c5 = (k[KW_CC45] - mz[2]) * k[KW_INV45];
    if (c5 > 1.0f) c5 = 1.0f;
    if (c5 < -1.0f) c5 = -1.0f;
    /* axes 4 and 6 aligned when M e_z (axis 6 in frame 3) is on the z axis */
    s = dh_sqrt_f32(mz[0] * mz[0] + mz[1] * mz[1]);
    if (k[KW_ORTHO] != 0.0f)
        s5 = s;
    else
        s5 = dh_sqrt_f32(1.0f - c5 * c5);
    if (s < IKC_SING_WRIST) {
        /* axes 4 and 6 aligned: joint 4 from q_ref */
        t4 = cref[3];
        (void)dh_sincos_f32(t4, &s4, &c4);
        s5 = (c4 * mz[0] + s4 * mz[1]) * k[KW_INVSA5];
        sol->flags |= DH_IKC_SING_WRIST;
    } else {
        xp = m->sa[4] * s5;
        yp = -(m->ca[3] * m->sa[4] * c5 + m->sa[3] * m->ca[4]);
        c4 = xp * mz[0] + yp * mz[1];
        s4 = xp * mz[1] - yp * mz[0];
        t4 = dh_atan2f_deg_(s4, c4, 0.0f);
        c = 1.0f / dh_sqrt_f32(c4 * c4 + s4 * s4);
        c4 *= c;
        s4 *= c;
    }
    t5 = ikc_atan2(s5, c5, 0.0f);
    {
        const float mpx = c4 * mx[0] + s4 * mx[1], mpy = -s4 * mx[0] + c4 * mx[1], mpz = mx[2];
        const float sa4 = m->sa[3], ca4 = m->ca[3], ca5 = m->ca[4], sa5 = m->sa[4];
        n11 = c5 * mpx + ca4 * s5 * mpy + sa4 * s5 * mpz;
        n21 = -s5 * ca5 * mpx + (ca4 * c5 * ca5 - sa4 * sa5) * mpy + (sa4 * c5 * ca5 + ca4 * sa5) * mpz;
    }
    t6 = ikc_atan2(n21, n11, 0.0f);
    sol->q[3] = ikc_wrap(t4);
    sol->q[4] = t5;
    sol->q[5] = t6;
    if ((sol->flags & DH_IKC_SING_WRIST) != 0u) return 1u;
    for (j = 0; j < 3u; j++) sol[1].q[j] = sol->q[j];
    sol[1].flags = sol->flags | DH_IKC_WRIST_ALT;
    if (k[KW_ORTHO] != 0.0f) {
        sol[1].q[3] = ikc_wrap(t4 + 180.0f);
        sol[1].q[4] = ikc_wrap(-t5);
        sol[1].q[5] = ikc_wrap(t6 + 180.0f);
        return 2u;
    }
    /* general wrist: the other sign of sin theta5 */
    s5 = -s5;
    xp = m->sa[4] * s5;
    yp = -(m->ca[3] * m->sa[4] * c5 + m->sa[3] * m->ca[4]);
    c4 = xp * mz[0] + yp * mz[1];
    s4 = xp * mz[1] - yp * mz[0];
    sol[1].q[3] = dh_atan2f_deg_(s4, c4, 0.0f);
    c = 1.0f / dh_sqrt_f32(c4 * c4 + s4 * s4);
    c4 *= c;
    s4 *= c;
    sol[1].q[4] = ikc_atan2(s5, c5, 0.0f);
    {
        const float mpx = c4 * mx[0] + s4 * mx[1], mpy = -s4 * mx[0] + c4 * mx[1], mpz = mx[2];
        const float sa4 = m->sa[3], ca4 = m->ca[3], ca5 = m->ca[4], sa5 = m->sa[4];
        n11 = c5 * mpx + ca4 * s5 * mpy + sa4 * s5 * mpz;
        n21 = -s5 * ca5 * mpx + (ca4 * c5 * ca5 - sa4 * sa5) * mpy + (sa4 * c5 * ca5 + ca4 * sa5) * mpz;
    }
    sol[1].q[5] = ikc_atan2(n21, n11, 0.0f);
    return 2u;
}

/* Joints 2, 3 of the RRR arm for one shoulder branch: (vx, vy) the wrist
 * centre in the plane of the arm; writes sol[0] and maybe sol[1] (q[0]
 * and flags preset in sol[0]). Returns 0, 1 or 2. */
static uint32_t ikc_elbow_rrr(const dh_ikc_model_f32 *m, float vx, float vy, const float *cref,
                              dh_ikc_sol_f32 *sol)
{
    const float *k = m->k;
    const float v2 = vx * vx + vy * vy, v = dh_sqrt_f32(v2), D = k[KW_D], Kp = v2 - k[KW_A2RHO];
    const float aD = fabsf(D), KD = (D < 0.0f) ? -Kp : Kp;
    /* dK = |D| - |K'| from |v| (no cancellation of the squares against the
     * constant a2^2 + rho^2): stretched elbow (|a2| + rho)^2 - |v|^2,
     * folded |v|^2 - (|a2| - rho)^2. Moving K' by dK moves the wrist centre
     * by dK / (2 |v|): the branches coincide within KW_EPS. */
    const float dK = (KD >= 0.0f) ? (k[KW_CPLUS] - v) * (k[KW_CPLUS] + v) : (v - k[KW_CMINUS]) * (v + k[KW_CMINUS]);
    const float tol = 2.0f * k[KW_EPS] * v;
    const float A = m->a[1] + Kp * k[KW_INV2A2];
    float sq, psi, B;
    uint32_t b, nb = 2u;
    if (dK < -tol) return 0u;
    if (dK <= tol) {
        nb = 1u;
        sq = 0.0f;
        sol->flags |= DH_IKC_SING_ELBOW;
    } else {
        /* D^2 - K'^2 = dK (|D| + |K'|) */
        sq = dh_sqrt_f32(dK * (2.0f * aD - dK));
    }
    psi = dh_atan2f_deg_(sq, KD, 0.0f);
    for (b = 0; b < nb; b++) {
        const float sg = (b == 0u) ? 1.0f : -1.0f;
        if (b == 1u) {
            sol[1].q[0] = sol[0].q[0];
            sol[1].flags = sol[0].flags | DH_IKC_ELBOW_ALT;
        }
        /* a3 s3 - e c3 = rho sin(theta3 - phi) = +-sqrt(r3) / (2 |a2|) */
        B = k[KW_SIGMA] * sg * sq * fabsf(k[KW_INV2A2]);
        sol[b].q[2] = ikc_wrap(k[KW_PHI] + sg * psi);
        sol[b].q[1] = ikc_atan2(A * vy - B * vx, A * vx + B * vy, cref[1]);
    }
    return nb;
}

/* Joints 2, 3 of the RRP arm (the prismatic extension z3 = +-sqrt(.)). */
static uint32_t ikc_elbow_rrp(const dh_ikc_model_f32 *m, float vx, float vy, const float *cref,
                              dh_ikc_sol_f32 *sol)
{
    const float *k = m->k;
    const float W = k[KW_W], eps = k[KW_EPS], tau2 = m->sa[1];
    const float v = dh_sqrt_f32(vx * vx + vy * vy), r = (v - fabsf(W)) * (v + fabsf(W));
    const float tol = eps * (2.0f * fabsf(W) + eps);
    float z;
    uint32_t b, nb = 2u;
    if (r < -tol) return 0u;
    if (r <= tol) {
        nb = 1u;
        z = 0.0f;
        sol->flags |= DH_IKC_SING_ELBOW;
    } else {
        z = dh_sqrt_f32(r);
    }
    for (b = 0; b < nb; b++) {
        const float zb = (b == 0u) ? z : -z;
        if (b == 1u) {
            sol[1].q[0] = sol[0].q[0];
            sol[1].flags = sol[0].flags | DH_IKC_ELBOW_ALT;
        }
        sol[b].q[1] = ikc_atan2(tau2 * zb * vx + W * vy, W * vx - tau2 * zb * vy, cref[1]);
        sol[b].q[2] = zb - k[KW_Z3C];
    }
    return nb;
}

uint32_t dh_ikc_wrist_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T06, const float *cref,
                           dh_ikc_sol_f32 *sol)
{
    const float *k = m->k;
    const float sa6 = m->sa[5], ca6 = m->ca[5], a6 = m->a[5], d6 = m->d[5];
    const float h = k[KW_H], eps = k[KW_EPS], tau = m->sa[0];
    float R6[9], px, py, pz, rad, tol, u;
    uint32_t i, na = 0, nu = 2u, b, cnt = 0, out;
    /* R6 = R06 Rx(alpha6)^T; wrist centre o5 = p - a6 n - d6 R6 e_z */
    for (i = 0; i < 3u; i++) {
        R6[i] = T06->m[0][i];
        R6[3u + i] = ca6 * T06->m[1][i] - sa6 * T06->m[2][i];
        R6[6u + i] = sa6 * T06->m[1][i] + ca6 * T06->m[2][i];
    }
    px = T06->m[3][0] - a6 * R6[0] - d6 * R6[6];
    py = T06->m[3][1] - a6 * R6[1] - d6 * R6[7];
    pz = T06->m[3][2] - a6 * R6[2] - d6 * R6[8];
    /* shoulder: u = +-sqrt(px^2 + py^2 - h^2) */
    rad = dh_sqrt_f32(px * px + py * py);
    rad = (rad - fabsf(h)) * (rad + fabsf(h));
    tol = eps * (2.0f * fabsf(h) + eps);
    if (rad < -tol) return 0u;
    if (rad <= tol) {
        nu = 1u;
        u = 0.0f;
    } else {
        u = dh_sqrt_f32(rad);
    }
    /* arm solutions in sol[0..3] */
    for (b = 0; b < nu; b++) {
        const float ub = (b == 0u) ? u : -u;
        float vx, vy;
        dh_ikc_sol_f32 *s = &sol[na];
        s->flags = (b == 0u) ? 0u : DH_IKC_SHOULDER_ALT;
        if (nu == 1u && k[KW_HZERO] != 0.0f) {
            /* wrist centre on axis 1: joint 1 from q_ref */
            s->q[0] = cref[0];
            s->flags |= DH_IKC_SING_SHOULDER;
        } else {
            s->q[0] = ikc_atan2(tau * h * px + ub * py, ub * px - tau * h * py, cref[0]);
        }
        vx = ub - m->a[0];
        vy = tau * (pz - m->d[0]);
        if (m->kind == DH_IKC_WRIST_RRR)
            na += ikc_elbow_rrr(m, vx, vy, cref, s);
        else
            na += ikc_elbow_rrp(m, vx, vy, cref, s);
    }
    if (na == 0u) return 0u;
    /* each arm solution i -> wrist solutions at 2i, 2i+1 (from the last:
     * nothing unread is overwritten), then compacted */
    for (i = na; i-- > 0u;) {
        if (i != 0u) sol[2u * i] = sol[i];
        sol[2u * i + 1u].flags = 0xFFFFFFFFu;
        (void)ikc_wrist(m, R6, cref, &sol[2u * i]);
    }
    out = 0;
    for (i = 0; i < 2u * na; i++) {
        if (sol[i].flags == 0xFFFFFFFFu) continue;
        if (out != i) sol[out] = sol[i];
        out++;
    }
    cnt = out;
    return cnt;
}
