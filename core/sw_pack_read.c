/* SPDX-License-Identifier: MIT */
/* The pack container: header, section table, section bounds and checksums,
 * which sections must or may appear (reading a file: sw_pack_load.c). The
 * records inside the sections are checked by sw_pack_validate.c and, for the
 * trimmed-surface group, the Seam Graph and the static levels,
 * sw_pack_validate_trim.c, sw_pack_validate_seam.c and
 * sw_pack_validate_levels.c. Format: assets/PACK_FORMAT.md. */
#include "sw_pack.h"

#include <stdio.h>
#include <string.h>

#define XXH_STATIC_LINKING_ONLY /* XXH3_state_t on the stack: no malloc here */
#include <xxhash.h>

#include "sw_pack_instances.h"
#include "sw_pack_notes.h"
#include "sw_pack_validate.h"
#include "sw_up_axis.h"
#include "sw_walk_memory.h"

/* The records are read in place, so their layout is the format. */
#define SW_PIN(type, field, off) _Static_assert(offsetof(type, field) == (off), #type "." #field)
_Static_assert(sizeof(sw_pack_header) == 64, "sw_pack_header");
SW_PIN(sw_pack_header, magic, 0);
SW_PIN(sw_pack_header, version, 8);
SW_PIN(sw_pack_header, byte_order, 12);
SW_PIN(sw_pack_header, total_size, 16);
SW_PIN(sw_pack_header, runtime_bytes, 24);
SW_PIN(sw_pack_header, section_count, 32);
SW_PIN(sw_pack_header, section_table_offset, 36);
SW_PIN(sw_pack_header, header_checksum, 40);
SW_PIN(sw_pack_header, reserved, 48);
_Static_assert(sizeof(sw_pack_section) == 32, "sw_pack_section");
SW_PIN(sw_pack_section, type, 0);
SW_PIN(sw_pack_section, flags, 4);
SW_PIN(sw_pack_section, offset, 8);
SW_PIN(sw_pack_section, size, 16);
SW_PIN(sw_pack_section, checksum, 24);
_Static_assert(sizeof(sw_pack_meta) == 64, "sw_pack_meta");
SW_PIN(sw_pack_meta, part_count, 0);
SW_PIN(sw_pack_meta, patch_count, 4);
SW_PIN(sw_pack_meta, control_count, 8);
SW_PIN(sw_pack_meta, adjacency_count, 12);
SW_PIN(sw_pack_meta, box_min, 16);
SW_PIN(sw_pack_meta, box_max, 28);
SW_PIN(sw_pack_meta, units, 40);
SW_PIN(sw_pack_meta, model_tolerance, 44);
SW_PIN(sw_pack_meta, reserved, 48);
_Static_assert(sizeof(sw_pack_part) == 80, "sw_pack_part");
SW_PIN(sw_pack_part, first_patch, 0);
SW_PIN(sw_pack_part, patch_count, 4);
SW_PIN(sw_pack_part, color, 8);
SW_PIN(sw_pack_part, name, 24);
_Static_assert(sizeof(sw_pack_patch) == 48, "sw_pack_patch");
SW_PIN(sw_pack_patch, first_control, 0);
SW_PIN(sw_pack_patch, degree_u, 4);
SW_PIN(sw_pack_patch, degree_v, 5);
SW_PIN(sw_pack_patch, flags, 6);
SW_PIN(sw_pack_patch, part, 8);
SW_PIN(sw_pack_patch, box_min, 12);
SW_PIN(sw_pack_patch, box_max, 24);
SW_PIN(sw_pack_patch, d2_bound, 36);
_Static_assert(sizeof(sw_pack_adjacency) == 12, "sw_pack_adjacency");
SW_PIN(sw_pack_adjacency, patch_a, 0);
SW_PIN(sw_pack_adjacency, patch_b, 4);
SW_PIN(sw_pack_adjacency, edge_a, 8);
SW_PIN(sw_pack_adjacency, edge_b, 9);
SW_PIN(sw_pack_adjacency, reversed, 10);
SW_PIN(sw_pack_adjacency, reserved, 11);
_Static_assert(sizeof(sw_pack_surface) == 40, "sw_pack_surface");
SW_PIN(sw_pack_surface, part, 0);
SW_PIN(sw_pack_surface, first_patch, 4);
SW_PIN(sw_pack_surface, patch_count, 8);
SW_PIN(sw_pack_surface, first_loop, 12);
SW_PIN(sw_pack_surface, loop_count, 16);
SW_PIN(sw_pack_surface, flags, 20);
SW_PIN(sw_pack_surface, domain, 24);
_Static_assert(sizeof(sw_pack_trim_loop) == 12, "sw_pack_trim_loop");
SW_PIN(sw_pack_trim_loop, first_curve, 0);
SW_PIN(sw_pack_trim_loop, curve_count, 4);
SW_PIN(sw_pack_trim_loop, flags, 8);
_Static_assert(sizeof(sw_pack_trim_curve) == 16, "sw_pack_trim_curve");
SW_PIN(sw_pack_trim_curve, first_float, 0);
SW_PIN(sw_pack_trim_curve, count, 4);
SW_PIN(sw_pack_trim_curve, degree, 8);
SW_PIN(sw_pack_trim_curve, flags, 9);
SW_PIN(sw_pack_trim_curve, reserved, 10);
SW_PIN(sw_pack_trim_curve, reserved2, 12);
_Static_assert(sizeof(sw_pack_patch_domain) == 24, "sw_pack_patch_domain");
SW_PIN(sw_pack_patch_domain, surface, 0);
SW_PIN(sw_pack_patch_domain, mask, 4);
SW_PIN(sw_pack_patch_domain, domain, 8);
_Static_assert(sizeof(sw_pack_trim_mask) == 128, "sw_pack_trim_mask");
_Static_assert(sizeof(sw_pack_viewpoint) == 96, "sw_pack_viewpoint");
SW_PIN(sw_pack_viewpoint, name, 0);
SW_PIN(sw_pack_viewpoint, eye, 48);
SW_PIN(sw_pack_viewpoint, target, 60);
SW_PIN(sw_pack_viewpoint, up, 72);
SW_PIN(sw_pack_viewpoint, fov_deg, 84);
SW_PIN(sw_pack_viewpoint, reserved, 88);
_Static_assert(sizeof(sw_pack_seam) == 64, "sw_pack_seam");
SW_PIN(sw_pack_seam, vertex_count, 0);
SW_PIN(sw_pack_seam, original_count, 4);
SW_PIN(sw_pack_seam, slot_count, 8);
SW_PIN(sw_pack_seam, loop_count, 12);
SW_PIN(sw_pack_seam, edge_count, 16);
SW_PIN(sw_pack_seam, collapse_count, 20);
SW_PIN(sw_pack_seam, slot_ref_count, 24);
SW_PIN(sw_pack_seam, surface_count, 28);
SW_PIN(sw_pack_seam, tolerance, 32);
SW_PIN(sw_pack_seam, reserved, 36);
/* The Seam Graph's records are core/sw_seam_graph.h's structs, stored as is. */
_Static_assert(sizeof(sw_seam_vertex) == 32, "sw_seam_vertex");
SW_PIN(sw_seam_vertex, p, 0);
SW_PIN(sw_seam_vertex, child, 12);
SW_PIN(sw_seam_vertex, error, 16);
SW_PIN(sw_seam_vertex, first_slot_ref, 20);
SW_PIN(sw_seam_vertex, slot_ref_count, 24);
SW_PIN(sw_seam_vertex, reserved, 28);
_Static_assert(sizeof(sw_seam_slot) == 12, "sw_seam_slot");
SW_PIN(sw_seam_slot, vertex, 0);
SW_PIN(sw_seam_slot, uv, 4);
_Static_assert(sizeof(sw_seam_loop) == 16, "sw_seam_loop");
SW_PIN(sw_seam_loop, surface, 0);
SW_PIN(sw_seam_loop, first_slot, 4);
SW_PIN(sw_seam_loop, slot_count, 8);
SW_PIN(sw_seam_loop, flags, 12);
_Static_assert(sizeof(sw_seam_edge) == 8, "sw_seam_edge");
SW_PIN(sw_seam_edge, a, 0);
SW_PIN(sw_seam_edge, b, 4);
_Static_assert(sizeof(sw_seam_collapse) == 12, "sw_seam_collapse");
SW_PIN(sw_seam_collapse, v1, 0);
SW_PIN(sw_seam_collapse, v2, 4);
SW_PIN(sw_seam_collapse, error, 8);
_Static_assert(sizeof(sw_pack_orientation) == 16, "sw_pack_orientation");
SW_PIN(sw_pack_orientation, up_axis, 0);
SW_PIN(sw_pack_orientation, reserved, 4);
_Static_assert(sizeof(float) == 4, "CONTROL holds IEEE binary32");
_Static_assert(sizeof(SW_PACK_MAGIC) - 1 == 8, "magic is 8 bytes");

enum { HEADER_BYTES = 64, SECTION_BYTES = 32, CONTROL_POINT_BYTES = 16,
       TRANSFORM_BYTES = 16 * 4, LAST_KNOWN = SW_SECTION_LEVEL_CHAIN_POINTS };

/* Types this file does not index: SIGNATURE is checked by the unit
 * (sw_pack_signature.h), ORIENTATION, IMPORT_NOTES, the SUPER_* and PART_LEVEL* groups by
 * their own modules, each with its own "a second ..." rule. */
static int indexed_here(uint32_t t)
{
    return t >= SW_SECTION_META && t <= LAST_KNOWN &&
           (t <= SW_SECTION_SEAM_SURFACE_LOOPS || t >= SW_SECTION_LEVELS);
}

sw_status sw_pack_find_group(const sw_pack *pack, const uint32_t *types,
                             const uint64_t *record_bytes, int count, int32_t *index,
                             sw_error *err)
{
    for (int k = 0; k < count; k++)
        index[k] = -1;
    for (uint32_t i = 0; i < pack->header->section_count; i++) {
        const sw_pack_section *s = &pack->sections[i];
        for (int k = 0; k < count; k++) {
            if (s->type != types[k])
                continue;
            const char *name = sw_section_type_name(s->type);
            if (index[k] >= 0)
                return sw_error_set(err, SW_ERR_FORMAT, "section %u (%s): a second %s section "
                                    "(the first is section %d)", (unsigned)i, name, name,
                                    (int)index[k]);
            if (s->size % record_bytes[k] != 0 || s->size / record_bytes[k] > UINT32_MAX)
                return sw_error_set(err, SW_ERR_FORMAT, "section %u (%s): %llu bytes, expected "
                                    "a multiple of %llu", (unsigned)i, name,
                                    (unsigned long long)s->size,
                                    (unsigned long long)record_bytes[k]);
            index[k] = (int32_t)i;
        }
    }
    return SW_OK;
}

uint64_t sw_pack_runtime_bytes(uint64_t walk_bytes)
{
    if (walk_bytes > UINT64_MAX / 4)
        return UINT64_MAX; /* no real pack; saturate instead of wrapping */
    return SW_PACK_ALIGN + walk_bytes;
}

uint64_t sw_pack_arena_bytes(uint64_t total_size)
{
    if (total_size > UINT64_MAX / 4)
        return UINT64_MAX;
    return (total_size + SW_PACK_ALIGN - 1) / SW_PACK_ALIGN * SW_PACK_ALIGN + SW_PACK_ALIGN;
}

sw_status sw_pack_check_header_identity(const sw_pack_header *h, uint64_t actual_size,
                                        const char *what, sw_error *err)
{
    if (memcmp(h->magic, SW_PACK_MAGIC, 8) != 0)
        return sw_error_set(err, SW_ERR_FORMAT,
                            "header.magic: not a seamwalk pack (expected \"SWPACK\\r\\n\")");
    if (h->byte_order != SW_PACK_BYTE_ORDER_MARK) {
        if (h->byte_order == 0x04030201u)
            return sw_error_set(err, SW_ERR_FORMAT,
                                "header.byte_order: 0x04030201, the pack is little-endian and "
                                "this host is big-endian");
        return sw_error_set(err, SW_ERR_FORMAT, "header.byte_order: 0x%08x, expected 0x%08x",
                            (unsigned)h->byte_order, SW_PACK_BYTE_ORDER_MARK);
    }
    if (h->version != SW_PACK_VERSION && h->version != SW_PACK_VERSION_INSTANCED)
        return sw_error_set(err, SW_ERR_VERSION, "header.version: %u, this build reads versions "
                            "%u and %u", (unsigned)h->version, SW_PACK_VERSION,
                            SW_PACK_VERSION_INSTANCED);
    if (h->total_size != actual_size)
        return sw_error_set(err, SW_ERR_FORMAT,
                            "header.total_size: %llu, but the %s is %llu bytes%s",
                            (unsigned long long)h->total_size, what,
                            (unsigned long long)actual_size,
                            h->total_size > actual_size ? " (truncated)" : "");
    return SW_OK;
}

/* XXH3-64 of the header with header_checksum read as zero, then the table. */
static uint64_t header_checksum(const uint8_t *data, uint32_t section_count)
{
    sw_pack_header copy;
    memcpy(&copy, data, sizeof copy);
    copy.header_checksum = 0;
    XXH3_state_t state;
    XXH3_INITSTATE(&state);
    XXH3_64bits_reset(&state);
    XXH3_64bits_update(&state, &copy, sizeof copy);
    XXH3_64bits_update(&state, data + HEADER_BYTES, (size_t)section_count * SECTION_BYTES);
    return XXH3_64bits_digest(&state);
}

static sw_status check_header(const uint8_t *data, size_t size, sw_error *err)
{
    const sw_pack_header *h = (const sw_pack_header *)data;
    sw_status s = sw_pack_check_header_identity(h, size, "data", err);
    if (s != SW_OK)
        return s;
    if (h->section_count < 1 || h->section_count > SW_PACK_MAX_SECTIONS)
        return sw_error_set(err, SW_ERR_FORMAT, "header.section_count: %u, expected 1..%u",
                            (unsigned)h->section_count, SW_PACK_MAX_SECTIONS);
    if (h->section_table_offset != HEADER_BYTES)
        return sw_error_set(err, SW_ERR_FORMAT, "header.section_table_offset: %u, expected %d",
                            (unsigned)h->section_table_offset, HEADER_BYTES);
    uint64_t table_end = HEADER_BYTES + (uint64_t)h->section_count * SECTION_BYTES;
    if (table_end > size)
        return sw_error_set(err, SW_ERR_FORMAT,
                            "header.section_count: %u sections end at byte %llu, past the "
                            "end of the %zu-byte pack",
                            (unsigned)h->section_count, (unsigned long long)table_end, size);
    uint64_t computed = header_checksum(data, h->section_count);
    if (computed != h->header_checksum)
        return sw_error_set(err, SW_ERR_CHECKSUM,
                            "header.header_checksum: mismatch (stored 0x%016llx, computed "
                            "0x%016llx): the header or the section table is corrupt",
                            (unsigned long long)h->header_checksum,
                            (unsigned long long)computed);
    for (size_t i = 0; i < sizeof h->reserved; i++)
        if (h->reserved[i] != 0)
            return sw_error_set(err, SW_ERR_FORMAT, "header.reserved[%zu]: 0x%02x, expected 0",
                                i, h->reserved[i]);
    return SW_OK;
}

/* "section 2 (PATCHES)" or "section 7 (type 99)", for messages. */
static const char *section_label(char *buf, size_t cap, uint32_t index, uint32_t type)
{
    const char *name = sw_section_type_name(type);
    if (strcmp(name, "unknown") == 0)
        snprintf(buf, cap, "section %u (type %u)", (unsigned)index, (unsigned)type);
    else
        snprintf(buf, cap, "section %u (%s)", (unsigned)index, name);
    return buf;
}

static sw_status check_section(size_t size, uint64_t table_end, uint32_t index,
                               const sw_pack_section *s, sw_error *err)
{
    char label[48];
    section_label(label, sizeof label, index, s->type);
    if (s->offset % SW_PACK_ALIGN != 0)
        return sw_error_set(err, SW_ERR_FORMAT, "%s: offset %llu is not a multiple of %u", label,
                            (unsigned long long)s->offset, SW_PACK_ALIGN);
    if (s->offset < table_end)
        return sw_error_set(err, SW_ERR_FORMAT,
                            "%s: offset %llu lies in the header or section table (ends at %llu)",
                            label, (unsigned long long)s->offset, (unsigned long long)table_end);
    if (s->offset > size || s->size > size - s->offset)
        return sw_error_set(err, SW_ERR_FORMAT,
                            "%s: offset %llu + size %llu exceeds the pack size %zu", label,
                            (unsigned long long)s->offset, (unsigned long long)s->size, size);
    if (s->flags != 0)
        return sw_error_set(err, SW_ERR_FORMAT, "%s: flags 0x%x, expected 0 in version %u", label,
                            (unsigned)s->flags, SW_PACK_VERSION);
    return SW_OK;
}

/* The checksums of the sections before the first whose bounds fail, as
 * parts (sw_parts.h), largest section first so that parts run at once end
 * together: on the showroom SEAM_VERTICES alone is half the bytes. */
typedef struct checksum_job {
    const uint8_t *data;
    const sw_pack_section *sections;
    uint32_t order[SW_PACK_MAX_SECTIONS];
    uint64_t computed[SW_PACK_MAX_SECTIONS];
} checksum_job;

static void checksum_part(void *arg, uint32_t p)
{
    checksum_job *job = arg;
    const sw_pack_section *s = &job->sections[job->order[p]];
    job->computed[job->order[p]] = XXH3_64bits(job->data + s->offset, (size_t)s->size);
}

/* Sections [0, count) by size, largest first (at most 256: insertion). */
static void order_by_size(checksum_job *job, uint32_t count)
{
    for (uint32_t i = 0; i < count; i++) {
        uint32_t j = i;
        for (; j > 0 && job->sections[job->order[j - 1]].size < job->sections[i].size; j--)
            job->order[j] = job->order[j - 1];
        job->order[j] = i;
    }
}

/* Every section's bounds, then the checksums of those before the first
 * that fails them; the first problem in table order is named, as one pass
 * checking each section whole would. */
static sw_status check_sections(const uint8_t *data, size_t size, const sw_parts_runner *runner,
                                sw_error *err)
{
    const sw_pack_header *h = (const sw_pack_header *)data;
    const sw_pack_section *sections = (const sw_pack_section *)(data + HEADER_BYTES);
    uint64_t table_end = HEADER_BYTES + (uint64_t)h->section_count * SECTION_BYTES;
    sw_error bounds_err = { SW_OK, "" };
    sw_status bounds = SW_OK;
    uint32_t good = 0;
    while (good < h->section_count &&
           (bounds = check_section(size, table_end, good, &sections[good], &bounds_err)) == SW_OK)
        good++;
    checksum_job job = {.data = data, .sections = sections};
    order_by_size(&job, good);
    sw_parts_run(runner, checksum_part, &job, good);
    for (uint32_t i = 0; i < good; i++)
        if (job.computed[i] != sections[i].checksum) {
            char label[48];
            return sw_error_set(err, SW_ERR_CHECKSUM, "%s: checksum mismatch (stored 0x%016llx, "
                                "computed 0x%016llx)",
                                section_label(label, sizeof label, i, sections[i].type),
                                (unsigned long long)sections[i].checksum,
                                (unsigned long long)job.computed[i]);
        }
    if (bounds != SW_OK && err)
        *err = bounds_err;
    return bounds;
}

/* At most 256 sections, so comparing every pair costs nothing worth sorting
 * for. Empty sections occupy no bytes and overlap nothing. */
static sw_status check_overlaps(const sw_pack_section *sections, uint32_t count, sw_error *err)
{
    for (uint32_t i = 0; i < count; i++) {
        for (uint32_t j = i + 1; j < count; j++) {
            const sw_pack_section *a = &sections[i], *b = &sections[j];
            if (a->size == 0 || b->size == 0)
                continue;
            if (a->offset < b->offset + b->size && b->offset < a->offset + a->size) {
                char la[48], lb[48];
                return sw_error_set(err, SW_ERR_FORMAT, "%s: bytes %llu..%llu overlap %s",
                                    section_label(la, sizeof la, j, b->type),
                                    (unsigned long long)b->offset,
                                    (unsigned long long)(b->offset + b->size - 1),
                                    section_label(lb, sizeof lb, i, a->type));
            }
        }
    }
    return SW_OK;
}

/* Finds the known sections: every known type at most once, META, PARTS,
 * PATCHES and CONTROL exactly once; unknown types are left alone (they passed
 * the bounds and checksum checks already). index[type] is the table index,
 * or -1. */
static sw_status find_sections(const sw_pack_section *sections, uint32_t count,
                               int32_t index[LAST_KNOWN + 1], sw_error *err)
{
    for (uint32_t t = 0; t <= LAST_KNOWN; t++)
        index[t] = -1;
    for (uint32_t i = 0; i < count; i++) {
        uint32_t t = sections[i].type;
        if (!indexed_here(t))
            continue;
        if (index[t] >= 0)
            return sw_error_set(err, SW_ERR_FORMAT, "section %u (%s): a second %s section "
                                "(the first is section %d)", (unsigned)i,
                                sw_section_type_name(t), sw_section_type_name(t), (int)index[t]);
        index[t] = (int32_t)i;
    }
    for (uint32_t t = SW_SECTION_META; t < SW_SECTION_ADJACENCY; t++)
        if (index[t] < 0)
            return sw_error_set(err, SW_ERR_FORMAT, "section table: no %s section (required)",
                                sw_section_type_name(t));
    return SW_OK;
}

/* The Seam Graph: all eight sections or none (each is useless without the
 * others, and SEAM's counts size them all), and its loops index SURFACES. */
static sw_status check_seam_group(const int32_t index[LAST_KNOWN + 1], sw_error *err)
{
    int32_t seam = index[SW_SECTION_SEAM];
    for (uint32_t t = SW_SECTION_SEAM_VERTICES; seam < 0 && t <= SW_SECTION_SEAM_SURFACE_LOOPS;
         t++)
        if (index[t] >= 0)
            return sw_error_set(err, SW_ERR_FORMAT, "section %d (%s): present without a SEAM "
                                "section", (int)index[t], sw_section_type_name(t));
    if (seam < 0)
        return SW_OK;
    for (uint32_t t = SW_SECTION_SEAM_VERTICES; t <= SW_SECTION_SEAM_SURFACE_LOOPS; t++)
        if (index[t] < 0)
            return sw_error_set(err, SW_ERR_FORMAT, "section %d (SEAM): no %s section (the "
                                "Seam Graph's sections appear together)", (int)seam,
                                sw_section_type_name(t));
    if (index[SW_SECTION_SURFACES] < 0)
        return sw_error_set(err, SW_ERR_FORMAT, "section %d (SEAM): present without a SURFACES "
                            "section (its loops index SURFACES)", (int)seam);
    return SW_OK;
}

/* The static levels: all seven sections or none (LEVELS' counts size the
 * others), and only beside a Seam Graph (a level's chains follow its loops). */
static sw_status check_levels_group(const int32_t index[LAST_KNOWN + 1], sw_error *err)
{
    int32_t levels = index[SW_SECTION_LEVELS];
    for (uint32_t t = SW_SECTION_LEVEL_RECORDS; levels < 0 && t <= LAST_KNOWN; t++)
        if (index[t] >= 0)
            return sw_error_set(err, SW_ERR_FORMAT, "section %d (%s): present without a LEVELS "
                                "section", (int)index[t], sw_section_type_name(t));
    if (levels < 0)
        return SW_OK;
    for (uint32_t t = SW_SECTION_LEVEL_RECORDS; t <= LAST_KNOWN; t++)
        if (index[t] < 0)
            return sw_error_set(err, SW_ERR_FORMAT, "section %d (LEVELS): no %s section (the "
                                "levels' sections appear together)", (int)levels,
                                sw_section_type_name(t));
    if (index[SW_SECTION_SEAM] < 0)
        return sw_error_set(err, SW_ERR_FORMAT, "section %d (LEVELS): present without a Seam "
                            "Graph (a level's chains follow its loops)", (int)levels);
    return SW_OK;
}

/* The trimmed-surface group: its records index SURFACES, and every patch of
 * a pack with surfaces needs its domain, so the others are meaningless
 * alone. VIEWPOINTS and PART_TRANSFORMS stand on their own. */
static sw_status check_groups(const int32_t index[LAST_KNOWN + 1], sw_error *err)
{
    static const uint32_t needs_surfaces[] = { SW_SECTION_TRIM_LOOPS, SW_SECTION_TRIM_CURVES,
                                               SW_SECTION_TRIM_DATA, SW_SECTION_PATCH_DOMAINS,
                                               SW_SECTION_TRIM_MASKS };
    int32_t surfaces = index[SW_SECTION_SURFACES];
    for (size_t k = 0; surfaces < 0 && k < sizeof needs_surfaces / sizeof *needs_surfaces; k++) {
        uint32_t t = needs_surfaces[k];
        if (index[t] >= 0)
            return sw_error_set(err, SW_ERR_FORMAT, "section %d (%s): present without a "
                                "SURFACES section", (int)index[t], sw_section_type_name(t));
    }
    if (surfaces >= 0 && index[SW_SECTION_PATCH_DOMAINS] < 0)
        return sw_error_set(err, SW_ERR_FORMAT, "section %d (SURFACES): no PATCH_DOMAINS "
                            "section (required with SURFACES)", (int)surfaces);
    sw_status s = check_seam_group(index, err);
    return s == SW_OK ? check_levels_group(index, err) : s;
}

/* Each known section's size must be its count (in META, SEAM or LEVELS, named by
 * count_name) times its record size. */
static sw_status check_section_size(const sw_pack_section *sections, int32_t index,
                                    uint32_t type, uint64_t count, uint64_t record,
                                    const char *count_name, sw_error *err)
{
    uint64_t expected = count * record;
    uint64_t actual = index >= 0 ? sections[index].size : 0;
    if (actual == expected)
        return SW_OK;
    if (index < 0)
        return sw_error_set(err, SW_ERR_FORMAT,
                            "%s: %llu, but there is no %s section", count_name,
                            (unsigned long long)count, sw_section_type_name(type));
    return sw_error_set(err, SW_ERR_FORMAT,
                        "section %d (%s): %llu bytes, expected %s %llu x %llu = %llu",
                        (int)index, sw_section_type_name(type), (unsigned long long)actual,
                        count_name, (unsigned long long)count, (unsigned long long)record,
                        (unsigned long long)expected);
}

static sw_status map_sections(const uint8_t *data, const int32_t index[], sw_pack *out,
                              sw_error *err)
{
    const sw_pack_section *sec = out->sections;
    const sw_pack_section *meta = &sec[index[SW_SECTION_META]];
    if (meta->size != sizeof(sw_pack_meta))
        return sw_error_set(err, SW_ERR_FORMAT, "section %d (META): %llu bytes, expected %zu",
                            (int)index[SW_SECTION_META], (unsigned long long)meta->size,
                            sizeof(sw_pack_meta));
    const sw_pack_meta *m = (const sw_pack_meta *)(data + meta->offset);
    sw_status s;
    if ((s = check_section_size(sec, index[SW_SECTION_PARTS], SW_SECTION_PARTS, m->part_count,
                                sizeof(sw_pack_part), "META.part_count", err)) != SW_OK ||
        (s = check_section_size(sec, index[SW_SECTION_PATCHES], SW_SECTION_PATCHES,
                                m->patch_count, sizeof(sw_pack_patch), "META.patch_count",
                                err)) != SW_OK ||
        (s = check_section_size(sec, index[SW_SECTION_CONTROL], SW_SECTION_CONTROL,
                                m->control_count, CONTROL_POINT_BYTES, "META.control_count",
                                err)) != SW_OK ||
        (s = check_section_size(sec, index[SW_SECTION_ADJACENCY], SW_SECTION_ADJACENCY,
                                m->adjacency_count, sizeof(sw_pack_adjacency),
                                "META.adjacency_count", err)) != SW_OK)
        return s;
    out->meta = m;
    out->parts = (const sw_pack_part *)(data + sec[index[SW_SECTION_PARTS]].offset);
    out->patches = (const sw_pack_patch *)(data + sec[index[SW_SECTION_PATCHES]].offset);
    out->control = (const float *)(data + sec[index[SW_SECTION_CONTROL]].offset);
    out->adjacency = index[SW_SECTION_ADJACENCY] >= 0
                         ? (const sw_pack_adjacency *)(data +
                                                       sec[index[SW_SECTION_ADJACENCY]].offset)
                         : NULL;
    return SW_OK;
}

/* An optional section of whole records whose count is its size / record:
 * *view is NULL and *count 0 when it is absent. */
static sw_status record_view(const uint8_t *data, const sw_pack_section *sections, int32_t index,
                             uint64_t record, const void **view, uint32_t *count, sw_error *err)
{
    *view = NULL;
    *count = 0;
    if (index < 0)
        return SW_OK;
    const sw_pack_section *s = &sections[index];
    const char *name = sw_section_type_name(s->type);
    if (s->size % record != 0)
        return sw_error_set(err, SW_ERR_FORMAT, "section %d (%s): %llu bytes, not a multiple "
                            "of its %llu-byte record", (int)index, name,
                            (unsigned long long)s->size, (unsigned long long)record);
    if (s->size / record > UINT32_MAX)
        return sw_error_set(err, SW_ERR_RANGE, "section %d (%s): %llu records, at most %u",
                            (int)index, name, (unsigned long long)(s->size / record),
                            UINT32_MAX);
    *view = data + s->offset;
    *count = (uint32_t)(s->size / record);
    return SW_OK;
}

/* The optional sections sized by META's counts (one record per patch or
 * per part): NULL when absent. */
static sw_status counted_view(const uint8_t *data, const sw_pack_section *sections, int32_t index,
                              uint32_t type, uint32_t count, uint64_t record,
                              const char *count_name, const void **view, sw_error *err)
{
    *view = NULL;
    if (index < 0)
        return SW_OK;
    sw_status s = check_section_size(sections, index, type, count, record, count_name, err);
    if (s == SW_OK)
        *view = data + sections[index].offset;
    return s;
}

static sw_status map_optional(const uint8_t *data, const int32_t index[], sw_pack *out,
                              sw_error *err)
{
    const sw_pack_section *sec = out->sections;
    const void *v[8];
    sw_status s;
    if ((s = check_groups(index, err)) != SW_OK ||
        (s = record_view(data, sec, index[SW_SECTION_SURFACES], sizeof(sw_pack_surface), &v[0],
                         &out->surface_count, err)) != SW_OK ||
        (s = record_view(data, sec, index[SW_SECTION_TRIM_LOOPS], sizeof(sw_pack_trim_loop),
                         &v[1], &out->trim_loop_count, err)) != SW_OK ||
        (s = record_view(data, sec, index[SW_SECTION_TRIM_CURVES], sizeof(sw_pack_trim_curve),
                         &v[2], &out->trim_curve_count, err)) != SW_OK ||
        (s = record_view(data, sec, index[SW_SECTION_TRIM_DATA], sizeof(float), &v[3],
                         &out->trim_data_count, err)) != SW_OK ||
        (s = counted_view(data, sec, index[SW_SECTION_PATCH_DOMAINS], SW_SECTION_PATCH_DOMAINS,
                          out->meta->patch_count, sizeof(sw_pack_patch_domain),
                          "META.patch_count", &v[4], err)) != SW_OK ||
        (s = record_view(data, sec, index[SW_SECTION_TRIM_MASKS], sizeof(sw_pack_trim_mask),
                         &v[5], &out->trim_mask_count, err)) != SW_OK ||
        (s = record_view(data, sec, index[SW_SECTION_VIEWPOINTS], sizeof(sw_pack_viewpoint),
                         &v[6], &out->viewpoint_count, err)) != SW_OK ||
        (s = counted_view(data, sec, index[SW_SECTION_PART_TRANSFORMS],
                          SW_SECTION_PART_TRANSFORMS, out->meta->part_count, TRANSFORM_BYTES,
                          "META.part_count", &v[7], err)) != SW_OK)
        return s;
    out->surfaces = v[0];
    out->trim_loops = v[1];
    out->trim_curves = v[2];
    out->trim_data = v[3];
    out->patch_domains = v[4];
    out->trim_masks = v[5];
    out->viewpoints = v[6];
    out->part_transforms = v[7];
    return SW_OK;
}

/* One section of a group whose header record holds the counts. */
typedef struct counted_section {
    uint32_t type;
    uint64_t count, record;
    const char *name;   /* the count, for messages: "SEAM.vertex_count" */
} counted_section;

/* v[k] = the bytes of group[k], each exactly its count times its record
 * size (check_groups made sure every one is present). */
static sw_status map_counted(const uint8_t *data, const int32_t index[],
                             const sw_pack_section *sec, const counted_section *group, size_t n,
                             const void **v, sw_error *err)
{
    for (size_t k = 0; k < n; k++) {
        int32_t i = index[group[k].type];
        sw_status s = check_section_size(sec, i, group[k].type, group[k].count, group[k].record,
                                         group[k].name, err);
        if (s != SW_OK)
            return s;
        v[k] = data + sec[i].offset;
    }
    return SW_OK;
}

/* The Seam Graph's views, each section sized by its SEAM count (check_groups
 * made sure all eight are present or none). */
static sw_status map_seam(const uint8_t *data, const int32_t index[], sw_pack *out, sw_error *err)
{
    const sw_pack_section *sec = out->sections;
    int32_t at = index[SW_SECTION_SEAM];
    if (at < 0)
        return SW_OK;
    if (sec[at].size != sizeof(sw_pack_seam))
        return sw_error_set(err, SW_ERR_FORMAT, "section %d (SEAM): %llu bytes, expected %zu",
                            (int)at, (unsigned long long)sec[at].size, sizeof(sw_pack_seam));
    const sw_pack_seam *h = (const sw_pack_seam *)(data + sec[at].offset);
    const counted_section parts[] = {
        { SW_SECTION_SEAM_VERTICES, h->vertex_count, sizeof(sw_seam_vertex), "SEAM.vertex_count" },
        { SW_SECTION_SEAM_SLOTS, h->slot_count, sizeof(sw_seam_slot), "SEAM.slot_count" },
        { SW_SECTION_SEAM_LOOPS, h->loop_count, sizeof(sw_seam_loop), "SEAM.loop_count" },
        { SW_SECTION_SEAM_EDGES, h->edge_count, sizeof(sw_seam_edge), "SEAM.edge_count" },
        { SW_SECTION_SEAM_COLLAPSES, h->collapse_count, sizeof(sw_seam_collapse),
          "SEAM.collapse_count" },
        { SW_SECTION_SEAM_SLOT_REFS, h->slot_ref_count, sizeof(uint32_t), "SEAM.slot_ref_count" },
        { SW_SECTION_SEAM_SURFACE_LOOPS, (uint64_t)h->surface_count + 1, sizeof(uint32_t),
          "(SEAM.surface_count + 1)" },
    };
    const void *v[sizeof parts / sizeof *parts];
    sw_status s = map_counted(data, index, sec, parts, sizeof parts / sizeof *parts, v, err);
    if (s != SW_OK)
        return s;
    out->seam_header = h;
    out->seam = (sw_seam_graph){
        .vertices = v[0], .slots = v[1], .loops = v[2], .edges = v[3], .collapses = v[4],
        .slot_refs = v[5], .surface_loops = v[6], .vertex_count = h->vertex_count,
        .original_count = h->original_count, .slot_count = h->slot_count,
        .loop_count = h->loop_count, .edge_count = h->edge_count,
        .collapse_count = h->collapse_count, .slot_ref_count = h->slot_ref_count,
        .surface_count = h->surface_count, .tolerance = h->tolerance };
    return SW_OK;
}

/* The levels' views, each section sized by its LEVELS count (check_groups
 * made sure all seven are present or none). LEVEL_INDICES is exactly
 * index_count x 2 bytes, even when that is no multiple of 4: sizes are
 * exact and only offsets are aligned. */
static sw_status map_levels(const uint8_t *data, const int32_t index[], sw_pack *out,
                            sw_error *err)
{
    const sw_pack_section *sec = out->sections;
    int32_t at = index[SW_SECTION_LEVELS];
    if (at < 0)
        return SW_OK;
    if (sec[at].size != sizeof(sw_pack_levels))
        return sw_error_set(err, SW_ERR_FORMAT, "section %d (LEVELS): %llu bytes, expected %zu",
                            (int)at, (unsigned long long)sec[at].size, sizeof(sw_pack_levels));
    const sw_pack_levels *h = (const sw_pack_levels *)(data + sec[at].offset);
    const counted_section parts[] = {
        { SW_SECTION_LEVEL_RECORDS, h->level_count, sizeof(sw_level), "LEVELS.level_count" },
        { SW_SECTION_LEVEL_SURFACES, (uint64_t)h->surface_count + 1, sizeof(uint32_t),
          "(LEVELS.surface_count + 1)" },
        { SW_SECTION_LEVEL_VERTICES, h->vertex_count, sizeof(sw_level_vertex),
          "LEVELS.vertex_count" },
        { SW_SECTION_LEVEL_INDICES, h->index_count, sizeof(uint16_t), "LEVELS.index_count" },
        { SW_SECTION_LEVEL_CHAINS, h->chain_count, sizeof(sw_level_chain), "LEVELS.chain_count" },
        { SW_SECTION_LEVEL_CHAIN_POINTS, h->chain_point_count, sizeof(sw_strip_point),
          "LEVELS.chain_point_count" },
    };
    const void *v[sizeof parts / sizeof *parts];
    sw_status s = map_counted(data, index, sec, parts, sizeof parts / sizeof *parts, v, err);
    if (s != SW_OK)
        return s;
    out->levels_header = h;
    out->levels = (sw_levels){
        .levels = v[0], .surface_levels = v[1], .vertices = v[2], .indices = v[3],
        .chains = v[4], .chain_points = v[5], .level_count = h->level_count,
        .vertex_count = h->vertex_count, .index_count = h->index_count,
        .chain_count = h->chain_count, .chain_point_count = h->chain_point_count,
        .surface_count = h->surface_count };
    return SW_OK;
}

/* After the seam sections are validated: the walk's size follows their
 * indices. The header must hold at least what this reader's runtime takes
 * (the runtime sizes its arena from it before reading the pack); more is
 * a pack written when the runtime took more, which still runs: a unit
 * whose firmware is updated keeps walking the packs it holds. A pack whose
 * graph this reader skips (the seam sections under types it does not know)
 * may count a walk it cannot size: then the value must cover the pack. */
static sw_status check_runtime_bytes(const sw_pack *pack, sw_error *err)
{
    /* A placed pack's is the placed scene's: sw_pack_map_instances checks it
     * (and that the version and the sections agree). */
    if (pack->header->version == SW_PACK_VERSION_INSTANCED)
        return SW_OK;
    for (uint32_t i = 0; i < pack->header->section_count; i++)
        if (pack->sections[i].type == SW_SECTION_PROTOTYPES ||
            pack->sections[i].type == SW_SECTION_INSTANCES)
            return SW_OK;
    uint64_t walk = pack->seam_header ? sw_walk_arena_bytes(&pack->seam, pack->surfaces) : 0;
    uint64_t expected = sw_pack_runtime_bytes(walk);
    uint64_t got = pack->header->runtime_bytes;
    if (got < expected)
        return sw_error_set(err, SW_ERR_FORMAT,
                            "header.runtime_bytes: %llu, expected at least %llu for a walk "
                            "of %llu bytes (its seamwalk-pack's runtime took less than this "
                            "one: build it again)",
                            (unsigned long long)pack->header->runtime_bytes,
                            (unsigned long long)expected, (unsigned long long)walk);
    return SW_OK;
}

sw_status sw_pack_open_memory(const void *data, size_t size, sw_pack *out, sw_error *err)
{
    return sw_pack_open_memory_with(data, size, NULL, out, err);
}

sw_status sw_pack_open_memory_with(const void *data, size_t size, const sw_parts_runner *runner,
                                   sw_pack *out, sw_error *err)
{
    if (!out)
        return sw_error_set(err, SW_ERR_ARG, "sw_pack_open_memory: out is NULL");
    memset(out, 0, sizeof *out);
    if (size < HEADER_BYTES || !data)
        return sw_error_set(err, SW_ERR_FORMAT, "header: %zu bytes, a pack is at least %d",
                            data ? size : 0, HEADER_BYTES);
    if ((uintptr_t)data % 8 != 0)
        return sw_error_set(err, SW_ERR_ARG, "sw_pack_open_memory: data at %p is not 8-byte "
                            "aligned", data);
    const uint8_t *bytes = data;
    sw_status s = check_header(bytes, size, err);
    if (s != SW_OK)
        return s;
    const sw_pack_header *h = data;
    const sw_pack_section *sections = (const sw_pack_section *)(bytes + HEADER_BYTES);
    if ((s = check_sections(bytes, size, runner, err)) != SW_OK)
        return s;
    if ((s = check_overlaps(sections, h->section_count, err)) != SW_OK)
        return s;
    int32_t index[LAST_KNOWN + 1];
    if ((s = find_sections(sections, h->section_count, index, err)) != SW_OK)
        return s;
    sw_pack pack = { .data = bytes, .size = size, .header = h, .sections = sections };
    if ((s = map_sections(bytes, index, &pack, err)) != SW_OK ||
        (s = map_optional(bytes, index, &pack, err)) != SW_OK ||
        (s = map_seam(bytes, index, &pack, err)) != SW_OK ||
        (s = map_levels(bytes, index, &pack, err)) != SW_OK ||
        (s = sw_pack_validate_records(&pack, err)) != SW_OK ||
        (s = sw_pack_validate_trim(&pack, err)) != SW_OK ||
        (s = sw_pack_validate_seam(&pack, runner, err)) != SW_OK ||
        (s = sw_pack_validate_levels(&pack, runner, err)) != SW_OK ||
        (s = check_runtime_bytes(&pack, err)) != SW_OK ||
        (s = sw_pack_map_orientation(bytes, &pack, err)) != SW_OK ||
        (s = sw_pack_map_import_notes(bytes, &pack, err)) != SW_OK ||
        (s = sw_pack_map_supers(bytes, &pack, err)) != SW_OK ||
        (s = sw_pack_map_part_levels(bytes, &pack, err)) != SW_OK ||
        (s = sw_pack_map_instances(bytes, &pack, err)) != SW_OK)
        return s;
    *out = pack;
    return SW_OK;
}
