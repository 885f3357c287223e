/* SPDX-License-Identifier: MIT */
/*
 * test_stellaris: zspan on QEMU's Stellaris boards, whose OLED controllers
 * were modelled by QEMU's authors, against the host (issue 20).
 *
 * Host side: the firmware's scenes (examples/stellaris-oled/oled_scene.c)
 * rendered by the host core through the same drivers into zspan's own
 * emulated SSD0323 / SSD0303 (host_sim/emu); each frame's picture on the
 * emulated glass must equal the core's render (zs_render_rows unpacked),
 * with no protocol error, no pool drop, and the wire's FNV-1a hash is kept.
 *
 * QEMU side: each image is booted for 1, 2 and 3 frames and halts; its
 * reported wire hashes must equal the host's (the same bytes on the wire),
 * then the monitor's screendump is taken (512x256 or 384x64: every pixel
 * 4x4, grey 17 v or black/white), reduced 4x (each block must be uniform
 * and an exact level) and compared pixel for pixel with the host's picture
 * of that frame. Then the LM3S811 image is pointed at I2C address 0x3C,
 * where nobody answers: it must report the NACK and exit, not hang.
 *
 * QEMU runs under a time limit; a run that does not finish is killed and
 * fails the test.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "demo_scene.h"
#include "emu.h"
#include "emu_gray.h"
#include "emu_mono.h"
#include "oled_scene.h"
#include "zspan/panel.h"

#ifndef FW_QEMU
#define FW_QEMU "qemu-system-arm"
#endif
#ifndef STELLARIS_OUT
#define STELLARIS_OUT "out/stellaris"
#endif

#define FRAMES 3
#define RUN_SECONDS 90

typedef struct board {
    const char *name, *machine, *elf;
    int w, h, levels; /* levels: 16 (GRAY4) or 2 */
    uint8_t px[FRAMES][OLED_BIG_W * OLED_BIG_H]; /* the host's glass, frame by frame */
    uint32_t stream[FRAMES];
} board;

static board big = {"lm3s6965", "lm3s6965evb", OLED_FW_6965, OLED_BIG_W, OLED_BIG_H, 16, {{0}}, {0}};
static board small = {"lm3s811", "lm3s811evb", OLED_FW_811, OLED_SMALL_W, OLED_SMALL_H, 2, {{0}}, {0}};

/* ---- the host ---- */

static unsigned drops(const zs_renderer *r)
{
    return r->stats.tris_dropped + r->stats.verts_dropped + r->stats.records_skipped;
}

static int host_big(void)
{
    static demo_scene scene;
    static emu_gray e;
    static uint8_t img[OLED_BIG_H * OLED_BIG_W / 2], band[OLED_BIG_W / 2 * 8];
    emu_gray_port port;
    zs_renderer r;
    zs_panel p;
    zs_config cfg = oled_big_config();
    size_t n = zs_arena_bytes(&cfg);
    uint8_t *arena = malloc(n);
    int f, rc = 0;
    demo_scene_init(&scene);
    emu_gray_init(&e);
    if (!arena || zs_init(&r, arena, n, &cfg) != ZS_OK || emu_gray_port_init(&port, &e) != 0 ||
        zs_panel_init(&p, &zs_panel_ssd0323_128x64, &port.bus, ZS_FMT_GRAY4, 0) != ZS_PANEL_OK) {
        fprintf(stderr, "host lm3s6965: set-up failed\n");
        free(arena);
        return -1;
    }
    for (f = 0; f < FRAMES && rc == 0; f++) {
        uint8_t view[OLED_BIG_W * OLED_BIG_H];
        int x, y;
        if (oled_big_frame(&r, &scene, (uint32_t)f) != ZS_OK ||
            zs_render_rows(&r, 0, OLED_BIG_H, img, OLED_BIG_W / 2) != ZS_OK || drops(&r)) {
            fprintf(stderr, "host lm3s6965 frame %d: render failed or %u drops\n", f, drops(&r));
            rc = -1;
            break;
        }
        for (y = 0; y < OLED_BIG_H; y++)
            for (x = 0; x < OLED_BIG_W; x++)
                big.px[f][y * OLED_BIG_W + x] =
                    (uint8_t)((img[y * (OLED_BIG_W / 2) + x / 2] >> (x % 2 ? 0 : 4)) & 15u);
        if (oled_big_frame(&r, &scene, (uint32_t)f) != ZS_OK ||
            zs_panel_stream(&p, &r, band, NULL, sizeof band, 8, NULL, NULL) != ZS_PANEL_OK) {
            fprintf(stderr, "host lm3s6965 frame %d: stream failed\n", f);
            rc = -1;
            break;
        }
        emu_gray_view(&e, view);
        if (memcmp(view, big.px[f], sizeof view) != 0 || e.errors) {
            fprintf(stderr, "host lm3s6965 frame %d: the emulated SSD0323 shows another picture%s%s\n",
                    f, e.errors ? ": " : "", e.errors ? e.first_error : "");
            rc = -1;
        }
        big.stream[f] = port.stream;
        {
            char path[256];
            snprintf(path, sizeof path, STELLARIS_OUT "/host-lm3s6965-%d.png", f);
            (void)emu_gray_write_png(&e, path);
        }
    }
    free(arena);
    return rc;
}

static int host_small(void)
{
    static uint8_t img[OLED_SMALL_W * 2], band[OLED_SMALL_W];
    emu_mono e;
    emu_mono_port port;
    zs_renderer r;
    zs_panel p;
    zs_config cfg = oled_small_config();
    size_t n = zs_arena_bytes(&cfg);
    uint8_t *arena = malloc(n);
    int f, rc = 0;
    if (!arena || zs_init(&r, arena, n, &cfg) != ZS_OK ||
        emu_mono_init(&e, emu_mono_model_find("ssd0303-96x16")) != 0 ||
        emu_mono_port_init(&port, &e, 1, ZS_SSD0303_I2C_ADDR) != 0) {
        fprintf(stderr, "host lm3s811: set-up failed\n");
        free(arena);
        return -1;
    }
    port.co_each = 1;   /* the Stellaris port's framing */
    port.max_frame = 64; /* and its data bytes a transaction */
    if (zs_panel_init(&p, &zs_panel_ssd0303_96x16, &port.bus, ZS_FMT_MONO_PAGE, 0) != ZS_PANEL_OK) {
        fprintf(stderr, "host lm3s811: panel init failed\n");
        rc = -1;
    }
    for (f = 0; f < FRAMES && rc == 0; f++) {
        uint8_t view[OLED_SMALL_W * OLED_SMALL_H];
        int x, y;
        if (oled_small_frame(&r, (uint32_t)f) != ZS_OK ||
            zs_render_rows(&r, 0, OLED_SMALL_H, img, OLED_SMALL_W) != ZS_OK || drops(&r)) {
            fprintf(stderr, "host lm3s811 frame %d: render failed or %u drops\n", f, drops(&r));
            rc = -1;
            break;
        }
        for (y = 0; y < OLED_SMALL_H; y++)
            for (x = 0; x < OLED_SMALL_W; x++)
                small.px[f][y * OLED_SMALL_W + x] =
                    (uint8_t)((img[(y / 8) * OLED_SMALL_W + x] >> (y % 8)) & 1u);
        if (oled_small_frame(&r, (uint32_t)f) != ZS_OK ||
            zs_panel_stream(&p, &r, band, NULL, sizeof band, 8, NULL, NULL) != ZS_PANEL_OK) {
            fprintf(stderr, "host lm3s811 frame %d: stream failed\n", f);
            rc = -1;
            break;
        }
        emu_mono_view(&e, 0, view);
        if (memcmp(view, small.px[f], sizeof view) != 0 || e.errors) {
            fprintf(stderr, "host lm3s811 frame %d: the emulated SSD0303 shows another picture%s%s\n",
                    f, e.errors ? ": " : "", e.errors ? e.first_error : "");
            rc = -1;
        }
        small.stream[f] = port.stream;
        {
            char path[256];
            snprintf(path, sizeof path, STELLARIS_OUT "/host-lm3s811-%d.png", f);
            (void)emu_mono_write_png(&e, 0, path);
        }
    }
    emu_mono_free(&e);
    free(arena);
    return rc;
}

static int host_setup(void **state)
{
    (void)state;
    mkdir("out", 0777);
    mkdir(STELLARIS_OUT, 0777);
    if (host_big() != 0 || host_small() != 0)
        return -1;
    return 0;
}

/* ---- QEMU ---- */

typedef struct qemu_run {
    char text[65536];
    size_t n;
    int status;       /* exit status, -1 if killed */
    int timed_out;
} qemu_run;

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + t.tv_nsec * 1e-9;
}

/* Reads what the child printed until `until` appears (NULL: end of output)
 * or the deadline; 1 when found (or at the end), 0 on timeout. */
static int read_until(qemu_run *q, int fd, const char *until, double deadline)
{
    for (;;) {
        struct pollfd pf = {fd, POLLIN, 0};
        double left = deadline - now_s();
        ssize_t got;
        if (until && strstr(q->text, until))
            return 1;
        if (left <= 0)
            return 0;
        if (poll(&pf, 1, (int)(left * 1000) + 1) <= 0)
            continue;
        if (q->n + 1 >= sizeof q->text)
            q->n = 0; /* keep going; the markers are short */
        got = read(fd, q->text + q->n, sizeof q->text - 1 - q->n);
        if (got <= 0)
            return until == NULL || strstr(q->text, until) != NULL;
        q->n += (size_t)got;
        q->text[q->n] = 0;
    }
}

/* Boots elf on machine with the semihosting words args; after "DONE" takes
 * the screen into ppm (if not NULL) and quits. */
static void run_qemu(qemu_run *q, const board *b, const char *args, const char *ppm)
{
    int in[2], out[2];
    pid_t pid;
    char semi[256];
    double deadline = now_s() + RUN_SECONDS;
    int st;
    memset(q, 0, sizeof *q);
    snprintf(semi, sizeof semi, "enable=on,target=native,%s", args);
    assert_int_equal(pipe(in), 0);
    assert_int_equal(pipe(out), 0);
    pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        dup2(in[0], 0);
        dup2(out[1], 1);
        dup2(out[1], 2);
        close(in[1]);
        close(out[0]);
        execlp(FW_QEMU, FW_QEMU, "-M", b->machine, "-display", "none", "-monitor", "stdio",
               "-serial", "none", "-icount", "shift=0", "-semihosting-config", semi, "-kernel",
               b->elf, (char *)NULL);
        _exit(127);
    }
    close(in[0]);
    close(out[1]);
    if (ppm) {
        if (read_until(q, out[0], "DONE ", deadline)) {
            char cmd[512];
            int len = snprintf(cmd, sizeof cmd, "screendump %s\nquit\n", ppm);
            if (write(in[1], cmd, (size_t)len) != len)
                q->timed_out = 1;
        } else {
            q->timed_out = 1;
        }
    }
    if (!q->timed_out && !read_until(q, out[0], NULL, deadline))
        q->timed_out = 1;
    if (q->timed_out)
        kill(pid, SIGKILL); /* our own child only */
    close(in[1]);
    close(out[0]);
    waitpid(pid, &st, 0);
    q->status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* The "F board k ... stream=X ... dropped=N" line of frame k. */
static int frame_line(const qemu_run *q, const board *b, int k, uint32_t *stream,
                      unsigned long *instr, unsigned long *dropped)
{
    char prefix[64];
    const char *p, *s, *i, *d;
    snprintf(prefix, sizeof prefix, "F %s %d ", b->name, k);
    if (!(p = strstr(q->text, prefix)) || !(s = strstr(p, "stream=")) ||
        !(i = strstr(p, "instr=")) || !(d = strstr(p, "dropped=")))
        return 0;
    *stream = (uint32_t)strtoul(s + 7, NULL, 16);
    *instr = strtoul(i + 6, NULL, 10);
    *dropped = strtoul(d + 8, NULL, 10);
    return 1;
}

/* Reads a P6 PPM of (4 w) x (4 h) and reduces it to w x h levels. */
static void reduce_ppm(const char *path, const board *b, uint8_t *px)
{
    FILE *f = fopen(path, "rb");
    int w, h, max, x, y, c;
    unsigned char *rgb;
    if (!f)
        fail_msg("%s: no screendump", path);
    if (fscanf(f, "P6 %d %d %d", &w, &h, &max) != 3 || fgetc(f) == EOF)
        fail_msg("%s: not a binary PPM", path);
    if (w != 4 * b->w || h != 4 * b->h || max != 255)
        fail_msg("%s: %dx%d (max %d), want %dx%d", path, w, h, max, 4 * b->w, 4 * b->h);
    rgb = malloc((size_t)w * (size_t)h * 3u);
    assert_non_null(rgb);
    if (fread(rgb, 3, (size_t)w * (size_t)h, f) != (size_t)w * (size_t)h)
        fail_msg("%s: short", path);
    fclose(f);
    for (y = 0; y < b->h; y++)
        for (x = 0; x < b->w; x++) {
            const unsigned char *o = rgb + ((size_t)(4 * y) * (size_t)w + (size_t)(4 * x)) * 3u;
            int v = o[0], dx, dy;
            for (dy = 0; dy < 4; dy++)
                for (dx = 0; dx < 4; dx++)
                    for (c = 0; c < 3; c++)
                        if (o[((size_t)dy * (size_t)w + (size_t)dx) * 3u + (size_t)c] != v)
                            fail_msg("%s: the 4x4 block of (%d,%d) is not one grey", path, x, y);
            if (b->levels == 16 ? v % 17 != 0 : (v != 0 && v != 255))
                fail_msg("%s: grey %d at (%d,%d) is no level", path, v, x, y);
            px[y * b->w + x] = (uint8_t)(b->levels == 16 ? v / 17 : v / 255);
        }
    free(rgb);
}

static void check_board(board *b)
{
    static qemu_run q;
    int k;
    for (k = 1; k <= FRAMES; k++) {
        char ppm[256], args[64], png[256];
        uint8_t got[OLED_BIG_W * OLED_BIG_H], rgb[3 * OLED_BIG_W * OLED_BIG_H];
        const uint8_t *want = b->px[k - 1];
        int j, diff = 0, first = -1, i;
        snprintf(ppm, sizeof ppm, STELLARIS_OUT "/qemu-%s-%d.ppm", b->name, k - 1);
        snprintf(args, sizeof args, "arg=frames=%d,arg=halt", k);
        remove(ppm);
        run_qemu(&q, b, args, ppm);
        if (q.timed_out)
            fail_msg("%s, %d frames: no DONE within %d s:\n%s", b->name, k, RUN_SECONDS, q.text);
        for (j = 0; j < k; j++) {
            uint32_t stream;
            unsigned long instr, dropped;
            if (!frame_line(&q, b, j, &stream, &instr, &dropped))
                fail_msg("%s: no line of frame %d in:\n%s", b->name, j, q.text);
            if (stream != b->stream[j])
                fail_msg("%s frame %d: wire hash %08x, the host's emulated bus %08x", b->name, j,
                         (unsigned)stream, (unsigned)b->stream[j]);
            assert_int_equal(dropped, 0);
            if (j == k - 1)
                print_message("%s frame %d: %lu instructions, wire hash %08x = host\n", b->name,
                              j, instr, (unsigned)stream);
        }
        reduce_ppm(ppm, b, got);
        for (i = 0; i < b->w * b->h; i++)
            if (got[i] != want[i] && diff++ == 0)
                first = i;
        for (i = 0; i < b->w * b->h; i++)
            rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] =
                (uint8_t)(b->levels == 16 ? got[i] * 17 : got[i] * 255);
        snprintf(png, sizeof png, STELLARIS_OUT "/qemu-%s-%d.png", b->name, k - 1);
        (void)emu_png_write_rgb(png, rgb, (unsigned)b->w, (unsigned)b->h);
        if (diff)
            fail_msg("%s frame %d: %d of %d pixels differ from the host, first (%d,%d): %u vs %u",
                     b->name, k - 1, diff, b->w * b->h, first % b->w, first / b->w, got[first],
                     want[first]);
        {
            unsigned seen = 0;
            for (i = 0; i < b->w * b->h; i++)
                seen |= 1u << got[i];
            print_message("%s frame %d: QEMU's screen = the host's, %dx%d pixels, %d levels "
                          "seen\n", b->name, k - 1, b->w, b->h, __builtin_popcount(seen));
            assert_true(__builtin_popcount(seen) >= (b->levels == 16 ? 8 : 2));
        }
    }
}

static void test_lm3s6965_ssd0323(void **state)
{
    (void)state;
    check_board(&big);
}

static void test_lm3s811_ssd0303(void **state)
{
    (void)state;
    check_board(&small);
}

static void test_lm3s811_i2c_nack(void **state)
{
    static qemu_run q;
    (void)state;
    run_qemu(&q, &small, "arg=frames=1,arg=addr=60", NULL); /* 0x3C: nobody there */
    print_message("%s", q.text);
    assert_false(q.timed_out);
    assert_int_equal(q.status, 2);
    assert_non_null(strstr(q.text, "E lm3s811 panel init: the bus reported a failure / nobody "
                                   "acknowledged the I2C address (NACK)"));
    assert_null(strstr(q.text, "DONE"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lm3s6965_ssd0323),
        cmocka_unit_test(test_lm3s811_ssd0303),
        cmocka_unit_test(test_lm3s811_i2c_nack),
    };
    return cmocka_run_group_tests_name("stellaris", tests, host_setup, NULL);
}
