/* seamwalk-pack: the host tool that turns model files into packs and looks
 * inside packs. Commands: build, info, verify (usage below). Exit status: 0
 * success, 1 failure (one line on stderr naming the file), 2 usage error.
 * A failed build never leaves a partial or damaged output file: the pack is
 * written through sw_write_file_atomic only after everything succeeded. */
#include <inttypes.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sw_model.h"
#include "sw_pack.h"
#include "sw_pack_write.h"
#include "sw_scene.h"
#include "sw_text_scan.h"

static const char usage_text[] =
    "usage: seamwalk-pack build INPUT... -o OUT.swpack [--quiet]\n"
    "       seamwalk-pack info [--json] PACK\n"
    "       seamwalk-pack verify PACK\n"
    "       seamwalk-pack --help\n"
    "INPUT: a Newell listing (.txt), Bezier patch text (.bpt) or a scene (.ini).\n"
    "Each .txt/.bpt input becomes one part named after the file; a scene adds its parts.\n";

static int usage_error(const char *fmt, const char *arg)
{
    fputs("seamwalk-pack: ", stderr);
    fprintf(stderr, fmt, arg);
    fputc('\n', stderr);
    fputs(usage_text, stderr);
    return 2;
}

static int fail(const sw_error *err)
{
    fprintf(stderr, "seamwalk-pack: %s\n", err->message);
    return 1;
}

/* ---- build -------------------------------------------------------------- */

/* The part name for a model file: its base name without the extension. */
static void part_name_for(const char *path, char name[56])
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const char *dot = strrchr(base, '.');
    size_t len = dot && dot != base ? (size_t)(dot - base) : strlen(base);
    if (len > 55)
        len = 55;
    memcpy(name, base, len);
    name[len] = '\0';
}

static sw_status add_input(sw_model *model, const char *path, sw_error *err)
{
    if (sw_scene_is_scene_path(path))
        return sw_scene_load(path, model, err);
    char name[56];
    float color[4];
    part_name_for(path, name);
    sw_scene_default_color(model->part_count, color);
    sw_status st = sw_model_begin_part(model, name, color, err);
    return st != SW_OK ? st : sw_scene_import_file(path, model, err);
}

static sw_status build_pack(const char *const *inputs, int input_count, const char *out_path,
                            size_t *bytes_out, sw_model *model, sw_error *err)
{
    sw_status st = SW_OK;
    for (int i = 0; st == SW_OK && i < input_count; i++)
        st = add_input(model, inputs[i], err);
    if (st != SW_OK)
        return st;
    sw_pack_contents contents;
    memset(&contents, 0, sizeof contents);
    uint8_t *bytes = NULL;
    st = sw_pack_contents_from_model(model, &contents, err);
    if (st == SW_OK) {
        st = sw_pack_serialize(&contents, &bytes, bytes_out, err);
        sw_pack_contents_free(&contents);
    }
    if (st == SW_OK)
        st = sw_write_file_atomic(out_path, bytes, *bytes_out, err); /* names the path */
    free(bytes);
    return st;
}

static int cmd_build(int argc, char **argv)
{
    const char *out_path = NULL;
    int quiet = 0, input_count = 0;
    const char **inputs = calloc((size_t)argc + 1, sizeof *inputs);
    if (!inputs)
        return fail(&(sw_error){SW_ERR_NO_MEMORY, "out of memory"});
    for (int i = 0; i < argc; i++) {
        if (strcmp(argv[i], "-o") == 0) {
            if (i + 1 == argc || out_path) {
                free(inputs);
                return usage_error("build: %s needs exactly one OUT.swpack", "-o");
            }
            out_path = argv[++i];
        } else if (strcmp(argv[i], "--quiet") == 0) {
            quiet = 1;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            free(inputs);
            return usage_error("build: unknown option '%s'", argv[i]);
        } else {
            inputs[input_count++] = argv[i];
        }
    }
    if (!out_path || input_count == 0) {
        free(inputs);
        return usage_error("build: %s", !out_path ? "missing -o OUT.swpack" : "no INPUT");
    }
    sw_model model;
    sw_model_init(&model);
    sw_error err = {0};
    size_t bytes = 0;
    sw_status st = build_pack(inputs, input_count, out_path, &bytes, &model, &err);
    if (st == SW_OK && !quiet)
        printf("seamwalk-pack: %zu parts, %zu patches, %zu bytes -> %s\n", model.part_count,
               model.patch_count, bytes, out_path);
    sw_model_free(&model);
    free(inputs);
    return st == SW_OK ? 0 : fail(&err);
}

/* ---- reading a pack --------------------------------------------------- */

/* Reads and validates the pack at path; *bytes must be freed by the caller.
 * malloc's alignment (16 on the hosts we build on) meets the reader's 8. */
static sw_status open_pack(const char *path, char **bytes, sw_pack *pack, sw_error *err)
{
    size_t size;
    sw_status st = sw_read_whole_file(path, bytes, &size, err);
    if (st != SW_OK)
        return st;
    st = sw_pack_open_memory(*bytes, size, pack, err);
    if (st != SW_OK)
        sw_error_prefix(err, "%s", path);
    return st;
}

typedef struct pack_stats {
    uint32_t rational;
    int degree_min[2], degree_max[2]; /* u, v */
    double diagonal;
} pack_stats;

static pack_stats gather_stats(const sw_pack *pack)
{
    pack_stats s = {.degree_min = {SW_BEZIER_MAX_DEGREE, SW_BEZIER_MAX_DEGREE}};
    for (uint32_t i = 0; i < pack->meta->patch_count; i++) {
        const sw_pack_patch *p = &pack->patches[i];
        s.rational += (p->flags & SW_PATCH_RATIONAL) != 0;
        int d[2] = {p->degree_u, p->degree_v};
        for (int k = 0; k < 2; k++) {
            s.degree_min[k] = d[k] < s.degree_min[k] ? d[k] : s.degree_min[k];
            s.degree_max[k] = d[k] > s.degree_max[k] ? d[k] : s.degree_max[k];
        }
    }
    if (pack->meta->patch_count == 0)
        s.degree_min[0] = s.degree_min[1] = 0;
    const float *lo = pack->meta->box_min, *hi = pack->meta->box_max;
    double dx = (double)hi[0] - lo[0], dy = (double)hi[1] - lo[1], dz = (double)hi[2] - lo[2];
    s.diagonal = sqrt(dx * dx + dy * dy + dz * dz);
    return s;
}

/* ---- info, plain text --------------------------------------------------- */

static void print_info_text(const char *path, const sw_pack *pack, const pack_stats *s)
{
    const sw_pack_meta *m = pack->meta;
    printf("%s: seamwalk pack version %" PRIu32 ", %" PRIu64 " bytes\n", path,
           pack->header->version, pack->header->total_size);
    printf("  %-16s %" PRIu32 "\n", "parts", m->part_count);
    for (uint32_t i = 0; i < m->part_count; i++) {
        const sw_pack_part *p = &pack->parts[i];
        printf("    %-20s %6" PRIu32 " patches  colour %.3f %.3f %.3f %.3f\n", p->name,
               p->patch_count, p->color[0], p->color[1], p->color[2], p->color[3]);
    }
    printf("  %-16s %" PRIu32 " (one per Bezier patch for Bezier inputs)\n", "surfaces",
           m->patch_count);
    printf("  %-16s %" PRIu32 "\n", "bezier patches", m->patch_count);
    printf("  %-16s %" PRIu32 "\n", "control points", m->control_count);
    printf("  %-16s %" PRIu32 "\n", "rational", s->rational);
    printf("  %-16s u %d..%d, v %d..%d\n", "degrees", s->degree_min[0], s->degree_max[0],
           s->degree_min[1], s->degree_max[1]);
    printf("  %-16s %" PRIu32 "\n", "adjacency", m->adjacency_count);
    printf("  %-16s %" PRIu32 "\n", "sections", pack->header->section_count);
    for (uint32_t i = 0; i < pack->header->section_count; i++) {
        const sw_pack_section *sec = &pack->sections[i];
        printf("    %-12s offset %10" PRIu64 "  size %10" PRIu64 "\n",
               sw_section_type_name(sec->type), sec->offset, sec->size);
    }
    printf("  %-16s min %g %g %g, max %g %g %g\n", "box", m->box_min[0], m->box_min[1],
           m->box_min[2], m->box_max[0], m->box_max[1], m->box_max[2]);
    printf("  %-16s %g (box diagonal)\n", "model size", s->diagonal);
    printf("  %-16s %" PRIu64 " bytes\n", "runtime memory", pack->header->runtime_bytes);
}

/* ---- info, JSON ------------------------------------------------------------ */

/* Writes s as a JSON string; part names are UTF-8 but may hold anything. */
static void print_json_string(const char *s, size_t max)
{
    putchar('"');
    for (size_t i = 0; i < max && s[i]; i++) {
        unsigned char c = (unsigned char)s[i];
        if (c == '"' || c == '\\')
            printf("\\%c", c);
        else if (c < 0x20 || c == 0x7f)
            printf("\\u%04x", c);
        else
            putchar(c);
    }
    putchar('"');
}

static void print_json_floats(const float *v, int n)
{
    putchar('[');
    for (int k = 0; k < n; k++)
        printf("%s%.9g", k ? ", " : "", v[k]);
    putchar(']');
}

static void print_json_parts(const sw_pack *pack)
{
    printf("  \"parts\": [");
    for (uint32_t i = 0; i < pack->meta->part_count; i++) {
        const sw_pack_part *p = &pack->parts[i];
        printf("%s\n    {\"name\": ", i ? "," : "");
        print_json_string(p->name, sizeof p->name);
        printf(", \"first_patch\": %" PRIu32 ", \"patches\": %" PRIu32 ", \"color\": ",
               p->first_patch, p->patch_count);
        print_json_floats(p->color, 4);
        putchar('}');
    }
    printf("%s],\n", pack->meta->part_count ? "\n  " : "");
}

static void print_json_sections(const sw_pack *pack)
{
    printf("  \"sections\": [");
    for (uint32_t i = 0; i < pack->header->section_count; i++) {
        const sw_pack_section *sec = &pack->sections[i];
        printf("%s\n    {\"type\": %" PRIu32 ", \"name\": \"%s\", \"offset\": %" PRIu64
               ", \"size\": %" PRIu64 "}",
               i ? "," : "", sec->type, sw_section_type_name(sec->type), sec->offset, sec->size);
    }
    printf("\n  ],\n");
}

static void print_info_json(const char *path, const sw_pack *pack, const pack_stats *s)
{
    const sw_pack_meta *m = pack->meta;
    printf("{\n  \"file\": ");
    print_json_string(path, SIZE_MAX);
    printf(",\n  \"version\": %" PRIu32 ",\n  \"total_bytes\": %" PRIu64 ",\n",
           pack->header->version, pack->header->total_size);
    printf("  \"part_count\": %" PRIu32 ",\n", m->part_count);
    print_json_parts(pack);
    printf("  \"surfaces\": %" PRIu32 ",\n", m->patch_count);
    printf("  \"surfaces_note\": \"one per Bezier patch for Bezier inputs\",\n");
    printf("  \"bezier_patches\": %" PRIu32 ",\n", m->patch_count);
    printf("  \"control_points\": %" PRIu32 ",\n", m->control_count);
    printf("  \"rational_patches\": %" PRIu32 ",\n", s->rational);
    printf("  \"degree_u\": [%d, %d],\n  \"degree_v\": [%d, %d],\n", s->degree_min[0],
           s->degree_max[0], s->degree_min[1], s->degree_max[1]);
    printf("  \"adjacency\": %" PRIu32 ",\n", m->adjacency_count);
    print_json_sections(pack);
    printf("  \"box\": {\"min\": ");
    print_json_floats(m->box_min, 3);
    printf(", \"max\": ");
    print_json_floats(m->box_max, 3);
    printf("},\n  \"model_size\": %.9g,\n", s->diagonal);
    printf("  \"runtime_bytes\": %" PRIu64 "\n}\n", pack->header->runtime_bytes);
}

static int cmd_info(int argc, char **argv)
{
    int json = 0;
    const char *path = NULL;
    for (int i = 0; i < argc; i++) {
        if (strcmp(argv[i], "--json") == 0)
            json = 1;
        else if (argv[i][0] == '-' && argv[i][1] != '\0')
            return usage_error("info: unknown option '%s'", argv[i]);
        else if (path)
            return usage_error("info: more than one PACK ('%s')", argv[i]);
        else
            path = argv[i];
    }
    if (!path)
        return usage_error("info: %s", "missing PACK");
    char *bytes = NULL;
    sw_pack pack;
    sw_error err = {0};
    if (open_pack(path, &bytes, &pack, &err) != SW_OK) {
        free(bytes);
        return fail(&err);
    }
    pack_stats stats = gather_stats(&pack);
    if (json)
        print_info_json(path, &pack, &stats);
    else
        print_info_text(path, &pack, &stats);
    free(bytes);
    return 0;
}

/* ---- verify --------------------------------------------------------------- */

static int cmd_verify(int argc, char **argv)
{
    if (argc != 1 || (argv[0][0] == '-' && argv[0][1] != '\0'))
        return usage_error("verify: %s", "expected exactly one PACK");
    char *bytes = NULL;
    sw_pack pack;
    sw_error err = {0};
    sw_status st = open_pack(argv[0], &bytes, &pack, &err);
    if (st == SW_OK)
        printf("%s: ok (%" PRIu32 " patches, %" PRIu64 " bytes)\n", argv[0],
               pack.meta->patch_count, pack.header->total_size);
    free(bytes);
    return st == SW_OK ? 0 : fail(&err);
}

int main(int argc, char **argv)
{
    if (argc < 2)
        return usage_error("%s", "missing command");
    const char *cmd = argv[1];
    if (strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0 || strcmp(cmd, "help") == 0) {
        fputs(usage_text, stdout);
        return 0;
    }
    int rc;
    if (strcmp(cmd, "build") == 0)
        rc = cmd_build(argc - 2, argv + 2);
    else if (strcmp(cmd, "info") == 0)
        rc = cmd_info(argc - 2, argv + 2);
    else if (strcmp(cmd, "verify") == 0)
        rc = cmd_verify(argc - 2, argv + 2);
    else
        return usage_error("unknown command '%s'", cmd);
    /* A full disk or closed pipe on stdout is a failure, not a silent success. */
    if (fflush(stdout) != 0 && rc == 0) {
        fprintf(stderr, "seamwalk-pack: cannot write to standard output\n");
        rc = 1;
    }
    return rc;
}
