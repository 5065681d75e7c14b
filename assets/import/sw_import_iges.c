/* SPDX-License-Identifier: MIT */
/* The native IGES reader's driver (sw_import_iges.h): sections, directory,
 * which entities become faces, 124 transforms, reference guards, and the
 * hand-over of the collected faces to the model in millimetres. */
#include "sw_import_iges.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "sw_iges_internal.h"

/* ---- which entities become faces ----------------------------------- */

/* Face-making entities in the order they are read: whole B-reps first, so
 * the faces they own are marked used before a lone face could take them. */
static int face_rank(int type)
{
    switch (type) {
    case 186: return 1;
    case 514: return 2;
    case 510: return 3;
    case 144: return 4;
    case 143: return 5;
    default: return iges_is_surface(type) ? 6 : 0;
    }
}

/* Read as parts of something else, or carry no shape: a 402 associativity (the
 * exporters' group of faces) carries no geometry and the faces it gathers
 * are read on their own, so it is not warned about (--strict accepts the
 * OCCT sample files, which each hold one group). */
static int known_type(int type)
{
    static const int types[] = {0, 116, 124, 141, 142, 402, 502, 504, 508};
    for (size_t i = 0; i < sizeof types / sizeof types[0]; i++)
        if (types[i] == type)
            return 1;
    return iges_is_curve(type) || face_rank(type) > 0;
}

static sw_status read_face_entity(iges_reader *r, int e, iges_faces *faces)
{
    switch (r->ents[e].type) {
    case 144: return iges_read_trimmed(r, e, faces);
    case 143: return iges_read_bounded(r, e, faces);
    case 186: case 514: case 510: return iges_read_brep(r, e, faces);
    default: return iges_read_untrimmed(r, e, faces);
    }
}

static void progress(const iges_reader *r, int done, int total)
{
    if (r->opt && r->opt->progress && total > 0 && done % 64 == 0)
        r->opt->progress(r->opt->progress_user, "IGES", (double)done / total);
}

/* A face that needs an unsupported entity is skipped with a warning, or
 * is an error when strict. */
static sw_status skip_or_fail(iges_reader *r, sw_status st)
{
    if (st != SW_ERR_UNSUPPORTED || (r->opt && r->opt->strict)) {
        r->unsupported_why = NULL;
        return st;
    }
    char kind[SW_IMPORT_KIND_CHARS];
    if (r->unsupported_why)
        snprintf(kind, sizeof kind, "IGES %d (%s)", r->unsupported_type, r->unsupported_why);
    else
        snprintf(kind, sizeof kind, "IGES %d", r->unsupported_type);
    sw_import_report_unsupported(r->report, kind);
    r->unsupported_why = NULL;
    return SW_OK;
}

/* Independent entities become faces (pass 0). gpucast_teapot.igs marks its
 * 32 surfaces physically dependent with no parent at all, so pass 1 takes
 * dependent face entities that nothing read so far has used. */
static sw_status read_faces(iges_reader *r, iges_faces *faces)
{
    for (int pass = 0; pass < 2; pass++)
        for (int rank = 1; rank <= 6; rank++)
            for (int e = 0; e < r->ent_count; e++) {
                iges_entity *ent = &r->ents[e];
                int dependent = ent->subordinate == 1 || ent->subordinate == 3;
                if (face_rank(ent->type) != rank || ent->used || dependent != pass)
                    continue;
                sw_status st = skip_or_fail(r, read_face_entity(r, e, faces));
                if (st != SW_OK)
                    return st;
                ent->used = 1;
                progress(r, e, r->ent_count);
            }
    for (int e = 0; e < r->ent_count; e++) {
        const iges_entity *ent = &r->ents[e];
        if (ent->subordinate == 0 && !known_type(ent->type)) {
            if (r->opt && r->opt->strict)
                return iges_fail_entity(r, e, SW_ERR_UNSUPPORTED,
                                        "entity type %d is not supported (strict)", ent->type);
            char kind[24];
            snprintf(kind, sizeof kind, "IGES %d", ent->type);
            sw_import_report_unsupported(r->report, kind);
        }
    }
    return SW_OK;
}

/* ---- into the model ---------------------------------------------------- */

static sw_status check_face(iges_reader *r, const iges_face *f)
{
    sw_nurbs_surface s = iges_surface_view(&f->surface);
    sw_status st = sw_nurbs_surface_check(&s, r->err);
    for (int l = 0; st == SW_OK && l < f->loop_count; l++)
        for (int c = 0; st == SW_OK && c < f->loops[l].curves.count; c++) {
            sw_nurbs_curve v = iges_curve_view(&f->loops[l].curves.items[c]);
            st = sw_nurbs_curve_check(&v, r->err);
        }
    if (st != SW_OK)
        sw_error_prefix(r->err, "%s: D line %d (type %d)", r->file, iges_de(f->entity),
                        r->ents[f->entity].type);
    return st;
}

static sw_status add_face(iges_reader *r, iges_face *f, sw_model *model)
{
    size_t curves = 0;
    for (int l = 0; l < f->loop_count; l++)
        curves += (size_t)f->loops[l].curves.count;
    sw_model_loop_input *in = calloc((size_t)f->loop_count + 1, sizeof *in);
    sw_nurbs_curve *views = calloc(curves + 1, sizeof *views);
    double *gaps = calloc(curves + 1, sizeof *gaps);
    if (!in || !views || !gaps) {
        free(in);
        free(views);
        free(gaps);
        return sw_error_set(r->err, SW_ERR_NO_MEMORY, "%s: out of memory", r->file);
    }
    size_t at = 0;
    for (int l = 0; l < f->loop_count; l++) {
        const iges_loop *lp = &f->loops[l];
        in[l] = (sw_model_loop_input){views + at, lp->computed, (size_t)lp->curves.count,
                                      lp->outer, gaps + at, NULL};
        for (int c = 0; c < lp->curves.count; c++) {
            gaps[at] = lp->curves.items[c].gap * r->units_to_mm;
            views[at++] = iges_curve_view(&lp->curves.items[c]);
        }
    }
    size_t n = (size_t)f->surface.count_u * (size_t)f->surface.count_v;
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++)
            f->surface.ctrl[i * 4 + k] *= r->units_to_mm;
    sw_nurbs_surface s = iges_surface_view(&f->surface);
    sw_status st = sw_model_add_surface(model, &s, f->reversed, in, (size_t)f->loop_count,
                                        r->err);
    if (st != SW_OK)
        sw_error_prefix(r->err, "%s: D line %d (type %d)", r->file, iges_de(f->entity),
                        r->ents[f->entity].type);
    free(in);
    free(views);
    free(gaps);
    return st;
}

static sw_status emit(iges_reader *r, iges_faces *faces, sw_model *model)
{
    for (int i = 0; i < faces->count; i++) {
        sw_status st = check_face(r, &faces->items[i]);
        if (st != SW_OK)
            return st;
    }
    for (int i = 0; i < faces->count; i++) {
        sw_status st = add_face(r, &faces->items[i], model);
        if (st != SW_OK)
            return st;
        r->report->faces++;
    }
    return SW_OK;
}

static void set_tolerance(iges_reader *r)
{
    double file_mm = r->resolution * r->units_to_mm;
    r->report->units_to_mm = r->units_to_mm;
    r->report->model_tolerance_mm = file_mm;
    double tol_mm = r->opt && r->opt->tolerance_mm > 0 ? r->opt->tolerance_mm
                  : file_mm > 0 ? file_mm : 0.01;
    r->tol = tol_mm / r->units_to_mm;
}

static const char *base_name(const char *path)
{
    const char *slash = path ? strrchr(path, '/') : NULL;
    return slash ? slash + 1 : path ? path : "<memory>";
}

sw_status sw_import_iges_memory(const char *text, size_t size, const char *file_name,
                                const sw_import_options *options, sw_model *model,
                                sw_import_report *report, sw_error *err)
{
    sw_error local_err;
    sw_import_report local_report;
    iges_reader r = {0};
    r.file = base_name(file_name);
    r.err = err ? err : &local_err;
    r.opt = options;
    r.report = report ? report : &local_report;
    memset(r.report, 0, sizeof *r.report);
    if (!model || (!text && size))
        return sw_error_set(err, SW_ERR_ARG, "%s: no model or no text", r.file);
    iges_faces faces = {0};
    sw_status st = iges_split_sections(&r, text ? text : "", size);
    if (st == SW_OK)
        st = iges_read_global(&r);
    if (st == SW_OK)
        st = iges_read_directory(&r);
    if (st == SW_OK) {
        set_tolerance(&r);
        st = read_faces(&r, &faces);
    }
    if (st == SW_OK)
        st = emit(&r, &faces, model);
    if (st == SW_OK && r.report->model_tolerance_mm > model->model_tolerance)
        model->model_tolerance = (float)r.report->model_tolerance_mm;
    if (st == SW_OK && options && options->progress)
        options->progress(options->progress_user, "IGES", 1.0);
    iges_faces_free(&faces);
    iges_reader_free(&r);
    return st;
}

sw_status sw_import_iges_file(const char *path, const sw_import_options *options,
                              sw_model *model, sw_import_report *report, sw_error *err)
{
    FILE *f = path ? fopen(path, "rb") : NULL;
    if (!f)
        return sw_error_set(err, SW_ERR_IO, "%s: cannot open", path ? path : "(null)");
    struct stat sb;
    if (fstat(fileno(f), &sb) != 0 || sb.st_size < 0) {
        fclose(f);
        return sw_error_set(err, SW_ERR_IO, "%s: cannot read its size", path);
    }
    size_t size = (size_t)sb.st_size;
    char *text = malloc(size ? size : 1);
    if (!text || fread(text, 1, size, f) != size) {
        free(text);
        fclose(f);
        return sw_error_set(err, text ? SW_ERR_IO : SW_ERR_NO_MEMORY, "%s: cannot read %zu bytes",
                            path, size);
    }
    fclose(f);
    sw_status st = sw_import_iges_memory(text, size, path, options, model, report, err);
    free(text);
    return st;
}
