/* SPDX-License-Identifier: MIT */
/*
 * Renderer sizing of the host programs: pool capacities from what a scene
 * submits, and the renderer set up in a malloc'd arena of that size.
 */
#ifndef ZSPAN_APP_ARENA_H
#define ZSPAN_APP_ARENA_H

#include <stddef.h>

#include "zspan/zspan.h"

/* A width x height configuration with room for tris stored triangles (capped
 * at ZS_MAX_TRIANGLES), verts vertices (0: three per triangle, capped at
 * ZS_MAX_VERTICES) and edges active edges (0: ZS_MAX_ACTIVE_EDGES). */
zs_config zs_app_config(int width, int height, unsigned long tris, unsigned long verts,
                        unsigned long edges);

/* Allocates the arena cfg needs (*bytes = its size) and zs_init()s r in it.
 * Returns the arena, to free() when done, or NULL after printing why. */
void *zs_app_renderer(zs_renderer *r, const zs_config *cfg, size_t *bytes, const char *prog);

#endif /* ZSPAN_APP_ARENA_H */
