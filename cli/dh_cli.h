/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_cli.h - helpers shared by the commands of the dhmath host tool.
 *
 * Every function that can fail prints one message on stderr starting
 * with "dhmath: " and returns the exit status (CLI_EXIT_ERR, or
 * CLI_EXIT_USAGE for usage errors); 0 on success. Nothing here writes to
 * stdout except cli_finish (which flushes it).
 */
#ifndef DHMATH_CLI_DH_CLI_H
#define DHMATH_CLI_DH_CLI_H

#include <stddef.h>
#include <stdio.h>

#include "dh_expr.h"
#include "dh_robotfile.h"
#include "dhmath/frame.h"
#include "dhmath/ikc.h"
#include "dhmath/robot.h"
#include "dhmath/track.h"

#define EXIT_USAGE 2
#define EXIT_ERR 2
#define EXIT_NOCONV 3
#define MAX_ROBOT_FILE (1024L * 1024L)

/** Output kept in memory until a command knows it succeeded (nothing on
 *  stdout on exit status 2). */
typedef struct {
    char *buf;
    size_t len, cap;
} cli_outbuf;

/** "dhmath: usage error: " fmt (one %s: arg), and the hint to run help. */
int cli_usage_error(const char *fmt, const char *arg);
/** "dhmath: error at column C of EXPR: ...". */
int cli_expr_error(const dh_expr_error *e);
/** "dhmath: error: what[: detail]". */
int cli_error(const char *what, const char *detail);
/** Flushes stdout: 0, or EXIT_ERR when writing failed. */
int cli_finish(void);
/** All of f (at most MAX_ROBOT_FILE bytes) into a malloc'd *buf (caller frees). */
int cli_read_all(FILE *f, const char *what, char **buf, size_t *len);
/** EXPR s ("-": standard input) in float (fixed == 0, into T) or fixed point (into F). */
int cli_eval_expr_arg(const char *s, int fixed, dh_mat4_f32 *T, dh_frame_q *F);
/** EXPR s in float. */
int cli_eval_expr(const char *s, dh_mat4_f32 *T);
/** One number s for the argument named what. */
int cli_parse_num(const char *s, const char *what, double *v);
/** Comma-separated list of exactly n numbers for the argument named what. */
int cli_parse_list(const char *s, unsigned n, double *v, const char *what);
/** Robot file path ("-": standard input): parsed and built (fixed: with the fixed path). */
int cli_load_robot(const char *path, int fixed, dh_robot *r, dh_robotfile *rf);
/** Appends text to b (grows it). */
int cli_out_add(cli_outbuf *b, const char *text);
/** Option opt's value s: one value for every joint of r or r->n values,
 *  each finite and > 0, into out. */
int cli_joint_values(const char *opt, const char *s, const dh_robot *r, float *out);
/** Per-joint rate limit for opt ("--vmax" or "--amax"): from s when not
 *  NULL (cli_joint_values), else the robot file's vmax= / amax= (every
 *  joint needs one; the message names cmd and the joint). */
int cli_joint_rates(const char *cmd, const char *opt, const char *s, const dh_robot *r, float *out);
/** --dt: a number > 0 seconds, also > 0 and finite in float. */
int cli_parse_dt(const char *s, double *dt);
/** The float tracker at q0 with period dt: the closed-form model of r
 *  (into m) when it has one, else damped steps; errors name --q0 (outside
 *  the limits) or cmd. */
int cli_track_start(const char *cmd, const dh_robot *r, dh_ikc_model_f32 *m, const float *q0, float dt,
                    dh_track_f32 *t);

#endif /* DHMATH_CLI_DH_CLI_H */
