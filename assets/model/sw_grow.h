/* SPDX-License-Identifier: MIT */
/* Growing a malloc'd array on the host: the one doubling rule the model's
 * and the sewing code's append functions share. Host only. */
#ifndef SW_GROW_H
#define SW_GROW_H

#include <stdint.h>
#include <stdlib.h>

/* items (may be NULL) with room for at least need elements of item_size
 * bytes: the same pointer when *capacity already holds them, else a larger
 * block (twice the capacity plus 64, or need if more) with *capacity
 * updated. NULL when out of memory or the size overflows; items is then
 * still valid and *capacity unchanged. */
static inline void *sw_grow(void *items, size_t *capacity, size_t need, size_t item_size)
{
    if (need <= *capacity)
        return items;
    size_t cap = *capacity <= (SIZE_MAX - 64) / 2 ? *capacity * 2 + 64 : SIZE_MAX;
    if (cap < need)
        cap = need;
    if (item_size && cap > SIZE_MAX / item_size)
        return NULL;
    void *grown = realloc(items, cap * item_size);
    if (grown)
        *capacity = cap;
    return grown;
}

#endif
