/* SPDX-License-Identifier: MIT */
/* The walk's pressure on its bound (sw_seam_walk_pressure): raised by
 * sqrt 2 at most every other frame while surfaces in view wait with the
 * drawn meshes over half the cache, never past SW_SEAM_PRESSURE_MAX, not
 * for waiting alone (a cache with room: its blocks, not its size), and
 * brought down by sqrt 2 only after 16 frames in a row with the drawn
 * meshes under a third of it. */
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
    w.cache.vertex_pool.units = 1000;
    w.cache.index_pool.units = 1000;
    return w;
}

/* One frame planned with waiting surfaces and drawn shares of the pools. */
static void frame(sw_seam_walk *w, uint32_t waiting, double vertex_share, double index_share)
{
    sw_seam_frame f;
    memset(&f, 0, sizeof f);
    f.waiting_surfaces = waiting;
    f.cache_drawn_vertices =
        (uint64_t)(vertex_share * w->cache.vertex_pool.units * SW_SEAM_CACHE_VERTEX_UNIT);
    f.cache_drawn_indices =
        (uint64_t)(index_share * w->cache.index_pool.units * SW_SEAM_CACHE_INDEX_UNIT);
    w->frame++;
    sw_seam_walk_pressure(w, &f);
}

static void test_rises_only_when_the_view_fills_the_cache(void)
{
    sw_seam_walk w = walk();
    frame(&w, 5, 0.3, 0.3);   /* waiting in a cache with room: its blocks, not its size */
    frame(&w, 5, 0.3, 0.3);
    SW_CHECK(w.pressure == 1.0);
    frame(&w, 0, 0.9, 0.9);   /* full, but nothing waits */
    SW_CHECK(w.pressure == 1.0);
    frame(&w, 5, 0.3, 0.6);   /* the index pool is the full one */
    SW_CHECK(fabs(w.pressure - sqrt(2.0)) < 1e-12);
    SW_CHECK(fabs(sw_seam_walk_error_px(&w) - 0.5 * sqrt(2.0)) < 1e-12);
    frame(&w, 5, 0.6, 0.6);   /* the frame after a rise: its meshes not made yet */
    SW_CHECK(fabs(w.pressure - sqrt(2.0)) < 1e-12);
    frame(&w, 5, 0.6, 0.6);
    SW_CHECK(fabs(w.pressure - 2.0) < 1e-12);
    for (int i = 0; i < 100; i++)
        frame(&w, 5, 0.9, 0.9);
    SW_CHECK(w.pressure == SW_SEAM_PRESSURE_MAX);
}

static void test_falls_after_sixteen_calm_frames(void)
{
    sw_seam_walk w = walk();
    for (int i = 0; i < 6; i++)
        frame(&w, 5, 0.9, 0.9);
    double raised = w.pressure;
    SW_CHECK(raised > 2.0);
    for (int i = 0; i < 15; i++)
        frame(&w, 0, 0.2, 0.2);
    SW_CHECK(w.pressure == raised);
    frame(&w, 0, 0.4, 0.2);   /* a third or more drawn: the count starts again */
    for (int i = 0; i < 15; i++)
        frame(&w, 0, 0.2, 0.2);
    SW_CHECK(w.pressure == raised);
    frame(&w, 0, 0.2, 0.2);
    SW_CHECK(fabs(w.pressure - raised / sqrt(2.0)) < 1e-12);
    for (int i = 0; i < 16 * 20; i++)
        frame(&w, 0, 0.2, 0.2);
    SW_CHECK(w.pressure == 1.0);   /* never below the bound asked for */
}

int main(void)
{
    SW_RUN(test_rises_only_when_the_view_fills_the_cache);
    SW_RUN(test_falls_after_sixteen_calm_frames);
    return sw_test_finish();
}
