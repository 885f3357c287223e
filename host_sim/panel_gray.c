/* SPDX-License-Identifier: MIT */
/*
 * zspan-sim panel on a 4-bit grey panel (SSD0323; issue 20): the demo scene
 * in ZS_FMT_GRAY4 through the panel driver into the emulated controller
 * (host_sim/emu/emu_gray.c) over 4-wire SPI. Each frame is also rendered
 * straight into memory and the emulated glass must show it level for level;
 * the last frame's glass is written as a PNG (--out).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "demo_scene.h"
#include "emu/emu_gray.h"
#include "sim.h"
#include "zs_app.h"
#include "zs_opts.h"
#include "zspan/panel.h"

#define GPROG "zspan-sim panel"

int sim_panel_gray(int argc, char **argv);

typedef struct gray_opts {
    zs_app_opts app;
    const char *out;
    int round;
} gray_opts;

static int parse(int argc, char **argv, gray_opts *o)
{
    int i, m;
    const char *v;
    memset(o, 0, sizeof *o);
    zs_app_defaults(&o->app, argc);
    o->app.band = 8;
    o->app.frames = 1;
    o->out = "out/panel_gray4.png";
    if (o->app.meshes == NULL)
        return SIM_EXIT_FAIL;
    for (i = 1; i < argc; i++) {
        if ((m = zs_app_option(argc, argv, &i, &o->app, GPROG)) != 0) {
            if (m < 0)
                return SIM_EXIT_USAGE;
        } else if (strcmp(argv[i], "--round") == 0) {
            o->round = 1;
        } else if ((m = zs_opt_value(argc, argv, &i, "--out", &v, GPROG)) != 0) {
            if (m < 0)
                return SIM_EXIT_USAGE;
            o->out = v;
        } else {
            fprintf(stderr, GPROG ": unknown option '%s' for a 4-bit grey panel\n", argv[i]);
            return SIM_EXIT_USAGE;
        }
    }
    if (o->app.nmeshes > 0) {
        fprintf(stderr, GPROG ": 4-bit grey panels show the demo scene only (no --mesh)\n");
        return SIM_EXIT_USAGE;
    }
    return 0;
}

static zs_status gray_frame(zs_renderer *r, const demo_scene *s, long k, const gray_opts *o)
{
    zs_camera cam;
    zs_shade_params sp;
    zs_status st = demo_camera(&cam, (uint32_t)(o->app.start_frame + k));
    if (st != ZS_OK || (st = zs_frame_begin(r, &cam, o->app.mode)) != ZS_OK)
        return st;
    sp = demo_shading(o->app.shade, ZS_FMT_GRAY4);
    sp.mono = o->round ? 0u : ZS_GRAY4_DITHER;
    if ((st = zs_frame_shading(r, &sp)) != ZS_OK)
        return st;
    return demo_scene_draw(r, s);
}

int sim_panel_gray(int argc, char **argv)
{
    gray_opts o;
    const zs_panel_desc *d;
    static emu_gray emu;
    emu_gray_port port;
    zs_panel lcd;
    zs_panel_status ps;
    zs_renderer r;
    zs_config cfg;
    demo_scene *scene = NULL;
    uint8_t *arena = NULL, *b0 = NULL, *b1 = NULL, *img = NULL;
    uint8_t view[EMU_GRAY_W * EMU_GRAY_H];
    size_t n, buf, stride;
    long k;
    int rc = parse(argc, argv, &o);
    zs_panel_frame_stats st;
    if (rc != 0) {
        zs_app_free(&o.app);
        return rc;
    }
    d = zs_panel_find(o.app.panel);
    rc = SIM_EXIT_FAIL;
    emu_gray_init(&emu);
    if (d == NULL || emu_gray_port_init(&port, &emu) != 0)
        goto done;
    ps = zs_panel_init(&lcd, d, &port.bus, ZS_FMT_GRAY4, (unsigned)o.app.rotation);
    if (ps != ZS_PANEL_OK) {
        fprintf(stderr, GPROG ": panel init: %s\n", zs_panel_strerror(ps));
        rc = ps == ZS_PANEL_ERR_ROTATION ? SIM_EXIT_USAGE : SIM_EXIT_FAIL;
        goto done;
    }
    scene = malloc(sizeof *scene);
    cfg = zs_config_default(lcd.width, lcd.height, DEMO_TRIANGLES * 2, DEMO_VERTICES * 2, 1024);
    cfg.flags = ZS_CFG_MONO;
    n = zs_arena_bytes(&cfg);
    arena = malloc(n);
    stride = zs_format_stride(ZS_FMT_GRAY4, lcd.width);
    buf = stride * (size_t)o.app.band;
    b0 = malloc(buf);
    b1 = malloc(buf);
    img = malloc(stride * lcd.height);
    if (!scene || !arena || !b0 || !b1 || !img || zs_init(&r, arena, n, &cfg) != ZS_OK)
        goto done;
    demo_scene_init(scene);
    for (k = 0; k < o.app.frames; k++) {
        unsigned x, y, bad = 0;
        zs_status zst = gray_frame(&r, scene, k, &o);
        if (zst == ZS_OK)
            zst = zs_render_rows(&r, 0, lcd.height, img, stride);
        if (zst == ZS_OK)
            zst = gray_frame(&r, scene, k, &o);
        if (zst != ZS_OK) {
            fprintf(stderr, GPROG ": frame: %s\n", zs_strerror(zst));
            goto done;
        }
        ps = zs_panel_stream(&lcd, &r, b0, b1, buf, (int)o.app.band, NULL, &st);
        if (ps != ZS_PANEL_OK) {
            fprintf(stderr, GPROG ": stream: %s (%s)\n", zs_panel_strerror(ps),
                    zs_strerror(st.render_status));
            goto done;
        }
        emu_gray_view(&emu, view);
        for (y = 0; y < lcd.height; y++)
            for (x = 0; x < lcd.width; x++)
                bad += view[y * EMU_GRAY_W + x] !=
                       ((img[y * stride + x / 2] >> (x % 2 ? 0 : 4)) & 15u);
        if (bad) {
            fprintf(stderr, GPROG ": frame %ld: %u pixels of the emulated glass differ from the "
                    "render\n", k, bad);
            goto done;
        }
    }
    if (emu.errors) {
        fprintf(stderr, GPROG ": protocol error: %s\n", emu.first_error);
        goto done;
    }
    if (sim_make_parent_dirs(o.out) != 0 || emu_gray_write_png(&emu, o.out) != 0) {
        fprintf(stderr, GPROG ": cannot write %s\n", o.out);
        goto done;
    }
    if (!o.app.quiet)
        printf("panel %s %ux%u over 4-wire SPI, GRAY4 %s: %ld frames, each on the glass as "
               "rendered; %u bytes a frame (%.2f ms at %.1f MHz); %s\n",
               d->name, lcd.width, lcd.height, o.round ? "rounded" : "dithered", o.app.frames,
               (unsigned)st.bytes, st.bytes * 8.0 / d->max_spi_hz * 1e3, d->max_spi_hz / 1e6,
               o.out);
    rc = SIM_EXIT_OK;
done:
    free(scene);
    free(arena);
    free(b0);
    free(b1);
    free(img);
    zs_app_free(&o.app);
    return rc;
}
