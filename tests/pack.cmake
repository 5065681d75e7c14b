# SPDX-License-Identifier: MIT
# tests of the pack area: the reader's fuzz targets replaying their seed
# packs, then the reader (test_pack; test_pack_trim for the optional
# sections) and the writer (test_pack_write).
sw_add_fuzz_target(fuzz_pack SOURCE ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz_pack.c LIBS sw_core
  CORPUS ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/pack)
# The runtime's threaded loader: helper threads check the parts, and the
# answer must be the serial reader's (tests/fuzz/fuzz_pack_load.c).
sw_add_fuzz_target(fuzz_pack_load SOURCE ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz_pack_load.c
  LIBS sw_runtime CORPUS ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/pack)
# A runtime-only build stops here (tests/CMakeLists.txt): the tests below
# need the assets library's pack writer.
if(NOT SW_BUILD_PACK_TOOL)
  return()
endif()
sw_add_test(test_pack SOURCES test_pack.c LIBS sw_assets sw_core)
sw_add_test(test_pack_trim SOURCES test_pack_trim.c LIBS sw_assets sw_core)
sw_add_test(test_pack_write SOURCES test_pack_write.c LIBS sw_assets sw_core)
# Packs of placed parts: merged from packs built apart, placed, expanded
# (checked point by point and read back as an ordinary pack), and one
# refusal per rule of PROTOTYPES and INSTANCES.
sw_add_test(test_pack_instances SOURCES test_pack_instances.c LIBS sw_assets sw_core)
# seamwalk-pack's progress line (a pseudo-terminal stands in for the user's).
sw_add_test(test_progress SOURCES test_progress.c LIBS sw_assets sw_core)
# The up axis: names, the ORIENTATION section, each input's default, the
# scene key (test_up_axis); the command line and the upright orbit
# (test_up_axis.sh: up_axis_cli, and up_axis_orbit on the shared models).
sw_add_test(test_up_axis SOURCES test_up_axis.c LIBS sw_assets sw_core)
foreach(mode cli orbit)
  add_test(NAME up_axis_${mode}
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_up_axis.sh ${mode} ${PROJECT_BINARY_DIR}
            ${PROJECT_SOURCE_DIR} ${SW_SHARED_MODELS})
  set_tests_properties(up_axis_${mode} PROPERTIES SKIP_RETURN_CODE 77)
endforeach()
# The cli mode runs the pack tool alone; the orbit walks with seamwalk.
sw_host_only_test(up_axis_cli PROGRAMS seamwalk-pack)
# The IMPORT_NOTES section: round trip, refusals, reports into records.
sw_add_test(test_pack_notes SOURCES test_pack_notes.c LIBS sw_assets sw_core)
# The static levels in the pack: round trip, one refusal per validation rule
# (each also with the checks' parts run backwards), the info report. Their
# fuzz seed (corpus/pack/seed-levels) is written by test_pack_write
# --write-corpus from the same hand-built levels (pack_sample.h).
sw_add_test(test_pack_levels SOURCES test_pack_levels.c LIBS sw_assets sw_core)
# The super-surfaces in the pack: round trip, one refusal per validation
# rule, the info report; their fuzz seed (corpus/pack/seed-supers) is
# written by test_pack_write --write-corpus (pack_sample.h).
sw_add_test(test_pack_super SOURCES test_pack_super.c LIBS sw_assets sw_core)
sw_add_test(test_pack_part_levels SOURCES test_pack_part_levels.c LIBS sw_assets sw_core)
