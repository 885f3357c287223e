/* SPDX-License-Identifier: MIT */
/* The bytes each driver puts on the wire, checked against the controllers'
 * datasheet values: command bytes, parameter counts, COLMOD and MADCTL
 * values, big-endian inclusive window coordinates with the module's RAM
 * offsets, SSD1351 unlock and remap values. */
#include "ptest.h"

/* Datasheet parameter counts of every command a controller's driver sends
 * (min..max: DCS controllers accept a command cut short after the
 * parameters that matter). */
typedef struct count_rule {
    uint8_t cmd, min, max;
} count_rule;

static const count_rule st7789_counts[] = {
    {0x01, 0, 0}, {0x11, 0, 0}, {0x13, 0, 0}, {0x20, 0, 0}, {0x21, 0, 0}, {0x29, 0, 0},
    {0x2A, 4, 4}, {0x2B, 4, 4}, {0x2C, 0, 0}, {0x36, 1, 1}, {0x3A, 1, 1}, {0xB2, 5, 5},
    {0xB7, 1, 1}, {0xBB, 1, 1}, {0xC0, 1, 1}, {0xC2, 1, 2}, {0xC3, 1, 1}, {0xC4, 1, 1},
    {0xC6, 1, 1}, {0xD0, 2, 2}, {0xE0, 14, 14}, {0xE1, 14, 14}, {0, 0xFF, 0xFF}};
static const count_rule ili9341_counts[] = {
    {0x01, 0, 0}, {0x11, 0, 0}, {0x13, 0, 0}, {0x20, 0, 0}, {0x29, 0, 0}, {0x2A, 4, 4},
    {0x2B, 4, 4}, {0x2C, 0, 0}, {0x36, 1, 1}, {0x3A, 1, 1}, {0x26, 1, 1}, {0xB1, 2, 2},
    {0xB6, 3, 4}, {0xC0, 1, 1}, {0xC1, 1, 1}, {0xC5, 2, 2}, {0xC7, 1, 1}, {0xCB, 5, 5},
    {0xCF, 3, 3}, {0xE0, 15, 15}, {0xE1, 15, 15}, {0xE8, 3, 3}, {0xEA, 2, 2}, {0xED, 4, 4},
    {0xF2, 1, 1}, {0xF7, 1, 1}, {0, 0xFF, 0xFF}};
static const count_rule st7735_counts[] = {
    {0x01, 0, 0}, {0x11, 0, 0}, {0x13, 0, 0}, {0x20, 0, 0}, {0x29, 0, 0}, {0x2A, 4, 4},
    {0x2B, 4, 4}, {0x2C, 0, 0}, {0x36, 1, 1}, {0x3A, 1, 1}, {0xB1, 3, 3}, {0xB2, 3, 3},
    {0xB3, 6, 6}, {0xB4, 1, 1}, {0xC0, 3, 3}, {0xC1, 1, 1}, {0xC2, 2, 2}, {0xC3, 2, 2},
    {0xC4, 2, 2}, {0xC5, 1, 1}, {0xE0, 16, 16}, {0xE1, 16, 16}, {0, 0xFF, 0xFF}};
static const count_rule gc9a01_counts[] = {
    {0x01, 0, 0}, {0x11, 0, 0}, {0x13, 0, 0}, {0x21, 0, 0}, {0x29, 0, 0}, {0x2A, 4, 4},
    {0x2B, 4, 4}, {0x2C, 0, 0}, {0x36, 1, 1}, {0x3A, 1, 1}, {0xFE, 0, 0}, {0xEF, 0, 0},
    {0xB6, 2, 2}, {0xC3, 1, 1}, {0xC4, 1, 1}, {0xC9, 1, 1}, {0xF0, 6, 6}, {0xF1, 6, 6},
    {0xF2, 6, 6}, {0xF3, 6, 6}, {0, 0xFF, 0xFF}};
static const count_rule ili9488_counts[] = {
    {0x01, 0, 0}, {0x11, 0, 0}, {0x13, 0, 0}, {0x20, 0, 0}, {0x29, 0, 0}, {0x2A, 4, 4},
    {0x2B, 4, 4}, {0x2C, 0, 0}, {0x36, 1, 1}, {0x3A, 1, 1}, {0xB0, 1, 1}, {0xB1, 1, 2},
    {0xB4, 1, 1}, {0xB6, 3, 3}, {0xC0, 2, 2}, {0xC1, 1, 1}, {0xC5, 3, 4}, {0xE0, 15, 15},
    {0xE1, 15, 15}, {0xE9, 1, 1}, {0xF7, 4, 4}, {0, 0xFF, 0xFF}};
static const count_rule ssd1351_counts[] = {
    {0xFD, 1, 1}, {0xAE, 0, 0}, {0xAF, 0, 0}, {0xA0, 1, 1}, {0xA1, 1, 1}, {0xA2, 1, 1},
    {0xA6, 0, 0}, {0xAB, 1, 1}, {0xB1, 1, 1}, {0xB3, 1, 1}, {0xB4, 3, 3}, {0xB5, 1, 1},
    {0xB6, 1, 1}, {0xBE, 1, 1}, {0xC1, 3, 3}, {0xC7, 1, 1}, {0xCA, 1, 1}, {0x15, 2, 2},
    {0x75, 2, 2}, {0x5C, 0, 0}, {0, 0xFF, 0xFF}};

static const count_rule *rules_for(const char *name)
{
    if (strncmp(name, "st7789", 6) == 0) return st7789_counts;
    if (strcmp(name, "ili9341") == 0) return ili9341_counts;
    if (strncmp(name, "st7735", 6) == 0) return st7735_counts;
    if (strcmp(name, "gc9a01") == 0) return gc9a01_counts;
    if (strcmp(name, "ili9488") == 0) return ili9488_counts;
    return ssd1351_counts;
}

/* A recorded command with its parameters. */
typedef struct rec_cmd {
    uint8_t cmd;
    uint8_t n;
    uint8_t p[64];
    uint32_t data; /* pixel bytes that followed */
} rec_cmd;

static size_t collect(const emu_panel *e, rec_cmd *out, size_t max)
{
    size_t i, k = 0;
    for (i = 0; i < e->nev; i++) {
        const emu_event *ev = &e->ev[i];
        if (ev->kind == 'C') {
            assert_true(k < max);
            memset(&out[k], 0, sizeof out[k]);
            out[k++].cmd = ev->byte;
        } else if (ev->kind == 'P') {
            assert_true(k > 0);
            if (out[k - 1].n < 64)
                out[k - 1].p[out[k - 1].n] = ev->byte;
            out[k - 1].n++;
        } else {
            assert_true(k > 0);
            out[k - 1].data += ev->n;
        }
    }
    return k;
}

static const rec_cmd *find_last(const rec_cmd *c, size_t n, uint8_t cmd)
{
    const rec_cmd *hit = NULL;
    size_t i;
    for (i = 0; i < n; i++)
        if (c[i].cmd == cmd)
            hit = &c[i];
    return hit;
}

static void check_counts(const char *name, const rec_cmd *c, size_t n)
{
    const count_rule *rules = rules_for(name);
    size_t i;
    for (i = 0; i < n; i++) {
        const count_rule *r = rules;
        while (!(r->min == 0xFF && r->max == 0xFF) && r->cmd != c[i].cmd)
            r++;
        if (r->min == 0xFF) {
            print_message("    %s: command 0x%02X not in the datasheet table\n", name, c[i].cmd);
            fail();
        }
        if (c[i].n < r->min || c[i].n > r->max) {
            print_message("    %s: command 0x%02X has %u parameters, datasheet %u..%u\n", name,
                          c[i].cmd, c[i].n, r->min, r->max);
            fail();
        }
    }
}

/* Inits a panel with recording on, opens a full window, sends one frame. */
static size_t record_panel(const zs_panel_desc *d, zs_format fmt, unsigned rot, rec_cmd *cmds,
                           size_t max, pt_rig *r)
{
    const emu_model *m = emu_model_find(d->name);
    size_t bytes;
    uint8_t *buf;
    assert_int_equal(emu_init(&r->emu, m), 0);
    emu_record(&r->emu, 1);
    assert_int_equal(emu_port_init(&r->port, &r->emu, 0, 0, 0), 0);
    assert_int_equal(zs_panel_init(&r->panel, d, &r->port.bus, fmt, rot), ZS_PANEL_OK);
    bytes = (size_t)r->panel.width * r->panel.height * zs_panel_bytes_per_pixel(d, fmt);
    buf = calloc(1, bytes);
    assert_int_equal(zs_panel_window(&r->panel, 0, 0, r->panel.width, r->panel.height),
                     ZS_PANEL_OK);
    assert_int_equal(zs_panel_write(&r->panel, buf, bytes), ZS_PANEL_OK);
    free(buf);
    emu_flush(&r->emu);
    if (r->emu.errors)
        pt_print_errors(&r->emu);
    assert_int_equal(r->emu.errors, 0);
    return collect(&r->emu, cmds, max);
}

static rec_cmd cmds[512];

static void test_dcs_init_sequences(void **state)
{
    /* name, COLMOD 16/18 bpp, MADCTL for rotations 0..3, INVON? */
    static const struct {
        const char *name;
        uint8_t colmod565, colmod666;
        uint8_t madctl[4];
        uint8_t invon;
    } want[] = {
        {"st7789-240x240", 0x55, 0x66, {0x00, 0x60, 0xC0, 0xA0}, 1},
        {"st7789-240x320", 0x55, 0x66, {0x00, 0x60, 0xC0, 0xA0}, 1},
        {"st7789-135x240", 0x55, 0x66, {0x00, 0x60, 0xC0, 0xA0}, 1},
        {"ili9341", 0x55, 0x66, {0x48, 0x28, 0x88, 0xE8}, 0},
        {"st7735-128x160", 0x05, 0x06, {0xC0, 0xA0, 0x00, 0x60}, 0},
        {"gc9a01", 0x05, 0x06, {0x08, 0x68, 0xC8, 0xA8}, 1},
        {"ili9488", 0x00, 0x66, {0x48, 0x28, 0x88, 0xE8}, 0},
    };
    unsigned i, rot, f;
    (void)state;
    for (i = 0; i < sizeof want / sizeof want[0]; i++) {
        const zs_panel_desc *d = zs_panel_find(want[i].name);
        assert_non_null(d);
        for (f = 0; f < 2; f++) {
            uint8_t colmod = f == 0 ? want[i].colmod565 : want[i].colmod666;
            if (colmod == 0)
                continue;
            for (rot = 0; rot < 4; rot++) {
                pt_rig r;
                size_t n = record_panel(d, pt_formats[f], rot, cmds, 512, &r), k;
                const rec_cmd *c;
                assert_true(n > 8);
                /* SWRESET first, RAMWR with the frame last */
                assert_int_equal(cmds[0].cmd, ZS_DCS_SWRESET);
                assert_int_equal(cmds[n - 1].cmd, ZS_DCS_RAMWR);
                assert_int_equal(cmds[n - 1].data,
                                 (uint32_t)d->width * d->height * (f == 0 ? 2u : 3u));
                c = find_last(cmds, n, ZS_DCS_COLMOD);
                assert_non_null(c);
                assert_int_equal(c->p[0], colmod);
                c = find_last(cmds, n, ZS_DCS_MADCTL);
                assert_non_null(c);
                assert_int_equal(c->p[0], want[i].madctl[rot]);
                assert_int_equal(zs_panel_madctl_for(d, rot), want[i].madctl[rot]);
                assert_non_null(find_last(cmds, n, want[i].invon ? 0x21 : 0x20));
                assert_null(find_last(cmds, n, want[i].invon ? 0x20 : 0x21));
                assert_non_null(find_last(cmds, n, ZS_DCS_SLPOUT));
                assert_non_null(find_last(cmds, n, ZS_DCS_NORON));
                /* DISPON comes after SLPOUT, COLMOD and MADCTL */
                for (k = 0; k < n && cmds[k].cmd != ZS_DCS_DISPON; k++)
                    ;
                assert_true(k < n);
                assert_true(find_last(cmds, k, ZS_DCS_SLPOUT) != NULL);
                assert_true(find_last(cmds, k, ZS_DCS_COLMOD) != NULL);
                assert_true(find_last(cmds, k, ZS_DCS_MADCTL) != NULL);
                check_counts(d->name, cmds, n);
                /* SWRESET -> SLPOUT >= 120 ms, SLPOUT -> next >= 5 ms: the
                 * emulator's clock saw no timing error */
                assert_int_equal(r.emu.errors & EMU_E_TIMING, 0);
                pt_rig_close(&r);
            }
        }
    }
}

/* Full-screen windows: CASET/RASET big-endian, inclusive, with offsets. */
static void test_dcs_windows_and_offsets(void **state)
{
    static const struct {
        const char *name;
        unsigned rot;
        uint16_t xs, xe, ys, ye;
    } want[] = {
        {"st7789-240x240", 0, 0, 239, 0, 239},
        {"st7789-240x240", 1, 0, 239, 0, 239},
        {"st7789-240x240", 2, 0, 239, 80, 319}, /* MY: rows 80..319 */
        {"st7789-240x240", 3, 80, 319, 0, 239}, /* MY|MV: columns 80..319 */
        {"st7789-240x320", 1, 0, 319, 0, 239},
        {"st7789-135x240", 0, 52, 186, 40, 279},
        {"st7789-135x240", 1, 40, 279, 53, 187},
        {"st7789-135x240", 2, 53, 187, 40, 279},
        {"st7789-135x240", 3, 40, 279, 52, 186},
        {"ili9341", 0, 0, 239, 0, 319},
        {"ili9341", 1, 0, 319, 0, 239},
        {"st7735-128x160", 0, 2, 129, 1, 160},
        {"st7735-128x160", 1, 1, 160, 2, 129},
        {"st7735-128x160", 2, 2, 129, 1, 160},
        {"gc9a01", 2, 0, 239, 0, 239},
        {"ili9488", 1, 0, 479, 0, 319},
    };
    unsigned i;
    (void)state;
    for (i = 0; i < sizeof want / sizeof want[0]; i++) {
        const zs_panel_desc *d = zs_panel_find(want[i].name);
        zs_format fmt = zs_panel_bytes_per_pixel(d, ZS_FMT_RGB565_BE) ? ZS_FMT_RGB565_BE
                                                                         : ZS_FMT_RGB666;
        pt_rig r;
        size_t n = record_panel(d, fmt, want[i].rot, cmds, 512, &r);
        const rec_cmd *ca = &cmds[n - 3], *ra = &cmds[n - 2];
        assert_int_equal(ca->cmd, ZS_DCS_CASET);
        assert_int_equal(ra->cmd, ZS_DCS_RASET);
        assert_int_equal(ca->n, 4);
        assert_int_equal(ra->n, 4);
        if (ca->p[0] != (want[i].xs >> 8) || ca->p[1] != (want[i].xs & 0xFF) ||
            ca->p[2] != (want[i].xe >> 8) || ca->p[3] != (want[i].xe & 0xFF) ||
            ra->p[0] != (want[i].ys >> 8) || ra->p[1] != (want[i].ys & 0xFF) ||
            ra->p[2] != (want[i].ye >> 8) || ra->p[3] != (want[i].ye & 0xFF)) {
            print_message("    %s rotation %u: CASET %02X %02X %02X %02X RASET %02X %02X %02X "
                          "%02X\n",
                          want[i].name, want[i].rot, ca->p[0], ca->p[1], ca->p[2], ca->p[3],
                          ra->p[0], ra->p[1], ra->p[2], ra->p[3]);
            fail();
        }
        pt_rig_close(&r);
    }
}

/* A partial window [10, 20) x [5, 8): inclusive ends on the wire. */
static void test_partial_window_bytes(void **state)
{
    pt_rig r;
    size_t n;
    uint8_t px[30 * 2] = {0};
    (void)state;
    n = record_panel(&zs_panel_st7789_240x240, ZS_FMT_RGB565_BE, 2, cmds, 512, &r);
    (void)n;
    emu_record(&r.emu, 1);
    assert_int_equal(zs_panel_window(&r.panel, 10, 5, 20, 8), ZS_PANEL_OK);
    assert_int_equal(zs_panel_write(&r.panel, px, sizeof px), ZS_PANEL_OK);
    n = collect(&r.emu, cmds, 512);
    assert_int_equal(n, 3);
    {
        /* rotation 2 (MX|MY): x offset 240-240-0 = 0, y offset 320-240-0 = 80 */
        static const uint8_t caset[4] = {0x00, 10, 0x00, 19};
        static const uint8_t raset[4] = {0x00, 85, 0x00, 87};
        assert_int_equal(cmds[0].cmd, 0x2A);
        assert_memory_equal(cmds[0].p, caset, 4);
        assert_int_equal(cmds[1].cmd, 0x2B);
        assert_memory_equal(cmds[1].p, raset, 4);
        assert_int_equal(cmds[2].cmd, 0x2C);
        assert_int_equal(cmds[2].data, 60);
    }
    pt_rig_close(&r);
}

static void test_ssd1351_sequence(void **state)
{
    static const uint8_t remap565[4] = {0x74, 0x77, 0x66, 0x65};
    static const uint8_t remap666[4] = {0xB4, 0xB7, 0xA6, 0xA5};
    unsigned rot, f;
    (void)state;
    for (f = 0; f < 2; f++)
        for (rot = 0; rot < 4; rot++) {
            pt_rig r;
            size_t n = record_panel(&zs_panel_ssd1351, pt_formats[f], rot, cmds, 512, &r), k;
            const rec_cmd *c;
            /* unlock first: 0xFD 0x12, then 0xFD 0xB1 before any protected command */
            assert_int_equal(cmds[0].cmd, 0xFD);
            assert_int_equal(cmds[0].p[0], 0x12);
            assert_int_equal(cmds[1].cmd, 0xFD);
            assert_int_equal(cmds[1].p[0], 0xB1);
            assert_int_equal(cmds[2].cmd, 0xAE);
            c = find_last(cmds, n, 0xA0);
            assert_non_null(c);
            assert_int_equal(c->p[0], f == 0 ? remap565[rot] : remap666[rot]);
            c = find_last(cmds, n, 0xCA);
            assert_non_null(c);
            assert_int_equal(c->p[0], 127); /* 128 multiplexed rows */
            for (k = 0; k < n && cmds[k].cmd != 0xAF; k++)
                ;
            assert_true(k < n);
            assert_true(find_last(cmds, k, 0xA0) != NULL);
            assert_int_equal(cmds[n - 3].cmd, 0x15);
            assert_int_equal(cmds[n - 3].p[0], 0);
            assert_int_equal(cmds[n - 3].p[1], 127);
            assert_int_equal(cmds[n - 2].cmd, 0x75);
            assert_int_equal(cmds[n - 2].p[0], 0);
            assert_int_equal(cmds[n - 2].p[1], 127);
            assert_int_equal(cmds[n - 1].cmd, 0x5C);
            assert_int_equal(cmds[n - 1].data, 128u * 128u * (f == 0 ? 2u : 3u));
            check_counts("ssd1351", cmds, n);
            pt_rig_close(&r);
        }
}

/* SSD1351 with vertical increment (rotations 1, 3): the column register gets
 * the panel's row range and the row register the panel's column range. */
static void test_ssd1351_rotated_window(void **state)
{
    pt_rig r;
    size_t n;
    uint8_t px[2 * 6 * 3] = {0};
    (void)state;
    n = record_panel(&zs_panel_ssd1351, ZS_FMT_RGB565_BE, 1, cmds, 512, &r);
    (void)n;
    emu_record(&r.emu, 1);
    assert_int_equal(zs_panel_window(&r.panel, 10, 20, 16, 23), ZS_PANEL_OK);
    assert_int_equal(zs_panel_write(&r.panel, px, 2 * 6 * 3), ZS_PANEL_OK);
    n = collect(&r.emu, cmds, 512);
    assert_int_equal(n, 3);
    assert_int_equal(cmds[0].cmd, 0x15);
    assert_int_equal(cmds[0].p[0], 20);
    assert_int_equal(cmds[0].p[1], 22);
    assert_int_equal(cmds[1].cmd, 0x75);
    assert_int_equal(cmds[1].p[0], 10);
    assert_int_equal(cmds[1].p[1], 15);
    pt_rig_close(&r);
}

/* Delays: the init runs the datasheet waits through the bus's delay hook. */
static void test_init_delays(void **state)
{
    pt_rig r;
    (void)state;
    assert_int_equal(pt_rig_open(&r, &zs_panel_st7789_240x240, ZS_FMT_RGB565_BE, 0, 0, 0, 0),
                     ZS_PANEL_OK);
    /* reset pulse + 120 ms, SWRESET 150 ms, SLPOUT 120 ms, NORON, DISPON */
    assert_true(r.port.bus.count.delay_ms >= 120u + 150u + 120u);
    assert_true(r.emu.seen_hwreset);
    assert_int_equal(r.emu.errors, 0);
    pt_rig_close(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_dcs_init_sequences),
        cmocka_unit_test(test_dcs_windows_and_offsets),
        cmocka_unit_test(test_partial_window_bytes),
        cmocka_unit_test(test_ssd1351_sequence),
        cmocka_unit_test(test_ssd1351_rotated_window),
        cmocka_unit_test(test_init_delays),
    };
    return cmocka_run_group_tests_name("panel_datasheet", tests, NULL, NULL);
}
