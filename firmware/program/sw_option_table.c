/* SPDX-License-Identifier: MIT */
/* seamwalk's options (sw_option_table.h), in the order --help lists them:
 * what to walk and how the camera moves, the display, the frames and their
 * output, the configuration and budgets, drawing, help; the tests' own last. */
#include "sw_option_table.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "sw_gl_pool.h"
#include "sw_options.h"
#include "sw_pack_store.h"

#define F(name) .field = offsetof(sw_options, name), .field_size = sizeof(((sw_options *)0)->name)
#define KEY(s, k) .section = s, .key = k

/* Ranges two rows share. */
#define PIXELS .min = 16, .max = 8192 /* --size, --headless, [display] size */
#define LEVELS .min = 0, .max = 255   /* --background, --back-faces */
#define ON_OFF .arg = "0|1", .kind = SW_OPTION_INT, .min = 0, .max = 1

_Static_assert(offsetof(sw_options, height) == offsetof(sw_options, width) + sizeof(int),
               "SW_OPTION_SIZE writes the height right after the width");

const sw_option_desc sw_option_table[] = {
    /* ---- what to walk, and how the camera moves ---- */
    {.name = "--pack", .arg = "FILE", .kind = SW_OPTION_TEXT, F(pack_path), KEY("pack", "pack"),
     .flags = SW_OPTION_PACK, .help = "walk this pack as it is: no signature is checked"},
    {.name = "--store", .arg = "DIR", .kind = SW_OPTION_TEXT, F(store_dir), KEY("pack", "store"),
     .flags = SW_OPTION_PACK,
     .help = "start the unit's pack store's slot (firmware/store/STORE.md): the pending one "
             "on trial, else the good one; none valid: a message screen, exit 3. Only packs "
             "its trusted keys signed start"},
    {.name = "--keys", .arg = "FILE", .kind = SW_OPTION_TEXT, .def_text = SW_STORE_DEFAULT_KEYS,
     F(keys_path), KEY("pack", "keys"),
     .help = "trusted public keys for --store (root's, writable by no one else)"},
    {.name = "--boot-attempts", .arg = "K", .kind = SW_OPTION_INT, .min = 1, .max = 1000, .def = 3,
     F(boot_attempts), KEY("pack", "boot_attempts"),
     .help = "boots a pending slot gets before falling back"},
    {.name = "--good-after-s", .arg = "S", .kind = SW_OPTION_REAL, .min = 0, .max = 1e9, .def = 30,
     F(good_after_s), KEY("pack", "good_after_s"),
     .help = "walk time of healthy frames before a pending slot is marked good"},
    {.name = "--path", .arg = "FILE", .kind = SW_OPTION_TEXT, F(path_file),
     .flags = SW_OPTION_CAMERA,
     .help = "follow a camera path (format: firmware/kiosk/sw_camera_path.h)"},
    {.name = "--orbit", .kind = SW_OPTION_FLAG, F(orbit), .flags = SW_OPTION_CAMERA,
     .help = "circle the model around the pack's up axis ([navigation] mode = orbit in the "
             "config)"},
    {.name = "--view", .arg = "NAME", .kind = SW_OPTION_TEXT, F(view_name),
     .flags = SW_OPTION_CAMERA, .help = "stand at one of the pack's named viewpoints"},
    {.name = "--navigate", .kind = SW_OPTION_FLAG, F(navigate), .flags = SW_OPTION_CAMERA,
     .help = "the unit's inputs drive the camera: gamepads (hidapi, hot-plugged), [gpio] "
             "buttons (libgpiod), the keyboard (evdev); walk, orbit, viewpoints, home, "
             "attract tour (docs/kiosk.md, \"Inputs and navigation\"; keys: [keyboard], "
             "[navigation], [gpio NAME] in the config)"},
    {.name = "--input-timeline", .arg = "FILE", .kind = SW_OPTION_TEXT, F(input_timeline),
     .flags = SW_OPTION_CAMERA,
     .help = "the same navigation driven by a recorded input timeline (format: "
             "firmware/kiosk/sw_input_timeline.h) through fake devices on a simulated 30 Hz "
             "clock: replays exactly"},
    {.name = "--pose-log", .arg = "FILE", .kind = SW_OPTION_TEXT, F(pose_log),
     .help = "write each frame's camera pose (frame t eye target up)"},
    /* ---- the display ---- */
    {.name = "--display", .arg = "auto|headless|kms|x11|wayland", .kind = SW_OPTION_DISPLAY,
     .def_text = "auto", F(display), KEY("display", "display"),
     .help = "where to draw:\n"
             "  headless  EGL surfaceless, offscreen; needs a size (CI)\n"
             "  kms       full screen on /dev/dri/card*, no X or Wayland (libdrm + GBM; "
             "needs DRM master: nothing else showing on it)\n"
             "  x11       a window on $DISPLAY (EGL on X11)\n"
             "  wayland   a window on $WAYLAND_DISPLAY (EGL on Wayland)\n"
             "  auto      wayland if WAYLAND_DISPLAY is set, else x11 if DISPLAY is set, else "
             "kms if a /dev/dri/card* exists, each only if EGL offers it; else headless\n"
             "the summary line says which ran and why; a display that cannot open is one "
             "error line, exit 1"},
    {.name = "--size", .arg = "WxH", .kind = SW_OPTION_SIZE, PIXELS, F(width),
     KEY("display", "size"),
     .help = "headless: the picture; window: its size (1280x720 without); kms: that mode if "
             "the connector has it, else its preferred mode, else its largest"},
    {.name = "--headless", .arg = "WxH", .kind = SW_OPTION_HEADLESS, PIXELS, F(width),
     .help = "--display headless --size WxH"},
    {.name = "--fov-deg", .arg = "DEG", .kind = SW_OPTION_REAL, .min = 5, .max = 150, .def = 45,
     F(fov_deg), KEY("display", "fov_deg"), .help = "vertical field of view"},
    /* ---- frames and output ---- */
    {.name = "--frames", .arg = "N", .kind = SW_OPTION_INT, .min = 1, .max = 10000000,
     .def = 120, F(frames),
     .help = "frames to render; closing the window, SIGTERM or Ctrl-C end the walk sooner, "
             "stats written"},
    {.name = "--duration", .arg = "S", .kind = SW_OPTION_REAL, .min = 0.001, .max = 1e7,
     .def_text = "one walk of --frames frames", F(duration_s),
     .help = "the soak: walk for S seconds, the path (or orbit) taken as a loop of --frames "
             "frames, again and again; the stats keep the last loop's frames and add "
             "resident memory at start, after the first loop and at the end, and the worst "
             "frame of all"},
    {.name = "--png-dir", .arg = "DIR", .kind = SW_OPTION_TEXT, F(png_dir),
     .help = "write frame_NNNNN.png every --png-every frames"},
    {.name = "--png-every", .arg = "K", .kind = SW_OPTION_INT, .min = 1, .max = 2147483647,
     .def = 1, F(png_every), .help = "see --png-dir"},
    {.name = "--stats", .arg = "FILE.json", .kind = SW_OPTION_TEXT, F(stats_path),
     .help = "write the walk's statistics"},
    {.name = "--measure-every", .arg = "K", .kind = SW_OPTION_INT, .min = 0, .max = 2147483647,
     .def = 4, F(measure_every),
     .help = "measure error and cracks every K-th frame, frame 0 first; 0: never, as a kiosk "
             "runs (on the 40,000-patch showroom a measured frame takes ~0.35 s more)"},
    /* ---- configuration and budgets ---- */
    {.name = "--config", .arg = "FILE", .kind = SW_OPTION_TEXT, F(config_path),
     .flags = SW_OPTION_READ_FIRST,
     .help = "read the unit's configuration (example, every key and its default: "
             "firmware/dist/seamwalk.ini); its values fill what the command line does not "
             "give; without it no file is read"},
    {.name = "--memory-mb", .arg = "M", .kind = SW_OPTION_REAL, .min = 1, .max = 1 << 20,
     .def = 256, F(memory_mb), KEY("render", "memory_mb"),
     .help = "refuse to start if the arena needs more"},
    {.name = "--max-error-px", .arg = "E", .kind = SW_OPTION_REAL, .min = 0.01, .max = 100,
     .def = 0.5, F(max_error_px), KEY("render", "max_error_px"),
     .help = "screen-space tessellation error bound"},
    {.name = "--workers", .arg = "N", .kind = SW_OPTION_INT, .min = -1,
     .max = SW_OPTIONS_MAX_WORKERS, .def = -1, F(workers), KEY("budgets", "workers"),
     .help = "tessellation threads beside the drawing one; -1: the cores less one, at least "
             "1; 0: tessellate in the frame, single-threaded. With workers the frame draws "
             "the meshes it has and swaps new ones in as they are done, never waiting for "
             "them (the first frame excepted)"},
    {.name = "--target-ms", .arg = "MS", .kind = SW_OPTION_REAL, .min = 1, .max = 10000,
     .def = 16.7, F(target_ms), KEY("budgets", "frame_ms"),
     .help = "the frame time the work budgets hold with workers: the triangles made a frame "
             "follow from it"},
    {.name = "--visibility-thread", ON_OFF, .def = 1, F(visibility_thread),
     .help = "with workers, 1: culling, bounds, seams and scheduling for the next frame run "
             "on their own thread while this one is drawn (the input then shows a frame "
             "later); 0: on the drawing thread, in turn"},
    {.name = "--batch-tris", .arg = "N", .kind = SW_OPTION_INT, .min = 0, .max = 1 << 24,
     .def = SW_GL_POOL_BATCH_TRIANGLES, F(batch_tris), KEY("render", "batch_tris"),
     .help = "wait for the GL driver after every N triangles drawn (0: only at the frame's "
             "end): what llvmpipe holds in flight, so resident memory, stays bounded"},
    {.name = "--sync-work", ON_OFF, .def = 0, F(sync_work),
     .help = "1: each frame waits for the work it asked for, no budget: frames as --workers "
             "0 draws them, for the tests' golden images (the test suite sets "
             "SEAMWALK_TEST_SYNC_WORK=1)"},
    /* ---- drawing ---- */
    {.name = "--no-cache", .kind = SW_OPTION_FLAG, F(no_cache),
     .help = "tessellate every visible surface every frame at its exact bound, keeping "
             "nothing: the baseline the cache is measured against "
             "(tests/bench/walk_cache_bench.sh), not for units"},
    {.name = "--background", .arg = "R,G,B", .kind = SW_OPTION_RGB, LEVELS,
     .def_text = "237,240,245", F(background),
     .help = "clear to this colour; one the model never has shows holes (tests/image_holes.c)"},
    {.name = "--back-faces", .arg = "lit|hidden|R,G,B", .kind = SW_OPTION_BACK_FACES, LEVELS,
     .def_text = "lit", F(back_color),
     .help = "lit: both sides shaded; R,G,B: back faces flat in that colour, so the inside of "
             "a solid showing through a crack can be told from its outside; hidden: back "
             "faces not drawn (for closed solids whose faces point out; an open shell seen "
             "from behind shows nothing there)"},
    {.name = "--cone-cull", ON_OFF, .def = 1, F(cone_cull),
     .help = "with --back-faces hidden: surfaces whose normal cone faces away from the eye "
             "over their whole box are not drawn at all (1); with back faces drawn it is "
             "always off"},
    {.name = "--cull", .arg = "tree|brute", .kind = SW_OPTION_WORD, .max = 1, F(cull_brute),
     .help = "frustum culling through the hierarchy (tree) or every patch box every frame "
             "(brute: the same answers, the baseline tests/bench/cull_bench.sh measures "
             "against)"},
    {.name = "--depth-bits", .arg = "16|24", .kind = SW_OPTION_DEPTH_BITS, .min = 16, .max = 24,
     .def = 24, F(depth_bits),
     .help = "at most this many bits of depth: 24 where GL_OES_depth24 is offered, else 16; "
             "the stats say which"},
    {.name = "--depth-fit", ON_OFF, .def = 1, F(depth_fit),
     .help = "fit near and far to the surfaces drawn each frame (1) or to the model's box (0)"},
    {.name = "--static-levels", ON_OFF, .def = 1, F(static_levels),
     .help = "with workers, a surface in view whose mesh is not made yet is drawn from the "
             "pack's static levels (1) or waits, undrawn (0)"},
    {.name = "--part-levels", ON_OFF, .def = 1, F(part_levels),
     .help = "a part far enough away is drawn whole from one of the pack's part levels, "
             "within the bound (1), or surface by surface (0)"},
    {.name = "--leaner-standins", ON_OFF, .def = 1, F(leaner_standins),
     .help = "with workers, a stand-in within its bound but made for one 1.6 times finer or "
             "more gets the walk's own mesh when the workers have budget left (1: fewer "
             "triangles to draw), or stays (0)"},
    {.name = "--fill-crossings", ON_OFF, .def = 1, F(fill_crossings),
     .help = "close each seam crossing (a T-junction with the surface across) with a "
             "zero-area fan, and give each loop point the tessellator dropped its vertex "
             "and a fan (1), or not (0: single-pixel pinholes open along such seams)"},
    /* ---- help ---- */
    {.name = "--help", .kind = SW_OPTION_FLAG, F(help), .flags = SW_OPTION_STOPS,
     .help = "this, on standard output"},
    {.name = "-h", .kind = SW_OPTION_FLAG, F(help), .flags = SW_OPTION_STOPS | SW_OPTION_ALIAS},
    {.name = "--help-test", .kind = SW_OPTION_FLAG, F(help_test), .flags = SW_OPTION_STOPS,
     .help = "the options only the tests use (mutants, stalls, holes on purpose): never on a "
             "unit"},
    {.name = "--version", .kind = SW_OPTION_FLAG, F(version), .flags = SW_OPTION_STOPS,
     .help = "seamwalk's version"},
    /* ---- the tests' own: each makes the walk wrong or slow on purpose ---- */
    {.name = "--test-stall-workers", .arg = "F", .kind = SW_OPTION_INT, .min = 0,
     .max = 2147483647, .def = -1, .def_text = "never", F(stall_workers_at),
     .flags = SW_OPTION_TEST_ONLY,
     .help = "from frame F on the workers take no work: frames must go on with the meshes "
             "they have"},
    {.name = "--test-standin-silhouettes", ON_OFF, .def = 1, F(standin_silhouettes),
     .flags = SW_OPTION_TEST_ONLY,
     .help = "where a silhouette may cross a stand-in, its level is chosen by the bound it "
             "was made for (1) or by its error (0: the tests' mutant, whose silhouettes leave "
             "slits)"},
    {.name = "--test-part-levels-coarsest", ON_OFF, .def = 0, F(part_levels_coarsest),
     .flags = SW_OPTION_TEST_ONLY,
     .help = "every part in view drawn from its coarsest part level whatever the bound (1: "
             "the tests' mutant)"},
    {.name = "--test-slow-workers", .arg = "MS", .kind = SW_OPTION_INT, .min = 0, .max = 10000,
     .def = 0, F(slow_workers_ms), .flags = SW_OPTION_TEST_ONLY,
     .help = "each job is published MS late, so a batch takes many frames (no half batch "
             "may show)"},
    {.name = "--test-grow-kb", .arg = "K", .kind = SW_OPTION_INT, .min = 0, .max = 1 << 20,
     .def = 0, F(test_grow_kb), .flags = SW_OPTION_TEST_ONLY,
     .help = "K kB more resident memory at each loop's end of a soak, no allocation (the "
             "soak must fail on it)"},
    {.name = "--test-cache-vertices", .arg = "N", .kind = SW_OPTION_INT, .min = 0,
     .max = 2147483647, .def = 0, .def_text = "the pack's", F(cache_vertices),
     .flags = SW_OPTION_TEST_ONLY,
     .help = "the mesh cache cut to about N vertices (and 6 N indices): a view larger than "
             "it, so the bound must be raised for room"},
    {.name = "--test-pressure", ON_OFF, .def = 1,
     F(pressure), .flags = SW_OPTION_TEST_ONLY,
     .help = "0: the bound is never raised when the cache cannot hold the view (the mutant "
             "that leaves surfaces undrawn)"},
    {.name = "--test-drop-surface", .arg = "S", .kind = SW_OPTION_INT, .min = 0,
     .max = 2147483647, .def = -1, .def_text = "none", F(drop_surface),
     .flags = SW_OPTION_TEST_ONLY,
     .help = "never draw surface S: a hole on purpose, for the image tests' mutants"},
};
const size_t sw_option_count = sizeof sw_option_table / sizeof sw_option_table[0];

const sw_option_desc *sw_option_find(const char *name)
{
    for (size_t i = 0; i < sw_option_count; i++)
        if (!strcmp(sw_option_table[i].name, name))
            return &sw_option_table[i];
    return NULL;
}

const sw_option_desc *sw_option_for_key(const char *section, const char *key)
{
    for (size_t i = 0; i < sw_option_count; i++) {
        const sw_option_desc *d = &sw_option_table[i];
        if (d->key && !strcmp(d->section, section) && !strcmp(d->key, key))
            return d;
    }
    return NULL;
}

void sw_option_format_number(double value, char *out, size_t size)
{
    if (value == floor(value) && fabs(value) < 1e15)
        snprintf(out, size, "%.0f", value);
    else
        snprintf(out, size, "%g", value);
}

void sw_option_format_range(const sw_option_desc *d, char *out, size_t size)
{
    out[0] = '\0';
    int numeric = d->kind == SW_OPTION_INT || d->kind == SW_OPTION_REAL;
    int per_part = d->kind == SW_OPTION_SIZE || d->kind == SW_OPTION_HEADLESS ||
                   d->kind == SW_OPTION_RGB || d->kind == SW_OPTION_BACK_FACES;
    if ((!numeric && !per_part) || (d->arg && !strcmp(d->arg, "0|1")))
        return;
    char lo[32], hi[32];
    sw_option_format_number(d->min, lo, sizeof lo);
    sw_option_format_number(d->max, hi, sizeof hi);
    snprintf(out, size, "%s..%s", lo, hi);
}

/* The i-th of a WORD row's words ("tree|brute"). */
static void word_of(const char *words, int i, char *out, size_t size)
{
    for (; i > 0 && words; i--)
        words = strchr(words, '|') ? strchr(words, '|') + 1 : NULL;
    size_t n = words ? strcspn(words, "|") : 0;
    snprintf(out, size, "%.*s", (int)n, words ? words : "");
}

void sw_option_format_default(const sw_option_desc *d, char *out, size_t size)
{
    out[0] = '\0';
    if (d->def_text)
        snprintf(out, size, "%s", d->def_text);
    else if (d->kind == SW_OPTION_WORD)
        word_of(d->arg, (int)d->def, out, size);
    else if (d->kind == SW_OPTION_INT || d->kind == SW_OPTION_REAL ||
             d->kind == SW_OPTION_DEPTH_BITS)
        sw_option_format_number(d->def, out, size);
}
