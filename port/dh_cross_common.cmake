# SPDX-License-Identifier: Apache-2.0
# dh_cross_common.cmake - the part of dhmath's toolchain files that does not
# depend on the architecture, included by arm-none-eabi-common.cmake and
# riscv32-common.cmake after they set
#   _dh_core_flags     the core flags every compile (and link) gets
#   _dh_core_flag_re   a regex that finds them in CMAKE_C_FLAGS

# The compiler check cannot link a bare-metal executable without our
# startup and linker script: check by building a static library instead.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

# Never pick up host libraries, headers or packages. The compiler driver
# finds the C library's multilib variant matching the core flags by itself.
# The prefixes the user names (CMAKE_PREFIX_PATH, on the command line or in
# the environment) are target prefixes, e.g. a cross build of dhmath
# installed with cmake --install: they are search roots, so
# find_package(dhmath) finds <prefix>/lib/cmake/dhmath there and nowhere
# on the host.
set(CMAKE_FIND_ROOT_PATH ${CMAKE_CURRENT_LIST_DIR}/no-sysroot)
foreach(_dh_p IN LISTS CMAKE_PREFIX_PATH)
  list(APPEND CMAKE_FIND_ROOT_PATH "${_dh_p}")
endforeach()
if(DEFINED ENV{CMAKE_PREFIX_PATH})
  string(REPLACE ":" ";" _dh_env_prefixes "$ENV{CMAKE_PREFIX_PATH}")
  list(APPEND CMAKE_FIND_ROOT_PATH ${_dh_env_prefixes})
endif()
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# The library links libm by name (-lm) so the driver picks the multilib
# variant (a find_library() hit would be one fixed variant, or the host's).
set(DHMATH_LIBM m CACHE STRING "libm for the target: linked as -lm")

set(CMAKE_C_FLAGS_INIT "${_dh_core_flags} -std=c99 -ffunction-sections -fdata-sections")
set(CMAKE_ASM_FLAGS_INIT "${_dh_core_flags}")
set(CMAKE_EXE_LINKER_FLAGS_INIT "-Wl,--gc-sections")
# CMAKE_C_FLAGS_INIT is ignored when CMAKE_C_FLAGS is given on the command
# line (-DCMAKE_C_FLAGS=-fstack-usage would silently build for the
# compiler's default core): keep the core flags in front.
if(DEFINED CACHE{CMAKE_C_FLAGS} AND NOT CMAKE_C_FLAGS MATCHES "${_dh_core_flag_re}")
  set(CMAKE_C_FLAGS "${_dh_core_flags} -std=c99 -ffunction-sections -fdata-sections ${CMAKE_C_FLAGS}"
      CACHE STRING "C flags (core flags added by the dhmath toolchain file)" FORCE)
endif()

# Optimised by default: the target suites run under emulation (and the
# footprint/guards stages look at optimised code). -DCMAKE_BUILD_TYPE=...
# still wins.
if(NOT CMAKE_BUILD_TYPE)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type (default Release for targets)")
endif()
