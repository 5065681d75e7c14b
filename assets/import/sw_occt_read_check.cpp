/* SPDX-License-Identifier: MIT */
/* The file read once by OpenCASCADE in a child process before it is read
 * in this one: OCCT 7.6's readers crash on some damaged files instead of
 * failing (fuzz_step_occt: SIGSEGV in Interface_InterfaceModel::AddEntity
 * on a mutated STEP file), and a crash would take seamwalk-pack down with
 * no word of the file. A child that dies (a signal, or a sanitizer's exit)
 * or does not finish in its time becomes a clear error, and only a file
 * the reader survives is read again in this process. Costs one more parse
 * (not the transfer, the dear part). */
#include "sw_occt_internal.h"

#include <IGESControl_Reader.hxx>
#include <STEPControl_Reader.hxx>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace sw_occt {

namespace {

/* Many times an honest parse's time, even in a sanitizer's build, yet
 * short of a test's or a fuzzer's patience for the files they use: a
 * reader stuck in a loop (OpenCASCADE's entity numbering, on a fuzzed
 * file) becomes an error instead of a hang. */
double allowed_seconds(const char *path)
{
    /* Tests: a reader that never finishes, given this many seconds
     * (test_early_checks.sh). */
    const char *hang = std::getenv("SEAMWALK_TEST_READER_HANG");
    if (hang && std::atof(hang) > 0)
        return std::atof(hang);
    struct stat st;
    double mb = stat(path, &st) == 0 ? (double)st.st_size / (1024.0 * 1024.0) : 0.0;
    return 30.0 + 10.0 * mb;
}

double now_seconds()
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

[[noreturn]] void read_in_child(const char *path, bool step)
{
    /* The parent's crash handlers (a fuzzer's, a sanitizer's) are not the
     * child's business: it dies plainly. */
    const int deadly[] = { SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL };
    for (int sig : deadly)
        std::signal(sig, SIG_DFL);
    int null = open("/dev/null", O_WRONLY);
    if (null >= 0) {
        dup2(null, 1);
        dup2(null, 2);
    }
    /* Tests: a reader that crashes, on any file (test_early_checks.sh). */
    if (std::getenv("SEAMWALK_TEST_READER_CRASH"))
        std::raise(SIGSEGV);
    if (std::getenv("SEAMWALK_TEST_READER_HANG"))
        for (;;)
            pause();
    try {
        if (step) {
            STEPControl_Reader reader;
            reader.ReadFile(path);
        } else {
            IGESControl_Reader reader;
            reader.ReadFile(path);
        }
    } catch (...) {   /* an exception is an answer: the parent reads it again */
    }
    _exit(0);
}

/* Waits for the child until the deadline: true when it ended (status
 * set), false when it was still running and has been killed. Polls: a
 * parse takes milliseconds to seconds, and a sleep that doubles up to
 * 50 ms costs at most that much after it ends. */
bool wait_until(pid_t pid, double deadline, int *status)
{
    long sleep_ns = 1000000;
    for (;;) {
        pid_t got = waitpid(pid, status, WNOHANG);
        if (got == pid)
            return true;
        if (got < 0 && errno != EINTR)
            return true;   /* no such child: nothing to wait for, status 0 */
        if (now_seconds() >= deadline)
            break;
        struct timespec nap = { 0, sleep_ns };
        nanosleep(&nap, NULL);
        if (sleep_ns < 50000000)
            sleep_ns *= 2;
    }
    kill(pid, SIGKILL);
    while (waitpid(pid, status, 0) < 0 && errno == EINTR) {
    }
    return false;
}

}  // namespace

sw_status reader_survives(const char *path, bool step, sw_error *err)
{
    const char *format = step ? "STEP" : "IGES";
    double allowed = allowed_seconds(path);
    std::fflush(stdout);
    std::fflush(stderr);
    pid_t pid = fork();
    if (pid < 0)
        return SW_OK;   /* without fork the file is read in process, as before */
    if (pid == 0)
        read_in_child(path, step);
    int status = 0;
    if (!wait_until(pid, now_seconds() + allowed, &status))
        return sw_error_set(err, SW_ERR_FORMAT, "%s: OpenCASCADE's %s reader did not finish "
                            "reading the file in %.0f s (the time allowed for its size): it is "
                            "damaged or holds what the reader cannot read", path, format, allowed);
    if (WIFSIGNALED(status))
        return sw_error_set(err, SW_ERR_FORMAT, "%s: OpenCASCADE's %s reader crashed on "
                            "the file (signal %d, %s): it is damaged or holds what the reader "
                            "cannot read", path, format, WTERMSIG(status),
                            strsignal(WTERMSIG(status)));
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return sw_error_set(err, SW_ERR_FORMAT, "%s: OpenCASCADE's %s reader failed on the "
                            "file (its reading process ended with status %d): it is damaged or "
                            "holds what the reader cannot read", path, format,
                            WIFEXITED(status) ? WEXITSTATUS(status) : -1);
    return SW_OK;
}

}  // namespace sw_occt
