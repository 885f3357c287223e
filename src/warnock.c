/* SPDX-License-Identifier: MIT */
/* Warnock mode: visibility by recursive subdivision of the band's
 * rectangle. Every record crossing the band gets its planes once (in the
 * active pool, idle in this mode); then a window
 *  - that no record reaches gets the background,
 *  - that one record reaches gets that record's spans and background,
 *  - that a record surrounds in front of all others there gets that record,
 *  - else splits into quadrants, down to single pixels, which the pixel-
 *    centre rule decides (nearest depth, ties to the first submitted).
 * Each record is classified against a window as disjoint, intersecting,
 * contained or surrounding by exact integer tests on its edges (centre.c),
 * and its depth over the window bounded by its plane at the corners (a
 * plane is linear) or, for a steep one, by its vertex depths widened past
 * the evaluation error. The depths compared are the ones the other modes
 * compare, so the image is theirs byte for byte.
 *
 * No memory but the pools and a bounded stack of windows: the candidates are
 * tested again in every window instead of being passed down in lists. */
#include "zs_centre.h"

/* A band of at most ZS_MAX_DIM = 2^10 pixels each way reaches single pixels
 * after 10 halvings; depth first, the stack holds at most three siblings
 * waiting per level plus the four children just pushed. */
#define ZS_WARNOCK_LEVELS 10
#define ZS_WARNOCK_STACK (3 * ZS_WARNOCK_LEVELS + 4)

/* A steep plane's evaluations at covered centres stay within 2^24 (Q40) of
 * the true plane, which lies between its vertex depths (activate.c). */
#define ZS_STEEP_SLACK ((int64_t)1 << 24)

enum { ZS_WIN_DISJOINT, ZS_WIN_INTERSECTING, ZS_WIN_CONTAINED, ZS_WIN_SURROUNDING };

typedef struct zs_window {
    int16_t x0, y0, x1, y1; /* pixels [x0, x1) x [y0, y1) */
} zs_window;

typedef struct zs_band {
    zs_renderer *r;
    uint8_t *buf;   /* row y0 of the band */
    size_t stride;
    int32_t y0;
    uint16_t n;     /* candidates: active[0 .. n) */
} zs_band;

static uint8_t *band_row(const zs_band *b, int32_t y)
{
    return b->buf + (size_t)(y - b->y0) * b->stride;
}

static void view_of(const zs_renderer *r, const zs_active *a, zs_rec_view *v)
{
    zs_canonical_vertices(r, &r->priv.tris[a->tri], v->s);
    v->long_left = (a->flags & ZS_ACT_LONG_LEFT) != 0;
    v->row0 = zs_clampi(zs_first_row(v->s[0]->y), 0, r->cfg.height);
    v->row_end = a->y_end;
}

static int classify(const zs_rec_view *v, const zs_window *w)
{
    int32_t X0 = 16 * w->x0 + 8, X1 = 16 * (w->x1 - 1) + 8;
    int32_t Y0 = 16 * w->y0 + 8, Y1 = 16 * (w->y1 - 1) + 8;
    int32_t cmin, cmax;
    if (zs_rec_separated(v, w->x0, w->y0, w->x1, w->y1))
        return ZS_WIN_DISJOINT;
    /* the covered centres are a convex set's lattice points: all four
     * corners covered, the whole window is */
    if (zs_rec_covers(v, X0, Y0) && zs_rec_covers(v, X1, Y0) && zs_rec_covers(v, X0, Y1) &&
        zs_rec_covers(v, X1, Y1))
        return ZS_WIN_SURROUNDING;
    cmin = v->s[0]->x < v->s[1]->x ? v->s[0]->x : v->s[1]->x;
    cmin = cmin < v->s[2]->x ? cmin : v->s[2]->x;
    cmax = v->s[0]->x > v->s[1]->x ? v->s[0]->x : v->s[1]->x;
    cmax = cmax > v->s[2]->x ? cmax : v->s[2]->x;
    if (v->row0 >= w->y0 && v->row_end <= w->y1 && zs_first_row(cmin) >= w->x0 &&
        zs_first_row(cmax) <= w->x1)
        return ZS_WIN_CONTAINED;
    return ZS_WIN_INTERSECTING;
}

/* Least and largest depth the record can show at the window's centres. */
static void depth_bounds(const zs_rec_view *v, const zs_active *a, const zs_active_plane *p,
                         const zs_window *w, int64_t *lo, int64_t *hi)
{
    if (a->flags & ZS_ACT_STEEP) {
        uint32_t z0 = v->s[0]->z, z1 = v->s[1]->z, z2 = v->s[2]->z;
        uint32_t zmin = z0 < z1 ? z0 : z1, zmax = z0 < z1 ? z1 : z0;
        zmin = zmin < z2 ? zmin : z2;
        zmax = zmax > z2 ? zmax : z2;
        *lo = (int64_t)zmin * 1024 - ZS_STEEP_SLACK;
        *hi = (int64_t)zmax * 1024 + ZS_STEEP_SLACK;
    } else {
        int64_t top = zs_row_depth(p, a, w->y0), bottom = zs_row_depth(p, a, w->y1 - 1);
        int64_t left = zs_mul64_small(a->zdx, w->x0), right = zs_mul64_small(a->zdx, w->x1 - 1);
        int64_t rmin = top < bottom ? top : bottom, rmax = top < bottom ? bottom : top;
        *lo = rmin + (left < right ? left : right);
        *hi = rmax + (left < right ? right : left);
    }
}

/* Rows of the window set to record i (or the background, i < 0). */
static void fill(const zs_band *b, const zs_window *w, int i, int32_t x0, int32_t x1, int32_t y)
{
    zs_renderer *r = b->r;
    uint8_t *row = band_row(b, y);
    if (x0 >= x1)
        return;
    if (i < 0)
        zs_fill_flat(row, x0, x1, r->priv.bpp, r->priv.background);
    else if (r->priv.active[i].flags & ZS_ACT_GOURAUD)
        zs_fill_gouraud(r, &r->priv.acolor[i], y - r->priv.active[i].y0, row, x0, x1);
    else
        zs_fill_flat(row, x0, x1, r->priv.bpp, r->priv.active[i].pixel);
    (void)w;
    r->stats.spans++;
}

static void fill_window(const zs_band *b, const zs_window *w, int i)
{
    int32_t y;
    for (y = w->y0; y < w->y1; y++)
        fill(b, w, i, w->x0, w->x1, y);
}

/* The only record reaching the window: its spans, background around. */
static void draw_single(const zs_band *b, const zs_window *w, int i, const zs_rec_view *v)
{
    int32_t y;
    for (y = w->y0; y < w->y1; y++) {
        int32_t xl = w->x1, xr = w->x1;
        if (y >= v->row0 && y < v->row_end) {
            xl = zs_clampi(zs_rec_left_col(v, y), w->x0, w->x1);
            xr = zs_clampi(zs_rec_right_col(v, y), w->x0, w->x1);
            if (xr < xl)
                xr = xl;
        }
        fill(b, w, -1, w->x0, xl, y);
        fill(b, w, i, xl, xr, y);
        fill(b, w, -1, xr, w->x1, y);
    }
}

/* A one-pixel window: the nearest record covering the centre. */
static void decide_pixel(const zs_band *b, const zs_window *w)
{
    zs_renderer *r = b->r;
    zs_active *act = r->priv.active;
    int32_t X = 16 * w->x0 + 8, Y = 16 * w->y0 + 8;
    int64_t best_z = 0;
    int best = -1, i;
    for (i = 0; i < b->n; i++) {
        zs_rec_view v;
        int64_t z;
        view_of(r, &act[i], &v);
        if (!zs_rec_covers(&v, X, Y))
            continue;
        z = zs_rec_depth(r, &v, &act[i], &r->priv.aplane[i], w->x0, w->y0);
        r->stats.depth_evals++;
        if (best < 0 || z < best_z || (z == best_z && act[i].tri < act[best].tri)) {
            best = i;
            best_z = z;
        }
    }
    r->stats.pixel_decisions++;
    fill(b, w, best, w->x0, w->x1, w->y0);
}

/* Is record f (surrounding, depth at most f_hi) in front of every other
 * record reaching the window? */
static int in_front(const zs_band *b, const zs_window *w, int f, int64_t f_hi)
{
    const zs_renderer *r = b->r;
    const zs_active *act = r->priv.active;
    int i;
    for (i = 0; i < b->n; i++) {
        zs_rec_view v;
        int64_t lo, hi;
        if (i == f)
            continue;
        view_of(r, &act[i], &v);
        if (classify(&v, w) == ZS_WIN_DISJOINT)
            continue;
        depth_bounds(&v, &act[i], &r->priv.aplane[i], w, &lo, &hi);
        if (!(f_hi < lo || (f_hi == lo && act[f].tri < act[i].tri)))
            return 0;
    }
    return 1;
}

/* Decides a window if it is simple; 0 when it must be split. */
static int resolve(const zs_band *b, const zs_window *w)
{
    const zs_renderer *r = b->r;
    const zs_active *act = r->priv.active;
    int i, reach = 0, one = -1, front = -1, one_kind = ZS_WIN_DISJOINT;
    int64_t front_hi = 0;
    zs_rec_view one_view;
    for (i = 0; i < b->n; i++) {
        zs_rec_view v;
        int kind;
        view_of(r, &act[i], &v);
        kind = classify(&v, w);
        if (kind == ZS_WIN_DISJOINT)
            continue;
        reach++;
        one = i;
        one_kind = kind;
        one_view = v;
        if (kind == ZS_WIN_SURROUNDING) {
            int64_t lo, hi;
            depth_bounds(&v, &act[i], &r->priv.aplane[i], w, &lo, &hi);
            if (front < 0 || hi < front_hi || (hi == front_hi && act[i].tri < act[front].tri)) {
                front = i;
                front_hi = hi;
            }
        }
    }
    if (reach == 0) {
        fill_window(b, w, -1);
        return 1;
    }
    if (reach == 1) {
        if (one_kind == ZS_WIN_SURROUNDING)
            fill_window(b, w, one);
        else
            draw_single(b, w, one, &one_view);
        return 1;
    }
    if (front >= 0 && in_front(b, w, front, front_hi)) {
        fill_window(b, w, front);
        return 1;
    }
    return 0;
}

static void subdivide(const zs_band *b, int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
    zs_window stack[ZS_WARNOCK_STACK];
    int sp = 0;
    stack[sp].x0 = (int16_t)x0;
    stack[sp].y0 = (int16_t)y0;
    stack[sp].x1 = (int16_t)x1;
    stack[sp].y1 = (int16_t)y1;
    sp++;
    while (sp > 0) {
        zs_window w = stack[--sp];
        int16_t mx, my;
        b->r->stats.windows++;
        if (w.x1 - w.x0 == 1 && w.y1 - w.y0 == 1) {
            decide_pixel(b, &w);
            continue;
        }
        if (resolve(b, &w))
            continue;
        /* quadrants (halves when one side is a pixel), pushed so the top
         * left is taken first */
        mx = (int16_t)(w.x1 - w.x0 > 1 ? (w.x0 + w.x1) / 2 : w.x1);
        my = (int16_t)(w.y1 - w.y0 > 1 ? (w.y0 + w.y1) / 2 : w.y1);
        if (mx < w.x1 && my < w.y1) {
            stack[sp].x0 = mx; stack[sp].y0 = my; stack[sp].x1 = w.x1; stack[sp].y1 = w.y1;
            sp++;
        }
        if (my < w.y1) {
            stack[sp].x0 = w.x0; stack[sp].y0 = my; stack[sp].x1 = mx; stack[sp].y1 = w.y1;
            sp++;
        }
        if (mx < w.x1) {
            stack[sp].x0 = mx; stack[sp].y0 = w.y0; stack[sp].x1 = w.x1; stack[sp].y1 = my;
            sp++;
        }
        stack[sp].x0 = w.x0; stack[sp].y0 = w.y0; stack[sp].x1 = mx; stack[sp].y1 = my;
        sp++;
    }
}

/* Records crossing rows [y, y + n): counted, or given planes in the active
 * pool (as many as it holds) when fill is set. */
static uint32_t gather(zs_renderer *r, int32_t y, int32_t n, int fill_pool)
{
    const zs_tri *tris = r->priv.tris;
    uint32_t cap = r->cfg.max_active_edges / 2u, count = 0;
    int32_t b = y - (int32_t)r->priv.tall_rows + 1, first = r->stats.windows == 0;
    if (b < 0)
        b = 0;
    for (; b < y + n; b++) {
        uint16_t ti;
        for (ti = r->priv.buckets[b]; ti != ZS_NONE; ti = tris[ti].next) {
            zs_rec_view v;
            zs_rec_view_make(r, ti, &v);
            if (v.row_end <= y)
                continue;
            if (fill_pool) {
                if (count >= cap) {
                    /* capacity policy: left out of the band; counted in the
                     * first band it reaches, as drawn records are */
                    if (b >= y || first)
                        r->stats.records_skipped++;
                    continue;
                }
                zs_rec_planes(r, ti, &v, v.row0, &r->priv.active[count], &r->priv.aplane[count],
                              r->priv.acolor ? &r->priv.acolor[count] : 0, 1);
                if (b >= y || first) /* counted in the first band it reaches */
                    r->stats.tris_drawn++;
            }
            count++;
        }
    }
    return count;
}

void zs_warnock_rows(zs_renderer *r, int32_t y0, int32_t rows, uint8_t *buf, size_t stride)
{
    uint32_t cap = r->cfg.max_active_edges / 2u;
    int32_t y = y0, end = y0 + rows;
    zs_rec_count_tall(r);
    while (y < end) {
        /* a band whose records do not all fit the pool is rendered in
         * parts, halved until they do (down to one row) */
        int32_t n = end - y;
        zs_band b;
        uint32_t demand;
        while (n > 1 && gather(r, y, n, 0) > cap)
            n = (n + 1) / 2;
        demand = 2u * gather(r, y, n, 1); /* edge sides, as the row modes count them */
        if (demand > 2u * cap)
            demand = 2u * cap;
        if (demand > r->stats.max_active_edges)
            r->stats.max_active_edges = demand;
        b.r = r;
        b.buf = buf + (size_t)(y - y0) * stride;
        b.stride = stride;
        b.y0 = y;
        b.n = (uint16_t)(demand / 2u);
        subdivide(&b, 0, y, r->cfg.width, y + n);
        r->stats.pixels_shaded += (uint32_t)n * r->cfg.width;
        y += n;
    }
}
