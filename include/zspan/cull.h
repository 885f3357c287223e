/* SPDX-License-Identifier: MIT */
/*
 * zspan culling by bounding boxes: whole draws and whole groups of draws
 * left out before any of their vertices is transformed.
 *
 *  - zs_draw_bounded: one draw with its mesh's box (zs_mesh_bounds, or the
 *    converter's). If the box, placed by the model matrix, is wholly outside
 *    one plane of the view frustum, nothing is transformed; the triangles are
 *    counted as submitted and rejected (and in tris_untransformed, their
 *    vertices in verts_untransformed) and use their tags, so the frame is the
 *    same as with zs_draw.
 *  - zs_draw_cells: a static scene's objects grouped by a host-built tree of
 *    boxes (app/zs_cells_build.c: a k-d split or a uniform grid), emitted as
 *    const arrays. A cell outside the frustum is skipped with everything
 *    under it (zs_stats.cells_culled); the objects of the cells that remain
 *    go through zs_draw_bounded, in object order, so the image equals drawing
 *    every object with zs_draw in that order.
 *
 * The box test is conservative: a box is culled only when all 8 corners are
 * beyond one frustum plane by more than a margin (1/256 of w), larger than
 * any rounding of the transform.
 */
#ifndef ZSPAN_CULL_H
#define ZSPAN_CULL_H

#include "zspan/zspan.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A box in the mesh's int16 position units (before its scale). */
typedef struct zs_bounds {
    int16_t lo[3], hi[3];
} zs_bounds;

/* The box of a mesh's vertices (all zero for a mesh without any). */
void zs_mesh_bounds(const zs_mesh *mesh, zs_bounds *out);

/* zs_draw, first testing bounds (placed by model, NULL = identity) against
 * the frustum. bounds NULL: plain zs_draw. Errors as zs_draw (the mesh is
 * checked before the box is tested); lo > hi on an axis: ZS_ERR_ARGUMENT. */
zs_status zs_draw_bounded(zs_renderer *r, const zs_mesh *mesh, const zs_mat34 *model,
                          const zs_bounds *bounds);

/* One object of a scene: a mesh placed by a model matrix (NULL = identity),
 * with its mesh's box. */
typedef struct zs_scene_object {
    const zs_mesh *mesh;
    const zs_mat34 *model;
    zs_bounds bounds;
} zs_scene_object;

#define ZS_CELLS_MAX_DEPTH 24 /* cells on one root-to-leaf path */

/* A cell: a world box (Q16.16) holding objects [first_object, first_object +
 * object_count), its whole subtree's. A leaf (child_count 0) draws them; an
 * inner cell's children [first_child, first_child + child_count) split its
 * range among them in order. Layout (zs_cells_check refuses anything else):
 * cell 0 is the root; the children of cell i come right after those of the
 * cells before it (first_child of the first inner cell is 1, and so on), each
 * after its parent, so every cell but the root is a child once; a leaf's
 * objects come right after the previous leaf's in depth-first order. */
typedef struct zs_cell {
    zs_fixed lo[3], hi[3];
    uint16_t first_child, child_count;
    uint16_t first_object, object_count;
} zs_cell;

typedef struct zs_cells {
    const zs_cell *cells;
    const zs_scene_object *objects;
    uint16_t cell_count;   /* 1 .. 65535 */
    uint16_t object_count;
} zs_cells;

/* ZS_OK, ZS_ERR_NULL (a NULL array or object mesh), or ZS_ERR_BSP for a
 * layout other than the one above, a range out of bounds, a box with lo > hi
 * or a path longer than ZS_CELLS_MAX_DEPTH. One pass over cells and objects. */
zs_status zs_cells_check(const zs_cells *scene);

/* Checks the scene, then draws what the frustum can see (see above). The
 * first error of a draw stops it and is returned. */
zs_status zs_draw_cells(zs_renderer *r, const zs_cells *scene);

#ifdef __cplusplus
}
#endif

#endif /* ZSPAN_CULL_H */
