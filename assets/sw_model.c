/* The host-side model (sw_model.h): growable arrays of parts and patches. */
#include "sw_model.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Parts that nobody named or coloured get this neutral grey. */
static const float default_color[4] = {0.8f, 0.8f, 0.8f, 1.0f};

void sw_model_init(sw_model *model)
{
    memset(model, 0, sizeof *model);
}

void sw_model_free(sw_model *model)
{
    if (!model)
        return;
    for (size_t i = 0; i < model->patch_count; i++)
        free(model->patches[i].ctrl);
    free(model->patches);
    free(model->parts);
    sw_model_init(model);
}

/* Makes room for one more element of elem_size bytes in *array, doubling the
 * capacity so that n appends cost O(n) copies. */
static sw_status grow(void **array, size_t *capacity, size_t count, size_t elem_size,
                      const char *what, sw_error *err)
{
    if (count < *capacity)
        return SW_OK;
    size_t wanted = *capacity ? *capacity * 2 : 16;
    if (wanted > SIZE_MAX / elem_size)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "too many %s (%zu)", what, count);
    void *bigger = realloc(*array, wanted * elem_size);
    if (!bigger)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory growing %s to %zu", what,
                            wanted);
    *array = bigger;
    *capacity = wanted;
    return SW_OK;
}

sw_status sw_model_begin_part(sw_model *model, const char *name, const float color[4],
                              sw_error *err)
{
    if (!model)
        return sw_error_set(err, SW_ERR_ARG, "sw_model_begin_part: model is NULL");
    void *parts = model->parts;
    sw_status st = grow(&parts, &model->part_capacity, model->part_count,
                        sizeof *model->parts, "parts", err);
    model->parts = parts;
    if (st != SW_OK)
        return st;
    sw_model_part *part = &model->parts[model->part_count++];
    memset(part, 0, sizeof *part);
    /* Truncation is the documented contract: pack part names are 56 bytes. */
    size_t len = name ? strnlen(name, sizeof part->name - 1) : 0;
    if (len)
        memcpy(part->name, name, len);
    memcpy(part->color, color ? color : default_color, sizeof part->color);
    part->first_patch = model->patch_count;
    return SW_OK;
}

/* Rejects what would make an invalid pack later, so every importer gets the
 * same checks even if it forgot one. */
static sw_status check_patch(int degree_u, int degree_v, int rational, const double *ctrl,
                             sw_error *err)
{
    if (degree_u < 1 || degree_u > SW_BEZIER_MAX_DEGREE || degree_v < 1 ||
        degree_v > SW_BEZIER_MAX_DEGREE)
        return sw_error_set(err, SW_ERR_RANGE, "patch degree %d x %d out of range 1..%d",
                            degree_u, degree_v, SW_BEZIER_MAX_DEGREE);
    if (!ctrl)
        return sw_error_set(err, SW_ERR_ARG, "sw_model_add_patch: ctrl is NULL");
    size_t points = (size_t)(degree_u + 1) * (size_t)(degree_v + 1);
    for (size_t k = 0; k < points; k++) {
        const double *p = ctrl + 4 * k;
        if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2]))
            return sw_error_set(err, SW_ERR_RANGE, "control point %zu is not finite", k);
        if (rational && !(isfinite(p[3]) && p[3] > 0.0))
            return sw_error_set(err, SW_ERR_RANGE,
                                "control point %zu has weight %g; weights must be > 0", k, p[3]);
    }
    return SW_OK;
}

sw_status sw_model_add_patch(sw_model *model, int degree_u, int degree_v, int rational,
                             const double *ctrl, sw_error *err)
{
    if (!model)
        return sw_error_set(err, SW_ERR_ARG, "sw_model_add_patch: model is NULL");
    sw_status st = check_patch(degree_u, degree_v, rational, ctrl, err);
    if (st != SW_OK)
        return st;
    if (model->part_count == 0 && (st = sw_model_begin_part(model, "", NULL, err)) != SW_OK)
        return st;
    void *patches = model->patches;
    st = grow(&patches, &model->patch_capacity, model->patch_count, sizeof *model->patches,
              "patches", err);
    model->patches = patches;
    if (st != SW_OK)
        return st;
    size_t doubles = 4 * (size_t)(degree_u + 1) * (size_t)(degree_v + 1);
    double *copy = malloc(doubles * sizeof *copy);
    if (!copy)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory copying a patch");
    memcpy(copy, ctrl, doubles * sizeof *copy);
    if (!rational) {
        for (size_t k = 3; k < doubles; k += 4)
            copy[k] = 1.0;
    }
    model->patches[model->patch_count] = (sw_model_patch){
        .degree_u = degree_u,
        .degree_v = degree_v,
        .rational = rational ? 1 : 0,
        .ctrl = copy,
        .part = model->part_count - 1,
    };
    model->patch_count++;
    model->parts[model->part_count - 1].patch_count++;
    return SW_OK;
}

static size_t point_count(const sw_model_patch *patch)
{
    return (size_t)(patch->degree_u + 1) * (size_t)(patch->degree_v + 1);
}

void sw_model_transform_part(sw_model *model, size_t part, const sw_mat4 *m)
{
    if (!model || !m || part >= model->part_count)
        return;
    const sw_model_part *p = &model->parts[part];
    for (size_t i = p->first_patch; i < p->first_patch + p->patch_count; i++) {
        sw_model_patch *patch = &model->patches[i];
        size_t n = point_count(patch);
        for (size_t k = 0; k < n; k++) {
            double *c = patch->ctrl + 4 * k;
            sw_vec3 q = sw_mat4_transform_point(m, sw_v3(c[0], c[1], c[2]));
            c[0] = q.x;
            c[1] = q.y;
            c[2] = q.z;
        }
    }
}

sw_bezier_patch sw_model_patch_view(const sw_model_patch *patch)
{
    return (sw_bezier_patch){
        .degree_u = patch->degree_u,
        .degree_v = patch->degree_v,
        .rational = patch->rational,
        .ctrl = patch->ctrl,
    };
}

/* The box of the control points: it contains every patch (convex hull), which
 * is what culling and camera placement need. */
sw_box sw_model_box(const sw_model *model)
{
    sw_box box = sw_box_empty();
    for (size_t i = 0; model && i < model->patch_count; i++) {
        const sw_model_patch *patch = &model->patches[i];
        size_t n = point_count(patch);
        for (size_t k = 0; k < n; k++) {
            const double *c = patch->ctrl + 4 * k;
            sw_box_add_point(&box, sw_v3(c[0], c[1], c[2]));
        }
    }
    return box;
}
