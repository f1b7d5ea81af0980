# SPDX-License-Identifier: MIT
# install(EXPORT) + package config so that find_package(sparsedyn) works for consumers.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS sparsedyn EXPORT sparsedynTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY include/sparsedyn DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT sparsedynTargets NAMESPACE sparsedyn::
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/sparsedyn)

configure_package_config_file(cmake/sparsedynConfig.cmake.in
  ${PROJECT_BINARY_DIR}/sparsedynConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/sparsedyn)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/sparsedynConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/sparsedynConfig.cmake
              ${PROJECT_BINARY_DIR}/sparsedynConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/sparsedyn)
if(TARGET sparsedyn_cli)
  install(TARGETS sparsedyn_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
# The web viewer: built into `sparsedyn view`, and installed as its two files too (the page
# opens a .sdrec with its Open... button when served from anywhere).
if(TARGET viewer AND SPARSEDYN_VIEWER_DIST)
  install(FILES ${SPARSEDYN_VIEWER_DIST}/viewer.html ${SPARSEDYN_VIEWER_DIST}/viewer.js
          DESTINATION ${CMAKE_INSTALL_DATADIR}/sparsedyn/viewer)
endif()
install(FILES README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})

include(cmake/SparsedynPackage.cmake)
