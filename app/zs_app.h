/* SPDX-License-Identifier: MIT */
/*
 * The frame loop of the programs that drive a panel (zspan-sim panel on an
 * emulated panel, zspan-linux, zspan-mcp2210): their common options, the
 * demo scene or mesh files, the panel driver, full frames (zs_panel_stream)
 * or partial updates (only the rows that changed, narrowed to the changed
 * columns), timing and statistics. The bus is the caller's.
 */
#ifndef ZSPAN_APP_H
#define ZSPAN_APP_H

#include <stdint.h>
#include <stdio.h>

#include "zspan/bus.h"
#include "zspan/panel.h"
#include "zspan/zspan.h"

typedef struct zs_app_opts {
    const char *panel;
    long rotation;
    zs_format format;
    int format_set;
    const char **meshes;
    int nmeshes;
    long frames;          /* 0 = until interrupted */
    long band;            /* rows per band */
    double spin;          /* degrees per frame */
    long start_frame;     /* first demo frame (0 = the still image of make demo) */
    zs_visibility mode;
    zs_shading shade;
    int partial;          /* send only the rows that changed */
    int quiet;
    int list;
    long backlight;       /* 0..255 */
    const char *dump;     /* write the last frame as sent (wire format, raw) */
    int flip_winding;     /* --mesh files with clockwise triangles */
    int two_sided;        /* draw the meshes' back faces too */
    int up_axis;          /* the mesh files' up axis (zs_opt_up_axis) */
    unsigned mono;        /* 1-bit panels: ZS_MONO_DIFFUSE (--diffuse), ZS_MONO_LINES
                             (--lines); 0 ordered dithering */
} zs_app_opts;

/* What the loop reports after each frame. */
typedef struct zs_app_frame {
    long index;
    double seconds;                        /* scene, rendering and sending */
    uint32_t bytes;                        /* on the bus */
    long rows;                             /* rows sent */
    const zs_panel_frame_stats *stream;    /* full frames: the driver's figures; else NULL */
    const zs_stats *stats;                 /* the renderer's */
} zs_app_frame;

/* The bus's side, for messages and figures. Unused members are zero. */
typedef struct zs_app_port {
    const char *name;                        /* "spidev", "MCP2210" */
    uint32_t clock_hz;                       /* for the wire model (0: the panel's rating) */
    int async;                               /* the bus returns before the bytes are out:
                                                render the next band into a second buffer */
    const char *(*error)(void *ctx);         /* why the bus failed */
    void (*report)(void *ctx, FILE *f);      /* port statistics, may be NULL */
    /* After the panel's init and the renderer's setup, before frame 0;
     * non-zero stops the run (exit status 1). May be NULL. */
    int (*ready)(void *ctx, const zs_panel *lcd, const zs_wire_model *wire);
    /* After every frame sent; non-zero ends the run (successfully). May be NULL. */
    int (*frame_done)(void *ctx, const zs_app_frame *f);
    void *ctx;
} zs_app_port;

/* A program's own part of the command line. */
typedef struct zs_app_cli {
    const char *prog;
    void (*usage)(FILE *f);                  /* --help */
    /* Its option at argv[*i], as zs_app_option: 1 consumed, 0 unknown, -1 bad. */
    int (*option)(void *cfg, int argc, char **argv, int *i);
    void *cfg;
    /* The program's own defaults, set over zs_app_defaults' before the
     * arguments are read. May be NULL. */
    void (*defaults)(zs_app_opts *o);
} zs_app_cli;

/* zs_app_parse's result when the program should go on and run. */
#define ZS_APP_PARSED (-1)

/* Defaults, then every argument: --help, the common options, the program's.
 * Returns ZS_APP_PARSED, or the exit status after --help or --list (0), a
 * bad command line (2) or no memory (1); then o is already freed. */
int zs_app_parse(zs_app_opts *o, int argc, char **argv, const zs_app_cli *cli);

/* Checks what the options name before any device is opened: the panel
 * exists and takes the wire format. 0, or -1 after a message naming the
 * option (zs_app_parse calls it). */
int zs_app_check(const zs_app_opts *o, const char *prog);

/* The wire format: --format, else the panel's first of RGB565 (big-endian),
 * RGB666 and 1-bit pages. */
zs_format zs_app_wire_format(const zs_app_opts *o, const zs_panel_desc *d);

/* Defaults; argc bounds the number of --mesh options. */
void zs_app_defaults(zs_app_opts *o, int argc);
/* Matches one common option at argv[*i]: 1 consumed (value too), 0 not a
 * common option, -1 bad value (message printed). */
int zs_app_option(int argc, char **argv, int *i, zs_app_opts *o, const char *prog);
void zs_app_free(zs_app_opts *o);
/* Help text of the common options. */
#define ZS_APP_USAGE                                                                          \
    "Panel and picture:\n"                                                                    \
    "  --panel NAME          st7789-240x240 (default); --list shows the panels\n"            \
    "  --rotation 0..3       quarter turns clockwise (default 0)\n"                          \
    "  --format rgb565|rgb666  wire pixel format (default rgb565; ili9488: rgb666)\n"        \
    "  --mesh FILE           a mesh file (assimp formats; repeatable) instead of the demo\n" \
    "  --flip-winding, --two-sided, --up-axis AXIS\n"                                    \
    "                        the mesh files' triangles are clockwise; draw back faces;\n" \
    "                        their up axis (x, y, z, -x, -y, -z; default auto)\n"          \
    "  --frames N            frames to send (default 1; 0 = until Ctrl-C)\n"                 \
    "  --start N             first demo frame (default 0)\n"                                 \
    "  --spin DEG            turn per frame (demo: camera orbit, multiples of 3; default 3)\n" \
    "  --mode span|zline     visibility (default span)\n"                                    \
    "  --shade flat|gouraud  shading (default gouraud)\n"                                    \
    "  --band N              rows per band (default 16)\n"                                   \
    "  --partial             after the first frame send only the rows that changed\n"        \
    "                        (narrowed to the changed columns; not on 1-bit panels)\n"       \
    "  --diffuse, --lines    1-bit panels: error diffusion, or a hidden-line drawing,\n"     \
    "                        instead of ordered dithering\n"                                  \
    "  --brightness 0..255   backlight level (GPIO backlight: 0 off, else on; default 255)\n" \
    "  --quiet               only errors\n"                                            \
    "  --help, --version\n"
/* The panels the drivers know, with sizes, clocks and wire formats. */
void zs_app_list_panels(FILE *f);

/* Runs the program on an open bus. Returns the exit status: 0 ok, 1 failure,
 * 2 unknown panel or format, 3 (ZS_APP_EXIT_BUS) the bus failed mid-run. */
int zs_app_run(const zs_app_opts *o, zs_bus *bus, const zs_app_port *port, const char *prog);

/* Exit status for a bus failure in the middle of the run. */
#define ZS_APP_EXIT_BUS 3

#endif /* ZSPAN_APP_H */
