/* SPDX-License-Identifier: MIT */
/* libFuzzer entry point for the configuration file parser (sw_config.h):
 * every input either loads into a config that keeps the parser's promises or
 * fails with a message that names the file and a line. Accepted buttons'
 * parameters are accepted by the debouncer. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "sw_config.h"
#include "sw_kiosk.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int gpio_ok(const sw_kiosk_gpio *g)
{
    sw_debounce d;
    sw_debounce_params p = sw_kiosk_gpio_debounce(g);
    return sw_debounce_init(&d, &p, 0, 0) == 0 && g->name[0] && g->chip[0] &&
           (g->line_name[0] != '\0') != (g->line_offset >= 0);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static sw_config cfg;
    sw_error err = {0};
    sw_status st = sw_config_load_memory((const char *)data, size, "fuzz.ini", &cfg, &err);
    if (st != SW_OK) {
        if (strncmp(err.message, "fuzz.ini:", 9) != 0 || err.message[9] < '1' ||
            err.message[9] > '9')
            abort();
        return 0;
    }
    if (cfg.kiosk.gpio_count < 0 || cfg.kiosk.gpio_count > SW_CONFIG_GPIO_MAX)
        abort();
    for (int i = 0; i < cfg.kiosk.gpio_count; i++)
        if (!gpio_ok(&cfg.kiosk.gpio[i]))
            abort();
    if (cfg.pack[0] && cfg.store[0])
        abort();
    if (!(cfg.memory_mb >= 1 && cfg.max_error_px >= 0.01 && cfg.fov_deg >= 5))
        abort();
    return 0;
}
