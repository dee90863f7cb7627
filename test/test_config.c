/* Configuration sanity: the settings the library was built with are in
 * range and, when a config header is given, it was really included. */
#include "dht.h"
#include "dhmath/dh_common.h"

static void settings_in_range(void)
{
    DHT_TRUE(DH_MAX_JOINTS >= 1 && DH_MAX_JOINTS <= 32);
    DHT_TRUE(DH_QPOS_FRAC >= 8 && DH_QPOS_FRAC <= 24);
    DHT_EQ_INT(DH_QPOS_ONE, (int32_t)1 << DH_QPOS_FRAC);
    DHT_EQ_INT(DH_Q30_ONE, 0x40000000);
    DHT_EQ_INT(DH_Q16_ONE, 0x10000);
}

static void config_header_honoured(void)
{
#ifdef DH_CONFIG_HEADER
    /* dh_config.h includes the header; the test header defines this */
    DHT_EQ_INT(DH_TEST_CONFIG_HEADER_SEEN, 1);
#else
    DHT_TRUE(1); /* no config header in this build: nothing to prove */
#endif
}

static const dht_case cases[] = {
    DHT_CASE(settings_in_range),
    DHT_CASE(config_header_honoured),
};
DHT_MAIN(cases)
