/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_cli.c - helpers shared by the commands of the dhmath host tool
 * (dhmath.c, dh_move_cmd.c): messages, numbers and joint lists, robot
 * files, buffered output, rate limits and the tracker's start.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dh_cli.h"

int cli_usage_error(const char *fmt, const char *arg)
{
    fputs("dhmath: usage error: ", stderr);
    fprintf(stderr, fmt, arg ? arg : "");
    fputs("\n(run 'dhmath help' for usage)\n", stderr);
    return EXIT_USAGE;
}

int cli_expr_error(const dh_expr_error *e)
{
    fprintf(stderr, "dhmath: error at column %lu of EXPR: %s\n", (unsigned long)(e->pos + 1), e->msg);
    return EXIT_ERR;
}

int cli_error(const char *what, const char *detail)
{
    fprintf(stderr, "dhmath: error: %s%s%s\n", what, detail ? ": " : "", detail ? detail : "");
    return EXIT_ERR;
}

int cli_finish(void)
{
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fputs("dhmath: error: writing to stdout failed\n", stderr);
        return EXIT_ERR;
    }
    return 0;
}

/* All of f (at most MAX_ROBOT_FILE bytes) into a malloc'd *buf (caller frees). */
int cli_read_all(FILE *f, const char *what, char **buf, size_t *len)
{
    *buf = (char *)malloc((size_t)MAX_ROBOT_FILE + 1u);
    if (!*buf) return cli_error("out of memory", NULL);
    *len = fread(*buf, 1, (size_t)MAX_ROBOT_FILE + 1u, f);
    if (ferror(f) || *len > (size_t)MAX_ROBOT_FILE) {
        fprintf(stderr, "dhmath: error: %s: %s\n", what, ferror(f) ? "cannot read it" : "larger than 1 MiB");
        free(*buf);
        *buf = NULL;
        return EXIT_ERR;
    }
    return 0;
}

/* EXPR argument s ("-": standard input) in float (fixed == 0, into T) or on
 * the fixed-point path (into F) */
int cli_eval_expr_arg(const char *s, int fixed, dh_mat4_f32 *T, dh_frame_q *F)
{
    dh_expr_error e;
    char *in = NULL;
    size_t len = strlen(s);
    int bad, rc;
    if (strcmp(s, "-") == 0) {
        if ((rc = cli_read_all(stdin, "EXPR from standard input", &in, &len)) != 0) return rc;
        s = in;
    }
    bad = fixed ? dh_expr_eval_q(s, len, F, &e) : dh_expr_eval_f32(s, len, T, &e);
    free(in);
    return bad ? cli_expr_error(&e) : 0;
}

int cli_eval_expr(const char *s, dh_mat4_f32 *T)
{
    return cli_eval_expr_arg(s, 0, T, NULL);
}

int cli_parse_num(const char *s, const char *what, double *v)
{
    const char *why = dh_expr_parse_number(s, strlen(s), v);
    if (why) {
        fprintf(stderr, "dhmath: error: bad number '%s' for %s: %s\n", s, what, why);
        return EXIT_ERR;
    }
    return 0;
}

/* comma-separated list of exactly n numbers */
int cli_parse_list(const char *s, unsigned n, double *v, const char *what)
{
    unsigned count = 0;
    const char *p = s;
    if (*s == '\0') {
        fprintf(stderr, "dhmath: error: %s: expected %u values, got none\n", what, n);
        return EXIT_ERR;
    }
    for (;;) {
        const char *e = strchr(p, ',');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        double x = 0.0;
        const char *why = dh_expr_parse_number(p, len, &x);
        if (why) {
            fprintf(stderr, "dhmath: error: %s: value %u '%.*s' (column %lu): %s\n", what, count + 1,
                    (int)(len > 40 ? 40 : len), p, (unsigned long)(p - s + 1), why);
            return EXIT_ERR;
        }
        if (count < n) v[count] = x;
        count++;
        if (!e) break;
        p = e + 1;
    }
    if (count != n) {
        fprintf(stderr, "dhmath: error: %s: expected %u values (one per joint), got %u\n", what, n, count);
        return EXIT_ERR;
    }
    return 0;
}

/* robot file path ("-": standard input, named <stdin> in messages) */
int cli_load_robot(const char *path, int fixed, dh_robot *r, dh_robotfile *rf)
{
    const int in = strcmp(path, "-") == 0;
    FILE *f = in ? stdin : fopen(path, "rb");
    char *buf;
    size_t len;
    dh_rf_error e;
    int rc;
    char what[300];
    if (!f) {
        fprintf(stderr, "dhmath: error: cannot open robot file '%s'\n", path);
        return EXIT_ERR;
    }
    if (in) path = "<stdin>";
    (void)snprintf(what, sizeof what, "robot file %s", path);
    rc = cli_read_all(f, what, &buf, &len);
    if (!in) fclose(f);
    if (rc) return rc;
    if (dh_robotfile_parse(path, buf, len, rf, &e)) rc = cli_error(e.msg, NULL);
    if (!rc && dh_robotfile_build(path, rf, fixed, r, &e)) rc = cli_error(e.msg, NULL);
    free(buf);
    return rc;
}

int cli_out_add(cli_outbuf *b, const char *text)
{
    const size_t n = strlen(text);
    if (b->len + n + 1u > b->cap) {
        size_t cap = b->cap ? b->cap * 2u : 4096u;
        char *p;
        while (cap < b->len + n + 1u) cap *= 2u;
        p = (char *)realloc(b->buf, cap);
        if (!p) return cli_error("out of memory", NULL);
        b->buf = p;
        b->cap = cap;
    }
    memcpy(b->buf + b->len, text, n + 1u);
    b->len += n;
    return 0;
}

/* one value for every joint or n values, each > 0 */
int cli_joint_values(const char *opt, const char *s, const dh_robot *r, float *out)
{
    double v[DH_MAX_JOINTS];
    unsigned i, commas = 0;
    const char *p;
    for (p = s; *p; p++) commas += (*p == ',');
    if (commas == 0u) {
        if (cli_parse_num(s, opt, &v[0])) return EXIT_ERR;
        for (i = 1; i < r->n; i++) v[i] = v[0];
    } else if (cli_parse_list(s, r->n, v, opt)) {
        return EXIT_ERR;
    }
    for (i = 0; i < r->n; i++) {
        if (!(v[i] > 0.0) || !((float)v[i] > 0.0f) || !isfinite((float)v[i])) {
            fprintf(stderr, "dhmath: error: %s: joint %u value %.9g must be a finite number greater than 0\n", opt,
                    i + 1u, v[i]);
            return EXIT_ERR;
        }
        out[i] = (float)v[i];
    }
    return 0;
}

int cli_joint_rates(const char *cmd, const char *opt, const char *s, const dh_robot *r, float *out)
{
    const int acc = strcmp(opt, "--amax") == 0;
    unsigned i;
    if (s) return cli_joint_values(opt, s, r, out);
    for (i = 0; i < r->n; i++) {
        const float v = acc ? r->joint[i].amax : r->joint[i].vmax;
        if (!isfinite(v)) {
            fprintf(stderr, "dhmath: error: %s: no %s and joint %u has no %s= in the robot file\n", cmd, opt, i + 1u,
                    opt + 2);
            return EXIT_ERR;
        }
        out[i] = v;
    }
    return 0;
}

int cli_parse_dt(const char *s, double *dt)
{
    int rc = cli_parse_num(s, "--dt", dt);
    if (rc) return rc;
    if (!(*dt > 0.0) || !((float)*dt > 0.0f) || !isfinite((float)*dt))
        return cli_error("--dt", "the control period must be greater than 0 seconds");
    return 0;
}

int cli_track_start(const char *cmd, const dh_robot *r, dh_ikc_model_f32 *m, const float *q0, float dt,
                    dh_track_f32 *t)
{
    const dh_ikc_model_f32 *mp = NULL;
    dh_status st;
    if (dh_ikc_analyse_f32(r, m) == DH_OK && m->kind != DH_IKC_NONE) mp = m;
    st = dh_track_init_f32(t, r, mp, q0, dt);
    if (st == DH_ERR_LIMIT) return cli_error("--q0", "a joint value is outside its limits");
    if (st != DH_OK) return cli_error(cmd, dh_status_str(st));
    return 0;
}
