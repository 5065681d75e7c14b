/* SPDX-License-Identifier: MIT */
/* .bpt Bezier patch text (format and point order: sw_import_bpt.h). */
#include "sw_import_bpt.h"

#include <stdlib.h>

#include "sw_text_scan.h"

/* One patch as parsed: degrees and where its points start in the shared
 * array of x, y, z, w doubles. */
typedef struct bpt_patch {
    int degree_u, degree_v;
    size_t first_point;
} bpt_patch;

typedef struct bpt_data {
    bpt_patch *patches;
    double *points;             /* 4 per point, sw_bezier_patch layout */
    size_t point_count, point_capacity;
} bpt_data;

/* Each patch takes at least one line, so more patches than bytes left is a
 * lie; this bounds what a hostile count can make us allocate. */
static long record_limit(const sw_text_scan *s)
{
    size_t left = (size_t)(s->end - s->p);
    return left > (size_t)LONG_MAX ? LONG_MAX : (long)left;
}

static sw_status reserve_points(bpt_data *d, size_t more, const char *file, sw_error *err)
{
    size_t need = d->point_count + more;
    if (need <= d->point_capacity)
        return SW_OK;
    size_t cap = d->point_capacity ? d->point_capacity : 256;
    while (cap < need)
        cap *= 2;
    double *bigger = realloc(d->points, cap * 4 * sizeof *bigger);
    if (!bigger)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "%s: out of memory for %zu control points",
                            file, need);
    d->points = bigger;
    d->point_capacity = cap;
    return SW_OK;
}

static sw_status parse_point(sw_text_scan *s, double *c, sw_error *err)
{
    static const char *const names[3] = {"control point x", "control point y",
                                         "control point z"};
    sw_scan_skip_empty_lines(s);
    for (int k = 0; k < 3; k++) {
        sw_status st = sw_scan_double(s, &c[k], names[k], err);
        if (st != SW_OK)
            return st;
    }
    c[3] = 1.0;
    return sw_scan_end_line(s, "a control point's x y z", err);
}

static sw_status parse_patch(sw_text_scan *s, long number, bpt_data *d, sw_error *err)
{
    sw_scan_skip_empty_lines(s);
    if (sw_scan_at_eof(s))
        return sw_error_set(err, SW_ERR_FORMAT,
                            "%s:%ld: expected the degrees of patch %ld, found the end of the file",
                            s->file, s->line, number);
    long du = 0, dv = 0;
    sw_status st;
    if ((st = sw_scan_long(s, &du, 1, SW_BEZIER_MAX_DEGREE, "degree u", err)) ||
        (st = sw_scan_long(s, &dv, 1, SW_BEZIER_MAX_DEGREE, "degree v", err)) ||
        (st = sw_scan_end_line(s, "the degrees 'du dv'", err)))
        return st;
    size_t n = (size_t)(du + 1) * (size_t)(dv + 1);
    if ((st = reserve_points(d, n, s->file, err)) != SW_OK)
        return st;
    d->patches[number - 1] = (bpt_patch){(int)du, (int)dv, d->point_count};
    for (size_t k = 0; k < n; k++) {
        if ((st = parse_point(s, d->points + 4 * (d->point_count + k), err)) != SW_OK)
            return st;
    }
    d->point_count += n;
    return SW_OK;
}

static sw_status parse_all(sw_text_scan *s, long *count, bpt_data *d, sw_error *err)
{
    sw_scan_skip_empty_lines(s);
    sw_status st = sw_scan_long(s, count, 1, record_limit(s), "patch count", err);
    if (st == SW_OK)
        st = sw_scan_end_line(s, "the patch count", err);
    if (st != SW_OK)
        return st;
    d->patches = malloc((size_t)*count * sizeof *d->patches);
    if (!d->patches)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "%s: out of memory for %ld patches",
                            s->file, *count);
    for (long p = 1; p <= *count; p++) {
        if ((st = parse_patch(s, p, d, err)) != SW_OK)
            return st;
    }
    sw_scan_skip_empty_lines(s);
    if (!sw_scan_at_eof(s))
        return sw_error_set(err, SW_ERR_FORMAT,
                            "%s:%ld: expected the end of the file after %ld patches", s->file,
                            s->line, *count);
    return SW_OK;
}

/* Parses everything first and adds patches only when the whole file is good,
 * so a malformed file leaves the model as it was. */
sw_status sw_import_bpt_memory(const char *text, size_t size, const char *file_name,
                               sw_model *model, sw_error *err)
{
    if (!model || (!text && size))
        return sw_error_set(err, SW_ERR_ARG, "sw_import_bpt_memory: NULL argument");
    sw_text_scan s;
    sw_scan_init(&s, text, size, file_name);
    bpt_data d = {0};
    long count = 0;
    sw_status st = parse_all(&s, &count, &d, err);
    for (long p = 0; st == SW_OK && p < count; p++) {
        const bpt_patch *bp = &d.patches[p];
        st = sw_model_add_patch(model, bp->degree_u, bp->degree_v, 0,
                                d.points + 4 * bp->first_point, err);
    }
    free(d.patches);
    free(d.points);
    return st;
}

sw_status sw_import_bpt_file(const char *path, sw_model *model, sw_error *err)
{
    char *text;
    size_t size;
    sw_status st = sw_read_whole_file(path, &text, &size, err);
    if (st != SW_OK)
        return st;
    st = sw_import_bpt_memory(text, size, path, model, err);
    free(text);
    return st;
}
