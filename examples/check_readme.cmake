# SPDX-License-Identifier: Apache-2.0
# Fails when README.md does not contain examples/readme_example.c verbatim.
file(READ ${README} readme)
file(READ ${EXAMPLE} example)
string(FIND "${readme}" "${example}" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "README.md does not contain ${EXAMPLE} verbatim: update the README's example")
endif()
