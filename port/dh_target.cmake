# SPDX-License-Identifier: Apache-2.0
# dh_target.cmake - how target (Cortex-M or RV32, QEMU) test executables are linked.
# Included by test/CMakeLists.txt when cross-compiling, after the `dht`
# library target exists and before the test executables are created.
#
# Provides
#   dh_target_link(<target>)  adds the startup (Cortex-M: port/startup_cm.c
#                             with newlib's semihosting syscalls, rdimon;
#                             RV32: port/startup_rv.c with picolibc's
#                             semihosting library), the board's linker
#                             script port/${DH_TARGET_BOARD}.ld, libm and a
#                             map file; the executable then runs under
#                             CMAKE_CROSSCOMPILING_EMULATOR (set by the
#                             toolchain file).
#   DH_TARGET_ITER_DIV        divisor for DHT_ITER(n) loop counts on this
#                             core (see the table below; measured run
#                             times are in docs/porting.md).
# Cache options (non-DH_ names, the DH_ namespace is closed):
#   DHT_ITER_DIV_OVERRIDE     use this DHT_ITER divisor instead (e.g. 1 for
#                             a full-length soak run under QEMU)
#   DHT_SEED                  seed for the target runner (the host reads
#                             the DHT_SEED environment variable; a target
#                             has no environment, so rebuild with
#                             -DDHT_SEED=0x... to replay a failing seed)

if(NOT DEFINED DH_TARGET_BOARD OR NOT DEFINED DH_TARGET_CPU)
  message(FATAL_ERROR "dh_target.cmake: DH_TARGET_BOARD / DH_TARGET_CPU unset; "
                      "configure with -DCMAKE_TOOLCHAIN_FILE=port/<core>.cmake")
endif()

set(_dh_port_dir ${CMAKE_CURRENT_LIST_DIR})
set(_dh_ld ${_dh_port_dir}/${DH_TARGET_BOARD}.ld)
if(NOT EXISTS ${_dh_ld})
  message(FATAL_ERROR "dh_target.cmake: no linker script ${_dh_ld} for board ${DH_TARGET_BOARD}")
endif()

# DHT_ITER divisor per core. QEMU's cost is the number of guest
# instructions: soft float (M0, M3, and double precision on the M4F) costs
# 10-30 instructions per operation, the M0 also lacks the 32x32->64
# multiply. The host runs the full (often exhaustive) loops; the target
# runs check that the code compiled for the core gives the same results,
# which a 1/20..1/200 sample does. Measured QEMU CPU time of the whole
# suite per core is in docs/porting.md; keep each core under ~30 s.
if(CMAKE_C_FLAGS MATCHES "cortex-m0")
  set(DH_TARGET_ITER_DIV 200)
elseif(CMAKE_C_FLAGS MATCHES "cortex-m3")
  set(DH_TARGET_ITER_DIV 100)
elseif(CMAKE_C_FLAGS MATCHES "cortex-m4")
  set(DH_TARGET_ITER_DIV 50)
elseif(CMAKE_C_FLAGS MATCHES "cortex-m7")
  set(DH_TARGET_ITER_DIV 20)
elseif(CMAKE_C_FLAGS MATCHES "rv32ima")
  # both RV32 cores: QEMU emulates RISC-V F instructions through its
  # softfloat helpers, so the FPU core is no faster to emulate than soft
  # float (at the M4F's 50 its suites take several times as long as the
  # RV32IMAC ones at 100)
  set(DH_TARGET_ITER_DIV 100)
else()
  set(DH_TARGET_ITER_DIV 200)
endif()
set(DHT_ITER_DIV_OVERRIDE "" CACHE STRING "Override the target DHT_ITER divisor (empty: per-core default)")
if(DHT_ITER_DIV_OVERRIDE)
  set(DH_TARGET_ITER_DIV ${DHT_ITER_DIV_OVERRIDE})
endif()

set(DHT_SEED "" CACHE STRING "Seed of the target test runner (empty: the default seed of test/dht_common.c)")
# the same rule as the host's DHT_SEED (test/dht.h dht_parse_seed): decimal
# without a leading zero or 0x hex, so "010" cannot silently become octal 8
if(NOT DHT_SEED STREQUAL "" AND NOT DHT_SEED MATCHES "^(0|[1-9][0-9]*|0[xX][0-9a-fA-F]+)$")
  message(FATAL_ERROR "DHT_SEED=${DHT_SEED} is not a seed: decimal digits without a leading zero, or 0x and hex digits")
endif()
if(NOT DHT_SEED STREQUAL "" AND TARGET dht)
  target_compile_definitions(dht PRIVATE DHT_DEFAULT_SEED=${DHT_SEED})
endif()

if(CMAKE_SYSTEM_PROCESSOR MATCHES "^riscv")
  # with a floor() that replaces the wrong one of Debian's picolibc 1.8
  # (see port/picolibc_floor.c)
  set(_dh_startup ${_dh_port_dir}/startup_rv.c ${_dh_port_dir}/picolibc_floor.c)
  # picolibc: its semihosting library for stdio, picolibc.ld (INCLUDEd by
  # the board script) for the sections
  set(_dh_libc_opts --oslib=semihost)
  set(_dh_ld_deps ${_dh_ld})
  # the fault self-test's expected message (port/startup_rv.c)
  set(_dh_fault_re "breakpoint at pc 0x")
else()
  set(_dh_startup ${_dh_port_dir}/startup_cm.c)
  set(_dh_libc_opts --specs=rdimon.specs)
  set(_dh_ld_deps ${_dh_ld} ${_dh_port_dir}/cm_sections.ld)
  set(_dh_fault_re "(HardFault|UsageFault) at pc 0x")
endif()

function(dh_target_link tgt)
  target_sources(${tgt} PRIVATE ${_dh_startup})
  target_link_options(${tgt} PRIVATE
    -nostartfiles ${_dh_libc_opts}
    -L${_dh_port_dir} -T${_dh_ld}
    -Wl,--gc-sections
    -Wl,-Map=$<TARGET_FILE:${tgt}>.map)
  target_link_libraries(${tgt} PRIVATE m)
  set_property(TARGET ${tgt} APPEND PROPERTY LINK_DEPENDS ${_dh_ld_deps})
endfunction()

# Self-tests of this infrastructure, run by ctest on every target before the
# library's suites mean anything: a failing case must give a non-zero QEMU
# exit status (the number of failed cases) and a crash must end the run
# with status 3 and a message instead of hanging.
if(TARGET dht)
  string(REPLACE ";" "|" _dh_emu "${CMAKE_CROSSCOMPILING_EMULATOR}")
  foreach(_st IN ITEMS runner fault)
    add_executable(port_selftest_${_st} ${_dh_port_dir}/selftest/selftest_${_st}.c)
    target_link_libraries(port_selftest_${_st} PRIVATE dht)
    set_target_properties(port_selftest_${_st} PROPERTIES C_STANDARD 99 C_EXTENSIONS OFF)
    target_compile_options(port_selftest_${_st} PRIVATE -Wall -Wextra -Werror)
    dh_target_link(port_selftest_${_st})
  endforeach()
  add_test(NAME port_selftest_runner
    COMMAND ${CMAKE_COMMAND} "-DEMU=${_dh_emu}" -DEXE=$<TARGET_FILE:port_selftest_runner>
            -DSTATUS=2
            "-DEXPECT=OK . startup_copies_data_and_zeroes_bss~~OK . float_and_double_arithmetic~~diff 0.25 > tol 0.001~~-5000000000 != 2~~OK . runs_after_failures~~FAILED  . 2 test"
            -P ${_dh_port_dir}/selftest/expect.cmake)
  add_test(NAME port_selftest_fault
    COMMAND ${CMAKE_COMMAND} "-DEMU=${_dh_emu}" -DEXE=$<TARGET_FILE:port_selftest_fault>
            -DSTATUS=3
            "-DEXPECT=about to trap~~\\*\\*\\* dhmath target: ${_dh_fault_re}"
            -P ${_dh_port_dir}/selftest/expect.cmake)
endif()

# The firmware examples (examples/firmware/) are built and checked on every
# target as well.
if(TARGET dht AND EXISTS ${PROJECT_SOURCE_DIR}/examples/firmware/CMakeLists.txt)
  add_subdirectory(${PROJECT_SOURCE_DIR}/examples/firmware ${CMAKE_BINARY_DIR}/examples/firmware)
endif()
