/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_errors_trig.c - bad input to the lookup-table trigonometry
 * (docs/errors.md, section trig.h).
 *
 * Float: NaN (quiet, signalling, negative), +-Inf -> DH_ERR_NAN with both
 * outputs set to a quiet NaN; finite angles of any magnitude up to FLT_MAX
 * and denormals -> DH_OK and the correct value (exact reduction).
 * Fixed: every int32 is a valid angle; the extremes and random int32 across
 * the whole range give the correct value, never beyond +-1.0.
 * References are double sin/cos of the exactly reduced angle (fmod of a
 * double holding the float or the Q16.16 value exactly).
 */
#include <math.h>
#include <string.h>

#include "dht.h"
#include "dhmath/trig.h"

#define PI_D 3.14159265358979323846

/* proven bound of dh_sincos_f32 (trig.h): 6.2e-8 */
#define TRIG_F32_TOL 6.2e-8
/* bound of dh_sincos_q (trig.h): 1.05 LSB of Q2.30 */
#define TRIG_Q_TOL_LSB 1.05

static int is_quiet_nan(float f)
{
    uint32_t u = dht_f32_bits(f);
    return (u & 0x7F800000u) == 0x7F800000u && (u & 0x00400000u) != 0u;
}

/* double sin/cos of deg degrees, reduced exactly first */
static void ref_sincos(double deg, double *s, double *c)
{
    double r = fmod(deg, 360.0); /* exact */
    *s = sin(r * (PI_D / 180.0));
    *c = cos(r * (PI_D / 180.0));
}

static void check_f32_angle(float deg)
{
    float s = 5.0f, c = 5.0f;
    double rs, rc;
    DHT_EQ_INT(dh_sincos_f32(deg, &s, &c), DH_OK);
    ref_sincos((double)deg, &rs, &rc);
    DHT_NEAR(s, rs, TRIG_F32_TOL);
    DHT_NEAR(c, rc, TRIG_F32_TOL);
    DHT_TRUE(s >= -1.0f && s <= 1.0f && c >= -1.0f && c <= 1.0f);
    DHT_EQ_F32_BITS(dh_sin_f32(deg), s);
    DHT_EQ_F32_BITS(dh_cos_f32(deg), c);
}

/* NaN of every kind and +-Inf: DH_ERR_NAN, both outputs a quiet NaN */
static void trig_f32_nan_inf(void)
{
    static const uint32_t bad[] = {
        0x7FC00000u, /* quiet NaN */
        0xFFC00000u, /* negative quiet NaN */
        0x7F800001u, /* signalling NaN */
        0xFF800001u, /* negative signalling NaN */
        0x7FFFFFFFu, /* NaN, all payload bits */
        0xFFFFFFFFu,
        0x7F800000u, /* +Inf */
        0xFF800000u  /* -Inf */
    };
    unsigned i;
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        float s = 0.25f, c = 0.5f;
        const float deg = dht_f32_from_bits(bad[i]);
        DHT_EQ_INT(dh_sincos_f32(deg, &s, &c), DH_ERR_NAN);
        DHT_TRUE_MSG(is_quiet_nan(s) && is_quiet_nan(c), "input 0x%08lx: s 0x%08lx c 0x%08lx",
                     (unsigned long)bad[i], (unsigned long)dht_f32_bits(s), (unsigned long)dht_f32_bits(c));
        DHT_TRUE(is_quiet_nan(dh_sin_f32(deg)));
        DHT_TRUE(is_quiet_nan(dh_cos_f32(deg)));
    }
}

/* finite angles beyond +-1e6 degrees up to +-FLT_MAX: DH_OK, exact reduction */
static void trig_f32_huge_angles(void)
{
    static const float fixed[] = {
        1e6f, -1e6f, 1.0000001e6f, 8388607.5f, 8388608.0f, -8388608.0f, 8388609.0f,
        16777216.0f, 16777218.0f, 1e10f, -1e10f, 1e20f, 3.0e38f, -3.0e38f,
        3.4028235e38f, -3.4028235e38f, 360.0f * 8388608.0f, 90.0f * 16777216.0f
    };
    unsigned i;
    uint32_t k;
    for (i = 0; i < sizeof fixed / sizeof fixed[0]; i++) check_f32_angle(fixed[i]);
    /* random floats with exponents from 2^20 up to the largest binade */
    for (k = 0; k < DHT_ITER(200000u); k++) {
        uint32_t e = 127u + 20u + dht_rand_u32() % (254u - 147u + 1u);
        uint32_t u = (e << 23) | (dht_rand_u32() & 0x007FFFFFu) | (dht_rand_u32() & 0x80000000u);
        check_f32_angle(dht_f32_from_bits(u));
    }
    /* dense sweep between whole degrees just above 1e6 (fractions kept) */
    for (k = 0; k < DHT_ITER(100000u); k++) {
        check_f32_angle(1e6f + (float)k * 0.0625f);
    }
}

/* denormal and signed-zero angles: DH_OK; sin keeps the sign, cos == 1 */
static void trig_f32_tiny_angles(void)
{
    static const uint32_t tiny[] = { 0x00000000u, 0x80000000u, 0x00000001u, 0x80000001u,
                                     0x007FFFFFu, 0x807FFFFFu, 0x00800000u, 0x80800000u };
    unsigned i;
    for (i = 0; i < sizeof tiny / sizeof tiny[0]; i++) {
        float s = 5.0f, c = 5.0f;
        const float deg = dht_f32_from_bits(tiny[i]);
        DHT_EQ_INT(dh_sincos_f32(deg, &s, &c), DH_OK);
        DHT_EQ_F32_BITS(c, 1.0f);
        DHT_NEAR(s, (double)deg * (PI_D / 180.0), TRIG_F32_TOL);
        DHT_EQ_INT(dht_f32_bits(s) >> 31, tiny[i] >> 31); /* sin(-x) == -sin(x), also for 0 */
    }
}

static void check_q_angle(int32_t a)
{
    dh_q30 s = 12345, c = 12345;
    double rs, rc;
    dh_sincos_q(a, &s, &c);
    ref_sincos((double)a / 65536.0, &rs, &rc);
    DHT_TRUE(s >= -DH_Q30_ONE && s <= DH_Q30_ONE && c >= -DH_Q30_ONE && c <= DH_Q30_ONE);
    DHT_NEAR((double)s, rs * 1073741824.0, TRIG_Q_TOL_LSB);
    DHT_NEAR((double)c, rc * 1073741824.0, TRIG_Q_TOL_LSB);
    DHT_EQ_INT(dh_sin_q(a), s);
    DHT_EQ_INT(dh_cos_q(a), c);
}

/* the whole int32 range is valid: extremes, their neighbours, random */
static void trig_q_full_int32_range(void)
{
    static const int32_t ext[] = { INT32_MIN, INT32_MIN + 1, INT32_MIN + 2, -1, 0, 1,
                                   INT32_MAX - 1, INT32_MAX, (int32_t)(90 * 65536), -(int32_t)(90 * 65536),
                                   (int32_t)(32767 * 65536), -(int32_t)(32767 * 65536) };
    unsigned i;
    uint32_t k;
    for (i = 0; i < sizeof ext / sizeof ext[0]; i++) check_q_angle(ext[i]);
    /* INT32_MIN is -32768 degrees == -8 degrees (mod 360) */
    {
        dh_q30 s1, c1, s2, c2;
        dh_sincos_q(INT32_MIN, &s1, &c1);
        dh_sincos_q(-8 * 65536, &s2, &c2);
        DHT_EQ_INT(s1, s2);
        DHT_EQ_INT(c1, c2);
    }
    for (k = 0; k < DHT_ITER(400000u); k++) check_q_angle((int32_t)dht_rand_u32());
    /* dense: every input within 4096 LSB of both ends of the range */
    for (k = 0; k < 4096u; k++) {
        check_q_angle((int32_t)(INT32_MIN + (int32_t)k));
        check_q_angle((int32_t)(INT32_MAX - (int32_t)k));
    }
}

static const dht_case cases[] = {
    DHT_CASE(trig_f32_nan_inf),
    DHT_CASE(trig_f32_huge_angles),
    DHT_CASE(trig_f32_tiny_angles),
    DHT_CASE(trig_q_full_int32_range),
};
DHT_MAIN(cases)
