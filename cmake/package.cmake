# SPDX-License-Identifier: BSD-3-Clause
# The Debian packages: `cpack --config BUILD/CPackConfig.cmake -G DEB` packs the components of cmake/install.cmake
# into one package each, under /usr:
#   restitution              the program, its man page, share/restitution and the docs (restitution_program)
#   librestitutionX.Y        the shared library, named after its SONAME librestitution.so.X.Y (restitution_shlib)
#   librestitution-dev       headers, static library, development link, restitution.pc, CMake package
#   python3-restitution      the Python module, if built (restitution_python)
# Debian's layout (libraries in lib/<multiarch triplet>, the module in lib/python3/dist-packages) comes from
# configuring with CMAKE_INSTALL_PREFIX=/usr, which tests/deb_package.sh does in a folder of its own; a build
# configured for another prefix packs lib/ instead and is refused there. Dependencies on shared libraries are read
# from the binaries by dpkg-shlibdeps (Debian: dpkg-dev). tests/deb_package.sh builds the packages, runs lintian.
set(CPACK_GENERATOR DEB)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_PACKAGE_NAME restitution)
set(CPACK_PACKAGE_VENDOR "The restitution developers")
# A placeholder address (GitHub's no-reply domain): Debian requires one in Maintainer.
set(RESTITUTION_DEB_MAINTAINER "restitution developers <restitution@users.noreply.github.com>")
set(CPACK_PACKAGE_CONTACT "${RESTITUTION_DEB_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${RESTITUTION_DEB_MAINTAINER}")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
# Debian orders "~" before anything, so a development version sorts below its release: 0.4.0~dev253+g... < 0.4.0.
# The revision -1 marks the packaging as Debian's (not a native package), whose changelog is changelog.Debian.gz.
string(REPLACE ".dev" "~dev" CPACK_DEBIAN_PACKAGE_VERSION "${RESTITUTION_VERSION}")
set(CPACK_DEBIAN_PACKAGE_RELEASE 1)
set(CPACK_PACKAGE_VERSION ${CPACK_DEBIAN_PACKAGE_VERSION})
set(restitution_deb_full_version "${CPACK_DEBIAN_PACKAGE_VERSION}-${CPACK_DEBIAN_PACKAGE_RELEASE}")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)  # the shlibs file of the shared library's package
set(CPACK_STRIP_FILES ON)
set(RESTITUTION_DEB_SOVERSION "${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR}")  # SONAME librestitution.so.X.Y

set(CPACK_COMPONENTS_ALL restitution_program restitution_shlib restitution_dev)
set(restitution_deb_packages restitution librestitution${RESTITUTION_DEB_SOVERSION} librestitution-dev)
if(TARGET _restitution)
  list(APPEND CPACK_COMPONENTS_ALL restitution_python)
  list(APPEND restitution_deb_packages python3-restitution)
endif()

# The SUNDIALS the binaries carry, if it is the optimized CVODE (cmake/sundials.cmake): its copyright paragraph and
# the reason for the copy. The CPack summary stays unset: each description's first line is its synopsis.
set(RESTITUTION_DEB_SUNDIALS_PARAGRAPH "")
set(RESTITUTION_DEB_SUNDIALS_NOTE "")
set(restitution_deb_cvode "")
if(RESTITUTION_SUNDIALS_BUILD STREQUAL "optimized")
  set(RESTITUTION_DEB_SUNDIALS_SOURCE_VERSION ${debian_sundials_version})
  set(restitution_debian_dir ${PROJECT_SOURCE_DIR}/cmake/debian)
  configure_file(${restitution_debian_dir}/sundials-paragraph.in ${PROJECT_BINARY_DIR}/debian/sundials-paragraph @ONLY)
  configure_file(${restitution_debian_dir}/sundials-note.in ${PROJECT_BINARY_DIR}/debian/sundials-note @ONLY)
  file(READ ${PROJECT_BINARY_DIR}/debian/sundials-paragraph RESTITUTION_DEB_SUNDIALS_PARAGRAPH)
  file(READ ${PROJECT_BINARY_DIR}/debian/sundials-note RESTITUTION_DEB_SUNDIALS_NOTE)
  set(restitution_deb_cvode
      " It carries an optimized static build of CVODE ${RESTITUTION_SUNDIALS_VERSION} from Debian's own sundials source package (2-3x faster solves than Debian's unoptimized libsundials); README.Debian says why.")
endif()
# ${out_var}: the synopsis, then the text in lines of at most 79 characters (CPack leaves lines as they are, and
# Debian's tools want an extended description in lines of at most 80).
function(restitution_deb_description out_var synopsis text)
  string(ASCII 31 unit_separator)  # a ";" of the text stays a character, not a list separator
  string(REPLACE ";" "${unit_separator}" text "${text}")
  string(REGEX REPLACE "[ \n]+" ";" words "${text}")
  set(result "${synopsis}")
  set(line "")
  foreach(word IN LISTS words)
    string(LENGTH "${line} ${word}" length)
    if(line AND length GREATER 79)
      string(APPEND result "\n${line}")
      set(line "${word}")
    elseif(line)
      string(APPEND line " ${word}")
    else()
      set(line "${word}")
    endif()
  endforeach()
  string(REPLACE "${unit_separator}" ";" result "${result}\n${line}")
  set(${out_var} "${result}" PARENT_SCOPE)
endfunction()
set(restitution_deb_about "The coefficient of normal restitution of colliding viscoelastic spheres, certified to a requested accuracy.")
set(CPACK_DEBIAN_RESTITUTION_PROGRAM_PACKAGE_NAME restitution)
set(CPACK_DEBIAN_RESTITUTION_PROGRAM_PACKAGE_SECTION science)
restitution_deb_description(CPACK_DEBIAN_RESTITUTION_PROGRAM_DESCRIPTION "coefficient of restitution of colliding viscoelastic spheres"
                            "${restitution_deb_about} This package holds the program restitution with its man page, scenes, plot scripts and reference data.${restitution_deb_cvode}")
# Its plots run Python with matplotlib and numpy (share/restitution/scripts/plots).
set(CPACK_DEBIAN_RESTITUTION_PROGRAM_PACKAGE_RECOMMENDS "python3, python3-matplotlib, python3-numpy")
set(CPACK_DEBIAN_RESTITUTION_SHLIB_PACKAGE_NAME librestitution${RESTITUTION_DEB_SOVERSION})
set(CPACK_DEBIAN_RESTITUTION_SHLIB_PACKAGE_SECTION libs)
restitution_deb_description(CPACK_DEBIAN_RESTITUTION_SHLIB_DESCRIPTION "coefficient of restitution library (shared)"
                            "${restitution_deb_about} This package holds the shared library librestitution.so.${RESTITUTION_DEB_SOVERSION}.${restitution_deb_cvode}")
set(CPACK_DEBIAN_RESTITUTION_DEV_PACKAGE_NAME librestitution-dev)
set(CPACK_DEBIAN_RESTITUTION_DEV_PACKAGE_SECTION libdevel)
# The development link points to the shared library; restitution.pc links fmt (and SUNDIALS when it is the system's).
set(restitution_deb_dev_depends "librestitution${RESTITUTION_DEB_SOVERSION} (= ${restitution_deb_full_version}), libfmt-dev")
if(RESTITUTION_SUNDIALS_BUILD STREQUAL "system")
  string(APPEND restitution_deb_dev_depends ", libsundials-dev")
endif()
set(CPACK_DEBIAN_RESTITUTION_DEV_PACKAGE_DEPENDS "${restitution_deb_dev_depends}")
set(CPACK_DEBIAN_RESTITUTION_DEV_PACKAGE_RECOMMENDS pkg-config)
restitution_deb_description(CPACK_DEBIAN_RESTITUTION_DEV_DESCRIPTION "coefficient of restitution library (development files)"
                            "${restitution_deb_about} This package holds the C++ headers, the static library, the pkg-config file and the CMake package (find_package(restitution)).${restitution_deb_cvode}")
set(CPACK_DEBIAN_RESTITUTION_PYTHON_PACKAGE_NAME python3-restitution)
set(CPACK_DEBIAN_RESTITUTION_PYTHON_PACKAGE_SECTION python)
set(CPACK_DEBIAN_RESTITUTION_PYTHON_PACKAGE_DEPENDS "python3, python3-numpy")
set(CPACK_DEBIAN_RESTITUTION_PYTHON_PACKAGE_RECOMMENDS python3-matplotlib)
restitution_deb_description(CPACK_DEBIAN_RESTITUTION_PYTHON_DESCRIPTION "coefficient of restitution (Python 3 module)"
                            "${restitution_deb_about} This package holds the Python 3 module restitution.${restitution_deb_cvode}")

# What Debian wants in each package's /usr/share/doc/<package>: the copyright in the machine-readable format
# (the licence text from LICENSE), the changelog (one entry: the commit packed; CHANGELOG.md says what changed)
# and README.Debian. Only the packages install them (EXCLUDE_FROM_ALL): a plain `cmake --install` does not.
file(STRINGS ${PROJECT_SOURCE_DIR}/LICENSE license_lines)
set(RESTITUTION_DEB_LICENSE_TEXT "")
set(in_text OFF)
foreach(line IN LISTS license_lines)
  if(line MATCHES "^Redistribution")
    set(in_text ON)
  endif()
  if(in_text)
    if(line STREQUAL "")
      set(line ".")
    endif()
    string(APPEND RESTITUTION_DEB_LICENSE_TEXT " ${line}\n")
  endif()
endforeach()
string(REGEX REPLACE "\n$" "" RESTITUTION_DEB_LICENSE_TEXT "${RESTITUTION_DEB_LICENSE_TEXT}")
set(restitution_deb_dir ${PROJECT_BINARY_DIR}/debian)
configure_file(${PROJECT_SOURCE_DIR}/cmake/debian/copyright.in ${restitution_deb_dir}/copyright @ONLY)
configure_file(${PROJECT_SOURCE_DIR}/cmake/debian/README.Debian.in ${restitution_deb_dir}/README.Debian @ONLY)
# The entry's date is the commit's, so that the same commit packs the same changelog.
execute_process(COMMAND git -C ${PROJECT_SOURCE_DIR} log -1 --format=%ct OUTPUT_VARIABLE commit_time
                OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE git_result ERROR_QUIET)
if(NOT git_result EQUAL 0 OR commit_time STREQUAL "")
  string(TIMESTAMP commit_time "%s" UTC)  # a tree without git: the time of configuring
endif()
execute_process(COMMAND date -u -R -d @${commit_time} OUTPUT_VARIABLE changelog_date OUTPUT_STRIP_TRAILING_WHITESPACE
                COMMAND_ERROR_IS_FATAL ANY)
file(WRITE ${restitution_deb_dir}/changelog.Debian
     "restitution (${restitution_deb_full_version}) unstable; urgency=medium\n\n"
     "  * Packed with CPack from commit ${RESTITUTION_COMMIT}.\n"
     "    /usr/share/doc/restitution/CHANGELOG.md lists the changes.\n\n"
     " -- ${RESTITUTION_DEB_MAINTAINER}  ${changelog_date}\n")
execute_process(COMMAND gzip -9nf ${restitution_deb_dir}/changelog.Debian COMMAND_ERROR_IS_FATAL ANY)
foreach(component package IN ZIP_LISTS CPACK_COMPONENTS_ALL restitution_deb_packages)
  install(FILES ${restitution_deb_dir}/copyright ${restitution_deb_dir}/changelog.Debian.gz
                ${restitution_deb_dir}/README.Debian
          DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/${package} COMPONENT ${component} EXCLUDE_FROM_ALL)
  # lintian expects the changelog of a first upload to Debian to close its ITP bug; these packages are not
  # uploaded to Debian, so there is none.
  file(WRITE ${restitution_deb_dir}/overrides/${package}
       "# Built by the project itself, not uploaded to Debian: there is no ITP bug for the changelog to close.\n"
       "${package}: initial-upload-closes-no-bugs\n")
  install(FILES ${restitution_deb_dir}/overrides/${package} DESTINATION ${CMAKE_INSTALL_DATADIR}/lintian/overrides
          COMPONENT ${component} EXCLUDE_FROM_ALL)
endforeach()
# Debian names the upstream changelog changelog.gz; CHANGELOG.md stays beside it for the man page's SEE ALSO.
add_custom_command(OUTPUT ${restitution_deb_dir}/changelog.gz
                   COMMAND sh -c "gzip -9n < \"$1\" > \"$2\"" sh ${PROJECT_SOURCE_DIR}/CHANGELOG.md
                           ${restitution_deb_dir}/changelog.gz
                   DEPENDS ${PROJECT_SOURCE_DIR}/CHANGELOG.md VERBATIM)
add_custom_target(restitution_deb_changelog ALL DEPENDS ${restitution_deb_dir}/changelog.gz)
install(FILES ${restitution_deb_dir}/changelog.gz DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT restitution_program
        EXCLUDE_FROM_ALL)
set(CPACK_POST_BUILD_SCRIPTS ${PROJECT_SOURCE_DIR}/cmake/debian/ldconfig_trigger.cmake)
include(CPack)
