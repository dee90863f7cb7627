/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file config.h
 * @brief The one place where every compile-time setting is defined, checked
 *        and documented.
 *
 * Each CMake option maps to exactly one DH_* define here. A project may also
 * define DH_CONFIG_HEADER="my_dh_config.h" to set them from a header; the
 * header is included first and anything it does not set gets the default.
 *
 * Two settings change the binary interface: DH_MAX_JOINTS (the layout of
 * dh_robot) and DH_QPOS_FRAC (the meaning of every dh_qpos). An application
 * must be compiled with the values the library was built with; the
 * configuration check at the end of this header makes a mismatch fail to
 * link, naming the setting. The other settings only change the library's
 * own code.
 */
#ifndef DHMATH_CONFIG_H
#define DHMATH_CONFIG_H

/** @name Library version (semantic versioning). The one definition: CMake's
 *  project version and the pkg-config file's are read from here, and
 *  tools/check.sh package checks library.json's against it.
 * @{ */
#define DH_VERSION_MAJOR 0        /**< incompatible API changes */
#define DH_VERSION_MINOR 3        /**< while MAJOR is 0: also incompatible */
#define DH_VERSION_PATCH 0        /**< compatible fixes */
#define DH_VERSION_STRING "0.3.0" /**< "MAJOR.MINOR.PATCH" */
/** @} */

#ifdef DH_CONFIG_HEADER
#include DH_CONFIG_HEADER
#endif

/**
 * DH_MAX_JOINTS: capacity of dh_robot (layout-changing, PUBLIC definition).
 * Range 1..32, default 8. A decimal literal (it becomes part of a symbol
 * name, see the configuration check below).
 */
#ifndef DH_MAX_JOINTS
#define DH_MAX_JOINTS 8
#endif
#if (DH_MAX_JOINTS < 1) || (DH_MAX_JOINTS > 32)
#error "DH_MAX_JOINTS must be in 1..32"
#endif

/**
 * DH_QPOS_FRAC: fraction bits of fixed-point lengths (dh_qpos).
 * Range 8..24, default 16 (Q16.16: +-32767 units at 1.5e-5 resolution;
 * in millimetres +-32 m at 15 nm). Layout-neutral but changes values: PUBLIC,
 * part of the binary interface, a decimal literal.
 */
#ifndef DH_QPOS_FRAC
#define DH_QPOS_FRAC 16
#endif
#if (DH_QPOS_FRAC < 8) || (DH_QPOS_FRAC > 24)
#error "DH_QPOS_FRAC must be in 8..24"
#endif

/**
 * DH_CHECK_ARGS: 1 = DH_ASSERT checks pointer arguments (programmer
 * errors); 0 = no checks. Default 1. Range 0..1.
 */
#ifndef DH_CHECK_ARGS
#define DH_CHECK_ARGS 1
#endif
#if (DH_CHECK_ARGS != 0) && (DH_CHECK_ARGS != 1)
#error "DH_CHECK_ARGS must be 0 or 1"
#endif

/**
 * DH_USE_INTRINSICS: 1 = use the Cortex-M intrinsics of src/internal/dh_port.h
 * (SSAT, SMULL/SMLAL, CLZ) when the compiler targets an ARM core that has
 * them; 0 = always the plain C fallback. Default 1. Range 0..1.
 */
#ifndef DH_USE_INTRINSICS
#define DH_USE_INTRINSICS 1
#endif
#if (DH_USE_INTRINSICS != 0) && (DH_USE_INTRINSICS != 1)
#error "DH_USE_INTRINSICS must be 0 or 1"
#endif

/**
 * DH_SMALL: 1 = size-first implementations: every function keeps its
 * contract (same formats, same status codes, same accuracy bounds) but
 * is built from loops and a single general code path instead of the
 * unrolled code and the fast paths that the default build adds for speed.
 * For firmware where flash matters more than cycles (docs/generated/footprint.md
 * gives both figures; docs/design.md lists which results may differ in
 * the last bit). Default 0. Range 0..1. PUBLIC: results may differ.
 */
#ifndef DH_SMALL
#define DH_SMALL 0
#endif
#if (DH_SMALL != 0) && (DH_SMALL != 1)
#error "DH_SMALL must be 0 or 1"
#endif

/**
 * DH_ASSERT(cond): called for programmer errors only (NULL pointers).
 * Override it by defining DH_ASSERT before this header (or in
 * DH_CONFIG_HEADER). Default: a trap (__builtin_trap on GCC/Clang, an
 * endless loop elsewhere), so a NULL pointer stops the program at the call
 * instead of corrupting memory.
 */
#ifndef DH_ASSERT
#if DH_CHECK_ARGS
#if defined(__GNUC__) || defined(__clang__)
#define DH_ASSERT(cond) do { if (!(cond)) { __builtin_trap(); } } while (0)
#else
#define DH_ASSERT(cond) do { if (!(cond)) { for (;;) { } } } while (0)
#endif
#else
#define DH_ASSERT(cond) ((void)0)
#endif
#endif

/**
 * @name Configuration check
 * The library defines one symbol per interface setting, named after the
 * value it was built with (src/config/dh_config.c), e.g.
 * dhmath_config_mismatch_DH_MAX_JOINTS_is_8. Every translation unit that
 * includes this header (GCC 11 or later, Clang 13 or later, ELF targets)
 * references the symbols of ITS values from a 4-byte-aligned pair of
 * PC-relative offsets in .rodata.dhmath_config_check_j<N>_q<F>, a section
 * that every linker script places with the rest of .rodata.* (no section
 * of its own: --orphan-handling=error links). The section is in a COMDAT
 * group named like it (the image keeps one 8-byte copy per configuration,
 * however many translation units include the header) and carries
 * SHF_GNU_RETAIN (binutils 2.36 or later), so --gc-sections keeps it and
 * the linker resolves the references; the library's two 1-byte symbols
 * stay in .rodata with it. No code, no RAM. Built with other values, the
 * link fails with "undefined reference to
 * dhmath_config_mismatch_DH_MAX_JOINTS_is_6" (the application's value).
 * The references are hidden symbols: a shared object that links the static
 * library resolves them inside itself. The library's own sources define
 * DH_NO_CONFIG_CHECK (they define the symbols instead); an application may
 * define it to leave the check out.
 * @{ */
#define DH_CFG_CAT2_(a, b) a##b                /**< token paste */
#define DH_CFG_CAT_(a, b) DH_CFG_CAT2_(a, b)   /**< token paste after expansion */
#define DH_CFG_STR2_(x) #x                     /**< stringify */
#define DH_CFG_STR_(x) DH_CFG_STR2_(x)         /**< stringify after expansion */
/** The symbol of this translation unit's DH_MAX_JOINTS. */
#define DH_CFG_SYM_MAX_JOINTS_ DH_CFG_CAT_(dhmath_config_mismatch_DH_MAX_JOINTS_is_, DH_MAX_JOINTS)
/** The symbol of this translation unit's DH_QPOS_FRAC. */
#define DH_CFG_SYM_QPOS_FRAC_ DH_CFG_CAT_(dhmath_config_mismatch_DH_QPOS_FRAC_is_, DH_QPOS_FRAC)
/** @} */

#if !defined(DH_NO_CONFIG_CHECK) && defined(__ELF__) && \
    ((defined(__clang__) && (__clang_major__ >= 13)) || (!defined(__clang__) && defined(__GNUC__) && (__GNUC__ >= 11)))
/* The two references, in a retained COMDAT .rodata section. */
#define DH_CFG_GROUP_ "dhmath_config_check_j" DH_CFG_STR_(DH_MAX_JOINTS) "_q" DH_CFG_STR_(DH_QPOS_FRAC)
__asm__(".pushsection .rodata." DH_CFG_GROUP_ ",\"aGR\",%progbits," DH_CFG_GROUP_ ",comdat\n\t"
        ".balign 4\n\t"
        ".hidden dhmath_config_mismatch_DH_MAX_JOINTS_is_" DH_CFG_STR_(DH_MAX_JOINTS) "\n\t"
        ".hidden dhmath_config_mismatch_DH_QPOS_FRAC_is_" DH_CFG_STR_(DH_QPOS_FRAC) "\n\t"
        ".4byte dhmath_config_mismatch_DH_MAX_JOINTS_is_" DH_CFG_STR_(DH_MAX_JOINTS) " - .\n\t"
        ".4byte dhmath_config_mismatch_DH_QPOS_FRAC_is_" DH_CFG_STR_(DH_QPOS_FRAC) " - .\n\t"
        ".popsection");
#endif

#endif /* DHMATH_CONFIG_H */
