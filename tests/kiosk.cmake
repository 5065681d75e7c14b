# SPDX-License-Identifier: MIT
# tests of the kiosk pieces of issue 11: configuration and button debouncing.
sw_add_test(test_debounce SOURCES test_debounce.c LIBS sw_runtime)
sw_add_test(test_config SOURCES test_config.c LIBS sw_runtime
  ARGS ${PROJECT_SOURCE_DIR}/firmware/dist/seamwalk.ini)
# seamwalk's option table: the command line, --help and the config keys
# take each range and default from its rows (tests/test_options.c).
sw_add_test(test_options SOURCES test_options.c LIBS sw_runtime)
sw_add_fuzz_target(fuzz_config SOURCE ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz_config.c
  LIBS sw_runtime CORPUS ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/config
  DICT ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/dict/config.dict)

# Inputs and navigation (issue 11 items 2-5): recorded descriptors in tests/hid/.
set(SW_HID_FIXTURES ${CMAKE_CURRENT_SOURCE_DIR}/hid)
sw_add_test(test_hid_desc SOURCES test_hid_desc.c LIBS sw_runtime ARGS ${SW_HID_FIXTURES})
sw_add_test(test_gamepad_map SOURCES test_gamepad_map.c LIBS sw_runtime ARGS ${SW_HID_FIXTURES})
sw_add_test(test_pads SOURCES test_pads.c LIBS sw_runtime ARGS ${SW_HID_FIXTURES})
sw_add_test(test_nav SOURCES test_nav.c LIBS sw_runtime)
sw_add_test(test_kiosk SOURCES test_kiosk.c LIBS sw_runtime ARGS ${SW_HID_FIXTURES})
sw_add_test(test_input_timeline SOURCES test_input_timeline.c LIBS sw_runtime)
sw_add_fuzz_target(fuzz_hid_desc SOURCE ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz_hid_desc.c
  LIBS sw_runtime CORPUS ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/hid_desc)
sw_add_fuzz_target(fuzz_pad_mapping SOURCE ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz_pad_mapping.c
  LIBS sw_runtime CORPUS ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/pad_mapping
  DICT ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/dict/pad_mapping.dict)
sw_add_fuzz_target(fuzz_input_timeline SOURCE ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz_input_timeline.c
  LIBS sw_runtime CORPUS ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/input_timeline
  DICT ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/dict/input_timeline.dict)

# The evdev keyboard through libevdev, SYN_DROPPED included, on a recorded
# event stream with the kernel's ioctls faked for it (tests/test_evdev_keys.c).
sw_add_test(test_evdev_keys SOURCES test_evdev_keys.c LIBS sw_runtime)
# A runtime-only build stops here (tests/CMakeLists.txt): the tests below
# walk packs that seamwalk-pack builds.
if(NOT SW_BUILD_PACK_TOOL)
  return()
endif()

# seamwalk --config end to end (tests/test_config_walk.sh).
add_test(NAME walk_config
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_config_walk.sh ${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR})

# seamwalk --input-timeline end to end (tests/test_input_walk.sh).
add_test(NAME walk_input_timeline
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_input_walk.sh ${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR})

# The service as shipped (issue 25): the unit verifies and rates <= 3.0 in
# systemd-analyze security, the udev rule grants only game controllers'
# hidraw nodes, seamwalk draws with llvmpipe under the unit's system call
# filter (tests/test_service.sh, tests/unit_sandbox.py); seamwalk's
# READY=1, WATCHDOG=1 and STATUS= read from a NOTIFY_SOCKET of the test's
# own (tests/test_notify.py).
add_test(NAME test_service COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_service.sh
         $<TARGET_FILE:seamwalk> $<TARGET_FILE:seamwalk-pack> ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/service)
add_test(NAME test_notify COMMAND python3 ${CMAKE_CURRENT_SOURCE_DIR}/test_notify.py
         $<TARGET_FILE:seamwalk> $<TARGET_FILE:seamwalk-pack> ${PROJECT_SOURCE_DIR}/assets/samples
         ${CMAKE_CURRENT_BINARY_DIR}/notify)
