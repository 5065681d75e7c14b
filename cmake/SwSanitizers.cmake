# SPDX-License-Identifier: MIT
# Sanitizer builds apply to every target in the tree, libraries included, so a
# report can point into any layer.
if(SW_ASAN AND SW_TSAN)
  message(FATAL_ERROR "SW_ASAN and SW_TSAN cannot be combined")
endif()
if(SW_ASAN)
  # Optimised (the sanitizers' documentation asks for -O1 or more; the
  # build type stays Debug, so asserts stay on): at -O0 the suite's
  # pack-building tests ran about three times as long as at -O1
  # (test_pack_cli 322 -> 120 s, up_axis_cli 195 -> 58 s), and -O2 took
  # another quarter to a third off the pack tool (a 3,000-patch showroom's
  # build 35-40 -> 28-29 s of CPU, the OCCT bearing 3.0 -> 1.4-2.0 s;
  # packs byte for byte the same), for CI's half hour.
  set(SW_ASAN_OPTIMIZE -O2 CACHE STRING "optimisation of the ASan+UBSan build")
  add_compile_options(${SW_ASAN_OPTIMIZE} -fsanitize=address,undefined -fno-omit-frame-pointer
    -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()
if(SW_TSAN)
  add_compile_options(-fsanitize=thread -fno-omit-frame-pointer)
  add_link_options(-fsanitize=thread)
endif()
# sw_without_tsan(target): the target compiled and linked without TSan.
# Only for programs that start no thread, and what they link: the host tool
# (assets/CMakeLists.txt) and the test programs built on it alone
# (tests/CMakeLists.txt). TSan reports races between threads and has
# nothing to check there.
function(sw_without_tsan target)
  foreach(property COMPILE_OPTIONS LINK_OPTIONS)
    get_target_property(options ${target} ${property})
    if(options)
      list(REMOVE_ITEM options -fsanitize=thread)
      set_property(TARGET ${target} PROPERTY ${property} ${options})
    endif()
  endforeach()
endfunction()
if(SW_FUZZ)
  # The whole tree carries coverage instrumentation, so libFuzzer sees the
  # parsers' branches, not only the target's entry point.
  if(NOT CMAKE_C_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "SW_FUZZ needs clang (CC=clang)")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
