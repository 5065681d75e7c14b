/* SPDX-License-Identifier: MIT */
/* Installing a pack into the store's inactive slot (sw_store_install.h).
 * Order of the steps, and why each is safe to be cut off by a power loss:
 *   1. check the pack in memory (nothing on disk changes if it is refused);
 *   2. if the target slot is still named in the state (an old good or
 *      pending pack), one state update marks it empty first, so no boot can
 *      pick a half-written slot;
 *   3. write chunks with pwrite + fdatasync, recording in the journal the
 *      bytes known to be on disk, so a new install of the same pack resumes;
 *   4. truncate, fsync, read the slot back and verify digest, checksums and
 *      signature;
 *   5. one state update makes the slot pending. Until then the unit boots
 *      the old pack; from then on, the new one. */
#include "sw_store_install.h"

#include <errno.h>
#include <fcntl.h>
#include <sodium.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "sw_pack.h"

static sw_status read_file(const char *path, uint8_t **out, size_t *size, sw_error *err)
{
    *out = NULL;
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    struct stat st;
    if (fd < 0 || fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        sw_status rc = sw_error_set(err, SW_ERR_IO, "%s: %s", path,
                                    fd < 0 ? strerror(errno) : "not a regular file");
        if (fd >= 0)
            close(fd);
        return rc;
    }
    size_t n = (size_t)st.st_size, got = 0;
    uint8_t *buf = malloc(n ? n : 1); /* malloc's 16-byte alignment meets the reader's 8 */
    ssize_t r = 1;
    while (buf && got < n && (r = read(fd, buf + got, n - got)) > 0)
        got += (size_t)r;
    int e = errno;
    close(fd);
    if (!buf || got != n) {
        free(buf);
        return sw_error_set(err, !buf ? SW_ERR_NO_MEMORY : SW_ERR_IO, "read %s: %s", path,
                            !buf ? "out of memory" : r < 0 ? strerror(e) : "file shrank");
    }
    *out = buf;
    *size = n;
    return SW_OK;
}

/* The signature first, over the raw bytes, so a pack from anyone else
 * reaches no section parser; then every checksum and index. */
sw_status sw_store_check_pack(const uint8_t *bytes, size_t size, const sw_trusted_keys *keys,
                              const sw_pack_signature **sig, enum sw_install_refusal *refusal,
                              sw_error *err)
{
    sw_pack pack;
    sw_pack_signature raw;
    sw_status st = sw_pack_check_signature_raw(bytes, size, keys, &raw, err);
    if (st != SW_OK) {
        /* sw_pack_signature_locate says "not signed" when the header and
         * table are sound but hold no SIGNATURE. */
        int unsigned_ = st == SW_ERR_FORMAT && err && !strncmp(err->message, "not signed", 10);
        *refusal = st == SW_ERR_ARG ? SW_INSTALL_UNTRUSTED
                   : st == SW_ERR_CHECKSUM ? SW_INSTALL_TAMPERED
                   : unsigned_ ? SW_INSTALL_UNSIGNED : SW_INSTALL_INVALID;
        return st;
    }
    *refusal = SW_INSTALL_INVALID;
    if ((st = sw_pack_open_memory(bytes, size, &pack, err)) != SW_OK ||
        (st = sw_pack_signature_find(&pack, sig, NULL, err)) != SW_OK)
        return st;
    *refusal = SW_INSTALL_ACCEPTED;
    return SW_OK;
}

static void digest_of(const uint8_t *bytes, size_t size, uint8_t out[32])
{
    crypto_generichash(out, 32, bytes, size, NULL, 0);
}

sw_status sw_store_verify_slot(const sw_store *s, int slot, const sw_store_slot *expect,
                               const sw_trusted_keys *keys, sw_error *err)
{
    char path[3200];
    sw_store_slot_path(s, slot, path, sizeof path);
    uint8_t *bytes;
    size_t size;
    const sw_pack_signature *sig;
    enum sw_install_refusal why;
    sw_status st = read_file(path, &bytes, &size, err);
    if (st == SW_OK && (st = sw_store_check_pack(bytes, size, keys, &sig, &why, err)) == SW_OK &&
        (size != expect->size || sig->pack_version != expect->version))
        st = sw_error_set(err, SW_ERR_FORMAT, "%llu bytes, version %llu; the state says %llu "
                          "bytes, version %llu", (unsigned long long)size,
                          (unsigned long long)sig->pack_version,
                          (unsigned long long)expect->size, (unsigned long long)expect->version);
    if (st != SW_OK)
        sw_error_prefix(err, "%s", path);
    free(bytes);
    return st;
}

/* The slot to write: never the active (good) one, and not a pending one
 * either when the other slot is free (a unit with no good pack yet keeps
 * its pending one until the new one is in). */
static int target_slot(const sw_store_state *st)
{
    if (st->active != SW_SLOT_NONE)
        return 1 - st->active;
    return st->pending != SW_SLOT_NONE ? 1 - st->pending : SW_SLOT_A;
}

typedef struct install {
    sw_store *store;
    const sw_install_options *o;
    const uint8_t *pack;
    size_t size;
    sw_store_state state;
    int slot;
    char path[3200];
    sw_store_journal journal;
} install;

/* Step 2 and the journal: empties the target in the state if it is named
 * there, and keeps the bytes of an interrupted install of the same pack. */
static sw_status prepare_slot(install *in, uint64_t *resumed_at, sw_error *err)
{
    sw_store_state *st = &in->state;
    sw_store_journal old;
    int present = 0;
    sw_error ignored = { 0 }; /* a damaged journal only means starting over */
    if (sw_store_read_journal(in->store, &old, &present, &ignored) != SW_OK)
        present = 0;
    struct stat fs;
    int resume = present && old.slot == in->slot && old.size == in->journal.size &&
                 memcmp(old.digest, in->journal.digest, 32) == 0 &&
                 st->slot[in->slot].state == SW_SLOT_EMPTY && st->pending != in->slot &&
                 stat(in->path, &fs) == 0 && (uint64_t)fs.st_size >= old.done;
    *resumed_at = resume ? old.done : 0;
    in->journal.done = *resumed_at;
    if (st->slot[in->slot].state != SW_SLOT_EMPTY || st->pending == in->slot) {
        st->slot[in->slot] = (sw_store_slot){ .state = SW_SLOT_EMPTY };
        if (st->pending == in->slot) {
            st->pending = SW_SLOT_NONE;
            st->attempts = 0;
        }
        sw_status rc = sw_store_write_state(in->store, st, err);
        if (rc != SW_OK)
            return rc;
    }
    return resume ? SW_OK : sw_store_write_journal(in->store, &in->journal, err);
}

static sw_status pwrite_all(int fd, const char *path, const uint8_t *bytes, size_t n,
                            uint64_t at, sw_error *err)
{
    while (n > 0) {
        ssize_t w = pwrite(fd, bytes, n, (off_t)at);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            return sw_error_set(err, SW_ERR_IO, "write %s at byte %llu: %s", path,
                                (unsigned long long)at, w < 0 ? strerror(errno) : "no progress");
        bytes += w;
        n -= (size_t)w;
        at += (uint64_t)w;
    }
    return SW_OK;
}

/* Step 3: each chunk is on disk (fdatasync) before the journal says so. */
static sw_status write_chunks(install *in, int fd, sw_error *err)
{
    size_t chunk = in->o->chunk_bytes ? in->o->chunk_bytes : 256u * 1024u;
    sw_store_journal *j = &in->journal;
    while (j->done < in->size) {
        size_t n = in->size - j->done < chunk ? (size_t)(in->size - j->done) : chunk;
        sw_status st = pwrite_all(fd, in->path, in->pack + j->done, n, j->done, err);
        if (st != SW_OK)
            return st;
        if (fdatasync(fd) != 0)
            return sw_error_set(err, SW_ERR_IO, "fdatasync %s: %s", in->path, strerror(errno));
        j->done += n;
        if ((st = sw_store_write_journal(in->store, j, err)) != SW_OK)
            return st;
        if (in->o->progress)
            in->o->progress(in->o->progress_user, j->done, in->size);
    }
    return SW_OK;
}

/* A new install goes into a new file: the old one is unlinked first, not
 * written over, since a walk may have it mapped (sw_pack_map_checked: a
 * unit on trial walks its pending slot, the one a new install replaces)
 * and must not see its bytes change; unlinked, its pages stay the walk's
 * until it ends. A resumed install continues its own new file, which no
 * walk has: the state names its slot empty. */
static sw_status write_slot(install *in, sw_error *err)
{
    if (in->journal.done == 0 && unlink(in->path) != 0 && errno != ENOENT)
        return sw_error_set(err, SW_ERR_IO, "unlink %s: %s", in->path, strerror(errno));
    int fd = open(in->path, O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0)
        return sw_error_set(err, SW_ERR_IO, "%s: %s", in->path, strerror(errno));
    sw_status st = write_chunks(in, fd, err);
    if (st == SW_OK && ftruncate(fd, (off_t)in->size) != 0)
        st = sw_error_set(err, SW_ERR_IO, "ftruncate %s: %s", in->path, strerror(errno));
    if (st == SW_OK && fsync(fd) != 0)
        st = sw_error_set(err, SW_ERR_IO, "fsync %s: %s", in->path, strerror(errno));
    if (st == SW_OK) /* so the read-back comes from the device, not our own cached pages */
        (void)posix_fadvise(fd, 0, 0, POSIX_FADV_DONTNEED);
    if (close(fd) != 0 && st == SW_OK)
        st = sw_error_set(err, SW_ERR_IO, "close %s: %s", in->path, strerror(errno));
    return st == SW_OK ? sw_store_sync_dir(in->store->dir, err) : st;
}

/* Step 4: what the unit will boot is the file, so read it again, whole,
 * through a new descriptor (its cached pages were dropped after the fsync,
 * where the kernel allows) and check it as a boot would. */
static sw_status read_back(install *in, sw_error *err)
{
    uint8_t *bytes, digest[32];
    size_t size;
    const sw_pack_signature *sig;
    enum sw_install_refusal why;
    sw_status st = read_file(in->path, &bytes, &size, err);
    if (st != SW_OK)
        return st;
    if (size == in->size)
        digest_of(bytes, size, digest);
    if (size != in->size || memcmp(digest, in->journal.digest, 32) != 0)
        st = sw_error_set(err, SW_ERR_CHECKSUM, "%s: read back %zu bytes that differ from the "
                          "%zu written", in->path, size, in->size);
    else if ((st = sw_store_check_pack(bytes, size, in->o->keys, &sig, &why, err)) != SW_OK)
        sw_error_prefix(err, "%s: read back", in->path);
    free(bytes);
    return st;
}

/* Step 1 on the pack and the state: refusals change nothing. */
static sw_status accept_pack(install *in, sw_install_report *r, sw_error *err)
{
    const sw_pack_signature *sig;
    sw_status st = sw_store_check_pack(in->pack, in->size, in->o->keys, &sig, &r->refusal, err);
    if (st != SW_OK)
        return st;
    r->version = sig->pack_version;
    memcpy(r->name, sig->name, sizeof r->name);
    const sw_store_state *state = &in->state;
    if (state->active != SW_SLOT_NONE && !in->o->allow_downgrade &&
        sig->pack_version < state->slot[state->active].version) {
        r->refusal = SW_INSTALL_OLDER;
        return sw_error_set(err, SW_ERR_RANGE, "pack '%s' is version %llu, older than the "
                            "active slot %c's version %llu (--allow-downgrade to install it)",
                            sig->name, (unsigned long long)sig->pack_version,
                            sw_slot_letter(state->active),
                            (unsigned long long)state->slot[state->active].version);
    }
    return SW_OK;
}

static sw_status run_install(install *in, sw_install_report *r, sw_error *err)
{
    sw_status st = sw_store_read_state(in->store, &in->state, err);
    if (st != SW_OK || (st = accept_pack(in, r, err)) != SW_OK)
        return st;
    in->slot = r->slot = target_slot(&in->state);
    sw_store_slot_path(in->store, in->slot, in->path, sizeof in->path);
    in->journal = (sw_store_journal){ .slot = in->slot, .size = in->size };
    digest_of(in->pack, in->size, in->journal.digest);
    if ((st = prepare_slot(in, &r->resumed_at, err)) != SW_OK ||
        (st = write_slot(in, err)) != SW_OK || (st = read_back(in, err)) != SW_OK)
        return st;
    sw_store_slot *slot = &in->state.slot[in->slot];
    *slot = (sw_store_slot){ SW_SLOT_PENDING, r->version, in->size, "" };
    memcpy(slot->name, r->name, sizeof slot->name);
    in->state.pending = in->slot;
    in->state.attempts = 0;
    if ((st = sw_store_write_state(in->store, &in->state, err)) != SW_OK)
        return st;
    /* The install is done once the state says so; a journal left behind is
     * ignored by the next install (its slot is no longer empty). */
    sw_error ignored = { 0 };
    (void)sw_store_remove_journal(in->store, &ignored);
    return SW_OK;
}

sw_status sw_store_install(sw_store *s, const uint8_t *pack, size_t size,
                           const sw_install_options *o, sw_install_report *report,
                           sw_error *err)
{
    *report = (sw_install_report){ .slot = SW_SLOT_NONE };
    if (!o->keys || o->keys->count == 0)
        return sw_error_set(err, SW_ERR_ARG, "no trusted keys: the unit accepts no pack");
    if (sodium_init() < 0)
        return sw_error_set(err, SW_ERR_UNSUPPORTED, "libsodium failed to initialise");
    sw_status st = sw_store_lock(s, 0, err);
    if (st != SW_OK)
        return st;
    install in = { .store = s, .o = o, .pack = pack, .size = size };
    st = run_install(&in, report, err);
    sw_store_unlock(s);
    return st;
}
