# SPDX-License-Identifier: MIT
# The Seam Graph in the pack: writer round trip, one refusal per validation
# rule, the info report (test_pack_seam); seamwalk-pack info on the fuzz seed
# that holds a graph (test_pack_seam_info). The seed itself is replayed by
# fuzz_pack_replay with the rest of tests/fuzz/corpus/pack; test_pack_write
# --write-corpus regenerates it.
sw_add_test(test_pack_seam SOURCES test_pack_seam.c LIBS sw_assets sw_core)
add_test(NAME test_pack_seam_info
  COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/test_pack_seam_info.sh $<TARGET_FILE:seamwalk-pack>
          ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/pack/seed-seam-graph)
# seamwalk-pack verify's proof that every surface tessellates at every seam
# state (a bow-tie trim fails it).
sw_add_test(test_pack_verify_tess SOURCES test_pack_verify_tess.c LIBS sw_assets sw_core)
# The static levels: made from a pack, checked by what they must be.
sw_add_test(test_levels_build SOURCES test_levels_build.c LIBS sw_assets sw_core)
sw_add_test(test_part_rim SOURCES test_part_rim.c
  LIBS sw_assets sw_core meshoptimizer::meshoptimizer)
# The distance from points to a mesh, which measures the part levels.
sw_add_test(test_mesh_distance SOURCES test_mesh_distance.c LIBS sw_assets sw_core)
# ... and on the teaset sample as the pack tool builds it.
add_test(NAME levels_teaset COMMAND bash -c
  "$<TARGET_FILE:seamwalk-pack> build ${PROJECT_SOURCE_DIR}/assets/samples/teaset.ini -o ${CMAKE_CURRENT_BINARY_DIR}/levels_teaset.swpack --quiet && $<TARGET_FILE:test_levels_build> ${CMAKE_CURRENT_BINARY_DIR}/levels_teaset.swpack")
# Super-surfaces: clustering on hand-built surfaces, and on the teaset as
# the pack tool builds it (every sampled normal inside its cluster's cone).
sw_add_test(test_cluster SOURCES test_cluster.c LIBS sw_assets sw_core)
# The teaset's three files as one model, not its scene: the clusters are
# made again from the whole pack, and a scene's are made per prototype.
add_test(NAME cluster_teaset COMMAND bash -c
  "cd ${PROJECT_SOURCE_DIR}/assets/samples && $<TARGET_FILE:seamwalk-pack> build teapot.txt teacup.txt teaspoon.txt -o ${CMAKE_CURRENT_BINARY_DIR}/cluster_teaset.swpack --quiet && $<TARGET_FILE:test_cluster> ${CMAKE_CURRENT_BINARY_DIR}/cluster_teaset.swpack")
# The part levels of the built teaset against its exact surfaces.
add_executable(test_part_levels_build_prog test_part_levels_build.c)
target_link_libraries(test_part_levels_build_prog PRIVATE sw_assets sw_core)
target_include_directories(test_part_levels_build_prog PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
sw_apply_warnings(test_part_levels_build_prog)
add_test(NAME part_levels_teaset COMMAND bash -c
  "$<TARGET_FILE:seamwalk-pack> build ${PROJECT_SOURCE_DIR}/assets/samples/teaset.ini -o ${CMAKE_CURRENT_BINARY_DIR}/part_levels_teaset.swpack --quiet && $<TARGET_FILE:test_part_levels_build_prog> ${CMAKE_CURRENT_BINARY_DIR}/part_levels_teaset.swpack")
# Thin sheets (plates with holes, arched rails with slots): each piece's
# finest level is one a view can use.
add_test(NAME part_levels_sheets COMMAND bash -c
  "$<TARGET_FILE:seamwalk-pack> build ${CMAKE_CURRENT_SOURCE_DIR}/part_levels_sheets.ini -o ${CMAKE_CURRENT_BINARY_DIR}/part_levels_sheets.swpack --quiet && $<TARGET_FILE:test_part_levels_build_prog> ${CMAKE_CURRENT_BINARY_DIR}/part_levels_sheets.swpack")
# A part cut into pieces (a generated courtyard of 1,400 patches, one part,
# cut past 512 patches):
# its pieces' levels against its surfaces, and their borders against each
# other at every front; fails when no part is cut. The pictures of such a
# part are tests/test_pieces.sh (firmware.cmake).
add_test(NAME part_levels_courtyard COMMAND bash -c
  "python3 ${CMAKE_CURRENT_SOURCE_DIR}/gen_soup.py ${CMAKE_CURRENT_BINARY_DIR}/pieces_court.igs --cells 24 > /dev/null && $<TARGET_FILE:seamwalk-pack> build ${CMAKE_CURRENT_BINARY_DIR}/pieces_court.igs -o ${CMAKE_CURRENT_BINARY_DIR}/pieces_court.swpack --cut-patches 512 --quiet && $<TARGET_FILE:test_part_levels_build_prog> --cut ${CMAKE_CURRENT_BINARY_DIR}/pieces_court.swpack")
# The levels made on threads (seamwalk-pack build --threads): the same pack
# bytes with 1 and 4 threads, a showroom of many parts and a courtyard cut
# into pieces (build_threads: the tool as it is, so under TSan it runs
# uninstrumented); the same levels, made in a test program whose workers
# TSan checks (build_threads_levels, tests/run-tsan.sh --threaded).
add_test(NAME build_threads COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_build_threads.sh
  $<TARGET_FILE:seamwalk-pack> ${PROJECT_SOURCE_DIR})
# ... and a STEP assembly of many faces, converted on the threads.
add_test(NAME build_threads_step COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_build_threads.sh
  $<TARGET_FILE:seamwalk-pack> ${PROJECT_SOURCE_DIR} --step ${SW_SHARED_MODELS}/occt_linkrods.step)
set_tests_properties(build_threads_step PROPERTIES SKIP_RETURN_CODE 77 ENVIRONMENT
  "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_SOURCE_DIR}/occt-lsan.supp:print_suppressions=0")
sw_host_only_test(build_threads PROGRAMS seamwalk-pack)
add_executable(test_build_threads test_build_threads.c)
target_link_libraries(test_build_threads PRIVATE sw_assets sw_threads sw_core)
target_include_directories(test_build_threads PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
sw_apply_warnings(test_build_threads)
add_test(NAME build_threads_levels COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_build_threads.sh
  $<TARGET_FILE:seamwalk-pack> ${PROJECT_SOURCE_DIR} $<TARGET_FILE:test_build_threads>)
