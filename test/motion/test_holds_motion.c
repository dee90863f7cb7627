/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_holds_motion.c - motion objects that hold nothing (motion.h: "holds
 * no profile / path / move / blend / sequence"): a profile, path, move,
 * blend or blended sequence made by its constructor and then given one
 * field out of its documented range is refused by every function that
 * reads it with DH_ERR_ARG, its outputs untouched and the object itself
 * unchanged. Each case first checks that the untouched object is read
 * fine, so a refusal is the field's doing.
 */
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_canary.h"
#include "dhmath/motion.h"
#include "dhmath/mat4.h"

#define Q16(x) ((int32_t)((x) * 65536))

/* ---- fixed-point profiles -------------------------------------------------- */

/* dh_profile_eval_q on p with d != 0: DH_ERR_ARG, outputs untouched */
static void profq_refused(const dh_profile_q *p)
{
    int32_t pos, vel, acc;
    CANARY(pos);
    CANARY(vel);
    CANARY(acc);
    DHT_EQ_INT(dh_profile_eval_q(p, p->T / 3u, &pos, &vel, &acc), DH_ERR_ARG);
    DHT_EQ_INT(dh_profile_eval_q(p, 0u, &pos, &vel, &acc), DH_ERR_ARG);
    UNTOUCHED(pos);
    UNTOUCHED(vel);
    UNTOUCHED(acc);
}

/* one field of a profile set out of range: the profile it starts from
 * (0 trapezoid, 1 seven-phase, 2 quintic), the field, its value, and xa
 * when not 0 */
enum { F_T, F_V, F_A, F_J, F_XJ, F_XA, F_KIND };
typedef struct {
    int base, field;
    int32_t v, xa;
} profq_bad;

static const profq_bad bad[] = {
    { 2, F_T, 0, 0 },
    { 0, F_T, INT32_MIN, 0 },
    { 1, F_V, 0, 0 },
    { 2, F_A, -1, 0 },
    { 0, F_KIND, 7, 0 },
    { 0, F_XJ, -1, 0 },
    { 1, F_XJ, 0x10000001, 0x20000000 },
    { 1, F_XJ, 0x01000000, 0x01FFFFFF },
    { 0, F_XA, 0, 0 },
    { 0, F_XA, 0x20000001, 0 },
    { 1, F_XJ, 0, 0 },
    { 1, F_J, 0, 0 },
    { 0, F_XJ, 0x00100000, 0 },
};

static void profile_q_holds_none(void)
{
    dh_profile_q tr, sc, qu, p;
    unsigned k;
    int32_t pos, vel, acc, q[2], qd[2], qdd[2];
    const int32_t q0[2] = { 0, Q16(10) }, q1[2] = { Q16(90), Q16(10) };
    dh_profile_q jm[2];
    DHT_EQ_INT(dh_profile_trap_q(&tr, Q16(90), Q16(100), Q16(400)), DH_OK);
    DHT_EQ_INT(dh_profile_scurve_q(&sc, Q16(90), Q16(100), Q16(400), Q16(4000)), DH_OK);
    DHT_EQ_INT(dh_profile_quintic_q(&qu, Q16(90), 1000000u), DH_OK);
    /* the constructors' profiles are read: t >= T gives d exactly */
    DHT_EQ_INT(dh_profile_eval_q(&tr, tr.T, &pos, &vel, &acc), DH_OK);
    DHT_EQ_INT(pos, Q16(90));
    DHT_EQ_INT(dh_profile_eval_q(&sc, sc.T, &pos, &vel, &acc), DH_OK);
    DHT_EQ_INT(pos, Q16(90));
    DHT_EQ_INT(dh_profile_eval_q(&qu, qu.T, &pos, &vel, &acc), DH_OK);
    DHT_EQ_INT(pos, Q16(90));
    /* T out of 1 .. 2^31 - 1, peaks <= 0 (every kind); ratios out of
     * range: xj < 0, xj > 1/4, xa < 2 xj, xa <= xj, xa > 1/2; a
     * seven-phase profile without jerk phases or without jerk; a
     * trapezoid with jerk phases; an unknown kind */
    for (k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        p = (bad[k].base == 0) ? tr : ((bad[k].base == 1) ? sc : qu);
        switch (bad[k].field) {
        case F_T: p.T = (uint32_t)bad[k].v; break;
        case F_V: p.v = bad[k].v; break;
        case F_A: p.a = bad[k].v; break;
        case F_J: p.j = bad[k].v; break;
        case F_XJ: p.xj = bad[k].v; break;
        case F_XA: p.xa = bad[k].v; break;
        default: p.kind = (uint32_t)bad[k].v; break;
        }
        if (bad[k].xa != 0) p.xa = bad[k].xa;
        profq_refused(&p);
    }
    /* d == 0 holds the no move whatever the rest */
    p = tr;
    p.d = 0;
    p.T = 0x80000000u;
    DHT_EQ_INT(dh_profile_eval_q(&p, 5u, &pos, &vel, &acc), DH_OK);
    DHT_EQ_INT(pos, 0);
    DHT_EQ_INT(vel, 0);
    DHT_EQ_INT(acc, 0);
    /* a joint move with one profile that holds none: refused, untouched */
    DHT_EQ_INT(dh_joint_move_q(jm, 2u, q0, q1, (const int32_t[]){ Q16(100), Q16(100) },
                               (const int32_t[]){ Q16(400), Q16(400) }, NULL), DH_OK);
    DHT_EQ_INT(dh_joint_move_eval_q(jm, 2u, q0, q1, jm[0].T, q, qd, qdd), DH_OK);
    DHT_EQ_INT(q[0], q1[0]);
    DHT_EQ_INT(q[1], q1[1]);
    jm[0].xa = 0x30000000;
    CANARY(q);
    CANARY(qd);
    CANARY(qdd);
    DHT_EQ_INT(dh_joint_move_eval_q(jm, 2u, q0, q1, 1000u, q, qd, qdd), DH_ERR_ARG);
    UNTOUCHED(q);
    UNTOUCHED(qd);
    UNTOUCHED(qdd);
}

/* ---- fixed-point paths ----------------------------------------------------- */

/* A: identity at the origin; B: turned 90 degrees about z at (100, 50, 0) mm */
static void frames_q(dh_frame_q *A, dh_frame_q *B)
{
    memset(A, 0, sizeof *A);
    memset(B, 0, sizeof *B);
    A->r[0][0] = A->r[1][1] = A->r[2][2] = DH_Q30_ONE;
    B->r[0][1] = DH_Q30_ONE;  /* column 0: (0, 1, 0) */
    B->r[1][0] = -DH_Q30_ONE; /* column 1: (-1, 0, 0) */
    B->r[2][2] = DH_Q30_ONE;
    B->p[0] = Q16(100);
    B->p[1] = Q16(50);
}

static void pathq_refused(const dh_path_q *p)
{
    dh_frame_q T;
    CANARY(T);
    DHT_EQ_INT(dh_path_eval_q(p, DH_Q30_ONE / 2, &T), DH_ERR_ARG);
    UNTOUCHED(T);
}

/* q scaled by k/8 */
static void quat_scale_q(dh_quat_q *q, int32_t k)
{
    q->w = q->w / 8 * k;
    q->x = q->x / 8 * k;
    q->y = q->y / 8 * k;
    q->z = q->z / 8 * k;
}

static void path_q_holds_none(void)
{
    dh_frame_q A, B, T;
    dh_path_q good, p;
    frames_q(&A, &B);
    DHT_EQ_INT(dh_path_line_q(&good, &A, &B), DH_OK);
    DHT_EQ_INT(dh_path_eval_q(&good, DH_Q30_ONE, &T), DH_OK);
    DHT_TRUE(memcmp(&T, &B, sizeof T) == 0);
    p = good;
    p.kind = 9u;
    pathq_refused(&p);
    /* |qa|^2 or |qb|^2 outside (1/2, 2): scaled by 5/8 (0.39) or 12/8 (2.25) */
    p = good;
    quat_scale_q(&p.qa, 5);
    pathq_refused(&p);
    p = good;
    quat_scale_q(&p.qa, 12);
    pathq_refused(&p);
    p = good;
    quat_scale_q(&p.qb, 5);
    pathq_refused(&p);
    p = good;
    quat_scale_q(&p.qb, 12);
    pathq_refused(&p);
    /* within the factor 2 the path is still read */
    p = good;
    quat_scale_q(&p.qb, 9);
    DHT_EQ_INT(dh_path_eval_q(&p, 0, &T), DH_OK);
    DHT_TRUE(memcmp(&T, &A, sizeof T) == 0);
}

/* ---- fixed-point moves ----------------------------------------------------- */

static const dh_cart_limits_q LIM_Q = { 250 << 16, 2000 << 16, 45 << 16, 360 << 16 };

/* the joint step and the path functions on mv: DH_ERR_ARG, mv unchanged,
 * outputs untouched */
static void moveq_refused(dh_move_q *mv)
{
    dh_move_q before = *mv;
    dh_move_report_q rep;
    dh_frame_q T;
    int32_t q[DH_MAX_JOINTS];
    CANARY(rep);
    CANARY(T);
    CANARY(q);
    if (before.kind == (uint32_t)DH_MOVE_JOINT) {
        DHT_EQ_INT(dh_move_joint_step_q(mv, 1000u, q, &rep), DH_ERR_ARG);
    } else {
        DHT_EQ_INT(dh_move_target_q(mv, &T), DH_ERR_ARG);
        DHT_EQ_INT(dh_move_advance_q(mv, 1000u, DH_TRACK_OK, &rep), DH_ERR_ARG);
        DHT_EQ_INT(dh_move_advance_q(mv, 1000u, DH_TRACK_LAGGING, &rep), DH_ERR_ARG);
    }
    DHT_TRUE(memcmp(mv, &before, sizeof before) == 0);
    UNTOUCHED(rep);
    UNTOUCHED(T);
    UNTOUCHED(q);
}

/* the fields every move kind checks, each set out of range in turn */
static void moveq_common_refused(const dh_move_q *good, dh_move_q *mv)
{
    *mv = *good;
    mv->dur = 0x80000000u;
    mv->clock = 0u;
    moveq_refused(mv);
    *mv = *good;
    mv->clock = mv->dur + 1u;
    moveq_refused(mv);
    *mv = *good;
    mv->cfrac = (uint32_t)DH_Q30_ONE;
    moveq_refused(mv);
    *mv = *good;
    mv->feed = -1;
    moveq_refused(mv);
    *mv = *good;
    mv->feed = DH_Q30_ONE + 1;
    moveq_refused(mv);
    *mv = *good;
    mv->fcap = -1;
    moveq_refused(mv);
    *mv = *good;
    mv->fcap = DH_Q30_ONE + 1;
    moveq_refused(mv);
}

static void move_q_holds_none(void)
{
    const int32_t q0[2] = { 0, Q16(-20) }, q1[2] = { Q16(45), Q16(20) };
    const int32_t v[2] = { Q16(90), Q16(90) }, a[2] = { Q16(360), Q16(360) };
    dh_move_q good, mv;
    dh_move_report_q rep;
    dh_frame_q A, B, T;
    dh_path_q p;
    int32_t q[DH_MAX_JOINTS];
    /* joint move */
    DHT_EQ_INT(dh_move_joint_q(&good, 2u, q0, q1, v, a, NULL), DH_OK);
    mv = good;
    DHT_EQ_INT(dh_move_joint_step_q(&mv, 1000u, q, &rep), DH_OK);
    DHT_EQ_INT(rep.clock, 1000u);
    moveq_common_refused(&good, &mv);
    mv = good;
    mv.n = 0u;
    moveq_refused(&mv);
    mv = good;
    mv.n = DH_MAX_JOINTS + 1u;
    moveq_refused(&mv);
    /* path move */
    frames_q(&A, &B);
    DHT_EQ_INT(dh_path_line_q(&p, &A, &B), DH_OK);
    DHT_EQ_INT(dh_move_path_q(&good, &p, &LIM_Q), DH_OK);
    mv = good;
    DHT_EQ_INT(dh_move_target_q(&mv, &T), DH_OK);
    DHT_TRUE(memcmp(&T, &A, sizeof T) == 0);
    moveq_common_refused(&good, &mv);
    mv = good;
    mv.e = 31u;
    moveq_refused(&mv);
    /* a profile of s that holds none, or that does not end at s = 2^e
     * (beyond 1, or below 0): no target to read (the path and the
     * profile are checked where they are read, dh_move_q.c) */
    mv = good;
    mv.prof[0].xa = 0;
    CANARY(T);
    DHT_EQ_INT(dh_move_target_q(&mv, &T), DH_ERR_ARG);
    UNTOUCHED(T);
    mv.prof[0].xa = good.prof[0].xa;
    mv.prof[0].d = (int32_t)(2u << mv.e);
    mv.clock = mv.dur;
    DHT_EQ_INT(dh_move_target_q(&mv, &T), DH_ERR_ARG);
    UNTOUCHED(T);
    mv.prof[0].d = -(int32_t)(1u << mv.e);
    DHT_EQ_INT(dh_move_target_q(&mv, &T), DH_ERR_ARG);
    UNTOUCHED(T);
}

/* ---- float paths and moves ------------------------------------------------- */

static const dh_cart_limits_f32 LIM = { 0.25f, 2.0f, 45.0f, 360.0f };

static void frames_f32(dh_mat4_f32 *A, dh_mat4_f32 *B, dh_mat4_f32 *C)
{
    dh_mat4_identity_f32(A);
    dh_mat4_rotz_f32(90.0f, B);
    DH_M4(B, 0, 3) = 0.1f;
    dh_mat4_rotz_f32(90.0f, C);
    DH_M4(C, 0, 3) = 0.1f;
    DH_M4(C, 1, 3) = 0.1f;
}

static void quat_scale(dh_quat_f32 *q, float k)
{
    q->w *= k;
    q->x *= k;
    q->y *= k;
    q->z *= k;
}

static void path_refused(const dh_path_f32 *p)
{
    dh_mat4_f32 T;
    CANARY(T);
    DHT_EQ_INT(dh_path_eval_f32(p, 0.5f, &T), DH_ERR_ARG);
    UNTOUCHED(T);
}

static void path_f32_holds_none(void)
{
    dh_mat4_f32 A, B, C, T;
    dh_path_f32 good, p;
    frames_f32(&A, &B, &C);
    DHT_EQ_INT(dh_path_line_f32(&good, &A, &B), DH_OK);
    DHT_EQ_INT(dh_path_eval_f32(&good, 1.0f, &T), DH_OK);
    DHT_TRUE(memcmp(&T, &B, sizeof T) == 0);
    /* |qa|^2 or |qb|^2 outside (1/2, 2) */
    p = good;
    quat_scale(&p.qa, 0.6f);
    path_refused(&p);
    p = good;
    quat_scale(&p.qa, 1.5f);
    path_refused(&p);
    p = good;
    quat_scale(&p.qb, 0.6f);
    path_refused(&p);
    p = good;
    quat_scale(&p.qb, 1.5f);
    path_refused(&p);
}

static void movef_refused(dh_move_f32 *mv)
{
    dh_move_f32 before = *mv;
    dh_move_report_f32 rep;
    dh_mat4_f32 T;
    float q[DH_MAX_JOINTS];
    CANARY(rep);
    CANARY(T);
    CANARY(q);
    if (before.kind == (uint32_t)DH_MOVE_JOINT) {
        DHT_EQ_INT(dh_move_joint_step_f32(mv, 1e-3f, q, &rep), DH_ERR_ARG);
    } else {
        DHT_EQ_INT(dh_move_target_f32(mv, &T), DH_ERR_ARG);
        DHT_EQ_INT(dh_move_advance_f32(mv, 1e-3f, DH_TRACK_OK, &rep), DH_ERR_ARG);
    }
    DHT_TRUE(memcmp(mv, &before, sizeof before) == 0);
    UNTOUCHED(rep);
    UNTOUCHED(T);
    UNTOUCHED(q);
}

static void movef_common_refused(const dh_move_f32 *good, dh_move_f32 *mv)
{
    static const float bad_dur[3] = { NAN, INFINITY, -1.0f };
    static const float bad_rate[2] = { -0.25f, 1.25f };
    unsigned k;
    for (k = 0; k < 3u; k++) {
        *mv = *good;
        mv->dur = bad_dur[k];
        mv->clock = 0.0f;
        movef_refused(mv);
    }
    for (k = 0; k < 2u; k++) {
        *mv = *good;
        mv->feed = bad_rate[k];
        movef_refused(mv);
        *mv = *good;
        mv->fcap = bad_rate[k];
        movef_refused(mv);
    }
    *mv = *good;
    mv->clock = mv->dur * 1.5f;
    movef_refused(mv);
}

static void move_f32_holds_none(void)
{
    const float q0[2] = { 0.0f, -20.0f }, q1[2] = { 45.0f, 20.0f }, v[2] = { 90.0f, 90.0f }, a[2] = { 360.0f, 360.0f };
    dh_move_f32 good, mv;
    dh_move_report_f32 rep;
    dh_mat4_f32 A, B, C, T;
    dh_path_f32 p;
    float q[DH_MAX_JOINTS];
    DHT_EQ_INT(dh_move_joint_f32(&good, 2u, q0, q1, v, a, NULL), DH_OK);
    mv = good;
    DHT_EQ_INT(dh_move_joint_step_f32(&mv, 1e-3f, q, &rep), DH_OK);
    movef_common_refused(&good, &mv);
    mv = good;
    mv.n = 0u;
    movef_refused(&mv);
    mv = good;
    mv.n = DH_MAX_JOINTS + 1u;
    movef_refused(&mv);
    frames_f32(&A, &B, &C);
    DHT_EQ_INT(dh_path_line_f32(&p, &A, &B), DH_OK);
    DHT_EQ_INT(dh_move_path_f32(&good, &p, &LIM), DH_OK);
    mv = good;
    DHT_EQ_INT(dh_move_target_f32(&mv, &T), DH_OK);
    DHT_TRUE(memcmp(&T, &A, sizeof T) == 0);
    movef_common_refused(&good, &mv);
    /* the copy of the path holds none, or a profile of s whose position
     * is not finite: no target to read */
    mv = good;
    quat_scale(&mv.path.qb, 0.5f);
    CANARY(T);
    DHT_EQ_INT(dh_move_target_f32(&mv, &T), DH_ERR_ARG);
    mv = good;
    mv.prof[0].T = 0.0f;
    mv.prof[0].d = INFINITY;
    DHT_EQ_INT(dh_move_target_f32(&mv, &T), DH_ERR_ARG);
    UNTOUCHED(T);
}

/* ---- blends ---------------------------------------------------------------- */

static void blend_holds_none(void)
{
    dh_mat4_f32 A, B, C, T;
    dh_path_f32 ln[2], bad[2];
    dh_blend_f32 bl, bb;
    dh_blend_seg_f32 seg[2];
    dh_blend_seq_f32 sq, sb;
    const float radius = 0.02f;
    float t;
    frames_f32(&A, &B, &C);
    DHT_EQ_INT(dh_path_line_f32(&ln[0], &A, &B), DH_OK);
    DHT_EQ_INT(dh_path_line_f32(&ln[1], &B, &C), DH_OK);
    DHT_EQ_INT(dh_blend_plan_f32(&bl, &ln[0], &ln[1], &LIM, radius), DH_OK);
    DHT_TRUE(bl.tb > 0.0f);
    t = bl.t0 + 0.5f * bl.tb;
    DHT_EQ_INT(dh_blend_eval_f32(&bl, t, &T), DH_OK);
    bb = bl;
    quat_scale(&bb.p1.qa, 0.5f);
    CANARY(T);
    DHT_EQ_INT(dh_blend_eval_f32(&bb, t, &T), DH_ERR_ARG);
    bb = bl;
    quat_scale(&bb.p2.qb, 1.5f);
    DHT_EQ_INT(dh_blend_eval_f32(&bb, t, &T), DH_ERR_ARG);
    UNTOUCHED(T);
    /* sequence: n 0, no lines, no scalings; a line that holds no path
     * read in the overlap (either side of the corner) */
    DHT_EQ_INT(dh_blend_seq_plan_f32(&sq, seg, ln, 2u, &radius, &LIM), DH_OK);
    DHT_TRUE(seg[1].tb0 > 0.0f);
    t = seg[1].t0 + 0.5f * seg[1].tb0;
    DHT_EQ_INT(dh_blend_seq_eval_f32(&sq, t, &T), DH_OK);
    CANARY(T);
    sb = sq;
    sb.n = 0u;
    DHT_EQ_INT(dh_blend_seq_eval_f32(&sb, t, &T), DH_ERR_ARG);
    sb = sq;
    sb.p = NULL;
    DHT_EQ_INT(dh_blend_seq_eval_f32(&sb, t, &T), DH_ERR_ARG);
    sb = sq;
    sb.seg = NULL;
    DHT_EQ_INT(dh_blend_seq_eval_f32(&sb, t, &T), DH_ERR_ARG);
    sb = sq;
    sb.p = bad;
    bad[0] = ln[0];
    bad[1] = ln[1];
    quat_scale(&bad[0].qb, 0.5f);
    DHT_EQ_INT(dh_blend_seq_eval_f32(&sb, t, &T), DH_ERR_ARG);
    bad[0] = ln[0];
    quat_scale(&bad[1].qa, 1.5f);
    DHT_EQ_INT(dh_blend_seq_eval_f32(&sb, t, &T), DH_ERR_ARG);
    UNTOUCHED(T);
}

static const dht_case cases[] = {
    DHT_CASE(profile_q_holds_none),
    DHT_CASE(path_q_holds_none),
    DHT_CASE(move_q_holds_none),
    DHT_CASE(path_f32_holds_none),
    DHT_CASE(move_f32_holds_none),
    DHT_CASE(blend_holds_none),
};

DHT_MAIN(cases)
