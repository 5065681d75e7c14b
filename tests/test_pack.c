/* SPDX-License-Identifier: MIT */
/* The pack reader, version 1: what it accepts and, above all, what it
 * refuses and how it says so. The writer's side is in test_pack_write.c. */
#include <stdint.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <xxhash.h>

#include "sw_test.h"
#include "pack_sample.h"
#include "parts_backwards.h"

/* Opens bytes in order and with the parts run backwards: the same result
 * and message both ways, returned. */
static sw_status open_bytes(const uint8_t *bytes, size_t size, sw_error *err)
{
    sw_pack pack;
    memset(err, 0, sizeof *err);
    sw_status st = sw_pack_open_memory(bytes, size, &pack, err);
    sw_error again;
    SW_CHECK_MSG(sw_opens_the_same_backwards(bytes, size, st, err->message, &again),
                 "parts run backwards: \"%s\", in order: %s \"%s\"", again.message,
                 sw_status_name(st), err->message);
    return st;
}

/* Serialises s (checksums valid) and expects the reader to refuse it with
 * status and a message containing needle. */
static void expect_rejected(const sample *s, sw_status status, const char *needle)
{
    size_t size = 0;
    uint8_t *bytes = serialize_sample(s, &size);
    sw_error err;
    sw_status got = open_bytes(bytes, size, &err);
    SW_CHECK_MSG(got == status, "expected %s, got %s: %s", sw_status_name(status),
                 sw_status_name(got), err.message);
    SW_CHECK_MSG(strstr(err.message, needle) != NULL, "\"%s\" not in \"%s\"", needle, err.message);
    free(bytes);
}

/* ---- round trip and layout ---- */

static void test_round_trip_keeps_every_field(void)
{
    sample s;
    make_sample(&s);
    size_t size = 0;
    uint8_t *bytes = serialize_sample(&s, &size);
    sw_pack pack;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_open_memory(bytes, size, &pack, &err) == SW_OK, "%s", err.message);
    SW_CHECK(pack.header->total_size == size);
    SW_CHECK(pack.header->runtime_bytes == sw_pack_runtime_bytes(0));
    SW_CHECK(pack.header->section_count == SAMPLE_SECTIONS);
    SW_CHECK(memcmp(pack.meta, &s.meta, sizeof s.meta) == 0);
    SW_CHECK(memcmp(pack.parts, s.parts, sizeof s.parts) == 0);
    SW_CHECK(memcmp(pack.patches, s.patches, sizeof s.patches) == 0);
    SW_CHECK(memcmp(pack.control, s.control, sizeof s.control) == 0);
    SW_CHECK(memcmp(pack.adjacency, s.adjacency, sizeof s.adjacency) == 0);
    SW_CHECK(strcmp(pack.parts[1].name, "lid \xc3\xa9") == 0);
    SW_CHECK(pack.patches[1].flags == SW_PATCH_RATIONAL);
    SW_CHECK(pack.control[(16 + 4) * 4 + 3] == 0.7071f);
    for (uint32_t i = 0; i < pack.header->section_count; i++) {
        SW_CHECK(pack.sections[i].offset % 64 == 0);
        SW_CHECK(pack.sections[i].flags == 0);
        SW_CHECK(pack.sections[i].type == i + 1); /* written in type order */
    }
    free(bytes);
}

static void test_round_trip_keeps_optional_sections(void)
{
    sample s;
    make_sample(&s);
    size_t size = 0;
    uint8_t *bytes = serialize_sample(&s, &size);
    sw_pack pack;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_open_memory(bytes, size, &pack, &err) == SW_OK, "%s", err.message);
    SW_CHECK(pack.surface_count == 2 && memcmp(pack.surfaces, s.surfaces, sizeof s.surfaces) == 0);
    SW_CHECK(pack.trim_loop_count == 2 && memcmp(pack.trim_loops, s.loops, sizeof s.loops) == 0);
    SW_CHECK(pack.trim_curve_count == 2 &&
             memcmp(pack.trim_curves, s.curves, sizeof s.curves) == 0);
    SW_CHECK(pack.trim_data_count == SAMPLE_TRIM_DATA &&
             memcmp(pack.trim_data, s.trim_data, sizeof s.trim_data) == 0);
    SW_CHECK(memcmp(pack.patch_domains, s.domains, sizeof s.domains) == 0);
    SW_CHECK(pack.trim_mask_count == 1 && memcmp(pack.trim_masks, s.masks, sizeof s.masks) == 0);
    SW_CHECK(pack.viewpoint_count == 1 &&
             memcmp(pack.viewpoints, s.viewpoints, sizeof s.viewpoints) == 0);
    SW_CHECK(memcmp(pack.part_transforms, s.transforms, sizeof s.transforms) == 0);
    SW_CHECK(strcmp(pack.viewpoints[0].name, "front") == 0);
    SW_CHECK(pack.patch_domains[1].mask == SW_MASK_NONE && pack.trim_masks[0].rows[3] == 0xFFFFFFF8u);
    SW_CHECK(pack.trim_curves[1].flags == (SW_TRIM_RATIONAL | SW_TRIM_COMPUTED));
    free(bytes);
}

static void test_bezier_only_pack_has_no_optional_views(void)
{
    sample s;
    make_sample(&s);
    s.bezier_only = 1;
    size_t size = 0;
    uint8_t *bytes = serialize_sample(&s, &size);
    sw_pack pack;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_open_memory(bytes, size, &pack, &err) == SW_OK, "%s", err.message);
    SW_CHECK(pack.header->section_count == 5);
    SW_CHECK(!pack.surfaces && !pack.trim_loops && !pack.trim_curves && !pack.trim_data &&
             !pack.patch_domains && !pack.trim_masks && !pack.viewpoints && !pack.part_transforms);
    SW_CHECK(pack.surface_count == 0 && pack.trim_loop_count == 0 && pack.trim_curve_count == 0 &&
             pack.trim_data_count == 0 && pack.trim_mask_count == 0 && pack.viewpoint_count == 0);
    free(bytes);
}

static void test_runtime_bytes_formula(void)
{
    /* 64 slack and the walk; not the pack's own bytes. */
    SW_CHECK(sw_pack_runtime_bytes(0) == 64);
    SW_CHECK(sw_pack_runtime_bytes(1000) == 64 + 1000);
    SW_CHECK(sw_pack_runtime_bytes(UINT64_MAX) == UINT64_MAX);
    /* Copied into an arena: 100 bytes round up to 128, and 64 slack. */
    SW_CHECK(sw_pack_arena_bytes(100) == 128 + 64);
    SW_CHECK(sw_pack_arena_bytes(UINT64_MAX) == UINT64_MAX);
}

/* The header's runtime_bytes: less than the reader's formula is refused
 * (the runtime would size its arena short), more opens (a pack written when
 * the runtime took more keeps running after a firmware update). */
static void test_runtime_bytes_at_least_the_formula(void)
{
    sample s;
    make_sample(&s);
    size_t size = 0;
    uint8_t *bytes = serialize_sample(&s, &size);
    uint64_t exact = header_of(bytes)->runtime_bytes;
    header_of(bytes)->runtime_bytes = exact - 1;
    reseal(bytes);
    sw_error err;
    SW_CHECK(open_bytes(bytes, size, &err) == SW_ERR_FORMAT);
    SW_CHECK_MSG(strstr(err.message, "header.runtime_bytes: ") &&
                 strstr(err.message, "expected at least"), "%s", err.message);
    header_of(bytes)->runtime_bytes = exact + 4096;
    reseal(bytes);
    SW_CHECK_MSG(open_bytes(bytes, size, &err) == SW_OK, "%s", err.message);
    free(bytes);
}

static void test_section_type_names(void)
{
    SW_CHECK(strcmp(sw_section_type_name(SW_SECTION_META), "META") == 0);
    SW_CHECK(strcmp(sw_section_type_name(SW_SECTION_ADJACENCY), "ADJACENCY") == 0);
    SW_CHECK(strcmp(sw_section_type_name(SW_SECTION_SURFACES), "SURFACES") == 0);
    SW_CHECK(strcmp(sw_section_type_name(SW_SECTION_PATCH_DOMAINS), "PATCH_DOMAINS") == 0);
    SW_CHECK(strcmp(sw_section_type_name(SW_SECTION_PART_TRANSFORMS), "PART_TRANSFORMS") == 0);
    SW_CHECK(strcmp(sw_section_type_name(SW_SECTION_SEAM), "SEAM") == 0);
    SW_CHECK(strcmp(sw_section_type_name(SW_SECTION_SEAM_SURFACE_LOOPS), "SEAM_SURFACE_LOOPS") ==
             0);
    SW_CHECK(strcmp(sw_section_type_name(22), "unknown") == 0);
    SW_CHECK(strcmp(sw_section_type_name(0), "unknown") == 0);
    SW_CHECK(strcmp(sw_section_type_name(99), "unknown") == 0);
}

/* ---- corruption of the container ---- */

static void test_every_truncation_is_rejected(void)
{
    sample s;
    make_sample(&s);
    size_t size = 0;
    uint8_t *bytes = serialize_sample(&s, &size);
    int bad = 0;
    for (size_t n = 0; n < size; n++) {
        sw_error err;
        if (open_bytes(bytes, n, &err) == SW_OK || err.message[0] == '\0')
            bad++;
    }
    SW_CHECK_MSG(bad == 0, "%d of %zu truncations accepted or unexplained", bad, size);
    sw_error err;
    SW_CHECK(open_bytes(bytes, 1000, &err) == SW_ERR_FORMAT);
    SW_CHECK_MSG(strstr(err.message, "header.total_size") && strstr(err.message, "truncated"),
                 "%s", err.message);
    free(bytes);
}

static void test_flipped_byte_in_each_section_names_it(void)
{
    sample s;
    make_sample(&s);
    size_t size = 0;
    uint8_t *bytes = serialize_sample(&s, &size);
    const sw_pack_section *table = table_of(bytes);
    for (uint32_t i = 0; i < header_of(bytes)->section_count; i++) {
        if (table[i].size == 0)
            continue;
        uint64_t at[3] = { table[i].offset, table[i].offset + table[i].size / 2,
                           table[i].offset + table[i].size - 1 };
        char name[32];
        snprintf(name, sizeof name, "(%s): checksum mismatch", sw_section_type_name(table[i].type));
        for (int k = 0; k < 3; k++) {
            bytes[at[k]] ^= 0x10;
            sw_error err;
            sw_status st = open_bytes(bytes, size, &err);
            SW_CHECK_MSG(st == SW_ERR_CHECKSUM && strstr(err.message, name),
                         "byte %llu: %s", (unsigned long long)at[k], err.message);
            bytes[at[k]] ^= 0x10;
        }
    }
    free(bytes);
}

static void test_flipped_byte_in_header_or_table_is_rejected(void)
{
    sample s;
    make_sample(&s);
    size_t size = 0;
    uint8_t *bytes = serialize_sample(&s, &size);
    for (size_t at = 0; at < 64 + SAMPLE_SECTIONS * 32; at++) {
        bytes[at] ^= 0x01;
        sw_error err;
        sw_status st = open_bytes(bytes, size, &err);
        SW_CHECK_MSG(st != SW_OK && strncmp(err.message, "header.", 7) == 0, "byte %zu: %s", at,
                     err.message);
        bytes[at] ^= 0x01;
    }
    sw_error err;
    SW_CHECK(open_bytes(bytes, size, &err) == SW_OK);
    free(bytes);
}

static void test_bad_magic_is_rejected(void)
{
    sample s;
    make_sample(&s);
    size_t size = 0;
    uint8_t *bytes = serialize_sample(&s, &size);
    memcpy(bytes, "SWPACK\n\n", 8); /* what a text-mode transfer might make of it */
    reseal(bytes);
    sw_error err;
    SW_CHECK(open_bytes(bytes, size, &err) == SW_ERR_FORMAT);
    SW_CHECK_MSG(strstr(err.message, "header.magic"), "%s", err.message);
    free(bytes);
}

static void test_bad_version_is_rejected(void)
{
    sample s;
    make_sample(&s);
    size_t size = 0;
    uint8_t *bytes = serialize_sample(&s, &size);
    header_of(bytes)->version = 7;
    reseal(bytes);
    sw_error err;
    SW_CHECK(open_bytes(bytes, size, &err) == SW_ERR_VERSION);
    SW_CHECK_MSG(strcmp(err.message, "header.version: 7, this build reads versions 1 and 2") == 0, "%s",
                 err.message);
    free(bytes);
}

static void test_bad_byte_order_is_rejected(void)
{
    sample s;
    make_sample(&s);
    size_t size = 0;
    uint8_t *bytes = serialize_sample(&s, &size);
    header_of(bytes)->byte_order = 0x04030201u;
    reseal(bytes);
    sw_error err;
    SW_CHECK(open_bytes(bytes, size, &err) == SW_ERR_FORMAT);
    SW_CHECK_MSG(strstr(err.message, "header.byte_order") && strstr(err.message, "big-endian"),
                 "%s", err.message);
    free(bytes);
}

static void test_misaligned_data_is_an_argument_error(void)
{
    sample s;
    make_sample(&s);
    size_t size = 0;
    uint8_t *bytes = serialize_sample(&s, &size);
    uint8_t *shifted = malloc(size + 8);
    memcpy(shifted + 4, bytes, size);
    sw_error err;
    SW_CHECK(open_bytes(shifted + 4, size, &err) == SW_ERR_ARG);
    SW_CHECK_MSG(strstr(err.message, "8-byte aligned"), "%s", err.message);
    free(shifted);
    free(bytes);
}

/* Two problems: the first section in table order is named, whichever
 * kind each is (its bounds are checked before any checksum is computed,
 * and the checksums may be computed in any order). */
static void test_first_problem_in_table_order_is_named(void)
{
    sample s;
    make_sample(&s);
    size_t size = 0;
    uint8_t *bytes = serialize_sample(&s, &size);
    sw_pack_section *t = table_of(bytes);
    sw_error err;
    bytes[t[5].offset] ^= 1;
    bytes[t[2].offset] ^= 1;
    SW_CHECK(open_bytes(bytes, size, &err) == SW_ERR_CHECKSUM);
    SW_CHECK_MSG(strstr(err.message, "section 2 (PATCHES): checksum mismatch"), "%s",
                 err.message);
    bytes[t[2].offset] ^= 1;   /* 5's checksum still fails, after 4's flags */
    t[4].flags = 1;
    reseal(bytes);
    SW_CHECK(open_bytes(bytes, size, &err) == SW_ERR_FORMAT);
    SW_CHECK_MSG(strstr(err.message, "section 4 (ADJACENCY): flags 0x1"), "%s", err.message);
    bytes[t[1].offset] ^= 1;   /* 1's checksum now fails before 4's flags */
    SW_CHECK(open_bytes(bytes, size, &err) == SW_ERR_CHECKSUM);
    SW_CHECK_MSG(strstr(err.message, "section 1 (PARTS): checksum mismatch"), "%s", err.message);
    free(bytes);
}

/* Edits one table entry, reseals, and expects a message naming the rule. */
static void expect_table_edit_rejected(int entry, const sw_pack_section *edit, const char *needle)
{
    sample s;
    make_sample(&s);
    size_t size = 0;
    uint8_t *bytes = serialize_sample(&s, &size);
    table_of(bytes)[entry] = *edit;
    reseal(bytes);
    sw_error err;
    SW_CHECK_MSG(open_bytes(bytes, size, &err) != SW_OK && strstr(err.message, needle),
                 "\"%s\" not in \"%s\"", needle, err.message);
    free(bytes);
}

static void test_section_table_rules(void)
{
    sample s;
    make_sample(&s);
    size_t size = 0;
    uint8_t *bytes = serialize_sample(&s, &size);
    const sw_pack_section *t = table_of(bytes);
    sw_pack_section e = t[2];
    e.offset += 8;
    expect_table_edit_rejected(2, &e, "section 2 (PATCHES): offset");
    e = t[2];
    e.offset = 0;
    expect_table_edit_rejected(2, &e, "lies in the header or section table");
    e = t[4];
    e.size = size;
    expect_table_edit_rejected(4, &e, "section 4 (ADJACENCY): offset");
    e = t[1];
    e.flags = 1;
    expect_table_edit_rejected(1, &e, "section 1 (PARTS): flags 0x1");
    e = t[3];
    e.offset = t[2].offset; /* CONTROL on top of PATCHES, checksum made valid */
    e.size = t[2].size;
    e.checksum = t[2].checksum;
    expect_table_edit_rejected(3, &e, "overlap");
    e = t[1];
    e.type = SW_SECTION_META;
    expect_table_edit_rejected(1, &e, "a second META section");
    e = t[1];
    e.type = 77;
    expect_table_edit_rejected(1, &e, "no PARTS section");
    e = t[4];
    e.type = 77; /* ADJACENCY gone while META still counts one */
    expect_table_edit_rejected(4, &e, "META.adjacency_count: 1, but there is no ADJACENCY");
    free(bytes);
}

static void test_section_size_must_match_meta_count(void)
{
    sample s;
    make_sample(&s);
    size_t size = 0;
    uint8_t *bytes = serialize_sample(&s, &size);
    /* META claims one point more than CONTROL holds; META's checksum is valid. */
    sw_pack_meta *meta = (sw_pack_meta *)(bytes + table_of(bytes)[0].offset);
    meta->control_count = SAMPLE_CONTROL + 1;
    table_of(bytes)[0].checksum = XXH3_64bits(meta, sizeof *meta);
    reseal(bytes);
    sw_error err;
    SW_CHECK(open_bytes(bytes, size, &err) == SW_ERR_FORMAT);
    SW_CHECK_MSG(strstr(err.message, "section 3 (CONTROL): 656 bytes, expected META.control_count"),
                 "%s", err.message);
    free(bytes);
}

/* ---- records: every index, with valid checksums ---- */

static void test_patch_first_control_out_of_range(void)
{
    sample s;
    make_sample(&s);
    s.patches[2].first_control = 30; /* 30 + 16 points > 41 */
    expect_rejected(&s, SW_ERR_RANGE,
                    "PATCHES[2].first_control: 30 + 16 points exceeds CONTROL count 41");
    s.patches[2].first_control = UINT32_MAX; /* must not wrap around */
    expect_rejected(&s, SW_ERR_RANGE, "PATCHES[2].first_control: 4294967295 + 16 points");
}

static void test_patch_part_out_of_range(void)
{
    sample s;
    make_sample(&s);
    s.patches[1].part = 2;
    expect_rejected(&s, SW_ERR_RANGE, "PATCHES[1].part: 2, but PARTS has 2 entries");
}

static void test_patch_outside_its_parts_range(void)
{
    sample s;
    make_sample(&s);
    s.patches[1].part = 1; /* part 1 holds only patch 2 */
    expect_rejected(&s, SW_ERR_RANGE, "PATCHES[1].part: 1, but that part holds patches [2, 3)");
}

static void test_part_range_out_of_range(void)
{
    sample s;
    make_sample(&s);
    s.parts[1].patch_count = 2; /* patches 2..3 of 3 */
    expect_rejected(&s, SW_ERR_RANGE,
                    "PARTS[1].first_patch: 2 + patch_count 2 exceeds PATCHES count 3");
    s.parts[1].first_patch = UINT32_MAX; /* must not wrap around */
    expect_rejected(&s, SW_ERR_RANGE, "PARTS[1].first_patch: 4294967295");
}

static void test_adjacency_patch_out_of_range(void)
{
    sample s;
    make_sample(&s);
    s.adjacency[0].patch_b = 3;
    expect_rejected(&s, SW_ERR_RANGE, "ADJACENCY[0].patch_b: 3, but PATCHES has 3 entries");
    s.adjacency[0].patch_b = 0; /* a patch next to itself */
    expect_rejected(&s, SW_ERR_FORMAT, "ADJACENCY[0].patch_b: 0, the same as patch_a");
}

static void test_adjacency_edge_out_of_range(void)
{
    sample s;
    make_sample(&s);
    s.adjacency[0].edge_a = 4;
    expect_rejected(&s, SW_ERR_RANGE, "ADJACENCY[0].edge_a: 4, expected 0..3");
    make_sample(&s);
    s.adjacency[0].patch_b = 1; /* 4-point edge against a 3-point edge */
    expect_rejected(&s, SW_ERR_FORMAT, "ADJACENCY[0].edge_b: patch 0 edge 1 has 4 points");
}

static void test_record_fields_out_of_range(void)
{
    sample s;
    make_sample(&s);
    s.patches[0].degree_v = 16;
    expect_rejected(&s, SW_ERR_FORMAT, "PATCHES[0].degree: 3 x 16");
    make_sample(&s);
    s.patches[0].flags = 0x8;
    expect_rejected(&s, SW_ERR_FORMAT, "PATCHES[0].flags: 0x8");
    make_sample(&s);
    s.patches[2].box_max[1] = 0.5f; /* the hull reaches y = 1 */
    expect_rejected(&s, SW_ERR_FORMAT, "PATCHES[2].box: control point");
    make_sample(&s);
    s.meta.box_max[0] = NAN;
    expect_rejected(&s, SW_ERR_FORMAT, "META.box: x range 0..nan is not finite");
    make_sample(&s);
    s.meta.box_max[2] = 0.1f; /* patch 0 reaches z = 0.3 */
    expect_rejected(&s, SW_ERR_FORMAT, "PATCHES[0].box: z range 0..0.3 is outside META's");
    make_sample(&s);
    s.patches[1].box_min[0] = 2.0f;
    expect_rejected(&s, SW_ERR_FORMAT, "PATCHES[1].box: box_min.x 2 > box_max.x 1");
    make_sample(&s);
    s.patches[2].d2_bound[2] = -1.0f;
    expect_rejected(&s, SW_ERR_FORMAT, "PATCHES[2].d2_bound[2]: -1");
    make_sample(&s);
    s.parts[0].color[3] = 1.5f;
    expect_rejected(&s, SW_ERR_FORMAT, "PARTS[0].color[3]: 1.5");
    make_sample(&s);
    memset(s.parts[0].name, 'a', sizeof s.parts[0].name);
    expect_rejected(&s, SW_ERR_FORMAT, "PARTS[0].name: no NUL");
    make_sample(&s);
    strcpy(s.parts[0].name, "caf\xe9"); /* Latin-1, not UTF-8 */
    expect_rejected(&s, SW_ERR_FORMAT, "PARTS[0].name: invalid UTF-8 at byte 3");
    make_sample(&s);
    s.meta.units = 3;
    expect_rejected(&s, SW_ERR_FORMAT, "META.units: 3");
    make_sample(&s);
    s.meta.model_tolerance = -1.0f;
    expect_rejected(&s, SW_ERR_FORMAT, "META.model_tolerance");
    make_sample(&s);
    s.adjacency[0].reserved = 1;
    expect_rejected(&s, SW_ERR_FORMAT, "ADJACENCY[0].reserved: 1");
}

static void test_non_finite_control_is_rejected(void)
{
    sample s;
    make_sample(&s);
    s.control[5 * 4 + 1] = NAN;
    expect_rejected(&s, SW_ERR_FORMAT, "CONTROL[5].y: nan, expected a finite number");
    make_sample(&s);
    s.control[40 * 4 + 2] = INFINITY;
    expect_rejected(&s, SW_ERR_FORMAT, "CONTROL[40].z: inf");
}

static void test_zero_weight_of_rational_patch_is_rejected(void)
{
    sample s;
    make_sample(&s);
    s.control[(16 + 3) * 4 + 3] = 0.0f;
    expect_rejected(&s, SW_ERR_RANGE, "CONTROL[19].w: 0, but rational PATCHES[1] needs weights > 0");
    make_sample(&s);
    s.control[2 * 4 + 3] = 2.0f; /* patch 0 is polynomial */
    expect_rejected(&s, SW_ERR_FORMAT, "CONTROL[2].w: 2, but non-rational PATCHES[0]");
}

static void test_unknown_section_is_skipped(void)
{
    sample s;
    make_sample(&s);
    size_t size = 0, grown_size = 0;
    uint8_t *bytes = serialize_sample(&s, &size);
    uint8_t *grown = add_unknown_section(bytes, size, &grown_size);
    sw_pack pack;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_open_memory(grown, grown_size, &pack, &err) == SW_OK, "%s", err.message);
    SW_CHECK(pack.header->section_count == SAMPLE_SECTIONS + 1);
    SW_CHECK(memcmp(pack.patches, s.patches, sizeof s.patches) == 0);
    /* Skipped, but still checked: its bytes are covered by its checksum. */
    grown[grown_size - 1] ^= 1;
    SW_CHECK(sw_pack_open_memory(grown, grown_size, &pack, &err) == SW_ERR_CHECKSUM);
    SW_CHECK_MSG(strstr(err.message, "section 13 (type 99): checksum mismatch"), "%s", err.message);
    free(grown);
    free(bytes);
}

static void test_pack_without_adjacency_section_opens(void)
{
    sample s;
    make_sample(&s);
    s.meta.adjacency_count = 0;
    size_t size = 0;
    uint8_t *bytes = serialize_sample(&s, &size);
    table_of(bytes)[4].type = 99; /* the empty ADJACENCY becomes an unknown section */
    reseal(bytes);
    sw_pack pack;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_open_memory(bytes, size, &pack, &err) == SW_OK, "%s", err.message);
    SW_CHECK(pack.adjacency == NULL && pack.meta->adjacency_count == 0);
    free(bytes);
}

/* ---- files ---- */

/* The sample pack written to scratch file name: its bytes (the caller
 * frees them) and its path in path (256 bytes). */
static uint8_t *write_sample(sample *s, const char *name, char *path, size_t *size)
{
    make_sample(s);
    uint8_t *bytes = serialize_sample(s, size);
    snprintf(path, 256, "%s", scratch(name));
    write_plain(path, bytes, *size);
    return bytes;
}

static void test_load_into_small_arena_fails_cleanly(void)
{
    sample s;
    size_t size = 0;
    char path[256];
    uint8_t *bytes = write_sample(&s, "sample.swpack", path, &size);
    static _Alignas(64) unsigned char block[8192];
    sw_arena arena;
    sw_arena_init(&arena, block, size / 2);
    sw_pack pack;
    sw_error err = { 0 };
    SW_CHECK(sw_pack_load(path, &arena, &pack, &err) == SW_ERR_NO_MEMORY);
    SW_CHECK_MSG(strncmp(err.message, path, strlen(path)) == 0 && strstr(err.message, "arena"),
                 "%s", err.message);
    SW_CHECK(arena.used == 0);
    /* sw_pack_arena_bytes is enough, by definition. */
    SW_CHECK(sw_pack_arena_bytes(size) <= sizeof block);
    sw_arena_init(&arena, block, (size_t)sw_pack_arena_bytes(size));
    SW_CHECK_MSG(sw_pack_load(path, &arena, &pack, &err) == SW_OK, "%s", err.message);
    SW_CHECK(pack.meta->patch_count == 3 && memcmp(pack.control, s.control, sizeof s.control) == 0);
    SW_CHECK(sw_pack_load(scratch("missing.swpack"), &arena, &pack, &err) == SW_ERR_IO);
    SW_CHECK_MSG(strstr(err.message, "missing.swpack: cannot open"), "%s", err.message);
    free(bytes);
}

static sw_status refuse_raw(void *user, const uint8_t *bytes, size_t size, sw_error *err)
{
    (void)bytes, (void)size;
    ++*(int *)user;
    return sw_error_set(err, SW_ERR_FORMAT, "not signed by a trusted key");
}

/* A file only root can write is mapped, not copied: the same pack as the
 * copy; anyone else's, or one group or others may write, is not; a
 * refused or broken one leaves nothing mapped. */
static void test_map_only_what_root_alone_writes(void)
{
    sample s;
    size_t size = 0;
    char path[256];
    uint8_t *bytes = write_sample(&s, "mapped.swpack", path, &size);
    sw_pack pack;
    sw_pack_mapping map;
    sw_error err = { 0 };
    if (geteuid() != 0) {   /* a file of ours: we could change it under the walk */
        SW_CHECK(!sw_pack_file_mappable(path));
        SW_CHECK(sw_pack_map_checked(path, NULL, NULL, NULL, &map, &pack, &err) == SW_ERR_IO);
        SW_CHECK_MSG(strstr(err.message, "only root can write"), "%s", err.message);
        SW_CHECK(map.base == NULL);
        free(bytes);
        return;
    }
    SW_CHECK(chmod(path, 0644) == 0 && sw_pack_file_mappable(path));
    SW_CHECK_MSG(sw_pack_map_checked(path, NULL, NULL, NULL, &map, &pack, &err) == SW_OK, "%s",
                 err.message);
    SW_CHECK(map.base && map.size == size && memcmp(map.base, bytes, size) == 0);
    SW_CHECK(pack.meta->patch_count == 3 && memcmp(pack.control, s.control, sizeof s.control) == 0);
    SW_CHECK((const uint8_t *)pack.control >= (const uint8_t *)map.base &&
             (const uint8_t *)pack.control < (const uint8_t *)map.base + size);
    sw_pack_unmap(&map);
    SW_CHECK(map.base == NULL);
    int calls = 0;   /* the raw check first, on the mapped bytes */
    SW_CHECK(sw_pack_map_checked(path, NULL, refuse_raw, &calls, &map, &pack, &err) ==
             SW_ERR_FORMAT);
    SW_CHECK_MSG(calls == 1 && strstr(err.message, path) && map.base == NULL, "%s", err.message);
    SW_CHECK(chmod(path, 0664) == 0 && !sw_pack_file_mappable(path));
    SW_CHECK(sw_pack_map_checked(path, NULL, NULL, NULL, &map, &pack, &err) == SW_ERR_IO);
    SW_CHECK_MSG(strstr(err.message, "mode 0664") && map.base == NULL, "%s", err.message);
    SW_CHECK(chmod(path, 0644) == 0 && chown(path, 12345, 0) == 0 &&
             !sw_pack_file_mappable(path));
    SW_CHECK(sw_pack_map_checked(path, NULL, NULL, NULL, &map, &pack, &err) == SW_ERR_IO);
    SW_CHECK_MSG(strstr(err.message, "owner 12345"), "%s", err.message);
    SW_CHECK(chown(path, 0, 0) == 0);
    bytes[size - 1] ^= 1;   /* a section's checksum no longer holds */
    write_plain(path, bytes, size);
    SW_CHECK(chmod(path, 0644) == 0);
    SW_CHECK(sw_pack_map_checked(path, NULL, NULL, NULL, &map, &pack, &err) == SW_ERR_CHECKSUM);
    SW_CHECK_MSG(strstr(err.message, path) && map.base == NULL, "%s", err.message);
    write_plain(path, bytes, 10);
    SW_CHECK(sw_pack_map_checked(path, NULL, NULL, NULL, &map, &pack, &err) == SW_ERR_FORMAT);
    SW_CHECK(sw_pack_map_checked(scratch("missing.swpack"), NULL, NULL, NULL, &map, &pack,
                                 &err) == SW_ERR_IO);
    free(bytes);
}

static void test_read_header_detects_short_file(void)
{
    sample s;
    make_sample(&s);
    size_t size = 0;
    uint8_t *bytes = serialize_sample(&s, &size);
    char path[256];
    snprintf(path, sizeof path, "%s", scratch("short.swpack"));
    write_plain(path, bytes, size - 100);
    sw_pack_header h;
    sw_error err = { 0 };
    SW_CHECK(sw_pack_read_header(path, &h, &err) == SW_ERR_FORMAT);
    char expected[512];
    snprintf(expected, sizeof expected, "%s: header.total_size: %zu, but the file is %zu bytes "
             "(truncated)", path, size, size - 100);
    SW_CHECK_MSG(strcmp(err.message, expected) == 0, "%s", err.message);
    write_plain(path, bytes, 40);
    SW_CHECK(sw_pack_read_header(path, &h, &err) == SW_ERR_FORMAT);
    SW_CHECK_MSG(strstr(err.message, "the file is 40 bytes"), "%s", err.message);
    write_plain(path, bytes, size);
    SW_CHECK_MSG(sw_pack_read_header(path, &h, &err) == SW_OK, "%s", err.message);
    SW_CHECK(h.total_size == size && h.runtime_bytes == header_of(bytes)->runtime_bytes);
    free(bytes);
}

int main(void)
{
    if (!mkdtemp(scratch_dir)) {
        perror("mkdtemp");
        return 1;
    }
    SW_RUN(test_round_trip_keeps_every_field);
    SW_RUN(test_round_trip_keeps_optional_sections);
    SW_RUN(test_bezier_only_pack_has_no_optional_views);
    SW_RUN(test_runtime_bytes_formula);
    SW_RUN(test_runtime_bytes_at_least_the_formula);
    SW_RUN(test_section_type_names);
    SW_RUN(test_every_truncation_is_rejected);
    SW_RUN(test_flipped_byte_in_each_section_names_it);
    SW_RUN(test_flipped_byte_in_header_or_table_is_rejected);
    SW_RUN(test_bad_magic_is_rejected);
    SW_RUN(test_bad_version_is_rejected);
    SW_RUN(test_bad_byte_order_is_rejected);
    SW_RUN(test_misaligned_data_is_an_argument_error);
    SW_RUN(test_section_table_rules);
    SW_RUN(test_section_size_must_match_meta_count);
    SW_RUN(test_patch_first_control_out_of_range);
    SW_RUN(test_patch_part_out_of_range);
    SW_RUN(test_patch_outside_its_parts_range);
    SW_RUN(test_part_range_out_of_range);
    SW_RUN(test_adjacency_patch_out_of_range);
    SW_RUN(test_adjacency_edge_out_of_range);
    SW_RUN(test_record_fields_out_of_range);
    SW_RUN(test_non_finite_control_is_rejected);
    SW_RUN(test_zero_weight_of_rational_patch_is_rejected);
    SW_RUN(test_unknown_section_is_skipped);
    SW_RUN(test_first_problem_in_table_order_is_named);
    SW_RUN(test_pack_without_adjacency_section_opens);
    SW_RUN(test_load_into_small_arena_fails_cleanly);
    SW_RUN(test_read_header_detects_short_file);
    SW_RUN(test_map_only_what_root_alone_writes);
    remove_scratch();
    return sw_test_finish();
}
