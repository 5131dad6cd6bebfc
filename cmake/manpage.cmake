# SPDX-License-Identifier: BSD-3-Clause
# P/share/man/man1/restitution.1, made by Debian's help2man from `restitution --help` and `--version`, with the
# --help of every subcommand appended as the section COMMANDS (cmake/manpage_commands.cmake), so that the page
# says what the program says. Without help2man (Debian: help2man, in scripts/setup) no page is made.
if(RESTITUTION_SANITIZE OR RESTITUTION_BUILD_FUZZERS)
  return() # instrumented builds are not installed; help2man would run the instrumented program
endif()
find_program(HELP2MAN help2man)
if(NOT HELP2MAN)
  message(STATUS "help2man not found: no man page (Debian: apt-get install help2man)")
  return()
endif()
set(restitution_man_page ${PROJECT_BINARY_DIR}/restitution.1)
set(restitution_man_commands ${PROJECT_BINARY_DIR}/restitution.h2m)
add_custom_command(
  OUTPUT ${restitution_man_page}
  COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:restitution> -DOUTPUT=${restitution_man_commands}
          -DVERSION=${RESTITUTION_VERSION} -DCOMMIT=${RESTITUTION_COMMIT}
          -P ${PROJECT_SOURCE_DIR}/cmake/manpage_commands.cmake
  # The footer holds the program's name only: a development version does not fit beside the date in 80 columns
  # (the section VERSION names it in full).
  COMMAND ${HELP2MAN} --no-info --no-discard-stderr --section 1 --source "restitution"
          --name "coefficient of restitution of colliding viscoelastic spheres"
          --include ${restitution_man_commands} --output ${restitution_man_page} $<TARGET_FILE:restitution>
  DEPENDS restitution ${PROJECT_SOURCE_DIR}/cmake/manpage_commands.cmake
  COMMENT "help2man: restitution.1"
  VERBATIM)
# Debian's packages carry the page compressed (gzip -9n: no name or time stamp, so the same page gives the same
# bytes); that copy is installed only into the package's component (cmake/package.cmake), a plain install keeps
# the page as it is.
add_custom_command(OUTPUT ${restitution_man_page}.gz
                   COMMAND gzip -9nkf ${restitution_man_page}
                   DEPENDS ${restitution_man_page} VERBATIM)
add_custom_target(restitution_man_page ALL DEPENDS ${restitution_man_page} ${restitution_man_page}.gz)
install(FILES ${restitution_man_page} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT restitution_man)
install(FILES ${restitution_man_page}.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT restitution_program
        EXCLUDE_FROM_ALL)
