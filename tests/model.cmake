# SPDX-License-Identifier: MIT
# tests of the host model of trimmed NURBS (sw_model) and the trim geometry (sw_trim)
sw_add_test(test_model SOURCES test_model.c LIBS sw_assets sw_core)
sw_add_test(test_trim SOURCES test_trim.c LIBS sw_assets sw_core)
sw_add_test(test_trim_clip SOURCES test_trim_clip.c LIBS sw_assets sw_core)
