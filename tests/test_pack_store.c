/* SPDX-License-Identifier: MIT */
/* The pack store's text files and decisions (firmware/store/sw_store_text.c,
 * sw_store_boot.c, sw_pack_store.c): round trips, every parser error naming
 * its line, the boot decision (trial, fallback, good slot never counted),
 * mark-good and rollback on a directory, the state's two copies, and the
 * boot's run as boot-check (nothing changed) and as a boot. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "sw_pack_store.h"
#include "sw_test.h"

static sw_store_state two_slots(void)
{
    sw_store_state s = { .generation = 7, .active = SW_SLOT_A, .pending = SW_SLOT_B,
                         .attempts = 1 };
    s.slot[0] = (sw_store_slot){ SW_SLOT_GOOD, 3, 1000, "hall-3" };
    s.slot[1] = (sw_store_slot){ SW_SLOT_PENDING, 4, 2000, "hall 4" };
    return s;
}

static void test_state_round_trip(void)
{
    sw_store_state s = two_slots(), back;
    char text[SW_STORE_TEXT_MAX];
    size_t n = sw_store_state_format(&s, text, sizeof text);
    sw_error err = { 0 };
    SW_CHECK(n > 0);
    SW_CHECK_MSG(sw_store_state_parse(text, n, "state", &back, &err) == SW_OK, "%s",
                 err.message);
    SW_CHECK(memcmp(&back, &s, sizeof s) == 0);
    SW_CHECK(strstr(text, "slot B pending 4 2000 hall 4\n") != NULL);
}

/* The state's text with one line replaced (or the text cut at 'cut'). */
static sw_status parse_edited(const char *from, const char *to, sw_error *err)
{
    sw_store_state s = two_slots(), out;
    char text[SW_STORE_TEXT_MAX];
    size_t n = sw_store_state_format(&s, text, sizeof text);
    char *at = strstr(text, from);
    if (!at)
        return SW_OK;
    char edited[SW_STORE_TEXT_MAX];
    snprintf(edited, sizeof edited, "%.*s%s%s", (int)(at - text), text, to, at + strlen(from));
    (void)n;
    return sw_store_state_parse(edited, strlen(edited), "state", &out, err);
}

static void expect(sw_status got, sw_status want, const sw_error *err, const char *needle)
{
    SW_CHECK_MSG(got == want, "status %d, expected %d: %s", got, want, err->message);
    SW_CHECK_MSG(strstr(err->message, needle), "'%s' lacks '%s'", err->message, needle);
}

static void test_state_errors_name_the_line(void)
{
    sw_error err = { 0 };
    expect(parse_edited("seamwalk-store 1", "seamwalk-store 2", &err), SW_ERR_FORMAT, &err,
           "state:1: expected seamwalk-store 1");
    expect(parse_edited("generation 7", "generation -7", &err), SW_ERR_FORMAT, &err,
           "state:2: expected a whole number");
    expect(parse_edited("generation 7", "generation 07", &err), SW_ERR_FORMAT, &err, "state:2:");
    expect(parse_edited("active A", "active C", &err), SW_ERR_FORMAT, &err,
           "state:3: expected A, B or -");
    expect(parse_edited("attempts 1", "attempts 4294967296", &err), SW_ERR_FORMAT, &err,
           "state:5: expected a whole number in range");
    expect(parse_edited("slot A good", "slot A fine", &err), SW_ERR_FORMAT, &err,
           "state:6: expected a slot state");
    expect(parse_edited("slot B", "slot A", &err), SW_ERR_FORMAT, &err,
           "state:7: expected slot B");
    expect(parse_edited("slot A good 3 1000", "slot A good 3", &err), SW_ERR_FORMAT, &err,
           "state:6: expected slot LETTER STATE VERSION SIZE NAME");
    /* Any change above the check line is caught by the check. */
    expect(parse_edited("hall-3", "hall-4", &err), SW_ERR_CHECKSUM, &err,
           "state:8: check");
    expect(parse_edited("check ", "check", &err), SW_ERR_FORMAT, &err, "state:8: expected");
}

static void test_state_meaning_and_truncation(void)
{
    sw_store_state s = two_slots(), out;
    s.slot[0].state = SW_SLOT_PENDING; /* active, but not good */
    char text[SW_STORE_TEXT_MAX];
    size_t n = sw_store_state_format(&s, text, sizeof text);
    sw_error err = { 0 };
    expect(sw_store_state_parse(text, n, "state", &out, &err), SW_ERR_FORMAT, &err,
           "active slot A is pending, expected good");
    s = two_slots();
    n = sw_store_state_format(&s, text, sizeof text);
    size_t refused = 0;
    for (size_t cut = 0; cut < n; cut++)
        refused += sw_store_state_parse(text, cut, "state", &out, &err) != SW_OK;
    SW_CHECK(refused == n);
    text[n] = 'x';
    expect(sw_store_state_parse(text, n + 1, "state", &out, &err), SW_ERR_FORMAT, &err,
           "bytes after the check line");
    char nul[] = "seamwalk-store 1\ngener\0tion 1\n";
    expect(sw_store_state_parse(nul, sizeof nul - 1, "state", &out, &err), SW_ERR_FORMAT, &err,
           "state:2: a NUL byte");
}

static void test_journal_round_trip_and_errors(void)
{
    sw_store_journal j = { .slot = SW_SLOT_B, .size = 5000, .done = 4096 }, back;
    for (int i = 0; i < 32; i++)
        j.digest[i] = (uint8_t)(i * 37);
    char text[SW_STORE_TEXT_MAX];
    size_t n = sw_store_journal_format(&j, text, sizeof text);
    sw_error err = { 0 };
    SW_CHECK(sw_store_journal_parse(text, n, "journal", &back, &err) == SW_OK);
    SW_CHECK(memcmp(&back, &j, sizeof j) == 0);
    j.done = 5001; /* more done than the pack has */
    n = sw_store_journal_format(&j, text, sizeof text);
    expect(sw_store_journal_parse(text, n, "journal", &back, &err), SW_ERR_FORMAT, &err,
           "journal:5: expected a whole number in range");
    j.done = 1;
    n = sw_store_journal_format(&j, text, sizeof text);
    text[strstr(text, "digest ") - text + 7] = 'G';
    expect(sw_store_journal_parse(text, n, "journal", &back, &err), SW_ERR_FORMAT, &err,
           "journal:4: expected 64 lower-case hex digits");
}

static void test_boot_decision(void)
{
    sw_store_state s = two_slots();
    sw_boot_choice c;
    SW_CHECK(sw_store_boot_decide(&s, 3, &c) == 1);
    SW_CHECK(c.slot == SW_SLOT_B && c.trial && c.fallback == SW_SLOT_A && c.attempt == 2);
    SW_CHECK(sw_store_boot_decide(&s, 3, &c) == 1 && c.attempt == 3);
    /* Tries used up: the pending slot is given up, the good one runs. */
    SW_CHECK(sw_store_boot_decide(&s, 3, &c) == 1);
    SW_CHECK(c.slot == SW_SLOT_A && !c.trial && s.pending == SW_SLOT_NONE);
    SW_CHECK(s.slot[1].state == SW_SLOT_BAD);
    SW_CHECK_MSG(strstr(c.message, "did not run healthy in 3 boots: falling back to slot A"),
                 "%s", c.message);
    /* The good slot's boots change nothing, however many. */
    sw_store_state before = s;
    for (int i = 0; i < 100; i++)
        SW_CHECK(sw_store_boot_decide(&s, 3, &c) == 0 && c.slot == SW_SLOT_A);
    SW_CHECK(memcmp(&before, &s, sizeof s) == 0);
    sw_store_state empty = { .active = SW_SLOT_NONE, .pending = SW_SLOT_NONE };
    SW_CHECK(sw_store_boot_decide(&empty, 3, &c) == 0 && c.slot == SW_SLOT_NONE);
}

static void test_mark_good_and_rollback_on_disk(void)
{
    char dir[] = "/tmp/test_pack_store-XXXXXX";
    SW_CHECK(mkdtemp(dir) != NULL);
    sw_store store;
    sw_error err = { 0 };
    SW_CHECK(sw_store_open(&store, dir, &err) == SW_OK);
    sw_store_state s = two_slots(), back;
    SW_CHECK(sw_store_write_state(&store, &s, &err) == SW_OK && s.generation == 8);
    SW_CHECK(sw_store_mark_good(&store, SW_SLOT_B, 3, &err) == SW_ERR_ARG); /* wrong version */
    SW_CHECK(sw_store_mark_good(&store, SW_SLOT_B, 4, &err) == SW_OK);
    SW_CHECK(sw_store_read_state(&store, &back, &err) == SW_OK);
    SW_CHECK(back.active == SW_SLOT_B && back.pending == SW_SLOT_NONE && back.generation == 9);
    char said[256];
    SW_CHECK(sw_store_rollback(&store, said, sizeof said, &err) == SW_OK);
    SW_CHECK(sw_store_read_state(&store, &back, &err) == SW_OK && back.active == SW_SLOT_A);
    SW_CHECK(back.slot[1].state == SW_SLOT_BAD);
    SW_CHECK(sw_store_rollback(&store, said, sizeof said, &err) == SW_ERR_ARG);
    /* A held lock: mark-good and rollback say busy and change nothing. */
    sw_store other = store;
    SW_CHECK(sw_store_lock(&other, 0, &err) == SW_OK);
    SW_CHECK(sw_store_rollback(&store, said, sizeof said, &err) == SW_ERR_UNSUPPORTED);
    SW_CHECK_MSG(strstr(err.message, "busy"), "%s", err.message);
    sw_store_unlock(&other);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    SW_CHECK(system(cmd) == 0);
}

static void write_file(const char *dir, const char *name, const char *text)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    SW_CHECK(f != NULL);
    if (f) {
        fputs(text, f);
        fclose(f);
    }
}

static size_t read_file(const char *dir, const char *name, char *buf, size_t cap)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "r");
    size_t n = f ? fread(buf, 1, cap - 1, f) : 0;
    if (f)
        fclose(f);
    buf[n] = '\0';
    return n;
}

static void remove_dir(const char *dir)
{
    char cmd[256];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    SW_CHECK(system(cmd) == 0);
}

/* Two copies: written alike; one damaged, the other is read and the
 * damage named; both gone beside a slot file, an error, not an empty
 * store, unless the journal says an install is writing that slot. */
static void test_state_two_copies(void)
{
    char dir[] = "/tmp/test_pack_store-XXXXXX", a[SW_STORE_TEXT_MAX], b[SW_STORE_TEXT_MAX];
    SW_CHECK(mkdtemp(dir) != NULL);
    sw_store store;
    sw_error err = { 0 };
    SW_CHECK(sw_store_open(&store, dir, &err) == SW_OK);
    sw_store_state s = two_slots(), back;
    sw_state_copies copies;
    SW_CHECK(sw_store_write_state(&store, &s, &err) == SW_OK);
    SW_CHECK(read_file(dir, "state", a, sizeof a) > 0 && read_file(dir, "state.copy", b, sizeof b) > 0);
    SW_CHECK(strcmp(a, b) == 0);
    write_file(dir, "state", "seamwalk-store 1\ngeneration 99\n");
    SW_CHECK(sw_store_read_state_copies(&store, &back, &copies, &err) == SW_OK);
    SW_CHECK(back.generation == 8 && copies.used == 1 && !copies.valid[0] && copies.valid[1]);
    SW_CHECK_MSG(strstr(copies.why[0], "/state:3: expected \"active\""), "%s", copies.why[0]);
    write_file(dir, "state.copy", "");
    SW_CHECK(sw_store_read_state(&store, &back, &err) == SW_ERR_CHECKSUM);
    SW_CHECK_MSG(strstr(err.message, "state.copy: empty (0 bytes)"), "%s", err.message);
    char path[512];
    snprintf(path, sizeof path, "%s/state", dir);
    unlink(path);
    snprintf(path, sizeof path, "%s/state.copy", dir);
    unlink(path);
    SW_CHECK(sw_store_read_state(&store, &back, &err) == SW_OK && back.generation == 0);
    write_file(dir, "slot-b.swpack", "half a pack");
    SW_CHECK(sw_store_read_state(&store, &back, &err) == SW_ERR_FORMAT);
    SW_CHECK_MSG(strstr(err.message, "no state file beside the slot files"), "%s", err.message);
    sw_store_journal j = { .slot = SW_SLOT_B, .size = 100, .done = 11 };
    SW_CHECK(sw_store_write_journal(&store, &j, &err) == SW_OK);
    SW_CHECK(sw_store_read_state(&store, &back, &err) == SW_OK && back.generation == 0);
    remove_dir(dir);
}

/* boot-check's run (record 0) decides as the boot does and changes no
 * file; the boot (record 1) writes the attempt; a state that cannot be
 * written starts the good slot and says why. */
static void test_boot_begin_check_and_record(void)
{
    char dir[] = "/tmp/test_pack_store-XXXXXX", before[SW_STORE_TEXT_MAX], after[SW_STORE_TEXT_MAX];
    SW_CHECK(mkdtemp(dir) != NULL);
    sw_store store;
    sw_error err = { 0 };
    SW_CHECK(sw_store_open(&store, dir, &err) == SW_OK);
    sw_store_state s = two_slots(), st;
    s.attempts = 0;
    SW_CHECK(sw_store_write_state(&store, &s, &err) == SW_OK);
    read_file(dir, "state", before, sizeof before);
    sw_boot_choice c;
    sw_store_boot_begin(&store, 3, 0, &st, &c);
    SW_CHECK(c.slot == SW_SLOT_B && c.trial && c.attempt == 1 && c.message[0] == '\0');
    read_file(dir, "state", after, sizeof after);
    SW_CHECK(strcmp(before, after) == 0);
    char tmp[512];
    snprintf(tmp, sizeof tmp, "%s/state.tmp", dir);
    SW_CHECK(access(tmp, F_OK) != 0);
    sw_store_boot_begin(&store, 3, 1, &st, &c);
    SW_CHECK(c.slot == SW_SLOT_B && c.trial && st.attempts == 1);
    SW_CHECK(sw_store_read_state(&store, &st, &err) == SW_OK && st.attempts == 1);
    SW_CHECK(mkdir(tmp, 0755) == 0);
    for (int record = 0; record < 2; record++) {
        sw_store_boot_begin(&store, 3, record, &st, &c);
        SW_CHECK(c.slot == SW_SLOT_A && !c.trial);
        SW_CHECK_MSG(strstr(c.message, "cannot record the boot (") &&
                     strstr(c.message, "state.tmp: Is a directory): starting the good slot, "
                            "no trial"), "%s", c.message);
    }
    SW_CHECK(sw_store_read_state(&store, &st, &err) == SW_OK && st.attempts == 1);
    remove_dir(dir);
}

int main(void)
{
    SW_RUN(test_state_round_trip);
    SW_RUN(test_state_errors_name_the_line);
    SW_RUN(test_state_meaning_and_truncation);
    SW_RUN(test_journal_round_trip_and_errors);
    SW_RUN(test_boot_decision);
    SW_RUN(test_mark_good_and_rollback_on_disk);
    SW_RUN(test_state_two_copies);
    SW_RUN(test_boot_begin_check_and_record);
    return sw_test_finish();
}
