/* SPDX-License-Identifier: MIT */
/* PROTOTYPES and INSTANCES (sw_pack_instances.h), found, mapped and checked
 * once at load, after every other section. Rules: assets/PACK_FORMAT.md,
 * "Prototypes and instances". Allocates nothing: each space is walked once
 * in order with the prototype that owns the record in hand. */
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "sw_pack_instances.h"
#include "sw_pack_validate.h"

_Static_assert(sizeof(sw_pack_prototype) == 216, "sw_pack_prototype");
_Static_assert(offsetof(sw_pack_prototype, seam_tolerance) == 208, "sw_pack_prototype.tolerance");
_Static_assert(sizeof(sw_pack_instance) == 144, "sw_pack_instance");
_Static_assert(offsetof(sw_pack_instance, color) == 8, "sw_pack_instance.color");
_Static_assert(offsetof(sw_pack_instance, transform) == 24, "sw_pack_instance.transform");
_Static_assert(offsetof(sw_pack_instance, name) == 88, "sw_pack_instance.name");

static const char *const space_names[SW_SPACE_COUNT] = {
    "parts", "patches", "control points", "adjacency", "surfaces", "trim loops", "trim curves",
    "trim data", "trim masks", "seam originals", "seam collapses", "seam slots", "seam loops",
    "seam edges", "seam slot refs", "levels", "level vertices", "level indices", "level chains",
    "level chain points", "super-surfaces", "super members", "pieces", "part levels",
    "part level vertices", "part level indices" };

static sw_status check_tiling(const sw_pack *pack, sw_error *err)
{
    uint64_t total[SW_SPACE_COUNT];
    sw_pack_space_counts(pack, total);
    for (uint32_t k = 0; k < pack->prototype_count; k++) {
        const sw_pack_prototype *p = &pack->prototypes[k];
        if (p->count[SW_SPACE_PARTS] == 0)
            return sw_error_set(err, SW_ERR_FORMAT, "PROTOTYPES[%u]: no part, expected at "
                                "least one", (unsigned)k);
        if (!(p->seam_tolerance >= 0 && p->seam_tolerance <= pack->seam.tolerance) ||
            p->reserved != 0)
            return sw_error_set(err, SW_ERR_FORMAT, "PROTOTYPES[%u]: seam_tolerance %g, "
                                "reserved %u; expected 0 to the SEAM record's %g, and 0",
                                (unsigned)k, (double)p->seam_tolerance, (unsigned)p->reserved,
                                (double)pack->seam.tolerance);
    }
    for (int s = 0; s < SW_SPACE_COUNT; s++) {
        uint64_t next = 0;
        for (uint32_t k = 0; k < pack->prototype_count; k++) {
            const sw_pack_prototype *p = &pack->prototypes[k];
            if (p->first[s] != next)
                return sw_error_set(err, SW_ERR_FORMAT, "PROTOTYPES[%u]: its %s start at %u, "
                                    "expected %llu (the prototypes' runs follow each other)",
                                    (unsigned)k, space_names[s], (unsigned)p->first[s],
                                    (unsigned long long)next);
            next += p->count[s];
        }
        if (next != total[s])
            return sw_error_set(err, SW_ERR_FORMAT, "PROTOTYPES: the runs of %s end at %llu, "
                                "expected %llu (each record in one prototype)", space_names[s],
                                (unsigned long long)next, (unsigned long long)total[s]);
    }
    return SW_OK;
}

/* The prototype holding record i of a space, records taken in order. */
typedef struct owner {
    const sw_pack *pack;
    int space;
    uint32_t k;
} owner;

static const sw_pack_prototype *owner_of(owner *o, uint64_t i)
{
    const sw_pack_prototype *p = o->pack->prototypes;
    while (o->k + 1 < o->pack->prototype_count &&
           i >= (uint64_t)p[o->k].first[o->space] + p[o->k].count[o->space])
        o->k++;
    return &p[o->k];
}

static int inside(const sw_pack_prototype *p, int space, uint64_t first, uint64_t n)
{
    return first >= p->first[space] && first + n <= (uint64_t)p->first[space] + p->count[space];
}

/* Record i of the walked space refers to first .. first + n of space: it
 * must stay in the owner's run. */
static sw_status refer(owner *o, uint64_t i, const char *field, int space, uint64_t first,
                       uint64_t n, sw_error *err)
{
    const sw_pack_prototype *p = owner_of(o, i);
    if (inside(p, space, first, n))
        return SW_OK;
    return sw_error_set(err, SW_ERR_RANGE, "%s of prototype %u's %s record %llu: %llu + %llu, "
                        "expected within its own %s %u + %u", field, (unsigned)o->k,
                        space_names[o->space], (unsigned long long)i,
                        (unsigned long long)first, (unsigned long long)n, space_names[space],
                        (unsigned)p->first[space], (unsigned)p->count[space]);
}

/* A seam vertex reference, original or created. */
static sw_status refer_vertex(owner *o, uint64_t i, const char *field, uint32_t v, sw_error *err)
{
    uint32_t originals = o->pack->seam.original_count;
    if (v == SW_SEAM_NONE)
        return SW_OK;
    return v < originals ? refer(o, i, field, SW_SPACE_SEAM_ORIGINALS, v, 1, err)
                         : refer(o, i, field, SW_SPACE_SEAM_COLLAPSES, v - originals, 1, err);
}

/* A "+1" array's entries a[s], a[s + 1] for record s: within the owner's run
 * of space, its end included. */
static sw_status refer_bounds(owner *o, uint64_t s, const char *field, int space,
                              const uint32_t *a, sw_error *err)
{
    return refer(o, s, field, space, a[s], a[s + 1] - a[s], err);
}

static sw_status check_model(const sw_pack *pack, sw_error *err)
{
    sw_status st = SW_OK;
    owner o = { pack, SW_SPACE_PARTS, 0 };
    for (uint32_t i = 0; st == SW_OK && i < pack->meta->part_count; i++)
        st = refer(&o, i, "first_patch", SW_SPACE_PATCHES, pack->parts[i].first_patch,
                   pack->parts[i].patch_count, err);
    o = (owner){ pack, SW_SPACE_PATCHES, 0 };
    for (uint32_t i = 0; st == SW_OK && i < pack->meta->patch_count; i++) {
        const sw_pack_patch *p = &pack->patches[i];
        st = refer(&o, i, "part", SW_SPACE_PARTS, p->part, 1, err);
        if (st == SW_OK)
            st = refer(&o, i, "first_control", SW_SPACE_CONTROL, p->first_control,
                       (uint64_t)(p->degree_u + 1) * (p->degree_v + 1), err);
        const sw_pack_patch_domain *d = pack->patch_domains ? &pack->patch_domains[i] : NULL;
        if (st == SW_OK && d)
            st = refer(&o, i, "PATCH_DOMAINS.surface", SW_SPACE_SURFACES, d->surface, 1, err);
        if (st == SW_OK && d && d->mask != SW_MASK_NONE)
            st = refer(&o, i, "PATCH_DOMAINS.mask", SW_SPACE_TRIM_MASKS, d->mask, 1, err);
    }
    o = (owner){ pack, SW_SPACE_ADJACENCY, 0 };
    for (uint32_t i = 0; st == SW_OK && i < pack->meta->adjacency_count; i++) {
        st = refer(&o, i, "patch_a", SW_SPACE_PATCHES, pack->adjacency[i].patch_a, 1, err);
        if (st == SW_OK)
            st = refer(&o, i, "patch_b", SW_SPACE_PATCHES, pack->adjacency[i].patch_b, 1, err);
    }
    return st;
}

static sw_status check_surfaces(const sw_pack *pack, sw_error *err)
{
    sw_status st = SW_OK;
    owner o = { pack, SW_SPACE_SURFACES, 0 };
    for (uint32_t s = 0; st == SW_OK && s < pack->surface_count; s++) {
        const sw_pack_surface *f = &pack->surfaces[s];
        st = refer(&o, s, "part", SW_SPACE_PARTS, f->part, 1, err);
        if (st == SW_OK)
            st = refer(&o, s, "first_patch", SW_SPACE_PATCHES, f->first_patch, f->patch_count,
                       err);
        if (st == SW_OK)
            st = refer(&o, s, "first_loop", SW_SPACE_TRIM_LOOPS, f->first_loop, f->loop_count,
                       err);
        if (st == SW_OK && pack->seam_header)
            st = refer_bounds(&o, s, "SEAM_SURFACE_LOOPS", SW_SPACE_SEAM_LOOPS,
                              pack->seam.surface_loops, err);
        if (st == SW_OK && pack->levels_header)
            st = refer_bounds(&o, s, "LEVEL_SURFACES", SW_SPACE_LEVELS,
                              pack->levels.surface_levels, err);
        if (st == SW_OK && pack->supers.supers)
            st = refer(&o, s, "SUPER_OF", SW_SPACE_SUPERS, pack->supers.super_of[s], 1, err);
        if (st == SW_OK && pack->part_levels.levels)
            st = refer(&o, s, "PART_LEVEL_PIECE_OF", SW_SPACE_PIECES,
                       pack->part_levels.piece_of[s], 1, err);
    }
    o = (owner){ pack, SW_SPACE_TRIM_LOOPS, 0 };
    for (uint32_t i = 0; st == SW_OK && i < pack->trim_loop_count; i++)
        st = refer(&o, i, "first_curve", SW_SPACE_TRIM_CURVES, pack->trim_loops[i].first_curve,
                   pack->trim_loops[i].curve_count, err);
    o = (owner){ pack, SW_SPACE_TRIM_CURVES, 0 };
    for (uint32_t i = 0; st == SW_OK && i < pack->trim_curve_count; i++) {
        const sw_pack_trim_curve *c = &pack->trim_curves[i];
        st = refer(&o, i, "first_float", SW_SPACE_TRIM_DATA, c->first_float,
                   4ull * c->count + c->degree + 1, err);
    }
    return st;
}

static sw_status check_seam(const sw_pack *pack, sw_error *err)
{
    const sw_seam_graph *g = &pack->seam;
    sw_status st = SW_OK;
    owner o = { pack, SW_SPACE_SEAM_ORIGINALS, 0 };
    for (uint32_t v = 0; st == SW_OK && v < g->original_count; v++) {
        st = refer_vertex(&o, v, "child", g->vertices[v].child, err);
        if (st == SW_OK)
            st = refer(&o, v, "first_slot_ref", SW_SPACE_SEAM_SLOT_REFS,
                       g->vertices[v].first_slot_ref, g->vertices[v].slot_ref_count, err);
    }
    o = (owner){ pack, SW_SPACE_SEAM_COLLAPSES, 0 };
    for (uint32_t k = 0; st == SW_OK && k < g->collapse_count; k++) {
        st = refer_vertex(&o, k, "v1", g->collapses[k].v1, err);
        if (st == SW_OK)
            st = refer_vertex(&o, k, "v2", g->collapses[k].v2, err);
        if (st == SW_OK)
            st = refer_vertex(&o, k, "child", g->vertices[g->original_count + k].child, err);
    }
    o = (owner){ pack, SW_SPACE_SEAM_SLOTS, 0 };
    for (uint32_t i = 0; st == SW_OK && i < g->slot_count; i++)
        st = refer(&o, i, "vertex", SW_SPACE_SEAM_ORIGINALS, g->slots[i].vertex, 1, err);
    o = (owner){ pack, SW_SPACE_SEAM_LOOPS, 0 };
    for (uint32_t i = 0; st == SW_OK && i < g->loop_count; i++) {
        st = refer(&o, i, "surface", SW_SPACE_SURFACES, g->loops[i].surface, 1, err);
        if (st == SW_OK)
            st = refer(&o, i, "first_slot", SW_SPACE_SEAM_SLOTS, g->loops[i].first_slot,
                       g->loops[i].slot_count, err);
    }
    o = (owner){ pack, SW_SPACE_SEAM_EDGES, 0 };
    for (uint32_t i = 0; st == SW_OK && i < g->edge_count; i++) {
        st = refer_vertex(&o, i, "a", g->edges[i].a, err);
        if (st == SW_OK)
            st = refer_vertex(&o, i, "b", g->edges[i].b, err);
    }
    o = (owner){ pack, SW_SPACE_SEAM_SLOT_REFS, 0 };
    for (uint32_t i = 0; st == SW_OK && i < g->slot_ref_count; i++)
        st = refer(&o, i, "slot", SW_SPACE_SEAM_SLOTS, g->slot_refs[i], 1, err);
    return st;
}

static sw_status check_levels(const sw_pack *pack, sw_error *err)
{
    const sw_levels *l = &pack->levels;
    sw_status st = SW_OK;
    owner o = { pack, SW_SPACE_LEVELS, 0 };
    for (uint32_t i = 0; st == SW_OK && i < l->level_count; i++) {
        const sw_level *r = &l->levels[i];
        uint32_t loops = pack->seam.surface_loops[r->surface + 1] -
                         pack->seam.surface_loops[r->surface];
        st = refer(&o, i, "surface", SW_SPACE_SURFACES, r->surface, 1, err);
        if (st == SW_OK)
            st = refer(&o, i, "first_vertex", SW_SPACE_LEVEL_VERTICES, r->first_vertex,
                       r->vertex_count, err);
        if (st == SW_OK)
            st = refer(&o, i, "first_index", SW_SPACE_LEVEL_INDICES, r->first_index,
                       r->index_count, err);
        if (st == SW_OK)
            st = refer(&o, i, "first_chain", SW_SPACE_LEVEL_CHAINS, r->first_chain, loops, err);
    }
    o = (owner){ pack, SW_SPACE_LEVEL_CHAINS, 0 };
    for (uint32_t i = 0; st == SW_OK && i < l->chain_count; i++)
        st = refer(&o, i, "first_point", SW_SPACE_LEVEL_CHAIN_POINTS, l->chains[i].first_point,
                   l->chains[i].point_count, err);
    return st;
}

static sw_status check_supers_and_pieces(const sw_pack *pack, sw_error *err)
{
    const sw_supers *su = &pack->supers;
    sw_status st = SW_OK;
    owner o = { pack, SW_SPACE_SUPERS, 0 };
    for (uint32_t i = 0; st == SW_OK && i < su->super_count; i++) {
        st = refer(&o, i, "part", SW_SPACE_PARTS, su->supers[i].part, 1, err);
        if (st == SW_OK)
            st = refer(&o, i, "first_member", SW_SPACE_SUPER_MEMBERS, su->supers[i].first_member,
                       su->supers[i].member_count, err);
    }
    o = (owner){ pack, SW_SPACE_SUPER_MEMBERS, 0 };
    for (uint32_t i = 0; st == SW_OK && su->members && i < pack->surface_count; i++)
        st = refer(&o, i, "surface", SW_SPACE_SURFACES, su->members[i], 1, err);
    const sw_part_levels *pl = &pack->part_levels;
    o = (owner){ pack, SW_SPACE_PIECES, 0 };
    for (uint32_t g = 0; st == SW_OK && g < pl->piece_count; g++)
        st = refer_bounds(&o, g, "PART_LEVEL_RANGES", SW_SPACE_PART_LEVELS, pl->piece_levels,
                          err);
    o = (owner){ pack, SW_SPACE_PART_LEVELS, 0 };
    for (uint32_t i = 0; st == SW_OK && i < pl->level_count; i++) {
        const sw_part_level *r = &pl->levels[i];
        st = refer(&o, i, "piece", SW_SPACE_PIECES, r->piece, 1, err);
        if (st == SW_OK)
            st = refer(&o, i, "first_vertex", SW_SPACE_PART_LEVEL_VERTICES, r->first_vertex,
                       r->vertex_count, err);
        if (st == SW_OK)
            st = refer(&o, i, "first_index", SW_SPACE_PART_LEVEL_INDICES, r->first_index,
                       r->index_count, err);
    }
    return st;
}

/* A rotation, a uniform scale > 0 and a translation: its columns of equal
 * length and at right angles, turning the right way. */
static sw_status check_transform(const float *t, uint32_t i, sw_error *err)
{
    for (int k = 0; k < 16; k++)
        if (!isfinite(t[k]))
            return sw_error_set(err, SW_ERR_FORMAT, "INSTANCES[%u].transform[%d]: %g, expected "
                                "finite", (unsigned)i, k, (double)t[k]);
    if (t[3] != 0 || t[7] != 0 || t[11] != 0 || t[15] != 1)
        return sw_error_set(err, SW_ERR_FORMAT, "INSTANCES[%u].transform: its last row is %g %g "
                            "%g %g, expected 0 0 0 1", (unsigned)i, (double)t[3], (double)t[7],
                            (double)t[11], (double)t[15]);
    double s = sw_instance_scale(t);
    double c[3][3], det;
    for (int a = 0; a < 3; a++)
        for (int r = 0; r < 3; r++)
            c[a][r] = t[4 * a + r];
    det = c[0][0] * (c[1][1] * c[2][2] - c[1][2] * c[2][1]) -
          c[1][0] * (c[0][1] * c[2][2] - c[0][2] * c[2][1]) +
          c[2][0] * (c[0][1] * c[1][2] - c[0][2] * c[1][1]);
    int ok = s > 1e-12 && s < 1e12 && det > 0;
    for (int a = 0; ok && a < 3; a++)
        for (int b = a; b < 3; b++) {
            double dot = c[a][0] * c[b][0] + c[a][1] * c[b][1] + c[a][2] * c[b][2];
            ok = ok && fabs(dot - (a == b ? s * s : 0)) <= 1e-5 * s * s;
        }
    if (!ok)
        return sw_error_set(err, SW_ERR_FORMAT, "INSTANCES[%u].transform: expected a rotation, "
                            "a uniform scale between 1e-12 and 1e12 and a translation (no "
                            "mirror, no shear)", (unsigned)i);
    return SW_OK;
}

/* The larger of m and |x|. Written as a comparison, not fmax: GCC 12's
 * aarch64 vectoriser fails on fmax reductions over these loops (an
 * internal compiler error). A NaN is left out either way. */
static double widen(double m, double x)
{
    x = fabs(x);
    return x > m ? x : m;
}

/* The largest coordinate of any point the expansion moves. */
static double largest_coordinate(const sw_pack *pack)
{
    double m = 0;
    for (uint32_t i = 0; i < pack->meta->patch_count; i++)
        for (int k = 0; k < 3; k++)
            m = widen(widen(m, pack->patches[i].box_min[k]), pack->patches[i].box_max[k]);
    for (uint32_t v = 0; v < pack->seam.vertex_count; v++)
        for (int k = 0; k < 3; k++)
            m = widen(m, pack->seam.vertices[v].p[k]);
    for (uint32_t v = 0; v < pack->levels.vertex_count; v++)
        for (int k = 0; k < 3; k++)
            m = widen(m, pack->levels.vertices[v].p[k]);
    for (uint32_t v = 0; v < pack->part_levels.vertex_count; v++)
        for (int k = 0; k < 3; k++)
            m = widen(m, pack->part_levels.vertices[v].p[k]);
    return m;
}

/* The largest length the expansion scales: errors, bounds, sides. */
static double largest_length(const sw_pack *pack)
{
    double m = widen(0, pack->seam.tolerance);
    for (uint32_t v = 0; v < pack->seam.vertex_count; v++)
        m = widen(m, pack->seam.vertices[v].error);
    for (uint32_t k = 0; k < pack->seam.collapse_count; k++)
        m = widen(m, pack->seam.collapses[k].error);
    for (uint32_t i = 0; i < pack->levels.level_count; i++)
        m = widen(widen(m, pack->levels.levels[i].error), pack->levels.levels[i].made_bound);
    for (uint32_t i = 0; i < pack->part_levels.level_count; i++)
        m = widen(widen(m, pack->part_levels.levels[i].error),
                  pack->part_levels.levels[i].shading_side);
    return m;
}

/* Placed coordinates stay below this, so boxes, distances and their
 * squares stay finite in the walk's floats and doubles. */
#define PLACED_LIMIT 1e18

static sw_status check_instances(const sw_pack *pack, sw_error *err)
{
    if (pack->instance_count == 0)
        return sw_error_set(err, SW_ERR_FORMAT, "INSTANCES: no instance, expected at least one");
    double reach = largest_coordinate(pack) * sqrt(3.0), length = largest_length(pack);
    for (uint32_t i = 0; i < pack->instance_count; i++) {
        const sw_pack_instance *r = &pack->instances[i];
        if (r->prototype >= pack->prototype_count)
            return sw_error_set(err, SW_ERR_RANGE, "INSTANCES[%u].prototype: %u, expected < %u",
                                (unsigned)i, (unsigned)r->prototype,
                                (unsigned)pack->prototype_count);
        if (r->flags != 0)
            return sw_error_set(err, SW_ERR_FORMAT, "INSTANCES[%u].flags: 0x%x, expected 0",
                                (unsigned)i, (unsigned)r->flags);
        for (int k = 0; k < 4; k++)
            if (!(r->color[k] >= 0 && r->color[k] <= 1))
                return sw_error_set(err, SW_ERR_FORMAT, "INSTANCES[%u].color[%d]: %g, expected "
                                    "0..1", (unsigned)i, k, (double)r->color[k]);
        if (!memchr(r->name, 0, sizeof r->name))
            return sw_error_set(err, SW_ERR_FORMAT, "INSTANCES[%u].name: not NUL-terminated "
                                "within %zu bytes", (unsigned)i, sizeof r->name);
        sw_status st = check_transform(r->transform, i, err);
        if (st != SW_OK)
            return st;
        double far = reach * sw_instance_scale(r->transform) +
                     fabs((double)r->transform[12]) + fabs((double)r->transform[13]) +
                     fabs((double)r->transform[14]);
        if (!(far < PLACED_LIMIT))
            return sw_error_set(err, SW_ERR_RANGE, "INSTANCES[%u]: places points up to %g from "
                                "the origin, expected below %g", (unsigned)i, far, PLACED_LIMIT);
        if (!(length * sw_instance_scale(r->transform) < PLACED_LIMIT))
            return sw_error_set(err, SW_ERR_RANGE, "INSTANCES[%u]: scales an error of %g to "
                                "%g, expected below %g", (unsigned)i, length,
                                length * sw_instance_scale(r->transform), PLACED_LIMIT);
    }
    return SW_OK;
}

/* The placed scene's counts fit their indices (SW_SEAM_NONE and the "+1"
 * arrays' ends included), and the header counts its memory. */
static sw_status check_placed(const sw_pack *pack, sw_error *err)
{
    uint64_t counts[SW_SPACE_COUNT];
    sw_pack_placed_counts(pack->prototypes, pack->instances, pack->instance_count, counts);
    if (counts[SW_SPACE_SEAM_ORIGINALS] + counts[SW_SPACE_SEAM_COLLAPSES] >= SW_SEAM_NONE)
        return sw_error_set(err, SW_ERR_RANGE, "INSTANCES: place %llu seam vertices, expected "
                            "fewer than %u", (unsigned long long)(counts[SW_SPACE_SEAM_ORIGINALS] +
                                                             counts[SW_SPACE_SEAM_COLLAPSES]),
                            SW_SEAM_NONE);
    for (int s = 0; s < SW_SPACE_COUNT; s++)
        if (counts[s] >= UINT32_MAX)
            return sw_error_set(err, SW_ERR_RANGE, "INSTANCES: place %llu %s, expected fewer "
                                "than %u", (unsigned long long)counts[s], space_names[s],
                                UINT32_MAX);
    const sw_walk_placed placed = { pack->prototypes, pack->prototype_count, pack->instances,
                                    pack->instance_count, pack->patches };
    uint64_t want = sw_pack_instanced_runtime_bytes(pack->seam_header ? &pack->seam : NULL,
                                                    pack->surfaces, &placed);
    if (pack->header->runtime_bytes < want)
        return sw_error_set(err, SW_ERR_FORMAT, "header.runtime_bytes: %llu, expected at least "
                            "%llu for the placed scene of %u instances (its seamwalk-pack's "
                            "runtime took less than this one: build it again)",
                            (unsigned long long)pack->header->runtime_bytes,
                            (unsigned long long)want, (unsigned)pack->instance_count);
    return SW_OK;
}

static sw_status check_all(const sw_pack *pack, sw_error *err)
{
    sw_status st = check_tiling(pack, err);
    if (st == SW_OK)
        st = check_model(pack, err);
    if (st == SW_OK)
        st = check_surfaces(pack, err);
    if (st == SW_OK && pack->seam_header)
        st = check_seam(pack, err);
    if (st == SW_OK && pack->levels_header)
        st = check_levels(pack, err);
    if (st == SW_OK)
        st = check_supers_and_pieces(pack, err);
    if (st == SW_OK)
        st = check_instances(pack, err);
    return st == SW_OK ? check_placed(pack, err) : st;
}

enum { GROUP = 2 };
static const uint32_t group_types[GROUP] = { SW_SECTION_PROTOTYPES, SW_SECTION_INSTANCES };
static const uint64_t group_records[GROUP] = { sizeof(sw_pack_prototype),
                                               sizeof(sw_pack_instance) };

sw_status sw_pack_map_instances(const uint8_t *data, sw_pack *out, sw_error *err)
{
    int32_t index[GROUP];
    out->prototypes = NULL, out->prototype_count = 0;
    out->instances = NULL, out->instance_count = 0;
    sw_status st = sw_pack_find_group(out, group_types, group_records, GROUP, index, err);
    if (st != SW_OK)
        return st;
    int present = (index[0] >= 0) + (index[1] >= 0);
    int instanced = out->header->version == SW_PACK_VERSION_INSTANCED;
    if (present == 1)
        return sw_error_set(err, SW_ERR_FORMAT, "section table: %s without %s (they appear "
                            "together)", index[0] >= 0 ? "PROTOTYPES" : "INSTANCES",
                            index[0] >= 0 ? "INSTANCES" : "PROTOTYPES");
    if (present == 2 && !instanced)
        return sw_error_set(err, SW_ERR_FORMAT, "header.version: %u with PROTOTYPES and "
                            "INSTANCES, expected %u", (unsigned)out->header->version,
                            SW_PACK_VERSION_INSTANCED);
    if (present == 0 && instanced)
        return sw_error_set(err, SW_ERR_FORMAT, "header.version: %u without PROTOTYPES and "
                            "INSTANCES (version %u is a pack of placed parts)",
                            (unsigned)out->header->version, SW_PACK_VERSION_INSTANCED);
    if (present == 0)
        return SW_OK;
    const sw_pack_section *sec = out->sections;
    out->prototypes = (const sw_pack_prototype *)(data + sec[index[0]].offset);
    out->prototype_count = (uint32_t)(sec[index[0]].size / sizeof(sw_pack_prototype));
    out->instances = (const sw_pack_instance *)(data + sec[index[1]].offset);
    out->instance_count = (uint32_t)(sec[index[1]].size / sizeof(sw_pack_instance));
    if (out->prototype_count == 0)
        st = sw_error_set(err, SW_ERR_FORMAT, "PROTOTYPES: no prototype, expected at least one");
    else
        st = check_all(out, err);
    if (st != SW_OK) {
        out->prototypes = NULL, out->prototype_count = 0;
        out->instances = NULL, out->instance_count = 0;
    }
    return st;
}
