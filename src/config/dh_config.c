/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_config.c - the configuration check's symbols (include/dhmath/config.h):
 * one per interface setting, named after the value this library is built
 * with. Every translation unit of an application references the symbols of
 * its own values, so an application built with another DH_MAX_JOINTS or
 * DH_QPOS_FRAC fails to link, and the undefined symbol names the setting.
 * The references are two PC-relative offsets in a retained COMDAT .rodata
 * section (one 8-byte copy per image); they keep these two bytes in the
 * image (.rodata), nothing else.
 */
#include "dhmath/config.h"
#include "../internal/dh_build.h"

const uint8_t DH_CFG_SYM_MAX_JOINTS_ = 0u;
const uint8_t DH_CFG_SYM_QPOS_FRAC_ = 0u;
