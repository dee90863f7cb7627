# SPDX-License-Identifier: Apache-2.0
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
# --specs=picolibc.specs on every compile too: it puts picolibc's headers
# in front (the compiler has no C library of its own). The C flags carry it
# to the link as well (naming it twice is an error).
set(_dh_core_flags "${_dh_arch_flags} -mcmodel=medany --specs=picolibc.specs")
set(_dh_core_flag_re "-march=")
include(${CMAKE_CURRENT_LIST_DIR}/dh_cross_common.cmake)

set(DH_TARGET_CPU ${_dh_qemu_cpu} CACHE STRING "QEMU -cpu for target tests")
set(DH_TARGET_BOARD qemu-virt-rv32 CACHE STRING "QEMU machine (virt) and linker script port/<board>.ld")
set(DH_QEMU qemu-system-riscv32 CACHE STRING "Emulator used to run target tests")

set(CMAKE_CROSSCOMPILING_EMULATOR
    ${DH_QEMU} -machine virt -cpu ${DH_TARGET_CPU} -bios none
    -nographic -monitor none -serial none
    -semihosting-config enable=on,target=native
    -kernel)
