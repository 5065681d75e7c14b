/* SPDX-License-Identifier: MIT */
/* Sections and keys of showroom scenes (the format is in sw_scene.h): what
 * each key accepts, and the checks that need a whole section (required keys,
 * keys that exclude each other, generator parameters that depend on the
 * kind). Every message names file:line of the key, or of the section header
 * when something is missing. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "sw_scene.h"
#include "sw_scene_internal.h"
#include "sw_up_axis.h"

/* ---- values ------------------------------------------------------------- */

/* Parses between min and max whitespace-separated finite numbers from value. */
static int parse_numbers(scene_state *st, const char *key, const char *value, double *out,
                         int min, int max, int *count)
{
    const char *p = value;
    int n = 0;
    for (;;) {
        p += strspn(p, " \t");
        if (*p == '\0')
            break;
        size_t len = strcspn(p, " \t");
        char *stop;
        double v = strtod(p, &stop);
        if (stop != p + len || !isfinite(v))
            return scene_fail(st, SW_ERR_FORMAT, "%s: '%.*s' is not a finite number", key,
                              (int)(len > 32 ? 32 : len), p);
        if (n == max)
            return scene_fail(st, SW_ERR_FORMAT, "%s: expected at most %d numbers", key, max);
        out[n++] = v;
        p += len;
    }
    if (n < min)
        return scene_fail(st, SW_ERR_FORMAT, "%s: expected %s%d numbers, found %d", key,
                          min == max ? "" : "at least ", min, n);
    *count = n;
    return 1;
}

static int parse_vec3(scene_state *st, const char *key, const char *value, double out[3])
{
    int n;
    return parse_numbers(st, key, value, out, 3, 3, &n);
}

/* One unsigned decimal integer up to max (no sign, no blanks inside). */
static int parse_uint(scene_state *st, const char *key, const char *value,
                      unsigned long long max, unsigned long long *out)
{
    const char *p = value + strspn(value, " \t");
    size_t len = strcspn(p, " \t");
    char *stop;
    errno = 0;
    unsigned long long v = len && *p >= '0' && *p <= '9' ? strtoull(p, &stop, 10) : 0;
    if (!len || *p < '0' || *p > '9' || stop != p + len || p[len + strspn(p + len, " \t")])
        return scene_fail(st, SW_ERR_FORMAT, "%s: expected a whole number, found '%.32s'", key,
                          value);
    if (errno == ERANGE || v > max)
        return scene_fail(st, SW_ERR_RANGE, "%s: %.32s is larger than %llu", key, p, max);
    *out = v;
    return 1;
}

/* ---- part keys ---------------------------------------------------------- */

static int key_file(scene_state *st, scene_part *part, const char *value)
{
    size_t len = strlen(value);
    if (len == 0)
        return scene_fail(st, SW_ERR_FORMAT, "file: expected a file name");
    if (len >= sizeof part->file)
        return scene_fail(st, SW_ERR_FORMAT, "file: name longer than %zu bytes",
                          sizeof part->file - 1);
    memcpy(part->file, value, len + 1);
    return 1;
}

static int key_generate(scene_state *st, scene_part *part, const char *value)
{
    if (!sw_proc_kind_from_name(value, &part->proc.kind))
        return scene_fail(st, SW_ERR_FORMAT,
                          "generate: unknown kind '%.32s' (expected plate, vase or rail)", value);
    return 1;
}

static int key_translate(scene_state *st, scene_part *part, const char *value)
{
    return parse_vec3(st, "translate", value, part->translate);
}

static int key_rotate(scene_state *st, scene_part *part, const char *value)
{
    double v[4];
    int n;
    if (!parse_numbers(st, "rotate", value, v, 4, 4, &n))
        return 0;
    if (v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0)
        return scene_fail(st, SW_ERR_RANGE, "rotate: the axis must not be zero");
    memcpy(part->axis, v, sizeof part->axis);
    part->angle_deg = v[3];
    return 1;
}

static int key_scale(scene_state *st, scene_part *part, const char *value)
{
    double v[3];
    int n;
    if (!parse_numbers(st, "scale", value, v, 1, 3, &n))
        return 0;
    if (n == 2)
        return scene_fail(st, SW_ERR_FORMAT, "scale: expected 1 or 3 numbers, found 2");
    for (int k = 0; k < 3; k++) {
        part->scale[k] = v[n == 1 ? 0 : k];
        if (part->scale[k] == 0.0)
            return scene_fail(st, SW_ERR_RANGE, "scale: factors must not be zero");
    }
    return 1;
}

static int key_color(scene_state *st, scene_part *part, const char *value)
{
    double v[4] = {0, 0, 0, 1};
    int n;
    if (!parse_numbers(st, "color", value, v, 3, 4, &n))
        return 0;
    for (int k = 0; k < 4; k++) {
        if (v[k] < 0.0 || v[k] > 1.0)
            return scene_fail(st, SW_ERR_RANGE, "color: %g is outside 0..1", v[k]);
        part->color[k] = (float)v[k];
    }
    return 1;
}

/* Millimetres per unit; exact where the definition is (1 in = 25.4 mm). */
static const struct {
    const char *name;
    double mm;
} units[] = {{"mm", 1.0}, {"cm", 10.0}, {"m", 1000.0}, {"in", 25.4}, {"ft", 304.8}};

static int key_units(scene_state *st, scene_part *part, const char *value)
{
    for (size_t k = 0; k < sizeof units / sizeof units[0]; k++) {
        if (strcmp(value, units[k].name) == 0) {
            part->units_to_mm = units[k].mm;
            return 1;
        }
    }
    return scene_fail(st, SW_ERR_FORMAT, "units: unknown unit '%.32s' (expected mm, cm, m, in or ft)",
                      value);
}

static int key_size(scene_state *st, scene_part *part, const char *value)
{
    int n;
    return parse_numbers(st, "size", value, &part->proc.size_mm, 1, 1, &n);
}

static int key_height(scene_state *st, scene_part *part, const char *value)
{
    int n;
    return parse_numbers(st, "height", value, &part->proc.height_mm, 1, 1, &n);
}

/* Counts are range-checked per kind later; here only "a small whole number". */
static int key_holes(scene_state *st, scene_part *part, const char *value)
{
    unsigned long long v = 0;
    if (!parse_uint(st, "holes", value, 1000000, &v))
        return 0;
    part->proc.holes = (int)v;
    return 1;
}

static int key_segments(scene_state *st, scene_part *part, const char *value)
{
    unsigned long long v = 0;
    if (!parse_uint(st, "segments", value, 1000000, &v))
        return 0;
    part->proc.segments = (int)v;
    return 1;
}

static int key_seed(scene_state *st, scene_part *part, const char *value)
{
    unsigned long long v = 0;
    if (!parse_uint(st, "seed", value, UINT64_MAX, &v))
        return 0;
    part->proc.seed = v;
    return 1;
}

typedef struct part_key_def {
    const char *name;
    int (*parse)(scene_state *st, scene_part *part, const char *value);
} part_key_def;

/* Indexed by enum scene_part_key. */
static const part_key_def part_keys[PK_COUNT] = {
    [PK_FILE] = {"file", key_file},           [PK_GENERATE] = {"generate", key_generate},
    [PK_TRANSLATE] = {"translate", key_translate}, [PK_ROTATE] = {"rotate", key_rotate},
    [PK_SCALE] = {"scale", key_scale},        [PK_COLOR] = {"color", key_color},
    [PK_UNITS] = {"units", key_units},        [PK_SIZE] = {"size", key_size},
    [PK_HEIGHT] = {"height", key_height},     [PK_HOLES] = {"holes", key_holes},
    [PK_SEGMENTS] = {"segments", key_segments}, [PK_SEED] = {"seed", key_seed},
};

static int part_key(scene_state *st, const char *name, const char *value)
{
    scene_part *part = &st->parts[st->part_count - 1];
    for (int k = 0; k < PK_COUNT; k++) {
        if (strcmp(name, part_keys[k].name) != 0)
            continue;
        if (part->key_line[k])
            return scene_fail(st, SW_ERR_FORMAT, "key '%s' given twice in part '%s' (first at line %ld)",
                              name, part->name, part->key_line[k]);
        part->key_line[k] = st->line;
        return part_keys[k].parse(st, part, value);
    }
    return scene_fail(st, SW_ERR_FORMAT,
                      "unknown key '%s' in part '%s' (expected file or generate, translate, "
                      "rotate, scale, color, units, size, height, holes, segments, seed)",
                      name, part->name);
}

/* ---- view keys ---------------------------------------------------------- */

static int key_eye(scene_state *st, scene_view *view, const char *value)
{
    return parse_vec3(st, "eye", value, view->eye);
}

static int key_target(scene_state *st, scene_view *view, const char *value)
{
    return parse_vec3(st, "target", value, view->target);
}

static int key_up(scene_state *st, scene_view *view, const char *value)
{
    if (!parse_vec3(st, "up", value, view->up))
        return 0;
    if (view->up[0] == 0.0 && view->up[1] == 0.0 && view->up[2] == 0.0)
        return scene_fail(st, SW_ERR_RANGE, "up: the vector must not be zero");
    return 1;
}

static int key_fov(scene_state *st, scene_view *view, const char *value)
{
    int n;
    if (!parse_numbers(st, "fov", value, &view->fov_deg, 1, 1, &n))
        return 0;
    if (!(view->fov_deg > 0.0 && view->fov_deg < 180.0))
        return scene_fail(st, SW_ERR_RANGE, "fov: %g degrees, expected more than 0 and less than 180",
                          view->fov_deg);
    return 1;
}

static const struct {
    const char *name;
    int (*parse)(scene_state *st, scene_view *view, const char *value);
} view_keys[VK_COUNT] = {
    [VK_EYE] = {"eye", key_eye},
    [VK_TARGET] = {"target", key_target},
    [VK_UP] = {"up", key_up},
    [VK_FOV] = {"fov", key_fov},
};

static int view_key(scene_state *st, const char *name, const char *value)
{
    scene_view *view = &st->views[st->view_count - 1];
    for (int k = 0; k < VK_COUNT; k++) {
        if (strcmp(name, view_keys[k].name) != 0)
            continue;
        if (view->key_line[k])
            return scene_fail(st, SW_ERR_FORMAT, "key '%s' given twice in view '%s' (first at line %ld)",
                              name, view->name, view->key_line[k]);
        view->key_line[k] = st->line;
        return view_keys[k].parse(st, view, value);
    }
    return scene_fail(st, SW_ERR_FORMAT,
                      "unknown key '%s' in view '%s' (expected eye, target, up or fov)", name,
                      view->name);
}

/* ---- keys before the first section -------------------------------------- */

/* up_axis: which model axis points up. A key of the whole scene, so it
 * stands before the first section; [view] keeps `up`, the camera's. */
int scene_top_key(scene_state *st, const char *name, const char *value)
{
    if (strcmp(name, "up_axis") != 0)
        return scene_fail(st, SW_ERR_FORMAT, "key '%s' outside any section (only up_axis may "
                          "come before the first section)", name);
    if (st->up_axis_line)
        return scene_fail(st, SW_ERR_FORMAT, "key 'up_axis' given twice (first at line %ld)",
                          st->up_axis_line);
    if (!sw_up_axis_parse(value, &st->up_axis))
        return scene_fail(st, SW_ERR_FORMAT, "up_axis: '%.32s', expected x, y, z, -x, -y or -z",
                          value);
    st->up_axis_line = st->line;
    return 1;
}

/* ---- sections ----------------------------------------------------------- */

/* Checks a section's name (trailing blanks dropped); *len is its length. */
static int check_name(scene_state *st, const char *kind, const char *name, size_t *len)
{
    size_t n = strlen(name);
    while (n > 0 && (name[n - 1] == ' ' || name[n - 1] == '\t'))
        n--;
    if (n == 0)
        return section_fail(st, SW_ERR_FORMAT, "expected [%s NAME], found no name", kind);
    if (n > SCENE_NAME_MAX)
        return section_fail(st, SW_ERR_FORMAT, "%s name longer than %d bytes", kind,
                            SCENE_NAME_MAX);
    *len = n;
    return 1;
}

static int same_name(const char *a, const char *b, size_t b_len)
{
    return strlen(a) == b_len && memcmp(a, b, b_len) == 0;
}

/* Makes room for one more element; 0 after recording the error. */
static int grow(scene_state *st, void **array, size_t *capacity, size_t count, size_t size)
{
    if (count < *capacity)
        return 1;
    size_t cap = *capacity ? *capacity * 2 : 8;
    void *bigger = realloc(*array, cap * size);
    if (!bigger)
        return section_fail(st, SW_ERR_NO_MEMORY, "out of memory for %zu sections", cap);
    *array = bigger;
    *capacity = cap;
    return 1;
}

static int begin_part(scene_state *st, const char *name)
{
    size_t len = 0;
    if (!check_name(st, "part", name, &len))
        return 0;
    for (size_t i = 0; i < st->part_count; i++) {
        if (same_name(st->parts[i].name, name, len))
            return section_fail(st, SW_ERR_FORMAT, "part '%.*s' already defined at line %ld",
                                (int)len, name, st->parts[i].line);
    }
    void *parts = st->parts;
    int ok = grow(st, &parts, &st->part_capacity, st->part_count, sizeof *st->parts);
    st->parts = parts;
    if (!ok)
        return 0;
    scene_part *part = &st->parts[st->part_count++];
    *part = (scene_part){.line = st->pending_section, .scale = {1, 1, 1}, .axis = {0, 1, 0},
                         .units_to_mm = 1.0};
    memcpy(part->name, name, len);
    part->name[len] = '\0';
    sw_scene_default_color(st->part_count - 1, part->color);
    return 1;
}

static int begin_view(scene_state *st, const char *name)
{
    size_t len = 0;
    if (!check_name(st, "view", name, &len))
        return 0;
    for (size_t i = 0; i < st->view_count; i++) {
        if (same_name(st->views[i].name, name, len))
            return section_fail(st, SW_ERR_FORMAT, "view '%.*s' already defined at line %ld",
                                (int)len, name, st->views[i].line);
    }
    void *views = st->views;
    int ok = grow(st, &views, &st->view_capacity, st->view_count, sizeof *st->views);
    st->views = views;
    if (!ok)
        return 0;
    scene_view *view = &st->views[st->view_count++];
    *view = (scene_view){.line = st->pending_section, .up = {0, 1, 0}};
    memcpy(view->name, name, len);
    view->name[len] = '\0';
    return 1;
}

const scene_section_kind scene_section_kinds[] = {
    {"part", begin_part, part_key},
    {"view", begin_view, view_key},
};
const size_t scene_section_kind_count = sizeof scene_section_kinds / sizeof scene_section_kinds[0];

/* ---- whole-section checks ----------------------------------------------- */

static const unsigned proc_key_use[PK_COUNT] = {
    [PK_SIZE] = SW_PROC_USES_SIZE,         [PK_HEIGHT] = SW_PROC_USES_HEIGHT,
    [PK_HOLES] = SW_PROC_USES_HOLES,       [PK_SEGMENTS] = SW_PROC_USES_SEGMENTS,
    [PK_SEED] = SW_PROC_USES_SEED,
};

/* Copies the generator parameter of key k from the part's values into p. */
static void copy_proc_param(sw_proc_params *p, const sw_proc_params *given, int k)
{
    switch (k) {
    case PK_SIZE: p->size_mm = given->size_mm; break;
    case PK_HEIGHT: p->height_mm = given->height_mm; break;
    case PK_HOLES: p->holes = given->holes; break;
    case PK_SEGMENTS: p->segments = given->segments; break;
    case PK_SEED: p->seed = given->seed; break;
    default: break;
    }
}

/* Generator parameters: each one the kind takes and in range (checked alone
 * against the defaults, so the message points at the key that is wrong);
 * part->proc becomes the defaults with the given values. */
static int check_generated(scene_state *st, scene_part *part)
{
    const char *kind = sw_proc_kind_name(part->proc.kind);
    sw_proc_params p = sw_proc_defaults(part->proc.kind);
    if (part->key_line[PK_UNITS])
        return scene_fail_at(st, part->key_line[PK_UNITS], SW_ERR_FORMAT,
                             "units: generated parts are in millimetres (part '%s')", part->name);
    for (int k = PK_SIZE; k <= PK_SEED; k++) {
        if (!part->key_line[k])
            continue;
        if (!(sw_proc_params_used(part->proc.kind) & proc_key_use[k]))
            return scene_fail_at(st, part->key_line[k], SW_ERR_FORMAT,
                                 "%s: a generated %s takes no %s (part '%s')", part_keys[k].name,
                                 kind, part_keys[k].name, part->name);
        sw_proc_params one = sw_proc_defaults(part->proc.kind);
        copy_proc_param(&one, &part->proc, k);
        sw_error e = {0};
        if (sw_proc_check(&one, &e) != SW_OK)
            return scene_fail_at(st, part->key_line[k], e.status, "%s", e.message);
        copy_proc_param(&p, &part->proc, k);
    }
    part->proc = p;
    return 1;
}

static int check_part(scene_state *st, scene_part *part)
{
    long file = part->key_line[PK_FILE], gen = part->key_line[PK_GENERATE];
    if (!file && !gen)
        return scene_fail_at(st, part->line, SW_ERR_FORMAT,
                             "part '%s' has no file (or generate)", part->name);
    if (file && gen)
        return scene_fail_at(st, file > gen ? file : gen, SW_ERR_FORMAT,
                             "part '%s' has both file and generate", part->name);
    if (gen)
        return check_generated(st, part);
    for (int k = PK_SIZE; k <= PK_SEED; k++) {
        if (part->key_line[k])
            return scene_fail_at(st, part->key_line[k], SW_ERR_FORMAT,
                                 "%s: only generated parts take it (part '%s' has a file)",
                                 part_keys[k].name, part->name);
    }
    if (part->key_line[PK_UNITS] && scene_file_has_units(part->file))
        return scene_fail_at(st, part->key_line[PK_UNITS], SW_ERR_FORMAT,
                             "units: %s files carry their own units (part '%s')",
                             scene_extension(part->file), part->name);
    return 1;
}

static int check_view(scene_state *st, const scene_view *view)
{
    if (!view->key_line[VK_EYE] || !view->key_line[VK_TARGET])
        return scene_fail_at(st, view->line, SW_ERR_FORMAT, "view '%s' has no %s", view->name,
                             view->key_line[VK_EYE] ? "target" : "eye");
    sw_vec3 dir = sw_v3_sub(sw_v3(view->target[0], view->target[1], view->target[2]),
                            sw_v3(view->eye[0], view->eye[1], view->eye[2]));
    if (sw_v3_length(dir) == 0.0)
        return scene_fail_at(st, view->key_line[VK_TARGET], SW_ERR_RANGE,
                             "target: equals the eye (view '%s')", view->name);
    sw_vec3 up = sw_v3_normalize(sw_v3(view->up[0], view->up[1], view->up[2]));
    if (sw_v3_length(sw_v3_cross(sw_v3_normalize(dir), up)) < 1e-6) {
        long line = view->key_line[VK_UP] ? view->key_line[VK_UP] : view->key_line[VK_TARGET];
        return scene_fail_at(st, line, SW_ERR_RANGE,
                             "up: parallel to the view direction (view '%s')", view->name);
    }
    return 1;
}

int scene_check_sections(scene_state *st)
{
    if (st->part_count == 0)
        return scene_fail(st, SW_ERR_FORMAT, "expected at least one [part NAME] section");
    for (size_t i = 0; i < st->part_count; i++) {
        if (!check_part(st, &st->parts[i]))
            return 0;
    }
    for (size_t i = 0; i < st->view_count; i++) {
        if (!check_view(st, &st->views[i]))
            return 0;
    }
    return 1;
}
