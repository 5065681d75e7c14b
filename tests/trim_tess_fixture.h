/* SPDX-License-Identifier: MIT */
/* Fixtures of the trimmed-tessellation tests (test_trim_tess.c,
 * test_trim_tess_seams.c): surfaces from trim_tess_shapes.h, loops whose
 * points lie on the surface, one tessellation into static buffers. One copy
 * per test program. */
#ifndef TRIM_TESS_FIXTURE_H
#define TRIM_TESS_FIXTURE_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sw_test.h"
#include "sw_trim_tess.h"
#include "trim_tess_shapes.h"

enum { MAXV = 65536, MAXI = 6 * 65536, MAXP = 4096 };

static float g_pos[3 * MAXV], g_nrm[3 * MAXV], g_uv[2 * MAXV];
static uint32_t g_ids[MAXV];
static uint16_t g_idx[MAXI];
static unsigned char g_block[96u << 20];

/* ---- surfaces ---------------------------------------------------------------- */

typedef struct surface {
    sw_trim_patch patches[16];
    float ctrl[16][64];
    uint32_t count;
} surface;

static inline void make_bump(surface *s, int k) { s->count = shape_bump(k, s->patches, s->ctrl); }
static inline void make_cylinder(surface *s) { s->count = shape_cylinder(s->patches, s->ctrl); }

static inline const sw_trim_patch *patch_at(const surface *s, double u, double v)
{
    for (uint32_t i = 0; i < s->count; i++) {
        const float *d = s->patches[i].domain;
        if (u >= d[0] && u <= d[1] && v >= d[2] && v <= d[3])
            return &s->patches[i];
    }
    return &s->patches[0];
}

static inline sw_surface_point eval_at(const surface *s, double u, double v, sw_eval_order order)
{
    const sw_trim_patch *p = patch_at(s, u, v);
    double ctrl[4 * 16 * 16];
    sw_bezier_patch d = sw_bezier_patch_from_float(&p->patch, ctrl);
    sw_surface_point q;
    double a = (u - p->domain[0]) / (p->domain[1] - p->domain[0]);
    double b = (v - p->domain[2]) / (p->domain[3] - p->domain[2]);
    sw_bezier_eval(&d, fmin(fmax(a, 0), 1), fmin(fmax(b, 0), 1), order, &q);
    return q;
}

/* ---- loops ------------------------------------------------------------------- */

typedef struct loops {
    sw_trim_point pts[MAXP];
    uint32_t first[16];
    uint32_t count, n;
} loops;

static inline void begin_loops(loops *l)
{
    l->count = 0, l->n = 0, l->first[0] = 0;
}

/* Each point's position is the surface's there, in float; ids count up. */
static inline void add_point(loops *l, const surface *s, double u, double v)
{
    sw_trim_point *p = &l->pts[l->n];
    p->uv[0] = (float)u, p->uv[1] = (float)v;
    sw_surface_point q = eval_at(s, p->uv[0], p->uv[1], SW_EVAL_POINT);
    p->p[0] = (float)q.p.x, p->p[1] = (float)q.p.y, p->p[2] = (float)q.p.z;
    p->id = 1000 + l->n;
    l->n++;
}

static inline void end_loop(loops *l) { l->first[++l->count] = l->n; }

/* The rectangle [u0,u1] x [v0,v1], per points per side, counter-clockwise. */
static inline void add_rect(loops *l, const surface *s, double u0, double u1, double v0, double v1,
                     int per)
{
    for (int k = 0; k < per; k++)
        add_point(l, s, u0 + (u1 - u0) * k / per, v0);
    for (int k = 0; k < per; k++)
        add_point(l, s, u1, v0 + (v1 - v0) * k / per);
    for (int k = 0; k < per; k++)
        add_point(l, s, u1 - (u1 - u0) * k / per, v1);
    for (int k = 0; k < per; k++)
        add_point(l, s, u0, v1 - (v1 - v0) * k / per);
    end_loop(l);
}

static inline void add_circle(loops *l, const surface *s, double cu, double cv, double r, int n, int ccw)
{
    for (int k = 0; k < n; k++) {
        double a = 2 * SW_PI * k / n * (ccw ? 1 : -1);
        add_point(l, s, cu + r * cos(a), cv + r * sin(a));
    }
    end_loop(l);
}

static inline sw_trim_loops view(const loops *l)
{
    sw_trim_loops v = {l->pts, l->first, l->count};
    return v;
}

/* ---- running and checking ------------------------------------------------------ */

typedef struct mesh {
    uint32_t nv, ni;
    sw_trim_tess_result res;
} mesh;

static inline sw_status run(const surface *s, const loops *l, double err, mesh *m)
{
    sw_arena a;
    sw_arena_init(&a, g_block, sizeof g_block);
    sw_trim_loops lv = view(l);
    sw_trim_tess_buffers b = {g_pos, g_nrm, g_uv, g_ids, g_idx, MAXV, MAXI, 0, NULL, 0};
    sw_error e = {0};
    sw_status st = sw_trim_tess(s->patches, s->count, &lv, err, NULL, &a, &b, &m->res, &e);
    if (st != SW_OK)
        fprintf(stderr, "  sw_trim_tess: %s\n", e.message);
    m->nv = m->res.vertex_count, m->ni = m->res.index_count;
    SW_CHECK(a.used == 0);
    return st;
}

#endif
