/* SPDX-License-Identifier: MIT */
/*
 * The built-in demo scene of zspan-sim: a tilted torus (smooth normals) that
 * sinks into a checkered ground, two cubes that cut into each other, a cube the
 * torus passes through and a pyramid standing in the ground, seen from above.
 *
 * Built procedurally from integers: no floating point, no malloc, only the core
 * API, so a firmware build can share this file (freestanding C99). Positions
 * are int16 with a Q16.16 scale per mesh, like a mesh kept in flash.
 *
 *     static demo_scene scene;                    // about 15 KB at 32 x 16
 *     demo_scene_init(&scene);
 *     demo_frame(&r, &scene, 0, ZS_MODE_SPAN, ZS_SHADE_GOURAUD, ZS_FMT_RGB565_BE);
 *     ... zs_render_rows / zs_render_frame ...
 *
 * Frame n orbits the camera 3 degrees per frame around the vertical axis
 * (frame 0 is the still image of `make demo`).
 */
#ifndef ZSPAN_DEMO_SCENE_H
#define ZSPAN_DEMO_SCENE_H

#include <stdint.h>

#include "zspan/zspan.h"

/* Torus resolution: segments around the ring and around the tube. Each must
 * divide 32 (angles are multiples of 11.25 degrees, from an exact table).
 * A small target can build with -DDEMO_TORUS_U=16 -DDEMO_TORUS_V=8. */
#ifndef DEMO_TORUS_U
#define DEMO_TORUS_U 32
#endif
#ifndef DEMO_TORUS_V
#define DEMO_TORUS_V 16
#endif
#ifndef DEMO_GROUND_N
#define DEMO_GROUND_N 12 /* ground tiles per side */
#endif

#define DEMO_TORUS_VERTS (DEMO_TORUS_U * DEMO_TORUS_V)
#define DEMO_TORUS_TRIS (2 * DEMO_TORUS_U * DEMO_TORUS_V)
#define DEMO_GROUND_VERTS ((DEMO_GROUND_N + 1) * (DEMO_GROUND_N + 1))
#define DEMO_GROUND_TRIS (2 * DEMO_GROUND_N * DEMO_GROUND_N)
#define DEMO_CUBES 3

/* Triangles and vertices the scene submits per frame (before culling and clipping). */
#define DEMO_TRIANGLES (DEMO_TORUS_TRIS + DEMO_GROUND_TRIS + DEMO_CUBES * 12 + 6)
#define DEMO_VERTICES (DEMO_TORUS_VERTS + DEMO_GROUND_VERTS + DEMO_CUBES * 8 + 5)

typedef struct demo_scene {
    int16_t torus_pos[3 * DEMO_TORUS_VERTS];
    int16_t torus_nrm[3 * DEMO_TORUS_VERTS];
    uint16_t torus_idx[3 * DEMO_TORUS_TRIS];
    int16_t ground_pos[3 * DEMO_GROUND_VERTS];
    uint16_t ground_idx[3 * DEMO_GROUND_TRIS];
    zs_color ground_col[DEMO_GROUND_TRIS];
    zs_mesh torus, ground, cubes[DEMO_CUBES], pyramid;
    zs_mat34 torus_model, cube_model[DEMO_CUBES], pyramid_model;
} demo_scene;

/* Builds the meshes and their placements. */
void demo_scene_init(demo_scene *s);

/* The camera of frame n (orbiting; frame 0 is the default view). */
zs_status demo_camera(zs_camera *cam, uint32_t frame);

/* The scene's look: two lights, ambient, background and distance fog. */
zs_shade_params demo_shading(zs_shading shading, zs_format format);

/* Submits every mesh of the scene (after zs_frame_begin / zs_frame_shading). */
zs_status demo_scene_draw(zs_renderer *r, const demo_scene *s);

/* All of a frame but the rows: camera, zs_frame_begin, zs_frame_shading and
 * demo_scene_draw. Then render the rows with zs_render_rows or zs_render_frame. */
/* demo_frame with the 1-bit options ZS_MONO_* (zs_shade_params.mono) of a
 * 1-bit or GRAY4 format. */
zs_status demo_frame_mono(zs_renderer *r, const demo_scene *s, uint32_t frame,
                          zs_visibility mode, zs_shading shading, zs_format format, unsigned mono);
zs_status demo_frame(zs_renderer *r, const demo_scene *s, uint32_t frame, zs_visibility mode,
                     zs_shading shading, zs_format format);

#endif /* ZSPAN_DEMO_SCENE_H */
