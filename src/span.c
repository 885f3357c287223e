/* Span visibility for one row: walk the x-sorted active edge list, keep the
 * set of triangles the walk is inside, and make one depth decision per span.
 * Two depth planes differ linearly in x along a row, so where a triangle
 * penetrates the one in front, the crossing column is found with one division
 * and the span is split there. Decisions are exact at pixel centres, with
 * ties going to the earlier record, so the result equals the z-buffer mode
 * pixel for pixel. */
#include "zs_internal.h"

static int64_t depth_at(const zs_active *a, int32_t x)
{
    return a->zrow + a->zdx * x;
}

static void fill_span(zs_renderer *r, uint8_t *row, const zs_active *a, int32_t x0, int32_t x1,
                      uint32_t background)
{
    if (!a)
        zs_fill_flat(row, x0, x1, r->bpp, background);
    else if (a->gouraud)
        zs_fill_gouraud(r, a, row, x0, x1);
    else
        zs_fill_flat(row, x0, x1, r->bpp, a->pixel);
    r->stats.spans++;
}

/* Columns [x0, x1) with the in-polygon set fixed: split at crossings. */
static void resolve(zs_renderer *r, uint8_t *row, int32_t x0, int32_t x1, uint32_t background)
{
    zs_active *act = (zs_active *)r->active;
    const uint16_t *set = (const uint16_t *)r->in_set;
    int ns = r->n_set;
    int32_t x = x0;
    if (ns == 0) {
        fill_span(r, row, 0, x0, x1, background);
        return;
    }
    if (ns == 1) {
        fill_span(r, row, &act[set[0]], x0, x1, background);
        return;
    }
    for (;;) {
        zs_active *best = &act[set[0]];
        int64_t bz = depth_at(best, x);
        int32_t end = x1;
        int k;
        best->zcur = bz;
        for (k = 1; k < ns; k++) {
            zs_active *a = &act[set[k]];
            int64_t z = depth_at(a, x);
            a->zcur = z;
            if (z < bz || (z == bz && a->tri < best->tri)) {
                best = a;
                bz = z;
            }
        }
        r->stats.depth_evals += (uint32_t)ns;
        /* the first column where another plane overtakes the winner */
        for (k = 0; k < ns; k++) {
            const zs_active *a = &act[set[k]];
            int64_t slope = best->zdx - a->zdx, gap, steps;
            if (a == best || slope <= 0)
                continue; /* never gets nearer along this row */
            gap = a->zcur - bz; /* >= 0 */
            if (a->tri < best->tri)
                steps = (gap + slope - 1) / slope; /* wins the tie at equality */
            else
                steps = gap / slope + 1;
            if (steps < (int64_t)end - x)
                end = x + (int32_t)steps;
        }
        fill_span(r, row, best, x, end, background);
        if (end >= x1)
            return;
        r->stats.crossings++;
        x = end;
    }
}

void zs_span_row(zs_renderer *r, int y, uint8_t *row)
{
    const zs_edge *edges = (const zs_edge *)r->edges;
    const uint16_t *ael = (const uint16_t *)r->ael;
    zs_active *act = (zs_active *)r->active;
    uint16_t *set = (uint16_t *)r->in_set;
    int32_t w = r->cfg.width, cur = 0;
    int i = 0, n = r->n_ael;
    uint8_t bgpx[4];
    uint32_t background;
    (void)y;
    zs_pack_pixel(r->shade.format, r->shade.format == ZS_FMT_ID16 ? 0 : r->shade.background,
                  bgpx);
    memcpy(&background, bgpx, 4);
    r->n_set = 0;
    for (;;) {
        int32_t ex = i < n ? zs_clampi(edges[ael[i]].x, 0, w) : w;
        if (ex > cur) {
            resolve(r, row, cur, ex, background);
            cur = ex;
        }
        if (i >= n)
            break;
        /* every event at this column before the next span */
        while (i < n && zs_clampi(edges[ael[i]].x, 0, w) == ex) {
            const zs_edge *e = &edges[ael[i]];
            zs_active *a = &act[e->owner];
            if (!e->trailing) {
                if (++a->inside == 1) {
                    a->set_pos = r->n_set;
                    set[r->n_set++] = e->owner;
                }
            } else if (a->inside-- == 1) { /* left the triangle */
                uint16_t last = set[--r->n_set];
                set[a->set_pos] = last;
                act[last].set_pos = a->set_pos;
            }
            i++;
        }
    }
    r->stats.pixels_shaded += (uint32_t)w;
}
