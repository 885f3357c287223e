/* SPDX-License-Identifier: MIT */
/*
 * Host side of zspan's portal levels (not part of the core): the level file
 * format (parse, check, write), random maze and building generators, the
 * cell meshes, Teller-Sequin PVS precomputation and the C emitter. Used by
 * tools/zspan-level.c, host_sim/walk_cmd.c and tests/tools/test_level.c.
 * The format is described in README.md (Portal levels).
 */
#ifndef ZSPAN_TOOLS_LEVEL_H
#define ZSPAN_TOOLS_LEVEL_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "zspan/portal.h"

typedef struct lv_cell {
    int floor, ceiling;
    int nv;
    int *v;          /* vertex indices, counter-clockwise */
    int *edge_kind;  /* per edge v[i] -> v[i+1]: -1 wall, else the index of its portal */
} lv_cell;

/* An opening between cells a and b on their shared edge va - vb. */
typedef struct lv_portal {
    int a, b, va, vb;
    int line;
} lv_portal;

typedef struct lv_wall {
    int va, vb;
    int line;
} lv_wall;

typedef struct lv_level {
    int unit;                    /* level units per world unit (power of two, 1..256) */
    int nverts, ncells, nwalls, nportals;
    int (*xy)[2];
    lv_cell *cells;
    lv_wall *walls;
    lv_portal *portals;
} lv_level;

/* Parses and checks a level file's text. name labels the messages
 * ("NAME:LINE: ..."). Returns 0, or -1 with a message in err. */
int lv_parse(const char *text, const char *name, lv_level *lv, char *err, size_t errlen);
int lv_load(const char *path, lv_level *lv, char *err, size_t errlen);
/* Checks what lv_parse checks after parsing (closed cells, portals on shared
 * edges, no overlaps); fills edge_kind. */
int lv_check(lv_level *lv, char *err, size_t errlen);
void lv_free(lv_level *lv);
int lv_write(FILE *f, const lv_level *lv);

typedef enum lv_kind { LV_MAZE, LV_BUILDING } lv_kind;
/* A random level of cols x rows cells; the same seed gives the same level. */
void lv_generate(lv_level *lv, lv_kind kind, int cols, int rows, uint32_t seed);

/* PVS: ncells rows of (ncells + 7) / 8 bytes (zs_level's layout). */
typedef struct lv_pvs_stats {
    uint64_t sequences;   /* portal sequences tested */
    uint64_t stabbable;   /* of which some line stabs */
    int max_depth;
} lv_pvs_stats;
uint8_t *lv_compute_pvs(const lv_level *lv, lv_pvs_stats *stats);
/* Exact test: is there a line with every left point on its left (or on it)
 * and every right point on its right (or on it)? Points are integer pairs. */
int lv_stabbable(const int (*left)[2], int nl, const int (*right)[2], int nr);

/* The level as the core's arrays, built in memory. */
typedef struct lv_built {
    zs_level level;
    int16_t *vertices;
    zs_level_cell *cells;
    zs_level_portal *portals;
    uint8_t *pvs;
    zs_mesh *meshes;
    int16_t **positions;
    uint16_t **indices;
    zs_color **colors;
    int total_tris;
} lv_built;
/* pvs is taken over (freed by lv_built_free). Returns 0, or -1 with err. */
int lv_build(const lv_level *lv, uint8_t *pvs, lv_built *out, char *err, size_t errlen);
void lv_built_free(lv_built *b);
/* A scripted flight (world coordinates) of `frames` eye and target points:
 * from cell 0 to the cell farthest from it, through the portals' midpoints.
 * Returns 0, or -1 if no height is open in every cell. */
int lv_flight(const zs_level *lv, int frames, double (*eye)[3], double (*target)[3]);

/* C source defining `const zs_level NAME` and its arrays. */
int lv_emit_c(FILE *f, const lv_built *b, const char *name);

#endif
