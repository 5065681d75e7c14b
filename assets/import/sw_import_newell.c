/* SPDX-License-Identifier: MIT */
/* Newell teaset listings (format and control point order: sw_import_newell.h). */
#include "sw_import_newell.h"

#include <stdint.h>
#include <stdlib.h>

#include "sw_text_scan.h"

enum { NEWELL_POINTS = 16 };

typedef struct newell_counts {
    long vertices, patches;
} newell_counts;

/* Each record needs more than one byte, so a count larger than the bytes left
 * is a lie; this bounds what a hostile header can make us allocate. */
static long record_limit(const sw_text_scan *s)
{
    size_t left = (size_t)(s->end - s->p);
    return left > (size_t)LONG_MAX ? LONG_MAX : (long)left;
}

static sw_status parse_header(sw_text_scan *s, newell_counts *counts, sw_error *err)
{
    if (sw_scan_at_eof(s))
        return sw_error_set(err, SW_ERR_FORMAT, "%s:1: expected a title line, found an empty file",
                            s->file);
    sw_scan_skip_line(s);  /* the title */
    long objects, fourth;
    sw_status st;
    if ((st = sw_scan_long(s, &counts->vertices, 1, record_limit(s), "vertex count", err)) ||
        (st = sw_scan_long(s, &objects, 0, LONG_MAX, "object count", err)) ||
        (st = sw_scan_long(s, &counts->patches, 1, record_limit(s), "patch count", err)) ||
        (st = sw_scan_long(s, &fourth, 0, LONG_MAX, "fourth count", err)))
        return st;
    return sw_scan_end_line(s, "the four counts", err);
}

static sw_status parse_vertices(sw_text_scan *s, long count, double *xyz, sw_error *err)
{
    for (long v = 1; v <= count; v++) {
        sw_scan_skip_empty_lines(s);
        long number = 0, line = s->line, column = sw_scan_column(s);
        sw_status st = sw_scan_long(s, &number, LONG_MIN, LONG_MAX, "vertex number", err);
        if (st != SW_OK)
            return st;
        if (number != v)
            return sw_error_set(err, SW_ERR_FORMAT,
                                "%s:%ld:%ld: expected vertex number %ld, found %ld", s->file,
                                line, column, v, number);
        for (int k = 0; k < 3; k++) {
            static const char *const names[3] = {"vertex x", "vertex y", "vertex z"};
            if ((st = sw_scan_double(s, &xyz[3 * (v - 1) + k], names[k], err)) != SW_OK)
                return st;
        }
        if ((st = sw_scan_end_line(s, "a vertex's x y z", err)) != SW_OK)
            return st;
    }
    return SW_OK;
}

/* Counts the tokens left on the current line without consuming them. */
static int tokens_on_line(const sw_text_scan *s)
{
    sw_text_scan probe = *s;
    int n = 0;
    size_t len;
    while (sw_scan_peek(&probe, &len), len > 0) {
        probe.p += len;
        n++;
    }
    return n;
}

static sw_status parse_patch_line(sw_text_scan *s, long vertex_count, long idx[NEWELL_POINTS],
                                  sw_error *err)
{
    int found = tokens_on_line(s);
    if (found != NEWELL_POINTS)
        return sw_error_set(err, SW_ERR_FORMAT, "%s:%ld: expected %d vertex indices, found %d",
                            s->file, s->line, NEWELL_POINTS, found);
    for (int k = 0; k < NEWELL_POINTS; k++) {
        size_t len;
        const char *tok = sw_scan_peek(s, &len);
        /* The listing marks a patch's first index with '-'. */
        if (k == 0 && len > 1 && tok[0] == '-')
            s->p++;
        sw_status st = sw_scan_long(s, &idx[k], 1, vertex_count, "vertex index", err);
        if (st != SW_OK)
            return st;
    }
    return sw_scan_end_line(s, "16 vertex indices", err);
}

/* Listing position g * 4 + k is control point (i = g, j = k); see the header. */
static void gather_patch(const long idx[NEWELL_POINTS], const double *xyz, double ctrl[64])
{
    for (int g = 0; g < 4; g++) {
        for (int k = 0; k < 4; k++) {
            const double *v = xyz + 3 * (idx[g * 4 + k] - 1);
            double *c = ctrl + 4 * (k * 4 + g);
            c[0] = v[0];
            c[1] = v[1];
            c[2] = v[2];
            c[3] = 1.0;
        }
    }
}

static sw_status parse_patches(sw_text_scan *s, long vertex_count, long patch_count,
                               long *idx, sw_error *err)
{
    for (long p = 0; p < patch_count; p++) {
        sw_scan_skip_empty_lines(s);
        if (sw_scan_at_eof(s))
            return sw_error_set(err, SW_ERR_FORMAT,
                                "%s:%ld: expected patch %ld of %ld, found the end of the file",
                                s->file, s->line, p + 1, patch_count);
        sw_status st = parse_patch_line(s, vertex_count, idx + NEWELL_POINTS * p, err);
        if (st != SW_OK)
            return st;
    }
    sw_scan_skip_empty_lines(s);
    if (!sw_scan_at_eof(s))
        return sw_error_set(err, SW_ERR_FORMAT,
                            "%s:%ld: expected the end of the file after %ld patches", s->file,
                            s->line, patch_count);
    return SW_OK;
}

/* Parses everything first and adds patches only when the whole file is good,
 * so a malformed file leaves the model as it was. */
sw_status sw_import_newell_memory(const char *text, size_t size, const char *file_name,
                                  sw_model *model, sw_error *err)
{
    if (!model || (!text && size))
        return sw_error_set(err, SW_ERR_ARG, "sw_import_newell_memory: NULL argument");
    sw_text_scan s;
    sw_scan_init(&s, text, size, file_name);
    newell_counts counts = { 0 };
    sw_status st = parse_header(&s, &counts, err);
    if (st != SW_OK)
        return st;
    double *xyz = malloc((size_t)counts.vertices * 3 * sizeof *xyz);
    long *idx = malloc((size_t)counts.patches * NEWELL_POINTS * sizeof *idx);
    if (!xyz || !idx)
        st = sw_error_set(err, SW_ERR_NO_MEMORY, "%s: out of memory for %ld vertices",
                          s.file, counts.vertices);
    if (st == SW_OK)
        st = parse_vertices(&s, counts.vertices, xyz, err);
    if (st == SW_OK)
        st = parse_patches(&s, counts.vertices, counts.patches, idx, err);
    for (long p = 0; st == SW_OK && p < counts.patches; p++) {
        double ctrl[64];
        gather_patch(idx + NEWELL_POINTS * p, xyz, ctrl);
        st = sw_model_add_patch(model, 3, 3, 0, ctrl, err);
    }
    free(xyz);
    free(idx);
    return st;
}

sw_status sw_import_newell_file(const char *path, sw_model *model, sw_error *err)
{
    char *text;
    size_t size;
    sw_status st = sw_read_whole_file(path, &text, &size, err);
    if (st != SW_OK)
        return st;
    st = sw_import_newell_memory(text, size, path, model, err);
    free(text);
    return st;
}
