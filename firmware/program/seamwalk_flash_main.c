/* SPDX-License-Identifier: MIT */
/* seamwalk-flash: puts signed packs onto a display unit's pack store
 * (sw_pack_store.h, firmware/store/STORE.md) and looks after its slots.
 * Exit status (also in the usage text and docs/flashing.md):
 *   0 done
 *   1 failed (I/O error, damaged store); what the unit boots is unchanged
 *   2 usage error
 *   3 refused: not a valid pack, unsigned, untrusted key or tampered
 *   4 refused: older than the active pack (see --allow-downgrade)
 *   5 busy: another install (or the runtime) holds the store's lock
 *   6 boot-check: no slot would start
 * The trusted keys are the unit's own: [pack] keys in the unit's config
 * (--config, default /etc/seamwalk/seamwalk.ini), else /etc/seamwalk/keys,
 * and only from a file root alone can change (sw_store_read_trusted_keys).
 * --keys can only narrow them. */
#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "sw_config.h"
#include "sw_option_table.h"
#include "sw_pack_store.h"
#include "sw_store_install.h"

enum { EXIT_OK = 0, EXIT_FAILED = 1, EXIT_USAGE = 2, EXIT_REFUSED = 3, EXIT_OLDER = 4,
       EXIT_BUSY = 5, EXIT_NO_SLOT = 6 };

static const char usage_text[] =
    "usage: seamwalk-flash install [--store DIR] [--allow-downgrade] [--chunk-kb N]\n"
    "                              [--quiet] PACK|-\n"
    "       seamwalk-flash status [--store DIR]\n"
    "       seamwalk-flash mark-good [--store DIR]\n"
    "       seamwalk-flash rollback [--store DIR]\n"
    "       seamwalk-flash boot-check [--store DIR] [--attempts K]\n"
    "       seamwalk-flash repair [--store DIR]\n"
    "       seamwalk-flash --help | --version\n"
    "every command also takes [--config FILE] [--keys FILE]\n"
    "--config: the unit's config (default /etc/seamwalk/seamwalk.ini, if it\n"
    "exists): its [pack] store is the default DIR, its [pack] keys the unit's\n"
    "trusted keys (default /etc/seamwalk/keys; owned by root, writable by no\n"
    "one else), its boot_attempts boot-check's K. --keys: trust only these of\n"
    "the unit's keys (it cannot add one). PACK '-' reads standard input.\n"
    "boot-check says what the next boot would start and verifies it, without\n"
    "changing anything; run it as the unit's user to see what the service\n"
    "sees. repair rewrites a damaged copy of the state from the good one, or\n"
    "with no valid copy rebuilds the state from the slots that verify.\n"
    "exit: 0 done, 1 failed (the unit still boots what it did), 2 usage,\n"
    "3 refused (invalid, unsigned, untrusted or tampered pack), 4 refused (older\n"
    "than the active pack), 5 busy (another install holds the lock), 6 no slot\n"
    "would start (boot-check).\n";

typedef struct args {
    const char *store, *keys, *pack, *config;
    int allow_downgrade, quiet;
    long chunk_kb;
    long attempts;
} args;

static int usage(const char *fmt, const char *arg)
{
    return sw_usage_error("seamwalk-flash", fmt, arg);
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

/* --attempts K in the range of seamwalk's --boot-attempts and [pack]
 * boot_attempts, their row of the option table: 0, or a usage error. */
static int read_attempts(const char *v, long *out)
{
    const sw_option_desc *d = sw_option_for_key("pack", "boot_attempts");
    char range[80];
    sw_option_format_range(d, range, sizeof range);
    if (parse_long(v, (long)d->min, (long)d->max, out))
        return 0;
    return sw_usage_error("seamwalk-flash", "--attempts takes %s, not '%s'", range, v ? v : "");
}

static int parse_args(int argc, char **argv, args *a)
{
    for (int i = 0; i < argc; i++) {
        const char *o = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(o, "--store") == 0 && v)
            a->store = v, i++;
        else if (strcmp(o, "--keys") == 0 && v)
            a->keys = v, i++;
        else if (strcmp(o, "--config") == 0 && v)
            a->config = v, i++;
        else if (strcmp(o, "--chunk-kb") == 0) {
            if (!parse_long(v, 1, 1 << 20, &a->chunk_kb))
                return usage("--chunk-kb takes 1..1048576, not '%s'", v ? v : "");
            i++;
        } else if (strcmp(o, "--attempts") == 0) {
            int bad = read_attempts(v, &a->attempts);
            if (bad)
                return bad;
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
    return 0;
}

/* What the unit runs with: its config's store, keys and boot attempts. */
static sw_config unit;

static int read_unit_config(args *a)
{
    sw_config_defaults(&unit);
    const char *path = a->config ? a->config : SW_STORE_DEFAULT_CONFIG;
    sw_error err = { 0 };
    if ((a->config || access(path, F_OK) == 0) && sw_config_load(path, &unit, &err) != SW_OK) {
        fprintf(stderr, "seamwalk-flash: the unit's config: %s\n", err.message);
        return EXIT_FAILED;
    }
    if (!a->store && unit.store[0])
        a->store = unit.store;
    if (!a->attempts)
        a->attempts = unit.boot_attempts;
    return a->store ? 0 : usage("%s", "missing --store DIR (or [pack] store in the config)");
}

/* The unit's trusted keys; with --keys, only those of them it names: a
 * key the unit does not trust is refused (*widens 1), so --keys cannot
 * widen trust. */
static sw_status load_keys(const args *a, sw_trusted_keys *keys, int *widens, sw_error *err)
{
    const char *path = unit.keys[0] ? unit.keys : SW_STORE_DEFAULT_KEYS;
    sw_trusted_keys narrow;
    *widens = 0;
    sw_status st = sw_store_read_trusted_keys(path, keys, err);
    if (st != SW_OK || !a->keys)
        return st;
    if ((st = sw_store_read_keys(a->keys, &narrow, err)) != SW_OK)
        return st;
    for (uint32_t i = 0; i < narrow.count; i++) {
        uint32_t k = 0;
        while (k < keys->count && memcmp(keys->keys[k], narrow.keys[i], SW_KEY_BYTES) != 0)
            k++;
        *widens = k == keys->count;
        if (*widens)
            return sw_error_set(err, SW_ERR_ARG, "%s: key %02x%02x%02x%02x... is not among the "
                                "unit's trusted keys (%s): --keys can only narrow them",
                                a->keys, narrow.keys[i][0], narrow.keys[i][1],
                                narrow.keys[i][2], narrow.keys[i][3], path);
    }
    *keys = narrow;
    return SW_OK;
}

/* A keys failure's exit: a --keys key the unit does not trust is refused. */
static int keys_exit(int widens)
{
    return widens ? EXIT_REFUSED : EXIT_FAILED;
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
    if (sw_store_open(&store, a->store, &err) != SW_OK)
        return failed(&err, EXIT_FAILED);
    int widens;
    if (load_keys(a, &keys, &widens, &err) != SW_OK) {
        if (widens)
            fprintf(stderr, "seamwalk-flash: refused (untrusted key): nothing on the unit "
                    "changed\n");
        return failed(&err, keys_exit(widens));
    }
    if (read_input(a->pack, &bytes, &size, &err) != SW_OK)
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

/* The slots as their files say, verified, when no state is valid. */
static void print_slot_files(const sw_store *s, const sw_trusted_keys *keys)
{
    for (int i = 0; i < 2; i++) {
        sw_store_slot sl;
        sw_error err = { 0 };
        if (sw_store_peek_slot(s, i, &sl, &err) != SW_OK) {
            printf("slot %c file: %s\n", sw_slot_letter(i), err.message);
            continue;
        }
        printf("slot %c file: '%s' version %" PRIu64 ", %" PRIu64 " bytes", sw_slot_letter(i),
               sl.name, sl.version, sl.size);
        if (!keys)
            printf("\n");
        else if (sw_store_verify_slot(s, i, &sl, keys, &err) == SW_OK)
            printf(", verified\n");
        else
            printf(", NOT VALID: %s\n", err.message);
    }
}

static int cmd_status(const args *a)
{
    sw_store store;
    sw_store_state st;
    sw_state_copies copies;
    sw_store_journal j;
    sw_trusted_keys keys;
    sw_error err = { 0 }, key_err = { 0 };
    int journal = 0;
    if (sw_store_open(&store, a->store, &err) != SW_OK)
        return failed(&err, EXIT_FAILED);
    int widens;
    int have_keys = load_keys(a, &keys, &widens, &key_err) == SW_OK;
    if (sw_store_read_state_copies(&store, &st, &copies, &err) != SW_OK) {
        printf("%s\n", err.message);
        print_slot_files(&store, have_keys ? &keys : NULL);
        if (!have_keys)
            printf("slots not verified: %s\n", key_err.message);
        return EXIT_FAILED;
    }
    printf("store %s (state generation %" PRIu64 ")\n", store.dir, st.generation);
    for (int i = 0; i < SW_STATE_COPIES; i++)
        if (!copies.valid[i] && copies.used >= 0)
            printf("state: %s (seamwalk-flash repair rewrites it from %s)\n", copies.why[i],
                   sw_state_copy_names[copies.used]);
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

/* ---- repair ----------------------------------------------------------------- */

/* No valid copy: every slot file that verifies is good, the newest active. */
static void rebuild_from_slots(sw_store *s, const sw_trusted_keys *keys, sw_store_state *st)
{
    *st = (sw_store_state){ .active = SW_SLOT_NONE, .pending = SW_SLOT_NONE };
    for (int i = 0; i < 2; i++) {
        sw_store_slot sl;
        sw_error err = { 0 };
        if (sw_store_peek_slot(s, i, &sl, &err) == SW_OK &&
            sw_store_verify_slot(s, i, &sl, keys, &err) == SW_OK) {
            st->slot[i] = sl;
            if (st->active == SW_SLOT_NONE || sl.version > st->slot[st->active].version)
                st->active = i;
            printf("repair: slot %c '%s' version %" PRIu64 " verifies: good\n",
                   sw_slot_letter(i), sl.name, sl.version);
        } else {
            printf("repair: slot %c: %s: empty\n", sw_slot_letter(i), err.message);
        }
    }
}

static int repair_locked(sw_store *s, const sw_trusted_keys *keys)
{
    sw_store_state st;
    sw_state_copies copies;
    sw_error err = { 0 };
    int readable = sw_store_read_state_copies(s, &st, &copies, &err) == SW_OK;
    if (readable && copies.valid[0] && copies.valid[1] &&
        copies.generation[0] == copies.generation[1]) {
        printf("repair: both copies of the state are valid (generation %" PRIu64 "): nothing "
               "to do\n", st.generation);
        return EXIT_OK;
    }
    if (readable && copies.used >= 0) {
        for (int i = 0; i < SW_STATE_COPIES; i++)
            if (!copies.valid[i] || copies.generation[i] != st.generation)
                printf("repair: %s\n", copies.valid[i] ? "an older copy" : copies.why[i]);
        printf("repair: rewriting the state from %s (generation %" PRIu64 ")\n",
               sw_state_copy_names[copies.used], st.generation);
    } else {
        printf("repair: %s\n", readable ? "no state file" : err.message);
        rebuild_from_slots(s, keys, &st);
    }
    if (sw_store_write_state(s, &st, &err) != SW_OK)
        return failed(&err, EXIT_FAILED);
    printf("repair: state written (generation %" PRIu64 "): active %c, pending %c\n",
           st.generation, sw_slot_letter(st.active), sw_slot_letter(st.pending));
    return EXIT_OK;
}

static int cmd_repair(const args *a)
{
    sw_store store;
    sw_trusted_keys keys;
    sw_error err = { 0 };
    sw_status st;
    if (sw_store_open(&store, a->store, &err) != SW_OK)
        return failed(&err, EXIT_FAILED);
    int widens;
    if (load_keys(a, &keys, &widens, &err) != SW_OK)
        return failed(&err, keys_exit(widens));
    if ((st = sw_store_lock(&store, 0, &err)) != SW_OK)
        return failed(&err, st == SW_ERR_UNSUPPORTED ? EXIT_BUSY : EXIT_FAILED);
    int rc = repair_locked(&store, &keys);
    sw_store_unlock(&store);
    return rc;
}

/* ---- boot-check ------------------------------------------------------------- */

/* What seamwalk --store would start now, verified as it would verify it:
 * the boot's own steps (sw_store_boot_begin: the lock, both copies of the
 * state, the decision, the write probed, not made) and its fallback. As
 * the unit's user it sees what the service sees. */
static int cmd_boot_check(const args *a)
{
    sw_store store;
    sw_store_state st;
    sw_trusted_keys keys;
    sw_boot_choice c;
    sw_error err = { 0 };
    char kind[128];
    int slots[2];
    if (sw_store_open(&store, a->store, &err) != SW_OK)
        return failed(&err, EXIT_FAILED);
    int widens;
    if (load_keys(a, &keys, &widens, &err) != SW_OK) { /* the boot starts nothing either */
        printf("boot: %s\nboot: no valid slot\n", err.message);
        return EXIT_NO_SLOT;
    }
    sw_store_boot_begin(&store, (uint32_t)a->attempts, 0, &st, &c);
    if (c.message[0])
        printf("boot: %s\n", c.message);
    int n = sw_boot_choice_slots(&c, slots);
    for (int i = 0; i < n; i++) {
        int slot = slots[i];
        if (sw_store_verify_slot(&store, slot, &st.slot[slot], &keys, &err) != SW_OK) {
            printf("boot: slot %c does not verify: %s\n", sw_slot_letter(slot), err.message);
            continue;
        }
        sw_boot_kind(&c, &st, slot, kind, sizeof kind);
        printf("boot: slot %c '%s' version %" PRIu64 " (%s), verified\n", sw_slot_letter(slot),
               st.slot[slot].name, st.slot[slot].version, kind);
        return EXIT_OK;
    }
    printf("boot: no valid slot\n");
    return EXIT_NO_SLOT;
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
    if (strcmp(cmd, "--version") == 0) {
        puts("seamwalk-flash " SW_VERSION);
        return fflush(stdout) == 0 ? EXIT_OK : 1;
    }
    args a = { 0 };
    int rc = parse_args(argc - 2, argv + 2, &a);
    if (rc == 0)
        rc = read_unit_config(&a);
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
    else if (strcmp(cmd, "repair") == 0)
        rc = cmd_repair(&a);
    else
        return usage("unknown command '%s'", cmd);
    if (fflush(stdout) != 0 && rc == EXIT_OK) {
        fprintf(stderr, "seamwalk-flash: cannot write to standard output\n");
        rc = EXIT_FAILED;
    }
    return rc;
}
