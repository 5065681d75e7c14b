/* SPDX-License-Identifier: MIT */
/* sw_trim_tess on bad input: every argument and loop error returns its
 * status and writes nothing it should not; random bad loops never crash;
 * patches from a pack. (Split from test_trim_tess.c.) */
#include "trim_tess_fixture.h"

static sw_status call(const surface *s, const loops *l, double err, sw_arena *a, uint32_t *tris)
{
    sw_trim_loops lv = view(l);
    sw_trim_tess_buffers b = {g_pos, g_nrm, NULL, NULL, g_idx, MAXV, MAXI, 0, NULL, 0};
    sw_trim_tess_result res;
    sw_error e = {0};
    sw_status st = sw_trim_tess(s->patches, s->count, &lv, err, NULL, a, &b, &res, &e);
    SW_CHECK(st == SW_OK || e.message[0] != 0);
    *tris = res.index_count / 3;
    return st;
}

static void test_bad_inputs(void)
{
    static surface s;
    static loops l;
    make_bump(&s, 1);
    sw_arena a;
    sw_arena_init(&a, g_block, sizeof g_block);
    uint32_t tris;
    begin_loops(&l);
    add_rect(&l, &s, 0, 1, 0, 1, 2);
    SW_CHECK(call(&s, &l, 0, &a, &tris) == SW_ERR_ARG);
    SW_CHECK(call(&s, &l, -1, &a, &tris) == SW_ERR_ARG);
    SW_CHECK(call(&s, &l, NAN, &a, &tris) == SW_ERR_ARG);
    SW_CHECK(call(&s, &l, INFINITY, &a, &tris) == SW_ERR_ARG);
    /* A bound no 16-bit mesh meets. */
    SW_CHECK(call(&s, &l, 1e-12, &a, &tris) == SW_ERR_RANGE);
    /* No loops, empty loops, loops of two points: nothing to draw. */
    begin_loops(&l);
    SW_CHECK(call(&s, &l, 1e-3, &a, &tris) == SW_OK && tris == 0);
    end_loop(&l);
    end_loop(&l);
    SW_CHECK(call(&s, &l, 1e-3, &a, &tris) == SW_OK && tris == 0);
    begin_loops(&l);
    add_point(&l, &s, 0.2, 0.2);
    add_point(&l, &s, 0.6, 0.7);
    end_loop(&l);
    SW_CHECK(call(&s, &l, 1e-3, &a, &tris) == SW_OK && tris == 0);
    /* Collinear (no area) and repeated points, positions on one line too
     * (on the surface they would span a triangle: test_trim_tess_collapse.c). */
    begin_loops(&l);
    add_point(&l, &s, 0.1, 0.1);
    add_point(&l, &s, 0.5, 0.5);
    add_point(&l, &s, 0.9, 0.9);
    add_point(&l, &s, 0.9, 0.9);
    end_loop(&l);
    for (uint32_t i = 0; i < l.n; i++)
        l.pts[i].p[0] = l.pts[i].p[1] = l.pts[i].p[2] = l.pts[i].uv[0];
    SW_CHECK(call(&s, &l, 1e-3, &a, &tris) == SW_OK && tris == 0);
    /* Outside the domain. */
    begin_loops(&l);
    add_circle(&l, &s, 3, 3, 0.5, 16, 1);
    SW_CHECK(call(&s, &l, 1e-3, &a, &tris) == SW_ERR_RANGE);
    /* Decreasing loop_first. */
    begin_loops(&l);
    add_rect(&l, &s, 0, 1, 0, 1, 2);
    l.first[1] = 9, l.first[0] = 0;
    sw_trim_loops lv = {l.pts, l.first, 1};
    uint32_t bad_first[2] = {5, 2};
    lv.loop_first = bad_first;
    sw_trim_tess_buffers b = {g_pos, g_nrm, NULL, NULL, g_idx, MAXV, MAXI, 0, NULL, 0};
    sw_error e = {0};
    SW_CHECK(sw_trim_tess(s.patches, 1, &lv, 1e-3, NULL, &a, &b, NULL, &e) == SW_ERR_ARG);
    /* NULL pointers, no patches, no buffers. */
    begin_loops(&l);
    add_rect(&l, &s, 0, 1, 0, 1, 2);
    lv = view(&l);
    SW_CHECK(sw_trim_tess(NULL, 1, &lv, 1e-3, NULL, &a, &b, NULL, &e) == SW_ERR_ARG);
    SW_CHECK(sw_trim_tess(s.patches, 0, &lv, 1e-3, NULL, &a, &b, NULL, &e) == SW_ERR_ARG);
    SW_CHECK(sw_trim_tess(s.patches, 1, NULL, 1e-3, NULL, &a, &b, NULL, &e) == SW_ERR_ARG);
    SW_CHECK(sw_trim_tess(s.patches, 1, &lv, 1e-3, NULL, NULL, &b, NULL, &e) == SW_ERR_ARG);
    SW_CHECK(sw_trim_tess(s.patches, 1, &lv, 1e-3, NULL, &a, NULL, NULL, &e) == SW_ERR_ARG);
    sw_trim_tess_buffers nobuf = {NULL, NULL, NULL, NULL, NULL, 10, 10, 0, NULL, 0};
    SW_CHECK(sw_trim_tess(s.patches, 1, &lv, 1e-3, NULL, &a, &nobuf, NULL, &e) == SW_ERR_ARG);
    /* A bad degree, a bad domain, a non-finite control point. */
    static surface bad;
    bad = s;
    bad.patches[0].patch.degree_u = 0;
    SW_CHECK(call(&bad, &l, 1e-3, &a, &tris) == SW_ERR_ARG);
    bad = s;
    bad.patches[0].domain[1] = bad.patches[0].domain[0];
    SW_CHECK(call(&bad, &l, 1e-3, &a, &tris) == SW_ERR_ARG);
    bad = s;
    bad.patches[0].patch.ctrl = bad.ctrl[0];
    bad.ctrl[0][5] = NAN;
    SW_CHECK(call(&bad, &l, 1e-3, &a, &tris) == SW_ERR_RANGE);
    /* An arena too small at every step: a clean NO_MEMORY, never a crash. */
    size_t sizes[] = {0, 64, 1024, 16384, 200000};
    for (int k = 0; k < 5; k++) {
        sw_arena small;
        sw_arena_init(&small, g_block, sizes[k]);
        SW_CHECK(call(&s, &l, 1e-3, &small, &tris) == SW_ERR_NO_MEMORY);
        SW_CHECK(small.used == 0);
    }
    /* Crossing loops (a bow tie) give an error or a mesh, never a crash. */
    begin_loops(&l);
    add_point(&l, &s, 0.1, 0.1);
    add_point(&l, &s, 0.9, 0.9);
    add_point(&l, &s, 0.9, 0.1);
    add_point(&l, &s, 0.1, 0.9);
    end_loop(&l);
    sw_status st = call(&s, &l, 1e-3, &a, &tris);
    SW_CHECK(st == SW_OK || st == SW_ERR_FORMAT);
}

/* Random star-shaped loops (and a random star-shaped hole in some): the area
 * is the polygons', the mesh is watertight and every loop point is used. */
static void test_random_bad_loops_never_crash(void)
{
    static surface s;
    static loops l;
    make_bump(&s, 2);
    sw_test_rng_state = 0xBADC0DEull;
    int ok = 0, format = 0, other = 0;
    for (int trial = 0; trial < 40; trial++) {
        begin_loops(&l);
        int loops_n = 1 + (int)(sw_test_random() * 3);
        for (int k = 0; k < loops_n; k++) {
            int n = 3 + (int)(sw_test_random() * 12);
            for (int i = 0; i < n; i++)
                add_point(&l, &s, sw_test_random(), sw_test_random());
            end_loop(&l);
        }
        mesh m;
        sw_status st = run(&s, &l, 1e-2, &m);
        ok += st == SW_OK, format += st == SW_ERR_FORMAT;
        other += st != SW_OK && st != SW_ERR_FORMAT;
        uint32_t bad = 0;
        for (uint32_t i = 0; st == SW_OK && i < m.ni; i++)
            bad += g_idx[i] >= m.nv;
        SW_CHECK(bad == 0);
    }
    printf("  %d meshed, %d rejected as crossing\n", ok, format);
    SW_CHECK(other == 0);
}

/* A pack's surface as input: views into the pack, the same mesh as the
 * patches passed directly. */
static void test_patches_from_pack(void)
{
    static surface s;
    static loops l;
    make_bump(&s, 2);
    static float control[4 * 16 * 4];
    sw_pack_patch patches[4];
    sw_pack_patch_domain domains[4];
    memset(patches, 0, sizeof patches);
    memset(domains, 0, sizeof domains);
    for (uint32_t i = 0; i < 4; i++) {
        memcpy(control + 64 * i, s.ctrl[i], sizeof(float) * 64);
        patches[i].first_control = 16 * i, patches[i].degree_u = 3, patches[i].degree_v = 3;
        memcpy(domains[i].domain, s.patches[i].domain, sizeof domains[i].domain);
    }
    sw_pack_surface surf = {0, 0, 4, 0, 0, 0, {0, 1, 0, 1}};
    sw_pack pack;
    memset(&pack, 0, sizeof pack);
    pack.patches = patches, pack.control = control, pack.patch_domains = domains;
    pack.surfaces = &surf, pack.surface_count = 1;
    sw_trim_patch got[4];
    uint32_t count;
    sw_error e = {0};
    SW_CHECK(sw_trim_patches_from_pack(&pack, 0, got, 4, &count, &e) == SW_OK && count == 4);
    SW_CHECK(got[3].patch.ctrl == control + 4 * 48 && got[3].domain[0] == s.patches[3].domain[0]);
    SW_CHECK(sw_trim_patches_from_pack(&pack, 0, got, 3, &count, &e) == SW_ERR_NO_MEMORY &&
             count == 4);
    SW_CHECK(sw_trim_patches_from_pack(&pack, 1, got, 4, &count, &e) == SW_ERR_RANGE);
    begin_loops(&l);
    add_circle(&l, &s, 0.5, 0.5, 0.3, 40, 1);
    mesh direct;
    SW_CHECK(run(&s, &l, 1e-3, &direct) == SW_OK);
    static surface from_pack;
    from_pack.count = 4;
    memcpy(from_pack.patches, got, sizeof got);
    mesh m;
    SW_CHECK(run(&from_pack, &l, 1e-3, &m) == SW_OK);
    SW_CHECK(m.ni == direct.ni && m.nv == direct.nv && m.ni > 0);
}


int main(void)
{
    SW_RUN(test_bad_inputs);
    SW_RUN(test_patches_from_pack);
    SW_RUN(test_random_bad_loops_never_crash);
    return sw_test_finish();
}
