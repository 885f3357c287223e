/* SPDX-License-Identifier: MIT */
/*
 * zspan-linux: the demo scene (or a mesh file) on an SPI panel wired to a
 * Linux board: spidev for the data, libgpiod lines for D/C, reset and the
 * backlight; or bit-banged SPI on GPIO lines where there is no spidev.
 */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "zs_app.h"
#include "zs_opts.h"
#include "zs_linux.h"

static const char *prog = "zspan-linux";

static void usage(FILE *f)
{
    fprintf(f,
            "usage: %s [options]\n"
            "Renders the zspan demo (or a mesh) on an SPI panel through spidev + libgpiod.\n\n"
            "Wiring:\n"
            "  --spi /dev/spidevB.C  SPI device (default /dev/spidev0.0)\n"
            "  --gpiochip CHIP       GPIO chip of the lines below: name, number or path\n"
            "                        (default gpiochip0)\n"
            "  --dc N                D/C line offset (required)\n"
            "  --reset N             reset line offset (default: not wired)\n"
            "  --backlight N         backlight line offset (default: not wired)\n"
            "  --hz HZ               SPI clock (default 32000000; the controller may round it down)\n"
            "  --spi-mode 0..3       SPI mode (default 0)\n"
            "  --bits N              bits per word (default 8)\n"
            "  --bufsiz N            spidev message limit (default: read from\n"
            "                        /sys/module/spidev/parameters/bufsiz, else 4096)\n"
            "  --bitbang             bit-banged SPI on GPIO lines instead of spidev (slow):\n"
            "  --sclk N --mosi N [--cs N]   its clock, data and chip-select lines\n\n"
            "%s\n"
            "Exit status: 0 ok, 1 error, 2 usage, 3 the bus failed during the run.\n",
            prog, ZS_APP_USAGE);
}

static const char *port_error(void *ctx)
{
    return ((zs_linux_port *)ctx)->err;
}

static void port_report(void *ctx, FILE *f)
{
    zs_linux_port *p = ctx;
    if (p->cfg.bitbang)
        fprintf(f, "bit-banged SPI: %llu bytes in %llu writes, %llu bits, %llu GPIO writes\n",
                (unsigned long long)p->st.bytes, (unsigned long long)p->st.messages,
                (unsigned long long)p->st.bitbang_bits, (unsigned long long)p->st.gpio_writes);
    else
        fprintf(f,
                "spidev %s: %llu bytes in %llu messages (largest %u, bufsiz %u), %u Hz, "
                "%llu GPIO writes\n",
                p->cfg.spi_dev, (unsigned long long)p->st.bytes,
                (unsigned long long)p->st.messages, (unsigned)p->st.max_message,
                (unsigned)p->bufsiz, (unsigned)p->cfg.hz, (unsigned long long)p->st.gpio_writes);
}

/* The wiring options (zs_app_cli.option). */
static int port_option(void *cfg, int argc, char **argv, int *i)
{
    zs_linux_cfg *c = cfg;
    long v;
    int m;

    if (strcmp(argv[*i], "--bitbang") == 0) {
        c->bitbang = 1;
        return 1;
    }
    if ((m = zs_opt_value(argc, argv, i, "--spi", &c->spi_dev, prog)) != 0 ||
        (m = zs_opt_value(argc, argv, i, "--gpiochip", &c->gpiochip, prog)) != 0)
        return m;
#define LINE_OPT(name, lo, hi, field)                                                          \
    if ((m = zs_opt_long_at(argc, argv, i, name, lo, hi, &v, prog)) != 0)                      \
        return m > 0 ? (c->field = (__typeof__(c->field))v, 1) : -1;
    LINE_OPT("--dc", 0, 65535, dc)
    LINE_OPT("--reset", 0, 65535, reset)
    LINE_OPT("--backlight", 0, 65535, backlight)
    LINE_OPT("--sclk", 0, 65535, sclk)
    LINE_OPT("--mosi", 0, 65535, mosi)
    LINE_OPT("--cs", 0, 65535, cs)
    LINE_OPT("--hz", 1000, 200000000L, hz)
    LINE_OPT("--spi-mode", 0, 3, spi_mode)
    LINE_OPT("--bits", 1, 32, bits)
    LINE_OPT("--bufsiz", 1, 1L << 24, bufsiz)
#undef LINE_OPT
    return 0;
}

int main(int argc, char **argv)
{
    zs_app_opts o;
    zs_linux_cfg c = zs_linux_cfg_default();
    zs_app_cli cli = {NULL, usage, port_option, NULL, NULL};
    zs_linux_port port;
    zs_app_port ap;
    char err[512];
    int rc;

    cli.prog = prog;
    cli.cfg = &c;
    if ((rc = zs_app_parse(&o, argc, argv, &cli)) != ZS_APP_PARSED)
        return rc;
    if (c.dc < 0) {
        fprintf(stderr, "%s: --dc N is required (the GPIO line wired to the panel's D/C pin)\n",
                prog);
        zs_app_free(&o);
        return 2;
    }
    if (c.bitbang)
        c.spi_dev = NULL;
    if (zs_linux_open(&port, &c, err, sizeof err) != 0) {
        fprintf(stderr, "%s: %s\n", prog, err);
        zs_app_free(&o);
        return 1;
    }
    if (!o.quiet) {
        if (c.bitbang)
            printf("%s: bit-banged SPI on %s (SCLK %d, MOSI %d, CS %d), D/C %d, %s\n", prog,
                   c.gpiochip, c.sclk, c.mosi, c.cs, c.dc, port.gpio->api);
        else
            printf("%s: %s at %u Hz, mode %u, messages of at most %u bytes; %s D/C %d reset %d "
                   "backlight %d (%s)\n",
                   prog, c.spi_dev, (unsigned)port.cfg.hz, c.spi_mode, (unsigned)port.bufsiz,
                   c.gpiochip, c.dc, c.reset, c.backlight, port.gpio->api);
    }
    memset(&ap, 0, sizeof ap);
    ap.name = c.bitbang ? "bit-banged SPI" : "spidev";
    ap.clock_hz = port.cfg.hz;
    ap.error = port_error;
    ap.report = port_report;
    ap.ctx = &port;
    rc = zs_app_run(&o, &port.bus, &ap, prog);
    zs_linux_close(&port);
    zs_app_free(&o);
    return rc;
}
