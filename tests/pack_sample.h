/* Shared by the pack tests (test_pack.c: the reader; test_pack_write.c: the
 * writer): a small pack built by hand, header and table access for making
 * faulty packs with valid checksums, and a scratch directory for files.
 * Include after sw_test.h. */
#ifndef PACK_SAMPLE_H
#define PACK_SAMPLE_H

#include <dirent.h>
#include <errno.h>
#include <stdint.h>
#include <string.h>
#include <unistd.h>
#include <xxhash.h>

#include "sw_pack.h"
#include "sw_pack_write.h"

/* ---- a small pack built by hand: 2 parts, 3 patches, 1 adjacency ---- */

enum { SAMPLE_CONTROL = 16 + 9 + 16 };

typedef struct sample {
    sw_pack_meta meta;
    sw_pack_part parts[2];
    sw_pack_patch patches[3];
    float control[SAMPLE_CONTROL * 4];
    sw_pack_adjacency adjacency[1];
} sample;

static inline void set_grid(float *ctrl, int du, int dv, float x0, float z_bump, float w_mid)
{
    for (int j = 0; j <= dv; j++)
        for (int i = 0; i <= du; i++) {
            float *c = &ctrl[(j * (du + 1) + i) * 4];
            c[0] = x0 + (float)i / (float)du;
            c[1] = (float)j / (float)dv;
            c[2] = (i > 0 && i < du && j > 0 && j < dv) ? z_bump : 0.0f;
            c[3] = (i == du / 2 && j == dv / 2) ? w_mid : 1.0f;
        }
}

/* Patch boxes from their control points, META's box from the patches. */
static inline void fit_boxes(sample *s)
{
    for (int p = 0; p < 3; p++) {
        sw_pack_patch *pp = &s->patches[p];
        int n = (pp->degree_u + 1) * (pp->degree_v + 1);
        for (int k = 0; k < 3; k++) {
            pp->box_min[k] = pp->box_max[k] = s->control[pp->first_control * 4 + k];
            for (int i = 1; i < n; i++) {
                float v = s->control[(pp->first_control + i) * 4 + k];
                pp->box_min[k] = v < pp->box_min[k] ? v : pp->box_min[k];
                pp->box_max[k] = v > pp->box_max[k] ? v : pp->box_max[k];
            }
            s->meta.box_min[k] = p == 0 || pp->box_min[k] < s->meta.box_min[k] ? pp->box_min[k]
                                                                               : s->meta.box_min[k];
            s->meta.box_max[k] = p == 0 || pp->box_max[k] > s->meta.box_max[k] ? pp->box_max[k]
                                                                               : s->meta.box_max[k];
        }
    }
}

static inline void make_sample(sample *s)
{
    memset(s, 0, sizeof *s);
    s->meta = (sw_pack_meta){ .part_count = 2, .patch_count = 3, .control_count = SAMPLE_CONTROL,
                              .adjacency_count = 1, .units = SW_UNITS_MILLIMETRE,
                              .model_tolerance = 0.01f };
    s->parts[0] = (sw_pack_part){ .first_patch = 0, .patch_count = 2,
                                  .color = { 0.8f, 0.1f, 0.1f, 1.0f }, .name = "body" };
    s->parts[1] = (sw_pack_part){ .first_patch = 2, .patch_count = 1,
                                  .color = { 0.2f, 0.2f, 0.9f, 0.5f }, .name = "lid \xc3\xa9" };
    s->patches[0] = (sw_pack_patch){ .first_control = 0, .degree_u = 3, .degree_v = 3,
                                     .part = 0, .d2_bound = { 1.0f, 0.5f, 2.0f } };
    s->patches[1] = (sw_pack_patch){ .first_control = 16, .degree_u = 2, .degree_v = 2,
                                     .flags = SW_PATCH_RATIONAL, .part = 0,
                                     .d2_bound = { 3.0f, 0.0f, 1.5f } };
    s->patches[2] = (sw_pack_patch){ .first_control = 25, .degree_u = 3, .degree_v = 3,
                                     .part = 1, .d2_bound = { 0.25f, 0.25f, 0.25f } };
    set_grid(&s->control[0], 3, 3, 0.0f, 0.3f, 1.0f);
    set_grid(&s->control[16 * 4], 2, 2, 0.0f, 0.5f, 0.7071f);
    set_grid(&s->control[25 * 4], 3, 3, 1.0f, -0.2f, 1.0f);
    s->adjacency[0] = (sw_pack_adjacency){ .patch_a = 0, .patch_b = 2, .edge_a = SW_EDGE_U1,
                                           .edge_b = SW_EDGE_U0 };
    fit_boxes(s);
}

static inline sw_pack_contents sample_contents(const sample *s)
{
    return (sw_pack_contents){ .meta = s->meta, .parts = s->parts, .patches = s->patches,
                               .control = s->control, .adjacency = s->adjacency };
}

/* Serialised sample; malloc'd, so 8-byte aligned as the reader requires. */
static inline uint8_t *serialize_sample(const sample *s, size_t *size)
{
    sw_pack_contents c = sample_contents(s);
    uint8_t *bytes = NULL;
    sw_error err = { 0 };
    sw_status st = sw_pack_serialize(&c, &bytes, size, &err);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    return bytes;
}

static inline sw_pack_header *header_of(uint8_t *bytes) { return (sw_pack_header *)bytes; }
static inline sw_pack_section *table_of(uint8_t *bytes) { return (sw_pack_section *)(bytes + 64); }

/* Recomputes the header checksum after a test edited the header or table,
 * so the check under test is the one that fires. */
static inline void reseal(uint8_t *bytes)
{
    sw_pack_header *h = header_of(bytes);
    h->header_checksum = 0;
    h->header_checksum = XXH3_64bits(bytes, 64 + (size_t)h->section_count * 32);
}


/* ---- forward compatibility ---- */

/* Adds a 64-byte section of type 99 at the end. The sample's table ends at
 * byte 224 and its first section starts at 256, so a sixth entry fits
 * without moving anything. */
static inline uint8_t *add_unknown_section(const uint8_t *bytes, size_t size, size_t *new_size)
{
    size_t at = (size + 63) / 64 * 64;
    *new_size = at + 64;
    uint8_t *out = calloc(1, *new_size);
    memcpy(out, bytes, size);
    for (int i = 0; i < 64; i++)
        out[at + i] = (uint8_t)(0xA0 + i);
    sw_pack_header *h = header_of(out);
    table_of(out)[h->section_count] = (sw_pack_section){
        .type = 99, .offset = at, .size = 64, .checksum = XXH3_64bits(out + at, 64) };
    h->section_count++;
    h->total_size = *new_size;
    h->runtime_bytes = sw_pack_runtime_bytes(*new_size, 3);
    reseal(out);
    return out;
}


/* ---- files ---- */

/* Each program fills in the X with mkdtemp before using scratch(). */
static char scratch_dir[] = "/tmp/test_pack-XXXXXX";

static inline const char *scratch(const char *name)
{
    static char path[256];
    snprintf(path, sizeof path, "%s/%.200s", scratch_dir, name);
    return path;
}

static inline void write_plain(const char *path, const void *bytes, size_t size)
{
    FILE *f = fopen(path, "wb");
    SW_CHECK_MSG(f && fwrite(bytes, 1, size, f) == size, "%s", path);
    if (f)
        fclose(f);
}

/* Whole file into a malloc'd buffer; NULL when it cannot be read. */
static inline char *read_plain(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    char *buf = malloc(1 << 20);
    *size = fread(buf, 1, 1 << 20, f);
    fclose(f);
    return buf;
}

static inline int file_holds(const char *path, const char *text)
{
    size_t n = 0;
    char *buf = read_plain(path, &n);
    int same = buf && n == strlen(text) && memcmp(buf, text, n) == 0;
    free(buf);
    return same;
}

/* Files in the scratch directory whose names contain ".tmp-". */
static inline int leftover_temp_files(void)
{
    int n = 0;
    DIR *d = opendir(scratch_dir);
    struct dirent *e;
    while (d && (e = readdir(d)))
        n += strstr(e->d_name, ".tmp-") != NULL;
    if (d)
        closedir(d);
    return n;
}


static inline void remove_scratch(void)
{
    DIR *d = opendir(scratch_dir);
    struct dirent *e;
    while (d && (e = readdir(d)))
        if (e->d_name[0] != '.' && unlink(scratch(e->d_name)) != 0 && errno == EISDIR)
            rmdir(scratch(e->d_name));
    if (d)
        closedir(d);
    rmdir(scratch_dir);
}

#endif
