# SPDX-License-Identifier: MIT
# the original Seam Graph: trims flattened within the tolerance and sewn (sw_seam_sew.h)
sw_add_test(test_seam_sew SOURCES test_seam_sew.c LIBS sw_assets sw_core ARGS ${SW_SAMPLES} ${SW_SHARED_MODELS})
sw_add_test(test_seam_flatten SOURCES test_seam_flatten.c LIBS sw_assets sw_core)
# Beyond the intervals: gaps from the file, trims past the domain, T-junctions.
sw_add_test(test_seam_sew_repairs SOURCES test_seam_sew_repairs.c LIBS sw_assets sw_core)
sw_add_test(test_seam_sew_edges SOURCES test_seam_sew_edges.c LIBS sw_assets sw_core)
