/* seamwalk-flash: puts signed packs onto a display unit's pack store
 * (sw_pack_store.h, firmware/STORE.md) and looks after its slots.
 * Exit status (also in the usage text and the README):
 *   0 done
 *   1 failed (I/O error, damaged store); what the unit boots is unchanged
 *   2 usage error
 *   3 refused: not a valid pack, unsigned, untrusted key or tampered
 *   4 refused: older than the active pack (see --allow-downgrade)
 *   5 busy: another install (or the runtime) holds the store's lock
 *   6 boot-check: no slot would start */
#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "sw_pack_store.h"
#include "sw_store_install.h"

enum { EXIT_OK = 0, EXIT_FAILED = 1, EXIT_USAGE = 2, EXIT_REFUSED = 3, EXIT_OLDER = 4,
       EXIT_BUSY = 5, EXIT_NO_SLOT = 6 };

static const char usage_text[] =
    "usage: seamwalk-flash install --store DIR [--keys FILE] [--allow-downgrade]\n"
    "                              [--chunk-kb N] [--quiet] PACK|-\n"
    "       seamwalk-flash status --store DIR [--keys FILE]\n"
    "       seamwalk-flash mark-good --store DIR\n"
    "       seamwalk-flash rollback --store DIR\n"
    "       seamwalk-flash boot-check --store DIR [--keys FILE] [--attempts K]\n"
    "--keys: the unit's trusted public keys (default DIR/keys). PACK '-' reads\n"
    "standard input. boot-check says which slot the next boot would start and\n"
    "verifies it, without changing anything.\n"
    "exit: 0 done, 1 failed (the unit still boots what it did), 2 usage,\n"
    "3 refused (invalid, unsigned, untrusted or tampered pack), 4 refused (older\n"
    "than the active pack), 5 busy (another install holds the lock), 6 no slot\n"
    "would start (boot-check).\n";

typedef struct args {
    const char *store, *keys, *pack;
    int allow_downgrade, quiet;
    long chunk_kb;
    long attempts;
} args;

static int usage(const char *fmt, const char *arg)
{
    fputs("seamwalk-flash: ", stderr);
    fprintf(stderr, fmt, arg);
    fputc('\n', stderr);
    fputs(usage_text, stderr);
    return EXIT_USAGE;
}

static int failed(const sw_error *err, int code)
{
    fprintf(stderr, "seamwalk-flash: %s\n", err->message);
    return code;
}

static int parse_long(const char *s, long lo, long hi, long *out)
{
    char *end;
    if (!s)
        return 0;
    errno = 0;
    *out = strtol(s, &end, 10);
    return end != s && *end == '\0' && errno == 0 && *out >= lo && *out <= hi;
}

static int parse_args(int argc, char **argv, args *a)
{
    for (int i = 0; i < argc; i++) {
        const char *o = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(o, "--store") == 0 && v)
            a->store = v, i++;
        else if (strcmp(o, "--keys") == 0 && v)
            a->keys = v, i++;
        else if (strcmp(o, "--chunk-kb") == 0) {
            if (!parse_long(v, 1, 1 << 20, &a->chunk_kb))
                return usage("--chunk-kb takes 1..1048576, not '%s'", v ? v : "");
            i++;
        } else if (strcmp(o, "--attempts") == 0) {
            if (!parse_long(v, 1, 1000, &a->attempts))
                return usage("--attempts takes 1..1000, not '%s'", v ? v : "");
            i++;
        } else if (strcmp(o, "--allow-downgrade") == 0)
            a->allow_downgrade = 1;
        else if (strcmp(o, "--quiet") == 0)
            a->quiet = 1;
        else if ((o[0] == '-' && o[1] != '\0') || a->pack)
            return usage("unexpected '%s'", o);
        else
            a->pack = o;
    }
    return a->store ? 0 : usage("%s", "missing --store DIR");
}

static sw_status load_keys(const sw_store *s, const args *a, sw_trusted_keys *keys,
                           sw_error *err)
{
    char path[3200];
    if (a->keys)
        snprintf(path, sizeof path, "%s", a->keys);
    else
        sw_store_path(s, "keys", path, sizeof path);
    return sw_store_read_keys(path, keys, err);
}

/* All of a file or standard input, malloc'd (16-byte aligned). */
static sw_status read_input(const char *path, uint8_t **out, size_t *size, sw_error *err)
{
    FILE *f = strcmp(path, "-") == 0 ? stdin : fopen(path, "rb");
    if (!f)
        return sw_error_set(err, SW_ERR_IO, "%s: %s", path, strerror(errno));
    size_t cap = 1 << 20, n = 0;
    uint8_t *buf = malloc(cap);
    while (buf) {
        n += fread(buf + n, 1, cap - n, f);
        if (n < cap)
            break;
        uint8_t *bigger = realloc(buf, cap * 2);
        if (!bigger)
            free(buf);
        buf = bigger;
        cap *= 2;
    }
    int bad = ferror(f);
    if (f != stdin)
        fclose(f);
    if (!buf || bad) {
        free(buf);
        return sw_error_set(err, buf ? SW_ERR_IO : SW_ERR_NO_MEMORY, "%s: cannot read%s",
                            strcmp(path, "-") == 0 ? "standard input" : path,
                            buf ? "" : ": out of memory");
    }
    *out = buf;
    *size = n;
    return SW_OK;
}

/* ---- install -------------------------------------------------------------- */

typedef struct progress {
    int on;
    const sw_install_report *report;  /* its slot is set before the first chunk */
} progress;

static void show_progress(void *user, uint64_t done, uint64_t total)
{
    const progress *p = user;
    if (p->on)
        fprintf(stderr, "\rseamwalk-flash: writing slot %c %3d%% (%.1f of %.1f MiB)",
                sw_slot_letter(p->report->slot), total ? (int)(100 * done / total) : 100,
                done / 1048576.0, total / 1048576.0);
}

static int install_exit(const sw_install_report *r, sw_status st)
{
    if (st == SW_OK)
        return EXIT_OK;
    if (r->refusal == SW_INSTALL_OLDER)
        return EXIT_OLDER;
    if (r->refusal != SW_INSTALL_ACCEPTED)
        return EXIT_REFUSED;
    return st == SW_ERR_UNSUPPORTED ? EXIT_BUSY : EXIT_FAILED;
}

static const char *const refusal_words[] = {
    "", "not a valid pack", "unsigned", "untrusted key", "tampered", "older version",
};

static int cmd_install(const args *a)
{
    if (!a->pack)
        return usage("install: %s", "missing PACK (or - for standard input)");
    sw_store store;
    sw_trusted_keys keys;
    sw_error err = { 0 };
    uint8_t *bytes = NULL;
    size_t size = 0;
    if (sw_store_open(&store, a->store, &err) != SW_OK || load_keys(&store, a, &keys, &err) ||
        read_input(a->pack, &bytes, &size, &err) != SW_OK)
        return failed(&err, EXIT_FAILED);
    sw_install_report r;
    progress p = { !a->quiet && isatty(2), &r };
    sw_install_options o = { &keys, a->allow_downgrade, (size_t)a->chunk_kb * 1024u,
                             show_progress, &p };
    sw_status st = sw_store_install(&store, bytes, size, &o, &r, &err);
    free(bytes);
    if (p.on)
        fputs("\r\033[K", stderr);
    if (st != SW_OK) {
        if (r.refusal != SW_INSTALL_ACCEPTED) {
            fprintf(stderr, "seamwalk-flash: refused (%s): nothing on the unit changed\n",
                    refusal_words[r.refusal]);
            sw_error_prefix(&err, "%s", strcmp(a->pack, "-") ? a->pack : "standard input");
        }
        return failed(&err, install_exit(&r, st));
    }
    if (r.resumed_at)
        printf("seamwalk-flash: resumed an interrupted install at byte %" PRIu64 "\n",
               r.resumed_at);
    printf("seamwalk-flash: installed '%s' version %" PRIu64 " (%zu bytes) into slot %c, "
           "verified; pending: it starts at the next boot\n", r.name, r.version, size,
           sw_slot_letter(r.slot));
    return EXIT_OK;
}

/* ---- status, mark-good, rollback -------------------------------------------- */

static void print_slot(const sw_store *s, const sw_store_state *st, int i,
                       const sw_trusted_keys *keys)
{
    const sw_store_slot *sl = &st->slot[i];
    printf("slot %c: %s", sw_slot_letter(i), sw_slot_state_name(sl->state));
    if (sl->state != SW_SLOT_EMPTY)
        printf(", '%s' version %" PRIu64 ", %" PRIu64 " bytes", sl->name, sl->version,
               sl->size);
    sw_error err = { 0 };
    if (sl->state == SW_SLOT_EMPTY || !keys)
        printf("\n");
    else if (sw_store_verify_slot(s, i, sl, keys, &err) == SW_OK)
        printf(", verified\n");
    else
        printf(", NOT VALID: %s\n", err.message);
}

static int cmd_status(const args *a)
{
    sw_store store;
    sw_store_state st;
    sw_store_journal j;
    sw_trusted_keys keys;
    sw_error err = { 0 }, key_err = { 0 };
    int journal = 0;
    if (sw_store_open(&store, a->store, &err) != SW_OK ||
        sw_store_read_state(&store, &st, &err) != SW_OK)
        return failed(&err, EXIT_FAILED);
    int have_keys = load_keys(&store, a, &keys, &key_err) == SW_OK;
    printf("store %s (state generation %" PRIu64 ")\n", store.dir, st.generation);
    printf("active: %c\npending: %c", sw_slot_letter(st.active), sw_slot_letter(st.pending));
    if (st.pending != SW_SLOT_NONE)
        printf(" (%" PRIu32 " boots so far)", st.attempts);
    printf("\n");
    for (int i = 0; i < 2; i++)
        print_slot(&store, &st, i, have_keys ? &keys : NULL);
    if (!have_keys)
        printf("slots not verified: %s\n", key_err.message);
    if (sw_store_read_journal(&store, &j, &journal, &err) == SW_OK && journal &&
        st.slot[j.slot].state == SW_SLOT_EMPTY)
        printf("install: interrupted at byte %" PRIu64 " of %" PRIu64 " into slot %c (install "
               "the same pack again to resume)\n", j.done, j.size, sw_slot_letter(j.slot));
    return EXIT_OK;
}

static int cmd_mark_good(const args *a)
{
    sw_store store;
    sw_store_state st;
    sw_error err = { 0 };
    if (sw_store_open(&store, a->store, &err) != SW_OK ||
        sw_store_read_state(&store, &st, &err) != SW_OK)
        return failed(&err, EXIT_FAILED);
    if (st.pending == SW_SLOT_NONE)
        return failed(&(sw_error){ SW_ERR_ARG, "mark-good: no pending slot" }, EXIT_FAILED);
    int p = st.pending;
    sw_status rc = sw_store_mark_good(&store, p, st.slot[p].version, &err);
    if (rc != SW_OK)
        return failed(&err, rc == SW_ERR_UNSUPPORTED ? EXIT_BUSY : EXIT_FAILED);
    printf("seamwalk-flash: slot %c ('%s' version %" PRIu64 ") is good and active\n",
           sw_slot_letter(p), st.slot[p].name, st.slot[p].version);
    return EXIT_OK;
}

static int cmd_rollback(const args *a)
{
    sw_store store;
    sw_error err = { 0 };
    char said[512];
    if (sw_store_open(&store, a->store, &err) != SW_OK)
        return failed(&err, EXIT_FAILED);
    sw_status rc = sw_store_rollback(&store, said, sizeof said, &err);
    if (rc != SW_OK)
        return failed(&err, rc == SW_ERR_UNSUPPORTED ? EXIT_BUSY : EXIT_FAILED);
    printf("seamwalk-flash: rollback: %s\n", said);
    return EXIT_OK;
}

/* ---- boot-check ------------------------------------------------------------- */

/* What seamwalk --store would start now, verified as it would verify it:
 * the same decision (sw_store_boot_decide) and the same fallback. */
static int cmd_boot_check(const args *a)
{
    sw_store store;
    sw_store_state st;
    sw_trusted_keys keys;
    sw_boot_choice c;
    sw_error err = { 0 };
    if (sw_store_open(&store, a->store, &err) != SW_OK ||
        sw_store_read_state(&store, &st, &err) != SW_OK || load_keys(&store, a, &keys, &err))
        return failed(&err, EXIT_FAILED);
    sw_store_state after = st;
    sw_store_boot_decide(&after, a->attempts ? (uint32_t)a->attempts : 3u, &c);
    if (c.message[0])
        printf("boot: %s\n", c.message);
    int slot = c.slot;
    if (slot != SW_SLOT_NONE && sw_store_verify_slot(&store, slot, &st.slot[slot], &keys, &err)) {
        printf("boot: slot %c does not verify: %s\n", sw_slot_letter(slot), err.message);
        slot = c.trial ? c.fallback : SW_SLOT_NONE;
        if (slot != SW_SLOT_NONE &&
            sw_store_verify_slot(&store, slot, &st.slot[slot], &keys, &err) != SW_OK) {
            printf("boot: slot %c does not verify: %s\n", sw_slot_letter(slot), err.message);
            slot = SW_SLOT_NONE;
        }
    }
    if (slot == SW_SLOT_NONE) {
        printf("boot: no valid slot\n");
        return EXIT_NO_SLOT;
    }
    printf("boot: slot %c '%s' version %" PRIu64 " (%s), verified\n", sw_slot_letter(slot),
           st.slot[slot].name, st.slot[slot].version,
           slot == c.slot && c.trial ? "pending, on trial" : "good");
    return EXIT_OK;
}

int main(int argc, char **argv)
{
    if (argc < 2)
        return usage("%s", "missing command");
    const char *cmd = argv[1];
    if (strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0 || strcmp(cmd, "help") == 0) {
        fputs(usage_text, stdout);
        return EXIT_OK;
    }
    args a = { 0 };
    int rc = parse_args(argc - 2, argv + 2, &a);
    if (rc != 0)
        return rc;
    if (strcmp(cmd, "install") == 0)
        rc = cmd_install(&a);
    else if (strcmp(cmd, "status") == 0)
        rc = cmd_status(&a);
    else if (strcmp(cmd, "mark-good") == 0)
        rc = cmd_mark_good(&a);
    else if (strcmp(cmd, "rollback") == 0)
        rc = cmd_rollback(&a);
    else if (strcmp(cmd, "boot-check") == 0)
        rc = cmd_boot_check(&a);
    else
        return usage("unknown command '%s'", cmd);
    if (fflush(stdout) != 0 && rc == EXIT_OK) {
        fprintf(stderr, "seamwalk-flash: cannot write to standard output\n");
        rc = EXIT_FAILED;
    }
    return rc;
}
