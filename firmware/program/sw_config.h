/* SPDX-License-Identifier: MIT */
/* The unit's configuration file: an INI file read with inih
 * at start-up, before the arena is taken (sw_config_load reads the file into
 * a heap buffer it frees before returning; the frame loop never sees this).
 * `seamwalk --config FILE` reads one; its values fill the options the
 * command line does not give (sw_options.h). The service passes --config
 * /etc/seamwalk/seamwalk.ini (SW_CONFIG_DEFAULT_PATH); seamwalk itself
 * reads no file unless told to, so tests and developers are never
 * surprised by a unit's /etc. seamwalk-flash reads the same file for the
 * unit's store and keys.
 *
 * Every section and key, with its default, is in the example
 * firmware/dist/seamwalk.ini. The keys that set what a command-line option
 * sets take its range and default from the option table (sw_option_table.h). An unknown section or key, a key given twice, a bad
 * value (not a number, out of range, an unknown word) or a line that is not
 * [section] or key = value is SW_ERR_FORMAT with "FILE:LINE: [section] key:
 * what was expected". [gamepad], [keyboard], [navigation] and [gpio NAME]
 * are the kiosk's settings (sw_kiosk_config.h), which drive its input step
 * (sw_kiosk.h). */
#ifndef SW_CONFIG_H
#define SW_CONFIG_H

#include <stddef.h>

#include "sw_error.h"
#include "sw_kiosk_config.h"

#define SW_CONFIG_DEFAULT_PATH "/etc/seamwalk/seamwalk.ini"

/* inih reads lines of at most 200 bytes, so paths stay below that; the
 * kiosk's sections (sw_kiosk_config.h) hold theirs to the same limits. */
enum { SW_CONFIG_PATH_MAX = SW_KIOSK_PATH_MAX, SW_CONFIG_NAME_MAX = SW_KIOSK_NAME_MAX,
       SW_CONFIG_GPIO_MAX = SW_KIOSK_GPIO_MAX };

/* The same choices, in the same order, as sw_display_kind (platform/sw_display.h). */
typedef enum sw_config_display {
    SW_DISPLAY_AUTO = 0,      /* from what EGL offers and the machine has */
    SW_DISPLAY_HEADLESS,      /* EGL surfaceless */
    SW_DISPLAY_KMS,
    SW_DISPLAY_X11,
    SW_DISPLAY_WAYLAND,
} sw_config_display;

typedef struct sw_config {
    sw_config_display display;
    int width, height;                   /* [display] size; 0: not given */
    double fov_deg;
    char pack[SW_CONFIG_PATH_MAX];       /* [pack] pack = FILE ... */
    char store[SW_CONFIG_PATH_MAX];      /* ... or store = DIR, not both */
    char keys[SW_CONFIG_PATH_MAX];
    int boot_attempts;
    double good_after_s;
    double memory_mb, max_error_px;
    int render_batch_tris;               /* [render] batch_tris: --batch-tris */
    double budget_frame_ms;              /* [budgets] frame_ms: --target-ms */
    int budget_workers;                  /* [budgets] workers: --workers; -1 the cores less one */
    sw_kiosk_config kiosk;               /* [gamepad], [keyboard], [navigation], [gpio NAME] */
    /* The line each key of the sections above was given on (0: default),
     * indexed as sw_config_key_line finds them: a caller can tell a default
     * from a value equal to it and name the line. */
    long key_line[64];
} sw_config;

/* Sets every field to its documented default (also what load starts from). */
void sw_config_defaults(sw_config *cfg);

/* Parses text (size bytes, need not end in NUL) named file_name in messages. */
sw_status sw_config_load_memory(const char *text, size_t size, const char *file_name,
                                sw_config *cfg, sw_error *err);

/* Reads and parses a file of at most 1 MiB. */
sw_status sw_config_load(const char *path, sw_config *cfg, sw_error *err);

/* The line the loaded file set "section.key" on (for example
 * "render.memory_mb"), 0 if it did not (or there is no such key). */
long sw_config_key_line(const sw_config *cfg, const char *section_dot_key);

const char *sw_config_display_name(sw_config_display display);

#endif
