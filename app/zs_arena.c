/* SPDX-License-Identifier: MIT */
/* Renderer sizing of the host programs (see zs_arena.h). */
#include "zs_arena.h"

#include <stdio.h>
#include <stdlib.h>

zs_config zs_app_config(int width, int height, unsigned long tris, unsigned long verts,
                        unsigned long edges)
{
    if (tris > ZS_MAX_TRIANGLES)
        tris = ZS_MAX_TRIANGLES;
    if (verts == 0)
        verts = tris * 3u;
    if (verts > ZS_MAX_VERTICES)
        verts = ZS_MAX_VERTICES;
    if (edges == 0)
        edges = ZS_MAX_ACTIVE_EDGES;
    return zs_config_default((uint16_t)width, (uint16_t)height, (uint16_t)tris,
                             (uint16_t)verts, (uint16_t)edges);
}

void *zs_app_renderer(zs_renderer *r, const zs_config *cfg, size_t *bytes, const char *prog)
{
    void *arena;
    zs_status st;

    *bytes = zs_arena_bytes(cfg);
    if (*bytes == 0) {
        fprintf(stderr, "%s: zs_arena_bytes: invalid configuration\n", prog);
        return NULL;
    }
    arena = malloc(*bytes);
    if (arena == NULL) {
        fprintf(stderr, "%s: cannot allocate an arena of %lu bytes\n", prog,
                (unsigned long)*bytes);
        return NULL;
    }
    st = zs_init(r, arena, *bytes, cfg);
    if (st != ZS_OK) {
        fprintf(stderr, "%s: zs_init: %s\n", prog, zs_strerror(st));
        free(arena);
        return NULL;
    }
    return arena;
}
