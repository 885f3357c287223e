/* SPDX-License-Identifier: MIT */
/*
 * zspan: a fixed-point, no-malloc visible-surface renderer that draws a 3D
 * triangle scene one row (or band of rows) at a time into a caller's buffer.
 *
 * Freestanding C99. No floating point, no allocation: every byte the renderer
 * uses lives in one arena the caller provides; ZS_ARENA_BYTES() gives its size
 * at compile time.
 *
 * One frame: a triangle, RGB565 rows one at a time (this example is cut out
 * of the header, compiled and run by make test: check-header-example):
 *
 *     #include <string.h>
 *     #include "zspan/zspan.h"
 *
 *     void send_row(int y, const uint8_t *row, size_t bytes); // to the panel
 *
 *     static const int16_t tri_pos[] = {-256, -256, 0, 256, -256, 0, 0, 256, 0};
 *     static const uint16_t tri_idx[] = {0, 1, 2}; // counter-clockwise: front
 *     static uint8_t arena[ZS_ARENA_BYTES(240, 240, 1000, 800, 256)];
 *
 *     zs_status draw_frame(void)
 *     {
 *         static zs_renderer r;
 *         static uint8_t line[240 * 2]; // RGB565 big-endian, the default format
 *         zs_config cfg = zs_config_default(240, 240, 1000, 800, 256);
 *         zs_camera cam;
 *         zs_mesh mesh;
 *         zs_mat34 model = zs_mat34_translate(0, 0, ZS_FX(-3));
 *         zs_status st;
 *         int y;
 *
 *         if ((st = zs_init(&r, arena, sizeof arena, &cfg)) != ZS_OK)
 *             return st;
 *         memset(&cam, 0, sizeof cam);
 *         st = zs_camera_look_at(&cam, zs_vec3_make(0, 0, 0), zs_vec3_make(0, 0, ZS_FX(-1)),
 *                                zs_vec3_make(0, ZS_FX(1), 0));
 *         if (st == ZS_OK)
 *             st = zs_camera_perspective(&cam, ZS_FX(60), ZS_FX(1) / 10, ZS_FX(100));
 *         if (st != ZS_OK)
 *             return st;
 *
 *         memset(&mesh, 0, sizeof mesh);
 *         mesh.positions = tri_pos;       // int16 units of mesh.scale
 *         mesh.indices = tri_idx;
 *         mesh.scale = ZS_FX(1) / 256;
 *         mesh.vertex_count = 3;
 *         mesh.triangle_count = 1;
 *         mesh.color = ZS_RGB(255, 160, 0);
 *
 *         if ((st = zs_frame_begin(&r, &cam, ZS_MODE_SPAN)) != ZS_OK ||
 *             (st = zs_draw(&r, &mesh, &model)) != ZS_OK) // any number of draws
 *             return st;
 *         for (y = 0; y < 240; y++) {
 *             if ((st = zs_render_rows(&r, y, 1, line, sizeof line)) != ZS_OK)
 *                 return st;
 *             send_row(y, line, sizeof line);
 *         }
 *         return ZS_OK;
 *     }
 *
 * Conventions
 *  - Q16.16 fixed point (zs_fixed) for world quantities; ZS_FX(n) makes one.
 *  - Right-handed world; the camera looks down its -Z; counter-clockwise
 *    triangles (as seen by the camera) are front faces, others are culled.
 *  - Screen: x right, y down, pixel (i, j) has its centre at (i + 0.5, j + 0.5).
 *    Vertices are snapped to 1/16 pixel (28.4). Top-left fill rule: a pixel
 *    whose centre lies exactly on a left or top edge belongs to the triangle.
 *  - Depth: window depth z in [0, 1] (0 at the near plane, 1 at the far plane),
 *    held per vertex in Q2.30 (ZS_DEPTH_ONE == 1.0) and interpolated as a plane
 *    in screen space. Smaller is nearer. Exact ties go to the triangle that was
 *    submitted first, in both visibility modes.
 *  - Every range in this API is half-open [start, end) unless it says
 *    "inclusive".
 */
#ifndef ZSPAN_ZSPAN_H
#define ZSPAN_ZSPAN_H

/* Version of the library (semantic versioning; 0.x: the API may still change
 * between minor versions). CHANGELOG.md lists what changed. */
#define ZSPAN_VERSION_MAJOR 0
#define ZSPAN_VERSION_MINOR 5
#define ZSPAN_VERSION_PATCH 0
#define ZSPAN_VERSION_STRING "0.5.0"

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------ */
/* Compile-time feature selection                                       */
/* ------------------------------------------------------------------ */

/* Build src/ with -DZS_NO_<feature> (or -DZS_LEAN for all of them) and link
 * with -ffunction-sections -fdata-sections -Wl,--gc-sections: the left-out
 * stage is never called, so the linker drops its code (`make check-lean`
 * checks it and measures the footprint). Asking for a left-out feature at
 * run time is refused, never half done: a config flag is ZS_ERR_ARGUMENT
 * from zs_init (as an unknown bit), a mode ZS_ERR_MODE, a pixel format
 * ZS_ERR_FORMAT (as an unknown one).
 *   ZS_NO_TEXTURE   texture mapping (texture.c): ZS_CFG_TEXTURE refused; a
 *                   mesh with uvs or a texture is ZS_ERR_MODE from zs_draw
 *   ZS_NO_ABUFFER   the A-buffer (abuffer.c): ZS_CFG_ABUFFER refused;
 *                   zs_frame_antialias and zs_draw_opacity say ZS_ERR_MODE
 *   ZS_NO_ZLINE     the z-buffer line (zline.c): ZS_MODE_ZLINE is ZS_ERR_MODE
 *   ZS_NO_WARNOCK   area subdivision (warnock.c): ZS_MODE_WARNOCK is ZS_ERR_MODE
 *   ZS_NO_PRIORITY  list priority (priority.c, bsp.c, depth_sort.c):
 *                   ZS_MODE_PRIORITY is ZS_ERR_MODE, ZS_CFG_PRIORITY and
 *                   ZS_CFG_PRIORITY_ONLY refused, zs_draw_bsp ZS_ERR_MODE
 *   ZS_NO_GOURAUD   per-vertex colour and fog (the colour planes of shade.c):
 *                   ZS_SHADE_GOURAUD or fog is ZS_ERR_MODE from
 *                   zs_frame_shading, as with ZS_CFG_FLAT_ONLY (flat and lit
 *                   faces work; textures still light through their planes)
 *   ZS_NO_MONO      the 1-bit formats, hidden lines and ZS_FMT_GRAY4
 *                   (mono.c, lines.c, gray4.c): those formats are ZS_ERR_FORMAT,
 *                   ZS_CFG_MONO and ZS_CFG_LINES refused
 *   ZS_RGB565_ONLY  the byte formats but ZS_FMT_RGB565_BE and ZS_FMT_RGB565
 *                   (RGB666, GRAY8, RGB888, ID16) are ZS_ERR_FORMAT
 *   ZS_LEAN         all of the above: flat (and lit) faces, span mode, RGB565
 *   ZS_NO_LIGHTING  (not in ZS_LEAN) lighting: colours are drawn as they are;
 *                   zs_frame_shading says ZS_ERR_MODE for a light or an ambient
 *                   other than 1.0
 * A left-out feature changes no image of the others: a lean build renders
 * byte for byte what a full one does for what it supports. Give the same
 * -D to the files of your own that test ZS_HAS_* or ZS_CFG_FLAGS_OK. */
#ifdef ZS_LEAN
#ifndef ZS_NO_TEXTURE
#define ZS_NO_TEXTURE
#endif
#ifndef ZS_NO_ABUFFER
#define ZS_NO_ABUFFER
#endif
#ifndef ZS_NO_ZLINE
#define ZS_NO_ZLINE
#endif
#ifndef ZS_NO_WARNOCK
#define ZS_NO_WARNOCK
#endif
#ifndef ZS_NO_PRIORITY
#define ZS_NO_PRIORITY
#endif
#ifndef ZS_NO_GOURAUD
#define ZS_NO_GOURAUD
#endif
#ifndef ZS_NO_MONO
#define ZS_NO_MONO
#endif
#ifndef ZS_RGB565_ONLY
#define ZS_RGB565_ONLY
#endif
#endif
/* 1 if this build has the feature, else 0: for plain `if`s the compiler folds. */
#ifdef ZS_NO_TEXTURE
#define ZS_HAS_TEXTURE 0
#else
#define ZS_HAS_TEXTURE 1
#endif
#ifdef ZS_NO_ABUFFER
#define ZS_HAS_ABUFFER 0
#else
#define ZS_HAS_ABUFFER 1
#endif
#ifdef ZS_NO_ZLINE
#define ZS_HAS_ZLINE 0
#else
#define ZS_HAS_ZLINE 1
#endif
#ifdef ZS_NO_WARNOCK
#define ZS_HAS_WARNOCK 0
#else
#define ZS_HAS_WARNOCK 1
#endif
#ifdef ZS_NO_PRIORITY
#define ZS_HAS_PRIORITY 0
#else
#define ZS_HAS_PRIORITY 1
#endif
#ifdef ZS_NO_GOURAUD
#define ZS_HAS_GOURAUD 0
#else
#define ZS_HAS_GOURAUD 1
#endif
#ifdef ZS_NO_MONO
#define ZS_HAS_MONO 0
#else
#define ZS_HAS_MONO 1
#endif
#ifdef ZS_RGB565_ONLY
#define ZS_HAS_FORMATS 0
#else
#define ZS_HAS_FORMATS 1
#endif
#ifdef ZS_NO_LIGHTING
#define ZS_HAS_LIGHTING 0
#else
#define ZS_HAS_LIGHTING 1
#endif
/* Internal to src/: 1 in a ZS_LEAN build, where the core takes the smaller of
 * two paths that give the same results (one triangle-setup loop, one
 * projection, no whole-mesh shortcuts): the same images and statistics in
 * fewer bytes, for some more instructions. Not a switch of its own. */
#ifdef ZS_LEAN
#define ZS_SMALL_ 1
#else
#define ZS_SMALL_ 0
#endif

/* ------------------------------------------------------------------ */
/* Fixed point                                                          */
/* ------------------------------------------------------------------ */

typedef int32_t zs_fixed;                 /* Q16.16 */
#define ZS_FX_SHIFT 16
#define ZS_FX_ONE ((zs_fixed)65536)
/* Integer n as Q16.16 (|n| < 32768). */
#define ZS_FX(n) ((zs_fixed)((n) * 65536))
/* Rational a/b as Q16.16, rounded toward zero; for constants. */
#define ZS_FX_RATIO(a, b) ((zs_fixed)(((int64_t)(a) * 65536) / (b)))
#define ZS_DEPTH_ONE ((uint32_t)1 << 30)  /* window depth 1.0 in Q2.30 */

typedef struct zs_vec3 {
    zs_fixed x, y, z;
} zs_vec3;

/* Affine transform, Q16.16, row-major: p' = M[0..2][0..2] * p + M[.][3]. */
typedef struct zs_mat34 {
    zs_fixed m[3][4];
} zs_mat34;

zs_vec3 zs_vec3_make(zs_fixed x, zs_fixed y, zs_fixed z);
/* Q16.16 multiply, rounded to nearest (halves up), saturated to the int32
 * range. (Inside the pipeline coordinates saturate symmetrically to
 * +-INT32_MAX so that negating them is always defined.) */
zs_fixed zs_fx_mul(zs_fixed a, zs_fixed b);
/* Q16.16 divide, rounded toward zero, saturated; b == 0 gives +-INT32_MAX. */
zs_fixed zs_fx_div(zs_fixed a, zs_fixed b);
/* Sine and cosine of an angle in Q16.16 degrees (any value), result Q16.16. */
zs_fixed zs_fx_sin_deg(zs_fixed deg);
zs_fixed zs_fx_cos_deg(zs_fixed deg);
/* Floor of the square root of a 64-bit unsigned integer. */
uint32_t zs_isqrt64(uint64_t v);

zs_mat34 zs_mat34_identity(void);
/* out = a * b (apply b first), saturated. */
zs_mat34 zs_mat34_mul(const zs_mat34 *a, const zs_mat34 *b);
zs_mat34 zs_mat34_translate(zs_fixed x, zs_fixed y, zs_fixed z);
zs_mat34 zs_mat34_scale(zs_fixed sx, zs_fixed sy, zs_fixed sz);
/* Rotations by an angle in Q16.16 degrees, counter-clockwise looking down the
 * axis toward the origin (right-handed). */
zs_mat34 zs_mat34_rotate_x(zs_fixed deg);
zs_mat34 zs_mat34_rotate_y(zs_fixed deg);
zs_mat34 zs_mat34_rotate_z(zs_fixed deg);
zs_vec3 zs_mat34_apply(const zs_mat34 *m, zs_vec3 p);

/* ------------------------------------------------------------------ */
/* Errors                                                               */
/* ------------------------------------------------------------------ */

typedef enum zs_status {
    ZS_OK = 0,
    ZS_ERR_NULL,          /* a required pointer argument is NULL */
    ZS_ERR_SIZE,          /* width/height zero or above ZS_MAX_DIM */
    ZS_ERR_CAPACITY,      /* a capacity is zero or above its limit */
    ZS_ERR_ARENA_SMALL,   /* arena smaller than zs_arena_bytes() */
    ZS_ERR_CAMERA,        /* eye == target, up parallel to view, or bad projection */
    ZS_ERR_FOV,           /* field of view not in (0, 180) degrees */
    ZS_ERR_DEPTH_RANGE,   /* near <= 0 or far <= near */
    ZS_ERR_MESH,          /* mesh with no positions/indices, or a zero scale */
    ZS_ERR_INDEX,         /* a triangle index >= vertex_count (draw rejected whole) */
    ZS_ERR_STATE,         /* call out of order (e.g. draw before frame_begin) */
    ZS_ERR_ROW,           /* row range outside the screen or before the next row */
    ZS_ERR_BUFFER,        /* buffer stride too small for the width and format */
    ZS_ERR_FORMAT,        /* unknown pixel format */
    ZS_ERR_MODE,          /* unknown visibility or shading mode, or one the
                             config's flags left out */
    ZS_ERR_ARGUMENT,      /* any other argument out of its documented range */
    ZS_ERR_LEVEL,         /* malformed level or PVS data (zspan/portal.h) */
    ZS_ERR_TEXTURE,       /* bad texture: see zs_texture_check */
    ZS_ERR_BSP,           /* malformed BSP tree or scene cells (zspan/priority.h) */
    ZS_STATUS_COUNT
} zs_status;

/* A short English description of a status code; never NULL. */
const char *zs_strerror(zs_status status);

/* ------------------------------------------------------------------ */
/* Capacities and the arena                                             */
/* ------------------------------------------------------------------ */

#define ZS_MAX_DIM 1024          /* width and height limit, pixels */
#define ZS_MAX_TRIANGLES 65535   /* per frame, after clipping */
#define ZS_MAX_VERTICES 65535    /* per frame, including clip-made vertices */
#define ZS_MAX_ACTIVE_EDGES 4096 /* edge sides crossing one row (2 per triangle) */

/* zs_config.flags: leave out what a build does not use, to save RAM. */
#define ZS_CFG_NO_ZLINE 0x01u    /* no z-buffer line: ZS_MODE_ZLINE is refused */
#define ZS_CFG_FLAT_ONLY 0x02u   /* no per-vertex colour or fog: ZS_SHADE_GOURAUD
                                    and fog are refused (flat and lit faces work) */
/* Features a build adds (they cost arena only when asked for): */
#define ZS_CFG_MONO 0x04u        /* 1-bit output (ZS_FMT_MONO_*) and ZS_FMT_GRAY4: a
                                    grey scratch line and one line of diffusion
                                    error, 3 B per column */
#define ZS_CFG_LINES 0x08u       /* hidden-line drawing (ZS_MONO_LINES): two lines of
                                    triangle ids and two flag lines (6 B per column,
                                    4 B with ZS_CFG_MONO, whose lines it shares), a normal, three
                                    links and a draw-start bit per triangle record
                                    (14 B + 1 bit) and a link per vertex (2 B) */
#define ZS_CFG_PRIORITY 0x40u    /* depth sorting for ZS_MODE_PRIORITY (zs_depth_sort,
                                    zspan/priority.h): a list and a work word per
                                    triangle record, 4 B */
#define ZS_CFG_TEXTURE 0x10u     /* texture mapping (zs_mesh.uvs, zs_mesh.texture):
                                    6 B per vertex, ZS_ACTIVE_TEX_BYTES per active
                                    triangle (and the shade words and colour
                                    planes even with ZS_CFG_FLAT_ONLY), a table of
                                    ZS_MAX_FRAME_TEXTURES texture pointers; not
                                    with ZS_CFG_ABUFFER (ZS_ERR_ARGUMENT) */

#define ZS_CFG_ABUFFER 0x20u     /* A-buffer anti-aliasing and transparency
                                    (zs_frame_antialias): ZS_ABUFFER_BYTES */
#define ZS_CFG_PRIORITY_ONLY 0x80u /* list priority alone: no depth plane per active
                                    triangle (24 B each saved); every mode but
                                    ZS_MODE_PRIORITY is refused (ZS_ERR_MODE), and
                                    so is ZS_CFG_ABUFFER (ZS_ERR_ARGUMENT) */
/* Every flag there is; zs_init accepts those of ZS_CFG_BUILT (all of them in a
 * full build) and says ZS_ERR_ARGUMENT for any other bit (one list, so that
 * the core and its tests cannot disagree on which flags exist). */
#define ZS_CFG_ALL                                                                 \
    (ZS_CFG_NO_ZLINE | ZS_CFG_FLAT_ONLY | ZS_CFG_MONO | ZS_CFG_LINES | ZS_CFG_PRIORITY | \
     ZS_CFG_TEXTURE | ZS_CFG_ABUFFER | ZS_CFG_PRIORITY_ONLY)
/* The flags of ZS_CFG_ALL whose features this build has (see ZS_NO_TEXTURE). */
#define ZS_CFG_BUILT                                                               \
    (ZS_CFG_ALL & ~((ZS_HAS_TEXTURE ? 0u : ZS_CFG_TEXTURE) |                        \
                    (ZS_HAS_ABUFFER ? 0u : ZS_CFG_ABUFFER) |                        \
                    (ZS_HAS_PRIORITY ? 0u : (ZS_CFG_PRIORITY | ZS_CFG_PRIORITY_ONLY)) | \
                    (ZS_HAS_MONO ? 0u : (ZS_CFG_MONO | ZS_CFG_LINES))))
/* Does zs_init accept these flags? Only bits of ZS_CFG_BUILT, and not the
 * A-buffer with textures (its fragments carry none) or without depth planes. */
#define ZS_CFG_FLAGS_OK(flags)                                                     \
    (((flags) & ~(unsigned)ZS_CFG_BUILT) == 0u &&                                 \
     !(((flags) & ZS_CFG_ABUFFER) && ((flags) & (ZS_CFG_TEXTURE | ZS_CFG_PRIORITY_ONLY))))

/* Sizes of the records the arena holds (checked against sizeof in src/). */
#define ZS_VERTEX_BYTES 8u        /* screen x, y (28.4 in int16) and depth */
#define ZS_VERTEX_SHADE_BYTES 4u  /* per-vertex colour or light, and fog */
#define ZS_TRIANGLE_BYTES 12u     /* three vertex indices, bucket link, colour */
#define ZS_EDGE_BYTES 20u
#define ZS_ACTIVE_BYTES 32u       /* per active triangle: span state, flat pixel */
#define ZS_ACTIVE_PLANE_BYTES 24u /* per active triangle: depth plane (not with
                                     ZS_CFG_PRIORITY_ONLY) */
#define ZS_ACTIVE_COLOR_BYTES 36u /* per active triangle: colour planes */
#define ZS_TRI_NORMAL_BYTES 8u    /* ZS_CFG_LINES: a record's eye-space normal, draw */
#define ZS_TEX_VERTEX_BYTES 6u    /* ZS_CFG_TEXTURE: a vertex's u, v and texture slot */
#define ZS_ACTIVE_TEX_BYTES 120u  /* ZS_CFG_TEXTURE: per active triangle, texture planes */
#define ZS_MAX_FRAME_TEXTURES 16u /* distinct textures one frame may draw with */
#define ZS_ARENA_ALIGN 8u

/* Internal: n rounded up to a multiple of ZS_ARENA_ALIGN, in the unsigned
 * type T. */
#define ZS_ROUND8_T_(T, n) (((T)(n) + 7u) & ~(T)7u)
#define ZS_ROUND8_(n) ZS_ROUND8_T_(size_t, n)

/* Bytes of arena for a screen of w x h pixels holding up to max_tris
 * triangle records and max_verts vertices per frame and max_edges active
 * edge sides on one row (2 per triangle crossing the row; an active triangle
 * takes one slot per two), with the features `flags` (ZS_CFG_*) leaves in.
 * Includes alignment slack; a compile-time constant when the arguments are.
 * Per pool: vertices 8 B (+4 B shade), triangle records 12 B, row buckets
 * 2 B per row, edges 20 B, active triangles 32 B + a 24 B depth plane (none
 * with ZS_CFG_PRIORITY_ONLY) (+36 B colour planes), the
 * z-buffer line 10 B per column and 4 B; with ZS_CFG_MONO 3 B per column, with
 * ZS_CFG_LINES 6 B per column (4 with ZS_CFG_MONO too), 14 B and 1 bit
 * per triangle record and 2 B per vertex; with ZS_CFG_PRIORITY 4 B per
 * triangle record. */
#define ZS_ARENA_BYTES_CFG(w, h, max_tris, max_verts, max_edges, flags)            \
    ZS_ARENA_BYTES_T_(size_t, w, h, max_tris, max_verts, max_edges, flags)

/* Internal: ZS_ARENA_BYTES_CFG computed in the unsigned type T. The core
 * takes it in uint32_t where size_t is 16 bits, to see a figure that size_t
 * cannot hold (one expression for both, so they cannot drift apart). */
#define ZS_ARENA_BYTES_T_(T, w, h, max_tris, max_verts, max_edges, flags)          \
    (ZS_ROUND8_T_(T, (T)(max_verts) * ZS_VERTEX_BYTES) +                            \
     ((((flags) & (ZS_CFG_FLAT_ONLY | ZS_CFG_TEXTURE)) == ZS_CFG_FLAT_ONLY)         \
          ? 0u                                                                      \
          : ZS_ROUND8_T_(T, (T)(max_verts) * ZS_VERTEX_SHADE_BYTES)) +              \
     ZS_ROUND8_T_(T, (T)(max_tris) * ZS_TRIANGLE_BYTES) +                           \
     ZS_ROUND8_T_(T, (T)(h) * 2u) +                                                 \
     ZS_ROUND8_T_(T, (T)(max_edges) * ZS_EDGE_BYTES) +                              \
     2u * ZS_ROUND8_T_(T, (T)(max_edges) * 2u) +                                    \
     ZS_ROUND8_T_(T, (T)((max_edges) / 2u) * ZS_ACTIVE_BYTES) +                     \
     (((flags) & ZS_CFG_PRIORITY_ONLY)                                              \
          ? 0u                                                                      \
          : ZS_ROUND8_T_(T, (T)((max_edges) / 2u) * ZS_ACTIVE_PLANE_BYTES)) +       \
     ((((flags) & (ZS_CFG_FLAT_ONLY | ZS_CFG_TEXTURE)) == ZS_CFG_FLAT_ONLY)         \
          ? 0u                                                                      \
          : ZS_ROUND8_T_(T, (T)((max_edges) / 2u) * ZS_ACTIVE_COLOR_BYTES)) +       \
     2u * ZS_ROUND8_T_(T, (T)((max_edges) / 2u) * 2u) +                             \
     (((flags) & ZS_CFG_NO_ZLINE)                                                   \
          ? 0u                                                                      \
          : ZS_ROUND8_T_(T, (T)(w) * 8u) + ZS_ROUND8_T_(T, (T)(w) * 2u + 4u)) +     \
     (((flags) & (ZS_CFG_MONO | ZS_CFG_LINES)) ? ZS_ROUND8_T_(T, (T)(w)) : 0u) +     \
     (((flags) & ZS_CFG_MONO) ? ZS_ROUND8_T_(T, (T)(w) * 2u) : 0u) +                \
     (((flags) & ZS_CFG_LINES)                                                      \
          ? 2u * ZS_ROUND8_T_(T, (T)(w) * 2u) +                                     \
                (((flags) & ZS_CFG_MONO) ? 0u : ZS_ROUND8_T_(T, (T)(w))) +          \
                ZS_ROUND8_T_(T, (T)(max_tris) * ZS_TRI_NORMAL_BYTES) +              \
                ZS_ROUND8_T_(T, ((T)(max_tris) + 7u) / 8u) +                        \
                ZS_ROUND8_T_(T, (T)(max_tris) * 6u) +                               \
                ZS_ROUND8_T_(T, (T)(max_verts) * 2u)                                \
          : 0u) +                                                                   \
     (((flags) & ZS_CFG_PRIORITY) ? 2u * ZS_ROUND8_T_(T, (T)(max_tris) * 2u) : 0u) + \
     (((flags) & ZS_CFG_TEXTURE)                                                    \
          ? ZS_ROUND8_T_(T, (T)(max_verts) * ZS_TEX_VERTEX_BYTES) +                 \
                ZS_ROUND8_T_(T, (T)((max_edges) / 2u) * ZS_ACTIVE_TEX_BYTES) +      \
                ZS_ROUND8_T_(T, (T)ZS_MAX_FRAME_TEXTURES * (T)sizeof(void *))       \
          : 0u) +                                                                   \
     (((flags) & ZS_CFG_ABUFFER) ? ZS_ABUFFER_BYTES_T_(T, w, h, max_tris, max_edges) \
                                 : 0u) +                                            \
     ZS_ARENA_ALIGN)

/* ---- A-buffer (ZS_CFG_ABUFFER; src/abuffer.c) ----
 * Pixels that an edge or a penetration crosses are resolved from 4x4
 * sub-samples; the pools are fixed at compile time:
 *  - fragments (triangle, coverage mask, depth, colour) of the pixel being
 *    resolved: ZS_ABUFFER_FRAGMENTS, ZS_ABUFFER_FRAGMENT_BYTES each (fragments
 *    wholly behind an opaque one that covers the pixel are not kept); a pixel
 *    with more keeps its aliased value (zs_stats.aa_overflow);
 *  - triangles the resolve has open on a row: ZS_ABUFFER_TRIS(max_edges), each
 *    ZS_ABUFFER_TRI_BYTES plus 4 B of sweep lists (zs_stats.aa_skipped counts
 *    the triangles that found it full);
 *  - per column the row's mark (1 B); per row a bucket head (2 B); per
 *    triangle record a bucket link and an opacity (3 B);
 *  - opacity runs (zs_draw_opacity): ZS_ABUFFER_OPACITY_RUNS per frame. */
#define ZS_ABUFFER_FRAGMENTS 16u
#define ZS_ABUFFER_FRAGMENT_BYTES 32u
#define ZS_ABUFFER_TRI_BYTES 184u
#define ZS_ABUFFER_STATE_BYTES 96u
#define ZS_ABUFFER_OPACITY_RUNS 16u
#define ZS_ABUFFER_TRIS_T_(T, max_edges) ((T)(max_edges) / 2u + (T)(max_edges) / 8u + 4u)
#define ZS_ABUFFER_TRIS(max_edges) ZS_ABUFFER_TRIS_T_(size_t, max_edges)
#define ZS_ABUFFER_BYTES(w, h, max_tris, max_edges)                                 \
    ZS_ABUFFER_BYTES_T_(size_t, w, h, max_tris, max_edges)
#define ZS_ABUFFER_BYTES_T_(T, w, h, max_tris, max_edges)                           \
    (ZS_ROUND8_T_(T, ZS_ABUFFER_STATE_BYTES) +                                      \
     ZS_ROUND8_T_(T, ZS_ABUFFER_FRAGMENTS * ZS_ABUFFER_FRAGMENT_BYTES) +            \
     ZS_ROUND8_T_(T, (T)(w)) + ZS_ROUND8_T_(T, (T)(h) * 2u + 2u) +                  \
     ZS_ROUND8_T_(T, (T)(max_tris) * 3u) +                                          \
     ZS_ROUND8_T_(T, ZS_ABUFFER_TRIS_T_(T, max_edges) * ZS_ABUFFER_TRI_BYTES) +     \
     2u * ZS_ROUND8_T_(T, ZS_ABUFFER_TRIS_T_(T, max_edges) * 2u) +                  \
     ZS_ROUND8_T_(T, ZS_ABUFFER_OPACITY_RUNS * 4u))

/* Both visibility modes, Gouraud and fog; no 1-bit output, no hidden lines. */
#define ZS_ARENA_BYTES(w, h, max_tris, max_verts, max_edges)                        \
    ZS_ARENA_BYTES_CFG(w, h, max_tris, max_verts, max_edges, 0u)

typedef struct zs_config {
    uint16_t width, height;       /* pixels, 1..ZS_MAX_DIM */
    uint16_t max_triangles;       /* 1..ZS_MAX_TRIANGLES */
    uint16_t max_vertices;        /* 1..ZS_MAX_VERTICES */
    uint16_t max_active_edges;    /* 2..ZS_MAX_ACTIVE_EDGES: two per triangle
                                     crossing one row (edges that two
                                     triangles share are stored once) */
    uint16_t flags;               /* ZS_CFG_*; 0 = every feature but the added ones
                                     (ZS_CFG_MONO, ZS_CFG_LINES) */
} zs_config;

zs_config zs_config_default(uint16_t width, uint16_t height, uint16_t max_triangles,
                            uint16_t max_vertices, uint16_t max_active_edges);
/* All features (flags 0). */
/* The same figure as ZS_ARENA_BYTES_CFG, at run time (0 for an invalid config,
 * and where size_t is 16 bits (AVR) for one whose arena would not fit it:
 * zs_init then says ZS_ERR_CAPACITY). */
size_t zs_arena_bytes(const zs_config *cfg);

/* ------------------------------------------------------------------ */
/* Camera                                                               */
/* ------------------------------------------------------------------ */

typedef struct zs_camera {
    zs_mat34 view;           /* world -> eye (camera looks down eye -Z) */
    zs_fixed fov_deg;        /* vertical field of view, Q16.16 degrees */
    zs_fixed near_z, far_z;  /* positive distances, Q16.16 */
    uint8_t has_view, has_projection;
} zs_camera;

/* View from eye toward target; up need not be perpendicular. All Q16.16.
 * Keep the eye within 32767 units of the origin (Euclidean) so that the view
 * translation fits Q16.16 (it is clamped beyond). */
zs_status zs_camera_look_at(zs_camera *cam, zs_vec3 eye, zs_vec3 target, zs_vec3 up);
/* Perspective: vertical fov in (0, 180) degrees, 0 < near < far (Q16.16).
 * The fov must also be wide enough that cot(fov/2) fits Q16.16 (above about
 * 0.0035 degrees); narrower gives ZS_ERR_FOV.
 * The aspect ratio comes from the renderer's width and height (square pixels). */
zs_status zs_camera_perspective(zs_camera *cam, zs_fixed fov_deg, zs_fixed near_z,
                                zs_fixed far_z);
/* Use an explicit world->eye transform instead of look_at. */
zs_status zs_camera_set_view(zs_camera *cam, const zs_mat34 *view);

/* ------------------------------------------------------------------ */
/* Meshes                                                               */
/* ------------------------------------------------------------------ */

typedef uint32_t zs_color;   /* 0x00RRGGBB */
#define ZS_RGB(r, g, b) ((zs_color)(((uint32_t)(r) << 16) | ((uint32_t)(g) << 8) | (uint32_t)(b)))

/* A mesh in flash. Model-space position of vertex i is
 * positions[3i .. 3i+2] * scale (scale in Q16.16, so the product is Q16.16);
 * model coordinates must stay within +-32767 units. Model and view matrices
 * may place them farther apart: eye and clip coordinates are carried in 64
 * bits, so any view of such a scene is exact (README: Exactness and its limits). Normals are unit vectors
 * in Q1.14 (16384 == 1.0). Colour sources, first present wins: per-vertex
 * colours in Gouraud mode, per-face colours, per-vertex colours (averaged per
 * face in flat mode), then `color`. */
typedef struct zs_mesh {
    const int16_t *positions;       /* 3 per vertex */
    const uint16_t *indices;        /* 3 per triangle, counter-clockwise front */
    const zs_color *face_colors;    /* optional, 1 per triangle */
    const zs_color *vertex_colors;  /* optional, 1 per vertex */
    const int16_t *face_normals;    /* optional, 3 per triangle (else computed) */
    const int16_t *vertex_normals;  /* optional, 3 per vertex (else face normal) */
    zs_fixed scale;                 /* Q16.16, non-zero */
    uint16_t vertex_count;
    uint16_t triangle_count;
    zs_color color;                 /* used when no colour array is given */
    /* Texture mapping (needs ZS_CFG_TEXTURE; both NULL: untextured). */
    const int16_t *uvs;             /* 2 per vertex (u, v), ZS_UV_ONE == 1.0 */
    const struct zs_texture *texture; /* modulated by the lit colour, then fogged */
} zs_mesh;

/* ------------------------------------------------------------------ */
/* Textures                                                             */
/* ------------------------------------------------------------------ */

/* Texture coordinates in zs_mesh.uvs: Q3.12, so one texture spans 4096 and
 * a triangle may repeat it up to 8 times either way (with ZS_TEX_WRAP). u
 * runs along a texel row (x), v down the rows: texel (i, j) covers
 * u in [i, i + 1) * ZS_UV_ONE / width, v likewise (OpenGL's convention with
 * row 0 first). */
#define ZS_UV_ONE 4096
#define ZS_TEX_MAX_DIM 1024 /* width and height limit, texels */

typedef enum zs_tex_format {
    ZS_TEX_RGB565 = 0, /* uint16_t per texel, native RGB565 */
    ZS_TEX_PAL8 = 1    /* uint8_t per texel, an index into 256 RGB565 colours */
} zs_tex_format;

/* zs_texture.flags */
#define ZS_TEX_BILINEAR 0x01u /* bilinear filtering (else nearest texel) */
#define ZS_TEX_CLAMP 0x02u    /* clamp to the edge texels (else repeat) */
#define ZS_TEX_SUBDIV 0x04u   /* perspective exact every 16 columns (at multiples
                                 of 16) and affine between (else exact at every
                                 pixel); README: Texture mapping */

/* A texture in flash: width x height texels, row-major, row 0 first. */
typedef struct zs_texture {
    const void *texels;       /* width * height texels of `format` */
    const uint16_t *palette;  /* ZS_TEX_PAL8: 256 RGB565 colours (else unused) */
    uint16_t width, height;   /* powers of two, 1..ZS_TEX_MAX_DIM */
    uint8_t format;           /* zs_tex_format */
    uint8_t flags;            /* ZS_TEX_* */
} zs_texture;

/* ZS_OK if t is a texture zs_draw accepts; ZS_ERR_TEXTURE for a width or
 * height that is not a power of two in 1..ZS_TEX_MAX_DIM, no texels (or no
 * palette for ZS_TEX_PAL8), an unknown format or unknown flags; ZS_ERR_NULL
 * for t NULL. zs_draw also says ZS_ERR_TEXTURE for a mesh with uvs but no
 * texture or a texture but no uvs, and ZS_ERR_MODE when the config left
 * ZS_CFG_TEXTURE out. */
zs_status zs_texture_check(const zs_texture *t);

/* ------------------------------------------------------------------ */
/* Shading                                                              */
/* ------------------------------------------------------------------ */

typedef enum zs_visibility {
    ZS_MODE_SPAN = 0,   /* spanning scanline: one depth decision per span */
    ZS_MODE_ZLINE = 1,  /* scanline z-buffer: a depth per pixel of the row */
    ZS_MODE_PRIORITY = 2, /* list priority: the earliest stored triangle wins, no depth
                             test (zspan/priority.h: BSP or depth-sorted order) */
    ZS_MODE_WARNOCK = 3   /* area subdivision (Warnock) of each band's rectangle:
                             the same image as the other modes (README: Warnock
                             mode); zs_stats.windows, .pixel_decisions */
} zs_visibility;

typedef enum zs_shading {
    ZS_SHADE_FLAT = 0,     /* one colour per triangle (lit per face) */
    ZS_SHADE_GOURAUD = 1   /* colours per vertex (lit per vertex), interpolated */
} zs_shading;

/* Output pixel formats for zs_render_rows. ZS_FMT_COUNT counts the byte
 * formats (0 .. ZS_FMT_COUNT-1, whole bytes per pixel); the 1-bit formats
 * follow at ZS_FMT_MONO_PAGE and ZS_FMT_MONO_MSB (they need ZS_CFG_MONO, or
 * ZS_CFG_LINES for line drawings). */
typedef enum zs_format {
    ZS_FMT_RGB565_BE = 0,  /* 2 bytes, big-endian: the SPI wire order */
    ZS_FMT_RGB565 = 1,     /* 2 bytes, native uint16_t */
    ZS_FMT_RGB666 = 2,     /* 3 bytes R, G, B, each in bits 7..2 */
    ZS_FMT_GRAY8 = 3,      /* 1 byte luma (77 R + 150 G + 29 B) / 256 */
    ZS_FMT_RGB888 = 4,     /* 3 bytes R, G, B */
    ZS_FMT_ID16 = 5,       /* 2 bytes native: triangle tag (see zs_draw), 0 = none */
    ZS_FMT_COUNT,
    /* 1 bit per pixel, 1 = light (lit OLED pixel, white e-paper pixel) unless
     * ZS_MONO_INVERT. The grey (GRAY8 luma) is dithered (ZS_MONO_*). */
    ZS_FMT_MONO_PAGE = 8,  /* SSD1306 pages: byte x of page p holds column x of
                              rows 8p .. 8p+7, row 8p + k in bit k (LSB on top).
                              zs_render_rows(r, y0, rows, buf, stride): page
                              y0 / 8 at buf, the next at buf + stride (>= width);
                              a row sets its bit and keeps the other 7 (the
                              screen's last row clears the bits below it). */
    ZS_FMT_MONO_MSB = 9,   /* row-major (e-paper): row k at buf + k * stride
                              (>= (width + 7) / 8), pixel x in byte x / 8, bit
                              7 - x % 8; the unused low bits of the last byte 0 */
    /* 4-bit grey (SSD0323 OLEDs; issue 20): needs ZS_CFG_MONO (its grey scratch
     * line). Level round(15 g / 255) of the GRAY8 luma g, or ordered dithered
     * between levels (ZS_GRAY4_DITHER); 15 - level with ZS_MONO_INVERT. */
    ZS_FMT_GRAY4 = 10      /* row k at buf + k * stride (>= (width + 1) / 2):
                              pixel x in byte x / 2, the high nibble for even x
                              (two pixels a byte, high nibble first); an odd
                              width's last low nibble is 0 */
} zs_format;

/* Bytes per pixel of a byte format (0 for the 1-bit formats, ZS_FMT_GRAY4 and
 * unknown ones). */
unsigned zs_format_bytes(zs_format fmt);
/* The smallest stride zs_render_rows accepts for a format and width: width *
 * bytes per pixel, width for ZS_FMT_MONO_PAGE (one byte per column of a
 * page), (width + 7) / 8 for ZS_FMT_MONO_MSB, (width + 1) / 2 for
 * ZS_FMT_GRAY4; 0 for an unknown format. */
size_t zs_format_stride(zs_format fmt, unsigned width);
/* Is fmt one of the 1-bit formats? */
int zs_format_is_mono(zs_format fmt);

/* zs_shade_params.mono, for the 1-bit formats (0: ordered dithering). */
#define ZS_MONO_DIFFUSE 0x01u  /* error diffusion (Floyd-Steinberg weights, left to
                                  right) instead of the 8x8 Bayer matrix; one line
                                  of error carried between rows, so the image is
                                  the same whatever the band height */
#define ZS_MONO_LINES 0x02u    /* hidden-line drawing instead of filled surfaces
                                  (needs ZS_CFG_LINES): bit 1 on the pixels of
                                  visible silhouettes, creases and boundaries
                                  between draw calls, one pixel wide */
#define ZS_MONO_INVERT 0x04u   /* every output bit inverted (dark lines on light) */
/* zs_shade_params.mono for ZS_FMT_GRAY4: ZS_MONO_INVERT and this one. */
#define ZS_GRAY4_DITHER 0x08u  /* ordered dithering between the 16 levels (the
                                  8x8 Bayer matrix of the 1-bit formats): a flat
                                  grey g averages 15 g / 255 within 1/64 level */

#define ZS_MAX_LIGHTS 2

typedef struct zs_light {
    zs_vec3 direction;   /* world space, toward the light; need not be unit */
    zs_fixed intensity;  /* Q16.16, 1.0 = full */
} zs_light;

typedef struct zs_fog {
    zs_color color;
    zs_fixed start, end; /* eye distances (Q16.16): no fog before start, all fog from end */
    uint8_t enabled;
} zs_fog;

/* Per-frame look. Lighting: colour * (ambient + sum of max(0, N.L) * intensity),
 * saturated; with no light and ambient 1.0 the colours are used as they are. */
typedef struct zs_shade_params {
    zs_shading shading;
    zs_format format;
    zs_color background;
    zs_fixed ambient;                /* Q16.16 */
    uint8_t light_count;             /* 0..ZS_MAX_LIGHTS */
    zs_light lights[ZS_MAX_LIGHTS];
    zs_fog fog;
    uint8_t mono;                    /* ZS_MONO_*, for the 1-bit formats */
    uint8_t crease_deg;              /* ZS_MONO_LINES: a shared edge is drawn where
                                        its faces' normals differ by more than this
                                        (1..179 degrees; 0 = 30) */
} zs_shade_params;

/* Flat, RGB565 big-endian, black background, unlit (ambient 1.0), no fog,
 * ordered dithering. */
zs_shade_params zs_shade_default(void);

/* ------------------------------------------------------------------ */
/* Frame statistics                                                     */
/* ------------------------------------------------------------------ */

/* Every submitted triangle is counted in exactly one of culled, rejected,
 * empty, dropped and stored:
 *   tris_submitted == tris_culled + tris_rejected + tris_empty
 *                     + tris_dropped + tris_stored.
 * A triangle split by clipping counts once (stored if any piece was stored,
 * else dropped if any piece hit a full pool, else empty if any piece was
 * empty, else culled; rejected if clipping left nothing); tris_clipped counts
 * those that needed clipping, records counts the pieces stored. */
typedef struct zs_stats {
    uint32_t tris_submitted;   /* triangles passed to zs_draw */
    uint32_t tris_culled;      /* back-facing or zero area on screen */
    uint32_t tris_rejected;    /* wholly outside the view volume or the screen */
    uint32_t tris_clipped;     /* needed clipping (near/far/guard band) */
    uint32_t tris_empty;       /* cover no pixel centre (bounding box, or an exact
                                  test when the box holds at most 4 centres) */
    uint32_t tris_dropped;     /* lost to a full pool (capacity policy) */
    uint32_t tris_stored;      /* submitted triangles with at least one record */
    uint32_t records;          /* triangle records stored (pieces after clipping) */
    uint32_t tris_drawn;       /* records that were activated on some row */
    uint32_t verts_stored;     /* vertex pool use */
    uint32_t verts_dropped;    /* vertices that did not fit the pool */
    uint32_t records_skipped;  /* records never drawn: the active-edge pool was
                                  full on the row they start (capacity policy) */
    uint32_t saturated;        /* values clamped beyond the documented limits
                                  (model coordinates past +-32768 units, a model-
                                  view 3x3 entry past Q16.16, eye coordinates
                                  past 2^30 units); 0 within them */
    uint32_t rows;             /* rows rendered */
    uint32_t spans;            /* spans written (background spans included) */
    uint32_t max_active_edges; /* most edge sides active on one row (2 per
                                  triangle crossing it): the figure to size
                                  zs_config.max_active_edges from */
    uint32_t depth_evals;      /* plane evaluations for visibility */
    uint32_t crossings;        /* penetration crossings split inside a row */
    uint32_t pixels_shaded;    /* pixel writes (== width * rows: each pixel once) */
    uint32_t windows;          /* ZS_MODE_WARNOCK: windows visited (the band
                                  rectangles and every quadrant split off) */
    uint32_t pixel_decisions;  /* ZS_MODE_WARNOCK: one-pixel windows decided by
                                  the pixel-centre rule */
    /* list priority (zspan/priority.h); 0 in frames that do not use it */
    uint32_t bsp_nodes;        /* BSP nodes visited */
    uint32_t bsp_pruned;       /* triangles skipped because their node plane faces away */
    uint32_t sort_pairs;       /* depth sort: overlapping pairs the tests had to resolve */
    uint32_t sort_swaps;       /* depth sort: triangles moved ahead of their place */
    uint32_t sort_splits;      /* depth sort: triangles split for cycles or penetrations */
    uint32_t sort_giveups;     /* depth sort: pairs left as sorted (work or pool bound hit) */
    uint32_t tris_untransformed;  /* triangles of draws culled by their bounds: no vertex
                                     transformed (counted in tris_submitted and
                                     tris_rejected too) */
    uint32_t verts_untransformed; /* their vertices */
    uint32_t cells_culled;     /* scene cells culled whole against the frustum */
    /* A-buffer (zs_frame_antialias; 0 when it is off) */
    uint32_t aa_pixels;        /* pixels resolved from sub-samples */
    uint32_t aa_fragments;     /* fragments (triangle, mask) they were resolved from */
    uint32_t aa_overflow;      /* pixels left aliased: the row's fragment pool was full */
    uint32_t aa_skipped;       /* triangles left out of the resolve: its pool was full */
    uint32_t aa_max_fragments; /* most fragments one pixel needed (of
                                  ZS_ABUFFER_FRAGMENTS) */
    uint32_t records_dropped;  /* triangle records (clipped pieces count one each)
                                  lost to a full triangle or vertex pool: every
                                  capacity drop, also a piece of a triangle that
                                  another piece kept counted as stored; at least
                                  tris_dropped */
} zs_stats;

/* ------------------------------------------------------------------ */
/* The renderer                                                         */
/* ------------------------------------------------------------------ */

/* Called by zs_draw for every triangle record it stores (see
 * zs_set_setup_hook): the tag, the snapped screen vertices (x0,y0,x1,y1,x2,y2
 * in 28.4 pixels, y down) and the window depths (Q2.30). */
typedef void (*zs_setup_hook_fn)(void *user, uint16_t tag, const int32_t xy[6],
                                 const uint32_t z[3]);

/* The core's records, defined in src/zs_internal.h; a user never needs them. */
struct zs_vert;
struct zs_tri;
struct zs_edge;
struct zs_active;
struct zs_active_color;
struct zs_renderer;

/* The renderer's private state: pools carved from the arena and the frame
 * in progress. It may change between versions; do not use it. */
typedef struct zs_renderer_private {
    /* arena pools */
    struct zs_vert *verts;          /* screen vertices of the frame */
    uint32_t *vshade;               /* their shade words; NULL if flat only */
    struct zs_tri *tris;            /* triangle records */
    uint16_t *buckets;              /* per row: first record starting there */
    struct zs_edge *edges;          /* edge records */
    uint16_t *ael;                  /* active edge list (edge indices) */
    uint16_t *edge_free;            /* free edge records */
    struct zs_active *active;       /* active triangles */
    struct zs_active_plane *aplane; /* their depth planes; NULL with ZS_CFG_PRIORITY_ONLY */
    struct zs_active_color *acolor; /* their colour planes; NULL if flat only */
    uint16_t *in_set;               /* span mode: the in-polygon set */
    uint16_t *active_free;          /* free active triangles */
    uint32_t *sort_keys;            /* span mode: edge sort keys (8 B a column;
                                       NULL with ZS_CFG_NO_ZLINE) */
    uint16_t *zline_owner;          /* zline mode: the triangle owning each pixel
                                       (its depth there is the owner's plane) */
    uint8_t *mono_grey;             /* ZS_CFG_MONO: the row in GRAY8 before dithering */
    int16_t *mono_err;              /* ZS_CFG_MONO: diffusion error for the next row */
    uint16_t *line_ids[2];          /* ZS_CFG_LINES: this row's and the next row's ids */
    int16_t *tri_normal;            /* ZS_CFG_LINES: unit normal (Q14) and draw number
                                       per record */
    uint8_t *draw_starts;           /* ZS_CFG_LINES: bit per record, set where a draw's
                                       records begin */
    int32_t guard;                  /* guard band, in units of w */
    /* frame state */
    zs_vec3 light_dir[ZS_MAX_LIGHTS]; /* unit, Q16.16 */
    zs_fixed proj_sx, proj_sy;        /* clip-space x and y scale */
    int64_t depth_scale;              /* far / (far - near) in Q30, 0 if >= 8 */
    uint32_t tag_counter;             /* triangles submitted this frame */
    uint32_t background;              /* packed background pixel of the frame */
    int32_t next_row;
    uint16_t n_verts, n_tris, n_ael, n_sorted, n_edge_free, n_active_free;
    int32_t min_cross;                /* span walk: nearest crossing after a pick */
    uint16_t others_lo;               /* span walk: least depth bound of the rest */
    uint8_t state, mode, bpp;
    uint8_t steep;                    /* a steep plane is active this frame */
    uint8_t out_format;               /* the format asked for; shade.format is the
                                         scratch line's (GRAY8, ID16) for 1-bit ones */
    uint8_t line_keep;                /* a hidden-line frame: records of the triangles
                                         that hold no pixel centre are kept (not
                                         rendered) so the mesh around them is known */
    int32_t crease_cos;               /* cos of the crease angle, Q28 */
    int64_t line_depth_a;             /* far / (far - near), Q30: 1/w ~ A - depth */
    /* ZS_CFG_TEXTURE (texture.c); NULL without it */
    struct zs_tex_vert *tex_verts;    /* per vertex: u, v, texture slot */
    struct zs_active_tex *atex;       /* per active triangle: texture planes */
    const struct zs_texture **textures; /* the frame's textures, slot k at k - 1 */
    int64_t tex_depth_a;              /* far / (far - near), Q30 (1/w ~ A - depth) */
    uint8_t n_textures;               /* slots used this frame */
    uint8_t twin_shift;               /* raster: 32 - log2 of the twin table's size, 0
                                         for none (src/zs_internal.h) */
    uint32_t tex_serial;              /* frames begun (texture planes' freshness) */
    zs_setup_hook_fn setup_hook;
    void *setup_hook_user;
    uint16_t tall_rows;               /* Warnock, picking: most rows a record spans
                                         (0xFFFF: not yet counted this frame) */
    uint8_t rows_kind;                /* how zs_render_rows makes rows this frame */
    void *ranges;                     /* zs_draw_bsp: the walk giving zs_draw its
                                         triangle ranges, NULL otherwise */
    uint16_t *sort_list;              /* ZS_CFG_PRIORITY: zs_depth_sort's list */
    uint16_t *sort_aux;               /* ZS_CFG_PRIORITY: its marks, then new numbers */
    void (*row_fn)(struct zs_renderer *r, int y, uint8_t *row); /* the frame's row walk */
    /* A-buffer (abuffer.c) */
    struct zs_aa_state *aa;           /* its pools; NULL without ZS_CFG_ABUFFER */
    uint8_t aa_mode;                  /* zs_aa_mode of the frame */
    /* hidden lines (lines.c), ZS_CFG_LINES */
    uint8_t *line_pending;            /* flags the next row has got */
    uint16_t *line_vert_head;         /* per pool vertex, a record using it */
    uint16_t *line_next_rec;          /* per record corner, the next record using that
                                         corner's vertex */
    int32_t line_next;                /* the next row to render (rows are rendered one
                                         ahead of the output) */
    uint16_t line_feats;              /* records holding feature edges, sorted by top */
    uint16_t line_feat_next;          /* the next of them to join the active ones */
    uint16_t line_n_active;           /* records whose feature edges reach the row */
} zs_renderer_private;

/* Holds the arena's pools and the frame state. The struct is public so it
 * can be allocated statically; a user may read cfg, stats, shade and cam
 * (through the functions below where there is one) and never writes any
 * field; priv is private. */
typedef struct zs_renderer {
    zs_config cfg;         /* the configuration given to zs_init */
    zs_stats stats;        /* this frame's statistics (zs_frame_stats) */
    zs_shade_params shade; /* this frame's shading (zs_frame_shading); with a
                              1-bit format its format field holds the scratch
                              line's (GRAY8, or ID16 for line drawings) */
    zs_camera cam;         /* this frame's camera (zs_frame_begin) */
    zs_renderer_private priv;
} zs_renderer;

/* Checks the config and carves the arena (any alignment; ZS_ARENA_BYTES
 * includes the slack). ZS_ERR_ARENA_SMALL if arena_size < zs_arena_bytes(cfg).
 * The core stores its own record types in the arena, whatever type the
 * caller declared it with: build src/ with -fno-strict-aliasing (the
 * Makefile does), or hand it memory without a declared type. */
zs_status zs_init(zs_renderer *r, void *arena, size_t arena_size, const zs_config *cfg);

/* Starts a frame: clears the pools and statistics. The camera is copied. */
zs_status zs_frame_begin(zs_renderer *r, const zs_camera *cam, zs_visibility mode);
/* Shading for the frame; call after zs_frame_begin and before the first
 * zs_draw (zs_frame_begin resets it to zs_shade_default()). The 1-bit
 * formats and ZS_FMT_GRAY4 need ZS_CFG_MONO (ZS_MONO_LINES: ZS_CFG_LINES), else
 * ZS_ERR_MODE; unknown ZS_MONO_* bits (GRAY4: other than ZS_GRAY4_DITHER and
 * ZS_MONO_INVERT) or crease_deg >= 180 give ZS_ERR_ARGUMENT (mono and
 * crease_deg are ignored with a byte format). */
zs_status zs_frame_shading(zs_renderer *r, const zs_shade_params *params);

/* Capacity policy: a draw's vertices that do not fit the vertex pool are
 * dropped with the triangles using them; records that do not fit the
 * triangle pool are dropped (the last submitted lose); a triangle whose first
 * row finds the active-triangle pool full is skipped for the frame (on one
 * row, the later submitted lose). All of it is counted in zs_stats. */
/* Transforms, culls, clips and stores a mesh's triangles. model may be NULL
 * (identity). Each submitted triangle gets the next tag (1, 2, 3, ... in
 * submission order across the frame; after 65535 the count starts again at 1,
 * as 0 means "no triangle"), which ZS_FMT_ID16 writes. A draw rejected with an
 * error stores nothing and uses no tags. Triangles that do not fit the pools
 * are dropped and counted (capacity policy: the last ones submitted lose).
 * Normals are turned by the model matrix's 3x3 part; with a non-uniform scale
 * in it, lighting is approximate. */
zs_status zs_draw(zs_renderer *r, const zs_mesh *mesh, const zs_mat34 *model);

/* Renders rows y0 .. y0+rows-1 into buf (row k at buf + k*stride) in the
 * frame's format (the 1-bit formats: see ZS_FMT_MONO_PAGE / _MSB). Rows must be asked for in increasing order; rows skipped
 * over are not rendered (useful for partial updates). Every pixel of each row
 * is written exactly once in span mode. */
zs_status zs_render_rows(zs_renderer *r, int y0, int rows, void *buf, size_t stride);

/* Called with each finished band: rows y0 .. y0+rows-1, at buf with stride. */
typedef int (*zs_band_fn)(void *user, int y0, int rows, const void *buf, size_t stride);

/* Convenience: renders the rest of the frame band by band into buf (band_rows
 * rows of stride bytes; ZS_FMT_MONO_PAGE: band_rows / 8 pages, band_rows a
 * multiple of 8, else ZS_ERR_ROW) and hands each band to fn. A non-zero return from fn
 * stops the frame early (ZS_ERR_STATE is not set; ZS_OK is returned). */
zs_status zs_render_frame(zs_renderer *r, void *buf, size_t stride, int band_rows,
                          zs_band_fn fn, void *user);

/* The pixel format the frame renders in (what zs_frame_shading was given;
 * for the 1-bit formats shade.format holds the scratch line's). */
zs_format zs_frame_format(const zs_renderer *r);

/* Statistics of the current (or last) frame. */
const zs_stats *zs_frame_stats(const zs_renderer *r);

/* ---- A-buffer: anti-aliased edges and transparency (ZS_CFG_ABUFFER) ---- */
typedef enum zs_aa_mode {
    ZS_AA_OFF = 0,          /* as without the A-buffer, byte for byte */
    ZS_AA_EDGES = 1,        /* pixels crossed by an edge or a penetration are the
                               box-filtered mean of 4x4 sub-samples */
    ZS_AA_TRANSPARENT = 2   /* edges, and draws with an opacity below 255
                               (zs_draw_opacity) blended in depth order */
} zs_aa_mode;
/* Per frame, after zs_frame_shading and before the first zs_draw. Needs
 * ZS_CFG_ABUFFER and ZS_MODE_SPAN (ZS_MODE_ZLINE: ZS_ERR_MODE); an unknown
 * mode is ZS_ERR_ARGUMENT. zs_frame_begin resets it to ZS_AA_OFF. Triangles
 * that cover sub-samples but no pixel centre are stored too (for the
 * resolve only). ZS_FMT_ID16 writes the tag that covers most sub-samples. */
zs_status zs_frame_antialias(zs_renderer *r, zs_aa_mode mode);
/* Opacity (0 = invisible .. 255 = opaque) of the draws that follow, in
 * ZS_AA_TRANSPARENT frames (else ZS_ERR_MODE). A frame holds up to
 * ZS_ABUFFER_OPACITY_RUNS changes (then ZS_ERR_CAPACITY). Transparent
 * surfaces in front of the nearest opaque one are blended per sub-sample,
 * far to near: c = c + (surface - c) * opacity / 255. */
zs_status zs_draw_opacity(zs_renderer *r, uint8_t opacity);

/* Debug/verification hook: called for every triangle record stored by
 * zs_draw with its tag, the snapped screen vertices (x0,y0,x1,y1,x2,y2 in
 * 28.4 pixels, y down) and window depths (Q2.30). NULL disables. */
void zs_set_setup_hook(zs_renderer *r, zs_setup_hook_fn fn, void *user);

/* ------------------------------------------------------------------ */
/* Picking (issue 15)                                                   */
/* ------------------------------------------------------------------ */

#define ZS_PICK_NONE 0xFFFFu

/* What zs_pick found at a pixel. */
typedef struct zs_pick_hit {
    uint16_t record;   /* the visible triangle record (0 .. stats.records - 1,
                          in submission order), ZS_PICK_NONE for background */
    uint16_t tag;      /* its tag (what ZS_FMT_ID16 writes: 1 + the triangles
                          submitted before it, so draw call and index follow
                          from tris_submitted noted before each zs_draw); only
                          in an ID16 frame (records keep colours otherwise): 0 */
    uint32_t depth;    /* window depth at the pixel centre, Q2.30 (depth_q40 >> 10) */
    int64_t depth_q40; /* the depth the renderer decided by (Q40), 0 for background */
} zs_pick_hit;

/* Which stored triangle is visible at the centre of pixel (x, y), by the
 * renderer's own rule (top-left fill, the exact depth plane, ties to the
 * record submitted first): the pixel ZS_FMT_ID16 shows. Call once the
 * frame's rendering has begun (its draws are final) and before the next
 * zs_frame_begin. Work: the records whose first row lies within the tallest
 * record's height above y (about those crossing row y), no frame buffer.
 * ZS_ERR_ARGUMENT for a pixel off the screen, ZS_ERR_STATE before rendering,
 * ZS_ERR_CAPACITY (hit still filled) when the frame skipped records
 * (stats.records_skipped): the image may then differ from the answer. */
zs_status zs_pick(zs_renderer *r, int x, int y, zs_pick_hit *hit);

#ifdef __cplusplus
}
#endif

#endif /* ZSPAN_ZSPAN_H */
