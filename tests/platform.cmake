# tests of the platform area
