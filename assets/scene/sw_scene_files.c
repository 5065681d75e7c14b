/* SPDX-License-Identifier: MIT */
/* The files a scene names: their format by extension, whether the format
 * carries its units, the importer for each, and the default colours parts
 * get in order. Below the scene loader and the part cache, which both
 * import through it. */
#include <stdio.h>
#include <string.h>
#include <strings.h>

#include "sw_import_bpt.h"
#include "sw_import_iges.h"
#include "sw_import_newell.h"
#include "sw_import_occt.h"
#include "sw_scene.h"
#include "sw_scene_internal.h"

static const float palette[][4] = {
    {0.80f, 0.36f, 0.24f, 1.0f}, /* terracotta */
    {0.26f, 0.46f, 0.72f, 1.0f}, /* cornflower */
    {0.86f, 0.74f, 0.44f, 1.0f}, /* sand */
    {0.36f, 0.60f, 0.38f, 1.0f}, /* sage */
    {0.58f, 0.42f, 0.68f, 1.0f}, /* lavender */
    {0.75f, 0.75f, 0.78f, 1.0f}, /* pewter */
};

void sw_scene_default_color(size_t index, float out[4])
{
    memcpy(out, palette[index % (sizeof palette / sizeof palette[0])], 4 * sizeof(float));
}

const char *scene_extension(const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const char *dot = strrchr(base, '.');
    return dot && dot != base ? dot : "";
}

int sw_scene_is_scene_path(const char *path)
{
    return path && strcasecmp(scene_extension(path), ".ini") == 0;
}

/* ---- importers ---------------------------------------------------------- */

typedef sw_status (*import_fn)(const char *path, const sw_import_options *options,
                               sw_model *model, sw_import_report *report, sw_error *err);

static sw_status import_newell(const char *path, const sw_import_options *options,
                               sw_model *model, sw_import_report *report, sw_error *err)
{
    (void)options, (void)report;
    return sw_import_newell_file(path, model, err);
}

static sw_status import_bpt(const char *path, const sw_import_options *options, sw_model *model,
                            sw_import_report *report, sw_error *err)
{
    (void)options, (void)report;
    return sw_import_bpt_file(path, model, err);
}

/* Importers by extension; has_units: the format declares its units, so a
 * scene must not (sw_scene.h). */
static const struct {
    const char *ext;
    import_fn import;
    int has_units;
} importers[] = {
    {".txt", import_newell, 0},         {".bpt", import_bpt, 0},
    {".igs", sw_import_iges_file, 1},   {".iges", sw_import_iges_file, 1},
    {".stp", sw_import_occt_file, 1},   {".step", sw_import_occt_file, 1},
};

int scene_file_has_units(const char *path)
{
    const char *ext = scene_extension(path);
    for (size_t k = 0; k < sizeof importers / sizeof importers[0]; k++) {
        if (strcasecmp(ext, importers[k].ext) == 0)
            return importers[k].has_units;
    }
    return 0;
}

sw_status sw_scene_import_file_with(const char *path, const sw_import_options *options,
                                    sw_import_report *report, sw_model *model, sw_error *err)
{
    if (!path || !model)
        return sw_error_set(err, SW_ERR_ARG, "sw_scene_import_file: NULL argument");
    static const sw_import_options defaults = {0};
    const char *ext = scene_extension(path);
    for (size_t k = 0; k < sizeof importers / sizeof importers[0]; k++) {
        if (strcasecmp(ext, importers[k].ext) != 0)
            continue;
        sw_import_report one = {.units_to_mm = 1.0};
        sw_status st = importers[k].import(path, options ? options : &defaults, model, &one, err);
        if (report)
            sw_import_report_merge(report, &one);
        return st;
    }
    return sw_error_set(err, SW_ERR_UNSUPPORTED,
                        "%s: unsupported file type '%s' (expected .txt Newell listing, .bpt, "
                        ".igs/.iges or .stp/.step)",
                        path, ext);
}

sw_status sw_scene_import_file(const char *path, sw_model *model, sw_error *err)
{
    return sw_scene_import_file_with(path, NULL, NULL, model, err);
}
