/* SPDX-License-Identifier: MIT */
/* --navigate and --input-timeline (sw_kiosk_run.h). */
#include "sw_kiosk_run.h"

#include "sw_window_keys.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static int64_t monotonic_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (int64_t)ts.tv_sec * 1000000000 + ts.tv_nsec;
}

/* A whole small file into a fresh NUL-terminated buffer (start-up only). */
static sw_status read_file(const char *path, size_t limit, char **text, size_t *size,
                           sw_error *err)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return sw_error_set(err, SW_ERR_IO, "%s: %s", path, strerror(errno));
    *text = malloc(limit + 1);
    *size = *text ? fread(*text, 1, limit + 1, f) : 0;
    fclose(f);
    if (!*text)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "%s: no memory to read it", path);
    if (*size > limit)
        return sw_error_set(err, SW_ERR_FORMAT, "%s: larger than %zu bytes", path, limit);
    (*text)[*size] = '\0';
    return SW_OK;
}

/* The descriptor of plug event i, relative to the timeline's directory. */
static sw_status load_descriptor(sw_kiosk_run *r, const char *timeline_path, size_t i,
                                 sw_error *err)
{
    const sw_timeline_event *e = &r->events[i];
    char path[512];
    const char *slash = strrchr(timeline_path, '/');
    int dir = e->file[0] == '/' || !slash ? 0 : (int)(slash - timeline_path + 1);
    snprintf(path, sizeof path, "%.*s%s", dir, timeline_path, e->file);
    char *text;
    size_t size;
    sw_status st = read_file(path, 1 << 20, &text, &size, err);
    if (st == SW_OK && !(r->descs[i] = malloc(SW_HID_DESC_MAX)))
        st = sw_error_set(err, SW_ERR_NO_MEMORY, "%s: no memory", path);
    if (st == SW_OK)
        st = sw_hex_parse(text, size, path, r->descs[i], SW_HID_DESC_MAX, &r->desc_sizes[i],
                          err);
    free(text);
    return st;
}

static sw_status load_timeline(sw_kiosk_run *r, const char *path, sw_error *err)
{
    char *text;
    size_t size;
    sw_status st = read_file(path, 64 << 20, &text, &size, err);
    size_t n = st == SW_OK ? sw_timeline_count_events(text, size) : 0;
    if (st == SW_OK) {
        r->events = calloc(n, sizeof *r->events);
        r->descs = calloc(n, sizeof *r->descs);
        r->desc_sizes = calloc(n, sizeof *r->desc_sizes);
        if (!r->events || !r->descs || !r->desc_sizes)
            st = sw_error_set(err, SW_ERR_NO_MEMORY, "%s: no memory for %zu events", path, n);
    }
    if (st == SW_OK)
        st = sw_timeline_parse(text, size, path, r->events, n, &r->timeline, err);
    free(text);
    for (size_t i = 0; st == SW_OK && i < r->timeline.count; i++)
        if (r->events[i].kind == SW_TL_PLUG)
            st = load_descriptor(r, path, i, err);
    r->player = (sw_fake_player){&r->timeline, (const uint8_t *const *)r->descs,
                                 r->desc_sizes, 0};
    return st;
}

static sw_status open_pose_log(sw_kiosk_run *r, const char *path, sw_error *err)
{
    r->pose_log = fopen(path, "w");
    if (!r->pose_log)
        return sw_error_set(err, SW_ERR_IO, "%s: %s", path, strerror(errno));
    /* A line a frame, written as it is made: a watcher (the X11 test's key
     * sender) can tell when the walk's frames have begun. */
    setvbuf(r->pose_log, r->pose_buffer, _IOLBF, sizeof r->pose_buffer);
    fprintf(r->pose_log, "# frame t_s eye_x eye_y eye_z target_x target_y target_z up_x up_y "
            "up_z mode\n");
    return SW_OK;
}

sw_status sw_kiosk_run_start(sw_kiosk_run *r, const sw_kiosk_run_desc *desc,
                             sw_display *display, const sw_camera_frame *frame, const sw_box *box,
                             const sw_pack_viewpoint *views, uint32_t view_count,
                             double fovy_rad, double aspect, sw_error *err)
{
    const sw_kiosk_config *cfg = desc->config;
    sw_status st = SW_OK;
    if (cfg->gamepad_mapping[0] &&
        (st = sw_pad_mapping_db_load(cfg->gamepad_mapping, &r->db, err)) != SW_OK)
        return st;
    if (desc->pose_log && (st = open_pose_log(r, desc->pose_log, err)) != SW_OK)
        return st;
    r->simulated = desc->input_timeline != NULL;
    if (r->simulated) {
        if ((st = load_timeline(r, desc->input_timeline, err)) != SW_OK)
            return st;
        sw_fake_init(&r->fake);
        r->hid = sw_fake_hid_backend(&r->fake);
        r->gpio = sw_fake_gpio_backend(&r->fake);
        r->keys = sw_fake_key_backend(&r->fake);
        r->t0_ns = 0;
    } else {
#if SW_HAVE_HIDAPI
        r->hid = sw_hid_hidapi_backend();
#else
        if (cfg->gamepad_enabled)
            fprintf(stderr, "seamwalk: no gamepads: built without hidapi (SW_WITH_HIDAPI=OFF)\n");
#endif
#if SW_HAVE_GPIOD
        r->gpio = sw_gpio_gpiod_backend();   /* without: sw_options.c refused [gpio] buttons */
#endif
        r->keys = sw_window_has_keyboard(display) ? sw_window_key_backend(display)
                                                  : sw_evdev_key_backend();
        r->t0_ns = monotonic_ns();
    }
    r->last_ns = r->t0_ns;
    /* NULL: a backend the build lacks, so the kiosk opens none of those. */
    sw_kiosk_devices dev = {r->simulated || SW_HAVE_HIDAPI ? &r->hid : NULL,
                            r->simulated || SW_HAVE_GPIOD ? &r->gpio : NULL, &r->keys,
                            cfg->keyboard_device};
    sw_nav_params np = sw_kiosk_nav_params(cfg, fovy_rad, aspect, cfg->nav_mode == SW_NAV_ORBIT);
    sw_kiosk_init(&r->kiosk, cfg, &dev, cfg->gamepad_mapping[0] ? &r->db : NULL, &np, frame,
                  box, views, view_count, r->t0_ns);
    return SW_OK;
}

sw_camera_pose sw_kiosk_run_frame(sw_kiosk_run *r, int frame)
{
    int64_t now = r->simulated ? (int64_t)llround(frame * 1e9 / SW_KIOSK_TIMELINE_HZ)
                               : monotonic_ns();
    if (r->simulated)
        sw_fake_play(&r->player, &r->fake, (double)now * 1e-9);
    double dt = frame == 0 ? 0.0 : (double)(now - r->last_ns) * 1e-9;
    r->last_ns = now;
    sw_camera_pose p = sw_kiosk_step(&r->kiosk, now, dt);
    if (r->pose_log)
        fprintf(r->pose_log, "%d %.4f %.6f %.6f %.6f %.6f %.6f %.6f %.6f %.6f %.6f %s\n", frame,
                (double)(now - r->t0_ns) * 1e-9, p.eye.x, p.eye.y, p.eye.z, p.target.x,
                p.target.y, p.target.z, p.up.x, p.up.y, p.up.z,
                sw_nav_mode_name(r->kiosk.nav.mode));
    return p;
}

void sw_kiosk_run_stop(sw_kiosk_run *r)
{
    sw_kiosk_close(&r->kiosk);
    if (r->pose_log)
        fclose(r->pose_log);
    r->pose_log = NULL;
    for (size_t i = 0; r->descs && i < r->timeline.count; i++)
        free(r->descs[i]);
    free(r->descs);
    free(r->events);
    free(r->desc_sizes);
    r->descs = NULL;
    r->events = NULL;
    r->desc_sizes = NULL;
}
