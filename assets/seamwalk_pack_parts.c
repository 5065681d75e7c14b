/* SPDX-License-Identifier: MIT */
/* Scenes built in parts (seamwalk_pack_parts.h): `merge` places the packs
 * build-part made of a scene's prototypes, `ninja` writes the build file
 * that runs them. Neither imports a model file: the scene is read for its
 * prototypes and placements only (sw_scene_plan_read). */
#define _XOPEN_SOURCE 700 /* realpath */
#include "seamwalk_pack_parts.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "seamwalk_pack_build.h"
#include "sw_pack_write.h"
#include "sw_text_scan.h"
#include "sw_up_axis.h"
#include "sw_up_inputs.h"

static int usage(const char *fmt, const char *arg)
{
    return sw_usage_error("seamwalk-pack", fmt, arg);
}

static int failed(const sw_error *err)
{
    fprintf(stderr, "seamwalk-pack: %s\n", err->message);
    return 1;
}

/* ---- merge ---------------------------------------------------------------- */

typedef struct merge_args {
    const char *scene, *out;
    const char **parts;
    int part_count, quiet;
    int32_t up_axis;
} merge_args;

static int parse_merge(int argc, char **argv, merge_args *a)
{
    for (int i = 0; i < argc; i++) {
        if (strcmp(argv[i], "-o") == 0 && i + 1 < argc && !a->out) {
            a->out = argv[++i];
        } else if (strcmp(argv[i], "--up") == 0) {
            const char *u = i + 1 < argc ? argv[++i] : "";
            if (!sw_up_axis_parse(u, &a->up_axis))
                return usage("merge: --up takes x, y, z, -x, -y or -z, not '%s'", u);
        } else if (strcmp(argv[i], "--quiet") == 0) {
            a->quiet = 1;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            return usage("merge: unknown option '%s'", argv[i]);
        } else if (!a->scene) {
            a->scene = argv[i];
        } else {
            a->parts[a->part_count++] = argv[i];
        }
    }
    if (!a->scene || !a->out || a->part_count == 0)
        return usage("merge: %s", "takes SCENE.ini, the prototypes' packs and -o OUT.swpack");
    return 0;
}

/* The parts' packs read into bytes[k], one per prototype of the plan. */
static sw_status read_parts(const merge_args *a, const sw_scene_plan *plan, uint8_t **bytes,
                            size_t *sizes, sw_error *err)
{
    if ((size_t)a->part_count != plan->prototype_count)
        return sw_error_set(err, SW_ERR_ARG, "%s names %zu prototypes, %d packs given (one "
                            "per prototype, in order: build-part --prototype 0 .. %zu)",
                            a->scene, plan->prototype_count, a->part_count,
                            plan->prototype_count - 1);
    for (int k = 0; k < a->part_count; k++) {
        char *text = NULL;
        sw_status st = sw_read_whole_file(a->parts[k], &text, &sizes[k], err);
        bytes[k] = (uint8_t *)text;
        if (st != SW_OK)
            return st;
    }
    return SW_OK;
}

int sw_pack_cmd_merge(int argc, char **argv)
{
    merge_args a = { .parts = calloc((size_t)argc + 1, sizeof(char *)) };
    int rc = a.parts ? parse_merge(argc, argv, &a)
                     : failed(&(sw_error){ SW_ERR_NO_MEMORY, "out of memory" });
    if (rc != 0) {
        free(a.parts);
        return rc;
    }
    sw_scene_plan plan;
    sw_error err = { 0 };
    sw_status st = sw_scene_plan_read(a.scene, &plan, &err);
    uint8_t **bytes = calloc((size_t)a.part_count + 1, sizeof *bytes), *out = NULL;
    size_t *sizes = calloc((size_t)a.part_count + 1, sizeof *sizes), size = 0;
    if (st == SW_OK && (!bytes || !sizes))
        st = sw_error_set(&err, SW_ERR_NO_MEMORY, "out of memory");
    if (st == SW_OK)
        st = read_parts(&a, &plan, bytes, sizes, &err);
    if (st == SW_OK) {
        int32_t up = sw_up_input_default(a.scene, plan.views.up_axis);
        plan.views.up_axis = sw_up_inputs_choose(&a.scene, &up, 1, a.up_axis, stderr);
        st = sw_pack_tool_place(&plan, bytes, sizes, &out, &size, &err);
    }
    if (st == SW_OK)
        st = sw_write_file_atomic(a.out, out, size, &err);
    if (st == SW_OK && !a.quiet)
        printf("seamwalk-pack: %zu placements of %zu prototypes, %zu bytes -> %s\n",
               plan.placement_count, plan.prototype_count, size, a.out);
    for (int k = 0; bytes && k < a.part_count; k++)
        free(bytes[k]);
    free(bytes);
    free(sizes);
    free(out);
    sw_scene_plan_free(&plan);
    free(a.parts);
    return st == SW_OK ? 0 : failed(&err);
}

/* ---- ninja ---------------------------------------------------------------- */

/* A path as ninja reads it in a build line: $, space and : escaped. */
static void put_path(FILE *f, const char *p)
{
    for (; *p; p++) {
        if (*p == '$' || *p == ' ' || *p == ':')
            fputc('$', f);
        fputc(*p, f);
    }
}

/* The same quoted for the shell, for a rule's command. */
static void put_shell(FILE *f, const char *p)
{
    fputc('\'', f);
    for (; *p; p++) {
        if (*p == '\'')
            fputs("'\\''", f);
        else if (*p == '$')
            fputs("$$", f);
        else if (*p == '\n')
            fputc(' ', f);
        else
            fputc(*p, f);
    }
    fputc('\'', f);
}

static char *absolute(const char *path)
{
    char *r = realpath(path, NULL);
    return r ? r : strdup(path);
}

/* This program's own path: what the build file runs. */
static char *own_path(void)
{
    char buf[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
    if (n <= 0)
        return strdup("seamwalk-pack");
    buf[n] = '\0';
    return strdup(buf);
}

static void write_ninja(FILE *f, const char *tool, const char *scene, const sw_scene_plan *plan,
                        const char *pack, char **flags, int flag_count)
{
    fprintf(f, "# Written by seamwalk-pack ninja: each prototype of the scene packed apart\n"
               "# (build-part), then placed (merge); the same pack as seamwalk-pack build.\n"
               "ninja_required_version = 1.3\ntool = ");
    put_shell(f, tool);
    fprintf(f, "\nscene = ");
    put_shell(f, scene);
    fprintf(f, "\nflags =");
    for (int i = 0; i < flag_count; i++) {
        fputc(' ', f);
        put_shell(f, flags[i]);
    }
    fprintf(f, "\nrule part\n  command = $tool build-part $scene --prototype $k -o $out --quiet "
               "--threads 1 $flags\n  description = prototype $k\n"
               "rule place\n  command = $tool merge $scene $in -o $out --quiet\n"
               "  description = placing $out\n");
    for (size_t k = 0; k < plan->prototype_count; k++) {
        fprintf(f, "build parts/prototype_%zu.swpack: part | ", k);
        put_path(f, scene);
        fputc(' ', f);
        put_path(f, tool);
        /* every file: a prototype's tolerance follows the whole scene's size */
        for (size_t j = 0; j < plan->prototype_count; j++)
            if (plan->sources[j]) {
                fputc(' ', f);
                put_path(f, plan->sources[j]);
            }
        fprintf(f, "\n  k = %zu\n", k);
    }
    fputs("build ", f);
    put_path(f, pack);
    fputs(": place", f);
    for (size_t k = 0; k < plan->prototype_count; k++)
        fprintf(f, " parts/prototype_%zu.swpack", k);
    fputs(" | ", f);
    put_path(f, scene);
    fputs("\ndefault ", f);
    put_path(f, pack);
    fputc('\n', f);
}

int sw_pack_cmd_ninja(int argc, char **argv)
{
    const char *scene = NULL, *out = NULL, *pack = NULL;
    int flags_at = argc;
    for (int i = 0; i < argc; i++) {
        if (strcmp(argv[i], "--") == 0) {
            flags_at = i + 1;
            break;
        } else if (strcmp(argv[i], "-o") == 0 && i + 1 < argc && !out) {
            out = argv[++i];
        } else if (strcmp(argv[i], "--pack") == 0 && i + 1 < argc && !pack) {
            pack = argv[++i];
        } else if (argv[i][0] == '-') {
            return usage("ninja: unknown option '%s'", argv[i]);
        } else if (!scene) {
            scene = argv[i];
        } else {
            return usage("ninja: one SCENE.ini, not also '%s'", argv[i]);
        }
    }
    if (!scene || !out)
        return usage("ninja: %s", "takes SCENE.ini and -o build.ninja");
    char name[512];
    if (!pack) {
        const char *base = sw_pack_tool_base_name(scene), *dot = strrchr(base, '.');
        snprintf(name, sizeof name, "%.*s.swpack", dot ? (int)(dot - base) : (int)strlen(base),
                 base);
        pack = name;
    }
    sw_scene_plan plan;
    sw_error err = { 0 };
    sw_status st = sw_scene_plan_read(scene, &plan, &err);
    char *tool = own_path(), *full = absolute(scene);
    char tmp[4200];
    FILE *f = NULL;
    if (st == SW_OK && snprintf(tmp, sizeof tmp, "%s.tmp", out) >= (int)sizeof tmp)
        st = sw_error_set(&err, SW_ERR_ARG, "%.200s...: the name is too long", out);
    if (st == SW_OK && !(f = fopen(tmp, "w")))
        st = sw_error_set(&err, SW_ERR_IO, "%s: cannot write", tmp);
    if (st == SW_OK) {
        write_ninja(f, tool, full, &plan, pack, argv + flags_at, argc - flags_at);
        if (fclose(f) != 0 || rename(tmp, out) != 0)
            st = sw_error_set(&err, SW_ERR_IO, "%s: cannot write", out);
    }
    if (st == SW_OK)
        printf("seamwalk-pack: %zu prototypes and the placing -> %s (ninja -f %s)\n",
               plan.prototype_count, out, out);
    free(tool);
    free(full);
    sw_scene_plan_free(&plan);
    return st == SW_OK ? 0 : failed(&err);
}
