/* SPDX-License-Identifier: MIT */
/* Fuzz target: the pack store's state file and install journal parsers
 * (firmware/store/sw_store_text.c). Whatever parses must format back to text that
 * parses to the same values; the boot decision on it must stay in range. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "sw_pack_store.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void round_trip_state(const sw_store_state *s)
{
    char text[SW_STORE_TEXT_MAX];
    size_t n = sw_store_state_format(s, text, sizeof text);
    sw_store_state again;
    if (n == 0 || sw_store_state_parse(text, n, "fuzz", &again, NULL) != SW_OK ||
        again.generation != s->generation || again.active != s->active ||
        again.pending != s->pending || again.attempts != s->attempts)
        abort();
    sw_boot_choice c;
    sw_store_boot_decide(&again, 3, &c);
    if (c.slot < SW_SLOT_NONE || c.slot > SW_SLOT_B)
        abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *text = (const char *)data;
    sw_store_state s;
    sw_store_journal j;
    if (sw_store_state_parse(text, size, "fuzz", &s, NULL) == SW_OK)
        round_trip_state(&s);
    if (sw_store_journal_parse(text, size, "fuzz", &j, NULL) == SW_OK) {
        char out[SW_STORE_TEXT_MAX];
        size_t n = sw_store_journal_format(&j, out, sizeof out);
        sw_store_journal again;
        if (n == 0 || sw_store_journal_parse(out, n, "fuzz", &again, NULL) != SW_OK ||
            memcmp(&again, &j, sizeof j) != 0 || j.done > j.size)
            abort();
    }
    return 0;
}
