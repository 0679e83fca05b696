# Helpers shared by every hslam target: warnings, one precompiled header,
# and one function per kind of target so library CMakeLists stay three lines.

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

# hslam_add_library(<name> DEPS <targets...>): libs/<name>/src/*.cpp with
# public headers in libs/<name>/include/hslam/<name>/.
function(hslam_add_library name)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  file(GLOB srcs CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/src/*.cpp)
  add_library(hslam_${name} STATIC ${srcs})
  add_library(hslam::${name} ALIAS hslam_${name})
  target_include_directories(hslam_${name} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include)
  target_link_libraries(hslam_${name} PUBLIC ${ARG_DEPS})
  hslam_set_target_defaults(hslam_${name})
endfunction()

# hslam_add_app(<name> DEPS <targets...>): apps/<name>/*.cpp -> bin/<name>.
function(hslam_add_app name)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  file(GLOB srcs CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  add_executable(${name} ${srcs})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} hslam_tclap)
  hslam_set_target_defaults(${name})
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
