/* SPDX-License-Identifier: MIT */
/* The optional pack sections from a model (sw_pack_sections.h): surfaces,
 * their trimming loops and curves, each patch's domain and trim mask,
 * viewpoints and part transforms. Everything is rounded to float here, and
 * whatever the rounding could break is checked here, where the model record
 * can still be named. Format: assets/PACK_FORMAT.md. */
#include "sw_pack_sections.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_pack_validate.h"

void sw_pack_copy_name(char *dst, size_t cap, const char *src)
{
    size_t n = strnlen(src, cap - 1), o = 0;
    for (size_t i = 0; i < n;) {
        size_t len = sw_utf8_sequence_length((const unsigned char *)src + i, n - i);
        if (len == 0) {
            dst[o++] = '?';
            i++;
            continue;
        }
        memcpy(dst + o, src + i, len);
        o += len;
        i += len;
    }
    memset(dst + o, 0, cap - o);
}

/* A (u0, u1, v0, v1) domain as floats; SW_ERR_RANGE when a range is not
 * finite or collapses to a point in float. what names the model record. */
static sw_status convert_domain(const double in[4], float out[4], const char *what, size_t i,
                                sw_error *err)
{
    for (int k = 0; k < 4; k++)
        out[k] = (float)in[k];
    for (int a = 0; a < 2; a++)
        if (!isfinite(out[2 * a]) || !isfinite(out[2 * a + 1]) || !(out[2 * a] < out[2 * a + 1]))
            return sw_error_set(err, SW_ERR_RANGE, "%s %zu: %c range %.17g..%.17g is not a "
                                "non-empty range of floats", what, i, a ? 'v' : 'u', in[2 * a],
                                in[2 * a + 1]);
    return SW_OK;
}

static sw_status fits_u32(size_t n, const char *what, sw_error *err)
{
    if (n > UINT32_MAX)
        return sw_error_set(err, SW_ERR_RANGE, "model: %zu %s; a pack holds at most %u", n, what,
                            UINT32_MAX);
    return SW_OK;
}

static sw_status convert_surfaces(const sw_model *model, sw_pack_surface *out, sw_error *err)
{
    for (size_t i = 0; i < model->surface_count; i++) {
        const sw_model_surface *s = &model->surfaces[i];
        if (s->part >= model->part_count || s->first_patch > model->patch_count ||
            s->patch_count > model->patch_count - s->first_patch ||
            s->first_loop > model->loop_count || s->loop_count > model->loop_count - s->first_loop)
            return sw_error_set(err, SW_ERR_RANGE, "surface %zu: part %zu, patches %zu..+%zu or "
                                "loops %zu..+%zu out of range", i, s->part, s->first_patch,
                                s->patch_count, s->first_loop, s->loop_count);
        /* The reader requires it; say so here, where the cause is visible. */
        const sw_model_part *part = &model->parts[s->part];
        if (s->first_patch < part->first_patch ||
            s->first_patch + s->patch_count > part->first_patch + part->patch_count)
            return sw_error_set(err, SW_ERR_RANGE, "surface %zu: patches %zu..+%zu outside its "
                                "part %zu (patches %zu..+%zu)", i, s->first_patch,
                                s->patch_count, s->part, part->first_patch, part->patch_count);
        for (size_t p = s->first_patch; p < s->first_patch + s->patch_count; p++)
            if (model->patches[p].surface != i)
                return sw_error_set(err, SW_ERR_RANGE, "surface %zu: its patches %zu..+%zu "
                                    "include patch %zu of surface %zu", i, s->first_patch,
                                    s->patch_count, p, model->patches[p].surface);
        out[i] = (sw_pack_surface){ .part = (uint32_t)s->part,
                                    .first_patch = (uint32_t)s->first_patch,
                                    .patch_count = (uint32_t)s->patch_count,
                                    .first_loop = (uint32_t)s->first_loop,
                                    .loop_count = (uint32_t)s->loop_count };
        sw_status st = convert_domain(s->domain, out[i].domain, "surface", i, err);
        if (st != SW_OK)
            return st;
    }
    return SW_OK;
}

static sw_status convert_loops(const sw_model *model, sw_pack_trim_loop *out, sw_error *err)
{
    for (size_t i = 0; i < model->loop_count; i++) {
        const sw_model_loop *l = &model->loops[i];
        if (l->curve_count == 0 || l->first_curve > model->curve_count ||
            l->curve_count > model->curve_count - l->first_curve)
            return sw_error_set(err, SW_ERR_RANGE, "trim loop %zu: curves %zu..+%zu of %zu", i,
                                l->first_curve, l->curve_count, model->curve_count);
        out[i] = (sw_pack_trim_loop){ .first_curve = (uint32_t)l->first_curve,
                                      .curve_count = (uint32_t)l->curve_count,
                                      .flags = l->outer ? SW_LOOP_OUTER : 0 };
    }
    return SW_OK;
}

/* Floats of TRIM_DATA for every curve, checking what the format can hold. */
static sw_status count_trim_data(const sw_model *model, size_t *floats, sw_error *err)
{
    uint64_t total = 0;
    for (size_t i = 0; i < model->curve_count; i++) {
        const sw_model_trim_curve *c = &model->curves[i];
        if (c->degree < 1 || c->degree > 15 || c->count < c->degree + 1)
            return sw_error_set(err, SW_ERR_UNSUPPORTED, "trim curve %zu: degree %d with %d "
                                "points; a pack holds degrees 1..15 with at least degree + 1 "
                                "points", i, c->degree, c->count);
        total += (uint64_t)c->count * 4 + (uint64_t)c->degree + 1;
    }
    if (total > UINT32_MAX)
        return sw_error_set(err, SW_ERR_RANGE, "model: %llu floats of trim curves; a pack holds "
                            "at most %u", (unsigned long long)total, UINT32_MAX);
    *floats = (size_t)total;
    return SW_OK;
}

/* One curve's knots then (u, v, w) points at data. Rounding keeps knots
 * ordered and clamped (it is monotonic) but may empty the range or zero a
 * weight, so those are checked on the floats. */
static sw_status convert_curve(const sw_model_trim_curve *c, size_t i, float *data,
                               sw_pack_trim_curve *out, sw_error *err)
{
    size_t nk = (size_t)c->count + (size_t)c->degree + 1;
    int rational = 0;
    for (int j = 0; j < c->count; j++)
        rational |= c->ctrl[4 * j + 3] != 1.0;
    for (size_t k = 0; k < nk; k++)
        data[k] = (float)c->knots[k];
    if (!(data[c->degree] < data[c->count]))
        return sw_error_set(err, SW_ERR_RANGE, "trim curve %zu: knot range %.17g..%.17g is empty "
                            "in float", i, c->knots[c->degree], c->knots[c->count]);
    for (int j = 0; j < c->count; j++) {
        float *p = &data[nk + 3 * (size_t)j];
        p[0] = (float)c->ctrl[4 * j];
        p[1] = (float)c->ctrl[4 * j + 1];
        p[2] = rational ? (float)c->ctrl[4 * j + 3] : 1.0f;
        if (!isfinite(p[0]) || !isfinite(p[1]) || !(p[2] > 0.0f) || !isfinite(p[2]))
            return sw_error_set(err, SW_ERR_RANGE, "trim curve %zu: point %d (%g, %g, w %g) does "
                                "not fit floats with w > 0", i, j, c->ctrl[4 * j],
                                c->ctrl[4 * j + 1], c->ctrl[4 * j + 3]);
    }
    *out = (sw_pack_trim_curve){ .count = (uint32_t)c->count, .degree = (uint8_t)c->degree,
                                 .flags = (uint8_t)((rational ? SW_TRIM_RATIONAL : 0) |
                                                    (c->computed ? SW_TRIM_COMPUTED : 0)) };
    return SW_OK;
}

static sw_status convert_curves(const sw_model *model, sw_pack_trim_curve *out, float *data,
                                sw_error *err)
{
    size_t at = 0;
    for (size_t i = 0; i < model->curve_count; i++) {
        const sw_model_trim_curve *c = &model->curves[i];
        sw_status st = convert_curve(c, i, data + at, &out[i], err);
        if (st != SW_OK)
            return st;
        out[i].first_float = (uint32_t)at;
        at += (size_t)c->count * 4 + (size_t)c->degree + 1;
    }
    return SW_OK;
}

/* A mask with every cell set drops nothing: it is written as SW_MASK_NONE. */
static int mask_is_full(const uint32_t mask[32])
{
    for (int j = 0; j < 32; j++)
        if (mask[j] != UINT32_MAX)
            return 0;
    return 1;
}

/* The patch's domain, pulled into its surface's float domain: both are
 * rounded from doubles and the reader allows only a few float steps. */
static sw_status convert_patch_domain(const sw_model *model, size_t i,
                                      const sw_pack_surface *surfaces, sw_pack_patch_domain *out,
                                      sw_error *err)
{
    const sw_model_patch *p = &model->patches[i];
    if (p->surface >= model->surface_count)
        return sw_error_set(err, SW_ERR_RANGE, "patch %zu: surface %zu of %zu", i, p->surface,
                            model->surface_count);
    const sw_model_surface *s = &model->surfaces[p->surface];
    if (i < s->first_patch || i - s->first_patch >= s->patch_count)
        return sw_error_set(err, SW_ERR_RANGE, "patch %zu: outside its surface %zu (patches "
                            "%zu..+%zu)", i, p->surface, s->first_patch, s->patch_count);
    out->surface = (uint32_t)p->surface;
    sw_status st = convert_domain(p->domain, out->domain, "patch", i, err);
    const float *sd = surfaces[p->surface].domain;
    for (int k = 0; st == SW_OK && k < 4; k++)
        out->domain[k] = fminf(fmaxf(out->domain[k], sd[k & 2]), sd[(k & 2) + 1]);
    if (st == SW_OK && !(out->domain[0] < out->domain[1] && out->domain[2] < out->domain[3]))
        st = sw_error_set(err, SW_ERR_RANGE, "patch %zu: domain lies outside its surface %zu's",
                          i, p->surface);
    return st;
}

/* Patch domains and masks; *mask_count gets the masks used. */
static sw_status convert_patch_domains(const sw_model *model, const sw_pack_surface *surfaces,
                                       sw_pack_patch_domain *out, sw_pack_trim_mask *masks,
                                       uint32_t *mask_count, sw_error *err)
{
    uint32_t used = 0;
    for (size_t i = 0; i < model->patch_count; i++) {
        const sw_model_patch *p = &model->patches[i];
        sw_status st = convert_patch_domain(model, i, surfaces, &out[i], err);
        if (st != SW_OK)
            return st;
        out[i].mask = SW_MASK_NONE;
        if (p->masked && !mask_is_full(p->mask)) {
            memcpy(masks[used].rows, p->mask, sizeof masks[used].rows);
            out[i].mask = used++;
        }
    }
    *mask_count = used;
    return SW_OK;
}

static int vec_fits(const double v[3], float out[3])
{
    for (int k = 0; k < 3; k++)
        out[k] = (float)v[k];
    return isfinite(out[0]) && isfinite(out[1]) && isfinite(out[2]);
}

static sw_status convert_viewpoint(const sw_model_viewpoint *v, size_t i, sw_pack_viewpoint *out,
                                   sw_error *err)
{
    memset(out, 0, sizeof *out);
    sw_pack_copy_name(out->name, sizeof out->name, v->name);
    out->fov_deg = (float)v->fov_deg;
    int ok = vec_fits(v->eye, out->eye) && vec_fits(v->target, out->target) &&
             vec_fits(v->up, out->up);
    if (!ok || (out->eye[0] == out->target[0] && out->eye[1] == out->target[1] &&
                out->eye[2] == out->target[2]) ||
        (out->up[0] == 0.0f && out->up[1] == 0.0f && out->up[2] == 0.0f))
        return sw_error_set(err, SW_ERR_RANGE, "viewpoint %zu (%s): eye, target and up must be "
                            "finite floats, eye apart from target and up not zero", i, out->name);
    if (!(out->fov_deg >= 0.0f && out->fov_deg < 180.0f))
        return sw_error_set(err, SW_ERR_RANGE, "viewpoint %zu (%s): fov %g, expected 0 (the "
                            "default) or between 0 and 180 degrees", i, out->name, v->fov_deg);
    return SW_OK;
}

sw_status sw_pack_viewpoints_from_model(const sw_model *model, sw_pack_viewpoint *views,
                                       sw_error *err)
{
    for (size_t i = 0; i < model->viewpoint_count; i++) {
        sw_status st = convert_viewpoint(&model->viewpoints[i], i, &views[i], err);
        if (st != SW_OK)
            return st;
    }
    return SW_OK;
}

static sw_status convert_scene(const sw_model *model, sw_pack_viewpoint *views, float *transforms,
                               sw_error *err)
{
    sw_status st = sw_pack_viewpoints_from_model(model, views, err);
    if (st != SW_OK)
        return st;
    for (size_t i = 0; i < model->part_count; i++) {
        const double *m = model->parts[i].transform;
        float *f = &transforms[i * 16];
        for (int k = 0; k < 16; k++) {
            f[k] = (float)m[k];
            if (!isfinite(f[k]) || (k % 4 == 3 && f[k] != (k == 15 ? 1.0f : 0.0f)))
                return sw_error_set(err, SW_ERR_RANGE, "part %zu (%s): transform element %d is "
                                    "%g; a pack holds finite affine transforms", i,
                                    model->parts[i].name, k, m[k]);
        }
    }
    return SW_OK;
}

/* calloc(n + 1) so an empty array is still a pointer: present, count 0. */
static void *array_of(size_t n, size_t size) { return calloc(n + 1, size); }

sw_status sw_pack_sections_from_model(const sw_model *model, sw_pack_contents *out,
                                      sw_error *err)
{
    size_t floats = 0;
    sw_status st;
    if ((st = fits_u32(model->surface_count, "surfaces", err)) != SW_OK ||
        (st = fits_u32(model->loop_count, "trim loops", err)) != SW_OK ||
        (st = fits_u32(model->curve_count, "trim curves", err)) != SW_OK ||
        (st = fits_u32(model->viewpoint_count, "viewpoints", err)) != SW_OK ||
        (st = count_trim_data(model, &floats, err)) != SW_OK)
        return st;
    sw_pack_surface *surfaces = array_of(model->surface_count, sizeof *surfaces);
    sw_pack_trim_loop *loops = array_of(model->loop_count, sizeof *loops);
    sw_pack_trim_curve *curves = array_of(model->curve_count, sizeof *curves);
    float *data = array_of(floats, sizeof *data);
    sw_pack_patch_domain *domains = array_of(model->patch_count, sizeof *domains);
    sw_pack_trim_mask *masks = array_of(model->patch_count, sizeof *masks);
    sw_pack_viewpoint *views = array_of(model->viewpoint_count, sizeof *views);
    float *transforms = array_of(model->part_count * 16, sizeof *transforms);
    *out = (sw_pack_contents){ .meta = out->meta, .parts = out->parts, .patches = out->patches,
                               .control = out->control, .adjacency = out->adjacency,
                               .surfaces = surfaces, .surface_count = (uint32_t)model->surface_count,
                               .trim_loops = loops, .trim_loop_count = (uint32_t)model->loop_count,
                               .trim_curves = curves,
                               .trim_curve_count = (uint32_t)model->curve_count,
                               .trim_data = data, .trim_data_count = (uint32_t)floats,
                               .patch_domains = domains, .trim_masks = masks, .viewpoints = views,
                               .viewpoint_count = (uint32_t)model->viewpoint_count,
                               .part_transforms = transforms };
    if (!surfaces || !loops || !curves || !data || !domains || !masks || !views || !transforms)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "model: cannot allocate the trim sections");
    if ((st = convert_surfaces(model, surfaces, err)) != SW_OK ||
        (st = convert_loops(model, loops, err)) != SW_OK ||
        (st = convert_curves(model, curves, data, err)) != SW_OK ||
        (st = convert_patch_domains(model, surfaces, domains, masks, &out->trim_mask_count,
                                    err)) != SW_OK)
        return st;
    return convert_scene(model, views, transforms, err);
}
