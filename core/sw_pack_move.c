/* SPDX-License-Identifier: MIT */
#include "sw_pack_move.h"

#include <math.h>
#include <string.h>

#include "sw_bezier.h"
#include "sw_pack_instances.h"

static uint32_t shifted(const sw_pack_move *m, int space, uint32_t i)
{
    return (uint32_t)((int64_t)i + m->shift[space]);
}

uint32_t sw_pack_move_vertex(const sw_pack_move *m, uint32_t v)
{
    if (v == SW_SEAM_NONE)
        return v;
    if (v < m->src_originals)
        return shifted(m, SW_SPACE_SEAM_ORIGINALS, v);
    return m->dst_originals + shifted(m, SW_SPACE_SEAM_COLLAPSES, v - m->src_originals);
}

static float length(const sw_pack_move *m, float x)
{
    return m->transform ? (float)(x * m->scale) : x;
}

static void place(const sw_pack_move *m, const float p[3], float out[3])
{
    if (m->transform)
        sw_instance_place(m->transform, p, out);
    else
        memcpy(out, p, 3 * sizeof(float));
}

/* A direction turned by the transform's rotation, unit again. */
static void turn(const float *t, const double d[3], double out[3])
{
    double len = 0;
    for (int r = 0; r < 3; r++) {
        out[r] = t[r] * d[0] + t[4 + r] * d[1] + t[8 + r] * d[2];
        len += out[r] * out[r];
    }
    len = sqrt(len);
    for (int r = 0; r < 3; r++)
        out[r] = len > 0 ? out[r] / len : 0;
}

void sw_pack_move_parts(const sw_pack_move *m, const sw_pack_part *src, uint32_t n,
                        sw_pack_part *dst)
{
    for (uint32_t i = 0; i < n; i++) {
        dst[i] = src[i];
        dst[i].first_patch = shifted(m, SW_SPACE_PATCHES, src[i].first_patch);
    }
}

void sw_pack_move_control(const sw_pack_move *m, const float *src, uint32_t n, float *dst)
{
    for (uint32_t i = 0; i < n; i++) {
        place(m, &src[4 * (size_t)i], &dst[4 * (size_t)i]);
        dst[4 * (size_t)i + 3] = src[4 * (size_t)i + 3];
    }
}

static float float_up(double d)
{
    float f = (float)d;
    return (double)f < d ? nextafterf(f, INFINITY) : f;
}

/* The box of a patch, and with bounds its second-derivative bounds, from
 * its source points moved (sw_pack_move_control's floats), as the pack
 * writer makes them for the points it stores. */
static void remake_bounds(const sw_pack_move *m, sw_pack_patch *p, const float *src, int bounds)
{
    enum { MAX = SW_BEZIER_MAX_ORDER * SW_BEZIER_MAX_ORDER };
    float moved[4 * MAX];
    double ctrl[4 * MAX];
    size_t points = (size_t)(p->degree_u + 1) * (p->degree_v + 1);
    sw_pack_move_control(m, src, (uint32_t)points, moved);
    for (size_t k = 0; k < 4 * points; k++)
        ctrl[k] = moved[k];
    sw_bezier_patch view = { p->degree_u, p->degree_v, (p->flags & SW_PATCH_RATIONAL) != 0,
                             ctrl };
    sw_box box = sw_bezier_control_box(&view);
    const double lo[3] = { box.min.x, box.min.y, box.min.z };
    const double hi[3] = { box.max.x, box.max.y, box.max.z };
    sw_deriv_bounds d2;
    int bounded = bounds && sw_bezier_second_deriv_bounds(&view, &d2, NULL) == SW_OK;
    const double bound[3] = { bounded ? d2.uu : 0, bounded ? d2.uv : 0, bounded ? d2.vv : 0 };
    for (int k = 0; k < 3; k++) {
        p->box_min[k] = (float)lo[k];
        p->box_max[k] = (float)hi[k];
        p->d2_bound[k] = bounded ? float_up(bound[k]) : INFINITY;
    }
}

void sw_pack_move_patches(const sw_pack_move *m, const sw_pack_patch *src, uint32_t n,
                          const float *src_control, int bounds, sw_pack_patch *dst)
{
    for (uint32_t i = 0; i < n; i++) {
        dst[i] = src[i];
        dst[i].first_control = shifted(m, SW_SPACE_CONTROL, src[i].first_control);
        dst[i].part = shifted(m, SW_SPACE_PARTS, src[i].part);
        if (m->transform)
            remake_bounds(m, &dst[i], src_control + 4 * (size_t)src[i].first_control, bounds);
    }
}

void sw_pack_move_adjacency(const sw_pack_move *m, const sw_pack_adjacency *src, uint32_t n,
                            sw_pack_adjacency *dst)
{
    for (uint32_t i = 0; i < n; i++) {
        dst[i] = src[i];
        dst[i].patch_a = shifted(m, SW_SPACE_PATCHES, src[i].patch_a);
        dst[i].patch_b = shifted(m, SW_SPACE_PATCHES, src[i].patch_b);
    }
}

void sw_pack_move_surfaces(const sw_pack_move *m, const sw_pack_surface *src, uint32_t n,
                           sw_pack_surface *dst)
{
    for (uint32_t i = 0; i < n; i++) {
        dst[i] = src[i];
        dst[i].part = shifted(m, SW_SPACE_PARTS, src[i].part);
        dst[i].first_patch = shifted(m, SW_SPACE_PATCHES, src[i].first_patch);
        dst[i].first_loop = shifted(m, SW_SPACE_TRIM_LOOPS, src[i].first_loop);
    }
}

void sw_pack_move_trim_loops(const sw_pack_move *m, const sw_pack_trim_loop *src, uint32_t n,
                             sw_pack_trim_loop *dst)
{
    for (uint32_t i = 0; i < n; i++) {
        dst[i] = src[i];
        dst[i].first_curve = shifted(m, SW_SPACE_TRIM_CURVES, src[i].first_curve);
    }
}

void sw_pack_move_trim_curves(const sw_pack_move *m, const sw_pack_trim_curve *src, uint32_t n,
                              sw_pack_trim_curve *dst)
{
    for (uint32_t i = 0; i < n; i++) {
        dst[i] = src[i];
        dst[i].first_float = shifted(m, SW_SPACE_TRIM_DATA, src[i].first_float);
    }
}

void sw_pack_move_patch_domains(const sw_pack_move *m, const sw_pack_patch_domain *src,
                                uint32_t n, sw_pack_patch_domain *dst)
{
    for (uint32_t i = 0; i < n; i++) {
        dst[i] = src[i];
        dst[i].surface = shifted(m, SW_SPACE_SURFACES, src[i].surface);
        if (src[i].mask != SW_MASK_NONE)
            dst[i].mask = shifted(m, SW_SPACE_TRIM_MASKS, src[i].mask);
    }
}

void sw_pack_move_seam_vertices(const sw_pack_move *m, const sw_seam_vertex *src, uint32_t n,
                                sw_seam_vertex *dst)
{
    for (uint32_t i = 0; i < n; i++) {
        dst[i] = src[i];
        place(m, src[i].p, dst[i].p);
        dst[i].child = sw_pack_move_vertex(m, src[i].child);
        dst[i].error = length(m, src[i].error);
        if (src[i].slot_ref_count > 0)
            dst[i].first_slot_ref = shifted(m, SW_SPACE_SEAM_SLOT_REFS, src[i].first_slot_ref);
    }
}

void sw_pack_move_seam_slots(const sw_pack_move *m, const sw_seam_slot *src, uint32_t n,
                             sw_seam_slot *dst)
{
    for (uint32_t i = 0; i < n; i++) {
        dst[i] = src[i];
        dst[i].vertex = sw_pack_move_vertex(m, src[i].vertex);
    }
}

void sw_pack_move_seam_loops(const sw_pack_move *m, const sw_seam_loop *src, uint32_t n,
                             sw_seam_loop *dst)
{
    for (uint32_t i = 0; i < n; i++) {
        dst[i] = src[i];
        dst[i].surface = shifted(m, SW_SPACE_SURFACES, src[i].surface);
        dst[i].first_slot = shifted(m, SW_SPACE_SEAM_SLOTS, src[i].first_slot);
    }
}

void sw_pack_move_seam_edges(const sw_pack_move *m, const sw_seam_edge *src, uint32_t n,
                             sw_seam_edge *dst)
{
    for (uint32_t i = 0; i < n; i++) {
        dst[i].a = sw_pack_move_vertex(m, src[i].a);
        dst[i].b = sw_pack_move_vertex(m, src[i].b);
    }
}

void sw_pack_move_seam_collapses(const sw_pack_move *m, const sw_seam_collapse *src, uint32_t n,
                                 sw_seam_collapse *dst)
{
    for (uint32_t i = 0; i < n; i++) {
        dst[i].v1 = sw_pack_move_vertex(m, src[i].v1);
        dst[i].v2 = sw_pack_move_vertex(m, src[i].v2);
        dst[i].error = length(m, src[i].error);
    }
}

void sw_pack_move_indices(const sw_pack_move *m, int space, const uint32_t *src, uint32_t n,
                          uint32_t *dst)
{
    for (uint32_t i = 0; i < n; i++)
        dst[i] = shifted(m, space, src[i]);
}

void sw_pack_move_levels(const sw_pack_move *m, const sw_level *src, uint32_t n, sw_level *dst)
{
    for (uint32_t i = 0; i < n; i++) {
        dst[i] = src[i];
        dst[i].surface = shifted(m, SW_SPACE_SURFACES, src[i].surface);
        dst[i].first_vertex = shifted(m, SW_SPACE_LEVEL_VERTICES, src[i].first_vertex);
        dst[i].first_index = shifted(m, SW_SPACE_LEVEL_INDICES, src[i].first_index);
        dst[i].first_chain = shifted(m, SW_SPACE_LEVEL_CHAINS, src[i].first_chain);
        dst[i].error = length(m, src[i].error);
        dst[i].made_bound = length(m, src[i].made_bound);
    }
}

static int8_t snorm8(double x)
{
    double c = x < -1.0 ? -1.0 : x > 1.0 ? 1.0 : x;
    return (int8_t)lrint(c * 127.0);
}

void sw_pack_move_level_vertices(const sw_pack_move *m, const sw_level_vertex *src, uint32_t n,
                                 sw_level_vertex *dst)
{
    for (uint32_t i = 0; i < n; i++) {
        dst[i] = src[i];
        if (!m->transform)
            continue;
        place(m, src[i].p, dst[i].p);
        const double d[3] = { src[i].normal[0] / 127.0, src[i].normal[1] / 127.0,
                              src[i].normal[2] / 127.0 };
        double out[3];
        turn(m->transform, d, out);
        for (int k = 0; k < 3; k++)
            dst[i].normal[k] = snorm8(out[k]);
    }
}

void sw_pack_move_level_chains(const sw_pack_move *m, const sw_level_chain *src, uint32_t n,
                               sw_level_chain *dst)
{
    for (uint32_t i = 0; i < n; i++) {
        dst[i] = src[i];
        dst[i].first_point = shifted(m, SW_SPACE_LEVEL_CHAIN_POINTS, src[i].first_point);
    }
}

void sw_pack_move_supers(const sw_pack_move *m, const sw_super_surface *src, uint32_t n,
                         sw_super_surface *dst)
{
    for (uint32_t i = 0; i < n; i++) {
        dst[i] = src[i];
        dst[i].first_member = shifted(m, SW_SPACE_SUPER_MEMBERS, src[i].first_member);
        dst[i].part = shifted(m, SW_SPACE_PARTS, src[i].part);
        if (m->transform && src[i].span < SW_SUPER_SPAN_FULL) {
            const double d[3] = { src[i].axis[0], src[i].axis[1], src[i].axis[2] };
            double out[3];
            turn(m->transform, d, out);
            for (int k = 0; k < 3; k++)
                dst[i].axis[k] = (float)out[k];
            /* the turned axis is rounded to floats: the cone widens by more
             * than that, so it still holds every turned normal */
            dst[i].span = src[i].span + 1e-5f;
        }
    }
}

void sw_pack_move_part_levels(const sw_pack_move *m, const sw_part_level *src, uint32_t n,
                              sw_part_level *dst)
{
    for (uint32_t i = 0; i < n; i++) {
        dst[i] = src[i];
        dst[i].piece = shifted(m, SW_SPACE_PIECES, src[i].piece);
        dst[i].first_vertex = shifted(m, SW_SPACE_PART_LEVEL_VERTICES, src[i].first_vertex);
        dst[i].first_index = shifted(m, SW_SPACE_PART_LEVEL_INDICES, src[i].first_index);
        dst[i].error = length(m, src[i].error);
        dst[i].shading_side = length(m, src[i].shading_side);
    }
}
