/* SPDX-License-Identifier: MIT */
/* The Seam Graph in the pack: the sample's hand-built graph (pack_sample.h)
 * written and read back identical; which seam sections must appear together
 * and how their sizes are checked; one refusal per validation rule, each
 * made by breaking one field of an otherwise valid pack whose checksums are
 * all recomputed, so the rule under test is the one that fires; the info
 * report's seam lines. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <xxhash.h>

#include "sw_test.h"
#include "pack_sample.h"
#include "pack_expect.h"
#include "sw_pack_info.h"

/* The sample with graph g (NULL: none), serialised; malloc'd. */
static uint8_t *serialize_with_seam(const sample *s, const sample_seam *g, size_t *size)
{
    sw_pack_contents c = sample_contents(s);
    c.seam = g ? &g->graph : NULL;
    uint8_t *bytes = NULL;
    sw_error err = { 0 };
    sw_status st = sw_pack_serialize(&c, &bytes, size, &err);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    return bytes;
}

/* The sample with the (edited) graph g must be refused with status and needle. */
static void expect_rejected(const sample_seam *g, sw_status status, const char *needle)
{
    sample s;
    make_sample(&s);
    size_t size = 0;
    uint8_t *bytes = serialize_with_seam(&s, g, &size);
    expect_open(bytes, size, status, needle);
    free(bytes);
}

/* The sample with the (edited) graph g opens. */
static void expect_accepted(const sample_seam *g)
{
    expect_rejected(g, SW_OK, "");
}

/* A fresh sample graph to break one field of. */
static sample_seam *fresh(sample_seam *g)
{
    make_sample_seam(g);
    return g;
}

/* Serialises the sample with its graph, lets edit change any bytes (table or
 * sections), recomputes every checksum and expects status and needle. */
static void expect_bytes_rejected(void (*edit)(uint8_t *bytes), sw_status status,
                                  const char *needle)
{
    sample s;
    sample_seam g;
    make_sample(&s);
    make_sample_seam(&g);
    size_t size = 0;
    uint8_t *bytes = serialize_with_seam(&s, &g, &size);
    edit(bytes);
    reseal_all(bytes);
    expect_open(bytes, size, status, needle);
    free(bytes);
}

static sw_pack_seam *seam_record_of(uint8_t *b)
{
    return (sw_pack_seam *)(b + table_of(b)[entry_of(b, SW_SECTION_SEAM)].offset);
}

/* ---- round trip ---- */

static void test_graph_round_trips(void)
{
    sample s;
    sample_seam g;
    make_sample(&s);
    make_sample_seam(&g);
    size_t size = 0;
    uint8_t *bytes = serialize_with_seam(&s, &g, &size);
    sw_pack pack;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_open_memory(bytes, size, &pack, &err) == SW_OK, "%s", err.message);
    const sw_seam_graph *r = &pack.seam;
    SW_CHECK(pack.header->section_count == 21 && pack.seam_header);
    SW_CHECK(r->vertex_count == 14 && r->original_count == 10 && r->slot_count == 13 &&
             r->loop_count == 3 && r->edge_count == 11 && r->collapse_count == 4 &&
             r->slot_ref_count == 13 && r->surface_count == 2 && r->tolerance == 0.001f);
    SW_CHECK(memcmp(r->vertices, g.vertices, sizeof g.vertices) == 0);
    SW_CHECK(memcmp(r->slots, g.slots, sizeof g.slots) == 0);
    SW_CHECK(memcmp(r->loops, g.loops, sizeof g.loops) == 0);
    SW_CHECK(memcmp(r->edges, g.edges, sizeof g.edges) == 0);
    SW_CHECK(memcmp(r->collapses, g.collapses, sizeof g.collapses) == 0);
    SW_CHECK(memcmp(r->slot_refs, g.slot_refs, sizeof g.slot_refs) == 0);
    SW_CHECK(memcmp(r->surface_loops, g.surface_loops, 3 * sizeof(uint32_t)) == 0);
    /* The seam group follows the 13 other sections, in type order, 64-byte aligned. */
    for (uint32_t i = 13; i < 21; i++)
        SW_CHECK(pack.sections[i].type == SW_SECTION_SEAM + (i - 13) &&
                 pack.sections[i].offset % 64 == 0);
    SW_CHECK(pack.sections[13].size == 64 && pack.sections[14].size == 14 * 32);
    free(bytes);
}

/* Without a graph the writer adds nothing: the pack is the one it wrote
 * before the seam sections existed, and the reader's seam view is empty. */
static void test_no_graph_writes_no_seam_sections(void)
{
    sample s;
    make_sample(&s);
    size_t plain_size = 0, seam_size = 0;
    uint8_t *plain = serialize_with_seam(&s, NULL, &plain_size);
    sample_seam g;
    make_sample_seam(&g);
    uint8_t *with = serialize_with_seam(&s, &g, &seam_size);
    sw_pack pack;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_open_memory(plain, plain_size, &pack, &err) == SW_OK, "%s", err.message);
    SW_CHECK(pack.header->section_count == 13 && !pack.seam_header);
    SW_CHECK(!pack.seam.vertices && !pack.seam.surface_loops && pack.seam.vertex_count == 0 &&
             pack.seam.surface_count == 0);
    /* The other sections' bytes are the same with and without the graph. */
    sw_pack other;
    SW_CHECK(sw_pack_open_memory(with, seam_size, &other, &err) == SW_OK);
    for (uint32_t i = 0; i < 13; i++)
        SW_CHECK(pack.sections[i].size == other.sections[i].size &&
                 pack.sections[i].checksum == other.sections[i].checksum);
    free(plain);
    free(with);
}

/* A graph with nothing in it (every section empty, both surfaces without
 * loops) is valid: empty sections are views of zero records. */
static void test_empty_graph_is_valid(void)
{
    sample s;
    sample_seam g;
    make_sample(&s);
    make_sample_seam(&g);
    g.surface_loops[1] = g.surface_loops[2] = 0;
    g.graph = (sw_seam_graph){ .surface_loops = g.surface_loops, .surface_count = 2 };
    size_t size = 0;
    uint8_t *bytes = serialize_with_seam(&s, &g, &size);
    sw_pack pack;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_open_memory(bytes, size, &pack, &err) == SW_OK, "%s", err.message);
    SW_CHECK(pack.seam_header && pack.seam.vertex_count == 0 && pack.seam.loop_count == 0 &&
             pack.seam.surface_loops[2] == 0);
    free(bytes);
}

/* A version-1 reader that predates the seam sections sees unknown types;
 * moving them to unknown numbers shows such a pack is still accepted. */
static void renumber_seam(uint8_t *b)
{
    for (uint32_t t = SW_SECTION_SEAM; t <= SW_SECTION_SEAM_SURFACE_LOOPS; t++)
        table_of(b)[entry_of(b, t)].type = t + 100;
}

static void test_seam_sections_are_skippable(void)
{
    sample s;
    sample_seam g;
    make_sample(&s);
    make_sample_seam(&g);
    size_t size = 0;
    uint8_t *bytes = serialize_with_seam(&s, &g, &size);
    renumber_seam(bytes);
    reseal(bytes);
    sw_pack pack;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_open_memory(bytes, size, &pack, &err) == SW_OK, "%s", err.message);
    SW_CHECK(!pack.seam_header && pack.seam.vertex_count == 0 && pack.surface_count == 2);
    free(bytes);
}

/* ---- which sections, and their sizes ---- */

static void retype_seam(uint8_t *b) { table_of(b)[entry_of(b, SW_SECTION_SEAM)].type = 77; }
static void retype_edges(uint8_t *b) { table_of(b)[entry_of(b, SW_SECTION_SEAM_EDGES)].type = 77; }
static void retype_edges_as_slots(uint8_t *b)
{
    table_of(b)[entry_of(b, SW_SECTION_SEAM_EDGES)].type = SW_SECTION_SEAM_SLOTS;
}
static void shrink_seam(uint8_t *b) { table_of(b)[entry_of(b, SW_SECTION_SEAM)].size -= 4; }
static void shrink_vertices(uint8_t *b)
{
    table_of(b)[entry_of(b, SW_SECTION_SEAM_VERTICES)].size -= 32;
}
static void shrink_surface_loops(uint8_t *b)
{
    table_of(b)[entry_of(b, SW_SECTION_SEAM_SURFACE_LOOPS)].size -= 4;
}

static void test_group_rules(void)
{
    expect_bytes_rejected(retype_seam, SW_ERR_FORMAT, "section 14 (SEAM_VERTICES): present "
                                                      "without a SEAM section");
    expect_bytes_rejected(retype_edges, SW_ERR_FORMAT, "section 13 (SEAM): no SEAM_EDGES section "
                                                       "(the Seam Graph's sections appear "
                                                       "together)");
    expect_bytes_rejected(retype_edges_as_slots, SW_ERR_FORMAT, "section 17 (SEAM_SLOTS): a "
                                                                "second SEAM_SLOTS section (the "
                                                                "first is section 15)");
    /* A Bezier-only pack has no SURFACES for the loops to index. */
    sample s;
    sample_seam g;
    make_sample(&s);
    make_sample_seam(&g);
    s.bezier_only = 1;
    size_t size = 0;
    uint8_t *bytes = serialize_with_seam(&s, &g, &size);
    expect_open(bytes, size, SW_ERR_FORMAT, "section 5 (SEAM): present without a SURFACES "
                                            "section (its loops index SURFACES)");
    free(bytes);
}

static void claim_all_vertices(uint8_t *b) { seam_record_of(b)->vertex_count = UINT32_MAX; }

static void test_section_sizes(void)
{
    /* 64-bit products: a huge count cannot wrap around to the real size. */
    expect_bytes_rejected(claim_all_vertices, SW_ERR_FORMAT, "section 14 (SEAM_VERTICES): 448 "
                                                             "bytes, expected SEAM.vertex_count "
                                                             "4294967295 x 32 = 137438953440");
    expect_bytes_rejected(shrink_seam, SW_ERR_FORMAT, "section 13 (SEAM): 60 bytes, expected 64");
    expect_bytes_rejected(shrink_vertices, SW_ERR_FORMAT, "section 14 (SEAM_VERTICES): 416 bytes, "
                                                          "expected SEAM.vertex_count 14 x 32 = "
                                                          "448");
    expect_bytes_rejected(shrink_surface_loops, SW_ERR_FORMAT, "section 20 (SEAM_SURFACE_LOOPS): "
                                                               "8 bytes, expected "
                                                               "(SEAM.surface_count + 1) 3 x 4 = "
                                                               "12");
}

/* ---- SEAM ---- */

static void set_reserved(uint8_t *b) { seam_record_of(b)->reserved[27] = 1; }

static void test_header_rules(void)
{
    sample_seam g;
    expect_bytes_rejected(set_reserved, SW_ERR_FORMAT, "SEAM.reserved[27]: 0x01, expected 0");
    fresh(&g)->graph.tolerance = NAN;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM.tolerance: nan, expected finite >= 0");
    fresh(&g)->graph.tolerance = -1;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM.tolerance: -1, expected finite >= 0");
    /* Three surfaces claimed (the spare entry makes SURFACE_LOOPS the right size). */
    fresh(&g)->graph.surface_count = 3;
    g.surface_loops[3] = 3;
    expect_rejected(&g, SW_ERR_RANGE, "SEAM.surface_count: 3, but SURFACES has 2 entries");
    fresh(&g)->graph.original_count = 9;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM.vertex_count: 14, expected original_count 9 + "
                                       "collapse_count 4");
    fresh(&g)->graph.slot_ref_count = 12;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM.slot_ref_count: 12, expected slot_count 13 (every "
                                       "slot is listed once)");
}

/* ---- SEAM_VERTICES ---- */

static void test_vertex_fields(void)
{
    sample_seam g;
    fresh(&g)->vertices[4].p[1] = INFINITY;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_VERTICES[4].p.y: inf, expected a finite number");
    fresh(&g)->vertices[12].error = NAN;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_VERTICES[12].error: nan, expected finite >= 0");
    fresh(&g)->vertices[13].error = -0.5f;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_VERTICES[13].error: -0.5, expected finite >= 0");
    /* An original vertex may carry an error (a hierarchy cut at a floor),
     * within its child's: errors never drop towards the roots. */
    fresh(&g)->vertices[3].error = 1e30f;
    expect_rejected(&g, SW_ERR_FORMAT, "below its parent 3's 1e+30");
    fresh(&g);
    uint32_t child = g.vertices[3].child;
    SW_CHECK(child != SW_SEAM_NONE);
    g.vertices[3].error = g.vertices[child].error;
    expect_accepted(&g);
    fresh(&g)->vertices[5].reserved = 7;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_VERTICES[5].reserved: 7, expected 0");
    fresh(&g)->vertices[11].slot_ref_count = 1;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_VERTICES[11].first_slot_ref: 0 with slot_ref_count "
                                       "1, expected 0 and 0 (a created vertex sits in no slot)");
}

static void test_vertex_children(void)
{
    sample_seam g;
    fresh(&g)->vertices[0].child = 5; /* an original vertex */
    expect_rejected(&g, SW_ERR_RANGE, "SEAM_VERTICES[0].child: 5, expected 0xffffffff (none) or "
                                      "a created vertex in 10..13");
    fresh(&g)->vertices[11].child = 10; /* made before 11: a cycle could follow */
    expect_rejected(&g, SW_ERR_RANGE, "SEAM_VERTICES[11].child: 10, expected 0xffffffff (none) "
                                      "or a created vertex in 12..13");
    fresh(&g)->vertices[12].child = 12; /* itself */
    expect_rejected(&g, SW_ERR_RANGE, "SEAM_VERTICES[12].child: 12, expected 0xffffffff (none) "
                                      "or a created vertex in 13..13");
    fresh(&g)->vertices[13].child = 14;
    expect_rejected(&g, SW_ERR_RANGE, "SEAM_VERTICES[13].child: 14");
    /* A third parent: vertex 0 claims collapse 0's vertex 10. */
    fresh(&g)->vertices[0].child = 10;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_VERTICES[0].child: 10, but SEAM_COLLAPSES[0] creates "
                                       "it from vertices 6 and 2");
    /* Errors must not drop going up: 12 (0.25) is above 11 (0.3). */
    fresh(&g)->vertices[12].error = 0.25f;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_VERTICES[12].error: 0.25, below its parent 11's 0.3 "
                                       "(errors grow towards the roots)");
}

/* ---- SEAM_COLLAPSES ---- */

static void test_collapse_rules(void)
{
    sample_seam g;
    fresh(&g)->collapses[1].error = INFINITY;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_COLLAPSES[1].error: inf, expected finite >= 0");
    fresh(&g)->collapses[1].error = -1;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_COLLAPSES[1].error: -1, expected finite >= 0");
    fresh(&g)->collapses[2].v1 = 12; /* the vertex it creates */
    expect_rejected(&g, SW_ERR_RANGE, "SEAM_COLLAPSES[2].v1: 12, expected a vertex made before "
                                      "the one it creates (< 12)");
    fresh(&g)->collapses[0].v2 = 13;
    expect_rejected(&g, SW_ERR_RANGE, "SEAM_COLLAPSES[0].v2: 13, expected a vertex made before "
                                      "the one it creates (< 10)");
    fresh(&g)->collapses[3].v1 = 10;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_COLLAPSES[3].v2: 10, the same as v1");
    fresh(&g)->collapses[1].v1 = 9; /* vertex 9's child is 12 */
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_COLLAPSES[1].v1: vertex 9 has child 12, expected 11 "
                                       "(the vertex this collapse creates)");
    fresh(&g)->vertices[7].child = SW_SEAM_NONE; /* collapse 1 keeps 7 */
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_COLLAPSES[1].v2: vertex 7 has child 4294967295, "
                                       "expected 11");
    fresh(&g)->vertices[10].p[2] = 0.5f;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_VERTICES[10].p: (1, 1, 0.5), expected v2 2's (1, 1, "
                                       "0) (made by SEAM_COLLAPSES[0])");
    fresh(&g)->vertices[13].error = 0.5f;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_VERTICES[13].error: 0.5, below its "
                                       "SEAM_COLLAPSES[3].error 1");
}

/* ---- SEAM_SLOTS and SEAM_SLOT_REFS ---- */

static void test_slot_rules(void)
{
    sample_seam g;
    fresh(&g)->slots[4].vertex = 10; /* a created vertex */
    expect_rejected(&g, SW_ERR_RANGE, "SEAM_SLOTS[4].vertex: 10, expected an original vertex "
                                      "(< 10)");
    fresh(&g)->slots[7].uv[1] = NAN;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_SLOTS[7].uv[1]: nan, expected a finite number");
}

static void test_slot_ref_rules(void)
{
    sample_seam g;
    fresh(&g)->vertices[1].first_slot_ref = 2;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_VERTICES[1].first_slot_ref: 2, expected 1 (the runs "
                                       "of slot references follow vertex order)");
    fresh(&g)->vertices[9].slot_ref_count = 2;
    expect_rejected(&g, SW_ERR_RANGE, "SEAM_VERTICES[9].first_slot_ref: 12 + slot_ref_count 2 "
                                      "exceeds SEAM_SLOT_REFS count 13");
    fresh(&g)->slot_refs[0] = 13;
    expect_rejected(&g, SW_ERR_RANGE, "SEAM_SLOT_REFS[0]: 13, but SEAM_SLOTS has 13 entries");
    fresh(&g)->slot_refs[1] = 3; /* slot 3 holds vertex 2, not 1 */
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_SLOT_REFS[1]: slot 3 holds vertex 2, but the "
                                       "reference is in vertex 1's run");
    fresh(&g)->slot_refs[1] = 8;
    g.slot_refs[2] = 1;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_SLOT_REFS[2]: 1, expected more than the previous 8 "
                                       "(a vertex's slots in increasing order)");
    fresh(&g)->slot_refs[2] = 1; /* slot 1 listed twice, slot 8 not at all */
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_SLOT_REFS[2]: 1, expected more than the previous 1");
    fresh(&g)->vertices[9].slot_ref_count = 0; /* slot 6 listed under no vertex */
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_VERTICES[9].slot_ref_count: 0, expected at least 1");
    fresh(&g)->vertices[9].first_slot_ref = 11; /* runs out of vertex order */
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_VERTICES[9].first_slot_ref: 11, expected 12");
}

/* ---- SEAM_SURFACE_LOOPS and SEAM_LOOPS ---- */

static void test_surface_loop_rules(void)
{
    sample_seam g;
    fresh(&g)->surface_loops[0] = 1;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_SURFACE_LOOPS[0]: 1, expected 0");
    fresh(&g)->surface_loops[1] = 4;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_SURFACE_LOOPS[2]: 3 < the previous 4, expected "
                                       "non-decreasing");
    fresh(&g)->surface_loops[2] = 2;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_SURFACE_LOOPS[2]: 2, expected the SEAM_LOOPS count 3");
}

static void test_loop_rules(void)
{
    sample_seam g;
    fresh(&g)->loops[2].surface = 2;
    expect_rejected(&g, SW_ERR_RANGE, "SEAM_LOOPS[2].surface: 2, but SURFACES has 2 entries");
    fresh(&g)->loops[1].surface = 1; /* out of surface order */
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_LOOPS[1].surface: 1, but SEAM_SURFACE_LOOPS gives "
                                       "that surface the loops [2, 3)");
    fresh(&g)->loops[1].flags = 2;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_LOOPS[1].flags: 0x2 has unknown bits");
    fresh(&g)->loops[1].slot_count = 2;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_LOOPS[1].slot_count: 2, expected at least 3");
    fresh(&g)->loops[2].first_slot = 9;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_LOOPS[2].first_slot: 9, expected 8 (the loops cover "
                                       "SEAM_SLOTS in order)");
    fresh(&g)->loops[2].slot_count = 6;
    expect_rejected(&g, SW_ERR_RANGE, "SEAM_LOOPS[2].first_slot: 8 + slot_count 6 exceeds "
                                      "SEAM_SLOTS count 13");
    fresh(&g)->loops[2].slot_count = 4; /* slot 12 in no loop */
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_LOOPS: the loops end at slot 12, expected the "
                                       "SEAM_SLOTS count 13");
}

/* ---- SEAM_EDGES ---- */

static void test_edge_rules(void)
{
    sample_seam g;
    fresh(&g)->edges[3].b = 10;
    expect_rejected(&g, SW_ERR_RANGE, "SEAM_EDGES[3].b: 10, expected an original vertex (< 10)");
    fresh(&g)->edges[5].a = 9;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_EDGES[5].a: 9, expected less than b 9");
    fresh(&g)->edges[0] = (sw_seam_edge){ 1, 0 };
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_EDGES[0].a: 1, expected less than b 0");
}

/* ---- two problems ---- */

/* The check runs in parts (the vertices and the collapses in halves, the
 * slots, their references, the loops with the edges) that may run in any
 * order; with problems in two parts, the earlier part's is named, as one
 * pass in rule order would (expect_open also runs them backwards). */
static void test_first_problem_in_rule_order_is_named(void)
{
    sample_seam g;
    fresh(&g)->vertices[13].error = NAN;   /* the second half of the vertices */
    g.edges[3].b = 10;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_VERTICES[13].error: nan");
    fresh(&g)->vertices[12].error = 0.25f; /* collapse 3, the second half */
    g.slots[4].vertex = 10;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_VERTICES[12].error: 0.25, below its parent 11's");
    fresh(&g)->collapses[1].error = -1;    /* the first half, before the second's */
    g.vertices[13].error = 0.5f;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_COLLAPSES[1].error: -1");
    fresh(&g)->vertices[0].child = 10;     /* the parent count, before the slots */
    g.slots[7].uv[1] = NAN;
    expect_rejected(&g, SW_ERR_FORMAT, "SEAM_VERTICES[0].child: 10, but SEAM_COLLAPSES[0]");
    fresh(&g)->slot_refs[0] = 13;          /* the references, before the loops */
    g.loops[1].flags = 2;
    expect_rejected(&g, SW_ERR_RANGE, "SEAM_SLOT_REFS[0]: 13");
}

/* ---- seamwalk-pack info ---- */

/* The info report of the sample with graph g (NULL: none), as a string. */
static char *info_of(const sample_seam *g, int json)
{
    sample s;
    make_sample(&s);
    size_t size = 0;
    uint8_t *bytes = serialize_with_seam(&s, g, &size);
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

/* 64 + 14 x 32 + 13 x 12 + 3 x 16 + 11 x 8 + 4 x 12 + 13 x 4 + 3 x 4 = 916
 * bytes over 11 edges and 2 surfaces. */
static void test_info_reports_seam_graph(void)
{
    sample_seam g;
    make_sample_seam(&g);
    sw_pack_seam_stats st;
    sample s;
    make_sample(&s);
    size_t size = 0;
    uint8_t *bytes = serialize_with_seam(&s, &g, &size);
    sw_pack pack;
    sw_error err = { 0 };
    SW_CHECK(sw_pack_open_memory(bytes, size, &pack, &err) == SW_OK);
    SW_CHECK(sw_pack_gather_seam_stats(&pack, &st));
    SW_CHECK(st.bytes == 916 && st.created_vertices == 4);
    SW_CHECK(fabs(st.bytes_per_edge - 916.0 / 11) < 1e-9 && st.bytes_per_surface == 458.0 &&
             fabs(st.bytes_per_bezier_patch - 916.0 / 3) < 1e-9);
    free(bytes);
    char *text = info_of(&g, 0);
    SW_CHECK_MSG(strstr(text, "  seam graph       14 vertices (10 original, 4 created), 13 slots, "
                              "3 loops, 11 edges, 4 collapses, tolerance 0.001\n"), "%s", text);
    SW_CHECK_MSG(strstr(text, "  seam memory      916 bytes: 83.3 per boundary edge, 458.0 per "
                              "surface, 305.3 per bezier patch\n"), "%s", text);
    free(text);
    text = info_of(&g, 1);
    SW_CHECK_MSG(strstr(text, "  \"seam\": {\"vertices\": 14, \"original_vertices\": 10, "
                              "\"created_vertices\": 4, \"slots\": 13, \"loops\": 3, "
                              "\"edges\": 11, \"collapses\": 4,\n"), "%s", text);
    SW_CHECK_MSG(strstr(text, "\"bytes\": 916, \"bytes_per_edge\": 83.2727273, "
                              "\"bytes_per_surface\": 458, \"bytes_per_bezier_patch\": "
                              "305.333333},\n"), "%s", text);
    free(text);
    text = info_of(NULL, 0);
    SW_CHECK(!strstr(text, "seam graph") && !strstr(text, "seam memory"));
    free(text);
    text = info_of(NULL, 1);
    SW_CHECK(!strstr(text, "\"seam\""));
    free(text);
}

int main(void)
{
    SW_RUN(test_graph_round_trips);
    SW_RUN(test_no_graph_writes_no_seam_sections);
    SW_RUN(test_empty_graph_is_valid);
    SW_RUN(test_seam_sections_are_skippable);
    SW_RUN(test_group_rules);
    SW_RUN(test_section_sizes);
    SW_RUN(test_header_rules);
    SW_RUN(test_vertex_fields);
    SW_RUN(test_vertex_children);
    SW_RUN(test_collapse_rules);
    SW_RUN(test_slot_rules);
    SW_RUN(test_slot_ref_rules);
    SW_RUN(test_surface_loop_rules);
    SW_RUN(test_loop_rules);
    SW_RUN(test_edge_rules);
    SW_RUN(test_first_problem_in_rule_order_is_named);
    SW_RUN(test_info_reports_seam_graph);
    return sw_test_finish();
}
