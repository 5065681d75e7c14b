/* Walk statistics: percentiles, the error histogram's p99, and the JSON
 * contract (every field the stats file promises). */
#include <string.h>

#include "sw_stats.h"
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

static void test_json_has_every_contract_field(void)
{
    sw_arena a;
    sw_arena_init(&a, block, sizeof block);
    sw_stats s;
    SW_CHECK(sw_stats_init(&s, &a, 4, 0.5, NULL) == SW_OK);
    for (int i = 0; i < 4; i++)
        sw_stats_add_frame(&s, 10.0 + i, 1000u * (i + 1), 5);
    sw_stats_add_frame(&s, 99, 99, 99); /* past capacity: ignored */
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

int main(void)
{
    SW_RUN(test_percentiles_are_nearest_rank);
    SW_RUN(test_error_p99_never_understates);
    SW_RUN(test_json_has_every_contract_field);
    return sw_test_finish();
}
