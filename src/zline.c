/* Scanline z-buffer for one row: one line of depth, each triangle's span
 * walked with z += dz/dx per pixel. Exact for any input at the cost of
 * overdraw; the reference the span mode is tested against. */
#include "zs_internal.h"

void zs_zline_row(zs_renderer *r, int y, uint8_t *row)
{
    const zs_edge *edges = r->priv.edges;
    const uint16_t *ael = r->priv.ael;
    const zs_active *act = r->priv.active;
    int64_t *depth = r->priv.zline_depth;
    uint16_t *owner = r->priv.zline_owner;
    int32_t w = r->cfg.width, x;
    unsigned bpp = r->priv.bpp;
    uint32_t background;
    int i;
    (void)y;
    background = zs_background_word(r);
    zs_fill_flat(row, 0, w, bpp, background);
    r->stats.spans++;
    r->stats.pixels_shaded += (uint32_t)w;
    for (x = 0; x < w; x++) {
        depth[x] = INT64_MAX;
        owner[x] = ZS_NONE;
    }
    for (i = 0; i < r->priv.n_ael; i++) {
        const zs_edge *e = &edges[ael[i]];
        const zs_active *a;
        int32_t xl, xr;
        int64_t z;
        if (e->lead == ZS_NONE)
            continue;
        a = &act[e->lead];
        xl = zs_clampi(e->x, 0, w);
        xr = zs_clampi(edges[a->right].x, 0, w);
        if (xl >= xr)
            continue;
        r->stats.spans++;
        r->stats.depth_evals += (uint32_t)(xr - xl);
        z = a->zrow + a->zdx * xl;
        for (x = xl; x < xr; x++, z += a->zdx) {
            if (z < depth[x] || (z == depth[x] && a->tri < owner[x])) {
                depth[x] = z;
                owner[x] = a->tri;
                if (a->flags & ZS_ACT_GOURAUD)
                    zs_fill_gouraud(r, &r->priv.acolor[e->lead], row, x,
                                    x + 1);
                else
                    zs_fill_flat(row, x, x + 1, bpp, a->pixel);
                r->stats.pixels_shaded++;
            }
        }
    }
}
