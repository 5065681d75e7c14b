/* SPDX-License-Identifier: MIT */
/* The super-surfaces in the pack: the sample's hand-built clusters
 * (pack_sample.h) written and read back identical; which sections must
 * appear together and how their sizes are checked; one refusal per
 * validation rule, each made by breaking one field of an otherwise valid
 * pack (the writer recomputes the checksums), each also opened with the
 * checks' parts run backwards; the info report's lines. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "sw_test.h"
#include "pack_sample.h"
#include "pack_expect.h"
#include "sw_pack_info.h"

/* The sample with its graph and the (edited) clusters k, serialised;
 * members and super_of cut to list_count entries. malloc'd. */
static uint8_t *serialize_with(const sample_supers *k, uint32_t list_count, size_t *size)
{
    sw_supers v = k->view;
    v.surface_count = list_count;
    return serialize_sample_with(NULL, &v, size);
}

static void expect_rejected(const sample_supers *k, sw_status status, const char *needle)
{
    size_t size = 0;
    uint8_t *bytes = serialize_with(k, 2, &size);
    expect_open(bytes, size, status, needle);
    free(bytes);
}

static sample_supers *fresh(sample_supers *k)
{
    make_sample_supers(k);
    return k;
}

/* The sample with its graph and the clusters k (NULL: none) opened into
 * *pack; the bytes it views, malloc'd. */
static uint8_t *open_with(const sw_supers *k, sw_pack *pack)
{
    size_t size = 0;
    uint8_t *bytes = serialize_sample_with(NULL, k, &size);
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_open_memory(bytes, size, pack, &err) == SW_OK, "%s", err.message);
    return bytes;
}

static void test_round_trip(void)
{
    sample_supers k;
    make_sample_supers(&k);
    sw_pack pack;
    uint8_t *bytes = open_with(&k.view, &pack);
    const sw_supers *r = &pack.supers;
    SW_CHECK(r->super_count == 2 && r->surface_count == 2);
    SW_CHECK(memcmp(r->supers, k.supers, sizeof k.supers) == 0);
    SW_CHECK(memcmp(r->members, k.members, sizeof k.members) == 0);
    SW_CHECK(memcmp(r->super_of, k.super_of, sizeof k.super_of) == 0);
    /* The three come last, in type order, after the seam group's 21. */
    SW_CHECK(pack.header->section_count == 24);
    for (uint32_t i = 21; i < 24; i++)
        SW_CHECK(pack.sections[i].type == SW_SECTION_SUPER_SURFACES + (i - 21));
    SW_CHECK(strcmp(sw_section_type_name(SW_SECTION_SUPER_OF), "SUPER_OF") == 0);
    free(bytes);
}

static void test_absent_is_empty(void)
{
    sw_pack pack;
    uint8_t *bytes = open_with(NULL, &pack);
    SW_CHECK(!pack.supers.supers && !pack.supers.members && pack.supers.super_count == 0);
    free(bytes);
}

/* SUPER_MEMBERS and SUPER_OF one entry short: a truncated list. */
static void test_truncated_lists(void)
{
    sample_supers k;
    make_sample_supers(&k);
    size_t size = 0;
    uint8_t *bytes = serialize_with(&k, 1, &size);
    expect_open(bytes, size, SW_ERR_FORMAT, "(SUPER_MEMBERS): 1 entries, expected one per "
                "surface (2)");
    free(bytes);
}

/* The sample's clusters written, their table entry of type edited by
 * edit, every checksum made again: refused with status and needle. */
static void expect_table_edit(uint32_t type, void (*edit)(sw_pack_section *), sw_status status,
                              const char *needle)
{
    sample_supers k;
    make_sample_supers(&k);
    size_t size = 0;
    uint8_t *bytes = serialize_with(&k, 2, &size);
    edit(&table_of(bytes)[entry_of(bytes, type)]);
    reseal_all(bytes);
    expect_open(bytes, size, status, needle);
    free(bytes);
}

static void shorten(sw_pack_section *s) { s->size -= 4; }
static void rename_unknown(sw_pack_section *s) { s->type = 999; }

/* A section whose bytes are no whole number of records. */
static void test_partial_record(void)
{
    expect_table_edit(SW_SECTION_SUPER_SURFACES, shorten, SW_ERR_FORMAT,
                      "(SUPER_SURFACES): 60 bytes, expected a multiple of 32");
}

/* One of the three left out (its type renamed to an unknown one). */
static void test_group_together(void)
{
    expect_table_edit(SW_SECTION_SUPER_OF, rename_unknown, SW_ERR_FORMAT,
                      "no SUPER_OF section (the super-surfaces' three sections appear together)");
}

static void test_record_rules(void)
{
    sample_supers k;
    fresh(&k)->members[1] = 7;
    expect_rejected(&k, SW_ERR_RANGE, "SUPER_MEMBERS[1]: surface 7, expected < 2");
    /* Surface 0 in both records (both of part 0): SUPER_OF gives it to one. */
    fresh(&k)->members[1] = 0;
    k.supers[1].part = 0;
    expect_rejected(&k, SW_ERR_FORMAT, "SUPER_MEMBERS[1]: surface 0 in super-surface 1, but "
                    "SUPER_OF[0] is 0 (every surface is in exactly one)");
    fresh(&k)->supers[0].span = NAN;
    expect_rejected(&k, SW_ERR_FORMAT, "SUPER_SURFACES[0].span: nan, expected finite radians "
                    "in [0, pi]");
    fresh(&k)->supers[0].span = -0.5f;
    expect_rejected(&k, SW_ERR_FORMAT, "SUPER_SURFACES[0].span: -0.5");
    fresh(&k)->supers[1].span = 4.0f;
    expect_rejected(&k, SW_ERR_FORMAT, "SUPER_SURFACES[1].span: 4");
    fresh(&k)->supers[0].axis[2] = 0.5f;
    expect_rejected(&k, SW_ERR_FORMAT, "SUPER_SURFACES[0].axis: length 0.5, expected 1");
    fresh(&k)->supers[1].axis[0] = 1.0f;
    expect_rejected(&k, SW_ERR_FORMAT, "SUPER_SURFACES[1].axis: length 1, expected 0");
    fresh(&k)->supers[1].part = 0;
    expect_rejected(&k, SW_ERR_FORMAT, "SUPER_MEMBERS[1]: surface 1 of part 1 in super-surface "
                    "1 of part 0");
    fresh(&k)->supers[1].part = 5;
    expect_rejected(&k, SW_ERR_RANGE, "SUPER_SURFACES[1].part: 5, expected < 2");
    fresh(&k)->supers[0].member_count = 0;
    expect_rejected(&k, SW_ERR_FORMAT, "SUPER_SURFACES[0].member_count: 0, expected >= 1");
    fresh(&k)->supers[1].first_member = 0;
    expect_rejected(&k, SW_ERR_FORMAT, "SUPER_SURFACES[1].first_member: 0, expected 1");
    fresh(&k)->supers[0].reserved = 3;
    expect_rejected(&k, SW_ERR_FORMAT, "SUPER_SURFACES[0].reserved: 3, expected 0");
    fresh(&k)->super_of[1] = 2;
    expect_rejected(&k, SW_ERR_RANGE, "SUPER_OF[1]: 2, expected < 2");
}

/* One record holding both surfaces: members must still be one part's,
 * and fewer records than listed members are caught at the end. */
static void test_list_rules(void)
{
    sample_supers k;
    fresh(&k);
    k.supers[0].member_count = 2;
    k.super_of[1] = 0;
    view_sample_supers(&k, 1);
    expect_rejected(&k, SW_ERR_FORMAT, "SUPER_MEMBERS[1]: surface 1 of part 1 in super-surface "
                    "0 of part 0");
    fresh(&k);
    view_sample_supers(&k, 1);
    k.super_of[1] = 0;
    expect_rejected(&k, SW_ERR_FORMAT, "SUPER_SURFACES: members of 1 surfaces, expected every "
                    "one of the 2");
}

static void test_info(void)
{
    sample_supers k;
    make_sample_supers(&k);
    sw_pack pack;
    uint8_t *bytes = open_with(&k.view, &pack);
    sw_error err = { 0 };
    sw_pack_super_stats st;
    SW_CHECK(sw_pack_gather_super_stats(&pack, &st, &err) == SW_OK);
    SW_CHECK(st.supers == 2 && st.members_min == 1 && st.members_max == 1 && st.no_cone == 1);
    SW_CHECK(st.span_max_cone == 0.35f && st.span_median == 0.35f && !st.with_triangles);
    SW_CHECK(st.bytes == 64 + 8 + 8);
    char text[4096];
    FILE *f = fmemopen(text, sizeof text, "w");
    sw_pack_print_super_json(f, &pack, &st);
    fclose(f);
    SW_CHECK_MSG(strstr(text, "\"super_surfaces\": {\"count\": 2, \"members\": [1, 1, 1]") &&
                 strstr(text, "\"finest_triangles\": null"), "%s", text);
    free(bytes);
}

int main(void)
{
    SW_RUN(test_round_trip);
    SW_RUN(test_absent_is_empty);
    SW_RUN(test_truncated_lists);
    SW_RUN(test_partial_record);
    SW_RUN(test_group_together);
    SW_RUN(test_record_rules);
    SW_RUN(test_list_rules);
    SW_RUN(test_info);
    return sw_test_finish();
}
