/* SPDX-License-Identifier: MIT */
/* The surfaces the trimmed-tessellation test and benchmark share (tests/
 * test_trim_tess.c, tests/bench/trim_tess_bench.c): a bicubic bump cut into
 * k x k patches and a rational quarter cylinder, as sw_trim_patch views of
 * the caller's control arrays (64 floats per patch: bicubic at most). */
#ifndef TRIM_TESS_SHAPES_H
#define TRIM_TESS_SHAPES_H

#include <math.h>

#include "sw_bezier.h"
#include "sw_trim_tess.h"

/* The bump over [0,1]^2 cut into k x k patches (exact subdivision, k <= 4),
 * patch (a, b) covering [a/k, (a+1)/k] x [b/k, (b+1)/k]. Returns k * k. */
static inline uint32_t shape_bump(int k, sw_trim_patch *patches, float (*ctrl)[64])
{
    static const double h[4][4] = {{0, 0.2, 0.1, 0}, {0.1, 0.8, -0.4, 0.2},
                                   {0.3, -0.5, 0.9, 0.1}, {0, 0.1, 0.2, 0.3}};
    double whole[64], piece[64];
    for (int j = 0; j < 4; j++)
        for (int i = 0; i < 4; i++) {
            double *c = whole + (j * 4 + i) * 4;
            c[0] = i / 3.0, c[1] = j / 3.0, c[2] = h[i][j], c[3] = 1;
        }
    sw_bezier_patch w = {3, 3, 0, whole};
    uint32_t n = 0;
    for (int b = 0; b < k; b++)
        for (int a = 0; a < k; a++, n++) {
            sw_bezier_subpatch(&w, (double)a / k, (double)(a + 1) / k, (double)b / k,
                               (double)(b + 1) / k, piece);
            for (int q = 0; q < 64; q++)
                ctrl[n][q] = (float)piece[q];
            sw_trim_patch *p = &patches[n];
            p->patch = (sw_bezier_patchf){3, 3, 0, ctrl[n]};
            p->domain[0] = (float)a / k, p->domain[1] = (float)(a + 1) / k;
            p->domain[2] = (float)b / k, p->domain[3] = (float)(b + 1) / k;
        }
    return n;
}

/* A quarter of the unit cylinder: u along the arc (rational quadratic), v
 * along the axis (height 2), domain [0,1]^2. Returns 1. */
static inline uint32_t shape_cylinder(sw_trim_patch *patches, float (*ctrl)[64])
{
    const double r2 = sqrt(0.5), arc[3][3] = {{1, 0, 1}, {1, 1, r2}, {0, 1, 1}};
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 3; i++) {
            float *c = ctrl[0] + (j * 3 + i) * 4;
            c[0] = (float)arc[i][0], c[1] = (float)arc[i][1], c[2] = (float)(2 * j);
            c[3] = (float)arc[i][2];
        }
    patches[0].patch = (sw_bezier_patchf){2, 1, 1, ctrl[0]};
    patches[0].domain[0] = 0, patches[0].domain[1] = 1;
    patches[0].domain[2] = 0, patches[0].domain[3] = 1;
    return 1;
}

#endif
