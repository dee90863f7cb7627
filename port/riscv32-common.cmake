# riscv32-common.cmake - shared part of dhmath's RV32 toolchain files
# (riscv32-imac.cmake, riscv32-imafc.cmake). A per-core file sets
#   _dh_arch_flags   the -march/-mabi flags
#   _dh_qemu_cpu     QEMU's -cpu (a generic rv32 with the extensions)
# and includes this file.
#
# Compiler: Debian's gcc-riscv64-unknown-elf (multilib, builds rv32).
# C library: Debian's picolibc-riscv64-unknown-elf (--specs=picolibc.specs
# selects the multilib variant matching -march/-mabi; stdio through its
# semihosting library). Tests and examples run on QEMU's `virt` machine
# (qemu-system-riscv32, Debian package qemu-system-misc) through
# CMAKE_CROSSCOMPILING_EMULATOR, like the Cortex-M targets; the startup is
# port/startup_rv.c, the memory map port/qemu-virt-rv32.ld.
#
# Cache variables (the names the top CMakeLists knows):
#   DH_TARGET_CPU    QEMU -cpu
#   DH_TARGET_BOARD  QEMU -machine and port/<board>.ld (qemu-virt-rv32 is
#                    the `virt` machine)
#   DH_QEMU          the emulator program (qemu-system-riscv32)

set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR riscv32)

set(CMAKE_C_COMPILER riscv64-unknown-elf-gcc)
set(CMAKE_CXX_COMPILER riscv64-unknown-elf-g++)
set(CMAKE_ASM_COMPILER riscv64-unknown-elf-gcc)
set(CMAKE_AR riscv64-unknown-elf-ar CACHE FILEPATH "")
set(CMAKE_RANLIB riscv64-unknown-elf-ranlib CACHE FILEPATH "")
set(CMAKE_OBJCOPY riscv64-unknown-elf-objcopy CACHE FILEPATH "")
set(CMAKE_SIZE riscv64-unknown-elf-size CACHE FILEPATH "")
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

set(CMAKE_FIND_ROOT_PATH ${CMAKE_CURRENT_LIST_DIR}/no-sysroot)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
set(DHMATH_LIBM m CACHE STRING "libm for the target: linked as -lm")

# --specs=picolibc.specs on every compile too: it puts picolibc's headers
# in front (the compiler has no C library of its own).
set(_dh_rv_common "${_dh_arch_flags} -mcmodel=medany --specs=picolibc.specs")
set(CMAKE_C_FLAGS_INIT "${_dh_rv_common} -std=c99 -ffunction-sections -fdata-sections")
set(CMAKE_ASM_FLAGS_INIT "${_dh_rv_common}")
# (the C flags carry --specs=picolibc.specs to the link as well; naming it
# twice is an error)
set(CMAKE_EXE_LINKER_FLAGS_INIT "-Wl,--gc-sections")
# as in arm-none-eabi-common.cmake: keep the core flags when CMAKE_C_FLAGS
# is given on the command line
if(DEFINED CACHE{CMAKE_C_FLAGS} AND NOT CMAKE_C_FLAGS MATCHES "-march=")
  set(CMAKE_C_FLAGS "${_dh_rv_common} -std=c99 -ffunction-sections -fdata-sections ${CMAKE_C_FLAGS}"
      CACHE STRING "C flags (core flags added by the dhmath toolchain file)" FORCE)
endif()

if(NOT CMAKE_BUILD_TYPE)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type (default Release for targets)")
endif()

set(DH_TARGET_CPU ${_dh_qemu_cpu} CACHE STRING "QEMU -cpu for target tests")
set(DH_TARGET_BOARD qemu-virt-rv32 CACHE STRING "QEMU machine (virt) and linker script port/<board>.ld")
set(DH_QEMU qemu-system-riscv32 CACHE STRING "Emulator used to run target tests")

set(CMAKE_CROSSCOMPILING_EMULATOR
    ${DH_QEMU} -machine virt -cpu ${DH_TARGET_CPU} -bios none
    -nographic -monitor none -serial none
    -semihosting-config enable=on,target=native
    -kernel)
