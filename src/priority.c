/* SPDX-License-Identifier: MIT */
/* List-priority visibility for one row (ZS_MODE_PRIORITY): walk the x-sorted
 * active edge list as the span walk does, keep the set of triangles the walk
 * is inside, and let the one stored first (the lowest record number) be the
 * top. Records are stored in priority order (zs_draw_bsp, or the caller's
 * own order), so the key is the record number itself: no key storage, no
 * depth plane, no crossing. A new top is decided by one comparison when a
 * triangle enters; only when the top leaves is the set scanned. */
#include "zs_internal.h"

/* The member stored first, or NULL for an empty set. */
static zs_active *first_stored(zs_active *act, const uint16_t *set, int ns)
{
    zs_active *best = 0;
    int k;
    for (k = 0; k < ns; k++) {
        zs_active *a = &act[set[k]];
        if (!best || a->tri < best->tri)
            best = a;
    }
    return best;
}

/* Writes [x0, x1) of a (NULL: the background). */
static void put_span(zs_renderer *r, const zs_active *a, uint8_t *row, int32_t y, int32_t x0,
                     int32_t x1)
{
    if (!a)
        zs_fill_flat(row, x0, x1, r->priv.bpp, r->priv.background);
    else if (a->flags & ZS_ACT_GOURAUD)
        zs_fill_gouraud(r, &r->priv.acolor[a - r->priv.active], y - a->y0, row, x0, x1);
    else
        zs_fill_flat(row, x0, x1, r->priv.bpp, a->pixel);
    r->stats.spans++;
}

void zs_priority_row(zs_renderer *r, int y, uint8_t *row)
{
    zs_active *const act = r->priv.active;
    const zs_edge *const edges = r->priv.edges;
    const uint16_t *p = r->priv.ael;
    const uint16_t *const end = p + r->priv.n_ael;
    uint16_t *const set = r->priv.in_set;
    const int32_t width = (int32_t)r->cfg.width;
    zs_active *top = 0;            /* NULL with members: pick once the column's events are in */
    const zs_active *pend_top = 0; /* span started at pend_x0, not yet written */
    int32_t pend_x0 = 0, cur = 0;
    int ns = 0;
    for (;;) {
        const zs_edge *e = 0;
        int32_t x = width;
        uint16_t t;
        if (p != end) {
            e = &edges[*p++];
            x = e->x;
        }
        /* the events of a column are all applied before its span; edges off
         * the screen act at column 0 or at the width */
        if (x > cur) {
            if (x > width)
                x = width;
            if (!top && ns > 0)
                top = first_stored(act, set, ns);
            if (top != pend_top) { /* spans of one triangle merge */
                if (cur > pend_x0)
                    put_span(r, pend_top, row, y, pend_x0, cur);
                pend_top = top;
                pend_x0 = cur;
            }
            cur = x;
        }
        if (!e)
            break;
        /* in/out counters, as in the span walk: a span inverted by rounding
         * is never entered */
        t = e->trail;
        if (t != ZS_NONE) {
            zs_active *a = &act[t];
            if (a->inside-- == 1) { /* leaves the set */
                uint16_t last = set[--ns], pos = a->set_pos;
                set[pos] = last;
                act[last].set_pos = pos;
                if (a == top)
                    top = 0;
            }
        }
        t = e->lead;
        if (t != ZS_NONE) {
            zs_active *a = &act[t];
            if (++a->inside == 1) { /* enters the set */
                a->set_pos = (uint16_t)ns;
                set[ns++] = t;
                if (top && a->tri < top->tri)
                    top = a;
                else if (!top && ns == 1)
                    top = a;
            }
        }
    }
    if (width > pend_x0)
        put_span(r, pend_top, row, y, pend_x0, width);
    r->stats.pixels_shaded += (uint32_t)width;
}
