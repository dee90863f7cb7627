# SPDX-License-Identifier: Apache-2.0
# no_float.cmake - ctest script (cmake -P): the linked image ELF defines
# and references no soft-float or libm routine: no __aeabi_f* / __aeabi_d*
# (float and double arithmetic and conversions), no __aeabi_[ui]2f/2d,
# no libm entry points (sqrtf, sinf, ...) and no newlib float formatting.
# Variables: NM (arm-none-eabi-nm), ELF (the linked firmware).
execute_process(COMMAND ${NM} ${ELF} OUTPUT_VARIABLE syms RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR syms STREQUAL "")
  message(FATAL_ERROR "${NM} ${ELF} failed (${rc})")
endif()
string(REGEX MATCHALL "[ \t][A-Za-z] (__aeabi_[fd][a-z0-9]*|__aeabi_[a-z0-9]*2[fd]|_?_?(sqrt|sin|cos|atan2|fabs|floor)f?|_dtoa_r|__adddf3|__addsf3|__mulsf3|__muldf3)\n" bad "${syms}")
if(bad)
  message(FATAL_ERROR "floating-point routines linked into ${ELF}:\n${bad}")
endif()
message(STATUS "${ELF}: no floating-point routine linked")
