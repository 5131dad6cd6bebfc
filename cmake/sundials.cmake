# SPDX-License-Identifier: BSD-3-Clause
# Which SUNDIALS the library links (docs/performance.md, "SUNDIALS build"):
#   optimized: CVODE built -O3 from Debian's own source package by scripts/sundials into
#              build/sundials/<debian version>/ (the version of the installed libsundials-dev). Its objects go
#              into librestitution.a itself, so consumers of the installed package need no SUNDIALS at all.
#   system:    Debian's libsundials-dev, compiled without optimization (CVODE 2-3x slower). The fallback
#              when the optimized build is off or could not be made.
# Sets RESTITUTION_SUNDIALS_BUILD ("optimized" | "system"), RESTITUTION_SUNDIALS_VERSION,
# RESTITUTION_SUNDIALS_OBJECTS, RESTITUTION_SUNDIALS_INCLUDE_DIR, RESTITUTION_SUNDIALS_PATCHES and
# RESTITUTION_SUNDIALS_UNPATCHED_OBJECTS (optimized) or
# RESTITUTION_SUNDIALS_TARGETS (system). src/CMakeLists.txt applies them to restitution_lib.
option(RESTITUTION_SUNDIALS_OPTIMIZED "Link CVODE built -O3 from Debian's source package (scripts/sundials)" ON)

set(RESTITUTION_SUNDIALS_BUILD system)
if(RESTITUTION_SUNDIALS_OPTIMIZED)
  execute_process(COMMAND dpkg-query -W -f=\${Version} libsundials-dev OUTPUT_VARIABLE debian_sundials_version
                  RESULT_VARIABLE dpkg_result ERROR_QUIET)
  set(sundials_cache ${PROJECT_SOURCE_DIR}/build/sundials/${debian_sundials_version})
  # Configure only reads the cache: building it means apt-get source (and, without a deb-src entry, writing
  # /etc/apt), which belongs to the set-up (scripts/setup runs scripts/sundials), never to cmake or pip.
  if(dpkg_result EQUAL 0 AND EXISTS ${sundials_cache}/.complete)
    file(GLOB RESTITUTION_SUNDIALS_OBJECTS ${sundials_cache}/objects/*.o)
    # The objects our patches changed, built without them (tests/sundials_patches.cmake).
    file(GLOB RESTITUTION_SUNDIALS_UNPATCHED_OBJECTS ${sundials_cache}/unpatched/*.o)
    set(RESTITUTION_SUNDIALS_INCLUDE_DIR ${sundials_cache}/prefix/include)
    file(STRINGS ${RESTITUTION_SUNDIALS_INCLUDE_DIR}/sundials/sundials_config.h version_line
         REGEX "#define SUNDIALS_VERSION \"")
    string(REGEX REPLACE ".*\"(.*)\".*" "\\1" RESTITUTION_SUNDIALS_VERSION "${version_line}")
    # Line 2 of .complete: the patches of scripts/sundials-patches/ in the build ("none" if none applied).
    file(STRINGS ${sundials_cache}/.complete complete_lines)
    list(LENGTH complete_lines complete_count)
    set(RESTITUTION_SUNDIALS_PATCHES none)
    if(complete_count GREATER 1)
      list(GET complete_lines 1 RESTITUTION_SUNDIALS_PATCHES)
    endif()
    set(RESTITUTION_SUNDIALS_BUILD optimized)
  endif()
endif()

if(RESTITUTION_SUNDIALS_BUILD STREQUAL "system")
  find_package(SUNDIALS REQUIRED)
  set(RESTITUTION_SUNDIALS_VERSION ${SUNDIALS_VERSION})
  set(RESTITUTION_SUNDIALS_TARGETS
      SUNDIALS::cvode_shared SUNDIALS::nvecserial_shared SUNDIALS::sunmatrixdense_shared
      SUNDIALS::sunlinsoldense_shared SUNDIALS::sunnonlinsolfixedpoint_shared)
  message(NOTICE "SUNDIALS: Debian's libsundials ${SUNDIALS_VERSION}, compiled without optimization: CVODE "
                 "solves take 2-3x longer than with the optimized build (build it with bash scripts/sundials, "
                 "which bash scripts/setup runs, then configure again)")
else()
  message(STATUS "SUNDIALS: CVODE ${RESTITUTION_SUNDIALS_VERSION} built -O3 from Debian's source package "
                 "(${sundials_cache}; patches: ${RESTITUTION_SUNDIALS_PATCHES})")
endif()

# The CVODE calls are written against the SUNDIALS 6 API (SUNContext, SUNLinearSolver, ...); 5 lacks them and 7
# changed them (sunrealtype, SUNErrCode), so any other major version is refused here rather than failing to compile.
if(NOT RESTITUTION_SUNDIALS_VERSION MATCHES "^6\\.")
  message(FATAL_ERROR "restitution needs SUNDIALS 6.x (found '${RESTITUTION_SUNDIALS_VERSION}'): "
                      "install SUNDIALS 6 (Debian: libsundials-dev) or point SUNDIALS_DIR at a 6.x installation")
endif()
