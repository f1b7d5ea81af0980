# SPDX-License-Identifier: MIT
# CPack: `cpack -G "DEB;TGZ"` in a build tree (or `cmake --build <tree> --target package`)
# makes sparsedyn_<version>_<arch>.deb and sparsedyn-<version>-Linux.tar.gz from what
# SparsedynInstall.cmake installs: the static library, the headers, the CMake package files
# (find_package(sparsedyn)), the `sparsedyn` tool with the viewer built in, and the viewer's
# files. scripts/package.sh builds them from an optimized tree; CI unpacks the .deb with
# dpkg -x and builds tests/consumer/ against it.
set(CPACK_PACKAGE_NAME sparsedyn)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_VENDOR "the sparsedyn project")
set(CPACK_PACKAGE_CONTACT "the sparsedyn project <sparsedyn@users.noreply.invalid>")
set(CPACK_RESOURCE_FILE_README ${PROJECT_SOURCE_DIR}/README.md)
set(CPACK_GENERATOR "DEB;TGZ")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_SOURCE_GENERATOR "")

set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# The tool's run-time libraries by dpkg-shlibdeps; the headers and the CMake files need Eigen
# and Qhull's development packages (find_dependency in sparsedynConfig.cmake). Boost.Math
# (libboost-dev) is header-only and used only inside the library's sources, so the package
# needs it only to build, not to use (scripts/deps.sh installs it).
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libeigen3-dev (>= 3.4), libqhull-dev")
include(CPack)
