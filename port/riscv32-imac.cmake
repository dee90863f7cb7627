# SPDX-License-Identifier: Apache-2.0
# RISC-V RV32IMAC, ilp32: no FPU (soft float), with the M (multiply/divide,
# MULH for the 64-bit product), A and C extensions. QEMU's sifive-e31 CPU
# model is an RV32IMAC core (no F/D: a float instruction would trap).
#   cmake -S . -B build/rv32imac -DCMAKE_TOOLCHAIN_FILE=port/riscv32-imac.cmake
set(_dh_arch_flags "-march=rv32imac -mabi=ilp32")
set(_dh_qemu_cpu sifive-e31)
include(${CMAKE_CURRENT_LIST_DIR}/riscv32-common.cmake)
