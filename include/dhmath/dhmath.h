/* SPDX-License-Identifier: Apache-2.0 */
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

#include "dhmath/config.h"
#include "dhmath/common.h"
#include "dhmath/trig.h"
#include "dhmath/mat4.h"
#include "dhmath/frame.h"
#include "dhmath/robot.h"
#include "dhmath/kin.h"
#include "dhmath/rot.h"
#include "dhmath/ikc.h"
#include "dhmath/motion.h"
#include "dhmath/track.h"

/** Library major version: DH_VERSION_MAJOR (config.h, where the version is defined). */
#define DHMATH_VERSION_MAJOR DH_VERSION_MAJOR
/** Library minor version: DH_VERSION_MINOR. */
#define DHMATH_VERSION_MINOR DH_VERSION_MINOR
/** Library patch version: DH_VERSION_PATCH. */
#define DHMATH_VERSION_PATCH DH_VERSION_PATCH

#endif /* DHMATH_DHMATH_H */
