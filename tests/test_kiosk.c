/* SPDX-License-Identifier: MIT */
/* The input step (sw_kiosk.h) on fake devices: GPIO buttons with bouncing
 * edges become exactly one action, a tap shorter than the debounce time is
 * not lost, a long press runs the long action, a missing chip is a log line,
 * keys and gamepad buttons fire once per press and movement acts while
 * held, a window's keys drive the same key table. Argument: tests/hid. */
#include <linux/input.h>
#include <string.h>

#include "hid_fixture.h"
#include "sw_config.h"
#include "sw_input_fake.h"
#include "sw_kiosk.h"
#include "sw_test.h"
#include "sw_window_keys.h"

static sw_fake_devices fake;
static sw_kiosk kiosk;
static sw_config cfg;
static sw_hid_backend hid;
static sw_gpio_backend gpio;
static sw_key_backend keys;

static const int64_t ms = 1000000;

static void add_button(const char *name, const char *chip, sw_kiosk_action a,
                       sw_kiosk_action la)
{
    sw_kiosk_gpio *g = &cfg.kiosk.gpio[cfg.kiosk.gpio_count++];
    memset(g, 0, sizeof *g);
    snprintf(g->name, sizeof g->name, "%s", name);
    snprintf(g->chip, sizeof g->chip, "%s", chip);
    g->line_offset = 17;
    g->active_low = 1;
    g->debounce_ms = 10;
    g->min_press_ms = 2;
    g->long_press_ms = 800;
    g->action = a;
    g->long_action = la;
}

/* The kiosk on the fake devices, with key_backend as its keyboard (NULL:
 * the fake keyboard). */
static void start_keys(const sw_key_backend *key_backend)
{
    sw_config_defaults(&cfg);
    cfg.kiosk.attract_timeout_s = 0;
    add_button("next", "gpiochip0", SW_ACTION_NEXT_VIEW, SW_ACTION_NONE);
    add_button("home", "gpiochip0", SW_ACTION_HOME, SW_ACTION_ATTRACT);
    add_button("walk", "gpiochip0", SW_ACTION_FORWARD, SW_ACTION_NONE);
    add_button("gone", "missing", SW_ACTION_BACK, SW_ACTION_NONE);
    sw_fake_init(&fake);
    hid = sw_fake_hid_backend(&fake);
    gpio = sw_fake_gpio_backend(&fake);
    keys = key_backend ? *key_backend : sw_fake_key_backend(&fake);
    sw_kiosk_devices dev = {&hid, &gpio, &keys, "auto"};
    sw_nav_params np = sw_kiosk_nav_params(&cfg.kiosk, 0.8, 1.5, 0);
    sw_camera_frame f = sw_camera_frame_for_up(sw_v3(0, 0, 1));
    sw_box box = {sw_v3(-1000, -1000, 0), sw_v3(1000, 1000, 2000)};
    sw_kiosk_init(&kiosk, &cfg.kiosk, &dev, NULL, &np, &f, &box, NULL, 0, 0);
}

static void start(void) { start_keys(NULL); }

/* Steps frames of 10 ms from t0 to t1, counting actions a. */
static int count_actions(int64_t t0, int64_t t1, sw_kiosk_action a)
{
    int n = 0;
    for (int64_t t = t0; t <= t1; t += 10 * ms) {
        fake.now_ns = t;
        sw_kiosk_step(&kiosk, t, 0.01);
        n += (kiosk.last.actions >> a) & 1;
    }
    return n;
}

static void a_missing_chip_is_skipped(void)
{
    start();
    SW_CHECK(kiosk.button_count == 3);  /* "gone" is a log line */
}

static void bouncing_press_is_one_action(void)
{
    start();
    /* Active low: the press falls. Bounces for 4 ms each way. */
    static const int64_t at[] = {100, 101, 102, 103, 104, 300, 301, 302, 303};
    static const int level[] = {0, 1, 0, 1, 0, 1, 0, 1, 1};
    for (int i = 0; i < 9; i++)
        sw_fake_edge(&fake, "next", at[i] * ms, level[i]);
    SW_CHECK(count_actions(0, 500 * ms, SW_ACTION_NEXT_VIEW) == 1);
}

static void a_tap_shorter_than_the_debounce_time_counts(void)
{
    start();
    sw_fake_edge(&fake, "next", 100 * ms, 0);
    sw_fake_edge(&fake, "next", 103 * ms, 1);  /* 3 ms: held longer than min_press 2 ms */
    SW_CHECK(count_actions(0, 200 * ms, SW_ACTION_NEXT_VIEW) == 1);
    sw_fake_edge(&fake, "next", 300 * ms, 0);
    sw_fake_edge(&fake, "next", 301 * ms, 1);  /* 1 ms: a spike, ignored */
    SW_CHECK(count_actions(210 * ms, 400 * ms, SW_ACTION_NEXT_VIEW) == 0);
}

static void short_and_long_press_of_a_two_action_button(void)
{
    start();
    sw_fake_edge(&fake, "home", 100 * ms, 0);
    sw_fake_edge(&fake, "home", 200 * ms, 1);  /* short: home on release */
    SW_CHECK(count_actions(0, 300 * ms, SW_ACTION_HOME) == 1);
    sw_fake_edge(&fake, "home", 400 * ms, 0);
    sw_fake_edge(&fake, "home", 1500 * ms, 1); /* long: attract at 800 ms, no home */
    int homes = 0, tours = 0;
    for (int64_t t = 310 * ms; t <= 1700 * ms; t += 10 * ms) {
        fake.now_ns = t;
        sw_kiosk_step(&kiosk, t, 0.01);
        homes += (kiosk.last.actions >> SW_ACTION_HOME) & 1;
        tours += (kiosk.last.actions >> SW_ACTION_ATTRACT) & 1;
    }
    SW_CHECK(homes == 0 && tours == 1);
}

static void a_held_movement_button_walks(void)
{
    start();
    sw_fake_edge(&fake, "walk", 100 * ms, 0);
    sw_fake_edge(&fake, "walk", 600 * ms, 1);
    int moving = 0;
    for (int64_t t = 0; t <= 800 * ms; t += 10 * ms) {
        fake.now_ns = t;
        sw_kiosk_step(&kiosk, t, 0.01);
        moving += kiosk.last.move == 1;
    }
    SW_CHECK_MSG(moving == 50, "%d", moving);  /* 110 ms (press + debounce) to 600 ms (release + 10 ms) */
}

static void keys_fire_once_and_hold(void)
{
    start();
    sw_fake_key(&fake, 49, 1);   /* KEY_N down */
    sw_fake_key(&fake, 49, 2);   /* auto-repeat: nothing more */
    sw_fake_key(&fake, 103, 1);  /* KEY_UP down */
    sw_kiosk_step(&kiosk, 0, 0.01);
    SW_CHECK(kiosk.last.actions == 1u << SW_ACTION_NEXT_VIEW && kiosk.last.move == 1);
    sw_kiosk_step(&kiosk, 10 * ms, 0.01);
    SW_CHECK(kiosk.last.actions == 0 && kiosk.last.move == 1);
    sw_fake_key(&fake, 103, 0);
    sw_kiosk_step(&kiosk, 20 * ms, 0.01);
    SW_CHECK(kiosk.last.move == 0);
}

/* A developer window's keys (X11/XKB keysyms in the display's queue, as the
 * X11 and Wayland displays fill it) drive the same key table: N fires next
 * view once, Up walks while held, unknown keysyms are skipped. */
static void window_keys_drive_the_same_table(void)
{
    static sw_display window;
    memset(&window, 0, sizeof window);
    window.kind = SW_DISPLAY_KIND_X11;
    sw_key_queue_clear(&window.keys);
    sw_key_backend wk = sw_window_key_backend(&window);
    start_keys(&wk);
    SW_CHECK(kiosk.keys_on);
    sw_key_queue_push(&window.keys, 0xffbe, 1);  /* F1: no KEY_* in the table */
    sw_key_queue_push(&window.keys, 'N', 1);     /* shifted letters are the key */
    sw_key_queue_push(&window.keys, 0xff52, 1);  /* Up */
    sw_kiosk_step(&kiosk, 0, 0.01);
    SW_CHECK(kiosk.last.actions == 1u << SW_ACTION_NEXT_VIEW && kiosk.last.move == 1);
    sw_key_queue_push(&window.keys, 'n', 0);
    sw_kiosk_step(&kiosk, 10 * ms, 0.01);
    SW_CHECK(kiosk.last.actions == 0 && kiosk.last.move == 1);
    sw_key_queue_push(&window.keys, 0xff52, 0);
    sw_kiosk_step(&kiosk, 20 * ms, 0.01);
    SW_CHECK(kiosk.last.move == 0 && window.keys.count == 0);
    sw_kiosk_close(&kiosk);

    /* Headless has no window keyboard: opening it is an error, not a crash. */
    window.kind = SW_DISPLAY_KIND_HEADLESS;
    sw_error err = {0};
    SW_CHECK(!sw_window_has_keyboard(&window));
    SW_CHECK(wk.open(wk.ctx, "auto", &err) == -1);
    SW_CHECK_MSG(strstr(err.message, "headless display has no window keyboard") != NULL, "%s",
                 err.message);
    SW_CHECK(sw_window_keysym_code('w') == KEY_W && sw_window_keysym_code('0') == KEY_0 &&
             sw_window_keysym_code('9') == KEY_9 && sw_window_keysym_code(0xff55) == KEY_PAGEUP);
}

static void gamepad_buttons_fire_once_and_sticks_steer(void)
{
    start();
    uint8_t d[512];
    size_t n = hid_fixture("logitech_f310_dinput.hex", d, sizeof d);
    sw_hid_info info = {.bus = 3, .vendor = 0x046D, .product = 0xC216, .version = 0x0110};
    sw_fake_plug(&fake, 0, &info, d, n);
    uint8_t rep[8] = {0xFF, 0x80, 0x80, 0x80, 0x08 | 0x10, 0, 0, 0}; /* x right, button 1 */
    sw_fake_report(&fake, 0, rep, 8);
    sw_kiosk_step(&kiosk, 0, 0.01);
    SW_CHECK(kiosk.last.actions == 1u << cfg.kiosk.gamepad_action[SW_PAD_A]);
    SW_CHECK_NEAR(kiosk.last.turn, 1, 1e-4);
    sw_kiosk_step(&kiosk, 10 * ms, 0.01);  /* still held: no second action */
    SW_CHECK(kiosk.last.actions == 0 && kiosk.last.activity);
}

int main(int argc, char **argv)
{
    if (argc > 1)
        hid_dir = argv[1];
    SW_RUN(a_missing_chip_is_skipped);
    SW_RUN(bouncing_press_is_one_action);
    SW_RUN(a_tap_shorter_than_the_debounce_time_counts);
    SW_RUN(short_and_long_press_of_a_two_action_button);
    SW_RUN(a_held_movement_button_walks);
    SW_RUN(keys_fire_once_and_hold);
    SW_RUN(window_keys_drive_the_same_table);
    SW_RUN(gamepad_buttons_fire_once_and_sticks_steer);
    return sw_test_finish();
}
