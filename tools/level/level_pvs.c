/* SPDX-License-Identifier: MIT */
/* Potentially visible sets (Teller and Sequin): from every cell, depth first
 * through portal sequences, keeping a sequence only while one line stabs all
 * of its portals. Exact integer arithmetic on the plan. */
#include "level.h"

#include <stdlib.h>
#include <string.h>

typedef long long i64;

/* Side of q against the directed line through p with direction d. */
static i64 side(const int *p, i64 dx, i64 dy, const int *q)
{
    return dx * ((i64)q[1] - p[1]) - dy * ((i64)q[0] - p[0]);
}

static int separates(const int *p, i64 dx, i64 dy, const int (*left)[2], int nl,
                     const int (*right)[2], int nr)
{
    int i;
    for (i = 0; i < nl; i++)
        if (side(p, dx, dy, left[i]) < 0)
            return 0;
    for (i = 0; i < nr; i++)
        if (side(p, dx, dy, right[i]) > 0)
            return 0;
    return 1;
}

/* The linear program "find (a, b, c) != 0 with a x + b y + c >= 0 on the left
 * points and <= 0 on the right points" is solved by its vertices: if a
 * separating line exists, one also exists through two distinct points of the
 * sets (push it toward the points until it touches one, then turn it about
 * that point until it touches another). So it is enough to try the line
 * through every pair of distinct points, in both directions. All values are
 * exact: coordinates below 2^15, products below 2^32. */
int lv_stabbable(const int (*left)[2], int nl, const int (*right)[2], int nr)
{
    int n = nl + nr, i, j, distinct = 0;
    for (i = 0; i < n; i++) {
        const int *p = i < nl ? left[i] : right[i - nl];
        for (j = i + 1; j < n; j++) {
            const int *q = j < nl ? left[j] : right[j - nl];
            i64 dx = (i64)q[0] - p[0], dy = (i64)q[1] - p[1];
            if (dx == 0 && dy == 0)
                continue;
            distinct = 1;
            if (separates(p, dx, dy, left, nl, right, nr) ||
                separates(p, -dx, -dy, left, nl, right, nr))
                return 1;
        }
    }
    return !distinct; /* all points equal: any line through them */
}

typedef struct pvs_walk {
    const lv_level *lv;
    uint8_t *row;
    int *on_path;
    int (*left)[2], (*right)[2];
    lv_pvs_stats *st;
} pvs_walk;

/* Portal k of cell c, as seen leaving c: endpoints a -> b counter-clockwise
 * in c, and the cell entered. */
static int portal_out(const lv_level *lv, int c, int m, const int **a, const int **b)
{
    const lv_cell *cell = &lv->cells[c];
    const lv_portal *p = &lv->portals[cell->edge_kind[m]];
    *a = lv->xy[cell->v[m]];
    *b = lv->xy[cell->v[(m + 1) % cell->nv]];
    return p->a == c ? p->b : p->a;
}

static void extend(pvs_walk *w, int cell, int depth)
{
    const lv_cell *c = &w->lv->cells[cell];
    int m;
    for (m = 0; m < c->nv; m++) {
        const int *a, *b;
        int to;
        if (c->edge_kind[m] < 0)
            continue;
        to = portal_out(w->lv, cell, m, &a, &b);
        if (w->on_path[to])
            continue;
        /* crossing a -> b from the cell's side (its left), b stays on the
         * sightline's left and a on its right */
        w->left[depth][0] = b[0];
        w->left[depth][1] = b[1];
        w->right[depth][0] = a[0];
        w->right[depth][1] = a[1];
        w->st->sequences++;
        if (!lv_stabbable((const int(*)[2])w->left, depth + 1, (const int(*)[2])w->right,
                          depth + 1))
            continue;
        w->st->stabbable++;
        if (depth + 1 > w->st->max_depth)
            w->st->max_depth = depth + 1;
        w->row[to >> 3] |= (uint8_t)(1u << (to & 7));
        w->on_path[to] = 1;
        extend(w, to, depth + 1);
        w->on_path[to] = 0;
    }
}

uint8_t *lv_compute_pvs(const lv_level *lv, lv_pvs_stats *stats)
{
    int rb = (lv->ncells + 7) / 8, s;
    uint8_t *pvs = calloc((size_t)lv->ncells, (size_t)rb);
    pvs_walk w;
    lv_pvs_stats local;
    memset(&local, 0, sizeof local);
    w.lv = lv;
    w.on_path = calloc((size_t)lv->ncells, sizeof(int));
    w.left = malloc(sizeof *w.left * (size_t)(lv->ncells + 1));
    w.right = malloc(sizeof *w.right * (size_t)(lv->ncells + 1));
    w.st = stats ? stats : &local;
    memset(w.st, 0, sizeof *w.st);
    for (s = 0; s < lv->ncells; s++) {
        w.row = pvs + (size_t)s * (size_t)rb;
        w.row[s >> 3] |= (uint8_t)(1u << (s & 7));
        w.on_path[s] = 1;
        extend(&w, s, 0);
        w.on_path[s] = 0;
    }
    free(w.on_path);
    free(w.left);
    free(w.right);
    return pvs;
}
