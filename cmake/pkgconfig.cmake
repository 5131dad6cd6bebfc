# SPDX-License-Identifier: BSD-3-Clause
# P/lib/pkgconfig/restitution.pc for builds without CMake: c++ app.cpp $(pkg-config --cflags --libs restitution).
# Libs names librestitution.a (the static library, not the shared one beside it), so what its objects call
# into (SUNDIALS, fmt) goes into Libs, not Libs.private
# (which only `pkg-config --static` reads): a plain `--libs` must link. The flags are read from the targets
# restitution_lib links (src/CMakeLists.txt), so a SUNDIALS from elsewhere (SUNDIALS_DIR) shows up as it is.

# Link flags of one imported target or plain library item, and of what it links in turn, into ${out_var}.
function(restitution_link_flags item out_var)
  set(flags ${${out_var}})
  if(item MATCHES "^\\$<BUILD_INTERFACE:")  # build-only (header-only Boost): nothing to link
    return()
  endif()
  string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" item "${item}")
  if(TARGET ${item})
    get_target_property(type ${item} TYPE)
    get_target_property(imported ${item} IMPORTED)
    if(NOT type STREQUAL "INTERFACE_LIBRARY")
      if(NOT imported)
        # Built by this project (e.g. a SUNDIALS compiled along with it): its file in the build tree, which
        # an installed restitution.pc should not point into; install that library and find it instead.
        message(STATUS "restitution.pc links ${item} from the build tree")
        list(APPEND flags "$<TARGET_LINKER_FILE:${item}>")
        set(${out_var} ${flags} PARENT_SCOPE)
        return()
      endif()
      # The configuration's file: CMAKE_BUILD_TYPE's if the package has it, else the first one it has.
      get_target_property(configs ${item} IMPORTED_CONFIGURATIONS)
      string(TOUPPER "${CMAKE_BUILD_TYPE}" config)
      if(configs AND NOT config IN_LIST configs)
        list(GET configs 0 config)
      endif()
      get_target_property(file ${item} IMPORTED_LOCATION_${config})
      if(NOT file)
        get_target_property(file ${item} IMPORTED_LOCATION)
      endif()
      restitution_library_flag("${file}" flags)
    endif()
    get_target_property(dependencies ${item} INTERFACE_LINK_LIBRARIES)
    foreach(dependency IN LISTS dependencies)
      if(dependency)
        restitution_link_flags("${dependency}" flags)
      endif()
    endforeach()
  elseif(item MATCHES "^-" OR item MATCHES "^/")
    restitution_library_flag("${item}" flags)
  else()
    list(APPEND flags "-l${item}")
  endif()
  set(${out_var} ${flags} PARENT_SCOPE)
endfunction()

# A shared library /dir/libNAME.so[.N] becomes -L/dir (unless the linker searches dir anyway) -lNAME; a static
# archive keeps its full path, so that -lNAME cannot pick a shared library of the same name instead.
function(restitution_library_flag file out_var)
  set(flags ${${out_var}})
  get_filename_component(dir "${file}" DIRECTORY)
  get_filename_component(name "${file}" NAME)
  if(name MATCHES "^lib(.+)\\.so(\\.[0-9.]+)?$")
    if(NOT dir IN_LIST CMAKE_CXX_IMPLICIT_LINK_DIRECTORIES)
      list(APPEND flags "-L${dir}")
    endif()
    list(APPEND flags "-l${CMAKE_MATCH_1}")
  else()
    list(APPEND flags "${file}")
  endif()
  set(${out_var} ${flags} PARENT_SCOPE)
endfunction()

set(restitution_pc_flags)
get_target_property(restitution_lib_links restitution_lib LINK_LIBRARIES)
foreach(link IN LISTS restitution_lib_links)
  restitution_link_flags("${link}" restitution_pc_flags)
endforeach()
list(REMOVE_DUPLICATES restitution_pc_flags)
list(JOIN restitution_pc_flags " " restitution_pc_libs)

file(RELATIVE_PATH restitution_pc_to_prefix /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
string(REGEX REPLACE "/$" "" restitution_pc_to_prefix "${restitution_pc_to_prefix}")  # ../..
configure_file(${PROJECT_SOURCE_DIR}/cmake/restitution.pc.in ${PROJECT_BINARY_DIR}/restitution.pc.configured @ONLY)
file(GENERATE OUTPUT ${PROJECT_BINARY_DIR}/restitution.pc INPUT ${PROJECT_BINARY_DIR}/restitution.pc.configured)
install(FILES ${PROJECT_BINARY_DIR}/restitution.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig
        COMPONENT restitution_dev)
