/* SPDX-License-Identifier: MIT */
/* The input step (sw_kiosk.h): devices -> one sw_nav_input -> sw_nav. */
#include "sw_kiosk.h"

#include <linux/input-event-codes.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

_Static_assert((int)SW_KIOSK_PAD_BUTTONS == (int)SW_PAD_BUTTON_COUNT,
               "a [gamepad] action key per gamepad button");
_Static_assert((int)SW_KIOSK_GPIO_MAX <= (int)SW_GPIO_LINES_MAX,
               "a backend can hold every [gpio] button's line");

/* The keyboard's fixed table: development and service use, not showroom
 * configuration, so it is not in the config. */
static const struct { uint16_t code; uint8_t action; } key_table[SW_KIOSK_KEYS] = {
    {KEY_UP, SW_ACTION_FORWARD},      {KEY_W, SW_ACTION_FORWARD},
    {KEY_DOWN, SW_ACTION_BACK},       {KEY_S, SW_ACTION_BACK},
    {KEY_LEFT, SW_ACTION_TURN_LEFT},  {KEY_A, SW_ACTION_TURN_LEFT},
    {KEY_RIGHT, SW_ACTION_TURN_RIGHT}, {KEY_D, SW_ACTION_TURN_RIGHT},
    {KEY_Q, SW_ACTION_STRAFE_LEFT},   {KEY_E, SW_ACTION_STRAFE_RIGHT},
    {KEY_PAGEUP, SW_ACTION_LOOK_UP},  {KEY_PAGEDOWN, SW_ACTION_LOOK_DOWN},
    {KEY_N, SW_ACTION_NEXT_VIEW},     {KEY_P, SW_ACTION_PREV_VIEW},
    {KEY_H, SW_ACTION_HOME},          {KEY_HOME, SW_ACTION_HOME},
    {KEY_M, SW_ACTION_TOGGLE_MODE},   {KEY_T, SW_ACTION_ATTRACT},
    {KEY_SPACE, SW_ACTION_NEXT_VIEW}, {KEY_BACKSPACE, SW_ACTION_PREV_VIEW},
};

static int is_movement(int a)
{
    return a == SW_ACTION_FORWARD || a == SW_ACTION_BACK || a == SW_ACTION_TURN_LEFT ||
           a == SW_ACTION_TURN_RIGHT || a == SW_ACTION_LOOK_UP || a == SW_ACTION_LOOK_DOWN ||
           a == SW_ACTION_STRAFE_LEFT || a == SW_ACTION_STRAFE_RIGHT;
}

/* A held movement action as axis contributions. */
static void hold(sw_nav_input *in, int a)
{
    switch (a) {
    case SW_ACTION_FORWARD: in->move += 1; break;
    case SW_ACTION_BACK: in->move -= 1; break;
    case SW_ACTION_TURN_LEFT: in->turn -= 1; break;
    case SW_ACTION_TURN_RIGHT: in->turn += 1; break;
    case SW_ACTION_LOOK_UP: in->look += 1; break;
    case SW_ACTION_LOOK_DOWN: in->look -= 1; break;
    case SW_ACTION_STRAFE_LEFT: in->strafe -= 1; break;
    case SW_ACTION_STRAFE_RIGHT: in->strafe += 1; break;
    default: break;
    }
}

static void fire(sw_nav_input *in, int a)
{
    if (a != SW_ACTION_NONE && !is_movement(a))
        in->actions |= 1u << a;
}

/* The line a [gpio NAME] section asks the backend for. */
static sw_gpio_line gpio_line(const sw_kiosk_gpio *g)
{
    sw_gpio_line l = {.line_offset = g->line_offset, .active_low = g->active_low};
    _Static_assert(sizeof l.name == sizeof g->name && sizeof l.chip == sizeof g->chip &&
                   sizeof l.line_name == sizeof g->line_name, "names copied whole");
    memcpy(l.name, g->name, sizeof l.name);
    memcpy(l.chip, g->chip, sizeof l.chip);
    memcpy(l.line_name, g->line_name, sizeof l.line_name);
    switch (g->bias) {
    case SW_BIAS_DISABLE: l.bias = SW_GPIO_BIAS_DISABLE; break;
    case SW_BIAS_PULL_UP: l.bias = SW_GPIO_BIAS_PULL_UP; break;
    case SW_BIAS_PULL_DOWN: l.bias = SW_GPIO_BIAS_PULL_DOWN; break;
    default: l.bias = SW_GPIO_BIAS_AS_IS; break;
    }
    return l;
}

static void open_buttons(sw_kiosk *k, int64_t now_ns)
{
    for (int i = 0; i < k->cfg->gpio_count; i++) {
        sw_kiosk_button *b = &k->buttons[k->button_count];
        const sw_kiosk_gpio *g = &k->cfg->gpio[i];
        sw_error err = {0};
        int high = 0;
        *b = (sw_kiosk_button){.cfg = g, .handle = -1};
        sw_gpio_line line = gpio_line(g);
        b->handle = k->gpio->open(k->gpio->ctx, &line, &high, &err);
        if (b->handle < 0) {
            fprintf(stderr, "seamwalk: [gpio %s] not used: %s\n", g->name, err.message);
            continue;
        }
        sw_debounce_params dp = sw_kiosk_gpio_debounce(g);
        sw_debounce_init(&b->debounce, &dp, now_ns, high); /* the config checked dp */
        k->button_count++;
    }
}

void sw_kiosk_init(sw_kiosk *k, const sw_kiosk_config *cfg, const sw_kiosk_devices *dev,
                   const sw_pad_mapping_db *db, const sw_nav_params *nav,
                   const sw_camera_frame *frame, const sw_box *box,
                   const sw_pack_viewpoint *views, uint32_t view_count, int64_t now_ns)
{
    memset(k, 0, sizeof *k);
    k->cfg = cfg;
    if (dev->hid && cfg->gamepad_enabled) {
        sw_pads_init(&k->pads, *dev->hid, db, (float)cfg->gamepad_dead_zone);
        k->pads_on = 1;
    }
    k->gpio = dev->gpio;
    if (dev->gpio)
        open_buttons(k, now_ns);
    else if (cfg->gpio_count)
        fprintf(stderr, "seamwalk: %d [gpio] buttons configured, no GPIO in this run\n",
                cfg->gpio_count);
    k->keys = dev->keys;
    if (dev->keys && cfg->keyboard_enabled) {
        sw_error err = {0};
        k->keys_on = dev->keys->open(dev->keys->ctx, dev->key_device, &err) == 0;
        if (!k->keys_on)
            fprintf(stderr, "seamwalk: no keyboard: %s\n", err.message);
    }
    sw_nav_init(&k->nav, nav, frame, box, views, view_count);
}

static void poll_pads(sw_kiosk *k, int64_t now_ns, sw_nav_input *in)
{
    in->activity |= sw_pads_poll(&k->pads, now_ns);
    for (int i = 0; i < SW_PADS_MAX; i++) {
        const sw_pad *p = &k->pads.pads[i];
        if (!p->open)
            continue;
        in->move -= p->state.axis[SW_PAD_LEFTY];   /* SDL's y grows downwards */
        in->turn += p->state.axis[SW_PAD_LEFTX];
        in->strafe += p->state.axis[SW_PAD_RIGHTX];
        in->look -= p->state.axis[SW_PAD_RIGHTY];
        for (int b = 0; b < SW_PAD_BUTTON_COUNT; b++) {
            int a = k->cfg->gamepad_action[b];
            if (!((p->state.buttons >> b) & 1))
                continue;
            if (is_movement(a))
                hold(in, a);
            else if (!((p->prev_buttons >> b) & 1))
                fire(in, a);
        }
    }
}

static void button_event(sw_kiosk *k, sw_kiosk_button *b, const sw_debounce_event *e,
                         sw_nav_input *in)
{
    int a = b->cfg->action, la = b->cfg->long_action;
    k->gpio_events++;
    in->activity = 1;
    switch (e->kind) {
    case SW_DEBOUNCE_PRESS:
        b->held = 1;
        if (la == SW_ACTION_NONE)
            fire(in, a);
        if (is_movement(a))
            hold(in, a);  /* a tap shorter than a frame still moves for one */
        break;
    case SW_DEBOUNCE_RELEASE:
        b->held = b->long_held = 0;
        break;
    case SW_DEBOUNCE_SHORT:
        if (la != SW_ACTION_NONE)
            fire(in, a);
        break;
    case SW_DEBOUNCE_LONG:
        b->long_held = 1;
        fire(in, la);
        break;
    }
}

static void poll_buttons(sw_kiosk *k, int64_t now_ns, sw_nav_input *in)
{
    sw_debounce_event ev[SW_DEBOUNCE_EVENTS_MAX];
    for (int i = 0; i < k->button_count; i++) {
        sw_kiosk_button *b = &k->buttons[i];
        sw_gpio_edge edge;
        int tapped = 0;
        while (k->gpio->read(k->gpio->ctx, b->handle, &edge) == 1) {
            int n = sw_debounce_edge(&b->debounce, edge.t_ns, edge.high, ev);
            for (int e = 0; e < n; e++)
                button_event(k, b, &ev[e], in), tapped |= ev[e].kind == SW_DEBOUNCE_PRESS;
        }
        int n = sw_debounce_tick(&b->debounce, now_ns, ev);
        for (int e = 0; e < n; e++)
            button_event(k, b, &ev[e], in), tapped |= ev[e].kind == SW_DEBOUNCE_PRESS;
        if (b->held && !tapped)
            hold(in, b->cfg->action);
        if (b->long_held && is_movement(b->cfg->long_action))
            hold(in, b->cfg->long_action);
    }
}

static void poll_keys(sw_kiosk *k, sw_nav_input *in)
{
    int code, value, r;
    while ((r = k->keys->read(k->keys->ctx, &code, &value)) == 1) {
        for (int i = 0; i < SW_KIOSK_KEYS; i++) {
            if (key_table[i].code != code || value == 2)
                continue;
            in->activity = 1;
            if (value == 1 && !k->key_held[i])
                fire(in, key_table[i].action);
            k->key_held[i] = value == 1;
        }
    }
    if (r < 0) {
        fprintf(stderr, "seamwalk: the keyboard went away\n");
        k->keys->close(k->keys->ctx);
        k->keys_on = 0;
        memset(k->key_held, 0, sizeof k->key_held);
    }
    for (int i = 0; i < SW_KIOSK_KEYS; i++)
        if (k->key_held[i])
            hold(in, key_table[i].action);
}

static float unit(float v) { return v < -1 ? -1 : v > 1 ? 1 : v; }

sw_camera_pose sw_kiosk_step(sw_kiosk *k, int64_t now_ns, double dt_s)
{
    sw_nav_input in = {0};
    if (k->pads_on)
        poll_pads(k, now_ns, &in);
    if (k->button_count)
        poll_buttons(k, now_ns, &in);
    if (k->keys_on)
        poll_keys(k, &in);
    in.move = unit(in.move);
    in.strafe = unit(in.strafe);
    in.turn = unit(in.turn);
    in.look = unit(in.look);
    in.activity |= in.actions != 0 || in.move != 0 || in.strafe != 0 || in.turn != 0 ||
                   in.look != 0;
    k->last = in;
    sw_nav_step(&k->nav, &in, dt_s);
    return sw_nav_pose(&k->nav);
}

void sw_kiosk_close(sw_kiosk *k)
{
    if (k->pads_on)
        sw_pads_close(&k->pads);
    for (int i = 0; i < k->button_count; i++)
        k->gpio->close(k->gpio->ctx, k->buttons[i].handle);
    if (k->keys_on)
        k->keys->close(k->keys->ctx);
    k->pads_on = k->button_count = k->keys_on = 0;
}

sw_nav_params sw_kiosk_nav_params(const sw_kiosk_config *cfg, double fovy_rad, double aspect,
                                  int start_orbit)
{
    return (sw_nav_params){
        .walk_speed_mm_s = cfg->walk_speed_mm_s,
        .turn_speed_deg_s = cfg->turn_speed_deg_s,
        .orbit_speed_deg_s = cfg->orbit_speed_deg_s,
        .accel_s = cfg->accel_s,
        .eye_height_mm = cfg->eye_height_mm,
        .attract_timeout_s = cfg->attract_timeout_s,
        .attract_hold_s = cfg->attract_hold_s,
        .transition_s = cfg->transition_s,
        .fovy_rad = fovy_rad,
        .aspect = aspect,
        .start_orbit = start_orbit,
    };
}

sw_debounce_params sw_kiosk_gpio_debounce(const sw_kiosk_gpio *gpio)
{
    const int64_t ms = 1000000;
    return (sw_debounce_params){
        .debounce_ns = gpio->debounce_ms * ms,
        .min_press_ns = gpio->min_press_ms * ms,
        .long_press_ns = gpio->long_press_ms * ms,
        .active_low = gpio->active_low,
    };
}
