/* SPDX-License-Identifier: MIT */
/* The full path: renderer -> frame streamer -> driver -> bus -> emulated
 * panel. For every panel, pixel format and rotation the picture on the
 * emulated glass equals the picture the core renders into a plain buffer, and
 * an asynchronous bus (completion delivered later) gives the same picture as
 * a blocking one without the renderer ever writing a buffer the bus owns. */
#include "ptest.h"

#define MAXW 480
#define MAXH 480
static uint8_t arena[ZS_ARENA_BYTES(MAXW, MAXH, 600, 600, 256)];
static zs_renderer R;
static uint8_t ref[MAXW * MAXH * 3];
static uint8_t band0[MAXW * 3 * 16], band1[MAXW * 3 * 16];

/* A small scene: a flat-coloured cube, a vertex-coloured pyramid that cuts
 * into it, and a floor, turned by `frame`. */
static const int16_t cube_pos[] = {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1,
                                   -1, -1, 1,  1, -1, 1,  1, 1, 1,  -1, 1, 1};
static const uint16_t cube_idx[] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                    2, 3, 7, 2, 7, 6, 1, 2, 6, 1, 6, 5, 0, 4, 7, 0, 7, 3};
static const zs_color cube_col[] = {
    ZS_RGB(255, 0, 0),   ZS_RGB(200, 0, 0),   ZS_RGB(0, 255, 0),   ZS_RGB(0, 200, 0),
    ZS_RGB(0, 0, 255),   ZS_RGB(0, 0, 200),   ZS_RGB(255, 255, 0), ZS_RGB(200, 200, 0),
    ZS_RGB(0, 255, 255), ZS_RGB(0, 200, 200), ZS_RGB(255, 0, 255), ZS_RGB(200, 0, 200)};
static const int16_t pyr_pos[] = {0, 2, 0, -1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1};
static const uint16_t pyr_idx[] = {0, 2, 1, 0, 3, 2, 0, 4, 3, 0, 1, 4, 1, 2, 3, 1, 3, 4};
static const zs_color pyr_vcol[] = {ZS_RGB(255, 255, 255), ZS_RGB(255, 64, 0),
                                    ZS_RGB(0, 128, 255), ZS_RGB(64, 255, 64),
                                    ZS_RGB(255, 0, 128)};
static const int16_t floor_pos[] = {-4, -1, -4, 4, -1, -4, 4, -1, 4, -4, -1, 4};
static const uint16_t floor_idx[] = {0, 2, 1, 0, 3, 2};

static zs_mesh mesh(const int16_t *pos, uint16_t nv, const uint16_t *idx, uint16_t nt,
                    const zs_color *fcol, const zs_color *vcol, zs_color color)
{
    zs_mesh m;
    memset(&m, 0, sizeof m);
    m.positions = pos;
    m.indices = idx;
    m.face_colors = fcol;
    m.vertex_colors = vcol;
    m.scale = ZS_FX(1);
    m.vertex_count = nv;
    m.triangle_count = nt;
    m.color = color;
    return m;
}

/* Begins frame `frame` of the scene on an w x h renderer in fmt. */
static void scene_frame(unsigned w, unsigned h, zs_format fmt, unsigned frame)
{
    zs_config cfg = zs_config_default((uint16_t)w, (uint16_t)h, 600, 600, 256);
    zs_camera cam;
    zs_shade_params sp = zs_shade_default();
    zs_mesh cube = mesh(cube_pos, 8, cube_idx, 12, cube_col, NULL, 0);
    zs_mesh pyr = mesh(pyr_pos, 5, pyr_idx, 6, NULL, pyr_vcol, 0);
    zs_mesh flo = mesh(floor_pos, 4, floor_idx, 2, NULL, NULL, ZS_RGB(90, 90, 110));
    zs_mat34 m, t;

    assert_int_equal(zs_init(&R, arena, sizeof arena, &cfg), ZS_OK);
    assert_int_equal(zs_camera_look_at(&cam, zs_vec3_make(ZS_FX(3), ZS_FX(3), ZS_FX(6)),
                                       zs_vec3_make(0, 0, 0), zs_vec3_make(0, ZS_FX(1), 0)),
                     ZS_OK);
    assert_int_equal(zs_camera_perspective(&cam, ZS_FX(50), ZS_FX_RATIO(1, 10), ZS_FX(50)),
                     ZS_OK);
    assert_int_equal(zs_frame_begin(&R, &cam, ZS_MODE_SPAN), ZS_OK);
    sp.format = fmt;
    sp.shading = ZS_SHADE_GOURAUD;
    sp.background = ZS_RGB(20, 30, 60);
    assert_int_equal(zs_frame_shading(&R, &sp), ZS_OK);
    m = zs_mat34_rotate_y(ZS_FX((int)(frame * 17u)));
    assert_int_equal(zs_draw(&R, &flo, NULL), ZS_OK);
    assert_int_equal(zs_draw(&R, &cube, &m), ZS_OK);
    t = zs_mat34_translate(ZS_FX_RATIO(1, 2), 0, ZS_FX_RATIO(1, 3));
    m = zs_mat34_mul(&t, &m);
    assert_int_equal(zs_draw(&R, &pyr, &m), ZS_OK);
}

static void render_reference(unsigned w, unsigned h, zs_format fmt, unsigned frame)
{
    size_t stride = (size_t)w * zs_format_bytes(fmt);
    scene_frame(w, h, fmt, frame);
    assert_int_equal(zs_render_rows(&R, 0, (int)h, ref, stride), ZS_OK);
}

/* Streams the frame to an emulated panel; returns the number of pixels that
 * differ from the reference. */
static unsigned stream_case(const zs_panel_desc *d, zs_format fmt, unsigned rot, int async,
                            unsigned latency, uint32_t seed, uint32_t max_transfer, int band,
                            int two_buffers, unsigned frame, zs_panel_frame_stats *st,
                            unsigned *violations)
{
    pt_rig r;
    zs_wire_model wm = zs_wire_model_default(d->max_spi_hz);
    unsigned bad, w, h;

    assert_int_equal(pt_rig_open(&r, d, fmt, rot, async, latency, max_transfer), ZS_PANEL_OK);
    r.port.jitter_seed = seed;
    w = r.panel.width;
    h = r.panel.height;
    render_reference(w, h, fmt, frame);
    {
        /* the picture must have something in it, or equality proves nothing */
        unsigned bpp = zs_format_bytes(fmt), k, other = 0;
        for (k = 1; k < w * h; k++)
            other += memcmp(ref, ref + (size_t)k * bpp, bpp) != 0;
        assert_true(other > w * h / 5);
    }
    scene_frame(w, h, fmt, frame);
    assert_int_equal(zs_panel_stream(&r.panel, &R, band0, two_buffers ? band1 : NULL,
                                     (size_t)w * zs_format_bytes(fmt) * (size_t)band, band,
                                     &wm, st),
                     ZS_PANEL_OK);
    assert_true(zs_bus_idle(&r.port.bus));
    emu_flush(&r.emu);
    if (r.emu.errors)
        pt_print_errors(&r.emu);
    assert_int_equal(r.emu.errors, 0);
    bad = pt_compare_view(&r.emu, rot, ref, w, h, fmt);
    *violations = r.port.violations;
    if (r.port.violations)
        print_message("    bus: %s\n", r.port.violation);
    pt_rig_close(&r);
    return bad;
}

static void test_every_panel_format_rotation(void **state)
{
    unsigned i, f, rot, cases = 0;
    (void)state;
    for (i = 0; i < zs_panel_count(); i++) {
        const zs_panel_desc *d = zs_panel_at(i);
        for (f = 0; f < 2; f++) {
            if (!zs_panel_bytes_per_pixel(d, pt_formats[f]))
                continue;
            for (rot = 0; rot < 4; rot++) {
                zs_panel_frame_stats st;
                unsigned v, bad = stream_case(d, pt_formats[f], rot, 0, 0, 0, 0, 1, 1,
                                              rot + 2u * f, &st, &v);
                unsigned bpp = zs_panel_bytes_per_pixel(d, pt_formats[f]);
                if (bad)
                    print_message("    %s fmt %d rot %u: %u pixels differ\n", d->name,
                                  (int)pt_formats[f], rot, bad);
                assert_int_equal(bad, 0);
                assert_int_equal(v, 0);
                assert_int_equal(st.render_status, ZS_OK);
                assert_int_equal(st.bus.pixel_bytes, (uint32_t)d->width * d->height * bpp);
                assert_int_equal(st.bands, rot & 1u ? d->width : d->height);
                cases++;
            }
        }
    }
    assert_int_equal(cases, 60);
}

static void test_async_equals_blocking(void **state)
{
    static const struct {
        const char *name;
        zs_format fmt;
        unsigned rot, latency;
        uint32_t seed, max_transfer;
        int band, two;
    } cases[] = {
        {"st7789-240x240", ZS_FMT_RGB565_BE, 0, 4, 0, 0, 1, 1},
        {"st7789-240x240", ZS_FMT_RGB565_BE, 3, 9, 12345u, 4096, 4, 1},
        {"st7789-135x240", ZS_FMT_RGB666, 1, 5, 777u, 1000, 3, 1},
        {"ili9341", ZS_FMT_RGB565_BE, 1, 2, 0, 4096, 8, 1},
        {"st7735-128x160", ZS_FMT_RGB666, 2, 7, 99u, 64, 2, 1},
        {"gc9a01", ZS_FMT_RGB565_BE, 0, 3, 5u, 0, 16, 1},
        {"ili9488", ZS_FMT_RGB666, 1, 6, 31337u, 4096, 2, 1},
        {"ssd1351", ZS_FMT_RGB666, 3, 4, 4242u, 100, 1, 1},
        {"ssd1351", ZS_FMT_RGB565_BE, 0, 4, 0, 0, 5, 0}, /* one buffer */
        {"st7789-240x320", ZS_FMT_RGB565_BE, 2, 0, 0, 0, 1, 1}, /* done at once */
    };
    unsigned i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const zs_panel_desc *d = zs_panel_find(cases[i].name);
        zs_panel_frame_stats sb, sa;
        unsigned vb, va;
        assert_int_equal(stream_case(d, cases[i].fmt, cases[i].rot, 0, 0, 0, 0, cases[i].band,
                                     cases[i].two, 5, &sb, &vb),
                         0);
        assert_int_equal(stream_case(d, cases[i].fmt, cases[i].rot, 1, cases[i].latency,
                                     cases[i].seed, cases[i].max_transfer, cases[i].band,
                                     cases[i].two, 5, &sa, &va),
                         0);
        assert_int_equal(vb, 0);
        assert_int_equal(va, 0);
        assert_int_equal(sa.bus.pixel_bytes, sb.bus.pixel_bytes);
        assert_int_equal(sa.bus.commands, sb.bus.commands);
        if (cases[i].latency > 0 && cases[i].seed == 0)
            assert_true(sa.wire_waits > 0); /* the bus really was still busy */
        if (cases[i].max_transfer)
            assert_true(sa.bus.transfers >= sb.bus.pixel_bytes / cases[i].max_transfer);
    }
}

/* The checker itself: a streamer that renders into the buffer it has just
 * handed to the bus is caught (checksum; ASan poisoning is off here so the
 * breach is counted instead of aborting the program). */
static void test_bus_catches_buffer_reuse(void **state)
{
    pt_rig r;
    int y;
    size_t stride;
    (void)state;
    assert_int_equal(pt_rig_open(&r, &zs_panel_st7789_240x240, ZS_FMT_RGB565_BE, 0, 1, 3, 0),
                     ZS_PANEL_OK);
    r.port.no_poison = 1;
    stride = 240 * 2;
    scene_frame(240, 240, ZS_FMT_RGB565_BE, 1);
    assert_int_equal(zs_panel_window(&r.panel, 0, 0, 240, 240), ZS_PANEL_OK);
    for (y = 0; y < 240; y++) {
        /* wrong: no wait before reusing band0 */
        assert_int_equal(zs_render_rows(&R, y, 1, band0, stride), ZS_OK);
        assert_int_equal(zs_panel_write(&r.panel, band0, stride), ZS_PANEL_OK);
    }
    zs_bus_wait(&r.port.bus);
    assert_true(r.port.violations > 0);
    print_message("    caught: %s (%u times)\n", r.port.violation, r.port.violations);
    pt_rig_close(&r);
}

/* Wire figures: 240x240 RGB565 = 115,200 pixel bytes, 14.7456 ms at 62.5 MHz
 * plus the command and transfer overheads. */
static void test_frame_statistics(void **state)
{
    zs_panel_frame_stats st;
    unsigned v;
    uint64_t bits_ns;
    (void)state;
    assert_int_equal(stream_case(&zs_panel_st7789_240x240, ZS_FMT_RGB565_BE, 0, 1, 2, 0, 0, 1,
                                 1, 0, &st, &v),
                     0);
    assert_int_equal(st.bus.pixel_bytes, 115200);
    assert_int_equal(st.bus.commands, 3); /* CASET, RASET, RAMWR */
    assert_int_equal(st.bus.param_bytes, 8);
    assert_int_equal(st.bus.transfers, 240);
    assert_int_equal(st.bytes, 115200u + 3u + 8u);
    assert_int_equal(st.bands, 240);
    bits_ns = ((uint64_t)st.bytes * 8u * 1000000000u + 31250000u) / 62500000u;
    assert_int_equal(st.wire_ns, bits_ns + 3u * ZS_WIRE_CMD_OVERHEAD_NS +
                                     240u * ZS_WIRE_XFER_OVERHEAD_NS);
    assert_true(st.wire_ns > 14745600u && st.wire_ns < 15300000u);
}

static void test_stream_argument_checks(void **state)
{
    pt_rig r;
    zs_panel_frame_stats st;
    (void)state;
    assert_int_equal(pt_rig_open(&r, &zs_panel_gc9a01, ZS_FMT_RGB565_BE, 0, 0, 0, 0),
                     ZS_PANEL_OK);
    scene_frame(240, 240, ZS_FMT_RGB565_BE, 0);
    assert_int_equal(zs_panel_stream(&r.panel, &R, band0, band1, 479, 1, NULL, &st),
                     ZS_PANEL_ERR_BUFFER);
    assert_int_equal(zs_panel_stream(&r.panel, &R, band0, band1, 480, 0, NULL, &st),
                     ZS_PANEL_ERR_BUFFER);
    assert_int_equal(zs_panel_stream(&r.panel, NULL, band0, band1, 480, 1, NULL, &st),
                     ZS_PANEL_ERR_NULL);
    /* a renderer smaller than the panel: refused before anything is sent
     * (test_panel_contract checks the mismatches in detail) */
    scene_frame(240, 100, ZS_FMT_RGB565_BE, 0);
    assert_int_equal(zs_panel_stream(&r.panel, &R, band0, band1, 480, 1, NULL, &st),
                     ZS_PANEL_ERR_SIZE);
    assert_int_equal(st.render_status, ZS_OK);
    assert_int_equal(st.bands, 0);
    /* a frame that fits but cannot render (rows asked for out of order: the
     * core refuses a row before the last one) still reports the core's error */
    scene_frame(240, 240, ZS_FMT_RGB565_BE, 0);
    assert_int_equal(zs_render_rows(&R, 239, 1, band0, 480), ZS_OK);
    assert_int_equal(zs_panel_stream(&r.panel, &R, band0, band1, 480, 1, NULL, &st),
                     ZS_PANEL_ERR_RENDER);
    assert_int_not_equal(st.render_status, ZS_OK);
    pt_rig_close(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_panel_format_rotation),
        cmocka_unit_test(test_async_equals_blocking),
        cmocka_unit_test(test_bus_catches_buffer_reuse),
        cmocka_unit_test(test_frame_statistics),
        cmocka_unit_test(test_stream_argument_checks),
    };
    return cmocka_run_group_tests_name("panel_stream", tests, NULL, NULL);
}
