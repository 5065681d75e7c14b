/* SPDX-License-Identifier: MIT */
/* The pack: seamwalk's preprocessed model file, version 1, and its reader.
 * Written by seamwalk-pack on the host (assets/pack/sw_pack_write.c), read here by
 * the runtime and the host tools (core/sw_pack_read.c, sw_pack_validate.c). The format is specified in assets/PACK_FORMAT.md;
 * the structs below are its on-disk records (little-endian, no padding; the
 * _Static_asserts in sw_pack_read.c pin every size and offset).
 *
 * A pack is untrusted input: sw_pack_open_memory checks the header, the section
 * table, every checksum, every count and every index once, so code that walks
 * a validated sw_pack needs no further checks. */
#ifndef SW_PACK_H
#define SW_PACK_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "sw_arena.h"
#include "sw_error.h"
#include "sw_levels.h"
#include "sw_part_levels.h"
#include "sw_parts.h"
#include "sw_seam_graph.h"
#include "sw_super.h"

#define SW_PACK_MAGIC "SWPACK\r\n"        /* 8 bytes, no terminator in the file */
#define SW_PACK_VERSION 1u
#define SW_PACK_VERSION_INSTANCED 2u      /* a pack with PROTOTYPES and INSTANCES */
#define SW_PACK_BYTE_ORDER_MARK 0x01020304u /* reads 0x04030201 on a big-endian host */
#define SW_PACK_ALIGN 64u                  /* every section offset is a multiple */
#define SW_PACK_MAX_SECTIONS 256u

enum sw_section_type {
    SW_SECTION_META = 1,      /* one sw_pack_meta */
    SW_SECTION_PARTS = 2,     /* sw_pack_part[part_count] */
    SW_SECTION_PATCHES = 3,   /* sw_pack_patch[patch_count] */
    SW_SECTION_CONTROL = 4,   /* float[4 * control_count]: x, y, z, w per point */
    SW_SECTION_ADJACENCY = 5, /* sw_pack_adjacency[adjacency_count] */
    /* Trimmed-surface sections. Optional as a group: a pack of
     * untrimmed Bezier patches may omit them all; if SURFACES is present,
     * PATCH_DOMAINS must be too, and the other four need SURFACES (absent
     * ones count as empty). Each known type appears at most once. Their
     * record counts are size / record size, exact multiples; PATCH_DOMAINS
     * and PART_TRANSFORMS have one record per patch and per part. */
    SW_SECTION_SURFACES = 6,        /* sw_pack_surface[] */
    SW_SECTION_TRIM_LOOPS = 7,      /* sw_pack_trim_loop[] */
    SW_SECTION_TRIM_CURVES = 8,     /* sw_pack_trim_curve[] */
    SW_SECTION_TRIM_DATA = 9,       /* float[]: the trim curves' knots and (u, v, w) points */
    SW_SECTION_PATCH_DOMAINS = 10,  /* sw_pack_patch_domain[patch_count] */
    SW_SECTION_TRIM_MASKS = 11,     /* sw_pack_trim_mask[] */
    SW_SECTION_VIEWPOINTS = 12,     /* sw_pack_viewpoint[] */
    SW_SECTION_PART_TRANSFORMS = 13,/* float[16 * part_count], column-major, as sw_mat4, affine */
    /* The Seam Graph (core/sw_seam_graph.h). Optional as a group: all eight
     * appear together or none does, and they need SURFACES (loops index it).
     * SEAM holds every count; each other section is exactly its count times
     * its record size. An older version-1 reader skips them as unknown types
     * and draws with the trim masks instead. */
    SW_SECTION_SEAM = 14,               /* one sw_pack_seam */
    SW_SECTION_SEAM_VERTICES = 15,      /* sw_seam_vertex[vertex_count] */
    SW_SECTION_SEAM_SLOTS = 16,         /* sw_seam_slot[slot_count] */
    SW_SECTION_SEAM_LOOPS = 17,         /* sw_seam_loop[loop_count] */
    SW_SECTION_SEAM_EDGES = 18,         /* sw_seam_edge[edge_count] */
    SW_SECTION_SEAM_COLLAPSES = 19,     /* sw_seam_collapse[collapse_count] */
    SW_SECTION_SEAM_SLOT_REFS = 20,     /* uint32_t[slot_ref_count] */
    SW_SECTION_SEAM_SURFACE_LOOPS = 21, /* uint32_t[surface_count + 1] */
    /* 22 is SIGNATURE (core/sw_pack_signature.h). Which model axis points
     * up; optional, absent means +y, so packs written before it keep their
     * meaning and older readers skip it (core/sw_up_axis.h). */
    SW_SECTION_ORIENTATION = 23,        /* one sw_pack_orientation */
    /* What the import of each input skipped or read past, for `seamwalk-pack
     * info`; optional, absent means nothing to say (core/sw_pack_notes.h). */
    SW_SECTION_IMPORT_NOTES = 24,       /* sw_pack_import_note[] */
    /* Static levels of detail (core/sw_levels.h); optional, all seven or
     * none, and only beside a Seam Graph: absent, every surface is
     * tessellated on the fly. */
    SW_SECTION_LEVELS = 25,             /* one sw_pack_levels */
    SW_SECTION_LEVEL_RECORDS = 26,      /* sw_level[level_count] */
    SW_SECTION_LEVEL_SURFACES = 27,     /* uint32_t[surface_count + 1] */
    SW_SECTION_LEVEL_VERTICES = 28,     /* sw_level_vertex[vertex_count] */
    SW_SECTION_LEVEL_INDICES = 29,      /* uint16_t[index_count] */
    SW_SECTION_LEVEL_CHAINS = 30,       /* sw_level_chain[chain_count] */
    SW_SECTION_LEVEL_CHAIN_POINTS = 31, /* sw_strip_point[chain_point_count] */
    /* Super-surfaces (core/sw_super.h); optional, all three or none, and
     * only beside SURFACES (they index it). Each is a whole number of
     * records; SUPER_MEMBERS and SUPER_OF hold one per surface. */
    SW_SECTION_SUPER_SURFACES = 32,     /* sw_super_surface[] */
    SW_SECTION_SUPER_MEMBERS = 33,      /* uint32_t[surface_count]: surface indices */
    SW_SECTION_SUPER_OF = 34,           /* uint32_t[surface_count]: each surface's cluster */
    /* Part levels (core/sw_part_levels.h); optional, all six or none, and
     * only beside SURFACES (PART_LEVEL_PIECE_OF indexes it).
     * Older readers skip them; absent, every part is drawn by its
     * surfaces. */
    SW_SECTION_PART_LEVELS = 35,        /* one sw_pack_part_levels */
    SW_SECTION_PART_LEVEL_RECORDS = 36, /* sw_part_level[level_count] */
    SW_SECTION_PART_LEVEL_RANGES = 37,  /* uint32_t[piece_count + 1] */
    SW_SECTION_PART_LEVEL_VERTICES = 38,/* sw_level_vertex[vertex_count] */
    SW_SECTION_PART_LEVEL_INDICES = 39, /* uint16_t[index_count] */
    SW_SECTION_PART_LEVEL_PIECE_OF = 40,/* uint32_t[surface_count] */
    /* Instances (core/sw_pack_instances.h): the parts are stored once, in
     * runs that index nothing outside themselves (prototypes), and placed
     * by the instances; both or neither, and only in version 2, which
     * needs them (an older reader would draw every prototype once, where
     * it was modelled). */
    SW_SECTION_PROTOTYPES = 41,         /* sw_pack_prototype[] */
    SW_SECTION_INSTANCES = 42,          /* sw_pack_instance[] */
};

typedef struct sw_pack_header {       /* at offset 0, 64 bytes */
    char magic[8];                    /* SW_PACK_MAGIC */
    uint32_t version;                 /* SW_PACK_VERSION */
    uint32_t byte_order;              /* SW_PACK_BYTE_ORDER_MARK */
    uint64_t total_size;              /* bytes in the file */
    uint64_t runtime_bytes;           /* sw_pack_runtime_bytes(walk): the arena
                                         the runtime needs beside the pack's own bytes */
    uint32_t section_count;           /* 1..SW_PACK_MAX_SECTIONS */
    uint32_t section_table_offset;    /* 64: the table follows the header */
    uint64_t header_checksum;         /* XXH3-64 of header (this field 0) + section table */
    uint8_t reserved[16];             /* zero */
} sw_pack_header;

typedef struct sw_pack_section {      /* 32 bytes */
    uint32_t type;                    /* enum sw_section_type; unknown types are skipped */
    uint32_t flags;                   /* zero in version 1 */
    uint64_t offset;                  /* from the file start, multiple of SW_PACK_ALIGN */
    uint64_t size;                    /* bytes */
    uint64_t checksum;                /* XXH3-64 of the section's bytes */
} sw_pack_section;

enum sw_pack_units { SW_UNITS_UNSPECIFIED = 0, SW_UNITS_MILLIMETRE = 1, SW_UNITS_METRE = 2 };

typedef struct sw_pack_meta {         /* 64 bytes */
    uint32_t part_count;
    uint32_t patch_count;
    uint32_t control_count;
    uint32_t adjacency_count;
    float box_min[3], box_max[3];     /* of all patches */
    uint32_t units;                   /* enum sw_pack_units */
    float model_tolerance;            /* from the source file, 0 if unknown */
    uint8_t reserved[16];
} sw_pack_meta;

typedef struct sw_pack_part {         /* 80 bytes */
    uint32_t first_patch;
    uint32_t patch_count;
    float color[4];                   /* linear RGBA, each in [0, 1] */
    char name[56];                    /* NUL-terminated UTF-8 */
} sw_pack_part;

enum { SW_PATCH_RATIONAL = 1u };

typedef struct sw_pack_patch {        /* 48 bytes */
    uint32_t first_control;           /* index into CONTROL, in points */
    uint8_t degree_u, degree_v;       /* 1..15 */
    uint16_t flags;                   /* SW_PATCH_* */
    uint32_t part;                    /* index into PARTS */
    float box_min[3], box_max[3];     /* control-hull box */
    float d2_bound[3];                /* bounds of |F_uu|, |F_uv|, |F_vv| (sw_deriv_bounds) */
} sw_pack_patch;

enum sw_patch_edge { SW_EDGE_V0 = 0, SW_EDGE_U1 = 1, SW_EDGE_V1 = 2, SW_EDGE_U0 = 3 };

typedef struct sw_pack_adjacency {    /* 12 bytes: two patches share a boundary curve */
    uint32_t patch_a, patch_b;
    uint8_t edge_a, edge_b;           /* enum sw_patch_edge */
    uint8_t reversed;                 /* 1: b's edge runs against a's */
    uint8_t reserved;
} sw_pack_adjacency;

enum { SW_SURFACE_NO_LOOPS = 0 };

typedef struct sw_pack_surface {      /* 40 bytes: one trimmed NURBS surface of the source */
    uint32_t part;                    /* index into PARTS */
    uint32_t first_patch, patch_count;/* its Bezier patches, within the part's range */
    uint32_t first_loop, loop_count;  /* into TRIM_LOOPS; 0 loops: untrimmed */
    uint32_t flags;                   /* zero in version 1 */
    float domain[4];                  /* u0, u1, v0, v1, u0 < u1, v0 < v1 */
} sw_pack_surface;

enum { SW_LOOP_OUTER = 1u };

typedef struct sw_pack_trim_loop {    /* 12 bytes */
    uint32_t first_curve, curve_count;/* into TRIM_CURVES, head to tail, count >= 1 */
    uint32_t flags;                   /* SW_LOOP_* */
} sw_pack_trim_loop;

enum { SW_TRIM_RATIONAL = 1u, SW_TRIM_COMPUTED = 2u };

typedef struct sw_pack_trim_curve {   /* 16 bytes: a clamped B-spline in (u, v) */
    uint32_t first_float;             /* into TRIM_DATA: count + degree + 1 knots, */
    uint32_t count;                   /* then count points of (u, v, w) */
    uint8_t degree;                   /* 1..15 */
    uint8_t flags;                    /* SW_TRIM_* */
    uint16_t reserved;                /* zero */
    uint32_t reserved2;               /* zero */
} sw_pack_trim_curve;

#define SW_MASK_NONE 0xFFFFFFFFu /* a macro: enumerators must fit an int */

typedef struct sw_pack_patch_domain { /* 24 bytes, one per patch */
    uint32_t surface;                 /* into SURFACES */
    uint32_t mask;                    /* into TRIM_MASKS, or SW_MASK_NONE: wholly inside */
    float domain[4];                  /* u0, u1, v0, v1 within the surface's domain */
} sw_pack_patch_domain;

/* Which of the 32 x 32 equal cells of a patch's domain touch the trimmed
 * face: bit i of rows[j] is cell i along u, row j along v. Conservative: a
 * cell the trim boundary crosses is set. The runtime drops grid cells that
 * overlap no set cell; exact trimmed tessellation is the Seam Graph's job. */
typedef struct sw_pack_trim_mask {    /* 128 bytes */
    uint32_t rows[32];
} sw_pack_trim_mask;

typedef struct sw_pack_viewpoint {    /* 96 bytes: a named camera of a showroom scene */
    char name[48];                    /* NUL-terminated UTF-8 */
    float eye[3], target[3], up[3];
    float fov_deg;                    /* vertical; 0: the runtime's default */
    uint8_t reserved[8];              /* zero */
} sw_pack_viewpoint;

/* The Seam Graph's counts and sewing tolerance (section SEAM). */
typedef struct sw_pack_seam {         /* 64 bytes */
    uint32_t vertex_count;            /* original_count + collapse_count */
    uint32_t original_count;
    uint32_t slot_count;
    uint32_t loop_count;
    uint32_t edge_count;
    uint32_t collapse_count;
    uint32_t slot_ref_count;          /* == slot_count: every slot is listed once */
    uint32_t surface_count;           /* == the SURFACES count */
    float tolerance;                  /* the sewing tolerance, finite >= 0 */
    uint8_t reserved[28];             /* zero */
} sw_pack_seam;

/* Section ORIENTATION: the model's up axis, for the runtime's camera. */
typedef struct sw_pack_orientation {  /* 16 bytes */
    int32_t up_axis;                  /* enum sw_up_axis: +-1 x, +-2 y, +-3 z */
    uint8_t reserved[12];             /* zero */
} sw_pack_orientation;

/* Section IMPORT_NOTES: one record per input file and kind. */
enum sw_pack_note_kind { SW_NOTE_SKIPPED = 1, SW_NOTE_MESSAGE = 2 };
typedef struct sw_pack_import_note {  /* 128 bytes */
    uint32_t kind;                    /* SW_NOTE_SKIPPED: entities left out of the model;
                                         SW_NOTE_MESSAGE: messages about the file read past */
    uint32_t count;                   /* occurrences, >= 1 */
    char source[48];                  /* the input file's name, NUL-terminated UTF-8 */
    char what[72];                    /* "IGES 406", "STEP: Count of Parameters is not 2
                                         for si_unit", NUL-terminated UTF-8 */
} sw_pack_import_note;

/* The index spaces of a pack: each record kind that other records index,
 * and the flat arrays they index. A prototype is a run of each. */
enum sw_pack_space {
    SW_SPACE_PARTS, SW_SPACE_PATCHES, SW_SPACE_CONTROL, SW_SPACE_ADJACENCY, SW_SPACE_SURFACES,
    SW_SPACE_TRIM_LOOPS, SW_SPACE_TRIM_CURVES, SW_SPACE_TRIM_DATA, SW_SPACE_TRIM_MASKS,
    SW_SPACE_SEAM_ORIGINALS,      /* the Seam Graph's original vertices */
    SW_SPACE_SEAM_COLLAPSES,      /* its collapses, so its created vertices */
    SW_SPACE_SEAM_SLOTS, SW_SPACE_SEAM_LOOPS, SW_SPACE_SEAM_EDGES, SW_SPACE_SEAM_SLOT_REFS,
    SW_SPACE_LEVELS, SW_SPACE_LEVEL_VERTICES, SW_SPACE_LEVEL_INDICES, SW_SPACE_LEVEL_CHAINS,
    SW_SPACE_LEVEL_CHAIN_POINTS, SW_SPACE_SUPERS, SW_SPACE_SUPER_MEMBERS, SW_SPACE_PIECES,
    SW_SPACE_PART_LEVELS, SW_SPACE_PART_LEVEL_VERTICES, SW_SPACE_PART_LEVEL_INDICES,
    SW_SPACE_COUNT
};

/* Section PROTOTYPES: the parts stored once. Prototype k holds, in every
 * space, the run first[s] .. first[s] + count[s]; the runs tile each space
 * in prototype order, and a prototype's records index only its own runs. */
typedef struct sw_pack_prototype {    /* 216 bytes */
    uint32_t first[SW_SPACE_COUNT];
    uint32_t count[SW_SPACE_COUNT];
    float seam_tolerance;             /* its Seam Graph's sewing tolerance, in its own units
                                         (the SEAM record holds the largest); 0 without one */
    uint32_t reserved;                /* zero */
} sw_pack_prototype;

/* Section INSTANCES: where each prototype is placed, and as what. */
typedef struct sw_pack_instance {     /* 144 bytes */
    uint32_t prototype;               /* into PROTOTYPES */
    uint32_t flags;                   /* zero */
    float color[4];                   /* linear RGBA in [0, 1], for every part it places */
    float transform[16];              /* column-major as sw_mat4: a rotation, a uniform scale
                                         > 0 and a translation (no mirror) */
    char name[56];                    /* NUL-terminated UTF-8 */
} sw_pack_instance;

/* A validated pack: typed views into the caller's bytes (not copied). */
typedef struct sw_pack {
    const uint8_t *data;
    size_t size;
    const sw_pack_header *header;
    const sw_pack_section *sections;   /* header->section_count entries */
    const sw_pack_meta *meta;
    const sw_pack_part *parts;         /* meta->part_count */
    const sw_pack_patch *patches;      /* meta->patch_count */
    const float *control;              /* 4 * meta->control_count */
    const sw_pack_adjacency *adjacency;/* meta->adjacency_count */
    /* Optional sections: NULL with count 0 when absent. */
    const sw_pack_surface *surfaces;
    uint32_t surface_count;
    const sw_pack_trim_loop *trim_loops;
    uint32_t trim_loop_count;
    const sw_pack_trim_curve *trim_curves;
    uint32_t trim_curve_count;
    const float *trim_data;
    uint32_t trim_data_count;
    const sw_pack_patch_domain *patch_domains;   /* patch_count entries, or NULL */
    const sw_pack_trim_mask *trim_masks;
    uint32_t trim_mask_count;
    const sw_pack_viewpoint *viewpoints;
    uint32_t viewpoint_count;
    const float *part_transforms;                /* 16 * part_count, or NULL */
    int level_vertices_local;                    /* 1: the static and part levels'
                                                    vertices are their prototype's, in its
                                                    frame: a surface's or piece's are
                                                    placed by its part's transform
                                                    (sw_pack_expand_shared) */
    int control_local;                           /* 1: control is the prototypes'
                                                    points, in their frames: a patch's
                                                    are placed by its part's transform
                                                    (sw_pack_patch_control) */
    const uint32_t *stored_surface;              /* surface_count, or NULL: surface s is its
                                                    prototype's stored surface
                                                    stored_surface[s], whose static levels
                                                    it shares (levels.surface_levels NULL,
                                                    levels.levels the stored records:
                                                    sw_pack_surface_levels) and whose
                                                    patches' domains (patch_domains NULL:
                                                    sw_pack_domain_of) */
    const uint32_t *stored_surface_levels;       /* the stored surfaces' surface_levels, */
    const sw_pack_surface *stored_surfaces;      /* the stored surfaces, */
    const sw_pack_patch_domain *stored_domains;  /* and their patches' domains */
    /* The Seam Graph: views into the SEAM_* sections, every pointer NULL and
     * every count 0 when the pack has none. */
    const sw_pack_seam *seam_header;             /* NULL when absent */
    sw_seam_graph seam;
    const sw_pack_orientation *orientation;      /* NULL when absent: +y up */
    const sw_pack_import_note *import_notes;     /* NULL with count 0 when absent */
    uint32_t import_note_count;
    /* The static levels: views into the LEVEL_* sections, every pointer
     * NULL and every count 0 when the pack has none. */
    const sw_pack_levels *levels_header;         /* NULL when absent */
    sw_levels levels;
    /* The super-surfaces: views into the SUPER_* sections, every pointer
     * NULL and every count 0 when the pack has none. */
    sw_supers supers;
    /* The part levels: views into the PART_LEVEL* sections, every pointer
     * NULL and every count 0 when the pack has none. */
    sw_part_levels part_levels;
    /* The prototypes and their instances (version 2): NULL with count 0
     * when absent. A pack that has them is drawn through
     * sw_pack_expand (core/sw_pack_instances.h). */
    const sw_pack_prototype *prototypes;
    uint32_t prototype_count;
    const sw_pack_instance *instances;
    uint32_t instance_count;
} sw_pack;

/* The box of patches[first .. first + count)'s control hulls into lo and
 * hi (lo above hi, empty, when count is 0). */
static inline void sw_pack_patches_box(const sw_pack_patch *patches, uint32_t first,
                                       uint32_t count, float lo[3], float hi[3])
{
    for (int k = 0; k < 3; k++)
        lo[k] = 3.4e38f, hi[k] = -3.4e38f;
    for (uint32_t i = first; i < first + count; i++)
        for (int k = 0; k < 3; k++) {
            lo[k] = patches[i].box_min[k] < lo[k] ? patches[i].box_min[k] : lo[k];
            hi[k] = patches[i].box_max[k] > hi[k] ? patches[i].box_max[k] : hi[k];
        }
}

/* The diagonal of that box, 0 when empty. */
static inline double sw_pack_patches_diagonal(const sw_pack_patch *patches, uint32_t first,
                                              uint32_t count)
{
    float lo[3], hi[3];
    sw_pack_patches_box(patches, first, count, lo, hi);
    double d = 0;
    for (int k = 0; k < 3; k++)
        d += hi[k] > lo[k] ? ((double)hi[k] - lo[k]) * ((double)hi[k] - lo[k]) : 0;
    return sqrt(d);
}

/* runtime_bytes for a pack whose walk takes walk_bytes (sw_walk_arena_bytes
 * of its Seam Graph, 0 without one; every per-patch and per-surface state
 * is in its pools), and 64 bytes of alignment. Not the pack's
 * own bytes: the runtime maps the file (sw_pack_map_checked) and copies it
 * into the arena only when it cannot (sw_pack_arena_bytes). Writer, signer
 * and reader all use it (PACK_FORMAT.md, runtime_bytes). */
uint64_t sw_pack_runtime_bytes(uint64_t walk_bytes);

/* Arena bytes a pack of total_size bytes takes when it is copied into the
 * arena (sw_pack_load): the file, 64-byte aligned, and the alignment. */
uint64_t sw_pack_arena_bytes(uint64_t total_size);

/* Validates everything (every rule in PACK_FORMAT.md, "Validation rules")
 * and fills out with views into data; nothing is copied or allocated. data
 * must be 8-byte aligned (SW_ERR_ARG otherwise) and stay alive as long as out
 * is used. On failure out is zeroed, and err holds one line naming the
 * section or field: SW_ERR_FORMAT for malformed or truncated data,
 * SW_ERR_VERSION, SW_ERR_CHECKSUM, SW_ERR_RANGE for an index or count out of
 * range. */
sw_status sw_pack_open_memory(const void *data, size_t size, sw_pack *out, sw_error *err);

/* The same, with the section checksums, the Seam Graph's and the levels' rules in parts
 * run by runner (sw_parts.h: the runtime's loader passes one that uses its
 * spare cores); the same result and message whatever the runner. */
sw_status sw_pack_open_memory_with(const void *data, size_t size, const sw_parts_runner *runner,
                                   sw_pack *out, sw_error *err);

/* Reads and checks only the 64-byte header of the file at path (magic,
 * version, byte order, total size against the file's size), for sizing the
 * arena before sw_pack_load. */
sw_status sw_pack_read_header(const char *path, sw_pack_header *out, sw_error *err);

/* Reads the whole file into the arena (64-byte aligned) and validates it.
 * Errors are prefixed with the path; SW_ERR_NO_MEMORY when the arena cannot
 * hold the file. On failure the arena is reset to where it was. */
sw_status sw_pack_load(const char *path, sw_arena *arena, sw_pack *out, sw_error *err);

/* sw_pack_load validating with runner (sw_pack_open_memory_with). */
sw_status sw_pack_load_with(const char *path, sw_arena *arena, const sw_parts_runner *runner,
                            sw_pack *out, sw_error *err);

/* sw_pack_load_with, running check (may be NULL) on the file's raw bytes
 * before any of them is parsed: a unit checks the pack's signature there,
 * so bytes from anyone but its owner reach no section parser. */
typedef sw_status (*sw_pack_raw_check)(void *user, const uint8_t *bytes, size_t size,
                                       sw_error *err);
sw_status sw_pack_load_checked(const char *path, sw_arena *arena, const sw_parts_runner *runner,
                               sw_pack_raw_check check, void *user, sw_pack *out,
                               sw_error *err);

/* A pack file mapped read-only (sw_pack_map_checked). */
typedef struct sw_pack_mapping {
    void *base;
    size_t size;
} sw_pack_mapping;

/* 1 when the pack file at path may be mapped rather than copied: a regular
 * file owned by root and writable by neither group nor others, so no one
 * but root can change its bytes while the walk reads them (checked once,
 * then walked: bytes changed in place after the checks could index out of
 * bounds). Root's tools never write into a pack that may be walked:
 * seamwalk-pack writes a new file and renames it, seamwalk-flash writes
 * each install into a new file (firmware/store/STORE.md). A file its
 * reader owns could be changed by it: it is copied. */
int sw_pack_file_mappable(const char *path);

/* sw_pack_load_checked with the file mapped read-only (mmap) instead of
 * copied into an arena: its pages stay the kernel's to drop and read again
 * (clean file pages), not the arena's. The file must still be mappable
 * (sw_pack_file_mappable) when opened: SW_ERR_IO otherwise. On success
 * out views *map until sw_pack_unmap; on failure nothing stays mapped. */
sw_status sw_pack_map_checked(const char *path, const sw_parts_runner *runner,
                              sw_pack_raw_check check, void *user, sw_pack_mapping *map,
                              sw_pack *out, sw_error *err);
void sw_pack_unmap(sw_pack_mapping *map);

const char *sw_section_type_name(uint32_t type); /* "META", ... or "unknown" */

#endif
