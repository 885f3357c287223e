/* SPDX-License-Identifier: MIT */
/* Config flags that leave features out to save RAM: the arena shrinks by
 * the documented amounts, the features left out are refused with
 * ZS_ERR_MODE, and what remains renders exactly as the full renderer does. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "zspan/zspan.h"

#define W 96
#define H 72

static const int16_t cube_pos[] = {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1,
                                   -1, -1, 1,  1, -1, 1,  1, 1, 1,  -1, 1, 1};
static const uint16_t cube_idx[] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                    3, 7, 6, 3, 6, 2, 0, 4, 7, 0, 7, 3, 1, 2, 6, 1, 6, 5};
static const zs_color cube_col[] = {0xff0000, 0xff0000, 0x00ff00, 0x00ff00, 0x0000ff, 0x0000ff,
                                    0xffff00, 0xffff00, 0xff00ff, 0xff00ff, 0x00ffff, 0x00ffff};

/* Renders two interpenetrating lit cubes, flat shaded, in mode; returns the
 * status of the first failing call. */
static zs_status render(uint16_t flags, zs_visibility mode, zs_shading shading, int fog,
                        uint8_t *img)
{
    const zs_config base = zs_config_default(W, H, 64, 64, 64);
    zs_config cfg = base;
    size_t need;
    void *arena;
    zs_renderer r;
    zs_camera cam;
    zs_shade_params sp = zs_shade_default();
    zs_mesh m;
    zs_status st;
    int k;
    cfg.flags = flags;
    need = zs_arena_bytes(&cfg);
    arena = malloc(need);
    assert_non_null(arena);
    assert_int_equal(zs_init(&r, arena, need, &cfg), ZS_OK);
    memset(&cam, 0, sizeof cam);
    assert_int_equal(zs_camera_look_at(&cam, zs_vec3_make(ZS_FX(2), ZS_FX(2), ZS_FX(4)),
                                       zs_vec3_make(0, 0, 0), zs_vec3_make(0, ZS_FX(1), 0)),
                     ZS_OK);
    assert_int_equal(zs_camera_perspective(&cam, ZS_FX(50), ZS_FX(1) / 4, ZS_FX(50)), ZS_OK);
    st = zs_frame_begin(&r, &cam, mode);
    if (st == ZS_OK) {
        sp.format = ZS_FMT_RGB888;
        sp.shading = shading;
        sp.ambient = ZS_FX(1) / 3;
        sp.light_count = 1;
        sp.lights[0].direction = zs_vec3_make(ZS_FX(1), ZS_FX(2), ZS_FX(3));
        sp.lights[0].intensity = ZS_FX(1);
        if (fog) {
            sp.fog.enabled = 1;
            sp.fog.start = ZS_FX(5);
            sp.fog.end = ZS_FX(9);
            sp.fog.color = 0x808080;
        }
        st = zs_frame_shading(&r, &sp);
    }
    memset(&m, 0, sizeof m);
    m.positions = cube_pos;
    m.indices = cube_idx;
    m.face_colors = cube_col;
    m.scale = ZS_FX(1);
    m.vertex_count = 8;
    m.triangle_count = 12;
    for (k = 0; k < 2 && st == ZS_OK; k++) {
        zs_mat34 rot = zs_mat34_rotate_y(ZS_FX(25 * k + 10));
        zs_mat34 t = zs_mat34_translate(ZS_FX(k) / 2, ZS_FX(k) / 3, 0);
        zs_mat34 model = zs_mat34_mul(&t, &rot);
        st = zs_draw(&r, &m, &model);
    }
    if (st == ZS_OK)
        st = zs_render_rows(&r, 0, H, img, W * 3);
    free(arena);
    return st;
}

static void test_arena_sizes(void **state)
{
    zs_config c = zs_config_default(240, 240, 1000, 800, 256);
    size_t full, flat, span_only, lean, prio;
    (void)state;
    full = zs_arena_bytes(&c);
    c.flags = ZS_CFG_FLAT_ONLY;
    flat = zs_arena_bytes(&c);
    c.flags = ZS_CFG_NO_ZLINE;
    span_only = zs_arena_bytes(&c);
    c.flags = ZS_CFG_FLAT_ONLY | ZS_CFG_NO_ZLINE;
    lean = zs_arena_bytes(&c);
    assert_int_equal(full, ZS_ARENA_BYTES(240, 240, 1000, 800, 256));
    assert_int_equal(lean, ZS_ARENA_BYTES_CFG(240, 240, 1000, 800, 256,
                                              ZS_CFG_FLAT_ONLY | ZS_CFG_NO_ZLINE));
    /* shade words (4 B per vertex) and colour planes (36 B per triangle slot) */
    assert_int_equal(full - flat, 800 * 4 + 128 * 36);
    /* sort keys (8 B) and owners (2 B) a column, and the owners' sentinel
     * (2 B, rounded to 8) */
    assert_int_equal(full - span_only, 240 * 10 + 8);
    assert_int_equal(full - lean, 800 * 4 + 128 * 36 + 240 * 10 + 8);
    /* priority alone: no depth plane (24 B per triangle slot) */
    c.flags = ZS_CFG_PRIORITY_ONLY;
    prio = zs_arena_bytes(&c);
    assert_int_equal(full - prio, 128 * 24);
    assert_int_equal(prio, ZS_ARENA_BYTES_CFG(240, 240, 1000, 800, 256, ZS_CFG_PRIORITY_ONLY));
    c.flags = 0x100; /* no such flag */
    assert_int_equal(zs_arena_bytes(&c), 0);
    c.flags = ZS_CFG_PRIORITY_ONLY | ZS_CFG_ABUFFER; /* the resolve decides by depth */
    assert_int_equal(zs_arena_bytes(&c), 0);
    printf("test_config_flags: arena 240x240/1000/800/256 full %zu, flat-only %zu, span-only %zu, "
           "lean %zu, priority-only %zu bytes\n",
           full, flat, span_only, lean, prio);
}

static void test_refusals(void **state)
{
    uint8_t *img = malloc(W * H * 3);
    (void)state;
    assert_int_equal(render(ZS_CFG_NO_ZLINE, ZS_MODE_ZLINE, ZS_SHADE_FLAT, 0, img), ZS_ERR_MODE);
    assert_int_equal(render(ZS_CFG_FLAT_ONLY, ZS_MODE_SPAN, ZS_SHADE_GOURAUD, 0, img),
                     ZS_ERR_MODE);
    assert_int_equal(render(ZS_CFG_FLAT_ONLY, ZS_MODE_SPAN, ZS_SHADE_FLAT, 1, img), ZS_ERR_MODE);
    assert_int_equal(render(ZS_CFG_FLAT_ONLY, ZS_MODE_ZLINE, ZS_SHADE_FLAT, 0, img), ZS_OK);
    /* priority alone keeps no depth plane for the other modes */
    assert_int_equal(render(ZS_CFG_PRIORITY_ONLY, ZS_MODE_SPAN, ZS_SHADE_FLAT, 0, img), ZS_ERR_MODE);
    assert_int_equal(render(ZS_CFG_PRIORITY_ONLY, ZS_MODE_ZLINE, ZS_SHADE_FLAT, 0, img),
                     ZS_ERR_MODE);
    assert_int_equal(render(ZS_CFG_PRIORITY_ONLY, ZS_MODE_WARNOCK, ZS_SHADE_FLAT, 0, img),
                     ZS_ERR_MODE);
    free(img);
}

static void test_lean_equals_full(void **state)
{
    uint8_t *full = malloc(W * H * 3), *lean = malloc(W * H * 3);
    size_t covered = 0, i;
    (void)state;
    memset(full, 0x11, W * H * 3);
    memset(lean, 0x22, W * H * 3);
    assert_int_equal(render(0, ZS_MODE_ZLINE, ZS_SHADE_FLAT, 0, full), ZS_OK);
    assert_int_equal(render(ZS_CFG_FLAT_ONLY | ZS_CFG_NO_ZLINE, ZS_MODE_SPAN, ZS_SHADE_FLAT, 0,
                            lean),
                     ZS_OK);
    assert_memory_equal(full, lean, W * H * 3);
    for (i = 0; i < W * H; i++)
        covered += (full[3 * i] | full[3 * i + 1] | full[3 * i + 2]) != 0;
    assert_true(covered > W * H / 8); /* the cubes are really there */
    printf("test_config_flags: lean == full on %zu covered pixels\n", covered);
    free(full);
    free(lean);
}

/* Priority mode decides by record order alone: without depth planes
 * (ZS_CFG_PRIORITY_ONLY, with or without the other savings) it gives the
 * full renderer's priority image, Gouraud and fog included. */
static void test_priority_only_equals_full(void **state)
{
    static const uint16_t lean_flags[] = {ZS_CFG_PRIORITY_ONLY,
                                          ZS_CFG_PRIORITY_ONLY | ZS_CFG_NO_ZLINE,
                                          ZS_CFG_PRIORITY_ONLY | ZS_CFG_FLAT_ONLY};
    uint8_t *full = malloc(W * H * 3), *lean = malloc(W * H * 3);
    int k, shading;
    (void)state;
    for (shading = 0; shading < 2; shading++) {
        zs_shading sh = shading ? ZS_SHADE_GOURAUD : ZS_SHADE_FLAT;
        memset(full, 0x11, W * H * 3);
        assert_int_equal(render(0, ZS_MODE_PRIORITY, sh, shading, full), ZS_OK);
        for (k = 0; k < 3; k++) {
            if (shading && (lean_flags[k] & ZS_CFG_FLAT_ONLY))
                continue; /* Gouraud and fog are refused there */
            memset(lean, 0x22, W * H * 3);
            assert_int_equal(render(lean_flags[k], ZS_MODE_PRIORITY, sh, shading, lean), ZS_OK);
            assert_memory_equal(full, lean, W * H * 3);
        }
    }
    free(full);
    free(lean);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_arena_sizes),
        cmocka_unit_test(test_refusals),
        cmocka_unit_test(test_lean_equals_full),
        cmocka_unit_test(test_priority_only_equals_full),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
