# SPDX-License-Identifier: MIT
# The man pages against the programs (tests/check_man.py): every option and
# command --help prints has an entry and every option a page names exists,
# every config key of firmware/program/sw_config.c's table has an entry in
# seamwalk.ini(5) and the other way round, and `man --warnings -l` renders
# each page without a warning.
set(SW_MAN ${PROJECT_SOURCE_DIR}/docs/man)
set(SW_CHECK_MAN python3 ${CMAKE_CURRENT_SOURCE_DIR}/check_man.py)
add_test(NAME man_seamwalk COMMAND ${SW_CHECK_MAN} program ${SW_MAN}/seamwalk.1
  $<TARGET_FILE:seamwalk>)
add_test(NAME man_seamwalk_flash COMMAND ${SW_CHECK_MAN} program ${SW_MAN}/seamwalk-flash.8
  $<TARGET_FILE:seamwalk-flash>)
add_test(NAME man_seamwalk_pack COMMAND ${SW_CHECK_MAN} program ${SW_MAN}/seamwalk-pack.1
  $<TARGET_FILE:seamwalk-pack>)
add_test(NAME man_seamwalk_ini COMMAND ${SW_CHECK_MAN} config ${SW_MAN}/seamwalk.ini.5
  ${PROJECT_SOURCE_DIR}/firmware/program/sw_config.c $<TARGET_FILE:seamwalk>)
# seamwalk's option table against both pages: each option's argument, range
# and default, and those of the config key it shares (tests/option_table_dump.c).
add_executable(option_table_dump option_table_dump.c)
target_link_libraries(option_table_dump PRIVATE sw_runtime)
sw_apply_warnings(option_table_dump)
add_test(NAME man_option_table COMMAND ${SW_CHECK_MAN} table ${SW_MAN}/seamwalk.1
  ${SW_MAN}/seamwalk.ini.5 $<TARGET_FILE:option_table_dump>)
sw_host_only_test(man_seamwalk_pack PROGRAMS seamwalk-pack)
sw_host_only_test(man_seamwalk_flash PROGRAMS seamwalk-flash)

# The .deb packages (tests/test_package.sh): made by cpack from this build,
# unpacked into a staging root, their layout, control data, unit, programs
# and man pages checked there.
add_test(NAME package COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_package.sh
  ${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR} ${PROJECT_VERSION} ${CMAKE_CURRENT_BINARY_DIR}/package)
