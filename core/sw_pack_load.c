/* SPDX-License-Identifier: MIT */
/* Reading a pack file: its header alone (to size the arena), or the whole
 * file, into the arena or mapped, and then the checks of sw_pack_read.c
 * (sw_pack_open_memory_with); the file I/O only. */
#define _DEFAULT_SOURCE /* MAP_POPULATE */
#include <errno.h>
#include <fcntl.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "sw_pack.h"
#include "sw_pack_validate.h"

/* read(2) until n bytes arrived; a short file is an error, not a retry. */
static sw_status read_exactly(int fd, void *buf, size_t n, sw_error *err)
{
    size_t got = 0;
    while (got < n) {
        ssize_t r = read(fd, (uint8_t *)buf + got, n - got);
        if (r < 0 && errno == EINTR)
            continue;
        if (r < 0)
            return sw_error_set(err, SW_ERR_IO, "read failed after %zu of %zu bytes: %s", got, n,
                                strerror(errno));
        if (r == 0)
            return sw_error_set(err, SW_ERR_IO, "file ended after %zu of %zu bytes", got, n);
        got += (size_t)r;
    }
    return SW_OK;
}

/* Opens path read-only and returns its size; a directory or device is refused
 * because its size says nothing about its contents. */
static sw_status open_regular(const char *path, int *fd_out, uint64_t *size, sw_error *err)
{
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return sw_error_set(err, SW_ERR_IO, "cannot open: %s", strerror(errno));
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        close(fd);
        return sw_error_set(err, SW_ERR_IO, "not a regular file");
    }
    *fd_out = fd;
    *size = (uint64_t)st.st_size;
    return SW_OK;
}

static sw_status read_header_fd(int fd, uint64_t file_size, sw_pack_header *out, sw_error *err)
{
    if (file_size < sizeof(sw_pack_header))
        return sw_error_set(err, SW_ERR_FORMAT, "header: the file is %llu bytes, a pack is at "
                            "least %zu", (unsigned long long)file_size, sizeof(sw_pack_header));
    sw_status s = read_exactly(fd, out, sizeof *out, err);
    if (s != SW_OK)
        return s;
    return sw_pack_check_header_identity(out, file_size, "file", err);
}

sw_status sw_pack_read_header(const char *path, sw_pack_header *out, sw_error *err)
{
    uint64_t file_size = 0;
    int fd = -1;
    sw_status s = open_regular(path, &fd, &file_size, err);
    if (s != SW_OK) {
        sw_error_prefix(err, "%s", path);
        return s;
    }
    s = read_header_fd(fd, file_size, out, err);
    close(fd);
    if (s != SW_OK)
        sw_error_prefix(err, "%s", path);
    return s;
}

typedef struct raw_check {
    sw_pack_raw_check fn;
    void *user;
} raw_check;

static sw_status load_fd(int fd, uint64_t file_size, sw_arena *arena,
                         const sw_parts_runner *runner, const raw_check *check, sw_pack *out,
                         sw_error *err)
{
    uint8_t *buf = file_size <= SIZE_MAX ? sw_arena_alloc(arena, (size_t)file_size, 64) : NULL;
    if (!buf)
        return sw_error_set(err, SW_ERR_NO_MEMORY,
                            "the pack is %llu bytes, the arena has %zu of %zu bytes free",
                            (unsigned long long)file_size, arena->size - arena->used,
                            arena->size);
    sw_status s = read_exactly(fd, buf, (size_t)file_size, err);
    if (s == SW_OK && check->fn)
        s = check->fn(check->user, buf, (size_t)file_size, err);
    if (s != SW_OK)
        return s;
    return sw_pack_open_memory_with(buf, (size_t)file_size, runner, out, err);
}

sw_status sw_pack_load(const char *path, sw_arena *arena, sw_pack *out, sw_error *err)
{
    return sw_pack_load_with(path, arena, NULL, out, err);
}

sw_status sw_pack_load_with(const char *path, sw_arena *arena, const sw_parts_runner *runner,
                            sw_pack *out, sw_error *err)
{
    return sw_pack_load_checked(path, arena, runner, NULL, NULL, out, err);
}

sw_status sw_pack_load_checked(const char *path, sw_arena *arena, const sw_parts_runner *runner,
                               sw_pack_raw_check check_fn, void *user, sw_pack *out,
                               sw_error *err)
{
    const raw_check check = { check_fn, user };
    uint64_t file_size = 0;
    int fd = -1;
    sw_status s = open_regular(path, &fd, &file_size, err);
    if (s != SW_OK) {
        sw_error_prefix(err, "%s", path);
        return s;
    }
    /* A failed load gives its bytes back, so the caller can try another pack. */
    size_t mark = sw_arena_mark(arena);
    s = load_fd(fd, file_size, arena, runner, &check, out, err);
    close(fd);
    if (s != SW_OK) {
        sw_arena_reset_to(arena, mark);
        sw_error_prefix(err, "%s", path);
    }
    return s;
}

/* Only root can change it (sw_pack_file_mappable). */
static int mappable(const struct stat *st)
{
    return S_ISREG(st->st_mode) && st->st_uid == 0 && (st->st_mode & (S_IWGRP | S_IWOTH)) == 0;
}

int sw_pack_file_mappable(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && mappable(&st);
}

/* The open file mapped, checked and validated; map filled on success. */
static sw_status map_fd(int fd, const sw_parts_runner *runner, const raw_check *check,
                        sw_pack_mapping *map, sw_pack *out, sw_error *err)
{
    struct stat st;
    if (fstat(fd, &st) != 0)
        return sw_error_set(err, SW_ERR_IO, "cannot stat: %s", strerror(errno));
    if (!mappable(&st))
        return sw_error_set(err, SW_ERR_IO, "no longer a file only root can write (owner %u, "
                            "mode %04o): changed while the walk started",
                            (unsigned)st.st_uid, (unsigned)(st.st_mode & 07777));
    uint64_t file_size = (uint64_t)st.st_size;
    if (file_size < sizeof(sw_pack_header) || file_size > SIZE_MAX)
        return sw_error_set(err, SW_ERR_FORMAT, "header: the file is %llu bytes, a pack is at "
                            "least %zu", (unsigned long long)file_size, sizeof(sw_pack_header));
    /* Populated at once: the checks read every byte, in order. */
    void *base = mmap(NULL, (size_t)file_size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
    if (base == MAP_FAILED)
        return sw_error_set(err, SW_ERR_IO, "cannot map %llu bytes: %s",
                            (unsigned long long)file_size, strerror(errno));
    sw_status s = check->fn ? check->fn(check->user, base, (size_t)file_size, err) : SW_OK;
    if (s == SW_OK)
        s = sw_pack_open_memory_with(base, (size_t)file_size, runner, out, err);
    if (s != SW_OK) {
        munmap(base, (size_t)file_size);
        return s;
    }
    *map = (sw_pack_mapping){ base, (size_t)file_size };
    return SW_OK;
}

sw_status sw_pack_map_checked(const char *path, const sw_parts_runner *runner,
                              sw_pack_raw_check check_fn, void *user, sw_pack_mapping *map,
                              sw_pack *out, sw_error *err)
{
    const raw_check check = { check_fn, user };
    *map = (sw_pack_mapping){ NULL, 0 };
    uint64_t file_size = 0;
    int fd = -1;
    sw_status s = open_regular(path, &fd, &file_size, err);
    if (s == SW_OK) {
        s = map_fd(fd, runner, &check, map, out, err);
        close(fd);   /* the mapping keeps the file */
    }
    if (s != SW_OK)
        sw_error_prefix(err, "%s", path);
    return s;
}

void sw_pack_unmap(sw_pack_mapping *map)
{
    if (map->base)
        munmap(map->base, map->size);
    *map = (sw_pack_mapping){ NULL, 0 };
}
