/* SPDX-License-Identifier: MIT */
/* Random levels: a maze of equal square cells with full-width openings, or a
 * building floor of rooms of random sizes and heights joined by doors. Both
 * sit on a grid of cols x rows rectangles; a random spanning tree of the
 * grid (depth first) plus some extra openings makes the connections. */
#include "level.h"

#include <stdlib.h>
#include <string.h>

typedef struct gen_rng {
    uint32_t s;
} gen_rng;

static uint32_t rng_next(gen_rng *r)
{
    /* xorshift32 */
    uint32_t x = r->s;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    return r->s = x;
}

static int rng_range(gen_rng *r, int lo, int hi) /* inclusive */
{
    return lo + (int)(rng_next(r) % (uint32_t)(hi - lo + 1));
}

/* An opening across one grid edge: [d0, d1] along the edge. */
typedef struct gen_open {
    int open, d0, d1, cell; /* cell: the doorway cell through the wall */
} gen_open;

/* Walls are 2 * LV_HALF_WALL thick: cells on either side of one never
 * touch, so what is hidden behind a wall is a whole wall thickness away in
 * depth, far above the renderer's depth resolution. */
#define LV_HALF_WALL 1

typedef struct gen_state {
    lv_level *lv;
    int vcap;
    int *hash; /* vertex hash: index + 1, 0 empty */
    int hcap;
} gen_state;

static int vertex_id(gen_state *g, int x, int y)
{
    lv_level *lv = g->lv;
    uint32_t h = ((uint32_t)x * 73856093u) ^ ((uint32_t)y * 19349663u);
    int i = (int)(h % (uint32_t)g->hcap);
    while (g->hash[i]) {
        int k = g->hash[i] - 1;
        if (lv->xy[k][0] == x && lv->xy[k][1] == y)
            return k;
        i = (i + 1) % g->hcap;
    }
    if (lv->nverts == g->vcap) {
        g->vcap *= 2;
        lv->xy = realloc(lv->xy, sizeof *lv->xy * (size_t)g->vcap);
    }
    lv->xy[lv->nverts][0] = x;
    lv->xy[lv->nverts][1] = y;
    g->hash[i] = ++lv->nverts;
    return lv->nverts - 1;
}

/* Adds the points of one side of a cell (corner a, door points, up to corner
 * b exclusive) to the polygon; returns the new count. */
static int add_side(gen_state *g, int *poly, int n, int ax, int ay, int bx, int by,
                    const gen_open *o, int *door_at)
{
    poly[n++] = vertex_id(g, ax, ay);
    if (o->open) {
        int horiz = ay == by, fwd = horiz ? bx > ax : by > ay;
        int p0 = fwd ? o->d0 : o->d1, p1 = fwd ? o->d1 : o->d0;
        int x0 = horiz ? p0 : ax, y0 = horiz ? ay : p0, x1 = horiz ? p1 : ax, y1 = horiz ? ay : p1;
        if (x0 != ax || y0 != ay)
            poly[n++] = vertex_id(g, x0, y0);
        *door_at = n - 1; /* the edge from poly[n-1] is the opening */
        if (x1 != bx || y1 != by)
            poly[n++] = vertex_id(g, x1, y1);
    } else {
        *door_at = -1;
    }
    return n;
}

static void set_cell(lv_cell *cell, const int *poly, int n)
{
    cell->nv = n;
    cell->v = malloc(sizeof(int) * (size_t)n);
    memcpy(cell->v, poly, sizeof(int) * (size_t)n);
}

static void add_wall(lv_level *lv, int *wall_hash, int wcap, int u, int w)
{
    int a = u < w ? u : w, b = u < w ? w : u;
    uint32_t h = ((uint32_t)a * 2654435761u) ^ ((uint32_t)b * 40503u);
    int slot = (int)(h % (uint32_t)wcap);
    while (wall_hash[2 * slot] &&
           !(wall_hash[2 * slot] == a + 1 && wall_hash[2 * slot + 1] == b + 1))
        slot = (slot + 1) % wcap;
    if (wall_hash[2 * slot])
        return;
    wall_hash[2 * slot] = a + 1;
    wall_hash[2 * slot + 1] = b + 1;
    lv->walls[lv->nwalls].va = u;
    lv->walls[lv->nwalls].vb = w;
    lv->walls[lv->nwalls].line = 0;
    lv->nwalls++;
}

void lv_generate(lv_level *lv, lv_kind kind, int cols, int rows, uint32_t seed)
{
    gen_rng rng = {seed * 2654435761u + 12345u};
    gen_state g;
    int *xs = malloc(sizeof(int) * (size_t)(cols + 1)), *ys = malloc(sizeof(int) * (size_t)(rows + 1));
    int ncell = cols * rows, i, j, k;
    /* openings: h[j][i] between (i, j) and (i+1, j); v[j][i] between (i, j) and (i, j+1) */
    gen_open *oh = calloc((size_t)ncell, sizeof *oh), *ov = calloc((size_t)ncell, sizeof *ov);
    int *seen = calloc((size_t)ncell, sizeof(int)), *stack = malloc(sizeof(int) * (size_t)ncell);
    int sp = 0, ndoor = 0, extra = kind == LV_MAZE ? 10 : 30; /* percent of extra openings */
    int *wall_hash;
    int wcap;
    if (rng.s == 0)
        rng.s = 1;
    memset(lv, 0, sizeof *lv);
    lv->unit = 4;
    xs[0] = ys[0] = 0;
    for (i = 1; i <= cols; i++)
        xs[i] = xs[i - 1] + (kind == LV_MAZE ? 16 : rng_range(&rng, 14, 30));
    for (j = 1; j <= rows; j++)
        ys[j] = ys[j - 1] + (kind == LV_MAZE ? 16 : rng_range(&rng, 14, 30));
    /* spanning tree, depth first from cell 0 */
    seen[0] = 1;
    stack[sp++] = 0;
    while (sp) {
        int c = stack[sp - 1], ci = c % cols, cj = c / cols, nb[4], nn = 0;
        if (ci > 0 && !seen[c - 1])
            nb[nn++] = 0;
        if (ci < cols - 1 && !seen[c + 1])
            nb[nn++] = 1;
        if (cj > 0 && !seen[c - cols])
            nb[nn++] = 2;
        if (cj < rows - 1 && !seen[c + cols])
            nb[nn++] = 3;
        if (!nn) {
            sp--;
            continue;
        }
        k = nb[rng_next(&rng) % (uint32_t)nn];
        if (k == 0) {
            oh[c - 1].open = 1;
            c -= 1;
        } else if (k == 1) {
            oh[c].open = 1;
            c += 1;
        } else if (k == 2) {
            ov[c - cols].open = 1;
            c -= cols;
        } else {
            ov[c].open = 1;
            c += cols;
        }
        seen[c] = 1;
        stack[sp++] = c;
    }
    for (j = 0; j < rows; j++)
        for (i = 0; i < cols; i++) {
            gen_open *o[2] = {&oh[j * cols + i], &ov[j * cols + i]};
            int lim[2] = {i < cols - 1, j < rows - 1};
            for (k = 0; k < 2; k++) {
                int len, a0;
                if (!lim[k])
                    continue;
                if (!o[k]->open && (int)(rng_next(&rng) % 100u) < extra)
                    o[k]->open = 1;
                if (!o[k]->open)
                    continue;
                /* along the shared side: y for h (vertical side), x for v */
                a0 = k == 0 ? ys[j] : xs[i];
                len = k == 0 ? ys[j + 1] - ys[j] : xs[i + 1] - xs[i];
                if (kind == LV_MAZE) {
                    o[k]->d0 = a0 + LV_HALF_WALL;
                    o[k]->d1 = a0 + len - LV_HALF_WALL;
                } else {
                    int w = rng_range(&rng, 4, 6);
                    o[k]->d0 = a0 + LV_HALF_WALL + rng_range(&rng, 2, len - 2 * LV_HALF_WALL - 2 - w);
                    o[k]->d1 = o[k]->d0 + w;
                }
                o[k]->cell = ndoor++;
            }
        }
    ndoor += ncell; /* doorway cells follow the rooms */
    for (k = 0; k < ncell; k++) {
        if (oh[k].open)
            oh[k].cell += ncell;
        if (ov[k].open)
            ov[k].cell += ncell;
    }
    g.lv = lv;
    g.vcap = 64;
    lv->xy = malloc(sizeof *lv->xy * (size_t)g.vcap);
    g.hcap = 16 * (cols + 1) * (rows + 1) + 64;
    g.hash = calloc((size_t)g.hcap, sizeof(int));
    wcap = 16 * (cols + 1) * (rows + 1) + 64;
    wall_hash = calloc((size_t)wcap * 2, sizeof(int));
    lv->ncells = ndoor;
    lv->cells = calloc((size_t)ndoor, sizeof *lv->cells);
    lv->walls = malloc(sizeof *lv->walls * (size_t)wcap);
    lv->portals = malloc(sizeof *lv->portals * (size_t)(4 * ncell + 4));
    for (j = 0; j < rows; j++)
        for (i = 0; i < cols; i++) {
            int c = j * cols + i, poly[12], n = 0, door[4], m, s;
            static const gen_open closed = {0, 0, 0, 0};
            const gen_open *os[4];
            int x0 = xs[i] + LV_HALF_WALL, x1 = xs[i + 1] - LV_HALF_WALL;
            int y0 = ys[j] + LV_HALF_WALL, y1 = ys[j + 1] - LV_HALF_WALL;
            lv_cell *cell = &lv->cells[c];
            os[0] = j > 0 ? &ov[c - cols] : &closed;
            os[1] = i < cols - 1 ? &oh[c] : &closed;
            os[2] = j < rows - 1 ? &ov[c] : &closed;
            os[3] = i > 0 ? &oh[c - 1] : &closed;
            n = add_side(&g, poly, n, x0, y0, x1, y0, os[0], &door[0]);
            n = add_side(&g, poly, n, x1, y0, x1, y1, os[1], &door[1]);
            n = add_side(&g, poly, n, x1, y1, x0, y1, os[2], &door[2]);
            n = add_side(&g, poly, n, x0, y1, x0, y0, os[3], &door[3]);
            set_cell(cell, poly, n);
            if (kind == LV_MAZE) {
                cell->floor = 0;
                cell->ceiling = 12;
            } else {
                cell->floor = rng_range(&rng, 0, 2);
                cell->ceiling = rng_range(&rng, 11, 14);
            }
            for (m = 0; m < n; m++) {
                int is_door = 0;
                for (s = 0; s < 4; s++)
                    if (door[s] == m) {
                        lv_portal *p = &lv->portals[lv->nportals++];
                        p->a = c;
                        p->b = os[s]->cell;
                        p->va = poly[m];
                        p->vb = poly[(m + 1) % n];
                        p->line = 0;
                        is_door = 1;
                    }
                if (!is_door)
                    add_wall(lv, wall_hash, wcap, poly[m], poly[(m + 1) % n]);
            }
        }
    /* doorway cells: the opening through the wall's thickness, a portal to
     * the room on either side, walls (the jambs) on the other two sides */
    for (k = 0; k < 2 * ncell; k++) {
        const gen_open *o = k < ncell ? &oh[k] : &ov[k - ncell];
        int c = k % ncell, ci = c % cols, cj = c / cols, poly[4], n;
        lv_cell *cell, *ra, *rb;
        if (!o->open)
            continue;
        cell = &lv->cells[o->cell];
        ra = &lv->cells[c];
        rb = &lv->cells[k < ncell ? c + 1 : c + cols];
        if (k < ncell) {
            int x = xs[ci + 1];
            poly[0] = vertex_id(&g, x - LV_HALF_WALL, o->d0);
            poly[1] = vertex_id(&g, x + LV_HALF_WALL, o->d0);
            poly[2] = vertex_id(&g, x + LV_HALF_WALL, o->d1);
            poly[3] = vertex_id(&g, x - LV_HALF_WALL, o->d1);
            add_wall(lv, wall_hash, wcap, poly[0], poly[1]);
            add_wall(lv, wall_hash, wcap, poly[2], poly[3]);
        } else {
            int y = ys[cj + 1];
            poly[0] = vertex_id(&g, o->d0, y - LV_HALF_WALL);
            poly[1] = vertex_id(&g, o->d1, y - LV_HALF_WALL);
            poly[2] = vertex_id(&g, o->d1, y + LV_HALF_WALL);
            poly[3] = vertex_id(&g, o->d0, y + LV_HALF_WALL);
            add_wall(lv, wall_hash, wcap, poly[1], poly[2]);
            add_wall(lv, wall_hash, wcap, poly[3], poly[0]);
        }
        n = 4;
        set_cell(cell, poly, n);
        cell->floor = ra->floor > rb->floor ? ra->floor : rb->floor;
        cell->ceiling = ra->ceiling < rb->ceiling ? ra->ceiling : rb->ceiling;
        if (kind == LV_BUILDING)
            cell->ceiling -= 1; /* a lintel on both sides */
    }
    {
        char e[300];
        if (lv_check(lv, e, sizeof e) != 0) {
            fprintf(stderr, "zspan-level: generator bug: %s\n", e);
            abort();
        }
    }
    free(wall_hash);
    free(g.hash);
    free(xs);
    free(ys);
    free(oh);
    free(ov);
    free(seen);
    free(stack);
}
