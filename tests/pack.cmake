# tests of the pack area
