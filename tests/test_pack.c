/* The pack format, version 1: what the writer lays out, what the reader
 * accepts and, above all, what it refuses and how it says so.
 * Run with --write-corpus DIR to (re)write the fuzz seeds. */
#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <stdint.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#include <xxhash.h>

#include "sw_pack.h"
#include "sw_pack_write.h"
#include "sw_test.h"

/* ---- a small pack built by hand: 2 parts, 3 patches, 1 adjacency ---- */

enum { SAMPLE_CONTROL = 16 + 9 + 16 };

typedef struct sample {
    sw_pack_meta meta;
    sw_pack_part parts[2];
    sw_pack_patch patches[3];
    float control[SAMPLE_CONTROL * 4];
    sw_pack_adjacency adjacency[1];
} sample;

static void set_grid(float *ctrl, int du, int dv, float x0, float z_bump, float w_mid)
{
    for (int j = 0; j <= dv; j++)
        for (int i = 0; i <= du; i++) {
            float *c = &ctrl[(j * (du + 1) + i) * 4];
            c[0] = x0 + (float)i / (float)du;
            c[1] = (float)j / (float)dv;
            c[2] = (i > 0 && i < du && j > 0 && j < dv) ? z_bump : 0.0f;
            c[3] = (i == du / 2 && j == dv / 2) ? w_mid : 1.0f;
        }
}

/* Patch boxes from their control points, META's box from the patches. */
static void fit_boxes(sample *s)
{
    for (int p = 0; p < 3; p++) {
        sw_pack_patch *pp = &s->patches[p];
        int n = (pp->degree_u + 1) * (pp->degree_v + 1);
        for (int k = 0; k < 3; k++) {
            pp->box_min[k] = pp->box_max[k] = s->control[pp->first_control * 4 + k];
            for (int i = 1; i < n; i++) {
                float v = s->control[(pp->first_control + i) * 4 + k];
                pp->box_min[k] = v < pp->box_min[k] ? v : pp->box_min[k];
                pp->box_max[k] = v > pp->box_max[k] ? v : pp->box_max[k];
            }
            s->meta.box_min[k] = p == 0 || pp->box_min[k] < s->meta.box_min[k] ? pp->box_min[k]
                                                                               : s->meta.box_min[k];
            s->meta.box_max[k] = p == 0 || pp->box_max[k] > s->meta.box_max[k] ? pp->box_max[k]
                                                                               : s->meta.box_max[k];
        }
    }
}

static void make_sample(sample *s)
{
    memset(s, 0, sizeof *s);
    s->meta = (sw_pack_meta){ .part_count = 2, .patch_count = 3, .control_count = SAMPLE_CONTROL,
                              .adjacency_count = 1, .units = SW_UNITS_MILLIMETRE,
                              .model_tolerance = 0.01f };
    s->parts[0] = (sw_pack_part){ .first_patch = 0, .patch_count = 2,
                                  .color = { 0.8f, 0.1f, 0.1f, 1.0f }, .name = "body" };
    s->parts[1] = (sw_pack_part){ .first_patch = 2, .patch_count = 1,
                                  .color = { 0.2f, 0.2f, 0.9f, 0.5f }, .name = "lid \xc3\xa9" };
    s->patches[0] = (sw_pack_patch){ .first_control = 0, .degree_u = 3, .degree_v = 3,
                                     .part = 0, .d2_bound = { 1.0f, 0.5f, 2.0f } };
    s->patches[1] = (sw_pack_patch){ .first_control = 16, .degree_u = 2, .degree_v = 2,
                                     .flags = SW_PATCH_RATIONAL, .part = 0,
                                     .d2_bound = { 3.0f, 0.0f, 1.5f } };
    s->patches[2] = (sw_pack_patch){ .first_control = 25, .degree_u = 3, .degree_v = 3,
                                     .part = 1, .d2_bound = { 0.25f, 0.25f, 0.25f } };
    set_grid(&s->control[0], 3, 3, 0.0f, 0.3f, 1.0f);
    set_grid(&s->control[16 * 4], 2, 2, 0.0f, 0.5f, 0.7071f);
    set_grid(&s->control[25 * 4], 3, 3, 1.0f, -0.2f, 1.0f);
    s->adjacency[0] = (sw_pack_adjacency){ .patch_a = 0, .patch_b = 2, .edge_a = SW_EDGE_U1,
                                           .edge_b = SW_EDGE_U0 };
    fit_boxes(s);
}

static sw_pack_contents sample_contents(const sample *s)
{
    return (sw_pack_contents){ .meta = s->meta, .parts = s->parts, .patches = s->patches,
                               .control = s->control, .adjacency = s->adjacency };
}

/* Serialised sample; malloc'd, so 8-byte aligned as the reader requires. */
static uint8_t *serialize_sample(const sample *s, size_t *size)
{
    sw_pack_contents c = sample_contents(s);
    uint8_t *bytes = NULL;
    sw_error err = { 0 };
    sw_status st = sw_pack_serialize(&c, &bytes, size, &err);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    return bytes;
}

static sw_pack_header *header_of(uint8_t *bytes) { return (sw_pack_header *)bytes; }
static sw_pack_section *table_of(uint8_t *bytes) { return (sw_pack_section *)(bytes + 64); }

/* Recomputes the header checksum after a test edited the header or table,
 * so the check under test is the one that fires. */
static void reseal(uint8_t *bytes)
{
    sw_pack_header *h = header_of(bytes);
    h->header_checksum = 0;
    h->header_checksum = XXH3_64bits(bytes, 64 + (size_t)h->section_count * 32);
}

static sw_status open_bytes(const uint8_t *bytes, size_t size, sw_error *err)
{
    sw_pack pack;
    memset(err, 0, sizeof *err);
    return sw_pack_open_memory(bytes, size, &pack, err);
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
    SW_CHECK(pack.header->runtime_bytes == sw_pack_runtime_bytes(size, 3));
    SW_CHECK(pack.header->section_count == 5);
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
    }
    free(bytes);
}

static void test_runtime_bytes_formula(void)
{
    /* 100 bytes round up to 128, 10 patches x 16, 64 slack. */
    SW_CHECK(sw_pack_runtime_bytes(100, 10) == 128 + 160 + 64);
    SW_CHECK(sw_pack_runtime_bytes(128, 0) == 128 + 64);
    SW_CHECK(sw_pack_runtime_bytes(UINT64_MAX, 1) == UINT64_MAX);
}

static void test_section_type_names(void)
{
    SW_CHECK(strcmp(sw_section_type_name(SW_SECTION_META), "META") == 0);
    SW_CHECK(strcmp(sw_section_type_name(SW_SECTION_ADJACENCY), "ADJACENCY") == 0);
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
    for (int i = 0; i < 5; i++) {
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
    for (size_t at = 0; at < 64 + 5 * 32; at++) {
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
    SW_CHECK_MSG(strcmp(err.message, "header.version: 7, this build reads version 1") == 0, "%s",
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

/* ---- forward compatibility ---- */

/* Adds a 64-byte section of type 99 at the end. The sample's table ends at
 * byte 224 and its first section starts at 256, so a sixth entry fits
 * without moving anything. */
static uint8_t *add_unknown_section(const uint8_t *bytes, size_t size, size_t *new_size)
{
    size_t at = (size + 63) / 64 * 64;
    *new_size = at + 64;
    uint8_t *out = calloc(1, *new_size);
    memcpy(out, bytes, size);
    for (int i = 0; i < 64; i++)
        out[at + i] = (uint8_t)(0xA0 + i);
    sw_pack_header *h = header_of(out);
    table_of(out)[h->section_count] = (sw_pack_section){
        .type = 99, .offset = at, .size = 64, .checksum = XXH3_64bits(out + at, 64) };
    h->section_count++;
    h->total_size = *new_size;
    h->runtime_bytes = sw_pack_runtime_bytes(*new_size, 3);
    reseal(out);
    return out;
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
    SW_CHECK(pack.header->section_count == 6);
    SW_CHECK(memcmp(pack.patches, s.patches, sizeof s.patches) == 0);
    /* Skipped, but still checked: its bytes are covered by its checksum. */
    grown[grown_size - 1] ^= 1;
    SW_CHECK(sw_pack_open_memory(grown, grown_size, &pack, &err) == SW_ERR_CHECKSUM);
    SW_CHECK_MSG(strstr(err.message, "section 5 (type 99): checksum mismatch"), "%s", err.message);
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
    table_of(bytes)[4].type = 42; /* the empty ADJACENCY becomes an unknown section */
    reseal(bytes);
    sw_pack pack;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_open_memory(bytes, size, &pack, &err) == SW_OK, "%s", err.message);
    SW_CHECK(pack.adjacency == NULL && pack.meta->adjacency_count == 0);
    free(bytes);
}

/* ---- files ---- */

static char scratch_dir[] = "/tmp/test_pack-XXXXXX";

static const char *scratch(const char *name)
{
    static char path[256];
    snprintf(path, sizeof path, "%s/%s", scratch_dir, name);
    return path;
}

static void write_plain(const char *path, const void *bytes, size_t size)
{
    FILE *f = fopen(path, "wb");
    SW_CHECK_MSG(f && fwrite(bytes, 1, size, f) == size, "%s", path);
    if (f)
        fclose(f);
}

/* Whole file into a malloc'd buffer; NULL when it cannot be read. */
static char *read_plain(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    char *buf = malloc(1 << 20);
    *size = fread(buf, 1, 1 << 20, f);
    fclose(f);
    return buf;
}

static int file_holds(const char *path, const char *text)
{
    size_t n = 0;
    char *buf = read_plain(path, &n);
    int same = buf && n == strlen(text) && memcmp(buf, text, n) == 0;
    free(buf);
    return same;
}

/* Files in the scratch directory whose names contain ".tmp-". */
static int leftover_temp_files(void)
{
    int n = 0;
    DIR *d = opendir(scratch_dir);
    struct dirent *e;
    while (d && (e = readdir(d)))
        n += strstr(e->d_name, ".tmp-") != NULL;
    if (d)
        closedir(d);
    return n;
}

static void test_load_into_small_arena_fails_cleanly(void)
{
    sample s;
    make_sample(&s);
    size_t size = 0;
    uint8_t *bytes = serialize_sample(&s, &size);
    char path[256];
    snprintf(path, sizeof path, "%s", scratch("sample.swpack"));
    write_plain(path, bytes, size);
    static _Alignas(64) unsigned char block[8192];
    sw_arena arena;
    sw_arena_init(&arena, block, size / 2);
    sw_pack pack;
    sw_error err = { 0 };
    SW_CHECK(sw_pack_load(path, &arena, &pack, &err) == SW_ERR_NO_MEMORY);
    SW_CHECK_MSG(strncmp(err.message, path, strlen(path)) == 0 && strstr(err.message, "arena"),
                 "%s", err.message);
    SW_CHECK(arena.used == 0);
    /* runtime_bytes is enough, by definition. */
    SW_CHECK(header_of(bytes)->runtime_bytes <= sizeof block);
    sw_arena_init(&arena, block, (size_t)header_of(bytes)->runtime_bytes);
    SW_CHECK_MSG(sw_pack_load(path, &arena, &pack, &err) == SW_OK, "%s", err.message);
    SW_CHECK(pack.meta->patch_count == 3 && memcmp(pack.control, s.control, sizeof s.control) == 0);
    SW_CHECK(sw_pack_load(scratch("missing.swpack"), &arena, &pack, &err) == SW_ERR_IO);
    SW_CHECK_MSG(strstr(err.message, "missing.swpack: cannot open"), "%s", err.message);
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

static void test_write_atomic_replaces_existing_file(void)
{
    char path[256];
    snprintf(path, sizeof path, "%s", scratch("replace.bin"));
    write_plain(path, "old", 3);
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_write_file_atomic(path, (const uint8_t *)"new contents", 12, &err) == SW_OK,
                 "%s", err.message);
    SW_CHECK(file_holds(path, "new contents"));
    struct stat st;
    SW_CHECK(stat(path, &st) == 0 && (st.st_mode & 0777) == 0644);
    SW_CHECK(leftover_temp_files() == 0);
}

static void test_write_atomic_failure_leaves_existing_file(void)
{
    char keep[256], path[300];
    snprintf(keep, sizeof keep, "%s", scratch("keep.bin"));
    write_plain(keep, "old", 3);
    sw_error err = { 0 };
    /* The parent is a file: no temporary file can be made. */
    snprintf(path, sizeof path, "%s/child", keep);
    SW_CHECK(sw_write_file_atomic(path, (const uint8_t *)"new", 3, &err) == SW_ERR_IO);
    SW_CHECK_MSG(strstr(err.message, "temporary file"), "%s", err.message);
    SW_CHECK(file_holds(keep, "old"));
    /* The parent is missing. */
    SW_CHECK(sw_write_file_atomic(scratch("no/such/dir/x"), (const uint8_t *)"new", 3, &err) ==
             SW_ERR_IO);
    /* The target is a directory: the rename fails after the data was written. */
    SW_CHECK(mkdir(scratch("adir"), 0755) == 0);
    SW_CHECK(sw_write_file_atomic(scratch("adir"), (const uint8_t *)"new", 3, &err) == SW_ERR_IO);
    SW_CHECK_MSG(strstr(err.message, "rename"), "%s", err.message);
    struct stat st;
    SW_CHECK(stat(scratch("adir"), &st) == 0 && S_ISDIR(st.st_mode));
    SW_CHECK(leftover_temp_files() == 0);
}

/* A write that fails half-way (file size limit, works as root too) must not
 * touch the existing file and must not leave the temporary file behind. */
static void test_write_atomic_failed_write_leaves_existing_file(void)
{
    char keep[256];
    snprintf(keep, sizeof keep, "%s", scratch("limited.bin"));
    write_plain(keep, "old", 3);
    struct rlimit saved;
    SW_CHECK(getrlimit(RLIMIT_FSIZE, &saved) == 0);
    struct rlimit small = { .rlim_cur = 4096, .rlim_max = saved.rlim_max };
    signal(SIGXFSZ, SIG_IGN); /* so write returns EFBIG instead of killing us */
    SW_CHECK(setrlimit(RLIMIT_FSIZE, &small) == 0);
    uint8_t *big = calloc(1, 65536);
    sw_error err = { 0 };
    sw_status st = sw_write_file_atomic(keep, big, 65536, &err);
    setrlimit(RLIMIT_FSIZE, &saved);
    signal(SIGXFSZ, SIG_DFL);
    SW_CHECK(st == SW_ERR_IO);
    SW_CHECK_MSG(strstr(err.message, "write failed after 4096 of 65536 bytes"), "%s", err.message);
    SW_CHECK(file_holds(keep, "old"));
    SW_CHECK(leftover_temp_files() == 0);
    free(big);
}

static void remove_scratch(void)
{
    DIR *d = opendir(scratch_dir);
    struct dirent *e;
    while (d && (e = readdir(d)))
        if (e->d_name[0] != '.' && unlink(scratch(e->d_name)) != 0 && errno == EISDIR)
            rmdir(scratch(e->d_name));
    if (d)
        closedir(d);
    rmdir(scratch_dir);
}

/* ---- adjacency from a model ---- */

/* Bicubic patch over [x0, x0+1] x [y0, y0+1] on the surface z = 0.2xy + dz;
 * flip_v runs v downwards, so its u = 0 and u = 1 edges are reversed. */
static void add_bicubic(sw_model *model, double x0, double y0, double dz, int flip_v)
{
    double ctrl[16 * 4];
    for (int j = 0; j < 4; j++)
        for (int i = 0; i < 4; i++) {
            double *c = &ctrl[(j * 4 + i) * 4];
            c[0] = x0 + i / 3.0;
            c[1] = y0 + (flip_v ? 3 - j : j) / 3.0;
            c[2] = 0.2 * c[0] * c[1] + dz;
            c[3] = 1.0;
        }
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_model_add_patch(model, 3, 3, 0, ctrl, &err) == SW_OK, "%s", err.message);
}

/* Runs the writer's model conversion; returns the adjacency count. */
static uint32_t adjacency_of(const sw_model *model, sw_pack_adjacency *first)
{
    sw_pack_contents c;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_contents_from_model(model, &c, &err) == SW_OK, "%s", err.message);
    uint32_t n = c.meta.adjacency_count;
    if (n > 0 && first)
        *first = c.adjacency[0];
    sw_pack_contents_free(&c);
    return n;
}

static void start_model(sw_model *model)
{
    sw_model_init(model);
    sw_error err = { 0 };
    const float grey[4] = { 0.5f, 0.5f, 0.5f, 1.0f };
    SW_CHECK_MSG(sw_model_begin_part(model, "part", grey, &err) == SW_OK, "%s", err.message);
}

static void test_adjacency_finds_shared_edge(void)
{
    sw_model model;
    start_model(&model);
    add_bicubic(&model, 0, 0, 0, 0);
    add_bicubic(&model, 1, 0, 0, 0);
    sw_pack_adjacency a = { 0 };
    SW_CHECK(adjacency_of(&model, &a) == 1);
    SW_CHECK(a.patch_a == 0 && a.edge_a == SW_EDGE_U1 && a.patch_b == 1 &&
             a.edge_b == SW_EDGE_U0 && a.reversed == 0);
    sw_model_free(&model);
}

static void test_adjacency_finds_reversed_edge(void)
{
    sw_model model;
    start_model(&model);
    add_bicubic(&model, 0, 0, 0, 0);
    add_bicubic(&model, 1, 0, 0, 1); /* right neighbour, its v running down */
    sw_pack_adjacency a = { 0 };
    SW_CHECK(adjacency_of(&model, &a) == 1);
    SW_CHECK(a.patch_a == 0 && a.edge_a == SW_EDGE_U1 && a.patch_b == 1 &&
             a.edge_b == SW_EDGE_U0 && a.reversed == 1);
    sw_model_free(&model);
    /* The neighbour above with v running down meets patch 0 with its own
     * v = 1 row (y = 1), u running the same way: V1 against V1, not reversed. */
    start_model(&model);
    add_bicubic(&model, 0, 0, 0, 0);
    add_bicubic(&model, 0, 1, 0, 1);
    SW_CHECK(adjacency_of(&model, &a) == 1);
    SW_CHECK(a.patch_a == 0 && a.edge_a == SW_EDGE_V1 && a.patch_b == 1 &&
             a.edge_b == SW_EDGE_V1 && a.reversed == 0);
    sw_model_free(&model);
}

static void test_adjacency_skips_collapsed_edges(void)
{
    sw_model model;
    start_model(&model);
    /* Two bilinear triangles whose v = 1 edges both collapse to one pole,
     * as the patches around the teapot's lid knob do. */
    const double pole[3] = { 1.5, 1.5, 1.0 };
    for (int p = 0; p < 2; p++) {
        double ctrl[4 * 4] = { 2.0 * p, 0, 0, 1, 2.0 * p + 1, 0, 0, 1,
                               pole[0], pole[1], pole[2], 1, pole[0], pole[1], pole[2], 1 };
        sw_error err = { 0 };
        SW_CHECK_MSG(sw_model_add_patch(&model, 1, 1, 0, ctrl, &err) == SW_OK, "%s", err.message);
    }
    SW_CHECK(adjacency_of(&model, NULL) == 0);
    sw_model_free(&model);
}

static void test_adjacency_ignores_patches_apart(void)
{
    sw_model model;
    start_model(&model);
    add_bicubic(&model, 0, 0, 0, 0);
    add_bicubic(&model, 1, 0, 1e-6, 0); /* a gap of ~5e-7 of the diagonal */
    SW_CHECK(adjacency_of(&model, NULL) == 0);
    sw_model_free(&model);
    start_model(&model);
    add_bicubic(&model, 0, 0, 0, 0);
    add_bicubic(&model, 1, 0, 1e-11, 0); /* well inside 1e-9 of the diagonal */
    SW_CHECK(adjacency_of(&model, NULL) == 1);
    sw_model_free(&model);
}

static void test_adjacency_compares_weights(void)
{
    sw_model model;
    start_model(&model);
    double ctrl[4 * 4] = { 0, 0, 0, 1, 1, 0, 0, 1, 0, 1, 0, 1, 1, 1, 0, 1 };
    sw_error err = { 0 };
    SW_CHECK(sw_model_add_patch(&model, 1, 1, 1, ctrl, &err) == SW_OK);
    double right[4 * 4] = { 1, 0, 0, 2, 2, 0, 0, 1, 1, 1, 0, 1, 2, 1, 0, 1 };
    SW_CHECK(sw_model_add_patch(&model, 1, 1, 1, right, &err) == SW_OK);
    SW_CHECK(adjacency_of(&model, NULL) == 0); /* same positions, weight 2 against 1 */
    sw_model_free(&model);
    right[3] = 1;
    start_model(&model);
    SW_CHECK(sw_model_add_patch(&model, 1, 1, 1, ctrl, &err) == SW_OK);
    SW_CHECK(sw_model_add_patch(&model, 1, 1, 1, right, &err) == SW_OK);
    SW_CHECK(adjacency_of(&model, NULL) == 1);
    sw_model_free(&model);
}

/* A 250 x 400 grid of bilinear patches: 100,000 patches, every inner edge
 * shared once. Proves the candidate search is not quadratic. */
static void test_adjacency_scales_to_100k_patches(void)
{
    enum { NX = 250, NY = 400 };
    sw_model model;
    start_model(&model);
    sw_error err = { 0 };
    for (int y = 0; y < NY; y++)
        for (int x = 0; x < NX; x++) {
            double ctrl[16] = { x, y, 0, 1, x + 1, y, 0, 1, x, y + 1, 0, 1, x + 1, y + 1, 0, 1 };
            if (sw_model_add_patch(&model, 1, 1, 0, ctrl, &err) != SW_OK)
                break;
        }
    SW_CHECK(model.patch_count == NX * NY);
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    uint32_t n = adjacency_of(&model, NULL);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    double seconds = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    SW_CHECK_MSG(n == (NX - 1) * NY + NX * (NY - 1), "%u pairs", n);
    SW_CHECK_MSG(seconds < 30.0, "%.1f s", seconds); /* quadratic would take hours */
    printf("     100,000 patches: %u adjacencies in %.2f s\n", n, seconds);
    sw_model_free(&model);
}

static void test_model_pack_opens_and_matches_model(void)
{
    sw_model model;
    start_model(&model);
    add_bicubic(&model, 0, 0, 0, 0);
    add_bicubic(&model, 1, 0, 0, 1);
    sw_pack_contents c;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_contents_from_model(&model, &c, &err) == SW_OK, "%s", err.message);
    uint8_t *bytes = NULL;
    size_t size = 0;
    SW_CHECK(sw_pack_serialize(&c, &bytes, &size, &err) == SW_OK);
    sw_pack pack;
    SW_CHECK_MSG(sw_pack_open_memory(bytes, size, &pack, &err) == SW_OK, "%s", err.message);
    SW_CHECK(pack.meta->patch_count == 2 && pack.meta->control_count == 32);
    SW_CHECK(pack.meta->adjacency_count == 1 && pack.adjacency[0].reversed == 1);
    SW_CHECK(pack.patches[1].first_control == 16 && pack.patches[1].box_min[0] == 1.0f);
    SW_CHECK(pack.meta->box_max[0] == 2.0f && pack.meta->box_max[1] == 1.0f);
    for (int k = 0; k < 64; k++)
        SW_CHECK(pack.control[k] == (float)model.patches[0].ctrl[k]);
    SW_CHECK(strcmp(pack.parts[0].name, "part") == 0 && pack.parts[0].patch_count == 2);
    free(bytes);
    sw_pack_contents_free(&c);
    sw_model_free(&model);
}

/* ---- fuzz seeds ---- */

static int write_corpus(const char *dir)
{
    sample s;
    make_sample(&s);
    size_t size = 0, grown_size = 0;
    uint8_t *bytes = serialize_sample(&s, &size);
    uint8_t *grown = add_unknown_section(bytes, size, &grown_size);
    char path[512];
    snprintf(path, sizeof path, "%s/sample.swpack", dir);
    write_plain(path, bytes, size);
    snprintf(path, sizeof path, "%s/unknown-section.swpack", dir);
    write_plain(path, grown, grown_size);
    free(grown);
    free(bytes);
    sw_model model;
    start_model(&model);
    add_bicubic(&model, 0, 0, 0, 0);
    add_bicubic(&model, 1, 0, 0, 1);
    sw_pack_contents c;
    sw_error err = { 0 };
    if (sw_pack_contents_from_model(&model, &c, &err) != SW_OK ||
        sw_pack_serialize(&c, &bytes, &size, &err) != SW_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    snprintf(path, sizeof path, "%s/two-patches.swpack", dir);
    write_plain(path, bytes, size);
    free(bytes);
    sw_pack_contents_free(&c);
    sw_model_free(&model);
    return sw_test_failures ? 1 : 0;
}

int main(int argc, char **argv)
{
    if (argc == 3 && strcmp(argv[1], "--write-corpus") == 0)
        return write_corpus(argv[2]);
    if (!mkdtemp(scratch_dir)) {
        perror("mkdtemp");
        return 1;
    }
    SW_RUN(test_round_trip_keeps_every_field);
    SW_RUN(test_runtime_bytes_formula);
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
    SW_RUN(test_pack_without_adjacency_section_opens);
    SW_RUN(test_load_into_small_arena_fails_cleanly);
    SW_RUN(test_read_header_detects_short_file);
    SW_RUN(test_write_atomic_replaces_existing_file);
    SW_RUN(test_write_atomic_failure_leaves_existing_file);
    SW_RUN(test_write_atomic_failed_write_leaves_existing_file);
    SW_RUN(test_adjacency_finds_shared_edge);
    SW_RUN(test_adjacency_finds_reversed_edge);
    SW_RUN(test_adjacency_skips_collapsed_edges);
    SW_RUN(test_adjacency_ignores_patches_apart);
    SW_RUN(test_adjacency_compares_weights);
    SW_RUN(test_adjacency_scales_to_100k_patches);
    SW_RUN(test_model_pack_opens_and_matches_model);
    remove_scratch();
    return sw_test_finish();
}
