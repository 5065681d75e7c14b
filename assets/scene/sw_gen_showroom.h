/* SPDX-License-Identifier: MIT */
/* The showroom generator: `seamwalk-pack gen showroom --patches N -o
 * scene.ini [--part FILE]... [--seed S] [--catalog N]` writes a scene (sw_scene.h) that
 * lays out copies of the given part files and procedural objects
 * (sw_procedural.h) on a floor grid with aisles, adding up to N Bezier patches
 * when built, plus named viewpoints (entrance, overview, closeup). It writes
 * the scene and nothing else; `seamwalk-pack build scene.ini -o x.swpack`
 * packs it. For scale tests up to (and past) 100,000 patches.
 *
 * Counting: each part file is imported once to learn its patch count and box
 * (copies are scaled to a 1.2 m footprint and stood on the floor); procedural
 * objects announce their counts (sw_proc_patch_count). Objects are taken in a
 * seeded rotation (each file, plate, vase, rail) while they fit in what is
 * left, then plates of k x k patches fill the rest exactly, so the built scene
 * has exactly N patches when the importers count as they did here.
 *
 * Layout: 2 m cells in blocks of 4 x 4, 3 m aisles between blocks, blocks in
 * a near-square grid centred on the origin, +y up, the entrance on the -z
 * side. Host only. */
#ifndef SW_GEN_SHOWROOM_H
#define SW_GEN_SHOWROOM_H

#include <stddef.h>
#include <stdint.h>

#include "sw_error.h"

typedef struct sw_gen_showroom_desc {
    size_t patches;                 /* target, 1 .. SW_GEN_MAX_PATCHES */
    const char *const *part_files;  /* may be NULL when part_file_count is 0 */
    size_t part_file_count;
    uint64_t seed;
    size_t catalog;                 /* plates, vases and rails from this many designs of each
                                       (0..SW_GEN_MAX_CATALOG; 0: each object its own) */
} sw_gen_showroom_desc;

#define SW_GEN_MAX_CATALOG 1000

#define SW_GEN_MAX_PATCHES ((size_t)10000000)

typedef struct sw_gen_showroom_result {
    size_t patches;     /* planned: what the scene builds to */
    size_t parts;       /* [part] sections written */
    size_t file_parts;  /* of them, copies of part files */
    double width_mm, depth_mm;   /* floor extent of the grid */
} sw_gen_showroom_result;

/* Plans the showroom and returns the scene text in *text (malloc'd, NUL
 * terminated; the caller frees it). Part files appear in the scene by
 * absolute path. Errors name the part file that failed to import. */
sw_status sw_gen_showroom_scene(const sw_gen_showroom_desc *desc, char **text,
                                sw_gen_showroom_result *result, sw_error *err);

/* The command: argv holds the words after `gen` ("showroom", options...).
 * Writes the scene atomically (a temporary name, then rename) and one summary
 * line on stdout. Returns the exit status: 0 done, 1 failed (one line on
 * stderr), 2 usage error. */
int sw_pack_cmd_gen(int argc, char **argv);

#endif
