/* SPDX-License-Identifier: MIT */
/* The unit's configuration file: an INI file read with inih
 * at start-up, before the arena is taken (sw_config_load reads the file into
 * a heap buffer it frees before returning; the frame loop never sees this). `seamwalk --config FILE` reads one; its values fill the
 * options the command line does not give (sw_options.h). The service (issue
 * 11 item 7, not built yet) will pass --config /etc/seamwalk/seamwalk.ini
 * (SW_CONFIG_DEFAULT_PATH); seamwalk itself reads no file unless told to, so
 * tests and developers are never surprised by a unit's /etc.
 *
 * Every section and key, with its default, is in the example
 * firmware/dist/seamwalk.ini. An unknown section or key, a key given twice, a bad
 * value (not a number, out of range, an unknown word) or a line that is not
 * [section] or key = value is SW_ERR_FORMAT with "FILE:LINE: [section] key:
 * what was expected". Budgets are read and checked now but used by later
 * work (issues 6 and 7); [gamepad], [keyboard], [navigation] and [gpio]
 * drive the kiosk's input step (sw_kiosk.h). */
#ifndef SW_CONFIG_H
#define SW_CONFIG_H

#include <stddef.h>

#include "sw_debounce.h"
#include "sw_error.h"

#define SW_CONFIG_DEFAULT_PATH "/etc/seamwalk/seamwalk.ini"

/* The ranges a setting shares with its command-line option
 * (sw_options.h), so a value one takes the other takes too. */
#define SW_CONFIG_MAX_WORKERS 16          /* [budgets] workers, --workers */
#define SW_CONFIG_MAX_FRAME_MS 10000.0    /* [budgets] frame_ms, --target-ms */

/* inih reads lines of at most 200 bytes, so paths stay below that. */
enum { SW_CONFIG_PATH_MAX = 192, SW_CONFIG_NAME_MAX = 32, SW_CONFIG_GPIO_MAX = 16,
       SW_CONFIG_PAD_BUTTONS = 15 /* sw_pad_button, in its order */ };

/* The same choices, in the same order, as sw_display_kind (platform/sw_display.h). */
typedef enum sw_config_display {
    SW_DISPLAY_AUTO = 0,      /* from what EGL offers and the machine has */
    SW_DISPLAY_HEADLESS,      /* EGL surfaceless */
    SW_DISPLAY_KMS,
    SW_DISPLAY_X11,
    SW_DISPLAY_WAYLAND,
} sw_config_display;

typedef enum sw_config_nav_mode { SW_NAV_WALK = 0, SW_NAV_ORBIT } sw_config_nav_mode;

typedef enum sw_config_bias {
    SW_BIAS_AS_IS = 0, SW_BIAS_DISABLE, SW_BIAS_PULL_UP, SW_BIAS_PULL_DOWN
} sw_config_bias;

/* What a button does (sw_kiosk.h): the movement ones act while held, the
 * others once per press. */
typedef enum sw_config_action {
    SW_ACTION_NONE = 0, SW_ACTION_FORWARD, SW_ACTION_BACK, SW_ACTION_TURN_LEFT,
    SW_ACTION_TURN_RIGHT, SW_ACTION_NEXT_VIEW, SW_ACTION_PREV_VIEW, SW_ACTION_HOME,
    SW_ACTION_TOGGLE_MODE, SW_ACTION_ATTRACT, SW_ACTION_LOOK_UP, SW_ACTION_LOOK_DOWN,
    SW_ACTION_STRAFE_LEFT, SW_ACTION_STRAFE_RIGHT,
} sw_config_action;

/* One [gpio NAME] section: a button on a GPIO line (libgpiod, later work). */
typedef struct sw_config_gpio {
    char name[SW_CONFIG_NAME_MAX];
    char chip[SW_CONFIG_NAME_MAX];       /* gpiochip0, or a chip label */
    char line_name[SW_CONFIG_NAME_MAX];  /* "line = NAME", or empty with: */
    int line_offset;                     /* "line = 17"; -1 when named */
    int active_low;
    sw_config_bias bias;
    int debounce_ms, min_press_ms, long_press_ms;  /* see sw_debounce.h */
    sw_config_action action, long_action;
    long line;                           /* where the section starts, for messages */
} sw_config_gpio;

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
    int gamepad_enabled;
    char gamepad_mapping[SW_CONFIG_PATH_MAX];  /* gamecontrollerdb file, empty: none */
    double gamepad_dead_zone;
    sw_config_action gamepad_action[SW_CONFIG_PAD_BUTTONS];  /* [gamepad] a = ..., ... */
    int keyboard_enabled;
    char keyboard_device[SW_CONFIG_PATH_MAX];  /* an evdev path or "auto" */
    sw_config_nav_mode nav_mode;
    double walk_speed_mm_s, turn_speed_deg_s, orbit_speed_deg_s;
    double accel_s, eye_height_mm, transition_s, attract_hold_s;
    double attract_timeout_s;            /* 0: no attract mode */
    sw_config_gpio gpio[SW_CONFIG_GPIO_MAX];
    int gpio_count;
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

/* A button's debounce parameters in nanoseconds. Every [gpio] section the
 * parser accepts gives parameters sw_debounce_init accepts. */
sw_debounce_params sw_config_gpio_debounce(const sw_config_gpio *gpio);

#endif
