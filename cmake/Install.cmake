# `cmake --install` puts the shared library, the public headers, the CLI and a CMake package so that
# a downstream project can `find_package(fairsurf)` and link `fairsurf::fairsurf`.
include(CMakePackageConfigHelpers)
install(TARGETS fairsurf EXPORT fairsurfTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS fairsurf_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY include/fairsurf DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT fairsurfTargets NAMESPACE fairsurf::
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/fairsurf)
configure_package_config_file(cmake/fairsurfConfig.cmake.in
  ${CMAKE_BINARY_DIR}/fairsurfConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/fairsurf)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/fairsurfConfigVersion.cmake
  COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_BINARY_DIR}/fairsurfConfig.cmake ${CMAKE_BINARY_DIR}/fairsurfConfigVersion.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/fairsurf)
