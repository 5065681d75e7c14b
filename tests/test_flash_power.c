/* SPDX-License-Identifier: MIT */
/* Power loss during seamwalk-flash install: the installer is killed with
 * SIGKILL at random points, and after each kill the unit must boot the old
 * pack or the new one, verified (seamwalk-flash boot-check: the runtime's
 * decision and checks), never neither. Two kinds of kill point:
 *   - by call: the fault shim raises SIGKILL just before the Nth file-changing
 *     call (N random in 1..the calls of a whole install), so every step of the
 *     install can be hit whatever the machine's speed;
 *   - by timer: kill(SIGKILL) after a random delay up to the time a whole
 *     install takes.
 * Some killed stores are kept for the next trial, so installs that resume
 * an interrupted one are killed too.
 *   test_flash_power FLASH SHIM FIXTURE WORK CALL_TRIALS TIMED_TRIALS SEED */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "sw_test.h"

static const char *flash, *shim, *fixture, *work;
static char store[512], template_dir[512], out_path[512], config[1024];

/* Starts FLASH with args under the shim, output to out_path. */
static pid_t spawn(const char *cmd, const char *pack, const char *kill_at, const char *count)
{
    fflush(NULL); /* or the child's freopen writes our buffered lines again */
    pid_t pid = fork();
    if (pid != 0)
        return pid;
    FILE *out = freopen(out_path, "w", stdout);
    if (!out || dup2(fileno(stdout), 2) < 0)
        _exit(127);
    setenv("LD_PRELOAD", shim, 1);
    setenv("ASAN_OPTIONS", "verify_asan_link_order=0:detect_leaks=0", 1);
    if (kill_at)
        setenv("SW_FAULT_KILL_AT", kill_at, 1);
    if (count)
        setenv("SW_FAULT_COUNT_FILE", count, 1);
    char *argv[] = { (char *)flash, (char *)cmd, "--store", store, "--config", config,
                     "--chunk-kb", "32", "--quiet", (char *)pack, NULL };
    if (!pack)
        argv[6] = NULL; /* boot-check: just the store and the unit's config */
    execv(flash, argv);
    _exit(127);
}

static int wait_for(pid_t pid)
{
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        ;
    return status;
}

static char *slurp(const char *path)
{
    static char buf[8192];
    FILE *f = fopen(path, "r");
    size_t n = f ? fread(buf, 1, sizeof buf - 1, f) : 0;
    if (f)
        fclose(f);
    buf[n] = '\0';
    return buf;
}

/* The version boot-check says the unit would start, verified; -1 if none
 * or if it could not tell (a damaged state is a failure too). */
static int boot_version(void)
{
    int status = wait_for(spawn("boot-check", NULL, NULL, NULL));
    const char *text = slurp(out_path);
    const char *line = strstr(text, "boot: slot ");
    const char *v = line ? strstr(line, "' version ") : NULL;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !v || !strstr(v, "verified")) {
        fprintf(stderr, "boot-check failed (status %d): %s\n", status, text);
        return -1;
    }
    return atoi(v + strlen("' version "));
}

static void reset_store(void)
{
    char cmd[4096];
    snprintf(cmd, sizeof cmd, "rm -rf '%s' && cp -a '%s' '%s'", store, template_dir, store);
    SW_CHECK(system(cmd) == 0);
}

static void make_template(void)
{
    char cmd[8192];
    snprintf(cmd, sizeof cmd, "rm -rf '%s' && mkdir -p '%s' && "
             "'%s' install --store '%s' --config '%s' --quiet '%s/old.swpack' >/dev/null && "
             "'%s' mark-good --store '%s' --config '%s' >/dev/null", template_dir, template_dir,
             flash, template_dir, config, fixture, flash, template_dir, config);
    SW_CHECK(system(cmd) == 0);
}

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

typedef struct tally {
    int trials, survivals, old, new_, killed, completed, resumed;
} tally;

static char new_pack[1024];

/* One trial's aftermath: the boot must be the old pack (1) or the new (2). */
static int record(tally *t, int status)
{
    int killed = WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
    int done = WIFEXITED(status) && WEXITSTATUS(status) == 0;
    SW_CHECK_MSG(killed || done, "install ended with status %d: %s", status, slurp(out_path));
    t->killed += killed;
    t->completed += done;
    t->resumed += done && strstr(slurp(out_path), "resumed an interrupted install") != NULL;
    int v = boot_version();
    t->trials++;
    t->survivals += v == 1 || v == 2;
    t->old += v == 1;
    t->new_ += v == 2;
    SW_CHECK_MSG(v == 1 || v == 2, "trial %d: the unit would boot neither pack", t->trials);
    return killed && v == 1;
}

/* Calls and seconds of one whole install of the new pack. */
static long measure_install(double *seconds)
{
    char count_path[1100], *end;
    snprintf(count_path, sizeof count_path, "%s/calls", work);
    reset_store();
    double t0 = now_s();
    int status = wait_for(spawn("install", new_pack, NULL, count_path));
    *seconds = now_s() - t0;
    SW_CHECK_MSG(WIFEXITED(status) && WEXITSTATUS(status) == 0, "%s", slurp(out_path));
    long calls = strtol(slurp(count_path), &end, 10);
    SW_CHECK(boot_version() == 2);
    return calls;
}

static void kill_by_call(tally *t, int trials, long calls)
{
    int keep = 0;
    for (int i = 0; i < trials; i++) {
        if (!keep)
            reset_store();
        char at[32];
        snprintf(at, sizeof at, "%ld", 1 + rand() % calls);
        keep = record(t, wait_for(spawn("install", new_pack, at, NULL))) && rand() % 2;
    }
}

static void kill_by_timer(tally *t, int trials, double seconds)
{
    int keep = 0;
    for (int i = 0; i < trials; i++) {
        if (!keep)
            reset_store();
        double delay = seconds * 1.2 * (rand() / (RAND_MAX + 1.0));
        struct timespec ts = { (time_t)delay, (long)((delay - (double)(time_t)delay) * 1e9) };
        pid_t pid = spawn("install", new_pack, NULL, NULL);
        nanosleep(&ts, NULL);
        kill(pid, SIGKILL);
        keep = record(t, wait_for(pid)) && rand() % 2;
    }
}

/* Deterministic: killed half-way, the same install again resumes. */
static void test_interrupted_install_resumes(long calls)
{
    reset_store();
    char at[32];
    snprintf(at, sizeof at, "%ld", calls / 2);
    int status = wait_for(spawn("install", new_pack, at, NULL));
    SW_CHECK(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
    SW_CHECK(boot_version() == 1);
    status = wait_for(spawn("install", new_pack, NULL, NULL));
    SW_CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    SW_CHECK_MSG(strstr(slurp(out_path), "resumed an interrupted install at byte"), "%s",
                 slurp(out_path));
    SW_CHECK(boot_version() == 2);
}

int main(int argc, char **argv)
{
    if (argc != 8) {
        fprintf(stderr, "usage: %s FLASH SHIM FIXTURE WORK CALL_TRIALS TIMED_TRIALS SEED\n",
                argv[0]);
        return 2;
    }
    if (geteuid() != 0) { /* the unit's trusted keys must be root's (firmware/store/STORE.md) */
        printf("skipped: needs root, for trusted keys owned by root\n");
        return 77;
    }
    flash = argv[1], shim = argv[2], fixture = argv[3], work = argv[4];
    int call_trials = atoi(argv[5]), timed_trials = atoi(argv[6]);
    unsigned seed = (unsigned)strtoul(argv[7], NULL, 10);
    srand(seed);
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "rm -rf '%s' && mkdir -p '%s'", work, work);
    SW_CHECK(system(cmd) == 0);
    snprintf(store, sizeof store, "%s/unit", work);
    snprintf(template_dir, sizeof template_dir, "%s/template", work);
    snprintf(config, sizeof config, "%s/unit.ini", fixture); /* names the fixture's keys */
    snprintf(out_path, sizeof out_path, "%s/out.txt", work);
    snprintf(new_pack, sizeof new_pack, "%s/new.swpack", fixture);
    make_template();
    double seconds;
    long calls = measure_install(&seconds);
    printf("a whole install: %ld file-changing calls, %.3f s\n", calls, seconds);
    SW_CHECK(calls > 20);
    tally by_call = { 0 }, by_timer = { 0 };
    if (calls > 0)
        kill_by_call(&by_call, call_trials, calls);
    kill_by_timer(&by_timer, timed_trials, seconds);
    int before = sw_test_failures;
    test_interrupted_install_resumes(calls);
    printf("%s test_interrupted_install_resumes\n", sw_test_failures == before ? "ok  " : "FAIL");
    const tally *ts[2] = { &by_call, &by_timer };
    const char *names[2] = { "by call", "by timer" };
    for (int i = 0; i < 2; i++)
        printf("power loss %s (seed %u): %d trials, %d survivals (old pack %d, new pack %d), "
               "neither %d; %d killed, %d completed, %d of them resumed\n", names[i], seed,
               ts[i]->trials, ts[i]->survivals, ts[i]->old, ts[i]->new_,
               ts[i]->trials - ts[i]->survivals, ts[i]->killed, ts[i]->completed,
               ts[i]->resumed);
    SW_CHECK(by_call.trials == call_trials && by_timer.trials == timed_trials);
    return sw_test_finish();
}
