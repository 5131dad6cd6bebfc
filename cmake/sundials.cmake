# SPDX-License-Identifier: BSD-3-Clause
# Which SUNDIALS the library links (docs/performance.md, "SUNDIALS build"):
#   optimized: CVODE built -O3 from Debian's own source package by scripts/sundials-build, in this order from
#              build/sundials/<debian version>/ (a checkout's set-up, scripts/sundials; the version of the
#              installed libsundials-dev) or from third_party/sundials (what an sdist carries of that source,
#              built into the build folder at configure time). Its objects go into librestitution.a itself, so
#              consumers of the installed package need no SUNDIALS at all.
#   system:    Debian's libsundials-dev, compiled without optimization (CVODE 2-3x slower). The fallback
#              when the optimized build is off or could not be made.
# Sets RESTITUTION_SUNDIALS_BUILD ("optimized" | "system"), RESTITUTION_SUNDIALS_VERSION, RESTITUTION_SUNDIALS_SOURCE
# (where the CVODE came from, which restitution --version and build_info() name),
# RESTITUTION_SUNDIALS_OBJECTS, RESTITUTION_SUNDIALS_INCLUDE_DIR, RESTITUTION_SUNDIALS_PATCHES and
# RESTITUTION_SUNDIALS_UNPATCHED_OBJECTS (optimized) or
# RESTITUTION_SUNDIALS_TARGETS (system). src/CMakeLists.txt applies them to restitution_lib.
option(RESTITUTION_SUNDIALS_OPTIMIZED "Link CVODE built -O3 from Debian's source package (scripts/sundials)" ON)

# Reads a cache that scripts/sundials-build completed.
macro(restitution_use_sundials_cache cache)
  file(GLOB RESTITUTION_SUNDIALS_OBJECTS ${cache}/objects/*.o)
  # The objects our patches changed, built without them (tests/sundials_patches.cmake).
  file(GLOB RESTITUTION_SUNDIALS_UNPATCHED_OBJECTS ${cache}/unpatched/*.o)
  set(RESTITUTION_SUNDIALS_INCLUDE_DIR ${cache}/prefix/include)
  file(STRINGS ${RESTITUTION_SUNDIALS_INCLUDE_DIR}/sundials/sundials_config.h version_line
       REGEX "#define SUNDIALS_VERSION \"")
  string(REGEX REPLACE ".*\"(.*)\".*" "\\1" RESTITUTION_SUNDIALS_VERSION "${version_line}")
  # Line 2 of .complete: the patches of scripts/sundials-patches/ in the build ("none" if none applied).
  file(STRINGS ${cache}/.complete complete_lines)
  list(LENGTH complete_lines complete_count)
  set(RESTITUTION_SUNDIALS_PATCHES none)
  if(complete_count GREATER 1)
    list(GET complete_lines 1 RESTITUTION_SUNDIALS_PATCHES)
  endif()
  set(RESTITUTION_SUNDIALS_BUILD optimized)
  set(sundials_cache ${cache})
endmacro()

set(RESTITUTION_SUNDIALS_BUILD system)
set(bundle ${PROJECT_SOURCE_DIR}/third_party/sundials)
if(RESTITUTION_SUNDIALS_OPTIMIZED)
  execute_process(COMMAND dpkg-query -W -f=\${Version} libsundials-dev OUTPUT_VARIABLE debian_sundials_version
                  RESULT_VARIABLE dpkg_result ERROR_QUIET)
  # 1. A checkout: configure only reads the cache that scripts/sundials built. Building it means apt-get source
  # (and, without a deb-src entry, writing /etc/apt), which belongs to the set-up (scripts/setup runs
  # scripts/sundials), never to cmake or pip.
  if(dpkg_result EQUAL 0 AND EXISTS ${PROJECT_SOURCE_DIR}/build/sundials/${debian_sundials_version}/.complete)
    restitution_use_sundials_cache(${PROJECT_SOURCE_DIR}/build/sundials/${debian_sundials_version})
    set(RESTITUTION_SUNDIALS_SOURCE "Debian's source package sundials ${debian_sundials_version}")
  # 2. An sdist: it carries that source (third_party/sundials, setup.py), built here once per build folder by the
  # same script (no network, no apt: about 20 s).
  elseif(EXISTS ${bundle}/DEBIAN_VERSION)
    file(STRINGS ${bundle}/DEBIAN_VERSION bundled_version LIMIT_COUNT 1)
    set(cache ${PROJECT_BINARY_DIR}/sundials/${bundled_version})
    if(NOT EXISTS ${cache}/.complete)
      message(STATUS "SUNDIALS: building the sdist's CVODE (Debian's source package sundials ${bundled_version}) "
                     "optimized into ${cache}")
    endif()
    execute_process(COMMAND bash ${PROJECT_SOURCE_DIR}/scripts/sundials-build ${bundle} ${cache}
                    RESULT_VARIABLE bundle_result ERROR_VARIABLE bundle_error)
    string(STRIP "${bundle_error}" bundle_error)
    if(bundle_result EQUAL 0)
      if(bundle_error)  # e.g. a patch that did not apply: same results, slower
        message(STATUS "SUNDIALS: ${bundle_error}")
      endif()
      restitution_use_sundials_cache(${cache})
      set(RESTITUTION_SUNDIALS_SOURCE "Debian's source package sundials ${bundled_version}, bundled in the sdist")
    else()
      string(REGEX REPLACE ".*\n" "" bundle_error "${bundle_error}")  # the last line says why it stopped
      set(why " (building the sdist's CVODE failed: ${bundle_error})")
    endif()
  else()
    set(why " (no optimized CVODE: in a checkout bash scripts/sundials builds it, which bash scripts/setup runs; "
            "then configure again)")
  endif()
else()
  set(why " (-DRESTITUTION_SUNDIALS_OPTIMIZED=OFF)")
endif()

if(RESTITUTION_SUNDIALS_BUILD STREQUAL "system")
  find_package(SUNDIALS REQUIRED)
  set(RESTITUTION_SUNDIALS_VERSION ${SUNDIALS_VERSION})
  set(RESTITUTION_SUNDIALS_TARGETS
      SUNDIALS::cvode_shared SUNDIALS::nvecserial_shared SUNDIALS::sunmatrixdense_shared
      SUNDIALS::sunlinsoldense_shared SUNDIALS::sunnonlinsolfixedpoint_shared)
  set(RESTITUTION_SUNDIALS_SOURCE "Debian's libsundials")
  # The one line that says it (the module does not warn at import; restitution.build_info() tells).
  message(NOTICE "SUNDIALS: Debian's libsundials ${SUNDIALS_VERSION}, compiled without optimization: CVODE "
                 "solves take 2-3x longer than with the optimized build${why}")
else()
  message(STATUS "SUNDIALS: CVODE ${RESTITUTION_SUNDIALS_VERSION} built -O3 from ${RESTITUTION_SUNDIALS_SOURCE} "
                 "(${sundials_cache}; patches: ${RESTITUTION_SUNDIALS_PATCHES})")
endif()

# The CVODE calls are written against the SUNDIALS 6 API (SUNContext, SUNLinearSolver, ...); 5 lacks them and 7
# changed them (sunrealtype, SUNErrCode), so any other major version is refused here rather than failing to compile.
if(NOT RESTITUTION_SUNDIALS_VERSION MATCHES "^6\\.")
  message(FATAL_ERROR "restitution needs SUNDIALS 6.x (found '${RESTITUTION_SUNDIALS_VERSION}'): "
                      "install SUNDIALS 6 (Debian: libsundials-dev) or point SUNDIALS_DIR at a 6.x installation")
endif()
