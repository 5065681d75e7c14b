# tests of showroom scenes (issue 3): procedural objects and the showroom
# generator. test_scene itself is registered in assets.cmake.
sw_add_test(test_procedural SOURCES test_procedural.c LIBS sw_assets sw_core)
