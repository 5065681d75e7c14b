/* SPDX-License-Identifier: MIT */
/* The IMPORT_NOTES section (core/sw_pack_notes.h): what a build's importers
 * skipped or read past, carried in the pack for `seamwalk-pack info`; the
 * reports turned into records (assets/pack/sw_pack_import_notes.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sw_test.h"
#include "pack_sample.h"
#include "sw_pack_import_notes.h"
#include "sw_pack_notes.h"
#include "sw_pack_write.h"

static sw_status open_with(const sw_pack_import_note *notes, uint32_t count, uint8_t **bytes,
                           sw_pack *pack, sw_error *err)
{
    sample s;
    make_sample(&s);
    sw_pack_contents c = sample_contents(&s);
    c.import_notes = notes;
    c.import_note_count = count;
    size_t size = 0;
    *bytes = NULL;
    SW_CHECK_MSG(sw_pack_serialize(&c, bytes, &size, err) == SW_OK, "%s", err->message);
    memset(err, 0, sizeof *err);
    return sw_pack_open_memory(*bytes, size, pack, err);
}

static sw_pack_import_note note(uint32_t kind, uint32_t count, const char *source,
                                const char *what)
{
    sw_pack_import_note n;
    memset(&n, 0, sizeof n);
    n.kind = kind, n.count = count;
    strncpy(n.source, source, sizeof n.source - 1);
    strncpy(n.what, what, sizeof n.what - 1);
    return n;
}

static void test_notes_round_trip(void)
{
    const sw_pack_import_note notes[2] = {
        note(SW_NOTE_SKIPPED, 3, "hammer.iges", "IGES 406"),
        note(SW_NOTE_MESSAGE, 294, "box.step", "STEP: Parameter n0.1 (name) not a quoted String"),
    };
    uint8_t *bytes;
    sw_pack pack;
    sw_error err;
    SW_CHECK_MSG(open_with(notes, 2, &bytes, &pack, &err) == SW_OK, "%s", err.message);
    SW_CHECK(pack.import_note_count == 2 && pack.import_notes != NULL);
    if (pack.import_note_count == 2) {
        SW_CHECK(memcmp(&pack.import_notes[0], &notes[0], sizeof notes[0]) == 0);
        SW_CHECK(memcmp(&pack.import_notes[1], &notes[1], sizeof notes[1]) == 0);
    }
    free(bytes);
}

static void test_no_notes_no_section(void)
{
    uint8_t *bytes;
    sw_pack pack;
    sw_error err;
    SW_CHECK(open_with(NULL, 0, &bytes, &pack, &err) == SW_OK);
    SW_CHECK(pack.import_notes == NULL && pack.import_note_count == 0);
    for (uint32_t i = 0; i < pack.header->section_count; i++)
        SW_CHECK(pack.sections[i].type != SW_SECTION_IMPORT_NOTES);
    free(bytes);
}

static void refused(sw_pack_import_note bad, const char *piece)
{
    uint8_t *bytes;
    sw_pack pack;
    sw_error err;
    SW_CHECK(open_with(&bad, 1, &bytes, &pack, &err) == SW_ERR_FORMAT);
    SW_CHECK_MSG(strstr(err.message, piece) != NULL, "'%s' lacks '%s'", err.message, piece);
    free(bytes);
}

static void test_bad_notes_are_refused(void)
{
    refused(note(7, 1, "a.step", "x"), "IMPORT_NOTES[0].kind: 7");
    refused(note(SW_NOTE_SKIPPED, 0, "a.step", "x"), "IMPORT_NOTES[0].count: 0");
    sw_pack_import_note n = note(SW_NOTE_SKIPPED, 1, "a.step", "x");
    memset(n.source, 'a', sizeof n.source);
    refused(n, "IMPORT_NOTES[0].source: no NUL");
    n = note(SW_NOTE_SKIPPED, 1, "a.step", "x");
    memset(n.what, 'w', sizeof n.what);
    refused(n, "IMPORT_NOTES[0].what: no NUL");
}

/* Two inputs: one clean, one with a skipped kind, a message kind and more
 * messages than the tally names. */
static void test_reports_become_notes(void)
{
    sw_import_report r[2];
    memset(r, 0, sizeof r);
    sw_import_report_unsupported(&r[1], "IGES 406");
    sw_import_report_unsupported(&r[1], "IGES 406");
    sw_import_report_message(&r[1], "IGES: Global Section date", "G line 3: date");
    r[1].messages.total += 5;   /* kinds past the tally's first ones */
    const char *names[2] = {"clean.txt", "part.igs"};
    sw_pack_import_note *notes = NULL;
    uint32_t count = 0;
    sw_error err = {0};
    SW_CHECK(sw_pack_notes_from_reports(names, r, 2, &notes, &count, &err) == SW_OK);
    SW_CHECK_MSG(count == 3, "%u notes", (unsigned)count);
    if (count == 3) {
        SW_CHECK(notes[0].kind == SW_NOTE_SKIPPED && notes[0].count == 2);
        SW_CHECK(strcmp(notes[0].source, "part.igs") == 0 && strcmp(notes[0].what, "IGES 406") == 0);
        SW_CHECK(notes[1].kind == SW_NOTE_MESSAGE && notes[1].count == 1);
        SW_CHECK(notes[2].kind == SW_NOTE_MESSAGE && notes[2].count == 5);
        SW_CHECK(strcmp(notes[2].what, "(other kinds)") == 0);
    }
    free(notes);
    SW_CHECK(sw_pack_notes_from_reports(names, r, 1, &notes, &count, &err) == SW_OK);
    SW_CHECK(notes == NULL && count == 0);   /* a clean import says nothing */
}

int main(void)
{
    SW_RUN(test_notes_round_trip);
    SW_RUN(test_no_notes_no_section);
    SW_RUN(test_bad_notes_are_refused);
    SW_RUN(test_reports_become_notes);
    return sw_test_finish();
}
