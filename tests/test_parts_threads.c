/* SPDX-License-Identifier: MIT */
/* The parts runner on threads (core/sw_parts_threads.h): every part runs
 * exactly once whatever the helpers and the count; with a helper, two parts
 * do run at the same time; items handed to workers (sw_parts_take_items)
 * are each taken once, by one worker, in rising order on each, and a
 * failed one stops the taking; and a pack's checks give the same result and
 * message with it as in order on one thread (under TSan, without a race). */
#include <pthread.h>
#include <stdatomic.h>
#include <string.h>
#include <time.h>
#include <xxhash.h>

#include "sw_test.h"
#include "pack_sample.h"
#include "sw_parts_threads.h"

enum { MAX_PARTS = 200 };

typedef struct tally {
    _Atomic int runs[MAX_PARTS];
} tally;

static void count_part(void *arg, uint32_t p)
{
    tally *t = arg;
    atomic_fetch_add(&t->runs[p], 1);
}

static void test_every_part_runs_once(void)
{
    static const uint32_t counts[] = { 0, 1, 2, 3, 7, MAX_PARTS };
    for (uint32_t helpers = 0; helpers <= SW_PARTS_MAX_HELPERS + 2; helpers++)
        for (size_t c = 0; c < sizeof counts / sizeof counts[0]; c++) {
            static tally t;
            for (int p = 0; p < MAX_PARTS; p++)
                atomic_init(&t.runs[p], 0);
            sw_parts_threads threads;
            sw_parts_runner r = sw_parts_threads_runner(&threads, helpers);
            SW_CHECK(threads.helpers <= SW_PARTS_MAX_HELPERS);
            sw_parts_run(&r, count_part, &t, counts[c]);
            for (uint32_t p = 0; p < MAX_PARTS; p++)
                SW_CHECK_MSG(atomic_load(&t.runs[p]) == (p < counts[c]),
                             "helpers %u, %u parts: part %u ran %d times", helpers, counts[c], p,
                             atomic_load(&t.runs[p]));
        }
}

/* Two parts that each wait for the other to have started: they meet only
 * if they run at once (each gives up after 20 s, so a runner that ran
 * them one after the other fails the check instead of hanging). */
typedef struct meeting {
    _Atomic int started[2];
    int met[2];
} meeting;

static void meet_part(void *arg, uint32_t p)
{
    meeting *m = arg;
    atomic_store(&m->started[p], 1);
    struct timespec pause = { 0, 1000000 };
    for (int waited = 0; waited < 20000 && !atomic_load(&m->started[1 - p]); waited++)
        nanosleep(&pause, NULL);
    m->met[p] = atomic_load(&m->started[1 - p]);
}

static void test_a_helper_runs_parts_at_once(void)
{
    meeting m = { 0 };
    sw_parts_threads threads;
    sw_parts_runner r = sw_parts_threads_runner(&threads, 1);
    sw_parts_run(&r, meet_part, &m, 2);
    SW_CHECK(m.met[0] && m.met[1]);
}

/* The sample pack with its Seam Graph, edit applied, opened in order on
 * this thread and with three helpers: the same status and message. */
static void expect_same_with_threads(void (*edit)(sample_seam *g), const char *needle)
{
    sample s;
    make_sample(&s);
    sample_seam g;
    make_sample_seam(&g);
    if (edit)
        edit(&g);
    sw_pack_contents c = sample_contents(&s);
    c.seam = &g.graph;
    uint8_t *bytes = NULL;
    size_t size = 0;
    sw_error err = { 0 }, threaded_err = { 0 };
    SW_CHECK(sw_pack_serialize(&c, &bytes, &size, &err) == SW_OK);
    sw_pack pack;
    sw_status in_order = sw_pack_open_memory(bytes, size, &pack, &err);
    sw_parts_threads threads;
    sw_parts_runner r = sw_parts_threads_runner(&threads, 3);
    sw_status threaded = sw_pack_open_memory_with(bytes, size, &r, &pack, &threaded_err);
    SW_CHECK_MSG(threaded == in_order && strcmp(threaded_err.message, err.message) == 0,
                 "with threads: %s \"%s\"; in order: %s \"%s\"", sw_status_name(threaded),
                 threaded_err.message, sw_status_name(in_order), err.message);
    SW_CHECK_MSG(needle ? strstr(err.message, needle) != NULL : in_order == SW_OK, "%s",
                 err.message);
    free(bytes);
}

static void bad_vertex(sample_seam *g) { g->vertices[13].error = NAN; }
static void bad_collapse(sample_seam *g) { g->collapses[1].error = -1; }
static void bad_slot(sample_seam *g) { g->slots[7].uv[1] = NAN; }
static void bad_ref(sample_seam *g) { g->slot_refs[0] = 13; }
static void bad_loop(sample_seam *g) { g->loops[1].flags = 2; }
static void bad_edge(sample_seam *g) { g->edges[3].b = 10; }
static void bad_vertex_and_edge(sample_seam *g) { bad_vertex(g), bad_edge(g); }
static void bad_ref_and_collapse(sample_seam *g) { bad_ref(g), bad_collapse(g); }

/* Items taken by workers (sw_parts_take_items): who took each, and in
 * which order each worker took its own. */
enum { MAX_ITEMS = 500, MAX_WORKERS = 8 };

typedef struct takings {
    _Atomic int taken[MAX_ITEMS];
    uint32_t by[MAX_ITEMS];
    uint32_t last[MAX_WORKERS];     /* each worker's last item + 1 */
    _Atomic int out_of_order;       /* a worker took an item below its last */
    uint32_t fail_at;               /* the item whose call returns 0 */
} takings;

static int take_item(void *arg, uint32_t worker, uint32_t item)
{
    takings *t = arg;
    atomic_fetch_add(&t->taken[item], 1);
    t->by[item] = worker;
    if (worker >= MAX_WORKERS || item + 1 <= t->last[worker])
        atomic_store(&t->out_of_order, 1);
    if (worker < MAX_WORKERS)
        t->last[worker] = item + 1;
    return item != t->fail_at;
}

static void test_every_item_taken_once_by_a_worker(void)
{
    static const uint32_t counts[] = { 0, 1, 3, 50, MAX_ITEMS };
    for (uint32_t helpers = 0; helpers <= 3; helpers++)
        for (size_t c = 0; c < sizeof counts / sizeof counts[0]; c++) {
            static takings t;
            memset(&t, 0, sizeof t);
            t.fail_at = UINT32_MAX;
            sw_parts_threads threads;
            sw_parts_runner r = sw_parts_threads_runner(&threads, helpers);
            SW_CHECK(sw_parts_at_once(&r) == helpers + 1);
            sw_parts_take_items(&r, helpers + 1, take_item, &t, counts[c]);
            SW_CHECK_MSG(!atomic_load(&t.out_of_order), "helpers %u, %u items", helpers, counts[c]);
            for (uint32_t i = 0; i < MAX_ITEMS; i++)
                SW_CHECK_MSG(atomic_load(&t.taken[i]) == (i < counts[c]) &&
                             (i >= counts[c] || t.by[i] <= helpers),
                             "helpers %u, %u items: item %u taken %d times, by %u", helpers,
                             counts[c], i, atomic_load(&t.taken[i]), t.by[i]);
        }
    SW_CHECK(sw_parts_at_once(NULL) == 1);
}

/* In order on this thread (no runner), worker 0 takes every item in turn
 * and the first that fails is the last taken. */
static void test_a_failed_item_stops_the_taking(void)
{
    static takings t;
    memset(&t, 0, sizeof t);
    t.fail_at = 7;
    sw_parts_take_items(NULL, 4, take_item, &t, 20);
    for (uint32_t i = 0; i < 20; i++)
        SW_CHECK_MSG(atomic_load(&t.taken[i]) == (i <= 7) && t.by[i] == 0,
                     "item %u taken %d times, by %u", i, atomic_load(&t.taken[i]), t.by[i]);
}

static void test_checks_agree_with_threads(void)
{
    expect_same_with_threads(NULL, NULL);
    expect_same_with_threads(bad_vertex, "SEAM_VERTICES[13].error: nan");
    expect_same_with_threads(bad_collapse, "SEAM_COLLAPSES[1].error: -1");
    expect_same_with_threads(bad_slot, "SEAM_SLOTS[7].uv[1]: nan");
    expect_same_with_threads(bad_ref, "SEAM_SLOT_REFS[0]: 13");
    expect_same_with_threads(bad_loop, "SEAM_LOOPS[1].flags: 0x2");
    expect_same_with_threads(bad_edge, "SEAM_EDGES[3].b: 10");
    expect_same_with_threads(bad_vertex_and_edge, "SEAM_VERTICES[13].error: nan");
    expect_same_with_threads(bad_ref_and_collapse, "SEAM_COLLAPSES[1].error: -1");
}

int main(void)
{
    SW_RUN(test_every_part_runs_once);
    SW_RUN(test_a_helper_runs_parts_at_once);
    SW_RUN(test_every_item_taken_once_by_a_worker);
    SW_RUN(test_a_failed_item_stops_the_taking);
    SW_RUN(test_checks_agree_with_threads);
    return sw_test_finish();
}
