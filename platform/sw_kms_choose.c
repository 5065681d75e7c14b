/* SPDX-License-Identifier: MIT */
#include "sw_kms_choose.h"

int sw_kms_choose_connector(const sw_kms_connector_info *connectors, int count)
{
    for (int i = 0; i < count; i++)
        if (connectors[i].connected && connectors[i].mode_count > 0)
            return i;
    return -1;
}

/* a better than b: larger area, then higher refresh; ties keep the first. */
static int larger(const sw_kms_mode_info *a, const sw_kms_mode_info *b)
{
    long area_a = (long)a->width * a->height, area_b = (long)b->width * b->height;
    return area_a != area_b ? area_a > area_b : a->refresh_hz > b->refresh_hz;
}

int sw_kms_choose_mode(const sw_kms_mode_info *modes, int count, int want_width,
                       int want_height)
{
    int exact = -1, preferred = -1, largest = -1;
    for (int i = 0; i < count; i++) {
        const sw_kms_mode_info *m = &modes[i];
        if (want_width > 0 && m->width == want_width && m->height == want_height &&
            (exact < 0 || m->refresh_hz > modes[exact].refresh_hz))
            exact = i;
        if (m->preferred && preferred < 0)
            preferred = i;
        if (largest < 0 || larger(m, &modes[largest]))
            largest = i;
    }
    return exact >= 0 ? exact : preferred >= 0 ? preferred : largest;
}
