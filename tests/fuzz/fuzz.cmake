# sw_add_fuzz_target(NAME SOURCE src LIBS libs... CORPUS dir...)
# Every parser has one libFuzzer entry point (LLVMFuzzerTestOneInput). With
# SW_FUZZ=ON (clang) it becomes a libFuzzer binary; in every build it is also
# linked with fuzz_replay_main.c and registered in CTest to replay the seed
# corpus, so the entry point itself is always compiled and exercised.
function(sw_add_fuzz_target name)
  cmake_parse_arguments(F "" "SOURCE" "LIBS;CORPUS" ${ARGN})
  set(replay ${name}_replay)
  add_executable(${replay} ${F_SOURCE} ${PROJECT_SOURCE_DIR}/tests/fuzz/fuzz_replay_main.c)
  target_link_libraries(${replay} PRIVATE ${F_LIBS})
  sw_apply_warnings(${replay})
  add_test(NAME ${replay} COMMAND ${replay} ${F_CORPUS})
  if(SW_FUZZ)
    add_executable(${name} ${F_SOURCE})
    target_compile_options(${name} PRIVATE -fsanitize=fuzzer,address,undefined)
    target_link_options(${name} PRIVATE -fsanitize=fuzzer,address,undefined)
    target_link_libraries(${name} PRIVATE ${F_LIBS})
  endif()
endfunction()
