/* SPDX-License-Identifier: Apache-2.0 */
/* Configuration sanity: the settings the library was built with are in
 * range and, when a config header is given, it was really included. */
#include "dht.h"
#include "dhmath/common.h"
#include "dhmath/robot.h"

/* The Q constants have the values the formats define (a wrong one would
 * silently scale every fixed-point result). */
static void q_constants(void)
{
    DHT_EQ_INT(DH_QPOS_ONE, (int32_t)1 << DH_QPOS_FRAC);
    DHT_EQ_INT(DH_Q30_ONE, 0x40000000);
    DHT_EQ_INT(DH_Q16_ONE, 0x10000);
}

static void config_header_honoured(void)
{
    /* config.h includes DH_CONFIG_HEADER when the build sets one (the
     * confighdr variant of tools/check_variants.sh); the test header
     * defines DH_TEST_CONFIG_HEADER_SEEN. Without a config header the macro
     * must not leak in from anywhere else. */
#ifdef DH_CONFIG_HEADER
#ifdef DH_TEST_CONFIG_HEADER_SEEN
    int seen = DH_TEST_CONFIG_HEADER_SEEN;
#else
    int seen = 0;
#endif
    DHT_EQ_INT(seen, 1);
#else
#ifdef DH_TEST_CONFIG_HEADER_SEEN
    int seen = 1;
#else
    int seen = 0;
#endif
    DHT_EQ_INT(seen, 0);
#endif
}

/* The configured capacity is what the robot type really holds: a robot
 * accepts exactly DH_MAX_JOINTS joints and rejects one more. */
static void max_joints_is_the_capacity(void)
{
    dh_robot r;
    uint32_t i;
    DHT_EQ_INT(dh_robot_init(&r, DH_CONV_STANDARD), DH_OK);
    for (i = 0; i < (uint32_t)DH_MAX_JOINTS; i++)
        DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0.0f, 0.0f, 0.1f, 0.0f), DH_OK);
    DHT_EQ_INT(dh_robot_add_joint_f32(&r, DH_JOINT_REVOLUTE, 0.0f, 0.0f, 0.1f, 0.0f), DH_ERR_ARG);
    DHT_EQ_INT(r.n, DH_MAX_JOINTS);
    DHT_EQ_INT(sizeof r.joint / sizeof r.joint[0], DH_MAX_JOINTS);
}

static const dht_case cases[] = {
    DHT_CASE(q_constants),
    DHT_CASE(max_joints_is_the_capacity),
    DHT_CASE(config_header_honoured),
};
DHT_MAIN(cases)
