# SPDX-License-Identifier: Apache-2.0
# arm-none-eabi-common.cmake - shared part of dhmath's Cortex-M toolchain
# files. A per-core file (cortex-m0plus.cmake, cortex-m3.cmake,
# cortex-m4f.cmake, cortex-m7.cmake) sets
#   _dh_arch_flags   the -mcpu/-mfpu/-mfloat-abi/-mthumb flags
#   _dh_qemu_cpu     QEMU's -cpu name
#   _dh_board        QEMU machine = linker script port/<board>.ld
# and includes this file.
#
# Cache variables (the names the top CMakeLists knows):
#   DH_TARGET_CPU    QEMU -cpu   (override e.g. to run M0 code on another board)
#   DH_TARGET_BOARD  QEMU -machine and port/<board>.ld
#   DH_QEMU          the emulator program (qemu-system-arm)
# Tests run through CMAKE_CROSSCOMPILING_EMULATOR, so a plain `ctest` runs
# every test under QEMU with semihosting (see port/dh_target.cmake).

set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
set(CMAKE_AR arm-none-eabi-ar CACHE FILEPATH "")
set(CMAKE_RANLIB arm-none-eabi-ranlib CACHE FILEPATH "")
set(CMAKE_OBJCOPY arm-none-eabi-objcopy CACHE FILEPATH "")
set(CMAKE_SIZE arm-none-eabi-size CACHE FILEPATH "")

set(_dh_core_flags "${_dh_arch_flags}")
set(_dh_core_flag_re "-mcpu=")
include(${CMAKE_CURRENT_LIST_DIR}/dh_cross_common.cmake)

set(DH_TARGET_CPU ${_dh_qemu_cpu} CACHE STRING "QEMU -cpu for target tests")
set(DH_TARGET_BOARD ${_dh_board} CACHE STRING "QEMU -machine and linker script port/<board>.ld")
set(DH_QEMU qemu-system-arm CACHE STRING "Emulator used to run target tests")

set(CMAKE_CROSSCOMPILING_EMULATOR
    ${DH_QEMU} -machine ${DH_TARGET_BOARD} -cpu ${DH_TARGET_CPU}
    -nographic -monitor none -serial none
    -semihosting-config enable=on,target=native
    -kernel)
