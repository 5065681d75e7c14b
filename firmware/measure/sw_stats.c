/* SPDX-License-Identifier: MIT */
#include "sw_stats.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

size_t sw_stats_arena_bytes(int frames)
{
    size_t n = (size_t)frames;
    return 2 * sw_arena_worst_case(n * sizeof(float), 8) + 3 * sw_arena_worst_case(n * 4, 8) +
           sw_arena_worst_case(SW_ERROR_BINS * sizeof(uint64_t), 8) +
           3 * sw_arena_worst_case(n * 4, 8) +                  /* the culling's */
           2 * sw_arena_worst_case(n * sizeof(float), 8) +    /* the hand-over's */
           11 * sw_arena_worst_case(n * sizeof(float) + 1, 8); /* sorting scratch at the end */
}

sw_status sw_stats_init(sw_stats *s, sw_arena *arena, int frames, double error_bound_px,
                        sw_error *err)
{
    memset(s, 0, sizeof *s);
    s->frame_capacity = frames;
    s->frame_ms = sw_arena_alloc(arena, (size_t)frames * sizeof(float), 8);
    s->tris = sw_arena_alloc(arena, (size_t)frames * 4, 8);
    s->visible = sw_arena_alloc(arena, (size_t)frames * 4, 8);
    s->error_bins = sw_arena_alloc(arena, SW_ERROR_BINS * sizeof(uint64_t), 8);
    s->retess = sw_arena_alloc(arena, (size_t)frames * 4, 8);
    s->tess_ms = sw_arena_alloc(arena, (size_t)frames * sizeof(float), 8);
    s->cull_box_tests = sw_arena_alloc(arena, (size_t)frames * 4, 8);
    s->cone_culled = sw_arena_alloc(arena, (size_t)frames * 4, 8);
    s->cull_ms = sw_arena_alloc(arena, (size_t)frames * sizeof(float), 8);
    s->visibility_ms = sw_arena_alloc(arena, (size_t)frames * sizeof(float), 8);
    s->plan_wait_ms = sw_arena_alloc(arena, (size_t)frames * sizeof(float), 8);
    s->cull_method = "tree";
    if (!s->frame_ms || !s->tris || !s->visible || !s->error_bins || !s->retess || !s->tess_ms ||
        !s->cull_box_tests || !s->cone_culled || !s->cull_ms || !s->visibility_ms ||
        !s->plan_wait_ms)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "arena too small for the statistics");
    memset(s->error_bins, 0, SW_ERROR_BINS * sizeof(uint64_t));
    s->error_bound_px = error_bound_px;
    /* Bins cover four times the bound at 1/1024 of it: fine enough for p99. */
    s->error_bin_px = 4.0 * error_bound_px / SW_ERROR_BINS;
    s->mallocs_after_init = -1;
    s->process_mallocs_after_init = -1;
    s->rss_start_kb = s->rss_first_loop_kb = s->rss_end_kb = s->rss_peak_kb = -1;
    s->rss_end_file_kb = s->rss_end_anon_kb = -1;
    s->start_display_ms = s->start_prepare_ms = s->start_walk_init_ms = -1;
    s->start_workers_ms = s->start_gl_ms = s->start_frame_ms = s->start_load_wait_ms = -1;
    return SW_OK;
}

/* The array slot of the frame being recorded: a ring over the capacity. */
static int slot_of(const sw_stats *s)
{
    return (int)(s->frames_total % (uint64_t)s->frame_capacity);
}

void sw_stats_add_frame(sw_stats *s, double ms, uint32_t tris, uint32_t visible)
{
    if (s->frame_capacity <= 0)
        return;
    int k = slot_of(s);
    s->frame_ms[k] = (float)ms;
    s->tris[k] = tris;
    s->visible[k] = visible;
    if (s->frames_total == 0 || ms > s->worst_frame_ms)
        s->worst_frame_ms = ms, s->worst_frame = s->frames_total;
    s->frames_total++;
    if (s->frames < s->frame_capacity)
        s->frames++;
}

void sw_stats_add_cache_frame(sw_stats *s, uint32_t surfaces, uint64_t triangles,
                              uint64_t upload_bytes, uint32_t evictions, double tess_ms)
{
    if (s->frame_capacity <= 0)
        return;
    s->retess[slot_of(s)] = surfaces;
    s->tess_ms[slot_of(s)] = (float)tess_ms;
    s->retess_total += surfaces;
    s->retess_triangles_total += triangles;
    s->retess_triangles_max = triangles > s->retess_triangles_max ? triangles
                                                                  : s->retess_triangles_max;
    s->upload_bytes_total += upload_bytes;
    s->upload_bytes_max = upload_bytes > s->upload_bytes_max ? upload_bytes : s->upload_bytes_max;
    s->evictions += evictions;
    s->frames_without_retess += surfaces == 0;
}

static uint64_t max_u64(uint64_t a, uint64_t b) { return a > b ? a : b; }

void sw_stats_add_cache_fill(sw_stats *s, uint64_t used_vertices, uint64_t used_indices,
                             uint64_t drawn_vertices, uint64_t drawn_indices)
{
    s->used_vertices_max = max_u64(s->used_vertices_max, used_vertices);
    s->used_indices_max = max_u64(s->used_indices_max, used_indices);
    s->drawn_vertices_max = max_u64(s->drawn_vertices_max, drawn_vertices);
    s->drawn_indices_max = max_u64(s->drawn_indices_max, drawn_indices);
}

void sw_stats_add_cull_frame(sw_stats *s, uint64_t box_tests, uint32_t cone_culled,
                             double cull_ms)
{
    if (s->frames >= s->frame_capacity)
        return;
    s->cull_box_tests[s->frames] = box_tests > UINT32_MAX ? UINT32_MAX : (uint32_t)box_tests;
    s->cone_culled[s->frames] = cone_culled;
    s->cull_ms[s->frames] = (float)cull_ms;
}

void sw_stats_add_visibility_frame(sw_stats *s, double visibility_ms, double plan_wait_ms,
                                   int on_gl_thread, int overlapped)
{
    s->planned_on_gl_thread += on_gl_thread != 0;
    s->plans_overlapped += overlapped != 0;
    int k = slot_of(s);
    s->visibility_ms[k] = (float)visibility_ms;
    s->plan_wait_ms[k] = (float)plan_wait_ms;
}

void sw_stats_add_depth_range(sw_stats *s, double near_z, double far_z)
{
    double ratio = far_z / near_z;
    if (ratio > s->depth_far_over_near_max)
        s->depth_far_over_near_max = ratio;
}

void sw_stats_add_error_px(sw_stats *s, double e)
{
    if (s->route_behind) {
        s->error_behind_max_px = e > s->error_behind_max_px ? e : s->error_behind_max_px;
        s->error_behind_samples++;
        return;
    }
    if (e > s->error_max_px)
        s->error_max_px = e;
    s->error_samples++;
    double bin = e / s->error_bin_px;
    if (bin >= SW_ERROR_BINS)
        s->error_overflow++;
    else
        s->error_bins[(size_t)bin]++;
}

static int compare_float(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

static double nearest_rank(const float *sorted, int count, double p)
{
    int rank = (int)(p * count + 0.999999);
    if (rank < 1)
        rank = 1;
    if (rank > count)
        rank = count;
    return sorted[rank - 1];
}

sw_percentiles sw_percentiles_of(float *v, int count)
{
    sw_percentiles p = { 0, 0, 0, 0 };
    if (count <= 0)
        return p;
    qsort(v, (size_t)count, sizeof *v, compare_float);
    p.p50 = nearest_rank(v, count, 0.50);
    p.p90 = nearest_rank(v, count, 0.90);
    p.p99 = nearest_rank(v, count, 0.99);
    p.max = v[count - 1];
    return p;
}

double sw_stats_error_p99(const sw_stats *s)
{
    if (!s->error_samples)
        return 0.0;
    uint64_t need = (uint64_t)(0.99 * (double)s->error_samples + 0.999999), seen = 0;
    for (size_t i = 0; i < SW_ERROR_BINS; i++) {
        seen += s->error_bins[i];
        if (seen >= need) {
            double upper = (double)(i + 1) * s->error_bin_px;
            return upper < s->error_max_px ? upper : s->error_max_px;
        }
    }
    return s->error_max_px;
}

/* s as a JSON string: quotes, backslashes and control characters escaped. */
static void write_json_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (; s && *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\')
            fprintf(f, "\\%c", c);
        else if (c < 0x20)
            fprintf(f, "\\u%04x", c);
        else
            fputc(c, f);
    }
    fputc('"', f);
}

static void write_store(FILE *f, const sw_stats *s)
{
    fprintf(f, "  \"store\": {\"slot\": \"%c\", \"trial\": %s, \"marked_good\": %d, "
               "\"message_screen\": ", s->store_slot, s->store_trial ? "true" : "false",
            s->store_marked_good);
    if (s->store_message)
        write_json_string(f, s->store_message);
    else
        fputs("null", f);
    fputs(", \"log\": ", f);
    write_json_string(f, s->store_log);
    fputs("},\n", f);
}

/* n floats of sorting scratch (one byte more, so n 0 still gets a pointer). */
static float *scratch_floats(sw_arena *scratch, int n)
{
    return sw_arena_alloc(scratch, (size_t)n * sizeof(float) + 1, 8);
}

/* The cache's figures; without_tess is frame_ms less tess_ms, per frame:
 * what the frame costs with the same cached triangles and no tessellating
 * (culling, seam selection, drawing, glFinish). */
static sw_status write_cache(FILE *f, const sw_stats *s, sw_arena *scratch)
{
    int n = s->frames;
    float *tess = scratch_floats(scratch, n);
    float *rest = scratch_floats(scratch, n);
    float *count = scratch_floats(scratch, n);
    if (!tess || !rest || !count)
        return SW_ERR_NO_MEMORY;
    for (int i = 0; i < n; i++) {
        tess[i] = s->tess_ms[i];
        rest[i] = s->frame_ms[i] - s->tess_ms[i];
        count[i] = (float)s->retess[i];
    }
    sw_percentiles t = sw_percentiles_of(tess, n), d = sw_percentiles_of(rest, n);
    sw_percentiles c = sw_percentiles_of(count, n);
    fprintf(f, "  \"cache\": {\"retessellated\": {\"p50\": %.0f, \"max\": %.0f, \"total\": %llu}, "
               "\"frames_without_retess\": %d, \"retess_triangles\": {\"max\": %llu, "
               "\"total\": %llu}, \"upload_bytes\": {\"max\": %llu, \"total\": %llu}, "
               "\"evictions\": %llu, \"tess_ms\": {\"p50\": %.3f, \"max\": %.3f}, "
               "\"without_tess_ms\": {\"p50\": %.3f, \"p99\": %.3f}, "
               "\"pool\": {\"vertices\": %llu, \"indices\": %llu, \"used_vertices_max\": %llu, "
               "\"used_indices_max\": %llu, \"drawn_vertices_max\": %llu, "
               "\"drawn_indices_max\": %llu}},\n",
            c.p50, c.max, (unsigned long long)s->retess_total, s->frames_without_retess,
            (unsigned long long)s->retess_triangles_max,
            (unsigned long long)s->retess_triangles_total,
            (unsigned long long)s->upload_bytes_max, (unsigned long long)s->upload_bytes_total,
            (unsigned long long)s->evictions, t.p50, t.max, d.p50, d.p99,
            (unsigned long long)s->pool_vertices, (unsigned long long)s->pool_indices,
            (unsigned long long)s->used_vertices_max, (unsigned long long)s->used_indices_max,
            (unsigned long long)s->drawn_vertices_max, (unsigned long long)s->drawn_indices_max);
    return SW_OK;
}

/* The culling's figures, per frame: box tests against the frustum, surfaces
 * left out facing away, and the time both took. */
static sw_status write_cull(FILE *f, const sw_stats *s, sw_arena *scratch)
{
    int n = s->frames;
    float *tests = scratch_floats(scratch, n);
    float *cones = scratch_floats(scratch, n);
    float *ms = scratch_floats(scratch, n);
    if (!tests || !cones || !ms)
        return SW_ERR_NO_MEMORY;
    for (int i = 0; i < n; i++) {
        tests[i] = (float)s->cull_box_tests[i];
        cones[i] = (float)s->cone_culled[i];
        ms[i] = s->cull_ms[i];
    }
    sw_percentiles t = sw_percentiles_of(tests, n), c = sw_percentiles_of(cones, n);
    sw_percentiles m = sw_percentiles_of(ms, n);
    fprintf(f, "  \"cull\": {\"method\": \"%s\", \"cone_cull\": %s, "
               "\"box_tests\": {\"p50\": %.0f, \"max\": %.0f}, "
               "\"cone_culled\": {\"p50\": %.0f, \"max\": %.0f}, "
               "\"ms\": {\"p50\": %.4f, \"p99\": %.4f, \"max\": %.4f}, "
               "\"tree_build_ms\": %.3f, \"cones_build_ms\": %.3f},\n",
            s->cull_method, s->cone_cull ? "true" : "false", t.p50, t.max, c.p50, c.max, m.p50,
            m.p99, m.max, s->cull_tree_ms, s->cones_ms);
    return SW_OK;
}

void sw_stats_add_threads_frame(sw_stats *s, uint32_t waiting, uint32_t behind,
                                uint32_t frames_behind, double behind_ratio, uint32_t jobs,
                                uint32_t prefetch, uint32_t batches, uint32_t seam_ops,
                                double budget_tris, double budget_used)
{
    s->prefetch_total += prefetch;
    s->waiting_max = waiting > s->waiting_max ? waiting : s->waiting_max;
    s->behind_max = behind > s->behind_max ? behind : s->behind_max;
    if (frames_behind > s->frames_behind_max)
        s->frames_behind_max = frames_behind;
    s->behind_ratio_max = behind_ratio > s->behind_ratio_max ? behind_ratio : s->behind_ratio_max;
    s->jobs_total += jobs;
    s->batches_total += batches;
    s->seam_ops_total += seam_ops;
    if (budget_tris > 0) {
        s->budget_used_sum += budget_used;
        s->budget_used_max = budget_used > s->budget_used_max ? budget_used : s->budget_used_max;
        s->budget_frames++;
        s->budget_tris_last = budget_tris;
    }
}

void sw_stats_add_pressure(sw_stats *s, double pressure)
{
    if (pressure > 1.0)
        s->pressure_frames++;
    s->pressure_max = pressure > s->pressure_max ? pressure : s->pressure_max;
}

void sw_stats_add_standins(sw_stats *s, uint32_t drawn, uint32_t made, uint32_t coarser,
                           uint64_t triangles, uint32_t leaner_jobs)
{
    s->standins_max = drawn > s->standins_max ? drawn : s->standins_max;
    s->standins_made += made;
    s->standins_coarser += coarser;
    s->standins_leaner += leaner_jobs;
    s->standin_triangles += triangles;
    if (triangles > s->standin_triangles_max)
        s->standin_triangles_max = triangles;
}

void sw_stats_add_update_cap(sw_stats *s, double used, double cap)
{
    if (cap <= 0)
        return;
    s->updated_capped_batches++;
    if (used > cap) {
        s->updated_over_batches++;
        s->updated_over_max = fmax(s->updated_over_max, used / cap);
    }
}

/* The hand-over between V and P (sw_seam_visibility.h), per kept frame. */
static sw_status write_visibility(FILE *f, const sw_stats *s, sw_arena *scratch)
{
    int n = s->frames;
    float *vis = scratch_floats(scratch, n);
    float *wait = scratch_floats(scratch, n);
    if (!vis || !wait)
        return SW_ERR_NO_MEMORY;
    memcpy(vis, s->visibility_ms, (size_t)n * sizeof(float));
    memcpy(wait, s->plan_wait_ms, (size_t)n * sizeof(float));
    sw_percentiles v = sw_percentiles_of(vis, n), w = sw_percentiles_of(wait, n);
    fprintf(f, "  \"visibility\": {\"thread\": %s, "
               "\"ms\": {\"p50\": %.3f, \"p99\": %.3f, \"max\": %.3f}, "
               "\"plan_wait_ms\": {\"p50\": %.3f, \"p99\": %.3f, \"max\": %.3f}, "
               "\"planned_on_gl_thread\": %llu, \"overlapped_frames\": %llu},\n",
            s->visibility_thread ? "true" : "false", v.p50, v.p99, v.max, w.p50, w.p99, w.max,
            (unsigned long long)s->planned_on_gl_thread,
            (unsigned long long)s->plans_overlapped);
    return SW_OK;
}

void sw_stats_add_part_levels(sw_stats *s, uint32_t parts, uint32_t covered, uint64_t triangles)
{
    s->part_levels_max = parts > s->part_levels_max ? parts : s->part_levels_max;
    s->covered_max = covered > s->covered_max ? covered : s->covered_max;
    s->part_level_triangles += triangles;
    if (triangles > s->part_level_triangles_max)
        s->part_level_triangles_max = triangles;
}

static void write_part_levels(FILE *f, const sw_stats *s)
{
    fprintf(f, "  \"part_levels\": {\"parts_max\": %u, \"covered_surfaces_max\": %u, "
               "\"triangles\": {\"mean\": %.0f, \"max\": %llu}},\n",
            s->part_levels_max, s->covered_max,
            s->frames_total ? (double)s->part_level_triangles / (double)s->frames_total : 0.0,
            (unsigned long long)s->part_level_triangles_max);
}

static void write_threads(FILE *f, const sw_stats *s)
{
    fprintf(f, "  \"threads\": {\"workers\": %d, \"sync_work\": %d, \"target_ms\": %.3f, "
               "\"waiting_surfaces_max\": %u, \"pressure_max\": %.3f, \"pressure_frames\": %u, "
               "\"standins_max\": %u, \"standins_made\": %llu, \"standins_coarser\": %llu, "
               "\"standins_leaner_jobs\": %llu, "
               "\"standin_triangles\": {\"mean\": %.0f, \"max\": %llu}, "
               "\"behind_surfaces_max\": %u, "
               "\"frames_behind_max\": %u, \"behind_ratio_max\": %.3f, \"jobs\": %llu, "
               "\"prefetch_jobs\": %llu, \"batches\": %llu, \"seam_ops\": %llu, \"budget_used_mean\": %.3f, "
               "\"budget_used_max\": %.3f, \"budget_tris_last\": %.0f, "
               "\"worker_triangles\": %llu, \"worker_busy_ms\": %.1f, \"steals\": %llu, "
               "\"updated\": {\"capped_batches\": %llu, \"over_cap_batches\": %llu, "
               "\"over_cap_ratio_max\": %.3f}},\n",
            s->workers, s->sync_work, s->target_ms, s->waiting_max,
            s->pressure_max > 1.0 ? s->pressure_max : 1.0, s->pressure_frames, s->standins_max,
            (unsigned long long)s->standins_made, (unsigned long long)s->standins_coarser,
            (unsigned long long)s->standins_leaner,
            s->frames_total ? (double)s->standin_triangles / (double)s->frames_total : 0.0,
            (unsigned long long)s->standin_triangles_max, s->behind_max,
            s->frames_behind_max, s->behind_ratio_max, (unsigned long long)s->jobs_total,
            (unsigned long long)s->prefetch_total, (unsigned long long)s->batches_total, (unsigned long long)s->seam_ops_total,
            s->budget_frames ? s->budget_used_sum / s->budget_frames : 0.0, s->budget_used_max,
            s->budget_tris_last, (unsigned long long)s->worker_triangles, s->worker_busy_ms,
            (unsigned long long)s->worker_steals, (unsigned long long)s->updated_capped_batches,
            (unsigned long long)s->updated_over_batches, s->updated_over_max);
}

/* The kept frame times oldest first (the ring unrolled), for plots along
 * the path; then the soak's figures. */
static void write_series_and_soak(FILE *f, const sw_stats *s)
{
    int n = s->frames, first = s->frames_total > (uint64_t)n ? slot_of(s) : 0;
    fputs("  \"frame_ms_series\": [", f);
    for (int i = 0; i < n; i++)
        fprintf(f, "%s%.3f", i ? ", " : "", s->frame_ms[(first + i) % n]);
    fputs("],\n", f);
    fprintf(f, "  \"frames_total\": %llu,\n  \"worst_frame\": {\"ms\": %.3f, \"frame\": %llu},\n",
            (unsigned long long)s->frames_total, s->worst_frame_ms,
            (unsigned long long)s->worst_frame);
    fprintf(f, "  \"rss_kb\": {\"start\": %lld, \"after_first_loop\": %lld, \"end\": %lld, "
               "\"peak\": %lld, \"end_file\": %lld, \"end_anon\": %lld},\n",
            (long long)s->rss_start_kb, (long long)s->rss_first_loop_kb,
            (long long)s->rss_end_kb, (long long)s->rss_peak_kb, (long long)s->rss_end_file_kb,
            (long long)s->rss_end_anon_kb);
    fprintf(f, "  \"soak\": {\"duration_s\": %.3f, \"loops\": %llu, \"frames_per_loop\": %d, "
               "\"heap_resident\": %d, \"batch_waits\": %llu, \"rss_kb_per_loop\": [",
            s->duration_s, (unsigned long long)s->loops, s->frame_capacity, s->heap_resident,
            (unsigned long long)s->batch_waits);
    for (uint64_t i = 0; i < s->loops && i < SW_STATS_RSS_LOOPS; i++)
        fprintf(f, "%s%lld", i ? ", " : "", (long long)s->rss_loop_kb[i]);
    fputs("]},\n", f);
}

static float *copy_as_float_u32(const uint32_t *v, int n, sw_arena *a)
{
    float *out = sw_arena_alloc(a, (size_t)n * sizeof(float) + 1, 8);
    for (int i = 0; out && i < n; i++)
        out[i] = (float)v[i];
    return out;
}

sw_status sw_stats_write_json(const sw_stats *s, FILE *f, sw_arena *scratch, sw_error *err)
{
    size_t mark = sw_arena_mark(scratch);
    int n = s->frames;
    float *ms = scratch_floats(scratch, n);
    float *tris = copy_as_float_u32(s->tris, n, scratch);
    float *vis = copy_as_float_u32(s->visible, n, scratch);
    if (!ms || !tris || !vis) {
        sw_arena_reset_to(scratch, mark);
        return sw_error_set(err, SW_ERR_NO_MEMORY, "arena too small to sort the statistics");
    }
    memcpy(ms, s->frame_ms, (size_t)n * sizeof(float));
    sw_percentiles fms = sw_percentiles_of(ms, n), tri = sw_percentiles_of(tris, n);
    sw_percentiles visible = sw_percentiles_of(vis, n);
    fprintf(f, "{\n  \"version\": \"%s\",\n  \"frames\": %d,\n", SW_VERSION, n);
    fprintf(f, "  \"frame_ms\": {\"p50\": %.3f, \"p90\": %.3f, \"p99\": %.3f, \"max\": %.3f},\n",
            fms.p50, fms.p90, fms.p99, fms.max);
    fprintf(f, "  \"fps_median\": %.2f,\n", fms.p50 > 0 ? 1000.0 / fms.p50 : 0.0);
    fprintf(f, "  \"tris_per_frame\": {\"median\": %.0f, \"max\": %.0f},\n", tri.p50, tri.max);
    fprintf(f, "  \"patches\": {\"total\": %u, \"visible_median\": %.0f},\n", s->patches_total,
            visible.p50);
    fprintf(f, "  \"error_px\": {\"max\": %.5f, \"p99\": %.5f, \"bound\": %.5f, \"samples\": %llu, "
               "\"measured_frames\": %d, \"measure_every\": %d},\n",
            s->error_max_px, sw_stats_error_p99(s), s->error_bound_px,
            (unsigned long long)s->error_samples, s->measured_frames, s->measure_every);
    fprintf(f, "  \"error_px_behind\": {\"max\": %.5f, \"beyond_sewing_max\": %.5f, "
               "\"samples\": %llu},\n", s->error_behind_max_px, s->error_behind_beyond_sewing_px,
            (unsigned long long)s->error_behind_samples);
    fprintf(f, "  \"cracks_max\": %llu,\n", (unsigned long long)s->cracks_max);
    fprintf(f, "  \"capped_patches_max\": %llu,\n", (unsigned long long)s->capped_patches_max);
    if (s->frames && (write_cache(f, s, scratch) != SW_OK || write_cull(f, s, scratch) != SW_OK ||
                      write_visibility(f, s, scratch) != SW_OK)) {
        sw_arena_reset_to(scratch, mark);
        return sw_error_set(err, SW_ERR_NO_MEMORY, "arena too small to sort the statistics");
    }
    fprintf(f, "  \"seam\": {\"active_vertices_min\": %u, \"active_vertices_max\": %u, "
                   "\"surfaces_vanished_max\": %u, \"surfaces_failed_max\": %u, "
                   "\"surfaces_holes_filled_max\": %u, \"surfaces_untangled_max\": %u, "
                   "\"surfaces_clamped_max\": %u, \"crossings_max\": %llu, "
                   "\"arena_bytes\": %llu, \"arena_peak_bytes\": %llu, "
                   "\"sewing_offset_px_max\": %.5f, \"error_px_beyond_sewing_max\": %.5f},\n",
                s->seam_active_min, s->seam_active_max, s->surfaces_vanished_max,
                s->surfaces_failed_max, s->surfaces_holes_filled_max, s->surfaces_untangled_max,
                s->surfaces_clamped_max, (unsigned long long)s->seam_crossings_max,
                (unsigned long long)s->seam_arena_bytes,
                (unsigned long long)s->seam_arena_peak_bytes, s->seam_sewing_offset_px,
                s->seam_error_beyond_sewing_px);
    fprintf(f, "  \"seam_drawn\": {\"points_max\": %llu, \"t_vertices_max\": %llu, "
               "\"gaps_max\": %llu, \"free_points_max\": %llu, \"unchecked_frames\": %d, "
               "\"chord_error_px_max\": %.5f, \"fill_triangles_max\": %llu},\n",
            (unsigned long long)s->drawn_points_max, (unsigned long long)s->drawn_t_vertices_max,
            (unsigned long long)s->drawn_gaps_max, (unsigned long long)s->drawn_free_max,
            s->drawn_unchecked_frames, s->seam_chord_px_max,
            (unsigned long long)s->fill_triangles_max);
    fprintf(f, "  \"depth\": {\"bits\": %d, \"far_over_near_max\": %.1f},\n", s->depth_bits,
            s->depth_far_over_near_max);
    write_threads(f, s);
    write_part_levels(f, s);
    if (s->store)
        write_store(f, s);
    write_series_and_soak(f, s);
    fprintf(f, "  \"arena_bytes\": %llu,\n  \"arena_peak_bytes\": %llu,\n  \"runtime_bytes\": %llu,\n",
            (unsigned long long)s->arena_bytes, (unsigned long long)s->arena_peak_bytes,
            (unsigned long long)s->runtime_bytes);
    fprintf(f, "  \"pack_bytes\": %llu,\n  \"pack_mapped\": %s,\n",
            (unsigned long long)s->pack_bytes, s->pack_mapped ? "true" : "false");
    fprintf(f, "  \"mallocs_after_init\": %lld,\n", (long long)s->mallocs_after_init);
    fprintf(f, "  \"process_mallocs_after_init\": %lld,\n",
            (long long)s->process_mallocs_after_init);
    fprintf(f, "  \"pack_open_ms\": %.3f,\n  \"first_frame_ms\": %.3f,\n", s->pack_open_ms,
            s->first_frame_ms);
    fprintf(f, "  \"start_ms\": {\"display\": %.3f, \"pack_open\": %.3f, \"prepare\": %.3f, "
               "\"walk_init\": %.3f, \"workers\": %.3f, \"gl\": %.3f, \"first_frame\": %.3f, "
               "\"load_wait\": %.3f},\n",
            s->start_display_ms, s->pack_open_ms, s->start_prepare_ms, s->start_walk_init_ms,
            s->start_workers_ms, s->start_gl_ms, s->start_frame_ms, s->start_load_wait_ms);
    fprintf(f, "  \"walk_s\": %.3f,\n  \"viewport\": [%d, %d]\n}\n", s->walk_s, s->width,
            s->height);
    sw_arena_reset_to(scratch, mark);
    if (ferror(f))
        return sw_error_set(err, SW_ERR_IO, "writing the statistics failed");
    return SW_OK;
}
