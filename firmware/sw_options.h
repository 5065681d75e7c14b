/* The seamwalk command line, parsed into a struct where zero means default.
 * Called once by main before anything else. With --config FILE the file
 * (sw_config.h) is read first and fills what the command line does not give:
 * the command line wins. */
#ifndef SW_OPTIONS_H
#define SW_OPTIONS_H

#include "sw_config.h"
#include "sw_error.h"

typedef struct sw_options {
    const char *pack_path;
    int width, height;           /* from --headless WxH */
    const char *path_file;       /* --path FILE, or NULL with orbit set */
    int orbit;
    int no_cache;                /* --no-cache: tessellate every visible surface every frame at
                                    its exact bound (the benchmarks' baseline) */
    const char *view_name;       /* --view NAME: a still from the pack's named viewpoint */
    int frames;                  /* default 120 */
    const char *png_dir;         /* NULL: no pictures */
    int png_every;               /* default 1 */
    const char *stats_path;      /* NULL: no stats file */
    double memory_mb;            /* arena limit; default 256 */
    double max_error_px;         /* default 0.5 */
    int measure_every;           /* error and crack measurement every K-th frame; default 4 */
    double fov_deg;              /* vertical field of view; default 45 */
    const char *store_dir;       /* --store DIR: start a slot of the unit's pack store instead of --pack */
    const char *keys_path;       /* --keys FILE: trusted keys; default DIR/keys */
    int boot_attempts;           /* --boot-attempts K: boots a pending slot gets; default 3 */
    double good_after_s;         /* --good-after-s S: healthy walk time before mark-good; default 30 */
    int navigate;                /* --navigate: the unit's devices drive the camera */
    const char *input_timeline;  /* --input-timeline FILE: a timeline drives it (fake devices) */
    const char *pose_log;        /* --pose-log FILE: each frame's camera pose */
    int help;
    const char *config_path;     /* --config FILE, or NULL: no file is read */
    /* The file's values. pack_path, store_dir and keys_path may point into
     * it, so an sw_options stays where it was parsed (or is copied back). */
    sw_config config;
} sw_options;

/* Fills opts from argv. On a usage error returns SW_ERR_ARG with a message
 * naming the option and what it expects. */
sw_status sw_options_parse(int argc, char **argv, sw_options *opts, sw_error *err);

void sw_options_print_usage(const char *argv0);

#endif
