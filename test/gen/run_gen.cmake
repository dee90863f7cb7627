# SPDX-License-Identifier: Apache-2.0
# cmake -DEXE=dhmath -DIN=robot.dh -DNAME=ident -DOUT=file.c -P run_gen.cmake
# Runs `EXE gen IN NAME` and writes its stdout to OUT; fails (and leaves no
# OUT) when the command fails.
execute_process(COMMAND ${EXE} gen ${IN} ${NAME}
  OUTPUT_VARIABLE _src ERROR_VARIABLE _err RESULT_VARIABLE _rc)
if(NOT _rc EQUAL 0)
  file(REMOVE ${OUT})
  message(FATAL_ERROR "dhmath gen ${IN} ${NAME} failed (${_rc}): ${_err}")
endif()
file(WRITE ${OUT} "${_src}")
