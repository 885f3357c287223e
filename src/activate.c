/* Triangle activation: when a stored triangle reaches its first row, make its
 * two edges from the edge pool and its depth and colour planes.
 *
 * Edges are exact: for the pixel centre row yc the covered columns start at
 * ceil(x(yc) - 0.5), with x(yc) the exact rational on the edge. That value is
 * kept as an integer plus a remainder (a floor-divmod DDA), so a shared edge
 * gives both its triangles the same boundary and nothing cracks. */
#include "zs_internal.h"

/* Sets e to cover the edge a -> b (a above b) starting at row y. */
static void edge_init(zs_edge *e, const zs_vert *a, const zs_vert *b, int32_t y)
{
    int32_t dx = b->x - a->x, dy = b->y - a->y; /* |dx|, |dy| < 2^19 */
    int32_t den = 16 * dy;
    /* (x(yc) - 0.5) * den at yc = 16 y + 8, split as 16 * q0 * dy + m so the
     * part left to divide is small: q0 = floor((x_a - 8) / 16). */
    int32_t q0 = zs_asr32(a->x - 8, 4), r0 = a->x - 8 - 16 * q0;
    int32_t t = 16 * y + 8 - a->y; /* in [0, 16) on the edge's first row */
    int32_t x, err, step;
    if (t < 16) {
        int32_t m = r0 * dy + t * dx; /* |m| < 2^24 */
        int32_t q = m / den;
        if (m - q * den > 0)
            q++; /* ceil */
        x = q0 + q;
        err = q * den - m;
    } else { /* starts above the screen: the numerator needs 64 bits */
        int64_t m = (int64_t)r0 * dy + (int64_t)t * dx;
        int64_t q = m / den;
        if (m - q * den > 0)
            q++;
        x = q0 + (int32_t)q;
        err = (int32_t)(q * den - m);
    }
    step = (16 * dx) / den;
    if (step * den > 16 * dx)
        step--; /* floor */
    e->x = x;
    e->err = err;
    e->step = step;
    e->rstep = 16 * dx - step * den;
    e->den = den;
    e->y_end = (int16_t)zs_first_row(b->y);
}

/* Depth planes hold window depth in Q40 (10 bits below the vertices' Q30, so
 * stepping across a row adds no visible error). Gradients are clamped to
 * 256 depth ranges per pixel: with evaluation points at most 2^13 pixels from
 * the origin every product stays below 2^62. A triangle steeper than that is
 * narrower than 1/256 pixel across its depth range; only its depth is off.
 * The gradient is num * 2^14 / area2 (num in Q30 * 1/16 px, area in 1/256 px^2). */
#define ZS_DEPTH_GRADIENT_LIMIT ((int64_t)1 << 48)
static int64_t plane_gradient(int64_t num, int64_t area2)
{
    const int64_t limit = ZS_DEPTH_GRADIENT_LIMIT;
    int64_t q = num / area2, rem = num % area2;
    int64_t lim_q = limit >> 14;
    if (q > lim_q)
        return limit;
    if (q < -lim_q)
        return -limit;
    return q * ((int64_t)1 << 14) + (rem * ((int64_t)1 << 14)) / area2;
}

/* Depth plane of the triangle, origin at the pixel centre (ox, oy). */
static void depth_plane(zs_active *a, const zs_vert *v[3], int64_t area2, int32_t ox, int32_t oy,
                        int32_t y)
{
    int64_t dx1 = (int64_t)v[1]->x - v[0]->x, dy1 = (int64_t)v[1]->y - v[0]->y;
    int64_t dx2 = (int64_t)v[2]->x - v[0]->x, dy2 = (int64_t)v[2]->y - v[0]->y;
    int64_t dz1 = (int64_t)v[1]->z - v[0]->z, dz2 = (int64_t)v[2]->z - v[0]->z;
    int64_t z0;
    a->zdx = plane_gradient(dz1 * dy2 - dz2 * dy1, area2);
    a->zdy = plane_gradient(dz2 * dx1 - dz1 * dx2, area2);
    /* depth at the origin pixel centre, from vertex 0 (less than a pixel away) */
    z0 = (int64_t)v[0]->z * 1024 +
         zs_asr64(a->zdx * (16 * (int64_t)ox + 8 - v[0]->x) +
                      a->zdy * (16 * (int64_t)oy + 8 - v[0]->y),
                  4);
    a->zrow = z0 + a->zdy * ((int64_t)y - oy) - a->zdx * ox;
}

uint16_t zs_activate(zs_renderer *r, uint16_t ti, int32_t y, uint16_t *left)
{
    zs_tri *t = &((zs_tri *)r->tris)[ti];
    const zs_vert *pool = (const zs_vert *)r->verts;
    const zs_vert *v[3], *top, *mid, *bot, *tmp;
    zs_edge *edges = (zs_edge *)r->edges;
    uint16_t *efree = (uint16_t *)r->edge_free;
    uint16_t *afree = (uint16_t *)r->active_free;
    uint16_t ai, el, es;
    zs_active *a;
    zs_edge *elong, *eshort;
    int64_t cross, area2;
    int32_t ox, oy;
    if (r->n_active_free < 1 || r->n_edge_free < 2) {
        r->stats.edges_dropped++; /* capacity policy: the triangle is skipped */
        return ZS_NONE;
    }
    ai = afree[--r->n_active_free];
    el = efree[--r->n_edge_free];
    es = efree[--r->n_edge_free];
    a = &((zs_active *)r->active)[ai];
    elong = &edges[el];
    eshort = &edges[es];

    v[0] = &pool[t->v[0]];
    v[1] = &pool[t->v[1]];
    v[2] = &pool[t->v[2]];
    top = v[0];
    mid = v[1];
    bot = v[2];
    if (mid->y < top->y) { tmp = top; top = mid; mid = tmp; }
    if (bot->y < mid->y) { tmp = mid; mid = bot; bot = tmp; }
    if (mid->y < top->y) { tmp = top; top = mid; mid = tmp; }
    /* which side of the long edge top -> bot the middle vertex lies on */
    cross = ((int64_t)mid->x - top->x) * ((int64_t)bot->y - top->y) -
            ((int64_t)bot->x - top->x) * ((int64_t)mid->y - top->y);

    edge_init(elong, top, bot, y);
    if (y < zs_first_row(mid->y)) {
        edge_init(eshort, top, mid, y);
        eshort->upper = 1;
    } else {
        edge_init(eshort, mid, bot, y);
        eshort->upper = 0;
    }
    elong->upper = 0;
    elong->owner = eshort->owner = ai;
    elong->pad = eshort->pad = 0;
    /* mid to the right of the long edge: the long edge leads (left) */
    elong->trailing = cross > 0 ? 0 : 1;
    eshort->trailing = (uint8_t)!elong->trailing;
    a->right = elong->trailing ? el : es;
    a->tri = ti;
    a->inside = 0;
    a->set_pos = 0;
    a->y_end = elong->y_end;

    area2 = zs_area2(v[0], v[1], v[2]);
    ox = zs_asr32(v[0]->x, 4);
    oy = zs_asr32(v[0]->y, 4);
    depth_plane(a, v, area2, ox, oy, y);
    zs_shade_setup(r, a, t, v, ox, oy, area2, y);
    r->stats.tris_drawn++;
    *left = elong->trailing ? es : el;
    return ai;
}

/* Continues the upper short edge of an active triangle with the lower one. */
void zs_edge_continue(zs_renderer *r, zs_edge *e, int32_t y)
{
    const zs_active *a = &((const zs_active *)r->active)[e->owner];
    const zs_tri *t = &((const zs_tri *)r->tris)[a->tri];
    const zs_vert *pool = (const zs_vert *)r->verts;
    const zs_vert *top = &pool[t->v[0]], *mid = &pool[t->v[1]], *bot = &pool[t->v[2]], *tmp;
    if (mid->y < top->y) { tmp = top; top = mid; mid = tmp; }
    if (bot->y < mid->y) { tmp = mid; mid = bot; bot = tmp; }
    if (mid->y < top->y) { tmp = top; top = mid; mid = tmp; }
    edge_init(e, mid, bot, y);
    e->upper = 0;
}
