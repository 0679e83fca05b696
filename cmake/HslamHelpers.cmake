# Helpers shared by every hslam target: warnings, one precompiled header,
# and one function per kind of target so library CMakeLists stay three lines.
# Each function also installs what it creates (see docs/install.md):
#   apps -> <prefix>/bin, libraries and plug-in modules -> <prefix>/lib,
#   headers -> <prefix>/include/hslam/<lib>/, exported as hslam::<lib>.
include(GNUInstallDirs)

# Every target is compiled with the same flags (-fPIC included, also for
# executables) so that all of them can reuse the one precompiled header.
function(hslam_set_target_defaults target)
  set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE OFF)
  target_compile_options(${target} PRIVATE -fPIC -Wall -Wextra -Wno-unused-parameter)
  if(TARGET hslam_pch AND NOT "${target}" STREQUAL "hslam_pch")
    target_link_libraries(${target} PRIVATE hslam_pch_deps)
    target_precompile_headers(${target} REUSE_FROM hslam_pch)
  endif()
endfunction()

# One precompiled header with the heavy MRPT headers, compiled once and
# reused by every target (keeps a clean build on 2 cores short).
function(hslam_add_pch_target)
  add_library(hslam_pch_deps INTERFACE)
  target_link_libraries(hslam_pch_deps INTERFACE mrpt::maps mrpt::obs mrpt::poses
                                                 mrpt::config mrpt::io mrpt::system)
  add_library(hslam_pch STATIC ${PROJECT_SOURCE_DIR}/cmake/hslam_pch.cpp)
  target_link_libraries(hslam_pch PUBLIC hslam_pch_deps)
  set_target_properties(hslam_pch PROPERTIES POSITION_INDEPENDENT_CODE OFF)
  target_compile_options(hslam_pch PRIVATE -fPIC -Wall -Wextra -Wno-unused-parameter)
  target_precompile_headers(hslam_pch PRIVATE ${PROJECT_SOURCE_DIR}/cmake/hslam_pch.h)
endfunction()

# Run-time search path of an installed target: the libraries are found in
# <prefix>/lib relative to the binary, so a prefix can be moved (or unpacked
# by dpkg -x) anywhere. The build tree keeps CMake's absolute build RPATH.
function(hslam_set_install_rpath target from_dir)
  file(RELATIVE_PATH _rel "/_p/${from_dir}" "/_p/${CMAKE_INSTALL_LIBDIR}")
  if(_rel STREQUAL "")
    set(_rel ".")
  endif()
  set_target_properties(${target} PROPERTIES INSTALL_RPATH "$ORIGIN/${_rel}")
endfunction()

# hslam_add_library(<name> DEPS <targets...>): libs/<name>/src/*.cpp with
# public headers in libs/<name>/include/hslam/<name>/.
# Shared (libhslam-<name>.so): apps, tests and the plug-in modules loaded by
# MRPT's own tools then share one copy of each class, so MRPT's class and map
# registries hold one CTiledOccupancyGridMap2D / CPioneerSensor per process.
function(hslam_add_library name)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  file(GLOB srcs CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/src/*.cpp)
  add_library(hslam_${name} SHARED ${srcs})
  add_library(hslam::${name} ALIAS hslam_${name})
  set_target_properties(hslam_${name} PROPERTIES
    OUTPUT_NAME hslam-${name} EXPORT_NAME ${name}
    DEFINE_SYMBOL ""  # no -Dhslam_<name>_EXPORTS: same flags as every target (PCH, ccache)
    VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
  target_include_directories(hslam_${name} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(hslam_${name} PUBLIC ${ARG_DEPS})
  hslam_set_target_defaults(hslam_${name})
  hslam_set_install_rpath(hslam_${name} ${CMAKE_INSTALL_LIBDIR})
  install(TARGETS hslam_${name} EXPORT hslamTargets
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/hslam/${name}
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/hslam)
  set_property(GLOBAL APPEND PROPERTY HSLAM_EXPORTED_TARGETS hslam::${name})
endfunction()

# hslam_add_plugin_module(<target> <source> DEPS <targets...>): a module MRPT
# tools load with -p (or LD_PRELOAD), installed next to the libraries.
function(hslam_add_plugin_module target source)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  add_library(${target} MODULE ${source})
  target_link_libraries(${target} PRIVATE ${ARG_DEPS})
  hslam_set_target_defaults(${target})
  hslam_set_install_rpath(${target} ${CMAKE_INSTALL_LIBDIR})
  install(TARGETS ${target} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
endfunction()

# hslam_add_app(<name> DEPS <targets...>): apps/<name>/*.cpp -> bin/<name>,
# installed to <prefix>/bin with a man page (help2man) when help2man exists.
function(hslam_add_app name)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  file(GLOB srcs CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  add_executable(${name} ${srcs})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} hslam_tclap)
  hslam_set_target_defaults(${name})
  hslam_set_install_rpath(${name} ${CMAKE_INSTALL_BINDIR})
  install(TARGETS ${name} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  hslam_add_man_page(${name})
endfunction()

# Man page generated from the app's --help text (Debian help2man).
function(hslam_add_man_page app)
  if(NOT HSLAM_HELP2MAN)
    return()
  endif()
  set(_man ${CMAKE_BINARY_DIR}/man/${app}.1)
  add_custom_command(OUTPUT ${_man}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/man
    # Run by name from PATH: the usage line shows "hslam-x", not the build path.
    COMMAND ${CMAKE_COMMAND} -E env "PATH=$<TARGET_FILE_DIR:${app}>:$ENV{PATH}"
            ${HSLAM_HELP2MAN} --no-info --no-discard-stderr
            --version-string=${PROJECT_VERSION} --name=${app} --output=${_man} ${app}
    DEPENDS ${app}
    COMMENT "help2man ${app}" VERBATIM)
  add_custom_target(${app}-man ALL DEPENDS ${_man})
  install(FILES ${_man} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
endfunction()

# hslam_add_test(<lib> DEPS <targets...>): tests/<lib>/*_unittest.cpp -> one
# GoogleTest program per library, each test registered with CTest.
function(hslam_add_test lib)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  file(GLOB srcs CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*_unittest.cpp)
  set(target test_${lib})
  add_executable(${target} ${srcs})
  target_link_libraries(${target} PRIVATE ${ARG_DEPS} hslam_testing GTest::gtest GTest::gtest_main)
  hslam_set_target_defaults(${target})
  gtest_discover_tests(${target} DISCOVERY_MODE PRE_TEST DISCOVERY_TIMEOUT 120
                       WORKING_DIRECTORY ${CMAKE_BINARY_DIR}
                       PROPERTIES TIMEOUT 300)
endfunction()
