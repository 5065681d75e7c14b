/* SPDX-License-Identifier: MIT */
#include "sw_options.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static sw_status parse_int(const char *opt, const char *text, int min, int max, int *out,
                           sw_error *err)
{
    char *end;
    errno = 0;
    long v = text ? strtol(text, &end, 10) : 0;
    if (!text || *end != '\0' || end == text || errno || v < min || v > max)
        return sw_error_set(err, SW_ERR_ARG, "%s expects an integer in %d..%d, got '%s'", opt, min,
                            max, text ? text : "");
    *out = (int)v;
    return SW_OK;
}

static sw_status parse_real(const char *opt, const char *text, double min, double max,
                            double *out, sw_error *err)
{
    char *end;
    double v = text ? strtod(text, &end) : 0;
    if (!text || *end != '\0' || end == text || !isfinite(v) || v < min || v > max)
        return sw_error_set(err, SW_ERR_ARG, "%s expects a number in %g..%g, got '%s'", opt, min,
                            max, text ? text : "");
    *out = v;
    return SW_OK;
}

static sw_status parse_size(const char *opt, const char *text, int *w, int *h, sw_error *err)
{
    const char *x = text ? strchr(text, 'x') : NULL;
    char width[16], what[32];
    if (!x || (size_t)(x - text) >= sizeof width)
        return sw_error_set(err, SW_ERR_ARG, "%s expects WIDTHxHEIGHT, got '%s'", opt,
                            text ? text : "");
    memcpy(width, text, (size_t)(x - text));
    width[x - text] = '\0';
    snprintf(what, sizeof what, "%s width", opt);
    sw_status st = parse_int(what, width, 16, 8192, w, err);
    snprintf(what, sizeof what, "%s height", opt);
    return st != SW_OK ? st : parse_int(what, x + 1, 16, 8192, h, err);
}

/* The config's words are in sw_display_kind's order (sw_config.h). */
static sw_display_kind display_of(sw_config_display d)
{
    switch (d) {
    case SW_DISPLAY_HEADLESS: return SW_DISPLAY_KIND_HEADLESS;
    case SW_DISPLAY_KMS: return SW_DISPLAY_KIND_KMS;
    case SW_DISPLAY_X11: return SW_DISPLAY_KIND_X11;
    case SW_DISPLAY_WAYLAND: return SW_DISPLAY_KIND_WAYLAND;
    default: return SW_DISPLAY_KIND_AUTO;
    }
}

/* --background R,G,B (and --back-faces): three levels 0..255. */
static sw_status parse_rgb(const char *opt, const char *text, float rgb[3], sw_error *err)
{
    int level[3], used = 0;
    if (sscanf(text, "%d,%d,%d%n", &level[0], &level[1], &level[2], &used) != 3 ||
        text[used] != '\0')
        return sw_error_set(err, SW_ERR_ARG, "%s expects R,G,B (0..255 each), got '%s'", opt,
                            text);
    for (int c = 0; c < 3; c++) {
        if (level[c] < 0 || level[c] > 255)
            return sw_error_set(err, SW_ERR_ARG, "%s expects R,G,B (0..255 each), got '%s'", opt,
                                text);
        rgb[c] = (float)level[c] / 255.0f;
    }
    return SW_OK;
}

/* The defaults the config file also has come from it (sw_config_defaults),
 * so the two cannot drift apart; the rest are the command line's own.
 * Without --config the config keeps those defaults too: --navigate reads its
 * devices, mapping and speeds from it. */
static void set_defaults(sw_options *o)
{
    memset(o, 0, sizeof *o);
    sw_config_defaults(&o->config);
    const sw_config *c = &o->config;
    o->frames = 120;
    o->png_every = 1;
    o->measure_every = 4;
    o->memory_mb = c->memory_mb;
    o->max_error_px = c->max_error_px;
    o->batch_tris = c->render_batch_tris;
    o->fov_deg = c->fov_deg;
    o->boot_attempts = c->boot_attempts;
    o->good_after_s = c->good_after_s;
    o->depth_bits = 24;
    o->depth_fit = 1;
    o->fill_crossings = 1;
    o->static_levels = 1;
    o->part_levels = 1;
    o->leaner_standins = 1;
    o->cone_cull = 1;
    o->drop_surface = -1;
    o->workers = c->budget_workers;   /* -1: cores - 1, at least 1, decided in main */
    o->target_ms = c->budget_frame_ms;
    o->stall_workers_at = -1;
    o->standin_silhouettes = 1;
    o->visibility_thread = 1;
    /* The test suite's deterministic frames (tests/CMakeLists.txt sets it
     * for every test); the command line's --sync-work wins. */
    const char *sync = getenv("SEAMWALK_TEST_SYNC_WORK");
    o->sync_work = sync && !strcmp(sync, "1");
}

/* The file's values, before the command line overrides them. Its defaults
 * are the command line's, so a key the file leaves out changes nothing. */
static void apply_config(sw_options *o)
{
    const sw_config *c = &o->config;
    o->display = display_of(c->display);
    o->width = c->width;
    o->height = c->height;
    o->fov_deg = c->fov_deg;
    o->pack_path = c->pack[0] ? c->pack : NULL;
    o->store_dir = c->store[0] ? c->store : NULL;
    o->keys_path = c->keys[0] ? c->keys : NULL;
    o->boot_attempts = c->boot_attempts;
    o->good_after_s = c->good_after_s;
    o->memory_mb = c->memory_mb;
    o->max_error_px = c->max_error_px;
    o->batch_tris = c->render_batch_tris;
    o->target_ms = c->budget_frame_ms;
    o->workers = c->budget_workers;
    o->orbit = c->kiosk.nav_mode == SW_NAV_ORBIT;
}

/* --config FILE anywhere on the command line; the main loop checks it again. */
static const char *find_config(int argc, char **argv)
{
    for (int i = 1; i + 1 < argc; i++)
        if (!strcmp(argv[i], "--config"))
            return argv[i + 1];
    return NULL;
}

/* What the file chose in groups where the command line's choice replaces it
 * as a whole (--pack or --store; --path, --orbit or --view; the size). */
typedef struct config_choice {
    const char *pack_path, *store_dir;
    int orbit, width, height;
} config_choice;

static config_choice take_choice(sw_options *o)
{
    config_choice c = {o->pack_path, o->store_dir, o->orbit, o->width, o->height};
    o->pack_path = o->store_dir = NULL;
    o->orbit = o->width = o->height = 0;
    return c;
}

static void merge_choice(sw_options *o, const config_choice *c)
{
    if (!o->pack_path && !o->store_dir) {
        o->pack_path = c->pack_path;
        o->store_dir = c->store_dir;
    }
    if (!o->orbit && !o->path_file && !o->view_name && !o->navigate && !o->input_timeline)
        o->orbit = c->orbit;
    if (o->width)
        return;
    o->width = c->width;
    o->height = c->height;
}

static sw_status check_complete(const sw_options *o, sw_error *err)
{
    if (!o->pack_path == !o->store_dir)
        return sw_error_set(err, SW_ERR_ARG, "give exactly one of --pack FILE and --store DIR");
    if (!!o->orbit + !!o->path_file + !!o->view_name + !!o->navigate + !!o->input_timeline != 1)
        return sw_error_set(err, SW_ERR_ARG, "give exactly one of --path FILE, --orbit, --view "
                            "NAME, --navigate and --input-timeline FILE");
    return SW_OK;
}

/* What this build was made without is a usage error when the walk would
 * need it: a display left out, or [gpio] buttons for --navigate without
 * libgpiod (SW_WITH_GPIOD=OFF). Gamepads are looked for, not asked for, so
 * sw_kiosk_run.c only says they are missing. */
static sw_status check_built(const sw_options *o, sw_error *err)
{
    sw_status st = sw_display_kind_check_built(o->display, err);
    if (st != SW_OK || SW_HAVE_GPIOD || !o->navigate || o->config.kiosk.gpio_count == 0)
        return st;
    return sw_error_set(err, SW_ERR_ARG, "[gpio %s]: built without libgpiod (SW_WITH_GPIOD=OFF)",
                        o->config.kiosk.gpio[0].name);
}

sw_status sw_options_parse(int argc, char **argv, sw_options *o, sw_error *err)
{
    set_defaults(o);
    sw_status st = SW_OK;
    o->config_path = find_config(argc, argv);
    if (o->config_path) {
        if ((st = sw_config_load(o->config_path, &o->config, err)) != SW_OK)
            return st;
        apply_config(o);
    }
    config_choice choice = take_choice(o);
    for (int i = 1; i < argc && st == SW_OK; i++) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        int takes_value = 1;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            o->help = 1;
            return SW_OK;
        } else if (!strcmp(a, "--help-test")) {
            o->help = 2;
            return SW_OK;
        } else if (!strcmp(a, "--version")) {
            o->version = 1;
            return SW_OK;
        } else if (!strcmp(a, "--orbit")) {
            o->orbit = 1;
            takes_value = 0;
        } else if (!strcmp(a, "--navigate")) {
            o->navigate = 1;
            takes_value = 0;
        } else if (!strcmp(a, "--no-cache")) {
            o->no_cache = 1;
            takes_value = 0;
        } else if (!v) {
            return sw_error_set(err, SW_ERR_ARG, "%s: unknown option or missing value", a);
        } else if (!strcmp(a, "--config")) {
            if (v != o->config_path)
                return sw_error_set(err, SW_ERR_ARG, "--config given twice");
        } else if (!strcmp(a, "--pack")) {
            o->pack_path = v;
        } else if (!strcmp(a, "--headless")) {
            o->display = SW_DISPLAY_KIND_HEADLESS;
            st = parse_size(a, v, &o->width, &o->height, err);
        } else if (!strcmp(a, "--size")) {
            st = parse_size(a, v, &o->width, &o->height, err);
        } else if (!strcmp(a, "--display")) {
            st = sw_display_kind_parse(v, &o->display, err);
        } else if (!strcmp(a, "--path")) {
            o->path_file = v;
        } else if (!strcmp(a, "--view")) {
            o->view_name = v;
        } else if (!strcmp(a, "--input-timeline")) {
            o->input_timeline = v;
        } else if (!strcmp(a, "--pose-log")) {
            o->pose_log = v;
        } else if (!strcmp(a, "--frames")) {
            st = parse_int(a, v, 1, 10000000, &o->frames, err);
        } else if (!strcmp(a, "--duration")) {
            st = parse_real(a, v, 0.001, 1e7, &o->duration_s, err);
        } else if (!strcmp(a, "--png-dir")) {
            o->png_dir = v;
        } else if (!strcmp(a, "--png-every")) {
            st = parse_int(a, v, 1, INT_MAX, &o->png_every, err);
        } else if (!strcmp(a, "--stats")) {
            o->stats_path = v;
        } else if (!strcmp(a, "--memory-mb")) {
            st = parse_real(a, v, 1, 1 << 20, &o->memory_mb, err);
        } else if (!strcmp(a, "--max-error-px")) {
            st = parse_real(a, v, 0.01, 100, &o->max_error_px, err);
        } else if (!strcmp(a, "--measure-every")) {
            st = parse_int(a, v, 0, INT_MAX, &o->measure_every, err);
        } else if (!strcmp(a, "--store")) {
            o->store_dir = v;
        } else if (!strcmp(a, "--keys")) {
            o->keys_path = v;
        } else if (!strcmp(a, "--boot-attempts")) {
            st = parse_int(a, v, 1, 1000, &o->boot_attempts, err);
        } else if (!strcmp(a, "--good-after-s")) {
            st = parse_real(a, v, 0, 1e9, &o->good_after_s, err);
        } else if (!strcmp(a, "--background")) {
            o->background_set = 1;
            st = parse_rgb(a, v, o->background, err);
        } else if (!strcmp(a, "--back-faces")) {
            o->back_hidden = !strcmp(v, "hidden");
            o->back_flat = strcmp(v, "lit") != 0 && !o->back_hidden;
            if (o->back_flat)
                st = parse_rgb(a, v, o->back_color, err);
        } else if (!strcmp(a, "--cone-cull")) {
            st = parse_int(a, v, 0, 1, &o->cone_cull, err);
        } else if (!strcmp(a, "--cull")) {
            o->cull_brute = !strcmp(v, "brute");
            if (!o->cull_brute && strcmp(v, "tree"))
                st = sw_error_set(err, SW_ERR_ARG, "--cull expects tree or brute, got '%s'", v);
        } else if (!strcmp(a, "--depth-bits")) {
            st = parse_int(a, v, 16, 24, &o->depth_bits, err);
            if (st == SW_OK && o->depth_bits != 16 && o->depth_bits != 24)
                st = sw_error_set(err, SW_ERR_ARG, "--depth-bits expects 16 or 24, got '%s'", v);
        } else if (!strcmp(a, "--depth-fit")) {
            st = parse_int(a, v, 0, 1, &o->depth_fit, err);
        } else if (!strcmp(a, "--static-levels")) {
            st = parse_int(a, v, 0, 1, &o->static_levels, err);
        } else if (!strcmp(a, "--part-levels")) {
            st = parse_int(a, v, 0, 1, &o->part_levels, err);
        } else if (!strcmp(a, "--leaner-standins")) {
            st = parse_int(a, v, 0, 1, &o->leaner_standins, err);
        } else if (!strcmp(a, "--fill-crossings")) {
            st = parse_int(a, v, 0, 1, &o->fill_crossings, err);
        } else if (!strcmp(a, "--test-drop-surface")) {
            int s = 0;
            st = parse_int(a, v, 0, INT_MAX, &s, err);
            o->drop_surface = s;
        } else if (!strcmp(a, "--workers")) {
            st = parse_int(a, v, 0, SW_OPTIONS_MAX_WORKERS, &o->workers, err);
        } else if (!strcmp(a, "--target-ms")) {
            st = parse_real(a, v, 1, SW_CONFIG_MAX_FRAME_MS, &o->target_ms, err);
        } else if (!strcmp(a, "--visibility-thread")) {
            st = parse_int(a, v, 0, 1, &o->visibility_thread, err);
        } else if (!strcmp(a, "--sync-work")) {
            st = parse_int(a, v, 0, 1, &o->sync_work, err);
        } else if (!strcmp(a, "--batch-tris")) {
            st = parse_int(a, v, 0, 1 << 24, &o->batch_tris, err);
        } else if (!strcmp(a, "--test-grow-kb")) {
            st = parse_int(a, v, 0, 1 << 20, &o->test_grow_kb, err);
        } else if (!strcmp(a, "--test-slow-workers")) {
            st = parse_int(a, v, 0, 10000, &o->slow_workers_ms, err);
        } else if (!strcmp(a, "--test-standin-silhouettes")) {
            st = parse_int(a, v, 0, 1, &o->standin_silhouettes, err);
        } else if (!strcmp(a, "--test-part-levels-coarsest")) {
            st = parse_int(a, v, 0, 1, &o->part_levels_coarsest, err);
        } else if (!strcmp(a, "--test-stall-workers")) {
            st = parse_int(a, v, 0, INT_MAX, &o->stall_workers_at, err);
        } else if (!strcmp(a, "--fov-deg")) {
            st = parse_real(a, v, 5, 150, &o->fov_deg, err);
        } else {
            return sw_error_set(err, SW_ERR_ARG, "unknown option '%s'", a);
        }
        i += takes_value;
    }
    if (st == SW_OK)
        merge_choice(o, &choice);
    if (st == SW_OK)
        st = check_complete(o, err);
    return st != SW_OK ? st : check_built(o, err);
}

void sw_options_print_usage(FILE *out, const char *argv0)
{
    fprintf(out,
            "usage: %s --help | --help-test | --version\n"
            "       %s (--pack FILE | --store DIR)\n"
            "          (--path FILE | --orbit | --view NAME | --navigate | --input-timeline FILE)\n"
            "          [--display auto|headless|kms|x11|wayland] [--size WxH] [--headless WxH]\n"
            "          [--frames N] [--duration S] [--png-dir DIR] [--png-every K]\n"
            "          [--stats FILE.json]\n"
            "          [--memory-mb M] [--max-error-px E] [--measure-every K] [--fov-deg DEG]\n"
            "          [--config FILE] [--pose-log FILE] [--no-cache] [--background R,G,B]\n"
            "          [--back-faces lit|hidden|R,G,B] [--depth-bits 16|24] [--depth-fit 0|1]\n"
            "          [--fill-crossings 0|1] [--static-levels 0|1] [--part-levels 0|1]\n"
            "          [--leaner-standins 0|1]\n"
            "          [--cone-cull 0|1]\n"
            "          [--cull tree|brute]\n"
            "          [--workers N] [--target-ms MS] [--visibility-thread 0|1]\n"
            "          [--batch-tris N]\n"
            "Walks a seamwalk pack and shows it on a display. --pack runs the file unsigned\n"
            "(no signature checked); --store runs only packs its trusted keys signed.\n"
            "  --display NAME      where to draw (default auto, or [display] display):\n"
            "                        headless  EGL surfaceless, offscreen; needs a size (CI)\n"
            "                        kms       full screen on /dev/dri/card*, no X or Wayland\n"
            "                                  (libdrm + GBM; needs DRM master: nothing else\n"
            "                                  showing on it)\n"
            "                        x11       a window on $DISPLAY (EGL on X11)\n"
            "                        wayland   a window on $WAYLAND_DISPLAY (EGL on Wayland)\n"
            "                        auto      wayland if WAYLAND_DISPLAY is set, else x11 if\n"
            "                                  DISPLAY is set, else kms if a /dev/dri/card*\n"
            "                                  exists, each only if EGL offers it; else headless\n"
            "                      the summary line says which ran and why; a display that\n"
            "                      cannot open is one error line, exit 1\n"
            "  --size WxH          headless: the picture; window: its size (default 1280x720);\n"
            "                      kms: that mode if the connector has it, else its preferred\n"
            "                      mode, else its largest\n"
            "  --headless WxH      --display headless --size WxH\n"
            "  --config FILE       read the unit's configuration (example, every key and its\n"
            "                      default: firmware/dist/seamwalk.ini); its values fill what\n"
            "                      the command line does not give; without it no file is read\n"
            "  --path FILE         follow a camera path (format:\n"
            "                      firmware/kiosk/sw_camera_path.h)\n"
            "  --orbit             circle the model around the pack's up axis\n"
            "  --view NAME         stand at one of the pack's named viewpoints\n"
            "  --navigate          the unit's inputs drive the camera: gamepads (hidapi,\n"
            "                      hot-plugged), [gpio] buttons (libgpiod), the keyboard\n"
            "                      (evdev); walk, orbit, viewpoints, home, attract tour\n"
            "                      (docs/kiosk.md, \"Inputs and navigation\"; keys:\n"
            "                      [keyboard], [navigation], [gpio NAME] in the config)\n"
            "  --input-timeline FILE  the same navigation driven by a recorded input timeline\n"
            "                      (format: firmware/kiosk/sw_input_timeline.h) through fake\n"
            "                      devices on a simulated 30 Hz clock: replays exactly\n"
            "  --pose-log FILE     write each frame's camera pose (frame t eye target up)\n"
            "  --frames N          frames to render (default 120); closing the window,\n"
            "                      SIGTERM or Ctrl-C end the walk sooner, stats written\n"
            "  --duration S        the soak: walk for S seconds, the path (or orbit) taken\n"
            "                      as a loop of --frames frames, again and again; the stats\n"
            "                      keep the last loop's frames and add resident memory at\n"
            "                      start, after the first loop and at the end, and the\n"
            "                      worst frame of all\n"
            "  --png-dir DIR       write frame_NNNNN.png every --png-every frames\n"
            "  --stats FILE.json   write the walk's statistics\n"
            "  --memory-mb M       refuse to start if the arena needs more (default 256)\n"
            "  --max-error-px E    screen-space tessellation error bound (default 0.5)\n"
            "  --measure-every K   measure error and cracks every K-th frame, frame 0 first\n"
            "                      (default 4); 0: never, as a kiosk runs (on the\n"
            "                      40,000-patch showroom a measured frame takes ~0.35 s more)\n"
            "  --store DIR         start the unit's pack store's slot\n"
            "                      (firmware/store/STORE.md): the pending one on trial, else\n"
            "                      the good one; none valid: a message screen, exit 3\n"
            "  --keys FILE         trusted public keys for --store (default\n"
            "                      /etc/seamwalk/keys; root's, writable by no one else)\n"
            "  --boot-attempts K   boots a pending slot gets before falling back (default 3)\n"
            "  --good-after-s S    walk time of healthy frames before a pending slot is\n"
            "                      marked good (default 30)\n"
            "  --workers N         tessellation threads beside the drawing one (default: the\n"
            "                      cores less one, at least 1); 0: tessellate in the frame,\n"
            "                      single-threaded. With workers the frame draws the meshes\n"
            "                      it has and swaps new ones in as they are done, never\n"
            "                      waiting for them (the first frame excepted)\n"
            "  --target-ms MS      the frame time the work budgets hold with workers (default\n"
            "                      16.7): the triangles made a frame follow from it\n"
            "  --visibility-thread 0|1  with workers, 1 (default): culling, bounds, seams\n"
            "                      and scheduling for the next frame run on their own\n"
            "                      thread while this one is drawn (the input then shows\n"
            "                      a frame later); 0: on the drawing thread, in turn\n"
            "  --sync-work 0|1     1: each frame waits for the work it asked for, no budget:\n"
            "                      frames as --workers 0 draws them, for the tests' golden\n"
            "                      images (default 0; the test suite sets\n"
            "                      SEAMWALK_TEST_SYNC_WORK=1)\n"
            "  --batch-tris N      wait for the GL driver after every N triangles drawn\n"
            "                      (default 32768, or [render] batch_tris; 0: only at the\n"
            "                      frame's end): what llvmpipe holds in flight, so resident\n"
            "                      memory, stays bounded\n"
            "  --no-cache          tessellate every visible surface every frame at its exact\n"
            "                      bound, keeping nothing: the baseline the cache is measured\n"
            "                      against (tests/bench/walk_cache_bench.sh), not for units\n"
            "  --background R,G,B  clear to this colour, levels 0..255 (default 237,240,245);\n"
            "                      one the model never has shows holes (tests/image_holes.c)\n"
            "  --back-faces M      lit (default: both sides shaded) or R,G,B: back faces flat\n"
            "                      in that colour, so the inside of a solid showing through\n"
            "                      a crack can be told from its outside; or hidden: back\n"
            "                      faces not drawn (for closed solids whose faces point out;\n"
            "                      an open shell seen from behind shows nothing there)\n"
            "  --cone-cull 0|1     with --back-faces hidden: surfaces whose normal cone faces\n"
            "                      away from the eye over their whole box are not drawn at\n"
            "                      all (1, default); with back faces drawn it is always off\n"
            "  --cull tree|brute   frustum culling through the hierarchy (tree, default) or\n"
            "                      every patch box every frame (brute: the same answers, the\n"
            "                      baseline tests/bench/cull_bench.sh measures against)\n"
            "  --depth-bits B      at most B bits of depth, 16 or 24 (default 24: 24 where\n"
            "                      GL_OES_depth24 is offered, else 16; the stats say which)\n"
            "  --depth-fit 0|1     fit near and far to the surfaces drawn each frame (1,\n"
            "                      default) or to the model's box (0)\n"
            "  --static-levels 0|1  with workers, a surface in view whose mesh is not made\n"
            "                      yet is drawn from the pack's static levels (1, default)\n"
            "                      or waits, undrawn (0)\n"
            "  --part-levels 0|1   a part far enough away is drawn whole from one of the\n"
            "                      pack's part levels, within the bound (1, default), or\n"
            "                      surface by surface (0)\n"
            "  --leaner-standins 0|1  with workers, a stand-in within its bound but made for\n"
            "                      one 1.6 times finer or more gets the walk's own mesh\n"
            "                      when the workers have budget left (1, default: fewer\n"
            "                      triangles to draw), or stays (0)\n"
            "  --fill-crossings 0|1  close each seam crossing (a T-junction with the surface\n"
            "                      across) with a zero-area fan (1, default), or not (0:\n"
            "                      single-pixel pinholes open along such seams)\n"
            "  --help-test         the options only the tests use (mutants, stalls, holes on\n"
            "                      purpose): never on a unit\n",
            argv0, argv0);
}

void sw_options_print_test_usage(FILE *out)
{
    fputs("seamwalk's options for the tests only: each makes the walk wrong or slow on\n"
          "purpose, so a test can show that its check catches it.\n"
          "  --test-stall-workers F  from frame F on the workers take no work: frames must\n"
          "                      go on with the meshes they have (tests)\n"
          "  --test-standin-silhouettes 0|1  where a silhouette may cross a stand-in, its\n"
          "                      level is chosen by the bound it was made for (1, default)\n"
          "                      or by its error (0: the tests' mutant, whose silhouettes\n"
          "                      leave slits)\n"
          "  --test-part-levels-coarsest 0|1  every part in view drawn from its coarsest\n"
          "                      part level whatever the bound (1: the tests' mutant;\n"
          "                      0, default)\n"
          "  --test-slow-workers MS  each job is published MS late, so a batch takes\n"
          "                      many frames (tests: no half batch may show)\n"
          "  --test-grow-kb K    K kB more resident memory at each loop's end of a soak,\n"
          "                      no allocation (tests: the soak must fail on it)\n"
          "  --test-drop-surface S  never draw surface S: a hole on purpose, for the image\n"
          "                      tests' mutants\n",
          out);
}
