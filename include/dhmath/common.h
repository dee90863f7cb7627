/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Index: the functions of common.h by source file (src/common/).
 *   dh_status.c  dh_status_str
 */
/**
 * @file common.h
 * @brief Status codes, configuration, assertion hook and the basic float and
 *        fixed-point value types shared by every dhmath module.
 *
 * Storage convention (Paul 1981, eq. 1.56): a 4x4 homogeneous transform has
 * columns n, o, a, p; points are column vectors and are transformed as T*u.
 * Matrices are stored COLUMN-MAJOR: element (row r, column c) is m[c][r], so
 * each of n, o, a, p is a contiguous group of floats (see DH_M4()).
 */
#ifndef DHMATH_COMMON_H
#define DHMATH_COMMON_H

#include <stdint.h>
#include <stddef.h>

#include "dhmath/config.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * @brief Result of every dhmath function that can fail on data.
 *
 * Programmer errors (NULL pointers) are caught by DH_ASSERT instead.
 * DH_OK is 0; every failure is non-zero so `if (st) ...` works.
 */
typedef enum {
    DH_OK = 0,              /**< success */
    DH_ERR_ARG = 1,         /**< argument out of its documented range (joint count, enum value, size) */
    DH_ERR_NAN = 2,         /**< a NaN or infinite input */
    DH_ERR_SINGULAR = 3,    /**< matrix singular within the relative tolerance */
    DH_ERR_NOT_RIGID = 4,   /**< rotation part not orthonormal within tolerance, or bottom row not 0 0 0 1 */
    DH_ERR_ZERO_AXIS = 5,   /**< rotation axis of zero (or denormal) length */
    DH_ERR_DOMAIN = 6,      /**< mathematical domain error: focal length 0, point at infinity (w == 0) */
    DH_ERR_OVERFLOW = 7,    /**< fixed-point result saturated (or float result not finite) */
    DH_ERR_NO_CONVERGENCE = 8, /**< iteration limit reached without meeting the tolerance */
    DH_ERR_UNREACHABLE = 9, /**< target out of reach: best effort returned with its residual */
    DH_ERR_LIMIT = 10,      /**< joint value outside its limits */
    DH_ERR_UNAVAILABLE = 11, /**< the robot's float or fixed path is not prepared (dh_robot.flags says why) */
    DH_ERR_INCONSISTENT = 12 /**< a robot's derived fields differ from what its setters compute (dh_robot_check) */
} dh_status;

/** @brief Short English name of a status ("ok", "singular matrix", ...). Never NULL. */
const char *dh_status_str(dh_status st);

/* ---- float types ------------------------------------------------------ */

/** 3-vector (a point or a direction in 3-D). */
typedef struct {
    float x; /**< x component */
    float y; /**< y component */
    float z; /**< z component */
} dh_vec3_f32;
/** Homogeneous 4-vector [x y z w]^T (column). w = 1 point, w = 0 direction. */
typedef struct {
    float x; /**< x component */
    float y; /**< y component */
    float z; /**< z component */
    float w; /**< scale factor: 1 for a point, 0 for a direction */
} dh_vec4_f32;
/** Plane as the row vector [a b c d]: points u with a x + b y + c z + d w = 0 (Paul 1981 eq. 1.19-1.22). */
typedef struct {
    float a; /**< x coefficient */
    float b; /**< y coefficient */
    float c; /**< z coefficient */
    float d; /**< w coefficient (offset) */
} dh_plane_f32;
/** 3x3 matrix, column-major: m[col][row]. */
typedef struct {
    float m[3][3]; /**< m[col][row] */
} dh_mat3_f32;
/** 4x4 homogeneous transform, column-major: m[col][row]; columns n, o, a, p. */
typedef struct {
    float m[4][4]; /**< m[col][row]; columns n, o, a, p */
} dh_mat4_f32;

/** Element (row r, column c) of a dh_mat4_f32 pointer. */
#define DH_M4(T, r, c) ((T)->m[(c)][(r)])
/** Element (row r, column c) of a dh_mat3_f32 pointer. */
#define DH_M3(R, r, c) ((R)->m[(c)][(r)])

/* ---- fixed-point types ------------------------------------------------ */

/** Angle in degrees, Q16.16 (range +-32767.99998 deg, step 1/65536 deg). */
typedef int32_t dh_q16;
/** Sine, cosine, rotation entries: Q2.30, 1.0 == 0x40000000 exactly. */
typedef int32_t dh_q30;
/** Length (translation) in the user's unit with DH_QPOS_FRAC fraction bits (default Q16.16). */
typedef int32_t dh_qpos;

/** 1.0 in Q2.30 (exact). */
#define DH_Q30_ONE ((dh_q30)0x40000000)
/** 1.0 (one degree) in Q16.16. */
#define DH_Q16_ONE ((dh_q16)0x00010000)
/** One length unit in dh_qpos. */
#define DH_QPOS_ONE ((dh_qpos)((int32_t)1 << DH_QPOS_FRAC))

/** Fixed-point 3-vector of lengths (DH_QPOS_FRAC fraction bits). */
typedef struct {
    dh_qpos x; /**< x component */
    dh_qpos y; /**< y component */
    dh_qpos z; /**< z component */
} dh_vec3_q;
/**
 * Fixed-point 3-vector of int32 words in one of two formats, fixed by the
 * function that writes it:
 * - Q2.30 (1.0 = 2^30, range [-2, 2)): unit-scale values, e.g. the unit
 *   axis of dh_frame_to_axis_angle_q;
 * - Q3.29 RADIANS (1.0 rad = 2^29 = 0x20000000, range [-4, 4) rad): the
 *   rotation vector w that dh_rot_error_q writes: |w| <= pi within its
 *   error bound (kin.h), so each component lies within about +-pi
 *   (+-1686629713).
 * Read a dh_rot_error_q result as Q3.29, never as Q2.30 (that would halve it).
 */
typedef struct {
    dh_q30 x; /**< x component (Q2.30, or Q3.29 rad from dh_rot_error_q) */
    dh_q30 y; /**< y component (Q2.30, or Q3.29 rad from dh_rot_error_q) */
    dh_q30 z; /**< z component (Q2.30, or Q3.29 rad from dh_rot_error_q) */
} dh_dir3_q;
/**
 * Rigid frame in fixed point: rotation r (Q2.30, column-major r[col][row],
 * columns n, o, a) and position p (DH_QPOS_FRAC fraction bits).
 * The implied bottom row is 0 0 0 1.
 */
typedef struct {
    dh_q30 r[3][3]; /**< rotation, Q2.30, r[col][row] (columns n, o, a) */
    dh_qpos p[3];   /**< position, DH_QPOS_FRAC fraction bits */
} dh_frame_q;

#ifdef __cplusplus
}
#endif

#endif /* DHMATH_COMMON_H */
