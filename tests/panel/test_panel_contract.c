/* SPDX-License-Identifier: MIT */
/* The contract the panel and bus API check:
 *
 *  - zs_panel_stream refuses a renderer whose size or frame format is not the
 *    panel's, each with its own code, before a byte is sent;
 *  - zs_panel_write takes const data: an image in read-only memory reaches
 *    the wire byte for byte (RGB565 and RGB666 on a DCS panel and on the
 *    SSD1351, whose 18 bpp wire form is converted outside the caller's
 *    buffer), blocking and asynchronous, in chunks;
 *  - a bus whose completion never comes gives a timeout, not a hang; a
 *    transfer the port reports as failed gives an I/O error;
 *  - the panel's pixel format lasts between frames and can be changed;
 *  - a controller family is an operations table: the common code drives a
 *    table written here, and refuses an incomplete one;
 *  - every bus and panel status code has a distinct text that is the
 *    header's comment for it (read from the headers), and unknown codes a
 *    fallback.
 *
 * The expected wire bytes are written out here or computed from the values
 * the test image was built from, never from the driver. */
#include "ptest.h"

#include <ctype.h>
#include <unistd.h>

#ifndef ZT_TOP_DIR
#define ZT_TOP_DIR "."
#endif

/* A guard: a regression that hangs in a wait kills the program (counted as
 * a failure by the suite runner) instead of stalling the whole test run. */
#define HANG_GUARD_S 60u

/* ------------------------------------------------------------------ */
/* A port that records the wire                                          */
/* ------------------------------------------------------------------ */

#define CAP_MAX 65536

/* Blocking or asynchronous (completion after `latency` polls, or never);
 * optionally forwards every byte to an emulated panel. It logs every byte
 * with its D/C level as it would leave the chip: for an async transfer at
 * completion, after checking the buffer did not change while in flight. */
typedef struct cap_port {
    zs_bus bus;
    emu_panel *emu;            /* NULL: no panel behind the wire */
    int async;
    unsigned latency;          /* polls until completion */
    int never;                 /* 1: an async transfer never completes */
    int fail_next;             /* 1: the next async transfer ends in a fault */
    /* in flight */
    const uint8_t *inflight;
    size_t inflight_n;
    uint8_t inflight_copy[4096];
    unsigned polls_left;
    /* clock: advances one millisecond per poll */
    uint32_t now_ms;
    /* results */
    uint8_t dc[CAP_MAX];       /* 0 command byte, 1 data byte */
    uint8_t byte[CAP_MAX];
    size_t n;
    unsigned polls, transfers, commands, breaches;
} cap_port;

static void cap_log(cap_port *c, int dc, const uint8_t *d, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        assert_true(c->n < CAP_MAX);
        c->dc[c->n] = (uint8_t)dc;
        c->byte[c->n++] = d[i];
    }
    if (c->emu != NULL && n > 0) {
        if (dc)
            emu_data(c->emu, d, n);
        else
            emu_command(c->emu, d[0]);
    }
}

static void cap_complete(cap_port *c)
{
    if (c->inflight == NULL)
        return;
    if (memcmp(c->inflight, c->inflight_copy, c->inflight_n) != 0)
        c->breaches++; /* somebody wrote a buffer the bus owned */
    cap_log(c, 1, c->inflight, c->inflight_n);
    c->inflight = NULL;
    if (c->fail_next) {
        c->fail_next = 0;
        zs_bus_pixels_failed(&c->bus);
    } else {
        zs_bus_pixels_done(&c->bus);
    }
}

static int cap_command(void *u, uint8_t cmd, const uint8_t *params, size_t n)
{
    cap_port *c = u;
    if (c->inflight != NULL)
        c->breaches++; /* a command overtook pixel data */
    c->commands++;
    cap_log(c, 0, &cmd, 1);
    cap_log(c, 1, params, n);
    return 0;
}

static int cap_pixels(void *u, const uint8_t *data, size_t n)
{
    cap_port *c = u;
    c->transfers++;
    if (!c->async) {
        cap_log(c, 1, data, n);
        return 0;
    }
    if (c->inflight != NULL)
        c->breaches++;
    assert_true(n <= sizeof c->inflight_copy);
    c->inflight = data;
    c->inflight_n = n;
    memcpy(c->inflight_copy, data, n);
    c->polls_left = c->latency;
    if (!c->never && c->latency == 0)
        cap_complete(c);
    return 0;
}

static void cap_poll(void *u)
{
    cap_port *c = u;
    c->polls++;
    c->now_ms++;
    if (c->inflight == NULL || c->never)
        return;
    if (c->polls_left > 0)
        c->polls_left--;
    if (c->polls_left == 0)
        cap_complete(c);
}

static void cap_delay(void *u, uint32_t ms)
{
    cap_port *c = u;
    if (c->emu != NULL)
        emu_delay_ms(c->emu, ms);
}

static void cap_reset(void *u, int level)
{
    cap_port *c = u;
    if (c->emu != NULL)
        emu_reset_line(c->emu, level);
}

static uint32_t cap_clock(void *u)
{
    return ((cap_port *)u)->now_ms;
}

static const zs_bus_ops cap_ops = {
    .command = cap_command,
    .pixels = cap_pixels,
    .reset = cap_reset,
    .delay_ms = cap_delay,
    .poll = cap_poll,
};

static cap_port *cap_open(emu_panel *emu, int async, unsigned latency, uint32_t max_transfer)
{
    cap_port *c = calloc(1, sizeof *c);
    assert_non_null(c);
    c->emu = emu;
    c->async = async;
    c->latency = latency;
    assert_int_equal(zs_bus_init(&c->bus, &cap_ops, c, async ? ZS_BUS_ASYNC : 0u, max_transfer),
                     ZS_BUS_OK);
    return c;
}

/* Checks that the logged wire is exactly want (dc[i] for each byte). */
static void cap_expect(const cap_port *c, const uint8_t *want, const uint8_t *want_dc,
                       size_t n)
{
    size_t i;
    if (c->n != n)
        print_message("    wire: %zu bytes, expected %zu\n", c->n, n);
    assert_int_equal(c->n, n);
    for (i = 0; i < n; i++)
        if (c->byte[i] != want[i] || c->dc[i] != want_dc[i]) {
            print_message("    wire byte %zu: %02X (D/C %u), expected %02X (D/C %u)\n", i,
                          c->byte[i], c->dc[i], want[i], want_dc[i]);
            fail();
        }
}

/* ------------------------------------------------------------------ */
/* A small scene                                                         */
/* ------------------------------------------------------------------ */

static uint8_t arena[ZS_ARENA_BYTES(240, 240, 64, 64, 64)];
static zs_renderer R;
static uint8_t band0[240 * 3 * 4], band1[240 * 3 * 4];
static uint8_t ref[240 * 240 * 3];

static const int16_t quad_pos[] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
static const uint16_t quad_idx[] = {0, 1, 2, 0, 2, 3};
static const zs_color quad_col[] = {ZS_RGB(250, 40, 10), ZS_RGB(10, 200, 90),
                                    ZS_RGB(30, 60, 250), ZS_RGB(240, 240, 20)};

/* Begins a frame on a w x h renderer; format is the frame's (ZS_FMT_COUNT:
 * no zs_frame_shading call, the core's default). */
static void scene(unsigned w, unsigned h, zs_format format)
{
    zs_config cfg = zs_config_default((uint16_t)w, (uint16_t)h, 64, 64, 64);
    zs_camera cam;
    zs_mesh m;
    zs_mat34 rot = zs_mat34_rotate_z(ZS_FX(20));
    memset(&m, 0, sizeof m);
    m.positions = quad_pos;
    m.indices = quad_idx;
    m.vertex_colors = quad_col;
    m.scale = ZS_FX(1);
    m.vertex_count = 4;
    m.triangle_count = 2;
    assert_int_equal(zs_init(&R, arena, sizeof arena, &cfg), ZS_OK);
    assert_int_equal(zs_camera_look_at(&cam, zs_vec3_make(0, 0, ZS_FX(3)), zs_vec3_make(0, 0, 0),
                                       zs_vec3_make(0, ZS_FX(1), 0)),
                     ZS_OK);
    assert_int_equal(zs_camera_perspective(&cam, ZS_FX(60), ZS_FX_RATIO(1, 10), ZS_FX(20)),
                     ZS_OK);
    assert_int_equal(zs_frame_begin(&R, &cam, ZS_MODE_SPAN), ZS_OK);
    if (format != ZS_FMT_COUNT) {
        zs_shade_params sp = zs_shade_default();
        sp.shading = ZS_SHADE_GOURAUD;
        sp.format = format;
        sp.background = ZS_RGB(20, 30, 60);
        assert_int_equal(zs_frame_shading(&R, &sp), ZS_OK);
    }
    assert_int_equal(zs_draw(&R, &m, &rot), ZS_OK);
}

/* The core's picture of the scene in a plain buffer (the oracle). */
static void scene_reference(unsigned w, unsigned h, zs_format format)
{
    scene(w, h, format);
    assert_int_equal(zs_render_rows(&R, 0, (int)h, ref, (size_t)w * zs_format_bytes(format)),
                     ZS_OK);
}

/* ------------------------------------------------------------------ */
/* zs_panel_stream: size and format must be the panel's                 */
/* ------------------------------------------------------------------ */

/* A refused frame sends nothing: the bus counters and the emulator's byte
 * count stay where they were. */
static void expect_refused(pt_rig *r, zs_panel_status want)
{
    zs_bus_counters before = r->port.bus.count;
    uint64_t bytes_in = r->emu.bytes_in;
    zs_panel_frame_stats st;
    assert_int_equal(zs_panel_stream(&r->panel, &R, band0, band1, sizeof band0, 4, NULL, &st),
                     want);
    assert_int_equal(st.bands, 0);
    assert_int_equal(st.render_status, ZS_OK);
    assert_memory_equal(&r->port.bus.count, &before, sizeof before);
    assert_true(r->emu.bytes_in == bytes_in);
}

static void test_stream_refuses_other_size(void **state)
{
    pt_rig r;
    (void)state;
    assert_int_equal(pt_rig_open(&r, &zs_panel_st7789_240x240, ZS_FMT_RGB666, 0, 0, 0, 0),
                     ZS_PANEL_OK);
    scene(200, 240, ZS_FMT_RGB666); /* narrower */
    expect_refused(&r, ZS_PANEL_ERR_SIZE);
    scene(240, 200, ZS_FMT_RGB666); /* shorter */
    expect_refused(&r, ZS_PANEL_ERR_SIZE);
    scene(200, 240, ZS_FMT_RGB888); /* the case: both wrong, size first */
    expect_refused(&r, ZS_PANEL_ERR_SIZE);
    pt_rig_close(&r);

    /* 135x240 turned: the panel is 240x135, an unturned renderer is refused */
    assert_int_equal(pt_rig_open(&r, &zs_panel_st7789_135x240, ZS_FMT_RGB565_BE, 1, 0, 0, 0),
                     ZS_PANEL_OK);
    scene(135, 240, ZS_FMT_RGB565_BE);
    expect_refused(&r, ZS_PANEL_ERR_SIZE);
    /* the right size streams, and the glass shows the core's picture */
    scene_reference(240, 135, ZS_FMT_RGB565_BE);
    scene(240, 135, ZS_FMT_RGB565_BE);
    assert_int_equal(zs_panel_stream(&r.panel, &R, band0, band1, sizeof band0, 2, NULL, NULL),
                     ZS_PANEL_OK);
    emu_flush(&r.emu);
    assert_int_equal(r.emu.errors, 0);
    assert_int_equal(pt_compare_view(&r.emu, 1, ref, 240, 135, ZS_FMT_RGB565_BE), 0);
    pt_rig_close(&r);
}

static void test_stream_refuses_other_format(void **state)
{
    pt_rig r;
    (void)state;
    assert_int_equal(pt_rig_open(&r, &zs_panel_st7789_240x240, ZS_FMT_RGB666, 0, 0, 0, 0),
                     ZS_PANEL_OK);
    scene(240, 240, ZS_FMT_RGB888); /* 3 bytes too, but 8-bit channels */
    expect_refused(&r, ZS_PANEL_ERR_FRAME_FORMAT);
    scene(240, 240, ZS_FMT_RGB565_BE);
    expect_refused(&r, ZS_PANEL_ERR_FRAME_FORMAT);
    scene(240, 240, ZS_FMT_COUNT); /* no zs_frame_shading: the core's default */
    expect_refused(&r, ZS_PANEL_ERR_FRAME_FORMAT);
    pt_rig_close(&r);

    /* native-order RGB565 into a big-endian RGB565 panel */
    assert_int_equal(pt_rig_open(&r, &zs_panel_ssd1351, ZS_FMT_RGB565_BE, 0, 0, 0, 0),
                     ZS_PANEL_OK);
    scene(128, 128, ZS_FMT_RGB565);
    expect_refused(&r, ZS_PANEL_ERR_FRAME_FORMAT);
    scene(128, 128, ZS_FMT_GRAY8);
    expect_refused(&r, ZS_PANEL_ERR_FRAME_FORMAT);
    /* the matching frame goes through */
    scene_reference(128, 128, ZS_FMT_RGB565_BE);
    scene(128, 128, ZS_FMT_RGB565_BE);
    assert_int_equal(zs_panel_stream(&r.panel, &R, band0, NULL, sizeof band0, 3, NULL, NULL),
                     ZS_PANEL_OK);
    emu_flush(&r.emu);
    assert_int_equal(r.emu.errors, 0);
    assert_int_equal(pt_compare_view(&r.emu, 0, ref, 128, 128, ZS_FMT_RGB565_BE), 0);
    pt_rig_close(&r);
}

/* The panel's format lasts between frames and zs_panel_set_format changes
 * it (COLMOD / SSD1351 remap on the wire); the next frame must follow. */
static void test_format_is_a_panel_property(void **state)
{
    static const struct {
        const zs_panel_desc *d;
        uint8_t cmd, v666;
    } cases[] = {
        {&zs_panel_gc9a01, 0x3A, 0x06},           /* COLMOD 18 bpp */
        {&zs_panel_st7789_240x240, 0x3A, 0x66},
        {&zs_panel_ssd1351, 0xA0, 0xB4}, /* remap at rotation 0, 262k colours */
    };
    unsigned i, k;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        pt_rig r;
        unsigned w = cases[i].d->width, h = cases[i].d->height;
        assert_int_equal(pt_rig_open(&r, cases[i].d, ZS_FMT_RGB565_BE, 0, 1, 2, 0),
                         ZS_PANEL_OK);
        for (k = 0; k < 4; k++) {
            zs_format f = k < 2 ? ZS_FMT_RGB565_BE : ZS_FMT_RGB666;
            if (k == 2) {
                /* change: exactly one command with the new value */
                emu_record(&r.emu, 1);
                assert_int_equal(zs_panel_set_format(&r.panel, ZS_FMT_RGB666), ZS_PANEL_OK);
                assert_int_equal(r.emu.nev, 2);
                assert_int_equal(r.emu.ev[0].kind, 'C');
                assert_int_equal(r.emu.ev[0].byte, cases[i].cmd);
                assert_int_equal(r.emu.ev[1].kind, 'P');
                assert_int_equal(r.emu.ev[1].byte, cases[i].v666);
                emu_record(&r.emu, 0);
            }
            assert_int_equal(r.panel.format, f);
            /* two frames per format, nothing re-sent in between */
            scene_reference(w, h, f);
            scene(w, h, f);
            assert_int_equal(
                zs_panel_stream(&r.panel, &R, band0, band1, sizeof band0, 4, NULL, NULL),
                ZS_PANEL_OK);
            emu_flush(&r.emu);
            assert_int_equal(r.emu.errors, 0);
            assert_int_equal(pt_compare_view(&r.emu, 0, ref, w, h, f), 0);
            assert_int_equal(r.port.violations, 0);
        }
        pt_rig_close(&r);
    }
    /* refused formats leave the panel as it was and send nothing */
    {
        pt_rig r;
        uint64_t bytes_in;
        assert_int_equal(pt_rig_open(&r, &zs_panel_ili9488, ZS_FMT_RGB666, 0, 0, 0, 0),
                         ZS_PANEL_OK);
        bytes_in = r.emu.bytes_in;
        assert_int_equal(zs_panel_set_format(&r.panel, ZS_FMT_RGB565_BE), ZS_PANEL_ERR_FORMAT);
        assert_int_equal(zs_panel_set_format(&r.panel, ZS_FMT_RGB888), ZS_PANEL_ERR_FORMAT);
        assert_int_equal(zs_panel_set_format(&r.panel, (zs_format)77), ZS_PANEL_ERR_FORMAT);
        assert_int_equal(r.panel.format, ZS_FMT_RGB666);
        assert_true(r.emu.bytes_in == bytes_in);
        assert_int_equal(zs_panel_set_format(NULL, ZS_FMT_RGB666), ZS_PANEL_ERR_NULL);
        pt_rig_close(&r);
    }
}

/* ------------------------------------------------------------------ */
/* const data                                                           */
/* ------------------------------------------------------------------ */

/* Test images in read-only memory (a write to them faults). RGB666 bytes
 * are built from 6-bit values v(i) as v << 2, zspan's layout; the SSD1351
 * must receive v(i) itself. */
#define V6(i) ((uint8_t)(((i) * 7u + 3u) & 0x3Fu))
#define B666(i) ((uint8_t)(V6(i) << 2))
#define B565(i) ((uint8_t)(((i) * 37u + 11u) & 0xFFu))
#define X8(M, i) M(i), M(i + 1u), M(i + 2u), M(i + 3u), M(i + 4u), M(i + 5u), M(i + 6u), M(i + 7u)
#define X32(M, i) X8(M, i), X8(M, i + 8u), X8(M, i + 16u), X8(M, i + 24u)
#define X96(M, i) X32(M, i), X32(M, i + 32u), X32(M, i + 64u)

/* 10 x 10 pixels */
static const uint8_t flash666[300] = {X96(B666, 0u), X96(B666, 96u), X96(B666, 192u),
                                      X8(B666, 288u), B666(296u), B666(297u), B666(298u),
                                      B666(299u)};
static const uint8_t flash565[200] = {X96(B565, 0u), X96(B565, 96u), X8(B565, 192u)};

/* The window [3, 13) x [5, 15) at rotation 0: DCS CASET 3..12, RASET 5..14
 * (no offsets on the ST7789 240x240 at rotation 0), SSD1351 0x15 3..12,
 * 0x75 5..14. */
static const uint8_t dcs_head[] = {0x2A, 0x00, 0x03, 0x00, 0x0C, 0x2B, 0x00, 0x05, 0x00, 0x0E,
                                   0x2C};
static const uint8_t dcs_head_dc[] = {0, 1, 1, 1, 1, 0, 1, 1, 1, 1, 0};
static const uint8_t ssd_head[] = {0x15, 3, 12, 0x75, 5, 14, 0x5C};
static const uint8_t ssd_head_dc[] = {0, 1, 1, 0, 1, 1, 0};

/* Sends the const image through zs_panel_write in `chunk`-byte calls and
 * checks the wire: the window commands, then exactly the expected pixel
 * bytes. Also checks the emulated glass shows v(i) (RGB666) / the RGB565
 * pixels. */
static void const_case(const zs_panel_desc *d, zs_format fmt, int async, unsigned latency,
                       uint32_t max_transfer, size_t chunk)
{
    const uint8_t *img = fmt == ZS_FMT_RGB666 ? flash666 : flash565;
    size_t bytes = fmt == ZS_FMT_RGB666 ? sizeof flash666 : sizeof flash565, off, i;
    int ssd = d->ops == &zs_panel_ops_ssd1351;
    const uint8_t *head = ssd ? ssd_head : dcs_head, *head_dc = ssd ? ssd_head_dc : dcs_head_dc;
    size_t nhead = ssd ? sizeof ssd_head : sizeof dcs_head;
    uint8_t want[16 + 300], want_dc[16 + 300];
    emu_panel emu;
    zs_panel lcd;
    cap_port *c;
    uint32_t *view;
    unsigned vw, vh, x, y;

    assert_int_equal(emu_init(&emu, emu_model_find(d->name)), 0);
    c = cap_open(&emu, async, latency, max_transfer);
    assert_int_equal(zs_panel_init(&lcd, d, &c->bus, fmt, 0), ZS_PANEL_OK);
    c->n = 0; /* from here on */
    assert_int_equal(zs_panel_window(&lcd, 3, 5, 13, 15), ZS_PANEL_OK);
    for (off = 0; off < bytes; off += chunk) {
        size_t n = bytes - off < chunk ? bytes - off : chunk;
        assert_int_equal(zs_panel_write(&lcd, img + off, n), ZS_PANEL_OK);
    }
    assert_int_equal(zs_bus_wait(&c->bus), ZS_BUS_OK);
    assert_int_equal(lcd.window_bytes, 0);

    memcpy(want, head, nhead);
    memcpy(want_dc, head_dc, nhead);
    for (i = 0; i < bytes; i++) {
        /* DCS and SSD1351 16 bpp: the bytes as stored; SSD1351 18 bpp: v(i) */
        want[nhead + i] = ssd && fmt == ZS_FMT_RGB666 ? V6(i) : img[i];
        want_dc[nhead + i] = 1;
    }
    cap_expect(c, want, want_dc, nhead + bytes);
    assert_int_equal(c->breaches, 0);

    /* the glass */
    emu_flush(&emu);
    assert_int_equal(emu.errors, 0);
    emu_view_size(&emu, 0, &vw, &vh);
    view = malloc((size_t)vw * vh * sizeof *view);
    assert_non_null(view);
    emu_view_666(&emu, 0, view);
    for (y = 0; y < 10; y++)
        for (x = 0; x < 10; x++) {
            size_t k = (size_t)y * 10 + x;
            uint32_t got = view[(size_t)(5 + y) * vw + 3 + x], expect;
            if (fmt == ZS_FMT_RGB666)
                expect = (uint32_t)V6(3 * k) << 12 | (uint32_t)V6(3 * k + 1) << 6 | V6(3 * k + 2);
            else
                expect = emu_666_from_565be(&flash565[2 * k]);
            assert_int_equal(got, expect);
        }
    free(view);
    emu_free(&emu);
    free(c);
}

static void test_const_data_reaches_the_wire(void **state)
{
    static const struct {
        const zs_panel_desc *d;
        zs_format fmt;
        int async;
        unsigned latency;
        uint32_t max_transfer;
        size_t chunk;
    } cases[] = {
        {&zs_panel_st7789_240x240, ZS_FMT_RGB565_BE, 0, 0, 0, 200},
        {&zs_panel_st7789_240x240, ZS_FMT_RGB565_BE, 1, 3, 7, 33},
        {&zs_panel_st7789_240x240, ZS_FMT_RGB666, 0, 0, 0, 300},
        {&zs_panel_st7789_240x240, ZS_FMT_RGB666, 1, 2, 64, 31},
        {&zs_panel_ssd1351, ZS_FMT_RGB565_BE, 0, 0, 0, 200},
        {&zs_panel_ssd1351, ZS_FMT_RGB565_BE, 1, 1, 50, 7},
        /* converted: the scratch buffers, one on the bus while the other fills */
        {&zs_panel_ssd1351, ZS_FMT_RGB666, 0, 0, 0, 300},
        {&zs_panel_ssd1351, ZS_FMT_RGB666, 1, 4, 0, 300},
        {&zs_panel_ssd1351, ZS_FMT_RGB666, 1, 2, 10, 100},
        {&zs_panel_ssd1351, ZS_FMT_RGB666, 1, 0, 0, 1},
        {&zs_panel_ssd1351, ZS_FMT_RGB666, 1, 5, 29, 131},
    };
    unsigned i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++)
        const_case(cases[i].d, cases[i].fmt, cases[i].async, cases[i].latency,
                   cases[i].max_transfer, cases[i].chunk);
}

/* zs_panel_write_inplace is the zero-copy path: on the SSD1351 at 18 bpp it
 * converts the caller's (writable) buffer and sends it as one transfer. */
static void test_inplace_write(void **state)
{
    uint8_t buf[300], want[sizeof ssd_head + 300], want_dc[sizeof ssd_head + 300];
    zs_panel lcd;
    cap_port *c = cap_open(NULL, 0, 0, 0);
    size_t i;
    (void)state;
    memcpy(buf, flash666, sizeof buf);
    assert_int_equal(zs_panel_init(&lcd, &zs_panel_ssd1351, &c->bus, ZS_FMT_RGB666, 0),
                     ZS_PANEL_OK);
    c->n = 0;
    c->transfers = 0;
    assert_int_equal(zs_panel_window(&lcd, 3, 5, 13, 15), ZS_PANEL_OK);
    assert_int_equal(zs_panel_write_inplace(&lcd, buf, sizeof buf), ZS_PANEL_OK);
    assert_int_equal(c->transfers, 1);
    memcpy(want, ssd_head, sizeof ssd_head);
    memcpy(want_dc, ssd_head_dc, sizeof ssd_head);
    for (i = 0; i < 300; i++) {
        want[sizeof ssd_head + i] = V6(i);
        want_dc[sizeof ssd_head + i] = 1;
        assert_int_equal(buf[i], V6(i)); /* converted where it lay */
    }
    cap_expect(c, want, want_dc, sizeof want);
    /* a DCS panel sends the buffer as it is and leaves it alone */
    memcpy(buf, flash666, sizeof buf);
    assert_int_equal(zs_panel_init(&lcd, &zs_panel_st7789_240x240, &c->bus, ZS_FMT_RGB666, 0),
                     ZS_PANEL_OK);
    c->n = 0;
    assert_int_equal(zs_panel_window(&lcd, 3, 5, 13, 15), ZS_PANEL_OK);
    assert_int_equal(zs_panel_write_inplace(&lcd, buf, sizeof buf), ZS_PANEL_OK);
    assert_memory_equal(buf, flash666, sizeof buf);
    assert_memory_equal(c->byte + sizeof dcs_head, flash666, sizeof flash666);
    /* the same argument checks as zs_panel_write */
    assert_int_equal(zs_panel_write_inplace(&lcd, buf, 1), ZS_PANEL_ERR_STATE);
    assert_int_equal(zs_panel_write_inplace(&lcd, NULL, 1), ZS_PANEL_ERR_NULL);
    assert_int_equal(zs_panel_write(&lcd, NULL, 1), ZS_PANEL_ERR_NULL);
    free(c);
}

/* ------------------------------------------------------------------ */
/* Timeouts and faults                                                  */
/* ------------------------------------------------------------------ */

static void test_bus_timeout_counted_rounds(void **state)
{
    static const uint8_t px[8] = {1, 2, 3, 4, 5, 6, 7, 8};
    cap_port *c = cap_open(NULL, 1, 0, 0);
    (void)state;
    c->never = 1;
    alarm(HANG_GUARD_S);
    zs_bus_set_wait_limit(&c->bus, 1000, NULL);
    assert_int_equal(zs_bus_pixels(&c->bus, px, sizeof px), ZS_BUS_OK);
    assert_false(zs_bus_idle(&c->bus));
    assert_int_equal(zs_bus_wait(&c->bus), ZS_BUS_ERR_TIMEOUT);
    assert_int_equal(c->polls, 1000); /* one poll per round, `limit` rounds */
    assert_int_equal(c->bus.error, 1);
    /* the lost transfer still owns its buffer: no command, no new transfer,
     * and no second wait of 1000 rounds */
    assert_false(zs_bus_idle(&c->bus));
    assert_int_equal(zs_bus_cmd(&c->bus, 0x2C, NULL, 0), ZS_BUS_ERR_TIMEOUT);
    assert_int_equal(zs_bus_pixels(&c->bus, px, sizeof px), ZS_BUS_ERR_TIMEOUT);
    assert_int_equal(zs_bus_wait(&c->bus), ZS_BUS_ERR_TIMEOUT);
    assert_int_equal(c->polls, 1000);
    assert_int_equal(c->commands, 0);
    assert_int_equal(c->transfers, 1);
    /* the port ends it (say, after aborting its DMA): the bus works again */
    c->never = 0;
    cap_complete(c);
    assert_true(zs_bus_idle(&c->bus));
    assert_int_equal(zs_bus_wait(&c->bus), ZS_BUS_OK);
    assert_int_equal(zs_bus_cmd(&c->bus, 0x2C, NULL, 0), ZS_BUS_OK);
    /* a new transfer gets a whole new limit */
    c->never = 1;
    assert_int_equal(zs_bus_pixels(&c->bus, px, sizeof px), ZS_BUS_OK);
    assert_int_equal(zs_bus_wait(&c->bus), ZS_BUS_ERR_TIMEOUT);
    assert_int_equal(c->polls, 2000);
    /* zs_bus_init starts over (no limit, idle) */
    assert_int_equal(zs_bus_init(&c->bus, &cap_ops, c, ZS_BUS_ASYNC, 0), ZS_BUS_OK);
    assert_true(zs_bus_idle(&c->bus));
    assert_int_equal(c->bus.wait_limit, 0);
    assert_int_equal(zs_bus_wait(NULL), ZS_BUS_ERR_NULL);
    alarm(0);
    free(c);
}

static void test_bus_timeout_by_clock(void **state)
{
    static const uint8_t px[4] = {9, 9, 9, 9};
    static const uint32_t starts[] = {0u, 12345u, 0xFFFFFFF0u}; /* the last one wraps */
    unsigned i;
    (void)state;
    alarm(HANG_GUARD_S);
    for (i = 0; i < 3; i++) {
        cap_port *c = cap_open(NULL, 1, 0, 0);
        uint32_t t0;
        c->never = 1;
        c->now_ms = starts[i];
        zs_bus_set_wait_limit(&c->bus, 50, cap_clock);
        assert_int_equal(zs_bus_pixels(&c->bus, px, sizeof px), ZS_BUS_OK);
        t0 = c->now_ms;
        assert_int_equal(zs_bus_wait(&c->bus), ZS_BUS_ERR_TIMEOUT);
        /* at least the limit passed, and not much more (1 ms per poll) */
        assert_true(c->now_ms - t0 > 50u);
        assert_true(c->now_ms - t0 <= 51u);
        free(c);
    }
    /* a completion before the limit is no timeout */
    {
        cap_port *c = cap_open(NULL, 1, 30, 0);
        zs_bus_set_wait_limit(&c->bus, 50, cap_clock);
        assert_int_equal(zs_bus_pixels(&c->bus, px, sizeof px), ZS_BUS_OK);
        assert_int_equal(zs_bus_wait(&c->bus), ZS_BUS_OK);
        assert_int_equal(c->polls, 30);
        assert_int_equal(c->bus.error, 0);
        free(c);
    }
    alarm(0);
}

/* Through the panel: a frame or a write whose transfer never completes
 * returns ZS_PANEL_ERR_TIMEOUT. */
static void test_panel_timeout(void **state)
{
    emu_panel emu;
    zs_panel lcd;
    cap_port *c;
    zs_panel_frame_stats st;
    (void)state;
    alarm(HANG_GUARD_S);
    assert_int_equal(emu_init(&emu, emu_model_find("st7789-240x240")), 0);
    c = cap_open(&emu, 1, 0, 0);
    c->never = 1;
    zs_bus_set_wait_limit(&c->bus, 500, NULL);
    assert_int_equal(zs_panel_init(&lcd, &zs_panel_st7789_240x240, &c->bus, ZS_FMT_RGB565_BE, 0),
                     ZS_PANEL_OK); /* commands only: blocking */
    scene(240, 240, ZS_FMT_RGB565_BE);
    assert_int_equal(zs_panel_stream(&lcd, &R, band0, band1, sizeof band0, 1, NULL, &st),
                     ZS_PANEL_ERR_TIMEOUT);
    assert_int_equal(st.bands, 1); /* the first band started and never ended */
    assert_int_equal(c->polls, 500);
    assert_int_equal(c->transfers, 1);
    /* a write: the wait before its transfer gives up at once */
    assert_int_equal(zs_panel_write(&lcd, band0, 2), ZS_PANEL_ERR_TIMEOUT);
    assert_int_equal(zs_panel_window(&lcd, 0, 0, 1, 1), ZS_PANEL_ERR_TIMEOUT);
    assert_int_equal(c->polls, 500);
    c->never = 0;
    cap_complete(c);
    emu_free(&emu);
    free(c);
    alarm(0);
}

/* A transfer the port reports as failed: the next wait says ZS_BUS_ERR_IO
 * once; through the panel the frame ends with ZS_PANEL_ERR_IO. */
static void test_transfer_fault(void **state)
{
    static const uint8_t px[4] = {1, 2, 3, 4};
    cap_port *c = cap_open(NULL, 1, 2, 0);
    zs_panel lcd;
    (void)state;
    alarm(HANG_GUARD_S);
    c->fail_next = 1;
    assert_int_equal(zs_bus_pixels(&c->bus, px, sizeof px), ZS_BUS_OK);
    assert_int_equal(zs_bus_wait(&c->bus), ZS_BUS_ERR_IO);
    assert_int_equal(c->bus.error, 1);
    assert_int_equal(zs_bus_wait(&c->bus), ZS_BUS_OK); /* reported once */
    /* a fault that arrives before anyone waits is reported by the next
     * command, which is then not sent */
    c->fail_next = 1;
    c->latency = 0;
    assert_int_equal(zs_bus_pixels(&c->bus, px, sizeof px), ZS_BUS_OK);
    assert_true(zs_bus_idle(&c->bus));
    assert_int_equal(zs_bus_cmd(&c->bus, 0x00, NULL, 0), ZS_BUS_ERR_IO);
    assert_int_equal(c->commands, 0);
    /* in a frame */
    c->latency = 3;
    assert_int_equal(zs_panel_init(&lcd, &zs_panel_gc9a01, &c->bus, ZS_FMT_RGB565_BE, 0),
                     ZS_PANEL_OK);
    scene(240, 240, ZS_FMT_RGB565_BE);
    c->fail_next = 1;
    assert_int_equal(zs_panel_stream(&lcd, &R, band0, band1, sizeof band0, 2, NULL, NULL),
                     ZS_PANEL_ERR_IO);
    assert_true(zs_bus_idle(&c->bus));
    free(c);
    alarm(0);
}

/* ------------------------------------------------------------------ */
/* Operations tables                                                    */
/* ------------------------------------------------------------------ */

/* A made-up controller family, written only against the public ops table:
 * init sends 0xE1, the window 0xE5 with the four inclusive coordinates as
 * single bytes, 0xE7 before every write after the first, and the wire wants
 * each byte complemented. */
static zs_panel_status t_cmd(zs_panel *p, uint8_t cmd, const uint8_t *b, size_t n)
{
    return zs_bus_cmd(p->bus, cmd, b, n) == ZS_BUS_OK ? ZS_PANEL_OK : ZS_PANEL_ERR_IO;
}
static zs_panel_status t_init(zs_panel *p) { return t_cmd(p, 0xE1, NULL, 0); }
static zs_panel_status t_format(zs_panel *p)
{
    uint8_t v = (uint8_t)p->format;
    return t_cmd(p, 0xE2, &v, 1);
}
static zs_panel_status t_orient(zs_panel *p) { return t_cmd(p, 0xE3, &p->madctl, 1); }
static zs_panel_status t_invert(zs_panel *p) { return t_cmd(p, 0xE4, &p->inverted, 1); }
static zs_panel_status t_display(zs_panel *p, int on)
{
    return t_cmd(p, on ? 0xE6 : 0xE8, NULL, 0);
}
static zs_panel_status t_window(zs_panel *p, uint16_t xs, uint16_t ys, uint16_t xe, uint16_t ye)
{
    uint8_t b[4] = {(uint8_t)xs, (uint8_t)ys, (uint8_t)xe, (uint8_t)ye};
    return t_cmd(p, 0xE5, b, 4);
}
static zs_panel_status t_write_begin(zs_panel *p, size_t n)
{
    (void)n;
    return p->window_bytes == p->window_total ? ZS_PANEL_OK : t_cmd(p, 0xE7, NULL, 0);
}
static void t_complement(uint8_t *dst, const uint8_t *src, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        dst[i] = (uint8_t)~src[i];
}
static zs_panel_encode_fn t_encoder(const zs_panel *p)
{
    (void)p;
    return t_complement;
}
static const zs_panel_ops t_ops = {
    .name = "test",
    .init = t_init,
    .format = t_format,
    .orient = t_orient,
    .invert = t_invert,
    .display = t_display,
    .window = t_window,
    .write_begin = t_write_begin,
    .encoder = t_encoder,
};
static const zs_panel_desc t_desc = {
    .name = "test-20x10",
    .ops = &t_ops,
    .formats = (uint8_t)(1u << ZS_FMT_RGB565_BE),
    .width = 20,
    .height = 10,
    .ram_width = 32,
    .ram_height = 16,
    .col_offset = 4,
    .row_offset = 2,
};

static void test_new_family_is_an_ops_table(void **state)
{
    /* window [1, 3) x [0, 1) plus offsets (4, 2): RAM columns 5..6, row 2;
     * 4 bytes in two writes: the second announced by 0xE7, all complemented */
    static const uint8_t want[] = {0xE5, 5, 2, 6, 2, 0xAA, 0x55, 0xE7, 0x0F, 0xF0};
    static const uint8_t want_dc[] = {0, 1, 1, 1, 1, 1, 1, 0, 1, 1};
    static const uint8_t px[4] = {0x55, 0xAA, 0xF0, 0x0F};
    cap_port *c = cap_open(NULL, 0, 0, 0);
    zs_panel lcd;
    (void)state;
    assert_int_equal(zs_panel_init(&lcd, &t_desc, &c->bus, ZS_FMT_RGB565_BE, 0), ZS_PANEL_OK);
    assert_int_equal(c->n, 1);
    assert_int_equal(c->byte[0], 0xE1);
    c->n = 0;
    assert_int_equal(zs_panel_window(&lcd, 1, 0, 3, 1), ZS_PANEL_OK);
    assert_int_equal(zs_panel_write(&lcd, px, 2), ZS_PANEL_OK);
    assert_int_equal(zs_panel_write(&lcd, px + 2, 2), ZS_PANEL_OK);
    cap_expect(c, want, want_dc, sizeof want);
    /* the common code's rotation: 90 degrees turns 20x10 into 10x20 and
     * sends the orientation through the table */
    c->n = 0;
    assert_int_equal(zs_panel_set_rotation(&lcd, 1), ZS_PANEL_OK);
    assert_int_equal(lcd.width, 10);
    assert_int_equal(lcd.height, 20);
    assert_int_equal(c->n, 2);
    assert_int_equal(c->byte[0], 0xE3);
    assert_int_equal(c->byte[1], zs_panel_madctl_for(&t_desc, 1));
    free(c);
}

/* Tables the common code cannot drive are refused before a byte is sent. */
static void test_incomplete_tables_refused(void **state)
{
    zs_panel_ops no_window = t_ops, no_init = t_ops;
    zs_panel_desc d1 = t_desc, d2 = t_desc, d3 = t_desc, d4 = zs_panel_gc9a01;
    cap_port *c = cap_open(NULL, 0, 0, 0);
    zs_panel lcd;
    unsigned i;
    (void)state;
    no_window.window = NULL;
    no_init.init = NULL;
    d1.ops = NULL;
    d2.ops = &no_window;
    d3.ops = &no_init;
    d4.colmod_666 = 0; /* the DCS table's own check: no COLMOD for 18 bpp */
    assert_int_equal(zs_panel_init(&lcd, &d1, &c->bus, ZS_FMT_RGB565_BE, 0), ZS_PANEL_ERR_DESC);
    assert_int_equal(zs_panel_init(&lcd, &d2, &c->bus, ZS_FMT_RGB565_BE, 0), ZS_PANEL_ERR_DESC);
    assert_int_equal(zs_panel_init(&lcd, &d3, &c->bus, ZS_FMT_RGB565_BE, 0), ZS_PANEL_ERR_DESC);
    assert_int_equal(zs_panel_init(&lcd, &d4, &c->bus, ZS_FMT_RGB666, 0), ZS_PANEL_ERR_DESC);
    assert_int_equal(c->n, 0);
    /* every built-in description names a complete table */
    for (i = 0; i < zs_panel_count(); i++) {
        const zs_panel_ops *o = zs_panel_at(i)->ops;
        assert_non_null(o);
        assert_true(o == &zs_panel_ops_dcs || o == &zs_panel_ops_ssd1351 ||
                    o == &zs_panel_ops_ssd1306 || o == &zs_panel_ops_sh1106 ||
                    o == &zs_panel_ops_ssd1680 || o == &zs_panel_ops_ssd0303 ||
                    o == &zs_panel_ops_ssd0323);
        assert_non_null(o->name);
        assert_non_null(o->init);
        assert_non_null(o->format);
        assert_non_null(o->orient);
        assert_non_null(o->invert);
        assert_non_null(o->display);
        assert_non_null(o->window);
    }
    assert_string_not_equal(zs_panel_ops_dcs.name, zs_panel_ops_ssd1351.name);
    free(c);
}

/* ------------------------------------------------------------------ */
/* Status texts: the headers are the oracle                             */
/* ------------------------------------------------------------------ */

typedef struct hdr_enum {
    char name[32][48];
    char comment[32][200];
    int n;
} hdr_enum;

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *s;
    long len;
    assert_non_null(f);
    assert_int_equal(fseek(f, 0, SEEK_END), 0);
    len = ftell(f);
    assert_true(len > 0);
    rewind(f);
    s = malloc((size_t)len + 1);
    assert_non_null(s);
    assert_int_equal(fread(s, 1, (size_t)len, f), (size_t)len);
    s[len] = 0;
    fclose(f);
    return s;
}

/* Appends [p, end) to dst with every run of white space as one space (none
 * at the start). */
static void add_words(char *dst, size_t cap, const char *p, const char *end)
{
    size_t n = strlen(dst);
    for (; p < end && n + 2 < cap; p++) {
        if (isspace((unsigned char)*p)) {
            if (n > 0 && dst[n - 1] != ' ')
                dst[n++] = ' ';
        } else {
            dst[n++] = *p;
        }
    }
    dst[n] = 0;
}

/* The enumerators of "typedef enum TAG {" ... "} TAG;" in header, each with
 * the comment(s) after it up to the next one. */
static void parse_enum(const char *header, const char *tag, hdr_enum *e)
{
    char *text = slurp(header), open[80], close[80];
    const char *p, *end;
    int i;
    snprintf(open, sizeof open, "typedef enum %s {", tag);
    snprintf(close, sizeof close, "} %s;", tag);
    p = strstr(text, open);
    assert_non_null(p);
    end = strstr(p, close);
    assert_non_null(end);
    p += strlen(open);
    memset(e, 0, sizeof *e);
    while (p < end) {
        if (p[0] == '/' && p[1] == '*') {
            const char *q = strstr(p + 2, "*/");
            assert_true(q != NULL && q < end);
            assert_true(e->n > 0);
            add_words(e->comment[e->n - 1], sizeof e->comment[0], p + 2, q);
            p = q + 2;
        } else if (isalpha((unsigned char)*p) || *p == '_') {
            const char *q = p;
            while (isalnum((unsigned char)*q) || *q == '_')
                q++;
            assert_true(e->n < 32 && (size_t)(q - p) < sizeof e->name[0]);
            memcpy(e->name[e->n], p, (size_t)(q - p));
            e->n++;
            while (q < end && *q != ',' && *q != '\n' && !(q[0] == '/' && q[1] == '*'))
                q++; /* "= 0" */
            p = q;
        } else {
            p++;
        }
    }
    for (i = 0; i < e->n; i++) {
        size_t n = strlen(e->comment[i]);
        while (n > 0 && e->comment[i][n - 1] == ' ')
            e->comment[i][--n] = 0;
    }
    free(text);
}

typedef struct code_name {
    int code;
    const char *name;
} code_name;

static const code_name bus_codes[] = {
    {ZS_BUS_OK, "ZS_BUS_OK"},
    {ZS_BUS_ERR_NULL, "ZS_BUS_ERR_NULL"},
    {ZS_BUS_ERR_IO, "ZS_BUS_ERR_IO"},
    {ZS_BUS_ERR_ARGUMENT, "ZS_BUS_ERR_ARGUMENT"},
    {ZS_BUS_ERR_TIMEOUT, "ZS_BUS_ERR_TIMEOUT"},
};

static const code_name panel_codes[] = {
    {ZS_PANEL_OK, "ZS_PANEL_OK"},
    {ZS_PANEL_ERR_NULL, "ZS_PANEL_ERR_NULL"},
    {ZS_PANEL_ERR_IO, "ZS_PANEL_ERR_IO"},
    {ZS_PANEL_ERR_FORMAT, "ZS_PANEL_ERR_FORMAT"},
    {ZS_PANEL_ERR_ROTATION, "ZS_PANEL_ERR_ROTATION"},
    {ZS_PANEL_ERR_WINDOW, "ZS_PANEL_ERR_WINDOW"},
    {ZS_PANEL_ERR_STATE, "ZS_PANEL_ERR_STATE"},
    {ZS_PANEL_ERR_DESC, "ZS_PANEL_ERR_DESC"},
    {ZS_PANEL_ERR_BUFFER, "ZS_PANEL_ERR_BUFFER"},
    {ZS_PANEL_ERR_RENDER, "ZS_PANEL_ERR_RENDER"},
    {ZS_PANEL_ERR_TIMEOUT, "ZS_PANEL_ERR_TIMEOUT"},
    {ZS_PANEL_ERR_SIZE, "ZS_PANEL_ERR_SIZE"},
    {ZS_PANEL_ERR_FRAME_FORMAT, "ZS_PANEL_ERR_FRAME_FORMAT"},
};

/* Checks one enum: the header lists exactly these codes in order, then the
 * COUNT sentinel; the OK code reads "ok"; every other code's text is its
 * header comment; all texts distinct; values outside get `unknown`, which
 * is none of the codes' texts. */
static void check_texts(const char *header, const char *tag, const code_name *codes, int ncodes,
                        int count, const char *count_name, const char *(*text)(int),
                        const char *unknown)
{
    static hdr_enum e;
    static const int outside[] = {-1, 1000, 0x7FFFFFFF};
    int i, j;
    parse_enum(header, tag, &e);
    assert_int_equal(count, ncodes); /* a code added to the enum needs a row here */
    assert_int_equal(e.n, ncodes + 1);
    assert_string_equal(e.name[ncodes], count_name);
    for (i = 0; i < ncodes; i++) {
        const char *t = text(codes[i].code);
        assert_int_equal(codes[i].code, i);
        assert_string_equal(e.name[i], codes[i].name);
        assert_non_null(t);
        assert_true(t[0] != 0);
        if (i == 0) {
            assert_string_equal(t, "ok");
        } else {
            if (strcmp(t, e.comment[i]) != 0)
                print_message("    %s: text \"%s\", header \"%s\"\n", codes[i].name, t,
                              e.comment[i]);
            assert_string_equal(t, e.comment[i]);
        }
        for (j = 0; j < i; j++)
            assert_string_not_equal(t, text(codes[j].code));
    }
    assert_string_equal(text(count), unknown);
    for (i = 0; i < (int)(sizeof outside / sizeof outside[0]); i++)
        assert_string_equal(text(outside[i]), unknown);
    for (j = 0; j < ncodes; j++)
        assert_string_not_equal(unknown, text(codes[j].code));
}

static const char *bus_text(int s) { return zs_bus_strerror((zs_bus_status)s); }
static const char *panel_text(int s) { return zs_panel_strerror((zs_panel_status)s); }

static void test_status_texts_match_headers(void **state)
{
    (void)state;
    check_texts(ZT_TOP_DIR "/include/zspan/bus.h", "zs_bus_status", bus_codes,
                (int)(sizeof bus_codes / sizeof bus_codes[0]), ZS_BUS_STATUS_COUNT,
                "ZS_BUS_STATUS_COUNT", bus_text, "unknown bus status");
    check_texts(ZT_TOP_DIR "/include/zspan/panel.h", "zs_panel_status", panel_codes,
                (int)(sizeof panel_codes / sizeof panel_codes[0]), ZS_PANEL_STATUS_COUNT,
                "ZS_PANEL_STATUS_COUNT", panel_text, "unknown panel status");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_stream_refuses_other_size),
        cmocka_unit_test(test_stream_refuses_other_format),
        cmocka_unit_test(test_format_is_a_panel_property),
        cmocka_unit_test(test_const_data_reaches_the_wire),
        cmocka_unit_test(test_inplace_write),
        cmocka_unit_test(test_bus_timeout_counted_rounds),
        cmocka_unit_test(test_bus_timeout_by_clock),
        cmocka_unit_test(test_panel_timeout),
        cmocka_unit_test(test_transfer_fault),
        cmocka_unit_test(test_new_family_is_an_ops_table),
        cmocka_unit_test(test_incomplete_tables_refused),
        cmocka_unit_test(test_status_texts_match_headers),
    };
    return cmocka_run_group_tests_name("panel_contract", tests, NULL, NULL);
}
