/* SPDX-License-Identifier: MIT */
/* An LD_PRELOAD shim for the pack store's tests: counts the calls that
 * change files (write and pwrite on descriptors above 2, fsync, fdatasync,
 * ftruncate, rename, unlink) and, as the environment asks,
 *   SW_FAULT_KILL_AT=N        raises SIGKILL just before the Nth such call
 *                             (a power cut at that point, for the program)
 *   SW_FAULT_FAIL=OP:N[:ERR]  makes the Nth call of OP (write, fsync,
 *                             rename, ...; write counts pwrite, fsync
 *                             counts fdatasync) fail
 *                             with errno ERR (EIO, ENOSPC; default EIO)
 *   SW_FAULT_FULL_AFTER=B     a disk that fills after B bytes: writes past
 *                             them are cut short, then fail with ENOSPC
 *   SW_FAULT_COUNT_FILE=PATH  writes the number of calls to PATH at exit.
 * Every call is counted whether or not it is faulted. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <unistd.h>

static long calls, kill_at = -1, fail_at = -1, op_calls;
static char fail_op[16];
static int fail_errno = EIO;
static long long full_after = -1, written;

static void __attribute__((constructor)) read_env(void)
{
    const char *k = getenv("SW_FAULT_KILL_AT"), *f = getenv("SW_FAULT_FAIL");
    const char *full = getenv("SW_FAULT_FULL_AFTER");
    if (k)
        kill_at = atol(k);
    if (full)
        full_after = atoll(full);
    if (f) {
        const char *colon = strchr(f, ':');
        size_t n = colon ? (size_t)(colon - f) : 0;
        if (n > 0 && n < sizeof fail_op) {
            memcpy(fail_op, f, n);
            fail_at = atol(colon + 1);
            const char *e = strchr(colon + 1, ':');
            if (e && strcmp(e + 1, "ENOSPC") == 0)
                fail_errno = ENOSPC;
        }
    }
}

static void __attribute__((destructor)) write_count(void)
{
    const char *path = getenv("SW_FAULT_COUNT_FILE");
    if (!path)
        return;
    FILE *f = fopen(path, "w"); /* stdio's own writes do not come through our write() */
    if (f) {
        fprintf(f, "%ld\n", calls);
        fclose(f);
    }
}

/* 0: go on; -1: fail this call with errno set. */
static int intercept(const char *op)
{
    calls++;
    if (kill_at > 0 && calls == kill_at)
        raise(SIGKILL);
    if (fail_at > 0 && strcmp(op, fail_op) == 0 && ++op_calls == fail_at) {
        errno = fail_errno;
        return -1;
    }
    return 0;
}

#define NEXT(name) ((__typeof__(&name))dlsym(RTLD_NEXT, #name))

/* A full disk: how much of n still fits; 0 means ENOSPC now. */
static size_t room(size_t n)
{
    if (full_after < 0)
        return n;
    long long left = full_after - written;
    return left <= 0 ? 0 : (size_t)left < n ? (size_t)left : n;
}

ssize_t write(int fd, const void *buf, size_t n)
{
    if (fd > 2 && intercept("write") != 0)
        return -1;
    size_t fits = fd > 2 ? room(n) : n;
    if (n > 0 && fits == 0) {
        errno = ENOSPC;
        return -1;
    }
    ssize_t w = NEXT(write)(fd, buf, fits);
    if (fd > 2 && w > 0)
        written += w;
    return w;
}

static ssize_t do_pwrite(int fd, const void *buf, size_t n, off_t at)
{
    if (intercept("write") != 0)
        return -1;
    size_t fits = room(n);
    if (n > 0 && fits == 0) {
        errno = ENOSPC;
        return -1;
    }
    ssize_t w = NEXT(pwrite)(fd, buf, fits, at);
    if (w > 0)
        written += w;
    return w;
}

ssize_t pwrite(int fd, const void *buf, size_t n, off_t at) { return do_pwrite(fd, buf, n, at); }
ssize_t pwrite64(int fd, const void *buf, size_t n, off_t at) { return do_pwrite(fd, buf, n, at); }

int fsync(int fd) { return intercept("fsync") ? -1 : NEXT(fsync)(fd); }
int fdatasync(int fd) { return intercept("fsync") ? -1 : NEXT(fdatasync)(fd); }
int ftruncate(int fd, off_t n) { return intercept("ftruncate") ? -1 : NEXT(ftruncate)(fd, n); }
int ftruncate64(int fd, off_t n) { return intercept("ftruncate") ? -1 : NEXT(ftruncate)(fd, n); }
int rename(const char *a, const char *b) { return intercept("rename") ? -1 : NEXT(rename)(a, b); }
int unlink(const char *p) { return intercept("unlink") ? -1 : NEXT(unlink)(p); }
