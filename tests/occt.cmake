# SPDX-License-Identifier: MIT
# tests of the OpenCASCADE importer (assets/import/sw_import_occt.cpp), or, in a build
# without OCCT, of its "built without STEP support" fallback.
set(SW_OCCT_SCRATCH ${CMAKE_CURRENT_BINARY_DIR}/occt-scratch)
sw_add_test(test_import_occt SOURCES test_import_occt.c LIBS sw_assets sw_core
  ARGS ${SW_SHARED_MODELS} ${SW_OCCT_SCRATCH})
set_tests_properties(test_import_occt PROPERTIES SKIP_RETURN_CODE 77)

if(SW_OCCT_FOUND)
  # 20 cuts of each shared STEP file, each also re-terminated and parsed by OCCT.
  add_test(NAME test_import_occt_truncations
    COMMAND test_import_occt ${SW_SHARED_MODELS} ${SW_OCCT_SCRATCH}/cuts --truncations)
  # OCCT's never-freed singletons are suppressed, our allocations stay
  # checked (see the file).
  set_tests_properties(test_import_occt test_import_occt_truncations PROPERTIES
    SKIP_RETURN_CODE 77
    ENVIRONMENT "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_SOURCE_DIR}/occt-lsan.supp:print_suppressions=0")
  sw_host_only_test(test_import_occt_truncations PROGRAMS test_import_occt)
endif()

# The importer's geometry repairs (assets/import/sw_occt_pcurve.h,
# sw_occt_convert.h, sw_occt_unroll.h, the plane's in sw_occt_bspline.h), in
# C++ against OCCT: C++ gets its own warnings (sw_apply_warnings' are C's).
if(SW_OCCT_FOUND)
  add_executable(test_occt_geometry test_occt_geometry.cpp)
  target_include_directories(test_occt_geometry PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}
    ${PROJECT_SOURCE_DIR}/assets/import)
  target_include_directories(test_occt_geometry SYSTEM PRIVATE ${OpenCASCADE_INCLUDE_DIR})
  # Under TSan, the uninstrumented libraries, as sw_add_test links them.
  sw_test_libraries(pcurve_libs "sw_assets;sw_core" "")
  target_link_libraries(test_occt_geometry PRIVATE ${pcurve_libs} ${SW_OCCT_LIBRARIES})
  if(SW_TSAN)
    sw_without_tsan(test_occt_geometry)
  endif()
  target_compile_options(test_occt_geometry PRIVATE -Wall -Wextra -Wshadow)
  if(SW_WERROR)
    target_compile_options(test_occt_geometry PRIVATE -Werror)
  endif()
  add_test(NAME test_occt_geometry COMMAND test_occt_geometry)
  set_tests_properties(test_occt_geometry PROPERTIES LABELS unit ENVIRONMENT
    "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_SOURCE_DIR}/occt-lsan.supp:print_suppressions=0")
  sw_host_only_test(test_occt_geometry PROGRAMS test_occt_geometry)
endif()

# A STEP file through the OpenCASCADE importer, in-process (its time and
# memory capped by run-fuzzers.sh). OCCT's singletons never freed: leaks
# are not checked here (occt-lsan.supp covers the tests').
if(SW_OCCT_FOUND)
  sw_add_fuzz_target(fuzz_step_occt SOURCE ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz_step_occt.c
    LIBS sw_assets sw_core CORPUS ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/step_occt
    DICT ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/dict/step.dict MODELS stp step)
  set_tests_properties(fuzz_step_occt_replay PROPERTIES ENVIRONMENT
    "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_SOURCE_DIR}/occt-lsan.supp:print_suppressions=0")
endif()

# Small STEP files carrying the ways real exporters' files went wrong
# (tests/gen_step_cases.py): trim curves micrometres apart, a face no
# tolerance covers, a file with nothing left to draw, a check attached to no
# entity, a solid-angle unit; built, named, verified and walked.
add_test(NAME test_step_cases
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_step_cases.sh $<TARGET_FILE:seamwalk-pack>
          $<TARGET_FILE:seamwalk> ${PROJECT_SOURCE_DIR})
set_tests_properties(test_step_cases PROPERTIES SKIP_RETURN_CODE 77)
if(SW_ASAN OR SW_TSAN)
  # The sanitizers' allocators hold hundreds of MB of their own (quarantine,
  # red zones); the sewing's old search took over 1 GB without them.
  set_tests_properties(test_step_cases PROPERTIES ENVIRONMENT "SW_STEP_CASES_PEAK_MB=1500")
endif()
