/* SPDX-License-Identifier: MIT */
/* PNG output through stb_image_write with its allocations served by an arena.
 *
 * stb takes its allocator as macros, not as a parameter, so the arena is passed
 * through a file-static pointer that is set for the duration of one
 * sw_png_write call: one writer at a time, process-wide (the header says so).
 *
 * stb does not survive an allocation failure: stbiw__sbgrowf only asserts its
 * realloc result and then writes through the old (or NULL) pointer. So
 * sw_png_write checks the arena's free space against sw_png_scratch_bytes
 * before it calls stb at all, and that bound is derived below from stb's code.
 * As a backstop against a wrong bound, a failed allocation longjmps out of stb
 * (its frames own nothing but arena memory, which the reset gives back) and
 * the call fails with SW_ERR_NO_MEMORY instead of corrupting memory. */
#include "sw_png.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <setjmp.h>
#include <stdalign.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

/* Every stb block gets the alignment malloc would give it. */
#define PNG_ALIGN alignof(max_align_t)

static sw_arena *png_arena;   /* set only inside sw_png_write */
static jmp_buf png_out_of_memory;

static void *png_alloc(size_t size)
{
    void *p = sw_arena_alloc(png_arena, size, PNG_ALIGN);
    if (!p)
        longjmp(png_out_of_memory, 1);
    return p;
}

static void *png_realloc(void *ptr, size_t old_size, size_t new_size)
{
    void *p = sw_arena_realloc(png_arena, ptr, old_size, new_size, PNG_ALIGN);
    if (!p)
        longjmp(png_out_of_memory, 1);
    return p;
}

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC   /* nobody else can change the compression level */
#define STBIW_MALLOC(size) png_alloc(size)
#define STBIW_REALLOC_SIZED(ptr, old_size, new_size) png_realloc(ptr, old_size, new_size)
#define STBIW_FREE(ptr) ((void)(ptr))   /* given back by sw_arena_reset_to */
#include <stb_image_write.h>

/* Constants of stb_image_write 1.16's PNG path (lines cited from Debian's copy). */
enum {
    STB_ZHASH = 16384,      /* stbiw__ZHASH: buckets of the match hash table */
    STB_QUALITY = 8,        /* stbi_write_png_compression_level default; STATIC keeps it */
    STB_SB_HEADER = 2 * sizeof(int), /* stretchy-buffer header: capacity and count */
    STB_PNG_CHUNKS = 8 + 12 + 13 + 12 + 12, /* signature, IHDR, IDAT and IEND framing */
};

/* Bytes a stretchy buffer of item_size items takes in total, every growth a
 * fresh arena block (the worst case: growing in place, when the buffer is the
 * most recent allocation, takes less), until its capacity exceeds max_count.
 * stbiw__sbgrowf's capacities run m0 = 2, then m' = 2m + 1, and it grows on
 * a push when count + 1 >= m, so the last capacity is the first m > max_count. */
static size_t stretchy_bytes(size_t max_count, size_t item_size)
{
    size_t total = 0;
    for (size_t m = 2;; m = 2 * m + 1) {
        total += sw_arena_worst_case(m * item_size + STB_SB_HEADER, PNG_ALIGN);
        if (m > max_count)
            return total;
    }
}

/* The worst-case scratch of stbi_write_png_to_mem for an image of
 * L = (width * channels + 1) * height filtered bytes. Every STBIW_FREE is a
 * no-op here, so the bound is the sum of every allocation stb makes:
 *   1. filt, the filtered rows: L bytes.
 *   2. line_buffer, one row: width * channels bytes.
 *   3. stbi_zlib_compress's hash_table: STB_ZHASH pointers.
 *   4. the hash chains, stretchy arrays of pointers. A chain's count is cut
 *      from 2Q to Q before each push (Q = quality), so it never exceeds 2Q and
 *      takes at most stretchy_bytes(2Q, 8) (capacities 2, 5, 11, 23). Each
 *      chain also takes at least one push per block it owns, and there is one
 *      push per input position (< L), so the chains together take at most
 *      min(STB_ZHASH * stretchy_bytes(2Q), L * (worst bytes per push)); the
 *      worst ratio of bytes to pushes is the chain of 2 pushes (two blocks).
 *   5. out, the compressed stream (stretchy, 1-byte items). Fixed Huffman
 *      codes spend at most 9 bits per literal byte, and a match of length
 *      len >= 3 at most 7 + 5 + 5 + 13 bits, which is <= 9 * len bits (25 bits
 *      for 3 bytes is the tightest), so the stream is at most
 *      2 + ceil((3 + 9L + 7) / 8) bytes (zlib header, block header, end code,
 *      padding); the stored-block fallback only runs when it is shorter, and
 *      the Adler-32 adds 4. Its blocks then sum as in stretchy_bytes.
 *   6. the PNG file image: zlen + STB_PNG_CHUNKS, zlen bounded as in 5.
 * Each block may lose PNG_ALIGN - 1 bytes to alignment (counted per block). */
size_t sw_png_scratch_bytes(int width, int height, int channels)
{
    if (width < 1 || height < 1 || channels < 1 || channels > 4)
        return 0;
    size_t row = (size_t)width * (size_t)channels;
    size_t filtered = (row + 1) * (size_t)height;
    size_t zlib_max = 2 + (3 + 9 * filtered + 7 + 7) / 8 + 4;
    size_t chain_full = stretchy_bytes(2 * STB_QUALITY, sizeof(void *));
    size_t per_push = stretchy_bytes(2, sizeof(void *)) / 2;   /* blocks of 2 and 5 */
    size_t chains = STB_ZHASH * chain_full;
    if (filtered * per_push < chains)
        chains = filtered * per_push;
    return sw_arena_worst_case(filtered, PNG_ALIGN) + sw_arena_worst_case(row, PNG_ALIGN) +
           sw_arena_worst_case(STB_ZHASH * sizeof(void *), PNG_ALIGN) + chains +
           stretchy_bytes(zlib_max, 1) + sw_arena_worst_case(zlib_max + STB_PNG_CHUNKS, PNG_ALIGN);
}

static sw_status check_args(const char *path, int width, int height, int channels,
                            const uint8_t *pixels, size_t stride, sw_error *err)
{
    if (!path || !pixels || width < 1 || height < 1 || channels < 1 || channels > 4)
        return sw_error_set(err, SW_ERR_ARG, "png %s: need pixels, size >= 1x1 and 1..4 "
                            "channels (got %dx%d, %d channels)",
                            path ? path : "(null path)", width, height, channels);
    /* stb counts bytes in int, and its output buffer's capacity reaches about
     * 2.3 times the filtered size: keep that far from INT_MAX. */
    size_t row = (size_t)width * (size_t)channels;
    if ((row + 1) * (size_t)height > (size_t)INT_MAX / 4 || stride > (size_t)INT_MAX)
        return sw_error_set(err, SW_ERR_ARG, "png %s: %dx%d x %d is too large for stb",
                            path, width, height, channels);
    if (stride < row)
        return sw_error_set(err, SW_ERR_ARG, "png %s: stride %zu is less than a row (%zu bytes)",
                            path, stride, row);
    return SW_OK;
}

/* Written whole or not at all: into a temporary beside path, renamed over
 * it. A walk stopped mid-write (SIGTERM, a full disk) then leaves the
 * frame before it as it was and no truncated PNG that passes for a frame.
 * No fsync: a picture is not worth a flush per frame, and a power cut
 * loses at most the newest frames whole. */
static sw_status write_file(const char *path, const unsigned char *bytes, size_t size,
                            sw_error *err)
{
    char tmp[4096];
    if (snprintf(tmp, sizeof tmp, "%s.tmp", path) >= (int)sizeof tmp)
        return sw_error_set(err, SW_ERR_ARG, "png %s: path too long", path);
    int fd = open(tmp, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0)
        return sw_error_set(err, SW_ERR_IO, "png %s: cannot open for writing: %s", tmp,
                            strerror(errno));
    size_t at = 0;
    int write_errno = 0;
    while (at < size) {
        ssize_t n = write(fd, bytes + at, size - at);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            write_errno = n < 0 ? errno : ENOSPC;
            break;
        }
        at += (size_t)n;
    }
    if (close(fd) != 0 && at == size)
        write_errno = errno, at = 0;
    if (at != size) {
        remove(tmp);
        return sw_error_set(err, SW_ERR_IO, "png %s: writing %zu bytes failed: %s", tmp, size,
                            strerror(write_errno));
    }
    if (rename(tmp, path) != 0) {
        int e = errno;
        remove(tmp);
        return sw_error_set(err, SW_ERR_IO, "png %s: rename from %s: %s", path, tmp,
                            strerror(e));
    }
    return SW_OK;
}

sw_status sw_png_write(const char *path, int width, int height, int channels,
                       const uint8_t *pixels, size_t stride, sw_arena *scratch, sw_error *err)
{
    sw_status st = check_args(path, width, height, channels, pixels, stride, err);
    if (st != SW_OK)
        return st;
    size_t need = sw_png_scratch_bytes(width, height, channels);
    size_t mark = sw_arena_mark(scratch);
    size_t free_bytes = scratch->size - mark;
    if (free_bytes < need)
        return sw_error_set(err, SW_ERR_NO_MEMORY,
                            "png %s: scratch arena has %zu bytes free, %dx%d x %d needs %zu",
                            path, free_bytes, width, height, channels, need);
    png_arena = scratch;
    unsigned char *volatile png = NULL;
    int len = 0;
    if (setjmp(png_out_of_memory) == 0)
        png = stbi_write_png_to_mem(pixels, (int)stride, width, height, channels, &len);
    png_arena = NULL;
    if (png)
        st = write_file(path, png, (size_t)len, err);
    else
        st = sw_error_set(err, SW_ERR_NO_MEMORY,
                          "png %s: stb ran out of scratch within sw_png_scratch_bytes (%zu): "
                          "the bound is wrong",
                          path, need);
    sw_arena_reset_to(scratch, mark);
    return st;
}
