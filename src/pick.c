/* SPDX-License-Identifier: MIT */
/* Picking: which stored record a pixel shows, by the rule the renderer
 * draws with (centre.c), from the records alone: the ones whose first row
 * lies within the tallest record's height above the pixel's row are tested
 * at its centre, the covering ones get their depth plane. */
#include "zs_centre.h"

zs_status zs_pick(zs_renderer *r, int x, int y, zs_pick_hit *hit)
{
    const zs_tri *tris;
    int64_t best_z = 0;
    uint16_t best = ZS_PICK_NONE;
    int32_t b;
    if (!r || !hit)
        return ZS_ERR_NULL;
    if (r->priv.state != ZS_STATE_RENDERING && r->priv.state != ZS_STATE_DONE)
        return ZS_ERR_STATE;
    if (x < 0 || y < 0 || x >= (int)r->cfg.width || y >= (int)r->cfg.height)
        return ZS_ERR_ARGUMENT;
    tris = r->priv.tris;
    zs_rec_count_tall(r);
    b = y - (int32_t)r->priv.tall_rows + 1;
    for (b = b < 0 ? 0 : b; b <= y; b++) {
        uint16_t ti;
        for (ti = r->priv.buckets[b]; ti != ZS_NONE; ti = tris[ti].next) {
            zs_rec_view v;
            zs_active a;
            zs_active_plane pl;
            int64_t z;
            zs_rec_view_make(r, ti, &v);
            if (!zs_rec_covers(&v, 16 * x + 8, 16 * y + 8))
                continue;
            zs_rec_planes(r, ti, &v, v.row0, &a, &pl, 0, 0);
            z = zs_rec_depth(r, &v, &a, &pl, x, y);
            if (best == ZS_PICK_NONE || z < best_z || (z == best_z && ti < best)) {
                best = ti;
                best_z = z;
            }
        }
    }
    hit->record = best;
    hit->tag = 0;
    hit->depth_q40 = best == ZS_PICK_NONE ? 0 : best_z;
    hit->depth = best == ZS_PICK_NONE ? 0 : (uint32_t)zs_asr64(best_z, 10);
    if (best != ZS_PICK_NONE && r->shade.format == ZS_FMT_ID16)
        hit->tag = (uint16_t)tris[best].color; /* setup stores the tag there */
    return r->stats.records_skipped ? ZS_ERR_CAPACITY : ZS_OK;
}
