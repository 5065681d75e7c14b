/* SPDX-License-Identifier: MIT */
/* Showroom scene files (sw_scene.h). inih splits lines into sections and
 * key = value pairs; our line reader feeds it from memory and counts lines, so
 * every message can name file:line even though this inih build does not pass
 * line numbers to the handler. Parsing collects the sections first (their keys
 * are in sw_scene_keys.c); files are imported and objects generated only when
 * the whole scene parsed and checked. */
#include "sw_scene.h"

#include <ini.h>
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "sw_scene_internal.h"
#include "sw_text_scan.h"

/* Checks a "[...]" header the way inih will read it, so that our idea of
 * where sections start agrees with inih's. */
static int note_section_header(scene_state *st, const char *line, size_t len)
{
    const char *close = memchr(line, ']', len);
    if (!close)
        return scene_fail(st, SW_ERR_FORMAT, "expected ']' to close the section name");
    if ((size_t)(close - line - 1) > SCENE_SECTION_MAX)
        return scene_fail(st, SW_ERR_FORMAT, "section name longer than %d bytes",
                          SCENE_SECTION_MAX);
    if (st->pending_section)
        return section_fail(st, SW_ERR_FORMAT, "section has no keys");
    st->pending_section = st->line;
    return 1;
}

/* An fgets-style reader over the memory buffer for ini_parse_stream. It stops
 * inih (returns NULL) at the first error. */
static char *scene_read_line(char *str, int num, void *stream)
{
    scene_state *st = stream;
    if (st->error_line || st->pos >= st->size || num < 2)
        return NULL;
    const char *start = st->text + st->pos;
    const char *nl = memchr(start, '\n', st->size - st->pos);
    size_t len = nl ? (size_t)(nl - start) + 1 : st->size - st->pos;
    st->line++;
    if (len > (size_t)num - 1) {
        scene_fail(st, SW_ERR_FORMAT, "line longer than %d bytes", num - 2);
        return NULL;
    }
    memcpy(str, start, len);
    str[len] = '\0';
    st->pos += len;
    /* Classify the line as inih will: after a UTF-8 BOM on line 1, and with
     * isspace() as its idea of blank. */
    size_t lead = 0;
    if (st->line == 1 && len >= 3 && memcmp(str, "\xEF\xBB\xBF", 3) == 0)
        lead = 3;
    size_t indent = 0;
    while (isspace((unsigned char)str[lead + indent]))
        indent++;
    char first = str[lead + indent];
    int blank = first == '\0';
    /* Continuation lines would make inih call us for a key again on a line
     * that does not say so; nothing in a scene needs them. */
    if (indent > 0 && !blank && first != ';' && first != '#') {
        scene_fail(st, SW_ERR_FORMAT, "unexpected indentation");
        return NULL;
    }
    if (first == '[' && !note_section_header(st, str + lead + indent, len - lead - indent))
        return NULL;
    return str;
}

static const scene_section_kind *find_section_kind(const char *section, const char **name)
{
    for (size_t k = 0; k < scene_section_kind_count; k++) {
        size_t len = strlen(scene_section_kinds[k].word);
        if (strncmp(section, scene_section_kinds[k].word, len) != 0)
            continue;
        const char *rest = section + len;
        if (*rest != '\0' && *rest != ' ' && *rest != '\t')
            continue;
        rest += strspn(rest, " \t");
        *name = rest;
        return &scene_section_kinds[k];
    }
    return NULL;
}

static int scene_handler(void *user, const char *section, const char *name, const char *value)
{
    scene_state *st = user;
    if (st->error_line)
        return 0;
    if (section[0] == '\0')
        return scene_top_key(st, name, value);
    const char *part_name = NULL;
    const scene_section_kind *kind = find_section_kind(section, &part_name);
    if (!kind)
        return section_fail(st, SW_ERR_FORMAT, "unknown section [%s] (expected [part NAME] or [view NAME])",
                            section);
    /* A new section: the reader saw its header, or (belt and braces, should
     * inih and the reader ever disagree on a header) the name changed. */
    if (st->pending_section || strcmp(section, st->section) != 0) {
        if (!st->pending_section)
            st->pending_section = st->line;
        if (!kind->begin(st, part_name))
            return 0;
        st->pending_section = 0;
        snprintf(st->section, sizeof st->section, "%s", section);
    }
    return kind->key(st, name, value);
}

/* ---- loading ------------------------------------------------------------ */

/* base_dir/file, or file itself when it is absolute or there is no base. */
sw_status scene_resolve_path(const char *base_dir, const char *file, char out[SCENE_PATH_MAX],
                              sw_error *err)
{
    int n;
    if (file[0] == '/' || !base_dir || !base_dir[0])
        n = snprintf(out, SCENE_PATH_MAX, "%s", file);
    else
        n = snprintf(out, SCENE_PATH_MAX, "%s/%s", base_dir, file);
    if (n < 0 || n >= SCENE_PATH_MAX)
        return sw_error_set(err, SW_ERR_ARG, "path of '%s' longer than %d bytes", file,
                            SCENE_PATH_MAX - 1);
    return SW_OK;
}

/* Units, then scale, then rotate, then translate: M = T * R * S * U. */
static sw_mat4 part_matrix(const scene_part *part)
{
    double u = part->units_to_mm;
    sw_mat4 s = sw_mat4_scale(sw_v3(part->scale[0] * u, part->scale[1] * u, part->scale[2] * u));
    sw_mat4 r = sw_mat4_rotate(sw_v3(part->axis[0], part->axis[1], part->axis[2]),
                               part->angle_deg * (SW_PI / 180.0));
    sw_mat4 t = sw_mat4_translate(sw_v3(part->translate[0], part->translate[1],
                                        part->translate[2]));
    sw_mat4 rs = sw_mat4_mul(&r, &s);
    return sw_mat4_mul(&t, &rs);
}

/* The part's geometry: its file (relative to base_dir, read once per scene)
 * or its generated object. An importer may split a file into several parts
 * (assemblies); all of them get the scene part's placement. */
static sw_status load_part(const scene_state *st, const scene_part *part, const char *base_dir,
                           const sw_import_options *options, sw_import_report *report,
                           scene_cache *cache, sw_model *model, sw_error *err)
{
    size_t first = model->part_count;
    sw_status status;
    if (part->key_line[PK_GENERATE]) {
        status = sw_model_begin_part(model, part->name, part->color, err);
        if (status == SW_OK)
            status = sw_proc_add(model, &part->proc, err);
    } else {
        char path[SCENE_PATH_MAX];
        status = scene_resolve_path(base_dir, part->file, path, err);
        if (status == SW_OK)
            status = scene_cache_place(cache, path, part->name, part->color, options, report,
                                       model, err);
    }
    if (status != SW_OK) {
        long line = part->key_line[part->key_line[PK_FILE] ? PK_FILE : PK_GENERATE];
        sw_error_prefix(err, "%s:%ld: part '%s'", st->file_name, line, part->name);
        return status;
    }
    sw_mat4 m = part_matrix(part);
    for (size_t p = first; p < model->part_count; p++)
        sw_model_transform_part(model, p, &m);
    return SW_OK;
}

sw_status scene_load_view(const scene_state *st, const scene_view *view, sw_model *model,
                         sw_error *err)
{
    sw_model_viewpoint vp = {.fov_deg = view->fov_deg};
    snprintf(vp.name, sizeof vp.name, "%s", view->name);
    memcpy(vp.eye, view->eye, sizeof vp.eye);
    memcpy(vp.target, view->target, sizeof vp.target);
    memcpy(vp.up, view->up, sizeof vp.up);
    sw_status status = sw_model_add_viewpoint(model, &vp, err);
    if (status != SW_OK)
        sw_error_prefix(err, "%s:%ld: view '%s'", st->file_name, view->line, view->name);
    return status;
}

/* Runs inih over the text; on success st holds every checked section. */
sw_status scene_parse(scene_state *st)
{
    const char *nul = memchr(st->text, '\0', st->size);
    if (nul) {
        st->line = 1;
        for (const char *p = st->text; p < nul; p++)
            st->line += *p == '\n';
        scene_fail(st, SW_ERR_FORMAT, "NUL byte in a text file");
        return st->status;
    }
    int syntax_line = ini_parse_stream(scene_read_line, st, scene_handler, st);
    if (syntax_line > 0 && (!st->error_line || syntax_line < st->error_line)) {
        st->error_line = 0;
        st->line = syntax_line;
        scene_fail(st, SW_ERR_FORMAT, "expected [section] or key = value");
    } else if (syntax_line < 0 && !st->error_line) {
        scene_fail(st, SW_ERR_NO_MEMORY, "inih failed (%d)", syntax_line);
    }
    if (!st->error_line && st->pending_section)
        section_fail(st, SW_ERR_FORMAT, "section has no keys");
    if (!st->error_line)
        scene_check_sections(st);
    return st->error_line ? st->status : SW_OK;
}

sw_status sw_scene_load_memory_with(const char *text, size_t size, const char *file_name,
                                    const char *base_dir, const sw_import_options *options,
                                    sw_import_report *report, sw_model *model, sw_error *err)
{
    if (!model || (!text && size))
        return sw_error_set(err, SW_ERR_ARG, "sw_scene_load_memory: NULL argument");
    scene_state st = {
        .text = text ? text : "",
        .size = size,
        .file_name = file_name ? file_name : "<memory>",
        .err = err,
    };
    sw_status status = scene_parse(&st);
    scene_cache cache = {0};
    for (size_t i = 0; status == SW_OK && i < st.part_count; i++)
        status = load_part(&st, &st.parts[i], base_dir, options, report, &cache, model, err);
    scene_cache_free(&cache);
    for (size_t i = 0; status == SW_OK && i < st.view_count; i++)
        status = scene_load_view(&st, &st.views[i], model, err);
    if (status == SW_OK && st.up_axis_line)
        model->up_axis = st.up_axis;
    free(st.parts);
    free(st.views);
    return status;
}

sw_status sw_scene_load_memory(const char *text, size_t size, const char *file_name,
                               const char *base_dir, sw_model *model, sw_error *err)
{
    return sw_scene_load_memory_with(text, size, file_name, base_dir, NULL, NULL, model, err);
}

sw_status scene_base_dir(const char *path, char out[SCENE_PATH_MAX], sw_error *err)
{
    out[0] = '\0';
    const char *slash = strrchr(path, '/');
    if (!slash)
        return SW_OK;
    size_t len = (size_t)(slash - path);
    if (len == 0)
        len = 1; /* a scene in "/" */
    if (len >= SCENE_PATH_MAX)
        return sw_error_set(err, SW_ERR_ARG, "%s: path too long", path);
    memcpy(out, path, len);
    out[len] = '\0';
    return SW_OK;
}

sw_status sw_scene_load_with(const char *path, const sw_import_options *options,
                             sw_import_report *report, sw_model *model, sw_error *err)
{
    if (!path)
        return sw_error_set(err, SW_ERR_ARG, "sw_scene_load: path is NULL");
    char *text;
    size_t size;
    sw_status status = sw_read_whole_file(path, &text, &size, err);
    if (status != SW_OK)
        return status;
    char base_dir[SCENE_PATH_MAX];
    status = scene_base_dir(path, base_dir, err);
    if (status != SW_OK) {
        free(text);
        return status;
    }
    status = sw_scene_load_memory_with(text, size, path, base_dir, options, report, model, err);
    free(text);
    return status;
}

sw_status sw_scene_load(const char *path, sw_model *model, sw_error *err)
{
    return sw_scene_load_with(path, NULL, NULL, model, err);
}
