/* SPDX-License-Identifier: MIT */
#define _DEFAULT_SOURCE /* realpath */
/* The pack store's files and its state changes (sw_pack_store.h). Nothing
 * here allocates: the runtime calls sw_store_mark_good between frames (only
 * the trusted keys' realpath, at start, may allocate inside libc). */
#include "sw_pack_store.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

void sw_store_path(const sw_store *s, const char *file, char *out, size_t cap)
{
    snprintf(out, cap, "%s/%s", s->dir, file);
}

void sw_store_slot_path(const sw_store *s, int slot, char *out, size_t cap)
{
    snprintf(out, cap, "%s/slot-%c.swpack", s->dir, slot == SW_SLOT_B ? 'b' : 'a');
}

sw_status sw_store_open(sw_store *s, const char *dir, sw_error *err)
{
    s->lock_fd = -1;
    if (strlen(dir) >= sizeof s->dir - 32)
        return sw_error_set(err, SW_ERR_ARG, "%s: store path too long", dir);
    snprintf(s->dir, sizeof s->dir, "%s", dir);
    if (mkdir(dir, 0755) != 0 && errno != EEXIST)
        return sw_error_set(err, SW_ERR_IO, "%s: cannot create the store: %s", dir,
                            strerror(errno));
    struct stat st;
    if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode))
        return sw_error_set(err, SW_ERR_IO, "%s: not a directory", dir);
    return SW_OK;
}

sw_status sw_store_lock(sw_store *s, int wait, sw_error *err)
{
    char path[3200];
    sw_store_path(s, "lock", path, sizeof path);
    int fd = open(path, O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0 && (errno == EACCES || errno == EROFS || errno == EPERM))
        fd = open(path, O_RDONLY | O_CLOEXEC); /* a lock left by root, a read-only store */
    if (fd < 0)
        return sw_error_set(err, SW_ERR_IO, "%s: cannot open the lock: %s", path,
                            strerror(errno));
    if (flock(fd, LOCK_EX | (wait ? 0 : LOCK_NB)) != 0) {
        int e = errno;
        close(fd);
        if (e == EWOULDBLOCK)
            return sw_error_set(err, SW_ERR_UNSUPPORTED, "%s: busy: another seamwalk-flash or "
                                "seamwalk holds the store's lock", s->dir);
        return sw_error_set(err, SW_ERR_IO, "%s: flock: %s", path, strerror(e));
    }
    s->lock_fd = fd;
    return SW_OK;
}

void sw_store_unlock(sw_store *s)
{
    if (s->lock_fd >= 0)
        close(s->lock_fd); /* closing the only descriptor releases the flock */
    s->lock_fd = -1;
}

sw_status sw_store_sync_dir(const char *dir, sw_error *err)
{
    int fd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0)
        return sw_error_set(err, SW_ERR_IO, "%s: %s", dir, strerror(errno));
    int rc = fsync(fd);
    int e = errno;
    close(fd);
    return rc == 0 ? SW_OK : sw_error_set(err, SW_ERR_IO, "fsync %s: %s", dir, strerror(e));
}

static sw_status write_all(int fd, const char *path, const char *bytes, size_t size,
                           sw_error *err)
{
    while (size > 0) {
        ssize_t n = write(fd, bytes, size);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return sw_error_set(err, SW_ERR_IO, "write %s: %s", path,
                                n < 0 ? strerror(errno) : "wrote nothing");
        bytes += n;
        size -= (size_t)n;
    }
    return SW_OK;
}

/* The directory part of path, for the fsync after a rename. */
static void dir_of(const char *path, char *out, size_t cap)
{
    const char *slash = strrchr(path, '/');
    size_t n = slash ? (size_t)(slash - path) : 0;
    if (n == 0 || n >= cap)
        snprintf(out, cap, "%s", slash == path ? "/" : ".");
    else
        snprintf(out, cap, "%.*s", (int)n, path);
}

/* bytes into tmp, fsynced. A temp file left by another user (root's
 * install cut off) is removed first when it cannot be opened. */
static sw_status write_temp(const char *tmp, const char *bytes, size_t size, sw_error *err)
{
    int fd = open(tmp, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    int e = errno;
    if (fd < 0 && e == EACCES && unlink(tmp) == 0) {
        fd = open(tmp, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
        e = errno;
    }
    if (fd < 0)
        return sw_error_set(err, SW_ERR_IO, "%s: %s", tmp, strerror(e));
    sw_status st = write_all(fd, tmp, bytes, size, err);
    if (st == SW_OK && fsync(fd) != 0)
        st = sw_error_set(err, SW_ERR_IO, "fsync %s: %s", tmp, strerror(errno));
    if (close(fd) != 0 && st == SW_OK)
        st = sw_error_set(err, SW_ERR_IO, "close %s: %s", tmp, strerror(errno));
    return st;
}

sw_status sw_store_write_atomic(const char *path, const char *bytes, size_t size, sw_error *err)
{
    char tmp[3300], dir[3200];
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    sw_status st = write_temp(tmp, bytes, size, err);
    if (st == SW_OK && rename(tmp, path) != 0)
        st = sw_error_set(err, SW_ERR_IO, "rename %s to %s: %s", tmp, path, strerror(errno));
    if (st != SW_OK) {
        unlink(tmp);
        return st;
    }
    dir_of(path, dir, sizeof dir);
    return sw_store_sync_dir(dir, err);
}

/* A small file into buf; *present 0 when it does not exist. */
static sw_status read_small(const char *path, char *buf, size_t cap, size_t *size, int *present,
                            sw_error *err)
{
    *present = 0;
    *size = 0;
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return errno == ENOENT ? SW_OK : sw_error_set(err, SW_ERR_IO, "%s: %s", path,
                                                      strerror(errno));
    *present = 1;
    ssize_t n;
    while ((n = read(fd, buf + *size, cap - *size)) > 0 && *size + (size_t)n < cap)
        *size += (size_t)n;
    int e = errno;
    close(fd);
    if (n < 0)
        return sw_error_set(err, SW_ERR_IO, "read %s: %s", path, strerror(e));
    if (n > 0)
        return sw_error_set(err, SW_ERR_FORMAT, "%s: more than %zu bytes, not a store file",
                            path, cap - 1);
    return SW_OK;
}

const char *const sw_state_copy_names[SW_STATE_COPIES] = { "state", "state.copy" };

/* One copy: 1 valid, 0 damaged or unreadable (why in copies), -1 missing. */
static int read_copy(const sw_store *s, int i, sw_store_state *out, sw_state_copies *c)
{
    char path[3200], text[SW_STORE_TEXT_MAX];
    size_t size;
    int present;
    sw_error e = { 0 };
    sw_store_path(s, sw_state_copy_names[i], path, sizeof path);
    sw_status st = read_small(path, text, sizeof text, &size, &present, &e);
    if (st == SW_OK && !present) {
        c->missing[i] = 1;
        snprintf(c->why[i], sizeof c->why[i], "%.380s: missing", path);
        return -1;
    }
    if (st == SW_OK && size == 0)
        st = sw_error_set(&e, SW_ERR_FORMAT, "%s: empty (0 bytes), expected the store state",
                          path);
    if (st == SW_OK)
        st = sw_store_state_parse(text, size, path, out, &e);
    if (st != SW_OK) {
        snprintf(c->why[i], sizeof c->why[i], "%.399s", e.message);
        return 0;
    }
    c->valid[i] = 1;
    c->generation[i] = out->generation;
    return 1;
}

/* A slot file that no state names and no install is writing: the state
 * was lost, so this is not an empty store. */
static int orphan_slot_file(const sw_store *s)
{
    sw_store_journal j;
    int journal = 0;
    sw_error ignored = { 0 };
    if (sw_store_read_journal(s, &j, &journal, &ignored) != SW_OK)
        journal = 0;
    char path[3200];
    for (int i = 0; i < 2; i++) {
        sw_store_slot_path(s, i, path, sizeof path);
        if (!(journal && j.slot == i) && access(path, F_OK) == 0)
            return 1;
    }
    return 0;
}

sw_status sw_store_read_state_copies(const sw_store *s, sw_store_state *out,
                                     sw_state_copies *copies, sw_error *err)
{
    sw_state_copies local;
    sw_state_copies *c = copies ? copies : &local;
    sw_store_state st[SW_STATE_COPIES];
    *c = (sw_state_copies){ .used = -1 };
    for (int i = 0; i < SW_STATE_COPIES; i++)
        if (read_copy(s, i, &st[i], c) == 1 &&
            (c->used < 0 || st[i].generation > st[c->used].generation))
            c->used = i;
    if (c->used >= 0) {
        *out = st[c->used];
        return SW_OK;
    }
    if (c->missing[0] && c->missing[1] && !orphan_slot_file(s)) {
        *out = (sw_store_state){ .active = SW_SLOT_NONE, .pending = SW_SLOT_NONE };
        return SW_OK;
    }
    if (c->missing[0] && c->missing[1])
        return sw_error_set(err, SW_ERR_FORMAT, "%s: no state file beside the slot files "
                            "(seamwalk-flash repair rebuilds it from the slots)", s->dir);
    return sw_error_set(err, SW_ERR_CHECKSUM, "no valid store state (seamwalk-flash repair "
                        "rebuilds it from the slots): %s; %s", c->why[0],
                        c->why[1]);
}

sw_status sw_store_read_state(const sw_store *s, sw_store_state *out, sw_error *err)
{
    return sw_store_read_state_copies(s, out, NULL, err);
}

sw_status sw_store_write_state(const sw_store *s, sw_store_state *state, sw_error *err)
{
    char path[3200], text[SW_STORE_TEXT_MAX];
    state->generation++;
    size_t n = sw_store_state_format(state, text, sizeof text);
    if (n == 0)
        return sw_error_set(err, SW_ERR_RANGE, "the store state does not fit %d bytes",
                            SW_STORE_TEXT_MAX);
    /* One copy after the other: a power cut leaves at most one of them
     * old, never both changed half-way. */
    for (int i = 0; i < SW_STATE_COPIES; i++) {
        sw_store_path(s, sw_state_copy_names[i], path, sizeof path);
        sw_status st = sw_store_write_atomic(path, text, n, err);
        if (st != SW_OK)
            return st;
    }
    return SW_OK;
}

sw_status sw_store_probe_state_write(const sw_store *s, const sw_store_state *state,
                                     sw_error *err)
{
    char tmp[3200], text[SW_STORE_TEXT_MAX];
    sw_store_state next = *state;
    next.generation++;
    size_t n = sw_store_state_format(&next, text, sizeof text);
    if (n == 0)
        return sw_error_set(err, SW_ERR_RANGE, "the store state does not fit %d bytes",
                            SW_STORE_TEXT_MAX);
    sw_store_path(s, "state.tmp", tmp, sizeof tmp);
    sw_status st = write_temp(tmp, text, n, err);
    unlink(tmp);
    return st;
}

sw_status sw_store_read_journal(const sw_store *s, sw_store_journal *out, int *present,
                                sw_error *err)
{
    char path[3200], text[SW_STORE_TEXT_MAX];
    size_t size;
    sw_store_path(s, "journal", path, sizeof path);
    sw_status st = read_small(path, text, sizeof text, &size, present, err);
    if (st == SW_OK && *present)
        st = sw_store_journal_parse(text, size, path, out, err);
    return st;
}

sw_status sw_store_write_journal(const sw_store *s, const sw_store_journal *j, sw_error *err)
{
    char path[3200], text[SW_STORE_TEXT_MAX];
    size_t n = sw_store_journal_format(j, text, sizeof text);
    sw_store_path(s, "journal", path, sizeof path);
    return sw_store_write_atomic(path, text, n, err);
}

sw_status sw_store_remove_journal(const sw_store *s, sw_error *err)
{
    char path[3200];
    sw_store_path(s, "journal", path, sizeof path);
    if (unlink(path) != 0 && errno != ENOENT)
        return sw_error_set(err, SW_ERR_IO, "unlink %s: %s", path, strerror(errno));
    return sw_store_sync_dir(s->dir, err);
}

sw_status sw_store_read_keys(const char *path, sw_trusted_keys *keys, sw_error *err)
{
    char text[16384];
    size_t size;
    int present;
    *keys = (sw_trusted_keys){ 0 };
    sw_status st = read_small(path, text, sizeof text, &size, &present, err);
    if (st == SW_OK && !present)
        st = sw_error_set(err, SW_ERR_IO, "%s: No such file: the unit's trusted keys", path);
    if (st == SW_OK)
        st = sw_trusted_keys_parse(text, size, path, keys, err);
    if (st == SW_OK && keys->count == 0)
        st = sw_error_set(err, SW_ERR_FORMAT, "%s: no trusted keys in the file", path);
    return st;
}

sw_status sw_store_peek_slot(const sw_store *s, int slot, sw_store_slot *out, sw_error *err)
{
    char path[3200];
    static const size_t head_cap = 64 + 32 * SW_PACK_MAX_SECTIONS;
    uint8_t head[64 + 32 * SW_PACK_MAX_SECTIONS];
    *out = (sw_store_slot){ .state = SW_SLOT_EMPTY };
    sw_store_slot_path(s, slot, path, sizeof path);
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    struct stat fs;
    if (fd < 0 || fstat(fd, &fs) != 0) {
        sw_status rc = sw_error_set(err, SW_ERR_IO, "%s: %s", path, strerror(errno));
        if (fd >= 0)
            close(fd);
        return rc;
    }
    uint64_t size = (uint64_t)fs.st_size, offset = 0;
    ssize_t got = pread(fd, head, size < head_cap ? (size_t)size : head_cap, 0);
    uint32_t index;
    sw_pack_signature sig;
    sw_status st = got < 0 ? sw_error_set(err, SW_ERR_IO, "read: %s", strerror(errno))
                           : sw_pack_signature_locate(head, (size_t)got, size, &index, &offset,
                                                      NULL, err);
    if (st == SW_OK && pread(fd, &sig, sizeof sig, (off_t)offset) != (ssize_t)sizeof sig)
        st = sw_error_set(err, SW_ERR_IO, "cannot read the SIGNATURE record");
    if (st == SW_OK)
        st = sw_pack_signature_record_check(&sig, err);
    close(fd);
    if (st != SW_OK) {
        sw_error_prefix(err, "%s", path);
        return st;
    }
    *out = (sw_store_slot){ SW_SLOT_GOOD, sig.pack_version, size, "" };
    memcpy(out->name, sig.name, sizeof out->name);
    return SW_OK;
}

/* One path component of the trust anchor: root's, and no one else may write. */
static sw_status root_only(const char *path, const struct stat *st, const char *what,
                           sw_error *err)
{
    /* A link's own mode means nothing (always 0777); its owner and its
     * directory decide who can change it. In a sticky directory of root's
     * (/tmp) no one else can rename or remove root's entries, and each
     * entry on the way is checked in turn. */
    int sticky_dir = S_ISDIR(st->st_mode) && (st->st_mode & S_ISVTX);
    if (st->st_uid == 0 && (S_ISLNK(st->st_mode) || sticky_dir ||
                            !(st->st_mode & (S_IWGRP | S_IWOTH))))
        return SW_OK;
    return sw_error_set(err, SW_ERR_ARG, "%s: %s is owned by uid %u with mode %04o; trusted "
                        "keys must be owned by root and writable by no one else, in "
                        "directories the same (chown root:root, chmod go-w; firmware/store/STORE.md "
                        "\"Trusted keys\")", path, what, (unsigned)st->st_uid,
                        (unsigned)(st->st_mode & 07777));
}

/* path (absolute) and every directory above it: root's alone. The last
 * component is not followed when it is a link (lstat), so a link to the
 * keys must be root's too; the directories are followed. */
static sw_status root_only_chain(const char *path, sw_error *err)
{
    char dir[4096];
    struct stat st;
    if (lstat(path, &st) != 0)
        return sw_error_set(err, SW_ERR_IO, "%s: %s: the unit's trusted keys", path,
                            strerror(errno));
    sw_status rc = root_only(path, &st, S_ISLNK(st.st_mode) ? "a link to the trusted keys"
                                                            : "the trusted keys file", err);
    snprintf(dir, sizeof dir, "%s", path);
    for (char *slash = strrchr(dir, '/'); rc == SW_OK && slash; slash = strrchr(dir, '/')) {
        slash[slash == dir] = '\0'; /* keep "/" itself */
        if (stat(dir, &st) != 0)
            return sw_error_set(err, SW_ERR_IO, "%s: %s", dir, strerror(errno));
        rc = root_only(dir, &st, "a directory above the trusted keys", err);
        if (slash == dir)
            break;
    }
    return rc;
}

sw_status sw_store_read_trusted_keys(const char *path, sw_trusted_keys *keys, sw_error *err)
{
    char given[4096], real[4096], cwd[4096];
    *keys = (sw_trusted_keys){ 0 };
    if (path[0] == '/')
        snprintf(given, sizeof given, "%s", path);
    else if (getcwd(cwd, sizeof cwd))
        snprintf(given, sizeof given, "%.2000s/%.2000s", cwd, path);
    else
        return sw_error_set(err, SW_ERR_IO, "getcwd: %s", strerror(errno));
    /* The path as named (whoever can change a link on it can change the
     * keys), then the file it resolves to. */
    sw_status rc = root_only_chain(given, err);
    if (rc == SW_OK && !realpath(given, real))
        rc = sw_error_set(err, SW_ERR_IO, "%s: %s: the unit's trusted keys", path,
                          strerror(errno));
    if (rc == SW_OK)
        rc = root_only_chain(real, err);
    return rc == SW_OK ? sw_store_read_keys(real, keys, err) : rc;
}
