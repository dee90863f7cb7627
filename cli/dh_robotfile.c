/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_robotfile.c - robot file parser of the dhmath host tool (see
 * dh_robotfile.h). Line by line over the caller's buffer; no heap.
 */
#include "dh_robotfile.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "dh_expr.h"
#include "dhmath/mat4.h"

typedef struct {
    const char *name;
    dh_rf_error *err;
    const dh_robotfile *rf;   /* the description being built (NULL while parsing) */
} ctx;

static int is_blank(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/* printable copy of s[0..n) with \xNN escapes, truncated */

#if defined(__GNUC__)
__attribute__((format(printf, 4, 5)))
#endif
static int fail(const ctx *c, unsigned line, size_t col, const char *fmt, ...)
{
    if (c->err) {
        char text[200];
        va_list ap;
        va_start(ap, fmt);
        (void)vsnprintf(text, sizeof text, fmt, ap);
        va_end(ap);
        c->err->line = line;
        c->err->col = col;
        if (col)
            (void)snprintf(c->err->msg, sizeof c->err->msg, "%.80s:%u:%lu: %s", c->name, line,
                           (unsigned long)col, text);
        else
            (void)snprintf(c->err->msg, sizeof c->err->msg, "%.80s:%u: %s", c->name, line, text);
    }
    return -1;
}

static int tok_is(const char *s, size_t n, const char *word)
{
    return strlen(word) == n && memcmp(s, word, n) == 0;
}

/* next token of line[*i..n): returns its length, start in *s */
static size_t next_tok(const char *line, size_t n, size_t *i, size_t *s)
{
    while (*i < n && is_blank(line[*i])) (*i)++;
    *s = *i;
    while (*i < n && !is_blank(line[*i])) (*i)++;
    return *i - *s;
}

static int parse_joint(const ctx *c, dh_robotfile *rf, const char *line, size_t n, size_t i,
                       unsigned lineno, size_t kw_col)
{
    static const char *const keys[] = { "a", "d", "alpha", "theta", "min", "max", "vmax", "amax" };
    int seen[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
    double val[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
    size_t s, tl;
    dh_rf_joint *j;
    char q[160];

    if (rf->n >= (unsigned)DH_MAX_JOINTS)
        return fail(c, lineno, kw_col, "too many joints (this build holds at most %d, DH_MAX_JOINTS)",
                    DH_MAX_JOINTS);
    j = &rf->joint[rf->n];
    tl = next_tok(line, n, &i, &s);
    if (tl == 0) return fail(c, lineno, kw_col, "joint: missing type R or P");
    if (tok_is(line + s, tl, "R")) j->type = DH_JOINT_REVOLUTE;
    else if (tok_is(line + s, tl, "P")) j->type = DH_JOINT_PRISMATIC;
    else {
        dh_expr_quote(q, sizeof q, line + s, tl, 32u);
        return fail(c, lineno, s + 1, "joint: type must be R or P, not '%s'", q);
    }
    for (;;) {
        size_t eq, k, key = 8;
        const char *why;
        tl = next_tok(line, n, &i, &s);
        if (tl == 0) break;
        for (eq = 0; eq < tl && line[s + eq] != '='; eq++) { }
        if (eq == tl) {
            dh_expr_quote(q, sizeof q, line + s, tl, 32u);
            return fail(c, lineno, s + 1, "joint: expected key=value, got '%s'", q);
        }
        for (k = 0; k < 8u; k++)
            if (tok_is(line + s, eq, keys[k])) key = k;
        if (key == 8u) {
            dh_expr_quote(q, sizeof q, line + s, eq, 32u);
            return fail(c, lineno, s + 1, "joint: unknown key '%s' (keys: a d alpha theta min max vmax amax)", q);
        }
        if (seen[key]) return fail(c, lineno, s + 1, "joint: duplicate key '%s'", keys[key]);
        seen[key] = 1;
        why = dh_expr_parse_number(line + s + eq + 1, tl - eq - 1, &val[key]);
        if (why) {
            dh_expr_quote(q, sizeof q, line + s + eq + 1, tl - eq - 1, 32u);
            return fail(c, lineno, s + eq + 2, "joint: bad number '%s' for '%s': %s", q, keys[key], why);
        }
        if (key >= 6u && !(val[key] > 0.0))
            return fail(c, lineno, s + eq + 2, "joint: '%s' must be greater than 0, not %.9g", keys[key], val[key]);
    }
    if (seen[4] != seen[5])
        return fail(c, lineno, kw_col, "joint: '%s' given without '%s'", seen[4] ? "min" : "max",
                    seen[4] ? "max" : "min");
    if (seen[4] && val[4] > val[5])
        return fail(c, lineno, kw_col, "joint: min=%.9g is greater than max=%.9g", val[4], val[5]);
    j->a = val[0];
    j->d = val[1];
    j->alpha = val[2];
    j->theta = val[3];
    j->qmin = val[4];
    j->qmax = val[5];
    j->has_limits = seen[4];
    j->vmax = seen[6] ? val[6] : 0.0;
    j->amax = seen[7] ? val[7] : 0.0;
    j->line = lineno;
    rf->n++;
    return 0;
}

static int parse_frame(const ctx *c, dh_rf_frame *f, const char *kw, const char *line, size_t n,
                       size_t i, unsigned lineno, size_t kw_col)
{
    dh_expr_error e;
    dh_mat4_f32 T;
    size_t end = n;
    if (f->present)
        return fail(c, lineno, kw_col, "duplicate '%s' (first given on line %u)", kw, f->line);
    while (i < end && is_blank(line[i])) i++;
    while (end > i && is_blank(line[end - 1])) end--;
    if (end == i) return fail(c, lineno, kw_col, "'%s' needs an EXPR", kw);
    if (end - i > DH_RF_MAX_EXPR)
        return fail(c, lineno, i + 1, "'%s' EXPR longer than %d characters", kw, DH_RF_MAX_EXPR);
    if (dh_expr_eval_f32(line + i, end - i, &T, &e))
        return fail(c, lineno, i + e.pos + 1, "bad %s EXPR: %s", kw, e.msg);
    memcpy(f->text, line + i, end - i);
    f->text[end - i] = '\0';
    f->len = end - i;
    f->col0 = i;
    f->line = lineno;
    f->present = 1;
    return 0;
}

int dh_robotfile_parse(const char *name, const char *buf, size_t len, dh_robotfile *rf,
                       dh_rf_error *err)
{
    ctx c;
    size_t pos = 0;
    unsigned lineno = 0;
    int conv_seen = 0;
    unsigned conv_line = 0;

    c.name = name ? name : "<robot>";
    c.err = err;
    c.rf = NULL;
    memset(rf, 0, sizeof *rf);
    rf->conv = DH_CONV_STANDARD;
    if (!buf) len = 0;

    while (pos < len) {
        const char *line = buf + pos;
        size_t n = 0, i = 0, s, tl;
        char q[160];
        lineno++;
        while (pos + n < len && buf[pos + n] != '\n') n++;
        pos += n + 1; /* past the newline (or past the end) */
        /* strip comment */
        {
            size_t k;
            for (k = 0; k < n; k++)
                if (line[k] == '#') { n = k; break; }
        }
        tl = next_tok(line, n, &i, &s);
        if (tl == 0) continue;
        if (tok_is(line + s, tl, "convention")) {
            size_t s2, t2 = next_tok(line, n, &i, &s2), s3;
            if (conv_seen)
                return fail(&c, lineno, s + 1, "duplicate 'convention' (first given on line %u)", conv_line);
            if (rf->n > 0)
                return fail(&c, lineno, s + 1, "'convention' must come before the first joint");
            if (t2 == 0) return fail(&c, lineno, s + 1, "'convention' needs standard or modified");
            if (tok_is(line + s2, t2, "standard")) rf->conv = DH_CONV_STANDARD;
            else if (tok_is(line + s2, t2, "modified")) rf->conv = DH_CONV_MODIFIED;
            else {
                dh_expr_quote(q, sizeof q, line + s2, t2, 32u);
                return fail(&c, lineno, s2 + 1, "unknown convention '%s' (standard or modified)", q);
            }
            if (next_tok(line, n, &i, &s3) != 0) {
                dh_expr_quote(q, sizeof q, line + s3, n - s3, 32u);
                return fail(&c, lineno, s3 + 1, "unexpected '%s' after the convention", q);
            }
            conv_seen = 1;
            conv_line = lineno;
        } else if (tok_is(line + s, tl, "joint")) {
            if (parse_joint(&c, rf, line, n, i, lineno, s + 1)) return -1;
        } else if (tok_is(line + s, tl, "base")) {
            if (parse_frame(&c, &rf->base, "base", line, n, i, lineno, s + 1)) return -1;
        } else if (tok_is(line + s, tl, "tool")) {
            if (parse_frame(&c, &rf->tool, "tool", line, n, i, lineno, s + 1)) return -1;
        } else {
            dh_expr_quote(q, sizeof q, line + s, tl, 32u);
            return fail(&c, lineno, s + 1,
                        "unknown keyword '%s' (convention, joint, base, tool)", q);
        }
    }
    if (rf->n == 0) return fail(&c, lineno ? lineno : 1u, 0, "no 'joint' lines");
    return 0;
}

static int build_frame(const ctx *c, const dh_rf_frame *f, const char *kw, int fixed, dh_robot *r)
{
    dh_expr_error e;
    dh_status st;
    dh_mat4_f32 T;
    if (!f->present) return 0;
    if (dh_expr_eval_f32(f->text, f->len, &T, &e))
        return fail(c, f->line, f->col0 + e.pos + 1, "bad %s EXPR: %s", kw, e.msg);
    st = (kw[0] == 'b') ? dh_robot_set_base_f32(r, &T) : dh_robot_set_tool_f32(r, &T);
    if (st != DH_OK) return fail(c, f->line, 0, "%s: rejected by the library: %s", kw, dh_status_str(st));
    if (fixed) {
        dh_frame_q F;
        if (dh_expr_eval_q(f->text, f->len, &F, &e))
            return fail(c, f->line, f->col0 + e.pos + 1, "bad %s EXPR (--fixed): %s", kw, e.msg);
        st = (kw[0] == 'b') ? dh_robot_set_base_q(r, &F) : dh_robot_set_tool_q(r, &F);
        if (st != DH_OK)
            return fail(c, f->line, 0, "%s (--fixed): rejected by the library: %s", kw,
                        dh_status_str(st));
    }
    return 0;
}

/* With --fixed: the first constant of joint k (0-based) that has no
 * fixed-point form, named with its value and the format it misses (the
 * rule of dh_robot_add_joint_f32: |a|, |d| < 2^(31-DH_QPOS_FRAC) units,
 * |alpha|, |theta| < 32768 deg, on the float values stored). */
static int joint_q_error(const ctx *c, const dh_robot *r, unsigned k)
{
    static const char *const names[4] = { "a", "d", "alpha", "theta" };
    const dh_joint *j = &r->joint[k];
    const dh_rf_joint *fj = &c->rf->joint[k];
    const float v[4] = { j->a, j->d, j->alpha_deg, j->theta_deg };
    const double given[4] = { fj->a, fj->d, fj->alpha, fj->theta };
    unsigned i;
    for (i = 0; i < 4u; i++) {
        const int len = i < 2u;
        const float lim = len ? (float)(1L << (31 - DH_QPOS_FRAC)) : 32768.0f;
        char as_float[40] = "";
        if (!(v[i] >= lim || v[i] < -lim)) continue;
        if ((double)v[i] != given[i]) (void)snprintf(as_float, sizeof as_float, " (%.9g in float)", (double)v[i]);
        return fail(c, fj->line, 0,
                    "joint %u: %s=%.15g%s does not fit the fixed-point %s Q%d.%d of --fixed "
                    "(it needs %g <= %s < %g%s)",
                    k + 1u, names[i], given[i], as_float, len ? "length format" : "angle format (degrees)",
                    len ? 32 - DH_QPOS_FRAC : 16, len ? DH_QPOS_FRAC : 16, -(double)lim, names[i],
                    (double)lim, len ? " length units" : " deg");
    }
    return fail(c, fj->line, 0, "joint %u: a constant does not fit the fixed-point formats of --fixed", k + 1u);
}

int dh_robotfile_build(const char *name, const dh_robotfile *rf, int fixed, dh_robot *r,
                       dh_rf_error *err)
{
    ctx c;
    unsigned k;
    dh_status st;
    c.name = name ? name : "<robot>";
    c.err = err;
    c.rf = rf;
    st = dh_robot_init(r, rf->conv);
    if (st != DH_OK) return fail(&c, 1u, 0, "robot: %s", dh_status_str(st));
    for (k = 0; k < rf->n; k++) {
        const dh_rf_joint *j = &rf->joint[k];
        st = dh_robot_add_joint_f32(r, j->type, (float)j->theta, (float)j->d, (float)j->a,
                                    (float)j->alpha);
        if (st != DH_OK) return fail(&c, j->line, 0, "joint rejected by the library: %s", dh_status_str(st));
        if (fixed && (r->flags & DH_ROBOT_Q_NO_JOINT) != 0u) return joint_q_error(&c, r, k);
        if (j->has_limits) {
            st = dh_robot_set_limits_f32(r, k, (float)j->qmin, (float)j->qmax);
            if (st != DH_OK)
                return fail(&c, j->line, 0, "joint limits rejected by the library: %s", dh_status_str(st));
        }
        if (j->vmax > 0.0 || j->amax > 0.0) {
            /* an absent key is unlimited */
            const float inf = (float)HUGE_VAL;
            st = dh_robot_set_rates_f32(r, k, j->vmax > 0.0 ? (float)j->vmax : inf,
                                        j->amax > 0.0 ? (float)j->amax : inf);
            if (st != DH_OK)
                return fail(&c, j->line, 0, "joint rate limits rejected by the library: %s", dh_status_str(st));
        }
    }
    if (build_frame(&c, &rf->base, "base", fixed, r)) return -1;
    if (build_frame(&c, &rf->tool, "tool", fixed, r)) return -1;
    return 0;
}
