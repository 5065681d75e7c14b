/* SPDX-License-Identifier: MIT */
/* A test hook for the soak (seamwalk --test-grow-kb, tests/soak.sh): resident
 * memory that grows by a fixed step at each loop's end, with no allocation
 * in the frame loop, so a test can show that the soak's check fails on
 * growth as it must. The block is reserved at start, untouched; each step
 * writes the next step_bytes of it. Only the walk's thread calls it. */
#ifndef SW_GROW_HOOK_H
#define SW_GROW_HOOK_H

#include <stddef.h>
#include <stdint.h>

#include "sw_error.h"

typedef struct sw_grow_hook {
    unsigned char *block;   /* NULL: no hook */
    size_t size, step, touched;
} sw_grow_hook;

/* Reserves steps * step_bytes of address space (no pages yet).
 * SW_ERR_NO_MEMORY when the system refuses it. */
sw_status sw_grow_hook_init(sw_grow_hook *g, size_t step_bytes, uint32_t steps, sw_error *err);

/* Makes the next step resident; nothing once all steps are taken. */
void sw_grow_hook_step(sw_grow_hook *g);

void sw_grow_hook_destroy(sw_grow_hook *g);

#endif
