# tests of the platform area: headless GLES2 rendering and PNG output
sw_add_test(test_render SOURCES test_render.c LIBS sw_platform sw_core)
# test_png decodes what it wrote with stb_image, compiled in the test itself.
sw_add_test(test_png SOURCES test_png.c LIBS sw_platform sw_core sw_stb)
