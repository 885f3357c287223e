/* SPDX-License-Identifier: MIT */
/*
 * Vector hidden-line drawing on the host (double precision): the visible
 * parts of a scene's feature edges as screen-space segments, for
 * `zspan-sim render --svg-lines FILE`.
 *
 * Feature edges, per mesh (group) from its indices: boundary edges of a
 * front face, silhouettes (one face front, the other back) and creases (both
 * front, normals more than the crease angle apart). Each is clipped to the
 * near plane and then against every front face of the scene in screen space:
 * where the segment's projection is inside a face and the face is nearer
 * (1/w is affine along the segment and over each face), that interval is
 * hidden. What is left is exact up to double rounding (quantitative
 * invisibility by interval subtraction). Where front faces of two meshes
 * cut into each other, the segment they share (a boundary between draw
 * calls, as the core draws it) is clipped the same way.
 *
 * The camera is the core's: eye space, looking down -z, vertical field of
 * view fov; pixel centres at +0.5, y down.
 */
#ifndef ZSPAN_APP_HLINES_H
#define ZSPAN_APP_HLINES_H

#include <stddef.h>
#include <stdint.h>

typedef struct zs_hl_view {
    int width, height;
    double fov_deg;      /* vertical */
    double near_z;       /* > 0 */
    double crease_deg;   /* 0 = 30 */
} zs_hl_view;

typedef struct zs_hl_seg {
    double x0, y0, x1, y1; /* pixels, y down */
} zs_hl_seg;

typedef struct zs_hl_result {
    zs_hl_seg *seg;
    size_t n, cap;
    size_t feature_edges;  /* edges that were clipped */
    size_t meeting_lines;  /* segments where two meshes' faces meet, clipped */
} zs_hl_result;

/* pos: 3 per vertex in eye space; idx: 3 per triangle (counter-clockwise
 * front); group: per vertex... per triangle the mesh it belongs to (edges
 * join only triangles of one group, through shared vertex indices).
 * Returns 0, or -1 when out of memory. */
int zs_hl_compute(const zs_hl_view *v, const double *pos, size_t nverts, const uint32_t *idx,
                  const int *group, size_t ntris, zs_hl_result *out);
void zs_hl_free(zs_hl_result *r);

/* Screen position of an eye-space point (z < 0). */
void zs_hl_project(const zs_hl_view *v, const double p[3], double *x, double *y);

/* An SVG of the segments (black on white, crisp edges, 1 px wide); 0 on
 * success. */
int zs_hl_write_svg(const char *path, const zs_hl_view *v, const zs_hl_result *r);

#endif
