/* SPDX-License-Identifier: MIT */
/* Part files read once per scene load (sw_scene_internal.h). Copies go
 * through the model's public calls: sw_model_add_surface re-splits and
 * re-trims each surface, which is cheap next to reading a STEP file, and
 * single-patch untrimmed surfaces (Bezier inputs) go back through
 * sw_model_add_patch, so a copy holds exactly what a fresh import would. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sw_scene.h"
#include "sw_model_split.h"
#include "sw_scene_internal.h"

void scene_cache_free(scene_cache *cache)
{
    for (size_t i = 0; i < cache->count; i++) {
        free(cache->entries[i].path);
        sw_model_free(&cache->entries[i].model);
    }
    free(cache->entries);
    memset(cache, 0, sizeof *cache);
}

/* The file's entry in *out, importing the file the first time. */
static sw_status cache_entry(scene_cache *cache, const char *path,
                             const sw_import_options *options, sw_import_report *report,
                             const scene_cache_entry **out, sw_error *err)
{
    for (size_t i = 0; i < cache->count; i++) {
        if (strcmp(cache->entries[i].path, path) == 0) {
            *out = &cache->entries[i];
            return SW_OK;
        }
    }
    if (cache->count == cache->capacity) {
        size_t cap = cache->capacity ? 2 * cache->capacity : 8;
        scene_cache_entry *bigger = realloc(cache->entries, cap * sizeof *bigger);
        if (!bigger)
            return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory for %zu part files", cap);
        cache->entries = bigger;
        cache->capacity = cap;
    }
    scene_cache_entry *e = &cache->entries[cache->count];
    sw_model_init(&e->model);
    e->path = malloc(strlen(path) + 1);
    sw_status st = e->path ? sw_model_begin_part(&e->model, "", NULL, err)
                           : sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory");
    if (st == SW_OK)
        st = sw_scene_import_file_with(path, options, report, &e->model, err);
    if (st != SW_OK) {
        free(e->path);
        sw_model_free(&e->model);
        return st;
    }
    memcpy(e->path, path, strlen(path) + 1);
    cache->count++;
    *out = e;
    return SW_OK;
}

sw_status scene_cache_place(scene_cache *cache, const char *path, const char *name,
                            const float color[4], const sw_import_options *options,
                            sw_import_report *report, sw_model *model, sw_error *err)
{
    const scene_cache_entry *e = NULL;
    sw_status st = cache_entry(cache, path, options, report, &e, err);
    if (st != SW_OK)
        return st;
    const sw_model *from = &e->model;
    /* The import began a placeholder part (0); an importer that starts parts
     * of its own (OCCT: one per STEP product) leaves it empty. Then the scene
     * part is those parts, named "scene part/product" and in the scene's
     * colour; an empty placeholder is dropped unless the file gave nothing. */
    size_t named = from->part_count > 1 && from->parts[0].surface_count == 0 ? 1 : 0;
    for (size_t p = named; st == SW_OK && p < from->part_count; p++) {
        const sw_model_part *part = &from->parts[p];
        char full[sizeof part->name];
        if (named)
            snprintf(full, sizeof full, "%.27s/%.27s", name, part->name);
        st = sw_model_begin_part(model, named ? full : name, color, err);
        for (size_t s = 0; st == SW_OK && s < part->surface_count; s++)
            st = sw_model_copy_surface(from, part->first_surface + s, model, err);
    }
    if (from->model_tolerance > model->model_tolerance)
        model->model_tolerance = from->model_tolerance;
    return st;
}
