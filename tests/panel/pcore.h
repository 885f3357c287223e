/* SPDX-License-Identifier: MIT */
/* The core's side of the 1-bit and grey panel suites (test_panel_mono,
 * test_panel_gray4; header only): a random lit scene, a renderer for it and
 * the core's own picture, one value a pixel, to compare the emulated glass
 * with. */
#ifndef ZSPAN_TESTS_PANEL_PCORE_H
#define ZSPAN_TESTS_PANEL_PCORE_H

#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "zspan/panel.h"
#include "zspan/zspan.h"

/* 30 triangles over the screen, in front of the camera at depths 2..6,
 * vertex colours. */
typedef struct pc_scene {
    int16_t pos[3 * 90];
    uint16_t idx[3 * 30];
    zs_color vcol[90];
    zs_mesh mesh;
} pc_scene;

static inline uint32_t pc_rng(uint32_t *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s >> 8;
}

static inline void pc_make_scene(pc_scene *s, uint32_t seed)
{
    int i;
    for (i = 0; i < 90; i++) {
        int cx = (int)(pc_rng(&seed) % 4000) - 2000, cy = (int)(pc_rng(&seed) % 4000) - 2000;
        s->pos[3 * i] = (int16_t)(cx + (int)(pc_rng(&seed) % 2400) - 1200);
        s->pos[3 * i + 1] = (int16_t)(cy + (int)(pc_rng(&seed) % 2400) - 1200);
        s->pos[3 * i + 2] = (int16_t)(-2000 - (int)(pc_rng(&seed) % 4000));
        s->vcol[i] = pc_rng(&seed) & 0xFFFFFFu;
    }
    for (i = 0; i < 30; i++) {
        /* counter-clockwise seen from the camera: order by the sign of the area */
        int a = 3 * i, b = 3 * i + 1, c = 3 * i + 2;
        double x0 = s->pos[3 * a] / (double)-s->pos[3 * a + 2];
        double y0 = s->pos[3 * a + 1] / (double)-s->pos[3 * a + 2];
        double x1 = s->pos[3 * b] / (double)-s->pos[3 * b + 2];
        double y1 = s->pos[3 * b + 1] / (double)-s->pos[3 * b + 2];
        double x2 = s->pos[3 * c] / (double)-s->pos[3 * c + 2];
        double y2 = s->pos[3 * c + 1] / (double)-s->pos[3 * c + 2];
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

/* A w x h renderer with the 1-bit stages (ZS_CFG_MONO | ZS_CFG_LINES) whose
 * frames have the given background. */
typedef struct pc_core {
    zs_renderer r;
    uint8_t *arena;
    zs_color background;
} pc_core;

static inline void pc_core_open(pc_core *c, unsigned w, unsigned h, zs_color background)
{
    zs_config cfg = zs_config_default((uint16_t)w, (uint16_t)h, 200, 200, 200);
    cfg.flags = ZS_CFG_MONO | ZS_CFG_LINES;
    size_t n = zs_arena_bytes(&cfg);
    c->arena = malloc(n);
    c->background = background;
    assert_int_equal(zs_init(&c->r, c->arena, n, &cfg), ZS_OK);
}

static inline void pc_core_close(pc_core *c) { free(c->arena); }

/* Begins a frame of s in fmt (ZS_MONO_* / ZS_GRAY4_* options mono), Gouraud,
 * 70 degrees from the origin down -Z; the caller renders the rows. */
static inline void pc_frame(pc_core *c, const pc_scene *s, zs_format fmt, unsigned mono)
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
    sp.background = c->background;
    assert_int_equal(zs_frame_shading(&c->r, &sp), ZS_OK);
    assert_int_equal(zs_draw(&c->r, &s->mesh, NULL), ZS_OK);
}

/* The core's picture of the frame, rendered whole with zs_render_rows, one
 * byte a pixel: the level (ZS_FMT_GRAY4) or the bit (1-bit pages or rows). */
static inline void pc_reference(pc_core *c, const pc_scene *s, zs_format fmt, unsigned mono,
                                unsigned w, unsigned h, uint8_t *px)
{
    size_t n = zs_panel_window_bytes(fmt, w, h), stride = zs_format_stride(fmt, w);
    uint8_t *img = calloc(n, 1);
    pc_frame(c, s, fmt, mono);
    assert_int_equal(zs_render_rows(&c->r, 0, (int)h, img, stride), ZS_OK);
    for (unsigned y = 0; y < h; y++)
        for (unsigned x = 0; x < w; x++)
            px[y * w + x] = fmt == ZS_FMT_GRAY4
                                ? (uint8_t)((img[y * stride + x / 2] >> (x % 2 ? 0 : 4)) & 15u)
                            : fmt == ZS_FMT_MONO_PAGE
                                ? (uint8_t)((img[(y / 8) * w + x] >> (y % 8)) & 1u)
                                : (uint8_t)((img[y * stride + x / 8] >> (7 - x % 8)) & 1u);
    free(img);
}

#endif
