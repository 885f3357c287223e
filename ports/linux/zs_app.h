/*
 * The part of zspan-linux and zspan-mcp2210 that does not depend on the bus:
 * common options, the demo scene or a mesh file, the panel driver, full
 * frames (zs_panel_stream) or partial updates (only the rows that changed,
 * narrowed to the changed columns), timing and statistics.
 */
#ifndef ZSPAN_PORT_APP_H
#define ZSPAN_PORT_APP_H

#include <stdint.h>
#include <stdio.h>

#include "zspan/bus.h"
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
} zs_app_opts;

/* The bus's side, for messages and figures. */
typedef struct zs_app_port {
    const char *name;                        /* "spidev", "MCP2210" */
    uint32_t clock_hz;                       /* for the wire model */
    const char *(*error)(void *ctx);         /* why the bus failed */
    void (*report)(void *ctx, FILE *f);      /* port statistics, may be NULL */
    void *ctx;
} zs_app_port;

void zs_app_defaults(zs_app_opts *o, int argc);
/* Matches one common option at argv[*i]: 1 consumed (value too), 0 not a
 * common option, -1 bad value (message printed). */
int zs_app_option(int argc, char **argv, int *i, zs_app_opts *o, const char *prog);
extern const char zs_app_usage[];
void zs_app_list_panels(FILE *f);

/* "--name VALUE" or "--name=VALUE" at argv[*i]: 1 (value set, *i advanced),
 * 0 (another option), -1 (value missing, message printed). */
int zs_opt_value(int argc, char **argv, int *i, const char *name, const char **value,
                 const char *prog);
/* An integer in [lo, hi] (decimal or 0x hex); 0, or -1 with a message. */
int zs_opt_long(const char *prog, const char *opt, const char *s, long lo, long hi, long *out);

/* Runs the program on an open bus. Returns the exit status: 0 ok, 1 failure
 * (3 when the bus failed: device gone, I/O error). */
int zs_app_run(const zs_app_opts *o, zs_bus *bus, const zs_app_port *port, const char *prog);
void zs_app_free(zs_app_opts *o);

/* Exit status for a bus failure in the middle of the run. */
#define ZS_APP_EXIT_BUS 3

#endif
