/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_interp_q.c - the fixed-point slerp, pose interpolation and angle
 * between two frames (motion.h, "Fixed point") against double-precision
 * references computed here: the slerp from the axis and angle of a* b
 * with libm, the rotation of a quaternion from the textbook formula, the
 * interpolated position in double.
 */
#include <math.h>
#include <string.h>

#include "dht.h"
#include "dhmath/motion.h"

#define PI_D 3.14159265358979323846
#define Q30 1073741824.0

/* Bounds of the contracts (dh_slerp_q, dh_pose_interp_q, dh_pose_angle_q):
 * the half angle h from dh_atan2_q within 1 LSB of Q16.16 degrees
 * (2.7e-7 rad), s h rounded once (0.5 LSB), sin and cos within 1.05 LSB of
 * Q2.30: components within 4e-7; a rotation entry is a sum of products of
 * two components (factor up to 4 for the squares, the rounding of
 * dh_quat_to_frame_q 6e-7): 1.5e-6; the angle 1 LSB of dh_atan2_q plus
 * the rounding of the entries (1e-9): 2e-5 degrees. */
#define SLERP_TOL 4e-7
#define ROT_TOL 1.5e-6
#define ANGLE_TOL 2e-5

/* quaternions as double[4] (w, x, y, z) */
static void q4_normalise(double *q)
{
    double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    int k;
    for (k = 0; k < 4; k++) q[k] /= n;
}

/* o = a b, or a* b when conj */
static void q4_mul(const double *a, const double *b, int conj, double *o)
{
    const double g = conj ? -1.0 : 1.0, w = a[0], x = g * a[1], y = g * a[2], z = g * a[3];
    double r[4];
    r[0] = w * b[0] - x * b[1] - y * b[2] - z * b[3];
    r[1] = w * b[1] + x * b[0] + y * b[3] - z * b[2];
    r[2] = w * b[2] - x * b[3] + y * b[0] + z * b[1];
    r[3] = w * b[3] + x * b[2] - y * b[1] + z * b[0];
    memcpy(o, r, sizeof r);
}

/* uniform random unit quaternion (two planar angles, weights sqrt u, sqrt (1 - u)) */
static void q4_rand(double *q)
{
    const double u = dht_rand_uniform(0.0, 1.0);
    const double a = dht_rand_uniform(-PI_D, PI_D), b = dht_rand_uniform(-PI_D, PI_D);
    q[0] = sqrt(u) * cos(a);
    q[1] = sqrt(u) * sin(a);
    q[2] = sqrt(1.0 - u) * cos(b);
    q[3] = sqrt(1.0 - u) * sin(b);
}

/* b = a turned by deg degrees about a random axis */
static void q4_turn(const double *a, double deg, double *b)
{
    double r[4], n;
    do {
        r[1] = dht_rand_uniform(-1.0, 1.0);
        r[2] = dht_rand_uniform(-1.0, 1.0);
        r[3] = dht_rand_uniform(-1.0, 1.0);
        n = sqrt(r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
    } while (n < 0.05 || n > 1.0);
    r[0] = cos(deg * PI_D / 360.0);
    n = sin(deg * PI_D / 360.0) / n;
    r[1] *= n;
    r[2] *= n;
    r[3] *= n;
    q4_mul(a, r, 0, b);
}

/* exact slerp of unit a, b at s along the shorter arc (shorter) or toward b as given */
static void q4_slerp(const double *a, const double *b0, double s, int shorter, double *o)
{
    double b[4], r[4], n, h, f;
    int k;
    memcpy(b, b0, sizeof b);
    if (shorter && a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3] < 0.0)
        for (k = 0; k < 4; k++) b[k] = -b[k];
    q4_mul(a, b, 1, r);
    n = sqrt(r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
    if (n == 0.0) {
        memcpy(o, a, 4 * sizeof a[0]);
        return;
    }
    h = atan2(n, r[0]);
    f = sin(s * h) / n;
    r[0] = cos(s * h);
    r[1] *= f;
    r[2] *= f;
    r[3] *= f;
    q4_mul(a, r, 0, o);
}

/* rotation angle between unit a and b, degrees in [0, 180] */
static double q4_angle(const double *a, const double *b)
{
    double r[4];
    q4_mul(a, b, 1, r);
    return 360.0 / PI_D * atan2(sqrt(r[1] * r[1] + r[2] * r[2] + r[3] * r[3]), fabs(r[0]));
}

/* entry (row i, column j) of the rotation of unit q */
static double q4_R(const double *q, int i, int j)
{
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    const double R[3][3] = {
        { 1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y) },
        { 2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x) },
        { 2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y) },
    };
    return R[i][j];
}

/* the fixed quaternion of q scaled by f (|f q_k| < 2) */
static void q4_to_q(const double *q, double f, dh_quat_q *o)
{
    o->w = (dh_q30)llround(q[0] * f * Q30);
    o->x = (dh_q30)llround(q[1] * f * Q30);
    o->y = (dh_q30)llround(q[2] * f * Q30);
    o->z = (dh_q30)llround(q[3] * f * Q30);
}

static void q4_from_q(const dh_quat_q *q, double *o)
{
    o[0] = q->w;
    o[1] = q->x;
    o[2] = q->y;
    o[3] = q->z;
}

/* largest |o - r| over the components, o in Q2.30 */
static double q4_err(const dh_quat_q *o, const double *r)
{
    double d[4], m = 0.0;
    int k;
    q4_from_q(o, d);
    for (k = 0; k < 4; k++)
        if (fabs(d[k] / Q30 - r[k]) > m) m = fabs(d[k] / Q30 - r[k]);
    return m;
}

/* the fixed frame of the unit rotation q (entries rounded) at a random
 * position anywhere in the int32 range */
static void frame_of(const double *q, dh_frame_q *F)
{
    int i, j;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) F->r[j][i] = (dh_q30)llround(q4_R(q, i, j) * Q30);
        F->p[i] = (dh_qpos)dht_rand_u32();
    }
}

/* mostly uniform angles, also tiny ones and ones near 180 degrees */
static double draw_angle(int it)
{
    if (it % 4 == 0) return pow(10.0, dht_rand_uniform(-5.0, 0.0));
    if (it % 4 == 1) return 180.0 - pow(10.0, dht_rand_uniform(-4.0, 0.0));
    return dht_rand_uniform(0.0, 180.0);
}

/* s in [0, 2^30]: mostly uniform, also 1/2 and next to it */
static dh_q30 draw_s(int it)
{
    if (it % 9 == 0) return (dh_q30)(0x20000000 + (int32_t)(dht_rand_u32() % 3u) - 1);
    return (dh_q30)(dht_rand_u32() % 0x40000001u);
}

static void slerp_q_vs_double(void)
{
    int it, n = DHT_ITER(50000);
    double worst = 0.0;
    for (it = 0; it < n; it++) {
        double a[4], b[4], an[4], bn[4], r[4], e, f, d;
        dh_quat_q qa, qb, o;
        const dh_q30 s = draw_s(it);
        q4_rand(a);
        q4_turn(a, draw_angle(it), b);
        /* any scale: unit, or anywhere down to 2^-20 and up to 1.99 */
        f = (it % 3 == 0) ? 1.0 : pow(2.0, dht_rand_uniform(-20.0, 0.99));
        q4_to_q(a, f, &qa);
        f = (it % 5 == 0) ? -1.0 : pow(2.0, dht_rand_uniform(-20.0, 0.99));
        q4_to_q(b, f, &qb);
        q4_from_q(&qa, an);
        q4_from_q(&qb, bn);
        q4_normalise(an);
        q4_normalise(bn);
        DHT_EQ_INT(dh_slerp_q(&qa, &qb, s, &o), DH_OK);
        q4_slerp(an, bn, s / Q30, 1, r);
        e = q4_err(&o, r);
        /* a . b within the rounding of the normalisations (a few LSB) of
         * 0: both arcs are as short, and either is right */
        d = an[0] * bn[0] + an[1] * bn[1] + an[2] * bn[2] + an[3] * bn[3];
        if (fabs(d) < 16.0 / Q30) {
            double o2;
            int k;
            for (k = 0; k < 4; k++) bn[k] = (d < 0.0) ? bn[k] : -bn[k];   /* the other arc's end */
            q4_slerp(an, bn, s / Q30, 0, r);
            o2 = q4_err(&o, r);
            if (o2 < e) e = o2;
            dht_reach_max("slerp.near180", 1.0);
        }
        if (e > worst) worst = e;
        dht_reach_max("slerp.err", e);
        DHT_TRUE_MSG(e <= SLERP_TOL, "slerp off by %g at s=%.9g (angle %.9g deg)", e, s / Q30, q4_angle(an, bn));
    }
    dht_printf("slerp_q: worst component error %.3g\n", worst);
}

static void slerp_q_ends_alias_unit(void)
{
    int it, n = DHT_ITER(20000);
    for (it = 0; it < n; it++) {
        double a[4], b[4], an[4], bn[4], nn;
        dh_quat_q qa, qb, o, p, x;
        const dh_q30 s = draw_s(it);
        q4_rand(a);
        q4_turn(a, draw_angle(it), b);
        q4_to_q(a, pow(2.0, dht_rand_uniform(-10.0, 0.99)), &qa);
        q4_to_q(b, pow(2.0, dht_rand_uniform(-10.0, 0.99)), &qb);
        q4_from_q(&qa, an);
        q4_from_q(&qb, bn);
        q4_normalise(an);
        q4_normalise(bn);
        if (an[0] * bn[0] + an[1] * bn[1] + an[2] * bn[2] + an[3] * bn[3] < 0.0) {
            bn[0] = -bn[0]; bn[1] = -bn[1]; bn[2] = -bn[2]; bn[3] = -bn[3];
        }
        /* the ends: a / |a| and +-b / |b| as normalised (a few LSB) */
        DHT_EQ_INT(dh_slerp_q(&qa, &qb, 0, &o), DH_OK);
        DHT_TRUE(q4_err(&o, an) <= 4.0 / Q30);
        DHT_EQ_INT(dh_slerp_q(&qa, &qb, DH_Q30_ONE, &o), DH_OK);
        DHT_TRUE_MSG(q4_err(&o, bn) <= 4.0 / Q30, "end b off by %g (angle %.9g, dot %g) o %ld %ld %ld %ld", q4_err(&o, bn) * Q30, q4_angle(an, bn), an[0] * bn[0] + an[1] * bn[1] + an[2] * bn[2] + an[3] * bn[3], (long)o.w, (long)o.x, (long)o.y, (long)o.z);
        /* unit output */
        DHT_EQ_INT(dh_slerp_q(&qa, &qb, s, &p), DH_OK);
        q4_from_q(&p, a);
        nn = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2] + a[3] * a[3]) / Q30;
        DHT_NEAR(nn, 1.0, 8.0 / Q30);
        /* aliasing: out == a, out == b */
        x = qa;
        DHT_EQ_INT(dh_slerp_q(&x, &qb, s, &x), DH_OK);
        DHT_TRUE(memcmp(&x, &p, sizeof x) == 0);
        x = qb;
        DHT_EQ_INT(dh_slerp_q(&qa, &x, s, &x), DH_OK);
        DHT_TRUE(memcmp(&x, &p, sizeof x) == 0);
    }
}

static void slerp_q_special(void)
{
    const dh_quat_q a = { DH_Q30_ONE, 0, 0, 0 }, b = { 0, 0, 0, DH_Q30_ONE }, z = { 0, 0, 0, 0 };
    const dh_quat_q m = { INT32_MIN, 0, 0, 0 }, mb = { 0, INT32_MIN, 0, INT32_MIN };
    const dh_quat_q c = { -1073742, 0, 0, DH_Q30_ONE }; /* w = -1e-3: a . c < 0 */
    const double h = 0.70710678118654752 * Q30;
    dh_quat_q o, keep = { 1, 2, 3, 4 };
    /* 180 degrees: b as given, the midpoint (cos 45, 0, 0, sin 45) */
    DHT_EQ_INT(dh_slerp_q(&a, &b, 0x20000000, &o), DH_OK);
    DHT_NEAR(o.w, h, 4.0);
    DHT_NEAR(o.z, h, 4.0);
    DHT_TRUE(o.x == 0 && o.y == 0);
    /* INT32_MIN components are normalised, never negated into overflow:
     * m is -1, and -1 to mb / |mb| = (0, -1, 0, -1) / sqrt 2 is 180
     * degrees (taken as given) */
    DHT_EQ_INT(dh_slerp_q(&m, &mb, 0, &o), DH_OK);
    DHT_TRUE(o.w == -DH_Q30_ONE && o.x == 0 && o.y == 0 && o.z == 0);
    DHT_EQ_INT(dh_slerp_q(&m, &mb, 0x20000000, &o), DH_OK);
    DHT_NEAR(o.w, -h, 4.0);
    DHT_NEAR(o.x, -0.5 * Q30, 4.0);
    DHT_NEAR(o.z, -0.5 * Q30, 4.0);
    DHT_EQ_INT(dh_slerp_q(&m, &mb, DH_Q30_ONE, &o), DH_OK);
    DHT_NEAR(o.x, -h, 2.0);
    DHT_NEAR(o.z, -h, 2.0);
    /* a . c < 0: toward -c, the shorter arc */
    DHT_EQ_INT(dh_slerp_q(&a, &c, 0x20000000, &o), DH_OK);
    DHT_TRUE(o.z < 0);
    DHT_NEAR(o.w / Q30, cos(0.5 * acos(1e-3 / sqrt(1.0 + 1e-6))), SLERP_TOL);
    /* errors: out untouched */
    o = keep;
    DHT_EQ_INT(dh_slerp_q(&z, &b, 0, &o), DH_ERR_ZERO_AXIS);
    DHT_EQ_INT(dh_slerp_q(&a, &z, 0, &o), DH_ERR_ZERO_AXIS);
    DHT_EQ_INT(dh_slerp_q(&a, &b, -1, &o), DH_ERR_ARG);
    DHT_EQ_INT(dh_slerp_q(&a, &b, DH_Q30_ONE + 1, &o), DH_ERR_ARG);
    DHT_EQ_INT(dh_slerp_q(&a, &b, INT32_MIN, &o), DH_ERR_ARG);
    DHT_EQ_INT(dh_slerp_q(&a, &b, INT32_MAX, &o), DH_ERR_ARG);
    DHT_TRUE(memcmp(&o, &keep, sizeof o) == 0);
}

static void pose_interp_q_vs_double(void)
{
    int it, n = DHT_ITER(20000), i, j;
    double worst = 0.0;
    for (it = 0; it < n; it++) {
        double a[4], b[4], r[4], e, pr;
        dh_frame_q A, B, T, X;
        const dh_q30 s = draw_s(it);
        q4_rand(a);
        q4_turn(a, draw_angle(it), b);
        frame_of(a, &A);
        frame_of(b, &B);
        DHT_EQ_INT(dh_pose_interp_q(&A, &B, s, &T), DH_OK);
        /* the exact slerp of the rotations that A and B round */
        q4_slerp(a, b, s / Q30, 1, r);
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++) {
                e = fabs(T.r[j][i] / Q30 - q4_R(r, i, j));
                if (e > worst) worst = e;
                DHT_TRUE_MSG(e <= ROT_TOL, "entry (%d,%d) off by %g at s=%.9g", i, j, e, s / Q30);
            }
            pr = A.p[i] + s / Q30 * ((double)B.p[i] - A.p[i]);
            DHT_NEAR(T.p[i], pr, 0.5 + 1e-6);
            DHT_TRUE((T.p[i] >= A.p[i] && T.p[i] <= B.p[i]) || (T.p[i] <= A.p[i] && T.p[i] >= B.p[i]));
        }
        dht_reach_max("pose.err", worst);
        /* exact ends, aliasing */
        DHT_EQ_INT(dh_pose_interp_q(&A, &B, 0, &X), DH_OK);
        DHT_TRUE(memcmp(&X, &A, sizeof X) == 0);
        DHT_EQ_INT(dh_pose_interp_q(&A, &B, DH_Q30_ONE, &X), DH_OK);
        DHT_TRUE(memcmp(&X, &B, sizeof X) == 0);
        X = A;
        DHT_EQ_INT(dh_pose_interp_q(&X, &B, s, &X), DH_OK);
        DHT_TRUE(memcmp(&X, &T, sizeof X) == 0);
        X = B;
        DHT_EQ_INT(dh_pose_interp_q(&A, &X, s, &X), DH_OK);
        DHT_TRUE(memcmp(&X, &T, sizeof X) == 0);
    }
    dht_printf("pose_interp_q: worst rotation entry error %.3g\n", worst);
}

static void pose_angle_q_vs_double(void)
{
    int it, n = DHT_ITER(50000);
    double worst = 0.0;
    for (it = 0; it < n; it++) {
        double a[4], b[4], ref, e;
        dh_frame_q A, B;
        dh_q16 deg, back;
        q4_rand(a);
        q4_turn(a, draw_angle(it), b);
        frame_of(a, &A);
        frame_of(b, &B);
        DHT_EQ_INT(dh_pose_angle_q(&A, &B, &deg), DH_OK);
        DHT_EQ_INT(dh_pose_angle_q(&B, &A, &back), DH_OK);
        ref = q4_angle(a, b);
        e = fabs(deg / 65536.0 - ref);
        if (e > worst) worst = e;
        DHT_TRUE_MSG(e <= ANGLE_TOL, "angle %.9g vs %.9g", deg / 65536.0, ref);
        DHT_NEAR(back / 65536.0, ref, ANGLE_TOL);
        DHT_TRUE(deg >= 0 && deg <= 180 * 65536);
    }
    dht_printf("pose_angle_q: worst error %.3g deg\n", worst);
}

static void pose_q_errors(void)
{
    dh_frame_q A, B, bad, T, keep;
    dh_q16 deg = 7;
    double a[4];
    q4_rand(a);
    frame_of(a, &A);
    frame_of(a, &B);
    bad = A;
    bad.r[1][2] += 200000;   /* 1.9e-4 off orthonormal: beyond DH_ROT_TOL_Q */
    memset(&keep, 0x5a, sizeof keep);
    T = keep;
    DHT_EQ_INT(dh_pose_interp_q(&bad, &B, 0x10000000, &T), DH_ERR_NOT_RIGID);
    DHT_EQ_INT(dh_pose_interp_q(&A, &bad, 0x10000000, &T), DH_ERR_NOT_RIGID);
    DHT_EQ_INT(dh_pose_interp_q(&A, &B, -1, &T), DH_ERR_ARG);
    DHT_EQ_INT(dh_pose_interp_q(&A, &B, DH_Q30_ONE + 1, &T), DH_ERR_ARG);
    DHT_TRUE(memcmp(&T, &keep, sizeof T) == 0);
    DHT_EQ_INT(dh_pose_angle_q(&A, &bad, &deg), DH_ERR_NOT_RIGID);
    DHT_EQ_INT(dh_pose_angle_q(&bad, &B, &deg), DH_ERR_NOT_RIGID);
    DHT_EQ_INT(deg, 7);
    /* same rotation: angle 0 */
    DHT_EQ_INT(dh_pose_angle_q(&A, &B, &deg), DH_OK);
    DHT_TRUE(deg >= 0 && deg <= 2);
}

static const dht_case cases[] = {
    DHT_CASE(slerp_q_vs_double),
    DHT_CASE(slerp_q_ends_alias_unit),
    DHT_CASE(slerp_q_special),
    DHT_CASE(pose_interp_q_vs_double),
    DHT_CASE(pose_angle_q_vs_double),
    DHT_CASE(pose_q_errors),
};
DHT_MAIN(cases)
