/* SPDX-License-Identifier: MIT */
/* Internal records and helpers shared by the pipeline stages. */
#ifndef ZSPAN_INTERNAL_H
#define ZSPAN_INTERNAL_H

#include "zspan/zspan.h"
#include <string.h>

#define ZS_NONE 0xFFFFu

/* Colour planes and per-vertex shade words: Gouraud and fog, and the light
 * of textured records (zspan.h: ZS_NO_GOURAUD, ZS_NO_TEXTURE). */
#define ZS_HAS_PLANES_ (ZS_HAS_GOURAUD || ZS_HAS_TEXTURE)
/* Every row is RGB565, either byte order: no other byte format (ZS_RGB565_ONLY)
 * and no 1-bit stage's scratch line (GRAY8 or ID16; ZS_NO_MONO). */
#define ZS_ONLY_565_ (!ZS_HAS_FORMATS && !ZS_HAS_MONO)

/* zs_render_rows' paths (priv.rows_kind): the row machinery into byte
 * rows, into a 1-bit format's scratch line, or Warnock mode's rectangles. */
enum { ZS_ROWS_BYTES = 0, ZS_ROWS_MONO, ZS_ROWS_AREA };

/* Renderer states. */
enum { ZS_STATE_NONE = 0, ZS_STATE_READY, ZS_STATE_OPEN, ZS_STATE_RENDERING, ZS_STATE_DONE };

/* Guard band: x and y are clipped only beyond +-guard * w (NDC units), with
 * guard = min(4, 32767 / (8 * max(width, height)) - 1) (2..4 for screens up
 * to ZS_MAX_DIM), so projected 28.4 coordinates fit int16 and all edge and
 * plane arithmetic fits its integer types (see setup.c). */
#define ZS_GUARD_MAX 4

/* A screen-space vertex of the frame (8 bytes). Its shade word, bits 0..23
 * RGB888 (colour or light) and 24..31 fog 0..255, is kept in a parallel
 * array (vshade) unless the renderer is flat only. */
typedef struct zs_vert {
    int16_t x, y;    /* 28.4 pixels, y down, within the guard band */
    uint32_t z;      /* window depth Q2.30; ZS_VERT_UNPROJECTED if outside
                        (then x holds its outcode, geometry.c's only) */
} zs_vert;
#define ZS_VERT_UNPROJECTED 0x80000000u

/* A stored triangle (12 bytes); v[] index the vertex pool. */
typedef struct zs_tri {
    uint16_t v[3];
    uint16_t next;   /* next record in the same first-row bucket */
    uint32_t color;  /* bits 0..23 face RGB888, 24..31 ZS_TRI_* flags; the
                        tag instead when the format is ZS_FMT_ID16 */
} zs_tri;
#define ZS_TRI_MODULATE 0x01u  /* colour_i = face * vertex rgb_i / 255 */
#define ZS_TRI_FOG 0x02u       /* blend toward the fog colour by vertex fog */
#define ZS_TRI_TEXTURED 0x04u  /* textured: its light always in colour planes, so
                                  zs_fill_gouraud hands its spans to texture.c */

/* An edge stepped down the rows (20 bytes). Column = ceil(x - 0.5) exactly:
 * x is the integer column, err the remainder of the exact rational.
 * Where two triangles of a mesh share an edge, one record serves both (as in
 * Quake's edges with two surfaces): the walk leaves one triangle and enters
 * the other at it, and it is stepped once.
 *
 * The remainders are kept in whole 1/16 px steps: with den = 16 dy the exact
 * remainder is 16 err + f for a fixed f in [0, 16) (the row step's remainder
 * is a multiple of 16), and 16 err + f < 16 rstep exactly when err < rstep,
 * so dropping f changes no column, and err, rstep and dy fit 16 bits. */
typedef struct zs_edge {
    int32_t x;       /* first covered column at/after this edge, this row */
    uint32_t frac;   /* err << 16 | rstep: the remainder / 16 (x * 16 dy -
                        numerator, floored) and the remainder per row / 16,
                        both in [0, dy); next to x for one paired load */
    uint32_t run;    /* step << 16 | y_end: the whole columns per row (floor,
                        |step| < 2^12: an edge stepped at all spans two row
                        centres, dy > 16) and the first row this edge no
                        longer covers (0 < y_end < 2^15), one word for the
                        step loop (add with a shift, compare with a shift) */
    uint16_t lead;   /* active triangle this edge starts (its left edge), or ZS_NONE */
    uint16_t trail;  /* active triangle this edge ends (its right edge), or ZS_NONE */
    uint16_t dy;     /* rows of 1/16 px it spans (0 < dy < 2^16: int16 vertices) */
    uint16_t pad;    /* raster.c's column lists */
} zs_edge;

/* An active triangle: its depth plane and span-walk state, valid while it
 * crosses the current row. */
typedef struct zs_active {
    int64_t zdx;           /* depth per column (Q40); the rest of the plane is
                              in zs_active_plane (the walks compare slopes) */
    uint32_t pixel;        /* packed pixel of a flat triangle */
    uint16_t tri;          /* record index: the submission order for ties */
    uint16_t right;        /* its right (trailing) edge */
    int16_t y0;            /* the row zrow and the colour planes refer to */
    uint8_t flags;         /* ZS_ACT_* */
    uint8_t inside;        /* in/out counter while walking a row (mod 256) */
    uint16_t set_pos;      /* position in the in-polygon set */
    int16_t y_end;         /* first row below the triangle */
    int32_t cross;         /* span walk: column where it overtakes the top */
    uint16_t zlo, zhi;     /* span, zline: depth range in 2^-15 units, widened
                              past every evaluation error: where zlo > 0,
                              zlo * 2^25 <= depth (Q40) < zhi * 2^25 at any
                              centre it covers (activate.c) */
} zs_active;

/* Depth plane of an active triangle (same index; none with
 * ZS_CFG_PRIORITY_ONLY, whose walk decides by record order alone). */
typedef struct zs_active_plane {
    int64_t zrow;          /* depth at column 0 of row y0 (Q40); row y adds
                              zdy * (y - y0), exactly (planes are not stepped) */
    int64_t zdy;           /* depth per row (Q40) */
    int64_t zcur;          /* scratch: depth at the current span start (span
                              mode), at column 0 of row `cross` (zline mode) */
} zs_active_plane;

/* Colour planes of an active triangle (same index), for Gouraud shading. */
typedef struct zs_active_color {
    uint32_t crow[3];      /* colour at column 0 of row y0 (Q8.16, wrapping) */
    int32_t cdx[3], cdy[3];/* colour per column and per row (Q8.16) */
} zs_active_color;

#define ZS_ACT_GOURAUD 0x01u   /* colour varies across the triangle */
#define ZS_ACT_LONG_LEFT 0x02u /* the long edge is its left edge */
#define ZS_ACT_STEEP 0x04u     /* needle: zrow anchored exactly on every row */
#define ZS_ACT_LAZY 0x08u      /* span, zline: depth plane not made yet (most
                                  triangles are decided by their depth range
                                  and never need it); zs_make_plane makes it */

/* Compile-time checks that the header's sizes match the records. */
typedef char zs_check_vert[(sizeof(zs_vert) == ZS_VERTEX_BYTES) ? 1 : -1];
typedef char zs_check_tri[(sizeof(zs_tri) == ZS_TRIANGLE_BYTES) ? 1 : -1];
typedef char zs_check_edge[(sizeof(zs_edge) == ZS_EDGE_BYTES) ? 1 : -1];
typedef char zs_check_active[(sizeof(zs_active) == ZS_ACTIVE_BYTES) ? 1 : -1];
typedef char zs_check_aplane[(sizeof(zs_active_plane) == ZS_ACTIVE_PLANE_BYTES) ? 1 : -1];
typedef char zs_check_acolor[(sizeof(zs_active_color) == ZS_ACTIVE_COLOR_BYTES) ? 1 : -1];

/* Paths that real frames seldom take (clipping, needles, lighting set-up):
 * kept out of line and built for size, so the hot code around them stays
 * small and its stack frames do not carry their locals. */
#if defined(__GNUC__)
#define ZS_COLD __attribute__((cold, noinline))
#define ZS_NOINLINE __attribute__((noinline)) /* off a caller's frame, or one copy */
#define ZS_INLINE_ALWAYS __attribute__((always_inline)) inline /* a second caller elsewhere */
#else
#define ZS_INLINE_ALWAYS
#define ZS_COLD
#define ZS_NOINLINE
#endif

/* ---- integer helpers (fixed.c) ---- */
static inline int32_t zs_asr32(int32_t v, unsigned s);

int32_t zs_sin_q30(zs_fixed deg);                   /* sine, Q2.30 */
extern const zs_mat34 zs_identity34;                /* zs_mat34_identity() */
/* A divisor prepared for repeated divisions: one hardware-free 64/32 division
 * instead of one per quotient (plane gradients share their triangle's area). */
typedef struct zs_recip {
    uint32_t inv;
    int32_t exp;
    int32_t neg;
} zs_recip;
void zs_recip_init(zs_recip *rc, int64_t d); /* d != 0 */
/* floor(2^61 / d) for d in [2^30, 2^31), in (2^30, 2^31]. */
uint32_t zs_recip61(uint32_t d);
/* floor((nh * 2^32 + nl) / v) for v >= 2^31 and nh < v (32-bit steps only). */
uint32_t zs_udiv64_32(uint32_t nh, uint32_t nl, uint32_t v);
/* num * 2^bits / d to 31 significant bits (toward zero), clamped to +-limit;
 * for |num| < 2^62. */
int64_t zs_recip_muldiv(const zs_recip *rc, int64_t num, int bits, int64_t limit);
/* round(a * b / 65536) for |a| < 2^47 and any int32 b. */
int64_t zs_mul_q16_wide(int64_t a, int32_t b);
/* a * b / c for c > 0 and 0 <= b <= c (so |result| <= |a|), |a| < 2^63:
 * toward zero, or rounded half away from zero when round is non-zero.
 * Exact through a 128-bit product where a * b does not fit 64 bits. */
int64_t zs_muldiv64(int64_t a, int64_t b, int64_t c, int round);
/* out = a x b, exact (each product in 64 bits). */
void zs_cross3(const int32_t a[3], const int32_t b[3], int64_t out[3]);
/* round(sum a[i] * b[i] / 65536) without overflow for any int32 inputs. */
int64_t zs_dot3_q16(const int32_t a[3], const int32_t b[3]);
/* Shrink a vector by powers of two until every |component| < limit. */
void zs_shrink3(int64_t v[3], int64_t limit);
/* Unit vector (Q16.16) in the direction of v; 0 if v is zero. */
int zs_normalize3(const int64_t v[3], int32_t out[3]);

/* ---- pipeline stages ---- */
/* geometry.c: transform, light, cull, clip, hand triangles to setup */
/* setup.c */
typedef struct zs_svert {        /* a vertex on its way to setup */
    int64_t xc, yc, w;           /* clip space, Q16.16, never saturated */
    uint32_t shade;
    uint16_t pool;               /* pool index when already projected, else ZS_NONE */
    int16_t uv[2];               /* texture coordinates (ZS_CFG_TEXTURE) */
} zs_svert;
enum { ZS_SETUP_STORED, ZS_SETUP_CULLED, ZS_SETUP_EMPTY, ZS_SETUP_REJECTED, ZS_SETUP_DROPPED };
/* Projects a clip-space vertex into the pool; returns its index or ZS_NONE. */
/* The vertex must be inside the near, far and guard-band planes (its outcode
 * has none of ZS_OUT_NEAR, ZS_OUT_FAR, ZS_OUT_GUARD): then w fits 32 bits. */
uint16_t zs_project_vertex(zs_renderer *r, int64_t xc, int64_t yc, int32_t w, uint32_t shade);
/* Projected vertex data without storing it (same arithmetic as above). */
void zs_project(const zs_renderer *r, int64_t xc, int64_t yc, int32_t w, int16_t *x,
                int16_t *y, uint32_t *z);
/* The projection constants of the current frame for zs_project_fast; 0 when
 * it does not apply (depth_scale 0: near close to far). */
typedef struct zs_proj zs_proj;
int zs_proj_init(const zs_renderer *r, zs_proj *p);
/* Twice the signed screen area (1/256 px^2); < 0 for a front face. */
int64_t zs_area2(const zs_vert *a, const zs_vert *b, const zs_vert *c);
/* The same inline (the cull of every triangle): u * v for |u|, |v| < 2^16,
 * on Cortex-M0 as two 32-bit products (v split at bit 8) instead of a call. */
static inline int64_t zs_mul_diff(int32_t u, int32_t v)
{
#if defined(__ARM_ARCH_6M__)
    return (int64_t)(u * (v >= 0 ? v >> 8 : ~(~v >> 8))) * 256 + u * (v & 255);
#else
    return (int64_t)u * v;
#endif
}
static inline int64_t zs_area2_inline(const zs_vert *a, const zs_vert *b, const zs_vert *c)
{
    return zs_mul_diff(b->x - a->x, c->y - a->y) - zs_mul_diff(c->x - a->x, b->y - a->y);
}
/* First row whose pixel centre is at or below y (28.4): ceil(y/16 - 0.5). */
static inline int32_t zs_first_row(int32_t y)
{
    return zs_asr32(y + 7, 4);
}
/* Culls, bounds and stores one screen triangle; returns ZS_SETUP_*. */
/* area2: zs_area2 of the three vertices. */
int zs_setup_triangle(zs_renderer *r, uint16_t v0, uint16_t v1, uint16_t v2, int64_t area2,
                      uint32_t color,
                      uint16_t tag);
/* The triangles idx[0 .. 3n - 1] of a draw whose vertices (base + index) are
 * all projected: culled, bounded and stored as by zs_setup_triangle, and
 * counted. Triangle t's colour is (colors[t] & 0xFFFFFF) | (color's flags
 * byte), or color where colors is NULL; its tag (tag_base + t) % 65535 + 1
 * (tag_base < 65535, n < 65535). */
void zs_setup_run(zs_renderer *r, const uint16_t *idx, uint32_t n, uint16_t base,
                  const zs_color *colors, uint32_t color, uint32_t tag_base);
/* clip.c: clips polygon in[n] against the near/far planes and the guard band;
 * returns the vertex count of out (0..9). out must hold 9; it may be in
 * (in is read only before the first plane that cuts). */
int zs_clip_polygon(const zs_renderer *r, const zs_svert *in, int n, zs_svert *out);
/* Outcodes of a clip-space vertex. */
#define ZS_OUT_NEAR 0x01u
#define ZS_OUT_FAR 0x02u
#define ZS_OUT_GUARD 0x04u    /* beyond the guard band in x or y */
#define ZS_OUT_LEFT 0x10u     /* outside the view frustum (not the guard band) */
#define ZS_OUT_RIGHT 0x20u
#define ZS_OUT_BOTTOM 0x40u
#define ZS_OUT_TOP 0x80u
unsigned zs_outcode(const zs_renderer *r, int64_t xc, int64_t yc, int64_t w);

/* activate.c: edges and planes of a triangle reaching its first row */
/* Makes the triangle's planes and its two edges, appended to the active edge
 * list's unsorted tail; 0 when the pools are full (the triangle is skipped). */
int zs_activate(zs_renderer *r, uint16_t tri, int32_t y);
/* Sets the row constant of a steep plane exactly: the true depth at the
 * centre of column xa on row y when the triangle covers it (xa: its first
 * covered column there, clamped to the screen; 0 <= y <= height). */
void zs_anchor_depth(const zs_renderer *r, const zs_active *a, zs_active_plane *p, int32_t xa,
                     int32_t y);
/* The depth plane of a ZS_ACT_LAZY triangle, as activation would have made
 * it, during row y's walk (a steep one is anchored on row y like the rest). */
void zs_make_plane(zs_renderer *r, zs_active *a, int32_t y);
/* Appends the lower short edge of active triangle ai, starting at row y. */
void zs_continue_edge(zs_renderer *r, uint16_t ai, int32_t y);
/* The same for area.c (Warnock mode, picking): canonical vertex order and
 * depth plane of a record, as zs_activate makes them. */
void zs_canonical_vertices(const zs_renderer *r, const zs_tri *t, const zs_vert *v[3]);
void zs_record_depth_plane(zs_active *a, zs_active_plane *p, const zs_vert *s[3],
                           const zs_recip *area2, int32_t ox, int32_t oy, int32_t y);
/* raster.c's edge scratch (priv.sort_keys, 8 bytes a column; NULL with
 * ZS_CFG_NO_ZLINE): the twin table of the row's batch, 2^k keys (4 bytes:
 * the two vertex indices of an edge made for this row, or ZS_TWIN_EMPTY)
 * and as many edge indices, 2^k the most that fits (at most 128, none for
 * widths under 49; priv.twin_shift = 32 - k, 0 for none); then
 * merge_columns' column lists and columns, 2 (width + 1) bytes each. */
#define ZS_TWIN_EMPTY 0xFFFFFFFFu
#define ZS_TWIN_PROBES 8
static inline unsigned zs_twin_shift(uint32_t width)
{
    return width >= 193u ? 25u : width >= 97u ? 26u : width >= 49u ? 27u : 0u;
}
static inline uint32_t zs_twin_slots(unsigned shift)
{
    return shift ? (0xFFFFFFFFu >> shift) + 1u : 0u;
}
/* raster.c: rows, edges, the active edge list */
void zs_raster_begin(zs_renderer *r);
void zs_raster_row(zs_renderer *r, int y, uint8_t *row); /* row NULL: step only */

/* format.c: pixel packing. Each format's bytes from 8-bit channels, inline
 * so the Gouraud fill packs every pixel without a call. */
static inline void zs_store_rgb565_be(uint8_t *p, uint32_t r, uint32_t g, uint32_t b)
{
    uint32_t v = ((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3);
    p[0] = (uint8_t)(v >> 8);
    p[1] = (uint8_t)v;
}
static inline void zs_store_rgb565(uint8_t *p, uint32_t r, uint32_t g, uint32_t b)
{
    union {
        uint16_t v;
        uint8_t b[2];
    } u; /* the host's byte order */
    u.v = (uint16_t)(((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3));
    p[0] = u.b[0];
    p[1] = u.b[1];
}
static inline void zs_store_rgb666(uint8_t *p, uint32_t r, uint32_t g, uint32_t b)
{
    p[0] = (uint8_t)(r & 0xFCu);
    p[1] = (uint8_t)(g & 0xFCu);
    p[2] = (uint8_t)(b & 0xFCu);
}
static inline void zs_store_gray8(uint8_t *p, uint32_t r, uint32_t g, uint32_t b)
{
    p[0] = (uint8_t)((77u * r + 150u * g + 29u * b) >> 8); /* BT.601 luma */
}
static inline void zs_store_rgb888(uint8_t *p, uint32_t r, uint32_t g, uint32_t b)
{
    p[0] = (uint8_t)r;
    p[1] = (uint8_t)g;
    p[2] = (uint8_t)b;
}
void zs_pack_pixel(zs_format fmt, uint32_t rgb, uint8_t out[4]);
/* The packed pixel as a word whose bytes in memory are the pixel's bytes
 * (what zs_fill_flat writes); a 2-byte pixel is held twice (bytes 0, 1 and
 * 2, 3), so a fill stores the word as it is. */
uint32_t zs_pixel_word(zs_format fmt, uint32_t rgb);
/* The frame's packed background (tag 0 in ZS_FMT_ID16). */
uint32_t zs_background_word(const zs_renderer *r);

/* shade.c: colour planes and the Gouraud span fill */
/* dy: the row's offset from the triangle's y0. */
void zs_fill_gouraud(const zs_renderer *r, const zs_active_color *a, int32_t dy, uint8_t *row,
                     int x0, int x1);
/* Sets the colour planes and flat pixel of an active triangle. */
/* ac: the triangle's colour planes, NULL for a flat-only renderer. */
void zs_shade_setup(const zs_renderer *r, zs_active *a, zs_active_color *ac, const zs_tri *t,
                    const zs_vert *v[3], int32_t ox, int32_t oy, const zs_recip *area2,
                    int32_t y);
/* The flat pixel word of a record's colour word (RGB, or the ID16 tag):
 * what zs_shade_setup sets for a record without per-vertex colour. */
uint32_t zs_flat_pixel(const zs_renderer *r, uint32_t color);
uint32_t zs_light_color(uint32_t rgb, zs_fixed intensity);

/* texture.c: texture mapping (ZS_CFG_TEXTURE) */
typedef struct zs_tex_vert {
    int16_t u, v;   /* zs_mesh.uvs, or interpolated by the clipper */
    uint8_t slot;   /* 1 + index into priv.textures; 0 = untextured */
    uint8_t pad;
} zs_tex_vert;
typedef struct zs_active_tex {
    uint64_t q[3], s[3], t[3]; /* planes (row y0 at column 0, per column, per
                                  row), wrapping: 1/w, s/w, t/w (texel
                                  coordinates in 1/256 texel) */
    uint32_t f[3];             /* fog plane, Q8.16 wrapping (same layout) */
    uint32_t serial;           /* priv.tex_serial of the frame it was made in */
    int32_t s_base, t_base;    /* whole texels added to the texel indices */
    int32_t s_max, t_max;      /* the texel coordinates' range (1/256 texel) */
    int32_t q_min_hi;          /* smallest vertex 1/w, plane units >> 16 */
    int16_t y0;                /* the activation row the planes refer to */
    uint8_t slot, flags;       /* texture slot; ZS_ATEX_* */
    uint16_t tri;              /* the record they were made for (with serial and
                                  y0: made on the first span, for the record in
                                  that active slot) */
    uint16_t pad[3];
} zs_active_tex;
#define ZS_ATEX_FOG 0x01u      /* fogged */
typedef char zs_check_tex_vert[(sizeof(zs_tex_vert) == ZS_TEX_VERTEX_BYTES) ? 1 : -1];
typedef char zs_check_atex[(sizeof(zs_active_tex) == ZS_ACTIVE_TEX_BYTES) ? 1 : -1];
/* zs_draw: checks a mesh's texture and takes its frame slot (*slot 0 for an
 * untextured mesh); an error stores nothing. */
zs_status zs_tex_draw(zs_renderer *r, const zs_mesh *m, uint8_t *slot);
/* The texture coordinates of the draw's vertices base .. base + n - 1. */
void zs_tex_vertices(zs_renderer *r, const zs_mesh *m, uint16_t base, uint32_t n, uint8_t slot);
/* Fills [x0, x1) of row y with active triangle ai's texture (its record
 * ZS_TRI_TEXTURED; its light in the colour planes); makes the texture planes
 * on the triangle's first span. */
void zs_fill_textured(const zs_renderer *r, uint16_t ai, int32_t y, uint8_t *row, int x0,
                      int x1);

/* span.c / zline.c: one row's visibility */
void zs_span_row(zs_renderer *r, int y, uint8_t *row);
void zs_zline_row(zs_renderer *r, int y, uint8_t *row);
/* priority.c: one row by list priority (ZS_MODE_PRIORITY) */
void zs_priority_row(zs_renderer *r, int y, uint8_t *row);
/* bsp.c: the next triangle range [*t, *end) of a zs_draw_bsp walk; 0 at its end */
int zs_next_range(zs_renderer *r, uint32_t *t, uint32_t *end);

/* floor(v / 2^s) for either sign. Shifting ~v keeps the operand non-negative
 * (well defined in C99); compilers emit a single arithmetic shift. */
static inline int64_t zs_asr64(int64_t v, unsigned s)
{
    return v < 0 ? ~(~v >> s) : v >> s;
}

static inline int32_t zs_asr32(int32_t v, unsigned s)
{
    return v < 0 ? ~(~v >> s) : v >> s;
}

/* Clamps to +-INT32_MAX (symmetric, so negation stays defined) and counts
 * the clamps in *saturated when it is not NULL. */
static inline int32_t zs_sat32(int64_t v, uint32_t *saturated)
{
    if (v > INT32_MAX || v < -INT32_MAX) {
        if (saturated)
            (*saturated)++;
        return v > 0 ? INT32_MAX : -INT32_MAX;
    }
    return (int32_t)v;
}

/* ---- products without the Cortex-M0 helper ----
 * Cortex-M0 has no 32x32->64 multiply: each 64-bit product is a call of
 * __aeabi_lmul. These give the same exact results from 32-bit products
 * there (ZS_SPLIT_PRODUCTS selects them elsewhere, for the tests). */
#if defined(__ARM_ARCH_6M__) || defined(ZS_SPLIT_PRODUCTS)
#define ZS_SPLIT_MUL 1
#endif

/* a * b where |a| / 2^32 * |b| < 2^31 and |b| < 2^15 (for example |a| <=
 * 2^48 with a row or column offset): depth planes. */
static inline int64_t zs_mul64_small(int64_t a, int32_t b)
{
#ifdef ZS_SPLIT_MUL
    /* a = hi * 2^32 + mid * 2^16 + low with hi = floor(a / 2^32) and mid,
     * low in [0, 2^16): each partial product fits 32 bits */
    int32_t hi = (int32_t)zs_asr64(a, 32);
    uint32_t lo32 = (uint32_t)((uint64_t)a & 0xFFFFFFFFu);
    int32_t mid = (int32_t)(lo32 >> 16), low = (int32_t)(lo32 & 0xFFFFu);
    return (int64_t)(hi * b) * 4294967296 + (int64_t)(mid * b) * 65536 + low * b;
#else
    return a * b;
#endif
}

/* a * b for any 32-bit unsigned a and b. */
static inline uint64_t zs_umul32(uint32_t a, uint32_t b)
{
#ifdef ZS_SPLIT_MUL
    uint32_t al = a & 0xFFFFu, ah = a >> 16, bl = b & 0xFFFFu, bh = b >> 16;
    uint32_t ll = al * bl, mid1 = al * bh, mid2 = ah * bl, hh = ah * bh;
    uint32_t mid = mid1 + mid2, carry = mid < mid1 ? 0x10000u : 0u;
    uint32_t lo = ll + (mid << 16);
    hh += (mid >> 16) + carry + (lo < ll ? 1u : 0u);
    return ((uint64_t)hh << 32) | lo;
#else
    return (uint64_t)a * b;
#endif
}

/* a * b for |a| < 2^31 and |b| < 2^31 (products of differences). */
static inline int64_t zs_smul32(int32_t a, int32_t b)
{
#ifdef ZS_SPLIT_MUL
    uint32_t ua = a < 0 ? 0u - (uint32_t)a : (uint32_t)a;
    uint32_t ub = b < 0 ? 0u - (uint32_t)b : (uint32_t)b;
    uint64_t p = zs_umul32(ua, ub);
    return (a < 0) != (b < 0) ? -(int64_t)p : (int64_t)p;
#else
    return (int64_t)a * b;
#endif
}

/* Depth (Q40) of active triangle a at the centre of column 0 of row y. */
static inline int64_t zs_row_depth(const zs_active_plane *p, const zs_active *a, int32_t y)
{
    return p->zrow + zs_mul64_small(p->zdy, y - a->y0);
}

static inline int32_t zs_clampi(int32_t v, int32_t lo, int32_t hi)
{
    return v < lo ? lo : (v > hi ? hi : v);
}

/* ---- the projection of a vertex (front end: setup.c, geometry.c) ---- */
/* floor(2^61 / d) for d in [2^30, 2^31) without a 64-bit division, where a
 * 32-bit division is one instruction (not with ZS_SPLIT_MUL, see fixed.c):
 * y0 = 2^46 / round(d / 2^15) is within eps in [-2^-16, 2^-15] of 2^61 / d;
 * y0 (1 + eps + eps^2) is then within 2^-13 of it, and every truncation
 * below rounds down (the -1/256 too), so y lands on the floor or one short,
 * which the 32-bit remainder 2^61 - d y in [0, 2d) settles. Checked for all
 * 2^30 divisors against the division (tests/core/test_fixed.c samples). */
static inline uint32_t zs_recip61_fast(uint32_t d)
{
    uint32_t dh = (d + 0x4000u) >> 15;                 /* [2^15, 2^16] */
    uint32_t y = (0xFFFFFFFFu / dh) << 14;             /* < 2^31 */
    int64_t e = ((int64_t)1 << 61) - (int64_t)((uint64_t)d * y); /* 2^61 eps, < 2^47 */
    int32_t f = (int32_t)zs_asr64(e, 16);
    int64_t t = (int64_t)(int32_t)y * f;               /* y eps 2^45 */
    int32_t th = (int32_t)zs_asr64(t, 32);
    int64_t t2 = (int64_t)th * f;                      /* y eps^2 2^58 */
    /* y eps + y eps^2 - 1/256, in 1/256 units */
    int32_t c8 = zs_asr32(th, 5) + (int32_t)zs_asr64(t2, 50) - 1;
    uint32_t rem;
    y += (uint32_t)zs_asr32(c8, 8);
    rem = 0u - d * y; /* 2^61 - d y mod 2^32, exact: it is below 2d < 2^32 */
    return rem >= d ? y + 1u : y;
}

/* A frame's projection constants (zs_proj_init) for zs_project_fast. */
struct zs_proj {
    int64_t xk, yk;       /* 2^28 hw + 2^27 and 2^28 hh + 2^27 - 1: x and y's
                             offset and rounding in one constant */
    int32_t hw, nhh;      /* 8 * width and -8 * height (1/16 px) */
    uint32_t near_z;      /* the camera's near, Q16 */
    uint32_t ds_lo, ds_hi;/* priv.depth_scale's words (it is not 0) */
};

/* Number of left shifts that bring 0 < v < 2^31 into [2^30, 2^31); the
 * shifted value in *norm. Cortex-M0 has no clz instruction (a libgcc call):
 * there a binary search of five steps. */
static ZS_INLINE_ALWAYS unsigned zs_norm_shift(uint32_t v, uint32_t *norm)
{
#if defined(__GNUC__) && __SIZEOF_INT__ == 4 && !defined(__ARM_ARCH_6M__)
    unsigned s = (unsigned)__builtin_clz(v) - 1u;
    *norm = v << s;
    return s;
#elif ZS_SMALL_
    unsigned s = 0, k;
    for (k = 16; k > 0; k >>= 1)
        if (v < ((uint32_t)1 << (31u - k))) {
            v <<= k;
            s += k;
        }
    *norm = v;
    return s;
#else
    /* unrolled, each step's test by a shift (no constant to load) */
    unsigned s = 0;
#define ZS_NORM_STEP(k)                                                                   \
    if ((v >> (31u - (k))) == 0) {                                                        \
        v <<= (k);                                                                        \
        s += (k);                                                                         \
    }
    ZS_NORM_STEP(16u)
    ZS_NORM_STEP(8u)
    ZS_NORM_STEP(4u)
    ZS_NORM_STEP(2u)
    ZS_NORM_STEP(1u)
#undef ZS_NORM_STEP
    *norm = v;
    return s;
#endif
}

/* a * b for a, b <= 2^31: on Cortex-M0 the two middle products' sum then
 * fits 32 bits (no carry out of it); inline where called. */
static ZS_INLINE_ALWAYS uint64_t zs_umul31(uint32_t a, uint32_t b)
{
#ifdef ZS_SPLIT_MUL
    uint32_t al = a & 0xFFFFu, ah = a >> 16, bl = b & 0xFFFFu, bh = b >> 16;
    uint32_t ll = al * bl, mid = al * bh + ah * bl, hh = ah * bh;
    uint32_t lo = ll + (mid << 16);
    hh += (mid >> 16) + (lo < ll ? 1u : 0u);
    return ((uint64_t)hh << 32) | lo;
#else
    return (uint64_t)a * b;
#endif
}

/* a * b for |a| < 2^31, b <= 2^31. */
static inline int64_t zs_mul_su32(int32_t a, uint32_t b)
{
#ifdef ZS_SPLIT_MUL
    uint32_t ua = a < 0 ? 0u - (uint32_t)a : (uint32_t)a;
    uint64_t p = zs_umul32(ua, b);
    return a < 0 ? -(int64_t)p : (int64_t)p;
#else
    return (int64_t)a * (int64_t)b;
#endif
}

/* a * b for any int32 a and |b| < 2^15: on Cortex-M0 two 32-bit products
 * (a split at bit 16) instead of a call. */
static inline int64_t zs_mul_32x16(int32_t a, int32_t b)
{
#ifdef ZS_SPLIT_MUL
    int32_t hi = zs_asr32(a, 16), lo = (int32_t)((uint32_t)a & 0xFFFFu);
    return (int64_t)(hi * b) * 65536 + lo * b;
#else
    return (int64_t)a * b;
#endif
}

/* The low word of v / 2^k (1 <= k <= 31) from v's two words: no 64-bit shift
 * (a libgcc call on Cortex-M0, a branch on k elsewhere). */
static inline uint32_t zs_shr64_lo(uint64_t v, unsigned k)
{
    return ((uint32_t)v >> k) | ((uint32_t)(v >> 32) << (32u - k));
}

/* An int32 from its two's-complement bits (compilers emit nothing). */
static inline int32_t zs_s32(uint32_t u)
{
    return u < 0x80000000u ? (int32_t)u : -(int32_t)~u - 1;
}

/* An edge's run word (zs_edge) from its end row and step; its step; whether
 * it ends by row `row` (compared as the low halves, shifted up: one compare
 * with a shift on Thumb-2, row << 16 made once a row). */
static inline uint32_t zs_edge_run(int32_t y_end, int32_t step)
{
    return (uint32_t)step << 16 | (uint32_t)y_end;
}
static inline int32_t zs_run_step(uint32_t run)
{
    return zs_asr32(zs_s32(run), 16);
}
static inline int zs_run_ends(uint32_t run, uint32_t row_hi)
{
    return row_hi >= run << 16;
}

/* zs_project (setup.c), the same results, for a vertex with near <= w <= far,
 * w < 2^29 and |xc|, |yc| <= 7 w (inside the guard band, or off it by a
 * clipper's rounding) and below 2^31, when depth_scale is not 0: then xc / w
 * in Q28 fits 32 bits, and so do the depth's words. With inside set the
 * vertex is within the guard band, |xc|, |yc| <= guard * w: then x and y
 * need no clamp, as |xc| * inv / 2^(33 - s) <= guard * 2^28 (inv <= 2^61 /
 * (w 2^s)) puts x within hw +- guard * hw, inside +-(guard + 1) 8 width <=
 * 32767 (the guard's definition, renderer.c), and y likewise. */
static ZS_INLINE_ALWAYS void zs_project_body(const zs_proj *p, int32_t xc, int32_t yc,
                                              int32_t w, zs_vert *v, int inside, int narrow)
{
    uint32_t d, inv, q, m, zz;
    unsigned s = zs_norm_shift((uint32_t)w, &d); /* 2..30 */
    int32_t nx, ny, x, y;
    uint64_t dz;
#ifdef ZS_SPLIT_MUL
    inv = zs_recip61(d);
#else
    inv = zs_recip61_fast(d);
#endif
    /* floor(xc * inv / 2^(33 - s)): xc / w in Q28 */
#ifdef ZS_SPLIT_MUL
    /* (the products inline: |xc|, |yc| < 2^31) */
    nx = zs_s32(zs_shr64_lo(xc < 0 ? 0u - zs_umul31(0u - (uint32_t)xc, inv)
                                   : zs_umul31((uint32_t)xc, inv), 33u - s));
    ny = zs_s32(zs_shr64_lo(yc < 0 ? 0u - zs_umul31(0u - (uint32_t)yc, inv)
                                   : zs_umul31((uint32_t)yc, inv), 33u - s));
#else
    nx = zs_s32(zs_shr64_lo((uint64_t)zs_mul_su32(xc, inv), 33u - s));
    ny = zs_s32(zs_shr64_lo((uint64_t)zs_mul_su32(yc, inv), 33u - s));
#endif
    if (narrow) { /* ds_hi is 0 and near below 2^30: q by the same shift as nx */
        q = zs_shr64_lo(zs_umul32(p->near_z << 2, inv), 33u - s);
        dz = zs_umul32(0x40000000u - q, p->ds_lo);
    } else {
        q = zs_shr64_lo(zs_umul31(p->near_z, inv), 31u - s); /* near / w, Q30, <= 2^30 */
        m = 0x40000000u - q;
        dz = zs_umul32(m, p->ds_lo) + ((uint64_t)(m * p->ds_hi) << 32);
    }
    zz = zs_shr64_lo(dz, 30); /* under 2^30 + 16 for w <= far */
    x = (int32_t)zs_asr64(p->xk + zs_mul_32x16(nx, p->hw), 28);
    y = (int32_t)zs_asr64(p->yk + zs_mul_32x16(ny, p->nhh), 28);
    if (!inside) {
        x = zs_clampi(x, -32767, 32767);
        y = zs_clampi(y, -32767, 32767);
    }
    v->x = (int16_t)x;
    v->y = (int16_t)y;
    v->z = zz > 0x40000000u ? 0x40000000u : zz;
}

static inline void zs_project_fast(const zs_proj *p, int32_t xc, int32_t yc, int32_t w,
                                   zs_vert *v, int inside)
{
    zs_project_body(p, xc, yc, w, v, inside, 0);
}

/* Built for size, one copy out of line (setup.c) serves zs_project and the
 * draw loop; else inline in each. ZS_PROJECT_NARROW: a vertex inside the
 * guard band where ds_hi is 0 and near_z below 2^30. */
#if defined(__OPTIMIZE_SIZE__)
void zs_project_fast_out(const zs_proj *p, int32_t xc, int32_t yc, int32_t w, zs_vert *v,
                         int inside);
#define ZS_PROJECT_FAST zs_project_fast_out
#define ZS_PROJECT_NARROW(p, xc, yc, w, v) zs_project_fast_out(p, xc, yc, w, v, 1)
#else
#define ZS_PROJECT_FAST zs_project_fast
#define ZS_PROJECT_NARROW(p, xc, yc, w, v) zs_project_body(p, xc, yc, w, v, 1, 1)
#endif

/* ---- span fills (inline: they run once per span) ---- */
#if defined(__GNUC__)
/* Word stores into the caller's byte buffer; may_alias keeps them legal. */
typedef uint32_t zs_word_alias __attribute__((may_alias));
typedef uint16_t zs_half_alias __attribute__((may_alias));
#define ZS_WORD_STORES 1
#endif

#ifdef ZS_WORD_STORES
/* Words q[0 .. 4 * blocks - 1] = w for blocks >= 1; returns the word after
 * them. On Thumb a store-multiple writes 16 bytes in one instruction: two of
 * them per loop pass cost 4 instructions per 32 bytes, where single stores
 * cost 7 per 16 (the background and long spans are most of a row's bytes). */
#if defined(__thumb__)
static inline zs_word_alias *zs_store_blocks(zs_word_alias *q, uint32_t blocks, uint32_t w)
{
    register uint32_t w0 __asm__("r2") = w;
    register uint32_t w1 __asm__("r3") = w;
    register uint32_t w2 __asm__("r4") = w;
    register uint32_t w3 __asm__("r5") = w;
    __asm__ volatile(".syntax unified\n"
                     "    lsrs %1, %1, #1\n" /* pairs of blocks; C: one more */
                     "    bcc 2f\n"
                     "    stmia %0!, {%2, %3, %4, %5}\n"
                     "2:  beq 3f\n" /* Z still from lsrs: no pair */
                     "1:  stmia %0!, {%2, %3, %4, %5}\n"
                     "    stmia %0!, {%2, %3, %4, %5}\n"
                     "    subs %1, %1, #1\n"
                     "    bne 1b\n"
                     "3:\n"
                     : "+l"(q), "+l"(blocks)
                     : "l"(w0), "l"(w1), "l"(w2), "l"(w3)
                     : "cc", "memory");
    return q;
}
#else
static inline zs_word_alias *zs_store_blocks(zs_word_alias *q, uint32_t blocks, uint32_t w)
{
    for (; blocks > 0; blocks--, q += 4) {
        q[0] = w;
        q[1] = w;
        q[2] = w;
        q[3] = w;
    }
    return q;
}
#endif
#endif

/* n pixels of 2 bytes from p; pair holds the pixel twice (its bytes in
 * memory are b0 b1 b0 b1, as zs_pixel_word packs 2-byte formats), so it is
 * stored as it is, a word or a half at a time. */
static inline void zs_fill2(uint8_t *p, int n, uint32_t pair)
{
#ifdef ZS_WORD_STORES
    if (((uintptr_t)p & 1u) == 0) {
        zs_word_alias *q;
        if (n <= 0)
            return;
        if ((uintptr_t)p & 2u) {
            *(zs_half_alias *)(void *)p = (uint16_t)pair; /* both halves are the pixel */
            p += 2;
            n--;
        }
        q = (zs_word_alias *)(void *)p;
        if (n >= 8) {
            q = zs_store_blocks(q, (uint32_t)n >> 3, pair);
            n &= 7;
        }
        if (n & 4) { /* the rest (under 8): two words, a word, a half */
            q[0] = pair;
            q[1] = pair;
            q += 2;
        }
        if (n & 2)
            *q++ = pair;
        if (n & 1)
            *(zs_half_alias *)(void *)q = (uint16_t)pair;
        return;
    }
#endif
    {
        union {
            uint32_t w;
            uint8_t b[4];
        } u;
        u.w = pair;
        for (; n > 0; n--, p += 2) {
            p[0] = u.b[0];
            p[1] = u.b[1];
        }
    }
}

static inline void zs_fill_flat_body(uint8_t *row, int x0, int x1, unsigned bpp,
                                     uint32_t pixel)
{
    union {
        uint32_t w;
        uint8_t b[4];
    } u;
    uint8_t *p = row + (size_t)x0 * bpp;
    int n = x1 - x0;
    u.w = pixel;
    if (bpp == 2) {
        zs_fill2(p, n, pixel);
    } else if (bpp == 1) {
        for (; n > 0; n--)
            *p++ = u.b[0];
    } else {
        for (; n > 0; n--, p += 3) {
            p[0] = u.b[0];
            p[1] = u.b[1];
            p[2] = u.b[2];
        }
    }
}

/* Pixels x0 .. x1-1 of row set to a packed pixel. Built for size, one copy
 * out of line (format.c) serves both visibility modes; else inline. */
#if defined(__OPTIMIZE_SIZE__)
void zs_fill_flat(uint8_t *row, int x0, int x1, unsigned bpp, uint32_t pixel);
#else
static inline void zs_fill_flat(uint8_t *row, int x0, int x1, unsigned bpp, uint32_t pixel)
{
    zs_fill_flat_body(row, x0, x1, bpp, pixel);
}
#endif

/* abuffer.c: the A-buffer resolve (ZS_CFG_ABUFFER) */
void *zs_abuffer_carve(zs_renderer *r, uint8_t **cursor); /* its pools, from the arena */
void zs_abuffer_frame(zs_renderer *r);                    /* zs_frame_begin: mode off */
void zs_abuffer_begin(zs_renderer *r);                    /* first row of a frame */
void zs_abuffer_row(zs_renderer *r, int y, uint8_t *row); /* after the row (rows skipped
                                                             since the last call are stepped) */
void zs_abuffer_rows(zs_renderer *r, int y0, int rows, uint8_t *buf, size_t stride);
/* A triangle that covers no pixel centre, kept for the resolve alone; ZS_SETUP_*. */
ZS_COLD int zs_abuffer_store(zs_renderer *r, uint16_t i0, uint16_t i1, uint16_t i2,
                             uint32_t color, uint16_t tag);
/* shade.c: a record's colour at a vertex with shade word `shade` */
uint32_t zs_vertex_rgb(const zs_renderer *r, const zs_tri *t, uint32_t shade);

#endif
