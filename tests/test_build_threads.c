/* SPDX-License-Identifier: MIT */
/* The levels seamwalk-pack build makes on threads are the levels it makes
 * in order on one: the static levels (sw_levels_build) and the part levels
 * (sw_part_levels_build) of a pack, made with no runner and with four
 * threads (core/sw_parts_threads.h), have every array and every count of
 * their reports the same, byte for byte. Takes pack files (CTest passes a
 * generated showroom of many parts and a courtyard cut into pieces, with
 * --cut-patches as it was built) and fails on one without part levels,
 * or with --cut-patches on one that has no part cut.
 * The pack tool's own test compares whole packs (test_build_threads.sh);
 * this one runs the workers in a test program, so that under TSan they run
 * instrumented (tests/run-tsan.sh --threaded). */
#include <stdlib.h>
#include <string.h>

#include "sw_levels_build.h"
#include "sw_pack.h"
#include "sw_part_levels_build.h"
#include "sw_parts_threads.h"
#include "sw_test.h"

enum { HELPERS = 3 };

/* 1 when a[0 .. count) and b[0 .. count) of size bytes each are equal. */
static int same(const void *a, const void *b, size_t count, size_t size)
{
    return count == 0 || memcmp(a, b, count * size) == 0;
}

static void check_levels(const char *path, const sw_levels_built *a, const sw_levels_built *b,
                         sw_levels_report ra, sw_levels_report rb)
{
    const sw_levels *x = &a->view, *y = &b->view;
    int counts = x->level_count == y->level_count && x->vertex_count == y->vertex_count &&
                 x->index_count == y->index_count && x->chain_count == y->chain_count &&
                 x->chain_point_count == y->chain_point_count;
    SW_CHECK_MSG(counts, "%s: static levels %u/%u, vertices %u/%u, indices %u/%u in "
                 "order/threaded", path, x->level_count, y->level_count, x->vertex_count,
                 y->vertex_count, x->index_count, y->index_count);
    if (!counts)
        return;
    SW_CHECK_MSG(same(x->levels, y->levels, x->level_count, sizeof *x->levels) &&
                 same(x->surface_levels, y->surface_levels, x->surface_count + 1u,
                      sizeof *x->surface_levels) &&
                 same(x->vertices, y->vertices, x->vertex_count, sizeof *x->vertices) &&
                 same(a->uvs, b->uvs, 2u * x->vertex_count, sizeof *a->uvs) &&
                 same(x->indices, y->indices, x->index_count, sizeof *x->indices) &&
                 same(x->chains, y->chains, x->chain_count, sizeof *x->chains) &&
                 same(x->chain_points, y->chain_points, x->chain_point_count,
                      sizeof *x->chain_points),
                 "%s: the static levels' arrays differ", path);
    ra.seconds = rb.seconds = 0;
    SW_CHECK_MSG(memcmp(&ra, &rb, sizeof ra) == 0, "%s: the static levels' counts differ", path);
}

static void check_part_levels(const char *path, const sw_part_levels_built *a,
                              const sw_part_levels_built *b, sw_part_levels_report ra,
                              sw_part_levels_report rb)
{
    const sw_part_levels *x = &a->view, *y = &b->view;
    SW_CHECK_MSG(x->level_count > 0, "%s: no part levels", path);
    int counts = x->level_count == y->level_count && x->vertex_count == y->vertex_count &&
                 x->index_count == y->index_count && x->piece_count == y->piece_count;
    SW_CHECK_MSG(counts, "%s: part levels %u/%u, vertices %u/%u, indices %u/%u in "
                 "order/threaded", path, x->level_count, y->level_count, x->vertex_count,
                 y->vertex_count, x->index_count, y->index_count);
    if (!counts)
        return;
    SW_CHECK_MSG(same(x->levels, y->levels, x->level_count, sizeof *x->levels) &&
                 same(x->piece_levels, y->piece_levels, x->piece_count + 1u,
                      sizeof *x->piece_levels) &&
                 same(x->piece_of, y->piece_of, x->surface_count, sizeof *x->piece_of) &&
                 same(x->vertices, y->vertices, x->vertex_count, sizeof *x->vertices) &&
                 same(x->indices, y->indices, x->index_count, sizeof *x->indices),
                 "%s: the part levels' arrays differ", path);
    ra.seconds = rb.seconds = 0;
    SW_CHECK_MSG(memcmp(&ra, &rb, sizeof ra) == 0, "%s: the part levels' counts differ", path);
}

/* Both levels of pack made with runner (NULL: in order here). */
typedef struct made {
    sw_levels_built levels;
    sw_levels_report levels_report;
    sw_part_levels_built parts;
    sw_part_levels_report parts_report;
} made;

static int make(const sw_pack *pack, const sw_parts_runner *runner, uint32_t cut_patches,
                made *m)
{
    sw_error err = { 0 };
    const sw_levels_options lo = { .runner = runner };
    const sw_part_levels_options po = { .cut_patches = cut_patches, .runner = runner };
    memset(m, 0, sizeof *m);
    sw_status st = sw_levels_build(pack, &lo, &m->levels, &m->levels_report, &err);
    if (st == SW_OK)
        st = sw_part_levels_build(pack, &m->levels.view, &po, &m->parts, &m->parts_report, &err);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    SW_CHECK_MSG(st != SW_OK || !cut_patches || m->parts_report.cut_parts > 0,
                 "no part cut past %u patches", cut_patches);
    return st == SW_OK;
}

static void check_pack_file(const char *path, uint32_t cut_patches)
{
    size_t size = 0;
    uint8_t *bytes = sw_test_read_file(path, &size);
    if (!bytes)
        return;
    sw_pack pack;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_open_memory(bytes, size, &pack, &err) == SW_OK, "%s", err.message);
    sw_parts_threads threads;
    const sw_parts_runner runner = sw_parts_threads_runner(&threads, HELPERS);
    made in_order = { 0 }, threaded = { 0 };
    if (make(&pack, NULL, cut_patches, &in_order) && make(&pack, &runner, cut_patches, &threaded)) {
        check_levels(path, &in_order.levels, &threaded.levels, in_order.levels_report,
                     threaded.levels_report);
        check_part_levels(path, &in_order.parts, &threaded.parts, in_order.parts_report,
                          threaded.parts_report);
    }
    made *both[] = { &in_order, &threaded };
    for (int i = 0; i < 2; i++) {
        sw_levels_built_free(&both[i]->levels);
        sw_part_levels_built_free(&both[i]->parts);
    }
    free(bytes);
}

int main(int argc, char **argv)
{
    uint32_t cut_patches = 0;
    int first = 1;
    if (argc > 2 && strcmp(argv[1], "--cut-patches") == 0)
        cut_patches = (uint32_t)strtoul(argv[2], NULL, 10), first = 3;
    SW_CHECK_MSG(argc > first, "usage: test_build_threads [--cut-patches N] PACK...");
    for (int i = first; i < argc; i++)
        check_pack_file(argv[i], cut_patches);
    return sw_test_finish();
}
