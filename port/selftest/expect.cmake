# SPDX-License-Identifier: Apache-2.0
# expect.cmake - runs one target self-test executable under the emulator and
# checks its exit status and output (ctest alone can check either, not both).
#   cmake -DEMU="<emulator|args...>" -DEXE=<elf> -DSTATUS=<n>
#         -DEXPECT="<regex~~regex...>"  (EMU joined with |, EXPECT with ~~) -P expect.cmake
string(REPLACE "|" ";" EMU "${EMU}")
string(REPLACE "~~" ";" EXPECT "${EXPECT}")
execute_process(COMMAND ${EMU} ${EXE}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
                TIMEOUT 60)
message("${out}${err}")
if(NOT rc STREQUAL "${STATUS}")
  message(FATAL_ERROR "exit status '${rc}', expected ${STATUS}")
endif()
# (no square brackets in the regexes: they would stop CMake's list split)
foreach(re IN LISTS EXPECT)
  if(NOT "${out}${err}" MATCHES "${re}")
    message(FATAL_ERROR "output does not match '${re}'")
  endif()
endforeach()
message("self-test: exit status ${rc} and output as expected")
