/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file dh_gen.h
 * @brief `dhmath gen`: a dh_robot written out as a C source that defines it
 *        as a const object (flash), every field exactly as the setters left
 *        it (docs/cli.md, "gen").
 */
#ifndef DHMATH_CLI_DH_GEN_H
#define DHMATH_CLI_DH_GEN_H

#include <stdio.h>

#include "dhmath/robot.h"

/** Longest NAME accepted (C99 guarantees 63 significant initial characters
 *  of an internal identifier). */
#define DH_GEN_MAX_NAME 63

/**
 * Whether name can be the generated object's name: a C identifier of at
 * most DH_GEN_MAX_NAME characters, not a C99 keyword, not reserved (two
 * leading underscores or an underscore and an uppercase letter).
 * @return NULL when it can, else the reason (a static string).
 */
const char *dh_gen_name_problem(const char *name);

/**
 * Write to out the C source that includes dhmath/dhmath.h and defines
 * `const dh_robot name` equal to *r field by field (floats as hex-float
 * literals, so every bit is kept), with preprocessor guards that stop the
 * compilation under a DH_QPOS_FRAC other than this build's, a
 * DH_MAX_JOINTS below r->n or a dh_robot of another layout. The joints
 * r->n.. up to the compiling build's DH_MAX_JOINTS are the empty joint of
 * dh_robot_init. src names the robot file in the header comment (its last
 * path component is printed). name must pass dh_gen_name_problem(), r
 * must pass dh_robot_check().
 */
void dh_gen_write(FILE *out, const dh_robot *r, const char *name, const char *src);

#endif /* DHMATH_CLI_DH_GEN_H */
