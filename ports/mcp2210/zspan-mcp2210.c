/* SPDX-License-Identifier: MIT */
/*
 * zspan-mcp2210: the demo scene (or a mesh file) on an SPI panel behind a
 * Microchip MCP2210 USB-to-SPI bridge, through hidapi (hidraw).
 * About 60 KB/s: a full 240x240 RGB565 frame takes about 2 s; --partial
 * sends only the rows that changed.
 */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "zs_app.h"
#include "zs_opts.h"
#include "zs_mcp2210.h"

static const char *prog = "zspan-mcp2210";

static void usage(FILE *f)
{
    fprintf(f,
            "usage: %s [options]\n"
            "Renders the zspan demo (or a mesh) on an SPI panel behind an MCP2210 (hidapi).\n\n"
            "Wiring (GP pin numbers of the MCP2210):\n"
            "  --device PATH         hidraw device (default: the first 04D8:00DE found)\n"
            "  --cs N                chip-select pin (default 0: GP0)\n"
            "  --dc N                D/C pin (default 1)\n"
            "  --reset N             reset pin (default 2; -1 = not wired)\n"
            "  --backlight N         backlight pin (default -1 = not wired)\n"
            "  --hz HZ               SPI bit rate (default 12000000, the chip's maximum)\n"
            "  --spi-mode 0..3       SPI mode (default 0)\n"
            "  --timeout MS          answer timeout per report (default 1000)\n\n"
            "%s\n"
            "Throughput: about 60 KB/s (one 64-byte HID report per USB frame): a full 240x240\n"
            "RGB565 frame (115,200 bytes) takes about 2 s. Use --partial.\n"
            "Exit status: 0 ok, 1 error, 2 usage, 3 the device failed or vanished mid-run.\n",
            prog, ZS_APP_USAGE);
}

static const char *port_error(void *ctx)
{
    return ((zs_mcp2210 *)ctx)->err;
}

static void port_report(void *ctx, FILE *f)
{
    zs_mcp2210 *m = ctx;
    fprintf(f,
            "MCP2210: %llu reports (%llu with data, %llu end-of-transfer polls), %llu busy "
            "answers resent, %llu SPI bytes in %llu transactions, %llu settings, %llu GPIO\n",
            (unsigned long long)m->st.reports, (unsigned long long)m->st.xfer_reports,
            (unsigned long long)m->st.poll_reports, (unsigned long long)m->st.busy,
            (unsigned long long)m->st.spi_bytes, (unsigned long long)m->st.transactions,
            (unsigned long long)m->st.settings, (unsigned long long)m->st.gpio);
}

/* The device and wiring options (zs_app_cli.option). */
typedef struct mcp_args {
    zs_mcp2210_cfg c;
    const char *path;
} mcp_args;

static int port_option(void *cfg, int argc, char **argv, int *i)
{
    mcp_args *a = cfg;
    long v;
    int m;

    if ((m = zs_opt_value(argc, argv, i, "--device", &a->path, prog)) != 0)
        return m;
#define PIN_OPT(name, lo, hi, field)                                                           \
    if ((m = zs_opt_long_at(argc, argv, i, name, lo, hi, &v, prog)) != 0)                      \
        return m > 0 ? (a->c.field = (__typeof__(a->c.field))v, 1) : -1;
    PIN_OPT("--cs", 0, 8, cs_pin)
    PIN_OPT("--dc", 0, 8, dc_pin)
    PIN_OPT("--reset", -1, 8, reset_pin)
    PIN_OPT("--backlight", -1, 8, backlight_pin)
    PIN_OPT("--hz", 1000, 12000000L, bit_rate)
    PIN_OPT("--spi-mode", 0, 3, spi_mode)
    PIN_OPT("--timeout", 1, 600000L, timeout_ms)
#undef PIN_OPT
    return 0;
}

int main(int argc, char **argv)
{
    zs_app_opts o;
    mcp_args args;
    zs_app_cli cli = {NULL, usage, port_option, NULL, NULL};
    zs_mcp2210 m;
    zs_app_port ap;
    char err[512];
    int rc;

    args.c = zs_mcp2210_cfg_default();
    args.path = NULL;
    cli.prog = prog;
    cli.cfg = &args;
    if ((rc = zs_app_parse(&o, argc, argv, &cli)) != ZS_APP_PARSED)
        return rc;
    if (zs_mcp2210_open_hidapi(&m, args.path, &args.c, err, sizeof err) != 0) {
        fprintf(stderr, "%s: %s\n", prog, err);
        zs_app_free(&o);
        return 1;
    }
    if (!o.quiet)
        printf("%s: MCP2210 at %u bit/s, SPI mode %u, CS GP%d, D/C GP%d, reset GP%d, "
               "backlight GP%d\n",
               prog, (unsigned)args.c.bit_rate, args.c.spi_mode, args.c.cs_pin, args.c.dc_pin,
               args.c.reset_pin, args.c.backlight_pin);
    memset(&ap, 0, sizeof ap);
    ap.name = "MCP2210";
    ap.clock_hz = args.c.bit_rate;
    ap.error = port_error;
    ap.report = port_report;
    ap.ctx = &m;
    rc = zs_app_run(&o, &m.bus, &ap, prog);
    if (rc == ZS_APP_EXIT_BUS && !o.quiet)
        port_report(&m, stdout);
    zs_mcp2210_close(&m);
    zs_app_free(&o);
    return rc;
}
