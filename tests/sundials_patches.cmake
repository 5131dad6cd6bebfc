# SPDX-License-Identifier: BSD-3-Clause
# Our patches to CVODE (scripts/sundials-patches/) must change no result: the same program, linked once with
# the patched CVODE (librestitution.a) and once with the unpatched objects that scripts/sundials keeps in
# build/sundials/<version>/unpatched/ ahead of the library (so the library's copies are never pulled in),
# prints a grid of solves to the bit; the test compares the two outputs byte for byte.
if(RESTITUTION_SUNDIALS_UNPATCHED_OBJECTS)
  add_executable(cvode_results_dump cvode_results_dump.cpp)
  add_executable(cvode_results_dump_unpatched cvode_results_dump.cpp ${RESTITUTION_SUNDIALS_UNPATCHED_OBJECTS})
  foreach(program cvode_results_dump cvode_results_dump_unpatched)
    target_link_libraries(${program} PRIVATE restitution_lib)
  endforeach()
  add_test(NAME sundials_patches_keep_results
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/same_output.sh $<TARGET_FILE:cvode_results_dump>
                   $<TARGET_FILE:cvode_results_dump_unpatched>)
  set_tests_properties(sundials_patches_keep_results PROPERTIES LABELS unit TIMEOUT 300)
endif()
