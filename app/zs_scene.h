/* SPDX-License-Identifier: MIT */
/*
 * The scene of the animated programs (zspan-sim panel, zspan-linux,
 * zspan-mcp2210): the built-in demo scene, or mesh files fitted to the unit
 * sphere and turning about y. Built with ZS_APP_NO_MESH there is no mesh
 * loading (no assimp), only the demo.
 */
#ifndef ZSPAN_APP_SCENE_H
#define ZSPAN_APP_SCENE_H

#include <stdint.h>

#include "demo_scene.h"
#include "zs_model.h"
#include "zspan/zspan.h"

typedef struct zs_scene {
    demo_scene *demo;   /* the demo, or NULL */
    zs_model model;     /* else the meshes */
    uint32_t max_tris;  /* triangle pool a frame needs (clipping splits some) */
    unsigned mono;      /* ZS_MONO_* options of the frames' 1-bit format (0 none) */
} zs_scene;

/* The demo (nmeshes == 0) or the mesh files, with normals for Gouraud.
 * Returns 0, or -1 after a message. */
int zs_scene_load(zs_scene *s, const char *const *meshes, int nmeshes, zs_shading shade,
                  const char *prog);
/* The same with the meshes' winding (flip), back faces (two_sided) and up
 * axis (ZS_UP_* of zs_model.h). */
int zs_scene_load_meshes(zs_scene *s, const char *const *meshes, int nmeshes, zs_shading shade,
                         int flip, int two_sided, int up_axis, const char *prog);

/* Begins frame k: the demo's camera orbit from frame `start`, spin degrees
 * per frame in steps of 3 (at least one step when spin > 0), or the meshes
 * turned by spin x (start + k) degrees. The caller renders the rows. */
zs_status zs_scene_frame(zs_renderer *r, const zs_scene *s, long start, long k, double spin,
                         zs_visibility mode, zs_shading shade, zs_format fmt);

void zs_scene_free(zs_scene *s);

#endif /* ZSPAN_APP_SCENE_H */
