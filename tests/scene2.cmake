# tests of showroom scenes (issue 3): procedural objects and the showroom
# generator. test_scene itself is registered in assets.cmake.
sw_add_test(test_procedural SOURCES test_procedural.c LIBS sw_assets sw_core)

# The generator's command function as a program of its own (gen_cli.c), so
# test_gen.sh runs it whether or not seamwalk-pack wires `gen` yet.
add_executable(sw_gen_cli gen_cli.c)
target_link_libraries(sw_gen_cli PRIVATE sw_assets sw_core)
sw_apply_warnings(sw_gen_cli)

add_test(NAME test_gen
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_gen.sh $<TARGET_FILE:sw_gen_cli>
          $<TARGET_FILE:seamwalk-pack> procedural)
add_test(NAME test_gen_parts
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_gen.sh $<TARGET_FILE:sw_gen_cli>
          $<TARGET_FILE:seamwalk-pack> parts ${SW_SHARED_MODELS})
set_tests_properties(test_gen test_gen_parts PROPERTIES TIMEOUT 300)
set_tests_properties(test_gen_parts PROPERTIES SKIP_RETURN_CODE 77)
