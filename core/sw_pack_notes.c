/* SPDX-License-Identifier: MIT */
/* The IMPORT_NOTES section (sw_pack_notes.h). */
#include "sw_pack_notes.h"

#include <stddef.h>
#include <string.h>

_Static_assert(sizeof(sw_pack_import_note) == 128, "sw_pack_import_note");
_Static_assert(offsetof(sw_pack_import_note, source) == 8, "source");
_Static_assert(offsetof(sw_pack_import_note, what) == 56, "what");

const char *sw_pack_note_kind_name(uint32_t kind)
{
    return kind == SW_NOTE_SKIPPED ? "skipped" : kind == SW_NOTE_MESSAGE ? "(read past)" : "unknown";
}

static sw_status check_note(uint32_t i, const sw_pack_import_note *n, sw_error *err)
{
    if (n->kind != SW_NOTE_SKIPPED && n->kind != SW_NOTE_MESSAGE)
        return sw_error_set(err, SW_ERR_FORMAT, "IMPORT_NOTES[%u].kind: %u, expected 1 (skipped) "
                            "or 2 (message)", (unsigned)i, (unsigned)n->kind);
    if (n->count == 0)
        return sw_error_set(err, SW_ERR_FORMAT, "IMPORT_NOTES[%u].count: 0, expected >= 1",
                            (unsigned)i);
    if (!memchr(n->source, 0, sizeof n->source))
        return sw_error_set(err, SW_ERR_FORMAT, "IMPORT_NOTES[%u].source: no NUL in its %zu "
                            "bytes", (unsigned)i, sizeof n->source);
    if (!memchr(n->what, 0, sizeof n->what))
        return sw_error_set(err, SW_ERR_FORMAT, "IMPORT_NOTES[%u].what: no NUL in its %zu bytes",
                            (unsigned)i, sizeof n->what);
    return SW_OK;
}

sw_status sw_pack_map_import_notes(const uint8_t *data, sw_pack *out, sw_error *err)
{
    int found = -1;
    out->import_notes = NULL;
    out->import_note_count = 0;
    for (uint32_t i = 0; i < out->header->section_count; i++) {
        const sw_pack_section *s = &out->sections[i];
        if (s->type != SW_SECTION_IMPORT_NOTES)
            continue;
        if (found >= 0)
            return sw_error_set(err, SW_ERR_FORMAT, "section %u (IMPORT_NOTES): a second "
                                "IMPORT_NOTES section (the first is section %d)", (unsigned)i,
                                found);
        if (s->size % sizeof(sw_pack_import_note) != 0 ||
            s->size / sizeof(sw_pack_import_note) > UINT32_MAX)
            return sw_error_set(err, SW_ERR_FORMAT, "section %u (IMPORT_NOTES): %llu bytes, "
                                "expected a multiple of %zu", (unsigned)i,
                                (unsigned long long)s->size, sizeof(sw_pack_import_note));
        found = (int)i;
    }
    if (found < 0)
        return SW_OK;
    const sw_pack_section *s = &out->sections[found];
    const sw_pack_import_note *notes = (const sw_pack_import_note *)(data + s->offset);
    uint32_t count = (uint32_t)(s->size / sizeof *notes);
    for (uint32_t i = 0; i < count; i++) {
        sw_status st = check_note(i, &notes[i], err);
        if (st != SW_OK)
            return st;
    }
    out->import_notes = count ? notes : NULL;
    out->import_note_count = count;
    return SW_OK;
}
