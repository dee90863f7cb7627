/* SPDX-License-Identifier: Apache-2.0 */
/*
 * test_mat4_props.c - property tests of the float 4x4 module against
 * double-precision references computed here (test/support_ref.c), with
 * seeded random inputs. Every case prints the largest error it measured;
 * each tolerance is that measured bound with about 2x headroom (see
 * docs/accuracy_mat4.md). Errors are expressed in units of u = 2^-24 times
 * the natural scale of the quantity, so the bounds do not depend on the
 * magnitude of the random data.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "dht.h"
#include "support_ref.h"
#include "dhmath/mat4.h"
#include "dhmath/rot.h"

#define U24 5.9604644775390625e-8 /* 2^-24 */

static double dmax(double a, double b) { return a > b ? a : b; }

static void rand_rigid_f(dh_mat4_f32 *T, double tmax)
{
    dhr_mat4 D;
    dhr_rand_rigid(tmax, &D);
    dhr_to_f32(&D, T);
}

static void rand_general_f(dh_mat4_f32 *T)
{
    dhr_mat4 D;
    dhr_rand_general(&D);
    dhr_to_f32(&D, T);
}

/* ---- constructors vs references --------------------------------------- */

static void rotations_match_reference(void)
{
    /* dense sweep: random angles, not only whole degrees */
    double emax_xyz = 0.0, emax_axis = 0.0;
    int it;
    for (it = 0; it < DHT_ITER(20000); it++) {
        const float deg = (float)dht_rand_uniform(-720.0, 720.0);
        dh_mat4_f32 T;
        dhr_mat4 D;
        double k[3];
        DHT_EQ_INT(dh_mat4_rotx_f32(deg, &T), DH_OK);
        dhr_rotx((double)deg, &D);
        emax_xyz = dmax(emax_xyz, dhr_max_abs_diff(&T, &D));
        DHT_EQ_INT(dh_mat4_roty_f32(deg, &T), DH_OK);
        dhr_roty((double)deg, &D);
        emax_xyz = dmax(emax_xyz, dhr_max_abs_diff(&T, &D));
        DHT_EQ_INT(dh_mat4_rotz_f32(deg, &T), DH_OK);
        dhr_rotz((double)deg, &D);
        emax_xyz = dmax(emax_xyz, dhr_max_abs_diff(&T, &D));
        /* general axis: any length, reference built as C Rot(z) C^T */
        dhr_rand_unit3(k);
        {
            const double len = pow(10.0, dht_rand_uniform(-30.0, 30.0));
            const float kx = (float)(k[0] * len), ky = (float)(k[1] * len), kz = (float)(k[2] * len);
            DHT_EQ_INT(dh_mat4_rot_axis_f32(kx, ky, kz, deg, &T), DH_OK);
            DHT_TRUE(dhr_rot_axis((double)kx, (double)ky, (double)kz, (double)deg, &D));
            emax_axis = dmax(emax_axis, dhr_max_abs_diff(&T, &D));
        }
    }
    dht_printf("rot x/y/z max |err| = %.3g (%.2f u); rot_axis max |err| = %.3g (%.2f u)\n",
               emax_xyz, emax_xyz / U24, emax_axis, emax_axis / U24);
    /* measured over 10 seeds with the LUT trig: 1.00 u and 4.80 u; 2x headroom */
    DHT_TRUE(emax_xyz <= 2.0 * U24);
    DHT_TRUE(emax_axis <= 10.0 * U24);
}

/* ---- products ---------------------------------------------------------- */

/* max over elements of |C - A*B| / (u * sum_k |A_rk||B_kc|) */
static double product_err_units(const dh_mat4_f32 *C, const dh_mat4_f32 *A, const dh_mat4_f32 *B, int affine)
{
    double worst = 0.0;
    int r, c, k;
    for (r = 0; r < (affine ? 3 : 4); r++)
        for (c = 0; c < 4; c++) {
            double exact = 0.0, mag = 0.0;
            for (k = 0; k < 4; k++) {
                const double a = (double)DH_M4(A, r, k), b = (double)DH_M4(B, k, c);
                exact += a * b;
                mag += fabs(a * b);
            }
            if (mag > 0.0) worst = dmax(worst, fabs((double)DH_M4(C, r, c) - exact) / (U24 * mag));
            else DHT_TRUE(DH_M4(C, r, c) == 0.0f);
        }
    return worst;
}

static void products_match_reference_and_alias(void)
{
    double wfull = 0.0, waff = 0.0;
    int it;
    for (it = 0; it < DHT_ITER(20000); it++) {
        dh_mat4_f32 A, B, C, D, E;
        if (it & 1) {
            rand_rigid_f(&A, 1000.0);
            rand_rigid_f(&B, 1000.0);
        } else {
            rand_general_f(&A);
            rand_general_f(&B);
            DH_M4(&A, 3, 0) = 0; DH_M4(&A, 3, 1) = 0; DH_M4(&A, 3, 2) = 0; DH_M4(&A, 3, 3) = 1;
            DH_M4(&B, 3, 0) = 0; DH_M4(&B, 3, 1) = 0; DH_M4(&B, 3, 2) = 0; DH_M4(&B, 3, 3) = 1;
        }
        dh_mat4_mul_f32(&A, &B, &C);
        wfull = dmax(wfull, product_err_units(&C, &A, &B, 0));
        dh_mat4_mul_affine_f32(&A, &B, &D);
        waff = dmax(waff, product_err_units(&D, &A, &B, 1));
        /* affine == full on affine inputs (values; zeros may differ in sign) */
        {
            int r, c;
            for (r = 0; r < 4; r++)
                for (c = 0; c < 4; c++) DHT_TRUE(DH_M4(&C, r, c) == DH_M4(&D, r, c));
        }
        /* aliasing: out == A, out == B, out == A == B */
        E = A; dh_mat4_mul_f32(&E, &B, &E); DHT_TRUE(memcmp(&E, &C, sizeof E) == 0);
        E = B; dh_mat4_mul_f32(&A, &E, &E); DHT_TRUE(memcmp(&E, &C, sizeof E) == 0);
        E = A; dh_mat4_mul_affine_f32(&E, &B, &E); DHT_TRUE(memcmp(&E, &D, sizeof E) == 0);
        E = B; dh_mat4_mul_affine_f32(&A, &E, &E); DHT_TRUE(memcmp(&E, &D, sizeof E) == 0);
        dh_mat4_mul_f32(&A, &A, &C);
        E = A; dh_mat4_mul_f32(&E, &E, &E); DHT_TRUE(memcmp(&E, &C, sizeof E) == 0);
        /* pre/post multiplication */
        E = B; dh_mat4_premul_f32(&E, &A); dh_mat4_mul_f32(&A, &B, &C); DHT_TRUE(memcmp(&E, &C, sizeof E) == 0);
        E = A; dh_mat4_postmul_f32(&E, &B); DHT_TRUE(memcmp(&E, &C, sizeof E) == 0);
    }
    /* the affine product's bottom row of A is ignored */
    {
        dh_mat4_f32 A, B, C, D;
        rand_rigid_f(&A, 10.0);
        rand_rigid_f(&B, 10.0);
        dh_mat4_mul_affine_f32(&A, &B, &C);
        DH_M4(&A, 3, 0) = NAN; DH_M4(&A, 3, 3) = 7.0f;
        DH_M4(&B, 3, 1) = INFINITY;
        dh_mat4_mul_affine_f32(&A, &B, &D);
        DHT_TRUE(memcmp(&C, &D, sizeof C) == 0);
    }
    dht_printf("product max |err| / (u sum|A||B|): full %.3f, affine %.3f\n", wfull, waff);
    /* a 4-term sum has 4 roundings (a priori bound ~4 u); measured over 10
     * seeds: 2.86 u */
    DHT_TRUE(wfull <= 6.0);
    DHT_TRUE(waff <= 6.0);
}

/* ---- application -------------------------------------------------------- */

static void apply_matches_reference(void)
{
    double wp = 0.0, wd = 0.0, wh = 0.0;
    int it;
    for (it = 0; it < DHT_ITER(20000); it++) {
        dh_mat4_f32 T;
        dhr_mat4 D;
        dh_vec3_f32 u, v, batch[4], out[4];
        dh_vec4_f32 h, hv;
        double du[4], dv[4], mag;
        int i;
        rand_rigid_f(&T, 100.0);
        dhr_from_f32(&T, &D);
        u.x = (float)dht_rand_uniform(-100, 100);
        u.y = (float)dht_rand_uniform(-100, 100);
        u.z = (float)dht_rand_uniform(-100, 100);
        du[0] = u.x; du[1] = u.y; du[2] = u.z; du[3] = 1.0;
        dhr_apply4(&D, du, dv);
        dh_mat4_apply_point_f32(&T, &u, &v);
        for (i = 0; i < 3; i++) {
            mag = fabs(DHR_M4(&D, i, 0) * du[0]) + fabs(DHR_M4(&D, i, 1) * du[1]) +
                  fabs(DHR_M4(&D, i, 2) * du[2]) + fabs(DHR_M4(&D, i, 3));
            wp = dmax(wp, fabs((double)(&v.x)[i] - dv[i]) / (U24 * mag));
        }
        du[3] = 0.0;
        dhr_apply4(&D, du, dv);
        dh_mat4_apply_dir_f32(&T, &u, &v);
        for (i = 0; i < 3; i++) {
            mag = fabs(DHR_M4(&D, i, 0) * du[0]) + fabs(DHR_M4(&D, i, 1) * du[1]) + fabs(DHR_M4(&D, i, 2) * du[2]);
            wd = dmax(wd, fabs((double)(&v.x)[i] - dv[i]) / (U24 * mag));
        }
        /* batch == single, bitwise, also in place */
        for (i = 0; i < 4; i++) {
            batch[i].x = (float)dht_rand_uniform(-9, 9);
            batch[i].y = (float)dht_rand_uniform(-9, 9);
            batch[i].z = (float)dht_rand_uniform(-9, 9);
        }
        dh_mat4_apply_points_f32(&T, batch, out, 4);
        for (i = 0; i < 4; i++) {
            dh_mat4_apply_point_f32(&T, &batch[i], &v);
            DHT_TRUE(memcmp(&v, &out[i], sizeof v) == 0);
        }
        dh_mat4_apply_points_f32(&T, batch, batch, 4);
        DHT_TRUE(memcmp(batch, out, sizeof out) == 0);
        /* homogeneous point through a perspective: x/w with w away from 0 */
        {
            dh_mat4_f32 P, PT;
            dhr_mat4 DP;
            DHT_EQ_INT(dh_mat4_persp_f32(it % 3, (float)dht_rand_uniform(200, 400), &P), DH_OK);
            dh_mat4_mul_f32(&P, &T, &PT);
            dhr_from_f32(&PT, &DP);
            h.x = u.x; h.y = u.y; h.z = u.z; h.w = 1.0f;
            du[0] = u.x; du[1] = u.y; du[2] = u.z; du[3] = 1.0;
            dhr_apply4(&DP, du, dv);
            DHT_EQ_INT(dh_mat4_apply_point_h_f32(&PT, &h, &v), DH_OK);
            dh_mat4_apply_vec4_f32(&PT, &h, &hv);
            for (i = 0; i < 3; i++) {
                /* relative to the size of the homogeneous row sums */
                double rm = 0.0, wm = 0.0;
                int k;
                for (k = 0; k < 4; k++) {
                    rm += fabs(DHR_M4(&DP, i, k) * du[k]);
                    wm += fabs(DHR_M4(&DP, 3, k) * du[k]);
                }
                mag = (rm + fabs(dv[i] / dv[3]) * wm) / fabs(dv[3]);
                wh = dmax(wh, fabs((double)(&v.x)[i] - dv[i] / dv[3]) / (U24 * mag));
            }
        }
    }
    dht_printf("apply max |err| / (u sum|T||u|): point %.3f, dir %.3f, homogeneous point %.3f\n", wp, wd, wh);
    DHT_TRUE(wp <= 6.0);   /* measured 2.78 (10 seeds) */
    DHT_TRUE(wd <= 5.5);   /* measured 2.58 */
    DHT_TRUE(wh <= 4.0);   /* measured 1.83 */
}

/* ---- inverses ----------------------------------------------------------- */

static void rigid_inverse_properties(void)
{
    double w_ref = 0.0, w_id = 0.0, w_gen = 0.0, w_twice = 0.0;
    int it;
    for (it = 0; it < DHT_ITER(20000); it++) {
        dh_mat4_f32 T, Ti, Tg, Ta, P, Tii;
        dhr_mat4 D, Di;
        double tmax = pow(10.0, dht_rand_uniform(-3.0, 4.0)), scale;
        int r;
        rand_rigid_f(&T, tmax);
        DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, DH_MAT4_RIGID_TOL), DH_OK);
        dh_mat4_inv_rigid_f32(&T, &Ti);
        /* vs the double inverse of the (float) input; scale = 1 + |p| */
        dhr_from_f32(&T, &D);
        DHT_TRUE(dhr_inv(&D, &Di));
        scale = 1.0 + fabs(DHR_M4(&D, 0, 3)) + fabs(DHR_M4(&D, 1, 3)) + fabs(DHR_M4(&D, 2, 3));
        w_ref = dmax(w_ref, dhr_max_abs_diff(&Ti, &Di) / (U24 * scale));
        /* T * T^-1 == I */
        dh_mat4_mul_f32(&T, &Ti, &P);
        {
            dhr_mat4 I;
            dhr_identity(&I);
            w_id = dmax(w_id, dhr_max_abs_diff(&P, &I) / (U24 * scale));
        }
        /* general inverse agrees on rigid input; auto takes the fast path */
        DHT_EQ_INT(dh_mat4_inv_f32(&T, &Tg), DH_OK);
        w_gen = dmax(w_gen, dhr_max_abs_diff(&Tg, &Di) / (U24 * scale));
        DHT_EQ_INT(dh_mat4_inv_auto_f32(&T, &Ta), DH_OK);
        DHT_TRUE(memcmp(&Ta, &Ti, sizeof Ta) == 0);
        /* inv(inv(T)) == T */
        dh_mat4_inv_rigid_f32(&Ti, &Tii);
        {
            dhr_mat4 DT;
            dhr_from_f32(&T, &DT);
            w_twice = dmax(w_twice, dhr_max_abs_diff(&Tii, &DT) / (U24 * scale));
        }
        /* rotation block of the rigid inverse is the exact transpose */
        for (r = 0; r < 3; r++) {
            DHT_EQ_F32_BITS(DH_M4(&Ti, r, 0), DH_M4(&T, 0, r));
            DHT_EQ_F32_BITS(DH_M4(&Ti, r, 1), DH_M4(&T, 1, r));
            DHT_EQ_F32_BITS(DH_M4(&Ti, r, 2), DH_M4(&T, 2, r));
        }
    }
    dht_printf("rigid inverse max |err| / (u (1+|p|)): vs double %.3f, T*Ti-I %.3f, general %.3f, "
               "inv(inv(T))-T %.3f\n", w_ref, w_id, w_gen, w_twice);
    DHT_TRUE(w_ref <= 4.5);    /* measured 2.22 (10 seeds) */
    DHT_TRUE(w_id <= 6.5);     /* measured 3.16 */
    DHT_TRUE(w_gen <= 7.5);    /* measured 3.60 */
    DHT_TRUE(w_twice <= 6.5);  /* measured 3.16 */
}

/* random matrix with 2-norm condition number ~ cond: U diag V */
static void rand_conditioned(dhr_mat4 *D, double cond)
{
    dhr_mat4 U, V, S;
    double k[3];
    int i;
    dhr_rand_unit3(k);
    dhr_rot_axis(k[0], k[1], k[2], dht_rand_uniform(-180, 180), &U);
    dhr_rand_unit3(k);
    dhr_rot_axis(k[0], k[1], k[2], dht_rand_uniform(-180, 180), &V);
    /* mix the 4th dimension in too */
    {
        dhr_mat4 G;
        const double a = dhr_deg2rad(dht_rand_uniform(-180, 180));
        dhr_identity(&G);
        DHR_M4(&G, 0, 0) = cos(a); DHR_M4(&G, 0, 3) = -sin(a);
        DHR_M4(&G, 3, 0) = sin(a); DHR_M4(&G, 3, 3) = cos(a);
        dhr_mul(&U, &G, &U);
        DHR_M4(&G, 0, 0) = cos(2 * a); DHR_M4(&G, 0, 3) = sin(2 * a);
        DHR_M4(&G, 3, 0) = -sin(2 * a); DHR_M4(&G, 3, 3) = cos(2 * a);
        dhr_mul(&G, &V, &V);
    }
    dhr_identity(&S);
    for (i = 0; i < 4; i++) DHR_M4(&S, i, i) = pow(cond, -dht_rand_uniform(0.0, 1.0));
    DHR_M4(&S, 0, 0) = 1.0;
    DHR_M4(&S, 3, 3) = 1.0 / cond;
    dhr_mul(&U, &S, D);
    dhr_mul(D, &V, D);
}

/* D scaled by scale and rounded to float into T (D then holds T exactly),
 * Di its double inverse; returns the condition number in the 1-norm of
 * the library's criterion (= inf-norm of T^T) */
static double scaled_to_f32(double scale, dhr_mat4 *D, dhr_mat4 *Di, dh_mat4_f32 *T)
{
    dhr_mat4 Dt, Dti;
    int c, r;
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) D->m[c][r] *= scale;
    dhr_to_f32(D, T);
    dhr_from_f32(T, D);
    DHT_TRUE(dhr_inv(D, Di));
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) Dt.m[c][r] = D->m[r][c];
    DHT_TRUE(dhr_inv(&Dt, &Dti));
    return dhr_norm_inf(&Dt) * dhr_norm_inf(&Dti);
}

static void general_inverse_accuracy_and_scale_invariance(void)
{
    double worst = 0.0, worst_id = 0.0, max_acc_cond = 0.0;
    int it;
    for (it = 0; it < DHT_ITER(20000); it++) {
        dhr_mat4 D, Di, DX;
        dh_mat4_f32 T, X, XX;
        double cond, scale = pow(10.0, dht_rand_uniform(-20.0, 20.0));
        rand_conditioned(&D, pow(10.0, dht_rand_uniform(0.0, 4.5)));
        cond = scaled_to_f32(scale, &D, &Di, &T);
        DHT_TRUE_MSG(cond < DH_MAT4_COND_MAX / 2.0, "sample cond %g", cond);
        DHT_EQ_INT(dh_mat4_inv_f32(&T, &X), DH_OK);
        max_acc_cond = dmax(max_acc_cond, cond);
        /* relative error of the inverse in units of cond * u */
        worst = dmax(worst, dhr_max_abs_diff(&X, &Di) / dhr_max_abs(&Di) / (cond * U24));
        /* T * T^-1 == I, relative to cond */
        dhr_from_f32(&X, &DX);
        dhr_mul(&D, &DX, &DX);
        {
            dhr_mat4 I;
            dhr_identity(&I);
            worst_id = dmax(worst_id, dhr_max_abs_diff_d(&DX, &I) / (cond * U24));
        }
        /* inv(inv(T)) == T within the same kind of bound */
        DHT_EQ_INT(dh_mat4_inv_f32(&X, &XX), DH_OK);
        /* aliasing */
        XX = T;
        DHT_EQ_INT(dh_mat4_inv_f32(&XX, &XX), DH_OK);
        DHT_TRUE(memcmp(&XX, &X, sizeof X) == 0);
    }
    dht_printf("general inverse (cond up to %.3g, scale 1e+-20): max rel err / (cond u) = %.3f, "
               "max |T X - I| / (cond u) = %.3f\n", max_acc_cond, worst, worst_id);
    DHT_TRUE(worst <= 6.5);      /* measured 3.07 (10 seeds) */
    DHT_TRUE(worst_id <= 21.0);  /* measured 10.05 */
}

/* random affine [R p; 0 0 0 1] with R = U diag(1, c^-r, 1/c) V (2-norm
 * condition number of R = cond), |p_i| < pmax */
static void rand_affine_conditioned(dhr_mat4 *D, double cond, double pmax)
{
    dhr_mat4 U, V, S;
    double k[3];
    dhr_rand_unit3(k);
    dhr_rot_axis(k[0], k[1], k[2], dht_rand_uniform(-180, 180), &U);
    dhr_rand_unit3(k);
    dhr_rot_axis(k[0], k[1], k[2], dht_rand_uniform(-180, 180), &V);
    dhr_identity(&S);
    DHR_M4(&S, 1, 1) = pow(cond, -dht_rand_uniform(0.0, 1.0));
    DHR_M4(&S, 2, 2) = 1.0 / cond;
    dhr_mul(&U, &S, D);
    dhr_mul(D, &V, D);
    DHR_M4(D, 0, 3) = dht_rand_uniform(-pmax, pmax);
    DHR_M4(D, 1, 3) = dht_rand_uniform(-pmax, pmax);
    DHR_M4(D, 2, 3) = dht_rand_uniform(-pmax, pmax);
}

/* 1-norm condition number of the upper-left 3x3 block of an affine D */
static double cond1_rot(const dhr_mat4 *D)
{
    dhr_mat4 R, Ri, Rt, Rti;
    int c, r;
    R = *D;
    for (c = 0; c < 3; c++) {
        DHR_M4(&R, 3, c) = 0.0;
        DHR_M4(&R, c, 3) = 0.0;
    }
    DHR_M4(&R, 3, 3) = 1.0;
    DHT_TRUE(dhr_inv(&R, &Ri));
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) {
            Rt.m[c][r] = R.m[r][c];
            Rti.m[c][r] = Ri.m[r][c];
        }
    return dhr_norm_inf(&Rt) * dhr_norm_inf(&Rti);
}

/*
 * Accuracy where the adjugate fast paths decide (well-conditioned input at
 * moderate scale): affine transforms of any scale of R and unit of p, and
 * projective matrices at scales 0.1..10. Errors per block relative to
 * cond * u times the size of the exact block.
 */
static void general_inverse_fast_paths_accuracy(void)
{
    double w_rot = 0.0, w_tr = 0.0, w_proj = 0.0;
    int it;
    for (it = 0; it < DHT_ITER(20000); it++) {
        dhr_mat4 D, Di;
        dh_mat4_f32 T, X;
        double cond, mr = 0.0, scale;
        int c, r;
        /* affine: R scaled by 1e-20..1e20, p by 1e-3..1e4 */
        rand_affine_conditioned(&D, pow(10.0, dht_rand_uniform(0.0, 3.0)), pow(10.0, dht_rand_uniform(-3.0, 4.0)));
        scale = pow(10.0, dht_rand_uniform(-20.0, 20.0));
        for (c = 0; c < 3; c++)
            for (r = 0; r < 3; r++) D.m[c][r] *= scale;
        dhr_to_f32(&D, &T);
        dhr_from_f32(&T, &D);
        DHT_TRUE(dhr_inv(&D, &Di));
        cond = cond1_rot(&D);
        DHT_EQ_INT(dh_mat4_inv_f32(&T, &X), DH_OK);
        for (c = 0; c < 3; c++)
            for (r = 0; r < 3; r++) mr = dmax(mr, fabs(DHR_M4(&Di, r, c)));
        for (r = 0; r < 3; r++) {
            double tmag = 0.0;
            for (c = 0; c < 3; c++) {
                w_rot = dmax(w_rot, fabs((double)DH_M4(&X, r, c) - DHR_M4(&Di, r, c)) / (mr * cond * U24));
                tmag += fabs(DHR_M4(&Di, r, c) * DHR_M4(&D, c, 3));
            }
            /* translation relative to sum_j |R^-1_rj p_j| */
            if (tmag > 0.0) w_tr = dmax(w_tr, fabs((double)DH_M4(&X, r, 3) - DHR_M4(&Di, r, 3)) / (tmag * cond * U24));
            DHT_EQ_F32_BITS(DH_M4(&X, 3, r), 0.0f);
        }
        DHT_EQ_F32_BITS(DH_M4(&X, 3, 3), 1.0f);
        /* projective, scale 0.1..10, cond 1..1e3 */
        rand_conditioned(&D, pow(10.0, dht_rand_uniform(0.0, 3.0)));
        scale = pow(10.0, dht_rand_uniform(-1.0, 1.0));
        cond = scaled_to_f32(scale, &D, &Di, &T);
        DHT_EQ_INT(dh_mat4_inv_f32(&T, &X), DH_OK);
        w_proj = dmax(w_proj, dhr_max_abs_diff(&X, &Di) / dhr_max_abs(&Di) / (cond * U24));
    }
    dht_printf("fast paths: affine R^-1 max err / (max|R^-1| cond u) = %.3f, translation / (sum|R^-1||p| cond u) "
               "= %.3f; projective max rel err / (cond u) = %.3f\n", w_rot, w_tr, w_proj);
    /* measured over 10 seeds: 4.57, 4.63, 4.81 */
    DHT_TRUE(w_rot <= 9.5);
    DHT_TRUE(w_tr <= 9.5);
    DHT_TRUE(w_proj <= 10.0);
}

/*
 * The singularity decision does not depend on the scale: T and 2^k T (any
 * k with both in range), and for affine T also [2^k R, p], get the same
 * status, across condition numbers on both sides of the limit; when the
 * affine ones are inverted the results are exactly 2^-k times each other
 * in the R^-1 block (the scaling is exact).
 */
static void general_inverse_decision_scale_invariant(void)
{
    int it, n_ok = 0, n_sing = 0;
    for (it = 0; it < DHT_ITER(20000); it++) {
        dhr_mat4 D;
        dh_mat4_f32 T, T2, X, X2;
        dh_status s1, s2;
        const int k = (int)(dht_rand_u32() % 81u) - 40;
        const double cond = pow(10.0, dht_rand_uniform(0.0, 8.0));
        int c, r;
        if (it & 1) {
            rand_conditioned(&D, cond);
            dhr_to_f32(&D, &T);
            T2 = T;
            for (c = 0; c < 4; c++)
                for (r = 0; r < 4; r++) T2.m[c][r] = ldexpf(T.m[c][r], k);
        } else {
            rand_affine_conditioned(&D, cond, 100.0);
            dhr_to_f32(&D, &T);
            T2 = T;
            for (c = 0; c < 3; c++)
                for (r = 0; r < 3; r++) T2.m[c][r] = ldexpf(T.m[c][r], k);
        }
        s1 = dh_mat4_inv_f32(&T, &X);
        s2 = dh_mat4_inv_f32(&T2, &X2);
        DHT_TRUE(s1 == DH_OK || s1 == DH_ERR_SINGULAR);
        if ((it & 1) == 0 && cond <= 1e4) {
            /* affine and well inside the fast path's range: exact scaling */
            DHT_EQ_INT(s1, DH_OK);
            DHT_EQ_INT(s2, DH_OK);
            for (c = 0; c < 3; c++)
                for (r = 0; r < 3; r++) DHT_EQ_F32_BITS(X2.m[c][r], ldexpf(X.m[c][r], -k));
        } else if ((it & 1) || cond <= 1e4 || cond >= 1e7) {
            /* projective: same decision; affine: same decision outside the
             * band (1e4, 1e7) where the certified criterion decides */
            DHT_TRUE_MSG(s1 == s2, "it %d cond %g k %d: %d vs %d", it, cond, k, (int)s1, (int)s2);
        }
        if (s1 == DH_OK) n_ok++;
        else n_sing++;
    }
    dht_printf("scale invariance: %d accepted, %d reported singular\n", n_ok, n_sing);
    DHT_TRUE(n_ok > 0 && n_sing > 0);
}

static void general_inverse_reports_rank_deficient(void)
{
    /* rank 3 and rank 2 matrices rounded to float: never inverted */
    int it, kind;
    for (kind = 0; kind < 3; kind++) {
        for (it = 0; it < DHT_ITER(20000); it++) {
            dhr_mat4 D;
            dh_mat4_f32 T, O, O0;
            const double a = dht_rand_uniform(-2, 2), b = dht_rand_uniform(-2, 2);
            const double scale = pow(10.0, dht_rand_uniform(-20.0, 20.0));
            int c, r;
            dhr_rand_general(&D);
            if (kind == 0)
                for (c = 0; c < 4; c++) DHR_M4(&D, 3, c) = a * DHR_M4(&D, 0, c) + b * DHR_M4(&D, 1, c);
            if (kind == 1)
                for (r = 0; r < 4; r++) DHR_M4(&D, r, 3) = a * DHR_M4(&D, r, 0) + b * DHR_M4(&D, r, 1) + DHR_M4(&D, r, 2);
            if (kind == 2)
                for (r = 0; r < 4; r++) {
                    DHR_M4(&D, r, 3) = a * DHR_M4(&D, r, 0);
                    DHR_M4(&D, r, 2) = b * DHR_M4(&D, r, 0) + DHR_M4(&D, r, 1);
                }
            for (c = 0; c < 4; c++)
                for (r = 0; r < 4; r++) D.m[c][r] *= scale;
            dhr_to_f32(&D, &T);
            memset(&O, 0x5a, sizeof O);
            O0 = O;
            DHT_EQ_INT(dh_mat4_inv_f32(&T, &O), DH_ERR_SINGULAR);
            DHT_TRUE(memcmp(&O, &O0, sizeof O) == 0);
            DHT_EQ_INT(dh_mat4_inv_auto_f32(&T, &O), DH_ERR_SINGULAR);
        }
    }
    /* a singular affine transform: rotation block of rank 2 */
    {
        dh_mat4_f32 T, O;
        dh_mat4_scale_f32(1.0f, 1e-9f, 1.0f, &T);
        DHT_EQ_INT(dh_mat4_inv_f32(&T, &O), DH_ERR_SINGULAR);
        dh_mat4_scale_f32(1.0f, 1e-5f, 1.0f, &T); /* cond 1e5: invertible */
        DHT_EQ_INT(dh_mat4_inv_f32(&T, &O), DH_OK);
        DHT_EQ_F32_BITS(DH_M4(&O, 1, 1), 1.0f / 1e-5f);
    }
}

/* ---- planes ------------------------------------------------------------- */

static void plane_point_invariance(void)
{
    /* eq. 1.22: Q v == P u with v = T u and Q = P T^-1 */
    double worst = 0.0;
    int it;
    for (it = 0; it < DHT_ITER(20000); it++) {
        dh_mat4_f32 T;
        dh_plane_f32 P, Q;
        dh_vec3_f32 u, v;
        double pu, qv, mag, n;
        if (it & 1) {
            rand_rigid_f(&T, 100.0);
        } else {
            /* non-rigid affine: rotation times scale */
            dh_mat4_f32 S;
            rand_rigid_f(&T, 100.0);
            dh_mat4_scale_f32((float)dht_rand_uniform(0.5, 2), (float)dht_rand_uniform(0.5, 2), (float)dht_rand_uniform(0.5, 2),
                              &S);
            dh_mat4_mul_f32(&T, &S, &T);
        }
        P.a = (float)dht_rand_uniform(-1, 1);
        P.b = (float)dht_rand_uniform(-1, 1);
        P.c = (float)dht_rand_uniform(-1, 1);
        P.d = (float)dht_rand_uniform(-100, 100);
        u.x = (float)dht_rand_uniform(-100, 100);
        u.y = (float)dht_rand_uniform(-100, 100);
        u.z = (float)dht_rand_uniform(-100, 100);
        DHT_EQ_INT(dh_mat4_apply_plane_f32(&T, &P, &Q), DH_OK);
        dh_mat4_apply_point_f32(&T, &u, &v);
        pu = (double)P.a * u.x + (double)P.b * u.y + (double)P.c * u.z + (double)P.d;
        qv = (double)Q.a * v.x + (double)Q.b * v.y + (double)Q.c * v.z + (double)Q.d;
        /* natural scale: |P| (|u| + 1) */
        n = sqrt((double)P.a * P.a + (double)P.b * P.b + (double)P.c * P.c);
        mag = n * (fabs((double)u.x) + fabs((double)u.y) + fabs((double)u.z)) + fabs((double)P.d);
        worst = dmax(worst, fabs(qv - pu) / (U24 * mag));
    }
    dht_printf("plane invariance max |Q v - P u| / (u |P|(|u|+1)) = %.3f\n", worst);
    DHT_TRUE(worst <= 28.0); /* measured 13.5 (10 seeds) */
}

/* ---- equivalent angle and axis ----------------------------------------- */

/* max |Rot(k, th) - R| with Rot built in double from the outputs */
static double rebuild_err(const dh_mat4_f32 *R, const dh_vec3_f32 *k, float th)
{
    dhr_mat4 D;
    DHT_TRUE(dhr_rot_axis((double)k->x, (double)k->y, (double)k->z, (double)th, &D));
    {
        dh_mat4_f32 R3 = *R;
        int i;
        for (i = 0; i < 3; i++) {
            R3.m[3][i] = 0.0f;
            R3.m[i][3] = 0.0f;
        }
        R3.m[3][3] = 1.0f;
        return dhr_max_abs_diff(&R3, &D);
    }
}

static void axis_angle_round_trips(void)
{
    double w_th = 0.0, w_rebuild = 0.0, w_k = 0.0, w_k_small = 0.0, w_unit = 0.0;
    int it;
    for (it = 0; it < DHT_ITER(30000); it++) {
        double kd[3], th;
        dhr_mat4 D;
        dh_mat4_f32 R;
        dh_vec3_f32 k;
        float tho;
        const int band = it % 4;
        dhr_rand_unit3(kd);
        if (band == 0) th = dht_rand_uniform(0.0, 180.0);
        else if (band == 1) th = dht_rand_uniform(0.0, 1e-3);          /* near 0 */
        else if (band == 2) th = 180.0 - dht_rand_uniform(0.0, 1e-3);  /* near 180 */
        else th = dht_rand_uniform(89.0, 91.0);                        /* branch switch */
        DHT_TRUE(dhr_rot_axis(kd[0], kd[1], kd[2], th, &D));
        dhr_to_f32(&D, &R);
        DHT_EQ_INT(dh_mat4_to_axis_angle_f32(&R, &k, &tho), DH_OK);
        DHT_TRUE(tho >= 0.0f && tho <= 180.0f);
        w_unit = dmax(w_unit, fabs(sqrt((double)k.x * k.x + (double)k.y * k.y + (double)k.z * k.z) - 1.0));
        w_th = dmax(w_th, fabs((double)tho - th));
        w_rebuild = dmax(w_rebuild, rebuild_err(&R, &k, tho));
        {
            /* axis error; at 180 the sign of k is free */
            double e1 = fabs(k.x - kd[0]) + fabs(k.y - kd[1]) + fabs(k.z - kd[2]);
            double e2 = fabs(k.x + kd[0]) + fabs(k.y + kd[1]) + fabs(k.z + kd[2]);
            double e = (th > 179.0 && e2 < e1) ? e2 : e1;
            if (th >= 1.0) w_k = dmax(w_k, e);
            else w_k_small = dmax(w_k_small, e * dhr_deg2rad(th)); /* ill-defined: scaled by theta */
        }
        /* library round trip: Rot(k, theta) -> (k, theta) -> same rotation */
        {
            dh_mat4_f32 R2;
            dh_vec3_f32 k2;
            float th2;
            DHT_EQ_INT(dh_mat4_rot_axis_f32(k.x, k.y, k.z, tho, &R2), DH_OK);
            DHT_EQ_INT(dh_mat4_to_axis_angle_f32(&R2, &k2, &th2), DH_OK);
            w_rebuild = dmax(w_rebuild, rebuild_err(&R2, &k2, th2));
        }
    }
    dht_printf("axis-angle: max |theta err| = %.3g deg, max |Rot(k,th) - R| = %.3g (%.2f u), "
               "max axis err (th >= 1 deg) = %.3g, max axis err * theta_rad (th < 1 deg) = %.3g, "
               "max ||k|-1| = %.3g\n", w_th, w_rebuild, w_rebuild / U24, w_k, w_k_small, w_unit);
    /* measured over 10 seeds: 1.50e-5 deg, 8.34 u, 2.35e-7, 1.88e-9, 1.54e-7 */
    DHT_TRUE(w_th <= 3e-5);
    DHT_TRUE(w_rebuild <= 17.0 * U24);
    DHT_TRUE(w_k <= 5e-7);
    DHT_TRUE(w_k_small <= 4e-9);
    DHT_TRUE(w_unit <= 3.1e-7);
}

static void check_rigid_tolerance_is_honoured(void)
{
    int it;
    for (it = 0; it < DHT_ITER(5000); it++) {
        dh_mat4_f32 T;
        float tol = (float)pow(10.0, dht_rand_uniform(-6.0, -2.0));
        int i = (int)(dht_rand_u32() % 3u), j = (int)(dht_rand_u32() % 3u);
        rand_rigid_f(&T, 10.0);
        DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, 1e-6f), DH_OK);
        /* perturb one entry of R by 4 tol: some dot product moves by ~4 tol |R_ij| >~ tol */
        if (fabsf(DH_M4(&T, i, j)) < 0.5f) continue;
        DH_M4(&T, i, j) += 4.0f * tol * (DH_M4(&T, i, j) > 0 ? 1.0f : -1.0f);
        DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, tol), DH_ERR_NOT_RIGID);
        DHT_EQ_INT(dh_mat4_check_rigid_f32(&T, 16.0f * tol), DH_OK);
    }
}

static const dht_case cases[] = {
    DHT_CASE(rotations_match_reference),
    DHT_CASE(products_match_reference_and_alias),
    DHT_CASE(apply_matches_reference),
    DHT_CASE(rigid_inverse_properties),
    DHT_CASE(general_inverse_accuracy_and_scale_invariance),
    DHT_CASE(general_inverse_fast_paths_accuracy),
    DHT_CASE(general_inverse_decision_scale_invariant),
    DHT_CASE(general_inverse_reports_rank_deficient),
    DHT_CASE(plane_point_invariance),
    DHT_CASE(axis_angle_round_trips),
    DHT_CASE(check_rigid_tolerance_is_honoured),
};
DHT_MAIN(cases)
