# SPDX-License-Identifier: MIT
# The three programs' command-line conventions (tests/test_cli.sh): --help
# on stdout with exit 0; a usage error one line and a hint on stderr.
add_test(NAME cli_conventions COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_cli.sh
  $<TARGET_FILE:seamwalk> $<TARGET_FILE:seamwalk-pack> $<TARGET_FILE:seamwalk-flash>)
# The output checks fail on a crash after their expected line, and every
# one of the suite's goes through that check (tests/test_expect_output.py).
add_test(NAME expect_output COMMAND python3 ${CMAKE_CURRENT_SOURCE_DIR}/test_expect_output.py
  ${PROJECT_BINARY_DIR})
