/* libFuzzer entry point for the scene loader. Part files resolve against
 * SW_FUZZ_SCENE_DIR (the bundled samples), so inputs can reach the importers
 * and the transforms, not only the INI parsing. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "sw_scene.h"

#ifndef SW_FUZZ_SCENE_DIR
#define SW_FUZZ_SCENE_DIR "."
#endif

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sw_model model;
    sw_model_init(&model);
    sw_error err = {0};
    sw_status st = sw_scene_load_memory((const char *)data, size, "fuzz.ini", SW_FUZZ_SCENE_DIR,
                                        &model, &err);
    if (st != SW_OK && strncmp(err.message, "fuzz.ini:", 9) != 0)
        abort();
    if (st == SW_OK && model.part_count == 0)
        abort();
    sw_model_free(&model);
    return 0;
}
