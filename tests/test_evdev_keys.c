/* SPDX-License-Identifier: MIT */
/* The kiosk keyboard on evdev (platform/input/sw_evdev_keys.c) through libevdev,
 * without /dev/input: the device is a pipe carrying recorded input_events,
 * and the kernel's answers to libevdev's ioctls (its name, the keys it
 * has, the keys down now for a resync) come from ioctl below, which this
 * executable defines for the pipe and passes through for every other fd.
 * Everything above the kernel is the real code: libevdev, the backend, the
 * kiosk's held keys. The point is SYN_DROPPED (issue 25): a key released
 * while the kernel dropped events must come back as a release, or the
 * camera walks for ever. */
#define _DEFAULT_SOURCE   /* syscall() */
#include <errno.h>
#include <fcntl.h>
#include <linux/input.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include "sw_config.h"
#include "sw_input_backend.h"
#include "sw_input_fake.h"
#include "sw_kiosk.h"
#include "sw_test.h"

/* ---- the fake kernel ---------------------------------------------------------- */

static int pipe_fd[2] = {-1, -1};
static ino_t pipe_ino;
static unsigned char keys_down[KEY_MAX / 8 + 1];   /* what EVIOCGKEY answers */
static const int has_keys[] = {KEY_A, KEY_SPACE, KEY_UP, KEY_DOWN, KEY_N, KEY_W};

static int is_fake(int fd)
{
    struct stat st;
    return pipe_fd[0] >= 0 && fstat(fd, &st) == 0 && S_ISFIFO(st.st_mode) && st.st_ino == pipe_ino;
}

static void set_bit(unsigned char *bits, int n) { bits[n / 8] |= (unsigned char)(1u << (n % 8)); }

static int fake_ioctl(unsigned long req, void *arg)
{
    if (_IOC_TYPE(req) != 'E')
        return errno = ENOTTY, -1;
    unsigned nr = _IOC_NR(req), size = _IOC_SIZE(req);
    if (_IOC_DIR(req) & _IOC_READ)
        memset(arg, 0, size);
    if (nr == _IOC_NR(EVIOCGVERSION)) {
        *(int *)arg = EV_VERSION;
        return 0;
    }
    if (nr == _IOC_NR(EVIOCGNAME(0))) {
        snprintf(arg, size, "%s", "recorded keyboard");
        return (int)strlen(arg) + 1;
    }
    if (nr == _IOC_NR(EVIOCGPHYS(0)) || nr == _IOC_NR(EVIOCGUNIQ(0)))
        return errno = ENOENT, -1;
    if (nr == _IOC_NR(EVIOCGKEY(0))) {
        memcpy(arg, keys_down, size < sizeof keys_down ? size : sizeof keys_down);
        return (int)size;
    }
    if (nr == _IOC_NR(EVIOCGBIT(0, 0))) {   /* the event types: SYN, KEY, MSC */
        unsigned char *bits = arg;
        set_bit(bits, EV_SYN), set_bit(bits, EV_KEY), set_bit(bits, EV_MSC);
        return (int)size;
    }
    if (nr == _IOC_NR(EVIOCGBIT(EV_KEY, 0))) {
        for (size_t i = 0; i < sizeof has_keys / sizeof has_keys[0]; i++)
            set_bit(arg, has_keys[i]);
        return (int)size;
    }
    if (nr == _IOC_NR(EVIOCGBIT(EV_MSC, 0))) {
        set_bit(arg, MSC_SCAN);
        return (int)size;
    }
    return _IOC_DIR(req) & _IOC_READ ? (int)size : 0;   /* ids, LEDs, switches: none */
}

/* libevdev's ioctls land here; every other fd gets the kernel's. */
int ioctl(int fd, unsigned long req, ...)
{
    va_list ap;
    va_start(ap, req);
    void *arg = va_arg(ap, void *);
    va_end(ap);
    if (is_fake(fd))
        return fake_ioctl(req, arg);
    return (int)syscall(SYS_ioctl, fd, req, arg);
}

static void emit(int type, int code, int value)
{
    struct input_event ev = {.type = (unsigned short)type, .code = (unsigned short)code,
                             .value = value};
    SW_CHECK(write(pipe_fd[1], &ev, sizeof ev) == (ssize_t)sizeof ev);
}

/* A key as the kernel sends it: scan code, key, report; the state follows. */
static void key(int code, int value)
{
    emit(EV_MSC, MSC_SCAN, 0x70000 + code);
    emit(EV_KEY, code, value);
    emit(EV_SYN, SYN_REPORT, 0);
    if (value == 1)
        set_bit(keys_down, code);
    else if (value == 0)
        keys_down[code / 8] &= (unsigned char)~(1u << (code % 8));
}

static sw_key_backend open_fake(void)
{
    if (pipe_fd[0] >= 0)
        close(pipe_fd[0]), close(pipe_fd[1]);
    SW_CHECK(pipe(pipe_fd) == 0);
    struct stat st;
    fstat(pipe_fd[0], &st);
    pipe_ino = st.st_ino;
    memset(keys_down, 0, sizeof keys_down);
    return sw_evdev_key_backend();
}

static char path[64];
static const char *fake_path(void)
{
    snprintf(path, sizeof path, "/proc/self/fd/%d", pipe_fd[0]);
    return path;
}

/* Every key event pending, as "code:value " text. */
static const char *drain(sw_key_backend *kb)
{
    static char out[512];
    int code, value, n = 0;
    out[0] = '\0';
    while (kb->read(kb->ctx, &code, &value) == 1)
        n += snprintf(out + n, sizeof out - (size_t)n, "%d:%d ", code, value);
    return out;
}

/* ---- the backend ------------------------------------------------------------------ */

static void keys_pass_through_with_repeats(void)
{
    sw_key_backend kb = open_fake();
    sw_error err = {0};
    SW_CHECK_MSG(kb.open(kb.ctx, fake_path(), &err) == 0, "%s", err.message);
    key(KEY_N, 1), key(KEY_N, 2), key(KEY_N, 0), key(KEY_UP, 1);
    const char *got = drain(&kb);
    SW_CHECK_MSG(!strcmp(got, "49:1 49:2 49:0 103:1 "), "%s", got);
    SW_CHECK(!strcmp(drain(&kb), ""));   /* nothing pending: 0, not an error */
    kb.close(kb.ctx);
}

/* UP held; the kernel drops events (its buffer overflowed), among them
 * UP's release, then says SYN_DROPPED: the release comes from the resync. */
static void a_release_lost_in_a_drop_comes_back(void)
{
    sw_key_backend kb = open_fake();
    sw_error err = {0};
    SW_CHECK_MSG(kb.open(kb.ctx, fake_path(), &err) == 0, "%s", err.message);
    key(KEY_UP, 1);
    SW_CHECK(!strcmp(drain(&kb), "103:1 "));
    keys_down[KEY_UP / 8] &= (unsigned char)~(1u << (KEY_UP % 8));   /* released, unseen */
    set_bit(keys_down, KEY_W);                                        /* pressed, unseen */
    emit(EV_SYN, SYN_DROPPED, 0);
    emit(EV_KEY, KEY_DOWN, 1);   /* a partial frame after the drop: discarded */
    emit(EV_SYN, SYN_REPORT, 0);
    key(KEY_N, 1);               /* then the device goes on */
    /* The resync, in code order, from the state the kernel has when it is
     * read: W down, N down (already), UP up; N's own event then changes
     * nothing and libevdev drops it, so N is pressed once. DOWN, in the
     * partial frame, never happened as far as the state knows. */
    const char *got = drain(&kb);
    SW_CHECK_MSG(!strcmp(got, "17:1 49:1 103:0 "), "%s", got);
    kb.close(kb.ctx);
}

/* Whether the kernel answers an evdev ioctl on a file that is no device
 * at all: Linux says ENOTTY; qemu-user (the arm64 cross build's tests,
 * tests/cross/arm64.sh) passes no evdev ioctl on and says ENOSYS. */
static int kernel_knows_evdev_ioctls(void)
{
    int fd = open("/dev/null", O_RDONLY | O_CLOEXEC), version = 0;
    long rc = syscall(SYS_ioctl, fd, EVIOCGVERSION, &version);
    int known = !(rc < 0 && errno == ENOSYS);
    close(fd);
    return known;
}

static void a_path_that_is_no_device_is_refused(void)
{
    sw_key_backend kb = sw_evdev_key_backend();
    sw_error err = {0};
    SW_CHECK(kb.open(kb.ctx, "/no/such/event0", &err) == -1);
    SW_CHECK_MSG(strstr(err.message, "/no/such/event0: No such file") != NULL, "%s", err.message);
    SW_CHECK(kb.open(kb.ctx, "/dev/null", &err) == -1);
    if (!kernel_knows_evdev_ioctls()) {
        printf("skip /dev/null's wording: this kernel answers evdev ioctls with ENOSYS\n");
        return;
    }
    SW_CHECK_MSG(strstr(err.message, "/dev/null: not an evdev device") != NULL, "%s", err.message);
}

/* ---- through the kiosk: the camera stops ------------------------------------------ */

static void the_kiosk_stops_walking_after_the_drop(void)
{
    static sw_fake_devices fake;
    static sw_kiosk kiosk;
    static sw_config cfg;
    sw_key_backend kb = open_fake();
    sw_config_defaults(&cfg);
    cfg.kiosk.attract_timeout_s = 0;
    cfg.kiosk.gamepad_enabled = 0;
    sw_fake_init(&fake);
    sw_kiosk_devices dev = {NULL, NULL, &kb, fake_path()};
    sw_nav_params np = sw_kiosk_nav_params(&cfg.kiosk, 0.8, 1.5, 0);
    sw_camera_frame f = sw_camera_frame_for_up(sw_v3(0, 0, 1));
    sw_box box = {sw_v3(-1000, -1000, 0), sw_v3(1000, 1000, 2000)};
    sw_kiosk_init(&kiosk, &cfg.kiosk, &dev, NULL, &np, &f, &box, NULL, 0, 0);
    SW_CHECK(kiosk.keys_on);
    key(KEY_UP, 1);
    sw_kiosk_step(&kiosk, 0, 0.01);
    SW_CHECK(kiosk.last.move == 1);
    keys_down[KEY_UP / 8] = 0;   /* released while the kernel dropped events */
    emit(EV_SYN, SYN_DROPPED, 0);
    emit(EV_SYN, SYN_REPORT, 0);
    sw_kiosk_step(&kiosk, 10000000, 0.01);
    SW_CHECK_MSG(kiosk.last.move == 0, "still walking: move %g", (double)kiosk.last.move);
    sw_kiosk_close(&kiosk);
}

int main(void)
{
    SW_RUN(keys_pass_through_with_repeats);
    SW_RUN(a_release_lost_in_a_drop_comes_back);
    SW_RUN(a_path_that_is_no_device_is_refused);
    SW_RUN(the_kiosk_stops_walking_after_the_drop);
    return sw_test_finish();
}
