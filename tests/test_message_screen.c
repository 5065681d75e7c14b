/* SPDX-License-Identifier: MIT */
/* The "no valid pack" screen (platform/sw_message_screen.c), rendered
 * headless and read back: the background and text colours where the
 * glyphs say, nothing else, and not a black display. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "sw_egl_headless.h"
#include "sw_message_screen.h"
#include "sw_test.h"

enum { W = 320, H = 180 };
static const uint8_t bg[3] = { SW_MESSAGE_BACKGROUND_RGB }, fg[3] = { SW_MESSAGE_TEXT_RGB };

static int is(const uint8_t *px, const uint8_t rgb[3]) { return memcmp(px, rgb, 3) == 0; }

/* The pixel at the centre of glyph cell (col, row) of character i. */
static const uint8_t *cell_pixel(const uint8_t *rgba, int i, int col, int row)
{
    int cell, x0, y0;
    sw_message_screen_layout(W, H, 13, &cell, &x0, &y0);
    int x = x0 + (6 * i + col) * cell + cell / 2, y = y0 + row * cell + cell / 2;
    return rgba + ((size_t)y * W + (size_t)x) * 4;
}

static void test_no_valid_pack_screen(void)
{
    sw_egl_headless egl;
    sw_error err = { 0 };
    sw_status st = sw_egl_headless_init(&egl, SW_GL_API_GLES2, W, H, &err);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    if (st != SW_OK)
        return;
    uint8_t *rgba = malloc((size_t)W * H * 4);
    sw_message_screen_draw(W, H, "NO VALID PACK");
    SW_CHECK(sw_egl_headless_read_rgba(&egl, rgba, &err) == SW_OK);
    size_t background = 0, text = 0, other = 0;
    for (size_t i = 0; i < (size_t)W * H; i++) {
        const uint8_t *px = rgba + 4 * i;
        background += is(px, bg);
        text += is(px, fg);
        other += !is(px, bg) && !is(px, fg);
    }
    printf("message screen %dx%d: %zu background, %zu text, %zu other pixels\n", W, H,
           background, text, other);
    SW_CHECK(other == 0);
    SW_CHECK(background > (size_t)W * H / 2);
    SW_CHECK(text > (size_t)W * H / 50);
    /* 'N' (character 0): its left stem is set, the cell right of it on the
     * top row is not; 'V' (character 3) ends in one point at the bottom. */
    SW_CHECK(is(cell_pixel(rgba, 0, 0, 0), fg) && is(cell_pixel(rgba, 0, 1, 0), bg));
    SW_CHECK(is(cell_pixel(rgba, 3, 2, 6), fg) && is(cell_pixel(rgba, 3, 0, 6), bg));
    SW_CHECK(is(rgba, fg)); /* the border's top-left corner */
    free(rgba);
    sw_egl_headless_destroy(&egl);
}

int main(void)
{
    SW_RUN(test_no_valid_pack_screen);
    return sw_test_finish();
}
