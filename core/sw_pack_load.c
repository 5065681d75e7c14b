/* SPDX-License-Identifier: MIT */
/* Reading a pack file: its header alone (to size the arena), or the whole
 * file into the arena and then the checks of sw_pack_read.c
 * (sw_pack_open_memory_with); the file I/O only. */
#include <errno.h>
#include <fcntl.h>
#include <string.h>
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
