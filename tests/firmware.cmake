# tests of the firmware area: runtime modules, then the whole program.
sw_add_test(test_arena SOURCES test_arena.c LIBS sw_core)
sw_add_test(test_camera_path SOURCES test_camera_path.c LIBS sw_runtime)
sw_add_test(test_stats SOURCES test_stats.c LIBS sw_runtime)
sw_add_test(test_view SOURCES test_view.c LIBS sw_runtime)
sw_add_test(test_alloc_count SOURCES test_alloc_count.c LIBS sw_alloc_count)
sw_add_fuzz_target(fuzz_camera_path SOURCE ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz_camera_path.c
  LIBS sw_runtime CORPUS ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/camera_path)
