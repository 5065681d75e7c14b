/* SPDX-License-Identifier: MIT */
/* Specification of the host model (sw_model.h) and the text importers
 * (sw_import_newell.h, sw_import_bpt.h).
 * Usage: test_import SAMPLES_DIR [SHARED_MODELS_DIR] */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "sw_import_bpt.h"
#include "sw_import_newell.h"
#include "sw_model.h"
#include "sw_test.h"

static const char *samples_dir;
static const char *shared_dir;

/* Control point (i, j) of a model patch, as sw_bezier_patch lays it out. */
static const double *ctrl_at(const sw_model_patch *p, int i, int j)
{
    return p->ctrl + 4 * (j * (p->degree_u + 1) + i);
}

/* Imports from an exactly sized heap copy, so reading past the end (the text
 * is not NUL-terminated) trips AddressSanitizer. */
typedef sw_status (*import_memory_fn)(const char *, size_t, const char *, sw_model *, sw_error *);
static sw_status import_text(import_memory_fn fn, const char *text, size_t size, const char *name,
                             sw_model *model, sw_error *err)
{
    char *copy = malloc(size ? size : 1);
    memcpy(copy, text, size);
    sw_status st = fn(copy, size, name, model, err);
    free(copy);
    return st;
}

static sw_status import_newell(const char *text, sw_model *model, sw_error *err)
{
    return import_text(sw_import_newell_memory, text, strlen(text), "t.txt", model, err);
}

static sw_status import_bpt(const char *text, sw_model *model, sw_error *err)
{
    return import_text(sw_import_bpt_memory, text, strlen(text), "t.bpt", model, err);
}

/* A Newell listing of 16 vertices k = (k, 10k, 100k) and `patches` patches
 * 1..16, written into buf. */
static const char *small_newell(char *buf, size_t size, int patches)
{
    int n = snprintf(buf, size, "tiny\n16 1 %d %d\n", patches, patches);
    for (int k = 1; k <= 16; k++)
        n += snprintf(buf + n, size - (size_t)n, "%d  %d\t%d\t%d\n", k, k, 10 * k, 100 * k);
    for (int p = 0; p < patches; p++)
        n += snprintf(buf + n, size - (size_t)n,
                      "-1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16\n");
    return buf;
}

/* Checks status and that the message contains each of the given pieces. */
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

/* ---- sw_model ---------------------------------------------------------- */

static void model_patch_without_part_starts_an_unnamed_grey_part(void)
{
    sw_model m;
    sw_model_init(&m);
    double ctrl[16] = {0, 0, 0, 9, 1, 0, 0, 9, 0, 1, 0, 9, 1, 1, 0, 9};
    sw_error err = {0};
    SW_CHECK(sw_model_add_patch(&m, 1, 1, 0, ctrl, &err) == SW_OK);
    SW_CHECK(m.part_count == 1 && m.parts[0].name[0] == '\0');
    SW_CHECK(m.parts[0].patch_count == 1 && m.patches[0].part == 0);
    SW_CHECK(m.parts[0].color[0] == 0.8f && m.parts[0].color[3] == 1.0f);
    SW_CHECK(m.patches[0].ctrl[3] == 1.0); /* polynomial: weights forced to 1 */
    SW_CHECK(m.patches[0].ctrl != ctrl);
    sw_model_free(&m);
    SW_CHECK(m.patches == NULL && m.patch_count == 0);
}

static void model_part_names_are_truncated_to_55_bytes(void)
{
    sw_model m;
    sw_model_init(&m);
    char name[80];
    memset(name, 'n', sizeof name - 1);
    name[79] = '\0';
    SW_CHECK(sw_model_begin_part(&m, name, NULL, NULL) == SW_OK);
    SW_CHECK(strlen(m.parts[0].name) == 55);
    sw_model_free(&m);
}

static void model_rejects_bad_degrees_and_weights(void)
{
    sw_model m;
    sw_model_init(&m);
    double ctrl[4 * 17 * 17] = {0};
    sw_error err = {0};
    SW_CHECK(sw_model_add_patch(&m, 16, 1, 0, ctrl, &err) == SW_ERR_RANGE);
    SW_CHECK(sw_model_add_patch(&m, 1, 0, 0, ctrl, &err) == SW_ERR_RANGE);
    /* rational with weight 0 */
    SW_CHECK(sw_model_add_patch(&m, 1, 1, 1, ctrl, &err) == SW_ERR_RANGE);
    SW_CHECK(strstr(err.message, "weight") != NULL);
    ctrl[0] = NAN;
    SW_CHECK(sw_model_add_patch(&m, 1, 1, 0, ctrl, &err) == SW_ERR_RANGE);
    SW_CHECK(m.patch_count == 0);
    sw_model_free(&m);
}

static void model_transform_moves_only_its_part_and_keeps_weights(void)
{
    sw_model m;
    sw_model_init(&m);
    double ctrl[16] = {1, 2, 3, 2, 1, 2, 3, 2, 1, 2, 3, 2, 1, 2, 3, 2};
    sw_model_begin_part(&m, "a", NULL, NULL);
    sw_model_add_patch(&m, 1, 1, 1, ctrl, NULL);
    sw_model_begin_part(&m, "b", NULL, NULL);
    sw_model_add_patch(&m, 1, 1, 1, ctrl, NULL);
    sw_mat4 t = sw_mat4_translate(sw_v3(10, 20, 30));
    sw_model_transform_part(&m, 1, &t);
    SW_CHECK(m.patches[0].ctrl[0] == 1 && m.patches[1].ctrl[0] == 11);
    SW_CHECK(m.patches[1].ctrl[1] == 22 && m.patches[1].ctrl[2] == 33);
    SW_CHECK(m.patches[1].ctrl[3] == 2);
    sw_box box = sw_model_box(&m);
    SW_CHECK(box.min.x == 1 && box.max.z == 33);
    sw_model_free(&m);
}

/* ---- Newell listings ---------------------------------------------------- */

static void newell_group_of_four_runs_along_v(void)
{
    char buf[2048];
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK(import_newell(small_newell(buf, sizeof buf, 1), &m, &err) == SW_OK);
    SW_CHECK(m.patch_count == 1 && m.patches[0].degree_u == 3 && m.patches[0].degree_v == 3);
    SW_CHECK(!m.patches[0].rational);
    for (int i = 0; i < 4; i++) {
        for (int j = 0; j < 4; j++) {
            const double *c = ctrl_at(&m.patches[0], i, j);
            int k = i * 4 + j + 1;
            SW_CHECK_MSG(c[0] == k && c[1] == 10 * k && c[2] == 100 * k && c[3] == 1,
                         "(%d,%d) = %g %g %g", i, j, c[0], c[1], c[2]);
        }
    }
    sw_model_free(&m);
}

static void newell_first_index_may_omit_the_minus(void)
{
    char buf[2048];
    small_newell(buf, sizeof buf, 1);
    char *minus = strstr(buf, "\n-1 2 3");
    memmove(minus + 1, minus + 2, strlen(minus + 2) + 1);
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK(import_newell(buf, &m, &err) == SW_OK);
    SW_CHECK(m.patch_count == 1 && ctrl_at(&m.patches[0], 0, 0)[0] == 1);
    sw_model_free(&m);
}

/* Bernstein basis and derivative of degree 3, for a normal at the centre. */
static void cubic_basis(double t, double b[4], double d[4])
{
    double s = 1 - t;
    b[0] = s * s * s, b[1] = 3 * t * s * s, b[2] = 3 * t * t * s, b[3] = t * t * t;
    d[0] = -3 * s * s, d[1] = 3 * s * s - 6 * t * s, d[2] = 6 * t * s - 3 * t * t,
    d[3] = 3 * t * t;
}

/* cross(F_u, F_v) at (0.5, 0.5), dotted with the direction from the y axis. */
static double outwardness(const sw_model_patch *p)
{
    double b[4], d[4], pt[3] = {0}, fu[3] = {0}, fv[3] = {0};
    cubic_basis(0.5, b, d);
    for (int i = 0; i < 4; i++) {
        for (int j = 0; j < 4; j++) {
            for (int k = 0; k < 3; k++) {
                pt[k] += b[i] * b[j] * ctrl_at(p, i, j)[k];
                fu[k] += d[i] * b[j] * ctrl_at(p, i, j)[k];
                fv[k] += b[i] * d[j] * ctrl_at(p, i, j)[k];
            }
        }
    }
    double n[3] = {fu[1] * fv[2] - fu[2] * fv[1], fu[2] * fv[0] - fu[0] * fv[2],
                   fu[0] * fv[1] - fu[1] * fv[0]};
    return n[0] * pt[0] + n[2] * pt[2];
}

typedef struct newell_expect {
    const char *file;
    size_t patches;
    double min[3], max[3];
} newell_expect;

static const newell_expect teaset[] = {
    {"teapot", 28, {-0.851064, 0.0, -0.567376}, {1.0, 0.851064, 0.567376}},
    {"teacup", 26, {-1.0, 0.0, -1.0}, {1.0, 0.954545, 1.0}},
    {"teaspoon", 16, {-0.142857, -1.0, -0.107143}, {0.142857, 0.220982, 0.0892857}},
};

static void check_teaset_file(const char *path, const newell_expect *e)
{
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    sw_status st = sw_import_newell_file(path, &m, &err);
    SW_CHECK_MSG(st == SW_OK, "%s: %s", path, err.message);
    SW_CHECK_MSG(m.patch_count == e->patches, "%s: %zu patches", path, m.patch_count);
    sw_box box = sw_model_box(&m);
    SW_CHECK_NEAR(box.min.x, e->min[0], 1e-9);
    SW_CHECK_NEAR(box.min.y, e->min[1], 1e-9);
    SW_CHECK_NEAR(box.min.z, e->min[2], 1e-9);
    SW_CHECK_NEAR(box.max.x, e->max[0], 1e-9);
    SW_CHECK_NEAR(box.max.y, e->max[1], 1e-9);
    SW_CHECK_NEAR(box.max.z, e->max[2], 1e-9);
    sw_model_free(&m);
}

static void newell_bundled_teaset_imports(void)
{
    for (size_t k = 0; k < 3; k++) {
        char path[1024];
        snprintf(path, sizeof path, "%s/%s.txt", samples_dir, teaset[k].file);
        check_teaset_file(path, &teaset[k]);
    }
}

static void newell_shared_teaset_imports(void)
{
    struct stat st;
    if (!shared_dir || stat(shared_dir, &st) != 0) {
        printf("skip newell_shared_teaset_imports: shared models folder %s absent\n",
               shared_dir ? shared_dir : "(not given)");
        return;
    }
    for (size_t k = 0; k < 3; k++) {
        char path[1024];
        snprintf(path, sizeof path, "%s/newell_%s.txt", shared_dir, teaset[k].file);
        check_teaset_file(path, &teaset[k]);
    }
}

static void newell_teapot_known_points_and_outward_body(void)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/teapot.txt", samples_dir);
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK(sw_import_newell_file(path, &m, &err) == SW_OK);
    if (m.patch_count != 28) {
        sw_model_free(&m);
        return;
    }
    /* first patch lists vertices 1..16; vertex 2 is (0.397163 0.638298 -0.222411) */
    const double *c = ctrl_at(&m.patches[0], 0, 1);
    SW_CHECK(c[0] == 0.397163 && c[1] == 0.638298 && c[2] == -0.222411);
    c = ctrl_at(&m.patches[0], 1, 0); /* vertex 5 */
    SW_CHECK(c[0] == 0.379433 && c[1] == 0.675532 && c[2] == 0);
    c = ctrl_at(&m.patches[0], 3, 3); /* vertex 16 */
    SW_CHECK(c[0] == 0 && c[1] == 0.638298 && c[2] == -0.425532);
    /* The rim and body (patches 0..11) face away from the axis. */
    for (size_t p = 0; p < 12; p++)
        SW_CHECK_MSG(outwardness(&m.patches[p]) > 0, "teapot patch %zu faces inward", p);
    sw_model_free(&m);
}

static void newell_malformed_inputs_name_file_and_line(void)
{
    static const struct {
        const char *text;
        sw_status status;
        const char *piece1, *piece2;
    } cases[] = {
        {"", SW_ERR_FORMAT, "t.txt:1:", "title"},
        {"title\n", SW_ERR_FORMAT, "t.txt:2:", "expected vertex count"},
        {"title\n2 1 1\n", SW_ERR_FORMAT, "t.txt:2:", "expected fourth count"},
        {"title\n2 1 1 1 7\n", SW_ERR_FORMAT, "t.txt:2:", "after the four counts"},
        {"title\n0 1 1 1\n", SW_ERR_RANGE, "t.txt:2:1:", "vertex count 0 out of range"},
        {"title\n1 1 x 1\n", SW_ERR_FORMAT, "t.txt:2:5:", "expected patch count, found 'x'"},
        {"t\n99999 1 1 1\n1 0 0 0\n", SW_ERR_RANGE, "t.txt:2:", "vertex count 99999"},
        {"t\n2 1 1 1\n1 0 0 0\n3 0 0 0\n", SW_ERR_FORMAT, "t.txt:4:1:",
         "expected vertex number 2, found 3"},
        {"t\n1 1 1 1\n1 0 abc 0\n", SW_ERR_FORMAT, "t.txt:3:5:", "expected vertex y, found 'abc'"},
        {"t\n1 1 1 1\n1 0 1.5e 0\n", SW_ERR_FORMAT, "t.txt:3:", "vertex y"},
        {"t\n1 1 1 1\n1 0 nan 0\n", SW_ERR_FORMAT, "t.txt:3:", "vertex y"},
        {"t\n1 1 1 1\n1 0 1e999 0\n", SW_ERR_FORMAT, "t.txt:3:", "vertex y"},
        {"t\n1 1 1 1\n1 0 0\n", SW_ERR_FORMAT, "t.txt:3:", "vertex z, found the end of the line"},
        {"t\n1 1 1 1\n1 0 0 0 0\n", SW_ERR_FORMAT, "t.txt:3:", "end of the line"},
        {"t\n1 1 1 1\n1 0 0 0\n", SW_ERR_FORMAT, "t.txt:4:", "expected patch 1 of 1"},
        {"t\n1 1 1 1\n1 0 0 0\n-1 1 1 1 1 1 1 1 1 1 1 1 1 1 1\n", SW_ERR_FORMAT, "t.txt:4:",
         "expected 16 vertex indices, found 15"},
        {"t\n1 1 1 1\n1 0 0 0\n-1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1\n", SW_ERR_FORMAT, "t.txt:4:",
         "found 17"},
        {"t\n1 1 1 1\n1 0 0 0\n-1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 300\n", SW_ERR_RANGE, "t.txt:4:",
         "vertex index 300 out of range 1..1"},
        {"t\n1 1 1 1\n1 0 0 0\n-1 1 1 1 1 1 1 1 1 -1 1 1 1 1 1 1\n", SW_ERR_RANGE, "t.txt:4:",
         "vertex index -1 out of range"},
        {"t\n1 1 1 1\n1 0 0 0\n--1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1\n", SW_ERR_RANGE, "t.txt:4:2:",
         "vertex index -1"},
        {"t\n1 1 1 1\n1 0 0 0\n-1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1.5\n", SW_ERR_FORMAT, "t.txt:4:",
         "expected vertex index, found '1.5'"},
        {"t\n1 1 1 1\n1 0 0 0\n-1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1\nextra\n", SW_ERR_FORMAT,
         "t.txt:5:", "expected the end of the file after 1 patches"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        sw_model m;
        sw_model_init(&m);
        sw_error err = {0};
        sw_status st = import_newell(cases[k].text, &m, &err);
        check_error(st, &err, cases[k].status, cases[k].piece1, cases[k].piece2);
        SW_CHECK_MSG(m.patch_count == 0, "case %zu added patches", k);
        sw_model_free(&m);
    }
}

static void newell_counts_must_match_the_records(void)
{
    char buf[2048];
    small_newell(buf, sizeof buf, 2);
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    /* fewer patches than the count says */
    buf[strlen("tiny\n16 1 ")] = '3';
    check_error(import_newell(buf, &m, &err), &err, SW_ERR_FORMAT, "t.txt:21:",
                "expected patch 3 of 3, found the end of the file");
    /* more patches than the count says */
    buf[strlen("tiny\n16 1 ")] = '1';
    check_error(import_newell(buf, &m, &err), &err, SW_ERR_FORMAT, "t.txt:20:",
                "expected the end of the file after 1 patches");
    /* fewer vertices than the count says: the first patch line is read as one */
    buf[strlen("tiny\n1")] = '7';
    buf[strlen("tiny\n16 1 ")] = '2';
    check_error(import_newell(buf, &m, &err), &err, SW_ERR_FORMAT, "t.txt:19:",
                "expected vertex number 17");
    SW_CHECK(m.patch_count == 0);
    sw_model_free(&m);
}

/* Every cut before the last token of the file leaves something missing. */
static void newell_every_truncation_fails_cleanly(void)
{
    char buf[2048];
    size_t size = strlen(small_newell(buf, sizeof buf, 2));
    size_t last_token = size - strlen("16\n");
    for (size_t cut = 0; cut < size; cut++) {
        sw_model m;
        sw_model_init(&m);
        sw_error err = {0};
        sw_status st = import_text(sw_import_newell_memory, buf, cut, "cut.txt", &m, &err);
        if (cut < last_token) {
            SW_CHECK_MSG(st == SW_ERR_FORMAT || st == SW_ERR_RANGE, "cut %zu: %s", cut,
                         sw_status_name(st));
            SW_CHECK_MSG(strncmp(err.message, "cut.txt:", 8) == 0, "cut %zu: '%s'", cut,
                         err.message);
            SW_CHECK(m.patch_count == 0);
        }
        sw_model_free(&m);
    }
}

static void newell_accepts_crlf_and_blank_lines(void)
{
    const char *text = "t\r\n1 1 1 1\r\n\r\n1 0.5 0.25 2\r\n\r\n"
                       "-1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1\r\n\r\n";
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK_MSG(import_newell(text, &m, &err) == SW_OK, "%s", err.message);
    SW_CHECK(m.patch_count == 1 && m.patches[0].ctrl[1] == 0.25);
    sw_model_free(&m);
}

static void newell_missing_file_is_an_io_error(void)
{
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    check_error(sw_import_newell_file("no/such/teapot.txt", &m, &err), &err, SW_ERR_IO,
                "no/such/teapot.txt", "cannot open");
    check_error(sw_import_newell_file(".", &m, &err), &err, SW_ERR_IO, ".",
                "a directory, not a file");
    check_error(sw_import_newell_file("/dev/null", &m, &err), &err, SW_ERR_IO, "/dev/null",
                "not a regular file");
    sw_model_free(&m);
}

/* ---- .bpt ----------------------------------------------------------------- */

static void bpt_saddle_sample_has_its_degrees_and_points(void)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/saddle.bpt", samples_dir);
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK_MSG(sw_import_bpt_file(path, &m, &err) == SW_OK, "%s", err.message);
    SW_CHECK(m.patch_count == 2);
    if (m.patch_count == 2) {
        SW_CHECK(m.patches[0].degree_u == 2 && m.patches[0].degree_v == 2);
        SW_CHECK(m.patches[1].degree_u == 3 && m.patches[1].degree_v == 3);
        /* y = x * z on both; u runs along x, fastest in the file */
        const double *c = ctrl_at(&m.patches[0], 2, 0);
        SW_CHECK(c[0] == 1 && c[1] == -1.5 && c[2] == -1.5);
        c = ctrl_at(&m.patches[1], 3, 1);
        SW_CHECK(c[0] == 4 && c[1] == -2 && c[2] == -0.5);
        /* the shared edge x = 1 */
        SW_CHECK(ctrl_at(&m.patches[0], 2, 2)[1] == ctrl_at(&m.patches[1], 0, 3)[1]);
    }
    sw_model_free(&m);
}

static void bpt_u_runs_fastest_for_unequal_degrees(void)
{
    const char *text = "1\n1 2\n0 0 0\n1 0 0\n2 0 0\n3 0 0\n4 0 0\n5 0 0\n";
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK_MSG(import_bpt(text, &m, &err) == SW_OK, "%s", err.message);
    SW_CHECK(m.patch_count == 1 && m.patches[0].degree_u == 1 && m.patches[0].degree_v == 2);
    for (int j = 0; m.patch_count == 1 && j < 3; j++) {
        for (int i = 0; i < 2; i++)
            SW_CHECK(ctrl_at(&m.patches[0], i, j)[0] == j * 2 + i);
    }
    sw_model_free(&m);
}

static void bpt_malformed_inputs_name_file_and_line(void)
{
    static const struct {
        const char *text;
        sw_status status;
        const char *piece1, *piece2;
    } cases[] = {
        {"", SW_ERR_FORMAT, "t.bpt:1:", "expected patch count, found the end of the file"},
        {"0\n", SW_ERR_RANGE, "t.bpt:1:", "patch count 0 out of range"},
        {"two\n", SW_ERR_FORMAT, "t.bpt:1:1:", "expected patch count, found 'two'"},
        {"1 1\n", SW_ERR_FORMAT, "t.bpt:1:", "after the patch count"},
        {"1\n16 1\n", SW_ERR_RANGE, "t.bpt:2:", "degree u 16 out of range 1..15"},
        {"1\n1 0\n", SW_ERR_RANGE, "t.bpt:2:", "degree v 0 out of range 1..15"},
        {"1\n1\n", SW_ERR_FORMAT, "t.bpt:2:", "expected degree v"},
        {"1\n1 1\n0 0 0\n1 0 0\n0 1 0\n", SW_ERR_FORMAT, "t.bpt:6:",
         "expected control point x, found the end of the file"},
        {"1\n1 1\n0 0 0\n1 0 0\n0 1\n1 1 1\n", SW_ERR_FORMAT, "t.bpt:5:",
         "control point z, found the end of the line"},
        {"1\n1 1\n0 0 0\n1 0 0\n0 1 0 1\n1 1 1\n", SW_ERR_FORMAT, "t.bpt:5:", "found '1'"},
        {"1\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 inf\n", SW_ERR_FORMAT, "t.bpt:6:", "found 'inf'"},
        {"2\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n", SW_ERR_FORMAT, "t.bpt:7:",
         "expected the degrees of patch 2"},
        {"1\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n1 1\n", SW_ERR_FORMAT, "t.bpt:7:",
         "expected the end of the file after 1 patches"},
        {"1\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 1\0junk", SW_ERR_FORMAT, "t.bpt:6:", NULL},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        sw_model m;
        sw_model_init(&m);
        sw_error err = {0};
        size_t size = strlen(cases[k].text);
        if (k == sizeof cases / sizeof cases[0] - 1)
            size += 5; /* past the NUL: binary junk after the numbers */
        sw_status st = import_text(sw_import_bpt_memory, cases[k].text, size, "t.bpt", &m, &err);
        check_error(st, &err, cases[k].status, cases[k].piece1, cases[k].piece2);
        SW_CHECK_MSG(m.patch_count == 0, "case %zu added patches", k);
        sw_model_free(&m);
    }
}

static void bpt_every_truncation_fails_cleanly(void)
{
    const char *text = "2\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n1 2\n0 0 0\n1 0 0\n0 1 0\n"
                       "1 1 1\n0 2 0\n1 2 1.25\n";
    size_t size = strlen(text);
    size_t last_token = size - strlen("1.25\n");
    for (size_t cut = 0; cut < size; cut++) {
        sw_model m;
        sw_model_init(&m);
        sw_error err = {0};
        sw_status st = import_text(sw_import_bpt_memory, text, cut, "cut.bpt", &m, &err);
        if (cut < last_token) {
            SW_CHECK_MSG(st == SW_ERR_FORMAT || st == SW_ERR_RANGE, "cut %zu: %s", cut,
                         sw_status_name(st));
            SW_CHECK_MSG(strncmp(err.message, "cut.bpt:", 8) == 0, "cut %zu: '%s'", cut,
                         err.message);
        }
        sw_model_free(&m);
    }
    sw_model m;
    sw_model_init(&m);
    SW_CHECK(import_text(sw_import_bpt_memory, text, size, "t.bpt", &m, NULL) == SW_OK);
    SW_CHECK(m.patch_count == 2 && m.patches[1].degree_v == 2);
    sw_model_free(&m);
}

static void bpt_appends_to_the_current_part(void)
{
    sw_model m;
    sw_model_init(&m);
    sw_model_begin_part(&m, "first", NULL, NULL);
    SW_CHECK(import_bpt("1\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n", &m, NULL) == SW_OK);
    sw_model_begin_part(&m, "second", NULL, NULL);
    SW_CHECK(import_bpt("1\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n", &m, NULL) == SW_OK);
    SW_CHECK(m.part_count == 2 && m.parts[1].first_patch == 1 && m.parts[1].patch_count == 1);
    SW_CHECK(m.patches[1].part == 1);
    sw_model_free(&m);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: test_import SAMPLES_DIR [SHARED_MODELS_DIR]\n");
        return 2;
    }
    samples_dir = argv[1];
    shared_dir = argc > 2 ? argv[2] : NULL;
    SW_RUN(model_patch_without_part_starts_an_unnamed_grey_part);
    SW_RUN(model_part_names_are_truncated_to_55_bytes);
    SW_RUN(model_rejects_bad_degrees_and_weights);
    SW_RUN(model_transform_moves_only_its_part_and_keeps_weights);
    SW_RUN(newell_group_of_four_runs_along_v);
    SW_RUN(newell_first_index_may_omit_the_minus);
    SW_RUN(newell_bundled_teaset_imports);
    SW_RUN(newell_shared_teaset_imports);
    SW_RUN(newell_teapot_known_points_and_outward_body);
    SW_RUN(newell_malformed_inputs_name_file_and_line);
    SW_RUN(newell_counts_must_match_the_records);
    SW_RUN(newell_every_truncation_fails_cleanly);
    SW_RUN(newell_accepts_crlf_and_blank_lines);
    SW_RUN(newell_missing_file_is_an_io_error);
    SW_RUN(bpt_saddle_sample_has_its_degrees_and_points);
    SW_RUN(bpt_u_runs_fastest_for_unequal_degrees);
    SW_RUN(bpt_malformed_inputs_name_file_and_line);
    SW_RUN(bpt_every_truncation_fails_cleanly);
    SW_RUN(bpt_appends_to_the_current_part);
    return sw_test_finish();
}
