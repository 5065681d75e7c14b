# SPDX-License-Identifier: MIT
# tests of the platform area: headless GLES2 rendering and PNG output
sw_add_test(test_render SOURCES test_render.c LIBS sw_platform sw_core)
# test_png decodes what it wrote with stb_image, compiled in the test itself.
sw_add_test(test_png SOURCES test_png.c LIBS sw_png sw_core sw_stb)
# The display interface (issue 11 item 1): auto's choice, the errors of the
# displays this machine lacks, headless through the interface; the KMS
# path's pure parts; the window key queue.
sw_add_test(test_display SOURCES test_display.c LIBS sw_platform sw_core)
sw_add_test(test_kms_choose SOURCES test_kms_choose.c LIBS sw_platform)
sw_add_test(test_kms_flip SOURCES test_kms_flip.c LIBS sw_platform)
sw_add_test(test_key_queue SOURCES test_key_queue.c LIBS sw_platform)
# The Wayland keyboard's keymap and key codes with a real US keymap.
if(SW_WITH_WAYLAND)
  sw_add_test(test_xkb_keys SOURCES test_xkb_keys.c LIBS sw_platform PkgConfig::XKBCOMMON)
endif()
# A runtime-only build stops here (tests/CMakeLists.txt): the tests below
# run the programs end to end on packs that seamwalk-pack builds.
if(NOT SW_BUILD_PACK_TOOL)
  return()
endif()
# The X11 window on Xvfb (tests/test_display_x11.sh); skipped only where Xvfb
# is not installed, or in a build without X11.
if(SW_WITH_X11)
  add_executable(test_display_x11 test_display_x11.c)
  target_link_libraries(test_display_x11 PRIVATE sw_platform sw_core PkgConfig::X11)
  target_include_directories(test_display_x11 PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  sw_apply_warnings(test_display_x11)
  add_executable(x11_send_key x11_send_key.c)
  target_link_libraries(x11_send_key PRIVATE PkgConfig::X11)
  sw_apply_warnings(x11_send_key)
  add_test(NAME display_x11
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_display_x11.sh ${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR})
  set_tests_properties(display_x11 PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 120)
else()
  sw_test_not_built(SW_WITH_X11 display_x11)
endif()
# The Wayland window on Weston's headless backend (tests/test_display_wayland.sh;
# skipped only where weston is not installed, or in a build without Wayland).
if(SW_WITH_WAYLAND)
  add_test(NAME display_wayland
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_display_wayland.sh ${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR})
  set_tests_properties(display_wayland PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 120)
else()
  sw_test_not_built(SW_WITH_WAYLAND display_wayland test_xkb_keys)
endif()
# SIGTERM and SIGINT end a walk cleanly (tests/test_display_signal.sh).
add_test(NAME display_signal
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_display_signal.sh ${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR})
