/* SPDX-License-Identifier: MIT */
/* Shapes built in the tests of the model and the trims (test_model.c,
 * test_trim.c): exact rational circles as trim curves, rectangles as
 * polygons of lines, planes as B-spline surfaces with the identity
 * parameterisation. Everything lives in caller-provided structs. */
#ifndef MODEL_SHAPES_H
#define MODEL_SHAPES_H

#include <math.h>
#include <string.h>

#include "sw_nurbs.h"

/* A full circle as a degree-2 rational B-spline: nine control points on the
 * square around it, weights 1 and sqrt(2)/2 (The NURBS Book, section 7.5). */
typedef struct shape_circle {
    double knots[12];
    double ctrl[9 * 4];
    sw_nurbs_curve curve;
} shape_circle;

static inline void shape_circle_init(shape_circle *c, double cu, double cv, double r, int clockwise)
{
    static const double k[12] = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    static const double dir[9][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0},
                                     {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
    memcpy(c->knots, k, sizeof k);
    for (int i = 0; i < 9; i++) {
        double s = clockwise ? -1 : 1;
        c->ctrl[4 * i + 0] = cu + r * dir[i][0];
        c->ctrl[4 * i + 1] = cv + s * r * dir[i][1];
        c->ctrl[4 * i + 2] = 0;
        c->ctrl[4 * i + 3] = (i % 2) ? sqrt(0.5) : 1.0;
    }
    c->curve = (sw_nurbs_curve){2, 9, c->knots, c->ctrl};
}

/* Four degree-1 curves around [u0, u1] x [v0, v1], counter-clockwise. */
typedef struct shape_rect {
    double knots[4];
    double ctrl[4][2 * 4];
    sw_nurbs_curve curves[4];
} shape_rect;

static inline void shape_rect_init(shape_rect *r, double u0, double u1, double v0, double v1)
{
    const double corner[5][2] = {{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}, {u0, v0}};
    const double k[4] = {0, 0, 1, 1};
    memcpy(r->knots, k, sizeof k);
    for (int e = 0; e < 4; e++) {
        double *c = r->ctrl[e];
        c[0] = corner[e][0], c[1] = corner[e][1], c[2] = 0, c[3] = 1;
        c[4] = corner[e + 1][0], c[5] = corner[e + 1][1], c[6] = 0, c[7] = 1;
        r->curves[e] = (sw_nurbs_curve){1, 2, r->knots, c};
    }
}

/* The plane z = 0 over [0, su] x [0, sv] as a clamped B-spline of degree p
 * with spans_u x spans_v uniform spans and control points at the Greville
 * abscissae, so S(u, v) = (u, v, 0) exactly. */
enum { SHAPE_PLANE_MAX = 16 };
typedef struct shape_plane {
    double knots_u[SHAPE_PLANE_MAX + 8], knots_v[SHAPE_PLANE_MAX + 8];
    double ctrl[(SHAPE_PLANE_MAX + 4) * (SHAPE_PLANE_MAX + 4) * 4];
    sw_nurbs_surface surface;
} shape_plane;

static inline int shape_knots(double *knots, int p, int spans, double size)
{
    int count = spans + p, n = 0;
    for (int i = 0; i <= p; i++)
        knots[n++] = 0;
    for (int i = 1; i < spans; i++)
        knots[n++] = size * i / spans;
    for (int i = 0; i <= p; i++)
        knots[n++] = size;
    return count;
}

static inline double shape_greville(const double *knots, int p, int i)
{
    double s = 0;
    for (int k = 1; k <= p; k++)
        s += knots[i + k];
    return s / p;
}

static inline void shape_plane_init(shape_plane *pl, int p, int spans_u, int spans_v, double su,
                                    double sv)
{
    int nu = shape_knots(pl->knots_u, p, spans_u, su);
    int nv = shape_knots(pl->knots_v, p, spans_v, sv);
    for (int j = 0; j < nv; j++)
        for (int i = 0; i < nu; i++) {
            double *c = pl->ctrl + (j * nu + i) * 4;
            c[0] = shape_greville(pl->knots_u, p, i);
            c[1] = shape_greville(pl->knots_v, p, j);
            c[2] = 0;
            c[3] = 1;
        }
    pl->surface = (sw_nurbs_surface){p, p, nu, nv, pl->knots_u, pl->knots_v, pl->ctrl};
}

#endif
