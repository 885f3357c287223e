/* SPDX-License-Identifier: MIT */
/*
 * test_panel_mono: the monochrome panels (SSD1306 128x64 and 128x32, SH1106
 * 132x64, SSD1680 122x250) through their drivers into the emulated
 * controllers of host_sim/emu/emu_mono.c, over 4-wire SPI and I2C.
 *
 *  - The picture the emulated glass shows equals the core's 1-bit image
 *    (rendered whole with zs_render_rows) for every rotation each driver
 *    supports, Bayer, diffusion and line drawings, several band heights,
 *    with no protocol error.
 *  - The byte streams against the datasheets' command formats: SSD1306
 *    horizontal addressing and its 0x21/0x22 window, charge pump before
 *    display on, I2C control bytes 0x00 / 0x40; SH1106 page address and
 *    column (with its 2-column offset) before every page; SSD1680 gate
 *    count, data entry, RAM window and counters, 0x24 data, the refresh
 *    sequence 0xF7 / 0x20 and the BUSY wait.
 *  - SSD1680 partial refresh: the base written with write_base, then a
 *    partial refresh (0xFF) that the emulator accepts; without the base it
 *    flags the refresh.
 *  - A wrong table (mirror bit missing) gives a wrong picture; a wrong I2C
 *    address gives ZS_PANEL_ERR_IO; rotations the controller cannot do are
 *    refused.
 *  - Wire time of a full frame at 400 kHz and 1 MHz I2C is printed.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "emu_mono.h"
#include "pcore.h"
#include "zspan/panel.h"

static const char *const mono_panels[] = {"ssd1306-128x64", "ssd1306-128x32", "sh1106-132x64",
                                          "ssd1680-122x250"};


/* ---- a recording bus in front of the emulator ---- */

typedef struct rec {
    emu_mono_port port;        /* the real port (its bus is not used directly) */
    zs_bus bus;
    uint8_t kind[60000];       /* 'C' command byte, 'P' parameter, 'D' data */
    uint8_t byte[60000];
    size_t n;
    uint32_t delay_ms;
} rec;

static void rec_push(rec *r, uint8_t k, uint8_t b)
{
    if (r->n < sizeof r->kind) {
        r->kind[r->n] = k;
        r->byte[r->n] = b;
        r->n++;
    }
}

static int rec_command(void *user, uint8_t cmd, const uint8_t *params, size_t n)
{
    rec *r = user;
    rec_push(r, 'C', cmd);
    for (size_t i = 0; i < n; i++) rec_push(r, 'P', params[i]);
    return r->port.bus.ops->command(&r->port, cmd, params, n);
}

static int rec_pixels(void *user, const uint8_t *d, size_t n)
{
    rec *r = user;
    for (size_t i = 0; i < n; i++) rec_push(r, 'D', d[i]);
    return r->port.bus.ops->pixels(&r->port, d, n);
}

static void rec_reset(void *user, int level)
{
    rec *r = user;
    r->port.bus.ops->reset(&r->port, level);
}

static void rec_delay(void *user, uint32_t ms)
{
    rec *r = user;
    r->delay_ms += ms;
    r->port.bus.ops->delay_ms(&r->port, ms);
}

static const zs_bus_ops rec_ops = {rec_command, rec_pixels, rec_reset, NULL, rec_delay, NULL};

static void rec_open(rec *r, emu_mono *e, int i2c)
{
    memset(r, 0, sizeof *r);
    assert_int_equal(emu_mono_port_init(&r->port, e, i2c, ZS_SSD1306_I2C_ADDR), 0);
    assert_int_equal(zs_bus_init(&r->bus, &rec_ops, r, 0, 0), ZS_BUS_OK);
}

/* Index of the first occurrence of the command sequence seq (kinds 'C'/'P'
 * as recorded) at or after from, or -1. */
static long find_seq(const rec *r, size_t from, const char *kinds, const uint8_t *seq, size_t n)
{
    for (size_t i = from; i + n <= r->n; i++) {
        size_t k;
        for (k = 0; k < n; k++)
            if (r->kind[i + k] != (uint8_t)kinds[k] || r->byte[i + k] != seq[k]) break;
        if (k == n) return (long)i;
    }
    return -1;
}

/* ---- the image test ---- */

static unsigned run_image(const char *name, unsigned rot, int i2c, unsigned mono, int band,
                          uint32_t seed, int print)
{
    const zs_panel_desc *d = zs_panel_find(name);
    const emu_mono_model *m = emu_mono_model_find(name);
    zs_format fmt = zs_panel_supports(d, ZS_FMT_MONO_PAGE) ? ZS_FMT_MONO_PAGE : ZS_FMT_MONO_MSB;
    emu_mono e;
    rec *r = malloc(sizeof *r);
    zs_panel p;
    pc_core c;
    pc_scene s;
    assert_non_null(d);
    assert_non_null(m);
    assert_int_equal(emu_mono_init(&e, m), 0);
    rec_open(r, &e, i2c);
    assert_int_equal(zs_panel_init(&p, d, &r->bus, fmt, rot), ZS_PANEL_OK);
    pc_core_open(&c, p.width, p.height, 0x202020);
    pc_make_scene(&s, seed);
    uint8_t *want = malloc((size_t)p.width * p.height), *got = malloc((size_t)p.width * p.height);
    pc_reference(&c, &s, fmt, mono, p.width, p.height, want);
    pc_frame(&c, &s, fmt, mono);
    static uint8_t b0[4096], b1[4096];
    size_t bb = zs_panel_window_bytes(fmt, p.width, fmt == ZS_FMT_MONO_PAGE ? 8u * (unsigned)((band + 7) / 8) : (unsigned)band);
    zs_panel_frame_stats st;
    assert_int_equal(zs_panel_stream(&p, &c.r, b0, b1, bb, band, NULL, &st), ZS_PANEL_OK);
    emu_mono_view(&e, rot, got);
    unsigned bad = 0, lit = 0;
    for (size_t i = 0; i < (size_t)p.width * p.height; i++) {
        bad += want[i] != got[i];
        lit += want[i];
    }
    if (bad || e.errors)
        print_message("  %s rot %u %s mono %u band %d: %u pixels differ, errors 0x%x (%s)\n", name,
                      rot, i2c ? "I2C" : "SPI", mono, band, bad, e.errors, e.first_error);
    assert_true(lit > 0 && lit < (unsigned)p.width * p.height); /* a real picture */
    assert_int_equal(e.errors, 0);
    if (print)
        print_message("  %s %s: %lu wire clocks a frame%s\n", name, i2c ? "I2C" : "SPI",
                      (unsigned long)r->port.clocks, "");
    free(want);
    free(got);
    pc_core_close(&c);
    emu_mono_free(&e);
    free(r);
    return bad;
}

static void test_images(void **state)
{
    (void)state;
    unsigned cases = 0;
    for (unsigned i = 0; i < sizeof mono_panels / sizeof mono_panels[0]; i++) {
        const zs_panel_desc *d = zs_panel_find(mono_panels[i]);
        int oled = d->ops != &zs_panel_ops_ssd1680;
        for (unsigned rot = 0; rot < 4; rot++) {
            if (d->rotations && !(d->rotations & (1u << rot))) continue;
            for (int bus = 0; bus < (oled ? 2 : 1); bus++)
                for (unsigned look = 0; look < 3; look++) {
                    unsigned mono = look == 0 ? 0u : look == 1 ? ZS_MONO_DIFFUSE : ZS_MONO_LINES;
                    int band = look == 0 ? 8 : look == 1 ? 16 : 24;
                    if (!oled) band = look == 0 ? 1 : look == 1 ? 7 : 16;
                    assert_int_equal(run_image(d->name, rot, bus, mono, band, 11u + i + rot, 0), 0);
                    cases++;
                }
        }
    }
    print_message("mono panels: %u cases, the emulated glass equals the core's 1-bit image\n",
                  cases);
}

static void test_refused_rotations(void **state)
{
    (void)state;
    emu_mono e;
    rec *r = malloc(sizeof *r);
    zs_panel p;
    assert_int_equal(emu_mono_init(&e, emu_mono_model_find("ssd1306-128x64")), 0);
    rec_open(r, &e, 0);
    assert_int_equal(zs_panel_init(&p, &zs_panel_ssd1306_128x64, &r->bus, ZS_FMT_MONO_PAGE, 1),
                     ZS_PANEL_ERR_ROTATION);
    assert_int_equal(zs_panel_init(&p, &zs_panel_ssd1306_128x64, &r->bus, ZS_FMT_RGB565_BE, 0),
                     ZS_PANEL_ERR_FORMAT);
    assert_int_equal(zs_panel_init(&p, &zs_panel_ssd1306_128x64, &r->bus, ZS_FMT_MONO_PAGE, 0),
                     ZS_PANEL_OK);
    assert_int_equal(zs_panel_set_rotation(&p, 3), ZS_PANEL_ERR_ROTATION);
    assert_int_equal(zs_panel_window(&p, 0, 4, 128, 64), ZS_PANEL_ERR_WINDOW); /* not a page */
    assert_int_equal(zs_panel_window(&p, 0, 8, 128, 64), ZS_PANEL_OK);
    assert_int_equal(p.window_total, 128u * 7u);
    emu_mono_free(&e);
    assert_int_equal(emu_mono_init(&e, emu_mono_model_find("ssd1680-122x250")), 0);
    assert_int_equal(zs_panel_init(&p, &zs_panel_ssd1680_122x250, &r->bus, ZS_FMT_MONO_MSB, 2),
                     ZS_PANEL_ERR_ROTATION);
    emu_mono_free(&e);
    free(r);
}

/* The emulator is not circular: a table without the segment remap shows a
 * mirrored picture. */
static void test_wrong_table(void **state)
{
    (void)state;
    zs_panel_desc bad = zs_panel_ssd1306_128x64;
    bad.madctl = ZS_MADCTL_MY;
    emu_mono e;
    rec *r = malloc(sizeof *r);
    zs_panel p;
    pc_core c;
    pc_scene s;
    assert_int_equal(emu_mono_init(&e, emu_mono_model_find("ssd1306-128x64")), 0);
    rec_open(r, &e, 0);
    assert_int_equal(zs_panel_init(&p, &bad, &r->bus, ZS_FMT_MONO_PAGE, 0), ZS_PANEL_OK);
    pc_core_open(&c, 128, 64, 0x202020);
    pc_make_scene(&s, 5);
    uint8_t want[128 * 64], got[128 * 64];
    pc_reference(&c, &s, ZS_FMT_MONO_PAGE, 0, 128, 64, want);
    pc_frame(&c, &s, ZS_FMT_MONO_PAGE, 0);
    static uint8_t b0[1024];
    assert_int_equal(zs_panel_stream(&p, &c.r, b0, NULL, sizeof b0, 64, NULL, NULL), ZS_PANEL_OK);
    emu_mono_view(&e, 0, got);
    assert_true(memcmp(want, got, sizeof want) != 0);
    pc_core_close(&c);
    emu_mono_free(&e);
    free(r);
}

static void test_ssd1306_stream(void **state)
{
    (void)state;
    emu_mono e;
    rec *r = malloc(sizeof *r);
    zs_panel p;
    pc_core c;
    pc_scene s;
    for (int i2c = 0; i2c < 2; i2c++) {
        assert_int_equal(emu_mono_init(&e, emu_mono_model_find("ssd1306-128x64")), 0);
        rec_open(r, &e, i2c);
        assert_int_equal(zs_panel_init(&p, &zs_panel_ssd1306_128x64, &r->bus, ZS_FMT_MONO_PAGE, 0),
                         ZS_PANEL_OK);
        /* every byte of a command goes with D/C low (no 'P' bytes at all) */
        for (size_t k = 0; k < r->n; k++) assert_int_not_equal(r->kind[k], 'P');
        static const uint8_t pump[] = {0x8D, 0x14}, on = 0xAF, horiz[] = {0x20, 0x00},
                             mux[] = {0xA8, 0x3F}, pins[] = {0xDA, 0x12}, remap[] = {0xA1, 0xC8};
        long ip = find_seq(r, 0, "CC", pump, 2), ion = find_seq(r, 0, "C", &on, 1);
        assert_true(ip >= 0 && ion > ip);
        assert_true(find_seq(r, 0, "CC", horiz, 2) >= 0);
        assert_true(find_seq(r, 0, "CC", mux, 2) >= 0);
        assert_true(find_seq(r, 0, "CC", pins, 2) >= 0);
        assert_true(find_seq(r, 0, "CC", remap, 2) >= 0);
        size_t n0 = r->n;
        uint64_t clocks0 = r->port.clocks;
        uint32_t frames0 = r->port.frames;
        pc_core_open(&c, 128, 64, 0x202020);
        pc_make_scene(&s, 3);
        pc_frame(&c, &s, ZS_FMT_MONO_PAGE, 0);
        static uint8_t b0[1024], b1[1024];
        zs_panel_frame_stats st;
        assert_int_equal(zs_panel_stream(&p, &c.r, b0, b1, 256, 16, NULL, &st), ZS_PANEL_OK);
        /* the window: columns 0..127, pages 0..7, then 1024 data bytes */
        static const uint8_t win[] = {0x21, 0x00, 0x7F, 0x22, 0x00, 0x07};
        assert_int_equal(find_seq(r, n0, "CCCCCC", win, 6), (long)n0);
        size_t data = 0;
        for (size_t k = n0 + 6; k < r->n; k++) data += r->kind[k] == 'D';
        assert_int_equal(data, 1024);
        assert_int_equal(r->n, n0 + 6 + 1024);
        assert_int_equal(e.errors, 0);
        if (i2c) {
            /* per frame: 6 command transactions (3 bytes each: address, control,
             * command) and 8 pages of data (130 bytes each), 9 clocks a byte
             * and 2 for start and stop */
            double clocks = (double)(r->port.clocks - clocks0);
            assert_int_equal(r->port.frames - frames0, 6 + 8);
            assert_int_equal((long)clocks, 6 * (9 * 3 + 2) + 8 * (9 * 130 + 2));
            print_message("ssd1306-128x64 over I2C: %lu transactions, %.0f clocks a frame "
                          "(window and pages): %.2f ms at 400 kHz, %.2f ms at 1 MHz\n",
                          (unsigned long)(r->port.frames - frames0), clocks,
                          clocks / 400e3 * 1e3, clocks / 1e6 * 1e3);
        }
        pc_core_close(&c);
        emu_mono_free(&e);
    }
    /* a device that does not answer: the first command fails */
    assert_int_equal(emu_mono_init(&e, emu_mono_model_find("ssd1306-128x64")), 0);
    rec_open(r, &e, 1);
    r->port.addr = 0x3D;
    assert_int_equal(zs_panel_init(&p, &zs_panel_ssd1306_128x64, &r->bus, ZS_FMT_MONO_PAGE, 0),
                     ZS_PANEL_ERR_IO);
    assert_true(e.nacks > 0);
    emu_mono_free(&e);
    free(r);
}

static void test_i2c_framing(void **state)
{
    (void)state;
    emu_mono e;
    assert_int_equal(emu_mono_init(&e, emu_mono_model_find("ssd1306-128x32")), 0);
    /* Co = 1 pairs: command, command; then Co = 0 data */
    static const uint8_t a[] = {0x80, 0xAE, 0x80, 0x20, 0x80, 0x00};
    assert_int_equal(emu_mono_i2c_write(&e, 0x3C, a, sizeof a), 0);
    assert_int_equal(e.mode, 0);
    static const uint8_t b[] = {0x00, 0x21, 0x00, 0x7F, 0x22, 0x00, 0x03};
    assert_int_equal(emu_mono_i2c_write(&e, 0x3C, b, sizeof b), 0);
    static const uint8_t c[] = {0x40, 0xFF, 0x01};
    assert_int_equal(emu_mono_i2c_write(&e, 0x3C, c, sizeof c), 0);
    assert_int_equal(e.ram[0], 1);
    assert_int_equal(e.ram[1], 1);
    assert_int_equal(e.ram[128 + 1], 0);
    assert_int_equal(e.errors, 0);
    static const uint8_t bad[] = {0x01, 0xAF};
    assert_int_equal(emu_mono_i2c_write(&e, 0x3C, bad, sizeof bad), 0);
    assert_true(e.errors & EMU_M_I2C);
    assert_int_equal(emu_mono_i2c_write(&e, 0x3D, c, sizeof c), -1);
    emu_mono_free(&e);
}

static void test_sh1106_pages(void **state)
{
    (void)state;
    emu_mono e;
    rec *r = malloc(sizeof *r);
    zs_panel p;
    pc_core c;
    pc_scene s;
    assert_int_equal(emu_mono_init(&e, emu_mono_model_find("sh1106-132x64")), 0);
    rec_open(r, &e, 0);
    assert_int_equal(zs_panel_init(&p, &zs_panel_sh1106_132x64, &r->bus, ZS_FMT_MONO_PAGE, 0),
                     ZS_PANEL_OK);
    static const uint8_t dcdc[] = {0xAD, 0x8B}, pump = 0x8D, mode = 0x20;
    assert_true(find_seq(r, 0, "CC", dcdc, 2) >= 0);
    assert_int_equal(find_seq(r, 0, "C", &pump, 1), -1);
    assert_int_equal(find_seq(r, 0, "C", &mode, 1), -1);
    size_t n0 = r->n;
    pc_core_open(&c, 128, 64, 0x202020);
    pc_make_scene(&s, 4);
    pc_frame(&c, &s, ZS_FMT_MONO_PAGE, 0);
    static uint8_t b0[1024];
    assert_int_equal(zs_panel_stream(&p, &c.r, b0, NULL, sizeof b0, 64, NULL, NULL), ZS_PANEL_OK);
    /* page p: B0|p, column 2 (0x02, 0x10), then 128 data bytes */
    size_t k = n0;
    for (unsigned pg = 0; pg < 8; pg++) {
        uint8_t set[3] = {(uint8_t)(0xB0 | pg), 0x02, 0x10};
        assert_int_equal(find_seq(r, k, "CCC", set, 3), (long)k);
        k += 3;
        for (unsigned j = 0; j < 128; j++, k++) assert_int_equal(r->kind[k], 'D');
    }
    assert_int_equal(k, r->n);
    assert_int_equal(e.errors, 0);
    /* a write across a page end is refused */
    assert_int_equal(zs_panel_window(&p, 0, 0, 128, 64), ZS_PANEL_OK);
    assert_int_equal(zs_panel_write(&p, b0, 100), ZS_PANEL_OK);
    assert_int_equal(zs_panel_write(&p, b0, 100), ZS_PANEL_ERR_BUFFER);
    pc_core_close(&c);
    emu_mono_free(&e);
    free(r);
}

static void test_ssd1680_refresh(void **state)
{
    (void)state;
    emu_mono e;
    rec *r = malloc(sizeof *r);
    zs_panel p;
    pc_core c;
    pc_scene s;
    assert_int_equal(emu_mono_init(&e, emu_mono_model_find("ssd1680-122x250")), 0);
    rec_open(r, &e, 0);
    assert_int_equal(zs_panel_init(&p, &zs_panel_ssd1680_122x250, &r->bus, ZS_FMT_MONO_MSB, 0),
                     ZS_PANEL_OK);
    static const uint8_t drv[] = {0x01, 0xF9, 0x00, 0x00}, entry[] = {0x11, 0x03}, sw = 0x12;
    long isw = find_seq(r, 0, "C", &sw, 1);
    assert_true(isw >= 0 && find_seq(r, 0, "CPPP", drv, 4) > isw);
    assert_true(find_seq(r, 0, "CP", entry, 2) > isw);
    size_t n0 = r->n;
    uint32_t d0 = r->delay_ms;
    pc_core_open(&c, 122, 250, 0x202020);
    pc_make_scene(&s, 8);
    pc_frame(&c, &s, ZS_FMT_MONO_MSB, 0);
    static uint8_t b0[1024];
    assert_int_equal(zs_panel_stream(&p, &c.r, b0, NULL, sizeof b0, 32, NULL, NULL), ZS_PANEL_OK);
    static const uint8_t win[] = {0x44, 0x00, 0x0F, 0x45, 0x00, 0x00, 0xF9, 0x00,
                                  0x4E, 0x00, 0x4F, 0x00, 0x00, 0x24};
    assert_int_equal(find_seq(r, n0, "CPPCPPPPCPCPPC", win, sizeof win), (long)n0);
    static const uint8_t full[] = {0x22, 0xF7, 0x20};
    long iref = find_seq(r, n0, "CPC", full, 3);
    assert_int_equal(iref, (long)(n0 + sizeof win + 16 * 250));
    assert_true(r->delay_ms - d0 >= 4000); /* waited out BUSY */
    assert_int_equal(e.refreshes, 1);
    assert_int_equal(e.errors, 0);

    /* partial refresh without the base: flagged */
    pc_make_scene(&s, 9);
    pc_frame(&c, &s, ZS_FMT_MONO_MSB, 0);
    p.partial = 1;
    assert_int_equal(zs_panel_stream(&p, &c.r, b0, NULL, sizeof b0, 32, NULL, NULL), ZS_PANEL_OK);
    assert_true(e.errors & EMU_M_BASE);
    pc_core_close(&c);
    pc_core_open(&c, 122, 250, 0x202020);

    /* the right way: full refresh of frame A, A again as the base, partial B */
    emu_mono_free(&e);
    assert_int_equal(emu_mono_init(&e, emu_mono_model_find("ssd1680-122x250")), 0);
    rec_open(r, &e, 0);
    assert_int_equal(zs_panel_init(&p, &zs_panel_ssd1680_122x250, &r->bus, ZS_FMT_MONO_MSB, 0),
                     ZS_PANEL_OK);
    pc_make_scene(&s, 10);
    pc_frame(&c, &s, ZS_FMT_MONO_MSB, 0);
    assert_int_equal(zs_panel_stream(&p, &c.r, b0, NULL, sizeof b0, 32, NULL, NULL), ZS_PANEL_OK);
    pc_frame(&c, &s, ZS_FMT_MONO_MSB, 0);
    p.write_base = 1;
    size_t n1 = r->n;
    assert_int_equal(zs_panel_stream(&p, &c.r, b0, NULL, sizeof b0, 32, NULL, NULL), ZS_PANEL_OK);
    static const uint8_t red = 0x26, act = 0x20;
    assert_true(find_seq(r, n1, "C", &red, 1) >= 0);
    assert_int_equal(find_seq(r, n1, "C", &act, 1), -1); /* no refresh */
    p.write_base = 0;
    p.partial = 1;
    pc_scene s2;
    pc_make_scene(&s2, 12);
    uint8_t *want = malloc(122 * 250), *got = malloc(122 * 250);
    pc_reference(&c, &s2, ZS_FMT_MONO_MSB, 0, 122, 250, want);
    pc_frame(&c, &s2, ZS_FMT_MONO_MSB, 0);
    size_t n2 = r->n;
    assert_int_equal(zs_panel_stream(&p, &c.r, b0, NULL, sizeof b0, 32, NULL, NULL), ZS_PANEL_OK);
    static const uint8_t part[] = {0x22, 0xFF, 0x20};
    assert_true(find_seq(r, n2, "CPC", part, 3) > (long)n2);
    assert_int_equal(e.refreshes, 2);
    assert_int_equal(e.partial_refreshes, 1);
    assert_int_equal(e.errors, 0);
    emu_mono_view(&e, 0, got);
    assert_memory_equal(want, got, 122 * 250);
    free(want);
    free(got);
    pc_core_close(&c);
    emu_mono_free(&e);
    free(r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_images),
        cmocka_unit_test(test_refused_rotations),
        cmocka_unit_test(test_wrong_table),
        cmocka_unit_test(test_ssd1306_stream),
        cmocka_unit_test(test_i2c_framing),
        cmocka_unit_test(test_sh1106_pages),
        cmocka_unit_test(test_ssd1680_refresh),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
