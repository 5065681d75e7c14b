/* SPDX-License-Identifier: MIT */
/* sw_tess: buffer sizes and index layout, vertices against the double
 * evaluator, the deviation bound, the segment count for an error, the
 * bicubic fast path against the generic paths, shared edges bit-identical. */
#include <string.h>

#include "sw_tess.h"
#include "sw_test.h"

enum { MAXN = SW_BEZIER_MAX_ORDER, MAXV = 65536 };

static sw_vertex g_verts[MAXV + 16];
static sw_vertex g_verts2[MAXV + 16];
static uint16_t g_idx[6 * 255 * 255 + 16];

/* Control points uniform in [-1, 1]^3 (+ offset), weights in [0.5, 2]. */
static sw_bezier_patchf random_patchf(float *ctrl, int n, int m, int rational)
{
    for (int k = 0; k < (n + 1) * (m + 1); k++) {
        for (int c = 0; c < 3; c++)
            ctrl[k * 4 + c] = (float)(2 * sw_test_random() - 1);
        ctrl[k * 4 + 3] = rational ? (float)(0.5 + 1.5 * sw_test_random()) : 1.0f;
    }
    sw_bezier_patchf p = {n, m, rational, ctrl};
    return p;
}

static sw_surface_point eval_f(const sw_bezier_patchf *pf, double u, double v)
{
    double d[MAXN * MAXN * 4];
    sw_bezier_patch p = sw_bezier_patch_from_float(pf, d);
    sw_surface_point q;
    sw_bezier_eval(&p, u, v, SW_EVAL_FIRST, &q);
    return q;
}

static sw_vec3 pos_of(const sw_vertex *v) { return sw_v3(v->pos[0], v->pos[1], v->pos[2]); }

static void test_sizes_exact(void)
{
    const uint32_t grids[][2] = {{1, 1}, {1, 7}, {9, 2}, {16, 16}, {255, 1}, {255, 255}};
    float ctrl[16 * 4];
    sw_bezier_patchf p = random_patchf(ctrl, 3, 3, 0);
    for (size_t g = 0; g < sizeof grids / sizeof grids[0]; g++) {
        uint32_t nu = grids[g][0], nv = grids[g][1];
        sw_tess_sizes s = sw_tess_grid_sizes(nu, nv);
        SW_CHECK(s.vertex_count == (nu + 1) * (nv + 1));
        SW_CHECK(s.index_count == 6 * nu * nv);
        /* Canaries right after the reported sizes stay untouched. */
        memset(g_verts, 0xAB, sizeof g_verts);
        memset(g_idx, 0xCD, sizeof g_idx);
        sw_tess_grid(&p, nu, nv, 0, g_verts, g_idx);
        const unsigned char *vc = (const unsigned char *)&g_verts[s.vertex_count];
        int vert_canary = 1, idx_canary = 1;
        for (size_t i = 0; i < sizeof(sw_vertex) * 4; i++)
            vert_canary &= vc[i] == 0xAB;
        for (size_t i = 0; i < 8; i++)
            idx_canary &= g_idx[s.index_count + i] == 0xCDCD;
        SW_CHECK_MSG(vert_canary && idx_canary, "grid %ux%u", nu, nv);
        SW_CHECK(g_verts[s.vertex_count - 1].normal[3] == 0);
    }
    SW_CHECK(sizeof(sw_vertex) == 16);
}

/* Every index in [base, base + vertex_count); cell (a, b) is exactly
 * (v00, v10, v11), (v00, v11, v01). */
static void test_indices_in_range_and_laid_out(void)
{
    float ctrl[16 * 4];
    sw_bezier_patchf p = random_patchf(ctrl, 3, 3, 0);
    const uint32_t cases[][3] = {{1, 1, 0}, {5, 3, 1000}, {17, 4, 60000}, {255, 255, 0}};
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        uint32_t nu = cases[c][0], nv = cases[c][1], base = cases[c][2];
        sw_tess_sizes s = sw_tess_grid_sizes(nu, nv);
        SW_CHECK(base + s.vertex_count <= 65536);
        sw_tess_grid(&p, nu, nv, base, g_verts, g_idx);
        int in_range = 1, layout = 1;
        for (uint32_t i = 0; i < s.index_count; i++)
            in_range &= g_idx[i] >= base && g_idx[i] < base + s.vertex_count;
        for (uint32_t b = 0; b < nv; b++) {
            for (uint32_t a = 0; a < nu; a++) {
                const uint16_t *t = g_idx + 6 * (b * nu + a);
                uint32_t v00 = base + b * (nu + 1) + a, v01 = v00 + nu + 1;
                layout &= t[0] == v00 && t[1] == v00 + 1 && t[2] == v01 + 1;
                layout &= t[3] == v00 && t[4] == v01 + 1 && t[5] == v01;
            }
        }
        SW_CHECK_MSG(in_range, "grid %ux%u base %u", nu, nv, base);
        SW_CHECK_MSG(layout, "grid %ux%u base %u", nu, nv, base);
    }
}

/* Positions within 2e-6 of the double evaluator (float rounding of a
 * convex combination of coordinates <= 1 in size); packed normals within
 * 0.02 per component (quantisation step 1/127). */
static void test_vertices_match_eval(void)
{
    float ctrl[MAXN * MAXN * 4];
    const int degrees[][2] = {{3, 3}, {1, 1}, {2, 5}, {7, 4}, {15, 15}, {3, 3}, {4, 6}};
    double worst_p = 0, worst_n = 0;
    for (size_t d = 0; d < sizeof degrees / sizeof degrees[0]; d++) {
        for (int rational = 0; rational <= 1; rational++) {
            sw_bezier_patchf p = random_patchf(ctrl, degrees[d][0], degrees[d][1], rational);
            uint32_t nu = 3 + (uint32_t)(d * 5), nv = 2 + (uint32_t)(d * 3);
            sw_tess_grid(&p, nu, nv, 0, g_verts, g_idx);
            for (uint32_t b = 0; b <= nv; b++) {
                for (uint32_t a = 0; a <= nu; a++) {
                    const sw_vertex *v = &g_verts[b * (nu + 1) + a];
                    sw_surface_point q = eval_f(&p, (double)a / nu, (double)b / nv);
                    worst_p = fmax(worst_p, sw_v3_length(sw_v3_sub(pos_of(v), q.p)));
                    sw_vec3 n = sw_v3(v->normal[0] / 127.0, v->normal[1] / 127.0,
                                      v->normal[2] / 127.0);
                    sw_vec3 e = sw_v3_sub(n, q.normal);
                    worst_n = fmax(worst_n, fmax(fabs(e.x), fmax(fabs(e.y), fabs(e.z))));
                }
            }
        }
    }
    SW_CHECK_MSG(worst_p <= 2e-6, "worst position error %g", worst_p);
    SW_CHECK_MSG(worst_n <= 0.02, "worst normal component error %g", worst_n);
}

/* Largest distance of the surface from each flat triangle, measured at the
 * triangle's centroid and edge midpoints (corners from the double evaluator). */
static double measured_deviation(const sw_bezier_patchf *p, uint32_t nu, uint32_t nv)
{
    static const double bary[4][3] = {
        {1.0 / 3, 1.0 / 3, 1.0 / 3}, {0.5, 0.5, 0}, {0, 0.5, 0.5}, {0.5, 0, 0.5}};
    double worst = 0;
    for (uint32_t b = 0; b < nv; b++) {
        for (uint32_t a = 0; a < nu; a++) {
            /* Corners in the grid's triangle order: (00, 10, 11) and (00, 11, 01). */
            const double tri[2][3][2] = {{{a, b}, {a + 1, b}, {a + 1, b + 1}},
                                         {{a, b}, {a + 1, b + 1}, {a, b + 1}}};
            for (int t = 0; t < 2; t++) {
                sw_vec3 c[3];
                for (int k = 0; k < 3; k++)
                    c[k] = eval_f(p, tri[t][k][0] / nu, tri[t][k][1] / nv).p;
                for (int s = 0; s < 4; s++) {
                    double u = 0, v = 0;
                    sw_vec3 lin = sw_v3(0, 0, 0);
                    for (int k = 0; k < 3; k++) {
                        u += bary[s][k] * tri[t][k][0] / nu;
                        v += bary[s][k] * tri[t][k][1] / nv;
                        lin = sw_v3_add(lin, sw_v3_scale(c[k], bary[s][k]));
                    }
                    worst = fmax(worst, sw_v3_length(sw_v3_sub(eval_f(p, u, v).p, lin)));
                }
            }
        }
    }
    return worst;
}

static void test_deviation_within_grid_bound(void)
{
    float ctrl[MAXN * MAXN * 4];
    const int degrees[][2] = {{3, 3}, {3, 3}, {5, 2}, {4, 7}, {9, 9}, {1, 6}};
    for (size_t d = 0; d < sizeof degrees / sizeof degrees[0]; d++) {
        for (int rational = 0; rational <= 1; rational++) {
            sw_bezier_patchf pf = random_patchf(ctrl, degrees[d][0], degrees[d][1], rational);
            double dctrl[MAXN * MAXN * 4];
            sw_bezier_patch p = sw_bezier_patch_from_float(&pf, dctrl);
            sw_deriv_bounds bd;
            SW_CHECK(sw_bezier_second_deriv_bounds(&p, &bd, NULL) == SW_OK);
            const uint32_t grids[][2] = {{1, 1}, {4, 3}, {10, 12}};
            for (int g = 0; g < 3; g++) {
                uint32_t nu = grids[g][0], nv = grids[g][1];
                double dev = measured_deviation(&pf, nu, nv);
                double bound = sw_tess_grid_error_bound(&bd, nu, nv);
                SW_CHECK_MSG(dev <= bound, "degree %dx%d rational %d grid %ux%u: %g > %g",
                             degrees[d][0], degrees[d][1], rational, nu, nv, dev, bound);
            }
        }
    }
}

static void test_grid_error_bound_formula(void)
{
    sw_deriv_bounds b = {8, 4, 16};
    /* (1/4 * 8 + 2 * 1/2 * 1/4 * 4 + 1/16 * 16) / 8 = (2 + 1 + 1) / 8 */
    SW_CHECK_NEAR(sw_tess_grid_error_bound(&b, 2, 4), 0.5, 1e-15);
}

static void check_segments(const sw_deriv_bounds *b, double err)
{
    uint32_t nu = 0, nv = 0;
    int ok = sw_tess_segments_for_error(b, err, &nu, &nv);
    SW_CHECK(nu >= 1 && nu <= SW_TESS_MAX_SEGMENTS && nv >= 1 && nv <= SW_TESS_MAX_SEGMENTS);
    /* Brute force over every grid: the smallest product that meets err. */
    uint64_t best = 0;
    for (uint32_t u = 1; u <= SW_TESS_MAX_SEGMENTS; u++)
        for (uint32_t v = 1; v <= SW_TESS_MAX_SEGMENTS; v++)
            if (sw_tess_grid_error_bound(b, u, v) <= err && (!best || (uint64_t)u * v < best))
                best = (uint64_t)u * v;
    if (!best) {
        SW_CHECK_MSG(ok == 0, "bounds %g %g %g err %g: no grid meets it", b->uu, b->uv, b->vv,
                     err);
        return;
    }
    SW_CHECK(ok == 1);
    SW_CHECK(sw_tess_grid_error_bound(b, nu, nv) <= err);
    SW_CHECK(nu == 1 || sw_tess_grid_error_bound(b, nu - 1, nv) > err);
    SW_CHECK(nv == 1 || sw_tess_grid_error_bound(b, nu, nv - 1) > err);
    SW_CHECK_MSG((uint64_t)nu * nv == best, "bounds %g %g %g err %g: %ux%u, best product %llu",
                 b->uu, b->uv, b->vv, err, nu, nv, (unsigned long long)best);
}

static void test_segments_for_error_meets_and_is_minimal(void)
{
    for (int trial = 0; trial < 150; trial++) {
        double scale = pow(10, 4 * sw_test_random() - 1);
        sw_deriv_bounds b = {scale * sw_test_random(), scale * sw_test_random(),
                             scale * sw_test_random()};
        if (trial % 5 == 1)
            b.uv = 0;
        if (trial % 7 == 2)
            b.vv = 0;
        check_segments(&b, pow(10, -3 * sw_test_random()));
    }
}

static void test_segments_for_error_edge_cases(void)
{
    uint32_t nu = 0, nv = 0;
    sw_deriv_bounds zero = {0, 0, 0};
    SW_CHECK(sw_tess_segments_for_error(&zero, 1e-3, &nu, &nv) == 1);
    SW_CHECK(nu == 1 && nv == 1);
    sw_deriv_bounds only_u = {100, 0, 0};
    SW_CHECK(sw_tess_segments_for_error(&only_u, 1e-2, &nu, &nv) == 1);
    SW_CHECK(nu == 36 && nv == 1); /* 100 / (8 nu^2) <= 0.01 first at nu = 36 */
    sw_deriv_bounds huge = {1e9, 1e9, 1e9};
    SW_CHECK(sw_tess_segments_for_error(&huge, 1e-3, &nu, &nv) == 0);
    SW_CHECK(nu == SW_TESS_MAX_SEGMENTS && nv == SW_TESS_MAX_SEGMENTS);
    sw_deriv_bounds some = {1, 2, 3};
    SW_CHECK(sw_tess_segments_for_error(&some, 0, &nu, &nv) == 0);
    SW_CHECK(sw_tess_segments_for_error(&some, -1, &nu, &nv) == 0);
    SW_CHECK(sw_tess_segments_for_error(&some, NAN, &nu, &nv) == 0);
    SW_CHECK(nu == SW_TESS_MAX_SEGMENTS && nv == SW_TESS_MAX_SEGMENTS);
}

/* Degree elevation in u (n -> n + 1) of a polynomial patch: same surface. */
static sw_bezier_patchf elevate_u(const sw_bezier_patchf *p, float *out)
{
    int n = p->degree_u, m = p->degree_v;
    for (int j = 0; j <= m; j++) {
        for (int i = 0; i <= n + 1; i++) {
            double a = (double)i / (n + 1);
            for (int k = 0; k < 4; k++) {
                double lo = i > 0 ? p->ctrl[(j * (n + 1) + i - 1) * 4 + k] : 0;
                double hi = i <= n ? p->ctrl[(j * (n + 1) + i) * 4 + k] : 0;
                out[(j * (n + 2) + i) * 4 + k] = (float)(a * lo + (1 - a) * hi);
            }
        }
    }
    sw_bezier_patchf e = {n + 1, m, 0, out};
    return e;
}

/* The unrolled bicubic path against the generic polynomial path (the same
 * patch elevated to degree 4x3) and the rational path (all weights 1). */
static void test_bicubic_fast_path_matches_generic(void)
{
    float ctrl[16 * 4], elev[20 * 4];
    double worst_poly = 0, worst_rat = 0;
    for (int trial = 0; trial < 10; trial++) {
        sw_bezier_patchf p = random_patchf(ctrl, 3, 3, 0);
        sw_bezier_patchf e = elevate_u(&p, elev);
        sw_bezier_patchf r = p;
        r.rational = 1;
        sw_tess_grid(&p, 20, 13, 0, g_verts, g_idx);
        for (int pass = 0; pass < 2; pass++) {
            sw_tess_grid(pass ? &r : &e, 20, 13, 0, g_verts2, g_idx);
            for (uint32_t i = 0; i < 21 * 14; i++) {
                double d = sw_v3_length(sw_v3_sub(pos_of(&g_verts[i]), pos_of(&g_verts2[i])));
                double nd = 0;
                for (int k = 0; k < 3; k++)
                    nd = fmax(nd, abs(g_verts[i].normal[k] - g_verts2[i].normal[k]));
                SW_CHECK(nd <= 1);
                if (pass)
                    worst_rat = fmax(worst_rat, d);
                else
                    worst_poly = fmax(worst_poly, d);
            }
        }
    }
    /* Control hull of size ~3.5: 1e-6 relative. */
    SW_CHECK_MSG(worst_poly <= 3.5e-6, "fast vs generic polynomial %g", worst_poly);
    SW_CHECK_MSG(worst_rat <= 3.5e-6, "fast vs rational %g", worst_rat);
}

/* B's control row 0 (or column 0) is A's last row (column), listed in the same
 * direction: with the same segment count along it the boundary vertices of
 * both grids are the same bits. */
static void test_shared_edges_bit_identical(void)
{
    float a_ctrl[MAXN * MAXN * 4], b_ctrl[MAXN * MAXN * 4];
    const int degrees[][2] = {{3, 3}, {5, 4}, {3, 3}, {2, 7}};
    for (size_t d = 0; d < sizeof degrees / sizeof degrees[0]; d++) {
        int n = degrees[d][0], m = degrees[d][1], rational = d == 2 || d == 3;
        sw_bezier_patchf a = random_patchf(a_ctrl, n, m, rational);
        sw_bezier_patchf b = random_patchf(b_ctrl, n, m, rational);
        uint32_t nu = 37, nv_a = 11, nv_b = 5;
        /* Along u: A's row m is B's row 0. */
        memcpy(b_ctrl, a_ctrl + m * (n + 1) * 4, sizeof(float) * 4 * (n + 1));
        sw_tess_grid(&a, nu, nv_a, 0, g_verts, g_idx);
        sw_tess_grid(&b, nu, nv_b, 0, g_verts2, g_idx);
        int same = 1;
        for (uint32_t i = 0; i <= nu; i++)
            same &= memcmp(g_verts[nv_a * (nu + 1) + i].pos, g_verts2[i].pos, 12) == 0;
        SW_CHECK_MSG(same, "row edge, degree %dx%d rational %d", n, m, rational);
        /* Along v: A's column n is B's column 0. */
        for (int j = 0; j <= m; j++)
            memcpy(b_ctrl + j * (n + 1) * 4, a_ctrl + (j * (n + 1) + n) * 4, sizeof(float) * 4);
        uint32_t nu_a = 9, nu_b = 4, nv = 23;
        sw_tess_grid(&a, nu_a, nv, 0, g_verts, g_idx);
        sw_tess_grid(&b, nu_b, nv, 0, g_verts2, g_idx);
        same = 1;
        for (uint32_t j = 0; j <= nv; j++)
            same &= memcmp(g_verts[j * (nu_a + 1) + nu_a].pos, g_verts2[j * (nu_b + 1)].pos,
                           12) == 0;
        SW_CHECK_MSG(same, "column edge, degree %dx%d rational %d", n, m, rational);
    }
}

/* The same, with B's row listed backwards (as adjacent CAD faces often are):
 * the symmetric Bernstein values and sums make this bit-identical too. */
static void test_reversed_shared_edge_bit_identical(void)
{
    float a_ctrl[16 * 4], b_ctrl[16 * 4];
    for (int rational = 0; rational <= 1; rational++) {
        sw_bezier_patchf a = random_patchf(a_ctrl, 3, 3, rational);
        sw_bezier_patchf b = random_patchf(b_ctrl, 3, 3, rational);
        for (int i = 0; i <= 3; i++)
            memcpy(b_ctrl + i * 4, a_ctrl + (3 * 4 + 3 - i) * 4, sizeof(float) * 4);
        uint32_t nu = 29;
        sw_tess_grid(&a, nu, 6, 0, g_verts, g_idx);
        sw_tess_grid(&b, nu, 8, 0, g_verts2, g_idx);
        int same = 1;
        for (uint32_t i = 0; i <= nu; i++)
            same &= memcmp(g_verts[6 * (nu + 1) + i].pos, g_verts2[nu - i].pos, 12) == 0;
        SW_CHECK_MSG(same, "rational %d", rational);
    }
}

/* Teapot-lid pole: row v = 0 is one point. The packed normals there are
 * nonzero and close to the evaluator's limit normal. */
static void test_normals_at_collapsed_edge(void)
{
    float ctrl[16 * 4];
    for (int rational = 0; rational <= 1; rational++) {
        for (int j = 0; j < 4; j++) {
            for (int i = 0; i < 4; i++) {
                double ang = i * 0.5, r = j / 3.0;
                float *c = ctrl + (j * 4 + i) * 4;
                c[0] = (float)(5 + r * cos(ang)), c[1] = (float)(r * sin(ang));
                c[2] = (float)(1 - r * r), c[3] = rational ? 1 + 0.3f * i + 0.2f * j : 1;
            }
        }
        sw_bezier_patchf p = {3, 3, rational, ctrl};
        uint32_t nu = 8;
        sw_tess_grid(&p, nu, 8, 0, g_verts, g_idx);
        for (uint32_t a = 0; a <= nu; a++) {
            const int8_t *n8 = g_verts[a].normal;
            sw_vec3 n = sw_v3(n8[0] / 127.0, n8[1] / 127.0, n8[2] / 127.0);
            sw_surface_point q = eval_f(&p, (double)a / nu, 0);
            SW_CHECK_MSG(sw_v3_dot(n, q.normal) > 0.99, "rational %d a %u: dot %g", rational, a,
                         sw_v3_dot(n, q.normal));
        }
    }
}

int main(void)
{
    SW_RUN(test_sizes_exact);
    SW_RUN(test_indices_in_range_and_laid_out);
    SW_RUN(test_vertices_match_eval);
    SW_RUN(test_deviation_within_grid_bound);
    SW_RUN(test_grid_error_bound_formula);
    SW_RUN(test_segments_for_error_meets_and_is_minimal);
    SW_RUN(test_segments_for_error_edge_cases);
    SW_RUN(test_bicubic_fast_path_matches_generic);
    SW_RUN(test_shared_edges_bit_identical);
    SW_RUN(test_reversed_shared_edge_bit_identical);
    SW_RUN(test_normals_at_collapsed_edge);
    return sw_test_finish();
}
