/*
 * test_mat4_inv_regress.c - regression tests of dh_mat4_inv_f32 for the
 * inputs found by fuzz/fuzz_inverse.c (the same matrices are replayed from
 * fuzz/corpus/fuzz_inverse/ by tools/fuzz.sh) and for the magnitudes they
 * exposed: entries near FLT_MAX whose inverse underflows, tiny entries
 * next to huge ones, and a Gauss-Jordan elimination that overflows.
 *
 * References are computed here in double (support_ref: Gauss-Jordan with
 * partial pivoting on the float input converted exactly to double); the
 * proof checked for every DH_OK is the one the contract gives: some
 * induced norm of the right residual T X - I, evaluated in double, below
 * 1 (norms of D^-1 R D, D = diag(1,1,1,g), tried for g = 2^k and for the
 * Osborne factor sqrt(|q|_1 / |p|_1), as the library balances).
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_ref.h"
#include "dhmath/dh_mat4.h"

#define U24 5.9604644775390625e-8

/* fuzz/corpus/fuzz_inverse/proj_1e35_right_residual: columns 0, 1 and 3
 * nearly equal in rows 0-1, entries from 3.5e-43 to 1.6e35; balanced
 * condition number about 3.5e5 (limit 2^19 = 5.2e5). Rows of T. */
static const float k_proj_1e35[4][4] = {
    {-0x1.f3f2fap+116f, -0x1.f3f3f2p+116f, 0x1.f3f2p-126f, -0x1.f3f20ep+116f},
    {-0x1.f2bbf2p+116f, -0x1.f3f21ep+116f, 0x1.f2p-142f, -0x1.f3f3f2p+116f},
    {-0x1.f3f3f2p+116f, 0x1.f9p-141f, -0x1.f3p+116f, -0x1.23f3f2p-92f},
    {-0x1.f3f3f2p+116f, 0x0p+0f, -0x1.f3f3f2p+116f, 0x1.f3f3f2p-126f}};

/* fuzz/corpus/fuzz_inverse/affine_p3.6e7_residual_rejected and
 * affine_p7e8_rejected: well-conditioned R, |p| ~ 3.6e7 and ~7e8 (once
 * reported singular: the residual was dominated by the p column) */
static const float k_affine_p[2][4][4] = {
    {{0x1.0bcp-27f, 0x1.9b0004p-7f, 0x1.4b333p-3f, -0x1.b1b1b2p-3f},
     {-0x1.f1f1f2p-6f, 0x1.e02666p-8f, -0x1.f1f1f2p-6f, 0x1.9392p-10f},
     {-0x1.f1f1fep-6f, -0x1.b18518p+6f, -0x1.b1b1b2p+6f, 0x1.123cdp+25f},
     {0.0f, 0.0f, 0.0f, 1.0f}},
    {{0x1.0a6666p-9f, 0x1.0e6666p-10f, 0x1.266666p-13f, -0x1.515334p+29f},
     {0x1.0a6666p-9f, 0x1.0e6666p-10f, 0x1.266666p+0f, -0x1.515152p+29f},
     {0x1.0a6666p-9f, 0x1p-15f, 0.0f, -0x1.533bp+29f},
     {0.0f, 0.0f, 0.0f, 1.0f}}};

/* Gauss-Jordan on the scaled matrix (max 2^66.8, a column ~2^-40 of it)
 * meets a pivot whose reciprocal overflows: the Inf/NaN used to slip
 * past the condition and residual tests (a max of row sums drops a NaN)
 * and was only caught as DH_ERR_OVERFLOW; the balanced condition number is
 * above 2^100, so the answer is DH_ERR_SINGULAR. */
static const float k_gj_overflow[4][4] = {
    {-0x1.3cf696p+39f, 0x1.967d36p+63f, 0x1.0d3e98p-21f, 0x1.07d5dp-60f},
    {0x1.b95c98p+66f, 0x1.81b6bep+53f, 0x1.519734p+26f, 0x1.f34c3ep-27f},
    {0x1.2e3eep+38f, 0x1.09f082p-12f, -0x1.c3aa6p-31f, 0x1.c9d5fep-83f},
    {-0x1.79468p-3f, 0x1.630e88p+50f, 0x1.64bb5ap-67f, 0x1.a2449p-67f}};

/* entries up to 2^125, |q|_1 / |p|_1 ~ 2^-24: the inverse has subnormal
 * elements whose rounding, weighted by the balancing factor, is not
 * provably harmless to the residual, so DH_ERR_OVERFLOW (contract); the
 * same matrix scaled by 2^-40 inverts (found by extreme_magnitudes_sweep,
 * DHT_SEED=1) */
static const float k_underflow[4][4] = {
    {-0x1.d3e96ap+113f, -0x1.a5239ep+61f, 0x1.b976bep+119f, -0x1.3f70ep+37f},
    {-0x1.9817c6p+74f, -0x1.6daa5p+32f, 0x1.af5726p+115f, -0x1.d6774cp+125f},
    {0x1.288ca6p+79f, 0x1.361076p+110f, -0x1.7d90acp+91f, 0x1.fe9e6p+105f},
    {0x1.9e600ap+70f, 0x1.ef529cp+8f, 0x1.36c9aap+19f, -0x1.5e1394p+101f}};

static void from_rows(dh_mat4_f32 *T, const float A[4][4], int k)
{
    int r, c;
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++) DH_M4(T, r, c) = ldexpf(A[r][c], k);
}

/* induced norm of D^-1 R D, D = diag(1,1,1,g): 1-norm (cols) or inf (rows) */
static double bal_norm(const dhr_mat4 *R, double g, int rows)
{
    double w = 0.0;
    int a, b;
    for (a = 0; a < 4; a++) {
        double s = 0.0;
        for (b = 0; b < 4; b++) {
            const int r = rows ? a : b, c = rows ? b : a;
            double v = fabs(DHR_M4(R, r, c));
            if (r == 3 && c != 3) v /= g;
            if (c == 3 && r != 3) v *= g;
            s += v;
        }
        if (s > w) w = s;
    }
    return w;
}

static double osborne(const dhr_mat4 *T)
{
    double p = 0.0, q = 0.0;
    int i;
    for (i = 0; i < 3; i++) {
        p += fabs(DHR_M4(T, i, 3));
        q += fabs(DHR_M4(T, 3, i));
    }
    /* D^-1 T D multiplies p by g and divides q by g: g = sqrt(|q| / |p|)
     * makes both sqrt(|p| |q|) (the library's sg is 1/g, on T^T) */
    return (p > 0.0 && q > 0.0) ? sqrt(q) / sqrt(p) : 1.0;
}

/* smallest balanced norm of R over g = Osborne factor and 2^k, |k| <= 64
 * (the library clamps its factor to [2^-60, 2^60]) */
static double min_norm(const dhr_mat4 *R, double g0)
{
    double best = fmin(bal_norm(R, g0, 0), bal_norm(R, g0, 1));
    int k;
    for (k = -64; k <= 64; k++) {
        const double g = ldexp(1.0, k);
        best = fmin(best, fmin(bal_norm(R, g, 0), bal_norm(R, g, 1)));
    }
    return best;
}

typedef struct {
    double proof; /* min norm of T X - I */
    double left;  /* min norm of X T - I (informative) */
    double rel;   /* max|X - T^-1| / max|T^-1| */
    double cond;  /* smallest balanced 1-norm condition number over g */
    double cond_osb; /* the same with the Osborne factor (the contract's) */
} inv_check;

/* double reference and residuals of the float inverse X of T */
static int check_inverse(const dh_mat4_f32 *T, const dh_mat4_f32 *X, inv_check *o)
{
    dhr_mat4 D, Di, Dx, R;
    int i, j, k;
    dhr_from_f32(&D, T);
    if (!dhr_inv(&Di, &D)) return 0;
    dhr_from_f32(&Dx, X);
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            double s = (i == j) ? -1.0 : 0.0;
            for (k = 0; k < 4; k++) s += DHR_M4(&D, i, k) * DHR_M4(&Dx, k, j);
            DHR_M4(&R, i, j) = s;
        }
    o->proof = min_norm(&R, osborne(&D));
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            double s = (i == j) ? -1.0 : 0.0;
            for (k = 0; k < 4; k++) s += DHR_M4(&Dx, i, k) * DHR_M4(&D, k, j);
            DHR_M4(&R, i, j) = s;
        }
    o->left = min_norm(&R, osborne(&D));
    o->rel = dhr_max_abs_diff(X, &Di) / dhr_max_abs(&Di);
    {
        const double g0 = osborne(&D);
        double c = bal_norm(&D, g0, 0) * bal_norm(&Di, g0, 0);
        o->cond_osb = c;
        for (k = -64; k <= 64; k++) {
            const double g = ldexp(1.0, k);
            c = fmin(c, bal_norm(&D, g, 0) * bal_norm(&Di, g, 0));
        }
        o->cond = c;
    }
    return 1;
}

static void proj_1e35_inverts_at_every_scale(void)
{
    double worst_proof = 0.0, worst_rel = 0.0, max_left = 0.0;
    int k, nok = 0;
    for (k = -250; k <= 10; k++) {
        dh_mat4_f32 T, X, S;
        dhr_mat4 D, Di;
        dh_status st;
        from_rows(&T, k_proj_1e35, k);
        memset(&S, 0x5a, sizeof S);
        X = S;
        st = dh_mat4_inv_f32(&T, &X);
        dhr_from_f32(&D, &T);
        if (dhr_max_abs(&D) < (double)FLT_MIN) {
            /* zero or denormal matrix */
            DHT_EQ_INT(st, DH_ERR_SINGULAR);
            DHT_TRUE(memcmp(&X, &S, sizeof X) == 0);
            continue;
        }
        DHT_TRUE(dhr_inv(&Di, &D));
        if (dhr_max_abs(&Di) > (double)FLT_MAX) {
            /* the exact inverse does not fit a float */
            DHT_EQ_INT(st, DH_ERR_OVERFLOW);
            DHT_TRUE(memcmp(&X, &S, sizeof X) == 0);
            continue;
        }
        DHT_EQ_INT(st, DH_OK);
        {
            inv_check c;
            DHT_TRUE(check_inverse(&T, &X, &c));
            worst_proof = fmax(worst_proof, c.proof);
            worst_rel = fmax(worst_rel, c.rel / (c.cond * U24));
            max_left = fmax(max_left, c.left);
        }
        nok++;
    }
    dht_printf("proj_1e35 x 2^k: %d scales inverted; right residual <= %.3g, max|X - T^-1| / (max|T^-1| cond u) "
               "<= %.3g; left residual up to %.3g (not what the certificate bounds)\n",
               nok, worst_proof, worst_rel, max_left);
    DHT_TRUE(nok >= 240);           /* measured 240 of 261 (k = -229..10) */
    DHT_TRUE(worst_proof <= 0.011); /* measured 0.0054 */
    DHT_TRUE(worst_rel <= 0.2);     /* measured 0.0996 (contract: 3.1) */
}

static void affine_large_translation_inverts(void)
{
    int m;
    for (m = 0; m < 2; m++) {
        dh_mat4_f32 T, X;
        inv_check c;
        from_rows(&T, k_affine_p[m], 0);
        DHT_EQ_INT(dh_mat4_inv_f32(&T, &X), DH_OK);
        DHT_TRUE(check_inverse(&T, &X, &c));
        dht_printf("affine |p| %s: right residual %.3g, max|X - T^-1| / (max|T^-1| cond u) = %.3g (cond %.3g)\n",
                   m ? "7e8" : "3.6e7", c.proof, c.rel / (c.cond * U24), c.cond);
        DHT_TRUE(c.proof < 1.0);
        /* the contract's general figure, 3.1 cond u, measured 0.33 / 0.0014 */
        DHT_TRUE(c.rel <= 3.1 * c.cond * U24);
        DHT_TRUE(DH_M4(&X, 3, 0) == 0.0f && DH_M4(&X, 3, 1) == 0.0f && DH_M4(&X, 3, 2) == 0.0f &&
                 DH_M4(&X, 3, 3) == 1.0f);
    }
}

static void nonfinite_elimination_is_singular(void)
{
    dh_mat4_f32 T, X, S;
    inv_check c;
    dh_mat4_f32 I;
    from_rows(&T, k_gj_overflow, 0);
    memset(&S, 0x5a, sizeof S);
    X = S;
    DHT_EQ_INT(dh_mat4_inv_f32(&T, &X), DH_ERR_SINGULAR);
    DHT_TRUE(memcmp(&X, &S, sizeof X) == 0);
    /* the expectation, independently: condition number far above 2^19 */
    dh_mat4_identity_f32(&I);
    DHT_TRUE(check_inverse(&T, &I, &c));
    DHT_TRUE(c.cond > 1e30);
    /* in place: same status, T untouched */
    X = T;
    DHT_EQ_INT(dh_mat4_inv_f32(&X, &X), DH_ERR_SINGULAR);
    DHT_TRUE(memcmp(&X, &T, sizeof X) == 0);
}

static void underflowing_inverse_reported(void)
{
    dh_mat4_f32 T, X, S;
    inv_check c;
    from_rows(&T, k_underflow, 0);
    memset(&S, 0x5a, sizeof S);
    X = S;
    DHT_EQ_INT(dh_mat4_inv_f32(&T, &X), DH_ERR_OVERFLOW);
    DHT_TRUE(memcmp(&X, &S, sizeof X) == 0);
    /* scaled into a range where the inverse is normal: proven and accurate */
    from_rows(&T, k_underflow, -40);
    DHT_EQ_INT(dh_mat4_inv_f32(&T, &X), DH_OK);
    DHT_TRUE(check_inverse(&T, &X, &c));
    DHT_TRUE(c.proof < 1.0);
    DHT_TRUE(c.rel <= 3.1 * c.cond * U24);
}

/* random float with a mantissa in (-1, 1) and exponent e */
static float rand_at(int e) { return (float)ldexp(dht_rand_uniform(-1.0, 1.0), e); }

/*
 * Random projective matrices whose largest entries are 2^60..2^127 and the
 * others spread down over up to 200 binades (the fuzzer's extreme inputs):
 * every DH_OK carries a proof and the contract's accuracy; DH_ERR_OVERFLOW
 * only when the exact inverse does not fit, or (the underflow rule) for
 * max|T_ij| >= 2^17; DH_ERR_SINGULAR only for ill-conditioned matrices.
 */
static void extreme_magnitudes_sweep(void)
{
    double worst_proof = 0.0, worst_rel = 0.0, min_sing_cond = HUGE_VAL;
    long n_ok = 0, n_sing = 0, n_ovf = 0, n_under = 0;
    int it;
    for (it = 0; it < DHT_ITER(20000); it++) {
        dh_mat4_f32 T, X, S;
        dhr_mat4 D, Di;
        dh_status st;
        const int top = 60 + (int)(dht_rand_u32() % 68u);
        const int spread = (int)(dht_rand_u32() % 201u);
        int r, c;
        for (r = 0; r < 4; r++)
            for (c = 0; c < 4; c++) {
                const double f = dht_rand_uniform(0.0, 1.0) * dht_rand_uniform(0.0, 1.0);
                DH_M4(&T, r, c) = rand_at(top - (int)(f * spread));
            }
        memset(&S, 0x5a, sizeof S);
        X = S;
        st = dh_mat4_inv_f32(&T, &X);
        dhr_from_f32(&D, &T);
        if (!dhr_inv(&Di, &D)) {
            DHT_EQ_INT(st, DH_ERR_SINGULAR);
            n_sing++;
            continue;
        }
        if (st == DH_OK) {
            inv_check k;
            DHT_TRUE(check_inverse(&T, &X, &k));
            DHT_TRUE_MSG(k.proof < 1.0, "DH_OK without proof: residual %.3g (it %d)", k.proof, it);
            worst_proof = fmax(worst_proof, k.proof);
            worst_rel = fmax(worst_rel, k.rel / (k.cond * U24));
            n_ok++;
        } else {
            DHT_TRUE(memcmp(&X, &S, sizeof X) == 0);
            if (st == DH_ERR_OVERFLOW) {
                n_ovf++;
                if (dhr_max_abs(&Di) <= (double)FLT_MAX) {
                    /* the underflow rule, only above 2^17 (in practice 2^100) */
                    DHT_TRUE(dhr_max_abs(&D) >= 0x1p100);
                    n_under++;
                }
            } else {
                inv_check k;
                DHT_EQ_INT(st, DH_ERR_SINGULAR);
                DHT_TRUE(check_inverse(&T, &S, &k));
                min_sing_cond = fmin(min_sing_cond, k.cond_osb);
                n_sing++;
            }
        }
    }
    dht_printf("extreme magnitudes: %ld ok, %ld singular (smallest Osborne-balanced cond %.3g), %ld overflow (%ld by the "
               "underflow rule); right residual <= %.3g, max|X - T^-1| / (max|T^-1| cond u) <= %.3g\n",
               n_ok, n_sing, min_sing_cond, n_ovf, n_under, worst_proof, worst_rel);
    /* measured over 11 seeds (default, 1..8, 99, 12345): residual 0.043,
     * error 3.21 (cond here: the smallest over the balancings tried),
     * smallest rejected condition number 5.24e5 = the limit 2^19 */
    DHT_TRUE(worst_proof <= 0.09);
    DHT_TRUE(worst_rel <= 6.5);
    DHT_TRUE(min_sing_cond >= 4.9e5);
    DHT_TRUE(n_ok > DHT_ITER(20000) / 4);
}

/*
 * Persp(axis, f) with a small focal distance: T = [I 0; q^T 1], |q| = 1/f.
 * The inverse [I 0; -q^T 1] is exact in float and a similarity
 * diag(1, 1, 1, g), g -> 0, makes T as well conditioned as I, but with
 * p = 0 the certified path used to balance with g = 1 (condition ~ 1/f^2):
 * the default build accepted T on its projective fast path and rejected
 * 2^20 T (DH_SMALL rejected every scale). Now DH_OK at every scale, in
 * both builds, with the contract's proof and accuracy against a double
 * reference computed here.
 */
static void persp_small_focal_every_scale(void)
{
    static const float fs[] = {1e-3f, -1e-3f, 3e-4f, 1e-4f, 1e-5f, -1e-6f, 1e-8f, 1e-10f, 1e-12f};
    double worst_proof = 0.0, worst_rel = 0.0;
    int ax, fi, k;
    for (ax = 0; ax < 3; ax++)
        for (fi = 0; fi < (int)(sizeof fs / sizeof fs[0]); fi++) {
            dh_mat4_f32 P;
            DHT_EQ_INT(dh_mat4_persp_f32(ax, fs[fi], &P), DH_OK);
            for (k = -40; k <= 40; k++) {
                dh_mat4_f32 T, X, Y;
                inv_check c;
                int i, j;
                for (i = 0; i < 4; i++)
                    for (j = 0; j < 4; j++) T.m[i][j] = ldexpf(P.m[i][j], k);
                DHT_EQ_INT(dh_mat4_inv_f32(&T, &X), DH_OK);
                DHT_TRUE(check_inverse(&T, &X, &c));
                DHT_TRUE_MSG(c.proof < 1.0, "axis %d f %g 2^%d: residual %.3g", ax, (double)fs[fi], k, c.proof);
                DHT_TRUE_MSG(c.rel <= 3.1 * c.cond * U24, "axis %d f %g 2^%d: error %.3g, cond %.3g", ax,
                             (double)fs[fi], k, c.rel, c.cond);
                worst_proof = fmax(worst_proof, c.proof);
                worst_rel = fmax(worst_rel, c.rel / (c.cond * U24));
                /* the inverse of 2^k P is 2^-k [I 0; -q^T 1], exactly */
                for (i = 0; i < 4; i++)
                    for (j = 0; j < 4; j++) {
                        const float e = (i == j) ? 1.0f : (i == ax && j == 3) ? -P.m[ax][3] : 0.0f;
                        DHT_EQ_F32_BITS(X.m[i][j], ldexpf(e, -k));
                    }
                /* in place: the same */
                Y = T;
                DHT_EQ_INT(dh_mat4_inv_f32(&Y, &Y), DH_OK);
                DHT_TRUE(memcmp(&X, &Y, sizeof X) == 0);
            }
        }
    dht_printf("persp, small f, 2^-40..2^40: right residual <= %.3g, max|X - T^-1| / (max|T^-1| cond u) <= %.3g\n",
               worst_proof, worst_rel);
}

/*
 * T = [R 0; q^T w] (p = 0) at extreme magnitudes as in
 * extreme_magnitudes_sweep, in a quarter of the cases with q = 0 as well
 * (both zero: no balancing), in another with w = 1, and in a quarter
 * [R p; 0 w] (q = 0 alone, the mirror rule, unchanged): the same status at the
 * scales 2^-20, 1, 2^20 (unless an entry leaves the normal range or the
 * exact inverse does not fit in float), every
 * DH_OK with a proof and the accuracy of the contract, DH_ERR_SINGULAR
 * only for condition numbers (smallest over the balancings) near or
 * above the limit.
 */
/* the exact inverse of T exists and fits in float */
static int fits(const dh_mat4_f32 *T)
{
    dhr_mat4 D, Di;
    dhr_from_f32(&D, T);
    return dhr_inv(&Di, &D) && dhr_max_abs(&Di) <= (double)FLT_MAX;
}

static void p_zero_magnitudes_sweep(void)
{
    double worst_proof = 0.0, worst_rel = 0.0, min_sing_cond = HUGE_VAL;
    long n_ok = 0, n_sing = 0, n_ovf = 0;
    int it;
    for (it = 0; it < DHT_ITER(20000); it++) {
        dh_mat4_f32 T, X, S;
        dhr_mat4 D, Di;
        dh_status st;
        const int top = (int)(dht_rand_u32() % 200u) - 100;
        const int spread = (int)(dht_rand_u32() % 90u);
        const unsigned kind = dht_rand_u32() % 4u;
        int r, c, sc, in_range = 1;
        for (r = 0; r < 4; r++)
            for (c = 0; c < 4; c++) {
                const double f = dht_rand_uniform(0.0, 1.0) * dht_rand_uniform(0.0, 1.0);
                DH_M4(&T, r, c) = rand_at(top - (int)(f * spread));
            }
        for (r = 0; r < 3; r++) {
            if (kind != 3u) DH_M4(&T, r, 3) = 0.0f;  /* p = 0 */
            if (kind == 0u || kind == 3u) DH_M4(&T, 3, r) = 0.0f; /* q = 0 */
        }
        if (kind == 1u) DH_M4(&T, 3, 3) = 1.0f;
        memset(&S, 0x5a, sizeof S);
        X = S;
        st = dh_mat4_inv_f32(&T, &X);
        for (sc = -20; sc <= 20; sc += 40) {
            dh_mat4_f32 U, Y;
            for (r = 0; r < 4; r++)
                for (c = 0; c < 4; c++) {
                    const float v = T.m[r][c];
                    U.m[r][c] = ldexpf(v, sc);
                    if (v != 0.0f && !(fabsf(v) >= 0x1p-105f && fabsf(v) <= 0x1p107f)) in_range = 0;
                }
            if (in_range && fits(&T) && fits(&U)) DHT_EQ_INT(dh_mat4_inv_f32(&U, &Y), st);
        }
        dhr_from_f32(&D, &T);
        if (!dhr_inv(&Di, &D)) {
            DHT_EQ_INT(st, DH_ERR_SINGULAR);
            n_sing++;
            continue;
        }
        if (st == DH_OK) {
            inv_check k;
            DHT_TRUE(check_inverse(&T, &X, &k));
            DHT_TRUE_MSG(k.proof < 1.0, "DH_OK without proof: residual %.3g (it %d)", k.proof, it);
            DHT_TRUE_MSG(k.rel <= 6.5 * k.cond * U24, "error %.3g cond %.3g (it %d)", k.rel, k.cond, it);
            worst_proof = fmax(worst_proof, k.proof);
            worst_rel = fmax(worst_rel, k.rel / (k.cond * U24));
            n_ok++;
        } else {
            DHT_TRUE(memcmp(&X, &S, sizeof X) == 0);
            if (st == DH_ERR_OVERFLOW) {
                n_ovf++;
            } else {
                inv_check k;
                DHT_EQ_INT(st, DH_ERR_SINGULAR);
                DHT_TRUE(check_inverse(&T, &S, &k));
                min_sing_cond = fmin(min_sing_cond, k.cond);
                n_sing++;
            }
        }
    }
    dht_printf("p = 0 or q = 0: %ld ok, %ld singular (smallest cond %.3g), %ld overflow; right residual <= %.3g, "
               "max|X - T^-1| / (max|T^-1| cond u) <= %.3g\n",
               n_ok, n_sing, min_sing_cond, n_ovf, worst_proof, worst_rel);
    DHT_TRUE(worst_proof <= 0.09);
    DHT_TRUE(min_sing_cond >= 4.9e5);
    DHT_TRUE(n_ok > DHT_ITER(20000) / 4);
}


/*
 * Regression: a rigid T whose inverse translation -(R^T p) exceeds
 * FLT_MAX (|p| near FLT_MAX, R a 45-degree turn about z) was returned by
 * dh_mat4_inv_auto_f32 and used by dh_mat4_apply_plane_f32 with an Inf in
 * it and DH_OK, while the contract is "as dh_mat4_inv_f32": DH_ERR_OVERFLOW
 * with the output untouched. Both builds (default: rigid closed form;
 * DH_SMALL: the certified inverse for the plane).
 */
static void rigid_overflowing_translation_reported(void)
{
    dh_mat4_f32 T, out, ref;
    dh_plane_f32 P = {1.0f, 2.0f, 3.0f, 4.0f}, Q, Qref;
    const float big = 0.9f * FLT_MAX;
    DHT_EQ_INT(dh_mat4_rotz_f32(45.0f, &T), DH_OK);
    T.m[3][0] = big;   /* p = (big, big, 0): |R^T p|_x = big sqrt(2) */
    T.m[3][1] = big;
    DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, DH_MAT4_RIGID_TOL), DH_OK);
    DHT_EQ_INT(dh_mat4_inv_f32(&T, &out), DH_ERR_OVERFLOW);
    memset(&out, 0x5A, sizeof out);
    ref = out;
    DHT_EQ_INT(dh_mat4_inv_auto_f32(&T, &out), DH_ERR_OVERFLOW);
    DHT_TRUE(memcmp(&out, &ref, sizeof out) == 0);
    memset(&Q, 0x5A, sizeof Q);
    Qref = Q;
    DHT_EQ_INT(dh_mat4_apply_plane_f32(&T, &P, &Q), DH_ERR_OVERFLOW);
    DHT_TRUE(memcmp(&Q, &Qref, sizeof Q) == 0);
    /* a quarter of that translation fits: DH_OK and finite results */
    T.m[3][0] = 0.25f * big;
    T.m[3][1] = 0.25f * big;
    DHT_EQ_INT(dh_mat4_inv_auto_f32(&T, &out), DH_OK);
    DHT_TRUE(fabsf(out.m[3][0]) <= FLT_MAX && fabsf(out.m[3][1]) <= FLT_MAX);
    DHT_EQ_INT(dh_mat4_apply_plane_f32(&T, &P, &Q), DH_OK);
    DHT_TRUE(fabsf(Q.d) <= FLT_MAX);
}

/* A rotation with a subnormal translation (+-2^-149) and a bottom row near
 * 2^23: well conditioned once balanced, so DH_OK at every scale 2^k that
 * keeps p non-zero. The general path used to skip the balancing when the
 * quarter-sums of p underflowed to 0 and called these singular (found by
 * test_builds_agree; column-major words). */
static const uint32_t k_subnormal_p[3][16] = {
    {0x3de718b5u, 0xbf190dc4u, 0xbf4b2a47u, 0xcb000000u, 0x00000000u, 0xbf4c7898u, 0x3f1a099fu, 0x00000000u,
     0xbf7e5d6fu, 0xbd8b0d8cu, 0xbdb8948du, 0x00000000u, 0x00000000u, 0x00000000u, 0x80000001u, 0x3f800000u},
    {0x3f800000u, 0x354e697fu, 0x00000000u, 0x00000000u, 0xb48d1aa0u, 0x3eaf00a1u, 0xbf7094e8u, 0x00000000u,
     0xb541faf7u, 0x3f7094e8u, 0x3eaf00a1u, 0x4b000001u, 0x00000000u, 0x80000001u, 0x00000000u, 0x3f800000u},
    {0xbf773eb2u, 0x00000000u, 0xbe84c13du, 0x00000000u, 0xbe84c13du, 0x00000000u, 0x3f773eb2u, 0x4affffffu,
     0x00000000u, 0x3f800000u, 0x00000000u, 0x00000000u, 0x00000001u, 0x00000000u, 0x00000000u, 0x3f800000u}};

static void subnormal_translation_balanced(void)
{
    int n, k, c, r;
    for (n = 0; n < 3; n++) {
        for (k = 0; k <= 8; k++) {
            dh_mat4_f32 T, X;
            inv_check o;
            for (c = 0; c < 4; c++)
                for (r = 0; r < 4; r++) {
                    float v;
                    memcpy(&v, &k_subnormal_p[n][4 * c + r], sizeof v);
                    T.m[c][r] = ldexpf(v, k);
                }
            DHT_EQ_INT(dh_mat4_inv_f32(&T, &X), DH_OK);
            DHT_TRUE(check_inverse(&T, &X, &o));
            DHT_TRUE_MSG(o.proof <= 0.5 && o.rel <= 3.2 * o.cond * 0x1p-24,
                         "matrix %d at 2^%d: residual %.3g (bound 0.5), error %.3g (bound %.3g)", n, k,
                         o.proof, o.rel, 3.2 * o.cond * 0x1p-24);
        }
    }
}

static const dht_case cases[] = {
    DHT_CASE(proj_1e35_inverts_at_every_scale),
    DHT_CASE(affine_large_translation_inverts),
    DHT_CASE(nonfinite_elimination_is_singular),
    DHT_CASE(underflowing_inverse_reported),
    DHT_CASE(extreme_magnitudes_sweep),
    DHT_CASE(persp_small_focal_every_scale),
    DHT_CASE(p_zero_magnitudes_sweep),
    DHT_CASE(rigid_overflowing_translation_reported),
    DHT_CASE(subnormal_translation_balanced),
};
DHT_MAIN(cases)
