# tests of the platform area: headless GLES2 rendering and PNG output
sw_add_test(test_render SOURCES test_render.c LIBS sw_platform sw_core)
# test_png decodes what it wrote with stb_image, compiled in the test itself.
sw_add_test(test_png SOURCES test_png.c LIBS sw_platform sw_core sw_stb)
# Mesa/LLVM allocations that live until exit are not ours; see lsan.supp.
set_tests_properties(test_render PROPERTIES ENVIRONMENT
  "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_SOURCE_DIR}/lsan.supp:print_suppressions=0")
