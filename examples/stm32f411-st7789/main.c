/* SPDX-License-Identifier: MIT */
/*
 * Example: the zspan demo scene (app/demo_scene.h) orbiting on a 240x240
 * ST7789 module driven by an STM32F411 (board: ports/cortex-m/stm32f411/),
 * one line at a time into two 480-byte line buffers: one is rendered while
 * DMA sends the other.
 *
 * Built by make (build/fw/stm32f411-st7789.elf) with the cross compiler; it
 * was not run on hardware here (no board): flash it with e.g. st-flash or
 * OpenOCD after arm-none-eabi-objcopy -O binary.
 */
#include "board_f411.h"
#include "demo_scene.h"
#include "zspan/panel.h"

#define EX_W 240
#define EX_H 240
/* Pools: room for every submitted triangle (about half are culled, which
 * leaves room for clipping's splits); vertices and active edges with a
 * margin over what frame 0 uses on the host (710 vertices, 146 edges). */
#define EX_MAX_TRIS DEMO_TRIANGLES
#define EX_MAX_VERTS (DEMO_VERTICES + 256)
#define EX_MAX_EDGES 384

static uint8_t arena[ZS_ARENA_BYTES(EX_W, EX_H, EX_MAX_TRIS, EX_MAX_VERTS, EX_MAX_EDGES)];
static uint8_t line0[EX_W * 2], line1[EX_W * 2];
static demo_scene scene;

int main(void)
{
    static zs_renderer r;
    static zs_panel lcd;
    zs_config cfg = zs_config_default(EX_W, EX_H, EX_MAX_TRIS, EX_MAX_VERTS, EX_MAX_EDGES);
    zs_bus *bus = port_f411_bus();
    uint32_t frame = 0;

    if (bus == NULL)
        return 1;
    if (zs_panel_init(&lcd, &zs_panel_st7789_240x240, bus, ZS_FMT_RGB565_BE, 0) != ZS_PANEL_OK)
        return 1;
    zs_panel_backlight(&lcd, 255);
    if (zs_init(&r, arena, sizeof arena, &cfg) != ZS_OK)
        return 1;
    demo_scene_init(&scene);
    for (;;) {
        if (demo_frame(&r, &scene, frame, ZS_MODE_SPAN, ZS_SHADE_GOURAUD, ZS_FMT_RGB565_BE) !=
            ZS_OK)
            return 1;
        if (zs_panel_stream(&lcd, &r, line0, line1, sizeof line0, 1, NULL, NULL) !=
            ZS_PANEL_OK)
            return 1;
        frame = (frame + 1u) % 120u; /* 3 degrees per frame: one orbit */
    }
}
