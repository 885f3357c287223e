/* SPDX-License-Identifier: MIT */
/*
 * zspan-sim panel on a monochrome panel (SSD1306, SH1106, SSD1680): the demo
 * scene in 1 bit through the panel driver into the emulated controller
 * (host_sim/emu/emu_mono.c), over 4-wire SPI or I2C. Each run leaves two
 * pictures of the glass: the filled, dithered frame (--out) and the same
 * view as a hidden-line drawing (--lines-out), and reports the wire time.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "demo_scene.h"
#include "emu/emu_mono.h"
#include "sim.h"
#include "zs_app.h"
#include "zs_opts.h"
#include "zspan/panel.h"

#define MPROG "zspan-sim panel"

int sim_panel_mono(int argc, char **argv);

typedef struct mono_opts {
    zs_app_opts app;
    const char *out, *lines_out;
    int i2c, diffuse;
    double clock;
} mono_opts;

static int parse(int argc, char **argv, mono_opts *o)
{
    int i, m;
    const char *v;
    memset(o, 0, sizeof *o);
    zs_app_defaults(&o->app, argc);
    o->app.band = 8;
    o->app.frames = 1;
    o->out = "out/panel.png";
    o->lines_out = "out/panel_lines.png";
    if (o->app.meshes == NULL)
        return SIM_EXIT_FAIL;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        if ((m = zs_app_option(argc, argv, &i, &o->app, MPROG)) != 0) {
            if (m < 0)
                return SIM_EXIT_USAGE;
        } else if (strcmp(a, "--i2c") == 0) {
            o->i2c = 1;
        } else if (strcmp(a, "--diffuse") == 0) {
            o->diffuse = 1;
        } else if ((m = zs_opt_value(argc, argv, &i, "--out", &v, MPROG)) != 0) {
            if (m < 0)
                return SIM_EXIT_USAGE;
            o->out = v;
        } else if ((m = zs_opt_value(argc, argv, &i, "--lines-out", &v, MPROG)) != 0) {
            if (m < 0)
                return SIM_EXIT_USAGE;
            o->lines_out = v;
        } else if ((m = zs_opt_value(argc, argv, &i, "--clock", &v, MPROG)) != 0) {
            if (m < 0 || zs_opt_double(MPROG, "--clock", v, &o->clock) != 0 || o->clock < 1000.0 ||
                o->clock > 4e9) {
                fprintf(stderr, MPROG ": --clock wants Hz, 1000 .. 4e9\n");
                return SIM_EXIT_USAGE;
            }
        } else {
            fprintf(stderr, MPROG ": unknown option '%s' for a monochrome panel\n", a);
            return SIM_EXIT_USAGE;
        }
    }
    if (o->app.nmeshes > 0) {
        fprintf(stderr, MPROG ": monochrome panels show the demo scene only (no --mesh)\n");
        return SIM_EXIT_USAGE;
    }
    return 0;
}

/* Frame k of the demo in the panel's 1-bit format, `mono` flags. */
static zs_status demo_mono_frame(zs_renderer *r, const demo_scene *s, long k, const mono_opts *o,
                                 zs_format fmt, unsigned mono)
{
    zs_camera cam;
    zs_shade_params sp;
    zs_status st = demo_camera(&cam, (uint32_t)(o->app.start_frame + k));
    if (st != ZS_OK || (st = zs_frame_begin(r, &cam, o->app.mode)) != ZS_OK)
        return st;
    sp = demo_shading(o->app.shade, fmt);
    sp.mono = (uint8_t)mono;
    if ((st = zs_frame_shading(r, &sp)) != ZS_OK)
        return st;
    return demo_scene_draw(r, s);
}

static int write_glass(const emu_mono *e, unsigned rot, const char *path)
{
    if (path == NULL || path[0] == '\0')
        return 0;
    if (sim_make_parent_dirs(path) != 0 || emu_mono_write_png(e, rot, path) != 0) {
        fprintf(stderr, MPROG ": cannot write %s\n", path);
        return -1;
    }
    return 0;
}

int sim_panel_mono(int argc, char **argv)
{
    mono_opts o;
    const zs_panel_desc *d;
    const emu_mono_model *m;
    emu_mono emu;
    emu_mono_port port;
    zs_panel lcd;
    zs_panel_status ps;
    zs_renderer r;
    zs_config cfg;
    zs_format fmt;
    demo_scene *scene = NULL;
    uint8_t *arena = NULL, *b0 = NULL, *b1 = NULL;
    size_t n, buf;
    long k;
    int rc = parse(argc, argv, &o), epd;
    uint64_t clocks0 = 0, clocks_frame = 0;
    uint32_t frames0 = 0, frames_frame = 0;
    zs_panel_frame_stats st;
    if (rc != 0) {
        zs_app_free(&o.app);
        return rc;
    }
    d = zs_panel_find(o.app.panel);
    m = emu_mono_model_find(o.app.panel);
    if (d == NULL || m == NULL) {
        fprintf(stderr, MPROG ": unknown panel '%s'\n", o.app.panel);
        zs_app_free(&o.app);
        return SIM_EXIT_USAGE;
    }
    epd = m->family == EMU_MONO_SSD1680;
    if (o.i2c && epd) {
        fprintf(stderr, MPROG ": %s has no I2C interface\n", d->name);
        zs_app_free(&o.app);
        return SIM_EXIT_USAGE;
    }
    fmt = zs_panel_supports(d, ZS_FMT_MONO_PAGE) ? ZS_FMT_MONO_PAGE : ZS_FMT_MONO_MSB;
    rc = SIM_EXIT_FAIL;
    if (emu_mono_init(&emu, m) != 0 ||
        emu_mono_port_init(&port, &emu, o.i2c,
                           m->family == EMU_MONO_SSD0303 ? ZS_SSD0303_I2C_ADDR
                                                         : ZS_SSD1306_I2C_ADDR))
        goto done;
    ps = zs_panel_init(&lcd, d, &port.bus, fmt, (unsigned)o.app.rotation);
    if (ps != ZS_PANEL_OK) {
        fprintf(stderr, MPROG ": panel init: %s\n", zs_panel_strerror(ps));
        rc = ps == ZS_PANEL_ERR_ROTATION ? SIM_EXIT_USAGE : SIM_EXIT_FAIL;
        goto done;
    }
    scene = malloc(sizeof *scene);
    cfg = zs_config_default(lcd.width, lcd.height, DEMO_TRIANGLES * 2, DEMO_VERTICES * 2, 1024);
    cfg.flags = ZS_CFG_MONO | ZS_CFG_LINES;
    n = zs_arena_bytes(&cfg);
    arena = malloc(n);
    buf = zs_panel_window_bytes(fmt, lcd.width, (unsigned)(o.app.band < 8 ? 8 : o.app.band));
    b0 = malloc(buf);
    b1 = malloc(buf);
    if (!scene || !arena || !b0 || !b1 || zs_init(&r, arena, n, &cfg) != ZS_OK)
        goto done;
    demo_scene_init(scene);
    for (k = 0; k <= o.app.frames; k++) {
        /* frames 0 .. frames-1 filled; then the last view once more as lines */
        int lines = k == o.app.frames;
        long view = lines ? o.app.frames - 1 : k;
        unsigned mono = lines ? ZS_MONO_LINES : (o.diffuse ? ZS_MONO_DIFFUSE : 0u);
        zs_status zst;
        if (epd && lines)
            mono |= ZS_MONO_INVERT; /* dark lines on paper */
        zst = demo_mono_frame(&r, scene, view, &o, fmt, mono);
        if (zst != ZS_OK) {
            fprintf(stderr, MPROG ": frame: %s\n", zs_strerror(zst));
            goto done;
        }
        clocks0 = port.clocks;
        frames0 = port.frames;
        ps = zs_panel_stream(&lcd, &r, b0, b1, buf, (int)o.app.band, NULL, &st);
        if (ps != ZS_PANEL_OK) {
            fprintf(stderr, MPROG ": stream: %s (%s)\n", zs_panel_strerror(ps),
                    zs_strerror(st.render_status));
            goto done;
        }
        clocks_frame = port.clocks - clocks0;
        frames_frame = port.frames - frames0;
        if (write_glass(&emu, (unsigned)o.app.rotation, lines ? o.lines_out : o.out) != 0)
            goto done;
    }
    if (emu.errors) {
        fprintf(stderr, MPROG ": protocol error: %s\n", emu.first_error);
        goto done;
    }
    if (!o.app.quiet) {
        double clk = o.clock > 0 ? o.clock : (double)d->max_spi_hz;
        printf("panel %s %ux%u at rotation %ld over %s, %s\n", d->name, lcd.width, lcd.height,
               o.app.rotation, o.i2c ? "I2C" : "4-wire SPI",
               o.diffuse ? "error diffusion" : "ordered (Bayer) dithering");
        if (o.i2c)
            printf("wire per frame: %llu clocks (%u transactions): %.2f ms at 400 kHz, %.2f ms at "
                   "1 MHz\n",
                   (unsigned long long)clocks_frame, frames_frame, clocks_frame / 400.0,
                   clocks_frame / 1000.0);
        else
            printf("wire per frame: %u bytes -> %.3f ms at %.1f MHz\n", st.bytes,
                   (double)clocks_frame * 1e3 / clk, clk / 1e6);
        if (epd)
            printf("refreshes: %u full, %u partial\n", emu.refreshes - emu.partial_refreshes,
                   emu.partial_refreshes);
        printf("wrote %s (filled) and %s (hidden lines)\n", o.out, o.lines_out);
    }
    rc = SIM_EXIT_OK;
done:
    free(scene);
    free(arena);
    free(b0);
    free(b1);
    emu_mono_free(&emu);
    zs_app_free(&o.app);
    return rc;
}
