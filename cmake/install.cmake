# Installs the library, its headers, the vri program and the CMake package
# (lib/cmake/vri) so that find_package(vri) consumers build: see
# examples/consumer and tests/package/consumer_test.sh.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(VRI_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/vri CACHE STRING
    "Where vriConfig.cmake is installed, relative to the prefix")

# Two components under the prefix, runtime (bin/vri) and devel (library,
# headers, package), so that an install can leave out the Python module
# (component python, which goes to the interpreter's site-packages).
install(TARGETS vri EXPORT vriTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT devel
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# vri-cli (OUTPUT_NAME vri) becomes bin/vri, exported as vri::vri-cli.
install(TARGETS vri-cli EXPORT vriTargets RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/vri DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT devel)
install(FILES ${PROJECT_BINARY_DIR}/include/vri/version.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/vri
        COMPONENT devel)
install(EXPORT vriTargets NAMESPACE vri:: DESTINATION ${VRI_INSTALL_CMAKEDIR} COMPONENT devel)

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/vriConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/vriConfig.cmake
                              INSTALL_DESTINATION ${VRI_INSTALL_CMAKEDIR})
# 0.x: a minor release may break the API, so only the same minor version is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/vriConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/vriConfig.cmake ${PROJECT_BINARY_DIR}/vriConfigVersion.cmake
        DESTINATION ${VRI_INSTALL_CMAKEDIR} COMPONENT devel)
