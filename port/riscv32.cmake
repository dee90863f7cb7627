# RISC-V RV32IMAC, ilp32 (soft float): compile-only check that the library
# is portable C99 beyond ARM (no intrinsics path, no ARM assumptions).
# The Debian riscv64-unknown-elf-gcc ships no C library for rv32, so only
# the library is built (tests need a libc and an emulator setup):
#   cmake -S . -B build-rv32 -DCMAKE_TOOLCHAIN_FILE=port/riscv32.cmake -DDH_BUILD_TESTS=OFF
# (DH_BUILD_TESTS and DH_BUILD_TOOLS default to OFF with this file.)
# Headers: the library needs <math.h> and <string.h> declarations only;
# they come from newlib's generic headers (Debian package libnewlib-dev,
# /usr/include/newlib) when present.

set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR riscv32)
set(CMAKE_C_COMPILER riscv64-unknown-elf-gcc)
set(CMAKE_AR riscv64-unknown-elf-ar CACHE FILEPATH "")
set(CMAKE_RANLIB riscv64-unknown-elf-ranlib CACHE FILEPATH "")
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

set(CMAKE_FIND_ROOT_PATH ${CMAKE_CURRENT_LIST_DIR}/no-sysroot)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
set(DHMATH_LIBM m CACHE STRING "libm for the target: linked as -lm")

set(_dh_rv_flags "-march=rv32imac -mabi=ilp32 -mcmodel=medlow")
if(EXISTS /usr/include/newlib/math.h)
  string(APPEND _dh_rv_flags " -isystem /usr/include/newlib")
endif()
set(CMAKE_C_FLAGS_INIT "${_dh_rv_flags} -std=c99 -ffunction-sections -fdata-sections")

if(NOT CMAKE_BUILD_TYPE)
  set(CMAKE_BUILD_TYPE MinSizeRel CACHE STRING "Build type (default MinSizeRel for the compile-only target)")
endif()
set(DH_BUILD_TESTS OFF CACHE BOOL "No tests on riscv32 (no C library)")
set(DH_BUILD_TOOLS OFF CACHE BOOL "No host tools when cross-compiling")
