/**
 * @file dhmath.h
 * @brief Umbrella header: includes every dhmath module.
 *
 * Firmware that wants only part of the library may include the module
 * headers one by one; linking pulls in only the functions used
 * (the library is built with -ffunction-sections -fdata-sections).
 */
#ifndef DHMATH_DHMATH_H
#define DHMATH_DHMATH_H

#include "dhmath/dh_config.h"
#include "dhmath/dh_common.h"
#include "dhmath/dh_trig.h"
#include "dhmath/dh_mat4.h"
#include "dhmath/dh_fixed.h"
#include "dhmath/dh_robot.h"
#include "dhmath/dh_kin.h"
#include "dhmath/dh_rot.h"

/** Library major version (semantic versioning). */
#define DHMATH_VERSION_MAJOR 0
/** Library minor version. */
#define DHMATH_VERSION_MINOR 1
/** Library patch version. */
#define DHMATH_VERSION_PATCH 0

#endif /* DHMATH_DHMATH_H */
