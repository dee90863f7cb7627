# SPDX-License-Identifier: Apache-2.0
# Install rules of dhmath (included by the top-level CMakeLists.txt when
# DH_INSTALL is ON):
#   <prefix>/include/dhmath/*.h                 public headers
#   <prefix>/lib/libdhmath.a                    the library
#   <prefix>/lib/cmake/dhmath/                  find_package(dhmath 0.3 CONFIG)
#                                               -> imported target dhmath::dhmath
#   <prefix>/lib/cmake/dhmath/dhmathRobot.cmake  dhmath_add_robot() (with
#                                               dhmathGen.cmake)
#   <prefix>/lib/pkgconfig/dhmath.pc            pkg-config dhmath
#   <prefix>/bin/dhmath                         the host CLI (host builds
#                                               with DH_BUILD_TOOLS)
#   <prefix>/share/doc/dhmath/LICENSE           the licence (Apache-2.0)
# The build's DH_* settings travel as interface definitions (CMake) and in
# Cflags (pkg-config), so a consumer compiles with the library's layout.
include(CMakePackageConfigHelpers)

set(DH_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/dhmath)

install(TARGETS dhmath EXPORT dhmathTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/dhmath
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h")
if(DH_CONFIG_HEADER AND IS_ABSOLUTE "${DH_CONFIG_HEADER}")
  install(FILES ${DH_CONFIG_HEADER} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/dhmath)
endif()
install(EXPORT dhmathTargets NAMESPACE dhmath:: DESTINATION ${DH_INSTALL_CMAKEDIR})
if(DH_BUILD_TOOLS AND NOT CMAKE_CROSSCOMPILING)
  install(TARGETS dhmath_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(FILES ${PROJECT_SOURCE_DIR}/cmake/dhmathRobot.cmake ${PROJECT_SOURCE_DIR}/cmake/dhmathGen.cmake
  DESTINATION ${DH_INSTALL_CMAKEDIR})
# SPDX identifier of the licence: dhmathConfig.cmake (dhmath_LICENSE),
# dhmath.pc (License:)
set(DH_LICENSE Apache-2.0)

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/dhmathConfig.cmake.in
  ${PROJECT_BINARY_DIR}/dhmathConfig.cmake INSTALL_DESTINATION ${DH_INSTALL_CMAKEDIR}
  PATH_VARS CMAKE_INSTALL_BINDIR CMAKE_INSTALL_DOCDIR)
# 0.x: a new minor version may change the API, so only the same minor matches
write_basic_package_version_file(${PROJECT_BINARY_DIR}/dhmathConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/dhmathConfig.cmake ${PROJECT_BINARY_DIR}/dhmathConfigVersion.cmake
  DESTINATION ${DH_INSTALL_CMAKEDIR})

# pkg-config: the same definitions as the CMake target's interface
set(DH_PC_CFLAGS "")
foreach(_d IN LISTS DH_PUBLIC_DEFS)
  string(APPEND DH_PC_CFLAGS " -D${_d}")
endforeach()
if(DH_CONFIG_HEADER)
  if(IS_ABSOLUTE "${DH_CONFIG_HEADER}")
    get_filename_component(_dh_cfgname "${DH_CONFIG_HEADER}" NAME)
    string(APPEND DH_PC_CFLAGS " '-DDH_CONFIG_HEADER=\"dhmath/${_dh_cfgname}\"'")
  else()
    string(APPEND DH_PC_CFLAGS " '-DDH_CONFIG_HEADER=\"${DH_CONFIG_HEADER}\"'")
  endif()
endif()
# relocatable: the prefix relative to the .pc file's own directory
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  set(DH_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
else()
  file(RELATIVE_PATH _dh_rel "/p/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/p")
  string(REGEX REPLACE "/$" "" _dh_rel "${_dh_rel}")
  set(DH_PC_PREFIX "\${pcfiledir}/${_dh_rel}")
endif()
configure_file(${PROJECT_SOURCE_DIR}/cmake/dhmath.pc.in ${PROJECT_BINARY_DIR}/dhmath.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/dhmath.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
