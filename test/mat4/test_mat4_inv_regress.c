/* SPDX-License-Identifier: Apache-2.0 */
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
#include "dhmath/mat4.h"

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
    dhr_from_f32(T, &D);
    if (!dhr_inv(&D, &Di)) return 0;
    dhr_from_f32(X, &Dx);
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
        dhr_from_f32(&T, &D);
        if (dhr_max_abs(&D) < (double)FLT_MIN) {
            /* zero or denormal matrix */
            DHT_EQ_INT(st, DH_ERR_SINGULAR);
            DHT_TRUE(memcmp(&X, &S, sizeof X) == 0);
            continue;
        }
        DHT_TRUE(dhr_inv(&D, &Di));
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

/* ---------------------------------------------------------------------- */
/* the contract of dh_mat4_inv_f32 over the class it names                */
/* ---------------------------------------------------------------------- */

/* Error bound of the contract (mat4.h): bal_err <= INV_C cond u (its
 * balanced measure, 2^-147 absolute allowed for underflow) */
#define INV_C 5.0

/* T in row-major hexadecimal words, for the message of a failed check */
static void show(const char *what, const dh_mat4_f32 *T)
{
    uint32_t w[16];
    int r, c;
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++) memcpy(&w[4 * r + c], &DH_M4(T, r, c), sizeof w[0]);
    dht_printf("%s (row-major float bits):", what);
    for (r = 0; r < 16; r++) dht_printf(" %08lx", (unsigned long)w[r]);
    dht_printf("\n");
}

#define CHECK_M(c, T, ...)           \
    do {                             \
        if (!(c)) {                  \
            show("input", (T));      \
            DHT_TRUE_MSG(0, __VA_ARGS__); \
        }                            \
    } while (0)

/* 1-norm (largest column sum) */
static double norm1(const dhr_mat4 *A)
{
    double w = 0.0;
    int r, c;
    for (c = 0; c < 4; c++) {
        double s = 0.0;
        for (r = 0; r < 4; r++) s += fabs(DHR_M4(A, r, c));
        w = fmax(w, s);
    }
    return w;
}

/* bottom row 0 0 0 w, w a power of two (normal) */
static int is_affine_ref(const dh_mat4_f32 *T)
{
    int e;
    const double w = (double)DH_M4(T, 3, 3);
    return DH_M4(T, 3, 0) == 0.0f && DH_M4(T, 3, 1) == 0.0f && DH_M4(T, 3, 2) == 0.0f && fabs(w) >= (double)FLT_MIN &&
           fabs(w) <= (double)FLT_MAX && fabs(frexp(w, &e)) == 0.5;
}

/*
 * The balanced condition number as mat4.h defines it, from its
 * definition (double): M = T, or for an affine T blockdiag(R, 1) with R
 * scaled by the power of two that brings max|R_ij| into [1, 2);
 * B = E M E^-1, E = diag(1, 1, 1, g), g from A0 = M scaled (in float, by
 * an exact power of two) to max|A0_ij| in [1, 2): sqrt(|p|_1 / |q|_1),
 * p = column 3 and q = bottom row of A0 without the corner; for p = 0,
 * 2^-24 ||R||_1 / |q|_1; for q = 0, 2^24 |p|_1 / ||R||_1; clamped to
 * [2^-60, 2^60]. Also returns T^-1 (from B^-1, unbalanced), or HUGE_VAL
 * for a matrix the double elimination finds singular.
 */
static double ref_cond(const dh_mat4_f32 *T, dhr_mat4 *Ti, double tsum[2], double *go)
{
    const int aff = is_affine_ref(T);
    dhr_mat4 B, Bi;
    double mx = 0.0, p = 0.0, q = 0.0, nr = 0.0, g = 1.0, sr = 1.0;
    int r, c, e;
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++)
            if (!aff || (r < 3 && c < 3)) mx = fmax(mx, fabs((double)DH_M4(T, r, c)));
    if (mx == 0.0) return HUGE_VAL;
    (void)frexp(mx, &e); /* mx in [2^(e-1), 2^e); scaled by 2^(1-e), at least 2^-126 */
    if (e > 127) e = 127;
    for (c = 0; c < 3; c++) {
        double s = 0.0;
        for (r = 0; r < 3; r++) s += fabs((double)ldexpf(DH_M4(T, r, c), 1 - e));
        nr = fmax(nr, s);
    }
    if (aff) {
        sr = ldexp(1.0, 1 - e);
    } else {
        for (r = 0; r < 3; r++) {
            p += fabs((double)ldexpf(DH_M4(T, r, 3), 1 - e));
            q += fabs((double)ldexpf(DH_M4(T, 3, r), 1 - e));
        }
        if (p > 0.0 && q > 0.0) g = sqrt(p / q);
        else if (q > 0.0) g = ldexp(nr / q, -24);
        else if (p > 0.0) g = ldexp(p / nr, 24);
        g = fmin(fmax(g, ldexp(1.0, -60)), ldexp(1.0, 60));
    }
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++) {
            double v = (double)DH_M4(T, r, c);
            if (aff && (r == 3 || c == 3)) v = (r == c) ? 1.0 : 0.0;
            else v *= sr;
            if (c == 3 && r < 3) v /= g;
            if (r == 3 && c < 3) v *= g;
            DHR_M4(&B, r, c) = v;
        }
    *go = g;
    if (!dhr_inv(&B, &Bi)) return HUGE_VAL;
    if (Ti != NULL) {
        for (r = 0; r < 4; r++)
            for (c = 0; c < 4; c++) {
                double v = DHR_M4(&Bi, r, c);
                if (c == 3 && r < 3) v *= g;
                if (r == 3 && c < 3) v /= g;
                DHR_M4(Ti, r, c) = v;
            }
        if (aff) {
            /* T^-1 = [R^-1, -R^-1 p / w; 0 1 / w], R^-1 = sr (sR)^-1;
             * tsum: max_i sum_j |R^-1_ij p_j| / |w|; tsum[1]: the scale of
             * the translation's error bound, max|R^-1| |p|_1 / |w| */
            const double w = (double)DH_M4(T, 3, 3);
            double mri = 0.0, p1 = 0.0;
            for (r = 0; r < 3; r++) {
                double t = 0.0, ta = 0.0;
                for (c = 0; c < 3; c++) {
                    DHR_M4(Ti, r, c) *= sr;
                    t -= DHR_M4(Ti, r, c) * (double)DH_M4(T, c, 3);
                    ta += fabs(DHR_M4(Ti, r, c) * (double)DH_M4(T, c, 3));
                }
                DHR_M4(Ti, r, 3) = t / w;
                tsum[0] = fmax(tsum[0], ta / fabs(w));
                p1 += fabs((double)DH_M4(T, r, 3));
                for (c = 0; c < 3; c++) mri = fmax(mri, fabs(DHR_M4(Ti, r, c)));
            }
            tsum[1] = mri * p1 / fabs(w);
            DHR_M4(Ti, 3, 3) = 1.0 / w;
        }
    }
    return norm1(&B) * norm1(&Bi);
}

/*
 * The error of X as the contract measures it, relative: non-affine T
 * max|E (X - T^-1) E^-1| / max|E T^-1 E^-1|, E = diag(1, 1, 1, 1 / g) (the
 * balanced coordinates of ref_cond); affine T the larger of
 * max|X_R - R^-1| / max|R^-1| and max_i |X_i3 - t_i| / tsc (t = -R^-1 p
 * / w, tsc = max|R^-1| |p|_1 / |w|), the rest of the bottom row (0 in
 * T^-1) like the R^-1 block, the corner relative to 1 / w; after 2^-147
 * absolute (underflow).
 */
static double bal_err(const dh_mat4_f32 *X, const dhr_mat4 *Ti, double g, int aff, double tsc)
{
    double e = 0.0, m = 0.0, et = 0.0, ec = 0.0;
    int r, c;
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++) {
            double w = 1.0, d = fabs((double)DH_M4(X, r, c) - DHR_M4(Ti, r, c));
            d = fmax(d - 0x1p-147, 0.0);
            if (aff) {
                if (r < 3 && c < 3) {
                    e = fmax(e, d);
                    m = fmax(m, fabs(DHR_M4(Ti, r, c)));
                } else if (r < 3) {
                    et = fmax(et, d);
                } else if (c < 3) {
                    e = fmax(e, d);                          /* 0 in T^-1 */
                } else {
                    ec = d / fabs(DHR_M4(Ti, 3, 3));         /* 1 / w, relative */
                }
                continue;
            }
            if (c == 3 && r < 3) w = 1.0 / g;
            if (r == 3 && c < 3) w = g;
            e = fmax(e, d * w);
            m = fmax(m, fabs(DHR_M4(Ti, r, c)) * w);
        }
    e /= m;
    if (aff && tsc > 0.0) e = fmax(e, et / tsc);
    else if (aff && et > 0.0) return HUGE_VAL;
    return fmax(e, ec);
}

/* standard normal deviate (Box-Muller) */
static double gauss(void)
{
    const double u = 1.0 - dht_rand_uniform(0.0, 1.0), v = dht_rand_uniform(0.0, 1.0);
    return sqrt(-2.0 * log(u)) * cos(2.0 * DHR_PI * v);
}

/* random n x n orthogonal Q (Gram-Schmidt on normal deviates) */
static void rand_orth(int n, double Q[4][4])
{
    int i, j, k;
    for (i = 0; i < n; i++)
        for (j = 0; j < n; j++) Q[i][j] = gauss();
    for (j = 0; j < n; j++) {
        double nn = 0.0;
        for (k = 0; k < j; k++) {
            double d = 0.0;
            for (i = 0; i < n; i++) d += Q[i][j] * Q[i][k];
            for (i = 0; i < n; i++) Q[i][j] -= d * Q[i][k];
        }
        for (i = 0; i < n; i++) nn += Q[i][j] * Q[i][j];
        nn = sqrt(nn);
        for (i = 0; i < n; i++) Q[i][j] /= nn;
    }
}

/* 2^k T into U; 0 if an element does not scale exactly (or leaves the
 * normal range) */
static int scale_exact(const dh_mat4_f32 *T, int k, dh_mat4_f32 *U)
{
    int r, c;
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++) {
            const float v = DH_M4(T, r, c), w = ldexpf(v, k);
            if (v != 0.0f && !(fabsf(v) >= FLT_MIN && fabsf(w) >= FLT_MIN && fabsf(w) <= FLT_MAX)) return 0;
            DH_M4(U, r, c) = w;
        }
    return 1;
}

/* 1 when the elements the contract's "max|T_ij| < FLT_MIN" rule names
 * (all 16; of an affine-type T those of R) are all below FLT_MIN */
static int below_normal(const dh_mat4_f32 *T)
{
    const int n = is_affine_ref(T) ? 3 : 4;
    int r, c;
    for (r = 0; r < n; r++)
        for (c = 0; c < n; c++)
            if (!(fabsf(DH_M4(T, r, c)) < FLT_MIN)) return 0;
    return 1;
}

typedef struct {
    long n, n_ok, n_ovf, n_pairs;
    double worst;      /* max |X - T^-1| / (cond u max|T^-1|) */
    double worst_cond; /* its cond */
} contract_stats;

/*
 * One matrix against the contract: the status from the double reference
 * (cond < DH_MAT4_COND_MAX / 2: never DH_ERR_SINGULAR; DH_ERR_OVERFLOW
 * exactly when T^-1 has an element beyond FLT_MAX, or by the underflow
 * rule), the error bound on DH_OK, and the status of 2^k T (exact): the
 * same, except where either inverse leaves the float range.
 */
static void contract_one(const dh_mat4_f32 *T, int k, contract_stats *st)
{
    dh_mat4_f32 X, S, U, Y;
    dhr_mat4 Ti;
    double tsum[2] = {0.0, 0.0}, g = 1.0;
    const double cond = ref_cond(T, &Ti, tsum, &g);
    dh_status s;
    memset(&S, 0x5a, sizeof S);
    X = S;
    s = dh_mat4_inv_f32(T, &X);
    st->n++;
    if (s != DH_OK) CHECK_M(memcmp(&X, &S, sizeof X) == 0, T, "status %d: output written", (int)s);
    if (below_normal(T)) {
        /* the contract: max|T_ij| (affine type: max|R_ij|) < FLT_MIN is
         * DH_ERR_SINGULAR, whatever the condition of the exact matrix */
        CHECK_M(s == DH_ERR_SINGULAR, T, "max|T_ij| < FLT_MIN: status %d, expected DH_ERR_SINGULAR", (int)s);
    } else if (cond < (double)DH_MAT4_COND_MAX / 2.0) {
        const double mt = dhr_max_abs(&Ti);
        CHECK_M(s != DH_ERR_SINGULAR, T, "cond %.6g < %.6g (DH_MAT4_COND_MAX / 2) reported DH_ERR_SINGULAR", cond,
                (double)DH_MAT4_COND_MAX / 2.0);
        const double rb = INV_C * cond * U24; /* relative error bound */
        dhr_mat4 D;
        dhr_from_f32(T, &D);
        if (mt > (double)FLT_MAX * (1.0 + rb)) {
            CHECK_M(s == DH_ERR_OVERFLOW, T, "max|T^-1| %.6g > FLT_MAX: status %d, expected DH_ERR_OVERFLOW", mt,
                    (int)s);
        } else if (s == DH_ERR_OVERFLOW) {
            /* within the error bound of FLT_MAX, or the underflow rule
             * (elements of T^-1 below FLT_MIN, only for max|T| >= 2^78) */
            CHECK_M(fmax(mt, tsum[0]) * (1.0 + rb) >= (double)FLT_MAX || dhr_max_abs(&D) >= 0x1p78, T,
                    "DH_ERR_OVERFLOW with max|T^-1| %.6g, sum|R^-1||p| / |w| %.6g < FLT_MAX / (1 + %.3g) and "
                    "max|T| %.6g < 2^78", mt, tsum[0], rb, dhr_max_abs(&D));
            st->n_ovf++;
        } else {
            double err;
            CHECK_M(s == DH_OK, T, "cond %.6g: status %d, expected DH_OK", cond, (int)s);
            err = bal_err(&X, &Ti, g, is_affine_ref(T), tsum[1]) / (cond * U24);
            CHECK_M(err <= INV_C, T, "error %.4g cond u (balanced, see the contract) > bound %.1f cond u, cond %.6g",
                    err, INV_C, cond);
            if (err > st->worst) {
                st->worst = err;
                st->worst_cond = cond;
            }
            st->n_ok++;
        }
    }
    if (k != 0 && scale_exact(T, k, &U)) {
        const dh_status su = dh_mat4_inv_f32(&U, &Y);
        st->n_pairs++;
        if (s != DH_ERR_OVERFLOW && su != DH_ERR_OVERFLOW)
            CHECK_M(s == su, T, "status %d, but %d for 2^%d T (cond %.6g)", (int)s, (int)su, k, cond);
        else
            CHECK_M(s != DH_ERR_SINGULAR && su != DH_ERR_SINGULAR, T,
                    "status %d, but %d for 2^%d T (cond %.6g)", (int)s, (int)su, k, cond);
        if (su == DH_OK) {
            /* the accuracy of 2^k T too (an affine T becomes bottom row
             * 0 0 0 2^k: the affine type with w != 1) */
            dhr_mat4 Ui;
            double tu[2] = {0.0, 0.0}, gu = 1.0, eu;
            const double cu = ref_cond(&U, &Ui, tu, &gu);
            if (cu < (double)DH_MAT4_COND_MAX / 2.0) {
                eu = bal_err(&Y, &Ui, gu, is_affine_ref(&U), tu[1]) / (cu * U24);
                CHECK_M(eu <= INV_C, &U, "2^%d T: error %.4g cond u (balanced) > bound %.1f cond u, cond %.6g", k, eu,
                        INV_C, cu);
                if (eu > st->worst) {
                    st->worst = eu;
                    st->worst_cond = cu;
                }
            }
        }
    }
}

/* a random matrix of the contract's class: entries N(0, 1); kind 0: as
 * drawn, 1: last column and last row scaled by independent powers of two
 * (2^-40..2^40: the balancing), 2: affine (R and p normal, p scaled by
 * 2^-60..2^60), 3: like 1 with a row replaced by a combination of the
 * others plus eps N(0, 1), eps = 2^-24..1 (condition numbers on both
 * sides of the limit), 4 and 5: U diag(sv) V^T with random orthogonal U,
 * V, for the 4x4 matrix and for R of an affine one (as 2); the whole
 * matrix times 2^-100..2^100; 0 if an
 * element would exceed FLT_MAX (drawn again) */
static int rand_class(dh_mat4_f32 *T, unsigned kind)
{
    double a[4][4];
    const int kc = (int)(dht_rand_u32() % 81u) - 40, kr = (int)(dht_rand_u32() % 81u) - 40;
    const int kp = (int)(dht_rand_u32() % 121u) - 60, ks = (int)(dht_rand_u32() % 201u) - 100;
    int r, c;
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++) a[r][c] = gauss();
    if (kind >= 4u) {
        /* U diag(sv) V^T, sv = 1 and 2^-18..1 (the shapes where cofactors
         * cancel: one large singular value, the others small) */
        const int n = (kind == 4u) ? 4 : 3;
        double U[4][4], V[4][4], sv[4];
        int k;
        rand_orth(n, U);
        rand_orth(n, V);
        sv[0] = 1.0;
        for (k = 1; k < n; k++) sv[k] = ldexp(1.0, -(int)(dht_rand_u32() % 19u));
        if (dht_rand_u32() & 1u)
            for (k = 2; k < n; k++) sv[k] = sv[1]; /* all small ones equal */
        for (r = 0; r < n; r++)
            for (c = 0; c < n; c++) {
                double v = 0.0;
                for (k = 0; k < n; k++) v += U[r][k] * sv[k] * V[c][k];
                a[r][c] = v;
            }
    }
    if (kind == 3u) {
        const int row = (int)(dht_rand_u32() % 4u);
        const double eps = ldexp(1.0, -(int)(dht_rand_u32() % 25u));
        double w[4];
        for (r = 0; r < 4; r++) w[r] = gauss();
        for (c = 0; c < 4; c++) {
            double v = eps * gauss();
            for (r = 0; r < 4; r++)
                if (r != row) v += w[r] * a[r][c];
            a[row][c] = v;
        }
    }
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++) {
            double v = a[r][c];
            if (kind == 2u || kind == 5u) {
                if (r == 3) v = (c == 3) ? 1.0 : 0.0;
                else if (c == 3) v = ldexp(v, kp - ks);
            } else if (kind != 0u && kind != 4u) {
                if (c == 3 && r < 3) v = ldexp(v, kc);
                if (r == 3 && c < 3) v = ldexp(v, kr);
            }
            if (!((kind == 2u || kind == 5u) && r == 3)) v = ldexp(v, ks);
            if (!(fabs(v) < (double)FLT_MAX)) return 0;
            DH_M4(T, r, c) = (float)v;
        }
    return 1;
}

/*
 * The contract over its class: random matrices with normal entries
 * (balanced, unbalanced, affine, near-singular), at random scales; every
 * check against the double reference above.
 */
static void inverse_contract_random(void)
{
    contract_stats st;
    unsigned kind;
    int it;
    memset(&st, 0, sizeof st);
    for (it = 0; it < DHT_ITER(40000); it++) {
        dh_mat4_f32 T;
        kind = (unsigned)it % 6u;
        while (!rand_class(&T, kind)) {
        }
        contract_one(&T, (int)(dht_rand_u32() % 61u) - 30, &st);
    }
    dht_printf("contract class: %ld matrices, %ld DH_OK, %ld underflow-rule overflow, %ld scaled pairs; "
               "error / (cond u) <= %.3g (at cond %.3g; bound %.1f)\n",
               st.n, st.n_ok, st.n_ovf, st.n_pairs, st.worst, st.worst_cond, INV_C);
    DHT_TRUE(st.n_ok > DHT_ITER(40000) / 2);
}

/* The counts of a magnitude sweep (sweep_judge) */
typedef struct {
    double worst_proof, min_sing_cond;
    long n_ok, n_sing, n_sub, n_ovf, n_under;
    contract_stats cs;
} sweep_stats;

static void sweep_start(sweep_stats *ss)
{
    memset(ss, 0, sizeof *ss);
    ss->min_sing_cond = HUGE_VAL;
}

/*
 * X = T^-1 with status st (S: what X held before the call) against the
 * double reference: every DH_OK with a proof, the status and accuracy of
 * the contract (contract_one, at 2^k T), the output untouched otherwise;
 * DH_ERR_SINGULAR only when the reference is singular, T is below FLT_MIN
 * or ill-conditioned (smallest condition number kept); with under_rule,
 * DH_ERR_OVERFLOW for an inverse that fits only by the underflow rule.
 */
static void sweep_judge(const dh_mat4_f32 *T, const dh_mat4_f32 *X, const dh_mat4_f32 *S, dh_status st, int it,
                        int under_rule, sweep_stats *ss)
{
    dhr_mat4 D, Di;
    dhr_from_f32(T, &D);
    if (!dhr_inv(&D, &Di)) {
        DHT_EQ_INT(st, DH_ERR_SINGULAR);
        ss->n_sing++;
        return;
    }
    contract_one(T, (int)(dht_rand_u32() % 61u) - 30, &ss->cs);
    if (st == DH_OK) {
        inv_check k;
        DHT_TRUE(check_inverse(T, X, &k));
        CHECK_M(k.proof < 1.0, T, "DH_OK without proof: residual %.3g (it %d)", k.proof, it);
        ss->worst_proof = fmax(ss->worst_proof, k.proof);
        ss->n_ok++;
        return;
    }
    DHT_TRUE(memcmp(X, S, sizeof *X) == 0);
    if (st == DH_ERR_OVERFLOW) {
        ss->n_ovf++;
        if (under_rule && dhr_max_abs(&Di) <= (double)FLT_MAX) {
            /* the underflow rule, only above 2^17 (in practice 2^100) */
            DHT_TRUE(dhr_max_abs(&D) >= 0x1p100);
            ss->n_under++;
        }
    } else {
        double tsum[2] = {0.0, 0.0}, g = 1.0;
        DHT_EQ_INT(st, DH_ERR_SINGULAR);
        ss->n_sing++;
        if (below_normal(T)) { /* the contract's max|T_ij| < FLT_MIN rule */
            ss->n_sub++;
            return;
        }
        ss->min_sing_cond = fmin(ss->min_sing_cond, ref_cond(T, NULL, tsum, &g));
    }
}

/* the sweep's bounds: proofs within the contract's acceptance bound (DH_OK
 * needs a balanced right residual <= 1/2; the norms tried here include that
 * balancing), no DH_ERR_SINGULAR when well conditioned, a quarter of the
 * matrices invertible */
static void sweep_end(const sweep_stats *ss)
{
    DHT_TRUE_MSG(ss->worst_proof <= 0.5, "right residual %.3g > 1/2", ss->worst_proof);
    DHT_TRUE_MSG(ss->min_sing_cond >= (double)DH_MAT4_COND_MAX / 2.0, "DH_ERR_SINGULAR at cond %.6g < %.6g",
                 ss->min_sing_cond, (double)DH_MAT4_COND_MAX / 2.0);
    DHT_TRUE(ss->n_ok > DHT_ITER(20000) / 4);
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
    sweep_stats ss;
    int it;
    sweep_start(&ss);
    for (it = 0; it < DHT_ITER(20000); it++) {
        dh_mat4_f32 T, X, S;
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
        sweep_judge(&T, &X, &S, st, it, 1, &ss);
    }
    dht_printf("extreme magnitudes: %ld ok, %ld singular (%ld of them below FLT_MIN; smallest cond of the others "
               "%.3g), %ld overflow (%ld by the underflow rule); right residual <= %.3g, error / (cond u) <= %.3g (at "
               "cond %.3g; bound %.1f)\n", ss.n_ok, ss.n_sing, ss.n_sub, ss.min_sing_cond, ss.n_ovf, ss.n_under,
               ss.worst_proof, ss.cs.worst, ss.cs.worst_cond, INV_C);
    dht_reach_max("extreme.proof", ss.worst_proof);
    sweep_end(&ss);
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
 * exact inverse does not fit in float; one of them may be DH_ERR_OVERFLOW
 * by the contract's underflow rule where its max|T_ij| >= 2^78), every
 * DH_OK with a proof and the accuracy of the contract, DH_ERR_SINGULAR
 * only for condition numbers (smallest over the balancings) near or
 * above the limit.
 */
/* the exact inverse of T exists and fits in float */
static int fits(const dh_mat4_f32 *T)
{
    dhr_mat4 D, Di;
    dhr_from_f32(T, &D);
    return dhr_inv(&D, &Di) && dhr_max_abs(&Di) <= (double)FLT_MAX;
}

/* max |T_ij| (exact in double) */
static double f32_max_abs(const dh_mat4_f32 *T)
{
    dhr_mat4 D;
    dhr_from_f32(T, &D);
    return dhr_max_abs(&D);
}

static void p_zero_magnitudes_sweep(void)
{
    sweep_stats ss;
    long n_urule = 0; /* scaled pairs whose statuses differ by the underflow rule */
    int it;
    sweep_start(&ss);
    for (it = 0; it < DHT_ITER(20000); it++) {
        dh_mat4_f32 T, X, S;
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
            if (in_range && fits(&T) && fits(&U)) {
                const dh_status su = dh_mat4_inv_f32(&U, &Y);
                /* the same status, except DH_ERR_OVERFLOW by the
                 * contract's underflow rule, which applies only where
                 * max|T_ij| >= 2^78 (at 2^20 T or at T) */
                if (su == DH_ERR_OVERFLOW && st == DH_OK && f32_max_abs(&U) >= 0x1p78) {
                    n_urule++;
                } else if (st == DH_ERR_OVERFLOW && su == DH_OK && f32_max_abs(&T) >= 0x1p78) {
                    n_urule++;
                } else {
                    DHT_EQ_INT(su, st);
                }
            }
        }
        sweep_judge(&T, &X, &S, st, it, 0, &ss);
    }
    dht_reach_max("p_zero.below_normal", (double)ss.n_sub);
    dht_reach_max("p_zero.scaled_urule", (double)n_urule);
    dht_printf("p = 0 or q = 0: %ld ok, %ld singular (%ld of them below FLT_MIN; smallest cond of the others %.3g), "
               "%ld overflow; %ld scaled pairs apart by the underflow rule; right residual <= %.3g, "
               "error / (cond u) <= %.3g (at cond %.3g; bound %.1f)\n",
               ss.n_ok, ss.n_sing, ss.n_sub, ss.min_sing_cond, ss.n_ovf, n_urule, ss.worst_proof, ss.cs.worst,
               ss.cs.worst_cond, INV_C);
    sweep_end(&ss);
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

/*
 * Four inputs of the general inverse, rows of T: (a) cond 883, entries
 * 2^-106..2^19 (largest in the translation), and (b) cond 4.0e4, largest
 * entry 2^91: both were reported singular at some scales, where the
 * balanced matrix the elimination ran on had all its elements near 2^-60
 * and their products underflowed; (c) cond 2.2, one translation element
 * 2^-149: its inverse (max 1.4e43) overflows below the scale 2^16 and
 * inverts above; (d) affine, cond 372, with translation elements down to
 * 2^-87.
 */
static const float k_scaled[4][16] = {
    {0x1.4695a8p-46f, 0x1.a0a2d4p-43f, -0x1.a33fc6p-48f, -0x1.761deep+18f, 0x1.3982eep-47f, -0x1.e28334p-45f,
     0x1.671416p-48f, 0x1.be150ap+16f, -0x1.e6e4d6p-45f, -0x1.26019cp-42f, 0x1.cf3894p-46f, 0x1.002cap+19f,
     0x1.7ef84ap-106f, 0x1.6d35p-103f, -0x1.2e090cp-106f, -0x1.450cf6p-42f},
    {-0x1.64ff3ap+30f, -0x1.4e28fep+29f, -0x1.7a3196p+31f, -0x1.8f41dep+88f, -0x1.de4f68p+28f, -0x1.cc0de8p+27f,
     -0x1.04d12cp+30f, -0x1.24ba22p+87f, -0x1.dbf41ep+32f, -0x1.bdd762p+31f, -0x1.f7f3eep+33f, -0x1.0a087ap+91f,
     -0x1.53c09cp-31f, -0x1.4e5972p-32f, -0x1.7e846cp-30f, -0x1.cceea2p+27f},
    {-0x1.aebf2p-96f, 0x1.63e8b4p-95f, 0x1.156a1cp-93f, -0x1p-149f, -0x1.2527c4p-93f, -0x1.0ec2dcp-96f,
     -0x1.8d8c7p-96f, 0.0f, -0x1.431ab6p-97f, 0x1.1d8332p-93f, -0x1.fa92bcp-96f, 0.0f, 0x1.1d25d4p-43f,
     0x1.0b84ap-43f, 0x1.44eb32p-43f, 0x1.ecfa7cp-94f},
    {0x1.f60accp+2f, -0x1.5c1f34p+2f, -0x1.bf4552p+2f, -0x1.43d506p-49f, -0x1.9f397ep+2f, 0x1.26ea8ep+2f,
     0x1.6f9d28p+2f, 0x1.06ebdcp-87f, -0x1.1fb836p+3f, 0x1.8aea4ap+2f, 0x1.f54df4p+2f, -0x1.610ac4p-76f, 0.0f,
     0.0f, 0.0f, 1.0f}};

/* k_scaled[n] at every scale 2^k that keeps its elements finite and
 * non-zero (the affine one: R and p scaled, the bottom row kept): the
 * contract's status, accuracy and scale invariance */
static void scaled_input(int n)
{
    contract_stats cs;
    int k;
    memset(&cs, 0, sizeof cs);
    for (k = -60; k <= 60; k++) {
        dh_mat4_f32 T;
        int i, fin = 1;
        for (i = 0; i < 16; i++) {
            const float v = ldexpf(k_scaled[n][i], k);
            if (n == 3 && i >= 12) DH_M4(&T, 3, i - 12) = k_scaled[n][i];
            else DH_M4(&T, i / 4, i % 4) = v;
            if (!(fabsf(v) <= FLT_MAX) || (k_scaled[n][i] != 0.0f && v == 0.0f)) fin = 0;
        }
        if (!fin) continue;
        contract_one(&T, 1, &cs);
    }
    dht_printf("input %c: %ld scales, %ld DH_OK, error / (cond u) <= %.3g (bound %.1f)\n", 'a' + n, cs.n, cs.n_ok,
               cs.worst, INV_C);
    DHT_TRUE_MSG(cs.n_ok >= 20, "input %c: only %ld scales DH_OK", 'a' + n, cs.n_ok);
}

static void scaled_inputs_follow_contract(void)
{
    scaled_input(0);
    scaled_input(1);
    scaled_input(2);
}

static void affine_input_within_bound(void) { scaled_input(3); }

/* the statuses at the scales named above (independently of the bound) */
static void scaled_inputs_statuses(void)
{
    static const struct { int n, k; dh_status st; } want[] = {
        {0, 0, DH_OK}, {0, -4, DH_OK}, {1, 0, DH_OK}, {1, 36, DH_OK}, {2, 0, DH_ERR_OVERFLOW}, {2, 15, DH_ERR_OVERFLOW},
        {2, 17, DH_OK}, {3, 0, DH_OK}};
    size_t w;
    for (w = 0; w < sizeof want / sizeof want[0]; w++) {
        dh_mat4_f32 T, X;
        int i;
        for (i = 0; i < 16; i++) DH_M4(&T, i / 4, i % 4) = ldexpf(k_scaled[want[w].n][i], want[w].k);
        CHECK_M(dh_mat4_inv_f32(&T, &X) == want[w].st, &T, "input %c at 2^%d: status %d, expected %d",
                'a' + want[w].n, want[w].k, (int)dh_mat4_inv_f32(&T, &X), (int)want[w].st);
    }
}

/*
 * dh_mat4_inv_auto_f32 on T that pass the rigidity test only within its
 * tolerance: R = Q (I + D), Q a rotation, D symmetric with elements up to
 * DH_MAT4_RIGID_TOL / 2 (so R^T R - I is up to about the tolerance); the
 * closed form is taken and the contract's bound 3.1e-5 (1 + |p|_1) holds
 * against the double inverse of T.
 */
static void auto_near_rigid_within_bound(void)
{
    double worst = 0.0;
    long n = 0;
    int it;
    for (it = 0; it < DHT_ITER(20000); it++) {
        dhr_mat4 Q, D, Di;
        dh_mat4_f32 T, X, Y;
        double d[3][3], p1 = 0.0, err = 0.0;
        int r, c, k;
        dhr_rand_rigid(1000.0, &Q);
        for (r = 0; r < 3; r++)
            for (c = 0; c <= r; c++) d[r][c] = d[c][r] = dht_rand_uniform(-0.5, 0.5) * (double)DH_MAT4_RIGID_TOL;
        D = Q;
        for (r = 0; r < 3; r++)
            for (c = 0; c < 3; c++) {
                double v = DHR_M4(&Q, r, c);
                for (k = 0; k < 3; k++) v += DHR_M4(&Q, r, k) * d[k][c];
                DHR_M4(&D, r, c) = v;
            }
        dhr_to_f32(&D, &T);
        if (dh_mat4_check_rigid_f32(&T, DH_MAT4_RIGID_TOL) != DH_OK) continue;
        DHT_EQ_INT(dh_mat4_inv_auto_f32(&T, &X), DH_OK);
        /* the closed form was taken */
        dh_mat4_inv_rigid_f32(&T, &Y);
        CHECK_M(memcmp(&X, &Y, sizeof X) == 0, &T, "dh_mat4_inv_auto_f32 did not take the closed form");
        dhr_from_f32(&T, &D);
        DHT_TRUE(dhr_inv(&D, &Di));
        for (r = 0; r < 3; r++) p1 += fabs((double)DH_M4(&T, r, 3));
        err = dhr_max_abs_diff(&X, &Di);
        CHECK_M(err <= 3.1e-5 * (1.0 + p1), &T, "error %.6g > bound 3.1e-5 (1 + |p|_1) = %.6g", err,
                3.1e-5 * (1.0 + p1));
        worst = fmax(worst, err / (1.0 + p1));
        n++;
    }
    dht_printf("near-rigid T through dh_mat4_inv_auto_f32: %ld matrices, |X - T^-1| / (1 + |p|_1) <= %.3g = %.1f 2^-24 "
               "(bound 3.1e-5)\n", n, worst, worst / U24);
    DHT_TRUE(n > DHT_ITER(20000) / 4);
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
    DHT_CASE(inverse_contract_random),
    DHT_CASE(scaled_inputs_statuses),
    DHT_CASE(scaled_inputs_follow_contract),
    DHT_CASE(affine_input_within_bound),
    DHT_CASE(auto_near_rigid_within_bound),
};
DHT_MAIN(cases)
