/* SPDX-License-Identifier: MIT */
/* Walk statistics: percentiles, the error histogram's p99, and the JSON
 * contract (every field the stats file promises). */
#include <string.h>

#include "sw_stats.h"
#include "sw_rss.h"
#include "sw_test.h"

static unsigned char block[1 << 20] __attribute__((aligned(64)));

static void test_percentiles_are_nearest_rank(void)
{
    float v[100];
    for (int i = 0; i < 100; i++)
        v[i] = (float)(100 - i); /* 100..1, unsorted */
    sw_percentiles p = sw_percentiles_of(v, 100);
    SW_CHECK(p.p50 == 50 && p.p90 == 90 && p.p99 == 99 && p.max == 100);
    float one[1] = { 7 };
    p = sw_percentiles_of(one, 1);
    SW_CHECK(p.p50 == 7 && p.p99 == 7 && p.max == 7);
}

static void test_error_p99_never_understates(void)
{
    sw_arena a;
    sw_arena_init(&a, block, sizeof block);
    sw_stats s;
    SW_CHECK(sw_stats_init(&s, &a, 10, 0.5, NULL) == SW_OK);
    for (int i = 0; i < 990; i++)
        sw_stats_add_error_px(&s, 0.1);
    for (int i = 0; i < 10; i++)
        sw_stats_add_error_px(&s, 0.45);
    double p99 = sw_stats_error_p99(&s);
    SW_CHECK(p99 >= 0.1 && p99 <= 0.1 + s.error_bin_px);
    sw_stats_add_error_px(&s, 0.46);
    sw_stats_add_error_px(&s, 0.47);
    SW_CHECK(sw_stats_error_p99(&s) >= 0.45);
    SW_CHECK(s.error_max_px == 0.47);
    sw_stats_add_error_px(&s, 9.0); /* beyond the histogram: still the exact max */
    SW_CHECK(s.error_max_px == 9.0 && s.error_overflow == 1);
}

/* A mesh drawn behind the view (route_behind) is counted apart: its samples
 * leave error_px alone and make error_px_behind. */
static void test_behind_samples_are_kept_apart(void)
{
    sw_arena a;
    sw_arena_init(&a, block, sizeof block);
    sw_stats s;
    SW_CHECK(sw_stats_init(&s, &a, 4, 0.5, NULL) == SW_OK);
    sw_stats_add_error_px(&s, 0.2);
    s.route_behind = 1;
    sw_stats_add_error_px(&s, 0.9);
    sw_stats_add_error_px(&s, 0.7);
    s.route_behind = 0;
    sw_stats_add_error_px(&s, 0.3);
    SW_CHECK(s.error_max_px == 0.3 && s.error_samples == 2);
    SW_CHECK(s.error_behind_max_px == 0.9 && s.error_behind_samples == 2);
    sw_stats_add_frame(&s, 10.0, 1000u, 5);
    char buf[8192] = "";
    FILE *f = fmemopen(buf, sizeof buf - 1, "w");
    SW_CHECK(sw_stats_write_json(&s, f, &a, NULL) == SW_OK);
    fclose(f);
    SW_CHECK_MSG(strstr(buf, "\"error_px_behind\": {\"max\": 0.90000") != NULL, "%s", buf);
}

static void test_json_has_every_contract_field(void)
{
    sw_arena a;
    sw_arena_init(&a, block, sizeof block);
    sw_stats s;
    SW_CHECK(sw_stats_init(&s, &a, 4, 0.5, NULL) == SW_OK);
    for (int i = 0; i < 4; i++)
        sw_stats_add_frame(&s, 10.0 + i, 1000u * (i + 1), 5);
    sw_stats_add_error_px(&s, 0.25);
    s.mallocs_after_init = 0;
    char buf[4096] = "";
    FILE *f = fmemopen(buf, sizeof buf - 1, "w");
    SW_CHECK(sw_stats_write_json(&s, f, &a, NULL) == SW_OK);
    fclose(f);
    const char *fields[] = { "\"frames\": 4", "\"frame_ms\"", "\"p50\": 11.000", "\"p90\"",
                             "\"p99\"", "\"max\": 13.000", "\"fps_median\"", "\"tris_per_frame\"",
                             "\"median\": 2000", "\"max\": 4000", "\"patches\"", "\"total\"",
                             "\"visible_median\": 5", "\"error_px\"", "\"max\": 0.25000",
                             "\"cracks_max\"", "\"arena_bytes\"", "\"mallocs_after_init\": 0",
                             "\"pack_open_ms\"", "\"first_frame_ms\"" };
    for (size_t i = 0; i < sizeof fields / sizeof fields[0]; i++)
        SW_CHECK_MSG(strstr(buf, fields[i]) != NULL, "missing %s in\n%s", fields[i], buf);
}

/* Past its capacity (the soak) the arrays keep the last frames, oldest
 * replaced first; the worst frame and the count cover every frame. */
static void test_frames_past_capacity_keep_the_last_ones(void)
{
    sw_arena a;
    sw_arena_init(&a, block, sizeof block);
    sw_stats s;
    SW_CHECK(sw_stats_init(&s, &a, 3, 0.5, NULL) == SW_OK);
    const double ms[7] = { 5, 50, 6, 7, 8, 9, 10 };
    for (int i = 0; i < 7; i++) {
        sw_stats_add_cache_frame(&s, (uint32_t)i, 0, 0, 0, 1.0);
        sw_stats_add_frame(&s, ms[i], 100u + (uint32_t)i, 1);
    }
    SW_CHECK(s.frames == 3);
    SW_CHECK(s.frames_total == 7);
    SW_CHECK(s.worst_frame_ms == 50.0 && s.worst_frame == 1);
    char buf[8192] = "";
    FILE *f = fmemopen(buf, sizeof buf - 1, "w");
    SW_CHECK(sw_stats_write_json(&s, f, &a, NULL) == SW_OK);
    fclose(f);
    const char *fields[] = { "\"frames\": 3", "\"max\": 10.000", "\"median\": 105",
                             "\"frame_ms_series\": [8.000, 9.000, 10.000]",
                             "\"frames_total\": 7", "\"worst_frame\": {\"ms\": 50.000, \"frame\": 1}",
                             "\"rss_kb\": {\"start\": -1", "\"frames_per_loop\": 3" };
    for (size_t i = 0; i < sizeof fields / sizeof fields[0]; i++)
        SW_CHECK_MSG(strstr(buf, fields[i]) != NULL, "missing %s in\n%s", fields[i], buf);
}

/* The cache pools' fill: the most of each figure over the frames, written
 * with the capacity. */
static void test_cache_fill_keeps_the_most(void)
{
    sw_arena a;
    sw_arena_init(&a, block, sizeof block);
    sw_stats s;
    SW_CHECK(sw_stats_init(&s, &a, 4, 0.5, NULL) == SW_OK);
    s.pool_vertices = 1024, s.pool_indices = 6144;
    const uint64_t fill[3][4] = { { 500, 2000, 100, 400 }, { 300, 3000, 200, 300 },
                                  { 900, 1000, 50, 800 } };
    for (int i = 0; i < 3; i++) {
        sw_stats_add_cache_fill(&s, fill[i][0], fill[i][1], fill[i][2], fill[i][3]);
        sw_stats_add_frame(&s, 10.0, 100, 1);
    }
    char buf[8192] = "";
    FILE *f = fmemopen(buf, sizeof buf - 1, "w");
    SW_CHECK(sw_stats_write_json(&s, f, &a, NULL) == SW_OK);
    fclose(f);
    const char *want = "\"pool\": {\"vertices\": 1024, \"indices\": 6144, "
                       "\"used_vertices_max\": 900, \"used_indices_max\": 3000, "
                       "\"drawn_vertices_max\": 200, \"drawn_indices_max\": 800}";
    SW_CHECK_MSG(strstr(buf, want) != NULL, "missing %s in\n%s", want, buf);
}

static void test_rss_fields_are_read_from_status_text(void)
{
    const char text[] = "Name:\tseamwalk\nVmHWM:\t  123456 kB\nVmRSS:\t   98765 kB\n"
                        "RssAnon:\t 1 kB\n";
    int n = (int)sizeof text - 1;
    SW_CHECK(sw_rss_field_kb(text, n, "VmRSS:") == 98765);
    SW_CHECK(sw_rss_field_kb(text, n, "VmHWM:") == 123456);
    SW_CHECK(sw_rss_field_kb(text, n, "VmSwap:") == -1);
    SW_CHECK(sw_rss_field_kb("VmRSS: kB\n", 10, "VmRSS:") == -1);
    /* only at a line's start: "RssAnon:" is not "Anon:" */
    SW_CHECK(sw_rss_field_kb(text, n, "Anon:") == -1);
    sw_rss r;
    SW_CHECK(sw_rss_read(&r) == 1);   /* this process, on Linux */
    SW_CHECK(r.rss_kb > 0 && r.peak_kb >= r.rss_kb);
    /* Its own pages and its mapped files' (the program itself, at least):
     * parts of VmRSS (the rest is shared memory). */
    SW_CHECK_MSG(r.anon_kb > 0 && r.file_kb > 0 && r.anon_kb + r.file_kb <= r.rss_kb,
                 "anon %lld, file %lld, rss %lld", (long long)r.anon_kb, (long long)r.file_kb,
                 (long long)r.rss_kb);
}

int main(void)
{
    SW_RUN(test_percentiles_are_nearest_rank);
    SW_RUN(test_cache_fill_keeps_the_most);
    SW_RUN(test_error_p99_never_understates);
    SW_RUN(test_behind_samples_are_kept_apart);
    SW_RUN(test_json_has_every_contract_field);
    SW_RUN(test_frames_past_capacity_keep_the_last_ones);
    SW_RUN(test_rss_fields_are_read_from_status_text);
    return sw_test_finish();
}
