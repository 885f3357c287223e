/* SPDX-License-Identifier: MIT */
/* Span visibility for one row: walk the x-sorted active edge list, keep the
 * set of triangles the walk is inside and the nearest of them (the top).
 *
 * Decisions are exact at pixel centres: at every column the top is the
 * minimum of (depth, record index) over the set, the same rule the z-buffer
 * mode applies per pixel, so the two modes give identical images.
 *
 * Work stays small because a decision is only made when something changes:
 *  - a triangle entering is compared with the top once, at its first column;
 *  - when the top leaves, the nearest of the rest is picked, once all the
 *    events at that column are in (where a mesh's triangles share an edge,
 *    one leaves and the next enters at the same column);
 *  - two depth planes differ linearly along a row, so for each other member
 *    the first column where it would overtake the top (a penetration) is
 *    computed once, and only when it lies before either of the two ends
 *    (one multiplication; a division only for a real crossing). The nearest
 *    such column splits the span. */
#include "zs_internal.h"

#define NO_CROSS INT32_MAX

typedef struct row_ctx {
    zs_renderer *r;
    zs_active *act;
    const zs_edge *edges;
    uint16_t *set;
    uint8_t *row;
    zs_active *top;       /* nearest member, or NULL when the set is empty */
    const zs_active *pend_top; /* span started at pend_x0, not yet written */
    int32_t pend_x0;
    int dirty;            /* the top left: pick again before the next span */
    int32_t width;
    int32_t min_cross;    /* first column where a member overtakes the top */
    uint32_t background;  /* packed background pixel */
    uint32_t evals;
} row_ctx;

static int64_t depth_at(const zs_active *a, int32_t x)
{
    return a->zrow + a->zdx * x;
}

/* Does (za, a) win over (zb, b)? Nearer first, then the earlier record. */
static int nearer(int64_t za, const zs_active *a, int64_t zb, const zs_active *b)
{
    return za < zb || (za == zb && a->tri < b->tri);
}

/* First column after x where j overtakes top, or NO_CROSS when that does not
 * happen before one of the two triangles ends on this row. zj, zt: depths
 * at x, where top wins. */
static int32_t overtake(const zs_active *j, const zs_active *top, int32_t x,
                        int64_t zj, int64_t zt)
{
    int64_t slope = top->zdx - j->zdx, gap = zj - zt, reach, k;
    int32_t lim;
    int j_wins_tie = j->tri < top->tri;
    if (slope <= 0)
        return NO_CROSS; /* j never gets nearer along this row */
    lim = top->xr < j->xr ? top->xr : j->xr;
    if (lim - x <= 1)
        return NO_CROSS;
    reach = slope * (lim - x - 1); /* how much the gap closes by the last shared column */
    if (reach < gap || (reach == gap && !j_wins_tie))
        return NO_CROSS;
    k = j_wins_tie ? (gap + slope - 1) / slope : gap / slope + 1;
    return x + (int32_t)k;
}

/* Is a nearer than b at every centre both cover? (Their depth ranges say
 * so without evaluating either plane.) */
static int always_nearer(const zs_active *a, const zs_active *b)
{
    return a->zhi <= b->zlo;
}

/* The top by depth ranges alone, or NULL: the member whose range ends first
 * wins outright if it ends before every other range starts (typical where
 * surfaces are apart in depth); then no plane is evaluated and nothing can
 * overtake it. */
static zs_active *range_top(const row_ctx *c)
{
    int ns = c->r->priv.n_set, k;
    zs_active *near = 0;
    const zs_active *lo1_of = 0;
    uint16_t lo1 = 0xFFFFu, lo2 = 0xFFFFu; /* the two smallest zlo */
    for (k = 0; k < ns; k++) {
        zs_active *a = &c->act[c->set[k]];
        if (!near || a->zhi < near->zhi)
            near = a;
        if (a->zlo < lo1) {
            lo2 = lo1;
            lo1 = a->zlo;
            lo1_of = a;
        } else if (a->zlo < lo2) {
            lo2 = a->zlo;
        }
    }
    return near && near->zhi <= (near == lo1_of ? lo2 : lo1) ? near : 0;
}

/* Picks the top among the whole set at column x and the next crossing. */
static void retop(row_ctx *c, int32_t x)
{
    int ns = c->r->priv.n_set, k;
    zs_active *best = range_top(c);
    int64_t bz = 0;
    if (best) { /* nearer than every other member wherever they meet */
        c->top = best;
        c->dirty = 0;
        c->min_cross = NO_CROSS;
        for (k = 0; k < ns; k++)
            c->act[c->set[k]].cross = NO_CROSS;
        return;
    }
    for (k = 0; k < ns; k++) {
        zs_active *a = &c->act[c->set[k]];
        a->zcur = depth_at(a, x);
        if (!best || nearer(a->zcur, a, bz, best)) {
            best = a;
            bz = a->zcur;
        }
    }
    c->evals += (uint32_t)ns;
    c->top = best;
    c->dirty = 0;
    c->min_cross = NO_CROSS;
    for (k = 0; k < ns; k++) {
        zs_active *a = &c->act[c->set[k]];
        if (a == best)
            continue;
        a->cross = always_nearer(best, a) ? NO_CROSS : overtake(a, best, x, a->zcur, bz);
        if (a->cross < c->min_cross)
            c->min_cross = a->cross;
    }
}

/* Writes the pending span: [pend_x0, x) of pend_top. */
static void flush(row_ctx *c, int32_t x)
{
    const zs_active *a = c->pend_top;
    int32_t x0 = c->pend_x0;
    if (x <= x0)
        return;
    if (!a)
        zs_fill_flat(c->row, x0, x, c->r->priv.bpp, c->background);
    else if (a->flags & ZS_ACT_GOURAUD)
        zs_fill_gouraud(c->r, &c->r->priv.acolor[a - c->act], c->row, x0,
                        x);
    else
        zs_fill_flat(c->row, x0, x, c->r->priv.bpp, a->pixel);
    c->r->stats.spans++;
}

/* The top from x0 on. Spans of one surface split only by events behind it
 * (hidden triangles entering or leaving) are written as one. */
static void fill(row_ctx *c, int32_t x0)
{
    if (c->top == c->pend_top)
        return;
    flush(c, x0);
    c->pend_top = c->top;
    c->pend_x0 = x0;
}

/* Columns [x0, x1) with the set unchanged: split where the top is overtaken. */
static void emit(row_ctx *c, int32_t x0, int32_t x1)
{
    if (c->dirty)
        retop(c, x0);
    fill(c, x0);
    while (c->top && c->min_cross < x1) {
        int32_t xc = c->min_cross;
        c->r->stats.crossings++;
        retop(c, xc);
        fill(c, xc);
    }
}

static void enter(row_ctx *c, zs_active *a, uint16_t ai, int32_t x)
{
    int64_t za, zt;
    a->set_pos = c->r->priv.n_set;
    c->set[c->r->priv.n_set++] = ai;
    a->cross = NO_CROSS;
    a->xr = (int16_t)zs_clampi(c->edges[a->right].x, 0, c->width);
    if (c->dirty)
        return; /* the pick after this column's events includes it */
    if (!c->top) {
        c->top = a;
        c->min_cross = NO_CROSS;
        return;
    }
    if (always_nearer(c->top, a))
        return; /* behind the top wherever both are: no crossing either */
    if (always_nearer(a, c->top)) {
        retop(c, x); /* the new top; every member's crossing changes */
        return;
    }
    za = depth_at(a, x);
    zt = depth_at(c->top, x);
    c->evals += 2;
    if (nearer(za, a, zt, c->top)) {
        retop(c, x); /* a is the new top; every member's crossing changes */
        return;
    }
    a->cross = overtake(a, c->top, x, za, zt);
    if (a->cross < c->min_cross)
        c->min_cross = a->cross;
}

static void leave(row_ctx *c, zs_active *a, int32_t x)
{
    uint16_t last = c->set[--c->r->priv.n_set];
    c->set[a->set_pos] = last;
    c->act[last].set_pos = a->set_pos;
    (void)x;
    if (a == c->top) {
        c->top = 0;
        c->min_cross = NO_CROSS;
        c->dirty = c->r->priv.n_set > 0;
    } else if (c->dirty) {
        return;
    } else if (a->cross == c->min_cross && a->cross != NO_CROSS) {
        int k;
        c->min_cross = NO_CROSS;
        for (k = 0; k < c->r->priv.n_set; k++) {
            const zs_active *m = &c->act[c->set[k]];
            if (m != c->top && m->cross < c->min_cross)
                c->min_cross = m->cross;
        }
    }
}

void zs_span_row(zs_renderer *r, int y, uint8_t *row)
{
    const uint16_t *ael = r->priv.ael;
    row_ctx c;
    int32_t cur = 0;
    int i, n = r->priv.n_ael;
    (void)y;
    c.r = r;
    c.act = r->priv.active;
    c.edges = r->priv.edges;
    c.set = r->priv.in_set;
    c.row = row;
    c.top = 0;
    c.pend_top = 0;
    c.pend_x0 = 0;
    c.dirty = 0;
    c.width = r->cfg.width;
    c.min_cross = NO_CROSS;
    c.evals = 0;
    c.background = r->priv.background;
    r->priv.n_set = 0;
    for (i = 0; i < n; i++) {
        const zs_edge *e = &c.edges[ael[i]];
        int32_t x = zs_clampi(e->x, 0, c.width);
        if (x > cur) { /* all events at a column are applied before its span */
            emit(&c, cur, x);
            cur = x;
        }
        /* in/out counters: a span inverted by rounding is never entered */
        if (e->trail != ZS_NONE) {
            zs_active *a = &c.act[e->trail];
            if (a->inside-- == 1)
                leave(&c, a, x);
        }
        if (e->lead != ZS_NONE) {
            zs_active *a = &c.act[e->lead];
            if (++a->inside == 1)
                enter(&c, a, e->lead, x);
        }
    }
    if (cur < c.width)
        emit(&c, cur, c.width);
    flush(&c, c.width);
    r->stats.depth_evals += c.evals;
    r->stats.pixels_shaded += (uint32_t)c.width;
}
