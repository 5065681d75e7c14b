/* SPDX-License-Identifier: MIT */
/* The walk's pressure on its bound (sw_seam_walk_pressure): raised by the
 * share of the view that waited (stand-ins + waiting over stand-ins, sqrt
 * 2 to 4) at most every other frame while surfaces in view wait for room
 * in a full cache, when the drawn meshes fill over half of it or the
 * waiting ones are more than a 64th of those drawn; never past
 * SW_SEAM_PRESSURE_MAX; not for a few waiting nor in a cache with room;
 * brought down by sqrt 2 only after 16 frames in a row with none waiting
 * and the drawn meshes under a third of the cache. */
#include <math.h>
#include <string.h>

#include "sw_seam_walk_internal.h"
#include "sw_test.h"

static sw_seam_walk walk(void)
{
    sw_seam_walk w;
    memset(&w, 0, sizeof w);
    w.error_px = 0.5;
    w.pressure = 1.0;
    w.pressure_raised = UINT32_MAX - 1;   /* as sw_seam_walk_init leaves it */
    w.cache.vertex_pool.units = 1000;
    w.cache.index_pool.units = 1000;
    return w;
}

typedef struct shares {
    double drawn_vertices, drawn_indices, used;
} shares;

/* One frame planned: waiting surfaces beside 1,000 drawn by meshes (100
 * of them stand-ins) and 5,000 through part levels, the pools' shares. */
static void frame(sw_seam_walk *w, uint32_t waiting, shares sh)
{
    sw_seam_frame f;
    memset(&f, 0, sizeof f);
    f.waiting_surfaces = waiting;
    f.standins = 100;
    f.covered_surfaces = 5000;
    f.drawn_surfaces = 1000 + f.covered_surfaces;
    double v = (double)w->cache.vertex_pool.units * SW_SEAM_CACHE_VERTEX_UNIT;
    double i = (double)w->cache.index_pool.units * SW_SEAM_CACHE_INDEX_UNIT;
    f.cache_drawn_vertices = (uint64_t)(sh.drawn_vertices * v);
    f.cache_drawn_indices = (uint64_t)(sh.drawn_indices * i);
    f.cache_used_vertices = (uint64_t)(sh.used * v);
    f.cache_used_indices = (uint64_t)(sh.used * i);
    w->frame++;
    sw_seam_walk_pressure(w, &f);
}

static int near(double a, double b)
{
    return fabs(a - b) < 1e-12;
}

static void test_rises_only_when_the_view_fills_the_cache(void)
{
    sw_seam_walk w = walk();
    const shares full = { 0.9, 0.9, 1.0 }, batch = { 0.3, 0.3, 1.0 };
    frame(&w, 5, (shares){ 0.3, 0.3, 0.8 });   /* room left: its blocks, not its size */
    frame(&w, 5, (shares){ 0.9, 0.9, 0.9 });
    frame(&w, 0, full);   /* full, but nothing waits */
    frame(&w, 5, batch);  /* a few waiting while a batch holds the room */
    frame(&w, 5, batch);
    SW_CHECK(w.pressure == 1.0);
    frame(&w, 5, (shares){ 0.3, 0.6, 1.0 });   /* the index pool's drawn meshes fill it */
    SW_CHECK(near(w.pressure, sqrt(2.0)));     /* 105 / 100: sqrt 2 at least */
    SW_CHECK(near(sw_seam_walk_error_px(&w), 0.5 * sqrt(2.0)));
    frame(&w, 5, full);   /* the frame after a rise: its meshes not made yet */
    SW_CHECK(near(w.pressure, sqrt(2.0)));
    frame(&w, 150, batch);   /* a 64th of the drawn waiting: by 250 / 100 */
    SW_CHECK(near(w.pressure, 2.5 * sqrt(2.0)));
    frame(&w, 900, full);
    frame(&w, 900, full);    /* ten times the stand-ins: by 4 at most */
    SW_CHECK(near(w.pressure, 10.0 * sqrt(2.0)));
    for (int i = 0; i < 100; i++)
        frame(&w, 5, full);
    SW_CHECK(w.pressure == SW_SEAM_PRESSURE_MAX);
}

static void test_falls_after_sixteen_calm_frames(void)
{
    sw_seam_walk w = walk();
    const shares calm = { 0.2, 0.2, 0.9 };
    for (int i = 0; i < 6; i++)
        frame(&w, 5, (shares){ 0.9, 0.9, 1.0 });
    double raised = w.pressure;
    SW_CHECK(raised > 2.0);
    for (int i = 0; i < 15; i++)
        frame(&w, 0, calm);
    SW_CHECK(w.pressure == raised);
    frame(&w, 0, (shares){ 0.4, 0.2, 0.9 });   /* a third or more drawn: counted again */
    for (int i = 0; i < 15; i++)
        frame(&w, 0, calm);
    frame(&w, 1, calm);   /* one waiting, in a cache with room: counted again */
    for (int i = 0; i < 15; i++)
        frame(&w, 0, calm);
    SW_CHECK(w.pressure == raised);
    frame(&w, 0, calm);
    SW_CHECK(near(w.pressure, raised / sqrt(2.0)));
    for (int i = 0; i < 16 * 20; i++)
        frame(&w, 0, calm);
    SW_CHECK(w.pressure == 1.0);   /* never below the bound asked for */
}

/* The first frame of a view far larger than the cache: raised at once. */
static void test_first_frame_rises(void)
{
    sw_seam_walk w = walk();
    frame(&w, 300, (shares){ 0.9, 0.9, 1.0 });
    SW_CHECK(near(w.pressure, 4.0));
}

int main(void)
{
    SW_RUN(test_first_frame_rises);
    SW_RUN(test_rises_only_when_the_view_fills_the_cache);
    SW_RUN(test_falls_after_sixteen_calm_frames);
    return sw_test_finish();
}
