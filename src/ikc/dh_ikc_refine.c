/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_ikc_refine.c - closed-form IK of calibrated robots, float: the
 * recognition of a six-revolute chain within the calibration tolerance of
 * DH_IKC_PARALLEL_234 or of the spherical-wrist family DH_IKC_WRIST_RRR
 * (dh_ikc_calibrate_f32_, called by dh_ikc_analyse_f32 after the exact
 * detectors), the evaluation helpers of every family's refinement
 * (ikc_refine.h) and the refinement of DH_IKC_PARALLEL_234's raw
 * solutions on the exact chain (dh_ikc_refine_par234_f32_, called by
 * dh_ikc_f32 after the family solver has returned; the spherical wrist's:
 * dh_ikc_refine_wrist.c); interface in ikc_impl.h. Method and convergence
 * argument: docs/design.md ("Calibrated robots").
 *
 * Refinement of one branch: simplified Newton steps with the idealised
 * chain's Jacobian in the frame-1 split of the family (the errors in the
 * basis of frame 1: the position error of the joint 5 point along axis 2
 * and the rotation error across it depend on joints 1, 5, 6 only; the
 * planar position error and the rotation about axis 2 on joints 2, 3, 4
 * once those are known), each step one exact forward kinematics.
 *
 * A shoulder whose four branches are not all refined then starts again
 * from the virtual target of one of its branches (the exact errors there
 * applied to the idealised chain's T06), solved in closed form for each of
 * its missing or unconverged branches, and refines those starts.
 *
 * Stack: the entry keeps 24 floats (the cosines and sines of the branch's
 * joints, and the exact frame or the errors, or the virtual target and the
 * one-branch closed form's atan2 arguments); every helper runs from the
 * entry in sequence, none below another, and only the trigonometry and
 * angle helpers call dh_sincos_f32 and dh_atan2f_dg_.
 */
#include "dhmath/ikc.h"
#include "dhmath/trig.h"
#include "ikc_impl.h"
#include "ikc_refine.h"
#include "../internal/dh_floatops.h"

#include <math.h>
#include <stddef.h>

/* sin of DH_IKC_CAL_ANGLE_DEG (1 degree) */
#define REF_SIN_TOL 0.0174524064f
/* Converged: position error of the joint 5 point at most REF_POS_REL L (L:
 * the sum of the exact chain's |a| and |d|) and rotation error at most
 * REF_ROT rad. */
#define REF_POS_REL 4e-7f
#define REF_ROT 8e-7f
/* Largest joint step (rad): a larger Newton step is scaled down to it. */
#define REF_MAX_STEP 0.2f
/* |sin theta5| or a planar determinant below this (relative): the branch
 * is at a singularity of the idealised Jacobian and is not refined. */
#define REF_SING_TOL 1e-6f
/* Two refined solutions this close on every joint (deg) are one. */
#define REF_SAME_DEG 1e-3f

/* m->k layout of DH_IKC_PARALLEL_234 (dh_ikc_par234.c), the entries read here */
enum {
    RK_TAU = 0, RK_S2 = 1, RK_S23 = 2, RK_SB = 3, RK_W5 = 4, RK_H = 5, RK_D = 6, RK_A23 = 7, RK_E5 = 8,
    RK_W0 = 12, RK_SUM2 = 18, RK_DIF2 = 19
};
/* the branch bits of a solution's flags */
#define REF_BRANCH (DH_IKC_SHOULDER_ALT | DH_IKC_ELBOW_ALT | DH_IKC_WRIST_ALT)
#define REF_SING (DH_IKC_SING_WRIST | DH_IKC_SING_SHOULDER | DH_IKC_SING_ELBOW)

/* ---- analysis -------------------------------------------------------------------- */

/* The twists of m snapped to the nearest multiple of 90 degrees where within
 * 1 degree of it. */
static void ref_snap_twists(dh_ikc_model_f32 *m)
{
    uint32_t i;
    for (i = 0; i < 6u; i++) {
        if (fabsf(m->sa[i]) <= REF_SIN_TOL) {
            m->sa[i] = 0.0f;
            m->ca[i] = dh_ikc_sign_f32_(m->ca[i]);
        } else if (fabsf(m->ca[i]) <= REF_SIN_TOL) {
            m->ca[i] = 0.0f;
            m->sa[i] = dh_ikc_sign_f32_(m->sa[i]);
        } else {
            /* a general twist: kept */
        }
    }
}

/* the exact chain of m (a..ca) copied to xa..xca (to 1) or back, xa..xca
 * cleared (to 0) */
static void ref_keep(dh_ikc_model_f32 *m, int to)
{
    uint32_t i;
    for (i = 0; i < DH_IKC_JOINTS; i++) {
        if (to) {
            m->xa[i] = m->a[i];
            m->xd[i] = m->d[i];
            m->xsa[i] = m->sa[i];
            m->xca[i] = m->ca[i];
        } else {
            m->a[i] = m->xa[i];
            m->d[i] = m->xd[i];
            m->sa[i] = m->xsa[i];
            m->ca[i] = m->xca[i];
            m->xa[i] = 0.0f;
            m->xd[i] = 0.0f;
            m->xsa[i] = 0.0f;
            m->xca[i] = 0.0f;
        }
    }
}

int dh_ikc_calibrated_f32_(dh_ikc_model_f32 *m, int ok)
{
    uint32_t i;
    if (!ok) {
        ref_keep(m, 0);
        m->kind = DH_IKC_NONE;
        return 0;
    }
    m->calibrated = 1u;
    m->xlen = 0.0f;
    for (i = 0; i < 6u; i++) m->xlen += fabsf(m->xa[i]) + fabsf(m->xd[i]);
    if (!(m->xlen > 0.0f)) m->xlen = 1.0f;
    /* post^-1 (-a6, -d6 sa6, -d6 ca6): frame 5's origin seen from the tool */
    m->xw5[0] = -m->xa[5];
    m->xw5[1] = -m->xd[5] * m->xsa[5];
    m->xw5[2] = -m->xd[5] * m->xca[5];
    dh_ikc_xform_f32_(&m->post_inv, m->xw5, 1.0f, m->xw5);
    m->xframes = (dh_ikc_is_identity_f32_(&m->pre_inv) ? 0u : 1u) | (dh_ikc_is_identity_f32_(&m->post_inv) ? 0u : 2u);
    return 1;
}

int dh_ikc_calibrate_f32_(dh_ikc_model_f32 *m)
{
    float tol;
    if (m->n != 6u || m->prismatic != 0u) return 0;
    ref_keep(m, 1);
    ref_snap_twists(m);
    tol = DH_IKC_CAL_OFFSET_REL * dh_ikc_len_scale_f32_(m, 6u);
    if (fabsf(m->a[4]) <= tol) m->a[4] = 0.0f;
    if (dh_ikc_detect_par234_f32_(m)) return dh_ikc_calibrated_f32_(m, 1);
    /* the spherical wrist's idealisation: a4 and d5 within tol as 0 too,
     * which makes axes 4, 5, 6 meet; its detector runs from the caller */
    if (fabsf(m->a[3]) <= tol) m->a[3] = 0.0f;
    if (fabsf(m->d[4]) <= tol) m->d[4] = 0.0f;
    return 2;
}

/* ---- refinement ------------------------------------------------------------------ */

/* cs of the canonical values q (of the joint values being refined, so
 * that the verdict is on them) */
DH_NOINLINE void dh_ikc_ref_trig_f32_(const float *q, dh_ikc_ref_work_f32 *w)
{
    uint32_t i;
    for (i = 0; i < 12u; i += 2u) (void)dh_sincos_f32(q[i >> 1], &w->cs[i + 1u], &w->cs[i]);
}

/* Byte offsets of d, sin and cos of the twist from a in the model's
 * idealised chain, the same in its exact chain (xa..xca; checked below). */
#define REF_OD (offsetof(dh_ikc_model_f32, d) - offsetof(dh_ikc_model_f32, a))
#define REF_OS (offsetof(dh_ikc_model_f32, sa) - offsetof(dh_ikc_model_f32, a))
#define REF_OC (offsetof(dh_ikc_model_f32, ca) - offsetof(dh_ikc_model_f32, a))
typedef char ref_chain_layout_[(offsetof(dh_ikc_model_f32, xd) - offsetof(dh_ikc_model_f32, xa) == REF_OD &&
                                offsetof(dh_ikc_model_f32, xsa) - offsetof(dh_ikc_model_f32, xa) == REF_OS &&
                                offsetof(dh_ikc_model_f32, xca) - offsetof(dh_ikc_model_f32, xa) == REF_OC)
                                   ? 1
                                   : -1];

/* Joint j's value at byte offset o from a (or xa) of the chain at c. */
#define REF_CH(c, o, j) (*(const float *)(const void *)((c) + (o) + sizeof(float) * (j)))

/* dh_ikc_ref_fk_f32_ with soft float: u updated in place, per joint the
 * turn about z, the offsets, the twist, each a pass over the three rows
 * (a frame of a few words where every float lives in memory anyway). */
DH_NOINLINE void dh_ikc_ref_fk_rows_f32_(dh_ikc_ref_work_f32 *w, int ideal)
{
    const unsigned char *c = (const unsigned char *)(const void *)w->m +
                             (ideal ? offsetof(dh_ikc_model_f32, a) : offsetof(dh_ikc_model_f32, xa));
    float *u = w->u;
    uint32_t i, r;
    for (r = 0; r < 12u; r++) u[r] = ((r & 3u) == 0u && r < 9u) ? 1.0f : 0.0f;
    for (i = 0; i < 6u; i++) {
        const float *cs = &w->cs[2u * i];
        for (r = 0; r < 3u; r++) {
            const float x = u[r];
            u[r] = cs[0] * x + cs[1] * u[3u + r];
            u[3u + r] = cs[0] * u[3u + r] - cs[1] * x;
            u[9u + r] += REF_CH(c, REF_OD, i) * u[6u + r] + REF_CH(c, 0u, i) * u[r];
        }
        for (r = 0; r < 3u; r++) {
            const float y = u[3u + r];
            u[3u + r] = REF_CH(c, REF_OC, i) * y + REF_CH(c, REF_OS, i) * u[6u + r];
            u[6u + r] = REF_CH(c, REF_OC, i) * u[6u + r] - REF_CH(c, REF_OS, i) * y;
        }
    }
    for (r = 0; r < 3u; r++)
        u[9u + r] -= REF_CH(c, 0u, 5u) * u[r] +
                     REF_CH(c, REF_OD, 5u) * (REF_CH(c, REF_OS, 5u) * u[3u + r] + REF_CH(c, REF_OC, 5u) * u[6u + r]);
}

/* dh_ikc_ref_fk_f32_ with an FPU: the frame (columns x, y, z and the
 * point) held in locals, which stay in registers, and stored once: joint 1
 * from the identity (its columns and point written out), joints 2 to 5 in
 * full, their point the joint 5 point (frame 5's origin), joint 6 its
 * rotation only. */
DH_NOINLINE void dh_ikc_ref_fk_regs_f32_(dh_ikc_ref_work_f32 *w, int ideal)
{
    const unsigned char *c = (const unsigned char *)(const void *)w->m +
                             (ideal ? offsetof(dh_ikc_model_f32, a) : offsetof(dh_ikc_model_f32, xa));
    const float *cs = w->cs;
    float *u = w->u;
    const float sa1 = REF_CH(c, REF_OS, 0u), ca1 = REF_CH(c, REF_OC, 0u), a1 = REF_CH(c, 0u, 0u);
    float x0 = cs[0], x1 = cs[1], x2 = 0.0f, y0 = -ca1 * cs[1], y1 = ca1 * cs[0], y2 = sa1;
    float z0 = sa1 * cs[1], z1 = -sa1 * cs[0], z2 = ca1;
    float p0 = a1 * cs[0], p1 = a1 * cs[1], p2 = REF_CH(c, REF_OD, 0u);
    float t0, t1, t2, ct, st, sa, ca;
    uint32_t i;
    for (i = 1u; i < 5u; i++) {
        const float ai = REF_CH(c, 0u, i), di = REF_CH(c, REF_OD, i);
        ct = cs[2u * i];
        st = cs[2u * i + 1u];
        sa = REF_CH(c, REF_OS, i);
        ca = REF_CH(c, REF_OC, i);
        p0 += di * z0;
        p1 += di * z1;
        p2 += di * z2;
        t0 = ct * y0 - st * x0;
        t1 = ct * y1 - st * x1;
        t2 = ct * y2 - st * x2;
        x0 = ct * x0 + st * y0;
        x1 = ct * x1 + st * y1;
        x2 = ct * x2 + st * y2;
        p0 += ai * x0;
        p1 += ai * x1;
        p2 += ai * x2;
        y0 = ca * t0 + sa * z0;
        y1 = ca * t1 + sa * z1;
        y2 = ca * t2 + sa * z2;
        z0 = ca * z0 - sa * t0;
        z1 = ca * z1 - sa * t1;
        z2 = ca * z2 - sa * t2;
    }
    ct = cs[10];
    st = cs[11];
    sa = REF_CH(c, REF_OS, 5u);
    ca = REF_CH(c, REF_OC, 5u);
    t0 = ct * y0 - st * x0;
    t1 = ct * y1 - st * x1;
    t2 = ct * y2 - st * x2;
    u[0] = ct * x0 + st * y0;
    u[1] = ct * x1 + st * y1;
    u[2] = ct * x2 + st * y2;
    u[3] = ca * t0 + sa * z0;
    u[4] = ca * t1 + sa * z1;
    u[5] = ca * t2 + sa * z2;
    u[6] = ca * z0 - sa * t0;
    u[7] = ca * z1 - sa * t1;
    u[8] = ca * z2 - sa * t2;
    u[9] = p0;
    u[10] = p1;
    u[11] = p2;
}

/* u's rotation times the tool frame's (post = post_inv^-1, rotation S^T),
 * when there is one */
DH_NOINLINE void dh_ikc_ref_tool_f32_(dh_ikc_ref_work_f32 *w)
{
    const dh_mat4_f32 *P = &w->m->post_inv;
    float *u = w->u;
    uint32_t c, r;
    if ((w->m->xframes & 2u) == 0u) return;
    for (r = 0; r < 3u; r++) {
        const float x = u[r], y = u[3u + r], z = u[6u + r];
        for (c = 0; c < 3u; c++) u[3u * c + r] = x * P->m[0][c] + y * P->m[1][c] + z * P->m[2][c];
    }
}

/* u <- pre u (pre = pre_inv^-1 = (R^T, -R^T p): each column v to R^T v,
 * the point to R^T (v - p)), when there is a base frame */
DH_NOINLINE void dh_ikc_ref_base_f32_(dh_ikc_ref_work_f32 *w)
{
    const dh_mat4_f32 *P = &w->m->pre_inv;
    float *u = w->u;
    uint32_t c, r;
    if ((w->m->xframes & 1u) == 0u) return;
    for (r = 0; r < 3u; r++) u[9u + r] -= P->m[3][r];
    for (c = 0; c < 4u; c++) {
        float *v = &u[3u * c];
        const float x = v[0], y = v[1], z = v[2];
        for (r = 0; r < 3u; r++) v[r] = P->m[r][0] * x + P->m[r][1] * y + P->m[r][2] * z;
    }
}

/* The rotation error (x x xt + y x yt + z x zt) / 2 (rad) of u (the exact
 * chain's end frame) against the target into u[3..5] (the rotation is not
 * read after it). */
DH_NOINLINE void dh_ikc_ref_rot_f32_(dh_ikc_ref_work_f32 *w)
{
    const dh_mat4_f32 *T = w->T;
    float *u = w->u;
    float e0 = 0.0f, e1 = 0.0f, e2 = 0.0f;
    uint32_t k;
    for (k = 0; k < 3u; k++) {
        const float *t = T->m[k];
        const float v0 = u[3u * k], v1 = u[3u * k + 1u], v2 = u[3u * k + 2u];
        e0 += v1 * t[2] - v2 * t[1];
        e1 += v2 * t[0] - v0 * t[2];
        e2 += v0 * t[1] - v1 * t[0];
    }
    u[3] = 0.5f * e0;
    u[4] = 0.5f * e1;
    u[5] = 0.5f * e2;
}

/* The position error of the joint 5 point (u[9..11]) against the target
 * into u[0..2], the point into u[6..8]; then the verdict on branch b after
 * it steps: converged (|position error| <= tp = REF_POS_REL L and
 * |rotation error| <= REF_ROT, in the sum of their squares over the
 * squared bounds): b flagged DH_IKC_REFINED, DH_IKC_REF_DONE returned; an error
 * not finite: DH_IKC_REF_DONE; else it + 1 (DH_IKC_REF_DONE after DH_IKC_CAL_STEPS). */
DH_NOINLINE uint32_t dh_ikc_ref_pos_f32_(dh_ikc_ref_work_f32 *w, dh_ikc_sol_f32 *b, uint32_t it)
{
    const dh_mat4_f32 *T = w->T;
    const float *p = w->m->xw5;
    float *u = w->u;
    float ep = 0.0f, tp;
    uint32_t k;
    for (k = 0; k < 3u; k++) {
        u[k] = T->m[3][k] + T->m[0][k] * p[0] + T->m[1][k] * p[1] + T->m[2][k] * p[2] - u[9u + k];
        ep += u[k] * u[k];
        u[6u + k] = u[9u + k];
    }
    tp = REF_POS_REL * w->m->xlen;
    ep = ep / (tp * tp) + (u[3] * u[3] + u[4] * u[4] + u[5] * u[5]) * (1.0f / (REF_ROT * REF_ROT));
    if (ep <= 1.0f) {
        b->flags |= DH_IKC_REFINED;
        return DH_IKC_REF_DONE;
    }
    return (ep <= 1e30f) ? (it + 1u) : DH_IKC_REF_DONE;
}

/* The start of branch b: its DH_IKC_REFINED flag cleared; the step count 0,
 * or DH_IKC_REF_DONE when b is not finite. */
DH_NOINLINE uint32_t dh_ikc_ref_begin_f32_(dh_ikc_sol_f32 *b)
{
    b->flags &= ~(uint32_t)DH_IKC_REFINED;
    return dh_allfinite_f32(b->q, 6u) ? 0u : DH_IKC_REF_DONE;
}

/* dh_ikc_ref_pos_f32_'s errors and point into the basis of the idealised frame 1, in
 * place: pre^-1 (skipped when the identity), then Rz(theta1)^T,
 * Rx(alpha1)^T; the point from frame 1's origin (a1 c1, a1 s1, d1). */
DH_NOINLINE void dh_ikc_ref_frame1_f32_(dh_ikc_ref_work_f32 *w)
{
    const dh_ikc_model_f32 *m = w->m;
    const dh_mat4_f32 *P = &m->pre_inv;
    float *u = w->u;
    uint32_t k, r;
    if ((m->xframes & 1u) != 0u)
        for (k = 0; k < 3u; k++) {
            float *v = &u[3u * k];
            const float x = v[0], y = v[1], z = v[2];
            for (r = 0; r < 3u; r++) v[r] = P->m[0][r] * x + P->m[1][r] * y + P->m[2][r] * z + ((k == 2u) ? P->m[3][r] : 0.0f);
        }
    u[6] -= m->a[0] * w->cs[0];
    u[7] -= m->a[0] * w->cs[1];
    u[8] -= m->d[0];
    for (k = 0; k < 3u; k++) {
        float *v = &u[3u * k];
        const float x = v[0];
        v[0] = w->cs[0] * x + w->cs[1] * v[1];
        v[1] = w->cs[0] * v[1] - w->cs[1] * x;
    }
    for (k = 0; k < 3u; k++) {
        float *v = &u[3u * k];
        const float y = v[1];
        v[1] = m->ca[0] * y + m->sa[0] * v[2];
        v[2] = m->ca[0] * v[2] - m->sa[0] * y;
    }
}

/* cos and sin of phi = theta2 + s2 theta3 (with4 0) or + s23 theta4 into
 * cp[0], cp[1] */
static void ref_phi(const dh_ikc_model_f32 *m, const float *cs, int with4, float *cp)
{
    const float s2 = m->k[RK_S2];
    cp[0] = cs[2] * cs[4] - s2 * cs[3] * cs[5];
    cp[1] = cs[3] * cs[4] + s2 * cs[2] * cs[5];
    if (with4) {
        const float s23 = m->k[RK_S23], c = cp[0], s = cp[1];
        cp[0] = c * cs[6] - s23 * s * cs[7];
        cp[1] = s * cs[6] + s23 * c * cs[7];
    }
}

/* Joints 1, 5, 6 (rad) from the errors along axis 2 and the rotation error
 * across it (rows lin_z, ang_x, ang_y of the idealised Jacobian in frame 1:
 * joint 1 (-tau (px + a1), 0, tau), joint 5 (0, sb sphi, -sb cphi), joint 6
 * (0, w5 s5 cphi, w5 s5 sphi)) into u[9..11]; 0 at a singularity. */
static DH_NOINLINE int ref_a(dh_ikc_ref_work_f32 *w)
{
    const dh_ikc_model_f32 *m = w->m;
    float *u = w->u;
    float d1, r2;
    if (!(fabsf(u[6] + m->a[0]) > REF_SING_TOL * (fabsf(u[6]) + fabsf(u[7]) + fabsf(m->a[0]))) ||
        !(fabsf(w->cs[9]) > REF_SING_TOL))
        return 0;
    d1 = -m->k[RK_TAU] * u[2] / (u[6] + m->a[0]);
    r2 = u[4] - m->k[RK_TAU] * d1;
    ref_phi(m, w->cs, 1, &u[9]);
    u[11] = m->k[RK_W5] * (u[9] * u[3] + u[10] * r2) / w->cs[9];
    u[10] = m->k[RK_SB] * (u[10] * u[3] - u[9] * r2);
    u[9] = d1;
    return 1;
}

/* Joints 2, 3, 4 (rad) into u[6..8] from the planar errors and the
 * rotation about axis 2 less the parts of joints 1 and 6 (u[9], u[11]):
 * rows lin_x, lin_y, ang_z of the idealised Jacobian in frame 1, a planar
 * 3R (o2 u3 + o3 u4 = p om - (ey, -ex) with u3 = s2 dtheta3, u4 = s23
 * dtheta4, om their sum with dtheta2; o2, o3 the origins of frames 2, 3).
 * 0 at a singularity (elbow stretched or folded). */
static DH_NOINLINE int ref_b(dh_ikc_ref_work_f32 *w)
{
    const dh_ikc_model_f32 *m = w->m;
    float *u = w->u;
    float cp[2], det, om, gx, gy, u3;
    ref_phi(m, w->cs, 0, cp);
    /* o3 = a2 (c2, s2) + a3 (cos, sin)(theta2 + s2 theta3) into cp */
    cp[0] = m->a[1] * w->cs[2] + m->a[2] * cp[0];
    cp[1] = m->a[1] * w->cs[3] + m->a[2] * cp[1];
    det = m->a[1] * (w->cs[2] * cp[1] - w->cs[3] * cp[0]);
    if (!(fabsf(det) > REF_SING_TOL * fabsf(m->a[1] * m->a[2]))) return 0;
    om = u[5] + m->k[RK_SB] * m->k[RK_W5] * w->cs[8] * u[11];
    gx = u[6] * om - u[1];
    gy = u[7] * om + (u[0] - m->k[RK_TAU] * u[8] * u[9]);
    u3 = (gx * cp[1] - gy * cp[0]) / det;
    gx = m->a[1] * (w->cs[2] * gy - w->cs[3] * gx) / det;
    u[6] = om - u3 - gx;
    u[7] = m->k[RK_S2] * u3;
    u[8] = m->k[RK_S23] * gx;
    return 1;
}

/* The steps (rad; joints 1, 5, 6 in u[9..11], 2, 3, 4 in u[6..8]),
 * scaled to at most REF_MAX_STEP, added to q (degrees, wrapped), with cs
 * following: each step r (rad) as applied (the difference of the degree
 * values before the wrap: exact in float when the step is smaller than
 * the value (Fast2Sum), else within half an ulp of the step) turns the
 * joint's cosine and sine by the series of cos r to r^6 and sin r to r^5
 * (within 3e-9 up to REF_MAX_STEP), then they are scaled back to unit
 * length (one Newton step of 1 / sqrt). 0 when not finite. */
DH_NOINLINE int dh_ikc_ref_apply_f32_(dh_ikc_ref_work_f32 *w, float *q)
{
    /* joint i's step in u[ref_order[i]] */
    static const uint8_t ref_order[6] = { 9u, 6u, 7u, 8u, 10u, 11u };
    const float *u = w->u;
    float big = 0.0f, f = 1.0f;
    uint32_t i;
    for (i = 6u; i < 12u; i++)
        if (fabsf(u[i]) > big) big = fabsf(u[i]);
    if (!(big <= 1e30f)) return 0;
    if (big > REF_MAX_STEP) f = REF_MAX_STEP / big;
    f *= DH_RAD2DEG_F;
    for (i = 0; i < 6u; i++) {
        float *cs = &w->cs[2u * i];
        const float v = q[i] + f * u[ref_order[i]];
        const float r = DH_DEG2RAD_F * (v - q[i]), r2 = r * r;
        const float sd = r * (1.0f - (r2 * (1.0f / 6.0f)) * (1.0f - r2 * (1.0f / 20.0f)));
        const float cd = 1.0f - (r2 * 0.5f) * (1.0f - (r2 * (1.0f / 12.0f)) * (1.0f - r2 * (1.0f / 30.0f)));
        const float c = cs[0] * cd - cs[1] * sd, s = cs[1] * cd + cs[0] * sd;
        const float k = 1.5f - 0.5f * (c * c + s * s);
        cs[0] = c * k;
        cs[1] = s * k;
        q[i] = (fabsf(v) < 180.0f) ? v : dh_wrap180_f32(v);
    }
    return 1;
}

uint32_t dh_ikc_pack_f32_(dh_ikc_sol_f32 *sol, uint32_t raw)
{
    uint32_t s, k, i, n = 0;
    if (raw > DH_IKC_MAX_SOL) raw = DH_IKC_MAX_SOL;
    for (s = 0; s < raw; s++) {
        int keep = (sol[s].flags & DH_IKC_REFINED) != 0u;
        for (k = 0; keep && k < n; k++) {
            for (i = 0; i < 6u; i++) {
                float d = fabsf(sol[k].q[i] - sol[s].q[i]);
                if (d > 180.0f) d = 360.0f - d;
                if (!(d <= REF_SAME_DEG)) break;
            }
            if (i == 6u) keep = 0;
        }
        if (!keep) continue;
        if (n != s) sol[n] = sol[s];
        n++;
    }
    for (s = n; s < raw; s++) sol[s].flags = 0u;
    return n;
}

/* Private flag bits of the slots while dh_ikc_refine_f32_ runs, cleared
 * before it returns: a slot waiting for a start from the virtual target
 * (ref_plan), one waiting for its refinement (a raw branch, or started by
 * ref_start), and a free one. */
#define REF_PEND 0x100u
#define REF_NEW 0x200u
#define REF_FREE 0x400u
#define REF_PRIVATE 0x700u
/* dh_ikc_refine_f32_'s rounds take slot k & 7 and round k >> 3 */
typedef char ref_eight_slots_[(DH_IKC_MAX_SOL == 8u) ? 1 : -1];

/* The first-order virtual target of the canonical values q whose exact
 * errors (dh_ikc_ref_rot_f32_, dh_ikc_ref_pos_f32_: the joint 5 point's position error and the
 * rotation error, base frame) are in e, from the idealised chain's T06 at q
 * in u (dh_ikc_ref_fk_f32_, ideal): T'06 = the errors applied to it, the target whose
 * idealised solution of q's branch is q up to the change of the
 * deviations' effect between q and that solution. Its vectors as the
 * family solver reads them (the joint 5 point, x6 and axis 6) into u[0..8]. */
static DH_NOINLINE void ref_virtual(dh_ikc_ref_work_f32 *w, float *e)
{
    const dh_ikc_model_f32 *m = w->m;
    const dh_mat4_f32 *P = &m->pre_inv;
    float *u = w->u;
    uint32_t k;
    if ((m->xframes & 1u) != 0u)
        for (k = 0; k < 6u; k += 3u) {
            float *v = &e[k];
            const float x = v[0], y = v[1], z = v[2];
            v[0] = P->m[0][0] * x + P->m[1][0] * y + P->m[2][0] * z;
            v[1] = P->m[0][1] * x + P->m[1][1] * y + P->m[2][1] * z;
            v[2] = P->m[0][2] * x + P->m[1][2] * y + P->m[2][2] * z;
        }
    /* axis 6, then x6, each turned by the rotation error; the point moved by the position error */
    for (k = 0; k < 3u; k++) u[3u + k] = m->sa[5] * u[3u + k] + m->ca[5] * u[6u + k];
    for (k = 0; k < 6u; k += 3u) {
        const float *a = &u[(k == 0u) ? 3u : 0u];
        float *o = &u[(k == 0u) ? 6u : 3u];
        const float x = a[0], y = a[1], z = a[2];
        o[0] = x + e[4] * z - e[5] * y;
        o[1] = y + e[5] * x - e[3] * z;
        o[2] = z + e[3] * y - e[4] * x;
    }
    for (k = 0; k < 3u; k++) u[k] = u[9u + k] + e[k];
}

/* The idealised chain's solution of branch f (shoulder, wrist and elbow
 * bits) for the target whose vectors are in u (ref_virtual): the closed
 * form of DH_IKC_PARALLEL_234 (docs/design.md) for one branch, in four
 * helpers: ref_bs the shoulder, ref_bw and ref_b6 the wrist, ref_be the elbow, each writing
 * the arguments of its angles into cs (atan2 (y, x) pairs: joint 1 at 0,
 * 5 at 2, 6 at 4, 3 at 6, 2 at 8; cos and sin of phi at 10), ref_angles
 * the angles into q. 0 when the branch does not exist there (beyond the
 * shoulder cylinder or the elbow's reach, or the wrist singular). */
static DH_NOINLINE int ref_bs(dh_ikc_ref_work_f32 *w, uint32_t f)
{
    const float *k = w->m->k, *p = w->u;
    const float th = k[RK_TAU] * k[RK_H];
    float *o = w->cs;
    float r = p[0] * p[0] + p[1] * p[1] - k[RK_H] * k[RK_H];
    if (!(r > 0.0f)) return 0;
    r = dh_sqrt_f32(r);
    if ((f & DH_IKC_SHOULDER_ALT) != 0u) r = -r;
    o[1] = r * p[0] - th * p[1];
    o[0] = th * p[0] + r * p[1];
    r = 1.0f / dh_sqrt_f32(o[0] * o[0] + o[1] * o[1]);
    o[0] *= r;
    o[1] *= r;
    return 1;
}

static DH_NOINLINE int ref_bw(dh_ikc_ref_work_f32 *w)
{
    const float *k = w->m->k, *z = &w->u[6];
    const float tau = k[RK_TAU], sb = k[RK_SB], w5 = k[RK_W5];
    float *o = w->cs;
    const float c1 = o[1], s1 = o[0];
    float s5, cp, sp;
    cp = c1 * z[0] + s1 * z[1];
    sp = tau * z[2];
    s5 = dh_sqrt_f32(cp * cp + sp * sp);
    if (!(s5 > REF_SING_TOL)) return 0;
    o[2] = s5;
    o[3] = -sb * w5 * tau * (s1 * z[0] - c1 * z[1]);
    o[10] = w5 * cp / s5;
    o[11] = w5 * sp / s5;
    return 1;
}

/* Joint 6's pair from the first column (n11 = x1 . x6, n21 = y1 . x6,
 * n31 = z1 . x6), then the wrist flip of f. */
static DH_NOINLINE void ref_b6(dh_ikc_ref_work_f32 *w, uint32_t f)
{
    const float *k = w->m->k, *x = &w->u[3];
    float *o = w->cs;
    float n11, n21;
    o[5] = k[RK_SB] * k[RK_TAU] * o[2] * (o[0] * x[0] - o[1] * x[1]);
    n11 = o[1] * x[0] + o[0] * x[1];
    n21 = k[RK_TAU] * x[2];
    o[5] += o[3] * (o[10] * n11 + o[11] * n21);
    o[4] = -k[RK_W5] * k[RK_SB] * (o[10] * n21 - o[11] * n11);
    if ((f & DH_IKC_WRIST_ALT) != 0u) {
        o[2] = -o[2];
        o[4] = -o[4];
        o[5] = -o[5];
        o[10] = -o[10];
        o[11] = -o[11];
    }
}

static DH_NOINLINE int ref_be(dh_ikc_ref_work_f32 *w, uint32_t f)
{
    const dh_ikc_model_f32 *m = w->m;
    const float *k = m->k, *p = w->u;
    float *o = w->cs;
    float vx, vy, v2, r, kd, ad, bd;
    vx = o[1] * p[0] + o[0] * p[1] - m->a[0] - m->a[3] * o[10] - k[RK_E5] * o[11];
    vy = k[RK_TAU] * (p[2] - m->d[0]) - m->a[3] * o[11] + k[RK_E5] * o[10];
    v2 = vx * vx + vy * vy;
    r = (k[RK_SUM2] - v2) * (v2 - k[RK_DIF2]);
    if (!(r >= 0.0f)) return 0;
    r = dh_sqrt_f32(r);
    if ((f & DH_IKC_ELBOW_ALT) != 0u) r = -r;
    kd = (k[RK_D] < 0.0f) ? k[RK_A23] - v2 : v2 - k[RK_A23];
    ad = m->a[1] * fabsf(k[RK_D]) + m->a[2] * kd;
    bd = k[RK_S2] * m->a[2] * r;
    o[6] = r;
    o[7] = kd;
    o[8] = ad * vy - bd * vx;
    o[9] = ad * vx + bd * vy;
    return 1;
}

static DH_NOINLINE void ref_angles(float *o, float *q)
{
    /* a start: (0, 0) pairs need no rule of their own */
    q[0] = dh_atan2f_dg_(o[0], o[1]);
    q[4] = dh_atan2f_dg_(o[2], o[3]);
    q[5] = dh_atan2f_dg_(o[4], o[5]);
    q[2] = dh_atan2f_dg_(o[6], o[7]);
    q[1] = dh_atan2f_dg_(o[8], o[9]);
    o[10] = dh_atan2f_dg_(o[11], o[10]);
}

/* The branches of shoulder sh (0 or DH_IKC_SHOULDER_ALT) that did not
 * converge, or that the idealised chain did not have, marked REF_PEND
 * (those that did not converge in their slots, the missing ones in free
 * slots while there are any); returns the first of them, which holds the
 * values of the branch whose virtual target starts them (a converged one
 * when there is one), and DH_IKC_MAX_SOL when none is pending (every
 * branch converged, no free slot, or the shoulder has a singular branch or
 * none). */
static DH_NOINLINE uint32_t ref_plan(dh_ikc_sol_f32 *sol, uint32_t sh)
{
    uint32_t s, c, src = DH_IKC_MAX_SOL, done = 0u, pend;
    for (s = 0; s < DH_IKC_MAX_SOL; s++) {
        const uint32_t f = sol[s].flags;
        if ((f & REF_FREE) != 0u || (f & DH_IKC_SHOULDER_ALT) != sh) continue;
        if ((f & REF_SING) != 0u) return DH_IKC_MAX_SOL;
        if ((f & DH_IKC_REFINED) != 0u) {
            done |= 1u << ((f & (DH_IKC_ELBOW_ALT | DH_IKC_WRIST_ALT)) >> 1);
            src = s;
        } else if (src == DH_IKC_MAX_SOL || (sol[src].flags & DH_IKC_REFINED) == 0u) {
            src = s;
        } else {
            /* an unconverged branch after a converged one: the start stays */
        }
    }
    if (src == DH_IKC_MAX_SOL) return src;
    pend = DH_IKC_MAX_SOL;
    for (c = 0; c < 4u; c++) {
        const uint32_t f = sh | (c << 1);
        uint32_t slot = DH_IKC_MAX_SOL;
        if (((done >> c) & 1u) != 0u) continue;
        /* its own unconverged slot, else the first free one */
        for (s = DH_IKC_MAX_SOL; s > 0u; s--)
            if ((sol[s - 1u].flags & REF_FREE) != 0u) slot = s - 1u;
        for (s = 0; s < DH_IKC_MAX_SOL; s++)
            if ((sol[s].flags & (REF_FREE | REF_PEND | REF_BRANCH | DH_IKC_REFINED)) == f) slot = s;
        if (slot == DH_IKC_MAX_SOL) continue;
        sol[slot].flags = f | REF_PEND;
        if (slot < pend) pend = slot;
    }
    /* the start's values into the first pending slot */
    if (pend != DH_IKC_MAX_SOL && pend != src)
        for (c = 0; c < 6u; c++) sol[pend].q[c] = sol[src].q[c];
    return pend;
}

/* Slot b after its start (ref_bw, ref_be, ref_angles; ok 1 when it has
 * one): joint 4 from phi, flagged REF_NEW; none: free again. */
static DH_NOINLINE void ref_started(const dh_ikc_ref_work_f32 *w, dh_ikc_sol_f32 *b, int ok)
{
    const uint32_t f = b->flags & ~(uint32_t)REF_PEND;
    b->flags = REF_FREE;
    if (ok) {
        b->q[3] = dh_wrap180_f32(w->m->k[RK_S23] * (w->cs[10] - b->q[1] - w->m->k[RK_S2] * b->q[2]));
        b->flags = f | REF_NEW;
    }
}

/* Slots 0..raw-1 flagged REF_NEW (the raw branches), the others REF_FREE
 * (ms 0); or (ms 1) the private flags cleared and the number of slots up to
 * the last one in use returned. */
static DH_NOINLINE uint32_t ref_marks(dh_ikc_sol_f32 *sol, uint32_t raw, int ms)
{
    uint32_t s, n = 0;
    for (s = 0; s < DH_IKC_MAX_SOL; s++) {
        if (ms == 0) {
            sol[s].flags = (s < raw) ? (sol[s].flags | REF_NEW) : REF_FREE;
        } else {
            if ((sol[s].flags & REF_FREE) == 0u) n = s + 1u;
            sol[s].flags &= ~(uint32_t)REF_PRIVATE;
        }
    }
    return n;
}

/* Five rounds over the slots (k: round k >> 3, slot k & 7). Round 0
 * refines the raw branches. Rounds 1 and 3 restart shoulder 0, then 1: its
 * missing and unconverged branches marked (ref_plan), the virtual target
 * of one of its branches formed (ref_virtual) and each marked slot started
 * from it (ref_bs, ref_bw, ref_b6, ref_be, ref_angles: near the wrist
 * singularity the idealised joint 1 can be degrees off, which the wrist
 * turns into a planar point beyond the elbow's reach for one wrist branch
 * and into a start without a solution near it for the other); rounds 2
 * and 4 refine those starts. Each refinement at most DH_IKC_CAL_STEPS
 * steps, each one exact forward kinematics. The helpers run in sequence
 * from here, none below another, and only the work data, sol, k and one
 * count are kept across them. Returns the number of slots used (refined
 * ones flagged DH_IKC_REFINED). */
uint32_t dh_ikc_refine_par234_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, dh_ikc_sol_f32 *sol, uint32_t raw)
{
    dh_ikc_ref_work_f32 w;
    uint32_t k, it;
    w.m = m;
    w.T = T;
    (void)ref_marks(sol, (raw > DH_IKC_MAX_SOL) ? DH_IKC_MAX_SOL : raw, 0);
    k = 0;
    while (k < 5u * DH_IKC_MAX_SOL) {
        if ((k & 8u) != 0u) {
            /* a restart round */
            if ((k & 7u) == 0u) {
                it = ref_plan(sol, (k < 2u * DH_IKC_MAX_SOL) ? 0u : DH_IKC_SHOULDER_ALT);
                if (it == DH_IKC_MAX_SOL) {
                    k += DH_IKC_MAX_SOL;
                    continue;
                }
                /* from the first pending slot, holding the start's values:
                 * the exact errors there into its q, then the virtual
                 * target into w.u */
                k += it;
                dh_ikc_ref_trig_f32_(sol[k & 7u].q, &w);
                dh_ikc_ref_fk_f32_(&w, 0);
                dh_ikc_ref_tool_f32_(&w);
                dh_ikc_ref_base_f32_(&w);
                dh_ikc_ref_rot_f32_(&w);
                (void)dh_ikc_ref_pos_f32_(&w, &sol[k & 7u], 0u);
                for (it = 0; it < 6u; it++) sol[k & 7u].q[it] = w.u[it];
                dh_ikc_ref_fk_f32_(&w, 1);
                ref_virtual(&w, sol[k & 7u].q);
            }
            if ((sol[k & 7u].flags & REF_PEND) != 0u) {
                it = 0u;
                if (ref_bs(&w, sol[k & 7u].flags) && ref_bw(&w)) {
                    ref_b6(&w, sol[k & 7u].flags);
                    if (ref_be(&w, sol[k & 7u].flags)) it = 1u;
                }
                if (it != 0u) ref_angles(w.cs, sol[k & 7u].q);
                ref_started(&w, &sol[k & 7u], (int)it);
            }
            k++;
            continue;
        }
        if ((sol[k & 7u].flags & REF_NEW) == 0u) {
            k++;
            continue;
        }
        sol[k & 7u].flags &= ~(uint32_t)REF_NEW;
        it = dh_ikc_ref_begin_f32_(&sol[k & 7u]);
        if (it < DH_IKC_REF_DONE) dh_ikc_ref_trig_f32_(sol[k & 7u].q, &w);
        while (it < DH_IKC_REF_DONE) {
            dh_ikc_ref_fk_f32_(&w, 0);
            dh_ikc_ref_tool_f32_(&w);
            dh_ikc_ref_base_f32_(&w);
            dh_ikc_ref_rot_f32_(&w);
            it = dh_ikc_ref_pos_f32_(&w, &sol[k & 7u], it);
            if (it < DH_IKC_REF_DONE) {
                dh_ikc_ref_frame1_f32_(&w);
                if (!ref_a(&w) || !ref_b(&w) || !dh_ikc_ref_apply_f32_(&w, sol[k & 7u].q)) it = DH_IKC_REF_DONE;
            }
        }
        k++;
    }
    return ref_marks(sol, 0u, 1);
}
