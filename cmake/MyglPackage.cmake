# Installs the targets so that another project can do find_package(mygl) and link
# mygl::mygl (software backend + loader), mygl::glu (GLU, C API), mygl::glut (GLUT, C API) or
# mygl::reference (OSMesa).
include(CMakePackageConfigHelpers)
install(EXPORT myglTargets NAMESPACE mygl:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/mygl)
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/myglConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/myglConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/mygl)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/myglConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/myglConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/myglConfigVersion.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/mygl)
