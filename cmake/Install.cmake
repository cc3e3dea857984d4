# What `cmake --install` puts under the prefix (docs/embedding.md): the voxc command, the CMake
# package (find_package(voxc): voxc::voxc and voxc_add_ruleset), the OpenVDB module both load when
# first needed (<libdir>/voxc/libvoxc-openvdb.so, voxc/vdb/Vdb.h) and, with VOXC_LIBVOXC, libvoxc,
# its header and its pkg-config file.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(VOXC_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/voxc)
install(TARGETS voxc RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS voxc_openvdb_module LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/voxc)

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/voxcConfig.cmake.in
  ${PROJECT_BINARY_DIR}/packaging/voxcConfig.cmake
  INSTALL_DESTINATION ${VOXC_INSTALL_CMAKEDIR}
  PATH_VARS CMAKE_INSTALL_BINDIR CMAKE_INSTALL_LIBDIR CMAKE_INSTALL_INCLUDEDIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/packaging/voxcConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES
  ${PROJECT_BINARY_DIR}/packaging/voxcConfig.cmake
  ${PROJECT_BINARY_DIR}/packaging/voxcConfigVersion.cmake
  ${PROJECT_SOURCE_DIR}/cmake/VoxcRuleset.cmake
  DESTINATION ${VOXC_INSTALL_CMAKEDIR})

if(VOXC_LIBVOXC)
  install(TARGETS voxc_capi LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(FILES ${PROJECT_SOURCE_DIR}/runtime/capi/include/voxc/voxc.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/voxc)
  # The .pc file finds the prefix from where it lies, so an install moved with --prefix works.
  file(RELATIVE_PATH VOXC_PC_PREFIX_FROM_PCFILEDIR /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
  configure_file(${PROJECT_SOURCE_DIR}/cmake/voxc.pc.in ${PROJECT_BINARY_DIR}/packaging/voxc.pc @ONLY)
  install(FILES ${PROJECT_BINARY_DIR}/packaging/voxc.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
endif()
