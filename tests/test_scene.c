/* SPDX-License-Identifier: MIT */
/* Specification of showroom scene files (sw_scene.h).
 * Usage: test_scene SAMPLES_DIR. Files the cases need are written to a
 * scratch folder under /tmp, removed at the end. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "sw_procedural.h"
#include "sw_scene.h"
#include "sw_test.h"

static const char *samples_dir;

/* Loads a scene from an exactly sized heap copy (no NUL terminator, so
 * reading past the end trips AddressSanitizer), resolving against samples. */
static sw_status load(const char *text, sw_model *model, sw_error *err)
{
    size_t size = strlen(text);
    char *copy = malloc(size ? size : 1);
    memcpy(copy, text, size);
    sw_status st = sw_scene_load_memory(copy, size, "s.ini", samples_dir, model, err);
    free(copy);
    return st;
}

static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "wb");
    SW_CHECK_MSG(f != NULL, "cannot write %s", path);
    if (f) {
        fputs(text, f);
        fclose(f);
    }
}

static void check_error(sw_status st, const sw_error *err, sw_status want, const char *piece1,
                        const char *piece2)
{
    SW_CHECK_MSG(st == want, "status %s, want %s (%s)", sw_status_name(st), sw_status_name(want),
                 err->message);
    SW_CHECK_MSG(strstr(err->message, piece1) != NULL, "'%s' not in '%s'", piece1, err->message);
    if (piece2)
        SW_CHECK_MSG(strstr(err->message, piece2) != NULL, "'%s' not in '%s'", piece2,
                     err->message);
}

static const double *first_ctrl(const sw_model *m, size_t part)
{
    return m->patches[m->parts[part].first_patch].ctrl;
}

static void teaset_sample_has_three_parts_standing_on_one_floor(void)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/teaset.ini", samples_dir);
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK_MSG(sw_scene_load(path, &m, &err) == SW_OK, "%s", err.message);
    SW_CHECK(m.part_count == 3 && m.patch_count == 28 + 26 + 16);
    if (m.part_count != 3) {
        sw_model_free(&m);
        return;
    }
    static const char *const names[3] = {"teapot", "teacup", "teaspoon"};
    static const size_t patches[3] = {28, 26, 16};
    for (size_t p = 0; p < 3; p++) {
        SW_CHECK(strcmp(m.parts[p].name, names[p]) == 0);
        SW_CHECK(m.parts[p].patch_count == patches[p]);
        double min_y = INFINITY;
        const sw_model_part *part = &m.parts[p];
        for (size_t i = part->first_patch; i < part->first_patch + part->patch_count; i++) {
            for (int k = 0; k < 16; k++)
                min_y = fmin(min_y, m.patches[i].ctrl[4 * k + 1]);
        }
        SW_CHECK_NEAR(min_y, 0.0, 1e-6);
    }
    SW_CHECK(m.parts[0].color[0] == 0.16f && m.parts[0].color[2] == 0.62f);
    SW_CHECK(m.parts[0].color[3] == 1.0f);
    sw_box box = sw_model_box(&m);
    SW_CHECK(box.max.z > 1.0 && box.min.x < -0.8);
    sw_model_free(&m);
}

/* scale 2, then 90 degrees about z, then translate: the saddle's first point
 * (-1, 1.5, -1.5) becomes (-2, 3, -3), then (-3, -2, -3), then (7, -2, -6). */
static void transforms_apply_scale_then_rotate_then_translate(void)
{
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK_MSG(load("[part s]\nfile = saddle.bpt\ntranslate = 10 0 -3\nscale = 2\n"
                      "rotate = 0 0 1 90\n",
                      &m, &err) == SW_OK,
                 "%s", err.message);
    if (m.part_count == 1) {
        const double *c = first_ctrl(&m, 0);
        SW_CHECK_NEAR(c[0], 7.0, 1e-12);
        SW_CHECK_NEAR(c[1], -2.0, 1e-12);
        SW_CHECK_NEAR(c[2], -6.0, 1e-12);
        SW_CHECK(c[3] == 1.0);
    }
    sw_model_free(&m);
}

static void scale_and_translate_are_exact(void)
{
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK(load("[part s]\nfile = saddle.bpt\nscale = 2 4 0.5\ntranslate = 1 2 3\n", &m,
                  &err) == SW_OK);
    if (m.part_count == 1) {
        const double *c = first_ctrl(&m, 0); /* (-1, 1.5, -1.5) */
        SW_CHECK(c[0] == -1.0 && c[1] == 8.0 && c[2] == 2.25);
    }
    sw_model_free(&m);
}

static void rotation_is_right_handed_in_degrees(void)
{
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    /* about +y by 90: +x goes to -z */
    SW_CHECK(load("[part s]\nfile = saddle.bpt\nrotate = 0 2 0 90\n", &m, &err) == SW_OK);
    if (m.part_count == 1) {
        const double *c = m.patches[0].ctrl + 4 * 2; /* (1, -1.5, -1.5) */
        SW_CHECK_NEAR(c[0], -1.5, 1e-12);
        SW_CHECK_NEAR(c[1], -1.5, 1e-12);
        SW_CHECK_NEAR(c[2], -1.0, 1e-12);
    }
    sw_model_free(&m);
}

static void colours_names_and_defaults(void)
{
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK(load("# two parts\n[part first one]\nfile = saddle.bpt\ncolor = 0.25 0.5 1 0.75"
                  "  ; translucent\n\n[part second]\nfile=saddle.bpt\n",
                  &m, &err) == SW_OK);
    SW_CHECK(m.part_count == 2);
    if (m.part_count == 2) {
        SW_CHECK(strcmp(m.parts[0].name, "first one") == 0);
        SW_CHECK(m.parts[0].color[0] == 0.25f && m.parts[0].color[1] == 0.5f);
        SW_CHECK(m.parts[0].color[2] == 1.0f && m.parts[0].color[3] == 0.75f);
        float want[4];
        sw_scene_default_color(1, want);
        SW_CHECK(memcmp(m.parts[1].color, want, sizeof want) == 0);
        SW_CHECK(m.parts[1].first_patch == 2 && m.parts[1].patch_count == 2);
    }
    sw_model_free(&m);
}

static void files_resolve_against_the_scene_folder(void)
{
    /* the test runs in a scratch folder: a scene here naming a file here */
    write_file("here.bpt", "1\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 7\n");
    write_file("here.ini", "[part h]\nfile = here.bpt\n");
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK_MSG(sw_scene_load("here.ini", &m, &err) == SW_OK, "%s", err.message);
    SW_CHECK(m.patch_count == 1 && m.patches[0].ctrl[14] == 7);
    sw_model_free(&m);
    /* an absolute path ignores the base folder */
    char text[4200];
    snprintf(text, sizeof text, "[part a]\nfile = %s/saddle.bpt\n", samples_dir);
    sw_model_init(&m);
    SW_CHECK(sw_scene_load_memory(text, strlen(text), "a.ini", "/nonexistent", &m, &err) ==
             SW_OK);
    SW_CHECK(m.patch_count == 2);
    sw_model_free(&m);
}

static void errors_name_file_and_line(void)
{
    static const struct {
        const char *text;
        sw_status status;
        const char *piece1, *piece2;
    } cases[] = {
        {"[part a]\nfile = saddle.bpt\ncolour = 1 0 0\n", SW_ERR_FORMAT, "s.ini:3:",
         "unknown key 'colour'"},
        {"[part a]\nfile = saddle.bpt\nscale = big\n", SW_ERR_FORMAT, "s.ini:3:",
         "scale: 'big' is not a finite number"},
        {"[part a]\nfile = saddle.bpt\nscale = 1 2\n", SW_ERR_FORMAT, "s.ini:3:",
         "expected 1 or 3 numbers"},
        {"[part a]\nfile = saddle.bpt\nscale = 0\n", SW_ERR_RANGE, "s.ini:3:", "not be zero"},
        {"[part a]\nfile = saddle.bpt\ntranslate = 1 2\n", SW_ERR_FORMAT, "s.ini:3:",
         "translate: expected 3 numbers, found 2"},
        {"[part a]\nfile = saddle.bpt\ntranslate = 1 2 3 4\n", SW_ERR_FORMAT, "s.ini:3:",
         "at most 3"},
        {"[part a]\nfile = saddle.bpt\nrotate = 0 0 0 90\n", SW_ERR_RANGE, "s.ini:3:", "axis"},
        {"[part a]\nfile = saddle.bpt\ncolor = 1 0 2\n", SW_ERR_RANGE, "s.ini:3:",
         "color: 2 is outside 0..1"},
        {"[part a]\nfile = saddle.bpt\ncolor = 1 0 nan\n", SW_ERR_FORMAT, "s.ini:3:", "nan"},
        {"\n[part a]\nfile = nope.txt\n", SW_ERR_IO, "s.ini:3: part 'a':", "nope.txt"},
        {"[part a]\nfile = saddle.obj\n", SW_ERR_UNSUPPORTED, "s.ini:2: part 'a':", ".obj"},
        {"[part a]\nscale = 2\n", SW_ERR_FORMAT, "s.ini:1:", "part 'a' has no file"},
        {"[part a]\nfile = saddle.bpt\nfile = saddle.bpt\n", SW_ERR_FORMAT, "s.ini:3:",
         "given twice"},
        {"[part a]\nfile = saddle.bpt\n[part a]\nfile = saddle.bpt\n", SW_ERR_FORMAT, "s.ini:3:",
         "already defined at line 1"},
        {"[part a]\n[part b]\nfile = saddle.bpt\n", SW_ERR_FORMAT, "s.ini:1:", "no keys"},
        {"[part b]\nfile = saddle.bpt\n[part c]\n", SW_ERR_FORMAT, "s.ini:3:", "no keys"},
        {"[views a]\neye = 0 0 0\n", SW_ERR_FORMAT, "s.ini:1:", "unknown section [views a]"},
        {"[part]\nfile = saddle.bpt\n", SW_ERR_FORMAT, "s.ini:1:", "no name"},
        {"[party a]\nfile = saddle.bpt\n", SW_ERR_FORMAT, "s.ini:1:", "unknown section"},
        {"file = saddle.bpt\n", SW_ERR_FORMAT, "s.ini:1:", "outside any section"},
        {"[part a\nfile = saddle.bpt\n", SW_ERR_FORMAT, "s.ini:1:", "']'"},
        {"[part a]\nfile saddle.bpt\n", SW_ERR_FORMAT, "s.ini:2:", "key = value"},
        {"[part a]\nfile = saddle.bpt\n  scale = 2\n", SW_ERR_FORMAT, "s.ini:3:", "indentation"},
        {"; nothing\n", SW_ERR_FORMAT, "s.ini:", "at least one [part NAME]"},
        {"", SW_ERR_FORMAT, "s.ini:", "at least one"},
        {"[part a]\nfile = saddle.bpt\n[part this name is much too long for a pack part name]\n"
         "file = saddle.bpt\n",
         SW_ERR_FORMAT, "s.ini:3:", "longer than 49"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        sw_model m;
        sw_model_init(&m);
        sw_error err = {0};
        sw_status st = load(cases[k].text, &m, &err);
        check_error(st, &err, cases[k].status, cases[k].piece1, cases[k].piece2);
        sw_model_free(&m);
    }
}

/* inih skips a BOM, and any isspace() before a header; our reader must agree
 * (indented lines, \v and \f included, are errors; a BOM is not). */
static void a_bom_is_skipped_and_odd_blanks_are_indentation(void)
{
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK_MSG(load("\xEF\xBB\xBF[part a]\nfile = saddle.bpt\n", &m, &err) == SW_OK, "%s",
                 err.message);
    SW_CHECK(m.part_count == 1 && strcmp(m.parts[0].name, "a") == 0);
    sw_model_free(&m);
    sw_model_init(&m);
    check_error(load("\v[part a]\nfile = saddle.bpt\n", &m, &err), &err, SW_ERR_FORMAT,
                "s.ini:1:", "indentation");
    check_error(load("[part z]\nfile = saddle.bpt\n\f[part a]\nfile = saddle.bpt\n", &m, &err),
                &err, SW_ERR_FORMAT, "s.ini:3:", "indentation");
    sw_model_free(&m);
}

static void long_lines_and_nul_bytes_are_errors(void)
{
    char text[600];
    int n = snprintf(text, sizeof text, "[part a]\nfile = saddle.bpt\n; ");
    memset(text + n, 'x', 300);
    text[n + 300] = '\0';
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    check_error(load(text, &m, &err), &err, SW_ERR_FORMAT, "s.ini:3:", "line longer than");
    sw_model_free(&m);
    const char with_nul[] = "[part a]\nfile = sad\0dle.bpt\n";
    sw_model_init(&m);
    check_error(sw_scene_load_memory(with_nul, sizeof with_nul - 1, "s.ini", samples_dir, &m,
                                     &err),
                &err, SW_ERR_FORMAT, "s.ini:2:", "NUL");
    sw_model_free(&m);
}

static void errors_inside_part_files_name_both_files(void)
{
    write_file("broken.bpt", "1\n1 1\n0 0 0\n1 0 0\n0 one 0\n1 1 1\n");
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    sw_status st = sw_scene_load_memory("[part b]\nfile = broken.bpt\n", 26, "b.ini", ".", &m,
                                        &err);
    check_error(st, &err, SW_ERR_FORMAT, "b.ini:2: part 'b': ./broken.bpt:5:3:",
                "expected control point y, found 'one'");
    sw_model_free(&m);
    sw_model_init(&m);
    check_error(sw_scene_load("no_such_scene.ini", &m, &err), &err, SW_ERR_IO,
                "no_such_scene.ini", "cannot open");
    sw_model_free(&m);
}

static void import_file_picks_the_importer_by_extension(void)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/teacup.txt", samples_dir);
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK(sw_scene_import_file(path, &m, &err) == SW_OK && m.patch_count == 26);
    write_file("SPOON.BPT", "1\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n");
    SW_CHECK(sw_scene_import_file("SPOON.BPT", &m, &err) == SW_OK && m.patch_count == 27);
    check_error(sw_scene_import_file("x.3dm", &m, &err), &err, SW_ERR_UNSUPPORTED, "x.3dm",
                "unsupported");
    check_error(sw_scene_import_file("noext", &m, &err), &err, SW_ERR_UNSUPPORTED, "noext",
                NULL);
    SW_CHECK(sw_scene_is_scene_path("a/b/TEASET.INI") && !sw_scene_is_scene_path("a.ini/b"));
    sw_model_free(&m);
}

/* A file named by several parts is read once; every copy holds what a fresh
 * import would (placed by its own part), in its own part. */
static void a_file_used_twice_gives_two_equal_copies(void)
{
    sw_model one, two;
    sw_model_init(&one);
    sw_model_init(&two);
    sw_error err = {0};
    SW_CHECK(load("[part a]\nfile = teacup.txt\n", &one, &err) == SW_OK);
    SW_CHECK_MSG(load("[part a]\nfile = teacup.txt\n[part b]\nfile = saddle.bpt\n"
                      "[part c]\nfile = teacup.txt\ntranslate = 0 5 0\ncolor = 1 0 0\n",
                      &two, &err) == SW_OK,
                 "%s", err.message);
    SW_CHECK(two.part_count == 3 && one.patch_count == 26);
    if (two.part_count == 3 && one.patch_count == 26) {
        const sw_model_part *a = &two.parts[0], *c = &two.parts[2];
        SW_CHECK(strcmp(c->name, "c") == 0 && c->color[0] == 1.0f && c->color[1] == 0.0f);
        SW_CHECK(a->patch_count == 26 && c->patch_count == 26 && c->surface_count == 26);
        for (size_t i = 0; i < 26; i++) {
            const double *p = one.patches[i].ctrl, *q = two.patches[a->first_patch + i].ctrl,
                         *r = two.patches[c->first_patch + i].ctrl;
            SW_CHECK(memcmp(p, q, 64 * sizeof *p) == 0);
            SW_CHECK(r[0] == p[0] && r[1] == p[1] + 5.0 && r[2] == p[2]);
            SW_CHECK(two.patches[c->first_patch + i].rational == one.patches[i].rational);
        }
    }
    sw_model_free(&one);
    sw_model_free(&two);
}

/* ---- viewpoints --------------------------------------------------------- */

static void views_become_named_viewpoints(void)
{
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK_MSG(load("[view entrance]\neye = 0 1600 -5000\ntarget = 0 800 0\nfov = 55\n"
                      "[part a]\nfile = saddle.bpt\n"
                      "[view top]\neye = 1 20000 2\ntarget = 1 0 2\nup = 0 0 -1\n",
                      &m, &err) == SW_OK,
                 "%s", err.message);
    SW_CHECK(m.viewpoint_count == 2 && m.part_count == 1);
    if (m.viewpoint_count == 2) {
        const sw_model_viewpoint *a = &m.viewpoints[0], *b = &m.viewpoints[1];
        SW_CHECK(strcmp(a->name, "entrance") == 0 && strcmp(b->name, "top") == 0);
        SW_CHECK(a->eye[0] == 0 && a->eye[1] == 1600 && a->eye[2] == -5000);
        SW_CHECK(a->target[1] == 800 && a->fov_deg == 55);
        /* up defaults to +y, fov to 0 (the runtime's default) */
        SW_CHECK(a->up[0] == 0 && a->up[1] == 1 && a->up[2] == 0);
        SW_CHECK(b->up[2] == -1 && b->fov_deg == 0);
    }
    sw_model_free(&m);
}

static void view_errors_name_file_and_line(void)
{
    static const struct {
        const char *text;
        sw_status status;
        const char *piece1, *piece2;
    } cases[] = {
        {"[part a]\nfile = saddle.bpt\n[view v]\ntarget = 0 0 0\n", SW_ERR_FORMAT, "s.ini:3:",
         "view 'v' has no eye"},
        {"[part a]\nfile = saddle.bpt\n[view v]\neye = 0 0 1\n", SW_ERR_FORMAT, "s.ini:3:",
         "view 'v' has no target"},
        {"[part a]\nfile = saddle.bpt\n[view v]\neye = 0 0 1\ntarget = 0 0 0\n[view v]\n"
         "eye = 1 1 1\n",
         SW_ERR_FORMAT, "s.ini:6:", "view 'v' already defined at line 3"},
        {"[part a]\nfile = saddle.bpt\n[view v]\neye = 0 0 1x\ntarget = 0 0 0\n", SW_ERR_FORMAT,
         "s.ini:4:", "eye: '1x' is not a finite number"},
        {"[part a]\nfile = saddle.bpt\n[view v]\neye = 0 0\ntarget = 0 0 0\n", SW_ERR_FORMAT,
         "s.ini:4:", "eye: expected 3 numbers, found 2"},
        {"[part a]\nfile = saddle.bpt\n[view v]\neye = 0 0 1\ntarget = 0 0 0\nfov = 180\n",
         SW_ERR_RANGE, "s.ini:6:", "fov: 180 degrees"},
        {"[part a]\nfile = saddle.bpt\n[view v]\neye = 0 0 1\ntarget = 0 0 0\nfov = inf\n",
         SW_ERR_FORMAT, "s.ini:6:", "not a finite number"},
        {"[part a]\nfile = saddle.bpt\n[view v]\neye = 0 0 1\ntarget = 0 0 1\n", SW_ERR_RANGE,
         "s.ini:5:", "target: equals the eye"},
        {"[part a]\nfile = saddle.bpt\n[view v]\neye = 0 5 0\ntarget = 0 0 0\n", SW_ERR_RANGE,
         "s.ini:5:", "up: parallel to the view direction"},
        {"[part a]\nfile = saddle.bpt\n[view v]\neye = 0 0 1\nup = 0 0 2\ntarget = 0 0 0\n",
         SW_ERR_RANGE, "s.ini:5:", "up: parallel"},
        {"[part a]\nfile = saddle.bpt\n[view v]\neye = 0 0 1\nup = 0 0 0\n", SW_ERR_RANGE,
         "s.ini:5:", "up: the vector must not be zero"},
        {"[part a]\nfile = saddle.bpt\n[view v]\neye = 0 0 1\nlook = 0 0 0\n", SW_ERR_FORMAT,
         "s.ini:5:", "unknown key 'look' in view 'v'"},
        {"[part a]\nfile = saddle.bpt\n[view v]\neye = 0 0 1\neye = 0 0 1\n", SW_ERR_FORMAT,
         "s.ini:5:", "given twice in view 'v' (first at line 4)"},
        {"[view v]\neye = 0 0 1\ntarget = 0 0 0\n", SW_ERR_FORMAT, "s.ini:",
         "at least one [part NAME]"},
        {"[part a]\nfile = saddle.bpt\n[view]\neye = 0 0 1\n", SW_ERR_FORMAT, "s.ini:3:",
         "expected [view NAME], found no name"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        sw_model m;
        sw_model_init(&m);
        sw_error err = {0};
        check_error(load(cases[k].text, &m, &err), &err, cases[k].status, cases[k].piece1,
                    cases[k].piece2);
        sw_model_free(&m);
    }
}

/* A part and a view may share a name: they are named separately. */
static void parts_and_views_have_separate_names(void)
{
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK_MSG(load("[part a]\nfile = saddle.bpt\n[view a]\neye = 0 0 1\ntarget = 0 0 0\n", &m,
                      &err) == SW_OK,
                 "%s", err.message);
    SW_CHECK(m.part_count == 1 && m.viewpoint_count == 1);
    sw_model_free(&m);
}

/* ---- units -------------------------------------------------------------- */

/* Units scale unitless files to millimetres before the part's own scale:
 * every coordinate is multiplied by exactly the unit's millimetres. */
static void units_scale_unitless_files_exactly(void)
{
    static const struct {
        const char *unit;
        double mm;
    } units[] = {{"mm", 1.0}, {"cm", 10.0}, {"m", 1000.0}, {"in", 25.4}, {"ft", 304.8}};
    for (size_t k = 0; k < sizeof units / sizeof units[0]; k++) {
        char text[128];
        snprintf(text, sizeof text, "[part s]\nfile = saddle.bpt\nunits = %s\n", units[k].unit);
        sw_model m;
        sw_model_init(&m);
        sw_error err = {0};
        SW_CHECK_MSG(load(text, &m, &err) == SW_OK, "%s", err.message);
        if (m.part_count == 1) {
            const double *c = first_ctrl(&m, 0); /* (-1, 1.5, -1.5) */
            SW_CHECK_MSG(c[0] == -1.0 * units[k].mm && c[1] == 1.5 * units[k].mm &&
                             c[2] == -1.5 * units[k].mm,
                         "%s: (%.17g %.17g %.17g)", units[k].unit, c[0], c[1], c[2]);
        }
        sw_model_free(&m);
    }
    /* then scale and translate: (-1, 1.5, -1.5) in -> x -25.4 * 2 + 1 */
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK(load("[part s]\nfile = saddle.bpt\nunits = in\nscale = 2\ntranslate = 1 0 0\n", &m,
                  &err) == SW_OK);
    if (m.part_count == 1)
        SW_CHECK(first_ctrl(&m, 0)[0] == 2.0 * 25.4 * -1.0 + 1.0);
    sw_model_free(&m);
}

static void units_errors_name_the_line(void)
{
    static const struct {
        const char *text;
        const char *piece1, *piece2;
    } cases[] = {
        {"[part a]\nfile = saddle.bpt\nunits = inch\n", "s.ini:3:", "unknown unit 'inch'"},
        {"[part a]\nunits = mm\nfile = bracket.igs\n", "s.ini:2:",
         "units: .igs files carry their own units"},
        {"[part a]\nfile = BRACKET.STEP\nunits = m\n", "s.ini:3:", ".STEP files carry"},
        {"[part a]\nfile = b.iges\n\nunits = cm\n", "s.ini:4:", ".iges"},
        {"[part a]\nfile = b.stp\nunits = cm\n", "s.ini:3:", ".stp"},
        {"[part a]\ngenerate = vase\nunits = cm\n", "s.ini:3:",
         "units: generated parts are in millimetres"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        sw_model m;
        sw_model_init(&m);
        sw_error err = {0};
        check_error(load(cases[k].text, &m, &err), &err, SW_ERR_FORMAT, cases[k].piece1,
                    cases[k].piece2);
        SW_CHECK(m.part_count == 0); /* found while parsing: nothing was imported */
        sw_model_free(&m);
    }
}

/* ---- generated parts ---------------------------------------------------- */

static void generated_parts_have_the_announced_patches_and_placement(void)
{
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK_MSG(load("[part p]\ngenerate = plate\nsize = 500\nheight = 700\nholes = 2\n"
                      "segments = 3\nseed = 18446744073709551615\ntranslate = 1000 0 0\n"
                      "[part v]\ngenerate = vase\n[part r]\ngenerate = rail\nsegments = 5\n",
                      &m, &err) == SW_OK,
                 "%s", err.message);
    SW_CHECK(m.part_count == 3);
    if (m.part_count == 3) {
        sw_proc_params plate = sw_proc_defaults(SW_PROC_PLATE);
        plate.segments = 3;
        sw_proc_params vase = sw_proc_defaults(SW_PROC_VASE);
        sw_proc_params rail = sw_proc_defaults(SW_PROC_RAIL);
        rail.segments = 5;
        SW_CHECK(m.parts[0].patch_count == sw_proc_patch_count(&plate));
        SW_CHECK(m.parts[1].patch_count == sw_proc_patch_count(&vase));
        SW_CHECK(m.parts[2].patch_count == sw_proc_patch_count(&rail));
        /* the plate is 500 wide around x = 1000, at y = 700 */
        const sw_model_part *p = &m.parts[0];
        double min_x = INFINITY, max_x = -INFINITY;
        for (size_t i = p->first_patch; i < p->first_patch + p->patch_count; i++) {
            for (int k = 0; k < 16; k++) {
                min_x = fmin(min_x, m.patches[i].ctrl[4 * k]);
                max_x = fmax(max_x, m.patches[i].ctrl[4 * k]);
                SW_CHECK(m.patches[i].ctrl[4 * k + 1] == 700.0);
            }
        }
        SW_CHECK_NEAR(min_x, 750.0, 1e-9);
        SW_CHECK_NEAR(max_x, 1250.0, 1e-9);
    }
    sw_model_free(&m);
}

static void generator_errors_name_the_key(void)
{
    static const struct {
        const char *text;
        sw_status status;
        const char *piece1, *piece2;
    } cases[] = {
        {"[part a]\ngenerate = cube\n", SW_ERR_FORMAT, "s.ini:2:", "unknown kind 'cube'"},
        {"[part a]\ngenerate = vase\nholes = 2\n", SW_ERR_FORMAT, "s.ini:3:",
         "holes: a generated vase takes no holes"},
        {"[part a]\nsize = 10\nfile = saddle.bpt\n", SW_ERR_FORMAT, "s.ini:2:",
         "size: only generated parts take it"},
        {"[part a]\nfile = saddle.bpt\ngenerate = plate\n", SW_ERR_FORMAT, "s.ini:3:",
         "has both file and generate"},
        {"[part a]\ncolor = 1 1 1\n", SW_ERR_FORMAT, "s.ini:1:", "has no file (or generate)"},
        {"[part a]\ngenerate = plate\nholes = 65\n", SW_ERR_RANGE, "s.ini:3:",
         "plate: holes 65 outside 0..64"},
        {"[part a]\nsegments = 0\ngenerate = rail\n", SW_ERR_RANGE, "s.ini:2:",
         "rail: segments 0 outside"},
        {"[part a]\ngenerate = rail\nsize = 0.5\n", SW_ERR_RANGE, "s.ini:3:", "size 0.5 mm"},
        {"[part a]\ngenerate = vase\nheight = 0\n", SW_ERR_RANGE, "s.ini:3:", "height 0 mm"},
        {"[part a]\ngenerate = plate\nholes = -1\n", SW_ERR_FORMAT, "s.ini:3:",
         "holes: expected a whole number, found '-1'"},
        {"[part a]\ngenerate = plate\nsegments = 2.5\n", SW_ERR_FORMAT, "s.ini:3:",
         "segments: expected a whole number"},
        {"[part a]\ngenerate = plate\nseed = 18446744073709551616\n", SW_ERR_RANGE, "s.ini:3:",
         "seed: 18446744073709551616 is larger than"},
        {"[part a]\ngenerate = plate\nsegments = 99999999\n", SW_ERR_RANGE, "s.ini:3:",
         "larger than"},
        {"[part a]\ngenerate = plate\nsize = 1 2\n", SW_ERR_FORMAT, "s.ini:3:", "at most 1"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        sw_model m;
        sw_model_init(&m);
        sw_error err = {0};
        check_error(load(cases[k].text, &m, &err), &err, cases[k].status, cases[k].piece1,
                    cases[k].piece2);
        sw_model_free(&m);
    }
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: test_scene SAMPLES_DIR\n");
        return 2;
    }
    /* Work in a scratch folder of our own: some cases write files. */
    static char samples[4096], cwd[2048], scratch[] = "/tmp/sw_test_scene.XXXXXX";
    if (argv[1][0] != '/' && !getcwd(cwd, sizeof cwd))
        return 2;
    snprintf(samples, sizeof samples, "%s%s%s", cwd, cwd[0] ? "/" : "", argv[1]);
    samples_dir = samples;
    if (!mkdtemp(scratch) || chdir(scratch) != 0) {
        fprintf(stderr, "test_scene: cannot make a scratch folder\n");
        return 2;
    }
    SW_RUN(teaset_sample_has_three_parts_standing_on_one_floor);
    SW_RUN(transforms_apply_scale_then_rotate_then_translate);
    SW_RUN(scale_and_translate_are_exact);
    SW_RUN(rotation_is_right_handed_in_degrees);
    SW_RUN(colours_names_and_defaults);
    SW_RUN(files_resolve_against_the_scene_folder);
    SW_RUN(errors_name_file_and_line);
    SW_RUN(a_bom_is_skipped_and_odd_blanks_are_indentation);
    SW_RUN(long_lines_and_nul_bytes_are_errors);
    SW_RUN(errors_inside_part_files_name_both_files);
    SW_RUN(import_file_picks_the_importer_by_extension);
    SW_RUN(a_file_used_twice_gives_two_equal_copies);
    SW_RUN(views_become_named_viewpoints);
    SW_RUN(view_errors_name_file_and_line);
    SW_RUN(parts_and_views_have_separate_names);
    SW_RUN(units_scale_unitless_files_exactly);
    SW_RUN(units_errors_name_the_line);
    SW_RUN(generated_parts_have_the_announced_patches_and_placement);
    SW_RUN(generator_errors_name_the_key);
    static const char *const written[] = {"here.bpt", "here.ini", "broken.bpt", "SPOON.BPT"};
    for (size_t k = 0; k < sizeof written / sizeof written[0]; k++)
        remove(written[k]);
    if (chdir("/") == 0)
        rmdir(scratch);
    return sw_test_finish();
}
