/* SPDX-License-Identifier: MIT */
/* Regression tests for bugs found in review (each failed before its fix). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "../../src/zs_internal.h"

#define W 32
#define H 32

static uint8_t arena[ZS_ARENA_BYTES(W, H, 16, 16, 8)];

static void camera(zs_camera *cam)
{
    memset(cam, 0, sizeof *cam);
    assert_int_equal(zs_camera_look_at(cam, zs_vec3_make(0, 0, 0), zs_vec3_make(0, 0, -ZS_FX(1)),
                                       zs_vec3_make(0, ZS_FX(1), 0)),
                     ZS_OK);
    assert_int_equal(zs_camera_perspective(cam, ZS_FX(90), ZS_FX(1) / 10, ZS_FX(100)), ZS_OK);
}

/* One lit square facing the camera at z = -2, tilted so the light matters. */
static void draw_square(zs_renderer *r)
{
    static const int16_t pos[] = {-1, -1, -2, 1, -1, -3, 1, 1, -3, -1, 1, -2};
    static const uint16_t idx[] = {0, 1, 2, 0, 2, 3};
    zs_mesh m;
    memset(&m, 0, sizeof m);
    m.positions = pos;
    m.indices = idx;
    m.scale = ZS_FX(1);
    m.vertex_count = 4;
    m.triangle_count = 2;
    m.color = 0xC08040;
    assert_int_equal(zs_draw(r, &m, NULL), ZS_OK);
}

/* A refused zs_frame_shading must not change the lighting in force. */
static void test_refused_shading_keeps_lights(void **state)
{
    zs_renderer r;
    zs_config cfg = zs_config_default(W, H, 16, 16, 8);
    zs_camera cam;
    zs_shade_params good = zs_shade_default(), bad;
    uint8_t a[W * H * 3], b[W * H * 3];
    (void)state;
    camera(&cam);
    good.format = ZS_FMT_RGB888;
    good.ambient = ZS_FX(1) / 5;
    good.light_count = 1;
    good.lights[0].direction = zs_vec3_make(0, 0, ZS_FX(1));
    good.lights[0].intensity = ZS_FX(1);
    bad = good;
    bad.light_count = 2;
    bad.lights[0].direction = zs_vec3_make(ZS_FX(1), 0, 0); /* valid, then */
    bad.lights[1].direction = zs_vec3_make(0, 0, 0);        /* a zero direction */
    bad.lights[1].intensity = ZS_FX(1);

    assert_int_equal(zs_init(&r, arena, sizeof arena, &cfg), ZS_OK);
    assert_int_equal(zs_frame_begin(&r, &cam, ZS_MODE_SPAN), ZS_OK);
    assert_int_equal(zs_frame_shading(&r, &good), ZS_OK);
    draw_square(&r);
    assert_int_equal(zs_render_rows(&r, 0, H, a, W * 3), ZS_OK);

    assert_int_equal(zs_frame_begin(&r, &cam, ZS_MODE_SPAN), ZS_OK);
    assert_int_equal(zs_frame_shading(&r, &good), ZS_OK);
    assert_int_equal(zs_frame_shading(&r, &bad), ZS_ERR_ARGUMENT);
    draw_square(&r);
    assert_int_equal(zs_render_rows(&r, 0, H, b, W * 3), ZS_OK);
    assert_memory_equal(a, b, sizeof a);
}

/* With the active pools full, the triangle submitted last is the one lost. */
static void test_edge_pool_drops_the_last(void **state)
{
    /* two overlapping triangles with the same first row (y / z equal), the
     * second nearer */
    static const int16_t pos[] = {-60, 60, -100, -60, -60, -100, 60, -60, -100,
                                  -50, 54, -90,  -50, -54, -90,  70, -54, -90};
    static const uint16_t idx[] = {0, 1, 2, 3, 4, 5};
    zs_renderer r;
    zs_config cfg = zs_config_default(W, H, 16, 16, 2); /* room for one triangle */
    zs_camera cam;
    zs_shade_params sp = zs_shade_default();
    zs_mesh m;
    uint16_t ids[W * H];
    int count[3] = {0, 0, 0};
    size_t i;
    (void)state;
    camera(&cam);
    assert_int_equal(zs_init(&r, arena, sizeof arena, &cfg), ZS_OK);
    assert_int_equal(zs_frame_begin(&r, &cam, ZS_MODE_SPAN), ZS_OK);
    sp.format = ZS_FMT_ID16;
    assert_int_equal(zs_frame_shading(&r, &sp), ZS_OK);
    memset(&m, 0, sizeof m);
    m.positions = pos;
    m.indices = idx;
    m.scale = ZS_FX(1);
    m.scale = ZS_FX(1) / 10;
    m.vertex_count = 6;
    m.triangle_count = 2;
    assert_int_equal(zs_draw(&r, &m, NULL), ZS_OK);
    assert_int_equal(zs_render_rows(&r, 0, H, ids, W * 2), ZS_OK);
    for (i = 0; i < W * H; i++)
        if (ids[i] < 3)
            count[ids[i]]++;
    assert_int_equal(zs_frame_stats(&r)->records_skipped, 1);
    assert_true(count[1] > 0);
    assert_int_equal(count[2], 0);
}

/* A polygon that rounding makes non-convex must not overflow the clipper's
 * 9-vertex buffers (found by review; before the fix ASan reported index 9). */
static void test_clip_stays_in_bounds(void **state)
{
    zs_renderer r;
    zs_svert in[3], out[9];
    int n, k;
    (void)state;
    memset(&r, 0, sizeof r);
    r.priv.guard = 4;
    r.cam.near_z = 6553;
    r.cam.far_z = ZS_FX(100);
    in[0].xc = 34435837;
    in[0].yc = -36333234;
    in[0].w = 9083309;
    in[1].xc = -29618;
    in[1].yc = -26200;
    in[1].w = 6550;
    in[2].xc = 30265;
    in[2].yc = -26222;
    in[2].w = 6555;
    for (k = 0; k < 3; k++) {
        in[k].shade = 0;
        in[k].pool = ZS_NONE;
    }
    n = zs_clip_polygon(&r, in, 3, out);
    assert_true(n >= 0 && n <= 9);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_refused_shading_keeps_lights),
        cmocka_unit_test(test_edge_pool_drops_the_last),
        cmocka_unit_test(test_clip_stays_in_bounds),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
