# SPDX-License-Identifier: Apache-2.0
# Cortex-M4 with the single-precision FPU (FPv4-SP-D16), hard-float ABI.
# Tests run on QEMU's mps2-an386 (AN386 FPGA image: Cortex-M4F).
#   cmake -S . -B build-m4f -DCMAKE_TOOLCHAIN_FILE=port/cortex-m4f.cmake
set(_dh_arch_flags "-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard")
set(_dh_qemu_cpu cortex-m4)
set(_dh_board mps2-an386)
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi-common.cmake)
