/* SPDX-License-Identifier: MIT */
/*
 * zspan list priority: visibility by the order of the triangles instead of
 * their depth.
 *
 * In ZS_MODE_PRIORITY the span walk keeps, at every column, the covering
 * triangle that was stored first (the lowest record number): no depth plane
 * is evaluated and no crossing is looked for. The image is right when the
 * triangles are stored nearest first, which the functions here arrange:
 *
 *  - zs_draw_bsp: a static mesh compiled into a BSP tree on the host
 *    (zspan-meshc --bsp, const arrays in flash). Each frame the tree is walked
 *    from the eye, near side first, and every node's triangles are stored in
 *    that order. A node's triangles whose plane faces away from the eye are
 *    skipped without being looked at (counted in zs_stats.bsp_pruned).
 *
 *  - zs_depth_sort: for dynamic triangles (ZS_CFG_PRIORITY), after the
 *    frame's draws: the stored records sorted by their farthest depth, and
 *    with ZS_SORT_NNS the Newell-Newell-Sancha tests on every pair whose
 *    depth ranges overlap (x extents, y extents, each plane's side test both
 *    ways, the screen triangles' overlap), moving a record ahead, or, for a
 *    cyclic or penetrating pair, cutting one by the other's plane (new
 *    records and vertices from the pools). ZS_SORT_DEPTH is the plain sort
 *    alone: fast and approximate, wrong wherever depth ranges overlap in
 *    the wrong way (long surfaces, cycles, penetrations).
 *
 * Freestanding like the rest of the core: the walk keeps a stack of at most
 * ZS_BSP_MAX_STACK + 3 entries (4 bytes each, 524 bytes) on the C stack and
 * nothing else. An entry stays pending on it only for a node with both a
 * near and a far side to come back to, so a long chain (a convex object:
 * every plane has the rest behind it) costs nothing; zs_bsp_check refuses a
 * tree whose walk could need more from any eye position.
 */
#ifndef ZSPAN_PRIORITY_H
#define ZSPAN_PRIORITY_H

#include "zspan/zspan.h"

#ifdef __cplusplus
extern "C" {
#endif

#define ZS_BSP_NONE 0xFFFFu
#define ZS_BSP_MAX_STACK 128         /* pending entries of the walk (see above) */
#define ZS_BSP_MAX_NORMAL (1L << 24) /* |n[k]| below this */
#define ZS_BSP_MAX_D ((int64_t)1 << 42) /* |d| below this */

/* A node: the plane n . p + d = 0 over the mesh's int16 positions p (model
 * position units, before the mesh scale); its front side is n . p + d > 0.
 * The node's own triangles lie in the plane: [first, first + n_front) of the
 * mesh face the front side (seen from there they are front faces), the next
 * n_back face the back side. Children are whole subtrees in preorder: front
 * is this node's index + 1 (or ZS_BSP_NONE), back comes after the front
 * subtree (or ZS_BSP_NONE). zs_bsp_check refuses anything else, so a tree
 * with a cycle or a shared node is never followed. */
typedef struct zs_bsp_node {
    int64_t d;
    int32_t n[3];
    uint16_t front, back;
    uint16_t first, n_front, n_back;
} zs_bsp_node;

/* A compiled mesh: its triangles ordered by node (zspan-meshc --bsp writes
 * both). */
typedef struct zs_bsp {
    const zs_bsp_node *nodes;
    const zs_mesh *mesh;
    uint16_t node_count;  /* 1 .. 65535 */
} zs_bsp;

/* ZS_OK for a well-formed tree; ZS_ERR_NULL for a NULL tree, node array or
 * mesh; ZS_ERR_BSP for a child out of range or out of preorder (cycles and
 * shared nodes included), a triangle range outside the mesh, a plane with
 * |n[k]| >= ZS_BSP_MAX_NORMAL or |d| >= ZS_BSP_MAX_D, or a path whose walk
 * could leave more than ZS_BSP_MAX_STACK entries pending: going down to the
 * front child costs one for a back child and one for a non-empty node range,
 * going down to the back child one for a front child and one for n_back > 0.
 * Work: one pass over the nodes. */
zs_status zs_bsp_check(const zs_bsp *bsp);

/* Stores the tree's triangles near side first from the camera's eye (the
 * frame's camera: its view must be a rotation and a translation, as
 * zs_camera_look_at makes). model: NULL (identity) or a rotation times a
 * uniform scale (at least 1/256) plus a translation; else ZS_ERR_ARGUMENT.
 * Checks the tree first (zs_bsp_check: a bad tree stores nothing). Tags are
 * the mesh's triangle numbers, as with zs_draw. Works in every mode; in
 * ZS_MODE_PRIORITY the order is the visibility. */
zs_status zs_draw_bsp(zs_renderer *r, const zs_bsp *bsp, const zs_mat34 *model);

typedef enum zs_sort_kind {
    ZS_SORT_DEPTH = 0, /* by farthest depth only (approximate) */
    ZS_SORT_NNS = 1    /* and the Newell-Newell-Sancha tests, splitting cycles */
} zs_sort_kind;

#define ZS_SORT_BUDGET_DEFAULT 65536u /* pair tests per frame when budget is 0 */

/* Reorders the frame's stored records near to far (record 0 wins in
 * ZS_MODE_PRIORITY); call after the last draw, before rendering. At most
 * `budget` pair tests (0: ZS_SORT_BUDGET_DEFAULT); past it the rest stays as
 * the plain sort left it (zs_stats.sort_giveups). Splits take records and
 * vertices from the pools; a pair that cannot be split for want of room is
 * left as it is (sort_giveups too). zs_stats: sort_pairs (pairs the first
 * tests could not clear), sort_swaps, sort_splits. ZS_ERR_MODE without
 * ZS_CFG_PRIORITY, ZS_ERR_ARGUMENT for another kind, ZS_ERR_STATE outside
 * the draws of a frame. Work: O(n log n) for the sort, then at most budget
 * pair tests (each a few hundred operations) and list moves of O(n). */
zs_status zs_depth_sort(zs_renderer *r, zs_sort_kind kind, uint32_t budget);

/* ---- painter's output (src/painter.c) ----
 * The same orders streamed back to front, for a caller with a full frame
 * buffer or a rasteriser of its own. Both read the frame's stored records
 * after the draws (and zs_depth_sort, if used): record 0 is the nearest, so
 * back to front is the highest record first. */

/* Paints the whole frame into buf (row y at buf + y * stride) in the frame's
 * byte format: the background, then every record from the last to record 0,
 * each over the centres the span walk gives it (top-left rule, the same
 * exact edge columns) with the same shading, so the image is the one
 * zs_render_rows gives in ZS_MODE_PRIORITY, byte for byte (a frame that
 * skipped records for want of active-pool room, stats.records_skipped, is
 * painted whole here). Call after the draws, instead of zs_render_rows; the
 * frame is then done (zs_pick still answers). Pixels are written once per
 * covering record plus once for the background: stats.pixels_shaded counts
 * the writes (the overdraw), stats.spans the runs. It uses one slot of the
 * active pool and no edges, so a renderer that only paints can be made with
 * max_active_edges 2 (a smaller arena). ZS_ERR_NULL, ZS_ERR_STATE outside the draws of a frame,
 * ZS_ERR_MODE for a frame not in ZS_MODE_PRIORITY or with the A-buffer on,
 * ZS_ERR_FORMAT for the 1-bit formats and ZS_FMT_GRAY4, ZS_ERR_BUFFER for a
 * stride below width * bytes per pixel (or height rows of it past the
 * address space). Work: one pass over the records, each row of each record
 * a span fill. */
zs_status zs_paint_frame(zs_renderer *r, void *buf, size_t stride);

/* The frame's records back to front (the painter's order) into
 * records[0 .. *count): *count is set to the record count in any case;
 * ZS_ERR_CAPACITY (nothing written) when it exceeds capacity. records may be
 * NULL with capacity 0 to ask for the count. Valid from zs_frame_begin until
 * the next one (the order is final once the draws and any zs_depth_sort are
 * done). ZS_ERR_NULL for r or count NULL, ZS_ERR_STATE with no frame begun. */
zs_status zs_priority_order(const zs_renderer *r, uint16_t *records, uint32_t capacity,
                            uint32_t *count);

/* A stored record as the renderer draws it. */
typedef struct zs_record_tri {
    int16_t x[3], y[3]; /* screen vertices, 28.4 pixels, y down (a front face:
                           counter-clockwise on the screen) */
    uint32_t z[3];      /* window depth, Q2.30 */
    uint32_t rgb[3];    /* colour at each vertex, RGB888 after light and fog (all
                           three the face colour in flat shading); in a
                           ZS_FMT_ID16 frame the tag */
} zs_record_tri;

/* Record `record` of the frame (0 .. stats.records - 1). ZS_ERR_NULL,
 * ZS_ERR_STATE with no frame begun, ZS_ERR_ARGUMENT for a record past the
 * stored ones. */
zs_status zs_record_get(const zs_renderer *r, uint32_t record, zs_record_tri *out);

#ifdef __cplusplus
}
#endif

#endif /* ZSPAN_PRIORITY_H */
