/* SPDX-License-Identifier: MIT */
/* sw_cull_tree: the hierarchy gives exactly the per-surface nearest and
 * farthest depths of testing every patch box (sw_cull_brute), on generated
 * scenes from many random views and, given pack files, on real packs from
 * an orbit and from inside; a view holding everything or nothing costs one
 * box test; the depth range of a box is the 8 corners' extremes exactly;
 * the build fits its stated bytes and refuses a smaller arena.
 *   test_cull_tree [PACK.swpack...] */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_cull_tree.h"
#include "sw_pack.h"
#include "sw_test.h"

enum { MAX_SURFACES = 400, MAX_PATCHES = 400 * 40 };

static sw_pack_surface g_surfaces[MAX_SURFACES];
static sw_pack_patch g_patches[MAX_PATCHES];
static double g_near[2][MAX_SURFACES], g_far[2][MAX_SURFACES];

static unsigned g_seed = 777;
static double uniform(double lo, double hi)
{
    g_seed = g_seed * 1103515245u + 12345u;
    return lo + (hi - lo) * ((g_seed >> 8) & 0xFFFFFF) / (double)0xFFFFFF;
}

/* surfaces clusters of up to 40 patch boxes around random centres in a
 * 100-unit cube, some surfaces without patches; the patch count. */
static uint32_t make_scene(uint32_t surfaces)
{
    uint32_t at = 0;
    for (uint32_t s = 0; s < surfaces; s++) {
        uint32_t count = s % 17 == 5 ? 0 : 1 + (uint32_t)uniform(0, 39.99);
        g_surfaces[s] = (sw_pack_surface){ .first_patch = at, .patch_count = count };
        double cx = uniform(-50, 50), cy = uniform(-50, 50), cz = uniform(-50, 50);
        for (uint32_t i = 0; i < count; i++, at++) {
            sw_pack_patch *p = &g_patches[at];
            memset(p, 0, sizeof *p);
            double c[3] = { cx + uniform(-4, 4), cy + uniform(-4, 4), cz + uniform(-4, 4) };
            for (int k = 0; k < 3; k++) {
                double half = uniform(0, 1.5);
                p->box_min[k] = (float)(c[k] - half), p->box_max[k] = (float)(c[k] + half);
            }
        }
    }
    return at;
}

static sw_cull_view make_view(sw_vec3 eye, sw_vec3 target, double fovy, double near_z,
                              double far_z)
{
    sw_cull_view v;
    sw_mat4 look = sw_mat4_look_at(eye, target, sw_v3(0, 1, 0));
    sw_mat4 proj = sw_mat4_perspective(fovy, 16.0 / 9.0, near_z, far_z);
    sw_mat4 vp = sw_mat4_mul(&proj, &look);
    v.frustum = sw_frustum_from_matrix(&vp);
    v.eye = eye;
    v.forward = sw_v3_normalize(sw_v3_sub(target, eye));
    v.near_z = near_z;
    return v;
}

/* Both answers for every surface; the number that differ. */
static int compare(const sw_cull_tree *t, const sw_pack_surface *surfaces, uint32_t n,
                   const sw_pack_patch *patches, const sw_cull_view *v, sw_cull_counts *tree,
                   sw_cull_counts *brute, double *nearest[2], double *farthest[2])
{
    sw_cull_tree_query(t, v, nearest[0], farthest[0], tree);
    sw_cull_brute(surfaces, n, patches, v, nearest[1], farthest[1], brute);
    int differ = 0;
    for (uint32_t s = 0; s < n; s++)
        differ += nearest[0][s] != nearest[1][s] || farthest[0][s] != farthest[1][s];
    return differ;
}

static sw_status build(sw_cull_tree *t, uint32_t n, void **block)
{
    size_t bytes = (size_t)sw_cull_tree_bytes_of(g_surfaces, n);
    *block = malloc(bytes);
    sw_arena a;
    sw_arena_init(&a, *block, bytes);
    sw_error err;
    return sw_cull_tree_build(t, g_surfaces, n, g_patches, &a, &err);
}

static void test_tree_equals_brute_force_on_generated_scenes(void)
{
    double *nearest[2] = { g_near[0], g_near[1] }, *farthest[2] = { g_far[0], g_far[1] };
    sw_cull_counts tree = { 0, 0 }, brute = { 0, 0 };
    int differ = 0, views = 0;
    for (int scene = 0; scene < 12; scene++) {
        uint32_t n = 1 + (uint32_t)uniform(0, MAX_SURFACES - 1);
        make_scene(n);
        sw_cull_tree t;
        void *block;
        SW_CHECK(build(&t, n, &block) == SW_OK);
        for (int k = 0; k < 100; k++, views++) {
            sw_vec3 eye = sw_v3(uniform(-120, 120), uniform(-120, 120), uniform(-120, 120));
            sw_vec3 target = sw_v3(uniform(-60, 60), uniform(-60, 60), uniform(-60, 60));
            double near_z = uniform(0.01, 20);
            const sw_cull_view v = make_view(eye, target, uniform(0.2, 1.8), near_z,
                                             near_z + uniform(5, 300));
            differ += compare(&t, g_surfaces, n, g_patches, &v, &tree, &brute, nearest, farthest);
        }
        free(block);
    }
    SW_CHECK_MSG(differ == 0, "%d surface answers differ over %d views", differ, views);
    printf("  generated: %d views, box tests: tree %llu, every patch %llu\n", views,
           (unsigned long long)tree.box_tests, (unsigned long long)brute.box_tests);
    SW_CHECK(tree.box_tests < brute.box_tests / 2);
}

/* Far back with everything in view: the root is inside, one test; turned
 * away: the root is outside, one test, nothing visible. */
static void test_all_or_nothing_costs_one_test(void)
{
    double *nearest[2] = { g_near[0], g_near[1] }, *farthest[2] = { g_far[0], g_far[1] };
    uint32_t n = 300, patches = make_scene(n);
    sw_cull_tree t;
    void *block;
    SW_CHECK(build(&t, n, &block) == SW_OK);
    sw_cull_counts tree = { 0, 0 }, brute = { 0, 0 };
    sw_cull_view all = make_view(sw_v3(0, 0, 400), sw_v3(0, 0, 0), 0.8, 1, 1000);
    SW_CHECK(compare(&t, g_surfaces, n, g_patches, &all, &tree, &brute, nearest, farthest) == 0);
    SW_CHECK(tree.box_tests == 1 && brute.box_tests == patches);
    tree.box_tests = 0;
    sw_cull_view none = make_view(sw_v3(0, 0, 400), sw_v3(0, 0, 800), 0.8, 1, 1000);
    SW_CHECK(compare(&t, g_surfaces, n, g_patches, &none, &tree, &brute, nearest, farthest) == 0);
    SW_CHECK(tree.box_tests == 1);
    int seen = 0;
    for (uint32_t s = 0; s < n; s++)
        seen += isfinite(nearest[0][s]);
    SW_CHECK(seen == 0);
    free(block);
}

static void test_depth_range_is_the_corners_extremes(void)
{
    int differ = 0;
    for (int k = 0; k < 10000; k++) {
        sw_box b = { sw_v3(uniform(-9, 9), uniform(-9, 9), uniform(-9, 9)), sw_v3(0, 0, 0) };
        b.max = sw_v3_add(b.min, sw_v3(uniform(0, 5), uniform(0, 5), k % 7 ? uniform(0, 5) : 0));
        sw_vec3 eye = sw_v3(uniform(-20, 20), uniform(-20, 20), uniform(-20, 20));
        sw_vec3 f = sw_v3_normalize(sw_v3(uniform(-1, 1), k % 5 ? uniform(-1, 1) : 0,
                                          uniform(-1, 1)));
        double lo = INFINITY, hi = -INFINITY, got_lo, got_hi;
        for (int i = 0; i < 8; i++) {
            sw_vec3 c = sw_v3(i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y,
                              i & 4 ? b.max.z : b.min.z);
            double d = sw_v3_dot(sw_v3_sub(c, eye), f);
            lo = fmin(lo, d), hi = fmax(hi, d);
        }
        sw_box_depth_range(&b, eye, f, &got_lo, &got_hi);
        differ += got_lo != lo || got_hi != hi;
    }
    SW_CHECK(differ == 0);
}

static void test_build_fits_its_bytes_and_refuses_less(void)
{
    uint32_t n = 200;
    make_scene(n);
    size_t bytes = (size_t)sw_cull_tree_bytes_of(g_surfaces, n);
    void *block = malloc(bytes);
    sw_arena a;
    sw_error err;
    sw_cull_tree t;
    sw_arena_init(&a, block, bytes);
    SW_CHECK(sw_cull_tree_build(&t, g_surfaces, n, g_patches, &a, &err) == SW_OK);
    /* The nodes the bytes count are the nodes the build made. */
    uint64_t nodes = 0;
    for (uint32_t s = 0; s < n; s++)
        nodes += sw_cull_tree_patch_nodes(g_surfaces[s].patch_count);
    SW_CHECK_MSG(t.patch_node_count == nodes, "%u nodes built, %llu counted", t.patch_node_count,
                 (unsigned long long)nodes);
    SW_CHECK(sw_cull_tree_patch_nodes(0) == 0 && sw_cull_tree_patch_nodes(4) == 1 &&
             sw_cull_tree_patch_nodes(5) == 3 && sw_cull_tree_patch_nodes(40) == 31);
    /* Median splits: at most ceil(log2) + 1 levels over the surfaces with
     * patches, and as many over the 40 patches of one (in leaves of 4). */
    SW_CHECK_MSG(t.depth <= 9 + 5, "depth %u", t.depth);
    SW_CHECK(a.peak <= bytes);
    sw_arena_init(&a, block, bytes / 2);
    SW_CHECK(sw_cull_tree_build(&t, g_surfaces, n, g_patches, &a, &err) == SW_ERR_NO_MEMORY);
    SW_CHECK(strstr(err.message, "culling tree") != NULL);
    free(block);
}

/* A pack's surfaces from an orbit around its box at three distances and
 * from points inside it, each looking at the centre or away. */
static void check_pack(const char *path)
{
    static sw_arena a;
    sw_pack_header h;
    sw_error err;
    if (sw_pack_read_header(path, &h, &err) != SW_OK) {
        SW_CHECK_MSG(0, "%s", err.message);
        return;
    }
    size_t bytes = h.total_size + 4096;
    void *block = malloc(bytes);
    sw_arena_init(&a, block, bytes);
    sw_pack pack;
    if (sw_pack_load(path, &a, &pack, &err) != SW_OK) {
        SW_CHECK_MSG(0, "%s", err.message);
        free(block);
        return;
    }
    uint32_t n = pack.surface_count;
    size_t tree_bytes = (size_t)sw_cull_tree_bytes_of(pack.surfaces, n);
    void *tree_block = malloc(tree_bytes + 4 * n * sizeof(double));
    sw_arena ta;
    sw_arena_init(&ta, tree_block, tree_bytes);
    sw_cull_tree t;
    SW_CHECK(sw_cull_tree_build(&t, pack.surfaces, n, pack.patches, &ta, &err) == SW_OK);
    double *out = (double *)((char *)tree_block + tree_bytes);
    double *nearest[2] = { out, out + n }, *farthest[2] = { out + 2 * n, out + 3 * n };
    sw_vec3 lo = sw_v3(pack.meta->box_min[0], pack.meta->box_min[1], pack.meta->box_min[2]);
    sw_vec3 hi = sw_v3(pack.meta->box_max[0], pack.meta->box_max[1], pack.meta->box_max[2]);
    sw_vec3 centre = sw_v3_scale(sw_v3_add(lo, hi), 0.5);
    double size = sw_v3_length(sw_v3_sub(hi, lo));
    sw_cull_counts tree = { 0, 0 }, brute = { 0, 0 };
    int differ = 0, views = 0;
    for (int k = 0; k < 96; k++, views++) {
        double a_rad = k * 0.41, r = size * (k < 64 ? 0.3 + 0.7 * (k % 3) : uniform(0, 0.4));
        sw_vec3 eye = sw_v3_add(centre, sw_v3(r * cos(a_rad), 0.2 * r * sin(3 * a_rad),
                                              r * sin(a_rad)));
        sw_vec3 target = k % 4 == 3 ? sw_v3_sub(sw_v3_scale(eye, 2), centre) : centre;
        double near_z = size * 1e-3;
        const sw_cull_view v = make_view(eye, target, 0.785, near_z, size * 4);
        differ += compare(&t, pack.surfaces, n, pack.patches, &v, &tree, &brute, nearest, farthest);
    }
    SW_CHECK_MSG(differ == 0, "%s: %d surface answers differ over %d views", path, differ, views);
    printf("  %s: %u surfaces, %u patches; %d views, box tests: tree %llu, every patch %llu\n",
           path, n, pack.meta->patch_count, views, (unsigned long long)tree.box_tests,
           (unsigned long long)brute.box_tests);
    free(tree_block);
    free(block);
}

int main(int argc, char **argv)
{
    SW_RUN(test_depth_range_is_the_corners_extremes);
    SW_RUN(test_tree_equals_brute_force_on_generated_scenes);
    SW_RUN(test_all_or_nothing_costs_one_test);
    SW_RUN(test_build_fits_its_bytes_and_refuses_less);
    for (int i = 1; i < argc; i++)
        check_pack(argv[i]);
    return sw_test_finish();
}
