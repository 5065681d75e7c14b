# The three programs' command-line conventions (tests/test_cli.sh): --help
# on stdout with exit 0; a usage error one line and a hint on stderr.
add_test(NAME cli_conventions COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_cli.sh
  $<TARGET_FILE:seamwalk> $<TARGET_FILE:seamwalk-pack> $<TARGET_FILE:seamwalk-flash>)
