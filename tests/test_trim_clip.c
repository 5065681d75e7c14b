/* SPDX-License-Identifier: MIT */
/* sw_trim_clip: trimming loops cut along a parameter line, and
 * sw_model_cut_surface / sw_model_split on a model built here. Areas and
 * points are measured by sampling the curves (not by the cut's own
 * bookkeeping): the two sides' areas add up to the whole, every point of a
 * side lies on its side, and the pieces trace the original curves. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_math.h"
#include "sw_model.h"
#include "sw_model_split.h"
#include "sw_nurbs.h"
#include "sw_test.h"
#include "sw_trim_clip.h"

enum { SAMPLES = 400 };

static void curve_uv(const sw_model_trim_curve *c, double t, double uv[2])
{
    sw_nurbs_curve view = sw_model_curve_view(c);
    sw_vec3 p = sw_nurbs_curve_point(&view, t);
    uv[0] = p.x, uv[1] = p.y;
}

/* The area the set's loops bound (outer positive, holes negative, as
 * oriented by their flag), and the extremes of coordinate axis. */
static double set_area(const sw_trim_set *s, int axis, double *lo, double *hi)
{
    double total = 0;
    *lo = INFINITY, *hi = -INFINITY;
    for (size_t l = 0; l < s->loop_count; l++) {
        double area = 0, prev[2] = {0, 0}, first[2] = {0, 0};
        int started = 0;
        for (size_t i = 0; i < s->loops[l].curve_count; i++) {
            const sw_model_trim_curve *c = &s->curves[s->loops[l].first_curve + i];
            double t0 = c->knots[c->degree], t1 = c->knots[c->count];
            for (int k = 0; k < SAMPLES; k++) {
                double uv[2];
                curve_uv(c, t0 + (t1 - t0) * k / SAMPLES, uv);
                *lo = fmin(*lo, uv[axis]), *hi = fmax(*hi, uv[axis]);
                if (started)
                    area += prev[0] * uv[1] - uv[0] * prev[1];
                else
                    memcpy(first, uv, sizeof first), started = 1;
                memcpy(prev, uv, sizeof prev);
            }
        }
        area = 0.5 * (area + prev[0] * first[1] - first[0] * prev[1]);
        total += s->loops[l].outer ? fabs(area) : -fabs(area);
    }
    return total;
}

/* Each loop's curves head to tail (end of one = start of the next). */
static int loops_closed(const sw_trim_set *s)
{
    for (size_t l = 0; l < s->loop_count; l++)
        for (size_t i = 0; i < s->loops[l].curve_count; i++) {
            const sw_model_trim_curve *a = &s->curves[s->loops[l].first_curve + i];
            const sw_model_trim_curve *b =
                &s->curves[s->loops[l].first_curve + (i + 1) % s->loops[l].curve_count];
            double p[2], q[2];
            curve_uv(a, a->knots[a->count], p);
            curve_uv(b, b->knots[b->degree], q);
            if (hypot(p[0] - q[0], p[1] - q[1]) > 1e-9)
                return 0;
        }
    return 1;
}

static void add_line(sw_trim_set *s, double x0, double y0, double x1, double y1)
{
    static const double knots[4] = {0, 0, 1, 1};
    sw_model_trim_curve c = {1, 2, malloc(sizeof knots), malloc(8 * sizeof(double)), 0, 0.0, 0};
    memcpy(c.knots, knots, sizeof knots);
    const double ctrl[8] = {x0, y0, 0, 1, x1, y1, 0, 1};
    memcpy(c.ctrl, ctrl, sizeof ctrl);
    s->curves = realloc(s->curves, (s->curve_count + 1) * sizeof *s->curves);
    s->curves[s->curve_count++] = c;
}

/* A full circle as one rational quadratic (nine points), clockwise when
 * cw. */
static void add_circle(sw_trim_set *s, double cx, double cy, double r, int cw)
{
    static const double knots[12] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    const double h = sqrt(0.5);
    const double pts[9][3] = {{1, 0, 1}, {1, 1, h}, {0, 1, 1}, {-1, 1, h}, {-1, 0, 1},
                              {-1, -1, h}, {0, -1, 1}, {1, -1, h}, {1, 0, 1}};
    sw_model_trim_curve c = {2, 9, malloc(sizeof knots), malloc(36 * sizeof(double)), 0, 0.0, 0};
    memcpy(c.knots, knots, sizeof knots);
    for (int i = 0; i < 9; i++) {
        double y = cw ? -pts[i][1] : pts[i][1];
        c.ctrl[4 * i] = cx + r * pts[i][0], c.ctrl[4 * i + 1] = cy + r * y;
        c.ctrl[4 * i + 2] = 0, c.ctrl[4 * i + 3] = pts[i][2];
    }
    s->curves = realloc(s->curves, (s->curve_count + 1) * sizeof *s->curves);
    s->curves[s->curve_count++] = c;
}

static void add_loop(sw_trim_set *s, size_t first, int outer)
{
    s->loops = realloc(s->loops, (s->loop_count + 1) * sizeof *s->loops);
    s->loops[s->loop_count++] = (sw_model_loop){first, s->curve_count - first, outer};
}

/* A 10 x 4 rectangle, clockwise when cw, with a hole of radius 1 at (cx,
 * 2) when cx > 0. */
static sw_trim_set plate(int cw, double cx)
{
    sw_trim_set s = {0};
    if (cw) {
        add_line(&s, 0, 0, 0, 4), add_line(&s, 0, 4, 10, 4);
        add_line(&s, 10, 4, 10, 0), add_line(&s, 10, 0, 0, 0);
    } else {
        add_line(&s, 0, 0, 10, 0), add_line(&s, 10, 0, 10, 4);
        add_line(&s, 10, 4, 0, 4), add_line(&s, 0, 4, 0, 0);
    }
    add_loop(&s, 0, 1);
    if (cx > 0) {
        size_t first = s.curve_count;
        add_circle(&s, cx, 2, 1, 0);   /* counter-clockwise, as a hole should not be */
        add_loop(&s, first, 0);
    }
    return s;
}

/* Cuts in at (axis) and checks the sides: closed, each within its side,
 * areas summing to the whole's and each near the expected. */
static void check_cut(const sw_trim_set *in, int axis, double at, double low_area,
                      double high_area, size_t low_loops, size_t high_loops)
{
    sw_trim_set low = {0}, high = {0};
    sw_error err = {0};
    SW_CHECK_MSG(sw_trim_clip(in, axis, at, 1e-9, &low, &high, &err) == SW_OK, "%s", err.message);
    double lo, hi, whole = set_area(in, axis, &lo, &hi);
    double a_low = set_area(&low, axis, &lo, &hi);
    SW_CHECK_MSG(hi <= at + 1e-9, "low side reaches %g past the cut at %g", hi, at);
    double a_high = set_area(&high, axis, &lo, &hi);
    SW_CHECK_MSG(lo >= at - 1e-9, "high side reaches %g below the cut at %g", lo, at);
    SW_CHECK_MSG(fabs(a_low + a_high - whole) < 1e-3, "areas %g + %g, whole %g", a_low, a_high,
                 whole);
    SW_CHECK_MSG(fabs(a_low - low_area) < 1e-3 && fabs(a_high - high_area) < 1e-3,
                 "areas %g and %g, expected %g and %g", a_low, a_high, low_area, high_area);
    SW_CHECK_MSG(low.loop_count == low_loops && high.loop_count == high_loops,
                 "%zu and %zu loops, expected %zu and %zu", low.loop_count, high.loop_count,
                 low_loops, high_loops);
    SW_CHECK(loops_closed(&low) && loops_closed(&high));
    sw_trim_set_free(&low);
    sw_trim_set_free(&high);
}

static void test_a_rectangle_either_way_round(void)
{
    for (int cw = 0; cw < 2; cw++) {
        sw_trim_set s = plate(cw, 0);
        check_cut(&s, 0, 3.0, 12.0, 28.0, 1, 1);
        check_cut(&s, 1, 1.0, 10.0, 30.0, 1, 1);
        sw_trim_set_free(&s);
    }
}

/* A hole of radius 1 at (5, 2), cut at v = 2.5: each side one loop, the
 * outer one's arc, the cut, the hole's arc, the cut; their areas the
 * plate's halves less the hole's (a cap of pi/3 - sqrt(3)/4 above). The
 * hole is written counter-clockwise, as an outer loop: the cut orients it.
 * Cut at u = 3 the hole goes whole to the high side. */
static void test_a_hole_on_the_cut_joins_the_outer_loop(void)
{
    sw_trim_set s = plate(0, 5.0);
    double cap = SW_PI / 3 - sqrt(3.0) / 4;
    check_cut(&s, 1, 2.5, 25.0 - (SW_PI - cap), 15.0 - cap, 1, 1);
    check_cut(&s, 0, 3.0, 12.0, 28.0 - SW_PI, 1, 2);
    sw_trim_set_free(&s);
}

/* A line along a curve, through a curve's end or touching the hole's top
 * without crossing is refused (SW_ERR_RANGE), as is an axis that is
 * neither u nor v (SW_ERR_ARG). */
static void test_lines_that_graze_are_refused(void)
{
    sw_trim_set s = plate(0, 5.0);
    const double lines[][2] = {{0, 10.0}, {1, 4.0}, {1, 3.0}, {1, 1.0}, {1, 0.0}};
    for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++) {
        sw_trim_set low = {0}, high = {0};
        sw_error err = {0};
        sw_status st = sw_trim_clip(&s, (int)lines[i][0], lines[i][1], 1e-9, &low, &high, &err);
        SW_CHECK_MSG(st == SW_ERR_RANGE, "axis %g at %g: status %d", lines[i][0], lines[i][1],
                     (int)st);
        SW_CHECK(strstr(err.message, "trim cut:") != NULL);
        sw_trim_set_free(&low);
        sw_trim_set_free(&high);
    }
    sw_trim_set low = {0}, high = {0};
    sw_error err = {0};
    SW_CHECK(sw_trim_clip(&s, 2, 1.0, 1e-9, &low, &high, &err) == SW_ERR_ARG);
    sw_trim_set_free(&s);
}

/* The pieces trace the curve they were cut from: a rational circle split
 * by a cut through it, each piece's points on the circle. */
static void test_pieces_lie_on_the_original_curve(void)
{
    sw_trim_set s = {0};
    add_circle(&s, 0, 0, 2, 0);
    add_loop(&s, 0, 1);
    sw_trim_set low = {0}, high = {0};
    sw_error err = {0};
    SW_CHECK_MSG(sw_trim_clip(&s, 0, 0.7, 1e-9, &low, &high, &err) == SW_OK, "%s", err.message);
    double worst = 0;
    for (int side = 0; side < 2; side++) {
        const sw_trim_set *t = side ? &high : &low;
        for (size_t i = 0; i < t->curve_count; i++) {
            const sw_model_trim_curve *c = &t->curves[i];
            if (c->degree == 1)
                continue;   /* the cut */
            for (int k = 0; k <= 50; k++) {
                double uv[2];
                curve_uv(c, c->knots[c->degree] + (c->knots[c->count] - c->knots[c->degree]) *
                         k / 50, uv);
                worst = fmax(worst, fabs(hypot(uv[0], uv[1]) - 2.0));
            }
        }
    }
    SW_CHECK_MSG(worst < 1e-12, "a piece strays %g from the circle", worst);
    double lo, hi;
    SW_CHECK(fabs(set_area(&low, 0, &lo, &hi) + set_area(&high, 0, &lo, &hi) - 4 * SW_PI) < 1e-3);
    sw_trim_set_free(&low);
    sw_trim_set_free(&high);
    sw_trim_set_free(&s);
}

/* A model of one trimmed plane (the plate with its hole) cut into three
 * along u: three surfaces in the same part, their patches inside their
 * pieces (the model keeps a margin of 1e-5 of the domain around a face's
 * trims), the part's surface count three. */
static void test_a_model_split_into_pieces(void)
{
    sw_model m, out;
    sw_model_init(&m);
    sw_model_init(&out);
    sw_error err = {0};
    const double knots[4] = {0, 0, 10, 10}, knots_v[4] = {0, 0, 4, 4};
    double ctrl[16];
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 2; i++) {
            double *c = ctrl + 4 * (j * 2 + i);
            c[0] = 10.0 * i, c[1] = 4.0 * j, c[2] = 0, c[3] = 1;
        }
    const sw_nurbs_surface plane = {1, 1, 2, 2, knots, knots_v, ctrl};
    sw_trim_set p = plate(0, 5.0);
    sw_nurbs_curve views[8];
    for (size_t i = 0; i < p.curve_count; i++)
        views[i] = sw_model_curve_view(&p.curves[i]);
    const sw_model_loop_input loops[2] = {{views, NULL, 4, 1, NULL, NULL},
                                          {views + 4, NULL, 1, 0, NULL, NULL}};
    SW_CHECK(sw_model_begin_part(&m, "plate", NULL, &err) == SW_OK);
    SW_CHECK_MSG(sw_model_add_surface(&m, &plane, 0, loops, 2, &err) == SW_OK, "%s", err.message);
    sw_trim_set pieces[3] = {{0}};
    const double at[2] = {3.0, 7.0};
    SW_CHECK_MSG(sw_model_cut_surface(&m, 0, 0, at, 2, pieces, &err) == SW_OK, "%s", err.message);
    const sw_model_cut cut = {0, pieces, 3};
    SW_CHECK_MSG(sw_model_split(&m, &cut, 1, &out, &err) == SW_OK, "%s", err.message);
    SW_CHECK(out.surface_count == 3 && out.part_count == 1 && out.parts[0].surface_count == 3);
    for (size_t s = 0; s < out.surface_count; s++) {
        const sw_model_surface *f = &out.surfaces[s];
        double lo = s == 0 ? 0 : at[s - 1], hi = s == 2 ? 10 : at[s];
        for (size_t k = 0; k < f->patch_count; k++) {
            const double *d = out.patches[f->first_patch + k].domain;
            SW_CHECK_MSG(d[0] >= lo - 1e-3 && d[1] <= hi + 1e-3, "surface %zu: a patch on "
                         "u %g..%g, outside its piece %g..%g", s, d[0], d[1], lo, hi);
        }
    }
    for (int i = 0; i < 3; i++)
        sw_trim_set_free(&pieces[i]);
    sw_trim_set_free(&p);
    sw_model_free(&m);
    sw_model_free(&out);
}

int main(void)
{
    SW_RUN(test_a_rectangle_either_way_round);
    SW_RUN(test_a_hole_on_the_cut_joins_the_outer_loop);
    SW_RUN(test_lines_that_graze_are_refused);
    SW_RUN(test_pieces_lie_on_the_original_curve);
    SW_RUN(test_a_model_split_into_pieces);
    return sw_test_finish();
}
