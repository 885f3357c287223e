/* SPDX-License-Identifier: MIT */
/* Hidden-line drawing: the feature edges of the mesh, clipped by the
 * visibility the span walk computes. At the first row the records (every
 * front face of the frame, the triangles too small to hold a pixel centre
 * included: kept out of the rendering) are linked around their vertices,
 * and each record edge is classed from its faces: a silhouette or boundary
 * (no record across: the neighbour faces away, or there is none), a crease
 * (the dihedral angle of the exact eye-space normals above the crease
 * angle), or smooth. The records holding feature edges are sorted by their
 * tops and come into an active list as the rows reach them.
 *
 * An edge taller than wide is drawn where it crosses each row's centre
 * line, one that is wider where it crosses each column's: on the pixel
 * whose centre is nearer the crossing, so a line is one pixel wide, and
 * at most half a pixel off. The crossing lies on the step between two
 * pixel centres, whose ids (rows are rendered one ahead of the output)
 * say what is in front there; the crossing is drawn unless one of them
 * covers it nearer than the edge. An edge seen where no pixel centre sees
 * its faces (a sheet seen edge-on, the tip of a sharp corner) is drawn
 * all the same, which a change of ids between pixels could not give. */
#include "zs_mono.h"


/* Records of a hidden-line frame are at most 65534, so 0xFFFF is none. */
#define NO_RECORD 0xFFFFu

void zs_lines_draw(zs_renderer *r, const zs_mesh *m, const int32_t mv[3][3], uint16_t first,
                   uint32_t tag_base)
{
    int64_t mm[3][3], cof[3][3], big = 0;
    const zs_tri *tri = r->priv.tris;
    uint16_t i;
    int k, j;
    /* (M a) x (M b) = cof(M) (a x b): the cofactor matrix turns model-space
     * normals into eye-space ones, for any scaling; entries kept small so
     * every product below fits 63 bits */
    for (k = 0; k < 3; k++)
        for (j = 0; j < 3; j++) {
            mm[k][j] = mv[k][j];
            if ((mm[k][j] < 0 ? -mm[k][j] : mm[k][j]) > big)
                big = mm[k][j] < 0 ? -mm[k][j] : mm[k][j];
        }
    for (; big >= ((int64_t)1 << 28); big >>= 1)
        for (k = 0; k < 3; k++)
            for (j = 0; j < 3; j++)
                mm[k][j] = zs_asr64(mm[k][j], 1);
    big = 0;
    for (k = 0; k < 3; k++)
        for (j = 0; j < 3; j++) {
            int k1 = (k + 1) % 3, k2 = (k + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            cof[k][j] = mm[k1][j1] * mm[k2][j2] - mm[k1][j2] * mm[k2][j1];
            if ((cof[k][j] < 0 ? -cof[k][j] : cof[k][j]) > big)
                big = cof[k][j] < 0 ? -cof[k][j] : cof[k][j];
        }
    for (; big >= ((int64_t)1 << 24); big >>= 1)
        for (k = 0; k < 3; k++)
            for (j = 0; j < 3; j++)
                cof[k][j] = zs_asr64(cof[k][j], 1);
    for (i = first; i < r->priv.n_tris; i++) {
        int16_t *n = &r->priv.tri_normal[4u * i];
        /* the mesh triangle from the record's tag (ID16: the colour word) */
        uint32_t tag = tri[i].color - 1u;
        uint32_t t = tag >= tag_base ? tag - tag_base : tag + 65535u - tag_base;
        const int16_t *p0, *p1, *p2;
        int32_t e1[3], e2[3];
        int64_t nm[3], v[3];
        int32_t u[3];
        n[0] = n[1] = n[2] = 0;
        if (t >= m->triangle_count)
            continue;
        p0 = m->positions + 3u * m->indices[3u * t];
        p1 = m->positions + 3u * m->indices[3u * t + 1u];
        p2 = m->positions + 3u * m->indices[3u * t + 2u];
        for (k = 0; k < 3; k++) {
            e1[k] = p1[k] - p0[k];
            e2[k] = p2[k] - p0[k];
        }
        zs_cross3(e1, e2, nm);
        zs_shrink3(nm, (int64_t)1 << 24);
        for (k = 0; k < 3; k++)
            v[k] = cof[k][0] * nm[0] + cof[k][1] * nm[1] + cof[k][2] * nm[2];
        if (!zs_normalize3(v, u))
            continue;
        for (k = 0; k < 3; k++)
            n[k] = (int16_t)zs_asr32(u[k], 2);
    }
}

/* The record across edge k (v[k] -> v[k + 1]) of record i: the one that
 * runs the edge the other way (a consistently wound mesh); NO_RECORD if
 * none (a silhouette, whose neighbour faced away, a boundary, or a mesh
 * whose faces do not share vertices). */
static uint16_t neighbour(const zs_renderer *r, uint16_t i, int k)
{
    const zs_tri *t = r->priv.tris;
    uint16_t u = t[i].v[k], w = t[i].v[k == 2 ? 0 : k + 1], j = r->priv.line_vert_head[w];
    while (j != NO_RECORD) {
        int c = t[j].v[0] == w ? 0 : t[j].v[1] == w ? 1 : 2;
        if (j != i && t[j].v[c == 2 ? 0 : c + 1] == u)
            return j;
        j = r->priv.line_next_rec[3u * j + (unsigned)c];
    }
    return NO_RECORD;
}

/* First record with tag >= tag: records are in submission order, and so are
 * their tags (ID16 keeps the tag in the colour word) while a frame has fewer
 * than 65536 submitted triangles. */
static uint16_t first_record(const zs_renderer *r, uint16_t tag)
{
    const zs_tri *t = r->priv.tris;
    uint32_t lo = 0, hi = r->priv.n_tris;
    while (lo < hi) {
        uint32_t mid = (lo + hi) / 2u;
        if (t[mid].color < tag)
            lo = mid + 1u;
        else
            hi = mid;
    }
    return (uint16_t)lo;
}

/* Positions along the step from one pixel centre to its neighbour's, in
 * 1/4096 of the step. */
#define STEP_ONE 4096

/* The pair of pixel centres a decision is about: c0 = (px, py) and
 * c1 = c0 + (sx, sy), in 1/16 px, one pixel apart. */
typedef struct step_pair {
    int32_t px, py, sx, sy;
} step_pair;

/* n / d in 1/4096 (0 <= n <= d, d > 0), in 32-bit division. */
static int32_t fraction(uint64_t n, uint64_t d)
{
    while (d >= ((uint64_t)1 << 19)) {
        n >>= 1;
        d >>= 1;
    }
    return d ? (int32_t)(((uint32_t)n << 12) / (uint32_t)d) : 0;
}

/* The part [lo, hi] (1/4096 of the step) of the segment c0 -> c1 that
 * record t covers; 0 if none. An edge function is linear along the step, so
 * each edge cuts the segment once at most. */
static int cover_span(const zs_renderer *r, const zs_tri *t, const step_pair *s, int32_t *lo,
                      int32_t *hi, int *klo, int *khi)
{
    const zs_vert *pool = r->priv.verts;
    int64_t area = zs_area2_inline(&pool[t->v[0]], &pool[t->v[1]], &pool[t->v[2]]);
    int32_t l = 0, h = STEP_ONE;
    int k, el = -1, eh = -1;
    if (area == 0)
        return 0;
    for (k = 0; k < 3; k++) {
        const zs_vert *a = &pool[t->v[k]], *b = &pool[t->v[k == 2 ? 0 : k + 1]];
        int64_t ex = (int64_t)b->x - a->x, ey = (int64_t)b->y - a->y;
        /* the edge function, positive inside, at c0 and its change to c1 */
        int64_t e0 = ex * ((int64_t)s->py - a->y) - ey * ((int64_t)s->px - a->x);
        int64_t de = ex * s->sy - ey * s->sx, e1;
        if (area < 0) {
            e0 = -e0;
            de = -de;
        }
        e1 = e0 + de;
        /* inside where >= 0 (closed: a centre on an edge is where the
         * segment crosses it, whichever side the fill rule gives it to) */
        if (e0 < 0 && e1 < 0)
            return 0;
        if (e0 >= 0 && e1 >= 0) {
            if (e1 == 0 && e0 > 0 && h == STEP_ONE) { /* leaves at c1 */
                eh = k;
            } else if (e0 == 0 && e1 > 0 && l == 0) { /* enters at c0 */
                el = k;
            }
            continue;
        }
        if (e0 >= 0) { /* e1 < 0: leaves at e0 / (e0 - e1) */
            int32_t c = fraction((uint64_t)e0, (uint64_t)(e0 - e1));
            if (c <= h) {
                h = c;
                eh = k;
            }
        } else { /* e1 >= 0: enters there */
            int32_t c = fraction((uint64_t)-e0, (uint64_t)(e1 - e0));
            if (c >= l) {
                l = c;
                el = k;
            }
        }
    }
    if (l > h)
        return 0;
    *lo = l;
    *hi = h;
    *klo = el;
    *khi = eh;
    return 1;
}

/* The part of the segment that the records tagged tag cover together (a
 * clipped triangle has several records, one convex polygon in all), and
 * the edges it begins and ends at: edge k of a record runs from v[k] to
 * v[k + 1]; -1 where the cover reaches an end of the segment. */
typedef struct cover {
    int32_t lo, hi;
    uint16_t rec_lo, rec_hi;
    int edge_lo, edge_hi;
} cover;

static int tag_cover(const zs_renderer *r, uint16_t first, uint16_t tag, const step_pair *s,
                     cover *c)
{
    const zs_tri *t = r->priv.tris;
    uint16_t n = r->priv.n_tris, i;
    int32_t a, b;
    int any = 0, ka, kb;
    c->lo = STEP_ONE + 1; /* below any cover's end */
    c->hi = -1;
    c->rec_lo = c->rec_hi = first;
    c->edge_lo = c->edge_hi = -1;
    for (i = first; i < n && t[i].color == tag; i++)
        if (cover_span(r, &t[i], s, &a, &b, &ka, &kb)) {
            any = 1;
            if (a < c->lo) {
                c->lo = a;
                c->rec_lo = i;
                c->edge_lo = ka;
            }
            if (b > c->hi) {
                c->hi = b;
                c->rec_hi = i;
                c->edge_hi = kb;
            }
        }
    return any;
}

/* Window depth (Q2.30) of record t's plane at m (1/4096 of the step s).
 * The depth differences lose their 6 low bits so that every product fits
 * 63 bits (|dx|, |dy| < 2^16); the plane is only compared within 1/256 of
 * A - z here. */
static int64_t depth_at(const zs_renderer *r, const zs_tri *t, const step_pair *s, int32_t m)
{
    const zs_vert *a = &r->priv.verts[t->v[0]], *b = &r->priv.verts[t->v[1]],
                  *c = &r->priv.verts[t->v[2]];
    int64_t dx1 = (int32_t)b->x - a->x, dy1 = (int32_t)b->y - a->y;
    int64_t dx2 = (int32_t)c->x - a->x, dy2 = (int32_t)c->y - a->y;
    int64_t dz1 = zs_asr64((int64_t)b->z - (int64_t)a->z, 6);
    int64_t dz2 = zs_asr64((int64_t)c->z - (int64_t)a->z, 6);
    int64_t den = dx1 * dy2 - dx2 * dy1;
    int64_t gx = dz1 * dy2 - dz2 * dy1, gy = dz2 * dx1 - dz1 * dx2;
    int64_t num = gx * (s->px - a->x) + gy * (s->py - a->y) +
                  zs_asr64((gx * s->sx + gy * s->sy) * m, 12);
    if (den == 0)
        return a->z;
    return (int64_t)a->z + (num / den) * 64;
}

/* Do records a and b meet at m? Their depths agree to 1/64 of A - z
 * (proportional to 1/w: about 1.5% of the eye distance). */
static int meet_at(const zs_renderer *r, const zs_tri *a, const zs_tri *b, const step_pair *s,
                   int32_t m)
{
    int64_t za = depth_at(r, a, s, m), zb = depth_at(r, b, s, m);
    int64_t d = za > zb ? za - zb : zb - za;
    int64_t q = r->priv.line_depth_a - (za > zb ? za : zb);
    return d < ((int64_t)1 << 40) && q > 0 && d * 64 < q;
}

static int32_t dot_q28(const int16_t *p, const int16_t *q)
{
    return p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
}

/* Records i and j on one surface, smooth where they meet at m: of one
 * draw, normals within the crease angle, planes that meet there. For the
 * end of a walk that found no neighbour. */
static int meet_smoothly(const zs_renderer *r, uint16_t i, uint16_t j, const step_pair *s,
                         int32_t m)
{
    const int16_t *p = &r->priv.tri_normal[4u * i], *q = &r->priv.tri_normal[4u * j];
    return p[3] == q[3] && dot_q28(p, q) >= r->priv.crease_cos &&
           meet_at(r, &r->priv.tris[i], &r->priv.tris[j], s, m);
}

static int has_vertex(const zs_tri *t, uint16_t v)
{
    return t->v[0] == v || t->v[1] == v || t->v[2] == v;
}

/* Does a record tagged tag (from first on) hold the edge u-w? Then it is
 * the face across a crease, not something in front of the edge. */
static int holds_edge(const zs_renderer *r, uint16_t first, uint16_t tag, uint16_t u, uint16_t w)
{
    const zs_tri *t = r->priv.tris;
    uint16_t i;
    for (i = first; i < r->priv.n_tris && t[i].color == tag; i++)
        if (has_vertex(&t[i], u) && has_vertex(&t[i], w))
            return 1;
    return 0;
}

/* The first records of the last tags asked, by the tag's low bits (ids
 * repeat along an edge and along a row). */
#define MEMO_SIZE 16u
typedef struct tag_memo {
    uint16_t tag, rec;
} tag_memo;

static uint16_t record_of(const zs_renderer *r, tag_memo *memo, uint16_t tag)
{
    tag_memo *m = &memo[tag & (MEMO_SIZE - 1u)];
    if (m->tag != tag) {
        m->tag = tag;
        m->rec = first_record(r, tag);
    }
    return m->rec;
}

/* Does a record tagged tag (from first on) cover the point at m (1/4096
 * of the step s), edges included? Edge functions are linear along the
 * step, so 4096 times one at the point is exact in 64 bits. */
static int covers_point(const zs_renderer *r, uint16_t first, uint16_t tag, const step_pair *s,
                        int32_t m)
{
    const zs_vert *pool = r->priv.verts;
    const zs_tri *t = r->priv.tris;
    uint16_t i;
    for (i = first; i < r->priv.n_tris && t[i].color == tag; i++) {
        int64_t area = zs_area2_inline(&pool[t[i].v[0]], &pool[t[i].v[1]], &pool[t[i].v[2]]);
        int k, in = 1;
        for (k = 0; k < 3 && in; k++) {
            const zs_vert *a = &pool[t[i].v[k]], *b = &pool[t[i].v[k == 2 ? 0 : k + 1]];
            int32_t ex = (int32_t)b->x - a->x, ey = (int32_t)b->y - a->y;
            int64_t e0 = (int64_t)ex * (s->py - a->y) - (int64_t)ey * (s->px - a->x);
            int32_t de = ex * s->sy - ey * s->sx; /* |de| < 2^21 */
            int64_t e;
            if (area > 0) {
                e0 = -e0;
                de = -de;
            }
            /* e0 <= 0 inside; the sign at the point is e0's where the
             * other end agrees, else it takes the product */
            if ((e0 <= 0) == (e0 + de <= 0))
                e = e0;
            else
                e = e0 * STEP_ONE + (int64_t)de * m;
            in = e <= 0;
        }
        if (in && area != 0)
            return 1;
    }
    return 0;
}

/* Least and greatest depth of record i's corners. */
static void depth_bounds(const zs_renderer *r, uint16_t i, uint32_t *lo, uint32_t *hi)
{
    const zs_vert *pool = r->priv.verts;
    const uint16_t *v = r->priv.tris[i].v;
    uint32_t a = pool[v[0]].z, b = pool[v[1]].z, c = pool[v[2]].z;
    *lo = a < b ? (a < c ? a : c) : (b < c ? b : c);
    *hi = a > b ? (a > c ? a : c) : (b > c ? b : c);
}

/* Is the point at m (1/4096 of the step s) of record i's feature edge k
 * visible? The visibility the walk computed is the ids a and b at the two
 * centres around it: the point is hidden where one of them, not a face of
 * the edge, covers it and lies in front (by more than 1/256 of 1/w, a
 * relative margin, so surfaces that touch the edge do not hide it), or
 * where both lie in front and the point is between their covers. What no
 * centre sees is thinner than a pixel there and hides nothing. An open
 * edge (a silhouette, a boundary, or a mesh whose faces share no vertices)
 * is no line where the surface across it goes on smoothly: the planes meet
 * there, normals within the crease angle, one draw. */
static int edge_shown(const zs_renderer *r, tag_memo *memo, uint16_t i, int k,
                      const step_pair *s, int32_t m, uint16_t a, uint16_t b, int open)
{
    const zs_tri *t = r->priv.tris;
    const zs_vert *pool = r->priv.verts;
    uint16_t tf = (uint16_t)t[i].color, u = t[i].v[k], w = t[i].v[k == 2 ? 0 : k + 1];
    uint32_t elo = pool[u].z < pool[w].z ? pool[u].z : pool[w].z;
    uint32_t ehi = pool[u].z < pool[w].z ? pool[w].z : pool[u].z;
    int64_t zf = 0, tol = 0;
    uint16_t ids[2];
    int e, nearer = 0, have_zf = 0;
    ids[0] = a;
    ids[1] = b;
    for (e = 0; e < 2; e++) {
        uint16_t x = ids[e], fx;
        uint32_t xlo, xhi;
        if (x == 0 || x == tf)
            continue;
        fx = record_of(r, memo, x);
        if (fx >= r->priv.n_tris || t[fx].color != x || holds_edge(r, fx, x, u, w))
            continue; /* (every id the walk renders has a record) */
        /* a triangle of one record wholly behind the edge hides nothing;
         * one wholly in front (by the margin at the edge's nearest point)
         * is in front at the point too */
        depth_bounds(r, fx, &xlo, &xhi);
        if (fx + 1u < r->priv.n_tris && t[fx + 1u].color == x) {
            xlo = 0; /* a clipped triangle's pieces: no bounds */
            xhi = 0xFFFFFFFFu;
        }
        if (xlo >= ehi)
            continue;
        if ((int64_t)xhi >= (int64_t)elo - zs_asr64(r->priv.line_depth_a - (int64_t)elo, 8)) {
            if (!have_zf) { /* the edge's depth, once something else may hide it */
                zf = depth_at(r, &t[i], s, m);
                tol = zs_asr64(r->priv.line_depth_a - zf, 8);
                have_zf = 1;
            }
            if (depth_at(r, &t[fx], s, m) >= zf - tol)
                continue;
        }
        if (covers_point(r, fx, x, s, m))
            return 0; /* it covers the point, in front */
        nearer++;
    }
    /* neither covers it, and both are in front there: what lies between
     * them (a corner of a third triangle the step cuts) is taken to be too */
    if (nearer == 2)
        return 0;
    if (open) {
        /* the centre on the far side of the edge from the record's inside */
        const zs_vert *p = &pool[u], *q = &pool[w];
        int64_t area = zs_area2_inline(&pool[t[i].v[0]], &pool[t[i].v[1]], &pool[t[i].v[2]]);
        int64_t e0 = ((int64_t)q->x - p->x) * ((int64_t)s->py - p->y) -
                     ((int64_t)q->y - p->y) * ((int64_t)s->px - p->x);
        uint16_t x = (area < 0 ? -e0 : e0) >= 0 ? b : a;
        if (x && x != tf) {
            uint16_t fx = record_of(r, memo, x);
            if (fx < r->priv.n_tris && meet_smoothly(r, i, fx, s, m))
                return 0;
        }
    }
    return 1;
}

/* The rows' state while a frame's lines are drawn: the ids of row y and
 * the row below (NULL at the bottom), the flags of both. */
typedef struct line_rows {
    const uint16_t *cur, *below;
    uint8_t *flags, *pending;
    int y, w, h;
    tag_memo memo[MEMO_SIZE];
} line_rows;

static uint16_t id_at(line_rows *c, int64_t col, int64_t row)
{
    if (col < 0 || col >= c->w)
        return 0;
    if (row == c->y)
        return c->cur[col];
    if (row == c->y + 1 && c->below)
        return c->below[col];
    return 0;
}

/* Where the edge p -> q (p->y < q->y, at least as tall as wide) crosses row
 * y's centre line: the pixel whose centre is nearer the crossing, if the
 * crossing is visible. */
static void cross_row(const zs_renderer *r, line_rows *c, uint16_t i, int k,
                      const zs_vert *p, const zs_vert *q, int open)
{
    int64_t den = (int64_t)q->y - p->y, X, cx, rem;
    int32_t yc = 16 * c->y + 8;
    step_pair s;
    if (yc < p->y || yc >= q->y)
        return;
    X = (int64_t)p->x * den + (int64_t)(yc - p->y) * ((int64_t)q->x - p->x); /* x * den */
    if (X <= 0 || X >= 16 * (int64_t)c->w * den)
        return;
    /* now 0 < X < 2^31 (16 w < 2^15, den < 2^16): 32-bit divisions; the
     * centre left of the crossing, and where the crossing lies after it */
    cx = (int32_t)((uint32_t)(X + 8 * den) / (uint32_t)(16 * den)) - 1;
    rem = X - 8 * den - 16 * den * cx; /* [0, 16 den) */
    s.px = (int32_t)(16 * cx + 8);
    s.py = yc;
    s.sx = 16;
    s.sy = 0;
    if (edge_shown(r, c->memo, i, k, &s, (int32_t)((uint32_t)(rem * 256) / (uint32_t)den), id_at(c, cx, c->y),
                   id_at(c, cx + 1, c->y), open))
        c->flags[rem < 8 * den ? cx : cx + 1] = 1;
}

/* Where the edge p -> q (p->x < q->x, wider than tall) crosses column
 * centre lines between row y's centre and row y + 1's (from the top of the
 * screen on row 0, to its bottom on the last row): for each, the pixel in
 * that column whose centre is nearer, if the crossing is visible. */
static void cross_columns(const zs_renderer *r, line_rows *c, uint16_t i, int k,
                          const zs_vert *p, const zs_vert *q, int open)
{
    /* coordinates are int16 and p->x < q->x: every difference below fits
     * 16 bits unsigned, so the products fit 32 */
    int32_t den = (int32_t)q->x - p->x, dy = (int32_t)q->y - p->y, lo, hi, xs = p->x, xe = q->x;
    int32_t c0, c1, col;
    lo = c->y == 0 ? 1 : 16 * c->y + 8;
    hi = c->below ? 16 * c->y + 24 : 16 * c->h;
    if ((p->y < lo && q->y < lo) || (p->y >= hi && q->y >= hi))
        return;
    /* the part [xs, xe] of the edge within the band, rounded down */
    if (dy > 0) {
        if (lo > p->y)
            xs = p->x + (int32_t)((uint32_t)(lo - p->y) * (uint32_t)den / (uint32_t)dy);
        if (hi < q->y)
            xe = p->x + (int32_t)((uint32_t)(hi - p->y) * (uint32_t)den / (uint32_t)dy);
    } else if (dy < 0) {
        if (hi <= p->y)
            xs = p->x + (int32_t)((uint32_t)(p->y - hi) * (uint32_t)den / (uint32_t)-dy);
        if (lo > q->y)
            xe = p->x + (int32_t)((uint32_t)(p->y - lo) * (uint32_t)den / (uint32_t)-dy);
    }
    /* the columns whose centres lie in [p->x, q->x), near that part, on
     * screen (a column either side to spare: each is tested exactly) */
    c0 = zs_asr32((int32_t)p->x + 7, 4);
    c1 = zs_asr32((int32_t)q->x + 7, 4) - 1;
    if (zs_asr32(xs - 8, 4) > c0)
        c0 = zs_asr32(xs - 8, 4);
    if (zs_asr32(xe - 8, 4) + 1 < c1)
        c1 = zs_asr32(xe - 8, 4) + 1;
    if (c0 < 0)
        c0 = 0;
    if (c1 >= c->w)
        c1 = c->w - 1;
    for (col = c0; col <= c1; col++) {
        int32_t xc = 16 * col + 8, ry, row;
        int64_t Y;
        uint32_t rem;
        step_pair s;
        Y = (int64_t)p->y * den + (int64_t)(xc - p->x) * dy; /* y * den */
        if (xc < p->x || xc >= q->x || Y < (int64_t)lo * den || Y >= (int64_t)hi * den)
            continue;
        /* now 0 <= Y < 2^31: the centre above the crossing, and where the
         * crossing lies below it */
        ry = (int32_t)(((uint32_t)Y + 8u * (uint32_t)den) / (16u * (uint32_t)den)) - 1;
        rem = (uint32_t)(Y - 8 * (int64_t)den - 16 * (int64_t)den * ry);
        row = rem < 8u * (uint32_t)den ? ry : ry + 1;
        s.px = xc;
        s.py = 16 * ry + 8;
        s.sx = 0;
        s.sy = 16;
        if (!edge_shown(r, c->memo, i, k, &s, (int32_t)(rem * 256u / (uint32_t)den), id_at(c, col, ry),
                        id_at(c, col, ry + 1), open))
            continue;
        if (row == c->y)
            c->flags[col] = 1;
        else
            c->pending[col] = 1;
    }
}

/* The feature edges of record i (mask: bits 0-2 edge k drawn, bits 3-5 edge
 * k open) crossed in row y's band. */
static void record_lines(const zs_renderer *r, line_rows *c, uint16_t i, unsigned mask)
{
    const zs_vert *pool = r->priv.verts;
    const zs_tri *t = &r->priv.tris[i];
    int k;
    for (k = 0; k < 3; k++) {
        const zs_vert *p = &pool[t->v[k]], *q = &pool[t->v[k == 2 ? 0 : k + 1]];
        int32_t dx = (int32_t)q->x - p->x, dy = (int32_t)q->y - p->y;
        int open = (mask >> (3 + k)) & 1;
        if (!((mask >> k) & 1))
            continue;
        if ((dy < 0 ? -dy : dy) >= (dx < 0 ? -dx : dx)) {
            if (dy != 0)
                cross_row(r, c, i, k, dy > 0 ? p : q, dy > 0 ? q : p, open);
        } else {
            cross_columns(r, c, i, k, dx > 0 ? p : q, dx > 0 ? q : p, open);
        }
    }
}
/* Where, between the centres of s (ids a at c0, b at c1, of two draws),
 * the boundary between the draws lies, in 1/4096 of the step: where the
 * nearer one's cover ends, or, where each covers both centres (they cut
 * into each other), where their planes cross; -1 if the records are not
 * found on the step. */
static int32_t draw_cut(const zs_renderer *r, uint16_t a, uint16_t fa, uint16_t b, uint16_t fb,
                        const step_pair *s)
{
    const zs_tri *t = r->priv.tris;
    cover ca, cb;
    int32_t ta, tb;
    if (!tag_cover(r, fa, a, s, &ca) || !tag_cover(r, fb, b, s, &cb))
        return -1;
    ta = ca.hi;
    tb = cb.lo;
    if (ta >= STEP_ONE && tb <= 0) {
        int64_t d0 = depth_at(r, &t[fa], s, 0) - depth_at(r, &t[fb], s, 0);
        int64_t d1 = depth_at(r, &t[fa], s, STEP_ONE) - depth_at(r, &t[fb], s, STEP_ONE);
        /* a is in front at c0 (d0 <= 0), b at c1 (d1 >= 0) */
        if (d0 > 0 || d1 < 0 || d1 - d0 <= 0)
            return STEP_ONE / 2;
        return fraction((uint64_t)-d0, (uint64_t)(d1 - d0));
    }
    if (ta >= STEP_ONE) /* a reaches c1, b is in front there */
        return tb;
    if (tb <= 0) /* b reaches c0 */
        return ta;
    if (ta <= tb) /* a gap, covered by what no centre sees */
        return (ta + tb) / 2;
    return depth_at(r, &t[fa], s, (ta + tb) / 2) <= depth_at(r, &t[fb], s, (ta + tb) / 2) ? ta : tb;
}

/* Boundaries between draw calls that no feature edge gives (a surface
 * cutting into another, an object sunk into the floor): where neighbouring
 * centres see two draws and neither pixel has a line yet, the line goes on
 * the pixel nearer the boundary. */
static void draw_boundaries(const zs_renderer *r, line_rows *c)
{
    const int16_t *nrm = r->priv.tri_normal;
    step_pair s;
    int x;
    s.py = 16 * c->y + 8;
    s.sx = 16;
    s.sy = 0;
    for (x = 1; x < c->w; x++) {
        uint16_t a = c->cur[x - 1], b = c->cur[x], fa, fb;
        int32_t cut;
        if (a == b || !a || !b || c->flags[x - 1] || c->flags[x])
            continue;
        fa = record_of(r, c->memo, a);
        fb = record_of(r, c->memo, b);
        if (fa >= r->priv.n_tris || fb >= r->priv.n_tris ||
            nrm[4u * fa + 3u] == nrm[4u * fb + 3u])
            continue;
        s.px = 16 * x - 8;
        cut = draw_cut(r, a, fa, b, fb, &s);
        if (cut >= 0)
            c->flags[cut < STEP_ONE / 2 ? x - 1 : x] = 1;
    }
    if (!c->below)
        return;
    s.sx = 0;
    s.sy = 16;
    for (x = 0; x < c->w; x++) {
        uint16_t a = c->cur[x], b = c->below[x], fa, fb;
        int32_t cut;
        if (a == b || !a || !b || c->flags[x] || c->pending[x])
            continue;
        fa = record_of(r, c->memo, a);
        fb = record_of(r, c->memo, b);
        if (fa >= r->priv.n_tris || fb >= r->priv.n_tris ||
            nrm[4u * fa + 3u] == nrm[4u * fb + 3u])
            continue;
        s.px = 16 * x + 8;
        cut = draw_cut(r, a, fa, b, fb, &s);
        if (cut >= 0) {
            if (cut < STEP_ONE / 2)
                c->flags[x] = 1;
            else
                c->pending[x] = 1;
        }
    }
}

/* A record's top and bottom rows, 1/16 px. */
static int32_t rec_top(const zs_renderer *r, uint16_t i)
{
    const zs_vert *pool = r->priv.verts;
    const uint16_t *v = r->priv.tris[i].v;
    int32_t a = pool[v[0]].y, b = pool[v[1]].y, c = pool[v[2]].y;
    return a < b ? (a < c ? a : c) : (b < c ? b : c);
}

static int32_t rec_bottom(const zs_renderer *r, uint16_t i)
{
    const zs_vert *pool = r->priv.verts;
    const uint16_t *v = r->priv.tris[i].v;
    int32_t a = pool[v[0]].y, b = pool[v[1]].y, c = pool[v[2]].y;
    return a > b ? (a > c ? a : c) : (b > c ? b : c);
}

/* Heap sort of the records holding feature edges by their tops. */
static void sift(const zs_renderer *r, uint16_t *a, uint32_t root, uint32_t n)
{
    for (;;) {
        uint32_t c = 2u * root + 1u;
        uint16_t t;
        if (c >= n)
            return;
        if (c + 1u < n && rec_top(r, a[c + 1u]) > rec_top(r, a[c]))
            c++;
        if (rec_top(r, a[root]) >= rec_top(r, a[c]))
            return;
        t = a[root];
        a[root] = a[c];
        a[c] = t;
        root = c;
    }
}

void zs_lines_begin(zs_renderer *r)
{
    int64_t A;
    uint16_t i, draw = 0, n = r->priv.n_tris, *head = r->priv.line_vert_head,
                next_list = 0, *next = r->priv.line_next_rec;
    uint16_t *list = r->priv.line_next_rec, *mask = list + r->cfg.max_triangles;
    int16_t *nrm = r->priv.tri_normal;
    int deg = r->shade.crease_deg ? r->shade.crease_deg : 30, k;
    uint32_t end;
    r->priv.crease_cos = zs_fx_cos_deg(ZS_FX(deg)) * 4096; /* Q16 -> Q28 */
    r->priv.line_next = 0;
    if (r->priv.depth_scale != 0) {
        A = r->priv.depth_scale;
    } else {
        int64_t f = r->cam.far_z, nz = r->cam.near_z;
        A = (f * ((int64_t)1 << 30)) / (f - nz);
    }
    r->priv.line_depth_a = A;
    /* the records around each vertex, to find the one across an edge */
    for (i = 0; i < r->priv.n_verts; i++)
        head[i] = NO_RECORD;
    for (i = 0; i < n; i++) {
        const zs_tri *t = &r->priv.tris[i];
        for (k = 0; k < 3; k++) {
            next[3u * i + (unsigned)k] = head[t->v[k]];
            head[t->v[k]] = i;
        }
    }
    /* feature edges: bit k, edge k is one (a crease once, from the lower
     * record); bit 3 + k, it has no record across (kept in the draw
     * number's place until the links are done with) */
    for (i = 0; i < n; i++) {
        unsigned mk = 0;
        for (k = 0; k < 3; k++) {
            uint16_t j = neighbour(r, i, k);
            if (j == NO_RECORD)
                mk |= 9u << k;
            else if (i < j && dot_q28(&nrm[4u * i], &nrm[4u * j]) < r->priv.crease_cos)
                mk |= 1u << k;
        }
        nrm[4u * i + 3u] = (int16_t)mk;
    }
    for (i = 0; i < n; i++) {
        unsigned mk = (unsigned)nrm[4u * i + 3u];
        if (r->priv.draw_starts[i >> 3] & (1u << (i & 7u)))
            draw++;
        nrm[4u * i + 3u] = (int16_t)(draw & 0x7FFFu); /* draw number (wrapping) */
        mask[i] = (uint16_t)mk;
        if (mk)
            list[next_list++] = i;
    }
    for (end = next_list / 2u; end-- > 0u;)
        sift(r, list, end, next_list);
    for (end = next_list; end-- > 1u;) {
        uint16_t t = list[0];
        list[0] = list[end];
        list[end] = t;
        sift(r, list, 0, end);
    }
    r->priv.line_feats = next_list;
    r->priv.line_feat_next = 0;
    r->priv.line_n_active = 0;
}

/* Flags of row y: what the row above left for it (line_pending) and the
 * crossings of the feature edges in its band, on whichever of the two rows
 * is nearer (the row below is rendered now); the flags the row below gets
 * are left in line_pending. */
void zs_lines_row(zs_renderer *r, int y, uint8_t *flags)
{
    uint16_t *cur = r->priv.line_ids[0], *below = r->priv.line_ids[1];
    uint16_t *list = r->priv.line_next_rec, *mask = list + r->cfg.max_triangles,
             *act = mask + r->cfg.max_triangles;
    uint8_t *pending = r->priv.line_pending;
    int w = r->cfg.width, h = r->cfg.height;
    int32_t hi;
    uint16_t j;
    line_rows c;
    if (r->priv.line_next <= y) { /* not rendered ahead: no row above */
        zs_visible_row(r, y, (uint8_t *)cur);
        memset(pending, 0, (size_t)w);
    }
    memcpy(flags, pending, (size_t)w);
    memset(pending, 0, (size_t)w);
    c.cur = cur;
    c.below = y + 1 < h ? below : NULL;
    c.flags = flags;
    c.pending = pending;
    c.y = y;
    c.w = w;
    c.h = h;
    memset(c.memo, 0, sizeof c.memo); /* tag 0 is the background, never asked */
    if (c.below)
        zs_visible_row(r, y + 1, (uint8_t *)below);
    /* records join as their tops reach the band, leave once their bottoms
     * are above it */
    hi = c.below ? 16 * y + 24 : 16 * h;
    while (r->priv.line_feat_next < r->priv.line_feats &&
           rec_top(r, list[r->priv.line_feat_next]) < hi)
        act[r->priv.line_n_active++] = list[r->priv.line_feat_next++];
    for (j = 0; j < r->priv.line_n_active;) {
        uint16_t i = act[j];
        if (rec_bottom(r, i) < (y == 0 ? 1 : 16 * y + 8)) { /* cross_columns' band */
            act[j] = act[--r->priv.line_n_active];
            continue;
        }
        record_lines(r, &c, i, mask[i]);
        j++;
    }
    /* more than one draw: the first and last records' draw numbers differ */
    if (r->priv.n_tris > 1 &&
        r->priv.tri_normal[3] != r->priv.tri_normal[4u * (r->priv.n_tris - 1u) + 3u])
        draw_boundaries(r, &c);
    if (!c.below) {
        r->priv.line_next = y + 1;
        return;
    }
    r->priv.line_ids[0] = below;
    r->priv.line_ids[1] = cur;
    r->priv.line_next = y + 2;
}
