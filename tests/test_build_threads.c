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
#include "pack_file.h"

enum { HELPERS = 3 };

/* Both levels of pack made with runner (NULL: in order here). */
typedef struct made {
    sw_levels_built levels;
    sw_levels_report levels_report;
    sw_part_levels_built parts;
    sw_part_levels_report parts_report;
} made;

/* One array as made in order (a) and on threads (b): count items of size
 * bytes each. */
typedef struct array_pair {
    const char *name;
    const void *a, *b;
    uint32_t count_a, count_b;
    size_t size;
} array_pair;

/* Every pair the same length and the same bytes, each difference named. */
static void check_same(const char *path, const array_pair *pairs, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        const array_pair *p = &pairs[i];
        SW_CHECK_MSG(p->count_a == p->count_b, "%s: %s: %u in order, %u on threads", path,
                     p->name, p->count_a, p->count_b);
        SW_CHECK_MSG(p->count_a != p->count_b || p->count_a == 0 ||
                         memcmp(p->a, p->b, p->count_a * p->size) == 0,
                     "%s: %s: the bytes differ", path, p->name);
    }
}

/* The pair of arrays x->array and y->array of x->count and y->count items. */
#define PAIR(name, array, count) \
    { name, x->array, y->array, x->count, y->count, sizeof *x->array }

static void check_levels(const char *path, const sw_levels_built *a, const sw_levels_built *b)
{
    const sw_levels *x = &a->view, *y = &b->view;
    const array_pair pairs[] = {
        PAIR("static levels", levels, level_count),
        { "surface levels", x->surface_levels, y->surface_levels, x->surface_count + 1u,
          y->surface_count + 1u, sizeof *x->surface_levels },
        PAIR("vertices", vertices, vertex_count),
        { "uvs", a->uvs, b->uvs, 2u * x->vertex_count, 2u * y->vertex_count, sizeof *a->uvs },
        PAIR("indices", indices, index_count),
        PAIR("chains", chains, chain_count),
        PAIR("chain points", chain_points, chain_point_count),
    };
    check_same(path, pairs, sizeof pairs / sizeof *pairs);
}

static void check_part_levels(const char *path, const sw_part_levels_built *a,
                              const sw_part_levels_built *b)
{
    const sw_part_levels *x = &a->view, *y = &b->view;
    SW_CHECK_MSG(x->level_count > 0, "%s: no part levels", path);
    const array_pair pairs[] = {
        PAIR("part levels", levels, level_count),
        { "piece levels", x->piece_levels, y->piece_levels, x->piece_count + 1u,
          y->piece_count + 1u, sizeof *x->piece_levels },
        PAIR("pieces", piece_of, surface_count),
        PAIR("part vertices", vertices, vertex_count),
        PAIR("part indices", indices, index_count),
    };
    check_same(path, pairs, sizeof pairs / sizeof *pairs);
}

/* The reports' counts the same (the seconds aside). */
static void check_reports(const char *path, made *a, made *b)
{
    a->levels_report.seconds = b->levels_report.seconds = 0;
    a->parts_report.seconds = b->parts_report.seconds = 0;
    SW_CHECK_MSG(memcmp(&a->levels_report, &b->levels_report, sizeof a->levels_report) == 0,
                 "%s: the static levels' counts differ", path);
    SW_CHECK_MSG(memcmp(&a->parts_report, &b->parts_report, sizeof a->parts_report) == 0,
                 "%s: the part levels' counts differ", path);
}


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
    sw_pack pack;
    uint8_t *bytes = sw_test_open_pack_file(path, &pack);
    if (!bytes)
        return;
    sw_parts_threads threads;
    const sw_parts_runner runner = sw_parts_threads_runner(&threads, HELPERS);
    made in_order = { 0 }, threaded = { 0 };
    if (make(&pack, NULL, cut_patches, &in_order) && make(&pack, &runner, cut_patches, &threaded)) {
        check_levels(path, &in_order.levels, &threaded.levels);
        check_part_levels(path, &in_order.parts, &threaded.parts);
        check_reports(path, &in_order, &threaded);
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
