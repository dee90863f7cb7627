# SPDX-License-Identifier: Apache-2.0
# RISC-V RV32IMAFC, ilp32f: single-precision FPU (F), hard-float ABI for
# float arguments; double is soft. QEMU's sifive-e34 CPU model is an
# RV32IMAFC core (no D: a double-precision instruction would trap).
#   cmake -S . -B build/rv32imafc -DCMAKE_TOOLCHAIN_FILE=port/riscv32-imafc.cmake
set(_dh_arch_flags "-march=rv32imafc -mabi=ilp32f")
set(_dh_qemu_cpu sifive-e34)
include(${CMAKE_CURRENT_LIST_DIR}/riscv32-common.cmake)
