# SPDX-License-Identifier: MIT
# sw_add_fuzz_target(NAME SOURCE src LIBS libs... CORPUS dir [DICT file] [MODELS ext...])
# Every parser has one libFuzzer entry point (LLVMFuzzerTestOneInput). With
# SW_FUZZ=ON (clang) it becomes a libFuzzer binary; in every build it is also
# linked with fuzz_replay_main.c and registered in CTest to replay the seed
# corpus, so the entry point itself is always compiled and exercised.
# DICT: a libFuzzer dictionary (tests/fuzz/dict/, the text formats' words);
# MODELS: the extensions of real model files (../shared/models) that
# run-fuzzers.sh adds to the target's kept corpus. Every target is listed
# in the build's fuzz-targets.txt (name, corpus, dictionary, extensions),
# so run-fuzzers.sh runs each one the build defines.
function(sw_add_fuzz_target name)
  cmake_parse_arguments(F "" "SOURCE;DICT" "LIBS;CORPUS;MODELS" ${ARGN})
  string(REPLACE ";" "," models "${F_MODELS}")
  set(dict "${F_DICT}")
  if(NOT models)
    set(models -)
  endif()
  if(NOT dict)
    set(dict -)
  endif()
  set_property(GLOBAL APPEND PROPERTY SW_FUZZ_TARGET_LINES "${name} ${F_CORPUS} ${dict} ${models}")
  set(replay ${name}_replay)
  add_executable(${replay} ${F_SOURCE} ${PROJECT_SOURCE_DIR}/tests/fuzz/fuzz_replay_main.c)
  target_link_libraries(${replay} PRIVATE ${F_LIBS})
  sw_apply_warnings(${replay})
  add_test(NAME ${replay} COMMAND ${replay} ${F_CORPUS})
  sw_unit_test(${replay} "${F_LIBS}")
  if(SW_FUZZ)
    add_executable(${name} ${F_SOURCE})
    target_compile_options(${name} PRIVATE -fsanitize=fuzzer,address,undefined)
    target_link_options(${name} PRIVATE -fsanitize=fuzzer,address,undefined)
    target_link_libraries(${name} PRIVATE ${F_LIBS})
  endif()
endfunction()

# Written once every tests/*.cmake has added its targets.
function(sw_write_fuzz_targets)
  get_property(lines GLOBAL PROPERTY SW_FUZZ_TARGET_LINES)
  string(REPLACE ";" "\n" text "${lines}")
  file(WRITE ${PROJECT_BINARY_DIR}/fuzz-targets.txt "${text}\n")
endfunction()
cmake_language(DEFER DIRECTORY ${PROJECT_SOURCE_DIR} CALL sw_write_fuzz_targets)
