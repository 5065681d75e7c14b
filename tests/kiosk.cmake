# tests of the kiosk pieces of issue 11: configuration and button debouncing.
sw_add_test(test_debounce SOURCES test_debounce.c LIBS sw_runtime)
