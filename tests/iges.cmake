# SPDX-License-Identifier: MIT
# tests of the native IGES reader and point inversion / pcurve fitting
sw_add_test(test_import_iges SOURCES test_import_iges.c LIBS sw_assets sw_core
  ARGS ${SW_SHARED_MODELS})
set_tests_properties(test_import_iges PROPERTIES SKIP_RETURN_CODE 77)
sw_add_test(test_pcurve SOURCES test_pcurve.c LIBS sw_assets sw_core)
sw_add_fuzz_target(fuzz_iges SOURCE ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz_iges.c
  LIBS sw_assets sw_core CORPUS ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/iges
  DICT ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/dict/iges.dict
  MODELS igs iges)
