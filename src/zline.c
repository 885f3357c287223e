/* Scanline z-buffer for one row: one line of depth, each triangle's span
 * walked with z += dz/dx per pixel. Exact for any input at the cost of
 * overdraw; the reference the span mode is tested against. */
#include "zs_internal.h"

void zs_zline_row(zs_renderer *r, int y, uint8_t *row)
{
    const zs_edge *edges = (const zs_edge *)r->edges;
    const uint16_t *ael = (const uint16_t *)r->ael;
    const zs_active *act = (const zs_active *)r->active;
    int64_t *depth = (int64_t *)r->zline_depth;
    uint16_t *owner = (uint16_t *)r->zline_owner;
    int32_t w = r->cfg.width, x;
    unsigned bpp = r->bpp;
    uint8_t bgpx[4];
    uint32_t background;
    int i;
    (void)y;
    zs_pack_pixel(r->shade.format, r->shade.format == ZS_FMT_ID16 ? 0 : r->shade.background,
                  bgpx);
    {
        union {
            uint32_t w;
            uint8_t b[4];
        } u;
        u.b[0] = bgpx[0];
        u.b[1] = bgpx[1];
        u.b[2] = bgpx[2];
        u.b[3] = bgpx[3];
        background = u.w;
    }
    zs_fill_flat(row, 0, w, bpp, background);
    r->stats.spans++;
    r->stats.pixels_shaded += (uint32_t)w;
    for (x = 0; x < w; x++) {
        depth[x] = INT64_MAX;
        owner[x] = ZS_NONE;
    }
    for (i = 0; i < r->n_ael; i++) {
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
                    zs_fill_gouraud(r, &((const zs_active_color *)r->acolor)[e->lead], row, x,
                                    x + 1);
                else
                    zs_fill_flat(row, x, x + 1, bpp, a->pixel);
                r->stats.pixels_shaded++;
            }
        }
    }
}
