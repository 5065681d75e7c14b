# SPDX-License-Identifier: MIT
# tests of the runtime trimmed tessellation (core/sw_trim_tess.c)
sw_add_test(test_trim_tess SOURCES test_trim_tess.c LIBS sw_core)
sw_add_test(test_trim_tess_errors SOURCES test_trim_tess_errors.c LIBS sw_core)
sw_add_test(test_trim_tess_seams SOURCES test_trim_tess_seams.c LIBS sw_core)
sw_add_test(test_trim_cell SOURCES test_trim_cell.c LIBS sw_core)
sw_add_test(test_trim_tess_touching SOURCES test_trim_tess_touching.c LIBS sw_core)
sw_add_test(test_trim_tess_collapse SOURCES test_trim_tess_collapse.c LIBS sw_core)
# A runtime-only build stops here (tests/CMakeLists.txt): the tests below
# need the assets library's IGES reader.
if(NOT SW_BUILD_PACK_TOOL)
  return()
endif()
# The same on every trimmed surface of the shared IGES models (skipped, exit
# 77, when none is present).
sw_add_test(test_trim_tess_models SOURCES test_trim_tess_models.c LIBS sw_assets sw_core
  ARGS ${SW_SHARED_MODELS}/occt_hammer.iges ${SW_SHARED_MODELS}/occt_bearing.iges
       ${SW_SHARED_MODELS}/gpucast_teapot.igs)
set_tests_properties(test_trim_tess_models PROPERTIES SKIP_RETURN_CODE 77)
