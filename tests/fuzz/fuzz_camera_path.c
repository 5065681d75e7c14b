/* SPDX-License-Identifier: MIT */
/* Fuzz target: the camera path parser, and evaluation of whatever it accepts. */
#include <stddef.h>
#include <stdint.h>

#include "sw_camera_path.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static sw_camera_key keys[4096];
    const char *text = (const char *)data;
    size_t n = sw_camera_path_count_keys(text, size);
    sw_camera_path path;
    if (sw_camera_path_parse(text, size, "fuzz", keys, n < 4096 ? n : 4096, &path, NULL) != SW_OK)
        return 0;
    double t0 = sw_camera_path_start(&path), t1 = sw_camera_path_end(&path);
    for (int i = 0; i <= 16; i++)
        (void)sw_camera_path_at(&path, t0 + (t1 - t0) * i / 16.0);
    return 0;
}
