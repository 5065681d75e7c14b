/* SPDX-License-Identifier: MIT */
/* The exact surface at a (u, v) (core/sw_surface_at.h): the patch whose
 * domain holds the point answers, the nearest one for a point outside, the
 * first of equals on a shared edge; and the sampler, which tries the patch
 * it found last, answers as sw_surface_at does bit for bit, also where
 * domains overlap (where trying the last patch first would answer wrong). */
#include <string.h>

#include "sw_surface_at.h"
#include "sw_test.h"

/* A bilinear patch: the plane z = h over [x0, x0 + 1] x [y0, y0 + 1]
 * (its corners, u fastest; x, y, z, w each). */
static void flat(float ctrl[16], float x0, float y0, float h)
{
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 2; i++) {
            float *c = ctrl + 4 * (2 * j + i);
            c[0] = x0 + (float)i, c[1] = y0 + (float)j, c[2] = h, c[3] = 1;
        }
}

static sw_trim_patch patch(const float *ctrl, float u0, float u1, float v0, float v1)
{
    sw_trim_patch p = { { 1, 1, 0, ctrl }, { u0, u1, v0, v1 } };
    return p;
}

static int same(sw_vec3 a, sw_vec3 b) { return memcmp(&a, &b, sizeof a) == 0; }

/* The sampler against sw_surface_at over a grid of points inside, on the
 * edges of and beyond the patches, in an order that keeps leaving the
 * last patch. */
static void sampler_agrees(const sw_trim_patch *patches, uint32_t n, int disjoint)
{
    sw_surface_sampler s;
    sw_surface_sampler_init(&s, patches, n);
    SW_CHECK(s.disjoint == disjoint);
    int mismatches = 0;
    for (int k = 0; k < 3; k++)
        for (int j = -2; j <= 26; j++)
            for (int i = -2; i <= 26; i++) {
                double u = (k == 1 ? 24 - i : i) / 12.0, v = j / 12.0;
                mismatches += !same(sw_surface_sampler_at(&s, u, v),
                                    sw_surface_at(patches, n, u, v));
            }
    SW_CHECK_MSG(mismatches == 0, "%d points differ", mismatches);
}

static void test_the_holding_patch_answers(void)
{
    float a[16], b[16];
    flat(a, 0, 0, 1), flat(b, 1, 0, 2);
    const sw_trim_patch two[2] = { patch(a, 0, 1, 0, 1), patch(b, 1, 2, 0, 1) };
    SW_CHECK(sw_surface_at(two, 2, 0.25, 0.5).z == 1);
    SW_CHECK(sw_surface_at(two, 2, 1.75, 0.5).z == 2);
    SW_CHECK(sw_surface_at(two, 2, 1.0, 0.5).z == 1);    /* on the shared edge: the first */
    SW_CHECK(sw_surface_at(two, 2, 2.5, 0.5).z == 2);    /* beyond: the nearest, clamped */
    sw_vec3 p = sw_surface_at(two, 2, 1.5, 0.25);
    SW_CHECK(p.x == 1.5 && p.y == 0.25);
}

static void test_sampler_answers_as_sw_surface_at(void)
{
    float c[4][16];
    sw_trim_patch quad[4];
    for (int k = 0; k < 4; k++) {
        flat(c[k], (float)(k % 2), (float)(k / 2), (float)k);
        quad[k] = patch(c[k], (float)(k % 2), (float)(k % 2 + 1), (float)(k / 2),
                        (float)(k / 2 + 1));
    }
    sampler_agrees(quad, 4, 1);
    /* A patch whose domain overlaps another's: a point strictly inside the
     * last patch may still belong to the other (more inside it). */
    quad[3] = patch(c[3], 0.5f, 1.5f, -0.5f, 1.5f);
    sampler_agrees(quad, 4, 0);
    sw_surface_sampler s;
    sw_surface_sampler_init(&s, quad, 4);
    sw_surface_sampler_at(&s, 0.2, 0.5);             /* in patch 0 alone */
    SW_CHECK(sw_surface_sampler_at(&s, 0.9, 0.9).z == 3);   /* patch 3's: deeper inside it */
}

int main(void)
{
    SW_RUN(test_the_holding_patch_answers);
    SW_RUN(test_sampler_answers_as_sw_surface_at);
    return sw_test_finish();
}
