# SPDX-License-Identifier: Apache-2.0
# cmake -DEXE=dhmath -DCC=cc -DINC=include -DROBOT=puma560.dh -DDIR=tmp -DQPOS=16 -P cli_gen.cmake
# (QPOS: the DH_QPOS_FRAC the generator was built with)
# `dhmath gen` errors: a NAME that is no usable C identifier, a missing
# file or wrong arguments exit with status 2, a message on stderr and
# nothing on stdout. The guards of the generated source: it compiles with
# DH_MAX_JOINTS from the robot's joint count to 32 and stops with #error
# under fewer joints or another DH_QPOS_FRAC.
function(expect_error)
  execute_process(COMMAND ${EXE} gen ${ARGN} OUTPUT_VARIABLE _out ERROR_VARIABLE _err RESULT_VARIABLE _rc)
  if(NOT _rc EQUAL 2 OR NOT _out STREQUAL "" OR NOT _err MATCHES "dhmath: ")
    message(FATAL_ERROR "dhmath gen ${ARGN}: exit ${_rc}, stdout '${_out}', stderr '${_err}' (want 2, nothing, a message)")
  endif()
  message(STATUS "gen ${ARGN}: ${_err}")
endfunction()
# an empty NAME (an empty list element would vanish from ${ARGN})
execute_process(COMMAND ${EXE} gen ${ROBOT} "" OUTPUT_VARIABLE _out ERROR_VARIABLE _err RESULT_VARIABLE _rc)
if(NOT _rc EQUAL 2 OR NOT _out STREQUAL "" OR NOT _err MATCHES "it is empty")
  message(FATAL_ERROR "dhmath gen ROBOT '': exit ${_rc}, stderr '${_err}'")
endif()
foreach(_name "9lives" "a-b" "x y" "int" "_Bool" "__x" "_Robot" "r\$"
              "a123456789012345678901234567890123456789012345678901234567890123")
  expect_error(${ROBOT} "${_name}")
endforeach()
expect_error(${ROBOT})
expect_error(${ROBOT} a b)
expect_error(${DIR}/no-such-file.dh robot)

execute_process(COMMAND ${EXE} gen ${ROBOT} _my_robot1 OUTPUT_FILE ${DIR}/gen_guard.c RESULT_VARIABLE _rc)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "dhmath gen ${ROBOT} _my_robot1 failed")
endif()
function(try_cc want)
  execute_process(COMMAND ${CC} -std=c99 -pedantic -Werror -fsyntax-only -I${INC} ${ARGN} ${DIR}/gen_guard.c
                  RESULT_VARIABLE _rc ERROR_VARIABLE _err)
  if(want STREQUAL "ok" AND NOT _rc EQUAL 0)
    message(FATAL_ERROR "generated source does not compile with ${ARGN}: ${_err}")
  elseif(NOT want STREQUAL "ok" AND (_rc EQUAL 0 OR NOT _err MATCHES "${want}"))
    message(FATAL_ERROR "generated source with ${ARGN}: want an error '${want}', got ${_rc}: ${_err}")
  endif()
endfunction()
if(QPOS EQUAL 12)
  set(_other 16)
else()
  set(_other 12)
endif()
try_cc(ok -DDH_QPOS_FRAC=${QPOS} -DDH_MAX_JOINTS=6)
try_cc(ok -DDH_QPOS_FRAC=${QPOS} -DDH_MAX_JOINTS=32)
try_cc(ok -DDH_QPOS_FRAC=${QPOS} -DDH_MAX_JOINTS=8 -DDH_SMALL=1)
try_cc("DH_MAX_JOINTS must be at least 6" -DDH_QPOS_FRAC=${QPOS} -DDH_MAX_JOINTS=5)
try_cc("generated for DH_QPOS_FRAC ${QPOS}" -DDH_QPOS_FRAC=${_other})
