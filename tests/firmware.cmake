# SPDX-License-Identifier: MIT
# tests of the firmware area: runtime modules, then the whole program.
sw_add_test(test_arena SOURCES test_arena.c LIBS sw_core)
sw_add_test(test_buddy SOURCES test_buddy.c LIBS sw_core)
sw_add_test(test_steal_queue SOURCES test_steal_queue.c LIBS sw_core)
sw_add_test(test_handoff SOURCES test_handoff.c LIBS sw_core)
sw_add_test(test_camera_path SOURCES test_camera_path.c LIBS sw_runtime)
sw_add_test(test_stats SOURCES test_stats.c LIBS sw_runtime)
sw_add_test(test_seam_pressure SOURCES test_seam_pressure.c LIBS sw_runtime)
sw_add_test(test_view SOURCES test_view.c LIBS sw_runtime)
sw_add_test(test_seam_measure SOURCES test_seam_measure.c LIBS sw_runtime)
sw_add_test(test_seam_fill SOURCES test_seam_fill.c LIBS sw_runtime)
sw_add_test(test_seam_drawn SOURCES test_seam_drawn.c LIBS sw_runtime)
sw_add_test(test_alloc_count SOURCES test_alloc_count.c LIBS sw_alloc_count)
sw_add_fuzz_target(fuzz_camera_path SOURCE ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz_camera_path.c
  LIBS sw_runtime CORPUS ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/camera_path
  DICT ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/dict/camera_path.dict)
# The tessellation cache, and runtime_bytes holding the pack and the walk.
sw_add_test(test_seam_cache SOURCES test_seam_cache.c LIBS sw_runtime
            ARGS ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/pack/seed-seam-graph)
# A runtime-only build stops here (tests/CMakeLists.txt): the tests below
# need seamwalk-pack, the assets library or the benchmarks' baselines.
if(NOT SW_BUILD_PACK_TOOL)
  return()
endif()
sw_add_test(test_parts_threads SOURCES test_parts_threads.c LIBS sw_runtime sw_assets)
sw_add_test(test_cell_filter SOURCES test_cell_filter.c LIBS sw_cell_filter)

# The whole programs, end to end (tests/test_walk.sh).
add_executable(image_compare image_compare.c)
target_link_libraries(image_compare PRIVATE sw_stb ${MATH_LIBRARY})
add_executable(image_holes image_holes.c)
target_link_libraries(image_holes PRIVATE sw_stb ${MATH_LIBRARY})
sw_apply_warnings(image_holes)
foreach(mode teaset teapot golden errors seams)
  add_test(NAME walk_${mode}
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_walk.sh ${mode} ${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR})
  set_tests_properties(walk_${mode} PROPERTIES SKIP_RETURN_CODE 77)
endforeach()

# The seams as drawn on a real walk, with and without the crossing fans.
add_test(NAME seam_drawn_walk
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_seam_drawn_walk.sh ${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR})

# The includes run one way: no header circle, the walk's folders
# (firmware/walk/ and its thread folders) never include each other both
# ways, and firmware's jobs and platform's folders include round no circle.
add_test(NAME include_graph
  COMMAND python3 ${CMAKE_CURRENT_SOURCE_DIR}/check_includes.py ${PROJECT_SOURCE_DIR})

# The depth planes fit where the model is seen: no back face in front.
add_test(NAME depth_fit
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_depth_fit.sh ${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR})

# The threaded walk: stalled workers, two workers, --sync-work against --workers 0.
add_test(NAME walk_threads
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_walk_threads.sh ${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR})
set_tests_properties(walk_threads PROPERTIES TIMEOUT 600)

# The native IGES reader against OpenCASCADE on the shared models.
sw_add_test(test_iges_crosscheck SOURCES test_iges_crosscheck.c LIBS sw_assets sw_core
  ARGS ${SW_SHARED_MODELS})
set_tests_properties(test_iges_crosscheck PROPERTIES SKIP_RETURN_CODE 77
  ENVIRONMENT "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_SOURCE_DIR}/occt-lsan.supp:print_suppressions=0")

# Every shared CAD model built, walked headless and checked (tests/test_models.sh).
add_executable(occt_measure occt_measure.c)
target_link_libraries(occt_measure PRIVATE sw_assets sw_core)
sw_apply_warnings(occt_measure)
file(GLOB SW_SHARED_MODEL_FILES ${SW_SHARED_MODELS}/*.igs ${SW_SHARED_MODELS}/*.iges
  ${SW_SHARED_MODELS}/*.stp ${SW_SHARED_MODELS}/*.step ${SW_SHARED_MODELS}/*.txt)
foreach(file ${SW_SHARED_MODEL_FILES})
  get_filename_component(model ${file} NAME)
  add_test(NAME model_${model}
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_models.sh ${file} ${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR})
  set_tests_properties(model_${model} PROPERTIES SKIP_RETURN_CODE 77)
endforeach()

# Cracks and holes told by pixels alone (tests/test_image_holes.sh): the
# teaset sample and every shared model, close, mid and far, at the default
# bound against a 0.05 px reference; a dropped-surface mutant must be caught.
# Release only (the references are dense; the sanitizer runs cover the code
# through test_seam_fill, test_seam_drawn and the walks).
if(NOT SW_ASAN AND NOT SW_TSAN)
  foreach(file ${SW_SAMPLES}/teaset.ini ${SW_SHARED_MODEL_FILES})
    get_filename_component(model ${file} NAME)
    add_test(NAME holes_${model}
      COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_image_holes.sh ${file} ${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR})
    set_tests_properties(holes_${model} PROPERTIES SKIP_RETURN_CODE 77)
  endforeach()
endif()

# A walk judged by its pictures against the reference walk (--workers 0),
# tests/walk_pictures.py: on a 2,000-patch showroom the same walk matches
# pixel for pixel and a walk without a plate in view must show its hole;
# its orbit with far parts drawn from part levels meets the picture targets
# and the mutant drawing every part from its coarsest level does not
# (tests/test_walk_pictures.sh). Release only, as the holes tests above.
if(NOT SW_ASAN AND NOT SW_TSAN)
  add_test(NAME walk_pictures
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_walk_pictures.sh ${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR})
  set_tests_properties(walk_pictures PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300)
endif()

# Stand-ins' silhouettes (tests/test_silhouettes.sh): a generated courtyard
# of columns walked as the service walks it has no interior background
# pixel against the reference walk; the mutant whose stand-ins use the
# whole bound at silhouettes shows slits. Release only, as above.
if(NOT SW_ASAN AND NOT SW_TSAN)
  add_test(NAME silhouettes
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_silhouettes.sh ${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR})
  set_tests_properties(silhouettes PROPERTIES TIMEOUT 300)
endif()

# A part cut into pieces (tests/test_pieces.sh): a generated courtyard's
# levels and borders checked, its orbit drawn from its pieces' levels
# within the picture targets against the reference walk, and the mutant
# drawing every piece from its coarsest level fails them. Release only.
if(NOT SW_ASAN AND NOT SW_TSAN)
  add_test(NAME pieces
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_pieces.sh ${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR})
  set_tests_properties(pieces PROPERTIES TIMEOUT 300)
endif()

# The corpus command on the shared models (tests/corpus.sh): every file built,
# verified and walked close to far with no crack and no refused surface, and
# (IGES, STEP) its free border at most 1.05 times OpenCASCADE's sewing at the
# same tolerance. Release only: each model's test_models.sh run above covers
# the same code under the sanitizers.
if(EXISTS ${SW_SHARED_MODELS} AND NOT SW_ASAN AND NOT SW_TSAN)
  add_test(NAME corpus_shared_models
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/corpus.sh --build ${PROJECT_BINARY_DIR}
            --require-sewing
            --json ${PROJECT_BINARY_DIR}/tests/corpus.json ${SW_SHARED_MODELS})
endif()

# A generated patch soup (tests/gen_soup.py: 2068 faces sharing no topology,
# T-junctions, stones moved by up to 0.002 mm, columns that meet themselves)
# through the same command: its free border within 1.05x OpenCASCADE's.
if(NOT SW_ASAN AND NOT SW_TSAN)
  add_test(NAME corpus_patch_soup
    COMMAND sh -c "mkdir -p soup && python3 ${CMAKE_CURRENT_SOURCE_DIR}/gen_soup.py soup/courtyard.igs && bash ${CMAKE_CURRENT_SOURCE_DIR}/corpus.sh --build ${PROJECT_BINARY_DIR} --require-sewing soup"
    WORKING_DIRECTORY ${PROJECT_BINARY_DIR}/tests)
endif()

# The whole process's heap calls beside seamwalk's own (process_alloc_shim.c,
# preloaded): our code makes none after start-up; what Mesa and libc make is
# measured and printed, not claimed. Not under the sanitizers, which replace
# malloc themselves.
if(NOT SW_ASAN AND NOT SW_TSAN)
  add_library(process_alloc_shim MODULE process_alloc_shim.c)
  set_target_properties(process_alloc_shim PROPERTIES PREFIX "")
  add_test(NAME process_allocs
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_process_allocs.sh $<TARGET_FILE:seamwalk-pack>
            $<TARGET_FILE:seamwalk> $<TARGET_FILE:process_alloc_shim> ${SW_SAMPLES}
    WORKING_DIRECTORY ${PROJECT_BINARY_DIR}/tests)
endif()

# Culling end to end (tests/test_cull_walk.sh): the tree against every patch
# box, walks with --cull tree and brute picture for picture, and cone culling
# on and off with back faces hidden pixel for pixel, on the teaset, a
# generated showroom and every shared model. Release only (twelve walks a
# model; the sanitizer runs cover the code through test_cull_tree,
# test_normal_cone and the walk tests).
if(NOT SW_ASAN AND NOT SW_TSAN)
  add_test(NAME cull_walk
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_cull_walk.sh ${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR}
            ${SW_SHARED_MODEL_FILES})
endif()

# Under TSan, the step's own check (tests/tsan_check.sh): a planted race
# fails, the runtime is instrumented and the host tool is not.
if(SW_TSAN)
  add_executable(tsan_race tsan_race.c)
  target_link_libraries(tsan_race PRIVATE Threads::Threads)
  sw_apply_warnings(tsan_race)
  add_test(NAME tsan_check COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/tsan_check.sh
    ${PROJECT_BINARY_DIR})
endif()

# The start on huge pages (tests/test_huge_heap.sh): the walk runs with
# its heap advised for huge pages where THP is "madvise", with other
# tunables too, and not with the opt-out. Not under the sanitizers, whose
# allocators replace glibc's heap.
if(NOT SW_ASAN AND NOT SW_TSAN)
  add_test(NAME huge_heap COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_huge_heap.sh
    ${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR})
endif()

# The short soak: the teaset looped for 20 s; resident memory flat after
# the warm-up (the first quarter of the loops) and no allocation (tests/soak.sh; the 10-minute soak is the
# same script with --duration 600, docs/testing.md, "The soak"). Under the
# sanitizers resident memory is theirs (ASan's quarantine keeps what Mesa
# frees each frame: +3 MB in 20 s), so there only the loops and
# mallocs_after_init are checked.
if(SW_ASAN OR SW_TSAN)
  set(SW_SOAK_GROWTH_KB 1048576)
else()
  set(SW_SOAK_GROWTH_KB 2048)
endif()
sw_expect_output(soak_short
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/soak.sh ${PROJECT_BINARY_DIR}
          --duration 20 --frames 30 --max-growth-kb ${SW_SOAK_GROWTH_KB}
  PASS "soak: 20 s, .*mallocs_after_init 0\n" FAIL "soak: FAIL")
# The same check must fail on growth: 4 MB more resident at each loop's end
# (seamwalk --test-grow-kb, no allocation), so at least 4 MB past the first
# loop once two loops ran; nothing else may fail, and soak.sh must say so
# with its exit 1. Not under the sanitizers (their allowance above is 1 GB).
if(NOT SW_ASAN AND NOT SW_TSAN)
  sw_expect_output(soak_catches_growth EXIT 1
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/soak.sh ${PROJECT_BINARY_DIR}
            --duration 8 --frames 10 --test-grow-kb 4096
    PASS "mallocs_after_init 0\n.*soak: FAIL: resident memory grew by"
    FAIL "soak: FAIL: (mallocs|only)|the walk failed")
endif()
# Stand-ins seen in the pictures (tests/test_standins.sh): with the workers
# stalled, surfaces coming into view are drawn from their static levels,
# with no hole against the walk without workers; the mutant without them
# must show one.
# Registered where the shared models are (as in CI), and then never
# skipped; under the sanitizers on a 400-patch showroom (the same code).
if(EXISTS ${SW_SHARED_MODELS}/occt_hammer.iges)
  set(standin_patches 2000)
  if(SW_ASAN OR SW_TSAN)
    set(standin_patches 400)
  endif()
  add_test(NAME standins COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_standins.sh
           ${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR} ${SW_SHARED_MODELS} ${standin_patches})
endif()

# A scene of repeated parts packed as placed parts and as copies walks the
# same, pixel for pixel (tests/test_instances_walk.sh), as built and with
# every surface tessellated, with no crack and no gap.
add_test(NAME instances_walk COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_instances_walk.sh
         ${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR})

# corpus.sh's verdicts (tests/corpus_row.py) on made-up steps' outputs:
# faces OpenCASCADE transfers that the pack lacks and the build did not
# name as skipped, the failed step kept as the reason, the summary.
add_test(NAME corpus_row COMMAND python3 ${CMAKE_CURRENT_SOURCE_DIR}/test_corpus_row.py
         ${PROJECT_SOURCE_DIR})
sw_host_only_test(corpus_row)

# A pack built for a closest view (--closest-mm): fewer seam vertices, the
# same pictures from beyond it, and views closer than it clamped and
# counted (tests/test_closest.sh).
add_test(NAME closest_view COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_closest.sh
         ${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR})
