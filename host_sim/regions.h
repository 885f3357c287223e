/* SPDX-License-Identifier: MIT */
/* zspan-sim render --svg: the exact visible region of every triangle record,
 * on the host in double precision (host_sim/regions.c). */
#ifndef SIM_REGIONS_H
#define SIM_REGIONS_H

#include <stddef.h>
#include <stdint.h>

#include "raycast.h"

#define SIM_VR_MAX_VERTS 64 /* a convex piece: a triangle cut by lines, clipped */

typedef struct sim_vr_piece {
    int n;
    double x[SIM_VR_MAX_VERTS], y[SIM_VR_MAX_VERTS]; /* pixels, y down, positive area */
} sim_vr_piece;

/* The visible region of one record: the union of disjoint convex pieces. */
typedef struct sim_vr_region {
    sim_vr_piece *p;
    size_t n, cap;
    double area; /* px^2 */
} sim_vr_region;

typedef struct sim_vr_result {
    size_t n;             /* one region per record */
    sim_vr_region *r;
    double area;          /* sum of the regions' areas */
    unsigned long clips;  /* clip polygons subtracted */
    unsigned long overflow; /* pieces that had more corners than SIM_VR_MAX_VERTS (0) */
} sim_vr_result;

/* Each record's triangle, within the screen [0, w] x [0, h], less every part
 * of another record in front of it there (nearer by the planes through the
 * window depths; equal planes: the one submitted first is in front).
 * Returns 0, -1 out of memory, -2 when a piece had too many corners. */
int sim_vr_compute(const sim_rc_set *s, int w, int h, sim_vr_result *out);
void sim_vr_free(sim_vr_result *res);
/* One filled path per non-empty region (its pieces as subpaths), colour
 * rgb[i] (0xRRGGBB) for record i, data-tag its tag, over a background
 * rectangle. Returns 0 or -1. */
int sim_vr_write_svg(const char *path, const sim_vr_result *res, const sim_rc_set *s,
                     const uint32_t *rgb, uint32_t background, int w, int h);

#endif
