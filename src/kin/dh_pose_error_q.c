/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_pose_error_q.c - the orientation error a(dR) of two fixed-point
 * rotations (Q2.30), w = a(Rt R^T) in Q3.29 radians: the rotation vector
 * of dR (dh_rot_vec_q_, src/rot/dh_rot_q.c), or for small angles a series
 * on the skew part of dR. Integer only: no float, no libm, no 64-bit
 * division. Contract in include/dhmath/kin.h. Both inputs are checked as
 * the float path checks them (DH_ROT_ERROR_TOL_Q, det R > 0), else
 * DH_ERR_NOT_RIGID.
 */
#include "dhmath/kin.h"
#include "dhmath/frame.h"
#include "kin_impl.h"
#include "../rot/rot_impl.h"
#include "../internal/dh_qmath.h"

/* element (row a, column b) of a frame's rotation */
#define RQ(F, a, b) ((F)->r[(b)][(a)])

/* D = Rt R^T, each entry a three-term exact sum rounded once (entries of
 * checked rotations: products below 2^60.1). */
static DH_NOINLINE void poseq_delta(const dh_frame_q *Ft, const dh_frame_q *F, dh_frame_q *D)
{
    unsigned i, j, k;
    for (i = 0; i < 3u; i++)
        for (j = 0; j < 3u; j++) {
            int64_t t = 0;
            int ovf = 0;
            for (k = 0; k < 3u; k++) t += dh_q_mul64(RQ(Ft, i, k), RQ(F, j, k));
            RQ(D, i, j) = dh_q_rnd30(t, &ovf);
        }
    D->p[0] = 0;
    D->p[1] = 0;
    D->p[2] = 0;
}

/* 1/6 and 3/40 in Q2.30 */
#define POSEQ_SIXTH30 178956971
#define POSEQ_3_40_30 80530637

/* Small angles (sin theta below 1/16, cos theta >= 0: near convergence in
 * dh_ik_q, the common case) without the quaternion: u / 2 = sin(theta) k
 * from the skew part of D, w = (u / 2) theta / sin(theta) by the series
 * 1 + s^2/6 + 3 s^4/40 (truncation below 3e-9). 0 when D is beyond that. */
static DH_NOINLINE int poseq_small(const dh_frame_q *D, dh_dir3_q *w)
{
    int32_t uh[3], q2, q4, f;
    uint64_t s2 = 0u;
    unsigned i;
    uh[0] = (int32_t)(((int64_t)RQ(D, 2, 1) - RQ(D, 1, 2)) >> 1);
    uh[1] = (int32_t)(((int64_t)RQ(D, 0, 2) - RQ(D, 2, 0)) >> 1);
    uh[2] = (int32_t)(((int64_t)RQ(D, 1, 0) - RQ(D, 0, 1)) >> 1);
    if ((int64_t)RQ(D, 0, 0) + RQ(D, 1, 1) + RQ(D, 2, 2) < DH_Q_ONE30) return 0;   /* cos theta < 0 */
    for (i = 0; i < 3u; i++) s2 += (uint64_t)dh_q_mul64(uh[i], uh[i]);
    if (s2 >= ((uint64_t)1 << 52)) return 0;   /* sin theta >= 1/16 */
    q2 = (int32_t)(s2 >> 30);
    q4 = (int32_t)(dh_q_mul64(q2, q2) >> 30);
    f = DH_Q_ONE30 + (int32_t)(dh_q_mul64(q2, POSEQ_SIXTH30) >> 30) + (int32_t)(dh_q_mul64(q4, POSEQ_3_40_30) >> 30);
    w->x = (int32_t)dh_q_rshr(dh_q_mul64(uh[0], f), 31u);
    w->y = (int32_t)dh_q_rshr(dh_q_mul64(uh[1], f), 31u);
    w->z = (int32_t)dh_q_rshr(dh_q_mul64(uh[2], f), 31u);
    return 1;
}

/* w = a(Ft F^T) with the scratch D (dR) and q (its quaternion). */
DH_INLINE void poseq_err_core(const dh_frame_q *Ft, const dh_frame_q *F, dh_frame_q *D, dh_dir3_q *w, int32_t *q)
{
    poseq_delta(Ft, F, D);
    if (!poseq_small(D, w)) dh_rot_vec_q_(D, w, q);
}

void dh_kin_rot_error_q_(const dh_frame_q *F_target, const dh_frame_q *F, dh_kin_rot_scratch_q *s)
{
    poseq_err_core(F_target, F, &s->D, &s->w, s->q);
}

int dh_kin_rot_ok_q_(const dh_frame_q *F)
{
    return dh_rot_ok_q_(F, DH_ROT_ERROR_TOL_Q);
}

dh_status dh_kin_rot_error_to_q_(const dh_frame_q *F_target, const dh_frame_q *F, dh_frame_q *D, dh_dir3_q *w,
                                 int32_t *q)
{
    if (!dh_rot_ok_q_(F, DH_ROT_ERROR_TOL_Q)) return DH_ERR_NOT_RIGID;
    poseq_err_core(F_target, F, D, w, q);
    return DH_OK;
}

dh_status dh_rot_error_q(const dh_frame_q *F_target, const dh_frame_q *F, dh_dir3_q *w)
{
    dh_frame_q D;
    int32_t q[4];
    DH_ASSERT(F_target != NULL && F != NULL && w != NULL);
    if (!dh_rot_ok_q_(F_target, DH_ROT_ERROR_TOL_Q) || !dh_rot_ok_q_(F, DH_ROT_ERROR_TOL_Q)) return DH_ERR_NOT_RIGID;
    poseq_err_core(F_target, F, &D, w, q);
    return DH_OK;
}
