/* SPDX-License-Identifier: MIT */
/* A scene as prototypes and placements (sw_scene.h, sw_scene_plan_load). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sw_scene.h"
#include "sw_model_split.h"
#include "sw_scene_internal.h"
#include "sw_text_scan.h"

/* What makes two parts the same prototype. */
typedef struct proto_key {
    int generated;
    char *path;                 /* resolved file, or NULL when generated */
    sw_proc_params proc;        /* when generated */
    double shape[3];            /* the scale a non-uniform part bakes in; 1 1 1 otherwise */
} proto_key;

typedef struct plan_builder {
    sw_scene_plan *plan;
    proto_key *keys;
    size_t capacity, placement_capacity;
    scene_cache cache;
    int import;                 /* 0: the prototypes' sources only */
} plan_builder;

static int uniform(const double s[3])
{
    return s[0] == s[1] && s[1] == s[2];
}

static int same_key(const proto_key *a, const proto_key *b)
{
    if (a->generated != b->generated || memcmp(a->shape, b->shape, sizeof a->shape) != 0)
        return 0;
    if (!a->generated)
        return strcmp(a->path, b->path) == 0;
    const sw_proc_params *p = &a->proc, *q = &b->proc;
    return p->kind == q->kind && p->size_mm == q->size_mm && p->height_mm == q->height_mm &&
           p->holes == q->holes && p->segments == q->segments && p->seed == q->seed;
}

/* The key of part: its file or object, and the scale it bakes in. */
static sw_status key_of(const scene_part *part, const char *base_dir, proto_key *key,
                        sw_error *err)
{
    memset(key, 0, sizeof *key);
    double u = part->units_to_mm;
    for (int k = 0; k < 3; k++)
        key->shape[k] = uniform(part->scale) ? 1.0 : part->scale[k] * u;
    key->generated = part->key_line[PK_GENERATE] != 0;
    if (key->generated) {
        key->proc = part->proc;
        return SW_OK;
    }
    char path[SCENE_PATH_MAX];
    sw_status st = scene_resolve_path(base_dir, part->file, path, err);
    if (st == SW_OK && !(key->path = strdup(path)))
        st = sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory");
    return st;
}

/* Room for one more prototype. */
static sw_status grow(plan_builder *b, sw_error *err)
{
    sw_scene_plan *plan = b->plan;
    if (plan->prototype_count < b->capacity)
        return SW_OK;
    size_t cap = b->capacity ? 2 * b->capacity : 16;
    sw_model *models = realloc(plan->prototypes, cap * sizeof *models);
    if (models)
        plan->prototypes = models;
    proto_key *keys = models ? realloc(b->keys, cap * sizeof *keys) : NULL;
    if (keys)
        b->keys = keys;
    char **sources = keys ? realloc(plan->sources, cap * sizeof *sources) : NULL;
    if (sources)
        plan->sources = sources;
    sw_import_report *reports = sources ? realloc(plan->reports, cap * sizeof *reports) : NULL;
    if (!reports)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory for %zu prototypes", cap);
    plan->reports = reports;
    b->capacity = cap;
    return SW_OK;
}

/* A new prototype for key: the file's parts (or the object) in its own
 * frame, the baked scale applied. */
static sw_status add_prototype(plan_builder *b, const scene_part *part, proto_key *key,
                               const sw_import_options *options, sw_import_report *report,
                               sw_error *err)
{
    sw_scene_plan *plan = b->plan;
    sw_status st = grow(b, err);
    if (st != SW_OK)
        return st;
    size_t k = plan->prototype_count;
    sw_model *m = &plan->prototypes[k];
    sw_model_init(m);
    memset(&plan->reports[k], 0, sizeof plan->reports[k]);
    plan->sources[k] = key->path ? strdup(key->path) : NULL;
    b->keys[k] = *key;
    plan->prototype_count++;
    if (key->path && !plan->sources[k])
        return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory");
    key->path = NULL; /* the builder owns it now */
    if (!b->import)
        return SW_OK;
    float color[4];
    sw_scene_default_color(plan->prototype_count - 1, color);
    /* A prototype's parts are named by what they are within their file (a
     * STEP product) or not at all; each placement names them after itself
     * (sw_instance_part_name). */
    if (key->generated) {
        st = sw_model_begin_part(m, "", color, err);
        if (st == SW_OK)
            st = sw_proc_add(m, &part->proc, err);
    } else {
        st = scene_cache_place(&b->cache, b->keys[k].path, "", color, options,
                               &plan->reports[k], m, err);
        if (report)
            sw_import_report_merge(report, &plan->reports[k]);
        for (size_t p = 0; st == SW_OK && p < m->part_count; p++)
            if (m->parts[p].name[0] == '/')
                memmove(m->parts[p].name, m->parts[p].name + 1, strlen(m->parts[p].name));
    }
    if (st == SW_OK && !uniform(key->shape)) {
        sw_mat4 s = sw_mat4_scale(sw_v3(key->shape[0], key->shape[1], key->shape[2]));
        for (size_t p = 0; p < m->part_count; p++)
            sw_model_transform_part(m, p, &s);
    }
    return st;
}

/* The placement's transform: translate, rotate, then the uniform scale
 * (units included) when the prototype does not bake it in. */
static void placement_transform(const scene_part *part, sw_scene_placement *out)
{
    double s = uniform(part->scale) ? part->scale[0] * part->units_to_mm : 1.0;
    sw_mat4 sm = sw_mat4_scale(sw_v3(s, s, s));
    sw_mat4 r = sw_mat4_rotate(sw_v3(part->axis[0], part->axis[1], part->axis[2]),
                               part->angle_deg * (SW_PI / 180.0));
    sw_mat4 t = sw_mat4_translate(sw_v3(part->translate[0], part->translate[1],
                                        part->translate[2]));
    sw_mat4 rs = sw_mat4_mul(&r, &sm);
    sw_mat4 m = sw_mat4_mul(&t, &rs);
    for (int k = 0; k < 16; k++)
        out->transform[k] = (float)m.m[k];
    out->transform[3] = out->transform[7] = out->transform[11] = 0;
    out->transform[15] = 1;
    out->scale = fabs(s);
}

static sw_status add_placement(plan_builder *b, const scene_part *part, size_t prototype,
                               sw_error *err)
{
    sw_scene_plan *plan = b->plan;
    if (plan->placement_count == b->placement_capacity) {
        size_t cap = b->placement_capacity ? 2 * b->placement_capacity : 64;
        sw_scene_placement *more = realloc(plan->placements, cap * sizeof *more);
        if (!more)
            return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory for %zu placements", cap);
        plan->placements = more;
        b->placement_capacity = cap;
    }
    sw_scene_placement *pl = &plan->placements[plan->placement_count++];
    memset(pl, 0, sizeof *pl);
    pl->prototype = prototype;
    placement_transform(part, pl);
    memcpy(pl->color, part->color, sizeof pl->color);
    snprintf(pl->name, sizeof pl->name, "%s", part->name);
    return SW_OK;
}

static sw_status plan_part(plan_builder *b, const scene_state *st, const scene_part *part,
                           const char *base_dir, const sw_import_options *options,
                           sw_import_report *report, sw_error *err)
{
    proto_key key;
    sw_status status = key_of(part, base_dir, &key, err);
    size_t k = 0;
    while (status == SW_OK && k < b->plan->prototype_count && !same_key(&b->keys[k], &key))
        k++;
    if (status == SW_OK && k == b->plan->prototype_count)
        status = add_prototype(b, part, &key, options, report, err);
    free(key.path);
    if (status == SW_OK)
        status = add_placement(b, part, k, err);
    if (status != SW_OK) {
        long line = part->key_line[part->key_line[PK_FILE] ? PK_FILE : PK_GENERATE];
        sw_error_prefix(err, "%s:%ld: part '%s'", st->file_name, line, part->name);
    }
    return status;
}

static sw_status plan_load(const char *path, int import, const sw_import_options *options,
                           sw_import_report *report, sw_scene_plan *plan, sw_error *err)
{
    memset(plan, 0, sizeof *plan);
    sw_model_init(&plan->views);
    char *text = NULL, base_dir[SCENE_PATH_MAX];
    size_t size = 0;
    sw_status status = path ? sw_read_whole_file(path, &text, &size, err)
                            : sw_error_set(err, SW_ERR_ARG, "sw_scene_plan_load: path is NULL");
    if (status == SW_OK)
        status = scene_base_dir(path, base_dir, err);
    scene_state st = { .text = text ? text : "", .size = size, .file_name = path, .err = err };
    if (status == SW_OK)
        status = scene_parse(&st);
    plan_builder b = { .plan = plan, .import = import };
    for (size_t i = 0; status == SW_OK && i < st.part_count; i++)
        status = plan_part(&b, &st, &st.parts[i], base_dir, options, report, err);
    for (size_t i = 0; status == SW_OK && i < st.view_count; i++)
        status = scene_load_view(&st, &st.views[i], &plan->views, err);
    if (status == SW_OK && st.up_axis_line)
        plan->views.up_axis = st.up_axis;
    for (size_t k = 0; k < plan->prototype_count; k++)
        free(b.keys[k].path);
    for (size_t i = 0; i < plan->placement_count; i++) {
        sw_scene_placement *pl = &plan->placements[i];
        for (size_t j = 0; j < plan->placement_count; j++)
            if (plan->placements[j].prototype == pl->prototype)
                pl->prototype_scale = fmax(pl->prototype_scale, plan->placements[j].scale);
    }
    free(b.keys);
    scene_cache_free(&b.cache);
    free(st.parts);
    free(st.views);
    free(text);
    return status;
}

sw_status sw_scene_plan_load(const char *path, const sw_import_options *options,
                             sw_import_report *report, sw_scene_plan *plan, sw_error *err)
{
    return plan_load(path, 1, options, report, plan, err);
}

sw_status sw_scene_plan_read(const char *path, sw_scene_plan *plan, sw_error *err)
{
    return plan_load(path, 0, NULL, NULL, plan, err);
}

void sw_scene_plan_placed(const sw_scene_plan *plan, size_t *parts, size_t *patches)
{
    *parts = *patches = 0;
    for (size_t i = 0; i < plan->placement_count; i++) {
        const sw_model *m = &plan->prototypes[plan->placements[i].prototype];
        *parts += m->part_count;
        *patches += m->patch_count;
    }
}

sw_status sw_scene_plan_copies(sw_scene_plan *plan, sw_error *err)
{
    size_t n = plan->placement_count;
    sw_model *models = calloc(n + 1, sizeof *models);
    char **sources = calloc(n + 1, sizeof *sources);
    sw_import_report *reports = calloc(n + 1, sizeof *reports);
    uint8_t *reported = calloc(plan->prototype_count + 1, 1);
    sw_status st = models && sources && reports && reported
                       ? SW_OK : sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory");
    for (size_t i = 0; st == SW_OK && i < n; i++) {
        size_t k = plan->placements[i].prototype;
        const sw_model *from = &plan->prototypes[k];
        sw_model_init(&models[i]);
        for (size_t p = 0; st == SW_OK && p < from->part_count; p++) {
            st = sw_model_begin_part(&models[i], from->parts[p].name, from->parts[p].color, err);
            for (size_t f = 0; st == SW_OK && f < from->parts[p].surface_count; f++)
                st = sw_model_copy_surface(from, from->parts[p].first_surface + f, &models[i],
                                           err);
        }
        models[i].model_tolerance = from->model_tolerance;
        if (plan->sources[k] && !(sources[i] = strdup(plan->sources[k])))
            st = sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory");
        if (!reported[k])   /* the file's import, told once */
            reports[i] = plan->reports[k], reported[k] = 1;
    }
    free(reported);
    if (st != SW_OK) {
        for (size_t i = 0; models && i < n; i++)
            sw_model_free(&models[i]), free(sources ? sources[i] : NULL);
        free(models), free(sources), free(reports);
        return st;
    }
    for (size_t k = 0; k < plan->prototype_count; k++)
        sw_model_free(&plan->prototypes[k]), free(plan->sources[k]);
    free(plan->prototypes), free(plan->sources), free(plan->reports);
    plan->prototypes = models, plan->sources = sources, plan->reports = reports;
    plan->prototype_count = n;
    for (size_t i = 0; i < n; i++)
        plan->placements[i].prototype = i;
    return SW_OK;
}

void sw_scene_plan_free(sw_scene_plan *plan)
{
    for (size_t k = 0; k < plan->prototype_count; k++) {
        sw_model_free(&plan->prototypes[k]);
        free(plan->sources[k]);
    }
    free(plan->prototypes);
    free(plan->sources);
    free(plan->reports);
    free(plan->placements);
    sw_model_free(&plan->views);
    memset(plan, 0, sizeof *plan);
}
