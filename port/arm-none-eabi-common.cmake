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

# The compiler check cannot link a bare-metal executable without our
# startup and linker script: check by building a static library instead.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

# Never pick up host libraries or headers. The compiler driver finds
# newlib's multilib variant matching the -mcpu/-mfpu flags by itself.
set(CMAKE_FIND_ROOT_PATH ${CMAKE_CURRENT_LIST_DIR}/no-sysroot)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# The library links libm by name (-lm) so the driver picks the multilib
# variant (a find_library() hit would be one fixed variant, or the host's).
set(DHMATH_LIBM m CACHE STRING "libm for the target: linked as -lm")

set(CMAKE_C_FLAGS_INIT "${_dh_arch_flags} -std=c99 -ffunction-sections -fdata-sections")
set(CMAKE_ASM_FLAGS_INIT "${_dh_arch_flags}")
set(CMAKE_EXE_LINKER_FLAGS_INIT "-Wl,--gc-sections")
# CMAKE_C_FLAGS_INIT is ignored when CMAKE_C_FLAGS is given on the command
# line (-DCMAKE_C_FLAGS=-fstack-usage would silently build for the
# compiler's default ARMv4T/ARM-mode target): keep the core flags in front.
if(DEFINED CACHE{CMAKE_C_FLAGS} AND NOT CMAKE_C_FLAGS MATCHES "-mcpu=")
  set(CMAKE_C_FLAGS "${_dh_arch_flags} -std=c99 -ffunction-sections -fdata-sections ${CMAKE_C_FLAGS}"
      CACHE STRING "C flags (core flags added by the dhmath toolchain file)" FORCE)
endif()

# Optimised by default: the target suites run under emulation (and the
# footprint/guards stages look at optimised code). -DCMAKE_BUILD_TYPE=...
# still wins.
if(NOT CMAKE_BUILD_TYPE)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type (default Release for targets)")
endif()

set(DH_TARGET_CPU ${_dh_qemu_cpu} CACHE STRING "QEMU -cpu for target tests")
set(DH_TARGET_BOARD ${_dh_board} CACHE STRING "QEMU -machine and linker script port/<board>.ld")
set(DH_QEMU qemu-system-arm CACHE STRING "Emulator used to run target tests")

set(CMAKE_CROSSCOMPILING_EMULATOR
    ${DH_QEMU} -machine ${DH_TARGET_BOARD} -cpu ${DH_TARGET_CPU}
    -nographic -monitor none -serial none
    -semihosting-config enable=on,target=native
    -kernel)
