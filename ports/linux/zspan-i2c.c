/* SPDX-License-Identifier: MIT */
/*
 * zspan-i2c: the demo scene in 1 bit on an SSD1306 / SH1106 module on a
 * Linux I2C bus (/dev/i2c-N, e.g. a Raspberry Pi's pins 3 and 5),
 * filled with ordered dithering or error diffusion, or as a hidden-line
 * drawing. The frame loop and the common options are zs_app's, as for
 * zspan-linux (built without mesh loading: no assimp); this file is the bus.
 *
 *   zspan-i2c [--bus /dev/i2c-1] [--addr 0x3C] [--panel ssd1306-128x64]
 *             [--frames N] [--rotation 0|2] [--diffuse] [--lines] [--quiet] ...
 *
 * Exit status: 0 done, 1 failure, 2 bad command line, 3 the bus (the
 * message says what: no bus, permission, no device answering).
 */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "zs_app.h"
#include "zs_linux_i2c.h"
#include "zs_opts.h"

static const char *prog = "zspan-i2c";

typedef struct i2c_cfg {
    const char *bus;
    long addr;
} i2c_cfg;

/* What the report needs: the port, and the bus traffic of the frames alone. */
typedef struct i2c_run {
    zs_i2c_port port;
    const i2c_cfg *cfg;
    const char *panel;
    uint64_t bytes0;
    uint32_t messages0;
    long frames;
} i2c_run;

static void usage(FILE *f)
{
    fprintf(f,
            "usage: %s [options]\n"
            "Renders the zspan demo in 1 bit on an SSD1306 / SH1106 module on a Linux I2C bus\n"
            "(i2c-dev; built without mesh loading, so no --mesh).\n\n"
            "Wiring:\n"
            "  --bus /dev/i2c-N      I2C bus (default /dev/i2c-1)\n"
            "  --addr 0xNN           the module's address (default 0x3C)\n\n"
            "%s\n"
            "Here the panel defaults to ssd1306-128x64 (also ssd1306-128x32, sh1106-132x64),\n"
            "--frames to 30 and --rotation takes 0 or 2.\n"
            "Exit status: 0 ok, 1 error, 2 usage, 3 the bus (no bus, permission, no device).\n",
            prog, ZS_APP_USAGE);
}

static void defaults(zs_app_opts *o)
{
    o->panel = "ssd1306-128x64";
    o->frames = 30;
}

static int port_option(void *cfg, int argc, char **argv, int *i)
{
    i2c_cfg *c = cfg;
    int m;
    if ((m = zs_opt_value(argc, argv, i, "--bus", &c->bus, prog)) != 0)
        return m;
    return zs_opt_long_at(argc, argv, i, "--addr", 0x03, 0x77, &c->addr, prog);
}

static const char *port_error(void *ctx)
{
    return zs_i2c_error(&((i2c_run *)ctx)->port);
}

static int port_ready(void *ctx, const zs_panel *lcd, const zs_wire_model *wire)
{
    i2c_run *run = ctx;
    (void)lcd;
    (void)wire;
    run->bytes0 = run->port.bytes;
    run->messages0 = run->port.messages;
    return 0;
}

static int port_frame_done(void *ctx, const zs_app_frame *f)
{
    ((i2c_run *)ctx)->frames = f->index + 1;
    return 0;
}

static void port_report(void *ctx, FILE *f)
{
    const i2c_run *run = ctx;
    uint64_t bytes = run->port.bytes - run->bytes0;
    uint32_t msgs = run->port.messages - run->messages0;
    double n = run->frames > 0 ? (double)run->frames : 1.0;
    fprintf(f,
            "%s: %s on %s at 0x%02lX, %ld frames; wire %.0f bytes a frame: %.2f ms at 400 kHz, "
            "%.2f ms at 1 MHz\n",
            prog, run->panel, run->cfg->bus, run->cfg->addr, run->frames, (double)bytes / n,
            zs_i2c_wire_us(bytes, msgs, 400e3) / 1e3 / n, zs_i2c_wire_us(bytes, msgs, 1e6) / 1e3 / n);
}

int main(int argc, char **argv)
{
    zs_app_opts o;
    i2c_cfg c = {"/dev/i2c-1", 0x3C};
    zs_app_cli cli = {NULL, usage, port_option, NULL, defaults};
    static i2c_run run;
    zs_app_port ap;
    const zs_panel_desc *d;
    char err[256];
    int rc;

    cli.prog = prog;
    cli.cfg = &c;
    if ((rc = zs_app_parse(&o, argc, argv, &cli)) != ZS_APP_PARSED)
        return rc;
    d = zs_panel_find(o.panel);
    if (!zs_panel_supports(d, ZS_FMT_MONO_PAGE) || o.rotation % 2 != 0) {
        fprintf(stderr, "%s: %s\n", prog,
                o.rotation % 2 ? "--rotation: 0 or 2 on these modules"
                               : "--panel: not an I2C OLED module (ssd1306-*, sh1106-*)");
        zs_app_free(&o);
        return 2;
    }
    if (zs_i2c_open(&run.port, c.bus, (uint8_t)c.addr, err, sizeof err) != 0) {
        fprintf(stderr, "%s: %s\n", prog, err);
        zs_app_free(&o);
        return 3;
    }
    run.cfg = &c;
    run.panel = d->name;
    memset(&ap, 0, sizeof ap);
    ap.name = "I2C";
    ap.clock_hz = 400000;
    ap.error = port_error;
    ap.ready = port_ready;
    ap.frame_done = port_frame_done;
    ap.report = port_report;
    ap.ctx = &run;
    rc = zs_app_run(&o, &run.port.bus, &ap, prog);
    zs_i2c_close(&run.port);
    zs_app_free(&o);
    return rc;
}
