/* SPDX-License-Identifier: MIT */
/* libFuzzer entry point for the scene loader. Part files resolve against
 * SW_FUZZ_SCENE_DIR (the bundled samples), so inputs can reach the importers
 * and the transforms, not only the INI parsing; generated parts and views go
 * all the way into the model too. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "sw_scene.h"

#ifndef SW_FUZZ_SCENE_DIR
#define SW_FUZZ_SCENE_DIR "."
#endif

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* A generated part is up to 64 x 64 patches with trim masks: a few keep an
 * input fast, more only make the fuzzer slow without reaching new code. */
static int too_many_generated_parts(const uint8_t *data, size_t size)
{
    int count = 0;
    for (size_t i = 0; i + 8 <= size; i++)
        count += memcmp(data + i, "generate", 8) == 0;
    return count > 4;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (too_many_generated_parts(data, size))
        return 0;
    sw_model model;
    sw_model_init(&model);
    sw_error err = {0};
    sw_status st = sw_scene_load_memory((const char *)data, size, "fuzz.ini", SW_FUZZ_SCENE_DIR,
                                        &model, &err);
    if (st != SW_OK && strncmp(err.message, "fuzz.ini:", 9) != 0)
        abort();
    if (st == SW_OK && model.part_count == 0)
        abort();
    for (size_t i = 0; st == SW_OK && i < model.viewpoint_count; i++) {
        if (model.viewpoints[i].name[0] == '\0' || model.viewpoints[i].fov_deg < 0.0 ||
            model.viewpoints[i].fov_deg >= 180.0)
            abort();
    }
    sw_model_free(&model);
    return 0;
}
