/* SPDX-License-Identifier: MIT */
/* The host's builder of scene cells (see zs_cells_build.h). */
#include "zs_cells_build.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A cell while building: its objects [first, first + n) of the order. */
typedef struct bcell {
    size_t first, n;
    int child[64]; /* built children (grid: up to grid^2, at most 64) */
    int nchild;
} bcell;

typedef struct cb {
    const double *lo, *hi;
    uint32_t *order;
    bcell *c;
    size_t nc, cap;
    int depth;
} cb;

static int new_cell(cb *b, size_t first, size_t n)
{
    if (b->nc == b->cap) {
        b->cap = b->cap ? 2 * b->cap : 64;
        b->c = realloc(b->c, b->cap * sizeof *b->c);
        if (!b->c)
            abort();
    }
    memset(&b->c[b->nc], 0, sizeof b->c[b->nc]);
    b->c[b->nc].first = first;
    b->c[b->nc].n = n;
    return (int)b->nc++;
}

static int g_axis;
static const double *g_lo, *g_hi;
static int by_centre(const void *a, const void *b)
{
    uint32_t i = *(const uint32_t *)a, j = *(const uint32_t *)b;
    double ci = g_lo[3 * i + (size_t)g_axis] + g_hi[3 * i + (size_t)g_axis];
    double cj = g_lo[3 * j + (size_t)g_axis] + g_hi[3 * j + (size_t)g_axis];
    return ci < cj ? -1 : ci > cj ? 1 : (i > j) - (i < j);
}

static void box_of(const cb *b, size_t first, size_t n, double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++) {
        lo[k] = 1e300;
        hi[k] = -1e300;
    }
    for (size_t i = first; i < first + n; i++)
        for (int k = 0; k < 3; k++) {
            uint32_t o = b->order[i];
            lo[k] = b->lo[3 * o + (size_t)k] < lo[k] ? b->lo[3 * o + (size_t)k] : lo[k];
            hi[k] = b->hi[3 * o + (size_t)k] > hi[k] ? b->hi[3 * o + (size_t)k] : hi[k];
        }
}

static void kd(cb *b, int ci, int leaf, int depth)
{
    size_t first = b->c[ci].first, n = b->c[ci].n;
    if (depth > b->depth)
        b->depth = depth;
    if (n <= (size_t)leaf || depth >= ZS_CELLS_MAX_DEPTH - 1)
        return;
    double lo[3], hi[3];
    box_of(b, first, n, lo, hi);
    g_axis = 0;
    for (int k = 1; k < 3; k++)
        if (hi[k] - lo[k] > hi[g_axis] - lo[g_axis])
            g_axis = k;
    g_lo = b->lo;
    g_hi = b->hi;
    qsort(b->order + first, n, sizeof *b->order, by_centre);
    int a = new_cell(b, first, n / 2), c = new_cell(b, first + n / 2, n - n / 2);
    b->c[ci].child[0] = a;
    b->c[ci].child[1] = c;
    b->c[ci].nchild = 2;
    kd(b, a, leaf, depth + 1);
    kd(b, c, leaf, depth + 1);
}

static void grid(cb *b, int g)
{
    size_t n = b->c[0].n;
    double lo[3], hi[3];
    box_of(b, 0, n, lo, hi);
    int *col = malloc((n ? n : 1) * sizeof *col);
    uint32_t *tmp = malloc((n ? n : 1) * sizeof *tmp);
    if (!col || !tmp)
        abort();
    for (size_t i = 0; i < n; i++) {
        uint32_t o = b->order[i];
        double cx = (b->lo[3 * o] + b->hi[3 * o]) / 2, cz = (b->lo[3 * o + 2] + b->hi[3 * o + 2]) / 2;
        int gx = (int)((cx - lo[0]) / (hi[0] - lo[0] + 1e-9) * g);
        int gz = (int)((cz - lo[2]) / (hi[2] - lo[2] + 1e-9) * g);
        col[i] = (gz < g ? gz : g - 1) * g + (gx < g ? gx : g - 1);
    }
    size_t k = 0;
    for (int c = 0; c < g * g; c++) {
        size_t first = k;
        for (size_t i = 0; i < n; i++)
            if (col[i] == c)
                tmp[k++] = b->order[i];
        if (k > first && b->c[0].nchild < 64) {
            int child = new_cell(b, first, k - first); /* may move b->c */
            b->c[0].child[b->c[0].nchild++] = child;
        }
    }
    memcpy(b->order, tmp, n * sizeof *tmp);
    free(col);
    free(tmp);
    b->depth = 2;
}

static zs_fixed to_fx(double v, int up)
{
    double q = (up ? ceil(v * 65536.0) : floor(v * 65536.0)) + (up ? 1 : -1);
    return (zs_fixed)(q > 2147483647.0 ? 2147483647.0 : q < -2147483647.0 ? -2147483647.0 : q);
}

const char *zs_cellsb_build(const double *lo, const double *hi, size_t n, int kind, int param,
                            zs_cellsb_result *out)
{
    cb b;
    memset(out, 0, sizeof *out);
    memset(&b, 0, sizeof b);
    if (n == 0 || n > 65535)
        return "1 to 65535 objects";
    if (param < 1 || (kind == ZS_CELLS_GRID && param > 8))
        return "leaf size >= 1, grid columns 1..8";
    b.lo = lo;
    b.hi = hi;
    b.order = malloc(n * sizeof *b.order);
    if (!b.order)
        abort();
    for (size_t i = 0; i < n; i++)
        b.order[i] = (uint32_t)i;
    new_cell(&b, 0, n);
    if (kind == ZS_CELLS_KD)
        kd(&b, 0, param, 1);
    else
        grid(&b, param);
    /* breadth-first numbering */
    int *num = malloc(b.nc * sizeof *num), *queue = malloc(b.nc * sizeof *queue);
    out->cells = calloc(b.nc, sizeof *out->cells);
    if (!num || !queue || !out->cells)
        abort();
    size_t head = 0, tail = 0;
    queue[tail++] = 0;
    while (head < tail) {
        int c = queue[head++];
        num[c] = (int)(head - 1);
        for (int k = 0; k < b.c[c].nchild; k++)
            queue[tail++] = b.c[c].child[k];
    }
    size_t next = 1;
    for (size_t q = 0; q < b.nc; q++) {
        const bcell *c = &b.c[queue[q]];
        zs_cell *z = &out->cells[q];
        double l[3], h[3];
        box_of(&b, c->first, c->n, l, h);
        for (int k = 0; k < 3; k++) {
            z->lo[k] = to_fx(l[k], 0);
            z->hi[k] = to_fx(h[k], 1);
        }
        z->first_object = (uint16_t)c->first;
        z->object_count = (uint16_t)c->n;
        z->child_count = (uint16_t)c->nchild;
        z->first_child = (uint16_t)(c->nchild ? next : 0);
        next += (size_t)c->nchild;
    }
    out->cell_count = b.nc;
    out->order = b.order;
    out->depth = b.depth;
    free(num);
    free(queue);
    free(b.c);
    return NULL;
}

void zs_cellsb_free(zs_cellsb_result *r)
{
    free(r->cells);
    free(r->order);
    memset(r, 0, sizeof *r);
}
