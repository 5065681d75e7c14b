/* SPDX-License-Identifier: MIT */
/* The store's two small text files, the state and the install journal
 * (sw_pack_store.h; layout in firmware/store/STORE.md). Text, so an engineer can
 * read a unit's state with cat; a trailing XXH3 line, so a damaged file is
 * told apart from an old one. The parsers take untrusted bytes (a unit's
 * disk) and have a fuzz target (tests/fuzz/fuzz_store.c). */
#include <inttypes.h>
#include <stdio.h>
#include <string.h>
#include <xxhash.h>

#include "sw_pack_store.h"

static const char *const state_names[] = { "empty", "pending", "good", "bad" };

const char *sw_slot_state_name(enum sw_slot_state s)
{
    return (unsigned)s < 4 ? state_names[s] : "?";
}

char sw_slot_letter(int slot) { return slot == SW_SLOT_A ? 'A' : slot == SW_SLOT_B ? 'B' : '-'; }

/* Appends the check line over out[0, n); returns the new length, or 0 if
 * it does not fit. */
static size_t add_check(char *out, size_t n, size_t cap)
{
    if (n == 0 || n >= cap)
        return 0;
    int m = snprintf(out + n, cap - n, "check %016" PRIx64 "\n", (uint64_t)XXH3_64bits(out, n));
    return m > 0 && (size_t)m < cap - n ? n + (size_t)m : 0;
}

size_t sw_store_state_format(const sw_store_state *s, char *out, size_t cap)
{
    int n = snprintf(out, cap, "seamwalk-store 1\ngeneration %" PRIu64 "\nactive %c\n"
                     "pending %c\nattempts %" PRIu32 "\n", s->generation,
                     sw_slot_letter(s->active), sw_slot_letter(s->pending), s->attempts);
    for (int i = 0; i < 2 && n > 0 && (size_t)n < cap; i++) {
        const sw_store_slot *sl = &s->slot[i];
        char name[SW_PACK_NAME_BYTES];
        size_t len = strnlen(sl->name, sizeof name - 1);
        for (size_t k = 0; k < len; k++) /* one line per slot, whatever the signer wrote */
            name[k] = (unsigned char)sl->name[k] < 0x20 || sl->name[k] == 0x7f ? '?' : sl->name[k];
        name[len] = '\0';
        n += snprintf(out + n, cap - (size_t)n, "slot %c %s %" PRIu64 " %" PRIu64 " %s\n",
                      sw_slot_letter(i), sw_slot_state_name(sl->state), sl->version, sl->size,
                      name);
    }
    return n > 0 ? add_check(out, (size_t)n, cap) : 0;
}

size_t sw_store_journal_format(const sw_store_journal *j, char *out, size_t cap)
{
    char hex[65];
    for (int i = 0; i < 32; i++)
        snprintf(hex + 2 * i, 3, "%02x", j->digest[i]);
    int n = snprintf(out, cap, "seamwalk-journal 1\nslot %c\nsize %" PRIu64 "\ndigest %s\n"
                     "done %" PRIu64 "\n", sw_slot_letter(j->slot), j->size, hex, j->done);
    return n > 0 ? add_check(out, (size_t)n, cap) : 0;
}

/* ---- parsing -------------------------------------------------------------- */

typedef struct cursor {
    const char *text;
    size_t size, at;
    size_t line_no;
    const char *name;
    const char *line;                  /* the current line, without its '\n' */
    size_t len;
    sw_error *err;
} cursor;

static sw_status fail(cursor *c, const char *expected)
{
    return sw_error_set(c->err, SW_ERR_FORMAT, "%s:%zu: expected %s", c->name, c->line_no,
                        expected);
}

/* The next line; it must end with '\n' (a file cut short has no last one). */
static sw_status next_line(cursor *c, const char *expected)
{
    c->line_no++;
    const char *nl = c->at < c->size ? memchr(c->text + c->at, '\n', c->size - c->at) : NULL;
    if (!nl)
        return fail(c, expected);
    c->line = c->text + c->at;
    c->len = (size_t)(nl - c->line);
    c->at += c->len + 1;
    if (memchr(c->line, '\0', c->len))
        return sw_error_set(c->err, SW_ERR_FORMAT, "%s:%zu: a NUL byte", c->name, c->line_no);
    return SW_OK;
}

/* The line must start with key and a space; *value is the rest. */
static sw_status keyed(cursor *c, const char *key, const char **value, size_t *len)
{
    char expected[64];
    snprintf(expected, sizeof expected, "\"%s\" and a value", key);
    sw_status st = next_line(c, expected);
    size_t k = strlen(key);
    if (st != SW_OK)
        return st;
    if (c->len <= k + 1 || memcmp(c->line, key, k) != 0 || c->line[k] != ' ')
        return fail(c, expected);
    *value = c->line + k + 1;
    *len = c->len - k - 1;
    return SW_OK;
}

/* A decimal u64 of the whole of s[0, len), no sign, no leading zeros. */
static int parse_u64(const char *s, size_t len, uint64_t *out)
{
    if (len == 0 || len > 20 || (len > 1 && s[0] == '0'))
        return 0;
    uint64_t v = 0;
    for (size_t i = 0; i < len; i++) {
        if (s[i] < '0' || s[i] > '9')
            return 0;
        unsigned d = (unsigned)(s[i] - '0');
        if (v > (UINT64_MAX - d) / 10)
            return 0;
        v = v * 10 + d;
    }
    *out = v;
    return 1;
}

static sw_status keyed_u64(cursor *c, const char *key, uint64_t max, uint64_t *out)
{
    const char *v;
    size_t len;
    sw_status st = keyed(c, key, &v, &len);
    if (st != SW_OK)
        return st;
    if (!parse_u64(v, len, out) || *out > max)
        return fail(c, "a whole number in range");
    return SW_OK;
}

static int letter_slot(const char *v, size_t len, int allow_none, int *out)
{
    if (len != 1)
        return 0;
    *out = v[0] == 'A' ? SW_SLOT_A : v[0] == 'B' ? SW_SLOT_B : SW_SLOT_NONE;
    return *out != SW_SLOT_NONE || (allow_none && v[0] == '-');
}

static sw_status keyed_slot(cursor *c, const char *key, int allow_none, int *out)
{
    const char *v;
    size_t len;
    sw_status st = keyed(c, key, &v, &len);
    if (st != SW_OK)
        return st;
    return letter_slot(v, len, allow_none, out) ? SW_OK
                                                : fail(c, allow_none ? "A, B or -" : "A or B");
}

/* The "check" line over everything before it, then the end of the file. */
static sw_status check_line(cursor *c)
{
    size_t body = c->at;
    const char *v;
    size_t len;
    sw_status st = keyed(c, "check", &v, &len);
    if (st != SW_OK)
        return st;
    char want[17];
    snprintf(want, sizeof want, "%016" PRIx64, (uint64_t)XXH3_64bits(c->text, body));
    if (len != 16 || memcmp(v, want, 16) != 0)
        return sw_error_set(c->err, SW_ERR_CHECKSUM, "%s:%zu: check %.*s, but the lines above "
                            "hash to %s (a damaged file)", c->name, c->line_no,
                            (int)(len < 16 ? len : 16), v, want);
    if (c->at != c->size)
        return sw_error_set(c->err, SW_ERR_FORMAT, "%s:%zu: bytes after the check line",
                            c->name, c->line_no + 1);
    return SW_OK;
}

static sw_status magic_line(cursor *c, const char *magic)
{
    sw_status st = next_line(c, magic);
    if (st == SW_OK && (c->len != strlen(magic) || memcmp(c->line, magic, c->len) != 0))
        return fail(c, magic);
    return st;
}

/* s[0, len) up to the next space: the token, and the rest after the space. */
static int token(const char **s, size_t *len, const char **tok, size_t *tok_len)
{
    const char *sp = memchr(*s, ' ', *len);
    if (!sp)
        return 0;
    *tok = *s;
    *tok_len = (size_t)(sp - *s);
    *len -= *tok_len + 1;
    *s = sp + 1;
    return *tok_len > 0;
}

static int state_of(const char *t, size_t len, enum sw_slot_state *out)
{
    for (int i = 0; i < 4; i++)
        if (strlen(state_names[i]) == len && memcmp(t, state_names[i], len) == 0) {
            *out = (enum sw_slot_state)i;
            return 1;
        }
    return 0;
}

/* "slot A good 3 2842336 NAME": letter, state, version, size, the name. */
static sw_status slot_line(cursor *c, int index, sw_store_slot *out)
{
    const char *v, *t[4];
    size_t len, n[4];
    sw_status st = keyed(c, "slot", &v, &len);
    if (st != SW_OK)
        return st;
    int slot;
    for (int i = 0; i < 4; i++)
        if (!token(&v, &len, &t[i], &n[i]))
            return fail(c, "slot LETTER STATE VERSION SIZE NAME");
    if (!letter_slot(t[0], n[0], 0, &slot) || slot != index)
        return fail(c, index == 0 ? "slot A" : "slot B");
    if (!state_of(t[1], n[1], &out->state))
        return fail(c, "a slot state: empty, pending, good or bad");
    if (!parse_u64(t[2], n[2], &out->version) || !parse_u64(t[3], n[3], &out->size))
        return fail(c, "the slot's version and size as whole numbers");
    if (len >= SW_PACK_NAME_BYTES)
        return fail(c, "a pack name of at most 47 bytes");
    memcpy(out->name, v, len);
    out->name[len] = '\0';
    return SW_OK;
}

/* Beyond the syntax: the slots the state names must be in a state that
 * fits (active good, pending pending, not both the same slot). */
static sw_status check_state_meaning(cursor *c, const sw_store_state *s)
{
    if (s->active != SW_SLOT_NONE && s->slot[s->active].state != SW_SLOT_GOOD)
        return sw_error_set(c->err, SW_ERR_FORMAT, "%s: active slot %c is %s, expected good",
                            c->name, sw_slot_letter(s->active),
                            sw_slot_state_name(s->slot[s->active].state));
    if (s->pending != SW_SLOT_NONE &&
        (s->pending == s->active || s->slot[s->pending].state != SW_SLOT_PENDING))
        return sw_error_set(c->err, SW_ERR_FORMAT, "%s: pending slot %c is %s%s, expected "
                            "pending", c->name, sw_slot_letter(s->pending),
                            sw_slot_state_name(s->slot[s->pending].state),
                            s->pending == s->active ? " and active" : "");
    return SW_OK;
}

sw_status sw_store_state_parse(const char *text, size_t size, const char *name,
                               sw_store_state *out, sw_error *err)
{
    cursor c = { .text = text, .size = size, .name = name, .err = err };
    sw_store_state s = { 0 };
    uint64_t attempts;
    sw_status st = magic_line(&c, "seamwalk-store 1");
    if (st == SW_OK)
        st = keyed_u64(&c, "generation", UINT64_MAX, &s.generation);
    if (st == SW_OK)
        st = keyed_slot(&c, "active", 1, &s.active);
    if (st == SW_OK)
        st = keyed_slot(&c, "pending", 1, &s.pending);
    if (st == SW_OK && (st = keyed_u64(&c, "attempts", UINT32_MAX, &attempts)) == SW_OK)
        s.attempts = (uint32_t)attempts;
    for (int i = 0; i < 2 && st == SW_OK; i++)
        st = slot_line(&c, i, &s.slot[i]);
    if (st == SW_OK)
        st = check_line(&c);
    if (st == SW_OK)
        st = check_state_meaning(&c, &s);
    if (st == SW_OK)
        *out = s;
    return st;
}

sw_status sw_store_journal_parse(const char *text, size_t size, const char *name,
                                 sw_store_journal *out, sw_error *err)
{
    cursor c = { .text = text, .size = size, .name = name, .err = err };
    sw_store_journal j = { 0 };
    const char *v;
    size_t len;
    sw_status st = magic_line(&c, "seamwalk-journal 1");
    if (st == SW_OK)
        st = keyed_slot(&c, "slot", 0, &j.slot);
    if (st == SW_OK)
        st = keyed_u64(&c, "size", UINT64_MAX, &j.size);
    if (st == SW_OK && (st = keyed(&c, "digest", &v, &len)) == SW_OK) {
        int ok = len == 64;
        for (size_t i = 0; ok && i < 64; i++) {
            const char *hex = "0123456789abcdef", *d = memchr(hex, v[i], 16);
            ok = d != NULL && v[i] != '\0';
            if (ok)
                j.digest[i / 2] = (uint8_t)(i % 2 ? j.digest[i / 2] | (d - hex) : (d - hex) << 4);
        }
        if (!ok)
            st = fail(&c, "64 lower-case hex digits");
    }
    if (st == SW_OK)
        st = keyed_u64(&c, "done", j.size, &j.done);
    if (st == SW_OK)
        st = check_line(&c);
    if (st == SW_OK)
        *out = j;
    return st;
}
