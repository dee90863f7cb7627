# SPDX-License-Identifier: Apache-2.0
# Cortex-M3 (ARMv7-M, no FPU: soft float; has UMULL/SMULL and a divider).
# Tests run on QEMU's mps2-an385 (AN385 FPGA image: Cortex-M3).
#   cmake -S . -B build-m3 -DCMAKE_TOOLCHAIN_FILE=port/cortex-m3.cmake
set(_dh_arch_flags "-mcpu=cortex-m3 -mthumb -mfloat-abi=soft")
set(_dh_qemu_cpu cortex-m3)
set(_dh_board mps2-an385)
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi-common.cmake)
