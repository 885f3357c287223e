/*
 * zspan-sim: shared declarations of the host simulator (not part of the core).
 * Host code may use floating point, malloc and stdio; src/ may not.
 */
#ifndef ZSPAN_SIM_H
#define ZSPAN_SIM_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "zspan/zspan.h"

/* Exit codes of zspan-sim. */
#define SIM_EXIT_OK 0
#define SIM_EXIT_FAIL 1   /* a file, the core or the output failed */
#define SIM_EXIT_USAGE 2  /* bad command line */

/* Subcommands. argv[0] is the subcommand name. */
int sim_cmd_demo(int argc, char **argv);
int sim_cmd_render(int argc, char **argv);
void sim_print_usage(FILE *f);

/* ---- extension subcommands ---------------------------------------------
 * A source added to the simulator by an mk file (SIM_EXTRA_SRCS) adds a
 * subcommand without touching sim_main.c:
 *
 *     static int run_panel(int argc, char **argv) { ... }   // argv[0] = "panel"
 *     SIM_COMMAND(panel, "panel", run_panel,
 *                 "  panel [options]       ...one or more lines for --help\n")
 *
 * (a constructor function registers it before main; GCC/Clang). Returns of
 * run are the exit status (SIM_EXIT_*). */
typedef struct sim_command {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *usage; /* text for --help, or NULL */
} sim_command;

void sim_register_command(const sim_command *cmd);

#define SIM_COMMAND(ident, name, run, usage)                                                  \
    static const sim_command sim_command_##ident = {name, run, usage};                        \
    __attribute__((constructor)) static void sim_command_register_##ident(void)               \
    {                                                                                         \
        sim_register_command(&sim_command_##ident);                                           \
    }

/* Program name in messages; the option parsers are app/zs_opts.h. */
#define SIM_PROG "zspan-sim"

/* ---- output ------------------------------------------------------------- */

void sim_print_stats(FILE *f, const zs_stats *s);
/* Creates the parent directories of path (like mkdir -p of its dirname). */
int sim_make_parent_dirs(const char *path);
/* FNV-1a 32-bit checksum. */
uint32_t sim_fnv1a(const void *data, size_t n);
const char *sim_mode_name(zs_visibility mode);

/* Renders the rest of the current frame into img (height rows of stride
 * bytes) band by band with zs_render_frame. */
zs_status sim_render_image(zs_renderer *r, uint8_t *img, size_t stride, int height,
                           int band_rows);

#endif /* ZSPAN_SIM_H */
