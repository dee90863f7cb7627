/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_robot_check.c - dh_robot_check: a description whose derived fields
 * are not what the setters compute is reported (DH_ERR_INCONSISTENT), every
 * description the setters build passes.
 *
 * The hand-written case is the firmware hazard the check exists for: a
 * static const dh_robot that fills in the DH table (and the fixed copies)
 * but not the derived fields gives a wrong pose with DH_OK from FK. The
 * expected poses come from the double reference of support_robots.c, never
 * from the code under test.
 */
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_robots.h"
#include "dhmath/robot.h"

/* The first three joints of the Puma 560 (examples/robots/puma560.dh) as a
 * firmware author would write them: DH table, limits and fixed copies
 * (metres Q16.16, degrees Q16.16), the flags of a robot with both paths,
 * identity base and tool; sin/cos of alpha left out (zero). */
#define HW_JOINT(a_, d_, al_, aq_, dq_, alq_) \
    { .type = DH_JOINT_REVOLUTE, .a = (a_), .d = (d_), .alpha_deg = (al_), .qmin = 1.0f, .qmax = -1.0f, \
      .a_q = (aq_), .d_q = (dq_), .alpha_q = (alq_), .qmin_q = 1, .qmax_q = -1 }
#define HW_ID4 { .m = { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 }, { 0, 0, 0, 1 } } }
#define HW_IDQ { .r = { { 0x40000000, 0, 0 }, { 0, 0x40000000, 0 }, { 0, 0, 0x40000000 } } }
static const dh_robot hand_written = {
    .conv = DH_CONV_STANDARD,
    .n = 3u,
    .flags = DH_ROBOT_HAS_F32 | DH_ROBOT_HAS_Q,
    .joint = { HW_JOINT(0.0f, 0.67183f, 90.0f, 0, 44029, 90 * 65536),
               HW_JOINT(0.4318f, 0.0f, 0.0f, 28298, 0, 0),
               HW_JOINT(0.0203f, 0.15005f, -90.0f, 1330, 9834, -90 * 65536) },
    .base = HW_ID4, .tool = HW_ID4, .base_q = HW_IDQ, .tool_q = HW_IDQ
};

static const dhs_robot *const shipped[] = { &dhs_puma560_m, &dhs_puma560_mm, &dhs_ur5_m,
                                            &dhs_ur5_mm, &dhs_panda_m, &dhs_panda_mm };
#define N_SHIPPED (sizeof shipped / sizeof shipped[0])

/* FK of the hand-written robot returns DH_OK with a pose far from the
 * reference; the setter-built one matches the reference; the check tells
 * them apart. */
static void hand_written_const_robot_is_reported(void)
{
    dhs_robot d = dhs_puma560_m;
    dh_robot built;
    dh_mat4_f32 T;
    dhr_mat4 R;
    const float q[3] = { 30.0f, -40.0f, 50.0f };
    const double qd[3] = { 30.0, -40.0, 50.0 };
    d.n = 3u;
    d.j[0].qmin = d.j[1].qmin = d.j[2].qmin = 1.0; /* no limits, as written by hand */
    d.j[0].qmax = d.j[1].qmax = d.j[2].qmax = -1.0;
    DHT_EQ_INT(dhs_build(&d, &built), DH_OK);
    dhs_fk_desc(&d, qd, NULL, &R);
    DHT_EQ_INT(dh_fk_f32(&hand_written, q, &T), DH_OK);
    DHT_TRUE(dhs_pos_err_f32(&T, &R) > 0.05);  /* the hazard: wrong pose, DH_OK */
    DHT_EQ_INT(dh_fk_f32(&built, q, &T), DH_OK);
    DHT_TRUE(dhs_pos_err_f32(&T, &R) < 1e-6);
    DHT_EQ_INT(dh_robot_check(&hand_written), DH_ERR_INCONSISTENT);
    DHT_EQ_INT(dh_robot_check(&built), DH_OK);
    /* with the derived fields as the setters compute them it passes */
    {
        dh_robot fixed = hand_written;
        uint32_t i;
        for (i = 0; i < 3u; i++) {
            fixed.joint[i].sa = built.joint[i].sa;
            fixed.joint[i].ca = built.joint[i].ca;
            fixed.joint[i].sa_q = built.joint[i].sa_q;
            fixed.joint[i].ca_q = built.joint[i].ca_q;
            /* the fixed copies (written above for DH_QPOS_FRAC 16) */
            fixed.joint[i].a_q = built.joint[i].a_q;
            fixed.joint[i].d_q = built.joint[i].d_q;
            /* rate limits: zero (left out) is no valid limit */
            fixed.joint[i].vmax = built.joint[i].vmax;
            fixed.joint[i].amax = built.joint[i].amax;
            fixed.joint[i].vmax_q = built.joint[i].vmax_q;
            fixed.joint[i].amax_q = built.joint[i].amax_q;
        }
        fixed.flags = built.flags;
        DHT_EQ_INT(dh_robot_check(&fixed), DH_OK);
        fixed.joint[1].vmax_q = 0;
        DHT_EQ_INT(dh_robot_check(&fixed), DH_ERR_INCONSISTENT);
        fixed.joint[1].vmax_q = built.joint[1].vmax_q;
        fixed.flags = built.flags;
        DHT_EQ_INT(dh_robot_check(&fixed), DH_OK);
    }
}

static void flip_f32(float *x, uint32_t bit)
{
    uint32_t u;
    memcpy(&u, x, sizeof u);
    u ^= bit;
    memcpy(x, &u, sizeof u);
}

/* exponent all ones: Inf or NaN */
static void make_nonfinite(float *x, uint32_t frac)
{
    uint32_t u;
    memcpy(&u, x, sizeof u);
    u |= 0x7F800000u | frac;
    memcpy(x, &u, sizeof u);
}

#define EXPECT_BAD(r, what) \
    DHT_TRUE_MSG(dh_robot_check(&(r)) == DH_ERR_INCONSISTENT, "%s %s: not reported", d->name, what)

/* one derived field (or a primary one far from its fixed copy) changed in
 * a setter-built robot: reported */
static void corrupted_fields_are_reported(void)
{
    size_t m;
    for (m = 0; m < N_SHIPPED; m++) {
        const dhs_robot *d = shipped[m];
        dh_robot r, c;
        uint32_t i, b;
        DHT_EQ_INT(dhs_build(d, &r), DH_OK);
        DHT_EQ_INT(dh_robot_check(&r), DH_OK);
        for (b = 0; b < 32u; b++) {
            c = r;
            c.flags ^= 1u << b;
            DHT_TRUE_MSG(dh_robot_check(&c) == DH_ERR_INCONSISTENT, "%s flag bit %lu: not reported", d->name,
                         (unsigned long)b);
        }
        for (i = 0; i < r.n; i++) {
            for (b = 0; b < 32u; b++) {
                c = r; flip_f32(&c.joint[i].sa, 1u << b); EXPECT_BAD(c, "sa");
                c = r; flip_f32(&c.joint[i].ca, 1u << b); EXPECT_BAD(c, "ca");
                c = r; c.joint[i].sa_q ^= (int32_t)(1u << b); EXPECT_BAD(c, "sa_q");
                c = r; c.joint[i].ca_q ^= (int32_t)(1u << b); EXPECT_BAD(c, "ca_q");
                c = r; c.joint[i].a_q ^= (int32_t)(1u << b); EXPECT_BAD(c, "a_q");
                c = r; c.joint[i].d_q ^= (int32_t)(1u << b); EXPECT_BAD(c, "d_q");
                c = r; c.joint[i].theta_q ^= (int32_t)(1u << b); EXPECT_BAD(c, "theta_q");
            }
            c = r; c.joint[i].a += 1.0f; EXPECT_BAD(c, "a");
            c = r; c.joint[i].d -= 0.5f; EXPECT_BAD(c, "d");
            c = r; c.joint[i].alpha_deg += 1.0f; EXPECT_BAD(c, "alpha");
            c = r; c.joint[i].theta_deg += 0.25f; EXPECT_BAD(c, "theta");
            c = r; c.joint[i].alpha_q += 65536; EXPECT_BAD(c, "alpha_q");
            c = r; make_nonfinite(&c.joint[i].qmin, 0u); EXPECT_BAD(c, "qmin Inf");
            c = r; make_nonfinite(&c.joint[i].qmax, 0x400000u); EXPECT_BAD(c, "qmax NaN");
            c = r; make_nonfinite(&c.joint[i].d, 1u); EXPECT_BAD(c, "d NaN");
            /* rate limits: a pair neither setter leaves */
            c = r; c.joint[i].vmax = 0.0f; EXPECT_BAD(c, "vmax 0");
            c = r; make_nonfinite(&c.joint[i].amax, 0x400000u); EXPECT_BAD(c, "amax NaN");
            c = r; c.joint[i].amax_q = -5; EXPECT_BAD(c, "amax_q < 0");
            c = r; (void)dh_robot_set_rates_f32(&c, i, 90.0f, 400.0f); c.joint[i].vmax_q += 65536; EXPECT_BAD(c, "vmax_q");
            c = r; (void)dh_robot_set_rates_q(&c, i, 1000, 77777); c.joint[i].amax *= 1.5f; EXPECT_BAD(c, "amax");
        }
        for (b = 0; b < 16u; b++) {
            c = r; c.base.m[b >> 2][b & 3u] += 0.5f; EXPECT_BAD(c, "base");
            c = r; c.tool.m[b >> 2][b & 3u] -= 0.25f; EXPECT_BAD(c, "tool");
        }
        for (b = 0; b < 9u; b++) {
            c = r; c.base_q.r[b / 3u][b % 3u] ^= 0x100; EXPECT_BAD(c, "base_q");
            c = r; c.tool_q.r[b / 3u][b % 3u] ^= 0x4; EXPECT_BAD(c, "tool_q");
        }
        c = r; c.tool_q.p[2] += 1; EXPECT_BAD(c, "tool_q p");
        /* out of range: ARG (as FK) */
        c = r; c.conv = (dh_convention)2; DHT_EQ_INT(dh_robot_check(&c), DH_ERR_ARG);
        c = r; c.n = DH_MAX_JOINTS + 1u; DHT_EQ_INT(dh_robot_check(&c), DH_ERR_ARG);
        c = r; c.joint[r.n - 1u].type = (dh_joint_type)2; DHT_EQ_INT(dh_robot_check(&c), DH_ERR_ARG);
        /* the slots after n are not read */
        c = r;
        if (c.n < DH_MAX_JOINTS) {
            memset(&c.joint[c.n], 0xA5, sizeof c.joint[0]);
            DHT_EQ_INT(dh_robot_check(&c), DH_OK);
        }
        /* limits are primary fields: any finite pair passes */
        c = r;
        (void)dh_robot_set_limits_q(&c, 0, 0, 0);
        c.joint[0].qmin = 3.0f;
        c.joint[0].qmax = -7.0f;
        DHT_EQ_INT(dh_robot_check(&c), DH_OK);
    }
}

/* ---- random setter sequences: every description they leave passes ---- */

static float rnd_f(double lo, double hi)
{
    return (float)dht_rand_uniform(lo, hi);
}

static int32_t rnd_i(void)
{
    return (int32_t)dht_rand_u32();
}

/* a float frame: identity, a rotation/translation, or one that does not fit
 * the fixed formats (entry 2, position beyond dh_qpos) */
static void rnd_frame(dh_mat4_f32 *M)
{
    unsigned c, k, kind = dht_rand_u32() % 4u;
    for (c = 0; c < 4u; c++)
        for (k = 0; k < 4u; k++) M->m[c][k] = (c == k) ? 1.0f : 0.0f;
    if (kind == 0u) return;
    for (c = 0; c < 3u; c++)
        for (k = 0; k < 3u; k++) M->m[c][k] = rnd_f(-1.0, 1.0);
    for (k = 0; k < 3u; k++) M->m[3][k] = rnd_f(-2.0, 2.0);
    if (kind == 2u) M->m[dht_rand_u32() % 3u][dht_rand_u32() % 3u] = -0.0f;
    if (kind == 3u) {
        if (dht_rand_u32() & 1u) M->m[0][0] = 2.0f;
        else M->m[3][1] = 1e9f;
    }
}

static void rnd_frame_q(dh_frame_q *F)
{
    unsigned c, k, kind = dht_rand_u32() % 3u;
    for (c = 0; c < 3u; c++) {
        for (k = 0; k < 3u; k++) F->r[c][k] = (c == k) ? 0x40000000 : 0;
        F->p[c] = 0;
    }
    if (kind == 0u) return;
    for (c = 0; c < 3u; c++) {
        for (k = 0; k < 3u; k++) F->r[c][k] = (kind == 1u) ? rnd_i() >> 2 : rnd_i();
        F->p[c] = rnd_i();
    }
}

static void setter_sequences_pass(void)
{
    long it, n = DHT_ITER(3000);
    for (it = 0; it < n; it++) {
        dh_robot r;
        int step, steps = (int)(dht_rand_u32() % 24u);
        DHT_EQ_INT(dh_robot_init(&r, (dh_convention)(dht_rand_u32() & 1u)), DH_OK);
        DHT_EQ_INT(dh_robot_check(&r), DH_OK);
        for (step = 0; step < steps; step++) {
            const unsigned op = dht_rand_u32() % 10u;
            const dh_joint_type t = (dht_rand_u32() & 1u) ? DH_JOINT_PRISMATIC : DH_JOINT_REVOLUTE;
            const uint32_t i = (r.n > 0u) ? dht_rand_u32() % r.n : 0u;
            dh_mat4_f32 M;
            dh_frame_q F;
            float lo = rnd_f(-200.0, 200.0), hi = lo + rnd_f(0.0, 300.0);
            switch (op) {
            case 0:
            case 1:
                if (dht_rand_u32() % 4u == 0u)  /* a constant that does not fit Q */
                    (void)dh_robot_add_joint_f32(&r, t, rnd_f(-360, 360), 1e6f, rnd_f(-1, 1), rnd_f(-180, 180));
                else if (dht_rand_u32() % 4u == 0u)
                    (void)dh_robot_add_joint_f32(&r, t, 0.0f, -0.0f, 0.0f, 0.0f);
                else
                    (void)dh_robot_add_joint_f32(&r, t, rnd_f(-720, 720), rnd_f(-2, 2), rnd_f(-2, 2),
                                                 rnd_f(-400, 400));
                break;
            case 2:
                (void)dh_robot_add_joint_q(&r, t, (dht_rand_u32() & 1u) ? rnd_i() : 0, rnd_i() >> 8,
                                           (dht_rand_u32() & 1u) ? rnd_i() >> 8 : 0, rnd_i());
                break;
            case 3:
                if (r.n > 0u) (void)dh_robot_set_limits_f32(&r, i, (dht_rand_u32() & 1u) ? lo : -3e9f, hi);
                break;
            case 4:
                if (r.n > 0u) (void)dh_robot_set_limits_q(&r, i, rnd_i() >> 1, (int32_t)(dht_rand_u32() >> 1));
                break;
            case 8:
                if (r.n > 0u) {
                    const float inf = (float)HUGE_VAL;
                    const float v = (dht_rand_u32() & 1u) ? inf : (float)ldexp(rnd_f(0.5, 1.0), (int)(dht_rand_u32() % 80u) - 40);
                    const float a = (dht_rand_u32() & 1u) ? inf : (float)ldexp(rnd_f(0.5, 1.0), (int)(dht_rand_u32() % 80u) - 40);
                    DHT_EQ_INT(dh_robot_set_rates_f32(&r, i, v, a), DH_OK);
                }
                break;
            case 9:
                if (r.n > 0u)
                    DHT_EQ_INT(dh_robot_set_rates_q(&r, i, (int32_t)(dht_rand_u32() >> (1u + dht_rand_u32() % 31u)) | 1,
                                                    (dht_rand_u32() & 1u) ? INT32_MAX : (int32_t)(dht_rand_u32() >> 1) | 1),
                               DH_OK);
                break;
            case 5:
                rnd_frame(&M);
                if (dht_rand_u32() & 1u) (void)dh_robot_set_base_f32(&r, &M);
                else (void)dh_robot_set_tool_f32(&r, &M);
                break;
            default:
                rnd_frame_q(&F);
                if (dht_rand_u32() & 1u) (void)dh_robot_set_base_q(&r, &F);
                else (void)dh_robot_set_tool_q(&r, &F);
                break;
            }
            DHT_TRUE_MSG(dh_robot_check(&r) == DH_OK, "iteration %ld step %d (op %u): setter-built robot reported",
                         it, step, op);
        }
    }
}

/* dh_robot_init (integer only) leaves the state of the float setters'
 * sequence for the empty description: every slot the joint
 * dh_robot_add_joint_f32(R, 0, 0, 0, 0) writes, n back to 0, identity base
 * and tool set with dh_robot_set_base_f32 / _tool_f32; compared field by
 * field (floats by their bits), then the flags and the check. */
static void init_is_the_setter_sequence(void)
{
    static const dh_mat4_f32 id = HW_ID4;
    unsigned conv;
    for (conv = 0u; conv < 2u; conv++) {
        dh_robot a, b;
        uint32_t i;
        memset(&a, 0xA5, sizeof a);
        memset(&b, 0x5A, sizeof b);
        DHT_EQ_INT(dh_robot_init(&a, (dh_convention)conv), DH_OK);
        b.conv = (dh_convention)conv;
        b.n = 0u;
        b.flags = 0u;
        b.base = id;
        b.tool = id;
        b.base_q = (dh_frame_q)HW_IDQ;
        b.tool_q = (dh_frame_q)HW_IDQ;
        for (i = 0u; i < (uint32_t)DH_MAX_JOINTS; i++)
            DHT_EQ_INT(dh_robot_add_joint_f32(&b, DH_JOINT_REVOLUTE, 0.0f, 0.0f, 0.0f, 0.0f), DH_OK);
        b.n = 0u;
        DHT_EQ_INT(dh_robot_set_base_f32(&b, &id), DH_OK);
        DHT_EQ_INT(dh_robot_set_tool_f32(&b, &id), DH_OK);
        DHT_EQ_INT(a.conv, b.conv);
        DHT_EQ_INT(a.n, 0u);
        DHT_EQ_INT(a.flags, b.flags);
        DHT_EQ_INT(a.flags, DH_ROBOT_HAS_F32 | DH_ROBOT_HAS_Q | DH_ROBOT_BASE_ID_F32 | DH_ROBOT_TOOL_ID_F32 |
                                DH_ROBOT_BASE_ID_Q | DH_ROBOT_TOOL_ID_Q | DH_ROBOT_BASE_SMALL_Q);
        for (i = 0u; i < (uint32_t)DH_MAX_JOINTS; i++) {
            const dh_joint *x = &a.joint[i], *y = &b.joint[i];
            const float fx[10] = { x->a, x->d, x->alpha_deg, x->theta_deg, x->qmin, x->qmax, x->sa, x->ca, x->vmax, x->amax };
            const float fy[10] = { y->a, y->d, y->alpha_deg, y->theta_deg, y->qmin, y->qmax, y->sa, y->ca, y->vmax, y->amax };
            const int32_t ix[10] = { x->a_q, x->d_q, x->alpha_q, x->theta_q, x->sa_q, x->ca_q, x->qmin_q, x->qmax_q,
                                     x->vmax_q, x->amax_q };
            const int32_t iy[10] = { y->a_q, y->d_q, y->alpha_q, y->theta_q, y->sa_q, y->ca_q, y->qmin_q, y->qmax_q,
                                     y->vmax_q, y->amax_q };
            DHT_EQ_INT(x->type, DH_JOINT_REVOLUTE);
            DHT_TRUE(x->qmin > x->qmax && x->qmin_q > x->qmax_q); /* no limits */
            DHT_TRUE(x->ca == 1.0f && x->ca_q == DH_Q30_ONE && x->sa_q == 0);
            DHT_TRUE(x->vmax > 3.4e38f && x->amax > 3.4e38f && x->vmax_q == INT32_MAX && x->amax_q == INT32_MAX);
            DHT_EQ_INT(x->type, y->type);
            DHT_TRUE_MSG(memcmp(fx, fy, sizeof fx) == 0, "joint %u: float fields differ", (unsigned)i);
            DHT_TRUE_MSG(memcmp(ix, iy, sizeof ix) == 0, "joint %u: fixed fields differ", (unsigned)i);
        }
        DHT_TRUE(memcmp(&a.base, &b.base, sizeof a.base) == 0);
        DHT_TRUE(memcmp(&a.tool, &b.tool, sizeof a.tool) == 0);
        DHT_TRUE(memcmp(&a.base_q, &b.base_q, sizeof a.base_q) == 0);
        DHT_TRUE(memcmp(&a.tool_q, &b.tool_q, sizeof a.tool_q) == 0);
        DHT_EQ_INT(dh_robot_check(&a), DH_OK);
    }
}

static const dht_case cases[] = {
    DHT_CASE(init_is_the_setter_sequence),
    DHT_CASE(hand_written_const_robot_is_reported),
    DHT_CASE(corrupted_fields_are_reported),
    DHT_CASE(setter_sequences_pass),
};
DHT_MAIN(cases)
