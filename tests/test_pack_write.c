/* SPDX-License-Identifier: MIT */
/* The pack writer: model conversion and adjacency, and writing files
 * atomically. Run with --write-corpus DIR to (re)write the fuzz seeds in
 * tests/fuzz/corpus/pack. */
#include <signal.h>
#include <stdint.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h>

#include "sw_test.h"
#include "pack_sample.h"
#include "sw_pack_merge.h"

/* ---- writing files ---- */

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

/* ---- the optional sections from a model ---- */

/* Serialises model and opens the result; the caller frees *bytes. */
static int open_model_pack(const sw_model *model, uint8_t **bytes, sw_pack *pack)
{
    sw_pack_contents c;
    sw_error err = { 0 };
    size_t size = 0;
    *bytes = NULL;
    if (sw_pack_contents_from_model(model, &c, &err) != SW_OK) {
        SW_CHECK_MSG(0, "%s", err.message);
        return 0;
    }
    SW_CHECK(sw_pack_serialize(&c, bytes, &size, &err) == SW_OK);
    sw_pack_contents_free(&c);
    sw_status st = sw_pack_open_memory(*bytes, size, pack, &err);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    return st == SW_OK;
}

static void test_bezier_model_gets_one_untrimmed_surface_per_patch(void)
{
    sw_model model;
    start_model(&model);
    add_bicubic(&model, 0, 0, 0, 0);
    add_bicubic(&model, 1, 0, 0, 0);
    uint8_t *bytes;
    sw_pack pack;
    if (open_model_pack(&model, &bytes, &pack)) {
        SW_CHECK(pack.header->section_count == 13);
        SW_CHECK(pack.meta->units == SW_UNITS_MILLIMETRE);
        SW_CHECK(pack.surface_count == 2 && pack.trim_loop_count == 0 &&
                 pack.trim_curve_count == 0 && pack.trim_data_count == 0 &&
                 pack.trim_mask_count == 0 && pack.viewpoint_count == 0);
        for (uint32_t i = 0; i < 2; i++) {
            const sw_pack_surface *s = &pack.surfaces[i];
            SW_CHECK(s->part == 0 && s->first_patch == i && s->patch_count == 1 &&
                     s->loop_count == 0);
            SW_CHECK(s->domain[0] == 0 && s->domain[1] == 1 && s->domain[2] == 0 &&
                     s->domain[3] == 1);
            SW_CHECK(pack.patch_domains[i].surface == i &&
                     pack.patch_domains[i].mask == SW_MASK_NONE &&
                     memcmp(pack.patch_domains[i].domain, s->domain, sizeof s->domain) == 0);
        }
        for (int k = 0; k < 16; k++)
            SW_CHECK(pack.part_transforms[k] == (k % 5 == 0 ? 1.0f : 0.0f));
    }
    free(bytes);
    sw_model_free(&model);
}

/* A biquadratic plane over [0, 4] x [0, 2] in two spans along u, trimmed by
 * an outer rectangle (degree 1) and an inner circle (rational quadratic,
 * marked as computed by point inversion). */
static sw_status add_trimmed_plate(sw_model *model, sw_error *err)
{
    static const double ku[] = { 0, 0, 0, 1, 2, 2, 2 }, kv[] = { 0, 0, 0, 1, 1, 1 };
    double ctrl[4 * 3 * 4];
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 4; i++) {
            double *c = &ctrl[(j * 4 + i) * 4];
            c[0] = 4.0 * i / 3.0, c[1] = j, c[2] = 0, c[3] = 1;
        }
    sw_nurbs_surface plate = { 2, 2, 4, 3, ku, kv, ctrl };
    static const double rect_k[] = { 0, 0, 1, 2, 3, 4, 4 };
    static const double rect_p[] = { 0.1, 0.1, 0, 1, 1.9, 0.1, 0, 1, 1.9, 0.9, 0, 1,
                                     0.1, 0.9, 0, 1, 0.1, 0.1, 0, 1 };
    static const double circ_k[] = { 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4 };
    const double h = 0.70710678118654752;
    const double circ_p[] = { 1.2, 0.5, 0, 1, 1.2, 0.7, 0, h, 1.0, 0.7, 0, 1, 0.8, 0.7, 0, h,
                              0.8, 0.5, 0, 1, 0.8, 0.3, 0, h, 1.0, 0.3, 0, 1, 1.2, 0.3, 0, h,
                              1.2, 0.5, 0, 1 };
    sw_nurbs_curve rect = { 1, 5, rect_k, rect_p }, circle = { 2, 9, circ_k, circ_p };
    static const int computed = 1;
    sw_model_loop_input loops[2] = {{&rect, NULL, 1, 1, NULL, NULL},
                                    {&circle, &computed, 1, 0, NULL, NULL}};
    return sw_model_add_surface(model, &plate, 0, loops, 2, err);
}

static void test_trimmed_surface_round_trips(void)
{
    sw_model model;
    start_model(&model);
    sw_error err = { 0 };
    SW_CHECK_MSG(add_trimmed_plate(&model, &err) == SW_OK, "%s", err.message);
    uint8_t *bytes;
    sw_pack pack;
    if (model.surface_count == 1 && open_model_pack(&model, &bytes, &pack)) {
        const sw_pack_surface *s = &pack.surfaces[0];
        SW_CHECK(pack.surface_count == 1 && s->loop_count == 2 && s->patch_count >= 1 &&
                 s->patch_count == model.patch_count);
        SW_CHECK(s->domain[0] == 0 && s->domain[1] == 2 && s->domain[2] == 0 && s->domain[3] == 1);
        SW_CHECK(pack.trim_loops[0].flags == SW_LOOP_OUTER && pack.trim_loops[1].flags == 0);
        SW_CHECK(pack.trim_curve_count == 2 && pack.trim_curves[0].flags == 0 &&
                 pack.trim_curves[1].flags == (SW_TRIM_RATIONAL | SW_TRIM_COMPUTED));
        SW_CHECK(pack.trim_data_count == (7 + 15) + (12 + 27));
        const sw_model_trim_curve *mc = &model.curves[1];
        const float *d = &pack.trim_data[pack.trim_curves[1].first_float];
        SW_CHECK(pack.trim_curves[1].first_float == 22 && d[3] == (float)mc->knots[3]);
        SW_CHECK(d[12 + 3] == (float)mc->ctrl[4] && d[12 + 4] == (float)mc->ctrl[5] &&
                 d[12 + 5] == (float)mc->ctrl[7]);
        uint32_t masked = 0;
        for (uint32_t i = 0; i < pack.meta->patch_count; i++) {
            const sw_pack_patch_domain *pd = &pack.patch_domains[i];
            SW_CHECK(pd->surface == 0 && pd->domain[0] >= 0 && pd->domain[1] <= 2);
            masked += pd->mask != SW_MASK_NONE;
            if (pd->mask != SW_MASK_NONE)
                SW_CHECK(memcmp(pack.trim_masks[pd->mask].rows, model.patches[i].mask, 128) == 0);
        }
        SW_CHECK(masked == pack.trim_mask_count && masked >= 1);
        free(bytes);
    }
    sw_model_free(&model);
}

static void test_viewpoints_and_part_transforms_are_written(void)
{
    sw_model model;
    start_model(&model);
    add_bicubic(&model, 0, 0, 0, 0);
    sw_mat4 shift = sw_mat4_translate(sw_v3(10, 0, -2));
    sw_model_transform_part(&model, 0, &shift);
    sw_model_viewpoint view = { .name = "entrance", .eye = { 0, 1, 5 }, .target = { 0, 0, 0 },
                                .up = { 0, 1, 0 }, .fov_deg = 45 };
    sw_error err = { 0 };
    SW_CHECK(sw_model_add_viewpoint(&model, &view, &err) == SW_OK);
    uint8_t *bytes;
    sw_pack pack;
    if (open_model_pack(&model, &bytes, &pack)) {
        SW_CHECK(pack.viewpoint_count == 1 && strcmp(pack.viewpoints[0].name, "entrance") == 0);
        SW_CHECK(pack.viewpoints[0].eye[2] == 5 && pack.viewpoints[0].fov_deg == 45);
        SW_CHECK(pack.part_transforms[12] == 10 && pack.part_transforms[14] == -2 &&
                 pack.part_transforms[15] == 1);
        SW_CHECK(pack.patches[0].box_min[0] == 10.0f);
        free(bytes);
    }
    sw_model_free(&model);
}

/* Converts model and expects the writer to refuse with needle. */
static void expect_model_refused(const sw_model *model, const char *needle)
{
    sw_pack_contents c;
    sw_error err = { 0 };
    sw_status st = sw_pack_contents_from_model(model, &c, &err);
    SW_CHECK_MSG(st != SW_OK && strstr(err.message, needle), "\"%s\" not in \"%s\"", needle,
                 err.message);
    SW_CHECK(c.parts == NULL && c.surfaces == NULL); /* freed on failure */
}

static void test_writer_refuses_what_floats_cannot_hold(void)
{
    sw_model model;
    start_model(&model);
    add_bicubic(&model, 0, 0, 0, 0);
    sw_model_viewpoint view = { .name = "v", .eye = { 1, 1, 1 }, .target = { 1, 1, 1 + 1e-12 },
                                .up = { 0, 1, 0 } };
    sw_error err = { 0 };
    SW_CHECK(sw_model_add_viewpoint(&model, &view, &err) == SW_OK);
    expect_model_refused(&model, "viewpoint 0 (v): eye, target and up must be finite floats, "
                                 "eye apart from target");
    model.viewpoints[0].target[2] = 0;
    model.viewpoints[0].fov_deg = 180;
    expect_model_refused(&model, "viewpoint 0 (v): fov 180");
    model.viewpoint_count = 0;
    model.parts[0].transform[3] = 0.5;
    expect_model_refused(&model, "part 0 (part): transform element 3 is 0.5");
    model.parts[0].transform[3] = 0;
    model.surfaces[0].domain[0] = 1.0, model.surfaces[0].domain[1] = 1.0 + 1e-12;
    expect_model_refused(&model, "surface 0: u range 1..1.000000000001");
    sw_model_free(&model);
}

/* ---- fuzz seeds ---- */

/* Named without .swpack, which .gitignore keeps out of the repository for
 * generated packs; these few are committed on purpose. */

/* Serialises the model into dir/name; 0 on success. */
static int write_model_seed(const sw_model *model, const char *dir, const char *name)
{
    sw_pack_contents c;
    sw_error err = { 0 };
    uint8_t *bytes = NULL;
    size_t size = 0;
    if (sw_pack_contents_from_model(model, &c, &err) != SW_OK ||
        sw_pack_serialize(&c, &bytes, &size, &err) != SW_OK) {
        fprintf(stderr, "%s: %s\n", name, err.message);
        return 1;
    }
    char path[512];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    write_plain(path, bytes, size);
    free(bytes);
    sw_pack_contents_free(&c);
    return 0;
}

/* The sample with its hand-built Seam Graph, and with its static levels
 * and super-surfaces when asked (pack_sample.h), into dir/name. */
static void write_sample_seed(const char *dir, const char *name, int levels, int supers,
                              int part_levels)
{
    sample s;
    sample_seam g;
    sample_levels l;
    sample_supers k;
    sample_part_levels pl;
    make_sample(&s);
    make_sample_seam(&g);
    make_sample_levels(&l);
    make_sample_supers(&k);
    make_sample_part_levels(&pl);
    sw_pack_contents c = sample_contents(&s);
    c.seam = &g.graph;
    c.levels = levels ? &l.view : NULL;
    c.supers = supers ? &k.view : NULL;
    c.part_levels = part_levels ? &pl.view : NULL;
    uint8_t *bytes = NULL;
    size_t size = 0;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_serialize(&c, &bytes, &size, &err) == SW_OK, "%s", err.message);
    char path[512];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    write_plain(path, bytes, size);
    free(bytes);
}

/* The Bezier-only sample, z-up: an ORIENTATION section for the fuzzer. */
static void write_orientation_seed(const char *dir)
{
    sample s;
    make_sample(&s);
    s.bezier_only = 1;
    const sw_pack_orientation up = { .up_axis = 3 };
    sw_pack_contents c = sample_contents(&s);
    c.orientation = &up;
    uint8_t *bytes = NULL;
    size_t size = 0;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_serialize(&c, &bytes, &size, &err) == SW_OK, "%s", err.message);
    char path[512];
    snprintf(path, sizeof path, "%s/seed-orientation", dir);
    write_plain(path, bytes, size);
    free(bytes);
}

/* The sample with every group, as two prototypes placed three times: the
 * PROTOTYPES and INSTANCES sections for the fuzzer. */
static void write_instances_seed(const char *dir)
{
    size_t size = 0;
    sw_error err = { 0 };
    sample_levels l;
    sample_supers k;
    sample_part_levels pl;
    make_sample_levels(&l);
    make_sample_supers(&k);
    make_sample_part_levels(&pl);
    uint8_t *bytes = serialize_sample_all(&l.view, &k.view, &pl.view, &size);
    sw_pack packs[2];
    SW_CHECK_MSG(sw_pack_open_memory(bytes, size, &packs[0], &err) == SW_OK, "%s", err.message);
    packs[1] = packs[0];
    sw_pack_instance inst[3] = { { .prototype = 0, .color = { 1, 1, 1, 1 } },
                                 { .prototype = 1, .color = { 0.5f, 0.5f, 0.5f, 1 } },
                                 { .prototype = 0, .color = { 0, 0, 1, 1 } } };
    for (int i = 0; i < 3; i++) {
        float *t = inst[i].transform;
        t[0] = t[5] = t[10] = (float)(i + 1), t[15] = 1, t[12] = 3.0f * (float)i;
        snprintf(inst[i].name, sizeof inst[i].name, "copy %d", i);
    }
    sw_pack_merged m;
    uint8_t *placed = NULL;
    size_t placed_size = 0;
    SW_CHECK_MSG(sw_pack_merge(packs, 2, inst, 3, &m, &err) == SW_OK, "%s", err.message);
    SW_CHECK_MSG(sw_pack_serialize(&m.contents, &placed, &placed_size, &err) == SW_OK, "%s",
                 err.message);
    sw_pack_merged_free(&m);
    char path[512];
    snprintf(path, sizeof path, "%s/seed-instances", dir);
    write_plain(path, placed, placed_size);
    free(placed);
    free(bytes);
}

/* The hand-made sample with every optional section, without them, with an
 * unknown section, with a Seam Graph, with the graph and static levels; packs the writer makes of Bezier
 * patches and of a trimmed surface with a viewpoint. */
static int write_corpus(const char *dir)
{
    sample s;
    make_sample(&s);
    size_t size = 0, grown_size = 0;
    uint8_t *bytes = serialize_sample(&s, &size);
    uint8_t *grown = add_unknown_section(bytes, size, &grown_size);
    char path[512];
    snprintf(path, sizeof path, "%s/seed-sample", dir);
    write_plain(path, bytes, size);
    snprintf(path, sizeof path, "%s/seed-unknown-section", dir);
    write_plain(path, grown, grown_size);
    free(grown);
    free(bytes);
    s.bezier_only = 1;
    bytes = serialize_sample(&s, &size);
    snprintf(path, sizeof path, "%s/seed-bezier-only", dir);
    write_plain(path, bytes, size);
    free(bytes);
    write_sample_seed(dir, "seed-seam-graph", 0, 0, 0);
    write_sample_seed(dir, "seed-levels", 1, 0, 0);
    write_sample_seed(dir, "seed-supers", 1, 1, 0);
    write_sample_seed(dir, "seed-part-levels", 1, 1, 1);
    write_orientation_seed(dir);
    write_instances_seed(dir);
    sw_model model;
    start_model(&model);
    add_bicubic(&model, 0, 0, 0, 0);
    add_bicubic(&model, 1, 0, 0, 1);
    int failed = write_model_seed(&model, dir, "seed-two-patches");
    sw_model_free(&model);
    start_model(&model);
    sw_error err = { 0 };
    sw_model_viewpoint view = { .name = "above", .eye = { 1, 5, 0.5 }, .target = { 1, 0, 0.5 },
                                .up = { 0, 0, 1 }, .fov_deg = 40 };
    if (add_trimmed_plate(&model, &err) != SW_OK ||
        sw_model_add_viewpoint(&model, &view, &err) != SW_OK) {
        fprintf(stderr, "%s\n", err.message);
        failed = 1;
    }
    failed |= write_model_seed(&model, dir, "seed-trimmed-plate");
    sw_model_free(&model);
    return failed || sw_test_failures ? 1 : 0;
}

int main(int argc, char **argv)
{
    if (argc == 3 && strcmp(argv[1], "--write-corpus") == 0)
        return write_corpus(argv[2]);
    if (!mkdtemp(scratch_dir)) {
        perror("mkdtemp");
        return 1;
    }
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
    SW_RUN(test_bezier_model_gets_one_untrimmed_surface_per_patch);
    SW_RUN(test_trimmed_surface_round_trips);
    SW_RUN(test_viewpoints_and_part_transforms_are_written);
    SW_RUN(test_writer_refuses_what_floats_cannot_hold);
    remove_scratch();
    return sw_test_finish();
}
