/* SPDX-License-Identifier: MIT */
/* Stored triangle records evaluated at pixel centres directly, for Warnock
 * mode and picking: the coverage rule of the edge walk written as edge
 * functions, and the planes zs_activate makes, so every decision equals the
 * row machinery's without its pools of edges.
 *
 * Coverage: the walk covers column c of row y when the centre (X, Y) =
 * (16c + 8, 16y + 8) has s0.y <= Y < s2.y and X_left(Y) <= X < X_right(Y),
 * each boundary being the edge that spans Y. The triangle is convex, so its
 * left chain is the maximum and its right chain the minimum of their edges'
 * lines: testing every non-horizontal edge's line (left ones inclusive,
 * right ones exclusive) is the same rule, and the covered centres are the
 * lattice points of a convex set. */
#include "zs_centre.h"

static int32_t min3i(int32_t a, int32_t b, int32_t c)
{
    int32_t m = a < b ? a : b;
    return m < c ? m : c;
}

static int32_t max3i(int32_t a, int32_t b, int32_t c)
{
    int32_t m = a > b ? a : b;
    return m > c ? m : c;
}

int32_t zs_rec_first_row(const zs_renderer *r, uint16_t ti)
{
    const zs_tri *t = &r->priv.tris[ti];
    const zs_vert *p = r->priv.verts;
    return zs_clampi(zs_first_row(min3i(p[t->v[0]].y, p[t->v[1]].y, p[t->v[2]].y)), 0,
                     r->cfg.height);
}

void zs_rec_view_make(const zs_renderer *r, uint16_t ti, zs_rec_view *v)
{
    const zs_vert *s[3];
    zs_canonical_vertices(r, &r->priv.tris[ti], s);
    v->s[0] = s[0];
    v->s[1] = s[1];
    v->s[2] = s[2];
    v->long_left = zs_area2_inline(s[0], s[1], s[2]) > 0; /* as zs_activate decides */
    v->row0 = zs_clampi(zs_first_row(s[0]->y), 0, r->cfg.height);
    v->row_end = zs_first_row(s[2]->y);
}

/* The centre is on the covered side of edge a -> b (a above b). */
static int inside_edge(const zs_vert *a, const zs_vert *b, int32_t X, int32_t Y, int left)
{
    int32_t dx = b->x - a->x, dy = b->y - a->y; /* coordinates within int16 */
    int64_t d = (int64_t)(X - a->x) * dy - (int64_t)(Y - a->y) * dx; /* > 0: right of it */
    return left ? d >= 0 : d < 0;
}

int zs_rec_covers(const zs_rec_view *v, int32_t X, int32_t Y)
{
    const zs_vert *s0 = v->s[0], *s1 = v->s[1], *s2 = v->s[2];
    if (Y < s0->y || Y >= s2->y)
        return 0;
    if (!inside_edge(s0, s2, X, Y, v->long_left))
        return 0;
    if (s1->y > s0->y && !inside_edge(s0, s1, X, Y, !v->long_left))
        return 0;
    return s2->y <= s1->y || inside_edge(s1, s2, X, Y, !v->long_left);
}

/* All four corner centres outside edge a -> b: by convexity of the outside,
 * every centre of the window is. */
static int edge_separates(const zs_vert *a, const zs_vert *b, int left, int32_t X0, int32_t Y0,
                          int32_t X1, int32_t Y1)
{
    if (b->y == a->y)
        return 0; /* horizontal: the row range decides */
    return !inside_edge(a, b, X0, Y0, left) && !inside_edge(a, b, X1, Y0, left) &&
           !inside_edge(a, b, X0, Y1, left) && !inside_edge(a, b, X1, Y1, left);
}

int zs_rec_separated(const zs_rec_view *v, int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
    const zs_vert *s0 = v->s[0], *s1 = v->s[1], *s2 = v->s[2];
    int32_t X0 = 16 * x0 + 8, X1 = 16 * (x1 - 1) + 8, Y0 = 16 * y0 + 8, Y1 = 16 * (y1 - 1) + 8;
    /* bounding box: X_left >= the least vertex x, X_right <= the largest */
    if (Y1 < s0->y || Y0 >= s2->y || X1 < min3i(s0->x, s1->x, s2->x) ||
        X0 >= max3i(s0->x, s1->x, s2->x))
        return 1;
    return edge_separates(s0, s2, v->long_left, X0, Y0, X1, Y1) ||
           edge_separates(s0, s1, !v->long_left, X0, Y0, X1, Y1) ||
           edge_separates(s1, s2, !v->long_left, X0, Y0, X1, Y1);
}

/* ceil(x(Y) - 0.5) in columns on edge a -> b: the walk's exact column. */
static int32_t edge_col(const zs_vert *a, const zs_vert *b, int32_t Y)
{
    int64_t dx = (int64_t)b->x - a->x, dy = (int64_t)b->y - a->y;
    int64_t num = ((int64_t)a->x - 8) * dy + ((int64_t)Y - a->y) * dx, den = 16 * dy;
    int64_t q = num / den;
    if (q * den < num)
        q++;
    return (int32_t)q;
}

static int32_t chain_col(const zs_rec_view *v, int32_t y, int long_side)
{
    int32_t Y = 16 * y + 8;
    if (long_side)
        return edge_col(v->s[0], v->s[2], Y);
    return Y < v->s[1]->y ? edge_col(v->s[0], v->s[1], Y) : edge_col(v->s[1], v->s[2], Y);
}

int32_t zs_rec_left_col(const zs_rec_view *v, int32_t y)
{
    return chain_col(v, y, v->long_left);
}

int32_t zs_rec_right_col(const zs_rec_view *v, int32_t y)
{
    return chain_col(v, y, !v->long_left);
}

void zs_rec_planes(const zs_renderer *r, uint16_t ti, const zs_rec_view *v, int32_t y,
                   zs_active *a, zs_active_plane *p, zs_active_color *ac, int shade)
{
    const zs_tri *t = &r->priv.tris[ti];
    const zs_vert *pool = r->priv.verts;
    const zs_vert *s[3], *pv[3];
    zs_recip area2;
    s[0] = v->s[0];
    s[1] = v->s[1];
    s[2] = v->s[2];
    a->tri = ti;
    a->inside = 0;
    a->set_pos = 0;
    a->flags = v->long_left ? ZS_ACT_LONG_LEFT : 0;
    a->y_end = (int16_t)v->row_end;
    zs_recip_init(&area2, zs_area2_inline(s[0], s[1], s[2]));
    zs_record_depth_plane(a, p, s, &area2, zs_asr32(s[0]->x, 4), zs_asr32(s[0]->y, 4), y);
    if (!shade)
        return; /* depth only (picking) */
    pv[0] = &pool[t->v[0]];
    pv[1] = &pool[t->v[1]];
    pv[2] = &pool[t->v[2]];
    area2.neg = 1; /* a front face in submission order, as zs_activate has it */
    zs_shade_setup(r, a, ac, t, pv, zs_asr32(pv[0]->x, 4), zs_asr32(pv[0]->y, 4), &area2, y);
}

int64_t zs_rec_depth(const zs_renderer *r, const zs_rec_view *v, const zs_active *a,
                     zs_active_plane *p, int32_t x, int32_t y)
{
    if (a->flags & ZS_ACT_STEEP) /* the walk anchors it at its left edge on every row */
        zs_anchor_depth(r, a, p, zs_clampi(zs_rec_left_col(v, y), 0, r->cfg.width), y);
    return zs_row_depth(p, a, y) + zs_mul64_small(a->zdx, x);
}

void zs_rec_count_tall(zs_renderer *r)
{
    const zs_vert *p = r->priv.verts;
    int32_t tall = 0;
    uint16_t i;
    if (r->priv.tall_rows != 0xFFFFu)
        return;
    for (i = 0; i < r->priv.n_tris; i++) {
        const zs_tri *t = &r->priv.tris[i];
        int32_t y0 = p[t->v[0]].y, y1 = p[t->v[1]].y, y2 = p[t->v[2]].y;
        int32_t rows = zs_first_row(max3i(y0, y1, y2)) -
                       zs_clampi(zs_first_row(min3i(y0, y1, y2)), 0, r->cfg.height);
        tall = rows > tall ? rows : tall;
    }
    r->priv.tall_rows = (uint16_t)tall; /* first rows >= 0, last within int16 / 16 */
}
