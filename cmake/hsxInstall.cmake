# Install rules: the library, the public headers (include/hsx), the hsx program, and a CMake package so that
# another project's find_package(hsx) gives hsx::hsx.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS hsx_library EXPORT hsxTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/hsx DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
if(TARGET hsx)
  install(TARGETS hsx RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

set(HSX_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/hsx)
install(EXPORT hsxTargets NAMESPACE hsx:: DESTINATION ${HSX_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/hsxConfig.cmake.in ${PROJECT_BINARY_DIR}/hsxConfig.cmake
                              INSTALL_DESTINATION ${HSX_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/hsxConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/hsxConfig.cmake ${PROJECT_BINARY_DIR}/hsxConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/hsxDependencies.cmake
        DESTINATION ${HSX_CMAKE_DIR})
