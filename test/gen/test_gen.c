/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_gen.c - the robots `dhmath gen` wrote for the .dh files of examples/robots
 * (const dh_robot dhg_<stem>, compiled into this test from the build tree)
 * against the robots the setters build at run time from the same tables
 * (tools/gen_robots.py, dhs_build of support_robots.c: dh_robot_init,
 * dh_robot_add_joint_f32, dh_robot_set_limits_f32, dh_robot_set_base_f32 /
 * dh_robot_set_tool_f32). Both are read from the .dh file by different
 * parsers (the CLI's C parser, the Python generator), so equality also
 * checks that the emitted source keeps every bit.
 */
#include <string.h>

#include "dht.h"
#include "support_robots.h"
#include "dh_robots.h"
#include "dhg_list.h"
#include "dhmath/mat4.h"
#include "dhmath/robot.h"

#define DHG_DECL(stem, UP) extern const dh_robot dhg_##stem;
DHG_ROBOTS(DHG_DECL)

/* a dhs_robot from the DHR_ macros of dh_robots.h (as support_robots.c) */
#define DHG_JOINT(type, a, d, alpha, theta, qmin, qmax) { type, a, d, alpha, theta, qmin, qmax },
#define DHG_DESC(stem, UP) { DHR_##UP##_NAME, DHR_##UP##_CONV, DHR_##UP##_N, DHR_##UP##_UNIT_PER_M, \
                             { DHR_##UP##_JOINTS(DHG_JOINT) }, DHR_##UP##_BASE, DHR_##UP##_TOOL },
static const dhs_robot desc[] = { DHG_ROBOTS(DHG_DESC) };
#define DHG_PTR(stem, UP) &dhg_##stem,
static const dh_robot *const gen[] = { DHG_ROBOTS(DHG_PTR) };
#define N_ROBOTS (sizeof gen / sizeof gen[0])

/* the first member of a and b whose bits differ (NULL: none). Member by
 * member: where enums are short (arm-none-eabi) the struct has padding. */
static const char *first_difference(const dh_robot *a, const dh_robot *b)
{
    uint32_t i;
    if (a->conv != b->conv) return "conv";
    if (a->n != b->n) return "n";
    if (a->flags != b->flags) return "flags";
    for (i = 0; i < DH_MAX_JOINTS; i++) {
        const dh_joint *x = &a->joint[i], *y = &b->joint[i];
        /* the members after type: 16 four-byte members, no padding */
        if (x->type != y->type) return "joint type";
        if (memcmp(&x->a, &y->a, (size_t)((const char *)(&x->qmax_q + 1) - (const char *)&x->a)) != 0)
            return "joint constants";
    }
    if (memcmp(&a->base, &b->base, sizeof a->base) != 0) return "base";
    if (memcmp(&a->tool, &b->tool, sizeof a->tool) != 0) return "tool";
    if (memcmp(&a->base_q, &b->base_q, sizeof a->base_q) != 0) return "base_q";
    if (memcmp(&a->tool_q, &b->tool_q, sizeof a->tool_q) != 0) return "tool_q";
    return NULL;
}

/* every member, every joint slot */
static void generated_equal_runtime_built(void)
{
    size_t m;
    DHT_TRUE(N_ROBOTS >= 5u);
    for (m = 0; m < N_ROBOTS; m++) {
        dh_robot r;
        const char *diff;
        DHT_EQ_INT(dhs_build(&desc[m], &r), DH_OK);
        diff = first_difference(gen[m], &r);
        DHT_TRUE_MSG(diff == NULL, "%s: generated robot differs from the built one in %s", desc[m].name, diff);
        DHT_EQ_INT(gen[m]->n, desc[m].n);
        DHT_TRUE((gen[m]->flags & (DH_ROBOT_HAS_F32 | DH_ROBOT_HAS_Q)) == (DH_ROBOT_HAS_F32 | DH_ROBOT_HAS_Q));
        DHT_EQ_INT(dh_robot_check(gen[m]), DH_OK);
        DHT_EQ_INT(dh_robot_check(&r), DH_OK);
    }
}

/* random joint values: within the limits, and beyond them (FK does not
 * check limits) */
static void random_q(const dh_robot *r, float *q, int32_t *qq)
{
    double qd[DHS_MAX_JOINTS];
    uint32_t i;
    dhs_random_q_robot(r, qd);
    if (dht_rand_u32() % 4u == 0u)
        for (i = 0; i < r->n; i++) qd[i] *= 3.0;
    for (i = 0; i < r->n; i++) q[i] = (float)qd[i];
    dhs_q_from_double(r, qd, qq);
}

static void fk_bit_for_bit(void)
{
    long it, n = DHT_ITER(4000);
    size_t m;
    for (m = 0; m < N_ROBOTS; m++) {
        dh_robot r;
        DHT_EQ_INT(dhs_build(&desc[m], &r), DH_OK);
        for (it = 0; it < n; it++) {
            float q[DHS_MAX_JOINTS];
            int32_t qq[DHS_MAX_JOINTS];
            /* static: 2.5 KB of frames off the target's stack */
            static dh_mat4_f32 F1[DH_MAX_JOINTS], F2[DH_MAX_JOINTS];
            static dh_frame_q G1[DH_MAX_JOINTS], G2[DH_MAX_JOINTS];
            dh_mat4_f32 T1, T2;
            dh_frame_q P1, P2;
            dh_status s1, s2;
            random_q(&r, q, qq);
            memset(&T1, 0, sizeof T1);
            memset(&T2, 0, sizeof T2);
            s1 = dh_fk_f32(gen[m], q, &T1);
            s2 = dh_fk_f32(&r, q, &T2);
            DHT_EQ_INT(s1, DH_OK);
            DHT_EQ_INT(s2, DH_OK);
            DHT_TRUE_MSG(memcmp(&T1, &T2, sizeof T1) == 0, "%s: float FK differs (iteration %ld)", desc[m].name, it);
            memset(F1, 0, sizeof F1);
            memset(F2, 0, sizeof F2);
            DHT_EQ_INT(dh_fk_frames_f32(gen[m], q, F1, &T1), DH_OK);
            DHT_EQ_INT(dh_fk_frames_f32(&r, q, F2, &T2), DH_OK);
            DHT_TRUE(memcmp(F1, F2, sizeof F1) == 0 && memcmp(&T1, &T2, sizeof T1) == 0);
            memset(&P1, 0, sizeof P1);
            memset(&P2, 0, sizeof P2);
            s1 = dh_fk_q(gen[m], qq, &P1);
            s2 = dh_fk_q(&r, qq, &P2);
            DHT_EQ_INT(s1, s2);
            DHT_TRUE(s1 == DH_OK || s1 == DH_ERR_OVERFLOW);
            DHT_TRUE_MSG(memcmp(&P1, &P2, sizeof P1) == 0, "%s: fixed FK differs (iteration %ld)", desc[m].name, it);
            memset(G1, 0, sizeof G1);
            memset(G2, 0, sizeof G2);
            DHT_EQ_INT(dh_fk_frames_q(gen[m], qq, G1, &P1), dh_fk_frames_q(&r, qq, G2, &P2));
            DHT_TRUE(memcmp(G1, G2, sizeof G1) == 0 && memcmp(&P1, &P2, sizeof P1) == 0);
        }
    }
}

/* the generated robots are usable where the built ones are: a copy in RAM
 * takes further setters exactly like the built robot */
static void copy_takes_setters(void)
{
    size_t m;
    for (m = 0; m < N_ROBOTS; m++) {
        dh_robot a = *gen[m], b;
        dh_mat4_f32 M;
        DHT_EQ_INT(dhs_build(&desc[m], &b), DH_OK);
        dh_mat4_trans_f32(0.1f, -0.2f, 0.3f, &M);
        DHT_EQ_INT(dh_robot_set_tool_f32(&a, &M), DH_OK);
        DHT_EQ_INT(dh_robot_set_tool_f32(&b, &M), DH_OK);
        if (a.n < DH_MAX_JOINTS) {
            DHT_EQ_INT(dh_robot_add_joint_q(&a, DH_JOINT_PRISMATIC, 0, 100, 200, 90 * 65536), DH_OK);
            DHT_EQ_INT(dh_robot_add_joint_q(&b, DH_JOINT_PRISMATIC, 0, 100, 200, 90 * 65536), DH_OK);
        }
        DHT_TRUE_MSG(first_difference(&a, &b) == NULL, "%s: copies differ after the same setters", desc[m].name);
        DHT_EQ_INT(dh_robot_check(&a), DH_OK);
    }
}

static const dht_case cases[] = {
    DHT_CASE(generated_equal_runtime_built),
    DHT_CASE(fk_bit_for_bit),
    DHT_CASE(copy_takes_setters),
};
DHT_MAIN(cases)
