/* Showroom scene files (sw_scene.h). inih splits lines into sections and
 * key = value pairs; our line reader feeds it from memory and counts lines, so
 * every message can name file:line even though this inih build does not pass
 * line numbers to the handler. Parsing collects the parts first; files are
 * imported only when the whole scene parsed. */
#include "sw_scene.h"

#include <ini.h>
#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "sw_import_bpt.h"
#include "sw_import_newell.h"
#include "sw_text_scan.h"

enum { SCENE_NAME_MAX = 44, SCENE_SECTION_MAX = 49, SCENE_PATH_MAX = 4096 };

enum scene_key_bit {
    KEY_FILE = 1,
    KEY_TRANSLATE = 2,
    KEY_ROTATE = 4,
    KEY_SCALE = 8,
    KEY_COLOR = 16,
};

typedef struct scene_part {
    char name[SCENE_NAME_MAX + 1];
    char file[256];           /* as written; inih lines are shorter */
    long line, file_line;     /* of the section header and of `file =` */
    unsigned keys_seen;       /* enum scene_key_bit */
    double translate[3], axis[3], angle_deg, scale[3];
    float color[4];
} scene_part;

typedef struct scene_state {
    const char *text;
    size_t size, pos;
    const char *file_name;
    long line;                /* of the line inih is working on */
    long pending_section;     /* line of a header no key has followed yet, or 0 */
    char section[64];         /* inih's name of the section being filled */
    scene_part *parts;
    size_t part_count, part_capacity;
    sw_error *err;
    long error_line;          /* 0 while no error is recorded */
    sw_status status;         /* of the recorded error */
} scene_state;

/* Records the first error only (later ones are usually its consequences) and
 * returns 0, inih's "handler failed". */
static int scene_vfail(scene_state *st, long line, sw_status status, const char *fmt,
                       va_list ap)
{
    if (st->error_line)
        return 0;
    char what[SW_ERROR_MESSAGE_MAX];
    vsnprintf(what, sizeof what, fmt, ap);
    if (line < 1)
        line = 1; /* an empty file fails "at line 1"; 0 means "no error" */
    st->error_line = line;
    st->status = status;
    sw_error_set(st->err, status, "%s:%ld: %s", st->file_name, line, what);
    return 0;
}

/* Fails at the line being read. */
static int scene_fail(scene_state *st, sw_status status, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static int scene_fail(scene_state *st, sw_status status, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    scene_vfail(st, st->line, status, fmt, ap);
    va_end(ap);
    return 0;
}

/* Fails at the header of the section that is starting (or the current line). */
static int section_fail(scene_state *st, sw_status status, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static int section_fail(scene_state *st, sw_status status, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    scene_vfail(st, st->pending_section ? st->pending_section : st->line, status, fmt, ap);
    va_end(ap);
    return 0;
}

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

static int key_file(scene_state *st, scene_part *part, const char *value)
{
    size_t len = strlen(value);
    if (len == 0)
        return scene_fail(st, SW_ERR_FORMAT, "file: expected a file name");
    if (len >= sizeof part->file)
        return scene_fail(st, SW_ERR_FORMAT, "file: name longer than %zu bytes",
                          sizeof part->file - 1);
    memcpy(part->file, value, len + 1);
    part->file_line = st->line;
    return 1;
}

static int key_translate(scene_state *st, scene_part *part, const char *value)
{
    int n;
    return parse_numbers(st, "translate", value, part->translate, 3, 3, &n);
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

typedef struct scene_key {
    const char *name;
    unsigned bit;
    int (*parse)(scene_state *st, scene_part *part, const char *value);
} scene_key;

static const scene_key part_keys[] = {
    {"file", KEY_FILE, key_file},       {"translate", KEY_TRANSLATE, key_translate},
    {"rotate", KEY_ROTATE, key_rotate}, {"scale", KEY_SCALE, key_scale},
    {"color", KEY_COLOR, key_color},
};

static int part_key(scene_state *st, const char *name, const char *value)
{
    scene_part *part = &st->parts[st->part_count - 1];
    for (size_t k = 0; k < sizeof part_keys / sizeof part_keys[0]; k++) {
        if (strcmp(name, part_keys[k].name) != 0)
            continue;
        if (part->keys_seen & part_keys[k].bit)
            return scene_fail(st, SW_ERR_FORMAT, "key '%s' given twice in part '%s'", name,
                              part->name);
        part->keys_seen |= part_keys[k].bit;
        return part_keys[k].parse(st, part, value);
    }
    return scene_fail(st, SW_ERR_FORMAT,
                      "unknown key '%s' in part '%s' (expected file, translate, rotate, "
                      "scale or color)",
                      name, part->name);
}

static int begin_part(scene_state *st, const char *name)
{
    size_t len = strlen(name);
    while (len > 0 && (name[len - 1] == ' ' || name[len - 1] == '\t'))
        len--;
    if (len == 0)
        return section_fail(st, SW_ERR_FORMAT, "expected [part NAME], found no name");
    if (len > SCENE_NAME_MAX)
        return section_fail(st, SW_ERR_FORMAT, "part name longer than %d bytes", SCENE_NAME_MAX);
    for (size_t i = 0; i < st->part_count; i++) {
        if (strlen(st->parts[i].name) == len && memcmp(st->parts[i].name, name, len) == 0)
            return section_fail(st, SW_ERR_FORMAT, "part '%.*s' already defined at line %ld",
                                (int)len, name, st->parts[i].line);
    }
    if (st->part_count == st->part_capacity) {
        size_t cap = st->part_capacity ? st->part_capacity * 2 : 8;
        scene_part *bigger = realloc(st->parts, cap * sizeof *bigger);
        if (!bigger)
            return section_fail(st, SW_ERR_NO_MEMORY, "out of memory for %zu parts", cap);
        st->parts = bigger;
        st->part_capacity = cap;
    }
    scene_part *part = &st->parts[st->part_count++];
    *part = (scene_part){.line = st->pending_section, .scale = {1, 1, 1}, .axis = {0, 1, 0}};
    memcpy(part->name, name, len);
    part->name[len] = '\0';
    sw_scene_default_color(st->part_count - 1, part->color);
    return 1;
}

/* Section kinds by their first word; "[view NAME]" and the like go here. */
typedef struct scene_section_kind {
    const char *word;
    int (*begin)(scene_state *st, const char *name);
    int (*key)(scene_state *st, const char *name, const char *value);
} scene_section_kind;

static const scene_section_kind section_kinds[] = {
    {"part", begin_part, part_key},
};

static const scene_section_kind *find_section_kind(const char *section, const char **name)
{
    for (size_t k = 0; k < sizeof section_kinds / sizeof section_kinds[0]; k++) {
        size_t len = strlen(section_kinds[k].word);
        if (strncmp(section, section_kinds[k].word, len) != 0)
            continue;
        const char *rest = section + len;
        if (*rest != '\0' && *rest != ' ' && *rest != '\t')
            continue;
        rest += strspn(rest, " \t");
        *name = rest;
        return &section_kinds[k];
    }
    return NULL;
}

static int scene_handler(void *user, const char *section, const char *name, const char *value)
{
    scene_state *st = user;
    if (st->error_line)
        return 0;
    if (section[0] == '\0')
        return scene_fail(st, SW_ERR_FORMAT, "key '%s' outside any section", name);
    const char *part_name = NULL;
    const scene_section_kind *kind = find_section_kind(section, &part_name);
    if (!kind)
        return section_fail(st, SW_ERR_FORMAT, "unknown section [%s] (expected [part NAME])",
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

static const float palette[][4] = {
    {0.80f, 0.36f, 0.24f, 1.0f}, /* terracotta */
    {0.26f, 0.46f, 0.72f, 1.0f}, /* cornflower */
    {0.86f, 0.74f, 0.44f, 1.0f}, /* sand */
    {0.36f, 0.60f, 0.38f, 1.0f}, /* sage */
    {0.58f, 0.42f, 0.68f, 1.0f}, /* lavender */
    {0.75f, 0.75f, 0.78f, 1.0f}, /* pewter */
};

void sw_scene_default_color(size_t index, float out[4])
{
    memcpy(out, palette[index % (sizeof palette / sizeof palette[0])], 4 * sizeof(float));
}

/* The extension of path's last component, including the dot, or "". */
static const char *extension(const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const char *dot = strrchr(base, '.');
    return dot && dot != base ? dot : "";
}

int sw_scene_is_scene_path(const char *path)
{
    return path && strcasecmp(extension(path), ".ini") == 0;
}

typedef sw_status (*import_fn)(const char *path, sw_model *model, sw_error *err);

/* Importers by extension; IGES and STEP join here. */
static const struct {
    const char *ext;
    import_fn import;
} importers[] = {
    {".txt", sw_import_newell_file},
    {".bpt", sw_import_bpt_file},
};

sw_status sw_scene_import_file(const char *path, sw_model *model, sw_error *err)
{
    if (!path || !model)
        return sw_error_set(err, SW_ERR_ARG, "sw_scene_import_file: NULL argument");
    const char *ext = extension(path);
    for (size_t k = 0; k < sizeof importers / sizeof importers[0]; k++) {
        if (strcasecmp(ext, importers[k].ext) == 0)
            return importers[k].import(path, model, err);
    }
    return sw_error_set(err, SW_ERR_UNSUPPORTED,
                        "%s: unsupported file type '%s' (expected .txt Newell listing or .bpt)",
                        path, ext);
}

/* base_dir/file, or file itself when it is absolute or there is no base. */
static sw_status resolve_path(const char *base_dir, const char *file, char out[SCENE_PATH_MAX],
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

/* Scale, then rotate, then translate: M = T * R * S. */
static sw_mat4 part_matrix(const scene_part *part)
{
    sw_mat4 s = sw_mat4_scale(sw_v3(part->scale[0], part->scale[1], part->scale[2]));
    sw_mat4 r = sw_mat4_rotate(sw_v3(part->axis[0], part->axis[1], part->axis[2]),
                               part->angle_deg * (SW_PI / 180.0));
    sw_mat4 t = sw_mat4_translate(sw_v3(part->translate[0], part->translate[1],
                                        part->translate[2]));
    sw_mat4 rs = sw_mat4_mul(&r, &s);
    return sw_mat4_mul(&t, &rs);
}

static sw_status load_part(const scene_state *st, const scene_part *part, const char *base_dir,
                           sw_model *model, sw_error *err)
{
    char path[SCENE_PATH_MAX];
    sw_status status = resolve_path(base_dir, part->file, path, err);
    if (status == SW_OK)
        status = sw_model_begin_part(model, part->name, part->color, err);
    if (status == SW_OK)
        status = sw_scene_import_file(path, model, err);
    if (status != SW_OK) {
        sw_error_prefix(err, "%s:%ld: part '%s'", st->file_name, part->file_line, part->name);
        return status;
    }
    sw_mat4 m = part_matrix(part);
    sw_model_transform_part(model, model->part_count - 1, &m);
    return SW_OK;
}

/* Runs inih over the text; on success st->parts holds every part. */
static sw_status parse_scene(scene_state *st)
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
    if (!st->error_line && st->part_count == 0)
        scene_fail(st, SW_ERR_FORMAT, "expected at least one [part NAME] section");
    for (size_t i = 0; !st->error_line && i < st->part_count; i++) {
        if (!(st->parts[i].keys_seen & KEY_FILE)) {
            st->line = st->parts[i].line;
            scene_fail(st, SW_ERR_FORMAT, "part '%s' has no file", st->parts[i].name);
        }
    }
    return st->error_line ? st->status : SW_OK;
}

sw_status sw_scene_load_memory(const char *text, size_t size, const char *file_name,
                               const char *base_dir, sw_model *model, sw_error *err)
{
    if (!model || (!text && size))
        return sw_error_set(err, SW_ERR_ARG, "sw_scene_load_memory: NULL argument");
    scene_state st = {
        .text = text ? text : "",
        .size = size,
        .file_name = file_name ? file_name : "<memory>",
        .err = err,
    };
    sw_status status = parse_scene(&st);
    for (size_t i = 0; status == SW_OK && i < st.part_count; i++)
        status = load_part(&st, &st.parts[i], base_dir, model, err);
    free(st.parts);
    return status;
}

sw_status sw_scene_load(const char *path, sw_model *model, sw_error *err)
{
    if (!path)
        return sw_error_set(err, SW_ERR_ARG, "sw_scene_load: path is NULL");
    char *text;
    size_t size;
    sw_status status = sw_read_whole_file(path, &text, &size, err);
    if (status != SW_OK)
        return status;
    char base_dir[SCENE_PATH_MAX] = "";
    const char *slash = strrchr(path, '/');
    if (slash) {
        size_t len = (size_t)(slash - path);
        if (len == 0)
            len = 1; /* a scene in "/" */
        if (len >= sizeof base_dir) {
            free(text);
            return sw_error_set(err, SW_ERR_ARG, "%s: path too long", path);
        }
        memcpy(base_dir, path, len);
        base_dir[len] = '\0';
    }
    status = sw_scene_load_memory(text, size, path, base_dir, model, err);
    free(text);
    return status;
}
