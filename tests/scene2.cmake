# SPDX-License-Identifier: MIT
# tests of showroom scenes (issue 3): procedural objects and the showroom
# generator. test_scene itself is registered in assets.cmake.
sw_add_test(test_procedural SOURCES test_procedural.c LIBS sw_assets sw_core)

add_test(NAME test_gen
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_gen.sh $<TARGET_FILE:seamwalk-pack> procedural
          $<TARGET_FILE:seamwalk> ${PROJECT_SOURCE_DIR})
add_test(NAME test_gen_parts
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_gen.sh $<TARGET_FILE:seamwalk-pack> parts
          ${SW_SHARED_MODELS})
# A hang guard, not a timing test: under ASan on a loaded 2-core machine
# they took over 300 s (74 s and 104 s in Release there).
set_tests_properties(test_gen test_gen_parts PROPERTIES TIMEOUT 900)
set_tests_properties(test_gen_parts PROPERTIES SKIP_RETURN_CODE 77)
sw_host_only_test(test_gen_parts PROGRAMS seamwalk-pack)
# Under the sanitizers a quarter of the patches (500 to 1,000 parts, a
# 10,000-patch large showroom): the same generator, parts and checks; the
# Release sizes took ASan 87 s (parts) and 325 s (procedural) of CI.
if(SW_ASAN OR SW_TSAN)
  set_tests_properties(test_gen test_gen_parts PROPERTIES ENVIRONMENT SW_GEN_DIVISOR=4)
endif()
