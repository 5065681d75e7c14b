/* The pack store's text files and decisions (firmware/sw_store_text.c,
 * sw_store_boot.c, sw_pack_store.c): round trips, every parser error naming
 * its line, the boot decision (trial, fallback, good slot never counted),
 * mark-good and rollback on a directory. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
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

int main(void)
{
    SW_RUN(test_state_round_trip);
    SW_RUN(test_state_errors_name_the_line);
    SW_RUN(test_state_meaning_and_truncation);
    SW_RUN(test_journal_round_trip_and_errors);
    SW_RUN(test_boot_decision);
    SW_RUN(test_mark_good_and_rollback_on_disk);
    return sw_test_finish();
}
