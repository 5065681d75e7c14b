/* SPDX-License-Identifier: MIT */
/* The kiosk's settings: what the gamepad's buttons and the GPIO buttons
 * do, the keyboard, and how navigation moves. They are the [gamepad],
 * [keyboard], [navigation] and [gpio NAME] sections of the unit's config;
 * firmware/program/sw_config.h reads them from the file with their
 * defaults and ranges, and the kiosk (sw_kiosk.h, sw_nav.h) reads them
 * here, so the kiosk needs nothing of the program above it. */
#ifndef SW_KIOSK_CONFIG_H
#define SW_KIOSK_CONFIG_H

/* Paths and names come from the config file, whose reader (inih) takes
 * lines of at most 200 bytes, so they stay below that. */
enum { SW_KIOSK_PATH_MAX = 192, SW_KIOSK_NAME_MAX = 32, SW_KIOSK_GPIO_MAX = 16,
       SW_KIOSK_PAD_BUTTONS = 15 /* sw_pad_button, in its order */ };

/* The mode navigation starts in ([navigation] mode). */
typedef enum sw_kiosk_nav_mode { SW_NAV_WALK = 0, SW_NAV_ORBIT } sw_kiosk_nav_mode;

typedef enum sw_kiosk_gpio_bias {
    SW_BIAS_AS_IS = 0, SW_BIAS_DISABLE, SW_BIAS_PULL_UP, SW_BIAS_PULL_DOWN
} sw_kiosk_gpio_bias;

/* What a button does (sw_kiosk.h): the movement ones act while held, the
 * others once per press. */
typedef enum sw_kiosk_action {
    SW_ACTION_NONE = 0, SW_ACTION_FORWARD, SW_ACTION_BACK, SW_ACTION_TURN_LEFT,
    SW_ACTION_TURN_RIGHT, SW_ACTION_NEXT_VIEW, SW_ACTION_PREV_VIEW, SW_ACTION_HOME,
    SW_ACTION_TOGGLE_MODE, SW_ACTION_ATTRACT, SW_ACTION_LOOK_UP, SW_ACTION_LOOK_DOWN,
    SW_ACTION_STRAFE_LEFT, SW_ACTION_STRAFE_RIGHT,
} sw_kiosk_action;

/* One [gpio NAME] section: a button on a GPIO line (libgpiod). */
typedef struct sw_kiosk_gpio {
    char name[SW_KIOSK_NAME_MAX];
    char chip[SW_KIOSK_NAME_MAX];        /* gpiochip0, or a chip label */
    char line_name[SW_KIOSK_NAME_MAX];   /* "line = NAME", or empty with: */
    int line_offset;                     /* "line = 17"; -1 when named */
    int active_low;
    sw_kiosk_gpio_bias bias;
    int debounce_ms, min_press_ms, long_press_ms;  /* see sw_debounce.h */
    sw_kiosk_action action, long_action;
    long line;                           /* where the section starts, for messages */
} sw_kiosk_gpio;

typedef struct sw_kiosk_config {
    int gamepad_enabled;
    char gamepad_mapping[SW_KIOSK_PATH_MAX];  /* gamecontrollerdb file, empty: none */
    double gamepad_dead_zone;
    sw_kiosk_action gamepad_action[SW_KIOSK_PAD_BUTTONS];  /* [gamepad] a = ..., ... */
    int keyboard_enabled;
    char keyboard_device[SW_KIOSK_PATH_MAX];  /* an evdev path or "auto" */
    sw_kiosk_nav_mode nav_mode;
    double walk_speed_mm_s, turn_speed_deg_s, orbit_speed_deg_s;
    double accel_s, eye_height_mm, transition_s, attract_hold_s;
    double attract_timeout_s;            /* 0: no attract mode */
    sw_kiosk_gpio gpio[SW_KIOSK_GPIO_MAX];
    int gpio_count;
} sw_kiosk_config;

#endif
