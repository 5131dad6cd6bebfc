# SPDX-License-Identifier: BSD-3-Clause
# `cmake --install BUILD --prefix P` installs the library `restitution` as a CMake package:
#   P/LIB/librestitution.a, P/LIB/librestitution.so.X.Y (SONAME), P/include/restitution/*.hpp (umbrella:
#   restitution/restitution.hpp),
#   P/LIB/cmake/restitution/{restitutionConfig,restitutionConfigVersion,restitutionTargets}.cmake,
# where LIB is CMAKE_INSTALL_LIBDIR (GNUInstallDirs: lib, or lib/<multiarch triplet> when configured with
# CMAKE_INSTALL_PREFIX=/usr, as the Debian packages are).
# A consumer needs find_package(restitution 0.4 REQUIRED) and target_link_libraries(app restitution::restitution)
# (static) or restitution::restitution_shared.
# Every rule names its component, which the Debian packages split by (cmake/package.cmake): restitution_program
# (the program, its man page, data and docs), restitution_shlib (the shared library), restitution_dev (headers,
# static library, development link, pkg-config and CMake files) and restitution_python (python/CMakeLists.txt).
# A plain `cmake --install` installs all of them.
include(CMakePackageConfigHelpers)

set(restitution_package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/restitution)
install(TARGETS restitution_lib EXPORT restitutionTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        COMPONENT restitution_dev)
# Beside it the shared library (restitution::restitution_shared): librestitution.so.X.Y.Z, its SONAME link
# librestitution.so.X.Y and the development link librestitution.so (docs/library.md, "ABI").
if(TARGET restitution_shared)  # not in the instrumented builds (src/CMakeLists.txt)
  install(TARGETS restitution_shared EXPORT restitutionTargets LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          COMPONENT restitution_shlib NAMELINK_COMPONENT restitution_dev)
endif()
# The CVODE the archive carries stays private to it: its symbols become local (cmake/hide_sundials.sh), so a
# consumer that links its own SUNDIALS gets its own and restitution keeps the optimized copy.
if(RESTITUTION_SUNDIALS_BUILD STREQUAL "optimized")
  install(CODE "execute_process(COMMAND bash ${PROJECT_SOURCE_DIR}/cmake/hide_sundials.sh
                  \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/$<TARGET_FILE_NAME:restitution_lib>\"
                  ${RESTITUTION_SUNDIALS_OBJECTS} COMMAND_ERROR_IS_FATAL ANY)"
          COMPONENT restitution_dev)
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/restitution DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT restitution_dev)
install(EXPORT restitutionTargets NAMESPACE restitution:: DESTINATION ${restitution_package_dir} COMPONENT restitution_dev)

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/restitutionConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/restitutionConfig.cmake INSTALL_DESTINATION ${restitution_package_dir})
# Before 1.0 a minor version may change the API, so 0.4 accepts 0.4.x only.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/restitutionConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/restitutionConfig.cmake ${PROJECT_BINARY_DIR}/restitutionConfigVersion.cmake
        DESTINATION ${restitution_package_dir} COMPONENT restitution_dev)

# The program, its man page and the pkg-config file.
install(TARGETS restitution RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT restitution_program)
# What the program reads beside itself (src/cli/common/resource_root.hpp): plot scripts, the default scene (with the
# other shipped scenes) and the reference solutions, so that the installed program needs no checkout.
set(restitution_share_dir ${CMAKE_INSTALL_DATADIR}/restitution)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/scripts/plots DESTINATION ${restitution_share_dir}/scripts
        COMPONENT restitution_program FILES_MATCHING PATTERN "*.py" PATTERN "__pycache__" EXCLUDE)
# The shipped [[fit]] scenes read their CSV from within their folder (scenes/data/): a scene reads nothing outside it.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/scenes DESTINATION ${restitution_share_dir} COMPONENT restitution_program
        FILES_MATCHING PATTERN "*.toml" PATTERN "*.csv")
install(FILES ${PROJECT_SOURCE_DIR}/data/reference_solutions.csv DESTINATION ${restitution_share_dir}/data
        COMPONENT restitution_program)
# The fit examples of docs/fit.md.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/fit DESTINATION ${restitution_share_dir}/examples
        COMPONENT restitution_program FILES_MATCHING PATTERN "*.csv")
# The documentation the man page's SEE ALSO names: docs/ with the README, the licence and the changelog, in
# share/doc/restitution (CMAKE_INSTALL_DOCDIR).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT restitution_program)
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/CHANGELOG.md
        DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT restitution_program)
include(${CMAKE_CURRENT_LIST_DIR}/pkgconfig.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/manpage.cmake)
