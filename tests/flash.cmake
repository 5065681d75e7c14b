# SPDX-License-Identifier: MIT
# tests of signed packs and the unit's pack store (issue 12): signing and its
# check (test_pack_sign), the key file and store state parsers' fuzz targets.
sw_add_test(test_pack_store SOURCES test_pack_store.c LIBS sw_runtime)
# The screen a unit with no valid pack shows, read back from the framebuffer.
sw_add_test(test_message_screen SOURCES test_message_screen.c LIBS sw_platform sw_core)
# The parsers of the store's state file and journal.
sw_add_fuzz_target(fuzz_store SOURCE ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz_store.c
  LIBS sw_runtime CORPUS ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/store
  DICT ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/dict/store.dict)
# A runtime-only build stops here (tests/CMakeLists.txt): the tests below
# need signed packs that seamwalk-pack builds.
if(NOT SW_BUILD_PACK_TOOL)
  return()
endif()
sw_add_test(test_pack_sign SOURCES test_pack_sign.c LIBS sw_assets sw_core)

# The store tests' packs and keys (tests/flash_fixture.sh), made once.
set(SW_FLASH_FIXTURE ${CMAKE_CURRENT_BINARY_DIR}/flash_fixture)
add_test(NAME flash_fixture COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/flash_fixture.sh
         $<TARGET_FILE:seamwalk-pack> ${SW_SAMPLES} ${SW_FLASH_FIXTURE})
set_tests_properties(flash_fixture PROPERTIES FIXTURES_SETUP flash_packs)

# The fault shim (LD_PRELOAD): kills and I/O failures at chosen calls.
add_library(flash_fault_shim SHARED flash_fault_shim.c)
target_link_libraries(flash_fault_shim PRIVATE ${CMAKE_DL_LIBS})
set_target_properties(flash_fault_shim PROPERTIES PREFIX "")
if(SW_TSAN)  # preloaded into seamwalk-flash, which is built without TSan
  sw_without_tsan(flash_fault_shim)
endif()

# Power loss: SIGKILL at random calls and random times during install.
# Fewer trials under the sanitizers, where every run is several times slower.
if(SW_ASAN OR SW_TSAN)
  set(SW_FLASH_TRIALS 120 30)
else()
  set(SW_FLASH_TRIALS 200 40)
endif()
add_executable(test_flash_power test_flash_power.c)
target_include_directories(test_flash_power PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
sw_apply_warnings(test_flash_power)
if(SW_TSAN)  # one thread: it only starts and kills installs
  sw_without_tsan(test_flash_power)
endif()
add_test(NAME test_flash_power COMMAND test_flash_power $<TARGET_FILE:seamwalk-flash>
         $<TARGET_FILE:flash_fault_shim> ${SW_FLASH_FIXTURE}
         ${CMAKE_CURRENT_BINARY_DIR}/flash_power ${SW_FLASH_TRIALS} 12)
set_tests_properties(test_flash_power PROPERTIES FIXTURES_REQUIRED flash_packs SKIP_RETURN_CODE 77)
sw_host_only_test(test_flash_power PROGRAMS test_flash_power seamwalk-flash flash_fault_shim)

# Refusals, I/O faults and the install / status / mark-good / rollback flow.
add_test(NAME test_flash_cli COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_flash_cli.sh
         $<TARGET_FILE:seamwalk-flash> $<TARGET_FILE:flash_fault_shim> ${SW_FLASH_FIXTURE}
         ${CMAKE_CURRENT_BINARY_DIR}/flash_cli)
set_tests_properties(test_flash_cli PROPERTIES FIXTURES_REQUIRED flash_packs SKIP_RETURN_CODE 77)
sw_host_only_test(test_flash_cli PROGRAMS seamwalk-flash flash_fault_shim)

# The boot side: seamwalk --store (trial, mark-good, fallback after K boots,
# power cuts while a boot is recorded, the message screen read back).
# Its display is an X11 window on Xvfb: a headless walk never marks a slot good.
if(SW_WITH_X11)
  add_test(NAME test_flash_boot COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_flash_boot.sh
           $<TARGET_FILE:seamwalk> $<TARGET_FILE:seamwalk-flash> $<TARGET_FILE:flash_fault_shim>
           ${SW_FLASH_FIXTURE} ${CMAKE_CURRENT_BINARY_DIR}/flash_boot)
  set_tests_properties(test_flash_boot PROPERTIES FIXTURES_REQUIRED flash_packs SKIP_RETURN_CODE 77)
else()
  sw_test_not_built(SW_WITH_X11 test_flash_boot)
endif()

# The parser of key files.
sw_add_fuzz_target(fuzz_keys SOURCE ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz_keys.c
  LIBS sw_assets sw_core CORPUS ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/keys
  DICT ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/dict/keys.dict)

# No store fault stops a boot, and boot-check agrees with it: each fault
# the unit's user can meet (a root lock, a read-only store or mount, an
# unwritable or unreadable state, a busy lock), the boot and boot-check run
# as that user (nobody; the test needs root and is skipped without it).
add_test(NAME test_flash_store_faults COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_flash_store_faults.sh
         $<TARGET_FILE:seamwalk> $<TARGET_FILE:seamwalk-flash> ${SW_FLASH_FIXTURE}
         ${CMAKE_CURRENT_BINARY_DIR}/flash_store_faults)
set_tests_properties(test_flash_store_faults PROPERTIES FIXTURES_REQUIRED flash_packs
                     SKIP_RETURN_CODE 77)

# The state's two copies: each damaged, emptied or removed, then both, then
# seamwalk-flash repair (tests/test_flash_state.sh).
add_test(NAME test_flash_state COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_flash_state.sh
         $<TARGET_FILE:seamwalk> $<TARGET_FILE:seamwalk-flash> ${SW_FLASH_FIXTURE}
         ${CMAKE_CURRENT_BINARY_DIR}/flash_state)
set_tests_properties(test_flash_state PROPERTIES FIXTURES_REQUIRED flash_packs SKIP_RETURN_CODE 77)

# The unit's trust anchor: keys files the unit's user could change refused
# everywhere, --keys only narrowing, the signature checked before any
# section is parsed (tests/test_flash_keys.sh; needs root, else skipped).
add_test(NAME test_flash_keys COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_flash_keys.sh
         $<TARGET_FILE:seamwalk> $<TARGET_FILE:seamwalk-flash> ${SW_FLASH_FIXTURE}
         ${CMAKE_CURRENT_BINARY_DIR}/flash_keys)
set_tests_properties(test_flash_keys PROPERTIES FIXTURES_REQUIRED flash_packs SKIP_RETURN_CODE 77)

# Caps and early checks (issue 25, item 7): the 200,000-face STEP shell,
# the output checked before the build, directories named like models,
# control bytes escaped, no partial pack or stats on a full disk (the
# fault shim's).
add_test(NAME test_early_checks COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_early_checks.sh
         $<TARGET_FILE:seamwalk-pack> $<TARGET_FILE:seamwalk> $<TARGET_FILE:flash_fault_shim>
         ${SW_SAMPLES} ${CMAKE_CURRENT_BINARY_DIR}/early_checks)

# One version: each program's --version and the stats' (CMake's project
# version, the one source).
add_test(NAME test_version COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_version.sh
         ${PROJECT_VERSION} $<TARGET_FILE:seamwalk> $<TARGET_FILE:seamwalk-pack>
         $<TARGET_FILE:seamwalk-flash> ${SW_SAMPLES} ${CMAKE_CURRENT_BINARY_DIR}/version)
