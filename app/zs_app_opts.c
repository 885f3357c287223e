/* SPDX-License-Identifier: MIT */
/* Common options of the panel programs and the panel list (see zs_app.h). */
#include "zs_app.h"

#include <stdlib.h>
#include <string.h>

#include "zs_opts.h"

void zs_app_defaults(zs_app_opts *o, int argc)
{
    memset(o, 0, sizeof *o);
    o->panel = "st7789-240x240";
    o->frames = 1;
    o->band = 16;
    o->spin = 3.0;
    o->mode = ZS_MODE_SPAN;
    o->shade = ZS_SHADE_GOURAUD;
    o->backlight = 255;
    o->meshes = calloc((size_t)argc + 1, sizeof *o->meshes);
}

void zs_app_free(zs_app_opts *o)
{
    free(o->meshes);
    o->meshes = NULL;
}

int zs_app_option(int argc, char **argv, int *i, zs_app_opts *o, const char *prog)
{
    const char *a = argv[*i], *v;
    int m;

    if (strcmp(a, "--partial") == 0) { o->partial = 1; return 1; }
    if (strcmp(a, "--quiet") == 0) { o->quiet = 1; return 1; }
    if (strcmp(a, "--list") == 0) { o->list = 1; return 1; }
    if (strcmp(a, "--flip-winding") == 0) { o->flip_winding = 1; return 1; }
    if (strcmp(a, "--two-sided") == 0) { o->two_sided = 1; return 1; }
    if (strcmp(a, "--diffuse") == 0) { o->mono = ZS_MONO_DIFFUSE; return 1; }
    if (strcmp(a, "--lines") == 0) { o->mono = ZS_MONO_LINES; return 1; }
    if ((m = zs_opt_value(argc, argv, i, "--up-axis", &v, prog)) != 0)
        return m < 0 || zs_opt_up_axis(prog, "--up-axis", v, &o->up_axis) != 0 ? -1 : 1;
#define LONG_OPT(name, lo, hi, field)                                                          \
    if ((m = zs_opt_long_at(argc, argv, i, name, lo, hi, &o->field, prog)) != 0)               \
        return m;
    LONG_OPT("--rotation", 0, 3, rotation)
    LONG_OPT("--frames", 0, 100000000L, frames)
    LONG_OPT("--start", 0, 1000000L, start_frame)
    LONG_OPT("--band", 1, 2048, band)
    LONG_OPT("--brightness", 0, 255, backlight)
#undef LONG_OPT
    if ((m = zs_opt_value(argc, argv, i, "--panel", &o->panel, prog)) != 0)
        return m;
    if ((m = zs_opt_value(argc, argv, i, "--mesh", &v, prog)) != 0) {
        if (m > 0)
            o->meshes[o->nmeshes++] = v;
        return m;
    }
    if ((m = zs_opt_value(argc, argv, i, "--spin", &v, prog)) != 0) {
        if (m < 0 || zs_opt_double(prog, "--spin", v, &o->spin) != 0)
            return -1;
        if (!(o->spin > -3600.0 && o->spin < 3600.0)) {
            fprintf(stderr, "%s: --spin: %g is outside -3600..3600 degrees\n", prog, o->spin);
            return -1;
        }
        return 1;
    }
    if ((m = zs_opt_value(argc, argv, i, "--format", &v, prog)) != 0) {
        if (m < 0 || zs_opt_wire_format(prog, v, &o->format) != 0)
            return -1;
        o->format_set = 1;
        return 1;
    }
    if ((m = zs_opt_value(argc, argv, i, "--mode", &v, prog)) != 0)
        return m < 0 || zs_opt_mode(prog, v, &o->mode) != 0 ? -1 : 1;
    if ((m = zs_opt_value(argc, argv, i, "--shade", &v, prog)) != 0)
        return m < 0 || zs_opt_shade(prog, v, &o->shade) != 0 ? -1 : 1;
    return 0;
}

int zs_app_parse(zs_app_opts *o, int argc, char **argv, const zs_app_cli *cli)
{
    int i, m;

    zs_app_defaults(o, argc);
    if (o->meshes == NULL)
        return 1;
    if (cli->defaults != NULL)
        cli->defaults(o);
    for (i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            cli->usage(stdout);
            zs_app_free(o);
            return 0;
        }
        if (zs_opt_version(argv[i], cli->prog)) {
            zs_app_free(o);
            return 0;
        }
        m = zs_app_option(argc, argv, &i, o, cli->prog);
        if (m == 0)
            m = cli->option(cli->cfg, argc, argv, &i);
        if (m == 0)
            fprintf(stderr, "%s: unknown option '%s' (see --help)\n", cli->prog, argv[i]);
        if (m <= 0) {
            zs_app_free(o);
            return 2;
        }
    }
    if (o->list) {
        zs_app_list_panels(stdout);
        zs_app_free(o);
        return 0;
    }
    if (zs_app_check(o, cli->prog) != 0) {
        zs_app_free(o);
        return 2;
    }
    return ZS_APP_PARSED;
}

zs_format zs_app_wire_format(const zs_app_opts *o, const zs_panel_desc *d)
{
    if (o->format_set)
        return o->format;
    if (zs_panel_supports(d, ZS_FMT_RGB565_BE))
        return ZS_FMT_RGB565_BE;
    if (zs_panel_supports(d, ZS_FMT_RGB666))
        return ZS_FMT_RGB666;
    return ZS_FMT_MONO_PAGE;
}

int zs_app_check(const zs_app_opts *o, const char *prog)
{
    const zs_panel_desc *d = zs_panel_find(o->panel);
    zs_format fmt;

    if (d == NULL) {
        fprintf(stderr, "%s: --panel: unknown panel '%s' (--list shows them)\n", prog, o->panel);
        return -1;
    }
    fmt = zs_app_wire_format(o, d);
    if (!zs_panel_supports(d, fmt)) {
        fprintf(stderr, "%s: --format: %s does not take %s\n", prog, d->name,
                fmt == ZS_FMT_RGB565_BE ? "rgb565" : fmt == ZS_FMT_RGB666 ? "rgb666" : "1-bit pages");
        return -1;
    }
    if (fmt == ZS_FMT_MONO_PAGE && o->partial) {
        fprintf(stderr, "%s: --partial: not on a 1-bit panel (%s)\n", prog, d->name);
        return -1;
    }
    if (fmt != ZS_FMT_MONO_PAGE && o->mono) {
        fprintf(stderr, "%s: --diffuse and --lines are for 1-bit panels, not %s\n", prog,
                d->name);
        return -1;
    }
    return 0;
}

void zs_app_list_panels(FILE *f)
{
    unsigned i;

    fprintf(f, "%-16s %-9s %-10s %-8s %s\n", "panel", "size", "RAM", "clock", "formats");
    for (i = 0; i < zs_panel_count(); i++) {
        const zs_panel_desc *d = zs_panel_at(i);
        char size[24], ram[24];
        snprintf(size, sizeof size, "%ux%u", d->width, d->height);
        snprintf(ram, sizeof ram, "%ux%u", d->ram_width, d->ram_height);
        fprintf(f, "%-16s %-9s %-10s %4.1f MHz %s%s%s%s%s\n", d->name, size, ram,
                d->max_spi_hz / 1e6, zs_panel_bytes_per_pixel(d, ZS_FMT_RGB565_BE) ? "rgb565 " : "",
                zs_panel_bytes_per_pixel(d, ZS_FMT_RGB666) ? "rgb666" : "",
                zs_panel_supports(d, ZS_FMT_MONO_PAGE) ? "1-bit pages" : "",
                zs_panel_supports(d, ZS_FMT_MONO_MSB) ? "1-bit rows" : "",
                zs_panel_supports(d, ZS_FMT_GRAY4) ? "4-bit grey" : "");
    }
}
