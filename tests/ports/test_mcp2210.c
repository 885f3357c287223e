/* SPDX-License-Identifier: MIT */
/*
 * The MCP2210 port against the chip model, in process (the zs_hid_ops seam
 * instead of hidapi; test_mcp2210_vm runs the same code over the real
 * hidapi -> hidraw -> uhid path). The panel behind the model is host_sim's
 * emulated ST7789: what it shows must equal the rendered frame.
 */
#define _GNU_SOURCE
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "demo_scene.h"
#include "mcp2210_model.h"
#include "ports_common.h"
#include "zs_app.h"
#include "zs_mcp2210.h"
#include "zspan/panel.h"

#define PANEL "st7789-240x240"
#define W 240
#define H 240

typedef struct rig {
    emu_panel emu;
    mcp_model model;
    zs_mcp2210 m;
    uint8_t answer[64];
    int have_answer;
    long answers_left;     /* -1: always answer; else answer this many, then go silent */
    uint64_t max_chunk;    /* largest data count in a 0x42 report */
} rig;

static int t_write(void *h, const uint8_t report[64])
{
    rig *r = h;
    if (r->model.gone)
        return -1;
    if (report[0] == 0x42 && report[1] > r->max_chunk)
        r->max_chunk = report[1];
    r->have_answer = mcp_model_handle(&r->model, report, r->answer);
    return r->model.gone ? -1 : 0;
}

static int t_read(void *h, uint8_t report[64], int timeout_ms)
{
    rig *r = h;
    (void)timeout_ms;
    if (r->model.gone)
        return -1;
    if (!r->have_answer)
        return 0;
    if (r->answers_left == 0)
        return 0; /* silent: a timeout */
    if (r->answers_left > 0)
        r->answers_left--;
    memcpy(report, r->answer, 64);
    r->have_answer = 0;
    return 64;
}

static const char *t_error(void *h)
{
    (void)h;
    return "the model went away";
}

static const zs_hid_ops t_ops = {t_write, t_read, t_error, NULL};

static rig *rig_new(void)
{
    rig *r = calloc(1, sizeof *r);
    zs_mcp2210_cfg c = zs_mcp2210_cfg_default();
    assert_non_null(r);
    assert_int_equal(emu_init(&r->emu, emu_model_find(PANEL)), 0);
    mcp_model_init(&r->model, &r->emu, c.cs_pin, c.dc_pin, c.reset_pin, c.backlight_pin);
    r->answers_left = -1;
    return r;
}

static int rig_open(rig *r, unsigned busy_retries)
{
    zs_mcp2210_cfg c = zs_mcp2210_cfg_default();
    c.timeout_ms = 50;
    if (busy_retries)
        c.busy_retries = busy_retries;
    return zs_mcp2210_init(&r->m, &t_ops, r, &c);
}

static void rig_free(rig *r)
{
    emu_free(&r->emu);
    free(r);
}

/* Panel init + demo frame `frame` streamed in bands of `band` rows. */
static zs_panel_status send_frame(rig *r, uint32_t frame, int band)
{
    static demo_scene scene;
    static int ready;
    zs_panel lcd;
    zs_renderer rd;
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
    ps = zs_panel_init(&lcd, zs_panel_find(PANEL), &r->m.bus, ZS_FMT_RGB565_BE, 0);
    if (ps != ZS_PANEL_OK)
        return ps;
    cfg = zs_config_default(W, H, (uint16_t)max_tris, (uint16_t)(max_tris * 3u),
                            ZS_MAX_ACTIVE_EDGES);
    arena_size = zs_arena_bytes(&cfg);
    arena = malloc(arena_size);
    buf = malloc(band_bytes);
    assert_non_null(arena);
    assert_non_null(buf);
    assert_int_equal(zs_init(&rd, arena, arena_size, &cfg), ZS_OK);
    assert_int_equal(demo_frame(&rd, &scene, frame, ZS_MODE_SPAN, ZS_SHADE_GOURAUD,
                                ZS_FMT_RGB565_BE),
                     ZS_OK);
    ps = zs_panel_stream(&lcd, &rd, buf, NULL, band_bytes, band, NULL, &fs);
    free(arena);
    free(buf);
    return ps;
}

static void expect_picture(rig *r, uint32_t frame)
{
    uint32_t *want = ports_demo_666(W, H, frame);
    assert_non_null(want);
    emu_flush(&r->emu);
    if (r->model.errors)
        print_message("    model: %u protocol errors, first: %s\n", r->model.errors,
                      r->model.first_error);
    if (r->emu.errors)
        print_message("    panel: errors 0x%X, log: %s\n", (unsigned)r->emu.errors,
                      r->emu.log_lines ? r->emu.log[0] : "");
    assert_int_equal(r->model.errors, 0);
    assert_int_equal(r->emu.errors, 0);
    assert_int_equal(ports_view_diff(&r->emu, want, W, H), 0);
    free(want);
}

static void test_full_frame(void **state)
{
    rig *r = rig_new();
    (void)state;
    assert_int_equal(rig_open(r, 0), 0);
    assert_int_equal(send_frame(r, 0, 16), ZS_PANEL_OK);
    expect_picture(r, 0);
    /* Every SPI byte the port counted reached the panel, in reports of at most 60. */
    assert_true(r->max_chunk <= 60);
    assert_int_equal(r->m.st.spi_bytes, r->model.bytes_to_panel);
    assert_true(r->model.bytes_to_panel >= (uint64_t)W * H * 2u);
    assert_int_equal(r->m.st.busy, 0);
    print_message("    full frame: %llu reports, %llu SPI bytes, %llu transactions, %llu settings, "
                  "%llu GPIO\n",
                  (unsigned long long)r->m.st.reports, (unsigned long long)r->m.st.spi_bytes,
                  (unsigned long long)r->m.st.transactions, (unsigned long long)r->m.st.settings,
                  (unsigned long long)r->m.st.gpio);
    rig_free(r);
}

/* Busy answers to data reports (in bursts) and an engine that keeps shifting
 * after the last bytes: everything resent, D/C never changes inside a
 * transaction (the model counts that as an error), the picture is exact. */
static void test_busy_and_lag(void **state)
{
    rig *r = rig_new();
    (void)state;
    r->model.busy_every = 7;
    r->model.busy_burst = 3;
    r->model.lag = 2;
    assert_int_equal(rig_open(r, 0), 0);
    assert_int_equal(send_frame(r, 5, 8), ZS_PANEL_OK);
    expect_picture(r, 5);
    assert_true(r->model.busy_sent > 100);
    assert_int_equal(r->m.st.busy, r->model.busy_sent + r->model.poll_busy_sent);
    print_message("    %llu busy answers to data, %llu to end-of-transfer polls: all resent\n",
                  (unsigned long long)r->model.busy_sent,
                  (unsigned long long)r->model.poll_busy_sent);
    rig_free(r);
}

static void test_disconnect_mid_frame(void **state)
{
    rig *r = rig_new();
    (void)state;
    r->model.disconnect_after = 900; /* about half the frame */
    assert_int_equal(rig_open(r, 0), 0);
    assert_int_equal(send_frame(r, 0, 16), ZS_PANEL_ERR_IO);
    assert_int_equal(r->m.error, ZS_MCP2210_E_GONE);
    assert_non_null(strstr(r->m.err, "disconnected"));
    print_message("    error: %s\n", r->m.err);
    /* Sticky: nothing more goes out. */
    {
        uint64_t reports = r->m.st.reports;
        uint8_t b = 0;
        assert_int_not_equal(zs_mcp2210_spi(&r->m, &b, 1), 0);
        assert_int_equal(r->m.st.reports, reports);
    }
    rig_free(r);
}

static void test_timeout(void **state)
{
    rig *r = rig_new();
    (void)state;
    assert_int_equal(rig_open(r, 0), 0);
    r->answers_left = 300;
    assert_int_equal(send_frame(r, 0, 16), ZS_PANEL_ERR_IO);
    assert_int_equal(r->m.error, ZS_MCP2210_E_TIMEOUT);
    print_message("    error: %s\n", r->m.err);
    rig_free(r);
}

static void test_busy_forever(void **state)
{
    rig *r = rig_new();
    (void)state;
    assert_int_equal(rig_open(r, 40), 0);
    r->model.busy_every = 10;
    r->model.busy_burst = 1000000;
    assert_int_equal(send_frame(r, 0, 16), ZS_PANEL_ERR_IO);
    assert_int_equal(r->m.error, ZS_MCP2210_E_BUSY);
    print_message("    error: %s\n", r->m.err);
    rig_free(r);
}

static void test_external_master(void **state)
{
    rig *r = rig_new();
    (void)state;
    assert_int_equal(rig_open(r, 0), 0);
    r->model.bus_na = 1;
    assert_int_equal(send_frame(r, 0, 16), ZS_PANEL_ERR_IO);
    assert_int_equal(r->m.error, ZS_MCP2210_E_BUS_NA);
    rig_free(r);
}

static void test_bad_pins(void **state)
{
    zs_mcp2210 m;
    zs_mcp2210_cfg c = zs_mcp2210_cfg_default();
    (void)state;
    c.dc_pin = c.cs_pin;
    assert_int_not_equal(zs_mcp2210_init(&m, &t_ops, NULL, &c), 0);
    assert_int_equal(m.error, ZS_MCP2210_E_ARG);
    c = zs_mcp2210_cfg_default();
    c.reset_pin = 9;
    assert_int_not_equal(zs_mcp2210_init(&m, &t_ops, NULL, &c), 0);
}

/* The program's frame loop with --partial: frame 0 whole, frame 1 only the
 * rows that changed; the panel then shows frame 1 exactly. */
static void test_partial_updates(void **state)
{
    rig *r = rig_new();
    zs_app_opts o;
    zs_app_port ap;
    uint64_t bytes_full;
    (void)state;
    assert_int_equal(rig_open(r, 0), 0);
    zs_app_defaults(&o, 1);
    o.frames = 1;
    o.quiet = 1;
    memset(&ap, 0, sizeof ap);
    ap.name = "model";
    ap.clock_hz = 12000000u;
    assert_int_equal(zs_app_run(&o, &r->m.bus, &ap, "test"), 0);
    bytes_full = r->model.bytes_to_panel;
    /* Again, two frames, partial: the second sends less than a full frame. */
    r->model.bytes_to_panel = 0;
    o.frames = 2;
    o.partial = 1;
    o.spin = 3.0;
    assert_int_equal(zs_app_run(&o, &r->m.bus, &ap, "test"), 0);
    expect_picture(r, 1);
    print_message("    full frame %llu bytes; init + frame 0 + partial frame 1: %llu bytes\n",
                  (unsigned long long)bytes_full, (unsigned long long)r->model.bytes_to_panel);
    assert_true(r->model.bytes_to_panel < 2u * bytes_full);
    /* An unchanged frame sends no pixels at all. */
    r->model.bytes_to_panel = 0;
    o.spin = 0.0;
    assert_int_equal(zs_app_run(&o, &r->m.bus, &ap, "test"), 0);
    expect_picture(r, 0);
    zs_app_free(&o);
    rig_free(r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_full_frame),
        cmocka_unit_test(test_busy_and_lag),
        cmocka_unit_test(test_disconnect_mid_frame),
        cmocka_unit_test(test_timeout),
        cmocka_unit_test(test_busy_forever),
        cmocka_unit_test(test_external_master),
        cmocka_unit_test(test_bad_pins),
        cmocka_unit_test(test_partial_updates),
    };
    return cmocka_run_group_tests_name("mcp2210 port (chip model, in process)", tests, NULL, NULL);
}
