/* SPDX-License-Identifier: MIT */
/* The emulated controllers catch protocol errors (each bad stream raises its
 * flag, a good one none) and honour the commands a driver relies on:
 * windows with wrap-around, RAMWRC, MADCTL, COLMOD, inversion, offsets. */
#include "ptest.h"

static emu_panel E;

static void open_model(const char *name)
{
    assert_int_equal(emu_init(&E, emu_model_find(name)), 0);
}

static void cmd(uint8_t c, int n, ...)
{
    uint8_t p[16];
    va_list ap;
    int i;
    va_start(ap, n);
    for (i = 0; i < n; i++)
        p[i] = (uint8_t)va_arg(ap, int);
    va_end(ap);
    emu_command(&E, c);
    if (n > 0)
        emu_data(&E, p, (size_t)n);
}

/* Reset, wake up and switch on a DCS controller the right way. */
static void dcs_wake(void)
{
    emu_reset_line(&E, 0);
    emu_delay_ms(&E, 10);
    emu_reset_line(&E, 1);
    emu_delay_ms(&E, 120);
    cmd(0x01, 0);
    emu_delay_ms(&E, 150);
    cmd(0x11, 0);
    emu_delay_ms(&E, 120);
    cmd(0x3A, 1, 0x55);
    cmd(0x36, 1, 0x00);
    cmd(0x29, 0);
}

static void expect_only(uint32_t bits)
{
    emu_flush(&E);
    if (E.errors != bits) {
        pt_print_errors(&E);
        print_message("    errors 0x%X, expected 0x%X\n", (unsigned)E.errors, (unsigned)bits);
    }
    assert_int_equal(E.errors, bits);
    emu_free(&E);
}

static const uint8_t two_px[4] = {0xF8, 0x00, 0x07, 0xE0};

static void test_good_stream_clean(void **state)
{
    (void)state;
    open_model("st7789-240x240");
    dcs_wake();
    cmd(0x2A, 4, 0, 0, 0, 239);
    cmd(0x2B, 4, 0, 0, 0, 239);
    cmd(0x2C, 0);
    emu_data(&E, two_px, 4);
    expect_only(0);
}

static void test_pixels_before_slpout(void **state)
{
    (void)state;
    open_model("st7789-240x240");
    cmd(0x01, 0);
    emu_delay_ms(&E, 150);
    cmd(0x3A, 1, 0x55);
    cmd(0x29, 0);
    cmd(0x2C, 0);
    emu_data(&E, two_px, 4);
    expect_only(EMU_E_SLEEP);
}

static void test_pixels_before_dispon(void **state)
{
    (void)state;
    open_model("ili9341");
    cmd(0x01, 0);
    emu_delay_ms(&E, 150);
    cmd(0x11, 0);
    emu_delay_ms(&E, 120);
    cmd(0x3A, 1, 0x55);
    cmd(0x2C, 0);
    emu_data(&E, two_px, 4);
    expect_only(EMU_E_DISPOFF);
}

static void test_window_outside_ram(void **state)
{
    (void)state;
    /* column 240 does not exist without MV */
    open_model("st7789-240x240");
    dcs_wake();
    cmd(0x2A, 4, 0, 0, 0, 240);
    cmd(0x2C, 0);
    emu_data(&E, two_px, 4);
    expect_only(EMU_E_WINDOW);
    /* start after end */
    open_model("st7789-240x240");
    dcs_wake();
    cmd(0x2B, 4, 0, 20, 0, 10);
    expect_only(EMU_E_WINDOW);
    /* with MV the column range is the RAM's 320 rows: 0..319 is fine ... */
    open_model("st7789-240x240");
    dcs_wake();
    cmd(0x36, 1, 0x20);
    cmd(0x2A, 4, 0, 0, 0x01, 0x3F);
    cmd(0x2B, 4, 0, 0, 0, 239);
    cmd(0x2C, 0);
    emu_data(&E, two_px, 4);
    expect_only(0);
    /* ... but rows 0..240 are not */
    open_model("st7789-240x240");
    dcs_wake();
    cmd(0x36, 1, 0x20);
    cmd(0x2B, 4, 0, 0, 0, 240);
    cmd(0x2C, 0);
    expect_only(EMU_E_WINDOW);
    /* SSD1351: 128 columns */
    open_model("ssd1351");
    cmd(0x15, 2, 0, 128);
    expect_only(EMU_E_WINDOW);
}

static void test_wrong_parameter_count(void **state)
{
    (void)state;
    open_model("st7789-240x240");
    dcs_wake();
    cmd(0x2A, 3, 0, 0, 0); /* one short */
    cmd(0x2B, 4, 0, 0, 0, 9);
    expect_only(EMU_E_PARAM_COUNT);
    open_model("st7789-240x240");
    dcs_wake();
    cmd(0x36, 2, 0x00, 0x00); /* one too many */
    expect_only(EMU_E_PARAM_COUNT);
    open_model("gc9a01");
    dcs_wake();
    cmd(0x29, 1, 0x00); /* DISPON takes none */
    expect_only(EMU_E_PARAM_COUNT);
    open_model("ssd1351");
    cmd(0xFD, 1, 0x12);
    cmd(0x75, 1, 0); /* row takes two */
    expect_only(EMU_E_PARAM_COUNT);
    /* a short command at the very end of the stream */
    open_model("ili9341");
    dcs_wake();
    cmd(0x3A, 0);
    expect_only(EMU_E_PARAM_COUNT);
}

static void test_bad_parameter_values(void **state)
{
    (void)state;
    open_model("ili9488");
    dcs_wake(); /* sends COLMOD 0x55: no 16 bpp over SPI */
    expect_only(EMU_E_PARAM_VALUE);
    open_model("st7789-240x240");
    dcs_wake();
    cmd(0x3A, 1, 0x77);
    expect_only(EMU_E_PARAM_VALUE);
    open_model("ssd1351");
    cmd(0xA0, 1, 0xC0); /* 262k format 2 */
    expect_only(EMU_E_PARAM_VALUE);
}

static void test_stray_data_and_partial_pixel(void **state)
{
    (void)state;
    open_model("st7789-240x240");
    emu_data(&E, two_px, 2); /* nothing asked for data */
    expect_only(EMU_E_STRAY_DATA);
    open_model("st7789-240x240");
    dcs_wake();
    cmd(0x2C, 0);
    emu_data(&E, two_px, 3); /* a pixel and a half */
    cmd(0x00, 0);
    expect_only(EMU_E_PARTIAL_PIXEL);
    open_model("st7789-240x240");
    dcs_wake();
    cmd(0x2C, 0);
    emu_data(&E, two_px, 3);
    expect_only(EMU_E_PARTIAL_PIXEL); /* at the end of the stream */
}

static void test_timing(void **state)
{
    (void)state;
    open_model("st7789-240x240");
    cmd(0x01, 0);
    emu_delay_ms(&E, 10);
    cmd(0x11, 0); /* needs 120 ms after SWRESET */
    expect_only(EMU_E_TIMING);
    open_model("st7789-240x240");
    cmd(0x01, 0);
    cmd(0x3A, 1, 0x55); /* needs 5 ms after SWRESET */
    expect_only(EMU_E_TIMING);
    open_model("st7735-128x160");
    cmd(0x01, 0);
    emu_delay_ms(&E, 150);
    cmd(0x11, 0);
    emu_delay_ms(&E, 2);
    cmd(0x29, 0); /* needs 5 ms after SLPOUT */
    expect_only(EMU_E_TIMING);
    open_model("ili9341");
    emu_reset_line(&E, 0);
    emu_reset_line(&E, 1);
    cmd(0x01, 0); /* needs 5 ms after the reset pulse */
    expect_only(EMU_E_TIMING);
}

static void test_reset_line_held(void **state)
{
    (void)state;
    open_model("gc9a01");
    emu_reset_line(&E, 0);
    cmd(0x01, 0);
    expect_only(EMU_E_IN_RESET);
}

static void test_ssd1351_locks_and_bits(void **state)
{
    static const uint8_t bad666[3] = {0xFC, 0x00, 0x00};
    (void)state;
    open_model("ssd1351");
    cmd(0xB3, 1, 0xF1); /* protected until 0xFD 0xB1 */
    expect_only(EMU_E_LOCKED);
    open_model("ssd1351");
    cmd(0xFD, 1, 0x16);
    cmd(0xAF, 0);
    expect_only(EMU_E_LOCKED);
    open_model("ssd1351");
    cmd(0xFD, 1, 0x12);
    cmd(0xFD, 1, 0xB1);
    cmd(0xB3, 1, 0xF1);
    cmd(0xA0, 1, 0xB4);
    cmd(0xAF, 0);
    cmd(0x5C, 0);
    emu_data(&E, bad666, 3); /* bits 7..2: the driver forgot to shift */
    expect_only(EMU_E_PIXEL_BITS);
}

/* Read back one RAM cell through the glass of an unrotated view. */
static uint32_t view_at(unsigned x, unsigned y)
{
    unsigned w, h;
    uint32_t *v, r;
    emu_view_size(&E, 0, &w, &h);
    v = malloc((size_t)w * h * sizeof *v);
    emu_view_666(&E, 0, v);
    r = v[(size_t)y * w + x];
    free(v);
    return r;
}

static void px565(unsigned r5, unsigned g6, unsigned b5, uint8_t out[2])
{
    unsigned v = r5 << 11 | g6 << 5 | b5;
    out[0] = (uint8_t)(v >> 8);
    out[1] = (uint8_t)v;
}

static void test_wraparound_and_ramwrc(void **state)
{
    uint8_t p[2 * 6];
    unsigned i;
    (void)state;
    open_model("st7789-240x320");
    dcs_wake();
    cmd(0x21, 0); /* IPS: INVON shows true colours */
    cmd(0x2A, 4, 0, 10, 0, 11);
    cmd(0x2B, 4, 0, 20, 0, 20); /* 2 pixels */
    cmd(0x2C, 0);
    for (i = 0; i < 3; i++)
        px565(i + 1, 0, 0, p + 2 * i);
    emu_data(&E, p, 6); /* the third pixel wraps onto the first */
    assert_int_equal(E.wraps, 1);
    assert_int_equal(view_at(10, 20), (uint32_t)((3u << 1) << 12));
    assert_int_equal(view_at(11, 20), (uint32_t)((2u << 1) << 12));
    /* RAMWRC continues where RAMWR stopped */
    cmd(0x00, 0);
    cmd(0x3C, 0);
    px565(9, 0, 0, p);
    emu_data(&E, p, 2);
    assert_int_equal(view_at(11, 20), (uint32_t)((9u << 1) << 12));
    /* COLMOD 18 bpp: 3 bytes, value in bits 7..2 */
    cmd(0x3A, 1, 0x66);
    cmd(0x2C, 0);
    p[0] = 0x84;
    p[1] = 0x48;
    p[2] = 0xFC;
    emu_data(&E, p, 3);
    assert_int_equal(view_at(10, 20), (uint32_t)(0x21u << 12 | 0x12u << 6 | 0x3Fu));
    expect_only(0);
}

static void test_madctl_and_offsets(void **state)
{
    uint8_t p[2];
    (void)state;
    /* MX|MY on the 240x240 ST7789: address (0, 80) is the glass's bottom
     * right pixel, since the glass shows RAM rows 0..239 */
    open_model("st7789-240x240");
    dcs_wake();
    cmd(0x21, 0);
    cmd(0x36, 1, 0xC0);
    cmd(0x2A, 4, 0, 0, 0, 0);
    cmd(0x2B, 4, 0, 80, 0, 80);
    cmd(0x2C, 0);
    px565(31, 0, 0, p);
    emu_data(&E, p, 2);
    assert_int_equal(view_at(239, 239), 0x3Fu << 12);
    /* MV: the column address runs down the glass */
    cmd(0x36, 1, 0x20);
    cmd(0x2A, 4, 0, 5, 0, 6);
    cmd(0x2B, 4, 0, 9, 0, 9);
    cmd(0x2C, 0);
    px565(0, 63, 0, p);
    emu_data(&E, p, 2);
    emu_data(&E, p, 2);
    assert_int_equal(view_at(9, 5), 0x3Fu << 6);
    assert_int_equal(view_at(9, 6), 0x3Fu << 6);
    /* BGR bit on an RGB glass swaps red and blue */
    cmd(0x36, 1, 0x08);
    assert_int_equal(view_at(239, 239), 0x3Fu);
    /* INVOFF on IPS glass: inverted colours */
    cmd(0x36, 1, 0x00);
    cmd(0x20, 0);
    assert_int_equal(view_at(239, 239), 0x3Fu << 12 ^ 0x3FFFFu);
    /* display off: black */
    cmd(0x28, 0);
    assert_int_equal(view_at(239, 239), 0);
    expect_only(0);
    /* The 135x240 glass starts at RAM column 52, row 40. */
    open_model("st7789-135x240");
    dcs_wake();
    cmd(0x21, 0);
    cmd(0x2A, 4, 0, 52, 0, 52);
    cmd(0x2B, 4, 0, 40, 0, 40);
    cmd(0x2C, 0);
    px565(0, 0, 31, p);
    emu_data(&E, p, 2);
    assert_int_equal(view_at(0, 0), 0x3Fu);
    expect_only(0);
}

static void test_png_output(void **state)
{
    uint8_t *rgb = NULL;
    unsigned w = 0, h = 0;
    const char *path = "build/tests/panel/protocol_png.png";
    uint8_t p[2];
    (void)state;
    open_model("st7735-128x160");
    dcs_wake();
    cmd(0x36, 1, 0xC0); /* upright on this module */
    cmd(0x2A, 4, 0, 2, 0, 2);
    cmd(0x2B, 4, 0, 1, 0, 1);
    cmd(0x2C, 0);
    px565(31, 63, 31, p);
    emu_data(&E, p, 2);
    assert_int_equal(emu_write_png(&E, 1, path), 0);
    assert_int_equal(emu_png_read_rgb(path, &rgb, &w, &h), 0);
    assert_int_equal(w, 160); /* rotation 1: landscape */
    assert_int_equal(h, 128);
    /* the glass's top-left pixel is the bottom-left one of a picture turned
     * 90 degrees clockwise onto it */
    assert_int_equal(rgb[(127 * w + 0) * 3 + 0], 255);
    assert_int_equal(rgb[(127 * w + 0) * 3 + 1], 255);
    assert_int_equal(rgb[(0 * w + 0) * 3 + 1] == 255 && rgb[(0 * w + 0) * 3 + 0] == 255, 0);
    free(rgb);
    expect_only(0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_good_stream_clean),
        cmocka_unit_test(test_pixels_before_slpout),
        cmocka_unit_test(test_pixels_before_dispon),
        cmocka_unit_test(test_window_outside_ram),
        cmocka_unit_test(test_wrong_parameter_count),
        cmocka_unit_test(test_bad_parameter_values),
        cmocka_unit_test(test_stray_data_and_partial_pixel),
        cmocka_unit_test(test_timing),
        cmocka_unit_test(test_reset_line_held),
        cmocka_unit_test(test_ssd1351_locks_and_bits),
        cmocka_unit_test(test_wraparound_and_ramwrc),
        cmocka_unit_test(test_madctl_and_offsets),
        cmocka_unit_test(test_png_output),
    };
    return cmocka_run_group_tests_name("panel_protocol", tests, NULL, NULL);
}
