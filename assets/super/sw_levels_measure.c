/* SPDX-License-Identifier: MIT */
/* A level's measured error (sw_levels_measure.h). */
#include "sw_levels_measure.h"

#include <math.h>

#include "sw_surface_at.h"

static double triangle_worst(sw_surface_sampler *surface, const float *positions,
                             const float *uvs, const uint16_t t[3], uint32_t n)
{
    double worst = 0;
    for (uint32_t i = 0; i <= n; i++)
        for (uint32_t j = 0; i + j <= n; j++) {
            double w[3] = { (double)i / n, (double)j / n, (double)(n - i - j) / n };
            double p[3] = { 0, 0, 0 }, uv[2] = { 0, 0 };
            for (int k = 0; k < 3; k++) {
                for (int a = 0; a < 3; a++)
                    p[a] += w[k] * positions[3 * (size_t)t[k] + a];
                for (int a = 0; a < 2; a++)
                    uv[a] += w[k] * uvs[2 * (size_t)t[k] + a];
            }
            sw_vec3 s = sw_surface_sampler_at(surface, uv[0], uv[1]);
            worst = fmax(worst, sqrt((p[0] - s.x) * (p[0] - s.x) + (p[1] - s.y) * (p[1] - s.y) +
                                     (p[2] - s.z) * (p[2] - s.z)));
        }
    return worst;
}

double sw_levels_measure(const sw_trim_patch *patches, uint32_t patch_count,
                         const float *positions, const float *uvs, const uint16_t *indices,
                         uint32_t index_count, uint32_t n)
{
    sw_surface_sampler surface;
    sw_surface_sampler_init(&surface, patches, patch_count);
    double worst = 0;
    for (uint32_t t = 0; t + 2 < index_count; t += 3)
        worst = fmax(worst, triangle_worst(&surface, positions, uvs, indices + t, n ? n : 1));
    return worst;
}
