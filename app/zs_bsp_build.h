/* SPDX-License-Identifier: MIT */
/*
 * The host's BSP compiler (zspan-meshc --bsp, zspan-sim --order bsp, the
 * tests): builds a zs_bsp tree (zspan/priority.h) from a mesh in int16
 * positions, splitting the triangles that straddle a splitting plane.
 *
 * Splitters are the planes of the input triangles; at each node up to
 * `candidates` of them are scored by split_weight * splits + |front - back|
 * and the lowest wins (ties: the first); with the default weight, a tree whose
 * walk would need more than ZS_BSP_MAX_STACK entries is built again with the
 * weight halved (balance counts more) down to 1. A vertex within one position unit
 * of a plane counts as in it, so the roundings below never make a piece
 * straddle the plane that cut it.
 *
 * Split vertices are rounded to the int16 grid (at most sqrt(3)/2 units from
 * the exact point, reported as max_snap). Where rounding moves a split vertex
 * into its triangle, the thin triangle between the original edge and the
 * moved vertex is added (a sliver) so the pieces still cover all of the
 * original triangle: no cracks at T-junctions with neighbours that were not
 * cut at the same point.
 */
#ifndef ZSPAN_APP_BSP_BUILD_H
#define ZSPAN_APP_BSP_BUILD_H

#include <stddef.h>
#include <stdint.h>

#include "zspan/priority.h"

typedef struct zs_bspb_params {
    int split_weight; /* 0: 8 */
    int candidates;   /* splitters scored per node; 0: 24 */
} zs_bspb_params;

/* A mesh as arrays (optional ones NULL). */
typedef struct zs_bspb_mesh {
    int16_t *pos;    /* 3 per vertex */
    uint16_t *idx;   /* 3 per triangle */
    uint32_t *fcol;  /* per triangle */
    int16_t *fnrm;   /* 3 per triangle, Q14 */
    uint32_t *vcol;  /* per vertex */
    int16_t *vnrm;   /* 3 per vertex, Q14 */
    int16_t *uv;     /* 2 per vertex, Q3.12 (split vertices interpolate them) */
    size_t nv, nt;
} zs_bspb_mesh;

typedef struct zs_bspb_result {
    zs_bspb_mesh mesh;    /* the triangles in node order, split vertices appended */
    uint32_t *source;     /* per output triangle: the input triangle it is part of */
    uint8_t *is_split;    /* per output vertex: 1 if made by a split */
    zs_bsp_node *nodes;
    size_t node_count;
    size_t splits;        /* triangles (or pieces) cut by a plane */
    size_t slivers;       /* sliver triangles added */
    size_t dropped;       /* zero-area input triangles left out */
    int depth;            /* longest root-to-leaf path, nodes */
    int stack;            /* the walk's worst pending entries (<= ZS_BSP_MAX_STACK) */
    double max_snap;      /* largest rounding of a split vertex, position units */
    int split_weight;     /* the splitter score's weight the tree was built with */
} zs_bspb_result;

/* Builds the tree; returns NULL, or a message (out is then freed). The
 * limits: 65535 output vertices and triangles, 65534 nodes, a walk of at
 * most ZS_BSP_MAX_STACK pending entries. */
const char *zs_bspb_build(const zs_bspb_mesh *in, const zs_bspb_params *p, zs_bspb_result *out);
void zs_bspb_free(zs_bspb_result *r);

#endif /* ZSPAN_APP_BSP_BUILD_H */
