# SPDX-License-Identifier: Apache-2.0
# Cortex-M7 with the double-precision FPU (FPv5-D16), hard-float ABI.
# Tests run on QEMU's mps2-an500 (AN500 FPGA image: Cortex-M7). QEMU's
# cortex-m7 model implements the double-precision FPv5 (MVFR0 reports
# double-precision support), so -mfpu=fpv5-d16 code runs; an M7 with
# the single-precision FPU only would use -mfpu=fpv5-sp-d16.
#   cmake -S . -B build-m7 -DCMAKE_TOOLCHAIN_FILE=port/cortex-m7.cmake
set(_dh_arch_flags "-mcpu=cortex-m7 -mthumb -mfpu=fpv5-d16 -mfloat-abi=hard")
set(_dh_qemu_cpu cortex-m7)
set(_dh_board mps2-an500)
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi-common.cmake)
