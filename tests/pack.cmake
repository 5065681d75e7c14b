# tests of the pack area: the reader (test_pack; test_pack_trim for the optional
# sections), the writer (test_pack_write)
# and the reader's fuzz target with its seed packs.
sw_add_test(test_pack SOURCES test_pack.c LIBS sw_assets sw_core)
sw_add_test(test_pack_trim SOURCES test_pack_trim.c LIBS sw_assets sw_core)
sw_add_test(test_pack_write SOURCES test_pack_write.c LIBS sw_assets sw_core)
sw_add_fuzz_target(fuzz_pack SOURCE ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz_pack.c LIBS sw_core
  CORPUS ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/pack)
# seamwalk-pack's progress line (a pseudo-terminal stands in for the user's).
sw_add_test(test_progress SOURCES test_progress.c LIBS sw_assets sw_core)
