/* SPDX-License-Identifier: MIT */
/* Scanline z-buffer for one row: one line of depth and owner, each
 * triangle's span walked with z += dz/dx per pixel, then the row written from
 * the owners. Exact for any input at the cost of a depth test per covered
 * pixel; the reference the span mode is tested against. */
#include "zs_internal.h"

/* Writes the row from the owners of columns [x0, x1) (background outside):
 * one fill per run of equal owner, so every pixel is written once however
 * much the triangles overlap. */
static void write_runs(zs_renderer *r, const uint16_t *owner, uint8_t *row, int32_t x0,
                       int32_t x1)
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
        while (++x < x1 && owner[x] == o) {
        }
        if (o == ZS_NONE)
            zs_fill_flat(row, xs, x, bpp, background);
        else if (act[o].flags & ZS_ACT_GOURAUD)
            zs_fill_gouraud(r, &r->priv.acolor[o], row, xs, x);
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

void zs_zline_row(zs_renderer *r, int y, uint8_t *row)
{
    const zs_edge *edges = r->priv.edges;
    const uint16_t *ael = r->priv.ael;
    const zs_active *act = r->priv.active;
    int64_t *depth = r->priv.zline_depth;
    uint16_t *owner = r->priv.zline_owner; /* active triangle, or ZS_NONE */
    int32_t w = r->cfg.width, x, x0 = w, x1 = w; /* [x0, x1): columns drawn */
    uint32_t evals = 0;
    int i;
    (void)y;
    for (i = 0; i < r->priv.n_ael; i++) {
        const zs_edge *e = &edges[ael[i]];
        uint16_t ai = e->lead;
        int32_t xl, xr;
        int64_t z, dz;
        uint16_t tri;
        if (ai == ZS_NONE)
            continue;
        xl = zs_clampi(e->x, 0, w);
        xr = zs_clampi(edges[act[ai].right].x, 0, w);
        if (xl >= xr)
            continue;
        evals += (uint32_t)(xr - xl);
        /* the line is cleared only as far as spans reach */
        if (x0 == w) {
            clear(depth, owner, xl, xr);
            x0 = xl;
            x1 = xr;
        } else {
            if (xl < x0) {
                clear(depth, owner, xl, x0);
                x0 = xl;
            }
            if (xr > x1) {
                clear(depth, owner, x1, xr);
                x1 = xr;
            }
        }
        /* locals: the depth stores could otherwise alias the record */
        dz = act[ai].zdx;
        tri = act[ai].tri;
        z = act[ai].zrow + dz * xl;
        for (x = xl; x < xr; x++, z += dz) {
            /* nearer wins; at equal depth the earlier record (exact ties) */
            if (z < depth[x] || (z == depth[x] && tri < act[owner[x]].tri)) {
                depth[x] = z;
                owner[x] = ai;
            }
        }
    }
    r->stats.depth_evals += evals;
    write_runs(r, owner, row, x0, x1);
}
