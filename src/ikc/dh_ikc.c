/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_ikc.c - closed-form inverse kinematics, float: the front end
 * (dh_ikc_analyse_f32, dh_ikc_f32, dh_ikc_nearest_f32): the model and its
 * canonical chain, the target checks, the dispatch to the family solvers
 * (dh_ikc_wrist.c, dh_ikc_par234.c, dh_ikc_scara.c), then offsets,
 * 360-degree shifts and limits. Method: docs/design.md ("Closed-form
 * inverse kinematics"), after Paul 1981 ch. 3.
 *
 * Canonical chain (ikc_impl.h): standard DH joints with an MDH robot's
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

/* The conversion windows of m's joints from their limits (ikc_joint), and
 * the circular windows of the limits in canonical values (lim_w) by which
 * dh_ikc_f32 prunes the solver's branches. A revolute joint value q within
 * [lo, hi] (less than a turn apart) has the canonical value c = q + off
 * modulo 360 within r = (hi - lo) / 2 of the centre off + (lo + hi) / 2;
 * the radius adds a margin for the roundings of the centre (each within
 * 2^-24 of at most |off| + |lo| + |hi| + 360, a handful of them, with its
 * reduction exact below 2^20) and of the conversion of ikc_finish, so
 * that a value outside the window is outside the limits after the
 * conversion as well: the window only drops solutions the conversion
 * drops. Unlimited, wide, prismatic, or limits beyond 2^20 degrees: +inf.
 * Out of line: its frame is not in dh_ikc_analyse_f32's, under the
 * detectors' (256-byte stack budget on Cortex-M0+). */
static DH_NOINLINE void ikc_windows(dh_ikc_model_f32 *m)
{
    uint32_t i;
    for (i = 0; i < DH_IKC_JOINTS; i++) {
        m->lim_w[i] = 0.0f;
        m->lim_w[DH_IKC_JOINTS + i] = dh_f32_from_bits(0x7F800000u);
    }
    for (i = 0; i < m->n; i++) {
        const int lim = m->qmin[i] <= m->qmax[i];
        const float lo = lim ? m->qmin[i] : -180.0f, hi = lim ? m->qmax[i] : 180.0f;
        const float mag = fabsf(m->off[i]) + fabsf(lo) + fabsf(hi);
        /* v > -180 is v >= -180 + 2^-16, the next float */
        m->win_lo[i] = (lo > -180.0f) ? lo : (-180.0f + 0x1p-16f);
        m->win_hi[i] = (hi < 180.0f) ? hi : 180.0f;
        if (lim && !(hi - lo < 360.0f)) m->wide |= 1u << i;
        if (lim && (((m->wide | m->prismatic) >> i) & 1u) == 0u && mag <= 1048576.0f) {
            const float r = 0.5f * (hi - lo) + 1e-3f + 1e-6f * (mag + 720.0f);
            m->lim_w[i] = dh_ikc_ref_f32_(m->off[i] + 0.5f * (lo + hi));
            if (r < 180.0f) {
                m->lim_w[DH_IKC_JOINTS + i] = r;
                m->lim_any = 1u;
            }
        }
    }
}

/* Why the canonical chain of m has no closed form (every detector said no). */
static dh_ikc_why ikc_why(const dh_ikc_model_f32 *m)
{
    if (m->n == 6u && (m->prismatic == 0u || m->prismatic == 0x4u))
        return dh_ikc_spherical_f32_(m) ? DH_IKC_WHY_AXES : DH_IKC_WHY_WRIST;
    if (m->n == 4u && m->prismatic == 0x4u) return DH_IKC_WHY_AXES;
    return DH_IKC_WHY_JOINTS;
}

/* The end of an analysis that found kind: lim_any kept only where
 * dh_ikc_f32 prunes by it (ikc_prune: a spherical-wrist family, exact), so
 * that the other families pay one test for it. */
static dh_status ikc_found(dh_ikc_model_f32 *m)
{
    if (m->calibrated != 0u || (m->kind != DH_IKC_WRIST_RRR && m->kind != DH_IKC_WRIST_RRP)) m->lim_any = 0u;
    m->why = DH_IKC_WHY_NONE;
    return DH_OK;
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
    ikc_windows(m);
    ikc_inv_rigid(&m->pre_inv);
    m->post_inv = r->tool;
    ikc_inv_rigid(&m->post_inv);
    if (dh_ikc_detect_wrist_f32_(m)) {
        return ikc_found(m);
    }
    if (dh_ikc_detect_par234_f32_(m)) {
        m->kind = DH_IKC_PARALLEL_234;
        return ikc_found(m);
    }
    if (dh_ikc_detect_scara_f32_(m)) {
        m->kind = DH_IKC_SCARA;
        return ikc_found(m);
    }
    i = (uint32_t)dh_ikc_calibrate_f32_(m);
    if (i == 2u) i = (uint32_t)dh_ikc_calibrated_f32_(m, dh_ikc_detect_wrist_f32_(m));
    if (i != 0u) {
        return ikc_found(m);
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

/* 1 when the n floats of v (n 4 or 6) are all finite. With an FPU, the sum
 * of the differences x - x is exactly 0 then (each is +0) and NaN
 * otherwise (infinity - infinity, NaN - NaN): three operations per value,
 * no loop; soft float: dh_allfinite_f32 (its bit tests are the cheaper
 * there). */
DH_INLINE int ikc_finite46(const float *v, uint32_t n)
{
    float z;
    if (DH_SOFT_FLOAT) return dh_allfinite_f32(v, n);
    z = ((v[0] - v[0]) + (v[1] - v[1])) + ((v[2] - v[2]) + (v[3] - v[3]));
    if (n > 4u) z += (v[4] - v[4]) + (v[5] - v[5]);
    return dh_feq_f32(z, 0.0f);
}

/* Every check of dh_ikc_f32 made before anything is written. The common
 * case first: a rotation that passes dh_rot_cols_ok_f32 has finite
 * entries (a NaN or infinity fails its comparisons), and the bottom row
 * equal to 0 0 0 1 is finite, so with the translation and q_ref finite
 * the target passes every check; any other target goes through them in
 * the order of the statuses. */
static DH_NOINLINE dh_status ikc_args(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *q_ref,
                                      uint32_t opts)
{
    if (opts == 0u &&
        ((m->n == 6u && (m->kind == DH_IKC_WRIST_RRR || m->kind == DH_IKC_WRIST_RRP ||
                         m->kind == DH_IKC_PARALLEL_234)) ||
         (m->n == 4u && m->kind == DH_IKC_SCARA)) &&
        dh_rot_cols_ok_f32(T->m[0], T->m[1], T->m[2], DH_ROT_ERROR_TOL) && ikc_finite46(T->m[3], 4u) &&
        dh_feq_f32(T->m[0][3], 0.0f) && dh_feq_f32(T->m[1][3], 0.0f) && dh_feq_f32(T->m[2][3], 0.0f) &&
        dh_feq_f32(T->m[3][3], 1.0f) && (q_ref == NULL || ikc_finite46(q_ref, m->n)))
        return DH_OK;
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

/* A revolute value outside (-180, 180] (v = raw - offset, any finite)
 * wrapped into it. */
static DH_NOINLINE float ikc_wrap_any(float v)
{
    if (!(fabsf(v) <= 540.0f)) {
        /* a theta offset beyond +-360 deg: whole turns off first */
        const float x = v * (1.0f / 360.0f);
        if (fabsf(x) < 8388608.0f) v -= 360.0f * (float)(int32_t)x;
    }
    return dh_ikc_wrap_f32_(dh_ikc_wrap_f32_(v));
}

/* ikc_general's verdicts on a value */
#define IKC_V_IN 0  /* within the limits (or none) */
#define IKC_V_OUT 1 /* outside the limits */
#define IKC_V_NAN 2 /* not finite */

/* The general conversion of revolute joint i's value *v = raw - offset
 * (any float) with reference ref, after the window and one-turn tests of
 * ikc_joint: wrapped into (-180, 180] (a non-finite value: IKC_V_NAN, *v
 * unchanged), then, outside the limits, shifted by whole turns into them
 * to the value nearest ref (IKC_V_IN) or left wrapped (IKC_V_OUT). Inlined
 * into ikc_joint (no frame of its own under the tracker's on Cortex-M0+);
 * ikc_finish6 calls it out of line through ikc_general_call. */
DH_INLINE int ikc_general(const dh_ikc_model_f32 *m, uint32_t i, float ref, float *v)
{
    const int lim = m->qmin[i] <= m->qmax[i];
    const int narrow = ((m->wide >> i) & 1u) == 0u;
    /* no limits: every value in (-180, 180] stays, as one within limits
     * [-180, 180] less than a turn apart would */
    const float lo = lim ? m->qmin[i] : -180.0f, hi = lim ? m->qmax[i] : 180.0f;
    float x = *v;
    if (!(x > -180.0f && x <= 180.0f)) {
        if (!dh_isfinite_f32(x)) return IKC_V_NAN;
        x = ikc_wrap_any(x);
    }
    *v = x;
    /* limits less than a turn apart within (-180, 180]: no shift of a
     * value of (-180, 180] outside them enters them */
    if (!(x >= lo && x <= hi && (narrow || fabsf(ref - x) <= 180.0f)) &&
        ((narrow && lo > -180.0f && hi <= 180.0f) || !ikc_shift(v, lo, hi, ref)))
        return IKC_V_OUT;
    return IKC_V_IN;
}

/* ikc_general out of line (the rare case of ikc_finish6) */
static DH_NOINLINE int ikc_general_call(const dh_ikc_model_f32 *m, uint32_t i, float ref, float *v)
{
    return ikc_general(m, i, ref, v);
}

/* Joint i of the raw solutions sol[s] with bit s set in live_in (s < ns) to
 * its joint value. Returns live_in with the bits cleared of the solutions
 * whose value is outside the limits (lim: into *out instead) and of those
 * whose value is not finite (also cleared in *fin). The joint's constants
 * are read once for all solutions. Common case first: the revolute value
 * in (-180, 180] (so finite) and within its limits with no nearer shift
 * (limits less than a turn apart, or |ref - v| <= 180; with q_ref NULL,
 * ref = 0 and that always holds), left as it is: two comparisons against
 * the window [flo, fhi] = [lo, hi] within (-180, 180] (v > -180 is v >=
 * -180 + 2^-16, the next float) and, when ref decides, within 179.5 deg of
 * ref; a NaN fails them. A value outside the window is tried one turn
 * towards ref against the window of that shift, then takes the general
 * path, which decides exactly. */
static uint32_t ikc_joint(const dh_ikc_model_f32 *m, const float *q_ref, uint32_t i, dh_ikc_sol_f32 *sol,
                          uint32_t ns, uint32_t live_in, uint32_t *fin, uint32_t *out)
{
    uint32_t live = live_in;
    const int lim = m->qmin[i] <= m->qmax[i];
    /* limits less than a turn apart (or none): a value within them is the
     * only shifted one within them, so the nearest to ref */
    const int narrow = ((m->wide >> i) & 1u) == 0u;
    const float off = m->off[i], ref = (q_ref != NULL) ? q_ref[i] : 0.0f;
    float flo = m->win_lo[i], fhi = m->win_hi[i], slo, shi;
    uint32_t s, rest;
    if (!narrow && q_ref != NULL) {
        /* the distance to ref decides: the window narrowed to within 179.5
         * deg of ref, inside |ref - v| <= 180 after rounding (|ref| < 2^20,
         * ulp <= 1/8; a larger ref leaves no value in (-180, 180] in it) */
        const float rlo = ref - 179.5f, rhi = ref + 179.5f;
        if (rlo > flo) flo = rlo;
        if (rhi < fhi) fhi = rhi;
        /* one turn towards ref: kept when within the limits and 179.5 deg
         * of ref (the one shift within 180 deg of ref) */
        slo = (rlo > m->qmin[i]) ? rlo : m->qmin[i];
        shi = (rhi < m->qmax[i]) ? rhi : m->qmax[i];
    } else {
        /* one turn: kept when in the window (the wrapped value) */
        slo = flo;
        shi = fhi;
    }
    if ((m->prismatic >> i) & 1u) {
        for (s = 0; s < ns; s++) {
            const uint32_t bit = 1u << s;
            const float v = sol[s].q[i] - m->d[i];
            if ((live & bit) == 0u) continue;
            sol[s].q[i] = v;
            if (!dh_isfinite_f32(v)) {
                *fin &= ~bit;
                live &= ~bit;
            } else if (lim && !(v >= m->qmin[i] && v <= m->qmax[i])) {
                *out |= bit;
            } else {
                /* finite and within the limits: kept as it is */
            }
        }
        return live;
    }
    /* the live solutions only: rest holds the bits from s on */
    for (s = 0, rest = live; rest != 0u; s++, rest >>= 1) {
        uint32_t bit;
        float v, t;
        int verdict;
        if ((rest & 1u) == 0u) continue;
        v = sol[s].q[i] - off;
        if (v >= flo && v <= fhi) {
            sol[s].q[i] = v;
            continue;
        }
        /* one turn towards ref, rounded as ikc_wrap_any and ikc_shift
         * round it: when in [slo, shi], their result (the other way, or a
         * value beyond one turn, fails the test) */
        t = (v > ref) ? v - 360.0f : v + 360.0f;
        if (t >= slo && t <= shi) {
            sol[s].q[i] = t;
            continue;
        }
        bit = 1u << s;
        verdict = ikc_general(m, i, ref, &v);
        if (verdict == IKC_V_NAN) {
            *fin &= ~bit;
            live &= ~bit;
            continue;
        }
        if (verdict == IKC_V_OUT) *out |= bit;
        sol[s].q[i] = v;
    }
    return live;
}

/* Value *v = c - o of narrow revolute joint i with window [lo, hi]
 * (ikc_finish6): 1 when it is kept, its value in *v. ikc_joint's
 * operations: the window, one turn towards the reference into the window,
 * else ikc_general (ikc_general_call). */
DH_INLINE int ikc_val6(const dh_ikc_model_f32 *m, const float *q_ref, uint32_t i, float c, float o, float lo, float hi,
                       float *v)
{
    const float x = c - o;
    float ref, t;
    *v = x;
    if (x >= lo && x <= hi) return 1;
    ref = (q_ref != NULL) ? q_ref[i] : 0.0f;
    t = (x > ref) ? x - 360.0f : x + 360.0f;
    if (t >= lo && t <= hi) {
        *v = t;
        return 1;
    }
    return ikc_general_call(m, i, ref, v) == IKC_V_IN;
}

/* ikc_finish (opts 0) for six revolute joints whose limits are less than a
 * turn apart or absent (m->wide 0): each joint's window [win_lo, win_hi]
 * does not depend on q_ref, so the solutions are taken one by one, the
 * joints' offsets and windows held in registers, each value written
 * straight into the solution's final slot (sol[n], n <= s: the solution's
 * own slot or one already read) by ikc_val6, and the first value found outside the limits or not finite
 * leaves the solution (its slot is free again). Per value these are
 * ikc_joint's operations, so the kept solutions, values and order are
 * ikc_finish's; for the status, a solution left while none is kept is
 * checked for finite values in its slot as ikc_finish does (the values
 * written keep the finiteness of the raw ones). */
static DH_NOINLINE dh_status ikc_finish6(const dh_ikc_model_f32 *m, const float *q_ref, dh_ikc_sol_f32 *sol,
                                         uint32_t *n_sol)
{
    const uint32_t raw = *n_sol & 0xFu;
    const float o0 = m->off[0], o1 = m->off[1], o2 = m->off[2], o3 = m->off[3], o4 = m->off[4], o5 = m->off[5];
    const float l0 = m->win_lo[0], l1 = m->win_lo[1], l2 = m->win_lo[2], l3 = m->win_lo[3], l4 = m->win_lo[4],
                l5 = m->win_lo[5];
    const float h0 = m->win_hi[0], h1 = m->win_hi[1], h2 = m->win_hi[2], h3 = m->win_hi[3], h4 = m->win_hi[4],
                h5 = m->win_hi[5];
    uint32_t s, n = 0u, fin = 0u;
    for (s = 0; s < raw; s++) {
        const dh_ikc_sol_f32 *src = &sol[s];
        dh_ikc_sol_f32 *d = &sol[n];
        const uint32_t f = src->flags;
        float *v = d->q;
        if (ikc_val6(m, q_ref, 0u, src->q[0], o0, l0, h0, &v[0]) &&
            ikc_val6(m, q_ref, 1u, src->q[1], o1, l1, h1, &v[1]) &&
            ikc_val6(m, q_ref, 2u, src->q[2], o2, l2, h2, &v[2]) &&
            ikc_val6(m, q_ref, 3u, src->q[3], o3, l3, h3, &v[3]) &&
            ikc_val6(m, q_ref, 4u, src->q[4], o4, l4, h4, &v[4]) &&
            ikc_val6(m, q_ref, 5u, src->q[5], o5, l5, h5, &v[5])) {
            d->flags = f;
            n++;
        } else if (n == 0u && fin == 0u && dh_allfinite_f32(src->q, 6u)) {
            /* left while none is kept: the slot holds this solution's
             * values so far and its raw ones */
            fin = 1u;
        } else {
            /* left: its slot is free again */
        }
    }
    for (s = n; s < raw; s++) sol[s].flags = 0u;
    *n_sol = n;
    if (n != 0u) return DH_OK;
    return (fin == 0u) ? DH_ERR_UNREACHABLE : DH_ERR_LIMIT;
}

/* ikc_finish's raw_mask lists the masks for up to eight solutions */
typedef char ikc_raw_mask_fits_[(DH_IKC_MAX_SOL == 8u) ? 1 : -1];

/* The raw solutions sol[0..raw-1] to joint values: non-finite branches (a
 * target far beyond the reach overflows the squares of the position
 * solution) are no solutions; limits per opts; kept ones packed to the
 * front, in order. Joint by joint (ikc_joint): a solution found outside
 * the limits is not converted further unless opts keeps it. Out of line:
 * its frame is not on top of a solver's. */
static DH_NOINLINE dh_status ikc_finish(const dh_ikc_model_f32 *m, const float *q_ref, dh_ikc_sol_f32 *sol,
                                        uint32_t *n_sol)
{
    /* *n_sol on entry: the raw count (1..DH_IKC_MAX_SOL) in bits 0..3, opts
     * above (four arguments: no stack arguments in the callers' frames) */
    const uint32_t opts = *n_sol >> 4, raw = *n_sol & 0xFu;
    /* the mask of the first raw solutions (raw <= DH_IKC_MAX_SOL) */
    static const uint8_t raw_mask[DH_IKC_MAX_SOL + 1u] = { 0x00u, 0x01u, 0x03u, 0x07u, 0x0Fu, 0x1Fu, 0x3Fu, 0x7Fu, 0xFFu };
    const int keep = (opts & DH_IKC_KEEP_OUT_OF_LIMITS) != 0u;
    uint32_t i, s, n = 0, fin = raw_mask[raw], live, outl = 0u;
    live = fin;
    for (i = 0; i < m->n; i++) {
        live = ikc_joint(m, q_ref, i, sol, raw, live, &fin, &outl);
        if (!keep) live &= ~outl;
    }
    for (s = 0; s < raw; s++) {
        const uint32_t bit = 1u << s;
        if ((live & bit) == 0u) continue;
        if ((outl & bit) != 0u) sol[s].flags |= DH_IKC_OUT_OF_LIMITS;
        if (n != s) sol[n] = sol[s];
        n++;
    }
    for (s = n; s < raw; s++) sol[s].flags = 0u;
    *n_sol = n;
    if (n != 0u) return DH_OK;
    /* none kept: unreachable unless a solution is finite in every joint
     * (the conversion keeps a value finite exactly when it was, so the
     * joints left unconverted after a limit answer the same) */
    for (s = 0; s < raw; s++)
        if (((fin >> s) & 1u) != 0u && !dh_allfinite_f32(sol[s].q, m->n)) fin &= ~(1u << s);
    return (fin == 0u) ? DH_ERR_UNREACHABLE : DH_ERR_LIMIT;
}

/* dh_ikc_f32's conversion: ikc_finish, or ikc_finish6 when it applies
 * (opts 0, six revolute joints with narrow limits, an FPU: with soft
 * float its constants would not stay in registers, and its frame would
 * not fit under the Cortex-M0+ budget); *n_sol as ikc_finish's. Both
 * builds of a core take the same one (the entries of sol beyond the kept
 * ones, which the two leave differently, then agree between builds). */
DH_INLINE dh_status ikc_done(const dh_ikc_model_f32 *m, const float *q_ref, dh_ikc_sol_f32 *sol, uint32_t *n_sol)
{
    if (!DH_SOFT_FLOAT && m->wide == 0u && (*n_sol >> 4) == 0u && m->n == 6u && m->prismatic == 0u)
        return ikc_finish6(m, q_ref, sol, n_sol);
    return ikc_finish(m, q_ref, sol, n_sol);
}

/* 1 when dh_ikc_f32 solves m pruned by its limit windows first (m->lim_w,
 * ikc_windows): opts 0 (the limits apply), with an FPU (the one-pass
 * wrist solver leaves branches), a finite window on a spherical-wrist
 * family of an exact model (lim_any, ikc_found: the refinement moves a
 * calibrated model's values). The solutions kept are those of the full
 * solve: the window drops only branches whose joints 1-3 the conversion
 * finds outside the limits. */
DH_INLINE int ikc_prune(const dh_ikc_model_f32 *m, uint32_t opts)
{
    return !DH_SOFT_FLOAT && opts == 0u && m->lim_any != 0u;
}

dh_status dh_ikc_args_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *q_ref, uint32_t opts)
{
    const dh_status st = ikc_args(m, T, q_ref, opts);
    /* the refinement of a calibrated model runs in dh_ikc_f32 only */
    return (st == DH_OK && m->calibrated != 0u) ? DH_ERR_UNAVAILABLE : st;
}

dh_status dh_ikc_finish_f32_(const dh_ikc_model_f32 *m, const float *q_ref, uint32_t opts, dh_ikc_sol_f32 *sol,
                             uint32_t *n_sol)
{
    uint32_t raw = *n_sol;
    *n_sol = 0;
    if (raw > DH_IKC_MAX_SOL) raw = DH_IKC_MAX_SOL;
    if (raw == 0u) return DH_ERR_UNREACHABLE;
    *n_sol = raw | (opts << 4);
    return ikc_finish(m, q_ref, sol, n_sol);
}

dh_status dh_ikc_f32(const dh_ikc_model_f32 *m, const dh_mat4_f32 *target, const float *q_ref, uint32_t opts,
                     dh_ikc_sol_f32 *sol, uint32_t *n_sol)
{
    uint32_t raw;
    dh_status st;
    DH_ASSERT(m != NULL);
    DH_ASSERT(target != NULL);
    DH_ASSERT(sol != NULL);
    DH_ASSERT(n_sol != NULL);
    *n_sol = 0;
    st = ikc_args(m, target, q_ref, opts);
    if (st != DH_OK) return st;
    /* opts waits in *n_sol while the solver runs: one value fewer kept
     * across it, so that the target can be (the refinement of a calibrated
     * model reads it) within the same frame */
    *n_sol = opts << 4;
    if (ikc_prune(m, opts)) {
        /* the branches within the limits' windows; when none of them is
         * kept, the full solve below decides the status (DH_ERR_LIMIT or
         * DH_ERR_UNREACHABLE) */
        raw = dh_ikc_wrist_lim_f32_(m, target, q_ref, sol);
        if (raw != 0u) {
            *n_sol = (raw > DH_IKC_MAX_SOL) ? DH_IKC_MAX_SOL : raw;
            st = ikc_done(m, q_ref, sol, n_sol);
            if (st == DH_OK) return st;
        }
        *n_sol = 0u;
    }
    raw = dh_ikc_raw_f32_(m, target, q_ref, sol);
    if (m->calibrated != 0u) {
        raw = dh_ikc_refine_f32_(m, target, sol, raw);
        raw = dh_ikc_pack_f32_(sol, raw);
    }
    if (raw > DH_IKC_MAX_SOL) raw = DH_IKC_MAX_SOL;
    if (raw == 0u) {
        *n_sol = 0;
        return DH_ERR_UNREACHABLE;
    }
    *n_sol |= raw;
    return ikc_done(m, q_ref, sol, n_sol);
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
