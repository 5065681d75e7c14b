/* SPDX-License-Identifier: MIT */
/* libFuzzer entry point for the .bpt importer. Besides not
 * crashing, a failed import must leave the model empty and explain itself. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "sw_import_bpt.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sw_model model;
    sw_model_init(&model);
    sw_error err = {0};
    sw_status st = sw_import_bpt_memory((const char *)data, size, "fuzz.bpt", &model, &err);
    if (st != SW_OK && (model.patch_count != 0 || strncmp(err.message, "fuzz.bpt:", 9) != 0))
        abort();
    if (st == SW_OK && model.patch_count == 0)
        abort();
    sw_model_free(&model);
    return 0;
}
