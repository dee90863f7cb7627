/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dhmath.c - host command-line tool over the dhmath library.
 *
 * Exit status: 0 success, 2 any error (usage, EXPR, robot file, numbers,
 * library status), 3 `ik` did not converge (best joint values printed),
 * `ik --all` found no solution, or `move` had periods not ok or met its
 * period cap (the periods run are printed).
 * On status 2 nothing is written to stdout: every result is computed and
 * checked before the first byte is printed.
 * See docs/cli.md for the reference.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dh_cli.h"
#include "dh_expr.h"
#include "dh_move_cmd.h"
#include "dh_gen.h"
#include "dh_robotfile.h"
#include "dhmath/frame.h"
#include "dhmath/ikc.h"
#include "dhmath/kin.h"
#include "dhmath/mat4.h"
#include "dhmath/robot.h"
#include "dhmath/rot.h"
#include "dhmath/track.h"
#include "dhmath/dhmath.h"


static const char k_usage[] =
    "usage: dhmath COMMAND [options] ARGS\n"
    "\n"
    "commands:\n"
    "  eval [--fixed] EXPR             4x4 matrix of EXPR (4 lines of 4 numbers)\n"
    "  axis EXPR                       equivalent axis and angle: kx ky kz theta_deg\n"
    "  point EXPR x y z [w]            transformed homogeneous point: x y z w\n"
    "  plane EXPR a b c d              transformed plane [a b c d] * EXPR^-1\n"
    "  fk [--fixed] [--frames] [--expr] ROBOT q1,q2,...\n"
    "                                  end frame (with --frames: every joint frame,\n"
    "                                  then the end frame, separated by blank lines;\n"
    "                                  with --expr: each frame as one EXPR line)\n"
    "  jacobian [--fixed] ROBOT q1,q2,...\n"
    "                                  6 x n geometric Jacobian in the base frame\n"
    "                                  (rows vx vy vz wx wy wz; per radian for R joints)\n"
    "  ik [--fixed] [--q0 q1,...] [--position] [--tol-pos X] [--tol-rot RAD] [--w-rot X]\n"
    "     [--max-iter N] ROBOT EXPR    joint values reaching EXPR; status on stderr;\n"
    "                                  exit 0 converged, 3 not converged\n"
    "  ik --all [--fixed] [--q0 q1,...] ROBOT EXPR\n"
    "                                  every closed-form solution within the limits,\n"
    "                                  one per line (--q0: reference for the 360-degree\n"
    "                                  shifts and singular splits; --fixed: the robot's\n"
    "                                  fixed-point path); exit 0 at least one,\n"
    "                                  3 none, 2 no closed form for the robot\n"
    "  euler [--fixed] SEQ EXPR        Euler angles in degrees of EXPR's rotation; SEQ as\n"
    "                                  scipy Rotation: XYZ intrinsic (Rot(x,a) Rot(y,b)\n"
    "                                  Rot(z,c)), xyz extrinsic; 24 sequences\n"
    "  quat [--fixed] EXPR             unit quaternion of EXPR's rotation: w x y z (w >= 0)\n"
    "  gen ROBOT NAME                  C source defining const dh_robot NAME (flash)\n"
    "  track ROBOT --q0 q1,... --dt SECONDS [--vmax V] [--fixed]\n"
    "                                  tracking IK: one target EXPR per line on stdin,\n"
    "                                  one line per target: n joint values, ok|lagging|\n"
    "                                  unreachable, position error, rotation error (rad);\n"
    "                                  V: deg/s (length unit/s), one value or n values;\n"
    "                                  default the robot file's vmax=\n"
    ;

static const char k_usage_tail[] =
    "  help                            this text\n"
    "  --version                       program and library version\n"
    "\n"
    "EXPR: product, left to right, of terms separated by spaces or '*':\n"
    "  trans(x,y,z) rotx(deg) roty(deg) rotz(deg) rot(kx,ky,kz,deg)\n"
    "  scale(sx,sy,sz) persp(x|y|z,f) ident inv(EXPR)\n"
    "  e.g. dhmath eval \"trans(4,-3,7) roty(90) rotz(90)\"\n"
    "Joint values: degrees for revolute joints, length units for prismatic.\n"
    "'-' as EXPR or ROBOT reads it from standard input (once per command).\n"
    "--fixed: the integer-only fixed-point path (angles Q16.16 degrees, rotations Q2.30,\n"
    "lengths with DH_QPOS_FRAC fraction bits), printed in the same units as without it.\n"
    "Numbers are printed with %.9g. Exit status: 0 ok, 2 error, 3 ik not converged or no solution,\n"
    "move lagging, unreachable or not completed.\n";

/* ---- messages ----------------------------------------------------------- */




/* ---- output ------------------------------------------------------------- */

/* -0 prints as 0 */
static void put_num(double v, int last)
{
    if (v == 0.0) v = 0.0;
    printf(last ? "%.9g\n" : "%.9g ", v);
}

typedef struct { double m[4][4]; } rows4;

static void print_rows(const rows4 *R)
{
    unsigned r, c;
    for (r = 0; r < 4u; r++)
        for (c = 0; c < 4u; c++) put_num(R->m[r][c], c == 3u);
}

static void mat_to_rows(const dh_mat4_f32 *T, rows4 *R)
{
    unsigned r, c;
    for (r = 0; r < 4u; r++)
        for (c = 0; c < 4u; c++) R->m[r][c] = (double)DH_M4(T, r, c);
}

static void frame_to_rows(const dh_frame_q *F, rows4 *R)
{
    double (*M)[4] = R->m;
    const double rs = 1.0 / 1073741824.0;
    const double ps = 1.0 / (double)((int32_t)1 << DH_QPOS_FRAC);
    unsigned r, c;
    for (r = 0; r < 3u; r++) {
        for (c = 0; c < 3u; c++) M[r][c] = (double)F->r[c][r] * rs;
        M[r][3] = (double)F->p[r] * ps;
        M[3][r] = 0.0;
    }
    M[3][3] = 1.0;
}

static int rows_finite(const rows4 *R)
{
    unsigned r, c;
    for (r = 0; r < 4u; r++)
        for (c = 0; c < 4u; c++)
            if (!isfinite(R->m[r][c])) return 0;
    return 1;
}


/* ---- argument helpers --------------------------------------------------- */

typedef struct {
    int fixed, frames, position, expr, all;
    const char *q0;
    const char *tol_pos, *tol_rot, *w_rot, *max_iter, *dt, *vmax;
    const char *pos[8];
    int npos;
    int nstdin;               /* positional "-" arguments (standard input) */
} opts;

/* Split argv into options and positional arguments. Negative numbers are
 * positional; anything else starting with "--" must be a known option, given
 * at most once. "-" (standard input) may be given once. */
static int parse_opts(int argc, char **argv, opts *o, const char *allowed)
{
    int k, only_pos = 0;
    memset(o, 0, sizeof *o);
    for (k = 0; k < argc; k++) {
        const char *a = argv[k];
        if (!only_pos && a[0] == '-' && a[1] == '-') {
            const char *name = a + 2;
            int *flag = NULL;
            if (a[2] == '\0') { only_pos = 1; continue; }
            if (strcmp(name, "fixed") == 0 && strstr(allowed, "fixed")) flag = &o->fixed;
            else if (strcmp(name, "frames") == 0 && strstr(allowed, "frames")) flag = &o->frames;
            else if (strcmp(name, "position") == 0 && strstr(allowed, "position")) flag = &o->position;
            else if (strcmp(name, "expr") == 0 && strstr(allowed, "expr")) flag = &o->expr;
            else if (strcmp(name, "all") == 0 && strstr(allowed, "all")) flag = &o->all;
            if (flag) {
                if (*flag) return cli_usage_error("option '%s' given more than once", a);
                *flag = 1;
            } else {
                /* options with a value: --name VALUE or --name=VALUE */
                static const char *const valued[] = { "q0", "tol-pos", "tol-rot", "w-rot", "max-iter", "dt",
                                                      "vmax" };
                const char **slot[7];
                size_t v, nl;
                const char *eq = strchr(name, '=');
                slot[0] = &o->q0;
                slot[1] = &o->tol_pos;
                slot[2] = &o->tol_rot;
                slot[3] = &o->w_rot;
                slot[4] = &o->max_iter;
                slot[5] = &o->dt;
                slot[6] = &o->vmax;
                nl = eq ? (size_t)(eq - name) : strlen(name);
                for (v = 0; v < 7u; v++)
                    if (strlen(valued[v]) == nl && strncmp(name, valued[v], nl) == 0 && strstr(allowed, valued[v]))
                        break;
                if (v == 7u) return cli_usage_error("unknown or inapplicable option '%s'", a);
                if (*slot[v]) return cli_usage_error("option '%s' given more than once", a);
                if (eq) *slot[v] = eq + 1;
                else if (k + 1 < argc) *slot[v] = argv[++k];
                else return cli_usage_error("option '%s' needs a value", a);
            }
            continue;
        }
        if (!only_pos && a[0] == '-' && a[1] != '\0' && a[1] != '.' && (a[1] < '0' || a[1] > '9'))
            return cli_usage_error("unknown option '%s'", a);
        if (o->npos >= (int)(sizeof o->pos / sizeof o->pos[0]))
            return cli_usage_error("too many arguments (at '%s')", a);
        if (strcmp(a, "-") == 0 && o->nstdin++)
            return cli_usage_error("'%s' (standard input) given more than once", a);
        o->pos[o->npos++] = a;
    }
    return 0;
}




/* A projective EXPR (bottom row not 0 0 0 1, e.g. persp) has no rotation:
 * the error for axis, euler and quat (ik rejects such a target too). */
static int projective_error(const char *cmd, const dh_mat4_f32 *T)
{
    if (DH_M4(T, 3, 0) == 0.0f && DH_M4(T, 3, 1) == 0.0f && DH_M4(T, 3, 2) == 0.0f && DH_M4(T, 3, 3) == 1.0f)
        return 0;
    fprintf(stderr, "dhmath: error: %s: EXPR is not rigid: its bottom row is %.9g %.9g %.9g %.9g, not 0 0 0 1 "
            "(a perspective transform has no rotation)\n", cmd, (double)DH_M4(T, 3, 0), (double)DH_M4(T, 3, 1),
            (double)DH_M4(T, 3, 2), (double)DH_M4(T, 3, 3));
    return EXIT_ERR;
}




/* ---- commands ----------------------------------------------------------- */

static int cmd_eval(int argc, char **argv)
{
    opts o;
    rows4 M;
    int rc = parse_opts(argc, argv, &o, "fixed");
    if (rc) return rc;
    if (o.npos != 1) return cli_usage_error("eval takes one EXPR (quote it): dhmath eval [--fixed] EXPR", NULL);
    if (o.fixed) {
        dh_frame_q F;
        if ((rc = cli_eval_expr_arg(o.pos[0], 1, NULL, &F)) != 0) return rc;
        frame_to_rows(&F, &M);
    } else {
        dh_mat4_f32 T;
        if ((rc = cli_eval_expr(o.pos[0], &T)) != 0) return rc;
        mat_to_rows(&T, &M);
    }
    if (!rows_finite(&M)) return cli_error("result is not finite", NULL);
    print_rows(&M);
    return cli_finish();
}

static int cmd_axis(int argc, char **argv)
{
    opts o;
    dh_mat4_f32 T;
    dh_vec3_f32 k;
    float th = 0.0f;
    dh_status st;
    int rc = parse_opts(argc, argv, &o, "");
    if (rc) return rc;
    if (o.npos != 1) return cli_usage_error("axis takes one EXPR: dhmath axis EXPR", NULL);
    if ((rc = cli_eval_expr(o.pos[0], &T)) != 0) return rc;
    if ((rc = projective_error("axis", &T)) != 0) return rc;
    st = dh_mat4_to_axis_angle_f32(&T, &k, &th);
    if (st != DH_OK) return cli_error("axis: the rotation part of EXPR has no axis/angle", dh_status_str(st));
    if (!isfinite(k.x) || !isfinite(k.y) || !isfinite(k.z) || !isfinite(th))
        return cli_error("axis: result is not finite", NULL);
    put_num(k.x, 0);
    put_num(k.y, 0);
    put_num(k.z, 0);
    put_num(th, 1);
    return cli_finish();
}

/* Prints a, b, c, d on one line and finishes; the message when one is not finite. */
static int put_four(float a, float b, float c, float d, const char *not_finite)
{
    if (!isfinite(a) || !isfinite(b) || !isfinite(c) || !isfinite(d)) return cli_error(not_finite, NULL);
    put_num(a, 0);
    put_num(b, 0);
    put_num(c, 0);
    put_num(d, 1);
    return cli_finish();
}

static int cmd_point(int argc, char **argv)
{
    opts o;
    dh_mat4_f32 T;
    dh_vec4_f32 u, v;
    double x[4] = { 0.0, 0.0, 0.0, 1.0 };
    static const char *const names[4] = { "x", "y", "z", "w" };
    int rc = parse_opts(argc, argv, &o, ""), k;
    if (rc) return rc;
    if (o.npos != 4 && o.npos != 5) return cli_usage_error("point takes EXPR x y z [w]", NULL);
    if ((rc = cli_eval_expr(o.pos[0], &T)) != 0) return rc;
    for (k = 0; k + 1 < o.npos; k++)
        if ((rc = cli_parse_num(o.pos[k + 1], names[k], &x[k])) != 0) return rc;
    u.x = (float)x[0];
    u.y = (float)x[1];
    u.z = (float)x[2];
    u.w = (float)x[3];
    dh_mat4_apply_vec4_f32(&T, &u, &v);
    return put_four(v.x, v.y, v.z, v.w, "point: result is not finite (float overflow)");
}

static int cmd_plane(int argc, char **argv)
{
    opts o;
    dh_mat4_f32 T;
    dh_plane_f32 P, Q;
    double x[4];
    static const char *const names[4] = { "a", "b", "c", "d" };
    dh_status st;
    int rc = parse_opts(argc, argv, &o, ""), k;
    if (rc) return rc;
    if (o.npos != 5) return cli_usage_error("plane takes EXPR a b c d", NULL);
    if ((rc = cli_eval_expr(o.pos[0], &T)) != 0) return rc;
    for (k = 0; k < 4; k++)
        if ((rc = cli_parse_num(o.pos[k + 1], names[k], &x[k])) != 0) return rc;
    P.a = (float)x[0];
    P.b = (float)x[1];
    P.c = (float)x[2];
    P.d = (float)x[3];
    st = dh_mat4_apply_plane_f32(&T, &P, &Q);
    if (st == DH_ERR_SINGULAR)
        return cli_error("plane: EXPR is singular (a plane transforms with the inverse)", NULL);
    if (st != DH_OK) return cli_error("plane", dh_status_str(st));
    return put_four(Q.a, Q.b, Q.c, Q.d, "plane: result is not finite (float overflow)");
}

static void warn_limits(const dh_robot *r, const float *q)
{
    unsigned k;
    if (dh_robot_check_limits_f32(r, q) == DH_OK) return;
    for (k = 0; k < r->n; k++) {
        const dh_joint *j = &r->joint[k];
        if (j->qmin <= j->qmax && (q[k] < j->qmin || q[k] > j->qmax))
            fprintf(stderr, "dhmath: warning: joint %u value %.9g outside its limits [%.9g, %.9g]\n",
                    k + 1, (double)q[k], (double)j->qmin, (double)j->qmax);
    }
}

static double clean0(double v)
{
    return v == 0.0 ? 0.0 : v;
}

/* "trans(px,py,pz) rot(kx,ky,kz,theta)" of a rigid frame (axis via the library) */
static int frame_expr(const rows4 *R, char *buf, size_t cap)
{
    dh_mat4_f32 T;
    dh_vec3_f32 k;
    float th = 0.0f;
    unsigned r, c;
    for (r = 0; r < 4u; r++)
        for (c = 0; c < 4u; c++) DH_M4(&T, r, c) = (float)R->m[r][c];
    if (dh_mat4_to_axis_angle_f32(&T, &k, &th) != DH_OK) return -1;
    if (th == 0.0f) {
        k.x = 0.0f;
        k.y = 0.0f;
        k.z = 1.0f;
    }
    (void)snprintf(buf, cap, "trans(%.9g,%.9g,%.9g) rot(%.9g,%.9g,%.9g,%.9g)", clean0(R->m[0][3]),
                   clean0(R->m[1][3]), clean0(R->m[2][3]), clean0(k.x), clean0(k.y), clean0(k.z), clean0(th));
    return 0;
}

/* joint values (deg / length units) rounded to the fixed formats: dh_q16
 * degrees (revolute), dh_qpos (prismatic); an error when one does not fit */
static int joints_to_q(const dh_robot *r, const double *qd, int32_t *q)
{
    const double pscale = (double)((int32_t)1 << DH_QPOS_FRAC);
    unsigned k;
    for (k = 0; k < r->n; k++) {
        double s = r->joint[k].type == DH_JOINT_REVOLUTE ? 65536.0 : pscale;
        double v = floor(qd[k] * s + 0.5);
        if (v > 2147483647.0 || v < -2147483648.0) {
            fprintf(stderr, "dhmath: error: overflow: joint value %u (%.9g) does not fit %s\n", k + 1,
                    qd[k], r->joint[k].type == DH_JOINT_REVOLUTE ? "degrees Q16.16" : "the fixed-point length format");
            return EXIT_ERR;
        }
        q[k] = (int32_t)v;
    }
    return 0;
}

static int cmd_fk(int argc, char **argv)
{
    opts o;
    dh_robot r;
    dh_robotfile rf;
    double qd[DH_MAX_JOINTS];
    rows4 M[DH_MAX_JOINTS + 1];
    unsigned n, k, nout;
    dh_status st;
    int rc = parse_opts(argc, argv, &o, "fixed frames expr");
    if (rc) return rc;
    if (o.npos != 2) return cli_usage_error("fk takes ROBOTFILE q1,q2,...", NULL);
    if (o.expr && o.fixed) return cli_usage_error("fk: --expr and --fixed cannot be combined", NULL);
    if ((rc = cli_load_robot(o.pos[0], o.fixed, &r, &rf)) != 0) return rc;
    n = r.n;
    if ((rc = cli_parse_list(o.pos[1], n, qd, "joint values")) != 0) return rc;
    if (o.fixed) {
        int32_t q[DH_MAX_JOINTS];
        dh_frame_q frames[DH_MAX_JOINTS], Tend;
        if ((rc = joints_to_q(&r, qd, q)) != 0) return rc;
        if (o.frames) st = dh_fk_frames_q(&r, q, frames, &Tend);
        else st = dh_fk_q(&r, q, &Tend);
        if (st == DH_ERR_UNAVAILABLE)
            return cli_error("fk --fixed: a constant of the robot does not fit the fixed-point formats", NULL);
        if (st == DH_ERR_OVERFLOW) {
            fprintf(stderr, "dhmath: error: overflow: fk --fixed: an entry of a frame of the chain saturates "
                    "(positions must lie in the fixed-point length format Q%d.%d, |x| < %ld length units; rotation "
                    "entries in Q2.30); fk without --fixed computes it in float\n", 32 - DH_QPOS_FRAC, DH_QPOS_FRAC,
                    1L << (31 - DH_QPOS_FRAC));
            return EXIT_ERR;
        }
        if (st != DH_OK) return cli_error("fk --fixed", dh_status_str(st));
        nout = 0;
        if (o.frames)
            for (k = 0; k < n; k++) frame_to_rows(&frames[k], &M[nout++]);
        frame_to_rows(&Tend, &M[nout++]);
    } else {
        float q[DH_MAX_JOINTS];
        dh_mat4_f32 frames[DH_MAX_JOINTS], Tend;
        for (k = 0; k < n; k++) q[k] = (float)qd[k];
        if (o.frames) st = dh_fk_frames_f32(&r, q, frames, &Tend);
        else st = dh_fk_f32(&r, q, &Tend);
        if (st != DH_OK) return cli_error("fk", dh_status_str(st));
        nout = 0;
        if (o.frames)
            for (k = 0; k < n; k++) mat_to_rows(&frames[k], &M[nout++]);
        mat_to_rows(&Tend, &M[nout++]);
        warn_limits(&r, q);
    }
    for (k = 0; k < nout; k++)
        if (!rows_finite(&M[k])) return cli_error("fk: result is not finite", NULL);
    if (o.expr) {
        /* each frame as an EXPR that reproduces it: trans(p) rot(k, theta) */
        char line[DH_MAX_JOINTS + 1][200];
        for (k = 0; k < nout; k++)
            if (frame_expr(&M[k], line[k], sizeof line[k])) return cli_error("fk --expr: frame is not rigid", NULL);
        for (k = 0; k < nout; k++) puts(line[k]);
        return cli_finish();
    }
    for (k = 0; k < nout; k++) {
        if (k) putchar('\n');
        print_rows(&M[k]);
    }
    return cli_finish();
}

/* jacobian --fixed: dh_jacobian_q on the robot's fixed path, printed in
 * the float path's units (linear rows per radian in length units, or
 * dimensionless for prismatic joints; angular rows dimensionless) */
static int jacobian_fixed(const dh_robot *r, const double *qd)
{
    int32_t q[DH_MAX_JOINTS], J[6 * DH_MAX_JOINTS];
    const double pscale = (double)((int32_t)1 << DH_QPOS_FRAC);
    const unsigned n = r->n;
    unsigned k, row;
    dh_status st;
    int rc = joints_to_q(r, qd, q);
    if (rc) return rc;
    st = dh_jacobian_q(r, q, J, NULL);
    if (st == DH_ERR_UNAVAILABLE)
        return cli_error("jacobian --fixed: a constant of the robot does not fit the fixed-point formats", NULL);
    if (st == DH_ERR_OVERFLOW) {
        fprintf(stderr, "dhmath: error: overflow: jacobian --fixed: an entry of the chain or of the Jacobian "
                "saturates (lengths and lever arms must lie in the fixed-point length format Q%d.%d, |x| < %ld "
                "length units); jacobian without --fixed computes it in float\n", 32 - DH_QPOS_FRAC, DH_QPOS_FRAC,
                1L << (31 - DH_QPOS_FRAC));
        return EXIT_ERR;
    }
    if (st != DH_OK) return cli_error("jacobian --fixed", dh_status_str(st));
    for (row = 0; row < 6u; row++)
        for (k = 0; k < n; k++) {
            const int lin = row < 3u && r->joint[k].type == DH_JOINT_REVOLUTE;
            put_num((double)J[row * n + k] / (lin ? pscale : 1073741824.0), k + 1 == n);
        }
    return cli_finish();
}

static int cmd_jacobian(int argc, char **argv)
{
    opts o;
    dh_robot r;
    dh_robotfile rf;
    double qd[DH_MAX_JOINTS];
    float q[DH_MAX_JOINTS], J[6 * DH_MAX_JOINTS];
    unsigned n, k, row;
    dh_status st;
    int rc = parse_opts(argc, argv, &o, "fixed");
    if (rc) return rc;
    if (o.npos != 2) return cli_usage_error("jacobian takes ROBOTFILE q1,q2,...", NULL);
    if ((rc = cli_load_robot(o.pos[0], o.fixed, &r, &rf)) != 0) return rc;
    n = r.n;
    if ((rc = cli_parse_list(o.pos[1], n, qd, "joint values")) != 0) return rc;
    for (k = 0; k < n; k++) q[k] = (float)qd[k];
    if (o.fixed) {
        rc = jacobian_fixed(&r, qd);
        if (rc == 0) warn_limits(&r, q);
        return rc;
    }
    st = dh_jacobian_f32(&r, q, J, NULL);
    if (st != DH_OK) return cli_error("jacobian", dh_status_str(st));
    for (k = 0; k < 6u * n; k++)
        if (!isfinite(J[k])) return cli_error("jacobian: result is not finite", NULL);
    for (row = 0; row < 6u; row++)
        for (k = 0; k < n; k++) put_num(J[row * n + k], k + 1 == n);
    warn_limits(&r, q);
    return cli_finish();
}

/* characteristic length: sum of |a| + |d| of the joints plus the base and tool offsets */
static double robot_reach(const dh_robot *r, const dh_robotfile *rf)
{
    double L = 0.0;
    unsigned k;
    for (k = 0; k < rf->n; k++) L += fabs(rf->joint[k].a) + fabs(rf->joint[k].d);
    for (k = 0; k < 3u; k++) L += fabs((double)DH_M4(&r->base, k, 3)) + fabs((double)DH_M4(&r->tool, k, 3));
    return L;
}

/* w_rot accepted by dh_ik_f32: > 0 with w_rot^2 * 16 finite in float (its
 * contract: w_rot <= 4.6e18) */
static int ik_weight_ok(double w)
{
    float f;
    if (!(w > 0.0) || w > (double)FLT_MAX) return 0;
    f = (float)w;
    return isfinite(f * f * 16.0f);
}

/* DH_ERR_NOT_RIGID from dh_ik_f32: which frame is not rigid. The checks are
 * the contract's in its order: the target's bottom row, the target's
 * rotation when the mask drives it, then the end frame's rotation, which is
 * a rotation for any joint values unless the base or the tool is not rigid. */
static int ik_not_rigid(const char *path, const dh_robot *r, const dh_robotfile *rf, const dh_mat4_f32 *target,
                        uint32_t mask)
{
    float e[6];
    if (strcmp(path, "-") == 0) path = "<stdin>";
    if (projective_error("ik", target)) return EXIT_ERR;
    if ((mask & (DH_IK_RX | DH_IK_RY | DH_IK_RZ)) != 0u && dh_pose_error_f32(target, target, e) != DH_OK)
        return cli_error("ik: the rotation part of the target EXPR is not a rotation (not orthonormal with det +1; "
                         "--position ignores it)", NULL);
    if (dh_pose_error_f32(&r->base, &r->base, e) != DH_OK) {
        fprintf(stderr, "dhmath: error: ik: the robot's base (%s:%u) is not rigid: its 3x3 part is not a rotation, "
                "so the end frame has no orientation to match (--position ignores it)\n", path, rf->base.line);
        return EXIT_ERR;
    }
    if (dh_pose_error_f32(&r->tool, &r->tool, e) != DH_OK) {
        fprintf(stderr, "dhmath: error: ik: the robot's tool (%s:%u) is not rigid: its 3x3 part is not a rotation, "
                "so the end frame has no orientation to match (--position ignores it)\n", path, rf->tool.line);
        return EXIT_ERR;
    }
    return cli_error("ik: the end frame of the robot is not rigid (its rotation part is not a rotation)", NULL);
}

/* ik --all --fixed: every closed-form solution on the robot's fixed path
 * (dh_ikc_q: the target EXPR converted to a dh_frame_q, Q16.16 degrees and
 * dh_qpos out, printed in degrees and the robot's unit) */
static int ik_all_q(const opts *o, const dh_robot *r, const dh_mat4_f32 *target, const char *path)
{
    dh_ikc_model_q m;
    dh_ikc_sol_q sol[DH_IKC_MAX_SOL];
    dh_frame_q F;
    double qd[DH_IKC_JOINTS];
    int32_t qref[DH_IKC_JOINTS];
    const double pscale = (double)((int32_t)1 << DH_QPOS_FRAC);
    uint32_t n_sol = 0, n_all = 0, s, k;
    dh_status st;
    int rc;
    st = dh_ikc_analyse_q(r, &m);
    if (st != DH_OK) {
        fprintf(stderr, "dhmath: error: ik --all --fixed: %s has no fixed-point closed-form inverse kinematics: %s\n",
                path, dh_ikc_why_str(m.why));
        return EXIT_ERR;
    }
    for (k = 0; k < DH_IKC_JOINTS; k++) qd[k] = 0.0;
    if (o->q0 && (rc = cli_parse_list(o->q0, r->n, qd, "--q0")) != 0) return rc;
    for (k = 0; k < DH_IKC_JOINTS; k++) {
        const double v = floor(qd[k] * ((k < r->n && r->joint[k].type == DH_JOINT_PRISMATIC) ? pscale : 65536.0) + 0.5);
        if (v > 2147483647.0 || v < -2147483648.0) {
            fprintf(stderr, "dhmath: error: overflow: --q0 value %u (%.9g) does not fit %s\n", k + 1, qd[k],
                    r->joint[k].type == DH_JOINT_REVOLUTE ? "degrees Q16.16" : "the fixed-point length format");
            return EXIT_ERR;
        }
        qref[k] = (int32_t)v;
    }
    st = dh_frame_from_mat4_q(target, &F);
    if (st == DH_ERR_OVERFLOW) {
        fprintf(stderr, "dhmath: error: overflow: ik --all --fixed: the target EXPR does not fit the fixed-point "
                "formats (positions |x| < %ld length units, rotation entries in Q2.30)\n",
                (long)1 << (31 - DH_QPOS_FRAC));
        return EXIT_ERR;
    }
    if (st != DH_OK) return cli_error("ik --all --fixed: the target EXPR", dh_status_str(st));
    st = dh_ikc_q(&m, &F, qref, 0u, sol, &n_sol);
    if (st == DH_ERR_NOT_RIGID)
        return cli_error("ik --all --fixed: the rotation part of the target EXPR is not a rotation within 2^-10 "
                         "(orthonormal with det +1)", NULL);
    if (st == DH_ERR_OVERFLOW) {
        fprintf(stderr, "dhmath: error: overflow: ik --all --fixed: the target is more than 2^30 LSB (%ld length "
                "units) from the base; ik --all without --fixed solves it in float\n", (long)1 << (30 - DH_QPOS_FRAC));
        return EXIT_ERR;
    }
    if (st == DH_ERR_UNREACHABLE) {
        fprintf(stderr, "ik --all --fixed: no solution: the target is out of reach\n");
        return EXIT_NOCONV;
    }
    if (st == DH_ERR_LIMIT) {
        (void)dh_ikc_q(&m, &F, qref, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &n_all);
        fprintf(stderr, "ik --all --fixed: no solution within the joint limits (%u outside)\n", (unsigned)n_all);
        return EXIT_NOCONV;
    }
    if (st != DH_OK) return cli_error("ik --all --fixed", dh_status_str(st));
    for (s = 0; s < n_sol; s++)
        for (k = 0; k < r->n; k++)
            put_num((double)sol[s].q[k] / (r->joint[k].type == DH_JOINT_PRISMATIC ? pscale : 65536.0), k + 1 == r->n);
    rc = cli_finish();
    (void)dh_ikc_q(&m, &F, qref, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &n_all);
    fprintf(stderr, "ik --all --fixed: %u closed-form solution%s within the limits (%u outside)\n", (unsigned)n_sol,
            n_sol == 1u ? "" : "s", (unsigned)(n_all - n_sol));
    return rc;
}

/* ik --all: every closed-form solution (dh_ikc_f32, with --fixed dh_ikc_q),
 * one line each */
static int ik_all(const opts *o, const dh_robot *r, const dh_robotfile *rf, const dh_mat4_f32 *target)
{
    dh_ikc_model_f32 m;
    dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
    double qd[DH_IKC_JOINTS];
    float qref[DH_IKC_JOINTS];
    uint32_t n_sol = 0, n_all = 0, s, k;
    const char *path = strcmp(o->pos[0], "-") == 0 ? "<stdin>" : o->pos[0];
    dh_status st;
    int rc;
    if (o->position || o->tol_pos || o->tol_rot || o->w_rot || o->max_iter)
        return cli_usage_error("ik --all takes only --q0 (the closed form has no tolerances, weights or iterations)", NULL);
    if (o->fixed) return ik_all_q(o, r, target, path);
    st = dh_ikc_analyse_f32(r, &m);
    if (st != DH_OK) {
        fprintf(stderr, "dhmath: error: ik --all: %s has no closed-form inverse kinematics: %s\n", path,
                dh_ikc_why_str(m.why));
        return EXIT_ERR;
    }
    for (k = 0; k < DH_IKC_JOINTS; k++) qd[k] = 0.0;
    if (o->q0 && (rc = cli_parse_list(o->q0, r->n, qd, "--q0")) != 0) return rc;
    for (k = 0; k < DH_IKC_JOINTS; k++) qref[k] = (float)qd[k];
    st = dh_ikc_f32(&m, target, qref, 0u, sol, &n_sol);
    if (st == DH_ERR_NOT_RIGID) return ik_not_rigid(o->pos[0], r, rf, target, DH_IK_FULL);
    if (st == DH_ERR_UNREACHABLE) {
        fprintf(stderr, "ik --all: no solution: the target is out of reach%s\n",
                m.calibrated ? " (or no branch of the idealised closed form converged on the calibrated chain)" : "");
        return EXIT_NOCONV;
    }
    if (st == DH_ERR_LIMIT) {
        (void)dh_ikc_f32(&m, target, qref, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &n_all);
        fprintf(stderr, "ik --all: no solution within the joint limits (%u outside)\n", (unsigned)n_all);
        return EXIT_NOCONV;
    }
    if (st != DH_OK) return cli_error("ik --all", dh_status_str(st));
    for (s = 0; s < n_sol; s++)
        for (k = 0; k < r->n; k++) put_num(sol[s].q[k], k + 1 == r->n);
    rc = cli_finish();
    (void)dh_ikc_f32(&m, target, qref, DH_IKC_KEEP_OUT_OF_LIMITS, sol, &n_all);
    fprintf(stderr, "ik --all: %u closed-form solution%s within the limits (%u outside)%s\n", (unsigned)n_sol,
            n_sol == 1u ? "" : "s", (unsigned)(n_all - n_sol),
            m.calibrated ? ", refined by Newton steps on the calibrated chain (the robot is within the calibration "
                           "tolerance of a closed-form family)" : "");
    return rc;
}

/* ik --fixed: dh_ik_q on the robot's fixed path (robot in mm, say). The
 * target is EXPR evaluated in float and rounded to a dh_frame_q; --q0 and
 * the tolerances are rounded to the fixed formats; the joint values are
 * printed in degrees / length units as without --fixed. */
static int ik_fixed(const opts *o, const dh_robot *r, const dh_mat4_f32 *target)
{
    const double pscale = (double)((int32_t)1 << DH_QPOS_FRAC);
    double qd[DH_MAX_JOINTS], x;
    int32_t q0[DH_MAX_JOINTS], q[DH_MAX_JOINTS];
    static int32_t work[DH_IK_WORK_Q(DH_MAX_JOINTS)];
    dh_ik_params_q prm;
    dh_ik_result_q res;
    dh_frame_q F;
    unsigned k;
    dh_status st;
    int rc;
    if ((r->flags & DH_ROBOT_HAS_Q) == 0u)
        return cli_error("ik --fixed: a constant of the robot does not fit the fixed-point formats", NULL);
    if (dh_frame_from_mat4_q(target, &F) != DH_OK) {
        fprintf(stderr, "dhmath: error: ik --fixed: the target EXPR is not a rigid frame in the fixed-point formats "
                "(rotation entries in Q2.30, position |x| < %ld length units)\n", 1L << (31 - DH_QPOS_FRAC));
        return EXIT_ERR;
    }
    for (k = 0; k < r->n; k++) qd[k] = 0.0;
    if (o->q0 && (rc = cli_parse_list(o->q0, r->n, qd, "--q0")) != 0) return rc;
    if ((rc = joints_to_q(r, qd, q0)) != 0) return rc;
    dh_ik_params_default_q(r, &prm);
    if (o->position) prm.mask = DH_IK_POSITION;
    if (o->tol_pos) {
        if ((rc = cli_parse_num(o->tol_pos, "--tol-pos", &x)) != 0) return rc;
        if (!(x >= 0.0 && x * pscale < 2147483647.0)) return cli_error("--tol-pos must be >= 0 and fit the fixed length format", NULL);
        prm.tol_pos = (int32_t)floor(x * pscale + 0.5);
    }
    if (o->tol_rot) {
        if ((rc = cli_parse_num(o->tol_rot, "--tol-rot", &x)) != 0) return rc;
        if (!(x >= 0.0 && x < 2.0)) return cli_error("--tol-rot must be in [0, 2) rad with --fixed", NULL);
        prm.tol_rot = (int32_t)floor(x * 1073741824.0 + 0.5);
    }
    if (o->w_rot) {
        if ((rc = cli_parse_num(o->w_rot, "--w-rot", &x)) != 0) return rc;
        if (!(x > 0.0 && x * pscale < 2147483647.0 && floor(x * pscale + 0.5) >= 1.0))
            return cli_error("--w-rot must be > 0 and fit the fixed length format", NULL);
        prm.w_rot = (int32_t)floor(x * pscale + 0.5);
    }
    if (o->max_iter) {
        if ((rc = cli_parse_num(o->max_iter, "--max-iter", &x)) != 0) return rc;
        if (!(x >= 1.0 && x <= 1e6 && floor(x) == x)) return cli_error("--max-iter must be an integer in 1..1000000", NULL);
        prm.max_iter = (uint32_t)x;
    }
    memset(&res, 0, sizeof res);
    st = dh_ik_q(r, &F, q0, &prm, work, sizeof work / sizeof work[0], q, &res);
    if (st == DH_ERR_NOT_RIGID)
        return cli_error("ik --fixed: the target's rotation, or the robot's end rotation at the start, is not a "
                         "rotation (not orthonormal with det +1)", NULL);
    if (st == DH_ERR_OVERFLOW) {
        fprintf(stderr, "dhmath: error: overflow: ik --fixed: the forward kinematics or the pose error at the start "
                "saturates the fixed-point formats (|x| < %ld length units); ik without --fixed computes in float\n",
                1L << (31 - DH_QPOS_FRAC));
        return EXIT_ERR;
    }
    if (st != DH_OK && st != DH_ERR_NO_CONVERGENCE && st != DH_ERR_UNREACHABLE)
        return cli_error("ik --fixed", dh_status_str(st));
    for (k = 0; k < r->n; k++)
        put_num((double)q[k] / (r->joint[k].type == DH_JOINT_REVOLUTE ? 65536.0 : pscale), k + 1 == r->n);
    rc = cli_finish();
    fprintf(stderr, "ik --fixed: %s (%s), %lu iterations, position error %.3g, orientation error %.3g rad\n",
            st == DH_OK ? "converged" : "not converged", dh_status_str(st), (unsigned long)res.iterations,
            (double)res.err_pos / pscale, (double)res.err_rot / 1073741824.0);
    if (rc) return rc;
    return st == DH_OK ? 0 : EXIT_NOCONV;
}

static int cmd_ik(int argc, char **argv)
{
    opts o;
    dh_robot r;
    dh_robotfile rf;
    dh_mat4_f32 target;
    double qd[DH_MAX_JOINTS];
    float q0[DH_MAX_JOINTS], q[DH_MAX_JOINTS];
    static float work[DH_IK_WORK_FLOATS(DH_MAX_JOINTS)];
    dh_ik_params_f32 prm;
    dh_ik_result_f32 res;
    unsigned n, k;
    dh_status st;
    double L, x;
    int rc = parse_opts(argc, argv, &o, "q0 position tol-pos tol-rot w-rot max-iter all fixed");
    if (rc) return rc;
    if (o.npos != 2) return cli_usage_error("ik takes ROBOTFILE EXPR [--q0 q1,...] [--position] [--tol-pos X] "
                                        "[--tol-rot X] [--w-rot X] [--max-iter N] [--fixed], or --all [--fixed] [--q0 q1,...]", NULL);
    if ((rc = cli_load_robot(o.pos[0], o.fixed, &r, &rf)) != 0) return rc;
    if ((rc = cli_eval_expr(o.pos[1], &target)) != 0) return rc;
    if (o.all) return ik_all(&o, &r, &rf, &target);
    if (o.fixed) return ik_fixed(&o, &r, &target);
    n = r.n;
    for (k = 0; k < n; k++) qd[k] = 0.0;
    if (o.q0 && (rc = cli_parse_list(o.q0, n, qd, "--q0")) != 0) return rc;
    for (k = 0; k < n; k++) {
        const dh_joint *j = &r.joint[k];
        q0[k] = (float)qd[k];
        if (j->qmin <= j->qmax && (q0[k] < j->qmin || q0[k] > j->qmax))
            fprintf(stderr, "dhmath: warning: %s joint %u value %.9g outside its limits [%.9g, %.9g]: "
                    "clamped to %.9g\n", o.q0 ? "--q0:" : "start (no --q0, all zeros):", k + 1, (double)q0[k],
                    (double)j->qmin, (double)j->qmax, (double)(q0[k] < j->qmin ? j->qmin : j->qmax));
    }
    dh_ik_params_default_f32(&r, &prm);     /* scaled to the robot's size */
    /* L names the robot's size in the messages: sum of |a| + |d| of the
     * joints and the base and tool offsets (the library's L, which has the
     * tool's length instead of its offsets and no base, is near it). The
     * library scales w_rot to L / 4, which needs L^2 finite in float. */
    L = robot_reach(&r, &rf);
    if (!o.w_rot && !ik_weight_ok(0.25 * L)) {
        fprintf(stderr, "dhmath: error: ik: the robot's size overflows the float IK: L = %.9g (sum of |a| and |d| "
                "of the joints and the base and tool offsets) makes the default weight w_rot = L/4 = %.9g length "
                "units per radian, and dh_ik_f32 needs w_rot^2 finite in float (w_rot <= 4.6e18); give --w-rot, or "
                "describe the robot in a larger length unit\n", L, 0.25 * L);
        return EXIT_ERR;
    }
    if (o.position) prm.mask = DH_IK_POSITION;
    if (o.tol_pos) {
        if ((rc = cli_parse_num(o.tol_pos, "--tol-pos", &x)) != 0) return rc;
        if (!(x >= 0.0)) return cli_error("--tol-pos must be >= 0", NULL);
        prm.tol_pos = (float)x;
    }
    if (o.tol_rot) {
        if ((rc = cli_parse_num(o.tol_rot, "--tol-rot", &x)) != 0) return rc;
        if (!(x >= 0.0)) return cli_error("--tol-rot must be >= 0", NULL);
        prm.tol_rot = (float)x;
    }
    if (o.w_rot) {
        if ((rc = cli_parse_num(o.w_rot, "--w-rot", &x)) != 0) return rc;
        if (!(x > 0.0)) return cli_error("--w-rot must be > 0", NULL);
        if (!ik_weight_ok(x)) {
            fprintf(stderr, "dhmath: error: --w-rot %s is too large: dh_ik_f32 needs w_rot^2 finite in float "
                    "(w_rot <= 4.6e18)\n", o.w_rot);
            return EXIT_ERR;
        }
        prm.w_rot = (float)x;
    }
    if (o.max_iter) {
        if ((rc = cli_parse_num(o.max_iter, "--max-iter", &x)) != 0) return rc;
        if (!(x >= 1.0 && x <= 1e6 && floor(x) == x)) return cli_error("--max-iter must be an integer in 1..1000000", NULL);
        prm.max_iter = (uint32_t)x;
    }
    memset(&res, 0, sizeof res);
    st = dh_ik_f32(&r, &target, q0, &prm, work, sizeof work / sizeof work[0], q, &res);
    if (st == DH_ERR_NOT_RIGID) return ik_not_rigid(o.pos[0], &r, &rf, &target, prm.mask);
    if (st == DH_ERR_OVERFLOW) {
        fprintf(stderr, "dhmath: error: ik: overflow: the forward kinematics or the pose error at the start is not "
                "finite in float (the robot's size L = %.9g)\n", L);
        return EXIT_ERR;
    }
    if (st != DH_OK && st != DH_ERR_NO_CONVERGENCE && st != DH_ERR_UNREACHABLE && st != DH_ERR_SINGULAR)
        return cli_error("ik", dh_status_str(st));
    for (k = 0; k < n; k++)
        if (!isfinite(q[k])) return cli_error("ik: result is not finite", NULL);
    for (k = 0; k < n; k++) put_num(q[k], k + 1 == n);
    rc = cli_finish();
    fprintf(stderr, "ik: %s (%s), %lu iterations, position error %.3g, orientation error %.3g rad\n",
            st == DH_OK ? "converged" : "not converged", dh_status_str(st), (unsigned long)res.iterations,
            (double)res.err_pos, (double)res.err_rot);
    if (rc) return rc;
    return st == DH_OK ? 0 : EXIT_NOCONV;
}

static int rotation_of(const char *cmd, const char *expr, dh_mat3_f32 *R)
{
    dh_mat4_f32 T;
    int rc = cli_eval_expr(expr, &T);
    if (rc) return rc;
    if ((rc = projective_error(cmd, &T)) != 0) return rc;
    dh_mat4_get_rot_f32(&T, R);
    return 0;
}

static int rot_error(const char *cmd, dh_status st)
{
    if (st == DH_ERR_NOT_RIGID)
        fprintf(stderr, "dhmath: error: %s: the 3x3 part of EXPR is not a rotation (not orthonormal with det +1)\n", cmd);
    else
        fprintf(stderr, "dhmath: error: %s: %s\n", cmd, dh_status_str(st));
    return EXIT_ERR;
}

static int cmd_euler(int argc, char **argv)
{
    opts o;
    dh_mat3_f32 R;
    dh_euler_seq seq;
    float a[3];
    dh_status st;
    int rc = parse_opts(argc, argv, &o, "fixed");
    if (rc) return rc;
    if (o.npos != 2)
        return cli_usage_error("euler takes SEQ EXPR, e.g. dhmath euler [--fixed] XYZ \"rotx(10) roty(20)\"", NULL);
    if (dh_euler_parse(o.pos[0], &seq) != DH_OK)
        return cli_usage_error("unknown Euler sequence '%s' (three axis letters, uppercase intrinsic, "
                           "lowercase extrinsic, no two equal neighbours: XYZ, ZYX, ZYZ, xyz, ...)", o.pos[0]);
    if (o.fixed) {
        /* EXPR on the fixed-point path, angles Q16.16 degrees */
        dh_frame_q F;
        dh_q16 aq[3];
        if ((rc = cli_eval_expr_arg(o.pos[1], 1, NULL, &F)) != 0) return rc;
        st = dh_frame_to_euler_q(&F, seq, aq);
        if (st != DH_OK) return rot_error("euler --fixed", st);
        put_num(aq[0] / 65536.0, 0);
        put_num(aq[1] / 65536.0, 0);
        put_num(aq[2] / 65536.0, 1);
        return cli_finish();
    }
    if ((rc = rotation_of("euler", o.pos[1], &R)) != 0) return rc;
    st = dh_mat3_to_euler_f32(&R, seq, a);
    if (st != DH_OK) return rot_error("euler", st);
    if (!isfinite(a[0]) || !isfinite(a[1]) || !isfinite(a[2])) return cli_error("euler: result is not finite", NULL);
    put_num(a[0], 0);
    put_num(a[1], 0);
    put_num(a[2], 1);
    return cli_finish();
}

static int cmd_quat(int argc, char **argv)
{
    opts o;
    dh_mat3_f32 R;
    dh_quat_f32 q;
    dh_status st;
    int rc = parse_opts(argc, argv, &o, "fixed");
    if (rc) return rc;
    if (o.npos != 1) return cli_usage_error("quat takes one EXPR: dhmath quat [--fixed] EXPR", NULL);
    if (o.fixed) {
        /* EXPR on the fixed-point path, components Q2.30 */
        dh_frame_q F;
        dh_quat_q qq;
        if ((rc = cli_eval_expr_arg(o.pos[0], 1, NULL, &F)) != 0) return rc;
        st = dh_frame_to_quat_q(&F, &qq);
        if (st != DH_OK) return rot_error("quat --fixed", st);
        put_num(qq.w / 1073741824.0, 0);
        put_num(qq.x / 1073741824.0, 0);
        put_num(qq.y / 1073741824.0, 0);
        put_num(qq.z / 1073741824.0, 1);
        return cli_finish();
    }
    if ((rc = rotation_of("quat", o.pos[0], &R)) != 0) return rc;
    st = dh_mat3_to_quat_f32(&R, &q);
    if (st != DH_OK) return rot_error("quat", st);
    if (!isfinite(q.w) || !isfinite(q.x) || !isfinite(q.y) || !isfinite(q.z))
        return cli_error("quat: result is not finite", NULL);
    put_num(q.w, 0);
    put_num(q.x, 0);
    put_num(q.y, 0);
    put_num(q.z, 1);
    return cli_finish();
}

static int cmd_gen(int argc, char **argv)
{
    opts o;
    dh_robot r;
    dh_robotfile rf;
    const char *why;
    int rc = parse_opts(argc, argv, &o, "");
    if (rc) return rc;
    if (o.npos != 2) return cli_usage_error("gen takes ROBOTFILE NAME, e.g. dhmath gen puma560.dh puma560", NULL);
    if ((why = dh_gen_name_problem(o.pos[1])) != NULL) {
        fprintf(stderr, "dhmath: error: gen: NAME '%.80s' is not a usable C identifier: %s\n", o.pos[1], why);
        return EXIT_ERR;
    }
    if ((rc = cli_load_robot(o.pos[0], 0, &r, &rf)) != 0) return rc;
    if (dh_robot_check(&r) != DH_OK) return cli_error("gen: the built robot fails dh_robot_check", NULL);
    dh_gen_write(stdout, &r, o.pos[1], o.pos[0]);
    return cli_finish();
}

/* ---- track ---------------------------------------------------------------- */

/* The errors of FK(q) against T into rep (the report holds the closed
 * form's bounds when the tracker did not measure them): the command prints
 * measured errors. */
static void track_measure(const dh_robot *r, const float *q, const dh_mat4_f32 *T, dh_track_report_f32 *rep)
{
    dh_mat4_f32 F;
    float e[6];
    if (dh_fk_f32(r, q, &F) != DH_OK || dh_pose_error_f32(T, &F, e) != DH_OK) return;
    rep->pos_err = sqrtf(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    rep->rot_err = sqrtf(e[3] * e[3] + e[4] * e[4] + e[5] * e[5]);
    rep->measured = 1;
}




static const char *const k_track_word[3] = { "ok", "lagging", "unreachable" };

/* the next target line of track: 1 with T, 0 at the end of input, or an
 * exit code (the error printed) */
static int track_next(char *line, size_t cap, unsigned *lineno, dh_mat4_f32 *T)
{
    for (;;) {
        size_t len, b = 0;
        dh_expr_error e;
        if (!fgets(line, (int)cap, stdin)) {
            if (ferror(stdin)) return cli_error("reading the targets from standard input failed", NULL);
            return 0;
        }
        len = strlen(line);
        (*lineno)++;
        if (len == cap - 1u && line[len - 1u] != '\n' && !feof(stdin)) {
            fprintf(stderr, "dhmath: error: line %u: longer than %lu characters\n", *lineno,
                    (unsigned long)(cap - 2u));
            return EXIT_ERR;
        }
        while (len > 0u && (line[len - 1u] == '\n' || line[len - 1u] == '\r')) len--;
        while (b < len && (line[b] == ' ' || line[b] == '\t')) b++;
        if (b == len) continue; /* blank line */
        if (dh_expr_eval_f32(line, len, T, &e)) {
            fprintf(stderr, "dhmath: error: line %u: column %lu: %s\n", *lineno, (unsigned long)(e.pos + 1), e.msg);
            return EXIT_ERR;
        }
        return 1;
    }
}

/* track --fixed: the fixed-point tracker (dh_track_q) on the robot's fixed
 * path, lengths in the robot file's unit; q0 rounded to Q16.16 degrees /
 * dh_qpos, the period a whole number of microseconds, each target EXPR
 * evaluated in float and rounded to a dh_frame_q. The rate limits are the
 * fixed copies dh_robot_set_rates_f32 stored. */
/* The report's errors measured by FK at q when the tracker gave the closed
 * form's bounds instead (rep->measured 0): dh_fk_q, the position distance
 * and dh_rot_error_q's angle, rounded to the report's formats. */
static void track_fixed_measure(const dh_robot *r, const dh_frame_q *F, const int32_t *q, dh_track_report_q *rep)
{
    dh_frame_q T;
    dh_dir3_q w;
    double p2 = 0.0;
    unsigned k;
    if (rep->measured || dh_fk_q(r, q, &T) != DH_OK || dh_rot_error_q(F, &T, &w) != DH_OK) return;
    for (k = 0; k < 3u; k++) p2 += ((double)F->p[k] - T.p[k]) * ((double)F->p[k] - T.p[k]);
    rep->pos_err = (int32_t)fmin(floor(sqrt(p2) + 0.5), 2147483647.0);
    rep->rot_err = (int32_t)fmin(floor(sqrt((double)w.x * w.x + (double)w.y * w.y + (double)w.z * w.z) + 0.5), 2147483647.0);
    rep->measured = 1;
}

static int track_fixed(const dh_robot *r, const double *q0d, double dtd, cli_outbuf *out)
{
    static dh_ikc_model_q m;
    dh_mat4_f32 T_scratch;
    static dh_track_q t;
    int32_t q0[DH_MAX_JOINTS], q[DH_MAX_JOINTS];
    const double us = dtd * 1e6, one = (double)((int32_t)1 << DH_QPOS_FRAC);
    char line[4096], text[64];
    unsigned i, lineno = 0;
    int rc;
    dh_status st;
    const dh_ikc_model_q *mp = NULL;
    if (!(us >= 1.0 && us <= 1e6) || fabs(us - floor(us + 0.5)) > 1e-6 * us)
        return cli_error("--dt", "with --fixed the control period must be a whole number of microseconds, at most 1 s");
    if ((r->flags & DH_ROBOT_HAS_Q) == 0u)
        return cli_error("track --fixed", "the robot's constants do not fit the fixed-point formats");
    for (i = 0; i < r->n; i++) {
        const double v = q0d[i] * ((r->joint[i].type == DH_JOINT_REVOLUTE) ? 65536.0 : one);
        if (!(fabs(v) < 2147483647.0)) return cli_error("--q0", "a joint value does not fit the fixed-point format");
        q0[i] = (int32_t)floor(v + 0.5);
    }
    if (dh_ikc_analyse_q(r, &m) == DH_OK && m.kind != DH_IKC_NONE) mp = &m;
    st = dh_track_init_q(&t, r, mp, q0, (uint32_t)floor(us + 0.5));
    if (st == DH_ERR_LIMIT) return cli_error("--q0", "a joint value is outside its limits");
    if (st != DH_OK) return cli_error("track", dh_status_str(st));
    while ((rc = track_next(line, sizeof line, &lineno, &T_scratch)) == 1) {
        dh_frame_q F;
        dh_track_report_q rep;
        if (dh_frame_from_mat4_q(&T_scratch, &F) != DH_OK) {
            fprintf(stderr, "dhmath: error: line %u: target not representable in fixed point\n", lineno);
            return EXIT_ERR;
        }
        st = dh_track_step_q(&t, &F, q, &rep);
        if (st != DH_OK) {
            fprintf(stderr, "dhmath: error: line %u: target not rigid (rotation not orthonormal)\n", lineno);
            return EXIT_ERR;
        }
        track_fixed_measure(r, &F, q, &rep);
        for (i = 0; i < r->n; i++) {
            const double v = q[i] / ((r->joint[i].type == DH_JOINT_REVOLUTE) ? 65536.0 : one);
            (void)snprintf(text, sizeof text, "%.9g ", v == 0.0 ? 0.0 : v);
            if (cli_out_add(out, text)) return EXIT_ERR;
        }
        (void)snprintf(text, sizeof text, "%s %.9g %.9g\n", k_track_word[rep.state], rep.pos_err / one,
                       rep.rot_err / 536870912.0);
        if (cli_out_add(out, text)) return EXIT_ERR;
    }
    return rc;
}

static int cmd_track(int argc, char **argv)
{
    opts o;
    dh_robot r;
    static dh_robotfile rf;
    static dh_ikc_model_f32 m;
    static dh_track_f32 t;
    double q0d[DH_MAX_JOINTS], dtd = 0.0;
    float q0[DH_MAX_JOINTS], vmax[DH_MAX_JOINTS], q[DH_MAX_JOINTS];
    char line[4096], text[64];
    unsigned i, lineno = 0;
    cli_outbuf out = { NULL, 0u, 0u };
    int rc;
    dh_status st;
    dh_mat4_f32 T;
    if ((rc = parse_opts(argc, argv, &o, "fixed q0 dt vmax")) != 0) return rc;
    if (o.npos != 1) return cli_usage_error("track takes ROBOT --q0 q1,... --dt SECONDS [--vmax V] [--fixed]", NULL);
    if (strcmp(o.pos[0], "-") == 0)
        return cli_usage_error("track reads its targets from standard input: the robot must be a file", NULL);
    if (!o.q0) return cli_usage_error("track needs --q0 q1,... (the configuration at the first target)", NULL);
    if (!o.dt) return cli_usage_error("track needs --dt SECONDS (the control period)", NULL);
    if ((rc = cli_parse_dt(o.dt, &dtd)) != 0) return rc;
    if ((rc = cli_load_robot(o.pos[0], o.fixed, &r, &rf)) != 0) return rc;
    if ((rc = cli_parse_list(o.q0, r.n, q0d, "--q0")) != 0) return rc;
    for (i = 0; i < r.n; i++) q0[i] = (float)q0d[i];
    if ((rc = cli_joint_rates("track", "--vmax", o.vmax, &r, vmax)) != 0) return rc;
    for (i = 0; i < r.n; i++) {
        st = dh_robot_set_rates_f32(&r, i, vmax[i], r.joint[i].amax);
        if (st != DH_OK) return cli_error("--vmax rejected by the library", dh_status_str(st));
    }
    if (o.fixed) {
        rc = track_fixed(&r, q0d, dtd, &out);
        if (rc == 0 && out.len) fwrite(out.buf, 1, out.len, stdout);
        free(out.buf);
        return rc ? rc : cli_finish();
    }
    if ((rc = cli_track_start("track", &r, &m, q0, (float)dtd, &t)) != 0) return rc;
    while ((rc = track_next(line, sizeof line, &lineno, &T)) == 1) {
        dh_track_report_f32 rep;
        st = dh_track_step_f32(&t, &T, q, &rep);
        if (st != DH_OK) {
            fprintf(stderr, "dhmath: error: line %u: target %s\n", lineno,
                    st == DH_ERR_NAN ? "not finite" : "not rigid (rotation not orthonormal or bottom row not 0 0 0 1)");
            free(out.buf);
            return EXIT_ERR;
        }
        for (i = 0; i < r.n; i++) {
            (void)snprintf(text, sizeof text, "%.9g ", q[i] == 0.0f ? 0.0 : (double)q[i]);
            if (cli_out_add(&out, text)) { free(out.buf); return EXIT_ERR; }
        }
        if (!rep.measured) track_measure(&r, q, &T, &rep);
        (void)snprintf(text, sizeof text, "%s %.9g %.9g\n", k_track_word[rep.state], (double)rep.pos_err,
                       (double)rep.rot_err);
        if (cli_out_add(&out, text)) { free(out.buf); return EXIT_ERR; }
    }
    if (rc != 0) {
        free(out.buf);
        return rc;
    }
    if (out.len) fwrite(out.buf, 1, out.len, stdout);
    free(out.buf);
    return cli_finish();
}

int main(int argc, char **argv)
{
    const char *cmd;
    if (argc < 2) return cli_usage_error("no COMMAND given (eval, axis, point, plane, fk, jacobian, ik, "
                                     "euler, quat, gen, track, move, help, --version)", NULL);
    cmd = argv[1];
    if (strcmp(cmd, "help") == 0 || strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0) {
        fputs(k_usage, stdout);
        fputs(cli_move_usage, stdout);
        fputs(k_usage_tail, stdout);
        return cli_finish();
    }
    if (strcmp(cmd, "--version") == 0) {
        if (argc > 2) return cli_usage_error("--version takes no arguments", NULL);
        printf("dhmath %d.%d.%d\n", DHMATH_VERSION_MAJOR, DHMATH_VERSION_MINOR, DHMATH_VERSION_PATCH);
        return cli_finish();
    }
    argc -= 2;
    argv += 2;
    if (strcmp(cmd, "eval") == 0) return cmd_eval(argc, argv);
    if (strcmp(cmd, "axis") == 0) return cmd_axis(argc, argv);
    if (strcmp(cmd, "point") == 0) return cmd_point(argc, argv);
    if (strcmp(cmd, "plane") == 0) return cmd_plane(argc, argv);
    if (strcmp(cmd, "fk") == 0) return cmd_fk(argc, argv);
    if (strcmp(cmd, "jacobian") == 0) return cmd_jacobian(argc, argv);
    if (strcmp(cmd, "ik") == 0) return cmd_ik(argc, argv);
    if (strcmp(cmd, "euler") == 0) return cmd_euler(argc, argv);
    if (strcmp(cmd, "quat") == 0) return cmd_quat(argc, argv);
    if (strcmp(cmd, "gen") == 0) return cmd_gen(argc, argv);
    if (strcmp(cmd, "track") == 0) return cmd_track(argc, argv);
    if (strcmp(cmd, "move") == 0) return cli_cmd_move(argc, argv);
    return cli_usage_error("unknown command '%s'", cmd);
}
