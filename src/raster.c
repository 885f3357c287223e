/* SPDX-License-Identifier: MIT */
/* The row loop: activate the row's triangles, sort their new edges as a
 * batch, fold edges that two triangles share into one record, merge the batch
 * into the x-sorted active edge list, resolve the row, then step the edges,
 * retire finished ones and restore the order. */
#include "zs_internal.h"

/* Setup pushes records on the front of their row's list; turning each list
 * once puts them back in submission order, so when the active pools fill
 * up, the triangles submitted last are the ones dropped. */
static void reverse_buckets(zs_renderer *r)
{
    uint16_t *bucket = r->priv.buckets;
    zs_tri *tris = r->priv.tris;
    int y;
    for (y = 0; y < (int)r->cfg.height; y++) {
        uint16_t prev = ZS_NONE, t = bucket[y];
        while (t != ZS_NONE) {
            uint16_t next = tris[t].next;
            tris[t].next = prev;
            prev = t;
            t = next;
        }
        bucket[y] = prev;
    }
}

void zs_raster_begin(zs_renderer *r)
{
    uint16_t *efree = r->priv.edge_free;
    uint16_t *afree = r->priv.active_free;
    /* two edge sides per triangle: e / 2 triangles can never need more than
     * e edges, even while shared edges split at their continuations */
    uint16_t e = r->cfg.max_active_edges, a = (uint16_t)(e / 2u), i;
    /* free stacks, popped from the end: lowest indices first */
    for (i = 0; i < e; i++)
        efree[i] = (uint16_t)(e - 1u - i);
    for (i = 0; i < a; i++)
        afree[i] = (uint16_t)(a - 1u - i);
    r->priv.n_edge_free = e;
    r->priv.n_active_free = a;
    r->priv.n_ael = 0;
    r->priv.n_sorted = 0;
    r->priv.steep = 0;
    r->priv.background = zs_background_word(r); /* packed once a frame */
    reverse_buckets(r);
}

/* Two new edges on the same line over the same rows, one ending a triangle
 * and the other starting one: keep one record for both. Every pool edge is
 * owned by at least one triangle side, so the pool never holds more edges
 * than twice the active triangles. */
static int fold_edge(zs_renderer *r, zs_edge *keep, uint16_t keep_i, zs_edge *dup)
{
    zs_active *act = r->priv.active;
    if (keep->err != dup->err || keep->step != dup->step || keep->rstep != dup->rstep ||
        keep->den != dup->den || keep->y_end != dup->y_end)
        return 0;
    if ((keep->lead != ZS_NONE && dup->lead != ZS_NONE) ||
        (keep->trail != ZS_NONE && dup->trail != ZS_NONE))
        return 0; /* same side twice (coplanar duplicates): keep both */
    if (dup->lead != ZS_NONE)
        keep->lead = dup->lead;
    if (dup->trail != ZS_NONE) {
        keep->trail = dup->trail;
        act[dup->trail].right = keep_i;
    }
    return 1;
}

/* Sorts edge indices by column. The keys (column, index) are packed into
 * 32-bit words so the sort never chases pointers; it runs in the z-buffer
 * line, which is idle while edges are added. Insertion sort for a few, a
 * bottom-up merge sort for more (a row can start hundreds of triangles). */
static void sort_batch(zs_renderer *r, uint16_t *a, int n)
{
    const zs_edge *edges = r->priv.edges;
    uint32_t *key = r->priv.sort_keys, *tmp, *src, *dst;
    int width, i, j;
    if (n < 2)
        return;
    if (!key || n > (int)r->cfg.width) { /* no scratch, or more than it holds */
        for (i = 1; i < n; i++) {
            uint16_t e = a[i];
            int32_t x = edges[e].x;
            for (j = i; j > 0 && edges[a[j - 1]].x > x; j--)
                a[j] = a[j - 1];
            a[j] = e;
        }
        return;
    }
    tmp = key + n;
    /* columns are within +-2^14 of the screen: an offset makes them unsigned */
    for (i = 0; i < n; i++)
        key[i] = ((uint32_t)(edges[a[i]].x + 32768) << 16) | a[i];
    if (n <= 16) {
        for (i = 1; i < n; i++) {
            uint32_t k = key[i];
            for (j = i; j > 0 && key[j - 1] > k; j--)
                key[j] = key[j - 1];
            key[j] = k;
        }
        src = key;
    } else {
        src = key;
        dst = tmp;
        for (width = 1; width < n; width *= 2) {
            for (i = 0; i < n; i += 2 * width) {
                int mid = i + width < n ? i + width : n;
                int end = i + 2 * width < n ? i + 2 * width : n;
                int p = i, q = mid, k = i;
                while (p < mid && q < end)
                    dst[k++] = src[q] < src[p] ? src[q++] : src[p++];
                while (p < mid)
                    dst[k++] = src[p++];
                while (q < end)
                    dst[k++] = src[q++];
            }
            {
                uint32_t *t = src;
                src = dst;
                dst = t;
            }
        }
    }
    for (i = 0; i < n; i++)
        a[i] = (uint16_t)(src[i] & 0xFFFFu);
}

/* Activates the triangles first met on row y; sorts, folds and merges the
 * unsorted tail (those edges plus continuations made by the last step). */
static void add_new_edges(zs_renderer *r, int32_t y)
{
    uint16_t *ael = r->priv.ael;
    zs_edge *edges = r->priv.edges;
    uint16_t *bucket = r->priv.buckets;
    const zs_tri *tris = r->priv.tris;
    uint16_t *efree = r->priv.edge_free;
    int sorted = r->priv.n_sorted, n, i, j, k, w;
    uint16_t ti;
    for (ti = bucket[y]; ti != ZS_NONE; ti = tris[ti].next)
        zs_activate(r, ti, y);
    n = r->priv.n_ael;
    if (n == sorted)
        return;
    sort_batch(r, ael + sorted, n - sorted);
    /* fold shared edges: they start at the same column */
    w = sorted;
    for (i = sorted; i < n; i++) {
        zs_edge *e = &edges[ael[i]];
        int folded = 0;
        for (j = w - 1; j >= sorted && edges[ael[j]].x == e->x; j--) {
            if (fold_edge(r, &edges[ael[j]], ael[j], e)) {
                efree[r->priv.n_edge_free++] = ael[i];
                folded = 1;
                break;
            }
        }
        if (!folded)
            ael[w++] = ael[i];
    }
    n = w;
    /* merge from the back: both runs are sorted, the list has room; the free
     * stack's unused top (as many slots as edges in use) holds the batch */
    if (sorted > 0) {
        uint16_t *batch = efree + r->priv.n_edge_free;
        int nb = n - sorted;
        for (i = 0; i < nb; i++)
            batch[i] = ael[sorted + i];
        i = sorted - 1;
        j = nb - 1;
        k = n - 1;
        while (j >= 0) {
            if (i >= 0 && edges[ael[i]].x > edges[batch[j]].x)
                ael[k--] = ael[i--];
            else
                ael[k--] = batch[j--];
        }
    }
    r->priv.n_ael = (uint16_t)n;
    r->priv.n_sorted = (uint16_t)n;
}

/* Planes of active triangle ai to the next row (a steep plane is set again
 * by anchor_steep or zs_continue_edge). */
static inline void step_planes(zs_renderer *r, uint16_t ai)
{
    zs_active *a = &r->priv.active[ai];
    a->zrow += a->zdy;
    if (a->flags & ZS_ACT_GOURAUD) {
        zs_active_color *c = &r->priv.acolor[ai];
        c->crow[0] += (uint32_t)c->cdy[0];
        c->crow[1] += (uint32_t)c->cdy[1];
        c->crow[2] += (uint32_t)c->cdy[2];
    }
}

/* Row `next` of the steep planes: each anchored at its left edge's column.
 * A pass of its own, run only in frames with needles, so the edge stepping
 * loop stays as lean as without them. */
static void anchor_steep(zs_renderer *r, int32_t next)
{
    const uint16_t *ael = r->priv.ael;
    const zs_edge *edges = r->priv.edges;
    zs_active *act = r->priv.active;
    int i;
    for (i = 0; i < r->priv.n_ael; i++) {
        const zs_edge *e = &edges[ael[i]];
        if (e->lead != ZS_NONE && (act[e->lead].flags & ZS_ACT_STEEP))
            zs_anchor_depth(r, &act[e->lead], zs_clampi(e->x, 0, r->cfg.width), next);
    }
}

/* An edge ends above row `next`: each of its triangles either ends too (freed
 * with its left edge) or goes on with its lower short edge (queued in cont). */
static void retire_edge(zs_renderer *r, zs_edge *e, int32_t next, uint16_t *cont, int *n_cont)
{
    zs_active *act = r->priv.active;
    uint16_t *afree = r->priv.active_free;
    if (e->lead != ZS_NONE) {
        zs_active *a = &act[e->lead];
        if (next >= a->y_end) {
            afree[r->priv.n_active_free++] = e->lead;
        } else {
            step_planes(r, e->lead);
            cont[(*n_cont)++] = e->lead;
        }
    }
    if (e->trail != ZS_NONE && next < act[e->trail].y_end)
        cont[(*n_cont)++] = e->trail;
}

/* Steps every edge to row y + 1, retires finished ones and keeps the list
 * sorted (an edge that passed its left neighbour is moved back: rare). The
 * planes of each triangle step with its left edge. */
static void step_edges(zs_renderer *r, int32_t y)
{
    uint16_t *ael = r->priv.ael;
    zs_edge *edges = r->priv.edges;
    uint16_t *efree = r->priv.edge_free;
    /* continuations wait in the in-polygon set's array (unused between
     * rows): at most one per active triangle */
    uint16_t *cont = r->priv.in_set;
    int i, n = r->priv.n_ael, kept = 0, n_cont = 0;
    int32_t next = y + 1, prev_x = INT32_MIN;
    for (i = 0; i < n; i++) {
        uint16_t ei = ael[i];
        zs_edge *e = &edges[ei];
        if (next >= e->y_end) {
            retire_edge(r, e, next, cont, &n_cont);
            efree[r->priv.n_edge_free++] = ei;
            continue;
        }
        e->x += e->step;
        e->err -= e->rstep;
        if (e->err < 0) {
            e->err += e->den;
            e->x++;
        }
        if (e->lead != ZS_NONE)
            step_planes(r, e->lead);
        if (e->x >= prev_x) {
            prev_x = e->x;
            ael[kept++] = ei;
        } else {
            int j = kept;
            for (; j > 0 && edges[ael[j - 1]].x > e->x; j--)
                ael[j] = ael[j - 1];
            ael[j] = ei;
            kept++;
        }
    }
    r->priv.n_ael = (uint16_t)kept;
    r->priv.n_sorted = (uint16_t)kept;
    if (r->priv.steep)
        anchor_steep(r, next);
    /* lower short edges join the next row's batch (edges were freed first,
     * so the pool has room) */
    for (i = 0; i < n_cont; i++)
        zs_continue_edge(r, cont[i], next);
}

void zs_raster_row(zs_renderer *r, int y, uint8_t *row)
{
    uint32_t sides;
    add_new_edges(r, y);
    /* capacity demand in edge sides, two per active triangle (a shared edge
     * record serves two sides, but each triangle needs its pair) */
    sides = 2u * (uint32_t)(r->cfg.max_active_edges / 2u - r->priv.n_active_free);
    if (sides > r->stats.max_active_edges)
        r->stats.max_active_edges = sides;
    if (row) {
        if (r->priv.mode == ZS_MODE_ZLINE)
            zs_zline_row(r, y, row);
        else
            zs_span_row(r, y, row);
    }
    step_edges(r, y);
}
