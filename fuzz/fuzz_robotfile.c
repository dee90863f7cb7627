/* SPDX-License-Identifier: Apache-2.0 */
/*
 * fuzz_robotfile.c - the CLI's robot-file parser (cli/dh_robotfile.h) on
 * arbitrary bytes, then the library robot built from every file it
 * accepts, and forward kinematics on both paths.
 *
 * Invariants:
 *  - no crash, no read outside the exact-size input copy, no UB;
 *  - dh_robotfile_parse returns 0 or -1; on -1 the message is non-empty,
 *    NUL-terminated, printable ASCII and the line is >= 1;
 *  - on 0: 1 <= n <= DH_MAX_JOINTS, line numbers strictly increasing,
 *    every value finite (float range), min <= max where limits are given,
 *    base/tool texts NUL-terminated at len <= DH_RF_MAX_EXPR and the same
 *    bytes as in the file at (line, col0);
 *  - dh_robotfile_build (float and fixed) returns 0 or -1 with a message;
 *    when it succeeds FK returns a documented status: dh_fk_f32 DH_OK with
 *    a finite frame and bottom row 0 0 0 1, or DH_ERR_OVERFLOW;
 *    dh_fk_q DH_OK, DH_ERR_OVERFLOW, or DH_ERR_UNAVAILABLE when the fixed
 *    path is not prepared;
 *  - when both FKs succeed on a fixed-point build, the rotations agree
 *    within 1e-6 + A 2^-24 pi/180 per joint and per EXPR term, A the
 *    largest number in the file (same reasoning as fuzz_expr.c; a fixed build rejects scale/persp, so base and tool are
 *    rigid on both paths).
 */
#include <ctype.h>
#include <float.h>
#include <math.h>

#include "dh_robotfile.h"
#include "dhmath/robot.h"
#include "fuzz_common.h"

static void check_msg(const char *msg, size_t cap, const char *what)
{
    size_t k, n = 0;
    while (n < cap && msg[n] != '\0') n++;
    FZ_CHECK(n > 0 && n < cap, "%s: message empty or not terminated", what);
    for (k = 0; k < n; k++)
        FZ_CHECK(msg[k] >= 0x20 && msg[k] < 0x7f, "%s: non-printable byte 0x%02x in message", what,
                 (unsigned)(unsigned char)msg[k]);
}

static int finite_f(double v)
{
    return fabs(v) <= (double)FLT_MAX;
}

/* start of 1-based line `line` in buf, or NULL */
static const char *line_start(const char *buf, size_t len, unsigned line, size_t *rest)
{
    size_t k = 0;
    unsigned l = 1;
    while (l < line && k < len) {
        if (buf[k] == '\n') l++;
        k++;
    }
    if (l != line) return NULL;
    *rest = len - k;
    return buf + k;
}

static unsigned count_terms(const char *s, size_t n)
{
    unsigned c = 0;
    size_t k;
    for (k = 0; k < n; k++)
        if (isalpha((unsigned char)s[k]) && (k == 0 || !isalnum((unsigned char)s[k - 1]))) c++;
    return c;
}

static void check_frame_text(const char *buf, size_t len, const dh_rf_frame *f)
{
    size_t rest = 0;
    const char *ls;
    if (!f->present) return;
    FZ_CHECK(f->len > 0 && f->len <= DH_RF_MAX_EXPR && f->text[f->len] == '\0', "frame text len %lu",
             (unsigned long)f->len);
    ls = line_start(buf, len, f->line, &rest);
    FZ_CHECK(ls != NULL && f->col0 + f->len <= rest && memcmp(ls + f->col0, f->text, f->len) == 0,
             "frame text is not the file's bytes at line %u col0 %lu", f->line, (unsigned long)f->col0);
}

static void joint_values(const dh_robotfile *rf, float *q, int32_t *qq)
{
    unsigned k;
    for (k = 0; k < rf->n; k++) {
        /* deterministic joint values: whole/fractional degrees, small lengths */
        q[k] = rf->joint[k].type == DH_JOINT_REVOLUTE ? 37.5f * (float)k - 100.0f : 0.125f * (float)k;
        qq[k] = rf->joint[k].type == DH_JOINT_REVOLUTE ? (int32_t)(q[k] * 65536.0f)
                                                     : (int32_t)(q[k] * (float)DH_QPOS_ONE);
    }
}

/* float FK of a float build (r0); returns its status, frame in *T */
static dh_status fk_float(const dh_robotfile *rf, const dh_robot *r0, dh_mat4_f32 *T)
{
    float q[DH_MAX_JOINTS];
    int32_t qq[DH_MAX_JOINTS];
    dh_status sf;
    joint_values(rf, q, qq);
    sf = dh_fk_f32(r0, q, T);
    FZ_CHECK(sf == DH_OK || sf == DH_ERR_OVERFLOW, "dh_fk_f32 status %d", (int)sf);
    if (sf == DH_OK) {
        unsigned i, j;
        for (i = 0; i < 4u; i++)
            for (j = 0; j < 4u; j++) FZ_CHECK(isfinite(T->m[i][j]), "fk_f32 OK with non-finite m[%u][%u]", i, j);
        FZ_CHECK(T->m[0][3] == 0.0f && T->m[1][3] == 0.0f && T->m[2][3] == 0.0f && T->m[3][3] == 1.0f,
                 "fk_f32 bottom row not 0 0 0 1");
    }
    return sf;
}

/* fixed FK of a fixed build (r1), compared with the float FK of r0 */
static void fk_fixed(const dh_robotfile *rf, const dh_robot *r1, dh_status sf, const dh_mat4_f32 *T, double amax)
{
    float q[DH_MAX_JOINTS];
    int32_t qq[DH_MAX_JOINTS];
    dh_frame_q F;
    dh_mat4_f32 T1;
    dh_status sq, s1;
    joint_values(rf, q, qq);
    sq = dh_fk_q(r1, qq, &F);
    FZ_CHECK(sq == DH_OK || sq == DH_ERR_OVERFLOW || (sq == DH_ERR_UNAVAILABLE && (r1->flags & DH_ROBOT_HAS_Q) == 0u),
             "dh_fk_q status %d", (int)sq);
    /* dh_robot_set_base_q/_tool_q make the float frames of r1 stale
     * (robot.h), so its float path is unavailable when a non-identity
     * base or tool was set; otherwise it behaves as r0's */
    s1 = dh_fk_f32(r1, q, &T1);
    FZ_CHECK(s1 == sf || (s1 == DH_ERR_UNAVAILABLE && (rf->base.present || rf->tool.present)),
             "dh_fk_f32 on the fixed build: status %d, float build %d", (int)s1, (int)sf);
    if (sf == DH_OK && sq == DH_OK) {
        const double tol = (1e-6 + amax * 5.9604644775390625e-8 * (3.14159265358979 / 180.0)) * (double)(rf->n + 1u + count_terms(rf->base.text, rf->base.len) +
                                           count_terms(rf->tool.text, rf->tool.len));
        unsigned i, j;
        for (i = 0; i < 3u; i++)
            for (j = 0; j < 3u; j++) {
                const double d = fabs((double)F.r[i][j] / 1073741824.0 - (double)T->m[i][j]);
                FZ_CHECK(d <= tol, "FK rotation m[%u][%u]: fixed %.9f float %.9f (|d| %.3g > %.3g)", i, j,
                         (double)F.r[i][j] / 1073741824.0, (double)T->m[i][j], d, tol);
            }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *buf = (char *)malloc(size ? size : 1u);
    dh_robotfile *rf = (dh_robotfile *)malloc(sizeof *rf);
    dh_robot *r = (dh_robot *)malloc(sizeof *r);
    dh_rf_error e;
    int res, fixed;
    unsigned k;

    FZ_CHECK(buf != NULL && rf != NULL && r != NULL, "out of memory");
    if (size) memcpy(buf, data, size);

    memset(&e, 0, sizeof e);
    res = dh_robotfile_parse("fuzz.dh", buf, size, rf, &e);
    FZ_CHECK(res == 0 || res == -1, "parse returned %d", res);
    if (res != 0) {
        check_msg(e.msg, sizeof e.msg, "parse");
        FZ_CHECK(e.line >= 1, "error line %u", e.line);
        goto done;
    }
    FZ_CHECK(rf->n >= 1 && rf->n <= (unsigned)DH_MAX_JOINTS, "n = %u", rf->n);
    FZ_CHECK(rf->conv == DH_CONV_STANDARD || rf->conv == DH_CONV_MODIFIED, "conv %d", (int)rf->conv);
    for (k = 0; k < rf->n; k++) {
        const dh_rf_joint *j = &rf->joint[k];
        FZ_CHECK(j->type == DH_JOINT_REVOLUTE || j->type == DH_JOINT_PRISMATIC, "joint %u type", k);
        FZ_CHECK(finite_f(j->a) && finite_f(j->d) && finite_f(j->alpha) && finite_f(j->theta),
                 "joint %u non-finite parameter", k);
        FZ_CHECK(k == 0 || j->line > rf->joint[k - 1].line, "joint %u line %u not increasing", k, j->line);
        if (j->has_limits)
            FZ_CHECK(finite_f(j->qmin) && finite_f(j->qmax) && j->qmin <= j->qmax, "joint %u limits %g %g", k,
                     j->qmin, j->qmax);
    }
    check_frame_text(buf, size, &rf->base);
    check_frame_text(buf, size, &rf->tool);

    {
        dh_mat4_f32 T;
        dh_status sf = DH_ERR_ARG;
        for (fixed = 0; fixed < 2; fixed++) {
            memset(&e, 0, sizeof e);
            res = dh_robotfile_build("fuzz.dh", rf, fixed, r, &e);
            FZ_CHECK(res == 0 || res == -1, "build returned %d", res);
            if (res != 0) {
                check_msg(e.msg, sizeof e.msg, "build");
                FZ_CHECK(fixed == 1 || rf->base.present || rf->tool.present, "float build failed: %s", e.msg);
                break;
            }
            FZ_CHECK(r->n == rf->n, "robot has %u joints, file %u", (unsigned)r->n, rf->n);
            if (fixed == 0) sf = fk_float(rf, r, &T);
            else fk_fixed(rf, r, sf, &T, fz_max_number(buf, size));
        }
    }
done:
    free(r);
    free(rf);
    free(buf);
    return 0;
}
