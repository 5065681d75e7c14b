/* SPDX-License-Identifier: MIT */
/* The part levels in the pack: the sample's hand-made levels
 * (pack_sample.h) written and read back identical; the six sections
 * together or not at all; one refusal per validation rule, each made by
 * breaking one field of an otherwise valid pack (the writer recomputes the
 * checksums), each also opened with the checks' parts run backwards. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "sw_test.h"
#include "pack_sample.h"
#include "pack_expect.h"

static uint8_t *serialize_with(const sw_part_levels *pl, size_t *size)
{
    return serialize_sample_all(NULL, NULL, pl, size);
}

static void expect_rejected(const sample_part_levels *k, sw_status status, const char *needle)
{
    size_t size = 0;
    uint8_t *bytes = serialize_with(&k->view, &size);
    expect_open(bytes, size, status, needle);
    free(bytes);
}

static void test_round_trip(void)
{
    sample_part_levels k;
    make_sample_part_levels(&k);
    size_t size = 0;
    uint8_t *bytes = serialize_with(&k.view, &size);
    sw_pack pack;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_open_memory(bytes, size, &pack, &err) == SW_OK, "%s", err.message);
    const sw_part_levels *r = &pack.part_levels;
    SW_CHECK(r->level_count == 2 && r->piece_count == 2 && r->vertex_count == 7 &&
             r->index_count == 9 && r->surface_count == 2);
    SW_CHECK(memcmp(r->levels, k.levels, sizeof k.levels) == 0);
    SW_CHECK(memcmp(r->piece_levels, k.part_levels, 3 * sizeof *k.part_levels) == 0);
    SW_CHECK(memcmp(r->piece_of, k.piece_of, sizeof k.piece_of) == 0);
    SW_CHECK(memcmp(r->vertices, k.vertices, sizeof k.vertices) == 0);
    SW_CHECK(memcmp(r->indices, k.indices, sizeof k.indices) == 0);
    SW_CHECK(strcmp(sw_section_type_name(SW_SECTION_PART_LEVEL_INDICES),
                    "PART_LEVEL_INDICES") == 0);
    SW_CHECK(strcmp(sw_section_type_name(SW_SECTION_PART_LEVEL_PIECE_OF),
                    "PART_LEVEL_PIECE_OF") == 0);
    free(bytes);
    bytes = serialize_with(NULL, &size);
    SW_CHECK(sw_pack_open_memory(bytes, size, &pack, &err) == SW_OK);
    SW_CHECK(!pack.part_levels.levels && pack.part_levels.level_count == 0);
    free(bytes);
}

/* One of the six left out (its table entry renamed to an unknown type). */
static void test_group_incomplete(void)
{
    const uint32_t types[] = { SW_SECTION_PART_LEVEL_RANGES, SW_SECTION_PART_LEVEL_PIECE_OF };
    const char *needles[] = { "no PART_LEVEL_RANGES section", "no PART_LEVEL_PIECE_OF section" };
    for (int c = 0; c < 2; c++) {
        sample_part_levels k;
        make_sample_part_levels(&k);
        size_t size = 0;
        uint8_t *bytes = serialize_with(&k.view, &size);
        sw_pack_header *h = header_of(bytes);
        sw_pack_section *t = table_of(bytes);
        for (uint32_t i = 0; i < h->section_count; i++)
            if (t[i].type == types[c])
                t[i].type = 999;
        reseal(bytes);
        expect_open(bytes, size, SW_ERR_FORMAT, needles[c]);
        free(bytes);
    }
}

static void test_rules(void)
{
    sample_part_levels k;
    expect_rejected((make_sample_part_levels(&k), k.levels[1].piece = 1, &k), SW_ERR_FORMAT,
                    "PART_LEVEL_RECORDS[1].piece: 1, expected 0");
    expect_rejected((make_sample_part_levels(&k), k.levels[1].error = 0.1f, &k), SW_ERR_FORMAT,
                    "PART_LEVEL_RECORDS[1].error");
    expect_rejected((make_sample_part_levels(&k), k.levels[0].error = NAN, &k), SW_ERR_FORMAT,
                    "PART_LEVEL_RECORDS[0].error");
    expect_rejected((make_sample_part_levels(&k), k.levels[0].error = 0, &k), SW_ERR_FORMAT,
                    "PART_LEVEL_RECORDS[0].error");
    expect_rejected((make_sample_part_levels(&k), k.levels[1].vertex_count = 4, &k),
                    SW_ERR_RANGE, "PART_LEVEL_RECORDS[1]: vertices 4 + 4");
    expect_rejected((make_sample_part_levels(&k), k.levels[1].vertex_count = 2, &k),
                    SW_ERR_RANGE, "PART_LEVEL_RECORDS[1]: vertices 4 + 2");
    expect_rejected((make_sample_part_levels(&k), k.levels[0].index_count = 5, &k),
                    SW_ERR_RANGE, "PART_LEVEL_RECORDS[0]: indices 0 + 5");
    expect_rejected((make_sample_part_levels(&k), k.levels[1].index_count = 6, &k),
                    SW_ERR_RANGE, "PART_LEVEL_RECORDS[1]: indices 6 + 6");
    expect_rejected((make_sample_part_levels(&k), k.levels[1].front = SW_PART_LEVEL_WHOLE, &k),
                    SW_ERR_FORMAT, "PART_LEVEL_RECORDS[1].front: 255, expected below 1 (a part "
                    "not cut has one)");
    expect_rejected((make_sample_part_levels(&k), k.levels[1].front = 1, &k),
                    SW_ERR_FORMAT, "PART_LEVEL_RECORDS[1].front: 1, expected below 1 (a part "
                    "not cut has one)");
    expect_rejected((make_sample_part_levels(&k), k.levels[1].shading_side = -1, &k),
                    SW_ERR_FORMAT, "PART_LEVEL_RECORDS[1].shading_side: -1");
    expect_rejected((make_sample_part_levels(&k), k.levels[0].shading_side = NAN, &k),
                    SW_ERR_FORMAT, "PART_LEVEL_RECORDS[0].shading_side");
    expect_rejected((make_sample_part_levels(&k), k.indices[8] = 3, &k), SW_ERR_RANGE,
                    "PART_LEVEL_INDICES[8]: 3, expected < 3");
    expect_rejected((make_sample_part_levels(&k), k.part_levels[2] = 1, &k), SW_ERR_FORMAT,
                    "PART_LEVEL_RANGES: runs from 0 to 1, expected 0 to 2");
    expect_rejected((make_sample_part_levels(&k), k.part_levels[1] = 41, &k), SW_ERR_FORMAT,
                    "PART_LEVEL_RANGES[0]: 0 to 41, expected rising by at most 40 within the 2");
    expect_rejected((make_sample_part_levels(&k), k.piece_of[1] = 0, &k), SW_ERR_FORMAT,
                    "PART_LEVEL_PIECE_OF[1]: 0, expected 1 to 1 (a part's own pieces");
    expect_rejected((make_sample_part_levels(&k), k.piece_of[0] = 1, &k), SW_ERR_FORMAT,
                    "PART_LEVEL_PIECE_OF[0]: 1, expected 0 to 0");
    expect_rejected((make_sample_part_levels(&k), k.view.piece_count = 3, k.part_levels[3] = 2,
                     &k), SW_ERR_FORMAT, "PART_LEVEL_PIECE_OF: 2 pieces have surfaces, expected "
                    "all 3");
    expect_rejected((make_sample_part_levels(&k), k.vertices[5].p[1] = INFINITY, &k),
                    SW_ERR_FORMAT, "PART_LEVEL_VERTICES[5]");
    expect_rejected((make_sample_part_levels(&k), k.vertices[2].normal[3] = 1, &k),
                    SW_ERR_FORMAT, "PART_LEVEL_VERTICES[2]");
    expect_rejected((make_sample_part_levels(&k), k.view.piece_count = 1, &k), SW_ERR_FORMAT,
                    "PART_LEVEL_PIECE_OF[1]: 1, expected 1 to 0");
}

/* The counts record against the sections' sizes: one index fewer written
 * than PART_LEVELS says. */
static void test_counts_against_sizes(void)
{
    sample_part_levels k;
    make_sample_part_levels(&k);
    size_t size = 0;
    uint8_t *bytes = serialize_with(&k.view, &size);
    sw_pack_section *t = table_of(bytes);
    for (uint32_t i = 0; i < header_of(bytes)->section_count; i++)
        if (t[i].type == SW_SECTION_PART_LEVELS) {
            sw_pack_part_levels *h = (sw_pack_part_levels *)(bytes + t[i].offset);
            h->index_count = 12;
            t[i].checksum = XXH3_64bits(h, sizeof *h);
        }
    reseal(bytes);
    expect_open(bytes, size, SW_ERR_FORMAT, "(PART_LEVEL_INDICES): 9 records, expected 12");
    free(bytes);
}

int main(void)
{
    SW_RUN(test_round_trip);
    SW_RUN(test_group_incomplete);
    SW_RUN(test_rules);
    SW_RUN(test_counts_against_sizes);
    return sw_test_finish();
}
