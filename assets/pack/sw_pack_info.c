/* SPDX-License-Identifier: MIT */
/* seamwalk-pack info (sw_pack_info.h): stats per part and for the pack, as
 * aligned text and as JSON. Keys are added, never renamed: scripts read them. */
#include "sw_pack_info.h"
#include "sw_pack_instances.h"

#include <inttypes.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_pack_notes.h"
#include "sw_seam_border.h"
#include "sw_up_axis.h"

const char *sw_pack_units_name(uint32_t units)
{
    return units == SW_UNITS_MILLIMETRE ? "mm" : units == SW_UNITS_METRE ? "m" : "unspecified";
}

/* What the import skipped or read past, a line each (IMPORT_NOTES). */
static void print_notes_text(FILE *out, const sw_pack *pack)
{
    for (uint32_t i = 0; i < pack->import_note_count; i++) {
        const sw_pack_import_note *n = &pack->import_notes[i];
        fprintf(out, "  %-16s ", i ? "" : "import");
        sw_fput_escaped(out, n->source, sizeof n->source);
        fprintf(out, ": %" PRIu32 " x ", n->count);
        sw_fput_escaped(out, n->what, sizeof n->what);
        fprintf(out, " %s\n", sw_pack_note_kind_name(n->kind));
    }
}

static void json_string(FILE *out, const char *s, size_t max);

void sw_pack_json_string(FILE *out, const char *s, size_t max)
{
    json_string(out, s, max);
}

/* "import_notes": [...], always (empty for a clean import). */
static void json_notes(FILE *out, const sw_pack *pack)
{
    fprintf(out, "  \"import_notes\": [");
    for (uint32_t i = 0; i < pack->import_note_count; i++) {
        const sw_pack_import_note *n = &pack->import_notes[i];
        fprintf(out, "%s{\"source\": ", i ? ", " : "");
        json_string(out, n->source, sizeof n->source);
        fprintf(out, ", \"kind\": \"%s\", \"what\": ",
                n->kind == SW_NOTE_SKIPPED ? "skipped" : "message");
        json_string(out, n->what, sizeof n->what);
        fprintf(out, ", \"count\": %" PRIu32 "}", n->count);
    }
    fprintf(out, "],\n");
}

/* Packs from before ORIENTATION say so: their +y is the reader's default. */
static void print_up_axis_text(FILE *out, const sw_pack *pack)
{
    fprintf(out, "  %-16s %s%s\n", "up axis", sw_up_axis_name(sw_pack_up_axis(pack)),
            pack->orientation ? "" : " (no ORIENTATION section: the default)");
}

static void stats_init(sw_pack_part_stats *s)
{
    memset(s, 0, sizeof *s);
    s->degree_min[0] = s->degree_min[1] = s->trim_degree_min = INT32_MAX;
}

static void stats_finish(sw_pack_part_stats *s)
{
    for (int k = 0; k < 2; k++)
        if (s->patches == 0)
            s->degree_min[k] = s->degree_max[k] = 0;
    if (s->curves == 0)
        s->trim_degree_min = s->trim_degree_max = 0;
}

static void add_patch(sw_pack_part_stats *s, const sw_pack_patch *p)
{
    int d[2] = { p->degree_u, p->degree_v };
    for (int k = 0; k < 2; k++) {
        s->degree_min[k] = d[k] < s->degree_min[k] ? d[k] : s->degree_min[k];
        s->degree_max[k] = d[k] > s->degree_max[k] ? d[k] : s->degree_max[k];
    }
    for (int k = 0; k < 3; k++) {
        int first = s->patches == 0;
        s->box_min[k] = first || p->box_min[k] < s->box_min[k] ? p->box_min[k] : s->box_min[k];
        s->box_max[k] = first || p->box_max[k] > s->box_max[k] ? p->box_max[k] : s->box_max[k];
    }
    s->patches++;
    s->rational_patches += (p->flags & SW_PATCH_RATIONAL) != 0;
}

static void add_curve(sw_pack_part_stats *s, const sw_pack_trim_curve *c)
{
    s->curves++;
    s->rational_curves += (c->flags & SW_TRIM_RATIONAL) != 0;
    s->computed_curves += (c->flags & SW_TRIM_COMPUTED) != 0;
    s->trim_degree_min = c->degree < s->trim_degree_min ? c->degree : s->trim_degree_min;
    s->trim_degree_max = c->degree > s->trim_degree_max ? c->degree : s->trim_degree_max;
}

/* A surface's counts into both its part's stats and the total. */
static void add_surface(const sw_pack *pack, const sw_pack_surface *sf, sw_pack_part_stats *ps,
                        sw_pack_part_stats *total)
{
    int rational = 0;
    for (uint32_t p = 0; p < sf->patch_count; p++)
        rational |= (pack->patches[sf->first_patch + p].flags & SW_PATCH_RATIONAL) != 0;
    sw_pack_part_stats *both[2] = { ps, total };
    for (int b = 0; b < 2; b++) {
        both[b]->surfaces++;
        both[b]->trimmed_surfaces += sf->loop_count > 0;
        both[b]->rational_surfaces += (uint32_t)rational;
        both[b]->loops += sf->loop_count;
    }
    for (uint32_t l = 0; l < sf->loop_count; l++) {
        const sw_pack_trim_loop *loop = &pack->trim_loops[sf->first_loop + l];
        for (uint32_t c = 0; c < loop->curve_count; c++) {
            add_curve(ps, &pack->trim_curves[loop->first_curve + c]);
            add_curve(total, &pack->trim_curves[loop->first_curve + c]);
        }
    }
}

void sw_pack_gather_stats(const sw_pack *pack, sw_pack_part_stats *parts,
                          sw_pack_part_stats *total)
{
    uint32_t n = pack->meta->part_count;
    for (uint32_t i = 0; i < n; i++)
        stats_init(&parts[i]);
    stats_init(total);
    for (uint32_t i = 0; i < pack->meta->patch_count; i++) {
        add_patch(&parts[pack->patches[i].part], &pack->patches[i]);
        add_patch(total, &pack->patches[i]);
    }
    for (uint32_t i = 0; i < pack->surface_count; i++)
        add_surface(pack, &pack->surfaces[i], &parts[pack->surfaces[i].part], total);
    /* Without SURFACES every patch is an untrimmed surface of its own. */
    for (uint32_t i = 0; !pack->surfaces && i <= n; i++) {
        sw_pack_part_stats *s = i < n ? &parts[i] : total;
        s->surfaces = s->patches;
        s->rational_surfaces = s->rational_patches;
    }
    for (uint32_t i = 0; i < n; i++)
        stats_finish(&parts[i]);
    stats_finish(total);
}

void sw_pack_stats_add(sw_pack_part_stats *sum, const sw_pack_part_stats *s)
{
    int first = sum->patches == 0;
    sum->surfaces += s->surfaces, sum->trimmed_surfaces += s->trimmed_surfaces;
    sum->rational_surfaces += s->rational_surfaces, sum->rational_patches += s->rational_patches;
    sum->loops += s->loops, sum->curves += s->curves;
    sum->rational_curves += s->rational_curves, sum->computed_curves += s->computed_curves;
    for (int k = 0; s->patches && k < 2; k++) {
        sum->degree_min[k] = first || s->degree_min[k] < sum->degree_min[k] ? s->degree_min[k]
                                                                            : sum->degree_min[k];
        sum->degree_max[k] = s->degree_max[k] > sum->degree_max[k] ? s->degree_max[k]
                                                                   : sum->degree_max[k];
    }
    for (int k = 0; s->patches && k < 3; k++) {
        sum->box_min[k] = first || s->box_min[k] < sum->box_min[k] ? s->box_min[k] : sum->box_min[k];
        sum->box_max[k] = first || s->box_max[k] > sum->box_max[k] ? s->box_max[k] : sum->box_max[k];
    }
    if (s->curves) {
        int none = sum->curves == s->curves;
        sum->trim_degree_min = none || s->trim_degree_min < sum->trim_degree_min
                                   ? s->trim_degree_min : sum->trim_degree_min;
        sum->trim_degree_max = s->trim_degree_max > sum->trim_degree_max ? s->trim_degree_max
                                                                         : sum->trim_degree_max;
    }
    sum->patches += s->patches;
}

static double ratio(uint64_t bytes, uint32_t n) { return n ? (double)bytes / n : 0.0; }

static double border_fraction(const sw_seam_border *b)
{
    return b->length > 0 ? b->free_length / b->length : 0.0;
}

int sw_pack_gather_seam_stats(const sw_pack *pack, sw_pack_seam_stats *out)
{
    memset(out, 0, sizeof *out);
    if (!pack->seam_header)
        return 0;
    const sw_seam_graph *g = &pack->seam;
    for (uint32_t i = 0; i < pack->header->section_count; i++) {
        uint32_t t = pack->sections[i].type;
        if (t >= SW_SECTION_SEAM && t <= SW_SECTION_SEAM_SURFACE_LOOPS)
            out->bytes += pack->sections[i].size;
    }
    *out = (sw_pack_seam_stats){
        .vertices = g->vertex_count, .original_vertices = g->original_count,
        .created_vertices = g->vertex_count - g->original_count, .slots = g->slot_count,
        .loops = g->loop_count, .edges = g->edge_count, .collapses = g->collapse_count,
        .tolerance = g->tolerance, .bytes = out->bytes,
        .bytes_per_edge = ratio(out->bytes, g->edge_count),
        .bytes_per_surface = ratio(out->bytes, g->surface_count),
        .bytes_per_bezier_patch = ratio(out->bytes, pack->meta->patch_count) };
    return 1;
}

static int compare_floats(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

/* Rank r's figures; errors is scratch for one error per surface. */
static void gather_rank(const sw_levels *l, uint32_t r, float *errors,
                        sw_pack_level_rank_stats *out)
{
    uint32_t n = 0;
    for (uint32_t s = 0; s < l->surface_count; s++) {
        uint32_t k = l->surface_levels[s] + r;
        if (k >= l->surface_levels[s + 1])
            continue;
        out->triangles += l->levels[k].index_count / 3;
        if (r > 0)
            out->triangles_before += l->levels[k - 1].index_count / 3;
        errors[n++] = l->levels[k].error;
    }
    qsort(errors, n, sizeof *errors, compare_floats);
    out->levels = n;
    out->error_max = n ? errors[n - 1] : 0.0f;
    out->error_median = n ? errors[(n - 1) / 2] : 0.0f;
}

sw_status sw_pack_gather_levels_stats(const sw_pack *pack, sw_pack_levels_stats *out,
                                      sw_error *err)
{
    memset(out, 0, sizeof *out);
    if (!pack->levels_header)
        return SW_OK;
    const sw_levels *l = &pack->levels;
    for (uint32_t i = 0; i < pack->header->section_count; i++) {
        uint32_t t = pack->sections[i].type;
        if (t >= SW_SECTION_LEVELS && t <= SW_SECTION_LEVEL_CHAIN_POINTS)
            out->bytes += pack->sections[i].size;
    }
    out->levels = l->level_count;
    out->per_surface_min = l->surface_count ? UINT32_MAX : 0;
    for (uint32_t s = 0; s < l->surface_count; s++) {
        uint32_t n = l->surface_levels[s + 1] - l->surface_levels[s];
        out->per_surface_min = n < out->per_surface_min ? n : out->per_surface_min;
        out->per_surface_max = n > out->per_surface_max ? n : out->per_surface_max;
    }
    out->vertices = l->vertex_count;
    out->indices = l->index_count;
    out->triangles = l->index_count / 3;
    out->chain_points = l->chain_point_count;
    out->rank_count = out->per_surface_max; /* validated: at most SW_LEVELS_MAX */
    float *errors = malloc(((size_t)l->surface_count + 1) * sizeof *errors);
    if (!errors)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "cannot allocate the errors of %u surfaces' "
                            "levels", (unsigned)l->surface_count);
    for (uint32_t r = 0; r < out->rank_count; r++)
        gather_rank(l, r, errors, &out->ranks[r]);
    free(errors);
    return SW_OK;
}

/* ---- text ---------------------------------------------------------------- */

/* The parts info describes, with their stats and the counts of the whole:
 * the pack's own, or for a pack of placed parts the placed ones. */
typedef struct info_parts {
    uint32_t count;
    const sw_pack_part *parts;
    const float *transforms;          /* 16 per part, or NULL */
    const sw_pack_part_stats *stats;
    sw_pack_part_stats total;
    uint64_t patches, control_points, adjacency;
} info_parts;

static void print_degrees(FILE *out, const sw_pack_part_stats *s)
{
    fprintf(out, "u %d..%d, v %d..%d", s->degree_min[0], s->degree_max[0], s->degree_min[1],
            s->degree_max[1]);
    if (s->curves)
        fprintf(out, "; trims %d..%d", s->trim_degree_min, s->trim_degree_max);
    fputc('\n', out);
}

static void print_part_text(FILE *out, const sw_pack *pack, const info_parts *ip, uint32_t i)
{
    const char *units = sw_pack_units_name(pack->meta->units);
    const sw_pack_part_stats *s = &ip->stats[i];
    fprintf(out, "  part %" PRIu32 ": ", i);
    sw_fput_escaped(out, ip->parts[i].name, sizeof ip->parts[i].name);
    fputc('\n', out);
    fprintf(out, "    %-16s %" PRIu32 " (%" PRIu32 " trimmed, %" PRIu32 " rational)\n",
            "surfaces", s->surfaces, s->trimmed_surfaces, s->rational_surfaces);
    fprintf(out, "    %-16s %" PRIu32 " (%" PRIu32 " rational)\n", "bezier patches", s->patches,
            s->rational_patches);
    fprintf(out, "    %-16s %" PRIu32 "\n", "trim loops", s->loops);
    fprintf(out, "    %-16s %" PRIu32 " (%" PRIu32 " rational, %" PRIu32 " computed)\n",
            "trim curves", s->curves, s->rational_curves, s->computed_curves);
    fprintf(out, "    %-16s ", "degrees");
    print_degrees(out, s);
    fprintf(out, "    %-16s min %g %g %g, max %g %g %g %s\n", "box", s->box_min[0],
            s->box_min[1], s->box_min[2], s->box_max[0], s->box_max[1], s->box_max[2], units);
}

/* What each section's bytes come to per stored seam vertex, per stored
 * patch and per instance (a pack without instances places its parts once):
 * where a pack's size goes, whatever its scene's size. 0 where the pack has
 * none of the first two. */
typedef struct per_unit {
    double seam_vertices, patches, instances;
} per_unit;

static per_unit units_of(const sw_pack *pack)
{
    per_unit u = { pack->seam_header ? pack->seam.vertex_count : 0, pack->meta->patch_count,
                   pack->instances ? pack->instance_count : 1 };
    return u;
}

static double per(uint64_t bytes, double count) { return count > 0 ? bytes / count : 0; }

static void print_sections_text(FILE *out, const sw_pack *pack)
{
    fprintf(out, "  %-16s %" PRIu32 " (bytes, and per stored seam vertex, per stored patch, "
            "per instance)\n", "sections", pack->header->section_count);
    /* 15 fits every name up to PART_TRANSFORMS; only the seam group's
     * longer names widen the column. */
    int width = 15;
    for (uint32_t i = 0; i < pack->header->section_count; i++) {
        int len = (int)strlen(sw_section_type_name(pack->sections[i].type));
        width = len > width ? len : width;
    }
    per_unit u = units_of(pack);
    uint64_t total = 0;
    for (uint32_t i = 0; i < pack->header->section_count; i++) {
        const sw_pack_section *sec = &pack->sections[i];
        fprintf(out, "    %-*s offset %10" PRIu64 "  size %10" PRIu64 " %9.1f %9.1f %11.1f\n",
                width, sw_section_type_name(sec->type), sec->offset, sec->size,
                per(sec->size, u.seam_vertices), per(sec->size, u.patches),
                per(sec->size, u.instances));
        total += sec->size;
    }
    fprintf(out, "    %-*s %17s  size %10" PRIu64 " %9.1f %9.1f %11.1f\n", width,
            "all sections", "", total, per(total, u.seam_vertices), per(total, u.patches),
            per(total, u.instances));
}

/* Only for packs with a Seam Graph, so other packs' reports are unchanged. */
static void print_seam_text(FILE *out, const sw_pack *pack)
{
    sw_pack_seam_stats s;
    if (!sw_pack_gather_seam_stats(pack, &s))
        return;
    fprintf(out, "  %-16s %" PRIu32 " vertices (%" PRIu32 " original, %" PRIu32 " created), %"
            PRIu32 " slots, %" PRIu32 " loops, %" PRIu32 " edges, %" PRIu32 " collapses, "
            "tolerance %g\n", "seam graph", s.vertices, s.original_vertices, s.created_vertices,
            s.slots, s.loops, s.edges, s.collapses, s.tolerance);
    fprintf(out, "  %-16s %" PRIu64 " bytes: %.1f per boundary edge, %.1f per surface, %.1f per "
            "bezier patch\n", "seam memory", s.bytes, s.bytes_per_edge, s.bytes_per_surface,
            s.bytes_per_bezier_patch);
    sw_seam_border b;
    if (sw_seam_border_measure(&pack->seam, &b, NULL) == SW_OK)
        fprintf(out, "  %-16s %.6g of %.6g (%.4g%%), %zu of %zu edge uses free\n",
                "free border", b.free_length, b.length, 100.0 * border_fraction(&b),
                b.free_edges, b.edge_uses);
}

/* Only for packs with levels, so other packs' reports are unchanged. */
static void print_levels_text(FILE *out, const sw_pack *pack, const sw_pack_levels_stats *s)
{
    if (!pack->levels_header)
        return;
    fprintf(out, "  %-16s %" PRIu32 " (%" PRIu32 "..%" PRIu32 " per surface), %" PRIu32
            " vertices, %" PRIu32 " indices (%" PRIu32 " triangles), %" PRIu32 " chain points, %"
            PRIu64 " bytes\n", "levels", s->levels, s->per_surface_min, s->per_surface_max,
            s->vertices, s->indices, s->triangles, s->chain_points, s->bytes);
    for (uint32_t r = 0; r < s->rank_count; r++) {
        const sw_pack_level_rank_stats *k = &s->ranks[r];
        char rank[16];
        snprintf(rank, sizeof rank, "rank %" PRIu32, r);
        fprintf(out, "    %-14s %" PRIu32 " surfaces, %" PRIu64 " triangles, error max %g, "
                "median %g", rank, k->levels, k->triangles, (double)k->error_max,
                (double)k->error_median);
        if (k->triangles_before > 0)
            fprintf(out, "; %.0f%% fewer triangles than rank %" PRIu32 " of the same surfaces",
                    100.0 * (1.0 - (double)k->triangles / (double)k->triangles_before), r - 1);
        fputc('\n', out);
    }
}

/* The derived data's figures, gathered before anything is printed. */
typedef struct derived_stats {
    sw_pack_levels_stats levels;
    sw_pack_super_stats supers;
} derived_stats;

/* The runtime's memory pool by pool (sw_pack_runtime_pools): what a unit's
 * --memory-mb must hold, and where it goes. */
static void pool_list(const sw_pack *pack, const char *names[], uint64_t bytes[], int *n)
{
    sw_runtime_pools p;
    sw_pack_runtime_pools(pack, &p);
    *n = sw_runtime_pool_list(&p, names, bytes);
}

static void print_pools_text(FILE *out, const sw_pack *pack)
{
    const char *names[SW_RUNTIME_POOL_COUNT];
    uint64_t bytes[SW_RUNTIME_POOL_COUNT];
    int n;
    pool_list(pack, names, bytes, &n);
    fprintf(out, "  %-16s %" PRIu64 " bytes (%.1f MiB) beside the pack's own bytes, by "
            "pool:\n", "runtime memory", pack->header->runtime_bytes,
            pack->header->runtime_bytes / 1048576.0);
    uint64_t sum = 0;
    for (int i = 0; i < n; i++) {
        fprintf(out, "    %-16s %12" PRIu64 " bytes %8.1f MiB\n", names[i], bytes[i],
                bytes[i] / 1048576.0);
        sum += bytes[i];
    }
    if (pack->header->runtime_bytes > sum)   /* written when the runtime took more */
        fprintf(out, "    %-16s %12" PRIu64 " bytes %8.1f MiB (the header asks more than this "
                "seamwalk takes)\n", "beyond the pools", pack->header->runtime_bytes - sum,
                (pack->header->runtime_bytes - sum) / 1048576.0);
}

static void print_pools_json(FILE *out, const sw_pack *pack)
{
    const char *names[SW_RUNTIME_POOL_COUNT];
    uint64_t bytes[SW_RUNTIME_POOL_COUNT];
    int n;
    pool_list(pack, names, bytes, &n);
    fprintf(out, "  \"runtime_pools\": {");
    for (int i = 0; i < n; i++)
        fprintf(out, "%s\"%s\": %" PRIu64, i ? ", " : "", names[i], bytes[i]);
    fprintf(out, "}\n");
}

static void print_text(FILE *out, const char *path, const sw_pack *pack, const info_parts *ip,
                       const derived_stats *derived)
{
    const sw_pack_meta *m = pack->meta;
    const sw_pack_part_stats *t = &ip->total;
    fprintf(out, "%s: seamwalk pack version %" PRIu32 ", %" PRIu64 " bytes\n", path,
            pack->header->version, pack->header->total_size);
    fprintf(out, "  %-16s %" PRIu32 "\n", "parts", ip->count);
    for (uint32_t i = 0; i < ip->count; i++) {
        const sw_pack_part *p = &ip->parts[i];
        /* names are the file's bytes (a STEP product, a file name): shown
         * escaped, padded as the other columns */
        size_t len = strnlen(p->name, sizeof p->name);
        fputs("    ", out);
        sw_fput_escaped(out, p->name, sizeof p->name);
        fprintf(out, "%*s %6" PRIu32 " patches  colour %.3f %.3f %.3f %.3f\n",
                len < 20 ? (int)(20 - len) : 0, "", p->patch_count, p->color[0], p->color[1],
                p->color[2], p->color[3]);
    }
    fprintf(out, "  %-16s %" PRIu32 " (%" PRIu32 " trimmed)\n", "surfaces", t->surfaces,
            t->trimmed_surfaces);
    fprintf(out, "  %-16s %" PRIu64 "\n", "bezier patches", ip->patches);
    fprintf(out, "  %-16s %" PRIu64 "\n", "control points", ip->control_points);
    fprintf(out, "  %-16s %" PRIu32 "\n", "rational", t->rational_patches);
    fprintf(out, "  %-16s ", "degrees");
    print_degrees(out, t);
    fprintf(out, "  %-16s %" PRIu32 " loops, %" PRIu32 " curves (%" PRIu32 " computed), %" PRIu32
            " masks\n", "trimming", t->loops, t->curves, t->computed_curves, pack->trim_mask_count);
    fprintf(out, "  %-16s %" PRIu64 "\n", "adjacency", ip->adjacency);
    print_seam_text(out, pack);
    print_levels_text(out, pack, &derived->levels);
    sw_pack_print_super_text(out, pack, &derived->supers);
    sw_pack_print_part_levels_text(out, pack);
    fprintf(out, "  %-16s %" PRIu32, "viewpoints", pack->viewpoint_count);
    for (uint32_t i = 0; i < pack->viewpoint_count; i++)
    {
        fputs(i ? ", " : ": ", out);
        sw_fput_escaped(out, pack->viewpoints[i].name, sizeof pack->viewpoints[i].name);
    }
    fputc('\n', out);
    sw_pack_print_instances_text(out, pack);
    print_sections_text(out, pack);
    float lo[3], hi[3];
    sw_pack_placed_box(pack, lo, hi);
    double dx = (double)hi[0] - lo[0], dy = (double)hi[1] - lo[1], dz = (double)hi[2] - lo[2];
    fprintf(out, "  %-16s %s (model tolerance %g)\n", "units", sw_pack_units_name(m->units),
            m->model_tolerance);
    print_up_axis_text(out, pack);
    print_notes_text(out, pack);
    fprintf(out, "  %-16s min %g %g %g, max %g %g %g\n", "box", lo[0], lo[1], lo[2], hi[0], hi[1],
            hi[2]);
    fprintf(out, "  %-16s %g (box diagonal)\n", "model size", sqrt(dx * dx + dy * dy + dz * dz));
    print_pools_text(out, pack);
    for (uint32_t i = 0; i < ip->count; i++)
        print_part_text(out, pack, ip, i);
}

/* ---- JSON ------------------------------------------------------------------ */

/* Writes s as a JSON string; names are UTF-8 but may hold anything. */
static void json_string(FILE *out, const char *s, size_t max)
{
    fputc('"', out);
    for (size_t i = 0; i < max && s[i]; i++) {
        unsigned char c = (unsigned char)s[i];
        if (c == '"' || c == '\\')
            fprintf(out, "\\%c", c);
        else if (c < 0x20 || c == 0x7f)
            fprintf(out, "\\u%04x", c);
        else
            fputc(c, out);
    }
    fputc('"', out);
}

static void json_floats(FILE *out, const float *v, int n)
{
    fputc('[', out);
    for (int k = 0; k < n; k++)
        fprintf(out, "%s%.9g", k ? ", " : "", v[k]);
    fputc(']', out);
}

/* The counts a part and the whole pack share, as "key": value pairs. */
static void json_counts(FILE *out, const sw_pack_part_stats *s, const char *indent)
{
    fprintf(out, "%s\"trimmed_surfaces\": %" PRIu32 ", \"rational_surfaces\": %" PRIu32 ",\n",
            indent, s->trimmed_surfaces, s->rational_surfaces);
    fprintf(out, "%s\"trim_loops\": %" PRIu32 ", \"trim_curves\": %" PRIu32
            ", \"rational_trim_curves\": %" PRIu32 ", \"pcurves_computed\": %" PRIu32 ",\n",
            indent, s->loops, s->curves, s->rational_curves, s->computed_curves);
    fprintf(out, "%s\"trim_degree\": [%d, %d]", indent, s->trim_degree_min, s->trim_degree_max);
}

static void json_part(FILE *out, const info_parts *ip, uint32_t i)
{
    const sw_pack_part *p = &ip->parts[i];
    const sw_pack_part_stats *s = &ip->stats[i];
    fprintf(out, "%s\n    {\"name\": ", i ? "," : "");
    json_string(out, p->name, sizeof p->name);
    fprintf(out, ", \"first_patch\": %" PRIu32 ", \"patches\": %" PRIu32 ", \"color\": ",
            p->first_patch, p->patch_count);
    json_floats(out, p->color, 4);
    fprintf(out, ",\n     \"surfaces\": %" PRIu32 ", \"bezier_patches\": %" PRIu32
            ", \"rational_patches\": %" PRIu32 ",\n", s->surfaces, s->patches,
            s->rational_patches);
    fprintf(out, "     \"degree_u\": [%d, %d], \"degree_v\": [%d, %d],\n", s->degree_min[0],
            s->degree_max[0], s->degree_min[1], s->degree_max[1]);
    json_counts(out, s, "     ");
    fprintf(out, ",\n     \"box\": {\"min\": ");
    json_floats(out, s->box_min, 3);
    fprintf(out, ", \"max\": ");
    json_floats(out, s->box_max, 3);
    if (ip->transforms) {
        fprintf(out, "},\n     \"transform\": ");
        json_floats(out, &ip->transforms[(size_t)i * 16], 16);
        fputc('}', out);
    } else {
        fprintf(out, "}}");
    }
}

static void json_sections(FILE *out, const sw_pack *pack)
{
    per_unit u = units_of(pack);
    fprintf(out, "  \"sections\": [");
    for (uint32_t i = 0; i < pack->header->section_count; i++) {
        const sw_pack_section *sec = &pack->sections[i];
        fprintf(out, "%s\n    {\"type\": %" PRIu32 ", \"name\": \"%s\", \"offset\": %" PRIu64
                ", \"size\": %" PRIu64 ", \"per_seam_vertex\": %.3f, \"per_patch\": %.3f, "
                "\"per_instance\": %.3f}", i ? "," : "", sec->type,
                sw_section_type_name(sec->type), sec->offset, sec->size,
                per(sec->size, u.seam_vertices), per(sec->size, u.patches),
                per(sec->size, u.instances));
    }
    fprintf(out, "\n  ],\n");
}

static void json_viewpoints(FILE *out, const sw_pack *pack)
{
    fprintf(out, "  \"viewpoints\": [");
    for (uint32_t i = 0; i < pack->viewpoint_count; i++) {
        const sw_pack_viewpoint *v = &pack->viewpoints[i];
        fprintf(out, "%s\n    {\"name\": ", i ? "," : "");
        json_string(out, v->name, sizeof v->name);
        fprintf(out, ", \"eye\": ");
        json_floats(out, v->eye, 3);
        fprintf(out, ", \"target\": ");
        json_floats(out, v->target, 3);
        fprintf(out, ", \"up\": ");
        json_floats(out, v->up, 3);
        fprintf(out, ", \"fov_deg\": %.9g}", v->fov_deg);
    }
    fprintf(out, "%s],\n", pack->viewpoint_count ? "\n  " : "");
}

/* "seam": {...}, only for packs with a Seam Graph. */
static void json_seam(FILE *out, const sw_pack *pack)
{
    sw_pack_seam_stats s;
    if (!sw_pack_gather_seam_stats(pack, &s))
        return;
    fprintf(out, "  \"seam\": {\"vertices\": %" PRIu32 ", \"original_vertices\": %" PRIu32
            ", \"created_vertices\": %" PRIu32 ", \"slots\": %" PRIu32 ", \"loops\": %" PRIu32
            ", \"edges\": %" PRIu32 ", \"collapses\": %" PRIu32 ",\n", s.vertices,
            s.original_vertices, s.created_vertices, s.slots, s.loops, s.edges, s.collapses);
    fprintf(out, "           \"tolerance\": %.9g, \"bytes\": %" PRIu64 ", \"bytes_per_edge\": "
            "%.9g, \"bytes_per_surface\": %.9g, \"bytes_per_bezier_patch\": %.9g},\n",
            s.tolerance, s.bytes, s.bytes_per_edge, s.bytes_per_surface,
            s.bytes_per_bezier_patch);
    sw_seam_border b;
    if (sw_seam_border_measure(&pack->seam, &b, NULL) == SW_OK)
        fprintf(out, "  \"border\": {\"length\": %.9g, \"free_length\": %.9g, \"free_fraction\": "
                "%.9g, \"edge_uses\": %zu, \"free_edges\": %zu},\n", b.length, b.free_length,
                border_fraction(&b), b.edge_uses, b.free_edges);
}

/* "levels": {...}, or null for a pack without them (the key is always
 * there, so scripts can test it). */
static void json_levels(FILE *out, const sw_pack *pack, const sw_pack_levels_stats *s)
{
    if (!pack->levels_header) {
        fprintf(out, "  \"levels\": null,\n");
        return;
    }
    fprintf(out, "  \"levels\": {\"levels\": %" PRIu32 ", \"per_surface\": [%" PRIu32 ", %" PRIu32
            "], \"vertices\": %" PRIu32 ", \"indices\": %" PRIu32 ", \"triangles\": %" PRIu32
            ", \"chain_points\": %" PRIu32 ", \"bytes\": %" PRIu64 ",\n             \"ranks\": [",
            s->levels, s->per_surface_min, s->per_surface_max, s->vertices, s->indices,
            s->triangles, s->chain_points, s->bytes);
    for (uint32_t r = 0; r < s->rank_count; r++) {
        const sw_pack_level_rank_stats *k = &s->ranks[r];
        fprintf(out, "%s{\"rank\": %" PRIu32 ", \"surfaces\": %" PRIu32 ", \"triangles\": %"
                PRIu64 ", \"triangles_before\": %" PRIu64 ", \"error_max\": %.9g, "
                "\"error_median\": %.9g}", r ? ", " : "", r, k->levels, k->triangles,
                k->triangles_before, (double)k->error_max, (double)k->error_median);
    }
    fprintf(out, "]},\n");
}

static void print_json(FILE *out, const char *path, const sw_pack *pack, const info_parts *ip,
                       const derived_stats *derived)
{
    const sw_pack_meta *m = pack->meta;
    const sw_pack_part_stats *t = &ip->total;
    fprintf(out, "{\n  \"file\": ");
    json_string(out, path, SIZE_MAX);
    fprintf(out, ",\n  \"version\": %" PRIu32 ",\n  \"total_bytes\": %" PRIu64 ",\n",
            pack->header->version, pack->header->total_size);
    fprintf(out, "  \"part_count\": %" PRIu32 ",\n  \"parts\": [", ip->count);
    for (uint32_t i = 0; i < ip->count; i++)
        json_part(out, ip, i);
    fprintf(out, "%s],\n", ip->count ? "\n  " : "");
    fprintf(out, "  \"surfaces\": %" PRIu32 ",\n", t->surfaces);
    fprintf(out, "  \"surfaces_note\": \"one per Bezier patch for Bezier inputs\",\n");
    fprintf(out, "  \"bezier_patches\": %" PRIu64 ",\n", ip->patches);
    fprintf(out, "  \"control_points\": %" PRIu64 ",\n", ip->control_points);
    fprintf(out, "  \"rational_patches\": %" PRIu32 ",\n", t->rational_patches);
    fprintf(out, "  \"degree_u\": [%d, %d],\n  \"degree_v\": [%d, %d],\n", t->degree_min[0],
            t->degree_max[0], t->degree_min[1], t->degree_max[1]);
    json_counts(out, t, "  ");
    fprintf(out, ",\n  \"trim_masks\": %" PRIu32 ",\n", pack->trim_mask_count);
    fprintf(out, "  \"adjacency\": %" PRIu64 ",\n", ip->adjacency);
    json_seam(out, pack);
    json_levels(out, pack, &derived->levels);
    sw_pack_print_super_json(out, pack, &derived->supers);
    sw_pack_print_part_levels_json(out, pack);
    json_viewpoints(out, pack);
    sw_pack_print_instances_json(out, pack);
    json_sections(out, pack);
    fprintf(out, "  \"units\": \"%s\",\n  \"model_tolerance\": %.9g,\n",
            sw_pack_units_name(m->units), m->model_tolerance);
    fprintf(out, "  \"up_axis\": \"%s\",\n", sw_up_axis_name(sw_pack_up_axis(pack)));
    json_notes(out, pack);
    float lo[3], hi[3];
    sw_pack_placed_box(pack, lo, hi);
    fprintf(out, "  \"box\": {\"min\": ");
    json_floats(out, lo, 3);
    fprintf(out, ", \"max\": ");
    json_floats(out, hi, 3);
    double dx = (double)hi[0] - lo[0], dy = (double)hi[1] - lo[1], dz = (double)hi[2] - lo[2];
    fprintf(out, "},\n  \"model_size\": %.9g,\n", sqrt(dx * dx + dy * dy + dz * dz));
    fprintf(out, "  \"runtime_bytes\": %" PRIu64 ",\n", pack->header->runtime_bytes);
    print_pools_json(out, pack);
    fprintf(out, "}\n");
}

sw_status sw_pack_print_info(FILE *out, const char *path, const sw_pack *pack, int json,
                             sw_error *err)
{
    info_parts ip = { .count = pack->meta->part_count, .parts = pack->parts,
                      .transforms = pack->part_transforms, .patches = pack->meta->patch_count,
                      .control_points = pack->meta->control_count,
                      .adjacency = pack->meta->adjacency_count };
    sw_pack_part_stats *parts = calloc((size_t)pack->meta->part_count + 1, sizeof *parts);
    if (!parts)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "%s: cannot allocate stats for %u parts",
                            path, (unsigned)pack->meta->part_count);
    sw_pack_gather_stats(pack, parts, &ip.total);
    ip.stats = parts;
    sw_pack_placed_parts placed = { 0 };
    sw_status s = SW_OK;
    if (pack->instances && (s = sw_pack_place_parts(pack, parts, &placed, err)) == SW_OK) {
        ip.count = placed.count, ip.parts = placed.parts, ip.transforms = placed.transforms;
        ip.stats = placed.stats, ip.total = placed.total;
        uint64_t c[SW_SPACE_COUNT];
        sw_pack_placed_counts(pack->prototypes, pack->instances, pack->instance_count, c);
        ip.patches = c[SW_SPACE_PATCHES], ip.control_points = c[SW_SPACE_CONTROL];
        ip.adjacency = c[SW_SPACE_ADJACENCY];
    }
    derived_stats derived;
    if (s == SW_OK)
        s = sw_pack_gather_levels_stats(pack, &derived.levels, err);
    if (s == SW_OK)
        s = sw_pack_gather_super_stats(pack, &derived.supers, err);
    if (s == SW_OK && json)
        print_json(out, path, pack, &ip, &derived);
    else if (s == SW_OK)
        print_text(out, path, pack, &ip, &derived);
    free(parts);
    sw_pack_placed_parts_free(&placed);
    if (s != SW_OK)
        sw_error_prefix(err, "%s", path);
    return s;
}
