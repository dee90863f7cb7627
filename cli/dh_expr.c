/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_expr.c - EXPR parser/evaluator of the dhmath host tool (see dh_expr.h).
 *
 * One pass over the buffer with an explicit stack of partial products: a
 * term multiplies the product on top of the stack, "inv(" pushes an
 * identity, the matching ")" pops, inverts and multiplies into the level
 * below. No recursion, no heap, no globals.
 */
#include "dh_expr.h"

#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dhmath/frame.h"
#include "dhmath/mat4.h"

/* ---- term table ---------------------------------------------------- */

typedef enum {
    T_IDENT, T_TRANS, T_ROTX, T_ROTY, T_ROTZ, T_ROT, T_SCALE, T_PERSP, T_INV
} term_kind;

typedef struct {
    const char *name;
    term_kind kind;
    unsigned nargs;
    const char *args; /* for the arity message */
} term_info;

static const term_info k_terms[] = {
    { "ident", T_IDENT, 0u, "" },
    { "trans", T_TRANS, 3u, "x,y,z" },
    { "rotx", T_ROTX, 1u, "deg" },
    { "roty", T_ROTY, 1u, "deg" },
    { "rotz", T_ROTZ, 1u, "deg" },
    { "rot", T_ROT, 4u, "kx,ky,kz,deg" },
    { "scale", T_SCALE, 3u, "sx,sy,sz" },
    { "persp", T_PERSP, 2u, "x|y|z,f" },
    { "inv", T_INV, 1u, "EXPR" },
};

#define MAX_ARGS 4u

/* ---- parser state -------------------------------------------------- */

typedef struct {
    const char *buf;
    size_t len;
    size_t i;
    int fixed;
    dh_expr_error *err;
    unsigned depth;                               /* 0 = top level */
    dh_mat4_f32 acc_f[DH_EXPR_MAX_DEPTH + 1];
    dh_frame_q acc_q[DH_EXPR_MAX_DEPTH + 1];
    size_t open_pos[DH_EXPR_MAX_DEPTH + 1];       /* offset of "inv" of each level */
    int has_term[DH_EXPR_MAX_DEPTH + 1];
} parser;

static int is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

static int is_alpha(char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}

static int is_digit(char c)
{
    return c >= '0' && c <= '9';
}

static char lower(char c)
{
    return (c >= 'A' && c <= 'Z') ? (char)(c - 'A' + 'a') : c;
}

void dh_expr_quote(char *dst, size_t cap, const char *s, size_t n, size_t shown_max)
{
    size_t o = 0, k;
    for (k = 0; k < n && k < shown_max; k++) {
        unsigned char c = (unsigned char)s[k];
        if (c >= 0x20 && c < 0x7f && c != '\'') {
            if (o + 2 > cap) break;
            dst[o++] = (char)c;
        } else {
            if (o + 5 > cap) break;
            (void)snprintf(dst + o, cap - o, "\\x%02x", (unsigned)c);
            o += 4;
        }
    }
    if (k < n && o + 4 <= cap) {
        memcpy(dst + o, "...", 3);
        o += 3;
    }
    dst[o < cap ? o : cap - 1] = '\0';
}

#if defined(__GNUC__)
__attribute__((format(printf, 4, 5)))
#endif
static int fail(parser *p, size_t pos, dh_status st, const char *fmt, ...)
{
    if (p->err) {
        va_list ap;
        p->err->pos = pos;
        p->err->st = st;
        va_start(ap, fmt);
        (void)vsnprintf(p->err->msg, sizeof p->err->msg, fmt, ap);
        va_end(ap);
    }
    return -1;
}

static void skip_space(parser *p)
{
    while (p->i < p->len && is_space(p->buf[p->i])) p->i++;
}

/* ---- numbers ------------------------------------------------------- */

static int ieq(const char *s, size_t n, const char *word)
{
    size_t k;
    if (strlen(word) != n) return 0;
    for (k = 0; k < n; k++)
        if (lower(s[k]) != word[k]) return 0;
    return 1;
}

const char *dh_expr_parse_number(const char *buf, size_t len, double *out)
{
    char tmp[DH_EXPR_MAX_NUMBER + 1];
    size_t i = 0, int_digits = 0, frac_digits = 0;
    char *end = NULL;
    double v;

    if (len == 0) return "empty number";
    if (buf[0] == '+' || buf[0] == '-') i = 1;
    if (ieq(buf + i, len - i, "nan") || ieq(buf + i, len - i, "inf") ||
        ieq(buf + i, len - i, "infinity"))
        return "NaN and Inf are not allowed";
    if (len > DH_EXPR_MAX_NUMBER) return "number too long";
    while (i < len && is_digit(buf[i])) { i++; int_digits++; }
    if (i < len && buf[i] == '.') {
        i++;
        while (i < len && is_digit(buf[i])) { i++; frac_digits++; }
    }
    if (int_digits + frac_digits == 0) return "not a number";
    if (i < len && (buf[i] == 'e' || buf[i] == 'E')) {
        size_t exp_digits = 0;
        i++;
        if (i < len && (buf[i] == '+' || buf[i] == '-')) i++;
        while (i < len && is_digit(buf[i])) { i++; exp_digits++; }
        if (exp_digits == 0) return "bad exponent";
    }
    if (i != len) return "not a number";

    memcpy(tmp, buf, len);
    tmp[len] = '\0';
    errno = 0;
    v = strtod(tmp, &end);
    if (end != tmp + len) return "not a number";
    /* Accepted: the values that round to a finite float (|v| below the
     * overflow threshold FLT_MAX + half an ulp = 0x1.ffffffp+127; a value
     * between FLT_MAX and it is FLT_MAX) and, below FLT_MIN, the values
     * that a subnormal float holds to float precision (relative error
     * <= 2^-24, as rounding a normal float): every float printed with %.9g
     * reads back as the same float, while 1e-45 (rounds to 1.4e-45) and
     * 1e-46 (rounds to 0) are rejected rather than silently changed. */
    if (!isfinite(v) || (errno == ERANGE && fabs(v) > 1.0) || fabs(v) >= 0x1.ffffffp+127)
        return "out of float range";
    if (errno == ERANGE) return "out of float range (too small: underflows to 0)";
    if (fabs(v) > (double)FLT_MAX) {
        v = (v > 0.0) ? (double)FLT_MAX : -(double)FLT_MAX;
    } else if (v != 0.0 && fabs(v) < (double)FLT_MIN) {
        float f = (float)v;
        if (f == 0.0f) return "out of float range (too small: underflows to 0)";
        if (fabs((double)f - v) > fabs(v) * 0x1p-24)
            return "out of float range (too small: a subnormal float cannot hold it to float precision)";
    }
    *out = v;
    return NULL;
}

/* ---- fixed-point conversions (host side, in double) ----------------- */

static int to_fix(double v, double scale, int32_t *out)
{
    double r = floor(v * scale + 0.5);
    if (r > 2147483647.0 || r < -2147483648.0) return -1;
    *out = (int32_t)r;
    return 0;
}

static const char *status_msg(dh_status st)
{
    return dh_status_str(st);
}

/* ---- one term -------------------------------------------------------- */

typedef struct {
    size_t pos[MAX_ARGS];
    size_t len[MAX_ARGS];
    double v[MAX_ARGS];
} term_args;

static int multiply_f(parser *p, const dh_mat4_f32 *t, size_t pos, const char *what)
{
    dh_mat4_f32 *acc = &p->acc_f[p->depth];
    unsigned r, c;
    dh_mat4_mul_f32(acc, t, acc);
    for (c = 0; c < 4u; c++)
        for (r = 0; r < 4u; r++)
            if (!isfinite(acc->m[c][r]))
                return fail(p, pos, DH_ERR_OVERFLOW,
                            "overflow: the product up to '%s' is not finite in float", what);
    return 0;
}

static int multiply_q(parser *p, const dh_frame_q *t, size_t pos, const char *what)
{
    dh_frame_q *acc = &p->acc_q[p->depth];
    dh_status st = dh_frame_mul_q(acc, t, acc);
    if (st == DH_ERR_OVERFLOW)
        return fail(p, pos, st, "overflow: the fixed-point product up to '%s' saturates", what);
    if (st != DH_OK)
        return fail(p, pos, st, "'%s': %s", what, status_msg(st));
    return 0;
}

static int apply_term_f(parser *p, const term_info *ti, const term_args *a, int axis, size_t pos)
{
    dh_mat4_f32 t;
    dh_status st = DH_OK;
    switch (ti->kind) {
    case T_IDENT: dh_mat4_identity_f32(&t); break;
    case T_TRANS: dh_mat4_trans_f32((float)a->v[0], (float)a->v[1], (float)a->v[2], &t); break;
    case T_ROTX: st = dh_mat4_rotx_f32((float)a->v[0], &t); break;
    case T_ROTY: st = dh_mat4_roty_f32((float)a->v[0], &t); break;
    case T_ROTZ: st = dh_mat4_rotz_f32((float)a->v[0], &t); break;
    case T_ROT: {
        double n = sqrt(a->v[0] * a->v[0] + a->v[1] * a->v[1] + a->v[2] * a->v[2]);
        if (!(n > 0.0)) return fail(p, pos, DH_ERR_ZERO_AXIS, "'rot': zero rotation axis");
        st = dh_mat4_rot_axis_f32((float)(a->v[0] / n), (float)(a->v[1] / n), (float)(a->v[2] / n),
                                  (float)a->v[3], &t);
        break;
    }
    case T_SCALE: dh_mat4_scale_f32((float)a->v[0], (float)a->v[1], (float)a->v[2], &t); break;
    case T_PERSP:
        if (a->v[1] == 0.0)
            return fail(p, a->pos[1], DH_ERR_DOMAIN, "'persp': focal length f = 0");
        st = dh_mat4_persp_f32(axis, (float)a->v[1], &t);
        break;
    case T_INV: default:
        return fail(p, pos, DH_ERR_ARG, "internal: unexpected term");
    }
    if (st != DH_OK) {
        if (st == DH_ERR_ZERO_AXIS) return fail(p, pos, st, "'%s': zero rotation axis", ti->name);
        if (st == DH_ERR_DOMAIN) return fail(p, pos, st, "'%s': focal length f = 0", ti->name);
        return fail(p, pos, st, "'%s': %s", ti->name, status_msg(st));
    }
    return multiply_f(p, &t, pos, ti->name);
}

static int apply_term_q(parser *p, const term_info *ti, const term_args *a, size_t pos)
{
    dh_frame_q t;
    const double pscale = (double)((int32_t)1 << DH_QPOS_FRAC);
    int32_t x[MAX_ARGS];
    unsigned k;
    dh_status st = DH_OK;

    switch (ti->kind) {
    case T_IDENT: dh_frame_identity_q(&t); break;
    case T_TRANS:
        for (k = 0; k < 3u; k++)
            if (to_fix(a->v[k], pscale, &x[k]))
                return fail(p, a->pos[k], DH_ERR_OVERFLOW,
                            "overflow: length %.9g does not fit the fixed-point format Q%d.%d",
                            a->v[k], 32 - DH_QPOS_FRAC, DH_QPOS_FRAC);
        dh_frame_trans_q(x[0], x[1], x[2], &t);
        break;
    case T_ROTX: case T_ROTY: case T_ROTZ: case T_ROT: {
        unsigned ia = (ti->kind == T_ROT) ? 3u : 0u;
        if (to_fix(a->v[ia], 65536.0, &x[ia]))
            return fail(p, a->pos[ia], DH_ERR_OVERFLOW,
                        "overflow: angle %.9g deg does not fit degrees Q16.16", a->v[ia]);
        if (ti->kind == T_ROTX) dh_frame_rotx_q(x[0], &t);
        else if (ti->kind == T_ROTY) dh_frame_roty_q(x[0], &t);
        else if (ti->kind == T_ROTZ) dh_frame_rotz_q(x[0], &t);
        else {
            double n = sqrt(a->v[0] * a->v[0] + a->v[1] * a->v[1] + a->v[2] * a->v[2]);
            if (!(n > 0.0)) return fail(p, pos, DH_ERR_ZERO_AXIS, "'rot': zero rotation axis");
            for (k = 0; k < 3u; k++)
                (void)to_fix(a->v[k] / n, 1073741824.0, &x[k]); /* |v/n| <= 1: fits Q2.30 */
            st = dh_frame_rot_axis_q(x[0], x[1], x[2], x[3], &t);
        }
        break;
    }
    case T_SCALE: case T_PERSP:
        return fail(p, pos, DH_ERR_NOT_RIGID,
                    "'%s' is not rigid: it has no fixed-point (--fixed) form", ti->name);
    case T_INV: default:
        return fail(p, pos, DH_ERR_ARG, "internal: unexpected term");
    }
    if (st != DH_OK) {
        if (st == DH_ERR_ZERO_AXIS) return fail(p, pos, st, "'%s': zero rotation axis", ti->name);
        return fail(p, pos, st, "'%s': %s", ti->name, status_msg(st));
    }
    return multiply_q(p, &t, pos, ti->name);
}

/* Parse "(arg, ...)" after a term name; p->i is just after the name. */
static int parse_args(parser *p, const term_info *ti, size_t term_pos, term_args *a, size_t *nargs)
{
    size_t open, n = 0;
    skip_space(p);
    if (p->i >= p->len || p->buf[p->i] != '(')
        return fail(p, p->i < p->len ? p->i : term_pos, DH_ERR_ARG,
                    "'%s' needs an argument list: %s(%s)", ti->name, ti->name, ti->args);
    open = p->i++;
    skip_space(p);
    if (p->i < p->len && p->buf[p->i] == ')') {
        p->i++;
        *nargs = 0;
        return 0;
    }
    for (;;) {
        size_t s;
        skip_space(p);
        s = p->i;
        while (p->i < p->len && p->buf[p->i] != ',' && p->buf[p->i] != ')' &&
               p->buf[p->i] != '(' && !is_space(p->buf[p->i]))
            p->i++;
        if (p->i == s) {
            if (p->i >= p->len)
                return fail(p, open, DH_ERR_ARG,
                            "unbalanced '(': argument list of '%s' is not closed", ti->name);
            return fail(p, s, DH_ERR_ARG, "'%s': missing argument %lu", ti->name,
                        (unsigned long)(n + 1));
        }
        if (n < MAX_ARGS) {
            a->pos[n] = s;
            a->len[n] = p->i - s;
        }
        n++;
        skip_space(p);
        if (p->i >= p->len)
            return fail(p, open, DH_ERR_ARG,
                        "unbalanced '(': argument list of '%s' is not closed", ti->name);
        if (p->buf[p->i] == ',') { p->i++; continue; }
        if (p->buf[p->i] == ')') { p->i++; break; }
        {
            char q[64];
            dh_expr_quote(q, sizeof q, p->buf + p->i, 1, 24u);
            return fail(p, p->i, DH_ERR_ARG, "'%s': expected ',' or ')' but found '%s'",
                        ti->name, q);
        }
    }
    *nargs = n;
    return 0;
}

static int do_term(parser *p, const term_info *ti, size_t term_pos)
{
    term_args a;
    size_t nargs = 0, k;
    int axis = 0;

    memset(&a, 0, sizeof a);
    if (ti->kind == T_IDENT) {
        /* "ident" or "ident()" */
        size_t save = p->i;
        skip_space(p);
        if (p->i < p->len && p->buf[p->i] == '(') {
            if (parse_args(p, ti, term_pos, &a, &nargs)) return -1;
            if (nargs != 0)
                return fail(p, term_pos, DH_ERR_ARG, "'ident' takes no arguments, got %lu",
                            (unsigned long)nargs);
        } else {
            p->i = save;
        }
    } else {
        if (parse_args(p, ti, term_pos, &a, &nargs)) return -1;
        if (nargs != ti->nargs)
            return fail(p, term_pos, DH_ERR_ARG, "'%s' takes %u argument%s (%s), got %lu",
                        ti->name, ti->nargs, ti->nargs == 1u ? "" : "s", ti->args,
                        (unsigned long)nargs);
    }
    for (k = 0; k < nargs; k++) {
        const char *why;
        if (ti->kind == T_PERSP && k == 0) {
            char c = a.len[0] == 1 ? p->buf[a.pos[0]] : '\0';
            if (c == 'x') axis = 0;
            else if (c == 'y') axis = 1;
            else if (c == 'z') axis = 2;
            else {
                char q[64];
                dh_expr_quote(q, sizeof q, p->buf + a.pos[0], a.len[0], 24u);
                return fail(p, a.pos[0], DH_ERR_ARG, "'persp': axis must be x, y or z, not '%s'", q);
            }
            continue;
        }
        why = dh_expr_parse_number(p->buf + a.pos[k], a.len[k], &a.v[k]);
        if (why) {
            char q[64];
            dh_expr_quote(q, sizeof q, p->buf + a.pos[k], a.len[k], 24u);
            return fail(p, a.pos[k], why[0] == 'N' ? DH_ERR_NAN : DH_ERR_ARG,
                        "bad number '%s' (argument %lu of '%s'): %s", q, (unsigned long)(k + 1),
                        ti->name, why);
        }
    }
    return p->fixed ? apply_term_q(p, ti, &a, term_pos) : apply_term_f(p, ti, &a, axis, term_pos);
}

static int close_inv(parser *p)
{
    size_t pos = p->open_pos[p->depth];
    if (p->fixed) {
        dh_frame_q t;
        dh_status st = dh_frame_inv_q(&p->acc_q[p->depth], &t);
        if (st == DH_ERR_OVERFLOW)
            return fail(p, pos, st, "overflow: 'inv' saturates in fixed point");
        if (st != DH_OK) return fail(p, pos, st, "'inv': %s", status_msg(st));
        p->depth--;
        return multiply_q(p, &t, pos, "inv");
    } else {
        dh_mat4_f32 t;
        dh_status st = dh_mat4_inv_auto_f32(&p->acc_f[p->depth], &t);
        if (st == DH_ERR_SINGULAR) return fail(p, pos, st, "'inv': singular matrix");
        if (st != DH_OK) return fail(p, pos, st, "'inv': %s", status_msg(st));
        p->depth--;
        return multiply_f(p, &t, pos, "inv");
    }
}

static void push_identity(parser *p)
{
    if (p->fixed) dh_frame_identity_q(&p->acc_q[p->depth]);
    else dh_mat4_identity_f32(&p->acc_f[p->depth]);
    p->has_term[p->depth] = 0;
}

static int run(parser *p)
{
    int prev_term = 0;      /* the last thing read was a complete term */
    int separated = 1;      /* whitespace or '*' since the last term */
    int star_pending = 0;
    size_t star_pos = 0;

    p->depth = 0;
    p->open_pos[0] = 0;
    push_identity(p);

    for (;;) {
        char c;
        size_t before = p->i;
        skip_space(p);
        if (p->i != before) separated = 1;
        if (p->i >= p->len) break;
        c = p->buf[p->i];
        if (c == '*') {
            if (!prev_term) {
                if (star_pending) return fail(p, p->i, DH_ERR_ARG, "'*' follows '*'");
                return fail(p, p->i, DH_ERR_ARG, "'*' needs a term on its left");
            }
            prev_term = 0;
            star_pending = 1;
            star_pos = p->i++;
            separated = 1;
            continue;
        }
        if (c == ')') {
            if (star_pending) return fail(p, star_pos, DH_ERR_ARG, "expected a term after '*'");
            if (p->depth == 0) return fail(p, p->i, DH_ERR_ARG, "unbalanced ')'");
            if (!p->has_term[p->depth])
                return fail(p, p->open_pos[p->depth], DH_ERR_ARG, "'inv' of an empty expression");
            p->i++;
            if (close_inv(p)) return -1;
            p->has_term[p->depth] = 1;
            prev_term = 1;
            separated = 0;
            continue;
        }
        if (is_alpha(c)) {
            size_t s = p->i, n, k;
            const term_info *ti = NULL;
            while (p->i < p->len && (is_alpha(p->buf[p->i]) || is_digit(p->buf[p->i]))) p->i++;
            n = p->i - s;
            if (prev_term && !separated)
                return fail(p, s, DH_ERR_ARG, "missing space or '*' before this term");
            for (k = 0; k < sizeof k_terms / sizeof k_terms[0]; k++)
                if (strlen(k_terms[k].name) == n && memcmp(k_terms[k].name, p->buf + s, n) == 0)
                    ti = &k_terms[k];
            if (!ti) {
                char q[64];
                dh_expr_quote(q, sizeof q, p->buf + s, n, 24u);
                return fail(p, s, DH_ERR_ARG, "unknown term '%s'", q);
            }
            star_pending = 0;
            if (ti->kind == T_INV) {
                skip_space(p);
                if (p->i >= p->len || p->buf[p->i] != '(')
                    return fail(p, p->i < p->len ? p->i : s, DH_ERR_ARG, "'inv' needs '(': inv(EXPR)");
                if (p->depth >= DH_EXPR_MAX_DEPTH)
                    return fail(p, s, DH_ERR_ARG, "inv() nested deeper than %d levels",
                                DH_EXPR_MAX_DEPTH);
                p->i++;
                p->depth++;
                p->open_pos[p->depth] = s;
                push_identity(p);
                prev_term = 0;
                separated = 1;
                continue;
            }
            if (do_term(p, ti, s)) return -1;
            p->has_term[p->depth] = 1;
            prev_term = 1;
            separated = 0;
            continue;
        }
        {
            char q[64];
            dh_expr_quote(q, sizeof q, p->buf + p->i, 1, 24u);
            if (c == '(' || c == ',')
                return fail(p, p->i, DH_ERR_ARG, "unexpected '%s' (not after a term name)", q);
            if (is_digit(c) || c == '-' || c == '+' || c == '.')
                return fail(p, p->i, DH_ERR_ARG, "unexpected number: numbers go inside a term's parentheses");
            return fail(p, p->i, DH_ERR_ARG, "unexpected character '%s'", q);
        }
    }
    if (star_pending) return fail(p, star_pos, DH_ERR_ARG, "expected a term after '*'");
    if (p->depth > 0)
        return fail(p, p->open_pos[p->depth], DH_ERR_ARG, "unbalanced '(': 'inv(' is not closed");
    if (!p->has_term[0]) return fail(p, 0, DH_ERR_ARG, "empty expression");
    return 0;
}

static int eval(const char *buf, size_t len, int fixed, dh_mat4_f32 *out_f, dh_frame_q *out_q,
                dh_expr_error *err)
{
    /* The parser holds DH_EXPR_MAX_DEPTH+1 partial products; this is host code. */
    parser p;
    p.buf = buf;
    p.len = buf ? len : 0u;
    p.i = 0;
    p.fixed = fixed;
    p.err = err;
    if (run(&p)) return -1;
    if (fixed) *out_q = p.acc_q[0];
    else *out_f = p.acc_f[0];
    return 0;
}

int dh_expr_eval_f32(const char *buf, size_t len, dh_mat4_f32 *out, dh_expr_error *err)
{
    return eval(buf, len, 0, out, NULL, err);
}

int dh_expr_eval_q(const char *buf, size_t len, dh_frame_q *out, dh_expr_error *err)
{
    return eval(buf, len, 1, NULL, out, err);
}
