/* SPDX-License-Identifier: MIT */
/*
 * test_panel_gray4: the Stellaris boards' OLED drivers against zspan's own
 * emulated controllers (issue 20).
 *
 *  - SSD0323 (ZS_FMT_GRAY4, 4-wire SPI): frames streamed with
 *    zs_panel_stream in bands of 1, 3, 8 and 64 rows, rounded and dithered,
 *    show on the emulated glass level for level as the core rendered them
 *    (zs_render_rows into one buffer, unpacked here); no protocol error.
 *    A partial window lands on its pixels only; odd column starts are
 *    refused; a re-map without the nibble bit shows a wrong picture (the
 *    check is not circular).
 *  - SSD0303 (ZS_FMT_MONO_PAGE over I2C, Co = 1 framing, address 0x3D):
 *    frames equal the core's bits, page addressing per page; a port
 *    pointed at 0x3C (no device) gets ZS_PANEL_ERR_IO from zs_panel_init.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "emu_gray.h"
#include "emu_mono.h"
#include "zspan/panel.h"

/* ---- a scene for the core: 30 lit triangles in front of the camera ---- */

typedef struct scene {
    int16_t pos[3 * 90];
    uint16_t idx[3 * 30];
    zs_color vcol[90];
    zs_mesh mesh;
} scene;

static uint32_t rng(uint32_t *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s >> 8;
}

static void make_scene(scene *s, uint32_t seed)
{
    int i;
    for (i = 0; i < 90; i++) {
        int cx = (int)(rng(&seed) % 4000) - 2000, cy = (int)(rng(&seed) % 4000) - 2000;
        s->pos[3 * i] = (int16_t)(cx + (int)(rng(&seed) % 2400) - 1200);
        s->pos[3 * i + 1] = (int16_t)(cy + (int)(rng(&seed) % 2400) - 1200);
        s->pos[3 * i + 2] = (int16_t)(-2000 - (int)(rng(&seed) % 4000));
        s->vcol[i] = rng(&seed) & 0xFFFFFFu;
    }
    for (i = 0; i < 30; i++) {
        int a = 3 * i, b = 3 * i + 1, c = 3 * i + 2;
        double x0 = s->pos[3 * a] / (double)-s->pos[3 * a + 2], y0 = s->pos[3 * a + 1] / (double)-s->pos[3 * a + 2];
        double x1 = s->pos[3 * b] / (double)-s->pos[3 * b + 2], y1 = s->pos[3 * b + 1] / (double)-s->pos[3 * b + 2];
        double x2 = s->pos[3 * c] / (double)-s->pos[3 * c + 2], y2 = s->pos[3 * c + 1] / (double)-s->pos[3 * c + 2];
        double area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
        s->idx[3 * i] = (uint16_t)a;
        s->idx[3 * i + 1] = (uint16_t)(area > 0 ? b : c);
        s->idx[3 * i + 2] = (uint16_t)(area > 0 ? c : b);
    }
    memset(&s->mesh, 0, sizeof s->mesh);
    s->mesh.positions = s->pos;
    s->mesh.indices = s->idx;
    s->mesh.vertex_colors = s->vcol;
    s->mesh.scale = ZS_FX(1) / 1000;
    s->mesh.vertex_count = 90;
    s->mesh.triangle_count = 30;
}

typedef struct core {
    zs_renderer r;
    uint8_t *arena;
} core;

static void core_open(core *c, unsigned w, unsigned h)
{
    zs_config cfg = zs_config_default((uint16_t)w, (uint16_t)h, 200, 200, 200);
    cfg.flags = ZS_CFG_MONO;
    size_t n = zs_arena_bytes(&cfg);
    c->arena = malloc(n);
    assert_int_equal(zs_init(&c->r, c->arena, n, &cfg), ZS_OK);
}

static void frame(core *c, const scene *s, zs_format fmt, unsigned mono)
{
    zs_camera cam;
    assert_int_equal(zs_camera_look_at(&cam, zs_vec3_make(0, 0, 0), zs_vec3_make(0, 0, -ZS_FX(1)),
                                       zs_vec3_make(0, ZS_FX(1), 0)),
                     ZS_OK);
    assert_int_equal(zs_camera_perspective(&cam, ZS_FX(70), ZS_FX(1) / 2, ZS_FX(50)), ZS_OK);
    assert_int_equal(zs_frame_begin(&c->r, &cam, ZS_MODE_SPAN), ZS_OK);
    zs_shade_params sp = zs_shade_default();
    sp.shading = ZS_SHADE_GOURAUD;
    sp.format = fmt;
    sp.mono = (uint8_t)mono;
    sp.background = 0x303030;
    assert_int_equal(zs_frame_shading(&c->r, &sp), ZS_OK);
    assert_int_equal(zs_draw(&c->r, &s->mesh, NULL), ZS_OK);
}

/* The core's picture: levels (GRAY4) or 0/1 (pages), one byte a pixel. */
static void reference(core *c, const scene *s, zs_format fmt, unsigned mono, unsigned w,
                      unsigned h, uint8_t *px)
{
    size_t n = zs_panel_window_bytes(fmt, w, h), stride = zs_format_stride(fmt, w);
    uint8_t *img = calloc(n, 1);
    frame(c, s, fmt, mono);
    assert_int_equal(zs_render_rows(&c->r, 0, (int)h, img, stride), ZS_OK);
    for (unsigned y = 0; y < h; y++)
        for (unsigned x = 0; x < w; x++)
            px[y * w + x] = fmt == ZS_FMT_GRAY4
                                ? (uint8_t)((img[y * stride + x / 2] >> (x % 2 ? 0 : 4)) & 15u)
                                : (uint8_t)((img[(y / 8) * w + x] >> (y % 8)) & 1u);
    free(img);
}

static unsigned count_diff(const uint8_t *a, const uint8_t *b, size_t n, size_t *first)
{
    unsigned d = 0;
    for (size_t i = 0; i < n; i++)
        if (a[i] != b[i] && d++ == 0) *first = i;
    return d;
}

/* ---- SSD0323 ---- */

static void test_ssd0323_frames(void **state)
{
    (void)state;
    static const int bands[] = {1, 3, 8, 64};
    const zs_panel_desc *d = zs_panel_find("ssd0323-128x64");
    assert_non_null(d);
    core c;
    core_open(&c, 128, 64);
    scene s;
    static emu_gray e;
    emu_gray_port port;
    zs_panel p;
    uint8_t want[128 * 64], got[128 * 64], b0[64 * 8], b1[64 * 8];
    unsigned frames = 0;
    emu_gray_init(&e);
    assert_int_equal(emu_gray_port_init(&port, &e), 0);
    assert_int_equal(zs_panel_init(&p, d, &port.bus, ZS_FMT_GRAY4, 0), ZS_PANEL_OK);
    for (unsigned k = 0; k < 8; k++) {
        unsigned mono = (k & 1) ? ZS_GRAY4_DITHER : 0;
        make_scene(&s, 1000u + k);
        reference(&c, &s, ZS_FMT_GRAY4, mono, 128, 64, want);
        frame(&c, &s, ZS_FMT_GRAY4, mono);
        zs_panel_frame_stats st;
        assert_int_equal(zs_panel_stream(&p, &c.r, b0, k & 2 ? b1 : NULL, sizeof b0,
                                         bands[k % 4], NULL, &st),
                         ZS_PANEL_OK);
        assert_int_equal(st.bus.pixel_bytes, 64 * 64);
        emu_gray_view(&e, got);
        size_t first = 0;
        unsigned diff = count_diff(want, got, sizeof want, &first);
        if (diff)
            fail_msg("frame %u (band %d): %u pixels differ, first (%zu,%zu) %u vs %u", k,
                     bands[k % 4], diff, first % 128, first / 128, got[first], want[first]);
        if (e.errors)
            fail_msg("emulator: %s", e.first_error);
        frames++;
    }
    /* a grey ramp must use all 16 levels (the picture is not trivially flat) */
    unsigned seen = 0;
    for (size_t i = 0; i < sizeof got; i++) seen |= 1u << got[i];
    print_message("SSD0323: %u frames equal the core's GRAY4 levels; levels seen 0x%04x\n",
                  frames, seen);
    assert_true(__builtin_popcount(seen) >= 8);
    free(c.arena);
}

static void test_ssd0323_windows(void **state)
{
    (void)state;
    const zs_panel_desc *d = zs_panel_find("ssd0323-128x64");
    static emu_gray e;
    emu_gray_port port;
    zs_panel p;
    uint8_t before[128 * 64], after[128 * 64], data[6 * 5];
    emu_gray_init(&e);
    assert_int_equal(emu_gray_port_init(&port, &e), 0);
    assert_int_equal(zs_panel_init(&p, d, &port.bus, ZS_FMT_GRAY4, 0), ZS_PANEL_OK);
    assert_int_equal(zs_panel_init(&p, d, &port.bus, ZS_FMT_MONO_PAGE, 0), ZS_PANEL_ERR_FORMAT);
    assert_int_equal(zs_panel_init(&p, d, &port.bus, ZS_FMT_GRAY4, 2), ZS_PANEL_ERR_ROTATION);
    assert_int_equal(zs_panel_init(&p, d, &port.bus, ZS_FMT_GRAY4, 0), ZS_PANEL_OK);
    assert_int_equal(zs_panel_window(&p, 11, 5, 22, 10), ZS_PANEL_ERR_WINDOW); /* odd start */
    assert_int_equal(zs_panel_window(&p, 10, 5, 21, 10), ZS_PANEL_ERR_WINDOW); /* odd end */
    assert_int_equal(zs_panel_window_bytes(ZS_FMT_GRAY4, 127, 3), 64u * 3u);
    emu_gray_view(&e, before);
    /* columns 10..21 (6 pairs), rows 5..9: each pixel a known level */
    for (unsigned i = 0; i < sizeof data; i++)
        data[i] = (uint8_t)(((2 * i) % 16) << 4 | ((2 * i + 1) % 16));
    assert_int_equal(zs_panel_window(&p, 10, 5, 22, 10), ZS_PANEL_OK);
    assert_int_equal(zs_panel_write(&p, data, sizeof data), ZS_PANEL_OK);
    emu_gray_view(&e, after);
    for (unsigned y = 0; y < 64; y++)
        for (unsigned x = 0; x < 128; x++) {
            int in = x >= 10 && x < 22 && y >= 5 && y < 10;
            unsigned i = (y - 5) * 12 + (x - 10);
            uint8_t want = in ? (uint8_t)(i % 16) : before[y * 128 + x];
            if (after[y * 128 + x] != want)
                fail_msg("(%u,%u): %u, want %u", x, y, after[y * 128 + x], want);
        }
    assert_int_equal(e.errors, 0);
    /* without the nibble re-map the pairs come out swapped */
    {
        uint8_t raw[2] = {ZS_SSD0323_REMAP, ZS_SSD0323_RM_COMSPLIT};
        assert_int_equal(zs_bus_cmd(&port.bus, raw[0], NULL, 0), ZS_BUS_OK);
        assert_int_equal(zs_bus_cmd(&port.bus, raw[1], NULL, 0), ZS_BUS_OK);
        emu_gray_view(&e, after);
        assert_int_equal(after[5 * 128 + 10], 1);
        assert_int_equal(after[5 * 128 + 11], 0);
    }
}

/* ---- SSD0303 over I2C ---- */

static void test_ssd0303_frames(void **state)
{
    (void)state;
    const zs_panel_desc *d = zs_panel_find("ssd0303-96x16");
    assert_non_null(d);
    const emu_mono_model *m = emu_mono_model_find("ssd0303-96x16");
    assert_non_null(m);
    core c;
    core_open(&c, 96, 16);
    scene s;
    emu_mono e;
    emu_mono_port port;
    zs_panel p;
    uint8_t want[96 * 16], got[96 * 16], b0[96 * 2];
    assert_int_equal(emu_mono_init(&e, m), 0);
    assert_int_equal(emu_mono_port_init(&port, &e, 1, ZS_SSD0303_I2C_ADDR), 0);
    port.co_each = 1;
    assert_int_equal(zs_panel_init(&p, d, &port.bus, ZS_FMT_MONO_PAGE, 0), ZS_PANEL_OK);
    for (unsigned k = 0; k < 6; k++) {
        unsigned mono = (k & 1) ? ZS_MONO_DIFFUSE : 0;
        make_scene(&s, 2000u + k);
        reference(&c, &s, ZS_FMT_MONO_PAGE, mono, 96, 16, want);
        frame(&c, &s, ZS_FMT_MONO_PAGE, mono);
        assert_int_equal(zs_panel_stream(&p, &c.r, b0, NULL, sizeof b0, 8 + 8 * (k % 2), NULL,
                                         NULL),
                         ZS_PANEL_OK);
        emu_mono_view(&e, 0, got);
        size_t first = 0;
        unsigned diff = count_diff(want, got, sizeof want, &first);
        if (diff)
            fail_msg("frame %u: %u pixels differ, first (%zu,%zu)", k, diff, first % 96,
                     first / 96);
        if (e.errors)
            fail_msg("emulator: %s", e.first_error);
    }
    print_message("SSD0303: 6 frames over I2C equal the core's bits (%u transactions)\n",
                  port.frames);
    emu_mono_free(&e);
    free(c.arena);
}

static void test_ssd0303_nack(void **state)
{
    (void)state;
    emu_mono e;
    emu_mono_port port;
    zs_panel p;
    assert_int_equal(emu_mono_init(&e, emu_mono_model_find("ssd0303-96x16")), 0);
    assert_int_equal(emu_mono_port_init(&port, &e, 1, ZS_SSD1306_I2C_ADDR), 0); /* 0x3C */
    port.co_each = 1;
    assert_int_equal(zs_panel_init(&p, zs_panel_find("ssd0303-96x16"), &port.bus,
                                   ZS_FMT_MONO_PAGE, 0),
                     ZS_PANEL_ERR_IO);
    assert_true(e.nacks >= 1);
    assert_int_equal(e.i2c_frames, 0);
    emu_mono_free(&e);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ssd0323_frames),
        cmocka_unit_test(test_ssd0323_windows),
        cmocka_unit_test(test_ssd0303_frames),
        cmocka_unit_test(test_ssd0303_nack),
    };
    return cmocka_run_group_tests_name("panel_gray4", tests, NULL, NULL);
}
