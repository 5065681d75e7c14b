/* SPDX-License-Identifier: MIT */
/* sw_trim_tess: untrimmed coverage and the error bound, a disc with a hole
 * (area, inside, border bit-identical, every seam vertex used), no
 * T-vertices and no gaps (and the checks themselves fail on a bad mesh), a
 * rational cylinder quarter, loops along knot lines and grid lines, holes
 * and crowds in one cell, sizes and determinism. Bad input:
 * test_trim_tess_errors.c; crossings and border cells: test_trim_tess_seams.c. */
#include "trim_tess_fixture.h"


static double tri_area_uv(const uint16_t *t)
{
    const float *a = &g_uv[2 * t[0]], *b = &g_uv[2 * t[1]], *c = &g_uv[2 * t[2]];
    return 0.5 * (((double)b[0] - a[0]) * ((double)c[1] - a[1]) -
                  ((double)b[1] - a[1]) * ((double)c[0] - a[0]));
}

static double total_area(const mesh *m, int *negative)
{
    double sum = 0;
    *negative = 0;
    for (uint32_t t = 0; t < m->ni; t += 3) {
        double a = tri_area_uv(&g_idx[t]);
        *negative += a < 0;
        sum += a;
    }
    return sum;
}

/* Is there a triangle on exactly these three vertices? */
static int has_triangle(const uint16_t *idx, uint32_t ni, uint32_t a, uint32_t b, uint32_t c)
{
    for (uint32_t t = 0; t < ni; t += 3) {
        int ha = 0, hb = 0, hc = 0;
        for (int k = 0; k < 3; k++)
            ha |= idx[t + k] == a, hb |= idx[t + k] == b, hc |= idx[t + k] == c;
        if (ha && hb && hc)
            return 1;
    }
    return 0;
}

/* A vertex strictly inside a triangle edge (in (u, v), within a relative
 * 1e-7 of the edge's length, the float output's precision) that is not the
 * third corner of a thin triangle on that edge: a T-vertex. Returns how many
 * there are. */
static uint32_t count_t_vertices(const float *uv, uint32_t nv, const uint16_t *idx, uint32_t ni)
{
    uint32_t bad = 0;
    for (uint32_t t = 0; t < ni; t += 3) {
        for (int e = 0; e < 3; e++) {
            uint32_t ia = idx[t + e], ib = idx[t + (e + 1) % 3];
            double au = uv[2 * ia], av = uv[2 * ia + 1], bu = uv[2 * ib], bv = uv[2 * ib + 1];
            double du = bu - au, dv = bv - av, len2 = du * du + dv * dv;
            if (len2 == 0)
                continue;
            for (uint32_t p = 0; p < nv; p++) {
                if (p == ia || p == ib)
                    continue;
                double pu = uv[2 * p] - au, pv = uv[2 * p + 1] - av;
                double s = (pu * du + pv * dv) / len2, cr = pu * dv - pv * du;
                if (s > 1e-6 && s < 1 - 1e-6 && fabs(cr) <= 1e-7 * len2 &&
                    !has_triangle(idx, ni, ia, ib, p)) {
                    if (getenv("TT_DEBUG")) /* names each T-vertex when debugging */
                        fprintf(stderr, "T: %u (%.9g %.9g) on %u (%.9g %.9g) - %u (%.9g %.9g)\n", p,
                                uv[2 * p], uv[2 * p + 1], ia, au, av, ib, bu, bv);
                    bad++;
                }
            }
        }
    }
    return bad;
}

/* Every directed edge's reverse exists unless both ends are border
 * vertices: no gap, no crack in the index topology. */
static uint32_t count_open_edges(const uint32_t *ids, const uint16_t *idx, uint32_t ni)
{
    uint32_t bad = 0;
    for (uint32_t t = 0; t < ni; t += 3) {
        for (int e = 0; e < 3; e++) {
            uint32_t a = idx[t + e], b = idx[t + (e + 1) % 3];
            if (ids[a] != SW_TRIM_INTERIOR && ids[b] != SW_TRIM_INTERIOR)
                continue;
            int found = 0;
            for (uint32_t q = 0; q < ni && !found; q += 3)
                for (int f = 0; f < 3 && !found; f++)
                    found = idx[q + f] == b && idx[q + (f + 1) % 3] == a;
            bad += !found;
        }
    }
    return bad;
}

/* A crossing: a border vertex not at its loop point's (u, v). */
static int is_crossing(const loops *l, uint32_t v)
{
    if (g_ids[v] == SW_TRIM_INTERIOR)
        return 0;
    const sw_trim_point *p = &l->pts[g_ids[v] - 1000];
    return g_uv[2 * v] != p->uv[0] || g_uv[2 * v + 1] != p->uv[1];
}

/* Distance from the triangle's interpolated point to the surface at the
 * interpolated (u, v), at random points. Triangles touching a crossing (whose
 * position is a seam vertex's, by the paper's rule) are measured apart, at the
 * (u, v) of the loop points they took their positions from: the distance to
 * a surface point, which the parametric bound does not cover (the cell's box
 * grows by up to half a seam segment). */
static void measure_error(const surface *s, const loops *l, const mesh *m, int samples,
                          double *inner, double *border)
{
    *inner = *border = 0;
    for (uint32_t t = 0; t < m->ni; t += 3) {
        const uint16_t *tri = &g_idx[t];
        int crossing = is_crossing(l, tri[0]) || is_crossing(l, tri[1]) || is_crossing(l, tri[2]);
        for (int k = 0; k < samples; k++) {
            double a = sw_test_random(), b = sw_test_random();
            if (a + b > 1)
                a = 1 - a, b = 1 - b;
            double w[3] = {1 - a - b, a, b}, u = 0, v = 0, p[3] = {0, 0, 0};
            for (int c = 0; c < 3; c++) {
                /* A crossing stands for the loop point whose position it
                 * took: the triangle is inscribed at that point's (u, v). */
                const float *uv = is_crossing(l, tri[c]) ? l->pts[g_ids[tri[c]] - 1000].uv
                                                         : &g_uv[2 * tri[c]];
                u += w[c] * uv[0], v += w[c] * uv[1];
                for (int x = 0; x < 3; x++)
                    p[x] += w[c] * g_pos[3 * tri[c] + x];
            }
            sw_vec3 q = eval_at(s, u, v, SW_EVAL_POINT).p;
            double d = sw_v3_length(sw_v3_sub(sw_v3(p[0], p[1], p[2]), q));
            if (crossing)
                *border = fmax(*border, d);
            else
                *inner = fmax(*inner, d);
        }
    }
}

/* The largest error over a dense grid of (u, v): each grid point found in its
 * triangle; returns also how many grid points inside the region no triangle
 * holds (must be 0 where the region is the whole domain). */
static double dense_error(const surface *s, const loops *l, const mesh *m, int grid,
                          uint32_t *uncovered)
{
    double worst = 0;
    *uncovered = 0;
    for (int j = 0; j <= grid; j++) {
        for (int i = 0; i <= grid; i++) {
            double u = (i + 0.37) / (grid + 1.0), v = (j + 0.61) / (grid + 1.0);
            int found = 0;
            for (uint32_t t = 0; t < m->ni && !found; t += 3) {
                const uint16_t *tri = &g_idx[t];
                double A = tri_area_uv(tri);
                if (A <= 0 || is_crossing(l, tri[0]) || is_crossing(l, tri[1]) ||
                    is_crossing(l, tri[2]))
                    continue;
                double w[3];
                for (int c = 0; c < 3; c++) {
                    const float *p = &g_uv[2 * tri[(c + 1) % 3]], *q = &g_uv[2 * tri[(c + 2) % 3]];
                    w[c] = 0.5 * (((double)q[0] - p[0]) * (v - p[1]) -
                                  ((double)q[1] - p[1]) * (u - p[0])) / A;
                }
                if (w[0] < -1e-12 || w[1] < -1e-12 || w[2] < -1e-12)
                    continue;
                found = 1;
                double p[3] = {0, 0, 0};
                for (int c = 0; c < 3; c++)
                    for (int x = 0; x < 3; x++)
                        p[x] += w[c] * g_pos[3 * tri[c] + x];
                sw_vec3 q = eval_at(s, u, v, SW_EVAL_POINT).p;
                worst = fmax(worst, sw_v3_length(sw_v3_sub(sw_v3(p[0], p[1], p[2]), q)));
            }
            *uncovered += !found;
        }
    }
    return worst;
}

/* Every loop point is an output vertex with its position bit for bit, and
 * every border vertex's position is some loop point's. */
/* on_segment: crossings carry SW_TRIM_CROSSING and their own positions
 * (crossing_on_segment), so only loop points are checked. */
static void check_border(const loops *l, const mesh *m, int on_segment)
{
    static uint8_t seen[MAXP];
    memset(seen, 0, sizeof seen);
    uint32_t wrong = 0;
    for (uint32_t v = 0; v < m->nv; v++) {
        if (g_ids[v] == SW_TRIM_INTERIOR || (on_segment && g_ids[v] == SW_TRIM_CROSSING))
            continue;
        uint32_t k = g_ids[v] - 1000;
        if (k >= l->n) {
            wrong++;
            continue;
        }
        wrong += memcmp(&g_pos[3 * v], l->pts[k].p, sizeof l->pts[k].p) != 0;
        if (!is_crossing(l, v))
            seen[k] = 1;
    }
    uint32_t missing = 0;
    for (uint32_t k = 0; k < l->n; k++)
        missing += !seen[k];
    SW_CHECK_MSG(wrong == 0, "%u border vertices not bit-identical to their loop point", wrong);
    SW_CHECK_MSG(missing == 0, "%u of %u loop points missing from the output", missing, l->n);
}

static void check_mesh_topology(const mesh *m)
{
    int negative;
    total_area(m, &negative);
    SW_CHECK_MSG(negative == 0, "%d triangles clockwise in (u, v)", negative);
    uint32_t tv = count_t_vertices(g_uv, m->nv, g_idx, m->ni);
    SW_CHECK_MSG(tv == 0, "%u T-vertices", tv);
    uint32_t open = count_open_edges(g_ids, g_idx, m->ni);
    SW_CHECK_MSG(open == 0, "%u interior edges with one triangle", open);
    uint32_t bad_index = 0;
    for (uint32_t i = 0; i < m->ni; i++)
        bad_index += g_idx[i] >= m->nv;
    SW_CHECK(bad_index == 0);
    SW_CHECK(m->ni % 3 == 0);
}

/* ---- tests --------------------------------------------------------------------- */

static void test_checks_detect_t_vertex_and_gap(void)
{
    /* Two triangles over the unit square, the second split at the middle of
     * the diagonal on one side only: a T-vertex, and a gap along it. */
    static const float uv[] = {0, 0, 1, 0, 1, 1, 0, 1, 0.5f, 0.5f};
    static const uint16_t idx[] = {0, 1, 2, 0, 4, 3, 4, 2, 3};
    static const uint32_t ids[] = {1, 1, 1, 1, SW_TRIM_INTERIOR};
    SW_CHECK(count_t_vertices(uv, 5, idx, 9) == 1);
    SW_CHECK(count_open_edges(ids, idx, 9) == 2);
    static const uint16_t fixed[] = {0, 1, 4, 1, 2, 4, 0, 4, 3, 4, 2, 3};
    SW_CHECK(count_t_vertices(uv, 5, fixed, 12) == 0);
    SW_CHECK(count_open_edges(ids, fixed, 12) == 0);
}

static void test_untrimmed_covers_domain_and_meets_bound(void)
{
    static surface s;
    static loops l;
    make_bump(&s, 2);
    begin_loops(&l);
    add_rect(&l, &s, 0, 1, 0, 1, 16);
    const double errs[] = {1e-2, 1e-3, 2e-4};
    for (int e = 0; e < 3; e++) {
        mesh m;
        SW_CHECK(run(&s, &l, errs[e], &m) == SW_OK);
        int negative;
        SW_CHECK_NEAR(total_area(&m, &negative), 1.0, 1e-6);
        check_mesh_topology(&m);
        check_border(&l, &m, 0);
        double inner, border;
        measure_error(&s, &l, &m, 8, &inner, &border);
        uint32_t uncovered;
        double dense = dense_error(&s, &l, &m, 60, &uncovered);
        printf("  error %g: %u triangles, %u cells (%u crossed), bound %.3g, sampled %.3g, "
               "dense %.3g, at crossings %.3g\n", errs[e], m.ni / 3, m.res.leaf_count,
               m.res.crossed_count, m.res.error_bound, inner, dense, border);
        SW_CHECK(m.res.capped_count == 0 && m.res.error_bound <= errs[e]);
        SW_CHECK_MSG(inner <= errs[e] * (1 + 1e-9) + 1e-6, "sampled %g > %g", inner, errs[e]);
        SW_CHECK_MSG(dense <= errs[e] * (1 + 1e-9) + 1e-6, "dense %g > %g", dense, errs[e]);
        SW_CHECK(m.res.fallback_ears == 0);
    }
}

static int in_region(const loops *l, double u, double v)
{
    int in = 0;
    for (uint32_t k = 0; k < l->count; k++)
        for (uint32_t i = l->first[k]; i < l->first[k + 1]; i++) {
            uint32_t j = i + 1 < l->first[k + 1] ? i + 1 : l->first[k];
            const float *a = l->pts[i].uv, *b = l->pts[j].uv;
            if ((a[1] > v) != (b[1] > v) && a[0] + (v - a[1]) / (b[1] - a[1]) * (b[0] - a[0]) > u)
                in ^= 1;
        }
    return in;
}

static double loop_area(const loops *l, uint32_t k)
{
    double a = 0;
    for (uint32_t i = l->first[k]; i < l->first[k + 1]; i++) {
        uint32_t j = i + 1 < l->first[k + 1] ? i + 1 : l->first[k];
        a += (double)l->pts[i].uv[0] * l->pts[j].uv[1] - (double)l->pts[j].uv[0] * l->pts[i].uv[1];
    }
    return 0.5 * a;
}

static void test_disc_with_hole(void)
{
    static surface s;
    static loops l;
    make_bump(&s, 1);
    begin_loops(&l);
    add_circle(&l, &s, 0.5, 0.5, 0.4, 96, 0);   /* outer clockwise ... */
    add_circle(&l, &s, 0.45, 0.55, 0.15, 40, 1); /* ... hole counter-clockwise: even-odd */
    double expect = fabs(loop_area(&l, 0)) - fabs(loop_area(&l, 1));
    const double errs[] = {1e-2, 1e-3};
    for (int e = 0; e < 2; e++) {
        mesh m;
        SW_CHECK(run(&s, &l, errs[e], &m) == SW_OK);
        int negative;
        double area = total_area(&m, &negative);
        SW_CHECK_NEAR(area, expect, 1e-6);
        check_mesh_topology(&m);
        check_border(&l, &m, 0);
        uint32_t outside = 0;
        for (uint32_t t = 0; t < m.ni; t += 3) {
            double cu = 0, cv = 0;
            for (int c = 0; c < 3; c++)
                cu += g_uv[2 * g_idx[t + c]] / 3.0, cv += g_uv[2 * g_idx[t + c] + 1] / 3.0;
            outside += !in_region(&l, cu, cv);
        }
        SW_CHECK_MSG(outside == 0, "%u triangles outside the trim", outside);
        double inner, border;
        measure_error(&s, &l, &m, 8, &inner, &border);
        printf("  error %g: %u triangles, %u cells (%u crossed), area %.9f of %.9f, sampled %.3g, "
               "at crossings %.3g\n", errs[e], m.ni / 3, m.res.leaf_count, m.res.crossed_count,
               area, expect, inner, border);
        SW_CHECK(inner <= errs[e] * (1 + 1e-9) + 1e-6);
        SW_CHECK(m.res.fallback_ears == 0 && m.res.skipped_loops == 0);
    }
}

static void test_cylinder_quarter(void)
{
    static surface s;
    static loops l;
    make_cylinder(&s);
    begin_loops(&l);
    add_rect(&l, &s, 0, 1, 0, 1, 96); /* the arcs' seams within 5e-5 */
    mesh m;
    const double err = 1e-4;
    SW_CHECK(run(&s, &l, err, &m) == SW_OK);
    int negative;
    SW_CHECK_NEAR(total_area(&m, &negative), 1.0, 1e-6);
    check_mesh_topology(&m);
    check_border(&l, &m, 0);
    double inner, border, worst_radius = 0, worst_normal = 0;
    measure_error(&s, &l, &m, 8, &inner, &border);
    for (uint32_t v = 0; v < m.nv; v++) {
        const float *p = &g_pos[3 * v], *n = &g_nrm[3 * v];
        double r = sqrt((double)p[0] * p[0] + (double)p[1] * p[1]);
        if (g_ids[v] == SW_TRIM_INTERIOR)
            worst_radius = fmax(worst_radius, fabs(r - 1));
        /* The normal is radial (either sense, as F_u x F_v turns it). */
        double dot = fabs((n[0] * p[0] + n[1] * p[1]) / r);
        worst_normal = fmax(worst_normal, fabs(1 - dot) + fabs(n[2]));
    }
    printf("  %u triangles, bound %.3g, sampled %.3g, at crossings %.3g, |r - 1| at vertices "
           "%.2g, normal %.2g\n", m.ni / 3, m.res.error_bound, inner, border, worst_radius,
           worst_normal);
    SW_CHECK(inner <= err * (1 + 1e-9) + 1e-6);
    /* Strips along the axis: every triangle touches the border seams; with
     * seams this fine the inscribed triangles stay within twice the bound. */
    SW_CHECK_MSG(border <= 2 * err, "%g", border);
    SW_CHECK(worst_radius < 1e-6);
    SW_CHECK(worst_normal < 1e-5);
    /* F_uv = F_vv = 0: cells the full height, so the triangles are about a
     * fan per loop point (590 here; with the general mixed bound, or with
     * a merged row taking the whole arc's M_uu, 4236). */
    uint32_t points = l.first[1] - l.first[0];
    SW_CHECK_MSG(m.ni / 3 <= 2 * points, "%u triangles for %u loop points", m.ni / 3, points);
}

/* A loop exactly along the knot line between two patches and through patch
 * corners: only the left patch is kept, watertight, area exact. */
static void test_trim_along_knot_line(void)
{
    static surface s;
    static loops l;
    make_bump(&s, 2);
    begin_loops(&l);
    add_rect(&l, &s, 0, 0.5, 0, 1, 4);
    mesh m;
    SW_CHECK(run(&s, &l, 1e-3, &m) == SW_OK);
    int negative;
    SW_CHECK_NEAR(total_area(&m, &negative), 0.5, 1e-6);
    check_mesh_topology(&m);
    check_border(&l, &m, 0);
    uint32_t right = 0;
    for (uint32_t v = 0; v < m.nv; v++)
        right += g_uv[2 * v] > 0.5f;
    SW_CHECK_MSG(right == 0, "%u vertices right of the trim", right);
}

/* As run(), with the runtime's options (core/sw_seam_surface.c). */
static sw_status run_runtime(const surface *s, const loops *l, double err, mesh *m)
{
    sw_arena a;
    sw_arena_init(&a, g_block, sizeof g_block);
    sw_trim_loops lv = view(l);
    sw_trim_tess_buffers b = {g_pos, g_nrm, g_uv, g_ids, g_idx, MAXV, MAXI, 0, NULL, 0};
    const sw_trim_tess_options opt = {.crossing_on_segment = 1, .border_fraction = 0.65};
    sw_status st = sw_trim_tess(s->patches, s->count, &lv, err, &opt, &a, &b, &m->res, NULL);
    m->nv = m->res.vertex_count, m->ni = m->res.index_count;
    SW_CHECK(a.used == 0);
    return st;
}

/* A loop along the domain's border with points within rounding of the knot
 * line at u = 0 (1.7e-30 right of it on one side, 2.5e-15 left on the
 * other, as an exporter's trims came): tiles the domain at every bound.
 * Off the line by less than the clipping's crossings can tell apart, they
 * made the walk around the cell fail ("loops cross"). */
static void test_points_within_rounding_of_a_knot_line(void)
{
    static surface s;
    static loops l;
    make_bump(&s, 2);
    for (uint32_t i = 0; i < s.count; i++)   /* knot line at u = 0 */
        s.patches[i].domain[0] -= 0.5f, s.patches[i].domain[1] -= 0.5f;
    begin_loops(&l);
    const double bottom[] = {-0.5, -0.25, -0.00229, 1.7e-30, 0.0733, 0.25};
    const double top[] = {0.5, 0.25, 0.00229, -2.48e-15, -0.25};
    for (int k = 0; k < 6; k++)
        add_point(&l, &s, bottom[k], 0);
    add_point(&l, &s, 0.5, 0);
    add_point(&l, &s, 0.5, 0.5);
    for (int k = 0; k < 5; k++)
        add_point(&l, &s, top[k], 1);
    add_point(&l, &s, -0.5, 1);
    add_point(&l, &s, -0.5, 0.5);
    end_loop(&l);
    const double bounds[] = {1e-4, 1e-3, 1e-2, 0.1, 1, 10};
    for (int b = 0; b < 6; b++) {
        mesh m;
        sw_status st = run_runtime(&s, &l, bounds[b], &m);
        SW_CHECK_MSG(st == SW_OK, "bound %g: status %d", bounds[b], (int)st);
        int negative;
        if (st == SW_OK)
            SW_CHECK_NEAR(total_area(&m, &negative), 1.0, 1e-6);
    }
}

static uint32_t triangles_outside(const loops *l, const mesh *m)
{
    uint32_t outside = 0;
    for (uint32_t t = 0; t < m->ni; t += 3) {
        double cu = 0, cv = 0;
        for (int c = 0; c < 3; c++)
            cu += g_uv[2 * g_idx[t + c]] / 3.0, cv += g_uv[2 * g_idx[t + c] + 1] / 3.0;
        outside += !in_region(l, cu, cv);
    }
    return outside;
}

/* Tessellates at error 1 (opts: the runtime's options, else the defaults)
 * and checks the mesh tiles the loops' region: its area, its topology, the
 * border on the loop points, no triangle outside. */
static void check_tiles_region(const surface *s, const loops *l, int opts, double expect,
                               mesh *m)
{
    SW_CHECK((opts ? run_runtime(s, l, 1.0, m) : run(s, l, 1.0, m)) == SW_OK);
    int negative;
    SW_CHECK_NEAR(total_area(m, &negative), expect, 1e-6);
    check_mesh_topology(m);
    check_border(l, m, opts);
    SW_CHECK(triangles_outside(l, m) == 0);
}

/* A small hole in a surface coarse enough to be one grid cell (a bolt hole
 * in a face): the cell gets a grid line through the hole, so the hole's
 * rim is clipped like any crossing and nothing is skipped. */
static void test_hole_inside_one_cell(void)
{
    static surface s;
    static loops l;
    make_bump(&s, 1);
    begin_loops(&l);
    add_rect(&l, &s, 0, 1, 0, 1, 1);
    add_circle(&l, &s, 0.3, 0.6, 0.05, 24, 1);
    double expect = fabs(loop_area(&l, 0)) - fabs(loop_area(&l, 1));
    for (int opts = 0; opts < 2; opts++) {
        mesh m;
        check_tiles_region(&s, &l, opts, expect, &m);
        SW_CHECK(m.res.skipped_loops == 0 && m.res.fallback_ears == 0);
        SW_CHECK(m.res.leaf_count >= 2 && m.res.error_bound <= 1.0);
    }
}

/* 2000 loop points in what would be one cell: the cell is clipped in parts
 * and gets grid lines until no part holds more than a few dozen points (no
 * quadratic ear clipping over the whole seam, no fan of slivers). */
static void test_many_points_in_one_cell(void)
{
    static surface s;
    static loops l;
    make_bump(&s, 1);
    begin_loops(&l);
    add_circle(&l, &s, 0.5, 0.5, 0.3, 2000, 0);
    add_circle(&l, &s, 0.55, 0.45, 0.1, 1000, 1);
    double expect = fabs(loop_area(&l, 0)) - fabs(loop_area(&l, 1));
    for (int opts = 0; opts < 2; opts++) {
        mesh m;
        check_tiles_region(&s, &l, opts, expect, &m);
        SW_CHECK(m.res.fallback_ears == 0 && m.res.skipped_loops == 0);
        SW_CHECK_MSG(m.res.leaf_count > 8, "%u cells", m.res.leaf_count);
    }
}

/* Loops exactly on grid lines: the knot lines at 0.5 and the sub-patch
 * lines at 0.25 and 0.75 of a 2 x 2 bump, with a hole whose corners are
 * grid points. The region shrink keeps every loop point off the lines, and
 * the output keeps the caller's (u, v). */
static void test_loops_on_grid_lines(void)
{
    static surface s;
    static loops l;
    make_bump(&s, 2);
    begin_loops(&l);
    add_rect(&l, &s, 0.25, 0.75, 0.25, 0.75, 8);
    add_rect(&l, &s, 0.5, 0.625, 0.5, 0.625, 2);
    for (int opts = 0; opts < 2; opts++) {
        mesh m;
        SW_CHECK((opts ? run_runtime(&s, &l, 1e-3, &m) : run(&s, &l, 1e-3, &m)) == SW_OK);
        int negative;
        SW_CHECK_NEAR(total_area(&m, &negative), 0.25 - 0.125 * 0.125, 1e-6);
        check_mesh_topology(&m);
        check_border(&l, &m, opts);
        SW_CHECK(triangles_outside(&l, &m) == 0);
        uint32_t beyond = 0;
        for (uint32_t v = 0; v < m.nv; v++)
            beyond += g_uv[2 * v] < 0.25f || g_uv[2 * v] > 0.75f || g_uv[2 * v + 1] < 0.25f ||
                      g_uv[2 * v + 1] > 0.75f;
        SW_CHECK_MSG(beyond == 0, "%u vertices beyond the loop", beyond);
        SW_CHECK(m.res.fallback_ears == 0 && m.res.capped_count == 0 &&
                 m.res.error_bound <= 1e-3);
    }
}

static void test_sizes_and_determinism(void)
{
    static surface s;
    static loops l;
    make_bump(&s, 2);
    begin_loops(&l);
    add_circle(&l, &s, 0.5, 0.5, 0.45, 64, 1);
    add_circle(&l, &s, 0.3, 0.3, 0.1, 24, 0);
    sw_arena a;
    sw_arena_init(&a, g_block, sizeof g_block);
    sw_trim_loops lv = view(&l);
    sw_trim_tess_result sizes, res;
    sw_error e = {0};
    SW_CHECK(sw_trim_tess_sizes(s.patches, s.count, &lv, 1e-3, NULL, &a, &sizes, &e) == SW_OK);
    mesh m;
    SW_CHECK(run(&s, &l, 1e-3, &m) == SW_OK);
    SW_CHECK(sizes.vertex_count == m.nv && sizes.index_count == m.ni && m.ni > 0);
    static float pos2[3 * MAXV];
    static uint16_t idx2[MAXI];
    memcpy(pos2, g_pos, sizeof(float) * 3 * m.nv);
    memcpy(idx2, g_idx, sizeof(uint16_t) * m.ni);
    SW_CHECK(run(&s, &l, 1e-3, &m) == SW_OK);
    SW_CHECK(memcmp(pos2, g_pos, sizeof(float) * 3 * m.nv) == 0);
    SW_CHECK(memcmp(idx2, g_idx, sizeof(uint16_t) * m.ni) == 0);
    /* base_vertex shifts every index. */
    sw_trim_tess_buffers b = {g_pos, g_nrm, NULL, NULL, g_idx, MAXV, MAXI, 1000, NULL, 0};
    SW_CHECK(sw_trim_tess(s.patches, s.count, &lv, 1e-3, NULL, &a, &b, &res, &e) == SW_OK);
    uint32_t shifted = 0;
    for (uint32_t i = 0; i < m.ni; i++)
        shifted += g_idx[i] == idx2[i] + 1000;
    SW_CHECK(shifted == m.ni);
    /* The scratch bound is enough. */
    size_t need = sw_trim_tess_scratch_bytes(s.count, l.n, 3, NULL);
    SW_CHECK(need <= sizeof g_block);
    sw_arena_init(&a, g_block, need);
    SW_CHECK(sw_trim_tess(s.patches, s.count, &lv, 1e-3, NULL, &a, &b, &res, &e) == SW_OK);
    printf("  scratch bound %zu bytes, peak use %zu\n", need, a.peak);
}

/* Too small buffers: SW_ERR_NO_MEMORY with the counts, nothing written past
 * the capacities (canaries), at several truncated sizes. */
static void test_small_buffers(void)
{
    static surface s;
    static loops l;
    make_bump(&s, 1);
    begin_loops(&l);
    add_circle(&l, &s, 0.5, 0.5, 0.3, 32, 1);
    mesh full;
    SW_CHECK(run(&s, &l, 1e-3, &full) == SW_OK);
    sw_arena a;
    sw_arena_init(&a, g_block, sizeof g_block);
    sw_trim_loops lv = view(&l);
    const uint32_t vcaps[] = {0, 1, full.nv - 1, full.nv, full.nv};
    const uint32_t icaps[] = {0, 3, full.ni, full.ni - 1, 0};
    for (int k = 0; k < 5; k++) {
        memset(g_pos, 0xAB, sizeof(float) * 3 * (full.nv + 4));
        memset(g_idx, 0xCD, sizeof(uint16_t) * (full.ni + 4));
        sw_trim_tess_buffers b = {g_pos, g_nrm, NULL, NULL, g_idx, vcaps[k], icaps[k], 0, NULL, 0};
        sw_trim_tess_result res;
        sw_error e = {0};
        SW_CHECK(sw_trim_tess(s.patches, s.count, &lv, 1e-3, NULL, &a, &b, &res, &e) ==
                 SW_ERR_NO_MEMORY);
        SW_CHECK(res.vertex_count == full.nv && res.index_count == full.ni);
        const unsigned char *pc = (const unsigned char *)&g_pos[3 * vcaps[k]];
        int canary = 1;
        for (size_t i = 0; i < 12; i++)
            canary &= pc[i] == 0xAB;
        for (uint32_t i = icaps[k]; i < icaps[k] + 4; i++)
            canary &= g_idx[i] == 0xCDCD;
        SW_CHECK_MSG(canary, "case %d wrote past its capacity", k);
        SW_CHECK(e.message[0] != 0);
    }
}

static void test_random_star_loops(void)
{
    static surface s;
    static loops l;
    make_bump(&s, 2);
    sw_test_rng_state = 0x1234567ull;
    uint32_t failures_before = (uint32_t)sw_test_failures;
    for (int trial = 0; trial < 24; trial++) {
        begin_loops(&l);
        int n = 8 + (int)(sw_test_random() * 60);
        double cu = 0.4 + 0.2 * sw_test_random(), cv = 0.4 + 0.2 * sw_test_random();
        for (int k = 0; k < n; k++) {
            double a = 2 * SW_PI * (k + 0.8 * sw_test_random()) / n;
            double r = 0.15 + 0.23 * sw_test_random();
            add_point(&l, &s, cu + r * cos(a), cv + r * sin(a));
        }
        end_loop(&l);
        if (trial % 2) {
            int m = 6 + (int)(sw_test_random() * 20);
            for (int k = 0; k < m; k++) {
                double a = -2 * SW_PI * (k + 0.5 * sw_test_random()) / m;
                double r = 0.04 + 0.06 * sw_test_random();
                add_point(&l, &s, cu + r * cos(a), cv + r * sin(a));
            }
            end_loop(&l);
        }
        double expect = fabs(loop_area(&l, 0)) - (l.count > 1 ? fabs(loop_area(&l, 1)) : 0);
        mesh m;
        SW_CHECK(run(&s, &l, trial % 3 ? 1e-3 : 1e-2, &m) == SW_OK);
        int negative;
        SW_CHECK_NEAR(total_area(&m, &negative), expect, 1e-6);
        check_mesh_topology(&m);
        check_border(&l, &m, 0);
        SW_CHECK(m.res.fallback_ears == 0);
        if ((uint32_t)sw_test_failures != failures_before) {
            fprintf(stderr, "  trial %d failed\n", trial);
            return;
        }
    }
}

/* Random self-crossing polygons: SW_OK or SW_ERR_FORMAT, indices in range,
 * never a crash (this test runs under AddressSanitizer too). */
int main(void)
{
    SW_RUN(test_checks_detect_t_vertex_and_gap);
    SW_RUN(test_untrimmed_covers_domain_and_meets_bound);
    SW_RUN(test_disc_with_hole);
    SW_RUN(test_cylinder_quarter);
    SW_RUN(test_trim_along_knot_line);
    SW_RUN(test_points_within_rounding_of_a_knot_line);
    SW_RUN(test_hole_inside_one_cell);
    SW_RUN(test_many_points_in_one_cell);
    SW_RUN(test_loops_on_grid_lines);
    SW_RUN(test_sizes_and_determinism);
    SW_RUN(test_small_buffers);
    SW_RUN(test_random_star_loops);
    return sw_test_finish();
}
