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

# pkg-config: ssda.pc beside the CMake package, for builds without CMake
# (cc app.c $(pkg-config --cflags --libs ssda)). Its paths are relative to
# the .pc file (${pcfiledir}), so `cmake --install --prefix DIR` and a moved
# tree work; SSDA_CONFIG's feature switches are in Cflags, as they are in
# ssda::ssda's interface.
file(RELATIVE_PATH SSDA_PC_PREFIX_REL "/ssda-root/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/ssda-root")
string(REGEX REPLACE "/$" "" SSDA_PC_PREFIX_REL "${SSDA_PC_PREFIX_REL}")
foreach(_dir LIBDIR INCLUDEDIR)
  if(IS_ABSOLUTE "${CMAKE_INSTALL_${_dir}}")
    set(SSDA_PC_${_dir} "${CMAKE_INSTALL_${_dir}}")
  else()
    set(SSDA_PC_${_dir} "\${prefix}/${CMAKE_INSTALL_${_dir}}")
  endif()
endforeach()
set(SSDA_PC_CFLAGS "")
foreach(_def IN LISTS SSDA_CONFIG)
  string(APPEND SSDA_PC_CFLAGS " -D${_def}")
endforeach()
# A settings file (SSDA_CONFIG_FILE, lib/CMakeLists.txt) is installed into
# the include directory, where config.h finds it by its name.
if(SSDA_CONFIG_FILE)
  get_filename_component(_cfg_name "${SSDA_CONFIG_FILE}" NAME)
  install(FILES "${SSDA_CONFIG_FILE}" DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  string(APPEND SSDA_PC_CFLAGS " -DSSDA_CONFIG_FILE=${_cfg_name}")
endif()
configure_file(${PROJECT_SOURCE_DIR}/cmake/ssda.pc.in ${PROJECT_BINARY_DIR}/ssda.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/ssda.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
