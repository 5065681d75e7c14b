/* SPDX-License-Identifier: MIT */
/* walk_baseline: the walkthrough benchmark's baselines (walk_baseline.h)
 * walked like seamwalk walks: same pack, path or orbit, viewport, field of
 * view, renderer and stats file.
 *   walk_baseline --pack PACK (--path FILE | --orbit) --mode uniform|glu
 *                 [--segments S] [--tolerance-px T] [--size WxH] [--frames N]
 *                 [--every K] [--max-s S] [--measure-every M]
 *                 [--error-bins-px B] [--stats FILE.json]
 * --frames N positions along the path (as seamwalk --frames N), of which
 * every K-th is drawn (0, K, 2K, ...), stopping after --max-s seconds of
 * walking (0: never) so a slow baseline stays bounded; every M-th drawn
 * frame is measured (time spent measuring is left out of frame times, as
 * in seamwalk). --error-bins-px: the stats' error histogram spans 4 B
 * (default 0.5, seamwalk's; a coarse baseline needs more for its p99).
 * Prints one line of key=value figures the stats file has no field for. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "sw_camera_path.h"
#include "sw_egl_headless.h"
#include "sw_pack_instances.h"
#include "sw_rss.h"
#include "sw_surface_at.h"
#include "sw_up_axis.h"
#include "walk_baseline.h"

typedef struct wb_options {
    const char *pack_path, *path_file, *stats_path;
    int orbit, glu, width, height, frames, every, measure_every;
    unsigned segments;
    double tolerance_px, max_s, fov_deg, error_bins_px;
} wb_options;

/* Border edges the drawn-seam check holds in a frame: a uniform grid's
 * patches bring 4 S each. GLU's meshes bring far more (its strips share
 * no vertices, so each strip's sides are border edges too): on the 40,000
 * patch showroom they overflow this, and the frame is counted unchecked;
 * at 2^22 edges the check took 430 s for two frames. */
static uint32_t drawn_edges(const wb_options *o)
{
    (void)o;
    return 1u << 20;
}

typedef struct wb_run {
    wb_options opt;
    sw_egl_headless egl;
    int egl_up, renderer_up;
    sw_renderer renderer;
    void *block;
    void *placed_block;        /* a placed pack's scene, every array copied */
    sw_arena arena;
    sw_pack pack;
    sw_box box;
    sw_camera_path path;
    sw_camera_key *keys;       /* the path's, ours to free */
    sw_camera_frame frame;
    sw_stats stats;
    sw_seam_drawn drawn;
    float *sew_offset;
    wb_walk walk;
    uint32_t glu_skipped, failed_max, frames_run;
    int stopped_early;
} wb_run;

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

static int usage(const char *why)
{
    fprintf(stderr, "walk_baseline: %s\nusage: walk_baseline --pack PACK (--path FILE | --orbit) "
                    "--mode uniform|glu [--segments S] [--tolerance-px T] [--size WxH] "
                    "[--frames N] [--every K] [--max-s S] [--measure-every M] "
                    "[--error-bins-px B] [--stats FILE.json]\n", why);
    return 2;
}

static int number(const char *text, double lo, double hi, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(text, &end);
    if (errno || end == text || *end || !(v >= lo && v <= hi))
        return 0;
    *out = v;
    return 1;
}

/* One option with its value; 0 and a message on a bad one. */
static int parse_one(wb_options *o, const char *a, const char *v, char *why, size_t n)
{
    double x = 0;
    int ok = 1;
    if (!strcmp(a, "--pack")) o->pack_path = v;
    else if (!strcmp(a, "--path")) o->path_file = v;
    else if (!strcmp(a, "--stats")) o->stats_path = v;
    else if (!strcmp(a, "--mode")) {
        ok = !strcmp(v, "uniform") || !strcmp(v, "glu");
        o->glu = !strcmp(v, "glu");
    } else if (!strcmp(a, "--size")) {
        ok = sscanf(v, "%dx%d", &o->width, &o->height) == 2 && o->width > 0 && o->height > 0 &&
             o->width <= 8192 && o->height <= 8192;
    } else if (!strcmp(a, "--segments") && (ok = number(v, 1, SW_TESS_MAX_SEGMENTS, &x))) o->segments = (unsigned)x;
    else if (!strcmp(a, "--frames") && (ok = number(v, 1, 1e7, &x))) o->frames = (int)x;
    else if (!strcmp(a, "--every") && (ok = number(v, 1, 1e7, &x))) o->every = (int)x;
    else if (!strcmp(a, "--measure-every") && (ok = number(v, 1, 1e7, &x))) o->measure_every = (int)x;
    else if (!strcmp(a, "--tolerance-px")) ok = number(v, 0.01, 100, &o->tolerance_px);
    else if (!strcmp(a, "--max-s")) ok = number(v, 0, 1e7, &o->max_s);
    else if (!strcmp(a, "--fov-deg")) ok = number(v, 1, 170, &o->fov_deg);
    else if (!strcmp(a, "--error-bins-px")) ok = number(v, 0.01, 1000, &o->error_bins_px);
    else {
        snprintf(why, n, "unknown option %s", a);
        return 0;
    }
    if (!ok)
        snprintf(why, n, "%s: bad value '%s'", a, v);
    return ok;
}

static int parse(int argc, char **argv, wb_options *o, char *why, size_t n)
{
    *o = (wb_options){.width = 1280, .height = 720, .frames = 120, .every = 1,
                      .measure_every = 1, .segments = 8, .tolerance_px = 0.5, .fov_deg = 45,
                      .error_bins_px = 0.5};
    int mode = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--orbit")) {
            o->orbit = 1;
            continue;
        }
        if (i + 1 >= argc) {
            snprintf(why, n, "%s needs a value", argv[i]);
            return 0;
        }
        mode |= !strcmp(argv[i], "--mode");
        if (!parse_one(o, argv[i], argv[i + 1], why, n))
            return 0;
        i++;
    }
    if (!o->pack_path || !mode || (!o->path_file == !o->orbit)) {
        snprintf(why, n, "needs --pack, --mode and one of --path or --orbit");
        return 0;
    }
    return 1;
}

static int fail(const char *what, const sw_error *err)
{
    fprintf(stderr, "walk_baseline: %s%s%s\n", what, err ? ": " : "", err ? err->message : "");
    return 1;
}

/* The camera path, read whole (a benchmark may allocate). */
static int load_path(wb_run *r, sw_error *err)
{
    FILE *f = fopen(r->opt.path_file, "rb");
    if (!f)
        return sw_error_set(err, SW_ERR_IO, "%s: %s", r->opt.path_file, strerror(errno)), 0;
    static char text[1 << 22];
    size_t n = fread(text, 1, sizeof text, f);
    fclose(f);
    size_t keys = sw_camera_path_count_keys(text, n);
    sw_camera_key *k = r->keys = malloc((keys + 1) * sizeof *k);
    return k && sw_camera_path_parse(text, n, r->opt.path_file, k, keys, &r->path, err) == SW_OK;
}

/* Arena for the pack, the stats and the drawn-seam check; the pack loaded. */
static int load_pack(wb_run *r, sw_error *err)
{
    sw_pack_header h;
    if (sw_pack_read_header(r->opt.pack_path, &h, err) != SW_OK)
        return 0;
    size_t bytes = (size_t)h.runtime_bytes + sw_stats_arena_bytes(r->opt.frames) +
                   sw_seam_drawn_arena_bytes(drawn_edges(&r->opt), WB_BATCH_INDICES) + (1u << 20);
    if (!(r->block = malloc(bytes)))
        return sw_error_set(err, SW_ERR_NO_MEMORY, "cannot take %zu bytes", bytes), 0;
    sw_arena_init(&r->arena, r->block, bytes);
    sw_pack stored;
    if (sw_pack_load(r->opt.pack_path, &r->arena, &stored, err) != SW_OK)
        return 0;
    /* The tools' expansion (every placed array copied, as the pack of
     * copies would hold them), beside the arena: the baseline reads the
     * patches' domains and masks by patch, which the runtime's shares. */
    uint64_t counts[SW_SPACE_COUNT] = { 0 };
    if (stored.instances)
        sw_pack_placed_counts(stored.prototypes, stored.instances, stored.instance_count, counts);
    size_t placed = stored.instances ? (size_t)sw_pack_expand_bytes(counts) : 0;
    if (placed && !(r->placed_block = malloc(placed)))
        return sw_error_set(err, SW_ERR_NO_MEMORY, "cannot take %zu bytes", placed), 0;
    sw_arena pa;
    sw_arena_init(&pa, r->placed_block, placed);
    if (sw_pack_expand(&stored, &pa, &r->pack, err) != SW_OK)
        return 0;
    if (!r->pack.seam_header || !r->pack.patch_domains || !r->pack.meta->patch_count)
        return sw_error_set(err, SW_ERR_FORMAT, "%s: no patches, or no Seam Graph",
                            r->opt.pack_path), 0;
    const sw_pack_meta *m = r->pack.meta;
    r->box = (sw_box){ sw_v3(m->box_min[0], m->box_min[1], m->box_min[2]),
                       sw_v3(m->box_max[0], m->box_max[1], m->box_max[2]) };
    r->frame = sw_camera_frame_for_up(sw_up_axis_vector(sw_pack_up_axis(&r->pack)));
    return 1;
}

/* Every patch as the measure takes it, and each surface's sewing offset,
 * as seamwalk measures them at start. */
static int load_patches(wb_run *r, sw_error *err)
{
    const sw_pack *p = &r->pack;
    const sw_seam_graph *g = &p->seam;
    wb_walk *w = &r->walk;
    w->patches = malloc((p->meta->patch_count + 1) * sizeof *w->patches);
    w->surface_first = malloc((g->surface_count + 1) * sizeof *w->surface_first);
    r->sew_offset = malloc((g->surface_count + 1) * sizeof *r->sew_offset);
    if (!w->patches || !w->surface_first || !r->sew_offset)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory for the patches"), 0;
    for (uint32_t s = 0; s < g->surface_count; s++) {
        const sw_pack_surface *ps = &p->surfaces[s];
        uint32_t count = 0;
        w->surface_first[s] = ps->first_patch;
        if (sw_trim_patches_from_pack(p, s, w->patches + ps->first_patch, ps->patch_count,
                                      &count, err) != SW_OK)
            return 0;
        double worst = 0;
        for (uint32_t l = g->surface_loops[s]; l < g->surface_loops[s + 1]; l++)
            worst = fmax(worst, sw_seam_sewing_offset(g, &g->loops[l],
                                                               w->patches + ps->first_patch,
                                                               count));
        r->sew_offset[s] = (float)worst;
    }
    return 1;
}

static int start(wb_run *r, sw_error *err)
{
    const wb_options *o = &r->opt;
    if (sw_egl_headless_init_depth(&r->egl, SW_GL_API_GLES2, o->width, o->height, 24, err))
        return 0;
    r->egl_up = 1;
    if (!load_pack(r, err) || (o->path_file && !load_path(r, err)) || !load_patches(r, err))
        return 0;
    if (sw_stats_init(&r->stats, &r->arena, o->frames, o->error_bins_px, err) != SW_OK ||
        sw_seam_drawn_init(&r->drawn, &r->box, r->pack.seam.tolerance, drawn_edges(o),
                           WB_BATCH_INDICES, &r->arena, err) != SW_OK)
        return 0;
    if (sw_renderer_init(&r->renderer, WB_BATCH_VERTICES, WB_BATCH_INDICES, err) != SW_OK)
        return 0;
    r->renderer_up = 1;
    wb_walk *w = &r->walk;
    w->pack = &r->pack;
    w->renderer = &r->renderer;
    w->sew_offset = r->sew_offset;
    w->bound_floor = 0.1f * r->pack.seam.tolerance;
    w->segments = o->segments;
    w->error_px = o->glu ? o->tolerance_px : 0.5;
    w->batch.verts = malloc(WB_BATCH_VERTICES * sizeof(sw_vertex));
    w->batch.uvs = malloc(WB_BATCH_VERTICES * 2 * sizeof(float));
    w->batch.indices = malloc(WB_BATCH_INDICES * sizeof(uint16_t));
    if (!w->batch.verts || !w->batch.uvs || !w->batch.indices)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory for the batch"), 0;
    char why[256] = "";
    if (o->glu && !wb_glu_init(w, &r->glu_skipped, why, sizeof why))
        return sw_error_set(err, SW_ERR_UNSUPPORTED, "GLU: %s", why), 0;
    return 1;
}

static sw_camera_pose pose_at(const wb_run *r, int frame)
{
    const wb_options *o = &r->opt;
    if (o->orbit)
        return sw_camera_orbit_in(&r->box, &r->frame, o->fov_deg * SW_PI / 180.0,
                                  (double)o->width / o->height, (double)frame / o->frames);
    double t0 = sw_camera_path_start(&r->path), t1 = sw_camera_path_end(&r->path);
    double t = o->frames > 1 ? t0 + (t1 - t0) * frame / (o->frames - 1) : t0;
    return sw_camera_path_at(&r->path, t);
}

/* Near and far fitted to the visible patches, as seamwalk fits them to
 * its drawn surfaces (firmware/walk/visibility/sw_seam_depth.h). */
static sw_view fitted_view(const wb_run *r, const sw_view *v)
{
    double lo = INFINITY, hi = -INFINITY;
    for (uint32_t i = 0; i < r->pack.meta->patch_count; i++) {
        double d;
        if (!wb_patch_visible(&r->pack, i, v, &d))
            continue;
        sw_box b = wb_patch_box(&r->pack, i);
        for (int k = 0; k < 8; k++) {
            double z = sw_view_depth(v, sw_v3(k & 1 ? b.max.x : b.min.x, k & 2 ? b.max.y : b.min.y,
                                              k & 4 ? b.max.z : b.min.z));
            lo = fmin(lo, z), hi = fmax(hi, z);
        }
    }
    return lo <= hi ? sw_view_fit_depth(v, fmax(lo, v->near_z), hi, r->egl.depth_bits) : *v;
}

/* The measured frame's borders into the stats, as seamwalk records them. */
static void add_measured(wb_run *r)
{
    sw_stats *s = &r->stats;
    sw_seam_drawn_result d;
    sw_seam_drawn_check(&r->drawn, &d);
    s->drawn_unchecked_frames += !d.checked;
    s->drawn_points_max = d.points > s->drawn_points_max ? d.points : s->drawn_points_max;
    s->drawn_t_vertices_max = d.t_vertices > s->drawn_t_vertices_max ? d.t_vertices
                                                                     : s->drawn_t_vertices_max;
    s->drawn_gaps_max = d.gaps > s->drawn_gaps_max ? d.gaps : s->drawn_gaps_max;
    s->drawn_free_max = d.free_points > s->drawn_free_max ? d.free_points : s->drawn_free_max;
    s->seam_error_beyond_sewing_px = fmax(s->seam_error_beyond_sewing_px,
                                          r->walk.acc.beyond_sewing_px);
    s->seam_sewing_offset_px = fmax(s->seam_sewing_offset_px, r->walk.acc.sewing_offset_px);
    s->seam_chord_px_max = fmax(s->seam_chord_px_max, r->walk.acc.chord_px);
    s->measured_frames++;
}

static void run_frame(wb_run *r, int frame, int measuring)
{
    static const float background[4] = { 0.93f, 0.94f, 0.96f, 1.0f };
    double t0 = now_s();
    wb_walk *w = &r->walk;
    sw_camera_pose pose = pose_at(r, frame);
    sw_view culled = sw_view_make_depth(&pose, r->opt.fov_deg * SW_PI / 180.0, r->opt.width,
                                        r->opt.height, &r->box, r->egl.depth_bits);
    sw_view view = fitted_view(r, &culled);
    float mv[16], proj[16];
    sw_mat4_to_float(&view.view, mv);
    sw_mat4_to_float(&view.proj, proj);
    sw_renderer_begin_frame(&r->renderer, r->opt.width, r->opt.height, background, mv, proj);
    w->stats = measuring ? &r->stats : NULL;
    w->drawn = measuring ? &r->drawn : NULL;
    w->acc = (sw_seam_error){ 0, 0, 0 };
    w->measure_ms = 0;
    if (measuring)
        sw_seam_drawn_begin(&r->drawn);
    wb_frame out = { 0, 0, 0 };
    if (r->opt.glu)
        wb_glu_frame(w, &culled, &out);
    else
        wb_uniform_frame(w, &culled, &out);
    sw_renderer_finish(&r->renderer);
    double ms = (now_s() - t0) * 1000.0 - w->measure_ms;
    if (measuring)
        add_measured(r);
    r->failed_max = out.failed > r->failed_max ? out.failed : r->failed_max;
    int first = r->stats.frames_total == 0;
    sw_stats_add_frame(&r->stats, ms, (uint32_t)fmin(out.triangles, 4294967295.0), out.drawn);
    if (first)
        r->stats.first_frame_ms = ms;
}

static void walk(wb_run *r)
{
    sw_stats *s = &r->stats;
    sw_rss rss;
    sw_rss_read(&rss);
    s->rss_start_kb = rss.rss_kb;
    double t0 = now_s();
    for (int f = 0; f < r->opt.frames; f += r->opt.every) {
        if (r->opt.max_s > 0 && now_s() - t0 > r->opt.max_s) {
            r->stopped_early = 1;
            break;
        }
        run_frame(r, f, (int)(r->frames_run % (uint32_t)r->opt.measure_every) == 0);
        r->frames_run++;
    }
    s->walk_s = now_s() - t0;
    sw_rss_read(&rss);
    s->rss_end_kb = rss.rss_kb;
    s->rss_peak_kb = rss.peak_kb;
}

static int write_stats(wb_run *r, sw_error *err)
{
    sw_stats *s = &r->stats;
    s->patches_total = r->pack.meta->patch_count;
    s->measure_every = r->opt.measure_every;
    s->arena_bytes = r->arena.size;
    s->arena_peak_bytes = r->arena.peak;
    s->runtime_bytes = r->pack.header->runtime_bytes;
    s->width = r->opt.width, s->height = r->opt.height;
    s->depth_bits = r->egl.depth_bits;
    if (!r->opt.stats_path)
        return 1;
    FILE *f = fopen(r->opt.stats_path, "w");
    if (!f)
        return sw_error_set(err, SW_ERR_IO, "%s: %s", r->opt.stats_path, strerror(errno)), 0;
    sw_status st = sw_stats_write_json(s, f, &r->arena, err);
    return (fclose(f) == 0) & (st == SW_OK);
}

int main(int argc, char **argv)
{
    static wb_run r;
    char why[256];
    if (!parse(argc, argv, &r.opt, why, sizeof why))
        return usage(why);
    sw_error err = { SW_OK, "" };
    int ok = start(&r, &err);
    if (ok) {
        walk(&r);
        ok = write_stats(&r, &err);
    }
    if (ok)
        printf("walk_baseline: mode=%s segments=%u tolerance_px=%g frames_run=%u every=%d "
               "stopped_early=%d glu_skipped_surfaces=%u failed_surfaces_max=%u walk_s=%.3f\n",
               r.opt.glu ? "glu" : "uniform", r.opt.segments, r.opt.tolerance_px, r.frames_run,
               r.opt.every, r.stopped_early, r.glu_skipped, r.failed_max, r.stats.walk_s);
    wb_glu_free(&r.walk);
    free(r.walk.patches), free(r.walk.surface_first), free(r.sew_offset);
    free(r.walk.batch.verts), free(r.walk.batch.uvs), free(r.walk.batch.indices);
    free(r.keys), free(r.block), free(r.placed_block);
    if (r.renderer_up)
        sw_renderer_destroy(&r.renderer);
    if (r.egl_up)
        sw_egl_headless_destroy(&r.egl);
    return ok ? 0 : fail("failed", &err);
}
