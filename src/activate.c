/* SPDX-License-Identifier: MIT */
/* Triangle activation: when a stored triangle reaches its first row, make its
 * two edges from the edge pool and its depth and colour planes.
 *
 * Edges are exact: for the pixel centre row yc the covered columns start at
 * ceil(x(yc) - 0.5), with x(yc) the exact rational on the edge. That value is
 * kept as an integer plus a remainder (a floor-divmod DDA), so a shared edge
 * gives both its triangles the same boundary and nothing cracks. */
#include "zs_internal.h"

/* Inline where speed counts (the arguments stay in registers); one copy in
 * builds for size. */
#if defined(__OPTIMIZE_SIZE__)
#define ZS_HOT_INLINE
#else
#define ZS_HOT_INLINE ZS_INLINE_ALWAYS
#endif

/* Sets e to cover the edge a -> b (a above b) starting at row y. The
 * remainders are found against den = 16 dy and stored divided by 16 (exact
 * for the row steps, zs_edge). */
static void edge_init(zs_edge *e, const zs_vert *a, const zs_vert *b, int32_t y)
{
    int32_t dx = b->x - a->x, dy = b->y - a->y; /* |dx|, dy < 2^16 (int16 vertices), dy > 0 */
    int32_t den = 16 * dy;
    /* (x(yc) - 0.5) * den at yc = 16 y + 8, split as 16 * q0 * dy + m so the
     * part left to divide is small: q0 = floor((x_a - 8) / 16). */
    int32_t q0 = zs_asr32(a->x - 8, 4), r0 = a->x - 8 - 16 * q0;
    int32_t t = 16 * y + 8 - a->y; /* in [0, 16) on the edge's first row */
    int32_t x, err, step, rem;
    const int32_t y_end = zs_first_row(b->y);
    e->dy = (uint16_t)dy;
    if (y_end > y + 1) {
        step = dx / dy;
        if (step * dy > dx)
            step--; /* floor */
        rem = dx - step * dy; /* in [0, dy) */
        e->run = zs_edge_run(y_end, step);
        if (t < 16) {
            /* the first column from the step, without a second division:
             * with dx = step * dy + rem, m = r0 dy + t dx = 16 dy qa + n for
             * r0 + t step = 16 qa + ra, n = ra dy + t rem in [0, 2 den) */
            const int32_t A = r0 + t * step, qa = zs_asr32(A, 4);
            const int32_t n = (A - 16 * qa) * dy + t * rem;
            const int32_t c = n > den ? 2 : n > 0 ? 1 : 0; /* ceil(n / den) */
            e->x = q0 + qa + c;
            e->frac = (uint32_t)((c * den - n) >> 4) << 16 | (uint32_t)rem;
            return;
        }
    } else { /* covers one row: never stepped (a division saved, a helper call on M0);
              * it ends after row y (its end row as y + 1: 0 < y_end) */
        e->run = zs_edge_run(y + 1, 0);
        rem = 0;
    }
    if (t < 16) {
        int32_t m = r0 * dy + t * dx; /* |m| < 2^24 */
        int32_t q = m / den;
        if (m - q * den > 0)
            q++; /* ceil */
        x = q0 + q;
        err = q * den - m;
    } else { /* starts above the screen: the numerator needs 64 bits */
        int64_t m = (int64_t)r0 * dy + (int64_t)t * dx;
        int64_t q = m / den;
        if (m - q * den > 0)
            q++;
        x = q0 + (int32_t)q;
        err = (int32_t)(q * den - m);
    }
    e->x = x;
    e->frac = (uint32_t)(err >> 4) << 16 | (uint32_t)rem;
}

/* Depth planes hold window depth in Q40 (10 bits below the vertices' Q30, so
 * stepping across a row adds no visible error). The gradient is
 * num * 2^14 / area2 (num in Q30 * 1/16 px, area in 1/256 px^2), to 31
 * significant bits, clamped to 256 depth ranges per pixel.
 *
 * Needles: along a thin triangle the two gradients can be huge and nearly
 * cancel, so their rounding (or the clamp) would put the depth at a covered
 * pixel centre far off. Such a plane is marked steep and gets its constant
 * exactly on every row instead of by stepping: zs_anchor_depth evaluates the
 * true plane at the row's first covered column. Within one row a steep plane
 * needs no more: two covered centres of a row differ by at most one depth
 * range, so wherever a row has two, |zdx| is that small and exact enough;
 * where it has one, only the anchored column is ever evaluated. */
#define ZS_DEPTH_GRADIENT_LIMIT ((int64_t)1 << 48)
/* Steep when |zdx| * width + |zdy| * height (Q40 per pixel, times pixels)
 * reaches 2^46: the gradients' rounding (2^-29 relative) could then move a
 * covered centre's depth by 2^17 Q40 = 2^-23, approaching the 2^-20 that the
 * documented tolerance allows. */
#define ZS_STEEP_SPREAD ((int64_t)1 << 46)

static int64_t abs64(int64_t v)
{
    return v < 0 ? -v : v;
}

static int64_t max3_64(int64_t a, int64_t b, int64_t c)
{
    int64_t m = a > b ? a : b;
    return m > c ? m : c;
}

static int64_t min3_64(int64_t a, int64_t b, int64_t c)
{
    int64_t m = a < b ? a : b;
    return m < c ? m : c;
}

#ifdef ZS_SPLIT_MUL
/* a b - c d for |a|, |c| <= 2^30 and |b|, |d| <= 2^14 from 32-bit products:
 * a = 2^16 ah + al with al in [0, 2^16), so the high sum is below 2^29 and
 * the low one below 2^31 in magnitude (inline: at -Os a call each). */
static ZS_INLINE_ALWAYS int64_t cross16(int32_t a, int32_t b, int32_t c, int32_t d)
{
    const int32_t h = zs_asr32(a, 16) * b - zs_asr32(c, 16) * d;
    const int32_t l = (int32_t)((uint32_t)a & 0xFFFFu) * b - (int32_t)((uint32_t)c & 0xFFFFu) * d;
    return (int64_t)h * 65536 + l;
}
#endif

/* Depth plane of the triangle s (canonical order, sorted by y), origin at
 * the pixel centre (ox, oy) next to s[0]; marks it steep where needed. */
static ZS_INLINE_ALWAYS void depth_plane(zs_active *a, zs_active_plane *p, const zs_vert *s[3],
                                         const zs_recip *area2, int32_t ox, int32_t oy, int32_t y,
                                         int small)
{
    int64_t dx1 = (int64_t)s[1]->x - s[0]->x, dy1 = (int64_t)s[1]->y - s[0]->y;
    int64_t dx2 = (int64_t)s[2]->x - s[0]->x, dy2 = (int64_t)s[2]->y - s[0]->y;
    int64_t dz1 = (int64_t)s[1]->z - s[0]->z, dz2 = (int64_t)s[2]->z - s[0]->z;
    int64_t z0, w16, h16;
    /* |dz| <= 2^30, |dx|, |dy| < 2^18: products of 32-bit values */
    int32_t z1 = (int32_t)dz1, z2 = (int32_t)dz2;
    int64_t nx, ny;
    (void)small;
#ifdef ZS_SPLIT_MUL
    /* Cortex-M0: where every |dx|, |dy| <= 2^14 (any triangle of a screen
     * with guard * max(width, height) < 1024), two 32-bit products each
     * (cross16), not zs_smul32's four; in zs_make_plane only (small: the
     * hot caller, one copy of the code) */
    if (small && (((uint32_t)dx1 + 16384u) | ((uint32_t)dy1 + 16384u) | ((uint32_t)dx2 + 16384u) |
         ((uint32_t)dy2 + 16384u)) <= 32768u) {
        nx = cross16(z1, (int32_t)dy2, z2, (int32_t)dy1);
        ny = cross16(z2, (int32_t)dx1, z1, (int32_t)dx2);
    } else
#endif
    {
        nx = zs_smul32(z1, (int32_t)dy2) - zs_smul32(z2, (int32_t)dy1);
        ny = zs_smul32(z2, (int32_t)dx1) - zs_smul32(z1, (int32_t)dx2);
    }
    a->zdx = zs_recip_muldiv(area2, nx, 14, ZS_DEPTH_GRADIENT_LIMIT);
    p->zdy = zs_recip_muldiv(area2, ny, 14, ZS_DEPTH_GRADIENT_LIMIT);
    /* Below 2^32 each, the spread is under 2 * 2^28 * 2^17 = 2^46: the
     * common case needs no products. There the row constant comes in one
     * step: with the origin's terms inside the shift (multiples of 16 shift
     * out exactly) it is the same value, and the products stay below
     * 2^32 * 2^17 (28.4 coordinates fit int16; rows are below 2^11). */
    if ((uint64_t)(abs64(a->zdx) | abs64(p->zdy)) < ((uint64_t)1 << 32)) {
        p->zrow = (int64_t)s[0]->z * 1024 +
                  zs_asr64(zs_mul64_small(a->zdx, 8 - s[0]->x) +
                               zs_mul64_small(p->zdy, 16 * y + 8 - s[0]->y),
                           4);
        a->y0 = (int16_t)y;
        return;
    }
    /* extents in 1/16 px (<= 2^17), plus a pixel for the centres around */
    w16 = max3_64(0, dx1, dx2) - min3_64(0, dx1, dx2) + 16;
    h16 = dy2 + 16;
    /* gradients <= 2^48: at >> 4 each product stays below 2^62 */
    if ((abs64(a->zdx) >> 4) * w16 + (abs64(p->zdy) >> 4) * h16 >= ZS_STEEP_SPREAD)
        a->flags |= ZS_ACT_STEEP;
    /* depth at the origin pixel centre, from vertex 0 (less than a pixel away) */
    z0 = (int64_t)s[0]->z * 1024 +
         zs_asr64(zs_mul64_small(a->zdx, 16 * ox + 8 - s[0]->x) +
                      zs_mul64_small(p->zdy, 16 * oy + 8 - s[0]->y),
                  4);
    /* |ox|, |oy| < 2^13 (the guard band), gradients <= 2^48 */
    p->zrow = z0 + zs_mul64_small(p->zdy, y - oy) - zs_mul64_small(a->zdx, ox);
    a->y0 = (int16_t)y;
}

/* The depth range the span walk decides by without evaluating planes. At a
 * covered centre the true plane lies between the vertex depths, and an
 * evaluation differs from it by less than 2^24 Q40: for a non-steep plane by
 * the gradients' rounding (relative 2^-30) over its extent, under
 * 2^46 * 2^-30 + 2^14; for a steep one by its zdx's rounding alone (|zdx| <=
 * 2^40 wherever a row holds two covered centres) over fewer than
 * ZS_MAX_DIM = 2^10 columns, under 2^11 * 2^10. */
static void depth_range(zs_active *a, const zs_vert *s[3])
{
    uint32_t z0 = s[0]->z, z1 = s[1]->z, z2 = s[2]->z;
    uint32_t lo = z0 < z1 ? z0 : z1, hi = z0 < z1 ? z1 : z0;
    if (z2 < lo)
        lo = z2;
    if (z2 > hi)
        hi = z2;
    /* Q30 depths <= 2^30; one 2^-15 unit (2^15 Q30 = 2^25 Q40) of slack on
     * each side: zlo = floor(lo / 2^15) - 1, zhi = floor(hi / 2^15) + 2 */
    lo >>= 15;
    a->zlo = (uint16_t)(lo > 0 ? lo - 1u : 0u);
    a->zhi = (uint16_t)((hi >> 15) + 2u);
}

/* A vertex's place in the canonical order as one unsigned key: y, then x
 * (each biased so signed order becomes unsigned order). */
static ZS_INLINE_ALWAYS uint32_t order_key(const zs_vert *p)
{
#if defined(__GNUC__) && defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ && \
    (!defined(__arm__) || defined(__ARM_FEATURE_UNALIGNED))
    uint32_t w; /* x in the low half, y in the high: one load (ARMv6-M makes it a call) */
    __builtin_memcpy(&w, p, sizeof w);
    return w ^ 0x80008000u;
#else
    return ((uint32_t)(uint16_t)p->y << 16 | (uint16_t)p->x) ^ 0x80008000u;
#endif
}

/* The triangle's vertices in a canonical order: by y, then by x. Two
 * vertices of a stored triangle never share both, so equal triangles get
 * equal edges and equal planes however their vertices were rotated. */
static ZS_HOT_INLINE void sort_canonical(const zs_renderer *r, const zs_tri *t,
                                         const zs_vert *v[3])
{
    const zs_vert *pool = r->priv.verts, *p0, *p1, *p2, *tp;
    uint32_t k0, k1, k2, tk;
    p0 = &pool[t->v[0]];
    p1 = &pool[t->v[1]];
    p2 = &pool[t->v[2]];
    k0 = order_key(p0);
    k1 = order_key(p1);
    k2 = order_key(p2);
#define ZS_ORDER(ka, pa, kb, pb)                                                          \
    if (ka > kb) {                                                                        \
        tk = ka; ka = kb; kb = tk;                                                        \
        tp = pa; pa = pb; pb = tp;                                                        \
    }
    ZS_ORDER(k0, p0, k1, p1)
    ZS_ORDER(k1, p1, k2, p2)
    ZS_ORDER(k0, p0, k1, p1)
#undef ZS_ORDER
    v[0] = p0;
    v[1] = p1;
    v[2] = p2;
}

/* A lazy plane's record (span and zline modes) is read by nothing until
 * zs_make_plane makes it (span.c's depth_at, zline.c's new_row_depth): until
 * then it holds the canonical vertices, so that neither zs_make_plane nor
 * zs_continue_edge sorts them again. */
static ZS_INLINE_ALWAYS void stash_canonical(zs_active_plane *pl, const zs_vert *s[3])
{
    pl->zcur = (int64_t)(uintptr_t)s[0];
    pl->zrow = (int64_t)(uintptr_t)s[1];
    pl->zdy = (int64_t)(uintptr_t)s[2];
}

static ZS_INLINE_ALWAYS void unstash_canonical(const zs_active_plane *pl, const zs_vert *s[3])
{
    s[0] = (const zs_vert *)(uintptr_t)pl->zcur;
    s[1] = (const zs_vert *)(uintptr_t)pl->zrow;
    s[2] = (const zs_vert *)(uintptr_t)pl->zdy;
}

void zs_anchor_depth(const zs_renderer *r, const zs_active *a, zs_active_plane *pl, int32_t xa,
                     int32_t y)
{
    const zs_vert *s[3];
    zs_vert p; /* the pixel centre: 0 <= xa, y <= ZS_MAX_DIM, so it fits int16 */
    int64_t d, l0, l1, l2, z;
    sort_canonical(r, &r->priv.tris[a->tri], s);
    p.x = (int16_t)(16 * xa + 8);
    p.y = (int16_t)(16 * y + 8);
    /* twice the area, and the barycentric numerators of s[1] and s[2] at
     * the centre (edge functions; all below 2^35) */
    d = zs_area2(s[0], s[1], s[2]);
    l1 = zs_area2(s[2], s[0], &p);
    l2 = zs_area2(s[0], s[1], &p);
    if (d < 0) {
        d = -d;
        l1 = -l1;
        l2 = -l2;
    }
    l0 = d - l1 - l2;
    z = (int64_t)s[0]->z * 1024;
    /* a centre outside is never evaluated: any bounded value will do */
    if (l0 >= 0 && l1 >= 0 && l2 >= 0)
        z += zs_muldiv64(((int64_t)s[1]->z - s[0]->z) * 1024, l1, d, 1) +
             zs_muldiv64(((int64_t)s[2]->z - s[0]->z) * 1024, l2, d, 1);
    /* stored for row y0: row y's constant comes back exactly */
    pl->zrow = z - zs_mul64_small(a->zdx, xa) - zs_mul64_small(pl->zdy, y - a->y0);
}

/* Takes an edge from the pool for a -> b, owned by ai on one side, and
 * appends it to the list's unsorted tail. Where the row's batch already has
 * an edge from the same two vertices with that side free (the neighbour
 * across a shared edge), that record serves both: the fold merge_columns
 * would make, without making and sorting the twin. */
static ZS_HOT_INLINE uint16_t new_edge(zs_renderer *r, uint16_t ai, int left_side,
                                       const zs_vert *a, const zs_vert *b, int32_t y)
{
    zs_edge *const edges = r->priv.edges;
    const unsigned shift = r->priv.twin_shift;
    uint32_t *const keys = r->priv.sort_keys;
    uint16_t ei = ZS_NONE;
    zs_edge *e;
    if (shift) {
        /* the vertices' byte offsets in the pool (multiples of 8, < 2^19) */
        const char *pool = (const char *)r->priv.verts;
        const uint32_t mask = 0xFFFFFFFFu >> shift;
        const uint32_t key = (uint32_t)((const char *)a - pool) << 13 |
                             (uint32_t)((const char *)b - pool) >> 3;
        uint16_t *const index = (uint16_t *)(void *)(keys + mask + 1u);
        uint32_t h = (key * 0x9E3779B1u) >> shift;
        int p;
        for (p = ZS_TWIN_PROBES; p > 0; p--, h = (h + 1u) & mask) {
            const uint32_t k = keys[h];
            if (k == key) {
                ei = index[h];
                e = &edges[ei];
                if (left_side) {
                    if (e->lead == ZS_NONE) {
                        e->lead = ai;
                        return ei;
                    }
                } else if (e->trail == ZS_NONE) {
                    e->trail = ai;
                    r->priv.active[ai].right = ei;
                    return ei;
                }
                ei = ZS_NONE;
            } else if (k == ZS_TWIN_EMPTY) {
                /* listed before the set-up, so nothing of the table stays
                 * live across it (else no room near: not listed) */
                ei = r->priv.edge_free[--r->priv.n_edge_free];
                keys[h] = key;
                index[h] = ei;
                break;
            }
        }
    }
    if (ei == ZS_NONE)
        ei = r->priv.edge_free[--r->priv.n_edge_free];
    e = &edges[ei];
    edge_init(e, a, b, y);
    /* pad is merge_columns' to set */
    e->lead = left_side ? ai : (uint16_t)ZS_NONE;
    e->trail = left_side ? (uint16_t)ZS_NONE : ai;
    r->priv.ael[r->priv.n_ael++] = ei;
    if (!left_side)
        r->priv.active[ai].right = ei;
    return ei;
}

int zs_activate(zs_renderer *r, uint16_t ti, int32_t y)
{
    zs_tri *t = &r->priv.tris[ti];
    const zs_vert *pool = r->priv.verts;
    const zs_vert *v[3], *s[3];
    uint16_t ai, long_edge, short_edge;
    zs_active *a;
    int64_t cross;
    zs_recip area2;
    int long_left, plane_made = 0; /* area2 holds the area's reciprocal */
    const int lazy = r->priv.mode == ZS_MODE_SPAN || r->priv.mode == ZS_MODE_ZLINE;
    if (r->priv.n_active_free < 1 || r->priv.n_edge_free < 2) {
        r->stats.records_skipped++; /* capacity policy: the triangle is skipped */
        return 0;
    }
    ai = r->priv.active_free[--r->priv.n_active_free];
    a = &r->priv.active[ai];
    sort_canonical(r, t, s);
    /* twice the area in canonical order; its sign says which side of the
     * long edge top -> bottom the middle vertex lies on */
    cross = zs_area2_inline(s[0], s[1], s[2]);
    long_left = cross > 0; /* middle vertex to the right: the long edge leads */
    a->tri = ti;
    a->inside = 0;
    a->set_pos = 0;
    a->cross = -1; /* zline.c: no row depth cached */
    a->y_end = (int16_t)zs_first_row(s[2]->y);
    if (lazy) {
        /* the span walk or the z-buffer line makes the plane if it ever
         * evaluates one */
        a->flags = long_left ? ZS_ACT_LONG_LEFT | ZS_ACT_LAZY : ZS_ACT_LAZY;
        depth_range(a, s);
    } else {
        a->flags = long_left ? ZS_ACT_LONG_LEFT : 0;
    }
    long_edge = new_edge(r, ai, long_left, s[0], s[2], y);
    if (y < zs_first_row(s[1]->y))
        short_edge = new_edge(r, ai, !long_left, s[0], s[1], y);
    else
        short_edge = new_edge(r, ai, !long_left, s[1], s[2], y);
    a->y0 = (int16_t)y;
    if (lazy) {
        stash_canonical(&r->priv.aplane[ai], s); /* for zs_make_plane, zs_continue_edge */
    } else if (r->priv.mode != ZS_MODE_PRIORITY) { /* priority: decided by record order */
        zs_active_plane *pl = &r->priv.aplane[ai];
        plane_made = 1;
        zs_recip_init(&area2, cross);
        /* the depth plane from the canonical order: equal triangles, equal planes */
        depth_plane(a, pl, s, &area2, zs_asr32(s[0]->x, 4), zs_asr32(s[0]->y, 4), y, 0);
        if (a->flags & ZS_ACT_STEEP) {
            r->priv.steep = 1;
            zs_anchor_depth(r, a, pl,
                            zs_clampi(r->priv.edges[long_left ? long_edge : short_edge].x,
                                      0, r->cfg.width),
                            y);
        }
    }
    if ((t->color >> 24) == 0 || !r->priv.vshade) {
        /* one colour (flags cleared above): no planes, no vertices */
        a->pixel = zs_flat_pixel(r, t->color);
    } else {
        /* colours in submission order (per-vertex shades follow t->v); the
         * record's area is negative in that order (a front face). Only
         * colour planes need the area's reciprocal here where no plane was
         * made. */
        v[0] = &pool[t->v[0]];
        v[1] = &pool[t->v[1]];
        v[2] = &pool[t->v[2]];
        if (!plane_made)
            zs_recip_init(&area2, cross);
        area2.neg = 1;
        zs_shade_setup(r, a, r->priv.acolor ? &r->priv.acolor[ai] : 0, t, v,
                       zs_asr32(v[0]->x, 4), zs_asr32(v[0]->y, 4), &area2, y);
    }
    r->stats.tris_drawn++;
    return 1;
}

void zs_make_plane(zs_renderer *r, zs_active *a, int32_t y)
{
    const zs_vert *s[3];
    zs_recip area2;
    const uint16_t ai = (uint16_t)(a - r->priv.active);
    zs_active_plane *pl = &r->priv.aplane[ai];
    unstash_canonical(pl, s); /* made lazy by zs_activate (span, zline) */
    zs_recip_init(&area2, zs_area2_inline(s[0], s[1], s[2]));
    depth_plane(a, pl, s, &area2, zs_asr32(s[0]->x, 4), zs_asr32(s[0]->y, 4), a->y0, 1);
    a->flags &= (uint8_t)~ZS_ACT_LAZY;
    if (a->flags & ZS_ACT_STEEP) {
        /* anchored on this row at its left edge, as every row is from here
         * on (found in the list: needles are rare) */
        int i;
        r->priv.steep = 1;
        for (i = 0; i < r->priv.n_ael; i++) {
            const zs_edge *e = &r->priv.edges[r->priv.ael[i]];
            if (e->lead == ai) {
                zs_anchor_depth(r, a, pl, zs_clampi(e->x, 0, r->cfg.width), y);
                break;
            }
        }
    }
}

void zs_continue_edge(zs_renderer *r, uint16_t ai, int32_t y)
{
    zs_active *a = &r->priv.active[ai];
    const zs_vert *s[3];
    int left_side = !(a->flags & ZS_ACT_LONG_LEFT);
    uint16_t ei;
    if (a->flags & ZS_ACT_LAZY)
        unstash_canonical(&r->priv.aplane[ai], s);
    else
        sort_canonical(r, &r->priv.tris[a->tri], s);
    ei = new_edge(r, ai, left_side, s[1], s[2], y);
    if (left_side && (a->flags & ZS_ACT_STEEP))
        zs_anchor_depth(r, a, &r->priv.aplane[ai], zs_clampi(r->priv.edges[ei].x, 0, r->cfg.width),
                        y);
}

/* Warnock mode and picking (centre.c) evaluate records without activating
 * them: the same canonical order and plane, so the same depths (cold: off
 * the hot code). */
ZS_COLD void zs_canonical_vertices(const zs_renderer *r, const zs_tri *t, const zs_vert *v[3])
{
    sort_canonical(r, t, v);
}

ZS_COLD void zs_record_depth_plane(zs_active *a, zs_active_plane *p, const zs_vert *s[3],
                                   const zs_recip *area2, int32_t ox, int32_t oy, int32_t y)
{
    depth_plane(a, p, s, area2, ox, oy, y, 0);
}
