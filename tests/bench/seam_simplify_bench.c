/* SPDX-License-Identifier: MIT */
/* Seam Graph LOD benchmark: sw_seam_simplify's time and memory on sewn
 * grids of 10^3 .. 10^6 vertices (seam_graph_gen.h), and the runtime
 * selection's arena and update times on the result. Each size runs in a
 * child process so its peak resident memory is its own. Prints a table and
 * one JSON line per size; times are the process's CPU seconds (the machine
 * may be shared). Timing never fails it.
 *
 *   seam_simplify_bench            10^3, 10^4, 10^5, 10^6 vertices
 *   seam_simplify_bench --quick    10^3, 10^4
 *   seam_simplify_bench N          about N vertices */
#define _GNU_SOURCE
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "seam_graph_gen.h"
#include "sw_seam_select.h"
#include "sw_seam_simplify.h"

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

static double peak_rss_mb(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return ru.ru_maxrss / 1024.0;
}

/* The select side: arena bytes, one update from the roots to a mid bound,
 * the same update again (a frame where nothing changes: the fixed cost),
 * one to full detail (bound 0) and one back to the roots. */
static int run_select(const sw_seam_host *host, size_t *arena_bytes, double t[4])
{
    sw_seam_graph g = sw_seam_host_view(host);
    *arena_bytes = sw_seam_select_arena_bytes(&g);
    void *block = malloc(*arena_bytes);
    float *bound = malloc(((size_t)g.surface_count + 1) * sizeof *bound);
    sw_arena arena;
    sw_arena_init(&arena, block, *arena_bytes);
    sw_seam_select sel;
    sw_error err = {0};
    int ok = block && bound && sw_seam_select_init(&sel, &g, &arena, &err) == SW_OK;
    const float levels[4] = {0.01f, 0.01f, 0.0f, 1e30f};
    for (int i = 0; ok && i < 4; i++) {
        for (uint32_t s = 0; s < g.surface_count; s++)
            bound[s] = levels[i];
        double t0 = now_s();
        ok = sw_seam_select_update(&sel, bound, 0, NULL, &err) == SW_OK;
        t[i] = now_s() - t0;
    }
    if (!ok)
        fprintf(stderr, "select: %s\n", err.message);
    free(bound);
    free(block);
    return ok;
}

static int run_size(uint32_t target)
{
    uint32_t k = 8, n = (uint32_t)fmax(2.0, round(sqrt(target / (2.0 * k))));
    seam_gen p = {.nx = n, .ny = n, .k = k, .bumps = 0.05f, .seed = 42};
    sw_seam_host g;
    seam_gen_build(&p, &g);
    uint32_t originals = g.original_count;
    double rss0 = peak_rss_mb(), t0 = now_s();
    sw_error err = {0};
    if (sw_seam_simplify(&g, &err) != SW_OK) {
        fprintf(stderr, "simplify: %s\n", err.message);
        return 1;
    }
    double secs = now_s() - t0, rss1 = peak_rss_mb();
    size_t arena = 0;
    double ts[4] = {0};
    int ok = run_select(&g, &arena, ts);
    printf("%9u vertices %8u surfaces %9u collapses  simplify %8.3f s (%6.2f us/collapse)  "
           "peak +%7.1f MB (total %7.1f MB)  arena %7.1f MB  update mid %7.4f s, full %7.4f s, "
           "roots %7.4f s, unchanged frame %7.4f s\n",
           originals, g.surface_count, g.collapse_count, secs,
           1e6 * secs / (g.collapse_count ? g.collapse_count : 1), rss1 - rss0, rss1,
           arena / 1048576.0, ts[0], ts[2], ts[3], ts[1]);
    printf("{\"bench\":\"seam_simplify\",\"vertices\":%u,\"surfaces\":%u,\"slots\":%u,"
           "\"collapses\":%u,\"simplify_s\":%.6f,\"peak_rss_extra_mb\":%.2f,"
           "\"peak_rss_mb\":%.2f,\"select_arena_bytes\":%zu,\"update_mid_s\":%.6f,"
           "\"update_full_s\":%.6f,\"update_roots_s\":%.6f,\"update_unchanged_s\":%.6f}\n",
           originals, g.surface_count, g.slot_count, g.collapse_count, secs, rss1 - rss0, rss1,
           arena, ts[0], ts[2], ts[3], ts[1]);
    fflush(stdout);
    sw_seam_host_free(&g);
    return ok ? 0 : 1;
}

int main(int argc, char **argv)
{
    uint32_t sizes[4] = {1000, 10000, 100000, 1000000}, count = 4;
    if (argc > 1 && strcmp(argv[1], "--quick") == 0)
        count = 2;
    else if (argc > 1)
        sizes[0] = (uint32_t)strtoul(argv[1], NULL, 10), count = 1;
    int failed = 0;
    for (uint32_t i = 0; i < count; i++) {
        fflush(stdout);
        pid_t pid = fork();
        if (pid == 0)
            _exit(run_size(sizes[i]));
        int status = 0;
        if (pid < 0 || waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) ||
            WEXITSTATUS(status))
            failed = 1;
    }
    return failed;
}
