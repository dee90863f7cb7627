/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_ikc_scara.c - closed-form IK, float: R-R-P-R with four parallel axes
 * (DH_IKC_SCARA), detector and solver behind the front end dh_ikc.c;
 * interface in ikc_impl.h (canonical standard-DH chain, T06 = pre^-1 T
 * post^-1, raw canonical solutions in (-180, 180]). Derivation and
 * thresholds: docs/design.md, "Closed-form inverse kinematics: axes 2-3-4
 * parallel and SCARA".
 *
 * Notation: canonical joint i has a_i, d_i, alpha_i (sa_i, ca_i), theta_i;
 * A_i = Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i); x_i, y_i, z_i the axes
 * of frame i in frame 0. A twist of 0 or 180 degrees commutes with Rz up to
 * the sign of the angle: Rx(alpha) Rz(t) = Rz(c t) Rx(alpha), c = cos alpha.
 */
#include "ikc_impl.h"
#include "../internal/dh_floatops.h"
#include "dhmath/trig.h"

/* SCARA: the tool axis may lean this much (rad) off the joint axes. */
#define IKC_SCARA_TILT 1e-6f

/* ======================================================================
 * DH_IKC_SCARA
 *
 * Structure detected (canonical SDH): four joints R-R-P-R, alpha1, alpha2,
 * alpha3 in {0, 180} (|sa1|, |sa2|, |sa3| tiny: axes 1..4 parallel),
 * a1 != 0 and |b| != 0 for the effective second link b = (a2 + a3 cos g,
 * a3 sin g), g = s12 theta3 (theta3 the prismatic joint's fixed angle);
 * every d, offset and joint 4's a4, alpha4 free (Cobra 600: a1 = 0.325,
 * a2 = 0.275, alpha2 = 180).
 * Signs s1 = ca1, s12 = ca1 ca2, s123 = s12 ca3. R' = R04 Rx(alpha4)^T =
 * Rz(psi) Rx(alpha1 + alpha2 + alpha3), psi = t1 + s1 t2 + s12 theta3 +
 * s123 t4, so the tool axis z' = sa4 y4 + ca4 z4 must be (0, 0, s123) and
 * psi = atan2(x4y, x4x). The frame 3 origin p3 = p - a4 x4 - d4 z' has
 * z = d1 + s1 d2 + s12 d3 and (x, y) = Rz(t1) (a1 + |b| cos eta, |b| sin eta)
 * with eta = s1 t2 + delta, delta = atan2(by, bx): 2R with K = |p3xy|^2 -
 * a1^2 - |b|^2, D = 2 a1 |b|, eta = atan2(+-sqrt(D^2 - K^2), K sgn D).
 * ====================================================================== */

/* m->k layout, SCARA */
enum {
    S_S1 = 0, /* ca1 (+-1) */
    S_S12,    /* ca1 ca2 (+-1) */
    S_S123,   /* ca1 ca2 ca3 (+-1) */
    S_LB,     /* |b| */
    S_DELTA,  /* atan2(by, bx), degrees */
    S_D,      /* 2 a1 |b| */
    S_A1B,    /* a1^2 + |b|^2 */
    S_Z0,     /* d1 + s1 d2 */
    S_G,      /* s12 theta3 (fixed angle of the prismatic joint), degrees */
    S_ELB,    /* elbow band: (4 |D| tol)^2, compared with (D^2 - K^2)^2 / |p3xy|^2 */
    S_AXIS,   /* (position tolerance)^2: p3 on axis 1 */
    S_SUM2,   /* (|a1| + |b|)^2 */
    S_DIF2,   /* (|a1| - |b|)^2 */
    S_ZD0,    /* 0         } the direction (0, sa4, ca4) that T06 maps to the tool axis z' */
    S_ZDS,    /* sa4       } */
    S_ZDC,    /* ca4       } */
    S_P0,     /* -a4       } the point that T06 maps to the frame 3 origin */
    S_P1,     /* -d4 sa4   } */
    S_P2      /* -d4 ca4   } */
};

int dh_ikc_detect_scara_f32_(dh_ikc_model_f32 *m)
{
    float *k = m->k;
    float L, sg, cg, bx, by, tol;
    if (m->n != 4u || m->prismatic != 0x4u) return 0;
    if (!dh_ikc_zero_f32_(m->sa[0], IKC_TWIST_EPS) || !dh_ikc_zero_f32_(m->sa[1], IKC_TWIST_EPS) ||
        !dh_ikc_zero_f32_(m->sa[2], IKC_TWIST_EPS))
        return 0;
    L = dh_ikc_len_scale_f32_(m, 4u);
    k[S_S1] = dh_ikc_sign_f32_(m->ca[0]);
    k[S_S12] = k[S_S1] * dh_ikc_sign_f32_(m->ca[1]);
    k[S_S123] = k[S_S12] * dh_ikc_sign_f32_(m->ca[2]);
    k[S_G] = dh_wrap180_f32(k[S_S12] * dh_ikc_ref_f32_(m->off[2]));
    (void)dh_sincos_f32(k[S_G], &sg, &cg);
    bx = m->a[1] + m->a[2] * cg;
    by = m->a[2] * sg;
    k[S_LB] = dh_sqrt_f32(bx * bx + by * by);
    if (dh_ikc_zero_f32_(m->a[0], IKC_LEN_EPS * L) || dh_ikc_zero_f32_(k[S_LB], IKC_LEN_EPS * L)) return 0;
    k[S_DELTA] = dh_ikc_atan2_f32_(by, bx);
    k[S_D] = 2.0f * m->a[0] * k[S_LB];
    k[S_A1B] = m->a[0] * m->a[0] + k[S_LB] * k[S_LB];
    k[S_Z0] = m->d[0] + k[S_S1] * m->d[1];
    tol = IKC_POS_REL * L;
    k[S_ELB] = (4.0f * fabsf(k[S_D]) * tol) * (4.0f * fabsf(k[S_D]) * tol);
    k[S_AXIS] = tol * tol;
    k[S_SUM2] = (fabsf(m->a[0]) + k[S_LB]) * (fabsf(m->a[0]) + k[S_LB]);
    k[S_DIF2] = (fabsf(m->a[0]) - k[S_LB]) * (fabsf(m->a[0]) - k[S_LB]);
    k[S_ZD0] = 0.0f;
    k[S_ZDS] = m->sa[3];
    k[S_ZDC] = m->ca[3];
    k[S_P0] = -m->a[3];
    k[S_P1] = -(m->d[3] * m->sa[3]);
    k[S_P2] = -(m->d[3] * m->ca[3]);
    m->kind = DH_IKC_SCARA;
    return 1;
}

/* x4, z' (sol[2].q) and the frame 3 origin p3 (sol[3].q[0..2]) of T06:
 * slots 2 and 3 never hold a SCARA solution. */
static DH_NOINLINE void scara_vecs(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, dh_ikc_sol_f32 *sol)
{
    static const float scara_ex[3] = { 1.0f, 0.0f, 0.0f }; /* the direction e_x */
    dh_ikc_t06_vec_f32_(m, T, scara_ex, 0.0f, sol[2].q);
    dh_ikc_t06_vec_f32_(m, T, &m->k[S_ZD0], 0.0f, &sol[2].q[3]);
    dh_ikc_t06_vec_f32_(m, T, &m->k[S_P0], 1.0f, sol[3].q);
}

/* The solutions from the vectors of scara_vecs (a separate frame, so that
 * the transform's chain and the atan2 chain do not stack). */
static DH_NOINLINE uint32_t scara_solve(const dh_ikc_model_f32 *m, const float *q_ref, dh_ikc_sol_f32 *sol)
{
    const float *k = m->k;
    const float D = k[S_D], lb = k[S_LB];
    const float *xv = sol[2].q;
    const float zx = sol[2].q[3], zy = sol[2].q[4], zz = sol[2].q[5];
    const float px = sol[3].q[0], py = sol[3].q[1], pz = sol[3].q[2];
    const float p2 = px * px + py * py;
    const float K = p2 - k[S_A1B];
    const float Kd = D < 0.0f ? -K : K;
    const float Ad = m->a[0] * fabsf(D) + lb * Kd; /* (a1 + |b| cos eta) |D| */
    const float psi = dh_ikc_atan2_f32_(xv[1], xv[0]);
    const float d3 = k[S_S12] * (pz - k[S_Z0]);
    float rad = (k[S_SUM2] - p2) * (p2 - k[S_DIF2]), r; /* D^2 - K^2, as for PARALLEL_234 */
    uint32_t e, ne = 2u, flags = 0u;
    if (zx * zx + zy * zy > IKC_SCARA_TILT * IKC_SCARA_TILT || zz * k[S_S123] <= 0.0f) return 0u;
    if (rad * rad <= k[S_ELB] * p2) {
        rad = 0.0f;
        ne = 1u;
        flags = DH_IKC_SING_ELBOW;
    } else if (rad < 0.0f) {
        return 0u;
    } else {
        /* two elbow branches */
    }
    r = dh_sqrt_f32(rad);
    for (e = 0u; e < ne; e++) {
        const float sd = e ? -r : r; /* sin eta |D| */
        const float Bd = lb * sd;
        const float eta = dh_ikc_atan2_f32_(sd, Kd);
        uint32_t f = flags | (e ? DH_IKC_ELBOW_ALT : 0u);
        float t1;
        if (p2 <= k[S_AXIS]) {
            t1 = dh_ikc_ref_f32_(dh_ikc_cref_f32_(m, q_ref, 0u));
            f |= DH_IKC_SING_SHOULDER;
        } else {
            t1 = dh_ikc_atan2_f32_(Ad * py - Bd * px, Ad * px + Bd * py);
        }
        sol[e].q[0] = t1;
        sol[e].q[1] = dh_wrap180_f32(k[S_S1] * dh_wrap180_f32(eta - k[S_DELTA]));
        sol[e].q[2] = d3;
        sol[e].q[3] = dh_wrap180_f32(k[S_S123] * dh_wrap180_f32(dh_wrap180_f32(psi - t1) - (eta - k[S_DELTA]) - k[S_G]));
        sol[e].q[4] = 0.0f;
        sol[e].q[5] = 0.0f;
        sol[e].flags = f;
    }
    return ne;
}

uint32_t dh_ikc_scara_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *q_ref,
                           dh_ikc_sol_f32 *sol)
{
    scara_vecs(m, T, sol);
    return scara_solve(m, q_ref, sol);
}
