/* SPDX-License-Identifier: MIT */
/* The pack writer: model -> contents (float control points, boxes, second
 * derivative bounds, adjacency), contents -> bytes (header, section table,
 * 64-byte aligned sections, checksums), bytes -> file (atomically). Host only;
 * allocates with malloc. Format: assets/PACK_FORMAT.md. */
#include "sw_pack_write.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <xxhash.h>

#include "sw_pack_adjacency.h"
#include "sw_pack_instances.h"
#include "sw_pack_sections.h"
#include "sw_pack_validate.h"
#include "sw_seam_check.h"
#include "sw_walk_memory.h"

/* Types 1..13 (the first five always written), then the seam group's eight,
 * then ORIENTATION and IMPORT_NOTES, then the levels' seven, then the
 * super-surfaces' three, then the part levels' six, then PROTOTYPES and
 * INSTANCES. */
enum { FIXED_SECTIONS = 5, PLAIN_SECTIONS = 13, SEAM_SECTIONS = 8, LEVEL_SECTIONS = 7,
       SUPER_SECTIONS = 3, PART_LEVEL_SECTIONS = 6, INSTANCE_SECTIONS = 2,
       MAX_SECTIONS = PLAIN_SECTIONS + SEAM_SECTIONS + 2 + LEVEL_SECTIONS + SUPER_SECTIONS +
                      PART_LEVEL_SECTIONS + INSTANCE_SECTIONS,
       HEADER_BYTES = 64, SECTION_BYTES = 32 };

static uint64_t align_up(uint64_t x) { return (x + SW_PACK_ALIGN - 1) / SW_PACK_ALIGN * SW_PACK_ALIGN; }

typedef struct section_source {
    uint32_t type;
    const void *bytes;
    uint64_t size;
} section_source;

/* SEAM's record of g, for the writer to store. */
static sw_pack_seam seam_record(const sw_seam_graph *g)
{
    return (sw_pack_seam){ .vertex_count = g->vertex_count, .original_count = g->original_count,
                           .slot_count = g->slot_count, .loop_count = g->loop_count,
                           .edge_count = g->edge_count, .collapse_count = g->collapse_count,
                           .slot_ref_count = g->slot_ref_count,
                           .surface_count = g->surface_count, .tolerance = g->tolerance };
}

/* The eight seam sections of g (whose record is *record) into src[0..8). */
static void list_seam_sections(const sw_seam_graph *g, const sw_pack_seam *record,
                               section_source src[SEAM_SECTIONS])
{
    const section_source all[SEAM_SECTIONS] = {
        { SW_SECTION_SEAM, record, sizeof *record },
        { SW_SECTION_SEAM_VERTICES, g->vertices,
          (uint64_t)g->vertex_count * sizeof(sw_seam_vertex) },
        { SW_SECTION_SEAM_SLOTS, g->slots, (uint64_t)g->slot_count * sizeof(sw_seam_slot) },
        { SW_SECTION_SEAM_LOOPS, g->loops, (uint64_t)g->loop_count * sizeof(sw_seam_loop) },
        { SW_SECTION_SEAM_EDGES, g->edges, (uint64_t)g->edge_count * sizeof(sw_seam_edge) },
        { SW_SECTION_SEAM_COLLAPSES, g->collapses,
          (uint64_t)g->collapse_count * sizeof(sw_seam_collapse) },
        { SW_SECTION_SEAM_SLOT_REFS, g->slot_refs, (uint64_t)g->slot_ref_count * sizeof(uint32_t) },
        { SW_SECTION_SEAM_SURFACE_LOOPS, g->surface_loops,
          ((uint64_t)g->surface_count + 1) * sizeof(uint32_t) },
    };
    memcpy(src, all, sizeof all);
}

/* LEVELS' record of l, for the writer to store. */
static sw_pack_levels levels_record(const sw_levels *l)
{
    return (sw_pack_levels){ .level_count = l->level_count, .vertex_count = l->vertex_count,
                             .index_count = l->index_count, .chain_count = l->chain_count,
                             .chain_point_count = l->chain_point_count,
                             .surface_count = l->surface_count };
}

/* The seven level sections of l (whose record is *record) into src[0..7).
 * LEVEL_INDICES may be any even size: the next section starts at the next
 * multiple of 64 as always. */
static void list_level_sections(const sw_levels *l, const sw_pack_levels *record,
                                section_source src[LEVEL_SECTIONS])
{
    const section_source all[LEVEL_SECTIONS] = {
        { SW_SECTION_LEVELS, record, sizeof *record },
        { SW_SECTION_LEVEL_RECORDS, l->levels, (uint64_t)l->level_count * sizeof(sw_level) },
        { SW_SECTION_LEVEL_SURFACES, l->surface_levels,
          ((uint64_t)l->surface_count + 1) * sizeof(uint32_t) },
        { SW_SECTION_LEVEL_VERTICES, l->vertices,
          (uint64_t)l->vertex_count * sizeof(sw_level_vertex) },
        { SW_SECTION_LEVEL_INDICES, l->indices, (uint64_t)l->index_count * sizeof(uint16_t) },
        { SW_SECTION_LEVEL_CHAINS, l->chains, (uint64_t)l->chain_count * sizeof(sw_level_chain) },
        { SW_SECTION_LEVEL_CHAIN_POINTS, l->chain_points,
          (uint64_t)l->chain_point_count * sizeof(sw_strip_point) },
    };
    memcpy(src, all, sizeof all);
}

/* The sections contents asks for, in the order they are written: the five
 * of the walking skeleton always, each optional one when its array is set,
 * the seam group when there is a graph (seam_rec holds its SEAM record), the
 * level group when there are levels (levels_rec holds their LEVELS record),
 * the super-surfaces' group when there are clusters. */
static int list_sections(const sw_pack_contents *c, sw_pack_seam *seam_rec,
                         sw_pack_levels *levels_rec, sw_pack_part_levels *parts_rec,
                         section_source src[MAX_SECTIONS])
{
    const sw_pack_meta *m = &c->meta;
    const section_source all[PLAIN_SECTIONS] = {
        { SW_SECTION_META, m, sizeof *m },
        { SW_SECTION_PARTS, c->parts, (uint64_t)m->part_count * sizeof(sw_pack_part) },
        { SW_SECTION_PATCHES, c->patches, (uint64_t)m->patch_count * sizeof(sw_pack_patch) },
        { SW_SECTION_CONTROL, c->control, (uint64_t)m->control_count * 4 * sizeof(float) },
        { SW_SECTION_ADJACENCY, c->adjacency,
          (uint64_t)m->adjacency_count * sizeof(sw_pack_adjacency) },
        { SW_SECTION_SURFACES, c->surfaces, (uint64_t)c->surface_count * sizeof(sw_pack_surface) },
        { SW_SECTION_TRIM_LOOPS, c->trim_loops,
          (uint64_t)c->trim_loop_count * sizeof(sw_pack_trim_loop) },
        { SW_SECTION_TRIM_CURVES, c->trim_curves,
          (uint64_t)c->trim_curve_count * sizeof(sw_pack_trim_curve) },
        { SW_SECTION_TRIM_DATA, c->trim_data, (uint64_t)c->trim_data_count * sizeof(float) },
        { SW_SECTION_PATCH_DOMAINS, c->patch_domains,
          (uint64_t)m->patch_count * sizeof(sw_pack_patch_domain) },
        { SW_SECTION_TRIM_MASKS, c->trim_masks,
          (uint64_t)c->trim_mask_count * sizeof(sw_pack_trim_mask) },
        { SW_SECTION_VIEWPOINTS, c->viewpoints,
          (uint64_t)c->viewpoint_count * sizeof(sw_pack_viewpoint) },
        { SW_SECTION_PART_TRANSFORMS, c->part_transforms,
          (uint64_t)m->part_count * 16 * sizeof(float) },
    };
    int n = 0;
    for (int i = 0; i < PLAIN_SECTIONS; i++)
        if (i < FIXED_SECTIONS || all[i].bytes)
            src[n++] = all[i];
    if (c->seam) {
        *seam_rec = seam_record(c->seam);
        list_seam_sections(c->seam, seam_rec, &src[n]);
        n += SEAM_SECTIONS;
    }
    if (c->orientation)
        src[n++] = (section_source){ SW_SECTION_ORIENTATION, c->orientation,
                                     sizeof *c->orientation };
    if (c->import_notes)
        src[n++] = (section_source){ SW_SECTION_IMPORT_NOTES, c->import_notes,
                                     (size_t)c->import_note_count * sizeof *c->import_notes };
    if (c->levels) {
        *levels_rec = levels_record(c->levels);
        list_level_sections(c->levels, levels_rec, &src[n]);
        n += LEVEL_SECTIONS;
    }
    if (c->supers) {
        const sw_supers *sp = c->supers;
        uint64_t list = (uint64_t)sp->surface_count * sizeof(uint32_t);
        src[n++] = (section_source){ SW_SECTION_SUPER_SURFACES, sp->supers,
                                     (uint64_t)sp->super_count * sizeof(sw_super_surface) };
        src[n++] = (section_source){ SW_SECTION_SUPER_MEMBERS, sp->members, list };
        src[n++] = (section_source){ SW_SECTION_SUPER_OF, sp->super_of, list };
    }
    if (c->part_levels) {
        const sw_part_levels *pl = c->part_levels;
        *parts_rec = (sw_pack_part_levels){ pl->level_count, pl->vertex_count, pl->index_count,
                                            pl->piece_count };
        src[n++] = (section_source){ SW_SECTION_PART_LEVELS, parts_rec, sizeof *parts_rec };
        src[n++] = (section_source){ SW_SECTION_PART_LEVEL_RECORDS, pl->levels,
                                     (uint64_t)pl->level_count * sizeof(sw_part_level) };
        src[n++] = (section_source){ SW_SECTION_PART_LEVEL_RANGES, pl->piece_levels,
                                     ((uint64_t)pl->piece_count + 1) * sizeof(uint32_t) };
        src[n++] = (section_source){ SW_SECTION_PART_LEVEL_VERTICES, pl->vertices,
                                     (uint64_t)pl->vertex_count * sizeof(sw_level_vertex) };
        src[n++] = (section_source){ SW_SECTION_PART_LEVEL_INDICES, pl->indices,
                                     (uint64_t)pl->index_count * sizeof(uint16_t) };
        src[n++] = (section_source){ SW_SECTION_PART_LEVEL_PIECE_OF, pl->piece_of,
                                     (uint64_t)pl->surface_count * sizeof(uint32_t) };
    }
    if (c->instances) {
        src[n++] = (section_source){ SW_SECTION_PROTOTYPES, c->prototypes,
                                     (uint64_t)c->prototype_count * sizeof(sw_pack_prototype) };
        src[n++] = (section_source){ SW_SECTION_INSTANCES, c->instances,
                                     (uint64_t)c->instance_count * sizeof(sw_pack_instance) };
    }
    return n;
}

/* Places the sections after the table, each at the next multiple of 64;
 * returns the file size. */
static sw_status lay_out(const section_source *src, int n, sw_pack_section *table,
                         uint64_t *total, sw_error *err)
{
    uint64_t cursor = HEADER_BYTES + (uint64_t)n * SECTION_BYTES;
    for (int i = 0; i < n; i++) {
        if (src[i].size > 0 && !src[i].bytes)
            return sw_error_set(err, SW_ERR_ARG, "sw_pack_serialize: the counts give %llu bytes "
                                "of %s but the array is NULL", (unsigned long long)src[i].size,
                                sw_section_type_name(src[i].type));
        cursor = align_up(cursor);
        table[i] = (sw_pack_section){ .type = src[i].type, .offset = cursor, .size = src[i].size,
                                      .checksum = XXH3_64bits(src[i].bytes ? src[i].bytes : "",
                                                              (size_t)src[i].size) };
        cursor += src[i].size;
    }
    if (cursor > SIZE_MAX)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "sw_pack_serialize: %llu bytes",
                            (unsigned long long)cursor);
    *total = cursor;
    return SW_OK;
}

/* The walk's share of runtime_bytes; 0 for a graph that does not check
 * (the reader refuses such a pack for its graph before it sizes a walk). */
static uint64_t walk_bytes(const sw_pack_contents *c)
{
    if (c->instances)
        return 0; /* sw_pack_instanced_runtime_bytes counts the placed scene's */
    if (!c->seam || c->seam->surface_count != c->surface_count ||
        sw_seam_graph_check(c->seam, NULL) != SW_OK)
        return 0;
    return sw_walk_arena_bytes(c->seam, c->surfaces);
}

/* The header's runtime_bytes: of the pack, or of its placed scene. */
static uint64_t runtime_bytes(const sw_pack_contents *c)
{
    if (!c->instances)
        return sw_pack_runtime_bytes(walk_bytes(c));
    for (uint32_t i = 0; i < c->instance_count; i++)
        if (c->instances[i].prototype >= c->prototype_count)
            return 0; /* the reader refuses the instance first */
    int graph = c->seam && c->seam->surface_count == c->surface_count &&
                sw_seam_graph_check(c->seam, NULL) == SW_OK;
    const sw_walk_placed placed = { c->prototypes, c->prototype_count, c->instances,
                                    c->instance_count, c->patches };
    return sw_pack_instanced_runtime_bytes(graph ? c->seam : NULL, c->surfaces, &placed);
}

sw_status sw_pack_serialize(const sw_pack_contents *c, uint8_t **out, size_t *out_size,
                            sw_error *err)
{
    *out = NULL;
    *out_size = 0;
    section_source src[MAX_SECTIONS];
    sw_pack_section table[MAX_SECTIONS];
    sw_pack_seam seam_rec;
    sw_pack_levels levels_rec;
    sw_pack_part_levels parts_rec;
    int n = list_sections(c, &seam_rec, &levels_rec, &parts_rec, src);
    uint64_t total = 0;
    sw_status s = lay_out(src, n, table, &total, err);
    if (s != SW_OK)
        return s;
    uint8_t *buf = calloc(1, (size_t)total); /* zero padding between sections */
    if (!buf)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "sw_pack_serialize: cannot allocate %llu "
                            "bytes", (unsigned long long)total);
    for (int i = 0; i < n; i++)
        if (src[i].size > 0)
            memcpy(buf + table[i].offset, src[i].bytes, (size_t)src[i].size);
    sw_pack_header h = { .version = c->instances ? SW_PACK_VERSION_INSTANCED : SW_PACK_VERSION,
                         .byte_order = SW_PACK_BYTE_ORDER_MARK, .total_size = total,
                         .runtime_bytes = runtime_bytes(c),
                         .section_count = (uint32_t)n, .section_table_offset = HEADER_BYTES };
    memcpy(h.magic, SW_PACK_MAGIC, sizeof h.magic);
    memcpy(buf, &h, sizeof h);
    size_t table_bytes = (size_t)n * SECTION_BYTES;
    memcpy(buf + HEADER_BYTES, table, table_bytes);
    /* header_checksum is still 0 in buf, and the table follows the header. */
    h.header_checksum = XXH3_64bits(buf, HEADER_BYTES + table_bytes);
    memcpy(buf, &h, sizeof h);
    *out = buf;
    *out_size = (size_t)total;
    return SW_OK;
}

static sw_status convert_parts(const sw_model *model, sw_pack_part *parts, sw_error *err)
{
    for (size_t i = 0; i < model->part_count; i++) {
        const sw_model_part *mp = &model->parts[i];
        if (mp->first_patch > UINT32_MAX || mp->patch_count > UINT32_MAX - mp->first_patch)
            return sw_error_set(err, SW_ERR_RANGE, "part %zu: patches %zu..+%zu out of range", i,
                                mp->first_patch, mp->patch_count);
        parts[i].first_patch = (uint32_t)mp->first_patch;
        parts[i].patch_count = (uint32_t)mp->patch_count;
        for (int k = 0; k < 4; k++) {
            float c = mp->color[k];
            parts[i].color[k] = c >= 0.0f ? (c <= 1.0f ? c : 1.0f) : 0.0f; /* NaN -> 0 */
        }
        sw_pack_copy_name(parts[i].name, sizeof parts[i].name, mp->name);
    }
    return SW_OK;
}

/* The float nearest d that is not below it: bounds must stay bounds. */
static float float_up(double d)
{
    float f = (float)d;
    return (double)f < d ? nextafterf(f, INFINITY) : f;
}

/* Rounds one patch's control points to float into pack_ctrl (4 per point) and
 * exact_out (the same values as doubles), so the box and derivative bounds
 * describe the surface the runtime will evaluate. */
static sw_status convert_control(const sw_model_patch *mp, size_t index, float *pack_ctrl,
                                 double *exact_out, sw_error *err)
{
    size_t points = (size_t)(mp->degree_u + 1) * (size_t)(mp->degree_v + 1);
    for (size_t k = 0; k < points * 4; k++) {
        double d = (k % 4 == 3 && !mp->rational) ? 1.0 : mp->ctrl[k];
        float f = (float)d;
        if (!isfinite(f))
            return sw_error_set(err, SW_ERR_RANGE, "patch %zu: control point %zu.%c = %g is "
                                "not a finite float", index, k / 4, "xyzw"[k % 4], d);
        if (k % 4 == 3 && !(f > 0.0f))
            return sw_error_set(err, SW_ERR_RANGE, "patch %zu: control point %zu has weight %g, "
                                "expected > 0 as a float", index, k / 4, d);
        pack_ctrl[k] = f;
        exact_out[k] = f;
    }
    return SW_OK;
}

static sw_status convert_patch(const sw_model *model, size_t i, uint32_t first_control,
                               sw_pack_patch *pp, float *pack_ctrl, sw_error *err)
{
    const sw_model_patch *mp = &model->patches[i];
    double exact[SW_BEZIER_MAX_ORDER * SW_BEZIER_MAX_ORDER * 4];
    sw_status s = convert_control(mp, i, pack_ctrl, exact, err);
    if (s != SW_OK)
        return s;
    sw_bezier_patch view = { mp->degree_u, mp->degree_v, mp->rational != 0, exact };
    sw_deriv_bounds d2;
    if ((s = sw_bezier_second_deriv_bounds(&view, &d2, err)) != SW_OK) {
        sw_error_prefix(err, "patch %zu", i);
        return s;
    }
    sw_box box = sw_bezier_control_box(&view);
    *pp = (sw_pack_patch){ .first_control = first_control, .degree_u = (uint8_t)mp->degree_u,
                           .degree_v = (uint8_t)mp->degree_v,
                           .flags = mp->rational ? SW_PATCH_RATIONAL : 0,
                           .part = (uint32_t)mp->part };
    /* Exact: the box corners are control coordinates, already floats. */
    const double lo[3] = { box.min.x, box.min.y, box.min.z }, hi[3] = { box.max.x, box.max.y,
                                                                          box.max.z };
    const double bound[3] = { d2.uu, d2.uv, d2.vv };
    for (int k = 0; k < 3; k++) {
        pp->box_min[k] = (float)lo[k];
        pp->box_max[k] = (float)hi[k];
        pp->d2_bound[k] = float_up(bound[k]);
        if (!isfinite(pp->d2_bound[k]))
            return sw_error_set(err, SW_ERR_RANGE, "patch %zu: second derivative bound %g does "
                                "not fit a float", i, bound[k]);
    }
    return SW_OK;
}

/* Checks what the pack format cannot hold and counts control points. */
static sw_status check_model(const sw_model *model, uint64_t *control_count, sw_error *err)
{
    if (model->part_count > UINT32_MAX || model->patch_count > UINT32_MAX)
        return sw_error_set(err, SW_ERR_RANGE, "model: %zu parts, %zu patches; a pack holds at "
                            "most %u of each", model->part_count, model->patch_count, UINT32_MAX);
    uint64_t total = 0;
    for (size_t i = 0; i < model->patch_count; i++) {
        const sw_model_patch *p = &model->patches[i];
        if (p->degree_u < 1 || p->degree_u > SW_BEZIER_MAX_DEGREE || p->degree_v < 1 ||
            p->degree_v > SW_BEZIER_MAX_DEGREE)
            return sw_error_set(err, SW_ERR_UNSUPPORTED, "patch %zu: degree %d x %d, a pack "
                                "holds 1..%d", i, p->degree_u, p->degree_v, SW_BEZIER_MAX_DEGREE);
        if (p->part >= model->part_count)
            return sw_error_set(err, SW_ERR_RANGE, "patch %zu: part %zu of %zu", i, p->part,
                                model->part_count);
        /* The reader requires it; say so here, where the cause is visible. */
        const sw_model_part *part = &model->parts[p->part];
        if (i < part->first_patch || i - part->first_patch >= part->patch_count)
            return sw_error_set(err, SW_ERR_RANGE, "patch %zu: outside its part %zu (patches "
                                "%zu..+%zu)", i, p->part, part->first_patch, part->patch_count);
        total += (uint64_t)(p->degree_u + 1) * (uint64_t)(p->degree_v + 1);
    }
    if (total > UINT32_MAX)
        return sw_error_set(err, SW_ERR_RANGE, "model: %llu control points; a pack holds at "
                            "most %u", (unsigned long long)total, UINT32_MAX);
    *control_count = total;
    return SW_OK;
}

static void add_box(sw_pack_meta *m, const sw_pack_patch *p, int first)
{
    for (int k = 0; k < 3; k++) {
        m->box_min[k] = first || p->box_min[k] < m->box_min[k] ? p->box_min[k] : m->box_min[k];
        m->box_max[k] = first || p->box_max[k] > m->box_max[k] ? p->box_max[k] : m->box_max[k];
    }
}

/* Reports progress of a stage, if anyone listens. */
static void report(const sw_pack_progress *progress, const char *stage, double fraction)
{
    if (progress && progress->fn)
        progress->fn(progress->user, stage, fraction);
}

static sw_status fill_contents(const sw_model *model, sw_pack_part *parts, sw_pack_patch *patches,
                               float *control, sw_pack_meta *m,
                               const sw_pack_progress *progress, sw_error *err)
{
    sw_status s = convert_parts(model, parts, err);
    uint32_t next = 0;
    for (size_t i = 0; s == SW_OK && i < model->patch_count; i++) {
        if (i % 4096 == 0) /* a few hundred microseconds of work between reports */
            report(progress, "patches", (double)i / (double)model->patch_count);
        s = convert_patch(model, i, next, &patches[i], control + (size_t)next * 4, err);
        next += (uint32_t)(model->patches[i].degree_u + 1) * (uint32_t)(model->patches[i].degree_v + 1);
        if (s == SW_OK)
            add_box(m, &patches[i], i == 0);
    }
    return s;
}

sw_status sw_pack_contents_from_model(const sw_model *model, sw_pack_contents *out, sw_error *err)
{
    return sw_pack_contents_from_model_progress(model, NULL, out, err);
}

sw_status sw_pack_contents_from_model_progress(const sw_model *model,
                                               const sw_pack_progress *progress,
                                               sw_pack_contents *out, sw_error *err)
{
    memset(out, 0, sizeof *out);
    uint64_t control_count = 0;
    sw_status s = check_model(model, &control_count, err);
    if (s != SW_OK)
        return s;
    sw_pack_meta *m = &out->meta;
    m->part_count = (uint32_t)model->part_count;
    m->patch_count = (uint32_t)model->patch_count;
    m->control_count = (uint32_t)control_count;
    m->units = SW_UNITS_MILLIMETRE; /* importers convert to the model's unit, sw_model.h */
    m->model_tolerance = isfinite(model->model_tolerance) && model->model_tolerance > 0
                             ? model->model_tolerance : 0.0f;
    /* calloc(n + 1) so an empty model still gets a pointer to free. */
    sw_pack_part *parts = calloc(model->part_count + 1, sizeof *parts);
    sw_pack_patch *patches = calloc(model->patch_count + 1, sizeof *patches);
    float *control = calloc((size_t)control_count * 4 + 1, sizeof *control);
    out->parts = parts;
    out->patches = patches;
    out->control = control;
    if (!parts || !patches || !control)
        s = sw_error_set(err, SW_ERR_NO_MEMORY, "model: cannot allocate pack arrays for %zu "
                         "patches", model->patch_count);
    if (s == SW_OK)
        s = fill_contents(model, parts, patches, control, m, progress, err);
    sw_pack_adjacency *adjacency = NULL;
    if (s == SW_OK) {
        report(progress, "adjacency", 0.0);
        s = sw_pack_find_adjacency(model, &adjacency, &m->adjacency_count, err);
    }
    out->adjacency = adjacency;
    if (s == SW_OK) {
        report(progress, "trims", 0.0);
        s = sw_pack_sections_from_model(model, out, err);
    }
    if (s == SW_OK)
        report(progress, "trims", 1.0);
    if (s != SW_OK)
        sw_pack_contents_free(out);
    return s;
}

void sw_pack_contents_free(sw_pack_contents *c)
{
    const void *arrays[] = { c->parts, c->patches, c->control, c->adjacency, c->surfaces,
                             c->trim_loops, c->trim_curves, c->trim_data, c->patch_domains,
                             c->trim_masks, c->viewpoints, c->part_transforms };
    for (size_t i = 0; i < sizeof arrays / sizeof *arrays; i++)
        free((void *)arrays[i]);
    memset(c, 0, sizeof *c);
}

static sw_status write_all(int fd, const uint8_t *bytes, size_t size, sw_error *err)
{
    size_t done = 0;
    while (done < size) {
        ssize_t w = write(fd, bytes + done, size - done);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            return sw_error_set(err, SW_ERR_IO, "write failed after %zu of %zu bytes: %s", done,
                                size, w < 0 ? strerror(errno) : "no progress");
        done += (size_t)w;
    }
    return SW_OK;
}

/* Makes the rename itself durable; the new file is complete either way, so a
 * failure here is not reported. */
static void sync_parent_dir(const char *path)
{
    const char *slash = strrchr(path, '/');
    char dir[4096] = ".";
    if (slash && (size_t)(slash - path) < sizeof dir) {
        size_t n = slash == path ? 1 : (size_t)(slash - path);
        memcpy(dir, path, n);
        dir[n] = '\0';
    }
    int fd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
        fsync(fd);
        close(fd);
    }
}

static sw_status write_temp(int fd, const char *tmp, const uint8_t *bytes, size_t size,
                            sw_error *err)
{
    sw_status s = write_all(fd, bytes, size, err);
    /* mkstemp creates 0600; a pack is read by the runtime, often as another user. */
    if (s == SW_OK && fchmod(fd, 0644) != 0)
        s = sw_error_set(err, SW_ERR_IO, "chmod %s: %s", tmp, strerror(errno));
    if (s == SW_OK && fsync(fd) != 0)
        s = sw_error_set(err, SW_ERR_IO, "fsync %s: %s", tmp, strerror(errno));
    if (close(fd) != 0 && s == SW_OK)
        s = sw_error_set(err, SW_ERR_IO, "close %s: %s", tmp, strerror(errno));
    return s;
}

sw_status sw_write_file_atomic(const char *path, const uint8_t *bytes, size_t size, sw_error *err)
{
    size_t len = strlen(path);
    char *tmp = malloc(len + sizeof ".tmp-XXXXXX");
    if (!tmp)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "%s: cannot allocate a temporary name", path);
    memcpy(tmp, path, len);
    memcpy(tmp + len, ".tmp-XXXXXX", sizeof ".tmp-XXXXXX");
    int fd = mkstemp(tmp);
    if (fd < 0) {
        sw_status s = sw_error_set(err, SW_ERR_IO, "%s: cannot create a temporary file: %s",
                                   path, strerror(errno));
        free(tmp);
        return s;
    }
    sw_status s = write_temp(fd, tmp, bytes, size, err);
    if (s == SW_OK && rename(tmp, path) != 0)
        s = sw_error_set(err, SW_ERR_IO, "rename from %s: %s", tmp, strerror(errno));
    if (s != SW_OK) {
        unlink(tmp);
        sw_error_prefix(err, "%s", path);
    } else {
        sync_parent_dir(path);
    }
    free(tmp);
    return s;
}
