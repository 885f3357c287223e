/* SPDX-License-Identifier: MIT */
/*
 * The standard benchmark scenes (freestanding C99: host and firmware).
 *
 * 240x240, RGB565 big-endian, flat unlit colours (one per triangle), back
 * faces culled, camera at the origin looking down -Z, vertical fov 60 degrees,
 * near 0.1, far 100; frames f = 0..9:
 *   sphere285  T(0,0,-3) * Ry(30 + 2f)            sphereWithHole.stl, normalised
 *   cubes      T(0,0,-8) * Rx(20) * Ry(30 + 2f)   64 unit cubes, 4x4x4, 1.5 apart
 *   wuson      T(0,0,-3) * Ry(30 + 2f)            WusonOBJ.obj, normalised
 *   cluster    T(0,0,-3) * Rx(20) * Ry(30 + 2f)   40 interpenetrating spikes
 *                                                 (bench/gen_cluster.c), normalised:
 *                                                 depth work, many active edges
 *
 * Frame checksum: FNV-1a 32 over the RGB565 big-endian bytes of all rows in
 * order (offset basis 0x811C9DC5, prime 0x01000193).
 */
#ifndef ZSPAN_BENCH_SCENES_H
#define ZSPAN_BENCH_SCENES_H

#include "zspan/zspan.h"

#define BENCH_W 240
#define BENCH_H 240
#define BENCH_FRAMES 10
#define BENCH_SCENE_COUNT 4
#define BENCH_FNV_BASIS 0x811C9DC5u

typedef struct bench_scene {
    const char *name;
    const zs_mesh *mesh;
    zs_fixed tz;          /* translation along z */
    zs_fixed rx_deg;      /* tilt about x (applied after the spin about y) */
    /* Pool capacities (from a host run, see bench_caps.h). */
    uint16_t max_triangles, max_vertices, max_active_edges;
} bench_scene;

extern const bench_scene bench_scenes[BENCH_SCENE_COUNT];

/* Model-view matrix of frame f. */
zs_mat34 bench_model_view(const bench_scene *s, int frame);
zs_config bench_config(const bench_scene *s);
/* Camera of every scene. */
zs_status bench_camera(zs_camera *cam);
/* zs_frame_begin + zs_draw for frame f (the caller renders the rows). */
zs_status bench_submit(zs_renderer *r, const zs_camera *cam, const bench_scene *s, int frame,
                       zs_visibility mode);
/* The 1-bit outputs in the host == M4 == M0 checksum test (frame 0 of a
 * scene, span mode): 0 "mono-bayer" (ZS_FMT_MONO_MSB rows, ordered dither),
 * 1 "mono-diffuse" (ZS_FMT_MONO_PAGE pages, error diffusion), 2 "mono-lines"
 * (pages, hidden lines), 3 "gray4" (ZS_FMT_GRAY4 rows, rounded), 4
 * "gray4-dither" (ZS_FMT_GRAY4, ordered dithering; issue 20). The renderer
 * needs ZS_CFG_MONO | ZS_CFG_LINES. The checksum is FNV-1a 32 over the rows
 * (MSB, GRAY4) or pages in order. */
#define BENCH_MONO_VARIANTS 5
extern const char *const bench_mono_names[BENCH_MONO_VARIANTS];
zs_status bench_mono_frame(zs_renderer *r, const zs_camera *cam, const bench_scene *s, int k,
                           uint32_t *sum);
/* The textured scene in the host == M4 == M0 checksum test and the bench: a
 * ground trapezoid 1.2..30 units ahead with its texture repeated and a
 * textured cube of side 1.2 at T(0, -0.25, -3.5) * Rx(20) * Ry(30), RGB565
 * big-endian rows; variant k: 0 "tex-plain" (the same untextured, flat
 * colours: the baseline), 1 "tex-nearest" (64 x 64 RGB565, nearest, exact,
 * unlit), 2 "tex-nearest-zline" (1 in z-buffer mode: the same bytes),
 * 3 "tex-subdiv" (1 subdivided), 4 "tex-bilinear" (bilinear, exact, flat
 * lit), 5 "tex-lit-fog" (32 x 32 palette, bilinear, subdivided, clamped,
 * Gouraud lit with vertex colours, fog). The renderer: bench_tex_config().
 * The checksum is FNV-1a 32 over the rows in order; covered (may be NULL)
 * gets the number of pixels that are not the background (the bench's
 * textured pixels). */
#define BENCH_TEX_VARIANTS 6
extern const char *const bench_tex_names[BENCH_TEX_VARIANTS];
zs_config bench_tex_config(void);
zs_status bench_tex_frame(zs_renderer *r, const zs_camera *cam, int k, uint32_t *sum,
                          uint32_t *covered);
/* Warnock mode and the A-buffer in the host == M4 == M0 checksum test: the
 * textured scene's geometry in flat colours (as "tex-plain"), variant k: 0
 * "warnock" (ZS_MODE_WARNOCK: the same bytes as "tex-plain"), 1 "aa-edges"
 * (span mode, ZS_AA_EDGES), 2 "aa-transparent" (ZS_AA_TRANSPARENT, the cube
 * at opacity 160 over the ground). The renderer: bench_extra_config() (pools
 * for the scene, with ZS_CFG_ABUFFER). The checksum as
 * bench_tex_frame's. */
#define BENCH_EXTRA_VARIANTS 3
extern const char *const bench_extra_names[BENCH_EXTRA_VARIANTS];
zs_config bench_extra_config(void);
zs_status bench_extra_frame(zs_renderer *r, const zs_camera *cam, int k, uint32_t *sum);
/* FNV-1a 32 of n bytes, continuing from h. */
uint32_t bench_fnv1a(uint32_t h, const uint8_t *p, size_t n);

#endif
