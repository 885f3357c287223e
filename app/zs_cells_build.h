/* SPDX-License-Identifier: MIT */
/*
 * The host's builder of scene cells (zs_draw_cells, zspan/cull.h): groups a
 * static scene's objects by their world boxes into a tree of cells, either
 * a k-d split (the cell's objects halved at the median centre along the box's
 * longest axis until at most leaf_size remain) or a uniform grid (one level:
 * grid x grid columns over x and z). The objects come out reordered so that
 * each cell's are contiguous; draw them in that order.
 */
#ifndef ZSPAN_APP_CELLS_BUILD_H
#define ZSPAN_APP_CELLS_BUILD_H

#include <stddef.h>
#include <stdint.h>

#include "zspan/cull.h"

enum { ZS_CELLS_KD = 0, ZS_CELLS_GRID = 1 };

/* The default, by measurement (bench/priority.md, "Scene cells"): a k-d tree
 * with leaves of 4 objects culled with the fewest instructions per frame on
 * both scenes measured, on M4 and M0 (city of 244 objects: 0.97 M on M4 vs
 * 0.99 M for the best grid; forest of 1,000: 1.16 M vs 1.61 M, where a grid
 * of at most 8 x 8 columns leaves 16 objects a column to test). */
#define ZS_CELLS_DEFAULT_KIND ZS_CELLS_KD
#define ZS_CELLS_DEFAULT_PARAM 4

typedef struct zs_cellsb_result {
    zs_cell *cells;
    size_t cell_count;
    uint32_t *order; /* order[k]: the input object that is object k of the cells */
    int depth;
} zs_cellsb_result;

/* lo, hi: 3 doubles per object (world units). kind ZS_CELLS_KD (param: leaf
 * size, >= 1) or ZS_CELLS_GRID (param: columns per side, >= 1). Returns NULL
 * or a message. */
const char *zs_cellsb_build(const double *lo, const double *hi, size_t n, int kind, int param,
                            zs_cellsb_result *out);
void zs_cellsb_free(zs_cellsb_result *r);

#endif /* ZSPAN_APP_CELLS_BUILD_H */
