/* SPDX-License-Identifier: MIT */
/* sw_trim_tess where loops are seams (the Seam Graph walk's options):
 * crossings on their seam segment, and the cells a loop crosses taking
 * their share of the error. */
#include "trim_tess_fixture.h"

/* crossing_on_segment: the same cells, triangles and interior vertices as
 * the paper's rule; each crossing lies on the 3D chord of the loop segment
 * it crosses (where that chord comes nearest the surface), and the
 * triangles at crossings deviate less from the surface than with the
 * borrowed position (a coarse seam: 12 points around a disc on the bump). */
static float s_pos[3 * MAXV];
static uint16_t s_idx[MAXI];
static uint32_t s_ids[MAXV];

static double worst_at(const surface *s, const mesh *m, const float *pos, const uint32_t *ids,
                       uint32_t marker_lo, uint32_t marker_hi)
{
    double worst = 0;
    for (uint32_t t = 0; t + 2 < m->ni; t += 3) {
        const uint16_t *tri = g_idx + t;
        int at = 0;
        for (int k = 0; k < 3; k++)
            at |= ids[tri[k]] >= marker_lo && ids[tri[k]] <= marker_hi;
        if (!at)
            continue;
        double uv[2] = {0, 0}, flat[3] = {0, 0, 0};
        for (int k = 0; k < 3; k++)
            for (int c = 0; c < 3; c++) {
                flat[c] += pos[3 * tri[k] + c] / 3.0;
                if (c < 2)
                    uv[c] += g_uv[2 * tri[k] + c] / 3.0;
            }
        sw_surface_point q = eval_at(s, uv[0], uv[1], SW_EVAL_POINT);
        worst = fmax(worst, sw_v3_length(sw_v3_sub(q.p, sw_v3(flat[0], flat[1], flat[2]))));
    }
    return worst;
}

/* Distance from p to the segment a-b, and the segment parameter of the
 * nearest point (unclamped) in *t. */
static double chord_dist(const float *a, const float *b, const double p[3], double *t)
{
    double ab[3], ap[3], len2 = 0, d2 = 0;
    *t = 0;
    for (int c = 0; c < 3; c++) {
        ab[c] = (double)b[c] - a[c], ap[c] = p[c] - a[c];
        *t += ab[c] * ap[c], len2 += ab[c] * ab[c];
    }
    *t = len2 > 0 ? *t / len2 : 0;
    double tc = fmin(fmax(*t, 0.0), 1.0);
    for (int c = 0; c < 3; c++)
        d2 += (ap[c] - tc * ab[c]) * (ap[c] - tc * ab[c]);
    return sqrt(d2);
}

/* The loop segment p lies on, or -1. */
static int on_some_chord(const loops *l, const float p[3])
{
    const double q[3] = {p[0], p[1], p[2]};
    for (uint32_t k = 0; k < l->n; k++) {
        double t;
        double d = chord_dist(l->pts[k].p, l->pts[(k + 1) % l->n].p, q, &t);
        if (t >= -1e-6 && t <= 1 + 1e-6 && d <= 1e-6)
            return (int)k;
    }
    return -1;
}

/* Is crossing v where its chord comes nearest the surface at its (u, v)
 * (not slid along the chord)? */
static int nearest_on_chord(const surface *s, const loops *l, uint32_t v)
{
    int k = on_some_chord(l, g_pos + 3 * v);
    if (k < 0)
        return 0;
    sw_surface_point q = eval_at(s, g_uv[2 * v], g_uv[2 * v + 1], SW_EVAL_POINT);
    const double qp[3] = {q.p.x, q.p.y, q.p.z};
    double t, best = chord_dist(l->pts[k].p, l->pts[(k + 1) % l->n].p, qp, &t);
    const float *at = g_pos + 3 * v;
    double here = sw_v3_length(sw_v3_sub(q.p, sw_v3(at[0], at[1], at[2])));
    return here <= best + 1e-6;
}

static void test_crossings_on_their_segment(void)
{
    surface s;
    make_bump(&s, 2);
    loops l;
    begin_loops(&l);
    add_circle(&l, &s, 0.5, 0.5, 0.4, 12, 1);
    mesh snap, seg;
    SW_CHECK(run(&s, &l, 2e-3, &snap) == SW_OK);
    memcpy(s_pos, g_pos, sizeof(float) * 3 * snap.nv);
    memcpy(s_idx, g_idx, sizeof(uint16_t) * snap.ni);
    memcpy(s_ids, g_ids, sizeof(uint32_t) * snap.nv);
    double snapped = worst_at(&s, &snap, s_pos, s_ids, 1000, 1000 + l.n);
    sw_arena a;
    sw_arena_init(&a, g_block, sizeof g_block);
    sw_trim_loops lv = view(&l);
    sw_trim_tess_buffers b = {g_pos, g_nrm, g_uv, g_ids, g_idx, MAXV, MAXI, 0, NULL, 0};
    const sw_trim_tess_options opt = {.crossing_on_segment = 1};
    sw_error e = {0};
    SW_CHECK(sw_trim_tess(s.patches, s.count, &lv, 2e-3, &opt, &a, &b, &seg.res, &e) == SW_OK);
    seg.nv = seg.res.vertex_count, seg.ni = seg.res.index_count;
    SW_CHECK(seg.nv == snap.nv && seg.ni == snap.ni);
    SW_CHECK(memcmp(g_idx, s_idx, sizeof(uint16_t) * seg.ni) == 0);
    uint32_t crossings = 0, off_chord = 0, moved = 0, slid = 0;
    for (uint32_t v = 0; v < seg.nv; v++) {
        if (g_ids[v] == SW_TRIM_CROSSING) {
            crossings++;
            off_chord += on_some_chord(&l, g_pos + 3 * v) < 0;
            slid += off_chord == 0 && !nearest_on_chord(&s, &l, v);
        } else {
            moved += g_ids[v] != s_ids[v] || memcmp(g_pos + 3 * v, s_pos + 3 * v, 12) != 0;
        }
    }
    double placed = worst_at(&s, &seg, g_pos, g_ids, SW_TRIM_CROSSING, SW_TRIM_CROSSING);
    printf("  %u crossings; worst error of a triangle at a crossing: %.3g borrowed, %.3g on "
           "the segment (bound 2e-3)\n", crossings, snapped, placed);
    SW_CHECK(crossings > 0 && off_chord == 0 && moved == 0);
    SW_CHECK_MSG(slid == 0, "%u of %u crossings slid along their chord", slid, crossings);
    SW_CHECK_MSG(placed < snapped, "on the segment %.3g, borrowed %.3g", placed, snapped);
}

/* One tessellation with crossings on their segments and the given border
 * fraction into the globals; the worst error of its border triangles. */
static double border_worst(const surface *s, const loops *l, double error, double fraction,
                           mesh *m)
{
    sw_arena a;
    sw_arena_init(&a, g_block, sizeof g_block);
    sw_trim_loops lv = view(l);
    sw_trim_tess_buffers b = {g_pos, g_nrm, g_uv, g_ids, g_idx, MAXV, MAXI, 0, NULL, 0};
    const sw_trim_tess_options opt = {.crossing_on_segment = 1, .border_fraction = fraction};
    SW_CHECK(sw_trim_tess(s->patches, s->count, &lv, error, &opt, &a, &b, &m->res, NULL) == SW_OK);
    m->nv = m->res.vertex_count, m->ni = m->res.index_count;
    return worst_at(s, m, g_pos, g_ids, 0, UINT32_MAX - 1);
}

/* Cells a loop runs through take border_fraction of the error: the border
 * triangles (those with a loop point or a crossing) get within that share
 * of it plus the loop's own chord error (tiny here: 256 points on the
 * circle), while the interior keeps the whole error. */
static void test_border_cells_take_their_share(void)
{
    surface s;
    make_bump(&s, 2);
    loops l;
    begin_loops(&l);
    add_circle(&l, &s, 0.5, 0.5, 0.4, 256, 1);
    const double error = 2e-3;
    mesh whole, share;
    double border_whole = border_worst(&s, &l, error, 0, &whole);
    double border_share = border_worst(&s, &l, error, 0.5, &share);
    printf("  border triangles' worst error: %.3g with the whole %.3g, %.3g with half; %u -> %u "
           "triangles\n", border_whole, error, border_share, whole.ni / 3, share.ni / 3);
    /* The grid's cells come from sub-patch bounds, so their triangles sit
     * well below the bound (here about 0.3 of it) and no border triangle
     * of this case needs the share; the share must still lower them. */
    SW_CHECK_MSG(border_share < 0.75 * border_whole, "the share did not lower the border: %g "
                 "-> %g", border_whole, border_share);
    SW_CHECK(border_share <= 0.5 * error + 1e-4);
    SW_CHECK(share.ni > whole.ni && share.res.error_bound <= error);
}

int main(void)
{
    SW_RUN(test_crossings_on_their_segment);
    SW_RUN(test_border_cells_take_their_share);
    return sw_test_finish();
}
