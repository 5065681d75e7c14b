# tests of the firmware area
