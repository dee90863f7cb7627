# SPDX-License-Identifier: Apache-2.0
# cmake -DEXE=dhmath -DIN=robot.dh -DNAME=ident -DOUT=file.c -P dhmathGen.cmake
# The build step of dhmath_add_robot() (dhmathRobot.cmake): runs
# `EXE gen IN NAME` and writes its standard output to OUT; fails, leaving no
# OUT, when the command fails.
execute_process(COMMAND ${EXE} gen ${IN} ${NAME}
  OUTPUT_VARIABLE _src ERROR_VARIABLE _err RESULT_VARIABLE _rc)
if(NOT _rc EQUAL 0)
  file(REMOVE ${OUT})
  message(FATAL_ERROR "dhmath gen ${IN} ${NAME} failed (${_rc}): ${_err}")
endif()
file(WRITE ${OUT} "${_src}")
