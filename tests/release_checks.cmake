# SPDX-License-Identifier: BSD-3-Clause
# What a release promises besides the code (issue 28), included from tests/CMakeLists.txt:
#   citation      CITATION.cff is valid CFF 1.2.0 with this version and the two papers (tests/citation.py);
#   docs_cli      docs/cli.md names every option of every subcommand's --help and no other; docs/README.md
#                 lists every page (tests/docs_cli.py);
#   spdx_headers  every source file carries the SPDX license line (scripts/spdx --check).
# The pip wheel and its test suite against the installed package run in CI (.ci/run: tests/pip_install.sh),
# not here: they build the module a second time in a build folder of their own.
add_test(NAME citation COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/citation.py ${PROJECT_SOURCE_DIR})
add_test(NAME docs_cli
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/docs_cli.py $<TARGET_FILE:restitution> ${PROJECT_SOURCE_DIR})
add_test(NAME spdx_headers COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/scripts/spdx --check ${PROJECT_SOURCE_DIR})
set_tests_properties(docs_cli PROPERTIES LABELS unit)  # each under a second
set_tests_properties(citation spdx_headers PROPERTIES LABELS "unit;source")
