/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_motion_edges_q.c - edge cases of the fixed-point profiles, paths and
 * path moves (motion.h), each against the contract's closed form in double:
 * a trapezoid whose distance is exactly vmax^2 / amax (the cruise of length
 * 0), the quintic's acceleration at its peak (|acc| <= p->a), a pure
 * rotation moved at the angular limits, rates of s beyond int32 at e = 0,
 * arcs whose circle leaves int32, and the arc of one LSB.
 */
#include <math.h>
#include <string.h>

#include "dht.h"
#include "dhmath/motion.h"

#define Q16(x) ((int32_t)((x) * 65536))
#define RAD2DEG (180.0 / 3.14159265358979323846)

/* 1 when the n bytes at p are all zero */
static int all_zero(const void *p, size_t n)
{
    const unsigned char *b = (const unsigned char *)p;
    size_t i;
    for (i = 0; i < n; i++)
        if (b[i] != 0u) return 0;
    return 1;
}

/* |d| = vmax^2 / amax: the trapezoid reaches vmax just as it must brake
 * (T = 2 vmax / amax = 2 s); rounded up to whole us within 1 us + 2^-26 T,
 * peaks within the limits, and at T/2 the position d/2 (within the
 * evaluation's 4 + 2^-27 |d| LSB) at the speed vmax (the held shape's
 * rates within 1e-8 relative, and 1 LSB of rounding). */
static void trap_q_cruise_of_zero_length(void)
{
    const int32_t v = Q16(100), a = Q16(100), d = Q16(100);
    const double T_min = 2.0e6;
    dh_profile_q p;
    int32_t pos, vel, acc;
    int sign;
    for (sign = -1; sign <= 1; sign += 2) {
        DHT_EQ_INT(dh_profile_trap_q(&p, sign * d, v, a), DH_OK);
        DHT_TRUE_MSG((double)p.T >= T_min && (double)p.T <= T_min + 1.0 + T_min / 67108864.0, "T %lu us",
                     (unsigned long)p.T);
        DHT_TRUE(p.v <= v && p.a <= a);
        DHT_EQ_INT(p.xa, 0x20000000); /* no cruise: the acceleration phase is half the move */
        DHT_EQ_INT(dh_profile_eval_q(&p, p.T / 2u, &pos, &vel, &acc), DH_OK);
        DHT_NEAR(pos, sign * d / 2, 4.0 + (double)d / 134217728.0);
        DHT_NEAR(vel, sign * (double)v, 1.0 + 1e-6 * v);
        DHT_EQ_INT(dh_profile_eval_q(&p, p.T, &pos, &vel, &acc), DH_OK);
        DHT_EQ_INT(pos, sign * d);
    }
}

/* The quintic's acceleration peaks at x = (3 - sqrt 3) / 6 with
 * 10 |d| / (sqrt 3 T^2) (T in s): around it the evaluated |acc| stays
 * within p->a (rounded up from that peak) and within 1 LSB + 1e-6 of
 * the peak. T = 2^30 us makes t the shape's Q2.30 x exactly. */
static void quintic_q_acceleration_peak(void)
{
    const uint32_t T = 1u << 30;
    const double Ts = (double)T * 1e-6, d = 1073741824.0 - 1.0;
    const double peak = 10.0 * d / (sqrt(3.0) * Ts * Ts);
    const double xs = (3.0 - sqrt(3.0)) / 6.0 * 1073741824.0;
    dh_profile_q p;
    int32_t pos, vel, acc;
    long k;
    DHT_EQ_INT(dh_profile_quintic_q(&p, (int32_t)d, T), DH_OK);
    DHT_TRUE_MSG(p.a >= peak && p.a <= peak + 1.0, "a %ld, peak %.3f", (long)p.a, peak);
    for (k = -2000; k <= 2000; k += 7) {
        const uint32_t t = (uint32_t)((long)xs + k);
        DHT_EQ_INT(dh_profile_eval_q(&p, t, &pos, &vel, &acc), DH_OK);
        DHT_TRUE_MSG(acc <= p.a && acc >= 0, "acc %ld at x %lu, peak %ld", (long)acc, (unsigned long)t, (long)p.a);
        DHT_NEAR(acc, peak, 1.0 + 1e-6 * peak);
        /* the mirror image: the same magnitude braking */
        DHT_EQ_INT(dh_profile_eval_q(&p, T - t, &pos, &vel, &acc), DH_OK);
        DHT_TRUE(-acc <= p.a);
        DHT_NEAR(-acc, peak, 1.0 + 1e-6 * peak);
    }
}

static void frame_rotz(dh_frame_q *F, int quarter, int32_t x, int32_t y)
{
    memset(F, 0, sizeof *F);
    F->r[2][2] = DH_Q30_ONE;
    if (quarter == 0) {
        F->r[0][0] = F->r[1][1] = DH_Q30_ONE;
    } else {
        F->r[0][1] = DH_Q30_ONE;  /* column 0: (0, 1, 0) */
        F->r[1][0] = -DH_Q30_ONE; /* column 1: (-1, 0, 0) */
    }
    F->p[0] = x;
    F->p[1] = y;
}

/* A pure rotation of 90 degrees (length 0): s' <= wmax / angle,
 * s'' <= wdmax / angle, so T = angle / wmax + wmax / wdmax (2.125 s for
 * 45 deg/s, 360 deg/s^2) up to the rounding of the rates down and of T
 * up; at T/2 the frame is turned by half the angle, still at the origin. */
static void path_move_q_pure_rotation(void)
{
    static const dh_cart_limits_q lim = { Q16(250), Q16(2000), Q16(45), Q16(360) };
    dh_frame_q A, B, F;
    dh_path_q p;
    dh_profile_q prof, bad;
    uint32_t e;
    double ang, T_us, turn;
    frame_rotz(&A, 0, 0, 0);
    frame_rotz(&B, 1, 0, 0);
    DHT_EQ_INT(dh_path_line_q(&p, &A, &B), DH_OK);
    DHT_EQ_INT(p.length, 0);
    ang = (double)p.angle / 65536.0;
    DHT_NEAR(ang, 90.0, 3.1e-5);
    DHT_EQ_INT(dh_path_move_q(&prof, &e, &p, &lim), DH_OK);
    DHT_EQ_INT(prof.d, (int32_t)1 << e);
    T_us = (ang / 45.0 + 45.0 / 360.0) * 1e6;
    DHT_TRUE_MSG((double)prof.T >= T_us - 1e-3 && (double)prof.T <= T_us * (1.0 + 1e-7) + 1.0,
                 "T %lu us, exact %.3f us", (unsigned long)prof.T, T_us);
    DHT_EQ_INT(dh_path_move_eval_q(&prof, e, &p, prof.T / 2u, &F), DH_OK);
    turn = atan2((double)F.r[0][1], (double)F.r[0][0]) * RAD2DEG;
    DHT_NEAR(turn, 0.5 * ang, 1e-3);
    DHT_EQ_INT(F.p[0], 0);
    DHT_EQ_INT(F.p[1], 0);
    DHT_EQ_INT(F.p[2], 0);
    DHT_EQ_INT(dh_path_move_eval_q(&prof, e, &p, prof.T, &F), DH_OK);
    DHT_TRUE(memcmp(&F, &B, sizeof F) == 0);
    /* a profile that holds none is refused, T untouched */
    bad = prof;
    bad.xa = 0;
    memset(&F, 0x5A, sizeof F);
    DHT_EQ_INT(dh_path_move_eval_q(&bad, e, &p, prof.T / 2u, &F), DH_ERR_ARG);
    DHT_EQ_INT(F.p[0], (int32_t)0x5A5A5A5A);
}

/* A line of 1 LSB at vmax = amax = INT32_MAX: s' would be 2^31 - 1 per
 * second at e = 0, not below INT32_MAX: DH_ERR_OVERFLOW, *prof all zero
 * and e = 30 (no move). One LSB more of length and it plans. */
static void path_move_q_rates_beyond_int32(void)
{
    static const dh_cart_limits_q lim = { INT32_MAX, INT32_MAX, Q16(45), Q16(360) };
    dh_frame_q A, B;
    dh_path_q p;
    dh_profile_q prof;
    uint32_t e = 7u;
    frame_rotz(&A, 0, 0, 0);
    frame_rotz(&B, 0, 1, 0);
    DHT_EQ_INT(dh_path_line_q(&p, &A, &B), DH_OK);
    DHT_EQ_INT(p.length, 1);
    memset(&prof, 0x5A, sizeof prof);
    DHT_EQ_INT(dh_path_move_q(&prof, &e, &p, &lim), DH_ERR_OVERFLOW);
    DHT_TRUE(all_zero(&prof, sizeof prof));
    DHT_EQ_INT(e, 30u);
    frame_rotz(&B, 0, 2, 0);
    DHT_EQ_INT(dh_path_line_q(&p, &A, &B), DH_OK);
    DHT_EQ_INT(dh_path_move_q(&prof, &e, &p, &lim), DH_OK);
    DHT_EQ_INT(e, 0u);
}

/* Arcs with every side below 2^30 LSB whose circle reaches beyond int32
 * (A (25000, 0), B (25000, 10000), via (32000, 8000) units: centre x
 * 27357.1, radius 5527.9, its extreme x 32885 > 32767.99), and the mirror
 * image at negative x: DH_ERR_OVERFLOW, *p all zero. The same triangle
 * moved 1000 units towards the origin fits. */
static void arc_q_circle_beyond_int32(void)
{
    /* the two mirror images: x of A and B, x of via, the shift towards 0 */
    static const int32_t ax[2] = { -Q16(25000), Q16(25000) }, vx[2] = { -Q16(32000), Q16(32000) };
    static const int32_t sh[2] = { Q16(1000), -Q16(1000) };
    dh_frame_q A, B;
    dh_qpos via[3];
    dh_path_q p;
    unsigned k;
    for (k = 0; k < 2u; k++) {
        frame_rotz(&A, 0, ax[k], 0);
        frame_rotz(&B, 0, ax[k], Q16(10000));
        via[0] = vx[k];
        via[1] = Q16(8000);
        via[2] = 0;
        memset(&p, 0x5A, sizeof p);
        DHT_EQ_INT(dh_path_arc_q(&p, &A, via, &B), DH_ERR_OVERFLOW);
        DHT_TRUE(all_zero(&p, sizeof p));
        A.p[0] += sh[k];
        B.p[0] += sh[k];
        via[0] += sh[k];
        DHT_EQ_INT(dh_path_arc_q(&p, &A, via, &B), DH_OK);
        /* the circle through (0, 0), (0, 10000), (7000, 8000) relative to
         * A: centre x cx = 33e6 / 14000, radius sqrt(cx^2 + 5000^2) =
         * 5527.759261 units = 362267230.9 LSB, within 66 LSB (1e-3) */
        DHT_TRUE_MSG(p.radius >= 362267231 - 66 && p.radius <= 362267231 + 66, "radius %ld LSB", (long)p.radius);
    }
}

/* The smallest arc: p_A (0, 0), via (1, 0), p_B (1, 1) LSB (the finest
 * scale of the planning, 2^-29 LSB): the circle's radius 0.707 LSB rounds
 * to 1, and every evaluated point lies within 4 LSB + 2^-26 R of that
 * circle (centre (0.5, 0.5)), the ends exact. */
static void arc_q_of_one_lsb(void)
{
    dh_frame_q A, B, T;
    dh_qpos via[3] = { 1, 0, 0 };
    dh_path_q p;
    int k;
    frame_rotz(&A, 0, 0, 0);
    frame_rotz(&B, 0, 1, 1);
    DHT_EQ_INT(dh_path_arc_q(&p, &A, via, &B), DH_OK);
    DHT_EQ_INT(p.radius, 1);
    for (k = 0; k <= 8; k++) {
        double dx, dy;
        DHT_EQ_INT(dh_path_eval_q(&p, (dh_q30)(k * (DH_Q30_ONE / 8)), &T), DH_OK);
        dx = (double)T.p[0] - 0.5;
        dy = (double)T.p[1] - 0.5;
        DHT_TRUE_MSG(fabs(sqrt(dx * dx + dy * dy) - sqrt(0.5)) <= 4.0, "s %d/8: (%ld, %ld)", k, (long)T.p[0], (long)T.p[1]);
        DHT_EQ_INT(T.p[2], 0);
    }
    DHT_EQ_INT(dh_path_eval_q(&p, DH_Q30_ONE, &T), DH_OK);
    DHT_TRUE(memcmp(&T, &B, sizeof T) == 0);
}

static const dht_case cases[] = {
    DHT_CASE(trap_q_cruise_of_zero_length),
    DHT_CASE(quintic_q_acceleration_peak),
    DHT_CASE(path_move_q_pure_rotation),
    DHT_CASE(path_move_q_rates_beyond_int32),
    DHT_CASE(arc_q_circle_beyond_int32),
    DHT_CASE(arc_q_of_one_lsb),
};

DHT_MAIN(cases)
