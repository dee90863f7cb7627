/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file dh_expr.h
 * @brief Parser and evaluator of transform expressions (EXPR) for the host
 *        tool `dhmath`, usable on any byte buffer (e.g. from a fuzzer).
 *
 * EXPR is a product, evaluated left to right, of terms separated by
 * whitespace or `*`:
 *
 *     trans(x,y,z)  rotx(deg)  roty(deg)  rotz(deg)  rot(kx,ky,kz,deg)
 *     scale(sx,sy,sz)  persp(x|y|z,f)  ident  inv(EXPR)
 *
 * Angles are in degrees. `inv` nests up to DH_EXPR_MAX_DEPTH levels; the
 * evaluator keeps an explicit stack of partial products (no recursion).
 *
 * The module performs no heap allocation, keeps no global state and never
 * reads outside buf[0..len): the buffer need not be NUL-terminated and may
 * contain any bytes. Every malformed input gives an error with the 0-based
 * byte offset of the problem and a message naming it.
 */
#ifndef DHMATH_CLI_DH_EXPR_H
#define DHMATH_CLI_DH_EXPR_H

#include <stddef.h>

#include "dhmath/common.h"

/** Deepest nesting of inv(...) accepted. */
#define DH_EXPR_MAX_DEPTH 16
/** Longest numeric token accepted (characters). */
#define DH_EXPR_MAX_NUMBER 64
/** Size of the message buffer in dh_expr_error (including the NUL). */
#define DH_EXPR_MSG_LEN 192

/** Description of the first problem found in an EXPR. */
typedef struct {
    size_t pos;                 /**< 0-based byte offset into the buffer (column - 1) */
    dh_status st;               /**< library status behind the error (DH_ERR_ARG for syntax errors) */
    char msg[DH_EXPR_MSG_LEN];  /**< NUL-terminated English message, printable ASCII only */
} dh_expr_error;

/**
 * Evaluate EXPR in float.
 * @param buf  bytes of the expression (any content; NUL bytes are errors)
 * @param len  number of bytes in buf
 * @param out  result matrix; untouched on error
 * @param err  receives the problem on error (may be NULL); untouched on success
 * @return 0 on success, -1 on error.
 * Errors: syntax (unknown term, bad number, wrong arity, separators,
 * unbalanced parentheses, nesting deeper than DH_EXPR_MAX_DEPTH), NaN/Inf
 * or out-of-float-range numbers (as dh_expr_parse_number),
 * zero rotation axis, persp focal length 0, singular inv(), and
 * intermediate products that are not finite.
 */
int dh_expr_eval_f32(const char *buf, size_t len, dh_mat4_f32 *out, dh_expr_error *err);

/**
 * Evaluate EXPR on the fixed-point path (dh_frame_q): lengths are rounded
 * to dh_qpos (DH_QPOS_FRAC fraction bits), angles to degrees Q16.16, axes
 * normalised to Q2.30; products and inverses use dh_frame_mul_q and
 * dh_frame_inv_q. scale() and persp() are rejected (not rigid). Values that
 * do not fit their fixed format and saturated products are errors with
 * st = DH_ERR_OVERFLOW.
 * Same buffer, return and error conventions as dh_expr_eval_f32().
 */
int dh_expr_eval_q(const char *buf, size_t len, dh_frame_q *out, dh_expr_error *err);

/**
 * Parse all of buf[0..len) as one decimal number: optional sign, digits
 * with an optional point, optional exponent. No whitespace, hexadecimal,
 * NaN or Inf. The value must round to a finite float (a value between
 * FLT_MAX and the overflow threshold FLT_MAX + half an ulp is returned as
 * +-FLT_MAX, the float it rounds to); a non-zero value below FLT_MIN must
 * round to a non-zero subnormal float with a relative error <= 2^-24 (float
 * precision), so every float printed with %.9g is accepted and reads back
 * as the same float, while e.g. 1e-45 and 1e-46 are errors.
 * @param out  receives the value (as double) on success; untouched on error
 * @return NULL on success, else a static message naming the problem.
 */
const char *dh_expr_parse_number(const char *buf, size_t len, double *out);

/**
 * Copy s[0..n) into dst (capacity cap, always NUL-terminated) as printable
 * ASCII for error messages: bytes outside 0x20..0x7e and the quote character
 * become \xNN escapes; at most shown_max bytes are shown, then "...".
 */
void dh_expr_quote(char *dst, size_t cap, const char *s, size_t n, size_t shown_max);

#endif /* DHMATH_CLI_DH_EXPR_H */
