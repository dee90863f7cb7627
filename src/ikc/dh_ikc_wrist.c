/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_ikc_wrist.c - closed-form IK, float: the spherical-wrist families
 * DH_IKC_WRIST_RRR (Puma 560, KUKA KR5, ABB IRB140) and DH_IKC_WRIST_RRP
 * (Stanford arm), detector and solver behind the front end dh_ikc.c;
 * interface in ikc_impl.h. The method follows Paul 1981 ch. 3 (the arm
 * positions the wrist centre, the wrist the orientation); derivations:
 * docs/design.md ("Closed-form inverse kinematics").
 *
 * Two whole solvers, chosen by WRIST_ONE_PASS below: with an FPU, one
 * pass writes each solution into its final slot and takes the cosines and
 * sines of joints 1-3 from the normalised atan2 arguments (no sincos);
 * with soft float, the caller's solution array is the scratch (arms,
 * compactions, sincos of joints 1-3), which keeps the Cortex-M0+ frames
 * within the 256-byte stack budget.
 */
#include "dhmath/ikc.h"
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
    KW_CPHI,       /* cos, sin of KW_PHI: a3 / rho, e / rho (RRR) */
    KW_SPHI,
    KW_COUNT
};

typedef char dh_ikc_k_fits_[(KW_COUNT <= (int)DH_IKC_K) ? 1 : -1];

/* 1: the one-pass solver (its frame keeps the vectors of T06, 36 bytes
 * more than the in-place one); 0: the in-place solver (soft float). */
#define WRIST_ONE_PASS (!DH_SOFT_FLOAT)

/* The wrist phases B and C: inlined into their one caller by the one-pass
 * solver (the values pass in registers), out of line for the in-place
 * solver (its frames within the Cortex-M0+ stack budget). */
#if WRIST_ONE_PASS
#define WRIST_PHASE static
#else
#define WRIST_PHASE static DH_NOINLINE
#endif

/* Wrist singular when axis 6 is within this angle (rad) of axis 4: the
 * orientation error of the q_ref split is at most that angle. */
#define IKC_SING_WRIST 1.5e-6f
/* Length tolerance per unit of the characteristic length L. */
#define IKC_EPS_L 5e-7f

/* ---- small helpers --------------------------------------------------------- */

/* atan2 in degrees, (-180, 180], fallback when both arguments are zero
 * (free angle). dh_atan2f_dg_ (3 ulp): a third of the stack of the
 * correctly rounded degree version (dh_atan2f_deg_), which no solver frame
 * could afford on top; inlined by the one-pass solver (FPU builds) unless
 * optimised for size (DH_HOT_INLINE). */
DH_INLINE float wrist_atan2(float y, float x, float fallback)
{
    if (WRIST_ONE_PASS && DH_HOT_INLINE) return dh_atan2f_dg_fb_inl_(y, x, fallback);
    if (dh_feq_f32(y, 0.0f) && dh_feq_f32(x, 0.0f)) return fallback;
    return dh_atan2f_dg_(y, x);
}


/* A cosine that wrist_cs leaves for its caller to fill (no cosine is). */
#define WRIST_CS_NONE 2.0f

/* cs = (x, y) / |(x, y)|, the cosine and sine of atan2(y, x); cs[0] =
 * WRIST_CS_NONE when both are zero (wrist_atan2 takes its fallback: the
 * one-pass solver takes that angle's sincos, out of the frames that call
 * wrist_cs). Inlined, no call. */
DH_INLINE void wrist_cs(float y, float x, float *cs)
{
    float xs = x, ys = y, r2 = dh_mla_f32_(x, x, y * y), ir;
    if (!(r2 >= 1e-30f && r2 <= 1e30f)) {
        /* squares out of range (or zero): scaled by the larger magnitude */
        const float ax = fabsf(x), ay = fabsf(y), mx = (ax > ay) ? ax : ay;
        if (!(mx > 0.0f)) {
            cs[0] = WRIST_CS_NONE;
            return;
        }
        xs = x / mx;
        ys = y / mx;
        r2 = dh_mla_f32_(xs, xs, ys * ys);
    }
    ir = 1.0f / dh_sqrt_f32(r2);
    cs[0] = xs * ir;
    cs[1] = ys * ir;
}

/* 1: the second elbow branch of an arm two slots after the first (one
 * pass: the first's wrist solutions in between); 0: the next slot. */
#define WRIST_ARM1 (WRIST_ONE_PASS ? 2u : 1u)

/* flags of a slot that holds no solution (a singular wrist's second) */
#define IKC_GAP 0xFFFFFFFFu

/* ---- spherical-wrist families ------------------------------------------------- */

int dh_ikc_detect_wrist_f32_(dh_ikc_model_f32 *m)
{
    float *k = m->k, L = 0.0f;
    uint32_t i;
    if (!dh_ikc_spherical_f32_(m) || !dh_feq_f32(m->ca[3], 0.0f) || !dh_feq_f32(m->ca[4], 0.0f) ||
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
        k[KW_CPHI] = a3 / rho;
        k[KW_SPHI] = e / rho;
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
    k[KW_PRE] = dh_ikc_is_identity_f32_(&m->pre_inv) ? 0.0f : 1.0f;
    k[KW_POST] = dh_ikc_is_identity_f32_(&m->post_inv) ? 0.0f : 1.0f;
    return 1;
}

/* a <- Rx(alpha)^T Rz(theta)^T xa and b <- the same of xb (c, s of
 * theta); each may be its source (each vector is read before it is
 * written; a must not overlap xb). */
static void wrist_rzrx_t(const float *xa, const float *xb, float *a, float *b, float c, float s, float sa, float ca)
{
    uint32_t k;
    for (k = 0; k < 2u; k++) {
        const float *u = (k == 0u) ? xa : xb;
        float *v = (k == 0u) ? a : b;
        const float x = dh_mla_f32_(s, u[1], c * u[0]), y = dh_mls_f32_(s, u[0], c * u[1]), z = u[2];
        v[0] = x;
        v[1] = dh_mla_f32_(sa, z, ca * y);
        v[2] = dh_mls_f32_(sa, y, ca * z);
    }
}

/* Wrist, phase A, for the arm solution in out[0] (values and flags),
 * with rn, ra = R01^T of R06's columns n and a (joint 1 applied; shared
 * by the arm's elbow branches) and cs = cos, sin of joint 2 (RRR: of
 * theta2 + sigma theta3): M's third and first columns (R03^T of R06's
 * two columns) into out[0].q[3..5] and out[1].q[3..5] (rn, ra may be
 * those places: they are read in place). Wrist singular (axis 6 in frame 3 on
 * the z axis, joint 4's axis): flagged, and joint 4 from q_ref with its
 * sine and cosine into out[1].q[2], q[0], q[1]. Inlined into its one
 * caller (no frame of its own under the Cortex-M0+ budget). */
DH_INLINE void wrist_m(const dh_ikc_model_f32 *m, const float *q_ref, dh_ikc_sol_f32 *out, const float *rn,
                       const float *ra, const float *cs)
{
    const float *k = m->k;
    float *mz = &out[0].q[3], *mx = &out[1].q[3];
    float c;
    if (m->kind == DH_IKC_WRIST_RRR) {
        wrist_rzrx_t(ra, rn, mz, mx, cs[0], cs[1], k[KW_SA23], k[KW_CA23]);
    } else {
        wrist_rzrx_t(ra, rn, mz, mx, cs[0], cs[1], m->sa[1], m->ca[1]);
        wrist_rzrx_t(mz, mx, mz, mx, k[KW_C3], k[KW_S3], m->sa[2], m->ca[2]);
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
WRIST_PHASE void wrist_b(const dh_ikc_model_f32 *m, dh_ikc_sol_f32 *out)
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
        /* (c4, s4) = (X' m13, X' m23) / |X' (m13, m23)|, X' = sin a5 s5:
         * sin a5 = +-1 (cos a5 = 0), so the norm is s5 */
        r = sa5 / s5;
        c4 = m0 * r;
        s4 = m1 * r;
    }
    mpx = dh_mla_f32_(s4, out[1].q[4], c4 * out[1].q[3]);
    mpy = dh_mls_f32_(s4, out[1].q[3], c4 * out[1].q[4]);
    mpz = out[1].q[5];
    out[0].q[3] = s4;
    out[0].q[4] = c4;
    out[0].q[5] = s5;
    out[1].q[3] = c5;
    /* N21, N11 with cos a4 = cos a5 = 0 */
    out[1].q[4] = -sa4 * sa5 * mpy;
    out[1].q[5] = dh_mla_f32_(sa4 * s5, mpz, c5 * mpx);
}

/* Wrist, phase C: the angles, and the flipped solution (t4 + 180, -t5,
 * t6 + 180) into out[1] unless singular. */
WRIST_PHASE void wrist_c(dh_ikc_sol_f32 *out)
{
    const int sing = (out[0].flags & DH_IKC_SING_WRIST) != 0u;
    const float t4 = sing ? out[1].q[2] : wrist_atan2(out[0].q[3], out[0].q[4], 0.0f);
    const float t5 = wrist_atan2(out[0].q[5], out[1].q[3], 0.0f);
    const float t6 = wrist_atan2(out[1].q[4], out[1].q[5], 0.0f);
    out[0].q[3] = sing ? dh_ikc_wrap_f32_(t4) : t4;
    out[0].q[4] = t5;
    out[0].q[5] = t6;
    if (sing) {
        out[1].flags = IKC_GAP;
        return;
    }
    out[1].q[0] = out[0].q[0];
    out[1].q[1] = out[0].q[1];
    out[1].q[2] = out[0].q[2];
    out[1].q[3] = dh_ikc_wrap_f32_(t4 + 180.0f);
    out[1].q[4] = dh_ikc_wrap_f32_(-t5);
    out[1].q[5] = dh_ikc_wrap_f32_(t6 + 180.0f);
    out[1].flags = out[0].flags | DH_IKC_WRIST_ALT;
}

/* Joints 2, 3 of the RRR arm for one shoulder branch: sh holds theta1,
 * (vx, vy) (the wrist centre in the plane of the arm) in q[0..2] and the
 * flags; writes the arms (q[0..2], flags) into arm[0] and maybe
 * arm[WRIST_ARM1] (arm may be sh). One pass: cos, sin of theta2 + sigma
 * theta3 into their q[3..4] (q[3] WRIST_CS_NONE: theta2 fell back to
 * cref2).
 * Returns 0, 1, 2. */
static DH_NOINLINE uint32_t wrist_elbow_rrr(const dh_ikc_model_f32 *m, float cref2, const dh_ikc_sol_f32 *sh,
                                            dh_ikc_sol_f32 *arm)
{
    const float *k = m->k;
    const float t1 = sh->q[0], vx = sh->q[1], vy = sh->q[2];
    const float v2 = vx * vx + vy * vy, v = dh_sqrt_f32(v2), D = k[KW_D], Kp = v2 - k[KW_A2RHO];
    const float aD = fabsf(D), KD = (D < 0.0f) ? -Kp : Kp;
    /* dK = |D| - |K'| from |v| (no cancellation of the squares against the
     * constant a2^2 + rho^2): stretched elbow (|a2| + rho)^2 - |v|^2,
     * folded |v|^2 - (|a2| - rho)^2. Moving K' by dK moves the wrist centre
     * by dK / (2 |v|): the branches coincide within KW_EPS. */
    const float dK = (KD >= 0.0f) ? (k[KW_CPLUS] - v) * (k[KW_CPLUS] + v) : (v - k[KW_CMINUS]) * (v + k[KW_CMINUS]);
    const float tol = 2.0f * k[KW_EPS] * v;
    const float A = m->a[1] + Kp * k[KW_INV2A2];
    uint32_t fl = sh->flags;
    float sq = 0.0f, psi, cpsi[2] = { 1.0f, 0.0f }, B;
    uint32_t b, nb = 2u;
    if (dK < -tol) return 0u;
    if (dK <= tol) {
        nb = 1u;
        fl |= DH_IKC_SING_ELBOW;
    } else {
        /* D^2 - K'^2 = dK (|D| + |K'|) */
        sq = dh_sqrt_f32(dK * (2.0f * aD - dK));
    }
    psi = wrist_atan2(sq, KD, 0.0f);
    if (WRIST_ONE_PASS) wrist_cs(sq, KD, cpsi);
    for (b = nb; b-- > 0u;) {
        dh_ikc_sol_f32 *a = &arm[b * WRIST_ARM1];
        const float sg = (b == 0u) ? 1.0f : -1.0f;
        float y, x;
        /* a3 s3 - e c3 = rho sin(theta3 - phi) = +-sqrt(D^2 - K'^2) / (2 |a2|) */
        B = k[KW_SIGMA] * sg * sq * fabsf(k[KW_INV2A2]);
        y = dh_mls_f32_(B, vx, A * vy);
        x = dh_mla_f32_(B, vy, A * vx);
        a->q[0] = t1;
        a->q[2] = dh_ikc_wrap_f32_(k[KW_PHI] + sg * psi);
        a->q[1] = wrist_atan2(y, x, cref2);
        a->flags = (b == 0u) ? fl : (fl | DH_IKC_ELBOW_ALT);
        if (WRIST_ONE_PASS) {
            /* theta3 = phi + sg psi; theta2 + sigma theta3 */
            const float sps = sg * cpsi[1], sig = k[KW_SIGMA];
            const float c3 = dh_mls_f32_(k[KW_SPHI], sps, k[KW_CPHI] * cpsi[0]);
            const float s3 = dh_mla_f32_(k[KW_CPHI], sps, k[KW_SPHI] * cpsi[0]);
            float c2, s2;
            wrist_cs(y, x, &a->q[3]);
            c2 = a->q[3];
            s2 = a->q[4];
            if (!(c2 > 1.5f)) {
                a->q[3] = dh_mls_f32_(sig * s2, s3, c2 * c3);
                a->q[4] = dh_mla_f32_(sig * c2, s3, s2 * c3);
            }
        }
    }
    return nb;
}

/* Joints 2, 3 of the RRP arm (the prismatic extension z3 = +-sqrt(.)), as
 * wrist_elbow_rrr (one pass: cos, sin of theta2 in q[3..4]). */
static DH_NOINLINE uint32_t wrist_elbow_rrp(const dh_ikc_model_f32 *m, float cref2, const dh_ikc_sol_f32 *sh,
                                            dh_ikc_sol_f32 *arm)
{
    const float *k = m->k;
    const float t1 = sh->q[0], vx = sh->q[1], vy = sh->q[2];
    const float W = k[KW_W], eps = k[KW_EPS], tau2 = m->sa[1];
    const float v = dh_sqrt_f32(vx * vx + vy * vy), r = (v - fabsf(W)) * (v + fabsf(W));
    const float tol = eps * (2.0f * fabsf(W) + eps);
    uint32_t fl = sh->flags;
    float z = 0.0f;
    uint32_t b, nb = 2u;
    if (r < -tol) return 0u;
    if (r <= tol) {
        nb = 1u;
        fl |= DH_IKC_SING_ELBOW;
    } else {
        z = dh_sqrt_f32(r);
    }
    for (b = nb; b-- > 0u;) {
        dh_ikc_sol_f32 *a = &arm[b * WRIST_ARM1];
        const float zb = (b == 0u) ? z : -z;
        const float y = tau2 * zb * vx + W * vy, x = W * vx - tau2 * zb * vy;
        a->q[0] = t1;
        a->q[1] = wrist_atan2(y, x, cref2);
        a->q[2] = zb - k[KW_Z3C];
        a->flags = (b == 0u) ? fl : (fl | DH_IKC_ELBOW_ALT);
        if (WRIST_ONE_PASS) wrist_cs(y, x, &a->q[3]);
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
static DH_NOINLINE float wrist_reach(const dh_ikc_model_f32 *m, uint32_t b, float ub, float vy, float pl1)
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

/* Shoulder: u = +-sqrt(px^2 + py^2 - h^2) of the wrist centre p, each
 * moved onto the arm's reach by wrist_reach, theta1; per branch sol[b]
 * gets theta1, vx, vy and its flags (one pass: cos, sin of theta1 into
 * q[3..4], q[3] WRIST_CS_NONE when theta1 is cref1). Returns the number of branches (0, 1 or 2). */
static DH_NOINLINE uint32_t wrist_shoulder(const dh_ikc_model_f32 *m, float cref1, const float *p,
                                           dh_ikc_sol_f32 *sol)
{
    const float *k = m->k;
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
            s->q[3] = WRIST_CS_NONE;
        } else {
            ub = wrist_reach(m, b, ub, vy, fabsf(px) + fabsf(py));
            if (b != 0u && !(u > 0.0f) && !(ub < 0.0f)) continue; /* both branches at u = 0: one */
            s->flags = (b == 0u) ? 0u : DH_IKC_SHOULDER_ALT;
            if (WRIST_ONE_PASS && b != 0u && nu != 0u && dh_feq_f32(h, 0.0f) && dh_feq_f32(ub, -sol[0].q[5]) &&
                !dh_feq_f32(sol[0].q[5], 0.0f)) {
                /* h = 0 and u -> -u: the arguments of branch 0 negated,
                 * theta1 + 180 (its cosine and sine negated; one pass
                 * only: the in-place solver's frame has no room) */
                const float t0 = sol[0].q[0];
                s->q[0] = (t0 > 0.0f) ? t0 - 180.0f : t0 + 180.0f;
                s->q[3] = -sol[0].q[3];
                s->q[4] = -sol[0].q[4];
            } else {
                s->q[0] = wrist_atan2(tau * h * px + ub * py, ub * px - tau * h * py, cref1);
                if (WRIST_ONE_PASS) wrist_cs(tau * h * px + ub * py, ub * px - tau * h * py, &s->q[3]);
            }
            if (WRIST_ONE_PASS) s->q[5] = ub; /* u of this branch, for the next one */
        }
        s->q[1] = ub - m->a[0];
        s->q[2] = vy;
        nu++;
    }
    return nu;
}

/* The vectors of T06 the wrist families need: R06 e_x into rn, R06
 * Rx(alpha6)^T e_z into ra, the wrist centre into p. T06 = pre_inv T
 * post_inv; the products with an identity pre_inv or post_inv (flagged at
 * analysis) are left out. */
static DH_NOINLINE void wrist_prepare(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, float *rn, float *ra,
                                      float *p)
{
    const int pre = !dh_feq_f32(m->k[KW_PRE], 0.0f), post = !dh_feq_f32(m->k[KW_POST], 0.0f);
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
        dh_ikc_xform_f32_(&m->post_inv, ra, 0.0f, ra);
        dh_ikc_xform_f32_(&m->post_inv, p, 1.0f, p);
        dh_ikc_xform_f32_(T, rn, 0.0f, rn);
    } else {
        for (i = 0; i < 3u; i++) rn[i] = T->m[0][i];
    }
    dh_ikc_xform_f32_(T, ra, 0.0f, ra);
    dh_ikc_xform_f32_(T, p, 1.0f, p);
    if (pre) {
        dh_ikc_xform_f32_(&m->pre_inv, rn, 0.0f, rn);
        dh_ikc_xform_f32_(&m->pre_inv, ra, 0.0f, ra);
        dh_ikc_xform_f32_(&m->pre_inv, p, 1.0f, p);
    }
}

#if WRIST_ONE_PASS

/* The wrist solutions of the arm in a[0] (R01^T of R06's columns n and a
 * in rot->q[3..5] and rot->q[0..2]; cos, sin of its joint 2 in v[8..9],
 * or WRIST_CS_NONE: from dh_sincos_f32 here) into a[0] and a[1]. */
static DH_NOINLINE void wrist_arm(const dh_ikc_model_f32 *m, const float *q_ref, dh_ikc_sol_f32 *a, float *v,
                                  const dh_ikc_sol_f32 *rot)
{
    if (v[8] > 1.5f) {
        const float t2 = (m->kind == DH_IKC_WRIST_RRR) ? a->q[1] + m->k[KW_SIGMA] * a->q[2] : a->q[1];
        (void)dh_sincos_f32(t2, &v[9], &v[8]);
    }
    wrist_m(m, q_ref, a, &rot->q[3], &rot->q[0], &v[8]);
    wrist_b(m, a);
    wrist_c(a);
}

/* 1 when the arm's joint 2 or (RRR) 3 lies outside the window win
 * (dh_ikc_out_f32_) */
static DH_NOINLINE int wrist_left(const dh_ikc_model_f32 *m, const float *win, const dh_ikc_sol_f32 *arm)
{
    return dh_ikc_out_f32_(win, 1u, arm->q[1]) || (m->kind == DH_IKC_WRIST_RRR && dh_ikc_out_f32_(win, 2u, arm->q[2]));
}

/* One pass: the shoulder branches into sol[6] and sol[7] (read before any
 * solution reaches them), each arm into its solution's final slot
 * (elbow branch 1 two slots on, moved down when branch 0's wrist is
 * singular or branch 0 left the window), its wrist solutions there and in
 * the next slot. R01^T of R06's columns a and n, shared by a shoulder
 * branch's arms, waits in q[0..2] and q[3..5] of the fourth slot from its
 * first arm (n0 + 3 <= 7: written last, by the second arm's flipped wrist
 * solution, which reads the column n in place). win: a window of
 * canonical values (dh_ikc_out_f32_; NULL: none); a shoulder branch whose
 * joint 1 lies outside it is left before its elbow, an arm whose joint 2
 * or 3 does before its wrist; the branches kept are computed by the same
 * operations as without it, so they come out the same, in the same
 * order. */
DH_INLINE uint32_t wrist_solve(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *q_ref,
                               const float *win, dh_ikc_sol_f32 *sol)
{
    /* R06 e_x, R06 Rx(alpha6)^T e_z, the wrist centre; after the
     * shoulder v[6..7] = cos, sin of joint 1, v[8..9] of joint 2 (RRR: of
     * theta2 + sigma theta3) for wrist_m */
    float v[10];
    const float cref2 = dh_ikc_cref_f32_(m, q_ref, 1u);
    uint32_t b, e, ns, ne, n = 0u;
    wrist_prepare(m, T, v, &v[3], &v[6]);
    ns = wrist_shoulder(m, dh_ikc_cref_f32_(m, q_ref, 0u), &v[6], &sol[6]);
    for (b = 0; b < ns; b++) {
        const dh_ikc_sol_f32 *sh = &sol[6u + b];
        const uint32_t n0 = n;
        if (win != NULL && dh_ikc_out_f32_(win, 0u, sh->q[0])) continue;
        ne = (m->kind == DH_IKC_WRIST_RRR) ? wrist_elbow_rrr(m, cref2, sh, &sol[n]) : wrist_elbow_rrp(m, cref2, sh, &sol[n]);
        if (ne != 0u) {
            /* joint 1 of both elbow branches (the arms keep theta1 in q[0]) */
            float *rot = sol[n0 + 3u].q;
            v[6] = sh->q[3]; /* sh is not read after this */
            v[7] = sh->q[4];
            if (v[6] > 1.5f) (void)dh_sincos_f32(sol[n].q[0], &v[7], &v[6]);
            wrist_rzrx_t(&v[3], &v[0], &rot[0], &rot[3], v[6], v[7], m->sa[0], m->ca[0]);
        }
        for (e = 0; e < ne; e++) {
            dh_ikc_sol_f32 *a = &sol[n];
            if (win != NULL && wrist_left(m, win, &sol[n0 + e * 2u])) continue;
            if (e != 0u && n != n0 + 2u) *a = sol[n0 + 2u]; /* branch 0's wrist singular or left */
            v[8] = a->q[3];
            v[9] = a->q[4];
            wrist_arm(m, q_ref, a, v, &sol[n0 + 3u]);
            n += (a[1].flags == IKC_GAP) ? 1u : 2u;
        }
    }
    return n;
}

uint32_t dh_ikc_wrist_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *q_ref, dh_ikc_sol_f32 *sol)
{
    return wrist_solve(m, T, q_ref, NULL, sol);
}

uint32_t dh_ikc_wrist_win_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *wq,
                               dh_ikc_sol_f32 *sol)
{
    return wrist_solve(m, T, wq, &wq[6], sol);
}

uint32_t dh_ikc_wrist_lim_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *q_ref,
                               dh_ikc_sol_f32 *sol)
{
    return wrist_solve(m, T, q_ref, m->lim_w, sol);
}

#else

/* Layout of sol while the wrist families solve (the caller's array is the
 * scratch, so that no frame below the atan2 calls holds vectors):
 * sol[7].q[3..5] = R06 e_x, sol[6].q[3..5] = R06 Rx(alpha6)^T e_z (the
 * columns M is made of), sol[5].q[3..5] = the wrist centre; arm solutions
 * use q[0..2] and flags only. */
#define IKC_RN(sol) (&(sol)[7].q[3])
#define IKC_RA(sol) (&(sol)[6].q[3])
#define IKC_P(sol) (&(sol)[5].q[3])

/* wrist_m for the arm solution in *arm, copied into out[0] first, the
 * cosines and sines of its joints 1 and 2 (RRR: theta2 + sigma theta3)
 * from dh_sincos_f32. */
static DH_NOINLINE void wrist_a(const dh_ikc_model_f32 *m, const float *q_ref, const dh_ikc_sol_f32 *arm,
                                dh_ikc_sol_f32 *out, const float *rn, const float *ra)
{
    float cs[4];
    float *mz = &out[0].q[3], *mx = &out[1].q[3];
    const float t2 = (m->kind == DH_IKC_WRIST_RRR) ? arm->q[1] + m->k[KW_SIGMA] * arm->q[2] : arm->q[1];
    out[0].flags = arm->flags;
    out[0].q[0] = arm->q[0];
    out[0].q[1] = arm->q[1];
    out[0].q[2] = arm->q[2];
    (void)dh_sincos_f32(out[0].q[0], &cs[1], &cs[0]);
    (void)dh_sincos_f32(t2, &cs[3], &cs[2]);
    wrist_rzrx_t(ra, rn, mz, mx, cs[0], cs[1], m->sa[0], m->ca[0]);
    wrist_m(m, q_ref, out, mx, mz, &cs[2]);
}

/* Arm values and flags (q[0..2]) of src into dst, q[3..5] left alone. */
static void wrist_copy_arm(dh_ikc_sol_f32 *dst, const dh_ikc_sol_f32 *src)
{
    dst->q[0] = src->q[0];
    dst->q[1] = src->q[1];
    dst->q[2] = src->q[2];
    dst->flags = src->flags;
}

/* Entries of sol[0..n-1] whose flags are not IKC_GAP moved to the front
 * (arm values only when arm, else whole entries), in order. */
static DH_NOINLINE uint32_t wrist_compact(dh_ikc_sol_f32 *sol, uint32_t n, int arm)
{
    uint32_t i, out = 0;
    for (i = 0; i < n; i++) {
        if (sol[i].flags == IKC_GAP) continue;
        if (out != i) {
            if (arm) wrist_copy_arm(&sol[out], &sol[i]);
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
    wrist_prepare(m, T, IKC_RN(sol), IKC_RA(sol), IKC_P(sol));
    /* shoulder branches in sol[0..1], each -> elbow branches at 2b, 2b+1
     * (from the last: nothing unread is overwritten) */
    na = wrist_shoulder(m, dh_ikc_cref_f32_(m, q_ref, 0u), IKC_P(sol), sol);
    for (i = na; i-- > 0u;) {
        uint32_t ne;
        if (i != 0u) wrist_copy_arm(&sol[2u * i], &sol[i]);
        sol[2u * i + 1u].flags = IKC_GAP;
        c4 = dh_ikc_cref_f32_(m, q_ref, 1u);
        ne = (m->kind == DH_IKC_WRIST_RRR) ? wrist_elbow_rrr(m, c4, &sol[2u * i], &sol[2u * i])
                                           : wrist_elbow_rrp(m, c4, &sol[2u * i], &sol[2u * i]);
        if (ne == 0u) sol[2u * i].flags = IKC_GAP;
    }
    na = wrist_compact(sol, 2u * na, 1);
    /* arms to the end (slots 8 - na .. 7), then arm j -> wrist solutions at
     * 2j, 2j+1: every slot written has been read */
    base = DH_IKC_MAX_SOL - na;
    for (i = na; i-- > 0u;) wrist_copy_arm(&sol[base + i], &sol[i]);
    for (i = 0; i < na; i++) {
        wrist_a(m, q_ref, &sol[base + i], &sol[2u * i], IKC_RN(sol), IKC_RA(sol));
        wrist_b(m, &sol[2u * i]);
        wrist_c(&sol[2u * i]);
    }
    return wrist_compact(sol, 2u * na, 0);
}

/* The in-place solver leaves no branch early: every solution (a window
 * only narrows the set a caller may need; dh_ikc_raw_win_f32_ calls
 * dh_ikc_wrist_f32_ directly in these builds). */
uint32_t dh_ikc_wrist_win_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *wq,
                               dh_ikc_sol_f32 *sol)
{
    return dh_ikc_wrist_f32_(m, T, wq, sol);
}

uint32_t dh_ikc_wrist_lim_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *q_ref,
                               dh_ikc_sol_f32 *sol)
{
    return dh_ikc_wrist_f32_(m, T, q_ref, sol);
}

#endif /* WRIST_ONE_PASS */
