/* SPDX-License-Identifier: MIT */
/* The static levels in the pack: the sample's hand-built levels over its
 * Seam Graph (pack_sample.h) written and read back identical; which level
 * sections must appear together and how their sizes are checked; one
 * refusal per validation rule, each made by breaking one field of an
 * otherwise valid pack whose checksums are all recomputed, so the rule
 * under test is the one that fires, and each also opened with the checks'
 * parts run backwards; the info report's level lines. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <xxhash.h>

#include "sw_test.h"
#include "pack_sample.h"
#include "pack_expect.h"
#include "sw_pack_info.h"

/* The sample with its graph and levels l (NULL: none), serialised; malloc'd. */
static uint8_t *serialize_with_levels(const sample_levels *l, size_t *size)
{
    return serialize_sample_with(l ? &l->view : NULL, NULL, size);
}

/* The sample with the (edited) levels l must be refused with status and needle. */
static void expect_rejected(const sample_levels *l, sw_status status, const char *needle)
{
    size_t size = 0;
    uint8_t *bytes = serialize_with_levels(l, &size);
    expect_open(bytes, size, status, needle);
    free(bytes);
}

/* Fresh sample levels to break one field of. */
static sample_levels *fresh(sample_levels *l)
{
    make_sample_levels(l);
    return l;
}

/* Serialises the sample with its levels, lets edit change any bytes (table
 * or sections), recomputes every checksum and expects status and needle. */
static void expect_bytes_rejected(void (*edit)(uint8_t *bytes), sw_status status,
                                  const char *needle)
{
    sample_levels l;
    make_sample_levels(&l);
    size_t size = 0;
    uint8_t *bytes = serialize_with_levels(&l, &size);
    edit(bytes);
    reseal_all(bytes);
    expect_open(bytes, size, status, needle);
    free(bytes);
}

static sw_pack_levels *levels_record_of(uint8_t *b)
{
    return (sw_pack_levels *)(b + table_of(b)[entry_of(b, SW_SECTION_LEVELS)].offset);
}

/* ---- round trip ---- */

static void test_levels_round_trip(void)
{
    sample_levels l;
    make_sample_levels(&l);
    size_t size = 0;
    uint8_t *bytes = serialize_with_levels(&l, &size);
    sw_pack pack;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_open_memory(bytes, size, &pack, &err) == SW_OK, "%s", err.message);
    const sw_levels *r = &pack.levels;
    const sw_pack_levels *h = pack.levels_header;
    SW_CHECK(pack.header->section_count == 28 && h);
    SW_CHECK(h->level_count == 3 && h->vertex_count == 11 && h->index_count == 15 &&
             h->chain_count == 4 && h->chain_point_count == 11 && h->surface_count == 2);
    SW_CHECK(r->level_count == 3 && r->vertex_count == 11 && r->index_count == 15 &&
             r->chain_count == 4 && r->chain_point_count == 11 && r->surface_count == 2);
    SW_CHECK(memcmp(r->levels, l.levels, sizeof l.levels) == 0);
    SW_CHECK(memcmp(r->surface_levels, l.surface_levels, 3 * sizeof(uint32_t)) == 0);
    SW_CHECK(memcmp(r->vertices, l.vertices, sizeof l.vertices) == 0);
    SW_CHECK(memcmp(r->indices, l.indices, sizeof l.indices) == 0);
    SW_CHECK(memcmp(r->chains, l.chains, sizeof l.chains) == 0);
    SW_CHECK(memcmp(r->chain_points, l.points, sizeof l.points) == 0);
    /* The level group follows the other 21 sections, in type order, 64-byte
     * aligned; LEVEL_INDICES keeps its exact 30 bytes. */
    for (uint32_t i = 21; i < 28; i++)
        SW_CHECK(pack.sections[i].type == SW_SECTION_LEVELS + (i - 21) &&
                 pack.sections[i].offset % 64 == 0);
    SW_CHECK(pack.sections[21].size == 32 && pack.sections[25].size == 30);
    free(bytes);
}

/* With ORIENTATION and IMPORT_NOTES too, the levels come last, in type
 * order, and each of the three one-section types is still read. */
static void test_levels_follow_orientation_and_notes(void)
{
    sample s;
    sample_seam g;
    sample_levels l;
    make_sample(&s);
    make_sample_seam(&g);
    make_sample_levels(&l);
    const sw_pack_orientation up = { .up_axis = 3 };
    const sw_pack_import_note note = { .kind = SW_NOTE_SKIPPED, .count = 2, .source = "a.igs",
                                       .what = "IGES 406" };
    sw_pack_contents c = sample_contents(&s);
    c.seam = &g.graph;
    c.orientation = &up;
    c.import_notes = &note;
    c.import_note_count = 1;
    c.levels = &l.view;
    uint8_t *bytes = NULL;
    size_t size = 0;
    sw_error err = { 0 };
    SW_CHECK(sw_pack_serialize(&c, &bytes, &size, &err) == SW_OK);
    sw_pack pack;
    SW_CHECK_MSG(sw_pack_open_memory(bytes, size, &pack, &err) == SW_OK, "%s", err.message);
    SW_CHECK(pack.header->section_count == 30);
    SW_CHECK(pack.sections[21].type == SW_SECTION_ORIENTATION &&
             pack.sections[22].type == SW_SECTION_IMPORT_NOTES);
    for (uint32_t i = 23; i < 30; i++)
        SW_CHECK(pack.sections[i].type == SW_SECTION_LEVELS + (i - 23));
    SW_CHECK(pack.orientation && pack.orientation->up_axis == 3 && pack.import_note_count == 1 &&
             pack.levels_header && pack.levels.level_count == 3);
    free(bytes);
}

/* Without levels the writer adds nothing and the reader's view is empty. */
static void test_no_levels_writes_no_level_sections(void)
{
    size_t size = 0;
    uint8_t *bytes = serialize_with_levels(NULL, &size);
    sw_pack pack;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_open_memory(bytes, size, &pack, &err) == SW_OK, "%s", err.message);
    SW_CHECK(pack.header->section_count == 21 && !pack.levels_header);
    SW_CHECK(!pack.levels.levels && !pack.levels.surface_levels && !pack.levels.vertices &&
             !pack.levels.indices && !pack.levels.chains && !pack.levels.chain_points &&
             pack.levels.level_count == 0 && pack.levels.surface_count == 0);
    free(bytes);
}

/* A surface may have no level; a pack whose surfaces have none is valid. */
static void test_surfaces_without_levels_are_valid(void)
{
    sample_levels l;
    make_sample_levels(&l);
    l.surface_levels[1] = l.surface_levels[2] = 0;
    l.view.level_count = l.view.vertex_count = l.view.index_count = 0;
    l.view.chain_count = l.view.chain_point_count = 0;
    size_t size = 0;
    uint8_t *bytes = serialize_with_levels(&l, &size);
    expect_open(bytes, size, SW_OK, "");
    free(bytes);
}

/* A version-1 reader that predates the levels sees unknown types and
 * skips them. */
static void renumber_levels(uint8_t *b)
{
    for (uint32_t t = SW_SECTION_LEVELS; t <= SW_SECTION_LEVEL_CHAIN_POINTS; t++)
        table_of(b)[entry_of(b, t)].type = t + 100;
}

static void test_level_sections_are_skippable(void)
{
    sample_levels l;
    make_sample_levels(&l);
    size_t size = 0;
    uint8_t *bytes = serialize_with_levels(&l, &size);
    renumber_levels(bytes);
    reseal(bytes);
    sw_pack pack;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_open_memory(bytes, size, &pack, &err) == SW_OK, "%s", err.message);
    SW_CHECK(!pack.levels_header && pack.levels.level_count == 0 && pack.seam_header);
    free(bytes);
}

/* ---- which sections, and their sizes ---- */

static void retype_levels(uint8_t *b) { table_of(b)[entry_of(b, SW_SECTION_LEVELS)].type = 77; }
static void retype_chains(uint8_t *b)
{
    table_of(b)[entry_of(b, SW_SECTION_LEVEL_CHAINS)].type = 77;
}
static void retype_chains_as_indices(uint8_t *b)
{
    table_of(b)[entry_of(b, SW_SECTION_LEVEL_CHAINS)].type = SW_SECTION_LEVEL_INDICES;
}

static void test_group_rules(void)
{
    expect_bytes_rejected(retype_levels, SW_ERR_FORMAT, "section 22 (LEVEL_RECORDS): present "
                                                        "without a LEVELS section");
    expect_bytes_rejected(retype_chains, SW_ERR_FORMAT, "section 21 (LEVELS): no LEVEL_CHAINS "
                                                        "section (the levels' sections appear "
                                                        "together)");
    expect_bytes_rejected(retype_chains_as_indices, SW_ERR_FORMAT, "section 26 (LEVEL_INDICES): "
                                                                   "a second LEVEL_INDICES "
                                                                   "section (the first is "
                                                                   "section 25)");
    /* Without a Seam Graph there are no loops for the chains to follow. */
    sample s;
    sample_levels l;
    make_sample(&s);
    make_sample_levels(&l);
    sw_pack_contents c = sample_contents(&s);
    c.levels = &l.view;
    uint8_t *bytes = NULL;
    size_t size = 0;
    sw_error err = { 0 };
    SW_CHECK(sw_pack_serialize(&c, &bytes, &size, &err) == SW_OK);
    expect_open(bytes, size, SW_ERR_FORMAT, "section 13 (LEVELS): present without a Seam Graph "
                                            "(a level's chains follow its loops)");
    free(bytes);
}

static void shrink_levels(uint8_t *b) { table_of(b)[entry_of(b, SW_SECTION_LEVELS)].size -= 4; }
static void claim_16_indices(uint8_t *b) { levels_record_of(b)->index_count = 16; }
static void claim_all_vertices(uint8_t *b) { levels_record_of(b)->vertex_count = UINT32_MAX; }
static void shrink_surface_levels(uint8_t *b)
{
    table_of(b)[entry_of(b, SW_SECTION_LEVEL_SURFACES)].size -= 4;
}

static void test_section_sizes(void)
{
    expect_bytes_rejected(shrink_levels, SW_ERR_FORMAT, "section 21 (LEVELS): 28 bytes, "
                                                        "expected 32");
    /* Exact sizes: the 30-byte section is not rounded up to 32 (or 64). */
    expect_bytes_rejected(claim_16_indices, SW_ERR_FORMAT, "section 25 (LEVEL_INDICES): 30 bytes, "
                                                           "expected LEVELS.index_count 16 x 2 = "
                                                           "32");
    /* 64-bit products: a huge count cannot wrap around to the real size. */
    expect_bytes_rejected(claim_all_vertices, SW_ERR_FORMAT, "section 24 (LEVEL_VERTICES): 176 "
                                                             "bytes, expected "
                                                             "LEVELS.vertex_count 4294967295 x "
                                                             "16 = 68719476720");
    expect_bytes_rejected(shrink_surface_levels, SW_ERR_FORMAT, "section 23 (LEVEL_SURFACES): 8 "
                                                                "bytes, expected "
                                                                "(LEVELS.surface_count + 1) 3 x 4 "
                                                                "= 12");
}

/* ---- LEVELS ---- */

static void set_reserved(uint8_t *b) { levels_record_of(b)->reserved[7] = 1; }

static void test_header_rules(void)
{
    sample_levels l;
    expect_bytes_rejected(set_reserved, SW_ERR_FORMAT, "LEVELS.reserved[7]: 0x01, expected 0");
    /* Three surfaces claimed (the spare entry makes LEVEL_SURFACES the right size). */
    fresh(&l)->view.surface_count = 3;
    l.surface_levels[3] = 3;
    expect_rejected(&l, SW_ERR_RANGE, "LEVELS.surface_count: 3, but SURFACES has 2 entries");
}

/* ---- LEVEL_SURFACES ---- */

static void test_surface_level_rules(void)
{
    sample_levels l;
    fresh(&l)->surface_levels[0] = 1;
    expect_rejected(&l, SW_ERR_FORMAT, "LEVEL_SURFACES[0]: 1, expected 0");
    fresh(&l)->surface_levels[1] = 3;
    l.surface_levels[2] = 2;
    expect_rejected(&l, SW_ERR_FORMAT, "LEVEL_SURFACES[2]: 2 < the previous 3, expected "
                                       "non-decreasing");
    fresh(&l)->surface_levels[2] = 2;
    expect_rejected(&l, SW_ERR_FORMAT, "LEVEL_SURFACES[2]: 2, expected the LEVEL_RECORDS count 3");
    fresh(&l)->surface_levels[1] = 0;
    l.surface_levels[2] = 7;
    expect_rejected(&l, SW_ERR_RANGE, "LEVEL_SURFACES[2]: surface 1 has 7 levels, at most 6");
}

/* ---- LEVEL_RECORDS and LEVEL_INDICES ---- */

static void test_level_fields(void)
{
    sample_levels l;
    fresh(&l)->levels[0].surface = 1;
    expect_rejected(&l, SW_ERR_FORMAT, "LEVEL_RECORDS[0].surface: 1, expected 0 (LEVEL_SURFACES "
                                       "gives surface 0 the levels [0, 1))");
    fresh(&l)->levels[1].error = NAN;
    expect_rejected(&l, SW_ERR_FORMAT, "LEVEL_RECORDS[1].error: nan, expected finite >= 0");
    fresh(&l)->levels[0].error = -0.5f;
    expect_rejected(&l, SW_ERR_FORMAT, "LEVEL_RECORDS[0].error: -0.5, expected finite >= 0");
    fresh(&l)->levels[2].error = 0.005f; /* level 1's: not rising */
    expect_rejected(&l, SW_ERR_FORMAT, "LEVEL_RECORDS[2].error: 0.005, expected more than the "
                                       "previous level's 0.005 (errors rise over a surface's "
                                       "levels)");
    fresh(&l)->levels[2].made_bound = -1.0f;
    expect_rejected(&l, SW_ERR_FORMAT, "LEVEL_RECORDS[2].made_bound: -1, expected finite and >= 0");
    fresh(&l)->levels[1].made_bound = INFINITY;
    expect_rejected(&l, SW_ERR_FORMAT, "LEVEL_RECORDS[1].made_bound: inf, expected finite and >= 0");
}

static void test_level_ranges(void)
{
    sample_levels l;
    fresh(&l)->levels[1].vertex_count = 0;
    expect_rejected(&l, SW_ERR_RANGE, "LEVEL_RECORDS[1].vertex_count: 0, expected 1..65536 "
                                      "(16-bit indices)");
    fresh(&l)->levels[1].vertex_count = 65537;
    expect_rejected(&l, SW_ERR_RANGE, "LEVEL_RECORDS[1].vertex_count: 65537, expected 1..65536");
    fresh(&l)->levels[2].first_vertex = 8;
    l.levels[2].vertex_count = 4;
    expect_rejected(&l, SW_ERR_RANGE, "LEVEL_RECORDS[2].first_vertex: 8 + vertex_count 4 exceeds "
                                      "LEVEL_VERTICES count 11");
    fresh(&l)->levels[2].first_vertex = UINT32_MAX; /* 64-bit sums: no wrap to 2 */
    expect_rejected(&l, SW_ERR_RANGE, "LEVEL_RECORDS[2].first_vertex: 4294967295 + vertex_count "
                                      "3 exceeds");
    fresh(&l)->levels[0].index_count = 5;
    expect_rejected(&l, SW_ERR_FORMAT, "LEVEL_RECORDS[0].index_count: 5, expected a multiple of 3 "
                                       "(triangles)");
    fresh(&l)->levels[2].index_count = 6;
    expect_rejected(&l, SW_ERR_RANGE, "LEVEL_RECORDS[2].first_index: 12 + index_count 6 exceeds "
                                      "LEVEL_INDICES count 15");
    fresh(&l)->levels[2].first_chain = 4;
    expect_rejected(&l, SW_ERR_RANGE, "LEVEL_RECORDS[2].first_chain: 4 + the surface's 1 loops "
                                      "exceeds LEVEL_CHAINS count 4");
    fresh(&l)->levels[0].first_chain = 3; /* surface 0 has two loops */
    expect_rejected(&l, SW_ERR_RANGE, "LEVEL_RECORDS[0].first_chain: 3 + the surface's 2 loops "
                                      "exceeds LEVEL_CHAINS count 4");
    fresh(&l)->indices[14] = 3; /* level 2 has 3 vertices */
    expect_rejected(&l, SW_ERR_RANGE, "LEVEL_INDICES[14]: 3, expected < 3 "
                                      "(LEVEL_RECORDS[2].vertex_count)");
}

/* ---- LEVEL_CHAINS and LEVEL_CHAIN_POINTS ---- */

static void test_chain_rules(void)
{
    sample_levels l;
    fresh(&l)->chains[3].first_point = 9;
    expect_rejected(&l, SW_ERR_RANGE, "LEVEL_CHAINS[3].first_point: 9 + point_count 3 exceeds "
                                      "LEVEL_CHAIN_POINTS count 11");
    fresh(&l)->points[9].vertex = 3; /* level 2 has 3 vertices */
    expect_rejected(&l, SW_ERR_RANGE, "LEVEL_CHAIN_POINTS[9].vertex: 3, expected < 3 "
                                      "(LEVEL_RECORDS[2].vertex_count)");
    fresh(&l)->points[5].t = 2; /* 0 2 1 3: twice down */
    l.points[6].t = 1;
    expect_rejected(&l, SW_ERR_FORMAT, "LEVEL_CHAINS[2]: its 4 points do not go once round "
                                       "SEAM_LOOPS[2] (LEVEL_RECORDS[1]'s chain 0): expected each "
                                       "t in [0, 5), rising but for one wrap");
    fresh(&l)->points[3].t = 5; /* loop 0 has 5 slots */
    expect_rejected(&l, SW_ERR_FORMAT, "LEVEL_CHAINS[0]: its 4 points do not go once round "
                                       "SEAM_LOOPS[0]");
    fresh(&l)->points[3].t = NAN;
    expect_rejected(&l, SW_ERR_FORMAT, "LEVEL_CHAINS[0]: its 4 points do not go once round");
    fresh(&l)->chains[2].point_count = 0;
    expect_rejected(&l, SW_ERR_FORMAT, "LEVEL_CHAINS[2].point_count: 0, but SEAM_LOOPS[2] is an "
                                       "outer loop (LEVEL_RECORDS[1]'s chain 0; only a hole "
                                       "vanishes)");
}

/* ---- LEVEL_VERTICES ---- */

static void test_vertex_rules(void)
{
    sample_levels l;
    fresh(&l)->vertices[7].p[1] = INFINITY;
    expect_rejected(&l, SW_ERR_FORMAT, "LEVEL_VERTICES[7].p.y: inf, expected a finite number");
    fresh(&l)->vertices[2].p[2] = NAN;
    expect_rejected(&l, SW_ERR_FORMAT, "LEVEL_VERTICES[2].p.z: nan, expected a finite number");
    fresh(&l)->vertices[10].normal[3] = 1;
    expect_rejected(&l, SW_ERR_FORMAT, "LEVEL_VERTICES[10].normal[3]: 1, expected 0");
}

/* ---- two problems ---- */

/* The checks run in parts (the surfaces' levels in quarters, the vertices
 * in halves) that may run in any order; with problems in two parts the
 * earlier part's is named, as one pass in rule order would (expect_open
 * also runs them backwards). Surface 0 is in the second quarter, surface 1
 * in the fourth. */
static void test_first_problem_in_rule_order_is_named(void)
{
    sample_levels l;
    fresh(&l)->vertices[0].normal[3] = 5;  /* the vertices, after every level */
    l.levels[2].made_bound = NAN;
    expect_rejected(&l, SW_ERR_FORMAT, "LEVEL_RECORDS[2].made_bound: nan");
    fresh(&l)->levels[1].error = -1;       /* surface 1 ... */
    l.chains[0].point_count = 0;           /* ... after surface 0's outer chain */
    expect_rejected(&l, SW_ERR_FORMAT, "LEVEL_CHAINS[0].point_count: 0");
    fresh(&l)->vertices[10].p[0] = NAN;    /* the second half, after the first */
    l.vertices[1].normal[3] = 2;
    expect_rejected(&l, SW_ERR_FORMAT, "LEVEL_VERTICES[1].normal[3]: 2");
}

/* ---- seamwalk-pack info ---- */

/* The info report of the sample with levels l (NULL: none), as a string. */
static char *info_of(const sample_levels *l, int json)
{
    size_t size = 0;
    uint8_t *bytes = serialize_with_levels(l, &size);
    sw_pack pack;
    sw_error err = { 0 };
    SW_CHECK(sw_pack_open_memory(bytes, size, &pack, &err) == SW_OK);
    char *text = NULL;
    size_t len = 0;
    FILE *out = open_memstream(&text, &len);
    SW_CHECK(sw_pack_print_info(out, "s.swpack", &pack, json, &err) == SW_OK);
    fclose(out);
    free(bytes);
    return text;
}

/* 32 + 3 x 32 + 3 x 4 + 11 x 16 + 15 x 2 + 4 x 8 + 11 x 8 = 466 bytes. Rank
 * 0 is levels 0 and 1 (2 + 2 triangles, errors 0.01 and 0.005), rank 1
 * level 2 (1 triangle, 0.02), half of level 1's of the same surface. */
static void test_info_reports_levels(void)
{
    sample_levels l;
    make_sample_levels(&l);
    char *text = info_of(&l, 0);
    SW_CHECK_MSG(strstr(text, "  levels           3 (1..2 per surface), 11 vertices, 15 indices "
                              "(5 triangles), 11 chain points, 466 bytes\n"
                              "    rank 0         2 surfaces, 4 triangles, error max 0.01, "
                              "median 0.005\n"
                              "    rank 1         1 surfaces, 1 triangles, error max 0.02, "
                              "median 0.02; 50% fewer triangles than rank 0 of the same "
                              "surfaces\n"), "%s", text);
    free(text);
    text = info_of(&l, 1);
    SW_CHECK_MSG(strstr(text, "  \"levels\": {\"levels\": 3, \"per_surface\": [1, 2], "
                              "\"vertices\": 11, \"indices\": 15, \"triangles\": 5, "
                              "\"chain_points\": 11, \"bytes\": 466,\n"
                              "             \"ranks\": [{\"rank\": 0, \"surfaces\": 2, "
                              "\"triangles\": 4, \"triangles_before\": 0, "
                              "\"error_max\": 0.00999999978, "
                              "\"error_median\": 0.00499999989}, {\"rank\": 1, \"surfaces\": 1, "
                              "\"triangles\": 1, \"triangles_before\": 2, "
                              "\"error_max\": 0.0199999996, "
                              "\"error_median\": 0.0199999996}]},\n"), "%s", text);
    free(text);
    text = info_of(NULL, 0);
    SW_CHECK(!strstr(text, "  levels "));
    free(text);
    text = info_of(NULL, 1);
    SW_CHECK_MSG(strstr(text, "  \"levels\": null,\n"), "%s", text);
    free(text);
}

int main(void)
{
    SW_RUN(test_levels_round_trip);
    SW_RUN(test_levels_follow_orientation_and_notes);
    SW_RUN(test_no_levels_writes_no_level_sections);
    SW_RUN(test_surfaces_without_levels_are_valid);
    SW_RUN(test_level_sections_are_skippable);
    SW_RUN(test_group_rules);
    SW_RUN(test_section_sizes);
    SW_RUN(test_header_rules);
    SW_RUN(test_surface_level_rules);
    SW_RUN(test_level_fields);
    SW_RUN(test_level_ranges);
    SW_RUN(test_chain_rules);
    SW_RUN(test_vertex_rules);
    SW_RUN(test_first_problem_in_rule_order_is_named);
    SW_RUN(test_info_reports_levels);
    return sw_test_finish();
}
