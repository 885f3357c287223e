/* SPDX-License-Identifier: MIT */
/* Scanline z-buffer for one row: one line of depth and owner, each
 * triangle's span walked with z += dz/dx per pixel, then the row written from
 * the owners. Exact for any input at the cost of a depth test per covered
 * pixel; the reference the span mode is tested against. */
#include "zs_internal.h"

/* First column from x on (up to x1) not owned by o. The owner line is 8-byte
 * aligned in the arena: pairs of owners are compared as words. */
static int32_t run_end(const uint16_t *owner, int32_t x, int32_t x1, uint16_t o)
{
#ifdef ZS_WORD_STORES
    const zs_word_alias *wp;
    uint32_t pair = (uint32_t)o * 0x10001u;
    if ((x & 1) && x < x1) {
        if (owner[x] != o)
            return x;
        x++;
    }
    wp = (const zs_word_alias *)(const void *)(owner + x);
    while (x + 1 < x1 && *wp == pair) {
        wp++;
        x += 2;
    }
#endif
    while (x < x1 && owner[x] == o)
        x++;
    return x;
}

/* Writes the row from the owners of columns [x0, x1) (background outside):
 * one fill per run of equal owner, so every pixel is written once however
 * much the triangles overlap. */
static void write_runs(zs_renderer *r, int32_t y, const uint16_t *owner, uint8_t *row,
                       int32_t x0, int32_t x1)
{
    const zs_active *act = r->priv.active;
    int32_t w = r->cfg.width, x = x0;
    unsigned bpp = r->priv.bpp;
    uint32_t background = r->priv.background;
    if (x0 > 0) {
        zs_fill_flat(row, 0, x0, bpp, background);
        r->stats.spans++;
    }
    while (x < x1) {
        uint16_t o = owner[x];
        int32_t xs = x;
        x = run_end(owner, x + 1, x1, o);
        if (o == ZS_NONE)
            zs_fill_flat(row, xs, x, bpp, background);
        else if (act[o].flags & ZS_ACT_GOURAUD)
            zs_fill_gouraud(r, &r->priv.acolor[o], y - act[o].y0, row, xs, x);
        else
            zs_fill_flat(row, xs, x, bpp, act[o].pixel);
        r->stats.spans++;
    }
    if (x1 < w) {
        zs_fill_flat(row, x1, w, bpp, background);
        r->stats.spans++;
    }
    r->stats.pixels_shaded += (uint32_t)w;
}

static void clear(int64_t *depth, uint16_t *owner, int32_t x0, int32_t x1)
{
    int32_t x;
    for (x = x0; x < x1; x++) {
        depth[x] = INT64_MAX;
        owner[x] = ZS_NONE;
    }
}

/* Columns [x0, x1) that no span of this row has reached yet: taken without a
 * test (what a cleared line would give). z: depth at x0. */
static void take(int64_t *depth, uint16_t *owner, int32_t x0, int32_t x1, int64_t z, int64_t dz,
                 uint16_t ai)
{
    int32_t x;
    for (x = x0; x < x1; x++, z += dz) {
        depth[x] = z;
        owner[x] = ai;
    }
}

/* Columns [x0, x1) already reached: nearer wins; at equal depth the earlier
 * record (exact ties). */
static void test(int64_t *depth, uint16_t *owner, const zs_active *act, int32_t x0, int32_t x1,
                 int64_t z, int64_t dz, uint16_t ai)
{
    uint16_t tri = act[ai].tri; /* a local: the depth stores could alias the record */
    int32_t x;
    for (x = x0; x < x1; x++, z += dz) {
        if (z < depth[x] || (z == depth[x] && tri < act[owner[x]].tri)) {
            depth[x] = z;
            owner[x] = ai;
        }
    }
}

void zs_zline_row(zs_renderer *r, int y, uint8_t *row)
{
    const zs_edge *edges = r->priv.edges;
    const uint16_t *ael = r->priv.ael;
    const zs_active *act = r->priv.active;
    int64_t *depth = r->priv.zline_depth;
    uint16_t *owner = r->priv.zline_owner; /* active triangle, or ZS_NONE */
    int32_t w = r->cfg.width, x0 = w, x1 = w; /* [x0, x1): columns reached */
    uint32_t evals = 0;
    int i;
    for (i = 0; i < r->priv.n_ael; i++) {
        const zs_edge *e = &edges[ael[i]];
        uint16_t ai = e->lead;
        int32_t xl, xr, a, b;
        int64_t z, dz;
        if (ai == ZS_NONE)
            continue;
        xl = zs_clampi(e->x, 0, w);
        xr = zs_clampi(edges[act[ai].right].x, 0, w);
        if (xl >= xr)
            continue;
        evals += (uint32_t)(xr - xl);
        dz = act[ai].zdx;
        z = zs_row_depth(&act[ai], y) + zs_mul64_small(dz, xl);
        if (x0 == w) { /* the row's first span */
            take(depth, owner, xl, xr, z, dz, ai);
            x0 = xl;
            x1 = xr;
            continue;
        }
        /* the part of [xl, xr) within [x0, x1) is tested; the rest is new
         * (a gap between the two ranges is cleared, as the line is cleared
         * only as far as spans reach) */
        a = xl > x0 ? xl : x0;
        b = xr < x1 ? xr : x1;
        if (a < b)
            test(depth, owner, act, a, b, z + zs_mul64_small(dz, a - xl), dz, ai);
        if (xl < x0) {
            b = xr < x0 ? xr : x0;
            take(depth, owner, xl, b, z, dz, ai);
            clear(depth, owner, b, x0);
            x0 = xl;
        }
        if (xr > x1) {
            a = xl > x1 ? xl : x1;
            clear(depth, owner, x1, a);
            take(depth, owner, a, xr, z + zs_mul64_small(dz, a - xl), dz, ai);
            x1 = xr;
        }
    }
    r->stats.depth_evals += evals;
    write_runs(r, y, owner, row, x0, x1);
}
