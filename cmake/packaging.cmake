# Installation and packaging: `cmake --install build [--prefix P] [--component C]` and `cpack`.
# Components: dev (libacd, headers, CMake package), commands (acd and the application programs),
# python (the `acd` module, see python/CMakeLists.txt).
include(CMakePackageConfigHelpers)

foreach(command acd_cli pointloc planner tetmesh skeleton)
  if(TARGET ${command})
    install(TARGETS ${command} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT commands)
  endif()
endforeach()

set(ACD_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/acd)
install(EXPORT acdTargets NAMESPACE acd:: DESTINATION ${ACD_CMAKE_DIR} COMPONENT dev)
configure_package_config_file(cmake/acdConfig.cmake.in ${PROJECT_BINARY_DIR}/acdConfig.cmake
                              INSTALL_DESTINATION ${ACD_CMAKE_DIR})
# 0.x: a minor version may change the API.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/acdConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/acdConfig.cmake ${PROJECT_BINARY_DIR}/acdConfigVersion.cmake
        DESTINATION ${ACD_CMAKE_DIR} COMPONENT dev)

# One .deb with everything (cpack -G DEB in build/); run-time libraries found by dpkg-shlibdeps.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME acd)
set(CPACK_PACKAGE_VENDOR "acd")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "approximate convex decomposition of polyhedra (Lien & Amato, SPM 2007)")
set(CPACK_PACKAGE_DESCRIPTION "The acd command, the applications pointloc, planner, tetmesh and skeleton,
the static library libacd with its headers and CMake package (find_package(acd)),
and the Python module acd for Debian's python3.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "acd maintainers <acd@localhost>")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_COMPRESSION_TYPE gzip)
# What find_package(acd) needs on the consumer's side (libacd is static).
set(ACD_DEB_DEPENDS "libcgal-dev, libeigen3-dev, libtbb-dev, libgmp-dev, libmpfr-dev, libtinyxml2-dev, libtinygltf-dev, libassimp-dev")
if(ACD_BUILD_PYTHON)
  string(APPEND ACD_DEB_DEPENDS ", python3 (>= ${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}), "
         "python3 (<< ${Python_VERSION_MAJOR}.${ACD_PYTHON_NEXT_MINOR}), python3-numpy")
endif()
set(CPACK_DEBIAN_PACKAGE_DEPENDS "${ACD_DEB_DEPENDS}")
include(CPack)
