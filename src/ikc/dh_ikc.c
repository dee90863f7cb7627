/* SPDX-License-Identifier: Apache-2.0 */
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
#include "dhmath/ikc.h"
#include "dhmath/kin.h"
#include "dhmath/mat4.h"
#include "dhmath/trig.h"
#include "ikc_impl.h"
#include "../internal/dh_floatops.h"

#include <math.h>

/* Family constants of the wrist families, m->k. */
enum {
    KW_H = 0,      /* offset of the wrist centre from the plane of axis 1 (h) */
    KW_EPS,        /* length tolerance of the branch coincidences: 5e-7 L */
    KW_HZERO,      /* 1: |h| <= KW_EPS (wrist centre can reach axis 1) */
    KW_INV45,      /* 1 / (sin alpha4 sin alpha5) */
    KW_INVSA5,     /* 1 / sin alpha5 */
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
    KW_PRE,        /* 1: pre_inv is not the identity (its product is needed) */
    KW_POST,       /* 1: post_inv is not the identity */
    KW_COUNT
};

typedef char dh_ikc_k_fits_[(KW_COUNT <= (int)DH_IKC_K) ? 1 : -1];

/* Wrist singular when axis 6 is within this angle (rad) of axis 4: the
 * orientation error of the q_ref split is at most that angle. */
#define IKC_SING_WRIST 1.5e-6f
/* Length tolerance per unit of the characteristic length L. */
#define IKC_EPS_L 5e-7f

/* ---- small helpers --------------------------------------------------------- */

/* atan2 in degrees, fallback when both arguments are zero (free angle).
 * The radian atan2 (<= 2 ulp) scaled: a third of the stack of the degree
 * version (dh_atan2f_deg_), which no solver frame could afford on top. */
DH_INLINE float ikc_atan2(float y, float x, float fallback)
{
    if (dh_feq_f32(y, 0.0f) && dh_feq_f32(x, 0.0f)) return fallback;
    return dh_atan2f_(y, x) * DH_RAD2DEG_F;
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
            if (!dh_feq_f32(T->m[c][r], (c == r) ? 1.0f : 0.0f)) return 0;
    return 1;
}

/* The last three axes meet in one point: a4 = a5 = d5 = 0 and axes 4, 5
 * and 5, 6 not parallel (joints 4..6 revolute). */
static int ikc_spherical(const dh_ikc_model_f32 *m)
{
    return m->n == 6u && (m->prismatic & 0x38u) == 0u && dh_feq_f32(m->a[3], 0.0f) && dh_feq_f32(m->a[4], 0.0f) &&
           dh_feq_f32(m->d[4], 0.0f) && !dh_feq_f32(m->sa[3], 0.0f) && !dh_feq_f32(m->sa[4], 0.0f);
}

/* ---- analysis -------------------------------------------------------------- */

/* Canonical chain of r into m (a, d, sa, ca, off, limits, prismatic);
 * the frame before it into m->pre_inv (inverted by the caller). */
static DH_NOINLINE void ikc_canonical(const dh_robot *r, dh_ikc_model_f32 *m)
{
    uint32_t i, n = r->n;
    const int mdh = (r->conv == DH_CONV_MODIFIED);
    dh_mat4_f32 *P = &m->pre_inv;
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
    *P = r->base;
    if (mdh) {
        /* base * Rx(alpha_0) Tx(a_0), column by column */
        const float sa = r->joint[0].sa, ca = r->joint[0].ca, a0 = r->joint[0].a;
        for (i = 0; i < 3u; i++) {
            const float b0 = r->base.m[0][i], b1 = r->base.m[1][i], b2 = r->base.m[2][i];
            P->m[1][i] = ca * b1 + sa * b2;
            P->m[2][i] = ca * b2 - sa * b1;
            P->m[3][i] = a0 * b0 + r->base.m[3][i];
        }
    }
}

/* A float frame with bottom row 0 0 0 1 and a rotation within
 * DH_ROT_ERROR_TOL (det > 0), every entry finite. */
static int ikc_rigid(const dh_mat4_f32 *F)
{
    return dh_allfinite_f32(&F->m[0][0], 16u) && dh_feq_f32(F->m[0][3], 0.0f) && dh_feq_f32(F->m[1][3], 0.0f) &&
           dh_feq_f32(F->m[2][3], 0.0f) && dh_feq_f32(F->m[3][3], 1.0f) &&
           dh_rot_cols_ok_f32(F->m[0], F->m[1], F->m[2], DH_ROT_ERROR_TOL);
}

/* F <- F^-1 for a rigid F (Paul 1981 eq. 1.57: R^T, -R^T p); an exact
 * identity stays exact. The base and tool are rotations to the float
 * rounding in practice; one off orthonormal by e moves the solutions by
 * about e. */
static void ikc_inv_rigid(dh_mat4_f32 *F)
{
    float p0 = F->m[3][0], p1 = F->m[3][1], p2 = F->m[3][2], t;
    uint32_t i;
    t = F->m[0][1]; F->m[0][1] = F->m[1][0]; F->m[1][0] = t;
    t = F->m[0][2]; F->m[0][2] = F->m[2][0]; F->m[2][0] = t;
    t = F->m[1][2]; F->m[1][2] = F->m[2][1]; F->m[2][1] = t;
    for (i = 0; i < 3u; i++) F->m[3][i] = 0.0f - (F->m[0][i] * p0 + F->m[1][i] * p1 + F->m[2][i] * p2);
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
    uint32_t i;
    DH_ASSERT(r != NULL);
    DH_ASSERT(m != NULL);
    memset(m, 0, sizeof *m);
    for (i = 0; i < 4u; i++) {
        m->pre_inv.m[i][i] = 1.0f;
        m->post_inv.m[i][i] = 1.0f;
    }
    if (r->n > (uint32_t)DH_MAX_JOINTS || (r->conv != DH_CONV_STANDARD && r->conv != DH_CONV_MODIFIED))
        return ikc_none(m, DH_IKC_WHY_JOINTS, DH_ERR_ARG);
    for (i = 0; i < r->n; i++)
        if (r->joint[i].type != DH_JOINT_REVOLUTE && r->joint[i].type != DH_JOINT_PRISMATIC)
            return ikc_none(m, DH_IKC_WHY_JOINTS, DH_ERR_ARG);
    if ((r->flags & DH_ROBOT_HAS_F32) == 0u) return ikc_none(m, DH_IKC_WHY_PATH, DH_ERR_UNAVAILABLE);
    if (!ikc_rigid(&r->base) || !ikc_rigid(&r->tool)) return ikc_none(m, DH_IKC_WHY_PATH, DH_ERR_NOT_RIGID);
    if (r->n == 0u || r->n > DH_IKC_JOINTS) return ikc_none(m, DH_IKC_WHY_JOINTS, DH_ERR_UNAVAILABLE);
    m->n = r->n;
    ikc_canonical(r, m);
    ikc_inv_rigid(&m->pre_inv);
    m->post_inv = r->tool;
    ikc_inv_rigid(&m->post_inv);
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
    case DH_IKC_WHY_AXES: return "the wrist axes meet in one point but the arm (or a non-orthogonal wrist) matches no closed-form family";
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
    if (!dh_feq_f32(T->m[0][3], 0.0f) || !dh_feq_f32(T->m[1][3], 0.0f) || !dh_feq_f32(T->m[2][3], 0.0f) ||
        !dh_feq_f32(T->m[3][3], 1.0f))
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
    /* within the limits and within 180 deg of ref: no other shift is nearer */
    if (*v >= lo && *v <= hi && fabsf(ref - *v) <= 180.0f) return 1;
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

/* Raw canonical solution -> joint values; 1 when within the limits.
 * Common case first: the revolute value already in (-180, 180] and within
 * its limits with no nearer shift (|ref - v| <= 180), left as it is. */
static DH_NOINLINE int ikc_to_joints(const dh_ikc_model_f32 *m, const float *q_ref, float *q)
{
    uint32_t i;
    int in = 1;
    for (i = 0; i < m->n; i++) {
        const float lo = m->qmin[i], hi = m->qmax[i], ref = (q_ref != NULL) ? q_ref[i] : 0.0f;
        float v;
        if ((m->prismatic >> i) & 1u) {
            q[i] -= m->d[i];
            if (lo <= hi && (q[i] < lo || q[i] > hi)) in = 0;
            continue;
        }
        v = q[i] - m->off[i];
        if (!(v > -180.0f && v <= 180.0f)) {
            if (!(fabsf(v) <= 540.0f)) {
                /* a theta offset beyond +-360 deg: whole turns off first */
                const float x = v * (1.0f / 360.0f);
                if (fabsf(x) < 8388608.0f) v -= 360.0f * (float)(int32_t)x;
            }
            v = ikc_wrap(ikc_wrap(v));
        }
        q[i] = v;
        /* (with q_ref NULL, ref = 0 and |v| <= 180: no nearer shift) */
        if (lo <= hi && !(v >= lo && v <= hi && (q_ref == NULL || fabsf(ref - v) <= 180.0f))) {
            if (!ikc_shift(&v, lo, hi, ref)) in = 0;
            q[i] = v;
        }
    }
    return in;
}

/* The raw solutions sol[0..raw-1] to joint values: non-finite branches (a
 * target far beyond the reach overflows the squares of the position
 * solution) are no solutions; limits per opts; kept ones packed to the
 * front. Out of line: its frame is not on top of a solver's. */
static DH_NOINLINE dh_status ikc_finish(const dh_ikc_model_f32 *m, const float *q_ref, uint32_t opts,
                                        dh_ikc_sol_f32 *sol, uint32_t raw, uint32_t *n_sol)
{
    uint32_t i, j, out = 0, finite = 0;
    for (i = 0; i < raw; i++) {
        if (!dh_allfinite_f32(sol[i].q, m->n)) continue;
        finite++;
        if (!ikc_to_joints(m, q_ref, sol[i].q)) {
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
    if (finite == 0u) return DH_ERR_UNREACHABLE;
    return (out == 0u) ? DH_ERR_LIMIT : DH_OK;
}

dh_status dh_ikc_f32(const dh_ikc_model_f32 *m, const dh_mat4_f32 *target, const float *q_ref, uint32_t opts,
                     dh_ikc_sol_f32 *sol, uint32_t *n_sol)
{
    uint32_t raw = 0;
    dh_status st;
    DH_ASSERT(m != NULL);
    DH_ASSERT(target != NULL);
    DH_ASSERT(sol != NULL);
    DH_ASSERT(n_sol != NULL);
    *n_sol = 0;
    st = ikc_args(m, target, q_ref, opts);
    if (st != DH_OK) return st;
    switch (m->kind) {
    case DH_IKC_WRIST_RRR:
    case DH_IKC_WRIST_RRP: raw = dh_ikc_wrist_f32_(m, target, q_ref, sol); break;
    case DH_IKC_PARALLEL_234: raw = dh_ikc_par234_f32_(m, target, q_ref, sol); break;
    default: raw = dh_ikc_scara_f32_(m, target, q_ref, sol); break;
    }
    if (raw > DH_IKC_MAX_SOL) raw = DH_IKC_MAX_SOL;
    if (raw == 0u) return DH_ERR_UNREACHABLE;
    return ikc_finish(m, q_ref, opts, sol, raw, n_sol);
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

float dh_ikc_cref_f32_(const dh_ikc_model_f32 *m, const float *q_ref, uint32_t i)
{
    const float v = (q_ref != NULL) ? q_ref[i] : 0.0f;
    return v + (((m->prismatic >> i) & 1u) ? m->d[i] : m->off[i]);
}

/* out = A (x, w) for w = 1 (point) or 0 (direction); out may alias x. */
static void ikc_xform(const dh_mat4_f32 *A, const float *x, float w, float *out)
{
    const float x0 = x[0], x1 = x[1], x2 = x[2];
    uint32_t i;
    for (i = 0; i < 3u; i++) out[i] = A->m[0][i] * x0 + A->m[1][i] * x1 + A->m[2][i] * x2 + A->m[3][i] * w;
}

void dh_ikc_t06_vec_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *v, float w, float *out)
{
    out[0] = v[0];
    out[1] = v[1];
    out[2] = v[2];
    if (!ikc_is_identity(&m->post_inv)) ikc_xform(&m->post_inv, out, w, out);
    ikc_xform(T, out, w, out);
    if (!ikc_is_identity(&m->pre_inv)) ikc_xform(&m->pre_inv, out, w, out);
}

/* ---- spherical-wrist families ------------------------------------------------- */

int dh_ikc_detect_wrist_f32_(dh_ikc_model_f32 *m)
{
    float *k = m->k, L = 0.0f;
    uint32_t i;
    if (!ikc_spherical(m) || !dh_feq_f32(m->ca[3], 0.0f) || !dh_feq_f32(m->ca[4], 0.0f) ||
        !dh_feq_f32(m->ca[0], 0.0f))
        return 0;
    for (i = 0; i < 6u; i++) {
        L += fabsf(m->a[i]) + fabsf(m->d[i]);
        if (((m->prismatic >> i) & 1u) && m->qmin[i] <= m->qmax[i])
            L += (fabsf(m->qmin[i]) > fabsf(m->qmax[i])) ? fabsf(m->qmin[i]) : fabsf(m->qmax[i]);
    }
    k[KW_EPS] = IKC_EPS_L * ((L > 0.0f) ? L : 1.0f);
    k[KW_INV45] = 1.0f / (m->sa[3] * m->sa[4]);
    k[KW_INVSA5] = 1.0f / m->sa[4];
    if (m->prismatic == 0u) {
        const float e = m->sa[2] * m->d[3], a2 = m->a[1], a3 = m->a[2];
        const float rho = dh_sqrt_f32(a3 * a3 + e * e);
        if (!dh_feq_f32(m->sa[1], 0.0f) || dh_feq_f32(a2, 0.0f) || !(rho > 0.0f)) return 0;
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
        if (!dh_feq_f32(m->ca[1], 0.0f)) return 0;
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
    k[KW_PRE] = ikc_is_identity(&m->pre_inv) ? 0.0f : 1.0f;
    k[KW_POST] = ikc_is_identity(&m->post_inv) ? 0.0f : 1.0f;
    return 1;
}

/* v <- Rx(alpha)^T Rz(theta)^T v for the two 3-vectors at a and b (c, s
 * of theta). */
static void ikc_rzrx_t(float *a, float *b, float c, float s, float sa, float ca)
{
    uint32_t k;
    for (k = 0; k < 2u; k++) {
        float *v = (k == 0u) ? a : b;
        const float x = c * v[0] + s * v[1], y = c * v[1] - s * v[0], z = v[2];
        v[0] = x;
        v[1] = ca * y + sa * z;
        v[2] = ca * z - sa * y;
    }
}

/* Layout of sol while the wrist families solve (the caller's array is the
 * scratch, so that no frame below the atan2 calls holds vectors):
 * sol[7].q[3..5] = R06 e_x, sol[6].q[3..5] = R06 Rx(alpha6)^T e_z (the
 * columns M is made of), sol[5].q[3..5] = the wrist centre; arm solutions
 * use q[0..2] and flags only. */
#define IKC_RN(sol) (&(sol)[7].q[3])
#define IKC_RA(sol) (&(sol)[6].q[3])
#define IKC_P(sol) (&(sol)[5].q[3])
#define IKC_GAP 0xFFFFFFFFu

/* Wrist, phase A, for the arm solution in *arm: the arm values and flags
 * into out[0]; M's third and first columns (R03^T of R06's two columns)
 * into out[0].q[3..5] and out[1].q[3..5] (for the last arm these are
 * where R06's columns are, so they are read in place). Wrist singular
 * (axis 6 in frame 3 on the z axis, joint 4's axis): flagged, and joint 4
 * from q_ref with its sine and cosine into out[1].q[2], q[0], q[1]. */
static DH_NOINLINE void ikc_wrist_a(const dh_ikc_model_f32 *m, const float *q_ref, const dh_ikc_sol_f32 *arm,
                                    dh_ikc_sol_f32 *out, const float *rn, const float *ra)
{
    const float *k = m->k;
    const float t1 = arm->q[0], t2 = arm->q[1], t3 = arm->q[2];
    float *mz = &out[0].q[3], *mx = &out[1].q[3];
    float c, s;
    uint32_t i;
    out[0].flags = arm->flags;
    for (i = 0; i < 3u; i++) {
        mx[i] = rn[i];
        mz[i] = ra[i];
    }
    out[0].q[0] = t1;
    out[0].q[1] = t2;
    out[0].q[2] = t3;
    (void)dh_sincos_f32(t1, &s, &c);
    ikc_rzrx_t(mz, mx, c, s, m->sa[0], m->ca[0]);
    if (m->kind == DH_IKC_WRIST_RRR) {
        (void)dh_sincos_f32(t2 + k[KW_SIGMA] * t3, &s, &c);
        ikc_rzrx_t(mz, mx, c, s, k[KW_SA23], k[KW_CA23]);
    } else {
        (void)dh_sincos_f32(t2, &s, &c);
        ikc_rzrx_t(mz, mx, c, s, m->sa[1], m->ca[1]);
        ikc_rzrx_t(mz, mx, k[KW_C3], k[KW_S3], m->sa[2], m->ca[2]);
    }
    if (mz[0] * mz[0] + mz[1] * mz[1] < IKC_SING_WRIST * IKC_SING_WRIST) {
        out[0].flags |= DH_IKC_SING_WRIST;
        c = dh_ikc_cref_f32_(m, q_ref, 3u);
        out[1].q[2] = c;
        (void)dh_sincos_f32(c, &out[1].q[0], &out[1].q[1]);
    }
}

/* Wrist, phase B (orthogonal wrist): from M's columns the atan2 arguments
 * of theta4 (y, x into out[0].q[3], q[4]), theta5 (out[0].q[5],
 * out[1].q[3]) and theta6 (out[1].q[4], q[5]). theta4 rotates (X', Y') =
 * (sin a5 s5, 0) onto (m13, m23); theta6 from M e_x rotated back by theta4
 * against the first two columns of Rx(a4) Rz(t5) Rx(a5) (consistency). */
static DH_NOINLINE void ikc_wrist_b(const dh_ikc_model_f32 *m, dh_ikc_sol_f32 *out)
{
    const float *k = m->k;
    const float m0 = out[0].q[3], m1 = out[0].q[4], m2 = out[0].q[5];
    const float sa4 = m->sa[3], sa5 = m->sa[4];
    float c5 = -m2 * k[KW_INV45], s5, c4, s4, mpx, mpy, mpz;
    if (c5 > 1.0f) c5 = 1.0f;
    if (c5 < -1.0f) c5 = -1.0f;
    if ((out[0].flags & DH_IKC_SING_WRIST) != 0u) {
        s4 = out[1].q[0];
        c4 = out[1].q[1];
        s5 = (c4 * m0 + s4 * m1) * k[KW_INVSA5];
    } else {
        float r;
        s5 = dh_sqrt_f32(m0 * m0 + m1 * m1);
        /* (c4, s4) proportional to (X' m13, X' m23), X' = sin a5 s5 */
        c4 = sa5 * m0;
        s4 = sa5 * m1;
        r = 1.0f / dh_sqrt_f32(c4 * c4 + s4 * s4);
        c4 *= r;
        s4 *= r;
    }
    mpx = c4 * out[1].q[3] + s4 * out[1].q[4];
    mpy = c4 * out[1].q[4] - s4 * out[1].q[3];
    mpz = out[1].q[5];
    out[0].q[3] = s4;
    out[0].q[4] = c4;
    out[0].q[5] = s5;
    out[1].q[3] = c5;
    /* N21, N11 with cos a4 = cos a5 = 0 */
    out[1].q[4] = -sa4 * sa5 * mpy;
    out[1].q[5] = c5 * mpx + sa4 * s5 * mpz;
}

/* Wrist, phase C: the angles, and the flipped solution (t4 + 180, -t5,
 * t6 + 180) into out[1] unless singular. */
static DH_NOINLINE void ikc_wrist_c(dh_ikc_sol_f32 *out)
{
    const int sing = (out[0].flags & DH_IKC_SING_WRIST) != 0u;
    const float t4 = sing ? out[1].q[2] : ikc_atan2(out[0].q[3], out[0].q[4], 0.0f);
    const float t5 = ikc_atan2(out[0].q[5], out[1].q[3], 0.0f);
    const float t6 = ikc_atan2(out[1].q[4], out[1].q[5], 0.0f);
    out[0].q[3] = ikc_wrap(t4);
    out[0].q[4] = t5;
    out[0].q[5] = t6;
    if (sing) {
        out[1].flags = IKC_GAP;
        return;
    }
    out[1].q[0] = out[0].q[0];
    out[1].q[1] = out[0].q[1];
    out[1].q[2] = out[0].q[2];
    out[1].q[3] = ikc_wrap(t4 + 180.0f);
    out[1].q[4] = ikc_wrap(-t5);
    out[1].q[5] = ikc_wrap(t6 + 180.0f);
    out[1].flags = out[0].flags | DH_IKC_WRIST_ALT;
}

/* Joints 2, 3 of the RRR arm for one shoulder branch: sol[0] holds theta1,
 * (vx, vy) (the wrist centre in the plane of the arm) in q[0..2] and the
 * flags; writes sol[0] and maybe sol[1] (q[0..2], flags). Returns 0, 1, 2. */
static DH_NOINLINE uint32_t ikc_elbow_rrr(const dh_ikc_model_f32 *m, float cref2, dh_ikc_sol_f32 *sol)
{
    const float *k = m->k;
    const float vx = sol->q[1], vy = sol->q[2];
    const float v2 = vx * vx + vy * vy, v = dh_sqrt_f32(v2), D = k[KW_D], Kp = v2 - k[KW_A2RHO];
    const float aD = fabsf(D), KD = (D < 0.0f) ? -Kp : Kp;
    /* dK = |D| - |K'| from |v| (no cancellation of the squares against the
     * constant a2^2 + rho^2): stretched elbow (|a2| + rho)^2 - |v|^2,
     * folded |v|^2 - (|a2| - rho)^2. Moving K' by dK moves the wrist centre
     * by dK / (2 |v|): the branches coincide within KW_EPS. */
    const float dK = (KD >= 0.0f) ? (k[KW_CPLUS] - v) * (k[KW_CPLUS] + v) : (v - k[KW_CMINUS]) * (v + k[KW_CMINUS]);
    const float tol = 2.0f * k[KW_EPS] * v;
    const float A = m->a[1] + Kp * k[KW_INV2A2];
    float sq = 0.0f, psi, B;
    uint32_t b, nb = 2u;
    if (dK < -tol) return 0u;
    if (dK <= tol) {
        nb = 1u;
        sol->flags |= DH_IKC_SING_ELBOW;
    } else {
        /* D^2 - K'^2 = dK (|D| + |K'|) */
        sq = dh_sqrt_f32(dK * (2.0f * aD - dK));
    }
    psi = ikc_atan2(sq, KD, 0.0f);
    for (b = nb; b-- > 0u;) {
        const float sg = (b == 0u) ? 1.0f : -1.0f;
        if (b == 1u) {
            sol[1].q[0] = sol[0].q[0];
            sol[1].flags = sol[0].flags | DH_IKC_ELBOW_ALT;
        }
        /* a3 s3 - e c3 = rho sin(theta3 - phi) = +-sqrt(D^2 - K'^2) / (2 |a2|) */
        B = k[KW_SIGMA] * sg * sq * fabsf(k[KW_INV2A2]);
        sol[b].q[2] = ikc_wrap(k[KW_PHI] + sg * psi);
        sol[b].q[1] = ikc_atan2(A * vy - B * vx, A * vx + B * vy, cref2);
    }
    return nb;
}

/* Joints 2, 3 of the RRP arm (the prismatic extension z3 = +-sqrt(.)). */
static DH_NOINLINE uint32_t ikc_elbow_rrp(const dh_ikc_model_f32 *m, float cref2, dh_ikc_sol_f32 *sol)
{
    const float *k = m->k;
    const float vx = sol->q[1], vy = sol->q[2];
    const float W = k[KW_W], eps = k[KW_EPS], tau2 = m->sa[1];
    const float v = dh_sqrt_f32(vx * vx + vy * vy), r = (v - fabsf(W)) * (v + fabsf(W));
    const float tol = eps * (2.0f * fabsf(W) + eps);
    float z = 0.0f;
    uint32_t b, nb = 2u;
    if (r < -tol) return 0u;
    if (r <= tol) {
        nb = 1u;
        sol->flags |= DH_IKC_SING_ELBOW;
    } else {
        z = dh_sqrt_f32(r);
    }
    for (b = nb; b-- > 0u;) {
        const float zb = (b == 0u) ? z : -z;
        if (b == 1u) {
            sol[1].q[0] = sol[0].q[0];
            sol[1].flags = sol[0].flags | DH_IKC_ELBOW_ALT;
        }
        sol[b].q[1] = ikc_atan2(tau2 * zb * vx + W * vy, W * vx - tau2 * zb * vy, cref2);
        sol[b].q[2] = zb - k[KW_Z3C];
    }
    return nb;
}

/* u of shoulder branch b (u >= 0 for b = 0, u <= 0 for b = 1) moved onto the
 * arm's reach: when the planar point (ub - a1, vy) lies beyond it (|v|
 * below the folded radius |a2| - rho (RRR) or |W| (RRP), above the
 * stretched |a2| + rho (RRR)), the u' = a1 +- sqrt(r^2 - vy^2) on that
 * radius nearest ub, if |u'^2 - ub^2| <= 2 eps (|px| + |py|): u^2 = px^2 +
 * py^2 - h^2 moves by 2 (px dpx + py dpy), so u' belongs to a wrist centre
 * at most sqrt(2) eps away. Near the shoulder cylinder (u small) the
 * target's rounding moves u by far more than eps; this keeps such targets
 * on the boundary solvable. Otherwise ub. */
static DH_NOINLINE float ikc_reach(const dh_ikc_model_f32 *m, uint32_t b, float ub, float vy, float pl1)
{
    const float *k = m->k, a1 = m->a[0], vx = ub - a1, v = dh_sqrt_f32(vx * vx + vy * vy);
    float r, w, best = ub, db = -1.0f;
    uint32_t i;
    if (m->kind == DH_IKC_WRIST_RRR) {
        if (v < k[KW_CMINUS]) r = k[KW_CMINUS];
        else if (v > k[KW_CPLUS]) r = k[KW_CPLUS];
        else return ub;
    } else {
        r = fabsf(k[KW_W]);
        if (v >= r) return ub;
    }
    w = (r - fabsf(vy)) * (r + fabsf(vy));
    if (!(w >= 0.0f)) return ub; /* vy alone is beyond: the elbow decides */
    w = dh_sqrt_f32(w);
    for (i = 0; i < 2u; i++) {
        const float c = (i == 0u) ? a1 + w : a1 - w, d = fabsf(c - ub);
        if ((b == 0u) ? (c < 0.0f) : (c > 0.0f)) continue;
        if (d * fabsf(c + ub) > 2.0f * k[KW_EPS] * pl1) continue;
        if (db < 0.0f || d < db) {
            db = d;
            best = c;
        }
    }
    return best;
}

/* Shoulder: u = +-sqrt(px^2 + py^2 - h^2) of the wrist centre p (read
 * from IKC_P), each moved onto the arm's reach by ikc_reach, theta1; per
 * branch sol[b] gets theta1, vx, vy and its flags. Returns the number of
 * branches (0, 1 or 2). */
static DH_NOINLINE uint32_t ikc_shoulder(const dh_ikc_model_f32 *m, float cref1, dh_ikc_sol_f32 *sol)
{
    const float *k = m->k, *p = IKC_P(sol);
    const float h = k[KW_H], eps = k[KW_EPS], tau = m->sa[0];
    const float px = p[0], py = p[1], pz = p[2], vy = tau * (pz - m->d[0]);
    float rad, tol, u = 0.0f;
    uint32_t b, nb, nu = 0u;
    int sing;
    rad = dh_sqrt_f32(px * px + py * py);
    rad = (rad - fabsf(h)) * (rad + fabsf(h));
    tol = eps * (2.0f * fabsf(h) + eps);
    if (rad < -tol) return 0u;
    if (rad > 0.0f) u = dh_sqrt_f32(rad);
    /* wrist centre on axis 1: joint 1 from q_ref, one branch */
    sing = (rad <= tol && !dh_feq_f32(k[KW_HZERO], 0.0f));
    nb = sing ? 1u : 2u;
    for (b = 0; b < nb; b++) {
        dh_ikc_sol_f32 *s = &sol[nu];
        float ub = (b == 0u) ? u : -u;
        if (sing) {
            s->q[0] = cref1;
            s->flags = DH_IKC_SING_SHOULDER;
        } else {
            ub = ikc_reach(m, b, ub, vy, fabsf(px) + fabsf(py));
            if (b != 0u && !(u > 0.0f) && !(ub < 0.0f)) continue; /* both branches at u = 0: one */
            s->q[0] = ikc_atan2(tau * h * px + ub * py, ub * px - tau * h * py, cref1);
            s->flags = (b == 0u) ? 0u : DH_IKC_SHOULDER_ALT;
        }
        s->q[1] = ub - m->a[0];
        s->q[2] = vy;
        nu++;
    }
    return nu;
}

/* The vectors of T06 the wrist families need, into the scratch of sol.
 * T06 = pre_inv T post_inv; the products with an identity pre_inv or
 * post_inv (flagged at analysis) are left out. */
static DH_NOINLINE void ikc_prepare(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, dh_ikc_sol_f32 *sol)
{
    const int pre = !dh_feq_f32(m->k[KW_PRE], 0.0f), post = !dh_feq_f32(m->k[KW_POST], 0.0f);
    float *rn = IKC_RN(sol), *ra = IKC_RA(sol), *p = IKC_P(sol);
    uint32_t i;
    /* in the frame of T's columns: e_x, Rx(alpha6)^T e_z and the wrist
     * centre o5 = (-a6, -d6 sin alpha6, -d6 cos alpha6) */
    ra[0] = 0.0f;
    ra[1] = m->sa[5];
    ra[2] = m->ca[5];
    p[0] = -m->a[5];
    p[1] = -m->d[5] * m->sa[5];
    p[2] = -m->d[5] * m->ca[5];
    if (post) {
        for (i = 0; i < 3u; i++) rn[i] = m->post_inv.m[0][i];
        ikc_xform(&m->post_inv, ra, 0.0f, ra);
        ikc_xform(&m->post_inv, p, 1.0f, p);
        ikc_xform(T, rn, 0.0f, rn);
    } else {
        for (i = 0; i < 3u; i++) rn[i] = T->m[0][i];
    }
    ikc_xform(T, ra, 0.0f, ra);
    ikc_xform(T, p, 1.0f, p);
    if (pre) {
        ikc_xform(&m->pre_inv, rn, 0.0f, rn);
        ikc_xform(&m->pre_inv, ra, 0.0f, ra);
        ikc_xform(&m->pre_inv, p, 1.0f, p);
    }
}

/* Arm values and flags (q[0..2]) of src into dst, q[3..5] left alone. */
static void ikc_copy_arm(dh_ikc_sol_f32 *dst, const dh_ikc_sol_f32 *src)
{
    dst->q[0] = src->q[0];
    dst->q[1] = src->q[1];
    dst->q[2] = src->q[2];
    dst->flags = src->flags;
}

/* Entries of sol[0..n-1] whose flags are not IKC_GAP moved to the front
 * (arm values only when arm, else whole entries), in order. */
static DH_NOINLINE uint32_t ikc_compact(dh_ikc_sol_f32 *sol, uint32_t n, int arm)
{
    uint32_t i, out = 0;
    for (i = 0; i < n; i++) {
        if (sol[i].flags == IKC_GAP) continue;
        if (out != i) {
            if (arm) ikc_copy_arm(&sol[out], &sol[i]);
            else sol[out] = sol[i];
        }
        out++;
    }
    return out;
}

uint32_t dh_ikc_wrist_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *q_ref, dh_ikc_sol_f32 *sol)
{
    uint32_t i, na, base;
    float c4;
    ikc_prepare(m, T, sol);
    /* shoulder branches in sol[0..1], each -> elbow branches at 2b, 2b+1
     * (from the last: nothing unread is overwritten) */
    na = ikc_shoulder(m, dh_ikc_cref_f32_(m, q_ref, 0u), sol);
    for (i = na; i-- > 0u;) {
        uint32_t ne;
        if (i != 0u) ikc_copy_arm(&sol[2u * i], &sol[i]);
        sol[2u * i + 1u].flags = IKC_GAP;
        c4 = dh_ikc_cref_f32_(m, q_ref, 1u);
        ne = (m->kind == DH_IKC_WRIST_RRR) ? ikc_elbow_rrr(m, c4, &sol[2u * i]) : ikc_elbow_rrp(m, c4, &sol[2u * i]);
        if (ne == 0u) sol[2u * i].flags = IKC_GAP;
    }
    na = ikc_compact(sol, 2u * na, 1);
    /* arms to the end (slots 8 - na .. 7), then arm j -> wrist solutions at
     * 2j, 2j+1: every slot written has been read */
    base = DH_IKC_MAX_SOL - na;
    for (i = na; i-- > 0u;) ikc_copy_arm(&sol[base + i], &sol[i]);
    for (i = 0; i < na; i++) {
        ikc_wrist_a(m, q_ref, &sol[base + i], &sol[2u * i], IKC_RN(sol), IKC_RA(sol));
        ikc_wrist_b(m, &sol[2u * i]);
        ikc_wrist_c(&sol[2u * i]);
    }
    return ikc_compact(sol, 2u * na, 0);
}
