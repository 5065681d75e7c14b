/* SPDX-License-Identifier: MIT */
/* The pack reader on the optional sections (trimmed surfaces, masks,
 * viewpoints, part transforms): which sections may appear together, how
 * their sizes are checked, and one refusal per record rule, each made with
 * valid checksums so the rule under test is the one that fires. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>
#include <xxhash.h>

#include "sw_test.h"
#include "pack_sample.h"

/* Serialises s and expects the reader to refuse it with status and a message
 * containing needle. */
static void expect_rejected(const sample *s, sw_status status, const char *needle)
{
    size_t size = 0;
    uint8_t *bytes = serialize_sample(s, &size);
    sw_pack pack;
    sw_error err = { 0 };
    sw_status got = sw_pack_open_memory(bytes, size, &pack, &err);
    SW_CHECK_MSG(got == status, "expected %s, got %s: %s", sw_status_name(status),
                 sw_status_name(got), err.message);
    SW_CHECK_MSG(strstr(err.message, needle) != NULL, "\"%s\" not in \"%s\"", needle, err.message);
    free(bytes);
}

static void expect_accepted(const sample *s)
{
    size_t size = 0;
    uint8_t *bytes = serialize_sample(s, &size);
    sw_pack pack;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_open_memory(bytes, size, &pack, &err) == SW_OK, "%s", err.message);
    free(bytes);
}

/* Serialises the sample, lets edit change its table, reseals every checksum
 * and expects needle in the reader's refusal. */
static void expect_table_rejected(void (*edit)(uint8_t *bytes), const char *needle)
{
    sample s;
    make_sample(&s);
    size_t size = 0;
    uint8_t *bytes = serialize_sample(&s, &size);
    edit(bytes);
    reseal_all(bytes);
    sw_pack pack;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_open_memory(bytes, size, &pack, &err) != SW_OK &&
                 strstr(err.message, needle), "\"%s\" not in \"%s\"", needle, err.message);
    free(bytes);
}

/* ---- which sections, and their sizes ---- */

static void retype_domains(uint8_t *b) { table_of(b)[entry_of(b, SW_SECTION_PATCH_DOMAINS)].type = 77; }
static void retype_surfaces(uint8_t *b) { table_of(b)[entry_of(b, SW_SECTION_SURFACES)].type = 77; }
static void retype_masks_as_loops(uint8_t *b)
{
    table_of(b)[entry_of(b, SW_SECTION_TRIM_MASKS)].type = SW_SECTION_TRIM_LOOPS;
}
static void shrink_surfaces(uint8_t *b) { table_of(b)[entry_of(b, SW_SECTION_SURFACES)].size -= 4; }
static void shrink_trim_data(uint8_t *b) { table_of(b)[entry_of(b, SW_SECTION_TRIM_DATA)].size -= 2; }
static void shrink_domains(uint8_t *b) { table_of(b)[entry_of(b, SW_SECTION_PATCH_DOMAINS)].size -= 24; }
static void shrink_transforms(uint8_t *b)
{
    table_of(b)[entry_of(b, SW_SECTION_PART_TRANSFORMS)].size -= 64;
}
static void drop_one_curve(uint8_t *b) { table_of(b)[entry_of(b, SW_SECTION_TRIM_CURVES)].size -= 16; }

static void test_group_rules(void)
{
    expect_table_rejected(retype_domains, "section 5 (SURFACES): no PATCH_DOMAINS section "
                                          "(required with SURFACES)");
    expect_table_rejected(retype_surfaces, "section 6 (TRIM_LOOPS): present without a SURFACES "
                                           "section");
    expect_table_rejected(retype_masks_as_loops, "section 10 (TRIM_LOOPS): a second TRIM_LOOPS "
                                                 "section (the first is section 6)");
}

static void test_optional_section_sizes(void)
{
    expect_table_rejected(shrink_surfaces, "section 5 (SURFACES): 76 bytes, not a multiple of "
                                           "its 40-byte record");
    expect_table_rejected(shrink_trim_data, "section 8 (TRIM_DATA): 242 bytes, not a multiple "
                                            "of its 4-byte record");
    expect_table_rejected(shrink_domains, "section 9 (PATCH_DOMAINS): 48 bytes, expected "
                                          "META.patch_count 3 x 24 = 72");
    expect_table_rejected(shrink_transforms, "section 12 (PART_TRANSFORMS): 64 bytes, expected "
                                             "META.part_count 2 x 64 = 128");
    /* One curve fewer: the count follows the size, so loop 1 now points past it. */
    expect_table_rejected(drop_one_curve, "TRIM_LOOPS[1].first_curve: 1 + curve_count 1 exceeds "
                                          "TRIM_CURVES count 1");
}

static void test_viewpoints_and_transforms_stand_alone(void)
{
    sample s;
    make_sample(&s);
    s.bezier_only = 1;
    sw_pack_contents c = sample_contents(&s);
    c.viewpoints = s.viewpoints;
    c.viewpoint_count = 1;
    c.part_transforms = s.transforms;
    uint8_t *bytes = NULL;
    size_t size = 0;
    sw_error err = { 0 };
    SW_CHECK(sw_pack_serialize(&c, &bytes, &size, &err) == SW_OK);
    sw_pack pack;
    SW_CHECK_MSG(sw_pack_open_memory(bytes, size, &pack, &err) == SW_OK, "%s", err.message);
    SW_CHECK(pack.header->section_count == 7 && !pack.surfaces && pack.viewpoint_count == 1 &&
             pack.part_transforms && pack.part_transforms[16 + 12] == 1.0f);
    free(bytes);
}

/* ---- SURFACES ---- */

static void test_surface_rules(void)
{
    sample s;
    make_sample(&s);
    s.surfaces[1].part = 2;
    expect_rejected(&s, SW_ERR_RANGE, "SURFACES[1].part: 2, but PARTS has 2 entries");
    make_sample(&s);
    s.surfaces[1].part = 0; /* patch 2 belongs to part 1 */
    expect_rejected(&s, SW_ERR_RANGE, "SURFACES[1].first_patch: 2 + patch_count 1 is outside "
                                      "PARTS[0]'s patches [0, 2)");
    make_sample(&s);
    s.surfaces[0].patch_count = UINT32_MAX; /* must not wrap around */
    expect_rejected(&s, SW_ERR_RANGE, "SURFACES[0].first_patch: 0 + patch_count 4294967295");
    make_sample(&s);
    s.surfaces[1].first_loop = 1;
    s.surfaces[1].loop_count = 2;
    expect_rejected(&s, SW_ERR_RANGE, "SURFACES[1].first_loop: 1 + loop_count 2 exceeds "
                                      "TRIM_LOOPS count 2");
    make_sample(&s);
    s.surfaces[0].flags = 4;
    expect_rejected(&s, SW_ERR_FORMAT, "SURFACES[0].flags: 0x4, expected 0");
    make_sample(&s);
    s.surfaces[0].domain[3] = INFINITY;
    expect_rejected(&s, SW_ERR_FORMAT, "SURFACES[0].domain: v range 0..inf is not finite");
    make_sample(&s);
    s.surfaces[1].domain[0] = 1;
    expect_rejected(&s, SW_ERR_FORMAT, "SURFACES[1].domain: u0 1 >= u1 1");
}

/* Parts 0 and 1 may overlap, so surface 0 can reach into patch 2. */
static void test_surface_ranges_must_not_overlap(void)
{
    sample s;
    make_sample(&s);
    s.parts[0].patch_count = 3;
    s.surfaces[0].patch_count = 3;
    expect_rejected(&s, SW_ERR_RANGE, "SURFACES[0].first_patch: its patches [0, 3) include "
                                      "patch 2 of SURFACES[1]");
}

/* ---- PATCH_DOMAINS ---- */

static void test_patch_domain_rules(void)
{
    sample s;
    make_sample(&s);
    s.domains[2].surface = 2;
    expect_rejected(&s, SW_ERR_RANGE, "PATCH_DOMAINS[2].surface: 2, but SURFACES has 2 entries");
    make_sample(&s);
    s.domains[2].surface = 0;
    expect_rejected(&s, SW_ERR_RANGE, "PATCH_DOMAINS[2].surface: 0, but that surface holds "
                                      "patches [0, 2)");
    make_sample(&s);
    s.domains[1].mask = 1;
    expect_rejected(&s, SW_ERR_RANGE, "PATCH_DOMAINS[1].mask: 1, but TRIM_MASKS has 1 entries");
    make_sample(&s);
    s.domains[0].domain[1] = NAN;
    expect_rejected(&s, SW_ERR_FORMAT, "PATCH_DOMAINS[0].domain: u range 0..nan is not finite");
    make_sample(&s);
    s.domains[0].domain[2] = 1;
    expect_rejected(&s, SW_ERR_FORMAT, "PATCH_DOMAINS[0].domain: v0 1 >= v1 1");
    make_sample(&s);
    s.domains[1].domain[1] = 2.5f;
    expect_rejected(&s, SW_ERR_RANGE, "PATCH_DOMAINS[1].domain: u range 1..2.5 is outside "
                                      "SURFACES[0]'s 0..2");
}

static void test_patch_domain_may_exceed_surface_by_float_rounding(void)
{
    sample s;
    make_sample(&s);
    s.domains[1].domain[1] = nextafterf(2.0f, 3.0f);
    expect_accepted(&s);
    s.domains[1].domain[1] = 2.0f + 16 * FLT_EPSILON;
    expect_rejected(&s, SW_ERR_RANGE, "PATCH_DOMAINS[1].domain: u range");
}

/* ---- TRIM_LOOPS ---- */

static void test_loop_rules(void)
{
    sample s;
    make_sample(&s);
    s.loops[1].curve_count = 0;
    expect_rejected(&s, SW_ERR_FORMAT, "TRIM_LOOPS[1].curve_count: 0, expected at least 1");
    make_sample(&s);
    s.loops[1].first_curve = UINT32_MAX; /* must not wrap around */
    expect_rejected(&s, SW_ERR_RANGE, "TRIM_LOOPS[1].first_curve: 4294967295 + curve_count 1 "
                                      "exceeds TRIM_CURVES count 2");
    make_sample(&s);
    s.loops[0].flags = 2;
    expect_rejected(&s, SW_ERR_FORMAT, "TRIM_LOOPS[0].flags: 0x2 has unknown bits");
}

/* ---- TRIM_CURVES and TRIM_DATA ---- */

static void test_curve_fields(void)
{
    sample s;
    make_sample(&s);
    s.curves[0].degree = 0;
    expect_rejected(&s, SW_ERR_FORMAT, "TRIM_CURVES[0].degree: 0, expected 1..15");
    s.curves[0].degree = 16;
    expect_rejected(&s, SW_ERR_FORMAT, "TRIM_CURVES[0].degree: 16, expected 1..15");
    make_sample(&s);
    s.curves[1].flags = 4;
    expect_rejected(&s, SW_ERR_FORMAT, "TRIM_CURVES[1].flags: 0x4 has unknown bits");
    make_sample(&s);
    s.curves[1].reserved2 = 9;
    expect_rejected(&s, SW_ERR_FORMAT, "TRIM_CURVES[1].reserved2: 9, expected 0");
    make_sample(&s);
    s.curves[1].count = 2; /* a quadratic needs 3 points */
    expect_rejected(&s, SW_ERR_FORMAT, "TRIM_CURVES[1].count: 2, expected at least degree + 1 = 3");
    make_sample(&s);
    s.curves[1].first_float = CIRCLE_AT + 1;
    expect_rejected(&s, SW_ERR_RANGE, "TRIM_CURVES[1].first_float: 23 + 39 floats exceeds "
                                      "TRIM_DATA count 61");
    s.curves[1].first_float = UINT32_MAX; /* must not wrap around */
    expect_rejected(&s, SW_ERR_RANGE, "TRIM_CURVES[1].first_float: 4294967295 + 39 floats");
    make_sample(&s);
    s.curves[1].count = UINT32_MAX;
    expect_rejected(&s, SW_ERR_RANGE, "TRIM_CURVES[1].first_float: 22 + 17179869183 floats");
}

static void test_curve_knots(void)
{
    sample s;
    make_sample(&s);
    s.trim_data[RECT_AT + 3] = 0.5f;
    expect_rejected(&s, SW_ERR_FORMAT, "TRIM_CURVES[0].knots[3]: 0.5 < knots[2] 1, expected "
                                       "non-decreasing");
    make_sample(&s);
    s.trim_data[RECT_AT + 1] = 0.5f;
    expect_rejected(&s, SW_ERR_FORMAT, "TRIM_CURVES[0].knots[1]: 0.5, expected 0 (clamped");
    make_sample(&s);
    s.trim_data[CIRCLE_AT + 9] = 3.5f;
    expect_rejected(&s, SW_ERR_FORMAT, "TRIM_CURVES[1].knots[9]: 3.5, expected 4 (clamped");
    make_sample(&s);
    for (int k = 0; k < 7; k++)
        s.trim_data[RECT_AT + k] = 2.0f;
    expect_rejected(&s, SW_ERR_FORMAT, "TRIM_CURVES[0].knots: empty range 2..2");
}

static void test_curve_weights_and_data(void)
{
    sample s;
    make_sample(&s);
    s.trim_data[CIRCLE_AT + 12 + 3 * 3 + 2] = 0.0f;
    expect_rejected(&s, SW_ERR_RANGE, "TRIM_CURVES[1].points[3].w: 0, expected > 0");
    make_sample(&s);
    s.trim_data[RECT_AT + 7 + 3 * 4 + 2] = 2.0f;
    expect_rejected(&s, SW_ERR_FORMAT, "TRIM_CURVES[0].points[4].w: 2, expected 1 (the curve is "
                                       "not rational)");
    make_sample(&s);
    s.trim_data[40] = NAN;
    expect_rejected(&s, SW_ERR_FORMAT, "TRIM_DATA[40]: nan, expected a finite number");
}

/* ---- VIEWPOINTS and PART_TRANSFORMS ---- */

static void test_viewpoint_rules(void)
{
    sample s;
    make_sample(&s);
    memset(s.viewpoints[0].name, 'v', sizeof s.viewpoints[0].name);
    expect_rejected(&s, SW_ERR_FORMAT, "VIEWPOINTS[0].name: no NUL in its 48 bytes");
    make_sample(&s);
    strcpy(s.viewpoints[0].name, "entr\xe9"); /* Latin-1 */
    expect_rejected(&s, SW_ERR_FORMAT, "VIEWPOINTS[0].name: invalid UTF-8 at byte 4");
    make_sample(&s);
    s.viewpoints[0].eye[1] = INFINITY;
    expect_rejected(&s, SW_ERR_FORMAT, "VIEWPOINTS[0].eye.y: inf, expected a finite number");
    make_sample(&s);
    s.viewpoints[0].up[2] = NAN;
    expect_rejected(&s, SW_ERR_FORMAT, "VIEWPOINTS[0].up.z: nan");
    make_sample(&s);
    s.viewpoints[0].target[2] = 3;
    expect_rejected(&s, SW_ERR_FORMAT, "VIEWPOINTS[0].target: equals eye (1, 0.5, 3)");
    make_sample(&s);
    s.viewpoints[0].up[1] = 0;
    expect_rejected(&s, SW_ERR_FORMAT, "VIEWPOINTS[0].up: the zero vector");
    make_sample(&s);
    s.viewpoints[0].fov_deg = 180;
    expect_rejected(&s, SW_ERR_FORMAT, "VIEWPOINTS[0].fov_deg: 180, expected 0 (the default)");
    make_sample(&s);
    s.viewpoints[0].reserved[7] = 1;
    expect_rejected(&s, SW_ERR_FORMAT, "VIEWPOINTS[0].reserved[7]: 0x01, expected 0");
}

static void test_part_transform_rules(void)
{
    sample s;
    make_sample(&s);
    s.transforms[16 + 13] = NAN;
    expect_rejected(&s, SW_ERR_FORMAT, "PART_TRANSFORMS[1][13]: nan, expected a finite number");
    make_sample(&s);
    s.transforms[3] = 0.5f; /* a projective map */
    expect_rejected(&s, SW_ERR_FORMAT, "PART_TRANSFORMS[0][3]: 0.5, expected 0 (the last row of "
                                       "an affine map is 0 0 0 1)");
    make_sample(&s);
    s.transforms[16 + 15] = 2;
    expect_rejected(&s, SW_ERR_FORMAT, "PART_TRANSFORMS[1][15]: 2, expected 1");
}

int main(void)
{
    SW_RUN(test_group_rules);
    SW_RUN(test_optional_section_sizes);
    SW_RUN(test_viewpoints_and_transforms_stand_alone);
    SW_RUN(test_surface_rules);
    SW_RUN(test_surface_ranges_must_not_overlap);
    SW_RUN(test_patch_domain_rules);
    SW_RUN(test_patch_domain_may_exceed_surface_by_float_rounding);
    SW_RUN(test_loop_rules);
    SW_RUN(test_curve_fields);
    SW_RUN(test_curve_knots);
    SW_RUN(test_curve_weights_and_data);
    SW_RUN(test_viewpoint_rules);
    SW_RUN(test_part_transform_rules);
    return sw_test_finish();
}
