# Installation of the data and docs, the CMake package (find_package(hslam))
# and the Debian package (cpack -G DEB). Libraries, apps, plug-in modules and
# headers are installed by the functions in HslamHelpers.cmake.
include(CMakePackageConfigHelpers)

set(HSLAM_INSTALL_DATADIR ${CMAKE_INSTALL_DATADIR}/hslam)
set(HSLAM_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/hslam)

# Data the apps look up at run time in <prefix>/share/hslam, found from the
# executable's location (hslam::common::dataDir()). The build tree mirrors it
# with a link, so build/bin/<app> finds the source tree's files the same way.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/config_ini DESTINATION ${HSLAM_INSTALL_DATADIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/rawlog_samples DESTINATION ${HSLAM_INSTALL_DATADIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
file(MAKE_DIRECTORY ${CMAKE_BINARY_DIR}/share/hslam)
foreach(_data config_ini rawlog_samples)
  if(NOT EXISTS ${CMAKE_BINARY_DIR}/share/hslam/${_data})
    file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${_data} ${CMAKE_BINARY_DIR}/share/hslam/${_data} SYMBOLIC)
  endif()
endforeach()

# CMake package.
install(EXPORT hslamTargets NAMESPACE hslam:: DESTINATION ${HSLAM_INSTALL_CMAKEDIR})
get_property(HSLAM_EXPORTED_TARGETS GLOBAL PROPERTY HSLAM_EXPORTED_TARGETS)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/hslamConfig.cmake.in
  ${CMAKE_BINARY_DIR}/cmake/hslamConfig.cmake
  INSTALL_DESTINATION ${HSLAM_INSTALL_CMAKEDIR}
  PATH_VARS HSLAM_INSTALL_DATADIR)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/cmake/hslamConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/cmake/hslamConfig.cmake ${CMAKE_BINARY_DIR}/cmake/hslamConfigVersion.cmake
        DESTINATION ${HSLAM_INSTALL_CMAKEDIR})

# Debian package: cpack -G DEB -> hslam_<version>_amd64.deb installing to /usr,
# Depends: computed by dpkg-shlibdeps from the installed binaries.
set(CPACK_PACKAGE_NAME hslam)
set(CPACK_PACKAGE_VENDOR "hslam")
set(CPACK_PACKAGE_CONTACT "hslam maintainers <hslam@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Hybrid indoor SLAM plug-ins, libraries and apps for MRPT 2.5")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Our own libraries are in the package: let dpkg-shlibdeps resolve them there.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS ${CMAKE_BINARY_DIR}/lib)
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "mrpt-apps")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "libmrpt-dev, libopencv-dev, libeigen3-dev")
set(CPACK_STRIP_FILES ON)
set(CPACK_GENERATOR DEB)
include(CPack)
