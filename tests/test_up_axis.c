/* SPDX-License-Identifier: MIT */
/* The up axis: its names, the pack's ORIENTATION section (written, read back,
 * absent in older packs, refused when malformed), which axis each kind of
 * input gets and how a build of several inputs chooses, and the scene's
 * up_axis key. The command line and the runtime's orbit are in
 * test_up_axis.sh. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <xxhash.h>

#include "sw_test.h"
#include "pack_sample.h"
#include "sw_scene.h"
#include "sw_up_axis.h"
#include "sw_up_inputs.h"

/* ---- names ---- */

static void test_names_parse_back_to_their_axis(void)
{
    const int32_t all[6] = { SW_UP_POS_X, SW_UP_NEG_X, SW_UP_POS_Y, SW_UP_NEG_Y, SW_UP_POS_Z,
                             SW_UP_NEG_Z };
    const char *names[6] = { "+x", "-x", "+y", "-y", "+z", "-z" };
    for (int i = 0; i < 6; i++) {
        int32_t got = 0;
        SW_CHECK(strcmp(sw_up_axis_name(all[i]), names[i]) == 0);
        SW_CHECK(sw_up_axis_parse(names[i], &got) && got == all[i]);
        SW_CHECK(sw_up_axis_valid(all[i]));
    }
    int32_t got = 0;
    SW_CHECK(sw_up_axis_parse("z", &got) && got == SW_UP_POS_Z);
    SW_CHECK(sw_up_axis_parse("y", &got) && got == SW_UP_POS_Y);
    SW_CHECK(SW_UP_DEFAULT == SW_UP_POS_Y);
}

static void test_other_text_is_no_axis(void)
{
    const char *bad[] = { "", "w", "+", "-", "xy", "X", "+-x", " x", "x ", "1", "up" };
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        int32_t got = 77;
        SW_CHECK_MSG(!sw_up_axis_parse(bad[i], &got) && got == 77, "'%s'", bad[i]);
    }
    int32_t got = 77;
    SW_CHECK(!sw_up_axis_parse(NULL, &got));
    SW_CHECK(!sw_up_axis_valid(0) && !sw_up_axis_valid(4) && !sw_up_axis_valid(-4));
    SW_CHECK(strcmp(sw_up_axis_name(0), "invalid") == 0);
}

static void test_vectors_are_the_unit_axes(void)
{
    sw_vec3 z = sw_up_axis_vector(SW_UP_POS_Z), nx = sw_up_axis_vector(SW_UP_NEG_X);
    SW_CHECK(z.x == 0 && z.y == 0 && z.z == 1);
    SW_CHECK(nx.x == -1 && nx.y == 0 && nx.z == 0);
    sw_vec3 fallback = sw_up_axis_vector(9);
    SW_CHECK(fallback.x == 0 && fallback.y == 1 && fallback.z == 0);
}

/* ---- the ORIENTATION section ---- */

static uint8_t *serialize_with(const sw_pack_orientation *o, size_t *size)
{
    sample s;
    make_sample(&s);
    sw_pack_contents c = sample_contents(&s);
    c.orientation = o;
    uint8_t *bytes = NULL;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_serialize(&c, &bytes, size, &err) == SW_OK, "%s", err.message);
    return bytes;
}

static sw_status open_bytes(const uint8_t *bytes, size_t size, sw_pack *pack, sw_error *err)
{
    memset(err, 0, sizeof *err);
    return sw_pack_open_memory(bytes, size, pack, err);
}

static void test_round_trip_keeps_the_up_axis(void)
{
    for (int32_t axis = -3; axis <= 3; axis++) {
        if (axis == 0)
            continue;
        sw_pack_orientation o = { .up_axis = axis };
        size_t size = 0;
        uint8_t *bytes = serialize_with(&o, &size);
        sw_pack pack;
        sw_error err;
        SW_CHECK_MSG(open_bytes(bytes, size, &pack, &err) == SW_OK, "%s", err.message);
        SW_CHECK(pack.orientation != NULL && sw_pack_up_axis(&pack) == axis);
        const sw_pack_section *last = &pack.sections[pack.header->section_count - 1];
        SW_CHECK(last->type == SW_SECTION_ORIENTATION && last->size == 16);
        SW_CHECK(pack.header->section_count == SAMPLE_SECTIONS + 1);
        SW_CHECK(strcmp(sw_section_type_name(last->type), "ORIENTATION") == 0);
        free(bytes);
    }
}

static void test_a_pack_without_the_section_is_y_up(void)
{
    size_t size = 0;
    uint8_t *bytes = serialize_with(NULL, &size);
    sw_pack pack;
    sw_error err;
    SW_CHECK_MSG(open_bytes(bytes, size, &pack, &err) == SW_OK, "%s", err.message);
    SW_CHECK(pack.orientation == NULL && sw_pack_up_axis(&pack) == SW_UP_POS_Y);
    SW_CHECK(pack.header->section_count == SAMPLE_SECTIONS);
    free(bytes);
}

static void expect_refused(const uint8_t *bytes, size_t size, const char *needle)
{
    sw_pack pack;
    sw_error err;
    sw_status st = open_bytes(bytes, size, &pack, &err);
    SW_CHECK_MSG(st == SW_ERR_FORMAT, "got %s: %s", sw_status_name(st), err.message);
    SW_CHECK_MSG(strstr(err.message, needle) != NULL, "\"%s\" not in \"%s\"", needle,
                 err.message);
}

static void test_a_bad_axis_or_reserved_byte_is_refused(void)
{
    const int32_t bad[] = { 0, 4, -4, 0x7fffffff };
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        sw_pack_orientation o = { .up_axis = bad[i] };
        size_t size = 0;
        uint8_t *bytes = serialize_with(&o, &size);
        char needle[64];
        snprintf(needle, sizeof needle, "(ORIENTATION): up_axis %d, expected", (int)bad[i]);
        expect_refused(bytes, size, needle);
        free(bytes);
    }
    sw_pack_orientation o = { .up_axis = SW_UP_POS_Z, .reserved = { [5] = 1 } };
    size_t size = 0;
    uint8_t *bytes = serialize_with(&o, &size);
    expect_refused(bytes, size, "ORIENTATION.reserved[5]: 0x01, expected 0");
    free(bytes);
}

/* Section i of the table made type, size bytes, its checksum and the
 * header's valid again. */
static void retype(uint8_t *bytes, uint32_t i, uint32_t type, uint64_t size)
{
    sw_pack_section *s = &table_of(bytes)[i];
    s->type = type;
    s->size = size;
    s->checksum = XXH3_64bits(bytes + s->offset, (size_t)size);
    reseal(bytes);
}

static void test_a_wrong_size_is_refused(void)
{
    sw_pack_orientation o = { .up_axis = SW_UP_POS_Z };
    size_t size = 0;
    uint8_t *bytes = serialize_with(&o, &size);
    retype(bytes, SAMPLE_SECTIONS, SW_SECTION_ORIENTATION, 12);
    expect_refused(bytes, size, "section 13 (ORIENTATION): 12 bytes, expected 16");
    free(bytes);
}

static void test_a_second_section_is_refused(void)
{
    sw_pack_orientation o = { .up_axis = SW_UP_POS_Z };
    size_t size = 0;
    uint8_t *bytes = serialize_with(&o, &size);
    /* VIEWPOINTS (section 11, optional) becomes a second, valid record. */
    SW_CHECK(table_of(bytes)[11].type == SW_SECTION_VIEWPOINTS);
    memcpy(bytes + table_of(bytes)[11].offset, &o, sizeof o);
    retype(bytes, 11, SW_SECTION_ORIENTATION, sizeof o);
    expect_refused(bytes, size, "section 13 (ORIENTATION): a second ORIENTATION section (the "
                   "first is section 11)");
    free(bytes);
}

/* ---- what a build chooses ---- */

static void test_each_input_kind_has_its_convention(void)
{
    SW_CHECK(sw_up_input_default("a/part.stp", 0) == SW_UP_POS_Z);
    SW_CHECK(sw_up_input_default("PART.STEP", 0) == SW_UP_POS_Z);
    SW_CHECK(sw_up_input_default("hammer.iges", 0) == SW_UP_POS_Z);
    SW_CHECK(sw_up_input_default("x.IGS", 0) == SW_UP_POS_Z);
    SW_CHECK(sw_up_input_default("teapot.txt", 0) == SW_UP_POS_Y);
    SW_CHECK(sw_up_input_default("saddle.bpt", 0) == SW_UP_POS_Y);
    SW_CHECK(sw_up_input_default("show.ini", 0) == SW_UP_POS_Y);
    SW_CHECK(sw_up_input_default("show.ini", SW_UP_NEG_X) == SW_UP_NEG_X);
    SW_CHECK(sw_up_input_default("teapot.txt", SW_UP_POS_Z) == SW_UP_POS_Y); /* not a scene */
    SW_CHECK(sw_up_input_default("dir.stp/teapot.txt", 0) == SW_UP_POS_Y);  /* by the file name */
}

/* sw_up_inputs_choose with its warning captured. */
static int32_t choose(const char *const *paths, const int32_t *defaults, int n, int32_t over,
                      char *warning, size_t cap)
{
    FILE *f = tmpfile();
    int32_t axis = sw_up_inputs_choose(paths, defaults, n, over, f);
    rewind(f);
    size_t got = fread(warning, 1, cap - 1, f);
    warning[got] = '\0';
    fclose(f);
    return axis;
}

static void test_inputs_that_differ_take_the_first_and_warn(void)
{
    const char *paths[3] = { "screw.step", "teapot.txt", "show.ini" };
    const int32_t defaults[3] = { SW_UP_POS_Z, SW_UP_POS_Y, SW_UP_POS_Y };
    char w[512];
    SW_CHECK(choose(paths, defaults, 3, 0, w, sizeof w) == SW_UP_POS_Z);
    SW_CHECK_MSG(strcmp(w, "warning: the inputs' up axes differ: screw.step (+z), teapot.txt "
                        "(+y), show.ini (+y); the pack takes the first input's, +z (--up "
                        "sets it)\n") == 0, "%s", w);
    SW_CHECK(choose(paths + 1, defaults + 1, 2, 0, w, sizeof w) == SW_UP_POS_Y);
    SW_CHECK_MSG(w[0] == '\0', "no warning when they agree: %s", w);
}

static void test_an_override_wins_silently(void)
{
    const char *paths[2] = { "screw.step", "teapot.txt" };
    const int32_t defaults[2] = { SW_UP_POS_Z, SW_UP_POS_Y };
    char w[512];
    SW_CHECK(choose(paths, defaults, 2, SW_UP_NEG_Y, w, sizeof w) == SW_UP_NEG_Y);
    SW_CHECK_MSG(w[0] == '\0', "%s", w);
}

/* ---- the scene key ---- */

static sw_status load_scene(const char *text, sw_model *model, sw_error *err)
{
    sw_model_init(model);
    memset(err, 0, sizeof *err);
    return sw_scene_load_memory(text, strlen(text), "s.ini", NULL, model, err);
}

static const char plate[] = "[part p]\ngenerate = plate\nsegments = 1\nholes = 0\n";

static void test_a_scene_says_its_up_axis_before_its_sections(void)
{
    char text[256];
    sw_model m;
    sw_error err;
    snprintf(text, sizeof text, "; z-up showroom\nup_axis = -z\n%s", plate);
    SW_CHECK_MSG(load_scene(text, &m, &err) == SW_OK, "%s", err.message);
    SW_CHECK(m.up_axis == SW_UP_NEG_Z);
    sw_model_free(&m);
    SW_CHECK_MSG(load_scene(plate, &m, &err) == SW_OK, "%s", err.message);
    SW_CHECK(m.up_axis == 0); /* not said: the build takes +y for a scene */
    sw_model_free(&m);
}

static void expect_scene_error(const char *text, const char *needle)
{
    sw_model m;
    sw_error err;
    SW_CHECK(load_scene(text, &m, &err) == SW_ERR_FORMAT);
    SW_CHECK_MSG(strstr(err.message, needle) != NULL, "\"%s\" not in \"%s\"", needle,
                 err.message);
    sw_model_free(&m);
}

static void test_a_bad_scene_up_axis_names_its_line(void)
{
    char text[256];
    snprintf(text, sizeof text, "up_axis = w\n%s", plate);
    expect_scene_error(text, "s.ini:1: up_axis: 'w', expected x, y, z, -x, -y or -z");
    snprintf(text, sizeof text, "up_axis = z\nup_axis = y\n%s", plate);
    expect_scene_error(text, "s.ini:2: key 'up_axis' given twice (first at line 1)");
    snprintf(text, sizeof text, "%sup_axis = z\n", plate);
    expect_scene_error(text, "s.ini:5: unknown key 'up_axis' in part 'p'");
    expect_scene_error("units = mm\n", "s.ini:1: key 'units' outside any section");
}

int main(void)
{
    SW_RUN(test_names_parse_back_to_their_axis);
    SW_RUN(test_other_text_is_no_axis);
    SW_RUN(test_vectors_are_the_unit_axes);
    SW_RUN(test_round_trip_keeps_the_up_axis);
    SW_RUN(test_a_pack_without_the_section_is_y_up);
    SW_RUN(test_a_bad_axis_or_reserved_byte_is_refused);
    SW_RUN(test_a_wrong_size_is_refused);
    SW_RUN(test_a_second_section_is_refused);
    SW_RUN(test_each_input_kind_has_its_convention);
    SW_RUN(test_inputs_that_differ_take_the_first_and_warn);
    SW_RUN(test_an_override_wins_silently);
    SW_RUN(test_a_scene_says_its_up_axis_before_its_sections);
    SW_RUN(test_a_bad_scene_up_axis_names_its_line);
    return sw_test_finish();
}
