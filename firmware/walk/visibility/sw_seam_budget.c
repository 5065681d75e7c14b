/* SPDX-License-Identifier: MIT */
#include "sw_seam_budget.h"

#include <math.h>

/* Until the workers have made anything: a guess of the reference machine's
 * order (sw_trim_tess.h: millions of triangles a second, a few thousand a
 * millisecond); the first measured frames replace it. */
#define SW_BUDGET_START_TRIS_PER_MS 1000.0
#define SW_BUDGET_MIN_SCALE 0.1
/* When drawing alone takes longer than the target, the work may add this
 * much to it. */
#define SW_BUDGET_OVER_BASE 1.25

void sw_seam_budget_init(sw_seam_budget *b, double target_ms)
{
    *b = (sw_seam_budget){ .target_ms = target_ms, .scale = 1.0,
                           .tris_per_ms = SW_BUDGET_START_TRIS_PER_MS };
    b->new_tris = b->updated_tris = SW_BUDGET_START_TRIS_PER_MS * target_ms;
}

void sw_seam_budget_after_frame(sw_seam_budget *b, double frame_ms, int swapped,
                                uint64_t made_tris, uint64_t busy_ns, uint32_t workers)
{
    uint64_t tris = made_tris - b->seen_tris, ns = busy_ns - b->seen_ns;
    b->seen_tris = made_tris, b->seen_ns = busy_ns;
    if (ns > 1000000 && tris > 0)   /* at least a millisecond of work to learn from */
        b->tris_per_ms = 0.8 * b->tris_per_ms + 0.2 * ((double)tris / ((double)ns * 1e-6));
    /* What drawing alone costs: frames that swapped nothing in. The budget
     * answers only for what the work adds, so a scene that cannot be drawn
     * within the target does not starve the work. */
    if (!swapped)
        b->base_ms = b->base_ms > 0 ? 0.9 * b->base_ms + 0.1 * frame_ms : frame_ms;
    double hold = fmax(b->target_ms, SW_BUDGET_OVER_BASE * b->base_ms);
    if (frame_ms > hold)
        b->scale *= fmax(0.5, hold / frame_ms);
    else
        b->scale = fmin(1.0, b->scale * 1.1);
    b->scale = fmax(b->scale, SW_BUDGET_MIN_SCALE);
    /* What the workers make while the GL thread draws one frame. */
    double n = b->scale * b->tris_per_ms * fmax(b->target_ms, frame_ms) * workers;
    /* Updates (loops that moved under a mesh) spent over M come out of
     * the next frame's N, so the two together hold. */
    double over = b->updated_used > b->updated_tris ? b->updated_used - b->updated_tris : 0;
    b->updated_tris = n;
    b->new_tris = fmax(0.1 * n, n - over);
}

double sw_seam_weight(int has_mesh, double eps_min, double eps_max, double eps)
{
    if (!has_mesh)
        return 1e30;
    if (eps < eps_min)
        return (eps_min / eps) * (eps_min / eps);
    if (eps >= eps_max)
        return eps / eps_max;
    return 0.0;
}

double sw_seam_weight_culled(double w) { return w > 0.0 ? 1.0 - 1.0 / w : 0.0; }

/* Heaviest first: a min-heap by weight, then the minimum swapped to the end. */
static void sift(sw_seam_candidate *c, uint32_t n, uint32_t i)
{
    for (;;) {
        uint32_t l = 2 * i + 1, r = l + 1, m = i;
        if (l < n && c[l].weight < c[m].weight)
            m = l;
        if (r < n && c[r].weight < c[m].weight)
            m = r;
        if (m == i)
            return;
        sw_seam_candidate t = c[i];
        c[i] = c[m], c[m] = t, i = m;
    }
}

void sw_seam_candidates_sort(sw_seam_candidate *c, uint32_t n)
{
    for (uint32_t i = n / 2; i-- > 0;)
        sift(c, n, i);
    for (uint32_t end = n; end > 1; end--) {
        sw_seam_candidate t = c[0];
        c[0] = c[end - 1], c[end - 1] = t;
        sift(c, end - 1, 0);
    }
}
