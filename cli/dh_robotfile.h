/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file dh_robotfile.h
 * @brief Parser of dhmath robot description files (host tool), usable on
 *        any byte buffer (e.g. from a fuzzer).
 *
 * Format, one statement per line (`#` starts a comment, blank lines are
 * ignored, tokens are separated by spaces or tabs, a trailing CR is
 * ignored):
 *
 *     convention standard|modified      at most once, before the first joint
 *                                       (default standard)
 *     joint R|P a=.. d=.. alpha=.. theta=.. [min=.. max=..]
 *     base EXPR                         at most once (default ident)
 *     tool EXPR                         at most once (default ident)
 *
 * Missing joint keys are 0. alpha and theta are degrees; for R joints
 * theta= is the offset added to the joint variable and min/max are degrees;
 * for P joints d= is the offset added to the joint variable and min/max are
 * lengths. min and max come together, min <= max. At most DH_MAX_JOINTS
 * joints, at least one. EXPR is the dh_expr.h language.
 *
 * No heap, no globals, never reads outside buf[0..len).
 */
#ifndef DHMATH_CLI_DH_ROBOTFILE_H
#define DHMATH_CLI_DH_ROBOTFILE_H

#include <stddef.h>

#include "dhmath/robot.h"

/** Longest base/tool EXPR kept (bytes). */
#define DH_RF_MAX_EXPR 512
/** Size of the message buffer in dh_rf_error (including the NUL). */
#define DH_RF_MSG_LEN 320

/** One joint line as written in the file. */
typedef struct {
    dh_joint_type type;
    double a, d, alpha, theta;   /**< lengths; alpha/theta in degrees */
    double qmin, qmax;           /**< limits when has_limits */
    int has_limits;
    double vmax, amax;           /**< rate limits (deg/s, deg/s^2 or length unit/s, /s^2); 0 = not given (unlimited) */
    unsigned line;               /**< 1-based line number in the file */
} dh_rf_joint;

/** A base or tool statement: the EXPR text and where it came from. */
typedef struct {
    int present;
    unsigned line;               /**< 1-based line number */
    size_t col0;                 /**< 0-based column where the EXPR starts */
    size_t len;
    char text[DH_RF_MAX_EXPR + 1];
} dh_rf_frame;

/** Parsed robot file (independent of the library's dh_robot layout). */
typedef struct {
    dh_convention conv;
    unsigned n;                  /**< joints, 1..DH_MAX_JOINTS after a successful parse */
    dh_rf_joint joint[DH_MAX_JOINTS];
    dh_rf_frame base, tool;
} dh_robotfile;

/** First problem found; msg already reads "NAME:LINE:COL: text". */
typedef struct {
    unsigned line;               /**< 1-based line (the last line for whole-file problems) */
    size_t col;                  /**< 1-based column, 0 when not applicable */
    char msg[DH_RF_MSG_LEN];     /**< NUL-terminated, printable ASCII only */
} dh_rf_error;

/**
 * Parse a robot file held in buf[0..len).
 * @param name  file name used in messages (NULL = "<robot>")
 * @param rf    result; contents unspecified on error
 * @param err   receives the problem on error (may be NULL)
 * @return 0 on success, -1 on error (unknown keyword or key, duplicate key
 *         or statement, bad number, too many or no joints, min > max,
 *         min without max, bad or too long EXPR, misplaced convention).
 * base/tool EXPRs are checked by evaluating them in float.
 */
int dh_robotfile_parse(const char *name, const char *buf, size_t len, dh_robotfile *rf,
                       dh_rf_error *err);

/**
 * Build a library robot from a parsed file: dh_robot_init, one
 * dh_robot_add_joint_f32 per joint, limits, and base/tool. With fixed != 0
 * the base and tool are evaluated on the fixed-point EXPR path and set with
 * dh_robot_set_base_q/dh_robot_set_tool_q (after the float ones), and a
 * joint constant without a fixed-point form (|a|, |d| >= 2^(31-DH_QPOS_FRAC),
 * |alpha|, |theta| >= 32768 deg) is an error naming the joint, the constant,
 * its value and the range it misses.
 * @return 0, or -1 with err naming the file line the library rejected.
 */
int dh_robotfile_build(const char *name, const dh_robotfile *rf, int fixed, dh_robot *r,
                       dh_rf_error *err);

#endif /* DHMATH_CLI_DH_ROBOTFILE_H */
