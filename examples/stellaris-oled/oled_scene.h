/* SPDX-License-Identifier: MIT */
/*
 * The scenes of the Stellaris OLED firmware (issue 20), shared with the host
 * harness that renders the same frames (tests/stellaris/test_stellaris.c).
 * Freestanding C99, no float, no malloc.
 *
 *  - "big" (LM3S6965 + SSD0323, 128x64, 64 KB SRAM): the demo scene of
 *    app/demo_scene.c (built with a 16x8 torus) orbited 24 degrees a frame,
 *    Gouraud, lit, fog, in ZS_FMT_GRAY4 with ordered dithering;
 *  - "small" (LM3S811 + SSD0303, 96x16, 8 KB SRAM): a lit cube spinning 20
 *    degrees a frame about its vertical axis, flat, in ZS_FMT_MONO_PAGE with
 *    ordered dithering.
 */
#ifndef ZSPAN_OLED_SCENE_H
#define ZSPAN_OLED_SCENE_H

#include "zspan/zspan.h"

#define OLED_BIG_W 128
#define OLED_BIG_H 64
#define OLED_SMALL_W 96
#define OLED_SMALL_H 16

/* Pool capacities of each scene: the largest use over every frame (the big
 * scene repeats after 15 frames: 431 records, 326 vertices, 148 edge sides)
 * with a margin; the firmware reports drops, the harness requires 0. */
#define OLED_BIG_TRIS 480
#define OLED_BIG_VERTS 360
#define OLED_BIG_EDGES 168
#define OLED_BIG_FLAGS (ZS_CFG_MONO | ZS_CFG_NO_ZLINE)
#define OLED_SMALL_TRIS 12
#define OLED_SMALL_VERTS 16
#define OLED_SMALL_EDGES 12
#define OLED_SMALL_FLAGS (ZS_CFG_MONO | ZS_CFG_NO_ZLINE | ZS_CFG_FLAT_ONLY)

struct demo_scene;

zs_config oled_big_config(void);
zs_config oled_small_config(void);
/* Everything of frame f but the rows (camera, zs_frame_begin, shading, draws). */
zs_status oled_big_frame(zs_renderer *r, const struct demo_scene *s, uint32_t f);
zs_status oled_small_frame(zs_renderer *r, uint32_t f);

#endif
