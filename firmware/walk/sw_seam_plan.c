/* SPDX-License-Identifier: MIT */
#include "sw_seam_plan.h"

#include <string.h>

size_t sw_seam_plan_bytes(uint32_t surface_count)
{
    size_t n = (size_t)surface_count + 1;
    return sw_arena_worst_case(n * sizeof(sw_seam_draw_item), 64) +
           sw_arena_worst_case(n * sizeof(sw_seam_upload_item), 64);
}

sw_status sw_seam_plan_init(sw_seam_plan *p, uint32_t surface_count, sw_arena *arena,
                            sw_error *err)
{
    memset(p, 0, sizeof *p);
    size_t n = (size_t)surface_count + 1;
    p->draws = sw_arena_alloc(arena, n * sizeof(sw_seam_draw_item), 64);
    p->uploads = sw_arena_alloc(arena, n * sizeof(sw_seam_upload_item), 64);
    if (!p->draws || !p->uploads)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "arena too small for a frame plan "
                            "(%zu bytes)", sw_seam_plan_bytes(surface_count));
    p->capacity = surface_count;
    return SW_OK;
}

void sw_seam_plan_begin(sw_seam_plan *p, uint32_t number)
{
    p->number = number;
    p->draw_count = p->upload_count = 0;
    p->depth_known = 0;
    p->overflow = 0;
    p->visibility_ms = p->drawn_ms = 0;
    p->on_gl_thread = p->overlapped = 0;
    p->swapped = 0;
}

/* A surface is planned once a frame and uploaded at most once (its mesh is
 * made at most once a frame), so the counts stay within capacity; the
 * check keeps a broken caller from writing past the arrays, and counts. */
void sw_seam_plan_draw(sw_seam_plan *p, const sw_seam_draw_item *item)
{
    if (p->draw_count < p->capacity)
        p->draws[p->draw_count++] = *item;
    else
        p->overflow++;
}

void sw_seam_plan_upload(sw_seam_plan *p, uint32_t first_vertex, uint32_t vertex_count,
                         uint32_t first_index, uint32_t index_count)
{
    if (p->upload_count < p->capacity)
        p->uploads[p->upload_count++] =
            (sw_seam_upload_item){ first_vertex, vertex_count, first_index, index_count };
    else
        p->overflow++;
}
