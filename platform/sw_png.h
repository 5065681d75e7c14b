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
 * file image, with their growth by doubling). */
size_t sw_png_scratch_bytes(int width, int height, int channels);

/* Writes pixels (rows top first, stride bytes apart, channels 1..4) to path.
 * Takes scratch from the arena and gives it all back before returning. */
sw_status sw_png_write(const char *path, int width, int height, int channels,
                       const uint8_t *pixels, size_t stride, sw_arena *scratch, sw_error *err);

#endif
