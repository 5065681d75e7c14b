/* SPDX-License-Identifier: MIT */
/* seamwalk's refusal when a pack needs more memory than --memory-mb: the
 * message says by how much and which of the pack's pools take most, so
 * whoever sizes a unit (or builds its packs: seamwalk-pack build
 * --closest-mm, fewer patches) knows what to change. The pools are a
 * function of the validated pack (sw_pack_runtime_pools), so the pack is
 * read once more here, into a block of its own given back at once; only
 * this refusal, before the run takes anything, reads it so, and only a
 * pack no larger than the limit. Otherwise, or when the block cannot be
 * had or the pack does not load, the message says the total and where the
 * pools are listed. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <string.h>

#include "seamwalk_program.h"
#include "sw_heap.h"
#include "sw_pack_instances.h"

/* The pools, largest first, appended to msg (at most cap bytes with its
 * NUL): "name X MiB, ..." up to five, then how many more. */
static void largest_pools(const sw_pack *pack, char *msg, size_t cap)
{
    sw_runtime_pools pools;
    sw_pack_runtime_pools(pack, &pools);
    const char *names[SW_RUNTIME_POOL_COUNT];
    uint64_t bytes[SW_RUNTIME_POOL_COUNT];
    int n = sw_runtime_pool_list(&pools, names, bytes);
    for (int i = 1; i < n; i++)   /* a few entries: insertion sort, largest first */
        for (int j = i; j > 0 && bytes[j] > bytes[j - 1]; j--) {
            uint64_t b = bytes[j];
            const char *s = names[j];
            bytes[j] = bytes[j - 1], names[j] = names[j - 1];
            bytes[j - 1] = b, names[j - 1] = s;
        }
    uint64_t sum = 0;
    for (int i = 0; i < n; i++)
        sum += bytes[i];
    size_t at = strlen(msg);
    if (pack->header->runtime_bytes > sum)   /* written when the runtime took more */
        at += (size_t)snprintf(msg + at, cap - at, "header's own %.1f MiB beyond the pools, ",
                               (pack->header->runtime_bytes - sum) / 1048576.0);
    int shown = 0;
    for (int i = 0; i < n && shown < 5 && at < cap; i++, shown++)
        at += (size_t)snprintf(msg + at, cap - at, "%s%s %.1f MiB", shown ? ", " : "", names[i],
                               bytes[i] / 1048576.0);
    if (at < cap && n > shown)
        snprintf(msg + at, cap - at, " and %d smaller", n - shown);
}

sw_status sw_program_memory_short(const sw_program *rt, const sw_pack_header *h, double need,
                                  sw_pack_raw_check check, void *user, sw_error *err)
{
    double limit = rt->opt.memory_mb * 1048576.0;
    char pools[SW_ERROR_MESSAGE_MAX] = "";
    /* Read only a pack within the limit: on a unit short of memory, one
     * larger than what the run may take must not be read to say so. */
    size_t bytes = (size_t)h->total_size + 2 * SW_PACK_ALIGN;
    void *block = (double)h->total_size <= limit ? sw_heap_take_block(bytes) : NULL;
    if (block) {
        sw_arena arena;
        sw_arena_init(&arena, block, bytes);
        sw_pack pack;
        sw_error ignored;
        if (sw_pack_load_checked(rt->opt.pack_path, &arena, NULL, check, user, &pack,
                                 &ignored) == SW_OK)
            largest_pools(&pack, pools, sizeof pools);
        sw_heap_give_block(block, bytes);
    }
    if (!pools[0] && (double)h->total_size > limit)
        snprintf(pools, sizeof pools, "the pack itself %.1f MiB (the rest not read: "
                 "seamwalk-pack info lists them)", h->total_size / 1048576.0);
    else if (!pools[0])
        snprintf(pools, sizeof pools, "seamwalk-pack info lists them");
    char copied[160] = "";
    if (!rt->pack_mapped)
        snprintf(copied, sizeof copied, "the pack's file copied into it %.1f MiB (a file only "
                 "root can write is mapped instead), ", h->total_size / 1048576.0);
    return sw_error_set(err, SW_ERR_NO_MEMORY,
                        "needs %.1f MiB of memory, more than --memory-mb %.1f by %.1f MiB; "
                        "of it %sthe pack's runtime memory %.1f MiB by pool, largest first: %s",
                        need / 1048576.0, rt->opt.memory_mb, (need - limit) / 1048576.0,
                        copied, h->runtime_bytes / 1048576.0, pools);
}
