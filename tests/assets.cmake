# SPDX-License-Identifier: MIT
# tests of the assets area: host model, importers, scenes, seamwalk-pack
sw_add_test(test_import SOURCES test_import.c LIBS sw_assets sw_core
  ARGS ${SW_SAMPLES} ${SW_SHARED_MODELS})
sw_add_test(test_scene SOURCES test_scene.c LIBS sw_assets sw_core ARGS ${SW_SAMPLES})

sw_add_fuzz_target(fuzz_newell SOURCE ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz_newell.c
  LIBS sw_assets sw_core CORPUS ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/newell
  DICT ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/dict/newell.dict
  MODELS txt)
sw_add_fuzz_target(fuzz_bpt SOURCE ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz_bpt.c
  LIBS sw_assets sw_core CORPUS ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/bpt
  DICT ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/dict/bpt.dict
  MODELS bpt)
# Scenes name model files; the fuzzer's resolve against the bundled samples.
sw_add_fuzz_target(fuzz_scene SOURCE ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz_scene.c
  LIBS sw_assets sw_core CORPUS ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/scene
  DICT ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/dict/scene.dict)
target_compile_definitions(fuzz_scene_replay PRIVATE SW_FUZZ_SCENE_DIR="${SW_SAMPLES}")
if(TARGET fuzz_scene)
  target_compile_definitions(fuzz_scene PRIVATE SW_FUZZ_SCENE_DIR="${SW_SAMPLES}")
endif()
add_test(NAME test_pack_cli
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_pack_cli.sh $<TARGET_FILE:seamwalk-pack>
          ${SW_SAMPLES} ${SW_SHARED_MODELS})
sw_host_only_test(test_pack_cli PROGRAMS seamwalk-pack)
# A scene built whole, on 1 and on 4 threads, in parts (build-part, merge)
# and through the build.ninja `seamwalk-pack ninja` writes: one pack, byte
# for byte (tests/test_build_parts.sh).
add_test(NAME build_parts COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_build_parts.sh
         ${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR})
sw_host_only_test(build_parts PROGRAMS seamwalk-pack)

# The STEP file's quick pass before OpenCASCADE: instances, shells' faces,
# the limits (issue 25: a shell listing one face 200,000 times).
sw_add_test(test_step_scan SOURCES test_step_scan.c LIBS sw_assets sw_core)
sw_add_fuzz_target(fuzz_step_scan SOURCE ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz_step_scan.c
  LIBS sw_assets sw_core CORPUS ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/step_scan
  DICT ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/dict/step.dict
  MODELS stp step)
