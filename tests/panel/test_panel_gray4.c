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
#include "pcore.h"
#include "zspan/panel.h"


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
    pc_core c;
    pc_core_open(&c, 128, 64, 0x303030);
    pc_scene s;
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
        pc_make_scene(&s, 1000u + k);
        pc_reference(&c, &s, ZS_FMT_GRAY4, mono, 128, 64, want);
        pc_frame(&c, &s, ZS_FMT_GRAY4, mono);
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
    pc_core_close(&c);
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
    pc_core c;
    pc_core_open(&c, 96, 16, 0x303030);
    pc_scene s;
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
        pc_make_scene(&s, 2000u + k);
        pc_reference(&c, &s, ZS_FMT_MONO_PAGE, mono, 96, 16, want);
        pc_frame(&c, &s, ZS_FMT_MONO_PAGE, mono);
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
    pc_core_close(&c);
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
