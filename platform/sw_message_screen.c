/* SPDX-License-Identifier: MIT */
/* The message screen (sw_message_screen.h). */
#include "sw_message_screen.h"

#include <GLES2/gl2.h>
#include <string.h>

/* 5 x 7 glyphs, one row per byte, bit 4 the leftmost column. */
static const struct glyph { char c; unsigned char rows[7]; } glyphs[] = {
    { 'A', { 0x0E, 0x11, 0x11, 0x1F, 0x11, 0x11, 0x11 } },
    { 'C', { 0x0E, 0x11, 0x10, 0x10, 0x10, 0x11, 0x0E } },
    { 'D', { 0x1E, 0x11, 0x11, 0x11, 0x11, 0x11, 0x1E } },
    { 'I', { 0x0E, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0E } },
    { 'K', { 0x11, 0x12, 0x14, 0x18, 0x14, 0x12, 0x11 } },
    { 'L', { 0x10, 0x10, 0x10, 0x10, 0x10, 0x10, 0x1F } },
    { 'N', { 0x11, 0x19, 0x15, 0x13, 0x11, 0x11, 0x11 } },
    { 'O', { 0x0E, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0E } },
    { 'P', { 0x1E, 0x11, 0x11, 0x1E, 0x10, 0x10, 0x10 } },
    { 'V', { 0x11, 0x11, 0x11, 0x11, 0x11, 0x0A, 0x04 } },
};

static const unsigned char *rows_of(char c)
{
    for (size_t i = 0; i < sizeof glyphs / sizeof glyphs[0]; i++)
        if (glyphs[i].c == c)
            return glyphs[i].rows;
    return NULL;
}

void sw_message_screen_layout(int width, int height, int length, int *cell, int *x0, int *y0)
{
    /* Each character is 6 cells wide (5 and a gap); the text spans at most
     * 80% of the width and a third of the height. */
    int columns = length > 0 ? 6 * length : 6;
    int c = (width * 4 / 5) / columns, by_height = height / 3 / 7;
    *cell = c < by_height ? c : by_height;
    if (*cell < 1)
        *cell = 1;
    *x0 = (width - *cell * (columns - 1)) / 2;
    *y0 = (height - *cell * 7) / 2;
}

/* Fills a rectangle given from the top-left, in GL's bottom-up coordinates. */
static void fill(int height, int x, int y, int w, int h, float r, float g, float b)
{
    glScissor(x, height - y - h, w, h);
    glClearColor(r, g, b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
}

void sw_message_screen_draw(int width, int height, const char *text)
{
    int cell, x0, y0, len = (int)strlen(text);
    sw_message_screen_layout(width, height, len, &cell, &x0, &y0);
    glViewport(0, 0, width, height);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(0x80 / 255.0f, 0x10 / 255.0f, 0x10 / 255.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    int border = height / 60 + 1;
    fill(height, 0, 0, width, border, 1, 1, 1);
    fill(height, 0, height - border, width, border, 1, 1, 1);
    fill(height, 0, 0, border, height, 1, 1, 1);
    fill(height, width - border, 0, border, height, 1, 1, 1);
    for (int i = 0; i < len; i++) {
        const unsigned char *rows = rows_of(text[i]);
        for (int r = 0; rows && r < 7; r++)
            for (int col = 0; col < 5; col++)
                if (rows[r] & (0x10 >> col))
                    fill(height, x0 + (6 * i + col) * cell, y0 + r * cell, cell, cell, 1, 1, 1);
    }
    glDisable(GL_SCISSOR_TEST);
}
