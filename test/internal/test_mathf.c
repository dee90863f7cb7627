/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_mathf.c - the library's private float helpers (src/internal/dh_mathf.h):
 * dh_atan2f_, dh_atan2f_dg_ and dh_sincosf_ against double-precision libm atan2 / sin /
 * cos evaluated on the same float inputs (converted to double exactly).
 *
 * Error measure: |f - ref| in units of the last place of the float nearest
 * ref (ulp of a float of that magnitude; 2^-149 below FLT_MIN), so
 * "<= 2 ulp" is the documented contract. The double references carry
 * ~1e-16 relative error (glibc / newlib reduce huge arguments exactly), far
 * below the float ulp.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "dht.h"
#include "../../src/internal/dh_mathf.h"

#define PI_D 3.14159265358979323846
#define ULP_TOL 2.0  /* contract of dh_mathf.h (measured maxima printed) */
#define ULP_TOL_DG 3.0 /* dh_atan2f_dg_'s */

/* ulp of a float of magnitude |v| (v the exact value, double) */
static double ulp_of(double v)
{
    int e;
    v = fabs(v);
    if (v < (double)FLT_MIN) return ldexp(1.0, -149);
    (void)frexp(v, &e);           /* v = m 2^e, m in [0.5, 1) */
    if (e > 128) e = 128;
    return ldexp(1.0, e - 24);
}

static double ulp_err(float f, double ref)
{
    return fabs((double)f - ref) / ulp_of(ref);
}

/* any finite float with a random exponent in [emin, emax] and random sign */
static float rand_float_exp(int emin, int emax)
{
    double m = dht_rand_uniform(1.0, 2.0);
    int e = emin + (int)(dht_rand_u32() % (uint32_t)(emax - emin + 1));
    float f = (float)ldexp(m, e);
    return (dht_rand_u32() & 1u) ? -f : f;
}

/* ---- atan2 ---------------------------------------------------------------- */

static double worst_atan2 = 0.0;
/* 1: the sweeps check dh_atan2f_dg_ (degrees, (-180, 180], 3 ulp, of
 * 2^-100 for results below it) */
static int atan2_deg = 0;

static void check_atan2(float y, float x)
{
    float a;
    double ref = atan2((double)y, (double)x), e;
    if (atan2_deg) {
        /* modulo 360: the float nearest a reference just above -180 may be
         * -180, which the range (-180, 180] gives as 180 */
        a = dh_atan2f_dg_(y, x);
        ref *= 180.0 / PI_D;
        DHT_TRUE_MSG(a > -180.0f && a <= 180.0f, "atan2 deg(%.9g, %.9g) = %.9g", (double)y, (double)x, (double)a);
        e = fabs(remainder((double)a - ref, 360.0)) / ulp_of(fmax(fabs(ref), 0x1p-100));
    } else {
        a = dh_atan2f_(y, x);
        e = ulp_err(a, ref);
    }
    if (e > worst_atan2) worst_atan2 = e;
    DHT_TRUE_MSG(e <= (atan2_deg ? ULP_TOL_DG : ULP_TOL), "atan2%s(%.9g, %.9g) = %.9g, ref %.17g: %.3g ulp",
                 atan2_deg ? " deg" : "", (double)y, (double)x, (double)a, ref, e);
}

static void atan2_sweep_angles(void)
{
    /* every direction, dense: angle uniform in (-pi, pi], radius 2^-60..2^60 */
    int it, n = DHT_ITER(400000);
    worst_atan2 = 0.0;
    for (it = 0; it < n; it++) {
        double t = dht_rand_uniform(-PI_D, PI_D);
        double rho = ldexp(dht_rand_uniform(1.0, 2.0), (int)(dht_rand_u32() % 121u) - 60);
        check_atan2((float)(rho * sin(t)), (float)(rho * cos(t)));
    }
    dht_printf("atan2, random directions: max %.3f ulp\n", worst_atan2);
}

static void atan2_sweep_octant_edges(void)
{
    /* ratios at and around the internal split 1/2, the diagonal, the axes
     * and tan(pi/8), in all four quadrants */
    static const double ratios[] = { 0.5, 1.0, 0.0, 0.41421356237309503 };
    int it, n = DHT_ITER(100000);
    worst_atan2 = 0.0;
    for (it = 0; it < n; it++) {
        double r0 = ratios[it % 4];
        double q = r0 + dht_rand_uniform(-1e-3, 1e-3) * ((it >> 4) % 2 ? 1.0 : 1e-4);
        float x = rand_float_exp(-20, 20);
        float y = (float)((double)x * q);
        if (it & 4) { float t = x; x = y; y = t; }
        if (it & 8) y = -y;
        check_atan2(y, x);
    }
    dht_printf("atan2, octant edges: max %.3f ulp\n", worst_atan2);
}

static void atan2_extreme_magnitudes(void)
{
    /* random bit patterns over the whole finite range (subnormal to
     * FLT_MAX, the ratio anything), and both near FLT_MAX */
    int it, n = DHT_ITER(400000);
    worst_atan2 = 0.0;
    for (it = 0; it < n; it++) {
        float x = dht_f32_from_bits(dht_rand_u32() % 0x7F800000u);
        float y = dht_f32_from_bits(dht_rand_u32() % 0x7F800000u);
        if (it & 1) x = -x;
        if (it & 2) y = -y;
        check_atan2(y, x);
        check_atan2(FLT_MAX * (float)dht_rand_uniform(0.4, 1.0), -FLT_MAX * (float)dht_rand_uniform(0.4, 1.0));
        check_atan2(dht_f32_from_bits(dht_rand_u32() % 0x00800000u), dht_f32_from_bits(dht_rand_u32() % 0x00800000u));
    }
    dht_printf("atan2, whole range incl. subnormal and near FLT_MAX: max %.3f ulp\n", worst_atan2);
}

static void atan2_special(void)
{
    const float pz = 0.0f, nz = -0.0f, inf = INFINITY;
    const float pi = (float)PI_D, pio2 = (float)(PI_D / 2), pio4 = (float)(PI_D / 4),
                tpio4 = (float)(3 * PI_D / 4);
    float nan_;
    /* signed zeros */
    DHT_EQ_F32_BITS(dh_atan2f_(pz, pz), pz);
    DHT_EQ_F32_BITS(dh_atan2f_(nz, pz), nz);
    DHT_EQ_F32_BITS(dh_atan2f_(pz, nz), pi);
    DHT_EQ_F32_BITS(dh_atan2f_(nz, nz), -pi);
    DHT_EQ_F32_BITS(dh_atan2f_(pz, 3.0f), pz);
    DHT_EQ_F32_BITS(dh_atan2f_(nz, 3.0f), nz);
    DHT_EQ_F32_BITS(dh_atan2f_(pz, -3.0f), pi);
    DHT_EQ_F32_BITS(dh_atan2f_(nz, -3.0f), -pi);
    DHT_EQ_F32_BITS(dh_atan2f_(2.0f, pz), pio2);
    DHT_EQ_F32_BITS(dh_atan2f_(2.0f, nz), pio2);
    DHT_EQ_F32_BITS(dh_atan2f_(-2.0f, pz), -pio2);
    DHT_EQ_F32_BITS(dh_atan2f_(-2.0f, nz), -pio2);
    DHT_EQ_F32_BITS(dh_atan2f_(1e-45f, pz), pio2);
    /* infinities */
    DHT_EQ_F32_BITS(dh_atan2f_(inf, inf), pio4);
    DHT_EQ_F32_BITS(dh_atan2f_(-inf, inf), -pio4);
    DHT_EQ_F32_BITS(dh_atan2f_(inf, -inf), tpio4);
    DHT_EQ_F32_BITS(dh_atan2f_(-inf, -inf), -tpio4);
    DHT_EQ_F32_BITS(dh_atan2f_(inf, 5.0f), pio2);
    DHT_EQ_F32_BITS(dh_atan2f_(-inf, -5.0f), -pio2);
    DHT_EQ_F32_BITS(dh_atan2f_(inf, pz), pio2);
    DHT_EQ_F32_BITS(dh_atan2f_(5.0f, inf), pz);
    DHT_EQ_F32_BITS(dh_atan2f_(-5.0f, inf), nz);
    DHT_EQ_F32_BITS(dh_atan2f_(5.0f, -inf), pi);
    DHT_EQ_F32_BITS(dh_atan2f_(-5.0f, -inf), -pi);
    DHT_EQ_F32_BITS(dh_atan2f_(FLT_MAX, inf), pz);
    /* equal magnitudes are exactly +-pi/4, +-3pi/4 (float nearest) */
    DHT_EQ_F32_BITS(dh_atan2f_(7.0f, 7.0f), pio4);
    DHT_EQ_F32_BITS(dh_atan2f_(-FLT_MAX, FLT_MAX), -pio4);
    DHT_EQ_F32_BITS(dh_atan2f_(1e-45f, -1e-45f), tpio4);
    /* exact results at the axes */
    DHT_EQ_F32_BITS(dh_atan2f_(0.0f, 1e-45f), pz);
    DHT_EQ_F32_BITS(dh_atan2f_(1.0f, 0.0f), pio2);
    /* NaN in either argument */
    nan_ = NAN;
    DHT_TRUE(isnan(dh_atan2f_(nan_, 1.0f)));
    DHT_TRUE(isnan(dh_atan2f_(1.0f, nan_)));
    DHT_TRUE(isnan(dh_atan2f_(nan_, inf)));
    DHT_TRUE(isnan(dh_atan2f_(pz, -nan_)));
    /* odd in y bit for bit */
    {
        int it;
        for (it = 0; it < DHT_ITER(20000); it++) {
            float x = rand_float_exp(-30, 30), y = rand_float_exp(-30, 30);
            DHT_EQ_F32_BITS(dh_atan2f_(-y, x), -dh_atan2f_(y, x));
        }
    }
}

/* ---- sin / cos ------------------------------------------------------------ */

static double worst_s, worst_c, worst_abs;

static void check_sincos(float x)
{
    float s, c;
    double rs = sin((double)x), rc = cos((double)x), es, ec;
    dh_sincosf_(x, &s, &c);
    es = ulp_err(s, rs);
    ec = ulp_err(c, rc);
    if (es > worst_s) worst_s = es;
    if (ec > worst_c) worst_c = ec;
    if (fabs((double)s - rs) > worst_abs) worst_abs = fabs((double)s - rs);
    if (fabs((double)c - rc) > worst_abs) worst_abs = fabs((double)c - rc);
    DHT_TRUE_MSG(es <= ULP_TOL && ec <= ULP_TOL, "sincos(%.9g) = %.9g %.9g, ref %.17g %.17g: %.3g / %.3g ulp",
                 (double)x, (double)s, (double)c, rs, rc, es, ec);
}

static void sincos_dense(void)
{
    /* dense in [-4 pi, 4 pi]: every float of a random 1e-3-wide window plus
     * random points, so the reduction boundaries (multiples of pi/4) are
     * crossed densely */
    int it, n = DHT_ITER(300000);
    worst_s = worst_c = worst_abs = 0.0;
    for (it = 0; it < n; it++) {
        check_sincos((float)dht_rand_uniform(-4.0 * PI_D, 4.0 * PI_D));
    }
    for (it = 0; it < DHT_ITER(16); it++) {
        /* consecutive floats around k pi/4 */
        int k = (int)(dht_rand_u32() % 33u) - 16, j;
        uint32_t b = dht_f32_bits((float)(k * PI_D / 4.0));
        for (j = -300; j <= 300; j++) {
            if (k == 0) check_sincos(dht_f32_from_bits(dht_f32_bits(1e-3f) + (uint32_t)(j + 300)));
            else check_sincos(dht_f32_from_bits(b + (uint32_t)j));
        }
    }
    dht_printf("sincos |x| <= 4 pi: max %.3f ulp (sin), %.3f ulp (cos), %.3g absolute\n",
               worst_s, worst_c, worst_abs);
}

static void sincos_whole_range(void)
{
    /* random bit patterns over every finite float: tiny, subnormal, huge
     * (exact reduction), and the floats nearest multiples of pi/2 at
     * large magnitudes */
    int it, n = DHT_ITER(300000);
    worst_s = worst_c = worst_abs = 0.0;
    for (it = 0; it < n; it++) {
        float x = dht_f32_from_bits(dht_rand_u32() % 0x7F800000u);
        check_sincos((it & 1) ? -x : x);
    }
    for (it = 0; it < DHT_ITER(20000); it++) {
        double k = floor(ldexp(dht_rand_uniform(1.0, 2.0), (int)(dht_rand_u32() % 40u)));
        check_sincos((float)(k * (PI_D / 2.0)));
    }
    check_sincos(FLT_MAX);
    check_sincos(-FLT_MAX);
    check_sincos(1e30f);
    dht_printf("sincos, whole finite range: max %.3f ulp (sin), %.3f ulp (cos), %.3g absolute\n",
               worst_s, worst_c, worst_abs);
}

static void sincos_special(void)
{
    float s, c;
    int it;
    dh_sincosf_(0.0f, &s, &c);
    DHT_EQ_F32_BITS(s, 0.0f);
    DHT_EQ_F32_BITS(c, 1.0f);
    dh_sincosf_(-0.0f, &s, &c);
    DHT_EQ_F32_BITS(s, -0.0f);
    DHT_EQ_F32_BITS(c, 1.0f);
    dh_sincosf_(1e-45f, &s, &c);
    DHT_EQ_F32_BITS(s, 1e-45f);
    DHT_EQ_F32_BITS(c, 1.0f);
    dh_sincosf_(INFINITY, &s, &c);
    DHT_TRUE(isnan(s) && isnan(c));
    dh_sincosf_(-INFINITY, &s, &c);
    DHT_TRUE(isnan(s) && isnan(c));
    dh_sincosf_(NAN, &s, &c);
    DHT_TRUE(isnan(s) && isnan(c));
    /* sin odd and cos even, bit for bit */
    for (it = 0; it < DHT_ITER(20000); it++) {
        float x = rand_float_exp(-30, 100), s2, c2;
        dh_sincosf_(x, &s, &c);
        dh_sincosf_(-x, &s2, &c2);
        DHT_EQ_F32_BITS(s2, -s);
        DHT_EQ_F32_BITS(c2, c);
        DHT_TRUE(s >= -1.0f && s <= 1.0f && c >= -1.0f && c <= 1.0f);
    }
}

/* dh_atan2f_dg_: the three sweeps in degrees (finite arguments, not both
 * zero), then its conventions */
static void atan2_deg_sweeps(void)
{
    atan2_deg = 1;
    atan2_sweep_angles();
    atan2_sweep_octant_edges();
    atan2_extreme_magnitudes();
    atan2_deg = 0;
    DHT_EQ_F32_BITS(dh_atan2f_dg_(0.0f, -1.0f), 180.0f);
    DHT_EQ_F32_BITS(dh_atan2f_dg_(-0.0f, -1.0f), 180.0f);
    DHT_EQ_F32_BITS(dh_atan2f_dg_(-1e-30f, -1.0f), 180.0f);
    DHT_EQ_F32_BITS(dh_atan2f_dg_(0.0f, 2.0f), 0.0f);
    DHT_EQ_F32_BITS(dh_atan2f_dg_(2.0f, 0.0f), 90.0f);
    DHT_EQ_F32_BITS(dh_atan2f_dg_(-2.0f, -0.0f), -90.0f);
    DHT_EQ_F32_BITS(dh_atan2f_dg_(7.0f, 7.0f), 45.0f);
    DHT_EQ_F32_BITS(dh_atan2f_dg_(-FLT_MAX, -FLT_MAX), -135.0f);
    DHT_EQ_F32_BITS(dh_atan2f_dg_(0.0f, 0.0f), 45.0f);
    DHT_TRUE(isnan(dh_atan2f_dg_(NAN, 1.0f)));
    DHT_TRUE(isnan(dh_atan2f_dg_(1.0f, NAN)));
    DHT_TRUE(isnan(dh_atan2f_dg_(NAN, NAN)));
}

static const dht_case cases[] = {
    DHT_CASE(atan2_sweep_angles),
    DHT_CASE(atan2_sweep_octant_edges),
    DHT_CASE(atan2_extreme_magnitudes),
    DHT_CASE(atan2_special),
    DHT_CASE(atan2_deg_sweeps),
    DHT_CASE(sincos_dense),
    DHT_CASE(sincos_whole_range),
    DHT_CASE(sincos_special),
};

DHT_MAIN(cases)
