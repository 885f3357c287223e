/* SPDX-License-Identifier: MIT */
/*
 * zspan-i2c: the demo scene in 1 bit on an SSD1306 / SH1106 module on a
 * Linux I2C bus (/dev/i2c-N, e.g. a Raspberry Pi's pins 3 and 5), filled
 * with ordered dithering or error diffusion, or as a hidden-line drawing.
 *
 *   zspan-i2c [--bus /dev/i2c-1] [--addr 0x3C] [--panel ssd1306-128x64]
 *             [--frames N] [--rotation 0|2] [--diffuse] [--lines] [--quiet]
 *
 * Exit status: 0 done, 1 failure, 2 bad command line, 3 the bus (the
 * message says what: no bus, permission, no device answering).
 */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "demo_scene.h"
#include "zs_linux_i2c.h"
#include "zspan/panel.h"

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec / 1e9;
}

static int usage(void)
{
    fprintf(stderr, "usage: zspan-i2c [--bus /dev/i2c-1] [--addr 0x3C] [--panel NAME] "
                    "[--frames N] [--rotation 0|2] [--diffuse] [--lines] [--quiet]\n"
                    "panels: ssd1306-128x64, ssd1306-128x32, sh1106-132x64\n");
    return 2;
}

int main(int argc, char **argv)
{
    const char *bus = "/dev/i2c-1", *name = "ssd1306-128x64";
    long addr = 0x3C, frames = 30, rot = 0;
    int diffuse = 0, lines = 0, quiet = 0, i;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        char *end = NULL;
        if (strcmp(a, "--diffuse") == 0) diffuse = 1;
        else if (strcmp(a, "--lines") == 0) lines = 1;
        else if (strcmp(a, "--quiet") == 0) quiet = 1;
        else if (v && strcmp(a, "--bus") == 0) bus = argv[++i];
        else if (v && strcmp(a, "--panel") == 0) name = argv[++i];
        else if (v && strcmp(a, "--addr") == 0) {
            addr = strtol(argv[++i], &end, 0);
            if (*end || addr < 0x03 || addr > 0x77) return usage();
        } else if (v && strcmp(a, "--frames") == 0) {
            frames = strtol(argv[++i], &end, 10);
            if (*end || frames < 1 || frames > 1000000) return usage();
        } else if (v && strcmp(a, "--rotation") == 0) {
            rot = strtol(argv[++i], &end, 10);
            if (*end || (rot != 0 && rot != 2)) return usage();
        } else
            return usage();
    }
    const zs_panel_desc *d = zs_panel_find(name);
    if (d == NULL || !zs_panel_supports(d, ZS_FMT_MONO_PAGE)) {
        fprintf(stderr, "zspan-i2c: '%s' is no I2C OLED panel\n", name);
        return usage();
    }
    zs_i2c_port port;
    char err[256];
    if (zs_i2c_open(&port, bus, (uint8_t)addr, err, sizeof err) != 0) {
        fprintf(stderr, "zspan-i2c: %s\n", err);
        return 3;
    }
    zs_panel lcd;
    zs_panel_status ps = zs_panel_init(&lcd, d, &port.bus, ZS_FMT_MONO_PAGE, (unsigned)rot);
    if (ps != ZS_PANEL_OK) {
        fprintf(stderr, "zspan-i2c: panel init: %s%s%s\n", zs_panel_strerror(ps),
                ps == ZS_PANEL_ERR_IO ? ": " : "", ps == ZS_PANEL_ERR_IO ? zs_i2c_error(&port) : "");
        zs_i2c_close(&port);
        return ps == ZS_PANEL_ERR_IO ? 3 : 1;
    }
    static demo_scene scene;
    demo_scene_init(&scene);
    zs_config cfg = zs_config_default(lcd.width, lcd.height, DEMO_TRIANGLES * 2, DEMO_VERTICES * 2,
                                      1024);
    cfg.flags = ZS_CFG_MONO | ZS_CFG_LINES;
    size_t n = zs_arena_bytes(&cfg);
    void *arena = malloc(n);
    static uint8_t buf[2][132 * 2];
    zs_renderer r;
    if (arena == NULL || zs_init(&r, arena, n, &cfg) != ZS_OK) {
        fprintf(stderr, "zspan-i2c: no memory for the renderer\n");
        return 1;
    }
    double t_all = 0;
    uint64_t bytes_all = 0;
    uint32_t msgs_all = 0;
    for (long k = 0; k < frames; k++) {
        zs_camera cam;
        zs_shade_params sp;
        double t0 = now_s();
        uint64_t b0 = port.bytes;
        uint32_t m0 = port.messages;
        demo_camera(&cam, (uint32_t)k);
        zs_frame_begin(&r, &cam, ZS_MODE_SPAN);
        sp = demo_shading(ZS_SHADE_GOURAUD, ZS_FMT_MONO_PAGE);
        sp.mono = (uint8_t)(lines ? ZS_MONO_LINES : diffuse ? ZS_MONO_DIFFUSE : 0);
        zs_frame_shading(&r, &sp);
        demo_scene_draw(&r, &scene);
        ps = zs_panel_stream(&lcd, &r, buf[0], buf[1], sizeof buf[0], 16, NULL, NULL);
        if (ps != ZS_PANEL_OK) {
            fprintf(stderr, "zspan-i2c: frame %ld: %s%s%s\n", k, zs_panel_strerror(ps),
                    ps == ZS_PANEL_ERR_IO ? ": " : "", ps == ZS_PANEL_ERR_IO ? zs_i2c_error(&port) : "");
            zs_i2c_close(&port);
            free(arena);
            return ps == ZS_PANEL_ERR_IO ? 3 : 1;
        }
        t_all += now_s() - t0;
        bytes_all += port.bytes - b0;
        msgs_all += port.messages - m0;
    }
    if (!quiet)
        printf("zspan-i2c: %s on %s at 0x%02lX, %ld frames, %.1f ms a frame (rendering and the "
               "bus); wire %.0f bytes a frame: %.2f ms at 400 kHz, %.2f ms at 1 MHz\n",
               d->name, bus, addr, frames, t_all * 1e3 / (double)frames,
               (double)bytes_all / (double)frames,
               zs_i2c_wire_us(bytes_all, msgs_all, 400e3) / 1e3 / (double)frames,
               zs_i2c_wire_us(bytes_all, msgs_all, 1e6) / 1e3 / (double)frames);
    zs_i2c_close(&port);
    free(arena);
    return 0;
}
