# Sanitizer builds apply to every target in the tree, libraries included, so a
# report can point into any layer.
if(SW_ASAN AND SW_TSAN)
  message(FATAL_ERROR "SW_ASAN and SW_TSAN cannot be combined")
endif()
if(SW_ASAN)
  # -O1, as the sanitizers' own documentation advises: the suite under
  # ASan+UBSan ran about twice as long at -O0, for the same reports (the
  # build type stays Debug, so asserts stay on).
  add_compile_options(-O1 -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()
if(SW_TSAN)
  add_compile_options(-fsanitize=thread -fno-omit-frame-pointer)
  add_link_options(-fsanitize=thread)
endif()
if(SW_FUZZ)
  # The whole tree carries coverage instrumentation, so libFuzzer sees the
  # parsers' branches, not only the target's entry point.
  if(NOT CMAKE_C_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "SW_FUZZ needs clang (CC=clang)")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
