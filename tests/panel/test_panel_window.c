/* SPDX-License-Identifier: MIT */
/* The simulator's live window: under a private Xvfb server the SDL2 window
 * opens, shows a frame of an emulated panel, and a screenshot of it (taken
 * from the X server, not from SDL) equals the PNG written for the same frame,
 * each panel pixel a scale x scale block. Skipped, with the reason, when Xvfb
 * cannot start. */
#include <errno.h>
#include <poll.h>
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include "ptest.h"
#include "emu_window.h"

/* SDL and Xlib keep caches for the life of the process: not our leaks. */
const char *__asan_default_options(void);
const char *__asan_default_options(void)
{
    return "detect_leaks=0";
}

static pid_t xvfb_pid = -1;
static char why_not[256];

static int x_errors;
static int on_x_error(Display *d, XErrorEvent *e)
{
    (void)d;
    if (getenv("ZS_DEBUG_WINDOW"))
        print_message("    X error %d request %d resource 0x%lx\n", e->error_code,
                      e->request_code, (unsigned long)e->resourceid);
    x_errors++;
    return 0;
}

/* Starts Xvfb on a free display (it tells us which through -displayfd). */
static int start_xvfb(void)
{
    int fds[2], n = 0;
    char fdarg[16], buf[32];
    struct pollfd pfd;

    if (pipe(fds) != 0) {
        snprintf(why_not, sizeof why_not, "pipe: %s", strerror(errno));
        return -1;
    }
    xvfb_pid = fork();
    if (xvfb_pid < 0) {
        snprintf(why_not, sizeof why_not, "fork: %s", strerror(errno));
        return -1;
    }
    if (xvfb_pid == 0) {
        close(fds[0]);
        snprintf(fdarg, sizeof fdarg, "%d", fds[1]);
        freopen("/dev/null", "w", stderr);
        execlp("Xvfb", "Xvfb", "-displayfd", fdarg, "-screen", "0", "800x600x24", "-nolisten",
               "tcp", (char *)NULL);
        _exit(127);
    }
    close(fds[1]);
    pfd.fd = fds[0];
    pfd.events = POLLIN;
    while (n < (int)sizeof buf - 1 && poll(&pfd, 1, 15000) > 0) {
        ssize_t k = read(fds[0], buf + n, sizeof buf - 1 - (size_t)n);
        if (k <= 0)
            break;
        n += (int)k;
        if (buf[n - 1] == '\n')
            break;
    }
    close(fds[0]);
    buf[n] = '\0';
    if (n == 0 || buf[0] < '0' || buf[0] > '9') {
        int status;
        snprintf(why_not, sizeof why_not,
                 "Xvfb did not start (not installed? `make deps` installs xvfb)");
        kill(xvfb_pid, SIGTERM);
        waitpid(xvfb_pid, &status, 0);
        xvfb_pid = -1;
        return -1;
    }
    buf[strcspn(buf, "\n")] = '\0';
    {
        char disp[40];
        snprintf(disp, sizeof disp, ":%s", buf);
        setenv("DISPLAY", disp, 1);
    }
    setenv("SDL_VIDEODRIVER", "x11", 1);
    return 0;
}

static void stop_xvfb(void)
{
    if (xvfb_pid > 0) {
        int status;
        kill(xvfb_pid, SIGTERM);
        waitpid(xvfb_pid, &status, 0);
        xvfb_pid = -1;
    }
}

static int group_setup(void **state)
{
    (void)state;
    if (start_xvfb() != 0)
        print_message("    window test: %s\n", why_not);
    return 0;
}

static int group_teardown(void **state)
{
    (void)state;
    stop_xvfb();
    return 0;
}

/* Screenshot of an X window as 8-bit RGB; 0 on success. */
static int grab(Display *dpy, Window w, unsigned width, unsigned height, uint8_t *out)
{
    XImage *im;
    unsigned x, y;
    XSync(dpy, False);
    x_errors = 0;
    im = XGetImage(dpy, w, 0, 0, width, height, AllPlanes, ZPixmap);
    XSync(dpy, False);
    if (im == NULL || x_errors)
        return -1;
    for (y = 0; y < height; y++)
        for (x = 0; x < width; x++) {
            unsigned long p = XGetPixel(im, (int)x, (int)y);
            uint8_t *o = out + ((size_t)y * width + x) * 3;
            o[0] = (uint8_t)((p & im->red_mask) >> __builtin_ctzl(im->red_mask));
            o[1] = (uint8_t)((p & im->green_mask) >> __builtin_ctzl(im->green_mask));
            o[2] = (uint8_t)((p & im->blue_mask) >> __builtin_ctzl(im->blue_mask));
        }
    XDestroyImage(im);
    return 0;
}

static unsigned diff_scaled(const uint8_t *shot, const uint8_t *png, unsigned w, unsigned h,
                            unsigned scale)
{
    unsigned x, y, bad = 0;
    for (y = 0; y < h * scale; y++)
        for (x = 0; x < w * scale; x++)
            bad += memcmp(shot + ((size_t)y * w * scale + x) * 3,
                          png + ((size_t)(y / scale) * w + x / scale) * 3, 3) != 0;
    return bad;
}

static void test_window_screenshot_matches_png(void **state)
{
    const unsigned scale = 2, rot = 1;
    const char *png_path = "build/tests/panel/window_frame.png";
    pt_rig r;
    unsigned w, h, x, y, bad = 1, tries;
    uint8_t *img, *rgb, *png = NULL, *shot;
    unsigned pw = 0, ph = 0;
    char err[160];
    emu_window *win;
    Display *dpy;
    Window xw;
    (void)state;

    if (xvfb_pid <= 0) {
        print_message("    SKIPPED: %s\n", why_not);
        skip();
    }
    /* A frame on a non-square panel turned 90 degrees. */
    assert_int_equal(pt_rig_open(&r, &zs_panel_st7789_135x240, ZS_FMT_RGB565_BE, rot, 0, 0, 0),
                     ZS_PANEL_OK);
    w = r.panel.width;
    h = r.panel.height;
    img = malloc((size_t)w * h * 2);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++)
            pt_pattern_pixel(x, y, ZS_FMT_RGB565_BE, img + ((size_t)y * w + x) * 2);
    assert_int_equal(zs_panel_window(&r.panel, 0, 0, (uint16_t)w, (uint16_t)h), ZS_PANEL_OK);
    assert_int_equal(zs_panel_write(&r.panel, img, (size_t)w * h * 2), ZS_PANEL_OK);
    assert_int_equal(r.emu.errors, 0);
    assert_int_equal(emu_write_png(&r.emu, rot, png_path), 0);
    assert_int_equal(emu_png_read_rgb(png_path, &png, &pw, &ph), 0);
    assert_int_equal(pw, w);
    assert_int_equal(ph, h);
    rgb = malloc((size_t)w * h * 3);
    emu_view_rgb(&r.emu, rot, rgb);

    win = emu_window_open("zspan test", w, h, scale, err, sizeof err);
    if (win == NULL)
        print_message("    window: %s\n", err);
    assert_non_null(win);
    xw = (Window)emu_window_x11_id(win);
    assert_true(xw != 0);
    XSetErrorHandler(on_x_error);
    dpy = XOpenDisplay(NULL);
    assert_non_null(dpy);
    shot = malloc((size_t)w * h * scale * scale * 3);
    /* The window maps asynchronously: show, let it settle, compare; retry. */
    for (tries = 0; tries < 100 && bad != 0; tries++) {
        struct timespec ts = {0, 50000000};
        emu_window_poll(win);
        assert_int_equal(emu_window_show(win, rgb, w, h), 0);
        nanosleep(&ts, NULL);
        emu_window_poll(win);
        xw = (Window)emu_window_x11_id(win);
        if (grab(dpy, xw, w * scale, h * scale, shot) == 0)
            bad = diff_scaled(shot, png, w, h, scale);
        else if (getenv("ZS_DEBUG_WINDOW")) {
            XWindowAttributes a;
            XGetWindowAttributes(dpy, xw, &a);
            print_message("    grab failed (%d X errors), map state %d, %dx%d at %d,%d\n",
                          x_errors, a.map_state, a.width, a.height, a.x, a.y);
        }
    }
    print_message("    %ux%u window (scale %u): %u pixels differ from the PNG after %u tries\n",
                  w * scale, h * scale, scale, bad, tries);
    assert_int_equal(bad, 0);
    /* keep the screenshot for a person to look at */
    emu_png_write_rgb("build/tests/panel/window_screenshot.png", shot, w * scale, h * scale);
    XCloseDisplay(dpy);
    emu_window_close(win);
    free(shot);
    free(rgb);
    free(png);
    free(img);
    pt_rig_close(&r);
}

static void test_no_display_is_reported(void **state)
{
    char err[160];
    char *saved = getenv("DISPLAY") ? strdup(getenv("DISPLAY")) : NULL;
    emu_window *win;
    (void)state;
    unsetenv("DISPLAY");
    unsetenv("WAYLAND_DISPLAY");
    win = emu_window_open("none", 10, 10, 1, err, sizeof err);
    assert_null(win);
    assert_non_null(strstr(err, "display"));
    if (saved) {
        setenv("DISPLAY", saved, 1);
        free(saved);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_window_screenshot_matches_png),
        cmocka_unit_test(test_no_display_is_reported),
    };
    return cmocka_run_group_tests_name("panel_window", tests, group_setup, group_teardown);
}
