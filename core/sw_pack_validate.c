/* SPDX-License-Identifier: MIT */
/* The record checks of sw_pack_open_memory: every value the runtime indexes
 * with, divides by or draws is checked here once, so the walk over a
 * validated pack needs no checks of its own. Messages name the record and
 * field: "PATCHES[17].first_control: ...". Rules: assets/PACK_FORMAT.md. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "sw_pack_validate.h"

static const char axis_name[4] = { 'x', 'y', 'z', 'w' };

enum { NO_INDEX = -1 };

/* The box of record rec (index i, or NO_INDEX for META). The label is only
 * formatted on failure: this runs once per patch at load time. */
static sw_status check_box(const char *rec, int64_t i, const float *min, const float *max,
                           int need_ordered, sw_error *err)
{
    for (int k = 0; k < 3; k++) {
        int finite = isfinite(min[k]) && isfinite(max[k]);
        if (finite && (!need_ordered || min[k] <= max[k]))
            continue;
        char label[32];
        if (i == NO_INDEX)
            snprintf(label, sizeof label, "%s", rec);
        else
            snprintf(label, sizeof label, "%s[%lld]", rec, (long long)i);
        if (!finite)
            return sw_error_set(err, SW_ERR_FORMAT, "%s.box: %c range %g..%g is not finite",
                                label, axis_name[k], (double)min[k], (double)max[k]);
        return sw_error_set(err, SW_ERR_FORMAT, "%s.box: box_min.%c %g > box_max.%c %g", label,
                            axis_name[k], (double)min[k], axis_name[k], (double)max[k]);
    }
    return SW_OK;
}

static sw_status validate_meta(const sw_pack_meta *m, sw_error *err)
{
    for (size_t i = 0; i < sizeof m->reserved; i++)
        if (m->reserved[i] != 0)
            return sw_error_set(err, SW_ERR_FORMAT, "META.reserved[%zu]: 0x%02x, expected 0", i,
                                m->reserved[i]);
    sw_status s = check_box("META", NO_INDEX, m->box_min, m->box_max, m->patch_count > 0, err);
    if (s != SW_OK)
        return s;
    if (m->units > SW_UNITS_METRE)
        return sw_error_set(err, SW_ERR_FORMAT, "META.units: %u, expected 0..%d",
                            (unsigned)m->units, SW_UNITS_METRE);
    if (!isfinite(m->model_tolerance) || !(m->model_tolerance >= 0.0f))
        return sw_error_set(err, SW_ERR_FORMAT, "META.model_tolerance: %g, expected finite >= 0",
                            (double)m->model_tolerance);
    return SW_OK;
}

static sw_status validate_part(const sw_pack *pack, uint32_t i, sw_error *err)
{
    const sw_pack_part *p = &pack->parts[i];
    uint64_t end = (uint64_t)p->first_patch + p->patch_count;
    if (end > pack->meta->patch_count)
        return sw_error_set(err, SW_ERR_RANGE,
                            "PARTS[%u].first_patch: %u + patch_count %u exceeds PATCHES count %u",
                            (unsigned)i, (unsigned)p->first_patch, (unsigned)p->patch_count,
                            (unsigned)pack->meta->patch_count);
    for (int k = 0; k < 4; k++)
        if (!(p->color[k] >= 0.0f && p->color[k] <= 1.0f))
            return sw_error_set(err, SW_ERR_FORMAT, "PARTS[%u].color[%d]: %g, expected 0..1",
                                (unsigned)i, k, (double)p->color[k]);
    const char *nul = memchr(p->name, '\0', sizeof p->name);
    if (!nul)
        return sw_error_set(err, SW_ERR_FORMAT, "PARTS[%u].name: no NUL in its %zu bytes",
                            (unsigned)i, sizeof p->name);
    long bad = sw_utf8_error_at((const unsigned char *)p->name, (size_t)(nul - p->name));
    if (bad >= 0)
        return sw_error_set(err, SW_ERR_FORMAT, "PARTS[%u].name: invalid UTF-8 at byte %ld",
                            (unsigned)i, bad);
    return SW_OK;
}

/* The fields of one patch record, before its control points are looked at. */
static sw_status validate_patch_fields(const sw_pack *pack, uint32_t i, sw_error *err)
{
    const sw_pack_patch *p = &pack->patches[i];
    const sw_pack_meta *m = pack->meta;
    if (p->degree_u < 1 || p->degree_u > 15 || p->degree_v < 1 || p->degree_v > 15)
        return sw_error_set(err, SW_ERR_FORMAT, "PATCHES[%u].degree: %u x %u, expected 1..15 each",
                            (unsigned)i, p->degree_u, p->degree_v);
    if (p->flags & ~(uint16_t)SW_PATCH_RATIONAL)
        return sw_error_set(err, SW_ERR_FORMAT, "PATCHES[%u].flags: 0x%x has unknown bits",
                            (unsigned)i, p->flags);
    if (p->part >= m->part_count)
        return sw_error_set(err, SW_ERR_RANGE, "PATCHES[%u].part: %u, but PARTS has %u entries",
                            (unsigned)i, (unsigned)p->part, (unsigned)m->part_count);
    const sw_pack_part *part = &pack->parts[p->part];
    if (i < part->first_patch || i - part->first_patch >= part->patch_count)
        return sw_error_set(err, SW_ERR_RANGE,
                            "PATCHES[%u].part: %u, but that part holds patches [%u, %llu)",
                            (unsigned)i, (unsigned)p->part, (unsigned)part->first_patch,
                            (unsigned long long)part->first_patch + part->patch_count);
    uint64_t points = (uint64_t)(p->degree_u + 1) * (p->degree_v + 1);
    if ((uint64_t)p->first_control + points > m->control_count)
        return sw_error_set(err, SW_ERR_RANGE,
                            "PATCHES[%u].first_control: %u + %llu points exceeds CONTROL count %u",
                            (unsigned)i, (unsigned)p->first_control, (unsigned long long)points,
                            (unsigned)m->control_count);
    sw_status s = check_box("PATCHES", i, p->box_min, p->box_max, 1, err);
    if (s != SW_OK)
        return s;
    for (int k = 0; k < 3; k++) {
        if (p->box_min[k] < m->box_min[k] || p->box_max[k] > m->box_max[k])
            return sw_error_set(err, SW_ERR_FORMAT, "PATCHES[%u].box: %c range %g..%g is outside "
                                "META's %g..%g", (unsigned)i, axis_name[k], (double)p->box_min[k],
                                (double)p->box_max[k], (double)m->box_min[k],
                                (double)m->box_max[k]);
        if (!isfinite(p->d2_bound[k]) || !(p->d2_bound[k] >= 0.0f))
            return sw_error_set(err, SW_ERR_FORMAT, "PATCHES[%u].d2_bound[%d]: %g, expected "
                                "finite >= 0", (unsigned)i, k, (double)p->d2_bound[k]);
    }
    return SW_OK;
}

/* Weights and the box of one patch's control points (all already finite). */
static sw_status validate_patch_control(const sw_pack *pack, uint32_t i, sw_error *err)
{
    const sw_pack_patch *p = &pack->patches[i];
    uint32_t points = (uint32_t)(p->degree_u + 1) * (p->degree_v + 1);
    int rational = (p->flags & SW_PATCH_RATIONAL) != 0;
    for (uint32_t k = 0; k < points; k++) {
        uint32_t index = p->first_control + k;
        const float *c = &pack->control[(size_t)index * 4];
        if (rational && !(c[3] > 0.0f))
            return sw_error_set(err, SW_ERR_RANGE, "CONTROL[%u].w: %g, but rational PATCHES[%u] "
                                "needs weights > 0", (unsigned)index, (double)c[3], (unsigned)i);
        if (!rational && c[3] != 1.0f)
            return sw_error_set(err, SW_ERR_FORMAT, "CONTROL[%u].w: %g, but non-rational "
                                "PATCHES[%u] needs weight 1", (unsigned)index, (double)c[3],
                                (unsigned)i);
        for (int a = 0; a < 3; a++)
            if (c[a] < p->box_min[a] || c[a] > p->box_max[a])
                return sw_error_set(err, SW_ERR_FORMAT, "PATCHES[%u].box: control point %u "
                                    "(CONTROL[%u]).%c = %g is outside %g..%g", (unsigned)i,
                                    (unsigned)k, (unsigned)index, axis_name[a], (double)c[a],
                                    (double)p->box_min[a], (double)p->box_max[a]);
    }
    return SW_OK;
}

static sw_status validate_control_finite(const sw_pack *pack, sw_error *err)
{
    size_t n = (size_t)pack->meta->control_count * 4;
    for (size_t i = 0; i < n; i++)
        if (!isfinite(pack->control[i]))
            return sw_error_set(err, SW_ERR_FORMAT, "CONTROL[%zu].%c: %g, expected a finite number",
                                i / 4, axis_name[i % 4], (double)pack->control[i]);
    return SW_OK;
}

static sw_status validate_adjacency(const sw_pack *pack, uint32_t i, sw_error *err)
{
    const sw_pack_adjacency *a = &pack->adjacency[i];
    uint32_t n = pack->meta->patch_count;
    if (a->patch_a >= n || a->patch_b >= n)
        return sw_error_set(err, SW_ERR_RANGE, "ADJACENCY[%u].%s: %u, but PATCHES has %u entries",
                            (unsigned)i, a->patch_a >= n ? "patch_a" : "patch_b",
                            (unsigned)(a->patch_a >= n ? a->patch_a : a->patch_b), (unsigned)n);
    if (a->patch_a == a->patch_b)
        return sw_error_set(err, SW_ERR_FORMAT, "ADJACENCY[%u].patch_b: %u, the same as patch_a",
                            (unsigned)i, (unsigned)a->patch_b);
    if (a->edge_a > SW_EDGE_U0 || a->edge_b > SW_EDGE_U0)
        return sw_error_set(err, SW_ERR_RANGE, "ADJACENCY[%u].%s: %u, expected 0..3", (unsigned)i,
                            a->edge_a > SW_EDGE_U0 ? "edge_a" : "edge_b",
                            a->edge_a > SW_EDGE_U0 ? a->edge_a : a->edge_b);
    if (a->reversed > 1)
        return sw_error_set(err, SW_ERR_FORMAT, "ADJACENCY[%u].reversed: %u, expected 0 or 1",
                            (unsigned)i, a->reversed);
    if (a->reserved != 0)
        return sw_error_set(err, SW_ERR_FORMAT, "ADJACENCY[%u].reserved: %u, expected 0",
                            (unsigned)i, a->reserved);
    /* Seam code walks both boundary rows in step, so they must be equally long. */
    uint32_t na = sw_pack_edge_points(&pack->patches[a->patch_a], a->edge_a);
    uint32_t nb = sw_pack_edge_points(&pack->patches[a->patch_b], a->edge_b);
    if (na != nb)
        return sw_error_set(err, SW_ERR_FORMAT, "ADJACENCY[%u].edge_b: patch %u edge %u has %u "
                            "points, patch %u edge %u has %u", (unsigned)i, (unsigned)a->patch_a,
                            a->edge_a, (unsigned)na, (unsigned)a->patch_b, a->edge_b,
                            (unsigned)nb);
    return SW_OK;
}

static sw_status check_vec3_finite(uint32_t i, const char *field, const float *v, sw_error *err)
{
    for (int k = 0; k < 3; k++)
        if (!isfinite(v[k]))
            return sw_error_set(err, SW_ERR_FORMAT, "VIEWPOINTS[%u].%s.%c: %g, expected a "
                                "finite number", (unsigned)i, field, axis_name[k], (double)v[k]);
    return SW_OK;
}

static sw_status validate_viewpoint(const sw_pack_viewpoint *v, uint32_t i, sw_error *err)
{
    const char *nul = memchr(v->name, '\0', sizeof v->name);
    if (!nul)
        return sw_error_set(err, SW_ERR_FORMAT, "VIEWPOINTS[%u].name: no NUL in its %zu bytes",
                            (unsigned)i, sizeof v->name);
    long bad = sw_utf8_error_at((const unsigned char *)v->name, (size_t)(nul - v->name));
    if (bad >= 0)
        return sw_error_set(err, SW_ERR_FORMAT, "VIEWPOINTS[%u].name: invalid UTF-8 at byte %ld",
                            (unsigned)i, bad);
    sw_status s;
    if ((s = check_vec3_finite(i, "eye", v->eye, err)) != SW_OK ||
        (s = check_vec3_finite(i, "target", v->target, err)) != SW_OK ||
        (s = check_vec3_finite(i, "up", v->up, err)) != SW_OK)
        return s;
    /* A camera needs a direction to look in and an up to roll by. */
    if (v->eye[0] == v->target[0] && v->eye[1] == v->target[1] && v->eye[2] == v->target[2])
        return sw_error_set(err, SW_ERR_FORMAT, "VIEWPOINTS[%u].target: equals eye (%g, %g, %g)",
                            (unsigned)i, (double)v->eye[0], (double)v->eye[1],
                            (double)v->eye[2]);
    if (v->up[0] == 0.0f && v->up[1] == 0.0f && v->up[2] == 0.0f)
        return sw_error_set(err, SW_ERR_FORMAT, "VIEWPOINTS[%u].up: the zero vector",
                            (unsigned)i);
    if (!(v->fov_deg >= 0.0f && v->fov_deg < 180.0f))
        return sw_error_set(err, SW_ERR_FORMAT, "VIEWPOINTS[%u].fov_deg: %g, expected 0 "
                            "(the default) or between 0 and 180", (unsigned)i, (double)v->fov_deg);
    for (size_t k = 0; k < sizeof v->reserved; k++)
        if (v->reserved[k] != 0)
            return sw_error_set(err, SW_ERR_FORMAT, "VIEWPOINTS[%u].reserved[%zu]: 0x%02x, "
                                "expected 0", (unsigned)i, k, v->reserved[k]);
    return SW_OK;
}

/* Column-major 4 x 4 (sw_mat4): finite and affine, so the runtime can place
 * and invert a part without a projective divide. */
static sw_status validate_part_transform(const float *m, uint32_t i, sw_error *err)
{
    for (int k = 0; k < 16; k++)
        if (!isfinite(m[k]))
            return sw_error_set(err, SW_ERR_FORMAT, "PART_TRANSFORMS[%u][%d]: %g, expected a "
                                "finite number", (unsigned)i, k, (double)m[k]);
    static const int row3[4] = { 3, 7, 11, 15 };
    for (int c = 0; c < 4; c++) {
        float want = c == 3 ? 1.0f : 0.0f;
        if (m[row3[c]] != want)
            return sw_error_set(err, SW_ERR_FORMAT, "PART_TRANSFORMS[%u][%d]: %g, expected %g "
                                "(the last row of an affine map is 0 0 0 1)", (unsigned)i,
                                row3[c], (double)m[row3[c]], (double)want);
    }
    return SW_OK;
}

static sw_status validate_scene_records(const sw_pack *pack, sw_error *err)
{
    sw_status s = SW_OK;
    for (uint32_t i = 0; s == SW_OK && i < pack->viewpoint_count; i++)
        s = validate_viewpoint(&pack->viewpoints[i], i, err);
    for (uint32_t i = 0; s == SW_OK && pack->part_transforms && i < pack->meta->part_count; i++)
        s = validate_part_transform(&pack->part_transforms[(size_t)i * 16], i, err);
    return s;
}

sw_status sw_pack_validate_records(const sw_pack *pack, sw_error *err)
{
    const sw_pack_meta *m = pack->meta;
    sw_status s = validate_meta(m, err);
    if (s != SW_OK)
        return s;
    for (uint32_t i = 0; i < m->part_count; i++)
        if ((s = validate_part(pack, i, err)) != SW_OK)
            return s;
    if ((s = validate_control_finite(pack, err)) != SW_OK)
        return s;
    for (uint32_t i = 0; i < m->patch_count; i++)
        if ((s = validate_patch_fields(pack, i, err)) != SW_OK ||
            (s = validate_patch_control(pack, i, err)) != SW_OK)
            return s;
    /* Patches before adjacency: edge lengths come from checked degrees. */
    for (uint32_t i = 0; i < m->adjacency_count; i++)
        if ((s = validate_adjacency(pack, i, err)) != SW_OK)
            return s;
    return validate_scene_records(pack, err);
}
