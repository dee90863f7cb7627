/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_fixed_const.c - the compile-time constant macros of frame.h
 * (DH_Q16, DH_Q30, DH_QPOS) in static const initialisers.
 *
 * Expected values: the exact binary value of each double literal times
 * 2^16 / 2^30, rounded to nearest with halves away from zero, computed
 * with exact rational arithmetic outside this code and written here as
 * integers; also checked against libm llround() of the literal times the
 * scale (an independent rounding). The edges: +-32767.99998 deg, -32768
 * deg (INT32_MIN), +-1.0 in Q2.30 (2^30 exactly), -2.0 (INT32_MIN), the
 * largest Q2.30 below 2 (INT32_MAX), and halves of an LSB (away from 0).
 * test/fixed_const_m0.cmake compiles test/fixed_const_m0.c (the same
 * macros) for Cortex-M0+ and checks with nm that no float routine is
 * referenced.
 */
#include <math.h>
#include <stdint.h>

#include "dht.h"
#include "dhmath/frame.h"

#define Q16_LIST(X) \
    X(90.5, 5931008) X(-90.5, -5931008) X(0.0, 0) X(1.0, 65536) X(-1.0, -65536) \
    X(45.0, 2949120) X(180.0, 11796480) X(-180.0, -11796480) X(359.999, 23592894) \
    X(32767.99998, 2147483647) X(-32767.99998, -2147483647) X(-32768.0, (-2147483647 - 1)) \
    X(32767.0, 2147418112) X(7.62939453125e-06, 1) X(-7.62939453125e-06, -1) \
    X(2.288818359375e-05, 2) X(0.1, 6554) X(123.456789, 8090864) X(1e-9, 0)

#define Q30_LIST(X) \
    X(0.70710678, 759250124) X(-0.70710678, -759250124) X(1.0, 1073741824) \
    X(-1.0, -1073741824) X(-2.0, (-2147483647 - 1)) X(0.5, 536870912) \
    X(1.9999999990686774, 2147483647) X(0.866025403784, 929887697) \
    X(4.656612873077393e-10, 1) X(-4.656612873077393e-10, -1) X(1e-12, 0) X(-1e-12, 0)

#define QPOS_LIST(X) X(123.25) X(-0.001) X(1000.0) X(-250.125) X(0.0) X(3.0e-6)

#define AS_Q16(lit, exp) DH_Q16(lit),
#define AS_Q30(lit, exp) DH_Q30(lit),
#define AS_QPOS(lit) DH_QPOS(lit),
#define AS_EXP(lit, exp) exp,
#define AS_LIT(lit, exp) lit,
#define AS_LIT1(lit) lit,

static const dh_q16 q16_vals[] = { Q16_LIST(AS_Q16) };
static const int32_t q16_exp[] = { Q16_LIST(AS_EXP) };
static const double q16_lit[] = { Q16_LIST(AS_LIT) };
static const dh_q30 q30_vals[] = { Q30_LIST(AS_Q30) };
static const int32_t q30_exp[] = { Q30_LIST(AS_EXP) };
static const double q30_lit[] = { Q30_LIST(AS_LIT) };
static const dh_qpos qpos_vals[] = { QPOS_LIST(AS_QPOS) };
static const double qpos_lit[] = { QPOS_LIST(AS_LIT1) };

/* a firmware-style table: a joint limit and a target written without float */
typedef struct {
    dh_q16 qmin, qmax;
    dh_q30 c45;
    dh_qpos reach;
} limits_q;
static const limits_q lim = { DH_Q16(-170.0), DH_Q16(170.25), DH_Q30(0.70710678118654752), DH_QPOS(0.5) };

#define N(a) (sizeof(a) / sizeof((a)[0]))

static void q16_values(void)
{
    unsigned i;
    for (i = 0; i < N(q16_vals); i++) {
        DHT_EQ_INT(q16_vals[i], q16_exp[i]);
        DHT_EQ_INT(q16_vals[i], llround(q16_lit[i] * 65536.0));
    }
}

static void q30_values(void)
{
    unsigned i;
    for (i = 0; i < N(q30_vals); i++) {
        DHT_EQ_INT(q30_vals[i], q30_exp[i]);
        DHT_EQ_INT(q30_vals[i], llround(q30_lit[i] * 1073741824.0));
    }
    DHT_EQ_INT(DH_Q30(1.0), DH_Q30_ONE);
    DHT_EQ_INT(DH_Q16(1.0), DH_Q16_ONE);
}

static void qpos_values(void)
{
    unsigned i;
    for (i = 0; i < N(qpos_vals); i++) {
        DHT_EQ_INT(qpos_vals[i], llround(ldexp(qpos_lit[i], DH_QPOS_FRAC)));
    }
    DHT_EQ_INT(DH_QPOS(1.0), DH_QPOS_ONE);
}

static void struct_initialiser(void)
{
    DHT_EQ_INT(lim.qmin, -170 * 65536);
    DHT_EQ_INT(lim.qmax, 170 * 65536 + 16384);
    DHT_EQ_INT(lim.c45, 759250125);   /* 2^29 sqrt(2) = 759250124.99 */
    DHT_EQ_INT(lim.reach, DH_QPOS_ONE / 2);
}

static const dht_case cases[] = {
    DHT_CASE(q16_values),
    DHT_CASE(q30_values),
    DHT_CASE(qpos_values),
    DHT_CASE(struct_initialiser),
};
DHT_MAIN(cases)
