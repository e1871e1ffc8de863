# Install rules and the CMake package, so that find_package(ssda) gives ssda::ssda.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS ssda EXPORT ssdaTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/ssda
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT ssdaTargets NAMESPACE ssda::
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/ssda)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/ssdaConfig.cmake.in
        ${PROJECT_BINARY_DIR}/ssdaConfig.cmake
        INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/ssda)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/ssdaConfigVersion.cmake
        COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/ssdaConfig.cmake
              ${PROJECT_BINARY_DIR}/ssdaConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/ssda)
