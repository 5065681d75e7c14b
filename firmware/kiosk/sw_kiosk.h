/* SPDX-License-Identifier: MIT */
/* The frame loop's input step: poll the devices ->
 * actions -> navigation -> the camera pose, once per frame on the GL
 * thread. seamwalk_main.c calls sw_kiosk_init at start-up and
 * sw_kiosk_step per frame, nothing else.
 *
 * Inputs and what they do:
 *  - gamepads (sw_pads.h): left stick walks (y) and turns (x), right stick
 *    strafes (x) and looks (y); each button's action is a [gamepad] key of
 *    the config (a = next_view, ...). In orbit mode turn swings around,
 *    look changes the height and move zooms.
 *  - GPIO buttons ([gpio NAME] sections): debounced (sw_debounce.h);
 *    movement actions act while held; other actions fire on press, or, for
 *    a button with a long_action, the action on a short press's release and
 *    the long action on the long press.
 *  - the keyboard (evdev, a fixed table, see sw_kiosk.c and docs/kiosk.md):
 *    arrows or WASD, Q/E strafe, Page Up/Down look, N/P viewpoints, H or
 *    Home, M mode, T tour.
 * Absent devices are log lines, never failures: no gamepad is simply none
 * yet (hot-plug finds it later), a GPIO line that cannot be requested is
 * logged and skipped, a keyboard that is missing is logged.
 *
 * Memory: none allocated here. The hidapi backend's enumeration (once a
 * second, sw_pads.h) and open allocate inside libhidapi/libudev; those
 * calls are not ours, so mallocs_after_init (which counts our code's calls)
 * stays 0 and process_mallocs_after_init shows them. The fake devices of
 * --input-timeline allocate nothing. */
#ifndef SW_KIOSK_H
#define SW_KIOSK_H

#include <stdint.h>

#include "sw_debounce.h"
#include "sw_input_backend.h"
#include "sw_kiosk_config.h"
#include "sw_nav.h"
#include "sw_pads.h"

typedef struct sw_kiosk_devices {
    const sw_hid_backend *hid;    /* NULL: no gamepads */
    const sw_gpio_backend *gpio;  /* NULL: no GPIO buttons */
    const sw_key_backend *keys;   /* NULL: no keyboard */
    const char *key_device;       /* for keys->open */
} sw_kiosk_devices;

typedef struct sw_kiosk_button {
    const sw_kiosk_gpio *cfg;
    int handle;                   /* -1: its line could not be requested */
    sw_debounce debounce;
    int held, long_held;
} sw_kiosk_button;

enum { SW_KIOSK_KEYS = 20 };

typedef struct sw_kiosk {
    const sw_kiosk_config *cfg;
    sw_pads pads;
    int pads_on;
    const sw_gpio_backend *gpio;
    sw_kiosk_button buttons[SW_KIOSK_GPIO_MAX];
    int button_count;
    const sw_key_backend *keys;
    int keys_on;
    uint8_t key_held[SW_KIOSK_KEYS];
    sw_nav nav;
    sw_nav_input last;            /* the latest step's input, for tests */
    uint64_t gpio_events;         /* debounced events seen, for tests */
} sw_kiosk;

/* Opens the devices the config asks for (logging what is missing) and
 * starts the navigation. now_ns: the clock the devices' timestamps use. */
void sw_kiosk_init(sw_kiosk *k, const sw_kiosk_config *cfg, const sw_kiosk_devices *dev,
                   const sw_pad_mapping_db *db, const sw_nav_params *nav,
                   const sw_camera_frame *frame, const sw_box *box,
                   const sw_pack_viewpoint *views, uint32_t view_count, int64_t now_ns);

/* One frame: polls, maps, steps the navigation by dt_s; the pose to draw. */
sw_camera_pose sw_kiosk_step(sw_kiosk *k, int64_t now_ns, double dt_s);

void sw_kiosk_close(sw_kiosk *k);

/* The navigation parameters from the config (fovy, aspect from the caller). */
sw_nav_params sw_kiosk_nav_params(const sw_kiosk_config *cfg, double fovy_rad, double aspect,
                                  int start_orbit);

/* A button's debounce parameters in nanoseconds. Every [gpio] section the
 * config's parser accepts gives parameters sw_debounce_init accepts. */
sw_debounce_params sw_kiosk_gpio_debounce(const sw_kiosk_gpio *gpio);

#endif
