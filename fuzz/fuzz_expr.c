/* SPDX-License-Identifier: Apache-2.0 */
/*
 * fuzz_expr.c - the CLI's EXPR parser/evaluator (cli/dh_expr.h) on
 * arbitrary bytes.
 *
 * Invariants:
 *  - no crash, no out-of-bounds read (the input is copied into a buffer of
 *    exactly its length, so ASan catches any read past buf[len-1]), no UB;
 *  - both evaluators return 0 or -1; on -1 the error has st != DH_OK,
 *    pos <= len, a non-empty NUL-terminated printable-ASCII message, and
 *    the output is untouched; with err == NULL the result is the same;
 *  - the float result of a successful evaluation is finite everywhere;
 *  - evaluation is deterministic (no hidden state: a second call gives the
 *    same bits);
 *  - a successful fixed-point evaluation implies a successful float one
 *    (the fixed path accepts a subset of EXPR: rigid terms whose values
 *    fit), and the two rotations agree within (1e-6 + A 2^-24 pi/180) per
 *    term, A the largest number in the text: angle rounding to Q16.16 is
 *    1.3e-7 rad, to float at most A 2^-24 degrees (an angle of 32072.72
 *    degrees is 0.001 degree off in float), float and Q2.30 rounding a few
 *    1e-7 per product, and rotation errors add without amplification;
 *  - dh_expr_parse_number on the whole buffer: on success the value equals
 *    strtod of the same text (or is +-FLT_MAX for a text between FLT_MAX
 *    and the float overflow threshold), is within the float range and does
 *    not round to float 0 unless it is 0, and the text uses only the
 *    documented characters; on error *out is untouched.
 */
#include <ctype.h>
#include <float.h>
#include <math.h>

#include "dh_expr.h"
#include "dhmath/frame.h"
#include "fuzz_common.h"

static void check_error(const dh_expr_error *e, size_t len, const char *what)
{
    size_t k, n = 0;
    FZ_CHECK(e->st != DH_OK, "%s: error with st == DH_OK", what);
    FZ_CHECK(e->pos <= len, "%s: error pos %lu > len %lu", what, (unsigned long)e->pos, (unsigned long)len);
    while (n < sizeof e->msg && e->msg[n] != '\0') n++;
    FZ_CHECK(n > 0 && n < sizeof e->msg, "%s: message empty or not terminated", what);
    for (k = 0; k < n; k++)
        FZ_CHECK(e->msg[k] >= 0x20 && e->msg[k] < 0x7f, "%s: non-printable byte 0x%02x in message", what,
                 (unsigned)(unsigned char)e->msg[k]);
}

static unsigned count_terms(const char *buf, size_t len)
{
    unsigned n = 0;
    size_t k;
    for (k = 0; k < len; k++)
        if (isalpha((unsigned char)buf[k]) && (k == 0 || !isalnum((unsigned char)buf[k - 1]))) n++;
    return n;
}

static void check_number(const char *buf, size_t len)
{
    double v = 12345.0;
    const char *why = dh_expr_parse_number(buf, len, &v);
    if (why != NULL) {
        FZ_CHECK(v == 12345.0, "parse_number wrote *out on error");
        FZ_CHECK(why[0] != '\0', "empty parse_number message");
        return;
    }
    {
        char tmp[DH_EXPR_MAX_NUMBER + 1];
        size_t k;
        double r;
        FZ_CHECK(len > 0 && len <= DH_EXPR_MAX_NUMBER, "number of length %lu accepted", (unsigned long)len);
        for (k = 0; k < len; k++)
            FZ_CHECK(strchr("0123456789+-.eE", buf[k]) != NULL && buf[k] != '\0',
                     "number with byte 0x%02x accepted", (unsigned)(unsigned char)buf[k]);
        memcpy(tmp, buf, len);
        tmp[len] = '\0';
        r = strtod(tmp, NULL);
        FZ_CHECK(r == v || (r != r && v != v) || (fabs(r) > (double)FLT_MAX && fabs(v) == (double)FLT_MAX),
                 "'%s': %.17g vs strtod %.17g", tmp, v, r);
        FZ_CHECK(fabs(v) <= (double)FLT_MAX && (v == 0.0 || (float)v != 0.0f), "'%s' = %g out of float range",
                 tmp, v);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    /* exact-size copy: any read past the end is an ASan heap overflow */
    char *buf = (char *)malloc(size ? size : 1u);
    dh_mat4_f32 Tf, Tf2, sentinel_f;
    dh_frame_q Fq, Fq2, sentinel_q;
    dh_expr_error e;
    int rf, rq, r2;

    FZ_CHECK(buf != NULL, "out of memory");
    if (size) memcpy(buf, data, size);

    memset(&sentinel_f, 0xa5, sizeof sentinel_f);
    memset(&sentinel_q, 0xa5, sizeof sentinel_q);

    Tf = sentinel_f;
    memset(&e, 0, sizeof e);
    rf = dh_expr_eval_f32(buf, size, &Tf, &e);
    FZ_CHECK(rf == 0 || rf == -1, "eval_f32 returned %d", rf);
    Tf2 = sentinel_f;
    r2 = dh_expr_eval_f32(buf, size, &Tf2, NULL);
    FZ_CHECK(r2 == rf && memcmp(&Tf, &Tf2, sizeof Tf) == 0, "eval_f32 not deterministic / differs with err NULL");
    if (rf) {
        check_error(&e, size, "eval_f32");
        FZ_CHECK(memcmp(&Tf, &sentinel_f, sizeof Tf) == 0, "eval_f32 wrote out on error");
    } else {
        unsigned i, j;
        for (i = 0; i < 4u; i++)
            for (j = 0; j < 4u; j++)
                FZ_CHECK(isfinite(Tf.m[i][j]), "eval_f32 OK with non-finite element m[%u][%u]", i, j);
    }

    Fq = sentinel_q;
    memset(&e, 0, sizeof e);
    rq = dh_expr_eval_q(buf, size, &Fq, &e);
    FZ_CHECK(rq == 0 || rq == -1, "eval_q returned %d", rq);
    Fq2 = sentinel_q;
    r2 = dh_expr_eval_q(buf, size, &Fq2, NULL);
    FZ_CHECK(r2 == rq && memcmp(&Fq, &Fq2, sizeof Fq) == 0, "eval_q not deterministic / differs with err NULL");
    if (rq) {
        check_error(&e, size, "eval_q");
        FZ_CHECK(memcmp(&Fq, &sentinel_q, sizeof Fq) == 0, "eval_q wrote out on error");
    } else {
        const double tol = (1e-6 + fz_max_number(buf, size) * 5.9604644775390625e-8 * (3.14159265358979 / 180.0)) *
                           (double)(count_terms(buf, size) + 1u);
        unsigned i, j;
        FZ_CHECK(rf == 0, "fixed-point EXPR accepted but float rejected it");
        for (i = 0; i < 3u; i++)
            for (j = 0; j < 3u; j++) {
                const double d = fabs((double)Fq.r[i][j] / 1073741824.0 - (double)Tf.m[i][j]);
                FZ_CHECK(d <= tol, "rotation entry m[%u][%u]: fixed %.9f float %.9f (|d| %.3g > %.3g)", i, j,
                         (double)Fq.r[i][j] / 1073741824.0, (double)Tf.m[i][j], d, tol);
            }
    }

    check_number(buf, size);
    free(buf);
    return 0;
}
