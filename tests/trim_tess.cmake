# tests of the runtime trimmed tessellation (core/sw_trim_tess.c)
sw_add_test(test_trim_tess SOURCES test_trim_tess.c LIBS sw_core)
