/* SPDX-License-Identifier: MIT */
/* Panel driver -> bus -> emulated panel with synthetic pictures (no renderer):
 * for every panel, pixel format and rotation the picture the viewer sees
 * equals the picture sent, pixel for pixel. */
#include "ptest.h"
#include "emu_gray.h"
#include "emu_mono.h"

/* Sends a full-screen picture in chunks of `chunk` bytes (any size: pixels
 * may straddle chunks). */
static void send_full(pt_rig *r, const uint8_t *img, size_t bytes, size_t chunk)
{
    size_t off = 0;
    assert_int_equal(zs_panel_window(&r->panel, 0, 0, r->panel.width, r->panel.height),
                     ZS_PANEL_OK);
    while (off < bytes) {
        size_t n = bytes - off < chunk ? bytes - off : chunk;
        assert_int_equal(zs_panel_write(&r->panel, img + off, n), ZS_PANEL_OK);
        off += n;
    }
    zs_bus_wait(&r->port.bus);
}

static uint8_t *make_picture(unsigned w, unsigned h, zs_format fmt, unsigned salt)
{
    unsigned bpp = fmt == ZS_FMT_RGB565_BE ? 2u : 3u, x, y;
    uint8_t *img = malloc((size_t)w * h * bpp);
    assert_non_null(img);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++)
            pt_pattern_pixel(x + salt, y, fmt, img + ((size_t)y * w + x) * bpp);
    return img;
}

/* One panel/format/rotation: full frame, then a partial window on top. */
static void run_case(const zs_panel_desc *d, zs_format fmt, unsigned rot, int async,
                     size_t chunk, int ramwrc)
{
    pt_rig r;
    unsigned w, h, bpp = fmt == ZS_FMT_RGB565_BE ? 2u : 3u, x, y, bad;
    uint8_t *img, *copy, *patch;
    size_t bytes;

    assert_int_equal(pt_rig_open(&r, d, fmt, rot, async, 3, 0), ZS_PANEL_OK);
    r.panel.use_ramwrc = (uint8_t)ramwrc;
    w = r.panel.width;
    h = r.panel.height;
    bytes = (size_t)w * h * bpp;
    img = make_picture(w, h, fmt, 0);
    copy = malloc(bytes);
    assert_non_null(copy);
    memcpy(copy, img, bytes);
    send_full(&r, img, bytes, ramwrc ? (chunk / bpp) * bpp : chunk);
    /* const data: the caller's bytes are left alone (the SSD1351 at 18 bpp
     * converts a copy) */
    assert_memory_equal(img, copy, bytes);
    emu_flush(&r.emu);
    if (r.emu.errors != 0)
        pt_print_errors(&r.emu);
    assert_int_equal(r.emu.errors, 0);
    assert_int_equal(r.port.violations, 0);
    bad = pt_compare_view(&r.emu, rot, img, w, h, fmt);
    if (bad)
        print_message("    %s fmt %d rotation %u: %u pixels differ\n", d->name, (int)fmt, rot,
                      bad);
    assert_int_equal(bad, 0);

    /* A partial window: 7 x 5 pixels at (w/3, h/2) with a new picture. */
    {
        unsigned px = w / 3, py = h / 2, pw = 7, ph = 5;
        patch = malloc((size_t)pw * ph * bpp);
        assert_non_null(patch);
        for (y = 0; y < ph; y++)
            for (x = 0; x < pw; x++) {
                uint8_t *dst = img + ((size_t)(py + y) * w + px + x) * bpp;
                pt_pattern_pixel(x + 1000u, y + 77u, fmt, dst);
                memcpy(patch + ((size_t)y * pw + x) * bpp, dst, bpp);
            }
        assert_int_equal(zs_panel_window(&r.panel, (uint16_t)px, (uint16_t)py,
                                         (uint16_t)(px + pw), (uint16_t)(py + ph)),
                         ZS_PANEL_OK);
        assert_int_equal(zs_panel_write(&r.panel, patch, (size_t)pw * ph * bpp), ZS_PANEL_OK);
        zs_bus_wait(&r.port.bus);
        emu_flush(&r.emu);
        assert_int_equal(r.emu.errors, 0);
        assert_int_equal(pt_compare_view(&r.emu, rot, img, w, h, fmt), 0);
        free(patch);
    }
    free(img);
    free(copy);
    pt_rig_close(&r);
}

static void test_all_panels_formats_rotations(void **state)
{
    unsigned i, f, rot, cases = 0;
    (void)state;
    for (i = 0; i < zs_panel_count(); i++) {
        const zs_panel_desc *d = zs_panel_at(i);
        for (f = 0; f < 2; f++) {
            if (zs_panel_bytes_per_pixel(d, pt_formats[f]) == 0)
                continue;
            for (rot = 0; rot < 4; rot++) {
                run_case(d, pt_formats[f], rot, 0, 4096, 0);
                cases++;
            }
        }
    }
    print_message("    %u panel/format/rotation cases\n", cases);
    assert_int_equal(cases, 4u * (2u * 7u + 1u)); /* ILI9488: RGB666 only */
}

static void test_async_odd_chunks(void **state)
{
    unsigned i, rot;
    (void)state;
    for (i = 0; i < zs_panel_count(); i++) {
        const zs_panel_desc *d = zs_panel_at(i);
        zs_format fmt = zs_panel_bytes_per_pixel(d, ZS_FMT_RGB565_BE) ? ZS_FMT_RGB565_BE
                                                                         : ZS_FMT_RGB666;
        if (!zs_panel_bytes_per_pixel(d, fmt))
            continue; /* the 1-bit panels: test_panel_mono */
        for (rot = 0; rot < 4; rot++)
            run_case(d, fmt, rot, 1, 1001, 0); /* 1001: pixels cut across chunks */
    }
}

static void test_ramwrc_chunks(void **state)
{
    unsigned i, f;
    (void)state;
    for (i = 0; i < zs_panel_count(); i++) {
        const zs_panel_desc *d = zs_panel_at(i);
        if (d->ops != &zs_panel_ops_dcs)
            continue;
        for (f = 0; f < 2; f++)
            if (zs_panel_bytes_per_pixel(d, pt_formats[f]))
                run_case(d, pt_formats[f], i & 3u, 0, 960, 1);
    }
}

/* The emulator's module facts and the driver's tables describe the same
 * hardware; a mismatch in size would make every other test meaningless. */
static void test_tables_match_models(void **state)
{
    unsigned i, colour = 0;
    (void)state;
    for (i = 0; i < zs_panel_count(); i++)
        colour += zs_panel_bytes_per_pixel(zs_panel_at(i), ZS_FMT_RGB565_BE) ||
                  zs_panel_bytes_per_pixel(zs_panel_at(i), ZS_FMT_RGB666);
    assert_int_equal(colour, emu_model_count());
    for (i = 0; i < zs_panel_count(); i++) {
        const zs_panel_desc *d = zs_panel_at(i);
        const emu_model *m = emu_model_find(d->name);
        if (!m && d->formats == (1u << ZS_FMT_GRAY4)) { /* the SSD0323: emu_gray.c */
            assert_int_equal(d->width, EMU_GRAY_W);
            assert_int_equal(d->height, EMU_GRAY_H);
            assert_true(d->ram_width == 2 * EMU_GRAY_RAM_COLS && d->ram_height == EMU_GRAY_RAM_ROWS);
            assert_ptr_equal(zs_panel_find(d->name), d);
            continue;
        }
        if (!m && d->formats >> 8) { /* a 1-bit panel: its own emulator */
            const emu_mono_model *mm = emu_mono_model_find(d->name);
            assert_non_null(mm);
            assert_int_equal(d->width, mm->vis_w);
            assert_int_equal(d->height, mm->vis_h);
            assert_true(d->ram_width <= mm->ram_w && d->ram_height <= mm->ram_h);
            assert_ptr_equal(zs_panel_find(d->name), d);
            continue;
        }
        assert_non_null(m);
        assert_int_equal(d->width, m->vis_w);
        assert_int_equal(d->height, m->vis_h);
        assert_int_equal(d->ram_width, m->ram_w);
        assert_int_equal(d->ram_height, m->ram_h);
        assert_ptr_equal(zs_panel_find(d->name), d);
    }
    assert_null(zs_panel_find("no-such-panel"));
    assert_null(zs_panel_at(zs_panel_count()));
}

/* A wrong table (mirror bit missing, BGR missing, no inversion) must show up
 * as a wrong picture in the emulator: the check is not circular. */
static void test_wrong_table_is_visible(void **state)
{
    zs_panel_desc bad[3];
    unsigned k;
    (void)state;
    bad[0] = zs_panel_ili9341;
    bad[0].madctl = ZS_MADCTL_BGR; /* forgot MX */
    bad[1] = zs_panel_ili9341;
    bad[1].madctl = ZS_MADCTL_MX; /* forgot BGR */
    bad[2] = zs_panel_st7789_240x240;
    bad[2].invert = 0; /* forgot INVON on IPS glass */
    for (k = 0; k < 3; k++) {
        pt_rig r;
        unsigned w, h;
        uint8_t *img;
        assert_int_equal(pt_rig_open(&r, &bad[k], ZS_FMT_RGB565_BE, 0, 0, 0, 0), ZS_PANEL_OK);
        w = r.panel.width;
        h = r.panel.height;
        img = make_picture(w, h, ZS_FMT_RGB565_BE, 5);
        send_full(&r, img, (size_t)w * h * 2, 4096);
        assert_int_equal(r.emu.errors, 0);
        assert_true(pt_compare_view(&r.emu, 0, img, w, h, ZS_FMT_RGB565_BE) > w * h / 2);
        free(img);
        pt_rig_close(&r);
    }
}

static void test_driver_argument_checks(void **state)
{
    pt_rig r;
    uint8_t px[4] = {0};
    (void)state;
    assert_int_equal(pt_rig_open(&r, &zs_panel_ili9488, ZS_FMT_RGB565_BE, 0, 0, 0, 0),
                     ZS_PANEL_ERR_FORMAT);
    pt_rig_close(&r);
    assert_int_equal(pt_rig_open(&r, &zs_panel_st7789_240x240, ZS_FMT_GRAY8, 0, 0, 0, 0),
                     ZS_PANEL_ERR_FORMAT);
    pt_rig_close(&r);
    assert_int_equal(pt_rig_open(&r, &zs_panel_st7789_240x240, ZS_FMT_RGB565_BE, 4, 0, 0, 0),
                     ZS_PANEL_ERR_ROTATION);
    pt_rig_close(&r);
    assert_int_equal(pt_rig_open(&r, &zs_panel_st7789_135x240, ZS_FMT_RGB565_BE, 1, 0, 0, 0),
                     ZS_PANEL_OK);
    assert_int_equal(r.panel.width, 240);
    assert_int_equal(r.panel.height, 135);
    /* windows are half-open and must lie inside the visible area */
    assert_int_equal(zs_panel_window(&r.panel, 0, 0, 241, 1), ZS_PANEL_ERR_WINDOW);
    assert_int_equal(zs_panel_window(&r.panel, 0, 0, 240, 136), ZS_PANEL_ERR_WINDOW);
    assert_int_equal(zs_panel_window(&r.panel, 5, 0, 5, 1), ZS_PANEL_ERR_WINDOW);
    /* pixels need an open window, and no more than it holds */
    assert_int_equal(zs_panel_write(&r.panel, px, 2), ZS_PANEL_ERR_STATE);
    assert_int_equal(zs_panel_window(&r.panel, 239, 134, 240, 135), ZS_PANEL_OK);
    assert_int_equal(zs_panel_write(&r.panel, px, 4), ZS_PANEL_ERR_STATE);
    assert_int_equal(zs_panel_write(&r.panel, px, 2), ZS_PANEL_OK);
    assert_int_equal(zs_panel_write(&r.panel, px, 2), ZS_PANEL_ERR_STATE);
    assert_int_equal(zs_panel_init(NULL, &zs_panel_gc9a01, &r.port.bus, ZS_FMT_RGB565_BE, 0),
                     ZS_PANEL_ERR_NULL);
    assert_string_equal(zs_panel_strerror(ZS_PANEL_ERR_WINDOW),
                        "empty window or outside the visible area");
    emu_flush(&r.emu);
    assert_int_equal(r.emu.errors, 0);
    pt_rig_close(&r);
}

/* Rotation changes at run time: MADCTL is re-sent and the next frame fits. */
static void test_set_rotation_and_inversion(void **state)
{
    pt_rig r;
    unsigned rot;
    (void)state;
    assert_int_equal(pt_rig_open(&r, &zs_panel_st7789_135x240, ZS_FMT_RGB666, 0, 0, 0, 0),
                     ZS_PANEL_OK);
    for (rot = 0; rot < 4; rot++) {
        unsigned w, h;
        uint8_t *img, *copy;
        assert_int_equal(zs_panel_set_rotation(&r.panel, rot), ZS_PANEL_OK);
        w = r.panel.width;
        h = r.panel.height;
        img = make_picture(w, h, ZS_FMT_RGB666, rot);
        copy = malloc((size_t)w * h * 3);
        memcpy(copy, img, (size_t)w * h * 3);
        send_full(&r, img, (size_t)w * h * 3, 777);
        assert_memory_equal(img, copy, (size_t)w * h * 3);
        assert_int_equal(pt_compare_view(&r.emu, rot, img, w, h, ZS_FMT_RGB666), 0);
        /* user inversion: every channel complemented on the glass */
        assert_int_equal(zs_panel_set_inversion(&r.panel, 1), ZS_PANEL_OK);
        {
            uint32_t *v = malloc((size_t)w * h * sizeof *v);
            emu_view_666(&r.emu, rot, v);
            assert_int_equal(v[0] ^ 0x3FFFFu, pt_666(ZS_FMT_RGB666, img));
            free(v);
        }
        assert_int_equal(zs_panel_set_inversion(&r.panel, 0), ZS_PANEL_OK);
        free(img);
        free(copy);
    }
    assert_int_equal(zs_panel_set_rotation(&r.panel, 4), ZS_PANEL_ERR_ROTATION);
    assert_int_equal(zs_panel_display_on(&r.panel, 0), ZS_PANEL_OK);
    {
        uint32_t v[1];
        unsigned w, h;
        uint32_t *all;
        emu_view_size(&r.emu, 3, &w, &h);
        all = malloc((size_t)w * h * sizeof *all);
        emu_view_666(&r.emu, 3, all);
        v[0] = all[0];
        free(all);
        assert_int_equal(v[0], 0); /* display off: black */
    }
    emu_flush(&r.emu);
    assert_int_equal(r.emu.errors, 0);
    pt_rig_close(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tables_match_models),
        cmocka_unit_test(test_all_panels_formats_rotations),
        cmocka_unit_test(test_async_odd_chunks),
        cmocka_unit_test(test_ramwrc_chunks),
        cmocka_unit_test(test_wrong_table_is_visible),
        cmocka_unit_test(test_driver_argument_checks),
        cmocka_unit_test(test_set_rotation_and_inversion),
    };
    return cmocka_run_group_tests_name("panel_image", tests, NULL, NULL);
}
