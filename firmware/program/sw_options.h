/* SPDX-License-Identifier: MIT */
/* The seamwalk command line, parsed into a struct where zero means default.
 * Called once by main before anything else. With --config FILE the file
 * (sw_config.h) is read first and fills what the command line does not give:
 * the command line wins. Every option's name, range, default and help is a
 * row of sw_option_table.c; the comments below say what the walk makes of the
 * fields. */
#ifndef SW_OPTIONS_H
#define SW_OPTIONS_H

#include <stdio.h>

#include "sw_config.h"
#include "sw_display.h"
#include "sw_error.h"
#include "sw_option_table.h"

typedef struct sw_options {
    const char *pack_path;       /* --pack FILE, unsigned */
    sw_display_kind display;     /* --display NAME (--headless WxH: headless) */
    int width, height;           /* --size WxH or --headless WxH; 0: the display's own
                                    (headless has none and refuses to start) */
    const char *path_file;       /* --path FILE, or NULL with orbit set */
    int orbit;
    int no_cache;                /* --no-cache: tessellate every visible surface every frame at
                                    its exact bound (the benchmarks' baseline) */
    const char *view_name;       /* --view NAME: a still from the pack's named viewpoint */
    int frames;                  /* with duration_s, the frames of one loop */
    double duration_s;           /* --duration S: the soak, the path looped for S seconds;
                                    0: one walk of --frames frames */
    const char *png_dir;         /* NULL: no pictures */
    int png_every;
    const char *stats_path;      /* NULL: no stats file */
    double memory_mb;            /* the arena's limit */
    double max_error_px;
    int measure_every;           /* error and crack measurement every K-th frame (0: none) */
    double fov_deg;              /* vertical field of view */
    const char *store_dir;       /* --store DIR: start a slot of the unit's pack store */
    const char *keys_path;       /* --keys FILE: trusted keys; NULL: SW_STORE_DEFAULT_KEYS */
    int boot_attempts;           /* boots a pending slot gets */
    double good_after_s;         /* healthy walk time before mark-good */
    int background_set;          /* --background R,G,B: clear to it instead of the default */
    float background[3];         /* 0..1, from 0..255 levels */
    int back_flat;               /* --back-faces R,G,B: back faces flat in that colour
                                    (tests/test_image_holes.sh); 0: lit */
    int back_hidden;             /* --back-faces hidden: back faces not drawn (solids whose
                                    faces all point out); cone culling only then */
    int cone_cull;               /* with back faces hidden, whole surfaces facing away are
                                    not drawn */
    int cull_brute;              /* --cull brute: every patch box tested every frame instead
                                    of the culling tree (the benchmarks' "before") */
    float back_color[3];
    int depth_bits;              /* at most this many, 16 or 24 */
    int depth_fit;               /* near and far fitted to the drawn surfaces each frame, or
                                    to the model box */
    int static_levels;           /* the pack's static levels stand in for meshes not made yet */
    int part_levels;             /* far parts drawn whole from the pack's part levels */
    int leaner_standins;         /* stand-ins far finer than their bound replaced by the
                                    walk's own meshes */
    int fill_crossings;          /* fans over seam crossings (0 shows the T-junction
                                    pinholes they close) */
    long drop_surface;           /* --test-drop-surface S: surface S is never drawn (a
                                    mutation for the image tests); -1: none */
    int navigate;                /* --navigate: the unit's devices drive the camera */
    const char *input_timeline;  /* --input-timeline FILE: a timeline drives it (fake devices) */
    const char *pose_log;        /* --pose-log FILE: each frame's camera pose */
    int workers;                 /* tessellation threads; 0: in the frame; -1: the cores less
                                    one, at least 1 (seamwalk_start.c) */
    double target_ms;            /* the budgets' frame time */
    int sync_work;               /* each frame waits for its work (tests) */
    int stall_workers_at;        /* --test-stall-workers F: workers idle from frame F; -1 */
    int standin_silhouettes;     /* where a silhouette may cross a stand-in, its level chosen
                                    by the bound it was made for (1) or by its error (0, tests) */
    int part_levels_coarsest;    /* parts in view drawn from their coarsest level whatever the
                                    bound (1, tests) */
    int visibility_thread;       /* V on its own thread (with workers) */
    int slow_workers_ms;         /* --test-slow-workers MS: each job published MS late */
    long cache_vertices;         /* --test-cache-vertices N: the mesh cache cut to about N
                                    vertices (0: its whole size) */
    int pressure;                /* --test-pressure 0: the bound never raised for room */
    int batch_tris;              /* triangles drawn before waiting for the GL driver; 0: at
                                    the frame's end */
    int test_grow_kb;            /* --test-grow-kb K: K kB more resident at each loop's end
                                    (tests: the soak must fail on it) */
    int help;                    /* --help (or -h) */
    int help_test;               /* --help-test */
    int version;                 /* --version: print it and exit */
    const char *config_path;     /* --config FILE, or NULL: no file is read */
    /* The file's values. pack_path, store_dir and keys_path may point into
     * it, so an sw_options stays where it was parsed (or is copied back). */
    sw_config config;
} sw_options;

/* Fills opts from argv. On a usage error returns SW_ERR_ARG with a message
 * naming the option and what it expects. */
sw_status sw_options_parse(int argc, char **argv, sw_options *opts, sw_error *err);

/* The usage: on stdout for --help, which is asked for. */
void sw_options_print_usage(FILE *out, const char *argv0);

/* The options only the tests use (--help-test), kept out of --help and
 * the man page: a unit never needs them. */
void sw_options_print_test_usage(FILE *out);

#endif
