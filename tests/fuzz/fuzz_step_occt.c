/* SPDX-License-Identifier: MIT */
/* Fuzz target: a STEP file through the importer seamwalk-pack uses
 * (sw_import_occt_file: the quick pass of sw_step_scan.c, then
 * OpenCASCADE's reader, the transfer, sewing and the conversion to the
 * host model), in-process. OpenCASCADE reads files, so each input is
 * written to one file of this process's. run-fuzzers.sh caps each input's
 * time and the process's memory (-timeout, -rss_limit_mb): an input past
 * either is a finding, like a crash. */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "sw_import.h"
#include "sw_import_occt.h"
#include "sw_model.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static char path[64];
    if (!path[0])
        snprintf(path, sizeof path, "/tmp/sw-fuzz-step-%ld.step", (long)getpid());
    FILE *f = fopen(path, "wb");
    if (!f)
        return 0;
    size_t written = fwrite(data, 1, size, f);
    if (fclose(f) != 0 || written != size)
        return 0;
    sw_model model;
    sw_model_init(&model);
    sw_error err = {0};
    static const sw_import_options options = {0};
    (void)sw_import_occt_file(path, &options, &model, NULL, &err);
    sw_model_free(&model);
    return 0;
}
