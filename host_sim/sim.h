/* SPDX-License-Identifier: MIT */
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
void sim_print_demo_usage(FILE *f);
void sim_print_render_usage(FILE *f);

/* ---- the subcommands' command lines ------------------------------------
 * Each parser checks every option (ranges, files to write) before anything
 * is loaded or opened and returns 0 (go on), SIM_EXIT_USAGE after a message,
 * or SIM_EXIT_OK with done set after --help or --version. */

enum { SHADE_FLAT, SHADE_GOURAUD, SHADE_IDS };

#define SIM_DEMO_OUT "out/demo.png"
#define SIM_RENDER_OUT "out/render.png"

typedef struct sim_demo_opts {
    const char *out;
    int out_set;
    zs_visibility mode;
    zs_shading shading;
    int width, height, compare, done;
    long frame, band;
} sim_demo_opts;

int sim_demo_parse(int argc, char **argv, sim_demo_opts *o);

/* zspan-sim render --order: how priority mode gets its order (zspan/priority.h) */
enum { SIM_ORDER_SUBMIT = 0, SIM_ORDER_BSP, SIM_ORDER_NNS, SIM_ORDER_SORT };

typedef struct sim_render_opts {
    const char **files;
    int nfiles;
    int width, height;
    double fov, near_z, far_z;
    double eye[3], target[3], up[3];
    double rot[3];
    int has_rot;
    int fit;
    int smooth;
    int flip_winding;     /* the files' triangles are clockwise */
    int two_sided;        /* draw back faces too */
    int up_axis;          /* ZS_UP_* of app/zs_model.h: the files' up axis */
    zs_visibility mode;
    int order;            /* --order (priority mode): SIM_ORDER_* */
    int painter;          /* --painter: zs_paint_frame into the whole image */
    int cells;            /* --cells: 0 none, 1 + ZS_CELLS_KD or ZS_CELLS_GRID */
    int shade;
    const char *out;
    int out_set;
    const char *dump;
    const char *svg_lines; /* --svg-lines FILE: the visible feature edges as SVG */
    int raycast;          /* --mode raycast: visibility by a host ray caster */
    long grid;            /* --grid N: its cells, N x N pixels (0: none) */
    const char *svg;      /* --svg FILE: the visible regions (Weiler-Atherton) */
    zs_color background;
    int has_light;
    double light[4];
    int has_ambient;
    double ambient;
    int unlit;
    int fog;
    double fog_start, fog_end;
    zs_color fog_color;
    long band;
    long max_tris, max_verts, max_edges;
    int aa;               /* --aa: anti-aliased edges (the A-buffer) */
    int n_opacity;        /* --opacity A1,A2,...: per draw in file order (the last repeats) */
    uint8_t opacity[16];
    int quiet;
    int textures;         /* --textures: the materials' diffuse textures (assimp files) */
    long tex_size;        /* --texture-size N (power of two) */
    int tex_bilinear;     /* --texture-filter bilinear */
    int done;             /* --help or --version was answered */
    /* Checked conversions of the camera options. */
    zs_vec3 q_eye, q_target, q_up;
    zs_fixed q_fov, q_near, q_far, q_ambient;
} sim_render_opts;

int sim_render_parse(int argc, char **argv, sim_render_opts *o);

/* --cells (host_sim/cells_draw.c): the scene's chunks as scene cells of kind
 * (app/zs_cells_build.h) drawn with zs_draw_cells; *cell_count the cells. */
struct zs_model;
zs_status sim_draw_cells(zs_renderer *r, const struct zs_model *scene, const zs_mat34 *model,
                         int kind, size_t *cell_count);
void sim_render_opts_free(sim_render_opts *o);

/* zspan-sim panel's parser (host_sim/panel_cmd.c) run on its own, for the
 * fuzz harness: the same results; the options are freed. */
int sim_panel_parse_check(int argc, char **argv);

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
/* Creates the parent directories of path (like mkdir -p of its dirname);
 * only for the default output paths (out/...): a path the user gives is
 * used as it is. */
int sim_make_parent_dirs(const char *path);
/* Checks an output path the user gave (opt names the option): not too
 * long, its directory exists. 0, or -1 after a message. */
int sim_check_output(const char *path, const char *opt);
/* FNV-1a 32-bit checksum. */
uint32_t sim_fnv1a(const void *data, size_t n);
const char *sim_mode_name(zs_visibility mode);

/* Renders the rest of the current frame into img (height rows of stride
 * bytes) band by band with zs_render_frame. */
zs_status sim_render_image(zs_renderer *r, uint8_t *img, size_t stride, int height,
                           int band_rows);

#endif /* ZSPAN_SIM_H */
