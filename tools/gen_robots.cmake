# SPDX-License-Identifier: Apache-2.0
# dh_robot_tables(<target>...): give the targets the header dh_robots.h with
# the shipped robots' DH tables, generated at build time from
# examples/robots/*.dh by tools/gen_robots.py (macro layout: the head of that
# script). Host and cross builds alike; the generator runs on the build host.
# Call once per directory, with every target of that directory that needs it.
set(_dh_robots_root ${CMAKE_CURRENT_LIST_DIR}/..)
function(dh_robot_tables first)
  # not DH_*: that cache namespace is the library's options (checked)
  find_program(DHMATH_ROBOTS_PYTHON3 NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
  if(NOT DHMATH_ROBOTS_PYTHON3)
    find_program(DHMATH_ROBOTS_PYTHON3 NAMES python3 REQUIRED)
  endif()
  file(GLOB _dh CONFIGURE_DEPENDS ${_dh_robots_root}/examples/robots/*.dh)
  set(_dir ${CMAKE_CURRENT_BINARY_DIR}/dh_robots)
  add_custom_command(OUTPUT ${_dir}/dh_robots.h
    COMMAND ${CMAKE_COMMAND} -E make_directory ${_dir}
    COMMAND ${DHMATH_ROBOTS_PYTHON3} ${_dh_robots_root}/tools/gen_robots.py -o ${_dir}/dh_robots.h ${_dh}
    DEPENDS ${_dh_robots_root}/tools/gen_robots.py ${_dh}
    COMMENT "Robot tables from examples/robots/*.dh"
    VERBATIM)
  add_custom_target(${first}_dh_robots DEPENDS ${_dir}/dh_robots.h)
  foreach(t IN ITEMS ${first} ${ARGN})
    add_dependencies(${t} ${first}_dh_robots)
    target_include_directories(${t} PRIVATE ${_dir})
  endforeach()
endfunction()
