/* SPDX-License-Identifier: MIT */
/*
 * Example: a spinning cube on a 240x240 ST7789 wired to a Linux board's SPI
 * (spidev) with D/C and reset on GPIO lines (libgpiod), through the Linux
 * port (ports/linux) and the panel driver. Band by band, no framebuffer.
 *
 *     example-linux-spidev /dev/spidev0.0 gpiochip0 DC_LINE RESET_LINE [FRAMES]
 *
 * e.g. on a Raspberry Pi: /dev/spidev0.0 gpiochip0 25 27 (README: Raspberry Pi +
 * ST7789). Built by make; run here only as far as its error for a missing device.
 */
#include <stdio.h>
#include <stdlib.h>

#include "zs_linux.h"
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
    static zs_linux_port port;
    static zs_renderer r;
    zs_panel lcd;
    zs_linux_cfg cfg = zs_linux_cfg_default();
    zs_config rc = zs_config_default(W, H, 12, 16, 12);
    zs_mesh cube = {cube_pos, cube_idx, NULL, cube_colors, NULL, NULL, ZS_FX_RATIO(8, 10), 8, 12, 0,
                    NULL, NULL};
    zs_mat34 view = zs_mat34_identity();
    zs_camera cam;
    char err[256];
    long frames, f;

    if (argc < 5) {
        fprintf(stderr, "usage: %s SPIDEV GPIOCHIP DC_LINE RESET_LINE [FRAMES]\n", argv[0]);
        return 2;
    }
    cfg.spi_dev = argv[1];
    cfg.gpiochip = argv[2];
    cfg.dc = atoi(argv[3]);
    cfg.reset = atoi(argv[4]);
    frames = argc > 5 ? atol(argv[5]) : 360;
    if (zs_linux_open(&port, &cfg, err, sizeof err) != 0) {
        fprintf(stderr, "%s: %s\n", argv[0], err);
        return 1;
    }
    if (zs_panel_init(&lcd, &zs_panel_st7789_240x240, &port.bus, ZS_FMT_RGB565_BE, 0) !=
            ZS_PANEL_OK ||
        zs_init(&r, arena, sizeof arena, &rc) != ZS_OK || zs_camera_set_view(&cam, &view) ||
        zs_camera_perspective(&cam, ZS_FX(50), ZS_FX_RATIO(1, 10), ZS_FX(20))) {
        fprintf(stderr, "%s: panel or renderer set-up failed\n", argv[0]);
        zs_linux_close(&port);
        return 1;
    }
    for (f = 0; f < frames; f++) {
        zs_shade_params look = zs_shade_default();
        zs_mat34 ry = zs_mat34_rotate_y(ZS_FX(f % 360));
        zs_mat34 rx = zs_mat34_rotate_x(ZS_FX((2 * f) % 360));
        zs_mat34 t = zs_mat34_translate(0, 0, -ZS_FX(3));
        zs_mat34 m = zs_mat34_mul(&rx, &ry);
        m = zs_mat34_mul(&t, &m);
        look.shading = ZS_SHADE_GOURAUD;
        look.format = lcd.format;
        if (zs_frame_begin(&r, &cam, ZS_MODE_SPAN) || zs_frame_shading(&r, &look) ||
            zs_draw(&r, &cube, &m) ||
            zs_panel_stream(&lcd, &r, band0, band1, sizeof band0, BAND, NULL, NULL)) {
            fprintf(stderr, "%s: frame %ld failed: %s\n", argv[0], f, port.err);
            zs_linux_close(&port);
            return 3;
        }
    }
    zs_linux_close(&port);
    return 0;
}
