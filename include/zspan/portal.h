/* SPDX-License-Identifier: MIT */
/*
 * zspan portals: draw only the cells of an indoor level that the eye can see.
 *
 * A level is a 2.5D floor plan split into convex cells (rooms) joined by
 * portals (openings). A host tool (tools/zspan-level) precomputes, for every
 * cell, its potentially visible set (PVS: the cells some sightline from
 * anywhere in the cell reaches through a chain of portals, Teller and Sequin)
 * and emits the level as the const arrays below. At run time
 * zs_level_draw finds the eye's cell, takes its PVS and narrows it further by
 * walking the portals from the eye with a shrinking screen-space window: a
 * portal is followed only if the eye is on its near side and its projection
 * meets the window the walk came through. Only the cells that survive are
 * submitted (zs_draw, one mesh per cell, in cell order, so the image equals
 * that of drawing every cell).
 *
 * Freestanding like the rest of the core. The walk uses a fixed stack of at
 * most ZS_LEVEL_MAX_DEPTH entries (14 bytes each) and a bitset of
 * ZS_LEVEL_MAX_CELLS bits, both on the C stack (about 800 bytes); nothing
 * else.
 *
 * Coordinates: a level's plan point (x, y) at height h (level units, int16)
 * is the world point (x * unit, h * unit, -y * unit), unit in Q16.16 (the
 * meshes' scale). Seen from above (+Y), x runs right and plan y up, so a
 * plan polygon that is counter-clockwise is counter-clockwise on screen too.
 */
#ifndef ZSPAN_PORTAL_H
#define ZSPAN_PORTAL_H

#include "zspan/zspan.h"

#ifdef __cplusplus
extern "C" {
#endif

#define ZS_LEVEL_MAX_CELLS 1024   /* cells in a level */
#define ZS_LEVEL_MAX_DEPTH 48     /* portals in one chain of the walk */
#define ZS_LEVEL_MAX_COORD 16384  /* |plan coordinate| and |height|, level units */
#define ZS_LEVEL_WALK_BUDGET 4096 /* portal tests per frame before the walk gives
                                     up and draws the whole PVS */
#define ZS_LEVEL_MARGIN_PX 2      /* pixels added around every portal's projection */

/* A portal as seen from the cell it leaves: its plan endpoints a -> b run
 * counter-clockwise along that cell's boundary (the cell is on the left of
 * a -> b), its opening spans heights [bottom, top], and it leads into cell
 * `to`. */
typedef struct zs_level_portal {
    int16_t ax, ay, bx, by;
    int16_t bottom, top;
    uint16_t to;
} zs_level_portal;

/* A convex cell: its plan polygon (counter-clockwise, vertex_count points
 * from first_vertex of zs_level.vertices), the portals leaving it
 * (portal_count from first_portal of zs_level.portals) and its floor and
 * ceiling heights. */
typedef struct zs_level_cell {
    uint16_t first_vertex, vertex_count;
    uint16_t first_portal, portal_count;
    int16_t floor, ceiling;
} zs_level_cell;

typedef struct zs_level {
    uint16_t cell_count;                 /* 1..ZS_LEVEL_MAX_CELLS */
    uint16_t portal_count;               /* directed portals (two per opening) */
    uint16_t vertex_count;               /* plan points, 2 int16 each */
    zs_fixed unit;                       /* world units per level unit, Q16.16 > 0 */
    const int16_t *vertices;             /* x, y pairs */
    const zs_level_cell *cells;
    const zs_level_portal *portals;
    const uint8_t *pvs;                  /* cell_count rows of (cell_count + 7) / 8
                                            bytes; bit j (byte j / 8, bit j % 8) of
                                            row i: cell j is potentially visible
                                            from cell i */
    const zs_mesh *meshes;               /* one per cell, scale == unit */
} zs_level;

/* What zs_level_draw submits. */
typedef enum zs_level_cull {
    ZS_LEVEL_CULL_NONE = 0,    /* every cell */
    ZS_LEVEL_CULL_PVS = 1,     /* the eye cell's PVS */
    ZS_LEVEL_CULL_PORTALS = 2  /* the PVS narrowed by the portal walk */
} zs_level_cull;

typedef struct zs_level_stats {
    int32_t eye_cell;          /* the eye's cell, -1 if none (then every cell is drawn) */
    uint32_t pvs_cells;        /* cells in its PVS */
    uint32_t cells_visited;    /* cells entered by the walk (the eye cell included;
                                  a cell reached along two chains counts twice) */
    uint32_t portals_tested;   /* portals the walk looked at */
    uint32_t cells_drawn;      /* meshes submitted */
    uint32_t tris_submitted;   /* their triangles */
    uint32_t tris_culled;      /* triangles of the cells left out: never transformed */
    uint8_t fallback;          /* the walk hit ZS_LEVEL_WALK_BUDGET or ZS_LEVEL_MAX_DEPTH,
                                  so the whole PVS was drawn */
} zs_level_stats;

/* Checks a level: counts within limits, non-NULL arrays, every index in
 * range, cells convex and counter-clockwise with floor < ceiling, portals
 * leading to another existing cell with bottom < top, world coordinates
 * within +-32767 units, and a PVS whose rows contain their own cell and every
 * neighbour with no bit set past cell_count. ZS_ERR_NULL for a NULL level,
 * ZS_ERR_LEVEL for anything else wrong; ZS_OK otherwise. */
zs_status zs_level_check(const zs_level *lv);

/* The cell whose plan polygon (boundary included) holds the eye and whose
 * floor..ceiling holds its height; the first such cell, or -1. The level
 * must have passed zs_level_check. */
int32_t zs_level_find_cell(const zs_level *lv, zs_vec3 eye);

/* Submits the level's cells for the open frame of r (after zs_frame_begin,
 * zs_frame_shading if any, before rendering), each with the identity model
 * matrix. eye is the camera's position (the one given to zs_camera_look_at).
 * stats may be NULL. Checks the level first (zs_level_check: nothing is
 * submitted if it fails) and returns the first zs_draw error, if any.
 * ZS_ERR_ARGUMENT for an unknown cull. The eye should stay farther than the
 * near plane's half diagonal from every wall, as for any camera: nearer, a
 * wall is clipped away and what lies behind it differs from drawing every
 * cell. */
zs_status zs_level_draw(zs_renderer *r, const zs_level *lv, zs_vec3 eye, zs_level_cull cull,
                        zs_level_stats *stats);

/* Projects a world point with the open frame's camera (the matrices
 * zs_frame_begin set up): xy[0], xy[1] in pixels, Q16.16 (x right, y down,
 * pixel centres at +0.5, clamped to +-2^14 pixels) and *depth the eye
 * distance along the view axis (Q16.16). ZS_ERR_NULL for a NULL pointer,
 * ZS_ERR_STATE before the first zs_frame_begin, ZS_ERR_ARGUMENT when the
 * point is nearer than the near plane (*depth is set, xy is not). */
zs_status zs_project_point(const zs_renderer *r, zs_vec3 world, zs_fixed xy[2], zs_fixed *depth);

#ifdef __cplusplus
}
#endif

#endif /* ZSPAN_PORTAL_H */
