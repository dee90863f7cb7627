/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_ikc_par234.c - closed-form IK, float: six revolute joints with axes
 * 2, 3, 4 parallel (DH_IKC_PARALLEL_234, Universal Robots), detector and
 * solver behind the front end dh_ikc.c; interface in ikc_impl.h
 * (canonical standard-DH chain, T06 = pre^-1 T post^-1, raw canonical
 * solutions in (-180, 180]). Derivation and thresholds: docs/design.md,
 * "Closed-form inverse kinematics: axes 2-3-4 parallel and SCARA".
 *
 * Notation: canonical joint i has a_i, d_i, alpha_i (sa_i, ca_i), theta_i;
 * A_i = Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i); x_i, y_i, z_i the axes
 * of frame i in frame 0. A twist of 0 or 180 degrees commutes with Rz up to
 * the sign of the angle: Rx(alpha) Rz(t) = Rz(c t) Rx(alpha), c = cos alpha.
 */
#include "ikc_impl.h"
#include "../internal/dh_floatops.h"
#include "dhmath/trig.h"

/* Wrist (PARALLEL_234): |sin theta5| at most this is singular. */
#define IKC_WRIST_TOL 1e-6f
/* Boundary search (par234_search): evaluations per shoulder branch and
 * half (the branch's u, then pairs by thirds: the interval shrinks to 4e-5
 * of its width; the merged branch searches two halves); a record whose
 * planar point lies beyond the elbow's reach at the branch's u by more
 * than IKC_HOPELESS tol (1e-3 L) plus what the search can move it is not
 * searched for; a search stops at the first u' where one record lies
 * within IKC_SEARCH_OK tol of the reach. */
#define IKC_SEARCH_N 49u
#define IKC_HOPELESS 2500.0f
#define IKC_SEARCH_OK 0.5f

/* ======================================================================
 * DH_IKC_PARALLEL_234
 *
 * Structure detected (canonical SDH): six revolute joints, alpha1 = +-90
 * (|ca1| tiny), alpha2, alpha3 in {0, 180} (|sa2|, |sa3| tiny: axes 2, 3,
 * 4 parallel), alpha4 = +-90 and alpha5 = +-90 (|ca4|, |ca5| tiny),
 * a5 = 0, a2 != 0, a3 != 0; a1, a4, every d, every offset, a6 and alpha6
 * are free (UR3/UR5/UR10: a1 = a4 = 0, alpha = 90, 0, 0, 90, -90, 0).
 *
 * Signs: tau = sa1, s2 = ca2, s23 = ca2 ca3, sb = sin(alpha2 + alpha3 +
 * alpha4) = s23 sa4, w5 = sa5 (each +-1). Frame 1: x1 = (c1, s1, 0),
 * y1 = (0, 0, tau), z1 = tau (s1, -c1, 0). Frames 2..4 turn about axes
 * parallel to z1: R14 = Rz(phi) Rx(alpha2 + alpha3 + alpha4) with
 * phi = t2 + s2 t3 + s23 t4, and in frame 1 (a5 = 0)
 *   o5 = a2 (c2, s2) + a3 (cos, sin)(t2 + s2 t3) + a4 (cphi, sphi)
 *        + sb d5 (sphi, -cphi),   z component h = d2 + s2 d3 + s23 d4.
 * Tool side: R' = R06 Rx(alpha6)^T (x' = x6, z' = sa6 y6 + ca6 z6 = axis 6),
 * p05 = p - R06 (a6, d6 sa6, d6 ca6) = o5.
 * 1. z1 . p05 = h: tau (s1 px - c1 py) = h, so with u = +-sqrt(px^2 + py^2
 *    - h^2): (c1, s1) ~ (u px - tau h py, tau h px + u py).
 * 2. N = R01^T R' = Rz(phi) Rx(beta) Rz(t5) Rx(alpha5) Rz(t6), whose third
 *    column is Rz(phi) (w5 s5, 0, -sb w5 c5): c5 = -sb w5 n33,
 *    s5 = +-|(n13, n23)|, (cphi, sphi) = (n13, n23) / (w5 s5).
 * 3. t6 from the first column rotated back, m' = Rz(-phi) N e_x:
 *    t6 = atan2(-w5 sb m'y, c5 m'x + s5 sb m'z); consistent with phi, so the
 *    solution stays exact however small s5 is. Wrist flip (s5 -> -s5):
 *    (phi + 180, -t5, t6 + 180).
 * 4. Planar 2R: v = p1 - a4 (cphi, sphi) - sb d5 (sphi, -cphi) with
 *    p1 = (c1 px + s1 py - a1, tau (pz - d1)); K = |v|^2 - a2^2 - a3^2,
 *    D = 2 a2 a3: t3 = atan2(+-sqrt(D^2 - K^2), K sgn D); (A, B) = (a2 + a3
 *    c3, s2 a3 s3): t2 = atan2(A vy - B vx, A vx + B vy);
 *    t4 = s23 (phi - t2 - s2 t3).
 * Singular: |s5| <= IKC_WRIST_TOL (axes 2, 3, 4, 6 parallel): t5 = 0 or 180,
 * t6 = cref6, phi from the first column: Rz(phi) g = (n11, n21) with
 * g = (c5 c6, -sb w5 s6). Shoulder: px^2 + py^2 - h^2 within the position
 * tolerance (the joint 5 point on the cylinder of radius |h| about axis 1,
 * or on axis 1 when h = 0): one branch u = 0, or t1 = cref1 on the axis.
 * ====================================================================== */

/* m->k layout, PARALLEL_234 */
enum {
    P_TAU = 0, /* sa1 (+-1) */
    P_S2,      /* ca2 (+-1) */
    P_S23,     /* ca2 ca3 (+-1) */
    P_SB,      /* sin(alpha2 + alpha3 + alpha4) = s23 sa4 (+-1) */
    P_W5,      /* sa5 (+-1) */
    P_H,       /* h = d2 + s2 d3 + s23 d4 */
    P_D,       /* 2 a2 a3 */
    P_A23,     /* a2^2 + a3^2 */
    P_E5,      /* sb d5 */
    P_TOLS,    /* shoulder band on px^2 + py^2 - h^2 */
    P_AXIS,    /* (position tolerance)^2: the point on axis 1 */
    P_ELB,     /* elbow band: (4 |D| tol)^2, compared with (D^2 - K^2)^2 / |v|^2 */
    P_W0,      /* -a6       } the point (-w, 1) that T06 maps to p05 */
    P_W1,      /* -d6 sa6   } */
    P_W2,      /* -d6 ca6   } */
    P_Z0,      /* 0         } the direction (0, sa6, ca6) that T06 maps to axis 6 */
    P_SA6,     /* sa6       } */
    P_CA6,     /* ca6       } */
    P_SUM2,    /* (|a2| + |a3|)^2 */
    P_DIF2     /* (|a2| - |a3|)^2 */
};

int dh_ikc_detect_par234_f32_(dh_ikc_model_f32 *m)
{
    float *k = m->k;
    float L, tol;
    if (m->n != 6u || m->prismatic != 0u) return 0;
    if (!dh_ikc_zero_f32_(m->ca[0], IKC_TWIST_EPS) || !dh_ikc_zero_f32_(m->sa[1], IKC_TWIST_EPS) ||
        !dh_ikc_zero_f32_(m->sa[2], IKC_TWIST_EPS) || !dh_ikc_zero_f32_(m->ca[3], IKC_TWIST_EPS) ||
        !dh_ikc_zero_f32_(m->ca[4], IKC_TWIST_EPS))
        return 0;
    L = dh_ikc_len_scale_f32_(m, 6u);
    if (!dh_ikc_zero_f32_(m->a[4], IKC_LEN_EPS * L) || dh_ikc_zero_f32_(m->a[1], IKC_LEN_EPS * L) ||
        dh_ikc_zero_f32_(m->a[2], IKC_LEN_EPS * L))
        return 0;
    k[P_TAU] = dh_ikc_sign_f32_(m->sa[0]);
    k[P_S2] = dh_ikc_sign_f32_(m->ca[1]);
    k[P_S23] = k[P_S2] * dh_ikc_sign_f32_(m->ca[2]);
    k[P_SB] = k[P_S23] * dh_ikc_sign_f32_(m->sa[3]);
    k[P_W5] = dh_ikc_sign_f32_(m->sa[4]);
    k[P_H] = m->d[1] + k[P_S2] * m->d[2] + k[P_S23] * m->d[3];
    k[P_D] = 2.0f * m->a[1] * m->a[2];
    k[P_A23] = m->a[1] * m->a[1] + m->a[2] * m->a[2];
    k[P_E5] = k[P_SB] * m->d[4];
    tol = IKC_POS_REL * L;
    k[P_TOLS] = 2.0f * fabsf(k[P_H]) * tol + tol * tol;
    k[P_AXIS] = tol * tol;
    k[P_ELB] = (4.0f * fabsf(k[P_D]) * tol) * (4.0f * fabsf(k[P_D]) * tol);
    k[P_W0] = -m->a[5];
    k[P_W1] = -(m->d[5] * m->sa[5]);
    k[P_W2] = -(m->d[5] * m->ca[5]);
    k[P_Z0] = 0.0f;
    k[P_SA6] = m->sa[5];
    k[P_CA6] = m->ca[5];
    k[P_SUM2] = (fabsf(m->a[1]) + fabsf(m->a[2])) * (fabsf(m->a[1]) + fabsf(m->a[2]));
    k[P_DIF2] = (fabsf(m->a[1]) - fabsf(m->a[2])) * (fabsf(m->a[1]) - fabsf(m->a[2]));
    m->kind = DH_IKC_PARALLEL_234;
    return 1;
}

/* The solver runs in two flat passes so that no call chain holds more than
 * one solver frame (stack budget): pass 1 writes one record per (shoulder,
 * wrist) choice into the solution slots r = 4 shoulder + 2 wrist and r + 1
 * (sol[r].q = t1, t5, t6, cphi, sphi, p1x; sol[r + 1].q[0] = p1y; flags in
 * sol[r].flags, IKC_EMPTY in sol[r + 1].flags for no record); pass 2 turns
 * each record into its elbow solutions in the same two slots; the slots
 * left empty are then squeezed out, keeping the branch order. */
#define IKC_EMPTY 0xFFFFFFFFu

/* Pass 1a for one shoulder branch (f: its flags, DH_IKC_SHOULDER_ALT for
 * the second): joint 1 from the joint 5 point p05 and u (pw = px, py, pz,
 * u, px^2 + py^2, kept in sol[1].q[1..5]) into rec = sol + 4 s: t1 in
 * rec[0].q[0], the joint 5 point in frame 1 in rec[0].q[5] and
 * rec[1].q[0], (c1, s1) in rec[3].q[1..2] (scratch). */
static DH_NOINLINE void par234_shoulder(const dh_ikc_model_f32 *m, const float *q_ref, uint32_t f,
                                        dh_ikc_sol_f32 *sol)
{
    const float *k = m->k;
    const float *pw = &sol[1].q[1];
    dh_ikc_sol_f32 *rec = &sol[((f & DH_IKC_SHOULDER_ALT) != 0u) ? 4u : 0u];
    float c1, s1;
    if ((f & DH_IKC_SING_SHOULDER) != 0u && pw[4] <= k[P_AXIS]) {
        (void)dh_sincos_f32(dh_ikc_ref_f32_(dh_ikc_cref_f32_(m, q_ref, 0u)), &s1, &c1);
    } else {
        const float th = k[P_TAU] * k[P_H], uu = (f & DH_IKC_SHOULDER_ALT) ? -pw[3] : pw[3];
        const float X = uu * pw[0] - th * pw[1], Y = th * pw[0] + uu * pw[1];
        const float inv = 1.0f / dh_sqrt_f32(X * X + Y * Y);
        c1 = X * inv;
        s1 = Y * inv;
    }
    rec[3].q[1] = c1;
    rec[3].q[2] = s1;
    rec[0].q[5] = c1 * pw[0] + s1 * pw[1] - m->a[0];
    rec[1].q[0] = k[P_TAU] * (pw[2] - m->d[0]);
    /* t1 = atan2(s1, c1) is taken by par234_angles (rec[3].q[5] = 1) */
    rec[3].q[5] = 1.0f;
    if ((f & DH_IKC_SING_SHOULDER) != 0u && pw[4] <= k[P_AXIS]) {
        rec[0].q[0] = dh_ikc_ref_f32_(dh_ikc_cref_f32_(m, q_ref, 0u));
        rec[3].q[5] = 0.0f;
    }
}

/* Pass 1b: the two wrist records of the shoulder branch (rec = sol + 4 s,
 * after par234_shoulder). */
static DH_NOINLINE void par234_wrist(const dh_ikc_model_f32 *m, const float *q_ref, uint32_t f,
                                     dh_ikc_sol_f32 *sol)
{
    const float *k = m->k;
    const float tau = k[P_TAU], sb = k[P_SB], w5 = k[P_W5];
    dh_ikc_sol_f32 *rec = &sol[((f & DH_IKC_SHOULDER_ALT) != 0u) ? 4u : 0u];
    const float c1 = rec[3].q[1], s1 = rec[3].q[2];
    uint32_t fw = f;
    /* x' = x6 and z' = axis 6 of T06, in sol[6] (par234_p05; read here
     * before the second branch's flip record overwrites them) */
    const float *xv = sol[6].q, *zv = &sol[6].q[3];
    {
    /* N = R01^T R': first column (n11, n21, n31), third column (n13, n23, n33) */
    const float xx = xv[0], xy = xv[1];
    const float zx = zv[0], zy = zv[1];
    const float n11 = c1 * xx + s1 * xy, n21 = tau * xv[2];
    const float n13 = c1 * zx + s1 * zy;
    const float n23 = tau * zv[2];
    const float c5 = -sb * w5 * tau * (s1 * zx - c1 * zy);
    const float s5q = n13 * n13 + n23 * n23;
    float cp, sp;
    if (s5q <= IKC_WRIST_TOL * IKC_WRIST_TOL) {
        /* axes 2, 3, 4, 6 parallel: t6 from cref, phi from the first column,
         * Rz(phi) (c5 c6, -sb w5 s6) = (n11, n21) */
        float s6, c6, gx, gy, nn;
        rec[0].q[1] = c5 < 0.0f ? 180.0f : 0.0f;
        rec[0].q[2] = dh_ikc_ref_f32_(dh_ikc_cref_f32_(m, q_ref, 5u));
        (void)dh_sincos_f32(rec[0].q[2], &s6, &c6);
        gx = (c5 < 0.0f ? -c6 : c6);
        gy = -sb * w5 * s6;
        cp = n11 * gx + n21 * gy;
        sp = n21 * gx - n11 * gy;
        nn = cp * cp + sp * sp;
        if (nn > 0.0f) {
            nn = 1.0f / dh_sqrt_f32(nn);
            cp *= nn;
            sp *= nn;
        } else {
            cp = 1.0f;
        }
        fw |= DH_IKC_SING_WRIST;
        rec[2].flags = IKC_EMPTY;
        rec[3].flags = IKC_EMPTY;
    } else {
        const float s5 = dh_sqrt_f32(s5q);
        const float inv = w5 / s5; /* 1 / (w5 s5) */
        const float n31 = tau * (s1 * xx - c1 * xy);
        cp = n13 * inv;
        sp = n23 * inv;
        /* t6 = atan2(-w5 sb m'y, c5 m'x + s5 sb m'z), m' = Rz(-phi) N e_x;
         * its two arguments parked in rec[2] until the angles are taken */
        rec[2].q[1] = -w5 * sb * (cp * n21 - sp * n11);
        rec[2].q[2] = c5 * (cp * n11 + sp * n21) + s5 * sb * n31;
        rec[2].q[3] = -cp;
        rec[2].q[4] = -sp;
        rec[3].q[3] = s5; /* t5 = atan2(s5, c5), taken by par234_angles */
        rec[3].q[4] = c5;
        rec[2].q[5] = rec[0].q[5];
        rec[3].q[0] = rec[1].q[0];
        rec[2].flags = fw | DH_IKC_WRIST_ALT;
        rec[3].flags = 0u;
    }
    rec[0].q[3] = cp;
    rec[0].q[4] = sp;
    rec[0].flags = fw;
    rec[1].flags = 0u;
    }
}

/* Pass 1c: the angles from their parked arguments (kept out of the
 * frames above for the stack): t1 unless taken from cref; unless wrist
 * singular, t5 and t6 and the flip (phi + 180, -t5, t6 + 180) of the
 * second record. */
static DH_NOINLINE void par234_angles(dh_ikc_sol_f32 *rec)
{
    if (!dh_feq_f32(rec[3].q[5], 0.0f)) rec[0].q[0] = dh_ikc_atan2_f32_(rec[3].q[2], rec[3].q[1]);
    if (rec[3].flags == IKC_EMPTY) return;
    rec[0].q[1] = dh_ikc_atan2_f32_(rec[3].q[3], rec[3].q[4]);
    rec[0].q[2] = dh_ikc_atan2_f32_(rec[2].q[1], rec[2].q[2]);
    rec[2].q[0] = rec[0].q[0];
    rec[2].q[1] = dh_wrap180_f32(-rec[0].q[1]);
    rec[2].q[2] = dh_wrap180_f32(rec[0].q[2] + 180.0f);
}

/* Pass 2a for one record (slots rec[0], rec[1]): the planar point v, the
 * elbow radicand and phi into scratch rec[1].q[0..5] = phi, vx, vy, A |D|,
 * K sgn D, sqrt(radicand); t5, t6 moved to rec[0].q[4..5]. Returns the
 * number of elbow solutions (0: unreachable), flags in rec[0].flags. */
static DH_NOINLINE uint32_t par234_elbow_prep(const dh_ikc_model_f32 *m, dh_ikc_sol_f32 *rec)
{
    const float *k = m->k;
    float rad, v2;
    uint32_t ne = 2u;
    /* rec[1].q[1..2] = v: the planar point less the joint 4 and 5 terms */
    rec[1].q[1] = rec[0].q[5] - m->a[3] * rec[0].q[3] - k[P_E5] * rec[0].q[4];
    rec[1].q[2] = rec[1].q[0] - m->a[3] * rec[0].q[4] + k[P_E5] * rec[0].q[3];
    rec[1].q[0] = dh_ikc_atan2_f32_(rec[0].q[4], rec[0].q[3]); /* phi */
    v2 = rec[1].q[1] * rec[1].q[1] + rec[1].q[2] * rec[1].q[2];
    rec[1].q[4] = (k[P_D] < 0.0f) ? k[P_A23] - v2 : v2 - k[P_A23]; /* K sgn D */
    rec[1].q[3] = m->a[1] * fabsf(k[P_D]) + m->a[2] * rec[1].q[4]; /* A |D| */
    rec[0].q[4] = rec[0].q[1];
    rec[0].q[5] = rec[0].q[2];
    /* D^2 - K^2 = ((|a2| + |a3|)^2 - |v|^2) (|v|^2 - (|a2| - |a3|)^2): no
     * cancellation of large terms near the stretched or folded elbow */
    rad = (k[P_SUM2] - v2) * (v2 - k[P_DIF2]);
    /* merging moves the point by about |rad| / (4 |D| |v|): within the
     * position tolerance tol when rad^2 <= (4 |D| tol)^2 |v|^2 */
    if (rad * rad <= k[P_ELB] * v2) {
        rad = 0.0f;
        ne = 1u;
        rec[0].flags |= DH_IKC_SING_ELBOW;
    } else if (rad < 0.0f) {
        return 0u;
    } else {
        /* two elbow branches */
    }
    rec[1].q[5] = dh_sqrt_f32(rad);
    return ne;
}

/* Pass 2b: elbow solution e of the record prepared by par234_elbow_prep. */
static DH_NOINLINE void par234_elbow(const dh_ikc_model_f32 *m, const float *q_ref, uint32_t e,
                                     dh_ikc_sol_f32 *rec)
{
    const float *k = m->k;
    const float *w = rec[1].q; /* phi, vx, vy, A |D|, K sgn D, sqrt(radicand) */
    const float s3d = e ? -w[5] : w[5]; /* s3 |D| */
    const float Bd = k[P_S2] * m->a[2] * s3d;
    const float y = w[3] * w[2] - Bd * w[1], x = w[3] * w[1] + Bd * w[2];
    const float t3 = dh_ikc_atan2_f32_(s3d, w[4]);
    const float t2 = (dh_feq_f32(x, 0.0f) && dh_feq_f32(y, 0.0f)) ? dh_ikc_ref_f32_(dh_ikc_cref_f32_(m, q_ref, 1u))
                                                                   : dh_ikc_atan2_f32_(y, x);
    const float t4 = dh_wrap180_f32(k[P_S23] * (w[0] - t2 - k[P_S2] * t3));
    rec[e].q[0] = rec[0].q[0];
    rec[e].q[1] = t2;
    rec[e].q[2] = t3;
    rec[e].q[3] = t4;
    rec[e].q[4] = rec[0].q[4];
    rec[e].q[5] = rec[0].q[5];
    rec[e].flags = rec[0].flags | (e ? DH_IKC_ELBOW_ALT : 0u);
}

/* The elbow's margin of wrist record w (0, or 1: the flip) at the
 * shoulder coordinate u: the radicand of par234_elbow_prep divided by
 * 4 |D| tol |v|, about the planar point's distance inside the 2R's reach
 * in units of tol (>= -1: par234_elbow_prep solves it). The arithmetic is
 * that of par234_shoulder, par234_wrist and par234_elbow_prep. A singular
 * wrist gives 0 (not searched for). */
DH_INLINE float par234_margin(const dh_ikc_model_f32 *m, const dh_ikc_sol_f32 *sol, float u, uint32_t w,
                              float *s5)
{
    const float *k = m->k, *pw = &sol[1].q[1], *zv = &sol[6].q[3];
    const float th = k[P_TAU] * k[P_H];
    const float X = u * pw[0] - th * pw[1], Y = th * pw[0] + u * pw[1];
    const float inv = 1.0f / dh_sqrt_f32(X * X + Y * Y);
    const float c1 = X * inv, s1 = Y * inv;
    const float n13 = c1 * zv[0] + s1 * zv[1], n23 = k[P_TAU] * zv[2];
    const float s5q = n13 * n13 + n23 * n23;
    float cp, sp, vx, vy, v2, den;
    if (s5q <= IKC_WRIST_TOL * IKC_WRIST_TOL) return 0.0f;
    *s5 = dh_sqrt_f32(s5q);
    den = k[P_W5] / *s5;
    cp = w ? -(n13 * den) : n13 * den;
    sp = w ? -(n23 * den) : n23 * den;
    vx = c1 * pw[0] + s1 * pw[1] - m->a[0] - m->a[3] * cp - k[P_E5] * sp;
    vy = k[P_TAU] * (pw[2] - m->d[0]) - m->a[3] * sp + k[P_E5] * cp;
    v2 = vx * vx + vy * vy;
    den = dh_sqrt_f32(k[P_ELB] * v2);
    if (!(den > 0.0f)) return -2.0f * IKC_HOPELESS; /* the planar point on axis 2 */
    return (k[P_SUM2] - v2) * (v2 - k[P_DIF2]) / den;
}

/* The larger margin of the records searched for (flags bits 0, 1 of the
 * scratch slot) at u. */
DH_INLINE float par234_best(const dh_ikc_model_f32 *m, const dh_ikc_sol_f32 *sol, float u, uint32_t mask)
{
    float g = -3.0e38f, s5 = 1.0f;
    uint32_t w;
    for (w = 0u; w < 2u; w++) {
        if ((mask & (1u << w)) != 0u) {
            const float gw = par234_margin(m, sol, u, w, &s5);
            if (gw > g) g = gw;
        }
    }
    return g;
}

/* Boundary search, the next evaluation i of shoulder branch s (before
 * its pass 1; pw as par234_p05 left it, x' and z' in sol[6]). Near the shoulder
 * cylinder the rounding of the target leaves joint 1 free by up to about
 * 1e-3 rad, which the wrist (dividing by s5) turns into tenths of mm of
 * the elbow's planar point: when a record lies beyond the elbow's reach at
 * the branch's u, u' is searched for with |u'^2 - (px^2 + py^2 - h^2)| <=
 * the shoulder band (the joint 5 point moved radially by at most tol;
 * u' of the branch's sign; for the merged branch u' >= 0, then u' <= 0)
 * by thirds for the largest margin of its records (those not hopeless at
 * u), stopping at the first u' where one lies within IKC_SEARCH_OK tol of
 * the reach; else u stays. A branch with a record solved at u is not
 * searched (it is solved). Sets pw[3] for par234_shoulder; returns 1
 * while the search goes on. Scratch sc = sol[4 s] (free until pass 1 of the branch): lo,
 * hi, the first margin of a pair, u; in its flags the records searched
 * (bits 0, 1) and i (from bit 2; 0 before the first evaluation). */
static DH_NOINLINE uint32_t par234_search(const dh_ikc_model_f32 *m, uint32_t ns, uint32_t s, dh_ikc_sol_f32 *sol)
{
    const float *k = m->k;
    float *pw = &sol[1].q[1], *sc = sol[4u * s].q;
    const uint32_t i = sol[4u * s].flags >> 2;
    const float third = (sc[1] - sc[0]) * (11.0f / 32.0f);
    float c, g;
    if (i == 0u) {
        const float rad = pw[4] - k[P_H] * k[P_H], tol = dh_sqrt_f32(k[P_AXIS]);
        uint32_t w, mask = 0u;
        float best = -3.0e38f, s5 = 1.0f, width;
        c = (s != 0u) ? -pw[3] : pw[3];
        sc[3] = c;
        if (ns == 1u && pw[4] <= k[P_AXIS]) return 0u;
        sc[1] = dh_sqrt_f32(rad + k[P_TOLS]);
        sc[0] = (rad > k[P_TOLS]) ? dh_sqrt_f32(rad - k[P_TOLS]) : 0.0f;
        width = ((ns == 1u) ? 2.0f * sc[1] : sc[1] - sc[0]) / tol;
        /* u' turns joint 1 by up to width / |h|, which moves the planar
         * point by up to (|a4| + |sb d5|) / s5 as much (and by the width
         * along x1): a record beyond that plus IKC_HOPELESS tol is hopeless */
        for (w = 0u; w < 2u; w++) {
            g = par234_margin(m, sol, c, w, &s5);
            if (g >= -(IKC_HOPELESS +
                       width * (1.0f + (fabsf(m->a[3]) + fabsf(k[P_E5])) / (s5 * (fabsf(k[P_H]) + tol)))))
                mask |= 1u << w;
            if (g > best) best = g;
        }
        if (mask == 0u || best >= -1.0f) return 0u;
        sol[4u * s].flags = mask | 4u;
        if (s != 0u) {
            const float lo = sc[0];
            sc[0] = -sc[1];
            sc[1] = -lo;
        }
        return 1u;
    }
    c = ((i & 1u) != 0u) ? sc[0] + third : sc[1] - third;
    g = par234_best(m, sol, c, sol[4u * s].flags & 3u);
    if (g < -IKC_SEARCH_OK) {
        if ((i & 1u) != 0u) {
            sc[2] = g;
        } else if (g > sc[2]) {
            sc[0] += third;
        } else {
            sc[1] -= third;
        }
        if (i + 1u < IKC_SEARCH_N || (i + 1u < 2u * IKC_SEARCH_N - 1u && ns == 1u)) {
            sol[4u * s].flags += 4u;
            if (i + 1u == IKC_SEARCH_N) {
                /* the merged branch: the half u' <= 0 after u' >= 0 */
                sc[0] = -dh_sqrt_f32(pw[4] - k[P_H] * k[P_H] + k[P_TOLS]);
                sc[1] = 0.0f;
            }
            return 1u;
        }
        c = sc[3];
    }
    pw[3] = (s != 0u) ? -c : c;
    return 0u;
}

/* The joint 5 point p05 and u = sqrt(px^2 + py^2 - h^2) into pw (as
 * par234_wrist reads them), x' = x6 and z' = axis 6 of T06 into sol6[0..5];
 * returns the number of shoulder branches (0:
 * unreachable, 1: merged or on axis 1). */
static DH_NOINLINE uint32_t par234_p05(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, float *pw, float *sol6)
{
    static const float par234_ex[3] = { 1.0f, 0.0f, 0.0f }; /* the direction e_x */
    const float *k = m->k;
    float rad;
    dh_ikc_t06_vec_f32_(m, T, &k[P_W0], 1.0f, pw);
    dh_ikc_t06_vec_f32_(m, T, par234_ex, 0.0f, sol6);
    dh_ikc_t06_vec_f32_(m, T, &k[P_Z0], 0.0f, &sol6[3]);
    pw[4] = pw[0] * pw[0] + pw[1] * pw[1];
    rad = pw[4] - k[P_H] * k[P_H];
    pw[3] = 0.0f;
    if (rad < -k[P_TOLS]) return 0u;
    if (rad <= k[P_TOLS]) return 1u;
    pw[3] = dh_sqrt_f32(rad);
    return 2u;
}

/* The records of shoulder branch s (after par234_angles) whose joint 1, 5
 * or 6 lies outside the window of wq (dh_ikc_raw_win_f32_) are dropped
 * (their slot pair marked IKC_EMPTY). */
static DH_NOINLINE void par234_window(const float *wq, uint32_t s, dh_ikc_sol_f32 *sol)
{
    const float *const win = &wq[6];
    uint32_t r;
    for (r = 4u * s; r < 4u * s + 4u; r += 2u)
        if (sol[r + 1u].flags != IKC_EMPTY &&
            (dh_ikc_out_f32_(win, 0u, sol[r].q[0]) || dh_ikc_out_f32_(win, 4u, sol[r].q[1]) ||
             dh_ikc_out_f32_(win, 5u, sol[r].q[2])))
            sol[r + 1u].flags = IKC_EMPTY;
}

/* The elbow solutions sol[0..ne-1] of a record whose joint 2, 3 or 4 lies
 * outside the window of wq are dropped (flags IKC_EMPTY). */
static DH_NOINLINE void par234_window_elbow(const float *wq, uint32_t ne, dh_ikc_sol_f32 *sol)
{
    const float *const win = &wq[6];
    uint32_t e;
    for (e = 0u; e < ne; e++)
        if (dh_ikc_out_f32_(win, 1u, sol[e].q[1]) || dh_ikc_out_f32_(win, 2u, sol[e].q[2]) ||
            dh_ikc_out_f32_(win, 3u, sol[e].q[3]))
            sol[e].flags = IKC_EMPTY;
}

/* The solver; win 1: q_ref is the wq of dh_ikc_raw_win_f32_ (0: no window): the records whose
 * joint 1, 5 or 6 lies outside it are dropped before pass 2, the elbow
 * solutions whose joint 2, 3 or 4 does after it; the records and solutions
 * kept are computed by the same operations as without it, so they come out
 * the same, in the same order. */
DH_INLINE uint32_t par234_solve(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *q_ref, int win,
                                dh_ikc_sol_f32 *sol)
{
    float *pw = &sol[1].q[1]; /* px, py, pz, u, px^2 + py^2 (slot 1 is free until pass 2) */
    const uint32_t ns = par234_p05(m, T, pw, sol[6].q);
    const uint32_t fs = (ns == 1u) ? (uint32_t)DH_IKC_SING_SHOULDER : 0u;
    uint32_t s, cnt = 0u;
    if (ns == 0u) return 0u;
    if (ns == 1u) {
        sol[5].flags = IKC_EMPTY;
        sol[7].flags = IKC_EMPTY;
    }
    for (s = 0u; s < ns; s++) {
        sol[4u * s].flags = 0u;
        while (par234_search(m, ns, s, sol) != 0u) {
            /* the search's state is in sol[4 s] */
        }
        par234_shoulder(m, q_ref, fs | (s ? DH_IKC_SHOULDER_ALT : 0u), sol);
        par234_wrist(m, q_ref, fs | (s ? DH_IKC_SHOULDER_ALT : 0u), sol);
        par234_angles(&sol[4u * s]);
        if (win) par234_window(q_ref, s, sol);
    }
    for (s = 0u; s < 8u; s += 2u) {
        uint32_t ne = 0u, e;
        if (sol[s + 1u].flags != IKC_EMPTY) ne = par234_elbow_prep(m, &sol[s]);
        if (ne == 0u) sol[s].flags = IKC_EMPTY;
        sol[s + 1u].flags = IKC_EMPTY;
        for (e = 0u; e < ne; e++) par234_elbow(m, q_ref, e, &sol[s]);
        if (win) par234_window_elbow(q_ref, ne, &sol[s]);
    }
    for (s = 0u; s < 8u; s++) {
        uint32_t i;
        if (sol[s].flags == IKC_EMPTY) continue;
        if (cnt != s) {
            for (i = 0u; i < 6u; i++) sol[cnt].q[i] = sol[s].q[i];
            sol[cnt].flags = sol[s].flags;
        }
        cnt++;
    }
    return cnt;
}

uint32_t dh_ikc_par234_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *q_ref,
                            dh_ikc_sol_f32 *sol)
{
    return par234_solve(m, T, q_ref, 0, sol);
}

uint32_t dh_ikc_par234_win_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *wq,
                                dh_ikc_sol_f32 *sol)
{
    return par234_solve(m, T, wq, 1, sol);
}
