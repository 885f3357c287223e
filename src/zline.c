/* SPDX-License-Identifier: MIT */
/* Scanline z-buffer for one row: a line of owners, each triangle's span
 * tested pixel by pixel against the owner's depth with z += dz/dx per pixel
 * on both planes, then the row written from the owners. Exact for any input
 * at the cost of a depth test per overlapped pixel; the reference the span
 * mode is tested against. A pixel's depth is its owner's plane there, so it
 * is not stored. Work is kept to where spans overlap: a span that overlaps
 * no other is written as it is, runs whose owner's depth range is apart
 * from the triangle's are decided whole, and a plane is made only for
 * triangles that need a depth. */
#include "zs_internal.h"

/* Ends owner runs in test() and write_runs(): no active index (they stay
 * below 2^11) nor ZS_NONE. */
#define SENTINEL 0xFFFEu

/* First column from x on not owned by o; a SENTINEL (no owner) ends the
 * columns reached, so there is no bound test. The owner line is 8-byte
 * aligned in the arena and has two slots past the last column: pairs of
 * owners are compared as words, up to the one holding the sentinel. */
static int32_t run_end(const uint16_t *owner, int32_t x, uint16_t o)
{
#ifdef ZS_WORD_STORES
    const zs_word_alias *wp;
    const uint32_t pair = (uint32_t)o * 0x10001u;
    if (x & 1) {
        if (owner[x] != o)
            return x;
        x++;
    }
    wp = (const zs_word_alias *)(const void *)(owner + x);
    while (*wp == pair)
        wp++;
    x = (int32_t)((const uint16_t *)(const void *)wp - owner);
#endif
    while (owner[x] == o)
        x++;
    return x;
}

/* Writes columns [x0, x1) of the row from their owners: one fill per run of
 * equal owner, so every pixel is written once however much the triangles
 * overlap. */
static void write_runs(zs_renderer *r, int32_t y, uint16_t *owner, uint8_t *row,
                       int32_t x0, int32_t x1)
{
    const zs_active *act = r->priv.active;
    int32_t x = x0;
    unsigned bpp = r->priv.bpp;
    owner[x1] = SENTINEL; /* past the cluster: no one reads it before a set_owner */
    while (x < x1) {
        uint16_t o = owner[x];
        int32_t xs = x;
        x = run_end(owner, x + 1, o);
        if (act[o].flags & ZS_ACT_GOURAUD)
            zs_fill_gouraud(r, &r->priv.acolor[o], y - act[o].y0, row, xs, x);
        else
            zs_fill_flat(row, xs, x, bpp, act[o].pixel);
        r->stats.spans++;
    }
}

/* Columns [x0, x1) of one triangle alone: its span, no owner needed. */
static void write_alone(zs_renderer *r, int32_t y, uint16_t ai, uint8_t *row, int32_t x0,
                        int32_t x1)
{
    const zs_active *a = &r->priv.active[ai];
    if (a->flags & ZS_ACT_GOURAUD)
        zs_fill_gouraud(r, &r->priv.acolor[ai], y - a->y0, row, x0, x1);
    else
        zs_fill_flat(row, x0, x1, r->priv.bpp, a->pixel);
    r->stats.spans++;
}

/* The background over [x0, x1), if not empty. */
static void write_gap(zs_renderer *r, uint8_t *row, int32_t x0, int32_t x1)
{
    if (x1 > x0) {
        zs_fill_flat(row, x0, x1, r->priv.bpp, r->priv.background);
        r->stats.spans++;
    }
}

/* Owners of columns [x0, x1) := o: a 2-byte fill (the pair holds o twice,
 * as zs_fill2 wants; its halves are equal, so byte order does not matter). */
static void set_owner(uint16_t *owner, int32_t x0, int32_t x1, uint16_t o)
{
    zs_fill2((uint8_t *)(void *)(owner + x0), x1 - x0, (uint32_t)o * 0x10001u);
}

/* Depth (Q40) of active triangle ai at column 0 of row y, its plane made
 * first if nothing has needed it yet; kept in zcur for the rest of the row
 * (cross holds the row it is for: the span walk's fields are free in this
 * mode). */
static int64_t new_row_depth(zs_renderer *r, uint16_t ai, int32_t y)
{
    zs_active *a = &r->priv.active[ai];
    zs_active_plane *p = &r->priv.aplane[ai];
    if (a->flags & ZS_ACT_LAZY)
        zs_make_plane(r, a, y);
    p->zcur = zs_row_depth(p, a, y);
    a->cross = y;
    return p->zcur;
}

/* act, pl: the renderer's arrays, passed in locals (owner stores could alias
 * the renderer, so its fields would be loaded again after each). */
static inline int64_t row_depth(zs_renderer *r, const zs_active *act, const zs_active_plane *pl,
                                uint16_t ai, int32_t y)
{
    return act[ai].cross == y ? pl[ai].zcur : new_row_depth(r, ai, y);
}

/* Columns [x0, x1) already reached, tested pixel by pixel against the owner:
 * nearer wins; at equal depth the earlier record (exact ties). A pixel's
 * stored depth is its owner's plane at that column (the owner won there with
 * that depth), so the line keeps owners only: along a run of one owner the
 * difference of the two depths is stepped (d += dz - dz_owner per pixel,
 * exact), started afresh where the owner changes. */
static void test(zs_renderer *r, int32_t y, uint16_t *owner, int32_t x0, int32_t x1,
                 uint16_t ai)
{
    const zs_active *act = r->priv.active;
    const zs_active_plane *pl = r->priv.aplane;
    const uint16_t tri = act[ai].tri, zlo = act[ai].zlo, zhi = act[ai].zhi;
    /* its depth at column 0 of this row: made at the first run whose owner
     * the depth ranges do not decide (a triangle has one span a row, so
     * nothing has cached it yet) */
    int64_t zrow = 0, dz = 0;
    int have_depth = 0;
    uint16_t *q = owner + x0, *const q1 = owner + x1;
    /* a sentinel at x1 (the line has a slot past the last column) ends every
     * run there: no bound test per pixel */
    const uint16_t kept = *q1;
    *q1 = SENTINEL;
    while (q != q1) {
        uint16_t o = *q;
        int64_t d, dd;
        /* depth ranges apart (activate.c): one is nearer at every centre
         * both cover, and no depth is needed */
        if (zhi <= act[o].zlo) {
            do
                *q = ai;
            while (*++q == o);
            continue;
        }
        if (act[o].zhi <= zlo) {
            while (*++q == o)
                ;
            continue;
        }
        if (!have_depth) {
            zrow = new_row_depth(r, ai, y);
            dz = act[ai].zdx;
            have_depth = 1;
        }
        /* d < 0 or (d == 0 and the tie goes to ai): d - tie < 0 (integers) */
        d = zrow - row_depth(r, act, pl, o, y) - (tri < act[o].tri);
        dd = dz - act[o].zdx;
        d += zs_mul64_small(dd, (int32_t)(q - owner));
        do {
            if (d < 0)
                *q = ai;
            d += dd;
        } while (*++q == o);
    }
    *q1 = kept;
}

/* Spans come in order of their left columns (the edge list is sorted), so
 * the row falls into clusters of overlapping spans with gaps between them:
 * a span starting at or right of the cluster's end starts a new one, and the
 * cluster before it is final. A cluster of one span is written as it is;
 * only overlaps go through the owner line and its depth tests. */
void zs_zline_row(zs_renderer *r, int y, uint8_t *row)
{
    const zs_edge *edges = r->priv.edges;
    const uint16_t *ael = r->priv.ael;
    const zs_active *act = r->priv.active;
    uint16_t *owner = r->priv.zline_owner; /* active triangle */
    const int32_t w = r->cfg.width;
    int32_t x0 = 0, x1 = 0; /* the cluster [x0, x1); the row is written up to x0 */
    uint16_t alone = ZS_NONE; /* the cluster's only span, its owners not set */
    uint32_t evals = 0;
    int i;
    for (i = 0; i < r->priv.n_ael; i++) {
        const zs_edge *e = &edges[ael[i]];
        uint16_t ai = e->lead;
        int32_t xl, xr;
        if (ai == ZS_NONE)
            continue;
        xl = zs_clampi(e->x, 0, w);
        xr = zs_clampi(edges[act[ai].right].x, 0, w);
        if (xl >= xr)
            continue;
        evals += (uint32_t)(xr - xl);
        if (xl >= x1) { /* a new cluster: the last one is final */
            if (alone != ZS_NONE)
                write_alone(r, y, alone, row, x0, x1);
            else if (x1 > x0)
                write_runs(r, y, owner, row, x0, x1);
            write_gap(r, row, x1, xl);
            x0 = xl;
            x1 = xr;
            alone = ai;
            continue;
        }
        /* it overlaps the cluster (xl >= x0: spans come in order) */
        if (alone != ZS_NONE) {
            set_owner(owner, x0, x1, alone);
            alone = ZS_NONE;
        }
        test(r, y, owner, xl, xr < x1 ? xr : x1, ai);
        if (xr > x1) {
            set_owner(owner, x1, xr, ai);
            x1 = xr;
        }
    }
    if (alone != ZS_NONE)
        write_alone(r, y, alone, row, x0, x1);
    else if (x1 > x0)
        write_runs(r, y, owner, row, x0, x1);
    write_gap(r, row, x1, w);
    r->stats.depth_evals += evals;
    r->stats.pixels_shaded += (uint32_t)w;
}
