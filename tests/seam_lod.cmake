# SPDX-License-Identifier: MIT
# tests of the Seam Graph's level of detail: the host simplifier (assets) and
# the runtime selection (core), on synthetic graphs (seam_graph_gen.h)
sw_add_test(test_seam_simplify SOURCES test_seam_simplify.c LIBS sw_assets)
sw_add_test(test_seam_reroot SOURCES test_seam_reroot.c LIBS sw_assets)
# sw_alloc_count wraps malloc: the selection test proves it allocates nothing
sw_add_test(test_seam_select SOURCES test_seam_select.c LIBS sw_assets sw_alloc_count)
sw_add_test(test_seam_select_loop SOURCES test_seam_select_loop.c LIBS sw_assets)
# loops the tessellator refused: slits and thin spikes cut out (core/sw_seam_surface.c)
sw_add_test(test_seam_untangle SOURCES test_seam_untangle.c LIBS sw_core)
