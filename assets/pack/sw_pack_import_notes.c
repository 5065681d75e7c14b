/* SPDX-License-Identifier: MIT */
#include "sw_pack_import_notes.h"

#include <stdlib.h>
#include <string.h>

#include "sw_pack_sections.h"

/* Records for one tally (at most SW_IMPORT_KINDS + 1); *n grows. */
static void notes_of(const char *name, const sw_import_tally *t, uint32_t kind,
                     sw_pack_import_note *out, uint32_t *n)
{
    size_t listed = 0;
    for (size_t k = 0; k < t->kinds && k < SW_IMPORT_KINDS; k++) {
        sw_pack_import_note *r = &out[(*n)++];
        memset(r, 0, sizeof *r);
        r->kind = kind;
        r->count = t->count[k] > UINT32_MAX ? UINT32_MAX : (uint32_t)t->count[k];
        sw_pack_copy_name(r->source, sizeof r->source, name);
        sw_pack_copy_name(r->what, sizeof r->what, t->kind[k]);
        listed += t->count[k];
    }
    if (t->total > listed) {
        sw_pack_import_note *r = &out[(*n)++];
        memset(r, 0, sizeof *r);
        r->kind = kind;
        r->count = t->total - listed > UINT32_MAX ? UINT32_MAX : (uint32_t)(t->total - listed);
        sw_pack_copy_name(r->source, sizeof r->source, name);
        sw_pack_copy_name(r->what, sizeof r->what, "(other kinds)");
    }
}

sw_status sw_pack_notes_from_reports(const char *const *names, const sw_import_report *reports,
                                     size_t n, sw_pack_import_note **out, uint32_t *count,
                                     sw_error *err)
{
    *out = NULL;
    *count = 0;
    size_t most = 0;
    for (size_t i = 0; i < n; i++)
        most += (reports[i].unsupported.total > 0) * (SW_IMPORT_KINDS + 1) +
                (reports[i].messages.total > 0) * (SW_IMPORT_KINDS + 1);
    if (most == 0)
        return SW_OK;
    if (most > UINT32_MAX / 2)
        return sw_error_set(err, SW_ERR_RANGE, "import notes: %zu inputs, too many", n);
    sw_pack_import_note *notes = malloc(most * sizeof *notes);
    if (!notes)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "import notes: out of memory");
    uint32_t k = 0;
    for (size_t i = 0; i < n; i++) {
        notes_of(names[i], &reports[i].unsupported, SW_NOTE_SKIPPED, notes, &k);
        notes_of(names[i], &reports[i].messages, SW_NOTE_MESSAGE, notes, &k);
    }
    *out = notes;
    *count = k;
    return SW_OK;
}
