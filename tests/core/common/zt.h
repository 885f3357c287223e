/* SPDX-License-Identifier: MIT */
/*
 * zt: shared helpers for the zspan core test suites.
 *
 * Everything here is an oracle or a harness written independently of the
 * renderer: a fixed-seed PRNG, a collector for the setup hook, a half-space
 * reference rasterizer with the top-left rule on 28.4 coordinates, a
 * double-precision ray caster over the hook's snapped triangles, a scene
 * builder that places vertices by their intended screen position, and frame
 * rendering / image comparison helpers.
 */
#ifndef ZT_H
#define ZT_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "zspan/zspan.h"

/* ---------------- PRNG (splitmix64) ---------------- */

typedef struct zt_rng {
    uint64_t s;
} zt_rng;

void zt_rng_seed(zt_rng *g, uint64_t seed);
uint64_t zt_u64(zt_rng *g);
uint32_t zt_u32(zt_rng *g);
/* Uniform in [0, n) (n > 0). */
uint32_t zt_below(zt_rng *g, uint32_t n);
/* Uniform in [lo, hi], inclusive. */
int64_t zt_range(zt_rng *g, int64_t lo, int64_t hi);
/* Uniform in [0, 1). */
double zt_unit(zt_rng *g);
double zt_uniform(zt_rng *g, double lo, double hi);

/* ---------------- setup-hook collector ---------------- */

typedef struct zt_rec {
    uint16_t tag;
    uint32_t order;   /* call order of the hook (0-based) */
    int32_t xy[6];    /* 28.4, y down */
    uint32_t z[3];    /* Q2.30 */
} zt_rec;

typedef struct zt_recs {
    zt_rec *v;
    size_t n, cap;
} zt_recs;

/* Hook function: user must be a zt_recs*. */
void zt_recs_hook(void *user, uint16_t tag, const int32_t xy[6], const uint32_t z[3]);
void zt_recs_clear(zt_recs *rs);
void zt_recs_free(zt_recs *rs);

/* ---------------- reference rasterizer ---------------- */

/* Twice the signed area in 28.4 units squared (y down): > 0 for a triangle
 * that is clockwise on screen as drawn with y down. */
int64_t zt_area2(const int32_t xy[6]);
/* 1 if the centre of pixel (px, py) is inside the triangle by half-space edge
 * functions with the top-left rule (orientation independent); 0 otherwise
 * (also for zero area). */
int zt_covers(const int32_t xy[6], int px, int py);
/* Pixel bounding box that can contain covered centres, clipped to w x h.
 * Returns 0 if empty. Inclusive bounds. */
int zt_bbox(const int32_t xy[6], int w, int h, int *x0, int *y0, int *x1, int *y1);
/* Window depth of the triangle's plane (screen-space interpolation of the
 * three vertex depths) at the centre of pixel (px, py), in double. */
double zt_depth_at(const zt_rec *t, int px, int py);
/* Number of records covering each pixel (cnt has w*h entries). */
void zt_coverage_count(const zt_recs *rs, int w, int h, uint16_t *cnt);

/* ---------------- ray caster ---------------- */

typedef struct zt_cast {
    int w, h;
    uint16_t *owner;   /* tag of the nearest record, 0 = none */
    double *z1;        /* its depth */
    double *z2;        /* depth of the nearest record with another tag (or 2.0) */
    uint8_t *exact;    /* 1 if another tag's record has the same three
                          vertices (xy and z) as the nearest, in any order:
                          an exact tie that submission order decides (the
                          renderer builds planes from a canonical vertex
                          order); such records are left out of z2 */
    int32_t *best;     /* index of the nearest record, -1 = none */
} zt_cast;

/* Same three (x, y, z) vertices in any order. */
int zt_same_vertex_set(const zt_rec *a, const zt_rec *b);

void zt_cast_alloc(zt_cast *c, int w, int h);
void zt_cast_free(zt_cast *c);
/* Nearest surface at every pixel centre; exact double ties, and copies of a
 * record in any vertex order, go to the record hooked first. */
void zt_raycast(const zt_recs *rs, zt_cast *c);

/* ---------------- scene builder ---------------- */

/* World units per int16 position unit is 1/unit_div (scale = ZS_FX(1)/unit_div). */
typedef struct zt_scene {
    int w, h;
    int unit_div;
    int16_t *pos;
    uint16_t *idx;
    zs_color *fcol;
    zs_color *vcol;
    size_t nv, nt, capv, capt;
    int clamped;       /* positions that did not fit int16 */
} zt_scene;

void zt_scene_init(zt_scene *s, int w, int h, int unit_div);
void zt_scene_reset(zt_scene *s);
void zt_scene_free(zt_scene *s);
/* Adds a vertex at world (x, y, z) (units), returns its index. */
int zt_scene_vertex_world(zt_scene *s, double x, double y, double z, zs_color c);
/* Adds a vertex that the standard camera (see zt_camera_std) maps to pixel
 * position (px, py) (pixel units, y down, before snapping) at eye depth d > 0. */
int zt_scene_vertex_px(zt_scene *s, double px, double py, double d, zs_color c);
/* Adds a vertex on the eye-depth-1 plane that the standard camera maps
 * exactly to the 28.4 screen position (qx, qy) if the transform is exact.
 * Requires unit_div == 8 * h (then one position unit is 1/16 pixel). */
int zt_scene_vertex_q(zt_scene *s, int32_t qx, int32_t qy, zs_color c);
/* Adds a triangle as given. */
void zt_scene_tri(zt_scene *s, int a, int b, int c, zs_color fc);
/* Adds a triangle, reordered so that it is front-facing for the standard
 * camera if all three vertices are in front of it (by their world coords). */
void zt_scene_tri_front(zt_scene *s, int a, int b, int c, zs_color fc);
/* Mesh view of the scene (arrays stay owned by the scene). use_fcol/use_vcol
 * select the optional colour arrays. */
zs_mesh zt_scene_mesh(const zt_scene *s, int use_fcol, int use_vcol);
/* Resets s (w x h, unit_div 128) to one screen-filling quad of grey level v
 * (two front triangles 2 px past every edge, depth 2) and returns its mesh
 * with face colours. */
zs_mesh zt_scene_grey_quad(zt_scene *s, int w, int h, int v);
/* One light at random (a direction in front, intensity min_intensity ..
 * 1.5) and an ambient level of 0 .. 0.5, into sp. */
void zt_random_light(zt_rng *g, zs_shade_params *sp, zs_fixed min_intensity);
/* Pixel position of a world point under the standard camera (no snapping). */
void zt_world_to_px(int w, int h, double x, double y, double z, double *px, double *py);

/* Random scene content for the standard camera (see zt_scene_vertex_px),
 * appended to s: ntri triangles (approximately; pairs may add one more) made
 * of the kinds enabled in flags, random colours. near_d is the camera's near
 * distance (for the near-plane crossing kind). */
enum {
    ZT_SC_PLAIN = 1,    /* random triangles, per-vertex depth varies (penetrations) */
    ZT_SC_FLAT = 2,     /* triangles at one depth */
    ZT_SC_SHARED = 4,   /* abutting pairs sharing an edge (shared vertex indices) */
    ZT_SC_DUP = 8,      /* duplicates of earlier triangles: same indices, rotated
                           indices, or copied vertices */
    ZT_SC_NEAR = 16,    /* crossing the near plane or reaching behind the eye */
    ZT_SC_BIG = 32,     /* large tilted planes, partly off-screen */
    ZT_SC_LAYERS = 64,  /* overlapping stacked triangles whose vertex depths
                           are a few position units apart, some equal: depth
                           ranges that just touch, just miss or overlap */
    ZT_SC_ALL = 127
};
void zt_scene_random(zt_rng *g, zt_scene *s, int ntri, unsigned flags, double near_d);

/* Standard camera: eye at origin looking toward -Z, up +Y, fov 90 degrees. */
void zt_camera_std(zs_camera *cam, zs_fixed near_z, zs_fixed far_z);

/* ---------------- renderer harness ---------------- */

typedef struct zt_ctx {
    zs_renderer r;
    zs_config cfg;
    uint8_t *arena;
    size_t arena_size;
} zt_ctx;

/* Allocates exactly zs_arena_bytes(cfg) with malloc and inits; aborts the
 * test program on failure. */
void zt_ctx_init(zt_ctx *c, int w, int h, int max_tris, int max_verts, int max_edges);
/* The same with config flags (ZS_CFG_*). */
void zt_ctx_init_flags(zt_ctx *c, int w, int h, int max_tris, int max_verts, int max_edges,
                       uint16_t flags);
void zt_ctx_free(zt_ctx *c);
/* zs_frame_begin, zs_frame_shading(sp) and, when m is not NULL, zs_draw(m)
 * without a model matrix; the first status that is not ZS_OK, else ZS_OK. */
zs_status zt_begin(zt_ctx *c, const zs_camera *cam, zs_visibility mode,
                   const zs_shade_params *sp, const zs_mesh *m);

/* Renders the rest of the frame into img (w * bpp bytes per row, tight)
 * with zs_render_rows in bands of band rows (band >= h: whole frame in one
 * call). Returns the first non-OK status. */
zs_status zt_render_rows_all(zs_renderer *r, uint8_t *img, int w, int h, zs_format fmt,
                             int band);
/* Same through zs_render_frame with a band buffer and a copying callback. */
zs_status zt_render_frame_all(zs_renderer *r, uint8_t *img, int w, int h, zs_format fmt,
                              int band);

/* One whole frame: hook -> recs (if recs != NULL, cleared first),
 * frame_begin(mode), shading(sp or default with fmt ID16 if sp == NULL),
 * draw every mesh (model NULL), render with band rows. img must hold
 * w*h*bpp bytes. Returns the first non-OK status (draw errors included). */
zs_status zt_frame(zt_ctx *c, const zs_camera *cam, zs_visibility mode,
                   const zs_shade_params *sp, const zs_mesh *meshes, int nmesh,
                   zt_recs *recs, uint8_t *img, int band);

/* The visibility modes in a loop index 0, 1, 2: span, zline, Warnock. */
#define ZT_NMODES 3
#define ZT_MODE(i) ((zs_visibility)((i) == 2 ? ZS_MODE_WARNOCK : (i)))
#define ZT_MODE_NAME(i) ((i) == 2 ? "warnock" : (i) ? "zline" : "span")

/* ID16 pixel read (native order). */
uint16_t zt_id_at(const uint8_t *img, int w, int x, int y);

/* Index of the first differing byte, or -1. */
long zt_first_diff(const uint8_t *a, const uint8_t *b, size_t n);

/* Failure context printed by the suites. */
extern char zt_ctx_msg[512];

#endif
