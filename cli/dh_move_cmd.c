/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_move_cmd.c - `dhmath move`: a sequence of joint, line and arc
 * segments run by the move executor of motion.h, one CSV line per control
 * period (docs/cli.md, "move").
 *
 * Every segment is planned before the first period runs (EXPRs, joint
 * lists, limits, paths and their profiles), so that a bad argument exits
 * with status 2 and nothing on stdout. A line or arc segment starts at the
 * frame where the previous one was planned to end (the first at FK(q0));
 * a joint segment starts at the configuration the robot is in when it
 * begins. Joint segments are sampled by dh_move_joint_step_f32; line and
 * arc segments are tracked by the float tracker of track.h (set up as for
 * `track`, by cli_track_start) between dh_move_target_f32 and
 * dh_move_advance_f32. The output is kept in memory until the move ends.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dh_cli.h"
#include "dh_move_cmd.h"
#include "dhmath/mat4.h"
#include "dhmath/motion.h"
#include "dhmath/robot.h"

/** Most segments on one command line. */
#define MOVE_MAX_SEG 64
/* items of the fixed queue (move --fixed): segments are appended as it drains */
#define MOVE_QUEUE_CAP 4u
/** Most control periods of one move (the output is kept in memory). */
#define MOVE_MAX_PERIODS 1000000.0
/** The cap on the periods of a line or arc segment: MOVE_CAP_FACTOR times
 *  its planned duration plus MOVE_CAP_EXTRA seconds, in periods. */
#define MOVE_CAP_FACTOR 4.0
#define MOVE_CAP_EXTRA 1.0

const char cli_move_usage[] =
    "  move ROBOT --q0 q1,... --dt SECONDS SEGMENT... [--speed S] [--accel A]\n"
    "       [--rspeed DEG_S] [--raccel DEG_S2] [--jerk J] [--blend R] [--vmax V] [--amax V] [--fixed]\n"
    "                                  SEGMENT: --line EXPR | --arc VIA_EXPR END_EXPR |\n"
    "                                  --joint q1,...; CSV on stdout: t,q1,...,qn,status\n"
    "                                  per control period (ok|lagging|unreachable);\n"
    "                                  exit 0 all ok, 3 lagging/unreachable or not\n"
    "                                  completed, 2 error\n";

enum { SEG_LINE = 0, SEG_ARC = 1, SEG_JOINT = 2 };
static const char *const k_seg_opt[3] = { "--line", "--arc", "--joint" };
static const char *const k_state_word[3] = { "ok", "lagging", "unreachable" };

typedef struct {
    int kind;
    const char *a, *b; /* line: EXPR; arc: VIA_EXPR, END_EXPR; joint: the list */
} move_seg;

typedef struct {
    const char *robot, *q0, *dt, *speed, *accel, *rspeed, *raccel, *jerk, *blend, *vmax, *amax;
    int fixed, nstdin;
    unsigned nseg;
    move_seg seg[MOVE_MAX_SEG];
} move_args;

/* Everything the periods need, planned before the first one. */
typedef struct {
    dh_robot r;
    dh_robotfile rf;
    dh_ikc_model_f32 m;
    dh_track_f32 t;
    dh_move_f32 mv;
    dh_path_f32 path[MOVE_MAX_SEG];      /* line and arc segments */
    float q1[MOVE_MAX_SEG][DH_MAX_JOINTS]; /* joint segments */
    float q0[DH_MAX_JOINTS], vmax[DH_MAX_JOINTS], amax[DH_MAX_JOINTS], jmax[DH_MAX_JOINTS];
    dh_cart_limits_f32 lim;
    dh_cart_jerk_f32 cj;   /* with --jerk: the Cartesian segments' jerk limits */
    float blend;           /* --blend R: the radius of every corner between Cartesian segments (-1: none) */
    dh_queue_f32 qu;       /* with --blend: the queue that runs consecutive Cartesian segments */
    dh_queue_item_f32 items[MOVE_MAX_SEG];
    double dt;
    int jerk;
    int32_t jq[DH_MAX_JOINTS]; /* --fixed --jerk: the joints' jerk limits (Q16.16 deg/s^3, dh_qpos/s^3) */
    dh_cart_jerk_q cjq;        /* --fixed --jerk: the Cartesian segments' jerk limits */
    cli_outbuf out;
    double periods;   /* periods printed so far */
    double bad;       /* periods not ok */
} move_plan;

/* ---- arguments ------------------------------------------------------------ */

static int move_value(const char *name, const char **slot, const char *v)
{
    if (*slot) return cli_usage_error("option '--%s' given more than once", name);
    *slot = v;
    return 0;
}

/* one valued option at argv[*k] (--name VALUE or --name=VALUE): 1 when
 * name is not one of move's, else 0 or an exit status */
static int move_valued(move_args *a, int argc, char **argv, int *k, int *rc)
{
    static const char *const names[11] = { "q0", "dt", "speed", "accel", "rspeed", "raccel", "jerk", "blend", "vmax",
                                           "amax", "line" };
    const char **slot[11];
    const char *name = argv[*k] + 2, *eq = strchr(name, '=');
    const size_t nl = eq ? (size_t)(eq - name) : strlen(name);
    unsigned v;
    slot[0] = &a->q0;
    slot[1] = &a->dt;
    slot[2] = &a->speed;
    slot[3] = &a->accel;
    slot[4] = &a->rspeed;
    slot[5] = &a->raccel;
    slot[6] = &a->jerk;
    slot[7] = &a->blend;
    slot[8] = &a->vmax;
    slot[9] = &a->amax;
    slot[10] = NULL;
    for (v = 0; v < 11u; v++)
        if (strlen(names[v]) == nl && strncmp(name, names[v], nl) == 0) break;
    if (v == 11u) return 1;
    if (!eq && *k + 1 >= argc) {
        *rc = cli_usage_error("option '%s' needs a value", argv[*k]);
        return 0;
    }
    eq = eq ? eq + 1 : argv[++*k];
    if (v < 10u) {
        *rc = move_value(names[v], slot[v], eq);
        return 0;
    }
    if (a->nseg >= MOVE_MAX_SEG) {
        *rc = cli_usage_error("more than 64 segments (at '%s')", argv[*k]);
        return 0;
    }
    a->seg[a->nseg].kind = SEG_LINE;
    a->seg[a->nseg].a = eq;
    a->seg[a->nseg++].b = NULL;
    *rc = 0;
    return 0;
}

/* --arc VIA END and --joint LIST (no '=' form for --arc) */
static int move_segment(move_args *a, int argc, char **argv, int *k)
{
    const char *arg = argv[*k];
    const int arc = strcmp(arg, "--arc") == 0;
    const int need = arc ? 2 : 1;
    move_seg *s;
    if (a->nseg >= MOVE_MAX_SEG) return cli_usage_error("more than 64 segments (at '%s')", arg);
    s = &a->seg[a->nseg];
    if (!arc && strncmp(arg, "--joint=", 8) == 0) {
        s->kind = SEG_JOINT;
        s->a = arg + 8;
        s->b = NULL;
        a->nseg++;
        return 0;
    }
    if (*k + need >= argc)
        return cli_usage_error(arc ? "'%s' needs two values: VIA_EXPR END_EXPR" : "option '%s' needs a value", arg);
    s->kind = arc ? SEG_ARC : SEG_JOINT;
    s->a = argv[++*k];
    s->b = arc ? argv[++*k] : NULL;
    a->nseg++;
    return 0;
}

static int move_parse(int argc, char **argv, move_args *a)
{
    int k, rc = 0;
    unsigned s;
    memset(a, 0, sizeof *a);
    for (k = 0; k < argc; k++) {
        const char *arg = argv[k];
        if (arg[0] == '-' && arg[1] == '-') {
            if (strcmp(arg, "--fixed") == 0) {
                if (a->fixed++) return cli_usage_error("option '%s' given more than once", arg);
            } else if (strcmp(arg, "--arc") == 0 || strcmp(arg, "--joint") == 0 || strncmp(arg, "--joint=", 8) == 0) {
                if ((rc = move_segment(a, argc, argv, &k)) != 0) return rc;
            } else if (move_valued(a, argc, argv, &k, &rc)) {
                return cli_usage_error("unknown or inapplicable option '%s'", arg);
            } else if (rc) {
                return rc;
            }
            continue;
        }
        if (arg[0] == '-' && arg[1] != '\0') return cli_usage_error("unknown option '%s'", arg);
        if (a->robot) return cli_usage_error("move takes one ROBOT (extra argument '%s')", arg);
        a->robot = arg;
    }
    if (!a->robot) return cli_usage_error("move needs a ROBOT file", NULL);
    if (!a->q0) return cli_usage_error("move needs --q0 q1,... (the configuration at the start)", NULL);
    if (!a->dt) return cli_usage_error("move needs --dt SECONDS (the control period)", NULL);
    if (a->nseg == 0u) return cli_usage_error("move needs at least one segment: --line EXPR, --arc VIA END or --joint q1,...", NULL);
    /* '-' (standard input) once, for the robot or one EXPR */
    a->nstdin = strcmp(a->robot, "-") == 0;
    for (s = 0; s < a->nseg; s++) {
        a->nstdin += a->seg[s].kind != SEG_JOINT && strcmp(a->seg[s].a, "-") == 0;
        a->nstdin += a->seg[s].kind == SEG_ARC && strcmp(a->seg[s].b, "-") == 0;
    }
    if (a->nstdin > 1) return cli_usage_error("'-' (standard input) given more than once%s", "");
    return 0;
}

/* --blend R: a radius finite and >= 0 in float */
static int move_blend(const move_args *a, float *r)
{
    double x = 0.0;
    int rc;
    if ((rc = cli_parse_num(a->blend, "--blend", &x)) != 0) return rc;
    if (!(x >= 0.0) || !isfinite((float)x)) {
        fprintf(stderr, "dhmath: error: --blend: %.9g must be a finite radius >= 0 (length unit)\n", x);
        return EXIT_ERR;
    }
    *r = (float)x;
    return 0;
}

/* a Cartesian limit: finite and > 0 in float */
static int move_limit(const char *opt, const char *s, const char *unit, float *v)
{
    double x = 0.0;
    int rc;
    if (!s) {
        fprintf(stderr, "dhmath: error: move: a --line or --arc segment needs %s (%s)\n", opt, unit);
        return EXIT_ERR;
    }
    if ((rc = cli_parse_num(s, opt, &x)) != 0) return rc;
    if (!(x > 0.0) || !((float)x > 0.0f) || !isfinite((float)x)) {
        fprintf(stderr, "dhmath: error: %s: %.9g must be a finite number greater than 0\n", opt, x);
        return EXIT_ERR;
    }
    *v = (float)x;
    return 0;
}

static int seg_error(unsigned i, const move_seg *s, const char *what, const char *detail)
{
    fprintf(stderr, "dhmath: error: segment %u (%s): %s%s%s\n", i + 1u, k_seg_opt[s->kind], what,
            detail ? ": " : "", detail ? detail : "");
    return EXIT_ERR;
}

/* an EXPR of segment i ("-": standard input): a rigid frame */
static int seg_frame(unsigned i, const move_seg *s, const char *expr, const char *which, dh_mat4_f32 *T)
{
    dh_expr_error e;
    if (strcmp(expr, "-") == 0) {
        const int rc = cli_eval_expr(expr, T);
        if (rc) return rc;
    } else if (dh_expr_eval_f32(expr, strlen(expr), T, &e)) {
        fprintf(stderr, "dhmath: error: segment %u (%s): %s EXPR, column %lu: %s\n", i + 1u, k_seg_opt[s->kind],
                which, (unsigned long)(e.pos + 1), e.msg);
        return EXIT_ERR;
    }
    if (dh_mat4_check_rigid_f32(T, DH_ROT_TOL) != DH_OK)
        return seg_error(i, s, which, "not a rigid frame (rotation not orthonormal or bottom row not 0 0 0 1)");
    return 0;
}

static const char *path_why(dh_status st)
{
    switch (st) {
    case DH_ERR_SINGULAR: return "the start, via and end points are collinear or too close to it (a flatter arc is a line)";
    case DH_ERR_OVERFLOW: return "the path or its profile overflows float (points or limits too far apart)";
    default: return dh_status_str(st);
    }
}

/* Plans every segment: joint lists within the limits, paths from the
 * planned end of the previous segment, profiles within the limits. */
static int move_plan_segments(const move_args *a, move_plan *p)
{
    dh_mat4_f32 F, B;
    float qs[DH_MAX_JOINTS];
    unsigned i, j;
    int known = 1, rc;
    dh_status st;
    memcpy(qs, p->q0, sizeof qs);
    if ((st = dh_fk_f32(&p->r, p->q0, &F)) != DH_OK) return cli_error("move: FK of --q0", dh_status_str(st));
    for (i = 0; i < a->nseg; i++) {
        const move_seg *s = &a->seg[i];
        if (s->kind == SEG_JOINT) {
            double v[DH_MAX_JOINTS];
            char what[64];
            (void)snprintf(what, sizeof what, "segment %u (--joint)", i + 1u);
            if ((rc = cli_parse_list(s->a, p->r.n, v, what)) != 0) return rc;
            for (j = 0; j < p->r.n; j++) p->q1[i][j] = (float)v[j];
            st = dh_robot_check_limits_f32(&p->r, p->q1[i]);
            if (st == DH_ERR_NAN) return seg_error(i, s, "a joint value is not finite in float", NULL);
            if (st != DH_OK) return seg_error(i, s, "a joint value is outside its limits", NULL);
            if (known) {
                st = dh_move_joint_f32(&p->mv, p->r.n, qs, p->q1[i], p->vmax, p->amax, p->jerk ? p->jmax : NULL);
                if (st != DH_OK) return seg_error(i, s, "the joint move cannot be planned", dh_status_str(st));
            }
            memcpy(qs, p->q1[i], sizeof qs);
            known = 1;
            if ((st = dh_fk_f32(&p->r, qs, &F)) != DH_OK) return seg_error(i, s, "FK of the end", dh_status_str(st));
            continue;
        }
        if (s->kind == SEG_LINE) {
            if ((rc = seg_frame(i, s, s->a, "end frame", &B)) != 0) return rc;
            st = dh_path_line_f32(&p->path[i], &F, &B);
        } else {
            dh_mat4_f32 V;
            float via[3];
            if ((rc = seg_frame(i, s, s->a, "via frame", &V)) != 0) return rc;
            if ((rc = seg_frame(i, s, s->b, "end frame", &B)) != 0) return rc;
            via[0] = DH_M4(&V, 0, 3);
            via[1] = DH_M4(&V, 1, 3);
            via[2] = DH_M4(&V, 2, 3);
            st = dh_path_arc_f32(&p->path[i], &F, via, &B);
        }
        if (st != DH_OK) return seg_error(i, s, "no path from the previous segment's end", path_why(st));
        st = dh_move_path_jerk_f32(&p->mv, &p->path[i], &p->lim, p->jerk ? &p->cj : NULL);
        if (st != DH_OK) return seg_error(i, s, "the move along the path cannot be planned", path_why(st));
        F = B;
        known = 0;
    }
    return 0;
}

/* ---- periods ---------------------------------------------------------------- */

/* a period's line up to its joint values: the cap on the periods, the
 * count of periods not ok, the time */
static int move_line_start(move_plan *p, int state)
{
    char text[64];
    if (p->periods >= MOVE_MAX_PERIODS) {
        fprintf(stderr, "dhmath: error: move: more than %.0f control periods; use a larger --dt\n", MOVE_MAX_PERIODS);
        return EXIT_ERR;
    }
    p->periods += 1.0;
    if (state != DH_TRACK_OK) p->bad += 1.0;
    (void)snprintf(text, sizeof text, "%.9g", p->periods * p->dt);
    return cli_out_add(&p->out, text);
}

static int move_line(move_plan *p, const float *q, int state)
{
    char text[64];
    unsigned j;
    if (move_line_start(p, state)) return EXIT_ERR;
    for (j = 0; j < p->r.n; j++) {
        (void)snprintf(text, sizeof text, ",%.9g", q[j] == 0.0f ? 0.0 : (double)q[j]);
        if (cli_out_add(&p->out, text)) return EXIT_ERR;
    }
    (void)snprintf(text, sizeof text, ",%s\n", k_state_word[state]);
    return cli_out_add(&p->out, text);
}

/* the cap on the periods of a segment of planned duration dur */
static double move_cap(const move_plan *p, float dur)
{
    return ceil((MOVE_CAP_FACTOR * (double)dur + MOVE_CAP_EXTRA) / p->dt);
}

static int cap_reached(unsigned i, const move_seg *s, double cap)
{
    fprintf(stderr, "dhmath: move: segment %u (%s) did not complete within %.0f control periods (%g times its "
            "planned duration plus %g s): stopped there\n", i + 1u, k_seg_opt[s->kind], cap, MOVE_CAP_FACTOR,
            MOVE_CAP_EXTRA);
    return EXIT_NOCONV;
}

/* joint segment i from the configuration q (updated) */
static int run_joint(move_plan *p, unsigned i, const move_seg *s, float *q)
{
    dh_move_report_f32 rep;
    double cap, k = 0.0;
    int rc;
    dh_status st = dh_move_joint_f32(&p->mv, p->r.n, q, p->q1[i], p->vmax, p->amax, p->jerk ? p->jmax : NULL);
    if (st != DH_OK) return seg_error(i, s, "the joint move cannot be planned", dh_status_str(st));
    cap = move_cap(p, p->mv.dur);
    do {
        if (k >= cap) return cap_reached(i, s, cap);
        k += 1.0;
        st = dh_move_joint_step_f32(&p->mv, (float)p->dt, q, &rep);
        if (st != DH_OK) return seg_error(i, s, "dh_move_joint_step_f32", dh_status_str(st));
        if ((rc = move_line(p, q, DH_TRACK_OK)) != 0) return rc;
    } while (!rep.done);
    return 0;
}

/* line or arc segment i, tracked from the tracker's configuration */
static int run_path(move_plan *p, unsigned i, const move_seg *s, float *q)
{
    dh_move_report_f32 rep;
    dh_track_report_f32 trep;
    dh_mat4_f32 T;
    double cap, k = 0.0;
    int rc;
    dh_status st = dh_move_path_jerk_f32(&p->mv, &p->path[i], &p->lim, p->jerk ? &p->cj : NULL);
    if (st != DH_OK) return seg_error(i, s, "the move along the path cannot be planned", path_why(st));
    cap = move_cap(p, p->mv.dur);
    do {
        if (k >= cap) return cap_reached(i, s, cap);
        k += 1.0;
        if ((st = dh_move_target_f32(&p->mv, &T)) == DH_OK) st = dh_track_step_f32(&p->t, &T, q, &trep);
        if (st == DH_OK) st = dh_move_advance_f32(&p->mv, (float)p->dt, trep.state, &rep);
        if (st != DH_OK) return seg_error(i, s, "a control period failed", dh_status_str(st));
        if ((rc = move_line(p, q, (int)trep.state)) != 0) return rc;
    } while (!rep.done);
    return 0;
}

/* segment i appended to the queue: with --jerk a line as a jerk-limited
 * blended line, an arc as a jerk-limited move (its corners at rest);
 * else as a blended move */
static dh_status blend_add(move_plan *p, unsigned i, const move_seg *s)
{
    if (!p->jerk) return dh_queue_add_path_blend_f32(&p->qu, &p->path[i], &p->lim, p->blend);
    if (s->kind == SEG_LINE) return dh_queue_add_path_blend_jerk_f32(&p->qu, &p->path[i], &p->lim, &p->cj, p->blend);
    return dh_queue_add_path_jerk_f32(&p->qu, &p->path[i], &p->lim, &p->cj);
}

/* the planned duration of the queue's head move: its profile's, or its
 * jerk-limited blended scaling's when longer (lowered at its corners) */
static float blend_dur(const move_plan *p)
{
    const dh_queue_item_f32 *it = &p->qu.items[p->qu.head];
    return (it->jerk == 2u && it->seg.T > it->prof.T) ? it->seg.T : it->prof.T;
}

/* Cartesian segments i0..i1-1 (lines and arcs) run by one queue with
 * their corners blended within --blend (with --jerk: the corners between
 * lines, jerk-limited), tracked from the tracker's configuration; a
 * tracker that lags slows the queue's feed override */
static int run_blend(move_plan *p, const move_args *a, unsigned i0, unsigned i1, float *q)
{
    dh_queue_report_f32 rep;
    dh_queue_cmd_f32 cmd;
    dh_track_report_f32 trep;
    double k = 0.0;
    unsigned i = i0;
    int rc;
    dh_status st = dh_queue_init_f32(&p->qu, p->items, MOVE_MAX_SEG);
    for (; i < i1 && st == DH_OK; i++) {
        st = blend_add(p, i, &a->seg[i]);
        if (st != DH_OK) return seg_error(i, &a->seg[i], "the blended move cannot be planned", path_why(st));
    }
    for (i = i0; i < i1;) {
        const double cap = move_cap(p, blend_dur(p));
        if (k >= cap) return cap_reached(i, &a->seg[i], cap);
        k += 1.0;
        st = dh_queue_target_f32(&p->qu, &p->t, (float)p->dt, &cmd);
        if (st == DH_OK) st = dh_track_step_f32(&p->t, &cmd.T, q, &trep);
        if (st == DH_OK) st = dh_queue_advance_f32(&p->qu, trep.state, &rep);
        if (st != DH_OK) return seg_error(i, &a->seg[i], "a control period failed", dh_status_str(st));
        if ((rc = move_line(p, q, (int)trep.state)) != 0) return rc;
        if (rep.done) {
            i++;
            k = 0.0;
        }
    }
    return 0;
}

static int move_run(const move_args *a, move_plan *p)
{
    float q[DH_MAX_JOINTS];
    unsigned i;
    int tracking = 0, rc = 0;
    memcpy(q, p->q0, sizeof q);
    for (i = 0; i < p->r.n; i++) {
        char text[32];
        (void)snprintf(text, sizeof text, i == 0u ? "t,q%u" : ",q%u", i + 1u);
        if (cli_out_add(&p->out, text)) return EXIT_ERR;
    }
    if (cli_out_add(&p->out, ",status\n")) return EXIT_ERR;
    for (i = 0; i < a->nseg && rc == 0; i++) {
        const move_seg *s = &a->seg[i];
        if (s->kind == SEG_JOINT) {
            rc = run_joint(p, i, s, q);
            tracking = 0;
            continue;
        }
        /* the tracker starts (again) where the robot is at rest */
        if (!tracking && (rc = cli_track_start("move", &p->r, &p->m, q, (float)p->dt, &p->t)) != 0) return rc;
        tracking = 1;
        if (p->blend >= 0.0f) {
            /* with --blend: this segment and the Cartesian ones after it */
            unsigned e = i + 1u;
            while (e < a->nseg && a->seg[e].kind != SEG_JOINT) e++;
            rc = run_blend(p, a, i, e, q);
            i = e - 1u;
        } else {
            rc = run_path(p, i, s, q);
        }
    }
    return rc;
}

/* ---- --fixed: the fixed-point executor and tracker ---------------------------- */

/* --fixed with an option the fixed-point motion API does not offer: exit 2 */
static int move_fixed_check(const move_args *a)
{
    if (a->jerk && a->blend)
        return cli_error("move --fixed --jerk --blend", "the fixed-point blended corners are not jerk-limited; run "
                         "--fixed --jerk without --blend, or --blend --jerk without --fixed");
    return 0;
}

/* one CSV line of fixed joint values (Q16.16 degrees, dh_qpos lengths) */
static int move_line_q(move_plan *p, const int32_t *q, int state)
{
    const double one = (double)((int32_t)1 << DH_QPOS_FRAC);
    char text[64];
    unsigned j;
    if (move_line_start(p, state)) return EXIT_ERR;
    for (j = 0; j < p->r.n; j++) {
        const double v = q[j] / ((p->r.joint[j].type == DH_JOINT_REVOLUTE) ? 65536.0 : one);
        (void)snprintf(text, sizeof text, ",%.9g", v == 0.0 ? 0.0 : v);
        if (cli_out_add(&p->out, text)) return EXIT_ERR;
    }
    (void)snprintf(text, sizeof text, ",%s\n", k_state_word[state]);
    return cli_out_add(&p->out, text);
}

/* n joint values in degrees / length units into Q16.16 / dh_qpos */
static int move_to_q(const dh_robot *r, const double *v, const char *what, int32_t *q)
{
    const double one = (double)((int32_t)1 << DH_QPOS_FRAC);
    unsigned i;
    for (i = 0; i < r->n; i++) {
        const double x = floor(v[i] * ((r->joint[i].type == DH_JOINT_REVOLUTE) ? 65536.0 : one) + 0.5);
        if (!(fabs(x) < 2147483647.0)) return cli_error(what, "a joint value does not fit the fixed-point format");
        q[i] = (int32_t)x;
    }
    return 0;
}

/* a Cartesian limit scaled to its fixed format: at least 1 LSB, below 2^31 */
static int move_lim_q(const char *opt, float v, double scale, int32_t *out)
{
    const double x = floor((double)v * scale);
    if (!(x >= 1.0 && x < 2147483647.0))
        return cli_error(opt, "out of the fixed-point range (1 LSB .. 32767 units per second^k at Q16.16)");
    *out = (int32_t)x;
    return 0;
}

/* --fixed --jerk with a joint segment: every joint's jerk limit J in its
 * fixed format (Q16.16 deg/s^3, dh_qpos/s^3) */
static int move_jerk_q(const move_args *a, move_plan *p)
{
    const double one = (double)((int32_t)1 << DH_QPOS_FRAC);
    unsigned i, joint = 0;
    int rc;
    for (i = 0; i < a->nseg; i++) joint += a->seg[i].kind == SEG_JOINT;
    for (i = 0; i < p->r.n && p->jerk && joint; i++) {
        const double scale = (p->r.joint[i].type == DH_JOINT_REVOLUTE) ? 65536.0 : one;
        if ((rc = move_lim_q("--jerk", p->jmax[i], scale, &p->jq[i])) != 0) return rc;
    }
    return 0;
}

/* The fixed-point set-up: dt in whole microseconds, the robot's fixed path,
 * q0 and the limits in their formats, the closed-form model (*mp) */
static int move_fixed_setup(const move_args *a, move_plan *p, uint32_t *us, int32_t *q, dh_cart_limits_q *lim,
                            dh_ikc_model_q *m, const dh_ikc_model_q **mp)
{
    const double u = p->dt * 1e6, one = (double)((int32_t)1 << DH_QPOS_FRAC);
    double q0d[DH_MAX_JOINTS];
    int rc;
    if (!(u >= 1.0 && u <= 1e6) || fabs(u - floor(u + 0.5)) > 1e-6 * u)
        return cli_error("--dt", "with --fixed the control period must be a whole number of microseconds, at most 1 s");
    *us = (uint32_t)floor(u + 0.5);
    if ((p->r.flags & DH_ROBOT_HAS_Q) == 0u)
        return cli_error("move --fixed", "the robot's constants do not fit the fixed-point formats");
    if ((rc = cli_parse_list(a->q0, p->r.n, q0d, "--q0")) != 0) return rc;
    if ((rc = move_to_q(&p->r, q0d, "--q0", q)) != 0) return rc;
    memset(lim, 0, sizeof *lim);
    if (p->lim.vmax > 0.0f) {
        if ((rc = move_lim_q("--speed", p->lim.vmax, one, &lim->vmax)) != 0) return rc;
        if ((rc = move_lim_q("--accel", p->lim.amax, one, &lim->amax)) != 0) return rc;
        if ((rc = move_lim_q("--rspeed", p->lim.wmax, 65536.0, &lim->wmax)) != 0) return rc;
        if ((rc = move_lim_q("--raccel", p->lim.wdmax, 65536.0, &lim->wdmax)) != 0) return rc;
        if (p->jerk && (rc = move_lim_q("--jerk", p->cj.jmax, one, &p->cjq.jmax)) != 0) return rc;
        if (p->jerk && (rc = move_lim_q("--jerk (the angular jerk J * raccel / accel)", p->cj.wjmax, 65536.0,
                                        &p->cjq.wjmax)) != 0)
            return rc;
    }
    if ((rc = move_jerk_q(a, p)) != 0) return rc;
    *mp = (dh_ikc_analyse_q(&p->r, m) == DH_OK && m->kind != DH_IKC_NONE) ? m : NULL;
    return 0;
}

/* the fixed path of line or arc segment i from F: its end from the float
 * plan's end frame, an arc's via point its float arc's midpoint */
static int plan_path_q(move_plan *p, unsigned i, const move_seg *s, const dh_frame_q *F, dh_path_q *path,
                       dh_frame_q *B)
{
    dh_mat4_f32 M;
    dh_qpos via[3];
    unsigned k;
    dh_status st;
    if (dh_frame_from_mat4_q(&p->path[i].B, B) != DH_OK)
        return seg_error(i, s, "the end frame is not representable in fixed point", NULL);
    if (s->kind == SEG_LINE) {
        st = dh_path_line_q(path, F, B);
    } else {
        (void)dh_path_eval_f32(&p->path[i], 0.5f, &M);
        for (k = 0; k < 3u; k++) {
            const double x = floor((double)DH_M4(&M, k, 3) * (double)((int32_t)1 << DH_QPOS_FRAC) + 0.5);
            if (!(fabs(x) < 2147483647.0)) return seg_error(i, s, "the arc is not representable in fixed point", NULL);
            via[k] = (dh_qpos)x;
        }
        st = dh_path_arc_q(path, F, via, B);
    }
    if (st != DH_OK) return seg_error(i, s, "no fixed-point path from the previous segment's end", path_why(st));
    return 0;
}

/* segment i (fixed, a joint move or a line or arc) appended to the fixed
 * queue qu, from F (updated to its end: B, or the FK of a joint move's
 * end); with --blend a line or arc as a blended path (its corner with
 * the next line or arc blended within the radius) */
static int queue_add_q(move_plan *p, unsigned i, const move_seg *s, dh_queue_q *qu, const dh_cart_limits_q *lim,
                       dh_frame_q *F)
{
    static dh_path_q path;
    int32_t q1[DH_MAX_JOINTS], vq[DH_MAX_JOINTS], aq[DH_MAX_JOINTS];
    double v[DH_MAX_JOINTS];
    dh_frame_q B;
    unsigned j;
    int rc;
    dh_status st;
    if (s->kind == SEG_JOINT) {
        if ((rc = cli_parse_list(s->a, p->r.n, v, "--joint")) != 0) return rc;
        if ((rc = move_to_q(&p->r, v, "--joint", q1)) != 0) return rc;
        for (j = 0; j < p->r.n; j++) {
            vq[j] = p->r.joint[j].vmax_q;
            aq[j] = p->r.joint[j].amax_q;
        }
        st = dh_queue_add_joint_q(qu, p->r.n, q1, vq, aq, p->jerk ? p->jq : NULL);
        if (st != DH_OK) return seg_error(i, s, "the fixed-point joint move cannot be queued", dh_status_str(st));
        if ((st = dh_fk_q(&p->r, q1, F)) != DH_OK) return seg_error(i, s, "FK of the end", dh_status_str(st));
        return 0;
    }
    if ((rc = plan_path_q(p, i, s, F, &path, &B)) != 0) return rc;
    if (p->blend >= 0.0f) {
        const double R = floor((double)p->blend * (double)((int32_t)1 << DH_QPOS_FRAC) + 0.5);
        if (!(R < 2147483647.0)) return cli_error("--blend", "the radius does not fit the fixed-point length format");
        st = dh_queue_add_path_blend_q(qu, &path, lim, (dh_qpos)R);
    } else {
        st = dh_queue_add_path_jerk_q(qu, &path, lim, p->jerk ? &p->cjq : NULL);
    }
    if (st != DH_OK) return seg_error(i, s, "the fixed-point move along the path cannot be planned", path_why(st));
    *F = B;
    return 0;
}

/* Segments i0 .. i1 - 1 (fixed; joint moves, lines and arcs, with
 * --blend the corners between lines and arcs blended) run by the fixed
 * queue (dh_queue_q), appended as it drains (MOVE_QUEUE_CAP >= 3: a
 * path's corner with the next is planned when the next is appended,
 * before the path starts): joint commands go to the robot as they are, path frames
 * through the tracker t (started again at the last joint command when the
 * queue says so), whose lagging periods slow the move down (its feed
 * override). F is where the first starts (updated to the last end); t and
 * q end at the last move's end, the tracker started there after a joint
 * move. */
static int run_queue_q(move_plan *p, const move_args *a, unsigned i0, unsigned i1, dh_frame_q *F,
                       const dh_cart_limits_q *lim, dh_track_q *t, const dh_ikc_model_q *mp, int32_t *q)
{
    static dh_queue_item_q items[MOVE_QUEUE_CAP];
    static dh_queue_q qu;
    dh_queue_cmd_q cmd;
    dh_queue_report_q rep;
    dh_track_report_q trep;
    double cap, k = 0.0;
    unsigned next = i0, at;
    uint32_t seq = 0u;
    int rc;
    dh_status st = dh_queue_init_q(&qu, items, MOVE_QUEUE_CAP);
    if (st != DH_OK) return cli_error("move --fixed: the queue", dh_status_str(st));
    for (;;) {
        dh_track_state state = DH_TRACK_OK;
        while (next < i1 && qu.count < qu.cap) {
            if ((rc = queue_add_q(p, next, &a->seg[next], &qu, lim, F)) != 0) return rc;
            next++;
        }
        if (qu.count == 0u) break;
        at = i0 + qu.seq;
        if (qu.seq != seq) k = 0.0;
        seq = qu.seq;
        cap = move_cap(p, qu.started ? (float)(qu.mv.dur * 1e-6) : 0.0f);
        if (k >= cap) return cap_reached(at, &a->seg[at], cap);
        k += 1.0;
        st = dh_queue_target_q(&qu, t, &cmd);
        if (st != DH_OK) return seg_error(at, &a->seg[at], "the fixed-point queue cannot start it", dh_status_str(st));
        if (cmd.kind == DH_MOVE_PATH) {
            if (cmd.sync) st = dh_track_init_q(t, &p->r, mp, cmd.q, t->dt_us);
            if (st == DH_OK) st = dh_track_step_q(t, &cmd.T, q, &trep);
            state = trep.state;
        } else if (cmd.kind == DH_MOVE_JOINT) {
            memcpy(q, cmd.q, p->r.n * sizeof q[0]);
        }
        if (st == DH_OK) st = dh_queue_advance_q(&qu, state, &rep);
        if (st != DH_OK) return seg_error(at, &a->seg[at], "a control period failed", dh_status_str(st));
        if ((rc = move_line_q(p, q, (int)state)) != 0) return rc;
    }
    /* after a joint move the tracker starts again at its end, at rest */
    if (qu.hold == DH_MOVE_JOINT && (st = dh_track_init_q(t, &p->r, mp, q, t->dt_us)) != DH_OK)
        return cli_error("move --fixed: the tracker", dh_status_str(st));
    return 0;
}

/* move --fixed: every segment through the fixed queue and tracker */
static int move_run_fixed(const move_args *a, move_plan *p)
{
    static dh_ikc_model_q m;
    static dh_track_q t;
    const dh_ikc_model_q *mp = NULL;
    int32_t q[DH_MAX_JOINTS];
    dh_cart_limits_q lim;
    dh_frame_q F;
    uint32_t us = 0u;
    unsigned i;
    int rc;
    dh_status st;
    if ((rc = move_fixed_setup(a, p, &us, q, &lim, &m, &mp)) != 0) return rc;
    for (i = 0; i < p->r.n; i++) {
        char text[32];
        (void)snprintf(text, sizeof text, i == 0u ? "t,q%u" : ",q%u", i + 1u);
        if (cli_out_add(&p->out, text)) return EXIT_ERR;
    }
    if (cli_out_add(&p->out, ",status\n")) return EXIT_ERR;
    if ((st = dh_fk_q(&p->r, q, &F)) != DH_OK) return cli_error("move --fixed: FK of --q0", dh_status_str(st));
    st = dh_track_init_q(&t, &p->r, mp, q, us);
    if (st == DH_ERR_LIMIT) return cli_error("--q0", "a joint value is outside its limits");
    if (st != DH_OK) return cli_error("move --fixed: the tracker", dh_status_str(st));
    return run_queue_q(p, a, 0u, a->nseg, &F, &lim, &t, mp, q);
}

int cli_cmd_move(int argc, char **argv)
{
    static move_args a;
    static move_plan p;
    double q0d[DH_MAX_JOINTS];
    unsigned i, cart = 0;
    int rc;
    dh_status st;
    if ((rc = move_parse(argc, argv, &a)) != 0) return rc;
    if (a.fixed && (rc = move_fixed_check(&a)) != 0) return rc;
    for (i = 0; i < a.nseg; i++) cart += a.seg[i].kind != SEG_JOINT;
    memset(&p, 0, sizeof p);
    p.blend = -1.0f;
    if (a.blend && (rc = move_blend(&a, &p.blend)) != 0) return rc;
    if ((rc = cli_parse_dt(a.dt, &p.dt)) != 0) return rc;
    if ((rc = cli_load_robot(a.robot, a.fixed, &p.r, &p.rf)) != 0) return rc;
    if ((rc = cli_parse_list(a.q0, p.r.n, q0d, "--q0")) != 0) return rc;
    for (i = 0; i < p.r.n; i++) p.q0[i] = (float)q0d[i];
    st = dh_robot_check_limits_f32(&p.r, p.q0);
    if (st == DH_ERR_NAN) return cli_error("--q0", "a joint value is not finite in float");
    if (st != DH_OK) return cli_error("--q0", "a joint value is outside its limits");
    if ((rc = cli_joint_rates("move", "--vmax", a.vmax, &p.r, p.vmax)) != 0) return rc;
    if ((rc = cli_joint_rates("move", "--amax", a.amax, &p.r, p.amax)) != 0) return rc;
    for (i = 0; i < p.r.n; i++) {
        st = dh_robot_set_rates_f32(&p.r, i, p.vmax[i], p.amax[i]);
        if (st != DH_OK) return cli_error("--vmax/--amax rejected by the library", dh_status_str(st));
    }
    if (a.jerk) {
        float j;
        if ((rc = move_limit("--jerk", a.jerk, "deg/s^3", &j)) != 0) return rc;
        for (i = 0; i < p.r.n; i++) p.jmax[i] = j;
        p.jerk = 1;
    }
    if (cart) {
        if ((rc = move_limit("--speed", a.speed, "length unit/s", &p.lim.vmax)) != 0) return rc;
        if ((rc = move_limit("--accel", a.accel, "length unit/s^2", &p.lim.amax)) != 0) return rc;
        if ((rc = move_limit("--rspeed", a.rspeed, "deg/s", &p.lim.wmax)) != 0) return rc;
        if ((rc = move_limit("--raccel", a.raccel, "deg/s^2", &p.lim.wdmax)) != 0) return rc;
        if (p.jerk) {
            /* J is the tool's linear jerk; the angular jerk limit gives the
             * rotation the same jerk time as the translation:
             * raccel / wjmax = accel / J */
            if ((rc = move_limit("--jerk", a.jerk, "length unit/s^3", &p.cj.jmax)) != 0) return rc;
            p.cj.wjmax = (float)((double)p.cj.jmax * (double)p.lim.wdmax / (double)p.lim.amax);
            if (!(p.cj.wjmax > 0.0f) || p.cj.wjmax > FLT_MAX)
                return cli_error("move --jerk", "the angular jerk limit J * raccel / accel is not a positive float");
        }
    }
    if ((rc = move_plan_segments(&a, &p)) != 0) return rc;
    rc = a.fixed ? move_run_fixed(&a, &p) : move_run(&a, &p);
    if (rc == EXIT_ERR || rc == EXIT_USAGE) {
        free(p.out.buf);
        return rc;
    }
    if (rc == 0 && p.bad > 0.0)
        fprintf(stderr, "dhmath: move: completed with %.0f of %.0f control periods lagging or unreachable\n", p.bad,
                p.periods);
    if (p.out.len) fwrite(p.out.buf, 1, p.out.len, stdout);
    free(p.out.buf);
    if (cli_finish()) return EXIT_ERR;
    return (rc != 0 || p.bad > 0.0) ? EXIT_NOCONV : 0;
}
