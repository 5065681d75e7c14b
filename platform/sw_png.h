/* SPDX-License-Identifier: MIT */
/* PNG files through stb_image_write, with every allocation stb makes served
 * from a caller-given arena region, so writing frames does not call malloc
 * after start-up. Only one thread at a time may write. */
#ifndef SW_PNG_H
#define SW_PNG_H

#include <stddef.h>
#include <stdint.h>

#include "sw_arena.h"
#include "sw_error.h"

/* Worst-case scratch bytes sw_png_write needs for an image of this size
 * (stb's zlib hash chains, the filtered rows, the compressed stream and the
 * file image, with their growth by doubling); derived from stb's code in
 * sw_png.c. 0 for a size or channel count sw_png_write rejects. On noise (the
 * worst input) the measured peak is 0.7 to 1.0 of it. */
size_t sw_png_scratch_bytes(int width, int height, int channels);

/* Writes pixels (rows top first, stride bytes apart, channels 1..4) to path.
 * Takes scratch from the arena and gives it all back before returning.
 * SW_ERR_NO_MEMORY, before anything runs or is written, when the arena has
 * less than sw_png_scratch_bytes free; SW_ERR_IO naming the path when the
 * file cannot be written (a partial file is removed); SW_ERR_ARG for bad
 * arguments or images too large for stb's int arithmetic. */
sw_status sw_png_write(const char *path, int width, int height, int channels,
                       const uint8_t *pixels, size_t stride, sw_arena *scratch, sw_error *err);

#endif
