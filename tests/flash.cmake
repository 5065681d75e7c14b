# tests of signed packs and the unit's pack store (issue 12): signing and its
# check (test_pack_sign), the key file and store state parsers' fuzz targets.
sw_add_test(test_pack_sign SOURCES test_pack_sign.c LIBS sw_assets sw_core)
