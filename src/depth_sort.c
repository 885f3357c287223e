/* SPDX-License-Identifier: MIT */
/* Depth sort of the stored records for ZS_MODE_PRIORITY (zs_depth_sort,
 * zspan/priority.h): a list far to near by each record's farthest depth,
 * then (ZS_SORT_NNS) the Newell-Newell-Sancha tests on every pair whose
 * depth ranges overlap, moving or splitting records until no record is
 * drawn after one it hides. The records are then renumbered near to far
 * (priority order) and the row buckets rebuilt.
 *
 * Everything is in screen space: x, y in 28.4 pixels and window depth z,
 * where a triangle's plane stays a plane (a projective map keeps planes). */
#include "zs_internal.h"
#include "zspan/priority.h"

#define MOVED 0x8000u /* aux: moved ahead once (a second move means a cycle) */
#define DEAD 0x4000u  /* aux: replaced by its pieces */
#define Z_SHIFT 10    /* depth bits dropped in plane arithmetic (Q20 left) */

typedef struct sort_ctx {
    zs_renderer *r;
    uint16_t *list; /* far to near */
    uint16_t *aux;
    uint32_t n;     /* list length */
    uint32_t budget;
} sort_ctx;

static const zs_vert *vert(const zs_renderer *r, uint16_t t, int k)
{
    return &r->priv.verts[r->priv.tris[t].v[k]];
}

static uint32_t zmax_of(const zs_renderer *r, uint16_t t)
{
    uint32_t a = vert(r, t, 0)->z, b = vert(r, t, 1)->z, c = vert(r, t, 2)->z;
    uint32_t m = a > b ? a : b;
    return m > c ? m : c;
}

static uint32_t zmin_of(const zs_renderer *r, uint16_t t)
{
    uint32_t a = vert(r, t, 0)->z, b = vert(r, t, 1)->z, c = vert(r, t, 2)->z;
    uint32_t m = a < b ? a : b;
    return m < c ? m : c;
}

/* Farther first (larger farthest depth), then the earlier record. */
static int before(const zs_renderer *r, uint16_t a, uint16_t b)
{
    uint32_t za = zmax_of(r, a), zb = zmax_of(r, b);
    return za > zb || (za == zb && a < b);
}

/* Heap sort of list[0, n) by `before` (no allocation, O(n log n)). */
static void sift(const zs_renderer *r, uint16_t *l, uint32_t i, uint32_t n)
{
    for (;;) {
        uint32_t c = 2 * i + 1, m = i;
        uint16_t t;
        if (c < n && before(r, l[m], l[c]))
            m = c;
        if (c + 1 < n && before(r, l[m], l[c + 1]))
            m = c + 1;
        if (m == i)
            return;
        t = l[i];
        l[i] = l[m];
        l[m] = t;
        i = m;
    }
}

static void heap_sort(const zs_renderer *r, uint16_t *l, uint32_t n)
{
    uint32_t i;
    for (i = n / 2; i-- > 0;)
        sift(r, l, i, n);
    for (i = n; i-- > 1;) {
        uint16_t t = l[0];
        l[0] = l[i];
        l[i] = t;
        sift(r, l, 0, i);
    }
}

/* A record's plane n . (p - p0) in (x, y, z >> Z_SHIFT), and a tolerance of
 * one unit of each coordinate; 0 for a record without area. */
typedef struct plane {
    int64_t n[3];
    int64_t p0[3];
    int64_t tol;
} plane;

static int64_t abs64(int64_t v)
{
    return v < 0 ? -v : v;
}

static void point(const zs_vert *v, int64_t p[3])
{
    p[0] = v->x;
    p[1] = v->y;
    p[2] = (int64_t)(v->z >> Z_SHIFT);
}

static int make_plane(const zs_renderer *r, uint16_t t, plane *pl)
{
    int64_t a[3], b[3], c[3];
    int k;
    point(vert(r, t, 0), a);
    point(vert(r, t, 1), b);
    point(vert(r, t, 2), c);
    for (k = 0; k < 3; k++) {
        b[k] -= a[k];
        c[k] -= a[k];
        pl->p0[k] = a[k];
    }
    /* |x|, |y| differences < 2^16, z < 2^21: products < 2^38 */
    pl->n[0] = b[1] * c[2] - b[2] * c[1];
    pl->n[1] = b[2] * c[0] - b[0] * c[2];
    pl->n[2] = b[0] * c[1] - b[1] * c[0];
    pl->tol = abs64(pl->n[0]) + abs64(pl->n[1]) + abs64(pl->n[2]);
    return pl->n[2] != 0;
}

/* Signed side of v: > 0 farther than the plane (larger z), < 0 nearer, 0
 * within the tolerance. */
static int side(const plane *pl, const zs_vert *v)
{
    int64_t p[3], s;
    point(v, p);
    s = pl->n[0] * (p[0] - pl->p0[0]) + pl->n[1] * (p[1] - pl->p0[1]) +
        pl->n[2] * (p[2] - pl->p0[2]);
    if (pl->n[2] < 0)
        s = -s;
    return s > pl->tol ? 1 : s < -pl->tol ? -1 : 0;
}

/* Are all of t's vertices on side `want` (1 far, -1 near) of pl or in it? */
static int all_on(const zs_renderer *r, const plane *pl, uint16_t t, int want)
{
    int k;
    for (k = 0; k < 3; k++)
        if (side(pl, vert(r, t, k)) == -want)
            return 0;
    return 1;
}

/* Do the two screen triangles share no pixel centre? (An edge of either with
 * the other wholly on its outer side or on it: separating axes.) */
static int apart_on_screen(const zs_renderer *r, uint16_t a, uint16_t b)
{
    int pass, k, j;
    for (pass = 0; pass < 2; pass++) {
        uint16_t s = pass ? b : a, o = pass ? a : b;
        const zs_vert *v[3];
        int64_t orient;
        for (k = 0; k < 3; k++)
            v[k] = vert(r, s, k);
        orient = zs_area2(v[0], v[1], v[2]);
        if (orient == 0)
            return 1;
        for (k = 0; k < 3; k++) {
            const zs_vert *p = v[k], *q = v[(k + 1) % 3];
            int outside = 1;
            for (j = 0; j < 3 && outside; j++) {
                const zs_vert *w = vert(r, o, j);
                int64_t e = (int64_t)(q->x - p->x) * (w->y - p->y) -
                            (int64_t)(q->y - p->y) * (w->x - p->x);
                /* inside is the side of the third vertex */
                if ((orient < 0 && e < 0) || (orient > 0 && e > 0))
                    outside = 0;
            }
            if (outside)
                return 1;
        }
    }
    return 0;
}

/* Can p be drawn before q (p does not hide any part of q)? */
static int may_precede(const zs_renderer *r, uint16_t p, uint16_t q)
{
    plane pp, pq;
    int k;
    int32_t pxl = INT32_MAX, pxh = INT32_MIN, pyl = INT32_MAX, pyh = INT32_MIN;
    int32_t qxl = INT32_MAX, qxh = INT32_MIN, qyl = INT32_MAX, qyh = INT32_MIN;
    for (k = 0; k < 3; k++) {
        const zs_vert *a = vert(r, p, k), *b = vert(r, q, k);
        pxl = a->x < pxl ? a->x : pxl;
        pxh = a->x > pxh ? a->x : pxh;
        pyl = a->y < pyl ? a->y : pyl;
        pyh = a->y > pyh ? a->y : pyh;
        qxl = b->x < qxl ? b->x : qxl;
        qxh = b->x > qxh ? b->x : qxh;
        qyl = b->y < qyl ? b->y : qyl;
        qyh = b->y > qyh ? b->y : qyh;
    }
    if (pxh <= qxl || qxh <= pxl || pyh <= qyl || qyh <= pyl)
        return 1; /* x or y extents apart */
    if (make_plane(r, q, &pq) && all_on(r, &pq, p, 1))
        return 1; /* p behind q's plane */
    if (make_plane(r, p, &pp) && all_on(r, &pp, q, -1))
        return 1; /* q in front of p's plane */
    return apart_on_screen(r, p, q);
}

/* Interpolates from a to b by num / den (0 <= num <= den, den > 0). */
static int32_t lerp32(int64_t a, int64_t b, int64_t num, int64_t den)
{
    return (int32_t)(a + zs_muldiv64(b - a, num, den, 1));
}

/* The vertex where edge a-b crosses pl (sa, sb: their plane values, opposite
 * signs), or ZS_NONE with the vertex pool full. */
static uint16_t cut_vertex(zs_renderer *r, uint16_t a, uint16_t b, int64_t sa, int64_t sb)
{
    const zs_vert *va = &r->priv.verts[a], *vb = &r->priv.verts[b];
    uint16_t n = r->priv.n_verts;
    int64_t num = abs64(sa), den = abs64(sa - sb);
    zs_vert *v;
    if (n >= r->cfg.max_vertices)
        return ZS_NONE;
    v = &r->priv.verts[n];
    v->x = (int16_t)lerp32(va->x, vb->x, num, den);
    v->y = (int16_t)lerp32(va->y, vb->y, num, den);
    v->z = (uint32_t)lerp32(va->z, vb->z, num, den);
    if (r->priv.vshade) {
        uint32_t ca = r->priv.vshade[a], cb = r->priv.vshade[b], c = 0;
        unsigned s;
        for (s = 0; s < 32; s += 8)
            c |= (uint32_t)lerp32((ca >> s) & 255u, (cb >> s) & 255u, num, den) << s;
        r->priv.vshade[n] = c;
    }
    r->priv.n_verts = (uint16_t)(n + 1u);
    r->stats.verts_stored = r->priv.n_verts;
    return n;
}

static int64_t plane_value(const plane *pl, const zs_vert *v)
{
    int64_t p[3];
    point(v, p);
    return pl->n[0] * (p[0] - pl->p0[0]) + pl->n[1] * (p[1] - pl->p0[1]) +
           pl->n[2] * (p[2] - pl->p0[2]);
}

/* Cuts record q by the plane of record p into pieces stored as new records;
 * their numbers in out (up to 3), count returned; -1 if it could not be cut
 * (no plane, it does not straddle, or a pool is full). */
static int split_record(sort_ctx *c, uint16_t p, uint16_t q, uint16_t *out)
{
    zs_renderer *r = c->r;
    plane pl;
    uint16_t poly[2][4];
    int np[2] = {0, 0}, k, side_k[3], nf = 0, nb = 0, n_out = 0, h;
    int64_t s[3];
    const zs_tri *t = &r->priv.tris[q];
    uint32_t color = t->color;
    uint16_t tv[3];
    if (!make_plane(r, p, &pl))
        return -1;
    for (k = 0; k < 3; k++) {
        tv[k] = t->v[k];
        s[k] = plane_value(&pl, &r->priv.verts[tv[k]]);
        side_k[k] = side(&pl, &r->priv.verts[tv[k]]);
        nf += side_k[k] > 0;
        nb += side_k[k] < 0;
    }
    if (!nf || !nb)
        return -1;
    /* worst case 2 new vertices and 3 records */
    if ((uint32_t)r->priv.n_verts + 2u > r->cfg.max_vertices ||
        (uint32_t)r->priv.n_tris + 3u > r->cfg.max_triangles)
        return -1;
    for (k = 0; k < 3; k++) {
        int j = (k + 1) % 3;
        if (side_k[k] >= 0)
            poly[0][np[0]++] = tv[k];
        if (side_k[k] <= 0)
            poly[1][np[1]++] = tv[k];
        if (side_k[k] * side_k[j] < 0) {
            uint16_t x = cut_vertex(r, tv[k], tv[j], s[k], s[j]);
            poly[0][np[0]++] = x;
            poly[1][np[1]++] = x;
        }
    }
    for (h = 0; h < 2; h++)
        for (k = 1; k + 1 < np[h]; k++) {
            uint16_t a = poly[h][0], b = poly[h][k], d = poly[h][k + 1];
            uint16_t before_n = r->priv.n_tris;
            zs_setup_triangle(r, a, b, d,
                              zs_area2(&r->priv.verts[a], &r->priv.verts[b], &r->priv.verts[d]),
                              color, (uint16_t)color);
            if (r->priv.n_tris != before_n)
                out[n_out++] = before_n;
        }
    r->stats.sort_splits++;
    return n_out;
}

/* Puts record t into list[from, n) at its place by `before`. */
static void insert_sorted(sort_ctx *c, uint32_t from, uint16_t t)
{
    uint32_t j = c->n++;
    while (j > from && before(c->r, t, c->list[j - 1])) {
        c->list[j] = c->list[j - 1];
        j--;
    }
    c->list[j] = t;
}

static void nns(sort_ctx *c)
{
    zs_renderer *r = c->r;
    uint32_t i = 0;
    while (i < c->n) {
        uint16_t p = c->list[i];
        uint32_t zmin = zmin_of(r, p), j;
        int restart = 0;
        for (j = i + 1; j < c->n; j++) {
            uint16_t q = c->list[j];
            if (zmax_of(r, q) <= zmin) {
                /* the list is sorted but for the records moved ahead, which
                 * sit right after p (a chain of moves): past them, this and
                 * every later one is nearer than p */
                if (c->aux[q] & MOVED)
                    continue;
                break;
            }
            if (c->budget == 0) {
                r->stats.sort_giveups++;
                return; /* the rest stays in plain sorted order */
            }
            c->budget--;
            if (may_precede(r, p, q))
                continue;
            r->stats.sort_pairs++;
            if (!(c->aux[q] & MOVED) && may_precede(r, q, p)) {
                /* q goes first: move it ahead of p and start again with it */
                uint32_t k;
                for (k = j; k > i; k--)
                    c->list[k] = c->list[k - 1];
                c->list[i] = q;
                c->aux[q] |= MOVED;
                r->stats.sort_swaps++;
                restart = 1;
                break;
            }
            /* a cycle or a penetration: cut q by p's plane (else p by q's) */
            {
                uint16_t pieces[3];
                uint16_t victim = q;
                int np = split_record(c, p, q, pieces), k;
                if (np < 0) {
                    victim = p;
                    np = split_record(c, q, p, pieces);
                }
                if (np < 0) {
                    r->stats.sort_giveups++; /* cannot be cut: leave the pair */
                    continue;
                }
                c->aux[victim] |= DEAD;
                /* take the victim out of the list, put the pieces in */
                {
                    uint32_t at = victim == q ? j : i, m;
                    for (m = at; m + 1 < c->n; m++)
                        c->list[m] = c->list[m + 1];
                    c->n--;
                }
                for (k = 0; k < np; k++) {
                    c->aux[pieces[k]] = 0;
                    insert_sorted(c, i, pieces[k]);
                }
                restart = 1;
                break;
            }
        }
        if (!restart)
            i++;
    }
}

/* Renumbers the records so that list[n - 1] (the nearest) is record 0 and
 * rebuilds the row buckets; dead records go past the end. */
static void renumber(sort_ctx *c)
{
    zs_renderer *r = c->r;
    uint16_t *pos = c->aux; /* reused: the new number of each record */
    uint32_t total = r->priv.n_tris, k, next = c->n;
    for (k = 0; k < total; k++)
        pos[k] = ZS_NONE;
    for (k = 0; k < c->n; k++)
        pos[c->list[c->n - 1u - k]] = (uint16_t)k;
    for (k = 0; k < total; k++)
        if (pos[k] == ZS_NONE)
            pos[k] = (uint16_t)next++;
    for (k = 0; k < total; k++) {
        while (pos[k] != k) { /* follow the cycle through slot k */
            uint16_t j = pos[k], tp;
            zs_tri tt = r->priv.tris[k];
            r->priv.tris[k] = r->priv.tris[j];
            r->priv.tris[j] = tt;
            tp = pos[k];
            pos[k] = pos[j];
            pos[j] = tp;
        }
    }
    r->priv.n_tris = (uint16_t)c->n;
    /* pushed in order, so each bucket runs newest first, as setup leaves
     * it (zs_raster_begin turns it) */
    memset(r->priv.buckets, 0xFF, (size_t)r->cfg.height * 2u);
    for (k = 0; k < c->n; k++) {
        zs_tri *t = &r->priv.tris[k];
        int32_t ymin = r->priv.verts[t->v[0]].y, row;
        int m;
        for (m = 1; m < 3; m++)
            ymin = r->priv.verts[t->v[m]].y < ymin ? r->priv.verts[t->v[m]].y : ymin;
        row = zs_clampi(zs_first_row(ymin), 0, (int32_t)r->cfg.height - 1);
        t->next = r->priv.buckets[row];
        r->priv.buckets[row] = (uint16_t)k;
    }
}

zs_status zs_depth_sort(zs_renderer *r, zs_sort_kind kind, uint32_t budget)
{
    sort_ctx c;
    uint32_t k;
    if (!r)
        return ZS_ERR_NULL;
    if (!(r->cfg.flags & ZS_CFG_PRIORITY))
        return ZS_ERR_MODE;
    if (kind != ZS_SORT_DEPTH && kind != ZS_SORT_NNS)
        return ZS_ERR_ARGUMENT;
    if (r->priv.state != ZS_STATE_OPEN)
        return ZS_ERR_STATE;
    c.r = r;
    c.list = r->priv.sort_list;
    c.aux = r->priv.sort_aux;
    c.n = r->priv.n_tris;
    c.budget = budget ? budget : ZS_SORT_BUDGET_DEFAULT;
    for (k = 0; k < c.n; k++) {
        c.list[k] = (uint16_t)k;
        c.aux[k] = 0;
    }
    heap_sort(r, c.list, c.n);
    if (kind == ZS_SORT_NNS)
        nns(&c);
    renumber(&c);
    return ZS_OK;
}
