/* SPDX-License-Identifier: MIT */
/* seamwalk's --navigate and --input-timeline: chooses the devices (the real
 * ones, or fake ones fed from a timeline), loads what they need at start-up
 * (the mapping file, the timeline and its descriptors, the pose log) and
 * gives the frame loop one call per frame. Called by seamwalk_main.c only.
 *
 * Clocks: with --navigate, CLOCK_MONOTONIC (libgpiod's event timestamps are
 * on it); with --input-timeline, simulated: frame f is at f / 30 s, so a
 * run replays to the same poses whatever the machine's speed. */
#ifndef SW_KIOSK_RUN_H
#define SW_KIOSK_RUN_H

#include <stdio.h>

#include "sw_display.h"
#include "sw_input_fake.h"
#include "sw_kiosk.h"

#define SW_KIOSK_TIMELINE_HZ 30.0

/* What seamwalk's options ask of the kiosk (sw_options.h fills them). */
typedef struct sw_kiosk_run_desc {
    const sw_kiosk_config *config;
    const char *input_timeline;      /* a timeline drives fake devices; NULL: the real ones */
    const char *pose_log;            /* each frame's camera pose goes there; NULL: nowhere */
} sw_kiosk_run_desc;

typedef struct sw_kiosk_run {
    sw_kiosk kiosk;
    sw_hid_backend hid;
    sw_gpio_backend gpio;
    sw_key_backend keys;
    sw_pad_mapping_db db;
    sw_fake_devices fake;
    sw_fake_player player;
    sw_timeline timeline;
    sw_timeline_event *events;       /* malloc'd at start-up */
    uint8_t **descs;                 /* per event, plugs only */
    size_t *desc_sizes;
    int simulated;
    int64_t t0_ns, last_ns;
    FILE *pose_log;
    char pose_buffer[1 << 16];       /* the log's stdio buffer: no allocation per frame */
} sw_kiosk_run;

/* Start-up: may allocate. fovy/aspect for the orbit's distance. display:
 * with --navigate, a window's keyboard is read from it (else evdev); may be
 * NULL. */
sw_status sw_kiosk_run_start(sw_kiosk_run *run, const sw_kiosk_run_desc *desc,
                             sw_display *display, const sw_camera_frame *frame, const sw_box *box,
                             const sw_pack_viewpoint *views, uint32_t view_count,
                             double fovy_rad, double aspect, sw_error *err);

/* Per frame: feeds due timeline events, polls, navigates; logs the pose. */
sw_camera_pose sw_kiosk_run_frame(sw_kiosk_run *run, int frame);

void sw_kiosk_run_stop(sw_kiosk_run *run);

#endif
