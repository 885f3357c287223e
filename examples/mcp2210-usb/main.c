/* SPDX-License-Identifier: MIT */
/*
 * Example: a turning cube on a 240x240 ST7789 behind a Microchip MCP2210
 * USB-to-SPI bridge (hidapi, hidraw), through the MCP2210 port (ports/mcp2210)
 * and the panel driver. About 60 KB/s over USB: a frame takes about 2 s.
 *
 *     example-mcp2210-usb [HIDRAW_PATH] [FRAMES]
 *
 * Pins as the port's defaults: CS GP0, D/C GP1, reset GP2 (README: MCP2210
 * breakout + ST7789). Built by make; run here only as far as its error for a
 * missing device.
 */
#include <stdio.h>
#include <stdlib.h>

#include "zs_mcp2210.h"
#include "zspan/panel.h"
#include "zspan/zspan.h"

#define W 240
#define H 240
#define BAND 16

static const int16_t cube_pos[8 * 3] = {
    -1, -1, -1, 1, -1, -1, -1, 1, -1, 1, 1, -1, -1, -1, 1, 1, -1, 1, -1, 1, 1, 1, 1, 1,
};
static const uint16_t cube_idx[12 * 3] = {
    1, 3, 7, 1, 7, 5, 0, 6, 2, 0, 4, 6, 2, 6, 7, 2, 7, 3,
    0, 1, 5, 0, 5, 4, 4, 5, 7, 4, 7, 6, 0, 3, 1, 0, 2, 3,
};
static const zs_color cube_colors[8] = {
    ZS_RGB(40, 40, 40), ZS_RGB(255, 40, 40), ZS_RGB(40, 255, 40), ZS_RGB(255, 255, 40),
    ZS_RGB(40, 40, 255), ZS_RGB(255, 40, 255), ZS_RGB(40, 255, 255), ZS_RGB(255, 255, 255),
};

static uint8_t arena[ZS_ARENA_BYTES(W, H, 12, 16, 12)];
static uint8_t band0[BAND * W * 2], band1[BAND * W * 2];

int main(int argc, char **argv)
{
    static zs_mcp2210 port;
    static zs_renderer r;
    zs_panel lcd;
    zs_mcp2210_cfg cfg = zs_mcp2210_cfg_default();
    zs_config rc = zs_config_default(W, H, 12, 16, 12);
    zs_mesh cube = {cube_pos, cube_idx, NULL, cube_colors, NULL, NULL, ZS_FX_RATIO(8, 10), 8, 12, 0,
                    NULL, NULL};
    zs_mat34 view = zs_mat34_identity();
    zs_camera cam;
    char err[256];
    long frames, f;

    frames = argc > 2 ? atol(argv[2]) : 30;
    if (zs_mcp2210_open_hidapi(&port, argc > 1 ? argv[1] : NULL, &cfg, err, sizeof err) != 0) {
        fprintf(stderr, "%s: %s\n", argv[0], err);
        return 1;
    }
    if (zs_panel_init(&lcd, &zs_panel_st7789_240x240, &port.bus, ZS_FMT_RGB565_BE, 0) !=
            ZS_PANEL_OK ||
        zs_init(&r, arena, sizeof arena, &rc) != ZS_OK || zs_camera_set_view(&cam, &view) ||
        zs_camera_perspective(&cam, ZS_FX(50), ZS_FX_RATIO(1, 10), ZS_FX(20))) {
        fprintf(stderr, "%s: panel or renderer set-up failed\n", argv[0]);
        zs_mcp2210_close(&port);
        return 1;
    }
    for (f = 0; f < frames; f++) {
        zs_shade_params look = zs_shade_default();
        zs_mat34 ry = zs_mat34_rotate_y(ZS_FX((12 * f) % 360));
        zs_mat34 rx = zs_mat34_rotate_x(ZS_FX((24 * f) % 360));
        zs_mat34 t = zs_mat34_translate(0, 0, -ZS_FX(3));
        zs_mat34 m = zs_mat34_mul(&rx, &ry);
        m = zs_mat34_mul(&t, &m);
        look.shading = ZS_SHADE_GOURAUD;
        look.format = lcd.format;
        if (zs_frame_begin(&r, &cam, ZS_MODE_SPAN) || zs_frame_shading(&r, &look) ||
            zs_draw(&r, &cube, &m) ||
            zs_panel_stream(&lcd, &r, band0, band1, sizeof band0, BAND, NULL, NULL)) {
            fprintf(stderr, "%s: frame %ld failed: %s\n", argv[0], f, port.err);
            zs_mcp2210_close(&port);
            return 3;
        }
    }
    zs_mcp2210_close(&port);
    return 0;
}
