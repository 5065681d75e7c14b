/* SPDX-License-Identifier: MIT */
/* PNG output: exact round trips through stb_image, the scratch bound against
 * the measured peak on incompressible images up to 3840x2160, and the errors
 * (too little scratch, unwritable path, bad arguments). */
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>

#include <string.h>

#include "sw_png.h"
#include "sw_test.h"

static void fill_noise(uint8_t *p, size_t n)
{
    for (size_t i = 0; i < n; i++)
        p[i] = (uint8_t)(sw_test_random() * 256.0);
}

/* An arena sized to the bound, starting 3 bytes in so stb's blocks need
 * alignment padding, as they may in a shared scratch arena. */
typedef struct test_arena {
    void *block;
    sw_arena arena;
    size_t mark;
} test_arena;

static int test_arena_open(test_arena *t, size_t bytes)
{
    t->block = malloc(bytes + 3);
    if (!t->block)
        return 0;
    sw_arena_init(&t->arena, t->block, bytes + 3);
    sw_arena_alloc(&t->arena, 3, 1);
    t->mark = sw_arena_mark(&t->arena);
    return 1;
}

static int file_exists(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (f)
        fclose(f);
    return f != NULL;
}

/* 37x23 (odd sizes) with 5 bytes of padding per row: what goes in comes out. */
static void roundtrip(int channels)
{
    enum { PW = 37, PH = 23, PAD = 5 };
    size_t stride = (size_t)PW * (size_t)channels + PAD;
    uint8_t *in = malloc(stride * PH);
    fill_noise(in, stride * PH);
    for (int y = 0; y < PH / 2; y++)   /* half gradient, half noise: both paths of zlib */
        for (size_t x = 0; x < stride; x++)
            in[(size_t)y * stride + x] = (uint8_t)(x + (size_t)y);
    test_arena t;
    SW_CHECK(test_arena_open(&t, sw_png_scratch_bytes(PW, PH, channels)));
    char path[64];
    snprintf(path, sizeof path, "test_png_roundtrip_%d.png", channels);
    sw_error err = { 0 };
    sw_status st = sw_png_write(path, PW, PH, channels, in, stride, &t.arena, &err);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    SW_CHECK(sw_arena_mark(&t.arena) == t.mark);   /* scratch given back */
    int w = 0, h = 0, n = 0;
    uint8_t *out = stbi_load(path, &w, &h, &n, 0);
    SW_CHECK_MSG(out != NULL, "stb_image cannot read %s: %s", path, stbi_failure_reason());
    if (out) {
        SW_CHECK(w == PW && h == PH && n == channels);
        int rows_equal = 0;
        for (int y = 0; y < PH; y++)
            rows_equal += memcmp(out + (size_t)y * PW * channels, in + (size_t)y * stride,
                                 (size_t)PW * channels) == 0;
        SW_CHECK_MSG(rows_equal == PH, "%d channels: %d of %d rows equal", channels, rows_equal,
                     PH);
        stbi_image_free(out);
    }
    remove(path);
    free(t.block);
    free(in);
}

static void test_roundtrip_grey(void) { roundtrip(1); }
static void test_roundtrip_grey_alpha(void) { roundtrip(2); }
static void test_roundtrip_rgb(void) { roundtrip(3); }
static void test_roundtrip_rgba(void) { roundtrip(4); }

/* Noise does not compress, so stb's stream, hash chains and stored-block
 * fallback all reach their largest; a flat image makes chains hit the cap. */
static void check_peak(int w, int h, int channels, int noise)
{
    size_t bytes = (size_t)w * (size_t)h * (size_t)channels;
    uint8_t *img = malloc(bytes);
    if (noise)
        fill_noise(img, bytes);
    else
        memset(img, 0x5a, bytes);
    size_t bound = sw_png_scratch_bytes(w, h, channels);
    test_arena t;
    SW_CHECK(test_arena_open(&t, bound));
    sw_error err = { 0 };
    sw_status st = sw_png_write("test_png_peak.png", w, h, channels, img,
                                (size_t)w * (size_t)channels, &t.arena, &err);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    size_t peak = t.arena.peak - t.mark;
    SW_CHECK_MSG(peak <= bound, "%dx%d x %d: peak %zu > bound %zu", w, h, channels, peak, bound);
    printf("  %s %dx%d x %d: peak %zu bytes, bound %zu (%.2fx the peak, %.2f bytes per "
           "pixel byte)\n",
           noise ? "noise" : "flat ", w, h, channels, peak, bound, (double)bound / (double)peak,
           (double)bound / (double)bytes);
    remove("test_png_peak.png");
    free(t.block);
    free(img);
}

static void test_peak_within_bound_small(void)
{
    check_peak(1, 1, 1, 1);
    check_peak(3, 2, 4, 1);
    check_peak(64, 48, 4, 1);
    check_peak(64, 48, 4, 0);
}

static void test_peak_within_bound_large(void)
{
    check_peak(640, 480, 3, 1);
    check_peak(1920, 1080, 4, 1);
    check_peak(1920, 1080, 4, 0);
    check_peak(3840, 2160, 4, 1);
}

/* One byte short of the bound: refused before stb runs, nothing written. */
static void test_too_small_arena_is_no_memory_and_no_file(void)
{
    enum { PW = 64, PH = 48 };
    static uint8_t img[PW * PH * 3];
    fill_noise(img, sizeof img);
    const char *path = "test_png_no_memory.png";
    remove(path);
    test_arena t;
    SW_CHECK(test_arena_open(&t, sw_png_scratch_bytes(PW, PH, 3) - 1));
    sw_error err = { 0 };
    SW_CHECK(sw_png_write(path, PW, PH, 3, img, PW * 3, &t.arena, &err) == SW_ERR_NO_MEMORY);
    SW_CHECK(strstr(err.message, path) != NULL);
    SW_CHECK(!file_exists(path));
    SW_CHECK(t.arena.peak == t.mark);   /* stb never ran */
    free(t.block);
}

static void test_unwritable_path_is_io_error_naming_it(void)
{
    static uint8_t img[4 * 4 * 4];
    const char *path = "/nonexistent-seamwalk-dir/frame.png";
    test_arena t;
    SW_CHECK(test_arena_open(&t, sw_png_scratch_bytes(4, 4, 4)));
    sw_error err = { 0 };
    SW_CHECK(sw_png_write(path, 4, 4, 4, img, 16, &t.arena, &err) == SW_ERR_IO);
    SW_CHECK_MSG(strstr(err.message, path) != NULL, "message: %s", err.message);
    SW_CHECK(sw_arena_mark(&t.arena) == t.mark);
    free(t.block);
}

static void test_bad_arguments_are_rejected(void)
{
    static uint8_t img[4 * 4 * 4];
    test_arena t;
    SW_CHECK(test_arena_open(&t, sw_png_scratch_bytes(4, 4, 4)));
    sw_error err = { 0 };
    SW_CHECK(sw_png_write("x.png", 4, 4, 5, img, 20, &t.arena, &err) == SW_ERR_ARG);
    SW_CHECK(sw_png_write("x.png", 0, 4, 4, img, 16, &t.arena, &err) == SW_ERR_ARG);
    SW_CHECK(sw_png_write("x.png", 4, 4, 4, img, 15, &t.arena, &err) == SW_ERR_ARG);
    SW_CHECK(sw_png_write("x.png", 100000, 100000, 4, img, 400000, &t.arena, &err) == SW_ERR_ARG);
    SW_CHECK(!file_exists("x.png"));
    SW_CHECK(sw_png_scratch_bytes(4, 4, 0) == 0);
    free(t.block);
}

int main(void)
{
    SW_RUN(test_roundtrip_grey);
    SW_RUN(test_roundtrip_grey_alpha);
    SW_RUN(test_roundtrip_rgb);
    SW_RUN(test_roundtrip_rgba);
    SW_RUN(test_peak_within_bound_small);
    SW_RUN(test_peak_within_bound_large);
    SW_RUN(test_too_small_arena_is_no_memory_and_no_file);
    SW_RUN(test_unwritable_path_is_io_error_naming_it);
    SW_RUN(test_bad_arguments_are_rejected);
    return sw_test_finish();
}
