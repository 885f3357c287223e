/* SPDX-License-Identifier: MIT */
/*
 * The application layer (app/): option parsing, renderer sizing, the panel
 * programs' command-line driver and the demo scene's frame steps. Built
 * without mesh loading (ZS_APP_NO_MESH); meshes are tested through
 * zspan-sim and zspan-meshc.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "zs_app.h"
#include "zs_arena.h"
#include "zs_opts.h"
#include "zs_scene.h"

#define PROG "test_app"

static void test_value_forms(void **state)
{
    char *argv[] = {"prog", "--out", "a.png", "--out=b.png", "--outx", "--out"};
    const char *v = NULL;
    int i = 1;
    (void)state;
    assert_int_equal(zs_opt_value(6, argv, &i, "--out", &v, PROG), 1);
    assert_string_equal(v, "a.png");
    assert_int_equal(i, 2);
    i = 3;
    assert_int_equal(zs_opt_value(6, argv, &i, "--out", &v, PROG), 1);
    assert_string_equal(v, "b.png");
    assert_int_equal(i, 3);
    i = 4;
    assert_int_equal(zs_opt_value(6, argv, &i, "--out", &v, PROG), 0);
    i = 5; /* the value is missing */
    assert_int_equal(zs_opt_value(6, argv, &i, "--out", &v, PROG), -1);
}

static void test_numbers(void **state)
{
    long n = 0;
    double d[3];
    int w, h;
    (void)state;
    assert_int_equal(zs_opt_long(PROG, "--n", "42", 0, 100, &n), 0);
    assert_int_equal(n, 42);
    assert_int_equal(zs_opt_long(PROG, "--n", "0x1F", 0, 100, &n), 0);
    assert_int_equal(n, 31);
    assert_int_equal(zs_opt_long(PROG, "--n", "010", 0, 100, &n), 0); /* not octal */
    assert_int_equal(n, 10);
    assert_int_equal(zs_opt_long(PROG, "--n", "-3", -5, 5, &n), 0);
    assert_int_equal(n, -3);
    assert_int_equal(zs_opt_long(PROG, "--n", "101", 0, 100, &n), -1);
    assert_int_equal(zs_opt_long(PROG, "--n", "4x", 0, 100, &n), -1);
    assert_int_equal(zs_opt_long(PROG, "--n", "", 0, 100, &n), -1);
    assert_int_equal(n, -3); /* untouched by failures */
    assert_int_equal(zs_opt_doubles(PROG, "--eye", "1,-2.5,3e1", d, 3), 0);
    assert_true(d[0] == 1.0 && d[1] == -2.5 && d[2] == 30.0);
    assert_int_equal(zs_opt_doubles(PROG, "--eye", "1,2", d, 3), -1);
    assert_int_equal(zs_opt_doubles(PROG, "--eye", "1,2,3,4", d, 3), -1);
    assert_int_equal(zs_opt_double(PROG, "--fov", "inf", d), -1);
    assert_int_equal(zs_opt_size(PROG, "--size", "320x240", &w, &h), 0);
    assert_true(w == 320 && h == 240);
    assert_int_equal(zs_opt_size(PROG, "--size", "0x240", &w, &h), -1);
    assert_int_equal(zs_opt_size(PROG, "--size", "320", &w, &h), -1);
}

static void test_words_and_colours(void **state)
{
    zs_visibility mode = ZS_MODE_SPAN;
    zs_shading shade = ZS_SHADE_FLAT;
    zs_format fmt = ZS_FMT_RGB565_BE;
    zs_color c = 0;
    zs_fixed f = 0;
    (void)state;
    assert_int_equal(zs_opt_mode(PROG, "zline", &mode), 0);
    assert_int_equal(mode, ZS_MODE_ZLINE);
    assert_int_equal(zs_opt_mode(PROG, "spam", &mode), -1);
    assert_int_equal(mode, ZS_MODE_ZLINE);
    assert_int_equal(zs_opt_shade(PROG, "gouraud", &shade), 0);
    assert_int_equal(shade, ZS_SHADE_GOURAUD);
    assert_int_equal(zs_opt_wire_format(PROG, "rgb666", &fmt), 0);
    assert_int_equal(fmt, ZS_FMT_RGB666);
    assert_int_equal(zs_opt_color(PROG, "--bg", "#10Ab3c", &c), 0);
    assert_int_equal(c, 0x10AB3C);
    assert_int_equal(zs_opt_color(PROG, "--bg", "10AB3", &c), -1);
    assert_int_equal(zs_opt_fixed(PROG, "--near", 0.5, &f), 0);
    assert_int_equal(f, 32768);
    assert_int_equal(zs_opt_fixed(PROG, "--near", 40000.0, &f), -1);
}

static void test_sizing(void **state)
{
    zs_config c;
    zs_renderer r;
    size_t bytes;
    void *arena;
    (void)state;
    c = zs_app_config(240, 135, 100, 0, 0);
    assert_int_equal(c.width, 240);
    assert_int_equal(c.height, 135);
    assert_int_equal(c.max_triangles, 100);
    assert_int_equal(c.max_vertices, 300);
    assert_int_equal(c.max_active_edges, ZS_MAX_ACTIVE_EDGES);
    c = zs_app_config(240, 240, 1000000ul, 0, 64);
    assert_int_equal(c.max_triangles, ZS_MAX_TRIANGLES);
    assert_int_equal(c.max_vertices, ZS_MAX_VERTICES);
    assert_int_equal(c.max_active_edges, 64);
    c = zs_app_config(240, 240, 10, 7, 0);
    assert_int_equal(c.max_vertices, 7);
    arena = zs_app_renderer(&r, &c, &bytes, PROG);
    assert_non_null(arena);
    assert_int_equal(bytes, zs_arena_bytes(&c));
    free(arena);
    c.width = 0; /* invalid: no arena, a message */
    assert_null(zs_app_renderer(&r, &c, &bytes, PROG));
}

/* ---- the panel programs' command line ------------------------------------------ */

static int usage_calls;
static void fake_usage(FILE *f)
{
    (void)f;
    usage_calls++;
}

static int fake_option(void *cfg, int argc, char **argv, int *i)
{
    return zs_opt_long_at(argc, argv, i, "--dc", 0, 99, cfg, PROG);
}

static int parse(int argc, char **argv, zs_app_opts *o, long *dc)
{
    zs_app_cli cli;
    cli.prog = PROG;
    cli.usage = fake_usage;
    cli.option = fake_option;
    cli.cfg = dc;
    cli.defaults = NULL;
    return zs_app_parse(o, argc, argv, &cli);
}

static void test_command_line(void **state)
{
    char *ok[] = {"p", "--panel=ili9341", "--dc", "7", "--mesh", "a.obj", "--mesh", "b.obj",
                  "--partial", "--frames", "0", "--mode", "zline", "--spin", "-6"};
    char *help[] = {"p", "--dc", "1", "-h", "--bogus"};
    char *bad_port[] = {"p", "--dc", "100"};
    char *unknown[] = {"p", "--bogus"};
    char *list[] = {"p", "--list"};
    zs_app_opts o;
    long dc = -1;
    (void)state;
    assert_int_equal(parse(15, ok, &o, &dc), ZS_APP_PARSED);
    assert_string_equal(o.panel, "ili9341");
    assert_int_equal(dc, 7);
    assert_int_equal(o.nmeshes, 2);
    assert_string_equal(o.meshes[1], "b.obj");
    assert_true(o.partial && o.frames == 0 && o.mode == ZS_MODE_ZLINE && o.spin == -6.0);
    assert_int_equal(o.band, 16); /* defaults stay */
    zs_app_free(&o);
    assert_int_equal(parse(5, help, &o, &dc), 0);
    assert_int_equal(usage_calls, 1);
    assert_null(o.meshes);
    assert_int_equal(parse(3, bad_port, &o, &dc), 2);
    assert_int_equal(parse(2, unknown, &o, &dc), 2);
    assert_int_equal(parse(2, list, &o, &dc), 0);
    /* the 1-bit options: a 1-bit panel's wire format is 1-bit pages, and
     * what needs the other kind is refused before any device is opened */
    {
        char *mono[] = {"p", "--panel", "ssd1306-128x64", "--lines"};
        char *mono_colour[] = {"p", "--panel", "ili9341", "--diffuse"};
        char *mono_partial[] = {"p", "--panel", "sh1106-132x64", "--partial"};
        assert_int_equal(parse(4, mono, &o, &dc), ZS_APP_PARSED);
        assert_int_equal(o.mono, ZS_MONO_LINES);
        assert_int_equal(zs_app_wire_format(&o, zs_panel_find(o.panel)), ZS_FMT_MONO_PAGE);
        zs_app_free(&o);
        assert_int_equal(parse(4, mono_colour, &o, &dc), 2);
        assert_int_equal(parse(4, mono_partial, &o, &dc), 2);
    }
}

/* ---- the demo scene's frames ------------------------------------------------------ */

static uint32_t frame_hash(zs_renderer *r, const zs_scene *s, long start, long k, double spin)
{
    static uint8_t rows[64 * 48 * 2];
    uint32_t h = 2166136261u;
    size_t i;
    assert_int_equal(zs_scene_frame(r, s, start, k, spin, ZS_MODE_SPAN, ZS_SHADE_GOURAUD,
                                    ZS_FMT_RGB565_BE),
                     ZS_OK);
    assert_int_equal(zs_render_rows(r, 0, 48, rows, 64 * 2), ZS_OK);
    for (i = 0; i < sizeof rows; i++)
        h = (h ^ rows[i]) * 16777619u;
    return h;
}

static void test_demo_steps(void **state)
{
    zs_scene s;
    zs_renderer r;
    zs_config c;
    size_t bytes;
    void *arena;
    (void)state;
    assert_int_equal(zs_scene_load(&s, NULL, 0, ZS_SHADE_GOURAUD, PROG), 0);
    assert_non_null(s.demo);
    c = zs_app_config(64, 48, s.max_tris, 0, 0);
    arena = zs_app_renderer(&r, &c, &bytes, PROG);
    assert_non_null(arena);
    /* spin 6: two demo frames a step; spin 1: one; spin 0: a still image */
    assert_int_equal(frame_hash(&r, &s, 0, 2, 6.0), frame_hash(&r, &s, 4, 0, 0.0));
    assert_int_equal(frame_hash(&r, &s, 3, 2, 1.0), frame_hash(&r, &s, 5, 0, 3.0));
    assert_int_equal(frame_hash(&r, &s, 1, 9, 0.0), frame_hash(&r, &s, 1, 0, 0.0));
    assert_int_not_equal(frame_hash(&r, &s, 0, 1, 3.0), frame_hash(&r, &s, 0, 0, 3.0));
    /* no mesh loading in this build */
    {
        const char *files[] = {"a.obj"};
        zs_scene m;
        assert_int_equal(zs_scene_load(&m, files, 1, ZS_SHADE_FLAT, PROG), -1);
        zs_scene_free(&m);
    }
    free(arena);
    zs_scene_free(&s);
}

/* --seq patterns: exactly one integer conversion; the name has the number. */
static void test_seq_patterns(void **state)
{
    static const char *const bad[] = {"%s.png", "f.png", "f_%d%d", "%ld", "%n", "%5$d", "%*d",
                                      "%.*d", "%#d", "%x", "%1234d", "f_%", "%%", "%c"};
    char buf[64];
    size_t k;
    (void)state;
    for (k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        if (zs_opt_seq_pattern(PROG, "--seq", bad[k]) != -1)
            fail_msg("'%s' accepted", bad[k]);
        assert_int_equal(zs_opt_seq_path(buf, sizeof buf, bad[k], 7), -1);
    }
    assert_int_equal(zs_opt_seq_pattern(PROG, "--seq", "out/f_%03d.png"), 0);
    assert_int_equal(zs_opt_seq_path(buf, sizeof buf, "out/f_%03d.png", 7), 0);
    assert_string_equal(buf, "out/f_007.png");
    assert_int_equal(zs_opt_seq_path(buf, sizeof buf, "a%%b_%-4u|", 42), 0);
    assert_string_equal(buf, "a%b_42  |");
    assert_int_equal(zs_opt_seq_path(buf, sizeof buf, "%+.3i%%", 5), 0);
    assert_string_equal(buf, "+005%");
    /* Too long for the buffer: refused, not cut. */
    assert_int_equal(zs_opt_seq_path(buf, 8, "abcdef_%d", 123), -1);
    assert_int_equal(zs_opt_seq_path(buf, 10, "abcdef_%d", 12), 0);
    assert_string_equal(buf, "abcdef_12");
}

/* --version, up axes, and the panel options checked before a device opens. */
static void test_version_axis_check(void **state)
{
    zs_app_opts o;
    int up = -1;
    (void)state;
    assert_int_equal(zs_opt_version("--version", PROG), 1);
    assert_int_equal(zs_opt_version("--versio", PROG), 0);
    assert_int_equal(zs_opt_up_axis(PROG, "--up-axis", "z", &up), 0);
    assert_int_equal(up, 3);
    assert_int_equal(zs_opt_up_axis(PROG, "--up-axis", "-y", &up), 0);
    assert_int_equal(up, 5);
    assert_int_equal(zs_opt_up_axis(PROG, "--up-axis", "+x", &up), 0);
    assert_int_equal(up, 1);
    assert_int_equal(zs_opt_up_axis(PROG, "--up-axis", "w", &up), -1);
    assert_int_equal(up, 1);
    zs_app_defaults(&o, 1);
    assert_int_equal(zs_app_check(&o, PROG), 0);
    o.panel = "nosuch";
    assert_int_equal(zs_app_check(&o, PROG), -1);
    o.panel = "ili9488";
    o.format = ZS_FMT_RGB565_BE; /* ili9488 takes only RGB666 over SPI */
    o.format_set = 1;
    assert_int_equal(zs_app_check(&o, PROG), -1);
    o.format_set = 0;
    assert_int_equal(zs_app_check(&o, PROG), 0);
    zs_app_free(&o);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_value_forms),     cmocka_unit_test(test_numbers),
        cmocka_unit_test(test_words_and_colours), cmocka_unit_test(test_sizing),
        cmocka_unit_test(test_command_line),    cmocka_unit_test(test_demo_steps),
        cmocka_unit_test(test_seq_patterns),    cmocka_unit_test(test_version_axis_check),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
