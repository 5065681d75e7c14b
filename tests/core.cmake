# SPDX-License-Identifier: MIT
# tests of the core area
sw_add_test(test_math SOURCES test_math.c LIBS sw_core)
sw_add_test(test_error SOURCES test_error.c LIBS sw_core)
sw_add_test(test_bezier SOURCES test_bezier.c LIBS sw_core)
sw_add_test(test_surface_at SOURCES test_surface_at.c LIBS sw_core)
sw_add_test(test_nurbs SOURCES test_nurbs.c LIBS sw_core)
sw_add_test(test_tess SOURCES test_tess.c LIBS sw_core)
sw_add_test(test_normal_cone SOURCES test_normal_cone.c LIBS sw_core)
sw_add_test(test_cull_tree SOURCES test_cull_tree.c LIBS sw_core)
sw_add_test(test_border_strip SOURCES test_border_strip.c LIBS sw_core)
