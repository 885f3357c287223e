/* SPDX-License-Identifier: MIT */
/*
 * The Linux port (spidev + libgpiod) against emulated devices: the real
 * libgpiod 1.6 and the port's real open/ioctl calls, with umockdev's preload
 * library routing /dev/spidev0.0 and /dev/gpiochip0 to ioctl handlers in this
 * program (umockdev_testbed_attach_ioctl). The handlers act like the kernel:
 *
 *   spidev: SPI_IOC_WR/RD_MODE, _BITS_PER_WORD, _MAX_SPEED_HZ; SPI_IOC_MESSAGE
 *   rejects a message larger than the module's bufsiz with EMSGSIZE (as
 *   drivers/spi/spidev.c does) and otherwise clocks the bytes into host_sim's
 *   emulated ST7789 with the D/C level of the GPIO line wired to it;
 *   gpiochip (GPIO uAPI v1, what libgpiod 1.6 speaks): chip info, line info
 *   (one line held by a kernel consumer, to see the "busy" message), line
 *   handle requests (EBUSY for that line) and SET_LINE_VALUES on the handle;
 *   the bit-banged mode's SCLK/MOSI/CS edges are decoded into bytes.
 *
 * The program re-runs itself under umockdev-wrapper (LD_PRELOAD); without
 * umockdev every test is skipped with the reason. Not built with the
 * sanitizers: AddressSanitizer must be first in the preload list, which
 * umockdev-wrapper's LD_PRELOAD is not.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include <linux/gpio.h>
#include <linux/spi/spidev.h>
#include <umockdev.h>

#include <cmocka.h>

#include "demo_scene.h"
#include "ports_common.h"
#include "zs_linux.h"
#include "zspan/panel.h"

#define PANEL "st7789-240x240"
#define W 240
#define H 240
#define NLINES 32
#define KERNEL_LINE 13          /* held by "spi0 CS1" */
#define POOL 24                 /* line-handle fds handed out per test */

/* ---- the emulated hardware ---------------------------------------------------- */

typedef struct hw {
    emu_panel emu;
    /* spidev */
    uint8_t mode, bits;
    uint32_t speed;
    uint32_t bufsiz;            /* what the "kernel" enforces */
    uint64_t messages, bytes, rejected;
    uint32_t max_message;
    uint64_t messages_at_limit;
    /* GPIO lines */
    int level[NLINES];
    int requested[NLINES];
    int handle_line[POOL];      /* pool index -> line offset (-1 free) */
    int pool_fd[POOL];
    int pool_next;
    int dc, reset, sclk, mosi, cs;   /* wiring: line offsets, -1 none */
    uint64_t gpio_sets;
    /* bit-bang decoder */
    unsigned shift, nbits;
    uint64_t bb_bytes;
    /* time */
    uint64_t t0_us, delivered_ms;
    unsigned errors;
    char first_error[200];
} hw;

static hw H_;
static UMockdevTestbed *tb;
static char *tb_root;
static int have_umockdev;
static char skip_reason[200];

static uint64_t now_us(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint64_t)ts.tv_sec * 1000000u + (uint64_t)ts.tv_nsec / 1000u;
}

static void tick(hw *h)
{
    uint64_t ms = (now_us() - h->t0_us) / 1000u;
    if (ms > h->delivered_ms) {
        emu_delay_ms(&h->emu, (uint32_t)(ms - h->delivered_ms));
        h->delivered_ms = ms;
    }
}

static void hw_error(hw *h, const char *fmt, ...)
{
    va_list ap;
    if (h->errors++ == 0) {
        va_start(ap, fmt);
        vsnprintf(h->first_error, sizeof h->first_error, fmt, ap);
        va_end(ap);
    }
}

/* Bytes on the SPI wire: D/C from its line. */
static void wire_bytes(hw *h, const uint8_t *d, size_t n)
{
    tick(h);
    if (h->dc >= 0 && h->level[h->dc] == 0) {
        size_t i;
        for (i = 0; i < n; i++)
            emu_command(&h->emu, d[i]);
    } else {
        emu_data(&h->emu, d, n);
    }
}

static void line_changed(hw *h, int line, int v)
{
    int old = h->level[line];
    h->level[line] = v;
    h->gpio_sets++;
    if (line == h->reset && old != v) {
        tick(h);
        emu_reset_line(&h->emu, v);
    }
    if (line == h->cs && v == 0 && old != 0)
        h->nbits = 0;
    /* Mode 0: MOSI sampled on the rising SCLK edge while CS is low. */
    if (line == h->sclk && old == 0 && v == 1 && (h->cs < 0 || h->level[h->cs] == 0)) {
        h->shift = (h->shift << 1) | (unsigned)(h->level[h->mosi] & 1);
        if (++h->nbits == 8) {
            uint8_t b = (uint8_t)h->shift;
            h->nbits = 0;
            h->bb_bytes++;
            wire_bytes(h, &b, 1);
        }
    }
}

static void hw_reset(hw *h, int dc, int reset, int sclk, int mosi, int cs)
{
    int i;
    if (h->emu.m != NULL)
        emu_free(&h->emu);
    memset(h, 0, sizeof *h);
    assert_int_equal(emu_init(&h->emu, emu_model_find(PANEL)), 0);
    h->bufsiz = 4096;
    h->dc = dc;
    h->reset = reset;
    h->sclk = sclk;
    h->mosi = mosi;
    h->cs = cs;
    for (i = 0; i < NLINES; i++)
        h->level[i] = 1;
    for (i = 0; i < POOL; i++) {
        char path[64];
        h->handle_line[i] = -1;
        snprintf(path, sizeof path, "/dev/gpioline%d", i);
        h->pool_fd[i] = open(path, O_RDWR | O_CLOEXEC);
        assert_true(h->pool_fd[i] >= 0);
    }
    h->t0_us = now_us();
}

static void hw_done(hw *h)
{
    int i;
    for (i = 0; i < POOL; i++)
        if (h->handle_line[i] < 0 && h->pool_fd[i] >= 0)
            close(h->pool_fd[i]); /* never handed out; the others libgpiod closed */
}

/* ---- ioctl handlers (umockdev's thread; the caller blocks meanwhile) ----------- */

static gboolean on_spidev(UMockdevIoctlBase *base, UMockdevIoctlClient *c, gpointer user)
{
    hw *h = user;
    gulong req = umockdev_ioctl_client_get_request(c);
    UMockdevIoctlData *arg = umockdev_ioctl_client_get_arg(c);
    (void)base;

    if (req == SPI_IOC_WR_MODE || req == SPI_IOC_RD_MODE || req == SPI_IOC_WR_BITS_PER_WORD ||
        req == SPI_IOC_RD_BITS_PER_WORD) {
        g_autoptr(UMockdevIoctlData) d = umockdev_ioctl_data_resolve(arg, 0, 1, NULL);
        uint8_t *field = req == SPI_IOC_WR_MODE || req == SPI_IOC_RD_MODE ? &h->mode : &h->bits;
        if (req == SPI_IOC_WR_MODE || req == SPI_IOC_WR_BITS_PER_WORD)
            *field = d->data[0];
        else
            d->data[0] = *field;
        umockdev_ioctl_client_complete(c, 0, 0);
        return TRUE;
    }
    if (req == SPI_IOC_WR_MAX_SPEED_HZ || req == SPI_IOC_RD_MAX_SPEED_HZ) {
        g_autoptr(UMockdevIoctlData) d = umockdev_ioctl_data_resolve(arg, 0, 4, NULL);
        if (req == SPI_IOC_WR_MAX_SPEED_HZ)
            memcpy(&h->speed, d->data, 4);
        else
            memcpy(d->data, &h->speed, 4);
        umockdev_ioctl_client_complete(c, 0, 0);
        return TRUE;
    }
    if (_IOC_TYPE(req) == SPI_IOC_MAGIC && _IOC_NR(req) == 0 && _IOC_DIR(req) == _IOC_WRITE) {
        size_t n = _IOC_SIZE(req) / sizeof(struct spi_ioc_transfer), i, total = 0;
        g_autoptr(UMockdevIoctlData) d =
            umockdev_ioctl_data_resolve(arg, 0, n * sizeof(struct spi_ioc_transfer), NULL);
        struct spi_ioc_transfer *t = (struct spi_ioc_transfer *)d->data;
        for (i = 0; i < n; i++)
            total += t[i].len;
        if (total > h->bufsiz) {
            h->rejected++;
            umockdev_ioctl_client_complete(c, -1, EMSGSIZE);
            return TRUE;
        }
        for (i = 0; i < n; i++) {
            g_autoptr(UMockdevIoctlData) tx = NULL;
            if (t[i].len == 0)
                continue;
            if (t[i].bits_per_word != 0 && t[i].bits_per_word != 8)
                hw_error(h, "transfer with %u bits per word", t[i].bits_per_word);
            tx = umockdev_ioctl_data_resolve(d, i * sizeof(struct spi_ioc_transfer) +
                                                    offsetof(struct spi_ioc_transfer, tx_buf),
                                             t[i].len, NULL);
            wire_bytes(h, tx->data, t[i].len);
        }
        h->messages++;
        h->bytes += total;
        if (total > h->max_message)
            h->max_message = (uint32_t)total;
        if (total == h->bufsiz)
            h->messages_at_limit++;
        umockdev_ioctl_client_complete(c, (glong)total, 0);
        return TRUE;
    }
    umockdev_ioctl_client_complete(c, -1, ENOTTY);
    return TRUE;
}

static gboolean on_gpiochip(UMockdevIoctlBase *base, UMockdevIoctlClient *c, gpointer user)
{
    hw *h = user;
    gulong req = umockdev_ioctl_client_get_request(c);
    UMockdevIoctlData *arg = umockdev_ioctl_client_get_arg(c);
    (void)base;

    if (req == GPIO_GET_CHIPINFO_IOCTL) {
        g_autoptr(UMockdevIoctlData) d =
            umockdev_ioctl_data_resolve(arg, 0, sizeof(struct gpiochip_info), NULL);
        struct gpiochip_info *ci = (struct gpiochip_info *)d->data;
        memset(ci, 0, sizeof *ci);
        snprintf(ci->name, sizeof ci->name, "gpiochip0");
        snprintf(ci->label, sizeof ci->label, "zspan-test-gpio");
        ci->lines = NLINES;
        umockdev_ioctl_client_complete(c, 0, 0);
        return TRUE;
    }
    if (req == GPIO_GET_LINEINFO_IOCTL) {
        g_autoptr(UMockdevIoctlData) d =
            umockdev_ioctl_data_resolve(arg, 0, sizeof(struct gpioline_info), NULL);
        struct gpioline_info *li = (struct gpioline_info *)d->data;
        unsigned off = li->line_offset;
        if (off >= NLINES) {
            umockdev_ioctl_client_complete(c, -1, EINVAL);
            return TRUE;
        }
        memset(li, 0, sizeof *li);
        li->line_offset = off;
        snprintf(li->name, sizeof li->name, "GPIO%u", off);
        if (off == KERNEL_LINE) {
            li->flags = GPIOLINE_FLAG_KERNEL | GPIOLINE_FLAG_IS_OUT;
            snprintf(li->consumer, sizeof li->consumer, "spi0 CS1");
        } else if (h->requested[off]) {
            li->flags = GPIOLINE_FLAG_KERNEL | GPIOLINE_FLAG_IS_OUT;
            snprintf(li->consumer, sizeof li->consumer, "zspan");
        }
        umockdev_ioctl_client_complete(c, 0, 0);
        return TRUE;
    }
    if (req == GPIO_GET_LINEHANDLE_IOCTL) {
        g_autoptr(UMockdevIoctlData) d =
            umockdev_ioctl_data_resolve(arg, 0, sizeof(struct gpiohandle_request), NULL);
        struct gpiohandle_request *r = (struct gpiohandle_request *)d->data;
        unsigned off = r->lineoffsets[0];
        if (r->lines != 1) {
            hw_error(h, "line request of %u lines (the port requests one at a time)", r->lines);
            umockdev_ioctl_client_complete(c, -1, EINVAL);
            return TRUE;
        }
        if (off >= NLINES) {
            umockdev_ioctl_client_complete(c, -1, EINVAL);
            return TRUE;
        }
        if (off == KERNEL_LINE || h->requested[off]) {
            umockdev_ioctl_client_complete(c, -1, EBUSY);
            return TRUE;
        }
        if (!(r->flags & GPIOHANDLE_REQUEST_OUTPUT) || h->pool_next >= POOL) {
            hw_error(h, "line %u: not an output request, or out of handles", off);
            umockdev_ioctl_client_complete(c, -1, EINVAL);
            return TRUE;
        }
        h->requested[off] = 1;
        h->handle_line[h->pool_next] = (int)off;
        r->fd = h->pool_fd[h->pool_next++];
        line_changed(h, (int)off, r->default_values[0] ? 1 : 0);
        umockdev_ioctl_client_complete(c, 0, 0);
        return TRUE;
    }
    umockdev_ioctl_client_complete(c, -1, ENOTTY);
    return TRUE;
}

static gboolean on_gpioline(UMockdevIoctlBase *base, UMockdevIoctlClient *c, gpointer user)
{
    hw *h = user;
    gulong req = umockdev_ioctl_client_get_request(c);
    UMockdevIoctlData *arg = umockdev_ioctl_client_get_arg(c);
    const char *node = umockdev_ioctl_client_get_devnode(c);
    int idx = atoi(node + strlen("/dev/gpioline")), line;
    (void)base;
    if (idx < 0 || idx >= POOL || (line = h->handle_line[idx]) < 0) {
        umockdev_ioctl_client_complete(c, -1, EBADF);
        return TRUE;
    }
    if (req == GPIOHANDLE_SET_LINE_VALUES_IOCTL || req == GPIOHANDLE_GET_LINE_VALUES_IOCTL) {
        g_autoptr(UMockdevIoctlData) d =
            umockdev_ioctl_data_resolve(arg, 0, sizeof(struct gpiohandle_data), NULL);
        struct gpiohandle_data *v = (struct gpiohandle_data *)d->data;
        if (req == GPIOHANDLE_SET_LINE_VALUES_IOCTL)
            line_changed(h, line, v->values[0] ? 1 : 0);
        else
            v->values[0] = (uint8_t)h->level[line];
        umockdev_ioctl_client_complete(c, 0, 0);
        return TRUE;
    }
    umockdev_ioctl_client_complete(c, -1, ENOTTY);
    return TRUE;
}

/* ---- the testbed ---------------------------------------------------------------- */

static void write_file(const char *rel, const char *text)
{
    char path[512];
    FILE *f;
    snprintf(path, sizeof path, "%s/%s", tb_root, rel);
    f = fopen(path, "w");
    if (f != NULL) {
        fputs(text, f);
        fclose(f);
    }
}

static void set_bufsiz_param(const char *text)
{
    char path[512];
    snprintf(path, sizeof path, "%s/sys/module/spidev/parameters", tb_root);
    if (text == NULL) {
        snprintf(path, sizeof path, "%s/sys/module/spidev/parameters/bufsiz", tb_root);
        unlink(path);
        return;
    }
    g_mkdir_with_parents(path, 0755);
    write_file("sys/module/spidev/parameters/bufsiz", text);
}

static int setup_testbed(void)
{
    GError *err = NULL;
    UMockdevIoctlBase *spi, *chip, *line;
    gchar *sys;
    int i;

    tb = umockdev_testbed_new();
    tb_root = umockdev_testbed_get_root_dir(tb);
    umockdev_testbed_add_device(tb, "spidev", "spidev0.0", NULL, "dev", "153:0", NULL, "DEVNAME",
                                "/dev/spidev0.0", NULL);
    sys = umockdev_testbed_add_device(tb, "gpio", "gpiochip0", NULL, "dev", "254:0", NULL,
                                      "DEVNAME", "/dev/gpiochip0", NULL);
    /* libgpiod 1.6 strips the last character of sysfs "dev" (the newline). */
    umockdev_testbed_set_attribute(tb, sys, "dev", "254:0\n");
    g_free(sys);
    write_file("dev/spidev0.0", "");
    write_file("dev/gpiochip0", "");
    spi = umockdev_ioctl_base_new();
    chip = umockdev_ioctl_base_new();
    line = umockdev_ioctl_base_new();
    g_signal_connect(spi, "handle-ioctl", G_CALLBACK(on_spidev), &H_);
    g_signal_connect(chip, "handle-ioctl", G_CALLBACK(on_gpiochip), &H_);
    g_signal_connect(line, "handle-ioctl", G_CALLBACK(on_gpioline), &H_);
    if (!umockdev_testbed_attach_ioctl(tb, "/dev/spidev0.0", spi, &err) ||
        !umockdev_testbed_attach_ioctl(tb, "/dev/gpiochip0", chip, &err)) {
        snprintf(skip_reason, sizeof skip_reason, "umockdev attach_ioctl: %s",
                 err != NULL ? err->message : "failed");
        return -1;
    }
    for (i = 0; i < POOL; i++) {
        char name[32], dev[16], node[48];
        snprintf(name, sizeof name, "gpioline%d", i);
        snprintf(dev, sizeof dev, "254:%d", 100 + i);
        snprintf(node, sizeof node, "/dev/gpioline%d", i);
        g_free(umockdev_testbed_add_device(tb, "gpio", name, NULL, "dev", dev, NULL, "DEVNAME",
                                           node, NULL));
        snprintf(name, sizeof name, "dev/gpioline%d", i);
        write_file(name, "");
        if (!umockdev_testbed_attach_ioctl(tb, node, line, &err)) {
            snprintf(skip_reason, sizeof skip_reason, "umockdev attach_ioctl: %s",
                     err != NULL ? err->message : "failed");
            return -1;
        }
    }
    return 0;
}

static void need_umockdev(void)
{
    if (!have_umockdev) {
        printf("SKIPPED: %s\n", skip_reason);
        skip();
    }
}

/* ---- helpers -------------------------------------------------------------------- */

static zs_panel_status stream_demo(zs_bus *bus, uint32_t frame, int band)
{
    static demo_scene scene;
    static int ready;
    zs_panel lcd;
    zs_renderer r;
    zs_config cfg;
    zs_panel_status ps;
    zs_panel_frame_stats fs;
    unsigned max_tris = DEMO_TRIANGLES * 2u + 64u;
    size_t arena_size, band_bytes = (size_t)W * 2u * (size_t)band;
    void *arena;
    uint8_t *buf;
    if (!ready) {
        demo_scene_init(&scene);
        ready = 1;
    }
    ps = zs_panel_init(&lcd, zs_panel_find(PANEL), bus, ZS_FMT_RGB565_BE, 0);
    if (ps != ZS_PANEL_OK)
        return ps;
    cfg = zs_config_default(W, H, (uint16_t)max_tris, (uint16_t)(max_tris * 3u),
                            ZS_MAX_ACTIVE_EDGES);
    arena_size = zs_arena_bytes(&cfg);
    arena = malloc(arena_size);
    buf = malloc(band_bytes);
    assert_non_null(arena);
    assert_non_null(buf);
    assert_int_equal(zs_init(&r, arena, arena_size, &cfg), ZS_OK);
    assert_int_equal(
        demo_frame(&r, &scene, frame, ZS_MODE_SPAN, ZS_SHADE_GOURAUD, ZS_FMT_RGB565_BE), ZS_OK);
    ps = zs_panel_stream(&lcd, &r, buf, NULL, band_bytes, band, NULL, &fs);
    free(arena);
    free(buf);
    return ps;
}

static void expect_frame(uint32_t frame)
{
    uint32_t *want = ports_demo_666(W, H, frame);
    assert_non_null(want);
    emu_flush(&H_.emu);
    if (H_.errors)
        print_message("    emulation: %s\n", H_.first_error);
    if (H_.emu.errors)
        print_message("    panel errors 0x%X: %s\n", (unsigned)H_.emu.errors,
                      H_.emu.log_lines ? H_.emu.log[0] : "");
    assert_int_equal(H_.errors, 0);
    assert_int_equal(H_.emu.errors, 0);
    assert_int_equal(ports_view_diff(&H_.emu, want, W, H), 0);
    free(want);
}

static zs_linux_cfg spidev_cfg(void)
{
    zs_linux_cfg c = zs_linux_cfg_default();
    c.spi_dev = "/dev/spidev0.0";
    c.gpiochip = "gpiochip0";
    c.dc = 25;
    c.reset = 27;
    c.backlight = 18;
    c.hz = 40000000u;
    return c;
}

/* ---- tests ---------------------------------------------------------------------- */

/* A whole frame through spidev (default bufsiz: no module parameter file):
 * every message fits 4096 bytes, most are exactly 4096, the panel shows the
 * rendered frame. */
static void test_spidev_frame_default_bufsiz(void **state)
{
    zs_linux_port p;
    char err[256];
    (void)state;
    need_umockdev();
    set_bufsiz_param(NULL);
    hw_reset(&H_, 25, 27, -1, -1, -1);
    assert_int_equal(zs_spidev_bufsiz(), 4096);
    {
        zs_linux_cfg c = spidev_cfg();
        assert_int_equal(zs_linux_open(&p, &c, err, sizeof err), 0);
    }
    assert_int_equal(p.bufsiz, 4096);
    assert_int_equal(H_.mode, 0);
    assert_int_equal(H_.bits, 8);
    assert_int_equal(H_.speed, 40000000u);
    assert_int_equal(stream_demo(&p.bus, 0, 16), ZS_PANEL_OK);
    zs_linux_close(&p);
    expect_frame(0);
    print_message("    %llu messages, %llu bytes, largest %u, %llu of exactly 4096, %llu GPIO "
                  "writes (libgpiod 1.6 -> gpiochip0 ioctls)\n",
                  (unsigned long long)H_.messages, (unsigned long long)H_.bytes, H_.max_message,
                  (unsigned long long)H_.messages_at_limit, (unsigned long long)H_.gpio_sets);
    assert_int_equal(H_.rejected, 0);
    assert_int_equal(H_.max_message, 4096);
    /* Bands of 16 rows (7680 bytes) go out as 4096 + 3584. */
    assert_true(H_.messages_at_limit >= 15);
    assert_int_equal(p.st.max_message, 4096);
    hw_done(&H_);
}

/* The module parameter says 1000: messages are cut there. */
static void test_spidev_bufsiz_param(void **state)
{
    zs_linux_port p;
    zs_linux_cfg c = spidev_cfg();
    char err[256];
    (void)state;
    need_umockdev();
    set_bufsiz_param("1000\n");
    hw_reset(&H_, 25, 27, -1, -1, -1);
    H_.bufsiz = 1000;
    assert_int_equal(zs_spidev_bufsiz(), 1000);
    assert_int_equal(zs_linux_open(&p, &c, err, sizeof err), 0);
    assert_int_equal(p.bufsiz, 1000);
    assert_int_equal(stream_demo(&p.bus, 3, 8), ZS_PANEL_OK);
    zs_linux_close(&p);
    expect_frame(3);
    print_message("    bufsiz 1000: %llu messages, largest %u, %llu at the limit, none rejected\n",
                  (unsigned long long)H_.messages, H_.max_message,
                  (unsigned long long)H_.messages_at_limit);
    assert_int_equal(H_.rejected, 0);
    assert_int_equal(H_.max_message, 1000);
    assert_true(H_.messages_at_limit > 0);
    set_bufsiz_param(NULL);
    hw_done(&H_);
}

/* A port that ignored the limit would fail: the emulated spidev rejects an
 * oversized message with EMSGSIZE and the port says so. */
static void test_spidev_limit_enforced(void **state)
{
    zs_linux_port p;
    zs_linux_cfg c = spidev_cfg();
    char err[256];
    (void)state;
    need_umockdev();
    hw_reset(&H_, 25, 27, -1, -1, -1);
    c.bufsiz = 8192; /* wrong on purpose: the kernel takes 4096 */
    assert_int_equal(zs_linux_open(&p, &c, err, sizeof err), 0);
    assert_int_equal(stream_demo(&p.bus, 0, 16), ZS_PANEL_ERR_IO);
    print_message("    %s\n", p.err);
    assert_non_null(strstr(p.err, "bufsiz"));
    assert_true(H_.rejected > 0);
    zs_linux_close(&p);
    hw_done(&H_);
}

static void test_missing_device(void **state)
{
    zs_linux_port p;
    zs_linux_cfg c = spidev_cfg();
    char err[256];
    (void)state;
    need_umockdev();
    hw_reset(&H_, 25, 27, -1, -1, -1);
    c.spi_dev = "/dev/spidev7.3";
    assert_int_not_equal(zs_linux_open(&p, &c, err, sizeof err), 0);
    print_message("    %s\n", err);
    assert_non_null(strstr(err, "no such SPI device"));
    c = spidev_cfg();
    c.gpiochip = "gpiochip9";
    assert_int_not_equal(zs_linux_open(&p, &c, err, sizeof err), 0);
    print_message("    %s\n", err);
    assert_non_null(strstr(err, "gpiochip9"));
    hw_done(&H_);
}

/* D/C on a line the kernel holds: the message names the line and its user. */
static void test_busy_line(void **state)
{
    zs_linux_port p;
    zs_linux_cfg c = spidev_cfg();
    char err[256];
    (void)state;
    need_umockdev();
    hw_reset(&H_, KERNEL_LINE, 27, -1, -1, -1);
    c.dc = KERNEL_LINE;
    assert_int_not_equal(zs_linux_open(&p, &c, err, sizeof err), 0);
    print_message("    %s\n", err);
    assert_non_null(strstr(err, "busy"));
    assert_non_null(strstr(err, "spi0 CS1"));
    assert_non_null(strstr(err, "D/C"));
    c = spidev_cfg();
    c.reset = 40; /* past the chip's 32 lines */
    assert_int_not_equal(zs_linux_open(&p, &c, err, sizeof err), 0);
    print_message("    %s\n", err);
    assert_non_null(strstr(err, "does not exist"));
    hw_done(&H_);
}

/* Bit-banged SPI on libgpiod lines: panel init and a 20 x 12 window, every
 * bit an edge on the emulated chip's lines. */
static void test_bitbang_window(void **state)
{
    zs_linux_port p;
    zs_linux_cfg c = spidev_cfg();
    zs_panel lcd;
    char err[256];
    enum { X0 = 100, Y0 = 50, WW = 20, HH = 12 };
    uint8_t img[WW * HH * 2];
    uint32_t *view;
    unsigned i, x, y, bad = 0;
    (void)state;
    need_umockdev();
    hw_reset(&H_, 25, 27, 11, 10, 8);
    c.bitbang = 1;
    c.spi_dev = NULL;
    c.sclk = 11;
    c.mosi = 10;
    c.cs = 8;
    assert_int_equal(zs_linux_open(&p, &c, err, sizeof err), 0);
    assert_int_equal(zs_panel_init(&lcd, zs_panel_find(PANEL), &p.bus, ZS_FMT_RGB565_BE, 0),
                     ZS_PANEL_OK);
    for (i = 0; i < WW * HH; i++) {
        uint16_t v = (uint16_t)(i * 2654435761u >> 16);
        img[2 * i] = (uint8_t)(v >> 8);
        img[2 * i + 1] = (uint8_t)v;
    }
    assert_int_equal(zs_panel_window(&lcd, X0, Y0, X0 + WW, Y0 + HH), ZS_PANEL_OK);
    assert_int_equal(zs_panel_write(&lcd, img, sizeof img), ZS_PANEL_OK);
    zs_linux_close(&p);
    emu_flush(&H_.emu);
    assert_int_equal(H_.errors, 0);
    assert_int_equal(H_.emu.errors, 0);
    view = malloc(W * H * sizeof *view);
    assert_non_null(view);
    emu_view_666(&H_.emu, 0, view);
    for (y = 0; y < HH; y++)
        for (x = 0; x < WW; x++)
            if (view[(Y0 + y) * W + X0 + x] != emu_666_from_565be(img + 2 * (y * WW + x)))
                bad++;
    free(view);
    print_message("    bit-banged: %llu bytes decoded from %llu line changes\n",
                  (unsigned long long)H_.bb_bytes, (unsigned long long)H_.gpio_sets);
    assert_int_equal(bad, 0);
    assert_int_equal(H_.bb_bytes, p.st.bytes);
    hw_done(&H_);
}

int main(int argc, char **argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_spidev_frame_default_bufsiz),
        cmocka_unit_test(test_spidev_bufsiz_param),
        cmocka_unit_test(test_spidev_limit_enforced),
        cmocka_unit_test(test_missing_device),
        cmocka_unit_test(test_busy_line),
        cmocka_unit_test(test_bitbang_window),
    };
    (void)argc;
    if (getenv("ZS_UMOCKDEV_CHILD") == NULL) {
        /* Run again with umockdev's preload library. */
        setenv("ZS_UMOCKDEV_CHILD", "1", 1);
        execvp("umockdev-wrapper", (char *[]){"umockdev-wrapper", argv[0], NULL});
        snprintf(skip_reason, sizeof skip_reason,
                 "umockdev-wrapper not found (Debian: umockdev): the spidev/libgpiod "
                 "emulation needs it");
    } else if (getenv("LD_PRELOAD") == NULL || strstr(getenv("LD_PRELOAD"), "umockdev") == NULL) {
        snprintf(skip_reason, sizeof skip_reason, "umockdev's preload library is not active");
    } else if (setup_testbed() == 0) {
        have_umockdev = 1;
    }
    return cmocka_run_group_tests_name("linux port: spidev + libgpiod 1.6 under umockdev", tests,
                                       NULL, NULL);
}
