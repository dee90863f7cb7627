/* SPDX-License-Identifier: Apache-2.0 */
/*
 * accuracy_data.c - writes the CSV data behind the plots in docs/generated/img/ and
 * docs/generated/accuracy_plots.md (run by tools/plot_accuracy.py).
 *
 * Usage: accuracy_data OUTDIR
 *
 * Files written:
 *  trig_sweep.csv  every angle k/4096 degree in [-720, 720] (5.9 million,
 *                  exactly representable in float, Q16.16 and the same for
 *                  all methods), max |error| of sin and cos per 0.25-degree
 *                  bin for: dh_sincos_f32, dh_sincos_q, glibc sinf/cosf of
 *                  r = deg * (float)(pi/180), libfixmath fix16_sin/cos of the
 *                  radian value rounded to fix16 in double (the most
 *                  favourable input for the peer).
 *  trig_large.csv  |deg| log-spaced 1 .. 1e7 (20 bins per decade, 4000 random
 *                  floats each, both signs): max |error| per bin for the
 *                  same methods, each within its input range (Q16.16
 *                  degrees < 32768; fix16 radians < 32768).
 *  fk_err.csv      robot,path,err_mm,err_impl_mm: position error of the end
 *                  frame for 100000 random configurations within the joint
 *                  limits, Puma 560 and UR5 built in mm, float and fixed
 *                  path. err_mm is against the double FK of the nominal DH
 *                  table at the exact joint values the path received
 *                  (end to end, includes the rounding of the DH constants);
 *                  err_impl_mm against the double FK of the constants as
 *                  the dh_robot stores them (the implementation error alone).
 *  summary.csv     key,value: the maxima quoted in docs/generated/accuracy_plots.md.
 *
 * References: libm sin/cos in double of the exactly reduced angle
 * (fmod(deg, 360) is exact), errors in units of 1.0.
 */
#include "bench_common.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dhmath/dhmath.h"

#if BENCH_HAVE_FIXMATH
#include <libfixmath/fix16.h>
#endif

#define PI_D 3.14159265358979323846
#define NAN_ERR (-1.0) /* written as empty: method not applicable */

static void ref_sincos(double deg, double *s, double *c)
{
    double r = fmod(deg, 360.0) * (PI_D / 180.0);
    *s = sin(r);
    *c = cos(r);
}

static double e2(double s, double c, double rs, double rc)
{
    double a = fabs(s - rs), b = fabs(c - rc);
    return a > b ? a : b;
}

static double err_dh_f32(float x, double rs, double rc)
{
    float s, c;
    (void)dh_sincos_f32(x, &s, &c);
    return e2(s, c, rs, rc);
}

static double err_glibc(float x, double rs, double rc)
{
    float r = x * (float)(PI_D / 180.0);
    return e2(sinf(r), cosf(r), rs, rc);
}

static double err_dh_q(dh_q16 x, double rs, double rc)
{
    dh_q30 s, c;
    dh_sincos_q(x, &s, &c);
    return e2(s / 1073741824.0, c / 1073741824.0, rs, rc);
}

#if BENCH_HAVE_FIXMATH
static double err_fix16(double deg, double rs, double rc)
{
    fix16_t r = (fix16_t)floor(deg * (PI_D / 180.0) * 65536.0 + 0.5);
    return e2(fix16_sin(r) / 65536.0, fix16_cos(r) / 65536.0, rs, rc);
}
#endif

static FILE *open_out(const char *dir, const char *name)
{
    char path[1024];
    FILE *f;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    f = fopen(path, "w");
    if (f == NULL) {
        perror(path);
        exit(1);
    }
    return f;
}

static void put_err(FILE *f, double e)
{
    if (e < 0.0) fprintf(f, ",");
    else fprintf(f, ",%.4e", e);
}

/* ---- trig ------------------------------------------------------------------ */

#define M_DH_F32 0
#define M_DH_Q 1
#define M_GLIBC 2
#define M_FIX16 3
#define N_METH 4
static const char *meth_name[N_METH] = { "dh_f32", "dh_q", "glibc", "fix16" };

static void trig_sweep(const char *dir, double sweep_max[N_METH])
{
    const long steps = 4096, lo = -720L * steps, hi = 720L * steps, per_bin = steps / 4;
    FILE *f = open_out(dir, "trig_sweep.csv");
    long k;
    double bin[N_METH];
    int m;
    fprintf(f, "deg,dh_f32,dh_q,glibc,fix16\n");
    for (m = 0; m < N_METH; m++) {
        sweep_max[m] = 0.0;
        bin[m] = 0.0;
    }
    for (k = lo; k < hi; k++) {
        double d = (double)k / (double)steps, rs, rc, e[N_METH];
        ref_sincos(d, &rs, &rc);
        e[M_DH_F32] = err_dh_f32((float)d, rs, rc);
        e[M_DH_Q] = err_dh_q((dh_q16)(k * (65536L / steps)), rs, rc);
        e[M_GLIBC] = err_glibc((float)d, rs, rc);
#if BENCH_HAVE_FIXMATH
        e[M_FIX16] = err_fix16(d, rs, rc);
#else
        e[M_FIX16] = NAN_ERR;
#endif
        for (m = 0; m < N_METH; m++) {
            if (e[m] > bin[m]) bin[m] = e[m];
            if (e[m] > sweep_max[m]) sweep_max[m] = e[m];
        }
        if ((k - lo + 1) % per_bin == 0) {
            fprintf(f, "%.4f", ((double)(k + 1) - per_bin / 2.0) / (double)steps);
            for (m = 0; m < N_METH; m++) {
                put_err(f, (m == M_FIX16 && !BENCH_HAVE_FIXMATH) ? NAN_ERR : bin[m]);
                bin[m] = 0.0;
            }
            fprintf(f, "\n");
        }
    }
    fclose(f);
}

static void trig_large(const char *dir, double large_max[N_METH], double glibc_at_1e4[1])
{
    FILE *f = open_out(dir, "trig_large.csv");
    uint64_t rng = 0x243F6A8885A308D3ULL;
    int b, m;
    fprintf(f, "deg_lo,deg_hi,dh_f32,dh_q,glibc,fix16\n");
    for (m = 0; m < N_METH; m++) large_max[m] = 0.0;
    glibc_at_1e4[0] = 0.0;
    for (b = 0; b < 140; b++) {
        double lo = pow(10.0, b / 20.0), hi = pow(10.0, (b + 1) / 20.0), mx[N_METH] = { 0, 0, 0, 0 };
        int have_q = hi <= 32767.0, have_fx = hi * (PI_D / 180.0) < 32767.0;
        int n;
        for (n = 0; n < 4000; n++) {
            float x = (float)exp(bench_rand(&rng, log(lo), log(hi)));
            double d, rs, rc, e;
            if (n & 1) x = -x;
            d = (double)x;
            ref_sincos(d, &rs, &rc);
            e = err_dh_f32(x, rs, rc);
            if (e > mx[M_DH_F32]) mx[M_DH_F32] = e;
            e = err_glibc(x, rs, rc);
            if (e > mx[M_GLIBC]) mx[M_GLIBC] = e;
            if (have_q) {
                /* the float angle rounded to Q16.16; reference at that value */
                dh_q16 xq = (dh_q16)floor(d * 65536.0 + 0.5);
                double rsq, rcq;
                ref_sincos(xq / 65536.0, &rsq, &rcq);
                e = err_dh_q(xq, rsq, rcq);
                if (e > mx[M_DH_Q]) mx[M_DH_Q] = e;
            }
#if BENCH_HAVE_FIXMATH
            if (have_fx) {
                e = err_fix16(d, rs, rc);
                if (e > mx[M_FIX16]) mx[M_FIX16] = e;
            }
#endif
        }
        fprintf(f, "%.6g,%.6g", lo, hi);
        put_err(f, mx[M_DH_F32]);
        put_err(f, have_q ? mx[M_DH_Q] : NAN_ERR);
        put_err(f, mx[M_GLIBC]);
        put_err(f, (have_fx && BENCH_HAVE_FIXMATH) ? mx[M_FIX16] : NAN_ERR);
        fprintf(f, "\n");
        for (m = 0; m < N_METH; m++)
            if (mx[m] > large_max[m]) large_max[m] = mx[m];
        if (hi <= 1.0001e4 && mx[M_GLIBC] > glibc_at_1e4[0]) glibc_at_1e4[0] = mx[M_GLIBC];
    }
    fclose(f);
}

/* ---- FK ---------------------------------------------------------------------- */

static void build(dh_robot *r, const bench_dh_robot *d, double scale)
{
    unsigned i;
    int ok = dh_robot_init(r, DH_CONV_STANDARD) == DH_OK;
    for (i = 0; i < d->n && ok; i++)
        ok = dh_robot_add_joint_f32(r, DH_JOINT_REVOLUTE, (float)d->j[i].theta_deg, (float)(d->j[i].d * scale),
                                    (float)(d->j[i].a * scale), (float)d->j[i].alpha_deg) == DH_OK;
    if (!ok || (r->flags & DH_ROBOT_HAS_Q) == 0u) {
        fprintf(stderr, "cannot build %s\n", d->name);
        exit(1);
    }
}

typedef struct {
    double max_e2e[2], max_impl[2], sum_e2e[2];
} fk_stats;

static void fk_robot(FILE *f, const bench_dh_robot *d, fk_stats *st, int n_cfg)
{
    dh_robot r;
    uint64_t rng = 0x13198A2E03707344ULL;
    double a_f[6], d_f[6], al_f[6], th_f[6], a_q[6], d_q[6], al_q[6], th_q[6];
    const double qs = (double)(1L << DH_QPOS_FRAC);
    unsigned i;
    int n, p;
    build(&r, d, 1000.0);
    for (i = 0; i < d->n; i++) {
        const dh_joint *j = &r.joint[i];
        a_f[i] = j->a;
        d_f[i] = j->d;
        al_f[i] = j->alpha_deg;
        th_f[i] = j->theta_deg;
        a_q[i] = j->a_q / qs;
        d_q[i] = j->d_q / qs;
        al_q[i] = j->alpha_q / 65536.0;
        th_q[i] = j->theta_q / 65536.0;
    }
    memset(st, 0, sizeof *st);
    for (n = 0; n < n_cfg; n++) {
        double q[6], qf_d[6], qq_d[6], R[4][4], Ri[4][4];
        float qf[6];
        int32_t qq[6];
        dh_mat4_f32 T;
        dh_frame_q F;
        double e[2], ei[2];
        for (i = 0; i < d->n; i++) {
            q[i] = bench_rand(&rng, d->j[i].qmin, d->j[i].qmax);
            qf[i] = (float)q[i];
            qf_d[i] = qf[i];
            qq[i] = (int32_t)floor(q[i] * 65536.0 + 0.5);
            qq_d[i] = qq[i] / 65536.0;
        }
        if (dh_fk_f32(&r, qf, &T) != DH_OK || dh_fk_q(&r, qq, &F) != DH_OK) {
            fprintf(stderr, "FK failed on %s\n", d->name);
            exit(1);
        }
        /* float path */
        bench_ref_fk(d, 1000.0, qf_d, R);
        bench_ref_fk_params(d->n, a_f, d_f, al_f, th_f, qf_d, Ri);
        e[0] = ei[0] = 0.0;
        for (p = 0; p < 3; p++) {
            e[0] = fmax(e[0], fabs((double)T.m[3][p] - R[3][p]));
            ei[0] = fmax(ei[0], fabs((double)T.m[3][p] - Ri[3][p]));
        }
        /* fixed path */
        bench_ref_fk(d, 1000.0, qq_d, R);
        bench_ref_fk_params(d->n, a_q, d_q, al_q, th_q, qq_d, Ri);
        e[1] = ei[1] = 0.0;
        for (p = 0; p < 3; p++) {
            e[1] = fmax(e[1], fabs(F.p[p] / qs - R[3][p]));
            ei[1] = fmax(ei[1], fabs(F.p[p] / qs - Ri[3][p]));
        }
        for (p = 0; p < 2; p++) {
            fprintf(f, "%s,%s,%.4e,%.4e\n", d->name, p == 0 ? "float" : "fixed", e[p], ei[p]);
            st->max_e2e[p] = fmax(st->max_e2e[p], e[p]);
            st->max_impl[p] = fmax(st->max_impl[p], ei[p]);
            st->sum_e2e[p] += e[p];
        }
    }
}

int main(int argc, char **argv)
{
    double sweep_max[N_METH], large_max[N_METH], g1e4;
    fk_stats puma, ur5;
    const int n_cfg = 100000;
    FILE *f, *s;
    int m;
    if (argc != 2) {
        fprintf(stderr, "usage: %s OUTDIR\n", argv[0]);
        return 2;
    }
    trig_sweep(argv[1], sweep_max);
    trig_large(argv[1], large_max, &g1e4);
    f = open_out(argv[1], "fk_err.csv");
    fprintf(f, "robot,path,err_mm,err_impl_mm\n");
    fk_robot(f, &bench_puma560, &puma, n_cfg);
    fk_robot(f, &bench_ur5, &ur5, n_cfg);
    fclose(f);

    s = open_out(argv[1], "summary.csv");
    fprintf(s, "key,value\n");
    fprintf(s, "have_fixmath,%d\n", BENCH_HAVE_FIXMATH);
    fprintf(s, "sweep_points,%ld\n", 1440L * 4096L);
    for (m = 0; m < N_METH; m++) {
        fprintf(s, "sweep_max_%s,%.4e\n", meth_name[m], sweep_max[m]);
        fprintf(s, "large_max_%s,%.4e\n", meth_name[m], large_max[m]);
    }
    fprintf(s, "large_max_glibc_upto_1e4,%.4e\n", g1e4);
    fprintf(s, "fk_configs,%d\n", n_cfg);
    fprintf(s, "fk_qpos_frac,%d\n", DH_QPOS_FRAC);
    fprintf(s, "fk_puma_float_max_mm,%.4e\nfk_puma_fixed_max_mm,%.4e\n", puma.max_e2e[0], puma.max_e2e[1]);
    fprintf(s, "fk_puma_float_mean_mm,%.4e\nfk_puma_fixed_mean_mm,%.4e\n", puma.sum_e2e[0] / n_cfg,
            puma.sum_e2e[1] / n_cfg);
    fprintf(s, "fk_puma_float_impl_max_mm,%.4e\nfk_puma_fixed_impl_max_mm,%.4e\n", puma.max_impl[0],
            puma.max_impl[1]);
    fprintf(s, "fk_ur5_float_max_mm,%.4e\nfk_ur5_fixed_max_mm,%.4e\n", ur5.max_e2e[0], ur5.max_e2e[1]);
    fprintf(s, "fk_ur5_float_mean_mm,%.4e\nfk_ur5_fixed_mean_mm,%.4e\n", ur5.sum_e2e[0] / n_cfg,
            ur5.sum_e2e[1] / n_cfg);
    fprintf(s, "fk_ur5_float_impl_max_mm,%.4e\nfk_ur5_fixed_impl_max_mm,%.4e\n", ur5.max_impl[0],
            ur5.max_impl[1]);
    fclose(s);
    return 0;
}
