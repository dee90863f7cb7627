/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_itrig_q.c - inverse trigonometry in fixed point: atan2 of two int32
 * and asin/acos of Q2.30, results in Q16.16 degrees (contracts in
 * include/dhmath/trig.h). Integer only: no float, no libm, no division.
 * The atan2 takes 32-bit products of 16-bit pieces only (the same bits on
 * every core, no 64-bit multiply call on the Cortex-M0); asin / acos add
 * one 32x32->64 square and a 64-bit integer square root.
 *
 * Method (table-seeded reciprocal, then a table of Taylor cubics of atan):
 *  1. x = max(|x|, |y|), y = min as uint32 (|INT32_MIN| = 2^31 exactly);
 *     y == x gives 45 deg exactly. Both are shifted left by the same
 *     amount until x is in [2^30, 2^31] (exact: any common scale gives
 *     the same bits); then y < x.
 *  2. Reciprocal: s = itrigq_recip_tab[(x >> 23) - 128], the constant of
 *     least relative error over its bucket, so that x s / 2^46 = 1 - E
 *     with |E| <= 0.003892 (the table's worst bucket end). e = 2^30 E is
 *     computed as 2^30 - floor(x s / 2^16) from the 16-bit halves of x
 *     (each product < 2^32): e in [2^30 E, 2^30 E + 1). Then
 *     1 / (1 - E) = 1 + E + E^2 + E^3 + E^4 / (1 - E); f = e + e^2 + e^3
 *     in Q30 (e^2 from (e >> 7)^2 >> 16: < 2 units; e^3: < 1.02 units)
 *     misses it by < 1 + 2 + 1.02 + E^4 2^30 (0.25) < 4.3 units of 2^-30.
 *  3. Ratio: y / x = (y s / 2^46) / (1 - E). r0 = floor(y s / 2^16) as in
 *     2 (< 1 unit short of rho = 2^30 y s / 2^46 < 1.004 2^30), then
 *     r = r0 + r0 f / 2^30 floored, up to 1.02 below (itrigq_mulf):
 *     |r - 2^30 y / x| < 1.004 + 1.02 + 1.004 x 4.3 < 6.4 units of 2^-30,
 *     i.e. (atan' <= 1) an angle error < 6.4 x 2^-30 rad = 3.4e-7 deg =
 *     0.023 LSB of Q16.16.
 *  4. atan(r) at the nearest r_k = k / 64 (k = 0..64, the rounding of r):
 *     h = r - r_k in [-2^-7, 2^-7], delta = 2^7 h exactly in Q23, and
 *     atan(r) = a_k + b_k delta + c_k delta^2 + d_k delta^3 (Taylor,
 *     coefficients in units of 2^-25 deg, itrigq_atan_tab). Remainder:
 *     the 4th derivative of atan is at most 3! in magnitude, so it is
 *     < h^4 / 4 <= 2^-30 rad = 0.0035 LSB. Table roundings: 0.5 unit
 *     each, c stored halved (1.0): 2.5 units of 2^-25 deg. Horner in 32
 *     bits with delta' = (delta >> 8) / 2^15 (within 2^-15 below delta):
 *     p = c + d delta' floored (< 306 2^-15 + 1 = 1.01 units),
 *     q = b + p delta' floored (|p| <= 38414: < 1.01 + 1.18 + 1 = 3.19),
 *     then a + q delta floored, up to 1.14 below (itrigq_muld; < 3.19 +
 *     1.14 = 4.33): 6.9 units of 2^-25 deg = 0.014 LSB. Total before the
 *     final rounding: 0.023 + 0.0035 + 0.014 < 0.041 LSB. Ranges: every
 *     product above is below 2^31 in magnitude (2^32 unsigned in
 *     itrigq_mul16); the sum stays below 45.5 deg < 2^31 units of 2^-25
 *     deg.
 *  5. Rounded once to Q16.16 (0.5 LSB): total < 0.55 LSB. The octant
 *     result is clamped to [0, 45 deg]; y == 0 gives r = 0, k = 0,
 *     delta = 0 and exactly 0; the reflections in Q16.16 are exact:
 *     90 - phi for |y| > |x|, 180 - phi for x < 0, the sign of y last
 *     (atan2(-y, x) == -atan2(y, x) except at 180).
 *  Tables (const): 129 x 2 + 65 x 12 bytes, written by
 *  tools/gen_itrig_tables.py.
 * asin / acos: c = floor(sqrt(2^60 - s^2)) (s the clamped Q2.30 magnitude;
 * digit-by-digit square root, remainder < 2^32) at the scale of s, then
 * the same first-quadrant atan2: the root's error (< 1 unit at 2^30)
 * moves the angle by < 2^-30 rad = 0.004 LSB.
 */
#include "dhmath/trig.h"
#include "../internal/dh_qmath.h"

#define DH_ITRIG_Q16_45  ((uint32_t)45 << 16)
#define DH_ITRIG_Q16_90  ((uint32_t)90 << 16)
#define DH_ITRIG_Q16_180 ((uint32_t)180 << 16)
#define DH_ITRIG_Q30     0x40000000u
#define DH_ITRIG_Q30_TOL 0x40000200u   /* 1 + 2^-21 in Q2.30 */

/* one Taylor segment of atan (itrigq_atan_tab) */
typedef struct {
    uint32_t a, b;
    int16_t c2, d;
} itrigq_seg;

/* floor(u s / 2^16) = (u >> 16) s + ((u & 0xFFFF) s >> 16) exactly, for
 * u <= 2^31 and s < 2^16 (each product < 2^32) with u s / 2^16 < 2^32 */
static uint32_t itrigq_mul16(uint32_t u, uint32_t s)
{
    return (u >> 16) * s + (((u & 0xFFFFu) * s) >> 16);
}

/* floor(r f / 2^30) or up to 1.02 less, for r < 2^30.01, |f| < 2^22.01:
 * r = rh 2^15 + rl, f = fh 2^8 + fl, the term rl fl / 2^30 (< 2^-7) dropped */
static int32_t itrigq_mulf(uint32_t r, int32_t f)
{
    const int32_t rh = (int32_t)(r >> 15), rl = (int32_t)(r & 0x7FFFu);
    const int32_t fh = f >> 8, fl = (int32_t)((uint32_t)f & 0xFFu);
    const int32_t u = rh * fl + ((rl * fh) >> 7);
    return (rh * fh + (u >> 8)) >> 7;
}

/* floor(q d / 2^23) or up to 1.14 less, for 0 <= q < 2^24, |d| <= 2^23,
 * dh = d >> 8: q = qh 2^12 + ql, d = dh 2^8 + dl, q dl / 2^23 taken as
 * (q >> 8) dl / 2^15 (< 2^-7 less) */
static int32_t itrigq_muld(uint32_t q, int32_t d, int32_t dh)
{
    const int32_t qh = (int32_t)(q >> 12), ql = (int32_t)(q & 0xFFFu);
    const int32_t v = ql * dh + (int32_t)(q >> 8) * (int32_t)((uint32_t)d & 0xFFu);
    return (qh * dh + (v >> 12)) >> 3;
}

/* atan2(ay, ax) in Q16.16 degrees, [0, 90 deg], for magnitudes not both 0 */
static DH_NOINLINE uint32_t itrigq_atan2_u(uint32_t ay, uint32_t ax)
{
    /* round(2^23 / (j + 128.5)), j = 0..127; 2^15 at j = 128 (x = 2^31) */
    static const uint16_t itrigq_recip_tab[129] = {
        65281u, 64777u, 64281u, 63792u, 63310u, 62836u, 62369u, 61909u, 61455u, 61008u,
        60568u, 60133u, 59705u, 59283u, 58867u, 58457u, 58053u, 57654u, 57260u, 56872u,
        56489u, 56111u, 55738u, 55370u, 55007u, 54649u, 54295u, 53946u, 53601u, 53261u,
        52925u, 52593u, 52265u, 51942u, 51622u, 51306u, 50995u, 50686u, 50382u, 50081u,
        49784u, 49490u, 49200u, 48913u, 48630u, 48349u, 48072u, 47798u, 47528u, 47260u,
        46995u, 46733u, 46474u, 46218u, 45965u, 45714u, 45467u, 45222u, 44979u, 44739u,
        44502u, 44267u, 44035u, 43805u, 43577u, 43352u, 43129u, 42908u, 42690u, 42474u,
        42260u, 42048u, 41838u, 41631u, 41425u, 41222u, 41020u, 40820u, 40623u, 40427u,
        40233u, 40041u, 39851u, 39662u, 39476u, 39291u, 39108u, 38926u, 38746u, 38568u,
        38392u, 38217u, 38044u, 37872u, 37702u, 37533u, 37366u, 37200u, 37036u, 36873u,
        36712u, 36552u, 36393u, 36236u, 36080u, 35926u, 35772u, 35620u, 35470u, 35320u,
        35172u, 35026u, 34880u, 34735u, 34592u, 34450u, 34309u, 34169u, 34031u, 33893u,
        33757u, 33622u, 33487u, 33354u, 33222u, 33091u, 32961u, 32832u, 32768u,
    };
    /* Taylor coefficients of atan at r_k = k/64 in units of 2^-25 deg for
     * the variable delta = (r - r_k) 2^7 in [-1, 1]: a = atan(r_k),
     * b = 2^-7 / (1 + r_k^2), c2 = -2^-14 r_k / (1 + r_k^2)^2 / 2 (half
     * of the coefficient c), d = 2^-21 (3 r_k^2 - 1) / (3 (1 + r_k^2)^3);
     * radians times 180/pi, each rounded to nearest. */
    static const itrigq_seg itrigq_atan_tab[65] = {
        { 0u, 15019745u, 0, -306 }, { 30037045u, 15016079u, -916, -305 },
        { 60059434u, 15005091u, -1830, -304 }, { 90052551u, 14986815u, -2738, -302 },
        { 120001869u, 14961302u, -3638, -298 }, { 149892985u, 14928628u, -4528, -295 },
        { 179711667u, 14888885u, -5405, -290 }, { 209443891u, 14842189u, -6266, -284 },
        { 239075877u, 14788672u, -7110, -278 }, { 268594130u, 14728483u, -7934, -271 },
        { 297985474u, 14661791u, -8736, -263 }, { 327237080u, 14588778u, -9514, -255 },
        { 356336501u, 14509640u, -10266, -246 }, { 385271698u, 14424590u, -10992, -237 },
        { 414031065u, 14333848u, -11689, -227 }, { 442603450u, 14237647u, -12356, -217 },
        { 470978177u, 14136230u, -12993, -207 }, { 499145060u, 14029846u, -13598, -196 },
        { 527094420u, 13918750u, -14171, -185 }, { 554817093u, 13803203u, -14711, -174 },
        { 582304440u, 13683469u, -15217, -163 }, { 609548353u, 13559814u, -15691, -152 },
        { 636541259u, 13432505u, -16131, -141 }, { 663276117u, 13301811u, -16537, -130 },
        { 689746422u, 13167995u, -16911, -119 }, { 715946194u, 13031323u, -17252, -108 },
        { 741869981u, 12892053u, -17560, -98 }, { 767512843u, 12750440u, -17837, -87 },
        { 792870348u, 12606737u, -18083, -77 }, { 817938559u, 12461186u, -18299, -67 },
        { 842714019u, 12314026u, -18486, -57 }, { 867193745u, 12165488u, -18644, -48 },
        { 891375203u, 12015796u, -18775, -39 }, { 915256302u, 11865164u, -18879, -30 },
        { 938835371u, 11713799u, -18958, -22 }, { 962111144u, 11561901u, -19013, -14 },
        { 985082745u, 11409658u, -19044, -7 }, { 1007749666u, 11257251u, -19054, 0 },
        { 1030111753u, 11104851u, -19043, 7 }, { 1052169184u, 10952621u, -19012, 14 },
        { 1073922454u, 10800715u, -18962, 20 }, { 1095372358u, 10649277u, -18895, 25 },
        { 1116519966u, 10498443u, -18811, 30 }, { 1137366616u, 10348339u, -18712, 35 },
        { 1157913888u, 10199084u, -18599, 40 }, { 1178163592u, 10050788u, -18473, 44 },
        { 1198117749u, 9903554u, -18334, 48 }, { 1217778576u, 9757474u, -18184, 52 },
        { 1237148473u, 9612637u, -18024, 55 }, { 1256230004u, 9469120u, -17854, 58 },
        { 1275025884u, 9326997u, -17675, 61 }, { 1293538966u, 9186333u, -17489, 63 },
        { 1311772230u, 9047187u, -17296, 65 }, { 1329728764u, 8909613u, -17097, 67 },
        { 1347411759u, 8773656u, -16892, 69 }, { 1364824494u, 8639359u, -16682, 71 },
        { 1381970325u, 8506758u, -16468, 72 }, { 1398852678u, 8375885u, -16250, 73 },
        { 1415475035u, 8246766u, -16029, 74 }, { 1431840927u, 8119424u, -15806, 75 },
        { 1447953927u, 7993877u, -15581, 75 }, { 1463817640u, 7870139u, -15354, 76 },
        { 1479435696u, 7748221u, -15126, 76 }, { 1494811742u, 7628131u, -14897, 76 },
        { 1509949440u, 7509872u, -14668, 76 },
    };
    const itrigq_seg *g;
    uint32_t w = 0u, x = ax, y = ay, s, r, k, t;
    int32_t e, e2, f, d, dh, p, q, a;

    if (ay > ax) {
        w = 1u;
        x = ay;
        y = ax;
    }
    if (y == x) return DH_ITRIG_Q16_45;      /* w = 0 */

    /* 1. normalise: x in [2^30, 2^31] */
    if (x < 0x00008000u) { x <<= 16; y <<= 16; }
    if (x < 0x00800000u) { x <<= 8; y <<= 8; }
    if (x < 0x08000000u) { x <<= 4; y <<= 4; }
    if (x < 0x20000000u) { x <<= 2; y <<= 2; }
    if (x < 0x40000000u) { x <<= 1; y <<= 1; }

    /* 2. reciprocal: s / 2^15 = (1 - e) 2^31 / x, |e| < 2^-8; then
     *    1 / (1 - e) = 1 + f, f = e + e^2 + e^3 (e, f in Q30) */
    s = itrigq_recip_tab[(x >> 23) - 128u];
    e = (int32_t)(DH_ITRIG_Q30 - itrigq_mul16(x, s));
    e2 = (int32_t)((uint32_t)((e >> 7) * (e >> 7)) >> 16);
    f = e + e2 + ((e2 * (e >> 8)) >> 22);

    /* 3. ratio r = y / x in Q30: y s / 2^16 times (1 + f) */
    r = itrigq_mul16(y, s);
    r += (uint32_t)itrigq_mulf(r, f);

    /* 4. atan(r) = a + delta (b + delta (c + delta d)), delta = (r - k/64)
     *    2^7 in Q23 (d), in units of 2^-25 deg */
    k = (r + 0x00800000u) >> 24;
    d = (int32_t)(r - (k << 24));
    dh = d >> 8;
    g = &itrigq_atan_tab[k];
    p = 2 * (int32_t)g->c2 + (((int32_t)g->d * dh) >> 15);
    q = (int32_t)g->b + ((p * dh) >> 15);
    a = (int32_t)g->a + itrigq_muld((uint32_t)q, d, dh);

    /* 5. round to Q16.16 (2^9 units), clamp to the octant */
    if (a < 0) a = 0;
    t = ((uint32_t)a + 256u) >> 9;
    if (t > DH_ITRIG_Q16_45) t = DH_ITRIG_Q16_45;
    return w ? DH_ITRIG_Q16_90 - t : t;
}

/* Q16.16 magnitude <= 180 deg -> int32 with the sign neg */
static int32_t itrigq_signed(uint32_t t, uint32_t neg)
{
    return neg ? -(int32_t)t : (int32_t)t;
}

dh_status dh_atan2_q(int32_t y, int32_t x, dh_q16 *deg_q16)
{
    uint32_t ax, ay, t;

    DH_ASSERT(deg_q16 != NULL);
    ax = dh_q_abs_u32(x);
    ay = dh_q_abs_u32(y);
    if ((ax | ay) == 0u) return DH_ERR_DOMAIN;
    t = itrigq_atan2_u(ay, ax);
    if (x < 0) t = DH_ITRIG_Q16_180 - t;
    /* y < 0 next to the negative x axis: -180 is outside (-180, 180] */
    if (y < 0 && t == DH_ITRIG_Q16_180) t--;
    *deg_q16 = itrigq_signed(t, (y < 0) ? 1u : 0u);
    return DH_OK;
}

/* floor(sqrt(2^60 - a^2)) for a <= 2^30 (dh_q_isqrt62, dh_qmath.h) */
static uint32_t itrigq_cofactor(uint32_t a)
{
    return dh_q_isqrt62(((uint64_t)1 << 60) - (uint64_t)dh_q_mul64((int32_t)a, (int32_t)a));
}

/* |v| clamped to 2^30 when within 1 + 2^-21; 1 (out of domain) otherwise */
static int itrigq_unit_q(int32_t v, uint32_t *a)
{
    uint32_t m = dh_q_abs_u32(v);
    if (m > DH_ITRIG_Q30_TOL) return 1;
    *a = (m > DH_ITRIG_Q30) ? DH_ITRIG_Q30 : m;
    return 0;
}

dh_status dh_asin_q(dh_q30 s_q30, dh_q16 *deg_q16)
{
    uint32_t a;

    DH_ASSERT(deg_q16 != NULL);
    if (itrigq_unit_q(s_q30, &a) != 0) return DH_ERR_DOMAIN;
    *deg_q16 = itrigq_signed(itrigq_atan2_u(a, itrigq_cofactor(a)), (s_q30 < 0) ? 1u : 0u);
    return DH_OK;
}

dh_status dh_acos_q(dh_q30 c_q30, dh_q16 *deg_q16)
{
    uint32_t a, t;

    DH_ASSERT(deg_q16 != NULL);
    if (itrigq_unit_q(c_q30, &a) != 0) return DH_ERR_DOMAIN;
    t = itrigq_atan2_u(itrigq_cofactor(a), a);
    if (c_q30 < 0) t = DH_ITRIG_Q16_180 - t;
    *deg_q16 = (int32_t)t;
    return DH_OK;
}
