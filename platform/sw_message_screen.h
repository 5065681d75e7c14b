/* SPDX-License-Identifier: MIT */
/* A screen that says what is wrong when there is nothing to walk (no valid
 * pack on the unit): a dark red background, a white border and a line of
 * blocky capitals, drawn with glScissor and glClear alone, so it needs no
 * shader, buffer or texture and works where the renderer could not start.
 * Called by seamwalk on the GL thread. */
#ifndef SW_MESSAGE_SCREEN_H
#define SW_MESSAGE_SCREEN_H

/* The colours, for tests that read the pixels back (RGB, 0..255). */
#define SW_MESSAGE_BACKGROUND_RGB 0x80, 0x10, 0x10
#define SW_MESSAGE_TEXT_RGB 0xFF, 0xFF, 0xFF

/* Draws text (capitals of "NO VALID PACK" and spaces; other characters are
 * left blank) centred, as large as fits, into the current framebuffer of
 * width x height. */
void sw_message_screen_draw(int width, int height, const char *text);

/* The glyph cell's size in pixels that sw_message_screen_draw uses for a
 * text of length characters, and where the text starts (its top-left corner
 * from the top-left of the screen), for tests. */
void sw_message_screen_layout(int width, int height, int length, int *cell, int *x0, int *y0);

#endif
