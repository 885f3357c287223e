/* The row loop: activate the row's triangles, merge their edges (sorted as a
 * batch) into the x-sorted active edge list, resolve the row, then step the
 * edges, retire finished ones and restore the order. */
#include "zs_internal.h"

void zs_raster_begin(zs_renderer *r)
{
    uint16_t *efree = (uint16_t *)r->edge_free;
    uint16_t *afree = (uint16_t *)r->active_free;
    uint16_t e = r->cfg.max_active_edges, a = (uint16_t)((e + 1u) / 2u), i;
    /* free stacks, popped from the end: lowest indices first */
    for (i = 0; i < e; i++)
        efree[i] = (uint16_t)(e - 1u - i);
    for (i = 0; i < a; i++)
        afree[i] = (uint16_t)(a - 1u - i);
    r->n_edge_free = e;
    r->n_active_free = a;
    r->n_ael = 0;
}

/* Activates the triangles first met on row y and merges their edges. */
static void add_new_edges(zs_renderer *r, int32_t y)
{
    uint16_t *ael = (uint16_t *)r->ael;
    const zs_edge *edges = (const zs_edge *)r->edges;
    uint16_t *bucket = (uint16_t *)r->buckets;
    const zs_tri *tris = (const zs_tri *)r->tris;
    uint16_t old_n = r->n_ael, n = old_n, ti;
    int i, j, k;
    for (ti = bucket[y]; ti != ZS_NONE; ti = tris[ti].next) {
        uint16_t left, ai = zs_activate(r, ti, y, &left);
        if (ai == ZS_NONE)
            continue;
        ael[n++] = left;
        ael[n++] = ((const zs_active *)r->active)[ai].right;
    }
    if (n == old_n)
        return;
    /* sort the new batch (insertion sort: batches are small) */
    for (i = old_n + 1; i < n; i++) {
        uint16_t e = ael[i];
        int32_t x = edges[e].x;
        for (j = i; j > old_n && edges[ael[j - 1]].x > x; j--)
            ael[j] = ael[j - 1];
        ael[j] = e;
    }
    /* merge from the back: both runs are sorted, the list has room */
    if (old_n > 0) {
        /* the free stack's unused top holds at least as many slots as there
         * are edges in use, so it serves as scratch for the batch */
        uint16_t *batch = (uint16_t *)r->edge_free + r->n_edge_free;
        int nb = n - old_n;
        memcpy(batch, ael + old_n, (size_t)nb * sizeof batch[0]);
        i = old_n - 1;
        j = nb - 1;
        k = n - 1;
        while (j >= 0) {
            if (i >= 0 && edges[ael[i]].x > edges[batch[j]].x)
                ael[k--] = ael[i--];
            else
                ael[k--] = batch[j--];
        }
    }
    r->n_ael = n;
}

/* Steps every edge to row y + 1, retires finished ones and keeps the list
 * sorted (an edge that passed its left neighbour is moved back: rare). The
 * planes of each triangle step with its left edge. */
static void step_edges(zs_renderer *r, int32_t y)
{
    uint16_t *ael = (uint16_t *)r->ael;
    zs_edge *edges = (zs_edge *)r->edges;
    zs_active *act = (zs_active *)r->active;
    uint16_t *efree = (uint16_t *)r->edge_free;
    uint16_t *afree = (uint16_t *)r->active_free;
    int i, n = r->n_ael, kept = 0;
    int32_t next = y + 1, prev_x = INT32_MIN;
    for (i = 0; i < n; i++) {
        uint16_t ei = ael[i];
        zs_edge *e = &edges[ei];
        zs_active *a = &act[e->owner];
        if (next >= e->y_end) {
            if (!e->upper || next >= a->y_end) {
                efree[r->n_edge_free++] = ei;
                if (!e->trailing) /* free the triangle once, with its left edge */
                    afree[r->n_active_free++] = e->owner;
                continue;
            }
            zs_edge_continue(r, e, next);
        } else {
            e->x += e->step;
            e->err -= e->rstep;
            if (e->err < 0) {
                e->err += e->den;
                e->x++;
            }
        }
        if (!e->trailing) {
            a->zrow += a->zdy;
            if (a->gouraud) {
                a->crow[0] += (uint32_t)a->cdy[0];
                a->crow[1] += (uint32_t)a->cdy[1];
                a->crow[2] += (uint32_t)a->cdy[2];
            }
        }
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
    r->n_ael = (uint16_t)kept;
}

void zs_raster_row(zs_renderer *r, int y, uint8_t *row)
{
    add_new_edges(r, y);
    if (r->n_ael > r->stats.max_active_edges)
        r->stats.max_active_edges = r->n_ael;
    if (row) {
        if (r->mode == ZS_MODE_ZLINE)
            zs_zline_row(r, y, row);
        else
            zs_span_row(r, y, row);
    }
    step_edges(r, y);
}
