/* SPDX-License-Identifier: MIT */
/* Projection, snapping and triangle setup: screen vertices in 28.4, window
 * depth in Q2.30, back-face culling by the sign of the snapped area, and
 * compact triangle records bucketed by their first row.
 *
 * Ranges: the guard band keeps |x|, |y| of every projected vertex below
 * 2.5 * 2048 px = 2^17 in 28.4, so edge numerators stay below 2^37 and twice
 * the area below 2^37 (see raster.c). */
#include "zs_internal.h"

int zs_proj_init(const zs_renderer *r, zs_proj *p)
{
    int64_t hw = 8 * (int64_t)r->cfg.width, hh = 8 * (int64_t)r->cfg.height;
    uint64_t ds = (uint64_t)r->priv.depth_scale;
    p->hw = (int32_t)hw;
    p->nhh = (int32_t)-hh;
    p->xk = hw * ((int64_t)1 << 28) + ((int64_t)1 << 27);
    p->yk = hh * ((int64_t)1 << 28) + ((int64_t)1 << 27) - 1;
    p->near_z = (uint32_t)r->cam.near_z;
    p->ds_lo = (uint32_t)(ds & 0xFFFFFFFFu);
    p->ds_hi = (uint32_t)(ds >> 32);
    return ds != 0;
}

/* |v| * inv for inv < 2^32 and a product below 2^64 (so the high word of
 * |v| times inv fits 32 bits). */
static uint64_t mag_mul(uint64_t m, uint32_t inv)
{
    return zs_umul32((uint32_t)(m & 0xFFFFFFFFu), inv) +
           ((uint64_t)((uint32_t)(m >> 32) * inv) << 32);
}

/* floor(v * inv / 2^sh) for |v| * inv < 2^64: the magnitude is formed
 * unsigned, as |v| may reach guard * w and the product 2^63. */
static int64_t mul_floor_shift(int64_t v, uint32_t inv, unsigned sh)
{
    if (v >= 0)
        return (int64_t)(mag_mul((uint64_t)v, inv) >> sh);
    return -(int64_t)((mag_mul((uint64_t)0 - (uint64_t)v, inv) + (((uint64_t)1 << sh) - 1u)) >> sh);
}

#if defined(__OPTIMIZE_SIZE__)
void zs_project_fast_out(const zs_proj *p, int32_t xc, int32_t yc, int32_t w, zs_vert *v,
                         int inside)
{
    zs_project_body(p, xc, yc, w, v, inside, 0); /* inline here: no second call */
}
#endif

/* |v| <= 7 w (for w < 2^28: then v fits 32 bits). */
static int within7(int64_t v, int32_t w)
{
    return v >= -7 * (int64_t)w && v <= 7 * (int64_t)w;
}

/* One division per vertex: 1/w as a normalised reciprocal, then products.
 *   w * 2^s in [2^30, 2^31), inv = 2^61 / (w * 2^s) in (2^30, 2^31],
 *   xc / w = xc * inv * 2^(s - 61).
 * Inside the guard band |xc|, |yc| <= guard * w, so xc / w fits Q28 easily.
 * Window depth z = far (w - near) / ((far - near) w) = A (1 - near / w) with
 * A = far / (far - near) precomputed per frame (depth_scale, Q30). The
 * common case, w below 2^28 (4096 units), in 32-bit words (zs_project_fast);
 * far vertices and near close to far here. */
void zs_project(const zs_renderer *r, int64_t xc, int64_t yc, int32_t w, int16_t *x,
                int16_t *y, uint32_t *z)
{
    int64_t hw = 8 * (int64_t)r->cfg.width; /* half the width in 1/16 px */
    int64_t hh = 8 * (int64_t)r->cfg.height;
    unsigned s;
    uint32_t inv, d;
    int64_t nx, ny, q, zz;
    zs_proj p;
    /* (a small build: this path only, the same results in fewer bytes) */
    if (!ZS_SMALL_ && w < ((int32_t)1 << 28) && w >= r->cam.near_z && w <= r->cam.far_z &&
        within7(xc, w) && within7(yc, w) && zs_proj_init(r, &p)) {
        zs_vert v;
        ZS_PROJECT_FAST(&p, (int32_t)xc, (int32_t)yc, w, &v, 0);
        *x = v.x;
        *y = v.y;
        *z = v.z;
        return;
    }
    s = zs_norm_shift((uint32_t)w, &d);
    inv = zs_recip61(d);
    nx = mul_floor_shift(xc, inv, 33u - s); /* xc / w in Q28 */
    ny = mul_floor_shift(yc, inv, 33u - s);
    q = (int64_t)(zs_umul32((uint32_t)r->cam.near_z, inv) >> (31u - s)); /* near / w, Q30 */
    /* the guard band keeps these within int16 (clamped all the same) */
    *x = (int16_t)zs_clampi(
        (int32_t)(hw + zs_asr64(zs_mul64_small(nx, (int32_t)hw) + ((int64_t)1 << 27), 28)), -32767,
        32767);
    *y = (int16_t)zs_clampi(
        (int32_t)(hh - zs_asr64(zs_mul64_small(ny, (int32_t)hh) + ((int64_t)1 << 27), 28)), -32767,
        32767);
    if (q >= ((int64_t)1 << 30)) {
        zz = 0;
    } else if (r->priv.depth_scale != 0) {
        /* (2^30 - q) <= 2^30 times depth_scale < 2^33: its two words */
        uint32_t m = (uint32_t)(((int64_t)1 << 30) - q);
        uint64_t ds = (uint64_t)r->priv.depth_scale;
        zz = (int64_t)((zs_umul32(m, (uint32_t)(ds & 0xFFFFFFFFu)) +
                        ((uint64_t)(m * (uint32_t)(ds >> 32)) << 32)) >> 30);
    } else { /* near close to far: A too large for the product */
        int64_t f = r->cam.far_z;
        zz = (((int64_t)1 << 30) - q) * f / (f - r->cam.near_z);
    }
    *z = (uint32_t)(zz > ((int64_t)1 << 30) ? ((int64_t)1 << 30) : zz);
}

uint16_t zs_project_vertex(zs_renderer *r, int64_t xc, int64_t yc, int32_t w, uint32_t shade)
{
    zs_vert *v;
    if (r->priv.n_verts >= r->cfg.max_vertices) {
        r->stats.verts_dropped++;
        return ZS_NONE;
    }
    v = &r->priv.verts[r->priv.n_verts];
    zs_project(r, xc, yc, w, &v->x, &v->y, &v->z);
    if (r->priv.vshade)
        r->priv.vshade[r->priv.n_verts] = shade;
    r->stats.verts_stored = ++r->priv.n_verts;
    return (uint16_t)(r->priv.n_verts - 1u);
}

int64_t zs_area2(const zs_vert *a, const zs_vert *b, const zs_vert *c)
{
    return zs_area2_inline(a, b, c);
}

/* Edge u -> v's function at the centre (px, py), dx (py - uy) - dy (px - ux),
 * less one unless the edge is a left or top one: then a centre is covered by
 * the top-left rule (inside, or on a left or top edge: the rasterizer's
 * ceil(x - 0.5) edges) exactly where it is >= 0. The edge is a left or top
 * one where dy < 0, or dy = 0 and dx > 0: where dy 2^13 - dx < 0, for
 * |dx|, |dy| < 2^12. */
static int32_t edge_at(int32_t ux, int32_t uy, int32_t dx, int32_t dy, int32_t px, int32_t py)
{
    return dx * (py - uy) - dy * (px - ux) + ~zs_asr32(dy * 8192 - dx, 31);
}

static int32_t span3(int32_t a, int32_t b, int32_t c)
{
    int32_t lo = a < b ? a : b, hi = a < b ? b : a;
    return (c > hi ? c : hi) - (c < lo ? c : lo);
}

/* Does the triangle a, b, c (area2 < 0), every coordinate within 2^12 of
 * the others, miss every pixel centre of columns col0 .. col1 - 1, rows
 * row0 .. row1 - 1 (a few centres inside its box)? (0 for a wider one: it
 * is not tested.) Taken as a, c, b (then the area is positive: with y down
 * the edges run clockwise, so a left edge goes up and a top edge goes
 * right); each edge function is stepped from the first centre (below 2^26
 * here). */
static ZS_NOINLINE int misses_centres(const zs_renderer *r, const zs_vert *a, const zs_vert *b,
                                      const zs_vert *c, int32_t row0, int32_t row1,
                                      int32_t col0, int32_t col1)
{
    int32_t ax = a->x, ay = a->y, bx = b->x, by = b->y, cx = c->x, cy = c->y;
    int32_t px = 16 * col0 + 8, py = 16 * row0 + 8, i, j;
    int32_t d0x, d0y, d1x, d1y, d2x, d2y, e0, e1, e2;
    /* a box the screen did not cut spans under 16 (rows + 1) in y (x
     * likewise): within 2^12 */
    if ((row0 == 0 || row1 == (int32_t)r->cfg.height || col0 == 0 ||
         col1 == (int32_t)r->cfg.width) &&
        (span3(ax, bx, cx) >= 4096 || span3(ay, by, cy) >= 4096))
        return 0;
    d0x = cx - ax;
    d0y = cy - ay;
    d1x = bx - cx;
    d1y = by - cy;
    d2x = ax - bx;
    d2y = ay - by;
    e0 = edge_at(ax, ay, d0x, d0y, px, py);
    e1 = edge_at(cx, cy, d1x, d1y, px, py);
    e2 = edge_at(bx, by, d2x, d2y, px, py);
    if ((e0 | e1 | e2) >= 0) /* the first centre */
        return 0;
    if (row1 - row0 + col1 - col0 == 2) /* the only one (the commonest case) */
        return 1;
    for (j = row0; j < row1; j++) {
        int32_t f0 = e0, f1 = e1, f2 = e2;
        for (i = col0; i < col1; i++) {
            if ((f0 | f1 | f2) >= 0)
                return 0;
            f0 -= 16 * d0y;
            f1 -= 16 * d1y;
            f2 -= 16 * d2y;
        }
        e0 += 16 * d0x;
        e1 += 16 * d1x;
        e2 += 16 * d2x;
    }
    return 1;
}

/* The bounding box of a triangle: a sorting network of the three, two
 * compares each way. */
static inline void box3(const zs_vert *a, const zs_vert *b, const zs_vert *c, int32_t *xmin,
                        int32_t *xmax, int32_t *ymin, int32_t *ymax)
{
    int32_t ax = a->x, bx = b->x, cx = c->x, ay = a->y, by = b->y, cy = c->y;
    int32_t lo = ax < bx ? ax : bx, hi = ax < bx ? bx : ax;
    *xmin = cx < lo ? cx : lo;
    *xmax = cx > hi ? cx : hi;
    lo = ay < by ? ay : by;
    hi = ay < by ? by : ay;
    *ymin = cy < lo ? cy : lo;
    *ymax = cy > hi ? cy : hi;
}

int zs_setup_triangle(zs_renderer *r, uint16_t i0, uint16_t i1, uint16_t i2, int64_t area2,
                      uint32_t color, uint16_t tag)
{
    const zs_vert *pool = r->priv.verts;
    const zs_vert *a = &pool[i0], *b = &pool[i1], *c = &pool[i2];
    int32_t xmin, xmax, ymin, ymax, row0, row1, col0, col1;
    zs_tri *t;
    uint16_t *bucket = r->priv.buckets;
    /* counter-clockwise seen from the camera is clockwise with y down */
    if (area2 >= 0)
        return ZS_SETUP_CULLED;
    box3(a, b, c, &xmin, &xmax, &ymin, &ymax);
    if (xmax <= 0 || ymax <= 0 || xmin >= 16 * (int32_t)r->cfg.width ||
        ymin >= 16 * (int32_t)r->cfg.height)
        return ZS_SETUP_REJECTED;
    /* pixel centres covered by the bounding box, within the screen: one
     * bound each, as ymin < 16 height puts its first row at or above height
     * and ymax > 0 puts its first row at or below 0 (x likewise) */
    row0 = zs_first_row(ymin);
    row0 = row0 < 0 ? 0 : row0;
    row1 = zs_first_row(ymax);
    row1 = row1 > (int32_t)r->cfg.height ? (int32_t)r->cfg.height : row1;
    col0 = zs_first_row(xmin);
    col0 = col0 < 0 ? 0 : col0;
    col1 = zs_first_row(xmax);
    col1 = col1 > (int32_t)r->cfg.width ? (int32_t)r->cfg.width : col1;
    if (row0 >= row1 || col0 >= col1 ||
        ((row1 - row0) * (col1 - col0) <= 4 && misses_centres(r, a, b, c, row0, row1, col0, col1))) {
        if (ZS_HAS_ABUFFER && r->priv.aa_mode)
            return zs_abuffer_store(r, i0, i1, i2, color, tag);
#ifndef ZS_NO_MONO
        if (r->priv.line_keep && r->priv.n_tris < r->cfg.max_triangles) {
            /* hidden lines: kept out of the buckets, never rendered */
            t = &r->priv.tris[r->priv.n_tris++];
            t->v[0] = i0;
            t->v[1] = i1;
            t->v[2] = i2;
            t->color = tag;
        }
#endif
        return ZS_SETUP_EMPTY;
    }
    if (r->priv.n_tris >= r->cfg.max_triangles) {
        r->stats.records_dropped++;
        return ZS_SETUP_DROPPED; /* capacity policy: the last triangles are dropped */
    }
    t = &r->priv.tris[r->priv.n_tris];
    t->v[0] = i0;
    t->v[1] = i1;
    t->v[2] = i2;
    t->color = (ZS_HAS_FORMATS || ZS_HAS_MONO) && r->shade.format == ZS_FMT_ID16 ? tag : color;
    t->next = bucket[row0];
    bucket[row0] = r->priv.n_tris;
    r->priv.n_tris++;
    r->stats.records++;
    if (r->priv.setup_hook) {
        const zs_vert *v[3];
        int32_t xy[6];
        uint32_t z[3];
        int k;
        v[0] = a;
        v[1] = b;
        v[2] = c;
        for (k = 0; k < 3; k++) {
            xy[2 * k] = v[k]->x;
            xy[2 * k + 1] = v[k]->y;
            z[k] = v[k]->z;
        }
        r->priv.setup_hook(r->priv.setup_hook_user, tag, xy, z);
    }
    return ZS_SETUP_STORED;
}

/* Is a, b, c a back face (zs_area2 >= 0)? On Cortex-M0 the area's two
 * products in 32 bits when every difference is below 2^14 (as in every small
 * triangle: each product below 2^28), not the split 64-bit ones. */
static inline int back_face(const zs_vert *a, const zs_vert *b, const zs_vert *c)
{
#ifdef ZS_SPLIT_MUL
    int32_t ux = b->x - a->x, uy = b->y - a->y, vx = c->x - a->x, vy = c->y - a->y;
    if ((((uint32_t)ux + 16384u) | ((uint32_t)uy + 16384u) | ((uint32_t)vx + 16384u) |
         ((uint32_t)vy + 16384u)) < 32768u)
        return ux * vy - vx * uy >= 0;
#endif
    return zs_area2_inline(a, b, c) >= 0;
}

/* (both word loops read a vertex's x as the low half of a word: little-endian only) */
#if defined(__ARM_FEATURE_SIMD32) && defined(ZS_WORD_STORES) && defined(__BYTE_ORDER__) && \
    __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
#define SIMD_AREA 1
/* Twice the area of a, b, c, for differences within int16: each vertex's x,
 * y as one word (x the low half), both differences at once (ssub16), and
 * ux vy - uy vx by one dual multiply (smusdx: each product below 2^30). */
static inline int32_t area2_simd(uint32_t pa, uint32_t pb, uint32_t pc)
{
    uint32_t u, v;
    int32_t s;
    __asm__(".syntax unified\n"
            "    ssub16 %1, %4, %3\n"
            "    ssub16 %2, %5, %3\n"
            "    smusdx %0, %1, %2\n"
            : "=r"(s), "=&r"(u), "=&r"(v)
            : "r"(pa), "r"(pb), "r"(pc));
    return s;
}

/* The least and greatest x and y of three such words, both halves at once:
 * ssub16 sets each half's GE flag where the first is at least the second
 * (by the exact difference), sel takes each half by its flag. */
static inline void box_simd(uint32_t pa, uint32_t pb, uint32_t pc, uint32_t *lo, uint32_t *hi)
{
    uint32_t t, mn, mx;
    __asm__(".syntax unified\n"
            "    ssub16 %2, %3, %4\n"
            "    sel %0, %4, %3\n"
            "    sel %1, %3, %4\n"
            "    ssub16 %2, %0, %5\n"
            "    sel %0, %5, %0\n"
            "    ssub16 %2, %5, %1\n"
            "    sel %1, %5, %1\n"
            : "=&r"(mn), "=&r"(mx), "=&r"(t)
            : "r"(pa), "r"(pb), "r"(pc));
    *lo = mn;
    *hi = mx;
}

static inline uint32_t vert_word(const zs_vert *v)
{
    return *(const zs_word_alias *)(const void *)v;
}
#endif

/* The state of zs_setup_run's plain loop (no A-buffer, hidden lines, setup
 * hook or tag format), in locals once plain_tri is inlined. */
typedef struct plain_run {
    const zs_renderer *r;
    const zs_vert *pool; /* the draw's first vertex */
    zs_tri *tris;
    uint16_t *bucket;
    const zs_color *colors;
    uint32_t color, flags, nt, cap, rejected, empty, dropped, base;
    int32_t width, height;
} plain_run;

/* Front face t (indices idx[0..2], vertices a, b, c) with its bounding box:
 * zs_setup_triangle's decisions. */
static ZS_INLINE_ALWAYS void plain_front(plain_run *p, const uint16_t *idx, uint32_t t,
                                         const zs_vert *a, const zs_vert *b, const zs_vert *c,
                                         int32_t xmin, int32_t xmax, int32_t ymin, int32_t ymax)
{
    int32_t row0, row1, col0, col1;
    zs_tri *rec;
    if (xmax <= 0 || ymax <= 0 || xmin >= 16 * p->width || ymin >= 16 * p->height) {
        p->rejected++;
        return;
    }
    row0 = zs_first_row(ymin);
    row0 = row0 < 0 ? 0 : row0;
    row1 = zs_first_row(ymax);
    row1 = row1 > p->height ? p->height : row1;
    col0 = zs_first_row(xmin);
    col0 = col0 < 0 ? 0 : col0;
    col1 = zs_first_row(xmax);
    col1 = col1 > p->width ? p->width : col1;
    if (row0 >= row1 || col0 >= col1 ||
        ((row1 - row0) * (col1 - col0) <= 4 &&
         misses_centres(p->r, a, b, c, row0, row1, col0, col1))) {
        p->empty++;
        return;
    }
    if (p->nt >= p->cap) {
        p->dropped++;
        return;
    }
    rec = &p->tris[p->nt];
    rec->v[0] = (uint16_t)(p->base + idx[0]);
    rec->v[1] = (uint16_t)(p->base + idx[1]);
    rec->v[2] = (uint16_t)(p->base + idx[2]);
    rec->color = p->colors ? (p->colors[t] & 0xFFFFFFu) | p->flags : p->color;
    rec->next = p->bucket[row0];
    p->bucket[row0] = (uint16_t)p->nt;
    p->nt++;
}

/* Triangle t (indices idx[0..2]): the cull, then plain_front. simd (a
 * constant where inlined): differences below 2^14 (Cortex-M0's 32-bit
 * products). */
static ZS_INLINE_ALWAYS void plain_tri(plain_run *p, const uint16_t *idx, uint32_t t, int simd)
{
    const zs_vert *a = &p->pool[idx[0]], *b = &p->pool[idx[1]], *c = &p->pool[idx[2]];
    int32_t xmin, xmax, ymin, ymax;
    (void)simd;
#ifdef ZS_SPLIT_MUL
    if (simd ? (b->x - a->x) * (c->y - a->y) - (c->x - a->x) * (b->y - a->y) >= 0
             : back_face(a, b, c))
#else
    if (back_face(a, b, c))
#endif
        return; /* culled: counted at the end */
    box3(a, b, c, &xmin, &xmax, &ymin, &ymax);
    plain_front(p, idx, t, a, b, c, xmin, xmax, ymin, ymax);
}

#ifdef SIMD_AREA
/* The Cortex-M4 words' loop: the back faces (most of a closed mesh's
 * culled triangles) skipped in an assembly loop of 14 instructions each
 * (area2_simd's cull), which stops at a front face with its words. */
static ZS_INLINE_ALWAYS void plain_simd(plain_run *p, const uint16_t *idx, uint32_t n)
{
    const zs_vert *const pool = p->pool;
    const uint16_t *const end = idx + 3u * n;
    uint32_t t = 0;
    while (idx != end) {
        uint32_t pa, pb, pc, v, lo, hi;
        int32_t area;
        __asm__(".syntax unified\n"
                "1:  ldrh %[b], [%[idx], #2]\n"
                "    ldrh %[c], [%[idx], #4]\n"
                "    ldrh %[a], [%[idx]], #6\n"
                "    ldr %[a], [%[pool], %[a], lsl #3]\n"
                "    ldr %[b], [%[pool], %[b], lsl #3]\n"
                "    ldr %[c], [%[pool], %[c], lsl #3]\n"
                "    ssub16 %[s], %[b], %[a]\n"
                "    ssub16 %[v], %[c], %[a]\n"
                "    smusdx %[s], %[s], %[v]\n"
                "    cmp %[s], #0\n"
                "    blt 2f\n"
                "    adds %[t], %[t], #1\n"
                "    cmp %[idx], %[end]\n"
                "    bne 1b\n"
                "2:\n"
                : [idx] "+r"(idx), [t] "+r"(t), [a] "=&r"(pa), [b] "=&r"(pb), [c] "=&r"(pc),
                  [s] "=&r"(area), [v] "=&r"(v)
                : [pool] "r"(pool), [end] "r"(end)
                : "cc", "memory");
        if (area >= 0)
            break; /* the rest were back faces: counted at the end */
        box_simd(pa, pb, pc, &lo, &hi);
        plain_front(p, idx - 3, t, &pool[idx[-3]], &pool[idx[-2]], &pool[idx[-1]],
                    zs_asr32(zs_s32(lo << 16), 16), zs_asr32(zs_s32(hi << 16), 16),
                    zs_asr32(zs_s32(lo), 16), zs_asr32(zs_s32(hi), 16));
        t++;
    }
}
#endif

#if defined(__GNUC__) && defined(__ARM_ARCH_6M__) && defined(__BYTE_ORDER__) && \
    __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
#define CULL_ASM_M0 1
/* Cortex-M0's loop for differences below 2^14 and n < 32768 (t0 the first
 * one's number in the draw): the back
 * faces skipped in an assembly loop of 27 instructions each (the compiler's
 * spills a dozen values), which stops at a front face. Each vertex is one
 * word, x in its low half: sxth(b - ax) is bx - ax (the difference fits
 * int16), b >> 16 is by; the two products (below 2^28) compare as
 * plain_tri's 32-bit cull. */
static ZS_INLINE_ALWAYS void plain_m0(plain_run *p, const uint16_t *idx, uint32_t n, uint32_t t0)
{
    const zs_vert *const pool = p->pool;
    const uint16_t *const start = idx, *const end = idx + 3u * n;
    while (idx != end) {
        uint32_t wa, wb, wc, u, v, t;
        int32_t xmin, xmax, ymin, ymax;
        __asm__(".syntax unified\n"
                "1:  ldrh %[a], [%[idx], #0]\n"
                "    ldrh %[b], [%[idx], #2]\n"
                "    ldrh %[c], [%[idx], #4]\n"
                "    lsls %[a], %[a], #3\n"
                "    lsls %[b], %[b], #3\n"
                "    lsls %[c], %[c], #3\n"
                "    ldr %[a], [%[pool], %[a]]\n"
                "    ldr %[b], [%[pool], %[b]]\n"
                "    ldr %[c], [%[pool], %[c]]\n"
                "    sxth %[u], %[a]\n"
                "    asrs %[a], %[a], #16\n"
                "    subs %[v], %[c], %[u]\n"
                "    sxth %[v], %[v]\n"
                "    subs %[u], %[b], %[u]\n"
                "    sxth %[u], %[u]\n"
                "    asrs %[b], %[b], #16\n"
                "    subs %[b], %[b], %[a]\n"
                "    asrs %[c], %[c], #16\n"
                "    subs %[c], %[c], %[a]\n"
                "    muls %[u], %[c], %[u]\n"
                "    muls %[v], %[b], %[v]\n"
                "    cmp %[u], %[v]\n"
                "    blt 2f\n"
                "    adds %[idx], %[idx], #6\n"
                "    cmp %[idx], %[end]\n"
                "    bne 1b\n"
                "2:\n"
                : [idx] "+l"(idx), [a] "=&l"(wa), [b] "=&l"(wb), [c] "=&l"(wc), [u] "=&l"(u),
                  [v] "=&l"(v)
                /* end high: Thumb-1 GCC reads "r" as a low register, one
                 * past the seven left beside a frame pointer (r7) */
                : [pool] "l"(pool), [end] "h"(end)
                : "cc", "memory");
        if (idx == end)
            break; /* the rest were back faces: counted at the end */
        /* t from 3 t < 98304 halfwords: (3 t * 21846) >> 16 = t + (2 t >> 16) */
        t = t0 + (((uint32_t)(idx - start) * 21846u) >> 16);
        {
            const zs_vert *a = &pool[idx[0]], *b = &pool[idx[1]], *c = &pool[idx[2]];
            box3(a, b, c, &xmin, &xmax, &ymin, &ymax);
            plain_front(p, idx, t, a, b, c, xmin, xmax, ymin, ymax);
        }
        idx += 3;
    }
}
#endif

/* zs_setup_run's loop for the plain frame, one copy for each kind of cull. */
static ZS_NOINLINE void setup_run_plain(zs_renderer *r, const uint16_t *idx, uint32_t n,
                                        uint16_t base, const zs_color *colors, uint32_t color)
{
    plain_run p;
    uint32_t t, first;
    int32_t dim;
    p.r = r;
    p.pool = r->priv.verts + base;
    p.tris = r->priv.tris;
    p.bucket = r->priv.buckets;
    p.colors = colors;
    p.color = color;
    p.flags = color & 0xFF000000u;
    p.nt = first = r->priv.n_tris;
    p.cap = r->cfg.max_triangles;
    p.rejected = p.empty = p.dropped = 0;
    p.base = base;
    p.width = r->cfg.width;
    p.height = r->cfg.height;
    dim = p.width > p.height ? p.width : p.height;
    /* every vertex of the draw is inside the guard band: x within
     * (1 -+ guard) 8 width, so differences within 16 guard width (y
     * likewise): within int16 where guard * max(width, height) < 2048 (the
     * Cortex-M4 words), below 2^14 where it is below 1024 (Cortex-M0's
     * 32-bit products) */
#ifdef SIMD_AREA
    if (r->priv.guard * dim < 2048) {
        plain_simd(&p, idx, n);
    } else {
        for (t = 0; t < n; t++, idx += 3)
            plain_tri(&p, idx, t, 0);
    }
#else
#if defined(ZS_SPLIT_MUL)
    if (r->priv.guard * dim < 1024) {
#else
    if (dim < 0) { /* no such path here */
#endif
#ifdef CULL_ASM_M0
        /* in runs below 32768 triangles (plain_m0's t), one copy of the code */
        uint32_t run;
        for (t = 0; t < n; t += run) {
            run = n - t < 32767u ? n - t : 32767u;
            plain_m0(&p, idx + 3u * t, run, t);
        }
#else
        for (t = 0; t < n; t++, idx += 3)
            plain_tri(&p, idx, t, 1);
#endif
    } else {
        for (t = 0; t < n; t++, idx += 3)
            plain_tri(&p, idx, t, 0);
    }
#endif
    r->priv.n_tris = (uint16_t)p.nt;
    r->stats.records += p.nt - first;
    r->stats.tris_stored += p.nt - first;
    r->stats.tris_culled += n - (p.nt - first) - p.rejected - p.empty - p.dropped;
    r->stats.tris_rejected += p.rejected;
    r->stats.tris_empty += p.empty;
    r->stats.tris_dropped += p.dropped;
    r->stats.records_dropped += p.dropped;
}

void zs_setup_run(zs_renderer *r, const uint16_t *idx, uint32_t n, uint16_t base,
                  const zs_color *colors, uint32_t color, uint32_t tag_base)
{
    const zs_vert *pool = r->priv.verts + base;
    uint32_t t, culled = 0, counts[5] = {0, 0, 0, 0, 0};
    const uint32_t flags = color & 0xFF000000u;
#ifndef ZS_NO_MONO
    const int lines = r->priv.line_keep;
#else
    const int lines = 0;
#endif
    if (!r->priv.aa_mode && !lines && !r->priv.setup_hook && r->shade.format != ZS_FMT_ID16) {
        setup_run_plain(r, idx, n, base, colors, color);
        return;
    }
    for (t = 0; t < n; t++, idx += 3) {
        uint32_t i0 = idx[0], i1 = idx[1], i2 = idx[2], tag = tag_base + t;
        int64_t area2 = zs_area2_inline(&pool[i0], &pool[i1], &pool[i2]);
        if (area2 >= 0) { /* culled before the colour is looked up */
            culled++;
            continue;
        }
        if (tag >= 65535u) /* tag_base + t < 2 * 65535: the tag wraps once */
            tag -= 65535u;
        counts[zs_setup_triangle(r, (uint16_t)(base + i0), (uint16_t)(base + i1),
                                 (uint16_t)(base + i2), area2,
                                 colors ? (colors[t] & 0xFFFFFFu) | flags : color,
                                 (uint16_t)(tag + 1u))]++;
    }
    r->stats.tris_culled += culled + counts[ZS_SETUP_CULLED];
    r->stats.tris_stored += counts[ZS_SETUP_STORED];
    r->stats.tris_empty += counts[ZS_SETUP_EMPTY];
    r->stats.tris_rejected += counts[ZS_SETUP_REJECTED];
    r->stats.tris_dropped += counts[ZS_SETUP_DROPPED];
}
