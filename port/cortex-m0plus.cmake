# SPDX-License-Identifier: Apache-2.0
# Cortex-M0+ (ARMv6-M): no FPU (soft float), no 32x32->64 multiply (SMULL),
# no divide instruction, no SSAT/CLZ.
# QEMU has no Cortex-M0+ model; ARMv6-M code runs on its cortex-m0 CPU.
# See docs/porting.md for the choice of board.
#   cmake -S . -B build-m0 -DCMAKE_TOOLCHAIN_FILE=port/cortex-m0plus.cmake
set(_dh_arch_flags "-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft")
set(_dh_qemu_cpu cortex-m0)
set(_dh_board microbit)
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi-common.cmake)
