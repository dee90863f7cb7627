/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_rot_q.c - fixed-point rotation conversions (Euler angles, quaternion,
 * angle and axis, orientation error) against independent double
 * references: elementary rotations and Rodrigues' formula in double with
 * libm, the quaternion of a known axis and angle. The limits are the float
 * path's documented bounds (include/dhmath/rot.h, kin.h) and, away
 * from the Euler poles, 2e-5 deg.
 */
#include "dht.h"
#include "support_canary.h"
#include "dhmath/rot.h"
#include "dhmath/kin.h"
#include "dhmath/frame.h"

#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846
#define D2R (PI / 180.0)
#define Q30 1073741824.0
#define Q16 65536.0

typedef double m3[3][3]; /* [row][col] */

static void m_mul(m3 out, m3 A, m3 B)
{
    m3 t;
    int r, c, k;
    for (r = 0; r < 3; r++)
        for (c = 0; c < 3; c++) {
            t[r][c] = 0;
            for (k = 0; k < 3; k++) t[r][c] += A[r][k] * B[k][c];
        }
    memcpy(out, t, sizeof t);
}

static void m_elem(m3 R, int ax, double deg)
{
    const double c = cos(deg * D2R), s = sin(deg * D2R);
    const int u = (ax + 1) % 3, w = (ax + 2) % 3;
    memset(R, 0, sizeof(m3));
    R[ax][ax] = 1;
    R[u][u] = c;
    R[w][w] = c;
    R[w][u] = s;
    R[u][w] = -s;
}

/* R of the Euler angles (deg) of sequence seq, from its name (rot.h). */
static void m_euler(m3 R, unsigned seq, const double *a)
{
    const char *nm = dh_euler_name((dh_euler_seq)seq);
    m3 E;
    int k;
    memset(R, 0, sizeof(m3));
    R[0][0] = R[1][1] = R[2][2] = 1;
    for (k = 0; k < 3; k++) {
        if (seq < 12) {
            m_elem(E, nm[k] - 'X', a[k]);
            m_mul(R, R, E);                     /* intrinsic: post-multiply */
        } else {
            m_elem(E, nm[k] - 'x', a[k]);
            m_mul(R, E, R);                     /* extrinsic: pre-multiply */
        }
    }
}

static void m_rod(m3 R, const double *k, double th)
{
    const double c = cos(th), s = sin(th), v = 1 - c;
    R[0][0] = k[0] * k[0] * v + c;        R[0][1] = k[0] * k[1] * v - k[2] * s; R[0][2] = k[0] * k[2] * v + k[1] * s;
    R[1][0] = k[1] * k[0] * v + k[2] * s; R[1][1] = k[1] * k[1] * v + c;        R[1][2] = k[1] * k[2] * v - k[0] * s;
    R[2][0] = k[2] * k[0] * v - k[1] * s; R[2][1] = k[2] * k[1] * v + k[0] * s; R[2][2] = k[2] * k[2] * v + c;
}

static void rand_axis(double *k)
{
    double n;
    do {
        k[0] = dht_rand_uniform(-1, 1);
        k[1] = dht_rand_uniform(-1, 1);
        k[2] = dht_rand_uniform(-1, 1);
        n = sqrt(k[0] * k[0] + k[1] * k[1] + k[2] * k[2]);
    } while (n < 0.1 || n > 1);
    k[0] /= n; k[1] /= n; k[2] /= n;
}

static int32_t q30(double v) { return (int32_t)floor(v * Q30 + 0.5); }

static void to_frame(m3 R, dh_frame_q *F)
{
    int r, c;
    for (r = 0; r < 3; r++)
        for (c = 0; c < 3; c++) F->r[c][r] = q30(R[r][c]);
    F->p[0] = F->p[1] = F->p[2] = 12345;
}

static double err_frame(const dh_frame_q *F, m3 R)
{
    double e = 0;
    int r, c;
    for (r = 0; r < 3; r++)
        for (c = 0; c < 3; c++) {
            double d = fabs(F->r[c][r] / Q30 - R[r][c]);
            if (d > e) e = d;
        }
    return e;
}

static double err_m(m3 A, m3 B)
{
    double e = 0;
    int r, c;
    for (r = 0; r < 3; r++)
        for (c = 0; c < 3; c++)
            if (fabs(A[r][c] - B[r][c]) > e) e = fabs(A[r][c] - B[r][c]);
    return e;
}

/* |a - b| in degrees modulo 360 */
static double ang_diff(double a, double b)
{
    double d = fmod(fabs(a - b), 360.0);
    return d > 180 ? 360 - d : d;
}

/* ---- Euler ---------------------------------------------------------------- */

static void euler_random(void)
{
    unsigned seq;
    long it, cnt = DHT_ITER(4000);
    double e_ang = 0, e_rep = 0, e_mid = 0;
    for (seq = 0; seq < DH_EULER_COUNT; seq++) {
        const int proper = (seq % 12) >= 6;
        for (it = 0; it < cnt; it++) {
            double a[3], b[3];
            m3 R, Rb;
            dh_frame_q F;
            dh_q16 o[3];
            const int near = (it % 4) == 0; /* a quarter next to a pole */
            a[0] = dht_rand_uniform(-179.99, 180);
            a[2] = dht_rand_uniform(-179.99, 180);
            if (near) {
                const double off = (it % 8 == 0) ? 0.0 : pow(10.0, dht_rand_uniform(-8, 0));
                a[1] = proper ? ((it % 3) ? off : 180 - off) : ((it % 3) ? 90 - off : -90 + off);
            } else {
                a[1] = proper ? dht_rand_uniform(1, 179) : dht_rand_uniform(-89, 89);
            }
            m_euler(R, seq, a);
            to_frame(R, &F);
            DHT_EQ_INT(dh_frame_to_euler_q(&F, (dh_euler_seq)seq, o), DH_OK);
            b[0] = o[0] / Q16; b[1] = o[1] / Q16; b[2] = o[2] / Q16;
            /* ranges */
            DHT_TRUE(b[0] > -180 && b[0] <= 180 && b[2] > -180 && b[2] <= 180);
            DHT_TRUE(proper ? (b[1] >= 0 && b[1] <= 180) : (b[1] >= -90 && b[1] <= 90));
            m_euler(Rb, seq, b);
            if (err_m(Rb, R) > e_rep) e_rep = err_m(Rb, R);
            DHT_TRUE_MSG(err_m(Rb, R) <= 6e-7, "seq %s a (%.9g %.9g %.9g) reproduces R within %.3g",
                         dh_euler_name((dh_euler_seq)seq), a[0], a[1], a[2], err_m(Rb, R));
            if (near) {
                double d = ang_diff(b[1], a[1]);
                if (d > e_mid) e_mid = d;
                DHT_TRUE_MSG(d <= 1e-5, "seq %s middle %.9g vs %.9g", dh_euler_name((dh_euler_seq)seq), b[1], a[1]);
            } else {
                int k;
                for (k = 0; k < 3; k++) {
                    double d = ang_diff(b[k], a[k]);
                    if (d > e_ang) e_ang = d;
                    DHT_TRUE_MSG(d <= 2e-5, "seq %s angle %d: %.9g vs %.9g", dh_euler_name((dh_euler_seq)seq), k,
                                 b[k], a[k]);
                }
            }
        }
    }
    dht_printf("euler: angles %.3g deg (>= 1 deg from a pole), middle near a pole %.3g deg, R reproduced %.3g\n",
               e_ang, e_mid, e_rep);
}

/* At the pole: the third angle is exactly 0 (the float path's policy). */
static void euler_pole_policy(void)
{
    unsigned seq;
    for (seq = 0; seq < DH_EULER_COUNT; seq++) {
        const int proper = (seq % 12) >= 6;
        double a[3];
        m3 R;
        dh_frame_q F;
        dh_q16 o[3];
        a[0] = 30; a[1] = proper ? 0 : 90; a[2] = 20;
        m_euler(R, seq, a);
        to_frame(R, &F);
        DHT_EQ_INT(dh_frame_to_euler_q(&F, (dh_euler_seq)seq, o), DH_OK);
        DHT_EQ_INT(o[2], 0);
        DHT_EQ_INT(o[1], proper ? 0 : 90 * 65536);
    }
}

static void euler_to_frame(void)
{
    unsigned seq;
    long it, cnt = DHT_ITER(2000);
    double e = 0;
    for (seq = 0; seq < DH_EULER_COUNT; seq++)
        for (it = 0; it < cnt; it++) {
            dh_q16 a[3];
            double ad[3];
            m3 R;
            dh_frame_q F;
            int k;
            for (k = 0; k < 3; k++) {
                a[k] = (dh_q16)(dht_rand_u32() % (720u * 65536u)) - 360 * 65536;
                ad[k] = a[k] / Q16;
            }
            DHT_EQ_INT(dh_euler_to_frame_q((dh_euler_seq)seq, a, &F), DH_OK);
            m_euler(R, seq, ad);
            if (err_frame(&F, R) > e) e = err_frame(&F, R);
            DHT_TRUE(err_frame(&F, R) <= 4.0 / Q30);
            DHT_TRUE(F.p[0] == 0 && F.p[1] == 0 && F.p[2] == 0);
        }
    dht_printf("euler_to_frame: entry error %.3g LSB\n", e * Q30);
}

/* ---- quaternion, angle and axis ------------------------------------------ */

/* a random rotation (axis k, angle th in [0, pi]) with the listed special
 * angles mixed in */
static double rand_angle(long it)
{
    switch (it % 10) {
    case 0: return 0;
    case 1: return PI;
    case 2: return PI - pow(10.0, dht_rand_uniform(-9, -1));
    case 3: return pow(10.0, dht_rand_uniform(-9, -1));
    case 4: return PI / 2;
    default: return dht_rand_uniform(0, PI);
    }
}

static void quat_axis_angle_random(void)
{
    long it, cnt = DHT_ITER(20000);
    double eq = 0, ea = 0, er = 0;
    for (it = 0; it < cnt; it++) {
        double k[3], th = rand_angle(it), qr[4], qs, kk[3];
        m3 R, Rb;
        dh_frame_q F;
        dh_quat_q q;
        dh_dir3_q ax;
        dh_q16 deg;
        int c;
        if (it % 20 == 1) { k[0] = 0; k[1] = (it % 40 == 1) ? 1 : 0; k[2] = (it % 40 == 1) ? 0 : 1; }
        else rand_axis(k);
        m_rod(R, k, th);
        to_frame(R, &F);
        /* exact quaternion, w >= 0; at pi the sign is the method's */
        qr[0] = cos(th / 2);
        for (c = 0; c < 3; c++) qr[c + 1] = sin(th / 2) * k[c];
        DHT_EQ_INT(dh_frame_to_quat_q(&F, &q), DH_OK);
        DHT_TRUE(q.w >= 0);
        qs = (q.x * qr[1] + q.y * qr[2] + q.z * qr[3] + q.w * qr[0] < 0) ? -1 : 1;
        {
            double d = fabs(q.w / Q30 - qs * qr[0]);
            d = fmax(d, fabs(q.x / Q30 - qs * qr[1]));
            d = fmax(d, fabs(q.y / Q30 - qs * qr[2]));
            d = fmax(d, fabs(q.z / Q30 - qs * qr[3]));
            if (d > eq) eq = d;
            DHT_TRUE_MSG(d <= 2e-7, "quaternion error %.3g at th %.9g", d, th);
        }
        DHT_EQ_INT(dh_frame_to_axis_angle_q(&F, &ax, &deg), DH_OK);
        DHT_TRUE(deg >= 0 && deg <= 180 * 65536);
        if (fabs(deg / Q16 - th / D2R) > ea) ea = fabs(deg / Q16 - th / D2R);
        DHT_TRUE_MSG(fabs(deg / Q16 - th / D2R) <= 2e-5, "angle %.9g vs %.9g", deg / Q16, th / D2R);
        kk[0] = ax.x / Q30; kk[1] = ax.y / Q30; kk[2] = ax.z / Q30;
        m_rod(Rb, kk, deg / Q16 * D2R);
        if (err_m(Rb, R) > er) er = err_m(Rb, R);
        DHT_TRUE_MSG(err_m(Rb, R) <= 3e-7, "axis-angle reproduces R within %.3g (th %.9g)", err_m(Rb, R), th);
        if (th == 0) {
            DHT_EQ_INT(deg, 0);
            DHT_TRUE(ax.x == 0 && ax.y == 0 && ax.z == DH_Q30_ONE);
        }
    }
    dht_printf("quaternion %.3g, axis-angle: angle %.3g deg, R reproduced %.3g\n", eq, ea, er);
}

/* 180 degrees: the component of the largest diagonal entry is positive. */
static void quat_axis_180(void)
{
    static const double ks[3][3] = { { -1, 0, 0 }, { 0, -1, 0 }, { 0.6, -0.8, 0 } };
    int i;
    for (i = 0; i < 3; i++) {
        m3 R;
        dh_frame_q F;
        dh_quat_q q;
        dh_dir3_q ax;
        dh_q16 deg;
        m_rod(R, ks[i], PI);
        to_frame(R, &F);
        DHT_EQ_INT(dh_frame_to_quat_q(&F, &q), DH_OK);
        DHT_EQ_INT(dh_frame_to_axis_angle_q(&F, &ax, &deg), DH_OK);
        DHT_EQ_INT(deg, 180 * 65536);
        if (i == 0) DHT_TRUE(q.x > 0 && ax.x > 0);
        if (i == 1) DHT_TRUE(q.y > 0 && ax.y > 0);
        if (i == 2) DHT_TRUE(q.y > 0 && q.x < 0 && ax.y > 0); /* r11 = 2 .64 - 1 > r00 */
    }
}

static void quat_to_frame(void)
{
    long it, cnt = DHT_ITER(20000);
    double e = 0;
    for (it = 0; it < cnt; it++) {
        double v[4], n, k[3], th;
        m3 R;
        dh_quat_q q;
        dh_frame_q F;
        int c, sh = (int)(dht_rand_u32() % 31u);
        for (c = 0; c < 4; c++) v[c] = dht_rand_uniform(-1, 1);
        n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + v[3] * v[3]);
        /* any scale from a few units to the int32 range */
        q.w = (int32_t)(v[0] / n * ldexp(1.0, sh));
        q.x = (int32_t)(v[1] / n * ldexp(1.0, sh));
        q.y = (int32_t)(v[2] / n * ldexp(1.0, sh));
        q.z = (int32_t)(v[3] / n * ldexp(1.0, sh));
        if (q.w == 0 && q.x == 0 && q.y == 0 && q.z == 0) q.w = 1;
        /* reference: the rotation of the integer quaternion as given */
        v[0] = q.w; v[1] = q.x; v[2] = q.y; v[3] = q.z;
        n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + v[3] * v[3]);
        th = 2 * atan2(sqrt(v[1] * v[1] + v[2] * v[2] + v[3] * v[3]), v[0]);
        {
            double vn = sqrt(v[1] * v[1] + v[2] * v[2] + v[3] * v[3]);
            if (vn == 0) { k[0] = 0; k[1] = 0; k[2] = 1; }
            else for (c = 0; c < 3; c++) k[c] = v[c + 1] / vn;
        }
        (void)n;
        m_rod(R, k, th);
        DHT_EQ_INT(dh_quat_to_frame_q(&q, &F), DH_OK);
        if (err_frame(&F, R) > e) e = err_frame(&F, R);
        DHT_TRUE_MSG(err_frame(&F, R) <= 6e-7, "quat_to_frame %.3g at scale 2^%d", err_frame(&F, R), sh);
    }
    dht_printf("quat_to_frame: entry error %.3g\n", e);
}

/* ---- orientation error ----------------------------------------------------- */

static void rot_error_random(void)
{
    long it, cnt = DHT_ITER(20000);
    double e = 0;
    for (it = 0; it < cnt; it++) {
        double k[3], kb[3], th = rand_angle(it);
        m3 R, D, Rt;
        dh_frame_q Ft, F;
        dh_dir3_q w;
        double wr[3], d;
        int c;
        rand_axis(kb);
        m_rod(R, kb, dht_rand_uniform(0, PI));
        rand_axis(k);
        m_rod(D, k, th);
        m_mul(Rt, D, R);                       /* R_target = Rot(w) R */
        to_frame(Rt, &Ft);
        to_frame(R, &F);
        DHT_EQ_INT(dh_rot_error_q(&Ft, &F, &w), DH_OK);
        for (c = 0; c < 3; c++) wr[c] = k[c] * th;
        /* at pi both signs are the same rotation */
        if (th > PI - 1e-6 && w.x * wr[0] + w.y * wr[1] + w.z * wr[2] < 0)
            for (c = 0; c < 3; c++) wr[c] = -wr[c];
        d = fabs(w.x / 536870912.0 - wr[0]);
        d = fmax(d, fabs(w.y / 536870912.0 - wr[1]));
        d = fmax(d, fabs(w.z / 536870912.0 - wr[2]));
        if (d > e) e = d;
        DHT_TRUE_MSG(d <= 6.3e-7, "rot_error %.3g rad at th %.9g", d, th);
    }
    dht_printf("rot_error: %.3g rad\n", e);
}

/* ---- bad input (docs/errors.md) ---------------------------------------------- */

static void rot_q_bad(void)
{
    dh_frame_q F, G;
    dh_quat_q q;
    dh_dir3_q ax, w;
    dh_q16 deg, ang[3];
    int c, k;
    dh_frame_identity_q(&F);
    /* sequence out of range */
    CANARY(ang);
    DHT_EQ_INT(dh_frame_to_euler_q(&F, (dh_euler_seq)24, ang), DH_ERR_ARG);
    DHT_EQ_INT(dh_frame_to_euler_q(&F, (dh_euler_seq)-1, ang), DH_ERR_ARG);
    UNTOUCHED(ang);
    CANARY(G);
    ang[0] = ang[1] = ang[2] = 0;
    DHT_EQ_INT(dh_euler_to_frame_q((dh_euler_seq)24, ang, &G), DH_ERR_ARG);
    UNTOUCHED(G);
    /* not orthonormal (scaled by 1 + 2e-4, sheared) or a reflection: NOT_RIGID */
    for (k = 0; k < 4; k++) {
        dh_frame_identity_q(&F);
        if (k == 0) for (c = 0; c < 3; c++) F.r[c][c] = q30(1.0002);
        if (k == 1) F.r[1][0] = q30(2e-4);
        if (k == 2) F.r[2][2] = -DH_Q30_ONE;
        if (k == 3) for (c = 0; c < 3; c++) F.r[c][0] = F.r[c][1] = F.r[c][2] = INT32_MIN;
        CANARY(ang); CANARY(q); CANARY(ax); CANARY(deg); CANARY(w);
        DHT_EQ_INT(dh_frame_to_euler_q(&F, DH_EULER_ZYX, ang), DH_ERR_NOT_RIGID);
        DHT_EQ_INT(dh_frame_to_quat_q(&F, &q), DH_ERR_NOT_RIGID);
        DHT_EQ_INT(dh_frame_to_axis_angle_q(&F, &ax, &deg), DH_ERR_NOT_RIGID);
        if (k != 0 && k != 1) DHT_EQ_INT(dh_rot_error_q(&F, &F, &w), DH_ERR_NOT_RIGID);
        UNTOUCHED(ang); UNTOUCHED(q); UNTOUCHED(ax); UNTOUCHED(deg); UNTOUCHED(w);
    }
    /* within the tolerance: accepted as it is (the float path's policy) */
    dh_frame_identity_q(&F);
    F.r[1][0] = q30(5e-5);
    DHT_EQ_INT(dh_frame_to_euler_q(&F, DH_EULER_ZYX, ang), DH_OK);
    /* orientation error: its own tolerance DH_ROT_ERROR_TOL_Q (1e-3) */
    F.r[1][0] = q30(5e-4);
    DHT_EQ_INT(dh_rot_error_q(&F, &F, &w), DH_OK);
    F.r[1][0] = q30(2e-3);
    CANARY(w);
    DHT_EQ_INT(dh_rot_error_q(&F, &F, &w), DH_ERR_NOT_RIGID);
    UNTOUCHED(w);
    /* zero quaternion: ZERO_AXIS, untouched */
    memset(&q, 0, sizeof q);
    CANARY(G);
    DHT_EQ_INT(dh_quat_to_frame_q(&q, &G), DH_ERR_ZERO_AXIS);
    UNTOUCHED(G);
    /* INT32_MIN components: never negated; (MIN, MIN, 0, 0) is 90 deg about x,
     * (MIN, 0, 0, 0) the identity */
    q.w = INT32_MIN; q.x = INT32_MIN; q.y = 0; q.z = 0;
    DHT_EQ_INT(dh_quat_to_frame_q(&q, &G), DH_OK);
    for (c = 0; c < 3; c++)
        for (k = 0; k < 3; k++) {
            /* Rx(90): columns (1 0 0), (0 0 1), (0 -1 0); within 4 LSB (contract: a few LSB) */
            const int32_t e = (c == 0 && k == 0) ? DH_Q30_ONE : (c == 1 && k == 2) ? DH_Q30_ONE :
                              (c == 2 && k == 1) ? -DH_Q30_ONE : 0;
            DHT_TRUE_MSG(G.r[c][k] - (int64_t)e <= 4 && (int64_t)e - G.r[c][k] <= 4, "entry %d %d: %ld", c, k,
                         (long)G.r[c][k]);
        }
    q.x = 0;
    DHT_EQ_INT(dh_quat_to_frame_q(&q, &G), DH_OK);
    for (c = 0; c < 3; c++)
        for (k = 0; k < 3; k++) DHT_EQ_INT(G.r[c][k], c == k ? DH_Q30_ONE : 0);
    /* any Q16.16 angle, INT32_MIN included */
    ang[0] = INT32_MIN; ang[1] = INT32_MAX; ang[2] = INT32_MIN;
    DHT_EQ_INT(dh_euler_to_frame_q(DH_EULER_XYZ, ang, &G), DH_OK);
    DHT_TRUE(dh_frame_ortho_error_q(&G) <= 8);
}

static const dht_case cases[] = {
    DHT_CASE(euler_random),
    DHT_CASE(euler_pole_policy),
    DHT_CASE(euler_to_frame),
    DHT_CASE(quat_axis_angle_random),
    DHT_CASE(quat_axis_180),
    DHT_CASE(quat_to_frame),
    DHT_CASE(rot_error_random),
    DHT_CASE(rot_q_bad),
};
DHT_MAIN(cases)
