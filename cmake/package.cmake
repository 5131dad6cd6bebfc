# SPDX-License-Identifier: BSD-3-Clause
# The Debian package: `cpack --config BUILD/CPackConfig.cmake -G DEB` packs what `cmake --install` installs
# (cmake/install.cmake: the program, its man page, the static and the shared library, the headers, restitution.pc,
# the CMake package, share/restitution and the docs in share/doc/restitution) under /usr. Its dependencies are
# read from the binaries by dpkg-shlibdeps (Debian: dpkg-dev). tests/deb_package.sh builds and checks it.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME restitution)
set(CPACK_PACKAGE_VENDOR "The restitution developers")
set(CPACK_PACKAGE_CONTACT "The restitution developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "coefficient of restitution of colliding viscoelastic spheres")
set(CPACK_PACKAGE_DESCRIPTION
    "The coefficient of normal restitution of colliding viscoelastic spheres, certified to a requested accuracy:\n"
    "the program restitution, the C++ library (static and shared), scenes, and inputs for DEM codes.")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
# Debian orders "~" before anything, so a development version sorts below its release: 0.4.0~dev253+g... < 0.4.0.
string(REPLACE ".dev" "~dev" CPACK_DEBIAN_PACKAGE_VERSION "${RESTITUTION_VERSION}")
set(CPACK_PACKAGE_VERSION ${CPACK_DEBIAN_PACKAGE_VERSION})
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# The plots the program makes run Python with matplotlib, the Python module needs numpy; pkg-config and fmt's
# headers serve consumers of the static library.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3, python3-matplotlib, python3-numpy, pkg-config, libfmt-dev")
include(CPack)
