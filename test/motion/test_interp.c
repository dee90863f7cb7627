/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_interp.c - slerp, pose interpolation and the angle between two
 * frames (motion.h) against double-precision references computed here:
 * the quaternion path a (a* b)^s from its axis and angle with libm, the
 * rotation matrix of a quaternion from the textbook formula.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "dht.h"
#include "dhmath/motion.h"

#define PI_D 3.14159265358979323846

/* Bounds of the contracts. Angle: atan2(2 sin t, 2 cos t) from dot
 * products of three terms (each within 3 ulp of 1, 1.8e-7): 2 sin t within
 * 6e-7, 2 cos t within 1.2e-6 (nine terms), so t within 1e-6 rad = 6e-5
 * deg; the reference is the exact rotation before its entries were
 * rounded, which adds 2^-25 per entry. */
#define SLERP_TOL 1e-6   /* slerp components */
#define ROT_TOL 2e-6     /* rotation entries of an interpolated pose */
#define ANGLE_TOL 1e-4   /* degrees */

typedef struct { double w, x, y, z; } dq;

static void dq_norm(dq *q)
{
    double n = sqrt(q->w * q->w + q->x * q->x + q->y * q->y + q->z * q->z);
    q->w /= n; q->x /= n; q->y /= n; q->z /= n;
}

static void dq_mul(const dq *a, const dq *b, dq *o)
{
    dq r;
    r.w = a->w * b->w - a->x * b->x - a->y * b->y - a->z * b->z;
    r.x = a->w * b->x + a->x * b->w + a->y * b->z - a->z * b->y;
    r.y = a->w * b->y - a->x * b->z + a->y * b->w + a->z * b->x;
    r.z = a->w * b->z + a->x * b->y - a->y * b->x + a->z * b->w;
    *o = r;
}

/* a uniformly distributed unit quaternion from three uniform numbers
 * (the subgroup algorithm: two independent planar angles, weights sqrt u
 * and sqrt (1 - u)) */
static void dq_rand(dq *q)
{
    double u = dht_rand_uniform(0.0, 1.0), a = dht_rand_uniform(0.0, 2.0 * PI_D), b = dht_rand_uniform(0.0, 2.0 * PI_D);
    q->w = sqrt(1.0 - u) * sin(a);
    q->x = sqrt(1.0 - u) * cos(a);
    q->y = sqrt(u) * sin(b);
    q->z = sqrt(u) * cos(b);
}

/* b = a rotated further by deg about a random axis */
static void dq_near(const dq *a, double deg, dq *b)
{
    dq r;
    double h = deg * PI_D / 360.0, n;
    do {
        r.x = dht_rand_uniform(-1.0, 1.0);
        r.y = dht_rand_uniform(-1.0, 1.0);
        r.z = dht_rand_uniform(-1.0, 1.0);
        n = sqrt(r.x * r.x + r.y * r.y + r.z * r.z);
    } while (n > 1.0 || n < 1e-2);
    r.w = cos(h);
    r.x *= sin(h) / n; r.y *= sin(h) / n; r.z *= sin(h) / n;
    dq_mul(a, &r, b);
}

/* exact slerp along the shorter arc of the unit quaternions a, b */
static void dq_slerp(const dq *a, const dq *b0, double s, dq *o)
{
    dq b = *b0, r, c;
    double n, h;
    if (a->w * b.w + a->x * b.x + a->y * b.y + a->z * b.z < 0.0) { b.w = -b.w; b.x = -b.x; b.y = -b.y; b.z = -b.z; }
    c.w = a->w; c.x = -a->x; c.y = -a->y; c.z = -a->z;
    dq_mul(&c, &b, &r);
    n = sqrt(r.x * r.x + r.y * r.y + r.z * r.z);
    if (n == 0.0) { *o = *a; return; }
    h = atan2(n, r.w);
    r.w = cos(s * h);
    r.x *= sin(s * h) / n; r.y *= sin(s * h) / n; r.z *= sin(s * h) / n;
    dq_mul(a, &r, o);
}

/* rotation angle between two unit quaternions, degrees */
static double dq_angle(const dq *a, const dq *b)
{
    dq c, r;
    c.w = a->w; c.x = -a->x; c.y = -a->y; c.z = -a->z;
    dq_mul(&c, b, &r);
    return 2.0 * atan2(sqrt(r.x * r.x + r.y * r.y + r.z * r.z), fabs(r.w)) * 180.0 / PI_D;
}

static double dq_diff(const dh_quat_f32 *q, const dq *r)
{
    double m = fabs(q->w - r->w), e;
    e = fabs(q->x - r->x); if (e > m) m = e;
    e = fabs(q->y - r->y); if (e > m) m = e;
    e = fabs(q->z - r->z); if (e > m) m = e;
    return m;
}

static void dq_to_f(const dq *d, dh_quat_f32 *q)
{
    q->w = (float)d->w; q->x = (float)d->x; q->y = (float)d->y; q->z = (float)d->z;
}

static void dq_from_f(const dh_quat_f32 *q, dq *d)
{
    d->w = q->w; d->x = q->x; d->y = q->y; d->z = q->z;
    dq_norm(d);
}

/* R (row r, column c) of a unit quaternion */
static double dq_R(const dq *q, int r, int c)
{
    double w = q->w, x = q->x, y = q->y, z = q->z;
    double R[3][3] = {
        { 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y) },
        { 2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x) },
        { 2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y) },
    };
    return R[r][c];
}

/* a rigid float frame of the unit quaternion q (rounded entries) and a position */
static void frame_of(const dq *q, double px, double py, double pz, dh_mat4_f32 *T)
{
    int r, c;
    memset(T, 0, sizeof *T);
    for (r = 0; r < 3; r++)
        for (c = 0; c < 3; c++) DH_M4(T, r, c) = (float)dq_R(q, r, c);
    DH_M4(T, 0, 3) = (float)px;
    DH_M4(T, 1, 3) = (float)py;
    DH_M4(T, 2, 3) = (float)pz;
    DH_M4(T, 3, 3) = 1.0f;
}

/* an angle between a and b: mostly uniform, also tiny and near 180 */
static double draw_angle(int it)
{
    switch (it % 4) {
    case 0: return pow(10.0, dht_rand_uniform(-4.0, 0.0));
    case 1: return 180.0 - pow(10.0, dht_rand_uniform(-3.0, 0.0));
    default: return dht_rand_uniform(0.0, 180.0);
    }
}

static void slerp_vs_double(void)
{
    int it, n = DHT_ITER(100000);
    double worst = 0.0;
    for (it = 0; it < n; it++) {
        dq a, b, r, af, bf;
        dh_quat_f32 qa, qb, q;
        double s = (it % 7 == 0) ? 0.5 : dht_rand_uniform(0.0, 1.0), e;
        dq_rand(&a);
        dq_near(&a, draw_angle(it), &b);
        if (dht_rand_u32() & 1u) { b.w = -b.w; b.x = -b.x; b.y = -b.y; b.z = -b.z; }
        dq_to_f(&a, &qa);
        dq_to_f(&b, &qb);
        dq_from_f(&qa, &af);  /* the reference interpolates the float inputs, normalised */
        dq_from_f(&qb, &bf);
        DHT_EQ_INT(dh_slerp_f32(&qa, &qb, (float)s, &q), DH_OK);
        dq_slerp(&af, &bf, (float)s, &r);
        e = dq_diff(&q, &r);
        if (e > worst) worst = e;
        DHT_TRUE_MSG(e <= SLERP_TOL, "slerp off by %g at s=%g (angle %g deg)", e, s, dq_angle(&af, &bf));
    }
    dht_printf("slerp: worst component error %.3g\n", worst);
}

static void slerp_ends_and_uniform_speed(void)
{
    int it, n = DHT_ITER(20000);
    for (it = 0; it < n; it++) {
        dq a, b, af, bf, qd;
        dh_quat_f32 qa, qb, na, nb, q;
        double ang, s = dht_rand_uniform(0.0, 1.0);
        dq_rand(&a);
        dq_near(&a, draw_angle(it), &b);
        dq_to_f(&a, &qa);
        dq_to_f(&b, &qb);
        DHT_EQ_INT(dh_quat_normalize_f32(&qa, &na), DH_OK);
        DHT_EQ_INT(dh_quat_normalize_f32(&qb, &nb), DH_OK);
        if (na.w * nb.w + na.x * nb.x + na.y * nb.y + na.z * nb.z < 0.0f) {
            nb.w = -nb.w; nb.x = -nb.x; nb.y = -nb.y; nb.z = -nb.z;
        }
        DHT_EQ_INT(dh_slerp_f32(&qa, &qb, 0.0f, &q), DH_OK);
        DHT_TRUE(memcmp(&q, &na, sizeof q) == 0);
        DHT_EQ_INT(dh_slerp_f32(&qa, &qb, 1.0f, &q), DH_OK);
        DHT_TRUE(memcmp(&q, &nb, sizeof q) == 0);
        /* the angle from a is s times the whole (uniform angular speed) */
        dq_from_f(&qa, &af);
        dq_from_f(&qb, &bf);
        ang = dq_angle(&af, &bf);
        DHT_EQ_INT(dh_slerp_f32(&qa, &qb, (float)s, &q), DH_OK);
        dq_from_f(&q, &qd);
        DHT_NEAR(dq_angle(&af, &qd), (float)s * ang, ANGLE_TOL);
        DHT_NEAR(dq_angle(&qd, &bf), (1.0 - (float)s) * ang, ANGLE_TOL);
        /* aliasing: out == a, out == b */
        {
            dh_quat_f32 o = qa, p;
            DHT_EQ_INT(dh_slerp_f32(&qa, &qb, (float)s, &p), DH_OK);
            DHT_EQ_INT(dh_slerp_f32(&o, &qb, (float)s, &o), DH_OK);
            DHT_TRUE(memcmp(&o, &p, sizeof o) == 0);
            o = qb;
            DHT_EQ_INT(dh_slerp_f32(&qa, &o, (float)s, &o), DH_OK);
            DHT_TRUE(memcmp(&o, &p, sizeof o) == 0);
        }
    }
}

/* at exactly 180 degrees (a . b == 0) the path runs to b as given; just
 * short of it, to the nearer of +-b */
static void slerp_at_180(void)
{
    const dh_quat_f32 a = { 1.0f, 0.0f, 0.0f, 0.0f }, b = { 0.0f, 0.0f, 0.0f, 1.0f };
    const dh_quat_f32 mb = { 0.0f, 0.0f, 0.0f, -1.0f }, c = { -1e-3f, 0.0f, 0.0f, 1.0f };
    const float h = 0.70710678118654752f;
    dh_quat_f32 q;
    DHT_EQ_INT(dh_slerp_f32(&a, &b, 0.5f, &q), DH_OK);
    DHT_NEAR(q.w, h, 1e-7);
    DHT_NEAR(q.z, h, 1e-7);
    DHT_TRUE(q.x == 0.0f && q.y == 0.0f);
    DHT_EQ_INT(dh_slerp_f32(&a, &mb, 0.5f, &q), DH_OK);
    DHT_NEAR(q.w, h, 1e-7);
    DHT_NEAR(q.z, -h, 1e-7);
    DHT_EQ_INT(dh_slerp_f32(&a, &mb, 1.0f, &q), DH_OK);
    DHT_TRUE(q.w == 0.0f && q.z == -1.0f);
    /* a . c < 0: toward -c, the shorter arc (angle 179.885 deg, w = -1e-3) */
    DHT_EQ_INT(dh_slerp_f32(&a, &c, 0.5f, &q), DH_OK);
    DHT_TRUE(q.z < 0.0f);
    DHT_NEAR(q.w, cos(0.5 * acos(1e-3 / sqrt(1.0 + 1e-6))), 1e-6);
}

static void pose_interp_vs_double(void)
{
    int it, n = DHT_ITER(50000), r, c;
    double worst = 0.0;
    for (it = 0; it < n; it++) {
        dq a, b, qr;
        dh_mat4_f32 A, B, T, X;
        double s = dht_rand_uniform(0.0, 1.0), pa[3], pb[3], sf, L = pow(10.0, dht_rand_uniform(-3.0, 3.0));
        dq_rand(&a);
        dq_near(&a, draw_angle(it), &b);
        for (r = 0; r < 3; r++) {
            pa[r] = dht_rand_uniform(-L, L);
            pb[r] = dht_rand_uniform(-L, L);
        }
        frame_of(&a, pa[0], pa[1], pa[2], &A);
        frame_of(&b, pb[0], pb[1], pb[2], &B);
        sf = (float)s;
        DHT_EQ_INT(dh_pose_interp_f32(&A, &B, (float)s, &T), DH_OK);
        /* the reference interpolates the exact rotations that were rounded
         * into A and B: entries within the rounding (2^-25 each) of them */
        dq_slerp(&a, &b, sf, &qr);
        for (r = 0; r < 3; r++) {
            double pr = (float)pa[r] + sf * ((double)(float)pb[r] - (float)pa[r]);
            for (c = 0; c < 3; c++) {
                double e = fabs(DH_M4(&T, r, c) - dq_R(&qr, r, c));
                if (e > worst) worst = e;
                DHT_TRUE_MSG(e <= ROT_TOL, "entry (%d,%d) off by %g at s=%g", r, c, e, s);
            }
            /* a difference, a product and a sum in float: 2 ulp of the largest magnitude */
            DHT_NEAR(DH_M4(&T, r, 3), pr, 2.0 * FLT_EPSILON * L);
            DHT_TRUE(DH_M4(&T, 3, r) == 0.0f);
        }
        DHT_TRUE(DH_M4(&T, 3, 3) == 1.0f);
        /* exact ends, aliasing */
        DHT_EQ_INT(dh_pose_interp_f32(&A, &B, 0.0f, &X), DH_OK);
        DHT_TRUE(memcmp(&X, &A, sizeof X) == 0);
        DHT_EQ_INT(dh_pose_interp_f32(&A, &B, 1.0f, &X), DH_OK);
        DHT_TRUE(memcmp(&X, &B, sizeof X) == 0);
        X = A;
        DHT_EQ_INT(dh_pose_interp_f32(&X, &B, (float)s, &X), DH_OK);
        DHT_TRUE(memcmp(&X, &T, sizeof X) == 0);
        X = B;
        DHT_EQ_INT(dh_pose_interp_f32(&A, &X, (float)s, &X), DH_OK);
        DHT_TRUE(memcmp(&X, &T, sizeof X) == 0);
    }
    dht_printf("pose interpolation: worst rotation entry error %.3g\n", worst);
}

static void pose_angle_vs_double(void)
{
    int it, n = DHT_ITER(100000);
    double worst = 0.0;
    for (it = 0; it < n; it++) {
        dq a, b;
        dh_mat4_f32 A, B;
        float deg, back;
        double ref, e;
        dq_rand(&a);
        dq_near(&a, draw_angle(it), &b);
        frame_of(&a, 1.0, 2.0, 3.0, &A);
        frame_of(&b, -1.0, 0.0, 5.0, &B);
        DHT_EQ_INT(dh_pose_angle_f32(&A, &B, &deg), DH_OK);
        DHT_EQ_INT(dh_pose_angle_f32(&B, &A, &back), DH_OK);
        ref = dq_angle(&a, &b);
        e = fabs(deg - ref);
        if (e > worst) worst = e;
        DHT_TRUE_MSG(e <= ANGLE_TOL, "angle %.9g vs %.9g", (double)deg, ref);
        DHT_NEAR(back, ref, ANGLE_TOL);
        DHT_TRUE(deg >= 0.0f && deg <= 180.0f);
    }
    dht_printf("angle: worst error %.3g deg\n", worst);
}

static const dht_case cases[] = {
    DHT_CASE(slerp_vs_double),
    DHT_CASE(slerp_ends_and_uniform_speed),
    DHT_CASE(slerp_at_180),
    DHT_CASE(pose_interp_vs_double),
    DHT_CASE(pose_angle_vs_double),
};
DHT_MAIN(cases)
