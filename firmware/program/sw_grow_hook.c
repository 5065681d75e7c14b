/* SPDX-License-Identifier: MIT */
#define _DEFAULT_SOURCE /* MAP_ANONYMOUS */
#include "sw_grow_hook.h"

#include <string.h>
#include <sys/mman.h>

sw_status sw_grow_hook_init(sw_grow_hook *g, size_t step_bytes, uint32_t steps, sw_error *err)
{
    *g = (sw_grow_hook){ 0 };
    if (step_bytes == 0 || steps == 0)
        return SW_OK;
    size_t size = step_bytes * steps;
    /* mmap, not malloc: pages come only as the steps write them, whatever
     * the allocator's thresholds, and the walk's malloc count stays ours. */
    void *p = mmap(NULL, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "--test-grow-kb: cannot reserve %zu bytes",
                            size);
    *g = (sw_grow_hook){ .block = p, .size = size, .step = step_bytes };
    return SW_OK;
}

void sw_grow_hook_step(sw_grow_hook *g)
{
    if (!g->block || g->touched + g->step > g->size)
        return;
    memset(g->block + g->touched, 0xA5, g->step);
    g->touched += g->step;
}

void sw_grow_hook_destroy(sw_grow_hook *g)
{
    if (g->block)
        munmap(g->block, g->size);
    *g = (sw_grow_hook){ 0 };
}
