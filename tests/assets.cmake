# tests of the assets area
