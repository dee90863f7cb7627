# SPDX-License-Identifier: Apache-2.0
# fixed_const_m0.cmake - ctest script (cmake -P): test/fixed_const_m0.c,
# which uses DH_Q16 / DH_Q30 / DH_QPOS, compiled for Cortex-M0+ (soft
# float) at -O0 and -Os references no routine (nm -u lists nothing but the
# configuration guard's symbols of config.h: no soft-float call), and the out-of-range variant does not compile (even
# without -Werror: the initialiser is not a constant).
# Variables: CC (arm-none-eabi-gcc), NM, SRC_DIR (project root), OUT (dir).
set(base -mcpu=cortex-m0plus -mthumb -mfloat-abi=soft -std=c99 -pedantic -Wall -Wextra
         -Wconversion -I${SRC_DIR}/include -c ${SRC_DIR}/test/fixed_const_m0.c)
set(flags ${base} -Werror)
foreach(opt -O0 -Os)
  set(obj ${OUT}/fixed_const_m0${opt}.o)
  execute_process(COMMAND ${CC} ${opt} ${flags} -o ${obj} RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "fixed_const_m0.c ${opt} does not compile:\n${err}")
  endif()
  execute_process(COMMAND ${NM} -u ${obj} OUTPUT_VARIABLE undef RESULT_VARIABLE rc)
  string(REGEX REPLACE "[ \t]*U dhmath_config_mismatch_[A-Za-z0-9_]+\n" "" undef "${undef}")
  if(NOT rc EQUAL 0 OR NOT undef STREQUAL "")
    message(FATAL_ERROR "fixed_const_m0.c ${opt} references routines (nm -u):\n${undef}")
  endif()
  message(STATUS "fixed_const_m0.c ${opt}: no undefined symbols")
endforeach()
# without -Werror: rejected as a non-constant initialiser, not for a warning
execute_process(COMMAND ${CC} -Os -DDH_CONST_OUT_OF_RANGE ${base} -o ${OUT}/fixed_const_bad.o
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(rc EQUAL 0)
  message(FATAL_ERROR "an out-of-range DH_Q16 literal in a static initialiser compiled")
endif()
message(STATUS "out-of-range literal rejected:\n${err}")
