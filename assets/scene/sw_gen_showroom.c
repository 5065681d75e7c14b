/* SPDX-License-Identifier: MIT */
/* The showroom generator (sw_gen_showroom.h): plan the objects, lay them
 * out, print the scene. Planning uses the same counts the build will see: a
 * part file is imported once, a procedural object announces its count. */
#define _XOPEN_SOURCE 700 /* realpath */
#include "sw_gen_showroom.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sw_model.h"
#include "sw_pack_write.h"
#include "sw_procedural.h"
#include "sw_scene.h"
#include "sw_up_axis.h"
#include "sw_up_inputs.h"

/* Floor grid (millimetres): cells of one object, blocks of cells, aisles. */
#define CELL_MM 2000.0
#define BLOCK_CELLS 4
#define AISLE_MM 3000.0
#define FOOTPRINT_MM 1200.0   /* part-file copies are scaled to this width */
/* Longest absolute path that still fits a scene line ("file = " + path). */
#define MAX_SCENE_PATH 180

typedef struct gen_file {
    char path[PATH_MAX];      /* absolute */
    char stem[33];            /* base name without extension, safe in a section name */
    size_t patches;
    sw_box box;               /* as placed: stood up when stand_up */
    int stand_up;             /* a z-up file (STEP, IGES): +z turned to the showroom's +y */
    size_t copies;
} gen_file;

typedef struct gen_item {
    int file;                 /* index into the files, or -1: procedural */
    sw_proc_params proc;
    size_t patches;
    int yaw_quarters;         /* rotation about +y, in quarter turns */
    float color[4];
} gen_item;

typedef struct gen_plan {
    gen_file *files;
    size_t file_count;
    gen_item *items;
    size_t item_count, item_capacity;
    uint64_t rng;
    uint64_t seed;
    size_t catalog;           /* designs per kind of object; 0: each object its own */
} gen_plan;

/* ---- random numbers ----------------------------------------------------- */

static uint64_t rng_next(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* A whole number in lo..hi. */
static int rng_int(uint64_t *state, int lo, int hi)
{
    return lo + (int)(rng_next(state) % (uint64_t)(hi - lo + 1));
}

/* A value in lo..hi rounded to 0.1 mm, so the scene text says it exactly. */
static double rng_mm(uint64_t *state, double lo, double hi)
{
    double unit = (double)(rng_next(state) >> 11) * 0x1.0p-53;
    return round((lo + (hi - lo) * unit) * 10.0) / 10.0;
}

/* ---- part files --------------------------------------------------------- */

/* The file's base name without extension, with anything but [A-Za-z0-9_-]
 * replaced, so it can name a section. */
static void file_stem(const char *path, char stem[33])
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const char *dot = strrchr(base, '.');
    size_t len = dot && dot != base ? (size_t)(dot - base) : strlen(base);
    if (len > 32)
        len = 32;
    for (size_t i = 0; i < len; i++) {
        char c = base[i];
        int ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                 c == '_' || c == '-';
        stem[i] = ok ? c : '_';
    }
    stem[len] = '\0';
}

/* inih would cut a value at " ;" and strip blanks around it. */
static int path_fits_a_scene(const char *path)
{
    size_t len = strlen(path);
    return len > 0 && len <= MAX_SCENE_PATH && !strpbrk(path, ";\n\r\t") && path[0] != ' ' &&
           path[len - 1] != ' ';
}

/* Imports the file once: its patch count and box. */
static sw_status measure_file(const char *path, gen_file *file, sw_error *err)
{
    if (!realpath(path, file->path))
        return sw_error_set(err, SW_ERR_IO, "%s: %s", path, strerror(errno));
    if (!path_fits_a_scene(file->path))
        return sw_error_set(err, SW_ERR_ARG,
                            "%s: the absolute path must be at most %d bytes without ';' or "
                            "blanks at its ends to go into a scene",
                            file->path, MAX_SCENE_PATH);
    file_stem(file->path, file->stem);
    sw_model m;
    sw_model_init(&m);
    sw_status st = sw_model_begin_part(&m, file->stem, NULL, err);
    if (st == SW_OK)
        st = sw_scene_import_file(file->path, &m, err);
    file->patches = m.patch_count;
    file->box = sw_model_box(&m);
    sw_model_free(&m);
    file->stand_up = sw_up_input_default(file->path, 0) == SW_UP_POS_Z;
    if (file->stand_up) /* x by -90 degrees: (x, y, z) -> (x, z, -y) */
        file->box = (sw_box){ sw_v3(file->box.min.x, file->box.min.z, -file->box.max.y),
                              sw_v3(file->box.max.x, file->box.max.z, -file->box.min.y) };
    if (st == SW_OK && file->patches == 0)
        st = sw_error_set(err, SW_ERR_FORMAT, "%s: no patches", file->path);
    return st;
}

/* ---- planning ----------------------------------------------------------- */

static sw_status push_item(gen_plan *plan, const gen_item *item, sw_error *err)
{
    if (plan->item_count == plan->item_capacity) {
        size_t cap = plan->item_capacity ? 2 * plan->item_capacity : 256;
        gen_item *bigger = realloc(plan->items, cap * sizeof *bigger);
        if (!bigger)
            return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory planning %zu objects", cap);
        plan->items = bigger;
        plan->item_capacity = cap;
    }
    plan->items[plan->item_count++] = *item;
    return SW_OK;
}

/* A procedural object of a kind with seeded proportions that fit a cell;
 * from a catalog, one of its designs (the same proportions and seed each
 * time a design is drawn: a showroom's repeated products). */
static gen_item random_object(gen_plan *plan, sw_proc_kind kind)
{
    uint64_t design_rng, *r = &plan->rng;
    if (plan->catalog > 0) {
        uint64_t design = (uint64_t)rng_int(r, 0, (int)plan->catalog - 1);
        design_rng = plan->seed ^ (0x51A7E0000ull + (uint64_t)kind * 0x10000ull + design);
        r = &design_rng;
    }
    gen_item item = {.file = -1, .proc = sw_proc_defaults(kind)};
    sw_proc_params *p = &item.proc;
    if (kind == SW_PROC_PLATE) {
        p->size_mm = rng_mm(r, 600, 1400);
        p->height_mm = rng_int(r, 0, 1) ? rng_mm(r, 400, 900) : 0.0;
        p->holes = rng_int(r, 0, 9);
        p->segments = rng_int(r, 3, 8);
    } else if (kind == SW_PROC_VASE) {
        p->size_mm = rng_mm(r, 200, 600);
        p->height_mm = rng_mm(r, 300, 1400);
        p->segments = rng_int(r, 4, 12);
    } else {
        p->size_mm = rng_mm(r, 1000, 1700);
        p->height_mm = rng_mm(r, 60, 200);
        p->holes = rng_int(r, 0, 4);
        p->segments = rng_int(r, 8, 24);
    }
    p->seed = rng_next(r);
    item.patches = sw_proc_patch_count(p);
    return item;
}

/* The next object of the rotation: each file, then plate, vase and rail. */
static gen_item next_object(gen_plan *plan, size_t turn)
{
    size_t slot = turn % (plan->file_count + 3);
    if (slot < plan->file_count)
        return (gen_item){.file = (int)slot, .patches = plan->files[slot].patches};
    return random_object(plan, (sw_proc_kind)(SW_PROC_PLATE + (int)(slot - plan->file_count)));
}

/* Plates of k x k patches (k up to the maximum) use up the rest exactly:
 * after each, what is left is less than 2k + 1. */
static sw_status fill_with_plates(gen_plan *plan, size_t remaining, sw_error *err)
{
    sw_status st = SW_OK;
    while (st == SW_OK && remaining > 0) {
        gen_item item = random_object(plan, SW_PROC_PLATE);
        int k = 1;
        while (k < SW_PROC_MAX_SEGMENTS && (size_t)(k + 1) * (size_t)(k + 1) <= remaining)
            k++;
        item.proc.segments = k;
        item.patches = sw_proc_patch_count(&item.proc);
        remaining -= item.patches;
        st = push_item(plan, &item, err);
    }
    return st;
}

static sw_status plan_objects(gen_plan *plan, size_t target, sw_error *err)
{
    size_t remaining = target, misses = 0, menu = plan->file_count + 3;
    for (size_t turn = 0; remaining > 0 && misses < menu; turn++) {
        gen_item item = next_object(plan, turn);
        if (item.patches > remaining) {
            misses++;
            continue;
        }
        misses = 0;
        remaining -= item.patches;
        if (item.file >= 0)
            plan->files[item.file].copies++;
        sw_status st = push_item(plan, &item, err);
        if (st != SW_OK)
            return st;
    }
    return fill_with_plates(plan, remaining, err);
}

/* Yaw and colour, drawn after the objects so that adding a kind of decoration
 * does not change which objects a seed gives. */
static void decorate(gen_plan *plan)
{
    for (size_t i = 0; i < plan->item_count; i++) {
        gen_item *item = &plan->items[i];
        item->yaw_quarters = rng_int(&plan->rng, 0, 3);
        size_t c = item->file >= 0 ? (size_t)item->file : (size_t)rng_int(&plan->rng, 0, 5);
        sw_scene_default_color(c, item->color);
    }
}

/* ---- layout ------------------------------------------------------------- */

typedef struct gen_layout {
    size_t cols;                  /* blocks per row (along x) */
    double width_mm, depth_mm;
} gen_layout;

static double extent(size_t blocks)
{
    return (double)blocks * BLOCK_CELLS * CELL_MM + (double)(blocks - 1) * AISLE_MM;
}

static gen_layout plan_layout(size_t items)
{
    size_t per_block = BLOCK_CELLS * BLOCK_CELLS;
    size_t blocks = (items + per_block - 1) / per_block, cols = 1;
    while (cols * cols < blocks)
        cols++;
    size_t rows = (blocks + cols - 1) / cols;
    return (gen_layout){.cols = cols, .width_mm = extent(cols), .depth_mm = extent(rows)};
}

/* The floor point under the centre of item i's cell. */
static sw_vec3 cell_centre(const gen_layout *l, size_t i)
{
    size_t per_block = BLOCK_CELLS * BLOCK_CELLS, block = i / per_block, cell = i % per_block;
    double pitch = BLOCK_CELLS * CELL_MM + AISLE_MM;
    double x = (double)(block % l->cols) * pitch + (double)(cell % BLOCK_CELLS) * CELL_MM;
    double z = (double)(block / l->cols) * pitch + (double)(cell / BLOCK_CELLS) * CELL_MM;
    return sw_v3(x + 0.5 * CELL_MM - 0.5 * l->width_mm, 0.0, z + 0.5 * CELL_MM - 0.5 * l->depth_mm);
}

/* ---- scene text --------------------------------------------------------- */

typedef struct gen_text {
    char *buf;
    size_t len, cap;
    int failed;
} gen_text;

static void text_printf(gen_text *t, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void text_printf(gen_text *t, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = t->failed ? -1 : vsnprintf(t->buf ? t->buf + t->len : NULL,
                                       t->buf ? t->cap - t->len : 0, fmt, ap);
    va_end(ap);
    if (n < 0) {
        t->failed = 1;
        return;
    }
    if (t->len + (size_t)n + 1 > t->cap) {
        size_t cap = t->cap ? t->cap : 1 << 16;
        while (cap < t->len + (size_t)n + 1)
            cap *= 2;
        char *bigger = realloc(t->buf, cap);
        if (!bigger) {
            t->failed = 1;
            return;
        }
        t->buf = bigger;
        t->cap = cap;
        va_start(ap, fmt);
        vsnprintf(t->buf + t->len, t->cap - t->len, fmt, ap);
        va_end(ap);
    }
    t->len += (size_t)n;
}

static const double quarter_cos[4] = {1, 0, -1, 0}, quarter_sin[4] = {0, 1, 0, -1};

/* The turn about y by yaw_quarters after standing a z-up part up (x by -90
 * degrees), as the one axis and angle a scene's rotate takes: the quaternion
 * (cos h, 0, sin h, 0) (cos 45, -sin 45, 0, 0), h half the yaw. */
static void write_stand_up_rotate(gen_text *t, int yaw_quarters)
{
    double h = 0.25 * SW_PI * yaw_quarters, r = sqrt(0.5);
    double w = cos(h) * r, v[3] = { -cos(h) * r, sin(h) * r, sin(h) * r };
    text_printf(t, "rotate = %.12g %.12g %.12g %.12g\n", v[0], v[1], v[2],
                2 * acos(w) * 180 / SW_PI);
}

/* A copy of a part file: scaled to the footprint, turned, its box centred on
 * the cell and its lowest point on the floor. Scene order: scale, rotate,
 * translate, so the translation undoes the turned, scaled box centre. */
static void write_file_part(gen_text *t, const gen_file *f, const gen_item *item, sw_vec3 cell)
{
    sw_vec3 size = sw_v3_sub(f->box.max, f->box.min), c = sw_box_center(&f->box);
    double wide = fmax(size.x, size.z);
    if (!(wide > 0.0))
        wide = fmax(size.y, 1e-9);
    double s = FOOTPRINT_MM / wide, co = quarter_cos[item->yaw_quarters],
           si = quarter_sin[item->yaw_quarters];
    double x = s * (c.x * co + c.z * si), z = s * (-c.x * si + c.z * co);
    text_printf(t, "file = %s\nscale = %.9g\n", f->path, s);
    if (f->stand_up)
        write_stand_up_rotate(t, item->yaw_quarters);
    else if (item->yaw_quarters)
        text_printf(t, "rotate = 0 1 0 %d\n", 90 * item->yaw_quarters);
    text_printf(t, "translate = %.6f %.6f %.6f\n", cell.x - x, -s * f->box.min.y, cell.z - z);
}

static void write_generated_part(gen_text *t, const gen_item *item, sw_vec3 cell)
{
    const sw_proc_params *p = &item->proc;
    unsigned used = sw_proc_params_used(p->kind);
    text_printf(t, "generate = %s\nsize = %.1f\nheight = %.1f\n", sw_proc_kind_name(p->kind),
                p->size_mm, p->height_mm);
    if (used & SW_PROC_USES_HOLES)
        text_printf(t, "holes = %d\n", p->holes);
    text_printf(t, "segments = %d\nseed = %llu\n", p->segments, (unsigned long long)p->seed);
    if (item->yaw_quarters)
        text_printf(t, "rotate = 0 1 0 %d\n", 90 * item->yaw_quarters);
    text_printf(t, "translate = %.1f 0 %.1f\n", cell.x, cell.z);
}

static void write_parts(gen_text *t, const gen_plan *plan, const gen_layout *l)
{
    for (size_t i = 0; i < plan->item_count; i++) {
        const gen_item *item = &plan->items[i];
        const char *stem =
            item->file >= 0 ? plan->files[item->file].stem : sw_proc_kind_name(item->proc.kind);
        text_printf(t, "\n[part %s_%05zu]\n", stem, i + 1);
        if (item->file >= 0)
            write_file_part(t, &plan->files[item->file], item, cell_centre(l, i));
        else
            write_generated_part(t, item, cell_centre(l, i));
        text_printf(t, "color = %.2f %.2f %.2f\n", item->color[0], item->color[1],
                    item->color[2]);
    }
}

static void write_view(gen_text *t, const char *name, sw_vec3 eye, sw_vec3 target, int fov)
{
    text_printf(t, "\n[view %s]\neye = %.1f %.1f %.1f\ntarget = %.1f %.1f %.1f\nfov = %d\n", name,
                eye.x, eye.y, eye.z, target.x, target.y, target.z, fov);
}

/* At the entrance (the -z side) at eye height looking in; high over the
 * front left corner looking at the centre; close to the first object. */
static void write_views(gen_text *t, const gen_layout *l)
{
    double w = l->width_mm, d = l->depth_mm, big = fmax(w, d);
    write_view(t, "entrance", sw_v3(0, 1700, -0.5 * d - 3000), sw_v3(0, 1000, -0.5 * d + 4000), 60);
    write_view(t, "overview", sw_v3(-0.5 * w - 2000, 0.6 * big + 3000, -0.5 * d - 2000),
               sw_v3(0, 0, 0), 50);
    sw_vec3 c = cell_centre(l, 0);
    write_view(t, "closeup", sw_v3_add(c, sw_v3(1300, 1300, -2200)),
               sw_v3_add(c, sw_v3(0, 400, 0)), 45);
}

static void write_header(gen_text *t, const sw_gen_showroom_desc *desc, const gen_plan *plan,
                         const gen_layout *l, size_t file_parts)
{
    text_printf(t,
                "; A showroom written by `seamwalk-pack gen showroom --patches %zu --seed %llu`.\n"
                "; %zu parts (%zu copies of %zu part files, the rest generated), %zu Bezier\n"
                "; patches when built. Floor %.0f x %.0f mm: %.0f mm cells in blocks of %d x %d,\n"
                "; %.0f mm aisles; millimetres, y up, the entrance on the -z side.\n"
                "; Build: seamwalk-pack build THIS.ini -o showroom.swpack\n",
                desc->patches, (unsigned long long)desc->seed, plan->item_count, file_parts,
                plan->file_count, desc->patches, l->width_mm, l->depth_mm, CELL_MM, BLOCK_CELLS,
                BLOCK_CELLS, AISLE_MM);
}

static sw_status measure_files(const sw_gen_showroom_desc *desc, gen_plan *plan, sw_error *err)
{
    if (desc->part_file_count == 0)
        return SW_OK;
    plan->files = calloc(desc->part_file_count, sizeof *plan->files);
    if (!plan->files)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory for %zu part files",
                            desc->part_file_count);
    plan->file_count = desc->part_file_count;
    for (size_t i = 0; i < plan->file_count; i++) {
        sw_status st = measure_file(desc->part_files[i], &plan->files[i], err);
        if (st != SW_OK)
            return st;
    }
    return SW_OK;
}

sw_status sw_gen_showroom_scene(const sw_gen_showroom_desc *desc, char **text,
                                sw_gen_showroom_result *result, sw_error *err)
{
    if (!desc || !text || (desc->part_file_count && !desc->part_files))
        return sw_error_set(err, SW_ERR_ARG, "sw_gen_showroom_scene: NULL argument");
    *text = NULL;
    if (desc->patches < 1 || desc->patches > SW_GEN_MAX_PATCHES)
        return sw_error_set(err, SW_ERR_RANGE, "--patches %zu outside 1..%zu", desc->patches,
                            SW_GEN_MAX_PATCHES);
    gen_plan plan = {.rng = desc->seed, .seed = desc->seed, .catalog = desc->catalog};
    sw_status st = measure_files(desc, &plan, err);
    if (st == SW_OK)
        st = plan_objects(&plan, desc->patches, err);
    gen_text t = {0};
    if (st == SW_OK) {
        decorate(&plan);
        gen_layout l = plan_layout(plan.item_count);
        size_t file_parts = 0;
        for (size_t i = 0; i < plan.file_count; i++)
            file_parts += plan.files[i].copies;
        write_header(&t, desc, &plan, &l, file_parts);
        write_views(&t, &l);
        write_parts(&t, &plan, &l);
        if (t.failed)
            st = sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory writing the scene");
        if (st == SW_OK && result)
            *result = (sw_gen_showroom_result){desc->patches, plan.item_count, file_parts,
                                               l.width_mm, l.depth_mm};
    }
    if (st == SW_OK)
        *text = t.buf;
    else
        free(t.buf);
    free(plan.files);
    free(plan.items);
    return st;
}

/* ---- the command -------------------------------------------------------- */

static int gen_usage_error(const char *fmt, const char *arg)
{
    char what[SW_ERROR_MESSAGE_MAX];
    snprintf(what, sizeof what, fmt, arg);
    return sw_usage_error("seamwalk-pack", "gen: %s", what);
}

/* A whole decimal number up to max, all of arg. */
static int parse_count(const char *arg, unsigned long long max, unsigned long long *out)
{
    char *end;
    errno = 0;
    unsigned long long v = arg[0] >= '0' && arg[0] <= '9' ? strtoull(arg, &end, 10) : 0;
    if (arg[0] < '0' || arg[0] > '9' || *end != '\0' || errno == ERANGE || v > max)
        return 0;
    *out = v;
    return 1;
}

typedef struct gen_args {
    sw_gen_showroom_desc desc;
    const char *out_path;
    const char **files;
} gen_args;

/* Returns 0 when the arguments are good, else the usage error's status. */
static int parse_gen_args(int argc, char **argv, gen_args *a)
{
    if (argc < 1 || strcmp(argv[0], "showroom") != 0)
        return gen_usage_error("expected 'showroom', found '%s'", argc < 1 ? "" : argv[0]);
    int have_patches = 0;
    for (int i = 1; i < argc; i++) {
        const char *opt = argv[i];
        int known = !strcmp(opt, "--patches") || !strcmp(opt, "-o") || !strcmp(opt, "--part") ||
                    !strcmp(opt, "--seed") || !strcmp(opt, "--catalog");
        if (!known)
            return gen_usage_error("unknown argument '%s'", opt);
        if (i + 1 == argc)
            return gen_usage_error("%s needs a value", opt);
        const char *val = argv[++i];
        unsigned long long v = 0;
        if (!strcmp(opt, "--patches")) {
            if (have_patches++ || !parse_count(val, SW_GEN_MAX_PATCHES, &v) || v == 0)
                return gen_usage_error("--patches: expected one count in 1..10000000, found '%s'", val);
            a->desc.patches = (size_t)v;
        } else if (!strcmp(opt, "--seed")) {
            if (!parse_count(val, UINT64_MAX, &v))
                return gen_usage_error("--seed: expected a whole number, found '%s'", val);
            a->desc.seed = v;
        } else if (!strcmp(opt, "--catalog")) {
            if (!parse_count(val, SW_GEN_MAX_CATALOG, &v))
                return gen_usage_error("--catalog: expected a count in 0..1000, found '%s'", val);
            a->desc.catalog = (size_t)v;
        } else if (!strcmp(opt, "-o")) {
            if (a->out_path)
                return gen_usage_error("%s given twice", "-o");
            a->out_path = val;
        } else {
            a->files[a->desc.part_file_count++] = val;
        }
    }
    if (!have_patches || !a->out_path)
        return gen_usage_error("missing %s", !have_patches ? "--patches N" : "-o SCENE.ini");
    return 0;
}

int sw_pack_cmd_gen(int argc, char **argv)
{
    gen_args a = {.desc = {.seed = 1}};
    a.files = calloc((size_t)(argc > 0 ? argc : 1), sizeof *a.files);
    if (!a.files) {
        fputs("seamwalk-pack: gen: out of memory\n", stderr);
        return 1;
    }
    a.desc.part_files = a.files;
    int rc = parse_gen_args(argc, argv, &a);
    if (rc) {
        free(a.files);
        return rc;
    }
    char *text = NULL;
    sw_gen_showroom_result r;
    sw_error err = {0};
    sw_status st = sw_gen_showroom_scene(&a.desc, &text, &r, &err);
    if (st == SW_OK)
        st = sw_write_file_atomic(a.out_path, (const uint8_t *)text, strlen(text), &err);
    free(text);
    free(a.files);
    if (st != SW_OK) {
        fprintf(stderr, "seamwalk-pack: gen: %s\n", err.message);
        return 1;
    }
    printf("seamwalk-pack: showroom of %zu parts (%zu copies of part files), %zu patches, "
           "floor %.0f x %.0f mm -> %s\n",
           r.parts, r.file_parts, r.patches, r.width_mm, r.depth_mm, a.out_path);
    return 0;
}
