/* SPDX-License-Identifier: MIT */
/* The configuration file (firmware/program/sw_config.h) and --config in seamwalk's
 * options (firmware/program/sw_options.h). argv[1]: the example firmware/dist/seamwalk.ini. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sw_config.h"
#include "sw_kiosk.h"
#include "sw_options.h"
#include "sw_test.h"

static const char *example_path;

static sw_status load_text(const char *text, sw_config *cfg, sw_error *err)
{
    return sw_config_load_memory(text, strlen(text), "bad.ini", cfg, err);
}

/* Everything but the lines the keys were given on. */
static int same_values(const sw_config *a, const sw_config *b)
{
    sw_config x = *a, y = *b;
    memset(x.key_line, 0, sizeof x.key_line);
    memset(y.key_line, 0, sizeof y.key_line);
    return memcmp(&x, &y, sizeof x) == 0;
}

/* The shipped config is the defaults but for what the service needs: the
 * unit's store and the KMS display (never auto, which could fall back to a
 * headless walk nobody sees). */
static void example_loads_and_is_the_defaults_but_store_and_kms(void)
{
    sw_config cfg, def;
    sw_error err = {0};
    sw_config_defaults(&def);
    sw_status st = sw_config_load(example_path, &cfg, &err);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    SW_CHECK(cfg.display == SW_DISPLAY_KMS);
    SW_CHECK_MSG(!strcmp(cfg.store, "/var/lib/seamwalk/store"), "store = '%s'", cfg.store);
    SW_CHECK(cfg.pack[0] == '\0');
    def.display = SW_DISPLAY_KMS;
    snprintf(def.store, sizeof def.store, "%s", "/var/lib/seamwalk/store");
    SW_CHECK(same_values(&cfg, &def));
    /* Every key but size (no default) is written out in the example. */
    static const char *const keys[] = {
        "display.display", "display.fov_deg", "pack.pack", "pack.store", "pack.keys",
        "pack.boot_attempts", "pack.good_after_s", "render.memory_mb", "render.max_error_px",
        "render.batch_tris", "budgets.frame_ms", "budgets.workers", "gamepad.enabled",
        "gamepad.mapping", "gamepad.dead_zone", "navigation.mode", "navigation.walk_speed_mm_s",
        "navigation.turn_speed_deg_s", "navigation.orbit_speed_deg_s",
        "navigation.attract_timeout_s"};
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
        SW_CHECK_MSG(sw_config_key_line(&cfg, keys[i]) > 0, "%s not in the example", keys[i]);
    SW_CHECK(sw_config_key_line(&cfg, "display.size") == 0);
    SW_CHECK(sw_config_key_line(&cfg, "display.nonsense") == 0);
    SW_CHECK(cfg.kiosk.gpio_count == 0);
}

static char *read_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    static char text[1 << 16];
    size_t n = f ? fread(text, 1, sizeof text - 1, f) : 0;
    if (f)
        fclose(f);
    text[n] = '\0';
    return text;
}

/* The example's commented [gpio next] block, uncommented (";key" lines, not
 * "; prose"), loads, and its keys hold the gpio defaults it claims. */
static void example_gpio_block_uncommented_is_the_gpio_defaults(void)
{
    char *text = read_file(example_path);
    char *block = strstr(text, ";[gpio next]");
    SW_CHECK(block != NULL);
    if (!block)
        return;
    static char out[1 << 16];
    size_t n = 0;
    for (char *p = block; *p; p++) {
        int line_start = p == block || p[-1] == '\n';
        if (line_start && p[0] == ';' && p[1] != ' ' && p[1] != '\n')
            continue;
        out[n++] = *p;
    }
    out[n] = '\0';
    sw_config cfg;
    sw_error err = {0};
    sw_status st = sw_config_load_memory(out, n, "gpio.ini", &cfg, &err);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    SW_CHECK(cfg.kiosk.gpio_count == 1);
    const sw_kiosk_gpio *g = &cfg.kiosk.gpio[0];
    SW_CHECK(!strcmp(g->name, "next") && !strcmp(g->chip, "gpiochip0"));
    SW_CHECK(g->line_offset == 17 && g->line_name[0] == '\0');
    SW_CHECK(g->active_low == 0 && g->bias == SW_BIAS_AS_IS);
    SW_CHECK(g->debounce_ms == 10 && g->min_press_ms == 2 && g->long_press_ms == 800);
    SW_CHECK(g->action == SW_ACTION_NONE && g->long_action == SW_ACTION_NONE);
    sw_debounce_params p = sw_kiosk_gpio_debounce(g);
    SW_CHECK(p.debounce_ns == 10000000 && p.min_press_ns == 2000000);
    SW_CHECK(p.long_press_ns == 800000000 && p.active_low == 0);
    sw_debounce d;
    SW_CHECK(sw_debounce_init(&d, &p, 0, 0) == 0);
}

static void empty_file_is_the_defaults(void)
{
    sw_config cfg, def;
    sw_config_defaults(&def);
    SW_CHECK(load_text("", &cfg, NULL) == SW_OK);
    SW_CHECK(same_values(&cfg, &def));
    SW_CHECK(load_text("; only a comment\n\n# another\n", &cfg, NULL) == SW_OK);
    SW_CHECK(same_values(&cfg, &def));
}

/* "pack =" with nothing after it is no pack, as in the example. */
static void empty_pack_beside_store_is_no_pack(void)
{
    sw_config cfg;
    sw_error err = {0};
    SW_CHECK_MSG(load_text("[pack]\npack =\nstore = units/7\n", &cfg, &err) == SW_OK, "%s",
                 err.message);
    SW_CHECK(cfg.pack[0] == '\0' && !strcmp(cfg.store, "units/7"));
}

static void values_are_read(void)
{
    const char *text =
        "\xEF\xBB\xBF[display]\r\n"
        "display = headless\r\n"
        "size = 640x480 ; inline comment\n"
        "[pack]\n"
        "store = /data/packs\n"
        "[render]\n"
        "memory_mb = 96.5\n"
        "[gamepad]\n"
        "enabled = off\n"
        "mapping = /etc/seamwalk/gamecontrollerdb.txt\n"
        "[navigation]\n"
        "mode = orbit\n"
        "attract_timeout_s = 0\n"
        "[gpio next]\n"
        "chip = gpiochip1\n"
        "line = BUTTON_NEXT\n"
        "active_low = yes\n"
        "bias = pull-up\n"
        "debounce_ms = 20\n"
        "long_press_ms = 0\n"
        "action = next_view\n"
        "[gpio home]\n"
        "chip = pinctrl-bcm2711\n"
        "line = 27\n"
        "long_action = attract\n";
    sw_config cfg;
    sw_error err = {0};
    sw_status st = load_text(text, &cfg, &err);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    SW_CHECK(cfg.width == 640 && cfg.height == 480);
    SW_CHECK(!strcmp(cfg.store, "/data/packs") && cfg.pack[0] == '\0');
    SW_CHECK(cfg.memory_mb == 96.5);
    SW_CHECK(cfg.kiosk.gamepad_enabled == 0);
    SW_CHECK(!strcmp(cfg.kiosk.gamepad_mapping, "/etc/seamwalk/gamecontrollerdb.txt"));
    SW_CHECK(cfg.kiosk.nav_mode == SW_NAV_ORBIT && cfg.kiosk.attract_timeout_s == 0);
    SW_CHECK(sw_config_key_line(&cfg, "display.size") == 3);
    SW_CHECK(cfg.kiosk.gpio_count == 2);
    const sw_kiosk_gpio *a = &cfg.kiosk.gpio[0], *b = &cfg.kiosk.gpio[1];
    SW_CHECK(!strcmp(a->line_name, "BUTTON_NEXT") && a->line_offset == -1);
    SW_CHECK(a->active_low == 1 && a->bias == SW_BIAS_PULL_UP && a->debounce_ms == 20);
    SW_CHECK(a->long_press_ms == 0 && a->action == SW_ACTION_NEXT_VIEW && a->line == 14);
    SW_CHECK(!strcmp(b->chip, "pinctrl-bcm2711") && b->line_offset == 27);
    SW_CHECK(b->line_name[0] == '\0' && b->long_action == SW_ACTION_ATTRACT);
    SW_CHECK(b->debounce_ms == 10 && b->long_press_ms == 800);
}

typedef struct bad_case {
    const char *text;
    const char *message;  /* the whole message starts with this */
} bad_case;

static const bad_case bad_cases[] = {
    {"[render]\nmemory_mb = 10\nfoo = 1\n",
     "bad.ini:3: [render] unknown key 'foo' (expected memory_mb, max_error_px, batch_tris)"},
    {"[render]\nmemory_mb = 10\n\n[rendr]\n", "bad.ini:4: unknown section [rendr]"},
    {"[render]\n[gamepads]\n", "bad.ini:2: unknown section [gamepads]"},
    {"[render]\nmemory_mb = 12x\n", "bad.ini:2: [render] memory_mb: expected a number, got '12x'"},
    {"[render]\nmemory_mb =\n", "bad.ini:2: [render] memory_mb: expected a number, got ''"},
    {"[render]\nmax_error_px = 0\n", "bad.ini:2: [render] max_error_px: expected 0.01..100, got 0"},
    {"[render]\nmemory_mb = inf\n", "bad.ini:2: [render] memory_mb: expected a number, got 'inf'"},
    {"[pack]\nboot_attempts = 2.5\n",
     "bad.ini:2: [pack] boot_attempts: expected an integer, got '2.5'"},
    {"[pack]\nboot_attempts = 0\n", "bad.ini:2: [pack] boot_attempts: expected 1..1000, got 0"},
    {"[display]\ndisplay = hdmi\n",
     "bad.ini:2: [display] display: expected auto, headless, kms, x11 or wayland, got 'hdmi'"},
    {"[navigation]\nmode = fly\n", "bad.ini:2: [navigation] mode: expected walk or orbit, got 'fly'"},
    {"[gamepad]\nenabled = maybe\n", "bad.ini:2: [gamepad] enabled: expected no, yes, off, on"},
    {"[display]\nsize = 1280\n", "bad.ini:2: [display] size: expected WIDTHxHEIGHT, each 16..8192"},
    {"[display]\nsize = 8x8\n", "bad.ini:2: [display] size: expected WIDTHxHEIGHT, each 16..8192"},
    {"[render]\nmemory_mb 256\n", "bad.ini:2: expected [section] or key = value"},
    {"[render]\nmemory_mb = 1\nmemory_mb = 2\n",
     "bad.ini:3: [render] memory_mb: given twice (first on line 2)"},
    {"memory_mb = 1\n", "bad.ini:1: memory_mb: expected a [section] before the first key"},
    {"[render\nmemory_mb = 1\n", "bad.ini:1: expected ']' to close the section name"},
    {"[render] x\n", "bad.ini:1: expected nothing but a comment after ']'"},
    {"[render]\n  memory_mb = 1\n", "bad.ini:2: unexpected indentation"},
    {"[render]\nmemory_mb = 1\n\0\n", "bad.ini:3: NUL byte in a text file"},
    {"[pack]\npack = \nstore = units/7\npack = a.swpack\n",
     "bad.ini:4: [pack] pack: given twice (first on line 2)"},
    {"[pack]\npack = a.swpack\nstore = units/7\n",
     "bad.ini:3: [pack] store: expected pack = FILE or store = DIR, not both (the other is on line 2)"},
    {"[gpio next]\nline = 3\n", "bad.ini:1: [gpio next] chip: missing"},
    {"[gpio next]\nchip = gpiochip0\n[render]\n", "bad.ini:1: [gpio next] line: missing"},
    {"[gpio next]\nchip = gpiochip0\nline = 3\nmin_press_ms = 11\n",
     "bad.ini:4: [gpio next] min_press_ms: expected at most debounce_ms (10), got 11"},
    {"[gpio next]\nchip = gpiochip0\nline = 3\nlong_press_ms = 5\ndebounce_ms = 5\n",
     "bad.ini:5: [gpio next] long_press_ms: expected 0 or more than debounce_ms (5), got 5"},
    {"[gpio next]\nchip = gpiochip0\nline = 3x\n",
     "bad.ini:3: [gpio next] line: expected a line offset 0..65535 or a line name, got '3x'"},
    {"[gpio next]\nchip =\n", "bad.ini:2: [gpio next] chip: expected a name, got nothing"},
    {"[gpio next]\nchip = c\nline = 1\naction = jump\n",
     "bad.ini:4: [gpio next] action: expected none, forward, back"},
    {"[gpio next]\nchip = c\nline = 1\npin = 4\n",
     "bad.ini:4: [gpio next] unknown key 'pin' (expected chip, line, debounce_ms"},
    {"[gpio next]\nchip = c\nline = 1\n[gpio next]\n",
     "bad.ini:4: [gpio next]: expected a new button name, [gpio next] is on line 1"},
    {"[gpio n/x]\n", "bad.ini:1: [gpio n/x]: expected [gpio NAME]"},
    {"[gpio ]\n", "bad.ini:1: [gpio ]: expected [gpio NAME]"},
};

static void bad_files_name_line_and_key(void)
{
    for (size_t i = 0; i < sizeof bad_cases / sizeof bad_cases[0]; i++) {
        const bad_case *c = &bad_cases[i];
        size_t size = strlen(c->text);
        if (strstr(c->message, "NUL byte"))
            size += 2; /* the case's text goes on past its NUL */
        sw_config cfg;
        sw_error err = {0};
        sw_status st = sw_config_load_memory(c->text, size, "bad.ini", &cfg, &err);
        SW_CHECK_MSG(st == SW_ERR_FORMAT, "case %zu: status %d", i, (int)st);
        SW_CHECK_MSG(!strncmp(err.message, c->message, strlen(c->message)),
                     "case %zu: got '%s', expected '%s...'", i, err.message, c->message);
    }
}

/* Paths hold up to SW_CONFIG_PATH_MAX - 1 bytes; inih's 200-byte lines leave
 * room for one more only without spaces around '='. */
static void long_values_and_lines_are_errors(void)
{
    static char text[512];
    char path[300];
    memset(path, 'a', SW_CONFIG_PATH_MAX);
    path[SW_CONFIG_PATH_MAX] = '\0';
    snprintf(text, sizeof text, "[pack]\npack=%s\n", path);
    sw_config cfg;
    sw_error err = {0};
    SW_CHECK(load_text(text, &cfg, &err) == SW_ERR_FORMAT);
    const char *expected = "bad.ini:2: [pack] pack: expected at most 191 bytes, got 192";
    SW_CHECK_MSG(!strcmp(err.message, expected), "%s", err.message);
    path[SW_CONFIG_PATH_MAX - 1] = '\0';
    snprintf(text, sizeof text, "[pack]\npack = %s\n", path);
    SW_CHECK_MSG(load_text(text, &cfg, &err) == SW_OK, "%s", err.message);
    SW_CHECK(strlen(cfg.pack) == SW_CONFIG_PATH_MAX - 1);
    memset(path, 'b', 250);
    path[250] = '\0';
    snprintf(text, sizeof text, "[pack]\n; %s\n", path);
    SW_CHECK(load_text(text, &cfg, &err) == SW_ERR_FORMAT);
    SW_CHECK_MSG(!strcmp(err.message, "bad.ini:2: line longer than 198 bytes"), "%s",
                 err.message);
}

static void too_many_gpio_sections_is_an_error(void)
{
    static char text[8192];
    size_t n = 0;
    for (int i = 0; i <= SW_CONFIG_GPIO_MAX; i++)
        n += (size_t)snprintf(text + n, sizeof text - n, "[gpio b%d]\nchip = c\nline = %d\n", i, i);
    sw_config cfg;
    sw_error err = {0};
    SW_CHECK(load_text(text, &cfg, &err) == SW_ERR_FORMAT);
    char expected[96];
    snprintf(expected, sizeof expected, "bad.ini:%d: [gpio b%d]: expected at most %d",
             3 * SW_CONFIG_GPIO_MAX + 1, SW_CONFIG_GPIO_MAX, SW_CONFIG_GPIO_MAX);
    SW_CHECK_MSG(!strncmp(err.message, expected, strlen(expected)), "%s", err.message);
}

static void missing_file_is_an_io_error(void)
{
    sw_config cfg;
    sw_error err = {0};
    SW_CHECK(sw_config_load("no/such/seamwalk.ini", &cfg, &err) == SW_ERR_IO);
    SW_CHECK_MSG(!strncmp(err.message, "no/such/seamwalk.ini: ", 22), "%s", err.message);
}

/* ---- --config in the options ------------------------------------------- */

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "wb");
    SW_CHECK(f != NULL);
    if (f) {
        fputs(text, f);
        fclose(f);
    }
}

static sw_status parse(sw_options *o, sw_error *err, int argc, char **argv)
{
    return sw_options_parse(argc, argv, o, err);
}

static const char unit_ini[] = "[display]\nsize = 640x480\nfov_deg = 60\n[pack]\npack = a.swpack\n"
                               "[render]\nmemory_mb = 100\nmax_error_px = 2\n"
                               "[navigation]\nmode = orbit\n";

static void config_fills_what_the_command_line_leaves_out(void)
{
    write_text("unit.ini", unit_ini);
    static sw_options o;
    sw_error err = {0};
    char *argv[] = {"seamwalk", "--config", "unit.ini", "--memory-mb", "50"};
    sw_status st = parse(&o, &err, 5, argv);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    SW_CHECK(o.memory_mb == 50);         /* the command line wins */
    SW_CHECK(o.max_error_px == 2);       /* the file fills the rest */
    SW_CHECK(o.fov_deg == 60);
    SW_CHECK(o.pack_path && !strcmp(o.pack_path, "a.swpack"));
    SW_CHECK(o.width == 640 && o.height == 480 && o.orbit == 1);
    SW_CHECK(o.frames == 120 && o.boot_attempts == 3);  /* neither gives them */
    SW_CHECK(o.config_path && !strcmp(o.config_path, "unit.ini"));
}

static void command_line_choice_replaces_the_files(void)
{
    write_text("unit.ini", unit_ini);
    static sw_options o;
    sw_error err = {0};
    char *argv[] = {"seamwalk", "--store", "units/7", "--path", "walk.path", "--headless",
                    "320x200", "--max-error-px", "0.25", "--config", "unit.ini"};
    sw_status st = parse(&o, &err, 11, argv);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    SW_CHECK(o.store_dir && !strcmp(o.store_dir, "units/7") && o.pack_path == NULL);
    SW_CHECK(o.path_file && !strcmp(o.path_file, "walk.path") && o.orbit == 0);
    SW_CHECK(o.width == 320 && o.height == 200);
    SW_CHECK(o.max_error_px == 0.25 && o.memory_mb == 100);
}

static void display_comes_from_the_file_unless_the_command_line_names_one(void)
{
    write_text("kms.ini", "; a kiosk\n[display]\ndisplay = kms\nsize = 1920x1080\n"
                          "[pack]\npack = a.swpack\n[navigation]\nmode = orbit\n");
    static sw_options o;
    sw_error err = {0};
    char *argv[] = {"seamwalk", "--config", "kms.ini", "--headless", "64x64"};
    sw_status st = parse(&o, &err, 3, argv);
    if (SW_HAVE_KMS) {
        SW_CHECK_MSG(st == SW_OK, "%s", err.message);
        SW_CHECK(o.display == SW_DISPLAY_KIND_KMS && o.width == 1920 && o.height == 1080);
    } else {   /* a build without KMS refuses the file's display */
        SW_CHECK_MSG(st == SW_ERR_ARG && !strcmp(err.message, "built without KMS "
                     "(SW_WITH_KMS=OFF)"), "%s", err.message);
    }
    st = parse(&o, &err, 5, argv);  /* --headless overrides the file's display and size */
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    SW_CHECK(o.display == SW_DISPLAY_KIND_HEADLESS && o.width == 64);
    char *window[] = {"seamwalk", "--config", "kms.ini", "--display", "x11", "--size", "800x600"};
    st = parse(&o, &err, 7, window);
    if (!SW_HAVE_X11) {   /* a build without X11 refuses the window it was asked for */
        SW_CHECK_MSG(st == SW_ERR_ARG && !strcmp(err.message, "built without X11 "
                     "(SW_WITH_X11=OFF)"), "%s", err.message);
        return;
    }
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    SW_CHECK(o.display == SW_DISPLAY_KIND_X11 && o.width == 800 && o.height == 600);
}

/* The service as shipped: the unit's own ExecStart arguments (from
 * seamwalk.service beside the example) with the shipped config in place of
 * /etc/seamwalk/seamwalk.ini. A config with neither pack nor store made
 * every start a usage error (exit 2), restarted every RestartSec for ever;
 * this start must parse, to the store, the root-owned keys and KMS. */
static void the_units_command_line_with_the_shipped_config_parses(void)
{
    char unit_path[1024], line[1024] = "";
    const char *slash = strrchr(example_path, '/');
    int dir = slash ? (int)(slash - example_path) + 1 : 0;
    snprintf(unit_path, sizeof unit_path, "%.*sseamwalk.service", dir, example_path);
    FILE *f = fopen(unit_path, "r");
    SW_CHECK_MSG(f != NULL, "%s", unit_path);
    if (!f)
        return;
    while (fgets(line, sizeof line, f) && strncmp(line, "ExecStart=", 10) != 0)
        line[0] = '\0';
    fclose(f);
    char *argv[32];
    int argc = 0;
    for (char *w = strtok(line + 10, " \n"); w && argc < 32; w = strtok(NULL, " \n"))
        argv[argc++] = w;
    SW_CHECK_MSG(argc > 2 && strstr(argv[0], "seamwalk") != NULL, "ExecStart: %d words", argc);
    int config_at = 0;
    for (int i = 1; i + 1 < argc; i++)
        if (!strcmp(argv[i], "--config") && !strcmp(argv[i + 1], "/etc/seamwalk/seamwalk.ini"))
            config_at = i + 1;
    SW_CHECK_MSG(config_at > 0, "ExecStart passes no --config /etc/seamwalk/seamwalk.ini");
    if (!config_at)
        return;
    argv[config_at] = (char *)example_path;
    static sw_options o;
    sw_error err = {0};
    sw_status st = parse(&o, &err, argc, argv);
    if (!SW_HAVE_KMS) {   /* the shipped display is kms: a build without it refuses it */
        SW_CHECK_MSG(st == SW_ERR_ARG && strstr(err.message, "built without KMS"), "%s",
                     err.message);
        return;
    }
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    SW_CHECK(o.display == SW_DISPLAY_KIND_KMS);
    SW_CHECK(o.pack_path == NULL);
    SW_CHECK_MSG(o.store_dir && !strcmp(o.store_dir, "/var/lib/seamwalk/store"), "%s",
                 o.store_dir ? o.store_dir : "(none)");
    SW_CHECK_MSG(o.keys_path && !strcmp(o.keys_path, "/etc/seamwalk/keys"), "%s",
                 o.keys_path ? o.keys_path : "(none)");
    SW_CHECK(o.navigate == 1 && o.measure_every == 0 && o.duration_s > 1e6);
}

/* [budgets] sets the workers and the frame time the budgets hold; the
 * command line wins. */
static void budgets_come_from_the_file(void)
{
    write_text("budgets.ini", "[pack]\npack = a.swpack\n[navigation]\nmode = orbit\n"
                              "[budgets]\nframe_ms = 25\nworkers = 0\n");
    static sw_options o;
    sw_error err = {0};
    char *argv[] = {"seamwalk", "--config", "budgets.ini", "--headless", "64x48", "--workers",
                    "2"};
    sw_status st = parse(&o, &err, 5, argv);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    SW_CHECK(o.target_ms == 25 && o.workers == 0);
    st = parse(&o, &err, 7, argv);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    SW_CHECK(o.target_ms == 25 && o.workers == 2);
    write_text("budgets.ini", "[budgets]\nworkers = 65\n");
    SW_CHECK(parse(&o, &err, 5, argv) == SW_ERR_FORMAT);
    SW_CHECK_MSG(strstr(err.message, "budgets.ini:2: [budgets] workers:") != NULL, "%s",
                 err.message);
    /* The file takes what the command line takes, no more: workers up to
     * the walk's 16 (17 once passed here and failed when the workers
     * started), a frame time up to 10 s (the file stopped at 1 s). */
    write_text("budgets.ini", "[pack]\npack = a.swpack\n[navigation]\nmode = orbit\n"
                              "[budgets]\nworkers = 16\nframe_ms = 5000\n");
    st = parse(&o, &err, 5, argv);
    SW_CHECK_MSG(st == SW_OK && o.workers == 16 && o.target_ms == 5000, "%s", err.message);
    write_text("budgets.ini", "[budgets]\nworkers = 17\n");
    SW_CHECK(parse(&o, &err, 5, argv) == SW_ERR_FORMAT);
    SW_CHECK_MSG(strstr(err.message, "budgets.ini:2: [budgets] workers:") != NULL, "%s",
                 err.message);
    char *too_many[] = {"seamwalk", "--headless", "64x48", "--orbit", "--pack", "a.swpack",
                        "--workers", "17"};
    SW_CHECK(parse(&o, &err, 8, too_many) != SW_OK);
    SW_CHECK_MSG(strstr(err.message, "--workers") != NULL, "%s", err.message);
}

/* --navigate without --config walks with the config's defaults: keyboard and
 * gamepads on, the documented speeds (a zeroed config walked nowhere). */
static void without_a_file_the_config_has_its_defaults(void)
{
    static sw_options o;
    sw_config want;
    sw_config_defaults(&want);
    sw_error err = {0};
    char *argv[] = {"seamwalk", "--pack", "a.swpack", "--navigate", "--headless", "64x48"};
    sw_status st = parse(&o, &err, 6, argv);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    SW_CHECK(o.navigate && o.config_path == NULL);
    SW_CHECK(o.config.kiosk.keyboard_enabled && o.config.kiosk.gamepad_enabled);
    SW_CHECK(o.config.kiosk.walk_speed_mm_s == want.kiosk.walk_speed_mm_s &&
             want.kiosk.walk_speed_mm_s > 0);
    SW_CHECK(o.config.kiosk.attract_timeout_s == want.kiosk.attract_timeout_s);
    SW_CHECK(!strcmp(o.config.kiosk.keyboard_device, "auto"));
}

static void an_unknown_display_word_is_refused(void)
{
    static sw_options o;
    sw_error err = {0};
    char *argv[] = {"seamwalk", "--pack", "a.swpack", "--orbit", "--display", "fbdev"};
    SW_CHECK(parse(&o, &err, 6, argv) == SW_ERR_ARG);
    SW_CHECK_MSG(!strcmp(err.message, "--display expects auto, headless, kms, x11 or wayland, "
                         "got 'fbdev'"), "%s", err.message);
    char *size[] = {"seamwalk", "--pack", "a.swpack", "--orbit", "--size", "wide"};
    SW_CHECK(parse(&o, &err, 6, size) == SW_ERR_ARG);
    SW_CHECK_MSG(!strcmp(err.message, "--size expects WIDTHxHEIGHT, got 'wide'"), "%s",
                 err.message);
}

static void bad_config_stops_option_parsing(void)
{
    write_text("bad_unit.ini", "[render]\nmemory_mb = lots\n");
    static sw_options o;
    sw_error err = {0};
    char *argv[] = {"seamwalk", "--pack", "a.swpack", "--headless", "64x64", "--orbit",
                    "--config", "bad_unit.ini"};
    SW_CHECK(parse(&o, &err, 8, argv) == SW_ERR_FORMAT);
    SW_CHECK_MSG(!strcmp(err.message, "bad_unit.ini:2: [render] memory_mb: expected a number, "
                         "got 'lots'"), "%s", err.message);
    char *twice[] = {"seamwalk", "--config", "unit.ini", "--config", "bad_unit.ini"};
    write_text("unit.ini", unit_ini);
    SW_CHECK(parse(&o, &err, 5, twice) == SW_ERR_ARG);
    SW_CHECK_MSG(strstr(err.message, "--config given twice") != NULL, "%s", err.message);
}

static void without_config_no_file_is_read(void)
{
    static sw_options o;
    sw_error err = {0};
    char *argv[] = {"seamwalk", "--pack", "a.swpack", "--orbit"};
    sw_status st = parse(&o, &err, 4, argv);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    SW_CHECK(o.config_path == NULL && o.memory_mb == 256);
    /* No size: the display decides (headless then refuses, sw_display.h). */
    SW_CHECK(o.display == SW_DISPLAY_KIND_AUTO && o.width == 0 && o.height == 0);
}

/* The kiosk input keys ([gamepad] actions, [keyboard], the navigation
 * timing) go through the same table: bad words, unknown keys and ranges
 * name the file, the line and the key. */
static void kiosk_input_keys_have_file_line_errors(void)
{
    static const struct { const char *text, *needle; } bad[] = {
        {"[gamepad]\na = fly\n", "x.ini:2: [gamepad] a: expected none, forward, back"},
        {"[gamepad]\nz = home\n", "x.ini:2: [gamepad] unknown key 'z'"},
        {"[keyboard]\nenabled = maybe\n", "x.ini:2: [keyboard] enabled: expected no, yes"},
        {"[keyboard]\nlayout = us\n", "x.ini:2: [keyboard] unknown key 'layout'"},
        {"[navigation]\naccel_s = 0\n", "x.ini:2: [navigation] accel_s: expected 0.01..10"},
        {"[navigation]\ntransition_s = -1\n", "transition_s: expected 0.05..60"},
        {"[gpio b]\nchip = c\nline = 1\naction = strafe_up\n", "x.ini:4: [gpio b] action"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        sw_config cfg;
        sw_error err = {0};
        SW_CHECK(sw_config_load_memory(bad[i].text, strlen(bad[i].text), "x.ini", &cfg, &err) ==
                 SW_ERR_FORMAT);
        SW_CHECK_MSG(strstr(err.message, bad[i].needle) != NULL, "%s (expected '%s')",
                     err.message, bad[i].needle);
    }
    static const char good[] = "[gamepad]\na = home\ndpup = look_up\n[keyboard]\n"
                               "device = /dev/input/event3\n[navigation]\naccel_s = 1\n";
    sw_config cfg;
    sw_error err = {0};
    SW_CHECK(sw_config_load_memory(good, sizeof good - 1, "x.ini", &cfg, &err) == SW_OK);
    SW_CHECK(cfg.kiosk.gamepad_action[0] == SW_ACTION_HOME && cfg.kiosk.gamepad_action[11] ==
             SW_ACTION_LOOK_UP && !strcmp(cfg.kiosk.keyboard_device, "/dev/input/event3") &&
             cfg.kiosk.accel_s == 1 && cfg.kiosk.gamepad_action[1] == SW_ACTION_PREV_VIEW);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: %s firmware/dist/seamwalk.ini\n", argv[0]);
        return 2;
    }
    example_path = argv[1];
    SW_RUN(kiosk_input_keys_have_file_line_errors);
    SW_RUN(example_loads_and_is_the_defaults_but_store_and_kms);
    SW_RUN(example_gpio_block_uncommented_is_the_gpio_defaults);
    SW_RUN(empty_file_is_the_defaults);
    SW_RUN(empty_pack_beside_store_is_no_pack);
    SW_RUN(values_are_read);
    SW_RUN(bad_files_name_line_and_key);
    SW_RUN(long_values_and_lines_are_errors);
    SW_RUN(too_many_gpio_sections_is_an_error);
    SW_RUN(missing_file_is_an_io_error);
    SW_RUN(config_fills_what_the_command_line_leaves_out);
    SW_RUN(command_line_choice_replaces_the_files);
    SW_RUN(display_comes_from_the_file_unless_the_command_line_names_one);
    SW_RUN(the_units_command_line_with_the_shipped_config_parses);
    SW_RUN(without_a_file_the_config_has_its_defaults);
    SW_RUN(budgets_come_from_the_file);
    SW_RUN(an_unknown_display_word_is_refused);
    SW_RUN(bad_config_stops_option_parsing);
    SW_RUN(without_config_no_file_is_read);
    return sw_test_finish();
}
