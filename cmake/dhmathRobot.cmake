# SPDX-License-Identifier: Apache-2.0
# dhmath_add_robot(<target> ROBOT <file.dh> NAME <c_identifier> [OUTPUT <file.c>])
#
# Turns a robot file (docs/cli.md) into C source at build time and adds it
# to <target>: `dhmath gen <file.dh> <c_identifier>` writes the definition
# of `const dh_robot <c_identifier>` with every derived field computed, so
# the robot lives in flash and the firmware declares it with
#   extern const dh_robot <c_identifier>;
# ROBOT is relative to the calling directory's source directory, OUTPUT
# (default <c_identifier>.c) to its binary directory. The source is
# regenerated when the robot file or the generator changes. It compiles
# against the target's dhmath (the generated source checks that it sees the
# DH_MAX_JOINTS and DH_QPOS_FRAC the generator was built with).
#
# The generator runs on the build host. It is, in this order:
#   DHMATH_EXECUTABLE   a variable or cache entry naming the program (or a
#                       CMake target that builds it): always wins;
#   dhmath_cli          the CLI target of a vendored dhmath
#                       (add_subdirectory), in a build that is not a cross
#                       build (a cross build's target would not run here);
#   find_program()      `dhmath` in the installed package's bin/ (this
#                       package's prefix), CMAKE_PREFIX_PATH's bin/ and PATH;
#                       the result is cached in DHMATH_EXECUTABLE.
# A cross build that finds none stops, saying how to get a host dhmath.
#
# Provided by the dhmath CMake package (find_package(dhmath)) and by the
# top-level CMakeLists.txt (add_subdirectory / FetchContent).
include_guard(GLOBAL)
set_property(GLOBAL PROPERTY _dhmath_robot_gen "${CMAKE_CURRENT_LIST_DIR}/dhmathGen.cmake")

function(dhmath_add_robot target)
  cmake_parse_arguments(PARSE_ARGV 1 _ar "" "ROBOT;NAME;OUTPUT" "")
  if(_ar_UNPARSED_ARGUMENTS OR NOT _ar_ROBOT OR NOT _ar_NAME)
    message(FATAL_ERROR "dhmath_add_robot(${target} ...): usage "
      "dhmath_add_robot(<target> ROBOT <file.dh> NAME <c_identifier> [OUTPUT <file.c>])")
  endif()
  if(NOT TARGET ${target})
    message(FATAL_ERROR "dhmath_add_robot: ${target} is not a target")
  endif()
  if(NOT _ar_NAME MATCHES "^[A-Za-z_][A-Za-z0-9_]*$")
    message(FATAL_ERROR "dhmath_add_robot: NAME '${_ar_NAME}' is not a C identifier")
  endif()
  get_filename_component(_in "${_ar_ROBOT}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
  if(NOT _ar_OUTPUT)
    set(_ar_OUTPUT ${_ar_NAME}.c)
  endif()
  get_filename_component(_out "${_ar_OUTPUT}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")

  if(DHMATH_EXECUTABLE)
    set(_exe "${DHMATH_EXECUTABLE}")
  elseif(TARGET dhmath_cli AND NOT CMAKE_CROSSCOMPILING)
    set(_exe dhmath_cli)
  else()
    # the installed package's bin/ (dhmathConfig.cmake sets the property)
    get_property(_bindir GLOBAL PROPERTY _dhmath_robot_bindir)
    find_program(DHMATH_EXECUTABLE NAMES dhmath HINTS ${_bindir}
      DOC "Host dhmath CLI that dhmath_add_robot() runs (dhmath gen)")
    if(NOT DHMATH_EXECUTABLE)
      message(FATAL_ERROR "dhmath_add_robot(${target}): no host `dhmath` program to run "
        "`dhmath gen ${_ar_ROBOT} ${_ar_NAME}`. A cross build runs the generator on the build "
        "host: build dhmath for the host (cmake -S <dhmath> -B build-host && cmake --build "
        "build-host && cmake --install build-host --prefix <host-prefix>) and add <host-prefix> "
        "to CMAKE_PREFIX_PATH or PATH, or pass -DDHMATH_EXECUTABLE=<path to the host dhmath>.")
    endif()
    set(_exe "${DHMATH_EXECUTABLE}")
  endif()
  if(TARGET ${_exe})
    set(_dep ${_exe})
    set(_exe $<TARGET_FILE:${_exe}>)
  else()
    set(_dep ${_exe})
  endif()

  get_property(_gen GLOBAL PROPERTY _dhmath_robot_gen)
  add_custom_command(OUTPUT ${_out}
    COMMAND ${CMAKE_COMMAND} -DEXE=${_exe} -DIN=${_in} -DNAME=${_ar_NAME} -DOUT=${_out} -P ${_gen}
    DEPENDS ${_in} ${_dep} ${_gen}
    COMMENT "dhmath gen ${_ar_ROBOT} ${_ar_NAME}"
    VERBATIM)
  target_sources(${target} PRIVATE ${_out})
endfunction()
