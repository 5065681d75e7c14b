# SPDX-License-Identifier: MIT
# Each test's cost in seconds, as measured on the 2-core development VM
# (CTest's own averages, rounded; tests under 8 s left at CTest's default):
# a fresh build has no CTest history, and in declaration order the longest
# tests came last (CI's ASan run ended on walk_bench_smoke's 73 s with one
# core idle). CTest runs the costliest first. Only the order matters: a
# wrong figure costs time, never a result. Used by tests/ and tests/bench/
# (set_tests_properties sees only its own directory's tests).
set(SW_TEST_COSTS_RELEASE
    standins 70 soak_short 23 walk_pictures 26 cull_walk 143 corpus_shared_models 114 test_pack_cli 67 walk_bench_smoke 48
    test_gen_parts 46 up_axis_cli 39 test_gen 38 holes_nist_mbe_pmi_4.stp 33 test_import_occt 32
    test_flash_power 30 model_nist_mbe_pmi_4.stp 25 model_occt_linkrods.step 20
    cull_bench_smoke 17 holes_occt_linkrods.step 17 test_flash_cli 15 walk_threads 15
    test_iges_crosscheck 14 corpus_patch_soup 13 holes_teaset.ini 12
    model_axom_boxed_sphere.step 12 holes_newell_teacup.txt 11 test_flash_boot 11 display_x11 11
    holes_newell_teapot.txt 10 display_signal 10 model_occt_hammer.iges 10 walk_seams 10
    holes_gpucast_teapot.igs 9 model_occt_screw.step 9 test_png 9 model_nist_mbe_pmi_1.stp 9
    model_occt_bearing.iges 9 test_import_occt_truncations 9 holes_axom_boxed_sphere.step 8
    up_axis_orbit 8 model_gpucast_teapot.igs 8 instances_walk 23 build_parts 22)
set(SW_TEST_COSTS_ASAN
    standins 150 test_pack_cli 143 test_gen_parts 133 up_axis_cli 83 test_gen 73 test_import_occt 73
    build_parts 68 instances_walk 64
    walk_bench_smoke 73 model_occt_linkrods.step 65 walk_threads 58 test_iges_crosscheck 44
    model_nist_mbe_pmi_4.stp 41 cull_bench_smoke 41 test_flash_cli 37 test_flash_power 35
    soak_short 29 test_flash_boot 28 walk_golden 27 model_axom_boxed_sphere.step 22
    up_axis_orbit 18 test_seam_sew 18 model_occt_bearing.iges 16 model_occt_screw.step 16
    walk_seams 15 model_occt_hammer.iges 14 model_nist_mbe_pmi_1.stp 14
    test_import_occt_truncations 14 display_x11 13 seam_drawn_walk 13 walk_input_timeline 13
    display_signal 12 display_wayland 12 walk_cache_bench_smoke 12 model_gpucast_teapot.igs 12
    walk_teaset 11 walk_threads_bench_smoke 11 walk_errors 11 model_nist_mbe_pmi_11.stp 11
    test_png 11 model_newell_teapot.txt 10 walk_config 10 model_newell_teacup.txt 10
    test_trim_tess 10 model_newell_teaspoon.txt 9)
set(SW_TEST_COSTS_TSAN
    test_gen_parts 125 walk_bench_smoke 103 test_gen 102 test_pack_cli 92
    test_iges_crosscheck 87 walk_golden 74 up_axis_cli 62 cull_bench_smoke 62 test_png 49
    model_nist_mbe_pmi_4.stp 47 test_flash_boot 45 model_occt_linkrods.step 43
    walk_input_timeline 43 test_import_occt 43 test_flash_power 42 seam_drawn_walk 40
    walk_teaset 32 walk_seams 31 model_axom_boxed_sphere.step 29 walk_errors 27 soak_short 27
    up_axis_orbit 27 test_flash_cli 25 walk_config 23 test_seam_sew 23
    model_gpucast_teapot.igs 22 model_newell_teacup.txt 21 display_x11 20 display_wayland 19
    model_occt_bearing.iges 18 model_nist_mbe_pmi_1.stp 17 model_occt_hammer.iges 17
    display_signal 17 test_trim_tess 17 model_newell_teapot.txt 17 model_occt_screw.step 16
    model_nist_mbe_pmi_11.stp 16 test_import_occt_truncations 16 model_newell_teaspoon.txt 13
    walk_threads_bench_smoke 13 walk_cache_bench_smoke 13 walk_threads 90 walk_teapot 10
    flash_fixture 8)

# The unit tests under qemu-user (the arm64 cross build, tests/cross/arm64.sh),
# where emulation makes the arithmetic-heavy ones the long ones.
set(SW_TEST_COSTS_EMULATED
    test_trim_tess 67 test_png 19 test_bezier 14 test_normal_cone 10 test_cull_tree 8 test_nurbs 8)

function(sw_apply_test_costs)
  if(CMAKE_CROSSCOMPILING_EMULATOR)
    set(costs ${SW_TEST_COSTS_EMULATED})
  elseif(SW_ASAN)
    set(costs ${SW_TEST_COSTS_ASAN})
  elseif(SW_TSAN)
    set(costs ${SW_TEST_COSTS_TSAN})
  else()
    set(costs ${SW_TEST_COSTS_RELEASE})
  endif()
  list(LENGTH costs n)
  math(EXPR last "${n} - 1")
  foreach(i RANGE 0 ${last} 2)
    math(EXPR j "${i} + 1")
    list(GET costs ${i} name)
    list(GET costs ${j} cost)
    if(TEST ${name})
      set_tests_properties(${name} PROPERTIES COST ${cost})
    endif()
  endforeach()
endfunction()
